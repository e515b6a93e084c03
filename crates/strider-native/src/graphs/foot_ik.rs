//! The forward event of `graphs/foot_ik.ron`, compiled ahead of time: the native baseline that
//! `strider bench` measures the interpreter against (see docs/performance.md).
//!
//! Generated from the graph; do not edit. Regenerate after changing the graph or the
//! compiler with:
//!
//!     cargo run --release -- native graphs/foot_ik.ron --out crates/strider-native/src/graphs/foot_ik.rs

use strider_nodes::{Op, ValueType};
use strider_vm::native::{Frame, NativeProgram, step};

/// The forward event of `foot_ik`, compiled ahead of time.
pub static NATIVE: NativeProgram = NativeProgram {
    name: "foot_ik",
    fingerprint: 0xa02e1b77138bb6ca,
    forward,
};

fn forward(f: &mut Frame<'_>) {
    let mut pc: usize = 1;
    loop {
        pc = match pc {
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
                step(f, Op::GetTransform, &[0, 0, 13, 3], 34);
                step(f, Op::BreakTransform, &[3, 22, 7, 23], 35);
                step(f, Op::BreakVector, &[22, 40, 41, 42], 36);
                step(f, Op::MakeVector, &[40, 41, 0, 24], 37);
                step(f, Op::MulF, &[0, 58, 43], 38);
                step(f, Op::MakeVector, &[40, 41, 43, 25], 39);
                step(f, Op::LineTrace, &[24, 25, 9, 26, 27, 44], 40);
                step(f, Op::RotationFromNormal, &[27, 46, 47, 8], 41);
                step(f, Op::Copy(ValueType::Quat), &[8, 6], 42);
                step(f, Op::Jump, &[43], 43)
            }
            43 => {
                step(f, Op::Copy(ValueType::Bone), &[9, 1], 44);
                step(f, Op::Copy(ValueType::Vec3), &[69, 33], 45);
                step(f, Op::Copy(ValueType::Quat), &[20, 9], 46);
                step(f, Op::GetTransform, &[1, 0, 13, 4], 47);
                step(f, Op::BreakTransform, &[4, 34, 10, 35], 48);
                step(f, Op::BreakVector, &[34, 48, 49, 50], 49);
                step(f, Op::MakeVector, &[48, 49, 0, 36], 50);
                step(f, Op::MulF, &[0, 58, 51], 51);
                step(f, Op::MakeVector, &[48, 49, 51, 37], 52);
                step(f, Op::DrawLine, &[36, 37, 59, 70], 53);
                step(f, Op::GetTransform, &[1, 0, 13, 4], 54);
                step(f, Op::BreakTransform, &[4, 34, 10, 35], 55);
                step(f, Op::BreakVector, &[34, 48, 49, 50], 56);
                step(f, Op::MakeVector, &[48, 49, 0, 36], 57);
                step(f, Op::MulF, &[0, 58, 51], 58);
                step(f, Op::MakeVector, &[48, 49, 51, 37], 59);
                step(f, Op::LineTrace, &[36, 37, 10, 38, 39, 52], 60);
                step(f, Op::DrawPoint, &[38, 60, 71], 61);
                step(f, Op::GetTransform, &[1, 0, 13, 4], 62);
                step(f, Op::BreakTransform, &[4, 34, 10, 35], 63);
                step(f, Op::BreakVector, &[34, 48, 49, 50], 64);
                step(f, Op::MakeVector, &[48, 49, 0, 36], 65);
                step(f, Op::MulF, &[0, 58, 51], 66);
                step(f, Op::MakeVector, &[48, 49, 51, 37], 67);
                step(f, Op::LineTrace, &[36, 37, 10, 38, 39, 52], 68);
                step(f, Op::ScaleV, &[39, 1, 40], 69);
                step(f, Op::MakeVector, &[61, 61, 1, 41], 70);
                step(f, Op::SubV, &[40, 41, 42], 71);
                step(f, Op::FootOffsetFromTrace, &[10, 52, 0, 53], 72);
                step(f, Op::MakeVector, &[61, 61, 53, 43], 73);
                step(f, Op::AddV, &[42, 43, 44], 74);
                step(f, Op::Copy(ValueType::Vec3), &[44, 33], 75);
                step(f, Op::GetTransform, &[1, 0, 13, 4], 76);
                step(f, Op::BreakTransform, &[4, 34, 10, 35], 77);
                step(f, Op::BreakVector, &[34, 48, 49, 50], 78);
                step(f, Op::MakeVector, &[48, 49, 0, 36], 79);
                step(f, Op::MulF, &[0, 58, 51], 80);
                step(f, Op::MakeVector, &[48, 49, 51, 37], 81);
                step(f, Op::LineTrace, &[36, 37, 10, 38, 39, 52], 82);
                step(f, Op::RotationFromNormal, &[39, 54, 55, 11], 83);
                step(f, Op::Copy(ValueType::Quat), &[11, 9], 84);
                step(f, Op::Jump, &[85], 85)
            }
            85 => {
                step(f, Op::BreakVector, &[21, 12, 13, 14], 86);
                step(f, Op::BreakVector, &[33, 15, 16, 17], 87);
                step(f, Op::MinF, &[14, 17, 11], 88);
                step(f, Op::Not, &[0, 2], 89);
                step(f, Op::WorldTransform, &[0], 90);
                step(f, Op::BreakTransform, &[0, 3, 2, 4], 91);
                step(f, Op::DistanceV, &[3, 0, 10], 92);
                step(f, Op::GreaterF, &[10, 8, 1], 93);
                step(f, Op::Or, &[2, 1, 3], 94);
                step(f, Op::LessF, &[11, 9, 4], 95);
                step(f, Op::Select(ValueType::Float), &[4, 5, 6, 18], 96);
                step(f, Op::Select(ValueType::Float), &[3, 62, 18, 19], 97);
                step(f, Op::FloatLerp, &[9, 11, 19, 20], 98);
                step(f, Op::Copy(ValueType::Float), &[20, 9], 99);
                step(f, Op::BreakVector, &[21, 12, 13, 14], 100);
                step(f, Op::BreakVector, &[33, 15, 16, 17], 101);
                step(f, Op::MinF, &[14, 17, 11], 102);
                step(f, Op::Not, &[0, 2], 103);
                step(f, Op::WorldTransform, &[0], 104);
                step(f, Op::BreakTransform, &[0, 3, 2, 4], 105);
                step(f, Op::DistanceV, &[3, 0, 10], 106);
                step(f, Op::GreaterF, &[10, 8, 1], 107);
                step(f, Op::Or, &[2, 1, 3], 108);
                step(f, Op::Copy(ValueType::Vec3), &[1, 5], 109);
                step(f, Op::Copy(ValueType::Vec3), &[21, 6], 110);
                step(f, Op::Copy(ValueType::Float), &[11, 21], 111);
                step(f, Op::Copy(ValueType::Bool), &[3, 5], 112);
                step(f, Op::Copy(ValueType::Vec3), &[69, 7], 113);
                step(f, Op::MakeVector, &[61, 61, 21, 8], 114);
                step(f, Op::SubV, &[6, 8, 9], 115);
                step(f, Op::BreakVector, &[9, 25, 26, 27], 116);
                step(f, Op::BreakVector, &[5, 22, 23, 24], 117);
                step(f, Op::LessF, &[27, 24, 6], 118);
                step(f, Op::Select(ValueType::Float), &[6, 3, 4, 28], 119);
                step(f, Op::Select(ValueType::Float), &[5, 62, 28, 29], 120);
                step(f, Op::VectorLerp, &[5, 9, 29, 61, 10], 121);
                step(f, Op::Copy(ValueType::Vec3), &[10, 7], 122);
                step(f, Op::Jump, &[123], 123)
            }
            123 => {
                step(f, Op::Copy(ValueType::Vec3), &[7, 1], 124);
                step(f, Op::BreakVector, &[21, 12, 13, 14], 125);
                step(f, Op::BreakVector, &[33, 15, 16, 17], 126);
                step(f, Op::MinF, &[14, 17, 11], 127);
                step(f, Op::Not, &[0, 2], 128);
                step(f, Op::WorldTransform, &[0], 129);
                step(f, Op::BreakTransform, &[0, 3, 2, 4], 130);
                step(f, Op::DistanceV, &[3, 0, 10], 131);
                step(f, Op::GreaterF, &[10, 8, 1], 132);
                step(f, Op::Or, &[2, 1, 3], 133);
                step(f, Op::Copy(ValueType::Vec3), &[2, 11], 134);
                step(f, Op::Copy(ValueType::Vec3), &[33, 12], 135);
                step(f, Op::Copy(ValueType::Float), &[11, 30], 136);
                step(f, Op::Copy(ValueType::Bool), &[3, 7], 137);
                step(f, Op::Copy(ValueType::Vec3), &[69, 13], 138);
                step(f, Op::MakeVector, &[61, 61, 30, 14], 139);
                step(f, Op::SubV, &[12, 14, 15], 140);
                step(f, Op::BreakVector, &[15, 34, 35, 36], 141);
                step(f, Op::BreakVector, &[11, 31, 32, 33], 142);
                step(f, Op::LessF, &[36, 33, 8], 143);
                step(f, Op::Select(ValueType::Float), &[8, 3, 4, 37], 144);
                step(f, Op::Select(ValueType::Float), &[7, 62, 37, 38], 145);
                step(f, Op::VectorLerp, &[11, 15, 38, 61, 16], 146);
                step(f, Op::Copy(ValueType::Vec3), &[16, 13], 147);
                step(f, Op::Jump, &[148], 148)
            }
            148 => {
                step(f, Op::Copy(ValueType::Vec3), &[13, 2], 149);
                step(f, Op::Not, &[0, 2], 150);
                step(f, Op::WorldTransform, &[0], 151);
                step(f, Op::BreakTransform, &[0, 3, 2, 4], 152);
                step(f, Op::DistanceV, &[3, 0, 10], 153);
                step(f, Op::GreaterF, &[10, 8, 1], 154);
                step(f, Op::Or, &[2, 1, 3], 155);
                step(f, Op::Select(ValueType::Float), &[3, 62, 7, 39], 156);
                step(f, Op::QuatLerp, &[0, 6, 39, 3], 157);
                step(f, Op::Copy(ValueType::Quat), &[3, 0], 158);
                step(f, Op::Not, &[0, 2], 159);
                step(f, Op::WorldTransform, &[0], 160);
                step(f, Op::BreakTransform, &[0, 3, 2, 4], 161);
                step(f, Op::DistanceV, &[3, 0, 10], 162);
                step(f, Op::GreaterF, &[10, 8, 1], 163);
                step(f, Op::Or, &[2, 1, 3], 164);
                step(f, Op::Select(ValueType::Float), &[3, 62, 7, 39], 165);
                step(f, Op::QuatLerp, &[1, 9, 39, 4], 166);
                step(f, Op::Copy(ValueType::Quat), &[4, 1], 167);
                step(f, Op::Copy(ValueType::Bool), &[13, 0], 168);
                step(f, Op::WorldTransform, &[0], 169);
                step(f, Op::BreakTransform, &[0, 3, 2, 4], 170);
                step(f, Op::Copy(ValueType::Vec3), &[3, 0], 171);
                step(f, Op::GetTransform, &[10, 0, 13, 1], 172);
                step(f, Op::BreakTransform, &[1, 17, 5, 18], 173);
                step(f, Op::MakeVector, &[61, 61, 9, 19], 174);
                step(f, Op::AddV, &[17, 19, 20], 175);
                step(f, Op::MakeTransform, &[20, 5, 72, 2], 176);
                step(f, Op::SetTransform, &[11, 2, 0, 13, 63], 177);
                step(f, Op::Copy(ValueType::Bone), &[12, 2], 178);
                step(f, Op::Copy(ValueType::Bone), &[13, 3], 179);
                step(f, Op::Copy(ValueType::Bone), &[14, 4], 180);
                step(f, Op::Copy(ValueType::Vec3), &[1, 45], 181);
                step(f, Op::Copy(ValueType::Quat), &[0, 12], 182);
                step(f, Op::Copy(ValueType::Vec3), &[73, 46], 183);
                step(f, Op::Copy(ValueType::Vec3), &[74, 47], 184);
                step(f, Op::GetTransform, &[4, 0, 13, 5], 185);
                step(f, Op::BreakTransform, &[5, 48, 13, 49], 186);
                step(f, Op::MakeVector, &[61, 61, 9, 50], 187);
                step(f, Op::AddV, &[48, 50, 51], 188);
                step(f, Op::AddV, &[51, 45, 52], 189);
                step(f, Op::MulQ, &[12, 13, 14], 190);
                step(f, Op::MakeTransform, &[52, 14, 72, 6], 191);
                step(f, Op::GetTransform, &[3, 0, 14, 7], 192);
                step(f, Op::BreakTransform, &[7, 53, 15, 54], 193);
                step(f, Op::MakeVector, &[61, 2, 61, 55], 194);
                step(f, Op::AddV, &[53, 55, 56], 195);
                step(f, Op::TwoBoneIK, &[2, 3, 4, 6, 46, 47, 56, 1, 63, 14, 64, 65, 13, 11, 56], 196);
                step(f, Op::GetTransform, &[4, 0, 13, 5], 197);
                step(f, Op::BreakTransform, &[5, 48, 13, 49], 198);
                step(f, Op::MakeVector, &[61, 61, 9, 50], 199);
                step(f, Op::AddV, &[48, 50, 51], 200);
                step(f, Op::AddV, &[51, 45, 52], 201);
                step(f, Op::MulQ, &[12, 13, 14], 202);
                step(f, Op::MakeTransform, &[52, 14, 72, 6], 203);
                step(f, Op::DrawTransform, &[6, 66, 59], 204);
                step(f, Op::Copy(ValueType::Bone), &[15, 5], 205);
                step(f, Op::Copy(ValueType::Bone), &[16, 6], 206);
                step(f, Op::Copy(ValueType::Bone), &[17, 7], 207);
                step(f, Op::Copy(ValueType::Vec3), &[2, 57], 208);
                step(f, Op::Copy(ValueType::Quat), &[1, 16], 209);
                step(f, Op::Copy(ValueType::Vec3), &[71, 58], 210);
                step(f, Op::Copy(ValueType::Vec3), &[75, 59], 211);
                step(f, Op::GetTransform, &[7, 0, 13, 8], 212);
                step(f, Op::BreakTransform, &[8, 60, 17, 61], 213);
                step(f, Op::MakeVector, &[61, 61, 9, 62], 214);
                step(f, Op::AddV, &[60, 62, 63], 215);
                step(f, Op::AddV, &[63, 57, 64], 216);
                step(f, Op::MulQ, &[16, 17, 18], 217);
                step(f, Op::MakeTransform, &[64, 18, 72, 9], 218);
                step(f, Op::GetTransform, &[6, 0, 14, 10], 219);
                step(f, Op::BreakTransform, &[10, 65, 19, 66], 220);
                step(f, Op::MakeVector, &[61, 2, 61, 67], 221);
                step(f, Op::AddV, &[65, 67, 68], 222);
                step(f, Op::TwoBoneIK, &[5, 6, 7, 9, 58, 59, 68, 1, 63, 14, 64, 65, 13, 12, 57], 223);
                step(f, Op::GetTransform, &[7, 0, 13, 8], 224);
                step(f, Op::BreakTransform, &[8, 60, 17, 61], 225);
                step(f, Op::MakeVector, &[61, 61, 9, 62], 226);
                step(f, Op::AddV, &[60, 62, 63], 227);
                step(f, Op::AddV, &[63, 57, 64], 228);
                step(f, Op::MulQ, &[16, 17, 18], 229);
                step(f, Op::MakeTransform, &[64, 18, 72, 9], 230);
                step(f, Op::DrawTransform, &[9, 66, 59], 231);
                step(f, Op::End, &[], 232)
            }
            _ => return,
        };
    }
}
