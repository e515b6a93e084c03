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
    fingerprint: 0x62739a4e63ba4688,
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
                step(f, Op::LengthV, &[17, 178], 113);
                step(f, Op::GreaterF, &[178, 37, 11], 114);
                step(f, Op::Copy(ValueType::Bool), &[11, 2], 115);
                step(f, Op::MakeRelative, &[5, 4, 6], 116);
                step(f, Op::Select(ValueType::Transform), &[11, 3, 6, 7], 117);
                step(f, Op::Copy(ValueType::Transform), &[7, 2], 118);
                step(f, Op::InverseT, &[5, 6], 119);
                step(f, Op::MulT, &[4, 6, 7], 120);
                step(f, Op::Copy(ValueType::Transform), &[7, 1], 121);
                step(f, Op::TransformVector, &[2, 0, 18], 122);
                step(f, Op::InverseT, &[4, 5], 123);
                step(f, Op::DeltaTime, &[176], 124);
                step(f, Op::DivF, &[154, 176, 177], 125);
                step(f, Op::ScaleV, &[17, 177, 20], 126);
                step(f, Op::TransformVector, &[5, 20, 21], 127);
                step(f, Op::BreakVector, &[21, 178, 177, 179], 128);
                step(f, Op::MakeVector, &[178, 177, 152, 16], 129);
                step(f, Op::LengthV, &[16, 180], 130);
                step(f, Op::MulF, &[180, 140, 181], 131);
                step(f, Op::NegF, &[181, 180], 132);
                step(f, Op::ClampF, &[179, 180, 181, 182], 133);
                step(f, Op::MakeVector, &[178, 177, 182, 19], 134);
                step(f, Op::Select(ValueType::Vec3), &[2, 18, 19, 20], 135);
                step(f, Op::VectorLerp, &[18, 20, 38, 152, 21], 136);
                step(f, Op::Copy(ValueType::Vec3), &[21, 0], 137);
                step(f, Op::TransformVector, &[2, 1, 16], 138);
                step(f, Op::TransformVector, &[2, 0, 18], 139);
                step(f, Op::Select(ValueType::Vec3), &[2, 18, 19, 20], 140);
                step(f, Op::VectorLerp, &[16, 20, 39, 152, 21], 141);
                step(f, Op::Copy(ValueType::Vec3), &[21, 1], 142);
                step(f, Op::LengthV, &[20, 179], 143);
                step(f, Op::Copy(ValueType::Float), &[179, 0], 144);
                step(f, Op::BreakVector, &[17, 180, 181, 177], 145);
                step(f, Op::MulF, &[182, 176, 178], 146);
                step(f, Op::SubF, &[177, 178, 179], 147);
                step(f, Op::Select(ValueType::Float), &[11, 152, 179, 180], 148);
                step(f, Op::Copy(ValueType::Float), &[180, 1], 149);
                step(f, Op::JumpIfFalse, &[2, 163], 150)
            }
            150 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 12], 151);
                step(f, Op::Copy(ValueType::Int), &[2, 6], 152);
                152
            }
            152 => {
                step(f, Op::ForEachNext(Elem::Bone), &[12, 6, 13, 8, 7, 162], 153)
            }
            153 => {
                step(f, Op::ArrayAt(Elem::Transform), &[8, 8, 6], 154);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 8, 6], 155);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 8, 6], 156);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 8, 6], 157);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 8, 6], 158);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 8, 6], 159);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 8, 6], 160);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 8, 6], 161);
                step(f, Op::Jump, &[152], 162)
            }
            162 => {
                step(f, Op::Copy(ValueType::Float), &[152, 18], 163);
                163
            }
            163 => {
                step(f, Op::Copy(ValueType::Transform), &[4, 0], 164);
                step(f, Op::Copy(ValueType::Bool), &[9, 0], 165);
                step(f, Op::JumpIfFalse, &[8, 171], 166)
            }
            166 => {
                step(f, Op::GetTransform, &[33, 2, 9, 7], 167);
                step(f, Op::BreakTransform, &[7, 18, 2, 19], 168);
                step(f, Op::ScaleV, &[0, 155, 16], 169);
                step(f, Op::AddV, &[18, 16, 21], 170);
                step(f, Op::DrawArrow, &[18, 21, 153, 7], 171);
                171
            }
            171 => {
                step(f, Op::Copy(ValueType::Float), &[152, 181], 172);
                step(f, Op::Copy(ValueType::Float), &[154, 176], 173);
                step(f, Op::Copy(ValueType::Bool), &[10, 11], 174);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[8, 9], 175);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 176);
                step(f, Op::MakeVector, &[152, 152, 60, 20], 177);
                177
            }
            177 => {
                step(f, Op::ForEachNext(Elem::Transform), &[9, 7, 5, 8, 6, 187], 178)
            }
            178 => {
                step(f, Op::BreakTransform, &[5, 17, 2, 19], 179);
                step(f, Op::TransformPoint, &[2, 17, 16], 180);
                step(f, Op::LerpV, &[16, 17, 154, 18], 181);
                step(f, Op::AddV, &[18, 20, 21], 182);
                step(f, Op::SubV, &[18, 20, 19], 183);
                step(f, Op::LineTrace, &[21, 19, 12, 16, 17, 182], 184);
                step(f, Op::JumpIfFalse, &[12, 186], 185)
            }
            185 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 11], 186);
                186
            }
            186 => {
                step(f, Op::Jump, &[177], 187)
            }
            187 => {
                step(f, Op::Copy(ValueType::Bool), &[11, 12], 188);
                step(f, Op::Or, &[12, 7, 11], 189);
                step(f, Op::NotEquals(Elem::Bool), &[11, 5, 13], 190);
                step(f, Op::JumpIfFalse, &[13, 219], 191)
            }
            191 => {
                step(f, Op::NotEquals(Elem::Bool), &[12, 6, 14], 192);
                step(f, Op::JumpIfFalse, &[14, 219], 193)
            }
            193 => {
                step(f, Op::Copy(ValueType::Int), &[1, 6], 194);
                step(f, Op::Copy(ValueType::Int), &[2, 8], 195);
                195
            }
            195 => {
                step(f, Op::ForNext, &[8, 6, 7, 219], 196)
            }
            196 => {
                step(f, Op::AddF, &[181, 176, 177], 197);
                step(f, Op::MulF, &[177, 153, 178], 198);
                step(f, Op::Copy(ValueType::Bool), &[10, 15], 199);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[8, 10], 200);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 201);
                step(f, Op::MakeVector, &[152, 152, 60, 18], 202);
                202
            }
            202 => {
                step(f, Op::ForEachNext(Elem::Transform), &[10, 7, 6, 9, 10, 212], 203)
            }
            203 => {
                step(f, Op::BreakTransform, &[6, 16, 2, 17], 204);
                step(f, Op::TransformPoint, &[2, 16, 19], 205);
                step(f, Op::LerpV, &[19, 16, 178, 21], 206);
                step(f, Op::AddV, &[21, 18, 20], 207);
                step(f, Op::SubV, &[21, 18, 17], 208);
                step(f, Op::LineTrace, &[20, 17, 16, 16, 19, 179], 209);
                step(f, Op::JumpIfFalse, &[16, 211], 210)
            }
            210 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 15], 211);
                211
            }
            211 => {
                step(f, Op::Jump, &[202], 212)
            }
            212 => {
                step(f, Op::Copy(ValueType::Bool), &[15, 16], 213);
                step(f, Op::Equals(Elem::Bool), &[16, 6, 15], 214);
                step(f, Op::JumpIfFalse, &[15, 217], 215)
            }
            215 => {
                step(f, Op::Copy(ValueType::Float), &[178, 181], 216);
                step(f, Op::Jump, &[218], 217)
            }
            217 => {
                step(f, Op::Copy(ValueType::Float), &[178, 176], 218);
                218
            }
            218 => {
                step(f, Op::Jump, &[195], 219)
            }
            219 => {
                step(f, Op::Select(ValueType::Float), &[5, 156, 154, 180], 220);
                step(f, Op::NotEquals(Elem::Bool), &[12, 6, 14], 221);
                step(f, Op::AddF, &[181, 176, 177], 222);
                step(f, Op::MulF, &[177, 153, 182], 223);
                step(f, Op::Select(ValueType::Float), &[14, 182, 153, 179], 224);
                step(f, Op::Select(ValueType::Float), &[13, 179, 152, 178], 225);
                step(f, Op::MulF, &[180, 178, 176], 226);
                step(f, Op::DeltaTime, &[181], 227);
                step(f, Op::DivF, &[181, 144, 177], 228);
                step(f, Op::MulF, &[176, 177, 182], 229);
                step(f, Op::AddF, &[22, 182, 178], 230);
                step(f, Op::ClampF, &[178, 152, 154, 180], 231);
                step(f, Op::Select(ValueType::Float), &[11, 156, 154, 181], 232);
                step(f, Op::SubF, &[154, 179, 176], 233);
                step(f, Op::Select(ValueType::Float), &[13, 176, 154, 182], 234);
                step(f, Op::MulF, &[181, 182, 178], 235);
                step(f, Op::MulF, &[178, 177, 179], 236);
                step(f, Op::AddF, &[180, 179, 176], 237);
                step(f, Op::ClampF, &[176, 152, 154, 181], 238);
                step(f, Op::SmoothStepF, &[181, 152, 154, 182], 239);
                step(f, Op::AddF, &[23, 182, 177], 240);
                step(f, Op::MulF, &[177, 153, 178], 241);
                step(f, Op::SubF, &[154, 178, 179], 242);
                step(f, Op::MulF, &[179, 179, 180], 243);
                step(f, Op::SubF, &[154, 180, 176], 244);
                step(f, Op::Copy(ValueType::Float), &[176, 24], 245);
                step(f, Op::Copy(ValueType::Float), &[182, 23], 246);
                step(f, Op::Copy(ValueType::Float), &[181, 22], 247);
                step(f, Op::GreaterF, &[23, 152, 16], 248);
                step(f, Op::TransformVector, &[2, 3, 21], 249);
                step(f, Op::Select(ValueType::Vec3), &[16, 21, 0, 16], 250);
                step(f, Op::Copy(ValueType::Vec3), &[16, 3], 251);
                step(f, Op::LerpV, &[0, 3, 23, 17], 252);
                step(f, Op::Select(ValueType::Vec3), &[16, 17, 0, 19], 253);
                step(f, Op::Copy(ValueType::Vec3), &[19, 2], 254);
                step(f, Op::Copy(ValueType::Bool), &[11, 5], 255);
                step(f, Op::Copy(ValueType::Bool), &[12, 6], 256);
                step(f, Op::Copy(ValueType::Bool), &[10, 7], 257);
                step(f, Op::SubF, &[154, 24, 177], 258);
                step(f, Op::MulF, &[1, 177, 178], 259);
                step(f, Op::AddF, &[2, 178, 179], 260);
                step(f, Op::Copy(ValueType::Float), &[4, 180], 261);
                step(f, Op::Copy(ValueType::Float), &[5, 176], 262);
                step(f, Op::Copy(ValueType::Float), &[2, 182], 263);
                step(f, Op::Copy(ValueType::Float), &[141, 181], 264);
                step(f, Op::Copy(ValueType::Float), &[54, 177], 265);
                step(f, Op::SubF, &[179, 182, 178], 266);
                step(f, Op::DeltaTime, &[183], 267);
                step(f, Op::DivF, &[178, 183, 184], 268);
                step(f, Op::MulF, &[184, 177, 185], 269);
                step(f, Op::AddF, &[179, 185, 186], 270);
                step(f, Op::MulF, &[184, 157, 187], 271);
                step(f, Op::DivF, &[158, 181, 188], 272);
                step(f, Op::DivF, &[187, 188, 189], 273);
                step(f, Op::SubF, &[186, 189, 190], 274);
                step(f, Op::AddF, &[182, 185, 191], 275);
                step(f, Op::SubF, &[180, 191, 192], 276);
                step(f, Op::AddF, &[192, 189, 193], 277);
                step(f, Op::SubF, &[176, 184, 194], 278);
                step(f, Op::MulF, &[188, 193, 195], 279);
                step(f, Op::AddF, &[194, 195, 196], 280);
                step(f, Op::MulF, &[196, 183, 197], 281);
                step(f, Op::AddF, &[193, 197, 198], 282);
                step(f, Op::FloatLerp, &[152, 154, 188, 199], 283);
                step(f, Op::SubF, &[154, 199, 200], 284);
                step(f, Op::MulF, &[198, 200, 201], 285);
                step(f, Op::AddF, &[190, 201, 202], 286);
                step(f, Op::Copy(ValueType::Float), &[202, 203], 287);
                step(f, Op::MulF, &[188, 197, 204], 288);
                step(f, Op::SubF, &[194, 204, 205], 289);
                step(f, Op::MulF, &[205, 200, 206], 290);
                step(f, Op::AddF, &[184, 206, 207], 291);
                step(f, Op::Copy(ValueType::Float), &[207, 208], 292);
                step(f, Op::SubF, &[179, 203, 209], 293);
                step(f, Op::Copy(ValueType::Float), &[209, 3], 294);
                step(f, Op::Copy(ValueType::Float), &[203, 4], 295);
                step(f, Op::Copy(ValueType::Float), &[4, 180], 296);
                step(f, Op::Copy(ValueType::Float), &[5, 176], 297);
                step(f, Op::Copy(ValueType::Float), &[2, 182], 298);
                step(f, Op::Copy(ValueType::Float), &[141, 181], 299);
                step(f, Op::Copy(ValueType::Float), &[54, 177], 300);
                step(f, Op::SubF, &[179, 182, 178], 301);
                step(f, Op::DeltaTime, &[183], 302);
                step(f, Op::DivF, &[178, 183, 184], 303);
                step(f, Op::MulF, &[184, 177, 185], 304);
                step(f, Op::AddF, &[179, 185, 186], 305);
                step(f, Op::MulF, &[184, 157, 187], 306);
                step(f, Op::DivF, &[158, 181, 188], 307);
                step(f, Op::DivF, &[187, 188, 189], 308);
                step(f, Op::SubF, &[186, 189, 190], 309);
                step(f, Op::AddF, &[182, 185, 191], 310);
                step(f, Op::SubF, &[180, 191, 192], 311);
                step(f, Op::AddF, &[192, 189, 193], 312);
                step(f, Op::SubF, &[176, 184, 194], 313);
                step(f, Op::MulF, &[188, 193, 195], 314);
                step(f, Op::AddF, &[194, 195, 196], 315);
                step(f, Op::MulF, &[196, 183, 197], 316);
                step(f, Op::AddF, &[193, 197, 198], 317);
                step(f, Op::FloatLerp, &[152, 154, 188, 199], 318);
                step(f, Op::SubF, &[154, 199, 200], 319);
                step(f, Op::MulF, &[198, 200, 201], 320);
                step(f, Op::AddF, &[190, 201, 202], 321);
                step(f, Op::Copy(ValueType::Float), &[202, 203], 322);
                step(f, Op::MulF, &[188, 197, 204], 323);
                step(f, Op::SubF, &[194, 204, 205], 324);
                step(f, Op::MulF, &[205, 200, 206], 325);
                step(f, Op::AddF, &[184, 206, 207], 326);
                step(f, Op::Copy(ValueType::Float), &[207, 208], 327);
                step(f, Op::Copy(ValueType::Float), &[208, 5], 328);
                step(f, Op::Copy(ValueType::Float), &[179, 2], 329);
                step(f, Op::LengthV, &[4, 209], 330);
                step(f, Op::GreaterF, &[209, 31, 15], 331);
                step(f, Op::LengthV, &[2, 178], 332);
                step(f, Op::GreaterF, &[178, 31, 14], 333);
                step(f, Op::And, &[15, 14, 13], 334);
                step(f, Op::Select(ValueType::Vec3), &[15, 4, 6, 20], 335);
                step(f, Op::MovementAngleOffset, &[20, 14, 152, 159, 159, 160, 42, 161, 177], 336);
                step(f, Op::Copy(ValueType::Float), &[14, 181], 337);
                step(f, Op::SubF, &[177, 181, 187], 338);
                step(f, Op::AddF, &[187, 162, 186], 339);
                step(f, Op::DivF, &[186, 163, 182], 340);
                step(f, Op::FractF, &[182, 185], 341);
                step(f, Op::MulF, &[185, 163, 180], 342);
                step(f, Op::SubF, &[180, 162, 191], 343);
                step(f, Op::Copy(ValueType::Float), &[191, 189], 344);
                step(f, Op::AbsF, &[189, 192], 345);
                step(f, Op::Select(ValueType::Vec3), &[14, 2, 6, 18], 346);
                step(f, Op::MovementAngleOffset, &[18, 14, 152, 159, 159, 160, 42, 161, 176], 347);
                step(f, Op::Copy(ValueType::Float), &[14, 195], 348);
                step(f, Op::SubF, &[176, 195, 183], 349);
                step(f, Op::AddF, &[183, 162, 196], 350);
                step(f, Op::DivF, &[196, 163, 193], 351);
                step(f, Op::FractF, &[193, 199], 352);
                step(f, Op::MulF, &[199, 163, 198], 353);
                step(f, Op::SubF, &[198, 162, 190], 354);
                step(f, Op::Copy(ValueType::Float), &[190, 201], 355);
                step(f, Op::AbsF, &[201, 202], 356);
                step(f, Op::MaxF, &[192, 202, 203], 357);
                step(f, Op::SubF, &[176, 177, 188], 358);
                step(f, Op::AddF, &[188, 162, 197], 359);
                step(f, Op::DivF, &[197, 163, 194], 360);
                step(f, Op::FractF, &[194, 204], 361);
                step(f, Op::MulF, &[204, 163, 200], 362);
                step(f, Op::SubF, &[200, 162, 205], 363);
                step(f, Op::Copy(ValueType::Float), &[205, 184], 364);
                step(f, Op::AbsF, &[184, 206], 365);
                step(f, Op::MaxF, &[203, 206, 207], 366);
                step(f, Op::LessF, &[207, 164, 16], 367);
                step(f, Op::And, &[13, 16, 11], 368);
                step(f, Op::Not, &[15, 12], 369);
                step(f, Op::Not, &[14, 13], 370);
                step(f, Op::And, &[12, 13, 16], 371);
                step(f, Op::Or, &[11, 16, 15], 372);
                step(f, Op::JumpIfFalse, &[15, 394], 373)
            }
            373 => {
                step(f, Op::DeltaTime, &[208], 374);
                step(f, Op::MulF, &[40, 208, 179], 375);
                step(f, Op::GreaterF, &[179, 152, 12], 376);
                step(f, Op::DivF, &[54, 208, 209], 377);
                step(f, Op::FloatLerp, &[152, 154, 40, 181], 378);
                step(f, Op::SubF, &[154, 181, 187], 379);
                step(f, Op::DivF, &[187, 181, 186], 380);
                step(f, Op::DivF, &[154, 179, 182], 381);
                step(f, Op::SubF, &[186, 182, 185], 382);
                step(f, Op::AddF, &[209, 185, 180], 383);
                step(f, Op::Select(ValueType::Float), &[12, 180, 152, 191], 384);
                step(f, Op::MulF, &[184, 191, 189], 385);
                step(f, Op::AddF, &[176, 189, 195], 386);
                step(f, Op::SinF, &[195, 183], 387);
                step(f, Op::NegF, &[183, 196], 388);
                step(f, Op::CosF, &[195, 193], 389);
                step(f, Op::MakeVector, &[196, 193, 152, 21], 390);
                step(f, Op::Select(ValueType::Vec3), &[14, 21, 6, 16], 391);
                step(f, Op::MovementAngleOffset, &[16, 14, 152, 40, 41, 160, 162, 161, 199], 392);
                step(f, Op::Copy(ValueType::Float), &[199, 14], 393);
                step(f, Op::Jump, &[450], 394)
            }
            394 => {
                step(f, Op::DeltaTime, &[208], 395);
                step(f, Op::DivF, &[208, 44, 198], 396);
                step(f, Op::AddF, &[198, 153, 190], 397);
                step(f, Op::FloorF, &[190, 201], 398);
                step(f, Op::MaxF, &[201, 154, 192], 399);
                step(f, Op::ToInt, &[192, 9], 400);
                step(f, Op::Copy(ValueType::Int), &[9, 10], 401);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 402);
                step(f, Op::MulF, &[44, 153, 202], 403);
                step(f, Op::SubF, &[54, 202, 177], 404);
                step(f, Op::DivF, &[177, 208, 188], 405);
                step(f, Op::FloatLerp, &[152, 154, 38, 197], 406);
                step(f, Op::GreaterF, &[197, 152, 13], 407);
                step(f, Op::DivF, &[40, 192, 194], 408);
                step(f, Op::DivF, &[41, 192, 204], 409);
                step(f, Op::SubF, &[160, 43, 200], 410);
                step(f, Op::GreaterF, &[43, 152, 11], 411);
                411
            }
            411 => {
                step(f, Op::ForNext, &[7, 10, 6, 450], 412)
            }
            412 => {
                step(f, Op::ToFloat, &[6, 205], 413);
                step(f, Op::AddF, &[205, 154, 203], 414);
                step(f, Op::DivF, &[203, 192, 206], 415);
                step(f, Op::AddF, &[206, 188, 207], 416);
                step(f, Op::MulF, &[38, 207, 181], 417);
                step(f, Op::FloatLerp, &[152, 154, 181, 187], 418);
                step(f, Op::DivF, &[187, 197, 179], 419);
                step(f, Op::Select(ValueType::Float), &[13, 179, 207, 182], 420);
                step(f, Op::LerpV, &[4, 2, 182, 17], 421);
                step(f, Op::LengthV, &[17, 186], 422);
                step(f, Op::GreaterF, &[186, 31, 16], 423);
                step(f, Op::Select(ValueType::Vec3), &[16, 17, 6, 19], 424);
                step(f, Op::MulF, &[208, 207, 185], 425);
                step(f, Op::MulF, &[8, 185, 209], 426);
                step(f, Op::AddF, &[12, 209, 180], 427);
                step(f, Op::FractF, &[180, 184], 428);
                step(f, Op::MulF, &[184, 157, 191], 429);
                step(f, Op::FractF, &[191, 176], 430);
                step(f, Op::LessF, &[176, 161, 15], 431);
                step(f, Op::MovementAngleOffset, &[19, 14, 152, 159, 159, 160, 42, 161, 189], 432);
                step(f, Op::Copy(ValueType::Float), &[14, 183], 433);
                step(f, Op::SubF, &[189, 183, 195], 434);
                step(f, Op::AddF, &[195, 162, 193], 435);
                step(f, Op::DivF, &[193, 163, 196], 436);
                step(f, Op::FractF, &[196, 199], 437);
                step(f, Op::MulF, &[199, 163, 198], 438);
                step(f, Op::SubF, &[198, 162, 190], 439);
                step(f, Op::Copy(ValueType::Float), &[190, 201], 440);
                step(f, Op::AbsF, &[201, 202], 441);
                step(f, Op::SmoothStepF, &[202, 200, 160, 177], 442);
                step(f, Op::GreaterF, &[202, 160, 12], 443);
                step(f, Op::Select(ValueType::Float), &[12, 154, 152, 205], 444);
                step(f, Op::Select(ValueType::Float), &[11, 177, 205, 203], 445);
                step(f, Op::Select(ValueType::Float), &[15, 152, 203, 206], 446);
                step(f, Op::LerpF, &[194, 204, 206, 181], 447);
                step(f, Op::MovementAngleOffset, &[19, 14, 184, 181, 181, 160, 42, 161, 187], 448);
                step(f, Op::Copy(ValueType::Float), &[187, 14], 449);
                step(f, Op::Jump, &[411], 450)
            }
            450 => {
                step(f, Op::QuatFromAxisAngle, &[8, 14, 2], 451);
                step(f, Op::Copy(ValueType::Quat), &[2, 0], 452);
                step(f, Op::SinF, &[14, 179], 453);
                step(f, Op::AbsF, &[179, 182], 454);
                step(f, Op::RemapF, &[182, 45, 46, 152, 154, 9, 186], 455);
                step(f, Op::BreakVector, &[18, 207, 185, 209], 456);
                step(f, Op::AbsF, &[207, 180], 457);
                step(f, Op::DivF, &[180, 178, 191], 458);
                step(f, Op::RemapF, &[191, 45, 46, 152, 154, 9, 176], 459);
                step(f, Op::TransformVector, &[2, 9, 20], 460);
                step(f, Op::DistanceV, &[20, 9, 183], 461);
                step(f, Op::DivF, &[183, 208, 189], 462);
                step(f, Op::RemapF, &[189, 50, 51, 154, 152, 9, 195], 463);
                step(f, Op::MulF, &[176, 195, 193], 464);
                step(f, Op::MaxF, &[186, 193, 196], 465);
                step(f, Op::Copy(ValueType::Float), &[196, 15], 466);
                step(f, Op::Copy(ValueType::Vec3), &[2, 4], 467);
                step(f, Op::Copy(ValueType::Bool), &[9, 14], 468);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 2], 469);
                step(f, Op::Copy(ValueType::Int), &[2, 8], 470);
                470
            }
            470 => {
                step(f, Op::ForEachNext(Elem::Bool), &[2, 8, 16, 9, 6, 475], 471)
            }
            471 => {
                step(f, Op::Not, &[16, 12], 472);
                step(f, Op::JumpIfFalse, &[12, 474], 473)
            }
            473 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 14], 474);
                474
            }
            474 => {
                step(f, Op::Jump, &[470], 475)
            }
            475 => {
                step(f, Op::Copy(ValueType::Bool), &[14, 15], 476);
                step(f, Op::Copy(ValueType::Bool), &[9, 11], 477);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 478);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 479);
                479
            }
            479 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 7, 15, 10, 6, 493], 480)
            }
            480 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 10, 4], 481);
                step(f, Op::BreakTransform, &[4, 21, 2, 16], 482);
                step(f, Op::BreakVector, &[21, 199, 198, 190], 483);
                step(f, Op::MakeVector, &[199, 198, 152, 17], 484);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 10, 7], 485);
                step(f, Op::BreakTransform, &[7, 19, 2, 18], 486);
                step(f, Op::BreakVector, &[19, 201, 202, 177], 487);
                step(f, Op::MakeVector, &[201, 202, 152, 20], 488);
                step(f, Op::DistanceV, &[17, 20, 205], 489);
                step(f, Op::GreaterF, &[205, 33, 13], 490);
                step(f, Op::JumpIfFalse, &[13, 492], 491)
            }
            491 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 11], 492);
                492
            }
            492 => {
                step(f, Op::Jump, &[479], 493)
            }
            493 => {
                step(f, Op::Copy(ValueType::Bool), &[11, 16], 494);
                step(f, Op::And, &[15, 16, 12], 495);
                step(f, Op::LengthV, &[2, 203], 496);
                step(f, Op::GreaterF, &[203, 31, 14], 497);
                step(f, Op::GreaterF, &[0, 31, 13], 498);
                step(f, Op::Or, &[14, 13, 11], 499);
                step(f, Op::Not, &[11, 16], 500);
                step(f, Op::And, &[12, 16, 13], 501);
                step(f, Op::DeltaTime, &[206], 502);
                step(f, Op::MulF, &[206, 36, 181], 503);
                step(f, Op::AddF, &[12, 181, 184], 504);
                step(f, Op::GreaterF, &[12, 153, 11], 505);
                step(f, Op::AddF, &[35, 153, 187], 506);
                step(f, Op::Select(ValueType::Float), &[11, 187, 35, 188], 507);
                step(f, Op::MinF, &[184, 188, 192], 508);
                step(f, Op::NotEquals(Elem::Bool), &[16, 4, 11], 509);
                step(f, Op::Not, &[12, 17], 510);
                step(f, Op::And, &[11, 17, 18], 511);
                step(f, Op::SubF, &[13, 31, 194], 512);
                step(f, Op::SubF, &[13, 203, 197], 513);
                step(f, Op::DivF, &[194, 197, 200], 514);
                step(f, Op::ClampF, &[200, 152, 154, 204], 515);
                step(f, Op::MulF, &[8, 204, 179], 516);
                step(f, Op::RemapF, &[203, 31, 32, 152, 154, 9, 182], 517);
                step(f, Op::MaxF, &[182, 9, 185], 518);
                step(f, Op::Select(ValueType::Float), &[15, 154, 185, 209], 519);
                step(f, Op::Select(ValueType::Float), &[16, 34, 209, 207], 520);
                step(f, Op::Select(ValueType::Float), &[12, 182, 207, 178], 521);
                step(f, Op::SubF, &[154, 23, 180], 522);
                step(f, Op::MulF, &[178, 180, 191], 523);
                step(f, Op::LerpF, &[25, 48, 15, 183], 524);
                step(f, Op::RemapF, &[203, 28, 29, 26, 27, 9, 208], 525);
                step(f, Op::LerpF, &[208, 47, 15, 189], 526);
                step(f, Op::MaxF, &[203, 30, 176], 527);
                step(f, Op::DivF, &[189, 176, 195], 528);
                step(f, Op::AddF, &[183, 195, 186], 529);
                step(f, Op::DivF, &[191, 186, 193], 530);
                step(f, Op::SubF, &[154, 204, 196], 531);
                step(f, Op::MulF, &[193, 196, 190], 532);
                step(f, Op::AddF, &[179, 190, 198], 533);
                step(f, Op::MulF, &[198, 157, 199], 534);
                step(f, Op::AddF, &[8, 193, 177], 535);
                step(f, Op::Select(ValueType::Float), &[18, 199, 177, 201], 536);
                step(f, Op::DivF, &[157, 201, 202], 537);
                step(f, Op::GreaterF, &[201, 152, 11], 538);
                step(f, Op::CycleStep, &[12, 202, 152, 11, 205, 181], 539);
                step(f, Op::Select(ValueType::Float), &[13, 192, 205, 187], 540);
                step(f, Op::Copy(ValueType::Float), &[187, 12], 541);
                step(f, Op::Copy(ValueType::Float), &[193, 8], 542);
                step(f, Op::Copy(ValueType::Bool), &[14, 3], 543);
                step(f, Op::Copy(ValueType::Float), &[195, 6], 544);
                step(f, Op::Copy(ValueType::Float), &[186, 7], 545);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 546);
                step(f, Op::Copy(ValueType::Int), &[2, 9], 547);
                step(f, Op::DivF, &[183, 186, 184], 548);
                step(f, Op::MulF, &[11, 204, 188], 549);
                step(f, Op::MulF, &[206, 153, 194], 550);
                step(f, Op::SubF, &[184, 10, 197], 551);
                step(f, Op::MaxF, &[197, 152, 200], 552);
                step(f, Op::DivF, &[200, 184, 208], 553);
                step(f, Op::SubF, &[154, 15, 176], 554);
                step(f, Op::DivF, &[54, 206, 189], 555);
                step(f, Op::SubF, &[153, 189, 179], 556);
                step(f, Op::MulF, &[208, 176, 190], 557);
                step(f, Op::MulF, &[190, 180, 198], 558);
                step(f, Op::MulF, &[198, 138, 177], 559);
                step(f, Op::MulF, &[177, 179, 199], 560);
                step(f, Op::SubF, &[154, 199, 201], 561);
                561
            }
            561 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 9, 14, 8, 6, 605], 562)
            }
            562 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 8, 181], 563);
                step(f, Op::ToFloat, &[8, 202], 564);
                step(f, Op::MulF, &[202, 153, 192], 565);
                step(f, Op::AddF, &[12, 192, 205], 566);
                step(f, Op::FractF, &[205, 187], 567);
                step(f, Op::SubF, &[181, 187, 193], 568);
                step(f, Op::GreaterF, &[193, 153, 17], 569);
                step(f, Op::ArrayAt(Elem::Float), &[2, 8, 195], 570);
                step(f, Op::Select(ValueType::Float), &[17, 152, 195, 186], 571);
                step(f, Op::ArraySetAt(Elem::Float), &[3, 8, 186], 572);
                step(f, Op::SubF, &[154, 181, 204], 573);
                step(f, Op::AddF, &[187, 204, 197], 574);
                step(f, Op::DivF, &[187, 197, 200], 575);
                step(f, Op::MaxF, &[182, 9, 185], 576);
                step(f, Op::Select(ValueType::Float), &[15, 154, 185, 209], 577);
                step(f, Op::Select(ValueType::Float), &[16, 34, 209, 207], 578);
                step(f, Op::Select(ValueType::Float), &[12, 182, 207, 178], 579);
                step(f, Op::MulF, &[178, 180, 191], 580);
                step(f, Op::DivF, &[191, 183, 206], 581);
                step(f, Op::MulF, &[206, 196, 189], 582);
                step(f, Op::AddF, &[188, 189, 190], 583);
                step(f, Op::MulF, &[190, 157, 198], 584);
                step(f, Op::AddF, &[11, 206, 177], 585);
                step(f, Op::Select(ValueType::Float), &[18, 198, 177, 179], 586);
                step(f, Op::MulF, &[179, 194, 199], 587);
                step(f, Op::MulF, &[200, 199, 202], 588);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 8, 11], 589);
                step(f, Op::MulF, &[199, 201, 192], 590);
                step(f, Op::Select(ValueType::Float), &[11, 199, 192, 205], 591);
                step(f, Op::MulF, &[208, 195, 193], 592);
                step(f, Op::MulF, &[193, 176, 186], 593);
                step(f, Op::MulF, &[186, 180, 181], 594);
                step(f, Op::MulF, &[181, 138, 204], 595);
                step(f, Op::Select(ValueType::Float), &[11, 152, 204, 197], 596);
                step(f, Op::SubF, &[205, 197, 189], 597);
                step(f, Op::AddF, &[195, 189, 190], 598);
                step(f, Op::Select(ValueType::Float), &[17, 202, 190, 177], 599);
                step(f, Op::MinF, &[177, 157, 198], 600);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 8, 198], 601);
                step(f, Op::JumpIfFalse, &[17, 603], 602)
            }
            602 => {
                step(f, Op::Copy(ValueType::Float), &[178, 9], 603);
                603
            }
            603 => {
                step(f, Op::ArraySetAt(Elem::Float), &[0, 8, 187], 604);
                step(f, Op::Jump, &[561], 605)
            }
            605 => {
                step(f, Op::Copy(ValueType::Float), &[184, 10], 606);
                step(f, Op::Copy(ValueType::Bool), &[16, 4], 607);
                step(f, Op::Copy(ValueType::Float), &[203, 13], 608);
                step(f, Op::MaxF, &[182, 9, 185], 609);
                step(f, Op::Select(ValueType::Float), &[15, 154, 185, 209], 610);
                step(f, Op::Select(ValueType::Float), &[16, 34, 209, 207], 611);
                step(f, Op::Select(ValueType::Float), &[12, 182, 207, 178], 612);
                step(f, Op::MulF, &[178, 180, 191], 613);
                step(f, Op::DivF, &[191, 183, 206], 614);
                step(f, Op::Copy(ValueType::Float), &[206, 11], 615);
                step(f, Op::TransformVector, &[2, 9, 16], 616);
                step(f, Op::DistanceV, &[16, 9, 179], 617);
                step(f, Op::DeltaTime, &[200], 618);
                step(f, Op::DivF, &[179, 200, 192], 619);
                step(f, Op::RemapF, &[192, 50, 51, 152, 154, 9, 199], 620);
                step(f, Op::BreakTransform, &[2, 21, 2, 18], 621);
                step(f, Op::BreakVector, &[21, 193, 186, 181], 622);
                step(f, Op::NegF, &[186, 204], 623);
                step(f, Op::Atan2F, &[193, 204, 197], 624);
                step(f, Op::AbsF, &[197, 205], 625);
                step(f, Op::RemapF, &[205, 108, 109, 152, 154, 9, 189], 626);
                step(f, Op::MulF, &[199, 189, 195], 627);
                step(f, Op::FloatLerp, &[16, 152, 110, 190], 628);
                step(f, Op::MaxF, &[195, 190, 202], 629);
                step(f, Op::Copy(ValueType::Float), &[202, 16], 630);
                step(f, Op::Copy(ValueType::Float), &[197, 17], 631);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 632);
                step(f, Op::Copy(ValueType::Int), &[2, 10], 633);
                633
            }
            633 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 10, 0, 7, 6, 1566], 634)
            }
            634 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 13], 635);
                step(f, Op::Copy(ValueType::Bool), &[10, 14], 636);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 7, 11], 637);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 177], 638);
                step(f, Op::GreaterEqualF, &[177, 154, 17], 639);
                step(f, Op::And, &[11, 17, 18], 640);
                step(f, Op::Or, &[1, 2, 15], 641);
                step(f, Op::GreaterF, &[23, 152, 16], 642);
                step(f, Op::Or, &[15, 16, 12], 643);
                step(f, Op::Not, &[12, 11], 644);
                step(f, Op::And, &[18, 11, 15], 645);
                step(f, Op::JumpIfFalse, &[15, 755], 646)
            }
            646 => {
                step(f, Op::ArrayAt(Elem::Transform), &[2, 7, 5], 647);
                step(f, Op::BreakTransform, &[5, 19, 2, 17], 648);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 7, 20], 649);
                step(f, Op::SubV, &[19, 20, 16], 650);
                step(f, Op::TransformPoint, &[2, 16, 18], 651);
                step(f, Op::GetTransform, &[34, 2, 9, 6], 652);
                step(f, Op::BreakTransform, &[6, 21, 3, 16], 653);
                step(f, Op::BreakVector, &[21, 198, 187, 176], 654);
                step(f, Op::SubF, &[154, 15, 188], 655);
                step(f, Op::MulF, &[14, 188, 194], 656);
                step(f, Op::QuatFromAxisAngle, &[8, 194, 4], 657);
                step(f, Op::GetTransform, &[0, 2, 9, 4], 658);
                step(f, Op::BreakTransform, &[4, 22, 5, 23], 659);
                step(f, Op::SubV, &[22, 21, 24], 660);
                step(f, Op::BreakVector, &[24, 196, 201, 208], 661);
                step(f, Op::MakeVector, &[196, 201, 152, 25], 662);
                step(f, Op::RotateVector, &[4, 25, 26], 663);
                step(f, Op::BreakVector, &[26, 184, 203, 185], 664);
                step(f, Op::MulF, &[49, 15, 209], 665);
                step(f, Op::Equals(Elem::Int), &[7, 2, 16], 666);
                step(f, Op::Select(ValueType::Float), &[16, 154, 156, 182], 667);
                step(f, Op::MulF, &[209, 182, 207], 668);
                step(f, Op::AddF, &[184, 207, 178], 669);
                step(f, Op::AddF, &[198, 178, 180], 670);
                step(f, Op::AddF, &[187, 203, 183], 671);
                step(f, Op::BreakVector, &[22, 191, 206, 179], 672);
                step(f, Op::SubF, &[179, 55, 200], 673);
                step(f, Op::MakeVector, &[180, 183, 200, 27], 674);
                step(f, Op::MulF, &[6, 153, 192], 675);
                step(f, Op::ScaleV, &[2, 192, 28], 676);
                step(f, Op::AddV, &[27, 28, 29], 677);
                step(f, Op::DistanceV, &[18, 29, 181], 678);
                step(f, Op::TransformVector, &[2, 10, 18], 679);
                step(f, Op::DistanceV, &[18, 10, 186], 680);
                step(f, Op::MaxF, &[181, 186, 193], 681);
                step(f, Op::LessEqualF, &[193, 62, 12], 682);
                step(f, Op::LengthV, &[2, 204], 683);
                step(f, Op::LengthV, &[4, 205], 684);
                step(f, Op::MaxF, &[204, 205, 189], 685);
                step(f, Op::LessEqualF, &[189, 31, 11], 686);
                step(f, Op::And, &[12, 11, 18], 687);
                step(f, Op::ArrayAt(Elem::Bool), &[1, 7, 15], 688);
                step(f, Op::And, &[18, 15, 11], 689);
                step(f, Op::JumpIfFalse, &[11, 692], 690)
            }
            690 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 14], 691);
                step(f, Op::Jump, &[721], 692)
            }
            692 => {
                step(f, Op::MakeVector, &[152, 152, 60, 18], 693);
                step(f, Op::AddV, &[29, 18, 30], 694);
                step(f, Op::SubV, &[29, 18, 31], 695);
                step(f, Op::SphereTrace, &[30, 31, 59, 12, 32, 33, 199], 696);
                step(f, Op::SubV, &[32, 29, 33], 697);
                step(f, Op::DistanceV, &[33, 20, 190], 698);
                step(f, Op::RotateVector, &[0, 9, 32], 699);
                step(f, Op::ScaleV, &[32, 64, 33], 700);
                step(f, Op::AddV, &[30, 33, 34], 701);
                step(f, Op::AddV, &[31, 33, 35], 702);
                step(f, Op::SphereTrace, &[34, 35, 59, 18, 36, 37, 195], 703);
                step(f, Op::SubV, &[36, 29, 38], 704);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 7, 39], 705);
                step(f, Op::DistanceV, &[38, 39, 202], 706);
                step(f, Op::MaxF, &[190, 202, 197], 707);
                step(f, Op::ScaleV, &[32, 61, 39], 708);
                step(f, Op::AddV, &[34, 39, 40], 709);
                step(f, Op::AddV, &[35, 39, 41], 710);
                step(f, Op::SphereTrace, &[40, 41, 59, 11, 42, 43, 181], 711);
                step(f, Op::SubV, &[42, 29, 44], 712);
                step(f, Op::ArrayAt(Elem::Vec3), &[2, 7, 45], 713);
                step(f, Op::DistanceV, &[44, 45, 186], 714);
                step(f, Op::MaxF, &[197, 186, 193], 715);
                step(f, Op::LessEqualF, &[193, 62, 19], 716);
                step(f, Op::And, &[12, 18, 20], 717);
                step(f, Op::And, &[20, 15, 12], 718);
                step(f, Op::And, &[19, 12, 20], 719);
                step(f, Op::JumpIfFalse, &[20, 721], 720)
            }
            720 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 14], 721);
                721
            }
            721 => {
                step(f, Op::JumpIfFalse, &[14, 755], 722)
            }
            722 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 7], 723);
                step(f, Op::BreakTransform, &[7, 45, 6, 46], 724);
                step(f, Op::AddV, &[29, 20, 47], 725);
                step(f, Op::Copy(ValueType::Float), &[52, 204], 726);
                step(f, Op::Copy(ValueType::Float), &[54, 205], 727);
                step(f, Op::SubV, &[47, 19, 20], 728);
                step(f, Op::DeltaTime, &[189], 729);
                step(f, Op::DivF, &[205, 189, 199], 730);
                step(f, Op::ScaleV, &[20, 199, 48], 731);
                step(f, Op::AddV, &[47, 48, 49], 732);
                step(f, Op::AddV, &[19, 48, 50], 733);
                step(f, Op::SubV, &[45, 50, 48], 734);
                step(f, Op::FloatLerp, &[152, 154, 204, 190], 735);
                step(f, Op::SubF, &[154, 190, 202], 736);
                step(f, Op::ScaleV, &[48, 202, 50], 737);
                step(f, Op::AddV, &[49, 50, 48], 738);
                step(f, Op::MulF, &[204, 189, 186], 739);
                step(f, Op::GreaterF, &[186, 152, 12], 740);
                step(f, Op::DivF, &[190, 186, 197], 741);
                step(f, Op::Select(ValueType::Float), &[12, 197, 154, 193], 742);
                step(f, Op::ScaleV, &[20, 193, 49], 743);
                step(f, Op::SubV, &[48, 49, 50], 744);
                step(f, Op::Copy(ValueType::Vec3), &[50, 20], 745);
                step(f, Op::BreakVector, &[20, 205, 199, 202], 746);
                step(f, Op::ClampF, &[202, 65, 66, 189], 747);
                step(f, Op::MakeVector, &[205, 199, 189, 48], 748);
                step(f, Op::MakeTransform, &[48, 6, 5, 8], 749);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 7, 8], 750);
                step(f, Op::MakeTransform, &[47, 1, 5, 8], 751);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 7, 8], 752);
                step(f, Op::JumpIfFalse, &[15, 754], 753)
            }
            753 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 7], 754);
                754
            }
            754 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 13], 755);
                755
            }
            755 => {
                step(f, Op::JumpIfFalse, &[13, 960], 756)
            }
            756 => {
                step(f, Op::GetTransform, &[34, 2, 9, 6], 757);
                step(f, Op::BreakTransform, &[6, 21, 3, 16], 758);
                step(f, Op::BreakVector, &[21, 198, 187, 176], 759);
                step(f, Op::SubF, &[154, 15, 188], 760);
                step(f, Op::MulF, &[14, 188, 194], 761);
                step(f, Op::QuatFromAxisAngle, &[8, 194, 4], 762);
                step(f, Op::GetTransform, &[0, 2, 9, 4], 763);
                step(f, Op::BreakTransform, &[4, 22, 5, 23], 764);
                step(f, Op::SubV, &[22, 21, 24], 765);
                step(f, Op::BreakVector, &[24, 196, 201, 208], 766);
                step(f, Op::MakeVector, &[196, 201, 152, 25], 767);
                step(f, Op::RotateVector, &[4, 25, 26], 768);
                step(f, Op::BreakVector, &[26, 184, 203, 185], 769);
                step(f, Op::MulF, &[49, 15, 209], 770);
                step(f, Op::Equals(Elem::Int), &[7, 2, 16], 771);
                step(f, Op::Select(ValueType::Float), &[16, 154, 156, 182], 772);
                step(f, Op::MulF, &[209, 182, 207], 773);
                step(f, Op::AddF, &[184, 207, 178], 774);
                step(f, Op::AddF, &[198, 178, 180], 775);
                step(f, Op::AddF, &[187, 203, 183], 776);
                step(f, Op::BreakVector, &[22, 191, 206, 179], 777);
                step(f, Op::SubF, &[179, 55, 200], 778);
                step(f, Op::MakeVector, &[180, 183, 200, 27], 779);
                step(f, Op::SubF, &[154, 177, 204], 780);
                step(f, Op::MaxF, &[204, 152, 186], 781);
                step(f, Op::MulF, &[10, 7, 190], 782);
                step(f, Op::MulF, &[186, 190, 197], 783);
                step(f, Op::ScaleV, &[2, 197, 49], 784);
                step(f, Op::AddV, &[27, 49, 50], 785);
                step(f, Op::MulF, &[6, 153, 192], 786);
                step(f, Op::ScaleV, &[2, 192, 28], 787);
                step(f, Op::AddV, &[50, 28, 20], 788);
                step(f, Op::RotateVector, &[0, 9, 32], 789);
                step(f, Op::Copy(ValueType::Float), &[159, 193], 790);
                step(f, Op::Copy(ValueType::Vec3), &[6, 48], 791);
                step(f, Op::Copy(ValueType::Vec3), &[8, 47], 792);
                step(f, Op::Copy(ValueType::Bool), &[10, 19], 793);
                step(f, Op::Copy(ValueType::Float), &[159, 202], 794);
                step(f, Op::Copy(ValueType::Vec3), &[6, 50], 795);
                step(f, Op::MulI, &[0, 0, 8], 796);
                step(f, Op::Copy(ValueType::Int), &[8, 9], 797);
                step(f, Op::Copy(ValueType::Int), &[2, 6], 798);
                step(f, Op::SubI, &[0, 3, 8], 799);
                step(f, Op::DivI, &[8, 4, 11], 800);
                step(f, Op::MakeVector, &[152, 152, 60, 51], 801);
                step(f, Op::ScaleV, &[32, 64, 52], 802);
                802
            }
            802 => {
                step(f, Op::ForNext, &[6, 9, 8, 849], 803)
            }
            803 => {
                step(f, Op::ModI, &[8, 0, 12], 804);
                step(f, Op::ToFloat, &[12, 189], 805);
                step(f, Op::MulF, &[189, 61, 199], 806);
                step(f, Op::MulF, &[199, 182, 205], 807);
                step(f, Op::MakeVector, &[205, 152, 152, 53], 808);
                step(f, Op::DivI, &[8, 0, 12], 809);
                step(f, Op::SubI, &[12, 11, 8], 810);
                step(f, Op::ToFloat, &[8, 189], 811);
                step(f, Op::MulF, &[189, 61, 199], 812);
                step(f, Op::ScaleV, &[32, 199, 54], 813);
                step(f, Op::AddV, &[53, 54, 55], 814);
                step(f, Op::AddV, &[20, 55, 53], 815);
                step(f, Op::AddV, &[53, 51, 54], 816);
                step(f, Op::SubV, &[53, 51, 56], 817);
                step(f, Op::SphereTrace, &[54, 56, 59, 20, 53, 57, 205], 818);
                step(f, Op::BreakVector, &[53, 189, 199, 205], 819);
                step(f, Op::AddV, &[54, 52, 58], 820);
                step(f, Op::AddV, &[56, 52, 54], 821);
                step(f, Op::SphereTrace, &[58, 54, 59, 14, 56, 59, 189], 822);
                step(f, Op::BreakVector, &[56, 199, 189, 210], 823);
                step(f, Op::SubF, &[205, 210, 189], 824);
                step(f, Op::AbsF, &[189, 199], 825);
                step(f, Op::Select(ValueType::Float), &[20, 152, 154, 189], 826);
                step(f, Op::AddF, &[199, 189, 211], 827);
                step(f, Op::LengthV, &[55, 189], 828);
                step(f, Op::RemapF, &[189, 152, 165, 152, 154, 9, 199], 829);
                step(f, Op::MinF, &[205, 210, 189], 830);
                step(f, Op::RemapF, &[189, 166, 165, 154, 153, 9, 205], 831);
                step(f, Op::AddF, &[199, 205, 210], 832);
                step(f, Op::AddF, &[211, 210, 189], 833);
                step(f, Op::LessF, &[189, 193, 12], 834);
                step(f, Op::And, &[20, 12, 15], 835);
                step(f, Op::JumpIfFalse, &[15, 843], 836)
            }
            836 => {
                step(f, Op::Copy(ValueType::Float), &[193, 202], 837);
                step(f, Op::Copy(ValueType::Vec3), &[48, 50], 838);
                step(f, Op::Copy(ValueType::Float), &[189, 193], 839);
                step(f, Op::Copy(ValueType::Vec3), &[53, 48], 840);
                step(f, Op::Copy(ValueType::Vec3), &[57, 47], 841);
                step(f, Op::Copy(ValueType::Bool), &[9, 19], 842);
                step(f, Op::Jump, &[848], 843)
            }
            843 => {
                step(f, Op::LessF, &[189, 202, 13], 844);
                step(f, Op::And, &[20, 13, 16], 845);
                step(f, Op::JumpIfFalse, &[16, 848], 846)
            }
            846 => {
                step(f, Op::Copy(ValueType::Float), &[189, 202], 847);
                step(f, Op::Copy(ValueType::Vec3), &[53, 50], 848);
                848
            }
            848 => {
                step(f, Op::Jump, &[802], 849)
            }
            849 => {
                step(f, Op::JumpIfFalse, &[8, 851], 850)
            }
            850 => {
                step(f, Op::DrawSphere, &[48, 59, 9], 851);
                851
            }
            851 => {
                step(f, Op::GreaterF, &[63, 152, 14], 852);
                step(f, Op::SubF, &[193, 202, 199], 853);
                step(f, Op::DivF, &[199, 63, 205], 854);
                step(f, Op::PowF, &[167, 205, 210], 855);
                step(f, Op::Select(ValueType::Float), &[14, 210, 152, 211], 856);
                step(f, Op::ScaleV, &[50, 211, 54], 857);
                step(f, Op::AddV, &[48, 54, 58], 858);
                step(f, Op::AddF, &[211, 154, 189], 859);
                step(f, Op::DivF, &[154, 189, 193], 860);
                step(f, Op::ScaleV, &[58, 193, 59], 861);
                step(f, Op::Copy(ValueType::Vec3), &[59, 56], 862);
                step(f, Op::Copy(ValueType::Vec3), &[47, 55], 863);
                step(f, Op::Copy(ValueType::Bool), &[19, 12], 864);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 7], 865);
                step(f, Op::BreakTransform, &[7, 45, 6, 46], 866);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 177], 867);
                step(f, Op::SubF, &[154, 177, 204], 868);
                step(f, Op::MaxF, &[204, 152, 186], 869);
                step(f, Op::MulF, &[10, 7, 190], 870);
                step(f, Op::MulF, &[186, 190, 197], 871);
                step(f, Op::ScaleV, &[2, 197, 49], 872);
                step(f, Op::SubV, &[56, 49, 57], 873);
                step(f, Op::Select(ValueType::Vec3), &[12, 57, 45, 53], 874);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 7, 5], 875);
                step(f, Op::BreakTransform, &[5, 19, 2, 17], 876);
                step(f, Op::Copy(ValueType::Float), &[52, 202], 877);
                step(f, Op::Copy(ValueType::Float), &[54, 199], 878);
                step(f, Op::SubV, &[53, 19, 20], 879);
                step(f, Op::DeltaTime, &[205], 880);
                step(f, Op::DivF, &[199, 205, 210], 881);
                step(f, Op::ScaleV, &[20, 210, 51], 882);
                step(f, Op::AddV, &[53, 51, 52], 883);
                step(f, Op::AddV, &[19, 51, 50], 884);
                step(f, Op::SubV, &[45, 50, 48], 885);
                step(f, Op::FloatLerp, &[152, 154, 202, 211], 886);
                step(f, Op::SubF, &[154, 211, 189], 887);
                step(f, Op::ScaleV, &[48, 189, 54], 888);
                step(f, Op::AddV, &[52, 54, 58], 889);
                step(f, Op::MulF, &[202, 205, 193], 890);
                step(f, Op::GreaterF, &[193, 152, 15], 891);
                step(f, Op::DivF, &[211, 193, 204], 892);
                step(f, Op::Select(ValueType::Float), &[15, 204, 154, 186], 893);
                step(f, Op::ScaleV, &[20, 186, 59], 894);
                step(f, Op::SubV, &[58, 59, 47], 895);
                step(f, Op::Copy(ValueType::Vec3), &[47, 49], 896);
                step(f, Op::BreakVector, &[49, 190, 197, 199], 897);
                step(f, Op::ClampF, &[199, 65, 66, 210], 898);
                step(f, Op::MakeVector, &[190, 197, 210, 56], 899);
                step(f, Op::RotationFromNormal, &[55, 189, 202, 2], 900);
                step(f, Op::PerFootRotationFactor, &[14, 114, 115, 205], 901);
                step(f, Op::MulF, &[14, 205, 193], 902);
                step(f, Op::SubF, &[154, 15, 188], 903);
                step(f, Op::MulF, &[193, 188, 211], 904);
                step(f, Op::QuatFromAxisAngle, &[8, 211, 7], 905);
                step(f, Op::MulQ, &[2, 7, 8], 906);
                step(f, Op::Select(ValueType::Quat), &[12, 8, 6, 2], 907);
                step(f, Op::MakeTransform, &[56, 2, 5, 8], 908);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 7, 8], 909);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 7], 910);
                step(f, Op::BreakTransform, &[7, 45, 6, 46], 911);
                step(f, Op::Select(ValueType::Vec3), &[12, 57, 45, 53], 912);
                step(f, Op::MakeTransform, &[53, 1, 5, 5], 913);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 7, 5], 914);
                step(f, Op::GetTransform, &[34, 2, 9, 6], 915);
                step(f, Op::BreakTransform, &[6, 21, 3, 16], 916);
                step(f, Op::BreakVector, &[21, 198, 187, 176], 917);
                step(f, Op::MulF, &[14, 188, 194], 918);
                step(f, Op::QuatFromAxisAngle, &[8, 194, 4], 919);
                step(f, Op::GetTransform, &[0, 2, 9, 4], 920);
                step(f, Op::BreakTransform, &[4, 22, 5, 23], 921);
                step(f, Op::SubV, &[22, 21, 24], 922);
                step(f, Op::BreakVector, &[24, 196, 201, 208], 923);
                step(f, Op::MakeVector, &[196, 201, 152, 25], 924);
                step(f, Op::RotateVector, &[4, 25, 26], 925);
                step(f, Op::BreakVector, &[26, 184, 203, 185], 926);
                step(f, Op::MulF, &[49, 15, 209], 927);
                step(f, Op::MulF, &[209, 182, 207], 928);
                step(f, Op::AddF, &[184, 207, 178], 929);
                step(f, Op::AddF, &[198, 178, 180], 930);
                step(f, Op::AddF, &[187, 203, 183], 931);
                step(f, Op::BreakVector, &[22, 191, 206, 179], 932);
                step(f, Op::SubF, &[179, 55, 200], 933);
                step(f, Op::MakeVector, &[180, 183, 200, 27], 934);
                step(f, Op::MulF, &[6, 153, 192], 935);
                step(f, Op::ScaleV, &[2, 192, 28], 936);
                step(f, Op::AddV, &[27, 28, 29], 937);
                step(f, Op::SubV, &[53, 29, 17], 938);
                step(f, Op::ArraySetAt(Elem::Vec3), &[0, 7, 17], 939);
                step(f, Op::ArraySetAt(Elem::Bool), &[1, 7, 12], 940);
                step(f, Op::GreaterEqualF, &[177, 154, 17], 941);
                step(f, Op::JumpIfFalse, &[17, 958], 942)
            }
            942 => {
                step(f, Op::MakeVector, &[152, 152, 60, 18], 943);
                step(f, Op::AddV, &[29, 18, 30], 944);
                step(f, Op::RotateVector, &[0, 9, 32], 945);
                step(f, Op::ScaleV, &[32, 64, 33], 946);
                step(f, Op::AddV, &[30, 33, 34], 947);
                step(f, Op::SubV, &[29, 18, 31], 948);
                step(f, Op::AddV, &[31, 33, 35], 949);
                step(f, Op::SphereTrace, &[34, 35, 59, 18, 36, 37, 195], 950);
                step(f, Op::SubV, &[36, 29, 38], 951);
                step(f, Op::ArraySetAt(Elem::Vec3), &[1, 7, 38], 952);
                step(f, Op::ScaleV, &[32, 61, 39], 953);
                step(f, Op::AddV, &[34, 39, 40], 954);
                step(f, Op::AddV, &[35, 39, 41], 955);
                step(f, Op::SphereTrace, &[40, 41, 59, 11, 42, 43, 181], 956);
                step(f, Op::SubV, &[42, 29, 44], 957);
                step(f, Op::ArraySetAt(Elem::Vec3), &[2, 7, 44], 958);
                958
            }
            958 => {
                step(f, Op::JumpIfFalse, &[12, 960], 959)
            }
            959 => {
                step(f, Op::Copy(ValueType::Bool), &[9, 7], 960);
                960
            }
            960 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 7, 8], 961);
                step(f, Op::GreaterF, &[23, 152, 13], 962);
                step(f, Op::InterpolateTransform, &[2, 3, 24, 7], 963);
                step(f, Op::Select(ValueType::Transform), &[13, 7, 2, 5], 964);
                step(f, Op::MakeAbsolute, &[8, 5, 6], 965);
                step(f, Op::BreakTransform, &[6, 19, 7, 51], 966);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 7, 4], 967);
                step(f, Op::BreakTransform, &[4, 50, 8, 48], 968);
                step(f, Op::AddF, &[69, 70, 204], 969);
                step(f, Op::ClampSpatially, &[19, 50, 152, 204, 52], 970);
                step(f, Op::SubF, &[154, 15, 186], 971);
                step(f, Op::MulF, &[14, 186, 199], 972);
                step(f, Op::LimitRotationAroundZ, &[7, 199, 104, 2], 973);
                step(f, Op::MakeTransform, &[52, 2, 5, 4], 974);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 7, 4], 975);
                step(f, Op::ArrayAt(Elem::Float), &[4, 7, 190], 976);
                step(f, Op::FloatLerp, &[190, 152, 107, 197], 977);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 7, 20], 978);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 210], 979);
                step(f, Op::GreaterEqualF, &[210, 154, 16], 980);
                step(f, Op::And, &[20, 16, 14], 981);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 7, 8], 982);
                step(f, Op::MakeAbsolute, &[8, 5, 6], 983);
                step(f, Op::BreakTransform, &[6, 19, 7, 51], 984);
                step(f, Op::RotateVector, &[7, 9, 54], 985);
                step(f, Op::LimitRotationAroundZ, &[7, 199, 104, 2], 986);
                step(f, Op::RotateVector, &[2, 9, 20], 987);
                step(f, Op::CrossV, &[54, 20, 58], 988);
                step(f, Op::BreakVector, &[58, 189, 202, 205], 989);
                step(f, Op::DotV, &[54, 20, 193], 990);
                step(f, Op::Atan2F, &[205, 193, 211], 991);
                step(f, Op::AbsF, &[211, 176], 992);
                step(f, Op::Select(ValueType::Float), &[14, 176, 152, 188], 993);
                step(f, Op::AddF, &[197, 188, 194], 994);
                step(f, Op::ArraySetAt(Elem::Float), &[4, 7, 194], 995);
                step(f, Op::JumpIfFalse, &[20, 1072], 996)
            }
            996 => {
                step(f, Op::JumpIfFalse, &[16, 998], 997)
            }
            997 => {
                step(f, Op::Jump, &[1071], 998)
            }
            998 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 4], 999);
                step(f, Op::BreakTransform, &[4, 59, 6, 47], 1000);
                step(f, Op::SubF, &[154, 210, 208], 1001);
                step(f, Op::MulF, &[10, 7, 196], 1002);
                step(f, Op::MulF, &[208, 196, 201], 1003);
                step(f, Op::ScaleV, &[2, 201, 49], 1004);
                step(f, Op::AddV, &[59, 49, 55], 1005);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1006);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 12], 1007);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 15], 1008);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 12, 8], 1009);
                step(f, Op::BreakTransform, &[8, 56, 3, 46], 1010);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 12, 6], 1011);
                step(f, Op::BreakTransform, &[6, 45, 5, 57], 1012);
                step(f, Op::LessEqualF, &[90, 152, 17], 1013);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 185], 1014);
                step(f, Op::SmoothStepF, &[185, 152, 90, 182], 1015);
                step(f, Op::Select(ValueType::Float), &[17, 154, 182, 209], 1016);
                step(f, Op::LerpV, &[56, 45, 209, 16], 1017);
                step(f, Op::MakeTransform, &[16, 1, 5, 9], 1018);
                step(f, Op::Select(ValueType::Transform), &[15, 8, 9, 10], 1019);
                step(f, Op::MakeAbsolute, &[10, 5, 11], 1020);
                step(f, Op::Select(ValueType::Transform), &[19, 11, 10, 12], 1021);
                step(f, Op::BreakTransform, &[12, 23, 4, 21], 1022);
                step(f, Op::SubF, &[154, 16, 184], 1023);
                step(f, Op::MulF, &[186, 184, 207], 1024);
                step(f, Op::MulF, &[14, 207, 178], 1025);
                step(f, Op::FootAvoidance, &[55, 23, 178, 19, 86, 24], 1026);
                step(f, Op::RemapF, &[15, 89, 154, 152, 154, 9, 198], 1027);
                step(f, Op::LerpV, &[55, 24, 198, 25], 1028);
                step(f, Op::FootAvoidance, &[25, 23, 17, 19, 112, 26], 1029);
                step(f, Op::LerpV, &[25, 26, 16, 22], 1030);
                step(f, Op::MakeTransform, &[22, 6, 5, 13], 1031);
                step(f, Op::BreakTransform, &[13, 27, 8, 28], 1032);
                step(f, Op::MakeVector, &[152, 152, 60, 53], 1033);
                step(f, Op::AddV, &[27, 53, 17], 1034);
                step(f, Op::SubV, &[27, 53, 30], 1035);
                step(f, Op::LineTrace, &[17, 30, 18, 18, 31, 187], 1036);
                step(f, Op::RotateVector, &[8, 8, 33], 1037);
                step(f, Op::FindQuatBetween, &[33, 31, 7], 1038);
                step(f, Op::MulQ, &[7, 8, 2], 1039);
                step(f, Op::MulF, &[58, 57, 203], 1040);
                step(f, Op::AddF, &[203, 68, 191], 1041);
                step(f, Op::NegF, &[191, 206], 1042);
                step(f, Op::MakeVector, &[152, 206, 152, 37], 1043);
                step(f, Op::RotateVector, &[2, 37, 36], 1044);
                step(f, Op::AddV, &[18, 36, 38], 1045);
                step(f, Op::AddV, &[38, 53, 32], 1046);
                step(f, Op::SubV, &[38, 53, 34], 1047);
                step(f, Op::LineTrace, &[32, 34, 11, 35, 39, 179], 1048);
                step(f, Op::BreakVector, &[35, 180, 183, 200], 1049);
                step(f, Op::BreakVector, &[38, 192, 177, 195], 1050);
                step(f, Op::SubF, &[200, 195, 181], 1051);
                step(f, Op::Select(ValueType::Float), &[11, 181, 152, 204], 1052);
                step(f, Op::AddF, &[64, 68, 190], 1053);
                step(f, Op::MakeVector, &[152, 190, 152, 40], 1054);
                step(f, Op::RotateVector, &[2, 40, 41], 1055);
                step(f, Op::AddV, &[18, 41, 43], 1056);
                step(f, Op::AddV, &[43, 53, 29], 1057);
                step(f, Op::SubV, &[43, 53, 42], 1058);
                step(f, Op::LineTrace, &[29, 42, 12, 44, 48, 199], 1059);
                step(f, Op::BreakVector, &[44, 189, 202, 193], 1060);
                step(f, Op::BreakVector, &[43, 205, 211, 176], 1061);
                step(f, Op::SubF, &[193, 176, 188], 1062);
                step(f, Op::Select(ValueType::Float), &[12, 188, 152, 197], 1063);
                step(f, Op::MaxF, &[204, 197, 194], 1064);
                step(f, Op::ClampF, &[194, 152, 67, 187], 1065);
                step(f, Op::MakeVector, &[152, 152, 187, 52], 1066);
                step(f, Op::AddV, &[18, 52, 19], 1067);
                step(f, Op::MakeTransform, &[19, 2, 5, 14], 1068);
                step(f, Op::Select(ValueType::Transform), &[18, 14, 13, 15], 1069);
                step(f, Op::Copy(ValueType::Transform), &[15, 13], 1070);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 7, 13], 1071);
                1071
            }
            1071 => {
                step(f, Op::Jump, &[1188], 1072)
            }
            1072 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 7, 14], 1073);
                step(f, Op::MakeAbsolute, &[14, 5, 15], 1074);
                step(f, Op::BreakTransform, &[15, 51, 7, 58], 1075);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 4], 1076);
                step(f, Op::BreakTransform, &[4, 59, 6, 47], 1077);
                step(f, Op::SubF, &[154, 210, 208], 1078);
                step(f, Op::MulF, &[10, 7, 196], 1079);
                step(f, Op::MulF, &[208, 196, 201], 1080);
                step(f, Op::ScaleV, &[2, 201, 49], 1081);
                step(f, Op::AddV, &[59, 49, 55], 1082);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1083);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 12], 1084);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 15], 1085);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 12, 8], 1086);
                step(f, Op::BreakTransform, &[8, 56, 3, 46], 1087);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 12, 6], 1088);
                step(f, Op::BreakTransform, &[6, 45, 5, 57], 1089);
                step(f, Op::LessEqualF, &[90, 152, 17], 1090);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 185], 1091);
                step(f, Op::SmoothStepF, &[185, 152, 90, 182], 1092);
                step(f, Op::Select(ValueType::Float), &[17, 154, 182, 209], 1093);
                step(f, Op::LerpV, &[56, 45, 209, 16], 1094);
                step(f, Op::MakeTransform, &[16, 1, 5, 9], 1095);
                step(f, Op::Select(ValueType::Transform), &[15, 8, 9, 10], 1096);
                step(f, Op::MakeAbsolute, &[10, 5, 11], 1097);
                step(f, Op::Select(ValueType::Transform), &[19, 11, 10, 12], 1098);
                step(f, Op::BreakTransform, &[12, 23, 4, 21], 1099);
                step(f, Op::SubF, &[154, 16, 184], 1100);
                step(f, Op::MulF, &[186, 184, 207], 1101);
                step(f, Op::MulF, &[14, 207, 178], 1102);
                step(f, Op::FootAvoidance, &[55, 23, 178, 19, 86, 24], 1103);
                step(f, Op::RemapF, &[15, 89, 154, 152, 154, 9, 198], 1104);
                step(f, Op::LerpV, &[55, 24, 198, 25], 1105);
                step(f, Op::FootAvoidance, &[25, 23, 17, 19, 112, 26], 1106);
                step(f, Op::LerpV, &[25, 26, 16, 22], 1107);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 7, 13], 1108);
                step(f, Op::MakeAbsolute, &[13, 5, 14], 1109);
                step(f, Op::BreakTransform, &[14, 20, 8, 54], 1110);
                step(f, Op::ArrayAt(Elem::Float), &[3, 7, 203], 1111);
                step(f, Op::SubF, &[210, 203, 191], 1112);
                step(f, Op::DeltaTime, &[206], 1113);
                step(f, Op::DivF, &[54, 206, 179], 1114);
                step(f, Op::MulF, &[191, 179, 180], 1115);
                step(f, Op::AddF, &[203, 180, 183], 1116);
                step(f, Op::ClampF, &[183, 152, 154, 177], 1117);
                step(f, Op::AddF, &[210, 180, 192], 1118);
                step(f, Op::ClampF, &[192, 152, 154, 195], 1119);
                step(f, Op::AddF, &[177, 195, 200], 1120);
                step(f, Op::MulF, &[200, 153, 181], 1121);
                step(f, Op::SubF, &[154, 181, 190], 1122);
                step(f, Op::GreaterF, &[191, 152, 14], 1123);
                step(f, Op::SubF, &[195, 177, 199], 1124);
                step(f, Op::DivF, &[199, 191, 189], 1125);
                step(f, Op::Select(ValueType::Float), &[14, 189, 154, 202], 1126);
                step(f, Op::MulF, &[190, 202, 205], 1127);
                step(f, Op::MulF, &[85, 205, 211], 1128);
                step(f, Op::Copy(ValueType::Float), &[54, 176], 1129);
                step(f, Op::SubV, &[22, 20, 28], 1130);
                step(f, Op::DeltaTime, &[193], 1131);
                step(f, Op::DivF, &[176, 193, 188], 1132);
                step(f, Op::ScaleV, &[28, 188, 27], 1133);
                step(f, Op::AddV, &[22, 27, 17], 1134);
                step(f, Op::AddV, &[20, 27, 30], 1135);
                step(f, Op::SubV, &[51, 30, 31], 1136);
                step(f, Op::FloatLerp, &[152, 154, 211, 197], 1137);
                step(f, Op::SubF, &[154, 197, 204], 1138);
                step(f, Op::ScaleV, &[31, 204, 33], 1139);
                step(f, Op::AddV, &[17, 33, 37], 1140);
                step(f, Op::MulF, &[211, 193, 194], 1141);
                step(f, Op::GreaterF, &[194, 152, 11], 1142);
                step(f, Op::DivF, &[197, 194, 187], 1143);
                step(f, Op::Select(ValueType::Float), &[11, 187, 154, 206], 1144);
                step(f, Op::ScaleV, &[28, 206, 36], 1145);
                step(f, Op::SubV, &[37, 36, 32], 1146);
                step(f, Op::Copy(ValueType::Vec3), &[32, 34], 1147);
                step(f, Op::MakeTransform, &[34, 6, 5, 15], 1148);
                step(f, Op::BreakTransform, &[15, 39, 2, 35], 1149);
                step(f, Op::MakeVector, &[152, 152, 60, 38], 1150);
                step(f, Op::AddV, &[39, 38, 40], 1151);
                step(f, Op::SubV, &[39, 38, 41], 1152);
                step(f, Op::LineTrace, &[40, 41, 12, 53, 29, 179], 1153);
                step(f, Op::RotateVector, &[2, 8, 42], 1154);
                step(f, Op::FindQuatBetween, &[42, 29, 7], 1155);
                step(f, Op::MulQ, &[7, 2, 8], 1156);
                step(f, Op::MulF, &[58, 57, 203], 1157);
                step(f, Op::AddF, &[203, 68, 183], 1158);
                step(f, Op::NegF, &[183, 180], 1159);
                step(f, Op::MakeVector, &[152, 180, 152, 48], 1160);
                step(f, Op::RotateVector, &[8, 48, 44], 1161);
                step(f, Op::AddV, &[53, 44, 43], 1162);
                step(f, Op::AddV, &[43, 38, 18], 1163);
                step(f, Op::SubV, &[43, 38, 52], 1164);
                step(f, Op::LineTrace, &[18, 52, 18, 19, 58, 192], 1165);
                step(f, Op::BreakVector, &[19, 200, 181, 177], 1166);
                step(f, Op::BreakVector, &[43, 195, 191, 199], 1167);
                step(f, Op::SubF, &[177, 199, 189], 1168);
                step(f, Op::Select(ValueType::Float), &[18, 189, 152, 190], 1169);
                step(f, Op::AddF, &[64, 68, 202], 1170);
                step(f, Op::MakeVector, &[152, 202, 152, 54], 1171);
                step(f, Op::RotateVector, &[8, 54, 20], 1172);
                step(f, Op::AddV, &[53, 20, 27], 1173);
                step(f, Op::AddV, &[27, 38, 30], 1174);
                step(f, Op::SubV, &[27, 38, 51], 1175);
                step(f, Op::LineTrace, &[30, 51, 14, 31, 17, 205], 1176);
                step(f, Op::BreakVector, &[31, 176, 188, 204], 1177);
                step(f, Op::BreakVector, &[27, 193, 211, 194], 1178);
                step(f, Op::SubF, &[204, 194, 197], 1179);
                step(f, Op::Select(ValueType::Float), &[14, 197, 152, 187], 1180);
                step(f, Op::MaxF, &[190, 187, 206], 1181);
                step(f, Op::ClampF, &[206, 152, 67, 179], 1182);
                step(f, Op::MakeVector, &[152, 152, 179, 33], 1183);
                step(f, Op::AddV, &[53, 33, 28], 1184);
                step(f, Op::MakeTransform, &[28, 8, 5, 13], 1185);
                step(f, Op::Select(ValueType::Transform), &[12, 13, 15, 14], 1186);
                step(f, Op::Copy(ValueType::Transform), &[14, 13], 1187);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 7, 13], 1188);
                1188
            }
            1188 => {
                step(f, Op::JumpIfFalse, &[16, 1271], 1189)
            }
            1189 => {
                step(f, Op::JumpIfFalse, &[20, 1191], 1190)
            }
            1190 => {
                step(f, Op::Jump, &[1252], 1191)
            }
            1191 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 7, 15], 1192);
                step(f, Op::BreakTransform, &[15, 36, 2, 37], 1193);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1194);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 12], 1195);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 12, 14], 1196);
                step(f, Op::BreakTransform, &[14, 32, 7, 34], 1197);
                step(f, Op::MakeAbsolute, &[14, 5, 13], 1198);
                step(f, Op::BreakTransform, &[13, 35, 8, 39], 1199);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 185], 1200);
                step(f, Op::SmoothStepF, &[185, 152, 154, 203], 1201);
                step(f, Op::RemapF, &[15, 152, 89, 152, 154, 9, 183], 1202);
                step(f, Op::MulF, &[203, 183, 180], 1203);
                step(f, Op::Select(ValueType::Float), &[19, 180, 152, 192], 1204);
                step(f, Op::LerpV, &[32, 35, 192, 40], 1205);
                step(f, Op::MakeTransform, &[40, 1, 5, 16], 1206);
                step(f, Op::BreakTransform, &[16, 41, 9, 29], 1207);
                step(f, Op::SubF, &[154, 16, 184], 1208);
                step(f, Op::MulF, &[186, 184, 207], 1209);
                step(f, Op::MulF, &[14, 207, 178], 1210);
                step(f, Op::FootAvoidance, &[36, 41, 178, 19, 86, 42], 1211);
                step(f, Op::MakeTransform, &[42, 2, 5, 17], 1212);
                step(f, Op::BreakTransform, &[17, 48, 2, 44], 1213);
                step(f, Op::MakeVector, &[152, 152, 60, 18], 1214);
                step(f, Op::AddV, &[48, 18, 52], 1215);
                step(f, Op::SubV, &[48, 18, 58], 1216);
                step(f, Op::LineTrace, &[52, 58, 11, 19, 43, 181], 1217);
                step(f, Op::RotateVector, &[2, 8, 54], 1218);
                step(f, Op::FindQuatBetween, &[54, 43, 10], 1219);
                step(f, Op::MulQ, &[10, 2, 11], 1220);
                step(f, Op::MulF, &[58, 57, 200], 1221);
                step(f, Op::AddF, &[200, 68, 191], 1222);
                step(f, Op::NegF, &[191, 195], 1223);
                step(f, Op::MakeVector, &[152, 195, 152, 20], 1224);
                step(f, Op::RotateVector, &[11, 20, 38], 1225);
                step(f, Op::AddV, &[19, 38, 17], 1226);
                step(f, Op::AddV, &[17, 18, 30], 1227);
                step(f, Op::SubV, &[17, 18, 51], 1228);
                step(f, Op::LineTrace, &[30, 51, 18, 31, 27, 177], 1229);
                step(f, Op::BreakVector, &[31, 199, 189, 202], 1230);
                step(f, Op::BreakVector, &[17, 205, 176, 188], 1231);
                step(f, Op::SubF, &[202, 188, 193], 1232);
                step(f, Op::Select(ValueType::Float), &[18, 193, 152, 211], 1233);
                step(f, Op::AddF, &[64, 68, 194], 1234);
                step(f, Op::MakeVector, &[152, 194, 152, 33], 1235);
                step(f, Op::RotateVector, &[11, 33, 53], 1236);
                step(f, Op::AddV, &[19, 53, 28], 1237);
                step(f, Op::AddV, &[28, 18, 37], 1238);
                step(f, Op::SubV, &[28, 18, 36], 1239);
                step(f, Op::LineTrace, &[37, 36, 14, 42, 44, 204], 1240);
                step(f, Op::BreakVector, &[42, 197, 187, 190], 1241);
                step(f, Op::BreakVector, &[28, 206, 179, 181], 1242);
                step(f, Op::SubF, &[190, 181, 200], 1243);
                step(f, Op::Select(ValueType::Float), &[14, 200, 152, 191], 1244);
                step(f, Op::MaxF, &[211, 191, 195], 1245);
                step(f, Op::ClampF, &[195, 152, 67, 177], 1246);
                step(f, Op::MakeVector, &[152, 152, 177, 48], 1247);
                step(f, Op::AddV, &[19, 48, 52], 1248);
                step(f, Op::MakeTransform, &[52, 11, 5, 18], 1249);
                step(f, Op::Select(ValueType::Transform), &[11, 18, 17, 19], 1250);
                step(f, Op::Copy(ValueType::Transform), &[19, 17], 1251);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 7, 17], 1252);
                1252
            }
            1252 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 7, 18], 1253);
                step(f, Op::BreakTransform, &[18, 58, 2, 43], 1254);
                step(f, Op::SubV, &[58, 50, 54], 1255);
                step(f, Op::LengthV, &[54, 189], 1256);
                step(f, Op::SubF, &[69, 70, 199], 1257);
                step(f, Op::SubF, &[189, 199, 176], 1258);
                step(f, Op::MulF, &[70, 157, 205], 1259);
                step(f, Op::ClampF, &[176, 152, 205, 188], 1260);
                step(f, Op::MulF, &[188, 188, 202], 1261);
                step(f, Op::MulF, &[70, 168, 193], 1262);
                step(f, Op::DivF, &[202, 193, 194], 1263);
                step(f, Op::SubF, &[189, 194, 204], 1264);
                step(f, Op::DivF, &[204, 189, 187], 1265);
                step(f, Op::ScaleV, &[54, 187, 20], 1266);
                step(f, Op::AddV, &[50, 20, 38], 1267);
                step(f, Op::MakeTransform, &[38, 2, 5, 19], 1268);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 19], 1269);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 19], 1270);
                step(f, Op::Jump, &[1437], 1271)
            }
            1271 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 7, 18], 1272);
                step(f, Op::BreakTransform, &[18, 58, 2, 43], 1273);
                step(f, Op::SubV, &[58, 50, 54], 1274);
                step(f, Op::LengthV, &[54, 189], 1275);
                step(f, Op::SubF, &[69, 70, 199], 1276);
                step(f, Op::SubF, &[189, 199, 176], 1277);
                step(f, Op::MulF, &[70, 157, 205], 1278);
                step(f, Op::ClampF, &[176, 152, 205, 188], 1279);
                step(f, Op::MulF, &[188, 188, 202], 1280);
                step(f, Op::MulF, &[70, 168, 193], 1281);
                step(f, Op::DivF, &[202, 193, 194], 1282);
                step(f, Op::SubF, &[189, 194, 204], 1283);
                step(f, Op::DivF, &[204, 189, 187], 1284);
                step(f, Op::ScaleV, &[54, 187, 20], 1285);
                step(f, Op::AddV, &[50, 20, 38], 1286);
                step(f, Op::MakeTransform, &[38, 2, 5, 19], 1287);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 7, 15], 1288);
                step(f, Op::ClampF, &[210, 152, 154, 197], 1289);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[6, 5], 1290);
                step(f, Op::ArrayReset(Elem::Vec3), &[5], 1291);
                step(f, Op::BreakTransform, &[19, 27, 10, 30], 1292);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 27], 1293);
                step(f, Op::UnitV, &[2, 51], 1294);
                step(f, Op::LengthV, &[2, 179], 1295);
                step(f, Op::RemapF, &[179, 152, 71, 152, 72, 9, 206], 1296);
                step(f, Op::ScaleV, &[51, 206, 31], 1297);
                step(f, Op::SubV, &[27, 31, 17], 1298);
                step(f, Op::MakeVector, &[152, 152, 74, 33], 1299);
                step(f, Op::AddV, &[17, 33, 53], 1300);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 53], 1301);
                step(f, Op::RemapF, &[179, 152, 71, 152, 76, 9, 181], 1302);
                step(f, Op::MakeVector, &[152, 152, 181, 18], 1303);
                step(f, Op::AddV, &[53, 18, 36], 1304);
                step(f, Op::BreakTransform, &[15, 37, 11, 44], 1305);
                step(f, Op::BreakVector, &[37, 190, 200, 191], 1306);
                step(f, Op::BreakVector, &[27, 211, 195, 177], 1307);
                step(f, Op::SubF, &[191, 177, 199], 1308);
                step(f, Op::MaxF, &[199, 152, 176], 1309);
                step(f, Op::MulF, &[176, 78, 205], 1310);
                step(f, Op::MinF, &[205, 79, 188], 1311);
                step(f, Op::AbsF, &[199, 193], 1312);
                step(f, Op::RemapF, &[193, 152, 82, 152, 81, 9, 202], 1313);
                step(f, Op::AddF, &[188, 202, 194], 1314);
                step(f, Op::MakeVector, &[152, 152, 194, 42], 1315);
                step(f, Op::AddV, &[36, 42, 28], 1316);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 28], 1317);
                step(f, Op::RemapF, &[179, 152, 71, 152, 73, 9, 189], 1318);
                step(f, Op::ScaleV, &[51, 189, 19], 1319);
                step(f, Op::AddV, &[37, 19, 48], 1320);
                step(f, Op::MakeVector, &[152, 152, 75, 52], 1321);
                step(f, Op::AddV, &[48, 52, 43], 1322);
                step(f, Op::RemapF, &[179, 152, 71, 152, 77, 9, 204], 1323);
                step(f, Op::MakeVector, &[152, 152, 204, 58], 1324);
                step(f, Op::AddV, &[43, 58, 54], 1325);
                step(f, Op::NegF, &[199, 187], 1326);
                step(f, Op::MaxF, &[187, 152, 206], 1327);
                step(f, Op::MulF, &[206, 80, 181], 1328);
                step(f, Op::AddF, &[181, 202, 190], 1329);
                step(f, Op::MakeVector, &[152, 152, 190, 20], 1330);
                step(f, Op::AddV, &[54, 20, 50], 1331);
                step(f, Op::LerpV, &[28, 50, 153, 38], 1332);
                step(f, Op::GetTransform, &[35, 2, 9, 17], 1333);
                step(f, Op::BreakTransform, &[17, 30, 2, 31], 1334);
                step(f, Op::BreakVector, &[30, 200, 195, 211], 1335);
                step(f, Op::SubF, &[154, 15, 177], 1336);
                step(f, Op::MulF, &[83, 177, 191], 1337);
                step(f, Op::MulF, &[14, 191, 176], 1338);
                step(f, Op::QuatFromAxisAngle, &[8, 176, 2], 1339);
                step(f, Op::SubV, &[38, 30, 17], 1340);
                step(f, Op::BreakVector, &[17, 205, 193, 188], 1341);
                step(f, Op::MakeVector, &[205, 193, 152, 33], 1342);
                step(f, Op::RotateVector, &[2, 33, 18], 1343);
                step(f, Op::BreakVector, &[18, 194, 189, 179], 1344);
                step(f, Op::AddF, &[200, 194, 204], 1345);
                step(f, Op::AddF, &[195, 189, 199], 1346);
                step(f, Op::BreakVector, &[38, 187, 206, 181], 1347);
                step(f, Op::MakeVector, &[204, 199, 181, 53], 1348);
                step(f, Op::DistanceV, &[27, 37, 202], 1349);
                step(f, Op::RemapF, &[202, 157, 169, 152, 154, 9, 190], 1350);
                step(f, Op::LerpV, &[38, 53, 190, 44], 1351);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 44], 1352);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 50], 1353);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 43], 1354);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 37], 1355);
                step(f, Op::JumpIfFalse, &[8, 1357], 1356)
            }
            1356 => {
                step(f, Op::DrawSpline, &[5, 2, 5, 153, 11], 1357);
                1357
            }
            1357 => {
                step(f, Op::Spline, &[5, 197, 2, 36, 42], 1358);
                step(f, Op::SlerpQ, &[10, 11, 197, 2], 1359);
                step(f, Op::MulF, &[197, 162, 211], 1360);
                step(f, Op::SinF, &[211, 177], 1361);
                step(f, Op::SmoothStepF, &[197, 152, 97, 191], 1362);
                step(f, Op::MulF, &[177, 191, 176], 1363);
                step(f, Op::MulF, &[176, 84, 188], 1364);
                step(f, Op::SlerpQ, &[2, 1, 188, 10], 1365);
                step(f, Op::MakeTransform, &[36, 10, 5, 18], 1366);
                step(f, Op::Copy(ValueType::Transform), &[18, 19], 1367);
                step(f, Op::BreakTransform, &[19, 51, 11, 19], 1368);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1369);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 12], 1370);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 12, 14], 1371);
                step(f, Op::BreakTransform, &[14, 32, 7, 34], 1372);
                step(f, Op::GreaterF, &[23, 152, 13], 1373);
                step(f, Op::InterpolateTransform, &[2, 3, 24, 7], 1374);
                step(f, Op::Select(ValueType::Transform), &[13, 7, 2, 5], 1375);
                step(f, Op::MakeAbsolute, &[14, 5, 13], 1376);
                step(f, Op::BreakTransform, &[13, 35, 8, 39], 1377);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 185], 1378);
                step(f, Op::SmoothStepF, &[185, 152, 154, 203], 1379);
                step(f, Op::RemapF, &[15, 152, 89, 152, 154, 9, 183], 1380);
                step(f, Op::MulF, &[203, 183, 180], 1381);
                step(f, Op::Select(ValueType::Float), &[19, 180, 152, 192], 1382);
                step(f, Op::LerpV, &[32, 35, 192, 40], 1383);
                step(f, Op::MakeTransform, &[40, 1, 5, 16], 1384);
                step(f, Op::BreakTransform, &[16, 41, 9, 29], 1385);
                step(f, Op::SubF, &[154, 15, 186], 1386);
                step(f, Op::SubF, &[154, 16, 184], 1387);
                step(f, Op::MulF, &[186, 184, 207], 1388);
                step(f, Op::MulF, &[14, 207, 178], 1389);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 12], 1390);
                step(f, Op::Select(ValueType::Float), &[12, 87, 152, 193], 1391);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 210], 1392);
                step(f, Op::ClampF, &[210, 152, 154, 197], 1393);
                step(f, Op::MulF, &[197, 162, 205], 1394);
                step(f, Op::SinF, &[205, 179], 1395);
                step(f, Op::MulF, &[179, 179, 194], 1396);
                step(f, Op::MulF, &[193, 194, 200], 1397);
                step(f, Op::AddF, &[86, 200, 189], 1398);
                step(f, Op::FootAvoidance, &[51, 41, 178, 19, 189, 48], 1399);
                step(f, Op::SubV, &[48, 51, 52], 1400);
                step(f, Op::LengthV, &[52, 195], 1401);
                step(f, Op::AddF, &[195, 200, 187], 1402);
                step(f, Op::DivF, &[195, 187, 206], 1403);
                step(f, Op::MulF, &[111, 157, 181], 1404);
                step(f, Op::LessEqualF, &[195, 181, 20], 1405);
                step(f, Op::MulF, &[111, 168, 199], 1406);
                step(f, Op::DivF, &[195, 199, 204], 1407);
                step(f, Op::DivF, &[111, 195, 202], 1408);
                step(f, Op::SubF, &[154, 202, 190], 1409);
                step(f, Op::Select(ValueType::Float), &[20, 204, 190, 211], 1410);
                step(f, Op::GreaterF, &[111, 152, 18], 1411);
                step(f, Op::Select(ValueType::Float), &[18, 16, 152, 177], 1412);
                step(f, Op::LerpF, &[206, 211, 177, 191], 1413);
                step(f, Op::LessF, &[185, 210, 14], 1414);
                step(f, Op::LessEqualF, &[88, 152, 11], 1415);
                step(f, Op::SmoothStepF, &[185, 152, 88, 176], 1416);
                step(f, Op::MulF, &[176, 15, 188], 1417);
                step(f, Op::SubF, &[154, 188, 183], 1418);
                step(f, Op::Select(ValueType::Float), &[11, 154, 183, 203], 1419);
                step(f, Op::Select(ValueType::Float), &[14, 203, 154, 180], 1420);
                step(f, Op::MulF, &[191, 180, 192], 1421);
                step(f, Op::SmoothStepF, &[197, 152, 88, 205], 1422);
                step(f, Op::Select(ValueType::Float), &[11, 154, 205, 179], 1423);
                step(f, Op::MulF, &[192, 179, 193], 1424);
                step(f, Op::ScaleV, &[52, 193, 58], 1425);
                step(f, Op::AddV, &[51, 58, 20], 1426);
                step(f, Op::MulF, &[3, 143, 189], 1427);
                step(f, Op::MulF, &[189, 194, 200], 1428);
                step(f, Op::MakeVector, &[152, 152, 200, 54], 1429);
                step(f, Op::AddV, &[20, 54, 28], 1430);
                step(f, Op::MakeTransform, &[28, 11, 5, 15], 1431);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 15], 1432);
                step(f, Op::ScaleV, &[52, 192, 31], 1433);
                step(f, Op::AddV, &[51, 31, 30], 1434);
                step(f, Op::AddV, &[30, 54, 17], 1435);
                step(f, Op::MakeTransform, &[17, 11, 5, 17], 1436);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 17], 1437);
                1437
            }
            1437 => {
                step(f, Op::JumpIfFalse, &[13, 1460], 1438)
            }
            1438 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 7, 18], 1439);
                step(f, Op::BreakTransform, &[18, 33, 2, 18], 1440);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 7, 19], 1441);
                step(f, Op::BreakTransform, &[19, 27, 10, 38], 1442);
                step(f, Op::MulF, &[23, 23, 187], 1443);
                step(f, Op::LerpV, &[33, 27, 187, 53], 1444);
                step(f, Op::SubF, &[154, 23, 181], 1445);
                step(f, Op::MulF, &[23, 181, 199], 1446);
                step(f, Op::MulF, &[145, 157, 195], 1447);
                step(f, Op::MulF, &[199, 195, 202], 1448);
                step(f, Op::MakeVector, &[152, 152, 202, 44], 1449);
                step(f, Op::AddV, &[53, 44, 50], 1450);
                step(f, Op::SlerpQ, &[2, 10, 23, 7], 1451);
                step(f, Op::MakeTransform, &[50, 7, 5, 7], 1452);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 7, 7], 1453);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 7, 18], 1454);
                step(f, Op::BreakTransform, &[18, 33, 2, 18], 1455);
                step(f, Op::LerpV, &[33, 27, 187, 53], 1456);
                step(f, Op::AddV, &[53, 44, 50], 1457);
                step(f, Op::SlerpQ, &[2, 10, 23, 7], 1458);
                step(f, Op::MakeTransform, &[50, 7, 5, 7], 1459);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 7, 7], 1460);
                1460
            }
            1460 => {
                step(f, Op::GreaterEqualF, &[210, 154, 16], 1461);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 7, 16], 1462);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 7, 4], 1463);
                step(f, Op::BreakTransform, &[4, 59, 6, 47], 1464);
                step(f, Op::SubF, &[154, 210, 208], 1465);
                step(f, Op::MulF, &[10, 7, 196], 1466);
                step(f, Op::MulF, &[208, 196, 201], 1467);
                step(f, Op::ScaleV, &[2, 201, 49], 1468);
                step(f, Op::AddV, &[59, 49, 55], 1469);
                step(f, Op::Equals(Elem::Int), &[7, 2, 19], 1470);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 12], 1471);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 12, 15], 1472);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 12, 8], 1473);
                step(f, Op::BreakTransform, &[8, 56, 3, 46], 1474);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 12, 6], 1475);
                step(f, Op::BreakTransform, &[6, 45, 5, 57], 1476);
                step(f, Op::LessEqualF, &[90, 152, 17], 1477);
                step(f, Op::ArrayAt(Elem::Float), &[2, 12, 185], 1478);
                step(f, Op::SmoothStepF, &[185, 152, 90, 182], 1479);
                step(f, Op::Select(ValueType::Float), &[17, 154, 182, 209], 1480);
                step(f, Op::LerpV, &[56, 45, 209, 16], 1481);
                step(f, Op::MakeTransform, &[16, 1, 5, 9], 1482);
                step(f, Op::Select(ValueType::Transform), &[15, 8, 9, 10], 1483);
                step(f, Op::MakeAbsolute, &[10, 5, 11], 1484);
                step(f, Op::Select(ValueType::Transform), &[19, 11, 10, 12], 1485);
                step(f, Op::BreakTransform, &[12, 23, 4, 21], 1486);
                step(f, Op::SubF, &[154, 16, 184], 1487);
                step(f, Op::MulF, &[186, 184, 207], 1488);
                step(f, Op::MulF, &[14, 207, 178], 1489);
                step(f, Op::FootAvoidance, &[55, 23, 178, 19, 86, 24], 1490);
                step(f, Op::RemapF, &[15, 89, 154, 152, 154, 9, 198], 1491);
                step(f, Op::LerpV, &[55, 24, 198, 25], 1492);
                step(f, Op::FootAvoidance, &[25, 23, 17, 19, 112, 26], 1493);
                step(f, Op::LerpV, &[25, 26, 16, 22], 1494);
                step(f, Op::MakeTransform, &[22, 1, 5, 14], 1495);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 7, 14], 1496);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 7, 13], 1497);
                step(f, Op::BreakTransform, &[13, 43, 8, 37], 1498);
                step(f, Op::MakeVector, &[152, 152, 55, 42], 1499);
                step(f, Op::AddV, &[43, 42, 36], 1500);
                step(f, Op::GetTransform, &[0, 2, 9, 16], 1501);
                step(f, Op::BreakTransform, &[16, 19, 9, 34], 1502);
                step(f, Op::MakeTransform, &[36, 9, 5, 15], 1503);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 7, 20], 1504);
                step(f, Op::GetTransform, &[20, 2, 9, 17], 1505);
                step(f, Op::BreakTransform, &[17, 39, 11, 32], 1506);
                step(f, Op::SubV, &[39, 19, 35], 1507);
                step(f, Op::AddV, &[36, 35, 40], 1508);
                step(f, Op::FootPivots, &[36, 40, 57, 56, 55, 58, 29, 41, 48], 1509);
                step(f, Op::GetParent, &[0, 18], 1510);
                step(f, Op::GetParent, &[18, 19], 1511);
                step(f, Op::GetTransform, &[19, 2, 10, 19], 1512);
                step(f, Op::BreakTransform, &[19, 58, 2, 20], 1513);
                step(f, Op::SubV, &[43, 58, 28], 1514);
                step(f, Op::DotV, &[28, 9, 190], 1515);
                step(f, Op::RemapF, &[190, 92, 91, 93, 152, 9, 204], 1516);
                step(f, Op::LengthV, &[2, 177], 1517);
                step(f, Op::RemapF, &[177, 152, 103, 152, 154, 9, 206], 1518);
                step(f, Op::MulF, &[204, 206, 211], 1519);
                step(f, Op::QuatFromAxisAngle, &[12, 211, 10], 1520);
                step(f, Op::RotateAroundPoint, &[15, 29, 10, 18], 1521);
                step(f, Op::ArrayAt(Elem::Float), &[2, 7, 176], 1522);
                step(f, Op::SmoothStepF, &[176, 152, 97, 188], 1523);
                step(f, Op::SubF, &[154, 176, 183], 1524);
                step(f, Op::SmoothStepF, &[183, 152, 97, 203], 1525);
                step(f, Op::MulF, &[188, 203, 180], 1526);
                step(f, Op::LerpF, &[96, 154, 180, 191], 1527);
                step(f, Op::MulF, &[211, 191, 197], 1528);
                step(f, Op::QuatFromAxisAngle, &[12, 197, 7], 1529);
                step(f, Op::SubV, &[41, 29, 52], 1530);
                step(f, Op::RotateVector, &[7, 52, 31], 1531);
                step(f, Op::AddV, &[29, 31, 51], 1532);
                step(f, Op::RemapF, &[190, 94, 92, 95, 152, 9, 205], 1533);
                step(f, Op::MulF, &[205, 206, 179], 1534);
                step(f, Op::QuatFromAxisAngle, &[12, 179, 6], 1535);
                step(f, Op::RotateAroundPoint, &[18, 51, 6, 7], 1536);
                step(f, Op::RemapF, &[190, 98, 99, 152, 100, 9, 193], 1537);
                step(f, Op::RotateVector, &[8, 8, 30], 1538);
                step(f, Op::BreakVector, &[30, 189, 194, 200], 1539);
                step(f, Op::CosF, &[102, 192], 1540);
                step(f, Op::CosF, &[101, 181], 1541);
                step(f, Op::RemapF, &[200, 192, 181, 152, 154, 9, 195], 1542);
                step(f, Op::MulF, &[206, 195, 199], 1543);
                step(f, Op::MulF, &[193, 199, 202], 1544);
                step(f, Op::QuatFromAxisAngle, &[12, 202, 3], 1545);
                step(f, Op::RotateAroundPoint, &[7, 48, 3, 4], 1546);
                step(f, Op::SubF, &[154, 15, 187], 1547);
                step(f, Op::MulF, &[14, 187, 210], 1548);
                step(f, Op::LimitRotationAroundZ, &[8, 210, 104, 5], 1549);
                step(f, Op::RotateAroundPoint, &[4, 43, 5, 6], 1550);
                step(f, Op::BreakTransform, &[6, 54, 4, 17], 1551);
                step(f, Op::ArrayAt(Elem::Float), &[4, 7, 196], 1552);
                step(f, Op::MulF, &[196, 105, 208], 1553);
                step(f, Op::MulF, &[208, 106, 201], 1554);
                step(f, Op::AddF, &[208, 106, 185], 1555);
                step(f, Op::DivF, &[201, 185, 182], 1556);
                step(f, Op::MakeVector, &[152, 152, 182, 38], 1557);
                step(f, Op::AddV, &[54, 38, 18], 1558);
                step(f, Op::MakeTransform, &[18, 4, 17, 8], 1559);
                step(f, Op::ArraySetAt(Elem::Transform), &[7, 7, 8], 1560);
                step(f, Op::JumpIfFalse, &[8, 1565], 1561)
            }
            1561 => {
                step(f, Op::DrawPoint, &[48, 170, 12], 1562);
                step(f, Op::DrawPoint, &[29, 170, 9], 1563);
                step(f, Op::DrawPoint, &[51, 170, 8], 1564);
                step(f, Op::DrawTransform, &[13, 169, 153], 1565);
                1565
            }
            1565 => {
                step(f, Op::Jump, &[633], 1566)
            }
            1566 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1567);
                step(f, Op::Copy(ValueType::Int), &[2, 8], 1568);
                1568
            }
            1568 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 8, 1, 6, 9, 1607], 1569)
            }
            1569 => {
                step(f, Op::GetParent, &[1, 22], 1570);
                step(f, Op::GetParent, &[22, 23], 1571);
                step(f, Op::GetParent, &[23, 24], 1572);
                step(f, Op::GetTransform, &[24, 2, 10, 9], 1573);
                step(f, Op::BreakTransform, &[9, 27, 9, 33], 1574);
                step(f, Op::LengthV, &[1, 209], 1575);
                step(f, Op::ClavicleOffset, &[12, 209, 118, 122, 184], 1576);
                step(f, Op::MakeVector, &[152, 152, 184, 44], 1577);
                step(f, Op::AddV, &[27, 44, 53], 1578);
                step(f, Op::MakeTransform, &[53, 9, 5, 5], 1579);
                step(f, Op::SetTransform, &[24, 5, 2, 9, 154], 1580);
                step(f, Op::GetTransform, &[1, 2, 10, 10], 1581);
                step(f, Op::GetTransform, &[23, 2, 10, 11], 1582);
                step(f, Op::BreakTransform, &[11, 50, 11, 47], 1583);
                step(f, Op::Equals(Elem::Int), &[6, 2, 12], 1584);
                step(f, Op::Select(ValueType::Int), &[12, 3, 2, 11], 1585);
                step(f, Op::ArrayAt(Elem::Float), &[0, 11, 186], 1586);
                step(f, Op::ArmSwingRotation, &[186, 1, 0, 119, 161, 171, 154, 118, 116, 117, 120, 161, 154, 207], 1587);
                step(f, Op::QuatFromAxisAngle, &[12, 207, 2], 1588);
                step(f, Op::RotateAroundPoint, &[10, 50, 2, 12], 1589);
                step(f, Op::BreakTransform, &[12, 49, 10, 59], 1590);
                step(f, Op::RemapF, &[209, 152, 118, 152, 121, 9, 178], 1591);
                step(f, Op::MakeVector, &[152, 152, 178, 46], 1592);
                step(f, Op::AddV, &[49, 46, 57], 1593);
                step(f, Op::MakeTransform, &[57, 10, 5, 14], 1594);
                step(f, Op::Select(ValueType::Vec3), &[12, 13, 12, 45], 1595);
                step(f, Op::Select(ValueType::Vec3), &[12, 9, 14, 56], 1596);
                step(f, Op::ArrayAt(Elem::Vec3), &[4, 6, 16], 1597);
                step(f, Op::TwoBoneIK, &[23, 22, 1, 14, 45, 56, 16, 2, 154, 10, 172, 173, 9, 20, 198], 1598);
                step(f, Op::JumpIfFalse, &[8, 1606], 1599)
            }
            1599 => {
                step(f, Op::GetTransform, &[23, 2, 10, 11], 1600);
                step(f, Op::BreakTransform, &[11, 50, 11, 47], 1601);
                step(f, Op::GetTransform, &[1, 2, 10, 10], 1602);
                step(f, Op::RotateAroundPoint, &[10, 50, 2, 12], 1603);
                step(f, Op::BreakTransform, &[12, 49, 10, 59], 1604);
                step(f, Op::AddV, &[49, 46, 57], 1605);
                step(f, Op::DrawLine, &[50, 57, 153, 9], 1606);
                1606
            }
            1606 => {
                step(f, Op::Jump, &[1568], 1607)
            }
            1607 => {
                step(f, Op::NegF, &[3, 177], 1608);
                step(f, Op::MakeVector, &[152, 152, 177, 21], 1609);
                step(f, Op::MakeTransform, &[21, 1, 5, 16], 1610);
                step(f, Op::SetTransform, &[36, 16, 2, 9, 154], 1611);
                step(f, Op::Copy(ValueType::Float), &[159, 204], 1612);
                step(f, Op::Copy(ValueType::Bool), &[10, 18], 1613);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 11], 1614);
                step(f, Op::Copy(ValueType::Int), &[2, 12], 1615);
                step(f, Op::MakeVector, &[152, 152, 60, 24], 1616);
                1616
            }
            1616 => {
                step(f, Op::ForEachNext(Elem::Transform), &[11, 12, 17, 7, 10, 1628], 1617)
            }
            1617 => {
                step(f, Op::BreakTransform, &[17, 55, 7, 23], 1618);
                step(f, Op::AddV, &[55, 24, 25], 1619);
                step(f, Op::SubV, &[55, 24, 26], 1620);
                step(f, Op::SphereTrace, &[25, 26, 59, 14, 22, 37, 176], 1621);
                step(f, Op::BreakVector, &[22, 183, 188, 203], 1622);
                step(f, Op::LessF, &[203, 204, 11], 1623);
                step(f, Op::And, &[14, 11, 13], 1624);
                step(f, Op::JumpIfFalse, &[13, 1627], 1625)
            }
            1625 => {
                step(f, Op::Copy(ValueType::Float), &[203, 204], 1626);
                step(f, Op::Copy(ValueType::Bool), &[9, 18], 1627);
                1627
            }
            1627 => {
                step(f, Op::Jump, &[1616], 1628)
            }
            1628 => {
                step(f, Op::Select(ValueType::Float), &[18, 204, 152, 180], 1629);
                step(f, Op::ClampF, &[180, 65, 66, 191], 1630);
                step(f, Op::Copy(ValueType::Float), &[191, 211], 1631);
                step(f, Op::SubF, &[154, 23, 197], 1632);
                step(f, Op::MulF, &[211, 197, 205], 1633);
                step(f, Op::SubF, &[154, 142, 179], 1634);
                step(f, Op::MulF, &[3, 179, 190], 1635);
                step(f, Op::AddF, &[205, 190, 189], 1636);
                step(f, Op::MakeVector, &[18, 152, 152, 42], 1637);
                step(f, Op::MakeVector, &[189, 152, 152, 34], 1638);
                step(f, Op::Select(ValueType::Float), &[2, 189, 19, 194], 1639);
                step(f, Op::MakeVector, &[194, 152, 152, 32], 1640);
                step(f, Op::Copy(ValueType::Float), &[53, 181], 1641);
                step(f, Op::Copy(ValueType::Float), &[54, 192], 1642);
                step(f, Op::SubV, &[34, 32, 19], 1643);
                step(f, Op::DeltaTime, &[200], 1644);
                step(f, Op::DivF, &[192, 200, 195], 1645);
                step(f, Op::ScaleV, &[19, 195, 39], 1646);
                step(f, Op::AddV, &[34, 39, 35], 1647);
                step(f, Op::AddV, &[32, 39, 36], 1648);
                step(f, Op::SubV, &[42, 36, 40], 1649);
                step(f, Op::FloatLerp, &[152, 154, 181, 206], 1650);
                step(f, Op::SubF, &[154, 206, 193], 1651);
                step(f, Op::ScaleV, &[40, 193, 20], 1652);
                step(f, Op::AddV, &[35, 20, 58], 1653);
                step(f, Op::MulF, &[181, 200, 199], 1654);
                step(f, Op::GreaterF, &[199, 152, 16], 1655);
                step(f, Op::DivF, &[206, 199, 202], 1656);
                step(f, Op::Select(ValueType::Float), &[16, 202, 154, 187], 1657);
                step(f, Op::ScaleV, &[19, 187, 28], 1658);
                step(f, Op::SubV, &[58, 28, 41], 1659);
                step(f, Op::Copy(ValueType::Vec3), &[41, 52], 1660);
                step(f, Op::BreakVector, &[52, 210, 196, 208], 1661);
                step(f, Op::Select(ValueType::Float), &[1, 189, 210, 185], 1662);
                step(f, Op::Copy(ValueType::Float), &[185, 18], 1663);
                step(f, Op::Copy(ValueType::Float), &[189, 19], 1664);
                step(f, Op::GetTransform, &[37, 2, 9, 19], 1665);
                step(f, Op::BreakTransform, &[19, 31, 6, 30], 1666);
                step(f, Op::PelvisLean, &[1, 125, 130, 131, 201, 182], 1667);
                step(f, Op::LengthV, &[2, 184], 1668);
                step(f, Op::RemapF, &[184, 152, 125, 152, 123, 9, 186], 1669);
                step(f, Op::MulF, &[15, 124, 207], 1670);
                step(f, Op::SubF, &[154, 207, 209], 1671);
                step(f, Op::MulF, &[186, 209, 178], 1672);
                step(f, Op::MulF, &[12, 174, 198], 1673);
                step(f, Op::SinF, &[198, 177], 1674);
                step(f, Op::MulF, &[178, 177, 176], 1675);
                step(f, Op::MulF, &[176, 197, 183], 1676);
                step(f, Op::AddF, &[183, 18, 188], 1677);
                step(f, Op::SubF, &[188, 3, 203], 1678);
                step(f, Op::MakeVector, &[152, 182, 203, 43], 1679);
                step(f, Op::AddV, &[31, 43, 38], 1680);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 2, 15], 1681);
                step(f, Op::BreakTransform, &[15, 54, 3, 17], 1682);
                step(f, Op::BreakVector, &[54, 204, 180, 191], 1683);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 3, 18], 1684);
                step(f, Op::BreakTransform, &[18, 18, 8, 48], 1685);
                step(f, Op::BreakVector, &[18, 211, 179, 190], 1686);
                step(f, Op::SubF, &[191, 190, 205], 1687);
                step(f, Op::PelvisSideLean, &[205, 132, 133, 194], 1688);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 2, 7], 1689);
                step(f, Op::BreakTransform, &[7, 29, 5, 51], 1690);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 3, 4], 1691);
                step(f, Op::BreakTransform, &[4, 33, 4, 27], 1692);
                step(f, Op::SlerpQ, &[5, 4, 153, 9], 1693);
                step(f, Op::EulerFromQuat, &[9, 2, 44], 1694);
                step(f, Op::BreakVector, &[44, 192, 195, 193], 1695);
                step(f, Op::RemapF, &[184, 126, 125, 152, 127, 9, 181], 1696);
                step(f, Op::SubV, &[54, 18, 53], 1697);
                step(f, Op::RotateVector, &[0, 9, 16], 1698);
                step(f, Op::DotV, &[53, 16, 200], 1699);
                step(f, Op::MulF, &[181, 200, 199], 1700);
                step(f, Op::AddF, &[193, 199, 206], 1701);
                step(f, Op::MakeVector, &[201, 194, 206, 45], 1702);
                step(f, Op::QuatFromEuler, &[45, 2, 11], 1703);
                step(f, Op::MakeTransform, &[38, 11, 5, 6], 1704);
                step(f, Op::SetTransform, &[38, 6, 2, 9, 154], 1705);
                step(f, Op::GetTransform, &[39, 3, 9, 8], 1706);
                step(f, Op::BreakTransform, &[8, 56, 2, 47], 1707);
                step(f, Op::QuatFromAxisAngle, &[8, 199, 10], 1708);
                step(f, Op::DivF, &[128, 170, 202], 1709);
                step(f, Op::QuatScale, &[10, 202, 7], 1710);
                step(f, Op::MulQ, &[2, 7, 6], 1711);
                step(f, Op::MakeTransform, &[56, 6, 5, 13], 1712);
                step(f, Op::SetTransform, &[40, 13, 3, 9, 154], 1713);
                step(f, Op::GetTransform, &[41, 3, 9, 9], 1714);
                step(f, Op::BreakTransform, &[9, 59, 3, 46], 1715);
                step(f, Op::MulQ, &[3, 7, 8], 1716);
                step(f, Op::MakeTransform, &[59, 8, 5, 5], 1717);
                step(f, Op::SetTransform, &[42, 5, 3, 9, 154], 1718);
                step(f, Op::GetTransform, &[43, 3, 9, 14], 1719);
                step(f, Op::BreakTransform, &[14, 49, 4, 50], 1720);
                step(f, Op::MulQ, &[4, 7, 5], 1721);
                step(f, Op::MakeTransform, &[49, 5, 5, 11], 1722);
                step(f, Op::SetTransform, &[44, 11, 3, 9, 154], 1723);
                step(f, Op::GetTransform, &[45, 3, 9, 10], 1724);
                step(f, Op::BreakTransform, &[10, 57, 9, 21], 1725);
                step(f, Op::QuatScale, &[10, 129, 11], 1726);
                step(f, Op::MulQ, &[9, 11, 2], 1727);
                step(f, Op::MakeTransform, &[57, 2, 5, 12], 1728);
                step(f, Op::SetTransform, &[46, 12, 3, 9, 154], 1729);
                step(f, Op::Or, &[1, 2, 17], 1730);
                step(f, Op::Copy(ValueType::Float), &[152, 187], 1731);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1732);
                step(f, Op::Copy(ValueType::Int), &[2, 9], 1733);
                1733
            }
            1733 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 9, 25, 11, 6, 1780], 1734)
            }
            1734 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 11, 15], 1735);
                step(f, Op::GetParent, &[25, 26], 1736);
                step(f, Op::GetParent, &[26, 27], 1737);
                step(f, Op::GetTransform, &[27, 2, 10, 16], 1738);
                step(f, Op::BreakTransform, &[16, 23, 6, 55], 1739);
                step(f, Op::BreakVector, &[23, 196, 208, 210], 1740);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 11, 17], 1741);
                step(f, Op::BreakTransform, &[17, 25, 3, 26], 1742);
                step(f, Op::BreakVector, &[25, 185, 189, 207], 1743);
                step(f, Op::ArrayAt(Elem::Float), &[1, 11, 186], 1744);
                step(f, Op::MulF, &[186, 134, 209], 1745);
                step(f, Op::MulF, &[209, 209, 198], 1746);
                step(f, Op::SubF, &[196, 185, 177], 1747);
                step(f, Op::SubF, &[208, 189, 178], 1748);
                step(f, Op::MakeVector, &[177, 178, 152, 37], 1749);
                step(f, Op::DotV, &[37, 37, 176], 1750);
                step(f, Op::SubF, &[198, 176, 197], 1751);
                step(f, Op::SqrtF, &[197, 183], 1752);
                step(f, Op::AddF, &[207, 183, 188], 1753);
                step(f, Op::SubF, &[210, 188, 182], 1754);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 11, 19], 1755);
                step(f, Op::BreakTransform, &[19, 22, 8, 24], 1756);
                step(f, Op::BreakVector, &[22, 203, 180, 204], 1757);
                step(f, Op::AddF, &[204, 55, 179], 1758);
                step(f, Op::MinF, &[207, 179, 211], 1759);
                step(f, Op::AddF, &[211, 183, 190], 1760);
                step(f, Op::SubF, &[210, 190, 191], 1761);
                step(f, Op::Equals(Elem::Int), &[11, 2, 19], 1762);
                step(f, Op::Select(ValueType::Int), &[19, 3, 2, 8], 1763);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 8, 12], 1764);
                step(f, Op::ArrayAt(Elem::Float), &[2, 8, 205], 1765);
                step(f, Op::RemapF, &[205, 153, 154, 152, 154, 9, 192], 1766);
                step(f, Op::RemapF, &[205, 152, 137, 154, 152, 9, 195], 1767);
                step(f, Op::MaxF, &[192, 195, 184], 1768);
                step(f, Op::Select(ValueType::Float), &[12, 154, 184, 181], 1769);
                step(f, Op::LerpF, &[182, 191, 181, 200], 1770);
                step(f, Op::ArrayAt(Elem::Float), &[2, 11, 193], 1771);
                step(f, Op::RemapF, &[193, 153, 154, 152, 154, 9, 194], 1772);
                step(f, Op::MulF, &[200, 194, 201], 1773);
                step(f, Op::RemapF, &[193, 152, 137, 154, 152, 9, 206], 1774);
                step(f, Op::MulF, &[182, 206, 199], 1775);
                step(f, Op::MaxF, &[201, 199, 202], 1776);
                step(f, Op::Select(ValueType::Float), &[15, 182, 202, 186], 1777);
                step(f, Op::MaxF, &[187, 186, 209], 1778);
                step(f, Op::Copy(ValueType::Float), &[209, 187], 1779);
                step(f, Op::Jump, &[1733], 1780)
            }
            1780 => {
                step(f, Op::ClampF, &[187, 152, 135, 185], 1781);
                step(f, Op::Copy(ValueType::Float), &[185, 196], 1782);
                step(f, Op::MakeVector, &[20, 152, 152, 34], 1783);
                step(f, Op::MakeVector, &[196, 152, 152, 32], 1784);
                step(f, Op::MakeVector, &[21, 152, 152, 39], 1785);
                step(f, Op::GreaterF, &[196, 20, 20], 1786);
                step(f, Op::Select(ValueType::Float), &[20, 139, 136, 189], 1787);
                step(f, Op::Copy(ValueType::Float), &[54, 208], 1788);
                step(f, Op::SubV, &[32, 39, 36], 1789);
                step(f, Op::DeltaTime, &[177], 1790);
                step(f, Op::DivF, &[208, 177, 178], 1791);
                step(f, Op::ScaleV, &[36, 178, 42], 1792);
                step(f, Op::AddV, &[32, 42, 40], 1793);
                step(f, Op::AddV, &[39, 42, 20], 1794);
                step(f, Op::SubV, &[34, 20, 35], 1795);
                step(f, Op::FloatLerp, &[152, 154, 189, 176], 1796);
                step(f, Op::SubF, &[154, 176, 198], 1797);
                step(f, Op::ScaleV, &[35, 198, 19], 1798);
                step(f, Op::AddV, &[40, 19, 28], 1799);
                step(f, Op::MulF, &[189, 177, 197], 1800);
                step(f, Op::GreaterF, &[197, 152, 11], 1801);
                step(f, Op::DivF, &[176, 197, 188], 1802);
                step(f, Op::Select(ValueType::Float), &[11, 188, 154, 180], 1803);
                step(f, Op::ScaleV, &[36, 180, 58], 1804);
                step(f, Op::SubV, &[28, 58, 41], 1805);
                step(f, Op::Copy(ValueType::Vec3), &[41, 52], 1806);
                step(f, Op::BreakVector, &[52, 203, 204, 179], 1807);
                step(f, Op::Select(ValueType::Float), &[17, 196, 203, 207], 1808);
                step(f, Op::Copy(ValueType::Float), &[207, 20], 1809);
                step(f, Op::Copy(ValueType::Float), &[196, 21], 1810);
                step(f, Op::GetTransform, &[47, 2, 10, 15], 1811);
                step(f, Op::BreakTransform, &[15, 30, 4, 31], 1812);
                step(f, Op::MakeVector, &[152, 152, 20, 43], 1813);
                step(f, Op::SubV, &[30, 43, 17], 1814);
                step(f, Op::MakeTransform, &[17, 4, 5, 18], 1815);
                step(f, Op::SetTransform, &[48, 18, 2, 9, 154], 1816);
                step(f, Op::JumpIfFalse, &[8, 1822], 1817)
            }
            1817 => {
                step(f, Op::GetTransform, &[47, 2, 10, 15], 1818);
                step(f, Op::BreakTransform, &[15, 30, 4, 31], 1819);
                step(f, Op::SubV, &[30, 43, 17], 1820);
                step(f, Op::MakeTransform, &[17, 4, 5, 18], 1821);
                step(f, Op::DrawTransform, &[18, 175, 153], 1822);
                1822
            }
            1822 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1823);
                step(f, Op::Copy(ValueType::Int), &[2, 7], 1824);
                1824
            }
            1824 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 7, 2, 10, 12, 1873], 1825)
            }
            1825 => {
                step(f, Op::GetParent, &[2, 29], 1826);
                step(f, Op::GetParent, &[29, 30], 1827);
                step(f, Op::GetTransform, &[30, 2, 10, 7], 1828);
                step(f, Op::BreakTransform, &[7, 48, 7, 29], 1829);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 10, 4], 1830);
                step(f, Op::BreakTransform, &[4, 51, 5, 27], 1831);
                step(f, Op::SubV, &[51, 48, 33], 1832);
                step(f, Op::LengthV, &[33, 183], 1833);
                step(f, Op::ArrayAt(Elem::Float), &[1, 10, 211], 1834);
                step(f, Op::MulF, &[211, 146, 190], 1835);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 10, 14], 1836);
                step(f, Op::MulF, &[16, 113, 210], 1837);
                step(f, Op::ArrayAt(Elem::Float), &[2, 10, 205], 1838);
                step(f, Op::ClampF, &[205, 152, 154, 192], 1839);
                step(f, Op::LessF, &[192, 153, 13], 1840);
                step(f, Op::SmoothStepF, &[192, 148, 149, 195], 1841);
                step(f, Op::MulF, &[192, 162, 184], 1842);
                step(f, Op::SinF, &[184, 181], 1843);
                step(f, Op::MaxF, &[195, 181, 191], 1844);
                step(f, Op::Select(ValueType::Float), &[13, 191, 181, 194], 1845);
                step(f, Op::MulF, &[194, 147, 200], 1846);
                step(f, Op::Select(ValueType::Float), &[14, 210, 200, 193], 1847);
                step(f, Op::SubF, &[190, 193, 206], 1848);
                step(f, Op::SubF, &[183, 206, 199], 1849);
                step(f, Op::MaxF, &[199, 152, 201], 1850);
                step(f, Op::MulF, &[201, 201, 182], 1851);
                step(f, Op::AddF, &[201, 193, 202], 1852);
                step(f, Op::DivF, &[182, 202, 186], 1853);
                step(f, Op::SubF, &[183, 186, 209], 1854);
                step(f, Op::DivF, &[209, 183, 187], 1855);
                step(f, Op::ScaleV, &[33, 187, 44], 1856);
                step(f, Op::AddV, &[48, 44, 18], 1857);
                step(f, Op::ClampSpatially, &[18, 48, 152, 190, 54], 1858);
                step(f, Op::MakeTransform, &[54, 5, 5, 6], 1859);
                step(f, Op::Equals(Elem::Int), &[10, 2, 18], 1860);
                step(f, Op::Select(ValueType::Vec3), &[18, 13, 12, 16], 1861);
                step(f, Op::Select(ValueType::Vec3), &[18, 9, 14, 53], 1862);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 10, 8], 1863);
                step(f, Op::BreakTransform, &[8, 45, 10, 38], 1864);
                step(f, Op::ArrayAt(Elem::Vec3), &[3, 10, 47], 1865);
                step(f, Op::KneeVector, &[10, 0, 47, 150, 151, 56], 1866);
                step(f, Op::TwoBoneIK, &[30, 29, 2, 6, 16, 53, 56, 2, 154, 10, 172, 173, 9, 16, 185], 1867);
                step(f, Op::JumpIfFalse, &[8, 1872], 1868)
            }
            1868 => {
                step(f, Op::GetTransform, &[29, 2, 10, 13], 1869);
                step(f, Op::BreakTransform, &[13, 46, 9, 59], 1870);
                step(f, Op::AddV, &[46, 56, 50], 1871);
                step(f, Op::DrawLine, &[46, 50, 153, 15], 1872);
                1872
            }
            1872 => {
                step(f, Op::Jump, &[1824], 1873)
            }
            1873 => {
                step(f, Op::End, &[], 1874)
            }
            _ => return,
        } };
    }
}
