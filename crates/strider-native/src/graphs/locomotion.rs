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
    fingerprint: 0xd39a7ee0d9bdcc78,
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
                step(f, Op::LengthV, &[37, 136], 111);
                step(f, Op::GreaterF, &[136, 33, 10], 112);
                step(f, Op::Copy(ValueType::Bool), &[10, 2], 113);
                step(f, Op::MakeRelative, &[13, 12, 17], 114);
                step(f, Op::Select(ValueType::Transform), &[10, 111, 17, 18], 115);
                step(f, Op::Copy(ValueType::Transform), &[18, 2], 116);
                step(f, Op::InverseT, &[13, 15], 117);
                step(f, Op::MulT, &[12, 15, 16], 118);
                step(f, Op::Copy(ValueType::Transform), &[16, 1], 119);
                step(f, Op::TransformVector, &[2, 0, 42], 120);
                step(f, Op::InverseT, &[12, 14], 121);
                step(f, Op::DeltaTime, &[135], 122);
                step(f, Op::DivF, &[806, 135, 137], 123);
                step(f, Op::ScaleV, &[37, 137, 38], 124);
                step(f, Op::TransformVector, &[14, 38, 39], 125);
                step(f, Op::BreakVector, &[39, 138, 139, 140], 126);
                step(f, Op::MakeVector, &[138, 139, 804, 40], 127);
                step(f, Op::LengthV, &[40, 141], 128);
                step(f, Op::MulF, &[141, 118, 142], 129);
                step(f, Op::NegF, &[142, 143], 130);
                step(f, Op::ClampF, &[140, 143, 142, 144], 131);
                step(f, Op::MakeVector, &[138, 139, 144, 41], 132);
                step(f, Op::Select(ValueType::Vec3), &[2, 42, 41, 44], 133);
                step(f, Op::VectorLerp, &[42, 44, 34, 804, 45], 134);
                step(f, Op::Copy(ValueType::Vec3), &[45, 0], 135);
                step(f, Op::TransformVector, &[2, 1, 43], 136);
                step(f, Op::TransformVector, &[2, 0, 42], 137);
                step(f, Op::Select(ValueType::Vec3), &[2, 42, 41, 44], 138);
                step(f, Op::VectorLerp, &[43, 44, 35, 804, 46], 139);
                step(f, Op::Copy(ValueType::Vec3), &[46, 1], 140);
                step(f, Op::LengthV, &[44, 151], 141);
                step(f, Op::Copy(ValueType::Float), &[151, 0], 142);
                step(f, Op::BreakVector, &[37, 145, 146, 147], 143);
                step(f, Op::MulF, &[144, 135, 148], 144);
                step(f, Op::SubF, &[147, 148, 149], 145);
                step(f, Op::Select(ValueType::Float), &[10, 804, 149, 150], 146);
                step(f, Op::Copy(ValueType::Float), &[150, 1], 147);
                step(f, Op::JumpIfFalse, &[2, 161], 148)
            }
            148 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 12], 149);
                step(f, Op::Copy(ValueType::Int), &[72, 17], 150);
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
                step(f, Op::Copy(ValueType::Float), &[804, 14], 160);
                step(f, Op::Jump, &[161], 161)
            }
            161 => {
                step(f, Op::Copy(ValueType::Transform), &[12, 0], 162);
                step(f, Op::Copy(ValueType::Bool), &[98, 0], 163);
                step(f, Op::JumpIfFalse, &[8, 170], 164)
            }
            164 => {
                step(f, Op::GetTransform, &[34, 72, 98, 19], 165);
                step(f, Op::BreakTransform, &[19, 47, 9, 48], 166);
                step(f, Op::ScaleV, &[0, 807, 49], 167);
                step(f, Op::AddV, &[47, 49, 50], 168);
                step(f, Op::DrawArrow, &[47, 50, 805, 422], 169);
                step(f, Op::Jump, &[170], 170)
            }
            170 => {
                step(f, Op::Copy(ValueType::Float), &[804, 152], 171);
                step(f, Op::Copy(ValueType::Float), &[806, 153], 172);
                step(f, Op::Copy(ValueType::Float), &[806, 154], 173);
                step(f, Op::Copy(ValueType::Bool), &[99, 11], 174);
                step(f, Op::Copy(ValueType::Bool), &[99, 12], 175);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[7, 8], 176);
                step(f, Op::Copy(ValueType::Int), &[72, 25], 177);
                step(f, Op::MakeVector, &[804, 804, 53, 55], 178);
                178
            }
            178 => {
                step(f, Op::ForEachNext(Elem::Transform), &[8, 25, 21, 26, 27, 189], 179)
            }
            179 => {
                step(f, Op::BreakTransform, &[21, 51, 10, 52], 180);
                step(f, Op::TransformPoint, &[2, 51, 53], 181);
                step(f, Op::LerpV, &[53, 51, 154, 54], 182);
                step(f, Op::AddV, &[54, 55, 56], 183);
                step(f, Op::SubV, &[54, 55, 57], 184);
                step(f, Op::LineTrace, &[56, 57, 13, 58, 59, 155], 185);
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
                step(f, Op::Copy(ValueType::Int), &[72, 20], 198);
                198
            }
            198 => {
                step(f, Op::ForNext, &[20, 24, 22, 226], 199)
            }
            199 => {
                step(f, Op::AddF, &[152, 153, 156], 200);
                step(f, Op::MulF, &[156, 805, 157], 201);
                step(f, Op::Copy(ValueType::Float), &[157, 158], 202);
                step(f, Op::Copy(ValueType::Bool), &[99, 17], 203);
                step(f, Op::Copy(ValueType::Bool), &[99, 18], 204);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[7, 9], 205);
                step(f, Op::Copy(ValueType::Int), &[72, 28], 206);
                step(f, Op::MakeVector, &[804, 804, 53, 64], 207);
                207
            }
            207 => {
                step(f, Op::ForEachNext(Elem::Transform), &[9, 28, 22, 29, 30, 218], 208)
            }
            208 => {
                step(f, Op::BreakTransform, &[22, 60, 11, 61], 209);
                step(f, Op::TransformPoint, &[2, 60, 62], 210);
                step(f, Op::LerpV, &[62, 60, 158, 63], 211);
                step(f, Op::AddV, &[63, 64, 65], 212);
                step(f, Op::SubV, &[63, 64, 66], 213);
                step(f, Op::LineTrace, &[65, 66, 19, 67, 68, 159], 214);
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
                step(f, Op::Copy(ValueType::Float), &[157, 152], 223);
                step(f, Op::Jump, &[225], 224)
            }
            224 => {
                step(f, Op::Copy(ValueType::Float), &[157, 153], 225);
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
                step(f, Op::Select(ValueType::Float), &[5, 808, 806, 165], 229);
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 230);
                step(f, Op::AddF, &[152, 153, 156], 231);
                step(f, Op::MulF, &[156, 805, 160], 232);
                step(f, Op::Select(ValueType::Float), &[16, 160, 805, 161], 233);
                step(f, Op::Select(ValueType::Float), &[15, 161, 804, 167], 234);
                step(f, Op::MulF, &[165, 167, 169], 235);
                step(f, Op::DeltaTime, &[163], 236);
                step(f, Op::DivF, &[163, 121, 164], 237);
                step(f, Op::MulF, &[169, 164, 170], 238);
                step(f, Op::AddF, &[18, 170, 171], 239);
                step(f, Op::ClampF, &[171, 804, 806, 172], 240);
                step(f, Op::Select(ValueType::Float), &[14, 808, 806, 166], 241);
                step(f, Op::SubF, &[806, 161, 162], 242);
                step(f, Op::Select(ValueType::Float), &[15, 162, 806, 168], 243);
                step(f, Op::MulF, &[166, 168, 173], 244);
                step(f, Op::MulF, &[173, 164, 174], 245);
                step(f, Op::AddF, &[172, 174, 175], 246);
                step(f, Op::ClampF, &[175, 804, 806, 176], 247);
                step(f, Op::MulF, &[176, 176, 177], 248);
                step(f, Op::MulF, &[176, 809, 178], 249);
                step(f, Op::SubF, &[810, 178, 179], 250);
                step(f, Op::MulF, &[177, 179, 180], 251);
                step(f, Op::AddF, &[19, 180, 181], 252);
                step(f, Op::MulF, &[181, 805, 182], 253);
                step(f, Op::SubF, &[806, 182, 183], 254);
                step(f, Op::MulF, &[183, 183, 184], 255);
                step(f, Op::SubF, &[806, 184, 185], 256);
                step(f, Op::Copy(ValueType::Float), &[185, 20], 257);
                step(f, Op::Copy(ValueType::Float), &[180, 19], 258);
                step(f, Op::Copy(ValueType::Float), &[176, 18], 259);
                step(f, Op::GreaterF, &[19, 804, 21], 260);
                step(f, Op::TransformVector, &[2, 3, 69], 261);
                step(f, Op::Select(ValueType::Vec3), &[21, 69, 0, 70], 262);
                step(f, Op::Copy(ValueType::Vec3), &[70, 3], 263);
                step(f, Op::LerpV, &[0, 3, 19, 71], 264);
                step(f, Op::Select(ValueType::Vec3), &[21, 71, 0, 72], 265);
                step(f, Op::Copy(ValueType::Vec3), &[72, 2], 266);
                step(f, Op::Copy(ValueType::Bool), &[14, 5], 267);
                step(f, Op::Copy(ValueType::Bool), &[11, 6], 268);
                step(f, Op::Copy(ValueType::Bool), &[99, 7], 269);
                step(f, Op::SubF, &[806, 20, 186], 270);
                step(f, Op::MulF, &[1, 186, 187], 271);
                step(f, Op::AddF, &[2, 187, 188], 272);
                step(f, Op::SpringF, &[188, 119, 191, 31, 189, 190], 273);
                step(f, Op::SubF, &[188, 191, 192], 274);
                step(f, Op::Copy(ValueType::Float), &[192, 3], 275);
                step(f, Op::Copy(ValueType::Float), &[188, 2], 276);
                step(f, Op::LengthV, &[4, 194], 277);
                step(f, Op::GreaterF, &[194, 27, 22], 278);
                step(f, Op::LengthV, &[2, 195], 279);
                step(f, Op::GreaterF, &[195, 27, 23], 280);
                step(f, Op::And, &[22, 23, 25], 281);
                step(f, Op::Select(ValueType::Vec3), &[22, 4, 420, 73], 282);
                step(f, Op::MovementAngleOffset, &[73, 12, 804, 811, 811, 812, 38, 813, 196], 283);
                step(f, Op::Copy(ValueType::Float), &[196, 198], 284);
                step(f, Op::Copy(ValueType::Float), &[12, 199], 285);
                step(f, Op::Copy(ValueType::Float), &[804, 200], 286);
                step(f, Op::SubF, &[198, 199, 201], 287);
                step(f, Op::AddF, &[201, 814, 202], 288);
                step(f, Op::DivF, &[202, 815, 203], 289);
                step(f, Op::FractF, &[203, 204], 290);
                step(f, Op::MulF, &[204, 815, 205], 291);
                step(f, Op::SubF, &[205, 814, 206], 292);
                step(f, Op::Copy(ValueType::Float), &[206, 200], 293);
                step(f, Op::Jump, &[294], 294)
            }
            294 => {
                step(f, Op::AbsF, &[200, 225], 295);
                step(f, Op::Select(ValueType::Vec3), &[23, 2, 420, 74], 296);
                step(f, Op::MovementAngleOffset, &[74, 12, 804, 811, 811, 812, 38, 813, 197], 297);
                step(f, Op::Copy(ValueType::Float), &[197, 207], 298);
                step(f, Op::Copy(ValueType::Float), &[12, 208], 299);
                step(f, Op::Copy(ValueType::Float), &[804, 209], 300);
                step(f, Op::SubF, &[207, 208, 210], 301);
                step(f, Op::AddF, &[210, 814, 211], 302);
                step(f, Op::DivF, &[211, 815, 212], 303);
                step(f, Op::FractF, &[212, 213], 304);
                step(f, Op::MulF, &[213, 815, 214], 305);
                step(f, Op::SubF, &[214, 814, 215], 306);
                step(f, Op::Copy(ValueType::Float), &[215, 209], 307);
                step(f, Op::Jump, &[308], 308)
            }
            308 => {
                step(f, Op::AbsF, &[209, 226], 309);
                step(f, Op::MaxF, &[225, 226, 228], 310);
                step(f, Op::Copy(ValueType::Float), &[197, 216], 311);
                step(f, Op::Copy(ValueType::Float), &[196, 217], 312);
                step(f, Op::Copy(ValueType::Float), &[804, 218], 313);
                step(f, Op::SubF, &[216, 217, 219], 314);
                step(f, Op::AddF, &[219, 814, 220], 315);
                step(f, Op::DivF, &[220, 815, 221], 316);
                step(f, Op::FractF, &[221, 222], 317);
                step(f, Op::MulF, &[222, 815, 223], 318);
                step(f, Op::SubF, &[223, 814, 224], 319);
                step(f, Op::Copy(ValueType::Float), &[224, 218], 320);
                step(f, Op::Jump, &[321], 321)
            }
            321 => {
                step(f, Op::AbsF, &[218, 227], 322);
                step(f, Op::MaxF, &[228, 227, 229], 323);
                step(f, Op::LessF, &[229, 816, 24], 324);
                step(f, Op::And, &[25, 24, 26], 325);
                step(f, Op::Not, &[22, 27], 326);
                step(f, Op::Not, &[23, 28], 327);
                step(f, Op::And, &[27, 28, 29], 328);
                step(f, Op::Or, &[26, 29, 30], 329);
                step(f, Op::JumpIfFalse, &[30, 351], 330)
            }
            330 => {
                step(f, Op::DeltaTime, &[193], 331);
                step(f, Op::MulF, &[36, 193, 233], 332);
                step(f, Op::GreaterF, &[233, 804, 31], 333);
                step(f, Op::DivF, &[47, 193, 230], 334);
                step(f, Op::FloatLerp, &[804, 806, 36, 231], 335);
                step(f, Op::SubF, &[806, 231, 232], 336);
                step(f, Op::DivF, &[232, 231, 234], 337);
                step(f, Op::DivF, &[806, 233, 235], 338);
                step(f, Op::SubF, &[234, 235, 236], 339);
                step(f, Op::AddF, &[230, 236, 237], 340);
                step(f, Op::Select(ValueType::Float), &[31, 237, 804, 238], 341);
                step(f, Op::MulF, &[218, 238, 239], 342);
                step(f, Op::AddF, &[197, 239, 240], 343);
                step(f, Op::SinF, &[240, 241], 344);
                step(f, Op::NegF, &[241, 242], 345);
                step(f, Op::CosF, &[240, 243], 346);
                step(f, Op::MakeVector, &[242, 243, 804, 75], 347);
                step(f, Op::Select(ValueType::Vec3), &[23, 75, 420, 76], 348);
                step(f, Op::MovementAngleOffset, &[76, 12, 804, 36, 37, 812, 814, 813, 244], 349);
                step(f, Op::Copy(ValueType::Float), &[244, 12], 350);
                step(f, Op::Jump, &[386], 351)
            }
            351 => {
                step(f, Op::DeltaTime, &[193], 352);
                step(f, Op::DivF, &[193, 39, 245], 353);
                step(f, Op::AddF, &[245, 805, 246], 354);
                step(f, Op::FloorF, &[246, 247], 355);
                step(f, Op::MaxF, &[247, 806, 248], 356);
                step(f, Op::ToInt, &[248, 37], 357);
                step(f, Op::Copy(ValueType::Int), &[37, 36], 358);
                step(f, Op::Copy(ValueType::Int), &[72, 32], 359);
                step(f, Op::MulF, &[39, 805, 252], 360);
                step(f, Op::SubF, &[47, 252, 253], 361);
                step(f, Op::DivF, &[253, 193, 254], 362);
                step(f, Op::FloatLerp, &[804, 806, 34, 256], 363);
                step(f, Op::GreaterF, &[256, 804, 32], 364);
                step(f, Op::DivF, &[36, 248, 266], 365);
                step(f, Op::DivF, &[37, 248, 267], 366);
                366
            }
            366 => {
                step(f, Op::ForNext, &[32, 36, 34, 386], 367)
            }
            367 => {
                step(f, Op::ToFloat, &[34, 249], 368);
                step(f, Op::AddF, &[249, 806, 250], 369);
                step(f, Op::DivF, &[250, 248, 251], 370);
                step(f, Op::AddF, &[251, 254, 255], 371);
                step(f, Op::MulF, &[34, 255, 257], 372);
                step(f, Op::FloatLerp, &[804, 806, 257, 258], 373);
                step(f, Op::DivF, &[258, 256, 259], 374);
                step(f, Op::Select(ValueType::Float), &[32, 259, 255, 260], 375);
                step(f, Op::LerpV, &[4, 2, 260, 77], 376);
                step(f, Op::LengthV, &[77, 261], 377);
                step(f, Op::GreaterF, &[261, 27, 33], 378);
                step(f, Op::Select(ValueType::Vec3), &[33, 77, 420, 78], 379);
                step(f, Op::MulF, &[193, 255, 262], 380);
                step(f, Op::MulF, &[6, 262, 263], 381);
                step(f, Op::AddF, &[10, 263, 264], 382);
                step(f, Op::FractF, &[264, 265], 383);
                step(f, Op::MovementAngleOffset, &[78, 12, 265, 266, 267, 812, 38, 813, 268], 384);
                step(f, Op::Copy(ValueType::Float), &[268, 12], 385);
                step(f, Op::Jump, &[366], 386)
            }
            386 => {
                step(f, Op::QuatFromAxisAngle, &[423, 12, 12], 387);
                step(f, Op::Copy(ValueType::Quat), &[12, 0], 388);
                step(f, Op::SinF, &[12, 269], 389);
                step(f, Op::AbsF, &[269, 270], 390);
                step(f, Op::RemapF, &[270, 40, 41, 804, 806, 98, 271], 391);
                step(f, Op::Copy(ValueType::Float), &[271, 13], 392);
                step(f, Op::Copy(ValueType::Vec3), &[2, 4], 393);
                step(f, Op::Copy(ValueType::Bool), &[99, 35], 394);
                step(f, Op::Copy(ValueType::Bool), &[98, 36], 395);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 396);
                step(f, Op::Copy(ValueType::Int), &[72, 41], 397);
                397
            }
            397 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 41, 37, 42, 43, 403], 398)
            }
            398 => {
                step(f, Op::Not, &[37, 38], 399);
                step(f, Op::JumpIfFalse, &[38, 402], 400)
            }
            400 => {
                step(f, Op::Copy(ValueType::Bool), &[99, 36], 401);
                step(f, Op::Jump, &[402], 402)
            }
            402 => {
                step(f, Op::Jump, &[397], 403)
            }
            403 => {
                step(f, Op::Copy(ValueType::Bool), &[36, 35], 404);
                step(f, Op::Jump, &[405], 405)
            }
            405 => {
                step(f, Op::Copy(ValueType::Bool), &[99, 39], 406);
                step(f, Op::Copy(ValueType::Bool), &[98, 40], 407);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 408);
                step(f, Op::Copy(ValueType::Int), &[72, 44], 409);
                409
            }
            409 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 44, 15, 45, 46, 424], 410)
            }
            410 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 45, 23], 411);
                step(f, Op::BreakTransform, &[23, 79, 13, 80], 412);
                step(f, Op::BreakVector, &[79, 280, 281, 282], 413);
                step(f, Op::MakeVector, &[280, 281, 804, 83], 414);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 45, 24], 415);
                step(f, Op::BreakTransform, &[24, 81, 14, 82], 416);
                step(f, Op::BreakVector, &[81, 283, 284, 285], 417);
                step(f, Op::MakeVector, &[283, 284, 804, 84], 418);
                step(f, Op::DistanceV, &[83, 84, 286], 419);
                step(f, Op::GreaterF, &[286, 29, 41], 420);
                step(f, Op::JumpIfFalse, &[41, 423], 421)
            }
            421 => {
                step(f, Op::Copy(ValueType::Bool), &[99, 40], 422);
                step(f, Op::Jump, &[423], 423)
            }
            423 => {
                step(f, Op::Jump, &[409], 424)
            }
            424 => {
                step(f, Op::Copy(ValueType::Bool), &[40, 39], 425);
                step(f, Op::Jump, &[426], 426)
            }
            426 => {
                step(f, Op::And, &[35, 39, 42], 427);
                step(f, Op::LengthV, &[2, 272], 428);
                step(f, Op::GreaterF, &[272, 27, 34], 429);
                step(f, Op::GreaterF, &[0, 27, 43], 430);
                step(f, Op::Or, &[34, 43, 44], 431);
                step(f, Op::Not, &[44, 45], 432);
                step(f, Op::And, &[42, 45, 50], 433);
                step(f, Op::DeltaTime, &[311], 434);
                step(f, Op::MulF, &[311, 32, 312], 435);
                step(f, Op::AddF, &[10, 312, 313], 436);
                step(f, Op::GreaterF, &[10, 805, 51], 437);
                step(f, Op::AddF, &[31, 805, 309], 438);
                step(f, Op::Select(ValueType::Float), &[51, 309, 31, 310], 439);
                step(f, Op::MinF, &[313, 310, 314], 440);
                step(f, Op::NotEquals(Elem::Bool), &[45, 4, 46], 441);
                step(f, Op::Not, &[42, 47], 442);
                step(f, Op::And, &[46, 47, 48], 443);
                step(f, Op::SubF, &[11, 27, 295], 444);
                step(f, Op::SubF, &[11, 272, 296], 445);
                step(f, Op::DivF, &[295, 296, 297], 446);
                step(f, Op::ClampF, &[297, 804, 806, 298], 447);
                step(f, Op::MulF, &[6, 298, 300], 448);
                step(f, Op::RemapF, &[272, 27, 28, 804, 806, 98, 287], 449);
                step(f, Op::MaxF, &[287, 7, 288], 450);
                step(f, Op::Select(ValueType::Float), &[35, 806, 288, 289], 451);
                step(f, Op::Select(ValueType::Float), &[45, 30, 289, 290], 452);
                step(f, Op::Select(ValueType::Float), &[42, 287, 290, 291], 453);
                step(f, Op::SubF, &[806, 19, 292], 454);
                step(f, Op::MulF, &[291, 292, 293], 455);
                step(f, Op::LerpF, &[21, 43, 13, 275], 456);
                step(f, Op::RemapF, &[272, 24, 25, 22, 23, 98, 273], 457);
                step(f, Op::LerpF, &[273, 42, 13, 274], 458);
                step(f, Op::MaxF, &[272, 26, 276], 459);
                step(f, Op::DivF, &[274, 276, 277], 460);
                step(f, Op::AddF, &[275, 277, 278], 461);
                step(f, Op::DivF, &[293, 278, 294], 462);
                step(f, Op::SubF, &[806, 298, 299], 463);
                step(f, Op::MulF, &[294, 299, 301], 464);
                step(f, Op::AddF, &[300, 301, 302], 465);
                step(f, Op::MulF, &[302, 809, 303], 466);
                step(f, Op::AddF, &[6, 294, 304], 467);
                step(f, Op::Select(ValueType::Float), &[48, 303, 304, 305], 468);
                step(f, Op::DivF, &[809, 305, 306], 469);
                step(f, Op::GreaterF, &[305, 804, 49], 470);
                step(f, Op::CycleStep, &[10, 306, 804, 49, 307, 308], 471);
                step(f, Op::Select(ValueType::Float), &[50, 314, 307, 315], 472);
                step(f, Op::Copy(ValueType::Float), &[315, 10], 473);
                step(f, Op::Copy(ValueType::Float), &[294, 6], 474);
                step(f, Op::Copy(ValueType::Bool), &[34, 3], 475);
                step(f, Op::Copy(ValueType::Float), &[277, 4], 476);
                step(f, Op::Copy(ValueType::Float), &[278, 5], 477);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 478);
                step(f, Op::Copy(ValueType::Int), &[72, 38], 479);
                step(f, Op::DivF, &[275, 278, 279], 480);
                step(f, Op::MulF, &[9, 298, 321], 481);
                step(f, Op::MulF, &[311, 805, 327], 482);
                step(f, Op::SubF, &[279, 8, 332], 483);
                step(f, Op::MaxF, &[332, 804, 333], 484);
                step(f, Op::DivF, &[333, 279, 334], 485);
                step(f, Op::SubF, &[806, 13, 336], 486);
                step(f, Op::DivF, &[47, 311, 341], 487);
                step(f, Op::SubF, &[805, 341, 342], 488);
                step(f, Op::MulF, &[334, 336, 343], 489);
                step(f, Op::MulF, &[343, 292, 344], 490);
                step(f, Op::MulF, &[344, 116, 345], 491);
                step(f, Op::MulF, &[345, 342, 346], 492);
                step(f, Op::SubF, &[806, 346, 347], 493);
                493
            }
            493 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 38, 14, 39, 40, 538], 494)
            }
            494 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 39, 329], 495);
                step(f, Op::ToFloat, &[39, 316], 496);
                step(f, Op::MulF, &[316, 805, 317], 497);
                step(f, Op::AddF, &[10, 317, 318], 498);
                step(f, Op::FractF, &[318, 319], 499);
                step(f, Op::SubF, &[329, 319, 331], 500);
                step(f, Op::GreaterF, &[331, 805, 52], 501);
                step(f, Op::ArrayAt(Elem::Float), &[2, 39, 330], 502);
                step(f, Op::Select(ValueType::Float), &[52, 804, 330, 358], 503);
                step(f, Op::ArraySetAt(Elem::Float), &[3, 39, 358], 504);
                step(f, Op::SubF, &[806, 329, 352], 505);
                step(f, Op::AddF, &[319, 352, 353], 506);
                step(f, Op::DivF, &[319, 353, 354], 507);
                step(f, Op::MaxF, &[287, 7, 288], 508);
                step(f, Op::Select(ValueType::Float), &[35, 806, 288, 289], 509);
                step(f, Op::Select(ValueType::Float), &[45, 30, 289, 290], 510);
                step(f, Op::Select(ValueType::Float), &[42, 287, 290, 291], 511);
                step(f, Op::MulF, &[291, 292, 293], 512);
                step(f, Op::DivF, &[293, 275, 320], 513);
                step(f, Op::MulF, &[320, 299, 322], 514);
                step(f, Op::AddF, &[321, 322, 323], 515);
                step(f, Op::MulF, &[323, 809, 324], 516);
                step(f, Op::AddF, &[9, 320, 325], 517);
                step(f, Op::Select(ValueType::Float), &[48, 324, 325, 326], 518);
                step(f, Op::MulF, &[326, 327, 328], 519);
                step(f, Op::MulF, &[354, 328, 355], 520);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 39, 53], 521);
                step(f, Op::MulF, &[328, 347, 348], 522);
                step(f, Op::Select(ValueType::Float), &[53, 328, 348, 349], 523);
                step(f, Op::MulF, &[334, 330, 335], 524);
                step(f, Op::MulF, &[335, 336, 337], 525);
                step(f, Op::MulF, &[337, 292, 338], 526);
                step(f, Op::MulF, &[338, 116, 339], 527);
                step(f, Op::Select(ValueType::Float), &[53, 804, 339, 340], 528);
                step(f, Op::SubF, &[349, 340, 350], 529);
                step(f, Op::AddF, &[330, 350, 351], 530);
                step(f, Op::Select(ValueType::Float), &[52, 355, 351, 356], 531);
                step(f, Op::MinF, &[356, 809, 357], 532);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 39, 357], 533);
                step(f, Op::JumpIfFalse, &[52, 536], 534)
            }
            534 => {
                step(f, Op::Copy(ValueType::Float), &[291, 7], 535);
                step(f, Op::Jump, &[536], 536)
            }
            536 => {
                step(f, Op::ArraySetAt(Elem::Float), &[0, 39, 319], 537);
                step(f, Op::Jump, &[493], 538)
            }
            538 => {
                step(f, Op::Copy(ValueType::Float), &[279, 8], 539);
                step(f, Op::Copy(ValueType::Bool), &[45, 4], 540);
                step(f, Op::Copy(ValueType::Float), &[272, 11], 541);
                step(f, Op::MaxF, &[287, 7, 288], 542);
                step(f, Op::Select(ValueType::Float), &[35, 806, 288, 289], 543);
                step(f, Op::Select(ValueType::Float), &[45, 30, 289, 290], 544);
                step(f, Op::Select(ValueType::Float), &[42, 287, 290, 291], 545);
                step(f, Op::MulF, &[291, 292, 293], 546);
                step(f, Op::DivF, &[293, 275, 320], 547);
                step(f, Op::Copy(ValueType::Float), &[320, 9], 548);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 549);
                step(f, Op::Copy(ValueType::Int), &[72, 2], 550);
                550
            }
            550 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 2, 0, 3, 4, 1227], 551)
            }
            551 => {
                step(f, Op::Copy(ValueType::Bone), &[0, 16], 552);
                step(f, Op::Copy(ValueType::Int), &[3, 47], 553);
                step(f, Op::GetTransform, &[35, 72, 98, 25], 554);
                step(f, Op::BreakTransform, &[25, 87, 15, 88], 555);
                step(f, Op::BreakVector, &[87, 370, 371, 372], 556);
                step(f, Op::SubF, &[806, 13, 368], 557);
                step(f, Op::MulF, &[12, 368, 369], 558);
                step(f, Op::QuatFromAxisAngle, &[423, 369, 17], 559);
                step(f, Op::GetTransform, &[16, 72, 98, 26], 560);
                step(f, Op::BreakTransform, &[26, 89, 16, 90], 561);
                step(f, Op::SubV, &[89, 87, 91], 562);
                step(f, Op::BreakVector, &[91, 365, 366, 367], 563);
                step(f, Op::MakeVector, &[365, 366, 804, 92], 564);
                step(f, Op::RotateVector, &[17, 92, 93], 565);
                step(f, Op::BreakVector, &[93, 373, 374, 375], 566);
                step(f, Op::MulF, &[44, 13, 376], 567);
                step(f, Op::Equals(Elem::Int), &[47, 72, 54], 568);
                step(f, Op::Select(ValueType::Float), &[54, 806, 808, 385], 569);
                step(f, Op::MulF, &[376, 385, 377], 570);
                step(f, Op::AddF, &[373, 377, 378], 571);
                step(f, Op::AddF, &[370, 378, 379], 572);
                step(f, Op::AddF, &[371, 374, 380], 573);
                step(f, Op::BreakVector, &[89, 381, 382, 383], 574);
                step(f, Op::SubF, &[383, 48, 384], 575);
                step(f, Op::MakeVector, &[379, 380, 384, 94], 576);
                step(f, Op::ArrayAt(Elem::Float), &[2, 47, 359], 577);
                step(f, Op::SubF, &[806, 359, 360], 578);
                step(f, Op::MaxF, &[360, 804, 361], 579);
                step(f, Op::MulF, &[8, 5, 362], 580);
                step(f, Op::MulF, &[361, 362, 363], 581);
                step(f, Op::ScaleV, &[2, 363, 85], 582);
                step(f, Op::AddV, &[94, 85, 95], 583);
                step(f, Op::MulF, &[4, 805, 364], 584);
                step(f, Op::ScaleV, &[2, 364, 86], 585);
                step(f, Op::AddV, &[95, 86, 96], 586);
                step(f, Op::RotateVector, &[0, 424, 97], 587);
                step(f, Op::Copy(ValueType::Vec3), &[96, 118], 588);
                step(f, Op::Copy(ValueType::Vec3), &[97, 119], 589);
                step(f, Op::Copy(ValueType::Float), &[385, 404], 590);
                step(f, Op::Copy(ValueType::Vec3), &[420, 120], 591);
                step(f, Op::Copy(ValueType::Vec3), &[420, 121], 592);
                step(f, Op::Copy(ValueType::Bool), &[99, 56], 593);
                step(f, Op::Copy(ValueType::Float), &[811, 405], 594);
                step(f, Op::Copy(ValueType::Vec3), &[420, 122], 595);
                step(f, Op::Copy(ValueType::Vec3), &[423, 123], 596);
                step(f, Op::Copy(ValueType::Bool), &[99, 57], 597);
                step(f, Op::Copy(ValueType::Float), &[811, 406], 598);
                step(f, Op::Copy(ValueType::Vec3), &[420, 124], 599);
                step(f, Op::MulI, &[0, 0, 53], 600);
                step(f, Op::Copy(ValueType::Int), &[53, 52], 601);
                step(f, Op::Copy(ValueType::Int), &[72, 48], 602);
                step(f, Op::SubI, &[0, 73, 56], 603);
                step(f, Op::DivI, &[56, 74, 57], 604);
                step(f, Op::MakeVector, &[804, 804, 53, 129], 605);
                step(f, Op::ScaleV, &[119, 56, 134], 606);
                606
            }
            606 => {
                step(f, Op::ForNext, &[48, 52, 50, 654], 607)
            }
            607 => {
                step(f, Op::ModI, &[50, 0, 54], 608);
                step(f, Op::ToFloat, &[54, 407], 609);
                step(f, Op::MulF, &[407, 54, 409], 610);
                step(f, Op::MulF, &[409, 404, 410], 611);
                step(f, Op::MakeVector, &[410, 804, 804, 125], 612);
                step(f, Op::DivI, &[50, 0, 55], 613);
                step(f, Op::SubI, &[55, 57, 58], 614);
                step(f, Op::ToFloat, &[58, 408], 615);
                step(f, Op::MulF, &[408, 54, 411], 616);
                step(f, Op::ScaleV, &[119, 411, 126], 617);
                step(f, Op::AddV, &[125, 126, 127], 618);
                step(f, Op::AddV, &[118, 127, 128], 619);
                step(f, Op::AddV, &[128, 129, 130], 620);
                step(f, Op::SubV, &[128, 129, 131], 621);
                step(f, Op::SphereTrace, &[130, 131, 52, 58, 132, 133, 412], 622);
                step(f, Op::BreakVector, &[132, 414, 415, 416], 623);
                step(f, Op::AddV, &[130, 134, 135], 624);
                step(f, Op::AddV, &[131, 134, 136], 625);
                step(f, Op::SphereTrace, &[135, 136, 52, 59, 137, 138, 413], 626);
                step(f, Op::BreakVector, &[137, 417, 418, 419], 627);
                step(f, Op::SubF, &[416, 419, 420], 628);
                step(f, Op::AbsF, &[420, 421], 629);
                step(f, Op::Select(ValueType::Float), &[58, 804, 806, 422], 630);
                step(f, Op::AddF, &[421, 422, 427], 631);
                step(f, Op::LengthV, &[127, 423], 632);
                step(f, Op::RemapF, &[423, 804, 817, 804, 806, 98, 424], 633);
                step(f, Op::MinF, &[416, 419, 425], 634);
                step(f, Op::RemapF, &[425, 818, 817, 806, 805, 98, 426], 635);
                step(f, Op::AddF, &[424, 426, 428], 636);
                step(f, Op::AddF, &[427, 428, 429], 637);
                step(f, Op::LessF, &[429, 405, 60], 638);
                step(f, Op::And, &[58, 60, 61], 639);
                step(f, Op::JumpIfFalse, &[61, 647], 640)
            }
            640 => {
                step(f, Op::Copy(ValueType::Float), &[405, 406], 641);
                step(f, Op::Copy(ValueType::Vec3), &[122, 124], 642);
                step(f, Op::Copy(ValueType::Float), &[429, 405], 643);
                step(f, Op::Copy(ValueType::Vec3), &[132, 122], 644);
                step(f, Op::Copy(ValueType::Vec3), &[133, 123], 645);
                step(f, Op::Copy(ValueType::Bool), &[98, 57], 646);
                step(f, Op::Jump, &[653], 647)
            }
            647 => {
                step(f, Op::LessF, &[429, 406, 62], 648);
                step(f, Op::And, &[58, 62, 63], 649);
                step(f, Op::JumpIfFalse, &[63, 653], 650)
            }
            650 => {
                step(f, Op::Copy(ValueType::Float), &[429, 406], 651);
                step(f, Op::Copy(ValueType::Vec3), &[132, 124], 652);
                step(f, Op::Jump, &[653], 653)
            }
            653 => {
                step(f, Op::Jump, &[606], 654)
            }
            654 => {
                step(f, Op::JumpIfFalse, &[8, 657], 655)
            }
            655 => {
                step(f, Op::DrawSphere, &[122, 52, 424], 656);
                step(f, Op::Jump, &[657], 657)
            }
            657 => {
                step(f, Op::GreaterF, &[55, 804, 64], 658);
                step(f, Op::SubF, &[405, 406, 430], 659);
                step(f, Op::DivF, &[430, 55, 431], 660);
                step(f, Op::PowF, &[819, 431, 432], 661);
                step(f, Op::Select(ValueType::Float), &[64, 432, 804, 433], 662);
                step(f, Op::ScaleV, &[124, 433, 139], 663);
                step(f, Op::AddV, &[122, 139, 140], 664);
                step(f, Op::AddF, &[433, 806, 434], 665);
                step(f, Op::DivF, &[806, 434, 435], 666);
                step(f, Op::ScaleV, &[140, 435, 141], 667);
                step(f, Op::Copy(ValueType::Vec3), &[141, 120], 668);
                step(f, Op::Copy(ValueType::Vec3), &[123, 121], 669);
                step(f, Op::Copy(ValueType::Bool), &[57, 56], 670);
                step(f, Op::Jump, &[671], 671)
            }
            671 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 47, 27], 672);
                step(f, Op::BreakTransform, &[27, 99, 21, 100], 673);
                step(f, Op::ArrayAt(Elem::Float), &[2, 47, 359], 674);
                step(f, Op::SubF, &[806, 359, 360], 675);
                step(f, Op::MaxF, &[360, 804, 361], 676);
                step(f, Op::MulF, &[8, 5, 362], 677);
                step(f, Op::MulF, &[361, 362, 363], 678);
                step(f, Op::ScaleV, &[2, 363, 85], 679);
                step(f, Op::SubV, &[120, 85, 98], 680);
                step(f, Op::Select(ValueType::Vec3), &[56, 98, 99, 101], 681);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 47, 28], 682);
                step(f, Op::BreakTransform, &[28, 102, 23, 103], 683);
                step(f, Op::Copy(ValueType::Vec3), &[99, 104], 684);
                step(f, Op::Copy(ValueType::Vec3), &[101, 105], 685);
                step(f, Op::Copy(ValueType::Vec3), &[102, 106], 686);
                step(f, Op::Copy(ValueType::Float), &[45, 391], 687);
                step(f, Op::Copy(ValueType::Float), &[47, 392], 688);
                step(f, Op::Copy(ValueType::Vec3), &[420, 107], 689);
                step(f, Op::SubV, &[105, 106, 108], 690);
                step(f, Op::DeltaTime, &[393], 691);
                step(f, Op::DivF, &[392, 393, 394], 692);
                step(f, Op::ScaleV, &[108, 394, 109], 693);
                step(f, Op::AddV, &[105, 109, 110], 694);
                step(f, Op::AddV, &[106, 109, 111], 695);
                step(f, Op::SubV, &[104, 111, 112], 696);
                step(f, Op::FloatLerp, &[804, 806, 391, 395], 697);
                step(f, Op::SubF, &[806, 395, 396], 698);
                step(f, Op::ScaleV, &[112, 396, 113], 699);
                step(f, Op::AddV, &[110, 113, 115], 700);
                step(f, Op::MulF, &[391, 393, 397], 701);
                step(f, Op::GreaterF, &[397, 804, 55], 702);
                step(f, Op::DivF, &[395, 397, 398], 703);
                step(f, Op::Select(ValueType::Float), &[55, 398, 806, 399], 704);
                step(f, Op::ScaleV, &[108, 399, 114], 705);
                step(f, Op::SubV, &[115, 114, 116], 706);
                step(f, Op::Copy(ValueType::Vec3), &[116, 107], 707);
                step(f, Op::Jump, &[708], 708)
            }
            708 => {
                step(f, Op::BreakVector, &[107, 400, 401, 402], 709);
                step(f, Op::ClampF, &[402, 57, 58, 403], 710);
                step(f, Op::MakeVector, &[400, 401, 403, 117], 711);
                step(f, Op::RotationFromNormal, &[121, 389, 390, 19], 712);
                step(f, Op::PerFootRotationFactor, &[12, 94, 95, 386], 713);
                step(f, Op::MulF, &[12, 386, 387], 714);
                step(f, Op::SubF, &[806, 13, 368], 715);
                step(f, Op::MulF, &[387, 368, 388], 716);
                step(f, Op::QuatFromAxisAngle, &[423, 388, 18], 717);
                step(f, Op::MulQ, &[19, 18, 20], 718);
                step(f, Op::Select(ValueType::Quat), &[56, 20, 21, 22], 719);
                step(f, Op::MakeTransform, &[117, 22, 421, 30], 720);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 47, 30], 721);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 47, 27], 722);
                step(f, Op::BreakTransform, &[27, 99, 21, 100], 723);
                step(f, Op::Select(ValueType::Vec3), &[56, 98, 99, 101], 724);
                step(f, Op::MakeTransform, &[101, 92, 421, 29], 725);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 47, 29], 726);
                step(f, Op::JumpIfFalse, &[56, 729], 727)
            }
            727 => {
                step(f, Op::Copy(ValueType::Bool), &[98, 7], 728);
                step(f, Op::Jump, &[729], 729)
            }
            729 => {
                step(f, Op::Copy(ValueType::Int), &[3, 59], 730);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 59, 33], 731);
                step(f, Op::GreaterF, &[19, 804, 68], 732);
                step(f, Op::InterpolateTransform, &[2, 111, 20, 31], 733);
                step(f, Op::Select(ValueType::Transform), &[68, 31, 2, 32], 734);
                step(f, Op::MakeAbsolute, &[33, 32, 34], 735);
                step(f, Op::BreakTransform, &[34, 142, 24, 143], 736);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 59, 35], 737);
                step(f, Op::BreakTransform, &[35, 144, 25, 145], 738);
                step(f, Op::AddF, &[61, 62, 437], 739);
                step(f, Op::ClampSpatially, &[142, 144, 804, 437, 146], 740);
                step(f, Op::SubF, &[806, 13, 452], 741);
                step(f, Op::MulF, &[12, 452, 438], 742);
                step(f, Op::LimitRotationAroundZ, &[24, 438, 93, 26], 743);
                step(f, Op::MakeTransform, &[146, 26, 421, 36], 744);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 59, 36], 745);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 59, 65], 746);
                step(f, Op::JumpIfFalse, &[65, 800], 747)
            }
            747 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 59, 39], 748);
                step(f, Op::BreakTransform, &[39, 152, 28, 153], 749);
                step(f, Op::ArrayAt(Elem::Float), &[2, 59, 436], 750);
                step(f, Op::SubF, &[806, 436, 449], 751);
                step(f, Op::MulF, &[8, 5, 450], 752);
                step(f, Op::MulF, &[449, 450, 451], 753);
                step(f, Op::ScaleV, &[2, 451, 154], 754);
                step(f, Op::AddV, &[152, 154, 155], 755);
                step(f, Op::MakeTransform, &[155, 28, 421, 46], 756);
                step(f, Op::Copy(ValueType::Transform), &[46, 47], 757);
                step(f, Op::Copy(ValueType::Transform), &[111, 48], 758);
                step(f, Op::BreakTransform, &[47, 183, 33, 184], 759);
                step(f, Op::MakeVector, &[804, 804, 53, 185], 760);
                step(f, Op::AddV, &[183, 185, 186], 761);
                step(f, Op::SubV, &[183, 185, 187], 762);
                step(f, Op::LineTrace, &[186, 187, 72, 188, 189, 479], 763);
                step(f, Op::RotateVector, &[33, 423, 190], 764);
                step(f, Op::FindQuatBetween, &[190, 189, 34], 765);
                step(f, Op::MulQ, &[34, 33, 35], 766);
                step(f, Op::MulF, &[51, 50, 480], 767);
                step(f, Op::AddF, &[480, 60, 481], 768);
                step(f, Op::NegF, &[481, 482], 769);
                step(f, Op::MakeVector, &[804, 482, 804, 191], 770);
                step(f, Op::RotateVector, &[35, 191, 193], 771);
                step(f, Op::AddV, &[188, 193, 195], 772);
                step(f, Op::AddV, &[195, 185, 197], 773);
                step(f, Op::SubV, &[195, 185, 198], 774);
                step(f, Op::LineTrace, &[197, 198, 73, 201, 202, 484], 775);
                step(f, Op::BreakVector, &[201, 486, 487, 488], 776);
                step(f, Op::BreakVector, &[195, 492, 493, 494], 777);
                step(f, Op::SubF, &[488, 494, 498], 778);
                step(f, Op::Select(ValueType::Float), &[73, 498, 804, 500], 779);
                step(f, Op::AddF, &[56, 60, 483], 780);
                step(f, Op::MakeVector, &[804, 483, 804, 192], 781);
                step(f, Op::RotateVector, &[35, 192, 194], 782);
                step(f, Op::AddV, &[188, 194, 196], 783);
                step(f, Op::AddV, &[196, 185, 199], 784);
                step(f, Op::SubV, &[196, 185, 200], 785);
                step(f, Op::LineTrace, &[199, 200, 74, 203, 204, 485], 786);
                step(f, Op::BreakVector, &[203, 489, 490, 491], 787);
                step(f, Op::BreakVector, &[196, 495, 496, 497], 788);
                step(f, Op::SubF, &[491, 497, 499], 789);
                step(f, Op::Select(ValueType::Float), &[74, 499, 804, 501], 790);
                step(f, Op::MaxF, &[500, 501, 502], 791);
                step(f, Op::ClampF, &[502, 804, 59, 503], 792);
                step(f, Op::MakeVector, &[804, 804, 503, 205], 793);
                step(f, Op::AddV, &[188, 205, 206], 794);
                step(f, Op::MakeTransform, &[206, 35, 421, 49], 795);
                step(f, Op::Select(ValueType::Transform), &[72, 49, 47, 50], 796);
                step(f, Op::Copy(ValueType::Transform), &[50, 48], 797);
                step(f, Op::Jump, &[798], 798)
            }
            798 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 59, 48], 799);
                step(f, Op::Jump, &[901], 800)
            }
            800 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 59, 51], 801);
                step(f, Op::MakeAbsolute, &[51, 32, 52], 802);
                step(f, Op::BreakTransform, &[52, 207, 36, 208], 803);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 59, 39], 804);
                step(f, Op::BreakTransform, &[39, 152, 28, 153], 805);
                step(f, Op::ArrayAt(Elem::Float), &[2, 59, 436], 806);
                step(f, Op::SubF, &[806, 436, 449], 807);
                step(f, Op::MulF, &[8, 5, 450], 808);
                step(f, Op::MulF, &[449, 450, 451], 809);
                step(f, Op::ScaleV, &[2, 451, 154], 810);
                step(f, Op::AddV, &[152, 154, 155], 811);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 59, 53], 812);
                step(f, Op::MakeAbsolute, &[53, 32, 54], 813);
                step(f, Op::BreakTransform, &[54, 209, 37, 210], 814);
                step(f, Op::ArrayAt(Elem::Float), &[3, 59, 504], 815);
                step(f, Op::SubF, &[436, 504, 505], 816);
                step(f, Op::DeltaTime, &[520], 817);
                step(f, Op::DivF, &[47, 520, 506], 818);
                step(f, Op::MulF, &[505, 506, 507], 819);
                step(f, Op::AddF, &[504, 507, 508], 820);
                step(f, Op::ClampF, &[508, 804, 806, 510], 821);
                step(f, Op::AddF, &[436, 507, 509], 822);
                step(f, Op::ClampF, &[509, 804, 806, 511], 823);
                step(f, Op::AddF, &[510, 511, 512], 824);
                step(f, Op::MulF, &[512, 805, 513], 825);
                step(f, Op::SubF, &[806, 513, 514], 826);
                step(f, Op::GreaterF, &[505, 804, 75], 827);
                step(f, Op::SubF, &[511, 510, 515], 828);
                step(f, Op::DivF, &[515, 505, 516], 829);
                step(f, Op::Select(ValueType::Float), &[75, 516, 806, 517], 830);
                step(f, Op::MulF, &[514, 517, 518], 831);
                step(f, Op::MulF, &[77, 518, 519], 832);
                step(f, Op::Copy(ValueType::Vec3), &[207, 211], 833);
                step(f, Op::Copy(ValueType::Vec3), &[155, 212], 834);
                step(f, Op::Copy(ValueType::Vec3), &[209, 213], 835);
                step(f, Op::Copy(ValueType::Float), &[519, 521], 836);
                step(f, Op::Copy(ValueType::Float), &[47, 522], 837);
                step(f, Op::Copy(ValueType::Vec3), &[420, 214], 838);
                step(f, Op::SubV, &[212, 213, 215], 839);
                step(f, Op::DeltaTime, &[523], 840);
                step(f, Op::DivF, &[522, 523, 524], 841);
                step(f, Op::ScaleV, &[215, 524, 216], 842);
                step(f, Op::AddV, &[212, 216, 217], 843);
                step(f, Op::AddV, &[213, 216, 218], 844);
                step(f, Op::SubV, &[211, 218, 219], 845);
                step(f, Op::FloatLerp, &[804, 806, 521, 525], 846);
                step(f, Op::SubF, &[806, 525, 526], 847);
                step(f, Op::ScaleV, &[219, 526, 220], 848);
                step(f, Op::AddV, &[217, 220, 222], 849);
                step(f, Op::MulF, &[521, 523, 527], 850);
                step(f, Op::GreaterF, &[527, 804, 76], 851);
                step(f, Op::DivF, &[525, 527, 528], 852);
                step(f, Op::Select(ValueType::Float), &[76, 528, 806, 529], 853);
                step(f, Op::ScaleV, &[215, 529, 221], 854);
                step(f, Op::SubV, &[222, 221, 223], 855);
                step(f, Op::Copy(ValueType::Vec3), &[223, 214], 856);
                step(f, Op::Jump, &[857], 857)
            }
            857 => {
                step(f, Op::MakeTransform, &[214, 28, 421, 56], 858);
                step(f, Op::Copy(ValueType::Transform), &[56, 57], 859);
                step(f, Op::Copy(ValueType::Transform), &[111, 58], 860);
                step(f, Op::BreakTransform, &[57, 224, 38, 225], 861);
                step(f, Op::MakeVector, &[804, 804, 53, 226], 862);
                step(f, Op::AddV, &[224, 226, 227], 863);
                step(f, Op::SubV, &[224, 226, 228], 864);
                step(f, Op::LineTrace, &[227, 228, 77, 229, 230, 530], 865);
                step(f, Op::RotateVector, &[38, 423, 231], 866);
                step(f, Op::FindQuatBetween, &[231, 230, 39], 867);
                step(f, Op::MulQ, &[39, 38, 40], 868);
                step(f, Op::MulF, &[51, 50, 531], 869);
                step(f, Op::AddF, &[531, 60, 532], 870);
                step(f, Op::NegF, &[532, 533], 871);
                step(f, Op::MakeVector, &[804, 533, 804, 232], 872);
                step(f, Op::RotateVector, &[40, 232, 234], 873);
                step(f, Op::AddV, &[229, 234, 236], 874);
                step(f, Op::AddV, &[236, 226, 238], 875);
                step(f, Op::SubV, &[236, 226, 239], 876);
                step(f, Op::LineTrace, &[238, 239, 78, 242, 243, 535], 877);
                step(f, Op::BreakVector, &[242, 537, 538, 539], 878);
                step(f, Op::BreakVector, &[236, 543, 544, 545], 879);
                step(f, Op::SubF, &[539, 545, 549], 880);
                step(f, Op::Select(ValueType::Float), &[78, 549, 804, 551], 881);
                step(f, Op::AddF, &[56, 60, 534], 882);
                step(f, Op::MakeVector, &[804, 534, 804, 233], 883);
                step(f, Op::RotateVector, &[40, 233, 235], 884);
                step(f, Op::AddV, &[229, 235, 237], 885);
                step(f, Op::AddV, &[237, 226, 240], 886);
                step(f, Op::SubV, &[237, 226, 241], 887);
                step(f, Op::LineTrace, &[240, 241, 79, 244, 245, 536], 888);
                step(f, Op::BreakVector, &[244, 540, 541, 542], 889);
                step(f, Op::BreakVector, &[237, 546, 547, 548], 890);
                step(f, Op::SubF, &[542, 548, 550], 891);
                step(f, Op::Select(ValueType::Float), &[79, 550, 804, 552], 892);
                step(f, Op::MaxF, &[551, 552, 553], 893);
                step(f, Op::ClampF, &[553, 804, 59, 554], 894);
                step(f, Op::MakeVector, &[804, 804, 554, 246], 895);
                step(f, Op::AddV, &[229, 246, 247], 896);
                step(f, Op::MakeTransform, &[247, 40, 421, 59], 897);
                step(f, Op::Select(ValueType::Transform), &[77, 59, 57, 60], 898);
                step(f, Op::Copy(ValueType::Transform), &[60, 58], 899);
                step(f, Op::Jump, &[900], 900)
            }
            900 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 59, 58], 901);
                901
            }
            901 => {
                step(f, Op::GreaterEqualF, &[436, 806, 66], 902);
                step(f, Op::JumpIfFalse, &[66, 975], 903)
            }
            903 => {
                step(f, Op::JumpIfFalse, &[65, 905], 904)
            }
            904 => {
                step(f, Op::Jump, &[957], 905)
            }
            905 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 59, 61], 906);
                step(f, Op::BreakTransform, &[61, 248, 41, 249], 907);
                step(f, Op::Equals(Elem::Int), &[59, 72, 67], 908);
                step(f, Op::Select(ValueType::Int), &[67, 73, 72, 60], 909);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 60, 40], 910);
                step(f, Op::BreakTransform, &[40, 156, 29, 157], 911);
                step(f, Op::MulF, &[12, 452, 453], 912);
                step(f, Op::FootAvoidance, &[248, 156, 453, 67, 78, 158], 913);
                step(f, Op::MakeTransform, &[158, 41, 421, 41], 914);
                step(f, Op::Copy(ValueType::Transform), &[41, 42], 915);
                step(f, Op::Copy(ValueType::Transform), &[111, 43], 916);
                step(f, Op::BreakTransform, &[42, 159, 30, 160], 917);
                step(f, Op::MakeVector, &[804, 804, 53, 161], 918);
                step(f, Op::AddV, &[159, 161, 162], 919);
                step(f, Op::SubV, &[159, 161, 163], 920);
                step(f, Op::LineTrace, &[162, 163, 69, 164, 165, 454], 921);
                step(f, Op::RotateVector, &[30, 423, 166], 922);
                step(f, Op::FindQuatBetween, &[166, 165, 31], 923);
                step(f, Op::MulQ, &[31, 30, 32], 924);
                step(f, Op::MulF, &[51, 50, 455], 925);
                step(f, Op::AddF, &[455, 60, 456], 926);
                step(f, Op::NegF, &[456, 457], 927);
                step(f, Op::MakeVector, &[804, 457, 804, 167], 928);
                step(f, Op::RotateVector, &[32, 167, 169], 929);
                step(f, Op::AddV, &[164, 169, 171], 930);
                step(f, Op::AddV, &[171, 161, 173], 931);
                step(f, Op::SubV, &[171, 161, 174], 932);
                step(f, Op::LineTrace, &[173, 174, 70, 177, 178, 459], 933);
                step(f, Op::BreakVector, &[177, 461, 462, 463], 934);
                step(f, Op::BreakVector, &[171, 467, 468, 469], 935);
                step(f, Op::SubF, &[463, 469, 473], 936);
                step(f, Op::Select(ValueType::Float), &[70, 473, 804, 475], 937);
                step(f, Op::AddF, &[56, 60, 458], 938);
                step(f, Op::MakeVector, &[804, 458, 804, 168], 939);
                step(f, Op::RotateVector, &[32, 168, 170], 940);
                step(f, Op::AddV, &[164, 170, 172], 941);
                step(f, Op::AddV, &[172, 161, 175], 942);
                step(f, Op::SubV, &[172, 161, 176], 943);
                step(f, Op::LineTrace, &[175, 176, 71, 179, 180, 460], 944);
                step(f, Op::BreakVector, &[179, 464, 465, 466], 945);
                step(f, Op::BreakVector, &[172, 470, 471, 472], 946);
                step(f, Op::SubF, &[466, 472, 474], 947);
                step(f, Op::Select(ValueType::Float), &[71, 474, 804, 476], 948);
                step(f, Op::MaxF, &[475, 476, 477], 949);
                step(f, Op::ClampF, &[477, 804, 59, 478], 950);
                step(f, Op::MakeVector, &[804, 804, 478, 181], 951);
                step(f, Op::AddV, &[164, 181, 182], 952);
                step(f, Op::MakeTransform, &[182, 32, 421, 44], 953);
                step(f, Op::Select(ValueType::Transform), &[69, 44, 42, 45], 954);
                step(f, Op::Copy(ValueType::Transform), &[45, 43], 955);
                step(f, Op::Jump, &[956], 956)
            }
            956 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 59, 43], 957);
                957
            }
            957 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 59, 37], 958);
                step(f, Op::BreakTransform, &[37, 147, 27, 148], 959);
                step(f, Op::SubV, &[147, 144, 149], 960);
                step(f, Op::LengthV, &[149, 439], 961);
                step(f, Op::SubF, &[61, 62, 440], 962);
                step(f, Op::SubF, &[439, 440, 441], 963);
                step(f, Op::MulF, &[62, 809, 442], 964);
                step(f, Op::ClampF, &[441, 804, 442, 443], 965);
                step(f, Op::MulF, &[443, 443, 444], 966);
                step(f, Op::MulF, &[62, 820, 445], 967);
                step(f, Op::DivF, &[444, 445, 446], 968);
                step(f, Op::SubF, &[439, 446, 447], 969);
                step(f, Op::DivF, &[447, 439, 448], 970);
                step(f, Op::ScaleV, &[149, 448, 150], 971);
                step(f, Op::AddV, &[144, 150, 151], 972);
                step(f, Op::MakeTransform, &[151, 27, 421, 38], 973);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 59, 38], 974);
                step(f, Op::Jump, &[1116], 975)
            }
            975 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 59, 37], 976);
                step(f, Op::BreakTransform, &[37, 147, 27, 148], 977);
                step(f, Op::SubV, &[147, 144, 149], 978);
                step(f, Op::LengthV, &[149, 439], 979);
                step(f, Op::SubF, &[61, 62, 440], 980);
                step(f, Op::SubF, &[439, 440, 441], 981);
                step(f, Op::MulF, &[62, 809, 442], 982);
                step(f, Op::ClampF, &[441, 804, 442, 443], 983);
                step(f, Op::MulF, &[443, 443, 444], 984);
                step(f, Op::MulF, &[62, 820, 445], 985);
                step(f, Op::DivF, &[444, 445, 446], 986);
                step(f, Op::SubF, &[439, 446, 447], 987);
                step(f, Op::DivF, &[447, 439, 448], 988);
                step(f, Op::ScaleV, &[149, 448, 150], 989);
                step(f, Op::AddV, &[144, 150, 151], 990);
                step(f, Op::MakeTransform, &[151, 27, 421, 38], 991);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 59, 61], 992);
                step(f, Op::ClampF, &[436, 804, 806, 555], 993);
                step(f, Op::Copy(ValueType::Transform), &[38, 66], 994);
                step(f, Op::Copy(ValueType::Transform), &[61, 67], 995);
                step(f, Op::Copy(ValueType::Float), &[555, 573], 996);
                step(f, Op::Copy(ValueType::Transform), &[111, 68], 997);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[3, 2], 998);
                step(f, Op::ArrayReset(Elem::Vec3), &[2], 999);
                step(f, Op::BreakTransform, &[66, 266, 46, 267], 1000);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 266], 1001);
                step(f, Op::UnitV, &[2, 265], 1002);
                step(f, Op::LengthV, &[2, 574], 1003);
                step(f, Op::RemapF, &[574, 804, 63, 804, 64, 98, 575], 1004);
                step(f, Op::ScaleV, &[265, 575, 270], 1005);
                step(f, Op::SubV, &[266, 270, 276], 1006);
                step(f, Op::MakeVector, &[804, 804, 66, 274], 1007);
                step(f, Op::AddV, &[276, 274, 278], 1008);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 278], 1009);
                step(f, Op::RemapF, &[574, 804, 63, 804, 68, 98, 577], 1010);
                step(f, Op::MakeVector, &[804, 804, 577, 272], 1011);
                step(f, Op::AddV, &[278, 272, 282], 1012);
                step(f, Op::BreakTransform, &[67, 268, 47, 269], 1013);
                step(f, Op::BreakVector, &[268, 582, 583, 584], 1014);
                step(f, Op::BreakVector, &[266, 579, 580, 581], 1015);
                step(f, Op::SubF, &[584, 581, 585], 1016);
                step(f, Op::MaxF, &[585, 804, 587], 1017);
                step(f, Op::MulF, &[587, 70, 591], 1018);
                step(f, Op::MinF, &[591, 71, 592], 1019);
                step(f, Op::AbsF, &[585, 589], 1020);
                step(f, Op::RemapF, &[589, 804, 74, 804, 73, 98, 590], 1021);
                step(f, Op::AddF, &[592, 590, 594], 1022);
                step(f, Op::MakeVector, &[804, 804, 594, 280], 1023);
                step(f, Op::AddV, &[282, 280, 284], 1024);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 284], 1025);
                step(f, Op::RemapF, &[574, 804, 63, 804, 65, 98, 576], 1026);
                step(f, Op::ScaleV, &[265, 576, 271], 1027);
                step(f, Op::AddV, &[268, 271, 277], 1028);
                step(f, Op::MakeVector, &[804, 804, 67, 275], 1029);
                step(f, Op::AddV, &[277, 275, 279], 1030);
                step(f, Op::RemapF, &[574, 804, 63, 804, 69, 98, 578], 1031);
                step(f, Op::MakeVector, &[804, 804, 578, 273], 1032);
                step(f, Op::AddV, &[279, 273, 283], 1033);
                step(f, Op::NegF, &[585, 586], 1034);
                step(f, Op::MaxF, &[586, 804, 588], 1035);
                step(f, Op::MulF, &[588, 72, 593], 1036);
                step(f, Op::AddF, &[593, 590, 595], 1037);
                step(f, Op::MakeVector, &[804, 804, 595, 281], 1038);
                step(f, Op::AddV, &[283, 281, 285], 1039);
                step(f, Op::LerpV, &[284, 285, 805, 286], 1040);
                step(f, Op::GetTransform, &[36, 72, 98, 69], 1041);
                step(f, Op::BreakTransform, &[69, 287, 48, 288], 1042);
                step(f, Op::BreakVector, &[287, 605, 606, 607], 1043);
                step(f, Op::SubF, &[806, 13, 599], 1044);
                step(f, Op::MulF, &[75, 599, 600], 1045);
                step(f, Op::MulF, &[12, 600, 601], 1046);
                step(f, Op::QuatFromAxisAngle, &[423, 601, 49], 1047);
                step(f, Op::SubV, &[286, 287, 289], 1048);
                step(f, Op::BreakVector, &[289, 596, 597, 598], 1049);
                step(f, Op::MakeVector, &[596, 597, 804, 290], 1050);
                step(f, Op::RotateVector, &[49, 290, 291], 1051);
                step(f, Op::BreakVector, &[291, 602, 603, 604], 1052);
                step(f, Op::AddF, &[605, 602, 611], 1053);
                step(f, Op::AddF, &[606, 603, 612], 1054);
                step(f, Op::BreakVector, &[286, 608, 609, 610], 1055);
                step(f, Op::MakeVector, &[611, 612, 610, 292], 1056);
                step(f, Op::DistanceV, &[266, 268, 613], 1057);
                step(f, Op::RemapF, &[613, 809, 821, 804, 806, 98, 614], 1058);
                step(f, Op::LerpV, &[286, 292, 614, 293], 1059);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 293], 1060);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 285], 1061);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 279], 1062);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 268], 1063);
                step(f, Op::JumpIfFalse, &[8, 1066], 1064)
            }
            1064 => {
                step(f, Op::DrawSpline, &[2, 72, 75, 805, 425], 1065);
                step(f, Op::Jump, &[1066], 1066)
            }
            1066 => {
                step(f, Op::Spline, &[2, 573, 72, 294, 295], 1067);
                step(f, Op::SlerpQ, &[46, 47, 573, 50], 1068);
                step(f, Op::MulF, &[573, 814, 623], 1069);
                step(f, Op::SinF, &[623, 624], 1070);
                step(f, Op::Copy(ValueType::Float), &[573, 615], 1071);
                step(f, Op::Copy(ValueType::Float), &[804, 616], 1072);
                step(f, Op::DivF, &[615, 86, 617], 1073);
                step(f, Op::ClampF, &[617, 804, 806, 618], 1074);
                step(f, Op::MulF, &[618, 618, 619], 1075);
                step(f, Op::MulF, &[618, 809, 620], 1076);
                step(f, Op::SubF, &[810, 620, 621], 1077);
                step(f, Op::MulF, &[619, 621, 622], 1078);
                step(f, Op::Copy(ValueType::Float), &[622, 616], 1079);
                step(f, Op::Jump, &[1080], 1080)
            }
            1080 => {
                step(f, Op::MulF, &[624, 616, 625], 1081);
                step(f, Op::MulF, &[625, 76, 626], 1082);
                step(f, Op::SlerpQ, &[50, 92, 626, 51], 1083);
                step(f, Op::MakeTransform, &[294, 51, 421, 70], 1084);
                step(f, Op::Copy(ValueType::Transform), &[70, 68], 1085);
                step(f, Op::Jump, &[1086], 1086)
            }
            1086 => {
                step(f, Op::BreakTransform, &[68, 250, 42, 251], 1087);
                step(f, Op::Equals(Elem::Int), &[59, 72, 67], 1088);
                step(f, Op::Select(ValueType::Int), &[67, 73, 72, 60], 1089);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 60, 40], 1090);
                step(f, Op::BreakTransform, &[40, 156, 29, 157], 1091);
                step(f, Op::SubF, &[806, 13, 452], 1092);
                step(f, Op::MulF, &[12, 452, 453], 1093);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 60, 80], 1094);
                step(f, Op::Select(ValueType::Float), &[80, 79, 804, 558], 1095);
                step(f, Op::ArrayAt(Elem::Float), &[2, 59, 436], 1096);
                step(f, Op::ClampF, &[436, 804, 806, 555], 1097);
                step(f, Op::MulF, &[555, 814, 556], 1098);
                step(f, Op::SinF, &[556, 557], 1099);
                step(f, Op::MulF, &[557, 557, 559], 1100);
                step(f, Op::MulF, &[558, 559, 560], 1101);
                step(f, Op::AddF, &[78, 560, 561], 1102);
                step(f, Op::FootAvoidance, &[250, 156, 453, 67, 561, 252], 1103);
                step(f, Op::SubV, &[252, 250, 253], 1104);
                step(f, Op::LengthV, &[253, 562], 1105);
                step(f, Op::AddF, &[562, 560, 563], 1106);
                step(f, Op::DivF, &[562, 563, 564], 1107);
                step(f, Op::ScaleV, &[253, 564, 254], 1108);
                step(f, Op::AddV, &[250, 254, 255], 1109);
                step(f, Op::SubF, &[806, 120, 565], 1110);
                step(f, Op::MulF, &[3, 565, 566], 1111);
                step(f, Op::MulF, &[566, 559, 567], 1112);
                step(f, Op::MakeVector, &[804, 804, 567, 256], 1113);
                step(f, Op::AddV, &[255, 256, 257], 1114);
                step(f, Op::MakeTransform, &[257, 42, 421, 62], 1115);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 59, 62], 1116);
                1116
            }
            1116 => {
                step(f, Op::GreaterF, &[19, 804, 68], 1117);
                step(f, Op::JumpIfFalse, &[68, 1134], 1118)
            }
            1118 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 59, 63], 1119);
                step(f, Op::BreakTransform, &[63, 258, 43, 259], 1120);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 59, 64], 1121);
                step(f, Op::BreakTransform, &[64, 260, 44, 261], 1122);
                step(f, Op::MulF, &[19, 19, 568], 1123);
                step(f, Op::LerpV, &[258, 260, 568, 262], 1124);
                step(f, Op::SubF, &[806, 19, 569], 1125);
                step(f, Op::MulF, &[19, 569, 570], 1126);
                step(f, Op::MulF, &[122, 809, 571], 1127);
                step(f, Op::MulF, &[570, 571, 572], 1128);
                step(f, Op::MakeVector, &[804, 804, 572, 263], 1129);
                step(f, Op::AddV, &[262, 263, 264], 1130);
                step(f, Op::SlerpQ, &[43, 44, 19, 45], 1131);
                step(f, Op::MakeTransform, &[264, 45, 421, 65], 1132);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 59, 65], 1133);
                step(f, Op::Jump, &[1134], 1134)
            }
            1134 => {
                step(f, Op::GreaterEqualF, &[436, 806, 66], 1135);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 59, 66], 1136);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 59, 39], 1137);
                step(f, Op::BreakTransform, &[39, 152, 28, 153], 1138);
                step(f, Op::SubF, &[806, 436, 449], 1139);
                step(f, Op::MulF, &[8, 5, 450], 1140);
                step(f, Op::MulF, &[449, 450, 451], 1141);
                step(f, Op::ScaleV, &[2, 451, 154], 1142);
                step(f, Op::AddV, &[152, 154, 155], 1143);
                step(f, Op::MakeTransform, &[155, 92, 421, 55], 1144);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 59, 55], 1145);
                step(f, Op::Copy(ValueType::Bone), &[0, 17], 1146);
                step(f, Op::Copy(ValueType::Int), &[3, 61], 1147);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 61, 71], 1148);
                step(f, Op::BreakTransform, &[71, 296, 52, 297], 1149);
                step(f, Op::MakeVector, &[804, 804, 48, 306], 1150);
                step(f, Op::AddV, &[296, 306, 307], 1151);
                step(f, Op::GetTransform, &[17, 72, 98, 73], 1152);
                step(f, Op::BreakTransform, &[73, 301, 54, 302], 1153);
                step(f, Op::MakeTransform, &[307, 54, 421, 75], 1154);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 61, 20], 1155);
                step(f, Op::GetTransform, &[20, 72, 98, 74], 1156);
                step(f, Op::BreakTransform, &[74, 303, 55, 304], 1157);
                step(f, Op::SubV, &[303, 301, 305], 1158);
                step(f, Op::AddV, &[307, 305, 308], 1159);
                step(f, Op::FootPivots, &[307, 308, 50, 49, 48, 51, 309, 310, 311], 1160);
                step(f, Op::GetParent, &[17, 18], 1161);
                step(f, Op::GetParent, &[18, 19], 1162);
                step(f, Op::GetTransform, &[19, 72, 99, 72], 1163);
                step(f, Op::BreakTransform, &[72, 298, 53, 299], 1164);
                step(f, Op::SubV, &[296, 298, 300], 1165);
                step(f, Op::DotV, &[300, 424, 627], 1166);
                step(f, Op::RemapF, &[627, 81, 80, 82, 804, 98, 630], 1167);
                step(f, Op::LengthV, &[2, 628], 1168);
                step(f, Op::RemapF, &[628, 804, 92, 804, 806, 98, 629], 1169);
                step(f, Op::MulF, &[630, 629, 631], 1170);
                step(f, Op::QuatFromAxisAngle, &[426, 631, 56], 1171);
                step(f, Op::RotateAroundPoint, &[75, 309, 56, 76], 1172);
                step(f, Op::ArrayAt(Elem::Float), &[2, 61, 632], 1173);
                step(f, Op::Copy(ValueType::Float), &[632, 634], 1174);
                step(f, Op::Copy(ValueType::Float), &[804, 635], 1175);
                step(f, Op::DivF, &[634, 86, 636], 1176);
                step(f, Op::ClampF, &[636, 804, 806, 637], 1177);
                step(f, Op::MulF, &[637, 637, 638], 1178);
                step(f, Op::MulF, &[637, 809, 639], 1179);
                step(f, Op::SubF, &[810, 639, 640], 1180);
                step(f, Op::MulF, &[638, 640, 641], 1181);
                step(f, Op::Copy(ValueType::Float), &[641, 635], 1182);
                step(f, Op::Jump, &[1183], 1183)
            }
            1183 => {
                step(f, Op::SubF, &[806, 632, 633], 1184);
                step(f, Op::Copy(ValueType::Float), &[633, 642], 1185);
                step(f, Op::Copy(ValueType::Float), &[804, 643], 1186);
                step(f, Op::DivF, &[642, 86, 644], 1187);
                step(f, Op::ClampF, &[644, 804, 806, 645], 1188);
                step(f, Op::MulF, &[645, 645, 646], 1189);
                step(f, Op::MulF, &[645, 809, 647], 1190);
                step(f, Op::SubF, &[810, 647, 648], 1191);
                step(f, Op::MulF, &[646, 648, 649], 1192);
                step(f, Op::Copy(ValueType::Float), &[649, 643], 1193);
                step(f, Op::Jump, &[1194], 1194)
            }
            1194 => {
                step(f, Op::MulF, &[635, 643, 650], 1195);
                step(f, Op::LerpF, &[85, 806, 650, 651], 1196);
                step(f, Op::MulF, &[631, 651, 652], 1197);
                step(f, Op::QuatFromAxisAngle, &[426, 652, 57], 1198);
                step(f, Op::SubV, &[310, 309, 312], 1199);
                step(f, Op::RotateVector, &[57, 312, 313], 1200);
                step(f, Op::AddV, &[309, 313, 314], 1201);
                step(f, Op::RemapF, &[627, 83, 81, 84, 804, 98, 653], 1202);
                step(f, Op::MulF, &[653, 629, 654], 1203);
                step(f, Op::QuatFromAxisAngle, &[426, 654, 58], 1204);
                step(f, Op::RotateAroundPoint, &[76, 314, 58, 77], 1205);
                step(f, Op::RemapF, &[627, 87, 88, 804, 89, 98, 655], 1206);
                step(f, Op::RotateVector, &[52, 423, 315], 1207);
                step(f, Op::BreakVector, &[315, 656, 657, 658], 1208);
                step(f, Op::CosF, &[91, 660], 1209);
                step(f, Op::CosF, &[90, 659], 1210);
                step(f, Op::RemapF, &[658, 660, 659, 804, 806, 98, 661], 1211);
                step(f, Op::MulF, &[629, 661, 662], 1212);
                step(f, Op::MulF, &[655, 662, 663], 1213);
                step(f, Op::QuatFromAxisAngle, &[426, 663, 59], 1214);
                step(f, Op::RotateAroundPoint, &[77, 311, 59, 78], 1215);
                step(f, Op::SubF, &[806, 13, 664], 1216);
                step(f, Op::MulF, &[12, 664, 665], 1217);
                step(f, Op::LimitRotationAroundZ, &[52, 665, 93, 60], 1218);
                step(f, Op::RotateAroundPoint, &[78, 296, 60, 79], 1219);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 61, 79], 1220);
                step(f, Op::JumpIfFalse, &[8, 1226], 1221)
            }
            1221 => {
                step(f, Op::DrawPoint, &[311, 810, 426], 1222);
                step(f, Op::DrawPoint, &[309, 810, 424], 1223);
                step(f, Op::DrawPoint, &[314, 810, 423], 1224);
                step(f, Op::DrawTransform, &[71, 821, 805], 1225);
                step(f, Op::Jump, &[1226], 1226)
            }
            1226 => {
                step(f, Op::Jump, &[550], 1227)
            }
            1227 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1228);
                step(f, Op::Copy(ValueType::Int), &[72, 5], 1229);
                1229
            }
            1229 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 5, 1, 6, 7, 1271], 1230)
            }
            1230 => {
                step(f, Op::Copy(ValueType::Bone), &[1, 21], 1231);
                step(f, Op::Copy(ValueType::Int), &[6, 62], 1232);
                step(f, Op::GetParent, &[21, 22], 1233);
                step(f, Op::GetParent, &[22, 23], 1234);
                step(f, Op::GetParent, &[23, 24], 1235);
                step(f, Op::GetTransform, &[24, 72, 99, 80], 1236);
                step(f, Op::BreakTransform, &[80, 316, 61, 317], 1237);
                step(f, Op::LengthV, &[1, 667], 1238);
                step(f, Op::ClavicleOffset, &[10, 667, 98, 101, 668], 1239);
                step(f, Op::MakeVector, &[804, 804, 668, 318], 1240);
                step(f, Op::AddV, &[316, 318, 319], 1241);
                step(f, Op::MakeTransform, &[319, 61, 421, 81], 1242);
                step(f, Op::SetTransform, &[24, 81, 72, 98, 806], 1243);
                step(f, Op::GetTransform, &[21, 72, 99, 82], 1244);
                step(f, Op::GetTransform, &[23, 72, 99, 83], 1245);
                step(f, Op::BreakTransform, &[83, 320, 63, 321], 1246);
                step(f, Op::Equals(Elem::Int), &[62, 72, 81], 1247);
                step(f, Op::Select(ValueType::Int), &[81, 73, 72, 63], 1248);
                step(f, Op::ArrayAt(Elem::Float), &[0, 63, 666], 1249);
                step(f, Op::ArmSwingRotation, &[666, 1, 0, 99, 813, 822, 806, 98, 96, 97, 813, 813, 806, 669], 1250);
                step(f, Op::QuatFromAxisAngle, &[426, 669, 62], 1251);
                step(f, Op::RotateAroundPoint, &[82, 320, 62, 84], 1252);
                step(f, Op::BreakTransform, &[84, 322, 64, 323], 1253);
                step(f, Op::RemapF, &[667, 804, 98, 804, 100, 98, 670], 1254);
                step(f, Op::MakeVector, &[804, 804, 670, 324], 1255);
                step(f, Op::AddV, &[322, 324, 325], 1256);
                step(f, Op::MakeTransform, &[325, 64, 421, 85], 1257);
                step(f, Op::Select(ValueType::Vec3), &[81, 427, 426, 327], 1258);
                step(f, Op::Select(ValueType::Vec3), &[81, 424, 428, 328], 1259);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 62, 326], 1260);
                step(f, Op::TwoBoneIK, &[23, 22, 21, 85, 327, 328, 326, 72, 806, 99, 823, 824, 98, 82, 671], 1261);
                step(f, Op::JumpIfFalse, &[8, 1270], 1262)
            }
            1262 => {
                step(f, Op::GetTransform, &[23, 72, 99, 83], 1263);
                step(f, Op::BreakTransform, &[83, 320, 63, 321], 1264);
                step(f, Op::GetTransform, &[21, 72, 99, 82], 1265);
                step(f, Op::RotateAroundPoint, &[82, 320, 62, 84], 1266);
                step(f, Op::BreakTransform, &[84, 322, 64, 323], 1267);
                step(f, Op::AddV, &[322, 324, 325], 1268);
                step(f, Op::DrawLine, &[320, 325, 805, 424], 1269);
                step(f, Op::Jump, &[1270], 1270)
            }
            1270 => {
                step(f, Op::Jump, &[1229], 1271)
            }
            1271 => {
                step(f, Op::Copy(ValueType::Float), &[804, 674], 1272);
                step(f, Op::Copy(ValueType::Float), &[811, 675], 1273);
                step(f, Op::Copy(ValueType::Bool), &[99, 83], 1274);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 10], 1275);
                step(f, Op::Copy(ValueType::Int), &[72, 64], 1276);
                step(f, Op::MakeVector, &[804, 804, 53, 331], 1277);
                1277
            }
            1277 => {
                step(f, Op::ForEachNext(Elem::Transform), &[10, 64, 86, 65, 66, 1290], 1278)
            }
            1278 => {
                step(f, Op::BreakTransform, &[86, 329, 65, 330], 1279);
                step(f, Op::AddV, &[329, 331, 332], 1280);
                step(f, Op::SubV, &[329, 331, 333], 1281);
                step(f, Op::SphereTrace, &[332, 333, 52, 84, 334, 335, 676], 1282);
                step(f, Op::BreakVector, &[334, 677, 678, 679], 1283);
                step(f, Op::LessF, &[679, 675, 85], 1284);
                step(f, Op::And, &[84, 85, 86], 1285);
                step(f, Op::JumpIfFalse, &[86, 1289], 1286)
            }
            1286 => {
                step(f, Op::Copy(ValueType::Float), &[679, 675], 1287);
                step(f, Op::Copy(ValueType::Bool), &[98, 83], 1288);
                step(f, Op::Jump, &[1289], 1289)
            }
            1289 => {
                step(f, Op::Jump, &[1277], 1290)
            }
            1290 => {
                step(f, Op::Select(ValueType::Float), &[83, 675, 804, 680], 1291);
                step(f, Op::ClampF, &[680, 57, 58, 681], 1292);
                step(f, Op::Copy(ValueType::Float), &[681, 674], 1293);
                step(f, Op::Jump, &[1294], 1294)
            }
            1294 => {
                step(f, Op::SubF, &[806, 19, 673], 1295);
                step(f, Op::MulF, &[674, 673, 682], 1296);
                step(f, Op::MakeVector, &[14, 804, 804, 336], 1297);
                step(f, Op::MakeVector, &[682, 804, 804, 337], 1298);
                step(f, Op::Select(ValueType::Float), &[2, 682, 15, 683], 1299);
                step(f, Op::MakeVector, &[683, 804, 804, 338], 1300);
                step(f, Op::Copy(ValueType::Vec3), &[336, 339], 1301);
                step(f, Op::Copy(ValueType::Vec3), &[337, 340], 1302);
                step(f, Op::Copy(ValueType::Vec3), &[338, 341], 1303);
                step(f, Op::Copy(ValueType::Float), &[46, 684], 1304);
                step(f, Op::Copy(ValueType::Float), &[47, 685], 1305);
                step(f, Op::Copy(ValueType::Vec3), &[420, 342], 1306);
                step(f, Op::SubV, &[340, 341, 343], 1307);
                step(f, Op::DeltaTime, &[686], 1308);
                step(f, Op::DivF, &[685, 686, 687], 1309);
                step(f, Op::ScaleV, &[343, 687, 344], 1310);
                step(f, Op::AddV, &[340, 344, 345], 1311);
                step(f, Op::AddV, &[341, 344, 346], 1312);
                step(f, Op::SubV, &[339, 346, 347], 1313);
                step(f, Op::FloatLerp, &[804, 806, 684, 688], 1314);
                step(f, Op::SubF, &[806, 688, 689], 1315);
                step(f, Op::ScaleV, &[347, 689, 348], 1316);
                step(f, Op::AddV, &[345, 348, 350], 1317);
                step(f, Op::MulF, &[684, 686, 690], 1318);
                step(f, Op::GreaterF, &[690, 804, 87], 1319);
                step(f, Op::DivF, &[688, 690, 691], 1320);
                step(f, Op::Select(ValueType::Float), &[87, 691, 806, 692], 1321);
                step(f, Op::ScaleV, &[343, 692, 349], 1322);
                step(f, Op::SubV, &[350, 349, 351], 1323);
                step(f, Op::Copy(ValueType::Vec3), &[351, 342], 1324);
                step(f, Op::Jump, &[1325], 1325)
            }
            1325 => {
                step(f, Op::BreakVector, &[342, 693, 694, 695], 1326);
                step(f, Op::Select(ValueType::Float), &[1, 682, 693, 696], 1327);
                step(f, Op::Copy(ValueType::Float), &[696, 14], 1328);
                step(f, Op::Copy(ValueType::Float), &[682, 15], 1329);
                step(f, Op::GetTransform, &[37, 72, 98, 91], 1330);
                step(f, Op::BreakTransform, &[91, 364, 72, 365], 1331);
                step(f, Op::PelvisLean, &[1, 103, 108, 109, 712, 713], 1332);
                step(f, Op::LengthV, &[2, 672], 1333);
                step(f, Op::RemapF, &[672, 804, 103, 804, 102, 98, 697], 1334);
                step(f, Op::MulF, &[10, 825, 698], 1335);
                step(f, Op::SinF, &[698, 699], 1336);
                step(f, Op::MulF, &[697, 699, 700], 1337);
                step(f, Op::MulF, &[700, 673, 701], 1338);
                step(f, Op::AddF, &[701, 14, 702], 1339);
                step(f, Op::MulF, &[3, 120, 703], 1340);
                step(f, Op::SubF, &[702, 703, 704], 1341);
                step(f, Op::MakeVector, &[804, 713, 704, 366], 1342);
                step(f, Op::AddV, &[364, 366, 367], 1343);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 72, 87], 1344);
                step(f, Op::BreakTransform, &[87, 352, 66, 353], 1345);
                step(f, Op::BreakVector, &[352, 714, 715, 716], 1346);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 73, 88], 1347);
                step(f, Op::BreakTransform, &[88, 354, 67, 355], 1348);
                step(f, Op::BreakVector, &[354, 717, 718, 719], 1349);
                step(f, Op::SubF, &[716, 719, 720], 1350);
                step(f, Op::PelvisSideLean, &[720, 110, 111, 721], 1351);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 72, 89], 1352);
                step(f, Op::BreakTransform, &[89, 358, 68, 359], 1353);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 73, 90], 1354);
                step(f, Op::BreakTransform, &[90, 360, 69, 361], 1355);
                step(f, Op::SlerpQ, &[68, 69, 805, 70], 1356);
                step(f, Op::EulerFromQuat, &[70, 72, 362], 1357);
                step(f, Op::BreakVector, &[362, 708, 709, 710], 1358);
                step(f, Op::RemapF, &[672, 104, 103, 804, 105, 98, 706], 1359);
                step(f, Op::SubV, &[352, 354, 356], 1360);
                step(f, Op::RotateVector, &[0, 424, 357], 1361);
                step(f, Op::DotV, &[356, 357, 705], 1362);
                step(f, Op::MulF, &[706, 705, 707], 1363);
                step(f, Op::AddF, &[710, 707, 711], 1364);
                step(f, Op::MakeVector, &[712, 721, 711, 363], 1365);
                step(f, Op::QuatFromEuler, &[363, 72, 71], 1366);
                step(f, Op::MakeTransform, &[367, 71, 421, 92], 1367);
                step(f, Op::SetTransform, &[38, 92, 72, 98, 806], 1368);
                step(f, Op::GetTransform, &[39, 73, 98, 93], 1369);
                step(f, Op::BreakTransform, &[93, 368, 76, 369], 1370);
                step(f, Op::QuatFromAxisAngle, &[423, 707, 73], 1371);
                step(f, Op::DivF, &[106, 810, 722], 1372);
                step(f, Op::QuatScale, &[73, 722, 74], 1373);
                step(f, Op::MulQ, &[76, 74, 80], 1374);
                step(f, Op::MakeTransform, &[368, 80, 421, 97], 1375);
                step(f, Op::SetTransform, &[40, 97, 73, 98, 806], 1376);
                step(f, Op::GetTransform, &[41, 73, 98, 94], 1377);
                step(f, Op::BreakTransform, &[94, 370, 77, 371], 1378);
                step(f, Op::MulQ, &[77, 74, 81], 1379);
                step(f, Op::MakeTransform, &[370, 81, 421, 98], 1380);
                step(f, Op::SetTransform, &[42, 98, 73, 98, 806], 1381);
                step(f, Op::GetTransform, &[43, 73, 98, 95], 1382);
                step(f, Op::BreakTransform, &[95, 372, 78, 373], 1383);
                step(f, Op::MulQ, &[78, 74, 82], 1384);
                step(f, Op::MakeTransform, &[372, 82, 421, 99], 1385);
                step(f, Op::SetTransform, &[44, 99, 73, 98, 806], 1386);
                step(f, Op::GetTransform, &[45, 73, 98, 96], 1387);
                step(f, Op::BreakTransform, &[96, 374, 79, 375], 1388);
                step(f, Op::QuatScale, &[73, 107, 75], 1389);
                step(f, Op::MulQ, &[79, 75, 83], 1390);
                step(f, Op::MakeTransform, &[374, 83, 421, 100], 1391);
                step(f, Op::SetTransform, &[46, 100, 73, 98, 806], 1392);
                step(f, Op::Or, &[1, 2, 93], 1393);
                step(f, Op::Copy(ValueType::Float), &[804, 723], 1394);
                step(f, Op::Copy(ValueType::Float), &[804, 724], 1395);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1396);
                step(f, Op::Copy(ValueType::Int), &[72, 67], 1397);
                step(f, Op::SubF, &[806, 13, 756], 1398);
                1398
            }
            1398 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 67, 25, 68, 69, 1446], 1399)
            }
            1399 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 68, 88], 1400);
                step(f, Op::GetParent, &[25, 26], 1401);
                step(f, Op::GetParent, &[26, 27], 1402);
                step(f, Op::GetTransform, &[27, 72, 99, 101], 1403);
                step(f, Op::BreakTransform, &[101, 376, 84, 377], 1404);
                step(f, Op::BreakVector, &[376, 725, 726, 727], 1405);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 68, 102], 1406);
                step(f, Op::BreakTransform, &[102, 378, 85, 379], 1407);
                step(f, Op::BreakVector, &[378, 728, 729, 730], 1408);
                step(f, Op::ArrayAt(Elem::Float), &[1, 68, 734], 1409);
                step(f, Op::MulF, &[734, 112, 735], 1410);
                step(f, Op::MulF, &[735, 735, 736], 1411);
                step(f, Op::SubF, &[725, 728, 731], 1412);
                step(f, Op::SubF, &[726, 729, 732], 1413);
                step(f, Op::MakeVector, &[731, 732, 804, 380], 1414);
                step(f, Op::DotV, &[380, 380, 733], 1415);
                step(f, Op::SubF, &[736, 733, 737], 1416);
                step(f, Op::SqrtF, &[737, 738], 1417);
                step(f, Op::AddF, &[730, 738, 739], 1418);
                step(f, Op::SubF, &[727, 739, 740], 1419);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 68, 103], 1420);
                step(f, Op::BreakTransform, &[103, 381, 86, 382], 1421);
                step(f, Op::BreakVector, &[381, 741, 742, 743], 1422);
                step(f, Op::AddF, &[743, 48, 744], 1423);
                step(f, Op::MinF, &[730, 744, 745], 1424);
                step(f, Op::AddF, &[745, 738, 746], 1425);
                step(f, Op::SubF, &[727, 746, 747], 1426);
                step(f, Op::Equals(Elem::Int), &[68, 72, 89], 1427);
                step(f, Op::Select(ValueType::Int), &[89, 73, 72, 70], 1428);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 70, 90], 1429);
                step(f, Op::ArrayAt(Elem::Float), &[2, 70, 751], 1430);
                step(f, Op::RemapF, &[751, 805, 806, 804, 806, 98, 752], 1431);
                step(f, Op::RemapF, &[751, 804, 115, 806, 804, 98, 753], 1432);
                step(f, Op::MaxF, &[752, 753, 754], 1433);
                step(f, Op::Select(ValueType::Float), &[90, 806, 754, 755], 1434);
                step(f, Op::MulF, &[755, 756, 757], 1435);
                step(f, Op::LerpF, &[740, 747, 757, 758], 1436);
                step(f, Op::ArrayAt(Elem::Float), &[2, 68, 748], 1437);
                step(f, Op::RemapF, &[748, 805, 806, 804, 806, 98, 749], 1438);
                step(f, Op::MulF, &[758, 749, 759], 1439);
                step(f, Op::RemapF, &[748, 804, 115, 806, 804, 98, 750], 1440);
                step(f, Op::MulF, &[740, 750, 760], 1441);
                step(f, Op::MaxF, &[759, 760, 761], 1442);
                step(f, Op::Select(ValueType::Float), &[88, 740, 761, 762], 1443);
                step(f, Op::MaxF, &[724, 762, 763], 1444);
                step(f, Op::Copy(ValueType::Float), &[763, 724], 1445);
                step(f, Op::Jump, &[1398], 1446)
            }
            1446 => {
                step(f, Op::ClampF, &[724, 804, 113, 764], 1447);
                step(f, Op::Copy(ValueType::Float), &[764, 723], 1448);
                step(f, Op::Jump, &[1449], 1449)
            }
            1449 => {
                step(f, Op::MakeVector, &[16, 804, 804, 383], 1450);
                step(f, Op::MakeVector, &[723, 804, 804, 384], 1451);
                step(f, Op::MakeVector, &[17, 804, 804, 385], 1452);
                step(f, Op::GreaterF, &[723, 16, 91], 1453);
                step(f, Op::Select(ValueType::Float), &[91, 117, 114, 765], 1454);
                step(f, Op::Copy(ValueType::Vec3), &[383, 386], 1455);
                step(f, Op::Copy(ValueType::Vec3), &[384, 387], 1456);
                step(f, Op::Copy(ValueType::Vec3), &[385, 388], 1457);
                step(f, Op::Copy(ValueType::Float), &[765, 766], 1458);
                step(f, Op::Copy(ValueType::Float), &[47, 767], 1459);
                step(f, Op::Copy(ValueType::Vec3), &[420, 389], 1460);
                step(f, Op::SubV, &[387, 388, 390], 1461);
                step(f, Op::DeltaTime, &[768], 1462);
                step(f, Op::DivF, &[767, 768, 769], 1463);
                step(f, Op::ScaleV, &[390, 769, 391], 1464);
                step(f, Op::AddV, &[387, 391, 392], 1465);
                step(f, Op::AddV, &[388, 391, 393], 1466);
                step(f, Op::SubV, &[386, 393, 394], 1467);
                step(f, Op::FloatLerp, &[804, 806, 766, 770], 1468);
                step(f, Op::SubF, &[806, 770, 771], 1469);
                step(f, Op::ScaleV, &[394, 771, 395], 1470);
                step(f, Op::AddV, &[392, 395, 397], 1471);
                step(f, Op::MulF, &[766, 768, 772], 1472);
                step(f, Op::GreaterF, &[772, 804, 92], 1473);
                step(f, Op::DivF, &[770, 772, 773], 1474);
                step(f, Op::Select(ValueType::Float), &[92, 773, 806, 774], 1475);
                step(f, Op::ScaleV, &[390, 774, 396], 1476);
                step(f, Op::SubV, &[397, 396, 398], 1477);
                step(f, Op::Copy(ValueType::Vec3), &[398, 389], 1478);
                step(f, Op::Jump, &[1479], 1479)
            }
            1479 => {
                step(f, Op::BreakVector, &[389, 775, 776, 777], 1480);
                step(f, Op::Select(ValueType::Float), &[93, 723, 775, 778], 1481);
                step(f, Op::Copy(ValueType::Float), &[778, 16], 1482);
                step(f, Op::Copy(ValueType::Float), &[723, 17], 1483);
                step(f, Op::GetTransform, &[47, 72, 99, 104], 1484);
                step(f, Op::BreakTransform, &[104, 399, 87, 400], 1485);
                step(f, Op::MakeVector, &[804, 804, 16, 401], 1486);
                step(f, Op::SubV, &[399, 401, 402], 1487);
                step(f, Op::MakeTransform, &[402, 87, 421, 105], 1488);
                step(f, Op::SetTransform, &[48, 105, 72, 98, 806], 1489);
                step(f, Op::JumpIfFalse, &[8, 1496], 1490)
            }
            1490 => {
                step(f, Op::GetTransform, &[47, 72, 99, 104], 1491);
                step(f, Op::BreakTransform, &[104, 399, 87, 400], 1492);
                step(f, Op::SubV, &[399, 401, 402], 1493);
                step(f, Op::MakeTransform, &[402, 87, 421, 105], 1494);
                step(f, Op::DrawTransform, &[105, 826, 805], 1495);
                step(f, Op::Jump, &[1496], 1496)
            }
            1496 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1497);
                step(f, Op::Copy(ValueType::Int), &[72, 8], 1498);
                1498
            }
            1498 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 8, 2, 9, 10, 1553], 1499)
            }
            1499 => {
                step(f, Op::Copy(ValueType::Bone), &[2, 28], 1500);
                step(f, Op::Copy(ValueType::Int), &[9, 71], 1501);
                step(f, Op::GetParent, &[28, 29], 1502);
                step(f, Op::GetParent, &[29, 30], 1503);
                step(f, Op::GetTransform, &[30, 72, 99, 106], 1504);
                step(f, Op::BreakTransform, &[106, 403, 88, 404], 1505);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 71, 107], 1506);
                step(f, Op::BreakTransform, &[107, 405, 89, 406], 1507);
                step(f, Op::SubV, &[405, 403, 407], 1508);
                step(f, Op::LengthV, &[407, 794], 1509);
                step(f, Op::ArrayAt(Elem::Float), &[1, 71, 779], 1510);
                step(f, Op::MulF, &[779, 123, 780], 1511);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 71, 94], 1512);
                step(f, Op::ArrayAt(Elem::Float), &[2, 71, 781], 1513);
                step(f, Op::ClampF, &[781, 804, 806, 782], 1514);
                step(f, Op::LessF, &[782, 805, 95], 1515);
                step(f, Op::RemapF, &[782, 125, 126, 804, 806, 98, 785], 1516);
                step(f, Op::MulF, &[785, 785, 786], 1517);
                step(f, Op::MulF, &[785, 809, 787], 1518);
                step(f, Op::SubF, &[810, 787, 788], 1519);
                step(f, Op::MulF, &[786, 788, 789], 1520);
                step(f, Op::MulF, &[782, 814, 783], 1521);
                step(f, Op::SinF, &[783, 784], 1522);
                step(f, Op::MaxF, &[789, 784, 790], 1523);
                step(f, Op::Select(ValueType::Float), &[95, 790, 784, 791], 1524);
                step(f, Op::MulF, &[791, 124, 792], 1525);
                step(f, Op::Select(ValueType::Float), &[94, 804, 792, 793], 1526);
                step(f, Op::SubF, &[780, 793, 795], 1527);
                step(f, Op::SubF, &[794, 795, 796], 1528);
                step(f, Op::MaxF, &[796, 804, 797], 1529);
                step(f, Op::MulF, &[797, 797, 798], 1530);
                step(f, Op::AddF, &[797, 793, 799], 1531);
                step(f, Op::DivF, &[798, 799, 800], 1532);
                step(f, Op::SubF, &[794, 800, 801], 1533);
                step(f, Op::DivF, &[801, 794, 802], 1534);
                step(f, Op::ScaleV, &[407, 802, 408], 1535);
                step(f, Op::AddV, &[403, 408, 409], 1536);
                step(f, Op::ClampSpatially, &[409, 403, 804, 780, 410], 1537);
                step(f, Op::MakeTransform, &[410, 89, 421, 108], 1538);
                step(f, Op::Equals(Elem::Int), &[71, 72, 96], 1539);
                step(f, Op::Select(ValueType::Vec3), &[96, 427, 426, 415], 1540);
                step(f, Op::Select(ValueType::Vec3), &[96, 424, 428, 416], 1541);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 71, 109], 1542);
                step(f, Op::BreakTransform, &[109, 411, 90, 412], 1543);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 71, 413], 1544);
                step(f, Op::KneeVector, &[90, 0, 413, 127, 128, 414], 1545);
                step(f, Op::TwoBoneIK, &[30, 29, 28, 108, 415, 416, 414, 72, 806, 99, 823, 824, 98, 97, 803], 1546);
                step(f, Op::JumpIfFalse, &[8, 1552], 1547)
            }
            1547 => {
                step(f, Op::GetTransform, &[29, 72, 99, 110], 1548);
                step(f, Op::BreakTransform, &[110, 417, 91, 418], 1549);
                step(f, Op::AddV, &[417, 414, 419], 1550);
                step(f, Op::DrawLine, &[417, 419, 805, 429], 1551);
                step(f, Op::Jump, &[1552], 1552)
            }
            1552 => {
                step(f, Op::Jump, &[1498], 1553)
            }
            1553 => {
                step(f, Op::End, &[], 1554)
            }
            _ => return,
        } };
    }
}
