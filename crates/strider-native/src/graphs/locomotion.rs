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
    fingerprint: 0x5b3e0c343832b63d,
    forward,
};

fn forward(f: &mut Frame<'_>) {
    let mut pc: usize = 100;
    loop {
        // SAFETY: each `step` is an instruction of the program this code was generated
        // from, with its own operands; `NATIVE` runs only on that program (fingerprint).
        pc = unsafe { match pc {
            100 => {
                step(f, Op::Not, &[0, 1, 1, 1], 101);
                step(f, Op::WorldTransform, &[6], 102);
                step(f, Op::BreakTransform, &[6, 19, 2, 22], 103);
                step(f, Op::Select(ValueType::Transform), &[0, 0, 6, 4], 104);
                step(f, Op::BreakTransform, &[4, 20, 2, 17], 105);
                step(f, Op::SubV, &[19, 20, 21], 106);
                step(f, Op::LengthV, &[21, 183], 107);
                step(f, Op::GreaterF, &[183, 41, 2, 2, 2], 108);
                step(f, Op::MakeRelative, &[4, 6, 5], 109);
                step(f, Op::Select(ValueType::Transform), &[2, 3, 5, 2, 2, 2], 110);
                step(f, Op::InverseT, &[4, 5], 111);
                step(f, Op::MulT, &[6, 5, 1, 1, 1], 112);
                step(f, Op::TransformVector, &[2, 0, 18], 113);
                step(f, Op::InverseT, &[6, 4], 114);
                step(f, Op::DeltaTime, &[184], 115);
                step(f, Op::DivF, &[160, 184, 182], 116);
                step(f, Op::ScaleV, &[21, 182, 22], 117);
                step(f, Op::TransformVector, &[4, 22, 17], 118);
                step(f, Op::BreakVector, &[17, 183, 185, 186], 119);
                step(f, Op::BreakVector, &[21, 186, 187, 188], 120);
                step(f, Op::AddF, &[2, 188, 186], 121);
                step(f, Op::Select(ValueType::Float), &[2, 158, 186, 187], 122);
                step(f, Op::MakeVector, &[183, 185, 158, 19], 123);
                step(f, Op::LengthV, &[19, 188], 124);
                step(f, Op::MulF, &[188, 145, 186], 125);
                step(f, Op::MulF, &[186, 184, 188], 126);
                step(f, Op::NegF, &[188, 184], 127);
                step(f, Op::ClampF, &[187, 184, 188, 186], 128);
                step(f, Op::MulF, &[186, 182, 184], 129);
                step(f, Op::MakeVector, &[183, 185, 184, 20], 130);
                step(f, Op::Select(ValueType::Vec3), &[2, 18, 20, 22], 131);
                step(f, Op::VectorLerp, &[18, 22, 42, 158, 0, 0, 0], 132);
                step(f, Op::TransformVector, &[2, 1, 17], 133);
                step(f, Op::TransformVector, &[2, 0, 18], 134);
                step(f, Op::Select(ValueType::Vec3), &[2, 18, 20, 22], 135);
                step(f, Op::VectorLerp, &[17, 22, 43, 158, 1, 1, 1], 136);
                step(f, Op::LengthV, &[22, 0, 0, 0], 137);
                step(f, Op::SubF, &[187, 186, 188], 138);
                step(f, Op::NegF, &[146, 182], 139);
                step(f, Op::ClampF, &[188, 182, 146, 3], 140);
                step(f, Op::SubF, &[188, 3, 1, 1, 1, 3, 3], 141);
                step(f, Op::JumpIfFalse, &[2, 155], 142)
            }
            142 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 12], 143);
                step(f, Op::Copy(ValueType::Int), &[2, 6], 144);
                144
            }
            144 => {
                step(f, Op::ForEachNext(Elem::Bone), &[12, 6, 13, 8, 7, 154], 145)
            }
            145 => {
                step(f, Op::ArrayAt(Elem::Transform), &[8, 8, 5], 146);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 8, 5], 147);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 8, 5], 148);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 8, 5], 149);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 8, 5], 150);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 8, 5], 151);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 8, 5], 152);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 8, 5], 153);
                step(f, Op::Jump, &[144], 154)
            }
            154 => {
                step(f, Op::Copy(ValueType::Float), &[158, 22], 155);
                155
            }
            155 => {
                step(f, Op::Copy(ValueType::Transform), &[6, 0], 156);
                step(f, Op::Copy(ValueType::Bool), &[9, 0], 157);
                step(f, Op::JumpIfFalse, &[8, 163], 158)
            }
            158 => {
                step(f, Op::GetTransform, &[33, 2, 9, 4], 159);
                step(f, Op::BreakTransform, &[4, 21, 2, 19], 160);
                step(f, Op::ScaleV, &[0, 161, 18], 161);
                step(f, Op::AddV, &[21, 18, 20], 162);
                step(f, Op::DrawArrow, &[21, 20, 159, 8], 163);
                163
            }
            163 => {
                step(f, Op::Copy(ValueType::Float), &[158, 183], 164);
                step(f, Op::Copy(ValueType::Float), &[160, 184], 165);
                step(f, Op::Copy(ValueType::Bool), &[10, 11], 166);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[8, 9], 167);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 168);
                step(f, Op::MakeVector, &[158, 158, 64, 17], 169);
                169
            }
            169 => {
                step(f, Op::ForEachNext(Elem::Transform), &[9, 7, 5, 8, 6, 179], 170)
            }
            170 => {
                step(f, Op::BreakTransform, &[5, 22, 2, 19], 171);
                step(f, Op::TransformPoint, &[2, 22, 18], 172);
                step(f, Op::LerpV, &[18, 22, 160, 20], 173);
                step(f, Op::AddV, &[20, 17, 21], 174);
                step(f, Op::SubV, &[20, 17, 19], 175);
                step(f, Op::LineTrace, &[21, 19, 12, 18, 22, 185], 176);
                step(f, Op::JumpIfFalse, &[12, 178], 177)
            }
            177 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 11], 178);
                178
            }
            178 => {
                step(f, Op::Jump, &[169, 11, 11], 179)
            }
            179 => {
                step(f, Op::Or, &[11, 7, 12], 180);
                step(f, Op::NotEquals(Elem::Bool), &[12, 5, 13], 181);
                step(f, Op::JumpIfFalse, &[13, 208], 182)
            }
            182 => {
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 14], 183);
                step(f, Op::JumpIfFalse, &[14, 208, 1, 1], 184)
            }
            184 => {
                step(f, Op::Copy(ValueType::Int), &[2, 6], 185);
                185
            }
            185 => {
                step(f, Op::ForNext, &[6, 1, 8, 208], 186)
            }
            186 => {
                step(f, Op::AddF, &[183, 184, 186], 187);
                step(f, Op::MulF, &[186, 159, 187], 188);
                step(f, Op::Copy(ValueType::Bool), &[10, 15], 189);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[8, 10], 190);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 191);
                step(f, Op::MakeVector, &[158, 158, 64, 20], 192);
                192
            }
            192 => {
                step(f, Op::ForEachNext(Elem::Transform), &[10, 7, 6, 8, 9, 202], 193)
            }
            193 => {
                step(f, Op::BreakTransform, &[6, 18, 2, 19], 194);
                step(f, Op::TransformPoint, &[2, 18, 21], 195);
                step(f, Op::LerpV, &[21, 18, 187, 22], 196);
                step(f, Op::AddV, &[22, 20, 17], 197);
                step(f, Op::SubV, &[22, 20, 19], 198);
                step(f, Op::LineTrace, &[17, 19, 16, 18, 21, 182], 199);
                step(f, Op::JumpIfFalse, &[16, 201], 200)
            }
            200 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 15], 201);
                201
            }
            201 => {
                step(f, Op::Jump, &[192, 15, 15], 202)
            }
            202 => {
                step(f, Op::Equals(Elem::Bool), &[15, 6, 16], 203);
                step(f, Op::JumpIfFalse, &[16, 206], 204)
            }
            204 => {
                step(f, Op::Copy(ValueType::Float), &[187, 183], 205);
                step(f, Op::Jump, &[207], 206)
            }
            206 => {
                step(f, Op::Copy(ValueType::Float), &[187, 184], 207);
                207
            }
            207 => {
                step(f, Op::Jump, &[185], 208)
            }
            208 => {
                step(f, Op::Select(ValueType::Float), &[5, 162, 160, 188], 209);
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 14], 210);
                step(f, Op::AddF, &[183, 184, 186], 211);
                step(f, Op::MulF, &[186, 159, 185], 212);
                step(f, Op::Select(ValueType::Float), &[14, 185, 159, 182], 213);
                step(f, Op::Select(ValueType::Float), &[13, 182, 158, 187], 214);
                step(f, Op::MulF, &[188, 187, 183], 215);
                step(f, Op::DeltaTime, &[184], 216);
                step(f, Op::DivF, &[184, 150, 186], 217);
                step(f, Op::MulF, &[183, 186, 185], 218);
                step(f, Op::AddF, &[26, 185, 187], 219);
                step(f, Op::ClampF, &[187, 158, 160, 188], 220);
                step(f, Op::Select(ValueType::Float), &[12, 162, 160, 184], 221);
                step(f, Op::SubF, &[160, 182, 183], 222);
                step(f, Op::Select(ValueType::Float), &[13, 183, 160, 185], 223);
                step(f, Op::MulF, &[184, 185, 187], 224);
                step(f, Op::MulF, &[187, 186, 182], 225);
                step(f, Op::AddF, &[188, 182, 183], 226);
                step(f, Op::ClampF, &[183, 158, 160, 26], 227);
                step(f, Op::SmoothStepF, &[26, 158, 160, 184], 228);
                step(f, Op::AddF, &[27, 184, 185], 229);
                step(f, Op::MulF, &[185, 159, 186], 230);
                step(f, Op::SubF, &[160, 186, 187], 231);
                step(f, Op::MulF, &[187, 187, 182], 232);
                step(f, Op::SubF, &[160, 182, 28, 28, 28], 233);
                step(f, Op::Copy(ValueType::Float), &[184, 27, 26, 26], 234);
                step(f, Op::GreaterF, &[27, 158, 15], 235);
                step(f, Op::TransformVector, &[2, 3, 22], 236);
                step(f, Op::Select(ValueType::Vec3), &[15, 22, 0, 3, 3, 3], 237);
                step(f, Op::LerpV, &[0, 3, 27, 17], 238);
                step(f, Op::Select(ValueType::Vec3), &[15, 17, 0, 2, 2, 2], 239);
                step(f, Op::Copy(ValueType::Bool), &[12, 5], 240);
                step(f, Op::Copy(ValueType::Bool), &[11, 6], 241);
                step(f, Op::Copy(ValueType::Bool), &[10, 7], 242);
                step(f, Op::SubF, &[160, 28, 188], 243);
                step(f, Op::MulF, &[1, 188, 183], 244);
                step(f, Op::SubF, &[3, 2, 185], 245);
                step(f, Op::MulF, &[185, 188, 186], 246);
                step(f, Op::AddF, &[2, 186, 187], 247);
                step(f, Op::MulF, &[187, 188, 182], 248);
                step(f, Op::SubF, &[187, 182, 184], 249);
                step(f, Op::AddF, &[183, 184, 189], 250);
                step(f, Op::AddF, &[4, 189, 190], 251);
                step(f, Op::Copy(ValueType::Float), &[7, 191], 252);
                step(f, Op::Copy(ValueType::Float), &[8, 192], 253);
                step(f, Op::Copy(ValueType::Float), &[4, 193], 254);
                step(f, Op::Copy(ValueType::Float), &[147, 194], 255);
                step(f, Op::Copy(ValueType::Float), &[58, 195], 256);
                step(f, Op::SubF, &[190, 193, 196], 257);
                step(f, Op::DeltaTime, &[197], 258);
                step(f, Op::DivF, &[196, 197, 198], 259);
                step(f, Op::MulF, &[198, 195, 199], 260);
                step(f, Op::AddF, &[190, 199, 200], 261);
                step(f, Op::MulF, &[198, 163, 201], 262);
                step(f, Op::DivF, &[164, 194, 202], 263);
                step(f, Op::DivF, &[201, 202, 203], 264);
                step(f, Op::SubF, &[200, 203, 204], 265);
                step(f, Op::AddF, &[193, 199, 205], 266);
                step(f, Op::SubF, &[191, 205, 206], 267);
                step(f, Op::AddF, &[206, 203, 207], 268);
                step(f, Op::SubF, &[192, 198, 208], 269);
                step(f, Op::MulF, &[202, 207, 209], 270);
                step(f, Op::AddF, &[208, 209, 210], 271);
                step(f, Op::MulF, &[210, 197, 211], 272);
                step(f, Op::AddF, &[207, 211, 212], 273);
                step(f, Op::FloatLerp, &[158, 160, 202, 213], 274);
                step(f, Op::SubF, &[160, 213, 214], 275);
                step(f, Op::MulF, &[212, 214, 215], 276);
                step(f, Op::AddF, &[204, 215, 216], 277);
                step(f, Op::Copy(ValueType::Float), &[216, 217], 278);
                step(f, Op::MulF, &[202, 211, 218], 279);
                step(f, Op::SubF, &[208, 218, 219], 280);
                step(f, Op::MulF, &[219, 214, 220], 281);
                step(f, Op::AddF, &[198, 220, 221], 282);
                step(f, Op::Copy(ValueType::Float), &[221, 222], 283);
                step(f, Op::SubF, &[190, 217, 6], 284);
                step(f, Op::AddF, &[6, 182, 5, 5, 5, 6, 6], 285);
                step(f, Op::Copy(ValueType::Float), &[182, 2], 286);
                step(f, Op::SubF, &[3, 2, 185], 287);
                step(f, Op::MulF, &[185, 188, 186], 288);
                step(f, Op::AddF, &[2, 186, 187], 289);
                step(f, Op::MulF, &[187, 188, 182], 290);
                step(f, Op::SubF, &[187, 182, 184], 291);
                step(f, Op::AddF, &[183, 184, 189], 292);
                step(f, Op::AddF, &[4, 189, 190], 293);
                step(f, Op::Copy(ValueType::Float), &[7, 191], 294);
                step(f, Op::Copy(ValueType::Float), &[8, 192], 295);
                step(f, Op::Copy(ValueType::Float), &[4, 193], 296);
                step(f, Op::Copy(ValueType::Float), &[147, 194], 297);
                step(f, Op::Copy(ValueType::Float), &[58, 195], 298);
                step(f, Op::SubF, &[190, 193, 196], 299);
                step(f, Op::DeltaTime, &[197], 300);
                step(f, Op::DivF, &[196, 197, 198], 301);
                step(f, Op::MulF, &[198, 195, 199], 302);
                step(f, Op::AddF, &[190, 199, 200], 303);
                step(f, Op::MulF, &[198, 163, 201], 304);
                step(f, Op::DivF, &[164, 194, 202], 305);
                step(f, Op::DivF, &[201, 202, 203], 306);
                step(f, Op::SubF, &[200, 203, 204], 307);
                step(f, Op::AddF, &[193, 199, 205], 308);
                step(f, Op::SubF, &[191, 205, 206], 309);
                step(f, Op::AddF, &[206, 203, 207], 310);
                step(f, Op::SubF, &[192, 198, 208], 311);
                step(f, Op::MulF, &[202, 207, 209], 312);
                step(f, Op::AddF, &[208, 209, 210], 313);
                step(f, Op::MulF, &[210, 197, 211], 314);
                step(f, Op::AddF, &[207, 211, 212], 315);
                step(f, Op::FloatLerp, &[158, 160, 202, 213], 316);
                step(f, Op::SubF, &[160, 213, 214], 317);
                step(f, Op::MulF, &[212, 214, 215], 318);
                step(f, Op::AddF, &[204, 215, 216], 319);
                step(f, Op::Copy(ValueType::Float), &[216, 217], 320);
                step(f, Op::MulF, &[202, 211, 218], 321);
                step(f, Op::SubF, &[208, 218, 219], 322);
                step(f, Op::MulF, &[219, 214, 220], 323);
                step(f, Op::AddF, &[198, 220, 221], 324);
                step(f, Op::Copy(ValueType::Float), &[221, 222], 325);
                step(f, Op::Copy(ValueType::Float), &[217, 7], 326);
                step(f, Op::Copy(ValueType::Float), &[7, 191], 327);
                step(f, Op::Copy(ValueType::Float), &[8, 192], 328);
                step(f, Op::Copy(ValueType::Float), &[4, 193], 329);
                step(f, Op::Copy(ValueType::Float), &[147, 194], 330);
                step(f, Op::Copy(ValueType::Float), &[58, 195], 331);
                step(f, Op::SubF, &[190, 193, 196], 332);
                step(f, Op::DeltaTime, &[197], 333);
                step(f, Op::DivF, &[196, 197, 198], 334);
                step(f, Op::MulF, &[198, 195, 199], 335);
                step(f, Op::AddF, &[190, 199, 200], 336);
                step(f, Op::MulF, &[198, 163, 201], 337);
                step(f, Op::DivF, &[164, 194, 202], 338);
                step(f, Op::DivF, &[201, 202, 203], 339);
                step(f, Op::SubF, &[200, 203, 204], 340);
                step(f, Op::AddF, &[193, 199, 205], 341);
                step(f, Op::SubF, &[191, 205, 206], 342);
                step(f, Op::AddF, &[206, 203, 207], 343);
                step(f, Op::SubF, &[192, 198, 208], 344);
                step(f, Op::MulF, &[202, 207, 209], 345);
                step(f, Op::AddF, &[208, 209, 210], 346);
                step(f, Op::MulF, &[210, 197, 211], 347);
                step(f, Op::AddF, &[207, 211, 212], 348);
                step(f, Op::FloatLerp, &[158, 160, 202, 213], 349);
                step(f, Op::SubF, &[160, 213, 214], 350);
                step(f, Op::MulF, &[212, 214, 215], 351);
                step(f, Op::AddF, &[204, 215, 216], 352);
                step(f, Op::Copy(ValueType::Float), &[216, 217], 353);
                step(f, Op::MulF, &[202, 211, 218], 354);
                step(f, Op::SubF, &[208, 218, 219], 355);
                step(f, Op::MulF, &[219, 214, 220], 356);
                step(f, Op::AddF, &[198, 220, 221], 357);
                step(f, Op::Copy(ValueType::Float), &[221, 222], 358);
                step(f, Op::Copy(ValueType::Float), &[222, 8], 359);
                step(f, Op::Copy(ValueType::Float), &[190, 4], 360);
                step(f, Op::LengthV, &[4, 185], 361);
                step(f, Op::GreaterF, &[185, 35, 16], 362);
                step(f, Op::LengthV, &[2, 186], 363);
                step(f, Op::GreaterF, &[186, 35, 14], 364);
                step(f, Op::And, &[16, 14, 13], 365);
                step(f, Op::Select(ValueType::Vec3), &[16, 4, 7, 18], 366);
                step(f, Op::MovementAngleOffset, &[18, 17, 158, 165, 165, 166, 46, 167, 188, 17, 17], 367);
                step(f, Op::SubF, &[188, 17, 182], 368);
                step(f, Op::AddF, &[182, 168, 187], 369);
                step(f, Op::DivF, &[187, 169, 183], 370);
                step(f, Op::FractF, &[183, 184], 371);
                step(f, Op::MulF, &[184, 169, 189], 372);
                step(f, Op::SubF, &[189, 168, 196, 196, 196], 373);
                step(f, Op::AbsF, &[196, 195], 374);
                step(f, Op::Select(ValueType::Vec3), &[14, 2, 7, 19], 375);
                step(f, Op::MovementAngleOffset, &[19, 17, 158, 165, 165, 166, 46, 167, 194, 17, 17], 376);
                step(f, Op::SubF, &[194, 17, 201], 377);
                step(f, Op::AddF, &[201, 168, 200], 378);
                step(f, Op::DivF, &[200, 169, 193], 379);
                step(f, Op::FractF, &[193, 199], 380);
                step(f, Op::MulF, &[199, 169, 191], 381);
                step(f, Op::SubF, &[191, 168, 205, 205, 205], 382);
                step(f, Op::AbsF, &[205, 203], 383);
                step(f, Op::MaxF, &[195, 203, 206], 384);
                step(f, Op::SubF, &[194, 188, 192], 385);
                step(f, Op::AddF, &[192, 168, 209], 386);
                step(f, Op::DivF, &[209, 169, 197], 387);
                step(f, Op::FractF, &[197, 210], 388);
                step(f, Op::MulF, &[210, 169, 207], 389);
                step(f, Op::SubF, &[207, 168, 213, 213, 213], 390);
                step(f, Op::AbsF, &[213, 212], 391);
                step(f, Op::MaxF, &[206, 212, 204], 392);
                step(f, Op::DeltaTime, &[215], 393);
                step(f, Op::DivF, &[58, 215, 216], 394);
                step(f, Op::TransformVector, &[2, 9, 21], 395);
                step(f, Op::BreakVector, &[21, 217, 202, 211], 396);
                step(f, Op::NegF, &[217, 208], 397);
                step(f, Op::Atan2F, &[208, 202, 218], 398);
                step(f, Op::MulF, &[216, 218, 214], 399);
                step(f, Op::QuatFromAxisAngle, &[10, 214, 2], 400);
                step(f, Op::TransformVector, &[2, 4, 20], 401);
                step(f, Op::FloatLerp, &[158, 160, 42, 219], 402);
                step(f, Op::GreaterF, &[219, 158, 15], 403);
                step(f, Op::AddF, &[160, 216, 198], 404);
                step(f, Op::MulF, &[42, 198, 220], 405);
                step(f, Op::FloatLerp, &[158, 160, 220, 221], 406);
                step(f, Op::DivF, &[221, 219, 222], 407);
                step(f, Op::Select(ValueType::Float), &[15, 222, 198, 190], 408);
                step(f, Op::LerpV, &[20, 2, 190, 22], 409);
                step(f, Op::RotateVector, &[2, 22, 17], 410);
                step(f, Op::LengthV, &[17, 185], 411);
                step(f, Op::GreaterF, &[185, 35, 12], 412);
                step(f, Op::Select(ValueType::Vec3), &[12, 17, 7, 18], 413);
                step(f, Op::MovementAngleOffset, &[18, 17, 158, 165, 165, 166, 46, 167, 182, 17, 17], 414);
                step(f, Op::SubF, &[182, 17, 187], 415);
                step(f, Op::AddF, &[187, 168, 183], 416);
                step(f, Op::DivF, &[183, 169, 184], 417);
                step(f, Op::FractF, &[184, 189], 418);
                step(f, Op::MulF, &[189, 169, 196], 419);
                step(f, Op::SubF, &[196, 168, 201, 201, 201], 420);
                step(f, Op::AbsF, &[201, 200], 421);
                step(f, Op::SubF, &[182, 194, 193], 422);
                step(f, Op::AddF, &[193, 168, 199], 423);
                step(f, Op::DivF, &[199, 169, 191], 424);
                step(f, Op::FractF, &[191, 205], 425);
                step(f, Op::MulF, &[205, 169, 195], 426);
                step(f, Op::SubF, &[195, 168, 203, 203, 203], 427);
                step(f, Op::AbsF, &[203, 188], 428);
                step(f, Op::MaxF, &[200, 188, 192], 429);
                step(f, Op::MaxF, &[204, 192, 209], 430);
                step(f, Op::LessF, &[209, 170, 11], 431);
                step(f, Op::And, &[13, 11, 17], 432);
                step(f, Op::SubV, &[2, 20, 21], 433);
                step(f, Op::DotV, &[20, 21, 197], 434);
                step(f, Op::NegF, &[197, 210], 435);
                step(f, Op::DotV, &[21, 21, 207], 436);
                step(f, Op::DivF, &[210, 207, 206], 437);
                step(f, Op::ClampF, &[206, 158, 190, 212], 438);
                step(f, Op::LerpV, &[20, 2, 212, 22], 439);
                step(f, Op::LengthV, &[22, 211], 440);
                step(f, Op::LessF, &[211, 35, 11], 441);
                step(f, Op::Not, &[11, 13], 442);
                step(f, Op::And, &[17, 13, 11], 443);
                step(f, Op::Not, &[16, 13], 444);
                step(f, Op::Not, &[14, 17], 445);
                step(f, Op::And, &[13, 17, 16], 446);
                step(f, Op::Not, &[12, 13], 447);
                step(f, Op::And, &[16, 13, 17], 448);
                step(f, Op::Or, &[11, 17, 12], 449);
                step(f, Op::JumpIfFalse, &[12, 469], 450)
            }
            450 => {
                step(f, Op::MulF, &[44, 215, 217], 451);
                step(f, Op::GreaterF, &[217, 158, 13], 452);
                step(f, Op::FloatLerp, &[158, 160, 44, 202], 453);
                step(f, Op::SubF, &[160, 202, 208], 454);
                step(f, Op::DivF, &[208, 202, 214], 455);
                step(f, Op::DivF, &[160, 217, 220], 456);
                step(f, Op::SubF, &[214, 220, 221], 457);
                step(f, Op::AddF, &[216, 221, 198], 458);
                step(f, Op::Select(ValueType::Float), &[13, 198, 158, 222], 459);
                step(f, Op::MulF, &[213, 222, 185], 460);
                step(f, Op::AddF, &[194, 185, 187], 461);
                step(f, Op::SinF, &[187, 183], 462);
                step(f, Op::NegF, &[183, 184], 463);
                step(f, Op::CosF, &[187, 189], 464);
                step(f, Op::MakeVector, &[184, 189, 158, 17], 465);
                step(f, Op::Select(ValueType::Vec3), &[14, 17, 7, 18], 466);
                step(f, Op::MovementAngleOffset, &[18, 17, 158, 44, 45, 166, 168, 167, 196], 467);
                step(f, Op::Copy(ValueType::Float), &[196, 17], 468);
                step(f, Op::Jump, &[523], 469)
            }
            469 => {
                step(f, Op::DivF, &[215, 48, 201], 470);
                step(f, Op::AddF, &[201, 159, 182], 471);
                step(f, Op::FloorF, &[182, 193], 472);
                step(f, Op::MaxF, &[193, 160, 199], 473);
                step(f, Op::ToInt, &[199, 8, 8, 8], 474);
                step(f, Op::Copy(ValueType::Int), &[2, 9], 475);
                step(f, Op::MulF, &[48, 159, 191], 476);
                step(f, Op::SubF, &[58, 191, 205], 477);
                step(f, Op::DivF, &[205, 215, 195], 478);
                step(f, Op::DivF, &[44, 199, 203], 479);
                step(f, Op::DivF, &[45, 199, 188], 480);
                step(f, Op::SubF, &[166, 47, 200], 481);
                step(f, Op::GreaterF, &[47, 158, 16], 482);
                482
            }
            482 => {
                step(f, Op::ForNext, &[9, 8, 7, 523], 483)
            }
            483 => {
                step(f, Op::ToFloat, &[7, 192], 484);
                step(f, Op::AddF, &[192, 160, 204], 485);
                step(f, Op::DivF, &[204, 199, 209], 486);
                step(f, Op::AddF, &[209, 195, 197], 487);
                step(f, Op::SubF, &[197, 160, 207], 488);
                step(f, Op::MulF, &[207, 218, 210], 489);
                step(f, Op::QuatFromAxisAngle, &[10, 210, 2], 490);
                step(f, Op::MulF, &[42, 197, 190], 491);
                step(f, Op::FloatLerp, &[158, 160, 190, 206], 492);
                step(f, Op::DivF, &[206, 219, 212], 493);
                step(f, Op::Select(ValueType::Float), &[15, 212, 197, 211], 494);
                step(f, Op::LerpV, &[20, 2, 211, 21], 495);
                step(f, Op::RotateVector, &[2, 21, 22], 496);
                step(f, Op::LengthV, &[22, 202], 497);
                step(f, Op::GreaterF, &[202, 35, 11], 498);
                step(f, Op::Select(ValueType::Vec3), &[11, 22, 7, 17], 499);
                step(f, Op::MulF, &[215, 197, 208], 500);
                step(f, Op::MulF, &[11, 208, 217], 501);
                step(f, Op::AddF, &[15, 217, 214], 502);
                step(f, Op::FractF, &[214, 220], 503);
                step(f, Op::MulF, &[220, 163, 216], 504);
                step(f, Op::FractF, &[216, 221], 505);
                step(f, Op::LessF, &[221, 167, 17], 506);
                step(f, Op::MovementAngleOffset, &[17, 17, 158, 165, 165, 166, 46, 167, 198, 17, 17], 507);
                step(f, Op::SubF, &[198, 17, 213], 508);
                step(f, Op::AddF, &[213, 168, 222], 509);
                step(f, Op::DivF, &[222, 169, 185], 510);
                step(f, Op::FractF, &[185, 194], 511);
                step(f, Op::MulF, &[194, 169, 183], 512);
                step(f, Op::SubF, &[183, 168, 187, 187, 187], 513);
                step(f, Op::AbsF, &[187, 184], 514);
                step(f, Op::SmoothStepF, &[184, 200, 166, 189], 515);
                step(f, Op::GreaterF, &[184, 166, 12], 516);
                step(f, Op::Select(ValueType::Float), &[12, 160, 158, 196], 517);
                step(f, Op::Select(ValueType::Float), &[16, 189, 196, 201], 518);
                step(f, Op::Select(ValueType::Float), &[17, 158, 201, 182], 519);
                step(f, Op::LerpF, &[203, 188, 182, 193], 520);
                step(f, Op::MovementAngleOffset, &[17, 17, 220, 193, 193, 166, 46, 167, 191], 521);
                step(f, Op::Copy(ValueType::Float), &[191, 17], 522);
                step(f, Op::Jump, &[482], 523)
            }
            523 => {
                step(f, Op::QuatFromAxisAngle, &[10, 17, 0, 0, 0], 524);
                step(f, Op::SinF, &[17, 205], 525);
                step(f, Op::AbsF, &[205, 192], 526);
                step(f, Op::RemapF, &[192, 49, 50, 158, 160, 9, 204], 527);
                step(f, Op::BreakVector, &[19, 209, 207, 210], 528);
                step(f, Op::AbsF, &[209, 190], 529);
                step(f, Op::DivF, &[190, 186, 206], 530);
                step(f, Op::RemapF, &[206, 49, 50, 158, 160, 9, 212], 531);
                step(f, Op::TransformVector, &[2, 9, 18], 532);
                step(f, Op::DistanceV, &[18, 9, 211], 533);
                step(f, Op::DivF, &[211, 215, 202], 534);
                step(f, Op::RemapF, &[202, 54, 55, 160, 158, 9, 197], 535);
                step(f, Op::MulF, &[212, 197, 208], 536);
                step(f, Op::MaxF, &[204, 208, 18, 18, 18], 537);
                step(f, Op::Copy(ValueType::Vec3), &[2, 4], 538);
                step(f, Op::TransformVector, &[2, 5, 21], 539);
                step(f, Op::BreakTransform, &[2, 22, 2, 17], 540);
                step(f, Op::DeltaTime, &[217], 541);
                step(f, Op::DivF, &[160, 217, 214], 542);
                step(f, Op::ScaleV, &[22, 214, 20], 543);
                step(f, Op::NegV, &[20, 5], 544);
                step(f, Op::SubV, &[5, 21, 19], 545);
                step(f, Op::AddF, &[21, 217, 216], 546);
                step(f, Op::DivF, &[21, 216, 221], 547);
                step(f, Op::ScaleV, &[19, 221, 18], 548);
                step(f, Op::AddV, &[21, 18, 17], 549);
                step(f, Op::DivF, &[217, 216, 198], 550);
                step(f, Op::ScaleV, &[19, 198, 20], 551);
                step(f, Op::AddV, &[5, 20, 18], 552);
                step(f, Op::DotV, &[17, 18, 213], 553);
                step(f, Op::LessF, &[213, 158, 13], 554);
                step(f, Op::TransformVector, &[2, 9, 21], 555);
                step(f, Op::DistanceV, &[21, 9, 222], 556);
                step(f, Op::SubV, &[18, 17, 19], 557);
                step(f, Op::DotV, &[17, 19, 185], 558);
                step(f, Op::NegF, &[185, 194], 559);
                step(f, Op::DotV, &[19, 19, 183], 560);
                step(f, Op::DivF, &[194, 183, 187], 561);
                step(f, Op::ClampF, &[187, 158, 160, 184], 562);
                step(f, Op::SubF, &[160, 184, 189], 563);
                step(f, Op::MulF, &[217, 189, 196], 564);
                step(f, Op::DivF, &[222, 196, 201], 565);
                step(f, Op::RemapF, &[201, 54, 55, 158, 160, 9, 182], 566);
                step(f, Op::BreakVector, &[18, 193, 220, 191], 567);
                step(f, Op::NegF, &[193, 188], 568);
                step(f, Op::Atan2F, &[188, 220, 195], 569);
                step(f, Op::AbsF, &[195, 199], 570);
                step(f, Op::RemapF, &[199, 113, 114, 158, 160, 9, 200], 571);
                step(f, Op::MulF, &[182, 200, 203], 572);
                step(f, Op::DivF, &[222, 217, 218], 573);
                step(f, Op::RemapF, &[218, 54, 55, 158, 160, 9, 219], 574);
                step(f, Op::BreakVector, &[22, 205, 192, 207], 575);
                step(f, Op::NegF, &[192, 210], 576);
                step(f, Op::Atan2F, &[205, 210, 209], 577);
                step(f, Op::AbsF, &[209, 186], 578);
                step(f, Op::RemapF, &[186, 113, 114, 158, 160, 9, 190], 579);
                step(f, Op::MulF, &[219, 190, 206], 580);
                step(f, Op::Select(ValueType::Float), &[13, 203, 206, 211], 581);
                step(f, Op::FloatLerp, &[19, 158, 115, 215], 582);
                step(f, Op::MaxF, &[211, 215, 202], 583);
                step(f, Op::AbsF, &[20, 197], 584);
                step(f, Op::GreaterEqualF, &[197, 114, 14], 585);
                step(f, Op::LessF, &[186, 114, 11], 586);
                step(f, Op::And, &[14, 11, 12], 587);
                step(f, Op::SubF, &[197, 114, 212], 588);
                step(f, Op::SubF, &[197, 186, 204], 589);
                step(f, Op::DivF, &[212, 204, 208], 590);
                step(f, Op::SubF, &[160, 208, 214], 591);
                step(f, Op::MulF, &[115, 214, 221], 592);
                step(f, Op::FloatLerp, &[160, 158, 221, 216], 593);
                step(f, Op::MulF, &[219, 216, 198], 594);
                step(f, Op::Select(ValueType::Float), &[12, 198, 158, 213], 595);
                step(f, Op::MaxF, &[202, 213, 19, 19, 19], 596);
                step(f, Op::Select(ValueType::Float), &[13, 195, 209, 20, 20, 20, 5, 5], 597);
                step(f, Op::Copy(ValueType::Float), &[217, 21], 598);
                step(f, Op::Copy(ValueType::Bool), &[9, 17], 599);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 2], 600);
                step(f, Op::Copy(ValueType::Int), &[2, 6], 601);
                601
            }
            601 => {
                step(f, Op::ForEachNext(Elem::Bool), &[2, 6, 15, 7, 8, 606], 602)
            }
            602 => {
                step(f, Op::Not, &[15, 16], 603);
                step(f, Op::JumpIfFalse, &[16, 605], 604)
            }
            604 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 17], 605);
                605
            }
            605 => {
                step(f, Op::Jump, &[601, 17, 17], 606)
            }
            606 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 11], 607);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 608);
                step(f, Op::Copy(ValueType::Int), &[2, 9], 609);
                609
            }
            609 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 9, 15, 7, 8, 623], 610)
            }
            610 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 7, 4], 611);
                step(f, Op::BreakTransform, &[4, 20, 2, 21], 612);
                step(f, Op::BreakVector, &[20, 185, 183, 194], 613);
                step(f, Op::MakeVector, &[185, 183, 158, 17], 614);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 7, 5], 615);
                step(f, Op::BreakTransform, &[5, 19, 2, 18], 616);
                step(f, Op::BreakVector, &[19, 187, 184, 189], 617);
                step(f, Op::MakeVector, &[187, 184, 158, 22], 618);
                step(f, Op::DistanceV, &[17, 22, 196], 619);
                step(f, Op::GreaterF, &[196, 37, 14], 620);
                step(f, Op::JumpIfFalse, &[14, 622], 621)
            }
            621 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 11], 622);
                622
            }
            622 => {
                step(f, Op::Jump, &[609, 11, 11], 623)
            }
            623 => {
                step(f, Op::And, &[17, 11, 12], 624);
                step(f, Op::LengthV, &[2, 201], 625);
                step(f, Op::GreaterF, &[201, 35, 3], 626);
                step(f, Op::GreaterF, &[0, 35, 13], 627);
                step(f, Op::Or, &[3, 13, 15], 628);
                step(f, Op::Not, &[15, 16], 629);
                step(f, Op::And, &[12, 16, 14], 630);
                step(f, Op::DeltaTime, &[191], 631);
                step(f, Op::MulF, &[191, 40, 193], 632);
                step(f, Op::AddF, &[15, 193, 188], 633);
                step(f, Op::GreaterF, &[15, 159, 11], 634);
                step(f, Op::AddF, &[39, 159, 220], 635);
                step(f, Op::Select(ValueType::Float), &[11, 220, 39, 199], 636);
                step(f, Op::MinF, &[188, 199, 182], 637);
                step(f, Op::NotEquals(Elem::Bool), &[16, 4, 13], 638);
                step(f, Op::Not, &[12, 15], 639);
                step(f, Op::And, &[13, 15, 11], 640);
                step(f, Op::SubF, &[16, 35, 200], 641);
                step(f, Op::SubF, &[16, 201, 222], 642);
                step(f, Op::DivF, &[200, 222, 218], 643);
                step(f, Op::ClampF, &[218, 158, 160, 207], 644);
                step(f, Op::MulF, &[11, 207, 192], 645);
                step(f, Op::RemapF, &[201, 35, 36, 158, 160, 9, 205], 646);
                step(f, Op::MaxF, &[205, 12, 210], 647);
                step(f, Op::Select(ValueType::Float), &[17, 160, 210, 190], 648);
                step(f, Op::Select(ValueType::Float), &[16, 38, 190, 203], 649);
                step(f, Op::Select(ValueType::Float), &[12, 205, 203, 206], 650);
                step(f, Op::SubF, &[160, 27, 211], 651);
                step(f, Op::MulF, &[206, 211, 215], 652);
                step(f, Op::LerpF, &[29, 52, 18, 186], 653);
                step(f, Op::RemapF, &[201, 32, 33, 30, 31, 9, 197], 654);
                step(f, Op::LerpF, &[197, 51, 18, 204], 655);
                step(f, Op::MaxF, &[201, 34, 212], 656);
                step(f, Op::DivF, &[204, 212, 9], 657);
                step(f, Op::AddF, &[186, 9, 10], 658);
                step(f, Op::DivF, &[215, 10, 208], 659);
                step(f, Op::SubF, &[160, 207, 214], 660);
                step(f, Op::MulF, &[208, 214, 221], 661);
                step(f, Op::AddF, &[192, 221, 216], 662);
                step(f, Op::MulF, &[216, 163, 219], 663);
                step(f, Op::AddF, &[11, 208, 198], 664);
                step(f, Op::Select(ValueType::Float), &[11, 219, 198, 202], 665);
                step(f, Op::DivF, &[163, 202, 213], 666);
                step(f, Op::GreaterF, &[202, 158, 13], 667);
                step(f, Op::CycleStep, &[15, 213, 158, 13, 195, 209], 668);
                step(f, Op::Select(ValueType::Float), &[14, 182, 195, 15, 15, 15], 669);
                step(f, Op::Copy(ValueType::Float), &[208, 11, 3, 3, 9, 9, 10, 10], 670);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 671);
                step(f, Op::Copy(ValueType::Int), &[2, 6], 672);
                step(f, Op::DivF, &[186, 10, 217], 673);
                step(f, Op::MulF, &[14, 207, 194], 674);
                step(f, Op::MulF, &[191, 159, 183], 675);
                step(f, Op::SubF, &[217, 13, 185], 676);
                step(f, Op::MaxF, &[185, 158, 189], 677);
                step(f, Op::DivF, &[189, 217, 184], 678);
                step(f, Op::SubF, &[160, 18, 187], 679);
                step(f, Op::SubF, &[160, 19, 196], 680);
                step(f, Op::MulF, &[187, 196, 193], 681);
                step(f, Op::DivF, &[58, 191, 220], 682);
                step(f, Op::SubF, &[159, 220, 188], 683);
                step(f, Op::MulF, &[184, 193, 199], 684);
                step(f, Op::MulF, &[199, 211, 200], 685);
                step(f, Op::MulF, &[200, 143, 222], 686);
                step(f, Op::MulF, &[222, 188, 218], 687);
                step(f, Op::SubF, &[160, 218, 197], 688);
                688
            }
            688 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 6, 14, 8, 7, 732], 689)
            }
            689 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 8, 204], 690);
                step(f, Op::ToFloat, &[8, 212], 691);
                step(f, Op::MulF, &[212, 159, 192], 692);
                step(f, Op::AddF, &[15, 192, 221], 693);
                step(f, Op::FractF, &[221, 216], 694);
                step(f, Op::SubF, &[204, 216, 198], 695);
                step(f, Op::GreaterF, &[198, 159, 15], 696);
                step(f, Op::ArrayAt(Elem::Float), &[2, 8, 219], 697);
                step(f, Op::Select(ValueType::Float), &[15, 158, 219, 202], 698);
                step(f, Op::ArraySetAt(Elem::Float), &[3, 8, 202], 699);
                step(f, Op::SubF, &[160, 204, 209], 700);
                step(f, Op::AddF, &[216, 209, 213], 701);
                step(f, Op::DivF, &[216, 213, 182], 702);
                step(f, Op::MaxF, &[205, 12, 210], 703);
                step(f, Op::Select(ValueType::Float), &[17, 160, 210, 190], 704);
                step(f, Op::Select(ValueType::Float), &[16, 38, 190, 203], 705);
                step(f, Op::Select(ValueType::Float), &[12, 205, 203, 206], 706);
                step(f, Op::MulF, &[206, 211, 215], 707);
                step(f, Op::DivF, &[215, 186, 195], 708);
                step(f, Op::MulF, &[195, 214, 208], 709);
                step(f, Op::AddF, &[194, 208, 207], 710);
                step(f, Op::MulF, &[207, 163, 185], 711);
                step(f, Op::AddF, &[14, 195, 189], 712);
                step(f, Op::Select(ValueType::Float), &[11, 185, 189, 187], 713);
                step(f, Op::MulF, &[187, 183, 196], 714);
                step(f, Op::MulF, &[182, 196, 191], 715);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 8, 13], 716);
                step(f, Op::MulF, &[196, 197, 220], 717);
                step(f, Op::Select(ValueType::Float), &[13, 196, 220, 199], 718);
                step(f, Op::MulF, &[184, 219, 200], 719);
                step(f, Op::MulF, &[200, 193, 188], 720);
                step(f, Op::MulF, &[188, 211, 222], 721);
                step(f, Op::MulF, &[222, 143, 218], 722);
                step(f, Op::Select(ValueType::Float), &[13, 158, 218, 212], 723);
                step(f, Op::SubF, &[199, 212, 192], 724);
                step(f, Op::AddF, &[219, 192, 221], 725);
                step(f, Op::Select(ValueType::Float), &[15, 191, 221, 198], 726);
                step(f, Op::MinF, &[198, 163, 202], 727);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 8, 202], 728);
                step(f, Op::JumpIfFalse, &[15, 730], 729)
            }
            729 => {
                step(f, Op::Copy(ValueType::Float), &[206, 12], 730);
                730
            }
            730 => {
                step(f, Op::ArraySetAt(Elem::Float), &[0, 8, 216], 731);
                step(f, Op::Jump, &[688], 732)
            }
            732 => {
                step(f, Op::Copy(ValueType::Float), &[217, 13], 733);
                step(f, Op::Copy(ValueType::Bool), &[16, 4], 734);
                step(f, Op::Copy(ValueType::Float), &[201, 16], 735);
                step(f, Op::MaxF, &[205, 12, 210], 736);
                step(f, Op::Select(ValueType::Float), &[17, 160, 210, 190], 737);
                step(f, Op::Select(ValueType::Float), &[16, 38, 190, 203], 738);
                step(f, Op::Select(ValueType::Float), &[12, 205, 203, 206], 739);
                step(f, Op::MulF, &[206, 211, 215], 740);
                step(f, Op::DivF, &[215, 186, 195], 741);
                step(f, Op::Copy(ValueType::Float), &[195, 14], 742);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 743);
                step(f, Op::Copy(ValueType::Int), &[2, 9], 744);
                744
            }
            744 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 9, 0, 7, 8, 1660], 745)
            }
            745 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 14], 746);
                step(f, Op::Copy(ValueType::Bool), &[10, 13], 747);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 7, 15], 748);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 204], 749);
                step(f, Op::GreaterEqualF, &[204, 160, 11], 750);
                step(f, Op::And, &[15, 11, 17], 751);
                step(f, Op::Or, &[1, 2, 16], 752);
                step(f, Op::GreaterF, &[27, 158, 12], 753);
                step(f, Op::Or, &[16, 12, 15], 754);
                step(f, Op::Not, &[15, 12], 755);
                step(f, Op::And, &[17, 12, 16], 756);
                step(f, Op::JumpIfFalse, &[16, 863], 757)
            }
            757 => {
                step(f, Op::ArrayAt(Elem::Transform), &[2, 7, 6], 758);
                step(f, Op::BreakTransform, &[6, 21, 2, 20], 759);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 7, 18], 760);
                step(f, Op::SubV, &[21, 18, 19], 761);
                step(f, Op::TransformPoint, &[2, 19, 17], 762);
                step(f, Op::GetTransform, &[34, 2, 9, 4], 763);
                step(f, Op::BreakTransform, &[4, 22, 3, 19], 764);
                step(f, Op::BreakVector, &[22, 209, 213, 208], 765);
                step(f, Op::SubF, &[160, 18, 207], 766);
                step(f, Op::MulF, &[17, 207, 185], 767);
                step(f, Op::QuatFromAxisAngle, &[10, 185, 4], 768);
                step(f, Op::GetTransform, &[0, 2, 9, 5], 769);
                step(f, Op::BreakTransform, &[5, 23, 5, 24], 770);
                step(f, Op::SubV, &[23, 22, 25], 771);
                step(f, Op::BreakVector, &[25, 189, 187, 182], 772);
                step(f, Op::MakeVector, &[189, 187, 158, 26], 773);
                step(f, Op::RotateVector, &[4, 26, 27], 774);
                step(f, Op::BreakVector, &[27, 196, 220, 200], 775);
                step(f, Op::MulF, &[53, 18, 188], 776);
                step(f, Op::Equals(Elem::Int), &[7, 2, 15], 777);
                step(f, Op::Select(ValueType::Float), &[15, 160, 162, 222], 778);
                step(f, Op::MulF, &[188, 222, 218], 779);
                step(f, Op::AddF, &[196, 218, 199], 780);
                step(f, Op::AddF, &[209, 199, 212], 781);
                step(f, Op::AddF, &[213, 220, 192], 782);
                step(f, Op::BreakVector, &[23, 219, 191, 221], 783);
                step(f, Op::SubF, &[221, 59, 198], 784);
                step(f, Op::MakeVector, &[212, 192, 198, 28], 785);
                step(f, Op::MulF, &[9, 159, 202], 786);
                step(f, Op::ScaleV, &[2, 202, 29], 787);
                step(f, Op::AddV, &[28, 29, 30], 788);
                step(f, Op::DistanceV, &[17, 30, 216], 789);
                step(f, Op::TransformVector, &[2, 11, 17], 790);
                step(f, Op::DistanceV, &[17, 11, 183], 791);
                step(f, Op::MaxF, &[216, 183, 184], 792);
                step(f, Op::LessEqualF, &[184, 66, 12], 793);
                step(f, Op::LengthV, &[2, 193], 794);
                step(f, Op::LengthV, &[4, 194], 795);
                step(f, Op::MaxF, &[193, 194, 197], 796);
                step(f, Op::LessEqualF, &[197, 35, 17], 797);
                step(f, Op::And, &[12, 17, 16], 798);
                step(f, Op::ArrayAt(Elem::Bool), &[1, 7, 12], 799);
                step(f, Op::And, &[16, 12, 17], 800);
                step(f, Op::JumpIfFalse, &[17, 803], 801)
            }
            801 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 13], 802);
                step(f, Op::Jump, &[832], 803)
            }
            803 => {
                step(f, Op::MakeVector, &[158, 158, 64, 17], 804);
                step(f, Op::AddV, &[30, 17, 31], 805);
                step(f, Op::SubV, &[30, 17, 32], 806);
                step(f, Op::SphereTrace, &[31, 32, 63, 16, 33, 34, 214], 807);
                step(f, Op::SubV, &[33, 30, 34], 808);
                step(f, Op::DistanceV, &[34, 18, 217], 809);
                step(f, Op::RotateVector, &[0, 9, 33], 810);
                step(f, Op::ScaleV, &[33, 68, 34], 811);
                step(f, Op::AddV, &[31, 34, 35], 812);
                step(f, Op::AddV, &[32, 34, 36], 813);
                step(f, Op::SphereTrace, &[35, 36, 63, 17, 37, 38, 201], 814);
                step(f, Op::SubV, &[37, 30, 39], 815);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 7, 40], 816);
                step(f, Op::DistanceV, &[39, 40, 210], 817);
                step(f, Op::MaxF, &[217, 210, 190], 818);
                step(f, Op::ScaleV, &[33, 65, 40], 819);
                step(f, Op::AddV, &[35, 40, 41], 820);
                step(f, Op::AddV, &[36, 40, 42], 821);
                step(f, Op::SphereTrace, &[41, 42, 63, 18, 43, 44, 203], 822);
                step(f, Op::SubV, &[43, 30, 45], 823);
                step(f, Op::ArrayAt(Elem::Vec3), &[2, 7, 46], 824);
                step(f, Op::DistanceV, &[45, 46, 205], 825);
                step(f, Op::MaxF, &[190, 205, 206], 826);
                step(f, Op::LessEqualF, &[206, 66, 19], 827);
                step(f, Op::And, &[16, 17, 20], 828);
                step(f, Op::And, &[20, 12, 16], 829);
                step(f, Op::And, &[19, 16, 20], 830);
                step(f, Op::JumpIfFalse, &[20, 832], 831)
            }
            831 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 13], 832);
                832
            }
            832 => {
                step(f, Op::JumpIfFalse, &[13, 863], 833)
            }
            833 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 7], 834);
                step(f, Op::BreakTransform, &[7, 46, 6, 47], 835);
                step(f, Op::AddV, &[30, 18, 48, 56, 56, 58, 58], 836);
                step(f, Op::SubV, &[48, 21, 18], 837);
                step(f, Op::DeltaTime, &[211], 838);
                step(f, Op::DivF, &[58, 211, 186], 839);
                step(f, Op::ScaleV, &[18, 186, 49], 840);
                step(f, Op::AddV, &[48, 49, 50], 841);
                step(f, Op::AddV, &[21, 49, 51], 842);
                step(f, Op::SubV, &[46, 51, 49], 843);
                step(f, Op::FloatLerp, &[158, 160, 56, 215], 844);
                step(f, Op::SubF, &[160, 215, 195], 845);
                step(f, Op::ScaleV, &[49, 195, 51], 846);
                step(f, Op::AddV, &[50, 51, 49], 847);
                step(f, Op::MulF, &[56, 211, 183], 848);
                step(f, Op::GreaterF, &[183, 158, 16], 849);
                step(f, Op::DivF, &[215, 183, 216], 850);
                step(f, Op::Select(ValueType::Float), &[16, 216, 160, 184], 851);
                step(f, Op::ScaleV, &[18, 184, 50], 852);
                step(f, Op::SubV, &[49, 50, 51, 51, 51], 853);
                step(f, Op::BreakVector, &[51, 193, 194, 197], 854);
                step(f, Op::ClampF, &[197, 69, 70, 214], 855);
                step(f, Op::MakeVector, &[193, 194, 214, 18], 856);
                step(f, Op::MakeTransform, &[18, 6, 6, 8], 857);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 7, 8], 858);
                step(f, Op::MakeTransform, &[48, 1, 6, 8], 859);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 7, 8], 860);
                step(f, Op::JumpIfFalse, &[12, 862], 861)
            }
            861 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 7], 862);
                862
            }
            862 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 14], 863);
                863
            }
            863 => {
                step(f, Op::JumpIfFalse, &[14, 1061], 864)
            }
            864 => {
                step(f, Op::GetTransform, &[34, 2, 9, 4], 865);
                step(f, Op::BreakTransform, &[4, 22, 3, 19], 866);
                step(f, Op::BreakVector, &[22, 209, 213, 208], 867);
                step(f, Op::SubF, &[160, 18, 207], 868);
                step(f, Op::MulF, &[17, 207, 185], 869);
                step(f, Op::QuatFromAxisAngle, &[10, 185, 4], 870);
                step(f, Op::GetTransform, &[0, 2, 9, 5], 871);
                step(f, Op::BreakTransform, &[5, 23, 5, 24], 872);
                step(f, Op::SubV, &[23, 22, 25], 873);
                step(f, Op::BreakVector, &[25, 189, 187, 182], 874);
                step(f, Op::MakeVector, &[189, 187, 158, 26], 875);
                step(f, Op::RotateVector, &[4, 26, 27], 876);
                step(f, Op::BreakVector, &[27, 196, 220, 200], 877);
                step(f, Op::MulF, &[53, 18, 188], 878);
                step(f, Op::Equals(Elem::Int), &[7, 2, 15], 879);
                step(f, Op::Select(ValueType::Float), &[15, 160, 162, 222], 880);
                step(f, Op::MulF, &[188, 222, 218], 881);
                step(f, Op::AddF, &[196, 218, 199], 882);
                step(f, Op::AddF, &[209, 199, 212], 883);
                step(f, Op::AddF, &[213, 220, 192], 884);
                step(f, Op::BreakVector, &[23, 219, 191, 221], 885);
                step(f, Op::SubF, &[221, 59, 198], 886);
                step(f, Op::MakeVector, &[212, 192, 198, 28], 887);
                step(f, Op::SubF, &[160, 204, 210], 888);
                step(f, Op::MaxF, &[210, 158, 217], 889);
                step(f, Op::MulF, &[13, 10, 190], 890);
                step(f, Op::MulF, &[217, 190, 205], 891);
                step(f, Op::ScaleV, &[2, 205, 49], 892);
                step(f, Op::AddV, &[28, 49, 50], 893);
                step(f, Op::MulF, &[9, 159, 202], 894);
                step(f, Op::ScaleV, &[2, 202, 29], 895);
                step(f, Op::AddV, &[50, 29, 51], 896);
                step(f, Op::RotateVector, &[0, 9, 33], 897);
                step(f, Op::Copy(ValueType::Float), &[165, 206], 898);
                step(f, Op::Copy(ValueType::Vec3), &[7, 18], 899);
                step(f, Op::Copy(ValueType::Vec3), &[10, 48], 900);
                step(f, Op::Copy(ValueType::Bool), &[10, 19], 901);
                step(f, Op::Copy(ValueType::Float), &[165, 186], 902);
                step(f, Op::Copy(ValueType::Vec3), &[7, 50], 903);
                step(f, Op::MulI, &[0, 0, 6, 6, 6], 904);
                step(f, Op::Copy(ValueType::Int), &[2, 8], 905);
                step(f, Op::SubI, &[0, 3, 10], 906);
                step(f, Op::DivI, &[10, 4, 11], 907);
                step(f, Op::MakeVector, &[158, 158, 64, 52], 908);
                step(f, Op::ScaleV, &[33, 68, 53], 909);
                909
            }
            909 => {
                step(f, Op::ForNext, &[8, 6, 10, 956], 910)
            }
            910 => {
                step(f, Op::ModI, &[10, 0, 12], 911);
                step(f, Op::ToFloat, &[12, 195], 912);
                step(f, Op::MulF, &[195, 65, 211], 913);
                step(f, Op::MulF, &[211, 222, 183], 914);
                step(f, Op::MakeVector, &[183, 158, 158, 54], 915);
                step(f, Op::DivI, &[10, 0, 12], 916);
                step(f, Op::SubI, &[12, 11, 10], 917);
                step(f, Op::ToFloat, &[10, 215], 918);
                step(f, Op::MulF, &[215, 65, 216], 919);
                step(f, Op::ScaleV, &[33, 216, 55], 920);
                step(f, Op::AddV, &[54, 55, 56], 921);
                step(f, Op::AddV, &[51, 56, 54], 922);
                step(f, Op::AddV, &[54, 52, 55], 923);
                step(f, Op::SubV, &[54, 52, 57], 924);
                step(f, Op::SphereTrace, &[55, 57, 63, 20, 54, 58, 184], 925);
                step(f, Op::BreakVector, &[54, 197, 193, 194], 926);
                step(f, Op::AddV, &[55, 53, 59], 927);
                step(f, Op::AddV, &[57, 53, 55], 928);
                step(f, Op::SphereTrace, &[59, 55, 63, 13, 57, 60, 214], 929);
                step(f, Op::BreakVector, &[57, 195, 211, 183], 930);
                step(f, Op::SubF, &[194, 183, 215], 931);
                step(f, Op::AbsF, &[215, 216], 932);
                step(f, Op::Select(ValueType::Float), &[20, 158, 160, 184], 933);
                step(f, Op::AddF, &[216, 184, 193], 934);
                step(f, Op::LengthV, &[56, 197], 935);
                step(f, Op::RemapF, &[197, 158, 171, 158, 160, 9, 214], 936);
                step(f, Op::MinF, &[194, 183, 195], 937);
                step(f, Op::RemapF, &[195, 172, 171, 160, 159, 9, 211], 938);
                step(f, Op::AddF, &[214, 211, 215], 939);
                step(f, Op::AddF, &[193, 215, 184], 940);
                step(f, Op::LessF, &[184, 206, 16], 941);
                step(f, Op::And, &[20, 16, 12], 942);
                step(f, Op::JumpIfFalse, &[12, 950], 943)
            }
            943 => {
                step(f, Op::Copy(ValueType::Float), &[206, 186], 944);
                step(f, Op::Copy(ValueType::Vec3), &[18, 50], 945);
                step(f, Op::Copy(ValueType::Float), &[184, 206], 946);
                step(f, Op::Copy(ValueType::Vec3), &[54, 18], 947);
                step(f, Op::Copy(ValueType::Vec3), &[58, 48], 948);
                step(f, Op::Copy(ValueType::Bool), &[9, 19], 949);
                step(f, Op::Jump, &[955], 950)
            }
            950 => {
                step(f, Op::LessF, &[184, 186, 14], 951);
                step(f, Op::And, &[20, 14, 15], 952);
                step(f, Op::JumpIfFalse, &[15, 955], 953)
            }
            953 => {
                step(f, Op::Copy(ValueType::Float), &[184, 186], 954);
                step(f, Op::Copy(ValueType::Vec3), &[54, 50], 955);
                955
            }
            955 => {
                step(f, Op::Jump, &[909], 956)
            }
            956 => {
                step(f, Op::JumpIfFalse, &[8, 958], 957)
            }
            957 => {
                step(f, Op::DrawSphere, &[18, 63, 9], 958);
                958
            }
            958 => {
                step(f, Op::GreaterF, &[67, 158, 13], 959);
                step(f, Op::SubF, &[206, 186, 216], 960);
                step(f, Op::DivF, &[216, 67, 197], 961);
                step(f, Op::PowF, &[173, 197, 183], 962);
                step(f, Op::Select(ValueType::Float), &[13, 183, 158, 194], 963);
                step(f, Op::ScaleV, &[50, 194, 55], 964);
                step(f, Op::AddV, &[18, 55, 59], 965);
                step(f, Op::AddF, &[194, 160, 195], 966);
                step(f, Op::DivF, &[160, 195, 211], 967);
                step(f, Op::ScaleV, &[59, 211, 60, 60, 60, 48, 48, 19, 19], 968);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 7], 969);
                step(f, Op::BreakTransform, &[7, 46, 6, 47], 970);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 204], 971);
                step(f, Op::SubF, &[160, 204, 210], 972);
                step(f, Op::MaxF, &[210, 158, 217], 973);
                step(f, Op::MulF, &[13, 10, 190], 974);
                step(f, Op::MulF, &[217, 190, 205], 975);
                step(f, Op::ScaleV, &[2, 205, 49], 976);
                step(f, Op::SubV, &[60, 49, 57], 977);
                step(f, Op::Select(ValueType::Vec3), &[19, 57, 46, 56], 978);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 7, 6], 979);
                step(f, Op::BreakTransform, &[6, 21, 2, 20, 56, 56, 58, 58], 980);
                step(f, Op::SubV, &[56, 21, 58], 981);
                step(f, Op::DeltaTime, &[214], 982);
                step(f, Op::DivF, &[58, 214, 193], 983);
                step(f, Op::ScaleV, &[58, 193, 54], 984);
                step(f, Op::AddV, &[56, 54, 51], 985);
                step(f, Op::AddV, &[21, 54, 52], 986);
                step(f, Op::SubV, &[46, 52, 53], 987);
                step(f, Op::FloatLerp, &[158, 160, 56, 215], 988);
                step(f, Op::SubF, &[160, 215, 184], 989);
                step(f, Op::ScaleV, &[53, 184, 50], 990);
                step(f, Op::AddV, &[51, 50, 18], 991);
                step(f, Op::MulF, &[56, 214, 186], 992);
                step(f, Op::GreaterF, &[186, 158, 16], 993);
                step(f, Op::DivF, &[215, 186, 206], 994);
                step(f, Op::Select(ValueType::Float), &[16, 206, 160, 216], 995);
                step(f, Op::ScaleV, &[58, 216, 55], 996);
                step(f, Op::SubV, &[18, 55, 59, 59, 59], 997);
                step(f, Op::BreakVector, &[59, 197, 183, 194], 998);
                step(f, Op::ClampF, &[194, 69, 70, 195], 999);
                step(f, Op::MakeVector, &[197, 183, 195, 49], 1000);
                step(f, Op::RotationFromNormal, &[48, 211, 210, 2], 1001);
                step(f, Op::PerFootRotationFactor, &[17, 119, 120, 190], 1002);
                step(f, Op::MulF, &[17, 190, 217], 1003);
                step(f, Op::SubF, &[160, 18, 207], 1004);
                step(f, Op::MulF, &[217, 207, 205], 1005);
                step(f, Op::QuatFromAxisAngle, &[10, 205, 7], 1006);
                step(f, Op::MulQ, &[2, 7, 8], 1007);
                step(f, Op::Select(ValueType::Quat), &[19, 8, 6, 2], 1008);
                step(f, Op::MakeTransform, &[49, 2, 6, 8], 1009);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 7, 8], 1010);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 7], 1011);
                step(f, Op::BreakTransform, &[7, 46, 6, 47], 1012);
                step(f, Op::Select(ValueType::Vec3), &[19, 57, 46, 56], 1013);
                step(f, Op::MakeTransform, &[56, 1, 6, 6], 1014);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 7, 6], 1015);
                step(f, Op::GetTransform, &[34, 2, 9, 4], 1016);
                step(f, Op::BreakTransform, &[4, 22, 3, 19], 1017);
                step(f, Op::BreakVector, &[22, 209, 213, 208], 1018);
                step(f, Op::MulF, &[17, 207, 185], 1019);
                step(f, Op::QuatFromAxisAngle, &[10, 185, 4], 1020);
                step(f, Op::GetTransform, &[0, 2, 9, 5], 1021);
                step(f, Op::BreakTransform, &[5, 23, 5, 24], 1022);
                step(f, Op::SubV, &[23, 22, 25], 1023);
                step(f, Op::BreakVector, &[25, 189, 187, 182], 1024);
                step(f, Op::MakeVector, &[189, 187, 158, 26], 1025);
                step(f, Op::RotateVector, &[4, 26, 27], 1026);
                step(f, Op::BreakVector, &[27, 196, 220, 200], 1027);
                step(f, Op::MulF, &[53, 18, 188], 1028);
                step(f, Op::MulF, &[188, 222, 218], 1029);
                step(f, Op::AddF, &[196, 218, 199], 1030);
                step(f, Op::AddF, &[209, 199, 212], 1031);
                step(f, Op::AddF, &[213, 220, 192], 1032);
                step(f, Op::BreakVector, &[23, 219, 191, 221], 1033);
                step(f, Op::SubF, &[221, 59, 198], 1034);
                step(f, Op::MakeVector, &[212, 192, 198, 28], 1035);
                step(f, Op::MulF, &[9, 159, 202], 1036);
                step(f, Op::ScaleV, &[2, 202, 29], 1037);
                step(f, Op::AddV, &[28, 29, 30], 1038);
                step(f, Op::SubV, &[56, 30, 60], 1039);
                step(f, Op::ArraySetAt(Elem::Vec3), &[0, 7, 60], 1040);
                step(f, Op::ArraySetAt(Elem::Bool), &[1, 7, 19], 1041);
                step(f, Op::GreaterEqualF, &[204, 160, 11], 1042);
                step(f, Op::JumpIfFalse, &[11, 1059], 1043)
            }
            1043 => {
                step(f, Op::MakeVector, &[158, 158, 64, 17], 1044);
                step(f, Op::AddV, &[30, 17, 31], 1045);
                step(f, Op::RotateVector, &[0, 9, 33], 1046);
                step(f, Op::ScaleV, &[33, 68, 34], 1047);
                step(f, Op::AddV, &[31, 34, 35], 1048);
                step(f, Op::SubV, &[30, 17, 32], 1049);
                step(f, Op::AddV, &[32, 34, 36], 1050);
                step(f, Op::SphereTrace, &[35, 36, 63, 17, 37, 38, 201], 1051);
                step(f, Op::SubV, &[37, 30, 39], 1052);
                step(f, Op::ArraySetAt(Elem::Vec3), &[1, 7, 39], 1053);
                step(f, Op::ScaleV, &[33, 65, 40], 1054);
                step(f, Op::AddV, &[35, 40, 41], 1055);
                step(f, Op::AddV, &[36, 40, 42], 1056);
                step(f, Op::SphereTrace, &[41, 42, 63, 18, 43, 44, 203], 1057);
                step(f, Op::SubV, &[43, 30, 45], 1058);
                step(f, Op::ArraySetAt(Elem::Vec3), &[2, 7, 45], 1059);
                1059
            }
            1059 => {
                step(f, Op::JumpIfFalse, &[19, 1061], 1060)
            }
            1060 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 7], 1061);
                1061
            }
            1061 => {
                step(f, Op::ArrayAt(Elem::Float), &[4, 7, 193], 1062);
                step(f, Op::FloatLerp, &[193, 158, 112, 184], 1063);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 7, 12], 1064);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 214], 1065);
                step(f, Op::GreaterEqualF, &[214, 160, 14], 1066);
                step(f, Op::And, &[12, 14, 20], 1067);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 7, 8], 1068);
                step(f, Op::GreaterF, &[27, 158, 15], 1069);
                step(f, Op::InterpolateTransform, &[2, 3, 28, 7], 1070);
                step(f, Op::Select(ValueType::Transform), &[15, 7, 2, 6], 1071);
                step(f, Op::MakeAbsolute, &[8, 6, 4], 1072);
                step(f, Op::BreakTransform, &[4, 20, 7, 21], 1073);
                step(f, Op::RotateVector, &[7, 9, 54], 1074);
                step(f, Op::SubF, &[160, 18, 186], 1075);
                step(f, Op::MulF, &[17, 186, 215], 1076);
                step(f, Op::LimitRotationAroundZ, &[7, 215, 109, 8], 1077);
                step(f, Op::RotateVector, &[8, 9, 52], 1078);
                step(f, Op::CrossV, &[54, 52, 53], 1079);
                step(f, Op::BreakVector, &[53, 206, 216, 194], 1080);
                step(f, Op::DotV, &[54, 52, 183], 1081);
                step(f, Op::Atan2F, &[194, 183, 195], 1082);
                step(f, Op::AbsF, &[195, 197], 1083);
                step(f, Op::Select(ValueType::Float), &[20, 197, 158, 210], 1084);
                step(f, Op::AddF, &[184, 210, 211], 1085);
                step(f, Op::ArraySetAt(Elem::Float), &[4, 7, 211], 1086);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 7, 5], 1087);
                step(f, Op::BreakTransform, &[5, 50, 2, 51], 1088);
                step(f, Op::AddF, &[73, 74, 190], 1089);
                step(f, Op::ClampSpatially, &[20, 50, 158, 190, 58], 1090);
                step(f, Op::MakeTransform, &[58, 8, 6, 8], 1091);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 7, 8], 1092);
                step(f, Op::JumpIfFalse, &[12, 1168], 1093)
            }
            1093 => {
                step(f, Op::JumpIfFalse, &[14, 1095], 1094)
            }
            1094 => {
                step(f, Op::Jump, &[1167], 1095)
            }
            1095 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 4], 1096);
                step(f, Op::BreakTransform, &[4, 18, 6, 55], 1097);
                step(f, Op::SubF, &[160, 214, 217], 1098);
                step(f, Op::MulF, &[13, 10, 205], 1099);
                step(f, Op::MulF, &[217, 205, 208], 1100);
                step(f, Op::ScaleV, &[2, 208, 59], 1101);
                step(f, Op::AddV, &[18, 59, 48], 1102);
                step(f, Op::Equals(Elem::Int), &[7, 2, 13], 1103);
                step(f, Op::Select(ValueType::Int), &[13, 3, 2, 12], 1104);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 16], 1105);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 12, 5], 1106);
                step(f, Op::BreakTransform, &[5, 49, 3, 47], 1107);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 12, 8], 1108);
                step(f, Op::BreakTransform, &[8, 46, 5, 57], 1109);
                step(f, Op::LessEqualF, &[95, 158, 11], 1110);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 207], 1111);
                step(f, Op::SmoothStepF, &[207, 158, 95, 185], 1112);
                step(f, Op::Select(ValueType::Float), &[11, 160, 185, 182], 1113);
                step(f, Op::LerpV, &[49, 46, 182, 19], 1114);
                step(f, Op::MakeTransform, &[19, 1, 6, 9], 1115);
                step(f, Op::Select(ValueType::Transform), &[16, 5, 9, 10], 1116);
                step(f, Op::MakeAbsolute, &[10, 6, 11], 1117);
                step(f, Op::Select(ValueType::Transform), &[13, 11, 10, 12], 1118);
                step(f, Op::BreakTransform, &[12, 24, 4, 22], 1119);
                step(f, Op::SubF, &[160, 19, 187], 1120);
                step(f, Op::MulF, &[186, 187, 189], 1121);
                step(f, Op::MulF, &[17, 189, 200], 1122);
                step(f, Op::FootAvoidance, &[48, 24, 200, 13, 91, 25], 1123);
                step(f, Op::RemapF, &[18, 94, 160, 158, 160, 9, 188], 1124);
                step(f, Op::LerpV, &[48, 25, 188, 26], 1125);
                step(f, Op::FootAvoidance, &[26, 24, 20, 13, 117, 27], 1126);
                step(f, Op::LerpV, &[26, 27, 19, 23], 1127);
                step(f, Op::MakeTransform, &[23, 6, 6, 13], 1128);
                step(f, Op::BreakTransform, &[13, 28, 7, 29], 1129);
                step(f, Op::MakeVector, &[158, 158, 64, 56], 1130);
                step(f, Op::AddV, &[28, 56, 60], 1131);
                step(f, Op::SubV, &[28, 56, 31], 1132);
                step(f, Op::LineTrace, &[60, 31, 17, 17, 32, 222], 1133);
                step(f, Op::RotateVector, &[7, 10, 34], 1134);
                step(f, Op::FindQuatBetween, &[34, 32, 2], 1135);
                step(f, Op::MulQ, &[2, 7, 8], 1136);
                step(f, Op::MulF, &[62, 61, 196], 1137);
                step(f, Op::AddF, &[196, 72, 218], 1138);
                step(f, Op::NegF, &[218, 199], 1139);
                step(f, Op::MakeVector, &[158, 199, 158, 38], 1140);
                step(f, Op::RotateVector, &[8, 38, 37], 1141);
                step(f, Op::AddV, &[17, 37, 39], 1142);
                step(f, Op::AddV, &[39, 56, 33], 1143);
                step(f, Op::SubV, &[39, 56, 35], 1144);
                step(f, Op::LineTrace, &[33, 35, 18, 36, 40, 209], 1145);
                step(f, Op::BreakVector, &[36, 213, 220, 191], 1146);
                step(f, Op::BreakVector, &[39, 219, 221, 192], 1147);
                step(f, Op::SubF, &[191, 192, 198], 1148);
                step(f, Op::Select(ValueType::Float), &[18, 198, 158, 212], 1149);
                step(f, Op::AddF, &[68, 72, 202], 1150);
                step(f, Op::MakeVector, &[158, 202, 158, 41], 1151);
                step(f, Op::RotateVector, &[8, 41, 42], 1152);
                step(f, Op::AddV, &[17, 42, 44], 1153);
                step(f, Op::AddV, &[44, 56, 30], 1154);
                step(f, Op::SubV, &[44, 56, 43], 1155);
                step(f, Op::LineTrace, &[30, 43, 19, 45, 21, 204], 1156);
                step(f, Op::BreakVector, &[45, 201, 203, 193], 1157);
                step(f, Op::BreakVector, &[44, 215, 206, 216], 1158);
                step(f, Op::SubF, &[193, 216, 183], 1159);
                step(f, Op::Select(ValueType::Float), &[19, 183, 158, 194], 1160);
                step(f, Op::MaxF, &[212, 194, 195], 1161);
                step(f, Op::ClampF, &[195, 158, 71, 197], 1162);
                step(f, Op::MakeVector, &[158, 158, 197, 53], 1163);
                step(f, Op::AddV, &[17, 53, 52], 1164);
                step(f, Op::MakeTransform, &[52, 8, 6, 14], 1165);
                step(f, Op::Select(ValueType::Transform), &[17, 14, 13, 15, 15, 15], 1166);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 7, 15], 1167);
                1167
            }
            1167 => {
                step(f, Op::Jump, &[1281], 1168)
            }
            1168 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 7, 13], 1169);
                step(f, Op::MakeAbsolute, &[13, 6, 14], 1170);
                step(f, Op::BreakTransform, &[14, 54, 2, 51], 1171);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 4], 1172);
                step(f, Op::BreakTransform, &[4, 18, 6, 55], 1173);
                step(f, Op::SubF, &[160, 214, 217], 1174);
                step(f, Op::MulF, &[13, 10, 205], 1175);
                step(f, Op::MulF, &[217, 205, 208], 1176);
                step(f, Op::ScaleV, &[2, 208, 59], 1177);
                step(f, Op::AddV, &[18, 59, 48], 1178);
                step(f, Op::Equals(Elem::Int), &[7, 2, 13], 1179);
                step(f, Op::Select(ValueType::Int), &[13, 3, 2, 12], 1180);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 16], 1181);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 12, 5], 1182);
                step(f, Op::BreakTransform, &[5, 49, 3, 47], 1183);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 12, 8], 1184);
                step(f, Op::BreakTransform, &[8, 46, 5, 57], 1185);
                step(f, Op::LessEqualF, &[95, 158, 11], 1186);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 207], 1187);
                step(f, Op::SmoothStepF, &[207, 158, 95, 185], 1188);
                step(f, Op::Select(ValueType::Float), &[11, 160, 185, 182], 1189);
                step(f, Op::LerpV, &[49, 46, 182, 19], 1190);
                step(f, Op::MakeTransform, &[19, 1, 6, 9], 1191);
                step(f, Op::Select(ValueType::Transform), &[16, 5, 9, 10], 1192);
                step(f, Op::MakeAbsolute, &[10, 6, 11], 1193);
                step(f, Op::Select(ValueType::Transform), &[13, 11, 10, 12], 1194);
                step(f, Op::BreakTransform, &[12, 24, 4, 22], 1195);
                step(f, Op::SubF, &[160, 19, 187], 1196);
                step(f, Op::MulF, &[186, 187, 189], 1197);
                step(f, Op::MulF, &[17, 189, 200], 1198);
                step(f, Op::FootAvoidance, &[48, 24, 200, 13, 91, 25], 1199);
                step(f, Op::RemapF, &[18, 94, 160, 158, 160, 9, 188], 1200);
                step(f, Op::LerpV, &[48, 25, 188, 26], 1201);
                step(f, Op::FootAvoidance, &[26, 24, 20, 13, 117, 27], 1202);
                step(f, Op::LerpV, &[26, 27, 19, 23], 1203);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 7, 15], 1204);
                step(f, Op::MakeAbsolute, &[15, 6, 13], 1205);
                step(f, Op::BreakTransform, &[13, 20, 7, 58], 1206);
                step(f, Op::ArrayAt(Elem::Float), &[3, 7, 184], 1207);
                step(f, Op::SubF, &[214, 184, 210], 1208);
                step(f, Op::DeltaTime, &[211], 1209);
                step(f, Op::DivF, &[58, 211, 190], 1210);
                step(f, Op::MulF, &[210, 190, 222], 1211);
                step(f, Op::AddF, &[184, 222, 196], 1212);
                step(f, Op::ClampF, &[196, 158, 160, 218], 1213);
                step(f, Op::AddF, &[214, 222, 199], 1214);
                step(f, Op::ClampF, &[199, 158, 160, 209], 1215);
                step(f, Op::AddF, &[218, 209, 213], 1216);
                step(f, Op::MulF, &[213, 159, 220], 1217);
                step(f, Op::SubF, &[160, 220, 219], 1218);
                step(f, Op::GreaterF, &[210, 158, 20], 1219);
                step(f, Op::SubF, &[209, 218, 221], 1220);
                step(f, Op::DivF, &[221, 210, 191], 1221);
                step(f, Op::Select(ValueType::Float), &[20, 191, 160, 192], 1222);
                step(f, Op::MulF, &[219, 192, 198], 1223);
                step(f, Op::MulF, &[90, 198, 202, 58, 58], 1224);
                step(f, Op::SubV, &[23, 20, 29], 1225);
                step(f, Op::DeltaTime, &[204], 1226);
                step(f, Op::DivF, &[58, 204, 201], 1227);
                step(f, Op::ScaleV, &[29, 201, 28], 1228);
                step(f, Op::AddV, &[23, 28, 31], 1229);
                step(f, Op::AddV, &[20, 28, 60], 1230);
                step(f, Op::SubV, &[54, 60, 32], 1231);
                step(f, Op::FloatLerp, &[158, 160, 202, 203], 1232);
                step(f, Op::SubF, &[160, 203, 206], 1233);
                step(f, Op::ScaleV, &[32, 206, 34], 1234);
                step(f, Op::AddV, &[31, 34, 38], 1235);
                step(f, Op::MulF, &[202, 204, 215], 1236);
                step(f, Op::GreaterF, &[215, 158, 18], 1237);
                step(f, Op::DivF, &[203, 215, 193], 1238);
                step(f, Op::Select(ValueType::Float), &[18, 193, 160, 216], 1239);
                step(f, Op::ScaleV, &[29, 216, 37], 1240);
                step(f, Op::SubV, &[38, 37, 33, 33, 33], 1241);
                step(f, Op::MakeTransform, &[33, 6, 6, 14], 1242);
                step(f, Op::BreakTransform, &[14, 35, 8, 40], 1243);
                step(f, Op::MakeVector, &[158, 158, 64, 36], 1244);
                step(f, Op::AddV, &[35, 36, 39], 1245);
                step(f, Op::SubV, &[35, 36, 41], 1246);
                step(f, Op::LineTrace, &[39, 41, 19, 42, 56, 183], 1247);
                step(f, Op::RotateVector, &[8, 10, 21], 1248);
                step(f, Op::FindQuatBetween, &[21, 56, 2], 1249);
                step(f, Op::MulQ, &[2, 8, 7], 1250);
                step(f, Op::MulF, &[62, 61, 194], 1251);
                step(f, Op::AddF, &[194, 72, 212], 1252);
                step(f, Op::NegF, &[212, 195], 1253);
                step(f, Op::MakeVector, &[158, 195, 158, 30], 1254);
                step(f, Op::RotateVector, &[7, 30, 43], 1255);
                step(f, Op::AddV, &[42, 43, 45], 1256);
                step(f, Op::AddV, &[45, 36, 44], 1257);
                step(f, Op::SubV, &[45, 36, 17], 1258);
                step(f, Op::LineTrace, &[44, 17, 17, 53, 52, 197], 1259);
                step(f, Op::BreakVector, &[53, 211, 190, 184], 1260);
                step(f, Op::BreakVector, &[45, 196, 222, 199], 1261);
                step(f, Op::SubF, &[184, 199, 213], 1262);
                step(f, Op::Select(ValueType::Float), &[17, 213, 158, 220], 1263);
                step(f, Op::AddF, &[68, 72, 209], 1264);
                step(f, Op::MakeVector, &[158, 209, 158, 51], 1265);
                step(f, Op::RotateVector, &[7, 51, 58], 1266);
                step(f, Op::AddV, &[42, 58, 20], 1267);
                step(f, Op::AddV, &[20, 36, 28], 1268);
                step(f, Op::SubV, &[20, 36, 54], 1269);
                step(f, Op::LineTrace, &[28, 54, 20, 60, 32, 218], 1270);
                step(f, Op::BreakVector, &[60, 210, 221, 191], 1271);
                step(f, Op::BreakVector, &[20, 192, 219, 198], 1272);
                step(f, Op::SubF, &[191, 198, 201], 1273);
                step(f, Op::Select(ValueType::Float), &[20, 201, 158, 206], 1274);
                step(f, Op::MaxF, &[220, 206, 202], 1275);
                step(f, Op::ClampF, &[202, 158, 71, 204], 1276);
                step(f, Op::MakeVector, &[158, 158, 204, 31], 1277);
                step(f, Op::AddV, &[42, 31, 34], 1278);
                step(f, Op::MakeTransform, &[34, 7, 6, 15], 1279);
                step(f, Op::Select(ValueType::Transform), &[19, 15, 14, 13, 13, 13], 1280);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 7, 13], 1281);
                1281
            }
            1281 => {
                step(f, Op::JumpIfFalse, &[14, 1363], 1282)
            }
            1282 => {
                step(f, Op::JumpIfFalse, &[12, 1284], 1283)
            }
            1283 => {
                step(f, Op::Jump, &[1344], 1284)
            }
            1284 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 7, 14], 1285);
                step(f, Op::BreakTransform, &[14, 29, 2, 37], 1286);
                step(f, Op::Equals(Elem::Int), &[7, 2, 13], 1287);
                step(f, Op::Select(ValueType::Int), &[13, 3, 2, 12], 1288);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 12, 15], 1289);
                step(f, Op::BreakTransform, &[15, 38, 8, 33], 1290);
                step(f, Op::MakeAbsolute, &[15, 6, 13], 1291);
                step(f, Op::BreakTransform, &[13, 40, 7, 35], 1292);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 207], 1293);
                step(f, Op::SmoothStepF, &[207, 158, 160, 203], 1294);
                step(f, Op::RemapF, &[18, 158, 94, 158, 160, 9, 215], 1295);
                step(f, Op::MulF, &[203, 215, 193], 1296);
                step(f, Op::Select(ValueType::Float), &[13, 193, 158, 216], 1297);
                step(f, Op::LerpV, &[38, 40, 216, 39], 1298);
                step(f, Op::MakeTransform, &[39, 1, 6, 16], 1299);
                step(f, Op::BreakTransform, &[16, 41, 9, 21], 1300);
                step(f, Op::SubF, &[160, 19, 187], 1301);
                step(f, Op::MulF, &[186, 187, 189], 1302);
                step(f, Op::MulF, &[17, 189, 200], 1303);
                step(f, Op::FootAvoidance, &[29, 41, 200, 13, 91, 56], 1304);
                step(f, Op::MakeTransform, &[56, 2, 6, 17], 1305);
                step(f, Op::BreakTransform, &[17, 30, 2, 43], 1306);
                step(f, Op::MakeVector, &[158, 158, 64, 17], 1307);
                step(f, Op::AddV, &[30, 17, 44], 1308);
                step(f, Op::SubV, &[30, 17, 52], 1309);
                step(f, Op::LineTrace, &[44, 52, 18, 53, 45, 183], 1310);
                step(f, Op::RotateVector, &[2, 10, 51], 1311);
                step(f, Op::FindQuatBetween, &[51, 45, 10], 1312);
                step(f, Op::MulQ, &[10, 2, 11], 1313);
                step(f, Op::MulF, &[62, 61, 194], 1314);
                step(f, Op::AddF, &[194, 72, 212], 1315);
                step(f, Op::NegF, &[212, 195], 1316);
                step(f, Op::MakeVector, &[158, 195, 158, 58], 1317);
                step(f, Op::RotateVector, &[11, 58, 36], 1318);
                step(f, Op::AddV, &[53, 36, 28], 1319);
                step(f, Op::AddV, &[28, 17, 32], 1320);
                step(f, Op::SubV, &[28, 17, 54], 1321);
                step(f, Op::LineTrace, &[32, 54, 17, 60, 20, 197], 1322);
                step(f, Op::BreakVector, &[60, 190, 211, 196], 1323);
                step(f, Op::BreakVector, &[28, 222, 184, 199], 1324);
                step(f, Op::SubF, &[196, 199, 213], 1325);
                step(f, Op::Select(ValueType::Float), &[17, 213, 158, 209], 1326);
                step(f, Op::AddF, &[68, 72, 218], 1327);
                step(f, Op::MakeVector, &[158, 218, 158, 31], 1328);
                step(f, Op::RotateVector, &[11, 31, 42], 1329);
                step(f, Op::AddV, &[53, 42, 34], 1330);
                step(f, Op::AddV, &[34, 17, 37], 1331);
                step(f, Op::SubV, &[34, 17, 29], 1332);
                step(f, Op::LineTrace, &[37, 29, 20, 56, 43, 210], 1333);
                step(f, Op::BreakVector, &[56, 221, 192, 219], 1334);
                step(f, Op::BreakVector, &[34, 191, 198, 201], 1335);
                step(f, Op::SubF, &[219, 201, 206], 1336);
                step(f, Op::Select(ValueType::Float), &[20, 206, 158, 220], 1337);
                step(f, Op::MaxF, &[209, 220, 202], 1338);
                step(f, Op::ClampF, &[202, 158, 71, 204], 1339);
                step(f, Op::MakeVector, &[158, 158, 204, 30], 1340);
                step(f, Op::AddV, &[53, 30, 44], 1341);
                step(f, Op::MakeTransform, &[44, 11, 6, 18], 1342);
                step(f, Op::Select(ValueType::Transform), &[18, 18, 17, 19, 19, 19], 1343);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 7, 19], 1344);
                1344
            }
            1344 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 7, 17], 1345);
                step(f, Op::BreakTransform, &[17, 52, 2, 45], 1346);
                step(f, Op::SubV, &[52, 50, 51], 1347);
                step(f, Op::LengthV, &[51, 183], 1348);
                step(f, Op::SubF, &[73, 74, 194], 1349);
                step(f, Op::SubF, &[183, 194, 212], 1350);
                step(f, Op::MulF, &[74, 163, 195], 1351);
                step(f, Op::ClampF, &[212, 158, 195, 197], 1352);
                step(f, Op::MulF, &[197, 197, 190], 1353);
                step(f, Op::MulF, &[74, 174, 211], 1354);
                step(f, Op::DivF, &[190, 211, 184], 1355);
                step(f, Op::SubF, &[183, 184, 222], 1356);
                step(f, Op::DivF, &[222, 183, 196], 1357);
                step(f, Op::ScaleV, &[51, 196, 58], 1358);
                step(f, Op::AddV, &[50, 58, 36], 1359);
                step(f, Op::MakeTransform, &[36, 2, 6, 18], 1360);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 18], 1361);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 18], 1362);
                step(f, Op::Jump, &[1531], 1363)
            }
            1363 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 7, 17], 1364);
                step(f, Op::BreakTransform, &[17, 52, 2, 45], 1365);
                step(f, Op::SubV, &[52, 50, 51], 1366);
                step(f, Op::LengthV, &[51, 183], 1367);
                step(f, Op::SubF, &[73, 74, 194], 1368);
                step(f, Op::SubF, &[183, 194, 212], 1369);
                step(f, Op::MulF, &[74, 163, 195], 1370);
                step(f, Op::ClampF, &[212, 158, 195, 197], 1371);
                step(f, Op::MulF, &[197, 197, 190], 1372);
                step(f, Op::MulF, &[74, 174, 211], 1373);
                step(f, Op::DivF, &[190, 211, 184], 1374);
                step(f, Op::SubF, &[183, 184, 222], 1375);
                step(f, Op::DivF, &[222, 183, 196], 1376);
                step(f, Op::ScaleV, &[51, 196, 58], 1377);
                step(f, Op::AddV, &[50, 58, 36], 1378);
                step(f, Op::MakeTransform, &[36, 2, 6, 18], 1379);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 7, 14], 1380);
                step(f, Op::ClampF, &[214, 158, 160, 199], 1381);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[6, 5], 1382);
                step(f, Op::ArrayReset(Elem::Vec3), &[5], 1383);
                step(f, Op::BreakTransform, &[18, 20, 10, 32], 1384);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 20], 1385);
                step(f, Op::UnitV, &[2, 54], 1386);
                step(f, Op::LengthV, &[2, 213], 1387);
                step(f, Op::RemapF, &[213, 158, 75, 158, 76, 9, 218], 1388);
                step(f, Op::ScaleV, &[54, 218, 60], 1389);
                step(f, Op::SubV, &[20, 60, 28], 1390);
                step(f, Op::MakeVector, &[158, 158, 78, 31], 1391);
                step(f, Op::AddV, &[28, 31, 42], 1392);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 42], 1393);
                step(f, Op::RemapF, &[213, 158, 75, 158, 81, 9, 210], 1394);
                step(f, Op::MakeVector, &[158, 158, 210, 17], 1395);
                step(f, Op::AddV, &[42, 17, 29], 1396);
                step(f, Op::BreakTransform, &[14, 37, 11, 43], 1397);
                step(f, Op::BreakVector, &[37, 192, 221, 191], 1398);
                step(f, Op::BreakVector, &[20, 198, 201, 219], 1399);
                step(f, Op::SubF, &[191, 219, 206], 1400);
                step(f, Op::MaxF, &[206, 158, 209], 1401);
                step(f, Op::MulF, &[209, 83, 220], 1402);
                step(f, Op::MinF, &[220, 84, 202], 1403);
                step(f, Op::AbsF, &[206, 204], 1404);
                step(f, Op::RemapF, &[204, 158, 87, 158, 86, 9, 194], 1405);
                step(f, Op::AddF, &[202, 194, 195], 1406);
                step(f, Op::MakeVector, &[158, 158, 195, 56], 1407);
                step(f, Op::AddV, &[29, 56, 34], 1408);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 34], 1409);
                step(f, Op::RemapF, &[213, 158, 75, 158, 77, 9, 212], 1410);
                step(f, Op::ScaleV, &[54, 212, 30], 1411);
                step(f, Op::AddV, &[37, 30, 53], 1412);
                step(f, Op::LerpF, &[29, 52, 18, 197], 1413);
                step(f, Op::MulF, &[14, 197, 190], 1414);
                step(f, Op::RemapF, &[190, 160, 38, 79, 80, 9, 211], 1415);
                step(f, Op::MakeVector, &[158, 158, 211, 44], 1416);
                step(f, Op::AddV, &[53, 44, 45], 1417);
                step(f, Op::RemapF, &[213, 158, 75, 158, 82, 9, 184], 1418);
                step(f, Op::MakeVector, &[158, 158, 184, 52], 1419);
                step(f, Op::AddV, &[45, 52, 51], 1420);
                step(f, Op::NegF, &[206, 183], 1421);
                step(f, Op::MaxF, &[183, 158, 222], 1422);
                step(f, Op::MulF, &[222, 85, 196], 1423);
                step(f, Op::AddF, &[196, 194, 218], 1424);
                step(f, Op::MakeVector, &[158, 158, 218, 50], 1425);
                step(f, Op::AddV, &[51, 50, 58], 1426);
                step(f, Op::LerpV, &[34, 58, 159, 36], 1427);
                step(f, Op::GetTransform, &[35, 2, 9, 19], 1428);
                step(f, Op::BreakTransform, &[19, 32, 2, 60], 1429);
                step(f, Op::BreakVector, &[32, 210, 192, 221], 1430);
                step(f, Op::SubF, &[160, 18, 198], 1431);
                step(f, Op::MulF, &[88, 198, 201], 1432);
                step(f, Op::MulF, &[17, 201, 191], 1433);
                step(f, Op::QuatFromAxisAngle, &[10, 191, 2], 1434);
                step(f, Op::SubV, &[36, 32, 28], 1435);
                step(f, Op::BreakVector, &[28, 219, 209, 220], 1436);
                step(f, Op::MakeVector, &[219, 209, 158, 31], 1437);
                step(f, Op::RotateVector, &[2, 31, 17], 1438);
                step(f, Op::BreakVector, &[17, 204, 202, 195], 1439);
                step(f, Op::AddF, &[210, 204, 212], 1440);
                step(f, Op::AddF, &[192, 202, 197], 1441);
                step(f, Op::BreakVector, &[36, 190, 211, 213], 1442);
                step(f, Op::MakeVector, &[212, 197, 213, 42], 1443);
                step(f, Op::DistanceV, &[20, 37, 184], 1444);
                step(f, Op::RemapF, &[184, 163, 175, 158, 160, 9, 206], 1445);
                step(f, Op::LerpV, &[36, 42, 206, 43], 1446);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 43], 1447);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 58], 1448);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 45], 1449);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 37], 1450);
                step(f, Op::JumpIfFalse, &[8, 1452], 1451)
            }
            1451 => {
                step(f, Op::DrawSpline, &[5, 2, 5, 159, 12], 1452);
                1452
            }
            1452 => {
                step(f, Op::Spline, &[5, 199, 2, 29, 56], 1453);
                step(f, Op::SlerpQ, &[10, 11, 199, 2], 1454);
                step(f, Op::MulF, &[199, 168, 183], 1455);
                step(f, Op::SinF, &[183, 222], 1456);
                step(f, Op::SmoothStepF, &[199, 158, 102, 194], 1457);
                step(f, Op::MulF, &[222, 194, 196], 1458);
                step(f, Op::MulF, &[196, 89, 218], 1459);
                step(f, Op::SlerpQ, &[2, 1, 218, 10], 1460);
                step(f, Op::MakeTransform, &[29, 10, 6, 17, 17, 17], 1461);
                step(f, Op::BreakTransform, &[17, 54, 11, 30], 1462);
                step(f, Op::Equals(Elem::Int), &[7, 2, 13], 1463);
                step(f, Op::Select(ValueType::Int), &[13, 3, 2, 12], 1464);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 12, 15], 1465);
                step(f, Op::BreakTransform, &[15, 38, 8, 33], 1466);
                step(f, Op::GreaterF, &[27, 158, 15], 1467);
                step(f, Op::InterpolateTransform, &[2, 3, 28, 7], 1468);
                step(f, Op::Select(ValueType::Transform), &[15, 7, 2, 6], 1469);
                step(f, Op::MakeAbsolute, &[15, 6, 13], 1470);
                step(f, Op::BreakTransform, &[13, 40, 7, 35], 1471);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 207], 1472);
                step(f, Op::SmoothStepF, &[207, 158, 160, 203], 1473);
                step(f, Op::RemapF, &[18, 158, 94, 158, 160, 9, 215], 1474);
                step(f, Op::MulF, &[203, 215, 193], 1475);
                step(f, Op::Select(ValueType::Float), &[13, 193, 158, 216], 1476);
                step(f, Op::LerpV, &[38, 40, 216, 39], 1477);
                step(f, Op::MakeTransform, &[39, 1, 6, 16], 1478);
                step(f, Op::BreakTransform, &[16, 41, 9, 21], 1479);
                step(f, Op::SubF, &[160, 18, 186], 1480);
                step(f, Op::SubF, &[160, 19, 187], 1481);
                step(f, Op::MulF, &[186, 187, 189], 1482);
                step(f, Op::MulF, &[17, 189, 200], 1483);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 19], 1484);
                step(f, Op::Select(ValueType::Float), &[19, 92, 158, 221], 1485);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 214], 1486);
                step(f, Op::ClampF, &[214, 158, 160, 199], 1487);
                step(f, Op::MulF, &[199, 168, 198], 1488);
                step(f, Op::SinF, &[198, 201], 1489);
                step(f, Op::MulF, &[201, 201, 191], 1490);
                step(f, Op::MulF, &[221, 191, 220], 1491);
                step(f, Op::AddF, &[91, 220, 209], 1492);
                step(f, Op::FootAvoidance, &[54, 41, 200, 13, 209, 44], 1493);
                step(f, Op::SubV, &[44, 54, 53], 1494);
                step(f, Op::LengthV, &[53, 219], 1495);
                step(f, Op::AddF, &[219, 220, 195], 1496);
                step(f, Op::DivF, &[219, 195, 204], 1497);
                step(f, Op::MulF, &[116, 163, 210], 1498);
                step(f, Op::LessEqualF, &[219, 210, 12], 1499);
                step(f, Op::MulF, &[116, 174, 192], 1500);
                step(f, Op::DivF, &[219, 192, 202], 1501);
                step(f, Op::DivF, &[116, 219, 190], 1502);
                step(f, Op::SubF, &[160, 190, 211], 1503);
                step(f, Op::Select(ValueType::Float), &[12, 202, 211, 197], 1504);
                step(f, Op::GreaterF, &[116, 158, 17], 1505);
                step(f, Op::Select(ValueType::Float), &[17, 19, 158, 212], 1506);
                step(f, Op::LerpF, &[204, 197, 212, 213], 1507);
                step(f, Op::LessF, &[207, 214, 20], 1508);
                step(f, Op::LessEqualF, &[93, 158, 18], 1509);
                step(f, Op::SmoothStepF, &[207, 158, 93, 184], 1510);
                step(f, Op::MulF, &[184, 18, 206], 1511);
                step(f, Op::SubF, &[160, 206, 183], 1512);
                step(f, Op::Select(ValueType::Float), &[18, 160, 183, 194], 1513);
                step(f, Op::Select(ValueType::Float), &[20, 194, 160, 222], 1514);
                step(f, Op::MulF, &[213, 222, 196], 1515);
                step(f, Op::SmoothStepF, &[199, 158, 93, 218], 1516);
                step(f, Op::Select(ValueType::Float), &[18, 160, 218, 203], 1517);
                step(f, Op::MulF, &[196, 203, 215], 1518);
                step(f, Op::ScaleV, &[53, 215, 52], 1519);
                step(f, Op::AddV, &[54, 52, 50], 1520);
                step(f, Op::MulF, &[6, 149, 193], 1521);
                step(f, Op::MulF, &[193, 191, 216], 1522);
                step(f, Op::MakeVector, &[158, 158, 216, 51], 1523);
                step(f, Op::AddV, &[50, 51, 34], 1524);
                step(f, Op::MakeTransform, &[34, 11, 6, 18], 1525);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 18], 1526);
                step(f, Op::ScaleV, &[53, 196, 60], 1527);
                step(f, Op::AddV, &[54, 60, 32], 1528);
                step(f, Op::AddV, &[32, 51, 28], 1529);
                step(f, Op::MakeTransform, &[28, 11, 6, 14], 1530);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 14], 1531);
                1531
            }
            1531 => {
                step(f, Op::JumpIfFalse, &[15, 1554], 1532)
            }
            1532 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 7, 19], 1533);
                step(f, Op::BreakTransform, &[19, 31, 2, 17], 1534);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 7, 17], 1535);
                step(f, Op::BreakTransform, &[17, 20, 10, 36], 1536);
                step(f, Op::MulF, &[27, 27, 198], 1537);
                step(f, Op::LerpV, &[31, 20, 198, 42], 1538);
                step(f, Op::SubF, &[160, 27, 201], 1539);
                step(f, Op::MulF, &[27, 201, 221], 1540);
                step(f, Op::MulF, &[151, 163, 209], 1541);
                step(f, Op::MulF, &[221, 209, 220], 1542);
                step(f, Op::MakeVector, &[158, 158, 220, 43], 1543);
                step(f, Op::AddV, &[42, 43, 58], 1544);
                step(f, Op::SlerpQ, &[2, 10, 27, 8], 1545);
                step(f, Op::MakeTransform, &[58, 8, 6, 7], 1546);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 7], 1547);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 7, 19], 1548);
                step(f, Op::BreakTransform, &[19, 31, 2, 17], 1549);
                step(f, Op::LerpV, &[31, 20, 198, 42], 1550);
                step(f, Op::AddV, &[42, 43, 58], 1551);
                step(f, Op::SlerpQ, &[2, 10, 27, 8], 1552);
                step(f, Op::MakeTransform, &[58, 8, 6, 7], 1553);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 7], 1554);
                1554
            }
            1554 => {
                step(f, Op::GreaterEqualF, &[214, 160, 14], 1555);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 7, 14], 1556);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 4], 1557);
                step(f, Op::BreakTransform, &[4, 18, 6, 55], 1558);
                step(f, Op::SubF, &[160, 214, 217], 1559);
                step(f, Op::MulF, &[13, 10, 205], 1560);
                step(f, Op::MulF, &[217, 205, 208], 1561);
                step(f, Op::ScaleV, &[2, 208, 59], 1562);
                step(f, Op::AddV, &[18, 59, 48], 1563);
                step(f, Op::Equals(Elem::Int), &[7, 2, 13], 1564);
                step(f, Op::Select(ValueType::Int), &[13, 3, 2, 12], 1565);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 16], 1566);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 12, 5], 1567);
                step(f, Op::BreakTransform, &[5, 49, 3, 47], 1568);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 12, 8], 1569);
                step(f, Op::BreakTransform, &[8, 46, 5, 57], 1570);
                step(f, Op::LessEqualF, &[95, 158, 11], 1571);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 207], 1572);
                step(f, Op::SmoothStepF, &[207, 158, 95, 185], 1573);
                step(f, Op::Select(ValueType::Float), &[11, 160, 185, 182], 1574);
                step(f, Op::LerpV, &[49, 46, 182, 19], 1575);
                step(f, Op::MakeTransform, &[19, 1, 6, 9], 1576);
                step(f, Op::Select(ValueType::Transform), &[16, 5, 9, 10], 1577);
                step(f, Op::MakeAbsolute, &[10, 6, 11], 1578);
                step(f, Op::Select(ValueType::Transform), &[13, 11, 10, 12], 1579);
                step(f, Op::BreakTransform, &[12, 24, 4, 22], 1580);
                step(f, Op::SubF, &[160, 19, 187], 1581);
                step(f, Op::MulF, &[186, 187, 189], 1582);
                step(f, Op::MulF, &[17, 189, 200], 1583);
                step(f, Op::FootAvoidance, &[48, 24, 200, 13, 91, 25], 1584);
                step(f, Op::RemapF, &[18, 94, 160, 158, 160, 9, 188], 1585);
                step(f, Op::LerpV, &[48, 25, 188, 26], 1586);
                step(f, Op::FootAvoidance, &[26, 24, 20, 13, 117, 27], 1587);
                step(f, Op::LerpV, &[26, 27, 19, 23], 1588);
                step(f, Op::MakeTransform, &[23, 1, 6, 15], 1589);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 7, 15], 1590);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 7, 13], 1591);
                step(f, Op::BreakTransform, &[13, 45, 7, 37], 1592);
                step(f, Op::MakeVector, &[158, 158, 59, 56], 1593);
                step(f, Op::AddV, &[45, 56, 29], 1594);
                step(f, Op::GetTransform, &[0, 2, 9, 16], 1595);
                step(f, Op::BreakTransform, &[16, 30, 9, 33], 1596);
                step(f, Op::MakeTransform, &[29, 9, 6, 18], 1597);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 7, 20], 1598);
                step(f, Op::GetTransform, &[20, 2, 9, 14], 1599);
                step(f, Op::BreakTransform, &[14, 35, 11, 38], 1600);
                step(f, Op::SubV, &[35, 30, 40], 1601);
                step(f, Op::AddV, &[29, 40, 39], 1602);
                step(f, Op::FootPivots, &[29, 39, 61, 60, 59, 62, 21, 41, 44], 1603);
                step(f, Op::GetParent, &[0, 18], 1604);
                step(f, Op::GetParent, &[18, 19], 1605);
                step(f, Op::GetTransform, &[19, 2, 10, 17], 1606);
                step(f, Op::BreakTransform, &[17, 52, 2, 50], 1607);
                step(f, Op::SubV, &[45, 52, 34], 1608);
                step(f, Op::DotV, &[34, 9, 195], 1609);
                step(f, Op::RemapF, &[195, 97, 96, 98, 158, 9, 210], 1610);
                step(f, Op::LengthV, &[2, 192], 1611);
                step(f, Op::RemapF, &[192, 158, 108, 158, 160, 9, 219], 1612);
                step(f, Op::MulF, &[210, 219, 190], 1613);
                step(f, Op::QuatFromAxisAngle, &[13, 190, 10], 1614);
                step(f, Op::RotateAroundPoint, &[18, 21, 10, 19], 1615);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 202], 1616);
                step(f, Op::SmoothStepF, &[202, 158, 102, 211], 1617);
                step(f, Op::SubF, &[160, 202, 197], 1618);
                step(f, Op::SmoothStepF, &[197, 158, 102, 204], 1619);
                step(f, Op::MulF, &[211, 204, 212], 1620);
                step(f, Op::LerpF, &[101, 160, 212, 184], 1621);
                step(f, Op::MulF, &[190, 184, 206], 1622);
                step(f, Op::QuatFromAxisAngle, &[13, 206, 8], 1623);
                step(f, Op::SubV, &[41, 21, 53], 1624);
                step(f, Op::RotateVector, &[8, 53, 54], 1625);
                step(f, Op::AddV, &[21, 54, 60], 1626);
                step(f, Op::RemapF, &[195, 99, 97, 100, 158, 9, 183], 1627);
                step(f, Op::MulF, &[183, 219, 194], 1628);
                step(f, Op::QuatFromAxisAngle, &[13, 194, 6], 1629);
                step(f, Op::RotateAroundPoint, &[19, 60, 6, 7], 1630);
                step(f, Op::RemapF, &[195, 103, 104, 158, 105, 9, 213], 1631);
                step(f, Op::RotateVector, &[7, 10, 32], 1632);
                step(f, Op::BreakVector, &[32, 222, 199, 218], 1633);
                step(f, Op::CosF, &[107, 203], 1634);
                step(f, Op::CosF, &[106, 215], 1635);
                step(f, Op::RemapF, &[218, 203, 215, 158, 160, 9, 191], 1636);
                step(f, Op::MulF, &[219, 191, 193], 1637);
                step(f, Op::MulF, &[213, 193, 216], 1638);
                step(f, Op::QuatFromAxisAngle, &[13, 216, 3], 1639);
                step(f, Op::RotateAroundPoint, &[7, 44, 3, 4], 1640);
                step(f, Op::SubF, &[160, 18, 196], 1641);
                step(f, Op::MulF, &[17, 196, 201], 1642);
                step(f, Op::LimitRotationAroundZ, &[7, 201, 109, 5], 1643);
                step(f, Op::RotateAroundPoint, &[4, 45, 5, 8], 1644);
                step(f, Op::BreakTransform, &[8, 51, 4, 28], 1645);
                step(f, Op::ArrayAt(Elem::Float), &[4, 7, 209], 1646);
                step(f, Op::MulF, &[209, 110, 221], 1647);
                step(f, Op::MulF, &[221, 111, 220], 1648);
                step(f, Op::AddF, &[221, 111, 198], 1649);
                step(f, Op::DivF, &[220, 198, 214], 1650);
                step(f, Op::MakeVector, &[158, 158, 214, 36], 1651);
                step(f, Op::AddV, &[51, 36, 17], 1652);
                step(f, Op::MakeTransform, &[17, 4, 28, 5], 1653);
                step(f, Op::ArraySetAt(Elem::Transform), &[7, 7, 5], 1654);
                step(f, Op::JumpIfFalse, &[8, 1659], 1655)
            }
            1655 => {
                step(f, Op::DrawPoint, &[44, 176, 13], 1656);
                step(f, Op::DrawPoint, &[21, 176, 9], 1657);
                step(f, Op::DrawPoint, &[60, 176, 10], 1658);
                step(f, Op::DrawTransform, &[13, 175, 159], 1659);
                1659
            }
            1659 => {
                step(f, Op::Jump, &[744], 1660)
            }
            1660 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1661);
                step(f, Op::Copy(ValueType::Int), &[2, 10], 1662);
                1662
            }
            1662 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 10, 1, 6, 8, 1701], 1663)
            }
            1663 => {
                step(f, Op::GetParent, &[1, 22], 1664);
                step(f, Op::GetParent, &[22, 23], 1665);
                step(f, Op::GetParent, &[23, 24], 1666);
                step(f, Op::GetTransform, &[24, 2, 10, 9], 1667);
                step(f, Op::BreakTransform, &[9, 20, 9, 31], 1668);
                step(f, Op::LengthV, &[1, 205], 1669);
                step(f, Op::ClavicleOffset, &[15, 205, 123, 127, 217], 1670);
                step(f, Op::MakeVector, &[158, 158, 217, 42], 1671);
                step(f, Op::AddV, &[20, 42, 43], 1672);
                step(f, Op::MakeTransform, &[43, 9, 6, 6], 1673);
                step(f, Op::SetTransform, &[24, 6, 2, 9, 160], 1674);
                step(f, Op::GetTransform, &[1, 2, 10, 10], 1675);
                step(f, Op::GetTransform, &[23, 2, 10, 11], 1676);
                step(f, Op::BreakTransform, &[11, 58, 11, 55], 1677);
                step(f, Op::Equals(Elem::Int), &[6, 2, 19], 1678);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 11], 1679);
                step(f, Op::ArrayAt(Elem::Float), &[0, 11, 208], 1680);
                step(f, Op::ArmSwingRotation, &[208, 1, 0, 124, 167, 177, 160, 123, 121, 122, 125, 167, 160, 207], 1681);
                step(f, Op::QuatFromAxisAngle, &[13, 207, 2], 1682);
                step(f, Op::RotateAroundPoint, &[10, 58, 2, 12], 1683);
                step(f, Op::BreakTransform, &[12, 18, 10, 59], 1684);
                step(f, Op::RemapF, &[205, 158, 123, 158, 126, 9, 185], 1685);
                step(f, Op::MakeVector, &[158, 158, 185, 47], 1686);
                step(f, Op::AddV, &[18, 47, 57], 1687);
                step(f, Op::MakeTransform, &[57, 10, 6, 15], 1688);
                step(f, Op::Select(ValueType::Vec3), &[19, 14, 13, 46], 1689);
                step(f, Op::Select(ValueType::Vec3), &[19, 9, 15, 49], 1690);
                step(f, Op::ArrayAt(Elem::Vec3), &[4, 6, 19], 1691);
                step(f, Op::TwoBoneIK, &[23, 22, 1, 15, 46, 49, 19, 2, 160, 10, 178, 179, 9, 12, 182], 1692);
                step(f, Op::JumpIfFalse, &[8, 1700], 1693)
            }
            1693 => {
                step(f, Op::GetTransform, &[23, 2, 10, 11], 1694);
                step(f, Op::BreakTransform, &[11, 58, 11, 55], 1695);
                step(f, Op::GetTransform, &[1, 2, 10, 10], 1696);
                step(f, Op::RotateAroundPoint, &[10, 58, 2, 12], 1697);
                step(f, Op::BreakTransform, &[12, 18, 10, 59], 1698);
                step(f, Op::AddV, &[18, 47, 57], 1699);
                step(f, Op::DrawLine, &[58, 57, 159, 9], 1700);
                1700
            }
            1700 => {
                step(f, Op::Jump, &[1662], 1701)
            }
            1701 => {
                step(f, Op::NegF, &[5, 186], 1702);
                step(f, Op::MakeVector, &[158, 158, 186, 22], 1703);
                step(f, Op::MakeTransform, &[22, 1, 6, 16], 1704);
                step(f, Op::SetTransform, &[36, 16, 2, 9, 160], 1705);
                step(f, Op::Copy(ValueType::Float), &[165, 187], 1706);
                step(f, Op::Copy(ValueType::Bool), &[10, 17], 1707);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 11], 1708);
                step(f, Op::Copy(ValueType::Int), &[2, 12], 1709);
                step(f, Op::MakeVector, &[158, 158, 64, 25], 1710);
                1710
            }
            1710 => {
                step(f, Op::ForEachNext(Elem::Transform), &[11, 12, 14, 7, 9, 1722], 1711)
            }
            1711 => {
                step(f, Op::BreakTransform, &[14, 48, 8, 24], 1712);
                step(f, Op::AddV, &[48, 25, 26], 1713);
                step(f, Op::SubV, &[48, 25, 27], 1714);
                step(f, Op::SphereTrace, &[26, 27, 63, 20, 23, 37, 189], 1715);
                step(f, Op::BreakVector, &[23, 200, 188, 192], 1716);
                step(f, Op::LessF, &[192, 187, 18], 1717);
                step(f, Op::And, &[20, 18, 15], 1718);
                step(f, Op::JumpIfFalse, &[15, 1721], 1719)
            }
            1719 => {
                step(f, Op::Copy(ValueType::Float), &[192, 187], 1720);
                step(f, Op::Copy(ValueType::Bool), &[9, 17], 1721);
                1721
            }
            1721 => {
                step(f, Op::Jump, &[1710], 1722)
            }
            1722 => {
                step(f, Op::Select(ValueType::Float), &[17, 187, 158, 210], 1723);
                step(f, Op::ClampF, &[210, 69, 70, 202, 202, 202], 1724);
                step(f, Op::SubF, &[160, 27, 197], 1725);
                step(f, Op::MulF, &[202, 197, 204], 1726);
                step(f, Op::SubF, &[160, 148, 211], 1727);
                step(f, Op::MulF, &[5, 211, 212], 1728);
                step(f, Op::AddF, &[204, 212, 184], 1729);
                step(f, Op::MakeVector, &[22, 158, 158, 56], 1730);
                step(f, Op::MakeVector, &[184, 158, 158, 33], 1731);
                step(f, Op::Select(ValueType::Float), &[2, 184, 23, 190], 1732);
                step(f, Op::MakeVector, &[190, 158, 158, 38, 57, 57, 58, 58], 1733);
                step(f, Op::SubV, &[33, 38, 30], 1734);
                step(f, Op::DeltaTime, &[206], 1735);
                step(f, Op::DivF, &[58, 206, 183], 1736);
                step(f, Op::ScaleV, &[30, 183, 35], 1737);
                step(f, Op::AddV, &[33, 35, 40], 1738);
                step(f, Op::AddV, &[38, 35, 29], 1739);
                step(f, Op::SubV, &[56, 29, 39], 1740);
                step(f, Op::FloatLerp, &[158, 160, 57, 194], 1741);
                step(f, Op::SubF, &[160, 194, 195], 1742);
                step(f, Op::ScaleV, &[39, 195, 50], 1743);
                step(f, Op::AddV, &[40, 50, 52], 1744);
                step(f, Op::MulF, &[57, 206, 199], 1745);
                step(f, Op::GreaterF, &[199, 158, 14], 1746);
                step(f, Op::DivF, &[194, 199, 222], 1747);
                step(f, Op::Select(ValueType::Float), &[14, 222, 160, 203], 1748);
                step(f, Op::ScaleV, &[30, 203, 34], 1749);
                step(f, Op::SubV, &[52, 34, 41, 41, 41], 1750);
                step(f, Op::BreakVector, &[41, 215, 218, 191], 1751);
                step(f, Op::Select(ValueType::Float), &[1, 184, 215, 22, 22, 22], 1752);
                step(f, Op::Copy(ValueType::Float), &[184, 23], 1753);
                step(f, Op::GetTransform, &[37, 2, 9, 17], 1754);
                step(f, Op::BreakTransform, &[17, 53, 6, 54], 1755);
                step(f, Op::PelvisLean, &[1, 130, 135, 136, 219, 193], 1756);
                step(f, Op::LengthV, &[2, 213], 1757);
                step(f, Op::RemapF, &[213, 158, 130, 158, 128, 9, 216], 1758);
                step(f, Op::MulF, &[18, 129, 196], 1759);
                step(f, Op::SubF, &[160, 196, 201], 1760);
                step(f, Op::MulF, &[216, 201, 209], 1761);
                step(f, Op::MulF, &[15, 180, 221], 1762);
                step(f, Op::SinF, &[221, 198], 1763);
                step(f, Op::MulF, &[209, 198, 220], 1764);
                step(f, Op::MulF, &[220, 197, 214], 1765);
                step(f, Op::AddF, &[214, 22, 217], 1766);
                step(f, Op::SubF, &[217, 5, 208], 1767);
                step(f, Op::MakeVector, &[158, 193, 208, 32], 1768);
                step(f, Op::AddV, &[53, 32, 45], 1769);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 2, 18], 1770);
                step(f, Op::BreakTransform, &[18, 36, 3, 51], 1771);
                step(f, Op::BreakVector, &[36, 207, 205, 185], 1772);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 3, 19], 1773);
                step(f, Op::BreakTransform, &[19, 17, 7, 28], 1774);
                step(f, Op::BreakVector, &[17, 182, 186, 189], 1775);
                step(f, Op::SubF, &[185, 189, 188], 1776);
                step(f, Op::PelvisSideLean, &[188, 137, 138, 200], 1777);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 2, 7], 1778);
                step(f, Op::BreakTransform, &[7, 44, 5, 21], 1779);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 3, 4], 1780);
                step(f, Op::BreakTransform, &[4, 60, 4, 31], 1781);
                step(f, Op::SlerpQ, &[5, 4, 159, 9], 1782);
                step(f, Op::EulerFromQuat, &[9, 2, 20], 1783);
                step(f, Op::BreakVector, &[20, 192, 187, 210], 1784);
                step(f, Op::RemapF, &[213, 131, 130, 158, 132, 9, 202], 1785);
                step(f, Op::SubV, &[36, 17, 42], 1786);
                step(f, Op::RotateVector, &[0, 9, 43], 1787);
                step(f, Op::DotV, &[42, 43, 211], 1788);
                step(f, Op::MulF, &[202, 211, 204], 1789);
                step(f, Op::AddF, &[210, 204, 212], 1790);
                step(f, Op::MakeVector, &[219, 200, 212, 19], 1791);
                step(f, Op::QuatFromEuler, &[19, 2, 11], 1792);
                step(f, Op::MakeTransform, &[45, 11, 6, 8], 1793);
                step(f, Op::SetTransform, &[38, 8, 2, 9, 160], 1794);
                step(f, Op::GetTransform, &[39, 3, 9, 5], 1795);
                step(f, Op::BreakTransform, &[5, 46, 2, 49], 1796);
                step(f, Op::QuatFromAxisAngle, &[10, 204, 10], 1797);
                step(f, Op::DivF, &[133, 176, 190], 1798);
                step(f, Op::QuatScale, &[10, 190, 8], 1799);
                step(f, Op::MulQ, &[2, 8, 6], 1800);
                step(f, Op::MakeTransform, &[46, 6, 6, 13], 1801);
                step(f, Op::SetTransform, &[40, 13, 3, 9, 160], 1802);
                step(f, Op::GetTransform, &[41, 3, 9, 9], 1803);
                step(f, Op::BreakTransform, &[9, 55, 3, 59], 1804);
                step(f, Op::MulQ, &[3, 8, 7], 1805);
                step(f, Op::MakeTransform, &[55, 7, 6, 6], 1806);
                step(f, Op::SetTransform, &[42, 6, 3, 9, 160], 1807);
                step(f, Op::GetTransform, &[43, 3, 9, 15], 1808);
                step(f, Op::BreakTransform, &[15, 18, 4, 47], 1809);
                step(f, Op::MulQ, &[4, 8, 5], 1810);
                step(f, Op::MakeTransform, &[18, 5, 6, 11], 1811);
                step(f, Op::SetTransform, &[44, 11, 3, 9, 160], 1812);
                step(f, Op::GetTransform, &[45, 3, 9, 10], 1813);
                step(f, Op::BreakTransform, &[10, 57, 9, 58], 1814);
                step(f, Op::QuatScale, &[10, 134, 11], 1815);
                step(f, Op::MulQ, &[9, 11, 2], 1816);
                step(f, Op::MakeTransform, &[57, 2, 6, 12], 1817);
                step(f, Op::SetTransform, &[46, 12, 3, 9, 160], 1818);
                step(f, Op::Or, &[1, 2, 11], 1819);
                step(f, Op::Copy(ValueType::Float), &[158, 183], 1820);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1821);
                step(f, Op::Copy(ValueType::Int), &[2, 8], 1822);
                1822
            }
            1822 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 8, 25, 11, 6, 1869], 1823)
            }
            1823 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 11, 16], 1824);
                step(f, Op::GetParent, &[25, 26], 1825);
                step(f, Op::GetParent, &[26, 27], 1826);
                step(f, Op::GetTransform, &[27, 2, 10, 16], 1827);
                step(f, Op::BreakTransform, &[16, 22, 6, 24], 1828);
                step(f, Op::BreakVector, &[22, 195, 206, 194], 1829);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 11, 14], 1830);
                step(f, Op::BreakTransform, &[14, 48, 3, 26], 1831);
                step(f, Op::BreakVector, &[48, 199, 222, 203], 1832);
                step(f, Op::ArrayAt(Elem::Float), &[1, 11, 191], 1833);
                step(f, Op::MulF, &[191, 139, 218], 1834);
                step(f, Op::MulF, &[218, 218, 215], 1835);
                step(f, Op::SubF, &[195, 199, 184], 1836);
                step(f, Op::SubF, &[206, 222, 196], 1837);
                step(f, Op::MakeVector, &[184, 196, 158, 27], 1838);
                step(f, Op::DotV, &[27, 27, 201], 1839);
                step(f, Op::SubF, &[215, 201, 216], 1840);
                step(f, Op::SqrtF, &[216, 221], 1841);
                step(f, Op::AddF, &[203, 221, 198], 1842);
                step(f, Op::SubF, &[194, 198, 209], 1843);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 11, 17], 1844);
                step(f, Op::BreakTransform, &[17, 37, 7, 23], 1845);
                step(f, Op::BreakVector, &[37, 197, 220, 214], 1846);
                step(f, Op::AddF, &[214, 59, 217], 1847);
                step(f, Op::MinF, &[203, 217, 193], 1848);
                step(f, Op::AddF, &[193, 221, 208], 1849);
                step(f, Op::SubF, &[194, 208, 205], 1850);
                step(f, Op::Equals(Elem::Int), &[11, 2, 13], 1851);
                step(f, Op::Select(ValueType::Int), &[13, 3, 2, 10], 1852);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 10, 19], 1853);
                step(f, Op::ArrayAt(Elem::Float), &[2, 10, 207], 1854);
                step(f, Op::RemapF, &[207, 159, 160, 158, 160, 9, 182], 1855);
                step(f, Op::RemapF, &[207, 158, 142, 160, 158, 9, 186], 1856);
                step(f, Op::MaxF, &[182, 186, 185], 1857);
                step(f, Op::Select(ValueType::Float), &[19, 160, 185, 189], 1858);
                step(f, Op::LerpF, &[209, 205, 189, 188], 1859);
                step(f, Op::ArrayAt(Elem::Float), &[2, 11, 187], 1860);
                step(f, Op::RemapF, &[187, 159, 160, 158, 160, 9, 192], 1861);
                step(f, Op::MulF, &[188, 192, 213], 1862);
                step(f, Op::RemapF, &[187, 158, 142, 160, 158, 9, 202], 1863);
                step(f, Op::MulF, &[209, 202, 211], 1864);
                step(f, Op::MaxF, &[213, 211, 210], 1865);
                step(f, Op::Select(ValueType::Float), &[16, 209, 210, 200], 1866);
                step(f, Op::MaxF, &[183, 200, 212], 1867);
                step(f, Op::Copy(ValueType::Float), &[212, 183], 1868);
                step(f, Op::Jump, &[1822], 1869)
            }
            1869 => {
                step(f, Op::ClampF, &[183, 158, 140, 219, 219, 219], 1870);
                step(f, Op::MakeVector, &[24, 158, 158, 25], 1871);
                step(f, Op::MakeVector, &[219, 158, 158, 33], 1872);
                step(f, Op::MakeVector, &[25, 158, 158, 35], 1873);
                step(f, Op::GreaterF, &[219, 24, 12], 1874);
                step(f, Op::Select(ValueType::Float), &[12, 144, 141, 204, 58, 58], 1875);
                step(f, Op::SubV, &[33, 35, 38], 1876);
                step(f, Op::DeltaTime, &[190], 1877);
                step(f, Op::DivF, &[58, 190, 191], 1878);
                step(f, Op::ScaleV, &[38, 191, 29], 1879);
                step(f, Op::AddV, &[33, 29, 56], 1880);
                step(f, Op::AddV, &[35, 29, 39], 1881);
                step(f, Op::SubV, &[25, 39, 40], 1882);
                step(f, Op::FloatLerp, &[158, 160, 204, 218], 1883);
                step(f, Op::SubF, &[160, 218, 195], 1884);
                step(f, Op::ScaleV, &[40, 195, 50], 1885);
                step(f, Op::AddV, &[56, 50, 30], 1886);
                step(f, Op::MulF, &[204, 190, 199], 1887);
                step(f, Op::GreaterF, &[199, 158, 18], 1888);
                step(f, Op::DivF, &[218, 199, 206], 1889);
                step(f, Op::Select(ValueType::Float), &[18, 206, 160, 222], 1890);
                step(f, Op::ScaleV, &[38, 222, 34], 1891);
                step(f, Op::SubV, &[30, 34, 52, 52, 52], 1892);
                step(f, Op::BreakVector, &[52, 184, 196, 201], 1893);
                step(f, Op::Select(ValueType::Float), &[11, 219, 184, 24, 24, 24], 1894);
                step(f, Op::Copy(ValueType::Float), &[219, 25], 1895);
                step(f, Op::GetTransform, &[47, 2, 10, 18], 1896);
                step(f, Op::BreakTransform, &[18, 41, 4, 54], 1897);
                step(f, Op::MakeVector, &[158, 158, 24, 32], 1898);
                step(f, Op::SubV, &[41, 32, 53], 1899);
                step(f, Op::MakeTransform, &[53, 4, 6, 19], 1900);
                step(f, Op::SetTransform, &[48, 19, 2, 9, 160], 1901);
                step(f, Op::JumpIfFalse, &[8, 1907], 1902)
            }
            1902 => {
                step(f, Op::GetTransform, &[47, 2, 10, 18], 1903);
                step(f, Op::BreakTransform, &[18, 41, 4, 54], 1904);
                step(f, Op::SubV, &[41, 32, 53], 1905);
                step(f, Op::MakeTransform, &[53, 4, 6, 19], 1906);
                step(f, Op::DrawTransform, &[19, 181, 159], 1907);
                1907
            }
            1907 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1908);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 1909);
                1909
            }
            1909 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 7, 2, 9, 12, 1958], 1910)
            }
            1910 => {
                step(f, Op::GetParent, &[2, 29], 1911);
                step(f, Op::GetParent, &[29, 30], 1912);
                step(f, Op::GetTransform, &[30, 2, 10, 7], 1913);
                step(f, Op::BreakTransform, &[7, 51, 8, 28], 1914);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 9, 4], 1915);
                step(f, Op::BreakTransform, &[4, 21, 5, 44], 1916);
                step(f, Op::SubV, &[21, 51, 31], 1917);
                step(f, Op::LengthV, &[31, 215], 1918);
                step(f, Op::ArrayAt(Elem::Float), &[1, 9, 216], 1919);
                step(f, Op::MulF, &[216, 152, 198], 1920);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 9, 20], 1921);
                step(f, Op::MulF, &[19, 118, 197], 1922);
                step(f, Op::ArrayAt(Elem::Float), &[2, 9, 220], 1923);
                step(f, Op::ClampF, &[220, 158, 160, 214], 1924);
                step(f, Op::LessF, &[214, 159, 15], 1925);
                step(f, Op::SmoothStepF, &[214, 154, 155, 203], 1926);
                step(f, Op::MulF, &[214, 168, 217], 1927);
                step(f, Op::SinF, &[217, 193], 1928);
                step(f, Op::MaxF, &[203, 193, 221], 1929);
                step(f, Op::Select(ValueType::Float), &[15, 221, 193, 194], 1930);
                step(f, Op::MulF, &[194, 153, 208], 1931);
                step(f, Op::Select(ValueType::Float), &[20, 197, 208, 207], 1932);
                step(f, Op::SubF, &[198, 207, 182], 1933);
                step(f, Op::SubF, &[215, 182, 186], 1934);
                step(f, Op::MaxF, &[186, 158, 185], 1935);
                step(f, Op::MulF, &[185, 185, 189], 1936);
                step(f, Op::AddF, &[185, 207, 205], 1937);
                step(f, Op::DivF, &[189, 205, 188], 1938);
                step(f, Op::SubF, &[215, 188, 192], 1939);
                step(f, Op::DivF, &[192, 215, 187], 1940);
                step(f, Op::ScaleV, &[31, 187, 60], 1941);
                step(f, Op::AddV, &[51, 60, 20], 1942);
                step(f, Op::ClampSpatially, &[20, 51, 158, 198, 17], 1943);
                step(f, Op::MakeTransform, &[17, 5, 6, 8], 1944);
                step(f, Op::Equals(Elem::Int), &[9, 2, 17], 1945);
                step(f, Op::Select(ValueType::Vec3), &[17, 14, 13, 36], 1946);
                step(f, Op::Select(ValueType::Vec3), &[17, 9, 15, 42], 1947);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 9, 5], 1948);
                step(f, Op::BreakTransform, &[5, 43, 10, 19], 1949);
                step(f, Op::ArrayAt(Elem::Vec3), &[3, 9, 45], 1950);
                step(f, Op::KneeVector, &[10, 0, 45, 156, 157, 49], 1951);
                step(f, Op::TwoBoneIK, &[30, 29, 2, 8, 36, 42, 49, 2, 160, 10, 178, 179, 9, 14, 202], 1952);
                step(f, Op::JumpIfFalse, &[8, 1957], 1953)
            }
            1953 => {
                step(f, Op::GetTransform, &[29, 2, 10, 13], 1954);
                step(f, Op::BreakTransform, &[13, 46, 9, 59], 1955);
                step(f, Op::AddV, &[46, 49, 55], 1956);
                step(f, Op::DrawLine, &[46, 55, 159, 16], 1957);
                1957
            }
            1957 => {
                step(f, Op::Jump, &[1909], 1958)
            }
            1958 => {
                step(f, Op::End, &[], 1959)
            }
            _ => return,
        } };
    }
}
