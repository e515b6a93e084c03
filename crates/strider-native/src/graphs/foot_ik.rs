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
    fingerprint: 0x680339e931c46909,
    forward,
};

fn forward(f: &mut Frame<'_>) {
    let mut pc: usize = 1;
    loop {
        // SAFETY: each `step` is an instruction of the program this code was generated
        // from, with its own operands; `NATIVE` runs only on that program (fingerprint).
        pc = unsafe { match pc {
            1 => {
                step(f, Op::GetTransform, &[8, 0, 13, 3], 2);
                step(f, Op::BreakTransform, &[3, 22, 7, 23], 3);
                step(f, Op::BreakVector, &[22, 40, 41, 42], 4);
                step(f, Op::MakeVector, &[40, 41, 0, 24], 5);
                step(f, Op::MulF, &[0, 58, 43], 6);
                step(f, Op::MakeVector, &[40, 41, 43, 25], 7);
                step(f, Op::DrawLine, &[24, 25, 59, 69], 8);
                step(f, Op::LineTrace, &[24, 25, 9, 26, 27, 44], 9);
                step(f, Op::DrawPoint, &[26, 60, 70], 10);
                step(f, Op::ScaleV, &[27, 1, 28], 11);
                step(f, Op::MakeVector, &[61, 61, 1, 29], 12);
                step(f, Op::SubV, &[28, 29, 30], 13);
                step(f, Op::FootOffsetFromTrace, &[9, 44, 0, 45], 14);
                step(f, Op::MakeVector, &[61, 61, 45, 31], 15);
                step(f, Op::AddV, &[30, 31, 32], 16);
                step(f, Op::Copy(ValueType::Vec3), &[32, 21], 17);
                step(f, Op::RotationFromNormal, &[27, 46, 47, 8], 18);
                step(f, Op::Copy(ValueType::Quat), &[8, 6], 19);
                step(f, Op::GetTransform, &[9, 0, 13, 4], 20);
                step(f, Op::BreakTransform, &[4, 34, 10, 35], 21);
                step(f, Op::BreakVector, &[34, 48, 49, 50], 22);
                step(f, Op::MakeVector, &[48, 49, 0, 36], 23);
                step(f, Op::MulF, &[0, 58, 51], 24);
                step(f, Op::MakeVector, &[48, 49, 51, 37], 25);
                step(f, Op::DrawLine, &[36, 37, 59, 69], 26);
                step(f, Op::LineTrace, &[36, 37, 10, 38, 39, 52], 27);
                step(f, Op::DrawPoint, &[38, 60, 70], 28);
                step(f, Op::ScaleV, &[39, 1, 40], 29);
                step(f, Op::MakeVector, &[61, 61, 1, 41], 30);
                step(f, Op::SubV, &[40, 41, 42], 31);
                step(f, Op::FootOffsetFromTrace, &[10, 52, 0, 53], 32);
                step(f, Op::MakeVector, &[61, 61, 53, 43], 33);
                step(f, Op::AddV, &[42, 43, 44], 34);
                step(f, Op::Copy(ValueType::Vec3), &[44, 33], 35);
                step(f, Op::RotationFromNormal, &[39, 54, 55, 11], 36);
                step(f, Op::Copy(ValueType::Quat), &[11, 9], 37);
                step(f, Op::BreakVector, &[21, 12, 13, 14], 38);
                step(f, Op::BreakVector, &[33, 15, 16, 17], 39);
                step(f, Op::MinF, &[14, 17, 11], 40);
                step(f, Op::Not, &[0, 2], 41);
                step(f, Op::WorldTransform, &[0], 42);
                step(f, Op::BreakTransform, &[0, 3, 2, 4], 43);
                step(f, Op::DistanceV, &[3, 0, 10], 44);
                step(f, Op::GreaterF, &[10, 8, 1], 45);
                step(f, Op::Or, &[2, 1, 3], 46);
                step(f, Op::LessF, &[11, 9, 4], 47);
                step(f, Op::Select(ValueType::Float), &[4, 5, 6, 18], 48);
                step(f, Op::Select(ValueType::Float), &[3, 62, 18, 19], 49);
                step(f, Op::FloatLerp, &[9, 11, 19, 20], 50);
                step(f, Op::Copy(ValueType::Float), &[20, 9], 51);
                step(f, Op::Copy(ValueType::Vec3), &[1, 5], 52);
                step(f, Op::MakeVector, &[61, 61, 11, 8], 53);
                step(f, Op::SubV, &[21, 8, 9], 54);
                step(f, Op::BreakVector, &[9, 25, 26, 27], 55);
                step(f, Op::BreakVector, &[5, 22, 23, 24], 56);
                step(f, Op::LessF, &[27, 24, 6], 57);
                step(f, Op::Select(ValueType::Float), &[6, 3, 4, 28], 58);
                step(f, Op::Select(ValueType::Float), &[3, 62, 28, 29], 59);
                step(f, Op::VectorLerp, &[5, 9, 29, 61, 10], 60);
                step(f, Op::Copy(ValueType::Vec3), &[10, 7], 61);
                step(f, Op::Copy(ValueType::Vec3), &[7, 1], 62);
                step(f, Op::Copy(ValueType::Vec3), &[2, 11], 63);
                step(f, Op::MakeVector, &[61, 61, 11, 14], 64);
                step(f, Op::SubV, &[33, 14, 15], 65);
                step(f, Op::BreakVector, &[15, 34, 35, 36], 66);
                step(f, Op::BreakVector, &[11, 31, 32, 33], 67);
                step(f, Op::LessF, &[36, 33, 8], 68);
                step(f, Op::Select(ValueType::Float), &[8, 3, 4, 37], 69);
                step(f, Op::Select(ValueType::Float), &[3, 62, 37, 38], 70);
                step(f, Op::VectorLerp, &[11, 15, 38, 61, 16], 71);
                step(f, Op::Copy(ValueType::Vec3), &[16, 13], 72);
                step(f, Op::Copy(ValueType::Vec3), &[13, 2], 73);
                step(f, Op::Select(ValueType::Float), &[3, 62, 7, 39], 74);
                step(f, Op::QuatLerp, &[0, 6, 39, 3], 75);
                step(f, Op::Copy(ValueType::Quat), &[3, 0], 76);
                step(f, Op::QuatLerp, &[1, 9, 39, 4], 77);
                step(f, Op::Copy(ValueType::Quat), &[4, 1], 78);
                step(f, Op::Copy(ValueType::Bool), &[13, 0], 79);
                step(f, Op::Copy(ValueType::Vec3), &[3, 0], 80);
                step(f, Op::GetTransform, &[10, 0, 13, 1], 81);
                step(f, Op::BreakTransform, &[1, 17, 5, 18], 82);
                step(f, Op::MakeVector, &[61, 61, 9, 19], 83);
                step(f, Op::AddV, &[17, 19, 20], 84);
                step(f, Op::MakeTransform, &[20, 5, 71, 2], 85);
                step(f, Op::SetTransform, &[11, 2, 0, 13, 63], 86);
                step(f, Op::Copy(ValueType::Vec3), &[1, 45], 87);
                step(f, Op::Copy(ValueType::Quat), &[0, 12], 88);
                step(f, Op::GetTransform, &[14, 0, 13, 5], 89);
                step(f, Op::BreakTransform, &[5, 48, 13, 49], 90);
                step(f, Op::MakeVector, &[61, 61, 9, 50], 91);
                step(f, Op::AddV, &[48, 50, 51], 92);
                step(f, Op::AddV, &[51, 45, 52], 93);
                step(f, Op::MulQ, &[12, 13, 14], 94);
                step(f, Op::MakeTransform, &[52, 14, 71, 6], 95);
                step(f, Op::GetTransform, &[13, 0, 14, 7], 96);
                step(f, Op::BreakTransform, &[7, 53, 15, 54], 97);
                step(f, Op::MakeVector, &[61, 2, 61, 55], 98);
                step(f, Op::AddV, &[53, 55, 56], 99);
                step(f, Op::TwoBoneIK, &[12, 13, 14, 6, 72, 73, 56, 1, 63, 14, 64, 65, 13, 11, 56], 100);
                step(f, Op::GetTransform, &[14, 0, 13, 5], 101);
                step(f, Op::BreakTransform, &[5, 48, 13, 49], 102);
                step(f, Op::AddV, &[48, 50, 51], 103);
                step(f, Op::AddV, &[51, 45, 52], 104);
                step(f, Op::MulQ, &[12, 13, 14], 105);
                step(f, Op::MakeTransform, &[52, 14, 71, 6], 106);
                step(f, Op::DrawTransform, &[6, 66, 59], 107);
                step(f, Op::Copy(ValueType::Vec3), &[2, 57], 108);
                step(f, Op::Copy(ValueType::Quat), &[1, 16], 109);
                step(f, Op::GetTransform, &[17, 0, 13, 8], 110);
                step(f, Op::BreakTransform, &[8, 60, 17, 61], 111);
                step(f, Op::MakeVector, &[61, 61, 9, 62], 112);
                step(f, Op::AddV, &[60, 62, 63], 113);
                step(f, Op::AddV, &[63, 57, 64], 114);
                step(f, Op::MulQ, &[16, 17, 18], 115);
                step(f, Op::MakeTransform, &[64, 18, 71, 9], 116);
                step(f, Op::GetTransform, &[16, 0, 14, 10], 117);
                step(f, Op::BreakTransform, &[10, 65, 19, 66], 118);
                step(f, Op::MakeVector, &[61, 2, 61, 67], 119);
                step(f, Op::AddV, &[65, 67, 68], 120);
                step(f, Op::TwoBoneIK, &[15, 16, 17, 9, 70, 74, 68, 1, 63, 14, 64, 65, 13, 12, 57], 121);
                step(f, Op::GetTransform, &[17, 0, 13, 8], 122);
                step(f, Op::BreakTransform, &[8, 60, 17, 61], 123);
                step(f, Op::AddV, &[60, 62, 63], 124);
                step(f, Op::AddV, &[63, 57, 64], 125);
                step(f, Op::MulQ, &[16, 17, 18], 126);
                step(f, Op::MakeTransform, &[64, 18, 71, 9], 127);
                step(f, Op::DrawTransform, &[9, 66, 59], 128);
                step(f, Op::End, &[], 129)
            }
            _ => return,
        } };
    }
}
