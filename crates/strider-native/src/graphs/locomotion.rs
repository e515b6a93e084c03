//! The forward event of `graphs/locomotion.ron`, compiled ahead of time: the native baseline that
//! `strider bench` measures the interpreter against (see docs/performance.md).
//!
//! Generated from the graph; do not edit. Regenerate after changing the graph or the
//! compiler with:
//!
//! ```text
//! cargo run --release -- native graphs/locomotion.ron --out crates/strider-native/src/graphs/locomotion.rs
//! ```

use strider_nodes::{Elem, Op, ValueType};
use strider_vm::native::{Frame, NativeProgram, step};

/// The forward event of `locomotion`, compiled ahead of time.
pub static NATIVE: NativeProgram = NativeProgram {
    name: "locomotion",
    fingerprint: 0xdb501c22fab8a049,
    forward,
};

fn forward(f: &mut Frame<'_>) {
    let mut pc: usize = 92;
    loop {
        // SAFETY: each `step` is an instruction of the program this code was generated
        // from, with its own operands; `NATIVE` runs only on that program (fingerprint).
        pc = unsafe { match pc {
            92 => {
                step(f, Op::Not, &[0, 1, 1, 1], 93);
                step(f, Op::WorldTransform, &[5], 94);
                step(f, Op::BreakTransform, &[5, 8, 1, 11], 95);
                step(f, Op::Select(ValueType::Transform), &[0, 0, 5, 3], 96);
                step(f, Op::BreakTransform, &[3, 9, 1, 6], 97);
                step(f, Op::SubV, &[8, 9, 10], 98);
                step(f, Op::LengthV, &[10, 33], 99);
                step(f, Op::GreaterF, &[33, 85, 2, 2, 2], 100);
                step(f, Op::MakeRelative, &[3, 5, 4], 101);
                step(f, Op::Select(ValueType::Transform), &[2, 19, 4, 2, 2, 2], 102);
                step(f, Op::InverseT, &[3, 4], 103);
                step(f, Op::MulT, &[5, 4, 1, 1, 1], 104);
                step(f, Op::TransformVector, &[2, 0, 7], 105);
                step(f, Op::InverseT, &[5, 3], 106);
                step(f, Op::DeltaTime, &[34], 107);
                step(f, Op::DivFScaleV, &[201, 34, 32, 10, 32, 11], 108);
                step(f, Op::TransformVector, &[3, 11, 6], 109);
                step(f, Op::BreakVector, &[6, 33, 35, 36], 110);
                step(f, Op::BreakVector, &[10, 36, 37, 38], 111);
                step(f, Op::AddF, &[2, 38, 36], 112);
                step(f, Op::Select(ValueType::Float), &[2, 199, 36, 37], 113);
                step(f, Op::MakeVector, &[33, 35, 199, 8], 114);
                step(f, Op::LengthV, &[8, 38], 115);
                step(f, Op::MulFMulF, &[38, 186, 36, 36, 34, 38], 116);
                step(f, Op::NegF, &[38, 34], 117);
                step(f, Op::ClampF, &[37, 34, 38, 36], 118);
                step(f, Op::MulF, &[36, 32, 34], 119);
                step(f, Op::MakeVector, &[33, 35, 34, 9], 120);
                step(f, Op::Select(ValueType::Vec3), &[2, 7, 9, 11], 121);
                step(f, Op::VectorLerp, &[7, 11, 86, 199, 0, 0, 0], 122);
                step(f, Op::TransformVector, &[2, 1, 6], 123);
                step(f, Op::TransformVector, &[2, 0, 7], 124);
                step(f, Op::Select(ValueType::Vec3), &[2, 7, 9, 11], 125);
                step(f, Op::VectorLerp, &[6, 11, 87, 199, 1, 1, 1], 126);
                step(f, Op::LengthV, &[11, 0, 0, 0], 127);
                step(f, Op::SubF, &[37, 36, 38], 128);
                step(f, Op::NegF, &[187, 32], 129);
                step(f, Op::ClampF, &[38, 32, 187, 3], 130);
                step(f, Op::SubF, &[38, 3, 1, 1, 1, 3, 3], 131);
                step(f, Op::JumpIfFalse, &[2, 144], 132)
            }
            132 => {
                step(f, Op::Copy(ValueType::Int), &[9, 1], 133);
                133
            }
            133 => {
                step(f, Op::ForEachNext(Elem::Bone), &[0, 1, 13, 3, 2, 143], 134)
            }
            134 => {
                step(f, Op::ArrayAt(Elem::Transform), &[8, 3, 4], 135);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 3, 4], 136);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 3, 4], 137);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 3, 4], 138);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 3, 4], 139);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 3, 4], 140);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 3, 4], 141);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 3, 4], 142);
                step(f, Op::Jump, &[133], 143)
            }
            143 => {
                step(f, Op::Copy(ValueType::Float), &[199, 22], 144);
                144
            }
            144 => {
                step(f, Op::Copy(ValueType::Transform), &[5, 0], 145);
                step(f, Op::Copy(ValueType::Bool), &[19, 0], 146);
                step(f, Op::JumpIfFalse, &[18, 151], 147)
            }
            147 => {
                step(f, Op::GetTransformBreakTransform, &[33, 9, 19, 3, 3, 10, 1, 8], 148);
                step(f, Op::ScaleV, &[0, 202, 7], 149);
                step(f, Op::AddV, &[10, 7, 9], 150);
                step(f, Op::DrawArrow, &[10, 9, 200, 52], 151);
                151
            }
            151 => {
                step(f, Op::Copy(ValueType::Float), &[199, 33], 152);
                step(f, Op::Copy(ValueType::Float), &[201, 34], 153);
                step(f, Op::Copy(ValueType::Bool), &[20, 8], 154);
                step(f, Op::Copy(ValueType::Int), &[9, 2], 155);
                step(f, Op::MakeVector, &[199, 199, 105, 6], 156);
                156
            }
            156 => {
                step(f, Op::ForEachNext(Elem::Transform), &[8, 2, 4, 3, 1, 165], 157)
            }
            157 => {
                step(f, Op::BreakTransform, &[4, 11, 1, 8], 158);
                step(f, Op::TransformPoint, &[2, 11, 7], 159);
                step(f, Op::LerpV, &[7, 11, 201, 9], 160);
                step(f, Op::AddVSubV, &[9, 6, 10, 9, 6, 8], 161);
                step(f, Op::LineTrace, &[10, 8, 9, 7, 11, 35], 162);
                step(f, Op::JumpIfFalse, &[9, 164], 163)
            }
            163 => {
                step(f, Op::Copy(ValueType::Bool), &[19, 8], 164);
                164
            }
            164 => {
                step(f, Op::Jump, &[156, 8, 8], 165)
            }
            165 => {
                step(f, Op::Or, &[8, 7, 9], 166);
                step(f, Op::NotEquals(Elem::Bool), &[9, 5, 10], 167);
                step(f, Op::JumpIfFalse, &[10, 191], 168)
            }
            168 => {
                step(f, Op::NotEquals(Elem::Bool), &[8, 6, 11], 169);
                step(f, Op::JumpIfFalse, &[11, 191, 0, 0], 170)
            }
            170 => {
                step(f, Op::Copy(ValueType::Int), &[9, 1], 171);
                171
            }
            171 => {
                step(f, Op::ForNext, &[1, 0, 3, 191], 172)
            }
            172 => {
                step(f, Op::AddFMulF, &[33, 34, 36, 36, 200, 37], 173);
                step(f, Op::Copy(ValueType::Bool), &[20, 12], 174);
                step(f, Op::Copy(ValueType::Int), &[9, 2], 175);
                step(f, Op::MakeVector, &[199, 199, 105, 9], 176);
                176
            }
            176 => {
                step(f, Op::ForEachNext(Elem::Transform), &[8, 2, 5, 3, 4, 185], 177)
            }
            177 => {
                step(f, Op::BreakTransform, &[5, 7, 1, 8], 178);
                step(f, Op::TransformPoint, &[2, 7, 10], 179);
                step(f, Op::LerpV, &[10, 7, 37, 11], 180);
                step(f, Op::AddVSubV, &[11, 9, 6, 11, 9, 8], 181);
                step(f, Op::LineTrace, &[6, 8, 13, 7, 10, 32], 182);
                step(f, Op::JumpIfFalse, &[13, 184], 183)
            }
            183 => {
                step(f, Op::Copy(ValueType::Bool), &[19, 12], 184);
                184
            }
            184 => {
                step(f, Op::Jump, &[176, 12, 12], 185)
            }
            185 => {
                step(f, Op::Equals(Elem::Bool), &[12, 6, 13], 186);
                step(f, Op::JumpIfFalse, &[13, 189], 187)
            }
            187 => {
                step(f, Op::Copy(ValueType::Float), &[37, 33], 188);
                step(f, Op::Jump, &[190], 189)
            }
            189 => {
                step(f, Op::Copy(ValueType::Float), &[37, 34], 190);
                190
            }
            190 => {
                step(f, Op::Jump, &[171], 191)
            }
            191 => {
                step(f, Op::Select(ValueType::Float), &[5, 203, 201, 38], 192);
                step(f, Op::NotEquals(Elem::Bool), &[8, 6, 11], 193);
                step(f, Op::AddFMulF, &[33, 34, 36, 36, 200, 35], 194);
                step(f, Op::Select(ValueType::Float), &[11, 35, 200, 32], 195);
                step(f, Op::Select(ValueType::Float), &[10, 32, 199, 37], 196);
                step(f, Op::MulF, &[38, 37, 33], 197);
                step(f, Op::DeltaTime, &[34], 198);
                step(f, Op::DivF, &[34, 191, 36], 199);
                step(f, Op::MulFAddF, &[33, 36, 35, 26, 35, 37], 200);
                step(f, Op::ClampF, &[37, 199, 201, 38], 201);
                step(f, Op::Select(ValueType::Float), &[9, 203, 201, 34], 202);
                step(f, Op::SubF, &[201, 32, 33], 203);
                step(f, Op::Select(ValueType::Float), &[10, 33, 201, 35], 204);
                step(f, Op::MulFMulF, &[34, 35, 37, 37, 36, 32], 205);
                step(f, Op::AddF, &[38, 32, 33], 206);
                step(f, Op::ClampF, &[33, 199, 201, 26], 207);
                step(f, Op::SmoothStepF, &[26, 199, 201, 34], 208);
                step(f, Op::AddFMulF, &[27, 34, 35, 35, 200, 36], 209);
                step(f, Op::SubFMulF, &[201, 36, 37, 37, 37, 32], 210);
                step(f, Op::SubF, &[201, 32, 28, 28, 28], 211);
                step(f, Op::Copy(ValueType::Float), &[34, 27, 26, 26], 212);
                step(f, Op::GreaterF, &[27, 199, 12], 213);
                step(f, Op::TransformVector, &[2, 3, 11], 214);
                step(f, Op::Select(ValueType::Vec3), &[12, 11, 0, 3, 3, 3], 215);
                step(f, Op::LerpV, &[0, 3, 27, 6], 216);
                step(f, Op::Select(ValueType::Vec3), &[12, 6, 0, 2, 2, 2], 217);
                step(f, Op::Copy(ValueType::Bool), &[9, 5], 218);
                step(f, Op::Copy(ValueType::Bool), &[8, 6], 219);
                step(f, Op::Copy(ValueType::Bool), &[20, 7], 220);
                step(f, Op::SubFMulF, &[201, 28, 38, 1, 38, 33], 221);
                step(f, Op::SubFMulF, &[3, 2, 35, 35, 38, 36], 222);
                step(f, Op::AddFMulF, &[2, 36, 37, 37, 38, 32], 223);
                step(f, Op::SubFAddF, &[37, 32, 34, 33, 34, 39], 224);
                step(f, Op::AddF, &[4, 39, 40], 225);
                step(f, Op::Copy(ValueType::Float), &[7, 41], 226);
                step(f, Op::Copy(ValueType::Float), &[8, 42], 227);
                step(f, Op::Copy(ValueType::Float), &[4, 43], 228);
                step(f, Op::Copy(ValueType::Float), &[188, 44], 229);
                step(f, Op::Copy(ValueType::Float), &[31, 45], 230);
                step(f, Op::SubF, &[40, 43, 46], 231);
                step(f, Op::DeltaTime, &[47], 232);
                step(f, Op::DivF, &[46, 47, 48], 233);
                step(f, Op::MulFAddF, &[48, 45, 49, 40, 49, 50], 234);
                step(f, Op::MulF, &[48, 204, 51], 235);
                step(f, Op::DivF, &[205, 44, 52], 236);
                step(f, Op::DivFSubF, &[51, 52, 53, 50, 53, 54], 237);
                step(f, Op::AddF, &[43, 49, 55], 238);
                step(f, Op::SubFAddF, &[41, 55, 56, 56, 53, 57], 239);
                step(f, Op::SubFMulF, &[42, 48, 58, 52, 57, 59], 240);
                step(f, Op::AddFMulF, &[58, 59, 60, 60, 47, 61], 241);
                step(f, Op::AddF, &[57, 61, 62], 242);
                step(f, Op::FloatLerp, &[199, 201, 52, 63], 243);
                step(f, Op::SubFMulF, &[201, 63, 64, 62, 64, 65], 244);
                step(f, Op::AddF, &[54, 65, 66], 245);
                step(f, Op::Copy(ValueType::Float), &[66, 67], 246);
                step(f, Op::MulFSubF, &[52, 61, 68, 58, 68, 69], 247);
                step(f, Op::MulFAddF, &[69, 64, 70, 48, 70, 71], 248);
                step(f, Op::Copy(ValueType::Float), &[71, 72], 249);
                step(f, Op::SubFAddF, &[40, 67, 6, 6, 32, 5, 5, 5, 6, 6], 250);
                step(f, Op::Copy(ValueType::Float), &[32, 2], 251);
                step(f, Op::SubFMulF, &[3, 2, 35, 35, 38, 36], 252);
                step(f, Op::AddFMulF, &[2, 36, 37, 37, 38, 32], 253);
                step(f, Op::SubFAddF, &[37, 32, 34, 33, 34, 39], 254);
                step(f, Op::AddF, &[4, 39, 40], 255);
                step(f, Op::Copy(ValueType::Float), &[7, 41], 256);
                step(f, Op::Copy(ValueType::Float), &[8, 42], 257);
                step(f, Op::Copy(ValueType::Float), &[4, 43], 258);
                step(f, Op::Copy(ValueType::Float), &[188, 44], 259);
                step(f, Op::Copy(ValueType::Float), &[31, 45], 260);
                step(f, Op::SubF, &[40, 43, 46], 261);
                step(f, Op::DeltaTime, &[47], 262);
                step(f, Op::DivF, &[46, 47, 48], 263);
                step(f, Op::MulFAddF, &[48, 45, 49, 40, 49, 50], 264);
                step(f, Op::MulF, &[48, 204, 51], 265);
                step(f, Op::DivF, &[205, 44, 52], 266);
                step(f, Op::DivFSubF, &[51, 52, 53, 50, 53, 54], 267);
                step(f, Op::AddF, &[43, 49, 55], 268);
                step(f, Op::SubFAddF, &[41, 55, 56, 56, 53, 57], 269);
                step(f, Op::SubFMulF, &[42, 48, 58, 52, 57, 59], 270);
                step(f, Op::AddFMulF, &[58, 59, 60, 60, 47, 61], 271);
                step(f, Op::AddF, &[57, 61, 62], 272);
                step(f, Op::FloatLerp, &[199, 201, 52, 63], 273);
                step(f, Op::SubFMulF, &[201, 63, 64, 62, 64, 65], 274);
                step(f, Op::AddF, &[54, 65, 66], 275);
                step(f, Op::Copy(ValueType::Float), &[66, 67], 276);
                step(f, Op::MulFSubF, &[52, 61, 68, 58, 68, 69], 277);
                step(f, Op::MulFAddF, &[69, 64, 70, 48, 70, 71], 278);
                step(f, Op::Copy(ValueType::Float), &[71, 72], 279);
                step(f, Op::Copy(ValueType::Float), &[67, 7], 280);
                step(f, Op::Copy(ValueType::Float), &[7, 41], 281);
                step(f, Op::Copy(ValueType::Float), &[8, 42], 282);
                step(f, Op::Copy(ValueType::Float), &[4, 43], 283);
                step(f, Op::Copy(ValueType::Float), &[188, 44], 284);
                step(f, Op::Copy(ValueType::Float), &[31, 45], 285);
                step(f, Op::SubF, &[40, 43, 46], 286);
                step(f, Op::DeltaTime, &[47], 287);
                step(f, Op::DivF, &[46, 47, 48], 288);
                step(f, Op::MulFAddF, &[48, 45, 49, 40, 49, 50], 289);
                step(f, Op::MulF, &[48, 204, 51], 290);
                step(f, Op::DivF, &[205, 44, 52], 291);
                step(f, Op::DivFSubF, &[51, 52, 53, 50, 53, 54], 292);
                step(f, Op::AddF, &[43, 49, 55], 293);
                step(f, Op::SubFAddF, &[41, 55, 56, 56, 53, 57], 294);
                step(f, Op::SubFMulF, &[42, 48, 58, 52, 57, 59], 295);
                step(f, Op::AddFMulF, &[58, 59, 60, 60, 47, 61], 296);
                step(f, Op::AddF, &[57, 61, 62], 297);
                step(f, Op::FloatLerp, &[199, 201, 52, 63], 298);
                step(f, Op::SubFMulF, &[201, 63, 64, 62, 64, 65], 299);
                step(f, Op::AddF, &[54, 65, 66], 300);
                step(f, Op::Copy(ValueType::Float), &[66, 67], 301);
                step(f, Op::MulFSubF, &[52, 61, 68, 58, 68, 69], 302);
                step(f, Op::MulFAddF, &[69, 64, 70, 48, 70, 71], 303);
                step(f, Op::Copy(ValueType::Float), &[71, 72], 304);
                step(f, Op::Copy(ValueType::Float), &[72, 8], 305);
                step(f, Op::Copy(ValueType::Float), &[40, 4], 306);
                step(f, Op::LengthV, &[4, 35], 307);
                step(f, Op::GreaterF, &[35, 79, 13], 308);
                step(f, Op::LengthV, &[2, 36], 309);
                step(f, Op::GreaterF, &[36, 79, 11], 310);
                step(f, Op::And, &[13, 11, 10], 311);
                step(f, Op::Select(ValueType::Vec3), &[13, 4, 51, 7], 312);
                step(f, Op::MovementAngleOffset, &[7, 17, 199, 206, 206, 207, 90, 208, 38, 17, 17], 313);
                step(f, Op::SubFAddF, &[38, 17, 32, 32, 209, 37], 314);
                step(f, Op::DivF, &[37, 210, 33], 315);
                step(f, Op::FractF, &[33, 34], 316);
                step(f, Op::MulFSubF, &[34, 210, 39, 39, 209, 46, 46, 46], 317);
                step(f, Op::AbsF, &[46, 45], 318);
                step(f, Op::Select(ValueType::Vec3), &[11, 2, 51, 8], 319);
                step(f, Op::MovementAngleOffset, &[8, 17, 199, 206, 206, 207, 90, 208, 44, 17, 17], 320);
                step(f, Op::SubFAddF, &[44, 17, 51, 51, 209, 50], 321);
                step(f, Op::DivF, &[50, 210, 43], 322);
                step(f, Op::FractF, &[43, 49], 323);
                step(f, Op::MulFSubF, &[49, 210, 41, 41, 209, 55, 55, 55], 324);
                step(f, Op::AbsF, &[55, 53], 325);
                step(f, Op::MaxF, &[45, 53, 56], 326);
                step(f, Op::SubFAddF, &[44, 38, 42, 42, 209, 59], 327);
                step(f, Op::DivF, &[59, 210, 47], 328);
                step(f, Op::FractF, &[47, 60], 329);
                step(f, Op::MulFSubF, &[60, 210, 57, 57, 209, 63, 63, 63], 330);
                step(f, Op::AbsF, &[63, 62], 331);
                step(f, Op::MaxF, &[56, 62, 54], 332);
                step(f, Op::DeltaTime, &[65], 333);
                step(f, Op::DivF, &[31, 65, 66], 334);
                step(f, Op::TransformVector, &[2, 53, 10], 335);
                step(f, Op::BreakVector, &[10, 67, 52, 61], 336);
                step(f, Op::NegF, &[67, 58], 337);
                step(f, Op::Atan2F, &[58, 52, 68], 338);
                step(f, Op::MulF, &[66, 68, 64], 339);
                step(f, Op::QuatFromAxisAngle, &[54, 64, 1], 340);
                step(f, Op::TransformVector, &[2, 4, 9], 341);
                step(f, Op::FloatLerp, &[199, 201, 86, 69], 342);
                step(f, Op::GreaterF, &[69, 199, 12], 343);
                step(f, Op::AddFMulF, &[201, 66, 48, 86, 48, 70], 344);
                step(f, Op::FloatLerp, &[199, 201, 70, 71], 345);
                step(f, Op::DivF, &[71, 69, 72], 346);
                step(f, Op::Select(ValueType::Float), &[12, 72, 48, 40], 347);
                step(f, Op::LerpV, &[9, 2, 40, 11], 348);
                step(f, Op::RotateVector, &[1, 11, 6], 349);
                step(f, Op::LengthV, &[6, 35], 350);
                step(f, Op::GreaterF, &[35, 79, 9], 351);
                step(f, Op::Select(ValueType::Vec3), &[9, 6, 51, 7], 352);
                step(f, Op::MovementAngleOffset, &[7, 17, 199, 206, 206, 207, 90, 208, 32, 17, 17], 353);
                step(f, Op::SubFAddF, &[32, 17, 37, 37, 209, 33], 354);
                step(f, Op::DivF, &[33, 210, 34], 355);
                step(f, Op::FractF, &[34, 39], 356);
                step(f, Op::MulFSubF, &[39, 210, 46, 46, 209, 51, 51, 51], 357);
                step(f, Op::AbsF, &[51, 50], 358);
                step(f, Op::SubFAddF, &[32, 44, 43, 43, 209, 49], 359);
                step(f, Op::DivF, &[49, 210, 41], 360);
                step(f, Op::FractF, &[41, 55], 361);
                step(f, Op::MulFSubF, &[55, 210, 45, 45, 209, 53, 53, 53], 362);
                step(f, Op::AbsF, &[53, 38], 363);
                step(f, Op::MaxF, &[50, 38, 42], 364);
                step(f, Op::MaxF, &[54, 42, 59], 365);
                step(f, Op::LessF, &[59, 211, 8], 366);
                step(f, Op::And, &[10, 8, 14], 367);
                step(f, Op::SubV, &[2, 9, 10], 368);
                step(f, Op::DotV, &[9, 10, 47], 369);
                step(f, Op::NegF, &[47, 60], 370);
                step(f, Op::DotV, &[10, 10, 57], 371);
                step(f, Op::DivF, &[60, 57, 56], 372);
                step(f, Op::ClampF, &[56, 199, 40, 62], 373);
                step(f, Op::LerpV, &[9, 2, 62, 11], 374);
                step(f, Op::LengthV, &[11, 61], 375);
                step(f, Op::LessF, &[61, 79, 8], 376);
                step(f, Op::Not, &[8, 10], 377);
                step(f, Op::And, &[14, 10, 8], 378);
                step(f, Op::Not, &[13, 10], 379);
                step(f, Op::Not, &[11, 14], 380);
                step(f, Op::And, &[10, 14, 13], 381);
                step(f, Op::Not, &[9, 10], 382);
                step(f, Op::And, &[13, 10, 14], 383);
                step(f, Op::Or, &[8, 14, 9], 384);
                step(f, Op::JumpIfFalse, &[9, 402], 385)
            }
            385 => {
                step(f, Op::MulF, &[88, 65, 67], 386);
                step(f, Op::GreaterF, &[67, 199, 10], 387);
                step(f, Op::FloatLerp, &[199, 201, 88, 52], 388);
                step(f, Op::SubF, &[201, 52, 58], 389);
                step(f, Op::DivF, &[58, 52, 64], 390);
                step(f, Op::DivFSubF, &[201, 67, 70, 64, 70, 71], 391);
                step(f, Op::AddF, &[66, 71, 48], 392);
                step(f, Op::Select(ValueType::Float), &[10, 48, 199, 72], 393);
                step(f, Op::MulFAddF, &[63, 72, 35, 44, 35, 37], 394);
                step(f, Op::SinF, &[37, 33], 395);
                step(f, Op::NegF, &[33, 34], 396);
                step(f, Op::CosF, &[37, 39], 397);
                step(f, Op::MakeVector, &[34, 39, 199, 6], 398);
                step(f, Op::Select(ValueType::Vec3), &[11, 6, 51, 7], 399);
                step(f, Op::MovementAngleOffset, &[7, 17, 199, 88, 89, 207, 209, 208, 46], 400);
                step(f, Op::Copy(ValueType::Float), &[46, 17], 401);
                step(f, Op::Jump, &[450], 402)
            }
            402 => {
                step(f, Op::DivF, &[65, 92, 51], 403);
                step(f, Op::AddF, &[51, 200, 32], 404);
                step(f, Op::FloorF, &[32, 43], 405);
                step(f, Op::MaxF, &[43, 201, 49], 406);
                step(f, Op::ToInt, &[49, 3, 3, 3], 407);
                step(f, Op::Copy(ValueType::Int), &[9, 4], 408);
                step(f, Op::MulFSubF, &[92, 200, 41, 31, 41, 55], 409);
                step(f, Op::DivF, &[55, 65, 45], 410);
                step(f, Op::DivF, &[88, 49, 53], 411);
                step(f, Op::DivFSubF, &[89, 49, 38, 207, 91, 50], 412);
                step(f, Op::GreaterF, &[91, 199, 13], 413);
                413
            }
            413 => {
                step(f, Op::ForNext, &[4, 3, 2, 450], 414)
            }
            414 => {
                step(f, Op::ToFloat, &[2, 42], 415);
                step(f, Op::AddF, &[42, 201, 54], 416);
                step(f, Op::DivF, &[54, 49, 59], 417);
                step(f, Op::AddF, &[59, 45, 47], 418);
                step(f, Op::SubFMulF, &[47, 201, 57, 57, 68, 60], 419);
                step(f, Op::QuatFromAxisAngle, &[54, 60, 1], 420);
                step(f, Op::MulF, &[86, 47, 40], 421);
                step(f, Op::FloatLerp, &[199, 201, 40, 56], 422);
                step(f, Op::DivF, &[56, 69, 62], 423);
                step(f, Op::Select(ValueType::Float), &[12, 62, 47, 61], 424);
                step(f, Op::LerpV, &[9, 2, 61, 10], 425);
                step(f, Op::RotateVector, &[1, 10, 11], 426);
                step(f, Op::LengthV, &[11, 52], 427);
                step(f, Op::GreaterF, &[52, 79, 8], 428);
                step(f, Op::Select(ValueType::Vec3), &[8, 11, 51, 6], 429);
                step(f, Op::MulFMulF, &[65, 47, 58, 11, 58, 67], 430);
                step(f, Op::AddF, &[15, 67, 64], 431);
                step(f, Op::FractF, &[64, 70], 432);
                step(f, Op::MulF, &[70, 204, 66], 433);
                step(f, Op::FractF, &[66, 71], 434);
                step(f, Op::LessF, &[71, 208, 14], 435);
                step(f, Op::MovementAngleOffset, &[6, 17, 199, 206, 206, 207, 90, 208, 48, 17, 17], 436);
                step(f, Op::SubFAddF, &[48, 17, 63, 63, 209, 72], 437);
                step(f, Op::DivF, &[72, 210, 35], 438);
                step(f, Op::FractF, &[35, 44], 439);
                step(f, Op::MulFSubF, &[44, 210, 33, 33, 209, 37, 37, 37], 440);
                step(f, Op::AbsF, &[37, 34], 441);
                step(f, Op::SmoothStepF, &[34, 50, 207, 39], 442);
                step(f, Op::GreaterF, &[34, 207, 9], 443);
                step(f, Op::Select(ValueType::Float), &[9, 201, 199, 46], 444);
                step(f, Op::Select(ValueType::Float), &[13, 39, 46, 51], 445);
                step(f, Op::Select(ValueType::Float), &[14, 199, 51, 32], 446);
                step(f, Op::LerpF, &[53, 38, 32, 43], 447);
                step(f, Op::MovementAngleOffset, &[6, 17, 70, 43, 43, 207, 90, 208, 41], 448);
                step(f, Op::Copy(ValueType::Float), &[41, 17], 449);
                step(f, Op::Jump, &[413], 450)
            }
            450 => {
                step(f, Op::QuatFromAxisAngle, &[54, 17, 0, 0, 0], 451);
                step(f, Op::SinF, &[17, 55], 452);
                step(f, Op::AbsF, &[55, 42], 453);
                step(f, Op::RemapF, &[42, 93, 94, 199, 201, 19, 54], 454);
                step(f, Op::BreakVector, &[8, 59, 57, 60], 455);
                step(f, Op::AbsF, &[59, 40], 456);
                step(f, Op::DivF, &[40, 36, 56], 457);
                step(f, Op::RemapF, &[56, 93, 94, 199, 201, 19, 62], 458);
                step(f, Op::TransformVector, &[2, 53, 7], 459);
                step(f, Op::DistanceV, &[7, 53, 61], 460);
                step(f, Op::DivF, &[61, 65, 52], 461);
                step(f, Op::RemapF, &[52, 98, 99, 201, 199, 19, 47], 462);
                step(f, Op::MulF, &[62, 47, 58], 463);
                step(f, Op::MaxF, &[54, 58, 18, 18, 18], 464);
                step(f, Op::Copy(ValueType::Vec3), &[2, 4], 465);
                step(f, Op::TransformVector, &[2, 5, 10], 466);
                step(f, Op::BreakTransform, &[2, 11, 1, 6], 467);
                step(f, Op::DeltaTime, &[67], 468);
                step(f, Op::DivFScaleV, &[201, 67, 64, 11, 64, 9], 469);
                step(f, Op::NegV, &[9, 5], 470);
                step(f, Op::SubV, &[5, 10, 8], 471);
                step(f, Op::AddF, &[21, 67, 66], 472);
                step(f, Op::DivFScaleV, &[21, 66, 71, 8, 71, 7], 473);
                step(f, Op::AddV, &[10, 7, 6], 474);
                step(f, Op::DivFScaleV, &[67, 66, 48, 8, 48, 9], 475);
                step(f, Op::AddV, &[5, 9, 7], 476);
                step(f, Op::DotV, &[6, 7, 63], 477);
                step(f, Op::LessF, &[63, 199, 10], 478);
                step(f, Op::TransformVector, &[2, 53, 10], 479);
                step(f, Op::DistanceV, &[10, 53, 72], 480);
                step(f, Op::SubV, &[7, 6, 8], 481);
                step(f, Op::DotV, &[6, 8, 35], 482);
                step(f, Op::NegF, &[35, 44], 483);
                step(f, Op::DotV, &[8, 8, 33], 484);
                step(f, Op::DivF, &[44, 33, 37], 485);
                step(f, Op::ClampF, &[37, 199, 201, 34], 486);
                step(f, Op::SubFMulF, &[201, 34, 39, 67, 39, 46], 487);
                step(f, Op::DivF, &[72, 46, 51], 488);
                step(f, Op::RemapF, &[51, 98, 99, 199, 201, 19, 32], 489);
                step(f, Op::BreakVector, &[7, 43, 70, 41], 490);
                step(f, Op::NegF, &[43, 38], 491);
                step(f, Op::Atan2F, &[38, 70, 45], 492);
                step(f, Op::AbsF, &[45, 49], 493);
                step(f, Op::RemapF, &[49, 154, 155, 199, 201, 19, 50], 494);
                step(f, Op::MulF, &[32, 50, 53], 495);
                step(f, Op::DivF, &[72, 67, 68], 496);
                step(f, Op::RemapF, &[68, 98, 99, 199, 201, 19, 69], 497);
                step(f, Op::BreakVector, &[11, 55, 42, 57], 498);
                step(f, Op::NegF, &[42, 60], 499);
                step(f, Op::Atan2F, &[55, 60, 59], 500);
                step(f, Op::AbsF, &[59, 36], 501);
                step(f, Op::RemapF, &[36, 154, 155, 199, 201, 19, 40], 502);
                step(f, Op::MulF, &[69, 40, 56], 503);
                step(f, Op::Select(ValueType::Float), &[10, 53, 56, 61], 504);
                step(f, Op::FloatLerp, &[19, 199, 156, 65], 505);
                step(f, Op::MaxF, &[61, 65, 52], 506);
                step(f, Op::AbsF, &[20, 47], 507);
                step(f, Op::GreaterEqualF, &[47, 155, 11], 508);
                step(f, Op::LessF, &[36, 155, 8], 509);
                step(f, Op::And, &[11, 8, 9], 510);
                step(f, Op::SubF, &[47, 155, 62], 511);
                step(f, Op::SubF, &[47, 36, 54], 512);
                step(f, Op::DivFSubF, &[62, 54, 58, 201, 58, 64], 513);
                step(f, Op::MulF, &[156, 64, 71], 514);
                step(f, Op::FloatLerp, &[201, 199, 71, 66], 515);
                step(f, Op::MulF, &[69, 66, 48], 516);
                step(f, Op::Select(ValueType::Float), &[9, 48, 199, 63], 517);
                step(f, Op::MaxF, &[52, 63, 19, 19, 19], 518);
                step(f, Op::Select(ValueType::Float), &[10, 45, 59, 20, 20, 20, 5, 5], 519);
                step(f, Op::Copy(ValueType::Float), &[67, 21], 520);
                step(f, Op::Copy(ValueType::Bool), &[19, 14], 521);
                step(f, Op::Copy(ValueType::Int), &[9, 1], 522);
                522
            }
            522 => {
                step(f, Op::ForEachNext(Elem::Bool), &[0, 1, 12, 2, 3, 527], 523)
            }
            523 => {
                step(f, Op::Not, &[12, 13], 524);
                step(f, Op::JumpIfFalse, &[13, 526], 525)
            }
            525 => {
                step(f, Op::Copy(ValueType::Bool), &[20, 14], 526);
                526
            }
            526 => {
                step(f, Op::Jump, &[522, 14, 14], 527)
            }
            527 => {
                step(f, Op::Copy(ValueType::Bool), &[19, 8], 528);
                step(f, Op::Copy(ValueType::Int), &[9, 4], 529);
                529
            }
            529 => {
                step(f, Op::ForEachNext(Elem::Bone), &[0, 4, 15, 2, 3, 541], 530)
            }
            530 => {
                step(f, Op::ArrayAtBreakTransform, &[0, 2, 3, 3, 9, 1, 10], 531);
                step(f, Op::BreakVector, &[9, 35, 33, 44], 532);
                step(f, Op::MakeVector, &[35, 33, 199, 6], 533);
                step(f, Op::ArrayAtBreakTransform, &[8, 2, 4, 4, 8, 1, 7], 534);
                step(f, Op::BreakVector, &[8, 37, 34, 39], 535);
                step(f, Op::MakeVector, &[37, 34, 199, 11], 536);
                step(f, Op::DistanceV, &[6, 11, 46], 537);
                step(f, Op::GreaterF, &[46, 81, 11], 538);
                step(f, Op::JumpIfFalse, &[11, 540], 539)
            }
            539 => {
                step(f, Op::Copy(ValueType::Bool), &[20, 8], 540);
                540
            }
            540 => {
                step(f, Op::Jump, &[529, 8, 8], 541)
            }
            541 => {
                step(f, Op::And, &[14, 8, 9], 542);
                step(f, Op::LengthV, &[2, 51], 543);
                step(f, Op::GreaterF, &[51, 79, 3], 544);
                step(f, Op::GreaterF, &[0, 79, 10], 545);
                step(f, Op::Or, &[3, 10, 12], 546);
                step(f, Op::Not, &[12, 13], 547);
                step(f, Op::And, &[9, 13, 11], 548);
                step(f, Op::DeltaTime, &[41], 549);
                step(f, Op::MulFAddF, &[41, 84, 43, 15, 43, 38], 550);
                step(f, Op::GreaterF, &[15, 200, 8], 551);
                step(f, Op::AddF, &[83, 200, 70], 552);
                step(f, Op::Select(ValueType::Float), &[8, 70, 83, 49], 553);
                step(f, Op::MinF, &[38, 49, 32], 554);
                step(f, Op::NotEquals(Elem::Bool), &[13, 4, 10], 555);
                step(f, Op::Not, &[9, 12], 556);
                step(f, Op::And, &[10, 12, 8], 557);
                step(f, Op::SubF, &[16, 79, 50], 558);
                step(f, Op::SubF, &[16, 51, 72], 559);
                step(f, Op::DivF, &[50, 72, 68], 560);
                step(f, Op::ClampF, &[68, 199, 201, 57], 561);
                step(f, Op::MulF, &[11, 57, 42], 562);
                step(f, Op::RemapF, &[51, 79, 80, 199, 201, 19, 55], 563);
                step(f, Op::MaxF, &[55, 12, 60], 564);
                step(f, Op::Select(ValueType::Float), &[14, 201, 60, 40], 565);
                step(f, Op::Select(ValueType::Float), &[13, 82, 40, 53], 566);
                step(f, Op::Select(ValueType::Float), &[9, 55, 53, 56], 567);
                step(f, Op::SubFMulF, &[201, 27, 61, 56, 61, 65], 568);
                step(f, Op::LerpF, &[73, 96, 18, 36], 569);
                step(f, Op::RemapF, &[51, 76, 77, 74, 75, 19, 47], 570);
                step(f, Op::LerpF, &[47, 95, 18, 54], 571);
                step(f, Op::MaxF, &[51, 78, 62], 572);
                step(f, Op::DivF, &[54, 62, 9], 573);
                step(f, Op::AddF, &[36, 9, 10], 574);
                step(f, Op::DivFSubF, &[65, 10, 58, 201, 57, 64], 575);
                step(f, Op::MulFAddF, &[58, 64, 71, 42, 71, 66], 576);
                step(f, Op::MulFAddF, &[66, 204, 69, 11, 58, 48], 577);
                step(f, Op::Select(ValueType::Float), &[8, 69, 48, 52], 578);
                step(f, Op::DivF, &[204, 52, 63], 579);
                step(f, Op::GreaterF, &[52, 199, 10], 580);
                step(f, Op::CycleStep, &[15, 63, 199, 10, 45, 59], 581);
                step(f, Op::Select(ValueType::Float), &[11, 32, 45, 15, 15, 15], 582);
                step(f, Op::Copy(ValueType::Float), &[58, 11, 3, 3, 9, 9, 10, 10], 583);
                step(f, Op::Copy(ValueType::Int), &[9, 1], 584);
                step(f, Op::DivF, &[36, 10, 67], 585);
                step(f, Op::MulFMulF, &[14, 57, 44, 41, 200, 33], 586);
                step(f, Op::SubF, &[67, 13, 35], 587);
                step(f, Op::MaxF, &[35, 199, 39], 588);
                step(f, Op::DivFSubF, &[39, 67, 34, 201, 18, 37], 589);
                step(f, Op::SubFMulF, &[201, 19, 46, 37, 46, 43], 590);
                step(f, Op::DivFSubF, &[31, 41, 70, 200, 70, 38], 591);
                step(f, Op::MulFMulF, &[34, 43, 49, 49, 61, 50], 592);
                step(f, Op::MulFMulF, &[50, 184, 72, 72, 38, 68], 593);
                step(f, Op::SubF, &[201, 68, 47], 594);
                594
            }
            594 => {
                step(f, Op::ForEachNext(Elem::Bone), &[0, 1, 14, 3, 2, 630], 595)
            }
            595 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 3, 54], 596);
                step(f, Op::ToFloat, &[3, 62], 597);
                step(f, Op::MulFAddF, &[62, 200, 42, 15, 42, 71], 598);
                step(f, Op::FractF, &[71, 66], 599);
                step(f, Op::SubF, &[54, 66, 48], 600);
                step(f, Op::GreaterF, &[48, 200, 12], 601);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 69], 602);
                step(f, Op::Select(ValueType::Float), &[12, 199, 69, 52], 603);
                step(f, Op::ArraySetAt(Elem::Float), &[3, 3, 52], 604);
                step(f, Op::SubFAddF, &[201, 54, 59, 66, 59, 63], 605);
                step(f, Op::DivF, &[66, 63, 32], 606);
                step(f, Op::MaxF, &[55, 12, 60], 607);
                step(f, Op::Select(ValueType::Float), &[14, 201, 60, 40], 608);
                step(f, Op::Select(ValueType::Float), &[13, 82, 40, 53], 609);
                step(f, Op::Select(ValueType::Float), &[9, 55, 53, 56], 610);
                step(f, Op::MulF, &[56, 61, 65], 611);
                step(f, Op::DivF, &[65, 36, 45], 612);
                step(f, Op::MulFAddF, &[45, 64, 58, 44, 58, 57], 613);
                step(f, Op::MulFAddF, &[57, 204, 35, 14, 45, 39], 614);
                step(f, Op::Select(ValueType::Float), &[8, 35, 39, 37], 615);
                step(f, Op::MulFMulF, &[37, 33, 46, 32, 46, 41], 616);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 3, 10], 617);
                step(f, Op::MulF, &[46, 47, 70], 618);
                step(f, Op::Select(ValueType::Float), &[10, 46, 70, 49], 619);
                step(f, Op::MulFMulF, &[34, 69, 50, 50, 43, 38], 620);
                step(f, Op::MulFMulF, &[38, 61, 72, 72, 184, 68], 621);
                step(f, Op::Select(ValueType::Float), &[10, 199, 68, 62], 622);
                step(f, Op::SubFAddF, &[49, 62, 42, 69, 42, 71], 623);
                step(f, Op::Select(ValueType::Float), &[12, 41, 71, 48], 624);
                step(f, Op::MinF, &[48, 204, 52], 625);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 3, 52], 626);
                step(f, Op::JumpIfFalse, &[12, 628], 627)
            }
            627 => {
                step(f, Op::Copy(ValueType::Float), &[56, 12], 628);
                628
            }
            628 => {
                step(f, Op::ArraySetAt(Elem::Float), &[0, 3, 66], 629);
                step(f, Op::Jump, &[594], 630)
            }
            630 => {
                step(f, Op::Copy(ValueType::Float), &[67, 13], 631);
                step(f, Op::Copy(ValueType::Bool), &[13, 4], 632);
                step(f, Op::Copy(ValueType::Float), &[51, 16], 633);
                step(f, Op::MaxF, &[55, 12, 60], 634);
                step(f, Op::Select(ValueType::Float), &[14, 201, 60, 40], 635);
                step(f, Op::Select(ValueType::Float), &[13, 82, 40, 53], 636);
                step(f, Op::Select(ValueType::Float), &[9, 55, 53, 56], 637);
                step(f, Op::MulF, &[56, 61, 65], 638);
                step(f, Op::DivF, &[65, 36, 45], 639);
                step(f, Op::Copy(ValueType::Float), &[45, 14], 640);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 641);
                step(f, Op::Copy(ValueType::Int), &[9, 4], 642);
                642
            }
            642 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 4, 0, 2, 3, 1441], 643)
            }
            643 => {
                step(f, Op::Copy(ValueType::Bool), &[19, 11], 644);
                step(f, Op::Copy(ValueType::Bool), &[20, 10], 645);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 2, 12], 646);
                step(f, Op::ArrayAt(Elem::Float), &[2, 2, 54], 647);
                step(f, Op::GreaterEqualF, &[54, 201, 8], 648);
                step(f, Op::And, &[12, 8, 14], 649);
                step(f, Op::Or, &[1, 2, 13], 650);
                step(f, Op::GreaterF, &[27, 199, 9], 651);
                step(f, Op::Or, &[13, 9, 12], 652);
                step(f, Op::Not, &[12, 9], 653);
                step(f, Op::And, &[14, 9, 13], 654);
                step(f, Op::JumpIfFalse, &[13, 748], 655)
            }
            655 => {
                step(f, Op::ArrayAtBreakTransform, &[2, 2, 5, 5, 10, 1, 9], 656);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 2, 7], 657);
                step(f, Op::SubV, &[10, 7, 8], 658);
                step(f, Op::TransformPoint, &[2, 8, 6], 659);
                step(f, Op::GetTransformBreakTransform, &[34, 9, 19, 3, 3, 11, 2, 8], 660);
                step(f, Op::BreakVector, &[11, 59, 63, 58], 661);
                step(f, Op::SubFMulF, &[201, 18, 57, 17, 57, 35], 662);
                step(f, Op::QuatFromAxisAngle, &[54, 35, 3], 663);
                step(f, Op::GetTransformBreakTransform, &[0, 9, 19, 4, 4, 12, 4, 13], 664);
                step(f, Op::SubV, &[12, 11, 14], 665);
                step(f, Op::BreakVector, &[14, 39, 37, 32], 666);
                step(f, Op::MakeVector, &[39, 37, 199, 15], 667);
                step(f, Op::RotateVector, &[3, 15, 16], 668);
                step(f, Op::BreakVector, &[16, 46, 70, 50], 669);
                step(f, Op::MulF, &[97, 18, 38], 670);
                step(f, Op::Equals(Elem::Int), &[2, 9, 12], 671);
                step(f, Op::Select(ValueType::Float), &[12, 201, 203, 72], 672);
                step(f, Op::MulFAddF, &[38, 72, 68, 46, 68, 49], 673);
                step(f, Op::AddFAddF, &[59, 49, 62, 63, 70, 42], 674);
                step(f, Op::BreakVector, &[12, 69, 41, 71], 675);
                step(f, Op::SubF, &[71, 100, 48], 676);
                step(f, Op::MakeVector, &[62, 42, 48, 17], 677);
                step(f, Op::MulFScaleV, &[9, 200, 52, 2, 52, 18], 678);
                step(f, Op::AddV, &[17, 18, 19], 679);
                step(f, Op::DistanceV, &[6, 19, 66], 680);
                step(f, Op::TransformVector, &[2, 55, 6], 681);
                step(f, Op::DistanceV, &[6, 55, 33], 682);
                step(f, Op::MaxF, &[66, 33, 34], 683);
                step(f, Op::LessEqualF, &[34, 107, 9], 684);
                step(f, Op::LengthV, &[2, 43], 685);
                step(f, Op::LengthV, &[4, 44], 686);
                step(f, Op::MaxF, &[43, 44, 47], 687);
                step(f, Op::LessEqualF, &[47, 79, 14], 688);
                step(f, Op::And, &[9, 14, 13], 689);
                step(f, Op::ArrayAt(Elem::Bool), &[1, 2, 9], 690);
                step(f, Op::And, &[13, 9, 14], 691);
                step(f, Op::JumpIfFalse, &[14, 694], 692)
            }
            692 => {
                step(f, Op::Copy(ValueType::Bool), &[19, 10], 693);
                step(f, Op::Jump, &[720], 694)
            }
            694 => {
                step(f, Op::MakeVector, &[199, 199, 105, 6], 695);
                step(f, Op::AddVSubV, &[19, 6, 20, 19, 6, 21], 696);
                step(f, Op::SphereTrace, &[20, 21, 104, 13, 22, 23, 64], 697);
                step(f, Op::SubV, &[22, 19, 23], 698);
                step(f, Op::DistanceV, &[23, 7, 67], 699);
                step(f, Op::RotateVector, &[0, 53, 22], 700);
                step(f, Op::ScaleV, &[22, 109, 23], 701);
                step(f, Op::AddVAddV, &[20, 23, 24, 21, 23, 25], 702);
                step(f, Op::SphereTrace, &[24, 25, 104, 14, 26, 27, 51], 703);
                step(f, Op::SubV, &[26, 19, 28], 704);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 2, 29], 705);
                step(f, Op::DistanceV, &[28, 29, 60], 706);
                step(f, Op::MaxF, &[67, 60, 40], 707);
                step(f, Op::ScaleV, &[22, 106, 29], 708);
                step(f, Op::AddVAddV, &[24, 29, 30, 25, 29, 31], 709);
                step(f, Op::SphereTrace, &[30, 31, 104, 15, 32, 33, 53], 710);
                step(f, Op::SubV, &[32, 19, 34], 711);
                step(f, Op::ArrayAt(Elem::Vec3), &[2, 2, 35], 712);
                step(f, Op::DistanceV, &[34, 35, 55], 713);
                step(f, Op::MaxF, &[40, 55, 56], 714);
                step(f, Op::LessEqualF, &[56, 107, 16], 715);
                step(f, Op::And, &[13, 14, 17], 716);
                step(f, Op::And, &[17, 9, 13], 717);
                step(f, Op::And, &[16, 13, 17], 718);
                step(f, Op::JumpIfFalse, &[17, 720], 719)
            }
            719 => {
                step(f, Op::Copy(ValueType::Bool), &[19, 10], 720);
                720
            }
            720 => {
                step(f, Op::JumpIfFalse, &[10, 748], 721)
            }
            721 => {
                step(f, Op::ArrayAtBreakTransform, &[1, 2, 6, 6, 35, 5, 36], 722);
                step(f, Op::AddV, &[19, 7, 37, 29, 29, 31, 31], 723);
                step(f, Op::SubV, &[37, 10, 7], 724);
                step(f, Op::DeltaTime, &[61], 725);
                step(f, Op::DivFScaleV, &[31, 61, 36, 7, 36, 38], 726);
                step(f, Op::AddVAddV, &[37, 38, 39, 10, 38, 40], 727);
                step(f, Op::SubV, &[35, 40, 38], 728);
                step(f, Op::FloatLerp, &[199, 201, 29, 65], 729);
                step(f, Op::SubF, &[201, 65, 45], 730);
                step(f, Op::ScaleV, &[38, 45, 40], 731);
                step(f, Op::AddV, &[39, 40, 38], 732);
                step(f, Op::MulF, &[29, 61, 33], 733);
                step(f, Op::GreaterF, &[33, 199, 13], 734);
                step(f, Op::DivF, &[65, 33, 66], 735);
                step(f, Op::Select(ValueType::Float), &[13, 66, 201, 34], 736);
                step(f, Op::ScaleV, &[7, 34, 39], 737);
                step(f, Op::SubV, &[38, 39, 40, 40, 40], 738);
                step(f, Op::BreakVector, &[40, 43, 44, 47], 739);
                step(f, Op::ClampF, &[47, 110, 111, 64], 740);
                step(f, Op::MakeVector, &[43, 44, 64, 7], 741);
                step(f, Op::MakeTransform, &[7, 5, 50, 7], 742);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 2, 7], 743);
                step(f, Op::MakeTransform, &[37, 11, 50, 7], 744);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 2, 7], 745);
                step(f, Op::JumpIfFalse, &[9, 747], 746)
            }
            746 => {
                step(f, Op::Copy(ValueType::Bool), &[19, 7], 747);
                747
            }
            747 => {
                step(f, Op::Copy(ValueType::Bool), &[20, 11], 748);
                748
            }
            748 => {
                step(f, Op::JumpIfFalse, &[11, 917], 749)
            }
            749 => {
                step(f, Op::GetTransformBreakTransform, &[34, 9, 19, 3, 3, 11, 2, 8], 750);
                step(f, Op::BreakVector, &[11, 59, 63, 58], 751);
                step(f, Op::SubFMulF, &[201, 18, 57, 17, 57, 35], 752);
                step(f, Op::QuatFromAxisAngle, &[54, 35, 3], 753);
                step(f, Op::GetTransformBreakTransform, &[0, 9, 19, 4, 4, 12, 4, 13], 754);
                step(f, Op::SubV, &[12, 11, 14], 755);
                step(f, Op::BreakVector, &[14, 39, 37, 32], 756);
                step(f, Op::MakeVector, &[39, 37, 199, 15], 757);
                step(f, Op::RotateVector, &[3, 15, 16], 758);
                step(f, Op::BreakVector, &[16, 46, 70, 50], 759);
                step(f, Op::MulF, &[97, 18, 38], 760);
                step(f, Op::Equals(Elem::Int), &[2, 9, 12], 761);
                step(f, Op::Select(ValueType::Float), &[12, 201, 203, 72], 762);
                step(f, Op::MulFAddF, &[38, 72, 68, 46, 68, 49], 763);
                step(f, Op::AddFAddF, &[59, 49, 62, 63, 70, 42], 764);
                step(f, Op::BreakVector, &[12, 69, 41, 71], 765);
                step(f, Op::SubF, &[71, 100, 48], 766);
                step(f, Op::MakeVector, &[62, 42, 48, 17], 767);
                step(f, Op::SubF, &[201, 54, 60], 768);
                step(f, Op::MaxF, &[60, 199, 67], 769);
                step(f, Op::MulFMulF, &[13, 10, 40, 67, 40, 55], 770);
                step(f, Op::ScaleV, &[2, 55, 38], 771);
                step(f, Op::AddV, &[17, 38, 39], 772);
                step(f, Op::MulFScaleV, &[9, 200, 52, 2, 52, 18], 773);
                step(f, Op::AddV, &[39, 18, 40], 774);
                step(f, Op::RotateVector, &[0, 53, 22], 775);
                step(f, Op::Copy(ValueType::Float), &[206, 56], 776);
                step(f, Op::Copy(ValueType::Vec3), &[51, 7], 777);
                step(f, Op::Copy(ValueType::Vec3), &[54, 37], 778);
                step(f, Op::Copy(ValueType::Bool), &[20, 16], 779);
                step(f, Op::Copy(ValueType::Float), &[206, 36], 780);
                step(f, Op::Copy(ValueType::Vec3), &[51, 39], 781);
                step(f, Op::MulI, &[8, 8, 1, 1, 1], 782);
                step(f, Op::Copy(ValueType::Int), &[9, 3], 783);
                step(f, Op::SubI, &[8, 10, 5], 784);
                step(f, Op::DivI, &[5, 11, 6], 785);
                step(f, Op::MakeVector, &[199, 199, 105, 41], 786);
                step(f, Op::ScaleV, &[22, 109, 42], 787);
                787
            }
            787 => {
                step(f, Op::ForNext, &[3, 1, 5, 828], 788)
            }
            788 => {
                step(f, Op::ModI, &[5, 8, 7], 789);
                step(f, Op::ToFloat, &[7, 45], 790);
                step(f, Op::MulFMulF, &[45, 106, 61, 61, 72, 33], 791);
                step(f, Op::MakeVector, &[33, 199, 199, 43], 792);
                step(f, Op::DivI, &[5, 8, 7], 793);
                step(f, Op::SubI, &[7, 6, 5], 794);
                step(f, Op::ToFloat, &[5, 65], 795);
                step(f, Op::MulFScaleV, &[65, 106, 66, 22, 66, 44], 796);
                step(f, Op::AddVAddV, &[43, 44, 45, 40, 45, 43], 797);
                step(f, Op::AddVSubV, &[43, 41, 44, 43, 41, 46], 798);
                step(f, Op::SphereTrace, &[44, 46, 104, 17, 43, 47, 34], 799);
                step(f, Op::BreakVector, &[43, 47, 43, 44], 800);
                step(f, Op::AddVAddV, &[44, 42, 48, 46, 42, 44], 801);
                step(f, Op::SphereTrace, &[48, 44, 104, 10, 46, 49, 64], 802);
                step(f, Op::BreakVector, &[46, 45, 61, 33], 803);
                step(f, Op::SubF, &[44, 33, 65], 804);
                step(f, Op::AbsF, &[65, 66], 805);
                step(f, Op::Select(ValueType::Float), &[17, 199, 201, 34], 806);
                step(f, Op::AddF, &[66, 34, 43], 807);
                step(f, Op::LengthV, &[45, 47], 808);
                step(f, Op::RemapF, &[47, 199, 212, 199, 201, 19, 64], 809);
                step(f, Op::MinF, &[44, 33, 45], 810);
                step(f, Op::RemapF, &[45, 213, 212, 201, 200, 19, 61], 811);
                step(f, Op::AddFAddF, &[64, 61, 65, 43, 65, 34], 812);
                step(f, Op::LessF, &[34, 56, 13], 813);
                step(f, Op::And, &[17, 13, 9], 814);
                step(f, Op::JumpIfFalse, &[9, 822], 815)
            }
            815 => {
                step(f, Op::Copy(ValueType::Float), &[56, 36], 816);
                step(f, Op::Copy(ValueType::Vec3), &[7, 39], 817);
                step(f, Op::Copy(ValueType::Float), &[34, 56], 818);
                step(f, Op::Copy(ValueType::Vec3), &[43, 7], 819);
                step(f, Op::Copy(ValueType::Vec3), &[47, 37], 820);
                step(f, Op::Copy(ValueType::Bool), &[19, 16], 821);
                step(f, Op::Jump, &[827], 822)
            }
            822 => {
                step(f, Op::LessF, &[34, 36, 11], 823);
                step(f, Op::And, &[17, 11, 12], 824);
                step(f, Op::JumpIfFalse, &[12, 827], 825)
            }
            825 => {
                step(f, Op::Copy(ValueType::Float), &[34, 36], 826);
                step(f, Op::Copy(ValueType::Vec3), &[43, 39], 827);
                827
            }
            827 => {
                step(f, Op::Jump, &[787], 828)
            }
            828 => {
                step(f, Op::JumpIfFalse, &[18, 830], 829)
            }
            829 => {
                step(f, Op::DrawSphere, &[7, 104, 53], 830);
                830
            }
            830 => {
                step(f, Op::GreaterF, &[108, 199, 10], 831);
                step(f, Op::SubF, &[56, 36, 66], 832);
                step(f, Op::DivF, &[66, 108, 47], 833);
                step(f, Op::PowF, &[214, 47, 33], 834);
                step(f, Op::Select(ValueType::Float), &[10, 33, 199, 44], 835);
                step(f, Op::ScaleV, &[39, 44, 44], 836);
                step(f, Op::AddV, &[7, 44, 48], 837);
                step(f, Op::AddF, &[44, 201, 45], 838);
                step(f, Op::DivFScaleV, &[201, 45, 61, 48, 61, 49, 49, 49, 37, 37, 16, 16], 839);
                step(f, Op::ArrayAtBreakTransform, &[1, 2, 6, 6, 35, 5, 36], 840);
                step(f, Op::ArrayAt(Elem::Float), &[2, 2, 54], 841);
                step(f, Op::SubF, &[201, 54, 60], 842);
                step(f, Op::MaxF, &[60, 199, 67], 843);
                step(f, Op::MulFMulF, &[13, 10, 40, 67, 40, 55], 844);
                step(f, Op::ScaleV, &[2, 55, 38], 845);
                step(f, Op::SubV, &[49, 38, 46], 846);
                step(f, Op::Select(ValueType::Vec3), &[16, 46, 35, 45], 847);
                step(f, Op::ArrayAtBreakTransform, &[2, 2, 5, 5, 10, 1, 9, 29, 29, 31, 31], 848);
                step(f, Op::SubV, &[45, 10, 47], 849);
                step(f, Op::DeltaTime, &[64], 850);
                step(f, Op::DivFScaleV, &[31, 64, 43, 47, 43, 43], 851);
                step(f, Op::AddVAddV, &[45, 43, 40, 10, 43, 41], 852);
                step(f, Op::SubV, &[35, 41, 42], 853);
                step(f, Op::FloatLerp, &[199, 201, 29, 65], 854);
                step(f, Op::SubF, &[201, 65, 34], 855);
                step(f, Op::ScaleV, &[42, 34, 39], 856);
                step(f, Op::AddV, &[40, 39, 7], 857);
                step(f, Op::MulF, &[29, 64, 36], 858);
                step(f, Op::GreaterF, &[36, 199, 13], 859);
                step(f, Op::DivF, &[65, 36, 56], 860);
                step(f, Op::Select(ValueType::Float), &[13, 56, 201, 66], 861);
                step(f, Op::ScaleV, &[47, 66, 44], 862);
                step(f, Op::SubV, &[7, 44, 48, 48, 48], 863);
                step(f, Op::BreakVector, &[48, 47, 33, 44], 864);
                step(f, Op::ClampF, &[44, 110, 111, 45], 865);
                step(f, Op::MakeVector, &[47, 33, 45, 38], 866);
                step(f, Op::RotationFromNormal, &[37, 61, 60, 1], 867);
                step(f, Op::PerFootRotationFactor, &[17, 160, 161, 40], 868);
                step(f, Op::MulFSubF, &[17, 40, 67, 201, 18, 57], 869);
                step(f, Op::MulF, &[67, 57, 55], 870);
                step(f, Op::QuatFromAxisAngle, &[54, 55, 6], 871);
                step(f, Op::MulQ, &[1, 6, 7], 872);
                step(f, Op::Select(ValueType::Quat), &[16, 7, 5, 1], 873);
                step(f, Op::MakeTransform, &[38, 1, 50, 7], 874);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 2, 7], 875);
                step(f, Op::ArrayAtBreakTransform, &[1, 2, 6, 6, 35, 5, 36], 876);
                step(f, Op::Select(ValueType::Vec3), &[16, 46, 35, 45], 877);
                step(f, Op::MakeTransform, &[45, 11, 50, 5], 878);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 2, 5], 879);
                step(f, Op::GetTransformBreakTransform, &[34, 9, 19, 3, 3, 11, 2, 8], 880);
                step(f, Op::BreakVector, &[11, 59, 63, 58], 881);
                step(f, Op::MulF, &[17, 57, 35], 882);
                step(f, Op::QuatFromAxisAngle, &[54, 35, 3], 883);
                step(f, Op::GetTransformBreakTransform, &[0, 9, 19, 4, 4, 12, 4, 13], 884);
                step(f, Op::SubV, &[12, 11, 14], 885);
                step(f, Op::BreakVector, &[14, 39, 37, 32], 886);
                step(f, Op::MakeVector, &[39, 37, 199, 15], 887);
                step(f, Op::RotateVector, &[3, 15, 16], 888);
                step(f, Op::BreakVector, &[16, 46, 70, 50], 889);
                step(f, Op::MulFMulF, &[97, 18, 38, 38, 72, 68], 890);
                step(f, Op::AddFAddF, &[46, 68, 49, 59, 49, 62], 891);
                step(f, Op::AddF, &[63, 70, 42], 892);
                step(f, Op::BreakVector, &[12, 69, 41, 71], 893);
                step(f, Op::SubF, &[71, 100, 48], 894);
                step(f, Op::MakeVector, &[62, 42, 48, 17], 895);
                step(f, Op::MulFScaleV, &[9, 200, 52, 2, 52, 18], 896);
                step(f, Op::AddVSubV, &[17, 18, 19, 45, 19, 49], 897);
                step(f, Op::ArraySetAt(Elem::Vec3), &[0, 2, 49], 898);
                step(f, Op::ArraySetAt(Elem::Bool), &[1, 2, 16], 899);
                step(f, Op::GreaterEqualF, &[54, 201, 8], 900);
                step(f, Op::JumpIfFalse, &[8, 915], 901)
            }
            901 => {
                step(f, Op::MakeVector, &[199, 199, 105, 6], 902);
                step(f, Op::AddV, &[19, 6, 20], 903);
                step(f, Op::RotateVector, &[0, 53, 22], 904);
                step(f, Op::ScaleV, &[22, 109, 23], 905);
                step(f, Op::AddVSubV, &[20, 23, 24, 19, 6, 21], 906);
                step(f, Op::AddV, &[21, 23, 25], 907);
                step(f, Op::SphereTrace, &[24, 25, 104, 14, 26, 27, 51], 908);
                step(f, Op::SubV, &[26, 19, 28], 909);
                step(f, Op::ArraySetAt(Elem::Vec3), &[1, 2, 28], 910);
                step(f, Op::ScaleV, &[22, 106, 29], 911);
                step(f, Op::AddVAddV, &[24, 29, 30, 25, 29, 31], 912);
                step(f, Op::SphereTrace, &[30, 31, 104, 15, 32, 33, 53], 913);
                step(f, Op::SubV, &[32, 19, 34], 914);
                step(f, Op::ArraySetAt(Elem::Vec3), &[2, 2, 34], 915);
                915
            }
            915 => {
                step(f, Op::JumpIfFalse, &[16, 917], 916)
            }
            916 => {
                step(f, Op::Copy(ValueType::Bool), &[19, 7], 917);
                917
            }
            917 => {
                step(f, Op::ArrayAt(Elem::Float), &[4, 2, 43], 918);
                step(f, Op::FloatLerp, &[43, 199, 153, 34], 919);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 2, 9], 920);
                step(f, Op::ArrayAt(Elem::Float), &[2, 2, 64], 921);
                step(f, Op::GreaterEqualF, &[64, 201, 11], 922);
                step(f, Op::And, &[9, 11, 17], 923);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 2, 7], 924);
                step(f, Op::GreaterF, &[27, 199, 12], 925);
                step(f, Op::InterpolateTransform, &[2, 19, 28, 6], 926);
                step(f, Op::Select(ValueType::Transform), &[12, 6, 2, 5], 927);
                step(f, Op::MakeAbsolute, &[7, 5, 3], 928);
                step(f, Op::BreakTransform, &[3, 9, 6, 10], 929);
                step(f, Op::RotateVector, &[6, 53, 43], 930);
                step(f, Op::SubFMulF, &[201, 18, 36, 17, 36, 65], 931);
                step(f, Op::LimitRotationAroundZ, &[6, 65, 150, 7], 932);
                step(f, Op::RotateVector, &[7, 53, 41], 933);
                step(f, Op::CrossV, &[43, 41, 42], 934);
                step(f, Op::BreakVector, &[42, 56, 66, 44], 935);
                step(f, Op::DotV, &[43, 41, 33], 936);
                step(f, Op::Atan2F, &[44, 33, 45], 937);
                step(f, Op::AbsF, &[45, 47], 938);
                step(f, Op::Select(ValueType::Float), &[17, 47, 199, 60], 939);
                step(f, Op::AddF, &[34, 60, 61], 940);
                step(f, Op::ArraySetAt(Elem::Float), &[4, 2, 61], 941);
                step(f, Op::ArrayAtBreakTransform, &[8, 2, 4, 4, 39, 1, 40], 942);
                step(f, Op::AddF, &[114, 115, 40], 943);
                step(f, Op::ClampSpatially, &[9, 39, 199, 40, 47], 944);
                step(f, Op::MakeTransform, &[47, 7, 50, 7], 945);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 2, 7], 946);
                step(f, Op::JumpIfFalse, &[9, 1012], 947)
            }
            947 => {
                step(f, Op::JumpIfFalse, &[11, 949], 948)
            }
            948 => {
                step(f, Op::Jump, &[1011], 949)
            }
            949 => {
                step(f, Op::ArrayAtBreakTransform, &[1, 2, 3, 3, 7, 5, 44], 950);
                step(f, Op::SubFMulF, &[201, 64, 67, 13, 10, 55], 951);
                step(f, Op::MulFScaleV, &[67, 55, 58, 2, 58, 48], 952);
                step(f, Op::AddV, &[7, 48, 37], 953);
                step(f, Op::Equals(Elem::Int), &[2, 9, 10], 954);
                step(f, Op::Select(ValueType::Int), &[10, 10, 9, 7], 955);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 7, 13], 956);
                step(f, Op::ArrayAtBreakTransform, &[0, 7, 4, 4, 38, 2, 36], 957);
                step(f, Op::ArrayAtBreakTransform, &[3, 7, 7, 7, 35, 4, 46], 958);
                step(f, Op::LessEqualF, &[136, 199, 8], 959);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 57], 960);
                step(f, Op::SmoothStepF, &[57, 199, 136, 35], 961);
                step(f, Op::Select(ValueType::Float), &[8, 201, 35, 32], 962);
                step(f, Op::LerpV, &[38, 35, 32, 8], 963);
                step(f, Op::MakeTransform, &[8, 11, 50, 8], 964);
                step(f, Op::Select(ValueType::Transform), &[13, 4, 8, 9], 965);
                step(f, Op::MakeAbsolute, &[9, 5, 10], 966);
                step(f, Op::Select(ValueType::Transform), &[10, 10, 9, 11], 967);
                step(f, Op::BreakTransform, &[11, 13, 3, 11], 968);
                step(f, Op::SubFMulF, &[201, 19, 37, 36, 37, 39], 969);
                step(f, Op::MulF, &[17, 39, 50], 970);
                step(f, Op::FootAvoidance, &[37, 13, 50, 10, 132, 14], 971);
                step(f, Op::RemapF, &[18, 135, 201, 199, 201, 19, 38], 972);
                step(f, Op::LerpV, &[37, 14, 38, 15], 973);
                step(f, Op::FootAvoidance, &[15, 13, 20, 10, 158, 16], 974);
                step(f, Op::LerpV, &[15, 16, 19, 12], 975);
                step(f, Op::MakeTransform, &[12, 5, 50, 12], 976);
                step(f, Op::BreakTransform, &[12, 17, 6, 18], 977);
                step(f, Op::MakeVector, &[199, 199, 105, 45], 978);
                step(f, Op::AddVSubV, &[17, 45, 49, 17, 45, 20], 979);
                step(f, Op::LineTrace, &[49, 20, 14, 6, 21, 72], 980);
                step(f, Op::RotateVector, &[6, 54, 23], 981);
                step(f, Op::FindQuatBetween, &[23, 21, 1], 982);
                step(f, Op::MulQ, &[1, 6, 7], 983);
                step(f, Op::MulFAddF, &[103, 102, 46, 46, 113, 68], 984);
                step(f, Op::NegF, &[68, 49], 985);
                step(f, Op::MakeVector, &[199, 49, 199, 27], 986);
                step(f, Op::RotateVector, &[7, 27, 26], 987);
                step(f, Op::AddVAddV, &[6, 26, 28, 28, 45, 22], 988);
                step(f, Op::SubV, &[28, 45, 24], 989);
                step(f, Op::LineTrace, &[22, 24, 15, 25, 29, 59], 990);
                step(f, Op::BreakVector, &[25, 63, 70, 41], 991);
                step(f, Op::BreakVector, &[28, 69, 71, 42], 992);
                step(f, Op::SubF, &[41, 42, 48], 993);
                step(f, Op::Select(ValueType::Float), &[15, 48, 199, 62], 994);
                step(f, Op::AddF, &[109, 113, 52], 995);
                step(f, Op::MakeVector, &[199, 52, 199, 30], 996);
                step(f, Op::RotateVector, &[7, 30, 31], 997);
                step(f, Op::AddVAddV, &[6, 31, 33, 33, 45, 19], 998);
                step(f, Op::SubV, &[33, 45, 32], 999);
                step(f, Op::LineTrace, &[19, 32, 16, 34, 10, 54], 1000);
                step(f, Op::BreakVector, &[34, 51, 53, 43], 1001);
                step(f, Op::BreakVector, &[33, 65, 56, 66], 1002);
                step(f, Op::SubF, &[43, 66, 33], 1003);
                step(f, Op::Select(ValueType::Float), &[16, 33, 199, 44], 1004);
                step(f, Op::MaxF, &[62, 44, 45], 1005);
                step(f, Op::ClampF, &[45, 199, 112, 47], 1006);
                step(f, Op::MakeVector, &[199, 199, 47, 42], 1007);
                step(f, Op::AddV, &[6, 42, 41], 1008);
                step(f, Op::MakeTransform, &[41, 7, 50, 13], 1009);
                step(f, Op::Select(ValueType::Transform), &[14, 13, 12, 14, 14, 14], 1010);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 2, 14], 1011);
                1011
            }
            1011 => {
                step(f, Op::Jump, &[1110], 1012)
            }
            1012 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 2, 12], 1013);
                step(f, Op::MakeAbsolute, &[12, 5, 13], 1014);
                step(f, Op::BreakTransform, &[13, 43, 1, 40], 1015);
                step(f, Op::ArrayAtBreakTransform, &[1, 2, 3, 3, 7, 5, 44], 1016);
                step(f, Op::SubFMulF, &[201, 64, 67, 13, 10, 55], 1017);
                step(f, Op::MulFScaleV, &[67, 55, 58, 2, 58, 48], 1018);
                step(f, Op::AddV, &[7, 48, 37], 1019);
                step(f, Op::Equals(Elem::Int), &[2, 9, 10], 1020);
                step(f, Op::Select(ValueType::Int), &[10, 10, 9, 7], 1021);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 7, 13], 1022);
                step(f, Op::ArrayAtBreakTransform, &[0, 7, 4, 4, 38, 2, 36], 1023);
                step(f, Op::ArrayAtBreakTransform, &[3, 7, 7, 7, 35, 4, 46], 1024);
                step(f, Op::LessEqualF, &[136, 199, 8], 1025);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 57], 1026);
                step(f, Op::SmoothStepF, &[57, 199, 136, 35], 1027);
                step(f, Op::Select(ValueType::Float), &[8, 201, 35, 32], 1028);
                step(f, Op::LerpV, &[38, 35, 32, 8], 1029);
                step(f, Op::MakeTransform, &[8, 11, 50, 8], 1030);
                step(f, Op::Select(ValueType::Transform), &[13, 4, 8, 9], 1031);
                step(f, Op::MakeAbsolute, &[9, 5, 10], 1032);
                step(f, Op::Select(ValueType::Transform), &[10, 10, 9, 11], 1033);
                step(f, Op::BreakTransform, &[11, 13, 3, 11], 1034);
                step(f, Op::SubFMulF, &[201, 19, 37, 36, 37, 39], 1035);
                step(f, Op::MulF, &[17, 39, 50], 1036);
                step(f, Op::FootAvoidance, &[37, 13, 50, 10, 132, 14], 1037);
                step(f, Op::RemapF, &[18, 135, 201, 199, 201, 19, 38], 1038);
                step(f, Op::LerpV, &[37, 14, 38, 15], 1039);
                step(f, Op::FootAvoidance, &[15, 13, 20, 10, 158, 16], 1040);
                step(f, Op::LerpV, &[15, 16, 19, 12], 1041);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 2, 14], 1042);
                step(f, Op::MakeAbsolute, &[14, 5, 12], 1043);
                step(f, Op::BreakTransform, &[12, 9, 6, 47], 1044);
                step(f, Op::ArrayAt(Elem::Float), &[3, 2, 34], 1045);
                step(f, Op::SubF, &[64, 34, 60], 1046);
                step(f, Op::DeltaTime, &[61], 1047);
                step(f, Op::DivF, &[31, 61, 40], 1048);
                step(f, Op::MulFAddF, &[60, 40, 72, 34, 72, 46], 1049);
                step(f, Op::ClampF, &[46, 199, 201, 68], 1050);
                step(f, Op::AddF, &[64, 72, 49], 1051);
                step(f, Op::ClampF, &[49, 199, 201, 59], 1052);
                step(f, Op::AddFMulF, &[68, 59, 63, 63, 200, 70], 1053);
                step(f, Op::SubF, &[201, 70, 69], 1054);
                step(f, Op::GreaterF, &[60, 199, 17], 1055);
                step(f, Op::SubF, &[59, 68, 71], 1056);
                step(f, Op::DivF, &[71, 60, 41], 1057);
                step(f, Op::Select(ValueType::Float), &[17, 41, 201, 42], 1058);
                step(f, Op::MulFMulF, &[69, 42, 48, 131, 48, 52, 31, 31], 1059);
                step(f, Op::SubV, &[12, 9, 18], 1060);
                step(f, Op::DeltaTime, &[54], 1061);
                step(f, Op::DivFScaleV, &[31, 54, 51, 18, 51, 17], 1062);
                step(f, Op::AddVAddV, &[12, 17, 20, 9, 17, 49], 1063);
                step(f, Op::SubV, &[43, 49, 21], 1064);
                step(f, Op::FloatLerp, &[199, 201, 52, 53], 1065);
                step(f, Op::SubF, &[201, 53, 56], 1066);
                step(f, Op::ScaleV, &[21, 56, 23], 1067);
                step(f, Op::AddV, &[20, 23, 27], 1068);
                step(f, Op::MulF, &[52, 54, 65], 1069);
                step(f, Op::GreaterF, &[65, 199, 15], 1070);
                step(f, Op::DivF, &[53, 65, 43], 1071);
                step(f, Op::Select(ValueType::Float), &[15, 43, 201, 66], 1072);
                step(f, Op::ScaleV, &[18, 66, 26], 1073);
                step(f, Op::SubV, &[27, 26, 22, 22, 22], 1074);
                step(f, Op::MakeTransform, &[22, 5, 50, 13], 1075);
                step(f, Op::BreakTransform, &[13, 24, 7, 29], 1076);
                step(f, Op::MakeVector, &[199, 199, 105, 25], 1077);
                step(f, Op::AddVSubV, &[24, 25, 28, 24, 25, 30], 1078);
                step(f, Op::LineTrace, &[28, 30, 16, 31, 45, 33], 1079);
                step(f, Op::RotateVector, &[7, 54, 10], 1080);
                step(f, Op::FindQuatBetween, &[10, 45, 1], 1081);
                step(f, Op::MulQ, &[1, 7, 6], 1082);
                step(f, Op::MulFAddF, &[103, 102, 44, 44, 113, 62], 1083);
                step(f, Op::NegF, &[62, 45], 1084);
                step(f, Op::MakeVector, &[199, 45, 199, 19], 1085);
                step(f, Op::RotateVector, &[6, 19, 32], 1086);
                step(f, Op::AddVAddV, &[31, 32, 34, 34, 25, 33], 1087);
                step(f, Op::SubV, &[34, 25, 6], 1088);
                step(f, Op::LineTrace, &[33, 6, 14, 42, 41, 47], 1089);
                step(f, Op::BreakVector, &[42, 61, 40, 34], 1090);
                step(f, Op::BreakVector, &[34, 46, 72, 49], 1091);
                step(f, Op::SubF, &[34, 49, 63], 1092);
                step(f, Op::Select(ValueType::Float), &[14, 63, 199, 70], 1093);
                step(f, Op::AddF, &[109, 113, 59], 1094);
                step(f, Op::MakeVector, &[199, 59, 199, 40], 1095);
                step(f, Op::RotateVector, &[6, 40, 47], 1096);
                step(f, Op::AddVAddV, &[31, 47, 9, 9, 25, 17], 1097);
                step(f, Op::SubV, &[9, 25, 43], 1098);
                step(f, Op::LineTrace, &[17, 43, 17, 49, 21, 68], 1099);
                step(f, Op::BreakVector, &[49, 60, 71, 41], 1100);
                step(f, Op::BreakVector, &[9, 42, 69, 48], 1101);
                step(f, Op::SubF, &[41, 48, 51], 1102);
                step(f, Op::Select(ValueType::Float), &[17, 51, 199, 56], 1103);
                step(f, Op::MaxF, &[70, 56, 52], 1104);
                step(f, Op::ClampF, &[52, 199, 112, 54], 1105);
                step(f, Op::MakeVector, &[199, 199, 54, 20], 1106);
                step(f, Op::AddV, &[31, 20, 23], 1107);
                step(f, Op::MakeTransform, &[23, 6, 50, 14], 1108);
                step(f, Op::Select(ValueType::Transform), &[16, 14, 13, 12, 12, 12], 1109);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 2, 12], 1110);
                1110
            }
            1110 => {
                step(f, Op::JumpIfFalse, &[11, 1180], 1111)
            }
            1111 => {
                step(f, Op::JumpIfFalse, &[9, 1113], 1112)
            }
            1112 => {
                step(f, Op::Jump, &[1166], 1113)
            }
            1113 => {
                step(f, Op::ArrayAtBreakTransform, &[3, 2, 13, 13, 18, 1, 26], 1114);
                step(f, Op::Equals(Elem::Int), &[2, 9, 10], 1115);
                step(f, Op::Select(ValueType::Int), &[10, 10, 9, 7], 1116);
                step(f, Op::ArrayAtBreakTransform, &[6, 7, 14, 14, 27, 7, 22], 1117);
                step(f, Op::MakeAbsolute, &[14, 5, 12], 1118);
                step(f, Op::BreakTransform, &[12, 29, 6, 24], 1119);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 57], 1120);
                step(f, Op::SmoothStepF, &[57, 199, 201, 53], 1121);
                step(f, Op::RemapF, &[18, 199, 135, 199, 201, 19, 65], 1122);
                step(f, Op::MulF, &[53, 65, 43], 1123);
                step(f, Op::Select(ValueType::Float), &[10, 43, 199, 66], 1124);
                step(f, Op::LerpV, &[27, 29, 66, 28], 1125);
                step(f, Op::MakeTransform, &[28, 11, 50, 15], 1126);
                step(f, Op::BreakTransform, &[15, 30, 8, 10], 1127);
                step(f, Op::SubFMulF, &[201, 19, 37, 36, 37, 39], 1128);
                step(f, Op::MulF, &[17, 39, 50], 1129);
                step(f, Op::FootAvoidance, &[18, 30, 50, 10, 132, 45], 1130);
                step(f, Op::MakeTransform, &[45, 1, 50, 16], 1131);
                step(f, Op::BreakTransform, &[16, 19, 1, 32], 1132);
                step(f, Op::MakeVector, &[199, 199, 105, 6], 1133);
                step(f, Op::AddVSubV, &[19, 6, 33, 19, 6, 41], 1134);
                step(f, Op::LineTrace, &[33, 41, 15, 42, 34, 33], 1135);
                step(f, Op::RotateVector, &[1, 54, 40], 1136);
                step(f, Op::FindQuatBetween, &[40, 34, 9], 1137);
                step(f, Op::MulQ, &[9, 1, 10], 1138);
                step(f, Op::MulFAddF, &[103, 102, 44, 44, 113, 62], 1139);
                step(f, Op::NegF, &[62, 45], 1140);
                step(f, Op::MakeVector, &[199, 45, 199, 47], 1141);
                step(f, Op::RotateVector, &[10, 47, 25], 1142);
                step(f, Op::AddVAddV, &[42, 25, 17, 17, 6, 21], 1143);
                step(f, Op::SubV, &[17, 6, 43], 1144);
                step(f, Op::LineTrace, &[21, 43, 14, 49, 9, 47], 1145);
                step(f, Op::BreakVector, &[49, 40, 61, 46], 1146);
                step(f, Op::BreakVector, &[17, 72, 34, 49], 1147);
                step(f, Op::SubF, &[46, 49, 63], 1148);
                step(f, Op::Select(ValueType::Float), &[14, 63, 199, 59], 1149);
                step(f, Op::AddF, &[109, 113, 68], 1150);
                step(f, Op::MakeVector, &[199, 68, 199, 20], 1151);
                step(f, Op::RotateVector, &[10, 20, 31], 1152);
                step(f, Op::AddVAddV, &[42, 31, 23, 23, 6, 26], 1153);
                step(f, Op::SubV, &[23, 6, 18], 1154);
                step(f, Op::LineTrace, &[26, 18, 17, 45, 32, 60], 1155);
                step(f, Op::BreakVector, &[45, 71, 42, 69], 1156);
                step(f, Op::BreakVector, &[23, 41, 48, 51], 1157);
                step(f, Op::SubF, &[69, 51, 56], 1158);
                step(f, Op::Select(ValueType::Float), &[17, 56, 199, 70], 1159);
                step(f, Op::MaxF, &[59, 70, 52], 1160);
                step(f, Op::ClampF, &[52, 199, 112, 54], 1161);
                step(f, Op::MakeVector, &[199, 199, 54, 19], 1162);
                step(f, Op::AddV, &[42, 19, 33], 1163);
                step(f, Op::MakeTransform, &[33, 10, 50, 17], 1164);
                step(f, Op::Select(ValueType::Transform), &[15, 17, 16, 18, 18, 18], 1165);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 2, 18], 1166);
                1166
            }
            1166 => {
                step(f, Op::ArrayAtBreakTransform, &[0, 2, 16, 16, 41, 1, 34], 1167);
                step(f, Op::SubV, &[41, 39, 40], 1168);
                step(f, Op::LengthV, &[40, 33], 1169);
                step(f, Op::SubF, &[114, 115, 44], 1170);
                step(f, Op::SubFMulF, &[33, 44, 62, 115, 204, 45], 1171);
                step(f, Op::ClampF, &[62, 199, 45, 47], 1172);
                step(f, Op::MulFMulF, &[47, 47, 40, 115, 215, 61], 1173);
                step(f, Op::DivFSubF, &[40, 61, 34, 33, 34, 72], 1174);
                step(f, Op::DivFScaleV, &[72, 33, 46, 40, 46, 47], 1175);
                step(f, Op::AddV, &[39, 47, 25], 1176);
                step(f, Op::MakeTransform, &[25, 1, 50, 17], 1177);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 2, 17], 1178);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 2, 17], 1179);
                step(f, Op::Jump, &[1330], 1180)
            }
            1180 => {
                step(f, Op::ArrayAtBreakTransform, &[0, 2, 16, 16, 41, 1, 34], 1181);
                step(f, Op::SubV, &[41, 39, 40], 1182);
                step(f, Op::LengthV, &[40, 33], 1183);
                step(f, Op::SubF, &[114, 115, 44], 1184);
                step(f, Op::SubFMulF, &[33, 44, 62, 115, 204, 45], 1185);
                step(f, Op::ClampF, &[62, 199, 45, 47], 1186);
                step(f, Op::MulFMulF, &[47, 47, 40, 115, 215, 61], 1187);
                step(f, Op::DivFSubF, &[40, 61, 34, 33, 34, 72], 1188);
                step(f, Op::DivFScaleV, &[72, 33, 46, 40, 46, 47], 1189);
                step(f, Op::AddV, &[39, 47, 25], 1190);
                step(f, Op::MakeTransform, &[25, 1, 50, 17], 1191);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 2, 13], 1192);
                step(f, Op::ClampF, &[64, 199, 201, 49], 1193);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[6, 5], 1194);
                step(f, Op::ArrayReset(Elem::Vec3), &[5], 1195);
                step(f, Op::BreakTransform, &[17, 9, 9, 21], 1196);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 9], 1197);
                step(f, Op::UnitV, &[2, 43], 1198);
                step(f, Op::LengthV, &[2, 63], 1199);
                step(f, Op::RemapF, &[63, 199, 116, 199, 117, 19, 68], 1200);
                step(f, Op::ScaleV, &[43, 68, 49], 1201);
                step(f, Op::SubV, &[9, 49, 17], 1202);
                step(f, Op::MakeVector, &[199, 199, 119, 20], 1203);
                step(f, Op::AddV, &[17, 20, 31], 1204);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 31], 1205);
                step(f, Op::RemapF, &[63, 199, 116, 199, 122, 19, 60], 1206);
                step(f, Op::MakeVector, &[199, 199, 60, 6], 1207);
                step(f, Op::AddV, &[31, 6, 18], 1208);
                step(f, Op::BreakTransform, &[13, 26, 10, 32], 1209);
                step(f, Op::BreakVector, &[26, 42, 71, 41], 1210);
                step(f, Op::BreakVector, &[9, 48, 51, 69], 1211);
                step(f, Op::SubF, &[41, 69, 56], 1212);
                step(f, Op::MaxF, &[56, 199, 59], 1213);
                step(f, Op::MulF, &[59, 124, 70], 1214);
                step(f, Op::MinF, &[70, 125, 52], 1215);
                step(f, Op::AbsF, &[56, 54], 1216);
                step(f, Op::RemapF, &[54, 199, 128, 199, 127, 19, 44], 1217);
                step(f, Op::AddF, &[52, 44, 45], 1218);
                step(f, Op::MakeVector, &[199, 199, 45, 45], 1219);
                step(f, Op::AddV, &[18, 45, 23], 1220);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 23], 1221);
                step(f, Op::RemapF, &[63, 199, 116, 199, 118, 19, 62], 1222);
                step(f, Op::ScaleV, &[43, 62, 19], 1223);
                step(f, Op::AddV, &[26, 19, 42], 1224);
                step(f, Op::LerpF, &[73, 96, 18, 47], 1225);
                step(f, Op::MulF, &[14, 47, 40], 1226);
                step(f, Op::RemapF, &[40, 201, 82, 120, 121, 19, 61], 1227);
                step(f, Op::MakeVector, &[199, 199, 61, 33], 1228);
                step(f, Op::AddV, &[42, 33, 34], 1229);
                step(f, Op::RemapF, &[63, 199, 116, 199, 123, 19, 34], 1230);
                step(f, Op::MakeVector, &[199, 199, 34, 41], 1231);
                step(f, Op::AddV, &[34, 41, 40], 1232);
                step(f, Op::NegF, &[56, 33], 1233);
                step(f, Op::MaxF, &[33, 199, 72], 1234);
                step(f, Op::MulFAddF, &[72, 126, 46, 46, 44, 68], 1235);
                step(f, Op::MakeVector, &[199, 199, 68, 39], 1236);
                step(f, Op::AddV, &[40, 39, 47], 1237);
                step(f, Op::LerpV, &[23, 47, 200, 25], 1238);
                step(f, Op::GetTransformBreakTransform, &[35, 9, 19, 18, 18, 21, 1, 49], 1239);
                step(f, Op::BreakVector, &[21, 60, 42, 71], 1240);
                step(f, Op::SubFMulF, &[201, 18, 48, 129, 48, 51], 1241);
                step(f, Op::MulF, &[17, 51, 41], 1242);
                step(f, Op::QuatFromAxisAngle, &[54, 41, 1], 1243);
                step(f, Op::SubV, &[25, 21, 17], 1244);
                step(f, Op::BreakVector, &[17, 69, 59, 70], 1245);
                step(f, Op::MakeVector, &[69, 59, 199, 20], 1246);
                step(f, Op::RotateVector, &[1, 20, 6], 1247);
                step(f, Op::BreakVector, &[6, 54, 52, 45], 1248);
                step(f, Op::AddFAddF, &[60, 54, 62, 42, 52, 47], 1249);
                step(f, Op::BreakVector, &[25, 40, 61, 63], 1250);
                step(f, Op::MakeVector, &[62, 47, 63, 31], 1251);
                step(f, Op::DistanceV, &[9, 26, 34], 1252);
                step(f, Op::RemapF, &[34, 204, 216, 199, 201, 19, 56], 1253);
                step(f, Op::LerpV, &[25, 31, 56, 32], 1254);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 32], 1255);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 47], 1256);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 34], 1257);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 26], 1258);
                step(f, Op::JumpIfFalse, &[18, 1260], 1259)
            }
            1259 => {
                step(f, Op::DrawSpline, &[5, 9, 12, 200, 56], 1260);
                1260
            }
            1260 => {
                step(f, Op::Spline, &[5, 49, 9, 18, 45], 1261);
                step(f, Op::SlerpQ, &[9, 10, 49, 1], 1262);
                step(f, Op::MulF, &[49, 209, 33], 1263);
                step(f, Op::SinF, &[33, 72], 1264);
                step(f, Op::SmoothStepF, &[49, 199, 143, 44], 1265);
                step(f, Op::MulFMulF, &[72, 44, 46, 46, 130, 68], 1266);
                step(f, Op::SlerpQ, &[1, 11, 68, 9], 1267);
                step(f, Op::MakeTransform, &[18, 9, 50, 16, 16, 16], 1268);
                step(f, Op::BreakTransform, &[16, 43, 10, 19], 1269);
                step(f, Op::Equals(Elem::Int), &[2, 9, 10], 1270);
                step(f, Op::Select(ValueType::Int), &[10, 10, 9, 7], 1271);
                step(f, Op::ArrayAtBreakTransform, &[6, 7, 14, 14, 27, 7, 22], 1272);
                step(f, Op::GreaterF, &[27, 199, 12], 1273);
                step(f, Op::InterpolateTransform, &[2, 19, 28, 6], 1274);
                step(f, Op::Select(ValueType::Transform), &[12, 6, 2, 5], 1275);
                step(f, Op::MakeAbsolute, &[14, 5, 12], 1276);
                step(f, Op::BreakTransform, &[12, 29, 6, 24], 1277);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 57], 1278);
                step(f, Op::SmoothStepF, &[57, 199, 201, 53], 1279);
                step(f, Op::RemapF, &[18, 199, 135, 199, 201, 19, 65], 1280);
                step(f, Op::MulF, &[53, 65, 43], 1281);
                step(f, Op::Select(ValueType::Float), &[10, 43, 199, 66], 1282);
                step(f, Op::LerpV, &[27, 29, 66, 28], 1283);
                step(f, Op::MakeTransform, &[28, 11, 50, 15], 1284);
                step(f, Op::BreakTransform, &[15, 30, 8, 10], 1285);
                step(f, Op::SubF, &[201, 18, 36], 1286);
                step(f, Op::SubFMulF, &[201, 19, 37, 36, 37, 39], 1287);
                step(f, Op::MulF, &[17, 39, 50], 1288);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 7, 16], 1289);
                step(f, Op::Select(ValueType::Float), &[16, 133, 199, 71], 1290);
                step(f, Op::ArrayAt(Elem::Float), &[2, 2, 64], 1291);
                step(f, Op::ClampF, &[64, 199, 201, 49], 1292);
                step(f, Op::MulF, &[49, 209, 48], 1293);
                step(f, Op::SinF, &[48, 51], 1294);
                step(f, Op::MulFMulF, &[51, 51, 41, 71, 41, 70], 1295);
                step(f, Op::AddF, &[132, 70, 59], 1296);
                step(f, Op::FootAvoidance, &[43, 30, 50, 10, 59, 33], 1297);
                step(f, Op::SubV, &[33, 43, 42], 1298);
                step(f, Op::LengthV, &[42, 69], 1299);
                step(f, Op::AddF, &[69, 70, 45], 1300);
                step(f, Op::DivF, &[69, 45, 54], 1301);
                step(f, Op::MulF, &[157, 204, 60], 1302);
                step(f, Op::LessEqualF, &[69, 60, 9], 1303);
                step(f, Op::MulF, &[157, 215, 42], 1304);
                step(f, Op::DivF, &[69, 42, 52], 1305);
                step(f, Op::DivFSubF, &[157, 69, 40, 201, 40, 61], 1306);
                step(f, Op::Select(ValueType::Float), &[9, 52, 61, 47], 1307);
                step(f, Op::GreaterF, &[157, 199, 14], 1308);
                step(f, Op::Select(ValueType::Float), &[14, 19, 199, 62], 1309);
                step(f, Op::LerpF, &[54, 47, 62, 63], 1310);
                step(f, Op::LessF, &[57, 64, 17], 1311);
                step(f, Op::LessEqualF, &[134, 199, 15], 1312);
                step(f, Op::SmoothStepF, &[57, 199, 134, 34], 1313);
                step(f, Op::MulFSubF, &[34, 18, 56, 201, 56, 33], 1314);
                step(f, Op::Select(ValueType::Float), &[15, 201, 33, 44], 1315);
                step(f, Op::Select(ValueType::Float), &[17, 44, 201, 72], 1316);
                step(f, Op::MulF, &[63, 72, 46], 1317);
                step(f, Op::SmoothStepF, &[49, 199, 134, 68], 1318);
                step(f, Op::Select(ValueType::Float), &[15, 201, 68, 53], 1319);
                step(f, Op::MulFScaleV, &[46, 53, 65, 42, 65, 41], 1320);
                step(f, Op::AddV, &[43, 41, 39], 1321);
                step(f, Op::MulFMulF, &[6, 190, 43, 43, 41, 66], 1322);
                step(f, Op::MakeVector, &[199, 199, 66, 40], 1323);
                step(f, Op::AddV, &[39, 40, 23], 1324);
                step(f, Op::MakeTransform, &[23, 10, 50, 17], 1325);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 2, 17], 1326);
                step(f, Op::ScaleV, &[42, 46, 49], 1327);
                step(f, Op::AddVAddV, &[43, 49, 21, 21, 40, 17], 1328);
                step(f, Op::MakeTransform, &[17, 10, 50, 13], 1329);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 2, 13], 1330);
                1330
            }
            1330 => {
                step(f, Op::JumpIfFalse, &[12, 1348], 1331)
            }
            1331 => {
                step(f, Op::ArrayAtBreakTransform, &[5, 2, 18, 18, 20, 1, 6], 1332);
                step(f, Op::ArrayAtBreakTransform, &[8, 2, 16, 16, 9, 9, 25], 1333);
                step(f, Op::MulF, &[27, 27, 48], 1334);
                step(f, Op::LerpV, &[20, 9, 48, 31], 1335);
                step(f, Op::SubFMulF, &[201, 27, 51, 27, 51, 71], 1336);
                step(f, Op::MulFMulF, &[192, 204, 59, 71, 59, 70], 1337);
                step(f, Op::MakeVector, &[199, 199, 70, 32], 1338);
                step(f, Op::AddV, &[31, 32, 47], 1339);
                step(f, Op::SlerpQ, &[1, 9, 27, 7], 1340);
                step(f, Op::MakeTransform, &[47, 7, 50, 6], 1341);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 2, 6], 1342);
                step(f, Op::ArrayAtBreakTransform, &[5, 2, 18, 18, 20, 1, 6], 1343);
                step(f, Op::LerpV, &[20, 9, 48, 31], 1344);
                step(f, Op::AddV, &[31, 32, 47], 1345);
                step(f, Op::SlerpQ, &[1, 9, 27, 7], 1346);
                step(f, Op::MakeTransform, &[47, 7, 50, 6], 1347);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 2, 6], 1348);
                1348
            }
            1348 => {
                step(f, Op::GreaterEqualF, &[64, 201, 11], 1349);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 2, 11], 1350);
                step(f, Op::ArrayAtBreakTransform, &[1, 2, 3, 3, 7, 5, 44], 1351);
                step(f, Op::SubFMulF, &[201, 64, 67, 13, 10, 55], 1352);
                step(f, Op::MulFScaleV, &[67, 55, 58, 2, 58, 48], 1353);
                step(f, Op::AddV, &[7, 48, 37], 1354);
                step(f, Op::Equals(Elem::Int), &[2, 9, 10], 1355);
                step(f, Op::Select(ValueType::Int), &[10, 10, 9, 7], 1356);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 7, 13], 1357);
                step(f, Op::ArrayAtBreakTransform, &[0, 7, 4, 4, 38, 2, 36], 1358);
                step(f, Op::ArrayAtBreakTransform, &[3, 7, 7, 7, 35, 4, 46], 1359);
                step(f, Op::LessEqualF, &[136, 199, 8], 1360);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 57], 1361);
                step(f, Op::SmoothStepF, &[57, 199, 136, 35], 1362);
                step(f, Op::Select(ValueType::Float), &[8, 201, 35, 32], 1363);
                step(f, Op::LerpV, &[38, 35, 32, 8], 1364);
                step(f, Op::MakeTransform, &[8, 11, 50, 8], 1365);
                step(f, Op::Select(ValueType::Transform), &[13, 4, 8, 9], 1366);
                step(f, Op::MakeAbsolute, &[9, 5, 10], 1367);
                step(f, Op::Select(ValueType::Transform), &[10, 10, 9, 11], 1368);
                step(f, Op::BreakTransform, &[11, 13, 3, 11], 1369);
                step(f, Op::SubFMulF, &[201, 19, 37, 36, 37, 39], 1370);
                step(f, Op::MulF, &[17, 39, 50], 1371);
                step(f, Op::FootAvoidance, &[37, 13, 50, 10, 132, 14], 1372);
                step(f, Op::RemapF, &[18, 135, 201, 199, 201, 19, 38], 1373);
                step(f, Op::LerpV, &[37, 14, 38, 15], 1374);
                step(f, Op::FootAvoidance, &[15, 13, 20, 10, 158, 16], 1375);
                step(f, Op::LerpV, &[15, 16, 19, 12], 1376);
                step(f, Op::MakeTransform, &[12, 11, 50, 14], 1377);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 2, 14], 1378);
                step(f, Op::ArrayAtBreakTransform, &[5, 2, 12, 12, 34, 6, 26], 1379);
                step(f, Op::MakeVector, &[199, 199, 100, 45], 1380);
                step(f, Op::AddV, &[34, 45, 18], 1381);
                step(f, Op::GetTransformBreakTransform, &[0, 9, 19, 15, 15, 19, 8, 22], 1382);
                step(f, Op::MakeTransform, &[18, 8, 50, 17], 1383);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 2, 20], 1384);
                step(f, Op::GetTransformBreakTransform, &[20, 9, 19, 13, 13, 24, 10, 27], 1385);
                step(f, Op::SubV, &[24, 19, 29], 1386);
                step(f, Op::AddV, &[18, 29, 28], 1387);
                step(f, Op::FootPivots, &[18, 28, 102, 101, 100, 103, 10, 30, 33], 1388);
                step(f, Op::GetParent, &[0, 18], 1389);
                step(f, Op::GetParent, &[18, 19], 1390);
                step(f, Op::GetTransformBreakTransform, &[19, 9, 20, 16, 16, 41, 1, 39], 1391);
                step(f, Op::SubV, &[34, 41, 23], 1392);
                step(f, Op::DotV, &[23, 53, 45], 1393);
                step(f, Op::RemapF, &[45, 138, 137, 139, 199, 19, 60], 1394);
                step(f, Op::LengthV, &[2, 42], 1395);
                step(f, Op::RemapF, &[42, 199, 149, 199, 201, 19, 69], 1396);
                step(f, Op::MulF, &[60, 69, 40], 1397);
                step(f, Op::QuatFromAxisAngle, &[57, 40, 9], 1398);
                step(f, Op::RotateAroundPoint, &[17, 10, 9, 18], 1399);
                step(f, Op::ArrayAt(Elem::Float), &[2, 2, 52], 1400);
                step(f, Op::SmoothStepF, &[52, 199, 143, 61], 1401);
                step(f, Op::SubF, &[201, 52, 47], 1402);
                step(f, Op::SmoothStepF, &[47, 199, 143, 54], 1403);
                step(f, Op::MulF, &[61, 54, 62], 1404);
                step(f, Op::LerpF, &[142, 201, 62, 34], 1405);
                step(f, Op::MulF, &[40, 34, 56], 1406);
                step(f, Op::QuatFromAxisAngle, &[57, 56, 7], 1407);
                step(f, Op::SubV, &[30, 10, 42], 1408);
                step(f, Op::RotateVector, &[7, 42, 43], 1409);
                step(f, Op::AddV, &[10, 43, 49], 1410);
                step(f, Op::RemapF, &[45, 140, 138, 141, 199, 19, 33], 1411);
                step(f, Op::MulF, &[33, 69, 44], 1412);
                step(f, Op::QuatFromAxisAngle, &[57, 44, 5], 1413);
                step(f, Op::RotateAroundPoint, &[18, 49, 5, 6], 1414);
                step(f, Op::RemapF, &[45, 144, 145, 199, 146, 19, 63], 1415);
                step(f, Op::RotateVector, &[6, 54, 21], 1416);
                step(f, Op::BreakVector, &[21, 72, 49, 68], 1417);
                step(f, Op::CosF, &[148, 53], 1418);
                step(f, Op::CosF, &[147, 65], 1419);
                step(f, Op::RemapF, &[68, 53, 65, 199, 201, 19, 41], 1420);
                step(f, Op::MulFMulF, &[69, 41, 43, 63, 43, 66], 1421);
                step(f, Op::QuatFromAxisAngle, &[57, 66, 2], 1422);
                step(f, Op::RotateAroundPoint, &[6, 33, 2, 3], 1423);
                step(f, Op::SubFMulF, &[201, 18, 46, 17, 46, 51], 1424);
                step(f, Op::LimitRotationAroundZ, &[6, 51, 150, 4], 1425);
                step(f, Op::RotateAroundPoint, &[3, 34, 4, 7], 1426);
                step(f, Op::BreakTransform, &[7, 40, 3, 17], 1427);
                step(f, Op::ArrayAt(Elem::Float), &[4, 2, 59], 1428);
                step(f, Op::MulFMulF, &[59, 151, 71, 71, 152, 70], 1429);
                step(f, Op::AddF, &[71, 152, 48], 1430);
                step(f, Op::DivF, &[70, 48, 64], 1431);
                step(f, Op::MakeVector, &[199, 199, 64, 25], 1432);
                step(f, Op::AddV, &[40, 25, 6], 1433);
                step(f, Op::MakeTransform, &[6, 3, 17, 4], 1434);
                step(f, Op::ArraySetAt(Elem::Transform), &[7, 2, 4], 1435);
                step(f, Op::JumpIfFalse, &[18, 1440], 1436)
            }
            1436 => {
                step(f, Op::DrawPoint, &[33, 217, 57], 1437);
                step(f, Op::DrawPoint, &[10, 217, 53], 1438);
                step(f, Op::DrawPoint, &[49, 217, 54], 1439);
                step(f, Op::DrawTransform, &[12, 216, 200], 1440);
                1440
            }
            1440 => {
                step(f, Op::Jump, &[642], 1441)
            }
            1441 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1442);
                step(f, Op::Copy(ValueType::Int), &[9, 5], 1443);
                1443
            }
            1443 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 5, 1, 1, 3, 1479], 1444)
            }
            1444 => {
                step(f, Op::GetParent, &[1, 22], 1445);
                step(f, Op::GetParent, &[22, 23], 1446);
                step(f, Op::GetParent, &[23, 24], 1447);
                step(f, Op::GetTransformBreakTransform, &[24, 9, 20, 8, 8, 9, 8, 20], 1448);
                step(f, Op::LengthV, &[1, 55], 1449);
                step(f, Op::ClavicleOffset, &[15, 55, 164, 168, 67], 1450);
                step(f, Op::MakeVector, &[199, 199, 67, 31], 1451);
                step(f, Op::AddV, &[9, 31, 32], 1452);
                step(f, Op::MakeTransform, &[32, 8, 50, 5], 1453);
                step(f, Op::SetTransform, &[24, 5, 9, 19, 201], 1454);
                step(f, Op::GetTransform, &[1, 9, 20, 9], 1455);
                step(f, Op::GetTransformBreakTransform, &[23, 9, 20, 10, 10, 47, 10, 44], 1456);
                step(f, Op::Equals(Elem::Int), &[1, 9, 16], 1457);
                step(f, Op::Select(ValueType::Int), &[16, 10, 9, 6], 1458);
                step(f, Op::ArrayAt(Elem::Float), &[0, 6, 58], 1459);
                step(f, Op::ArmSwingRotation, &[58, 1, 0, 165, 208, 218, 201, 164, 162, 163, 166, 208, 201, 57], 1460);
                step(f, Op::QuatFromAxisAngle, &[57, 57, 1], 1461);
                step(f, Op::RotateAroundPoint, &[9, 47, 1, 11], 1462);
                step(f, Op::BreakTransform, &[11, 7, 9, 48], 1463);
                step(f, Op::RemapF, &[55, 199, 164, 199, 167, 19, 35], 1464);
                step(f, Op::MakeVector, &[199, 199, 35, 36], 1465);
                step(f, Op::AddV, &[7, 36, 46], 1466);
                step(f, Op::MakeTransform, &[46, 9, 50, 14], 1467);
                step(f, Op::Select(ValueType::Vec3), &[16, 58, 57, 35], 1468);
                step(f, Op::Select(ValueType::Vec3), &[16, 53, 59, 38], 1469);
                step(f, Op::ArrayAt(Elem::Vec3), &[4, 1, 8], 1470);
                step(f, Op::TwoBoneIK, &[23, 22, 1, 14, 35, 38, 8, 9, 201, 20, 219, 220, 19, 9, 32], 1471);
                step(f, Op::JumpIfFalse, &[18, 1478], 1472)
            }
            1472 => {
                step(f, Op::GetTransformBreakTransform, &[23, 9, 20, 10, 10, 47, 10, 44], 1473);
                step(f, Op::GetTransform, &[1, 9, 20, 9], 1474);
                step(f, Op::RotateAroundPoint, &[9, 47, 1, 11], 1475);
                step(f, Op::BreakTransform, &[11, 7, 9, 48], 1476);
                step(f, Op::AddV, &[7, 36, 46], 1477);
                step(f, Op::DrawLine, &[47, 46, 200, 53], 1478);
                1478
            }
            1478 => {
                step(f, Op::Jump, &[1443], 1479)
            }
            1479 => {
                step(f, Op::NegF, &[5, 36], 1480);
                step(f, Op::MakeVector, &[199, 199, 36, 11], 1481);
                step(f, Op::MakeTransform, &[11, 11, 50, 15], 1482);
                step(f, Op::SetTransform, &[36, 15, 9, 19, 201], 1483);
                step(f, Op::Copy(ValueType::Float), &[206, 37], 1484);
                step(f, Op::Copy(ValueType::Bool), &[20, 14], 1485);
                step(f, Op::Copy(ValueType::Int), &[9, 7], 1486);
                step(f, Op::MakeVector, &[199, 199, 105, 14], 1487);
                1487
            }
            1487 => {
                step(f, Op::ForEachNext(Elem::Transform), &[5, 7, 13, 2, 4, 1498], 1488)
            }
            1488 => {
                step(f, Op::BreakTransform, &[13, 37, 7, 13], 1489);
                step(f, Op::AddVSubV, &[37, 14, 15, 37, 14, 16], 1490);
                step(f, Op::SphereTrace, &[15, 16, 104, 17, 12, 26, 39], 1491);
                step(f, Op::BreakVector, &[12, 50, 38, 42], 1492);
                step(f, Op::LessF, &[42, 37, 15], 1493);
                step(f, Op::And, &[17, 15, 12], 1494);
                step(f, Op::JumpIfFalse, &[12, 1497], 1495)
            }
            1495 => {
                step(f, Op::Copy(ValueType::Float), &[42, 37], 1496);
                step(f, Op::Copy(ValueType::Bool), &[19, 14], 1497);
                1497
            }
            1497 => {
                step(f, Op::Jump, &[1487], 1498)
            }
            1498 => {
                step(f, Op::Select(ValueType::Float), &[14, 37, 199, 60], 1499);
                step(f, Op::ClampF, &[60, 110, 111, 52, 52, 52], 1500);
                step(f, Op::SubFMulF, &[201, 27, 47, 52, 47, 54], 1501);
                step(f, Op::SubFMulF, &[201, 189, 61, 5, 61, 62], 1502);
                step(f, Op::AddF, &[54, 62, 34], 1503);
                step(f, Op::MakeVector, &[22, 199, 199, 45], 1504);
                step(f, Op::MakeVector, &[34, 199, 199, 22], 1505);
                step(f, Op::Select(ValueType::Float), &[2, 34, 23, 40], 1506);
                step(f, Op::MakeVector, &[40, 199, 199, 27, 30, 30, 31, 31], 1507);
                step(f, Op::SubV, &[22, 27, 19], 1508);
                step(f, Op::DeltaTime, &[56], 1509);
                step(f, Op::DivFScaleV, &[31, 56, 33, 19, 33, 24], 1510);
                step(f, Op::AddVAddV, &[22, 24, 29, 27, 24, 18], 1511);
                step(f, Op::SubV, &[45, 18, 28], 1512);
                step(f, Op::FloatLerp, &[199, 201, 30, 44], 1513);
                step(f, Op::SubF, &[201, 44, 45], 1514);
                step(f, Op::ScaleV, &[28, 45, 39], 1515);
                step(f, Op::AddV, &[29, 39, 41], 1516);
                step(f, Op::MulF, &[30, 56, 49], 1517);
                step(f, Op::GreaterF, &[49, 199, 11], 1518);
                step(f, Op::DivF, &[44, 49, 72], 1519);
                step(f, Op::Select(ValueType::Float), &[11, 72, 201, 53], 1520);
                step(f, Op::ScaleV, &[19, 53, 23], 1521);
                step(f, Op::SubV, &[41, 23, 30, 30, 30], 1522);
                step(f, Op::BreakVector, &[30, 65, 68, 41], 1523);
                step(f, Op::Select(ValueType::Float), &[1, 34, 65, 22, 22, 22], 1524);
                step(f, Op::Copy(ValueType::Float), &[34, 23], 1525);
                step(f, Op::GetTransformBreakTransform, &[37, 9, 19, 16, 16, 42, 5, 43], 1526);
                step(f, Op::PelvisLean, &[1, 171, 176, 177, 69, 43], 1527);
                step(f, Op::LengthV, &[2, 63], 1528);
                step(f, Op::RemapF, &[63, 199, 171, 199, 169, 19, 66], 1529);
                step(f, Op::MulFSubF, &[18, 170, 46, 201, 46, 51], 1530);
                step(f, Op::MulFMulF, &[66, 51, 59, 15, 221, 71], 1531);
                step(f, Op::SinF, &[71, 48], 1532);
                step(f, Op::MulFMulF, &[59, 48, 70, 70, 47, 64], 1533);
                step(f, Op::AddF, &[64, 22, 67], 1534);
                step(f, Op::SubF, &[67, 5, 58], 1535);
                step(f, Op::MakeVector, &[199, 43, 58, 21], 1536);
                step(f, Op::AddV, &[42, 21, 34], 1537);
                step(f, Op::ArrayAtBreakTransform, &[7, 9, 17, 17, 25, 2, 40], 1538);
                step(f, Op::BreakVector, &[25, 57, 55, 35], 1539);
                step(f, Op::ArrayAtBreakTransform, &[7, 10, 18, 18, 6, 6, 17], 1540);
                step(f, Op::BreakVector, &[6, 32, 36, 39], 1541);
                step(f, Op::SubF, &[35, 39, 38], 1542);
                step(f, Op::PelvisSideLean, &[38, 178, 179, 50], 1543);
                step(f, Op::ArrayAtBreakTransform, &[5, 9, 6, 6, 33, 4, 10], 1544);
                step(f, Op::ArrayAtBreakTransform, &[5, 10, 3, 3, 49, 3, 20], 1545);
                step(f, Op::SlerpQ, &[4, 3, 200, 8], 1546);
                step(f, Op::EulerFromQuat, &[8, 9, 9], 1547);
                step(f, Op::BreakVector, &[9, 42, 37, 60], 1548);
                step(f, Op::RemapF, &[63, 172, 171, 199, 173, 19, 52], 1549);
                step(f, Op::SubV, &[25, 6, 31], 1550);
                step(f, Op::RotateVector, &[0, 53, 32], 1551);
                step(f, Op::DotV, &[31, 32, 61], 1552);
                step(f, Op::MulFAddF, &[52, 61, 54, 60, 54, 62], 1553);
                step(f, Op::MakeVector, &[69, 50, 62, 8], 1554);
                step(f, Op::QuatFromEuler, &[8, 9, 10], 1555);
                step(f, Op::MakeTransform, &[34, 10, 50, 7], 1556);
                step(f, Op::SetTransform, &[38, 7, 9, 19, 201], 1557);
                step(f, Op::GetTransformBreakTransform, &[39, 10, 19, 4, 4, 35, 1, 38], 1558);
                step(f, Op::QuatFromAxisAngle, &[54, 54, 9], 1559);
                step(f, Op::DivF, &[174, 217, 40], 1560);
                step(f, Op::QuatScale, &[9, 40, 7], 1561);
                step(f, Op::MulQ, &[1, 7, 5], 1562);
                step(f, Op::MakeTransform, &[35, 5, 50, 12], 1563);
                step(f, Op::SetTransform, &[40, 12, 10, 19, 201], 1564);
                step(f, Op::GetTransformBreakTransform, &[41, 10, 19, 8, 8, 44, 2, 48], 1565);
                step(f, Op::MulQ, &[2, 7, 6], 1566);
                step(f, Op::MakeTransform, &[44, 6, 50, 5], 1567);
                step(f, Op::SetTransform, &[42, 5, 10, 19, 201], 1568);
                step(f, Op::GetTransformBreakTransform, &[43, 10, 19, 14, 14, 7, 3, 36], 1569);
                step(f, Op::MulQ, &[3, 7, 4], 1570);
                step(f, Op::MakeTransform, &[7, 4, 50, 10], 1571);
                step(f, Op::SetTransform, &[44, 10, 10, 19, 201], 1572);
                step(f, Op::GetTransformBreakTransform, &[45, 10, 19, 9, 9, 46, 8, 47], 1573);
                step(f, Op::QuatScale, &[9, 175, 10], 1574);
                step(f, Op::MulQ, &[8, 10, 1], 1575);
                step(f, Op::MakeTransform, &[46, 1, 50, 11], 1576);
                step(f, Op::SetTransform, &[46, 11, 10, 19, 201], 1577);
                step(f, Op::Or, &[1, 2, 8], 1578);
                step(f, Op::Copy(ValueType::Float), &[199, 33], 1579);
                step(f, Op::Copy(ValueType::Int), &[9, 3], 1580);
                1580
            }
            1580 => {
                step(f, Op::ForEachNext(Elem::Bone), &[0, 3, 25, 6, 1, 1623], 1581)
            }
            1581 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 6, 13], 1582);
                step(f, Op::GetParent, &[25, 26], 1583);
                step(f, Op::GetParent, &[26, 27], 1584);
                step(f, Op::GetTransformBreakTransform, &[27, 9, 20, 15, 15, 11, 5, 13], 1585);
                step(f, Op::BreakVector, &[11, 45, 56, 44], 1586);
                step(f, Op::ArrayAtBreakTransform, &[7, 6, 13, 13, 37, 2, 15], 1587);
                step(f, Op::BreakVector, &[37, 49, 72, 53], 1588);
                step(f, Op::ArrayAt(Elem::Float), &[1, 6, 41], 1589);
                step(f, Op::MulFMulF, &[41, 180, 68, 68, 68, 65], 1590);
                step(f, Op::SubF, &[45, 49, 34], 1591);
                step(f, Op::SubF, &[56, 72, 46], 1592);
                step(f, Op::MakeVector, &[34, 46, 199, 16], 1593);
                step(f, Op::DotV, &[16, 16, 51], 1594);
                step(f, Op::SubF, &[65, 51, 66], 1595);
                step(f, Op::SqrtF, &[66, 71], 1596);
                step(f, Op::AddF, &[53, 71, 48], 1597);
                step(f, Op::SubF, &[44, 48, 59], 1598);
                step(f, Op::ArrayAtBreakTransform, &[3, 6, 16, 16, 26, 6, 12], 1599);
                step(f, Op::BreakVector, &[26, 47, 70, 64], 1600);
                step(f, Op::AddF, &[64, 100, 67], 1601);
                step(f, Op::MinF, &[53, 67, 43], 1602);
                step(f, Op::AddF, &[43, 71, 58], 1603);
                step(f, Op::SubF, &[44, 58, 55], 1604);
                step(f, Op::Equals(Elem::Int), &[6, 9, 10], 1605);
                step(f, Op::Select(ValueType::Int), &[10, 10, 9, 5], 1606);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 5, 16], 1607);
                step(f, Op::ArrayAt(Elem::Float), &[2, 5, 57], 1608);
                step(f, Op::RemapF, &[57, 200, 201, 199, 201, 19, 32], 1609);
                step(f, Op::RemapF, &[57, 199, 183, 201, 199, 19, 36], 1610);
                step(f, Op::MaxF, &[32, 36, 35], 1611);
                step(f, Op::Select(ValueType::Float), &[16, 201, 35, 39], 1612);
                step(f, Op::LerpF, &[59, 55, 39, 38], 1613);
                step(f, Op::ArrayAt(Elem::Float), &[2, 6, 37], 1614);
                step(f, Op::RemapF, &[37, 200, 201, 199, 201, 19, 42], 1615);
                step(f, Op::MulF, &[38, 42, 63], 1616);
                step(f, Op::RemapF, &[37, 199, 183, 201, 199, 19, 52], 1617);
                step(f, Op::MulF, &[59, 52, 61], 1618);
                step(f, Op::MaxF, &[63, 61, 60], 1619);
                step(f, Op::Select(ValueType::Float), &[13, 59, 60, 50], 1620);
                step(f, Op::MaxF, &[33, 50, 62], 1621);
                step(f, Op::Copy(ValueType::Float), &[62, 33], 1622);
                step(f, Op::Jump, &[1580], 1623)
            }
            1623 => {
                step(f, Op::ClampF, &[33, 199, 181, 69, 69, 69], 1624);
                step(f, Op::MakeVector, &[24, 199, 199, 14], 1625);
                step(f, Op::MakeVector, &[69, 199, 199, 22], 1626);
                step(f, Op::MakeVector, &[25, 199, 199, 24], 1627);
                step(f, Op::GreaterF, &[69, 24, 9], 1628);
                step(f, Op::Select(ValueType::Float), &[9, 185, 182, 54, 31, 31], 1629);
                step(f, Op::SubV, &[22, 24, 27], 1630);
                step(f, Op::DeltaTime, &[40], 1631);
                step(f, Op::DivFScaleV, &[31, 40, 41, 27, 41, 18], 1632);
                step(f, Op::AddVAddV, &[22, 18, 45, 24, 18, 28], 1633);
                step(f, Op::SubV, &[14, 28, 29], 1634);
                step(f, Op::FloatLerp, &[199, 201, 54, 68], 1635);
                step(f, Op::SubF, &[201, 68, 45], 1636);
                step(f, Op::ScaleV, &[29, 45, 39], 1637);
                step(f, Op::AddV, &[45, 39, 19], 1638);
                step(f, Op::MulF, &[54, 40, 49], 1639);
                step(f, Op::GreaterF, &[49, 199, 15], 1640);
                step(f, Op::DivF, &[68, 49, 56], 1641);
                step(f, Op::Select(ValueType::Float), &[15, 56, 201, 72], 1642);
                step(f, Op::ScaleV, &[27, 72, 23], 1643);
                step(f, Op::SubV, &[19, 23, 41, 41, 41], 1644);
                step(f, Op::BreakVector, &[41, 34, 46, 51], 1645);
                step(f, Op::Select(ValueType::Float), &[8, 69, 34, 24, 24, 24], 1646);
                step(f, Op::Copy(ValueType::Float), &[69, 25], 1647);
                step(f, Op::GetTransformBreakTransform, &[47, 9, 20, 17, 17, 30, 3, 43], 1648);
                step(f, Op::MakeVector, &[199, 199, 24, 21], 1649);
                step(f, Op::SubV, &[30, 21, 42], 1650);
                step(f, Op::MakeTransform, &[42, 3, 50, 18], 1651);
                step(f, Op::SetTransform, &[48, 18, 9, 19, 201], 1652);
                step(f, Op::JumpIfFalse, &[18, 1657], 1653)
            }
            1653 => {
                step(f, Op::GetTransformBreakTransform, &[47, 9, 20, 17, 17, 30, 3, 43], 1654);
                step(f, Op::SubV, &[30, 21, 42], 1655);
                step(f, Op::MakeTransform, &[42, 3, 50, 18], 1656);
                step(f, Op::DrawTransform, &[18, 222, 200], 1657);
                1657
            }
            1657 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1658);
                step(f, Op::Copy(ValueType::Int), &[9, 2], 1659);
                1659
            }
            1659 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 2, 2, 4, 7, 1701], 1660)
            }
            1660 => {
                step(f, Op::GetParent, &[2, 29], 1661);
                step(f, Op::GetParent, &[29, 30], 1662);
                step(f, Op::GetTransformBreakTransform, &[30, 9, 20, 6, 6, 40, 7, 17], 1663);
                step(f, Op::ArrayAtBreakTransform, &[7, 4, 3, 3, 10, 4, 33], 1664);
                step(f, Op::SubV, &[10, 40, 20], 1665);
                step(f, Op::LengthV, &[20, 65], 1666);
                step(f, Op::ArrayAt(Elem::Float), &[1, 4, 66], 1667);
                step(f, Op::MulF, &[66, 193, 48], 1668);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 4, 17], 1669);
                step(f, Op::MulF, &[19, 159, 47], 1670);
                step(f, Op::ArrayAt(Elem::Float), &[2, 4, 70], 1671);
                step(f, Op::ClampF, &[70, 199, 201, 64], 1672);
                step(f, Op::LessF, &[64, 200, 12], 1673);
                step(f, Op::SmoothStepF, &[64, 195, 196, 53], 1674);
                step(f, Op::MulF, &[64, 209, 67], 1675);
                step(f, Op::SinF, &[67, 43], 1676);
                step(f, Op::MaxF, &[53, 43, 71], 1677);
                step(f, Op::Select(ValueType::Float), &[12, 71, 43, 44], 1678);
                step(f, Op::MulF, &[44, 194, 58], 1679);
                step(f, Op::Select(ValueType::Float), &[17, 47, 58, 57], 1680);
                step(f, Op::SubF, &[48, 57, 32], 1681);
                step(f, Op::SubF, &[65, 32, 36], 1682);
                step(f, Op::MaxF, &[36, 199, 35], 1683);
                step(f, Op::MulFAddF, &[35, 35, 39, 35, 57, 55], 1684);
                step(f, Op::DivFSubF, &[39, 55, 38, 65, 38, 42], 1685);
                step(f, Op::DivFScaleV, &[42, 65, 37, 20, 37, 49], 1686);
                step(f, Op::AddV, &[40, 49, 9], 1687);
                step(f, Op::ClampSpatially, &[9, 40, 199, 48, 6], 1688);
                step(f, Op::MakeTransform, &[6, 4, 50, 7], 1689);
                step(f, Op::Equals(Elem::Int), &[4, 9, 14], 1690);
                step(f, Op::Select(ValueType::Vec3), &[14, 58, 57, 25], 1691);
                step(f, Op::Select(ValueType::Vec3), &[14, 53, 59, 31], 1692);
                step(f, Op::ArrayAtBreakTransform, &[5, 4, 4, 4, 32, 9, 8], 1693);
                step(f, Op::ArrayAt(Elem::Vec3), &[3, 4, 34], 1694);
                step(f, Op::KneeVector, &[9, 0, 34, 197, 198, 38], 1695);
                step(f, Op::TwoBoneIK, &[30, 29, 2, 7, 25, 31, 38, 9, 201, 20, 219, 220, 19, 11, 52], 1696);
                step(f, Op::JumpIfFalse, &[18, 1700], 1697)
            }
            1697 => {
                step(f, Op::GetTransformBreakTransform, &[29, 9, 20, 12, 12, 35, 8, 48], 1698);
                step(f, Op::AddV, &[35, 38, 44], 1699);
                step(f, Op::DrawLine, &[35, 44, 200, 60], 1700);
                1700
            }
            1700 => {
                step(f, Op::Jump, &[1659], 1701)
            }
            1701 => {
                step(f, Op::End, &[], 1702)
            }
            _ => return,
        } };
    }
}
