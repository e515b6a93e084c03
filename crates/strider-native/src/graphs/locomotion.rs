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
    fingerprint: 0x103e48c0db13ea02,
    forward,
};

fn forward(f: &mut Frame<'_>) {
    let mut pc: usize = 103;
    loop {
        // SAFETY: each `step` is an instruction of the program this code was generated
        // from, with its own operands; `NATIVE` runs only on that program (fingerprint).
        pc = unsafe { match pc {
            103 => {
                step(f, Op::Not, &[0, 9], 104);
                step(f, Op::Copy(ValueType::Bool), &[9, 1], 105);
                step(f, Op::WorldTransform, &[12], 106);
                step(f, Op::BreakTransform, &[12, 33, 7, 34], 107);
                step(f, Op::Select(ValueType::Transform), &[0, 0, 12, 13], 108);
                step(f, Op::BreakTransform, &[13, 35, 8, 36], 109);
                step(f, Op::SubV, &[33, 35, 37], 110);
                step(f, Op::LengthV, &[37, 140], 111);
                step(f, Op::GreaterF, &[140, 35, 10], 112);
                step(f, Op::Copy(ValueType::Bool), &[10, 2], 113);
                step(f, Op::MakeRelative, &[13, 12, 17], 114);
                step(f, Op::Select(ValueType::Transform), &[10, 112, 17, 18], 115);
                step(f, Op::Copy(ValueType::Transform), &[18, 2], 116);
                step(f, Op::InverseT, &[13, 15], 117);
                step(f, Op::MulT, &[12, 15, 16], 118);
                step(f, Op::Copy(ValueType::Transform), &[16, 1], 119);
                step(f, Op::TransformVector, &[2, 0, 42], 120);
                step(f, Op::InverseT, &[12, 14], 121);
                step(f, Op::DeltaTime, &[139], 122);
                step(f, Op::DivF, &[815, 139, 141], 123);
                step(f, Op::ScaleV, &[37, 141, 38], 124);
                step(f, Op::TransformVector, &[14, 38, 39], 125);
                step(f, Op::BreakVector, &[39, 142, 143, 144], 126);
                step(f, Op::MakeVector, &[142, 143, 813, 40], 127);
                step(f, Op::LengthV, &[40, 145], 128);
                step(f, Op::MulF, &[145, 121, 146], 129);
                step(f, Op::NegF, &[146, 147], 130);
                step(f, Op::ClampF, &[144, 147, 146, 148], 131);
                step(f, Op::MakeVector, &[142, 143, 148, 41], 132);
                step(f, Op::Select(ValueType::Vec3), &[2, 42, 41, 44], 133);
                step(f, Op::VectorLerp, &[42, 44, 36, 813, 45], 134);
                step(f, Op::Copy(ValueType::Vec3), &[45, 0], 135);
                step(f, Op::TransformVector, &[2, 1, 43], 136);
                step(f, Op::TransformVector, &[2, 0, 42], 137);
                step(f, Op::Select(ValueType::Vec3), &[2, 42, 41, 44], 138);
                step(f, Op::VectorLerp, &[43, 44, 37, 813, 46], 139);
                step(f, Op::Copy(ValueType::Vec3), &[46, 1], 140);
                step(f, Op::LengthV, &[44, 155], 141);
                step(f, Op::Copy(ValueType::Float), &[155, 0], 142);
                step(f, Op::BreakVector, &[37, 149, 150, 151], 143);
                step(f, Op::MulF, &[148, 139, 152], 144);
                step(f, Op::SubF, &[151, 152, 153], 145);
                step(f, Op::Select(ValueType::Float), &[10, 813, 153, 154], 146);
                step(f, Op::Copy(ValueType::Float), &[154, 1], 147);
                step(f, Op::JumpIfFalse, &[2, 161], 148)
            }
            148 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 12], 149);
                step(f, Op::Copy(ValueType::Int), &[71, 17], 150);
                150
            }
            150 => {
                step(f, Op::ForEachNext(Elem::Bone), &[12, 17, 13, 18, 19, 159], 151)
            }
            151 => {
                step(f, Op::ArrayAt(Elem::Transform), &[7, 18, 20], 152);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 18, 20], 153);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 18, 20], 154);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 18, 20], 155);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 18, 20], 156);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 18, 20], 157);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 18, 20], 158);
                step(f, Op::Jump, &[150], 159)
            }
            159 => {
                step(f, Op::Copy(ValueType::Float), &[813, 16], 160);
                step(f, Op::Jump, &[161], 161)
            }
            161 => {
                step(f, Op::Copy(ValueType::Transform), &[12, 0], 162);
                step(f, Op::Copy(ValueType::Bool), &[98, 0], 163);
                step(f, Op::JumpIfFalse, &[8, 170], 164)
            }
            164 => {
                step(f, Op::GetTransform, &[34, 71, 98, 19], 165);
                step(f, Op::BreakTransform, &[19, 47, 9, 48], 166);
                step(f, Op::ScaleV, &[0, 816, 49], 167);
                step(f, Op::AddV, &[47, 49, 50], 168);
                step(f, Op::DrawArrow, &[47, 50, 814, 423], 169);
                step(f, Op::Jump, &[170], 170)
            }
            170 => {
                step(f, Op::Copy(ValueType::Float), &[813, 156], 171);
                step(f, Op::Copy(ValueType::Float), &[815, 157], 172);
                step(f, Op::Copy(ValueType::Float), &[815, 158], 173);
                step(f, Op::Copy(ValueType::Bool), &[99, 11], 174);
                step(f, Op::Copy(ValueType::Bool), &[99, 12], 175);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[7, 8], 176);
                step(f, Op::Copy(ValueType::Int), &[71, 25], 177);
                step(f, Op::MakeVector, &[813, 813, 55, 55], 178);
                178
            }
            178 => {
                step(f, Op::ForEachNext(Elem::Transform), &[8, 25, 21, 26, 27, 189], 179)
            }
            179 => {
                step(f, Op::BreakTransform, &[21, 51, 10, 52], 180);
                step(f, Op::TransformPoint, &[2, 51, 53], 181);
                step(f, Op::LerpV, &[53, 51, 158, 54], 182);
                step(f, Op::AddV, &[54, 55, 56], 183);
                step(f, Op::SubV, &[54, 55, 57], 184);
                step(f, Op::LineTrace, &[56, 57, 13, 58, 59, 159], 185);
                step(f, Op::JumpIfFalse, &[13, 188], 186)
            }
            186 => {
                step(f, Op::Copy(ValueType::Bool), &[98, 12], 187);
                step(f, Op::Jump, &[188], 188)
            }
            188 => {
                step(f, Op::Jump, &[178], 189)
            }
            189 => {
                step(f, Op::Copy(ValueType::Bool), &[12, 11], 190);
                step(f, Op::Jump, &[191], 191)
            }
            191 => {
                step(f, Op::Or, &[11, 7, 14], 192);
                step(f, Op::NotEquals(Elem::Bool), &[14, 5, 15], 193);
                step(f, Op::JumpIfFalse, &[15, 228], 194)
            }
            194 => {
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 195);
                step(f, Op::JumpIfFalse, &[16, 227], 196)
            }
            196 => {
                step(f, Op::Copy(ValueType::Int), &[1, 24], 197);
                step(f, Op::Copy(ValueType::Int), &[71, 20], 198);
                198
            }
            198 => {
                step(f, Op::ForNext, &[20, 24, 22, 226], 199)
            }
            199 => {
                step(f, Op::AddF, &[156, 157, 160], 200);
                step(f, Op::MulF, &[160, 814, 161], 201);
                step(f, Op::Copy(ValueType::Float), &[161, 162], 202);
                step(f, Op::Copy(ValueType::Bool), &[99, 17], 203);
                step(f, Op::Copy(ValueType::Bool), &[99, 18], 204);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[7, 9], 205);
                step(f, Op::Copy(ValueType::Int), &[71, 28], 206);
                step(f, Op::MakeVector, &[813, 813, 55, 64], 207);
                207
            }
            207 => {
                step(f, Op::ForEachNext(Elem::Transform), &[9, 28, 22, 29, 30, 218], 208)
            }
            208 => {
                step(f, Op::BreakTransform, &[22, 60, 11, 61], 209);
                step(f, Op::TransformPoint, &[2, 60, 62], 210);
                step(f, Op::LerpV, &[62, 60, 162, 63], 211);
                step(f, Op::AddV, &[63, 64, 65], 212);
                step(f, Op::SubV, &[63, 64, 66], 213);
                step(f, Op::LineTrace, &[65, 66, 19, 67, 68, 163], 214);
                step(f, Op::JumpIfFalse, &[19, 217], 215)
            }
            215 => {
                step(f, Op::Copy(ValueType::Bool), &[98, 18], 216);
                step(f, Op::Jump, &[217], 217)
            }
            217 => {
                step(f, Op::Jump, &[207], 218)
            }
            218 => {
                step(f, Op::Copy(ValueType::Bool), &[18, 17], 219);
                step(f, Op::Jump, &[220], 220)
            }
            220 => {
                step(f, Op::Equals(Elem::Bool), &[17, 6, 20], 221);
                step(f, Op::JumpIfFalse, &[20, 224], 222)
            }
            222 => {
                step(f, Op::Copy(ValueType::Float), &[161, 156], 223);
                step(f, Op::Jump, &[225], 224)
            }
            224 => {
                step(f, Op::Copy(ValueType::Float), &[161, 157], 225);
                225
            }
            225 => {
                step(f, Op::Jump, &[198], 226)
            }
            226 => {
                step(f, Op::Jump, &[227], 227)
            }
            227 => {
                step(f, Op::Jump, &[228], 228)
            }
            228 => {
                step(f, Op::Select(ValueType::Float), &[5, 817, 815, 169], 229);
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 230);
                step(f, Op::AddF, &[156, 157, 160], 231);
                step(f, Op::MulF, &[160, 814, 164], 232);
                step(f, Op::Select(ValueType::Float), &[16, 164, 814, 165], 233);
                step(f, Op::Select(ValueType::Float), &[15, 165, 813, 171], 234);
                step(f, Op::MulF, &[169, 171, 173], 235);
                step(f, Op::DeltaTime, &[167], 236);
                step(f, Op::DivF, &[167, 125, 168], 237);
                step(f, Op::MulF, &[173, 168, 174], 238);
                step(f, Op::AddF, &[20, 174, 175], 239);
                step(f, Op::ClampF, &[175, 813, 815, 176], 240);
                step(f, Op::Select(ValueType::Float), &[14, 817, 815, 170], 241);
                step(f, Op::SubF, &[815, 165, 166], 242);
                step(f, Op::Select(ValueType::Float), &[15, 166, 815, 172], 243);
                step(f, Op::MulF, &[170, 172, 177], 244);
                step(f, Op::MulF, &[177, 168, 178], 245);
                step(f, Op::AddF, &[176, 178, 179], 246);
                step(f, Op::ClampF, &[179, 813, 815, 180], 247);
                step(f, Op::SmoothStepF, &[180, 813, 815, 181], 248);
                step(f, Op::AddF, &[21, 181, 182], 249);
                step(f, Op::MulF, &[182, 814, 183], 250);
                step(f, Op::SubF, &[815, 183, 184], 251);
                step(f, Op::MulF, &[184, 184, 185], 252);
                step(f, Op::SubF, &[815, 185, 186], 253);
                step(f, Op::Copy(ValueType::Float), &[186, 22], 254);
                step(f, Op::Copy(ValueType::Float), &[181, 21], 255);
                step(f, Op::Copy(ValueType::Float), &[180, 20], 256);
                step(f, Op::GreaterF, &[21, 813, 21], 257);
                step(f, Op::TransformVector, &[2, 3, 69], 258);
                step(f, Op::Select(ValueType::Vec3), &[21, 69, 0, 70], 259);
                step(f, Op::Copy(ValueType::Vec3), &[70, 3], 260);
                step(f, Op::LerpV, &[0, 3, 21, 71], 261);
                step(f, Op::Select(ValueType::Vec3), &[21, 71, 0, 72], 262);
                step(f, Op::Copy(ValueType::Vec3), &[72, 2], 263);
                step(f, Op::Copy(ValueType::Bool), &[14, 5], 264);
                step(f, Op::Copy(ValueType::Bool), &[11, 6], 265);
                step(f, Op::Copy(ValueType::Bool), &[99, 7], 266);
                step(f, Op::SubF, &[815, 22, 187], 267);
                step(f, Op::MulF, &[1, 187, 188], 268);
                step(f, Op::AddF, &[2, 188, 189], 269);
                step(f, Op::Copy(ValueType::Float), &[4, 190], 270);
                step(f, Op::Copy(ValueType::Float), &[5, 191], 271);
                step(f, Op::Copy(ValueType::Float), &[189, 192], 272);
                step(f, Op::Copy(ValueType::Float), &[2, 193], 273);
                step(f, Op::Copy(ValueType::Float), &[122, 194], 274);
                step(f, Op::Copy(ValueType::Float), &[49, 195], 275);
                step(f, Op::Copy(ValueType::Float), &[813, 196], 276);
                step(f, Op::Copy(ValueType::Float), &[813, 197], 277);
                step(f, Op::SubF, &[192, 193, 200], 278);
                step(f, Op::DeltaTime, &[198], 279);
                step(f, Op::DivF, &[200, 198, 201], 280);
                step(f, Op::MulF, &[201, 195, 202], 281);
                step(f, Op::AddF, &[192, 202, 204], 282);
                step(f, Op::MulF, &[201, 818, 205], 283);
                step(f, Op::DivF, &[819, 194, 199], 284);
                step(f, Op::DivF, &[205, 199, 206], 285);
                step(f, Op::SubF, &[204, 206, 220], 286);
                step(f, Op::AddF, &[193, 202, 203], 287);
                step(f, Op::SubF, &[190, 203, 207], 288);
                step(f, Op::AddF, &[207, 206, 208], 289);
                step(f, Op::SubF, &[191, 201, 209], 290);
                step(f, Op::MulF, &[199, 208, 210], 291);
                step(f, Op::AddF, &[209, 210, 211], 292);
                step(f, Op::MulF, &[211, 198, 214], 293);
                step(f, Op::AddF, &[208, 214, 215], 294);
                step(f, Op::FloatLerp, &[813, 815, 199, 212], 295);
                step(f, Op::SubF, &[815, 212, 213], 296);
                step(f, Op::MulF, &[215, 213, 216], 297);
                step(f, Op::AddF, &[220, 216, 221], 298);
                step(f, Op::Copy(ValueType::Float), &[221, 196], 299);
                step(f, Op::MulF, &[199, 214, 217], 300);
                step(f, Op::SubF, &[209, 217, 218], 301);
                step(f, Op::MulF, &[218, 213, 219], 302);
                step(f, Op::AddF, &[201, 219, 222], 303);
                step(f, Op::Copy(ValueType::Float), &[222, 197], 304);
                step(f, Op::Jump, &[305], 305)
            }
            305 => {
                step(f, Op::SubF, &[189, 196, 223], 306);
                step(f, Op::Copy(ValueType::Float), &[223, 3], 307);
                step(f, Op::Copy(ValueType::Float), &[196, 4], 308);
                step(f, Op::Copy(ValueType::Float), &[4, 190], 309);
                step(f, Op::Copy(ValueType::Float), &[5, 191], 310);
                step(f, Op::Copy(ValueType::Float), &[189, 192], 311);
                step(f, Op::Copy(ValueType::Float), &[2, 193], 312);
                step(f, Op::Copy(ValueType::Float), &[122, 194], 313);
                step(f, Op::Copy(ValueType::Float), &[49, 195], 314);
                step(f, Op::Copy(ValueType::Float), &[813, 196], 315);
                step(f, Op::Copy(ValueType::Float), &[813, 197], 316);
                step(f, Op::SubF, &[192, 193, 200], 317);
                step(f, Op::DeltaTime, &[198], 318);
                step(f, Op::DivF, &[200, 198, 201], 319);
                step(f, Op::MulF, &[201, 195, 202], 320);
                step(f, Op::AddF, &[192, 202, 204], 321);
                step(f, Op::MulF, &[201, 818, 205], 322);
                step(f, Op::DivF, &[819, 194, 199], 323);
                step(f, Op::DivF, &[205, 199, 206], 324);
                step(f, Op::SubF, &[204, 206, 220], 325);
                step(f, Op::AddF, &[193, 202, 203], 326);
                step(f, Op::SubF, &[190, 203, 207], 327);
                step(f, Op::AddF, &[207, 206, 208], 328);
                step(f, Op::SubF, &[191, 201, 209], 329);
                step(f, Op::MulF, &[199, 208, 210], 330);
                step(f, Op::AddF, &[209, 210, 211], 331);
                step(f, Op::MulF, &[211, 198, 214], 332);
                step(f, Op::AddF, &[208, 214, 215], 333);
                step(f, Op::FloatLerp, &[813, 815, 199, 212], 334);
                step(f, Op::SubF, &[815, 212, 213], 335);
                step(f, Op::MulF, &[215, 213, 216], 336);
                step(f, Op::AddF, &[220, 216, 221], 337);
                step(f, Op::Copy(ValueType::Float), &[221, 196], 338);
                step(f, Op::MulF, &[199, 214, 217], 339);
                step(f, Op::SubF, &[209, 217, 218], 340);
                step(f, Op::MulF, &[218, 213, 219], 341);
                step(f, Op::AddF, &[201, 219, 222], 342);
                step(f, Op::Copy(ValueType::Float), &[222, 197], 343);
                step(f, Op::Jump, &[344], 344)
            }
            344 => {
                step(f, Op::Copy(ValueType::Float), &[197, 5], 345);
                step(f, Op::Copy(ValueType::Float), &[189, 2], 346);
                step(f, Op::LengthV, &[4, 225], 347);
                step(f, Op::GreaterF, &[225, 29, 22], 348);
                step(f, Op::LengthV, &[2, 226], 349);
                step(f, Op::GreaterF, &[226, 29, 23], 350);
                step(f, Op::And, &[22, 23, 25], 351);
                step(f, Op::Select(ValueType::Vec3), &[22, 4, 421, 73], 352);
                step(f, Op::MovementAngleOffset, &[73, 14, 813, 820, 820, 821, 40, 822, 227], 353);
                step(f, Op::Copy(ValueType::Float), &[227, 229], 354);
                step(f, Op::Copy(ValueType::Float), &[14, 230], 355);
                step(f, Op::Copy(ValueType::Float), &[813, 231], 356);
                step(f, Op::SubF, &[229, 230, 232], 357);
                step(f, Op::AddF, &[232, 823, 233], 358);
                step(f, Op::DivF, &[233, 824, 234], 359);
                step(f, Op::FractF, &[234, 235], 360);
                step(f, Op::MulF, &[235, 824, 236], 361);
                step(f, Op::SubF, &[236, 823, 237], 362);
                step(f, Op::Copy(ValueType::Float), &[237, 231], 363);
                step(f, Op::Jump, &[364], 364)
            }
            364 => {
                step(f, Op::AbsF, &[231, 256], 365);
                step(f, Op::Select(ValueType::Vec3), &[23, 2, 421, 74], 366);
                step(f, Op::MovementAngleOffset, &[74, 14, 813, 820, 820, 821, 40, 822, 228], 367);
                step(f, Op::Copy(ValueType::Float), &[228, 238], 368);
                step(f, Op::Copy(ValueType::Float), &[14, 239], 369);
                step(f, Op::Copy(ValueType::Float), &[813, 240], 370);
                step(f, Op::SubF, &[238, 239, 241], 371);
                step(f, Op::AddF, &[241, 823, 242], 372);
                step(f, Op::DivF, &[242, 824, 243], 373);
                step(f, Op::FractF, &[243, 244], 374);
                step(f, Op::MulF, &[244, 824, 245], 375);
                step(f, Op::SubF, &[245, 823, 246], 376);
                step(f, Op::Copy(ValueType::Float), &[246, 240], 377);
                step(f, Op::Jump, &[378], 378)
            }
            378 => {
                step(f, Op::AbsF, &[240, 257], 379);
                step(f, Op::MaxF, &[256, 257, 259], 380);
                step(f, Op::Copy(ValueType::Float), &[228, 247], 381);
                step(f, Op::Copy(ValueType::Float), &[227, 248], 382);
                step(f, Op::Copy(ValueType::Float), &[813, 249], 383);
                step(f, Op::SubF, &[247, 248, 250], 384);
                step(f, Op::AddF, &[250, 823, 251], 385);
                step(f, Op::DivF, &[251, 824, 252], 386);
                step(f, Op::FractF, &[252, 253], 387);
                step(f, Op::MulF, &[253, 824, 254], 388);
                step(f, Op::SubF, &[254, 823, 255], 389);
                step(f, Op::Copy(ValueType::Float), &[255, 249], 390);
                step(f, Op::Jump, &[391], 391)
            }
            391 => {
                step(f, Op::AbsF, &[249, 258], 392);
                step(f, Op::MaxF, &[259, 258, 260], 393);
                step(f, Op::LessF, &[260, 825, 24], 394);
                step(f, Op::And, &[25, 24, 26], 395);
                step(f, Op::Not, &[22, 27], 396);
                step(f, Op::Not, &[23, 28], 397);
                step(f, Op::And, &[27, 28, 29], 398);
                step(f, Op::Or, &[26, 29, 30], 399);
                step(f, Op::JumpIfFalse, &[30, 421], 400)
            }
            400 => {
                step(f, Op::DeltaTime, &[224], 401);
                step(f, Op::MulF, &[38, 224, 264], 402);
                step(f, Op::GreaterF, &[264, 813, 31], 403);
                step(f, Op::DivF, &[49, 224, 261], 404);
                step(f, Op::FloatLerp, &[813, 815, 38, 262], 405);
                step(f, Op::SubF, &[815, 262, 263], 406);
                step(f, Op::DivF, &[263, 262, 265], 407);
                step(f, Op::DivF, &[815, 264, 266], 408);
                step(f, Op::SubF, &[265, 266, 267], 409);
                step(f, Op::AddF, &[261, 267, 268], 410);
                step(f, Op::Select(ValueType::Float), &[31, 268, 813, 269], 411);
                step(f, Op::MulF, &[249, 269, 270], 412);
                step(f, Op::AddF, &[228, 270, 271], 413);
                step(f, Op::SinF, &[271, 272], 414);
                step(f, Op::NegF, &[272, 273], 415);
                step(f, Op::CosF, &[271, 274], 416);
                step(f, Op::MakeVector, &[273, 274, 813, 75], 417);
                step(f, Op::Select(ValueType::Vec3), &[23, 75, 421, 76], 418);
                step(f, Op::MovementAngleOffset, &[76, 14, 813, 38, 39, 821, 823, 822, 275], 419);
                step(f, Op::Copy(ValueType::Float), &[275, 14], 420);
                step(f, Op::Jump, &[456], 421)
            }
            421 => {
                step(f, Op::DeltaTime, &[224], 422);
                step(f, Op::DivF, &[224, 41, 276], 423);
                step(f, Op::AddF, &[276, 814, 277], 424);
                step(f, Op::FloorF, &[277, 278], 425);
                step(f, Op::MaxF, &[278, 815, 279], 426);
                step(f, Op::ToInt, &[279, 36], 427);
                step(f, Op::Copy(ValueType::Int), &[36, 35], 428);
                step(f, Op::Copy(ValueType::Int), &[71, 31], 429);
                step(f, Op::MulF, &[41, 814, 283], 430);
                step(f, Op::SubF, &[49, 283, 284], 431);
                step(f, Op::DivF, &[284, 224, 285], 432);
                step(f, Op::FloatLerp, &[813, 815, 36, 287], 433);
                step(f, Op::GreaterF, &[287, 813, 32], 434);
                step(f, Op::DivF, &[38, 279, 297], 435);
                step(f, Op::DivF, &[39, 279, 298], 436);
                436
            }
            436 => {
                step(f, Op::ForNext, &[31, 35, 33, 456], 437)
            }
            437 => {
                step(f, Op::ToFloat, &[33, 280], 438);
                step(f, Op::AddF, &[280, 815, 281], 439);
                step(f, Op::DivF, &[281, 279, 282], 440);
                step(f, Op::AddF, &[282, 285, 286], 441);
                step(f, Op::MulF, &[36, 286, 288], 442);
                step(f, Op::FloatLerp, &[813, 815, 288, 289], 443);
                step(f, Op::DivF, &[289, 287, 290], 444);
                step(f, Op::Select(ValueType::Float), &[32, 290, 286, 291], 445);
                step(f, Op::LerpV, &[4, 2, 291, 77], 446);
                step(f, Op::LengthV, &[77, 292], 447);
                step(f, Op::GreaterF, &[292, 29, 33], 448);
                step(f, Op::Select(ValueType::Vec3), &[33, 77, 421, 78], 449);
                step(f, Op::MulF, &[224, 286, 293], 450);
                step(f, Op::MulF, &[8, 293, 294], 451);
                step(f, Op::AddF, &[12, 294, 295], 452);
                step(f, Op::FractF, &[295, 296], 453);
                step(f, Op::MovementAngleOffset, &[78, 14, 296, 297, 298, 821, 40, 822, 299], 454);
                step(f, Op::Copy(ValueType::Float), &[299, 14], 455);
                step(f, Op::Jump, &[436], 456)
            }
            456 => {
                step(f, Op::QuatFromAxisAngle, &[424, 14, 12], 457);
                step(f, Op::Copy(ValueType::Quat), &[12, 0], 458);
                step(f, Op::SinF, &[14, 300], 459);
                step(f, Op::AbsF, &[300, 301], 460);
                step(f, Op::RemapF, &[301, 42, 43, 813, 815, 98, 302], 461);
                step(f, Op::Copy(ValueType::Float), &[302, 15], 462);
                step(f, Op::Copy(ValueType::Vec3), &[2, 4], 463);
                step(f, Op::Copy(ValueType::Bool), &[99, 35], 464);
                step(f, Op::Copy(ValueType::Bool), &[98, 36], 465);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 466);
                step(f, Op::Copy(ValueType::Int), &[71, 40], 467);
                467
            }
            467 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 40, 37, 41, 42, 473], 468)
            }
            468 => {
                step(f, Op::Not, &[37, 38], 469);
                step(f, Op::JumpIfFalse, &[38, 472], 470)
            }
            470 => {
                step(f, Op::Copy(ValueType::Bool), &[99, 36], 471);
                step(f, Op::Jump, &[472], 472)
            }
            472 => {
                step(f, Op::Jump, &[467], 473)
            }
            473 => {
                step(f, Op::Copy(ValueType::Bool), &[36, 35], 474);
                step(f, Op::Jump, &[475], 475)
            }
            475 => {
                step(f, Op::Copy(ValueType::Bool), &[99, 39], 476);
                step(f, Op::Copy(ValueType::Bool), &[98, 40], 477);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 478);
                step(f, Op::Copy(ValueType::Int), &[71, 43], 479);
                479
            }
            479 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 43, 15, 44, 45, 494], 480)
            }
            480 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 44, 23], 481);
                step(f, Op::BreakTransform, &[23, 79, 13, 80], 482);
                step(f, Op::BreakVector, &[79, 311, 312, 313], 483);
                step(f, Op::MakeVector, &[311, 312, 813, 83], 484);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 44, 24], 485);
                step(f, Op::BreakTransform, &[24, 81, 14, 82], 486);
                step(f, Op::BreakVector, &[81, 314, 315, 316], 487);
                step(f, Op::MakeVector, &[314, 315, 813, 84], 488);
                step(f, Op::DistanceV, &[83, 84, 317], 489);
                step(f, Op::GreaterF, &[317, 31, 41], 490);
                step(f, Op::JumpIfFalse, &[41, 493], 491)
            }
            491 => {
                step(f, Op::Copy(ValueType::Bool), &[99, 40], 492);
                step(f, Op::Jump, &[493], 493)
            }
            493 => {
                step(f, Op::Jump, &[479], 494)
            }
            494 => {
                step(f, Op::Copy(ValueType::Bool), &[40, 39], 495);
                step(f, Op::Jump, &[496], 496)
            }
            496 => {
                step(f, Op::And, &[35, 39, 42], 497);
                step(f, Op::LengthV, &[2, 303], 498);
                step(f, Op::GreaterF, &[303, 29, 34], 499);
                step(f, Op::GreaterF, &[0, 29, 43], 500);
                step(f, Op::Or, &[34, 43, 44], 501);
                step(f, Op::Not, &[44, 45], 502);
                step(f, Op::And, &[42, 45, 50], 503);
                step(f, Op::DeltaTime, &[342], 504);
                step(f, Op::MulF, &[342, 34, 343], 505);
                step(f, Op::AddF, &[12, 343, 344], 506);
                step(f, Op::GreaterF, &[12, 814, 51], 507);
                step(f, Op::AddF, &[33, 814, 340], 508);
                step(f, Op::Select(ValueType::Float), &[51, 340, 33, 341], 509);
                step(f, Op::MinF, &[344, 341, 345], 510);
                step(f, Op::NotEquals(Elem::Bool), &[45, 4, 46], 511);
                step(f, Op::Not, &[42, 47], 512);
                step(f, Op::And, &[46, 47, 48], 513);
                step(f, Op::SubF, &[13, 29, 326], 514);
                step(f, Op::SubF, &[13, 303, 327], 515);
                step(f, Op::DivF, &[326, 327, 328], 516);
                step(f, Op::ClampF, &[328, 813, 815, 329], 517);
                step(f, Op::MulF, &[8, 329, 331], 518);
                step(f, Op::RemapF, &[303, 29, 30, 813, 815, 98, 318], 519);
                step(f, Op::MaxF, &[318, 9, 319], 520);
                step(f, Op::Select(ValueType::Float), &[35, 815, 319, 320], 521);
                step(f, Op::Select(ValueType::Float), &[45, 32, 320, 321], 522);
                step(f, Op::Select(ValueType::Float), &[42, 318, 321, 322], 523);
                step(f, Op::SubF, &[815, 21, 323], 524);
                step(f, Op::MulF, &[322, 323, 324], 525);
                step(f, Op::LerpF, &[23, 45, 15, 306], 526);
                step(f, Op::RemapF, &[303, 26, 27, 24, 25, 98, 304], 527);
                step(f, Op::LerpF, &[304, 44, 15, 305], 528);
                step(f, Op::MaxF, &[303, 28, 307], 529);
                step(f, Op::DivF, &[305, 307, 308], 530);
                step(f, Op::AddF, &[306, 308, 309], 531);
                step(f, Op::DivF, &[324, 309, 325], 532);
                step(f, Op::SubF, &[815, 329, 330], 533);
                step(f, Op::MulF, &[325, 330, 332], 534);
                step(f, Op::AddF, &[331, 332, 333], 535);
                step(f, Op::MulF, &[333, 818, 334], 536);
                step(f, Op::AddF, &[8, 325, 335], 537);
                step(f, Op::Select(ValueType::Float), &[48, 334, 335, 336], 538);
                step(f, Op::DivF, &[818, 336, 337], 539);
                step(f, Op::GreaterF, &[336, 813, 49], 540);
                step(f, Op::CycleStep, &[12, 337, 813, 49, 338, 339], 541);
                step(f, Op::Select(ValueType::Float), &[50, 345, 338, 346], 542);
                step(f, Op::Copy(ValueType::Float), &[346, 12], 543);
                step(f, Op::Copy(ValueType::Float), &[325, 8], 544);
                step(f, Op::Copy(ValueType::Bool), &[34, 3], 545);
                step(f, Op::Copy(ValueType::Float), &[308, 6], 546);
                step(f, Op::Copy(ValueType::Float), &[309, 7], 547);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 548);
                step(f, Op::Copy(ValueType::Int), &[71, 37], 549);
                step(f, Op::DivF, &[306, 309, 310], 550);
                step(f, Op::MulF, &[11, 329, 352], 551);
                step(f, Op::MulF, &[342, 814, 358], 552);
                step(f, Op::SubF, &[310, 10, 363], 553);
                step(f, Op::MaxF, &[363, 813, 364], 554);
                step(f, Op::DivF, &[364, 310, 365], 555);
                step(f, Op::SubF, &[815, 15, 367], 556);
                step(f, Op::DivF, &[49, 342, 372], 557);
                step(f, Op::SubF, &[814, 372, 373], 558);
                step(f, Op::MulF, &[365, 367, 374], 559);
                step(f, Op::MulF, &[374, 323, 375], 560);
                step(f, Op::MulF, &[375, 119, 376], 561);
                step(f, Op::MulF, &[376, 373, 377], 562);
                step(f, Op::SubF, &[815, 377, 378], 563);
                563
            }
            563 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 37, 14, 38, 39, 608], 564)
            }
            564 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 38, 360], 565);
                step(f, Op::ToFloat, &[38, 347], 566);
                step(f, Op::MulF, &[347, 814, 348], 567);
                step(f, Op::AddF, &[12, 348, 349], 568);
                step(f, Op::FractF, &[349, 350], 569);
                step(f, Op::SubF, &[360, 350, 362], 570);
                step(f, Op::GreaterF, &[362, 814, 52], 571);
                step(f, Op::ArrayAt(Elem::Float), &[2, 38, 361], 572);
                step(f, Op::Select(ValueType::Float), &[52, 813, 361, 389], 573);
                step(f, Op::ArraySetAt(Elem::Float), &[3, 38, 389], 574);
                step(f, Op::SubF, &[815, 360, 383], 575);
                step(f, Op::AddF, &[350, 383, 384], 576);
                step(f, Op::DivF, &[350, 384, 385], 577);
                step(f, Op::MaxF, &[318, 9, 319], 578);
                step(f, Op::Select(ValueType::Float), &[35, 815, 319, 320], 579);
                step(f, Op::Select(ValueType::Float), &[45, 32, 320, 321], 580);
                step(f, Op::Select(ValueType::Float), &[42, 318, 321, 322], 581);
                step(f, Op::MulF, &[322, 323, 324], 582);
                step(f, Op::DivF, &[324, 306, 351], 583);
                step(f, Op::MulF, &[351, 330, 353], 584);
                step(f, Op::AddF, &[352, 353, 354], 585);
                step(f, Op::MulF, &[354, 818, 355], 586);
                step(f, Op::AddF, &[11, 351, 356], 587);
                step(f, Op::Select(ValueType::Float), &[48, 355, 356, 357], 588);
                step(f, Op::MulF, &[357, 358, 359], 589);
                step(f, Op::MulF, &[385, 359, 386], 590);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 38, 53], 591);
                step(f, Op::MulF, &[359, 378, 379], 592);
                step(f, Op::Select(ValueType::Float), &[53, 359, 379, 380], 593);
                step(f, Op::MulF, &[365, 361, 366], 594);
                step(f, Op::MulF, &[366, 367, 368], 595);
                step(f, Op::MulF, &[368, 323, 369], 596);
                step(f, Op::MulF, &[369, 119, 370], 597);
                step(f, Op::Select(ValueType::Float), &[53, 813, 370, 371], 598);
                step(f, Op::SubF, &[380, 371, 381], 599);
                step(f, Op::AddF, &[361, 381, 382], 600);
                step(f, Op::Select(ValueType::Float), &[52, 386, 382, 387], 601);
                step(f, Op::MinF, &[387, 818, 388], 602);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 38, 388], 603);
                step(f, Op::JumpIfFalse, &[52, 606], 604)
            }
            604 => {
                step(f, Op::Copy(ValueType::Float), &[322, 9], 605);
                step(f, Op::Jump, &[606], 606)
            }
            606 => {
                step(f, Op::ArraySetAt(Elem::Float), &[0, 38, 350], 607);
                step(f, Op::Jump, &[563], 608)
            }
            608 => {
                step(f, Op::Copy(ValueType::Float), &[310, 10], 609);
                step(f, Op::Copy(ValueType::Bool), &[45, 4], 610);
                step(f, Op::Copy(ValueType::Float), &[303, 13], 611);
                step(f, Op::MaxF, &[318, 9, 319], 612);
                step(f, Op::Select(ValueType::Float), &[35, 815, 319, 320], 613);
                step(f, Op::Select(ValueType::Float), &[45, 32, 320, 321], 614);
                step(f, Op::Select(ValueType::Float), &[42, 318, 321, 322], 615);
                step(f, Op::MulF, &[322, 323, 324], 616);
                step(f, Op::DivF, &[324, 306, 351], 617);
                step(f, Op::Copy(ValueType::Float), &[351, 11], 618);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 619);
                step(f, Op::Copy(ValueType::Int), &[71, 2], 620);
                620
            }
            620 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 2, 0, 3, 4, 1269], 621)
            }
            621 => {
                step(f, Op::Copy(ValueType::Bone), &[0, 16], 622);
                step(f, Op::Copy(ValueType::Int), &[3, 46], 623);
                step(f, Op::GetTransform, &[35, 71, 98, 25], 624);
                step(f, Op::BreakTransform, &[25, 87, 15, 88], 625);
                step(f, Op::BreakVector, &[87, 401, 402, 403], 626);
                step(f, Op::SubF, &[815, 15, 399], 627);
                step(f, Op::MulF, &[14, 399, 400], 628);
                step(f, Op::QuatFromAxisAngle, &[424, 400, 17], 629);
                step(f, Op::GetTransform, &[16, 71, 98, 26], 630);
                step(f, Op::BreakTransform, &[26, 89, 16, 90], 631);
                step(f, Op::SubV, &[89, 87, 91], 632);
                step(f, Op::BreakVector, &[91, 396, 397, 398], 633);
                step(f, Op::MakeVector, &[396, 397, 813, 92], 634);
                step(f, Op::RotateVector, &[17, 92, 93], 635);
                step(f, Op::BreakVector, &[93, 404, 405, 406], 636);
                step(f, Op::MulF, &[46, 15, 407], 637);
                step(f, Op::Equals(Elem::Int), &[46, 71, 54], 638);
                step(f, Op::Select(ValueType::Float), &[54, 815, 817, 416], 639);
                step(f, Op::MulF, &[407, 416, 408], 640);
                step(f, Op::AddF, &[404, 408, 409], 641);
                step(f, Op::AddF, &[401, 409, 410], 642);
                step(f, Op::AddF, &[402, 405, 411], 643);
                step(f, Op::BreakVector, &[89, 412, 413, 414], 644);
                step(f, Op::SubF, &[414, 50, 415], 645);
                step(f, Op::MakeVector, &[410, 411, 415, 94], 646);
                step(f, Op::ArrayAt(Elem::Float), &[2, 46, 390], 647);
                step(f, Op::SubF, &[815, 390, 391], 648);
                step(f, Op::MaxF, &[391, 813, 392], 649);
                step(f, Op::MulF, &[10, 7, 393], 650);
                step(f, Op::MulF, &[392, 393, 394], 651);
                step(f, Op::ScaleV, &[2, 394, 85], 652);
                step(f, Op::AddV, &[94, 85, 95], 653);
                step(f, Op::MulF, &[6, 814, 395], 654);
                step(f, Op::ScaleV, &[2, 395, 86], 655);
                step(f, Op::AddV, &[95, 86, 96], 656);
                step(f, Op::RotateVector, &[0, 425, 97], 657);
                step(f, Op::Copy(ValueType::Vec3), &[96, 118], 658);
                step(f, Op::Copy(ValueType::Vec3), &[97, 119], 659);
                step(f, Op::Copy(ValueType::Float), &[416, 435], 660);
                step(f, Op::Copy(ValueType::Vec3), &[421, 120], 661);
                step(f, Op::Copy(ValueType::Vec3), &[421, 121], 662);
                step(f, Op::Copy(ValueType::Bool), &[99, 56], 663);
                step(f, Op::Copy(ValueType::Float), &[820, 436], 664);
                step(f, Op::Copy(ValueType::Vec3), &[421, 122], 665);
                step(f, Op::Copy(ValueType::Vec3), &[424, 123], 666);
                step(f, Op::Copy(ValueType::Bool), &[99, 57], 667);
                step(f, Op::Copy(ValueType::Float), &[820, 437], 668);
                step(f, Op::Copy(ValueType::Vec3), &[421, 124], 669);
                step(f, Op::MulI, &[0, 0, 52], 670);
                step(f, Op::Copy(ValueType::Int), &[52, 51], 671);
                step(f, Op::Copy(ValueType::Int), &[71, 47], 672);
                step(f, Op::SubI, &[0, 72, 55], 673);
                step(f, Op::DivI, &[55, 73, 56], 674);
                step(f, Op::MakeVector, &[813, 813, 55, 129], 675);
                step(f, Op::ScaleV, &[119, 58, 134], 676);
                676
            }
            676 => {
                step(f, Op::ForNext, &[47, 51, 49, 724], 677)
            }
            677 => {
                step(f, Op::ModI, &[49, 0, 53], 678);
                step(f, Op::ToFloat, &[53, 438], 679);
                step(f, Op::MulF, &[438, 56, 440], 680);
                step(f, Op::MulF, &[440, 435, 441], 681);
                step(f, Op::MakeVector, &[441, 813, 813, 125], 682);
                step(f, Op::DivI, &[49, 0, 54], 683);
                step(f, Op::SubI, &[54, 56, 57], 684);
                step(f, Op::ToFloat, &[57, 439], 685);
                step(f, Op::MulF, &[439, 56, 442], 686);
                step(f, Op::ScaleV, &[119, 442, 126], 687);
                step(f, Op::AddV, &[125, 126, 127], 688);
                step(f, Op::AddV, &[118, 127, 128], 689);
                step(f, Op::AddV, &[128, 129, 130], 690);
                step(f, Op::SubV, &[128, 129, 131], 691);
                step(f, Op::SphereTrace, &[130, 131, 54, 58, 132, 133, 443], 692);
                step(f, Op::BreakVector, &[132, 445, 446, 447], 693);
                step(f, Op::AddV, &[130, 134, 135], 694);
                step(f, Op::AddV, &[131, 134, 136], 695);
                step(f, Op::SphereTrace, &[135, 136, 54, 59, 137, 138, 444], 696);
                step(f, Op::BreakVector, &[137, 448, 449, 450], 697);
                step(f, Op::SubF, &[447, 450, 451], 698);
                step(f, Op::AbsF, &[451, 452], 699);
                step(f, Op::Select(ValueType::Float), &[58, 813, 815, 453], 700);
                step(f, Op::AddF, &[452, 453, 458], 701);
                step(f, Op::LengthV, &[127, 454], 702);
                step(f, Op::RemapF, &[454, 813, 826, 813, 815, 98, 455], 703);
                step(f, Op::MinF, &[447, 450, 456], 704);
                step(f, Op::RemapF, &[456, 827, 826, 815, 814, 98, 457], 705);
                step(f, Op::AddF, &[455, 457, 459], 706);
                step(f, Op::AddF, &[458, 459, 460], 707);
                step(f, Op::LessF, &[460, 436, 60], 708);
                step(f, Op::And, &[58, 60, 61], 709);
                step(f, Op::JumpIfFalse, &[61, 717], 710)
            }
            710 => {
                step(f, Op::Copy(ValueType::Float), &[436, 437], 711);
                step(f, Op::Copy(ValueType::Vec3), &[122, 124], 712);
                step(f, Op::Copy(ValueType::Float), &[460, 436], 713);
                step(f, Op::Copy(ValueType::Vec3), &[132, 122], 714);
                step(f, Op::Copy(ValueType::Vec3), &[133, 123], 715);
                step(f, Op::Copy(ValueType::Bool), &[98, 57], 716);
                step(f, Op::Jump, &[723], 717)
            }
            717 => {
                step(f, Op::LessF, &[460, 437, 62], 718);
                step(f, Op::And, &[58, 62, 63], 719);
                step(f, Op::JumpIfFalse, &[63, 723], 720)
            }
            720 => {
                step(f, Op::Copy(ValueType::Float), &[460, 437], 721);
                step(f, Op::Copy(ValueType::Vec3), &[132, 124], 722);
                step(f, Op::Jump, &[723], 723)
            }
            723 => {
                step(f, Op::Jump, &[676], 724)
            }
            724 => {
                step(f, Op::JumpIfFalse, &[8, 727], 725)
            }
            725 => {
                step(f, Op::DrawSphere, &[122, 54, 425], 726);
                step(f, Op::Jump, &[727], 727)
            }
            727 => {
                step(f, Op::GreaterF, &[57, 813, 64], 728);
                step(f, Op::SubF, &[436, 437, 461], 729);
                step(f, Op::DivF, &[461, 57, 462], 730);
                step(f, Op::PowF, &[828, 462, 463], 731);
                step(f, Op::Select(ValueType::Float), &[64, 463, 813, 464], 732);
                step(f, Op::ScaleV, &[124, 464, 139], 733);
                step(f, Op::AddV, &[122, 139, 140], 734);
                step(f, Op::AddF, &[464, 815, 465], 735);
                step(f, Op::DivF, &[815, 465, 466], 736);
                step(f, Op::ScaleV, &[140, 466, 141], 737);
                step(f, Op::Copy(ValueType::Vec3), &[141, 120], 738);
                step(f, Op::Copy(ValueType::Vec3), &[123, 121], 739);
                step(f, Op::Copy(ValueType::Bool), &[57, 56], 740);
                step(f, Op::Jump, &[741], 741)
            }
            741 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 46, 27], 742);
                step(f, Op::BreakTransform, &[27, 99, 21, 100], 743);
                step(f, Op::ArrayAt(Elem::Float), &[2, 46, 390], 744);
                step(f, Op::SubF, &[815, 390, 391], 745);
                step(f, Op::MaxF, &[391, 813, 392], 746);
                step(f, Op::MulF, &[10, 7, 393], 747);
                step(f, Op::MulF, &[392, 393, 394], 748);
                step(f, Op::ScaleV, &[2, 394, 85], 749);
                step(f, Op::SubV, &[120, 85, 98], 750);
                step(f, Op::Select(ValueType::Vec3), &[56, 98, 99, 101], 751);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 46, 28], 752);
                step(f, Op::BreakTransform, &[28, 102, 23, 103], 753);
                step(f, Op::Copy(ValueType::Vec3), &[99, 104], 754);
                step(f, Op::Copy(ValueType::Vec3), &[101, 105], 755);
                step(f, Op::Copy(ValueType::Vec3), &[102, 106], 756);
                step(f, Op::Copy(ValueType::Float), &[47, 422], 757);
                step(f, Op::Copy(ValueType::Float), &[49, 423], 758);
                step(f, Op::Copy(ValueType::Vec3), &[421, 107], 759);
                step(f, Op::SubV, &[105, 106, 108], 760);
                step(f, Op::DeltaTime, &[424], 761);
                step(f, Op::DivF, &[423, 424, 425], 762);
                step(f, Op::ScaleV, &[108, 425, 109], 763);
                step(f, Op::AddV, &[105, 109, 110], 764);
                step(f, Op::AddV, &[106, 109, 111], 765);
                step(f, Op::SubV, &[104, 111, 112], 766);
                step(f, Op::FloatLerp, &[813, 815, 422, 426], 767);
                step(f, Op::SubF, &[815, 426, 427], 768);
                step(f, Op::ScaleV, &[112, 427, 113], 769);
                step(f, Op::AddV, &[110, 113, 115], 770);
                step(f, Op::MulF, &[422, 424, 428], 771);
                step(f, Op::GreaterF, &[428, 813, 55], 772);
                step(f, Op::DivF, &[426, 428, 429], 773);
                step(f, Op::Select(ValueType::Float), &[55, 429, 815, 430], 774);
                step(f, Op::ScaleV, &[108, 430, 114], 775);
                step(f, Op::SubV, &[115, 114, 116], 776);
                step(f, Op::Copy(ValueType::Vec3), &[116, 107], 777);
                step(f, Op::Jump, &[778], 778)
            }
            778 => {
                step(f, Op::BreakVector, &[107, 431, 432, 433], 779);
                step(f, Op::ClampF, &[433, 59, 60, 434], 780);
                step(f, Op::MakeVector, &[431, 432, 434, 117], 781);
                step(f, Op::RotationFromNormal, &[121, 420, 421, 19], 782);
                step(f, Op::PerFootRotationFactor, &[14, 96, 97, 417], 783);
                step(f, Op::MulF, &[14, 417, 418], 784);
                step(f, Op::SubF, &[815, 15, 399], 785);
                step(f, Op::MulF, &[418, 399, 419], 786);
                step(f, Op::QuatFromAxisAngle, &[424, 419, 18], 787);
                step(f, Op::MulQ, &[19, 18, 20], 788);
                step(f, Op::Select(ValueType::Quat), &[56, 20, 21, 22], 789);
                step(f, Op::MakeTransform, &[117, 22, 422, 30], 790);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 46, 30], 791);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 46, 27], 792);
                step(f, Op::BreakTransform, &[27, 99, 21, 100], 793);
                step(f, Op::Select(ValueType::Vec3), &[56, 98, 99, 101], 794);
                step(f, Op::MakeTransform, &[101, 92, 422, 29], 795);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 46, 29], 796);
                step(f, Op::JumpIfFalse, &[56, 799], 797)
            }
            797 => {
                step(f, Op::Copy(ValueType::Bool), &[98, 7], 798);
                step(f, Op::Jump, &[799], 799)
            }
            799 => {
                step(f, Op::Copy(ValueType::Int), &[3, 58], 800);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 58, 33], 801);
                step(f, Op::GreaterF, &[21, 813, 68], 802);
                step(f, Op::InterpolateTransform, &[2, 112, 22, 31], 803);
                step(f, Op::Select(ValueType::Transform), &[68, 31, 2, 32], 804);
                step(f, Op::MakeAbsolute, &[33, 32, 34], 805);
                step(f, Op::BreakTransform, &[34, 142, 24, 143], 806);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 58, 35], 807);
                step(f, Op::BreakTransform, &[35, 144, 25, 145], 808);
                step(f, Op::AddF, &[63, 64, 468], 809);
                step(f, Op::ClampSpatially, &[142, 144, 813, 468, 146], 810);
                step(f, Op::SubF, &[815, 15, 483], 811);
                step(f, Op::MulF, &[14, 483, 469], 812);
                step(f, Op::LimitRotationAroundZ, &[24, 469, 95, 26], 813);
                step(f, Op::MakeTransform, &[146, 26, 422, 36], 814);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 58, 36], 815);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 58, 65], 816);
                step(f, Op::JumpIfFalse, &[65, 870], 817)
            }
            817 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 58, 39], 818);
                step(f, Op::BreakTransform, &[39, 152, 28, 153], 819);
                step(f, Op::ArrayAt(Elem::Float), &[2, 58, 467], 820);
                step(f, Op::SubF, &[815, 467, 480], 821);
                step(f, Op::MulF, &[10, 7, 481], 822);
                step(f, Op::MulF, &[480, 481, 482], 823);
                step(f, Op::ScaleV, &[2, 482, 154], 824);
                step(f, Op::AddV, &[152, 154, 155], 825);
                step(f, Op::MakeTransform, &[155, 28, 422, 46], 826);
                step(f, Op::Copy(ValueType::Transform), &[46, 47], 827);
                step(f, Op::Copy(ValueType::Transform), &[112, 48], 828);
                step(f, Op::BreakTransform, &[47, 183, 33, 184], 829);
                step(f, Op::MakeVector, &[813, 813, 55, 185], 830);
                step(f, Op::AddV, &[183, 185, 186], 831);
                step(f, Op::SubV, &[183, 185, 187], 832);
                step(f, Op::LineTrace, &[186, 187, 72, 188, 189, 510], 833);
                step(f, Op::RotateVector, &[33, 424, 190], 834);
                step(f, Op::FindQuatBetween, &[190, 189, 34], 835);
                step(f, Op::MulQ, &[34, 33, 35], 836);
                step(f, Op::MulF, &[53, 52, 511], 837);
                step(f, Op::AddF, &[511, 62, 512], 838);
                step(f, Op::NegF, &[512, 513], 839);
                step(f, Op::MakeVector, &[813, 513, 813, 191], 840);
                step(f, Op::RotateVector, &[35, 191, 193], 841);
                step(f, Op::AddV, &[188, 193, 195], 842);
                step(f, Op::AddV, &[195, 185, 197], 843);
                step(f, Op::SubV, &[195, 185, 198], 844);
                step(f, Op::LineTrace, &[197, 198, 73, 201, 202, 515], 845);
                step(f, Op::BreakVector, &[201, 517, 518, 519], 846);
                step(f, Op::BreakVector, &[195, 523, 524, 525], 847);
                step(f, Op::SubF, &[519, 525, 529], 848);
                step(f, Op::Select(ValueType::Float), &[73, 529, 813, 531], 849);
                step(f, Op::AddF, &[58, 62, 514], 850);
                step(f, Op::MakeVector, &[813, 514, 813, 192], 851);
                step(f, Op::RotateVector, &[35, 192, 194], 852);
                step(f, Op::AddV, &[188, 194, 196], 853);
                step(f, Op::AddV, &[196, 185, 199], 854);
                step(f, Op::SubV, &[196, 185, 200], 855);
                step(f, Op::LineTrace, &[199, 200, 74, 203, 204, 516], 856);
                step(f, Op::BreakVector, &[203, 520, 521, 522], 857);
                step(f, Op::BreakVector, &[196, 526, 527, 528], 858);
                step(f, Op::SubF, &[522, 528, 530], 859);
                step(f, Op::Select(ValueType::Float), &[74, 530, 813, 532], 860);
                step(f, Op::MaxF, &[531, 532, 533], 861);
                step(f, Op::ClampF, &[533, 813, 61, 534], 862);
                step(f, Op::MakeVector, &[813, 813, 534, 205], 863);
                step(f, Op::AddV, &[188, 205, 206], 864);
                step(f, Op::MakeTransform, &[206, 35, 422, 49], 865);
                step(f, Op::Select(ValueType::Transform), &[72, 49, 47, 50], 866);
                step(f, Op::Copy(ValueType::Transform), &[50, 48], 867);
                step(f, Op::Jump, &[868], 868)
            }
            868 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 58, 48], 869);
                step(f, Op::Jump, &[971], 870)
            }
            870 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 58, 51], 871);
                step(f, Op::MakeAbsolute, &[51, 32, 52], 872);
                step(f, Op::BreakTransform, &[52, 207, 36, 208], 873);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 58, 39], 874);
                step(f, Op::BreakTransform, &[39, 152, 28, 153], 875);
                step(f, Op::ArrayAt(Elem::Float), &[2, 58, 467], 876);
                step(f, Op::SubF, &[815, 467, 480], 877);
                step(f, Op::MulF, &[10, 7, 481], 878);
                step(f, Op::MulF, &[480, 481, 482], 879);
                step(f, Op::ScaleV, &[2, 482, 154], 880);
                step(f, Op::AddV, &[152, 154, 155], 881);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 58, 53], 882);
                step(f, Op::MakeAbsolute, &[53, 32, 54], 883);
                step(f, Op::BreakTransform, &[54, 209, 37, 210], 884);
                step(f, Op::ArrayAt(Elem::Float), &[3, 58, 535], 885);
                step(f, Op::SubF, &[467, 535, 536], 886);
                step(f, Op::DeltaTime, &[551], 887);
                step(f, Op::DivF, &[49, 551, 537], 888);
                step(f, Op::MulF, &[536, 537, 538], 889);
                step(f, Op::AddF, &[535, 538, 539], 890);
                step(f, Op::ClampF, &[539, 813, 815, 541], 891);
                step(f, Op::AddF, &[467, 538, 540], 892);
                step(f, Op::ClampF, &[540, 813, 815, 542], 893);
                step(f, Op::AddF, &[541, 542, 543], 894);
                step(f, Op::MulF, &[543, 814, 544], 895);
                step(f, Op::SubF, &[815, 544, 545], 896);
                step(f, Op::GreaterF, &[536, 813, 75], 897);
                step(f, Op::SubF, &[542, 541, 546], 898);
                step(f, Op::DivF, &[546, 536, 547], 899);
                step(f, Op::Select(ValueType::Float), &[75, 547, 815, 548], 900);
                step(f, Op::MulF, &[545, 548, 549], 901);
                step(f, Op::MulF, &[79, 549, 550], 902);
                step(f, Op::Copy(ValueType::Vec3), &[207, 211], 903);
                step(f, Op::Copy(ValueType::Vec3), &[155, 212], 904);
                step(f, Op::Copy(ValueType::Vec3), &[209, 213], 905);
                step(f, Op::Copy(ValueType::Float), &[550, 552], 906);
                step(f, Op::Copy(ValueType::Float), &[49, 553], 907);
                step(f, Op::Copy(ValueType::Vec3), &[421, 214], 908);
                step(f, Op::SubV, &[212, 213, 215], 909);
                step(f, Op::DeltaTime, &[554], 910);
                step(f, Op::DivF, &[553, 554, 555], 911);
                step(f, Op::ScaleV, &[215, 555, 216], 912);
                step(f, Op::AddV, &[212, 216, 217], 913);
                step(f, Op::AddV, &[213, 216, 218], 914);
                step(f, Op::SubV, &[211, 218, 219], 915);
                step(f, Op::FloatLerp, &[813, 815, 552, 556], 916);
                step(f, Op::SubF, &[815, 556, 557], 917);
                step(f, Op::ScaleV, &[219, 557, 220], 918);
                step(f, Op::AddV, &[217, 220, 222], 919);
                step(f, Op::MulF, &[552, 554, 558], 920);
                step(f, Op::GreaterF, &[558, 813, 76], 921);
                step(f, Op::DivF, &[556, 558, 559], 922);
                step(f, Op::Select(ValueType::Float), &[76, 559, 815, 560], 923);
                step(f, Op::ScaleV, &[215, 560, 221], 924);
                step(f, Op::SubV, &[222, 221, 223], 925);
                step(f, Op::Copy(ValueType::Vec3), &[223, 214], 926);
                step(f, Op::Jump, &[927], 927)
            }
            927 => {
                step(f, Op::MakeTransform, &[214, 28, 422, 56], 928);
                step(f, Op::Copy(ValueType::Transform), &[56, 57], 929);
                step(f, Op::Copy(ValueType::Transform), &[112, 58], 930);
                step(f, Op::BreakTransform, &[57, 224, 38, 225], 931);
                step(f, Op::MakeVector, &[813, 813, 55, 226], 932);
                step(f, Op::AddV, &[224, 226, 227], 933);
                step(f, Op::SubV, &[224, 226, 228], 934);
                step(f, Op::LineTrace, &[227, 228, 77, 229, 230, 561], 935);
                step(f, Op::RotateVector, &[38, 424, 231], 936);
                step(f, Op::FindQuatBetween, &[231, 230, 39], 937);
                step(f, Op::MulQ, &[39, 38, 40], 938);
                step(f, Op::MulF, &[53, 52, 562], 939);
                step(f, Op::AddF, &[562, 62, 563], 940);
                step(f, Op::NegF, &[563, 564], 941);
                step(f, Op::MakeVector, &[813, 564, 813, 232], 942);
                step(f, Op::RotateVector, &[40, 232, 234], 943);
                step(f, Op::AddV, &[229, 234, 236], 944);
                step(f, Op::AddV, &[236, 226, 238], 945);
                step(f, Op::SubV, &[236, 226, 239], 946);
                step(f, Op::LineTrace, &[238, 239, 78, 242, 243, 566], 947);
                step(f, Op::BreakVector, &[242, 568, 569, 570], 948);
                step(f, Op::BreakVector, &[236, 574, 575, 576], 949);
                step(f, Op::SubF, &[570, 576, 580], 950);
                step(f, Op::Select(ValueType::Float), &[78, 580, 813, 582], 951);
                step(f, Op::AddF, &[58, 62, 565], 952);
                step(f, Op::MakeVector, &[813, 565, 813, 233], 953);
                step(f, Op::RotateVector, &[40, 233, 235], 954);
                step(f, Op::AddV, &[229, 235, 237], 955);
                step(f, Op::AddV, &[237, 226, 240], 956);
                step(f, Op::SubV, &[237, 226, 241], 957);
                step(f, Op::LineTrace, &[240, 241, 79, 244, 245, 567], 958);
                step(f, Op::BreakVector, &[244, 571, 572, 573], 959);
                step(f, Op::BreakVector, &[237, 577, 578, 579], 960);
                step(f, Op::SubF, &[573, 579, 581], 961);
                step(f, Op::Select(ValueType::Float), &[79, 581, 813, 583], 962);
                step(f, Op::MaxF, &[582, 583, 584], 963);
                step(f, Op::ClampF, &[584, 813, 61, 585], 964);
                step(f, Op::MakeVector, &[813, 813, 585, 246], 965);
                step(f, Op::AddV, &[229, 246, 247], 966);
                step(f, Op::MakeTransform, &[247, 40, 422, 59], 967);
                step(f, Op::Select(ValueType::Transform), &[77, 59, 57, 60], 968);
                step(f, Op::Copy(ValueType::Transform), &[60, 58], 969);
                step(f, Op::Jump, &[970], 970)
            }
            970 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 58, 58], 971);
                971
            }
            971 => {
                step(f, Op::GreaterEqualF, &[467, 815, 66], 972);
                step(f, Op::JumpIfFalse, &[66, 1045], 973)
            }
            973 => {
                step(f, Op::JumpIfFalse, &[65, 975], 974)
            }
            974 => {
                step(f, Op::Jump, &[1027], 975)
            }
            975 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 58, 61], 976);
                step(f, Op::BreakTransform, &[61, 248, 41, 249], 977);
                step(f, Op::Equals(Elem::Int), &[58, 71, 67], 978);
                step(f, Op::Select(ValueType::Int), &[67, 72, 71, 59], 979);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 59, 40], 980);
                step(f, Op::BreakTransform, &[40, 156, 29, 157], 981);
                step(f, Op::MulF, &[14, 483, 484], 982);
                step(f, Op::FootAvoidance, &[248, 156, 484, 67, 80, 158], 983);
                step(f, Op::MakeTransform, &[158, 41, 422, 41], 984);
                step(f, Op::Copy(ValueType::Transform), &[41, 42], 985);
                step(f, Op::Copy(ValueType::Transform), &[112, 43], 986);
                step(f, Op::BreakTransform, &[42, 159, 30, 160], 987);
                step(f, Op::MakeVector, &[813, 813, 55, 161], 988);
                step(f, Op::AddV, &[159, 161, 162], 989);
                step(f, Op::SubV, &[159, 161, 163], 990);
                step(f, Op::LineTrace, &[162, 163, 69, 164, 165, 485], 991);
                step(f, Op::RotateVector, &[30, 424, 166], 992);
                step(f, Op::FindQuatBetween, &[166, 165, 31], 993);
                step(f, Op::MulQ, &[31, 30, 32], 994);
                step(f, Op::MulF, &[53, 52, 486], 995);
                step(f, Op::AddF, &[486, 62, 487], 996);
                step(f, Op::NegF, &[487, 488], 997);
                step(f, Op::MakeVector, &[813, 488, 813, 167], 998);
                step(f, Op::RotateVector, &[32, 167, 169], 999);
                step(f, Op::AddV, &[164, 169, 171], 1000);
                step(f, Op::AddV, &[171, 161, 173], 1001);
                step(f, Op::SubV, &[171, 161, 174], 1002);
                step(f, Op::LineTrace, &[173, 174, 70, 177, 178, 490], 1003);
                step(f, Op::BreakVector, &[177, 492, 493, 494], 1004);
                step(f, Op::BreakVector, &[171, 498, 499, 500], 1005);
                step(f, Op::SubF, &[494, 500, 504], 1006);
                step(f, Op::Select(ValueType::Float), &[70, 504, 813, 506], 1007);
                step(f, Op::AddF, &[58, 62, 489], 1008);
                step(f, Op::MakeVector, &[813, 489, 813, 168], 1009);
                step(f, Op::RotateVector, &[32, 168, 170], 1010);
                step(f, Op::AddV, &[164, 170, 172], 1011);
                step(f, Op::AddV, &[172, 161, 175], 1012);
                step(f, Op::SubV, &[172, 161, 176], 1013);
                step(f, Op::LineTrace, &[175, 176, 71, 179, 180, 491], 1014);
                step(f, Op::BreakVector, &[179, 495, 496, 497], 1015);
                step(f, Op::BreakVector, &[172, 501, 502, 503], 1016);
                step(f, Op::SubF, &[497, 503, 505], 1017);
                step(f, Op::Select(ValueType::Float), &[71, 505, 813, 507], 1018);
                step(f, Op::MaxF, &[506, 507, 508], 1019);
                step(f, Op::ClampF, &[508, 813, 61, 509], 1020);
                step(f, Op::MakeVector, &[813, 813, 509, 181], 1021);
                step(f, Op::AddV, &[164, 181, 182], 1022);
                step(f, Op::MakeTransform, &[182, 32, 422, 44], 1023);
                step(f, Op::Select(ValueType::Transform), &[69, 44, 42, 45], 1024);
                step(f, Op::Copy(ValueType::Transform), &[45, 43], 1025);
                step(f, Op::Jump, &[1026], 1026)
            }
            1026 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 58, 43], 1027);
                1027
            }
            1027 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 58, 37], 1028);
                step(f, Op::BreakTransform, &[37, 147, 27, 148], 1029);
                step(f, Op::SubV, &[147, 144, 149], 1030);
                step(f, Op::LengthV, &[149, 470], 1031);
                step(f, Op::SubF, &[63, 64, 471], 1032);
                step(f, Op::SubF, &[470, 471, 472], 1033);
                step(f, Op::MulF, &[64, 818, 473], 1034);
                step(f, Op::ClampF, &[472, 813, 473, 474], 1035);
                step(f, Op::MulF, &[474, 474, 475], 1036);
                step(f, Op::MulF, &[64, 829, 476], 1037);
                step(f, Op::DivF, &[475, 476, 477], 1038);
                step(f, Op::SubF, &[470, 477, 478], 1039);
                step(f, Op::DivF, &[478, 470, 479], 1040);
                step(f, Op::ScaleV, &[149, 479, 150], 1041);
                step(f, Op::AddV, &[144, 150, 151], 1042);
                step(f, Op::MakeTransform, &[151, 27, 422, 38], 1043);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 58, 38], 1044);
                step(f, Op::Jump, &[1176], 1045)
            }
            1045 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 58, 37], 1046);
                step(f, Op::BreakTransform, &[37, 147, 27, 148], 1047);
                step(f, Op::SubV, &[147, 144, 149], 1048);
                step(f, Op::LengthV, &[149, 470], 1049);
                step(f, Op::SubF, &[63, 64, 471], 1050);
                step(f, Op::SubF, &[470, 471, 472], 1051);
                step(f, Op::MulF, &[64, 818, 473], 1052);
                step(f, Op::ClampF, &[472, 813, 473, 474], 1053);
                step(f, Op::MulF, &[474, 474, 475], 1054);
                step(f, Op::MulF, &[64, 829, 476], 1055);
                step(f, Op::DivF, &[475, 476, 477], 1056);
                step(f, Op::SubF, &[470, 477, 478], 1057);
                step(f, Op::DivF, &[478, 470, 479], 1058);
                step(f, Op::ScaleV, &[149, 479, 150], 1059);
                step(f, Op::AddV, &[144, 150, 151], 1060);
                step(f, Op::MakeTransform, &[151, 27, 422, 38], 1061);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 58, 61], 1062);
                step(f, Op::ClampF, &[467, 813, 815, 586], 1063);
                step(f, Op::Copy(ValueType::Transform), &[38, 66], 1064);
                step(f, Op::Copy(ValueType::Transform), &[61, 67], 1065);
                step(f, Op::Copy(ValueType::Float), &[586, 603], 1066);
                step(f, Op::Copy(ValueType::Transform), &[112, 68], 1067);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[3, 2], 1068);
                step(f, Op::ArrayReset(Elem::Vec3), &[2], 1069);
                step(f, Op::BreakTransform, &[66, 266, 46, 267], 1070);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 266], 1071);
                step(f, Op::UnitV, &[2, 265], 1072);
                step(f, Op::LengthV, &[2, 604], 1073);
                step(f, Op::RemapF, &[604, 813, 65, 813, 66, 98, 605], 1074);
                step(f, Op::ScaleV, &[265, 605, 270], 1075);
                step(f, Op::SubV, &[266, 270, 276], 1076);
                step(f, Op::MakeVector, &[813, 813, 68, 274], 1077);
                step(f, Op::AddV, &[276, 274, 278], 1078);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 278], 1079);
                step(f, Op::RemapF, &[604, 813, 65, 813, 70, 98, 607], 1080);
                step(f, Op::MakeVector, &[813, 813, 607, 272], 1081);
                step(f, Op::AddV, &[278, 272, 282], 1082);
                step(f, Op::BreakTransform, &[67, 268, 47, 269], 1083);
                step(f, Op::BreakVector, &[268, 612, 613, 614], 1084);
                step(f, Op::BreakVector, &[266, 609, 610, 611], 1085);
                step(f, Op::SubF, &[614, 611, 615], 1086);
                step(f, Op::MaxF, &[615, 813, 617], 1087);
                step(f, Op::MulF, &[617, 72, 621], 1088);
                step(f, Op::MinF, &[621, 73, 622], 1089);
                step(f, Op::AbsF, &[615, 619], 1090);
                step(f, Op::RemapF, &[619, 813, 76, 813, 75, 98, 620], 1091);
                step(f, Op::AddF, &[622, 620, 624], 1092);
                step(f, Op::MakeVector, &[813, 813, 624, 280], 1093);
                step(f, Op::AddV, &[282, 280, 284], 1094);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 284], 1095);
                step(f, Op::RemapF, &[604, 813, 65, 813, 67, 98, 606], 1096);
                step(f, Op::ScaleV, &[265, 606, 271], 1097);
                step(f, Op::AddV, &[268, 271, 277], 1098);
                step(f, Op::MakeVector, &[813, 813, 69, 275], 1099);
                step(f, Op::AddV, &[277, 275, 279], 1100);
                step(f, Op::RemapF, &[604, 813, 65, 813, 71, 98, 608], 1101);
                step(f, Op::MakeVector, &[813, 813, 608, 273], 1102);
                step(f, Op::AddV, &[279, 273, 283], 1103);
                step(f, Op::NegF, &[615, 616], 1104);
                step(f, Op::MaxF, &[616, 813, 618], 1105);
                step(f, Op::MulF, &[618, 74, 623], 1106);
                step(f, Op::AddF, &[623, 620, 625], 1107);
                step(f, Op::MakeVector, &[813, 813, 625, 281], 1108);
                step(f, Op::AddV, &[283, 281, 285], 1109);
                step(f, Op::LerpV, &[284, 285, 814, 286], 1110);
                step(f, Op::GetTransform, &[36, 71, 98, 69], 1111);
                step(f, Op::BreakTransform, &[69, 287, 48, 288], 1112);
                step(f, Op::BreakVector, &[287, 635, 636, 637], 1113);
                step(f, Op::SubF, &[815, 15, 629], 1114);
                step(f, Op::MulF, &[77, 629, 630], 1115);
                step(f, Op::MulF, &[14, 630, 631], 1116);
                step(f, Op::QuatFromAxisAngle, &[424, 631, 49], 1117);
                step(f, Op::SubV, &[286, 287, 289], 1118);
                step(f, Op::BreakVector, &[289, 626, 627, 628], 1119);
                step(f, Op::MakeVector, &[626, 627, 813, 290], 1120);
                step(f, Op::RotateVector, &[49, 290, 291], 1121);
                step(f, Op::BreakVector, &[291, 632, 633, 634], 1122);
                step(f, Op::AddF, &[635, 632, 641], 1123);
                step(f, Op::AddF, &[636, 633, 642], 1124);
                step(f, Op::BreakVector, &[286, 638, 639, 640], 1125);
                step(f, Op::MakeVector, &[641, 642, 640, 292], 1126);
                step(f, Op::DistanceV, &[266, 268, 643], 1127);
                step(f, Op::RemapF, &[643, 818, 830, 813, 815, 98, 644], 1128);
                step(f, Op::LerpV, &[286, 292, 644, 293], 1129);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 293], 1130);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 285], 1131);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 279], 1132);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 268], 1133);
                step(f, Op::JumpIfFalse, &[8, 1136], 1134)
            }
            1134 => {
                step(f, Op::DrawSpline, &[2, 71, 74, 814, 426], 1135);
                step(f, Op::Jump, &[1136], 1136)
            }
            1136 => {
                step(f, Op::Spline, &[2, 603, 71, 294, 295], 1137);
                step(f, Op::SlerpQ, &[46, 47, 603, 50], 1138);
                step(f, Op::MulF, &[603, 823, 646], 1139);
                step(f, Op::SinF, &[646, 647], 1140);
                step(f, Op::SmoothStepF, &[603, 813, 88, 645], 1141);
                step(f, Op::MulF, &[647, 645, 648], 1142);
                step(f, Op::MulF, &[648, 78, 649], 1143);
                step(f, Op::SlerpQ, &[50, 92, 649, 51], 1144);
                step(f, Op::MakeTransform, &[294, 51, 422, 70], 1145);
                step(f, Op::Copy(ValueType::Transform), &[70, 68], 1146);
                step(f, Op::Jump, &[1147], 1147)
            }
            1147 => {
                step(f, Op::BreakTransform, &[68, 250, 42, 251], 1148);
                step(f, Op::Equals(Elem::Int), &[58, 71, 67], 1149);
                step(f, Op::Select(ValueType::Int), &[67, 72, 71, 59], 1150);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 59, 40], 1151);
                step(f, Op::BreakTransform, &[40, 156, 29, 157], 1152);
                step(f, Op::SubF, &[815, 15, 483], 1153);
                step(f, Op::MulF, &[14, 483, 484], 1154);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 59, 80], 1155);
                step(f, Op::Select(ValueType::Float), &[80, 81, 813, 589], 1156);
                step(f, Op::ArrayAt(Elem::Float), &[2, 58, 467], 1157);
                step(f, Op::ClampF, &[467, 813, 815, 586], 1158);
                step(f, Op::MulF, &[586, 823, 587], 1159);
                step(f, Op::SinF, &[587, 588], 1160);
                step(f, Op::MulF, &[588, 588, 590], 1161);
                step(f, Op::MulF, &[589, 590, 591], 1162);
                step(f, Op::AddF, &[80, 591, 592], 1163);
                step(f, Op::FootAvoidance, &[250, 156, 484, 67, 592, 252], 1164);
                step(f, Op::SubV, &[252, 250, 253], 1165);
                step(f, Op::LengthV, &[253, 593], 1166);
                step(f, Op::AddF, &[593, 591, 594], 1167);
                step(f, Op::DivF, &[593, 594, 595], 1168);
                step(f, Op::ScaleV, &[253, 595, 254], 1169);
                step(f, Op::AddV, &[250, 254, 255], 1170);
                step(f, Op::MulF, &[3, 124, 596], 1171);
                step(f, Op::MulF, &[596, 590, 597], 1172);
                step(f, Op::MakeVector, &[813, 813, 597, 256], 1173);
                step(f, Op::AddV, &[255, 256, 257], 1174);
                step(f, Op::MakeTransform, &[257, 42, 422, 62], 1175);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 58, 62], 1176);
                1176
            }
            1176 => {
                step(f, Op::GreaterF, &[21, 813, 68], 1177);
                step(f, Op::JumpIfFalse, &[68, 1194], 1178)
            }
            1178 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 58, 63], 1179);
                step(f, Op::BreakTransform, &[63, 258, 43, 259], 1180);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 58, 64], 1181);
                step(f, Op::BreakTransform, &[64, 260, 44, 261], 1182);
                step(f, Op::MulF, &[21, 21, 598], 1183);
                step(f, Op::LerpV, &[258, 260, 598, 262], 1184);
                step(f, Op::SubF, &[815, 21, 599], 1185);
                step(f, Op::MulF, &[21, 599, 600], 1186);
                step(f, Op::MulF, &[126, 818, 601], 1187);
                step(f, Op::MulF, &[600, 601, 602], 1188);
                step(f, Op::MakeVector, &[813, 813, 602, 263], 1189);
                step(f, Op::AddV, &[262, 263, 264], 1190);
                step(f, Op::SlerpQ, &[43, 44, 21, 45], 1191);
                step(f, Op::MakeTransform, &[264, 45, 422, 65], 1192);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 58, 65], 1193);
                step(f, Op::Jump, &[1194], 1194)
            }
            1194 => {
                step(f, Op::GreaterEqualF, &[467, 815, 66], 1195);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 58, 66], 1196);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 58, 39], 1197);
                step(f, Op::BreakTransform, &[39, 152, 28, 153], 1198);
                step(f, Op::SubF, &[815, 467, 480], 1199);
                step(f, Op::MulF, &[10, 7, 481], 1200);
                step(f, Op::MulF, &[480, 481, 482], 1201);
                step(f, Op::ScaleV, &[2, 482, 154], 1202);
                step(f, Op::AddV, &[152, 154, 155], 1203);
                step(f, Op::MakeTransform, &[155, 92, 422, 55], 1204);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 58, 55], 1205);
                step(f, Op::Copy(ValueType::Bone), &[0, 17], 1206);
                step(f, Op::Copy(ValueType::Int), &[3, 60], 1207);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 60, 71], 1208);
                step(f, Op::BreakTransform, &[71, 296, 52, 297], 1209);
                step(f, Op::MakeVector, &[813, 813, 50, 306], 1210);
                step(f, Op::AddV, &[296, 306, 307], 1211);
                step(f, Op::GetTransform, &[17, 71, 98, 73], 1212);
                step(f, Op::BreakTransform, &[73, 301, 54, 302], 1213);
                step(f, Op::MakeTransform, &[307, 54, 422, 75], 1214);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 60, 20], 1215);
                step(f, Op::GetTransform, &[20, 71, 98, 74], 1216);
                step(f, Op::BreakTransform, &[74, 303, 55, 304], 1217);
                step(f, Op::SubV, &[303, 301, 305], 1218);
                step(f, Op::AddV, &[307, 305, 308], 1219);
                step(f, Op::FootPivots, &[307, 308, 52, 51, 50, 53, 309, 310, 311], 1220);
                step(f, Op::GetParent, &[17, 18], 1221);
                step(f, Op::GetParent, &[18, 19], 1222);
                step(f, Op::GetTransform, &[19, 71, 99, 72], 1223);
                step(f, Op::BreakTransform, &[72, 298, 53, 299], 1224);
                step(f, Op::SubV, &[296, 298, 300], 1225);
                step(f, Op::DotV, &[300, 425, 650], 1226);
                step(f, Op::RemapF, &[650, 83, 82, 84, 813, 98, 653], 1227);
                step(f, Op::LengthV, &[2, 651], 1228);
                step(f, Op::RemapF, &[651, 813, 94, 813, 815, 98, 652], 1229);
                step(f, Op::MulF, &[653, 652, 654], 1230);
                step(f, Op::QuatFromAxisAngle, &[427, 654, 56], 1231);
                step(f, Op::RotateAroundPoint, &[75, 309, 56, 76], 1232);
                step(f, Op::ArrayAt(Elem::Float), &[2, 60, 655], 1233);
                step(f, Op::SmoothStepF, &[655, 813, 88, 657], 1234);
                step(f, Op::SubF, &[815, 655, 656], 1235);
                step(f, Op::SmoothStepF, &[656, 813, 88, 658], 1236);
                step(f, Op::MulF, &[657, 658, 659], 1237);
                step(f, Op::LerpF, &[87, 815, 659, 660], 1238);
                step(f, Op::MulF, &[654, 660, 661], 1239);
                step(f, Op::QuatFromAxisAngle, &[427, 661, 57], 1240);
                step(f, Op::SubV, &[310, 309, 312], 1241);
                step(f, Op::RotateVector, &[57, 312, 313], 1242);
                step(f, Op::AddV, &[309, 313, 314], 1243);
                step(f, Op::RemapF, &[650, 85, 83, 86, 813, 98, 662], 1244);
                step(f, Op::MulF, &[662, 652, 663], 1245);
                step(f, Op::QuatFromAxisAngle, &[427, 663, 58], 1246);
                step(f, Op::RotateAroundPoint, &[76, 314, 58, 77], 1247);
                step(f, Op::RemapF, &[650, 89, 90, 813, 91, 98, 664], 1248);
                step(f, Op::RotateVector, &[52, 424, 315], 1249);
                step(f, Op::BreakVector, &[315, 665, 666, 667], 1250);
                step(f, Op::CosF, &[93, 669], 1251);
                step(f, Op::CosF, &[92, 668], 1252);
                step(f, Op::RemapF, &[667, 669, 668, 813, 815, 98, 670], 1253);
                step(f, Op::MulF, &[652, 670, 671], 1254);
                step(f, Op::MulF, &[664, 671, 672], 1255);
                step(f, Op::QuatFromAxisAngle, &[427, 672, 59], 1256);
                step(f, Op::RotateAroundPoint, &[77, 311, 59, 78], 1257);
                step(f, Op::SubF, &[815, 15, 673], 1258);
                step(f, Op::MulF, &[14, 673, 674], 1259);
                step(f, Op::LimitRotationAroundZ, &[52, 674, 95, 60], 1260);
                step(f, Op::RotateAroundPoint, &[78, 296, 60, 79], 1261);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 60, 79], 1262);
                step(f, Op::JumpIfFalse, &[8, 1268], 1263)
            }
            1263 => {
                step(f, Op::DrawPoint, &[311, 831, 427], 1264);
                step(f, Op::DrawPoint, &[309, 831, 425], 1265);
                step(f, Op::DrawPoint, &[314, 831, 424], 1266);
                step(f, Op::DrawTransform, &[71, 830, 814], 1267);
                step(f, Op::Jump, &[1268], 1268)
            }
            1268 => {
                step(f, Op::Jump, &[620], 1269)
            }
            1269 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1270);
                step(f, Op::Copy(ValueType::Int), &[71, 5], 1271);
                1271
            }
            1271 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 5, 1, 6, 7, 1313], 1272)
            }
            1272 => {
                step(f, Op::Copy(ValueType::Bone), &[1, 21], 1273);
                step(f, Op::Copy(ValueType::Int), &[6, 61], 1274);
                step(f, Op::GetParent, &[21, 22], 1275);
                step(f, Op::GetParent, &[22, 23], 1276);
                step(f, Op::GetParent, &[23, 24], 1277);
                step(f, Op::GetTransform, &[24, 71, 99, 80], 1278);
                step(f, Op::BreakTransform, &[80, 316, 61, 317], 1279);
                step(f, Op::LengthV, &[1, 676], 1280);
                step(f, Op::ClavicleOffset, &[12, 676, 100, 103, 677], 1281);
                step(f, Op::MakeVector, &[813, 813, 677, 318], 1282);
                step(f, Op::AddV, &[316, 318, 319], 1283);
                step(f, Op::MakeTransform, &[319, 61, 422, 81], 1284);
                step(f, Op::SetTransform, &[24, 81, 71, 98, 815], 1285);
                step(f, Op::GetTransform, &[21, 71, 99, 82], 1286);
                step(f, Op::GetTransform, &[23, 71, 99, 83], 1287);
                step(f, Op::BreakTransform, &[83, 320, 63, 321], 1288);
                step(f, Op::Equals(Elem::Int), &[61, 71, 81], 1289);
                step(f, Op::Select(ValueType::Int), &[81, 72, 71, 62], 1290);
                step(f, Op::ArrayAt(Elem::Float), &[0, 62, 675], 1291);
                step(f, Op::ArmSwingRotation, &[675, 1, 0, 101, 822, 832, 815, 100, 98, 99, 822, 822, 815, 678], 1292);
                step(f, Op::QuatFromAxisAngle, &[427, 678, 62], 1293);
                step(f, Op::RotateAroundPoint, &[82, 320, 62, 84], 1294);
                step(f, Op::BreakTransform, &[84, 322, 64, 323], 1295);
                step(f, Op::RemapF, &[676, 813, 100, 813, 102, 98, 679], 1296);
                step(f, Op::MakeVector, &[813, 813, 679, 324], 1297);
                step(f, Op::AddV, &[322, 324, 325], 1298);
                step(f, Op::MakeTransform, &[325, 64, 422, 85], 1299);
                step(f, Op::Select(ValueType::Vec3), &[81, 428, 427, 327], 1300);
                step(f, Op::Select(ValueType::Vec3), &[81, 425, 429, 328], 1301);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 61, 326], 1302);
                step(f, Op::TwoBoneIK, &[23, 22, 21, 85, 327, 328, 326, 71, 815, 99, 833, 834, 98, 82, 680], 1303);
                step(f, Op::JumpIfFalse, &[8, 1312], 1304)
            }
            1304 => {
                step(f, Op::GetTransform, &[23, 71, 99, 83], 1305);
                step(f, Op::BreakTransform, &[83, 320, 63, 321], 1306);
                step(f, Op::GetTransform, &[21, 71, 99, 82], 1307);
                step(f, Op::RotateAroundPoint, &[82, 320, 62, 84], 1308);
                step(f, Op::BreakTransform, &[84, 322, 64, 323], 1309);
                step(f, Op::AddV, &[322, 324, 325], 1310);
                step(f, Op::DrawLine, &[320, 325, 814, 425], 1311);
                step(f, Op::Jump, &[1312], 1312)
            }
            1312 => {
                step(f, Op::Jump, &[1271], 1313)
            }
            1313 => {
                step(f, Op::NegF, &[3, 791], 1314);
                step(f, Op::MakeVector, &[813, 813, 791, 403], 1315);
                step(f, Op::MakeTransform, &[403, 92, 422, 106], 1316);
                step(f, Op::SetTransform, &[37, 106, 71, 98, 815], 1317);
                step(f, Op::Copy(ValueType::Float), &[813, 683], 1318);
                step(f, Op::Copy(ValueType::Float), &[820, 684], 1319);
                step(f, Op::Copy(ValueType::Bool), &[99, 83], 1320);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 10], 1321);
                step(f, Op::Copy(ValueType::Int), &[71, 63], 1322);
                step(f, Op::MakeVector, &[813, 813, 55, 331], 1323);
                1323
            }
            1323 => {
                step(f, Op::ForEachNext(Elem::Transform), &[10, 63, 86, 64, 65, 1336], 1324)
            }
            1324 => {
                step(f, Op::BreakTransform, &[86, 329, 65, 330], 1325);
                step(f, Op::AddV, &[329, 331, 332], 1326);
                step(f, Op::SubV, &[329, 331, 333], 1327);
                step(f, Op::SphereTrace, &[332, 333, 54, 84, 334, 335, 685], 1328);
                step(f, Op::BreakVector, &[334, 686, 687, 688], 1329);
                step(f, Op::LessF, &[688, 684, 85], 1330);
                step(f, Op::And, &[84, 85, 86], 1331);
                step(f, Op::JumpIfFalse, &[86, 1335], 1332)
            }
            1332 => {
                step(f, Op::Copy(ValueType::Float), &[688, 684], 1333);
                step(f, Op::Copy(ValueType::Bool), &[98, 83], 1334);
                step(f, Op::Jump, &[1335], 1335)
            }
            1335 => {
                step(f, Op::Jump, &[1323], 1336)
            }
            1336 => {
                step(f, Op::Select(ValueType::Float), &[83, 684, 813, 689], 1337);
                step(f, Op::ClampF, &[689, 59, 60, 690], 1338);
                step(f, Op::Copy(ValueType::Float), &[690, 683], 1339);
                step(f, Op::Jump, &[1340], 1340)
            }
            1340 => {
                step(f, Op::SubF, &[815, 21, 682], 1341);
                step(f, Op::MulF, &[683, 682, 691], 1342);
                step(f, Op::SubF, &[815, 123, 692], 1343);
                step(f, Op::MulF, &[3, 692, 693], 1344);
                step(f, Op::AddF, &[691, 693, 694], 1345);
                step(f, Op::MakeVector, &[16, 813, 813, 336], 1346);
                step(f, Op::MakeVector, &[694, 813, 813, 337], 1347);
                step(f, Op::Select(ValueType::Float), &[2, 694, 17, 695], 1348);
                step(f, Op::MakeVector, &[695, 813, 813, 338], 1349);
                step(f, Op::Copy(ValueType::Vec3), &[336, 339], 1350);
                step(f, Op::Copy(ValueType::Vec3), &[337, 340], 1351);
                step(f, Op::Copy(ValueType::Vec3), &[338, 341], 1352);
                step(f, Op::Copy(ValueType::Float), &[48, 696], 1353);
                step(f, Op::Copy(ValueType::Float), &[49, 697], 1354);
                step(f, Op::Copy(ValueType::Vec3), &[421, 342], 1355);
                step(f, Op::SubV, &[340, 341, 343], 1356);
                step(f, Op::DeltaTime, &[698], 1357);
                step(f, Op::DivF, &[697, 698, 699], 1358);
                step(f, Op::ScaleV, &[343, 699, 344], 1359);
                step(f, Op::AddV, &[340, 344, 345], 1360);
                step(f, Op::AddV, &[341, 344, 346], 1361);
                step(f, Op::SubV, &[339, 346, 347], 1362);
                step(f, Op::FloatLerp, &[813, 815, 696, 700], 1363);
                step(f, Op::SubF, &[815, 700, 701], 1364);
                step(f, Op::ScaleV, &[347, 701, 348], 1365);
                step(f, Op::AddV, &[345, 348, 350], 1366);
                step(f, Op::MulF, &[696, 698, 702], 1367);
                step(f, Op::GreaterF, &[702, 813, 87], 1368);
                step(f, Op::DivF, &[700, 702, 703], 1369);
                step(f, Op::Select(ValueType::Float), &[87, 703, 815, 704], 1370);
                step(f, Op::ScaleV, &[343, 704, 349], 1371);
                step(f, Op::SubV, &[350, 349, 351], 1372);
                step(f, Op::Copy(ValueType::Vec3), &[351, 342], 1373);
                step(f, Op::Jump, &[1374], 1374)
            }
            1374 => {
                step(f, Op::BreakVector, &[342, 705, 706, 707], 1375);
                step(f, Op::Select(ValueType::Float), &[1, 694, 705, 708], 1376);
                step(f, Op::Copy(ValueType::Float), &[708, 16], 1377);
                step(f, Op::Copy(ValueType::Float), &[694, 17], 1378);
                step(f, Op::GetTransform, &[38, 71, 98, 91], 1379);
                step(f, Op::BreakTransform, &[91, 364, 72, 365], 1380);
                step(f, Op::PelvisLean, &[1, 106, 111, 112, 726, 727], 1381);
                step(f, Op::LengthV, &[2, 681], 1382);
                step(f, Op::RemapF, &[681, 813, 106, 813, 104, 98, 709], 1383);
                step(f, Op::MulF, &[15, 105, 712], 1384);
                step(f, Op::SubF, &[815, 712, 713], 1385);
                step(f, Op::MulF, &[709, 713, 714], 1386);
                step(f, Op::MulF, &[12, 835, 710], 1387);
                step(f, Op::SinF, &[710, 711], 1388);
                step(f, Op::MulF, &[714, 711, 715], 1389);
                step(f, Op::MulF, &[715, 682, 716], 1390);
                step(f, Op::AddF, &[716, 16, 717], 1391);
                step(f, Op::SubF, &[717, 3, 718], 1392);
                step(f, Op::MakeVector, &[813, 727, 718, 366], 1393);
                step(f, Op::AddV, &[364, 366, 367], 1394);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 71, 87], 1395);
                step(f, Op::BreakTransform, &[87, 352, 66, 353], 1396);
                step(f, Op::BreakVector, &[352, 728, 729, 730], 1397);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 72, 88], 1398);
                step(f, Op::BreakTransform, &[88, 354, 67, 355], 1399);
                step(f, Op::BreakVector, &[354, 731, 732, 733], 1400);
                step(f, Op::SubF, &[730, 733, 734], 1401);
                step(f, Op::PelvisSideLean, &[734, 113, 114, 735], 1402);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 71, 89], 1403);
                step(f, Op::BreakTransform, &[89, 358, 68, 359], 1404);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 72, 90], 1405);
                step(f, Op::BreakTransform, &[90, 360, 69, 361], 1406);
                step(f, Op::SlerpQ, &[68, 69, 814, 70], 1407);
                step(f, Op::EulerFromQuat, &[70, 71, 362], 1408);
                step(f, Op::BreakVector, &[362, 722, 723, 724], 1409);
                step(f, Op::RemapF, &[681, 107, 106, 813, 108, 98, 720], 1410);
                step(f, Op::SubV, &[352, 354, 356], 1411);
                step(f, Op::RotateVector, &[0, 425, 357], 1412);
                step(f, Op::DotV, &[356, 357, 719], 1413);
                step(f, Op::MulF, &[720, 719, 721], 1414);
                step(f, Op::AddF, &[724, 721, 725], 1415);
                step(f, Op::MakeVector, &[726, 735, 725, 363], 1416);
                step(f, Op::QuatFromEuler, &[363, 71, 71], 1417);
                step(f, Op::MakeTransform, &[367, 71, 422, 92], 1418);
                step(f, Op::SetTransform, &[39, 92, 71, 98, 815], 1419);
                step(f, Op::GetTransform, &[40, 72, 98, 93], 1420);
                step(f, Op::BreakTransform, &[93, 368, 76, 369], 1421);
                step(f, Op::QuatFromAxisAngle, &[424, 721, 73], 1422);
                step(f, Op::DivF, &[109, 831, 736], 1423);
                step(f, Op::QuatScale, &[73, 736, 74], 1424);
                step(f, Op::MulQ, &[76, 74, 80], 1425);
                step(f, Op::MakeTransform, &[368, 80, 422, 97], 1426);
                step(f, Op::SetTransform, &[41, 97, 72, 98, 815], 1427);
                step(f, Op::GetTransform, &[42, 72, 98, 94], 1428);
                step(f, Op::BreakTransform, &[94, 370, 77, 371], 1429);
                step(f, Op::MulQ, &[77, 74, 81], 1430);
                step(f, Op::MakeTransform, &[370, 81, 422, 98], 1431);
                step(f, Op::SetTransform, &[43, 98, 72, 98, 815], 1432);
                step(f, Op::GetTransform, &[44, 72, 98, 95], 1433);
                step(f, Op::BreakTransform, &[95, 372, 78, 373], 1434);
                step(f, Op::MulQ, &[78, 74, 82], 1435);
                step(f, Op::MakeTransform, &[372, 82, 422, 99], 1436);
                step(f, Op::SetTransform, &[45, 99, 72, 98, 815], 1437);
                step(f, Op::GetTransform, &[46, 72, 98, 96], 1438);
                step(f, Op::BreakTransform, &[96, 374, 79, 375], 1439);
                step(f, Op::QuatScale, &[73, 110, 75], 1440);
                step(f, Op::MulQ, &[79, 75, 83], 1441);
                step(f, Op::MakeTransform, &[374, 83, 422, 100], 1442);
                step(f, Op::SetTransform, &[47, 100, 72, 98, 815], 1443);
                step(f, Op::Or, &[1, 2, 93], 1444);
                step(f, Op::Copy(ValueType::Float), &[813, 737], 1445);
                step(f, Op::Copy(ValueType::Float), &[813, 738], 1446);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1447);
                step(f, Op::Copy(ValueType::Int), &[71, 66], 1448);
                1448
            }
            1448 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 66, 25, 67, 68, 1495], 1449)
            }
            1449 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 67, 88], 1450);
                step(f, Op::GetParent, &[25, 26], 1451);
                step(f, Op::GetParent, &[26, 27], 1452);
                step(f, Op::GetTransform, &[27, 71, 99, 101], 1453);
                step(f, Op::BreakTransform, &[101, 376, 84, 377], 1454);
                step(f, Op::BreakVector, &[376, 739, 740, 741], 1455);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 67, 102], 1456);
                step(f, Op::BreakTransform, &[102, 378, 85, 379], 1457);
                step(f, Op::BreakVector, &[378, 742, 743, 744], 1458);
                step(f, Op::ArrayAt(Elem::Float), &[1, 67, 748], 1459);
                step(f, Op::MulF, &[748, 115, 749], 1460);
                step(f, Op::MulF, &[749, 749, 750], 1461);
                step(f, Op::SubF, &[739, 742, 745], 1462);
                step(f, Op::SubF, &[740, 743, 746], 1463);
                step(f, Op::MakeVector, &[745, 746, 813, 380], 1464);
                step(f, Op::DotV, &[380, 380, 747], 1465);
                step(f, Op::SubF, &[750, 747, 751], 1466);
                step(f, Op::SqrtF, &[751, 752], 1467);
                step(f, Op::AddF, &[744, 752, 753], 1468);
                step(f, Op::SubF, &[741, 753, 754], 1469);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 67, 103], 1470);
                step(f, Op::BreakTransform, &[103, 381, 86, 382], 1471);
                step(f, Op::BreakVector, &[381, 755, 756, 757], 1472);
                step(f, Op::AddF, &[757, 50, 758], 1473);
                step(f, Op::MinF, &[744, 758, 759], 1474);
                step(f, Op::AddF, &[759, 752, 760], 1475);
                step(f, Op::SubF, &[741, 760, 761], 1476);
                step(f, Op::Equals(Elem::Int), &[67, 71, 89], 1477);
                step(f, Op::Select(ValueType::Int), &[89, 72, 71, 69], 1478);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 69, 90], 1479);
                step(f, Op::ArrayAt(Elem::Float), &[2, 69, 765], 1480);
                step(f, Op::RemapF, &[765, 814, 815, 813, 815, 98, 766], 1481);
                step(f, Op::RemapF, &[765, 813, 118, 815, 813, 98, 767], 1482);
                step(f, Op::MaxF, &[766, 767, 768], 1483);
                step(f, Op::Select(ValueType::Float), &[90, 815, 768, 769], 1484);
                step(f, Op::LerpF, &[754, 761, 769, 770], 1485);
                step(f, Op::ArrayAt(Elem::Float), &[2, 67, 762], 1486);
                step(f, Op::RemapF, &[762, 814, 815, 813, 815, 98, 763], 1487);
                step(f, Op::MulF, &[770, 763, 771], 1488);
                step(f, Op::RemapF, &[762, 813, 118, 815, 813, 98, 764], 1489);
                step(f, Op::MulF, &[754, 764, 772], 1490);
                step(f, Op::MaxF, &[771, 772, 773], 1491);
                step(f, Op::Select(ValueType::Float), &[88, 754, 773, 774], 1492);
                step(f, Op::MaxF, &[738, 774, 775], 1493);
                step(f, Op::Copy(ValueType::Float), &[775, 738], 1494);
                step(f, Op::Jump, &[1448], 1495)
            }
            1495 => {
                step(f, Op::ClampF, &[738, 813, 116, 776], 1496);
                step(f, Op::Copy(ValueType::Float), &[776, 737], 1497);
                step(f, Op::Jump, &[1498], 1498)
            }
            1498 => {
                step(f, Op::MakeVector, &[18, 813, 813, 383], 1499);
                step(f, Op::MakeVector, &[737, 813, 813, 384], 1500);
                step(f, Op::MakeVector, &[19, 813, 813, 385], 1501);
                step(f, Op::GreaterF, &[737, 18, 91], 1502);
                step(f, Op::Select(ValueType::Float), &[91, 120, 117, 777], 1503);
                step(f, Op::Copy(ValueType::Vec3), &[383, 386], 1504);
                step(f, Op::Copy(ValueType::Vec3), &[384, 387], 1505);
                step(f, Op::Copy(ValueType::Vec3), &[385, 388], 1506);
                step(f, Op::Copy(ValueType::Float), &[777, 778], 1507);
                step(f, Op::Copy(ValueType::Float), &[49, 779], 1508);
                step(f, Op::Copy(ValueType::Vec3), &[421, 389], 1509);
                step(f, Op::SubV, &[387, 388, 390], 1510);
                step(f, Op::DeltaTime, &[780], 1511);
                step(f, Op::DivF, &[779, 780, 781], 1512);
                step(f, Op::ScaleV, &[390, 781, 391], 1513);
                step(f, Op::AddV, &[387, 391, 392], 1514);
                step(f, Op::AddV, &[388, 391, 393], 1515);
                step(f, Op::SubV, &[386, 393, 394], 1516);
                step(f, Op::FloatLerp, &[813, 815, 778, 782], 1517);
                step(f, Op::SubF, &[815, 782, 783], 1518);
                step(f, Op::ScaleV, &[394, 783, 395], 1519);
                step(f, Op::AddV, &[392, 395, 397], 1520);
                step(f, Op::MulF, &[778, 780, 784], 1521);
                step(f, Op::GreaterF, &[784, 813, 92], 1522);
                step(f, Op::DivF, &[782, 784, 785], 1523);
                step(f, Op::Select(ValueType::Float), &[92, 785, 815, 786], 1524);
                step(f, Op::ScaleV, &[390, 786, 396], 1525);
                step(f, Op::SubV, &[397, 396, 398], 1526);
                step(f, Op::Copy(ValueType::Vec3), &[398, 389], 1527);
                step(f, Op::Jump, &[1528], 1528)
            }
            1528 => {
                step(f, Op::BreakVector, &[389, 787, 788, 789], 1529);
                step(f, Op::Select(ValueType::Float), &[93, 737, 787, 790], 1530);
                step(f, Op::Copy(ValueType::Float), &[790, 18], 1531);
                step(f, Op::Copy(ValueType::Float), &[737, 19], 1532);
                step(f, Op::GetTransform, &[48, 71, 99, 104], 1533);
                step(f, Op::BreakTransform, &[104, 399, 87, 400], 1534);
                step(f, Op::MakeVector, &[813, 813, 18, 401], 1535);
                step(f, Op::SubV, &[399, 401, 402], 1536);
                step(f, Op::MakeTransform, &[402, 87, 422, 105], 1537);
                step(f, Op::SetTransform, &[49, 105, 71, 98, 815], 1538);
                step(f, Op::JumpIfFalse, &[8, 1545], 1539)
            }
            1539 => {
                step(f, Op::GetTransform, &[48, 71, 99, 104], 1540);
                step(f, Op::BreakTransform, &[104, 399, 87, 400], 1541);
                step(f, Op::SubV, &[399, 401, 402], 1542);
                step(f, Op::MakeTransform, &[402, 87, 422, 105], 1543);
                step(f, Op::DrawTransform, &[105, 836, 814], 1544);
                step(f, Op::Jump, &[1545], 1545)
            }
            1545 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1546);
                step(f, Op::Copy(ValueType::Int), &[71, 8], 1547);
                1547
            }
            1547 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 8, 2, 9, 10, 1598], 1548)
            }
            1548 => {
                step(f, Op::Copy(ValueType::Bone), &[2, 28], 1549);
                step(f, Op::Copy(ValueType::Int), &[9, 70], 1550);
                step(f, Op::GetParent, &[28, 29], 1551);
                step(f, Op::GetParent, &[29, 30], 1552);
                step(f, Op::GetTransform, &[30, 71, 99, 107], 1553);
                step(f, Op::BreakTransform, &[107, 404, 88, 405], 1554);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 70, 108], 1555);
                step(f, Op::BreakTransform, &[108, 406, 89, 407], 1556);
                step(f, Op::SubV, &[406, 404, 408], 1557);
                step(f, Op::LengthV, &[408, 803], 1558);
                step(f, Op::ArrayAt(Elem::Float), &[1, 70, 792], 1559);
                step(f, Op::MulF, &[792, 127, 793], 1560);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 70, 94], 1561);
                step(f, Op::ArrayAt(Elem::Float), &[2, 70, 794], 1562);
                step(f, Op::ClampF, &[794, 813, 815, 795], 1563);
                step(f, Op::LessF, &[795, 814, 95], 1564);
                step(f, Op::SmoothStepF, &[795, 129, 130, 798], 1565);
                step(f, Op::MulF, &[795, 823, 796], 1566);
                step(f, Op::SinF, &[796, 797], 1567);
                step(f, Op::MaxF, &[798, 797, 799], 1568);
                step(f, Op::Select(ValueType::Float), &[95, 799, 797, 800], 1569);
                step(f, Op::MulF, &[800, 128, 801], 1570);
                step(f, Op::Select(ValueType::Float), &[94, 813, 801, 802], 1571);
                step(f, Op::SubF, &[793, 802, 804], 1572);
                step(f, Op::SubF, &[803, 804, 805], 1573);
                step(f, Op::MaxF, &[805, 813, 806], 1574);
                step(f, Op::MulF, &[806, 806, 807], 1575);
                step(f, Op::AddF, &[806, 802, 808], 1576);
                step(f, Op::DivF, &[807, 808, 809], 1577);
                step(f, Op::SubF, &[803, 809, 810], 1578);
                step(f, Op::DivF, &[810, 803, 811], 1579);
                step(f, Op::ScaleV, &[408, 811, 409], 1580);
                step(f, Op::AddV, &[404, 409, 410], 1581);
                step(f, Op::ClampSpatially, &[410, 404, 813, 793, 411], 1582);
                step(f, Op::MakeTransform, &[411, 89, 422, 109], 1583);
                step(f, Op::Equals(Elem::Int), &[70, 71, 96], 1584);
                step(f, Op::Select(ValueType::Vec3), &[96, 428, 427, 416], 1585);
                step(f, Op::Select(ValueType::Vec3), &[96, 425, 429, 417], 1586);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 70, 110], 1587);
                step(f, Op::BreakTransform, &[110, 412, 90, 413], 1588);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 70, 414], 1589);
                step(f, Op::KneeVector, &[90, 0, 414, 131, 132, 415], 1590);
                step(f, Op::TwoBoneIK, &[30, 29, 28, 109, 416, 417, 415, 71, 815, 99, 833, 834, 98, 97, 812], 1591);
                step(f, Op::JumpIfFalse, &[8, 1597], 1592)
            }
            1592 => {
                step(f, Op::GetTransform, &[29, 71, 99, 111], 1593);
                step(f, Op::BreakTransform, &[111, 418, 91, 419], 1594);
                step(f, Op::AddV, &[418, 415, 420], 1595);
                step(f, Op::DrawLine, &[418, 420, 814, 430], 1596);
                step(f, Op::Jump, &[1597], 1597)
            }
            1597 => {
                step(f, Op::Jump, &[1547], 1598)
            }
            1598 => {
                step(f, Op::End, &[], 1599)
            }
            _ => return,
        } };
    }
}
