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
    fingerprint: 0x56d76248fc782a9f,
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
                step(f, Op::WorldTransform, &[6], 94);
                step(f, Op::BreakTransform, &[6, 19, 2, 22], 95);
                step(f, Op::Select(ValueType::Transform), &[0, 0, 6, 4], 96);
                step(f, Op::BreakTransform, &[4, 20, 2, 17], 97);
                step(f, Op::SubV, &[19, 20, 21], 98);
                step(f, Op::LengthV, &[21, 183], 99);
                step(f, Op::GreaterF, &[183, 41, 2, 2, 2], 100);
                step(f, Op::MakeRelative, &[4, 6, 5], 101);
                step(f, Op::Select(ValueType::Transform), &[2, 3, 5, 2, 2, 2], 102);
                step(f, Op::InverseT, &[4, 5], 103);
                step(f, Op::MulT, &[6, 5, 1, 1, 1], 104);
                step(f, Op::TransformVector, &[2, 0, 18], 105);
                step(f, Op::InverseT, &[6, 4], 106);
                step(f, Op::DeltaTime, &[184], 107);
                step(f, Op::DivFScaleV, &[160, 184, 182, 21, 182, 22], 108);
                step(f, Op::TransformVector, &[4, 22, 17], 109);
                step(f, Op::BreakVector, &[17, 183, 185, 186], 110);
                step(f, Op::BreakVector, &[21, 186, 187, 188], 111);
                step(f, Op::AddF, &[2, 188, 186], 112);
                step(f, Op::Select(ValueType::Float), &[2, 158, 186, 187], 113);
                step(f, Op::MakeVector, &[183, 185, 158, 19], 114);
                step(f, Op::LengthV, &[19, 188], 115);
                step(f, Op::MulFMulF, &[188, 145, 186, 186, 184, 188], 116);
                step(f, Op::NegF, &[188, 184], 117);
                step(f, Op::ClampF, &[187, 184, 188, 186], 118);
                step(f, Op::MulF, &[186, 182, 184], 119);
                step(f, Op::MakeVector, &[183, 185, 184, 20], 120);
                step(f, Op::Select(ValueType::Vec3), &[2, 18, 20, 22], 121);
                step(f, Op::VectorLerp, &[18, 22, 42, 158, 0, 0, 0], 122);
                step(f, Op::TransformVector, &[2, 1, 17], 123);
                step(f, Op::TransformVector, &[2, 0, 18], 124);
                step(f, Op::Select(ValueType::Vec3), &[2, 18, 20, 22], 125);
                step(f, Op::VectorLerp, &[17, 22, 43, 158, 1, 1, 1], 126);
                step(f, Op::LengthV, &[22, 0, 0, 0], 127);
                step(f, Op::SubF, &[187, 186, 188], 128);
                step(f, Op::NegF, &[146, 182], 129);
                step(f, Op::ClampF, &[188, 182, 146, 3], 130);
                step(f, Op::SubF, &[188, 3, 1, 1, 1, 3, 3], 131);
                step(f, Op::JumpIfFalse, &[2, 144], 132)
            }
            132 => {
                step(f, Op::Copy(ValueType::Int), &[2, 6], 133);
                133
            }
            133 => {
                step(f, Op::ForEachNext(Elem::Bone), &[0, 6, 13, 8, 7, 143], 134)
            }
            134 => {
                step(f, Op::ArrayAt(Elem::Transform), &[8, 8, 5], 135);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 8, 5], 136);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 8, 5], 137);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 8, 5], 138);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 8, 5], 139);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 8, 5], 140);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 8, 5], 141);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 8, 5], 142);
                step(f, Op::Jump, &[133], 143)
            }
            143 => {
                step(f, Op::Copy(ValueType::Float), &[158, 22], 144);
                144
            }
            144 => {
                step(f, Op::Copy(ValueType::Transform), &[6, 0], 145);
                step(f, Op::Copy(ValueType::Bool), &[9, 0], 146);
                step(f, Op::JumpIfFalse, &[8, 151], 147)
            }
            147 => {
                step(f, Op::GetTransformBreakTransform, &[33, 2, 9, 4, 4, 21, 2, 19], 148);
                step(f, Op::ScaleV, &[0, 161, 18], 149);
                step(f, Op::AddV, &[21, 18, 20], 150);
                step(f, Op::DrawArrow, &[21, 20, 159, 8], 151);
                151
            }
            151 => {
                step(f, Op::Copy(ValueType::Float), &[158, 183], 152);
                step(f, Op::Copy(ValueType::Float), &[160, 184], 153);
                step(f, Op::Copy(ValueType::Bool), &[10, 11], 154);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 155);
                step(f, Op::MakeVector, &[158, 158, 64, 17], 156);
                156
            }
            156 => {
                step(f, Op::ForEachNext(Elem::Transform), &[8, 7, 5, 8, 6, 165], 157)
            }
            157 => {
                step(f, Op::BreakTransform, &[5, 22, 2, 19], 158);
                step(f, Op::TransformPoint, &[2, 22, 18], 159);
                step(f, Op::LerpV, &[18, 22, 160, 20], 160);
                step(f, Op::AddVSubV, &[20, 17, 21, 20, 17, 19], 161);
                step(f, Op::LineTrace, &[21, 19, 12, 18, 22, 185], 162);
                step(f, Op::JumpIfFalse, &[12, 164], 163)
            }
            163 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 11], 164);
                164
            }
            164 => {
                step(f, Op::Jump, &[156, 11, 11], 165)
            }
            165 => {
                step(f, Op::Or, &[11, 7, 12], 166);
                step(f, Op::NotEquals(Elem::Bool), &[12, 5, 13], 167);
                step(f, Op::JumpIfFalse, &[13, 191], 168)
            }
            168 => {
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 14], 169);
                step(f, Op::JumpIfFalse, &[14, 191, 1, 1], 170)
            }
            170 => {
                step(f, Op::Copy(ValueType::Int), &[2, 6], 171);
                171
            }
            171 => {
                step(f, Op::ForNext, &[6, 1, 8, 191], 172)
            }
            172 => {
                step(f, Op::AddFMulF, &[183, 184, 186, 186, 159, 187], 173);
                step(f, Op::Copy(ValueType::Bool), &[10, 15], 174);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 175);
                step(f, Op::MakeVector, &[158, 158, 64, 20], 176);
                176
            }
            176 => {
                step(f, Op::ForEachNext(Elem::Transform), &[8, 7, 6, 8, 9, 185], 177)
            }
            177 => {
                step(f, Op::BreakTransform, &[6, 18, 2, 19], 178);
                step(f, Op::TransformPoint, &[2, 18, 21], 179);
                step(f, Op::LerpV, &[21, 18, 187, 22], 180);
                step(f, Op::AddVSubV, &[22, 20, 17, 22, 20, 19], 181);
                step(f, Op::LineTrace, &[17, 19, 16, 18, 21, 182], 182);
                step(f, Op::JumpIfFalse, &[16, 184], 183)
            }
            183 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 15], 184);
                184
            }
            184 => {
                step(f, Op::Jump, &[176, 15, 15], 185)
            }
            185 => {
                step(f, Op::Equals(Elem::Bool), &[15, 6, 16], 186);
                step(f, Op::JumpIfFalse, &[16, 189], 187)
            }
            187 => {
                step(f, Op::Copy(ValueType::Float), &[187, 183], 188);
                step(f, Op::Jump, &[190], 189)
            }
            189 => {
                step(f, Op::Copy(ValueType::Float), &[187, 184], 190);
                190
            }
            190 => {
                step(f, Op::Jump, &[171], 191)
            }
            191 => {
                step(f, Op::Select(ValueType::Float), &[5, 162, 160, 188], 192);
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 14], 193);
                step(f, Op::AddFMulF, &[183, 184, 186, 186, 159, 185], 194);
                step(f, Op::Select(ValueType::Float), &[14, 185, 159, 182], 195);
                step(f, Op::Select(ValueType::Float), &[13, 182, 158, 187], 196);
                step(f, Op::MulF, &[188, 187, 183], 197);
                step(f, Op::DeltaTime, &[184], 198);
                step(f, Op::DivF, &[184, 150, 186], 199);
                step(f, Op::MulFAddF, &[183, 186, 185, 26, 185, 187], 200);
                step(f, Op::ClampF, &[187, 158, 160, 188], 201);
                step(f, Op::Select(ValueType::Float), &[12, 162, 160, 184], 202);
                step(f, Op::SubF, &[160, 182, 183], 203);
                step(f, Op::Select(ValueType::Float), &[13, 183, 160, 185], 204);
                step(f, Op::MulFMulF, &[184, 185, 187, 187, 186, 182], 205);
                step(f, Op::AddF, &[188, 182, 183], 206);
                step(f, Op::ClampF, &[183, 158, 160, 26], 207);
                step(f, Op::SmoothStepF, &[26, 158, 160, 184], 208);
                step(f, Op::AddFMulF, &[27, 184, 185, 185, 159, 186], 209);
                step(f, Op::SubFMulF, &[160, 186, 187, 187, 187, 182], 210);
                step(f, Op::SubF, &[160, 182, 28, 28, 28], 211);
                step(f, Op::Copy(ValueType::Float), &[184, 27, 26, 26], 212);
                step(f, Op::GreaterF, &[27, 158, 15], 213);
                step(f, Op::TransformVector, &[2, 3, 22], 214);
                step(f, Op::Select(ValueType::Vec3), &[15, 22, 0, 3, 3, 3], 215);
                step(f, Op::LerpV, &[0, 3, 27, 17], 216);
                step(f, Op::Select(ValueType::Vec3), &[15, 17, 0, 2, 2, 2], 217);
                step(f, Op::Copy(ValueType::Bool), &[12, 5], 218);
                step(f, Op::Copy(ValueType::Bool), &[11, 6], 219);
                step(f, Op::Copy(ValueType::Bool), &[10, 7], 220);
                step(f, Op::SubFMulF, &[160, 28, 188, 1, 188, 183], 221);
                step(f, Op::SubFMulF, &[3, 2, 185, 185, 188, 186], 222);
                step(f, Op::AddFMulF, &[2, 186, 187, 187, 188, 182], 223);
                step(f, Op::SubFAddF, &[187, 182, 184, 183, 184, 189], 224);
                step(f, Op::AddF, &[4, 189, 190], 225);
                step(f, Op::Copy(ValueType::Float), &[7, 191], 226);
                step(f, Op::Copy(ValueType::Float), &[8, 192], 227);
                step(f, Op::Copy(ValueType::Float), &[4, 193], 228);
                step(f, Op::Copy(ValueType::Float), &[147, 194], 229);
                step(f, Op::Copy(ValueType::Float), &[58, 195], 230);
                step(f, Op::SubF, &[190, 193, 196], 231);
                step(f, Op::DeltaTime, &[197], 232);
                step(f, Op::DivF, &[196, 197, 198], 233);
                step(f, Op::MulFAddF, &[198, 195, 199, 190, 199, 200], 234);
                step(f, Op::MulF, &[198, 163, 201], 235);
                step(f, Op::DivF, &[164, 194, 202], 236);
                step(f, Op::DivFSubF, &[201, 202, 203, 200, 203, 204], 237);
                step(f, Op::AddF, &[193, 199, 205], 238);
                step(f, Op::SubFAddF, &[191, 205, 206, 206, 203, 207], 239);
                step(f, Op::SubFMulF, &[192, 198, 208, 202, 207, 209], 240);
                step(f, Op::AddFMulF, &[208, 209, 210, 210, 197, 211], 241);
                step(f, Op::AddF, &[207, 211, 212], 242);
                step(f, Op::FloatLerp, &[158, 160, 202, 213], 243);
                step(f, Op::SubFMulF, &[160, 213, 214, 212, 214, 215], 244);
                step(f, Op::AddF, &[204, 215, 216], 245);
                step(f, Op::Copy(ValueType::Float), &[216, 217], 246);
                step(f, Op::MulFSubF, &[202, 211, 218, 208, 218, 219], 247);
                step(f, Op::MulFAddF, &[219, 214, 220, 198, 220, 221], 248);
                step(f, Op::Copy(ValueType::Float), &[221, 222], 249);
                step(f, Op::SubFAddF, &[190, 217, 6, 6, 182, 5, 5, 5, 6, 6], 250);
                step(f, Op::Copy(ValueType::Float), &[182, 2], 251);
                step(f, Op::SubFMulF, &[3, 2, 185, 185, 188, 186], 252);
                step(f, Op::AddFMulF, &[2, 186, 187, 187, 188, 182], 253);
                step(f, Op::SubFAddF, &[187, 182, 184, 183, 184, 189], 254);
                step(f, Op::AddF, &[4, 189, 190], 255);
                step(f, Op::Copy(ValueType::Float), &[7, 191], 256);
                step(f, Op::Copy(ValueType::Float), &[8, 192], 257);
                step(f, Op::Copy(ValueType::Float), &[4, 193], 258);
                step(f, Op::Copy(ValueType::Float), &[147, 194], 259);
                step(f, Op::Copy(ValueType::Float), &[58, 195], 260);
                step(f, Op::SubF, &[190, 193, 196], 261);
                step(f, Op::DeltaTime, &[197], 262);
                step(f, Op::DivF, &[196, 197, 198], 263);
                step(f, Op::MulFAddF, &[198, 195, 199, 190, 199, 200], 264);
                step(f, Op::MulF, &[198, 163, 201], 265);
                step(f, Op::DivF, &[164, 194, 202], 266);
                step(f, Op::DivFSubF, &[201, 202, 203, 200, 203, 204], 267);
                step(f, Op::AddF, &[193, 199, 205], 268);
                step(f, Op::SubFAddF, &[191, 205, 206, 206, 203, 207], 269);
                step(f, Op::SubFMulF, &[192, 198, 208, 202, 207, 209], 270);
                step(f, Op::AddFMulF, &[208, 209, 210, 210, 197, 211], 271);
                step(f, Op::AddF, &[207, 211, 212], 272);
                step(f, Op::FloatLerp, &[158, 160, 202, 213], 273);
                step(f, Op::SubFMulF, &[160, 213, 214, 212, 214, 215], 274);
                step(f, Op::AddF, &[204, 215, 216], 275);
                step(f, Op::Copy(ValueType::Float), &[216, 217], 276);
                step(f, Op::MulFSubF, &[202, 211, 218, 208, 218, 219], 277);
                step(f, Op::MulFAddF, &[219, 214, 220, 198, 220, 221], 278);
                step(f, Op::Copy(ValueType::Float), &[221, 222], 279);
                step(f, Op::Copy(ValueType::Float), &[217, 7], 280);
                step(f, Op::Copy(ValueType::Float), &[7, 191], 281);
                step(f, Op::Copy(ValueType::Float), &[8, 192], 282);
                step(f, Op::Copy(ValueType::Float), &[4, 193], 283);
                step(f, Op::Copy(ValueType::Float), &[147, 194], 284);
                step(f, Op::Copy(ValueType::Float), &[58, 195], 285);
                step(f, Op::SubF, &[190, 193, 196], 286);
                step(f, Op::DeltaTime, &[197], 287);
                step(f, Op::DivF, &[196, 197, 198], 288);
                step(f, Op::MulFAddF, &[198, 195, 199, 190, 199, 200], 289);
                step(f, Op::MulF, &[198, 163, 201], 290);
                step(f, Op::DivF, &[164, 194, 202], 291);
                step(f, Op::DivFSubF, &[201, 202, 203, 200, 203, 204], 292);
                step(f, Op::AddF, &[193, 199, 205], 293);
                step(f, Op::SubFAddF, &[191, 205, 206, 206, 203, 207], 294);
                step(f, Op::SubFMulF, &[192, 198, 208, 202, 207, 209], 295);
                step(f, Op::AddFMulF, &[208, 209, 210, 210, 197, 211], 296);
                step(f, Op::AddF, &[207, 211, 212], 297);
                step(f, Op::FloatLerp, &[158, 160, 202, 213], 298);
                step(f, Op::SubFMulF, &[160, 213, 214, 212, 214, 215], 299);
                step(f, Op::AddF, &[204, 215, 216], 300);
                step(f, Op::Copy(ValueType::Float), &[216, 217], 301);
                step(f, Op::MulFSubF, &[202, 211, 218, 208, 218, 219], 302);
                step(f, Op::MulFAddF, &[219, 214, 220, 198, 220, 221], 303);
                step(f, Op::Copy(ValueType::Float), &[221, 222], 304);
                step(f, Op::Copy(ValueType::Float), &[222, 8], 305);
                step(f, Op::Copy(ValueType::Float), &[190, 4], 306);
                step(f, Op::LengthV, &[4, 185], 307);
                step(f, Op::GreaterF, &[185, 35, 16], 308);
                step(f, Op::LengthV, &[2, 186], 309);
                step(f, Op::GreaterF, &[186, 35, 14], 310);
                step(f, Op::And, &[16, 14, 13], 311);
                step(f, Op::Select(ValueType::Vec3), &[16, 4, 7, 18], 312);
                step(f, Op::MovementAngleOffset, &[18, 17, 158, 165, 165, 166, 46, 167, 188, 17, 17], 313);
                step(f, Op::SubFAddF, &[188, 17, 182, 182, 168, 187], 314);
                step(f, Op::DivF, &[187, 169, 183], 315);
                step(f, Op::FractF, &[183, 184], 316);
                step(f, Op::MulFSubF, &[184, 169, 189, 189, 168, 196, 196, 196], 317);
                step(f, Op::AbsF, &[196, 195], 318);
                step(f, Op::Select(ValueType::Vec3), &[14, 2, 7, 19], 319);
                step(f, Op::MovementAngleOffset, &[19, 17, 158, 165, 165, 166, 46, 167, 194, 17, 17], 320);
                step(f, Op::SubFAddF, &[194, 17, 201, 201, 168, 200], 321);
                step(f, Op::DivF, &[200, 169, 193], 322);
                step(f, Op::FractF, &[193, 199], 323);
                step(f, Op::MulFSubF, &[199, 169, 191, 191, 168, 205, 205, 205], 324);
                step(f, Op::AbsF, &[205, 203], 325);
                step(f, Op::MaxF, &[195, 203, 206], 326);
                step(f, Op::SubFAddF, &[194, 188, 192, 192, 168, 209], 327);
                step(f, Op::DivF, &[209, 169, 197], 328);
                step(f, Op::FractF, &[197, 210], 329);
                step(f, Op::MulFSubF, &[210, 169, 207, 207, 168, 213, 213, 213], 330);
                step(f, Op::AbsF, &[213, 212], 331);
                step(f, Op::MaxF, &[206, 212, 204], 332);
                step(f, Op::DeltaTime, &[215], 333);
                step(f, Op::DivF, &[58, 215, 216], 334);
                step(f, Op::TransformVector, &[2, 9, 21], 335);
                step(f, Op::BreakVector, &[21, 217, 202, 211], 336);
                step(f, Op::NegF, &[217, 208], 337);
                step(f, Op::Atan2F, &[208, 202, 218], 338);
                step(f, Op::MulF, &[216, 218, 214], 339);
                step(f, Op::QuatFromAxisAngle, &[10, 214, 2], 340);
                step(f, Op::TransformVector, &[2, 4, 20], 341);
                step(f, Op::FloatLerp, &[158, 160, 42, 219], 342);
                step(f, Op::GreaterF, &[219, 158, 15], 343);
                step(f, Op::AddFMulF, &[160, 216, 198, 42, 198, 220], 344);
                step(f, Op::FloatLerp, &[158, 160, 220, 221], 345);
                step(f, Op::DivF, &[221, 219, 222], 346);
                step(f, Op::Select(ValueType::Float), &[15, 222, 198, 190], 347);
                step(f, Op::LerpV, &[20, 2, 190, 22], 348);
                step(f, Op::RotateVector, &[2, 22, 17], 349);
                step(f, Op::LengthV, &[17, 185], 350);
                step(f, Op::GreaterF, &[185, 35, 12], 351);
                step(f, Op::Select(ValueType::Vec3), &[12, 17, 7, 18], 352);
                step(f, Op::MovementAngleOffset, &[18, 17, 158, 165, 165, 166, 46, 167, 182, 17, 17], 353);
                step(f, Op::SubFAddF, &[182, 17, 187, 187, 168, 183], 354);
                step(f, Op::DivF, &[183, 169, 184], 355);
                step(f, Op::FractF, &[184, 189], 356);
                step(f, Op::MulFSubF, &[189, 169, 196, 196, 168, 201, 201, 201], 357);
                step(f, Op::AbsF, &[201, 200], 358);
                step(f, Op::SubFAddF, &[182, 194, 193, 193, 168, 199], 359);
                step(f, Op::DivF, &[199, 169, 191], 360);
                step(f, Op::FractF, &[191, 205], 361);
                step(f, Op::MulFSubF, &[205, 169, 195, 195, 168, 203, 203, 203], 362);
                step(f, Op::AbsF, &[203, 188], 363);
                step(f, Op::MaxF, &[200, 188, 192], 364);
                step(f, Op::MaxF, &[204, 192, 209], 365);
                step(f, Op::LessF, &[209, 170, 11], 366);
                step(f, Op::And, &[13, 11, 17], 367);
                step(f, Op::SubV, &[2, 20, 21], 368);
                step(f, Op::DotV, &[20, 21, 197], 369);
                step(f, Op::NegF, &[197, 210], 370);
                step(f, Op::DotV, &[21, 21, 207], 371);
                step(f, Op::DivF, &[210, 207, 206], 372);
                step(f, Op::ClampF, &[206, 158, 190, 212], 373);
                step(f, Op::LerpV, &[20, 2, 212, 22], 374);
                step(f, Op::LengthV, &[22, 211], 375);
                step(f, Op::LessF, &[211, 35, 11], 376);
                step(f, Op::Not, &[11, 13], 377);
                step(f, Op::And, &[17, 13, 11], 378);
                step(f, Op::Not, &[16, 13], 379);
                step(f, Op::Not, &[14, 17], 380);
                step(f, Op::And, &[13, 17, 16], 381);
                step(f, Op::Not, &[12, 13], 382);
                step(f, Op::And, &[16, 13, 17], 383);
                step(f, Op::Or, &[11, 17, 12], 384);
                step(f, Op::JumpIfFalse, &[12, 402], 385)
            }
            385 => {
                step(f, Op::MulF, &[44, 215, 217], 386);
                step(f, Op::GreaterF, &[217, 158, 13], 387);
                step(f, Op::FloatLerp, &[158, 160, 44, 202], 388);
                step(f, Op::SubF, &[160, 202, 208], 389);
                step(f, Op::DivF, &[208, 202, 214], 390);
                step(f, Op::DivFSubF, &[160, 217, 220, 214, 220, 221], 391);
                step(f, Op::AddF, &[216, 221, 198], 392);
                step(f, Op::Select(ValueType::Float), &[13, 198, 158, 222], 393);
                step(f, Op::MulFAddF, &[213, 222, 185, 194, 185, 187], 394);
                step(f, Op::SinF, &[187, 183], 395);
                step(f, Op::NegF, &[183, 184], 396);
                step(f, Op::CosF, &[187, 189], 397);
                step(f, Op::MakeVector, &[184, 189, 158, 17], 398);
                step(f, Op::Select(ValueType::Vec3), &[14, 17, 7, 18], 399);
                step(f, Op::MovementAngleOffset, &[18, 17, 158, 44, 45, 166, 168, 167, 196], 400);
                step(f, Op::Copy(ValueType::Float), &[196, 17], 401);
                step(f, Op::Jump, &[450], 402)
            }
            402 => {
                step(f, Op::DivF, &[215, 48, 201], 403);
                step(f, Op::AddF, &[201, 159, 182], 404);
                step(f, Op::FloorF, &[182, 193], 405);
                step(f, Op::MaxF, &[193, 160, 199], 406);
                step(f, Op::ToInt, &[199, 8, 8, 8], 407);
                step(f, Op::Copy(ValueType::Int), &[2, 9], 408);
                step(f, Op::MulFSubF, &[48, 159, 191, 58, 191, 205], 409);
                step(f, Op::DivF, &[205, 215, 195], 410);
                step(f, Op::DivF, &[44, 199, 203], 411);
                step(f, Op::DivFSubF, &[45, 199, 188, 166, 47, 200], 412);
                step(f, Op::GreaterF, &[47, 158, 16], 413);
                413
            }
            413 => {
                step(f, Op::ForNext, &[9, 8, 7, 450], 414)
            }
            414 => {
                step(f, Op::ToFloat, &[7, 192], 415);
                step(f, Op::AddF, &[192, 160, 204], 416);
                step(f, Op::DivF, &[204, 199, 209], 417);
                step(f, Op::AddF, &[209, 195, 197], 418);
                step(f, Op::SubFMulF, &[197, 160, 207, 207, 218, 210], 419);
                step(f, Op::QuatFromAxisAngle, &[10, 210, 2], 420);
                step(f, Op::MulF, &[42, 197, 190], 421);
                step(f, Op::FloatLerp, &[158, 160, 190, 206], 422);
                step(f, Op::DivF, &[206, 219, 212], 423);
                step(f, Op::Select(ValueType::Float), &[15, 212, 197, 211], 424);
                step(f, Op::LerpV, &[20, 2, 211, 21], 425);
                step(f, Op::RotateVector, &[2, 21, 22], 426);
                step(f, Op::LengthV, &[22, 202], 427);
                step(f, Op::GreaterF, &[202, 35, 11], 428);
                step(f, Op::Select(ValueType::Vec3), &[11, 22, 7, 17], 429);
                step(f, Op::MulFMulF, &[215, 197, 208, 11, 208, 217], 430);
                step(f, Op::AddF, &[15, 217, 214], 431);
                step(f, Op::FractF, &[214, 220], 432);
                step(f, Op::MulF, &[220, 163, 216], 433);
                step(f, Op::FractF, &[216, 221], 434);
                step(f, Op::LessF, &[221, 167, 17], 435);
                step(f, Op::MovementAngleOffset, &[17, 17, 158, 165, 165, 166, 46, 167, 198, 17, 17], 436);
                step(f, Op::SubFAddF, &[198, 17, 213, 213, 168, 222], 437);
                step(f, Op::DivF, &[222, 169, 185], 438);
                step(f, Op::FractF, &[185, 194], 439);
                step(f, Op::MulFSubF, &[194, 169, 183, 183, 168, 187, 187, 187], 440);
                step(f, Op::AbsF, &[187, 184], 441);
                step(f, Op::SmoothStepF, &[184, 200, 166, 189], 442);
                step(f, Op::GreaterF, &[184, 166, 12], 443);
                step(f, Op::Select(ValueType::Float), &[12, 160, 158, 196], 444);
                step(f, Op::Select(ValueType::Float), &[16, 189, 196, 201], 445);
                step(f, Op::Select(ValueType::Float), &[17, 158, 201, 182], 446);
                step(f, Op::LerpF, &[203, 188, 182, 193], 447);
                step(f, Op::MovementAngleOffset, &[17, 17, 220, 193, 193, 166, 46, 167, 191], 448);
                step(f, Op::Copy(ValueType::Float), &[191, 17], 449);
                step(f, Op::Jump, &[413], 450)
            }
            450 => {
                step(f, Op::QuatFromAxisAngle, &[10, 17, 0, 0, 0], 451);
                step(f, Op::SinF, &[17, 205], 452);
                step(f, Op::AbsF, &[205, 192], 453);
                step(f, Op::RemapF, &[192, 49, 50, 158, 160, 9, 204], 454);
                step(f, Op::BreakVector, &[19, 209, 207, 210], 455);
                step(f, Op::AbsF, &[209, 190], 456);
                step(f, Op::DivF, &[190, 186, 206], 457);
                step(f, Op::RemapF, &[206, 49, 50, 158, 160, 9, 212], 458);
                step(f, Op::TransformVector, &[2, 9, 18], 459);
                step(f, Op::DistanceV, &[18, 9, 211], 460);
                step(f, Op::DivF, &[211, 215, 202], 461);
                step(f, Op::RemapF, &[202, 54, 55, 160, 158, 9, 197], 462);
                step(f, Op::MulF, &[212, 197, 208], 463);
                step(f, Op::MaxF, &[204, 208, 18, 18, 18], 464);
                step(f, Op::Copy(ValueType::Vec3), &[2, 4], 465);
                step(f, Op::TransformVector, &[2, 5, 21], 466);
                step(f, Op::BreakTransform, &[2, 22, 2, 17], 467);
                step(f, Op::DeltaTime, &[217], 468);
                step(f, Op::DivFScaleV, &[160, 217, 214, 22, 214, 20], 469);
                step(f, Op::NegV, &[20, 5], 470);
                step(f, Op::SubV, &[5, 21, 19], 471);
                step(f, Op::AddF, &[21, 217, 216], 472);
                step(f, Op::DivFScaleV, &[21, 216, 221, 19, 221, 18], 473);
                step(f, Op::AddV, &[21, 18, 17], 474);
                step(f, Op::DivFScaleV, &[217, 216, 198, 19, 198, 20], 475);
                step(f, Op::AddV, &[5, 20, 18], 476);
                step(f, Op::DotV, &[17, 18, 213], 477);
                step(f, Op::LessF, &[213, 158, 13], 478);
                step(f, Op::TransformVector, &[2, 9, 21], 479);
                step(f, Op::DistanceV, &[21, 9, 222], 480);
                step(f, Op::SubV, &[18, 17, 19], 481);
                step(f, Op::DotV, &[17, 19, 185], 482);
                step(f, Op::NegF, &[185, 194], 483);
                step(f, Op::DotV, &[19, 19, 183], 484);
                step(f, Op::DivF, &[194, 183, 187], 485);
                step(f, Op::ClampF, &[187, 158, 160, 184], 486);
                step(f, Op::SubFMulF, &[160, 184, 189, 217, 189, 196], 487);
                step(f, Op::DivF, &[222, 196, 201], 488);
                step(f, Op::RemapF, &[201, 54, 55, 158, 160, 9, 182], 489);
                step(f, Op::BreakVector, &[18, 193, 220, 191], 490);
                step(f, Op::NegF, &[193, 188], 491);
                step(f, Op::Atan2F, &[188, 220, 195], 492);
                step(f, Op::AbsF, &[195, 199], 493);
                step(f, Op::RemapF, &[199, 113, 114, 158, 160, 9, 200], 494);
                step(f, Op::MulF, &[182, 200, 203], 495);
                step(f, Op::DivF, &[222, 217, 218], 496);
                step(f, Op::RemapF, &[218, 54, 55, 158, 160, 9, 219], 497);
                step(f, Op::BreakVector, &[22, 205, 192, 207], 498);
                step(f, Op::NegF, &[192, 210], 499);
                step(f, Op::Atan2F, &[205, 210, 209], 500);
                step(f, Op::AbsF, &[209, 186], 501);
                step(f, Op::RemapF, &[186, 113, 114, 158, 160, 9, 190], 502);
                step(f, Op::MulF, &[219, 190, 206], 503);
                step(f, Op::Select(ValueType::Float), &[13, 203, 206, 211], 504);
                step(f, Op::FloatLerp, &[19, 158, 115, 215], 505);
                step(f, Op::MaxF, &[211, 215, 202], 506);
                step(f, Op::AbsF, &[20, 197], 507);
                step(f, Op::GreaterEqualF, &[197, 114, 14], 508);
                step(f, Op::LessF, &[186, 114, 11], 509);
                step(f, Op::And, &[14, 11, 12], 510);
                step(f, Op::SubF, &[197, 114, 212], 511);
                step(f, Op::SubF, &[197, 186, 204], 512);
                step(f, Op::DivFSubF, &[212, 204, 208, 160, 208, 214], 513);
                step(f, Op::MulF, &[115, 214, 221], 514);
                step(f, Op::FloatLerp, &[160, 158, 221, 216], 515);
                step(f, Op::MulF, &[219, 216, 198], 516);
                step(f, Op::Select(ValueType::Float), &[12, 198, 158, 213], 517);
                step(f, Op::MaxF, &[202, 213, 19, 19, 19], 518);
                step(f, Op::Select(ValueType::Float), &[13, 195, 209, 20, 20, 20, 5, 5], 519);
                step(f, Op::Copy(ValueType::Float), &[217, 21], 520);
                step(f, Op::Copy(ValueType::Bool), &[9, 17], 521);
                step(f, Op::Copy(ValueType::Int), &[2, 6], 522);
                522
            }
            522 => {
                step(f, Op::ForEachNext(Elem::Bool), &[0, 6, 15, 7, 8, 527], 523)
            }
            523 => {
                step(f, Op::Not, &[15, 16], 524);
                step(f, Op::JumpIfFalse, &[16, 526], 525)
            }
            525 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 17], 526);
                526
            }
            526 => {
                step(f, Op::Jump, &[522, 17, 17], 527)
            }
            527 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 11], 528);
                step(f, Op::Copy(ValueType::Int), &[2, 9], 529);
                529
            }
            529 => {
                step(f, Op::ForEachNext(Elem::Bone), &[0, 9, 15, 7, 8, 541], 530)
            }
            530 => {
                step(f, Op::ArrayAtBreakTransform, &[0, 7, 4, 4, 20, 2, 21], 531);
                step(f, Op::BreakVector, &[20, 185, 183, 194], 532);
                step(f, Op::MakeVector, &[185, 183, 158, 17], 533);
                step(f, Op::ArrayAtBreakTransform, &[8, 7, 5, 5, 19, 2, 18], 534);
                step(f, Op::BreakVector, &[19, 187, 184, 189], 535);
                step(f, Op::MakeVector, &[187, 184, 158, 22], 536);
                step(f, Op::DistanceV, &[17, 22, 196], 537);
                step(f, Op::GreaterF, &[196, 37, 14], 538);
                step(f, Op::JumpIfFalse, &[14, 540], 539)
            }
            539 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 11], 540);
                540
            }
            540 => {
                step(f, Op::Jump, &[529, 11, 11], 541)
            }
            541 => {
                step(f, Op::And, &[17, 11, 12], 542);
                step(f, Op::LengthV, &[2, 201], 543);
                step(f, Op::GreaterF, &[201, 35, 3], 544);
                step(f, Op::GreaterF, &[0, 35, 13], 545);
                step(f, Op::Or, &[3, 13, 15], 546);
                step(f, Op::Not, &[15, 16], 547);
                step(f, Op::And, &[12, 16, 14], 548);
                step(f, Op::DeltaTime, &[191], 549);
                step(f, Op::MulFAddF, &[191, 40, 193, 15, 193, 188], 550);
                step(f, Op::GreaterF, &[15, 159, 11], 551);
                step(f, Op::AddF, &[39, 159, 220], 552);
                step(f, Op::Select(ValueType::Float), &[11, 220, 39, 199], 553);
                step(f, Op::MinF, &[188, 199, 182], 554);
                step(f, Op::NotEquals(Elem::Bool), &[16, 4, 13], 555);
                step(f, Op::Not, &[12, 15], 556);
                step(f, Op::And, &[13, 15, 11], 557);
                step(f, Op::SubF, &[16, 35, 200], 558);
                step(f, Op::SubF, &[16, 201, 222], 559);
                step(f, Op::DivF, &[200, 222, 218], 560);
                step(f, Op::ClampF, &[218, 158, 160, 207], 561);
                step(f, Op::MulF, &[11, 207, 192], 562);
                step(f, Op::RemapF, &[201, 35, 36, 158, 160, 9, 205], 563);
                step(f, Op::MaxF, &[205, 12, 210], 564);
                step(f, Op::Select(ValueType::Float), &[17, 160, 210, 190], 565);
                step(f, Op::Select(ValueType::Float), &[16, 38, 190, 203], 566);
                step(f, Op::Select(ValueType::Float), &[12, 205, 203, 206], 567);
                step(f, Op::SubFMulF, &[160, 27, 211, 206, 211, 215], 568);
                step(f, Op::LerpF, &[29, 52, 18, 186], 569);
                step(f, Op::RemapF, &[201, 32, 33, 30, 31, 9, 197], 570);
                step(f, Op::LerpF, &[197, 51, 18, 204], 571);
                step(f, Op::MaxF, &[201, 34, 212], 572);
                step(f, Op::DivF, &[204, 212, 9], 573);
                step(f, Op::AddF, &[186, 9, 10], 574);
                step(f, Op::DivFSubF, &[215, 10, 208, 160, 207, 214], 575);
                step(f, Op::MulFAddF, &[208, 214, 221, 192, 221, 216], 576);
                step(f, Op::MulFAddF, &[216, 163, 219, 11, 208, 198], 577);
                step(f, Op::Select(ValueType::Float), &[11, 219, 198, 202], 578);
                step(f, Op::DivF, &[163, 202, 213], 579);
                step(f, Op::GreaterF, &[202, 158, 13], 580);
                step(f, Op::CycleStep, &[15, 213, 158, 13, 195, 209], 581);
                step(f, Op::Select(ValueType::Float), &[14, 182, 195, 15, 15, 15], 582);
                step(f, Op::Copy(ValueType::Float), &[208, 11, 3, 3, 9, 9, 10, 10], 583);
                step(f, Op::Copy(ValueType::Int), &[2, 6], 584);
                step(f, Op::DivF, &[186, 10, 217], 585);
                step(f, Op::MulFMulF, &[14, 207, 194, 191, 159, 183], 586);
                step(f, Op::SubF, &[217, 13, 185], 587);
                step(f, Op::MaxF, &[185, 158, 189], 588);
                step(f, Op::DivFSubF, &[189, 217, 184, 160, 18, 187], 589);
                step(f, Op::SubFMulF, &[160, 19, 196, 187, 196, 193], 590);
                step(f, Op::DivFSubF, &[58, 191, 220, 159, 220, 188], 591);
                step(f, Op::MulFMulF, &[184, 193, 199, 199, 211, 200], 592);
                step(f, Op::MulFMulF, &[200, 143, 222, 222, 188, 218], 593);
                step(f, Op::SubF, &[160, 218, 197], 594);
                594
            }
            594 => {
                step(f, Op::ForEachNext(Elem::Bone), &[0, 6, 14, 8, 7, 630], 595)
            }
            595 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 8, 204], 596);
                step(f, Op::ToFloat, &[8, 212], 597);
                step(f, Op::MulFAddF, &[212, 159, 192, 15, 192, 221], 598);
                step(f, Op::FractF, &[221, 216], 599);
                step(f, Op::SubF, &[204, 216, 198], 600);
                step(f, Op::GreaterF, &[198, 159, 15], 601);
                step(f, Op::ArrayAt(Elem::Float), &[2, 8, 219], 602);
                step(f, Op::Select(ValueType::Float), &[15, 158, 219, 202], 603);
                step(f, Op::ArraySetAt(Elem::Float), &[3, 8, 202], 604);
                step(f, Op::SubFAddF, &[160, 204, 209, 216, 209, 213], 605);
                step(f, Op::DivF, &[216, 213, 182], 606);
                step(f, Op::MaxF, &[205, 12, 210], 607);
                step(f, Op::Select(ValueType::Float), &[17, 160, 210, 190], 608);
                step(f, Op::Select(ValueType::Float), &[16, 38, 190, 203], 609);
                step(f, Op::Select(ValueType::Float), &[12, 205, 203, 206], 610);
                step(f, Op::MulF, &[206, 211, 215], 611);
                step(f, Op::DivF, &[215, 186, 195], 612);
                step(f, Op::MulFAddF, &[195, 214, 208, 194, 208, 207], 613);
                step(f, Op::MulFAddF, &[207, 163, 185, 14, 195, 189], 614);
                step(f, Op::Select(ValueType::Float), &[11, 185, 189, 187], 615);
                step(f, Op::MulFMulF, &[187, 183, 196, 182, 196, 191], 616);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 8, 13], 617);
                step(f, Op::MulF, &[196, 197, 220], 618);
                step(f, Op::Select(ValueType::Float), &[13, 196, 220, 199], 619);
                step(f, Op::MulFMulF, &[184, 219, 200, 200, 193, 188], 620);
                step(f, Op::MulFMulF, &[188, 211, 222, 222, 143, 218], 621);
                step(f, Op::Select(ValueType::Float), &[13, 158, 218, 212], 622);
                step(f, Op::SubFAddF, &[199, 212, 192, 219, 192, 221], 623);
                step(f, Op::Select(ValueType::Float), &[15, 191, 221, 198], 624);
                step(f, Op::MinF, &[198, 163, 202], 625);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 8, 202], 626);
                step(f, Op::JumpIfFalse, &[15, 628], 627)
            }
            627 => {
                step(f, Op::Copy(ValueType::Float), &[206, 12], 628);
                628
            }
            628 => {
                step(f, Op::ArraySetAt(Elem::Float), &[0, 8, 216], 629);
                step(f, Op::Jump, &[594], 630)
            }
            630 => {
                step(f, Op::Copy(ValueType::Float), &[217, 13], 631);
                step(f, Op::Copy(ValueType::Bool), &[16, 4], 632);
                step(f, Op::Copy(ValueType::Float), &[201, 16], 633);
                step(f, Op::MaxF, &[205, 12, 210], 634);
                step(f, Op::Select(ValueType::Float), &[17, 160, 210, 190], 635);
                step(f, Op::Select(ValueType::Float), &[16, 38, 190, 203], 636);
                step(f, Op::Select(ValueType::Float), &[12, 205, 203, 206], 637);
                step(f, Op::MulF, &[206, 211, 215], 638);
                step(f, Op::DivF, &[215, 186, 195], 639);
                step(f, Op::Copy(ValueType::Float), &[195, 14], 640);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 641);
                step(f, Op::Copy(ValueType::Int), &[2, 9], 642);
                642
            }
            642 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 9, 0, 7, 8, 1441], 643)
            }
            643 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 14], 644);
                step(f, Op::Copy(ValueType::Bool), &[10, 13], 645);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 7, 15], 646);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 204], 647);
                step(f, Op::GreaterEqualF, &[204, 160, 11], 648);
                step(f, Op::And, &[15, 11, 17], 649);
                step(f, Op::Or, &[1, 2, 16], 650);
                step(f, Op::GreaterF, &[27, 158, 12], 651);
                step(f, Op::Or, &[16, 12, 15], 652);
                step(f, Op::Not, &[15, 12], 653);
                step(f, Op::And, &[17, 12, 16], 654);
                step(f, Op::JumpIfFalse, &[16, 748], 655)
            }
            655 => {
                step(f, Op::ArrayAtBreakTransform, &[2, 7, 6, 6, 21, 2, 20], 656);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 7, 18], 657);
                step(f, Op::SubV, &[21, 18, 19], 658);
                step(f, Op::TransformPoint, &[2, 19, 17], 659);
                step(f, Op::GetTransformBreakTransform, &[34, 2, 9, 4, 4, 22, 3, 19], 660);
                step(f, Op::BreakVector, &[22, 209, 213, 208], 661);
                step(f, Op::SubFMulF, &[160, 18, 207, 17, 207, 185], 662);
                step(f, Op::QuatFromAxisAngle, &[10, 185, 4], 663);
                step(f, Op::GetTransformBreakTransform, &[0, 2, 9, 5, 5, 23, 5, 24], 664);
                step(f, Op::SubV, &[23, 22, 25], 665);
                step(f, Op::BreakVector, &[25, 189, 187, 182], 666);
                step(f, Op::MakeVector, &[189, 187, 158, 26], 667);
                step(f, Op::RotateVector, &[4, 26, 27], 668);
                step(f, Op::BreakVector, &[27, 196, 220, 200], 669);
                step(f, Op::MulF, &[53, 18, 188], 670);
                step(f, Op::Equals(Elem::Int), &[7, 2, 15], 671);
                step(f, Op::Select(ValueType::Float), &[15, 160, 162, 222], 672);
                step(f, Op::MulFAddF, &[188, 222, 218, 196, 218, 199], 673);
                step(f, Op::AddFAddF, &[209, 199, 212, 213, 220, 192], 674);
                step(f, Op::BreakVector, &[23, 219, 191, 221], 675);
                step(f, Op::SubF, &[221, 59, 198], 676);
                step(f, Op::MakeVector, &[212, 192, 198, 28], 677);
                step(f, Op::MulFScaleV, &[9, 159, 202, 2, 202, 29], 678);
                step(f, Op::AddV, &[28, 29, 30], 679);
                step(f, Op::DistanceV, &[17, 30, 216], 680);
                step(f, Op::TransformVector, &[2, 11, 17], 681);
                step(f, Op::DistanceV, &[17, 11, 183], 682);
                step(f, Op::MaxF, &[216, 183, 184], 683);
                step(f, Op::LessEqualF, &[184, 66, 12], 684);
                step(f, Op::LengthV, &[2, 193], 685);
                step(f, Op::LengthV, &[4, 194], 686);
                step(f, Op::MaxF, &[193, 194, 197], 687);
                step(f, Op::LessEqualF, &[197, 35, 17], 688);
                step(f, Op::And, &[12, 17, 16], 689);
                step(f, Op::ArrayAt(Elem::Bool), &[1, 7, 12], 690);
                step(f, Op::And, &[16, 12, 17], 691);
                step(f, Op::JumpIfFalse, &[17, 694], 692)
            }
            692 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 13], 693);
                step(f, Op::Jump, &[720], 694)
            }
            694 => {
                step(f, Op::MakeVector, &[158, 158, 64, 17], 695);
                step(f, Op::AddVSubV, &[30, 17, 31, 30, 17, 32], 696);
                step(f, Op::SphereTrace, &[31, 32, 63, 16, 33, 34, 214], 697);
                step(f, Op::SubV, &[33, 30, 34], 698);
                step(f, Op::DistanceV, &[34, 18, 217], 699);
                step(f, Op::RotateVector, &[0, 9, 33], 700);
                step(f, Op::ScaleV, &[33, 68, 34], 701);
                step(f, Op::AddVAddV, &[31, 34, 35, 32, 34, 36], 702);
                step(f, Op::SphereTrace, &[35, 36, 63, 17, 37, 38, 201], 703);
                step(f, Op::SubV, &[37, 30, 39], 704);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 7, 40], 705);
                step(f, Op::DistanceV, &[39, 40, 210], 706);
                step(f, Op::MaxF, &[217, 210, 190], 707);
                step(f, Op::ScaleV, &[33, 65, 40], 708);
                step(f, Op::AddVAddV, &[35, 40, 41, 36, 40, 42], 709);
                step(f, Op::SphereTrace, &[41, 42, 63, 18, 43, 44, 203], 710);
                step(f, Op::SubV, &[43, 30, 45], 711);
                step(f, Op::ArrayAt(Elem::Vec3), &[2, 7, 46], 712);
                step(f, Op::DistanceV, &[45, 46, 205], 713);
                step(f, Op::MaxF, &[190, 205, 206], 714);
                step(f, Op::LessEqualF, &[206, 66, 19], 715);
                step(f, Op::And, &[16, 17, 20], 716);
                step(f, Op::And, &[20, 12, 16], 717);
                step(f, Op::And, &[19, 16, 20], 718);
                step(f, Op::JumpIfFalse, &[20, 720], 719)
            }
            719 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 13], 720);
                720
            }
            720 => {
                step(f, Op::JumpIfFalse, &[13, 748], 721)
            }
            721 => {
                step(f, Op::ArrayAtBreakTransform, &[1, 7, 7, 7, 46, 6, 47], 722);
                step(f, Op::AddV, &[30, 18, 48, 56, 56, 58, 58], 723);
                step(f, Op::SubV, &[48, 21, 18], 724);
                step(f, Op::DeltaTime, &[211], 725);
                step(f, Op::DivFScaleV, &[58, 211, 186, 18, 186, 49], 726);
                step(f, Op::AddVAddV, &[48, 49, 50, 21, 49, 51], 727);
                step(f, Op::SubV, &[46, 51, 49], 728);
                step(f, Op::FloatLerp, &[158, 160, 56, 215], 729);
                step(f, Op::SubF, &[160, 215, 195], 730);
                step(f, Op::ScaleV, &[49, 195, 51], 731);
                step(f, Op::AddV, &[50, 51, 49], 732);
                step(f, Op::MulF, &[56, 211, 183], 733);
                step(f, Op::GreaterF, &[183, 158, 16], 734);
                step(f, Op::DivF, &[215, 183, 216], 735);
                step(f, Op::Select(ValueType::Float), &[16, 216, 160, 184], 736);
                step(f, Op::ScaleV, &[18, 184, 50], 737);
                step(f, Op::SubV, &[49, 50, 51, 51, 51], 738);
                step(f, Op::BreakVector, &[51, 193, 194, 197], 739);
                step(f, Op::ClampF, &[197, 69, 70, 214], 740);
                step(f, Op::MakeVector, &[193, 194, 214, 18], 741);
                step(f, Op::MakeTransform, &[18, 6, 6, 8], 742);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 7, 8], 743);
                step(f, Op::MakeTransform, &[48, 1, 6, 8], 744);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 7, 8], 745);
                step(f, Op::JumpIfFalse, &[12, 747], 746)
            }
            746 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 7], 747);
                747
            }
            747 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 14], 748);
                748
            }
            748 => {
                step(f, Op::JumpIfFalse, &[14, 917], 749)
            }
            749 => {
                step(f, Op::GetTransformBreakTransform, &[34, 2, 9, 4, 4, 22, 3, 19], 750);
                step(f, Op::BreakVector, &[22, 209, 213, 208], 751);
                step(f, Op::SubFMulF, &[160, 18, 207, 17, 207, 185], 752);
                step(f, Op::QuatFromAxisAngle, &[10, 185, 4], 753);
                step(f, Op::GetTransformBreakTransform, &[0, 2, 9, 5, 5, 23, 5, 24], 754);
                step(f, Op::SubV, &[23, 22, 25], 755);
                step(f, Op::BreakVector, &[25, 189, 187, 182], 756);
                step(f, Op::MakeVector, &[189, 187, 158, 26], 757);
                step(f, Op::RotateVector, &[4, 26, 27], 758);
                step(f, Op::BreakVector, &[27, 196, 220, 200], 759);
                step(f, Op::MulF, &[53, 18, 188], 760);
                step(f, Op::Equals(Elem::Int), &[7, 2, 15], 761);
                step(f, Op::Select(ValueType::Float), &[15, 160, 162, 222], 762);
                step(f, Op::MulFAddF, &[188, 222, 218, 196, 218, 199], 763);
                step(f, Op::AddFAddF, &[209, 199, 212, 213, 220, 192], 764);
                step(f, Op::BreakVector, &[23, 219, 191, 221], 765);
                step(f, Op::SubF, &[221, 59, 198], 766);
                step(f, Op::MakeVector, &[212, 192, 198, 28], 767);
                step(f, Op::SubF, &[160, 204, 210], 768);
                step(f, Op::MaxF, &[210, 158, 217], 769);
                step(f, Op::MulFMulF, &[13, 10, 190, 217, 190, 205], 770);
                step(f, Op::ScaleV, &[2, 205, 49], 771);
                step(f, Op::AddV, &[28, 49, 50], 772);
                step(f, Op::MulFScaleV, &[9, 159, 202, 2, 202, 29], 773);
                step(f, Op::AddV, &[50, 29, 51], 774);
                step(f, Op::RotateVector, &[0, 9, 33], 775);
                step(f, Op::Copy(ValueType::Float), &[165, 206], 776);
                step(f, Op::Copy(ValueType::Vec3), &[7, 18], 777);
                step(f, Op::Copy(ValueType::Vec3), &[10, 48], 778);
                step(f, Op::Copy(ValueType::Bool), &[10, 19], 779);
                step(f, Op::Copy(ValueType::Float), &[165, 186], 780);
                step(f, Op::Copy(ValueType::Vec3), &[7, 50], 781);
                step(f, Op::MulI, &[0, 0, 6, 6, 6], 782);
                step(f, Op::Copy(ValueType::Int), &[2, 8], 783);
                step(f, Op::SubI, &[0, 3, 10], 784);
                step(f, Op::DivI, &[10, 4, 11], 785);
                step(f, Op::MakeVector, &[158, 158, 64, 52], 786);
                step(f, Op::ScaleV, &[33, 68, 53], 787);
                787
            }
            787 => {
                step(f, Op::ForNext, &[8, 6, 10, 828], 788)
            }
            788 => {
                step(f, Op::ModI, &[10, 0, 12], 789);
                step(f, Op::ToFloat, &[12, 195], 790);
                step(f, Op::MulFMulF, &[195, 65, 211, 211, 222, 183], 791);
                step(f, Op::MakeVector, &[183, 158, 158, 54], 792);
                step(f, Op::DivI, &[10, 0, 12], 793);
                step(f, Op::SubI, &[12, 11, 10], 794);
                step(f, Op::ToFloat, &[10, 215], 795);
                step(f, Op::MulFScaleV, &[215, 65, 216, 33, 216, 55], 796);
                step(f, Op::AddVAddV, &[54, 55, 56, 51, 56, 54], 797);
                step(f, Op::AddVSubV, &[54, 52, 55, 54, 52, 57], 798);
                step(f, Op::SphereTrace, &[55, 57, 63, 20, 54, 58, 184], 799);
                step(f, Op::BreakVector, &[54, 197, 193, 194], 800);
                step(f, Op::AddVAddV, &[55, 53, 59, 57, 53, 55], 801);
                step(f, Op::SphereTrace, &[59, 55, 63, 13, 57, 60, 214], 802);
                step(f, Op::BreakVector, &[57, 195, 211, 183], 803);
                step(f, Op::SubF, &[194, 183, 215], 804);
                step(f, Op::AbsF, &[215, 216], 805);
                step(f, Op::Select(ValueType::Float), &[20, 158, 160, 184], 806);
                step(f, Op::AddF, &[216, 184, 193], 807);
                step(f, Op::LengthV, &[56, 197], 808);
                step(f, Op::RemapF, &[197, 158, 171, 158, 160, 9, 214], 809);
                step(f, Op::MinF, &[194, 183, 195], 810);
                step(f, Op::RemapF, &[195, 172, 171, 160, 159, 9, 211], 811);
                step(f, Op::AddFAddF, &[214, 211, 215, 193, 215, 184], 812);
                step(f, Op::LessF, &[184, 206, 16], 813);
                step(f, Op::And, &[20, 16, 12], 814);
                step(f, Op::JumpIfFalse, &[12, 822], 815)
            }
            815 => {
                step(f, Op::Copy(ValueType::Float), &[206, 186], 816);
                step(f, Op::Copy(ValueType::Vec3), &[18, 50], 817);
                step(f, Op::Copy(ValueType::Float), &[184, 206], 818);
                step(f, Op::Copy(ValueType::Vec3), &[54, 18], 819);
                step(f, Op::Copy(ValueType::Vec3), &[58, 48], 820);
                step(f, Op::Copy(ValueType::Bool), &[9, 19], 821);
                step(f, Op::Jump, &[827], 822)
            }
            822 => {
                step(f, Op::LessF, &[184, 186, 14], 823);
                step(f, Op::And, &[20, 14, 15], 824);
                step(f, Op::JumpIfFalse, &[15, 827], 825)
            }
            825 => {
                step(f, Op::Copy(ValueType::Float), &[184, 186], 826);
                step(f, Op::Copy(ValueType::Vec3), &[54, 50], 827);
                827
            }
            827 => {
                step(f, Op::Jump, &[787], 828)
            }
            828 => {
                step(f, Op::JumpIfFalse, &[8, 830], 829)
            }
            829 => {
                step(f, Op::DrawSphere, &[18, 63, 9], 830);
                830
            }
            830 => {
                step(f, Op::GreaterF, &[67, 158, 13], 831);
                step(f, Op::SubF, &[206, 186, 216], 832);
                step(f, Op::DivF, &[216, 67, 197], 833);
                step(f, Op::PowF, &[173, 197, 183], 834);
                step(f, Op::Select(ValueType::Float), &[13, 183, 158, 194], 835);
                step(f, Op::ScaleV, &[50, 194, 55], 836);
                step(f, Op::AddV, &[18, 55, 59], 837);
                step(f, Op::AddF, &[194, 160, 195], 838);
                step(f, Op::DivFScaleV, &[160, 195, 211, 59, 211, 60, 60, 60, 48, 48, 19, 19], 839);
                step(f, Op::ArrayAtBreakTransform, &[1, 7, 7, 7, 46, 6, 47], 840);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 204], 841);
                step(f, Op::SubF, &[160, 204, 210], 842);
                step(f, Op::MaxF, &[210, 158, 217], 843);
                step(f, Op::MulFMulF, &[13, 10, 190, 217, 190, 205], 844);
                step(f, Op::ScaleV, &[2, 205, 49], 845);
                step(f, Op::SubV, &[60, 49, 57], 846);
                step(f, Op::Select(ValueType::Vec3), &[19, 57, 46, 56], 847);
                step(f, Op::ArrayAtBreakTransform, &[2, 7, 6, 6, 21, 2, 20, 56, 56, 58, 58], 848);
                step(f, Op::SubV, &[56, 21, 58], 849);
                step(f, Op::DeltaTime, &[214], 850);
                step(f, Op::DivFScaleV, &[58, 214, 193, 58, 193, 54], 851);
                step(f, Op::AddVAddV, &[56, 54, 51, 21, 54, 52], 852);
                step(f, Op::SubV, &[46, 52, 53], 853);
                step(f, Op::FloatLerp, &[158, 160, 56, 215], 854);
                step(f, Op::SubF, &[160, 215, 184], 855);
                step(f, Op::ScaleV, &[53, 184, 50], 856);
                step(f, Op::AddV, &[51, 50, 18], 857);
                step(f, Op::MulF, &[56, 214, 186], 858);
                step(f, Op::GreaterF, &[186, 158, 16], 859);
                step(f, Op::DivF, &[215, 186, 206], 860);
                step(f, Op::Select(ValueType::Float), &[16, 206, 160, 216], 861);
                step(f, Op::ScaleV, &[58, 216, 55], 862);
                step(f, Op::SubV, &[18, 55, 59, 59, 59], 863);
                step(f, Op::BreakVector, &[59, 197, 183, 194], 864);
                step(f, Op::ClampF, &[194, 69, 70, 195], 865);
                step(f, Op::MakeVector, &[197, 183, 195, 49], 866);
                step(f, Op::RotationFromNormal, &[48, 211, 210, 2], 867);
                step(f, Op::PerFootRotationFactor, &[17, 119, 120, 190], 868);
                step(f, Op::MulFSubF, &[17, 190, 217, 160, 18, 207], 869);
                step(f, Op::MulF, &[217, 207, 205], 870);
                step(f, Op::QuatFromAxisAngle, &[10, 205, 7], 871);
                step(f, Op::MulQ, &[2, 7, 8], 872);
                step(f, Op::Select(ValueType::Quat), &[19, 8, 6, 2], 873);
                step(f, Op::MakeTransform, &[49, 2, 6, 8], 874);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 7, 8], 875);
                step(f, Op::ArrayAtBreakTransform, &[1, 7, 7, 7, 46, 6, 47], 876);
                step(f, Op::Select(ValueType::Vec3), &[19, 57, 46, 56], 877);
                step(f, Op::MakeTransform, &[56, 1, 6, 6], 878);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 7, 6], 879);
                step(f, Op::GetTransformBreakTransform, &[34, 2, 9, 4, 4, 22, 3, 19], 880);
                step(f, Op::BreakVector, &[22, 209, 213, 208], 881);
                step(f, Op::MulF, &[17, 207, 185], 882);
                step(f, Op::QuatFromAxisAngle, &[10, 185, 4], 883);
                step(f, Op::GetTransformBreakTransform, &[0, 2, 9, 5, 5, 23, 5, 24], 884);
                step(f, Op::SubV, &[23, 22, 25], 885);
                step(f, Op::BreakVector, &[25, 189, 187, 182], 886);
                step(f, Op::MakeVector, &[189, 187, 158, 26], 887);
                step(f, Op::RotateVector, &[4, 26, 27], 888);
                step(f, Op::BreakVector, &[27, 196, 220, 200], 889);
                step(f, Op::MulFMulF, &[53, 18, 188, 188, 222, 218], 890);
                step(f, Op::AddFAddF, &[196, 218, 199, 209, 199, 212], 891);
                step(f, Op::AddF, &[213, 220, 192], 892);
                step(f, Op::BreakVector, &[23, 219, 191, 221], 893);
                step(f, Op::SubF, &[221, 59, 198], 894);
                step(f, Op::MakeVector, &[212, 192, 198, 28], 895);
                step(f, Op::MulFScaleV, &[9, 159, 202, 2, 202, 29], 896);
                step(f, Op::AddVSubV, &[28, 29, 30, 56, 30, 60], 897);
                step(f, Op::ArraySetAt(Elem::Vec3), &[0, 7, 60], 898);
                step(f, Op::ArraySetAt(Elem::Bool), &[1, 7, 19], 899);
                step(f, Op::GreaterEqualF, &[204, 160, 11], 900);
                step(f, Op::JumpIfFalse, &[11, 915], 901)
            }
            901 => {
                step(f, Op::MakeVector, &[158, 158, 64, 17], 902);
                step(f, Op::AddV, &[30, 17, 31], 903);
                step(f, Op::RotateVector, &[0, 9, 33], 904);
                step(f, Op::ScaleV, &[33, 68, 34], 905);
                step(f, Op::AddVSubV, &[31, 34, 35, 30, 17, 32], 906);
                step(f, Op::AddV, &[32, 34, 36], 907);
                step(f, Op::SphereTrace, &[35, 36, 63, 17, 37, 38, 201], 908);
                step(f, Op::SubV, &[37, 30, 39], 909);
                step(f, Op::ArraySetAt(Elem::Vec3), &[1, 7, 39], 910);
                step(f, Op::ScaleV, &[33, 65, 40], 911);
                step(f, Op::AddVAddV, &[35, 40, 41, 36, 40, 42], 912);
                step(f, Op::SphereTrace, &[41, 42, 63, 18, 43, 44, 203], 913);
                step(f, Op::SubV, &[43, 30, 45], 914);
                step(f, Op::ArraySetAt(Elem::Vec3), &[2, 7, 45], 915);
                915
            }
            915 => {
                step(f, Op::JumpIfFalse, &[19, 917], 916)
            }
            916 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 7], 917);
                917
            }
            917 => {
                step(f, Op::ArrayAt(Elem::Float), &[4, 7, 193], 918);
                step(f, Op::FloatLerp, &[193, 158, 112, 184], 919);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 7, 12], 920);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 214], 921);
                step(f, Op::GreaterEqualF, &[214, 160, 14], 922);
                step(f, Op::And, &[12, 14, 20], 923);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 7, 8], 924);
                step(f, Op::GreaterF, &[27, 158, 15], 925);
                step(f, Op::InterpolateTransform, &[2, 3, 28, 7], 926);
                step(f, Op::Select(ValueType::Transform), &[15, 7, 2, 6], 927);
                step(f, Op::MakeAbsolute, &[8, 6, 4], 928);
                step(f, Op::BreakTransform, &[4, 20, 7, 21], 929);
                step(f, Op::RotateVector, &[7, 9, 54], 930);
                step(f, Op::SubFMulF, &[160, 18, 186, 17, 186, 215], 931);
                step(f, Op::LimitRotationAroundZ, &[7, 215, 109, 8], 932);
                step(f, Op::RotateVector, &[8, 9, 52], 933);
                step(f, Op::CrossV, &[54, 52, 53], 934);
                step(f, Op::BreakVector, &[53, 206, 216, 194], 935);
                step(f, Op::DotV, &[54, 52, 183], 936);
                step(f, Op::Atan2F, &[194, 183, 195], 937);
                step(f, Op::AbsF, &[195, 197], 938);
                step(f, Op::Select(ValueType::Float), &[20, 197, 158, 210], 939);
                step(f, Op::AddF, &[184, 210, 211], 940);
                step(f, Op::ArraySetAt(Elem::Float), &[4, 7, 211], 941);
                step(f, Op::ArrayAtBreakTransform, &[8, 7, 5, 5, 50, 2, 51], 942);
                step(f, Op::AddF, &[73, 74, 190], 943);
                step(f, Op::ClampSpatially, &[20, 50, 158, 190, 58], 944);
                step(f, Op::MakeTransform, &[58, 8, 6, 8], 945);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 7, 8], 946);
                step(f, Op::JumpIfFalse, &[12, 1012], 947)
            }
            947 => {
                step(f, Op::JumpIfFalse, &[14, 949], 948)
            }
            948 => {
                step(f, Op::Jump, &[1011], 949)
            }
            949 => {
                step(f, Op::ArrayAtBreakTransform, &[1, 7, 4, 4, 18, 6, 55], 950);
                step(f, Op::SubFMulF, &[160, 214, 217, 13, 10, 205], 951);
                step(f, Op::MulFScaleV, &[217, 205, 208, 2, 208, 59], 952);
                step(f, Op::AddV, &[18, 59, 48], 953);
                step(f, Op::Equals(Elem::Int), &[7, 2, 13], 954);
                step(f, Op::Select(ValueType::Int), &[13, 3, 2, 12], 955);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 16], 956);
                step(f, Op::ArrayAtBreakTransform, &[0, 12, 5, 5, 49, 3, 47], 957);
                step(f, Op::ArrayAtBreakTransform, &[3, 12, 8, 8, 46, 5, 57], 958);
                step(f, Op::LessEqualF, &[95, 158, 11], 959);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 207], 960);
                step(f, Op::SmoothStepF, &[207, 158, 95, 185], 961);
                step(f, Op::Select(ValueType::Float), &[11, 160, 185, 182], 962);
                step(f, Op::LerpV, &[49, 46, 182, 19], 963);
                step(f, Op::MakeTransform, &[19, 1, 6, 9], 964);
                step(f, Op::Select(ValueType::Transform), &[16, 5, 9, 10], 965);
                step(f, Op::MakeAbsolute, &[10, 6, 11], 966);
                step(f, Op::Select(ValueType::Transform), &[13, 11, 10, 12], 967);
                step(f, Op::BreakTransform, &[12, 24, 4, 22], 968);
                step(f, Op::SubFMulF, &[160, 19, 187, 186, 187, 189], 969);
                step(f, Op::MulF, &[17, 189, 200], 970);
                step(f, Op::FootAvoidance, &[48, 24, 200, 13, 91, 25], 971);
                step(f, Op::RemapF, &[18, 94, 160, 158, 160, 9, 188], 972);
                step(f, Op::LerpV, &[48, 25, 188, 26], 973);
                step(f, Op::FootAvoidance, &[26, 24, 20, 13, 117, 27], 974);
                step(f, Op::LerpV, &[26, 27, 19, 23], 975);
                step(f, Op::MakeTransform, &[23, 6, 6, 13], 976);
                step(f, Op::BreakTransform, &[13, 28, 7, 29], 977);
                step(f, Op::MakeVector, &[158, 158, 64, 56], 978);
                step(f, Op::AddVSubV, &[28, 56, 60, 28, 56, 31], 979);
                step(f, Op::LineTrace, &[60, 31, 17, 17, 32, 222], 980);
                step(f, Op::RotateVector, &[7, 10, 34], 981);
                step(f, Op::FindQuatBetween, &[34, 32, 2], 982);
                step(f, Op::MulQ, &[2, 7, 8], 983);
                step(f, Op::MulFAddF, &[62, 61, 196, 196, 72, 218], 984);
                step(f, Op::NegF, &[218, 199], 985);
                step(f, Op::MakeVector, &[158, 199, 158, 38], 986);
                step(f, Op::RotateVector, &[8, 38, 37], 987);
                step(f, Op::AddVAddV, &[17, 37, 39, 39, 56, 33], 988);
                step(f, Op::SubV, &[39, 56, 35], 989);
                step(f, Op::LineTrace, &[33, 35, 18, 36, 40, 209], 990);
                step(f, Op::BreakVector, &[36, 213, 220, 191], 991);
                step(f, Op::BreakVector, &[39, 219, 221, 192], 992);
                step(f, Op::SubF, &[191, 192, 198], 993);
                step(f, Op::Select(ValueType::Float), &[18, 198, 158, 212], 994);
                step(f, Op::AddF, &[68, 72, 202], 995);
                step(f, Op::MakeVector, &[158, 202, 158, 41], 996);
                step(f, Op::RotateVector, &[8, 41, 42], 997);
                step(f, Op::AddVAddV, &[17, 42, 44, 44, 56, 30], 998);
                step(f, Op::SubV, &[44, 56, 43], 999);
                step(f, Op::LineTrace, &[30, 43, 19, 45, 21, 204], 1000);
                step(f, Op::BreakVector, &[45, 201, 203, 193], 1001);
                step(f, Op::BreakVector, &[44, 215, 206, 216], 1002);
                step(f, Op::SubF, &[193, 216, 183], 1003);
                step(f, Op::Select(ValueType::Float), &[19, 183, 158, 194], 1004);
                step(f, Op::MaxF, &[212, 194, 195], 1005);
                step(f, Op::ClampF, &[195, 158, 71, 197], 1006);
                step(f, Op::MakeVector, &[158, 158, 197, 53], 1007);
                step(f, Op::AddV, &[17, 53, 52], 1008);
                step(f, Op::MakeTransform, &[52, 8, 6, 14], 1009);
                step(f, Op::Select(ValueType::Transform), &[17, 14, 13, 15, 15, 15], 1010);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 7, 15], 1011);
                1011
            }
            1011 => {
                step(f, Op::Jump, &[1110], 1012)
            }
            1012 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 7, 13], 1013);
                step(f, Op::MakeAbsolute, &[13, 6, 14], 1014);
                step(f, Op::BreakTransform, &[14, 54, 2, 51], 1015);
                step(f, Op::ArrayAtBreakTransform, &[1, 7, 4, 4, 18, 6, 55], 1016);
                step(f, Op::SubFMulF, &[160, 214, 217, 13, 10, 205], 1017);
                step(f, Op::MulFScaleV, &[217, 205, 208, 2, 208, 59], 1018);
                step(f, Op::AddV, &[18, 59, 48], 1019);
                step(f, Op::Equals(Elem::Int), &[7, 2, 13], 1020);
                step(f, Op::Select(ValueType::Int), &[13, 3, 2, 12], 1021);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 16], 1022);
                step(f, Op::ArrayAtBreakTransform, &[0, 12, 5, 5, 49, 3, 47], 1023);
                step(f, Op::ArrayAtBreakTransform, &[3, 12, 8, 8, 46, 5, 57], 1024);
                step(f, Op::LessEqualF, &[95, 158, 11], 1025);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 207], 1026);
                step(f, Op::SmoothStepF, &[207, 158, 95, 185], 1027);
                step(f, Op::Select(ValueType::Float), &[11, 160, 185, 182], 1028);
                step(f, Op::LerpV, &[49, 46, 182, 19], 1029);
                step(f, Op::MakeTransform, &[19, 1, 6, 9], 1030);
                step(f, Op::Select(ValueType::Transform), &[16, 5, 9, 10], 1031);
                step(f, Op::MakeAbsolute, &[10, 6, 11], 1032);
                step(f, Op::Select(ValueType::Transform), &[13, 11, 10, 12], 1033);
                step(f, Op::BreakTransform, &[12, 24, 4, 22], 1034);
                step(f, Op::SubFMulF, &[160, 19, 187, 186, 187, 189], 1035);
                step(f, Op::MulF, &[17, 189, 200], 1036);
                step(f, Op::FootAvoidance, &[48, 24, 200, 13, 91, 25], 1037);
                step(f, Op::RemapF, &[18, 94, 160, 158, 160, 9, 188], 1038);
                step(f, Op::LerpV, &[48, 25, 188, 26], 1039);
                step(f, Op::FootAvoidance, &[26, 24, 20, 13, 117, 27], 1040);
                step(f, Op::LerpV, &[26, 27, 19, 23], 1041);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 7, 15], 1042);
                step(f, Op::MakeAbsolute, &[15, 6, 13], 1043);
                step(f, Op::BreakTransform, &[13, 20, 7, 58], 1044);
                step(f, Op::ArrayAt(Elem::Float), &[3, 7, 184], 1045);
                step(f, Op::SubF, &[214, 184, 210], 1046);
                step(f, Op::DeltaTime, &[211], 1047);
                step(f, Op::DivF, &[58, 211, 190], 1048);
                step(f, Op::MulFAddF, &[210, 190, 222, 184, 222, 196], 1049);
                step(f, Op::ClampF, &[196, 158, 160, 218], 1050);
                step(f, Op::AddF, &[214, 222, 199], 1051);
                step(f, Op::ClampF, &[199, 158, 160, 209], 1052);
                step(f, Op::AddFMulF, &[218, 209, 213, 213, 159, 220], 1053);
                step(f, Op::SubF, &[160, 220, 219], 1054);
                step(f, Op::GreaterF, &[210, 158, 20], 1055);
                step(f, Op::SubF, &[209, 218, 221], 1056);
                step(f, Op::DivF, &[221, 210, 191], 1057);
                step(f, Op::Select(ValueType::Float), &[20, 191, 160, 192], 1058);
                step(f, Op::MulFMulF, &[219, 192, 198, 90, 198, 202, 58, 58], 1059);
                step(f, Op::SubV, &[23, 20, 29], 1060);
                step(f, Op::DeltaTime, &[204], 1061);
                step(f, Op::DivFScaleV, &[58, 204, 201, 29, 201, 28], 1062);
                step(f, Op::AddVAddV, &[23, 28, 31, 20, 28, 60], 1063);
                step(f, Op::SubV, &[54, 60, 32], 1064);
                step(f, Op::FloatLerp, &[158, 160, 202, 203], 1065);
                step(f, Op::SubF, &[160, 203, 206], 1066);
                step(f, Op::ScaleV, &[32, 206, 34], 1067);
                step(f, Op::AddV, &[31, 34, 38], 1068);
                step(f, Op::MulF, &[202, 204, 215], 1069);
                step(f, Op::GreaterF, &[215, 158, 18], 1070);
                step(f, Op::DivF, &[203, 215, 193], 1071);
                step(f, Op::Select(ValueType::Float), &[18, 193, 160, 216], 1072);
                step(f, Op::ScaleV, &[29, 216, 37], 1073);
                step(f, Op::SubV, &[38, 37, 33, 33, 33], 1074);
                step(f, Op::MakeTransform, &[33, 6, 6, 14], 1075);
                step(f, Op::BreakTransform, &[14, 35, 8, 40], 1076);
                step(f, Op::MakeVector, &[158, 158, 64, 36], 1077);
                step(f, Op::AddVSubV, &[35, 36, 39, 35, 36, 41], 1078);
                step(f, Op::LineTrace, &[39, 41, 19, 42, 56, 183], 1079);
                step(f, Op::RotateVector, &[8, 10, 21], 1080);
                step(f, Op::FindQuatBetween, &[21, 56, 2], 1081);
                step(f, Op::MulQ, &[2, 8, 7], 1082);
                step(f, Op::MulFAddF, &[62, 61, 194, 194, 72, 212], 1083);
                step(f, Op::NegF, &[212, 195], 1084);
                step(f, Op::MakeVector, &[158, 195, 158, 30], 1085);
                step(f, Op::RotateVector, &[7, 30, 43], 1086);
                step(f, Op::AddVAddV, &[42, 43, 45, 45, 36, 44], 1087);
                step(f, Op::SubV, &[45, 36, 17], 1088);
                step(f, Op::LineTrace, &[44, 17, 17, 53, 52, 197], 1089);
                step(f, Op::BreakVector, &[53, 211, 190, 184], 1090);
                step(f, Op::BreakVector, &[45, 196, 222, 199], 1091);
                step(f, Op::SubF, &[184, 199, 213], 1092);
                step(f, Op::Select(ValueType::Float), &[17, 213, 158, 220], 1093);
                step(f, Op::AddF, &[68, 72, 209], 1094);
                step(f, Op::MakeVector, &[158, 209, 158, 51], 1095);
                step(f, Op::RotateVector, &[7, 51, 58], 1096);
                step(f, Op::AddVAddV, &[42, 58, 20, 20, 36, 28], 1097);
                step(f, Op::SubV, &[20, 36, 54], 1098);
                step(f, Op::LineTrace, &[28, 54, 20, 60, 32, 218], 1099);
                step(f, Op::BreakVector, &[60, 210, 221, 191], 1100);
                step(f, Op::BreakVector, &[20, 192, 219, 198], 1101);
                step(f, Op::SubF, &[191, 198, 201], 1102);
                step(f, Op::Select(ValueType::Float), &[20, 201, 158, 206], 1103);
                step(f, Op::MaxF, &[220, 206, 202], 1104);
                step(f, Op::ClampF, &[202, 158, 71, 204], 1105);
                step(f, Op::MakeVector, &[158, 158, 204, 31], 1106);
                step(f, Op::AddV, &[42, 31, 34], 1107);
                step(f, Op::MakeTransform, &[34, 7, 6, 15], 1108);
                step(f, Op::Select(ValueType::Transform), &[19, 15, 14, 13, 13, 13], 1109);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 7, 13], 1110);
                1110
            }
            1110 => {
                step(f, Op::JumpIfFalse, &[14, 1180], 1111)
            }
            1111 => {
                step(f, Op::JumpIfFalse, &[12, 1113], 1112)
            }
            1112 => {
                step(f, Op::Jump, &[1166], 1113)
            }
            1113 => {
                step(f, Op::ArrayAtBreakTransform, &[3, 7, 14, 14, 29, 2, 37], 1114);
                step(f, Op::Equals(Elem::Int), &[7, 2, 13], 1115);
                step(f, Op::Select(ValueType::Int), &[13, 3, 2, 12], 1116);
                step(f, Op::ArrayAtBreakTransform, &[6, 12, 15, 15, 38, 8, 33], 1117);
                step(f, Op::MakeAbsolute, &[15, 6, 13], 1118);
                step(f, Op::BreakTransform, &[13, 40, 7, 35], 1119);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 207], 1120);
                step(f, Op::SmoothStepF, &[207, 158, 160, 203], 1121);
                step(f, Op::RemapF, &[18, 158, 94, 158, 160, 9, 215], 1122);
                step(f, Op::MulF, &[203, 215, 193], 1123);
                step(f, Op::Select(ValueType::Float), &[13, 193, 158, 216], 1124);
                step(f, Op::LerpV, &[38, 40, 216, 39], 1125);
                step(f, Op::MakeTransform, &[39, 1, 6, 16], 1126);
                step(f, Op::BreakTransform, &[16, 41, 9, 21], 1127);
                step(f, Op::SubFMulF, &[160, 19, 187, 186, 187, 189], 1128);
                step(f, Op::MulF, &[17, 189, 200], 1129);
                step(f, Op::FootAvoidance, &[29, 41, 200, 13, 91, 56], 1130);
                step(f, Op::MakeTransform, &[56, 2, 6, 17], 1131);
                step(f, Op::BreakTransform, &[17, 30, 2, 43], 1132);
                step(f, Op::MakeVector, &[158, 158, 64, 17], 1133);
                step(f, Op::AddVSubV, &[30, 17, 44, 30, 17, 52], 1134);
                step(f, Op::LineTrace, &[44, 52, 18, 53, 45, 183], 1135);
                step(f, Op::RotateVector, &[2, 10, 51], 1136);
                step(f, Op::FindQuatBetween, &[51, 45, 10], 1137);
                step(f, Op::MulQ, &[10, 2, 11], 1138);
                step(f, Op::MulFAddF, &[62, 61, 194, 194, 72, 212], 1139);
                step(f, Op::NegF, &[212, 195], 1140);
                step(f, Op::MakeVector, &[158, 195, 158, 58], 1141);
                step(f, Op::RotateVector, &[11, 58, 36], 1142);
                step(f, Op::AddVAddV, &[53, 36, 28, 28, 17, 32], 1143);
                step(f, Op::SubV, &[28, 17, 54], 1144);
                step(f, Op::LineTrace, &[32, 54, 17, 60, 20, 197], 1145);
                step(f, Op::BreakVector, &[60, 190, 211, 196], 1146);
                step(f, Op::BreakVector, &[28, 222, 184, 199], 1147);
                step(f, Op::SubF, &[196, 199, 213], 1148);
                step(f, Op::Select(ValueType::Float), &[17, 213, 158, 209], 1149);
                step(f, Op::AddF, &[68, 72, 218], 1150);
                step(f, Op::MakeVector, &[158, 218, 158, 31], 1151);
                step(f, Op::RotateVector, &[11, 31, 42], 1152);
                step(f, Op::AddVAddV, &[53, 42, 34, 34, 17, 37], 1153);
                step(f, Op::SubV, &[34, 17, 29], 1154);
                step(f, Op::LineTrace, &[37, 29, 20, 56, 43, 210], 1155);
                step(f, Op::BreakVector, &[56, 221, 192, 219], 1156);
                step(f, Op::BreakVector, &[34, 191, 198, 201], 1157);
                step(f, Op::SubF, &[219, 201, 206], 1158);
                step(f, Op::Select(ValueType::Float), &[20, 206, 158, 220], 1159);
                step(f, Op::MaxF, &[209, 220, 202], 1160);
                step(f, Op::ClampF, &[202, 158, 71, 204], 1161);
                step(f, Op::MakeVector, &[158, 158, 204, 30], 1162);
                step(f, Op::AddV, &[53, 30, 44], 1163);
                step(f, Op::MakeTransform, &[44, 11, 6, 18], 1164);
                step(f, Op::Select(ValueType::Transform), &[18, 18, 17, 19, 19, 19], 1165);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 7, 19], 1166);
                1166
            }
            1166 => {
                step(f, Op::ArrayAtBreakTransform, &[0, 7, 17, 17, 52, 2, 45], 1167);
                step(f, Op::SubV, &[52, 50, 51], 1168);
                step(f, Op::LengthV, &[51, 183], 1169);
                step(f, Op::SubF, &[73, 74, 194], 1170);
                step(f, Op::SubFMulF, &[183, 194, 212, 74, 163, 195], 1171);
                step(f, Op::ClampF, &[212, 158, 195, 197], 1172);
                step(f, Op::MulFMulF, &[197, 197, 190, 74, 174, 211], 1173);
                step(f, Op::DivFSubF, &[190, 211, 184, 183, 184, 222], 1174);
                step(f, Op::DivFScaleV, &[222, 183, 196, 51, 196, 58], 1175);
                step(f, Op::AddV, &[50, 58, 36], 1176);
                step(f, Op::MakeTransform, &[36, 2, 6, 18], 1177);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 18], 1178);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 18], 1179);
                step(f, Op::Jump, &[1330], 1180)
            }
            1180 => {
                step(f, Op::ArrayAtBreakTransform, &[0, 7, 17, 17, 52, 2, 45], 1181);
                step(f, Op::SubV, &[52, 50, 51], 1182);
                step(f, Op::LengthV, &[51, 183], 1183);
                step(f, Op::SubF, &[73, 74, 194], 1184);
                step(f, Op::SubFMulF, &[183, 194, 212, 74, 163, 195], 1185);
                step(f, Op::ClampF, &[212, 158, 195, 197], 1186);
                step(f, Op::MulFMulF, &[197, 197, 190, 74, 174, 211], 1187);
                step(f, Op::DivFSubF, &[190, 211, 184, 183, 184, 222], 1188);
                step(f, Op::DivFScaleV, &[222, 183, 196, 51, 196, 58], 1189);
                step(f, Op::AddV, &[50, 58, 36], 1190);
                step(f, Op::MakeTransform, &[36, 2, 6, 18], 1191);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 7, 14], 1192);
                step(f, Op::ClampF, &[214, 158, 160, 199], 1193);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[6, 5], 1194);
                step(f, Op::ArrayReset(Elem::Vec3), &[5], 1195);
                step(f, Op::BreakTransform, &[18, 20, 10, 32], 1196);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 20], 1197);
                step(f, Op::UnitV, &[2, 54], 1198);
                step(f, Op::LengthV, &[2, 213], 1199);
                step(f, Op::RemapF, &[213, 158, 75, 158, 76, 9, 218], 1200);
                step(f, Op::ScaleV, &[54, 218, 60], 1201);
                step(f, Op::SubV, &[20, 60, 28], 1202);
                step(f, Op::MakeVector, &[158, 158, 78, 31], 1203);
                step(f, Op::AddV, &[28, 31, 42], 1204);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 42], 1205);
                step(f, Op::RemapF, &[213, 158, 75, 158, 81, 9, 210], 1206);
                step(f, Op::MakeVector, &[158, 158, 210, 17], 1207);
                step(f, Op::AddV, &[42, 17, 29], 1208);
                step(f, Op::BreakTransform, &[14, 37, 11, 43], 1209);
                step(f, Op::BreakVector, &[37, 192, 221, 191], 1210);
                step(f, Op::BreakVector, &[20, 198, 201, 219], 1211);
                step(f, Op::SubF, &[191, 219, 206], 1212);
                step(f, Op::MaxF, &[206, 158, 209], 1213);
                step(f, Op::MulF, &[209, 83, 220], 1214);
                step(f, Op::MinF, &[220, 84, 202], 1215);
                step(f, Op::AbsF, &[206, 204], 1216);
                step(f, Op::RemapF, &[204, 158, 87, 158, 86, 9, 194], 1217);
                step(f, Op::AddF, &[202, 194, 195], 1218);
                step(f, Op::MakeVector, &[158, 158, 195, 56], 1219);
                step(f, Op::AddV, &[29, 56, 34], 1220);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 34], 1221);
                step(f, Op::RemapF, &[213, 158, 75, 158, 77, 9, 212], 1222);
                step(f, Op::ScaleV, &[54, 212, 30], 1223);
                step(f, Op::AddV, &[37, 30, 53], 1224);
                step(f, Op::LerpF, &[29, 52, 18, 197], 1225);
                step(f, Op::MulF, &[14, 197, 190], 1226);
                step(f, Op::RemapF, &[190, 160, 38, 79, 80, 9, 211], 1227);
                step(f, Op::MakeVector, &[158, 158, 211, 44], 1228);
                step(f, Op::AddV, &[53, 44, 45], 1229);
                step(f, Op::RemapF, &[213, 158, 75, 158, 82, 9, 184], 1230);
                step(f, Op::MakeVector, &[158, 158, 184, 52], 1231);
                step(f, Op::AddV, &[45, 52, 51], 1232);
                step(f, Op::NegF, &[206, 183], 1233);
                step(f, Op::MaxF, &[183, 158, 222], 1234);
                step(f, Op::MulFAddF, &[222, 85, 196, 196, 194, 218], 1235);
                step(f, Op::MakeVector, &[158, 158, 218, 50], 1236);
                step(f, Op::AddV, &[51, 50, 58], 1237);
                step(f, Op::LerpV, &[34, 58, 159, 36], 1238);
                step(f, Op::GetTransformBreakTransform, &[35, 2, 9, 19, 19, 32, 2, 60], 1239);
                step(f, Op::BreakVector, &[32, 210, 192, 221], 1240);
                step(f, Op::SubFMulF, &[160, 18, 198, 88, 198, 201], 1241);
                step(f, Op::MulF, &[17, 201, 191], 1242);
                step(f, Op::QuatFromAxisAngle, &[10, 191, 2], 1243);
                step(f, Op::SubV, &[36, 32, 28], 1244);
                step(f, Op::BreakVector, &[28, 219, 209, 220], 1245);
                step(f, Op::MakeVector, &[219, 209, 158, 31], 1246);
                step(f, Op::RotateVector, &[2, 31, 17], 1247);
                step(f, Op::BreakVector, &[17, 204, 202, 195], 1248);
                step(f, Op::AddFAddF, &[210, 204, 212, 192, 202, 197], 1249);
                step(f, Op::BreakVector, &[36, 190, 211, 213], 1250);
                step(f, Op::MakeVector, &[212, 197, 213, 42], 1251);
                step(f, Op::DistanceV, &[20, 37, 184], 1252);
                step(f, Op::RemapF, &[184, 163, 175, 158, 160, 9, 206], 1253);
                step(f, Op::LerpV, &[36, 42, 206, 43], 1254);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 43], 1255);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 58], 1256);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 45], 1257);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 37], 1258);
                step(f, Op::JumpIfFalse, &[8, 1260], 1259)
            }
            1259 => {
                step(f, Op::DrawSpline, &[5, 2, 5, 159, 12], 1260);
                1260
            }
            1260 => {
                step(f, Op::Spline, &[5, 199, 2, 29, 56], 1261);
                step(f, Op::SlerpQ, &[10, 11, 199, 2], 1262);
                step(f, Op::MulF, &[199, 168, 183], 1263);
                step(f, Op::SinF, &[183, 222], 1264);
                step(f, Op::SmoothStepF, &[199, 158, 102, 194], 1265);
                step(f, Op::MulFMulF, &[222, 194, 196, 196, 89, 218], 1266);
                step(f, Op::SlerpQ, &[2, 1, 218, 10], 1267);
                step(f, Op::MakeTransform, &[29, 10, 6, 17, 17, 17], 1268);
                step(f, Op::BreakTransform, &[17, 54, 11, 30], 1269);
                step(f, Op::Equals(Elem::Int), &[7, 2, 13], 1270);
                step(f, Op::Select(ValueType::Int), &[13, 3, 2, 12], 1271);
                step(f, Op::ArrayAtBreakTransform, &[6, 12, 15, 15, 38, 8, 33], 1272);
                step(f, Op::GreaterF, &[27, 158, 15], 1273);
                step(f, Op::InterpolateTransform, &[2, 3, 28, 7], 1274);
                step(f, Op::Select(ValueType::Transform), &[15, 7, 2, 6], 1275);
                step(f, Op::MakeAbsolute, &[15, 6, 13], 1276);
                step(f, Op::BreakTransform, &[13, 40, 7, 35], 1277);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 207], 1278);
                step(f, Op::SmoothStepF, &[207, 158, 160, 203], 1279);
                step(f, Op::RemapF, &[18, 158, 94, 158, 160, 9, 215], 1280);
                step(f, Op::MulF, &[203, 215, 193], 1281);
                step(f, Op::Select(ValueType::Float), &[13, 193, 158, 216], 1282);
                step(f, Op::LerpV, &[38, 40, 216, 39], 1283);
                step(f, Op::MakeTransform, &[39, 1, 6, 16], 1284);
                step(f, Op::BreakTransform, &[16, 41, 9, 21], 1285);
                step(f, Op::SubF, &[160, 18, 186], 1286);
                step(f, Op::SubFMulF, &[160, 19, 187, 186, 187, 189], 1287);
                step(f, Op::MulF, &[17, 189, 200], 1288);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 19], 1289);
                step(f, Op::Select(ValueType::Float), &[19, 92, 158, 221], 1290);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 214], 1291);
                step(f, Op::ClampF, &[214, 158, 160, 199], 1292);
                step(f, Op::MulF, &[199, 168, 198], 1293);
                step(f, Op::SinF, &[198, 201], 1294);
                step(f, Op::MulFMulF, &[201, 201, 191, 221, 191, 220], 1295);
                step(f, Op::AddF, &[91, 220, 209], 1296);
                step(f, Op::FootAvoidance, &[54, 41, 200, 13, 209, 44], 1297);
                step(f, Op::SubV, &[44, 54, 53], 1298);
                step(f, Op::LengthV, &[53, 219], 1299);
                step(f, Op::AddF, &[219, 220, 195], 1300);
                step(f, Op::DivF, &[219, 195, 204], 1301);
                step(f, Op::MulF, &[116, 163, 210], 1302);
                step(f, Op::LessEqualF, &[219, 210, 12], 1303);
                step(f, Op::MulF, &[116, 174, 192], 1304);
                step(f, Op::DivF, &[219, 192, 202], 1305);
                step(f, Op::DivFSubF, &[116, 219, 190, 160, 190, 211], 1306);
                step(f, Op::Select(ValueType::Float), &[12, 202, 211, 197], 1307);
                step(f, Op::GreaterF, &[116, 158, 17], 1308);
                step(f, Op::Select(ValueType::Float), &[17, 19, 158, 212], 1309);
                step(f, Op::LerpF, &[204, 197, 212, 213], 1310);
                step(f, Op::LessF, &[207, 214, 20], 1311);
                step(f, Op::LessEqualF, &[93, 158, 18], 1312);
                step(f, Op::SmoothStepF, &[207, 158, 93, 184], 1313);
                step(f, Op::MulFSubF, &[184, 18, 206, 160, 206, 183], 1314);
                step(f, Op::Select(ValueType::Float), &[18, 160, 183, 194], 1315);
                step(f, Op::Select(ValueType::Float), &[20, 194, 160, 222], 1316);
                step(f, Op::MulF, &[213, 222, 196], 1317);
                step(f, Op::SmoothStepF, &[199, 158, 93, 218], 1318);
                step(f, Op::Select(ValueType::Float), &[18, 160, 218, 203], 1319);
                step(f, Op::MulFScaleV, &[196, 203, 215, 53, 215, 52], 1320);
                step(f, Op::AddV, &[54, 52, 50], 1321);
                step(f, Op::MulFMulF, &[6, 149, 193, 193, 191, 216], 1322);
                step(f, Op::MakeVector, &[158, 158, 216, 51], 1323);
                step(f, Op::AddV, &[50, 51, 34], 1324);
                step(f, Op::MakeTransform, &[34, 11, 6, 18], 1325);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 18], 1326);
                step(f, Op::ScaleV, &[53, 196, 60], 1327);
                step(f, Op::AddVAddV, &[54, 60, 32, 32, 51, 28], 1328);
                step(f, Op::MakeTransform, &[28, 11, 6, 14], 1329);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 14], 1330);
                1330
            }
            1330 => {
                step(f, Op::JumpIfFalse, &[15, 1348], 1331)
            }
            1331 => {
                step(f, Op::ArrayAtBreakTransform, &[5, 7, 19, 19, 31, 2, 17], 1332);
                step(f, Op::ArrayAtBreakTransform, &[8, 7, 17, 17, 20, 10, 36], 1333);
                step(f, Op::MulF, &[27, 27, 198], 1334);
                step(f, Op::LerpV, &[31, 20, 198, 42], 1335);
                step(f, Op::SubFMulF, &[160, 27, 201, 27, 201, 221], 1336);
                step(f, Op::MulFMulF, &[151, 163, 209, 221, 209, 220], 1337);
                step(f, Op::MakeVector, &[158, 158, 220, 43], 1338);
                step(f, Op::AddV, &[42, 43, 58], 1339);
                step(f, Op::SlerpQ, &[2, 10, 27, 8], 1340);
                step(f, Op::MakeTransform, &[58, 8, 6, 7], 1341);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 7], 1342);
                step(f, Op::ArrayAtBreakTransform, &[5, 7, 19, 19, 31, 2, 17], 1343);
                step(f, Op::LerpV, &[31, 20, 198, 42], 1344);
                step(f, Op::AddV, &[42, 43, 58], 1345);
                step(f, Op::SlerpQ, &[2, 10, 27, 8], 1346);
                step(f, Op::MakeTransform, &[58, 8, 6, 7], 1347);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 7], 1348);
                1348
            }
            1348 => {
                step(f, Op::GreaterEqualF, &[214, 160, 14], 1349);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 7, 14], 1350);
                step(f, Op::ArrayAtBreakTransform, &[1, 7, 4, 4, 18, 6, 55], 1351);
                step(f, Op::SubFMulF, &[160, 214, 217, 13, 10, 205], 1352);
                step(f, Op::MulFScaleV, &[217, 205, 208, 2, 208, 59], 1353);
                step(f, Op::AddV, &[18, 59, 48], 1354);
                step(f, Op::Equals(Elem::Int), &[7, 2, 13], 1355);
                step(f, Op::Select(ValueType::Int), &[13, 3, 2, 12], 1356);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 16], 1357);
                step(f, Op::ArrayAtBreakTransform, &[0, 12, 5, 5, 49, 3, 47], 1358);
                step(f, Op::ArrayAtBreakTransform, &[3, 12, 8, 8, 46, 5, 57], 1359);
                step(f, Op::LessEqualF, &[95, 158, 11], 1360);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 207], 1361);
                step(f, Op::SmoothStepF, &[207, 158, 95, 185], 1362);
                step(f, Op::Select(ValueType::Float), &[11, 160, 185, 182], 1363);
                step(f, Op::LerpV, &[49, 46, 182, 19], 1364);
                step(f, Op::MakeTransform, &[19, 1, 6, 9], 1365);
                step(f, Op::Select(ValueType::Transform), &[16, 5, 9, 10], 1366);
                step(f, Op::MakeAbsolute, &[10, 6, 11], 1367);
                step(f, Op::Select(ValueType::Transform), &[13, 11, 10, 12], 1368);
                step(f, Op::BreakTransform, &[12, 24, 4, 22], 1369);
                step(f, Op::SubFMulF, &[160, 19, 187, 186, 187, 189], 1370);
                step(f, Op::MulF, &[17, 189, 200], 1371);
                step(f, Op::FootAvoidance, &[48, 24, 200, 13, 91, 25], 1372);
                step(f, Op::RemapF, &[18, 94, 160, 158, 160, 9, 188], 1373);
                step(f, Op::LerpV, &[48, 25, 188, 26], 1374);
                step(f, Op::FootAvoidance, &[26, 24, 20, 13, 117, 27], 1375);
                step(f, Op::LerpV, &[26, 27, 19, 23], 1376);
                step(f, Op::MakeTransform, &[23, 1, 6, 15], 1377);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 7, 15], 1378);
                step(f, Op::ArrayAtBreakTransform, &[5, 7, 13, 13, 45, 7, 37], 1379);
                step(f, Op::MakeVector, &[158, 158, 59, 56], 1380);
                step(f, Op::AddV, &[45, 56, 29], 1381);
                step(f, Op::GetTransformBreakTransform, &[0, 2, 9, 16, 16, 30, 9, 33], 1382);
                step(f, Op::MakeTransform, &[29, 9, 6, 18], 1383);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 7, 20], 1384);
                step(f, Op::GetTransformBreakTransform, &[20, 2, 9, 14, 14, 35, 11, 38], 1385);
                step(f, Op::SubV, &[35, 30, 40], 1386);
                step(f, Op::AddV, &[29, 40, 39], 1387);
                step(f, Op::FootPivots, &[29, 39, 61, 60, 59, 62, 21, 41, 44], 1388);
                step(f, Op::GetParent, &[0, 18], 1389);
                step(f, Op::GetParent, &[18, 19], 1390);
                step(f, Op::GetTransformBreakTransform, &[19, 2, 10, 17, 17, 52, 2, 50], 1391);
                step(f, Op::SubV, &[45, 52, 34], 1392);
                step(f, Op::DotV, &[34, 9, 195], 1393);
                step(f, Op::RemapF, &[195, 97, 96, 98, 158, 9, 210], 1394);
                step(f, Op::LengthV, &[2, 192], 1395);
                step(f, Op::RemapF, &[192, 158, 108, 158, 160, 9, 219], 1396);
                step(f, Op::MulF, &[210, 219, 190], 1397);
                step(f, Op::QuatFromAxisAngle, &[13, 190, 10], 1398);
                step(f, Op::RotateAroundPoint, &[18, 21, 10, 19], 1399);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 202], 1400);
                step(f, Op::SmoothStepF, &[202, 158, 102, 211], 1401);
                step(f, Op::SubF, &[160, 202, 197], 1402);
                step(f, Op::SmoothStepF, &[197, 158, 102, 204], 1403);
                step(f, Op::MulF, &[211, 204, 212], 1404);
                step(f, Op::LerpF, &[101, 160, 212, 184], 1405);
                step(f, Op::MulF, &[190, 184, 206], 1406);
                step(f, Op::QuatFromAxisAngle, &[13, 206, 8], 1407);
                step(f, Op::SubV, &[41, 21, 53], 1408);
                step(f, Op::RotateVector, &[8, 53, 54], 1409);
                step(f, Op::AddV, &[21, 54, 60], 1410);
                step(f, Op::RemapF, &[195, 99, 97, 100, 158, 9, 183], 1411);
                step(f, Op::MulF, &[183, 219, 194], 1412);
                step(f, Op::QuatFromAxisAngle, &[13, 194, 6], 1413);
                step(f, Op::RotateAroundPoint, &[19, 60, 6, 7], 1414);
                step(f, Op::RemapF, &[195, 103, 104, 158, 105, 9, 213], 1415);
                step(f, Op::RotateVector, &[7, 10, 32], 1416);
                step(f, Op::BreakVector, &[32, 222, 199, 218], 1417);
                step(f, Op::CosF, &[107, 203], 1418);
                step(f, Op::CosF, &[106, 215], 1419);
                step(f, Op::RemapF, &[218, 203, 215, 158, 160, 9, 191], 1420);
                step(f, Op::MulFMulF, &[219, 191, 193, 213, 193, 216], 1421);
                step(f, Op::QuatFromAxisAngle, &[13, 216, 3], 1422);
                step(f, Op::RotateAroundPoint, &[7, 44, 3, 4], 1423);
                step(f, Op::SubFMulF, &[160, 18, 196, 17, 196, 201], 1424);
                step(f, Op::LimitRotationAroundZ, &[7, 201, 109, 5], 1425);
                step(f, Op::RotateAroundPoint, &[4, 45, 5, 8], 1426);
                step(f, Op::BreakTransform, &[8, 51, 4, 28], 1427);
                step(f, Op::ArrayAt(Elem::Float), &[4, 7, 209], 1428);
                step(f, Op::MulFMulF, &[209, 110, 221, 221, 111, 220], 1429);
                step(f, Op::AddF, &[221, 111, 198], 1430);
                step(f, Op::DivF, &[220, 198, 214], 1431);
                step(f, Op::MakeVector, &[158, 158, 214, 36], 1432);
                step(f, Op::AddV, &[51, 36, 17], 1433);
                step(f, Op::MakeTransform, &[17, 4, 28, 5], 1434);
                step(f, Op::ArraySetAt(Elem::Transform), &[7, 7, 5], 1435);
                step(f, Op::JumpIfFalse, &[8, 1440], 1436)
            }
            1436 => {
                step(f, Op::DrawPoint, &[44, 176, 13], 1437);
                step(f, Op::DrawPoint, &[21, 176, 9], 1438);
                step(f, Op::DrawPoint, &[60, 176, 10], 1439);
                step(f, Op::DrawTransform, &[13, 175, 159], 1440);
                1440
            }
            1440 => {
                step(f, Op::Jump, &[642], 1441)
            }
            1441 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1442);
                step(f, Op::Copy(ValueType::Int), &[2, 10], 1443);
                1443
            }
            1443 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 10, 1, 6, 8, 1479], 1444)
            }
            1444 => {
                step(f, Op::GetParent, &[1, 22], 1445);
                step(f, Op::GetParent, &[22, 23], 1446);
                step(f, Op::GetParent, &[23, 24], 1447);
                step(f, Op::GetTransformBreakTransform, &[24, 2, 10, 9, 9, 20, 9, 31], 1448);
                step(f, Op::LengthV, &[1, 205], 1449);
                step(f, Op::ClavicleOffset, &[15, 205, 123, 127, 217], 1450);
                step(f, Op::MakeVector, &[158, 158, 217, 42], 1451);
                step(f, Op::AddV, &[20, 42, 43], 1452);
                step(f, Op::MakeTransform, &[43, 9, 6, 6], 1453);
                step(f, Op::SetTransform, &[24, 6, 2, 9, 160], 1454);
                step(f, Op::GetTransform, &[1, 2, 10, 10], 1455);
                step(f, Op::GetTransformBreakTransform, &[23, 2, 10, 11, 11, 58, 11, 55], 1456);
                step(f, Op::Equals(Elem::Int), &[6, 2, 19], 1457);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 11], 1458);
                step(f, Op::ArrayAt(Elem::Float), &[0, 11, 208], 1459);
                step(f, Op::ArmSwingRotation, &[208, 1, 0, 124, 167, 177, 160, 123, 121, 122, 125, 167, 160, 207], 1460);
                step(f, Op::QuatFromAxisAngle, &[13, 207, 2], 1461);
                step(f, Op::RotateAroundPoint, &[10, 58, 2, 12], 1462);
                step(f, Op::BreakTransform, &[12, 18, 10, 59], 1463);
                step(f, Op::RemapF, &[205, 158, 123, 158, 126, 9, 185], 1464);
                step(f, Op::MakeVector, &[158, 158, 185, 47], 1465);
                step(f, Op::AddV, &[18, 47, 57], 1466);
                step(f, Op::MakeTransform, &[57, 10, 6, 15], 1467);
                step(f, Op::Select(ValueType::Vec3), &[19, 14, 13, 46], 1468);
                step(f, Op::Select(ValueType::Vec3), &[19, 9, 15, 49], 1469);
                step(f, Op::ArrayAt(Elem::Vec3), &[4, 6, 19], 1470);
                step(f, Op::TwoBoneIK, &[23, 22, 1, 15, 46, 49, 19, 2, 160, 10, 178, 179, 9, 12, 182], 1471);
                step(f, Op::JumpIfFalse, &[8, 1478], 1472)
            }
            1472 => {
                step(f, Op::GetTransformBreakTransform, &[23, 2, 10, 11, 11, 58, 11, 55], 1473);
                step(f, Op::GetTransform, &[1, 2, 10, 10], 1474);
                step(f, Op::RotateAroundPoint, &[10, 58, 2, 12], 1475);
                step(f, Op::BreakTransform, &[12, 18, 10, 59], 1476);
                step(f, Op::AddV, &[18, 47, 57], 1477);
                step(f, Op::DrawLine, &[58, 57, 159, 9], 1478);
                1478
            }
            1478 => {
                step(f, Op::Jump, &[1443], 1479)
            }
            1479 => {
                step(f, Op::NegF, &[5, 186], 1480);
                step(f, Op::MakeVector, &[158, 158, 186, 22], 1481);
                step(f, Op::MakeTransform, &[22, 1, 6, 16], 1482);
                step(f, Op::SetTransform, &[36, 16, 2, 9, 160], 1483);
                step(f, Op::Copy(ValueType::Float), &[165, 187], 1484);
                step(f, Op::Copy(ValueType::Bool), &[10, 17], 1485);
                step(f, Op::Copy(ValueType::Int), &[2, 12], 1486);
                step(f, Op::MakeVector, &[158, 158, 64, 25], 1487);
                1487
            }
            1487 => {
                step(f, Op::ForEachNext(Elem::Transform), &[5, 12, 14, 7, 9, 1498], 1488)
            }
            1488 => {
                step(f, Op::BreakTransform, &[14, 48, 8, 24], 1489);
                step(f, Op::AddVSubV, &[48, 25, 26, 48, 25, 27], 1490);
                step(f, Op::SphereTrace, &[26, 27, 63, 20, 23, 37, 189], 1491);
                step(f, Op::BreakVector, &[23, 200, 188, 192], 1492);
                step(f, Op::LessF, &[192, 187, 18], 1493);
                step(f, Op::And, &[20, 18, 15], 1494);
                step(f, Op::JumpIfFalse, &[15, 1497], 1495)
            }
            1495 => {
                step(f, Op::Copy(ValueType::Float), &[192, 187], 1496);
                step(f, Op::Copy(ValueType::Bool), &[9, 17], 1497);
                1497
            }
            1497 => {
                step(f, Op::Jump, &[1487], 1498)
            }
            1498 => {
                step(f, Op::Select(ValueType::Float), &[17, 187, 158, 210], 1499);
                step(f, Op::ClampF, &[210, 69, 70, 202, 202, 202], 1500);
                step(f, Op::SubFMulF, &[160, 27, 197, 202, 197, 204], 1501);
                step(f, Op::SubFMulF, &[160, 148, 211, 5, 211, 212], 1502);
                step(f, Op::AddF, &[204, 212, 184], 1503);
                step(f, Op::MakeVector, &[22, 158, 158, 56], 1504);
                step(f, Op::MakeVector, &[184, 158, 158, 33], 1505);
                step(f, Op::Select(ValueType::Float), &[2, 184, 23, 190], 1506);
                step(f, Op::MakeVector, &[190, 158, 158, 38, 57, 57, 58, 58], 1507);
                step(f, Op::SubV, &[33, 38, 30], 1508);
                step(f, Op::DeltaTime, &[206], 1509);
                step(f, Op::DivFScaleV, &[58, 206, 183, 30, 183, 35], 1510);
                step(f, Op::AddVAddV, &[33, 35, 40, 38, 35, 29], 1511);
                step(f, Op::SubV, &[56, 29, 39], 1512);
                step(f, Op::FloatLerp, &[158, 160, 57, 194], 1513);
                step(f, Op::SubF, &[160, 194, 195], 1514);
                step(f, Op::ScaleV, &[39, 195, 50], 1515);
                step(f, Op::AddV, &[40, 50, 52], 1516);
                step(f, Op::MulF, &[57, 206, 199], 1517);
                step(f, Op::GreaterF, &[199, 158, 14], 1518);
                step(f, Op::DivF, &[194, 199, 222], 1519);
                step(f, Op::Select(ValueType::Float), &[14, 222, 160, 203], 1520);
                step(f, Op::ScaleV, &[30, 203, 34], 1521);
                step(f, Op::SubV, &[52, 34, 41, 41, 41], 1522);
                step(f, Op::BreakVector, &[41, 215, 218, 191], 1523);
                step(f, Op::Select(ValueType::Float), &[1, 184, 215, 22, 22, 22], 1524);
                step(f, Op::Copy(ValueType::Float), &[184, 23], 1525);
                step(f, Op::GetTransformBreakTransform, &[37, 2, 9, 17, 17, 53, 6, 54], 1526);
                step(f, Op::PelvisLean, &[1, 130, 135, 136, 219, 193], 1527);
                step(f, Op::LengthV, &[2, 213], 1528);
                step(f, Op::RemapF, &[213, 158, 130, 158, 128, 9, 216], 1529);
                step(f, Op::MulFSubF, &[18, 129, 196, 160, 196, 201], 1530);
                step(f, Op::MulFMulF, &[216, 201, 209, 15, 180, 221], 1531);
                step(f, Op::SinF, &[221, 198], 1532);
                step(f, Op::MulFMulF, &[209, 198, 220, 220, 197, 214], 1533);
                step(f, Op::AddF, &[214, 22, 217], 1534);
                step(f, Op::SubF, &[217, 5, 208], 1535);
                step(f, Op::MakeVector, &[158, 193, 208, 32], 1536);
                step(f, Op::AddV, &[53, 32, 45], 1537);
                step(f, Op::ArrayAtBreakTransform, &[7, 2, 18, 18, 36, 3, 51], 1538);
                step(f, Op::BreakVector, &[36, 207, 205, 185], 1539);
                step(f, Op::ArrayAtBreakTransform, &[7, 3, 19, 19, 17, 7, 28], 1540);
                step(f, Op::BreakVector, &[17, 182, 186, 189], 1541);
                step(f, Op::SubF, &[185, 189, 188], 1542);
                step(f, Op::PelvisSideLean, &[188, 137, 138, 200], 1543);
                step(f, Op::ArrayAtBreakTransform, &[5, 2, 7, 7, 44, 5, 21], 1544);
                step(f, Op::ArrayAtBreakTransform, &[5, 3, 4, 4, 60, 4, 31], 1545);
                step(f, Op::SlerpQ, &[5, 4, 159, 9], 1546);
                step(f, Op::EulerFromQuat, &[9, 2, 20], 1547);
                step(f, Op::BreakVector, &[20, 192, 187, 210], 1548);
                step(f, Op::RemapF, &[213, 131, 130, 158, 132, 9, 202], 1549);
                step(f, Op::SubV, &[36, 17, 42], 1550);
                step(f, Op::RotateVector, &[0, 9, 43], 1551);
                step(f, Op::DotV, &[42, 43, 211], 1552);
                step(f, Op::MulFAddF, &[202, 211, 204, 210, 204, 212], 1553);
                step(f, Op::MakeVector, &[219, 200, 212, 19], 1554);
                step(f, Op::QuatFromEuler, &[19, 2, 11], 1555);
                step(f, Op::MakeTransform, &[45, 11, 6, 8], 1556);
                step(f, Op::SetTransform, &[38, 8, 2, 9, 160], 1557);
                step(f, Op::GetTransformBreakTransform, &[39, 3, 9, 5, 5, 46, 2, 49], 1558);
                step(f, Op::QuatFromAxisAngle, &[10, 204, 10], 1559);
                step(f, Op::DivF, &[133, 176, 190], 1560);
                step(f, Op::QuatScale, &[10, 190, 8], 1561);
                step(f, Op::MulQ, &[2, 8, 6], 1562);
                step(f, Op::MakeTransform, &[46, 6, 6, 13], 1563);
                step(f, Op::SetTransform, &[40, 13, 3, 9, 160], 1564);
                step(f, Op::GetTransformBreakTransform, &[41, 3, 9, 9, 9, 55, 3, 59], 1565);
                step(f, Op::MulQ, &[3, 8, 7], 1566);
                step(f, Op::MakeTransform, &[55, 7, 6, 6], 1567);
                step(f, Op::SetTransform, &[42, 6, 3, 9, 160], 1568);
                step(f, Op::GetTransformBreakTransform, &[43, 3, 9, 15, 15, 18, 4, 47], 1569);
                step(f, Op::MulQ, &[4, 8, 5], 1570);
                step(f, Op::MakeTransform, &[18, 5, 6, 11], 1571);
                step(f, Op::SetTransform, &[44, 11, 3, 9, 160], 1572);
                step(f, Op::GetTransformBreakTransform, &[45, 3, 9, 10, 10, 57, 9, 58], 1573);
                step(f, Op::QuatScale, &[10, 134, 11], 1574);
                step(f, Op::MulQ, &[9, 11, 2], 1575);
                step(f, Op::MakeTransform, &[57, 2, 6, 12], 1576);
                step(f, Op::SetTransform, &[46, 12, 3, 9, 160], 1577);
                step(f, Op::Or, &[1, 2, 11], 1578);
                step(f, Op::Copy(ValueType::Float), &[158, 183], 1579);
                step(f, Op::Copy(ValueType::Int), &[2, 8], 1580);
                1580
            }
            1580 => {
                step(f, Op::ForEachNext(Elem::Bone), &[0, 8, 25, 11, 6, 1623], 1581)
            }
            1581 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 11, 16], 1582);
                step(f, Op::GetParent, &[25, 26], 1583);
                step(f, Op::GetParent, &[26, 27], 1584);
                step(f, Op::GetTransformBreakTransform, &[27, 2, 10, 16, 16, 22, 6, 24], 1585);
                step(f, Op::BreakVector, &[22, 195, 206, 194], 1586);
                step(f, Op::ArrayAtBreakTransform, &[7, 11, 14, 14, 48, 3, 26], 1587);
                step(f, Op::BreakVector, &[48, 199, 222, 203], 1588);
                step(f, Op::ArrayAt(Elem::Float), &[1, 11, 191], 1589);
                step(f, Op::MulFMulF, &[191, 139, 218, 218, 218, 215], 1590);
                step(f, Op::SubF, &[195, 199, 184], 1591);
                step(f, Op::SubF, &[206, 222, 196], 1592);
                step(f, Op::MakeVector, &[184, 196, 158, 27], 1593);
                step(f, Op::DotV, &[27, 27, 201], 1594);
                step(f, Op::SubF, &[215, 201, 216], 1595);
                step(f, Op::SqrtF, &[216, 221], 1596);
                step(f, Op::AddF, &[203, 221, 198], 1597);
                step(f, Op::SubF, &[194, 198, 209], 1598);
                step(f, Op::ArrayAtBreakTransform, &[3, 11, 17, 17, 37, 7, 23], 1599);
                step(f, Op::BreakVector, &[37, 197, 220, 214], 1600);
                step(f, Op::AddF, &[214, 59, 217], 1601);
                step(f, Op::MinF, &[203, 217, 193], 1602);
                step(f, Op::AddF, &[193, 221, 208], 1603);
                step(f, Op::SubF, &[194, 208, 205], 1604);
                step(f, Op::Equals(Elem::Int), &[11, 2, 13], 1605);
                step(f, Op::Select(ValueType::Int), &[13, 3, 2, 10], 1606);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 10, 19], 1607);
                step(f, Op::ArrayAt(Elem::Float), &[2, 10, 207], 1608);
                step(f, Op::RemapF, &[207, 159, 160, 158, 160, 9, 182], 1609);
                step(f, Op::RemapF, &[207, 158, 142, 160, 158, 9, 186], 1610);
                step(f, Op::MaxF, &[182, 186, 185], 1611);
                step(f, Op::Select(ValueType::Float), &[19, 160, 185, 189], 1612);
                step(f, Op::LerpF, &[209, 205, 189, 188], 1613);
                step(f, Op::ArrayAt(Elem::Float), &[2, 11, 187], 1614);
                step(f, Op::RemapF, &[187, 159, 160, 158, 160, 9, 192], 1615);
                step(f, Op::MulF, &[188, 192, 213], 1616);
                step(f, Op::RemapF, &[187, 158, 142, 160, 158, 9, 202], 1617);
                step(f, Op::MulF, &[209, 202, 211], 1618);
                step(f, Op::MaxF, &[213, 211, 210], 1619);
                step(f, Op::Select(ValueType::Float), &[16, 209, 210, 200], 1620);
                step(f, Op::MaxF, &[183, 200, 212], 1621);
                step(f, Op::Copy(ValueType::Float), &[212, 183], 1622);
                step(f, Op::Jump, &[1580], 1623)
            }
            1623 => {
                step(f, Op::ClampF, &[183, 158, 140, 219, 219, 219], 1624);
                step(f, Op::MakeVector, &[24, 158, 158, 25], 1625);
                step(f, Op::MakeVector, &[219, 158, 158, 33], 1626);
                step(f, Op::MakeVector, &[25, 158, 158, 35], 1627);
                step(f, Op::GreaterF, &[219, 24, 12], 1628);
                step(f, Op::Select(ValueType::Float), &[12, 144, 141, 204, 58, 58], 1629);
                step(f, Op::SubV, &[33, 35, 38], 1630);
                step(f, Op::DeltaTime, &[190], 1631);
                step(f, Op::DivFScaleV, &[58, 190, 191, 38, 191, 29], 1632);
                step(f, Op::AddVAddV, &[33, 29, 56, 35, 29, 39], 1633);
                step(f, Op::SubV, &[25, 39, 40], 1634);
                step(f, Op::FloatLerp, &[158, 160, 204, 218], 1635);
                step(f, Op::SubF, &[160, 218, 195], 1636);
                step(f, Op::ScaleV, &[40, 195, 50], 1637);
                step(f, Op::AddV, &[56, 50, 30], 1638);
                step(f, Op::MulF, &[204, 190, 199], 1639);
                step(f, Op::GreaterF, &[199, 158, 18], 1640);
                step(f, Op::DivF, &[218, 199, 206], 1641);
                step(f, Op::Select(ValueType::Float), &[18, 206, 160, 222], 1642);
                step(f, Op::ScaleV, &[38, 222, 34], 1643);
                step(f, Op::SubV, &[30, 34, 52, 52, 52], 1644);
                step(f, Op::BreakVector, &[52, 184, 196, 201], 1645);
                step(f, Op::Select(ValueType::Float), &[11, 219, 184, 24, 24, 24], 1646);
                step(f, Op::Copy(ValueType::Float), &[219, 25], 1647);
                step(f, Op::GetTransformBreakTransform, &[47, 2, 10, 18, 18, 41, 4, 54], 1648);
                step(f, Op::MakeVector, &[158, 158, 24, 32], 1649);
                step(f, Op::SubV, &[41, 32, 53], 1650);
                step(f, Op::MakeTransform, &[53, 4, 6, 19], 1651);
                step(f, Op::SetTransform, &[48, 19, 2, 9, 160], 1652);
                step(f, Op::JumpIfFalse, &[8, 1657], 1653)
            }
            1653 => {
                step(f, Op::GetTransformBreakTransform, &[47, 2, 10, 18, 18, 41, 4, 54], 1654);
                step(f, Op::SubV, &[41, 32, 53], 1655);
                step(f, Op::MakeTransform, &[53, 4, 6, 19], 1656);
                step(f, Op::DrawTransform, &[19, 181, 159], 1657);
                1657
            }
            1657 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1658);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 1659);
                1659
            }
            1659 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 7, 2, 9, 12, 1701], 1660)
            }
            1660 => {
                step(f, Op::GetParent, &[2, 29], 1661);
                step(f, Op::GetParent, &[29, 30], 1662);
                step(f, Op::GetTransformBreakTransform, &[30, 2, 10, 7, 7, 51, 8, 28], 1663);
                step(f, Op::ArrayAtBreakTransform, &[7, 9, 4, 4, 21, 5, 44], 1664);
                step(f, Op::SubV, &[21, 51, 31], 1665);
                step(f, Op::LengthV, &[31, 215], 1666);
                step(f, Op::ArrayAt(Elem::Float), &[1, 9, 216], 1667);
                step(f, Op::MulF, &[216, 152, 198], 1668);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 9, 20], 1669);
                step(f, Op::MulF, &[19, 118, 197], 1670);
                step(f, Op::ArrayAt(Elem::Float), &[2, 9, 220], 1671);
                step(f, Op::ClampF, &[220, 158, 160, 214], 1672);
                step(f, Op::LessF, &[214, 159, 15], 1673);
                step(f, Op::SmoothStepF, &[214, 154, 155, 203], 1674);
                step(f, Op::MulF, &[214, 168, 217], 1675);
                step(f, Op::SinF, &[217, 193], 1676);
                step(f, Op::MaxF, &[203, 193, 221], 1677);
                step(f, Op::Select(ValueType::Float), &[15, 221, 193, 194], 1678);
                step(f, Op::MulF, &[194, 153, 208], 1679);
                step(f, Op::Select(ValueType::Float), &[20, 197, 208, 207], 1680);
                step(f, Op::SubF, &[198, 207, 182], 1681);
                step(f, Op::SubF, &[215, 182, 186], 1682);
                step(f, Op::MaxF, &[186, 158, 185], 1683);
                step(f, Op::MulFAddF, &[185, 185, 189, 185, 207, 205], 1684);
                step(f, Op::DivFSubF, &[189, 205, 188, 215, 188, 192], 1685);
                step(f, Op::DivFScaleV, &[192, 215, 187, 31, 187, 60], 1686);
                step(f, Op::AddV, &[51, 60, 20], 1687);
                step(f, Op::ClampSpatially, &[20, 51, 158, 198, 17], 1688);
                step(f, Op::MakeTransform, &[17, 5, 6, 8], 1689);
                step(f, Op::Equals(Elem::Int), &[9, 2, 17], 1690);
                step(f, Op::Select(ValueType::Vec3), &[17, 14, 13, 36], 1691);
                step(f, Op::Select(ValueType::Vec3), &[17, 9, 15, 42], 1692);
                step(f, Op::ArrayAtBreakTransform, &[5, 9, 5, 5, 43, 10, 19], 1693);
                step(f, Op::ArrayAt(Elem::Vec3), &[3, 9, 45], 1694);
                step(f, Op::KneeVector, &[10, 0, 45, 156, 157, 49], 1695);
                step(f, Op::TwoBoneIK, &[30, 29, 2, 8, 36, 42, 49, 2, 160, 10, 178, 179, 9, 14, 202], 1696);
                step(f, Op::JumpIfFalse, &[8, 1700], 1697)
            }
            1697 => {
                step(f, Op::GetTransformBreakTransform, &[29, 2, 10, 13, 13, 46, 9, 59], 1698);
                step(f, Op::AddV, &[46, 49, 55], 1699);
                step(f, Op::DrawLine, &[46, 55, 159, 16], 1700);
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
