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
    fingerprint: 0xa6754255c839f1b5,
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
                step(f, Op::ForEachNext(Elem::Bone), &[12, 6, 13, 8, 7, 168], 159)
            }
            159 => {
                step(f, Op::ArrayAt(Elem::Transform), &[8, 8, 6], 160);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 8, 6], 161);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 8, 6], 162);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 8, 6], 163);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 8, 6], 164);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 8, 6], 165);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 8, 6], 166);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 8, 6], 167);
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
                step(f, Op::Copy(ValueType::Int), &[2, 7], 182);
                step(f, Op::MakeVector, &[158, 158, 64, 17], 183);
                183
            }
            183 => {
                step(f, Op::ForEachNext(Elem::Transform), &[9, 7, 5, 8, 6, 193], 184)
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
                step(f, Op::Copy(ValueType::Int), &[2, 8], 201);
                201
            }
            201 => {
                step(f, Op::ForNext, &[8, 6, 7, 225], 202)
            }
            202 => {
                step(f, Op::AddF, &[188, 186, 182], 203);
                step(f, Op::MulF, &[182, 159, 183], 204);
                step(f, Op::Copy(ValueType::Bool), &[10, 15], 205);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[8, 10], 206);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 207);
                step(f, Op::MakeVector, &[158, 158, 64, 18], 208);
                208
            }
            208 => {
                step(f, Op::ForEachNext(Elem::Transform), &[10, 7, 6, 9, 10, 218], 209)
            }
            209 => {
                step(f, Op::BreakTransform, &[6, 19, 2, 20], 210);
                step(f, Op::TransformPoint, &[2, 19, 21], 211);
                step(f, Op::LerpV, &[21, 19, 183, 22], 212);
                step(f, Op::AddV, &[22, 18, 17], 213);
                step(f, Op::SubV, &[22, 18, 20], 214);
                step(f, Op::LineTrace, &[17, 20, 16, 19, 21, 185], 215);
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
                step(f, Op::TransformVector, &[2, 3, 22], 255);
                step(f, Op::Select(ValueType::Vec3), &[16, 22, 0, 17], 256);
                step(f, Op::Copy(ValueType::Vec3), &[17, 3], 257);
                step(f, Op::LerpV, &[0, 3, 27, 19], 258);
                step(f, Op::Select(ValueType::Vec3), &[16, 19, 0, 20], 259);
                step(f, Op::Copy(ValueType::Vec3), &[20, 2], 260);
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
                step(f, Op::Select(ValueType::Vec3), &[15, 4, 7, 21], 389);
                step(f, Op::MovementAngleOffset, &[21, 17, 158, 165, 165, 166, 46, 167, 184], 390);
                step(f, Op::Copy(ValueType::Float), &[17, 185], 391);
                step(f, Op::SubF, &[184, 185, 182], 392);
                step(f, Op::AddF, &[182, 168, 186], 393);
                step(f, Op::DivF, &[186, 169, 188], 394);
                step(f, Op::FractF, &[188, 183], 395);
                step(f, Op::MulF, &[183, 169, 187], 396);
                step(f, Op::SubF, &[187, 168, 189], 397);
                step(f, Op::Copy(ValueType::Float), &[189, 196], 398);
                step(f, Op::AbsF, &[196, 195], 399);
                step(f, Op::Select(ValueType::Vec3), &[14, 2, 7, 18], 400);
                step(f, Op::MovementAngleOffset, &[18, 17, 158, 165, 165, 166, 46, 167, 194], 401);
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
                step(f, Op::TransformVector, &[2, 9, 22], 423);
                step(f, Op::BreakVector, &[22, 208, 218, 214], 424);
                step(f, Op::NegF, &[208, 219], 425);
                step(f, Op::Atan2F, &[219, 218, 198], 426);
                step(f, Op::MulF, &[211, 198, 220], 427);
                step(f, Op::QuatFromAxisAngle, &[10, 220, 2], 428);
                step(f, Op::TransformVector, &[2, 4, 17], 429);
                step(f, Op::FloatLerp, &[158, 160, 42, 221], 430);
                step(f, Op::GreaterF, &[221, 158, 16], 431);
                step(f, Op::AddF, &[160, 211, 222], 432);
                step(f, Op::MulF, &[42, 222, 190], 433);
                step(f, Op::FloatLerp, &[158, 160, 190, 224], 434);
                step(f, Op::DivF, &[224, 221, 185], 435);
                step(f, Op::Select(ValueType::Float), &[16, 185, 222, 182], 436);
                step(f, Op::LerpV, &[17, 2, 182, 19], 437);
                step(f, Op::RotateVector, &[2, 19, 20], 438);
                step(f, Op::LengthV, &[20, 186], 439);
                step(f, Op::GreaterF, &[186, 35, 11], 440);
                step(f, Op::Select(ValueType::Vec3), &[11, 20, 7, 21], 441);
                step(f, Op::MovementAngleOffset, &[21, 17, 158, 165, 165, 166, 46, 167, 188], 442);
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
                step(f, Op::SubV, &[2, 17, 22], 464);
                step(f, Op::DotV, &[17, 22, 212], 465);
                step(f, Op::NegF, &[212, 204], 466);
                step(f, Op::DotV, &[22, 22, 209], 467);
                step(f, Op::DivF, &[204, 209, 216], 468);
                step(f, Op::ClampF, &[216, 158, 182, 214], 469);
                step(f, Op::LerpV, &[17, 2, 214, 19], 470);
                step(f, Op::LengthV, &[19, 208], 471);
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
                step(f, Op::MakeVector, &[196, 201, 158, 20], 496);
                step(f, Op::Select(ValueType::Vec3), &[14, 20, 7, 21], 497);
                step(f, Op::MovementAngleOffset, &[21, 17, 158, 44, 45, 166, 168, 167, 200], 498);
                step(f, Op::Copy(ValueType::Float), &[200, 17], 499);
                step(f, Op::Jump, &[557], 500)
            }
            500 => {
                step(f, Op::DivF, &[202, 48, 193], 501);
                step(f, Op::AddF, &[193, 159, 199], 502);
                step(f, Op::FloorF, &[199, 188], 503);
                step(f, Op::MaxF, &[188, 160, 205], 504);
                step(f, Op::ToInt, &[205, 9], 505);
                step(f, Op::Copy(ValueType::Int), &[9, 10], 506);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 507);
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
                step(f, Op::ForNext, &[7, 10, 6, 557], 515)
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
                step(f, Op::LerpV, &[17, 2, 216, 22], 527);
                step(f, Op::RotateVector, &[2, 22, 19], 528);
                step(f, Op::LengthV, &[19, 214], 529);
                step(f, Op::GreaterF, &[214, 35, 12], 530);
                step(f, Op::Select(ValueType::Vec3), &[12, 19, 7, 20], 531);
                step(f, Op::MulF, &[202, 217, 208], 532);
                step(f, Op::MulF, &[11, 208, 219], 533);
                step(f, Op::AddF, &[15, 219, 220], 534);
                step(f, Op::FractF, &[220, 218], 535);
                step(f, Op::MulF, &[218, 163, 190], 536);
                step(f, Op::FractF, &[190, 224], 537);
                step(f, Op::LessF, &[224, 167, 17], 538);
                step(f, Op::MovementAngleOffset, &[20, 17, 158, 165, 165, 166, 46, 167, 185], 539);
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
                step(f, Op::MovementAngleOffset, &[20, 17, 218, 188, 188, 166, 46, 167, 203], 555);
                step(f, Op::Copy(ValueType::Float), &[203, 17], 556);
                step(f, Op::Jump, &[514], 557)
            }
            557 => {
                step(f, Op::QuatFromAxisAngle, &[10, 17, 2], 558);
                step(f, Op::Copy(ValueType::Quat), &[2, 0], 559);
                step(f, Op::SinF, &[17, 206], 560);
                step(f, Op::AbsF, &[206, 191], 561);
                step(f, Op::RemapF, &[191, 49, 50, 158, 160, 9, 210], 562);
                step(f, Op::BreakVector, &[18, 207, 213, 212], 563);
                step(f, Op::AbsF, &[207, 204], 564);
                step(f, Op::DivF, &[204, 223, 209], 565);
                step(f, Op::RemapF, &[209, 49, 50, 158, 160, 9, 182], 566);
                step(f, Op::TransformVector, &[2, 9, 21], 567);
                step(f, Op::DistanceV, &[21, 9, 216], 568);
                step(f, Op::DivF, &[216, 202, 214], 569);
                step(f, Op::RemapF, &[214, 54, 55, 160, 158, 9, 217], 570);
                step(f, Op::MulF, &[182, 217, 208], 571);
                step(f, Op::MaxF, &[210, 208, 219], 572);
                step(f, Op::Copy(ValueType::Float), &[219, 18], 573);
                step(f, Op::Copy(ValueType::Vec3), &[2, 4], 574);
                step(f, Op::Copy(ValueType::Bool), &[9, 13], 575);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 2], 576);
                step(f, Op::Copy(ValueType::Int), &[2, 8], 577);
                577
            }
            577 => {
                step(f, Op::ForEachNext(Elem::Bool), &[2, 8, 14, 9, 6, 582], 578)
            }
            578 => {
                step(f, Op::Not, &[14, 12], 579);
                step(f, Op::JumpIfFalse, &[12, 581], 580)
            }
            580 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 13], 581);
                581
            }
            581 => {
                step(f, Op::Jump, &[577], 582)
            }
            582 => {
                step(f, Op::Copy(ValueType::Bool), &[13, 11], 583);
                step(f, Op::Copy(ValueType::Bool), &[9, 17], 584);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 585);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 586);
                586
            }
            586 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 7, 15, 10, 6, 600], 587)
            }
            587 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 10, 4], 588);
                step(f, Op::BreakTransform, &[4, 22, 2, 19], 589);
                step(f, Op::BreakVector, &[22, 220, 190, 224], 590);
                step(f, Op::MakeVector, &[220, 190, 158, 20], 591);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 10, 7], 592);
                step(f, Op::BreakTransform, &[7, 17, 2, 18], 593);
                step(f, Op::BreakVector, &[17, 185, 211, 222], 594);
                step(f, Op::MakeVector, &[185, 211, 158, 21], 595);
                step(f, Op::DistanceV, &[20, 21, 186], 596);
                step(f, Op::GreaterF, &[186, 37, 15], 597);
                step(f, Op::JumpIfFalse, &[15, 599], 598)
            }
            598 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 17], 599);
                599
            }
            599 => {
                step(f, Op::Jump, &[586], 600)
            }
            600 => {
                step(f, Op::Copy(ValueType::Bool), &[17, 16], 601);
                step(f, Op::And, &[11, 16, 14], 602);
                step(f, Op::LengthV, &[2, 215], 603);
                step(f, Op::GreaterF, &[215, 35, 12], 604);
                step(f, Op::GreaterF, &[0, 35, 13], 605);
                step(f, Op::Or, &[12, 13, 15], 606);
                step(f, Op::Not, &[15, 17], 607);
                step(f, Op::And, &[14, 17, 16], 608);
                step(f, Op::DeltaTime, &[183], 609);
                step(f, Op::MulF, &[183, 40, 194], 610);
                step(f, Op::AddF, &[15, 194, 189], 611);
                step(f, Op::GreaterF, &[15, 159, 13], 612);
                step(f, Op::AddF, &[39, 159, 187], 613);
                step(f, Op::Select(ValueType::Float), &[13, 187, 39, 196], 614);
                step(f, Op::MinF, &[189, 196, 200], 615);
                step(f, Op::NotEquals(Elem::Bool), &[17, 4, 15], 616);
                step(f, Op::Not, &[14, 13], 617);
                step(f, Op::And, &[15, 13, 18], 618);
                step(f, Op::SubF, &[16, 35, 201], 619);
                step(f, Op::SubF, &[16, 215, 193], 620);
                step(f, Op::DivF, &[201, 193, 199], 621);
                step(f, Op::ClampF, &[199, 158, 160, 188], 622);
                step(f, Op::MulF, &[11, 188, 218], 623);
                step(f, Op::RemapF, &[215, 35, 36, 158, 160, 9, 203], 624);
                step(f, Op::MaxF, &[203, 12, 184], 625);
                step(f, Op::Select(ValueType::Float), &[11, 160, 184, 192], 626);
                step(f, Op::Select(ValueType::Float), &[17, 38, 192, 195], 627);
                step(f, Op::Select(ValueType::Float), &[14, 203, 195, 197], 628);
                step(f, Op::SubF, &[160, 27, 198], 629);
                step(f, Op::MulF, &[197, 198, 205], 630);
                step(f, Op::LerpF, &[29, 52, 18, 221], 631);
                step(f, Op::RemapF, &[215, 32, 33, 30, 31, 9, 206], 632);
                step(f, Op::LerpF, &[206, 51, 18, 191], 633);
                step(f, Op::MaxF, &[215, 34, 212], 634);
                step(f, Op::DivF, &[191, 212, 213], 635);
                step(f, Op::AddF, &[221, 213, 207], 636);
                step(f, Op::DivF, &[205, 207, 204], 637);
                step(f, Op::SubF, &[160, 188, 223], 638);
                step(f, Op::MulF, &[204, 223, 209], 639);
                step(f, Op::AddF, &[218, 209, 202], 640);
                step(f, Op::MulF, &[202, 163, 216], 641);
                step(f, Op::AddF, &[11, 204, 214], 642);
                step(f, Op::Select(ValueType::Float), &[18, 216, 214, 182], 643);
                step(f, Op::DivF, &[163, 182, 217], 644);
                step(f, Op::GreaterF, &[182, 158, 13], 645);
                step(f, Op::CycleStep, &[15, 217, 158, 13, 208, 210], 646);
                step(f, Op::Select(ValueType::Float), &[16, 200, 208, 219], 647);
                step(f, Op::Copy(ValueType::Float), &[219, 15], 648);
                step(f, Op::Copy(ValueType::Float), &[204, 11], 649);
                step(f, Op::Copy(ValueType::Bool), &[12, 3], 650);
                step(f, Op::Copy(ValueType::Float), &[213, 9], 651);
                step(f, Op::Copy(ValueType::Float), &[207, 10], 652);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 653);
                step(f, Op::Copy(ValueType::Int), &[2, 9], 654);
                step(f, Op::DivF, &[221, 207, 224], 655);
                step(f, Op::MulF, &[14, 188, 190], 656);
                step(f, Op::MulF, &[183, 159, 220], 657);
                step(f, Op::SubF, &[224, 13, 222], 658);
                step(f, Op::MaxF, &[222, 158, 185], 659);
                step(f, Op::DivF, &[185, 224, 211], 660);
                step(f, Op::SubF, &[160, 18, 186], 661);
                step(f, Op::DivF, &[58, 183, 194], 662);
                step(f, Op::SubF, &[159, 194, 187], 663);
                step(f, Op::MulF, &[211, 186, 189], 664);
                step(f, Op::MulF, &[189, 198, 196], 665);
                step(f, Op::MulF, &[196, 143, 193], 666);
                step(f, Op::MulF, &[193, 187, 201], 667);
                step(f, Op::SubF, &[160, 201, 199], 668);
                668
            }
            668 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 9, 14, 8, 6, 712], 669)
            }
            669 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 8, 206], 670);
                step(f, Op::ToFloat, &[8, 191], 671);
                step(f, Op::MulF, &[191, 159, 212], 672);
                step(f, Op::AddF, &[15, 212, 209], 673);
                step(f, Op::FractF, &[209, 218], 674);
                step(f, Op::SubF, &[206, 218, 202], 675);
                step(f, Op::GreaterF, &[202, 159, 15], 676);
                step(f, Op::ArrayAt(Elem::Float), &[2, 8, 214], 677);
                step(f, Op::Select(ValueType::Float), &[15, 158, 214, 216], 678);
                step(f, Op::ArraySetAt(Elem::Float), &[3, 8, 216], 679);
                step(f, Op::SubF, &[160, 206, 182], 680);
                step(f, Op::AddF, &[218, 182, 210], 681);
                step(f, Op::DivF, &[218, 210, 217], 682);
                step(f, Op::MaxF, &[203, 12, 184], 683);
                step(f, Op::Select(ValueType::Float), &[11, 160, 184, 192], 684);
                step(f, Op::Select(ValueType::Float), &[17, 38, 192, 195], 685);
                step(f, Op::Select(ValueType::Float), &[14, 203, 195, 197], 686);
                step(f, Op::MulF, &[197, 198, 205], 687);
                step(f, Op::DivF, &[205, 221, 200], 688);
                step(f, Op::MulF, &[200, 223, 208], 689);
                step(f, Op::AddF, &[190, 208, 219], 690);
                step(f, Op::MulF, &[219, 163, 204], 691);
                step(f, Op::AddF, &[14, 200, 213], 692);
                step(f, Op::Select(ValueType::Float), &[18, 204, 213, 207], 693);
                step(f, Op::MulF, &[207, 220, 188], 694);
                step(f, Op::MulF, &[217, 188, 222], 695);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 8, 13], 696);
                step(f, Op::MulF, &[188, 199, 185], 697);
                step(f, Op::Select(ValueType::Float), &[13, 188, 185, 183], 698);
                step(f, Op::MulF, &[211, 214, 194], 699);
                step(f, Op::MulF, &[194, 186, 189], 700);
                step(f, Op::MulF, &[189, 198, 196], 701);
                step(f, Op::MulF, &[196, 143, 187], 702);
                step(f, Op::Select(ValueType::Float), &[13, 158, 187, 193], 703);
                step(f, Op::SubF, &[183, 193, 201], 704);
                step(f, Op::AddF, &[214, 201, 191], 705);
                step(f, Op::Select(ValueType::Float), &[15, 222, 191, 212], 706);
                step(f, Op::MinF, &[212, 163, 209], 707);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 8, 209], 708);
                step(f, Op::JumpIfFalse, &[15, 710], 709)
            }
            709 => {
                step(f, Op::Copy(ValueType::Float), &[197, 12], 710);
                710
            }
            710 => {
                step(f, Op::ArraySetAt(Elem::Float), &[0, 8, 218], 711);
                step(f, Op::Jump, &[668], 712)
            }
            712 => {
                step(f, Op::Copy(ValueType::Float), &[224, 13], 713);
                step(f, Op::Copy(ValueType::Bool), &[17, 4], 714);
                step(f, Op::Copy(ValueType::Float), &[215, 16], 715);
                step(f, Op::MaxF, &[203, 12, 184], 716);
                step(f, Op::Select(ValueType::Float), &[11, 160, 184, 192], 717);
                step(f, Op::Select(ValueType::Float), &[17, 38, 192, 195], 718);
                step(f, Op::Select(ValueType::Float), &[14, 203, 195, 197], 719);
                step(f, Op::MulF, &[197, 198, 205], 720);
                step(f, Op::DivF, &[205, 221, 200], 721);
                step(f, Op::Copy(ValueType::Float), &[200, 14], 722);
                step(f, Op::TransformVector, &[2, 5, 19], 723);
                step(f, Op::BreakTransform, &[2, 22, 2, 18], 724);
                step(f, Op::DeltaTime, &[202], 725);
                step(f, Op::DivF, &[160, 202, 216], 726);
                step(f, Op::ScaleV, &[22, 216, 17], 727);
                step(f, Op::NegV, &[17, 20], 728);
                step(f, Op::SubV, &[20, 19, 21], 729);
                step(f, Op::AddF, &[21, 202, 206], 730);
                step(f, Op::DivF, &[21, 206, 182], 731);
                step(f, Op::ScaleV, &[21, 182, 18], 732);
                step(f, Op::AddV, &[19, 18, 17], 733);
                step(f, Op::DivF, &[202, 206, 210], 734);
                step(f, Op::ScaleV, &[21, 210, 18], 735);
                step(f, Op::AddV, &[20, 18, 19], 736);
                step(f, Op::DotV, &[17, 19, 208], 737);
                step(f, Op::LessF, &[208, 158, 16], 738);
                step(f, Op::TransformVector, &[2, 9, 21], 739);
                step(f, Op::DistanceV, &[21, 9, 219], 740);
                step(f, Op::SubV, &[19, 17, 18], 741);
                step(f, Op::DotV, &[17, 18, 204], 742);
                step(f, Op::NegF, &[204, 213], 743);
                step(f, Op::DotV, &[18, 18, 207], 744);
                step(f, Op::DivF, &[213, 207, 217], 745);
                step(f, Op::ClampF, &[217, 158, 160, 185], 746);
                step(f, Op::SubF, &[160, 185, 188], 747);
                step(f, Op::MulF, &[202, 188, 194], 748);
                step(f, Op::DivF, &[219, 194, 189], 749);
                step(f, Op::RemapF, &[189, 54, 55, 158, 160, 9, 196], 750);
                step(f, Op::BreakVector, &[19, 187, 183, 193], 751);
                step(f, Op::NegF, &[187, 201], 752);
                step(f, Op::Atan2F, &[201, 183, 214], 753);
                step(f, Op::AbsF, &[214, 191], 754);
                step(f, Op::RemapF, &[191, 113, 114, 158, 160, 9, 222], 755);
                step(f, Op::MulF, &[196, 222, 212], 756);
                step(f, Op::DivF, &[219, 202, 209], 757);
                step(f, Op::RemapF, &[209, 54, 55, 158, 160, 9, 218], 758);
                step(f, Op::BreakVector, &[22, 186, 190, 199], 759);
                step(f, Op::NegF, &[190, 211], 760);
                step(f, Op::Atan2F, &[186, 211, 220], 761);
                step(f, Op::AbsF, &[220, 223], 762);
                step(f, Op::RemapF, &[223, 113, 114, 158, 160, 9, 224], 763);
                step(f, Op::MulF, &[218, 224, 215], 764);
                step(f, Op::Select(ValueType::Float), &[16, 212, 215, 184], 765);
                step(f, Op::FloatLerp, &[19, 158, 115, 192], 766);
                step(f, Op::MaxF, &[184, 192, 195], 767);
                step(f, Op::MaxF, &[195, 158, 203], 768);
                step(f, Op::Copy(ValueType::Float), &[203, 19], 769);
                step(f, Op::Select(ValueType::Float), &[16, 214, 220, 197], 770);
                step(f, Op::Copy(ValueType::Float), &[197, 20], 771);
                step(f, Op::Copy(ValueType::Vec3), &[20, 5], 772);
                step(f, Op::Copy(ValueType::Float), &[202, 21], 773);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 774);
                step(f, Op::Copy(ValueType::Int), &[2, 10], 775);
                775
            }
            775 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 10, 0, 7, 6, 1707], 776)
            }
            776 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 12], 777);
                step(f, Op::Copy(ValueType::Bool), &[10, 13], 778);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 7, 15], 779);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 198], 780);
                step(f, Op::GreaterEqualF, &[198, 160, 18], 781);
                step(f, Op::And, &[15, 18, 11], 782);
                step(f, Op::Or, &[1, 2, 17], 783);
                step(f, Op::GreaterF, &[27, 158, 14], 784);
                step(f, Op::Or, &[17, 14, 16], 785);
                step(f, Op::Not, &[16, 15], 786);
                step(f, Op::And, &[11, 15, 14], 787);
                step(f, Op::JumpIfFalse, &[14, 897], 788)
            }
            788 => {
                step(f, Op::ArrayAt(Elem::Transform), &[2, 7, 5], 789);
                step(f, Op::BreakTransform, &[5, 21, 2, 17], 790);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 7, 18], 791);
                step(f, Op::SubV, &[21, 18, 19], 792);
                step(f, Op::TransformPoint, &[2, 19, 22], 793);
                step(f, Op::GetTransform, &[34, 2, 9, 6], 794);
                step(f, Op::BreakTransform, &[6, 20, 3, 19], 795);
                step(f, Op::BreakVector, &[20, 205, 221, 200], 796);
                step(f, Op::SubF, &[160, 18, 216], 797);
                step(f, Op::MulF, &[17, 216, 182], 798);
                step(f, Op::QuatFromAxisAngle, &[10, 182, 4], 799);
                step(f, Op::GetTransform, &[0, 2, 9, 4], 800);
                step(f, Op::BreakTransform, &[4, 23, 5, 24], 801);
                step(f, Op::SubV, &[23, 20, 25], 802);
                step(f, Op::BreakVector, &[25, 206, 210, 208], 803);
                step(f, Op::MakeVector, &[206, 210, 158, 26], 804);
                step(f, Op::RotateVector, &[4, 26, 27], 805);
                step(f, Op::BreakVector, &[27, 204, 207, 213], 806);
                step(f, Op::MulF, &[53, 18, 217], 807);
                step(f, Op::Equals(Elem::Int), &[7, 2, 17], 808);
                step(f, Op::Select(ValueType::Float), &[17, 160, 162, 185], 809);
                step(f, Op::MulF, &[217, 185, 188], 810);
                step(f, Op::AddF, &[204, 188, 194], 811);
                step(f, Op::AddF, &[205, 194, 189], 812);
                step(f, Op::AddF, &[221, 207, 193], 813);
                step(f, Op::BreakVector, &[23, 187, 183, 201], 814);
                step(f, Op::SubF, &[201, 59, 191], 815);
                step(f, Op::MakeVector, &[189, 193, 191, 28], 816);
                step(f, Op::MulF, &[9, 159, 196], 817);
                step(f, Op::ScaleV, &[2, 196, 29], 818);
                step(f, Op::AddV, &[28, 29, 30], 819);
                step(f, Op::DistanceV, &[22, 30, 222], 820);
                step(f, Op::TransformVector, &[2, 11, 22], 821);
                step(f, Op::DistanceV, &[22, 11, 219], 822);
                step(f, Op::MaxF, &[222, 219, 209], 823);
                step(f, Op::LessEqualF, &[209, 66, 16], 824);
                step(f, Op::LengthV, &[2, 199], 825);
                step(f, Op::LengthV, &[4, 190], 826);
                step(f, Op::MaxF, &[199, 190, 186], 827);
                step(f, Op::LessEqualF, &[186, 35, 11], 828);
                step(f, Op::And, &[16, 11, 15], 829);
                step(f, Op::ArrayAt(Elem::Bool), &[1, 7, 14], 830);
                step(f, Op::And, &[15, 14, 11], 831);
                step(f, Op::JumpIfFalse, &[11, 834], 832)
            }
            832 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 13], 833);
                step(f, Op::Jump, &[863], 834)
            }
            834 => {
                step(f, Op::MakeVector, &[158, 158, 64, 22], 835);
                step(f, Op::AddV, &[30, 22, 31], 836);
                step(f, Op::SubV, &[30, 22, 32], 837);
                step(f, Op::SphereTrace, &[31, 32, 63, 16, 33, 34, 211], 838);
                step(f, Op::SubV, &[33, 30, 34], 839);
                step(f, Op::DistanceV, &[34, 18, 223], 840);
                step(f, Op::RotateVector, &[0, 9, 33], 841);
                step(f, Op::ScaleV, &[33, 68, 34], 842);
                step(f, Op::AddV, &[31, 34, 35], 843);
                step(f, Op::AddV, &[32, 34, 36], 844);
                step(f, Op::SphereTrace, &[35, 36, 63, 15, 37, 38, 218], 845);
                step(f, Op::SubV, &[37, 30, 39], 846);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 7, 40], 847);
                step(f, Op::DistanceV, &[39, 40, 224], 848);
                step(f, Op::MaxF, &[223, 224, 212], 849);
                step(f, Op::ScaleV, &[33, 65, 40], 850);
                step(f, Op::AddV, &[35, 40, 41], 851);
                step(f, Op::AddV, &[36, 40, 42], 852);
                step(f, Op::SphereTrace, &[41, 42, 63, 11, 43, 44, 215], 853);
                step(f, Op::SubV, &[43, 30, 45], 854);
                step(f, Op::ArrayAt(Elem::Vec3), &[2, 7, 46], 855);
                step(f, Op::DistanceV, &[45, 46, 184], 856);
                step(f, Op::MaxF, &[212, 184, 192], 857);
                step(f, Op::LessEqualF, &[192, 66, 19], 858);
                step(f, Op::And, &[16, 15, 20], 859);
                step(f, Op::And, &[20, 14, 16], 860);
                step(f, Op::And, &[19, 16, 20], 861);
                step(f, Op::JumpIfFalse, &[20, 863], 862)
            }
            862 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 13], 863);
                863
            }
            863 => {
                step(f, Op::JumpIfFalse, &[13, 897], 864)
            }
            864 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 7], 865);
                step(f, Op::BreakTransform, &[7, 46, 6, 47], 866);
                step(f, Op::AddV, &[30, 18, 48], 867);
                step(f, Op::Copy(ValueType::Float), &[56, 195], 868);
                step(f, Op::Copy(ValueType::Float), &[58, 203], 869);
                step(f, Op::SubV, &[48, 21, 18], 870);
                step(f, Op::DeltaTime, &[214], 871);
                step(f, Op::DivF, &[203, 214, 220], 872);
                step(f, Op::ScaleV, &[18, 220, 49], 873);
                step(f, Op::AddV, &[48, 49, 50], 874);
                step(f, Op::AddV, &[21, 49, 51], 875);
                step(f, Op::SubV, &[46, 51, 49], 876);
                step(f, Op::FloatLerp, &[158, 160, 195, 197], 877);
                step(f, Op::SubF, &[160, 197, 202], 878);
                step(f, Op::ScaleV, &[49, 202, 51], 879);
                step(f, Op::AddV, &[50, 51, 49], 880);
                step(f, Op::MulF, &[195, 214, 219], 881);
                step(f, Op::GreaterF, &[219, 158, 16], 882);
                step(f, Op::DivF, &[197, 219, 222], 883);
                step(f, Op::Select(ValueType::Float), &[16, 222, 160, 209], 884);
                step(f, Op::ScaleV, &[18, 209, 50], 885);
                step(f, Op::SubV, &[49, 50, 51], 886);
                step(f, Op::Copy(ValueType::Vec3), &[51, 18], 887);
                step(f, Op::BreakVector, &[18, 190, 199, 186], 888);
                step(f, Op::ClampF, &[186, 69, 70, 211], 889);
                step(f, Op::MakeVector, &[190, 199, 211, 49], 890);
                step(f, Op::MakeTransform, &[49, 6, 6, 8], 891);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 7, 8], 892);
                step(f, Op::MakeTransform, &[48, 1, 6, 8], 893);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 7, 8], 894);
                step(f, Op::JumpIfFalse, &[14, 896], 895)
            }
            895 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 7], 896);
                896
            }
            896 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 12], 897);
                897
            }
            897 => {
                step(f, Op::JumpIfFalse, &[12, 1102], 898)
            }
            898 => {
                step(f, Op::GetTransform, &[34, 2, 9, 6], 899);
                step(f, Op::BreakTransform, &[6, 20, 3, 19], 900);
                step(f, Op::BreakVector, &[20, 205, 221, 200], 901);
                step(f, Op::SubF, &[160, 18, 216], 902);
                step(f, Op::MulF, &[17, 216, 182], 903);
                step(f, Op::QuatFromAxisAngle, &[10, 182, 4], 904);
                step(f, Op::GetTransform, &[0, 2, 9, 4], 905);
                step(f, Op::BreakTransform, &[4, 23, 5, 24], 906);
                step(f, Op::SubV, &[23, 20, 25], 907);
                step(f, Op::BreakVector, &[25, 206, 210, 208], 908);
                step(f, Op::MakeVector, &[206, 210, 158, 26], 909);
                step(f, Op::RotateVector, &[4, 26, 27], 910);
                step(f, Op::BreakVector, &[27, 204, 207, 213], 911);
                step(f, Op::MulF, &[53, 18, 217], 912);
                step(f, Op::Equals(Elem::Int), &[7, 2, 17], 913);
                step(f, Op::Select(ValueType::Float), &[17, 160, 162, 185], 914);
                step(f, Op::MulF, &[217, 185, 188], 915);
                step(f, Op::AddF, &[204, 188, 194], 916);
                step(f, Op::AddF, &[205, 194, 189], 917);
                step(f, Op::AddF, &[221, 207, 193], 918);
                step(f, Op::BreakVector, &[23, 187, 183, 201], 919);
                step(f, Op::SubF, &[201, 59, 191], 920);
                step(f, Op::MakeVector, &[189, 193, 191, 28], 921);
                step(f, Op::SubF, &[160, 198, 223], 922);
                step(f, Op::MaxF, &[223, 158, 224], 923);
                step(f, Op::MulF, &[13, 10, 184], 924);
                step(f, Op::MulF, &[224, 184, 212], 925);
                step(f, Op::ScaleV, &[2, 212, 50], 926);
                step(f, Op::AddV, &[28, 50, 51], 927);
                step(f, Op::MulF, &[9, 159, 196], 928);
                step(f, Op::ScaleV, &[2, 196, 29], 929);
                step(f, Op::AddV, &[51, 29, 18], 930);
                step(f, Op::RotateVector, &[0, 9, 33], 931);
                step(f, Op::Copy(ValueType::Float), &[165, 192], 932);
                step(f, Op::Copy(ValueType::Vec3), &[7, 49], 933);
                step(f, Op::Copy(ValueType::Vec3), &[10, 48], 934);
                step(f, Op::Copy(ValueType::Bool), &[10, 19], 935);
                step(f, Op::Copy(ValueType::Float), &[165, 203], 936);
                step(f, Op::Copy(ValueType::Vec3), &[7, 51], 937);
                step(f, Op::MulI, &[0, 0, 8], 938);
                step(f, Op::Copy(ValueType::Int), &[8, 9], 939);
                step(f, Op::Copy(ValueType::Int), &[2, 6], 940);
                step(f, Op::SubI, &[0, 3, 8], 941);
                step(f, Op::DivI, &[8, 4, 11], 942);
                step(f, Op::MakeVector, &[158, 158, 64, 52], 943);
                step(f, Op::ScaleV, &[33, 68, 53], 944);
                944
            }
            944 => {
                step(f, Op::ForNext, &[6, 9, 8, 991], 945)
            }
            945 => {
                step(f, Op::ModI, &[8, 0, 12], 946);
                step(f, Op::ToFloat, &[12, 220], 947);
                step(f, Op::MulF, &[220, 65, 202], 948);
                step(f, Op::MulF, &[202, 185, 195], 949);
                step(f, Op::MakeVector, &[195, 158, 158, 54], 950);
                step(f, Op::DivI, &[8, 0, 12], 951);
                step(f, Op::SubI, &[12, 11, 8], 952);
                step(f, Op::ToFloat, &[8, 214], 953);
                step(f, Op::MulF, &[214, 65, 197], 954);
                step(f, Op::ScaleV, &[33, 197, 55], 955);
                step(f, Op::AddV, &[54, 55, 56], 956);
                step(f, Op::AddV, &[18, 56, 54], 957);
                step(f, Op::AddV, &[54, 52, 55], 958);
                step(f, Op::SubV, &[54, 52, 57], 959);
                step(f, Op::SphereTrace, &[55, 57, 63, 20, 54, 58, 219], 960);
                step(f, Op::BreakVector, &[54, 222, 209, 186], 961);
                step(f, Op::AddV, &[55, 53, 59], 962);
                step(f, Op::AddV, &[57, 53, 55], 963);
                step(f, Op::SphereTrace, &[59, 55, 63, 13, 57, 60, 190], 964);
                step(f, Op::BreakVector, &[57, 199, 211, 220], 965);
                step(f, Op::SubF, &[186, 220, 202], 966);
                step(f, Op::AbsF, &[202, 195], 967);
                step(f, Op::Select(ValueType::Float), &[20, 158, 160, 214], 968);
                step(f, Op::AddF, &[195, 214, 197], 969);
                step(f, Op::LengthV, &[56, 219], 970);
                step(f, Op::RemapF, &[219, 158, 171, 158, 160, 9, 209], 971);
                step(f, Op::MinF, &[186, 220, 222], 972);
                step(f, Op::RemapF, &[222, 172, 171, 160, 159, 9, 190], 973);
                step(f, Op::AddF, &[209, 190, 199], 974);
                step(f, Op::AddF, &[197, 199, 211], 975);
                step(f, Op::LessF, &[211, 192, 16], 976);
                step(f, Op::And, &[20, 16, 14], 977);
                step(f, Op::JumpIfFalse, &[14, 985], 978)
            }
            978 => {
                step(f, Op::Copy(ValueType::Float), &[192, 203], 979);
                step(f, Op::Copy(ValueType::Vec3), &[49, 51], 980);
                step(f, Op::Copy(ValueType::Float), &[211, 192], 981);
                step(f, Op::Copy(ValueType::Vec3), &[54, 49], 982);
                step(f, Op::Copy(ValueType::Vec3), &[58, 48], 983);
                step(f, Op::Copy(ValueType::Bool), &[9, 19], 984);
                step(f, Op::Jump, &[990], 985)
            }
            985 => {
                step(f, Op::LessF, &[211, 203, 12], 986);
                step(f, Op::And, &[20, 12, 17], 987);
                step(f, Op::JumpIfFalse, &[17, 990], 988)
            }
            988 => {
                step(f, Op::Copy(ValueType::Float), &[211, 203], 989);
                step(f, Op::Copy(ValueType::Vec3), &[54, 51], 990);
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
                step(f, Op::GreaterF, &[67, 158, 13], 994);
                step(f, Op::SubF, &[192, 203, 202], 995);
                step(f, Op::DivF, &[202, 67, 195], 996);
                step(f, Op::PowF, &[173, 195, 214], 997);
                step(f, Op::Select(ValueType::Float), &[13, 214, 158, 219], 998);
                step(f, Op::ScaleV, &[51, 219, 55], 999);
                step(f, Op::AddV, &[49, 55, 59], 1000);
                step(f, Op::AddF, &[219, 160, 186], 1001);
                step(f, Op::DivF, &[160, 186, 220], 1002);
                step(f, Op::ScaleV, &[59, 220, 60], 1003);
                step(f, Op::Copy(ValueType::Vec3), &[60, 57], 1004);
                step(f, Op::Copy(ValueType::Vec3), &[48, 56], 1005);
                step(f, Op::Copy(ValueType::Bool), &[19, 16], 1006);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 7], 1007);
                step(f, Op::BreakTransform, &[7, 46, 6, 47], 1008);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 198], 1009);
                step(f, Op::SubF, &[160, 198, 223], 1010);
                step(f, Op::MaxF, &[223, 158, 224], 1011);
                step(f, Op::MulF, &[13, 10, 184], 1012);
                step(f, Op::MulF, &[224, 184, 212], 1013);
                step(f, Op::ScaleV, &[2, 212, 50], 1014);
                step(f, Op::SubV, &[57, 50, 58], 1015);
                step(f, Op::Select(ValueType::Vec3), &[16, 58, 46, 54], 1016);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 7, 5], 1017);
                step(f, Op::BreakTransform, &[5, 21, 2, 17], 1018);
                step(f, Op::Copy(ValueType::Float), &[56, 222], 1019);
                step(f, Op::Copy(ValueType::Float), &[58, 190], 1020);
                step(f, Op::SubV, &[54, 21, 18], 1021);
                step(f, Op::DeltaTime, &[209], 1022);
                step(f, Op::DivF, &[190, 209, 197], 1023);
                step(f, Op::ScaleV, &[18, 197, 52], 1024);
                step(f, Op::AddV, &[54, 52, 53], 1025);
                step(f, Op::AddV, &[21, 52, 51], 1026);
                step(f, Op::SubV, &[46, 51, 49], 1027);
                step(f, Op::FloatLerp, &[158, 160, 222, 199], 1028);
                step(f, Op::SubF, &[160, 199, 211], 1029);
                step(f, Op::ScaleV, &[49, 211, 55], 1030);
                step(f, Op::AddV, &[53, 55, 59], 1031);
                step(f, Op::MulF, &[222, 209, 192], 1032);
                step(f, Op::GreaterF, &[192, 158, 14], 1033);
                step(f, Op::DivF, &[199, 192, 203], 1034);
                step(f, Op::Select(ValueType::Float), &[14, 203, 160, 202], 1035);
                step(f, Op::ScaleV, &[18, 202, 60], 1036);
                step(f, Op::SubV, &[59, 60, 48], 1037);
                step(f, Op::Copy(ValueType::Vec3), &[48, 50], 1038);
                step(f, Op::BreakVector, &[50, 195, 214, 219], 1039);
                step(f, Op::ClampF, &[219, 69, 70, 186], 1040);
                step(f, Op::MakeVector, &[195, 214, 186, 57], 1041);
                step(f, Op::RotationFromNormal, &[56, 220, 223, 2], 1042);
                step(f, Op::PerFootRotationFactor, &[17, 119, 120, 184], 1043);
                step(f, Op::MulF, &[17, 184, 224], 1044);
                step(f, Op::SubF, &[160, 18, 216], 1045);
                step(f, Op::MulF, &[224, 216, 212], 1046);
                step(f, Op::QuatFromAxisAngle, &[10, 212, 7], 1047);
                step(f, Op::MulQ, &[2, 7, 8], 1048);
                step(f, Op::Select(ValueType::Quat), &[16, 8, 6, 2], 1049);
                step(f, Op::MakeTransform, &[57, 2, 6, 8], 1050);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 7, 8], 1051);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 7], 1052);
                step(f, Op::BreakTransform, &[7, 46, 6, 47], 1053);
                step(f, Op::Select(ValueType::Vec3), &[16, 58, 46, 54], 1054);
                step(f, Op::MakeTransform, &[54, 1, 6, 5], 1055);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 7, 5], 1056);
                step(f, Op::GetTransform, &[34, 2, 9, 6], 1057);
                step(f, Op::BreakTransform, &[6, 20, 3, 19], 1058);
                step(f, Op::BreakVector, &[20, 205, 221, 200], 1059);
                step(f, Op::MulF, &[17, 216, 182], 1060);
                step(f, Op::QuatFromAxisAngle, &[10, 182, 4], 1061);
                step(f, Op::GetTransform, &[0, 2, 9, 4], 1062);
                step(f, Op::BreakTransform, &[4, 23, 5, 24], 1063);
                step(f, Op::SubV, &[23, 20, 25], 1064);
                step(f, Op::BreakVector, &[25, 206, 210, 208], 1065);
                step(f, Op::MakeVector, &[206, 210, 158, 26], 1066);
                step(f, Op::RotateVector, &[4, 26, 27], 1067);
                step(f, Op::BreakVector, &[27, 204, 207, 213], 1068);
                step(f, Op::MulF, &[53, 18, 217], 1069);
                step(f, Op::MulF, &[217, 185, 188], 1070);
                step(f, Op::AddF, &[204, 188, 194], 1071);
                step(f, Op::AddF, &[205, 194, 189], 1072);
                step(f, Op::AddF, &[221, 207, 193], 1073);
                step(f, Op::BreakVector, &[23, 187, 183, 201], 1074);
                step(f, Op::SubF, &[201, 59, 191], 1075);
                step(f, Op::MakeVector, &[189, 193, 191, 28], 1076);
                step(f, Op::MulF, &[9, 159, 196], 1077);
                step(f, Op::ScaleV, &[2, 196, 29], 1078);
                step(f, Op::AddV, &[28, 29, 30], 1079);
                step(f, Op::SubV, &[54, 30, 17], 1080);
                step(f, Op::ArraySetAt(Elem::Vec3), &[0, 7, 17], 1081);
                step(f, Op::ArraySetAt(Elem::Bool), &[1, 7, 16], 1082);
                step(f, Op::GreaterEqualF, &[198, 160, 18], 1083);
                step(f, Op::JumpIfFalse, &[18, 1100], 1084)
            }
            1084 => {
                step(f, Op::MakeVector, &[158, 158, 64, 22], 1085);
                step(f, Op::AddV, &[30, 22, 31], 1086);
                step(f, Op::RotateVector, &[0, 9, 33], 1087);
                step(f, Op::ScaleV, &[33, 68, 34], 1088);
                step(f, Op::AddV, &[31, 34, 35], 1089);
                step(f, Op::SubV, &[30, 22, 32], 1090);
                step(f, Op::AddV, &[32, 34, 36], 1091);
                step(f, Op::SphereTrace, &[35, 36, 63, 15, 37, 38, 218], 1092);
                step(f, Op::SubV, &[37, 30, 39], 1093);
                step(f, Op::ArraySetAt(Elem::Vec3), &[1, 7, 39], 1094);
                step(f, Op::ScaleV, &[33, 65, 40], 1095);
                step(f, Op::AddV, &[35, 40, 41], 1096);
                step(f, Op::AddV, &[36, 40, 42], 1097);
                step(f, Op::SphereTrace, &[41, 42, 63, 11, 43, 44, 215], 1098);
                step(f, Op::SubV, &[43, 30, 45], 1099);
                step(f, Op::ArraySetAt(Elem::Vec3), &[2, 7, 45], 1100);
                1100
            }
            1100 => {
                step(f, Op::JumpIfFalse, &[16, 1102], 1101)
            }
            1101 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 7], 1102);
                1102
            }
            1102 => {
                step(f, Op::ArrayAt(Elem::Float), &[4, 7, 190], 1103);
                step(f, Op::FloatLerp, &[190, 158, 112, 197], 1104);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 7, 12], 1105);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 211], 1106);
                step(f, Op::GreaterEqualF, &[211, 160, 20], 1107);
                step(f, Op::And, &[12, 20, 17], 1108);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 7, 8], 1109);
                step(f, Op::GreaterF, &[27, 158, 13], 1110);
                step(f, Op::InterpolateTransform, &[2, 3, 28, 7], 1111);
                step(f, Op::Select(ValueType::Transform), &[13, 7, 2, 5], 1112);
                step(f, Op::MakeAbsolute, &[8, 5, 6], 1113);
                step(f, Op::BreakTransform, &[6, 21, 7, 52], 1114);
                step(f, Op::RotateVector, &[7, 9, 51], 1115);
                step(f, Op::SubF, &[160, 18, 209], 1116);
                step(f, Op::MulF, &[17, 209, 222], 1117);
                step(f, Op::LimitRotationAroundZ, &[7, 222, 109, 8], 1118);
                step(f, Op::RotateVector, &[8, 9, 49], 1119);
                step(f, Op::CrossV, &[51, 49, 53], 1120);
                step(f, Op::BreakVector, &[53, 192, 199, 203], 1121);
                step(f, Op::DotV, &[51, 49, 202], 1122);
                step(f, Op::Atan2F, &[203, 202, 219], 1123);
                step(f, Op::AbsF, &[219, 186], 1124);
                step(f, Op::Select(ValueType::Float), &[17, 186, 158, 195], 1125);
                step(f, Op::AddF, &[197, 195, 214], 1126);
                step(f, Op::ArraySetAt(Elem::Float), &[4, 7, 214], 1127);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 7, 4], 1128);
                step(f, Op::BreakTransform, &[4, 55, 2, 18], 1129);
                step(f, Op::AddF, &[73, 74, 220], 1130);
                step(f, Op::ClampSpatially, &[21, 55, 158, 220, 59], 1131);
                step(f, Op::MakeTransform, &[59, 8, 6, 8], 1132);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 7, 8], 1133);
                step(f, Op::JumpIfFalse, &[12, 1210], 1134)
            }
            1134 => {
                step(f, Op::JumpIfFalse, &[20, 1136], 1135)
            }
            1135 => {
                step(f, Op::Jump, &[1209], 1136)
            }
            1136 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 6], 1137);
                step(f, Op::BreakTransform, &[6, 60, 6, 48], 1138);
                step(f, Op::SubF, &[160, 211, 223], 1139);
                step(f, Op::MulF, &[13, 10, 184], 1140);
                step(f, Op::MulF, &[223, 184, 224], 1141);
                step(f, Op::ScaleV, &[2, 224, 50], 1142);
                step(f, Op::AddV, &[60, 50, 56], 1143);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1144);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 12], 1145);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 14], 1146);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 12, 4], 1147);
                step(f, Op::BreakTransform, &[4, 57, 3, 47], 1148);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 12, 8], 1149);
                step(f, Op::BreakTransform, &[8, 46, 5, 58], 1150);
                step(f, Op::LessEqualF, &[95, 158, 18], 1151);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 212], 1152);
                step(f, Op::SmoothStepF, &[212, 158, 95, 200], 1153);
                step(f, Op::Select(ValueType::Float), &[18, 160, 200, 216], 1154);
                step(f, Op::LerpV, &[57, 46, 216, 19], 1155);
                step(f, Op::MakeTransform, &[19, 1, 6, 9], 1156);
                step(f, Op::Select(ValueType::Transform), &[14, 4, 9, 10], 1157);
                step(f, Op::MakeAbsolute, &[10, 5, 11], 1158);
                step(f, Op::Select(ValueType::Transform), &[19, 11, 10, 12], 1159);
                step(f, Op::BreakTransform, &[12, 24, 4, 20], 1160);
                step(f, Op::SubF, &[160, 19, 182], 1161);
                step(f, Op::MulF, &[209, 182, 208], 1162);
                step(f, Op::MulF, &[17, 208, 206], 1163);
                step(f, Op::FootAvoidance, &[56, 24, 206, 19, 91, 25], 1164);
                step(f, Op::RemapF, &[18, 94, 160, 158, 160, 9, 210], 1165);
                step(f, Op::LerpV, &[56, 25, 210, 26], 1166);
                step(f, Op::FootAvoidance, &[26, 24, 20, 19, 117, 27], 1167);
                step(f, Op::LerpV, &[26, 27, 19, 23], 1168);
                step(f, Op::MakeTransform, &[23, 6, 6, 13], 1169);
                step(f, Op::BreakTransform, &[13, 28, 7, 29], 1170);
                step(f, Op::MakeVector, &[158, 158, 64, 54], 1171);
                step(f, Op::AddV, &[28, 54, 17], 1172);
                step(f, Op::SubV, &[28, 54, 31], 1173);
                step(f, Op::LineTrace, &[17, 31, 15, 22, 32, 213], 1174);
                step(f, Op::RotateVector, &[7, 10, 34], 1175);
                step(f, Op::FindQuatBetween, &[34, 32, 2], 1176);
                step(f, Op::MulQ, &[2, 7, 8], 1177);
                step(f, Op::MulF, &[62, 61, 185], 1178);
                step(f, Op::AddF, &[185, 72, 217], 1179);
                step(f, Op::NegF, &[217, 188], 1180);
                step(f, Op::MakeVector, &[158, 188, 158, 38], 1181);
                step(f, Op::RotateVector, &[8, 38, 37], 1182);
                step(f, Op::AddV, &[22, 37, 39], 1183);
                step(f, Op::AddV, &[39, 54, 33], 1184);
                step(f, Op::SubV, &[39, 54, 35], 1185);
                step(f, Op::LineTrace, &[33, 35, 11, 36, 40, 204], 1186);
                step(f, Op::BreakVector, &[36, 194, 205, 207], 1187);
                step(f, Op::BreakVector, &[39, 221, 183, 187], 1188);
                step(f, Op::SubF, &[207, 187, 201], 1189);
                step(f, Op::Select(ValueType::Float), &[11, 201, 158, 189], 1190);
                step(f, Op::AddF, &[68, 72, 191], 1191);
                step(f, Op::MakeVector, &[158, 191, 158, 41], 1192);
                step(f, Op::RotateVector, &[8, 41, 42], 1193);
                step(f, Op::AddV, &[22, 42, 44], 1194);
                step(f, Op::AddV, &[44, 54, 30], 1195);
                step(f, Op::SubV, &[44, 54, 43], 1196);
                step(f, Op::LineTrace, &[30, 43, 16, 45, 52, 193], 1197);
                step(f, Op::BreakVector, &[45, 196, 198, 218], 1198);
                step(f, Op::BreakVector, &[44, 215, 190, 222], 1199);
                step(f, Op::SubF, &[218, 222, 192], 1200);
                step(f, Op::Select(ValueType::Float), &[16, 192, 158, 199], 1201);
                step(f, Op::MaxF, &[189, 199, 202], 1202);
                step(f, Op::ClampF, &[202, 158, 71, 203], 1203);
                step(f, Op::MakeVector, &[158, 158, 203, 53], 1204);
                step(f, Op::AddV, &[22, 53, 49], 1205);
                step(f, Op::MakeTransform, &[49, 8, 6, 14], 1206);
                step(f, Op::Select(ValueType::Transform), &[15, 14, 13, 15], 1207);
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
                step(f, Op::BreakTransform, &[15, 51, 2, 18], 1213);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 6], 1214);
                step(f, Op::BreakTransform, &[6, 60, 6, 48], 1215);
                step(f, Op::SubF, &[160, 211, 223], 1216);
                step(f, Op::MulF, &[13, 10, 184], 1217);
                step(f, Op::MulF, &[223, 184, 224], 1218);
                step(f, Op::ScaleV, &[2, 224, 50], 1219);
                step(f, Op::AddV, &[60, 50, 56], 1220);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1221);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 12], 1222);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 14], 1223);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 12, 4], 1224);
                step(f, Op::BreakTransform, &[4, 57, 3, 47], 1225);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 12, 8], 1226);
                step(f, Op::BreakTransform, &[8, 46, 5, 58], 1227);
                step(f, Op::LessEqualF, &[95, 158, 18], 1228);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 212], 1229);
                step(f, Op::SmoothStepF, &[212, 158, 95, 200], 1230);
                step(f, Op::Select(ValueType::Float), &[18, 160, 200, 216], 1231);
                step(f, Op::LerpV, &[57, 46, 216, 19], 1232);
                step(f, Op::MakeTransform, &[19, 1, 6, 9], 1233);
                step(f, Op::Select(ValueType::Transform), &[14, 4, 9, 10], 1234);
                step(f, Op::MakeAbsolute, &[10, 5, 11], 1235);
                step(f, Op::Select(ValueType::Transform), &[19, 11, 10, 12], 1236);
                step(f, Op::BreakTransform, &[12, 24, 4, 20], 1237);
                step(f, Op::SubF, &[160, 19, 182], 1238);
                step(f, Op::MulF, &[209, 182, 208], 1239);
                step(f, Op::MulF, &[17, 208, 206], 1240);
                step(f, Op::FootAvoidance, &[56, 24, 206, 19, 91, 25], 1241);
                step(f, Op::RemapF, &[18, 94, 160, 158, 160, 9, 210], 1242);
                step(f, Op::LerpV, &[56, 25, 210, 26], 1243);
                step(f, Op::FootAvoidance, &[26, 24, 20, 19, 117, 27], 1244);
                step(f, Op::LerpV, &[26, 27, 19, 23], 1245);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 7, 13], 1246);
                step(f, Op::MakeAbsolute, &[13, 5, 14], 1247);
                step(f, Op::BreakTransform, &[14, 21, 7, 59], 1248);
                step(f, Op::ArrayAt(Elem::Float), &[3, 7, 219], 1249);
                step(f, Op::SubF, &[211, 219, 186], 1250);
                step(f, Op::DeltaTime, &[195], 1251);
                step(f, Op::DivF, &[58, 195, 197], 1252);
                step(f, Op::MulF, &[186, 197, 214], 1253);
                step(f, Op::AddF, &[219, 214, 220], 1254);
                step(f, Op::ClampF, &[220, 158, 160, 213], 1255);
                step(f, Op::AddF, &[211, 214, 185], 1256);
                step(f, Op::ClampF, &[185, 158, 160, 217], 1257);
                step(f, Op::AddF, &[213, 217, 188], 1258);
                step(f, Op::MulF, &[188, 159, 204], 1259);
                step(f, Op::SubF, &[160, 204, 194], 1260);
                step(f, Op::GreaterF, &[186, 158, 17], 1261);
                step(f, Op::SubF, &[217, 213, 205], 1262);
                step(f, Op::DivF, &[205, 186, 183], 1263);
                step(f, Op::Select(ValueType::Float), &[17, 183, 160, 221], 1264);
                step(f, Op::MulF, &[194, 221, 187], 1265);
                step(f, Op::MulF, &[90, 187, 207], 1266);
                step(f, Op::Copy(ValueType::Float), &[58, 201], 1267);
                step(f, Op::SubV, &[23, 21, 29], 1268);
                step(f, Op::DeltaTime, &[191], 1269);
                step(f, Op::DivF, &[201, 191, 193], 1270);
                step(f, Op::ScaleV, &[29, 193, 28], 1271);
                step(f, Op::AddV, &[23, 28, 17], 1272);
                step(f, Op::AddV, &[21, 28, 31], 1273);
                step(f, Op::SubV, &[51, 31, 32], 1274);
                step(f, Op::FloatLerp, &[158, 160, 207, 196], 1275);
                step(f, Op::SubF, &[160, 196, 198], 1276);
                step(f, Op::ScaleV, &[32, 198, 34], 1277);
                step(f, Op::AddV, &[17, 34, 38], 1278);
                step(f, Op::MulF, &[207, 191, 190], 1279);
                step(f, Op::GreaterF, &[190, 158, 11], 1280);
                step(f, Op::DivF, &[196, 190, 215], 1281);
                step(f, Op::Select(ValueType::Float), &[11, 215, 160, 218], 1282);
                step(f, Op::ScaleV, &[29, 218, 37], 1283);
                step(f, Op::SubV, &[38, 37, 33], 1284);
                step(f, Op::Copy(ValueType::Vec3), &[33, 35], 1285);
                step(f, Op::MakeTransform, &[35, 6, 6, 15], 1286);
                step(f, Op::BreakTransform, &[15, 40, 8, 36], 1287);
                step(f, Op::MakeVector, &[158, 158, 64, 39], 1288);
                step(f, Op::AddV, &[40, 39, 41], 1289);
                step(f, Op::SubV, &[40, 39, 42], 1290);
                step(f, Op::LineTrace, &[41, 42, 16, 54, 30, 222], 1291);
                step(f, Op::RotateVector, &[8, 10, 43], 1292);
                step(f, Op::FindQuatBetween, &[43, 30, 2], 1293);
                step(f, Op::MulQ, &[2, 8, 7], 1294);
                step(f, Op::MulF, &[62, 61, 192], 1295);
                step(f, Op::AddF, &[192, 72, 189], 1296);
                step(f, Op::NegF, &[189, 199], 1297);
                step(f, Op::MakeVector, &[158, 199, 158, 52], 1298);
                step(f, Op::RotateVector, &[7, 52, 45], 1299);
                step(f, Op::AddV, &[54, 45, 44], 1300);
                step(f, Op::AddV, &[44, 39, 22], 1301);
                step(f, Op::SubV, &[44, 39, 53], 1302);
                step(f, Op::LineTrace, &[22, 53, 15, 49, 18, 202], 1303);
                step(f, Op::BreakVector, &[49, 203, 195, 197], 1304);
                step(f, Op::BreakVector, &[44, 219, 220, 214], 1305);
                step(f, Op::SubF, &[197, 214, 185], 1306);
                step(f, Op::Select(ValueType::Float), &[15, 185, 158, 188], 1307);
                step(f, Op::AddF, &[68, 72, 204], 1308);
                step(f, Op::MakeVector, &[158, 204, 158, 59], 1309);
                step(f, Op::RotateVector, &[7, 59, 21], 1310);
                step(f, Op::AddV, &[54, 21, 28], 1311);
                step(f, Op::AddV, &[28, 39, 31], 1312);
                step(f, Op::SubV, &[28, 39, 51], 1313);
                step(f, Op::LineTrace, &[31, 51, 17, 32, 17, 213], 1314);
                step(f, Op::BreakVector, &[32, 217, 186, 205], 1315);
                step(f, Op::BreakVector, &[28, 183, 194, 221], 1316);
                step(f, Op::SubF, &[205, 221, 187], 1317);
                step(f, Op::Select(ValueType::Float), &[17, 187, 158, 201], 1318);
                step(f, Op::MaxF, &[188, 201, 193], 1319);
                step(f, Op::ClampF, &[193, 158, 71, 198], 1320);
                step(f, Op::MakeVector, &[158, 158, 198, 34], 1321);
                step(f, Op::AddV, &[54, 34, 29], 1322);
                step(f, Op::MakeTransform, &[29, 7, 6, 13], 1323);
                step(f, Op::Select(ValueType::Transform), &[16, 13, 15, 14], 1324);
                step(f, Op::Copy(ValueType::Transform), &[14, 13], 1325);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 7, 13], 1326);
                1326
            }
            1326 => {
                step(f, Op::JumpIfFalse, &[20, 1409], 1327)
            }
            1327 => {
                step(f, Op::JumpIfFalse, &[12, 1329], 1328)
            }
            1328 => {
                step(f, Op::Jump, &[1390], 1329)
            }
            1329 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 7, 15], 1330);
                step(f, Op::BreakTransform, &[15, 37, 2, 38], 1331);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1332);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 12], 1333);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 12, 14], 1334);
                step(f, Op::BreakTransform, &[14, 33, 8, 35], 1335);
                step(f, Op::MakeAbsolute, &[14, 5, 13], 1336);
                step(f, Op::BreakTransform, &[13, 36, 7, 40], 1337);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 212], 1338);
                step(f, Op::SmoothStepF, &[212, 158, 160, 191], 1339);
                step(f, Op::RemapF, &[18, 158, 94, 158, 160, 9, 207], 1340);
                step(f, Op::MulF, &[191, 207, 190], 1341);
                step(f, Op::Select(ValueType::Float), &[19, 190, 158, 196], 1342);
                step(f, Op::LerpV, &[33, 36, 196, 41], 1343);
                step(f, Op::MakeTransform, &[41, 1, 6, 16], 1344);
                step(f, Op::BreakTransform, &[16, 42, 9, 30], 1345);
                step(f, Op::SubF, &[160, 19, 182], 1346);
                step(f, Op::MulF, &[209, 182, 208], 1347);
                step(f, Op::MulF, &[17, 208, 206], 1348);
                step(f, Op::FootAvoidance, &[37, 42, 206, 19, 91, 43], 1349);
                step(f, Op::MakeTransform, &[43, 2, 6, 17], 1350);
                step(f, Op::BreakTransform, &[17, 52, 2, 45], 1351);
                step(f, Op::MakeVector, &[158, 158, 64, 18], 1352);
                step(f, Op::AddV, &[52, 18, 22], 1353);
                step(f, Op::SubV, &[52, 18, 53], 1354);
                step(f, Op::LineTrace, &[22, 53, 11, 49, 44, 215], 1355);
                step(f, Op::RotateVector, &[2, 10, 59], 1356);
                step(f, Op::FindQuatBetween, &[59, 44, 10], 1357);
                step(f, Op::MulQ, &[10, 2, 11], 1358);
                step(f, Op::MulF, &[62, 61, 218], 1359);
                step(f, Op::AddF, &[218, 72, 222], 1360);
                step(f, Op::NegF, &[222, 192], 1361);
                step(f, Op::MakeVector, &[158, 192, 158, 21], 1362);
                step(f, Op::RotateVector, &[11, 21, 39], 1363);
                step(f, Op::AddV, &[49, 39, 17], 1364);
                step(f, Op::AddV, &[17, 18, 31], 1365);
                step(f, Op::SubV, &[17, 18, 51], 1366);
                step(f, Op::LineTrace, &[31, 51, 15, 32, 28, 189], 1367);
                step(f, Op::BreakVector, &[32, 199, 202, 195], 1368);
                step(f, Op::BreakVector, &[17, 203, 219, 220], 1369);
                step(f, Op::SubF, &[195, 220, 197], 1370);
                step(f, Op::Select(ValueType::Float), &[15, 197, 158, 214], 1371);
                step(f, Op::AddF, &[68, 72, 185], 1372);
                step(f, Op::MakeVector, &[158, 185, 158, 34], 1373);
                step(f, Op::RotateVector, &[11, 34, 54], 1374);
                step(f, Op::AddV, &[49, 54, 29], 1375);
                step(f, Op::AddV, &[29, 18, 38], 1376);
                step(f, Op::SubV, &[29, 18, 37], 1377);
                step(f, Op::LineTrace, &[38, 37, 17, 43, 45, 204], 1378);
                step(f, Op::BreakVector, &[43, 213, 186, 217], 1379);
                step(f, Op::BreakVector, &[29, 183, 194, 205], 1380);
                step(f, Op::SubF, &[217, 205, 221], 1381);
                step(f, Op::Select(ValueType::Float), &[17, 221, 158, 187], 1382);
                step(f, Op::MaxF, &[214, 187, 188], 1383);
                step(f, Op::ClampF, &[188, 158, 71, 201], 1384);
                step(f, Op::MakeVector, &[158, 158, 201, 52], 1385);
                step(f, Op::AddV, &[49, 52, 22], 1386);
                step(f, Op::MakeTransform, &[22, 11, 6, 18], 1387);
                step(f, Op::Select(ValueType::Transform), &[11, 18, 17, 19], 1388);
                step(f, Op::Copy(ValueType::Transform), &[19, 17], 1389);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 7, 17], 1390);
                1390
            }
            1390 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 7, 18], 1391);
                step(f, Op::BreakTransform, &[18, 53, 2, 44], 1392);
                step(f, Op::SubV, &[53, 55, 59], 1393);
                step(f, Op::LengthV, &[59, 193], 1394);
                step(f, Op::SubF, &[73, 74, 198], 1395);
                step(f, Op::SubF, &[193, 198, 215], 1396);
                step(f, Op::MulF, &[74, 163, 218], 1397);
                step(f, Op::ClampF, &[215, 158, 218, 222], 1398);
                step(f, Op::MulF, &[222, 222, 192], 1399);
                step(f, Op::MulF, &[74, 174, 189], 1400);
                step(f, Op::DivF, &[192, 189, 199], 1401);
                step(f, Op::SubF, &[193, 199, 202], 1402);
                step(f, Op::DivF, &[202, 193, 203], 1403);
                step(f, Op::ScaleV, &[59, 203, 21], 1404);
                step(f, Op::AddV, &[55, 21, 39], 1405);
                step(f, Op::MakeTransform, &[39, 2, 6, 19], 1406);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 19], 1407);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 19], 1408);
                step(f, Op::Jump, &[1578], 1409)
            }
            1409 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 7, 18], 1410);
                step(f, Op::BreakTransform, &[18, 53, 2, 44], 1411);
                step(f, Op::SubV, &[53, 55, 59], 1412);
                step(f, Op::LengthV, &[59, 193], 1413);
                step(f, Op::SubF, &[73, 74, 198], 1414);
                step(f, Op::SubF, &[193, 198, 215], 1415);
                step(f, Op::MulF, &[74, 163, 218], 1416);
                step(f, Op::ClampF, &[215, 158, 218, 222], 1417);
                step(f, Op::MulF, &[222, 222, 192], 1418);
                step(f, Op::MulF, &[74, 174, 189], 1419);
                step(f, Op::DivF, &[192, 189, 199], 1420);
                step(f, Op::SubF, &[193, 199, 202], 1421);
                step(f, Op::DivF, &[202, 193, 203], 1422);
                step(f, Op::ScaleV, &[59, 203, 21], 1423);
                step(f, Op::AddV, &[55, 21, 39], 1424);
                step(f, Op::MakeTransform, &[39, 2, 6, 19], 1425);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 7, 15], 1426);
                step(f, Op::ClampF, &[211, 158, 160, 219], 1427);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[6, 5], 1428);
                step(f, Op::ArrayReset(Elem::Vec3), &[5], 1429);
                step(f, Op::BreakTransform, &[19, 28, 10, 31], 1430);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 28], 1431);
                step(f, Op::UnitV, &[2, 51], 1432);
                step(f, Op::LengthV, &[2, 195], 1433);
                step(f, Op::RemapF, &[195, 158, 75, 158, 76, 9, 220], 1434);
                step(f, Op::ScaleV, &[51, 220, 32], 1435);
                step(f, Op::SubV, &[28, 32, 17], 1436);
                step(f, Op::MakeVector, &[158, 158, 78, 34], 1437);
                step(f, Op::AddV, &[17, 34, 54], 1438);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 54], 1439);
                step(f, Op::RemapF, &[195, 158, 75, 158, 81, 9, 197], 1440);
                step(f, Op::MakeVector, &[158, 158, 197, 18], 1441);
                step(f, Op::AddV, &[54, 18, 37], 1442);
                step(f, Op::BreakTransform, &[15, 38, 11, 45], 1443);
                step(f, Op::BreakVector, &[38, 185, 204, 186], 1444);
                step(f, Op::BreakVector, &[28, 213, 183, 194], 1445);
                step(f, Op::SubF, &[186, 194, 205], 1446);
                step(f, Op::MaxF, &[205, 158, 217], 1447);
                step(f, Op::MulF, &[217, 83, 221], 1448);
                step(f, Op::MinF, &[221, 84, 187], 1449);
                step(f, Op::AbsF, &[205, 214], 1450);
                step(f, Op::RemapF, &[214, 158, 87, 158, 86, 9, 188], 1451);
                step(f, Op::AddF, &[187, 188, 201], 1452);
                step(f, Op::MakeVector, &[158, 158, 201, 43], 1453);
                step(f, Op::AddV, &[37, 43, 29], 1454);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 29], 1455);
                step(f, Op::RemapF, &[195, 158, 75, 158, 77, 9, 198], 1456);
                step(f, Op::ScaleV, &[51, 198, 49], 1457);
                step(f, Op::AddV, &[38, 49, 52], 1458);
                step(f, Op::LerpF, &[29, 52, 18, 215], 1459);
                step(f, Op::MulF, &[14, 215, 218], 1460);
                step(f, Op::RemapF, &[218, 160, 38, 79, 80, 9, 222], 1461);
                step(f, Op::MakeVector, &[158, 158, 222, 22], 1462);
                step(f, Op::AddV, &[52, 22, 44], 1463);
                step(f, Op::RemapF, &[195, 158, 75, 158, 82, 9, 189], 1464);
                step(f, Op::MakeVector, &[158, 158, 189, 53], 1465);
                step(f, Op::AddV, &[44, 53, 59], 1466);
                step(f, Op::NegF, &[205, 192], 1467);
                step(f, Op::MaxF, &[192, 158, 199], 1468);
                step(f, Op::MulF, &[199, 85, 193], 1469);
                step(f, Op::AddF, &[193, 188, 202], 1470);
                step(f, Op::MakeVector, &[158, 158, 202, 21], 1471);
                step(f, Op::AddV, &[59, 21, 55], 1472);
                step(f, Op::LerpV, &[29, 55, 159, 39], 1473);
                step(f, Op::GetTransform, &[35, 2, 9, 17], 1474);
                step(f, Op::BreakTransform, &[17, 31, 2, 32], 1475);
                step(f, Op::BreakVector, &[31, 203, 220, 197], 1476);
                step(f, Op::SubF, &[160, 18, 185], 1477);
                step(f, Op::MulF, &[88, 185, 204], 1478);
                step(f, Op::MulF, &[17, 204, 183], 1479);
                step(f, Op::QuatFromAxisAngle, &[10, 183, 2], 1480);
                step(f, Op::SubV, &[39, 31, 17], 1481);
                step(f, Op::BreakVector, &[17, 213, 186, 194], 1482);
                step(f, Op::MakeVector, &[213, 186, 158, 34], 1483);
                step(f, Op::RotateVector, &[2, 34, 18], 1484);
                step(f, Op::BreakVector, &[18, 217, 221, 214], 1485);
                step(f, Op::AddF, &[203, 217, 187], 1486);
                step(f, Op::AddF, &[220, 221, 201], 1487);
                step(f, Op::BreakVector, &[39, 198, 215, 218], 1488);
                step(f, Op::MakeVector, &[187, 201, 218, 54], 1489);
                step(f, Op::DistanceV, &[28, 38, 222], 1490);
                step(f, Op::RemapF, &[222, 163, 175, 158, 160, 9, 195], 1491);
                step(f, Op::LerpV, &[39, 54, 195, 45], 1492);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 45], 1493);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 55], 1494);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 44], 1495);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 38], 1496);
                step(f, Op::JumpIfFalse, &[8, 1498], 1497)
            }
            1497 => {
                step(f, Op::DrawSpline, &[5, 2, 5, 159, 12], 1498);
                1498
            }
            1498 => {
                step(f, Op::Spline, &[5, 219, 2, 37, 43], 1499);
                step(f, Op::SlerpQ, &[10, 11, 219, 2], 1500);
                step(f, Op::MulF, &[219, 168, 189], 1501);
                step(f, Op::SinF, &[189, 205], 1502);
                step(f, Op::SmoothStepF, &[219, 158, 102, 192], 1503);
                step(f, Op::MulF, &[205, 192, 199], 1504);
                step(f, Op::MulF, &[199, 89, 188], 1505);
                step(f, Op::SlerpQ, &[2, 1, 188, 10], 1506);
                step(f, Op::MakeTransform, &[37, 10, 6, 18], 1507);
                step(f, Op::Copy(ValueType::Transform), &[18, 19], 1508);
                step(f, Op::BreakTransform, &[19, 51, 11, 49], 1509);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1510);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 12], 1511);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 12, 14], 1512);
                step(f, Op::BreakTransform, &[14, 33, 8, 35], 1513);
                step(f, Op::GreaterF, &[27, 158, 13], 1514);
                step(f, Op::InterpolateTransform, &[2, 3, 28, 7], 1515);
                step(f, Op::Select(ValueType::Transform), &[13, 7, 2, 5], 1516);
                step(f, Op::MakeAbsolute, &[14, 5, 13], 1517);
                step(f, Op::BreakTransform, &[13, 36, 7, 40], 1518);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 212], 1519);
                step(f, Op::SmoothStepF, &[212, 158, 160, 191], 1520);
                step(f, Op::RemapF, &[18, 158, 94, 158, 160, 9, 207], 1521);
                step(f, Op::MulF, &[191, 207, 190], 1522);
                step(f, Op::Select(ValueType::Float), &[19, 190, 158, 196], 1523);
                step(f, Op::LerpV, &[33, 36, 196, 41], 1524);
                step(f, Op::MakeTransform, &[41, 1, 6, 16], 1525);
                step(f, Op::BreakTransform, &[16, 42, 9, 30], 1526);
                step(f, Op::SubF, &[160, 18, 209], 1527);
                step(f, Op::SubF, &[160, 19, 182], 1528);
                step(f, Op::MulF, &[209, 182, 208], 1529);
                step(f, Op::MulF, &[17, 208, 206], 1530);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 16], 1531);
                step(f, Op::Select(ValueType::Float), &[16, 92, 158, 193], 1532);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 211], 1533);
                step(f, Op::ClampF, &[211, 158, 160, 219], 1534);
                step(f, Op::MulF, &[219, 168, 202], 1535);
                step(f, Op::SinF, &[202, 197], 1536);
                step(f, Op::MulF, &[197, 197, 185], 1537);
                step(f, Op::MulF, &[193, 185, 204], 1538);
                step(f, Op::AddF, &[91, 204, 183], 1539);
                step(f, Op::FootAvoidance, &[51, 42, 206, 19, 183, 22], 1540);
                step(f, Op::SubV, &[22, 51, 52], 1541);
                step(f, Op::LengthV, &[52, 194], 1542);
                step(f, Op::AddF, &[194, 204, 186], 1543);
                step(f, Op::DivF, &[194, 186, 213], 1544);
                step(f, Op::MulF, &[116, 163, 214], 1545);
                step(f, Op::LessEqualF, &[194, 214, 12], 1546);
                step(f, Op::MulF, &[116, 174, 203], 1547);
                step(f, Op::DivF, &[194, 203, 217], 1548);
                step(f, Op::DivF, &[116, 194, 220], 1549);
                step(f, Op::SubF, &[160, 220, 221], 1550);
                step(f, Op::Select(ValueType::Float), &[12, 217, 221, 198], 1551);
                step(f, Op::GreaterF, &[116, 158, 15], 1552);
                step(f, Op::Select(ValueType::Float), &[15, 19, 158, 215], 1553);
                step(f, Op::LerpF, &[213, 198, 215, 187], 1554);
                step(f, Op::LessF, &[212, 211, 17], 1555);
                step(f, Op::LessEqualF, &[93, 158, 11], 1556);
                step(f, Op::SmoothStepF, &[212, 158, 93, 201], 1557);
                step(f, Op::MulF, &[201, 18, 218], 1558);
                step(f, Op::SubF, &[160, 218, 222], 1559);
                step(f, Op::Select(ValueType::Float), &[11, 160, 222, 195], 1560);
                step(f, Op::Select(ValueType::Float), &[17, 195, 160, 189], 1561);
                step(f, Op::MulF, &[187, 189, 192], 1562);
                step(f, Op::SmoothStepF, &[219, 158, 93, 205], 1563);
                step(f, Op::Select(ValueType::Float), &[11, 160, 205, 199], 1564);
                step(f, Op::MulF, &[192, 199, 188], 1565);
                step(f, Op::ScaleV, &[52, 188, 53], 1566);
                step(f, Op::AddV, &[51, 53, 21], 1567);
                step(f, Op::MulF, &[6, 149, 191], 1568);
                step(f, Op::MulF, &[191, 185, 207], 1569);
                step(f, Op::MakeVector, &[158, 158, 207, 59], 1570);
                step(f, Op::AddV, &[21, 59, 29], 1571);
                step(f, Op::MakeTransform, &[29, 11, 6, 15], 1572);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 15], 1573);
                step(f, Op::ScaleV, &[52, 192, 32], 1574);
                step(f, Op::AddV, &[51, 32, 31], 1575);
                step(f, Op::AddV, &[31, 59, 17], 1576);
                step(f, Op::MakeTransform, &[17, 11, 6, 17], 1577);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 17], 1578);
                1578
            }
            1578 => {
                step(f, Op::JumpIfFalse, &[13, 1601], 1579)
            }
            1579 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 7, 18], 1580);
                step(f, Op::BreakTransform, &[18, 34, 2, 18], 1581);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 7, 19], 1582);
                step(f, Op::BreakTransform, &[19, 28, 10, 39], 1583);
                step(f, Op::MulF, &[27, 27, 190], 1584);
                step(f, Op::LerpV, &[34, 28, 190, 54], 1585);
                step(f, Op::SubF, &[160, 27, 196], 1586);
                step(f, Op::MulF, &[27, 196, 202], 1587);
                step(f, Op::MulF, &[151, 163, 197], 1588);
                step(f, Op::MulF, &[202, 197, 193], 1589);
                step(f, Op::MakeVector, &[158, 158, 193, 45], 1590);
                step(f, Op::AddV, &[54, 45, 55], 1591);
                step(f, Op::SlerpQ, &[2, 10, 27, 8], 1592);
                step(f, Op::MakeTransform, &[55, 8, 6, 7], 1593);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 7], 1594);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 7, 18], 1595);
                step(f, Op::BreakTransform, &[18, 34, 2, 18], 1596);
                step(f, Op::LerpV, &[34, 28, 190, 54], 1597);
                step(f, Op::AddV, &[54, 45, 55], 1598);
                step(f, Op::SlerpQ, &[2, 10, 27, 8], 1599);
                step(f, Op::MakeTransform, &[55, 8, 6, 7], 1600);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 7], 1601);
                1601
            }
            1601 => {
                step(f, Op::GreaterEqualF, &[211, 160, 20], 1602);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 7, 20], 1603);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 6], 1604);
                step(f, Op::BreakTransform, &[6, 60, 6, 48], 1605);
                step(f, Op::SubF, &[160, 211, 223], 1606);
                step(f, Op::MulF, &[13, 10, 184], 1607);
                step(f, Op::MulF, &[223, 184, 224], 1608);
                step(f, Op::ScaleV, &[2, 224, 50], 1609);
                step(f, Op::AddV, &[60, 50, 56], 1610);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1611);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 12], 1612);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 14], 1613);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 12, 4], 1614);
                step(f, Op::BreakTransform, &[4, 57, 3, 47], 1615);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 12, 8], 1616);
                step(f, Op::BreakTransform, &[8, 46, 5, 58], 1617);
                step(f, Op::LessEqualF, &[95, 158, 18], 1618);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 212], 1619);
                step(f, Op::SmoothStepF, &[212, 158, 95, 200], 1620);
                step(f, Op::Select(ValueType::Float), &[18, 160, 200, 216], 1621);
                step(f, Op::LerpV, &[57, 46, 216, 19], 1622);
                step(f, Op::MakeTransform, &[19, 1, 6, 9], 1623);
                step(f, Op::Select(ValueType::Transform), &[14, 4, 9, 10], 1624);
                step(f, Op::MakeAbsolute, &[10, 5, 11], 1625);
                step(f, Op::Select(ValueType::Transform), &[19, 11, 10, 12], 1626);
                step(f, Op::BreakTransform, &[12, 24, 4, 20], 1627);
                step(f, Op::SubF, &[160, 19, 182], 1628);
                step(f, Op::MulF, &[209, 182, 208], 1629);
                step(f, Op::MulF, &[17, 208, 206], 1630);
                step(f, Op::FootAvoidance, &[56, 24, 206, 19, 91, 25], 1631);
                step(f, Op::RemapF, &[18, 94, 160, 158, 160, 9, 210], 1632);
                step(f, Op::LerpV, &[56, 25, 210, 26], 1633);
                step(f, Op::FootAvoidance, &[26, 24, 20, 19, 117, 27], 1634);
                step(f, Op::LerpV, &[26, 27, 19, 23], 1635);
                step(f, Op::MakeTransform, &[23, 1, 6, 14], 1636);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 7, 14], 1637);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 7, 13], 1638);
                step(f, Op::BreakTransform, &[13, 44, 7, 38], 1639);
                step(f, Op::MakeVector, &[158, 158, 59, 43], 1640);
                step(f, Op::AddV, &[44, 43, 37], 1641);
                step(f, Op::GetTransform, &[0, 2, 9, 16], 1642);
                step(f, Op::BreakTransform, &[16, 49, 9, 35], 1643);
                step(f, Op::MakeTransform, &[37, 9, 6, 15], 1644);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 7, 20], 1645);
                step(f, Op::GetTransform, &[20, 2, 9, 17], 1646);
                step(f, Op::BreakTransform, &[17, 40, 11, 33], 1647);
                step(f, Op::SubV, &[40, 49, 36], 1648);
                step(f, Op::AddV, &[37, 36, 41], 1649);
                step(f, Op::FootPivots, &[37, 41, 61, 60, 59, 62, 30, 42, 22], 1650);
                step(f, Op::GetParent, &[0, 18], 1651);
                step(f, Op::GetParent, &[18, 19], 1652);
                step(f, Op::GetTransform, &[19, 2, 10, 19], 1653);
                step(f, Op::BreakTransform, &[19, 53, 2, 21], 1654);
                step(f, Op::SubV, &[44, 53, 29], 1655);
                step(f, Op::DotV, &[29, 9, 183], 1656);
                step(f, Op::RemapF, &[183, 97, 96, 98, 158, 9, 204], 1657);
                step(f, Op::LengthV, &[2, 186], 1658);
                step(f, Op::RemapF, &[186, 158, 108, 158, 160, 9, 214], 1659);
                step(f, Op::MulF, &[204, 214, 203], 1660);
                step(f, Op::QuatFromAxisAngle, &[13, 203, 10], 1661);
                step(f, Op::RotateAroundPoint, &[15, 30, 10, 18], 1662);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 194], 1663);
                step(f, Op::SmoothStepF, &[194, 158, 102, 220], 1664);
                step(f, Op::SubF, &[160, 194, 217], 1665);
                step(f, Op::SmoothStepF, &[217, 158, 102, 221], 1666);
                step(f, Op::MulF, &[220, 221, 198], 1667);
                step(f, Op::LerpF, &[101, 160, 198, 213], 1668);
                step(f, Op::MulF, &[203, 213, 215], 1669);
                step(f, Op::QuatFromAxisAngle, &[13, 215, 8], 1670);
                step(f, Op::SubV, &[42, 30, 52], 1671);
                step(f, Op::RotateVector, &[8, 52, 32], 1672);
                step(f, Op::AddV, &[30, 32, 51], 1673);
                step(f, Op::RemapF, &[183, 99, 97, 100, 158, 9, 201], 1674);
                step(f, Op::MulF, &[201, 214, 218], 1675);
                step(f, Op::QuatFromAxisAngle, &[13, 218, 6], 1676);
                step(f, Op::RotateAroundPoint, &[18, 51, 6, 7], 1677);
                step(f, Op::RemapF, &[183, 103, 104, 158, 105, 9, 222], 1678);
                step(f, Op::RotateVector, &[7, 10, 31], 1679);
                step(f, Op::BreakVector, &[31, 195, 187, 189], 1680);
                step(f, Op::CosF, &[107, 219], 1681);
                step(f, Op::CosF, &[106, 205], 1682);
                step(f, Op::RemapF, &[189, 219, 205, 158, 160, 9, 199], 1683);
                step(f, Op::MulF, &[214, 199, 188], 1684);
                step(f, Op::MulF, &[222, 188, 185], 1685);
                step(f, Op::QuatFromAxisAngle, &[13, 185, 3], 1686);
                step(f, Op::RotateAroundPoint, &[7, 22, 3, 6], 1687);
                step(f, Op::SubF, &[160, 18, 191], 1688);
                step(f, Op::MulF, &[17, 191, 207], 1689);
                step(f, Op::LimitRotationAroundZ, &[7, 207, 109, 5], 1690);
                step(f, Op::RotateAroundPoint, &[6, 44, 5, 8], 1691);
                step(f, Op::BreakTransform, &[8, 59, 4, 17], 1692);
                step(f, Op::ArrayAt(Elem::Float), &[4, 7, 192], 1693);
                step(f, Op::MulF, &[192, 110, 196], 1694);
                step(f, Op::MulF, &[196, 111, 197], 1695);
                step(f, Op::AddF, &[196, 111, 202], 1696);
                step(f, Op::DivF, &[197, 202, 193], 1697);
                step(f, Op::MakeVector, &[158, 158, 193, 39], 1698);
                step(f, Op::AddV, &[59, 39, 18], 1699);
                step(f, Op::MakeTransform, &[18, 4, 17, 4], 1700);
                step(f, Op::ArraySetAt(Elem::Transform), &[7, 7, 4], 1701);
                step(f, Op::JumpIfFalse, &[8, 1706], 1702)
            }
            1702 => {
                step(f, Op::DrawPoint, &[22, 176, 13], 1703);
                step(f, Op::DrawPoint, &[30, 176, 9], 1704);
                step(f, Op::DrawPoint, &[51, 176, 10], 1705);
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
                step(f, Op::ForEachNext(Elem::Bone), &[5, 8, 1, 6, 9, 1748], 1710)
            }
            1710 => {
                step(f, Op::GetParent, &[1, 22], 1711);
                step(f, Op::GetParent, &[22, 23], 1712);
                step(f, Op::GetParent, &[23, 24], 1713);
                step(f, Op::GetTransform, &[24, 2, 10, 9], 1714);
                step(f, Op::BreakTransform, &[9, 28, 9, 34], 1715);
                step(f, Op::LengthV, &[1, 190], 1716);
                step(f, Op::ClavicleOffset, &[15, 190, 123, 127, 211], 1717);
                step(f, Op::MakeVector, &[158, 158, 211, 45], 1718);
                step(f, Op::AddV, &[28, 45, 54], 1719);
                step(f, Op::MakeTransform, &[54, 9, 6, 5], 1720);
                step(f, Op::SetTransform, &[24, 5, 2, 9, 160], 1721);
                step(f, Op::GetTransform, &[1, 2, 10, 10], 1722);
                step(f, Op::GetTransform, &[23, 2, 10, 11], 1723);
                step(f, Op::BreakTransform, &[11, 55, 11, 48], 1724);
                step(f, Op::Equals(Elem::Int), &[6, 2, 16], 1725);
                step(f, Op::Select(ValueType::Int), &[16, 3, 2, 11], 1726);
                step(f, Op::ArrayAt(Elem::Float), &[0, 11, 184], 1727);
                step(f, Op::ArmSwingRotation, &[184, 1, 0, 124, 167, 177, 160, 123, 121, 122, 125, 167, 160, 223], 1728);
                step(f, Op::QuatFromAxisAngle, &[13, 223, 2], 1729);
                step(f, Op::RotateAroundPoint, &[10, 55, 2, 12], 1730);
                step(f, Op::BreakTransform, &[12, 50, 10, 60], 1731);
                step(f, Op::RemapF, &[190, 158, 123, 158, 126, 9, 224], 1732);
                step(f, Op::MakeVector, &[158, 158, 224, 47], 1733);
                step(f, Op::AddV, &[50, 47, 58], 1734);
                step(f, Op::MakeTransform, &[58, 10, 6, 14], 1735);
                step(f, Op::Select(ValueType::Vec3), &[16, 14, 13, 46], 1736);
                step(f, Op::Select(ValueType::Vec3), &[16, 9, 15, 57], 1737);
                step(f, Op::ArrayAt(Elem::Vec3), &[4, 6, 19], 1738);
                step(f, Op::TwoBoneIK, &[23, 22, 1, 14, 46, 57, 19, 2, 160, 10, 178, 179, 9, 12, 212], 1739);
                step(f, Op::JumpIfFalse, &[8, 1747], 1740)
            }
            1740 => {
                step(f, Op::GetTransform, &[23, 2, 10, 11], 1741);
                step(f, Op::BreakTransform, &[11, 55, 11, 48], 1742);
                step(f, Op::GetTransform, &[1, 2, 10, 10], 1743);
                step(f, Op::RotateAroundPoint, &[10, 55, 2, 12], 1744);
                step(f, Op::BreakTransform, &[12, 50, 10, 60], 1745);
                step(f, Op::AddV, &[50, 47, 58], 1746);
                step(f, Op::DrawLine, &[55, 58, 159, 9], 1747);
                1747
            }
            1747 => {
                step(f, Op::Jump, &[1709], 1748)
            }
            1748 => {
                step(f, Op::NegF, &[5, 200], 1749);
                step(f, Op::MakeVector, &[158, 158, 200, 20], 1750);
                step(f, Op::MakeTransform, &[20, 1, 6, 16], 1751);
                step(f, Op::SetTransform, &[36, 16, 2, 9, 160], 1752);
                step(f, Op::Copy(ValueType::Float), &[165, 216], 1753);
                step(f, Op::Copy(ValueType::Bool), &[10, 15], 1754);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 11], 1755);
                step(f, Op::Copy(ValueType::Int), &[2, 12], 1756);
                step(f, Op::MakeVector, &[158, 158, 64, 25], 1757);
                1757
            }
            1757 => {
                step(f, Op::ForEachNext(Elem::Transform), &[11, 12, 17, 7, 10, 1769], 1758)
            }
            1758 => {
                step(f, Op::BreakTransform, &[17, 56, 8, 24], 1759);
                step(f, Op::AddV, &[56, 25, 26], 1760);
                step(f, Op::SubV, &[56, 25, 27], 1761);
                step(f, Op::SphereTrace, &[26, 27, 63, 17, 23, 38, 182], 1762);
                step(f, Op::BreakVector, &[23, 209, 208, 206], 1763);
                step(f, Op::LessF, &[206, 216, 11], 1764);
                step(f, Op::And, &[17, 11, 13], 1765);
                step(f, Op::JumpIfFalse, &[13, 1768], 1766)
            }
            1766 => {
                step(f, Op::Copy(ValueType::Float), &[206, 216], 1767);
                step(f, Op::Copy(ValueType::Bool), &[9, 15], 1768);
                1768
            }
            1768 => {
                step(f, Op::Jump, &[1757], 1769)
            }
            1769 => {
                step(f, Op::Select(ValueType::Float), &[15, 216, 158, 210], 1770);
                step(f, Op::ClampF, &[210, 69, 70, 186], 1771);
                step(f, Op::Copy(ValueType::Float), &[186, 204], 1772);
                step(f, Op::SubF, &[160, 27, 194], 1773);
                step(f, Op::MulF, &[204, 194, 217], 1774);
                step(f, Op::SubF, &[160, 148, 220], 1775);
                step(f, Op::MulF, &[5, 220, 221], 1776);
                step(f, Op::AddF, &[217, 221, 198], 1777);
                step(f, Op::MakeVector, &[22, 158, 158, 43], 1778);
                step(f, Op::MakeVector, &[198, 158, 158, 35], 1779);
                step(f, Op::Select(ValueType::Float), &[2, 198, 23, 203], 1780);
                step(f, Op::MakeVector, &[203, 158, 158, 33], 1781);
                step(f, Op::Copy(ValueType::Float), &[57, 213], 1782);
                step(f, Op::Copy(ValueType::Float), &[58, 215], 1783);
                step(f, Op::SubV, &[35, 33, 40], 1784);
                step(f, Op::DeltaTime, &[201], 1785);
                step(f, Op::DivF, &[215, 201, 218], 1786);
                step(f, Op::ScaleV, &[40, 218, 49], 1787);
                step(f, Op::AddV, &[35, 49, 36], 1788);
                step(f, Op::AddV, &[33, 49, 37], 1789);
                step(f, Op::SubV, &[43, 37, 41], 1790);
                step(f, Op::FloatLerp, &[158, 160, 213, 183], 1791);
                step(f, Op::SubF, &[160, 183, 187], 1792);
                step(f, Op::ScaleV, &[41, 187, 21], 1793);
                step(f, Op::AddV, &[36, 21, 53], 1794);
                step(f, Op::MulF, &[213, 201, 195], 1795);
                step(f, Op::GreaterF, &[195, 158, 20], 1796);
                step(f, Op::DivF, &[183, 195, 189], 1797);
                step(f, Op::Select(ValueType::Float), &[20, 189, 160, 205], 1798);
                step(f, Op::ScaleV, &[40, 205, 29], 1799);
                step(f, Op::SubV, &[53, 29, 42], 1800);
                step(f, Op::Copy(ValueType::Vec3), &[42, 52], 1801);
                step(f, Op::BreakVector, &[52, 219, 199, 214], 1802);
                step(f, Op::Select(ValueType::Float), &[1, 198, 219, 188], 1803);
                step(f, Op::Copy(ValueType::Float), &[188, 22], 1804);
                step(f, Op::Copy(ValueType::Float), &[198, 23], 1805);
                step(f, Op::GetTransform, &[37, 2, 9, 19], 1806);
                step(f, Op::BreakTransform, &[19, 32, 6, 31], 1807);
                step(f, Op::PelvisLean, &[1, 130, 135, 136, 222, 185], 1808);
                step(f, Op::LengthV, &[2, 191], 1809);
                step(f, Op::RemapF, &[191, 158, 130, 158, 128, 9, 207], 1810);
                step(f, Op::MulF, &[18, 129, 192], 1811);
                step(f, Op::SubF, &[160, 192, 196], 1812);
                step(f, Op::MulF, &[207, 196, 197], 1813);
                step(f, Op::MulF, &[15, 180, 202], 1814);
                step(f, Op::SinF, &[202, 193], 1815);
                step(f, Op::MulF, &[197, 193, 211], 1816);
                step(f, Op::MulF, &[211, 194, 184], 1817);
                step(f, Op::AddF, &[184, 22, 223], 1818);
                step(f, Op::SubF, &[223, 5, 190], 1819);
                step(f, Op::MakeVector, &[158, 185, 190, 44], 1820);
                step(f, Op::AddV, &[32, 44, 39], 1821);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 2, 15], 1822);
                step(f, Op::BreakTransform, &[15, 59, 3, 17], 1823);
                step(f, Op::BreakVector, &[59, 224, 212, 200], 1824);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 3, 18], 1825);
                step(f, Op::BreakTransform, &[18, 18, 7, 22], 1826);
                step(f, Op::BreakVector, &[18, 182, 208, 209], 1827);
                step(f, Op::SubF, &[200, 209, 206], 1828);
                step(f, Op::PelvisSideLean, &[206, 137, 138, 216], 1829);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 2, 7], 1830);
                step(f, Op::BreakTransform, &[7, 30, 5, 51], 1831);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 3, 6], 1832);
                step(f, Op::BreakTransform, &[6, 34, 4, 28], 1833);
                step(f, Op::SlerpQ, &[5, 4, 159, 9], 1834);
                step(f, Op::EulerFromQuat, &[9, 2, 45], 1835);
                step(f, Op::BreakVector, &[45, 210, 186, 204], 1836);
                step(f, Op::RemapF, &[191, 131, 130, 158, 132, 9, 220], 1837);
                step(f, Op::SubV, &[59, 18, 54], 1838);
                step(f, Op::RotateVector, &[0, 9, 19], 1839);
                step(f, Op::DotV, &[54, 19, 217], 1840);
                step(f, Op::MulF, &[220, 217, 221], 1841);
                step(f, Op::AddF, &[204, 221, 203], 1842);
                step(f, Op::MakeVector, &[222, 216, 203, 46], 1843);
                step(f, Op::QuatFromEuler, &[46, 2, 11], 1844);
                step(f, Op::MakeTransform, &[39, 11, 6, 8], 1845);
                step(f, Op::SetTransform, &[38, 8, 2, 9, 160], 1846);
                step(f, Op::GetTransform, &[39, 3, 9, 4], 1847);
                step(f, Op::BreakTransform, &[4, 57, 2, 48], 1848);
                step(f, Op::QuatFromAxisAngle, &[10, 221, 10], 1849);
                step(f, Op::DivF, &[133, 176, 215], 1850);
                step(f, Op::QuatScale, &[10, 215, 8], 1851);
                step(f, Op::MulQ, &[2, 8, 6], 1852);
                step(f, Op::MakeTransform, &[57, 6, 6, 13], 1853);
                step(f, Op::SetTransform, &[40, 13, 3, 9, 160], 1854);
                step(f, Op::GetTransform, &[41, 3, 9, 9], 1855);
                step(f, Op::BreakTransform, &[9, 60, 3, 47], 1856);
                step(f, Op::MulQ, &[3, 8, 7], 1857);
                step(f, Op::MakeTransform, &[60, 7, 6, 5], 1858);
                step(f, Op::SetTransform, &[42, 5, 3, 9, 160], 1859);
                step(f, Op::GetTransform, &[43, 3, 9, 14], 1860);
                step(f, Op::BreakTransform, &[14, 50, 4, 55], 1861);
                step(f, Op::MulQ, &[4, 8, 5], 1862);
                step(f, Op::MakeTransform, &[50, 5, 6, 11], 1863);
                step(f, Op::SetTransform, &[44, 11, 3, 9, 160], 1864);
                step(f, Op::GetTransform, &[45, 3, 9, 10], 1865);
                step(f, Op::BreakTransform, &[10, 58, 9, 20], 1866);
                step(f, Op::QuatScale, &[10, 134, 11], 1867);
                step(f, Op::MulQ, &[9, 11, 2], 1868);
                step(f, Op::MakeTransform, &[58, 2, 6, 12], 1869);
                step(f, Op::SetTransform, &[46, 12, 3, 9, 160], 1870);
                step(f, Op::Or, &[1, 2, 18], 1871);
                step(f, Op::Copy(ValueType::Float), &[158, 218], 1872);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1873);
                step(f, Op::Copy(ValueType::Int), &[2, 9], 1874);
                1874
            }
            1874 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 9, 25, 11, 6, 1921], 1875)
            }
            1875 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 11, 14], 1876);
                step(f, Op::GetParent, &[25, 26], 1877);
                step(f, Op::GetParent, &[26, 27], 1878);
                step(f, Op::GetTransform, &[27, 2, 10, 16], 1879);
                step(f, Op::BreakTransform, &[16, 24, 6, 56], 1880);
                step(f, Op::BreakVector, &[24, 187, 201, 213], 1881);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 11, 17], 1882);
                step(f, Op::BreakTransform, &[17, 26, 3, 27], 1883);
                step(f, Op::BreakVector, &[26, 183, 195, 189], 1884);
                step(f, Op::ArrayAt(Elem::Float), &[1, 11, 205], 1885);
                step(f, Op::MulF, &[205, 139, 199], 1886);
                step(f, Op::MulF, &[199, 199, 214], 1887);
                step(f, Op::SubF, &[187, 183, 219], 1888);
                step(f, Op::SubF, &[201, 195, 188], 1889);
                step(f, Op::MakeVector, &[219, 188, 158, 38], 1890);
                step(f, Op::DotV, &[38, 38, 198], 1891);
                step(f, Op::SubF, &[214, 198, 192], 1892);
                step(f, Op::SqrtF, &[192, 196], 1893);
                step(f, Op::AddF, &[189, 196, 207], 1894);
                step(f, Op::SubF, &[213, 207, 202], 1895);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 11, 19], 1896);
                step(f, Op::BreakTransform, &[19, 23, 7, 25], 1897);
                step(f, Op::BreakVector, &[23, 193, 197, 194], 1898);
                step(f, Op::AddF, &[194, 59, 211], 1899);
                step(f, Op::MinF, &[189, 211, 184], 1900);
                step(f, Op::AddF, &[184, 196, 223], 1901);
                step(f, Op::SubF, &[213, 223, 185], 1902);
                step(f, Op::Equals(Elem::Int), &[11, 2, 19], 1903);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 8], 1904);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 8, 16], 1905);
                step(f, Op::ArrayAt(Elem::Float), &[2, 8, 190], 1906);
                step(f, Op::RemapF, &[190, 159, 160, 158, 160, 9, 212], 1907);
                step(f, Op::RemapF, &[190, 158, 142, 160, 158, 9, 224], 1908);
                step(f, Op::MaxF, &[212, 224, 182], 1909);
                step(f, Op::Select(ValueType::Float), &[16, 160, 182, 208], 1910);
                step(f, Op::LerpF, &[202, 185, 208, 200], 1911);
                step(f, Op::ArrayAt(Elem::Float), &[2, 11, 209], 1912);
                step(f, Op::RemapF, &[209, 159, 160, 158, 160, 9, 206], 1913);
                step(f, Op::MulF, &[200, 206, 186], 1914);
                step(f, Op::RemapF, &[209, 158, 142, 160, 158, 9, 210], 1915);
                step(f, Op::MulF, &[202, 210, 191], 1916);
                step(f, Op::MaxF, &[186, 191, 217], 1917);
                step(f, Op::Select(ValueType::Float), &[14, 202, 217, 220], 1918);
                step(f, Op::MaxF, &[218, 220, 204], 1919);
                step(f, Op::Copy(ValueType::Float), &[204, 218], 1920);
                step(f, Op::Jump, &[1874], 1921)
            }
            1921 => {
                step(f, Op::ClampF, &[218, 158, 140, 203], 1922);
                step(f, Op::Copy(ValueType::Float), &[203, 216], 1923);
                step(f, Op::MakeVector, &[24, 158, 158, 35], 1924);
                step(f, Op::MakeVector, &[216, 158, 158, 33], 1925);
                step(f, Op::MakeVector, &[25, 158, 158, 49], 1926);
                step(f, Op::GreaterF, &[216, 24, 12], 1927);
                step(f, Op::Select(ValueType::Float), &[12, 144, 141, 222], 1928);
                step(f, Op::Copy(ValueType::Float), &[58, 221], 1929);
                step(f, Op::SubV, &[33, 49, 37], 1930);
                step(f, Op::DeltaTime, &[215], 1931);
                step(f, Op::DivF, &[221, 215, 205], 1932);
                step(f, Op::ScaleV, &[37, 205, 43], 1933);
                step(f, Op::AddV, &[33, 43, 41], 1934);
                step(f, Op::AddV, &[49, 43, 21], 1935);
                step(f, Op::SubV, &[35, 21, 36], 1936);
                step(f, Op::FloatLerp, &[158, 160, 222, 199], 1937);
                step(f, Op::SubF, &[160, 199, 183], 1938);
                step(f, Op::ScaleV, &[36, 183, 40], 1939);
                step(f, Op::AddV, &[41, 40, 29], 1940);
                step(f, Op::MulF, &[222, 215, 187], 1941);
                step(f, Op::GreaterF, &[187, 158, 11], 1942);
                step(f, Op::DivF, &[199, 187, 195], 1943);
                step(f, Op::Select(ValueType::Float), &[11, 195, 160, 201], 1944);
                step(f, Op::ScaleV, &[37, 201, 53], 1945);
                step(f, Op::SubV, &[29, 53, 42], 1946);
                step(f, Op::Copy(ValueType::Vec3), &[42, 52], 1947);
                step(f, Op::BreakVector, &[52, 188, 219, 198], 1948);
                step(f, Op::Select(ValueType::Float), &[18, 216, 188, 214], 1949);
                step(f, Op::Copy(ValueType::Float), &[214, 24], 1950);
                step(f, Op::Copy(ValueType::Float), &[216, 25], 1951);
                step(f, Op::GetTransform, &[47, 2, 10, 15], 1952);
                step(f, Op::BreakTransform, &[15, 31, 4, 32], 1953);
                step(f, Op::MakeVector, &[158, 158, 24, 44], 1954);
                step(f, Op::SubV, &[31, 44, 17], 1955);
                step(f, Op::MakeTransform, &[17, 4, 6, 18], 1956);
                step(f, Op::SetTransform, &[48, 18, 2, 9, 160], 1957);
                step(f, Op::JumpIfFalse, &[8, 1963], 1958)
            }
            1958 => {
                step(f, Op::GetTransform, &[47, 2, 10, 15], 1959);
                step(f, Op::BreakTransform, &[15, 31, 4, 32], 1960);
                step(f, Op::SubV, &[31, 44, 17], 1961);
                step(f, Op::MakeTransform, &[17, 4, 6, 18], 1962);
                step(f, Op::DrawTransform, &[18, 181, 159], 1963);
                1963
            }
            1963 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1964);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 1965);
                1965
            }
            1965 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 7, 2, 10, 12, 2014], 1966)
            }
            1966 => {
                step(f, Op::GetParent, &[2, 29], 1967);
                step(f, Op::GetParent, &[29, 30], 1968);
                step(f, Op::GetTransform, &[30, 2, 10, 7], 1969);
                step(f, Op::BreakTransform, &[7, 22, 8, 30], 1970);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 10, 6], 1971);
                step(f, Op::BreakTransform, &[6, 51, 5, 28], 1972);
                step(f, Op::SubV, &[51, 22, 34], 1973);
                step(f, Op::LengthV, &[34, 192], 1974);
                step(f, Op::ArrayAt(Elem::Float), &[1, 10, 207], 1975);
                step(f, Op::MulF, &[207, 152, 193], 1976);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 10, 17], 1977);
                step(f, Op::MulF, &[19, 118, 197], 1978);
                step(f, Op::ArrayAt(Elem::Float), &[2, 10, 194], 1979);
                step(f, Op::ClampF, &[194, 158, 160, 189], 1980);
                step(f, Op::LessF, &[189, 159, 13], 1981);
                step(f, Op::SmoothStepF, &[189, 154, 155, 211], 1982);
                step(f, Op::MulF, &[189, 168, 184], 1983);
                step(f, Op::SinF, &[184, 196], 1984);
                step(f, Op::MaxF, &[211, 196, 213], 1985);
                step(f, Op::Select(ValueType::Float), &[13, 213, 196, 223], 1986);
                step(f, Op::MulF, &[223, 153, 190], 1987);
                step(f, Op::Select(ValueType::Float), &[17, 197, 190, 212], 1988);
                step(f, Op::SubF, &[193, 212, 224], 1989);
                step(f, Op::SubF, &[192, 224, 182], 1990);
                step(f, Op::MaxF, &[182, 158, 185], 1991);
                step(f, Op::MulF, &[185, 185, 208], 1992);
                step(f, Op::AddF, &[185, 212, 200], 1993);
                step(f, Op::DivF, &[208, 200, 206], 1994);
                step(f, Op::SubF, &[192, 206, 209], 1995);
                step(f, Op::DivF, &[209, 192, 210], 1996);
                step(f, Op::ScaleV, &[34, 210, 45], 1997);
                step(f, Op::AddV, &[22, 45, 18], 1998);
                step(f, Op::ClampSpatially, &[18, 22, 158, 193, 59], 1999);
                step(f, Op::MakeTransform, &[59, 5, 6, 8], 2000);
                step(f, Op::Equals(Elem::Int), &[10, 2, 15], 2001);
                step(f, Op::Select(ValueType::Vec3), &[15, 14, 13, 19], 2002);
                step(f, Op::Select(ValueType::Vec3), &[15, 9, 15, 54], 2003);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 10, 4], 2004);
                step(f, Op::BreakTransform, &[4, 46, 10, 39], 2005);
                step(f, Op::ArrayAt(Elem::Vec3), &[3, 10, 48], 2006);
                step(f, Op::KneeVector, &[10, 0, 48, 156, 157, 57], 2007);
                step(f, Op::TwoBoneIK, &[30, 29, 2, 8, 19, 54, 57, 2, 160, 10, 178, 179, 9, 20, 186], 2008);
                step(f, Op::JumpIfFalse, &[8, 2013], 2009)
            }
            2009 => {
                step(f, Op::GetTransform, &[29, 2, 10, 13], 2010);
                step(f, Op::BreakTransform, &[13, 47, 9, 60], 2011);
                step(f, Op::AddV, &[47, 57, 55], 2012);
                step(f, Op::DrawLine, &[47, 55, 159, 16], 2013);
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
