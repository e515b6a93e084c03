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
    fingerprint: 0xc92be63a6e46d234,
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
                step(f, Op::GetTransform, &[0, 0, 13, 3], 12);
                step(f, Op::BreakTransform, &[3, 22, 7, 23], 13);
                step(f, Op::BreakVector, &[22, 40, 41, 42], 14);
                step(f, Op::MakeVector, &[40, 41, 0, 24], 15);
                step(f, Op::MulF, &[0, 58, 43], 16);
                step(f, Op::MakeVector, &[40, 41, 43, 25], 17);
                step(f, Op::LineTrace, &[24, 25, 9, 26, 27, 44], 18);
                step(f, Op::DrawPoint, &[26, 60, 71], 19);
                step(f, Op::GetTransform, &[0, 0, 13, 3], 20);
                step(f, Op::BreakTransform, &[3, 22, 7, 23], 21);
                step(f, Op::BreakVector, &[22, 40, 41, 42], 22);
                step(f, Op::MakeVector, &[40, 41, 0, 24], 23);
                step(f, Op::MulF, &[0, 58, 43], 24);
                step(f, Op::MakeVector, &[40, 41, 43, 25], 25);
                step(f, Op::LineTrace, &[24, 25, 9, 26, 27, 44], 26);
                step(f, Op::ScaleV, &[27, 1, 28], 27);
                step(f, Op::MakeVector, &[61, 61, 1, 29], 28);
                step(f, Op::SubV, &[28, 29, 30], 29);
                step(f, Op::FootOffsetFromTrace, &[9, 44, 0, 45], 30);
                step(f, Op::MakeVector, &[61, 61, 45, 31], 31);
                step(f, Op::AddV, &[30, 31, 32], 32);
                step(f, Op::Copy(ValueType::Vec3), &[32, 21], 33);
                step(f, Op::RotationFromNormal, &[27, 46, 47, 8], 34);
                step(f, Op::Copy(ValueType::Quat), &[8, 6], 35);
                step(f, Op::Jump, &[36], 36)
            }
            36 => {
                step(f, Op::Copy(ValueType::Bone), &[9, 1], 37);
                step(f, Op::Copy(ValueType::Vec3), &[69, 33], 38);
                step(f, Op::Copy(ValueType::Quat), &[20, 9], 39);
                step(f, Op::GetTransform, &[1, 0, 13, 4], 40);
                step(f, Op::BreakTransform, &[4, 34, 10, 35], 41);
                step(f, Op::BreakVector, &[34, 48, 49, 50], 42);
                step(f, Op::MakeVector, &[48, 49, 0, 36], 43);
                step(f, Op::MulF, &[0, 58, 51], 44);
                step(f, Op::MakeVector, &[48, 49, 51, 37], 45);
                step(f, Op::DrawLine, &[36, 37, 59, 70], 46);
                step(f, Op::GetTransform, &[1, 0, 13, 4], 47);
                step(f, Op::BreakTransform, &[4, 34, 10, 35], 48);
                step(f, Op::BreakVector, &[34, 48, 49, 50], 49);
                step(f, Op::MakeVector, &[48, 49, 0, 36], 50);
                step(f, Op::MulF, &[0, 58, 51], 51);
                step(f, Op::MakeVector, &[48, 49, 51, 37], 52);
                step(f, Op::LineTrace, &[36, 37, 10, 38, 39, 52], 53);
                step(f, Op::DrawPoint, &[38, 60, 71], 54);
                step(f, Op::GetTransform, &[1, 0, 13, 4], 55);
                step(f, Op::BreakTransform, &[4, 34, 10, 35], 56);
                step(f, Op::BreakVector, &[34, 48, 49, 50], 57);
                step(f, Op::MakeVector, &[48, 49, 0, 36], 58);
                step(f, Op::MulF, &[0, 58, 51], 59);
                step(f, Op::MakeVector, &[48, 49, 51, 37], 60);
                step(f, Op::LineTrace, &[36, 37, 10, 38, 39, 52], 61);
                step(f, Op::ScaleV, &[39, 1, 40], 62);
                step(f, Op::MakeVector, &[61, 61, 1, 41], 63);
                step(f, Op::SubV, &[40, 41, 42], 64);
                step(f, Op::FootOffsetFromTrace, &[10, 52, 0, 53], 65);
                step(f, Op::MakeVector, &[61, 61, 53, 43], 66);
                step(f, Op::AddV, &[42, 43, 44], 67);
                step(f, Op::Copy(ValueType::Vec3), &[44, 33], 68);
                step(f, Op::RotationFromNormal, &[39, 54, 55, 11], 69);
                step(f, Op::Copy(ValueType::Quat), &[11, 9], 70);
                step(f, Op::Jump, &[71], 71)
            }
            71 => {
                step(f, Op::BreakVector, &[21, 12, 13, 14], 72);
                step(f, Op::BreakVector, &[33, 15, 16, 17], 73);
                step(f, Op::MinF, &[14, 17, 11], 74);
                step(f, Op::Not, &[0, 2], 75);
                step(f, Op::WorldTransform, &[0], 76);
                step(f, Op::BreakTransform, &[0, 3, 2, 4], 77);
                step(f, Op::DistanceV, &[3, 0, 10], 78);
                step(f, Op::GreaterF, &[10, 8, 1], 79);
                step(f, Op::Or, &[2, 1, 3], 80);
                step(f, Op::LessF, &[11, 9, 4], 81);
                step(f, Op::Select(ValueType::Float), &[4, 5, 6, 18], 82);
                step(f, Op::Select(ValueType::Float), &[3, 62, 18, 19], 83);
                step(f, Op::FloatLerp, &[9, 11, 19, 20], 84);
                step(f, Op::Copy(ValueType::Float), &[20, 9], 85);
                step(f, Op::Copy(ValueType::Vec3), &[1, 5], 86);
                step(f, Op::Copy(ValueType::Vec3), &[21, 6], 87);
                step(f, Op::Copy(ValueType::Float), &[11, 21], 88);
                step(f, Op::Copy(ValueType::Bool), &[3, 5], 89);
                step(f, Op::Copy(ValueType::Vec3), &[69, 7], 90);
                step(f, Op::MakeVector, &[61, 61, 21, 8], 91);
                step(f, Op::SubV, &[6, 8, 9], 92);
                step(f, Op::BreakVector, &[9, 25, 26, 27], 93);
                step(f, Op::BreakVector, &[5, 22, 23, 24], 94);
                step(f, Op::LessF, &[27, 24, 6], 95);
                step(f, Op::Select(ValueType::Float), &[6, 3, 4, 28], 96);
                step(f, Op::Select(ValueType::Float), &[5, 62, 28, 29], 97);
                step(f, Op::VectorLerp, &[5, 9, 29, 61, 10], 98);
                step(f, Op::Copy(ValueType::Vec3), &[10, 7], 99);
                step(f, Op::Jump, &[100], 100)
            }
            100 => {
                step(f, Op::Copy(ValueType::Vec3), &[7, 1], 101);
                step(f, Op::Copy(ValueType::Vec3), &[2, 11], 102);
                step(f, Op::Copy(ValueType::Vec3), &[33, 12], 103);
                step(f, Op::Copy(ValueType::Float), &[11, 30], 104);
                step(f, Op::Copy(ValueType::Bool), &[3, 7], 105);
                step(f, Op::Copy(ValueType::Vec3), &[69, 13], 106);
                step(f, Op::MakeVector, &[61, 61, 30, 14], 107);
                step(f, Op::SubV, &[12, 14, 15], 108);
                step(f, Op::BreakVector, &[15, 34, 35, 36], 109);
                step(f, Op::BreakVector, &[11, 31, 32, 33], 110);
                step(f, Op::LessF, &[36, 33, 8], 111);
                step(f, Op::Select(ValueType::Float), &[8, 3, 4, 37], 112);
                step(f, Op::Select(ValueType::Float), &[7, 62, 37, 38], 113);
                step(f, Op::VectorLerp, &[11, 15, 38, 61, 16], 114);
                step(f, Op::Copy(ValueType::Vec3), &[16, 13], 115);
                step(f, Op::Jump, &[116], 116)
            }
            116 => {
                step(f, Op::Copy(ValueType::Vec3), &[13, 2], 117);
                step(f, Op::Select(ValueType::Float), &[3, 62, 7, 39], 118);
                step(f, Op::QuatLerp, &[0, 6, 39, 3], 119);
                step(f, Op::Copy(ValueType::Quat), &[3, 0], 120);
                step(f, Op::QuatLerp, &[1, 9, 39, 4], 121);
                step(f, Op::Copy(ValueType::Quat), &[4, 1], 122);
                step(f, Op::Copy(ValueType::Bool), &[13, 0], 123);
                step(f, Op::Copy(ValueType::Vec3), &[3, 0], 124);
                step(f, Op::GetTransform, &[10, 0, 13, 1], 125);
                step(f, Op::BreakTransform, &[1, 17, 5, 18], 126);
                step(f, Op::MakeVector, &[61, 61, 9, 19], 127);
                step(f, Op::AddV, &[17, 19, 20], 128);
                step(f, Op::MakeTransform, &[20, 5, 72, 2], 129);
                step(f, Op::SetTransform, &[11, 2, 0, 13, 63], 130);
                step(f, Op::Copy(ValueType::Bone), &[12, 2], 131);
                step(f, Op::Copy(ValueType::Bone), &[13, 3], 132);
                step(f, Op::Copy(ValueType::Bone), &[14, 4], 133);
                step(f, Op::Copy(ValueType::Vec3), &[1, 45], 134);
                step(f, Op::Copy(ValueType::Quat), &[0, 12], 135);
                step(f, Op::Copy(ValueType::Vec3), &[73, 46], 136);
                step(f, Op::Copy(ValueType::Vec3), &[74, 47], 137);
                step(f, Op::GetTransform, &[4, 0, 13, 5], 138);
                step(f, Op::BreakTransform, &[5, 48, 13, 49], 139);
                step(f, Op::MakeVector, &[61, 61, 9, 50], 140);
                step(f, Op::AddV, &[48, 50, 51], 141);
                step(f, Op::AddV, &[51, 45, 52], 142);
                step(f, Op::MulQ, &[12, 13, 14], 143);
                step(f, Op::MakeTransform, &[52, 14, 72, 6], 144);
                step(f, Op::GetTransform, &[3, 0, 14, 7], 145);
                step(f, Op::BreakTransform, &[7, 53, 15, 54], 146);
                step(f, Op::MakeVector, &[61, 2, 61, 55], 147);
                step(f, Op::AddV, &[53, 55, 56], 148);
                step(f, Op::TwoBoneIK, &[2, 3, 4, 6, 46, 47, 56, 1, 63, 14, 64, 65, 13, 11, 56], 149);
                step(f, Op::GetTransform, &[4, 0, 13, 5], 150);
                step(f, Op::BreakTransform, &[5, 48, 13, 49], 151);
                step(f, Op::MakeVector, &[61, 61, 9, 50], 152);
                step(f, Op::AddV, &[48, 50, 51], 153);
                step(f, Op::AddV, &[51, 45, 52], 154);
                step(f, Op::MulQ, &[12, 13, 14], 155);
                step(f, Op::MakeTransform, &[52, 14, 72, 6], 156);
                step(f, Op::DrawTransform, &[6, 66, 59], 157);
                step(f, Op::Copy(ValueType::Bone), &[15, 5], 158);
                step(f, Op::Copy(ValueType::Bone), &[16, 6], 159);
                step(f, Op::Copy(ValueType::Bone), &[17, 7], 160);
                step(f, Op::Copy(ValueType::Vec3), &[2, 57], 161);
                step(f, Op::Copy(ValueType::Quat), &[1, 16], 162);
                step(f, Op::Copy(ValueType::Vec3), &[71, 58], 163);
                step(f, Op::Copy(ValueType::Vec3), &[75, 59], 164);
                step(f, Op::GetTransform, &[7, 0, 13, 8], 165);
                step(f, Op::BreakTransform, &[8, 60, 17, 61], 166);
                step(f, Op::MakeVector, &[61, 61, 9, 62], 167);
                step(f, Op::AddV, &[60, 62, 63], 168);
                step(f, Op::AddV, &[63, 57, 64], 169);
                step(f, Op::MulQ, &[16, 17, 18], 170);
                step(f, Op::MakeTransform, &[64, 18, 72, 9], 171);
                step(f, Op::GetTransform, &[6, 0, 14, 10], 172);
                step(f, Op::BreakTransform, &[10, 65, 19, 66], 173);
                step(f, Op::MakeVector, &[61, 2, 61, 67], 174);
                step(f, Op::AddV, &[65, 67, 68], 175);
                step(f, Op::TwoBoneIK, &[5, 6, 7, 9, 58, 59, 68, 1, 63, 14, 64, 65, 13, 12, 57], 176);
                step(f, Op::GetTransform, &[7, 0, 13, 8], 177);
                step(f, Op::BreakTransform, &[8, 60, 17, 61], 178);
                step(f, Op::MakeVector, &[61, 61, 9, 62], 179);
                step(f, Op::AddV, &[60, 62, 63], 180);
                step(f, Op::AddV, &[63, 57, 64], 181);
                step(f, Op::MulQ, &[16, 17, 18], 182);
                step(f, Op::MakeTransform, &[64, 18, 72, 9], 183);
                step(f, Op::DrawTransform, &[9, 66, 59], 184);
                step(f, Op::End, &[], 185)
            }
            _ => return,
        } };
    }
}
