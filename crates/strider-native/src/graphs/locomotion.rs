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
    fingerprint: 0x9c0cdd1678234b42,
    forward,
};

fn forward(f: &mut Frame<'_>) {
    let mut pc: usize = 94;
    loop {
        // SAFETY: each `step` is an instruction of the program this code was generated
        // from, with its own operands; `NATIVE` runs only on that program (fingerprint).
        pc = unsafe { match pc {
            94 => {
                step(f, Op::Not, &[0, 1, 1, 1], 95);
                step(f, Op::WorldTransform, &[6], 96);
                step(f, Op::BreakTransform, &[6, 19, 2, 22], 97);
                step(f, Op::Select(ValueType::Transform), &[0, 0, 6, 4], 98);
                step(f, Op::BreakTransform, &[4, 20, 2, 17], 99);
                step(f, Op::SubV, &[19, 20, 21], 100);
                step(f, Op::LengthV, &[21, 183], 101);
                step(f, Op::GreaterF, &[183, 41, 2, 2, 2], 102);
                step(f, Op::MakeRelative, &[4, 6, 5], 103);
                step(f, Op::Select(ValueType::Transform), &[2, 3, 5, 2, 2, 2], 104);
                step(f, Op::InverseT, &[4, 5], 105);
                step(f, Op::MulT, &[6, 5, 1, 1, 1], 106);
                step(f, Op::TransformVector, &[2, 0, 18], 107);
                step(f, Op::InverseT, &[6, 4], 108);
                step(f, Op::DeltaTime, &[184], 109);
                step(f, Op::DivFScaleV, &[160, 184, 182, 21, 182, 22], 110);
                step(f, Op::TransformVector, &[4, 22, 17], 111);
                step(f, Op::BreakVector, &[17, 183, 185, 186], 112);
                step(f, Op::BreakVector, &[21, 186, 187, 188], 113);
                step(f, Op::AddF, &[2, 188, 186], 114);
                step(f, Op::Select(ValueType::Float), &[2, 158, 186, 187], 115);
                step(f, Op::MakeVector, &[183, 185, 158, 19], 116);
                step(f, Op::LengthV, &[19, 188], 117);
                step(f, Op::MulFMulF, &[188, 145, 186, 186, 184, 188], 118);
                step(f, Op::NegF, &[188, 184], 119);
                step(f, Op::ClampF, &[187, 184, 188, 186], 120);
                step(f, Op::MulF, &[186, 182, 184], 121);
                step(f, Op::MakeVector, &[183, 185, 184, 20], 122);
                step(f, Op::Select(ValueType::Vec3), &[2, 18, 20, 22], 123);
                step(f, Op::VectorLerp, &[18, 22, 42, 158, 0, 0, 0], 124);
                step(f, Op::TransformVector, &[2, 1, 17], 125);
                step(f, Op::TransformVector, &[2, 0, 18], 126);
                step(f, Op::Select(ValueType::Vec3), &[2, 18, 20, 22], 127);
                step(f, Op::VectorLerp, &[17, 22, 43, 158, 1, 1, 1], 128);
                step(f, Op::LengthV, &[22, 0, 0, 0], 129);
                step(f, Op::SubF, &[187, 186, 188], 130);
                step(f, Op::NegF, &[146, 182], 131);
                step(f, Op::ClampF, &[188, 182, 146, 3], 132);
                step(f, Op::SubF, &[188, 3, 1, 1, 1, 3, 3], 133);
                step(f, Op::JumpIfFalse, &[2, 147], 134)
            }
            134 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 12], 135);
                step(f, Op::Copy(ValueType::Int), &[2, 6], 136);
                136
            }
            136 => {
                step(f, Op::ForEachNext(Elem::Bone), &[12, 6, 13, 8, 7, 146], 137)
            }
            137 => {
                step(f, Op::ArrayAt(Elem::Transform), &[8, 8, 5], 138);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 8, 5], 139);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 8, 5], 140);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 8, 5], 141);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 8, 5], 142);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 8, 5], 143);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 8, 5], 144);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 8, 5], 145);
                step(f, Op::Jump, &[136], 146)
            }
            146 => {
                step(f, Op::Copy(ValueType::Float), &[158, 22], 147);
                147
            }
            147 => {
                step(f, Op::Copy(ValueType::Transform), &[6, 0], 148);
                step(f, Op::Copy(ValueType::Bool), &[9, 0], 149);
                step(f, Op::JumpIfFalse, &[8, 154], 150)
            }
            150 => {
                step(f, Op::GetTransformBreakTransform, &[33, 2, 9, 4, 4, 21, 2, 19], 151);
                step(f, Op::ScaleV, &[0, 161, 18], 152);
                step(f, Op::AddV, &[21, 18, 20], 153);
                step(f, Op::DrawArrow, &[21, 20, 159, 8], 154);
                154
            }
            154 => {
                step(f, Op::Copy(ValueType::Float), &[158, 183], 155);
                step(f, Op::Copy(ValueType::Float), &[160, 184], 156);
                step(f, Op::Copy(ValueType::Bool), &[10, 11], 157);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[8, 9], 158);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 159);
                step(f, Op::MakeVector, &[158, 158, 64, 17], 160);
                160
            }
            160 => {
                step(f, Op::ForEachNext(Elem::Transform), &[9, 7, 5, 8, 6, 169], 161)
            }
            161 => {
                step(f, Op::BreakTransform, &[5, 22, 2, 19], 162);
                step(f, Op::TransformPoint, &[2, 22, 18], 163);
                step(f, Op::LerpV, &[18, 22, 160, 20], 164);
                step(f, Op::AddVSubV, &[20, 17, 21, 20, 17, 19], 165);
                step(f, Op::LineTrace, &[21, 19, 12, 18, 22, 185], 166);
                step(f, Op::JumpIfFalse, &[12, 168], 167)
            }
            167 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 11], 168);
                168
            }
            168 => {
                step(f, Op::Jump, &[160, 11, 11], 169)
            }
            169 => {
                step(f, Op::Or, &[11, 7, 12], 170);
                step(f, Op::NotEquals(Elem::Bool), &[12, 5, 13], 171);
                step(f, Op::JumpIfFalse, &[13, 196], 172)
            }
            172 => {
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 14], 173);
                step(f, Op::JumpIfFalse, &[14, 196, 1, 1], 174)
            }
            174 => {
                step(f, Op::Copy(ValueType::Int), &[2, 6], 175);
                175
            }
            175 => {
                step(f, Op::ForNext, &[6, 1, 8, 196], 176)
            }
            176 => {
                step(f, Op::AddFMulF, &[183, 184, 186, 186, 159, 187], 177);
                step(f, Op::Copy(ValueType::Bool), &[10, 15], 178);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[8, 10], 179);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 180);
                step(f, Op::MakeVector, &[158, 158, 64, 20], 181);
                181
            }
            181 => {
                step(f, Op::ForEachNext(Elem::Transform), &[10, 7, 6, 8, 9, 190], 182)
            }
            182 => {
                step(f, Op::BreakTransform, &[6, 18, 2, 19], 183);
                step(f, Op::TransformPoint, &[2, 18, 21], 184);
                step(f, Op::LerpV, &[21, 18, 187, 22], 185);
                step(f, Op::AddVSubV, &[22, 20, 17, 22, 20, 19], 186);
                step(f, Op::LineTrace, &[17, 19, 16, 18, 21, 182], 187);
                step(f, Op::JumpIfFalse, &[16, 189], 188)
            }
            188 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 15], 189);
                189
            }
            189 => {
                step(f, Op::Jump, &[181, 15, 15], 190)
            }
            190 => {
                step(f, Op::Equals(Elem::Bool), &[15, 6, 16], 191);
                step(f, Op::JumpIfFalse, &[16, 194], 192)
            }
            192 => {
                step(f, Op::Copy(ValueType::Float), &[187, 183], 193);
                step(f, Op::Jump, &[195], 194)
            }
            194 => {
                step(f, Op::Copy(ValueType::Float), &[187, 184], 195);
                195
            }
            195 => {
                step(f, Op::Jump, &[175], 196)
            }
            196 => {
                step(f, Op::Select(ValueType::Float), &[5, 162, 160, 188], 197);
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 14], 198);
                step(f, Op::AddFMulF, &[183, 184, 186, 186, 159, 185], 199);
                step(f, Op::Select(ValueType::Float), &[14, 185, 159, 182], 200);
                step(f, Op::Select(ValueType::Float), &[13, 182, 158, 187], 201);
                step(f, Op::MulF, &[188, 187, 183], 202);
                step(f, Op::DeltaTime, &[184], 203);
                step(f, Op::DivF, &[184, 150, 186], 204);
                step(f, Op::MulFAddF, &[183, 186, 185, 26, 185, 187], 205);
                step(f, Op::ClampF, &[187, 158, 160, 188], 206);
                step(f, Op::Select(ValueType::Float), &[12, 162, 160, 184], 207);
                step(f, Op::SubF, &[160, 182, 183], 208);
                step(f, Op::Select(ValueType::Float), &[13, 183, 160, 185], 209);
                step(f, Op::MulFMulF, &[184, 185, 187, 187, 186, 182], 210);
                step(f, Op::AddF, &[188, 182, 183], 211);
                step(f, Op::ClampF, &[183, 158, 160, 26], 212);
                step(f, Op::SmoothStepF, &[26, 158, 160, 184], 213);
                step(f, Op::AddFMulF, &[27, 184, 185, 185, 159, 186], 214);
                step(f, Op::SubFMulF, &[160, 186, 187, 187, 187, 182], 215);
                step(f, Op::SubF, &[160, 182, 28, 28, 28], 216);
                step(f, Op::Copy(ValueType::Float), &[184, 27, 26, 26], 217);
                step(f, Op::GreaterF, &[27, 158, 15], 218);
                step(f, Op::TransformVector, &[2, 3, 22], 219);
                step(f, Op::Select(ValueType::Vec3), &[15, 22, 0, 3, 3, 3], 220);
                step(f, Op::LerpV, &[0, 3, 27, 17], 221);
                step(f, Op::Select(ValueType::Vec3), &[15, 17, 0, 2, 2, 2], 222);
                step(f, Op::Copy(ValueType::Bool), &[12, 5], 223);
                step(f, Op::Copy(ValueType::Bool), &[11, 6], 224);
                step(f, Op::Copy(ValueType::Bool), &[10, 7], 225);
                step(f, Op::SubFMulF, &[160, 28, 188, 1, 188, 183], 226);
                step(f, Op::SubFMulF, &[3, 2, 185, 185, 188, 186], 227);
                step(f, Op::AddFMulF, &[2, 186, 187, 187, 188, 182], 228);
                step(f, Op::SubFAddF, &[187, 182, 184, 183, 184, 189], 229);
                step(f, Op::AddF, &[4, 189, 190], 230);
                step(f, Op::Copy(ValueType::Float), &[7, 191], 231);
                step(f, Op::Copy(ValueType::Float), &[8, 192], 232);
                step(f, Op::Copy(ValueType::Float), &[4, 193], 233);
                step(f, Op::Copy(ValueType::Float), &[147, 194], 234);
                step(f, Op::Copy(ValueType::Float), &[58, 195], 235);
                step(f, Op::SubF, &[190, 193, 196], 236);
                step(f, Op::DeltaTime, &[197], 237);
                step(f, Op::DivF, &[196, 197, 198], 238);
                step(f, Op::MulFAddF, &[198, 195, 199, 190, 199, 200], 239);
                step(f, Op::MulF, &[198, 163, 201], 240);
                step(f, Op::DivF, &[164, 194, 202], 241);
                step(f, Op::DivFSubF, &[201, 202, 203, 200, 203, 204], 242);
                step(f, Op::AddF, &[193, 199, 205], 243);
                step(f, Op::SubFAddF, &[191, 205, 206, 206, 203, 207], 244);
                step(f, Op::SubFMulF, &[192, 198, 208, 202, 207, 209], 245);
                step(f, Op::AddFMulF, &[208, 209, 210, 210, 197, 211], 246);
                step(f, Op::AddF, &[207, 211, 212], 247);
                step(f, Op::FloatLerp, &[158, 160, 202, 213], 248);
                step(f, Op::SubFMulF, &[160, 213, 214, 212, 214, 215], 249);
                step(f, Op::AddF, &[204, 215, 216], 250);
                step(f, Op::Copy(ValueType::Float), &[216, 217], 251);
                step(f, Op::MulFSubF, &[202, 211, 218, 208, 218, 219], 252);
                step(f, Op::MulFAddF, &[219, 214, 220, 198, 220, 221], 253);
                step(f, Op::Copy(ValueType::Float), &[221, 222], 254);
                step(f, Op::SubFAddF, &[190, 217, 6, 6, 182, 5, 5, 5, 6, 6], 255);
                step(f, Op::Copy(ValueType::Float), &[182, 2], 256);
                step(f, Op::SubFMulF, &[3, 2, 185, 185, 188, 186], 257);
                step(f, Op::AddFMulF, &[2, 186, 187, 187, 188, 182], 258);
                step(f, Op::SubFAddF, &[187, 182, 184, 183, 184, 189], 259);
                step(f, Op::AddF, &[4, 189, 190], 260);
                step(f, Op::Copy(ValueType::Float), &[7, 191], 261);
                step(f, Op::Copy(ValueType::Float), &[8, 192], 262);
                step(f, Op::Copy(ValueType::Float), &[4, 193], 263);
                step(f, Op::Copy(ValueType::Float), &[147, 194], 264);
                step(f, Op::Copy(ValueType::Float), &[58, 195], 265);
                step(f, Op::SubF, &[190, 193, 196], 266);
                step(f, Op::DeltaTime, &[197], 267);
                step(f, Op::DivF, &[196, 197, 198], 268);
                step(f, Op::MulFAddF, &[198, 195, 199, 190, 199, 200], 269);
                step(f, Op::MulF, &[198, 163, 201], 270);
                step(f, Op::DivF, &[164, 194, 202], 271);
                step(f, Op::DivFSubF, &[201, 202, 203, 200, 203, 204], 272);
                step(f, Op::AddF, &[193, 199, 205], 273);
                step(f, Op::SubFAddF, &[191, 205, 206, 206, 203, 207], 274);
                step(f, Op::SubFMulF, &[192, 198, 208, 202, 207, 209], 275);
                step(f, Op::AddFMulF, &[208, 209, 210, 210, 197, 211], 276);
                step(f, Op::AddF, &[207, 211, 212], 277);
                step(f, Op::FloatLerp, &[158, 160, 202, 213], 278);
                step(f, Op::SubFMulF, &[160, 213, 214, 212, 214, 215], 279);
                step(f, Op::AddF, &[204, 215, 216], 280);
                step(f, Op::Copy(ValueType::Float), &[216, 217], 281);
                step(f, Op::MulFSubF, &[202, 211, 218, 208, 218, 219], 282);
                step(f, Op::MulFAddF, &[219, 214, 220, 198, 220, 221], 283);
                step(f, Op::Copy(ValueType::Float), &[221, 222], 284);
                step(f, Op::Copy(ValueType::Float), &[217, 7], 285);
                step(f, Op::Copy(ValueType::Float), &[7, 191], 286);
                step(f, Op::Copy(ValueType::Float), &[8, 192], 287);
                step(f, Op::Copy(ValueType::Float), &[4, 193], 288);
                step(f, Op::Copy(ValueType::Float), &[147, 194], 289);
                step(f, Op::Copy(ValueType::Float), &[58, 195], 290);
                step(f, Op::SubF, &[190, 193, 196], 291);
                step(f, Op::DeltaTime, &[197], 292);
                step(f, Op::DivF, &[196, 197, 198], 293);
                step(f, Op::MulFAddF, &[198, 195, 199, 190, 199, 200], 294);
                step(f, Op::MulF, &[198, 163, 201], 295);
                step(f, Op::DivF, &[164, 194, 202], 296);
                step(f, Op::DivFSubF, &[201, 202, 203, 200, 203, 204], 297);
                step(f, Op::AddF, &[193, 199, 205], 298);
                step(f, Op::SubFAddF, &[191, 205, 206, 206, 203, 207], 299);
                step(f, Op::SubFMulF, &[192, 198, 208, 202, 207, 209], 300);
                step(f, Op::AddFMulF, &[208, 209, 210, 210, 197, 211], 301);
                step(f, Op::AddF, &[207, 211, 212], 302);
                step(f, Op::FloatLerp, &[158, 160, 202, 213], 303);
                step(f, Op::SubFMulF, &[160, 213, 214, 212, 214, 215], 304);
                step(f, Op::AddF, &[204, 215, 216], 305);
                step(f, Op::Copy(ValueType::Float), &[216, 217], 306);
                step(f, Op::MulFSubF, &[202, 211, 218, 208, 218, 219], 307);
                step(f, Op::MulFAddF, &[219, 214, 220, 198, 220, 221], 308);
                step(f, Op::Copy(ValueType::Float), &[221, 222], 309);
                step(f, Op::Copy(ValueType::Float), &[222, 8], 310);
                step(f, Op::Copy(ValueType::Float), &[190, 4], 311);
                step(f, Op::LengthV, &[4, 185], 312);
                step(f, Op::GreaterF, &[185, 35, 16], 313);
                step(f, Op::LengthV, &[2, 186], 314);
                step(f, Op::GreaterF, &[186, 35, 14], 315);
                step(f, Op::And, &[16, 14, 13], 316);
                step(f, Op::Select(ValueType::Vec3), &[16, 4, 7, 18], 317);
                step(f, Op::MovementAngleOffset, &[18, 17, 158, 165, 165, 166, 46, 167, 188, 17, 17], 318);
                step(f, Op::SubFAddF, &[188, 17, 182, 182, 168, 187], 319);
                step(f, Op::DivF, &[187, 169, 183], 320);
                step(f, Op::FractF, &[183, 184], 321);
                step(f, Op::MulFSubF, &[184, 169, 189, 189, 168, 196, 196, 196], 322);
                step(f, Op::AbsF, &[196, 195], 323);
                step(f, Op::Select(ValueType::Vec3), &[14, 2, 7, 19], 324);
                step(f, Op::MovementAngleOffset, &[19, 17, 158, 165, 165, 166, 46, 167, 194, 17, 17], 325);
                step(f, Op::SubFAddF, &[194, 17, 201, 201, 168, 200], 326);
                step(f, Op::DivF, &[200, 169, 193], 327);
                step(f, Op::FractF, &[193, 199], 328);
                step(f, Op::MulFSubF, &[199, 169, 191, 191, 168, 205, 205, 205], 329);
                step(f, Op::AbsF, &[205, 203], 330);
                step(f, Op::MaxF, &[195, 203, 206], 331);
                step(f, Op::SubFAddF, &[194, 188, 192, 192, 168, 209], 332);
                step(f, Op::DivF, &[209, 169, 197], 333);
                step(f, Op::FractF, &[197, 210], 334);
                step(f, Op::MulFSubF, &[210, 169, 207, 207, 168, 213, 213, 213], 335);
                step(f, Op::AbsF, &[213, 212], 336);
                step(f, Op::MaxF, &[206, 212, 204], 337);
                step(f, Op::DeltaTime, &[215], 338);
                step(f, Op::DivF, &[58, 215, 216], 339);
                step(f, Op::TransformVector, &[2, 9, 21], 340);
                step(f, Op::BreakVector, &[21, 217, 202, 211], 341);
                step(f, Op::NegF, &[217, 208], 342);
                step(f, Op::Atan2F, &[208, 202, 218], 343);
                step(f, Op::MulF, &[216, 218, 214], 344);
                step(f, Op::QuatFromAxisAngle, &[10, 214, 2], 345);
                step(f, Op::TransformVector, &[2, 4, 20], 346);
                step(f, Op::FloatLerp, &[158, 160, 42, 219], 347);
                step(f, Op::GreaterF, &[219, 158, 15], 348);
                step(f, Op::AddFMulF, &[160, 216, 198, 42, 198, 220], 349);
                step(f, Op::FloatLerp, &[158, 160, 220, 221], 350);
                step(f, Op::DivF, &[221, 219, 222], 351);
                step(f, Op::Select(ValueType::Float), &[15, 222, 198, 190], 352);
                step(f, Op::LerpV, &[20, 2, 190, 22], 353);
                step(f, Op::RotateVector, &[2, 22, 17], 354);
                step(f, Op::LengthV, &[17, 185], 355);
                step(f, Op::GreaterF, &[185, 35, 12], 356);
                step(f, Op::Select(ValueType::Vec3), &[12, 17, 7, 18], 357);
                step(f, Op::MovementAngleOffset, &[18, 17, 158, 165, 165, 166, 46, 167, 182, 17, 17], 358);
                step(f, Op::SubFAddF, &[182, 17, 187, 187, 168, 183], 359);
                step(f, Op::DivF, &[183, 169, 184], 360);
                step(f, Op::FractF, &[184, 189], 361);
                step(f, Op::MulFSubF, &[189, 169, 196, 196, 168, 201, 201, 201], 362);
                step(f, Op::AbsF, &[201, 200], 363);
                step(f, Op::SubFAddF, &[182, 194, 193, 193, 168, 199], 364);
                step(f, Op::DivF, &[199, 169, 191], 365);
                step(f, Op::FractF, &[191, 205], 366);
                step(f, Op::MulFSubF, &[205, 169, 195, 195, 168, 203, 203, 203], 367);
                step(f, Op::AbsF, &[203, 188], 368);
                step(f, Op::MaxF, &[200, 188, 192], 369);
                step(f, Op::MaxF, &[204, 192, 209], 370);
                step(f, Op::LessF, &[209, 170, 11], 371);
                step(f, Op::And, &[13, 11, 17], 372);
                step(f, Op::SubV, &[2, 20, 21], 373);
                step(f, Op::DotV, &[20, 21, 197], 374);
                step(f, Op::NegF, &[197, 210], 375);
                step(f, Op::DotV, &[21, 21, 207], 376);
                step(f, Op::DivF, &[210, 207, 206], 377);
                step(f, Op::ClampF, &[206, 158, 190, 212], 378);
                step(f, Op::LerpV, &[20, 2, 212, 22], 379);
                step(f, Op::LengthV, &[22, 211], 380);
                step(f, Op::LessF, &[211, 35, 11], 381);
                step(f, Op::Not, &[11, 13], 382);
                step(f, Op::And, &[17, 13, 11], 383);
                step(f, Op::Not, &[16, 13], 384);
                step(f, Op::Not, &[14, 17], 385);
                step(f, Op::And, &[13, 17, 16], 386);
                step(f, Op::Not, &[12, 13], 387);
                step(f, Op::And, &[16, 13, 17], 388);
                step(f, Op::Or, &[11, 17, 12], 389);
                step(f, Op::JumpIfFalse, &[12, 407], 390)
            }
            390 => {
                step(f, Op::MulF, &[44, 215, 217], 391);
                step(f, Op::GreaterF, &[217, 158, 13], 392);
                step(f, Op::FloatLerp, &[158, 160, 44, 202], 393);
                step(f, Op::SubF, &[160, 202, 208], 394);
                step(f, Op::DivF, &[208, 202, 214], 395);
                step(f, Op::DivFSubF, &[160, 217, 220, 214, 220, 221], 396);
                step(f, Op::AddF, &[216, 221, 198], 397);
                step(f, Op::Select(ValueType::Float), &[13, 198, 158, 222], 398);
                step(f, Op::MulFAddF, &[213, 222, 185, 194, 185, 187], 399);
                step(f, Op::SinF, &[187, 183], 400);
                step(f, Op::NegF, &[183, 184], 401);
                step(f, Op::CosF, &[187, 189], 402);
                step(f, Op::MakeVector, &[184, 189, 158, 17], 403);
                step(f, Op::Select(ValueType::Vec3), &[14, 17, 7, 18], 404);
                step(f, Op::MovementAngleOffset, &[18, 17, 158, 44, 45, 166, 168, 167, 196], 405);
                step(f, Op::Copy(ValueType::Float), &[196, 17], 406);
                step(f, Op::Jump, &[455], 407)
            }
            407 => {
                step(f, Op::DivF, &[215, 48, 201], 408);
                step(f, Op::AddF, &[201, 159, 182], 409);
                step(f, Op::FloorF, &[182, 193], 410);
                step(f, Op::MaxF, &[193, 160, 199], 411);
                step(f, Op::ToInt, &[199, 8, 8, 8], 412);
                step(f, Op::Copy(ValueType::Int), &[2, 9], 413);
                step(f, Op::MulFSubF, &[48, 159, 191, 58, 191, 205], 414);
                step(f, Op::DivF, &[205, 215, 195], 415);
                step(f, Op::DivF, &[44, 199, 203], 416);
                step(f, Op::DivFSubF, &[45, 199, 188, 166, 47, 200], 417);
                step(f, Op::GreaterF, &[47, 158, 16], 418);
                418
            }
            418 => {
                step(f, Op::ForNext, &[9, 8, 7, 455], 419)
            }
            419 => {
                step(f, Op::ToFloat, &[7, 192], 420);
                step(f, Op::AddF, &[192, 160, 204], 421);
                step(f, Op::DivF, &[204, 199, 209], 422);
                step(f, Op::AddF, &[209, 195, 197], 423);
                step(f, Op::SubFMulF, &[197, 160, 207, 207, 218, 210], 424);
                step(f, Op::QuatFromAxisAngle, &[10, 210, 2], 425);
                step(f, Op::MulF, &[42, 197, 190], 426);
                step(f, Op::FloatLerp, &[158, 160, 190, 206], 427);
                step(f, Op::DivF, &[206, 219, 212], 428);
                step(f, Op::Select(ValueType::Float), &[15, 212, 197, 211], 429);
                step(f, Op::LerpV, &[20, 2, 211, 21], 430);
                step(f, Op::RotateVector, &[2, 21, 22], 431);
                step(f, Op::LengthV, &[22, 202], 432);
                step(f, Op::GreaterF, &[202, 35, 11], 433);
                step(f, Op::Select(ValueType::Vec3), &[11, 22, 7, 17], 434);
                step(f, Op::MulFMulF, &[215, 197, 208, 11, 208, 217], 435);
                step(f, Op::AddF, &[15, 217, 214], 436);
                step(f, Op::FractF, &[214, 220], 437);
                step(f, Op::MulF, &[220, 163, 216], 438);
                step(f, Op::FractF, &[216, 221], 439);
                step(f, Op::LessF, &[221, 167, 17], 440);
                step(f, Op::MovementAngleOffset, &[17, 17, 158, 165, 165, 166, 46, 167, 198, 17, 17], 441);
                step(f, Op::SubFAddF, &[198, 17, 213, 213, 168, 222], 442);
                step(f, Op::DivF, &[222, 169, 185], 443);
                step(f, Op::FractF, &[185, 194], 444);
                step(f, Op::MulFSubF, &[194, 169, 183, 183, 168, 187, 187, 187], 445);
                step(f, Op::AbsF, &[187, 184], 446);
                step(f, Op::SmoothStepF, &[184, 200, 166, 189], 447);
                step(f, Op::GreaterF, &[184, 166, 12], 448);
                step(f, Op::Select(ValueType::Float), &[12, 160, 158, 196], 449);
                step(f, Op::Select(ValueType::Float), &[16, 189, 196, 201], 450);
                step(f, Op::Select(ValueType::Float), &[17, 158, 201, 182], 451);
                step(f, Op::LerpF, &[203, 188, 182, 193], 452);
                step(f, Op::MovementAngleOffset, &[17, 17, 220, 193, 193, 166, 46, 167, 191], 453);
                step(f, Op::Copy(ValueType::Float), &[191, 17], 454);
                step(f, Op::Jump, &[418], 455)
            }
            455 => {
                step(f, Op::QuatFromAxisAngle, &[10, 17, 0, 0, 0], 456);
                step(f, Op::SinF, &[17, 205], 457);
                step(f, Op::AbsF, &[205, 192], 458);
                step(f, Op::RemapF, &[192, 49, 50, 158, 160, 9, 204], 459);
                step(f, Op::BreakVector, &[19, 209, 207, 210], 460);
                step(f, Op::AbsF, &[209, 190], 461);
                step(f, Op::DivF, &[190, 186, 206], 462);
                step(f, Op::RemapF, &[206, 49, 50, 158, 160, 9, 212], 463);
                step(f, Op::TransformVector, &[2, 9, 18], 464);
                step(f, Op::DistanceV, &[18, 9, 211], 465);
                step(f, Op::DivF, &[211, 215, 202], 466);
                step(f, Op::RemapF, &[202, 54, 55, 160, 158, 9, 197], 467);
                step(f, Op::MulF, &[212, 197, 208], 468);
                step(f, Op::MaxF, &[204, 208, 18, 18, 18], 469);
                step(f, Op::Copy(ValueType::Vec3), &[2, 4], 470);
                step(f, Op::TransformVector, &[2, 5, 21], 471);
                step(f, Op::BreakTransform, &[2, 22, 2, 17], 472);
                step(f, Op::DeltaTime, &[217], 473);
                step(f, Op::DivFScaleV, &[160, 217, 214, 22, 214, 20], 474);
                step(f, Op::NegV, &[20, 5], 475);
                step(f, Op::SubV, &[5, 21, 19], 476);
                step(f, Op::AddF, &[21, 217, 216], 477);
                step(f, Op::DivFScaleV, &[21, 216, 221, 19, 221, 18], 478);
                step(f, Op::AddV, &[21, 18, 17], 479);
                step(f, Op::DivFScaleV, &[217, 216, 198, 19, 198, 20], 480);
                step(f, Op::AddV, &[5, 20, 18], 481);
                step(f, Op::DotV, &[17, 18, 213], 482);
                step(f, Op::LessF, &[213, 158, 13], 483);
                step(f, Op::TransformVector, &[2, 9, 21], 484);
                step(f, Op::DistanceV, &[21, 9, 222], 485);
                step(f, Op::SubV, &[18, 17, 19], 486);
                step(f, Op::DotV, &[17, 19, 185], 487);
                step(f, Op::NegF, &[185, 194], 488);
                step(f, Op::DotV, &[19, 19, 183], 489);
                step(f, Op::DivF, &[194, 183, 187], 490);
                step(f, Op::ClampF, &[187, 158, 160, 184], 491);
                step(f, Op::SubFMulF, &[160, 184, 189, 217, 189, 196], 492);
                step(f, Op::DivF, &[222, 196, 201], 493);
                step(f, Op::RemapF, &[201, 54, 55, 158, 160, 9, 182], 494);
                step(f, Op::BreakVector, &[18, 193, 220, 191], 495);
                step(f, Op::NegF, &[193, 188], 496);
                step(f, Op::Atan2F, &[188, 220, 195], 497);
                step(f, Op::AbsF, &[195, 199], 498);
                step(f, Op::RemapF, &[199, 113, 114, 158, 160, 9, 200], 499);
                step(f, Op::MulF, &[182, 200, 203], 500);
                step(f, Op::DivF, &[222, 217, 218], 501);
                step(f, Op::RemapF, &[218, 54, 55, 158, 160, 9, 219], 502);
                step(f, Op::BreakVector, &[22, 205, 192, 207], 503);
                step(f, Op::NegF, &[192, 210], 504);
                step(f, Op::Atan2F, &[205, 210, 209], 505);
                step(f, Op::AbsF, &[209, 186], 506);
                step(f, Op::RemapF, &[186, 113, 114, 158, 160, 9, 190], 507);
                step(f, Op::MulF, &[219, 190, 206], 508);
                step(f, Op::Select(ValueType::Float), &[13, 203, 206, 211], 509);
                step(f, Op::FloatLerp, &[19, 158, 115, 215], 510);
                step(f, Op::MaxF, &[211, 215, 202], 511);
                step(f, Op::AbsF, &[20, 197], 512);
                step(f, Op::GreaterEqualF, &[197, 114, 14], 513);
                step(f, Op::LessF, &[186, 114, 11], 514);
                step(f, Op::And, &[14, 11, 12], 515);
                step(f, Op::SubF, &[197, 114, 212], 516);
                step(f, Op::SubF, &[197, 186, 204], 517);
                step(f, Op::DivFSubF, &[212, 204, 208, 160, 208, 214], 518);
                step(f, Op::MulF, &[115, 214, 221], 519);
                step(f, Op::FloatLerp, &[160, 158, 221, 216], 520);
                step(f, Op::MulF, &[219, 216, 198], 521);
                step(f, Op::Select(ValueType::Float), &[12, 198, 158, 213], 522);
                step(f, Op::MaxF, &[202, 213, 19, 19, 19], 523);
                step(f, Op::Select(ValueType::Float), &[13, 195, 209, 20, 20, 20, 5, 5], 524);
                step(f, Op::Copy(ValueType::Float), &[217, 21], 525);
                step(f, Op::Copy(ValueType::Bool), &[9, 17], 526);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 2], 527);
                step(f, Op::Copy(ValueType::Int), &[2, 6], 528);
                528
            }
            528 => {
                step(f, Op::ForEachNext(Elem::Bool), &[2, 6, 15, 7, 8, 533], 529)
            }
            529 => {
                step(f, Op::Not, &[15, 16], 530);
                step(f, Op::JumpIfFalse, &[16, 532], 531)
            }
            531 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 17], 532);
                532
            }
            532 => {
                step(f, Op::Jump, &[528, 17, 17], 533)
            }
            533 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 11], 534);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 535);
                step(f, Op::Copy(ValueType::Int), &[2, 9], 536);
                536
            }
            536 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 9, 15, 7, 8, 548], 537)
            }
            537 => {
                step(f, Op::ArrayAtBreakTransform, &[0, 7, 4, 4, 20, 2, 21], 538);
                step(f, Op::BreakVector, &[20, 185, 183, 194], 539);
                step(f, Op::MakeVector, &[185, 183, 158, 17], 540);
                step(f, Op::ArrayAtBreakTransform, &[8, 7, 5, 5, 19, 2, 18], 541);
                step(f, Op::BreakVector, &[19, 187, 184, 189], 542);
                step(f, Op::MakeVector, &[187, 184, 158, 22], 543);
                step(f, Op::DistanceV, &[17, 22, 196], 544);
                step(f, Op::GreaterF, &[196, 37, 14], 545);
                step(f, Op::JumpIfFalse, &[14, 547], 546)
            }
            546 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 11], 547);
                547
            }
            547 => {
                step(f, Op::Jump, &[536, 11, 11], 548)
            }
            548 => {
                step(f, Op::And, &[17, 11, 12], 549);
                step(f, Op::LengthV, &[2, 201], 550);
                step(f, Op::GreaterF, &[201, 35, 3], 551);
                step(f, Op::GreaterF, &[0, 35, 13], 552);
                step(f, Op::Or, &[3, 13, 15], 553);
                step(f, Op::Not, &[15, 16], 554);
                step(f, Op::And, &[12, 16, 14], 555);
                step(f, Op::DeltaTime, &[191], 556);
                step(f, Op::MulFAddF, &[191, 40, 193, 15, 193, 188], 557);
                step(f, Op::GreaterF, &[15, 159, 11], 558);
                step(f, Op::AddF, &[39, 159, 220], 559);
                step(f, Op::Select(ValueType::Float), &[11, 220, 39, 199], 560);
                step(f, Op::MinF, &[188, 199, 182], 561);
                step(f, Op::NotEquals(Elem::Bool), &[16, 4, 13], 562);
                step(f, Op::Not, &[12, 15], 563);
                step(f, Op::And, &[13, 15, 11], 564);
                step(f, Op::SubF, &[16, 35, 200], 565);
                step(f, Op::SubF, &[16, 201, 222], 566);
                step(f, Op::DivF, &[200, 222, 218], 567);
                step(f, Op::ClampF, &[218, 158, 160, 207], 568);
                step(f, Op::MulF, &[11, 207, 192], 569);
                step(f, Op::RemapF, &[201, 35, 36, 158, 160, 9, 205], 570);
                step(f, Op::MaxF, &[205, 12, 210], 571);
                step(f, Op::Select(ValueType::Float), &[17, 160, 210, 190], 572);
                step(f, Op::Select(ValueType::Float), &[16, 38, 190, 203], 573);
                step(f, Op::Select(ValueType::Float), &[12, 205, 203, 206], 574);
                step(f, Op::SubFMulF, &[160, 27, 211, 206, 211, 215], 575);
                step(f, Op::LerpF, &[29, 52, 18, 186], 576);
                step(f, Op::RemapF, &[201, 32, 33, 30, 31, 9, 197], 577);
                step(f, Op::LerpF, &[197, 51, 18, 204], 578);
                step(f, Op::MaxF, &[201, 34, 212], 579);
                step(f, Op::DivF, &[204, 212, 9], 580);
                step(f, Op::AddF, &[186, 9, 10], 581);
                step(f, Op::DivFSubF, &[215, 10, 208, 160, 207, 214], 582);
                step(f, Op::MulFAddF, &[208, 214, 221, 192, 221, 216], 583);
                step(f, Op::MulFAddF, &[216, 163, 219, 11, 208, 198], 584);
                step(f, Op::Select(ValueType::Float), &[11, 219, 198, 202], 585);
                step(f, Op::DivF, &[163, 202, 213], 586);
                step(f, Op::GreaterF, &[202, 158, 13], 587);
                step(f, Op::CycleStep, &[15, 213, 158, 13, 195, 209], 588);
                step(f, Op::Select(ValueType::Float), &[14, 182, 195, 15, 15, 15], 589);
                step(f, Op::Copy(ValueType::Float), &[208, 11, 3, 3, 9, 9, 10, 10], 590);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 591);
                step(f, Op::Copy(ValueType::Int), &[2, 6], 592);
                step(f, Op::DivF, &[186, 10, 217], 593);
                step(f, Op::MulFMulF, &[14, 207, 194, 191, 159, 183], 594);
                step(f, Op::SubF, &[217, 13, 185], 595);
                step(f, Op::MaxF, &[185, 158, 189], 596);
                step(f, Op::DivFSubF, &[189, 217, 184, 160, 18, 187], 597);
                step(f, Op::SubFMulF, &[160, 19, 196, 187, 196, 193], 598);
                step(f, Op::DivFSubF, &[58, 191, 220, 159, 220, 188], 599);
                step(f, Op::MulFMulF, &[184, 193, 199, 199, 211, 200], 600);
                step(f, Op::MulFMulF, &[200, 143, 222, 222, 188, 218], 601);
                step(f, Op::SubF, &[160, 218, 197], 602);
                602
            }
            602 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 6, 14, 8, 7, 638], 603)
            }
            603 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 8, 204], 604);
                step(f, Op::ToFloat, &[8, 212], 605);
                step(f, Op::MulFAddF, &[212, 159, 192, 15, 192, 221], 606);
                step(f, Op::FractF, &[221, 216], 607);
                step(f, Op::SubF, &[204, 216, 198], 608);
                step(f, Op::GreaterF, &[198, 159, 15], 609);
                step(f, Op::ArrayAt(Elem::Float), &[2, 8, 219], 610);
                step(f, Op::Select(ValueType::Float), &[15, 158, 219, 202], 611);
                step(f, Op::ArraySetAt(Elem::Float), &[3, 8, 202], 612);
                step(f, Op::SubFAddF, &[160, 204, 209, 216, 209, 213], 613);
                step(f, Op::DivF, &[216, 213, 182], 614);
                step(f, Op::MaxF, &[205, 12, 210], 615);
                step(f, Op::Select(ValueType::Float), &[17, 160, 210, 190], 616);
                step(f, Op::Select(ValueType::Float), &[16, 38, 190, 203], 617);
                step(f, Op::Select(ValueType::Float), &[12, 205, 203, 206], 618);
                step(f, Op::MulF, &[206, 211, 215], 619);
                step(f, Op::DivF, &[215, 186, 195], 620);
                step(f, Op::MulFAddF, &[195, 214, 208, 194, 208, 207], 621);
                step(f, Op::MulFAddF, &[207, 163, 185, 14, 195, 189], 622);
                step(f, Op::Select(ValueType::Float), &[11, 185, 189, 187], 623);
                step(f, Op::MulFMulF, &[187, 183, 196, 182, 196, 191], 624);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 8, 13], 625);
                step(f, Op::MulF, &[196, 197, 220], 626);
                step(f, Op::Select(ValueType::Float), &[13, 196, 220, 199], 627);
                step(f, Op::MulFMulF, &[184, 219, 200, 200, 193, 188], 628);
                step(f, Op::MulFMulF, &[188, 211, 222, 222, 143, 218], 629);
                step(f, Op::Select(ValueType::Float), &[13, 158, 218, 212], 630);
                step(f, Op::SubFAddF, &[199, 212, 192, 219, 192, 221], 631);
                step(f, Op::Select(ValueType::Float), &[15, 191, 221, 198], 632);
                step(f, Op::MinF, &[198, 163, 202], 633);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 8, 202], 634);
                step(f, Op::JumpIfFalse, &[15, 636], 635)
            }
            635 => {
                step(f, Op::Copy(ValueType::Float), &[206, 12], 636);
                636
            }
            636 => {
                step(f, Op::ArraySetAt(Elem::Float), &[0, 8, 216], 637);
                step(f, Op::Jump, &[602], 638)
            }
            638 => {
                step(f, Op::Copy(ValueType::Float), &[217, 13], 639);
                step(f, Op::Copy(ValueType::Bool), &[16, 4], 640);
                step(f, Op::Copy(ValueType::Float), &[201, 16], 641);
                step(f, Op::MaxF, &[205, 12, 210], 642);
                step(f, Op::Select(ValueType::Float), &[17, 160, 210, 190], 643);
                step(f, Op::Select(ValueType::Float), &[16, 38, 190, 203], 644);
                step(f, Op::Select(ValueType::Float), &[12, 205, 203, 206], 645);
                step(f, Op::MulF, &[206, 211, 215], 646);
                step(f, Op::DivF, &[215, 186, 195], 647);
                step(f, Op::Copy(ValueType::Float), &[195, 14], 648);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 649);
                step(f, Op::Copy(ValueType::Int), &[2, 9], 650);
                650
            }
            650 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 9, 0, 7, 8, 1449], 651)
            }
            651 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 14], 652);
                step(f, Op::Copy(ValueType::Bool), &[10, 13], 653);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 7, 15], 654);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 204], 655);
                step(f, Op::GreaterEqualF, &[204, 160, 11], 656);
                step(f, Op::And, &[15, 11, 17], 657);
                step(f, Op::Or, &[1, 2, 16], 658);
                step(f, Op::GreaterF, &[27, 158, 12], 659);
                step(f, Op::Or, &[16, 12, 15], 660);
                step(f, Op::Not, &[15, 12], 661);
                step(f, Op::And, &[17, 12, 16], 662);
                step(f, Op::JumpIfFalse, &[16, 756], 663)
            }
            663 => {
                step(f, Op::ArrayAtBreakTransform, &[2, 7, 6, 6, 21, 2, 20], 664);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 7, 18], 665);
                step(f, Op::SubV, &[21, 18, 19], 666);
                step(f, Op::TransformPoint, &[2, 19, 17], 667);
                step(f, Op::GetTransformBreakTransform, &[34, 2, 9, 4, 4, 22, 3, 19], 668);
                step(f, Op::BreakVector, &[22, 209, 213, 208], 669);
                step(f, Op::SubFMulF, &[160, 18, 207, 17, 207, 185], 670);
                step(f, Op::QuatFromAxisAngle, &[10, 185, 4], 671);
                step(f, Op::GetTransformBreakTransform, &[0, 2, 9, 5, 5, 23, 5, 24], 672);
                step(f, Op::SubV, &[23, 22, 25], 673);
                step(f, Op::BreakVector, &[25, 189, 187, 182], 674);
                step(f, Op::MakeVector, &[189, 187, 158, 26], 675);
                step(f, Op::RotateVector, &[4, 26, 27], 676);
                step(f, Op::BreakVector, &[27, 196, 220, 200], 677);
                step(f, Op::MulF, &[53, 18, 188], 678);
                step(f, Op::Equals(Elem::Int), &[7, 2, 15], 679);
                step(f, Op::Select(ValueType::Float), &[15, 160, 162, 222], 680);
                step(f, Op::MulFAddF, &[188, 222, 218, 196, 218, 199], 681);
                step(f, Op::AddFAddF, &[209, 199, 212, 213, 220, 192], 682);
                step(f, Op::BreakVector, &[23, 219, 191, 221], 683);
                step(f, Op::SubF, &[221, 59, 198], 684);
                step(f, Op::MakeVector, &[212, 192, 198, 28], 685);
                step(f, Op::MulFScaleV, &[9, 159, 202, 2, 202, 29], 686);
                step(f, Op::AddV, &[28, 29, 30], 687);
                step(f, Op::DistanceV, &[17, 30, 216], 688);
                step(f, Op::TransformVector, &[2, 11, 17], 689);
                step(f, Op::DistanceV, &[17, 11, 183], 690);
                step(f, Op::MaxF, &[216, 183, 184], 691);
                step(f, Op::LessEqualF, &[184, 66, 12], 692);
                step(f, Op::LengthV, &[2, 193], 693);
                step(f, Op::LengthV, &[4, 194], 694);
                step(f, Op::MaxF, &[193, 194, 197], 695);
                step(f, Op::LessEqualF, &[197, 35, 17], 696);
                step(f, Op::And, &[12, 17, 16], 697);
                step(f, Op::ArrayAt(Elem::Bool), &[1, 7, 12], 698);
                step(f, Op::And, &[16, 12, 17], 699);
                step(f, Op::JumpIfFalse, &[17, 702], 700)
            }
            700 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 13], 701);
                step(f, Op::Jump, &[728], 702)
            }
            702 => {
                step(f, Op::MakeVector, &[158, 158, 64, 17], 703);
                step(f, Op::AddVSubV, &[30, 17, 31, 30, 17, 32], 704);
                step(f, Op::SphereTrace, &[31, 32, 63, 16, 33, 34, 214], 705);
                step(f, Op::SubV, &[33, 30, 34], 706);
                step(f, Op::DistanceV, &[34, 18, 217], 707);
                step(f, Op::RotateVector, &[0, 9, 33], 708);
                step(f, Op::ScaleV, &[33, 68, 34], 709);
                step(f, Op::AddVAddV, &[31, 34, 35, 32, 34, 36], 710);
                step(f, Op::SphereTrace, &[35, 36, 63, 17, 37, 38, 201], 711);
                step(f, Op::SubV, &[37, 30, 39], 712);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 7, 40], 713);
                step(f, Op::DistanceV, &[39, 40, 210], 714);
                step(f, Op::MaxF, &[217, 210, 190], 715);
                step(f, Op::ScaleV, &[33, 65, 40], 716);
                step(f, Op::AddVAddV, &[35, 40, 41, 36, 40, 42], 717);
                step(f, Op::SphereTrace, &[41, 42, 63, 18, 43, 44, 203], 718);
                step(f, Op::SubV, &[43, 30, 45], 719);
                step(f, Op::ArrayAt(Elem::Vec3), &[2, 7, 46], 720);
                step(f, Op::DistanceV, &[45, 46, 205], 721);
                step(f, Op::MaxF, &[190, 205, 206], 722);
                step(f, Op::LessEqualF, &[206, 66, 19], 723);
                step(f, Op::And, &[16, 17, 20], 724);
                step(f, Op::And, &[20, 12, 16], 725);
                step(f, Op::And, &[19, 16, 20], 726);
                step(f, Op::JumpIfFalse, &[20, 728], 727)
            }
            727 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 13], 728);
                728
            }
            728 => {
                step(f, Op::JumpIfFalse, &[13, 756], 729)
            }
            729 => {
                step(f, Op::ArrayAtBreakTransform, &[1, 7, 7, 7, 46, 6, 47], 730);
                step(f, Op::AddV, &[30, 18, 48, 56, 56, 58, 58], 731);
                step(f, Op::SubV, &[48, 21, 18], 732);
                step(f, Op::DeltaTime, &[211], 733);
                step(f, Op::DivFScaleV, &[58, 211, 186, 18, 186, 49], 734);
                step(f, Op::AddVAddV, &[48, 49, 50, 21, 49, 51], 735);
                step(f, Op::SubV, &[46, 51, 49], 736);
                step(f, Op::FloatLerp, &[158, 160, 56, 215], 737);
                step(f, Op::SubF, &[160, 215, 195], 738);
                step(f, Op::ScaleV, &[49, 195, 51], 739);
                step(f, Op::AddV, &[50, 51, 49], 740);
                step(f, Op::MulF, &[56, 211, 183], 741);
                step(f, Op::GreaterF, &[183, 158, 16], 742);
                step(f, Op::DivF, &[215, 183, 216], 743);
                step(f, Op::Select(ValueType::Float), &[16, 216, 160, 184], 744);
                step(f, Op::ScaleV, &[18, 184, 50], 745);
                step(f, Op::SubV, &[49, 50, 51, 51, 51], 746);
                step(f, Op::BreakVector, &[51, 193, 194, 197], 747);
                step(f, Op::ClampF, &[197, 69, 70, 214], 748);
                step(f, Op::MakeVector, &[193, 194, 214, 18], 749);
                step(f, Op::MakeTransform, &[18, 6, 6, 8], 750);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 7, 8], 751);
                step(f, Op::MakeTransform, &[48, 1, 6, 8], 752);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 7, 8], 753);
                step(f, Op::JumpIfFalse, &[12, 755], 754)
            }
            754 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 7], 755);
                755
            }
            755 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 14], 756);
                756
            }
            756 => {
                step(f, Op::JumpIfFalse, &[14, 925], 757)
            }
            757 => {
                step(f, Op::GetTransformBreakTransform, &[34, 2, 9, 4, 4, 22, 3, 19], 758);
                step(f, Op::BreakVector, &[22, 209, 213, 208], 759);
                step(f, Op::SubFMulF, &[160, 18, 207, 17, 207, 185], 760);
                step(f, Op::QuatFromAxisAngle, &[10, 185, 4], 761);
                step(f, Op::GetTransformBreakTransform, &[0, 2, 9, 5, 5, 23, 5, 24], 762);
                step(f, Op::SubV, &[23, 22, 25], 763);
                step(f, Op::BreakVector, &[25, 189, 187, 182], 764);
                step(f, Op::MakeVector, &[189, 187, 158, 26], 765);
                step(f, Op::RotateVector, &[4, 26, 27], 766);
                step(f, Op::BreakVector, &[27, 196, 220, 200], 767);
                step(f, Op::MulF, &[53, 18, 188], 768);
                step(f, Op::Equals(Elem::Int), &[7, 2, 15], 769);
                step(f, Op::Select(ValueType::Float), &[15, 160, 162, 222], 770);
                step(f, Op::MulFAddF, &[188, 222, 218, 196, 218, 199], 771);
                step(f, Op::AddFAddF, &[209, 199, 212, 213, 220, 192], 772);
                step(f, Op::BreakVector, &[23, 219, 191, 221], 773);
                step(f, Op::SubF, &[221, 59, 198], 774);
                step(f, Op::MakeVector, &[212, 192, 198, 28], 775);
                step(f, Op::SubF, &[160, 204, 210], 776);
                step(f, Op::MaxF, &[210, 158, 217], 777);
                step(f, Op::MulFMulF, &[13, 10, 190, 217, 190, 205], 778);
                step(f, Op::ScaleV, &[2, 205, 49], 779);
                step(f, Op::AddV, &[28, 49, 50], 780);
                step(f, Op::MulFScaleV, &[9, 159, 202, 2, 202, 29], 781);
                step(f, Op::AddV, &[50, 29, 51], 782);
                step(f, Op::RotateVector, &[0, 9, 33], 783);
                step(f, Op::Copy(ValueType::Float), &[165, 206], 784);
                step(f, Op::Copy(ValueType::Vec3), &[7, 18], 785);
                step(f, Op::Copy(ValueType::Vec3), &[10, 48], 786);
                step(f, Op::Copy(ValueType::Bool), &[10, 19], 787);
                step(f, Op::Copy(ValueType::Float), &[165, 186], 788);
                step(f, Op::Copy(ValueType::Vec3), &[7, 50], 789);
                step(f, Op::MulI, &[0, 0, 6, 6, 6], 790);
                step(f, Op::Copy(ValueType::Int), &[2, 8], 791);
                step(f, Op::SubI, &[0, 3, 10], 792);
                step(f, Op::DivI, &[10, 4, 11], 793);
                step(f, Op::MakeVector, &[158, 158, 64, 52], 794);
                step(f, Op::ScaleV, &[33, 68, 53], 795);
                795
            }
            795 => {
                step(f, Op::ForNext, &[8, 6, 10, 836], 796)
            }
            796 => {
                step(f, Op::ModI, &[10, 0, 12], 797);
                step(f, Op::ToFloat, &[12, 195], 798);
                step(f, Op::MulFMulF, &[195, 65, 211, 211, 222, 183], 799);
                step(f, Op::MakeVector, &[183, 158, 158, 54], 800);
                step(f, Op::DivI, &[10, 0, 12], 801);
                step(f, Op::SubI, &[12, 11, 10], 802);
                step(f, Op::ToFloat, &[10, 215], 803);
                step(f, Op::MulFScaleV, &[215, 65, 216, 33, 216, 55], 804);
                step(f, Op::AddVAddV, &[54, 55, 56, 51, 56, 54], 805);
                step(f, Op::AddVSubV, &[54, 52, 55, 54, 52, 57], 806);
                step(f, Op::SphereTrace, &[55, 57, 63, 20, 54, 58, 184], 807);
                step(f, Op::BreakVector, &[54, 197, 193, 194], 808);
                step(f, Op::AddVAddV, &[55, 53, 59, 57, 53, 55], 809);
                step(f, Op::SphereTrace, &[59, 55, 63, 13, 57, 60, 214], 810);
                step(f, Op::BreakVector, &[57, 195, 211, 183], 811);
                step(f, Op::SubF, &[194, 183, 215], 812);
                step(f, Op::AbsF, &[215, 216], 813);
                step(f, Op::Select(ValueType::Float), &[20, 158, 160, 184], 814);
                step(f, Op::AddF, &[216, 184, 193], 815);
                step(f, Op::LengthV, &[56, 197], 816);
                step(f, Op::RemapF, &[197, 158, 171, 158, 160, 9, 214], 817);
                step(f, Op::MinF, &[194, 183, 195], 818);
                step(f, Op::RemapF, &[195, 172, 171, 160, 159, 9, 211], 819);
                step(f, Op::AddFAddF, &[214, 211, 215, 193, 215, 184], 820);
                step(f, Op::LessF, &[184, 206, 16], 821);
                step(f, Op::And, &[20, 16, 12], 822);
                step(f, Op::JumpIfFalse, &[12, 830], 823)
            }
            823 => {
                step(f, Op::Copy(ValueType::Float), &[206, 186], 824);
                step(f, Op::Copy(ValueType::Vec3), &[18, 50], 825);
                step(f, Op::Copy(ValueType::Float), &[184, 206], 826);
                step(f, Op::Copy(ValueType::Vec3), &[54, 18], 827);
                step(f, Op::Copy(ValueType::Vec3), &[58, 48], 828);
                step(f, Op::Copy(ValueType::Bool), &[9, 19], 829);
                step(f, Op::Jump, &[835], 830)
            }
            830 => {
                step(f, Op::LessF, &[184, 186, 14], 831);
                step(f, Op::And, &[20, 14, 15], 832);
                step(f, Op::JumpIfFalse, &[15, 835], 833)
            }
            833 => {
                step(f, Op::Copy(ValueType::Float), &[184, 186], 834);
                step(f, Op::Copy(ValueType::Vec3), &[54, 50], 835);
                835
            }
            835 => {
                step(f, Op::Jump, &[795], 836)
            }
            836 => {
                step(f, Op::JumpIfFalse, &[8, 838], 837)
            }
            837 => {
                step(f, Op::DrawSphere, &[18, 63, 9], 838);
                838
            }
            838 => {
                step(f, Op::GreaterF, &[67, 158, 13], 839);
                step(f, Op::SubF, &[206, 186, 216], 840);
                step(f, Op::DivF, &[216, 67, 197], 841);
                step(f, Op::PowF, &[173, 197, 183], 842);
                step(f, Op::Select(ValueType::Float), &[13, 183, 158, 194], 843);
                step(f, Op::ScaleV, &[50, 194, 55], 844);
                step(f, Op::AddV, &[18, 55, 59], 845);
                step(f, Op::AddF, &[194, 160, 195], 846);
                step(f, Op::DivFScaleV, &[160, 195, 211, 59, 211, 60, 60, 60, 48, 48, 19, 19], 847);
                step(f, Op::ArrayAtBreakTransform, &[1, 7, 7, 7, 46, 6, 47], 848);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 204], 849);
                step(f, Op::SubF, &[160, 204, 210], 850);
                step(f, Op::MaxF, &[210, 158, 217], 851);
                step(f, Op::MulFMulF, &[13, 10, 190, 217, 190, 205], 852);
                step(f, Op::ScaleV, &[2, 205, 49], 853);
                step(f, Op::SubV, &[60, 49, 57], 854);
                step(f, Op::Select(ValueType::Vec3), &[19, 57, 46, 56], 855);
                step(f, Op::ArrayAtBreakTransform, &[2, 7, 6, 6, 21, 2, 20, 56, 56, 58, 58], 856);
                step(f, Op::SubV, &[56, 21, 58], 857);
                step(f, Op::DeltaTime, &[214], 858);
                step(f, Op::DivFScaleV, &[58, 214, 193, 58, 193, 54], 859);
                step(f, Op::AddVAddV, &[56, 54, 51, 21, 54, 52], 860);
                step(f, Op::SubV, &[46, 52, 53], 861);
                step(f, Op::FloatLerp, &[158, 160, 56, 215], 862);
                step(f, Op::SubF, &[160, 215, 184], 863);
                step(f, Op::ScaleV, &[53, 184, 50], 864);
                step(f, Op::AddV, &[51, 50, 18], 865);
                step(f, Op::MulF, &[56, 214, 186], 866);
                step(f, Op::GreaterF, &[186, 158, 16], 867);
                step(f, Op::DivF, &[215, 186, 206], 868);
                step(f, Op::Select(ValueType::Float), &[16, 206, 160, 216], 869);
                step(f, Op::ScaleV, &[58, 216, 55], 870);
                step(f, Op::SubV, &[18, 55, 59, 59, 59], 871);
                step(f, Op::BreakVector, &[59, 197, 183, 194], 872);
                step(f, Op::ClampF, &[194, 69, 70, 195], 873);
                step(f, Op::MakeVector, &[197, 183, 195, 49], 874);
                step(f, Op::RotationFromNormal, &[48, 211, 210, 2], 875);
                step(f, Op::PerFootRotationFactor, &[17, 119, 120, 190], 876);
                step(f, Op::MulFSubF, &[17, 190, 217, 160, 18, 207], 877);
                step(f, Op::MulF, &[217, 207, 205], 878);
                step(f, Op::QuatFromAxisAngle, &[10, 205, 7], 879);
                step(f, Op::MulQ, &[2, 7, 8], 880);
                step(f, Op::Select(ValueType::Quat), &[19, 8, 6, 2], 881);
                step(f, Op::MakeTransform, &[49, 2, 6, 8], 882);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 7, 8], 883);
                step(f, Op::ArrayAtBreakTransform, &[1, 7, 7, 7, 46, 6, 47], 884);
                step(f, Op::Select(ValueType::Vec3), &[19, 57, 46, 56], 885);
                step(f, Op::MakeTransform, &[56, 1, 6, 6], 886);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 7, 6], 887);
                step(f, Op::GetTransformBreakTransform, &[34, 2, 9, 4, 4, 22, 3, 19], 888);
                step(f, Op::BreakVector, &[22, 209, 213, 208], 889);
                step(f, Op::MulF, &[17, 207, 185], 890);
                step(f, Op::QuatFromAxisAngle, &[10, 185, 4], 891);
                step(f, Op::GetTransformBreakTransform, &[0, 2, 9, 5, 5, 23, 5, 24], 892);
                step(f, Op::SubV, &[23, 22, 25], 893);
                step(f, Op::BreakVector, &[25, 189, 187, 182], 894);
                step(f, Op::MakeVector, &[189, 187, 158, 26], 895);
                step(f, Op::RotateVector, &[4, 26, 27], 896);
                step(f, Op::BreakVector, &[27, 196, 220, 200], 897);
                step(f, Op::MulFMulF, &[53, 18, 188, 188, 222, 218], 898);
                step(f, Op::AddFAddF, &[196, 218, 199, 209, 199, 212], 899);
                step(f, Op::AddF, &[213, 220, 192], 900);
                step(f, Op::BreakVector, &[23, 219, 191, 221], 901);
                step(f, Op::SubF, &[221, 59, 198], 902);
                step(f, Op::MakeVector, &[212, 192, 198, 28], 903);
                step(f, Op::MulFScaleV, &[9, 159, 202, 2, 202, 29], 904);
                step(f, Op::AddVSubV, &[28, 29, 30, 56, 30, 60], 905);
                step(f, Op::ArraySetAt(Elem::Vec3), &[0, 7, 60], 906);
                step(f, Op::ArraySetAt(Elem::Bool), &[1, 7, 19], 907);
                step(f, Op::GreaterEqualF, &[204, 160, 11], 908);
                step(f, Op::JumpIfFalse, &[11, 923], 909)
            }
            909 => {
                step(f, Op::MakeVector, &[158, 158, 64, 17], 910);
                step(f, Op::AddV, &[30, 17, 31], 911);
                step(f, Op::RotateVector, &[0, 9, 33], 912);
                step(f, Op::ScaleV, &[33, 68, 34], 913);
                step(f, Op::AddVSubV, &[31, 34, 35, 30, 17, 32], 914);
                step(f, Op::AddV, &[32, 34, 36], 915);
                step(f, Op::SphereTrace, &[35, 36, 63, 17, 37, 38, 201], 916);
                step(f, Op::SubV, &[37, 30, 39], 917);
                step(f, Op::ArraySetAt(Elem::Vec3), &[1, 7, 39], 918);
                step(f, Op::ScaleV, &[33, 65, 40], 919);
                step(f, Op::AddVAddV, &[35, 40, 41, 36, 40, 42], 920);
                step(f, Op::SphereTrace, &[41, 42, 63, 18, 43, 44, 203], 921);
                step(f, Op::SubV, &[43, 30, 45], 922);
                step(f, Op::ArraySetAt(Elem::Vec3), &[2, 7, 45], 923);
                923
            }
            923 => {
                step(f, Op::JumpIfFalse, &[19, 925], 924)
            }
            924 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 7], 925);
                925
            }
            925 => {
                step(f, Op::ArrayAt(Elem::Float), &[4, 7, 193], 926);
                step(f, Op::FloatLerp, &[193, 158, 112, 184], 927);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 7, 12], 928);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 214], 929);
                step(f, Op::GreaterEqualF, &[214, 160, 14], 930);
                step(f, Op::And, &[12, 14, 20], 931);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 7, 8], 932);
                step(f, Op::GreaterF, &[27, 158, 15], 933);
                step(f, Op::InterpolateTransform, &[2, 3, 28, 7], 934);
                step(f, Op::Select(ValueType::Transform), &[15, 7, 2, 6], 935);
                step(f, Op::MakeAbsolute, &[8, 6, 4], 936);
                step(f, Op::BreakTransform, &[4, 20, 7, 21], 937);
                step(f, Op::RotateVector, &[7, 9, 54], 938);
                step(f, Op::SubFMulF, &[160, 18, 186, 17, 186, 215], 939);
                step(f, Op::LimitRotationAroundZ, &[7, 215, 109, 8], 940);
                step(f, Op::RotateVector, &[8, 9, 52], 941);
                step(f, Op::CrossV, &[54, 52, 53], 942);
                step(f, Op::BreakVector, &[53, 206, 216, 194], 943);
                step(f, Op::DotV, &[54, 52, 183], 944);
                step(f, Op::Atan2F, &[194, 183, 195], 945);
                step(f, Op::AbsF, &[195, 197], 946);
                step(f, Op::Select(ValueType::Float), &[20, 197, 158, 210], 947);
                step(f, Op::AddF, &[184, 210, 211], 948);
                step(f, Op::ArraySetAt(Elem::Float), &[4, 7, 211], 949);
                step(f, Op::ArrayAtBreakTransform, &[8, 7, 5, 5, 50, 2, 51], 950);
                step(f, Op::AddF, &[73, 74, 190], 951);
                step(f, Op::ClampSpatially, &[20, 50, 158, 190, 58], 952);
                step(f, Op::MakeTransform, &[58, 8, 6, 8], 953);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 7, 8], 954);
                step(f, Op::JumpIfFalse, &[12, 1020], 955)
            }
            955 => {
                step(f, Op::JumpIfFalse, &[14, 957], 956)
            }
            956 => {
                step(f, Op::Jump, &[1019], 957)
            }
            957 => {
                step(f, Op::ArrayAtBreakTransform, &[1, 7, 4, 4, 18, 6, 55], 958);
                step(f, Op::SubFMulF, &[160, 214, 217, 13, 10, 205], 959);
                step(f, Op::MulFScaleV, &[217, 205, 208, 2, 208, 59], 960);
                step(f, Op::AddV, &[18, 59, 48], 961);
                step(f, Op::Equals(Elem::Int), &[7, 2, 13], 962);
                step(f, Op::Select(ValueType::Int), &[13, 3, 2, 12], 963);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 16], 964);
                step(f, Op::ArrayAtBreakTransform, &[0, 12, 5, 5, 49, 3, 47], 965);
                step(f, Op::ArrayAtBreakTransform, &[3, 12, 8, 8, 46, 5, 57], 966);
                step(f, Op::LessEqualF, &[95, 158, 11], 967);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 207], 968);
                step(f, Op::SmoothStepF, &[207, 158, 95, 185], 969);
                step(f, Op::Select(ValueType::Float), &[11, 160, 185, 182], 970);
                step(f, Op::LerpV, &[49, 46, 182, 19], 971);
                step(f, Op::MakeTransform, &[19, 1, 6, 9], 972);
                step(f, Op::Select(ValueType::Transform), &[16, 5, 9, 10], 973);
                step(f, Op::MakeAbsolute, &[10, 6, 11], 974);
                step(f, Op::Select(ValueType::Transform), &[13, 11, 10, 12], 975);
                step(f, Op::BreakTransform, &[12, 24, 4, 22], 976);
                step(f, Op::SubFMulF, &[160, 19, 187, 186, 187, 189], 977);
                step(f, Op::MulF, &[17, 189, 200], 978);
                step(f, Op::FootAvoidance, &[48, 24, 200, 13, 91, 25], 979);
                step(f, Op::RemapF, &[18, 94, 160, 158, 160, 9, 188], 980);
                step(f, Op::LerpV, &[48, 25, 188, 26], 981);
                step(f, Op::FootAvoidance, &[26, 24, 20, 13, 117, 27], 982);
                step(f, Op::LerpV, &[26, 27, 19, 23], 983);
                step(f, Op::MakeTransform, &[23, 6, 6, 13], 984);
                step(f, Op::BreakTransform, &[13, 28, 7, 29], 985);
                step(f, Op::MakeVector, &[158, 158, 64, 56], 986);
                step(f, Op::AddVSubV, &[28, 56, 60, 28, 56, 31], 987);
                step(f, Op::LineTrace, &[60, 31, 17, 17, 32, 222], 988);
                step(f, Op::RotateVector, &[7, 10, 34], 989);
                step(f, Op::FindQuatBetween, &[34, 32, 2], 990);
                step(f, Op::MulQ, &[2, 7, 8], 991);
                step(f, Op::MulFAddF, &[62, 61, 196, 196, 72, 218], 992);
                step(f, Op::NegF, &[218, 199], 993);
                step(f, Op::MakeVector, &[158, 199, 158, 38], 994);
                step(f, Op::RotateVector, &[8, 38, 37], 995);
                step(f, Op::AddVAddV, &[17, 37, 39, 39, 56, 33], 996);
                step(f, Op::SubV, &[39, 56, 35], 997);
                step(f, Op::LineTrace, &[33, 35, 18, 36, 40, 209], 998);
                step(f, Op::BreakVector, &[36, 213, 220, 191], 999);
                step(f, Op::BreakVector, &[39, 219, 221, 192], 1000);
                step(f, Op::SubF, &[191, 192, 198], 1001);
                step(f, Op::Select(ValueType::Float), &[18, 198, 158, 212], 1002);
                step(f, Op::AddF, &[68, 72, 202], 1003);
                step(f, Op::MakeVector, &[158, 202, 158, 41], 1004);
                step(f, Op::RotateVector, &[8, 41, 42], 1005);
                step(f, Op::AddVAddV, &[17, 42, 44, 44, 56, 30], 1006);
                step(f, Op::SubV, &[44, 56, 43], 1007);
                step(f, Op::LineTrace, &[30, 43, 19, 45, 21, 204], 1008);
                step(f, Op::BreakVector, &[45, 201, 203, 193], 1009);
                step(f, Op::BreakVector, &[44, 215, 206, 216], 1010);
                step(f, Op::SubF, &[193, 216, 183], 1011);
                step(f, Op::Select(ValueType::Float), &[19, 183, 158, 194], 1012);
                step(f, Op::MaxF, &[212, 194, 195], 1013);
                step(f, Op::ClampF, &[195, 158, 71, 197], 1014);
                step(f, Op::MakeVector, &[158, 158, 197, 53], 1015);
                step(f, Op::AddV, &[17, 53, 52], 1016);
                step(f, Op::MakeTransform, &[52, 8, 6, 14], 1017);
                step(f, Op::Select(ValueType::Transform), &[17, 14, 13, 15, 15, 15], 1018);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 7, 15], 1019);
                1019
            }
            1019 => {
                step(f, Op::Jump, &[1118], 1020)
            }
            1020 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 7, 13], 1021);
                step(f, Op::MakeAbsolute, &[13, 6, 14], 1022);
                step(f, Op::BreakTransform, &[14, 54, 2, 51], 1023);
                step(f, Op::ArrayAtBreakTransform, &[1, 7, 4, 4, 18, 6, 55], 1024);
                step(f, Op::SubFMulF, &[160, 214, 217, 13, 10, 205], 1025);
                step(f, Op::MulFScaleV, &[217, 205, 208, 2, 208, 59], 1026);
                step(f, Op::AddV, &[18, 59, 48], 1027);
                step(f, Op::Equals(Elem::Int), &[7, 2, 13], 1028);
                step(f, Op::Select(ValueType::Int), &[13, 3, 2, 12], 1029);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 16], 1030);
                step(f, Op::ArrayAtBreakTransform, &[0, 12, 5, 5, 49, 3, 47], 1031);
                step(f, Op::ArrayAtBreakTransform, &[3, 12, 8, 8, 46, 5, 57], 1032);
                step(f, Op::LessEqualF, &[95, 158, 11], 1033);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 207], 1034);
                step(f, Op::SmoothStepF, &[207, 158, 95, 185], 1035);
                step(f, Op::Select(ValueType::Float), &[11, 160, 185, 182], 1036);
                step(f, Op::LerpV, &[49, 46, 182, 19], 1037);
                step(f, Op::MakeTransform, &[19, 1, 6, 9], 1038);
                step(f, Op::Select(ValueType::Transform), &[16, 5, 9, 10], 1039);
                step(f, Op::MakeAbsolute, &[10, 6, 11], 1040);
                step(f, Op::Select(ValueType::Transform), &[13, 11, 10, 12], 1041);
                step(f, Op::BreakTransform, &[12, 24, 4, 22], 1042);
                step(f, Op::SubFMulF, &[160, 19, 187, 186, 187, 189], 1043);
                step(f, Op::MulF, &[17, 189, 200], 1044);
                step(f, Op::FootAvoidance, &[48, 24, 200, 13, 91, 25], 1045);
                step(f, Op::RemapF, &[18, 94, 160, 158, 160, 9, 188], 1046);
                step(f, Op::LerpV, &[48, 25, 188, 26], 1047);
                step(f, Op::FootAvoidance, &[26, 24, 20, 13, 117, 27], 1048);
                step(f, Op::LerpV, &[26, 27, 19, 23], 1049);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 7, 15], 1050);
                step(f, Op::MakeAbsolute, &[15, 6, 13], 1051);
                step(f, Op::BreakTransform, &[13, 20, 7, 58], 1052);
                step(f, Op::ArrayAt(Elem::Float), &[3, 7, 184], 1053);
                step(f, Op::SubF, &[214, 184, 210], 1054);
                step(f, Op::DeltaTime, &[211], 1055);
                step(f, Op::DivF, &[58, 211, 190], 1056);
                step(f, Op::MulFAddF, &[210, 190, 222, 184, 222, 196], 1057);
                step(f, Op::ClampF, &[196, 158, 160, 218], 1058);
                step(f, Op::AddF, &[214, 222, 199], 1059);
                step(f, Op::ClampF, &[199, 158, 160, 209], 1060);
                step(f, Op::AddFMulF, &[218, 209, 213, 213, 159, 220], 1061);
                step(f, Op::SubF, &[160, 220, 219], 1062);
                step(f, Op::GreaterF, &[210, 158, 20], 1063);
                step(f, Op::SubF, &[209, 218, 221], 1064);
                step(f, Op::DivF, &[221, 210, 191], 1065);
                step(f, Op::Select(ValueType::Float), &[20, 191, 160, 192], 1066);
                step(f, Op::MulFMulF, &[219, 192, 198, 90, 198, 202, 58, 58], 1067);
                step(f, Op::SubV, &[23, 20, 29], 1068);
                step(f, Op::DeltaTime, &[204], 1069);
                step(f, Op::DivFScaleV, &[58, 204, 201, 29, 201, 28], 1070);
                step(f, Op::AddVAddV, &[23, 28, 31, 20, 28, 60], 1071);
                step(f, Op::SubV, &[54, 60, 32], 1072);
                step(f, Op::FloatLerp, &[158, 160, 202, 203], 1073);
                step(f, Op::SubF, &[160, 203, 206], 1074);
                step(f, Op::ScaleV, &[32, 206, 34], 1075);
                step(f, Op::AddV, &[31, 34, 38], 1076);
                step(f, Op::MulF, &[202, 204, 215], 1077);
                step(f, Op::GreaterF, &[215, 158, 18], 1078);
                step(f, Op::DivF, &[203, 215, 193], 1079);
                step(f, Op::Select(ValueType::Float), &[18, 193, 160, 216], 1080);
                step(f, Op::ScaleV, &[29, 216, 37], 1081);
                step(f, Op::SubV, &[38, 37, 33, 33, 33], 1082);
                step(f, Op::MakeTransform, &[33, 6, 6, 14], 1083);
                step(f, Op::BreakTransform, &[14, 35, 8, 40], 1084);
                step(f, Op::MakeVector, &[158, 158, 64, 36], 1085);
                step(f, Op::AddVSubV, &[35, 36, 39, 35, 36, 41], 1086);
                step(f, Op::LineTrace, &[39, 41, 19, 42, 56, 183], 1087);
                step(f, Op::RotateVector, &[8, 10, 21], 1088);
                step(f, Op::FindQuatBetween, &[21, 56, 2], 1089);
                step(f, Op::MulQ, &[2, 8, 7], 1090);
                step(f, Op::MulFAddF, &[62, 61, 194, 194, 72, 212], 1091);
                step(f, Op::NegF, &[212, 195], 1092);
                step(f, Op::MakeVector, &[158, 195, 158, 30], 1093);
                step(f, Op::RotateVector, &[7, 30, 43], 1094);
                step(f, Op::AddVAddV, &[42, 43, 45, 45, 36, 44], 1095);
                step(f, Op::SubV, &[45, 36, 17], 1096);
                step(f, Op::LineTrace, &[44, 17, 17, 53, 52, 197], 1097);
                step(f, Op::BreakVector, &[53, 211, 190, 184], 1098);
                step(f, Op::BreakVector, &[45, 196, 222, 199], 1099);
                step(f, Op::SubF, &[184, 199, 213], 1100);
                step(f, Op::Select(ValueType::Float), &[17, 213, 158, 220], 1101);
                step(f, Op::AddF, &[68, 72, 209], 1102);
                step(f, Op::MakeVector, &[158, 209, 158, 51], 1103);
                step(f, Op::RotateVector, &[7, 51, 58], 1104);
                step(f, Op::AddVAddV, &[42, 58, 20, 20, 36, 28], 1105);
                step(f, Op::SubV, &[20, 36, 54], 1106);
                step(f, Op::LineTrace, &[28, 54, 20, 60, 32, 218], 1107);
                step(f, Op::BreakVector, &[60, 210, 221, 191], 1108);
                step(f, Op::BreakVector, &[20, 192, 219, 198], 1109);
                step(f, Op::SubF, &[191, 198, 201], 1110);
                step(f, Op::Select(ValueType::Float), &[20, 201, 158, 206], 1111);
                step(f, Op::MaxF, &[220, 206, 202], 1112);
                step(f, Op::ClampF, &[202, 158, 71, 204], 1113);
                step(f, Op::MakeVector, &[158, 158, 204, 31], 1114);
                step(f, Op::AddV, &[42, 31, 34], 1115);
                step(f, Op::MakeTransform, &[34, 7, 6, 15], 1116);
                step(f, Op::Select(ValueType::Transform), &[19, 15, 14, 13, 13, 13], 1117);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 7, 13], 1118);
                1118
            }
            1118 => {
                step(f, Op::JumpIfFalse, &[14, 1188], 1119)
            }
            1119 => {
                step(f, Op::JumpIfFalse, &[12, 1121], 1120)
            }
            1120 => {
                step(f, Op::Jump, &[1174], 1121)
            }
            1121 => {
                step(f, Op::ArrayAtBreakTransform, &[3, 7, 14, 14, 29, 2, 37], 1122);
                step(f, Op::Equals(Elem::Int), &[7, 2, 13], 1123);
                step(f, Op::Select(ValueType::Int), &[13, 3, 2, 12], 1124);
                step(f, Op::ArrayAtBreakTransform, &[6, 12, 15, 15, 38, 8, 33], 1125);
                step(f, Op::MakeAbsolute, &[15, 6, 13], 1126);
                step(f, Op::BreakTransform, &[13, 40, 7, 35], 1127);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 207], 1128);
                step(f, Op::SmoothStepF, &[207, 158, 160, 203], 1129);
                step(f, Op::RemapF, &[18, 158, 94, 158, 160, 9, 215], 1130);
                step(f, Op::MulF, &[203, 215, 193], 1131);
                step(f, Op::Select(ValueType::Float), &[13, 193, 158, 216], 1132);
                step(f, Op::LerpV, &[38, 40, 216, 39], 1133);
                step(f, Op::MakeTransform, &[39, 1, 6, 16], 1134);
                step(f, Op::BreakTransform, &[16, 41, 9, 21], 1135);
                step(f, Op::SubFMulF, &[160, 19, 187, 186, 187, 189], 1136);
                step(f, Op::MulF, &[17, 189, 200], 1137);
                step(f, Op::FootAvoidance, &[29, 41, 200, 13, 91, 56], 1138);
                step(f, Op::MakeTransform, &[56, 2, 6, 17], 1139);
                step(f, Op::BreakTransform, &[17, 30, 2, 43], 1140);
                step(f, Op::MakeVector, &[158, 158, 64, 17], 1141);
                step(f, Op::AddVSubV, &[30, 17, 44, 30, 17, 52], 1142);
                step(f, Op::LineTrace, &[44, 52, 18, 53, 45, 183], 1143);
                step(f, Op::RotateVector, &[2, 10, 51], 1144);
                step(f, Op::FindQuatBetween, &[51, 45, 10], 1145);
                step(f, Op::MulQ, &[10, 2, 11], 1146);
                step(f, Op::MulFAddF, &[62, 61, 194, 194, 72, 212], 1147);
                step(f, Op::NegF, &[212, 195], 1148);
                step(f, Op::MakeVector, &[158, 195, 158, 58], 1149);
                step(f, Op::RotateVector, &[11, 58, 36], 1150);
                step(f, Op::AddVAddV, &[53, 36, 28, 28, 17, 32], 1151);
                step(f, Op::SubV, &[28, 17, 54], 1152);
                step(f, Op::LineTrace, &[32, 54, 17, 60, 20, 197], 1153);
                step(f, Op::BreakVector, &[60, 190, 211, 196], 1154);
                step(f, Op::BreakVector, &[28, 222, 184, 199], 1155);
                step(f, Op::SubF, &[196, 199, 213], 1156);
                step(f, Op::Select(ValueType::Float), &[17, 213, 158, 209], 1157);
                step(f, Op::AddF, &[68, 72, 218], 1158);
                step(f, Op::MakeVector, &[158, 218, 158, 31], 1159);
                step(f, Op::RotateVector, &[11, 31, 42], 1160);
                step(f, Op::AddVAddV, &[53, 42, 34, 34, 17, 37], 1161);
                step(f, Op::SubV, &[34, 17, 29], 1162);
                step(f, Op::LineTrace, &[37, 29, 20, 56, 43, 210], 1163);
                step(f, Op::BreakVector, &[56, 221, 192, 219], 1164);
                step(f, Op::BreakVector, &[34, 191, 198, 201], 1165);
                step(f, Op::SubF, &[219, 201, 206], 1166);
                step(f, Op::Select(ValueType::Float), &[20, 206, 158, 220], 1167);
                step(f, Op::MaxF, &[209, 220, 202], 1168);
                step(f, Op::ClampF, &[202, 158, 71, 204], 1169);
                step(f, Op::MakeVector, &[158, 158, 204, 30], 1170);
                step(f, Op::AddV, &[53, 30, 44], 1171);
                step(f, Op::MakeTransform, &[44, 11, 6, 18], 1172);
                step(f, Op::Select(ValueType::Transform), &[18, 18, 17, 19, 19, 19], 1173);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 7, 19], 1174);
                1174
            }
            1174 => {
                step(f, Op::ArrayAtBreakTransform, &[0, 7, 17, 17, 52, 2, 45], 1175);
                step(f, Op::SubV, &[52, 50, 51], 1176);
                step(f, Op::LengthV, &[51, 183], 1177);
                step(f, Op::SubF, &[73, 74, 194], 1178);
                step(f, Op::SubFMulF, &[183, 194, 212, 74, 163, 195], 1179);
                step(f, Op::ClampF, &[212, 158, 195, 197], 1180);
                step(f, Op::MulFMulF, &[197, 197, 190, 74, 174, 211], 1181);
                step(f, Op::DivFSubF, &[190, 211, 184, 183, 184, 222], 1182);
                step(f, Op::DivFScaleV, &[222, 183, 196, 51, 196, 58], 1183);
                step(f, Op::AddV, &[50, 58, 36], 1184);
                step(f, Op::MakeTransform, &[36, 2, 6, 18], 1185);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 18], 1186);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 18], 1187);
                step(f, Op::Jump, &[1338], 1188)
            }
            1188 => {
                step(f, Op::ArrayAtBreakTransform, &[0, 7, 17, 17, 52, 2, 45], 1189);
                step(f, Op::SubV, &[52, 50, 51], 1190);
                step(f, Op::LengthV, &[51, 183], 1191);
                step(f, Op::SubF, &[73, 74, 194], 1192);
                step(f, Op::SubFMulF, &[183, 194, 212, 74, 163, 195], 1193);
                step(f, Op::ClampF, &[212, 158, 195, 197], 1194);
                step(f, Op::MulFMulF, &[197, 197, 190, 74, 174, 211], 1195);
                step(f, Op::DivFSubF, &[190, 211, 184, 183, 184, 222], 1196);
                step(f, Op::DivFScaleV, &[222, 183, 196, 51, 196, 58], 1197);
                step(f, Op::AddV, &[50, 58, 36], 1198);
                step(f, Op::MakeTransform, &[36, 2, 6, 18], 1199);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 7, 14], 1200);
                step(f, Op::ClampF, &[214, 158, 160, 199], 1201);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[6, 5], 1202);
                step(f, Op::ArrayReset(Elem::Vec3), &[5], 1203);
                step(f, Op::BreakTransform, &[18, 20, 10, 32], 1204);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 20], 1205);
                step(f, Op::UnitV, &[2, 54], 1206);
                step(f, Op::LengthV, &[2, 213], 1207);
                step(f, Op::RemapF, &[213, 158, 75, 158, 76, 9, 218], 1208);
                step(f, Op::ScaleV, &[54, 218, 60], 1209);
                step(f, Op::SubV, &[20, 60, 28], 1210);
                step(f, Op::MakeVector, &[158, 158, 78, 31], 1211);
                step(f, Op::AddV, &[28, 31, 42], 1212);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 42], 1213);
                step(f, Op::RemapF, &[213, 158, 75, 158, 81, 9, 210], 1214);
                step(f, Op::MakeVector, &[158, 158, 210, 17], 1215);
                step(f, Op::AddV, &[42, 17, 29], 1216);
                step(f, Op::BreakTransform, &[14, 37, 11, 43], 1217);
                step(f, Op::BreakVector, &[37, 192, 221, 191], 1218);
                step(f, Op::BreakVector, &[20, 198, 201, 219], 1219);
                step(f, Op::SubF, &[191, 219, 206], 1220);
                step(f, Op::MaxF, &[206, 158, 209], 1221);
                step(f, Op::MulF, &[209, 83, 220], 1222);
                step(f, Op::MinF, &[220, 84, 202], 1223);
                step(f, Op::AbsF, &[206, 204], 1224);
                step(f, Op::RemapF, &[204, 158, 87, 158, 86, 9, 194], 1225);
                step(f, Op::AddF, &[202, 194, 195], 1226);
                step(f, Op::MakeVector, &[158, 158, 195, 56], 1227);
                step(f, Op::AddV, &[29, 56, 34], 1228);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 34], 1229);
                step(f, Op::RemapF, &[213, 158, 75, 158, 77, 9, 212], 1230);
                step(f, Op::ScaleV, &[54, 212, 30], 1231);
                step(f, Op::AddV, &[37, 30, 53], 1232);
                step(f, Op::LerpF, &[29, 52, 18, 197], 1233);
                step(f, Op::MulF, &[14, 197, 190], 1234);
                step(f, Op::RemapF, &[190, 160, 38, 79, 80, 9, 211], 1235);
                step(f, Op::MakeVector, &[158, 158, 211, 44], 1236);
                step(f, Op::AddV, &[53, 44, 45], 1237);
                step(f, Op::RemapF, &[213, 158, 75, 158, 82, 9, 184], 1238);
                step(f, Op::MakeVector, &[158, 158, 184, 52], 1239);
                step(f, Op::AddV, &[45, 52, 51], 1240);
                step(f, Op::NegF, &[206, 183], 1241);
                step(f, Op::MaxF, &[183, 158, 222], 1242);
                step(f, Op::MulFAddF, &[222, 85, 196, 196, 194, 218], 1243);
                step(f, Op::MakeVector, &[158, 158, 218, 50], 1244);
                step(f, Op::AddV, &[51, 50, 58], 1245);
                step(f, Op::LerpV, &[34, 58, 159, 36], 1246);
                step(f, Op::GetTransformBreakTransform, &[35, 2, 9, 19, 19, 32, 2, 60], 1247);
                step(f, Op::BreakVector, &[32, 210, 192, 221], 1248);
                step(f, Op::SubFMulF, &[160, 18, 198, 88, 198, 201], 1249);
                step(f, Op::MulF, &[17, 201, 191], 1250);
                step(f, Op::QuatFromAxisAngle, &[10, 191, 2], 1251);
                step(f, Op::SubV, &[36, 32, 28], 1252);
                step(f, Op::BreakVector, &[28, 219, 209, 220], 1253);
                step(f, Op::MakeVector, &[219, 209, 158, 31], 1254);
                step(f, Op::RotateVector, &[2, 31, 17], 1255);
                step(f, Op::BreakVector, &[17, 204, 202, 195], 1256);
                step(f, Op::AddFAddF, &[210, 204, 212, 192, 202, 197], 1257);
                step(f, Op::BreakVector, &[36, 190, 211, 213], 1258);
                step(f, Op::MakeVector, &[212, 197, 213, 42], 1259);
                step(f, Op::DistanceV, &[20, 37, 184], 1260);
                step(f, Op::RemapF, &[184, 163, 175, 158, 160, 9, 206], 1261);
                step(f, Op::LerpV, &[36, 42, 206, 43], 1262);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 43], 1263);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 58], 1264);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 45], 1265);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 37], 1266);
                step(f, Op::JumpIfFalse, &[8, 1268], 1267)
            }
            1267 => {
                step(f, Op::DrawSpline, &[5, 2, 5, 159, 12], 1268);
                1268
            }
            1268 => {
                step(f, Op::Spline, &[5, 199, 2, 29, 56], 1269);
                step(f, Op::SlerpQ, &[10, 11, 199, 2], 1270);
                step(f, Op::MulF, &[199, 168, 183], 1271);
                step(f, Op::SinF, &[183, 222], 1272);
                step(f, Op::SmoothStepF, &[199, 158, 102, 194], 1273);
                step(f, Op::MulFMulF, &[222, 194, 196, 196, 89, 218], 1274);
                step(f, Op::SlerpQ, &[2, 1, 218, 10], 1275);
                step(f, Op::MakeTransform, &[29, 10, 6, 17, 17, 17], 1276);
                step(f, Op::BreakTransform, &[17, 54, 11, 30], 1277);
                step(f, Op::Equals(Elem::Int), &[7, 2, 13], 1278);
                step(f, Op::Select(ValueType::Int), &[13, 3, 2, 12], 1279);
                step(f, Op::ArrayAtBreakTransform, &[6, 12, 15, 15, 38, 8, 33], 1280);
                step(f, Op::GreaterF, &[27, 158, 15], 1281);
                step(f, Op::InterpolateTransform, &[2, 3, 28, 7], 1282);
                step(f, Op::Select(ValueType::Transform), &[15, 7, 2, 6], 1283);
                step(f, Op::MakeAbsolute, &[15, 6, 13], 1284);
                step(f, Op::BreakTransform, &[13, 40, 7, 35], 1285);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 207], 1286);
                step(f, Op::SmoothStepF, &[207, 158, 160, 203], 1287);
                step(f, Op::RemapF, &[18, 158, 94, 158, 160, 9, 215], 1288);
                step(f, Op::MulF, &[203, 215, 193], 1289);
                step(f, Op::Select(ValueType::Float), &[13, 193, 158, 216], 1290);
                step(f, Op::LerpV, &[38, 40, 216, 39], 1291);
                step(f, Op::MakeTransform, &[39, 1, 6, 16], 1292);
                step(f, Op::BreakTransform, &[16, 41, 9, 21], 1293);
                step(f, Op::SubF, &[160, 18, 186], 1294);
                step(f, Op::SubFMulF, &[160, 19, 187, 186, 187, 189], 1295);
                step(f, Op::MulF, &[17, 189, 200], 1296);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 19], 1297);
                step(f, Op::Select(ValueType::Float), &[19, 92, 158, 221], 1298);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 214], 1299);
                step(f, Op::ClampF, &[214, 158, 160, 199], 1300);
                step(f, Op::MulF, &[199, 168, 198], 1301);
                step(f, Op::SinF, &[198, 201], 1302);
                step(f, Op::MulFMulF, &[201, 201, 191, 221, 191, 220], 1303);
                step(f, Op::AddF, &[91, 220, 209], 1304);
                step(f, Op::FootAvoidance, &[54, 41, 200, 13, 209, 44], 1305);
                step(f, Op::SubV, &[44, 54, 53], 1306);
                step(f, Op::LengthV, &[53, 219], 1307);
                step(f, Op::AddF, &[219, 220, 195], 1308);
                step(f, Op::DivF, &[219, 195, 204], 1309);
                step(f, Op::MulF, &[116, 163, 210], 1310);
                step(f, Op::LessEqualF, &[219, 210, 12], 1311);
                step(f, Op::MulF, &[116, 174, 192], 1312);
                step(f, Op::DivF, &[219, 192, 202], 1313);
                step(f, Op::DivFSubF, &[116, 219, 190, 160, 190, 211], 1314);
                step(f, Op::Select(ValueType::Float), &[12, 202, 211, 197], 1315);
                step(f, Op::GreaterF, &[116, 158, 17], 1316);
                step(f, Op::Select(ValueType::Float), &[17, 19, 158, 212], 1317);
                step(f, Op::LerpF, &[204, 197, 212, 213], 1318);
                step(f, Op::LessF, &[207, 214, 20], 1319);
                step(f, Op::LessEqualF, &[93, 158, 18], 1320);
                step(f, Op::SmoothStepF, &[207, 158, 93, 184], 1321);
                step(f, Op::MulFSubF, &[184, 18, 206, 160, 206, 183], 1322);
                step(f, Op::Select(ValueType::Float), &[18, 160, 183, 194], 1323);
                step(f, Op::Select(ValueType::Float), &[20, 194, 160, 222], 1324);
                step(f, Op::MulF, &[213, 222, 196], 1325);
                step(f, Op::SmoothStepF, &[199, 158, 93, 218], 1326);
                step(f, Op::Select(ValueType::Float), &[18, 160, 218, 203], 1327);
                step(f, Op::MulFScaleV, &[196, 203, 215, 53, 215, 52], 1328);
                step(f, Op::AddV, &[54, 52, 50], 1329);
                step(f, Op::MulFMulF, &[6, 149, 193, 193, 191, 216], 1330);
                step(f, Op::MakeVector, &[158, 158, 216, 51], 1331);
                step(f, Op::AddV, &[50, 51, 34], 1332);
                step(f, Op::MakeTransform, &[34, 11, 6, 18], 1333);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 18], 1334);
                step(f, Op::ScaleV, &[53, 196, 60], 1335);
                step(f, Op::AddVAddV, &[54, 60, 32, 32, 51, 28], 1336);
                step(f, Op::MakeTransform, &[28, 11, 6, 14], 1337);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 14], 1338);
                1338
            }
            1338 => {
                step(f, Op::JumpIfFalse, &[15, 1356], 1339)
            }
            1339 => {
                step(f, Op::ArrayAtBreakTransform, &[5, 7, 19, 19, 31, 2, 17], 1340);
                step(f, Op::ArrayAtBreakTransform, &[8, 7, 17, 17, 20, 10, 36], 1341);
                step(f, Op::MulF, &[27, 27, 198], 1342);
                step(f, Op::LerpV, &[31, 20, 198, 42], 1343);
                step(f, Op::SubFMulF, &[160, 27, 201, 27, 201, 221], 1344);
                step(f, Op::MulFMulF, &[151, 163, 209, 221, 209, 220], 1345);
                step(f, Op::MakeVector, &[158, 158, 220, 43], 1346);
                step(f, Op::AddV, &[42, 43, 58], 1347);
                step(f, Op::SlerpQ, &[2, 10, 27, 8], 1348);
                step(f, Op::MakeTransform, &[58, 8, 6, 7], 1349);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 7], 1350);
                step(f, Op::ArrayAtBreakTransform, &[5, 7, 19, 19, 31, 2, 17], 1351);
                step(f, Op::LerpV, &[31, 20, 198, 42], 1352);
                step(f, Op::AddV, &[42, 43, 58], 1353);
                step(f, Op::SlerpQ, &[2, 10, 27, 8], 1354);
                step(f, Op::MakeTransform, &[58, 8, 6, 7], 1355);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 7], 1356);
                1356
            }
            1356 => {
                step(f, Op::GreaterEqualF, &[214, 160, 14], 1357);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 7, 14], 1358);
                step(f, Op::ArrayAtBreakTransform, &[1, 7, 4, 4, 18, 6, 55], 1359);
                step(f, Op::SubFMulF, &[160, 214, 217, 13, 10, 205], 1360);
                step(f, Op::MulFScaleV, &[217, 205, 208, 2, 208, 59], 1361);
                step(f, Op::AddV, &[18, 59, 48], 1362);
                step(f, Op::Equals(Elem::Int), &[7, 2, 13], 1363);
                step(f, Op::Select(ValueType::Int), &[13, 3, 2, 12], 1364);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 16], 1365);
                step(f, Op::ArrayAtBreakTransform, &[0, 12, 5, 5, 49, 3, 47], 1366);
                step(f, Op::ArrayAtBreakTransform, &[3, 12, 8, 8, 46, 5, 57], 1367);
                step(f, Op::LessEqualF, &[95, 158, 11], 1368);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 207], 1369);
                step(f, Op::SmoothStepF, &[207, 158, 95, 185], 1370);
                step(f, Op::Select(ValueType::Float), &[11, 160, 185, 182], 1371);
                step(f, Op::LerpV, &[49, 46, 182, 19], 1372);
                step(f, Op::MakeTransform, &[19, 1, 6, 9], 1373);
                step(f, Op::Select(ValueType::Transform), &[16, 5, 9, 10], 1374);
                step(f, Op::MakeAbsolute, &[10, 6, 11], 1375);
                step(f, Op::Select(ValueType::Transform), &[13, 11, 10, 12], 1376);
                step(f, Op::BreakTransform, &[12, 24, 4, 22], 1377);
                step(f, Op::SubFMulF, &[160, 19, 187, 186, 187, 189], 1378);
                step(f, Op::MulF, &[17, 189, 200], 1379);
                step(f, Op::FootAvoidance, &[48, 24, 200, 13, 91, 25], 1380);
                step(f, Op::RemapF, &[18, 94, 160, 158, 160, 9, 188], 1381);
                step(f, Op::LerpV, &[48, 25, 188, 26], 1382);
                step(f, Op::FootAvoidance, &[26, 24, 20, 13, 117, 27], 1383);
                step(f, Op::LerpV, &[26, 27, 19, 23], 1384);
                step(f, Op::MakeTransform, &[23, 1, 6, 15], 1385);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 7, 15], 1386);
                step(f, Op::ArrayAtBreakTransform, &[5, 7, 13, 13, 45, 7, 37], 1387);
                step(f, Op::MakeVector, &[158, 158, 59, 56], 1388);
                step(f, Op::AddV, &[45, 56, 29], 1389);
                step(f, Op::GetTransformBreakTransform, &[0, 2, 9, 16, 16, 30, 9, 33], 1390);
                step(f, Op::MakeTransform, &[29, 9, 6, 18], 1391);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 7, 20], 1392);
                step(f, Op::GetTransformBreakTransform, &[20, 2, 9, 14, 14, 35, 11, 38], 1393);
                step(f, Op::SubV, &[35, 30, 40], 1394);
                step(f, Op::AddV, &[29, 40, 39], 1395);
                step(f, Op::FootPivots, &[29, 39, 61, 60, 59, 62, 21, 41, 44], 1396);
                step(f, Op::GetParent, &[0, 18], 1397);
                step(f, Op::GetParent, &[18, 19], 1398);
                step(f, Op::GetTransformBreakTransform, &[19, 2, 10, 17, 17, 52, 2, 50], 1399);
                step(f, Op::SubV, &[45, 52, 34], 1400);
                step(f, Op::DotV, &[34, 9, 195], 1401);
                step(f, Op::RemapF, &[195, 97, 96, 98, 158, 9, 210], 1402);
                step(f, Op::LengthV, &[2, 192], 1403);
                step(f, Op::RemapF, &[192, 158, 108, 158, 160, 9, 219], 1404);
                step(f, Op::MulF, &[210, 219, 190], 1405);
                step(f, Op::QuatFromAxisAngle, &[13, 190, 10], 1406);
                step(f, Op::RotateAroundPoint, &[18, 21, 10, 19], 1407);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 202], 1408);
                step(f, Op::SmoothStepF, &[202, 158, 102, 211], 1409);
                step(f, Op::SubF, &[160, 202, 197], 1410);
                step(f, Op::SmoothStepF, &[197, 158, 102, 204], 1411);
                step(f, Op::MulF, &[211, 204, 212], 1412);
                step(f, Op::LerpF, &[101, 160, 212, 184], 1413);
                step(f, Op::MulF, &[190, 184, 206], 1414);
                step(f, Op::QuatFromAxisAngle, &[13, 206, 8], 1415);
                step(f, Op::SubV, &[41, 21, 53], 1416);
                step(f, Op::RotateVector, &[8, 53, 54], 1417);
                step(f, Op::AddV, &[21, 54, 60], 1418);
                step(f, Op::RemapF, &[195, 99, 97, 100, 158, 9, 183], 1419);
                step(f, Op::MulF, &[183, 219, 194], 1420);
                step(f, Op::QuatFromAxisAngle, &[13, 194, 6], 1421);
                step(f, Op::RotateAroundPoint, &[19, 60, 6, 7], 1422);
                step(f, Op::RemapF, &[195, 103, 104, 158, 105, 9, 213], 1423);
                step(f, Op::RotateVector, &[7, 10, 32], 1424);
                step(f, Op::BreakVector, &[32, 222, 199, 218], 1425);
                step(f, Op::CosF, &[107, 203], 1426);
                step(f, Op::CosF, &[106, 215], 1427);
                step(f, Op::RemapF, &[218, 203, 215, 158, 160, 9, 191], 1428);
                step(f, Op::MulFMulF, &[219, 191, 193, 213, 193, 216], 1429);
                step(f, Op::QuatFromAxisAngle, &[13, 216, 3], 1430);
                step(f, Op::RotateAroundPoint, &[7, 44, 3, 4], 1431);
                step(f, Op::SubFMulF, &[160, 18, 196, 17, 196, 201], 1432);
                step(f, Op::LimitRotationAroundZ, &[7, 201, 109, 5], 1433);
                step(f, Op::RotateAroundPoint, &[4, 45, 5, 8], 1434);
                step(f, Op::BreakTransform, &[8, 51, 4, 28], 1435);
                step(f, Op::ArrayAt(Elem::Float), &[4, 7, 209], 1436);
                step(f, Op::MulFMulF, &[209, 110, 221, 221, 111, 220], 1437);
                step(f, Op::AddF, &[221, 111, 198], 1438);
                step(f, Op::DivF, &[220, 198, 214], 1439);
                step(f, Op::MakeVector, &[158, 158, 214, 36], 1440);
                step(f, Op::AddV, &[51, 36, 17], 1441);
                step(f, Op::MakeTransform, &[17, 4, 28, 5], 1442);
                step(f, Op::ArraySetAt(Elem::Transform), &[7, 7, 5], 1443);
                step(f, Op::JumpIfFalse, &[8, 1448], 1444)
            }
            1444 => {
                step(f, Op::DrawPoint, &[44, 176, 13], 1445);
                step(f, Op::DrawPoint, &[21, 176, 9], 1446);
                step(f, Op::DrawPoint, &[60, 176, 10], 1447);
                step(f, Op::DrawTransform, &[13, 175, 159], 1448);
                1448
            }
            1448 => {
                step(f, Op::Jump, &[650], 1449)
            }
            1449 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1450);
                step(f, Op::Copy(ValueType::Int), &[2, 10], 1451);
                1451
            }
            1451 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 10, 1, 6, 8, 1487], 1452)
            }
            1452 => {
                step(f, Op::GetParent, &[1, 22], 1453);
                step(f, Op::GetParent, &[22, 23], 1454);
                step(f, Op::GetParent, &[23, 24], 1455);
                step(f, Op::GetTransformBreakTransform, &[24, 2, 10, 9, 9, 20, 9, 31], 1456);
                step(f, Op::LengthV, &[1, 205], 1457);
                step(f, Op::ClavicleOffset, &[15, 205, 123, 127, 217], 1458);
                step(f, Op::MakeVector, &[158, 158, 217, 42], 1459);
                step(f, Op::AddV, &[20, 42, 43], 1460);
                step(f, Op::MakeTransform, &[43, 9, 6, 6], 1461);
                step(f, Op::SetTransform, &[24, 6, 2, 9, 160], 1462);
                step(f, Op::GetTransform, &[1, 2, 10, 10], 1463);
                step(f, Op::GetTransformBreakTransform, &[23, 2, 10, 11, 11, 58, 11, 55], 1464);
                step(f, Op::Equals(Elem::Int), &[6, 2, 19], 1465);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 11], 1466);
                step(f, Op::ArrayAt(Elem::Float), &[0, 11, 208], 1467);
                step(f, Op::ArmSwingRotation, &[208, 1, 0, 124, 167, 177, 160, 123, 121, 122, 125, 167, 160, 207], 1468);
                step(f, Op::QuatFromAxisAngle, &[13, 207, 2], 1469);
                step(f, Op::RotateAroundPoint, &[10, 58, 2, 12], 1470);
                step(f, Op::BreakTransform, &[12, 18, 10, 59], 1471);
                step(f, Op::RemapF, &[205, 158, 123, 158, 126, 9, 185], 1472);
                step(f, Op::MakeVector, &[158, 158, 185, 47], 1473);
                step(f, Op::AddV, &[18, 47, 57], 1474);
                step(f, Op::MakeTransform, &[57, 10, 6, 15], 1475);
                step(f, Op::Select(ValueType::Vec3), &[19, 14, 13, 46], 1476);
                step(f, Op::Select(ValueType::Vec3), &[19, 9, 15, 49], 1477);
                step(f, Op::ArrayAt(Elem::Vec3), &[4, 6, 19], 1478);
                step(f, Op::TwoBoneIK, &[23, 22, 1, 15, 46, 49, 19, 2, 160, 10, 178, 179, 9, 12, 182], 1479);
                step(f, Op::JumpIfFalse, &[8, 1486], 1480)
            }
            1480 => {
                step(f, Op::GetTransformBreakTransform, &[23, 2, 10, 11, 11, 58, 11, 55], 1481);
                step(f, Op::GetTransform, &[1, 2, 10, 10], 1482);
                step(f, Op::RotateAroundPoint, &[10, 58, 2, 12], 1483);
                step(f, Op::BreakTransform, &[12, 18, 10, 59], 1484);
                step(f, Op::AddV, &[18, 47, 57], 1485);
                step(f, Op::DrawLine, &[58, 57, 159, 9], 1486);
                1486
            }
            1486 => {
                step(f, Op::Jump, &[1451], 1487)
            }
            1487 => {
                step(f, Op::NegF, &[5, 186], 1488);
                step(f, Op::MakeVector, &[158, 158, 186, 22], 1489);
                step(f, Op::MakeTransform, &[22, 1, 6, 16], 1490);
                step(f, Op::SetTransform, &[36, 16, 2, 9, 160], 1491);
                step(f, Op::Copy(ValueType::Float), &[165, 187], 1492);
                step(f, Op::Copy(ValueType::Bool), &[10, 17], 1493);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 11], 1494);
                step(f, Op::Copy(ValueType::Int), &[2, 12], 1495);
                step(f, Op::MakeVector, &[158, 158, 64, 25], 1496);
                1496
            }
            1496 => {
                step(f, Op::ForEachNext(Elem::Transform), &[11, 12, 14, 7, 9, 1507], 1497)
            }
            1497 => {
                step(f, Op::BreakTransform, &[14, 48, 8, 24], 1498);
                step(f, Op::AddVSubV, &[48, 25, 26, 48, 25, 27], 1499);
                step(f, Op::SphereTrace, &[26, 27, 63, 20, 23, 37, 189], 1500);
                step(f, Op::BreakVector, &[23, 200, 188, 192], 1501);
                step(f, Op::LessF, &[192, 187, 18], 1502);
                step(f, Op::And, &[20, 18, 15], 1503);
                step(f, Op::JumpIfFalse, &[15, 1506], 1504)
            }
            1504 => {
                step(f, Op::Copy(ValueType::Float), &[192, 187], 1505);
                step(f, Op::Copy(ValueType::Bool), &[9, 17], 1506);
                1506
            }
            1506 => {
                step(f, Op::Jump, &[1496], 1507)
            }
            1507 => {
                step(f, Op::Select(ValueType::Float), &[17, 187, 158, 210], 1508);
                step(f, Op::ClampF, &[210, 69, 70, 202, 202, 202], 1509);
                step(f, Op::SubFMulF, &[160, 27, 197, 202, 197, 204], 1510);
                step(f, Op::SubFMulF, &[160, 148, 211, 5, 211, 212], 1511);
                step(f, Op::AddF, &[204, 212, 184], 1512);
                step(f, Op::MakeVector, &[22, 158, 158, 56], 1513);
                step(f, Op::MakeVector, &[184, 158, 158, 33], 1514);
                step(f, Op::Select(ValueType::Float), &[2, 184, 23, 190], 1515);
                step(f, Op::MakeVector, &[190, 158, 158, 38, 57, 57, 58, 58], 1516);
                step(f, Op::SubV, &[33, 38, 30], 1517);
                step(f, Op::DeltaTime, &[206], 1518);
                step(f, Op::DivFScaleV, &[58, 206, 183, 30, 183, 35], 1519);
                step(f, Op::AddVAddV, &[33, 35, 40, 38, 35, 29], 1520);
                step(f, Op::SubV, &[56, 29, 39], 1521);
                step(f, Op::FloatLerp, &[158, 160, 57, 194], 1522);
                step(f, Op::SubF, &[160, 194, 195], 1523);
                step(f, Op::ScaleV, &[39, 195, 50], 1524);
                step(f, Op::AddV, &[40, 50, 52], 1525);
                step(f, Op::MulF, &[57, 206, 199], 1526);
                step(f, Op::GreaterF, &[199, 158, 14], 1527);
                step(f, Op::DivF, &[194, 199, 222], 1528);
                step(f, Op::Select(ValueType::Float), &[14, 222, 160, 203], 1529);
                step(f, Op::ScaleV, &[30, 203, 34], 1530);
                step(f, Op::SubV, &[52, 34, 41, 41, 41], 1531);
                step(f, Op::BreakVector, &[41, 215, 218, 191], 1532);
                step(f, Op::Select(ValueType::Float), &[1, 184, 215, 22, 22, 22], 1533);
                step(f, Op::Copy(ValueType::Float), &[184, 23], 1534);
                step(f, Op::GetTransformBreakTransform, &[37, 2, 9, 17, 17, 53, 6, 54], 1535);
                step(f, Op::PelvisLean, &[1, 130, 135, 136, 219, 193], 1536);
                step(f, Op::LengthV, &[2, 213], 1537);
                step(f, Op::RemapF, &[213, 158, 130, 158, 128, 9, 216], 1538);
                step(f, Op::MulFSubF, &[18, 129, 196, 160, 196, 201], 1539);
                step(f, Op::MulFMulF, &[216, 201, 209, 15, 180, 221], 1540);
                step(f, Op::SinF, &[221, 198], 1541);
                step(f, Op::MulFMulF, &[209, 198, 220, 220, 197, 214], 1542);
                step(f, Op::AddF, &[214, 22, 217], 1543);
                step(f, Op::SubF, &[217, 5, 208], 1544);
                step(f, Op::MakeVector, &[158, 193, 208, 32], 1545);
                step(f, Op::AddV, &[53, 32, 45], 1546);
                step(f, Op::ArrayAtBreakTransform, &[7, 2, 18, 18, 36, 3, 51], 1547);
                step(f, Op::BreakVector, &[36, 207, 205, 185], 1548);
                step(f, Op::ArrayAtBreakTransform, &[7, 3, 19, 19, 17, 7, 28], 1549);
                step(f, Op::BreakVector, &[17, 182, 186, 189], 1550);
                step(f, Op::SubF, &[185, 189, 188], 1551);
                step(f, Op::PelvisSideLean, &[188, 137, 138, 200], 1552);
                step(f, Op::ArrayAtBreakTransform, &[5, 2, 7, 7, 44, 5, 21], 1553);
                step(f, Op::ArrayAtBreakTransform, &[5, 3, 4, 4, 60, 4, 31], 1554);
                step(f, Op::SlerpQ, &[5, 4, 159, 9], 1555);
                step(f, Op::EulerFromQuat, &[9, 2, 20], 1556);
                step(f, Op::BreakVector, &[20, 192, 187, 210], 1557);
                step(f, Op::RemapF, &[213, 131, 130, 158, 132, 9, 202], 1558);
                step(f, Op::SubV, &[36, 17, 42], 1559);
                step(f, Op::RotateVector, &[0, 9, 43], 1560);
                step(f, Op::DotV, &[42, 43, 211], 1561);
                step(f, Op::MulFAddF, &[202, 211, 204, 210, 204, 212], 1562);
                step(f, Op::MakeVector, &[219, 200, 212, 19], 1563);
                step(f, Op::QuatFromEuler, &[19, 2, 11], 1564);
                step(f, Op::MakeTransform, &[45, 11, 6, 8], 1565);
                step(f, Op::SetTransform, &[38, 8, 2, 9, 160], 1566);
                step(f, Op::GetTransformBreakTransform, &[39, 3, 9, 5, 5, 46, 2, 49], 1567);
                step(f, Op::QuatFromAxisAngle, &[10, 204, 10], 1568);
                step(f, Op::DivF, &[133, 176, 190], 1569);
                step(f, Op::QuatScale, &[10, 190, 8], 1570);
                step(f, Op::MulQ, &[2, 8, 6], 1571);
                step(f, Op::MakeTransform, &[46, 6, 6, 13], 1572);
                step(f, Op::SetTransform, &[40, 13, 3, 9, 160], 1573);
                step(f, Op::GetTransformBreakTransform, &[41, 3, 9, 9, 9, 55, 3, 59], 1574);
                step(f, Op::MulQ, &[3, 8, 7], 1575);
                step(f, Op::MakeTransform, &[55, 7, 6, 6], 1576);
                step(f, Op::SetTransform, &[42, 6, 3, 9, 160], 1577);
                step(f, Op::GetTransformBreakTransform, &[43, 3, 9, 15, 15, 18, 4, 47], 1578);
                step(f, Op::MulQ, &[4, 8, 5], 1579);
                step(f, Op::MakeTransform, &[18, 5, 6, 11], 1580);
                step(f, Op::SetTransform, &[44, 11, 3, 9, 160], 1581);
                step(f, Op::GetTransformBreakTransform, &[45, 3, 9, 10, 10, 57, 9, 58], 1582);
                step(f, Op::QuatScale, &[10, 134, 11], 1583);
                step(f, Op::MulQ, &[9, 11, 2], 1584);
                step(f, Op::MakeTransform, &[57, 2, 6, 12], 1585);
                step(f, Op::SetTransform, &[46, 12, 3, 9, 160], 1586);
                step(f, Op::Or, &[1, 2, 11], 1587);
                step(f, Op::Copy(ValueType::Float), &[158, 183], 1588);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1589);
                step(f, Op::Copy(ValueType::Int), &[2, 8], 1590);
                1590
            }
            1590 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 8, 25, 11, 6, 1633], 1591)
            }
            1591 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 11, 16], 1592);
                step(f, Op::GetParent, &[25, 26], 1593);
                step(f, Op::GetParent, &[26, 27], 1594);
                step(f, Op::GetTransformBreakTransform, &[27, 2, 10, 16, 16, 22, 6, 24], 1595);
                step(f, Op::BreakVector, &[22, 195, 206, 194], 1596);
                step(f, Op::ArrayAtBreakTransform, &[7, 11, 14, 14, 48, 3, 26], 1597);
                step(f, Op::BreakVector, &[48, 199, 222, 203], 1598);
                step(f, Op::ArrayAt(Elem::Float), &[1, 11, 191], 1599);
                step(f, Op::MulFMulF, &[191, 139, 218, 218, 218, 215], 1600);
                step(f, Op::SubF, &[195, 199, 184], 1601);
                step(f, Op::SubF, &[206, 222, 196], 1602);
                step(f, Op::MakeVector, &[184, 196, 158, 27], 1603);
                step(f, Op::DotV, &[27, 27, 201], 1604);
                step(f, Op::SubF, &[215, 201, 216], 1605);
                step(f, Op::SqrtF, &[216, 221], 1606);
                step(f, Op::AddF, &[203, 221, 198], 1607);
                step(f, Op::SubF, &[194, 198, 209], 1608);
                step(f, Op::ArrayAtBreakTransform, &[3, 11, 17, 17, 37, 7, 23], 1609);
                step(f, Op::BreakVector, &[37, 197, 220, 214], 1610);
                step(f, Op::AddF, &[214, 59, 217], 1611);
                step(f, Op::MinF, &[203, 217, 193], 1612);
                step(f, Op::AddF, &[193, 221, 208], 1613);
                step(f, Op::SubF, &[194, 208, 205], 1614);
                step(f, Op::Equals(Elem::Int), &[11, 2, 13], 1615);
                step(f, Op::Select(ValueType::Int), &[13, 3, 2, 10], 1616);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 10, 19], 1617);
                step(f, Op::ArrayAt(Elem::Float), &[2, 10, 207], 1618);
                step(f, Op::RemapF, &[207, 159, 160, 158, 160, 9, 182], 1619);
                step(f, Op::RemapF, &[207, 158, 142, 160, 158, 9, 186], 1620);
                step(f, Op::MaxF, &[182, 186, 185], 1621);
                step(f, Op::Select(ValueType::Float), &[19, 160, 185, 189], 1622);
                step(f, Op::LerpF, &[209, 205, 189, 188], 1623);
                step(f, Op::ArrayAt(Elem::Float), &[2, 11, 187], 1624);
                step(f, Op::RemapF, &[187, 159, 160, 158, 160, 9, 192], 1625);
                step(f, Op::MulF, &[188, 192, 213], 1626);
                step(f, Op::RemapF, &[187, 158, 142, 160, 158, 9, 202], 1627);
                step(f, Op::MulF, &[209, 202, 211], 1628);
                step(f, Op::MaxF, &[213, 211, 210], 1629);
                step(f, Op::Select(ValueType::Float), &[16, 209, 210, 200], 1630);
                step(f, Op::MaxF, &[183, 200, 212], 1631);
                step(f, Op::Copy(ValueType::Float), &[212, 183], 1632);
                step(f, Op::Jump, &[1590], 1633)
            }
            1633 => {
                step(f, Op::ClampF, &[183, 158, 140, 219, 219, 219], 1634);
                step(f, Op::MakeVector, &[24, 158, 158, 25], 1635);
                step(f, Op::MakeVector, &[219, 158, 158, 33], 1636);
                step(f, Op::MakeVector, &[25, 158, 158, 35], 1637);
                step(f, Op::GreaterF, &[219, 24, 12], 1638);
                step(f, Op::Select(ValueType::Float), &[12, 144, 141, 204, 58, 58], 1639);
                step(f, Op::SubV, &[33, 35, 38], 1640);
                step(f, Op::DeltaTime, &[190], 1641);
                step(f, Op::DivFScaleV, &[58, 190, 191, 38, 191, 29], 1642);
                step(f, Op::AddVAddV, &[33, 29, 56, 35, 29, 39], 1643);
                step(f, Op::SubV, &[25, 39, 40], 1644);
                step(f, Op::FloatLerp, &[158, 160, 204, 218], 1645);
                step(f, Op::SubF, &[160, 218, 195], 1646);
                step(f, Op::ScaleV, &[40, 195, 50], 1647);
                step(f, Op::AddV, &[56, 50, 30], 1648);
                step(f, Op::MulF, &[204, 190, 199], 1649);
                step(f, Op::GreaterF, &[199, 158, 18], 1650);
                step(f, Op::DivF, &[218, 199, 206], 1651);
                step(f, Op::Select(ValueType::Float), &[18, 206, 160, 222], 1652);
                step(f, Op::ScaleV, &[38, 222, 34], 1653);
                step(f, Op::SubV, &[30, 34, 52, 52, 52], 1654);
                step(f, Op::BreakVector, &[52, 184, 196, 201], 1655);
                step(f, Op::Select(ValueType::Float), &[11, 219, 184, 24, 24, 24], 1656);
                step(f, Op::Copy(ValueType::Float), &[219, 25], 1657);
                step(f, Op::GetTransformBreakTransform, &[47, 2, 10, 18, 18, 41, 4, 54], 1658);
                step(f, Op::MakeVector, &[158, 158, 24, 32], 1659);
                step(f, Op::SubV, &[41, 32, 53], 1660);
                step(f, Op::MakeTransform, &[53, 4, 6, 19], 1661);
                step(f, Op::SetTransform, &[48, 19, 2, 9, 160], 1662);
                step(f, Op::JumpIfFalse, &[8, 1667], 1663)
            }
            1663 => {
                step(f, Op::GetTransformBreakTransform, &[47, 2, 10, 18, 18, 41, 4, 54], 1664);
                step(f, Op::SubV, &[41, 32, 53], 1665);
                step(f, Op::MakeTransform, &[53, 4, 6, 19], 1666);
                step(f, Op::DrawTransform, &[19, 181, 159], 1667);
                1667
            }
            1667 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1668);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 1669);
                1669
            }
            1669 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 7, 2, 9, 12, 1711], 1670)
            }
            1670 => {
                step(f, Op::GetParent, &[2, 29], 1671);
                step(f, Op::GetParent, &[29, 30], 1672);
                step(f, Op::GetTransformBreakTransform, &[30, 2, 10, 7, 7, 51, 8, 28], 1673);
                step(f, Op::ArrayAtBreakTransform, &[7, 9, 4, 4, 21, 5, 44], 1674);
                step(f, Op::SubV, &[21, 51, 31], 1675);
                step(f, Op::LengthV, &[31, 215], 1676);
                step(f, Op::ArrayAt(Elem::Float), &[1, 9, 216], 1677);
                step(f, Op::MulF, &[216, 152, 198], 1678);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 9, 20], 1679);
                step(f, Op::MulF, &[19, 118, 197], 1680);
                step(f, Op::ArrayAt(Elem::Float), &[2, 9, 220], 1681);
                step(f, Op::ClampF, &[220, 158, 160, 214], 1682);
                step(f, Op::LessF, &[214, 159, 15], 1683);
                step(f, Op::SmoothStepF, &[214, 154, 155, 203], 1684);
                step(f, Op::MulF, &[214, 168, 217], 1685);
                step(f, Op::SinF, &[217, 193], 1686);
                step(f, Op::MaxF, &[203, 193, 221], 1687);
                step(f, Op::Select(ValueType::Float), &[15, 221, 193, 194], 1688);
                step(f, Op::MulF, &[194, 153, 208], 1689);
                step(f, Op::Select(ValueType::Float), &[20, 197, 208, 207], 1690);
                step(f, Op::SubF, &[198, 207, 182], 1691);
                step(f, Op::SubF, &[215, 182, 186], 1692);
                step(f, Op::MaxF, &[186, 158, 185], 1693);
                step(f, Op::MulFAddF, &[185, 185, 189, 185, 207, 205], 1694);
                step(f, Op::DivFSubF, &[189, 205, 188, 215, 188, 192], 1695);
                step(f, Op::DivFScaleV, &[192, 215, 187, 31, 187, 60], 1696);
                step(f, Op::AddV, &[51, 60, 20], 1697);
                step(f, Op::ClampSpatially, &[20, 51, 158, 198, 17], 1698);
                step(f, Op::MakeTransform, &[17, 5, 6, 8], 1699);
                step(f, Op::Equals(Elem::Int), &[9, 2, 17], 1700);
                step(f, Op::Select(ValueType::Vec3), &[17, 14, 13, 36], 1701);
                step(f, Op::Select(ValueType::Vec3), &[17, 9, 15, 42], 1702);
                step(f, Op::ArrayAtBreakTransform, &[5, 9, 5, 5, 43, 10, 19], 1703);
                step(f, Op::ArrayAt(Elem::Vec3), &[3, 9, 45], 1704);
                step(f, Op::KneeVector, &[10, 0, 45, 156, 157, 49], 1705);
                step(f, Op::TwoBoneIK, &[30, 29, 2, 8, 36, 42, 49, 2, 160, 10, 178, 179, 9, 14, 202], 1706);
                step(f, Op::JumpIfFalse, &[8, 1710], 1707)
            }
            1707 => {
                step(f, Op::GetTransformBreakTransform, &[29, 2, 10, 13, 13, 46, 9, 59], 1708);
                step(f, Op::AddV, &[46, 49, 55], 1709);
                step(f, Op::DrawLine, &[46, 55, 159, 16], 1710);
                1710
            }
            1710 => {
                step(f, Op::Jump, &[1669], 1711)
            }
            1711 => {
                step(f, Op::End, &[], 1712)
            }
            _ => return,
        } };
    }
}
