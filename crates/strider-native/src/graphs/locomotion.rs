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
    fingerprint: 0xa57a42a3107ed053,
    forward,
};

fn forward(f: &mut Frame<'_>) {
    let mut pc: usize = 105;
    loop {
        // SAFETY: each `step` is an instruction of the program this code was generated
        // from, with its own operands; `NATIVE` runs only on that program (fingerprint).
        pc = unsafe { match pc {
            105 => {
                step(f, Op::Not, &[0, 11], 106);
                step(f, Op::Copy(ValueType::Bool), &[11, 1], 107);
                step(f, Op::WorldTransform, &[4], 108);
                step(f, Op::BreakTransform, &[4, 20, 2, 21], 109);
                step(f, Op::Select(ValueType::Transform), &[0, 0, 4, 5], 110);
                step(f, Op::BreakTransform, &[5, 17, 2, 22], 111);
                step(f, Op::SubV, &[20, 17, 18], 112);
                step(f, Op::LengthV, &[18, 184], 113);
                step(f, Op::GreaterF, &[184, 41, 11], 114);
                step(f, Op::Copy(ValueType::Bool), &[11, 2], 115);
                step(f, Op::MakeRelative, &[5, 4, 6], 116);
                step(f, Op::Select(ValueType::Transform), &[11, 3, 6, 7], 117);
                step(f, Op::Copy(ValueType::Transform), &[7, 2], 118);
                step(f, Op::InverseT, &[5, 6], 119);
                step(f, Op::MulT, &[4, 6, 7], 120);
                step(f, Op::Copy(ValueType::Transform), &[7, 1], 121);
                step(f, Op::TransformVector, &[2, 0, 19], 122);
                step(f, Op::InverseT, &[4, 5], 123);
                step(f, Op::DeltaTime, &[182], 124);
                step(f, Op::DivF, &[160, 182, 183], 125);
                step(f, Op::ScaleV, &[18, 183, 21], 126);
                step(f, Op::TransformVector, &[5, 21, 22], 127);
                step(f, Op::BreakVector, &[22, 184, 185, 186], 128);
                step(f, Op::BreakVector, &[18, 186, 187, 188], 129);
                step(f, Op::AddF, &[2, 188, 186], 130);
                step(f, Op::Select(ValueType::Float), &[11, 158, 186, 187], 131);
                step(f, Op::MakeVector, &[184, 185, 158, 17], 132);
                step(f, Op::LengthV, &[17, 188], 133);
                step(f, Op::MulF, &[188, 145, 186], 134);
                step(f, Op::MulF, &[186, 182, 188], 135);
                step(f, Op::NegF, &[188, 182], 136);
                step(f, Op::ClampF, &[187, 182, 188, 186], 137);
                step(f, Op::MulF, &[186, 183, 182], 138);
                step(f, Op::MakeVector, &[184, 185, 182, 20], 139);
                step(f, Op::Select(ValueType::Vec3), &[2, 19, 20, 21], 140);
                step(f, Op::VectorLerp, &[19, 21, 42, 158, 22], 141);
                step(f, Op::Copy(ValueType::Vec3), &[22, 0], 142);
                step(f, Op::TransformVector, &[2, 1, 18], 143);
                step(f, Op::TransformVector, &[2, 0, 19], 144);
                step(f, Op::Select(ValueType::Vec3), &[2, 19, 20, 21], 145);
                step(f, Op::VectorLerp, &[18, 21, 43, 158, 17], 146);
                step(f, Op::Copy(ValueType::Vec3), &[17, 1], 147);
                step(f, Op::LengthV, &[21, 188], 148);
                step(f, Op::Copy(ValueType::Float), &[188, 0], 149);
                step(f, Op::SubF, &[187, 186, 183], 150);
                step(f, Op::NegF, &[146, 182], 151);
                step(f, Op::ClampF, &[183, 182, 146, 184], 152);
                step(f, Op::SubF, &[183, 184, 185], 153);
                step(f, Op::Copy(ValueType::Float), &[185, 1], 154);
                step(f, Op::Copy(ValueType::Float), &[184, 3], 155);
                step(f, Op::JumpIfFalse, &[2, 169], 156)
            }
            156 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 12], 157);
                step(f, Op::Copy(ValueType::Int), &[2, 6], 158);
                158
            }
            158 => {
                step(f, Op::ForEachNext(Elem::Bone), &[12, 6, 13, 7, 8, 168], 159)
            }
            159 => {
                step(f, Op::ArrayAt(Elem::Transform), &[8, 7, 6], 160);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 7, 6], 161);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 7, 6], 162);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 7, 6], 163);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 6], 164);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 6], 165);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 7, 6], 166);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 7, 6], 167);
                step(f, Op::Jump, &[158], 168)
            }
            168 => {
                step(f, Op::Copy(ValueType::Float), &[158, 22], 169);
                169
            }
            169 => {
                step(f, Op::Copy(ValueType::Transform), &[4, 0], 170);
                step(f, Op::Copy(ValueType::Bool), &[9, 0], 171);
                step(f, Op::JumpIfFalse, &[8, 177], 172)
            }
            172 => {
                step(f, Op::GetTransform, &[33, 2, 9, 7], 173);
                step(f, Op::BreakTransform, &[7, 22, 2, 19], 174);
                step(f, Op::ScaleV, &[0, 161, 20], 175);
                step(f, Op::AddV, &[22, 20, 18], 176);
                step(f, Op::DrawArrow, &[22, 18, 159, 8], 177);
                177
            }
            177 => {
                step(f, Op::Copy(ValueType::Float), &[158, 188], 178);
                step(f, Op::Copy(ValueType::Float), &[160, 186], 179);
                step(f, Op::Copy(ValueType::Bool), &[10, 11], 180);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[8, 9], 181);
                step(f, Op::Copy(ValueType::Int), &[2, 6], 182);
                step(f, Op::MakeVector, &[158, 158, 64, 17], 183);
                183
            }
            183 => {
                step(f, Op::ForEachNext(Elem::Transform), &[9, 6, 5, 8, 7, 193], 184)
            }
            184 => {
                step(f, Op::BreakTransform, &[5, 21, 2, 19], 185);
                step(f, Op::TransformPoint, &[2, 21, 20], 186);
                step(f, Op::LerpV, &[20, 21, 160, 18], 187);
                step(f, Op::AddV, &[18, 17, 22], 188);
                step(f, Op::SubV, &[18, 17, 19], 189);
                step(f, Op::LineTrace, &[22, 19, 12, 20, 21, 187], 190);
                step(f, Op::JumpIfFalse, &[12, 192], 191)
            }
            191 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 11], 192);
                192
            }
            192 => {
                step(f, Op::Jump, &[183], 193)
            }
            193 => {
                step(f, Op::Copy(ValueType::Bool), &[11, 12], 194);
                step(f, Op::Or, &[12, 7, 11], 195);
                step(f, Op::NotEquals(Elem::Bool), &[11, 5, 13], 196);
                step(f, Op::JumpIfFalse, &[13, 225], 197)
            }
            197 => {
                step(f, Op::NotEquals(Elem::Bool), &[12, 6, 14], 198);
                step(f, Op::JumpIfFalse, &[14, 225], 199)
            }
            199 => {
                step(f, Op::Copy(ValueType::Int), &[1, 6], 200);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 201);
                201
            }
            201 => {
                step(f, Op::ForNext, &[7, 6, 8, 225], 202)
            }
            202 => {
                step(f, Op::AddF, &[188, 186, 182], 203);
                step(f, Op::MulF, &[182, 159, 183], 204);
                step(f, Op::Copy(ValueType::Bool), &[10, 15], 205);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[8, 10], 206);
                step(f, Op::Copy(ValueType::Int), &[2, 6], 207);
                step(f, Op::MakeVector, &[158, 158, 64, 17], 208);
                208
            }
            208 => {
                step(f, Op::ForEachNext(Elem::Transform), &[10, 6, 6, 7, 8, 218], 209)
            }
            209 => {
                step(f, Op::BreakTransform, &[6, 18, 2, 19], 210);
                step(f, Op::TransformPoint, &[2, 18, 20], 211);
                step(f, Op::LerpV, &[20, 18, 183, 21], 212);
                step(f, Op::AddV, &[21, 17, 22], 213);
                step(f, Op::SubV, &[21, 17, 19], 214);
                step(f, Op::LineTrace, &[22, 19, 16, 18, 20, 185], 215);
                step(f, Op::JumpIfFalse, &[16, 217], 216)
            }
            216 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 15], 217);
                217
            }
            217 => {
                step(f, Op::Jump, &[208], 218)
            }
            218 => {
                step(f, Op::Copy(ValueType::Bool), &[15, 16], 219);
                step(f, Op::Equals(Elem::Bool), &[16, 6, 15], 220);
                step(f, Op::JumpIfFalse, &[15, 223], 221)
            }
            221 => {
                step(f, Op::Copy(ValueType::Float), &[183, 188], 222);
                step(f, Op::Jump, &[224], 223)
            }
            223 => {
                step(f, Op::Copy(ValueType::Float), &[183, 186], 224);
                224
            }
            224 => {
                step(f, Op::Jump, &[201], 225)
            }
            225 => {
                step(f, Op::Select(ValueType::Float), &[5, 162, 160, 184], 226);
                step(f, Op::NotEquals(Elem::Bool), &[12, 6, 14], 227);
                step(f, Op::AddF, &[188, 186, 182], 228);
                step(f, Op::MulF, &[182, 159, 187], 229);
                step(f, Op::Select(ValueType::Float), &[14, 187, 159, 185], 230);
                step(f, Op::Select(ValueType::Float), &[13, 185, 158, 183], 231);
                step(f, Op::MulF, &[184, 183, 186], 232);
                step(f, Op::DeltaTime, &[188], 233);
                step(f, Op::DivF, &[188, 150, 182], 234);
                step(f, Op::MulF, &[186, 182, 187], 235);
                step(f, Op::AddF, &[26, 187, 183], 236);
                step(f, Op::ClampF, &[183, 158, 160, 184], 237);
                step(f, Op::Select(ValueType::Float), &[11, 162, 160, 188], 238);
                step(f, Op::SubF, &[160, 185, 186], 239);
                step(f, Op::Select(ValueType::Float), &[13, 186, 160, 187], 240);
                step(f, Op::MulF, &[188, 187, 183], 241);
                step(f, Op::MulF, &[183, 182, 185], 242);
                step(f, Op::AddF, &[184, 185, 186], 243);
                step(f, Op::ClampF, &[186, 158, 160, 187], 244);
                step(f, Op::SmoothStepF, &[187, 158, 160, 188], 245);
                step(f, Op::AddF, &[27, 188, 182], 246);
                step(f, Op::MulF, &[182, 159, 183], 247);
                step(f, Op::SubF, &[160, 183, 184], 248);
                step(f, Op::MulF, &[184, 184, 185], 249);
                step(f, Op::SubF, &[160, 185, 186], 250);
                step(f, Op::Copy(ValueType::Float), &[186, 28], 251);
                step(f, Op::Copy(ValueType::Float), &[188, 27], 252);
                step(f, Op::Copy(ValueType::Float), &[187, 26], 253);
                step(f, Op::GreaterF, &[27, 158, 16], 254);
                step(f, Op::TransformVector, &[2, 3, 17], 255);
                step(f, Op::Select(ValueType::Vec3), &[16, 17, 0, 21], 256);
                step(f, Op::Copy(ValueType::Vec3), &[21, 3], 257);
                step(f, Op::LerpV, &[0, 3, 27, 18], 258);
                step(f, Op::Select(ValueType::Vec3), &[16, 18, 0, 19], 259);
                step(f, Op::Copy(ValueType::Vec3), &[19, 2], 260);
                step(f, Op::Copy(ValueType::Bool), &[11, 5], 261);
                step(f, Op::Copy(ValueType::Bool), &[12, 6], 262);
                step(f, Op::Copy(ValueType::Bool), &[10, 7], 263);
                step(f, Op::SubF, &[160, 28, 182], 264);
                step(f, Op::MulF, &[1, 182, 183], 265);
                step(f, Op::SubF, &[3, 2, 184], 266);
                step(f, Op::MulF, &[184, 182, 185], 267);
                step(f, Op::AddF, &[2, 185, 186], 268);
                step(f, Op::MulF, &[186, 182, 188], 269);
                step(f, Op::SubF, &[186, 188, 187], 270);
                step(f, Op::AddF, &[183, 187, 189], 271);
                step(f, Op::AddF, &[4, 189, 190], 272);
                step(f, Op::Copy(ValueType::Float), &[7, 191], 273);
                step(f, Op::Copy(ValueType::Float), &[8, 192], 274);
                step(f, Op::Copy(ValueType::Float), &[4, 193], 275);
                step(f, Op::Copy(ValueType::Float), &[147, 194], 276);
                step(f, Op::Copy(ValueType::Float), &[58, 195], 277);
                step(f, Op::SubF, &[190, 193, 196], 278);
                step(f, Op::DeltaTime, &[197], 279);
                step(f, Op::DivF, &[196, 197, 198], 280);
                step(f, Op::MulF, &[198, 195, 199], 281);
                step(f, Op::AddF, &[190, 199, 200], 282);
                step(f, Op::MulF, &[198, 163, 201], 283);
                step(f, Op::DivF, &[164, 194, 202], 284);
                step(f, Op::DivF, &[201, 202, 203], 285);
                step(f, Op::SubF, &[200, 203, 204], 286);
                step(f, Op::AddF, &[193, 199, 205], 287);
                step(f, Op::SubF, &[191, 205, 206], 288);
                step(f, Op::AddF, &[206, 203, 207], 289);
                step(f, Op::SubF, &[192, 198, 208], 290);
                step(f, Op::MulF, &[202, 207, 209], 291);
                step(f, Op::AddF, &[208, 209, 210], 292);
                step(f, Op::MulF, &[210, 197, 211], 293);
                step(f, Op::AddF, &[207, 211, 212], 294);
                step(f, Op::FloatLerp, &[158, 160, 202, 213], 295);
                step(f, Op::SubF, &[160, 213, 214], 296);
                step(f, Op::MulF, &[212, 214, 215], 297);
                step(f, Op::AddF, &[204, 215, 216], 298);
                step(f, Op::Copy(ValueType::Float), &[216, 217], 299);
                step(f, Op::MulF, &[202, 211, 218], 300);
                step(f, Op::SubF, &[208, 218, 219], 301);
                step(f, Op::MulF, &[219, 214, 220], 302);
                step(f, Op::AddF, &[198, 220, 221], 303);
                step(f, Op::Copy(ValueType::Float), &[221, 222], 304);
                step(f, Op::SubF, &[190, 217, 223], 305);
                step(f, Op::AddF, &[223, 188, 224], 306);
                step(f, Op::Copy(ValueType::Float), &[224, 5], 307);
                step(f, Op::Copy(ValueType::Float), &[223, 6], 308);
                step(f, Op::Copy(ValueType::Float), &[188, 2], 309);
                step(f, Op::SubF, &[3, 2, 184], 310);
                step(f, Op::MulF, &[184, 182, 185], 311);
                step(f, Op::AddF, &[2, 185, 186], 312);
                step(f, Op::MulF, &[186, 182, 188], 313);
                step(f, Op::SubF, &[186, 188, 187], 314);
                step(f, Op::AddF, &[183, 187, 189], 315);
                step(f, Op::AddF, &[4, 189, 190], 316);
                step(f, Op::Copy(ValueType::Float), &[7, 191], 317);
                step(f, Op::Copy(ValueType::Float), &[8, 192], 318);
                step(f, Op::Copy(ValueType::Float), &[4, 193], 319);
                step(f, Op::Copy(ValueType::Float), &[147, 194], 320);
                step(f, Op::Copy(ValueType::Float), &[58, 195], 321);
                step(f, Op::SubF, &[190, 193, 196], 322);
                step(f, Op::DeltaTime, &[197], 323);
                step(f, Op::DivF, &[196, 197, 198], 324);
                step(f, Op::MulF, &[198, 195, 199], 325);
                step(f, Op::AddF, &[190, 199, 200], 326);
                step(f, Op::MulF, &[198, 163, 201], 327);
                step(f, Op::DivF, &[164, 194, 202], 328);
                step(f, Op::DivF, &[201, 202, 203], 329);
                step(f, Op::SubF, &[200, 203, 204], 330);
                step(f, Op::AddF, &[193, 199, 205], 331);
                step(f, Op::SubF, &[191, 205, 206], 332);
                step(f, Op::AddF, &[206, 203, 207], 333);
                step(f, Op::SubF, &[192, 198, 208], 334);
                step(f, Op::MulF, &[202, 207, 209], 335);
                step(f, Op::AddF, &[208, 209, 210], 336);
                step(f, Op::MulF, &[210, 197, 211], 337);
                step(f, Op::AddF, &[207, 211, 212], 338);
                step(f, Op::FloatLerp, &[158, 160, 202, 213], 339);
                step(f, Op::SubF, &[160, 213, 214], 340);
                step(f, Op::MulF, &[212, 214, 215], 341);
                step(f, Op::AddF, &[204, 215, 216], 342);
                step(f, Op::Copy(ValueType::Float), &[216, 217], 343);
                step(f, Op::MulF, &[202, 211, 218], 344);
                step(f, Op::SubF, &[208, 218, 219], 345);
                step(f, Op::MulF, &[219, 214, 220], 346);
                step(f, Op::AddF, &[198, 220, 221], 347);
                step(f, Op::Copy(ValueType::Float), &[221, 222], 348);
                step(f, Op::Copy(ValueType::Float), &[217, 7], 349);
                step(f, Op::Copy(ValueType::Float), &[7, 191], 350);
                step(f, Op::Copy(ValueType::Float), &[8, 192], 351);
                step(f, Op::Copy(ValueType::Float), &[4, 193], 352);
                step(f, Op::Copy(ValueType::Float), &[147, 194], 353);
                step(f, Op::Copy(ValueType::Float), &[58, 195], 354);
                step(f, Op::SubF, &[190, 193, 196], 355);
                step(f, Op::DeltaTime, &[197], 356);
                step(f, Op::DivF, &[196, 197, 198], 357);
                step(f, Op::MulF, &[198, 195, 199], 358);
                step(f, Op::AddF, &[190, 199, 200], 359);
                step(f, Op::MulF, &[198, 163, 201], 360);
                step(f, Op::DivF, &[164, 194, 202], 361);
                step(f, Op::DivF, &[201, 202, 203], 362);
                step(f, Op::SubF, &[200, 203, 204], 363);
                step(f, Op::AddF, &[193, 199, 205], 364);
                step(f, Op::SubF, &[191, 205, 206], 365);
                step(f, Op::AddF, &[206, 203, 207], 366);
                step(f, Op::SubF, &[192, 198, 208], 367);
                step(f, Op::MulF, &[202, 207, 209], 368);
                step(f, Op::AddF, &[208, 209, 210], 369);
                step(f, Op::MulF, &[210, 197, 211], 370);
                step(f, Op::AddF, &[207, 211, 212], 371);
                step(f, Op::FloatLerp, &[158, 160, 202, 213], 372);
                step(f, Op::SubF, &[160, 213, 214], 373);
                step(f, Op::MulF, &[212, 214, 215], 374);
                step(f, Op::AddF, &[204, 215, 216], 375);
                step(f, Op::Copy(ValueType::Float), &[216, 217], 376);
                step(f, Op::MulF, &[202, 211, 218], 377);
                step(f, Op::SubF, &[208, 218, 219], 378);
                step(f, Op::MulF, &[219, 214, 220], 379);
                step(f, Op::AddF, &[198, 220, 221], 380);
                step(f, Op::Copy(ValueType::Float), &[221, 222], 381);
                step(f, Op::Copy(ValueType::Float), &[222, 8], 382);
                step(f, Op::Copy(ValueType::Float), &[190, 4], 383);
                step(f, Op::LengthV, &[4, 224], 384);
                step(f, Op::GreaterF, &[224, 35, 15], 385);
                step(f, Op::LengthV, &[2, 223], 386);
                step(f, Op::GreaterF, &[223, 35, 14], 387);
                step(f, Op::And, &[15, 14, 13], 388);
                step(f, Op::Select(ValueType::Vec3), &[15, 4, 7, 20], 389);
                step(f, Op::MovementAngleOffset, &[20, 17, 158, 165, 165, 166, 46, 167, 184], 390);
                step(f, Op::Copy(ValueType::Float), &[17, 185], 391);
                step(f, Op::SubF, &[184, 185, 182], 392);
                step(f, Op::AddF, &[182, 168, 186], 393);
                step(f, Op::DivF, &[186, 169, 188], 394);
                step(f, Op::FractF, &[188, 183], 395);
                step(f, Op::MulF, &[183, 169, 187], 396);
                step(f, Op::SubF, &[187, 168, 189], 397);
                step(f, Op::Copy(ValueType::Float), &[189, 196], 398);
                step(f, Op::AbsF, &[196, 195], 399);
                step(f, Op::Select(ValueType::Vec3), &[14, 2, 7, 22], 400);
                step(f, Op::MovementAngleOffset, &[22, 17, 158, 165, 165, 166, 46, 167, 194], 401);
                step(f, Op::Copy(ValueType::Float), &[17, 201], 402);
                step(f, Op::SubF, &[194, 201, 200], 403);
                step(f, Op::AddF, &[200, 168, 193], 404);
                step(f, Op::DivF, &[193, 169, 199], 405);
                step(f, Op::FractF, &[199, 191], 406);
                step(f, Op::MulF, &[191, 169, 205], 407);
                step(f, Op::SubF, &[205, 168, 203], 408);
                step(f, Op::Copy(ValueType::Float), &[203, 206], 409);
                step(f, Op::AbsF, &[206, 192], 410);
                step(f, Op::MaxF, &[195, 192, 209], 411);
                step(f, Op::SubF, &[194, 184, 197], 412);
                step(f, Op::AddF, &[197, 168, 210], 413);
                step(f, Op::DivF, &[210, 169, 207], 414);
                step(f, Op::FractF, &[207, 213], 415);
                step(f, Op::MulF, &[213, 169, 212], 416);
                step(f, Op::SubF, &[212, 168, 204], 417);
                step(f, Op::Copy(ValueType::Float), &[204, 215], 418);
                step(f, Op::AbsF, &[215, 216], 419);
                step(f, Op::MaxF, &[209, 216, 217], 420);
                step(f, Op::DeltaTime, &[202], 421);
                step(f, Op::DivF, &[58, 202, 211], 422);
                step(f, Op::TransformVector, &[2, 9, 17], 423);
                step(f, Op::BreakVector, &[17, 208, 218, 214], 424);
                step(f, Op::NegF, &[208, 219], 425);
                step(f, Op::Atan2F, &[219, 218, 198], 426);
                step(f, Op::MulF, &[211, 198, 220], 427);
                step(f, Op::QuatFromAxisAngle, &[10, 220, 2], 428);
                step(f, Op::TransformVector, &[2, 4, 21], 429);
                step(f, Op::FloatLerp, &[158, 160, 42, 221], 430);
                step(f, Op::GreaterF, &[221, 158, 16], 431);
                step(f, Op::AddF, &[160, 211, 222], 432);
                step(f, Op::MulF, &[42, 222, 190], 433);
                step(f, Op::FloatLerp, &[158, 160, 190, 224], 434);
                step(f, Op::DivF, &[224, 221, 185], 435);
                step(f, Op::Select(ValueType::Float), &[16, 185, 222, 182], 436);
                step(f, Op::LerpV, &[21, 2, 182, 18], 437);
                step(f, Op::RotateVector, &[2, 18, 19], 438);
                step(f, Op::LengthV, &[19, 186], 439);
                step(f, Op::GreaterF, &[186, 35, 11], 440);
                step(f, Op::Select(ValueType::Vec3), &[11, 19, 7, 20], 441);
                step(f, Op::MovementAngleOffset, &[20, 17, 158, 165, 165, 166, 46, 167, 188], 442);
                step(f, Op::Copy(ValueType::Float), &[17, 183], 443);
                step(f, Op::SubF, &[188, 183, 187], 444);
                step(f, Op::AddF, &[187, 168, 189], 445);
                step(f, Op::DivF, &[189, 169, 196], 446);
                step(f, Op::FractF, &[196, 201], 447);
                step(f, Op::MulF, &[201, 169, 200], 448);
                step(f, Op::SubF, &[200, 168, 193], 449);
                step(f, Op::Copy(ValueType::Float), &[193, 199], 450);
                step(f, Op::AbsF, &[199, 191], 451);
                step(f, Op::SubF, &[188, 194, 205], 452);
                step(f, Op::AddF, &[205, 168, 203], 453);
                step(f, Op::DivF, &[203, 169, 206], 454);
                step(f, Op::FractF, &[206, 192], 455);
                step(f, Op::MulF, &[192, 169, 195], 456);
                step(f, Op::SubF, &[195, 168, 184], 457);
                step(f, Op::Copy(ValueType::Float), &[184, 197], 458);
                step(f, Op::AbsF, &[197, 210], 459);
                step(f, Op::MaxF, &[191, 210, 207], 460);
                step(f, Op::MaxF, &[217, 207, 213], 461);
                step(f, Op::LessF, &[213, 170, 12], 462);
                step(f, Op::And, &[13, 12, 17], 463);
                step(f, Op::SubV, &[2, 21, 17], 464);
                step(f, Op::DotV, &[21, 17, 212], 465);
                step(f, Op::NegF, &[212, 204], 466);
                step(f, Op::DotV, &[17, 17, 209], 467);
                step(f, Op::DivF, &[204, 209, 216], 468);
                step(f, Op::ClampF, &[216, 158, 182, 214], 469);
                step(f, Op::LerpV, &[21, 2, 214, 18], 470);
                step(f, Op::LengthV, &[18, 208], 471);
                step(f, Op::LessF, &[208, 35, 12], 472);
                step(f, Op::Not, &[12, 13], 473);
                step(f, Op::And, &[17, 13, 12], 474);
                step(f, Op::Not, &[15, 13], 475);
                step(f, Op::Not, &[14, 17], 476);
                step(f, Op::And, &[13, 17, 15], 477);
                step(f, Op::Not, &[11, 13], 478);
                step(f, Op::And, &[15, 13, 17], 479);
                step(f, Op::Or, &[12, 17, 11], 480);
                step(f, Op::JumpIfFalse, &[11, 500], 481)
            }
            481 => {
                step(f, Op::MulF, &[44, 202, 218], 482);
                step(f, Op::GreaterF, &[218, 158, 13], 483);
                step(f, Op::FloatLerp, &[158, 160, 44, 219], 484);
                step(f, Op::SubF, &[160, 219, 220], 485);
                step(f, Op::DivF, &[220, 219, 190], 486);
                step(f, Op::DivF, &[160, 218, 224], 487);
                step(f, Op::SubF, &[190, 224, 185], 488);
                step(f, Op::AddF, &[211, 185, 222], 489);
                step(f, Op::Select(ValueType::Float), &[13, 222, 158, 186], 490);
                step(f, Op::MulF, &[215, 186, 183], 491);
                step(f, Op::AddF, &[194, 183, 187], 492);
                step(f, Op::SinF, &[187, 189], 493);
                step(f, Op::NegF, &[189, 196], 494);
                step(f, Op::CosF, &[187, 201], 495);
                step(f, Op::MakeVector, &[196, 201, 158, 19], 496);
                step(f, Op::Select(ValueType::Vec3), &[14, 19, 7, 20], 497);
                step(f, Op::MovementAngleOffset, &[20, 17, 158, 44, 45, 166, 168, 167, 200], 498);
                step(f, Op::Copy(ValueType::Float), &[200, 17], 499);
                step(f, Op::Jump, &[557], 500)
            }
            500 => {
                step(f, Op::DivF, &[202, 48, 193], 501);
                step(f, Op::AddF, &[193, 159, 199], 502);
                step(f, Op::FloorF, &[199, 188], 503);
                step(f, Op::MaxF, &[188, 160, 205], 504);
                step(f, Op::ToInt, &[205, 6], 505);
                step(f, Op::Copy(ValueType::Int), &[6, 7], 506);
                step(f, Op::Copy(ValueType::Int), &[2, 8], 507);
                step(f, Op::MulF, &[48, 159, 203], 508);
                step(f, Op::SubF, &[58, 203, 206], 509);
                step(f, Op::DivF, &[206, 202, 192], 510);
                step(f, Op::DivF, &[44, 205, 195], 511);
                step(f, Op::DivF, &[45, 205, 184], 512);
                step(f, Op::SubF, &[166, 47, 197], 513);
                step(f, Op::GreaterF, &[47, 158, 15], 514);
                514
            }
            514 => {
                step(f, Op::ForNext, &[8, 7, 6, 557], 515)
            }
            515 => {
                step(f, Op::ToFloat, &[6, 191], 516);
                step(f, Op::AddF, &[191, 160, 210], 517);
                step(f, Op::DivF, &[210, 205, 207], 518);
                step(f, Op::AddF, &[207, 192, 217], 519);
                step(f, Op::SubF, &[217, 160, 213], 520);
                step(f, Op::MulF, &[213, 198, 212], 521);
                step(f, Op::QuatFromAxisAngle, &[10, 212, 2], 522);
                step(f, Op::MulF, &[42, 217, 204], 523);
                step(f, Op::FloatLerp, &[158, 160, 204, 209], 524);
                step(f, Op::DivF, &[209, 221, 182], 525);
                step(f, Op::Select(ValueType::Float), &[16, 182, 217, 216], 526);
                step(f, Op::LerpV, &[21, 2, 216, 17], 527);
                step(f, Op::RotateVector, &[2, 17, 18], 528);
                step(f, Op::LengthV, &[18, 214], 529);
                step(f, Op::GreaterF, &[214, 35, 12], 530);
                step(f, Op::Select(ValueType::Vec3), &[12, 18, 7, 19], 531);
                step(f, Op::MulF, &[202, 217, 208], 532);
                step(f, Op::MulF, &[11, 208, 219], 533);
                step(f, Op::AddF, &[15, 219, 220], 534);
                step(f, Op::FractF, &[220, 218], 535);
                step(f, Op::MulF, &[218, 163, 190], 536);
                step(f, Op::FractF, &[190, 224], 537);
                step(f, Op::LessF, &[224, 167, 17], 538);
                step(f, Op::MovementAngleOffset, &[19, 17, 158, 165, 165, 166, 46, 167, 185], 539);
                step(f, Op::Copy(ValueType::Float), &[17, 211], 540);
                step(f, Op::SubF, &[185, 211, 222], 541);
                step(f, Op::AddF, &[222, 168, 186], 542);
                step(f, Op::DivF, &[186, 169, 215], 543);
                step(f, Op::FractF, &[215, 183], 544);
                step(f, Op::MulF, &[183, 169, 194], 545);
                step(f, Op::SubF, &[194, 168, 189], 546);
                step(f, Op::Copy(ValueType::Float), &[189, 187], 547);
                step(f, Op::AbsF, &[187, 196], 548);
                step(f, Op::SmoothStepF, &[196, 197, 166, 201], 549);
                step(f, Op::GreaterF, &[196, 166, 11], 550);
                step(f, Op::Select(ValueType::Float), &[11, 160, 158, 200], 551);
                step(f, Op::Select(ValueType::Float), &[15, 201, 200, 193], 552);
                step(f, Op::Select(ValueType::Float), &[17, 158, 193, 199], 553);
                step(f, Op::LerpF, &[195, 184, 199, 188], 554);
                step(f, Op::MovementAngleOffset, &[19, 17, 218, 188, 188, 166, 46, 167, 203], 555);
                step(f, Op::Copy(ValueType::Float), &[203, 17], 556);
                step(f, Op::Jump, &[514], 557)
            }
            557 => {
                step(f, Op::QuatFromAxisAngle, &[10, 17, 2], 558);
                step(f, Op::Copy(ValueType::Quat), &[2, 0], 559);
                step(f, Op::SinF, &[17, 206], 560);
                step(f, Op::AbsF, &[206, 191], 561);
                step(f, Op::RemapF, &[191, 49, 50, 158, 160, 9, 205], 562);
                step(f, Op::BreakVector, &[22, 210, 192, 207], 563);
                step(f, Op::AbsF, &[210, 198], 564);
                step(f, Op::DivF, &[198, 223, 213], 565);
                step(f, Op::RemapF, &[213, 49, 50, 158, 160, 9, 212], 566);
                step(f, Op::TransformVector, &[2, 9, 20], 567);
                step(f, Op::DistanceV, &[20, 9, 204], 568);
                step(f, Op::DivF, &[204, 202, 209], 569);
                step(f, Op::RemapF, &[209, 54, 55, 160, 158, 9, 221], 570);
                step(f, Op::MulF, &[212, 221, 182], 571);
                step(f, Op::MaxF, &[205, 182, 216], 572);
                step(f, Op::Copy(ValueType::Float), &[216, 18], 573);
                step(f, Op::Copy(ValueType::Vec3), &[2, 4], 574);
                step(f, Op::Copy(ValueType::Bool), &[9, 13], 575);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 2], 576);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 577);
                577
            }
            577 => {
                step(f, Op::ForEachNext(Elem::Bool), &[2, 7, 14, 8, 6, 582], 578)
            }
            578 => {
                step(f, Op::Not, &[14, 16], 579);
                step(f, Op::JumpIfFalse, &[16, 581], 580)
            }
            580 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 13], 581);
                581
            }
            581 => {
                step(f, Op::Jump, &[577], 582)
            }
            582 => {
                step(f, Op::Copy(ValueType::Bool), &[13, 12], 583);
                step(f, Op::Copy(ValueType::Bool), &[9, 11], 584);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 585);
                step(f, Op::Copy(ValueType::Int), &[2, 6], 586);
                586
            }
            586 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 6, 15, 7, 8, 600], 587)
            }
            587 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 7, 4], 588);
                step(f, Op::BreakTransform, &[4, 21, 2, 17], 589);
                step(f, Op::BreakVector, &[21, 214, 217, 208], 590);
                step(f, Op::MakeVector, &[214, 217, 158, 18], 591);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 7, 7], 592);
                step(f, Op::BreakTransform, &[7, 19, 2, 22], 593);
                step(f, Op::BreakVector, &[19, 219, 220, 190], 594);
                step(f, Op::MakeVector, &[219, 220, 158, 20], 595);
                step(f, Op::DistanceV, &[18, 20, 224], 596);
                step(f, Op::GreaterF, &[224, 37, 15], 597);
                step(f, Op::JumpIfFalse, &[15, 599], 598)
            }
            598 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 11], 599);
                599
            }
            599 => {
                step(f, Op::Jump, &[586], 600)
            }
            600 => {
                step(f, Op::Copy(ValueType::Bool), &[11, 17], 601);
                step(f, Op::And, &[12, 17, 14], 602);
                step(f, Op::LengthV, &[2, 185], 603);
                step(f, Op::GreaterF, &[185, 35, 16], 604);
                step(f, Op::GreaterF, &[0, 35, 13], 605);
                step(f, Op::Or, &[16, 13, 15], 606);
                step(f, Op::Not, &[15, 11], 607);
                step(f, Op::And, &[14, 11, 17], 608);
                step(f, Op::DeltaTime, &[211], 609);
                step(f, Op::MulF, &[211, 40, 222], 610);
                step(f, Op::AddF, &[15, 222, 186], 611);
                step(f, Op::GreaterF, &[15, 159, 13], 612);
                step(f, Op::AddF, &[39, 159, 215], 613);
                step(f, Op::Select(ValueType::Float), &[13, 215, 39, 183], 614);
                step(f, Op::MinF, &[186, 183, 194], 615);
                step(f, Op::NotEquals(Elem::Bool), &[11, 4, 15], 616);
                step(f, Op::Not, &[14, 13], 617);
                step(f, Op::And, &[15, 13, 18], 618);
                step(f, Op::SubF, &[16, 35, 189], 619);
                step(f, Op::SubF, &[16, 185, 187], 620);
                step(f, Op::DivF, &[189, 187, 197], 621);
                step(f, Op::ClampF, &[197, 158, 160, 196], 622);
                step(f, Op::MulF, &[11, 196, 200], 623);
                step(f, Op::RemapF, &[185, 35, 36, 158, 160, 9, 201], 624);
                step(f, Op::MaxF, &[201, 12, 193], 625);
                step(f, Op::Select(ValueType::Float), &[12, 160, 193, 184], 626);
                step(f, Op::Select(ValueType::Float), &[11, 38, 184, 195], 627);
                step(f, Op::Select(ValueType::Float), &[14, 201, 195, 199], 628);
                step(f, Op::SubF, &[160, 27, 188], 629);
                step(f, Op::MulF, &[199, 188, 218], 630);
                step(f, Op::LerpF, &[29, 52, 18, 203], 631);
                step(f, Op::RemapF, &[185, 32, 33, 30, 31, 9, 206], 632);
                step(f, Op::LerpF, &[206, 51, 18, 191], 633);
                step(f, Op::MaxF, &[185, 34, 192], 634);
                step(f, Op::DivF, &[191, 192, 207], 635);
                step(f, Op::AddF, &[203, 207, 210], 636);
                step(f, Op::DivF, &[218, 210, 198], 637);
                step(f, Op::SubF, &[160, 196, 223], 638);
                step(f, Op::MulF, &[198, 223, 213], 639);
                step(f, Op::AddF, &[200, 213, 202], 640);
                step(f, Op::MulF, &[202, 163, 204], 641);
                step(f, Op::AddF, &[11, 198, 209], 642);
                step(f, Op::Select(ValueType::Float), &[18, 204, 209, 212], 643);
                step(f, Op::DivF, &[163, 212, 221], 644);
                step(f, Op::GreaterF, &[212, 158, 13], 645);
                step(f, Op::CycleStep, &[15, 221, 158, 13, 182, 205], 646);
                step(f, Op::Select(ValueType::Float), &[17, 194, 182, 216], 647);
                step(f, Op::Copy(ValueType::Float), &[216, 15], 648);
                step(f, Op::Copy(ValueType::Float), &[198, 11], 649);
                step(f, Op::Copy(ValueType::Bool), &[16, 3], 650);
                step(f, Op::Copy(ValueType::Float), &[207, 9], 651);
                step(f, Op::Copy(ValueType::Float), &[210, 10], 652);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 653);
                step(f, Op::Copy(ValueType::Int), &[2, 6], 654);
                step(f, Op::DivF, &[203, 210, 208], 655);
                step(f, Op::MulF, &[14, 196, 214], 656);
                step(f, Op::MulF, &[211, 159, 217], 657);
                step(f, Op::SubF, &[208, 13, 190], 658);
                step(f, Op::MaxF, &[190, 158, 219], 659);
                step(f, Op::DivF, &[219, 208, 220], 660);
                step(f, Op::SubF, &[160, 18, 224], 661);
                step(f, Op::DivF, &[58, 211, 222], 662);
                step(f, Op::SubF, &[159, 222, 215], 663);
                step(f, Op::MulF, &[220, 224, 183], 664);
                step(f, Op::MulF, &[183, 188, 186], 665);
                step(f, Op::MulF, &[186, 143, 187], 666);
                step(f, Op::MulF, &[187, 215, 189], 667);
                step(f, Op::SubF, &[160, 189, 197], 668);
                668
            }
            668 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 6, 14, 8, 7, 712], 669)
            }
            669 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 8, 206], 670);
                step(f, Op::ToFloat, &[8, 191], 671);
                step(f, Op::MulF, &[191, 159, 192], 672);
                step(f, Op::AddF, &[15, 192, 200], 673);
                step(f, Op::FractF, &[200, 213], 674);
                step(f, Op::SubF, &[206, 213, 202], 675);
                step(f, Op::GreaterF, &[202, 159, 15], 676);
                step(f, Op::ArrayAt(Elem::Float), &[2, 8, 204], 677);
                step(f, Op::Select(ValueType::Float), &[15, 158, 204, 209], 678);
                step(f, Op::ArraySetAt(Elem::Float), &[3, 8, 209], 679);
                step(f, Op::SubF, &[160, 206, 212], 680);
                step(f, Op::AddF, &[213, 212, 205], 681);
                step(f, Op::DivF, &[213, 205, 221], 682);
                step(f, Op::MaxF, &[201, 12, 193], 683);
                step(f, Op::Select(ValueType::Float), &[12, 160, 193, 184], 684);
                step(f, Op::Select(ValueType::Float), &[11, 38, 184, 195], 685);
                step(f, Op::Select(ValueType::Float), &[14, 201, 195, 199], 686);
                step(f, Op::MulF, &[199, 188, 218], 687);
                step(f, Op::DivF, &[218, 203, 182], 688);
                step(f, Op::MulF, &[182, 223, 194], 689);
                step(f, Op::AddF, &[214, 194, 216], 690);
                step(f, Op::MulF, &[216, 163, 198], 691);
                step(f, Op::AddF, &[14, 182, 207], 692);
                step(f, Op::Select(ValueType::Float), &[18, 198, 207, 210], 693);
                step(f, Op::MulF, &[210, 217, 196], 694);
                step(f, Op::MulF, &[221, 196, 190], 695);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 8, 13], 696);
                step(f, Op::MulF, &[196, 197, 219], 697);
                step(f, Op::Select(ValueType::Float), &[13, 196, 219, 211], 698);
                step(f, Op::MulF, &[220, 204, 222], 699);
                step(f, Op::MulF, &[222, 224, 183], 700);
                step(f, Op::MulF, &[183, 188, 186], 701);
                step(f, Op::MulF, &[186, 143, 187], 702);
                step(f, Op::Select(ValueType::Float), &[13, 158, 187, 215], 703);
                step(f, Op::SubF, &[211, 215, 189], 704);
                step(f, Op::AddF, &[204, 189, 191], 705);
                step(f, Op::Select(ValueType::Float), &[15, 190, 191, 192], 706);
                step(f, Op::MinF, &[192, 163, 200], 707);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 8, 200], 708);
                step(f, Op::JumpIfFalse, &[15, 710], 709)
            }
            709 => {
                step(f, Op::Copy(ValueType::Float), &[199, 12], 710);
                710
            }
            710 => {
                step(f, Op::ArraySetAt(Elem::Float), &[0, 8, 213], 711);
                step(f, Op::Jump, &[668], 712)
            }
            712 => {
                step(f, Op::Copy(ValueType::Float), &[208, 13], 713);
                step(f, Op::Copy(ValueType::Bool), &[11, 4], 714);
                step(f, Op::Copy(ValueType::Float), &[185, 16], 715);
                step(f, Op::MaxF, &[201, 12, 193], 716);
                step(f, Op::Select(ValueType::Float), &[12, 160, 193, 184], 717);
                step(f, Op::Select(ValueType::Float), &[11, 38, 184, 195], 718);
                step(f, Op::Select(ValueType::Float), &[14, 201, 195, 199], 719);
                step(f, Op::MulF, &[199, 188, 218], 720);
                step(f, Op::DivF, &[218, 203, 182], 721);
                step(f, Op::Copy(ValueType::Float), &[182, 14], 722);
                step(f, Op::TransformVector, &[2, 5, 17], 723);
                step(f, Op::BreakTransform, &[2, 21, 2, 22], 724);
                step(f, Op::DeltaTime, &[202], 725);
                step(f, Op::DivF, &[160, 202, 209], 726);
                step(f, Op::ScaleV, &[21, 209, 19], 727);
                step(f, Op::NegV, &[19, 18], 728);
                step(f, Op::SubV, &[18, 17, 20], 729);
                step(f, Op::AddF, &[21, 202, 206], 730);
                step(f, Op::DivF, &[21, 206, 212], 731);
                step(f, Op::ScaleV, &[20, 212, 22], 732);
                step(f, Op::AddV, &[17, 22, 19], 733);
                step(f, Op::DivF, &[202, 206, 205], 734);
                step(f, Op::ScaleV, &[20, 205, 17], 735);
                step(f, Op::AddV, &[18, 17, 22], 736);
                step(f, Op::DotV, &[19, 22, 223], 737);
                step(f, Op::LessF, &[223, 158, 17], 738);
                step(f, Op::TransformVector, &[2, 9, 20], 739);
                step(f, Op::DistanceV, &[20, 9, 194], 740);
                step(f, Op::SubV, &[22, 19, 17], 741);
                step(f, Op::DotV, &[19, 17, 214], 742);
                step(f, Op::NegF, &[214, 216], 743);
                step(f, Op::DotV, &[17, 17, 198], 744);
                step(f, Op::DivF, &[216, 198, 207], 745);
                step(f, Op::ClampF, &[207, 158, 160, 210], 746);
                step(f, Op::SubF, &[160, 210, 217], 747);
                step(f, Op::MulF, &[202, 217, 221], 748);
                step(f, Op::DivF, &[194, 221, 197], 749);
                step(f, Op::RemapF, &[197, 54, 55, 158, 160, 9, 196], 750);
                step(f, Op::BreakVector, &[22, 219, 220, 222], 751);
                step(f, Op::NegF, &[219, 224], 752);
                step(f, Op::Atan2F, &[224, 220, 183], 753);
                step(f, Op::AbsF, &[183, 186], 754);
                step(f, Op::RemapF, &[186, 113, 114, 158, 160, 9, 187], 755);
                step(f, Op::MulF, &[196, 187, 211], 756);
                step(f, Op::DivF, &[194, 202, 215], 757);
                step(f, Op::RemapF, &[215, 54, 55, 158, 160, 9, 189], 758);
                step(f, Op::BreakVector, &[21, 204, 190, 191], 759);
                step(f, Op::NegF, &[190, 192], 760);
                step(f, Op::Atan2F, &[204, 192, 200], 761);
                step(f, Op::AbsF, &[200, 213], 762);
                step(f, Op::RemapF, &[213, 113, 114, 158, 160, 9, 208], 763);
                step(f, Op::MulF, &[189, 208, 185], 764);
                step(f, Op::Select(ValueType::Float), &[17, 211, 185, 193], 765);
                step(f, Op::FloatLerp, &[19, 158, 115, 184], 766);
                step(f, Op::MaxF, &[193, 184, 195], 767);
                step(f, Op::MaxF, &[195, 158, 201], 768);
                step(f, Op::Copy(ValueType::Float), &[201, 19], 769);
                step(f, Op::Select(ValueType::Float), &[17, 183, 200, 188], 770);
                step(f, Op::Copy(ValueType::Float), &[188, 20], 771);
                step(f, Op::Copy(ValueType::Vec3), &[18, 5], 772);
                step(f, Op::Copy(ValueType::Float), &[202, 21], 773);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 774);
                step(f, Op::Copy(ValueType::Int), &[2, 6], 775);
                775
            }
            775 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 6, 0, 7, 8, 1707], 776)
            }
            776 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 16], 777);
                step(f, Op::Copy(ValueType::Bool), &[10, 18], 778);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 7, 13], 779);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 199], 780);
                step(f, Op::GreaterEqualF, &[199, 160, 15], 781);
                step(f, Op::And, &[13, 15, 12], 782);
                step(f, Op::Or, &[1, 2, 11], 783);
                step(f, Op::GreaterF, &[27, 158, 14], 784);
                step(f, Op::Or, &[11, 14, 17], 785);
                step(f, Op::Not, &[17, 13], 786);
                step(f, Op::And, &[12, 13, 11], 787);
                step(f, Op::JumpIfFalse, &[11, 897], 788)
            }
            788 => {
                step(f, Op::ArrayAt(Elem::Transform), &[2, 7, 5], 789);
                step(f, Op::BreakTransform, &[5, 20, 2, 19], 790);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 7, 17], 791);
                step(f, Op::SubV, &[20, 17, 22], 792);
                step(f, Op::TransformPoint, &[2, 22, 21], 793);
                step(f, Op::GetTransform, &[34, 2, 9, 6], 794);
                step(f, Op::BreakTransform, &[6, 18, 3, 22], 795);
                step(f, Op::BreakVector, &[18, 203, 218, 182], 796);
                step(f, Op::SubF, &[160, 18, 209], 797);
                step(f, Op::MulF, &[17, 209, 212], 798);
                step(f, Op::QuatFromAxisAngle, &[10, 212, 4], 799);
                step(f, Op::GetTransform, &[0, 2, 9, 4], 800);
                step(f, Op::BreakTransform, &[4, 23, 5, 24], 801);
                step(f, Op::SubV, &[23, 18, 25], 802);
                step(f, Op::BreakVector, &[25, 206, 205, 223], 803);
                step(f, Op::MakeVector, &[206, 205, 158, 26], 804);
                step(f, Op::RotateVector, &[4, 26, 27], 805);
                step(f, Op::BreakVector, &[27, 214, 198, 216], 806);
                step(f, Op::MulF, &[53, 18, 207], 807);
                step(f, Op::Equals(Elem::Int), &[7, 2, 14], 808);
                step(f, Op::Select(ValueType::Float), &[14, 160, 162, 210], 809);
                step(f, Op::MulF, &[207, 210, 217], 810);
                step(f, Op::AddF, &[214, 217, 221], 811);
                step(f, Op::AddF, &[203, 221, 197], 812);
                step(f, Op::AddF, &[218, 198, 222], 813);
                step(f, Op::BreakVector, &[23, 219, 220, 224], 814);
                step(f, Op::SubF, &[224, 59, 186], 815);
                step(f, Op::MakeVector, &[197, 222, 186, 28], 816);
                step(f, Op::MulF, &[9, 159, 187], 817);
                step(f, Op::ScaleV, &[2, 187, 29], 818);
                step(f, Op::AddV, &[28, 29, 30], 819);
                step(f, Op::DistanceV, &[21, 30, 196], 820);
                step(f, Op::TransformVector, &[2, 11, 21], 821);
                step(f, Op::DistanceV, &[21, 11, 194], 822);
                step(f, Op::MaxF, &[196, 194, 215], 823);
                step(f, Op::LessEqualF, &[215, 66, 17], 824);
                step(f, Op::LengthV, &[2, 191], 825);
                step(f, Op::LengthV, &[4, 190], 826);
                step(f, Op::MaxF, &[191, 190, 192], 827);
                step(f, Op::LessEqualF, &[192, 35, 12], 828);
                step(f, Op::And, &[17, 12, 13], 829);
                step(f, Op::ArrayAt(Elem::Bool), &[1, 7, 11], 830);
                step(f, Op::And, &[13, 11, 12], 831);
                step(f, Op::JumpIfFalse, &[12, 834], 832)
            }
            832 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 18], 833);
                step(f, Op::Jump, &[863], 834)
            }
            834 => {
                step(f, Op::MakeVector, &[158, 158, 64, 21], 835);
                step(f, Op::AddV, &[30, 21, 31], 836);
                step(f, Op::SubV, &[30, 21, 32], 837);
                step(f, Op::SphereTrace, &[31, 32, 63, 17, 33, 34, 204], 838);
                step(f, Op::SubV, &[33, 30, 34], 839);
                step(f, Op::DistanceV, &[34, 17, 213], 840);
                step(f, Op::RotateVector, &[0, 9, 33], 841);
                step(f, Op::ScaleV, &[33, 68, 34], 842);
                step(f, Op::AddV, &[31, 34, 35], 843);
                step(f, Op::AddV, &[32, 34, 36], 844);
                step(f, Op::SphereTrace, &[35, 36, 63, 13, 37, 38, 189], 845);
                step(f, Op::SubV, &[37, 30, 39], 846);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 7, 40], 847);
                step(f, Op::DistanceV, &[39, 40, 208], 848);
                step(f, Op::MaxF, &[213, 208, 185], 849);
                step(f, Op::ScaleV, &[33, 65, 40], 850);
                step(f, Op::AddV, &[35, 40, 41], 851);
                step(f, Op::AddV, &[36, 40, 42], 852);
                step(f, Op::SphereTrace, &[41, 42, 63, 12, 43, 44, 211], 853);
                step(f, Op::SubV, &[43, 30, 45], 854);
                step(f, Op::ArrayAt(Elem::Vec3), &[2, 7, 46], 855);
                step(f, Op::DistanceV, &[45, 46, 184], 856);
                step(f, Op::MaxF, &[185, 184, 193], 857);
                step(f, Op::LessEqualF, &[193, 66, 19], 858);
                step(f, Op::And, &[17, 13, 20], 859);
                step(f, Op::And, &[20, 11, 17], 860);
                step(f, Op::And, &[19, 17, 20], 861);
                step(f, Op::JumpIfFalse, &[20, 863], 862)
            }
            862 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 18], 863);
                863
            }
            863 => {
                step(f, Op::JumpIfFalse, &[18, 897], 864)
            }
            864 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 7], 865);
                step(f, Op::BreakTransform, &[7, 46, 6, 47], 866);
                step(f, Op::AddV, &[30, 17, 48], 867);
                step(f, Op::Copy(ValueType::Float), &[56, 195], 868);
                step(f, Op::Copy(ValueType::Float), &[58, 201], 869);
                step(f, Op::SubV, &[48, 20, 17], 870);
                step(f, Op::DeltaTime, &[183], 871);
                step(f, Op::DivF, &[201, 183, 200], 872);
                step(f, Op::ScaleV, &[17, 200, 49], 873);
                step(f, Op::AddV, &[48, 49, 50], 874);
                step(f, Op::AddV, &[20, 49, 51], 875);
                step(f, Op::SubV, &[46, 51, 49], 876);
                step(f, Op::FloatLerp, &[158, 160, 195, 188], 877);
                step(f, Op::SubF, &[160, 188, 202], 878);
                step(f, Op::ScaleV, &[49, 202, 51], 879);
                step(f, Op::AddV, &[50, 51, 49], 880);
                step(f, Op::MulF, &[195, 183, 194], 881);
                step(f, Op::GreaterF, &[194, 158, 17], 882);
                step(f, Op::DivF, &[188, 194, 196], 883);
                step(f, Op::Select(ValueType::Float), &[17, 196, 160, 215], 884);
                step(f, Op::ScaleV, &[17, 215, 50], 885);
                step(f, Op::SubV, &[49, 50, 51], 886);
                step(f, Op::Copy(ValueType::Vec3), &[51, 17], 887);
                step(f, Op::BreakVector, &[17, 190, 191, 192], 888);
                step(f, Op::ClampF, &[192, 69, 70, 204], 889);
                step(f, Op::MakeVector, &[190, 191, 204, 49], 890);
                step(f, Op::MakeTransform, &[49, 6, 6, 8], 891);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 7, 8], 892);
                step(f, Op::MakeTransform, &[48, 1, 6, 8], 893);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 7, 8], 894);
                step(f, Op::JumpIfFalse, &[11, 896], 895)
            }
            895 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 7], 896);
                896
            }
            896 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 16], 897);
                897
            }
            897 => {
                step(f, Op::JumpIfFalse, &[16, 1102], 898)
            }
            898 => {
                step(f, Op::GetTransform, &[34, 2, 9, 6], 899);
                step(f, Op::BreakTransform, &[6, 18, 3, 22], 900);
                step(f, Op::BreakVector, &[18, 203, 218, 182], 901);
                step(f, Op::SubF, &[160, 18, 209], 902);
                step(f, Op::MulF, &[17, 209, 212], 903);
                step(f, Op::QuatFromAxisAngle, &[10, 212, 4], 904);
                step(f, Op::GetTransform, &[0, 2, 9, 4], 905);
                step(f, Op::BreakTransform, &[4, 23, 5, 24], 906);
                step(f, Op::SubV, &[23, 18, 25], 907);
                step(f, Op::BreakVector, &[25, 206, 205, 223], 908);
                step(f, Op::MakeVector, &[206, 205, 158, 26], 909);
                step(f, Op::RotateVector, &[4, 26, 27], 910);
                step(f, Op::BreakVector, &[27, 214, 198, 216], 911);
                step(f, Op::MulF, &[53, 18, 207], 912);
                step(f, Op::Equals(Elem::Int), &[7, 2, 14], 913);
                step(f, Op::Select(ValueType::Float), &[14, 160, 162, 210], 914);
                step(f, Op::MulF, &[207, 210, 217], 915);
                step(f, Op::AddF, &[214, 217, 221], 916);
                step(f, Op::AddF, &[203, 221, 197], 917);
                step(f, Op::AddF, &[218, 198, 222], 918);
                step(f, Op::BreakVector, &[23, 219, 220, 224], 919);
                step(f, Op::SubF, &[224, 59, 186], 920);
                step(f, Op::MakeVector, &[197, 222, 186, 28], 921);
                step(f, Op::SubF, &[160, 199, 208], 922);
                step(f, Op::MaxF, &[208, 158, 213], 923);
                step(f, Op::MulF, &[13, 10, 184], 924);
                step(f, Op::MulF, &[213, 184, 185], 925);
                step(f, Op::ScaleV, &[2, 185, 50], 926);
                step(f, Op::AddV, &[28, 50, 51], 927);
                step(f, Op::MulF, &[9, 159, 187], 928);
                step(f, Op::ScaleV, &[2, 187, 29], 929);
                step(f, Op::AddV, &[51, 29, 17], 930);
                step(f, Op::RotateVector, &[0, 9, 33], 931);
                step(f, Op::Copy(ValueType::Float), &[165, 193], 932);
                step(f, Op::Copy(ValueType::Vec3), &[7, 49], 933);
                step(f, Op::Copy(ValueType::Vec3), &[10, 48], 934);
                step(f, Op::Copy(ValueType::Bool), &[10, 19], 935);
                step(f, Op::Copy(ValueType::Float), &[165, 201], 936);
                step(f, Op::Copy(ValueType::Vec3), &[7, 51], 937);
                step(f, Op::MulI, &[0, 0, 6], 938);
                step(f, Op::Copy(ValueType::Int), &[6, 8], 939);
                step(f, Op::Copy(ValueType::Int), &[2, 6], 940);
                step(f, Op::SubI, &[0, 3, 9], 941);
                step(f, Op::DivI, &[9, 4, 10], 942);
                step(f, Op::MakeVector, &[158, 158, 64, 52], 943);
                step(f, Op::ScaleV, &[33, 68, 53], 944);
                944
            }
            944 => {
                step(f, Op::ForNext, &[6, 8, 9, 991], 945)
            }
            945 => {
                step(f, Op::ModI, &[9, 0, 6], 946);
                step(f, Op::ToFloat, &[6, 200], 947);
                step(f, Op::MulF, &[200, 65, 202], 948);
                step(f, Op::MulF, &[202, 210, 183], 949);
                step(f, Op::MakeVector, &[183, 158, 158, 54], 950);
                step(f, Op::DivI, &[9, 0, 8], 951);
                step(f, Op::SubI, &[8, 10, 6], 952);
                step(f, Op::ToFloat, &[6, 195], 953);
                step(f, Op::MulF, &[195, 65, 188], 954);
                step(f, Op::ScaleV, &[33, 188, 55], 955);
                step(f, Op::AddV, &[54, 55, 56], 956);
                step(f, Op::AddV, &[17, 56, 54], 957);
                step(f, Op::AddV, &[54, 52, 55], 958);
                step(f, Op::SubV, &[54, 52, 17], 959);
                step(f, Op::SphereTrace, &[55, 17, 63, 20, 52, 54, 194], 960);
                step(f, Op::BreakVector, &[52, 196, 215, 192], 961);
                step(f, Op::AddV, &[55, 53, 57], 962);
                step(f, Op::AddV, &[17, 53, 55], 963);
                step(f, Op::SphereTrace, &[57, 55, 63, 18, 17, 53, 190], 964);
                step(f, Op::BreakVector, &[17, 191, 204, 200], 965);
                step(f, Op::SubF, &[192, 200, 202], 966);
                step(f, Op::AbsF, &[202, 183], 967);
                step(f, Op::Select(ValueType::Float), &[20, 158, 160, 195], 968);
                step(f, Op::AddF, &[183, 195, 188], 969);
                step(f, Op::LengthV, &[56, 194], 970);
                step(f, Op::RemapF, &[194, 158, 171, 158, 160, 9, 196], 971);
                step(f, Op::MinF, &[192, 200, 215], 972);
                step(f, Op::RemapF, &[215, 172, 171, 160, 159, 9, 190], 973);
                step(f, Op::AddF, &[196, 190, 191], 974);
                step(f, Op::AddF, &[188, 191, 204], 975);
                step(f, Op::LessF, &[204, 193, 17], 976);
                step(f, Op::And, &[20, 17, 11], 977);
                step(f, Op::JumpIfFalse, &[11, 985], 978)
            }
            978 => {
                step(f, Op::Copy(ValueType::Float), &[193, 201], 979);
                step(f, Op::Copy(ValueType::Vec3), &[49, 51], 980);
                step(f, Op::Copy(ValueType::Float), &[204, 193], 981);
                step(f, Op::Copy(ValueType::Vec3), &[52, 49], 982);
                step(f, Op::Copy(ValueType::Vec3), &[54, 48], 983);
                step(f, Op::Copy(ValueType::Bool), &[9, 19], 984);
                step(f, Op::Jump, &[990], 985)
            }
            985 => {
                step(f, Op::LessF, &[204, 201, 16], 986);
                step(f, Op::And, &[20, 16, 14], 987);
                step(f, Op::JumpIfFalse, &[14, 990], 988)
            }
            988 => {
                step(f, Op::Copy(ValueType::Float), &[204, 201], 989);
                step(f, Op::Copy(ValueType::Vec3), &[52, 51], 990);
                990
            }
            990 => {
                step(f, Op::Jump, &[944], 991)
            }
            991 => {
                step(f, Op::JumpIfFalse, &[8, 993], 992)
            }
            992 => {
                step(f, Op::DrawSphere, &[49, 63, 9], 993);
                993
            }
            993 => {
                step(f, Op::GreaterF, &[67, 158, 18], 994);
                step(f, Op::SubF, &[193, 201, 202], 995);
                step(f, Op::DivF, &[202, 67, 183], 996);
                step(f, Op::PowF, &[173, 183, 195], 997);
                step(f, Op::Select(ValueType::Float), &[18, 195, 158, 194], 998);
                step(f, Op::ScaleV, &[51, 194, 53], 999);
                step(f, Op::AddV, &[49, 53, 55], 1000);
                step(f, Op::AddF, &[194, 160, 192], 1001);
                step(f, Op::DivF, &[160, 192, 200], 1002);
                step(f, Op::ScaleV, &[55, 200, 57], 1003);
                step(f, Op::Copy(ValueType::Vec3), &[57, 17], 1004);
                step(f, Op::Copy(ValueType::Vec3), &[48, 56], 1005);
                step(f, Op::Copy(ValueType::Bool), &[19, 17], 1006);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 7], 1007);
                step(f, Op::BreakTransform, &[7, 46, 6, 47], 1008);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 199], 1009);
                step(f, Op::SubF, &[160, 199, 208], 1010);
                step(f, Op::MaxF, &[208, 158, 213], 1011);
                step(f, Op::MulF, &[13, 10, 184], 1012);
                step(f, Op::MulF, &[213, 184, 185], 1013);
                step(f, Op::ScaleV, &[2, 185, 50], 1014);
                step(f, Op::SubV, &[17, 50, 54], 1015);
                step(f, Op::Select(ValueType::Vec3), &[17, 54, 46, 52], 1016);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 7, 5], 1017);
                step(f, Op::BreakTransform, &[5, 20, 2, 19], 1018);
                step(f, Op::Copy(ValueType::Float), &[56, 215], 1019);
                step(f, Op::Copy(ValueType::Float), &[58, 190], 1020);
                step(f, Op::SubV, &[52, 20, 51], 1021);
                step(f, Op::DeltaTime, &[196], 1022);
                step(f, Op::DivF, &[190, 196, 188], 1023);
                step(f, Op::ScaleV, &[51, 188, 49], 1024);
                step(f, Op::AddV, &[52, 49, 53], 1025);
                step(f, Op::AddV, &[20, 49, 55], 1026);
                step(f, Op::SubV, &[46, 55, 57], 1027);
                step(f, Op::FloatLerp, &[158, 160, 215, 191], 1028);
                step(f, Op::SubF, &[160, 191, 204], 1029);
                step(f, Op::ScaleV, &[57, 204, 48], 1030);
                step(f, Op::AddV, &[53, 48, 17], 1031);
                step(f, Op::MulF, &[215, 196, 193], 1032);
                step(f, Op::GreaterF, &[193, 158, 11], 1033);
                step(f, Op::DivF, &[191, 193, 201], 1034);
                step(f, Op::Select(ValueType::Float), &[11, 201, 160, 202], 1035);
                step(f, Op::ScaleV, &[51, 202, 50], 1036);
                step(f, Op::SubV, &[17, 50, 19], 1037);
                step(f, Op::Copy(ValueType::Vec3), &[19, 20], 1038);
                step(f, Op::BreakVector, &[20, 183, 195, 194], 1039);
                step(f, Op::ClampF, &[194, 69, 70, 192], 1040);
                step(f, Op::MakeVector, &[183, 195, 192, 49], 1041);
                step(f, Op::RotationFromNormal, &[56, 200, 208, 2], 1042);
                step(f, Op::PerFootRotationFactor, &[17, 119, 120, 184], 1043);
                step(f, Op::MulF, &[17, 184, 213], 1044);
                step(f, Op::SubF, &[160, 18, 209], 1045);
                step(f, Op::MulF, &[213, 209, 185], 1046);
                step(f, Op::QuatFromAxisAngle, &[10, 185, 7], 1047);
                step(f, Op::MulQ, &[2, 7, 8], 1048);
                step(f, Op::Select(ValueType::Quat), &[17, 8, 6, 2], 1049);
                step(f, Op::MakeTransform, &[49, 2, 6, 8], 1050);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 7, 8], 1051);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 7], 1052);
                step(f, Op::BreakTransform, &[7, 46, 6, 47], 1053);
                step(f, Op::Select(ValueType::Vec3), &[17, 54, 46, 52], 1054);
                step(f, Op::MakeTransform, &[52, 1, 6, 5], 1055);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 7, 5], 1056);
                step(f, Op::GetTransform, &[34, 2, 9, 6], 1057);
                step(f, Op::BreakTransform, &[6, 18, 3, 22], 1058);
                step(f, Op::BreakVector, &[18, 203, 218, 182], 1059);
                step(f, Op::MulF, &[17, 209, 212], 1060);
                step(f, Op::QuatFromAxisAngle, &[10, 212, 4], 1061);
                step(f, Op::GetTransform, &[0, 2, 9, 4], 1062);
                step(f, Op::BreakTransform, &[4, 23, 5, 24], 1063);
                step(f, Op::SubV, &[23, 18, 25], 1064);
                step(f, Op::BreakVector, &[25, 206, 205, 223], 1065);
                step(f, Op::MakeVector, &[206, 205, 158, 26], 1066);
                step(f, Op::RotateVector, &[4, 26, 27], 1067);
                step(f, Op::BreakVector, &[27, 214, 198, 216], 1068);
                step(f, Op::MulF, &[53, 18, 207], 1069);
                step(f, Op::MulF, &[207, 210, 217], 1070);
                step(f, Op::AddF, &[214, 217, 221], 1071);
                step(f, Op::AddF, &[203, 221, 197], 1072);
                step(f, Op::AddF, &[218, 198, 222], 1073);
                step(f, Op::BreakVector, &[23, 219, 220, 224], 1074);
                step(f, Op::SubF, &[224, 59, 186], 1075);
                step(f, Op::MakeVector, &[197, 222, 186, 28], 1076);
                step(f, Op::MulF, &[9, 159, 187], 1077);
                step(f, Op::ScaleV, &[2, 187, 29], 1078);
                step(f, Op::AddV, &[28, 29, 30], 1079);
                step(f, Op::SubV, &[52, 30, 55], 1080);
                step(f, Op::ArraySetAt(Elem::Vec3), &[0, 7, 55], 1081);
                step(f, Op::ArraySetAt(Elem::Bool), &[1, 7, 17], 1082);
                step(f, Op::GreaterEqualF, &[199, 160, 15], 1083);
                step(f, Op::JumpIfFalse, &[15, 1100], 1084)
            }
            1084 => {
                step(f, Op::MakeVector, &[158, 158, 64, 21], 1085);
                step(f, Op::AddV, &[30, 21, 31], 1086);
                step(f, Op::RotateVector, &[0, 9, 33], 1087);
                step(f, Op::ScaleV, &[33, 68, 34], 1088);
                step(f, Op::AddV, &[31, 34, 35], 1089);
                step(f, Op::SubV, &[30, 21, 32], 1090);
                step(f, Op::AddV, &[32, 34, 36], 1091);
                step(f, Op::SphereTrace, &[35, 36, 63, 13, 37, 38, 189], 1092);
                step(f, Op::SubV, &[37, 30, 39], 1093);
                step(f, Op::ArraySetAt(Elem::Vec3), &[1, 7, 39], 1094);
                step(f, Op::ScaleV, &[33, 65, 40], 1095);
                step(f, Op::AddV, &[35, 40, 41], 1096);
                step(f, Op::AddV, &[36, 40, 42], 1097);
                step(f, Op::SphereTrace, &[41, 42, 63, 12, 43, 44, 211], 1098);
                step(f, Op::SubV, &[43, 30, 45], 1099);
                step(f, Op::ArraySetAt(Elem::Vec3), &[2, 7, 45], 1100);
                1100
            }
            1100 => {
                step(f, Op::JumpIfFalse, &[17, 1102], 1101)
            }
            1101 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 7], 1102);
                1102
            }
            1102 => {
                step(f, Op::ArrayAt(Elem::Float), &[4, 7, 190], 1103);
                step(f, Op::FloatLerp, &[190, 158, 112, 188], 1104);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 7, 16], 1105);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 204], 1106);
                step(f, Op::GreaterEqualF, &[204, 160, 20], 1107);
                step(f, Op::And, &[16, 20, 14], 1108);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 7, 8], 1109);
                step(f, Op::GreaterF, &[27, 158, 18], 1110);
                step(f, Op::InterpolateTransform, &[2, 3, 28, 7], 1111);
                step(f, Op::Select(ValueType::Transform), &[18, 7, 2, 5], 1112);
                step(f, Op::MakeAbsolute, &[8, 5, 6], 1113);
                step(f, Op::BreakTransform, &[6, 57, 7, 48], 1114);
                step(f, Op::RotateVector, &[7, 9, 53], 1115);
                step(f, Op::SubF, &[160, 18, 196], 1116);
                step(f, Op::MulF, &[17, 196, 215], 1117);
                step(f, Op::LimitRotationAroundZ, &[7, 215, 109, 8], 1118);
                step(f, Op::RotateVector, &[8, 9, 51], 1119);
                step(f, Op::CrossV, &[53, 51, 17], 1120);
                step(f, Op::BreakVector, &[17, 191, 193, 201], 1121);
                step(f, Op::DotV, &[53, 51, 202], 1122);
                step(f, Op::Atan2F, &[201, 202, 194], 1123);
                step(f, Op::AbsF, &[194, 183], 1124);
                step(f, Op::Select(ValueType::Float), &[14, 183, 158, 192], 1125);
                step(f, Op::AddF, &[188, 192, 195], 1126);
                step(f, Op::ArraySetAt(Elem::Float), &[4, 7, 195], 1127);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 7, 4], 1128);
                step(f, Op::BreakTransform, &[4, 50, 2, 19], 1129);
                step(f, Op::AddF, &[73, 74, 200], 1130);
                step(f, Op::ClampSpatially, &[57, 50, 158, 200, 20], 1131);
                step(f, Op::MakeTransform, &[20, 8, 6, 8], 1132);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 7, 8], 1133);
                step(f, Op::JumpIfFalse, &[16, 1210], 1134)
            }
            1134 => {
                step(f, Op::JumpIfFalse, &[20, 1136], 1135)
            }
            1135 => {
                step(f, Op::Jump, &[1209], 1136)
            }
            1136 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 6], 1137);
                step(f, Op::BreakTransform, &[6, 56, 6, 49], 1138);
                step(f, Op::SubF, &[160, 204, 208], 1139);
                step(f, Op::MulF, &[13, 10, 184], 1140);
                step(f, Op::MulF, &[208, 184, 213], 1141);
                step(f, Op::ScaleV, &[2, 213, 47], 1142);
                step(f, Op::AddV, &[56, 47, 46], 1143);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1144);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 9], 1145);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 9, 11], 1146);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 9, 4], 1147);
                step(f, Op::BreakTransform, &[4, 54, 3, 22], 1148);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 9, 8], 1149);
                step(f, Op::BreakTransform, &[8, 24, 5, 18], 1150);
                step(f, Op::LessEqualF, &[95, 158, 15], 1151);
                step(f, Op::ArrayAt(Elem::Float), &[2, 9, 185], 1152);
                step(f, Op::SmoothStepF, &[185, 158, 95, 182], 1153);
                step(f, Op::Select(ValueType::Float), &[15, 160, 182, 209], 1154);
                step(f, Op::LerpV, &[54, 24, 209, 25], 1155);
                step(f, Op::MakeTransform, &[25, 1, 6, 9], 1156);
                step(f, Op::Select(ValueType::Transform), &[11, 4, 9, 10], 1157);
                step(f, Op::MakeAbsolute, &[10, 5, 11], 1158);
                step(f, Op::Select(ValueType::Transform), &[19, 11, 10, 12], 1159);
                step(f, Op::BreakTransform, &[12, 26, 4, 27], 1160);
                step(f, Op::SubF, &[160, 19, 212], 1161);
                step(f, Op::MulF, &[196, 212, 223], 1162);
                step(f, Op::MulF, &[17, 223, 205], 1163);
                step(f, Op::FootAvoidance, &[46, 26, 205, 19, 91, 23], 1164);
                step(f, Op::RemapF, &[18, 94, 160, 158, 160, 9, 206], 1165);
                step(f, Op::LerpV, &[46, 23, 206, 28], 1166);
                step(f, Op::FootAvoidance, &[28, 26, 20, 19, 117, 29], 1167);
                step(f, Op::LerpV, &[28, 29, 19, 52], 1168);
                step(f, Op::MakeTransform, &[52, 6, 6, 13], 1169);
                step(f, Op::BreakTransform, &[13, 55, 7, 31], 1170);
                step(f, Op::MakeVector, &[158, 158, 64, 21], 1171);
                step(f, Op::AddV, &[55, 21, 32], 1172);
                step(f, Op::SubV, &[55, 21, 34], 1173);
                step(f, Op::LineTrace, &[32, 34, 13, 38, 37, 216], 1174);
                step(f, Op::RotateVector, &[7, 10, 39], 1175);
                step(f, Op::FindQuatBetween, &[39, 37, 2], 1176);
                step(f, Op::MulQ, &[2, 7, 8], 1177);
                step(f, Op::MulF, &[62, 61, 207], 1178);
                step(f, Op::AddF, &[207, 72, 210], 1179);
                step(f, Op::NegF, &[210, 214], 1180);
                step(f, Op::MakeVector, &[158, 214, 158, 33], 1181);
                step(f, Op::RotateVector, &[8, 33, 35], 1182);
                step(f, Op::AddV, &[38, 35, 36], 1183);
                step(f, Op::AddV, &[36, 21, 40], 1184);
                step(f, Op::SubV, &[36, 21, 41], 1185);
                step(f, Op::LineTrace, &[40, 41, 12, 42, 44, 217], 1186);
                step(f, Op::BreakVector, &[42, 203, 221, 198], 1187);
                step(f, Op::BreakVector, &[36, 218, 219, 220], 1188);
                step(f, Op::SubF, &[198, 220, 224], 1189);
                step(f, Op::Select(ValueType::Float), &[12, 224, 158, 186], 1190);
                step(f, Op::AddF, &[68, 72, 197], 1191);
                step(f, Op::MakeVector, &[158, 197, 158, 30], 1192);
                step(f, Op::RotateVector, &[8, 30, 43], 1193);
                step(f, Op::AddV, &[38, 43, 45], 1194);
                step(f, Op::AddV, &[45, 21, 48], 1195);
                step(f, Op::SubV, &[45, 21, 17], 1196);
                step(f, Op::LineTrace, &[48, 17, 17, 51, 53, 222], 1197);
                step(f, Op::BreakVector, &[51, 187, 199, 189], 1198);
                step(f, Op::BreakVector, &[45, 211, 190, 215], 1199);
                step(f, Op::SubF, &[189, 215, 191], 1200);
                step(f, Op::Select(ValueType::Float), &[17, 191, 158, 193], 1201);
                step(f, Op::MaxF, &[186, 193, 201], 1202);
                step(f, Op::ClampF, &[201, 158, 71, 202], 1203);
                step(f, Op::MakeVector, &[158, 158, 202, 19], 1204);
                step(f, Op::AddV, &[38, 19, 57], 1205);
                step(f, Op::MakeTransform, &[57, 8, 6, 14], 1206);
                step(f, Op::Select(ValueType::Transform), &[13, 14, 13, 15], 1207);
                step(f, Op::Copy(ValueType::Transform), &[15, 13], 1208);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 7, 13], 1209);
                1209
            }
            1209 => {
                step(f, Op::Jump, &[1326], 1210)
            }
            1210 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 7, 14], 1211);
                step(f, Op::MakeAbsolute, &[14, 5, 15], 1212);
                step(f, Op::BreakTransform, &[15, 20, 2, 31], 1213);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 6], 1214);
                step(f, Op::BreakTransform, &[6, 56, 6, 49], 1215);
                step(f, Op::SubF, &[160, 204, 208], 1216);
                step(f, Op::MulF, &[13, 10, 184], 1217);
                step(f, Op::MulF, &[208, 184, 213], 1218);
                step(f, Op::ScaleV, &[2, 213, 47], 1219);
                step(f, Op::AddV, &[56, 47, 46], 1220);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1221);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 9], 1222);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 9, 11], 1223);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 9, 4], 1224);
                step(f, Op::BreakTransform, &[4, 54, 3, 22], 1225);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 9, 8], 1226);
                step(f, Op::BreakTransform, &[8, 24, 5, 18], 1227);
                step(f, Op::LessEqualF, &[95, 158, 15], 1228);
                step(f, Op::ArrayAt(Elem::Float), &[2, 9, 185], 1229);
                step(f, Op::SmoothStepF, &[185, 158, 95, 182], 1230);
                step(f, Op::Select(ValueType::Float), &[15, 160, 182, 209], 1231);
                step(f, Op::LerpV, &[54, 24, 209, 25], 1232);
                step(f, Op::MakeTransform, &[25, 1, 6, 9], 1233);
                step(f, Op::Select(ValueType::Transform), &[11, 4, 9, 10], 1234);
                step(f, Op::MakeAbsolute, &[10, 5, 11], 1235);
                step(f, Op::Select(ValueType::Transform), &[19, 11, 10, 12], 1236);
                step(f, Op::BreakTransform, &[12, 26, 4, 27], 1237);
                step(f, Op::SubF, &[160, 19, 212], 1238);
                step(f, Op::MulF, &[196, 212, 223], 1239);
                step(f, Op::MulF, &[17, 223, 205], 1240);
                step(f, Op::FootAvoidance, &[46, 26, 205, 19, 91, 23], 1241);
                step(f, Op::RemapF, &[18, 94, 160, 158, 160, 9, 206], 1242);
                step(f, Op::LerpV, &[46, 23, 206, 28], 1243);
                step(f, Op::FootAvoidance, &[28, 26, 20, 19, 117, 29], 1244);
                step(f, Op::LerpV, &[28, 29, 19, 52], 1245);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 7, 13], 1246);
                step(f, Op::MakeAbsolute, &[13, 5, 14], 1247);
                step(f, Op::BreakTransform, &[14, 55, 7, 32], 1248);
                step(f, Op::ArrayAt(Elem::Float), &[3, 7, 194], 1249);
                step(f, Op::SubF, &[204, 194, 183], 1250);
                step(f, Op::DeltaTime, &[188], 1251);
                step(f, Op::DivF, &[58, 188, 192], 1252);
                step(f, Op::MulF, &[183, 192, 195], 1253);
                step(f, Op::AddF, &[194, 195, 200], 1254);
                step(f, Op::ClampF, &[200, 158, 160, 216], 1255);
                step(f, Op::AddF, &[204, 195, 207], 1256);
                step(f, Op::ClampF, &[207, 158, 160, 210], 1257);
                step(f, Op::AddF, &[216, 210, 214], 1258);
                step(f, Op::MulF, &[214, 159, 217], 1259);
                step(f, Op::SubF, &[160, 217, 203], 1260);
                step(f, Op::GreaterF, &[183, 158, 14], 1261);
                step(f, Op::SubF, &[210, 216, 221], 1262);
                step(f, Op::DivF, &[221, 183, 218], 1263);
                step(f, Op::Select(ValueType::Float), &[14, 218, 160, 219], 1264);
                step(f, Op::MulF, &[203, 219, 198], 1265);
                step(f, Op::MulF, &[90, 198, 220], 1266);
                step(f, Op::Copy(ValueType::Float), &[58, 224], 1267);
                step(f, Op::SubV, &[52, 55, 34], 1268);
                step(f, Op::DeltaTime, &[197], 1269);
                step(f, Op::DivF, &[224, 197, 222], 1270);
                step(f, Op::ScaleV, &[34, 222, 37], 1271);
                step(f, Op::AddV, &[52, 37, 39], 1272);
                step(f, Op::AddV, &[55, 37, 33], 1273);
                step(f, Op::SubV, &[20, 33, 35], 1274);
                step(f, Op::FloatLerp, &[158, 160, 220, 187], 1275);
                step(f, Op::SubF, &[160, 187, 199], 1276);
                step(f, Op::ScaleV, &[35, 199, 40], 1277);
                step(f, Op::AddV, &[39, 40, 41], 1278);
                step(f, Op::MulF, &[220, 197, 190], 1279);
                step(f, Op::GreaterF, &[190, 158, 12], 1280);
                step(f, Op::DivF, &[187, 190, 211], 1281);
                step(f, Op::Select(ValueType::Float), &[12, 211, 160, 189], 1282);
                step(f, Op::ScaleV, &[34, 189, 44], 1283);
                step(f, Op::SubV, &[41, 44, 42], 1284);
                step(f, Op::Copy(ValueType::Vec3), &[42, 36], 1285);
                step(f, Op::MakeTransform, &[36, 6, 6, 15], 1286);
                step(f, Op::BreakTransform, &[15, 30, 8, 43], 1287);
                step(f, Op::MakeVector, &[158, 158, 64, 21], 1288);
                step(f, Op::AddV, &[30, 21, 17], 1289);
                step(f, Op::SubV, &[30, 21, 48], 1290);
                step(f, Op::LineTrace, &[17, 48, 17, 53, 51, 215], 1291);
                step(f, Op::RotateVector, &[8, 10, 45], 1292);
                step(f, Op::FindQuatBetween, &[45, 51, 2], 1293);
                step(f, Op::MulQ, &[2, 8, 7], 1294);
                step(f, Op::MulF, &[62, 61, 191], 1295);
                step(f, Op::AddF, &[191, 72, 186], 1296);
                step(f, Op::NegF, &[186, 193], 1297);
                step(f, Op::MakeVector, &[158, 193, 158, 19], 1298);
                step(f, Op::RotateVector, &[7, 19, 38], 1299);
                step(f, Op::AddV, &[53, 38, 57], 1300);
                step(f, Op::AddV, &[57, 21, 31], 1301);
                step(f, Op::SubV, &[57, 21, 32], 1302);
                step(f, Op::LineTrace, &[31, 32, 13, 37, 55, 201], 1303);
                step(f, Op::BreakVector, &[37, 202, 188, 192], 1304);
                step(f, Op::BreakVector, &[57, 194, 200, 195], 1305);
                step(f, Op::SubF, &[192, 195, 207], 1306);
                step(f, Op::Select(ValueType::Float), &[13, 207, 158, 214], 1307);
                step(f, Op::AddF, &[68, 72, 217], 1308);
                step(f, Op::MakeVector, &[158, 217, 158, 20], 1309);
                step(f, Op::RotateVector, &[7, 20, 33], 1310);
                step(f, Op::AddV, &[53, 33, 35], 1311);
                step(f, Op::AddV, &[35, 21, 39], 1312);
                step(f, Op::SubV, &[35, 21, 40], 1313);
                step(f, Op::LineTrace, &[39, 40, 14, 34, 41, 210], 1314);
                step(f, Op::BreakVector, &[34, 216, 183, 221], 1315);
                step(f, Op::BreakVector, &[35, 218, 203, 219], 1316);
                step(f, Op::SubF, &[221, 219, 198], 1317);
                step(f, Op::Select(ValueType::Float), &[14, 198, 158, 224], 1318);
                step(f, Op::MaxF, &[214, 224, 222], 1319);
                step(f, Op::ClampF, &[222, 158, 71, 199], 1320);
                step(f, Op::MakeVector, &[158, 158, 199, 44], 1321);
                step(f, Op::AddV, &[53, 44, 42], 1322);
                step(f, Op::MakeTransform, &[42, 7, 6, 13], 1323);
                step(f, Op::Select(ValueType::Transform), &[17, 13, 15, 14], 1324);
                step(f, Op::Copy(ValueType::Transform), &[14, 13], 1325);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 7, 13], 1326);
                1326
            }
            1326 => {
                step(f, Op::JumpIfFalse, &[20, 1409], 1327)
            }
            1327 => {
                step(f, Op::JumpIfFalse, &[16, 1329], 1328)
            }
            1328 => {
                step(f, Op::Jump, &[1390], 1329)
            }
            1329 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 7, 15], 1330);
                step(f, Op::BreakTransform, &[15, 36, 2, 43], 1331);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1332);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 9], 1333);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 9, 14], 1334);
                step(f, Op::BreakTransform, &[14, 30, 8, 17], 1335);
                step(f, Op::MakeAbsolute, &[14, 5, 13], 1336);
                step(f, Op::BreakTransform, &[13, 48, 7, 45], 1337);
                step(f, Op::ArrayAt(Elem::Float), &[2, 9, 185], 1338);
                step(f, Op::SmoothStepF, &[185, 158, 160, 197], 1339);
                step(f, Op::RemapF, &[18, 158, 94, 158, 160, 9, 220], 1340);
                step(f, Op::MulF, &[197, 220, 187], 1341);
                step(f, Op::Select(ValueType::Float), &[19, 187, 158, 190], 1342);
                step(f, Op::LerpV, &[30, 48, 190, 51], 1343);
                step(f, Op::MakeTransform, &[51, 1, 6, 16], 1344);
                step(f, Op::BreakTransform, &[16, 19, 9, 38], 1345);
                step(f, Op::SubF, &[160, 19, 212], 1346);
                step(f, Op::MulF, &[196, 212, 223], 1347);
                step(f, Op::MulF, &[17, 223, 205], 1348);
                step(f, Op::FootAvoidance, &[36, 19, 205, 19, 91, 31], 1349);
                step(f, Op::MakeTransform, &[31, 2, 6, 17], 1350);
                step(f, Op::BreakTransform, &[17, 32, 2, 55], 1351);
                step(f, Op::MakeVector, &[158, 158, 64, 37], 1352);
                step(f, Op::AddV, &[32, 37, 57], 1353);
                step(f, Op::SubV, &[32, 37, 20], 1354);
                step(f, Op::LineTrace, &[57, 20, 12, 33, 21, 211], 1355);
                step(f, Op::RotateVector, &[2, 10, 39], 1356);
                step(f, Op::FindQuatBetween, &[39, 21, 10], 1357);
                step(f, Op::MulQ, &[10, 2, 11], 1358);
                step(f, Op::MulF, &[62, 61, 189], 1359);
                step(f, Op::AddF, &[189, 72, 215], 1360);
                step(f, Op::NegF, &[215, 191], 1361);
                step(f, Op::MakeVector, &[158, 191, 158, 40], 1362);
                step(f, Op::RotateVector, &[11, 40, 41], 1363);
                step(f, Op::AddV, &[33, 41, 34], 1364);
                step(f, Op::AddV, &[34, 37, 35], 1365);
                step(f, Op::SubV, &[34, 37, 44], 1366);
                step(f, Op::LineTrace, &[35, 44, 13, 53, 42, 186], 1367);
                step(f, Op::BreakVector, &[53, 193, 201, 188], 1368);
                step(f, Op::BreakVector, &[34, 202, 194, 200], 1369);
                step(f, Op::SubF, &[188, 200, 192], 1370);
                step(f, Op::Select(ValueType::Float), &[13, 192, 158, 195], 1371);
                step(f, Op::AddF, &[68, 72, 207], 1372);
                step(f, Op::MakeVector, &[158, 207, 158, 43], 1373);
                step(f, Op::RotateVector, &[11, 43, 36], 1374);
                step(f, Op::AddV, &[33, 36, 31], 1375);
                step(f, Op::AddV, &[31, 37, 55], 1376);
                step(f, Op::SubV, &[31, 37, 32], 1377);
                step(f, Op::LineTrace, &[55, 32, 14, 20, 57, 217], 1378);
                step(f, Op::BreakVector, &[20, 210, 183, 216], 1379);
                step(f, Op::BreakVector, &[31, 203, 218, 219], 1380);
                step(f, Op::SubF, &[216, 219, 221], 1381);
                step(f, Op::Select(ValueType::Float), &[14, 221, 158, 198], 1382);
                step(f, Op::MaxF, &[195, 198, 214], 1383);
                step(f, Op::ClampF, &[214, 158, 71, 224], 1384);
                step(f, Op::MakeVector, &[158, 158, 224, 21], 1385);
                step(f, Op::AddV, &[33, 21, 39], 1386);
                step(f, Op::MakeTransform, &[39, 11, 6, 18], 1387);
                step(f, Op::Select(ValueType::Transform), &[12, 18, 17, 19], 1388);
                step(f, Op::Copy(ValueType::Transform), &[19, 17], 1389);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 7, 17], 1390);
                1390
            }
            1390 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 7, 18], 1391);
                step(f, Op::BreakTransform, &[18, 40, 2, 41], 1392);
                step(f, Op::SubV, &[40, 50, 35], 1393);
                step(f, Op::LengthV, &[35, 222], 1394);
                step(f, Op::SubF, &[73, 74, 199], 1395);
                step(f, Op::SubF, &[222, 199, 211], 1396);
                step(f, Op::MulF, &[74, 163, 189], 1397);
                step(f, Op::ClampF, &[211, 158, 189, 215], 1398);
                step(f, Op::MulF, &[215, 215, 191], 1399);
                step(f, Op::MulF, &[74, 174, 186], 1400);
                step(f, Op::DivF, &[191, 186, 193], 1401);
                step(f, Op::SubF, &[222, 193, 201], 1402);
                step(f, Op::DivF, &[201, 222, 194], 1403);
                step(f, Op::ScaleV, &[35, 194, 42], 1404);
                step(f, Op::AddV, &[50, 42, 44], 1405);
                step(f, Op::MakeTransform, &[44, 2, 6, 19], 1406);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 19], 1407);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 19], 1408);
                step(f, Op::Jump, &[1578], 1409)
            }
            1409 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 7, 18], 1410);
                step(f, Op::BreakTransform, &[18, 40, 2, 41], 1411);
                step(f, Op::SubV, &[40, 50, 35], 1412);
                step(f, Op::LengthV, &[35, 222], 1413);
                step(f, Op::SubF, &[73, 74, 199], 1414);
                step(f, Op::SubF, &[222, 199, 211], 1415);
                step(f, Op::MulF, &[74, 163, 189], 1416);
                step(f, Op::ClampF, &[211, 158, 189, 215], 1417);
                step(f, Op::MulF, &[215, 215, 191], 1418);
                step(f, Op::MulF, &[74, 174, 186], 1419);
                step(f, Op::DivF, &[191, 186, 193], 1420);
                step(f, Op::SubF, &[222, 193, 201], 1421);
                step(f, Op::DivF, &[201, 222, 194], 1422);
                step(f, Op::ScaleV, &[35, 194, 42], 1423);
                step(f, Op::AddV, &[50, 42, 44], 1424);
                step(f, Op::MakeTransform, &[44, 2, 6, 19], 1425);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 7, 15], 1426);
                step(f, Op::ClampF, &[204, 158, 160, 202], 1427);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[6, 5], 1428);
                step(f, Op::ArrayReset(Elem::Vec3), &[5], 1429);
                step(f, Op::BreakTransform, &[19, 53, 10, 34], 1430);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 53], 1431);
                step(f, Op::UnitV, &[2, 43], 1432);
                step(f, Op::LengthV, &[2, 188], 1433);
                step(f, Op::RemapF, &[188, 158, 75, 158, 76, 9, 200], 1434);
                step(f, Op::ScaleV, &[43, 200, 36], 1435);
                step(f, Op::SubV, &[53, 36, 37], 1436);
                step(f, Op::MakeVector, &[158, 158, 78, 32], 1437);
                step(f, Op::AddV, &[37, 32, 55], 1438);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 55], 1439);
                step(f, Op::RemapF, &[188, 158, 75, 158, 81, 9, 192], 1440);
                step(f, Op::MakeVector, &[158, 158, 192, 57], 1441);
                step(f, Op::AddV, &[55, 57, 20], 1442);
                step(f, Op::BreakTransform, &[15, 31, 11, 21], 1443);
                step(f, Op::BreakVector, &[31, 207, 217, 183], 1444);
                step(f, Op::BreakVector, &[53, 210, 203, 218], 1445);
                step(f, Op::SubF, &[183, 218, 216], 1446);
                step(f, Op::MaxF, &[216, 158, 219], 1447);
                step(f, Op::MulF, &[219, 83, 221], 1448);
                step(f, Op::MinF, &[221, 84, 195], 1449);
                step(f, Op::AbsF, &[216, 198], 1450);
                step(f, Op::RemapF, &[198, 158, 87, 158, 86, 9, 214], 1451);
                step(f, Op::AddF, &[195, 214, 224], 1452);
                step(f, Op::MakeVector, &[158, 158, 224, 33], 1453);
                step(f, Op::AddV, &[20, 33, 39], 1454);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 39], 1455);
                step(f, Op::RemapF, &[188, 158, 75, 158, 77, 9, 199], 1456);
                step(f, Op::ScaleV, &[43, 199, 41], 1457);
                step(f, Op::AddV, &[31, 41, 40], 1458);
                step(f, Op::LerpF, &[29, 52, 18, 189], 1459);
                step(f, Op::MulF, &[14, 189, 211], 1460);
                step(f, Op::RemapF, &[211, 160, 38, 79, 80, 9, 215], 1461);
                step(f, Op::MakeVector, &[158, 158, 215, 35], 1462);
                step(f, Op::AddV, &[40, 35, 42], 1463);
                step(f, Op::RemapF, &[188, 158, 75, 158, 82, 9, 186], 1464);
                step(f, Op::MakeVector, &[158, 158, 186, 50], 1465);
                step(f, Op::AddV, &[42, 50, 44], 1466);
                step(f, Op::NegF, &[216, 191], 1467);
                step(f, Op::MaxF, &[191, 158, 193], 1468);
                step(f, Op::MulF, &[193, 85, 201], 1469);
                step(f, Op::AddF, &[201, 214, 222], 1470);
                step(f, Op::MakeVector, &[158, 158, 222, 34], 1471);
                step(f, Op::AddV, &[44, 34, 36], 1472);
                step(f, Op::LerpV, &[39, 36, 159, 32], 1473);
                step(f, Op::GetTransform, &[35, 2, 9, 17], 1474);
                step(f, Op::BreakTransform, &[17, 37, 2, 55], 1475);
                step(f, Op::BreakVector, &[37, 194, 200, 192], 1476);
                step(f, Op::SubF, &[160, 18, 207], 1477);
                step(f, Op::MulF, &[88, 207, 217], 1478);
                step(f, Op::MulF, &[17, 217, 203], 1479);
                step(f, Op::QuatFromAxisAngle, &[10, 203, 2], 1480);
                step(f, Op::SubV, &[32, 37, 57], 1481);
                step(f, Op::BreakVector, &[57, 210, 183, 218], 1482);
                step(f, Op::MakeVector, &[210, 183, 158, 21], 1483);
                step(f, Op::RotateVector, &[2, 21, 20], 1484);
                step(f, Op::BreakVector, &[20, 219, 221, 198], 1485);
                step(f, Op::AddF, &[194, 219, 195], 1486);
                step(f, Op::AddF, &[200, 221, 224], 1487);
                step(f, Op::BreakVector, &[32, 199, 189, 211], 1488);
                step(f, Op::MakeVector, &[195, 224, 211, 33], 1489);
                step(f, Op::DistanceV, &[53, 31, 215], 1490);
                step(f, Op::RemapF, &[215, 163, 175, 158, 160, 9, 188], 1491);
                step(f, Op::LerpV, &[32, 33, 188, 43], 1492);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 43], 1493);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 36], 1494);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 42], 1495);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 31], 1496);
                step(f, Op::JumpIfFalse, &[8, 1498], 1497)
            }
            1497 => {
                step(f, Op::DrawSpline, &[5, 2, 5, 159, 12], 1498);
                1498
            }
            1498 => {
                step(f, Op::Spline, &[5, 202, 2, 41, 35], 1499);
                step(f, Op::SlerpQ, &[10, 11, 202, 2], 1500);
                step(f, Op::MulF, &[202, 168, 186], 1501);
                step(f, Op::SinF, &[186, 216], 1502);
                step(f, Op::SmoothStepF, &[202, 158, 102, 191], 1503);
                step(f, Op::MulF, &[216, 191, 193], 1504);
                step(f, Op::MulF, &[193, 89, 201], 1505);
                step(f, Op::SlerpQ, &[2, 1, 201, 10], 1506);
                step(f, Op::MakeTransform, &[41, 10, 6, 18], 1507);
                step(f, Op::Copy(ValueType::Transform), &[18, 19], 1508);
                step(f, Op::BreakTransform, &[19, 40, 11, 50], 1509);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1510);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 9], 1511);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 9, 14], 1512);
                step(f, Op::BreakTransform, &[14, 30, 8, 17], 1513);
                step(f, Op::GreaterF, &[27, 158, 18], 1514);
                step(f, Op::InterpolateTransform, &[2, 3, 28, 7], 1515);
                step(f, Op::Select(ValueType::Transform), &[18, 7, 2, 5], 1516);
                step(f, Op::MakeAbsolute, &[14, 5, 13], 1517);
                step(f, Op::BreakTransform, &[13, 48, 7, 45], 1518);
                step(f, Op::ArrayAt(Elem::Float), &[2, 9, 185], 1519);
                step(f, Op::SmoothStepF, &[185, 158, 160, 197], 1520);
                step(f, Op::RemapF, &[18, 158, 94, 158, 160, 9, 220], 1521);
                step(f, Op::MulF, &[197, 220, 187], 1522);
                step(f, Op::Select(ValueType::Float), &[19, 187, 158, 190], 1523);
                step(f, Op::LerpV, &[30, 48, 190, 51], 1524);
                step(f, Op::MakeTransform, &[51, 1, 6, 16], 1525);
                step(f, Op::BreakTransform, &[16, 19, 9, 38], 1526);
                step(f, Op::SubF, &[160, 18, 196], 1527);
                step(f, Op::SubF, &[160, 19, 212], 1528);
                step(f, Op::MulF, &[196, 212, 223], 1529);
                step(f, Op::MulF, &[17, 223, 205], 1530);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 9, 17], 1531);
                step(f, Op::Select(ValueType::Float), &[17, 92, 158, 214], 1532);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 204], 1533);
                step(f, Op::ClampF, &[204, 158, 160, 202], 1534);
                step(f, Op::MulF, &[202, 168, 222], 1535);
                step(f, Op::SinF, &[222, 192], 1536);
                step(f, Op::MulF, &[192, 192, 207], 1537);
                step(f, Op::MulF, &[214, 207, 217], 1538);
                step(f, Op::AddF, &[91, 217, 203], 1539);
                step(f, Op::FootAvoidance, &[40, 19, 205, 19, 203, 34], 1540);
                step(f, Op::SubV, &[34, 40, 44], 1541);
                step(f, Op::LengthV, &[44, 218], 1542);
                step(f, Op::AddF, &[218, 217, 183], 1543);
                step(f, Op::DivF, &[218, 183, 210], 1544);
                step(f, Op::MulF, &[116, 163, 198], 1545);
                step(f, Op::LessEqualF, &[218, 198, 16], 1546);
                step(f, Op::MulF, &[116, 174, 194], 1547);
                step(f, Op::DivF, &[218, 194, 219], 1548);
                step(f, Op::DivF, &[116, 218, 200], 1549);
                step(f, Op::SubF, &[160, 200, 221], 1550);
                step(f, Op::Select(ValueType::Float), &[16, 219, 221, 189], 1551);
                step(f, Op::GreaterF, &[116, 158, 13], 1552);
                step(f, Op::Select(ValueType::Float), &[13, 19, 158, 199], 1553);
                step(f, Op::LerpF, &[210, 189, 199, 195], 1554);
                step(f, Op::LessF, &[185, 204, 14], 1555);
                step(f, Op::LessEqualF, &[93, 158, 12], 1556);
                step(f, Op::SmoothStepF, &[185, 158, 93, 211], 1557);
                step(f, Op::MulF, &[211, 18, 224], 1558);
                step(f, Op::SubF, &[160, 224, 215], 1559);
                step(f, Op::Select(ValueType::Float), &[12, 160, 215, 188], 1560);
                step(f, Op::Select(ValueType::Float), &[14, 188, 160, 186], 1561);
                step(f, Op::MulF, &[195, 186, 191], 1562);
                step(f, Op::SmoothStepF, &[202, 158, 93, 216], 1563);
                step(f, Op::Select(ValueType::Float), &[12, 160, 216, 193], 1564);
                step(f, Op::MulF, &[191, 193, 201], 1565);
                step(f, Op::ScaleV, &[44, 201, 39], 1566);
                step(f, Op::AddV, &[40, 39, 55], 1567);
                step(f, Op::MulF, &[6, 149, 197], 1568);
                step(f, Op::MulF, &[197, 207, 220], 1569);
                step(f, Op::MakeVector, &[158, 158, 220, 37], 1570);
                step(f, Op::AddV, &[55, 37, 57], 1571);
                step(f, Op::MakeTransform, &[57, 11, 6, 15], 1572);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 15], 1573);
                step(f, Op::ScaleV, &[44, 191, 21], 1574);
                step(f, Op::AddV, &[40, 21, 20], 1575);
                step(f, Op::AddV, &[20, 37, 53], 1576);
                step(f, Op::MakeTransform, &[53, 11, 6, 17], 1577);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 17], 1578);
                1578
            }
            1578 => {
                step(f, Op::JumpIfFalse, &[18, 1601], 1579)
            }
            1579 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 7, 18], 1580);
                step(f, Op::BreakTransform, &[18, 32, 2, 33], 1581);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 7, 19], 1582);
                step(f, Op::BreakTransform, &[19, 43, 10, 36], 1583);
                step(f, Op::MulF, &[27, 27, 187], 1584);
                step(f, Op::LerpV, &[32, 43, 187, 42], 1585);
                step(f, Op::SubF, &[160, 27, 190], 1586);
                step(f, Op::MulF, &[27, 190, 222], 1587);
                step(f, Op::MulF, &[151, 163, 192], 1588);
                step(f, Op::MulF, &[222, 192, 214], 1589);
                step(f, Op::MakeVector, &[158, 158, 214, 31], 1590);
                step(f, Op::AddV, &[42, 31, 35], 1591);
                step(f, Op::SlerpQ, &[2, 10, 27, 8], 1592);
                step(f, Op::MakeTransform, &[35, 8, 6, 7], 1593);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 7], 1594);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 7, 18], 1595);
                step(f, Op::BreakTransform, &[18, 32, 2, 33], 1596);
                step(f, Op::LerpV, &[32, 43, 187, 42], 1597);
                step(f, Op::AddV, &[42, 31, 35], 1598);
                step(f, Op::SlerpQ, &[2, 10, 27, 8], 1599);
                step(f, Op::MakeTransform, &[35, 8, 6, 7], 1600);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 7], 1601);
                1601
            }
            1601 => {
                step(f, Op::GreaterEqualF, &[204, 160, 20], 1602);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 7, 20], 1603);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 6], 1604);
                step(f, Op::BreakTransform, &[6, 56, 6, 49], 1605);
                step(f, Op::SubF, &[160, 204, 208], 1606);
                step(f, Op::MulF, &[13, 10, 184], 1607);
                step(f, Op::MulF, &[208, 184, 213], 1608);
                step(f, Op::ScaleV, &[2, 213, 47], 1609);
                step(f, Op::AddV, &[56, 47, 46], 1610);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1611);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 9], 1612);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 9, 11], 1613);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 9, 4], 1614);
                step(f, Op::BreakTransform, &[4, 54, 3, 22], 1615);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 9, 8], 1616);
                step(f, Op::BreakTransform, &[8, 24, 5, 18], 1617);
                step(f, Op::LessEqualF, &[95, 158, 15], 1618);
                step(f, Op::ArrayAt(Elem::Float), &[2, 9, 185], 1619);
                step(f, Op::SmoothStepF, &[185, 158, 95, 182], 1620);
                step(f, Op::Select(ValueType::Float), &[15, 160, 182, 209], 1621);
                step(f, Op::LerpV, &[54, 24, 209, 25], 1622);
                step(f, Op::MakeTransform, &[25, 1, 6, 9], 1623);
                step(f, Op::Select(ValueType::Transform), &[11, 4, 9, 10], 1624);
                step(f, Op::MakeAbsolute, &[10, 5, 11], 1625);
                step(f, Op::Select(ValueType::Transform), &[19, 11, 10, 12], 1626);
                step(f, Op::BreakTransform, &[12, 26, 4, 27], 1627);
                step(f, Op::SubF, &[160, 19, 212], 1628);
                step(f, Op::MulF, &[196, 212, 223], 1629);
                step(f, Op::MulF, &[17, 223, 205], 1630);
                step(f, Op::FootAvoidance, &[46, 26, 205, 19, 91, 23], 1631);
                step(f, Op::RemapF, &[18, 94, 160, 158, 160, 9, 206], 1632);
                step(f, Op::LerpV, &[46, 23, 206, 28], 1633);
                step(f, Op::FootAvoidance, &[28, 26, 20, 19, 117, 29], 1634);
                step(f, Op::LerpV, &[28, 29, 19, 52], 1635);
                step(f, Op::MakeTransform, &[52, 1, 6, 14], 1636);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 7, 14], 1637);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 7, 13], 1638);
                step(f, Op::BreakTransform, &[13, 41, 7, 50], 1639);
                step(f, Op::MakeVector, &[158, 158, 59, 17], 1640);
                step(f, Op::AddV, &[41, 17, 45], 1641);
                step(f, Op::GetTransform, &[0, 2, 9, 16], 1642);
                step(f, Op::BreakTransform, &[16, 30, 9, 48], 1643);
                step(f, Op::MakeTransform, &[45, 9, 6, 15], 1644);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 7, 20], 1645);
                step(f, Op::GetTransform, &[20, 2, 9, 17], 1646);
                step(f, Op::BreakTransform, &[17, 51, 11, 38], 1647);
                step(f, Op::SubV, &[51, 30, 19], 1648);
                step(f, Op::AddV, &[45, 19, 34], 1649);
                step(f, Op::FootPivots, &[45, 34, 61, 60, 59, 62, 39, 55, 57], 1650);
                step(f, Op::GetParent, &[0, 18], 1651);
                step(f, Op::GetParent, &[18, 19], 1652);
                step(f, Op::GetTransform, &[19, 2, 10, 19], 1653);
                step(f, Op::BreakTransform, &[19, 44, 2, 21], 1654);
                step(f, Op::SubV, &[41, 44, 40], 1655);
                step(f, Op::DotV, &[40, 9, 203], 1656);
                step(f, Op::RemapF, &[203, 97, 96, 98, 158, 9, 217], 1657);
                step(f, Op::LengthV, &[2, 183], 1658);
                step(f, Op::RemapF, &[183, 158, 108, 158, 160, 9, 198], 1659);
                step(f, Op::MulF, &[217, 198, 194], 1660);
                step(f, Op::QuatFromAxisAngle, &[13, 194, 10], 1661);
                step(f, Op::RotateAroundPoint, &[15, 39, 10, 18], 1662);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 218], 1663);
                step(f, Op::SmoothStepF, &[218, 158, 102, 200], 1664);
                step(f, Op::SubF, &[160, 218, 219], 1665);
                step(f, Op::SmoothStepF, &[219, 158, 102, 221], 1666);
                step(f, Op::MulF, &[200, 221, 189], 1667);
                step(f, Op::LerpF, &[101, 160, 189, 199], 1668);
                step(f, Op::MulF, &[194, 199, 210], 1669);
                step(f, Op::QuatFromAxisAngle, &[13, 210, 8], 1670);
                step(f, Op::SubV, &[55, 39, 20], 1671);
                step(f, Op::RotateVector, &[8, 20, 37], 1672);
                step(f, Op::AddV, &[39, 37, 53], 1673);
                step(f, Op::RemapF, &[203, 99, 97, 100, 158, 9, 211], 1674);
                step(f, Op::MulF, &[211, 198, 224], 1675);
                step(f, Op::QuatFromAxisAngle, &[13, 224, 6], 1676);
                step(f, Op::RotateAroundPoint, &[18, 53, 6, 7], 1677);
                step(f, Op::RemapF, &[203, 103, 104, 158, 105, 9, 215], 1678);
                step(f, Op::RotateVector, &[7, 10, 36], 1679);
                step(f, Op::BreakVector, &[36, 188, 186, 195], 1680);
                step(f, Op::CosF, &[107, 202], 1681);
                step(f, Op::CosF, &[106, 216], 1682);
                step(f, Op::RemapF, &[195, 202, 216, 158, 160, 9, 193], 1683);
                step(f, Op::MulF, &[198, 193, 201], 1684);
                step(f, Op::MulF, &[215, 201, 197], 1685);
                step(f, Op::QuatFromAxisAngle, &[13, 197, 3], 1686);
                step(f, Op::RotateAroundPoint, &[7, 57, 3, 6], 1687);
                step(f, Op::SubF, &[160, 18, 207], 1688);
                step(f, Op::MulF, &[17, 207, 220], 1689);
                step(f, Op::LimitRotationAroundZ, &[7, 220, 109, 5], 1690);
                step(f, Op::RotateAroundPoint, &[6, 41, 5, 8], 1691);
                step(f, Op::BreakTransform, &[8, 33, 4, 32], 1692);
                step(f, Op::ArrayAt(Elem::Float), &[4, 7, 191], 1693);
                step(f, Op::MulF, &[191, 110, 190], 1694);
                step(f, Op::MulF, &[190, 111, 192], 1695);
                step(f, Op::AddF, &[190, 111, 222], 1696);
                step(f, Op::DivF, &[192, 222, 214], 1697);
                step(f, Op::MakeVector, &[158, 158, 214, 43], 1698);
                step(f, Op::AddV, &[33, 43, 31], 1699);
                step(f, Op::MakeTransform, &[31, 4, 32, 4], 1700);
                step(f, Op::ArraySetAt(Elem::Transform), &[7, 7, 4], 1701);
                step(f, Op::JumpIfFalse, &[8, 1706], 1702)
            }
            1702 => {
                step(f, Op::DrawPoint, &[57, 176, 13], 1703);
                step(f, Op::DrawPoint, &[39, 176, 9], 1704);
                step(f, Op::DrawPoint, &[53, 176, 10], 1705);
                step(f, Op::DrawTransform, &[13, 175, 159], 1706);
                1706
            }
            1706 => {
                step(f, Op::Jump, &[775], 1707)
            }
            1707 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1708);
                step(f, Op::Copy(ValueType::Int), &[2, 8], 1709);
                1709
            }
            1709 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 8, 1, 10, 6, 1748], 1710)
            }
            1710 => {
                step(f, Op::GetParent, &[1, 22], 1711);
                step(f, Op::GetParent, &[22, 23], 1712);
                step(f, Op::GetParent, &[23, 24], 1713);
                step(f, Op::GetTransform, &[24, 2, 10, 9], 1714);
                step(f, Op::BreakTransform, &[9, 42, 9, 35], 1715);
                step(f, Op::LengthV, &[1, 187], 1716);
                step(f, Op::ClavicleOffset, &[15, 187, 123, 127, 204], 1717);
                step(f, Op::MakeVector, &[158, 158, 204, 49], 1718);
                step(f, Op::AddV, &[42, 49, 47], 1719);
                step(f, Op::MakeTransform, &[47, 9, 6, 5], 1720);
                step(f, Op::SetTransform, &[24, 5, 2, 9, 160], 1721);
                step(f, Op::GetTransform, &[1, 2, 10, 10], 1722);
                step(f, Op::GetTransform, &[23, 2, 10, 11], 1723);
                step(f, Op::BreakTransform, &[11, 56, 11, 22], 1724);
                step(f, Op::Equals(Elem::Int), &[10, 2, 17], 1725);
                step(f, Op::Select(ValueType::Int), &[17, 3, 2, 9], 1726);
                step(f, Op::ArrayAt(Elem::Float), &[0, 9, 184], 1727);
                step(f, Op::ArmSwingRotation, &[184, 1, 0, 124, 167, 177, 160, 123, 121, 122, 125, 167, 160, 208], 1728);
                step(f, Op::QuatFromAxisAngle, &[13, 208, 2], 1729);
                step(f, Op::RotateAroundPoint, &[10, 56, 2, 12], 1730);
                step(f, Op::BreakTransform, &[12, 18, 10, 24], 1731);
                step(f, Op::RemapF, &[187, 158, 123, 158, 126, 9, 213], 1732);
                step(f, Op::MakeVector, &[158, 158, 213, 54], 1733);
                step(f, Op::AddV, &[18, 54, 25], 1734);
                step(f, Op::MakeTransform, &[25, 10, 6, 14], 1735);
                step(f, Op::Select(ValueType::Vec3), &[17, 14, 13, 27], 1736);
                step(f, Op::Select(ValueType::Vec3), &[17, 9, 15, 23], 1737);
                step(f, Op::ArrayAt(Elem::Vec3), &[4, 10, 46], 1738);
                step(f, Op::TwoBoneIK, &[23, 22, 1, 14, 27, 23, 46, 2, 160, 10, 178, 179, 9, 16, 185], 1739);
                step(f, Op::JumpIfFalse, &[8, 1747], 1740)
            }
            1740 => {
                step(f, Op::GetTransform, &[23, 2, 10, 11], 1741);
                step(f, Op::BreakTransform, &[11, 56, 11, 22], 1742);
                step(f, Op::GetTransform, &[1, 2, 10, 10], 1743);
                step(f, Op::RotateAroundPoint, &[10, 56, 2, 12], 1744);
                step(f, Op::BreakTransform, &[12, 18, 10, 24], 1745);
                step(f, Op::AddV, &[18, 54, 25], 1746);
                step(f, Op::DrawLine, &[56, 25, 159, 9], 1747);
                1747
            }
            1747 => {
                step(f, Op::Jump, &[1709], 1748)
            }
            1748 => {
                step(f, Op::NegF, &[5, 182], 1749);
                step(f, Op::MakeVector, &[158, 158, 182, 26], 1750);
                step(f, Op::MakeTransform, &[26, 1, 6, 16], 1751);
                step(f, Op::SetTransform, &[36, 16, 2, 9, 160], 1752);
                step(f, Op::Copy(ValueType::Float), &[165, 209], 1753);
                step(f, Op::Copy(ValueType::Bool), &[10, 13], 1754);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 11], 1755);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 1756);
                step(f, Op::MakeVector, &[158, 158, 64, 28], 1757);
                1757
            }
            1757 => {
                step(f, Op::ForEachNext(Elem::Transform), &[11, 7, 17, 6, 8, 1769], 1758)
            }
            1758 => {
                step(f, Op::BreakTransform, &[17, 29, 8, 52], 1759);
                step(f, Op::AddV, &[29, 28, 50], 1760);
                step(f, Op::SubV, &[29, 28, 17], 1761);
                step(f, Op::SphereTrace, &[50, 17, 63, 14, 48, 38, 196], 1762);
                step(f, Op::BreakVector, &[48, 212, 223, 205], 1763);
                step(f, Op::LessF, &[205, 209, 12], 1764);
                step(f, Op::And, &[14, 12, 18], 1765);
                step(f, Op::JumpIfFalse, &[18, 1768], 1766)
            }
            1766 => {
                step(f, Op::Copy(ValueType::Float), &[205, 209], 1767);
                step(f, Op::Copy(ValueType::Bool), &[9, 13], 1768);
                1768
            }
            1768 => {
                step(f, Op::Jump, &[1757], 1769)
            }
            1769 => {
                step(f, Op::Select(ValueType::Float), &[13, 209, 158, 206], 1770);
                step(f, Op::ClampF, &[206, 69, 70, 183], 1771);
                step(f, Op::Copy(ValueType::Float), &[183, 217], 1772);
                step(f, Op::SubF, &[160, 27, 218], 1773);
                step(f, Op::MulF, &[217, 218, 219], 1774);
                step(f, Op::SubF, &[160, 148, 200], 1775);
                step(f, Op::MulF, &[5, 200, 221], 1776);
                step(f, Op::AddF, &[219, 221, 189], 1777);
                step(f, Op::MakeVector, &[22, 158, 158, 30], 1778);
                step(f, Op::MakeVector, &[189, 158, 158, 51], 1779);
                step(f, Op::Select(ValueType::Float), &[2, 189, 23, 194], 1780);
                step(f, Op::MakeVector, &[194, 158, 158, 19], 1781);
                step(f, Op::Copy(ValueType::Float), &[57, 199], 1782);
                step(f, Op::Copy(ValueType::Float), &[58, 210], 1783);
                step(f, Op::SubV, &[51, 19, 34], 1784);
                step(f, Op::DeltaTime, &[211], 1785);
                step(f, Op::DivF, &[210, 211, 224], 1786);
                step(f, Op::ScaleV, &[34, 224, 45], 1787);
                step(f, Op::AddV, &[51, 45, 21], 1788);
                step(f, Op::AddV, &[19, 45, 44], 1789);
                step(f, Op::SubV, &[30, 44, 40], 1790);
                step(f, Op::FloatLerp, &[158, 160, 199, 203], 1791);
                step(f, Op::SubF, &[160, 203, 186], 1792);
                step(f, Op::ScaleV, &[40, 186, 55], 1793);
                step(f, Op::AddV, &[21, 55, 20], 1794);
                step(f, Op::MulF, &[199, 211, 188], 1795);
                step(f, Op::GreaterF, &[188, 158, 20], 1796);
                step(f, Op::DivF, &[203, 188, 195], 1797);
                step(f, Op::Select(ValueType::Float), &[20, 195, 160, 202], 1798);
                step(f, Op::ScaleV, &[34, 202, 37], 1799);
                step(f, Op::SubV, &[20, 37, 36], 1800);
                step(f, Op::Copy(ValueType::Vec3), &[36, 41], 1801);
                step(f, Op::BreakVector, &[41, 216, 193, 198], 1802);
                step(f, Op::Select(ValueType::Float), &[1, 189, 216, 201], 1803);
                step(f, Op::Copy(ValueType::Float), &[201, 22], 1804);
                step(f, Op::Copy(ValueType::Float), &[189, 23], 1805);
                step(f, Op::GetTransform, &[37, 2, 9, 19], 1806);
                step(f, Op::BreakTransform, &[19, 33, 6, 43], 1807);
                step(f, Op::PelvisLean, &[1, 130, 135, 136, 215, 197], 1808);
                step(f, Op::LengthV, &[2, 207], 1809);
                step(f, Op::RemapF, &[207, 158, 130, 158, 128, 9, 220], 1810);
                step(f, Op::MulF, &[18, 129, 191], 1811);
                step(f, Op::SubF, &[160, 191, 190], 1812);
                step(f, Op::MulF, &[220, 190, 192], 1813);
                step(f, Op::MulF, &[15, 180, 222], 1814);
                step(f, Op::SinF, &[222, 214], 1815);
                step(f, Op::MulF, &[192, 214, 204], 1816);
                step(f, Op::MulF, &[204, 218, 184], 1817);
                step(f, Op::AddF, &[184, 22, 208], 1818);
                step(f, Op::SubF, &[208, 5, 187], 1819);
                step(f, Op::MakeVector, &[158, 197, 187, 31], 1820);
                step(f, Op::AddV, &[33, 31, 32], 1821);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 2, 15], 1822);
                step(f, Op::BreakTransform, &[15, 57, 3, 39], 1823);
                step(f, Op::BreakVector, &[57, 213, 185, 182], 1824);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 3, 18], 1825);
                step(f, Op::BreakTransform, &[18, 53, 7, 35], 1826);
                step(f, Op::BreakVector, &[53, 196, 212, 223], 1827);
                step(f, Op::SubF, &[182, 223, 205], 1828);
                step(f, Op::PelvisSideLean, &[205, 137, 138, 209], 1829);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 2, 7], 1830);
                step(f, Op::BreakTransform, &[7, 42, 5, 49], 1831);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 3, 6], 1832);
                step(f, Op::BreakTransform, &[6, 47, 4, 23], 1833);
                step(f, Op::SlerpQ, &[5, 4, 159, 9], 1834);
                step(f, Op::EulerFromQuat, &[9, 2, 27], 1835);
                step(f, Op::BreakVector, &[27, 206, 183, 217], 1836);
                step(f, Op::RemapF, &[207, 131, 130, 158, 132, 9, 200], 1837);
                step(f, Op::SubV, &[57, 53, 46], 1838);
                step(f, Op::RotateVector, &[0, 9, 22], 1839);
                step(f, Op::DotV, &[46, 22, 219], 1840);
                step(f, Op::MulF, &[200, 219, 221], 1841);
                step(f, Op::AddF, &[217, 221, 194], 1842);
                step(f, Op::MakeVector, &[215, 209, 194, 24], 1843);
                step(f, Op::QuatFromEuler, &[24, 2, 11], 1844);
                step(f, Op::MakeTransform, &[32, 11, 6, 8], 1845);
                step(f, Op::SetTransform, &[38, 8, 2, 9, 160], 1846);
                step(f, Op::GetTransform, &[39, 3, 9, 4], 1847);
                step(f, Op::BreakTransform, &[4, 18, 2, 54], 1848);
                step(f, Op::QuatFromAxisAngle, &[10, 221, 10], 1849);
                step(f, Op::DivF, &[133, 176, 210], 1850);
                step(f, Op::QuatScale, &[10, 210, 8], 1851);
                step(f, Op::MulQ, &[2, 8, 6], 1852);
                step(f, Op::MakeTransform, &[18, 6, 6, 13], 1853);
                step(f, Op::SetTransform, &[40, 13, 3, 9, 160], 1854);
                step(f, Op::GetTransform, &[41, 3, 9, 9], 1855);
                step(f, Op::BreakTransform, &[9, 25, 3, 56], 1856);
                step(f, Op::MulQ, &[3, 8, 7], 1857);
                step(f, Op::MakeTransform, &[25, 7, 6, 5], 1858);
                step(f, Op::SetTransform, &[42, 5, 3, 9, 160], 1859);
                step(f, Op::GetTransform, &[43, 3, 9, 14], 1860);
                step(f, Op::BreakTransform, &[14, 26, 4, 52], 1861);
                step(f, Op::MulQ, &[4, 8, 5], 1862);
                step(f, Op::MakeTransform, &[26, 5, 6, 11], 1863);
                step(f, Op::SetTransform, &[44, 11, 3, 9, 160], 1864);
                step(f, Op::GetTransform, &[45, 3, 9, 10], 1865);
                step(f, Op::BreakTransform, &[10, 28, 9, 29], 1866);
                step(f, Op::QuatScale, &[10, 134, 11], 1867);
                step(f, Op::MulQ, &[9, 11, 2], 1868);
                step(f, Op::MakeTransform, &[28, 2, 6, 12], 1869);
                step(f, Op::SetTransform, &[46, 12, 3, 9, 160], 1870);
                step(f, Op::Or, &[1, 2, 15], 1871);
                step(f, Op::Copy(ValueType::Float), &[158, 224], 1872);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1873);
                step(f, Op::Copy(ValueType::Int), &[2, 9], 1874);
                1874
            }
            1874 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 9, 25, 10, 6, 1921], 1875)
            }
            1875 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 10, 11], 1876);
                step(f, Op::GetParent, &[25, 26], 1877);
                step(f, Op::GetParent, &[26, 27], 1878);
                step(f, Op::GetTransform, &[27, 2, 10, 16], 1879);
                step(f, Op::BreakTransform, &[16, 17, 6, 38], 1880);
                step(f, Op::BreakVector, &[17, 186, 199, 211], 1881);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 10, 17], 1882);
                step(f, Op::BreakTransform, &[17, 50, 3, 48], 1883);
                step(f, Op::BreakVector, &[50, 188, 203, 195], 1884);
                step(f, Op::ArrayAt(Elem::Float), &[1, 10, 202], 1885);
                step(f, Op::MulF, &[202, 139, 193], 1886);
                step(f, Op::MulF, &[193, 193, 198], 1887);
                step(f, Op::SubF, &[186, 188, 216], 1888);
                step(f, Op::SubF, &[199, 203, 201], 1889);
                step(f, Op::MakeVector, &[216, 201, 158, 51], 1890);
                step(f, Op::DotV, &[51, 51, 189], 1891);
                step(f, Op::SubF, &[198, 189, 191], 1892);
                step(f, Op::SqrtF, &[191, 190], 1893);
                step(f, Op::AddF, &[195, 190, 220], 1894);
                step(f, Op::SubF, &[211, 220, 222], 1895);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 10, 19], 1896);
                step(f, Op::BreakTransform, &[19, 19, 7, 45], 1897);
                step(f, Op::BreakVector, &[19, 192, 214, 204], 1898);
                step(f, Op::AddF, &[204, 59, 218], 1899);
                step(f, Op::MinF, &[195, 218, 184], 1900);
                step(f, Op::AddF, &[184, 190, 208], 1901);
                step(f, Op::SubF, &[211, 208, 187], 1902);
                step(f, Op::Equals(Elem::Int), &[10, 2, 19], 1903);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 7], 1904);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 7, 17], 1905);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 197], 1906);
                step(f, Op::RemapF, &[197, 159, 160, 158, 160, 9, 185], 1907);
                step(f, Op::RemapF, &[197, 158, 142, 160, 158, 9, 213], 1908);
                step(f, Op::MaxF, &[185, 213, 196], 1909);
                step(f, Op::Select(ValueType::Float), &[17, 160, 196, 212], 1910);
                step(f, Op::LerpF, &[222, 187, 212, 182], 1911);
                step(f, Op::ArrayAt(Elem::Float), &[2, 10, 223], 1912);
                step(f, Op::RemapF, &[223, 159, 160, 158, 160, 9, 205], 1913);
                step(f, Op::MulF, &[182, 205, 183], 1914);
                step(f, Op::RemapF, &[223, 158, 142, 160, 158, 9, 206], 1915);
                step(f, Op::MulF, &[222, 206, 207], 1916);
                step(f, Op::MaxF, &[183, 207, 200], 1917);
                step(f, Op::Select(ValueType::Float), &[11, 222, 200, 219], 1918);
                step(f, Op::MaxF, &[224, 219, 217], 1919);
                step(f, Op::Copy(ValueType::Float), &[217, 224], 1920);
                step(f, Op::Jump, &[1874], 1921)
            }
            1921 => {
                step(f, Op::ClampF, &[224, 158, 140, 194], 1922);
                step(f, Op::Copy(ValueType::Float), &[194, 209], 1923);
                step(f, Op::MakeVector, &[24, 158, 158, 30], 1924);
                step(f, Op::MakeVector, &[209, 158, 158, 44], 1925);
                step(f, Op::MakeVector, &[25, 158, 158, 40], 1926);
                step(f, Op::GreaterF, &[209, 24, 16], 1927);
                step(f, Op::Select(ValueType::Float), &[16, 144, 141, 215], 1928);
                step(f, Op::Copy(ValueType::Float), &[58, 221], 1929);
                step(f, Op::SubV, &[44, 40, 21], 1930);
                step(f, Op::DeltaTime, &[210], 1931);
                step(f, Op::DivF, &[221, 210, 202], 1932);
                step(f, Op::ScaleV, &[21, 202, 55], 1933);
                step(f, Op::AddV, &[44, 55, 34], 1934);
                step(f, Op::AddV, &[40, 55, 20], 1935);
                step(f, Op::SubV, &[30, 20, 37], 1936);
                step(f, Op::FloatLerp, &[158, 160, 215, 193], 1937);
                step(f, Op::SubF, &[160, 193, 186], 1938);
                step(f, Op::ScaleV, &[37, 186, 36], 1939);
                step(f, Op::AddV, &[34, 36, 41], 1940);
                step(f, Op::MulF, &[215, 210, 188], 1941);
                step(f, Op::GreaterF, &[188, 158, 12], 1942);
                step(f, Op::DivF, &[193, 188, 199], 1943);
                step(f, Op::Select(ValueType::Float), &[12, 199, 160, 203], 1944);
                step(f, Op::ScaleV, &[21, 203, 43], 1945);
                step(f, Op::SubV, &[41, 43, 31], 1946);
                step(f, Op::Copy(ValueType::Vec3), &[31, 33], 1947);
                step(f, Op::BreakVector, &[33, 201, 216, 189], 1948);
                step(f, Op::Select(ValueType::Float), &[15, 209, 201, 198], 1949);
                step(f, Op::Copy(ValueType::Float), &[198, 24], 1950);
                step(f, Op::Copy(ValueType::Float), &[209, 25], 1951);
                step(f, Op::GetTransform, &[47, 2, 10, 15], 1952);
                step(f, Op::BreakTransform, &[15, 39, 4, 35], 1953);
                step(f, Op::MakeVector, &[158, 158, 24, 42], 1954);
                step(f, Op::SubV, &[39, 42, 49], 1955);
                step(f, Op::MakeTransform, &[49, 4, 6, 18], 1956);
                step(f, Op::SetTransform, &[48, 18, 2, 9, 160], 1957);
                step(f, Op::JumpIfFalse, &[8, 1963], 1958)
            }
            1958 => {
                step(f, Op::GetTransform, &[47, 2, 10, 15], 1959);
                step(f, Op::BreakTransform, &[15, 39, 4, 35], 1960);
                step(f, Op::SubV, &[39, 42, 49], 1961);
                step(f, Op::MakeTransform, &[49, 4, 6, 18], 1962);
                step(f, Op::DrawTransform, &[18, 181, 159], 1963);
                1963
            }
            1963 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1964);
                step(f, Op::Copy(ValueType::Int), &[2, 8], 1965);
                1965
            }
            1965 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 8, 2, 6, 9, 2014], 1966)
            }
            1966 => {
                step(f, Op::GetParent, &[2, 29], 1967);
                step(f, Op::GetParent, &[29, 30], 1968);
                step(f, Op::GetTransform, &[30, 2, 10, 7], 1969);
                step(f, Op::BreakTransform, &[7, 23, 8, 47], 1970);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 6, 6], 1971);
                step(f, Op::BreakTransform, &[6, 27, 5, 53], 1972);
                step(f, Op::SubV, &[27, 23, 57], 1973);
                step(f, Op::LengthV, &[57, 191], 1974);
                step(f, Op::ArrayAt(Elem::Float), &[1, 6, 220], 1975);
                step(f, Op::MulF, &[220, 152, 192], 1976);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 6, 14], 1977);
                step(f, Op::MulF, &[19, 118, 214], 1978);
                step(f, Op::ArrayAt(Elem::Float), &[2, 6, 204], 1979);
                step(f, Op::ClampF, &[204, 158, 160, 195], 1980);
                step(f, Op::LessF, &[195, 159, 18], 1981);
                step(f, Op::SmoothStepF, &[195, 154, 155, 218], 1982);
                step(f, Op::MulF, &[195, 168, 184], 1983);
                step(f, Op::SinF, &[184, 190], 1984);
                step(f, Op::MaxF, &[218, 190, 208], 1985);
                step(f, Op::Select(ValueType::Float), &[18, 208, 190, 211], 1986);
                step(f, Op::MulF, &[211, 153, 197], 1987);
                step(f, Op::Select(ValueType::Float), &[14, 214, 197, 185], 1988);
                step(f, Op::SubF, &[192, 185, 213], 1989);
                step(f, Op::SubF, &[191, 213, 196], 1990);
                step(f, Op::MaxF, &[196, 158, 187], 1991);
                step(f, Op::MulF, &[187, 187, 212], 1992);
                step(f, Op::AddF, &[187, 185, 182], 1993);
                step(f, Op::DivF, &[212, 182, 205], 1994);
                step(f, Op::SubF, &[191, 205, 223], 1995);
                step(f, Op::DivF, &[223, 191, 206], 1996);
                step(f, Op::ScaleV, &[57, 206, 22], 1997);
                step(f, Op::AddV, &[23, 22, 46], 1998);
                step(f, Op::ClampSpatially, &[46, 23, 158, 192, 24], 1999);
                step(f, Op::MakeTransform, &[24, 5, 6, 8], 2000);
                step(f, Op::Equals(Elem::Int), &[6, 2, 13], 2001);
                step(f, Op::Select(ValueType::Vec3), &[13, 14, 13, 32], 2002);
                step(f, Op::Select(ValueType::Vec3), &[13, 9, 15, 54], 2003);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 6, 4], 2004);
                step(f, Op::BreakTransform, &[4, 18, 10, 56], 2005);
                step(f, Op::ArrayAt(Elem::Vec3), &[3, 6, 25], 2006);
                step(f, Op::KneeVector, &[10, 0, 25, 156, 157, 52], 2007);
                step(f, Op::TwoBoneIK, &[30, 29, 2, 8, 32, 54, 52, 2, 160, 10, 178, 179, 9, 20, 183], 2008);
                step(f, Op::JumpIfFalse, &[8, 2013], 2009)
            }
            2009 => {
                step(f, Op::GetTransform, &[29, 2, 10, 13], 2010);
                step(f, Op::BreakTransform, &[13, 26, 9, 29], 2011);
                step(f, Op::AddV, &[26, 52, 28], 2012);
                step(f, Op::DrawLine, &[26, 28, 159, 16], 2013);
                2013
            }
            2013 => {
                step(f, Op::Jump, &[1965], 2014)
            }
            2014 => {
                step(f, Op::End, &[], 2015)
            }
            _ => return,
        } };
    }
}
