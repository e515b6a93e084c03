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
    fingerprint: 0xcfa0d66b0dd11602,
    forward,
};

fn forward(f: &mut Frame<'_>) {
    let mut pc: usize = 1;
    loop {
        // SAFETY: each `step` is an instruction of the program this code was generated
        // from, with its own operands; `NATIVE` runs only on that program (fingerprint).
        pc = unsafe { match pc {
            1 => {
                step(f, Op::GetTransform, &[8, 0, 1, 0], 2);
                step(f, Op::BreakTransform, &[0, 9, 2, 10], 3);
                step(f, Op::BreakVector, &[9, 19, 20, 21], 4);
                step(f, Op::MakeVector, &[19, 20, 0, 10], 5);
                step(f, Op::MulF, &[0, 10, 21], 6);
                step(f, Op::MakeVector, &[19, 20, 21, 9], 7);
                step(f, Op::DrawLine, &[10, 9, 11, 3], 8);
                step(f, Op::LineTrace, &[10, 9, 3, 11, 12, 19], 9);
                step(f, Op::DrawPoint, &[11, 12, 4], 10);
                step(f, Op::ScaleV, &[12, 1, 9], 11);
                step(f, Op::MakeVector, &[13, 13, 1, 10], 12);
                step(f, Op::SubV, &[9, 10, 11], 13);
                step(f, Op::FootOffsetFromTrace, &[3, 19, 0, 20], 14);
                step(f, Op::MakeVector, &[13, 13, 20, 9], 15);
                step(f, Op::AddV, &[11, 9, 10], 16);
                step(f, Op::Copy(ValueType::Vec3), &[10, 9], 17);
                step(f, Op::RotationFromNormal, &[12, 21, 19, 2], 18);
                step(f, Op::Copy(ValueType::Quat), &[2, 3], 19);
                step(f, Op::GetTransform, &[9, 0, 1, 0], 20);
                step(f, Op::BreakTransform, &[0, 11, 2, 10], 21);
                step(f, Op::BreakVector, &[11, 20, 19, 21], 22);
                step(f, Op::MakeVector, &[20, 19, 0, 12], 23);
                step(f, Op::MulF, &[0, 10, 21], 24);
                step(f, Op::MakeVector, &[20, 19, 21, 10], 25);
                step(f, Op::DrawLine, &[12, 10, 11, 3], 26);
                step(f, Op::LineTrace, &[12, 10, 3, 11, 13, 19], 27);
                step(f, Op::DrawPoint, &[11, 12, 4], 28);
                step(f, Op::ScaleV, &[13, 1, 10], 29);
                step(f, Op::MakeVector, &[13, 13, 1, 12], 30);
                step(f, Op::SubV, &[10, 12, 11], 31);
                step(f, Op::FootOffsetFromTrace, &[3, 19, 0, 20], 32);
                step(f, Op::MakeVector, &[13, 13, 20, 10], 33);
                step(f, Op::AddV, &[11, 10, 12], 34);
                step(f, Op::Copy(ValueType::Vec3), &[12, 10], 35);
                step(f, Op::RotationFromNormal, &[13, 21, 19, 2], 36);
                step(f, Op::Copy(ValueType::Quat), &[2, 4], 37);
                step(f, Op::BreakVector, &[9, 20, 19, 21], 38);
                step(f, Op::BreakVector, &[10, 19, 20, 22], 39);
                step(f, Op::MinF, &[21, 22, 19], 40);
                step(f, Op::Not, &[0, 3], 41);
                step(f, Op::WorldTransform, &[0], 42);
                step(f, Op::BreakTransform, &[0, 11, 2, 12], 43);
                step(f, Op::DistanceV, &[11, 0, 20], 44);
                step(f, Op::GreaterF, &[20, 8, 4], 45);
                step(f, Op::Or, &[3, 4, 5], 46);
                step(f, Op::LessF, &[19, 9, 3], 47);
                step(f, Op::Select(ValueType::Float), &[3, 5, 6, 21], 48);
                step(f, Op::Select(ValueType::Float), &[5, 14, 21, 22], 49);
                step(f, Op::FloatLerp, &[9, 19, 22, 20], 50);
                step(f, Op::Copy(ValueType::Float), &[20, 9], 51);
                step(f, Op::Copy(ValueType::Vec3), &[1, 13], 52);
                step(f, Op::MakeVector, &[13, 13, 19, 12], 53);
                step(f, Op::SubV, &[9, 12, 14], 54);
                step(f, Op::BreakVector, &[14, 21, 22, 20], 55);
                step(f, Op::BreakVector, &[13, 21, 22, 23], 56);
                step(f, Op::LessF, &[20, 23, 4], 57);
                step(f, Op::Select(ValueType::Float), &[4, 3, 4, 21], 58);
                step(f, Op::Select(ValueType::Float), &[5, 14, 21, 22], 59);
                step(f, Op::VectorLerp, &[13, 14, 22, 13, 9], 60);
                step(f, Op::Copy(ValueType::Vec3), &[9, 12], 61);
                step(f, Op::Copy(ValueType::Vec3), &[12, 1], 62);
                step(f, Op::Copy(ValueType::Vec3), &[2, 13], 63);
                step(f, Op::MakeVector, &[13, 13, 19, 14], 64);
                step(f, Op::SubV, &[10, 14, 9], 65);
                step(f, Op::BreakVector, &[9, 20, 23, 21], 66);
                step(f, Op::BreakVector, &[13, 22, 19, 20], 67);
                step(f, Op::LessF, &[21, 20, 3], 68);
                step(f, Op::Select(ValueType::Float), &[3, 3, 4, 23], 69);
                step(f, Op::Select(ValueType::Float), &[5, 14, 23, 19], 70);
                step(f, Op::VectorLerp, &[13, 9, 19, 13, 12], 71);
                step(f, Op::Copy(ValueType::Vec3), &[12, 10], 72);
                step(f, Op::Copy(ValueType::Vec3), &[10, 2], 73);
                step(f, Op::Select(ValueType::Float), &[5, 14, 7, 22], 74);
                step(f, Op::QuatLerp, &[0, 3, 22, 2], 75);
                step(f, Op::Copy(ValueType::Quat), &[2, 0], 76);
                step(f, Op::QuatLerp, &[1, 4, 22, 3], 77);
                step(f, Op::Copy(ValueType::Quat), &[3, 1], 78);
                step(f, Op::Copy(ValueType::Bool), &[1, 0], 79);
                step(f, Op::Copy(ValueType::Vec3), &[11, 0], 80);
                step(f, Op::GetTransform, &[10, 0, 1, 0], 81);
                step(f, Op::BreakTransform, &[0, 14, 2, 9], 82);
                step(f, Op::MakeVector, &[13, 13, 9, 13], 83);
                step(f, Op::AddV, &[14, 13, 12], 84);
                step(f, Op::MakeTransform, &[12, 2, 5, 0], 85);
                step(f, Op::SetTransform, &[11, 0, 0, 1, 15], 86);
                step(f, Op::Copy(ValueType::Vec3), &[1, 10], 87);
                step(f, Op::Copy(ValueType::Quat), &[0, 4], 88);
                step(f, Op::GetTransform, &[14, 0, 1, 0], 89);
                step(f, Op::BreakTransform, &[0, 11, 3, 9], 90);
                step(f, Op::MakeVector, &[13, 13, 9, 13], 91);
                step(f, Op::AddV, &[11, 13, 14], 92);
                step(f, Op::AddV, &[14, 10, 12], 93);
                step(f, Op::MulQ, &[4, 3, 2], 94);
                step(f, Op::MakeTransform, &[12, 2, 5, 1], 95);
                step(f, Op::GetTransform, &[13, 0, 2, 2], 96);
                step(f, Op::BreakTransform, &[2, 15, 5, 16], 97);
                step(f, Op::MakeVector, &[13, 2, 13, 16], 98);
                step(f, Op::AddV, &[15, 16, 17], 99);
                step(f, Op::TwoBoneIK, &[12, 13, 14, 1, 6, 7, 17, 1, 15, 2, 16, 17, 1, 4, 20], 100);
                step(f, Op::GetTransform, &[14, 0, 1, 0], 101);
                step(f, Op::BreakTransform, &[0, 11, 3, 9], 102);
                step(f, Op::AddV, &[11, 13, 14], 103);
                step(f, Op::AddV, &[14, 10, 12], 104);
                step(f, Op::MulQ, &[4, 3, 2], 105);
                step(f, Op::MakeTransform, &[12, 2, 5, 1], 106);
                step(f, Op::DrawTransform, &[1, 18, 11], 107);
                step(f, Op::Copy(ValueType::Vec3), &[2, 15], 108);
                step(f, Op::Copy(ValueType::Quat), &[1, 5], 109);
                step(f, Op::GetTransform, &[17, 0, 1, 2], 110);
                step(f, Op::BreakTransform, &[2, 16, 3, 17], 111);
                step(f, Op::MakeVector, &[13, 13, 9, 9], 112);
                step(f, Op::AddV, &[16, 9, 11], 113);
                step(f, Op::AddV, &[11, 15, 13], 114);
                step(f, Op::MulQ, &[5, 3, 4], 115);
                step(f, Op::MakeTransform, &[13, 4, 5, 0], 116);
                step(f, Op::GetTransform, &[16, 0, 2, 1], 117);
                step(f, Op::BreakTransform, &[1, 10, 2, 14], 118);
                step(f, Op::MakeVector, &[13, 2, 13, 12], 119);
                step(f, Op::AddV, &[10, 12, 14], 120);
                step(f, Op::TwoBoneIK, &[15, 16, 17, 0, 4, 8, 14, 1, 15, 2, 16, 17, 1, 3, 21], 121);
                step(f, Op::GetTransform, &[17, 0, 1, 2], 122);
                step(f, Op::BreakTransform, &[2, 16, 3, 17], 123);
                step(f, Op::AddV, &[16, 9, 11], 124);
                step(f, Op::AddV, &[11, 15, 13], 125);
                step(f, Op::MulQ, &[5, 3, 4], 126);
                step(f, Op::MakeTransform, &[13, 4, 5, 0], 127);
                step(f, Op::DrawTransform, &[0, 18, 11], 128);
                step(f, Op::End, &[], 129)
            }
            _ => return,
        } };
    }
}
