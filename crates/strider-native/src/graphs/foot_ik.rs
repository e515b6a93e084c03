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
    fingerprint: 0xc9d906f047fa20d4,
    forward,
};

fn forward(f: &mut Frame<'_>) {
    let mut pc: usize = 1;
    loop {
        // SAFETY: each `step` is an instruction of the program this code was generated
        // from, with its own operands; `NATIVE` runs only on that program (fingerprint).
        pc = unsafe { match pc {
            1 => {
                step(f, Op::GetTransformBreakTransform, &[8, 0, 1, 0, 0, 9, 2, 10], 2);
                step(f, Op::BreakVector, &[9, 19, 20, 21], 3);
                step(f, Op::MakeVector, &[19, 20, 0, 10], 4);
                step(f, Op::MulF, &[0, 10, 21], 5);
                step(f, Op::MakeVector, &[19, 20, 21, 9], 6);
                step(f, Op::DrawLine, &[10, 9, 11, 3], 7);
                step(f, Op::LineTrace, &[10, 9, 3, 11, 12, 19], 8);
                step(f, Op::DrawPoint, &[11, 12, 4], 9);
                step(f, Op::ScaleV, &[12, 1, 9], 10);
                step(f, Op::MakeVector, &[13, 13, 1, 10], 11);
                step(f, Op::SubV, &[9, 10, 11], 12);
                step(f, Op::FootOffsetFromTrace, &[3, 19, 0, 20], 13);
                step(f, Op::MakeVector, &[13, 13, 20, 9], 14);
                step(f, Op::AddV, &[11, 9, 10, 10, 10], 15);
                step(f, Op::RotationFromNormal, &[12, 21, 19, 2, 2, 2], 16);
                step(f, Op::GetTransformBreakTransform, &[9, 0, 1, 0, 0, 9, 3, 11], 17);
                step(f, Op::BreakVector, &[9, 20, 19, 21], 18);
                step(f, Op::MakeVector, &[20, 19, 0, 12], 19);
                step(f, Op::MulF, &[0, 10, 21], 20);
                step(f, Op::MakeVector, &[20, 19, 21, 11], 21);
                step(f, Op::DrawLine, &[12, 11, 11, 3], 22);
                step(f, Op::LineTrace, &[12, 11, 3, 9, 13, 19], 23);
                step(f, Op::DrawPoint, &[9, 12, 4], 24);
                step(f, Op::ScaleV, &[13, 1, 11], 25);
                step(f, Op::MakeVector, &[13, 13, 1, 12], 26);
                step(f, Op::SubV, &[11, 12, 9], 27);
                step(f, Op::FootOffsetFromTrace, &[3, 19, 0, 20], 28);
                step(f, Op::MakeVector, &[13, 13, 20, 11], 29);
                step(f, Op::AddV, &[9, 11, 12, 12, 12], 30);
                step(f, Op::RotationFromNormal, &[13, 21, 19, 3, 3, 3], 31);
                step(f, Op::BreakVector, &[10, 20, 19, 21], 32);
                step(f, Op::BreakVector, &[12, 19, 20, 22], 33);
                step(f, Op::MinF, &[21, 22, 19], 34);
                step(f, Op::Not, &[0, 3], 35);
                step(f, Op::WorldTransform, &[0], 36);
                step(f, Op::BreakTransform, &[0, 9, 4, 11], 37);
                step(f, Op::DistanceV, &[9, 0, 20], 38);
                step(f, Op::GreaterF, &[20, 8, 4], 39);
                step(f, Op::Or, &[3, 4, 5], 40);
                step(f, Op::LessF, &[19, 9, 3], 41);
                step(f, Op::Select(ValueType::Float), &[3, 5, 6, 21], 42);
                step(f, Op::Select(ValueType::Float), &[5, 14, 21, 22], 43);
                step(f, Op::FloatLerp, &[9, 19, 22, 20], 44);
                step(f, Op::Copy(ValueType::Float), &[20, 9, 1, 1], 45);
                step(f, Op::MakeVector, &[13, 13, 19, 13], 46);
                step(f, Op::SubV, &[10, 13, 11], 47);
                step(f, Op::BreakVector, &[11, 21, 22, 20], 48);
                step(f, Op::BreakVector, &[1, 21, 22, 23], 49);
                step(f, Op::LessF, &[20, 23, 4], 50);
                step(f, Op::Select(ValueType::Float), &[4, 3, 4, 21], 51);
                step(f, Op::Select(ValueType::Float), &[5, 14, 21, 22], 52);
                step(f, Op::VectorLerp, &[1, 11, 22, 13, 10, 10, 10], 53);
                step(f, Op::Copy(ValueType::Vec3), &[10, 1, 2, 2], 54);
                step(f, Op::MakeVector, &[13, 13, 19, 13], 55);
                step(f, Op::SubV, &[12, 13, 11], 56);
                step(f, Op::BreakVector, &[11, 20, 23, 21], 57);
                step(f, Op::BreakVector, &[2, 22, 19, 20], 58);
                step(f, Op::LessF, &[21, 20, 3], 59);
                step(f, Op::Select(ValueType::Float), &[3, 3, 4, 23], 60);
                step(f, Op::Select(ValueType::Float), &[5, 14, 23, 19], 61);
                step(f, Op::VectorLerp, &[2, 11, 19, 13, 10, 10, 10], 62);
                step(f, Op::Copy(ValueType::Vec3), &[10, 2], 63);
                step(f, Op::Select(ValueType::Float), &[5, 14, 7, 22], 64);
                step(f, Op::QuatLerp, &[0, 2, 22, 4], 65);
                step(f, Op::Copy(ValueType::Quat), &[4, 0], 66);
                step(f, Op::QuatLerp, &[1, 3, 22, 2], 67);
                step(f, Op::Copy(ValueType::Quat), &[2, 1], 68);
                step(f, Op::Copy(ValueType::Bool), &[1, 0], 69);
                step(f, Op::Copy(ValueType::Vec3), &[9, 0], 70);
                step(f, Op::GetTransformBreakTransform, &[10, 0, 1, 0, 0, 12, 4, 13], 71);
                step(f, Op::MakeVector, &[13, 13, 9, 11], 72);
                step(f, Op::AddV, &[12, 11, 10], 73);
                step(f, Op::MakeTransform, &[10, 4, 5, 0], 74);
                step(f, Op::SetTransform, &[11, 0, 0, 1, 15, 1, 1, 0, 0], 75);
                step(f, Op::GetTransformBreakTransform, &[14, 0, 1, 0, 0, 9, 3, 13], 76);
                step(f, Op::MakeVector, &[13, 13, 9, 11], 77);
                step(f, Op::AddVAddV, &[9, 11, 12, 12, 1, 10], 78);
                step(f, Op::MulQ, &[0, 3, 2], 79);
                step(f, Op::MakeTransform, &[10, 2, 5, 1], 80);
                step(f, Op::GetTransformBreakTransform, &[13, 0, 2, 2, 2, 14, 4, 15], 81);
                step(f, Op::MakeVector, &[13, 2, 13, 15], 82);
                step(f, Op::AddV, &[14, 15, 16], 83);
                step(f, Op::TwoBoneIK, &[12, 13, 14, 1, 6, 7, 16, 1, 15, 2, 16, 17, 1, 4, 20], 84);
                step(f, Op::GetTransformBreakTransform, &[14, 0, 1, 0, 0, 9, 3, 13], 85);
                step(f, Op::AddVAddV, &[9, 11, 12, 12, 1, 10], 86);
                step(f, Op::MulQ, &[0, 3, 2], 87);
                step(f, Op::MakeTransform, &[10, 2, 5, 1], 88);
                step(f, Op::DrawTransform, &[1, 18, 11, 2, 2, 1, 1], 89);
                step(f, Op::GetTransformBreakTransform, &[17, 0, 1, 2, 2, 14, 4, 15], 90);
                step(f, Op::MakeVector, &[13, 13, 9, 16], 91);
                step(f, Op::AddVAddV, &[14, 16, 13, 13, 2, 9], 92);
                step(f, Op::MulQ, &[1, 4, 3], 93);
                step(f, Op::MakeTransform, &[9, 3, 5, 0], 94);
                step(f, Op::GetTransformBreakTransform, &[16, 0, 2, 1, 1, 11, 2, 12], 95);
                step(f, Op::MakeVector, &[13, 2, 13, 10], 96);
                step(f, Op::AddV, &[11, 10, 12], 97);
                step(f, Op::TwoBoneIK, &[15, 16, 17, 0, 4, 8, 12, 1, 15, 2, 16, 17, 1, 3, 21], 98);
                step(f, Op::GetTransformBreakTransform, &[17, 0, 1, 2, 2, 14, 4, 15], 99);
                step(f, Op::AddVAddV, &[14, 16, 13, 13, 2, 9], 100);
                step(f, Op::MulQ, &[1, 4, 3], 101);
                step(f, Op::MakeTransform, &[9, 3, 5, 0], 102);
                step(f, Op::DrawTransform, &[0, 18, 11], 103);
                step(f, Op::End, &[], 104)
            }
            _ => return,
        } };
    }
}
