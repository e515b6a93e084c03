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
    fingerprint: 0xe4d67ae25365d4f9,
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
                step(f, Op::DeltaTime, &[200], 421);
                step(f, Op::DivF, &[57, 200, 209], 422);
                step(f, Op::TransformVector, &[2, 8, 21], 423);
                step(f, Op::BreakVector, &[21, 206, 216, 212], 424);
                step(f, Op::NegF, &[206, 217], 425);
                step(f, Op::Atan2F, &[217, 216, 196], 426);
                step(f, Op::MulF, &[209, 196, 218], 427);
                step(f, Op::QuatFromAxisAngle, &[9, 218, 2], 428);
                step(f, Op::TransformVector, &[2, 4, 16], 429);
                step(f, Op::FloatLerp, &[156, 158, 41, 219], 430);
                step(f, Op::GreaterF, &[219, 156, 16], 431);
                step(f, Op::AddF, &[158, 209, 220], 432);
                step(f, Op::MulF, &[41, 220, 188], 433);
                step(f, Op::FloatLerp, &[156, 158, 188, 222], 434);
                step(f, Op::DivF, &[222, 219, 183], 435);
                step(f, Op::Select(ValueType::Float), &[16, 183, 220, 180], 436);
                step(f, Op::LerpV, &[16, 2, 180, 18], 437);
                step(f, Op::RotateVector, &[2, 18, 19], 438);
                step(f, Op::LengthV, &[19, 184], 439);
                step(f, Op::GreaterF, &[184, 34, 11], 440);
                step(f, Op::Select(ValueType::Vec3), &[11, 19, 6, 20], 441);
                step(f, Op::MovementAngleOffset, &[20, 17, 156, 163, 163, 164, 45, 165, 186], 442);
                step(f, Op::Copy(ValueType::Float), &[17, 181], 443);
                step(f, Op::SubF, &[186, 181, 185], 444);
                step(f, Op::AddF, &[185, 166, 187], 445);
                step(f, Op::DivF, &[187, 167, 194], 446);
                step(f, Op::FractF, &[194, 199], 447);
                step(f, Op::MulF, &[199, 167, 198], 448);
                step(f, Op::SubF, &[198, 166, 191], 449);
                step(f, Op::Copy(ValueType::Float), &[191, 197], 450);
                step(f, Op::AbsF, &[197, 189], 451);
                step(f, Op::SubF, &[186, 192, 203], 452);
                step(f, Op::AddF, &[203, 166, 201], 453);
                step(f, Op::DivF, &[201, 167, 204], 454);
                step(f, Op::FractF, &[204, 190], 455);
                step(f, Op::MulF, &[190, 167, 193], 456);
                step(f, Op::SubF, &[193, 166, 182], 457);
                step(f, Op::Copy(ValueType::Float), &[182, 195], 458);
                step(f, Op::AbsF, &[195, 208], 459);
                step(f, Op::MaxF, &[189, 208, 205], 460);
                step(f, Op::MaxF, &[215, 205, 211], 461);
                step(f, Op::LessF, &[211, 168, 12], 462);
                step(f, Op::And, &[13, 12, 11], 463);
                step(f, Op::Not, &[15, 12], 464);
                step(f, Op::Not, &[14, 13], 465);
                step(f, Op::And, &[12, 13, 15], 466);
                step(f, Op::Or, &[11, 15, 12], 467);
                step(f, Op::JumpIfFalse, &[12, 487], 468)
            }
            468 => {
                step(f, Op::MulF, &[43, 200, 210], 469);
                step(f, Op::GreaterF, &[210, 156, 13], 470);
                step(f, Op::FloatLerp, &[156, 158, 43, 202], 471);
                step(f, Op::SubF, &[158, 202, 207], 472);
                step(f, Op::DivF, &[207, 202, 214], 473);
                step(f, Op::DivF, &[158, 210, 212], 474);
                step(f, Op::SubF, &[214, 212, 206], 475);
                step(f, Op::AddF, &[209, 206, 216], 476);
                step(f, Op::Select(ValueType::Float), &[13, 216, 156, 217], 477);
                step(f, Op::MulF, &[213, 217, 196], 478);
                step(f, Op::AddF, &[192, 196, 218], 479);
                step(f, Op::SinF, &[218, 188], 480);
                step(f, Op::NegF, &[188, 222], 481);
                step(f, Op::CosF, &[218, 183], 482);
                step(f, Op::MakeVector, &[222, 183, 156, 21], 483);
                step(f, Op::Select(ValueType::Vec3), &[14, 21, 6, 16], 484);
                step(f, Op::MovementAngleOffset, &[16, 17, 156, 43, 44, 164, 166, 165, 220], 485);
                step(f, Op::Copy(ValueType::Float), &[220, 17], 486);
                step(f, Op::Jump, &[540], 487)
            }
            487 => {
                step(f, Op::DivF, &[200, 47, 180], 488);
                step(f, Op::AddF, &[180, 157, 184], 489);
                step(f, Op::FloorF, &[184, 181], 490);
                step(f, Op::MaxF, &[181, 158, 185], 491);
                step(f, Op::ToInt, &[185, 9], 492);
                step(f, Op::Copy(ValueType::Int), &[9, 10], 493);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 494);
                step(f, Op::MulF, &[47, 157, 187], 495);
                step(f, Op::SubF, &[57, 187, 194], 496);
                step(f, Op::DivF, &[194, 200, 199], 497);
                step(f, Op::DivF, &[43, 185, 198], 498);
                step(f, Op::DivF, &[44, 185, 191], 499);
                step(f, Op::SubF, &[164, 46, 197], 500);
                step(f, Op::GreaterF, &[46, 156, 11], 501);
                501
            }
            501 => {
                step(f, Op::ForNext, &[7, 10, 6, 540], 502)
            }
            502 => {
                step(f, Op::ToFloat, &[6, 186], 503);
                step(f, Op::AddF, &[186, 158, 203], 504);
                step(f, Op::DivF, &[203, 185, 201], 505);
                step(f, Op::AddF, &[201, 199, 204], 506);
                step(f, Op::MulF, &[41, 204, 190], 507);
                step(f, Op::FloatLerp, &[156, 158, 190, 193], 508);
                step(f, Op::DivF, &[193, 219, 182], 509);
                step(f, Op::Select(ValueType::Float), &[16, 182, 204, 195], 510);
                step(f, Op::LerpV, &[4, 2, 195, 18], 511);
                step(f, Op::LengthV, &[18, 189], 512);
                step(f, Op::GreaterF, &[189, 34, 15], 513);
                step(f, Op::Select(ValueType::Vec3), &[15, 18, 6, 19], 514);
                step(f, Op::MulF, &[200, 204, 208], 515);
                step(f, Op::MulF, &[11, 208, 205], 516);
                step(f, Op::AddF, &[15, 205, 215], 517);
                step(f, Op::FractF, &[215, 211], 518);
                step(f, Op::MulF, &[211, 161, 202], 519);
                step(f, Op::FractF, &[202, 207], 520);
                step(f, Op::LessF, &[207, 165, 12], 521);
                step(f, Op::MovementAngleOffset, &[19, 17, 156, 163, 163, 164, 45, 165, 210], 522);
                step(f, Op::Copy(ValueType::Float), &[17, 212], 523);
                step(f, Op::SubF, &[210, 212, 214], 524);
                step(f, Op::AddF, &[214, 166, 206], 525);
                step(f, Op::DivF, &[206, 167, 209], 526);
                step(f, Op::FractF, &[209, 216], 527);
                step(f, Op::MulF, &[216, 167, 213], 528);
                step(f, Op::SubF, &[213, 166, 217], 529);
                step(f, Op::Copy(ValueType::Float), &[217, 192], 530);
                step(f, Op::AbsF, &[192, 196], 531);
                step(f, Op::SmoothStepF, &[196, 197, 164, 188], 532);
                step(f, Op::GreaterF, &[196, 164, 13], 533);
                step(f, Op::Select(ValueType::Float), &[13, 158, 156, 218], 534);
                step(f, Op::Select(ValueType::Float), &[11, 188, 218, 183], 535);
                step(f, Op::Select(ValueType::Float), &[12, 156, 183, 222], 536);
                step(f, Op::LerpF, &[198, 191, 222, 220], 537);
                step(f, Op::MovementAngleOffset, &[19, 17, 211, 220, 220, 164, 45, 165, 180], 538);
                step(f, Op::Copy(ValueType::Float), &[180, 17], 539);
                step(f, Op::Jump, &[501], 540)
            }
            540 => {
                step(f, Op::QuatFromAxisAngle, &[9, 17, 2], 541);
                step(f, Op::Copy(ValueType::Quat), &[2, 0], 542);
                step(f, Op::SinF, &[17, 184], 543);
                step(f, Op::AbsF, &[184, 181], 544);
                step(f, Op::RemapF, &[181, 48, 49, 156, 158, 9, 187], 545);
                step(f, Op::BreakVector, &[17, 194, 186, 203], 546);
                step(f, Op::AbsF, &[194, 201], 547);
                step(f, Op::DivF, &[201, 221, 190], 548);
                step(f, Op::RemapF, &[190, 48, 49, 156, 158, 9, 193], 549);
                step(f, Op::TransformVector, &[2, 8, 20], 550);
                step(f, Op::DistanceV, &[20, 8, 182], 551);
                step(f, Op::DivF, &[182, 200, 195], 552);
                step(f, Op::RemapF, &[195, 53, 54, 158, 156, 9, 189], 553);
                step(f, Op::MulF, &[193, 189, 204], 554);
                step(f, Op::MaxF, &[187, 204, 208], 555);
                step(f, Op::Copy(ValueType::Float), &[208, 18], 556);
                step(f, Op::Copy(ValueType::Vec3), &[2, 4], 557);
                step(f, Op::Copy(ValueType::Bool), &[9, 14], 558);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 2], 559);
                step(f, Op::Copy(ValueType::Int), &[2, 8], 560);
                560
            }
            560 => {
                step(f, Op::ForEachNext(Elem::Bool), &[2, 8, 15, 9, 6, 565], 561)
            }
            561 => {
                step(f, Op::Not, &[15, 13], 562);
                step(f, Op::JumpIfFalse, &[13, 564], 563)
            }
            563 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 14], 564);
                564
            }
            564 => {
                step(f, Op::Jump, &[560], 565)
            }
            565 => {
                step(f, Op::Copy(ValueType::Bool), &[14, 12], 566);
                step(f, Op::Copy(ValueType::Bool), &[9, 11], 567);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 568);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 569);
                569
            }
            569 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 7, 15, 10, 6, 583], 570)
            }
            570 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 10, 4], 571);
                step(f, Op::BreakTransform, &[4, 21, 2, 16], 572);
                step(f, Op::BreakVector, &[21, 205, 215, 202], 573);
                step(f, Op::MakeVector, &[205, 215, 156, 18], 574);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 10, 7], 575);
                step(f, Op::BreakTransform, &[7, 19, 2, 17], 576);
                step(f, Op::BreakVector, &[19, 207, 210, 212], 577);
                step(f, Op::MakeVector, &[207, 210, 156, 20], 578);
                step(f, Op::DistanceV, &[18, 20, 214], 579);
                step(f, Op::GreaterF, &[214, 36, 16], 580);
                step(f, Op::JumpIfFalse, &[16, 582], 581)
            }
            581 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 11], 582);
                582
            }
            582 => {
                step(f, Op::Jump, &[569], 583)
            }
            583 => {
                step(f, Op::Copy(ValueType::Bool), &[11, 15], 584);
                step(f, Op::And, &[12, 15, 13], 585);
                step(f, Op::LengthV, &[2, 206], 586);
                step(f, Op::GreaterF, &[206, 34, 14], 587);
                step(f, Op::GreaterF, &[0, 34, 16], 588);
                step(f, Op::Or, &[14, 16, 11], 589);
                step(f, Op::Not, &[11, 15], 590);
                step(f, Op::And, &[13, 15, 16], 591);
                step(f, Op::DeltaTime, &[209], 592);
                step(f, Op::MulF, &[209, 39, 216], 593);
                step(f, Op::AddF, &[15, 216, 213], 594);
                step(f, Op::GreaterF, &[15, 157, 11], 595);
                step(f, Op::AddF, &[38, 157, 217], 596);
                step(f, Op::Select(ValueType::Float), &[11, 217, 38, 192], 597);
                step(f, Op::MinF, &[213, 192, 196], 598);
                step(f, Op::NotEquals(Elem::Bool), &[15, 4, 11], 599);
                step(f, Op::Not, &[13, 17], 600);
                step(f, Op::And, &[11, 17, 18], 601);
                step(f, Op::SubF, &[16, 34, 188], 602);
                step(f, Op::SubF, &[16, 206, 218], 603);
                step(f, Op::DivF, &[188, 218, 183], 604);
                step(f, Op::ClampF, &[183, 156, 158, 222], 605);
                step(f, Op::MulF, &[11, 222, 211], 606);
                step(f, Op::RemapF, &[206, 34, 35, 156, 158, 9, 220], 607);
                step(f, Op::MaxF, &[220, 12, 180], 608);
                step(f, Op::Select(ValueType::Float), &[12, 158, 180, 185], 609);
                step(f, Op::Select(ValueType::Float), &[15, 37, 185, 191], 610);
                step(f, Op::Select(ValueType::Float), &[13, 220, 191, 197], 611);
                step(f, Op::SubF, &[158, 26, 198], 612);
                step(f, Op::MulF, &[197, 198, 199], 613);
                step(f, Op::LerpF, &[28, 51, 18, 219], 614);
                step(f, Op::RemapF, &[206, 31, 32, 29, 30, 9, 184], 615);
                step(f, Op::LerpF, &[184, 50, 18, 181], 616);
                step(f, Op::MaxF, &[206, 33, 186], 617);
                step(f, Op::DivF, &[181, 186, 203], 618);
                step(f, Op::AddF, &[219, 203, 194], 619);
                step(f, Op::DivF, &[199, 194, 201], 620);
                step(f, Op::SubF, &[158, 222, 221], 621);
                step(f, Op::MulF, &[201, 221, 190], 622);
                step(f, Op::AddF, &[211, 190, 182], 623);
                step(f, Op::MulF, &[182, 161, 200], 624);
                step(f, Op::AddF, &[11, 201, 195], 625);
                step(f, Op::Select(ValueType::Float), &[18, 200, 195, 189], 626);
                step(f, Op::DivF, &[161, 189, 193], 627);
                step(f, Op::GreaterF, &[189, 156, 11], 628);
                step(f, Op::CycleStep, &[15, 193, 156, 11, 187, 204], 629);
                step(f, Op::Select(ValueType::Float), &[16, 196, 187, 208], 630);
                step(f, Op::Copy(ValueType::Float), &[208, 15], 631);
                step(f, Op::Copy(ValueType::Float), &[201, 11], 632);
                step(f, Op::Copy(ValueType::Bool), &[14, 3], 633);
                step(f, Op::Copy(ValueType::Float), &[203, 9], 634);
                step(f, Op::Copy(ValueType::Float), &[194, 10], 635);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 636);
                step(f, Op::Copy(ValueType::Int), &[2, 9], 637);
                step(f, Op::DivF, &[219, 194, 202], 638);
                step(f, Op::MulF, &[14, 222, 205], 639);
                step(f, Op::MulF, &[209, 157, 215], 640);
                step(f, Op::SubF, &[202, 13, 212], 641);
                step(f, Op::MaxF, &[212, 156, 207], 642);
                step(f, Op::DivF, &[207, 202, 210], 643);
                step(f, Op::SubF, &[158, 18, 214], 644);
                step(f, Op::DivF, &[57, 209, 216], 645);
                step(f, Op::SubF, &[157, 216, 217], 646);
                step(f, Op::MulF, &[210, 214, 192], 647);
                step(f, Op::MulF, &[192, 198, 213], 648);
                step(f, Op::MulF, &[213, 141, 188], 649);
                step(f, Op::MulF, &[188, 217, 218], 650);
                step(f, Op::SubF, &[158, 218, 183], 651);
                651
            }
            651 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 9, 14, 8, 6, 695], 652)
            }
            652 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 8, 184], 653);
                step(f, Op::ToFloat, &[8, 181], 654);
                step(f, Op::MulF, &[181, 157, 186], 655);
                step(f, Op::AddF, &[15, 186, 190], 656);
                step(f, Op::FractF, &[190, 211], 657);
                step(f, Op::SubF, &[184, 211, 182], 658);
                step(f, Op::GreaterF, &[182, 157, 17], 659);
                step(f, Op::ArrayAt(Elem::Float), &[2, 8, 195], 660);
                step(f, Op::Select(ValueType::Float), &[17, 156, 195, 200], 661);
                step(f, Op::ArraySetAt(Elem::Float), &[3, 8, 200], 662);
                step(f, Op::SubF, &[158, 184, 189], 663);
                step(f, Op::AddF, &[211, 189, 193], 664);
                step(f, Op::DivF, &[211, 193, 204], 665);
                step(f, Op::MaxF, &[220, 12, 180], 666);
                step(f, Op::Select(ValueType::Float), &[12, 158, 180, 185], 667);
                step(f, Op::Select(ValueType::Float), &[15, 37, 185, 191], 668);
                step(f, Op::Select(ValueType::Float), &[13, 220, 191, 197], 669);
                step(f, Op::MulF, &[197, 198, 199], 670);
                step(f, Op::DivF, &[199, 219, 187], 671);
                step(f, Op::MulF, &[187, 221, 196], 672);
                step(f, Op::AddF, &[205, 196, 208], 673);
                step(f, Op::MulF, &[208, 161, 201], 674);
                step(f, Op::AddF, &[14, 187, 203], 675);
                step(f, Op::Select(ValueType::Float), &[18, 201, 203, 194], 676);
                step(f, Op::MulF, &[194, 215, 222], 677);
                step(f, Op::MulF, &[204, 222, 212], 678);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 8, 11], 679);
                step(f, Op::MulF, &[222, 183, 207], 680);
                step(f, Op::Select(ValueType::Float), &[11, 222, 207, 209], 681);
                step(f, Op::MulF, &[210, 195, 216], 682);
                step(f, Op::MulF, &[216, 214, 192], 683);
                step(f, Op::MulF, &[192, 198, 213], 684);
                step(f, Op::MulF, &[213, 141, 188], 685);
                step(f, Op::Select(ValueType::Float), &[11, 156, 188, 217], 686);
                step(f, Op::SubF, &[209, 217, 218], 687);
                step(f, Op::AddF, &[195, 218, 181], 688);
                step(f, Op::Select(ValueType::Float), &[17, 212, 181, 186], 689);
                step(f, Op::MinF, &[186, 161, 190], 690);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 8, 190], 691);
                step(f, Op::JumpIfFalse, &[17, 693], 692)
            }
            692 => {
                step(f, Op::Copy(ValueType::Float), &[197, 12], 693);
                693
            }
            693 => {
                step(f, Op::ArraySetAt(Elem::Float), &[0, 8, 211], 694);
                step(f, Op::Jump, &[651], 695)
            }
            695 => {
                step(f, Op::Copy(ValueType::Float), &[202, 13], 696);
                step(f, Op::Copy(ValueType::Bool), &[15, 4], 697);
                step(f, Op::Copy(ValueType::Float), &[206, 16], 698);
                step(f, Op::MaxF, &[220, 12, 180], 699);
                step(f, Op::Select(ValueType::Float), &[12, 158, 180, 185], 700);
                step(f, Op::Select(ValueType::Float), &[15, 37, 185, 191], 701);
                step(f, Op::Select(ValueType::Float), &[13, 220, 191, 197], 702);
                step(f, Op::MulF, &[197, 198, 199], 703);
                step(f, Op::DivF, &[199, 219, 187], 704);
                step(f, Op::Copy(ValueType::Float), &[187, 14], 705);
                step(f, Op::TransformVector, &[2, 8, 16], 706);
                step(f, Op::DistanceV, &[16, 8, 182], 707);
                step(f, Op::DeltaTime, &[200], 708);
                step(f, Op::DivF, &[182, 200, 184], 709);
                step(f, Op::RemapF, &[184, 53, 54, 156, 158, 9, 189], 710);
                step(f, Op::BreakTransform, &[2, 21, 2, 17], 711);
                step(f, Op::BreakVector, &[21, 193, 196, 208], 712);
                step(f, Op::NegF, &[196, 201], 713);
                step(f, Op::Atan2F, &[193, 201, 203], 714);
                step(f, Op::AbsF, &[203, 194], 715);
                step(f, Op::RemapF, &[194, 111, 112, 156, 158, 9, 204], 716);
                step(f, Op::MulF, &[189, 204, 207], 717);
                step(f, Op::FloatLerp, &[19, 156, 113, 222], 718);
                step(f, Op::MaxF, &[207, 222, 216], 719);
                step(f, Op::Copy(ValueType::Float), &[216, 19], 720);
                step(f, Op::Copy(ValueType::Float), &[203, 20], 721);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 722);
                step(f, Op::Copy(ValueType::Int), &[2, 10], 723);
                723
            }
            723 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 10, 0, 7, 6, 1652], 724)
            }
            724 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 16], 725);
                step(f, Op::Copy(ValueType::Bool), &[10, 14], 726);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 7, 11], 727);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 192], 728);
                step(f, Op::GreaterEqualF, &[192, 158, 17], 729);
                step(f, Op::And, &[11, 17, 18], 730);
                step(f, Op::Or, &[1, 2, 12], 731);
                step(f, Op::GreaterF, &[26, 156, 15], 732);
                step(f, Op::Or, &[12, 15, 13], 733);
                step(f, Op::Not, &[13, 11], 734);
                step(f, Op::And, &[18, 11, 12], 735);
                step(f, Op::JumpIfFalse, &[12, 845], 736)
            }
            736 => {
                step(f, Op::ArrayAt(Elem::Transform), &[2, 7, 5], 737);
                step(f, Op::BreakTransform, &[5, 19, 2, 18], 738);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 7, 20], 739);
                step(f, Op::SubV, &[19, 20, 16], 740);
                step(f, Op::TransformPoint, &[2, 16, 17], 741);
                step(f, Op::GetTransform, &[34, 2, 9, 6], 742);
                step(f, Op::BreakTransform, &[6, 21, 3, 16], 743);
                step(f, Op::BreakVector, &[21, 213, 188, 209], 744);
                step(f, Op::SubF, &[158, 18, 217], 745);
                step(f, Op::MulF, &[17, 217, 195], 746);
                step(f, Op::QuatFromAxisAngle, &[9, 195, 4], 747);
                step(f, Op::GetTransform, &[0, 2, 9, 4], 748);
                step(f, Op::BreakTransform, &[4, 22, 5, 23], 749);
                step(f, Op::SubV, &[22, 21, 24], 750);
                step(f, Op::BreakVector, &[24, 218, 181, 212], 751);
                step(f, Op::MakeVector, &[218, 181, 156, 25], 752);
                step(f, Op::RotateVector, &[4, 25, 26], 753);
                step(f, Op::BreakVector, &[26, 186, 190, 211], 754);
                step(f, Op::MulF, &[52, 18, 183], 755);
                step(f, Op::Equals(Elem::Int), &[7, 2, 15], 756);
                step(f, Op::Select(ValueType::Float), &[15, 158, 160, 205], 757);
                step(f, Op::MulF, &[183, 205, 210], 758);
                step(f, Op::AddF, &[186, 210, 214], 759);
                step(f, Op::AddF, &[213, 214, 215], 760);
                step(f, Op::AddF, &[188, 190, 221], 761);
                step(f, Op::BreakVector, &[22, 202, 206, 180], 762);
                step(f, Op::SubF, &[180, 58, 185], 763);
                step(f, Op::MakeVector, &[215, 221, 185, 27], 764);
                step(f, Op::MulF, &[9, 157, 191], 765);
                step(f, Op::ScaleV, &[2, 191, 28], 766);
                step(f, Op::AddV, &[27, 28, 29], 767);
                step(f, Op::DistanceV, &[17, 29, 220], 768);
                step(f, Op::TransformVector, &[2, 10, 17], 769);
                step(f, Op::DistanceV, &[17, 10, 197], 770);
                step(f, Op::MaxF, &[220, 197, 198], 771);
                step(f, Op::LessEqualF, &[198, 65, 13], 772);
                step(f, Op::LengthV, &[2, 199], 773);
                step(f, Op::LengthV, &[4, 219], 774);
                step(f, Op::MaxF, &[199, 219, 187], 775);
                step(f, Op::LessEqualF, &[187, 34, 11], 776);
                step(f, Op::And, &[13, 11, 18], 777);
                step(f, Op::ArrayAt(Elem::Bool), &[1, 7, 12], 778);
                step(f, Op::And, &[18, 12, 11], 779);
                step(f, Op::JumpIfFalse, &[11, 782], 780)
            }
            780 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 14], 781);
                step(f, Op::Jump, &[811], 782)
            }
            782 => {
                step(f, Op::MakeVector, &[156, 156, 63, 17], 783);
                step(f, Op::AddV, &[29, 17, 30], 784);
                step(f, Op::SubV, &[29, 17, 31], 785);
                step(f, Op::SphereTrace, &[30, 31, 62, 13, 32, 33, 182], 786);
                step(f, Op::SubV, &[32, 29, 33], 787);
                step(f, Op::DistanceV, &[33, 20, 200], 788);
                step(f, Op::RotateVector, &[0, 8, 32], 789);
                step(f, Op::ScaleV, &[32, 67, 33], 790);
                step(f, Op::AddV, &[30, 33, 34], 791);
                step(f, Op::AddV, &[31, 33, 35], 792);
                step(f, Op::SphereTrace, &[34, 35, 62, 18, 36, 37, 184], 793);
                step(f, Op::SubV, &[36, 29, 38], 794);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 7, 39], 795);
                step(f, Op::DistanceV, &[38, 39, 208], 796);
                step(f, Op::MaxF, &[200, 208, 196], 797);
                step(f, Op::ScaleV, &[32, 64, 39], 798);
                step(f, Op::AddV, &[34, 39, 40], 799);
                step(f, Op::AddV, &[35, 39, 41], 800);
                step(f, Op::SphereTrace, &[40, 41, 62, 11, 42, 43, 193], 801);
                step(f, Op::SubV, &[42, 29, 44], 802);
                step(f, Op::ArrayAt(Elem::Vec3), &[2, 7, 45], 803);
                step(f, Op::DistanceV, &[44, 45, 201], 804);
                step(f, Op::MaxF, &[196, 201, 194], 805);
                step(f, Op::LessEqualF, &[194, 65, 19], 806);
                step(f, Op::And, &[13, 18, 20], 807);
                step(f, Op::And, &[20, 12, 13], 808);
                step(f, Op::And, &[19, 13, 20], 809);
                step(f, Op::JumpIfFalse, &[20, 811], 810)
            }
            810 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 14], 811);
                811
            }
            811 => {
                step(f, Op::JumpIfFalse, &[14, 845], 812)
            }
            812 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 7], 813);
                step(f, Op::BreakTransform, &[7, 45, 6, 46], 814);
                step(f, Op::AddV, &[29, 20, 47], 815);
                step(f, Op::Copy(ValueType::Float), &[55, 189], 816);
                step(f, Op::Copy(ValueType::Float), &[57, 204], 817);
                step(f, Op::SubV, &[47, 19, 20], 818);
                step(f, Op::DeltaTime, &[207], 819);
                step(f, Op::DivF, &[204, 207, 222], 820);
                step(f, Op::ScaleV, &[20, 222, 48], 821);
                step(f, Op::AddV, &[47, 48, 49], 822);
                step(f, Op::AddV, &[19, 48, 50], 823);
                step(f, Op::SubV, &[45, 50, 48], 824);
                step(f, Op::FloatLerp, &[156, 158, 189, 216], 825);
                step(f, Op::SubF, &[158, 216, 203], 826);
                step(f, Op::ScaleV, &[48, 203, 50], 827);
                step(f, Op::AddV, &[49, 50, 48], 828);
                step(f, Op::MulF, &[189, 207, 197], 829);
                step(f, Op::GreaterF, &[197, 156, 13], 830);
                step(f, Op::DivF, &[216, 197, 220], 831);
                step(f, Op::Select(ValueType::Float), &[13, 220, 158, 198], 832);
                step(f, Op::ScaleV, &[20, 198, 49], 833);
                step(f, Op::SubV, &[48, 49, 50], 834);
                step(f, Op::Copy(ValueType::Vec3), &[50, 20], 835);
                step(f, Op::BreakVector, &[20, 199, 219, 187], 836);
                step(f, Op::ClampF, &[187, 68, 69, 182], 837);
                step(f, Op::MakeVector, &[199, 219, 182, 48], 838);
                step(f, Op::MakeTransform, &[48, 6, 5, 8], 839);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 7, 8], 840);
                step(f, Op::MakeTransform, &[47, 1, 5, 8], 841);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 7, 8], 842);
                step(f, Op::JumpIfFalse, &[12, 844], 843)
            }
            843 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 7], 844);
                844
            }
            844 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 16], 845);
                845
            }
            845 => {
                step(f, Op::JumpIfFalse, &[16, 1050], 846)
            }
            846 => {
                step(f, Op::GetTransform, &[34, 2, 9, 6], 847);
                step(f, Op::BreakTransform, &[6, 21, 3, 16], 848);
                step(f, Op::BreakVector, &[21, 213, 188, 209], 849);
                step(f, Op::SubF, &[158, 18, 217], 850);
                step(f, Op::MulF, &[17, 217, 195], 851);
                step(f, Op::QuatFromAxisAngle, &[9, 195, 4], 852);
                step(f, Op::GetTransform, &[0, 2, 9, 4], 853);
                step(f, Op::BreakTransform, &[4, 22, 5, 23], 854);
                step(f, Op::SubV, &[22, 21, 24], 855);
                step(f, Op::BreakVector, &[24, 218, 181, 212], 856);
                step(f, Op::MakeVector, &[218, 181, 156, 25], 857);
                step(f, Op::RotateVector, &[4, 25, 26], 858);
                step(f, Op::BreakVector, &[26, 186, 190, 211], 859);
                step(f, Op::MulF, &[52, 18, 183], 860);
                step(f, Op::Equals(Elem::Int), &[7, 2, 15], 861);
                step(f, Op::Select(ValueType::Float), &[15, 158, 160, 205], 862);
                step(f, Op::MulF, &[183, 205, 210], 863);
                step(f, Op::AddF, &[186, 210, 214], 864);
                step(f, Op::AddF, &[213, 214, 215], 865);
                step(f, Op::AddF, &[188, 190, 221], 866);
                step(f, Op::BreakVector, &[22, 202, 206, 180], 867);
                step(f, Op::SubF, &[180, 58, 185], 868);
                step(f, Op::MakeVector, &[215, 221, 185, 27], 869);
                step(f, Op::SubF, &[158, 192, 200], 870);
                step(f, Op::MaxF, &[200, 156, 208], 871);
                step(f, Op::MulF, &[13, 10, 196], 872);
                step(f, Op::MulF, &[208, 196, 201], 873);
                step(f, Op::ScaleV, &[2, 201, 49], 874);
                step(f, Op::AddV, &[27, 49, 50], 875);
                step(f, Op::MulF, &[9, 157, 191], 876);
                step(f, Op::ScaleV, &[2, 191, 28], 877);
                step(f, Op::AddV, &[50, 28, 20], 878);
                step(f, Op::RotateVector, &[0, 8, 32], 879);
                step(f, Op::Copy(ValueType::Float), &[163, 194], 880);
                step(f, Op::Copy(ValueType::Vec3), &[6, 48], 881);
                step(f, Op::Copy(ValueType::Vec3), &[9, 47], 882);
                step(f, Op::Copy(ValueType::Bool), &[10, 19], 883);
                step(f, Op::Copy(ValueType::Float), &[163, 204], 884);
                step(f, Op::Copy(ValueType::Vec3), &[6, 50], 885);
                step(f, Op::MulI, &[0, 0, 8], 886);
                step(f, Op::Copy(ValueType::Int), &[8, 9], 887);
                step(f, Op::Copy(ValueType::Int), &[2, 6], 888);
                step(f, Op::SubI, &[0, 3, 8], 889);
                step(f, Op::DivI, &[8, 4, 11], 890);
                step(f, Op::MakeVector, &[156, 156, 63, 51], 891);
                step(f, Op::ScaleV, &[32, 67, 52], 892);
                892
            }
            892 => {
                step(f, Op::ForNext, &[6, 9, 8, 939], 893)
            }
            893 => {
                step(f, Op::ModI, &[8, 0, 12], 894);
                step(f, Op::ToFloat, &[12, 222], 895);
                step(f, Op::MulF, &[222, 64, 203], 896);
                step(f, Op::MulF, &[203, 205, 189], 897);
                step(f, Op::MakeVector, &[189, 156, 156, 53], 898);
                step(f, Op::DivI, &[8, 0, 12], 899);
                step(f, Op::SubI, &[12, 11, 8], 900);
                step(f, Op::ToFloat, &[8, 207], 901);
                step(f, Op::MulF, &[207, 64, 197], 902);
                step(f, Op::ScaleV, &[32, 197, 54], 903);
                step(f, Op::AddV, &[53, 54, 55], 904);
                step(f, Op::AddV, &[20, 55, 53], 905);
                step(f, Op::AddV, &[53, 51, 54], 906);
                step(f, Op::SubV, &[53, 51, 56], 907);
                step(f, Op::SphereTrace, &[54, 56, 62, 20, 53, 57, 216], 908);
                step(f, Op::BreakVector, &[53, 220, 198, 187], 909);
                step(f, Op::AddV, &[54, 52, 58], 910);
                step(f, Op::AddV, &[56, 52, 54], 911);
                step(f, Op::SphereTrace, &[58, 54, 62, 14, 56, 59, 182], 912);
                step(f, Op::BreakVector, &[56, 199, 219, 222], 913);
                step(f, Op::SubF, &[187, 222, 203], 914);
                step(f, Op::AbsF, &[203, 189], 915);
                step(f, Op::Select(ValueType::Float), &[20, 156, 158, 207], 916);
                step(f, Op::AddF, &[189, 207, 197], 917);
                step(f, Op::LengthV, &[55, 216], 918);
                step(f, Op::RemapF, &[216, 156, 169, 156, 158, 9, 198], 919);
                step(f, Op::MinF, &[187, 222, 220], 920);
                step(f, Op::RemapF, &[220, 170, 169, 158, 157, 9, 182], 921);
                step(f, Op::AddF, &[198, 182, 199], 922);
                step(f, Op::AddF, &[197, 199, 219], 923);
                step(f, Op::LessF, &[219, 194, 13], 924);
                step(f, Op::And, &[20, 13, 12], 925);
                step(f, Op::JumpIfFalse, &[12, 933], 926)
            }
            926 => {
                step(f, Op::Copy(ValueType::Float), &[194, 204], 927);
                step(f, Op::Copy(ValueType::Vec3), &[48, 50], 928);
                step(f, Op::Copy(ValueType::Float), &[219, 194], 929);
                step(f, Op::Copy(ValueType::Vec3), &[53, 48], 930);
                step(f, Op::Copy(ValueType::Vec3), &[57, 47], 931);
                step(f, Op::Copy(ValueType::Bool), &[9, 19], 932);
                step(f, Op::Jump, &[938], 933)
            }
            933 => {
                step(f, Op::LessF, &[219, 204, 16], 934);
                step(f, Op::And, &[20, 16, 15], 935);
                step(f, Op::JumpIfFalse, &[15, 938], 936)
            }
            936 => {
                step(f, Op::Copy(ValueType::Float), &[219, 204], 937);
                step(f, Op::Copy(ValueType::Vec3), &[53, 50], 938);
                938
            }
            938 => {
                step(f, Op::Jump, &[892], 939)
            }
            939 => {
                step(f, Op::JumpIfFalse, &[8, 941], 940)
            }
            940 => {
                step(f, Op::DrawSphere, &[48, 62, 8], 941);
                941
            }
            941 => {
                step(f, Op::GreaterF, &[66, 156, 14], 942);
                step(f, Op::SubF, &[194, 204, 203], 943);
                step(f, Op::DivF, &[203, 66, 189], 944);
                step(f, Op::PowF, &[171, 189, 207], 945);
                step(f, Op::Select(ValueType::Float), &[14, 207, 156, 216], 946);
                step(f, Op::ScaleV, &[50, 216, 54], 947);
                step(f, Op::AddV, &[48, 54, 58], 948);
                step(f, Op::AddF, &[216, 158, 187], 949);
                step(f, Op::DivF, &[158, 187, 222], 950);
                step(f, Op::ScaleV, &[58, 222, 59], 951);
                step(f, Op::Copy(ValueType::Vec3), &[59, 56], 952);
                step(f, Op::Copy(ValueType::Vec3), &[47, 55], 953);
                step(f, Op::Copy(ValueType::Bool), &[19, 13], 954);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 7], 955);
                step(f, Op::BreakTransform, &[7, 45, 6, 46], 956);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 192], 957);
                step(f, Op::SubF, &[158, 192, 200], 958);
                step(f, Op::MaxF, &[200, 156, 208], 959);
                step(f, Op::MulF, &[13, 10, 196], 960);
                step(f, Op::MulF, &[208, 196, 201], 961);
                step(f, Op::ScaleV, &[2, 201, 49], 962);
                step(f, Op::SubV, &[56, 49, 57], 963);
                step(f, Op::Select(ValueType::Vec3), &[13, 57, 45, 53], 964);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 7, 5], 965);
                step(f, Op::BreakTransform, &[5, 19, 2, 18], 966);
                step(f, Op::Copy(ValueType::Float), &[55, 220], 967);
                step(f, Op::Copy(ValueType::Float), &[57, 182], 968);
                step(f, Op::SubV, &[53, 19, 20], 969);
                step(f, Op::DeltaTime, &[198], 970);
                step(f, Op::DivF, &[182, 198, 197], 971);
                step(f, Op::ScaleV, &[20, 197, 51], 972);
                step(f, Op::AddV, &[53, 51, 52], 973);
                step(f, Op::AddV, &[19, 51, 50], 974);
                step(f, Op::SubV, &[45, 50, 48], 975);
                step(f, Op::FloatLerp, &[156, 158, 220, 199], 976);
                step(f, Op::SubF, &[158, 199, 219], 977);
                step(f, Op::ScaleV, &[48, 219, 54], 978);
                step(f, Op::AddV, &[52, 54, 58], 979);
                step(f, Op::MulF, &[220, 198, 194], 980);
                step(f, Op::GreaterF, &[194, 156, 12], 981);
                step(f, Op::DivF, &[199, 194, 204], 982);
                step(f, Op::Select(ValueType::Float), &[12, 204, 158, 203], 983);
                step(f, Op::ScaleV, &[20, 203, 59], 984);
                step(f, Op::SubV, &[58, 59, 47], 985);
                step(f, Op::Copy(ValueType::Vec3), &[47, 49], 986);
                step(f, Op::BreakVector, &[49, 189, 207, 216], 987);
                step(f, Op::ClampF, &[216, 68, 69, 187], 988);
                step(f, Op::MakeVector, &[189, 207, 187, 56], 989);
                step(f, Op::RotationFromNormal, &[55, 222, 200, 2], 990);
                step(f, Op::PerFootRotationFactor, &[17, 117, 118, 196], 991);
                step(f, Op::MulF, &[17, 196, 208], 992);
                step(f, Op::SubF, &[158, 18, 217], 993);
                step(f, Op::MulF, &[208, 217, 201], 994);
                step(f, Op::QuatFromAxisAngle, &[9, 201, 7], 995);
                step(f, Op::MulQ, &[2, 7, 8], 996);
                step(f, Op::Select(ValueType::Quat), &[13, 8, 6, 2], 997);
                step(f, Op::MakeTransform, &[56, 2, 5, 8], 998);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 7, 8], 999);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 7], 1000);
                step(f, Op::BreakTransform, &[7, 45, 6, 46], 1001);
                step(f, Op::Select(ValueType::Vec3), &[13, 57, 45, 53], 1002);
                step(f, Op::MakeTransform, &[53, 1, 5, 5], 1003);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 7, 5], 1004);
                step(f, Op::GetTransform, &[34, 2, 9, 6], 1005);
                step(f, Op::BreakTransform, &[6, 21, 3, 16], 1006);
                step(f, Op::BreakVector, &[21, 213, 188, 209], 1007);
                step(f, Op::MulF, &[17, 217, 195], 1008);
                step(f, Op::QuatFromAxisAngle, &[9, 195, 4], 1009);
                step(f, Op::GetTransform, &[0, 2, 9, 4], 1010);
                step(f, Op::BreakTransform, &[4, 22, 5, 23], 1011);
                step(f, Op::SubV, &[22, 21, 24], 1012);
                step(f, Op::BreakVector, &[24, 218, 181, 212], 1013);
                step(f, Op::MakeVector, &[218, 181, 156, 25], 1014);
                step(f, Op::RotateVector, &[4, 25, 26], 1015);
                step(f, Op::BreakVector, &[26, 186, 190, 211], 1016);
                step(f, Op::MulF, &[52, 18, 183], 1017);
                step(f, Op::MulF, &[183, 205, 210], 1018);
                step(f, Op::AddF, &[186, 210, 214], 1019);
                step(f, Op::AddF, &[213, 214, 215], 1020);
                step(f, Op::AddF, &[188, 190, 221], 1021);
                step(f, Op::BreakVector, &[22, 202, 206, 180], 1022);
                step(f, Op::SubF, &[180, 58, 185], 1023);
                step(f, Op::MakeVector, &[215, 221, 185, 27], 1024);
                step(f, Op::MulF, &[9, 157, 191], 1025);
                step(f, Op::ScaleV, &[2, 191, 28], 1026);
                step(f, Op::AddV, &[27, 28, 29], 1027);
                step(f, Op::SubV, &[53, 29, 18], 1028);
                step(f, Op::ArraySetAt(Elem::Vec3), &[0, 7, 18], 1029);
                step(f, Op::ArraySetAt(Elem::Bool), &[1, 7, 13], 1030);
                step(f, Op::GreaterEqualF, &[192, 158, 17], 1031);
                step(f, Op::JumpIfFalse, &[17, 1048], 1032)
            }
            1032 => {
                step(f, Op::MakeVector, &[156, 156, 63, 17], 1033);
                step(f, Op::AddV, &[29, 17, 30], 1034);
                step(f, Op::RotateVector, &[0, 8, 32], 1035);
                step(f, Op::ScaleV, &[32, 67, 33], 1036);
                step(f, Op::AddV, &[30, 33, 34], 1037);
                step(f, Op::SubV, &[29, 17, 31], 1038);
                step(f, Op::AddV, &[31, 33, 35], 1039);
                step(f, Op::SphereTrace, &[34, 35, 62, 18, 36, 37, 184], 1040);
                step(f, Op::SubV, &[36, 29, 38], 1041);
                step(f, Op::ArraySetAt(Elem::Vec3), &[1, 7, 38], 1042);
                step(f, Op::ScaleV, &[32, 64, 39], 1043);
                step(f, Op::AddV, &[34, 39, 40], 1044);
                step(f, Op::AddV, &[35, 39, 41], 1045);
                step(f, Op::SphereTrace, &[40, 41, 62, 11, 42, 43, 193], 1046);
                step(f, Op::SubV, &[42, 29, 44], 1047);
                step(f, Op::ArraySetAt(Elem::Vec3), &[2, 7, 44], 1048);
                1048
            }
            1048 => {
                step(f, Op::JumpIfFalse, &[13, 1050], 1049)
            }
            1049 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 7], 1050);
                1050
            }
            1050 => {
                step(f, Op::ArrayAt(Elem::Float), &[4, 7, 182], 1051);
                step(f, Op::FloatLerp, &[182, 156, 110, 197], 1052);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 7, 16], 1053);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 219], 1054);
                step(f, Op::GreaterEqualF, &[219, 158, 20], 1055);
                step(f, Op::And, &[16, 20, 15], 1056);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 7, 8], 1057);
                step(f, Op::GreaterF, &[26, 156, 14], 1058);
                step(f, Op::InterpolateTransform, &[2, 3, 27, 7], 1059);
                step(f, Op::Select(ValueType::Transform), &[14, 7, 2, 5], 1060);
                step(f, Op::MakeAbsolute, &[8, 5, 6], 1061);
                step(f, Op::BreakTransform, &[6, 19, 7, 51], 1062);
                step(f, Op::RotateVector, &[7, 8, 50], 1063);
                step(f, Op::SubF, &[158, 18, 198], 1064);
                step(f, Op::MulF, &[17, 198, 220], 1065);
                step(f, Op::LimitRotationAroundZ, &[7, 220, 107, 8], 1066);
                step(f, Op::RotateVector, &[8, 8, 48], 1067);
                step(f, Op::CrossV, &[50, 48, 52], 1068);
                step(f, Op::BreakVector, &[52, 194, 199, 204], 1069);
                step(f, Op::DotV, &[50, 48, 203], 1070);
                step(f, Op::Atan2F, &[204, 203, 216], 1071);
                step(f, Op::AbsF, &[216, 187], 1072);
                step(f, Op::Select(ValueType::Float), &[15, 187, 156, 189], 1073);
                step(f, Op::AddF, &[197, 189, 207], 1074);
                step(f, Op::ArraySetAt(Elem::Float), &[4, 7, 207], 1075);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 7, 4], 1076);
                step(f, Op::BreakTransform, &[4, 54, 2, 20], 1077);
                step(f, Op::AddF, &[72, 73, 200], 1078);
                step(f, Op::ClampSpatially, &[19, 54, 156, 200, 58], 1079);
                step(f, Op::MakeTransform, &[58, 8, 5, 8], 1080);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 7, 8], 1081);
                step(f, Op::JumpIfFalse, &[16, 1158], 1082)
            }
            1082 => {
                step(f, Op::JumpIfFalse, &[20, 1084], 1083)
            }
            1083 => {
                step(f, Op::Jump, &[1157], 1084)
            }
            1084 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 6], 1085);
                step(f, Op::BreakTransform, &[6, 59, 6, 47], 1086);
                step(f, Op::SubF, &[158, 219, 222], 1087);
                step(f, Op::MulF, &[13, 10, 196], 1088);
                step(f, Op::MulF, &[222, 196, 208], 1089);
                step(f, Op::ScaleV, &[2, 208, 49], 1090);
                step(f, Op::AddV, &[59, 49, 55], 1091);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1092);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 12], 1093);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 12], 1094);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 12, 4], 1095);
                step(f, Op::BreakTransform, &[4, 56, 3, 46], 1096);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 12, 8], 1097);
                step(f, Op::BreakTransform, &[8, 45, 5, 57], 1098);
                step(f, Op::LessEqualF, &[93, 156, 17], 1099);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 201], 1100);
                step(f, Op::SmoothStepF, &[201, 156, 93, 209], 1101);
                step(f, Op::Select(ValueType::Float), &[17, 158, 209, 217], 1102);
                step(f, Op::LerpV, &[56, 45, 217, 16], 1103);
                step(f, Op::MakeTransform, &[16, 1, 5, 9], 1104);
                step(f, Op::Select(ValueType::Transform), &[12, 4, 9, 10], 1105);
                step(f, Op::MakeAbsolute, &[10, 5, 11], 1106);
                step(f, Op::Select(ValueType::Transform), &[19, 11, 10, 12], 1107);
                step(f, Op::BreakTransform, &[12, 23, 4, 21], 1108);
                step(f, Op::SubF, &[158, 19, 195], 1109);
                step(f, Op::MulF, &[198, 195, 212], 1110);
                step(f, Op::MulF, &[17, 212, 181], 1111);
                step(f, Op::FootAvoidance, &[55, 23, 181, 19, 89, 24], 1112);
                step(f, Op::RemapF, &[18, 92, 158, 156, 158, 9, 218], 1113);
                step(f, Op::LerpV, &[55, 24, 218, 25], 1114);
                step(f, Op::FootAvoidance, &[25, 23, 20, 19, 115, 26], 1115);
                step(f, Op::LerpV, &[25, 26, 19, 22], 1116);
                step(f, Op::MakeTransform, &[22, 6, 5, 13], 1117);
                step(f, Op::BreakTransform, &[13, 27, 7, 28], 1118);
                step(f, Op::MakeVector, &[156, 156, 63, 53], 1119);
                step(f, Op::AddV, &[27, 53, 18], 1120);
                step(f, Op::SubV, &[27, 53, 30], 1121);
                step(f, Op::LineTrace, &[18, 30, 18, 17, 31, 211], 1122);
                step(f, Op::RotateVector, &[7, 9, 33], 1123);
                step(f, Op::FindQuatBetween, &[33, 31, 2], 1124);
                step(f, Op::MulQ, &[2, 7, 8], 1125);
                step(f, Op::MulF, &[61, 60, 183], 1126);
                step(f, Op::AddF, &[183, 71, 205], 1127);
                step(f, Op::NegF, &[205, 186], 1128);
                step(f, Op::MakeVector, &[156, 186, 156, 37], 1129);
                step(f, Op::RotateVector, &[8, 37, 36], 1130);
                step(f, Op::AddV, &[17, 36, 38], 1131);
                step(f, Op::AddV, &[38, 53, 32], 1132);
                step(f, Op::SubV, &[38, 53, 34], 1133);
                step(f, Op::LineTrace, &[32, 34, 11, 35, 39, 210], 1134);
                step(f, Op::BreakVector, &[35, 213, 214, 188], 1135);
                step(f, Op::BreakVector, &[38, 190, 202, 206], 1136);
                step(f, Op::SubF, &[188, 206, 180], 1137);
                step(f, Op::Select(ValueType::Float), &[11, 180, 156, 185], 1138);
                step(f, Op::AddF, &[67, 71, 215], 1139);
                step(f, Op::MakeVector, &[156, 215, 156, 40], 1140);
                step(f, Op::RotateVector, &[8, 40, 41], 1141);
                step(f, Op::AddV, &[17, 41, 43], 1142);
                step(f, Op::AddV, &[43, 53, 29], 1143);
                step(f, Op::SubV, &[43, 53, 42], 1144);
                step(f, Op::LineTrace, &[29, 42, 13, 44, 51, 221], 1145);
                step(f, Op::BreakVector, &[44, 191, 192, 184], 1146);
                step(f, Op::BreakVector, &[43, 193, 182, 220], 1147);
                step(f, Op::SubF, &[184, 220, 194], 1148);
                step(f, Op::Select(ValueType::Float), &[13, 194, 156, 199], 1149);
                step(f, Op::MaxF, &[185, 199, 203], 1150);
                step(f, Op::ClampF, &[203, 156, 70, 204], 1151);
                step(f, Op::MakeVector, &[156, 156, 204, 52], 1152);
                step(f, Op::AddV, &[17, 52, 48], 1153);
                step(f, Op::MakeTransform, &[48, 8, 5, 14], 1154);
                step(f, Op::Select(ValueType::Transform), &[18, 14, 13, 15], 1155);
                step(f, Op::Copy(ValueType::Transform), &[15, 13], 1156);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 7, 13], 1157);
                1157
            }
            1157 => {
                step(f, Op::Jump, &[1274], 1158)
            }
            1158 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 7, 14], 1159);
                step(f, Op::MakeAbsolute, &[14, 5, 15], 1160);
                step(f, Op::BreakTransform, &[15, 50, 2, 20], 1161);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 6], 1162);
                step(f, Op::BreakTransform, &[6, 59, 6, 47], 1163);
                step(f, Op::SubF, &[158, 219, 222], 1164);
                step(f, Op::MulF, &[13, 10, 196], 1165);
                step(f, Op::MulF, &[222, 196, 208], 1166);
                step(f, Op::ScaleV, &[2, 208, 49], 1167);
                step(f, Op::AddV, &[59, 49, 55], 1168);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1169);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 12], 1170);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 12], 1171);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 12, 4], 1172);
                step(f, Op::BreakTransform, &[4, 56, 3, 46], 1173);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 12, 8], 1174);
                step(f, Op::BreakTransform, &[8, 45, 5, 57], 1175);
                step(f, Op::LessEqualF, &[93, 156, 17], 1176);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 201], 1177);
                step(f, Op::SmoothStepF, &[201, 156, 93, 209], 1178);
                step(f, Op::Select(ValueType::Float), &[17, 158, 209, 217], 1179);
                step(f, Op::LerpV, &[56, 45, 217, 16], 1180);
                step(f, Op::MakeTransform, &[16, 1, 5, 9], 1181);
                step(f, Op::Select(ValueType::Transform), &[12, 4, 9, 10], 1182);
                step(f, Op::MakeAbsolute, &[10, 5, 11], 1183);
                step(f, Op::Select(ValueType::Transform), &[19, 11, 10, 12], 1184);
                step(f, Op::BreakTransform, &[12, 23, 4, 21], 1185);
                step(f, Op::SubF, &[158, 19, 195], 1186);
                step(f, Op::MulF, &[198, 195, 212], 1187);
                step(f, Op::MulF, &[17, 212, 181], 1188);
                step(f, Op::FootAvoidance, &[55, 23, 181, 19, 89, 24], 1189);
                step(f, Op::RemapF, &[18, 92, 158, 156, 158, 9, 218], 1190);
                step(f, Op::LerpV, &[55, 24, 218, 25], 1191);
                step(f, Op::FootAvoidance, &[25, 23, 20, 19, 115, 26], 1192);
                step(f, Op::LerpV, &[25, 26, 19, 22], 1193);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 7, 13], 1194);
                step(f, Op::MakeAbsolute, &[13, 5, 14], 1195);
                step(f, Op::BreakTransform, &[14, 19, 7, 58], 1196);
                step(f, Op::ArrayAt(Elem::Float), &[3, 7, 216], 1197);
                step(f, Op::SubF, &[219, 216, 187], 1198);
                step(f, Op::DeltaTime, &[189], 1199);
                step(f, Op::DivF, &[57, 189, 197], 1200);
                step(f, Op::MulF, &[187, 197, 207], 1201);
                step(f, Op::AddF, &[216, 207, 200], 1202);
                step(f, Op::ClampF, &[200, 156, 158, 211], 1203);
                step(f, Op::AddF, &[219, 207, 183], 1204);
                step(f, Op::ClampF, &[183, 156, 158, 205], 1205);
                step(f, Op::AddF, &[211, 205, 186], 1206);
                step(f, Op::MulF, &[186, 157, 210], 1207);
                step(f, Op::SubF, &[158, 210, 213], 1208);
                step(f, Op::GreaterF, &[187, 156, 15], 1209);
                step(f, Op::SubF, &[205, 211, 214], 1210);
                step(f, Op::DivF, &[214, 187, 190], 1211);
                step(f, Op::Select(ValueType::Float), &[15, 190, 158, 202], 1212);
                step(f, Op::MulF, &[213, 202, 188], 1213);
                step(f, Op::MulF, &[88, 188, 206], 1214);
                step(f, Op::Copy(ValueType::Float), &[57, 180], 1215);
                step(f, Op::SubV, &[22, 19, 28], 1216);
                step(f, Op::DeltaTime, &[215], 1217);
                step(f, Op::DivF, &[180, 215, 221], 1218);
                step(f, Op::ScaleV, &[28, 221, 27], 1219);
                step(f, Op::AddV, &[22, 27, 18], 1220);
                step(f, Op::AddV, &[19, 27, 30], 1221);
                step(f, Op::SubV, &[50, 30, 31], 1222);
                step(f, Op::FloatLerp, &[156, 158, 206, 191], 1223);
                step(f, Op::SubF, &[158, 191, 192], 1224);
                step(f, Op::ScaleV, &[31, 192, 33], 1225);
                step(f, Op::AddV, &[18, 33, 37], 1226);
                step(f, Op::MulF, &[206, 215, 182], 1227);
                step(f, Op::GreaterF, &[182, 156, 11], 1228);
                step(f, Op::DivF, &[191, 182, 193], 1229);
                step(f, Op::Select(ValueType::Float), &[11, 193, 158, 184], 1230);
                step(f, Op::ScaleV, &[28, 184, 36], 1231);
                step(f, Op::SubV, &[37, 36, 32], 1232);
                step(f, Op::Copy(ValueType::Vec3), &[32, 34], 1233);
                step(f, Op::MakeTransform, &[34, 6, 5, 15], 1234);
                step(f, Op::BreakTransform, &[15, 39, 8, 35], 1235);
                step(f, Op::MakeVector, &[156, 156, 63, 38], 1236);
                step(f, Op::AddV, &[39, 38, 40], 1237);
                step(f, Op::SubV, &[39, 38, 41], 1238);
                step(f, Op::LineTrace, &[40, 41, 13, 53, 29, 220], 1239);
                step(f, Op::RotateVector, &[8, 9, 42], 1240);
                step(f, Op::FindQuatBetween, &[42, 29, 2], 1241);
                step(f, Op::MulQ, &[2, 8, 7], 1242);
                step(f, Op::MulF, &[61, 60, 194], 1243);
                step(f, Op::AddF, &[194, 71, 185], 1244);
                step(f, Op::NegF, &[185, 199], 1245);
                step(f, Op::MakeVector, &[156, 199, 156, 51], 1246);
                step(f, Op::RotateVector, &[7, 51, 44], 1247);
                step(f, Op::AddV, &[53, 44, 43], 1248);
                step(f, Op::AddV, &[43, 38, 17], 1249);
                step(f, Op::SubV, &[43, 38, 52], 1250);
                step(f, Op::LineTrace, &[17, 52, 18, 48, 20, 203], 1251);
                step(f, Op::BreakVector, &[48, 204, 189, 197], 1252);
                step(f, Op::BreakVector, &[43, 216, 200, 207], 1253);
                step(f, Op::SubF, &[197, 207, 183], 1254);
                step(f, Op::Select(ValueType::Float), &[18, 183, 156, 186], 1255);
                step(f, Op::AddF, &[67, 71, 210], 1256);
                step(f, Op::MakeVector, &[156, 210, 156, 58], 1257);
                step(f, Op::RotateVector, &[7, 58, 19], 1258);
                step(f, Op::AddV, &[53, 19, 27], 1259);
                step(f, Op::AddV, &[27, 38, 30], 1260);
                step(f, Op::SubV, &[27, 38, 50], 1261);
                step(f, Op::LineTrace, &[30, 50, 15, 31, 18, 205], 1262);
                step(f, Op::BreakVector, &[31, 211, 187, 214], 1263);
                step(f, Op::BreakVector, &[27, 190, 202, 213], 1264);
                step(f, Op::SubF, &[214, 213, 188], 1265);
                step(f, Op::Select(ValueType::Float), &[15, 188, 156, 180], 1266);
                step(f, Op::MaxF, &[186, 180, 221], 1267);
                step(f, Op::ClampF, &[221, 156, 70, 192], 1268);
                step(f, Op::MakeVector, &[156, 156, 192, 33], 1269);
                step(f, Op::AddV, &[53, 33, 28], 1270);
                step(f, Op::MakeTransform, &[28, 7, 5, 13], 1271);
                step(f, Op::Select(ValueType::Transform), &[13, 13, 15, 14], 1272);
                step(f, Op::Copy(ValueType::Transform), &[14, 13], 1273);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 7, 13], 1274);
                1274
            }
            1274 => {
                step(f, Op::JumpIfFalse, &[20, 1357], 1275)
            }
            1275 => {
                step(f, Op::JumpIfFalse, &[16, 1277], 1276)
            }
            1276 => {
                step(f, Op::Jump, &[1338], 1277)
            }
            1277 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 7, 15], 1278);
                step(f, Op::BreakTransform, &[15, 36, 2, 37], 1279);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1280);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 12], 1281);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 12, 14], 1282);
                step(f, Op::BreakTransform, &[14, 32, 8, 34], 1283);
                step(f, Op::MakeAbsolute, &[14, 5, 13], 1284);
                step(f, Op::BreakTransform, &[13, 35, 7, 39], 1285);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 201], 1286);
                step(f, Op::SmoothStepF, &[201, 156, 158, 206], 1287);
                step(f, Op::RemapF, &[18, 156, 92, 156, 158, 9, 215], 1288);
                step(f, Op::MulF, &[206, 215, 182], 1289);
                step(f, Op::Select(ValueType::Float), &[19, 182, 156, 191], 1290);
                step(f, Op::LerpV, &[32, 35, 191, 40], 1291);
                step(f, Op::MakeTransform, &[40, 1, 5, 16], 1292);
                step(f, Op::BreakTransform, &[16, 41, 9, 29], 1293);
                step(f, Op::SubF, &[158, 19, 195], 1294);
                step(f, Op::MulF, &[198, 195, 212], 1295);
                step(f, Op::MulF, &[17, 212, 181], 1296);
                step(f, Op::FootAvoidance, &[36, 41, 181, 19, 89, 42], 1297);
                step(f, Op::MakeTransform, &[42, 2, 5, 17], 1298);
                step(f, Op::BreakTransform, &[17, 51, 2, 44], 1299);
                step(f, Op::MakeVector, &[156, 156, 63, 17], 1300);
                step(f, Op::AddV, &[51, 17, 20], 1301);
                step(f, Op::SubV, &[51, 17, 52], 1302);
                step(f, Op::LineTrace, &[20, 52, 11, 48, 43, 193], 1303);
                step(f, Op::RotateVector, &[2, 9, 58], 1304);
                step(f, Op::FindQuatBetween, &[58, 43, 10], 1305);
                step(f, Op::MulQ, &[10, 2, 11], 1306);
                step(f, Op::MulF, &[61, 60, 184], 1307);
                step(f, Op::AddF, &[184, 71, 220], 1308);
                step(f, Op::NegF, &[220, 194], 1309);
                step(f, Op::MakeVector, &[156, 194, 156, 19], 1310);
                step(f, Op::RotateVector, &[11, 19, 38], 1311);
                step(f, Op::AddV, &[48, 38, 18], 1312);
                step(f, Op::AddV, &[18, 17, 30], 1313);
                step(f, Op::SubV, &[18, 17, 50], 1314);
                step(f, Op::LineTrace, &[30, 50, 18, 31, 27, 185], 1315);
                step(f, Op::BreakVector, &[31, 199, 203, 189], 1316);
                step(f, Op::BreakVector, &[18, 204, 200, 216], 1317);
                step(f, Op::SubF, &[189, 216, 197], 1318);
                step(f, Op::Select(ValueType::Float), &[18, 197, 156, 207], 1319);
                step(f, Op::AddF, &[67, 71, 183], 1320);
                step(f, Op::MakeVector, &[156, 183, 156, 33], 1321);
                step(f, Op::RotateVector, &[11, 33, 53], 1322);
                step(f, Op::AddV, &[48, 53, 28], 1323);
                step(f, Op::AddV, &[28, 17, 37], 1324);
                step(f, Op::SubV, &[28, 17, 36], 1325);
                step(f, Op::LineTrace, &[37, 36, 15, 42, 44, 210], 1326);
                step(f, Op::BreakVector, &[42, 205, 187, 211], 1327);
                step(f, Op::BreakVector, &[28, 190, 202, 213], 1328);
                step(f, Op::SubF, &[211, 213, 214], 1329);
                step(f, Op::Select(ValueType::Float), &[15, 214, 156, 188], 1330);
                step(f, Op::MaxF, &[207, 188, 180], 1331);
                step(f, Op::ClampF, &[180, 156, 70, 186], 1332);
                step(f, Op::MakeVector, &[156, 156, 186, 51], 1333);
                step(f, Op::AddV, &[48, 51, 20], 1334);
                step(f, Op::MakeTransform, &[20, 11, 5, 18], 1335);
                step(f, Op::Select(ValueType::Transform), &[11, 18, 17, 19], 1336);
                step(f, Op::Copy(ValueType::Transform), &[19, 17], 1337);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 7, 17], 1338);
                1338
            }
            1338 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 7, 18], 1339);
                step(f, Op::BreakTransform, &[18, 52, 2, 43], 1340);
                step(f, Op::SubV, &[52, 54, 58], 1341);
                step(f, Op::LengthV, &[58, 221], 1342);
                step(f, Op::SubF, &[72, 73, 192], 1343);
                step(f, Op::SubF, &[221, 192, 193], 1344);
                step(f, Op::MulF, &[73, 161, 184], 1345);
                step(f, Op::ClampF, &[193, 156, 184, 220], 1346);
                step(f, Op::MulF, &[220, 220, 194], 1347);
                step(f, Op::MulF, &[73, 172, 185], 1348);
                step(f, Op::DivF, &[194, 185, 199], 1349);
                step(f, Op::SubF, &[221, 199, 203], 1350);
                step(f, Op::DivF, &[203, 221, 200], 1351);
                step(f, Op::ScaleV, &[58, 200, 19], 1352);
                step(f, Op::AddV, &[54, 19, 38], 1353);
                step(f, Op::MakeTransform, &[38, 2, 5, 19], 1354);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 19], 1355);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 19], 1356);
                step(f, Op::Jump, &[1523], 1357)
            }
            1357 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 7, 18], 1358);
                step(f, Op::BreakTransform, &[18, 52, 2, 43], 1359);
                step(f, Op::SubV, &[52, 54, 58], 1360);
                step(f, Op::LengthV, &[58, 221], 1361);
                step(f, Op::SubF, &[72, 73, 192], 1362);
                step(f, Op::SubF, &[221, 192, 193], 1363);
                step(f, Op::MulF, &[73, 161, 184], 1364);
                step(f, Op::ClampF, &[193, 156, 184, 220], 1365);
                step(f, Op::MulF, &[220, 220, 194], 1366);
                step(f, Op::MulF, &[73, 172, 185], 1367);
                step(f, Op::DivF, &[194, 185, 199], 1368);
                step(f, Op::SubF, &[221, 199, 203], 1369);
                step(f, Op::DivF, &[203, 221, 200], 1370);
                step(f, Op::ScaleV, &[58, 200, 19], 1371);
                step(f, Op::AddV, &[54, 19, 38], 1372);
                step(f, Op::MakeTransform, &[38, 2, 5, 19], 1373);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 7, 15], 1374);
                step(f, Op::ClampF, &[219, 156, 158, 204], 1375);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[6, 5], 1376);
                step(f, Op::ArrayReset(Elem::Vec3), &[5], 1377);
                step(f, Op::BreakTransform, &[19, 27, 10, 30], 1378);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 27], 1379);
                step(f, Op::UnitV, &[2, 50], 1380);
                step(f, Op::LengthV, &[2, 189], 1381);
                step(f, Op::RemapF, &[189, 156, 74, 156, 75, 9, 216], 1382);
                step(f, Op::ScaleV, &[50, 216, 31], 1383);
                step(f, Op::SubV, &[27, 31, 18], 1384);
                step(f, Op::MakeVector, &[156, 156, 77, 33], 1385);
                step(f, Op::AddV, &[18, 33, 53], 1386);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 53], 1387);
                step(f, Op::RemapF, &[189, 156, 74, 156, 79, 9, 197], 1388);
                step(f, Op::MakeVector, &[156, 156, 197, 17], 1389);
                step(f, Op::AddV, &[53, 17, 36], 1390);
                step(f, Op::BreakTransform, &[15, 37, 11, 44], 1391);
                step(f, Op::BreakVector, &[37, 183, 210, 187], 1392);
                step(f, Op::BreakVector, &[27, 205, 190, 202], 1393);
                step(f, Op::SubF, &[187, 202, 211], 1394);
                step(f, Op::MaxF, &[211, 156, 213], 1395);
                step(f, Op::MulF, &[213, 81, 214], 1396);
                step(f, Op::MinF, &[214, 82, 188], 1397);
                step(f, Op::AbsF, &[211, 207], 1398);
                step(f, Op::RemapF, &[207, 156, 85, 156, 84, 9, 180], 1399);
                step(f, Op::AddF, &[188, 180, 186], 1400);
                step(f, Op::MakeVector, &[156, 156, 186, 42], 1401);
                step(f, Op::AddV, &[36, 42, 28], 1402);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 28], 1403);
                step(f, Op::RemapF, &[189, 156, 74, 156, 76, 9, 192], 1404);
                step(f, Op::ScaleV, &[50, 192, 48], 1405);
                step(f, Op::AddV, &[37, 48, 51], 1406);
                step(f, Op::MakeVector, &[156, 156, 78, 20], 1407);
                step(f, Op::AddV, &[51, 20, 43], 1408);
                step(f, Op::RemapF, &[189, 156, 74, 156, 80, 9, 184], 1409);
                step(f, Op::MakeVector, &[156, 156, 184, 52], 1410);
                step(f, Op::AddV, &[43, 52, 58], 1411);
                step(f, Op::NegF, &[211, 193], 1412);
                step(f, Op::MaxF, &[193, 156, 220], 1413);
                step(f, Op::MulF, &[220, 83, 185], 1414);
                step(f, Op::AddF, &[185, 180, 194], 1415);
                step(f, Op::MakeVector, &[156, 156, 194, 19], 1416);
                step(f, Op::AddV, &[58, 19, 54], 1417);
                step(f, Op::LerpV, &[28, 54, 157, 38], 1418);
                step(f, Op::GetTransform, &[35, 2, 9, 17], 1419);
                step(f, Op::BreakTransform, &[17, 30, 2, 31], 1420);
                step(f, Op::BreakVector, &[30, 199, 203, 221], 1421);
                step(f, Op::SubF, &[158, 18, 200], 1422);
                step(f, Op::MulF, &[86, 200, 216], 1423);
                step(f, Op::MulF, &[17, 216, 197], 1424);
                step(f, Op::QuatFromAxisAngle, &[9, 197, 2], 1425);
                step(f, Op::SubV, &[38, 30, 18], 1426);
                step(f, Op::BreakVector, &[18, 183, 210, 190], 1427);
                step(f, Op::MakeVector, &[183, 210, 156, 33], 1428);
                step(f, Op::RotateVector, &[2, 33, 17], 1429);
                step(f, Op::BreakVector, &[17, 205, 187, 202], 1430);
                step(f, Op::AddF, &[199, 205, 213], 1431);
                step(f, Op::AddF, &[203, 187, 214], 1432);
                step(f, Op::BreakVector, &[38, 207, 188, 186], 1433);
                step(f, Op::MakeVector, &[213, 214, 186, 53], 1434);
                step(f, Op::DistanceV, &[27, 37, 192], 1435);
                step(f, Op::RemapF, &[192, 161, 173, 156, 158, 9, 189], 1436);
                step(f, Op::LerpV, &[38, 53, 189, 44], 1437);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 44], 1438);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 54], 1439);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 43], 1440);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 37], 1441);
                step(f, Op::JumpIfFalse, &[8, 1443], 1442)
            }
            1442 => {
                step(f, Op::DrawSpline, &[5, 2, 5, 157, 11], 1443);
                1443
            }
            1443 => {
                step(f, Op::Spline, &[5, 204, 2, 36, 42], 1444);
                step(f, Op::SlerpQ, &[10, 11, 204, 2], 1445);
                step(f, Op::MulF, &[204, 166, 184], 1446);
                step(f, Op::SinF, &[184, 211], 1447);
                step(f, Op::SmoothStepF, &[204, 156, 100, 193], 1448);
                step(f, Op::MulF, &[211, 193, 220], 1449);
                step(f, Op::MulF, &[220, 87, 180], 1450);
                step(f, Op::SlerpQ, &[2, 1, 180, 10], 1451);
                step(f, Op::MakeTransform, &[36, 10, 5, 18], 1452);
                step(f, Op::Copy(ValueType::Transform), &[18, 19], 1453);
                step(f, Op::BreakTransform, &[19, 50, 11, 48], 1454);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1455);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 12], 1456);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 12, 14], 1457);
                step(f, Op::BreakTransform, &[14, 32, 8, 34], 1458);
                step(f, Op::GreaterF, &[26, 156, 14], 1459);
                step(f, Op::InterpolateTransform, &[2, 3, 27, 7], 1460);
                step(f, Op::Select(ValueType::Transform), &[14, 7, 2, 5], 1461);
                step(f, Op::MakeAbsolute, &[14, 5, 13], 1462);
                step(f, Op::BreakTransform, &[13, 35, 7, 39], 1463);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 201], 1464);
                step(f, Op::SmoothStepF, &[201, 156, 158, 206], 1465);
                step(f, Op::RemapF, &[18, 156, 92, 156, 158, 9, 215], 1466);
                step(f, Op::MulF, &[206, 215, 182], 1467);
                step(f, Op::Select(ValueType::Float), &[19, 182, 156, 191], 1468);
                step(f, Op::LerpV, &[32, 35, 191, 40], 1469);
                step(f, Op::MakeTransform, &[40, 1, 5, 16], 1470);
                step(f, Op::BreakTransform, &[16, 41, 9, 29], 1471);
                step(f, Op::SubF, &[158, 18, 198], 1472);
                step(f, Op::SubF, &[158, 19, 195], 1473);
                step(f, Op::MulF, &[198, 195, 212], 1474);
                step(f, Op::MulF, &[17, 212, 181], 1475);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 13], 1476);
                step(f, Op::Select(ValueType::Float), &[13, 90, 156, 185], 1477);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 219], 1478);
                step(f, Op::ClampF, &[219, 156, 158, 204], 1479);
                step(f, Op::MulF, &[204, 166, 194], 1480);
                step(f, Op::SinF, &[194, 221], 1481);
                step(f, Op::MulF, &[221, 221, 200], 1482);
                step(f, Op::MulF, &[185, 200, 216], 1483);
                step(f, Op::AddF, &[89, 216, 197], 1484);
                step(f, Op::FootAvoidance, &[50, 41, 181, 19, 197, 20], 1485);
                step(f, Op::SubV, &[20, 50, 51], 1486);
                step(f, Op::LengthV, &[51, 190], 1487);
                step(f, Op::AddF, &[190, 216, 183], 1488);
                step(f, Op::DivF, &[190, 183, 210], 1489);
                step(f, Op::MulF, &[114, 161, 202], 1490);
                step(f, Op::LessEqualF, &[190, 202, 16], 1491);
                step(f, Op::MulF, &[114, 172, 199], 1492);
                step(f, Op::DivF, &[190, 199, 205], 1493);
                step(f, Op::DivF, &[114, 190, 187], 1494);
                step(f, Op::SubF, &[158, 187, 203], 1495);
                step(f, Op::Select(ValueType::Float), &[16, 205, 203, 188], 1496);
                step(f, Op::GreaterF, &[114, 156, 18], 1497);
                step(f, Op::Select(ValueType::Float), &[18, 19, 156, 207], 1498);
                step(f, Op::LerpF, &[210, 188, 207, 186], 1499);
                step(f, Op::LessF, &[201, 219, 15], 1500);
                step(f, Op::LessEqualF, &[91, 156, 11], 1501);
                step(f, Op::SmoothStepF, &[201, 156, 91, 213], 1502);
                step(f, Op::MulF, &[213, 18, 214], 1503);
                step(f, Op::SubF, &[158, 214, 192], 1504);
                step(f, Op::Select(ValueType::Float), &[11, 158, 192, 189], 1505);
                step(f, Op::Select(ValueType::Float), &[15, 189, 158, 184], 1506);
                step(f, Op::MulF, &[186, 184, 193], 1507);
                step(f, Op::SmoothStepF, &[204, 156, 91, 211], 1508);
                step(f, Op::Select(ValueType::Float), &[11, 158, 211, 220], 1509);
                step(f, Op::MulF, &[193, 220, 180], 1510);
                step(f, Op::ScaleV, &[51, 180, 52], 1511);
                step(f, Op::AddV, &[50, 52, 19], 1512);
                step(f, Op::MulF, &[6, 147, 206], 1513);
                step(f, Op::MulF, &[206, 200, 215], 1514);
                step(f, Op::MakeVector, &[156, 156, 215, 58], 1515);
                step(f, Op::AddV, &[19, 58, 28], 1516);
                step(f, Op::MakeTransform, &[28, 11, 5, 15], 1517);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 15], 1518);
                step(f, Op::ScaleV, &[51, 193, 31], 1519);
                step(f, Op::AddV, &[50, 31, 30], 1520);
                step(f, Op::AddV, &[30, 58, 18], 1521);
                step(f, Op::MakeTransform, &[18, 11, 5, 17], 1522);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 17], 1523);
                1523
            }
            1523 => {
                step(f, Op::JumpIfFalse, &[14, 1546], 1524)
            }
            1524 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 7, 18], 1525);
                step(f, Op::BreakTransform, &[18, 33, 2, 17], 1526);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 7, 19], 1527);
                step(f, Op::BreakTransform, &[19, 27, 10, 38], 1528);
                step(f, Op::MulF, &[26, 26, 182], 1529);
                step(f, Op::LerpV, &[33, 27, 182, 53], 1530);
                step(f, Op::SubF, &[158, 26, 191], 1531);
                step(f, Op::MulF, &[26, 191, 194], 1532);
                step(f, Op::MulF, &[149, 161, 221], 1533);
                step(f, Op::MulF, &[194, 221, 185], 1534);
                step(f, Op::MakeVector, &[156, 156, 185, 44], 1535);
                step(f, Op::AddV, &[53, 44, 54], 1536);
                step(f, Op::SlerpQ, &[2, 10, 26, 8], 1537);
                step(f, Op::MakeTransform, &[54, 8, 5, 7], 1538);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 7], 1539);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 7, 18], 1540);
                step(f, Op::BreakTransform, &[18, 33, 2, 17], 1541);
                step(f, Op::LerpV, &[33, 27, 182, 53], 1542);
                step(f, Op::AddV, &[53, 44, 54], 1543);
                step(f, Op::SlerpQ, &[2, 10, 26, 8], 1544);
                step(f, Op::MakeTransform, &[54, 8, 5, 7], 1545);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 7], 1546);
                1546
            }
            1546 => {
                step(f, Op::GreaterEqualF, &[219, 158, 20], 1547);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 7, 20], 1548);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 6], 1549);
                step(f, Op::BreakTransform, &[6, 59, 6, 47], 1550);
                step(f, Op::SubF, &[158, 219, 222], 1551);
                step(f, Op::MulF, &[13, 10, 196], 1552);
                step(f, Op::MulF, &[222, 196, 208], 1553);
                step(f, Op::ScaleV, &[2, 208, 49], 1554);
                step(f, Op::AddV, &[59, 49, 55], 1555);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1556);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 12], 1557);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 12], 1558);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 12, 4], 1559);
                step(f, Op::BreakTransform, &[4, 56, 3, 46], 1560);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 12, 8], 1561);
                step(f, Op::BreakTransform, &[8, 45, 5, 57], 1562);
                step(f, Op::LessEqualF, &[93, 156, 17], 1563);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 201], 1564);
                step(f, Op::SmoothStepF, &[201, 156, 93, 209], 1565);
                step(f, Op::Select(ValueType::Float), &[17, 158, 209, 217], 1566);
                step(f, Op::LerpV, &[56, 45, 217, 16], 1567);
                step(f, Op::MakeTransform, &[16, 1, 5, 9], 1568);
                step(f, Op::Select(ValueType::Transform), &[12, 4, 9, 10], 1569);
                step(f, Op::MakeAbsolute, &[10, 5, 11], 1570);
                step(f, Op::Select(ValueType::Transform), &[19, 11, 10, 12], 1571);
                step(f, Op::BreakTransform, &[12, 23, 4, 21], 1572);
                step(f, Op::SubF, &[158, 19, 195], 1573);
                step(f, Op::MulF, &[198, 195, 212], 1574);
                step(f, Op::MulF, &[17, 212, 181], 1575);
                step(f, Op::FootAvoidance, &[55, 23, 181, 19, 89, 24], 1576);
                step(f, Op::RemapF, &[18, 92, 158, 156, 158, 9, 218], 1577);
                step(f, Op::LerpV, &[55, 24, 218, 25], 1578);
                step(f, Op::FootAvoidance, &[25, 23, 20, 19, 115, 26], 1579);
                step(f, Op::LerpV, &[25, 26, 19, 22], 1580);
                step(f, Op::MakeTransform, &[22, 1, 5, 14], 1581);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 7, 14], 1582);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 7, 13], 1583);
                step(f, Op::BreakTransform, &[13, 43, 7, 37], 1584);
                step(f, Op::MakeVector, &[156, 156, 58, 42], 1585);
                step(f, Op::AddV, &[43, 42, 36], 1586);
                step(f, Op::GetTransform, &[0, 2, 9, 16], 1587);
                step(f, Op::BreakTransform, &[16, 48, 9, 34], 1588);
                step(f, Op::MakeTransform, &[36, 9, 5, 15], 1589);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 7, 20], 1590);
                step(f, Op::GetTransform, &[20, 2, 9, 17], 1591);
                step(f, Op::BreakTransform, &[17, 39, 11, 32], 1592);
                step(f, Op::SubV, &[39, 48, 35], 1593);
                step(f, Op::AddV, &[36, 35, 40], 1594);
                step(f, Op::FootPivots, &[36, 40, 60, 59, 58, 61, 29, 41, 20], 1595);
                step(f, Op::GetParent, &[0, 18], 1596);
                step(f, Op::GetParent, &[18, 19], 1597);
                step(f, Op::GetTransform, &[19, 2, 10, 19], 1598);
                step(f, Op::BreakTransform, &[19, 52, 2, 19], 1599);
                step(f, Op::SubV, &[43, 52, 28], 1600);
                step(f, Op::DotV, &[28, 8, 197], 1601);
                step(f, Op::RemapF, &[197, 95, 94, 96, 156, 9, 216], 1602);
                step(f, Op::LengthV, &[2, 183], 1603);
                step(f, Op::RemapF, &[183, 156, 106, 156, 158, 9, 202], 1604);
                step(f, Op::MulF, &[216, 202, 199], 1605);
                step(f, Op::QuatFromAxisAngle, &[12, 199, 10], 1606);
                step(f, Op::RotateAroundPoint, &[15, 29, 10, 18], 1607);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 190], 1608);
                step(f, Op::SmoothStepF, &[190, 156, 100, 187], 1609);
                step(f, Op::SubF, &[158, 190, 203], 1610);
                step(f, Op::SmoothStepF, &[203, 156, 100, 205], 1611);
                step(f, Op::MulF, &[187, 205, 188], 1612);
                step(f, Op::LerpF, &[99, 158, 188, 207], 1613);
                step(f, Op::MulF, &[199, 207, 210], 1614);
                step(f, Op::QuatFromAxisAngle, &[12, 210, 8], 1615);
                step(f, Op::SubV, &[41, 29, 51], 1616);
                step(f, Op::RotateVector, &[8, 51, 31], 1617);
                step(f, Op::AddV, &[29, 31, 50], 1618);
                step(f, Op::RemapF, &[197, 97, 95, 98, 156, 9, 213], 1619);
                step(f, Op::MulF, &[213, 202, 214], 1620);
                step(f, Op::QuatFromAxisAngle, &[12, 214, 6], 1621);
                step(f, Op::RotateAroundPoint, &[18, 50, 6, 7], 1622);
                step(f, Op::RemapF, &[197, 101, 102, 156, 103, 9, 192], 1623);
                step(f, Op::RotateVector, &[7, 9, 30], 1624);
                step(f, Op::BreakVector, &[30, 189, 184, 186], 1625);
                step(f, Op::CosF, &[105, 204], 1626);
                step(f, Op::CosF, &[104, 211], 1627);
                step(f, Op::RemapF, &[186, 204, 211, 156, 158, 9, 220], 1628);
                step(f, Op::MulF, &[202, 220, 180], 1629);
                step(f, Op::MulF, &[192, 180, 200], 1630);
                step(f, Op::QuatFromAxisAngle, &[12, 200, 3], 1631);
                step(f, Op::RotateAroundPoint, &[7, 20, 3, 6], 1632);
                step(f, Op::SubF, &[158, 18, 206], 1633);
                step(f, Op::MulF, &[17, 206, 215], 1634);
                step(f, Op::LimitRotationAroundZ, &[7, 215, 107, 5], 1635);
                step(f, Op::RotateAroundPoint, &[6, 43, 5, 8], 1636);
                step(f, Op::BreakTransform, &[8, 58, 4, 18], 1637);
                step(f, Op::ArrayAt(Elem::Float), &[4, 7, 193], 1638);
                step(f, Op::MulF, &[193, 108, 191], 1639);
                step(f, Op::MulF, &[191, 109, 194], 1640);
                step(f, Op::AddF, &[191, 109, 221], 1641);
                step(f, Op::DivF, &[194, 221, 185], 1642);
                step(f, Op::MakeVector, &[156, 156, 185, 38], 1643);
                step(f, Op::AddV, &[58, 38, 17], 1644);
                step(f, Op::MakeTransform, &[17, 4, 18, 4], 1645);
                step(f, Op::ArraySetAt(Elem::Transform), &[7, 7, 4], 1646);
                step(f, Op::JumpIfFalse, &[8, 1651], 1647)
            }
            1647 => {
                step(f, Op::DrawPoint, &[20, 174, 12], 1648);
                step(f, Op::DrawPoint, &[29, 174, 8], 1649);
                step(f, Op::DrawPoint, &[50, 174, 9], 1650);
                step(f, Op::DrawTransform, &[13, 173, 157], 1651);
                1651
            }
            1651 => {
                step(f, Op::Jump, &[723], 1652)
            }
            1652 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1653);
                step(f, Op::Copy(ValueType::Int), &[2, 8], 1654);
                1654
            }
            1654 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 8, 1, 6, 9, 1693], 1655)
            }
            1655 => {
                step(f, Op::GetParent, &[1, 22], 1656);
                step(f, Op::GetParent, &[22, 23], 1657);
                step(f, Op::GetParent, &[23, 24], 1658);
                step(f, Op::GetTransform, &[24, 2, 10, 9], 1659);
                step(f, Op::BreakTransform, &[9, 27, 9, 33], 1660);
                step(f, Op::LengthV, &[1, 182], 1661);
                step(f, Op::ClavicleOffset, &[15, 182, 121, 125, 219], 1662);
                step(f, Op::MakeVector, &[156, 156, 219, 44], 1663);
                step(f, Op::AddV, &[27, 44, 53], 1664);
                step(f, Op::MakeTransform, &[53, 9, 5, 5], 1665);
                step(f, Op::SetTransform, &[24, 5, 2, 9, 158], 1666);
                step(f, Op::GetTransform, &[1, 2, 10, 10], 1667);
                step(f, Op::GetTransform, &[23, 2, 10, 11], 1668);
                step(f, Op::BreakTransform, &[11, 54, 11, 47], 1669);
                step(f, Op::Equals(Elem::Int), &[6, 2, 13], 1670);
                step(f, Op::Select(ValueType::Int), &[13, 3, 2, 11], 1671);
                step(f, Op::ArrayAt(Elem::Float), &[0, 11, 196], 1672);
                step(f, Op::ArmSwingRotation, &[196, 1, 0, 122, 165, 175, 158, 121, 119, 120, 123, 165, 158, 222], 1673);
                step(f, Op::QuatFromAxisAngle, &[12, 222, 2], 1674);
                step(f, Op::RotateAroundPoint, &[10, 54, 2, 12], 1675);
                step(f, Op::BreakTransform, &[12, 49, 10, 59], 1676);
                step(f, Op::RemapF, &[182, 156, 121, 156, 124, 9, 208], 1677);
                step(f, Op::MakeVector, &[156, 156, 208, 46], 1678);
                step(f, Op::AddV, &[49, 46, 57], 1679);
                step(f, Op::MakeTransform, &[57, 10, 5, 14], 1680);
                step(f, Op::Select(ValueType::Vec3), &[13, 13, 12, 45], 1681);
                step(f, Op::Select(ValueType::Vec3), &[13, 8, 14, 56], 1682);
                step(f, Op::ArrayAt(Elem::Vec3), &[4, 6, 16], 1683);
                step(f, Op::TwoBoneIK, &[23, 22, 1, 14, 45, 56, 16, 2, 158, 10, 176, 177, 9, 16, 201], 1684);
                step(f, Op::JumpIfFalse, &[8, 1692], 1685)
            }
            1685 => {
                step(f, Op::GetTransform, &[23, 2, 10, 11], 1686);
                step(f, Op::BreakTransform, &[11, 54, 11, 47], 1687);
                step(f, Op::GetTransform, &[1, 2, 10, 10], 1688);
                step(f, Op::RotateAroundPoint, &[10, 54, 2, 12], 1689);
                step(f, Op::BreakTransform, &[12, 49, 10, 59], 1690);
                step(f, Op::AddV, &[49, 46, 57], 1691);
                step(f, Op::DrawLine, &[54, 57, 157, 8], 1692);
                1692
            }
            1692 => {
                step(f, Op::Jump, &[1654], 1693)
            }
            1693 => {
                step(f, Op::NegF, &[5, 209], 1694);
                step(f, Op::MakeVector, &[156, 156, 209, 21], 1695);
                step(f, Op::MakeTransform, &[21, 1, 5, 16], 1696);
                step(f, Op::SetTransform, &[36, 16, 2, 9, 158], 1697);
                step(f, Op::Copy(ValueType::Float), &[163, 217], 1698);
                step(f, Op::Copy(ValueType::Bool), &[10, 18], 1699);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 11], 1700);
                step(f, Op::Copy(ValueType::Int), &[2, 12], 1701);
                step(f, Op::MakeVector, &[156, 156, 63, 24], 1702);
                1702
            }
            1702 => {
                step(f, Op::ForEachNext(Elem::Transform), &[11, 12, 17, 7, 10, 1714], 1703)
            }
            1703 => {
                step(f, Op::BreakTransform, &[17, 55, 8, 23], 1704);
                step(f, Op::AddV, &[55, 24, 25], 1705);
                step(f, Op::SubV, &[55, 24, 26], 1706);
                step(f, Op::SphereTrace, &[25, 26, 62, 15, 22, 37, 195], 1707);
                step(f, Op::BreakVector, &[22, 198, 212, 181], 1708);
                step(f, Op::LessF, &[181, 217, 11], 1709);
                step(f, Op::And, &[15, 11, 14], 1710);
                step(f, Op::JumpIfFalse, &[14, 1713], 1711)
            }
            1711 => {
                step(f, Op::Copy(ValueType::Float), &[181, 217], 1712);
                step(f, Op::Copy(ValueType::Bool), &[9, 18], 1713);
                1713
            }
            1713 => {
                step(f, Op::Jump, &[1702], 1714)
            }
            1714 => {
                step(f, Op::Select(ValueType::Float), &[18, 217, 156, 218], 1715);
                step(f, Op::ClampF, &[218, 68, 69, 183], 1716);
                step(f, Op::Copy(ValueType::Float), &[183, 216], 1717);
                step(f, Op::SubF, &[158, 26, 190], 1718);
                step(f, Op::MulF, &[216, 190, 203], 1719);
                step(f, Op::SubF, &[158, 146, 187], 1720);
                step(f, Op::MulF, &[5, 187, 205], 1721);
                step(f, Op::AddF, &[203, 205, 188], 1722);
                step(f, Op::MakeVector, &[21, 156, 156, 42], 1723);
                step(f, Op::MakeVector, &[188, 156, 156, 34], 1724);
                step(f, Op::Select(ValueType::Float), &[2, 188, 22, 199], 1725);
                step(f, Op::MakeVector, &[199, 156, 156, 32], 1726);
                step(f, Op::Copy(ValueType::Float), &[56, 207], 1727);
                step(f, Op::Copy(ValueType::Float), &[57, 210], 1728);
                step(f, Op::SubV, &[34, 32, 39], 1729);
                step(f, Op::DeltaTime, &[213], 1730);
                step(f, Op::DivF, &[210, 213, 214], 1731);
                step(f, Op::ScaleV, &[39, 214, 48], 1732);
                step(f, Op::AddV, &[34, 48, 35], 1733);
                step(f, Op::AddV, &[32, 48, 36], 1734);
                step(f, Op::SubV, &[42, 36, 40], 1735);
                step(f, Op::FloatLerp, &[156, 158, 207, 197], 1736);
                step(f, Op::SubF, &[158, 197, 184], 1737);
                step(f, Op::ScaleV, &[40, 184, 19], 1738);
                step(f, Op::AddV, &[35, 19, 52], 1739);
                step(f, Op::MulF, &[207, 213, 189], 1740);
                step(f, Op::GreaterF, &[189, 156, 20], 1741);
                step(f, Op::DivF, &[197, 189, 186], 1742);
                step(f, Op::Select(ValueType::Float), &[20, 186, 158, 204], 1743);
                step(f, Op::ScaleV, &[39, 204, 28], 1744);
                step(f, Op::SubV, &[52, 28, 41], 1745);
                step(f, Op::Copy(ValueType::Vec3), &[41, 51], 1746);
                step(f, Op::BreakVector, &[51, 211, 202, 220], 1747);
                step(f, Op::Select(ValueType::Float), &[1, 188, 211, 180], 1748);
                step(f, Op::Copy(ValueType::Float), &[180, 21], 1749);
                step(f, Op::Copy(ValueType::Float), &[188, 22], 1750);
                step(f, Op::GetTransform, &[37, 2, 9, 19], 1751);
                step(f, Op::BreakTransform, &[19, 31, 6, 30], 1752);
                step(f, Op::PelvisLean, &[1, 128, 133, 134, 192, 200], 1753);
                step(f, Op::LengthV, &[2, 206], 1754);
                step(f, Op::RemapF, &[206, 156, 128, 156, 126, 9, 215], 1755);
                step(f, Op::MulF, &[18, 127, 193], 1756);
                step(f, Op::SubF, &[158, 193, 191], 1757);
                step(f, Op::MulF, &[215, 191, 194], 1758);
                step(f, Op::MulF, &[15, 178, 221], 1759);
                step(f, Op::SinF, &[221, 185], 1760);
                step(f, Op::MulF, &[194, 185, 219], 1761);
                step(f, Op::MulF, &[219, 190, 196], 1762);
                step(f, Op::AddF, &[196, 21, 222], 1763);
                step(f, Op::SubF, &[222, 5, 182], 1764);
                step(f, Op::MakeVector, &[156, 200, 182, 43], 1765);
                step(f, Op::AddV, &[31, 43, 38], 1766);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 2, 15], 1767);
                step(f, Op::BreakTransform, &[15, 58, 3, 17], 1768);
                step(f, Op::BreakVector, &[58, 208, 201, 209], 1769);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 3, 18], 1770);
                step(f, Op::BreakTransform, &[18, 18, 7, 20], 1771);
                step(f, Op::BreakVector, &[18, 195, 198, 212], 1772);
                step(f, Op::SubF, &[209, 212, 181], 1773);
                step(f, Op::PelvisSideLean, &[181, 135, 136, 217], 1774);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 2, 7], 1775);
                step(f, Op::BreakTransform, &[7, 29, 5, 50], 1776);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 3, 6], 1777);
                step(f, Op::BreakTransform, &[6, 33, 4, 27], 1778);
                step(f, Op::SlerpQ, &[5, 4, 157, 9], 1779);
                step(f, Op::EulerFromQuat, &[9, 2, 44], 1780);
                step(f, Op::BreakVector, &[44, 218, 183, 216], 1781);
                step(f, Op::RemapF, &[206, 129, 128, 156, 130, 9, 187], 1782);
                step(f, Op::SubV, &[58, 18, 53], 1783);
                step(f, Op::RotateVector, &[0, 8, 16], 1784);
                step(f, Op::DotV, &[53, 16, 203], 1785);
                step(f, Op::MulF, &[187, 203, 205], 1786);
                step(f, Op::AddF, &[216, 205, 199], 1787);
                step(f, Op::MakeVector, &[192, 217, 199, 45], 1788);
                step(f, Op::QuatFromEuler, &[45, 2, 11], 1789);
                step(f, Op::MakeTransform, &[38, 11, 5, 8], 1790);
                step(f, Op::SetTransform, &[38, 8, 2, 9, 158], 1791);
                step(f, Op::GetTransform, &[39, 3, 9, 4], 1792);
                step(f, Op::BreakTransform, &[4, 56, 2, 47], 1793);
                step(f, Op::QuatFromAxisAngle, &[9, 205, 10], 1794);
                step(f, Op::DivF, &[131, 174, 210], 1795);
                step(f, Op::QuatScale, &[10, 210, 8], 1796);
                step(f, Op::MulQ, &[2, 8, 6], 1797);
                step(f, Op::MakeTransform, &[56, 6, 5, 13], 1798);
                step(f, Op::SetTransform, &[40, 13, 3, 9, 158], 1799);
                step(f, Op::GetTransform, &[41, 3, 9, 9], 1800);
                step(f, Op::BreakTransform, &[9, 59, 3, 46], 1801);
                step(f, Op::MulQ, &[3, 8, 7], 1802);
                step(f, Op::MakeTransform, &[59, 7, 5, 5], 1803);
                step(f, Op::SetTransform, &[42, 5, 3, 9, 158], 1804);
                step(f, Op::GetTransform, &[43, 3, 9, 14], 1805);
                step(f, Op::BreakTransform, &[14, 49, 4, 54], 1806);
                step(f, Op::MulQ, &[4, 8, 5], 1807);
                step(f, Op::MakeTransform, &[49, 5, 5, 11], 1808);
                step(f, Op::SetTransform, &[44, 11, 3, 9, 158], 1809);
                step(f, Op::GetTransform, &[45, 3, 9, 10], 1810);
                step(f, Op::BreakTransform, &[10, 57, 9, 21], 1811);
                step(f, Op::QuatScale, &[10, 132, 11], 1812);
                step(f, Op::MulQ, &[9, 11, 2], 1813);
                step(f, Op::MakeTransform, &[57, 2, 5, 12], 1814);
                step(f, Op::SetTransform, &[46, 12, 3, 9, 158], 1815);
                step(f, Op::Or, &[1, 2, 17], 1816);
                step(f, Op::Copy(ValueType::Float), &[156, 214], 1817);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1818);
                step(f, Op::Copy(ValueType::Int), &[2, 9], 1819);
                1819
            }
            1819 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 9, 25, 11, 6, 1866], 1820)
            }
            1820 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 11, 12], 1821);
                step(f, Op::GetParent, &[25, 26], 1822);
                step(f, Op::GetParent, &[26, 27], 1823);
                step(f, Op::GetTransform, &[27, 2, 10, 16], 1824);
                step(f, Op::BreakTransform, &[16, 23, 6, 55], 1825);
                step(f, Op::BreakVector, &[23, 184, 207, 213], 1826);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 11, 17], 1827);
                step(f, Op::BreakTransform, &[17, 25, 3, 26], 1828);
                step(f, Op::BreakVector, &[25, 189, 197, 186], 1829);
                step(f, Op::ArrayAt(Elem::Float), &[1, 11, 204], 1830);
                step(f, Op::MulF, &[204, 137, 202], 1831);
                step(f, Op::MulF, &[202, 202, 220], 1832);
                step(f, Op::SubF, &[184, 189, 211], 1833);
                step(f, Op::SubF, &[207, 197, 180], 1834);
                step(f, Op::MakeVector, &[211, 180, 156, 37], 1835);
                step(f, Op::DotV, &[37, 37, 188], 1836);
                step(f, Op::SubF, &[220, 188, 193], 1837);
                step(f, Op::SqrtF, &[193, 191], 1838);
                step(f, Op::AddF, &[186, 191, 215], 1839);
                step(f, Op::SubF, &[213, 215, 221], 1840);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 11, 19], 1841);
                step(f, Op::BreakTransform, &[19, 22, 7, 24], 1842);
                step(f, Op::BreakVector, &[22, 185, 194, 190], 1843);
                step(f, Op::AddF, &[190, 58, 219], 1844);
                step(f, Op::MinF, &[186, 219, 196], 1845);
                step(f, Op::AddF, &[196, 191, 222], 1846);
                step(f, Op::SubF, &[213, 222, 182], 1847);
                step(f, Op::Equals(Elem::Int), &[11, 2, 19], 1848);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 8], 1849);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 8, 13], 1850);
                step(f, Op::ArrayAt(Elem::Float), &[2, 8, 200], 1851);
                step(f, Op::RemapF, &[200, 157, 158, 156, 158, 9, 201], 1852);
                step(f, Op::RemapF, &[200, 156, 140, 158, 156, 9, 208], 1853);
                step(f, Op::MaxF, &[201, 208, 195], 1854);
                step(f, Op::Select(ValueType::Float), &[13, 158, 195, 198], 1855);
                step(f, Op::LerpF, &[221, 182, 198, 209], 1856);
                step(f, Op::ArrayAt(Elem::Float), &[2, 11, 212], 1857);
                step(f, Op::RemapF, &[212, 157, 158, 156, 158, 9, 181], 1858);
                step(f, Op::MulF, &[209, 181, 183], 1859);
                step(f, Op::RemapF, &[212, 156, 140, 158, 156, 9, 218], 1860);
                step(f, Op::MulF, &[221, 218, 206], 1861);
                step(f, Op::MaxF, &[183, 206, 187], 1862);
                step(f, Op::Select(ValueType::Float), &[12, 221, 187, 203], 1863);
                step(f, Op::MaxF, &[214, 203, 216], 1864);
                step(f, Op::Copy(ValueType::Float), &[216, 214], 1865);
                step(f, Op::Jump, &[1819], 1866)
            }
            1866 => {
                step(f, Op::ClampF, &[214, 156, 138, 192], 1867);
                step(f, Op::Copy(ValueType::Float), &[192, 199], 1868);
                step(f, Op::MakeVector, &[23, 156, 156, 34], 1869);
                step(f, Op::MakeVector, &[199, 156, 156, 32], 1870);
                step(f, Op::MakeVector, &[24, 156, 156, 48], 1871);
                step(f, Op::GreaterF, &[199, 23, 16], 1872);
                step(f, Op::Select(ValueType::Float), &[16, 142, 139, 217], 1873);
                step(f, Op::Copy(ValueType::Float), &[57, 205], 1874);
                step(f, Op::SubV, &[32, 48, 36], 1875);
                step(f, Op::DeltaTime, &[210], 1876);
                step(f, Op::DivF, &[205, 210, 204], 1877);
                step(f, Op::ScaleV, &[36, 204, 42], 1878);
                step(f, Op::AddV, &[32, 42, 40], 1879);
                step(f, Op::AddV, &[48, 42, 19], 1880);
                step(f, Op::SubV, &[34, 19, 35], 1881);
                step(f, Op::FloatLerp, &[156, 158, 217, 202], 1882);
                step(f, Op::SubF, &[158, 202, 184], 1883);
                step(f, Op::ScaleV, &[35, 184, 39], 1884);
                step(f, Op::AddV, &[40, 39, 28], 1885);
                step(f, Op::MulF, &[217, 210, 189], 1886);
                step(f, Op::GreaterF, &[189, 156, 11], 1887);
                step(f, Op::DivF, &[202, 189, 197], 1888);
                step(f, Op::Select(ValueType::Float), &[11, 197, 158, 207], 1889);
                step(f, Op::ScaleV, &[36, 207, 52], 1890);
                step(f, Op::SubV, &[28, 52, 41], 1891);
                step(f, Op::Copy(ValueType::Vec3), &[41, 51], 1892);
                step(f, Op::BreakVector, &[51, 180, 211, 188], 1893);
                step(f, Op::Select(ValueType::Float), &[17, 199, 180, 220], 1894);
                step(f, Op::Copy(ValueType::Float), &[220, 23], 1895);
                step(f, Op::Copy(ValueType::Float), &[199, 24], 1896);
                step(f, Op::GetTransform, &[47, 2, 10, 15], 1897);
                step(f, Op::BreakTransform, &[15, 30, 4, 31], 1898);
                step(f, Op::MakeVector, &[156, 156, 23, 43], 1899);
                step(f, Op::SubV, &[30, 43, 17], 1900);
                step(f, Op::MakeTransform, &[17, 4, 5, 18], 1901);
                step(f, Op::SetTransform, &[48, 18, 2, 9, 158], 1902);
                step(f, Op::JumpIfFalse, &[8, 1908], 1903)
            }
            1903 => {
                step(f, Op::GetTransform, &[47, 2, 10, 15], 1904);
                step(f, Op::BreakTransform, &[15, 30, 4, 31], 1905);
                step(f, Op::SubV, &[30, 43, 17], 1906);
                step(f, Op::MakeTransform, &[17, 4, 5, 18], 1907);
                step(f, Op::DrawTransform, &[18, 179, 157], 1908);
                1908
            }
            1908 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1909);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 1910);
                1910
            }
            1910 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 7, 2, 10, 12, 1959], 1911)
            }
            1911 => {
                step(f, Op::GetParent, &[2, 29], 1912);
                step(f, Op::GetParent, &[29, 30], 1913);
                step(f, Op::GetTransform, &[30, 2, 10, 7], 1914);
                step(f, Op::BreakTransform, &[7, 20, 8, 29], 1915);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 10, 6], 1916);
                step(f, Op::BreakTransform, &[6, 50, 5, 27], 1917);
                step(f, Op::SubV, &[50, 20, 33], 1918);
                step(f, Op::LengthV, &[33, 193], 1919);
                step(f, Op::ArrayAt(Elem::Float), &[1, 10, 215], 1920);
                step(f, Op::MulF, &[215, 150, 185], 1921);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 10, 15], 1922);
                step(f, Op::MulF, &[19, 116, 194], 1923);
                step(f, Op::ArrayAt(Elem::Float), &[2, 10, 190], 1924);
                step(f, Op::ClampF, &[190, 156, 158, 186], 1925);
                step(f, Op::LessF, &[186, 157, 14], 1926);
                step(f, Op::SmoothStepF, &[186, 152, 153, 219], 1927);
                step(f, Op::MulF, &[186, 166, 191], 1928);
                step(f, Op::SinF, &[191, 196], 1929);
                step(f, Op::MaxF, &[219, 196, 213], 1930);
                step(f, Op::Select(ValueType::Float), &[14, 213, 196, 222], 1931);
                step(f, Op::MulF, &[222, 151, 200], 1932);
                step(f, Op::Select(ValueType::Float), &[15, 194, 200, 201], 1933);
                step(f, Op::SubF, &[185, 201, 208], 1934);
                step(f, Op::SubF, &[193, 208, 195], 1935);
                step(f, Op::MaxF, &[195, 156, 182], 1936);
                step(f, Op::MulF, &[182, 182, 198], 1937);
                step(f, Op::AddF, &[182, 201, 181], 1938);
                step(f, Op::DivF, &[198, 181, 209], 1939);
                step(f, Op::SubF, &[193, 209, 212], 1940);
                step(f, Op::DivF, &[212, 193, 218], 1941);
                step(f, Op::ScaleV, &[33, 218, 44], 1942);
                step(f, Op::AddV, &[20, 44, 18], 1943);
                step(f, Op::ClampSpatially, &[18, 20, 156, 185, 58], 1944);
                step(f, Op::MakeTransform, &[58, 5, 5, 8], 1945);
                step(f, Op::Equals(Elem::Int), &[10, 2, 18], 1946);
                step(f, Op::Select(ValueType::Vec3), &[18, 13, 12, 16], 1947);
                step(f, Op::Select(ValueType::Vec3), &[18, 8, 14, 53], 1948);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 10, 4], 1949);
                step(f, Op::BreakTransform, &[4, 45, 10, 38], 1950);
                step(f, Op::ArrayAt(Elem::Vec3), &[3, 10, 47], 1951);
                step(f, Op::KneeVector, &[10, 0, 47, 154, 155, 56], 1952);
                step(f, Op::TwoBoneIK, &[30, 29, 2, 8, 16, 53, 56, 2, 158, 10, 176, 177, 9, 20, 183], 1953);
                step(f, Op::JumpIfFalse, &[8, 1958], 1954)
            }
            1954 => {
                step(f, Op::GetTransform, &[29, 2, 10, 13], 1955);
                step(f, Op::BreakTransform, &[13, 46, 9, 59], 1956);
                step(f, Op::AddV, &[46, 56, 54], 1957);
                step(f, Op::DrawLine, &[46, 54, 157, 15], 1958);
                1958
            }
            1958 => {
                step(f, Op::Jump, &[1910], 1959)
            }
            1959 => {
                step(f, Op::End, &[], 1960)
            }
            _ => return,
        } };
    }
}
