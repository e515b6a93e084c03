//! The forward event of `graphs/foot_ik.ron`, compiled ahead of time: the native baseline that
//! `strider bench` measures the interpreter against (see docs/performance.md).
//!
//! Generated from the graph; do not edit. Regenerate after changing the graph or the
//! compiler with:
//!
//! ```text
//! cargo run --release -- native graphs/foot_ik.ron --out crates/strider-native/src/graphs/foot_ik.rs
//! ```

use strider_nodes::{Op, ValueType};
use strider_vm::native::{Frame, NativeProgram, step};

/// The forward event of `foot_ik`, compiled ahead of time.
pub static NATIVE: NativeProgram = NativeProgram {
    name: "foot_ik",
    fingerprint: 0xd091979a55afcace,
    forward,
};

fn forward(f: &mut Frame<'_>) {
    let mut pc: usize = 1;
    loop {
        // SAFETY: each `step` is an instruction of the program this code was generated
        // from, with its own operands; `NATIVE` runs only on that program (fingerprint).
        pc = unsafe { match pc {
            1 => {
                step(f, Op::GetTransformBreakTransform, &[8, 0, 4, 0, 0, 3, 2, 4], 2);
                step(f, Op::BreakVector, &[3, 1, 2, 3], 3);
                step(f, Op::MakeVector, &[1, 2, 6, 4], 4);
                step(f, Op::MulF, &[6, 15, 3], 5);
                step(f, Op::MakeVector, &[1, 2, 3, 3], 6);
                step(f, Op::DrawLine, &[4, 3, 16, 11], 7);
                step(f, Op::LineTrace, &[4, 3, 1, 5, 6, 1], 8);
                step(f, Op::DrawPoint, &[5, 17, 12], 9);
                step(f, Op::ScaleV, &[6, 7, 3], 10);
                step(f, Op::MakeVector, &[18, 18, 7, 4], 11);
                step(f, Op::SubV, &[3, 4, 5], 12);
                step(f, Op::FootOffsetFromTrace, &[1, 1, 6, 2], 13);
                step(f, Op::MakeVector, &[18, 18, 2, 3], 14);
                step(f, Op::AddV, &[5, 3, 4, 4, 4], 15);
                step(f, Op::RotationFromNormal, &[6, 3, 1, 2, 2, 2], 16);
                step(f, Op::GetTransformBreakTransform, &[9, 0, 4, 0, 0, 3, 3, 5], 17);
                step(f, Op::BreakVector, &[3, 2, 1, 3], 18);
                step(f, Op::MakeVector, &[2, 1, 6, 6], 19);
                step(f, Op::MulF, &[6, 15, 3], 20);
                step(f, Op::MakeVector, &[2, 1, 3, 5], 21);
                step(f, Op::DrawLine, &[6, 5, 16, 11], 22);
                step(f, Op::LineTrace, &[6, 5, 1, 3, 7, 1], 23);
                step(f, Op::DrawPoint, &[3, 17, 12], 24);
                step(f, Op::ScaleV, &[7, 7, 5], 25);
                step(f, Op::MakeVector, &[18, 18, 7, 6], 26);
                step(f, Op::SubV, &[5, 6, 3], 27);
                step(f, Op::FootOffsetFromTrace, &[1, 1, 6, 2], 28);
                step(f, Op::MakeVector, &[18, 18, 2, 5], 29);
                step(f, Op::AddV, &[3, 5, 6, 6, 6], 30);
                step(f, Op::RotationFromNormal, &[7, 3, 1, 3, 3, 3], 31);
                step(f, Op::BreakVector, &[4, 2, 1, 3], 32);
                step(f, Op::BreakVector, &[6, 1, 2, 4], 33);
                step(f, Op::MinF, &[3, 4, 1], 34);
                step(f, Op::Not, &[0, 1], 35);
                step(f, Op::WorldTransform, &[0], 36);
                step(f, Op::BreakTransform, &[0, 3, 4, 5], 37);
                step(f, Op::DistanceV, &[3, 0, 2], 38);
                step(f, Op::GreaterF, &[2, 14, 2], 39);
                step(f, Op::Or, &[1, 2, 3], 40);
                step(f, Op::LessF, &[1, 0, 1], 41);
                step(f, Op::Select(ValueType::Float), &[1, 11, 12, 3], 42);
                step(f, Op::Select(ValueType::Float), &[3, 19, 3, 4], 43);
                step(f, Op::FloatLerp, &[0, 1, 4, 2], 44);
                step(f, Op::Copy(ValueType::Float), &[2, 0, 1, 1], 45);
                step(f, Op::MakeVector, &[18, 18, 1, 7], 46);
                step(f, Op::SubV, &[4, 7, 5], 47);
                step(f, Op::BreakVector, &[5, 3, 4, 2], 48);
                step(f, Op::BreakVector, &[1, 3, 4, 5], 49);
                step(f, Op::LessF, &[2, 5, 2], 50);
                step(f, Op::Select(ValueType::Float), &[2, 9, 10, 3], 51);
                step(f, Op::Select(ValueType::Float), &[3, 19, 3, 4], 52);
                step(f, Op::VectorLerp, &[1, 5, 4, 18, 4, 4, 4], 53);
                step(f, Op::Copy(ValueType::Vec3), &[4, 1, 2, 2], 54);
                step(f, Op::MakeVector, &[18, 18, 1, 7], 55);
                step(f, Op::SubV, &[6, 7, 5], 56);
                step(f, Op::BreakVector, &[5, 2, 5, 3], 57);
                step(f, Op::BreakVector, &[2, 4, 1, 2], 58);
                step(f, Op::LessF, &[3, 2, 1], 59);
                step(f, Op::Select(ValueType::Float), &[1, 9, 10, 5], 60);
                step(f, Op::Select(ValueType::Float), &[3, 19, 5, 1], 61);
                step(f, Op::VectorLerp, &[2, 5, 1, 18, 4, 4, 4], 62);
                step(f, Op::Copy(ValueType::Vec3), &[4, 2], 63);
                step(f, Op::Select(ValueType::Float), &[3, 19, 13, 4], 64);
                step(f, Op::QuatLerp, &[0, 2, 4, 4], 65);
                step(f, Op::Copy(ValueType::Quat), &[4, 0], 66);
                step(f, Op::QuatLerp, &[1, 3, 4, 2], 67);
                step(f, Op::Copy(ValueType::Quat), &[2, 1], 68);
                step(f, Op::Copy(ValueType::Bool), &[4, 0], 69);
                step(f, Op::Copy(ValueType::Vec3), &[3, 0], 70);
                step(f, Op::GetTransformBreakTransform, &[10, 0, 4, 0, 0, 6, 4, 7], 71);
                step(f, Op::MakeVector, &[18, 18, 0, 5], 72);
                step(f, Op::AddV, &[6, 5, 4], 73);
                step(f, Op::MakeTransform, &[4, 4, 13, 0], 74);
                step(f, Op::SetTransform, &[11, 0, 0, 4, 20, 1, 1, 0, 0], 75);
                step(f, Op::GetTransformBreakTransform, &[14, 0, 4, 0, 0, 3, 3, 7], 76);
                step(f, Op::MakeVector, &[18, 18, 0, 5], 77);
                step(f, Op::AddVAddV, &[3, 5, 6, 6, 1, 4], 78);
                step(f, Op::MulQ, &[0, 3, 2], 79);
                step(f, Op::MakeTransform, &[4, 2, 13, 1], 80);
                step(f, Op::GetTransformBreakTransform, &[13, 0, 5, 2, 2, 8, 4, 9], 81);
                step(f, Op::MakeVector, &[18, 8, 18, 9], 82);
                step(f, Op::AddV, &[8, 9, 10], 83);
                step(f, Op::TwoBoneIK, &[12, 13, 14, 1, 14, 15, 10, 1, 20, 5, 21, 22, 4, 2, 2], 84);
                step(f, Op::GetTransformBreakTransform, &[14, 0, 4, 0, 0, 3, 3, 7], 85);
                step(f, Op::AddVAddV, &[3, 5, 6, 6, 1, 4], 86);
                step(f, Op::MulQ, &[0, 3, 2], 87);
                step(f, Op::MakeTransform, &[4, 2, 13, 1], 88);
                step(f, Op::DrawTransform, &[1, 23, 16, 2, 2, 1, 1], 89);
                step(f, Op::GetTransformBreakTransform, &[17, 0, 4, 2, 2, 8, 4, 9], 90);
                step(f, Op::MakeVector, &[18, 18, 0, 10], 91);
                step(f, Op::AddVAddV, &[8, 10, 7, 7, 2, 3], 92);
                step(f, Op::MulQ, &[1, 4, 3], 93);
                step(f, Op::MakeTransform, &[3, 3, 13, 0], 94);
                step(f, Op::GetTransformBreakTransform, &[16, 0, 5, 1, 1, 5, 2, 6], 95);
                step(f, Op::MakeVector, &[18, 8, 18, 4], 96);
                step(f, Op::AddV, &[5, 4, 6], 97);
                step(f, Op::TwoBoneIK, &[15, 16, 17, 0, 12, 16, 6, 1, 20, 5, 21, 22, 4, 1, 3], 98);
                step(f, Op::GetTransformBreakTransform, &[17, 0, 4, 2, 2, 8, 4, 9], 99);
                step(f, Op::AddVAddV, &[8, 10, 7, 7, 2, 3], 100);
                step(f, Op::MulQ, &[1, 4, 3], 101);
                step(f, Op::MakeTransform, &[3, 3, 13, 0], 102);
                step(f, Op::DrawTransform, &[0, 23, 16], 103);
                step(f, Op::End, &[], 104)
            }
            _ => return,
        } };
    }
}
