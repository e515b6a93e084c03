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
    fingerprint: 0x01bfa808652243cc,
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
                step(f, Op::BreakTransform, &[4, 19, 2, 20], 109);
                step(f, Op::Select(ValueType::Transform), &[0, 0, 4, 5], 110);
                step(f, Op::BreakTransform, &[5, 16, 2, 21], 111);
                step(f, Op::SubV, &[19, 16, 17], 112);
                step(f, Op::LengthV, &[17, 182], 113);
                step(f, Op::GreaterF, &[182, 40, 11], 114);
                step(f, Op::Copy(ValueType::Bool), &[11, 2], 115);
                step(f, Op::MakeRelative, &[5, 4, 6], 116);
                step(f, Op::Select(ValueType::Transform), &[11, 3, 6, 7], 117);
                step(f, Op::Copy(ValueType::Transform), &[7, 2], 118);
                step(f, Op::InverseT, &[5, 6], 119);
                step(f, Op::MulT, &[4, 6, 7], 120);
                step(f, Op::Copy(ValueType::Transform), &[7, 1], 121);
                step(f, Op::TransformVector, &[2, 0, 18], 122);
                step(f, Op::InverseT, &[4, 5], 123);
                step(f, Op::DeltaTime, &[180], 124);
                step(f, Op::DivF, &[158, 180, 181], 125);
                step(f, Op::ScaleV, &[17, 181, 20], 126);
                step(f, Op::TransformVector, &[5, 20, 21], 127);
                step(f, Op::BreakVector, &[21, 182, 183, 184], 128);
                step(f, Op::BreakVector, &[17, 184, 185, 186], 129);
                step(f, Op::AddF, &[2, 186, 184], 130);
                step(f, Op::Select(ValueType::Float), &[11, 156, 184, 185], 131);
                step(f, Op::MakeVector, &[182, 183, 156, 16], 132);
                step(f, Op::LengthV, &[16, 186], 133);
                step(f, Op::MulF, &[186, 143, 184], 134);
                step(f, Op::MulF, &[184, 180, 186], 135);
                step(f, Op::NegF, &[186, 180], 136);
                step(f, Op::ClampF, &[185, 180, 186, 184], 137);
                step(f, Op::MulF, &[184, 181, 180], 138);
                step(f, Op::MakeVector, &[182, 183, 180, 19], 139);
                step(f, Op::Select(ValueType::Vec3), &[2, 18, 19, 20], 140);
                step(f, Op::VectorLerp, &[18, 20, 41, 156, 21], 141);
                step(f, Op::Copy(ValueType::Vec3), &[21, 0], 142);
                step(f, Op::TransformVector, &[2, 1, 17], 143);
                step(f, Op::TransformVector, &[2, 0, 18], 144);
                step(f, Op::Select(ValueType::Vec3), &[2, 18, 19, 20], 145);
                step(f, Op::VectorLerp, &[17, 20, 42, 156, 16], 146);
                step(f, Op::Copy(ValueType::Vec3), &[16, 1], 147);
                step(f, Op::LengthV, &[20, 186], 148);
                step(f, Op::Copy(ValueType::Float), &[186, 0], 149);
                step(f, Op::SubF, &[185, 184, 181], 150);
                step(f, Op::NegF, &[144, 180], 151);
                step(f, Op::ClampF, &[181, 180, 144, 182], 152);
                step(f, Op::SubF, &[181, 182, 183], 153);
                step(f, Op::Copy(ValueType::Float), &[183, 1], 154);
                step(f, Op::Copy(ValueType::Float), &[182, 3], 155);
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
                step(f, Op::Copy(ValueType::Float), &[156, 21], 169);
                169
            }
            169 => {
                step(f, Op::Copy(ValueType::Transform), &[4, 0], 170);
                step(f, Op::Copy(ValueType::Bool), &[9, 0], 171);
                step(f, Op::JumpIfFalse, &[8, 177], 172)
            }
            172 => {
                step(f, Op::GetTransform, &[33, 2, 9, 7], 173);
                step(f, Op::BreakTransform, &[7, 21, 2, 18], 174);
                step(f, Op::ScaleV, &[0, 159, 19], 175);
                step(f, Op::AddV, &[21, 19, 17], 176);
                step(f, Op::DrawArrow, &[21, 17, 157, 7], 177);
                177
            }
            177 => {
                step(f, Op::Copy(ValueType::Float), &[156, 186], 178);
                step(f, Op::Copy(ValueType::Float), &[158, 184], 179);
                step(f, Op::Copy(ValueType::Bool), &[10, 11], 180);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[8, 9], 181);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 182);
                step(f, Op::MakeVector, &[156, 156, 63, 16], 183);
                183
            }
            183 => {
                step(f, Op::ForEachNext(Elem::Transform), &[9, 7, 5, 8, 6, 193], 184)
            }
            184 => {
                step(f, Op::BreakTransform, &[5, 20, 2, 18], 185);
                step(f, Op::TransformPoint, &[2, 20, 19], 186);
                step(f, Op::LerpV, &[19, 20, 158, 17], 187);
                step(f, Op::AddV, &[17, 16, 21], 188);
                step(f, Op::SubV, &[17, 16, 18], 189);
                step(f, Op::LineTrace, &[21, 18, 12, 19, 20, 185], 190);
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
                step(f, Op::AddF, &[186, 184, 180], 203);
                step(f, Op::MulF, &[180, 157, 181], 204);
                step(f, Op::Copy(ValueType::Bool), &[10, 15], 205);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[8, 10], 206);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 207);
                step(f, Op::MakeVector, &[156, 156, 63, 17], 208);
                208
            }
            208 => {
                step(f, Op::ForEachNext(Elem::Transform), &[10, 7, 6, 9, 10, 218], 209)
            }
            209 => {
                step(f, Op::BreakTransform, &[6, 18, 2, 19], 210);
                step(f, Op::TransformPoint, &[2, 18, 20], 211);
                step(f, Op::LerpV, &[20, 18, 181, 21], 212);
                step(f, Op::AddV, &[21, 17, 16], 213);
                step(f, Op::SubV, &[21, 17, 19], 214);
                step(f, Op::LineTrace, &[16, 19, 16, 18, 20, 183], 215);
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
                step(f, Op::Copy(ValueType::Float), &[181, 186], 222);
                step(f, Op::Jump, &[224], 223)
            }
            223 => {
                step(f, Op::Copy(ValueType::Float), &[181, 184], 224);
                224
            }
            224 => {
                step(f, Op::Jump, &[201], 225)
            }
            225 => {
                step(f, Op::Select(ValueType::Float), &[5, 160, 158, 182], 226);
                step(f, Op::NotEquals(Elem::Bool), &[12, 6, 14], 227);
                step(f, Op::AddF, &[186, 184, 180], 228);
                step(f, Op::MulF, &[180, 157, 185], 229);
                step(f, Op::Select(ValueType::Float), &[14, 185, 157, 183], 230);
                step(f, Op::Select(ValueType::Float), &[13, 183, 156, 181], 231);
                step(f, Op::MulF, &[182, 181, 184], 232);
                step(f, Op::DeltaTime, &[186], 233);
                step(f, Op::DivF, &[186, 148, 180], 234);
                step(f, Op::MulF, &[184, 180, 185], 235);
                step(f, Op::AddF, &[25, 185, 181], 236);
                step(f, Op::ClampF, &[181, 156, 158, 182], 237);
                step(f, Op::Select(ValueType::Float), &[11, 160, 158, 186], 238);
                step(f, Op::SubF, &[158, 183, 184], 239);
                step(f, Op::Select(ValueType::Float), &[13, 184, 158, 185], 240);
                step(f, Op::MulF, &[186, 185, 181], 241);
                step(f, Op::MulF, &[181, 180, 183], 242);
                step(f, Op::AddF, &[182, 183, 184], 243);
                step(f, Op::ClampF, &[184, 156, 158, 185], 244);
                step(f, Op::SmoothStepF, &[185, 156, 158, 186], 245);
                step(f, Op::AddF, &[26, 186, 180], 246);
                step(f, Op::MulF, &[180, 157, 181], 247);
                step(f, Op::SubF, &[158, 181, 182], 248);
                step(f, Op::MulF, &[182, 182, 183], 249);
                step(f, Op::SubF, &[158, 183, 184], 250);
                step(f, Op::Copy(ValueType::Float), &[184, 27], 251);
                step(f, Op::Copy(ValueType::Float), &[186, 26], 252);
                step(f, Op::Copy(ValueType::Float), &[185, 25], 253);
                step(f, Op::GreaterF, &[26, 156, 16], 254);
                step(f, Op::TransformVector, &[2, 3, 21], 255);
                step(f, Op::Select(ValueType::Vec3), &[16, 21, 0, 16], 256);
                step(f, Op::Copy(ValueType::Vec3), &[16, 3], 257);
                step(f, Op::LerpV, &[0, 3, 26, 18], 258);
                step(f, Op::Select(ValueType::Vec3), &[16, 18, 0, 19], 259);
                step(f, Op::Copy(ValueType::Vec3), &[19, 2], 260);
                step(f, Op::Copy(ValueType::Bool), &[11, 5], 261);
                step(f, Op::Copy(ValueType::Bool), &[12, 6], 262);
                step(f, Op::Copy(ValueType::Bool), &[10, 7], 263);
                step(f, Op::SubF, &[158, 27, 180], 264);
                step(f, Op::MulF, &[1, 180, 181], 265);
                step(f, Op::SubF, &[3, 2, 182], 266);
                step(f, Op::MulF, &[182, 180, 183], 267);
                step(f, Op::AddF, &[2, 183, 184], 268);
                step(f, Op::MulF, &[184, 180, 186], 269);
                step(f, Op::SubF, &[184, 186, 185], 270);
                step(f, Op::AddF, &[181, 185, 187], 271);
                step(f, Op::AddF, &[4, 187, 188], 272);
                step(f, Op::Copy(ValueType::Float), &[7, 189], 273);
                step(f, Op::Copy(ValueType::Float), &[8, 190], 274);
                step(f, Op::Copy(ValueType::Float), &[4, 191], 275);
                step(f, Op::Copy(ValueType::Float), &[145, 192], 276);
                step(f, Op::Copy(ValueType::Float), &[57, 193], 277);
                step(f, Op::SubF, &[188, 191, 194], 278);
                step(f, Op::DeltaTime, &[195], 279);
                step(f, Op::DivF, &[194, 195, 196], 280);
                step(f, Op::MulF, &[196, 193, 197], 281);
                step(f, Op::AddF, &[188, 197, 198], 282);
                step(f, Op::MulF, &[196, 161, 199], 283);
                step(f, Op::DivF, &[162, 192, 200], 284);
                step(f, Op::DivF, &[199, 200, 201], 285);
                step(f, Op::SubF, &[198, 201, 202], 286);
                step(f, Op::AddF, &[191, 197, 203], 287);
                step(f, Op::SubF, &[189, 203, 204], 288);
                step(f, Op::AddF, &[204, 201, 205], 289);
                step(f, Op::SubF, &[190, 196, 206], 290);
                step(f, Op::MulF, &[200, 205, 207], 291);
                step(f, Op::AddF, &[206, 207, 208], 292);
                step(f, Op::MulF, &[208, 195, 209], 293);
                step(f, Op::AddF, &[205, 209, 210], 294);
                step(f, Op::FloatLerp, &[156, 158, 200, 211], 295);
                step(f, Op::SubF, &[158, 211, 212], 296);
                step(f, Op::MulF, &[210, 212, 213], 297);
                step(f, Op::AddF, &[202, 213, 214], 298);
                step(f, Op::Copy(ValueType::Float), &[214, 215], 299);
                step(f, Op::MulF, &[200, 209, 216], 300);
                step(f, Op::SubF, &[206, 216, 217], 301);
                step(f, Op::MulF, &[217, 212, 218], 302);
                step(f, Op::AddF, &[196, 218, 219], 303);
                step(f, Op::Copy(ValueType::Float), &[219, 220], 304);
                step(f, Op::SubF, &[188, 215, 221], 305);
                step(f, Op::AddF, &[221, 186, 222], 306);
                step(f, Op::Copy(ValueType::Float), &[222, 5], 307);
                step(f, Op::Copy(ValueType::Float), &[221, 6], 308);
                step(f, Op::Copy(ValueType::Float), &[186, 2], 309);
                step(f, Op::SubF, &[3, 2, 182], 310);
                step(f, Op::MulF, &[182, 180, 183], 311);
                step(f, Op::AddF, &[2, 183, 184], 312);
                step(f, Op::MulF, &[184, 180, 186], 313);
                step(f, Op::SubF, &[184, 186, 185], 314);
                step(f, Op::AddF, &[181, 185, 187], 315);
                step(f, Op::AddF, &[4, 187, 188], 316);
                step(f, Op::Copy(ValueType::Float), &[7, 189], 317);
                step(f, Op::Copy(ValueType::Float), &[8, 190], 318);
                step(f, Op::Copy(ValueType::Float), &[4, 191], 319);
                step(f, Op::Copy(ValueType::Float), &[145, 192], 320);
                step(f, Op::Copy(ValueType::Float), &[57, 193], 321);
                step(f, Op::SubF, &[188, 191, 194], 322);
                step(f, Op::DeltaTime, &[195], 323);
                step(f, Op::DivF, &[194, 195, 196], 324);
                step(f, Op::MulF, &[196, 193, 197], 325);
                step(f, Op::AddF, &[188, 197, 198], 326);
                step(f, Op::MulF, &[196, 161, 199], 327);
                step(f, Op::DivF, &[162, 192, 200], 328);
                step(f, Op::DivF, &[199, 200, 201], 329);
                step(f, Op::SubF, &[198, 201, 202], 330);
                step(f, Op::AddF, &[191, 197, 203], 331);
                step(f, Op::SubF, &[189, 203, 204], 332);
                step(f, Op::AddF, &[204, 201, 205], 333);
                step(f, Op::SubF, &[190, 196, 206], 334);
                step(f, Op::MulF, &[200, 205, 207], 335);
                step(f, Op::AddF, &[206, 207, 208], 336);
                step(f, Op::MulF, &[208, 195, 209], 337);
                step(f, Op::AddF, &[205, 209, 210], 338);
                step(f, Op::FloatLerp, &[156, 158, 200, 211], 339);
                step(f, Op::SubF, &[158, 211, 212], 340);
                step(f, Op::MulF, &[210, 212, 213], 341);
                step(f, Op::AddF, &[202, 213, 214], 342);
                step(f, Op::Copy(ValueType::Float), &[214, 215], 343);
                step(f, Op::MulF, &[200, 209, 216], 344);
                step(f, Op::SubF, &[206, 216, 217], 345);
                step(f, Op::MulF, &[217, 212, 218], 346);
                step(f, Op::AddF, &[196, 218, 219], 347);
                step(f, Op::Copy(ValueType::Float), &[219, 220], 348);
                step(f, Op::Copy(ValueType::Float), &[215, 7], 349);
                step(f, Op::Copy(ValueType::Float), &[7, 189], 350);
                step(f, Op::Copy(ValueType::Float), &[8, 190], 351);
                step(f, Op::Copy(ValueType::Float), &[4, 191], 352);
                step(f, Op::Copy(ValueType::Float), &[145, 192], 353);
                step(f, Op::Copy(ValueType::Float), &[57, 193], 354);
                step(f, Op::SubF, &[188, 191, 194], 355);
                step(f, Op::DeltaTime, &[195], 356);
                step(f, Op::DivF, &[194, 195, 196], 357);
                step(f, Op::MulF, &[196, 193, 197], 358);
                step(f, Op::AddF, &[188, 197, 198], 359);
                step(f, Op::MulF, &[196, 161, 199], 360);
                step(f, Op::DivF, &[162, 192, 200], 361);
                step(f, Op::DivF, &[199, 200, 201], 362);
                step(f, Op::SubF, &[198, 201, 202], 363);
                step(f, Op::AddF, &[191, 197, 203], 364);
                step(f, Op::SubF, &[189, 203, 204], 365);
                step(f, Op::AddF, &[204, 201, 205], 366);
                step(f, Op::SubF, &[190, 196, 206], 367);
                step(f, Op::MulF, &[200, 205, 207], 368);
                step(f, Op::AddF, &[206, 207, 208], 369);
                step(f, Op::MulF, &[208, 195, 209], 370);
                step(f, Op::AddF, &[205, 209, 210], 371);
                step(f, Op::FloatLerp, &[156, 158, 200, 211], 372);
                step(f, Op::SubF, &[158, 211, 212], 373);
                step(f, Op::MulF, &[210, 212, 213], 374);
                step(f, Op::AddF, &[202, 213, 214], 375);
                step(f, Op::Copy(ValueType::Float), &[214, 215], 376);
                step(f, Op::MulF, &[200, 209, 216], 377);
                step(f, Op::SubF, &[206, 216, 217], 378);
                step(f, Op::MulF, &[217, 212, 218], 379);
                step(f, Op::AddF, &[196, 218, 219], 380);
                step(f, Op::Copy(ValueType::Float), &[219, 220], 381);
                step(f, Op::Copy(ValueType::Float), &[220, 8], 382);
                step(f, Op::Copy(ValueType::Float), &[188, 4], 383);
                step(f, Op::LengthV, &[4, 222], 384);
                step(f, Op::GreaterF, &[222, 34, 15], 385);
                step(f, Op::LengthV, &[2, 221], 386);
                step(f, Op::GreaterF, &[221, 34, 14], 387);
                step(f, Op::And, &[15, 14, 13], 388);
                step(f, Op::Select(ValueType::Vec3), &[15, 4, 6, 20], 389);
                step(f, Op::MovementAngleOffset, &[20, 17, 156, 163, 163, 164, 45, 165, 182], 390);
                step(f, Op::Copy(ValueType::Float), &[17, 183], 391);
                step(f, Op::SubF, &[182, 183, 180], 392);
                step(f, Op::AddF, &[180, 166, 184], 393);
                step(f, Op::DivF, &[184, 167, 186], 394);
                step(f, Op::FractF, &[186, 181], 395);
                step(f, Op::MulF, &[181, 167, 185], 396);
                step(f, Op::SubF, &[185, 166, 187], 397);
                step(f, Op::Copy(ValueType::Float), &[187, 194], 398);
                step(f, Op::AbsF, &[194, 193], 399);
                step(f, Op::Select(ValueType::Vec3), &[14, 2, 6, 17], 400);
                step(f, Op::MovementAngleOffset, &[17, 17, 156, 163, 163, 164, 45, 165, 192], 401);
                step(f, Op::Copy(ValueType::Float), &[17, 199], 402);
                step(f, Op::SubF, &[192, 199, 198], 403);
                step(f, Op::AddF, &[198, 166, 191], 404);
                step(f, Op::DivF, &[191, 167, 197], 405);
                step(f, Op::FractF, &[197, 189], 406);
                step(f, Op::MulF, &[189, 167, 203], 407);
                step(f, Op::SubF, &[203, 166, 201], 408);
                step(f, Op::Copy(ValueType::Float), &[201, 204], 409);
                step(f, Op::AbsF, &[204, 190], 410);
                step(f, Op::MaxF, &[193, 190, 207], 411);
                step(f, Op::SubF, &[192, 182, 195], 412);
                step(f, Op::AddF, &[195, 166, 208], 413);
                step(f, Op::DivF, &[208, 167, 205], 414);
                step(f, Op::FractF, &[205, 211], 415);
                step(f, Op::MulF, &[211, 167, 210], 416);
                step(f, Op::SubF, &[210, 166, 202], 417);
                step(f, Op::Copy(ValueType::Float), &[202, 213], 418);
                step(f, Op::AbsF, &[213, 214], 419);
                step(f, Op::MaxF, &[207, 214, 215], 420);
                step(f, Op::LessF, &[215, 168, 16], 421);
                step(f, Op::And, &[13, 16, 11], 422);
                step(f, Op::Not, &[15, 12], 423);
                step(f, Op::Not, &[14, 13], 424);
                step(f, Op::And, &[12, 13, 16], 425);
                step(f, Op::Or, &[11, 16, 15], 426);
                step(f, Op::JumpIfFalse, &[15, 448], 427)
            }
            427 => {
                step(f, Op::DeltaTime, &[200], 428);
                step(f, Op::MulF, &[43, 200, 209], 429);
                step(f, Op::GreaterF, &[209, 156, 12], 430);
                step(f, Op::DivF, &[57, 200, 206], 431);
                step(f, Op::FloatLerp, &[156, 158, 43, 216], 432);
                step(f, Op::SubF, &[158, 216, 212], 433);
                step(f, Op::DivF, &[212, 216, 217], 434);
                step(f, Op::DivF, &[158, 209, 196], 435);
                step(f, Op::SubF, &[217, 196, 218], 436);
                step(f, Op::AddF, &[206, 218, 219], 437);
                step(f, Op::Select(ValueType::Float), &[12, 219, 156, 220], 438);
                step(f, Op::MulF, &[213, 220, 188], 439);
                step(f, Op::AddF, &[192, 188, 222], 440);
                step(f, Op::SinF, &[222, 183], 441);
                step(f, Op::NegF, &[183, 180], 442);
                step(f, Op::CosF, &[222, 184], 443);
                step(f, Op::MakeVector, &[180, 184, 156, 21], 444);
                step(f, Op::Select(ValueType::Vec3), &[14, 21, 6, 16], 445);
                step(f, Op::MovementAngleOffset, &[16, 17, 156, 43, 44, 164, 166, 165, 186], 446);
                step(f, Op::Copy(ValueType::Float), &[186, 17], 447);
                step(f, Op::Jump, &[504], 448)
            }
            448 => {
                step(f, Op::DeltaTime, &[200], 449);
                step(f, Op::DivF, &[200, 47, 181], 450);
                step(f, Op::AddF, &[181, 157, 185], 451);
                step(f, Op::FloorF, &[185, 187], 452);
                step(f, Op::MaxF, &[187, 158, 194], 453);
                step(f, Op::ToInt, &[194, 9], 454);
                step(f, Op::Copy(ValueType::Int), &[9, 10], 455);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 456);
                step(f, Op::MulF, &[47, 157, 199], 457);
                step(f, Op::SubF, &[57, 199, 198], 458);
                step(f, Op::DivF, &[198, 200, 191], 459);
                step(f, Op::FloatLerp, &[156, 158, 41, 197], 460);
                step(f, Op::GreaterF, &[197, 156, 13], 461);
                step(f, Op::DivF, &[43, 194, 189], 462);
                step(f, Op::DivF, &[44, 194, 203], 463);
                step(f, Op::SubF, &[164, 46, 201], 464);
                step(f, Op::GreaterF, &[46, 156, 11], 465);
                465
            }
            465 => {
                step(f, Op::ForNext, &[7, 10, 6, 504], 466)
            }
            466 => {
                step(f, Op::ToFloat, &[6, 204], 467);
                step(f, Op::AddF, &[204, 158, 190], 468);
                step(f, Op::DivF, &[190, 194, 193], 469);
                step(f, Op::AddF, &[193, 191, 182], 470);
                step(f, Op::MulF, &[41, 182, 195], 471);
                step(f, Op::FloatLerp, &[156, 158, 195, 208], 472);
                step(f, Op::DivF, &[208, 197, 205], 473);
                step(f, Op::Select(ValueType::Float), &[13, 205, 182, 211], 474);
                step(f, Op::LerpV, &[4, 2, 211, 18], 475);
                step(f, Op::LengthV, &[18, 210], 476);
                step(f, Op::GreaterF, &[210, 34, 16], 477);
                step(f, Op::Select(ValueType::Vec3), &[16, 18, 6, 19], 478);
                step(f, Op::MulF, &[200, 182, 202], 479);
                step(f, Op::MulF, &[11, 202, 207], 480);
                step(f, Op::AddF, &[15, 207, 214], 481);
                step(f, Op::FractF, &[214, 215], 482);
                step(f, Op::MulF, &[215, 161, 212], 483);
                step(f, Op::FractF, &[212, 216], 484);
                step(f, Op::LessF, &[216, 165, 15], 485);
                step(f, Op::MovementAngleOffset, &[19, 17, 156, 163, 163, 164, 45, 165, 209], 486);
                step(f, Op::Copy(ValueType::Float), &[17, 196], 487);
                step(f, Op::SubF, &[209, 196, 217], 488);
                step(f, Op::AddF, &[217, 166, 206], 489);
                step(f, Op::DivF, &[206, 167, 218], 490);
                step(f, Op::FractF, &[218, 219], 491);
                step(f, Op::MulF, &[219, 167, 213], 492);
                step(f, Op::SubF, &[213, 166, 220], 493);
                step(f, Op::Copy(ValueType::Float), &[220, 188], 494);
                step(f, Op::AbsF, &[188, 192], 495);
                step(f, Op::SmoothStepF, &[192, 201, 164, 183], 496);
                step(f, Op::GreaterF, &[192, 164, 12], 497);
                step(f, Op::Select(ValueType::Float), &[12, 158, 156, 222], 498);
                step(f, Op::Select(ValueType::Float), &[11, 183, 222, 180], 499);
                step(f, Op::Select(ValueType::Float), &[15, 156, 180, 184], 500);
                step(f, Op::LerpF, &[189, 203, 184, 186], 501);
                step(f, Op::MovementAngleOffset, &[19, 17, 215, 186, 186, 164, 45, 165, 181], 502);
                step(f, Op::Copy(ValueType::Float), &[181, 17], 503);
                step(f, Op::Jump, &[465], 504)
            }
            504 => {
                step(f, Op::QuatFromAxisAngle, &[8, 17, 2], 505);
                step(f, Op::Copy(ValueType::Quat), &[2, 0], 506);
                step(f, Op::SinF, &[17, 185], 507);
                step(f, Op::AbsF, &[185, 187], 508);
                step(f, Op::RemapF, &[187, 48, 49, 156, 158, 9, 199], 509);
                step(f, Op::BreakVector, &[17, 198, 204, 190], 510);
                step(f, Op::AbsF, &[198, 193], 511);
                step(f, Op::DivF, &[193, 221, 195], 512);
                step(f, Op::RemapF, &[195, 48, 49, 156, 158, 9, 208], 513);
                step(f, Op::TransformVector, &[2, 9, 20], 514);
                step(f, Op::DistanceV, &[20, 9, 205], 515);
                step(f, Op::DivF, &[205, 200, 211], 516);
                step(f, Op::RemapF, &[211, 53, 54, 158, 156, 9, 210], 517);
                step(f, Op::MulF, &[208, 210, 182], 518);
                step(f, Op::MaxF, &[199, 182, 202], 519);
                step(f, Op::Copy(ValueType::Float), &[202, 18], 520);
                step(f, Op::Copy(ValueType::Vec3), &[2, 4], 521);
                step(f, Op::Copy(ValueType::Bool), &[9, 14], 522);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 2], 523);
                step(f, Op::Copy(ValueType::Int), &[2, 8], 524);
                524
            }
            524 => {
                step(f, Op::ForEachNext(Elem::Bool), &[2, 8, 16, 9, 6, 529], 525)
            }
            525 => {
                step(f, Op::Not, &[16, 12], 526);
                step(f, Op::JumpIfFalse, &[12, 528], 527)
            }
            527 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 14], 528);
                528
            }
            528 => {
                step(f, Op::Jump, &[524], 529)
            }
            529 => {
                step(f, Op::Copy(ValueType::Bool), &[14, 15], 530);
                step(f, Op::Copy(ValueType::Bool), &[9, 11], 531);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 532);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 533);
                533
            }
            533 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 7, 15, 10, 6, 547], 534)
            }
            534 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 10, 4], 535);
                step(f, Op::BreakTransform, &[4, 21, 2, 16], 536);
                step(f, Op::BreakVector, &[21, 207, 214, 212], 537);
                step(f, Op::MakeVector, &[207, 214, 156, 18], 538);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 10, 7], 539);
                step(f, Op::BreakTransform, &[7, 19, 2, 17], 540);
                step(f, Op::BreakVector, &[19, 216, 196, 209], 541);
                step(f, Op::MakeVector, &[216, 196, 156, 20], 542);
                step(f, Op::DistanceV, &[18, 20, 217], 543);
                step(f, Op::GreaterF, &[217, 36, 13], 544);
                step(f, Op::JumpIfFalse, &[13, 546], 545)
            }
            545 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 11], 546);
                546
            }
            546 => {
                step(f, Op::Jump, &[533], 547)
            }
            547 => {
                step(f, Op::Copy(ValueType::Bool), &[11, 16], 548);
                step(f, Op::And, &[15, 16, 12], 549);
                step(f, Op::LengthV, &[2, 206], 550);
                step(f, Op::GreaterF, &[206, 34, 14], 551);
                step(f, Op::GreaterF, &[0, 34, 13], 552);
                step(f, Op::Or, &[14, 13, 11], 553);
                step(f, Op::Not, &[11, 16], 554);
                step(f, Op::And, &[12, 16, 13], 555);
                step(f, Op::DeltaTime, &[218], 556);
                step(f, Op::MulF, &[218, 39, 219], 557);
                step(f, Op::AddF, &[15, 219, 213], 558);
                step(f, Op::GreaterF, &[15, 157, 11], 559);
                step(f, Op::AddF, &[38, 157, 220], 560);
                step(f, Op::Select(ValueType::Float), &[11, 220, 38, 188], 561);
                step(f, Op::MinF, &[213, 188, 192], 562);
                step(f, Op::NotEquals(Elem::Bool), &[16, 4, 11], 563);
                step(f, Op::Not, &[12, 17], 564);
                step(f, Op::And, &[11, 17, 18], 565);
                step(f, Op::SubF, &[16, 34, 183], 566);
                step(f, Op::SubF, &[16, 206, 222], 567);
                step(f, Op::DivF, &[183, 222, 180], 568);
                step(f, Op::ClampF, &[180, 156, 158, 184], 569);
                step(f, Op::MulF, &[11, 184, 186], 570);
                step(f, Op::RemapF, &[206, 34, 35, 156, 158, 9, 215], 571);
                step(f, Op::MaxF, &[215, 12, 181], 572);
                step(f, Op::Select(ValueType::Float), &[15, 158, 181, 189], 573);
                step(f, Op::Select(ValueType::Float), &[16, 37, 189, 191], 574);
                step(f, Op::Select(ValueType::Float), &[12, 215, 191, 194], 575);
                step(f, Op::SubF, &[158, 26, 197], 576);
                step(f, Op::MulF, &[194, 197, 201], 577);
                step(f, Op::LerpF, &[28, 51, 18, 203], 578);
                step(f, Op::RemapF, &[206, 31, 32, 29, 30, 9, 185], 579);
                step(f, Op::LerpF, &[185, 50, 18, 187], 580);
                step(f, Op::MaxF, &[206, 33, 190], 581);
                step(f, Op::DivF, &[187, 190, 204], 582);
                step(f, Op::AddF, &[203, 204, 198], 583);
                step(f, Op::DivF, &[201, 198, 193], 584);
                step(f, Op::SubF, &[158, 184, 221], 585);
                step(f, Op::MulF, &[193, 221, 195], 586);
                step(f, Op::AddF, &[186, 195, 200], 587);
                step(f, Op::MulF, &[200, 161, 205], 588);
                step(f, Op::AddF, &[11, 193, 211], 589);
                step(f, Op::Select(ValueType::Float), &[18, 205, 211, 208], 590);
                step(f, Op::DivF, &[161, 208, 210], 591);
                step(f, Op::GreaterF, &[208, 156, 11], 592);
                step(f, Op::CycleStep, &[15, 210, 156, 11, 182, 199], 593);
                step(f, Op::Select(ValueType::Float), &[13, 192, 182, 202], 594);
                step(f, Op::Copy(ValueType::Float), &[202, 15], 595);
                step(f, Op::Copy(ValueType::Float), &[193, 11], 596);
                step(f, Op::Copy(ValueType::Bool), &[14, 3], 597);
                step(f, Op::Copy(ValueType::Float), &[204, 9], 598);
                step(f, Op::Copy(ValueType::Float), &[198, 10], 599);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 600);
                step(f, Op::Copy(ValueType::Int), &[2, 9], 601);
                step(f, Op::DivF, &[203, 198, 212], 602);
                step(f, Op::MulF, &[14, 184, 207], 603);
                step(f, Op::MulF, &[218, 157, 214], 604);
                step(f, Op::SubF, &[212, 13, 209], 605);
                step(f, Op::MaxF, &[209, 156, 196], 606);
                step(f, Op::DivF, &[196, 212, 216], 607);
                step(f, Op::SubF, &[158, 18, 217], 608);
                step(f, Op::DivF, &[57, 218, 219], 609);
                step(f, Op::SubF, &[157, 219, 220], 610);
                step(f, Op::MulF, &[216, 217, 188], 611);
                step(f, Op::MulF, &[188, 197, 213], 612);
                step(f, Op::MulF, &[213, 141, 183], 613);
                step(f, Op::MulF, &[183, 220, 222], 614);
                step(f, Op::SubF, &[158, 222, 180], 615);
                615
            }
            615 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 9, 14, 8, 6, 659], 616)
            }
            616 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 8, 185], 617);
                step(f, Op::ToFloat, &[8, 187], 618);
                step(f, Op::MulF, &[187, 157, 190], 619);
                step(f, Op::AddF, &[15, 190, 186], 620);
                step(f, Op::FractF, &[186, 195], 621);
                step(f, Op::SubF, &[185, 195, 200], 622);
                step(f, Op::GreaterF, &[200, 157, 17], 623);
                step(f, Op::ArrayAt(Elem::Float), &[2, 8, 205], 624);
                step(f, Op::Select(ValueType::Float), &[17, 156, 205, 211], 625);
                step(f, Op::ArraySetAt(Elem::Float), &[3, 8, 211], 626);
                step(f, Op::SubF, &[158, 185, 208], 627);
                step(f, Op::AddF, &[195, 208, 199], 628);
                step(f, Op::DivF, &[195, 199, 210], 629);
                step(f, Op::MaxF, &[215, 12, 181], 630);
                step(f, Op::Select(ValueType::Float), &[15, 158, 181, 189], 631);
                step(f, Op::Select(ValueType::Float), &[16, 37, 189, 191], 632);
                step(f, Op::Select(ValueType::Float), &[12, 215, 191, 194], 633);
                step(f, Op::MulF, &[194, 197, 201], 634);
                step(f, Op::DivF, &[201, 203, 182], 635);
                step(f, Op::MulF, &[182, 221, 192], 636);
                step(f, Op::AddF, &[207, 192, 202], 637);
                step(f, Op::MulF, &[202, 161, 193], 638);
                step(f, Op::AddF, &[14, 182, 204], 639);
                step(f, Op::Select(ValueType::Float), &[18, 193, 204, 198], 640);
                step(f, Op::MulF, &[198, 214, 184], 641);
                step(f, Op::MulF, &[210, 184, 209], 642);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 8, 11], 643);
                step(f, Op::MulF, &[184, 180, 196], 644);
                step(f, Op::Select(ValueType::Float), &[11, 184, 196, 218], 645);
                step(f, Op::MulF, &[216, 205, 219], 646);
                step(f, Op::MulF, &[219, 217, 188], 647);
                step(f, Op::MulF, &[188, 197, 213], 648);
                step(f, Op::MulF, &[213, 141, 183], 649);
                step(f, Op::Select(ValueType::Float), &[11, 156, 183, 220], 650);
                step(f, Op::SubF, &[218, 220, 222], 651);
                step(f, Op::AddF, &[205, 222, 187], 652);
                step(f, Op::Select(ValueType::Float), &[17, 209, 187, 190], 653);
                step(f, Op::MinF, &[190, 161, 186], 654);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 8, 186], 655);
                step(f, Op::JumpIfFalse, &[17, 657], 656)
            }
            656 => {
                step(f, Op::Copy(ValueType::Float), &[194, 12], 657);
                657
            }
            657 => {
                step(f, Op::ArraySetAt(Elem::Float), &[0, 8, 195], 658);
                step(f, Op::Jump, &[615], 659)
            }
            659 => {
                step(f, Op::Copy(ValueType::Float), &[212, 13], 660);
                step(f, Op::Copy(ValueType::Bool), &[16, 4], 661);
                step(f, Op::Copy(ValueType::Float), &[206, 16], 662);
                step(f, Op::MaxF, &[215, 12, 181], 663);
                step(f, Op::Select(ValueType::Float), &[15, 158, 181, 189], 664);
                step(f, Op::Select(ValueType::Float), &[16, 37, 189, 191], 665);
                step(f, Op::Select(ValueType::Float), &[12, 215, 191, 194], 666);
                step(f, Op::MulF, &[194, 197, 201], 667);
                step(f, Op::DivF, &[201, 203, 182], 668);
                step(f, Op::Copy(ValueType::Float), &[182, 14], 669);
                step(f, Op::TransformVector, &[2, 9, 16], 670);
                step(f, Op::DistanceV, &[16, 9, 200], 671);
                step(f, Op::DeltaTime, &[211], 672);
                step(f, Op::DivF, &[200, 211, 185], 673);
                step(f, Op::RemapF, &[185, 53, 54, 156, 158, 9, 208], 674);
                step(f, Op::BreakTransform, &[2, 21, 2, 17], 675);
                step(f, Op::BreakVector, &[21, 199, 192, 202], 676);
                step(f, Op::NegF, &[192, 193], 677);
                step(f, Op::Atan2F, &[199, 193, 204], 678);
                step(f, Op::AbsF, &[204, 198], 679);
                step(f, Op::RemapF, &[198, 111, 112, 156, 158, 9, 210], 680);
                step(f, Op::MulF, &[208, 210, 184], 681);
                step(f, Op::FloatLerp, &[19, 156, 113, 196], 682);
                step(f, Op::MaxF, &[184, 196, 219], 683);
                step(f, Op::Copy(ValueType::Float), &[219, 19], 684);
                step(f, Op::Copy(ValueType::Float), &[204, 20], 685);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 686);
                step(f, Op::Copy(ValueType::Int), &[2, 10], 687);
                687
            }
            687 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 10, 0, 7, 6, 1616], 688)
            }
            688 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 13], 689);
                step(f, Op::Copy(ValueType::Bool), &[10, 14], 690);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 7, 11], 691);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 188], 692);
                step(f, Op::GreaterEqualF, &[188, 158, 17], 693);
                step(f, Op::And, &[11, 17, 18], 694);
                step(f, Op::Or, &[1, 2, 15], 695);
                step(f, Op::GreaterF, &[26, 156, 16], 696);
                step(f, Op::Or, &[15, 16, 12], 697);
                step(f, Op::Not, &[12, 11], 698);
                step(f, Op::And, &[18, 11, 15], 699);
                step(f, Op::JumpIfFalse, &[15, 809], 700)
            }
            700 => {
                step(f, Op::ArrayAt(Elem::Transform), &[2, 7, 5], 701);
                step(f, Op::BreakTransform, &[5, 19, 2, 18], 702);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 7, 20], 703);
                step(f, Op::SubV, &[19, 20, 16], 704);
                step(f, Op::TransformPoint, &[2, 16, 17], 705);
                step(f, Op::GetTransform, &[34, 2, 9, 6], 706);
                step(f, Op::BreakTransform, &[6, 21, 3, 16], 707);
                step(f, Op::BreakVector, &[21, 213, 183, 218], 708);
                step(f, Op::SubF, &[158, 18, 220], 709);
                step(f, Op::MulF, &[17, 220, 205], 710);
                step(f, Op::QuatFromAxisAngle, &[8, 205, 4], 711);
                step(f, Op::GetTransform, &[0, 2, 9, 4], 712);
                step(f, Op::BreakTransform, &[4, 22, 5, 23], 713);
                step(f, Op::SubV, &[22, 21, 24], 714);
                step(f, Op::BreakVector, &[24, 222, 187, 209], 715);
                step(f, Op::MakeVector, &[222, 187, 156, 25], 716);
                step(f, Op::RotateVector, &[4, 25, 26], 717);
                step(f, Op::BreakVector, &[26, 190, 186, 195], 718);
                step(f, Op::MulF, &[52, 18, 180], 719);
                step(f, Op::Equals(Elem::Int), &[7, 2, 16], 720);
                step(f, Op::Select(ValueType::Float), &[16, 158, 160, 207], 721);
                step(f, Op::MulF, &[180, 207, 214], 722);
                step(f, Op::AddF, &[190, 214, 216], 723);
                step(f, Op::AddF, &[213, 216, 217], 724);
                step(f, Op::AddF, &[183, 186, 221], 725);
                step(f, Op::BreakVector, &[22, 212, 206, 181], 726);
                step(f, Op::SubF, &[181, 58, 189], 727);
                step(f, Op::MakeVector, &[217, 221, 189, 27], 728);
                step(f, Op::MulF, &[9, 157, 191], 729);
                step(f, Op::ScaleV, &[2, 191, 28], 730);
                step(f, Op::AddV, &[27, 28, 29], 731);
                step(f, Op::DistanceV, &[17, 29, 215], 732);
                step(f, Op::TransformVector, &[2, 10, 17], 733);
                step(f, Op::DistanceV, &[17, 10, 194], 734);
                step(f, Op::MaxF, &[215, 194, 197], 735);
                step(f, Op::LessEqualF, &[197, 65, 12], 736);
                step(f, Op::LengthV, &[2, 201], 737);
                step(f, Op::LengthV, &[4, 203], 738);
                step(f, Op::MaxF, &[201, 203, 182], 739);
                step(f, Op::LessEqualF, &[182, 34, 11], 740);
                step(f, Op::And, &[12, 11, 18], 741);
                step(f, Op::ArrayAt(Elem::Bool), &[1, 7, 15], 742);
                step(f, Op::And, &[18, 15, 11], 743);
                step(f, Op::JumpIfFalse, &[11, 746], 744)
            }
            744 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 14], 745);
                step(f, Op::Jump, &[775], 746)
            }
            746 => {
                step(f, Op::MakeVector, &[156, 156, 63, 17], 747);
                step(f, Op::AddV, &[29, 17, 30], 748);
                step(f, Op::SubV, &[29, 17, 31], 749);
                step(f, Op::SphereTrace, &[30, 31, 62, 12, 32, 33, 200], 750);
                step(f, Op::SubV, &[32, 29, 33], 751);
                step(f, Op::DistanceV, &[33, 20, 211], 752);
                step(f, Op::RotateVector, &[0, 9, 32], 753);
                step(f, Op::ScaleV, &[32, 67, 33], 754);
                step(f, Op::AddV, &[30, 33, 34], 755);
                step(f, Op::AddV, &[31, 33, 35], 756);
                step(f, Op::SphereTrace, &[34, 35, 62, 18, 36, 37, 185], 757);
                step(f, Op::SubV, &[36, 29, 38], 758);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 7, 39], 759);
                step(f, Op::DistanceV, &[38, 39, 202], 760);
                step(f, Op::MaxF, &[211, 202, 192], 761);
                step(f, Op::ScaleV, &[32, 64, 39], 762);
                step(f, Op::AddV, &[34, 39, 40], 763);
                step(f, Op::AddV, &[35, 39, 41], 764);
                step(f, Op::SphereTrace, &[40, 41, 62, 11, 42, 43, 193], 765);
                step(f, Op::SubV, &[42, 29, 44], 766);
                step(f, Op::ArrayAt(Elem::Vec3), &[2, 7, 45], 767);
                step(f, Op::DistanceV, &[44, 45, 199], 768);
                step(f, Op::MaxF, &[192, 199, 198], 769);
                step(f, Op::LessEqualF, &[198, 65, 19], 770);
                step(f, Op::And, &[12, 18, 20], 771);
                step(f, Op::And, &[20, 15, 12], 772);
                step(f, Op::And, &[19, 12, 20], 773);
                step(f, Op::JumpIfFalse, &[20, 775], 774)
            }
            774 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 14], 775);
                775
            }
            775 => {
                step(f, Op::JumpIfFalse, &[14, 809], 776)
            }
            776 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 7], 777);
                step(f, Op::BreakTransform, &[7, 45, 6, 46], 778);
                step(f, Op::AddV, &[29, 20, 47], 779);
                step(f, Op::Copy(ValueType::Float), &[55, 208], 780);
                step(f, Op::Copy(ValueType::Float), &[57, 210], 781);
                step(f, Op::SubV, &[47, 19, 20], 782);
                step(f, Op::DeltaTime, &[184], 783);
                step(f, Op::DivF, &[210, 184, 196], 784);
                step(f, Op::ScaleV, &[20, 196, 48], 785);
                step(f, Op::AddV, &[47, 48, 49], 786);
                step(f, Op::AddV, &[19, 48, 50], 787);
                step(f, Op::SubV, &[45, 50, 48], 788);
                step(f, Op::FloatLerp, &[156, 158, 208, 219], 789);
                step(f, Op::SubF, &[158, 219, 204], 790);
                step(f, Op::ScaleV, &[48, 204, 50], 791);
                step(f, Op::AddV, &[49, 50, 48], 792);
                step(f, Op::MulF, &[208, 184, 194], 793);
                step(f, Op::GreaterF, &[194, 156, 12], 794);
                step(f, Op::DivF, &[219, 194, 215], 795);
                step(f, Op::Select(ValueType::Float), &[12, 215, 158, 197], 796);
                step(f, Op::ScaleV, &[20, 197, 49], 797);
                step(f, Op::SubV, &[48, 49, 50], 798);
                step(f, Op::Copy(ValueType::Vec3), &[50, 20], 799);
                step(f, Op::BreakVector, &[20, 201, 203, 182], 800);
                step(f, Op::ClampF, &[182, 68, 69, 200], 801);
                step(f, Op::MakeVector, &[201, 203, 200, 48], 802);
                step(f, Op::MakeTransform, &[48, 6, 5, 8], 803);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 7, 8], 804);
                step(f, Op::MakeTransform, &[47, 1, 5, 8], 805);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 7, 8], 806);
                step(f, Op::JumpIfFalse, &[15, 808], 807)
            }
            807 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 7], 808);
                808
            }
            808 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 13], 809);
                809
            }
            809 => {
                step(f, Op::JumpIfFalse, &[13, 1014], 810)
            }
            810 => {
                step(f, Op::GetTransform, &[34, 2, 9, 6], 811);
                step(f, Op::BreakTransform, &[6, 21, 3, 16], 812);
                step(f, Op::BreakVector, &[21, 213, 183, 218], 813);
                step(f, Op::SubF, &[158, 18, 220], 814);
                step(f, Op::MulF, &[17, 220, 205], 815);
                step(f, Op::QuatFromAxisAngle, &[8, 205, 4], 816);
                step(f, Op::GetTransform, &[0, 2, 9, 4], 817);
                step(f, Op::BreakTransform, &[4, 22, 5, 23], 818);
                step(f, Op::SubV, &[22, 21, 24], 819);
                step(f, Op::BreakVector, &[24, 222, 187, 209], 820);
                step(f, Op::MakeVector, &[222, 187, 156, 25], 821);
                step(f, Op::RotateVector, &[4, 25, 26], 822);
                step(f, Op::BreakVector, &[26, 190, 186, 195], 823);
                step(f, Op::MulF, &[52, 18, 180], 824);
                step(f, Op::Equals(Elem::Int), &[7, 2, 16], 825);
                step(f, Op::Select(ValueType::Float), &[16, 158, 160, 207], 826);
                step(f, Op::MulF, &[180, 207, 214], 827);
                step(f, Op::AddF, &[190, 214, 216], 828);
                step(f, Op::AddF, &[213, 216, 217], 829);
                step(f, Op::AddF, &[183, 186, 221], 830);
                step(f, Op::BreakVector, &[22, 212, 206, 181], 831);
                step(f, Op::SubF, &[181, 58, 189], 832);
                step(f, Op::MakeVector, &[217, 221, 189, 27], 833);
                step(f, Op::SubF, &[158, 188, 202], 834);
                step(f, Op::MaxF, &[202, 156, 211], 835);
                step(f, Op::MulF, &[13, 10, 192], 836);
                step(f, Op::MulF, &[211, 192, 199], 837);
                step(f, Op::ScaleV, &[2, 199, 49], 838);
                step(f, Op::AddV, &[27, 49, 50], 839);
                step(f, Op::MulF, &[9, 157, 191], 840);
                step(f, Op::ScaleV, &[2, 191, 28], 841);
                step(f, Op::AddV, &[50, 28, 20], 842);
                step(f, Op::RotateVector, &[0, 9, 32], 843);
                step(f, Op::Copy(ValueType::Float), &[163, 198], 844);
                step(f, Op::Copy(ValueType::Vec3), &[6, 48], 845);
                step(f, Op::Copy(ValueType::Vec3), &[8, 47], 846);
                step(f, Op::Copy(ValueType::Bool), &[10, 19], 847);
                step(f, Op::Copy(ValueType::Float), &[163, 210], 848);
                step(f, Op::Copy(ValueType::Vec3), &[6, 50], 849);
                step(f, Op::MulI, &[0, 0, 8], 850);
                step(f, Op::Copy(ValueType::Int), &[8, 9], 851);
                step(f, Op::Copy(ValueType::Int), &[2, 6], 852);
                step(f, Op::SubI, &[0, 3, 8], 853);
                step(f, Op::DivI, &[8, 4, 11], 854);
                step(f, Op::MakeVector, &[156, 156, 63, 51], 855);
                step(f, Op::ScaleV, &[32, 67, 52], 856);
                856
            }
            856 => {
                step(f, Op::ForNext, &[6, 9, 8, 903], 857)
            }
            857 => {
                step(f, Op::ModI, &[8, 0, 12], 858);
                step(f, Op::ToFloat, &[12, 196], 859);
                step(f, Op::MulF, &[196, 64, 204], 860);
                step(f, Op::MulF, &[204, 207, 184], 861);
                step(f, Op::MakeVector, &[184, 156, 156, 53], 862);
                step(f, Op::DivI, &[8, 0, 12], 863);
                step(f, Op::SubI, &[12, 11, 8], 864);
                step(f, Op::ToFloat, &[8, 208], 865);
                step(f, Op::MulF, &[208, 64, 194], 866);
                step(f, Op::ScaleV, &[32, 194, 54], 867);
                step(f, Op::AddV, &[53, 54, 55], 868);
                step(f, Op::AddV, &[20, 55, 53], 869);
                step(f, Op::AddV, &[53, 51, 54], 870);
                step(f, Op::SubV, &[53, 51, 56], 871);
                step(f, Op::SphereTrace, &[54, 56, 62, 20, 53, 57, 219], 872);
                step(f, Op::BreakVector, &[53, 215, 197, 182], 873);
                step(f, Op::AddV, &[54, 52, 58], 874);
                step(f, Op::AddV, &[56, 52, 54], 875);
                step(f, Op::SphereTrace, &[58, 54, 62, 14, 56, 59, 200], 876);
                step(f, Op::BreakVector, &[56, 201, 203, 196], 877);
                step(f, Op::SubF, &[182, 196, 204], 878);
                step(f, Op::AbsF, &[204, 184], 879);
                step(f, Op::Select(ValueType::Float), &[20, 156, 158, 208], 880);
                step(f, Op::AddF, &[184, 208, 194], 881);
                step(f, Op::LengthV, &[55, 219], 882);
                step(f, Op::RemapF, &[219, 156, 169, 156, 158, 9, 197], 883);
                step(f, Op::MinF, &[182, 196, 215], 884);
                step(f, Op::RemapF, &[215, 170, 169, 158, 157, 9, 200], 885);
                step(f, Op::AddF, &[197, 200, 201], 886);
                step(f, Op::AddF, &[194, 201, 203], 887);
                step(f, Op::LessF, &[203, 198, 12], 888);
                step(f, Op::And, &[20, 12, 15], 889);
                step(f, Op::JumpIfFalse, &[15, 897], 890)
            }
            890 => {
                step(f, Op::Copy(ValueType::Float), &[198, 210], 891);
                step(f, Op::Copy(ValueType::Vec3), &[48, 50], 892);
                step(f, Op::Copy(ValueType::Float), &[203, 198], 893);
                step(f, Op::Copy(ValueType::Vec3), &[53, 48], 894);
                step(f, Op::Copy(ValueType::Vec3), &[57, 47], 895);
                step(f, Op::Copy(ValueType::Bool), &[9, 19], 896);
                step(f, Op::Jump, &[902], 897)
            }
            897 => {
                step(f, Op::LessF, &[203, 210, 13], 898);
                step(f, Op::And, &[20, 13, 16], 899);
                step(f, Op::JumpIfFalse, &[16, 902], 900)
            }
            900 => {
                step(f, Op::Copy(ValueType::Float), &[203, 210], 901);
                step(f, Op::Copy(ValueType::Vec3), &[53, 50], 902);
                902
            }
            902 => {
                step(f, Op::Jump, &[856], 903)
            }
            903 => {
                step(f, Op::JumpIfFalse, &[8, 905], 904)
            }
            904 => {
                step(f, Op::DrawSphere, &[48, 62, 9], 905);
                905
            }
            905 => {
                step(f, Op::GreaterF, &[66, 156, 14], 906);
                step(f, Op::SubF, &[198, 210, 204], 907);
                step(f, Op::DivF, &[204, 66, 184], 908);
                step(f, Op::PowF, &[171, 184, 208], 909);
                step(f, Op::Select(ValueType::Float), &[14, 208, 156, 219], 910);
                step(f, Op::ScaleV, &[50, 219, 54], 911);
                step(f, Op::AddV, &[48, 54, 58], 912);
                step(f, Op::AddF, &[219, 158, 182], 913);
                step(f, Op::DivF, &[158, 182, 196], 914);
                step(f, Op::ScaleV, &[58, 196, 59], 915);
                step(f, Op::Copy(ValueType::Vec3), &[59, 56], 916);
                step(f, Op::Copy(ValueType::Vec3), &[47, 55], 917);
                step(f, Op::Copy(ValueType::Bool), &[19, 12], 918);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 7], 919);
                step(f, Op::BreakTransform, &[7, 45, 6, 46], 920);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 188], 921);
                step(f, Op::SubF, &[158, 188, 202], 922);
                step(f, Op::MaxF, &[202, 156, 211], 923);
                step(f, Op::MulF, &[13, 10, 192], 924);
                step(f, Op::MulF, &[211, 192, 199], 925);
                step(f, Op::ScaleV, &[2, 199, 49], 926);
                step(f, Op::SubV, &[56, 49, 57], 927);
                step(f, Op::Select(ValueType::Vec3), &[12, 57, 45, 53], 928);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 7, 5], 929);
                step(f, Op::BreakTransform, &[5, 19, 2, 18], 930);
                step(f, Op::Copy(ValueType::Float), &[55, 215], 931);
                step(f, Op::Copy(ValueType::Float), &[57, 197], 932);
                step(f, Op::SubV, &[53, 19, 20], 933);
                step(f, Op::DeltaTime, &[200], 934);
                step(f, Op::DivF, &[197, 200, 194], 935);
                step(f, Op::ScaleV, &[20, 194, 51], 936);
                step(f, Op::AddV, &[53, 51, 52], 937);
                step(f, Op::AddV, &[19, 51, 50], 938);
                step(f, Op::SubV, &[45, 50, 48], 939);
                step(f, Op::FloatLerp, &[156, 158, 215, 201], 940);
                step(f, Op::SubF, &[158, 201, 203], 941);
                step(f, Op::ScaleV, &[48, 203, 54], 942);
                step(f, Op::AddV, &[52, 54, 58], 943);
                step(f, Op::MulF, &[215, 200, 198], 944);
                step(f, Op::GreaterF, &[198, 156, 15], 945);
                step(f, Op::DivF, &[201, 198, 210], 946);
                step(f, Op::Select(ValueType::Float), &[15, 210, 158, 204], 947);
                step(f, Op::ScaleV, &[20, 204, 59], 948);
                step(f, Op::SubV, &[58, 59, 47], 949);
                step(f, Op::Copy(ValueType::Vec3), &[47, 49], 950);
                step(f, Op::BreakVector, &[49, 184, 208, 219], 951);
                step(f, Op::ClampF, &[219, 68, 69, 182], 952);
                step(f, Op::MakeVector, &[184, 208, 182, 56], 953);
                step(f, Op::RotationFromNormal, &[55, 196, 202, 2], 954);
                step(f, Op::PerFootRotationFactor, &[17, 117, 118, 192], 955);
                step(f, Op::MulF, &[17, 192, 211], 956);
                step(f, Op::SubF, &[158, 18, 220], 957);
                step(f, Op::MulF, &[211, 220, 199], 958);
                step(f, Op::QuatFromAxisAngle, &[8, 199, 7], 959);
                step(f, Op::MulQ, &[2, 7, 8], 960);
                step(f, Op::Select(ValueType::Quat), &[12, 8, 6, 2], 961);
                step(f, Op::MakeTransform, &[56, 2, 5, 8], 962);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 7, 8], 963);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 7], 964);
                step(f, Op::BreakTransform, &[7, 45, 6, 46], 965);
                step(f, Op::Select(ValueType::Vec3), &[12, 57, 45, 53], 966);
                step(f, Op::MakeTransform, &[53, 1, 5, 5], 967);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 7, 5], 968);
                step(f, Op::GetTransform, &[34, 2, 9, 6], 969);
                step(f, Op::BreakTransform, &[6, 21, 3, 16], 970);
                step(f, Op::BreakVector, &[21, 213, 183, 218], 971);
                step(f, Op::MulF, &[17, 220, 205], 972);
                step(f, Op::QuatFromAxisAngle, &[8, 205, 4], 973);
                step(f, Op::GetTransform, &[0, 2, 9, 4], 974);
                step(f, Op::BreakTransform, &[4, 22, 5, 23], 975);
                step(f, Op::SubV, &[22, 21, 24], 976);
                step(f, Op::BreakVector, &[24, 222, 187, 209], 977);
                step(f, Op::MakeVector, &[222, 187, 156, 25], 978);
                step(f, Op::RotateVector, &[4, 25, 26], 979);
                step(f, Op::BreakVector, &[26, 190, 186, 195], 980);
                step(f, Op::MulF, &[52, 18, 180], 981);
                step(f, Op::MulF, &[180, 207, 214], 982);
                step(f, Op::AddF, &[190, 214, 216], 983);
                step(f, Op::AddF, &[213, 216, 217], 984);
                step(f, Op::AddF, &[183, 186, 221], 985);
                step(f, Op::BreakVector, &[22, 212, 206, 181], 986);
                step(f, Op::SubF, &[181, 58, 189], 987);
                step(f, Op::MakeVector, &[217, 221, 189, 27], 988);
                step(f, Op::MulF, &[9, 157, 191], 989);
                step(f, Op::ScaleV, &[2, 191, 28], 990);
                step(f, Op::AddV, &[27, 28, 29], 991);
                step(f, Op::SubV, &[53, 29, 18], 992);
                step(f, Op::ArraySetAt(Elem::Vec3), &[0, 7, 18], 993);
                step(f, Op::ArraySetAt(Elem::Bool), &[1, 7, 12], 994);
                step(f, Op::GreaterEqualF, &[188, 158, 17], 995);
                step(f, Op::JumpIfFalse, &[17, 1012], 996)
            }
            996 => {
                step(f, Op::MakeVector, &[156, 156, 63, 17], 997);
                step(f, Op::AddV, &[29, 17, 30], 998);
                step(f, Op::RotateVector, &[0, 9, 32], 999);
                step(f, Op::ScaleV, &[32, 67, 33], 1000);
                step(f, Op::AddV, &[30, 33, 34], 1001);
                step(f, Op::SubV, &[29, 17, 31], 1002);
                step(f, Op::AddV, &[31, 33, 35], 1003);
                step(f, Op::SphereTrace, &[34, 35, 62, 18, 36, 37, 185], 1004);
                step(f, Op::SubV, &[36, 29, 38], 1005);
                step(f, Op::ArraySetAt(Elem::Vec3), &[1, 7, 38], 1006);
                step(f, Op::ScaleV, &[32, 64, 39], 1007);
                step(f, Op::AddV, &[34, 39, 40], 1008);
                step(f, Op::AddV, &[35, 39, 41], 1009);
                step(f, Op::SphereTrace, &[40, 41, 62, 11, 42, 43, 193], 1010);
                step(f, Op::SubV, &[42, 29, 44], 1011);
                step(f, Op::ArraySetAt(Elem::Vec3), &[2, 7, 44], 1012);
                1012
            }
            1012 => {
                step(f, Op::JumpIfFalse, &[12, 1014], 1013)
            }
            1013 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 7], 1014);
                1014
            }
            1014 => {
                step(f, Op::ArrayAt(Elem::Float), &[4, 7, 197], 1015);
                step(f, Op::FloatLerp, &[197, 156, 110, 194], 1016);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 7, 13], 1017);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 203], 1018);
                step(f, Op::GreaterEqualF, &[203, 158, 20], 1019);
                step(f, Op::And, &[13, 20, 16], 1020);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 7, 8], 1021);
                step(f, Op::GreaterF, &[26, 156, 14], 1022);
                step(f, Op::InterpolateTransform, &[2, 3, 27, 7], 1023);
                step(f, Op::Select(ValueType::Transform), &[14, 7, 2, 5], 1024);
                step(f, Op::MakeAbsolute, &[8, 5, 6], 1025);
                step(f, Op::BreakTransform, &[6, 19, 7, 51], 1026);
                step(f, Op::RotateVector, &[7, 9, 50], 1027);
                step(f, Op::SubF, &[158, 18, 200], 1028);
                step(f, Op::MulF, &[17, 200, 215], 1029);
                step(f, Op::LimitRotationAroundZ, &[7, 215, 107, 8], 1030);
                step(f, Op::RotateVector, &[8, 9, 48], 1031);
                step(f, Op::CrossV, &[50, 48, 52], 1032);
                step(f, Op::BreakVector, &[52, 198, 201, 210], 1033);
                step(f, Op::DotV, &[50, 48, 204], 1034);
                step(f, Op::Atan2F, &[210, 204, 219], 1035);
                step(f, Op::AbsF, &[219, 182], 1036);
                step(f, Op::Select(ValueType::Float), &[16, 182, 156, 184], 1037);
                step(f, Op::AddF, &[194, 184, 208], 1038);
                step(f, Op::ArraySetAt(Elem::Float), &[4, 7, 208], 1039);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 7, 4], 1040);
                step(f, Op::BreakTransform, &[4, 54, 2, 20], 1041);
                step(f, Op::AddF, &[72, 73, 196], 1042);
                step(f, Op::ClampSpatially, &[19, 54, 156, 196, 58], 1043);
                step(f, Op::MakeTransform, &[58, 8, 5, 8], 1044);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 7, 8], 1045);
                step(f, Op::JumpIfFalse, &[13, 1122], 1046)
            }
            1046 => {
                step(f, Op::JumpIfFalse, &[20, 1048], 1047)
            }
            1047 => {
                step(f, Op::Jump, &[1121], 1048)
            }
            1048 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 6], 1049);
                step(f, Op::BreakTransform, &[6, 59, 6, 47], 1050);
                step(f, Op::SubF, &[158, 203, 202], 1051);
                step(f, Op::MulF, &[13, 10, 192], 1052);
                step(f, Op::MulF, &[202, 192, 211], 1053);
                step(f, Op::ScaleV, &[2, 211, 49], 1054);
                step(f, Op::AddV, &[59, 49, 55], 1055);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1056);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 12], 1057);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 15], 1058);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 12, 4], 1059);
                step(f, Op::BreakTransform, &[4, 56, 3, 46], 1060);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 12, 8], 1061);
                step(f, Op::BreakTransform, &[8, 45, 5, 57], 1062);
                step(f, Op::LessEqualF, &[93, 156, 17], 1063);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 199], 1064);
                step(f, Op::SmoothStepF, &[199, 156, 93, 218], 1065);
                step(f, Op::Select(ValueType::Float), &[17, 158, 218, 220], 1066);
                step(f, Op::LerpV, &[56, 45, 220, 16], 1067);
                step(f, Op::MakeTransform, &[16, 1, 5, 9], 1068);
                step(f, Op::Select(ValueType::Transform), &[15, 4, 9, 10], 1069);
                step(f, Op::MakeAbsolute, &[10, 5, 11], 1070);
                step(f, Op::Select(ValueType::Transform), &[19, 11, 10, 12], 1071);
                step(f, Op::BreakTransform, &[12, 23, 4, 21], 1072);
                step(f, Op::SubF, &[158, 19, 205], 1073);
                step(f, Op::MulF, &[200, 205, 209], 1074);
                step(f, Op::MulF, &[17, 209, 187], 1075);
                step(f, Op::FootAvoidance, &[55, 23, 187, 19, 89, 24], 1076);
                step(f, Op::RemapF, &[18, 92, 158, 156, 158, 9, 222], 1077);
                step(f, Op::LerpV, &[55, 24, 222, 25], 1078);
                step(f, Op::FootAvoidance, &[25, 23, 20, 19, 115, 26], 1079);
                step(f, Op::LerpV, &[25, 26, 19, 22], 1080);
                step(f, Op::MakeTransform, &[22, 6, 5, 13], 1081);
                step(f, Op::BreakTransform, &[13, 27, 7, 28], 1082);
                step(f, Op::MakeVector, &[156, 156, 63, 53], 1083);
                step(f, Op::AddV, &[27, 53, 18], 1084);
                step(f, Op::SubV, &[27, 53, 30], 1085);
                step(f, Op::LineTrace, &[18, 30, 18, 17, 31, 195], 1086);
                step(f, Op::RotateVector, &[7, 8, 33], 1087);
                step(f, Op::FindQuatBetween, &[33, 31, 2], 1088);
                step(f, Op::MulQ, &[2, 7, 8], 1089);
                step(f, Op::MulF, &[61, 60, 180], 1090);
                step(f, Op::AddF, &[180, 71, 207], 1091);
                step(f, Op::NegF, &[207, 190], 1092);
                step(f, Op::MakeVector, &[156, 190, 156, 37], 1093);
                step(f, Op::RotateVector, &[8, 37, 36], 1094);
                step(f, Op::AddV, &[17, 36, 38], 1095);
                step(f, Op::AddV, &[38, 53, 32], 1096);
                step(f, Op::SubV, &[38, 53, 34], 1097);
                step(f, Op::LineTrace, &[32, 34, 11, 35, 39, 214], 1098);
                step(f, Op::BreakVector, &[35, 213, 216, 183], 1099);
                step(f, Op::BreakVector, &[38, 186, 206, 212], 1100);
                step(f, Op::SubF, &[183, 212, 181], 1101);
                step(f, Op::Select(ValueType::Float), &[11, 181, 156, 189], 1102);
                step(f, Op::AddF, &[67, 71, 217], 1103);
                step(f, Op::MakeVector, &[156, 217, 156, 40], 1104);
                step(f, Op::RotateVector, &[8, 40, 41], 1105);
                step(f, Op::AddV, &[17, 41, 43], 1106);
                step(f, Op::AddV, &[43, 53, 29], 1107);
                step(f, Op::SubV, &[43, 53, 42], 1108);
                step(f, Op::LineTrace, &[29, 42, 12, 44, 51, 221], 1109);
                step(f, Op::BreakVector, &[44, 191, 188, 185], 1110);
                step(f, Op::BreakVector, &[43, 193, 197, 215], 1111);
                step(f, Op::SubF, &[185, 215, 198], 1112);
                step(f, Op::Select(ValueType::Float), &[12, 198, 156, 201], 1113);
                step(f, Op::MaxF, &[189, 201, 204], 1114);
                step(f, Op::ClampF, &[204, 156, 70, 210], 1115);
                step(f, Op::MakeVector, &[156, 156, 210, 52], 1116);
                step(f, Op::AddV, &[17, 52, 48], 1117);
                step(f, Op::MakeTransform, &[48, 8, 5, 14], 1118);
                step(f, Op::Select(ValueType::Transform), &[18, 14, 13, 15], 1119);
                step(f, Op::Copy(ValueType::Transform), &[15, 13], 1120);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 7, 13], 1121);
                1121
            }
            1121 => {
                step(f, Op::Jump, &[1238], 1122)
            }
            1122 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 7, 14], 1123);
                step(f, Op::MakeAbsolute, &[14, 5, 15], 1124);
                step(f, Op::BreakTransform, &[15, 50, 2, 20], 1125);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 6], 1126);
                step(f, Op::BreakTransform, &[6, 59, 6, 47], 1127);
                step(f, Op::SubF, &[158, 203, 202], 1128);
                step(f, Op::MulF, &[13, 10, 192], 1129);
                step(f, Op::MulF, &[202, 192, 211], 1130);
                step(f, Op::ScaleV, &[2, 211, 49], 1131);
                step(f, Op::AddV, &[59, 49, 55], 1132);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1133);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 12], 1134);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 15], 1135);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 12, 4], 1136);
                step(f, Op::BreakTransform, &[4, 56, 3, 46], 1137);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 12, 8], 1138);
                step(f, Op::BreakTransform, &[8, 45, 5, 57], 1139);
                step(f, Op::LessEqualF, &[93, 156, 17], 1140);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 199], 1141);
                step(f, Op::SmoothStepF, &[199, 156, 93, 218], 1142);
                step(f, Op::Select(ValueType::Float), &[17, 158, 218, 220], 1143);
                step(f, Op::LerpV, &[56, 45, 220, 16], 1144);
                step(f, Op::MakeTransform, &[16, 1, 5, 9], 1145);
                step(f, Op::Select(ValueType::Transform), &[15, 4, 9, 10], 1146);
                step(f, Op::MakeAbsolute, &[10, 5, 11], 1147);
                step(f, Op::Select(ValueType::Transform), &[19, 11, 10, 12], 1148);
                step(f, Op::BreakTransform, &[12, 23, 4, 21], 1149);
                step(f, Op::SubF, &[158, 19, 205], 1150);
                step(f, Op::MulF, &[200, 205, 209], 1151);
                step(f, Op::MulF, &[17, 209, 187], 1152);
                step(f, Op::FootAvoidance, &[55, 23, 187, 19, 89, 24], 1153);
                step(f, Op::RemapF, &[18, 92, 158, 156, 158, 9, 222], 1154);
                step(f, Op::LerpV, &[55, 24, 222, 25], 1155);
                step(f, Op::FootAvoidance, &[25, 23, 20, 19, 115, 26], 1156);
                step(f, Op::LerpV, &[25, 26, 19, 22], 1157);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 7, 13], 1158);
                step(f, Op::MakeAbsolute, &[13, 5, 14], 1159);
                step(f, Op::BreakTransform, &[14, 19, 7, 58], 1160);
                step(f, Op::ArrayAt(Elem::Float), &[3, 7, 219], 1161);
                step(f, Op::SubF, &[203, 219, 182], 1162);
                step(f, Op::DeltaTime, &[184], 1163);
                step(f, Op::DivF, &[57, 184, 194], 1164);
                step(f, Op::MulF, &[182, 194, 208], 1165);
                step(f, Op::AddF, &[219, 208, 196], 1166);
                step(f, Op::ClampF, &[196, 156, 158, 195], 1167);
                step(f, Op::AddF, &[203, 208, 180], 1168);
                step(f, Op::ClampF, &[180, 156, 158, 207], 1169);
                step(f, Op::AddF, &[195, 207, 190], 1170);
                step(f, Op::MulF, &[190, 157, 214], 1171);
                step(f, Op::SubF, &[158, 214, 213], 1172);
                step(f, Op::GreaterF, &[182, 156, 16], 1173);
                step(f, Op::SubF, &[207, 195, 216], 1174);
                step(f, Op::DivF, &[216, 182, 186], 1175);
                step(f, Op::Select(ValueType::Float), &[16, 186, 158, 206], 1176);
                step(f, Op::MulF, &[213, 206, 183], 1177);
                step(f, Op::MulF, &[88, 183, 212], 1178);
                step(f, Op::Copy(ValueType::Float), &[57, 181], 1179);
                step(f, Op::SubV, &[22, 19, 28], 1180);
                step(f, Op::DeltaTime, &[217], 1181);
                step(f, Op::DivF, &[181, 217, 221], 1182);
                step(f, Op::ScaleV, &[28, 221, 27], 1183);
                step(f, Op::AddV, &[22, 27, 18], 1184);
                step(f, Op::AddV, &[19, 27, 30], 1185);
                step(f, Op::SubV, &[50, 30, 31], 1186);
                step(f, Op::FloatLerp, &[156, 158, 212, 188], 1187);
                step(f, Op::SubF, &[158, 188, 191], 1188);
                step(f, Op::ScaleV, &[31, 191, 33], 1189);
                step(f, Op::AddV, &[18, 33, 37], 1190);
                step(f, Op::MulF, &[212, 217, 193], 1191);
                step(f, Op::GreaterF, &[193, 156, 11], 1192);
                step(f, Op::DivF, &[188, 193, 197], 1193);
                step(f, Op::Select(ValueType::Float), &[11, 197, 158, 185], 1194);
                step(f, Op::ScaleV, &[28, 185, 36], 1195);
                step(f, Op::SubV, &[37, 36, 32], 1196);
                step(f, Op::Copy(ValueType::Vec3), &[32, 34], 1197);
                step(f, Op::MakeTransform, &[34, 6, 5, 15], 1198);
                step(f, Op::BreakTransform, &[15, 39, 8, 35], 1199);
                step(f, Op::MakeVector, &[156, 156, 63, 38], 1200);
                step(f, Op::AddV, &[39, 38, 40], 1201);
                step(f, Op::SubV, &[39, 38, 41], 1202);
                step(f, Op::LineTrace, &[40, 41, 12, 53, 29, 215], 1203);
                step(f, Op::RotateVector, &[8, 8, 42], 1204);
                step(f, Op::FindQuatBetween, &[42, 29, 2], 1205);
                step(f, Op::MulQ, &[2, 8, 7], 1206);
                step(f, Op::MulF, &[61, 60, 198], 1207);
                step(f, Op::AddF, &[198, 71, 189], 1208);
                step(f, Op::NegF, &[189, 201], 1209);
                step(f, Op::MakeVector, &[156, 201, 156, 51], 1210);
                step(f, Op::RotateVector, &[7, 51, 44], 1211);
                step(f, Op::AddV, &[53, 44, 43], 1212);
                step(f, Op::AddV, &[43, 38, 17], 1213);
                step(f, Op::SubV, &[43, 38, 52], 1214);
                step(f, Op::LineTrace, &[17, 52, 18, 48, 20, 204], 1215);
                step(f, Op::BreakVector, &[48, 210, 184, 194], 1216);
                step(f, Op::BreakVector, &[43, 219, 196, 208], 1217);
                step(f, Op::SubF, &[194, 208, 180], 1218);
                step(f, Op::Select(ValueType::Float), &[18, 180, 156, 190], 1219);
                step(f, Op::AddF, &[67, 71, 214], 1220);
                step(f, Op::MakeVector, &[156, 214, 156, 58], 1221);
                step(f, Op::RotateVector, &[7, 58, 19], 1222);
                step(f, Op::AddV, &[53, 19, 27], 1223);
                step(f, Op::AddV, &[27, 38, 30], 1224);
                step(f, Op::SubV, &[27, 38, 50], 1225);
                step(f, Op::LineTrace, &[30, 50, 16, 31, 18, 195], 1226);
                step(f, Op::BreakVector, &[31, 207, 182, 216], 1227);
                step(f, Op::BreakVector, &[27, 186, 206, 213], 1228);
                step(f, Op::SubF, &[216, 213, 183], 1229);
                step(f, Op::Select(ValueType::Float), &[16, 183, 156, 181], 1230);
                step(f, Op::MaxF, &[190, 181, 221], 1231);
                step(f, Op::ClampF, &[221, 156, 70, 191], 1232);
                step(f, Op::MakeVector, &[156, 156, 191, 33], 1233);
                step(f, Op::AddV, &[53, 33, 28], 1234);
                step(f, Op::MakeTransform, &[28, 7, 5, 13], 1235);
                step(f, Op::Select(ValueType::Transform), &[12, 13, 15, 14], 1236);
                step(f, Op::Copy(ValueType::Transform), &[14, 13], 1237);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 7, 13], 1238);
                1238
            }
            1238 => {
                step(f, Op::JumpIfFalse, &[20, 1321], 1239)
            }
            1239 => {
                step(f, Op::JumpIfFalse, &[13, 1241], 1240)
            }
            1240 => {
                step(f, Op::Jump, &[1302], 1241)
            }
            1241 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 7, 15], 1242);
                step(f, Op::BreakTransform, &[15, 36, 2, 37], 1243);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1244);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 12], 1245);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 12, 14], 1246);
                step(f, Op::BreakTransform, &[14, 32, 8, 34], 1247);
                step(f, Op::MakeAbsolute, &[14, 5, 13], 1248);
                step(f, Op::BreakTransform, &[13, 35, 7, 39], 1249);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 199], 1250);
                step(f, Op::SmoothStepF, &[199, 156, 158, 212], 1251);
                step(f, Op::RemapF, &[18, 156, 92, 156, 158, 9, 217], 1252);
                step(f, Op::MulF, &[212, 217, 188], 1253);
                step(f, Op::Select(ValueType::Float), &[19, 188, 156, 193], 1254);
                step(f, Op::LerpV, &[32, 35, 193, 40], 1255);
                step(f, Op::MakeTransform, &[40, 1, 5, 16], 1256);
                step(f, Op::BreakTransform, &[16, 41, 9, 29], 1257);
                step(f, Op::SubF, &[158, 19, 205], 1258);
                step(f, Op::MulF, &[200, 205, 209], 1259);
                step(f, Op::MulF, &[17, 209, 187], 1260);
                step(f, Op::FootAvoidance, &[36, 41, 187, 19, 89, 42], 1261);
                step(f, Op::MakeTransform, &[42, 2, 5, 17], 1262);
                step(f, Op::BreakTransform, &[17, 51, 2, 44], 1263);
                step(f, Op::MakeVector, &[156, 156, 63, 17], 1264);
                step(f, Op::AddV, &[51, 17, 20], 1265);
                step(f, Op::SubV, &[51, 17, 52], 1266);
                step(f, Op::LineTrace, &[20, 52, 11, 48, 43, 197], 1267);
                step(f, Op::RotateVector, &[2, 8, 58], 1268);
                step(f, Op::FindQuatBetween, &[58, 43, 10], 1269);
                step(f, Op::MulQ, &[10, 2, 11], 1270);
                step(f, Op::MulF, &[61, 60, 185], 1271);
                step(f, Op::AddF, &[185, 71, 215], 1272);
                step(f, Op::NegF, &[215, 198], 1273);
                step(f, Op::MakeVector, &[156, 198, 156, 19], 1274);
                step(f, Op::RotateVector, &[11, 19, 38], 1275);
                step(f, Op::AddV, &[48, 38, 18], 1276);
                step(f, Op::AddV, &[18, 17, 30], 1277);
                step(f, Op::SubV, &[18, 17, 50], 1278);
                step(f, Op::LineTrace, &[30, 50, 18, 31, 27, 189], 1279);
                step(f, Op::BreakVector, &[31, 201, 204, 184], 1280);
                step(f, Op::BreakVector, &[18, 210, 196, 219], 1281);
                step(f, Op::SubF, &[184, 219, 194], 1282);
                step(f, Op::Select(ValueType::Float), &[18, 194, 156, 208], 1283);
                step(f, Op::AddF, &[67, 71, 180], 1284);
                step(f, Op::MakeVector, &[156, 180, 156, 33], 1285);
                step(f, Op::RotateVector, &[11, 33, 53], 1286);
                step(f, Op::AddV, &[48, 53, 28], 1287);
                step(f, Op::AddV, &[28, 17, 37], 1288);
                step(f, Op::SubV, &[28, 17, 36], 1289);
                step(f, Op::LineTrace, &[37, 36, 16, 42, 44, 214], 1290);
                step(f, Op::BreakVector, &[42, 195, 182, 207], 1291);
                step(f, Op::BreakVector, &[28, 186, 206, 213], 1292);
                step(f, Op::SubF, &[207, 213, 216], 1293);
                step(f, Op::Select(ValueType::Float), &[16, 216, 156, 183], 1294);
                step(f, Op::MaxF, &[208, 183, 181], 1295);
                step(f, Op::ClampF, &[181, 156, 70, 190], 1296);
                step(f, Op::MakeVector, &[156, 156, 190, 51], 1297);
                step(f, Op::AddV, &[48, 51, 20], 1298);
                step(f, Op::MakeTransform, &[20, 11, 5, 18], 1299);
                step(f, Op::Select(ValueType::Transform), &[11, 18, 17, 19], 1300);
                step(f, Op::Copy(ValueType::Transform), &[19, 17], 1301);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 7, 17], 1302);
                1302
            }
            1302 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 7, 18], 1303);
                step(f, Op::BreakTransform, &[18, 52, 2, 43], 1304);
                step(f, Op::SubV, &[52, 54, 58], 1305);
                step(f, Op::LengthV, &[58, 221], 1306);
                step(f, Op::SubF, &[72, 73, 191], 1307);
                step(f, Op::SubF, &[221, 191, 197], 1308);
                step(f, Op::MulF, &[73, 161, 185], 1309);
                step(f, Op::ClampF, &[197, 156, 185, 215], 1310);
                step(f, Op::MulF, &[215, 215, 198], 1311);
                step(f, Op::MulF, &[73, 172, 189], 1312);
                step(f, Op::DivF, &[198, 189, 201], 1313);
                step(f, Op::SubF, &[221, 201, 204], 1314);
                step(f, Op::DivF, &[204, 221, 196], 1315);
                step(f, Op::ScaleV, &[58, 196, 19], 1316);
                step(f, Op::AddV, &[54, 19, 38], 1317);
                step(f, Op::MakeTransform, &[38, 2, 5, 19], 1318);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 19], 1319);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 19], 1320);
                step(f, Op::Jump, &[1487], 1321)
            }
            1321 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 7, 18], 1322);
                step(f, Op::BreakTransform, &[18, 52, 2, 43], 1323);
                step(f, Op::SubV, &[52, 54, 58], 1324);
                step(f, Op::LengthV, &[58, 221], 1325);
                step(f, Op::SubF, &[72, 73, 191], 1326);
                step(f, Op::SubF, &[221, 191, 197], 1327);
                step(f, Op::MulF, &[73, 161, 185], 1328);
                step(f, Op::ClampF, &[197, 156, 185, 215], 1329);
                step(f, Op::MulF, &[215, 215, 198], 1330);
                step(f, Op::MulF, &[73, 172, 189], 1331);
                step(f, Op::DivF, &[198, 189, 201], 1332);
                step(f, Op::SubF, &[221, 201, 204], 1333);
                step(f, Op::DivF, &[204, 221, 196], 1334);
                step(f, Op::ScaleV, &[58, 196, 19], 1335);
                step(f, Op::AddV, &[54, 19, 38], 1336);
                step(f, Op::MakeTransform, &[38, 2, 5, 19], 1337);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 7, 15], 1338);
                step(f, Op::ClampF, &[203, 156, 158, 210], 1339);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[6, 5], 1340);
                step(f, Op::ArrayReset(Elem::Vec3), &[5], 1341);
                step(f, Op::BreakTransform, &[19, 27, 10, 30], 1342);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 27], 1343);
                step(f, Op::UnitV, &[2, 50], 1344);
                step(f, Op::LengthV, &[2, 184], 1345);
                step(f, Op::RemapF, &[184, 156, 74, 156, 75, 9, 219], 1346);
                step(f, Op::ScaleV, &[50, 219, 31], 1347);
                step(f, Op::SubV, &[27, 31, 18], 1348);
                step(f, Op::MakeVector, &[156, 156, 77, 33], 1349);
                step(f, Op::AddV, &[18, 33, 53], 1350);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 53], 1351);
                step(f, Op::RemapF, &[184, 156, 74, 156, 79, 9, 194], 1352);
                step(f, Op::MakeVector, &[156, 156, 194, 17], 1353);
                step(f, Op::AddV, &[53, 17, 36], 1354);
                step(f, Op::BreakTransform, &[15, 37, 11, 44], 1355);
                step(f, Op::BreakVector, &[37, 180, 214, 182], 1356);
                step(f, Op::BreakVector, &[27, 195, 186, 206], 1357);
                step(f, Op::SubF, &[182, 206, 207], 1358);
                step(f, Op::MaxF, &[207, 156, 213], 1359);
                step(f, Op::MulF, &[213, 81, 216], 1360);
                step(f, Op::MinF, &[216, 82, 183], 1361);
                step(f, Op::AbsF, &[207, 208], 1362);
                step(f, Op::RemapF, &[208, 156, 85, 156, 84, 9, 181], 1363);
                step(f, Op::AddF, &[183, 181, 190], 1364);
                step(f, Op::MakeVector, &[156, 156, 190, 42], 1365);
                step(f, Op::AddV, &[36, 42, 28], 1366);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 28], 1367);
                step(f, Op::RemapF, &[184, 156, 74, 156, 76, 9, 191], 1368);
                step(f, Op::ScaleV, &[50, 191, 48], 1369);
                step(f, Op::AddV, &[37, 48, 51], 1370);
                step(f, Op::MakeVector, &[156, 156, 78, 20], 1371);
                step(f, Op::AddV, &[51, 20, 43], 1372);
                step(f, Op::RemapF, &[184, 156, 74, 156, 80, 9, 185], 1373);
                step(f, Op::MakeVector, &[156, 156, 185, 52], 1374);
                step(f, Op::AddV, &[43, 52, 58], 1375);
                step(f, Op::NegF, &[207, 197], 1376);
                step(f, Op::MaxF, &[197, 156, 215], 1377);
                step(f, Op::MulF, &[215, 83, 189], 1378);
                step(f, Op::AddF, &[189, 181, 198], 1379);
                step(f, Op::MakeVector, &[156, 156, 198, 19], 1380);
                step(f, Op::AddV, &[58, 19, 54], 1381);
                step(f, Op::LerpV, &[28, 54, 157, 38], 1382);
                step(f, Op::GetTransform, &[35, 2, 9, 17], 1383);
                step(f, Op::BreakTransform, &[17, 30, 2, 31], 1384);
                step(f, Op::BreakVector, &[30, 201, 204, 221], 1385);
                step(f, Op::SubF, &[158, 18, 196], 1386);
                step(f, Op::MulF, &[86, 196, 219], 1387);
                step(f, Op::MulF, &[17, 219, 194], 1388);
                step(f, Op::QuatFromAxisAngle, &[8, 194, 2], 1389);
                step(f, Op::SubV, &[38, 30, 18], 1390);
                step(f, Op::BreakVector, &[18, 180, 214, 186], 1391);
                step(f, Op::MakeVector, &[180, 214, 156, 33], 1392);
                step(f, Op::RotateVector, &[2, 33, 17], 1393);
                step(f, Op::BreakVector, &[17, 195, 182, 206], 1394);
                step(f, Op::AddF, &[201, 195, 213], 1395);
                step(f, Op::AddF, &[204, 182, 216], 1396);
                step(f, Op::BreakVector, &[38, 208, 183, 190], 1397);
                step(f, Op::MakeVector, &[213, 216, 190, 53], 1398);
                step(f, Op::DistanceV, &[27, 37, 191], 1399);
                step(f, Op::RemapF, &[191, 161, 173, 156, 158, 9, 184], 1400);
                step(f, Op::LerpV, &[38, 53, 184, 44], 1401);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 44], 1402);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 54], 1403);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 43], 1404);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 37], 1405);
                step(f, Op::JumpIfFalse, &[8, 1407], 1406)
            }
            1406 => {
                step(f, Op::DrawSpline, &[5, 2, 5, 157, 11], 1407);
                1407
            }
            1407 => {
                step(f, Op::Spline, &[5, 210, 2, 36, 42], 1408);
                step(f, Op::SlerpQ, &[10, 11, 210, 2], 1409);
                step(f, Op::MulF, &[210, 166, 185], 1410);
                step(f, Op::SinF, &[185, 207], 1411);
                step(f, Op::SmoothStepF, &[210, 156, 100, 197], 1412);
                step(f, Op::MulF, &[207, 197, 215], 1413);
                step(f, Op::MulF, &[215, 87, 181], 1414);
                step(f, Op::SlerpQ, &[2, 1, 181, 10], 1415);
                step(f, Op::MakeTransform, &[36, 10, 5, 18], 1416);
                step(f, Op::Copy(ValueType::Transform), &[18, 19], 1417);
                step(f, Op::BreakTransform, &[19, 50, 11, 48], 1418);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1419);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 12], 1420);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 12, 14], 1421);
                step(f, Op::BreakTransform, &[14, 32, 8, 34], 1422);
                step(f, Op::GreaterF, &[26, 156, 14], 1423);
                step(f, Op::InterpolateTransform, &[2, 3, 27, 7], 1424);
                step(f, Op::Select(ValueType::Transform), &[14, 7, 2, 5], 1425);
                step(f, Op::MakeAbsolute, &[14, 5, 13], 1426);
                step(f, Op::BreakTransform, &[13, 35, 7, 39], 1427);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 199], 1428);
                step(f, Op::SmoothStepF, &[199, 156, 158, 212], 1429);
                step(f, Op::RemapF, &[18, 156, 92, 156, 158, 9, 217], 1430);
                step(f, Op::MulF, &[212, 217, 188], 1431);
                step(f, Op::Select(ValueType::Float), &[19, 188, 156, 193], 1432);
                step(f, Op::LerpV, &[32, 35, 193, 40], 1433);
                step(f, Op::MakeTransform, &[40, 1, 5, 16], 1434);
                step(f, Op::BreakTransform, &[16, 41, 9, 29], 1435);
                step(f, Op::SubF, &[158, 18, 200], 1436);
                step(f, Op::SubF, &[158, 19, 205], 1437);
                step(f, Op::MulF, &[200, 205, 209], 1438);
                step(f, Op::MulF, &[17, 209, 187], 1439);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 12], 1440);
                step(f, Op::Select(ValueType::Float), &[12, 90, 156, 189], 1441);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 203], 1442);
                step(f, Op::ClampF, &[203, 156, 158, 210], 1443);
                step(f, Op::MulF, &[210, 166, 198], 1444);
                step(f, Op::SinF, &[198, 221], 1445);
                step(f, Op::MulF, &[221, 221, 196], 1446);
                step(f, Op::MulF, &[189, 196, 219], 1447);
                step(f, Op::AddF, &[89, 219, 194], 1448);
                step(f, Op::FootAvoidance, &[50, 41, 187, 19, 194, 20], 1449);
                step(f, Op::SubV, &[20, 50, 51], 1450);
                step(f, Op::LengthV, &[51, 186], 1451);
                step(f, Op::AddF, &[186, 219, 180], 1452);
                step(f, Op::DivF, &[186, 180, 214], 1453);
                step(f, Op::MulF, &[114, 161, 206], 1454);
                step(f, Op::LessEqualF, &[186, 206, 13], 1455);
                step(f, Op::MulF, &[114, 172, 195], 1456);
                step(f, Op::DivF, &[186, 195, 201], 1457);
                step(f, Op::DivF, &[114, 186, 182], 1458);
                step(f, Op::SubF, &[158, 182, 204], 1459);
                step(f, Op::Select(ValueType::Float), &[13, 201, 204, 183], 1460);
                step(f, Op::GreaterF, &[114, 156, 18], 1461);
                step(f, Op::Select(ValueType::Float), &[18, 19, 156, 208], 1462);
                step(f, Op::LerpF, &[214, 183, 208, 190], 1463);
                step(f, Op::LessF, &[199, 203, 16], 1464);
                step(f, Op::LessEqualF, &[91, 156, 11], 1465);
                step(f, Op::SmoothStepF, &[199, 156, 91, 213], 1466);
                step(f, Op::MulF, &[213, 18, 216], 1467);
                step(f, Op::SubF, &[158, 216, 191], 1468);
                step(f, Op::Select(ValueType::Float), &[11, 158, 191, 184], 1469);
                step(f, Op::Select(ValueType::Float), &[16, 184, 158, 185], 1470);
                step(f, Op::MulF, &[190, 185, 197], 1471);
                step(f, Op::SmoothStepF, &[210, 156, 91, 207], 1472);
                step(f, Op::Select(ValueType::Float), &[11, 158, 207, 215], 1473);
                step(f, Op::MulF, &[197, 215, 181], 1474);
                step(f, Op::ScaleV, &[51, 181, 52], 1475);
                step(f, Op::AddV, &[50, 52, 19], 1476);
                step(f, Op::MulF, &[6, 147, 212], 1477);
                step(f, Op::MulF, &[212, 196, 217], 1478);
                step(f, Op::MakeVector, &[156, 156, 217, 58], 1479);
                step(f, Op::AddV, &[19, 58, 28], 1480);
                step(f, Op::MakeTransform, &[28, 11, 5, 15], 1481);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 15], 1482);
                step(f, Op::ScaleV, &[51, 197, 31], 1483);
                step(f, Op::AddV, &[50, 31, 30], 1484);
                step(f, Op::AddV, &[30, 58, 18], 1485);
                step(f, Op::MakeTransform, &[18, 11, 5, 17], 1486);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 17], 1487);
                1487
            }
            1487 => {
                step(f, Op::JumpIfFalse, &[14, 1510], 1488)
            }
            1488 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 7, 18], 1489);
                step(f, Op::BreakTransform, &[18, 33, 2, 17], 1490);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 7, 19], 1491);
                step(f, Op::BreakTransform, &[19, 27, 10, 38], 1492);
                step(f, Op::MulF, &[26, 26, 188], 1493);
                step(f, Op::LerpV, &[33, 27, 188, 53], 1494);
                step(f, Op::SubF, &[158, 26, 193], 1495);
                step(f, Op::MulF, &[26, 193, 198], 1496);
                step(f, Op::MulF, &[149, 161, 221], 1497);
                step(f, Op::MulF, &[198, 221, 189], 1498);
                step(f, Op::MakeVector, &[156, 156, 189, 44], 1499);
                step(f, Op::AddV, &[53, 44, 54], 1500);
                step(f, Op::SlerpQ, &[2, 10, 26, 8], 1501);
                step(f, Op::MakeTransform, &[54, 8, 5, 7], 1502);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 7], 1503);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 7, 18], 1504);
                step(f, Op::BreakTransform, &[18, 33, 2, 17], 1505);
                step(f, Op::LerpV, &[33, 27, 188, 53], 1506);
                step(f, Op::AddV, &[53, 44, 54], 1507);
                step(f, Op::SlerpQ, &[2, 10, 26, 8], 1508);
                step(f, Op::MakeTransform, &[54, 8, 5, 7], 1509);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 7], 1510);
                1510
            }
            1510 => {
                step(f, Op::GreaterEqualF, &[203, 158, 20], 1511);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 7, 20], 1512);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 6], 1513);
                step(f, Op::BreakTransform, &[6, 59, 6, 47], 1514);
                step(f, Op::SubF, &[158, 203, 202], 1515);
                step(f, Op::MulF, &[13, 10, 192], 1516);
                step(f, Op::MulF, &[202, 192, 211], 1517);
                step(f, Op::ScaleV, &[2, 211, 49], 1518);
                step(f, Op::AddV, &[59, 49, 55], 1519);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1520);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 12], 1521);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 15], 1522);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 12, 4], 1523);
                step(f, Op::BreakTransform, &[4, 56, 3, 46], 1524);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 12, 8], 1525);
                step(f, Op::BreakTransform, &[8, 45, 5, 57], 1526);
                step(f, Op::LessEqualF, &[93, 156, 17], 1527);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 199], 1528);
                step(f, Op::SmoothStepF, &[199, 156, 93, 218], 1529);
                step(f, Op::Select(ValueType::Float), &[17, 158, 218, 220], 1530);
                step(f, Op::LerpV, &[56, 45, 220, 16], 1531);
                step(f, Op::MakeTransform, &[16, 1, 5, 9], 1532);
                step(f, Op::Select(ValueType::Transform), &[15, 4, 9, 10], 1533);
                step(f, Op::MakeAbsolute, &[10, 5, 11], 1534);
                step(f, Op::Select(ValueType::Transform), &[19, 11, 10, 12], 1535);
                step(f, Op::BreakTransform, &[12, 23, 4, 21], 1536);
                step(f, Op::SubF, &[158, 19, 205], 1537);
                step(f, Op::MulF, &[200, 205, 209], 1538);
                step(f, Op::MulF, &[17, 209, 187], 1539);
                step(f, Op::FootAvoidance, &[55, 23, 187, 19, 89, 24], 1540);
                step(f, Op::RemapF, &[18, 92, 158, 156, 158, 9, 222], 1541);
                step(f, Op::LerpV, &[55, 24, 222, 25], 1542);
                step(f, Op::FootAvoidance, &[25, 23, 20, 19, 115, 26], 1543);
                step(f, Op::LerpV, &[25, 26, 19, 22], 1544);
                step(f, Op::MakeTransform, &[22, 1, 5, 14], 1545);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 7, 14], 1546);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 7, 13], 1547);
                step(f, Op::BreakTransform, &[13, 43, 7, 37], 1548);
                step(f, Op::MakeVector, &[156, 156, 58, 42], 1549);
                step(f, Op::AddV, &[43, 42, 36], 1550);
                step(f, Op::GetTransform, &[0, 2, 9, 16], 1551);
                step(f, Op::BreakTransform, &[16, 48, 9, 34], 1552);
                step(f, Op::MakeTransform, &[36, 9, 5, 15], 1553);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 7, 20], 1554);
                step(f, Op::GetTransform, &[20, 2, 9, 17], 1555);
                step(f, Op::BreakTransform, &[17, 39, 11, 32], 1556);
                step(f, Op::SubV, &[39, 48, 35], 1557);
                step(f, Op::AddV, &[36, 35, 40], 1558);
                step(f, Op::FootPivots, &[36, 40, 60, 59, 58, 61, 29, 41, 20], 1559);
                step(f, Op::GetParent, &[0, 18], 1560);
                step(f, Op::GetParent, &[18, 19], 1561);
                step(f, Op::GetTransform, &[19, 2, 10, 19], 1562);
                step(f, Op::BreakTransform, &[19, 52, 2, 19], 1563);
                step(f, Op::SubV, &[43, 52, 28], 1564);
                step(f, Op::DotV, &[28, 9, 194], 1565);
                step(f, Op::RemapF, &[194, 95, 94, 96, 156, 9, 219], 1566);
                step(f, Op::LengthV, &[2, 180], 1567);
                step(f, Op::RemapF, &[180, 156, 106, 156, 158, 9, 206], 1568);
                step(f, Op::MulF, &[219, 206, 195], 1569);
                step(f, Op::QuatFromAxisAngle, &[12, 195, 10], 1570);
                step(f, Op::RotateAroundPoint, &[15, 29, 10, 18], 1571);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 186], 1572);
                step(f, Op::SmoothStepF, &[186, 156, 100, 182], 1573);
                step(f, Op::SubF, &[158, 186, 201], 1574);
                step(f, Op::SmoothStepF, &[201, 156, 100, 204], 1575);
                step(f, Op::MulF, &[182, 204, 183], 1576);
                step(f, Op::LerpF, &[99, 158, 183, 208], 1577);
                step(f, Op::MulF, &[195, 208, 214], 1578);
                step(f, Op::QuatFromAxisAngle, &[12, 214, 8], 1579);
                step(f, Op::SubV, &[41, 29, 51], 1580);
                step(f, Op::RotateVector, &[8, 51, 31], 1581);
                step(f, Op::AddV, &[29, 31, 50], 1582);
                step(f, Op::RemapF, &[194, 97, 95, 98, 156, 9, 213], 1583);
                step(f, Op::MulF, &[213, 206, 216], 1584);
                step(f, Op::QuatFromAxisAngle, &[12, 216, 6], 1585);
                step(f, Op::RotateAroundPoint, &[18, 50, 6, 7], 1586);
                step(f, Op::RemapF, &[194, 101, 102, 156, 103, 9, 191], 1587);
                step(f, Op::RotateVector, &[7, 8, 30], 1588);
                step(f, Op::BreakVector, &[30, 184, 185, 190], 1589);
                step(f, Op::CosF, &[105, 210], 1590);
                step(f, Op::CosF, &[104, 207], 1591);
                step(f, Op::RemapF, &[190, 210, 207, 156, 158, 9, 215], 1592);
                step(f, Op::MulF, &[206, 215, 181], 1593);
                step(f, Op::MulF, &[191, 181, 196], 1594);
                step(f, Op::QuatFromAxisAngle, &[12, 196, 3], 1595);
                step(f, Op::RotateAroundPoint, &[7, 20, 3, 6], 1596);
                step(f, Op::SubF, &[158, 18, 212], 1597);
                step(f, Op::MulF, &[17, 212, 217], 1598);
                step(f, Op::LimitRotationAroundZ, &[7, 217, 107, 5], 1599);
                step(f, Op::RotateAroundPoint, &[6, 43, 5, 8], 1600);
                step(f, Op::BreakTransform, &[8, 58, 4, 18], 1601);
                step(f, Op::ArrayAt(Elem::Float), &[4, 7, 197], 1602);
                step(f, Op::MulF, &[197, 108, 193], 1603);
                step(f, Op::MulF, &[193, 109, 198], 1604);
                step(f, Op::AddF, &[193, 109, 221], 1605);
                step(f, Op::DivF, &[198, 221, 189], 1606);
                step(f, Op::MakeVector, &[156, 156, 189, 38], 1607);
                step(f, Op::AddV, &[58, 38, 17], 1608);
                step(f, Op::MakeTransform, &[17, 4, 18, 4], 1609);
                step(f, Op::ArraySetAt(Elem::Transform), &[7, 7, 4], 1610);
                step(f, Op::JumpIfFalse, &[8, 1615], 1611)
            }
            1611 => {
                step(f, Op::DrawPoint, &[20, 174, 12], 1612);
                step(f, Op::DrawPoint, &[29, 174, 9], 1613);
                step(f, Op::DrawPoint, &[50, 174, 8], 1614);
                step(f, Op::DrawTransform, &[13, 173, 157], 1615);
                1615
            }
            1615 => {
                step(f, Op::Jump, &[687], 1616)
            }
            1616 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1617);
                step(f, Op::Copy(ValueType::Int), &[2, 8], 1618);
                1618
            }
            1618 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 8, 1, 6, 9, 1657], 1619)
            }
            1619 => {
                step(f, Op::GetParent, &[1, 22], 1620);
                step(f, Op::GetParent, &[22, 23], 1621);
                step(f, Op::GetParent, &[23, 24], 1622);
                step(f, Op::GetTransform, &[24, 2, 10, 9], 1623);
                step(f, Op::BreakTransform, &[9, 27, 9, 33], 1624);
                step(f, Op::LengthV, &[1, 188], 1625);
                step(f, Op::ClavicleOffset, &[15, 188, 121, 125, 203], 1626);
                step(f, Op::MakeVector, &[156, 156, 203, 44], 1627);
                step(f, Op::AddV, &[27, 44, 53], 1628);
                step(f, Op::MakeTransform, &[53, 9, 5, 5], 1629);
                step(f, Op::SetTransform, &[24, 5, 2, 9, 158], 1630);
                step(f, Op::GetTransform, &[1, 2, 10, 10], 1631);
                step(f, Op::GetTransform, &[23, 2, 10, 11], 1632);
                step(f, Op::BreakTransform, &[11, 54, 11, 47], 1633);
                step(f, Op::Equals(Elem::Int), &[6, 2, 12], 1634);
                step(f, Op::Select(ValueType::Int), &[12, 3, 2, 11], 1635);
                step(f, Op::ArrayAt(Elem::Float), &[0, 11, 192], 1636);
                step(f, Op::ArmSwingRotation, &[192, 1, 0, 122, 165, 175, 158, 121, 119, 120, 123, 165, 158, 202], 1637);
                step(f, Op::QuatFromAxisAngle, &[12, 202, 2], 1638);
                step(f, Op::RotateAroundPoint, &[10, 54, 2, 12], 1639);
                step(f, Op::BreakTransform, &[12, 49, 10, 59], 1640);
                step(f, Op::RemapF, &[188, 156, 121, 156, 124, 9, 211], 1641);
                step(f, Op::MakeVector, &[156, 156, 211, 46], 1642);
                step(f, Op::AddV, &[49, 46, 57], 1643);
                step(f, Op::MakeTransform, &[57, 10, 5, 14], 1644);
                step(f, Op::Select(ValueType::Vec3), &[12, 13, 12, 45], 1645);
                step(f, Op::Select(ValueType::Vec3), &[12, 9, 14, 56], 1646);
                step(f, Op::ArrayAt(Elem::Vec3), &[4, 6, 16], 1647);
                step(f, Op::TwoBoneIK, &[23, 22, 1, 14, 45, 56, 16, 2, 158, 10, 176, 177, 9, 13, 199], 1648);
                step(f, Op::JumpIfFalse, &[8, 1656], 1649)
            }
            1649 => {
                step(f, Op::GetTransform, &[23, 2, 10, 11], 1650);
                step(f, Op::BreakTransform, &[11, 54, 11, 47], 1651);
                step(f, Op::GetTransform, &[1, 2, 10, 10], 1652);
                step(f, Op::RotateAroundPoint, &[10, 54, 2, 12], 1653);
                step(f, Op::BreakTransform, &[12, 49, 10, 59], 1654);
                step(f, Op::AddV, &[49, 46, 57], 1655);
                step(f, Op::DrawLine, &[54, 57, 157, 9], 1656);
                1656
            }
            1656 => {
                step(f, Op::Jump, &[1618], 1657)
            }
            1657 => {
                step(f, Op::NegF, &[5, 218], 1658);
                step(f, Op::MakeVector, &[156, 156, 218, 21], 1659);
                step(f, Op::MakeTransform, &[21, 1, 5, 16], 1660);
                step(f, Op::SetTransform, &[36, 16, 2, 9, 158], 1661);
                step(f, Op::Copy(ValueType::Float), &[163, 220], 1662);
                step(f, Op::Copy(ValueType::Bool), &[10, 18], 1663);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 11], 1664);
                step(f, Op::Copy(ValueType::Int), &[2, 12], 1665);
                step(f, Op::MakeVector, &[156, 156, 63, 24], 1666);
                1666
            }
            1666 => {
                step(f, Op::ForEachNext(Elem::Transform), &[11, 12, 17, 7, 10, 1678], 1667)
            }
            1667 => {
                step(f, Op::BreakTransform, &[17, 55, 8, 23], 1668);
                step(f, Op::AddV, &[55, 24, 25], 1669);
                step(f, Op::SubV, &[55, 24, 26], 1670);
                step(f, Op::SphereTrace, &[25, 26, 62, 16, 22, 37, 200], 1671);
                step(f, Op::BreakVector, &[22, 205, 209, 187], 1672);
                step(f, Op::LessF, &[187, 220, 11], 1673);
                step(f, Op::And, &[16, 11, 14], 1674);
                step(f, Op::JumpIfFalse, &[14, 1677], 1675)
            }
            1675 => {
                step(f, Op::Copy(ValueType::Float), &[187, 220], 1676);
                step(f, Op::Copy(ValueType::Bool), &[9, 18], 1677);
                1677
            }
            1677 => {
                step(f, Op::Jump, &[1666], 1678)
            }
            1678 => {
                step(f, Op::Select(ValueType::Float), &[18, 220, 156, 222], 1679);
                step(f, Op::ClampF, &[222, 68, 69, 180], 1680);
                step(f, Op::Copy(ValueType::Float), &[180, 219], 1681);
                step(f, Op::SubF, &[158, 26, 186], 1682);
                step(f, Op::MulF, &[219, 186, 201], 1683);
                step(f, Op::SubF, &[158, 146, 182], 1684);
                step(f, Op::MulF, &[5, 182, 204], 1685);
                step(f, Op::AddF, &[201, 204, 183], 1686);
                step(f, Op::MakeVector, &[21, 156, 156, 42], 1687);
                step(f, Op::MakeVector, &[183, 156, 156, 34], 1688);
                step(f, Op::Select(ValueType::Float), &[2, 183, 22, 195], 1689);
                step(f, Op::MakeVector, &[195, 156, 156, 32], 1690);
                step(f, Op::Copy(ValueType::Float), &[56, 208], 1691);
                step(f, Op::Copy(ValueType::Float), &[57, 214], 1692);
                step(f, Op::SubV, &[34, 32, 39], 1693);
                step(f, Op::DeltaTime, &[213], 1694);
                step(f, Op::DivF, &[214, 213, 216], 1695);
                step(f, Op::ScaleV, &[39, 216, 48], 1696);
                step(f, Op::AddV, &[34, 48, 35], 1697);
                step(f, Op::AddV, &[32, 48, 36], 1698);
                step(f, Op::SubV, &[42, 36, 40], 1699);
                step(f, Op::FloatLerp, &[156, 158, 208, 194], 1700);
                step(f, Op::SubF, &[158, 194, 184], 1701);
                step(f, Op::ScaleV, &[40, 184, 19], 1702);
                step(f, Op::AddV, &[35, 19, 52], 1703);
                step(f, Op::MulF, &[208, 213, 185], 1704);
                step(f, Op::GreaterF, &[185, 156, 20], 1705);
                step(f, Op::DivF, &[194, 185, 190], 1706);
                step(f, Op::Select(ValueType::Float), &[20, 190, 158, 207], 1707);
                step(f, Op::ScaleV, &[39, 207, 28], 1708);
                step(f, Op::SubV, &[52, 28, 41], 1709);
                step(f, Op::Copy(ValueType::Vec3), &[41, 51], 1710);
                step(f, Op::BreakVector, &[51, 210, 206, 215], 1711);
                step(f, Op::Select(ValueType::Float), &[1, 183, 210, 181], 1712);
                step(f, Op::Copy(ValueType::Float), &[181, 21], 1713);
                step(f, Op::Copy(ValueType::Float), &[183, 22], 1714);
                step(f, Op::GetTransform, &[37, 2, 9, 19], 1715);
                step(f, Op::BreakTransform, &[19, 31, 6, 30], 1716);
                step(f, Op::PelvisLean, &[1, 128, 133, 134, 191, 196], 1717);
                step(f, Op::LengthV, &[2, 212], 1718);
                step(f, Op::RemapF, &[212, 156, 128, 156, 126, 9, 217], 1719);
                step(f, Op::MulF, &[18, 127, 197], 1720);
                step(f, Op::SubF, &[158, 197, 193], 1721);
                step(f, Op::MulF, &[217, 193, 198], 1722);
                step(f, Op::MulF, &[15, 178, 221], 1723);
                step(f, Op::SinF, &[221, 189], 1724);
                step(f, Op::MulF, &[198, 189, 203], 1725);
                step(f, Op::MulF, &[203, 186, 192], 1726);
                step(f, Op::AddF, &[192, 21, 202], 1727);
                step(f, Op::SubF, &[202, 5, 188], 1728);
                step(f, Op::MakeVector, &[156, 196, 188, 43], 1729);
                step(f, Op::AddV, &[31, 43, 38], 1730);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 2, 15], 1731);
                step(f, Op::BreakTransform, &[15, 58, 3, 17], 1732);
                step(f, Op::BreakVector, &[58, 211, 199, 218], 1733);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 3, 18], 1734);
                step(f, Op::BreakTransform, &[18, 18, 7, 20], 1735);
                step(f, Op::BreakVector, &[18, 200, 205, 209], 1736);
                step(f, Op::SubF, &[218, 209, 187], 1737);
                step(f, Op::PelvisSideLean, &[187, 135, 136, 220], 1738);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 2, 7], 1739);
                step(f, Op::BreakTransform, &[7, 29, 5, 50], 1740);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 3, 6], 1741);
                step(f, Op::BreakTransform, &[6, 33, 4, 27], 1742);
                step(f, Op::SlerpQ, &[5, 4, 157, 9], 1743);
                step(f, Op::EulerFromQuat, &[9, 2, 44], 1744);
                step(f, Op::BreakVector, &[44, 222, 180, 219], 1745);
                step(f, Op::RemapF, &[212, 129, 128, 156, 130, 9, 182], 1746);
                step(f, Op::SubV, &[58, 18, 53], 1747);
                step(f, Op::RotateVector, &[0, 9, 16], 1748);
                step(f, Op::DotV, &[53, 16, 201], 1749);
                step(f, Op::MulF, &[182, 201, 204], 1750);
                step(f, Op::AddF, &[219, 204, 195], 1751);
                step(f, Op::MakeVector, &[191, 220, 195, 45], 1752);
                step(f, Op::QuatFromEuler, &[45, 2, 11], 1753);
                step(f, Op::MakeTransform, &[38, 11, 5, 8], 1754);
                step(f, Op::SetTransform, &[38, 8, 2, 9, 158], 1755);
                step(f, Op::GetTransform, &[39, 3, 9, 4], 1756);
                step(f, Op::BreakTransform, &[4, 56, 2, 47], 1757);
                step(f, Op::QuatFromAxisAngle, &[8, 204, 10], 1758);
                step(f, Op::DivF, &[131, 174, 214], 1759);
                step(f, Op::QuatScale, &[10, 214, 8], 1760);
                step(f, Op::MulQ, &[2, 8, 6], 1761);
                step(f, Op::MakeTransform, &[56, 6, 5, 13], 1762);
                step(f, Op::SetTransform, &[40, 13, 3, 9, 158], 1763);
                step(f, Op::GetTransform, &[41, 3, 9, 9], 1764);
                step(f, Op::BreakTransform, &[9, 59, 3, 46], 1765);
                step(f, Op::MulQ, &[3, 8, 7], 1766);
                step(f, Op::MakeTransform, &[59, 7, 5, 5], 1767);
                step(f, Op::SetTransform, &[42, 5, 3, 9, 158], 1768);
                step(f, Op::GetTransform, &[43, 3, 9, 14], 1769);
                step(f, Op::BreakTransform, &[14, 49, 4, 54], 1770);
                step(f, Op::MulQ, &[4, 8, 5], 1771);
                step(f, Op::MakeTransform, &[49, 5, 5, 11], 1772);
                step(f, Op::SetTransform, &[44, 11, 3, 9, 158], 1773);
                step(f, Op::GetTransform, &[45, 3, 9, 10], 1774);
                step(f, Op::BreakTransform, &[10, 57, 9, 21], 1775);
                step(f, Op::QuatScale, &[10, 132, 11], 1776);
                step(f, Op::MulQ, &[9, 11, 2], 1777);
                step(f, Op::MakeTransform, &[57, 2, 5, 12], 1778);
                step(f, Op::SetTransform, &[46, 12, 3, 9, 158], 1779);
                step(f, Op::Or, &[1, 2, 17], 1780);
                step(f, Op::Copy(ValueType::Float), &[156, 216], 1781);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1782);
                step(f, Op::Copy(ValueType::Int), &[2, 9], 1783);
                1783
            }
            1783 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 9, 25, 11, 6, 1830], 1784)
            }
            1784 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 11, 15], 1785);
                step(f, Op::GetParent, &[25, 26], 1786);
                step(f, Op::GetParent, &[26, 27], 1787);
                step(f, Op::GetTransform, &[27, 2, 10, 16], 1788);
                step(f, Op::BreakTransform, &[16, 23, 6, 55], 1789);
                step(f, Op::BreakVector, &[23, 184, 208, 213], 1790);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 11, 17], 1791);
                step(f, Op::BreakTransform, &[17, 25, 3, 26], 1792);
                step(f, Op::BreakVector, &[25, 185, 194, 190], 1793);
                step(f, Op::ArrayAt(Elem::Float), &[1, 11, 207], 1794);
                step(f, Op::MulF, &[207, 137, 206], 1795);
                step(f, Op::MulF, &[206, 206, 215], 1796);
                step(f, Op::SubF, &[184, 185, 210], 1797);
                step(f, Op::SubF, &[208, 194, 181], 1798);
                step(f, Op::MakeVector, &[210, 181, 156, 37], 1799);
                step(f, Op::DotV, &[37, 37, 183], 1800);
                step(f, Op::SubF, &[215, 183, 197], 1801);
                step(f, Op::SqrtF, &[197, 193], 1802);
                step(f, Op::AddF, &[190, 193, 217], 1803);
                step(f, Op::SubF, &[213, 217, 221], 1804);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 11, 19], 1805);
                step(f, Op::BreakTransform, &[19, 22, 7, 24], 1806);
                step(f, Op::BreakVector, &[22, 189, 198, 186], 1807);
                step(f, Op::AddF, &[186, 58, 203], 1808);
                step(f, Op::MinF, &[190, 203, 192], 1809);
                step(f, Op::AddF, &[192, 193, 202], 1810);
                step(f, Op::SubF, &[213, 202, 188], 1811);
                step(f, Op::Equals(Elem::Int), &[11, 2, 19], 1812);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 8], 1813);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 8, 12], 1814);
                step(f, Op::ArrayAt(Elem::Float), &[2, 8, 196], 1815);
                step(f, Op::RemapF, &[196, 157, 158, 156, 158, 9, 199], 1816);
                step(f, Op::RemapF, &[196, 156, 140, 158, 156, 9, 211], 1817);
                step(f, Op::MaxF, &[199, 211, 200], 1818);
                step(f, Op::Select(ValueType::Float), &[12, 158, 200, 205], 1819);
                step(f, Op::LerpF, &[221, 188, 205, 209], 1820);
                step(f, Op::ArrayAt(Elem::Float), &[2, 11, 218], 1821);
                step(f, Op::RemapF, &[218, 157, 158, 156, 158, 9, 187], 1822);
                step(f, Op::MulF, &[209, 187, 180], 1823);
                step(f, Op::RemapF, &[218, 156, 140, 158, 156, 9, 222], 1824);
                step(f, Op::MulF, &[221, 222, 212], 1825);
                step(f, Op::MaxF, &[180, 212, 182], 1826);
                step(f, Op::Select(ValueType::Float), &[15, 221, 182, 201], 1827);
                step(f, Op::MaxF, &[216, 201, 219], 1828);
                step(f, Op::Copy(ValueType::Float), &[219, 216], 1829);
                step(f, Op::Jump, &[1783], 1830)
            }
            1830 => {
                step(f, Op::ClampF, &[216, 156, 138, 191], 1831);
                step(f, Op::Copy(ValueType::Float), &[191, 195], 1832);
                step(f, Op::MakeVector, &[23, 156, 156, 34], 1833);
                step(f, Op::MakeVector, &[195, 156, 156, 32], 1834);
                step(f, Op::MakeVector, &[24, 156, 156, 48], 1835);
                step(f, Op::GreaterF, &[195, 23, 13], 1836);
                step(f, Op::Select(ValueType::Float), &[13, 142, 139, 220], 1837);
                step(f, Op::Copy(ValueType::Float), &[57, 204], 1838);
                step(f, Op::SubV, &[32, 48, 36], 1839);
                step(f, Op::DeltaTime, &[214], 1840);
                step(f, Op::DivF, &[204, 214, 207], 1841);
                step(f, Op::ScaleV, &[36, 207, 42], 1842);
                step(f, Op::AddV, &[32, 42, 40], 1843);
                step(f, Op::AddV, &[48, 42, 19], 1844);
                step(f, Op::SubV, &[34, 19, 35], 1845);
                step(f, Op::FloatLerp, &[156, 158, 220, 206], 1846);
                step(f, Op::SubF, &[158, 206, 184], 1847);
                step(f, Op::ScaleV, &[35, 184, 39], 1848);
                step(f, Op::AddV, &[40, 39, 28], 1849);
                step(f, Op::MulF, &[220, 214, 185], 1850);
                step(f, Op::GreaterF, &[185, 156, 11], 1851);
                step(f, Op::DivF, &[206, 185, 194], 1852);
                step(f, Op::Select(ValueType::Float), &[11, 194, 158, 208], 1853);
                step(f, Op::ScaleV, &[36, 208, 52], 1854);
                step(f, Op::SubV, &[28, 52, 41], 1855);
                step(f, Op::Copy(ValueType::Vec3), &[41, 51], 1856);
                step(f, Op::BreakVector, &[51, 181, 210, 183], 1857);
                step(f, Op::Select(ValueType::Float), &[17, 195, 181, 215], 1858);
                step(f, Op::Copy(ValueType::Float), &[215, 23], 1859);
                step(f, Op::Copy(ValueType::Float), &[195, 24], 1860);
                step(f, Op::GetTransform, &[47, 2, 10, 15], 1861);
                step(f, Op::BreakTransform, &[15, 30, 4, 31], 1862);
                step(f, Op::MakeVector, &[156, 156, 23, 43], 1863);
                step(f, Op::SubV, &[30, 43, 17], 1864);
                step(f, Op::MakeTransform, &[17, 4, 5, 18], 1865);
                step(f, Op::SetTransform, &[48, 18, 2, 9, 158], 1866);
                step(f, Op::JumpIfFalse, &[8, 1872], 1867)
            }
            1867 => {
                step(f, Op::GetTransform, &[47, 2, 10, 15], 1868);
                step(f, Op::BreakTransform, &[15, 30, 4, 31], 1869);
                step(f, Op::SubV, &[30, 43, 17], 1870);
                step(f, Op::MakeTransform, &[17, 4, 5, 18], 1871);
                step(f, Op::DrawTransform, &[18, 179, 157], 1872);
                1872
            }
            1872 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1873);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 1874);
                1874
            }
            1874 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 7, 2, 10, 12, 1923], 1875)
            }
            1875 => {
                step(f, Op::GetParent, &[2, 29], 1876);
                step(f, Op::GetParent, &[29, 30], 1877);
                step(f, Op::GetTransform, &[30, 2, 10, 7], 1878);
                step(f, Op::BreakTransform, &[7, 20, 8, 29], 1879);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 10, 6], 1880);
                step(f, Op::BreakTransform, &[6, 50, 5, 27], 1881);
                step(f, Op::SubV, &[50, 20, 33], 1882);
                step(f, Op::LengthV, &[33, 197], 1883);
                step(f, Op::ArrayAt(Elem::Float), &[1, 10, 217], 1884);
                step(f, Op::MulF, &[217, 150, 189], 1885);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 10, 16], 1886);
                step(f, Op::MulF, &[19, 116, 198], 1887);
                step(f, Op::ArrayAt(Elem::Float), &[2, 10, 186], 1888);
                step(f, Op::ClampF, &[186, 156, 158, 190], 1889);
                step(f, Op::LessF, &[190, 157, 14], 1890);
                step(f, Op::SmoothStepF, &[190, 152, 153, 203], 1891);
                step(f, Op::MulF, &[190, 166, 192], 1892);
                step(f, Op::SinF, &[192, 193], 1893);
                step(f, Op::MaxF, &[203, 193, 202], 1894);
                step(f, Op::Select(ValueType::Float), &[14, 202, 193, 213], 1895);
                step(f, Op::MulF, &[213, 151, 196], 1896);
                step(f, Op::Select(ValueType::Float), &[16, 198, 196, 199], 1897);
                step(f, Op::SubF, &[189, 199, 211], 1898);
                step(f, Op::SubF, &[197, 211, 200], 1899);
                step(f, Op::MaxF, &[200, 156, 188], 1900);
                step(f, Op::MulF, &[188, 188, 205], 1901);
                step(f, Op::AddF, &[188, 199, 187], 1902);
                step(f, Op::DivF, &[205, 187, 209], 1903);
                step(f, Op::SubF, &[197, 209, 218], 1904);
                step(f, Op::DivF, &[218, 197, 222], 1905);
                step(f, Op::ScaleV, &[33, 222, 44], 1906);
                step(f, Op::AddV, &[20, 44, 18], 1907);
                step(f, Op::ClampSpatially, &[18, 20, 156, 189, 58], 1908);
                step(f, Op::MakeTransform, &[58, 5, 5, 8], 1909);
                step(f, Op::Equals(Elem::Int), &[10, 2, 18], 1910);
                step(f, Op::Select(ValueType::Vec3), &[18, 13, 12, 16], 1911);
                step(f, Op::Select(ValueType::Vec3), &[18, 9, 14, 53], 1912);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 10, 4], 1913);
                step(f, Op::BreakTransform, &[4, 45, 10, 38], 1914);
                step(f, Op::ArrayAt(Elem::Vec3), &[3, 10, 47], 1915);
                step(f, Op::KneeVector, &[10, 0, 47, 154, 155, 56], 1916);
                step(f, Op::TwoBoneIK, &[30, 29, 2, 8, 16, 53, 56, 2, 158, 10, 176, 177, 9, 20, 180], 1917);
                step(f, Op::JumpIfFalse, &[8, 1922], 1918)
            }
            1918 => {
                step(f, Op::GetTransform, &[29, 2, 10, 13], 1919);
                step(f, Op::BreakTransform, &[13, 46, 9, 59], 1920);
                step(f, Op::AddV, &[46, 56, 54], 1921);
                step(f, Op::DrawLine, &[46, 54, 157, 15], 1922);
                1922
            }
            1922 => {
                step(f, Op::Jump, &[1874], 1923)
            }
            1923 => {
                step(f, Op::End, &[], 1924)
            }
            _ => return,
        } };
    }
}
