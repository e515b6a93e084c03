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
    fingerprint: 0x2d086bf75b893d88,
    forward,
};

fn forward(f: &mut Frame<'_>) {
    let mut pc: usize = 1;
    loop {
        // SAFETY: each `step` is an instruction of the program this code was generated
        // from, with its own operands; `NATIVE` runs only on that program (fingerprint).
        pc = unsafe { match pc {
            1 => {
                step(f, Op::Copy(ValueType::Bone), &[8, 0], 2);
                step(f, Op::Copy(ValueType::Vec3), &[69, 21], 3);
                step(f, Op::Copy(ValueType::Quat), &[20, 6], 4);
                step(f, Op::GetTransform, &[0, 0, 13, 3], 5);
                step(f, Op::BreakTransform, &[3, 22, 7, 23], 6);
                step(f, Op::BreakVector, &[22, 40, 41, 42], 7);
                step(f, Op::MakeVector, &[40, 41, 0, 24], 8);
                step(f, Op::MulF, &[0, 58, 43], 9);
                step(f, Op::MakeVector, &[40, 41, 43, 25], 10);
                step(f, Op::DrawLine, &[24, 25, 59, 70], 11);
                step(f, Op::LineTrace, &[24, 25, 9, 26, 27, 44], 12);
                step(f, Op::DrawPoint, &[26, 60, 71], 13);
                step(f, Op::ScaleV, &[27, 1, 28], 14);
                step(f, Op::MakeVector, &[61, 61, 1, 29], 15);
                step(f, Op::SubV, &[28, 29, 30], 16);
                step(f, Op::FootOffsetFromTrace, &[9, 44, 0, 45], 17);
                step(f, Op::MakeVector, &[61, 61, 45, 31], 18);
                step(f, Op::AddV, &[30, 31, 32], 19);
                step(f, Op::Copy(ValueType::Vec3), &[32, 21], 20);
                step(f, Op::RotationFromNormal, &[27, 46, 47, 8], 21);
                step(f, Op::Copy(ValueType::Quat), &[8, 6], 22);
                step(f, Op::Jump, &[23], 23)
            }
            23 => {
                step(f, Op::Copy(ValueType::Bone), &[9, 1], 24);
                step(f, Op::Copy(ValueType::Vec3), &[69, 33], 25);
                step(f, Op::Copy(ValueType::Quat), &[20, 9], 26);
                step(f, Op::GetTransform, &[1, 0, 13, 4], 27);
                step(f, Op::BreakTransform, &[4, 34, 10, 35], 28);
                step(f, Op::BreakVector, &[34, 48, 49, 50], 29);
                step(f, Op::MakeVector, &[48, 49, 0, 36], 30);
                step(f, Op::MulF, &[0, 58, 51], 31);
                step(f, Op::MakeVector, &[48, 49, 51, 37], 32);
                step(f, Op::DrawLine, &[36, 37, 59, 70], 33);
                step(f, Op::LineTrace, &[36, 37, 10, 38, 39, 52], 34);
                step(f, Op::DrawPoint, &[38, 60, 71], 35);
                step(f, Op::ScaleV, &[39, 1, 40], 36);
                step(f, Op::MakeVector, &[61, 61, 1, 41], 37);
                step(f, Op::SubV, &[40, 41, 42], 38);
                step(f, Op::FootOffsetFromTrace, &[10, 52, 0, 53], 39);
                step(f, Op::MakeVector, &[61, 61, 53, 43], 40);
                step(f, Op::AddV, &[42, 43, 44], 41);
                step(f, Op::Copy(ValueType::Vec3), &[44, 33], 42);
                step(f, Op::RotationFromNormal, &[39, 54, 55, 11], 43);
                step(f, Op::Copy(ValueType::Quat), &[11, 9], 44);
                step(f, Op::Jump, &[45], 45)
            }
            45 => {
                step(f, Op::BreakVector, &[21, 12, 13, 14], 46);
                step(f, Op::BreakVector, &[33, 15, 16, 17], 47);
                step(f, Op::MinF, &[14, 17, 11], 48);
                step(f, Op::Not, &[0, 2], 49);
                step(f, Op::WorldTransform, &[0], 50);
                step(f, Op::BreakTransform, &[0, 3, 2, 4], 51);
                step(f, Op::DistanceV, &[3, 0, 10], 52);
                step(f, Op::GreaterF, &[10, 8, 1], 53);
                step(f, Op::Or, &[2, 1, 3], 54);
                step(f, Op::LessF, &[11, 9, 4], 55);
                step(f, Op::Select(ValueType::Float), &[4, 5, 6, 18], 56);
                step(f, Op::Select(ValueType::Float), &[3, 62, 18, 19], 57);
                step(f, Op::FloatLerp, &[9, 11, 19, 20], 58);
                step(f, Op::Copy(ValueType::Float), &[20, 9], 59);
                step(f, Op::Copy(ValueType::Vec3), &[1, 5], 60);
                step(f, Op::Copy(ValueType::Vec3), &[21, 6], 61);
                step(f, Op::Copy(ValueType::Float), &[11, 21], 62);
                step(f, Op::Copy(ValueType::Bool), &[3, 5], 63);
                step(f, Op::Copy(ValueType::Vec3), &[69, 7], 64);
                step(f, Op::MakeVector, &[61, 61, 21, 8], 65);
                step(f, Op::SubV, &[6, 8, 9], 66);
                step(f, Op::BreakVector, &[9, 25, 26, 27], 67);
                step(f, Op::BreakVector, &[5, 22, 23, 24], 68);
                step(f, Op::LessF, &[27, 24, 6], 69);
                step(f, Op::Select(ValueType::Float), &[6, 3, 4, 28], 70);
                step(f, Op::Select(ValueType::Float), &[5, 62, 28, 29], 71);
                step(f, Op::VectorLerp, &[5, 9, 29, 61, 10], 72);
                step(f, Op::Copy(ValueType::Vec3), &[10, 7], 73);
                step(f, Op::Jump, &[74], 74)
            }
            74 => {
                step(f, Op::Copy(ValueType::Vec3), &[7, 1], 75);
                step(f, Op::Copy(ValueType::Vec3), &[2, 11], 76);
                step(f, Op::Copy(ValueType::Vec3), &[33, 12], 77);
                step(f, Op::Copy(ValueType::Float), &[11, 30], 78);
                step(f, Op::Copy(ValueType::Bool), &[3, 7], 79);
                step(f, Op::Copy(ValueType::Vec3), &[69, 13], 80);
                step(f, Op::MakeVector, &[61, 61, 30, 14], 81);
                step(f, Op::SubV, &[12, 14, 15], 82);
                step(f, Op::BreakVector, &[15, 34, 35, 36], 83);
                step(f, Op::BreakVector, &[11, 31, 32, 33], 84);
                step(f, Op::LessF, &[36, 33, 8], 85);
                step(f, Op::Select(ValueType::Float), &[8, 3, 4, 37], 86);
                step(f, Op::Select(ValueType::Float), &[7, 62, 37, 38], 87);
                step(f, Op::VectorLerp, &[11, 15, 38, 61, 16], 88);
                step(f, Op::Copy(ValueType::Vec3), &[16, 13], 89);
                step(f, Op::Jump, &[90], 90)
            }
            90 => {
                step(f, Op::Copy(ValueType::Vec3), &[13, 2], 91);
                step(f, Op::Select(ValueType::Float), &[3, 62, 7, 39], 92);
                step(f, Op::QuatLerp, &[0, 6, 39, 3], 93);
                step(f, Op::Copy(ValueType::Quat), &[3, 0], 94);
                step(f, Op::QuatLerp, &[1, 9, 39, 4], 95);
                step(f, Op::Copy(ValueType::Quat), &[4, 1], 96);
                step(f, Op::Copy(ValueType::Bool), &[13, 0], 97);
                step(f, Op::Copy(ValueType::Vec3), &[3, 0], 98);
                step(f, Op::GetTransform, &[10, 0, 13, 1], 99);
                step(f, Op::BreakTransform, &[1, 17, 5, 18], 100);
                step(f, Op::MakeVector, &[61, 61, 9, 19], 101);
                step(f, Op::AddV, &[17, 19, 20], 102);
                step(f, Op::MakeTransform, &[20, 5, 72, 2], 103);
                step(f, Op::SetTransform, &[11, 2, 0, 13, 63], 104);
                step(f, Op::Copy(ValueType::Bone), &[12, 2], 105);
                step(f, Op::Copy(ValueType::Bone), &[13, 3], 106);
                step(f, Op::Copy(ValueType::Bone), &[14, 4], 107);
                step(f, Op::Copy(ValueType::Vec3), &[1, 45], 108);
                step(f, Op::Copy(ValueType::Quat), &[0, 12], 109);
                step(f, Op::Copy(ValueType::Vec3), &[73, 46], 110);
                step(f, Op::Copy(ValueType::Vec3), &[74, 47], 111);
                step(f, Op::GetTransform, &[4, 0, 13, 5], 112);
                step(f, Op::BreakTransform, &[5, 48, 13, 49], 113);
                step(f, Op::MakeVector, &[61, 61, 9, 50], 114);
                step(f, Op::AddV, &[48, 50, 51], 115);
                step(f, Op::AddV, &[51, 45, 52], 116);
                step(f, Op::MulQ, &[12, 13, 14], 117);
                step(f, Op::MakeTransform, &[52, 14, 72, 6], 118);
                step(f, Op::GetTransform, &[3, 0, 14, 7], 119);
                step(f, Op::BreakTransform, &[7, 53, 15, 54], 120);
                step(f, Op::MakeVector, &[61, 2, 61, 55], 121);
                step(f, Op::AddV, &[53, 55, 56], 122);
                step(f, Op::TwoBoneIK, &[2, 3, 4, 6, 46, 47, 56, 1, 63, 14, 64, 65, 13, 11, 56], 123);
                step(f, Op::GetTransform, &[4, 0, 13, 5], 124);
                step(f, Op::BreakTransform, &[5, 48, 13, 49], 125);
                step(f, Op::AddV, &[48, 50, 51], 126);
                step(f, Op::AddV, &[51, 45, 52], 127);
                step(f, Op::MulQ, &[12, 13, 14], 128);
                step(f, Op::MakeTransform, &[52, 14, 72, 6], 129);
                step(f, Op::DrawTransform, &[6, 66, 59], 130);
                step(f, Op::Copy(ValueType::Bone), &[15, 5], 131);
                step(f, Op::Copy(ValueType::Bone), &[16, 6], 132);
                step(f, Op::Copy(ValueType::Bone), &[17, 7], 133);
                step(f, Op::Copy(ValueType::Vec3), &[2, 57], 134);
                step(f, Op::Copy(ValueType::Quat), &[1, 16], 135);
                step(f, Op::Copy(ValueType::Vec3), &[71, 58], 136);
                step(f, Op::Copy(ValueType::Vec3), &[75, 59], 137);
                step(f, Op::GetTransform, &[7, 0, 13, 8], 138);
                step(f, Op::BreakTransform, &[8, 60, 17, 61], 139);
                step(f, Op::MakeVector, &[61, 61, 9, 62], 140);
                step(f, Op::AddV, &[60, 62, 63], 141);
                step(f, Op::AddV, &[63, 57, 64], 142);
                step(f, Op::MulQ, &[16, 17, 18], 143);
                step(f, Op::MakeTransform, &[64, 18, 72, 9], 144);
                step(f, Op::GetTransform, &[6, 0, 14, 10], 145);
                step(f, Op::BreakTransform, &[10, 65, 19, 66], 146);
                step(f, Op::MakeVector, &[61, 2, 61, 67], 147);
                step(f, Op::AddV, &[65, 67, 68], 148);
                step(f, Op::TwoBoneIK, &[5, 6, 7, 9, 58, 59, 68, 1, 63, 14, 64, 65, 13, 12, 57], 149);
                step(f, Op::GetTransform, &[7, 0, 13, 8], 150);
                step(f, Op::BreakTransform, &[8, 60, 17, 61], 151);
                step(f, Op::AddV, &[60, 62, 63], 152);
                step(f, Op::AddV, &[63, 57, 64], 153);
                step(f, Op::MulQ, &[16, 17, 18], 154);
                step(f, Op::MakeTransform, &[64, 18, 72, 9], 155);
                step(f, Op::DrawTransform, &[9, 66, 59], 156);
                step(f, Op::End, &[], 157)
            }
            _ => return,
        } };
    }
}
