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
    fingerprint: 0x5302d2fb32fee133,
    forward,
};

fn forward(f: &mut Frame<'_>) {
    let mut pc: usize = 105;
    loop {
        // SAFETY: each `step` is an instruction of the program this code was generated
        // from, with its own operands; `NATIVE` runs only on that program (fingerprint).
        pc = unsafe { match pc {
            105 => {
                step(f, Op::Not, &[0, 9], 106);
                step(f, Op::Copy(ValueType::Bool), &[9, 1], 107);
                step(f, Op::WorldTransform, &[12], 108);
                step(f, Op::BreakTransform, &[12, 33, 7, 34], 109);
                step(f, Op::Select(ValueType::Transform), &[0, 0, 12, 13], 110);
                step(f, Op::BreakTransform, &[13, 35, 8, 36], 111);
                step(f, Op::SubV, &[33, 35, 37], 112);
                step(f, Op::LengthV, &[37, 149], 113);
                step(f, Op::GreaterF, &[149, 35, 10], 114);
                step(f, Op::Copy(ValueType::Bool), &[10, 2], 115);
                step(f, Op::MakeRelative, &[13, 12, 17], 116);
                step(f, Op::Select(ValueType::Transform), &[10, 121, 17, 18], 117);
                step(f, Op::Copy(ValueType::Transform), &[18, 2], 118);
                step(f, Op::InverseT, &[13, 15], 119);
                step(f, Op::MulT, &[12, 15, 16], 120);
                step(f, Op::Copy(ValueType::Transform), &[16, 1], 121);
                step(f, Op::TransformVector, &[2, 0, 42], 122);
                step(f, Op::InverseT, &[12, 14], 123);
                step(f, Op::DeltaTime, &[148], 124);
                step(f, Op::DivF, &[888, 148, 150], 125);
                step(f, Op::ScaleV, &[37, 150, 38], 126);
                step(f, Op::TransformVector, &[14, 38, 39], 127);
                step(f, Op::BreakVector, &[39, 151, 152, 153], 128);
                step(f, Op::MakeVector, &[151, 152, 886, 40], 129);
                step(f, Op::LengthV, &[40, 154], 130);
                step(f, Op::MulF, &[154, 130, 155], 131);
                step(f, Op::NegF, &[155, 156], 132);
                step(f, Op::ClampF, &[153, 156, 155, 157], 133);
                step(f, Op::MakeVector, &[151, 152, 157, 41], 134);
                step(f, Op::Select(ValueType::Vec3), &[2, 42, 41, 44], 135);
                step(f, Op::VectorLerp, &[42, 44, 36, 886, 45], 136);
                step(f, Op::Copy(ValueType::Vec3), &[45, 0], 137);
                step(f, Op::TransformVector, &[2, 1, 43], 138);
                step(f, Op::TransformVector, &[2, 0, 42], 139);
                step(f, Op::Select(ValueType::Vec3), &[2, 42, 41, 44], 140);
                step(f, Op::VectorLerp, &[43, 44, 37, 886, 46], 141);
                step(f, Op::Copy(ValueType::Vec3), &[46, 1], 142);
                step(f, Op::LengthV, &[44, 164], 143);
                step(f, Op::Copy(ValueType::Float), &[164, 0], 144);
                step(f, Op::BreakVector, &[37, 158, 159, 160], 145);
                step(f, Op::MulF, &[157, 148, 161], 146);
                step(f, Op::SubF, &[160, 161, 162], 147);
                step(f, Op::Select(ValueType::Float), &[10, 886, 162, 163], 148);
                step(f, Op::Copy(ValueType::Float), &[163, 1], 149);
                step(f, Op::JumpIfFalse, &[2, 163], 150)
            }
            150 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 12], 151);
                step(f, Op::Copy(ValueType::Int), &[71, 17], 152);
                152
            }
            152 => {
                step(f, Op::ForEachNext(Elem::Bone), &[12, 17, 13, 18, 19, 162], 153)
            }
            153 => {
                step(f, Op::ArrayAt(Elem::Transform), &[8, 18, 20], 154);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 18, 20], 155);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 18, 20], 156);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 18, 20], 157);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 18, 20], 158);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 18, 20], 159);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 18, 20], 160);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 18, 20], 161);
                step(f, Op::Jump, &[152], 162)
            }
            162 => {
                step(f, Op::Copy(ValueType::Float), &[886, 16], 163);
                163
            }
            163 => {
                step(f, Op::Copy(ValueType::Transform), &[12, 0], 164);
                step(f, Op::Copy(ValueType::Bool), &[125, 0], 165);
                step(f, Op::JumpIfFalse, &[8, 171], 166)
            }
            166 => {
                step(f, Op::GetTransform, &[33, 71, 125, 19], 167);
                step(f, Op::BreakTransform, &[19, 47, 9, 48], 168);
                step(f, Op::ScaleV, &[0, 889, 49], 169);
                step(f, Op::AddV, &[47, 49, 50], 170);
                step(f, Op::DrawArrow, &[47, 50, 887, 479], 171);
                171
            }
            171 => {
                step(f, Op::Copy(ValueType::Float), &[886, 165], 172);
                step(f, Op::Copy(ValueType::Float), &[888, 166], 173);
                step(f, Op::Copy(ValueType::Bool), &[126, 12], 174);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[8, 9], 175);
                step(f, Op::Copy(ValueType::Int), &[71, 25], 176);
                step(f, Op::MakeVector, &[886, 886, 57, 55], 177);
                177
            }
            177 => {
                step(f, Op::ForEachNext(Elem::Transform), &[9, 25, 21, 26, 27, 187], 178)
            }
            178 => {
                step(f, Op::BreakTransform, &[21, 51, 10, 52], 179);
                step(f, Op::TransformPoint, &[2, 51, 53], 180);
                step(f, Op::LerpV, &[53, 51, 888, 54], 181);
                step(f, Op::AddV, &[54, 55, 56], 182);
                step(f, Op::SubV, &[54, 55, 57], 183);
                step(f, Op::LineTrace, &[56, 57, 13, 58, 59, 168], 184);
                step(f, Op::JumpIfFalse, &[13, 186], 185)
            }
            185 => {
                step(f, Op::Copy(ValueType::Bool), &[125, 12], 186);
                186
            }
            186 => {
                step(f, Op::Jump, &[177], 187)
            }
            187 => {
                step(f, Op::Copy(ValueType::Bool), &[12, 11], 188);
                step(f, Op::Or, &[11, 7, 14], 189);
                step(f, Op::NotEquals(Elem::Bool), &[14, 5, 15], 190);
                step(f, Op::JumpIfFalse, &[15, 219], 191)
            }
            191 => {
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 192);
                step(f, Op::JumpIfFalse, &[16, 219], 193)
            }
            193 => {
                step(f, Op::Copy(ValueType::Int), &[1, 24], 194);
                step(f, Op::Copy(ValueType::Int), &[71, 20], 195);
                195
            }
            195 => {
                step(f, Op::ForNext, &[20, 24, 22, 219], 196)
            }
            196 => {
                step(f, Op::AddF, &[165, 166, 169], 197);
                step(f, Op::MulF, &[169, 887, 170], 198);
                step(f, Op::Copy(ValueType::Bool), &[126, 18], 199);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[8, 10], 200);
                step(f, Op::Copy(ValueType::Int), &[71, 28], 201);
                step(f, Op::MakeVector, &[886, 886, 57, 64], 202);
                202
            }
            202 => {
                step(f, Op::ForEachNext(Elem::Transform), &[10, 28, 22, 29, 30, 212], 203)
            }
            203 => {
                step(f, Op::BreakTransform, &[22, 60, 11, 61], 204);
                step(f, Op::TransformPoint, &[2, 60, 62], 205);
                step(f, Op::LerpV, &[62, 60, 170, 63], 206);
                step(f, Op::AddV, &[63, 64, 65], 207);
                step(f, Op::SubV, &[63, 64, 66], 208);
                step(f, Op::LineTrace, &[65, 66, 19, 67, 68, 172], 209);
                step(f, Op::JumpIfFalse, &[19, 211], 210)
            }
            210 => {
                step(f, Op::Copy(ValueType::Bool), &[125, 18], 211);
                211
            }
            211 => {
                step(f, Op::Jump, &[202], 212)
            }
            212 => {
                step(f, Op::Copy(ValueType::Bool), &[18, 17], 213);
                step(f, Op::Equals(Elem::Bool), &[17, 6, 20], 214);
                step(f, Op::JumpIfFalse, &[20, 217], 215)
            }
            215 => {
                step(f, Op::Copy(ValueType::Float), &[170, 165], 216);
                step(f, Op::Jump, &[218], 217)
            }
            217 => {
                step(f, Op::Copy(ValueType::Float), &[170, 166], 218);
                218
            }
            218 => {
                step(f, Op::Jump, &[195], 219)
            }
            219 => {
                step(f, Op::Select(ValueType::Float), &[5, 890, 888, 178], 220);
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 221);
                step(f, Op::AddF, &[165, 166, 169], 222);
                step(f, Op::MulF, &[169, 887, 173], 223);
                step(f, Op::Select(ValueType::Float), &[16, 173, 887, 174], 224);
                step(f, Op::Select(ValueType::Float), &[15, 174, 886, 180], 225);
                step(f, Op::MulF, &[178, 180, 182], 226);
                step(f, Op::DeltaTime, &[176], 227);
                step(f, Op::DivF, &[176, 134, 177], 228);
                step(f, Op::MulF, &[182, 177, 183], 229);
                step(f, Op::AddF, &[20, 183, 184], 230);
                step(f, Op::ClampF, &[184, 886, 888, 185], 231);
                step(f, Op::Select(ValueType::Float), &[14, 890, 888, 179], 232);
                step(f, Op::SubF, &[888, 174, 175], 233);
                step(f, Op::Select(ValueType::Float), &[15, 175, 888, 181], 234);
                step(f, Op::MulF, &[179, 181, 186], 235);
                step(f, Op::MulF, &[186, 177, 187], 236);
                step(f, Op::AddF, &[185, 187, 188], 237);
                step(f, Op::ClampF, &[188, 886, 888, 189], 238);
                step(f, Op::SmoothStepF, &[189, 886, 888, 190], 239);
                step(f, Op::AddF, &[21, 190, 191], 240);
                step(f, Op::MulF, &[191, 887, 192], 241);
                step(f, Op::SubF, &[888, 192, 193], 242);
                step(f, Op::MulF, &[193, 193, 194], 243);
                step(f, Op::SubF, &[888, 194, 195], 244);
                step(f, Op::Copy(ValueType::Float), &[195, 22], 245);
                step(f, Op::Copy(ValueType::Float), &[190, 21], 246);
                step(f, Op::Copy(ValueType::Float), &[189, 20], 247);
                step(f, Op::GreaterF, &[21, 886, 21], 248);
                step(f, Op::TransformVector, &[2, 3, 69], 249);
                step(f, Op::Select(ValueType::Vec3), &[21, 69, 0, 70], 250);
                step(f, Op::Copy(ValueType::Vec3), &[70, 3], 251);
                step(f, Op::LerpV, &[0, 3, 21, 71], 252);
                step(f, Op::Select(ValueType::Vec3), &[21, 71, 0, 72], 253);
                step(f, Op::Copy(ValueType::Vec3), &[72, 2], 254);
                step(f, Op::Copy(ValueType::Bool), &[14, 5], 255);
                step(f, Op::Copy(ValueType::Bool), &[11, 6], 256);
                step(f, Op::Copy(ValueType::Bool), &[126, 7], 257);
                step(f, Op::SubF, &[888, 22, 196], 258);
                step(f, Op::MulF, &[1, 196, 197], 259);
                step(f, Op::AddF, &[2, 197, 198], 260);
                step(f, Op::Copy(ValueType::Float), &[4, 199], 261);
                step(f, Op::Copy(ValueType::Float), &[5, 200], 262);
                step(f, Op::Copy(ValueType::Float), &[2, 202], 263);
                step(f, Op::Copy(ValueType::Float), &[131, 203], 264);
                step(f, Op::Copy(ValueType::Float), &[51, 204], 265);
                step(f, Op::SubF, &[198, 202, 209], 266);
                step(f, Op::DeltaTime, &[207], 267);
                step(f, Op::DivF, &[209, 207, 210], 268);
                step(f, Op::MulF, &[210, 204, 211], 269);
                step(f, Op::AddF, &[198, 211, 213], 270);
                step(f, Op::MulF, &[210, 891, 214], 271);
                step(f, Op::DivF, &[892, 203, 208], 272);
                step(f, Op::DivF, &[214, 208, 215], 273);
                step(f, Op::SubF, &[213, 215, 229], 274);
                step(f, Op::AddF, &[202, 211, 212], 275);
                step(f, Op::SubF, &[199, 212, 216], 276);
                step(f, Op::AddF, &[216, 215, 217], 277);
                step(f, Op::SubF, &[200, 210, 218], 278);
                step(f, Op::MulF, &[208, 217, 219], 279);
                step(f, Op::AddF, &[218, 219, 220], 280);
                step(f, Op::MulF, &[220, 207, 223], 281);
                step(f, Op::AddF, &[217, 223, 224], 282);
                step(f, Op::FloatLerp, &[886, 888, 208, 221], 283);
                step(f, Op::SubF, &[888, 221, 222], 284);
                step(f, Op::MulF, &[224, 222, 225], 285);
                step(f, Op::AddF, &[229, 225, 230], 286);
                step(f, Op::Copy(ValueType::Float), &[230, 205], 287);
                step(f, Op::MulF, &[208, 223, 226], 288);
                step(f, Op::SubF, &[218, 226, 227], 289);
                step(f, Op::MulF, &[227, 222, 228], 290);
                step(f, Op::AddF, &[210, 228, 231], 291);
                step(f, Op::Copy(ValueType::Float), &[231, 206], 292);
                step(f, Op::SubF, &[198, 205, 232], 293);
                step(f, Op::Copy(ValueType::Float), &[232, 3], 294);
                step(f, Op::Copy(ValueType::Float), &[205, 4], 295);
                step(f, Op::Copy(ValueType::Float), &[4, 199], 296);
                step(f, Op::Copy(ValueType::Float), &[5, 200], 297);
                step(f, Op::Copy(ValueType::Float), &[2, 202], 298);
                step(f, Op::Copy(ValueType::Float), &[131, 203], 299);
                step(f, Op::Copy(ValueType::Float), &[51, 204], 300);
                step(f, Op::SubF, &[198, 202, 209], 301);
                step(f, Op::DeltaTime, &[207], 302);
                step(f, Op::DivF, &[209, 207, 210], 303);
                step(f, Op::MulF, &[210, 204, 211], 304);
                step(f, Op::AddF, &[198, 211, 213], 305);
                step(f, Op::MulF, &[210, 891, 214], 306);
                step(f, Op::DivF, &[892, 203, 208], 307);
                step(f, Op::DivF, &[214, 208, 215], 308);
                step(f, Op::SubF, &[213, 215, 229], 309);
                step(f, Op::AddF, &[202, 211, 212], 310);
                step(f, Op::SubF, &[199, 212, 216], 311);
                step(f, Op::AddF, &[216, 215, 217], 312);
                step(f, Op::SubF, &[200, 210, 218], 313);
                step(f, Op::MulF, &[208, 217, 219], 314);
                step(f, Op::AddF, &[218, 219, 220], 315);
                step(f, Op::MulF, &[220, 207, 223], 316);
                step(f, Op::AddF, &[217, 223, 224], 317);
                step(f, Op::FloatLerp, &[886, 888, 208, 221], 318);
                step(f, Op::SubF, &[888, 221, 222], 319);
                step(f, Op::MulF, &[224, 222, 225], 320);
                step(f, Op::AddF, &[229, 225, 230], 321);
                step(f, Op::Copy(ValueType::Float), &[230, 205], 322);
                step(f, Op::MulF, &[208, 223, 226], 323);
                step(f, Op::SubF, &[218, 226, 227], 324);
                step(f, Op::MulF, &[227, 222, 228], 325);
                step(f, Op::AddF, &[210, 228, 231], 326);
                step(f, Op::Copy(ValueType::Float), &[231, 206], 327);
                step(f, Op::Copy(ValueType::Float), &[206, 5], 328);
                step(f, Op::Copy(ValueType::Float), &[198, 2], 329);
                step(f, Op::LengthV, &[4, 234], 330);
                step(f, Op::GreaterF, &[234, 29, 22], 331);
                step(f, Op::LengthV, &[2, 235], 332);
                step(f, Op::GreaterF, &[235, 29, 23], 333);
                step(f, Op::And, &[22, 23, 25], 334);
                step(f, Op::Select(ValueType::Vec3), &[22, 4, 478, 73], 335);
                step(f, Op::MovementAngleOffset, &[73, 14, 886, 893, 893, 894, 40, 895, 236], 336);
                step(f, Op::Copy(ValueType::Float), &[14, 239], 337);
                step(f, Op::SubF, &[236, 239, 241], 338);
                step(f, Op::AddF, &[241, 896, 242], 339);
                step(f, Op::DivF, &[242, 897, 243], 340);
                step(f, Op::FractF, &[243, 244], 341);
                step(f, Op::MulF, &[244, 897, 245], 342);
                step(f, Op::SubF, &[245, 896, 246], 343);
                step(f, Op::Copy(ValueType::Float), &[246, 240], 344);
                step(f, Op::AbsF, &[240, 265], 345);
                step(f, Op::Select(ValueType::Vec3), &[23, 2, 478, 74], 346);
                step(f, Op::MovementAngleOffset, &[74, 14, 886, 893, 893, 894, 40, 895, 237], 347);
                step(f, Op::Copy(ValueType::Float), &[14, 248], 348);
                step(f, Op::SubF, &[237, 248, 250], 349);
                step(f, Op::AddF, &[250, 896, 251], 350);
                step(f, Op::DivF, &[251, 897, 252], 351);
                step(f, Op::FractF, &[252, 253], 352);
                step(f, Op::MulF, &[253, 897, 254], 353);
                step(f, Op::SubF, &[254, 896, 255], 354);
                step(f, Op::Copy(ValueType::Float), &[255, 249], 355);
                step(f, Op::AbsF, &[249, 266], 356);
                step(f, Op::MaxF, &[265, 266, 268], 357);
                step(f, Op::SubF, &[237, 236, 259], 358);
                step(f, Op::AddF, &[259, 896, 260], 359);
                step(f, Op::DivF, &[260, 897, 261], 360);
                step(f, Op::FractF, &[261, 262], 361);
                step(f, Op::MulF, &[262, 897, 263], 362);
                step(f, Op::SubF, &[263, 896, 264], 363);
                step(f, Op::Copy(ValueType::Float), &[264, 258], 364);
                step(f, Op::AbsF, &[258, 267], 365);
                step(f, Op::MaxF, &[268, 267, 269], 366);
                step(f, Op::LessF, &[269, 898, 24], 367);
                step(f, Op::And, &[25, 24, 26], 368);
                step(f, Op::Not, &[22, 27], 369);
                step(f, Op::Not, &[23, 28], 370);
                step(f, Op::And, &[27, 28, 29], 371);
                step(f, Op::Or, &[26, 29, 30], 372);
                step(f, Op::JumpIfFalse, &[30, 394], 373)
            }
            373 => {
                step(f, Op::DeltaTime, &[233], 374);
                step(f, Op::MulF, &[38, 233, 273], 375);
                step(f, Op::GreaterF, &[273, 886, 31], 376);
                step(f, Op::DivF, &[51, 233, 270], 377);
                step(f, Op::FloatLerp, &[886, 888, 38, 271], 378);
                step(f, Op::SubF, &[888, 271, 272], 379);
                step(f, Op::DivF, &[272, 271, 274], 380);
                step(f, Op::DivF, &[888, 273, 275], 381);
                step(f, Op::SubF, &[274, 275, 276], 382);
                step(f, Op::AddF, &[270, 276, 277], 383);
                step(f, Op::Select(ValueType::Float), &[31, 277, 886, 278], 384);
                step(f, Op::MulF, &[258, 278, 279], 385);
                step(f, Op::AddF, &[237, 279, 280], 386);
                step(f, Op::SinF, &[280, 281], 387);
                step(f, Op::NegF, &[281, 282], 388);
                step(f, Op::CosF, &[280, 283], 389);
                step(f, Op::MakeVector, &[282, 283, 886, 75], 390);
                step(f, Op::Select(ValueType::Vec3), &[23, 75, 478, 76], 391);
                step(f, Op::MovementAngleOffset, &[76, 14, 886, 38, 39, 894, 896, 895, 284], 392);
                step(f, Op::Copy(ValueType::Float), &[284, 14], 393);
                step(f, Op::Jump, &[429], 394)
            }
            394 => {
                step(f, Op::DeltaTime, &[233], 395);
                step(f, Op::DivF, &[233, 41, 285], 396);
                step(f, Op::AddF, &[285, 887, 286], 397);
                step(f, Op::FloorF, &[286, 287], 398);
                step(f, Op::MaxF, &[287, 888, 288], 399);
                step(f, Op::ToInt, &[288, 36], 400);
                step(f, Op::Copy(ValueType::Int), &[36, 35], 401);
                step(f, Op::Copy(ValueType::Int), &[71, 31], 402);
                step(f, Op::MulF, &[41, 887, 292], 403);
                step(f, Op::SubF, &[51, 292, 293], 404);
                step(f, Op::DivF, &[293, 233, 294], 405);
                step(f, Op::FloatLerp, &[886, 888, 36, 296], 406);
                step(f, Op::GreaterF, &[296, 886, 32], 407);
                step(f, Op::DivF, &[38, 288, 306], 408);
                step(f, Op::DivF, &[39, 288, 307], 409);
                409
            }
            409 => {
                step(f, Op::ForNext, &[31, 35, 33, 429], 410)
            }
            410 => {
                step(f, Op::ToFloat, &[33, 289], 411);
                step(f, Op::AddF, &[289, 888, 290], 412);
                step(f, Op::DivF, &[290, 288, 291], 413);
                step(f, Op::AddF, &[291, 294, 295], 414);
                step(f, Op::MulF, &[36, 295, 297], 415);
                step(f, Op::FloatLerp, &[886, 888, 297, 298], 416);
                step(f, Op::DivF, &[298, 296, 299], 417);
                step(f, Op::Select(ValueType::Float), &[32, 299, 295, 300], 418);
                step(f, Op::LerpV, &[4, 2, 300, 77], 419);
                step(f, Op::LengthV, &[77, 301], 420);
                step(f, Op::GreaterF, &[301, 29, 33], 421);
                step(f, Op::Select(ValueType::Vec3), &[33, 77, 478, 78], 422);
                step(f, Op::MulF, &[233, 295, 302], 423);
                step(f, Op::MulF, &[8, 302, 303], 424);
                step(f, Op::AddF, &[12, 303, 304], 425);
                step(f, Op::FractF, &[304, 305], 426);
                step(f, Op::MovementAngleOffset, &[78, 14, 305, 306, 307, 894, 40, 895, 308], 427);
                step(f, Op::Copy(ValueType::Float), &[308, 14], 428);
                step(f, Op::Jump, &[409], 429)
            }
            429 => {
                step(f, Op::QuatFromAxisAngle, &[480, 14, 12], 430);
                step(f, Op::Copy(ValueType::Quat), &[12, 0], 431);
                step(f, Op::SinF, &[14, 309], 432);
                step(f, Op::AbsF, &[309, 310], 433);
                step(f, Op::RemapF, &[310, 42, 43, 886, 888, 125, 311], 434);
                step(f, Op::BreakVector, &[74, 312, 313, 314], 435);
                step(f, Op::AbsF, &[312, 315], 436);
                step(f, Op::DivF, &[315, 235, 316], 437);
                step(f, Op::RemapF, &[316, 42, 43, 886, 888, 125, 317], 438);
                step(f, Op::TransformVector, &[2, 481, 79], 439);
                step(f, Op::DistanceV, &[79, 481, 318], 440);
                step(f, Op::DivF, &[318, 233, 319], 441);
                step(f, Op::RemapF, &[319, 47, 48, 888, 886, 125, 320], 442);
                step(f, Op::MulF, &[317, 320, 321], 443);
                step(f, Op::MaxF, &[311, 321, 322], 444);
                step(f, Op::Copy(ValueType::Float), &[322, 15], 445);
                step(f, Op::Copy(ValueType::Vec3), &[2, 4], 446);
                step(f, Op::Copy(ValueType::Bool), &[125, 36], 447);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 2], 448);
                step(f, Op::Copy(ValueType::Int), &[71, 40], 449);
                449
            }
            449 => {
                step(f, Op::ForEachNext(Elem::Bool), &[2, 40, 37, 41, 42, 454], 450)
            }
            450 => {
                step(f, Op::Not, &[37, 38], 451);
                step(f, Op::JumpIfFalse, &[38, 453], 452)
            }
            452 => {
                step(f, Op::Copy(ValueType::Bool), &[126, 36], 453);
                453
            }
            453 => {
                step(f, Op::Jump, &[449], 454)
            }
            454 => {
                step(f, Op::Copy(ValueType::Bool), &[36, 35], 455);
                step(f, Op::Copy(ValueType::Bool), &[125, 40], 456);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 457);
                step(f, Op::Copy(ValueType::Int), &[71, 43], 458);
                458
            }
            458 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 43, 15, 44, 45, 472], 459)
            }
            459 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 44, 23], 460);
                step(f, Op::BreakTransform, &[23, 80, 13, 81], 461);
                step(f, Op::BreakVector, &[80, 331, 332, 333], 462);
                step(f, Op::MakeVector, &[331, 332, 886, 84], 463);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 44, 24], 464);
                step(f, Op::BreakTransform, &[24, 82, 14, 83], 465);
                step(f, Op::BreakVector, &[82, 334, 335, 336], 466);
                step(f, Op::MakeVector, &[334, 335, 886, 85], 467);
                step(f, Op::DistanceV, &[84, 85, 337], 468);
                step(f, Op::GreaterF, &[337, 31, 41], 469);
                step(f, Op::JumpIfFalse, &[41, 471], 470)
            }
            470 => {
                step(f, Op::Copy(ValueType::Bool), &[126, 40], 471);
                471
            }
            471 => {
                step(f, Op::Jump, &[458], 472)
            }
            472 => {
                step(f, Op::Copy(ValueType::Bool), &[40, 39], 473);
                step(f, Op::And, &[35, 39, 42], 474);
                step(f, Op::LengthV, &[2, 323], 475);
                step(f, Op::GreaterF, &[323, 29, 34], 476);
                step(f, Op::GreaterF, &[0, 29, 43], 477);
                step(f, Op::Or, &[34, 43, 44], 478);
                step(f, Op::Not, &[44, 45], 479);
                step(f, Op::And, &[42, 45, 50], 480);
                step(f, Op::DeltaTime, &[362], 481);
                step(f, Op::MulF, &[362, 34, 363], 482);
                step(f, Op::AddF, &[12, 363, 364], 483);
                step(f, Op::GreaterF, &[12, 887, 51], 484);
                step(f, Op::AddF, &[33, 887, 360], 485);
                step(f, Op::Select(ValueType::Float), &[51, 360, 33, 361], 486);
                step(f, Op::MinF, &[364, 361, 365], 487);
                step(f, Op::NotEquals(Elem::Bool), &[45, 4, 46], 488);
                step(f, Op::Not, &[42, 47], 489);
                step(f, Op::And, &[46, 47, 48], 490);
                step(f, Op::SubF, &[13, 29, 346], 491);
                step(f, Op::SubF, &[13, 323, 347], 492);
                step(f, Op::DivF, &[346, 347, 348], 493);
                step(f, Op::ClampF, &[348, 886, 888, 349], 494);
                step(f, Op::MulF, &[8, 349, 351], 495);
                step(f, Op::RemapF, &[323, 29, 30, 886, 888, 125, 338], 496);
                step(f, Op::MaxF, &[338, 9, 339], 497);
                step(f, Op::Select(ValueType::Float), &[35, 888, 339, 340], 498);
                step(f, Op::Select(ValueType::Float), &[45, 32, 340, 341], 499);
                step(f, Op::Select(ValueType::Float), &[42, 338, 341, 342], 500);
                step(f, Op::SubF, &[888, 21, 343], 501);
                step(f, Op::MulF, &[342, 343, 344], 502);
                step(f, Op::LerpF, &[23, 45, 15, 326], 503);
                step(f, Op::RemapF, &[323, 26, 27, 24, 25, 125, 324], 504);
                step(f, Op::LerpF, &[324, 44, 15, 325], 505);
                step(f, Op::MaxF, &[323, 28, 327], 506);
                step(f, Op::DivF, &[325, 327, 328], 507);
                step(f, Op::AddF, &[326, 328, 329], 508);
                step(f, Op::DivF, &[344, 329, 345], 509);
                step(f, Op::SubF, &[888, 349, 350], 510);
                step(f, Op::MulF, &[345, 350, 352], 511);
                step(f, Op::AddF, &[351, 352, 353], 512);
                step(f, Op::MulF, &[353, 891, 354], 513);
                step(f, Op::AddF, &[8, 345, 355], 514);
                step(f, Op::Select(ValueType::Float), &[48, 354, 355, 356], 515);
                step(f, Op::DivF, &[891, 356, 357], 516);
                step(f, Op::GreaterF, &[356, 886, 49], 517);
                step(f, Op::CycleStep, &[12, 357, 886, 49, 358, 359], 518);
                step(f, Op::Select(ValueType::Float), &[50, 365, 358, 366], 519);
                step(f, Op::Copy(ValueType::Float), &[366, 12], 520);
                step(f, Op::Copy(ValueType::Float), &[345, 8], 521);
                step(f, Op::Copy(ValueType::Bool), &[34, 3], 522);
                step(f, Op::Copy(ValueType::Float), &[328, 6], 523);
                step(f, Op::Copy(ValueType::Float), &[329, 7], 524);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 525);
                step(f, Op::Copy(ValueType::Int), &[71, 37], 526);
                step(f, Op::DivF, &[326, 329, 330], 527);
                step(f, Op::MulF, &[11, 349, 372], 528);
                step(f, Op::MulF, &[362, 887, 378], 529);
                step(f, Op::SubF, &[330, 10, 383], 530);
                step(f, Op::MaxF, &[383, 886, 384], 531);
                step(f, Op::DivF, &[384, 330, 385], 532);
                step(f, Op::SubF, &[888, 15, 387], 533);
                step(f, Op::DivF, &[51, 362, 392], 534);
                step(f, Op::SubF, &[887, 392, 393], 535);
                step(f, Op::MulF, &[385, 387, 394], 536);
                step(f, Op::MulF, &[394, 343, 395], 537);
                step(f, Op::MulF, &[395, 128, 396], 538);
                step(f, Op::MulF, &[396, 393, 397], 539);
                step(f, Op::SubF, &[888, 397, 398], 540);
                540
            }
            540 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 37, 14, 38, 39, 584], 541)
            }
            541 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 38, 380], 542);
                step(f, Op::ToFloat, &[38, 367], 543);
                step(f, Op::MulF, &[367, 887, 368], 544);
                step(f, Op::AddF, &[12, 368, 369], 545);
                step(f, Op::FractF, &[369, 370], 546);
                step(f, Op::SubF, &[380, 370, 382], 547);
                step(f, Op::GreaterF, &[382, 887, 52], 548);
                step(f, Op::ArrayAt(Elem::Float), &[2, 38, 381], 549);
                step(f, Op::Select(ValueType::Float), &[52, 886, 381, 409], 550);
                step(f, Op::ArraySetAt(Elem::Float), &[3, 38, 409], 551);
                step(f, Op::SubF, &[888, 380, 403], 552);
                step(f, Op::AddF, &[370, 403, 404], 553);
                step(f, Op::DivF, &[370, 404, 405], 554);
                step(f, Op::MaxF, &[338, 9, 339], 555);
                step(f, Op::Select(ValueType::Float), &[35, 888, 339, 340], 556);
                step(f, Op::Select(ValueType::Float), &[45, 32, 340, 341], 557);
                step(f, Op::Select(ValueType::Float), &[42, 338, 341, 342], 558);
                step(f, Op::MulF, &[342, 343, 344], 559);
                step(f, Op::DivF, &[344, 326, 371], 560);
                step(f, Op::MulF, &[371, 350, 373], 561);
                step(f, Op::AddF, &[372, 373, 374], 562);
                step(f, Op::MulF, &[374, 891, 375], 563);
                step(f, Op::AddF, &[11, 371, 376], 564);
                step(f, Op::Select(ValueType::Float), &[48, 375, 376, 377], 565);
                step(f, Op::MulF, &[377, 378, 379], 566);
                step(f, Op::MulF, &[405, 379, 406], 567);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 38, 53], 568);
                step(f, Op::MulF, &[379, 398, 399], 569);
                step(f, Op::Select(ValueType::Float), &[53, 379, 399, 400], 570);
                step(f, Op::MulF, &[385, 381, 386], 571);
                step(f, Op::MulF, &[386, 387, 388], 572);
                step(f, Op::MulF, &[388, 343, 389], 573);
                step(f, Op::MulF, &[389, 128, 390], 574);
                step(f, Op::Select(ValueType::Float), &[53, 886, 390, 391], 575);
                step(f, Op::SubF, &[400, 391, 401], 576);
                step(f, Op::AddF, &[381, 401, 402], 577);
                step(f, Op::Select(ValueType::Float), &[52, 406, 402, 407], 578);
                step(f, Op::MinF, &[407, 891, 408], 579);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 38, 408], 580);
                step(f, Op::JumpIfFalse, &[52, 582], 581)
            }
            581 => {
                step(f, Op::Copy(ValueType::Float), &[342, 9], 582);
                582
            }
            582 => {
                step(f, Op::ArraySetAt(Elem::Float), &[0, 38, 370], 583);
                step(f, Op::Jump, &[540], 584)
            }
            584 => {
                step(f, Op::Copy(ValueType::Float), &[330, 10], 585);
                step(f, Op::Copy(ValueType::Bool), &[45, 4], 586);
                step(f, Op::Copy(ValueType::Float), &[323, 13], 587);
                step(f, Op::MaxF, &[338, 9, 339], 588);
                step(f, Op::Select(ValueType::Float), &[35, 888, 339, 340], 589);
                step(f, Op::Select(ValueType::Float), &[45, 32, 340, 341], 590);
                step(f, Op::Select(ValueType::Float), &[42, 338, 341, 342], 591);
                step(f, Op::MulF, &[342, 343, 344], 592);
                step(f, Op::DivF, &[344, 326, 371], 593);
                step(f, Op::Copy(ValueType::Float), &[371, 11], 594);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 595);
                step(f, Op::Copy(ValueType::Int), &[71, 2], 596);
                596
            }
            596 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 2, 0, 3, 4, 1460], 597)
            }
            597 => {
                step(f, Op::Copy(ValueType::Bool), &[125, 54], 598);
                step(f, Op::Copy(ValueType::Bool), &[126, 55], 599);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 3, 58], 600);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 410], 601);
                step(f, Op::GreaterEqualF, &[410, 888, 59], 602);
                step(f, Op::And, &[58, 59, 60], 603);
                step(f, Op::Or, &[1, 2, 62], 604);
                step(f, Op::GreaterF, &[21, 886, 61], 605);
                step(f, Op::Or, &[62, 61, 63], 606);
                step(f, Op::Not, &[63, 64], 607);
                step(f, Op::And, &[60, 64, 65], 608);
                step(f, Op::JumpIfFalse, &[65, 718], 609)
            }
            609 => {
                step(f, Op::ArrayAt(Elem::Transform), &[2, 3, 28], 610);
                step(f, Op::BreakTransform, &[28, 104, 23, 105], 611);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 3, 121], 612);
                step(f, Op::SubV, &[104, 121, 142], 613);
                step(f, Op::TransformPoint, &[2, 142, 143], 614);
                step(f, Op::GetTransform, &[34, 71, 125, 25], 615);
                step(f, Op::BreakTransform, &[25, 88, 15, 89], 616);
                step(f, Op::BreakVector, &[88, 421, 422, 423], 617);
                step(f, Op::SubF, &[888, 15, 419], 618);
                step(f, Op::MulF, &[14, 419, 420], 619);
                step(f, Op::QuatFromAxisAngle, &[480, 420, 17], 620);
                step(f, Op::GetTransform, &[0, 71, 125, 26], 621);
                step(f, Op::BreakTransform, &[26, 90, 16, 91], 622);
                step(f, Op::SubV, &[90, 88, 92], 623);
                step(f, Op::BreakVector, &[92, 416, 417, 418], 624);
                step(f, Op::MakeVector, &[416, 417, 886, 93], 625);
                step(f, Op::RotateVector, &[17, 93, 94], 626);
                step(f, Op::BreakVector, &[94, 424, 425, 426], 627);
                step(f, Op::MulF, &[46, 15, 427], 628);
                step(f, Op::Equals(Elem::Int), &[3, 71, 56], 629);
                step(f, Op::Select(ValueType::Float), &[56, 888, 890, 436], 630);
                step(f, Op::MulF, &[427, 436, 428], 631);
                step(f, Op::AddF, &[424, 428, 429], 632);
                step(f, Op::AddF, &[421, 429, 430], 633);
                step(f, Op::AddF, &[422, 425, 431], 634);
                step(f, Op::BreakVector, &[90, 432, 433, 434], 635);
                step(f, Op::SubF, &[434, 52, 435], 636);
                step(f, Op::MakeVector, &[430, 431, 435, 95], 637);
                step(f, Op::MulF, &[6, 887, 415], 638);
                step(f, Op::ScaleV, &[2, 415, 87], 639);
                step(f, Op::AddV, &[95, 87, 98], 640);
                step(f, Op::DistanceV, &[143, 98, 463], 641);
                step(f, Op::TransformVector, &[2, 482, 144], 642);
                step(f, Op::DistanceV, &[144, 482, 464], 643);
                step(f, Op::MaxF, &[463, 464, 465], 644);
                step(f, Op::LessEqualF, &[465, 59, 74], 645);
                step(f, Op::LengthV, &[2, 466], 646);
                step(f, Op::LengthV, &[4, 467], 647);
                step(f, Op::MaxF, &[466, 467, 468], 648);
                step(f, Op::LessEqualF, &[468, 29, 75], 649);
                step(f, Op::And, &[74, 75, 76], 650);
                step(f, Op::ArrayAt(Elem::Bool), &[1, 3, 66], 651);
                step(f, Op::And, &[76, 66, 77], 652);
                step(f, Op::JumpIfFalse, &[77, 655], 653)
            }
            653 => {
                step(f, Op::Copy(ValueType::Bool), &[125, 55], 654);
                step(f, Op::Jump, &[684], 655)
            }
            655 => {
                step(f, Op::MakeVector, &[886, 886, 57, 123], 656);
                step(f, Op::AddV, &[98, 123, 124], 657);
                step(f, Op::SubV, &[98, 123, 125], 658);
                step(f, Op::SphereTrace, &[124, 125, 56, 67, 126, 127, 455], 659);
                step(f, Op::SubV, &[126, 98, 140], 660);
                step(f, Op::DistanceV, &[140, 121, 459], 661);
                step(f, Op::RotateVector, &[0, 481, 99], 662);
                step(f, Op::ScaleV, &[99, 61, 128], 663);
                step(f, Op::AddV, &[124, 128, 129], 664);
                step(f, Op::AddV, &[125, 128, 130], 665);
                step(f, Op::SphereTrace, &[129, 130, 56, 68, 131, 132, 456], 666);
                step(f, Op::SubV, &[131, 98, 141], 667);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 3, 122], 668);
                step(f, Op::DistanceV, &[141, 122, 460], 669);
                step(f, Op::MaxF, &[459, 460, 461], 670);
                step(f, Op::ScaleV, &[99, 58, 133], 671);
                step(f, Op::AddV, &[129, 133, 134], 672);
                step(f, Op::AddV, &[130, 133, 135], 673);
                step(f, Op::SphereTrace, &[134, 135, 56, 69, 136, 137, 457], 674);
                step(f, Op::SubV, &[136, 98, 138], 675);
                step(f, Op::ArrayAt(Elem::Vec3), &[2, 3, 139], 676);
                step(f, Op::DistanceV, &[138, 139, 458], 677);
                step(f, Op::MaxF, &[461, 458, 462], 678);
                step(f, Op::LessEqualF, &[462, 59, 70], 679);
                step(f, Op::And, &[67, 68, 71], 680);
                step(f, Op::And, &[71, 66, 72], 681);
                step(f, Op::And, &[70, 72, 73], 682);
                step(f, Op::JumpIfFalse, &[73, 684], 683)
            }
            683 => {
                step(f, Op::Copy(ValueType::Bool), &[125, 55], 684);
                684
            }
            684 => {
                step(f, Op::JumpIfFalse, &[55, 718], 685)
            }
            685 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 27], 686);
                step(f, Op::BreakTransform, &[27, 101, 21, 102], 687);
                step(f, Op::AddV, &[98, 121, 145], 688);
                step(f, Op::Copy(ValueType::Float), &[49, 469], 689);
                step(f, Op::Copy(ValueType::Float), &[51, 470], 690);
                step(f, Op::SubV, &[145, 104, 150], 691);
                step(f, Op::DeltaTime, &[471], 692);
                step(f, Op::DivF, &[470, 471, 472], 693);
                step(f, Op::ScaleV, &[150, 472, 151], 694);
                step(f, Op::AddV, &[145, 151, 152], 695);
                step(f, Op::AddV, &[104, 151, 153], 696);
                step(f, Op::SubV, &[101, 153, 154], 697);
                step(f, Op::FloatLerp, &[886, 888, 469, 473], 698);
                step(f, Op::SubF, &[888, 473, 474], 699);
                step(f, Op::ScaleV, &[154, 474, 155], 700);
                step(f, Op::AddV, &[152, 155, 157], 701);
                step(f, Op::MulF, &[469, 471, 475], 702);
                step(f, Op::GreaterF, &[475, 886, 78], 703);
                step(f, Op::DivF, &[473, 475, 476], 704);
                step(f, Op::Select(ValueType::Float), &[78, 476, 888, 477], 705);
                step(f, Op::ScaleV, &[150, 477, 156], 706);
                step(f, Op::SubV, &[157, 156, 158], 707);
                step(f, Op::Copy(ValueType::Vec3), &[158, 149], 708);
                step(f, Op::BreakVector, &[149, 478, 479, 480], 709);
                step(f, Op::ClampF, &[480, 62, 63, 481], 710);
                step(f, Op::MakeVector, &[478, 479, 481, 159], 711);
                step(f, Op::MakeTransform, &[159, 21, 477, 31], 712);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 3, 31], 713);
                step(f, Op::MakeTransform, &[145, 94, 477, 32], 714);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 3, 32], 715);
                step(f, Op::JumpIfFalse, &[66, 717], 716)
            }
            716 => {
                step(f, Op::Copy(ValueType::Bool), &[125, 7], 717);
                717
            }
            717 => {
                step(f, Op::Copy(ValueType::Bool), &[126, 54], 718);
                718
            }
            718 => {
                step(f, Op::JumpIfFalse, &[54, 923], 719)
            }
            719 => {
                step(f, Op::GetTransform, &[34, 71, 125, 25], 720);
                step(f, Op::BreakTransform, &[25, 88, 15, 89], 721);
                step(f, Op::BreakVector, &[88, 421, 422, 423], 722);
                step(f, Op::SubF, &[888, 15, 419], 723);
                step(f, Op::MulF, &[14, 419, 420], 724);
                step(f, Op::QuatFromAxisAngle, &[480, 420, 17], 725);
                step(f, Op::GetTransform, &[0, 71, 125, 26], 726);
                step(f, Op::BreakTransform, &[26, 90, 16, 91], 727);
                step(f, Op::SubV, &[90, 88, 92], 728);
                step(f, Op::BreakVector, &[92, 416, 417, 418], 729);
                step(f, Op::MakeVector, &[416, 417, 886, 93], 730);
                step(f, Op::RotateVector, &[17, 93, 94], 731);
                step(f, Op::BreakVector, &[94, 424, 425, 426], 732);
                step(f, Op::MulF, &[46, 15, 427], 733);
                step(f, Op::Equals(Elem::Int), &[3, 71, 56], 734);
                step(f, Op::Select(ValueType::Float), &[56, 888, 890, 436], 735);
                step(f, Op::MulF, &[427, 436, 428], 736);
                step(f, Op::AddF, &[424, 428, 429], 737);
                step(f, Op::AddF, &[421, 429, 430], 738);
                step(f, Op::AddF, &[422, 425, 431], 739);
                step(f, Op::BreakVector, &[90, 432, 433, 434], 740);
                step(f, Op::SubF, &[434, 52, 435], 741);
                step(f, Op::MakeVector, &[430, 431, 435, 95], 742);
                step(f, Op::SubF, &[888, 410, 411], 743);
                step(f, Op::MaxF, &[411, 886, 412], 744);
                step(f, Op::MulF, &[10, 7, 413], 745);
                step(f, Op::MulF, &[412, 413, 414], 746);
                step(f, Op::ScaleV, &[2, 414, 86], 747);
                step(f, Op::AddV, &[95, 86, 96], 748);
                step(f, Op::MulF, &[6, 887, 415], 749);
                step(f, Op::ScaleV, &[2, 415, 87], 750);
                step(f, Op::AddV, &[96, 87, 97], 751);
                step(f, Op::RotateVector, &[0, 481, 99], 752);
                step(f, Op::Copy(ValueType::Float), &[893, 483], 753);
                step(f, Op::Copy(ValueType::Vec3), &[478, 164], 754);
                step(f, Op::Copy(ValueType::Vec3), &[480, 165], 755);
                step(f, Op::Copy(ValueType::Bool), &[126, 80], 756);
                step(f, Op::Copy(ValueType::Float), &[893, 484], 757);
                step(f, Op::Copy(ValueType::Vec3), &[478, 166], 758);
                step(f, Op::MulI, &[0, 0, 52], 759);
                step(f, Op::Copy(ValueType::Int), &[52, 51], 760);
                step(f, Op::Copy(ValueType::Int), &[71, 47], 761);
                step(f, Op::SubI, &[0, 72, 55], 762);
                step(f, Op::DivI, &[55, 73, 56], 763);
                step(f, Op::MakeVector, &[886, 886, 57, 171], 764);
                step(f, Op::ScaleV, &[99, 61, 176], 765);
                765
            }
            765 => {
                step(f, Op::ForNext, &[47, 51, 49, 812], 766)
            }
            766 => {
                step(f, Op::ModI, &[49, 0, 53], 767);
                step(f, Op::ToFloat, &[53, 485], 768);
                step(f, Op::MulF, &[485, 58, 487], 769);
                step(f, Op::MulF, &[487, 436, 488], 770);
                step(f, Op::MakeVector, &[488, 886, 886, 167], 771);
                step(f, Op::DivI, &[49, 0, 54], 772);
                step(f, Op::SubI, &[54, 56, 57], 773);
                step(f, Op::ToFloat, &[57, 486], 774);
                step(f, Op::MulF, &[486, 58, 489], 775);
                step(f, Op::ScaleV, &[99, 489, 168], 776);
                step(f, Op::AddV, &[167, 168, 169], 777);
                step(f, Op::AddV, &[97, 169, 170], 778);
                step(f, Op::AddV, &[170, 171, 172], 779);
                step(f, Op::SubV, &[170, 171, 173], 780);
                step(f, Op::SphereTrace, &[172, 173, 56, 81, 174, 175, 490], 781);
                step(f, Op::BreakVector, &[174, 492, 493, 494], 782);
                step(f, Op::AddV, &[172, 176, 177], 783);
                step(f, Op::AddV, &[173, 176, 178], 784);
                step(f, Op::SphereTrace, &[177, 178, 56, 82, 179, 180, 491], 785);
                step(f, Op::BreakVector, &[179, 495, 496, 497], 786);
                step(f, Op::SubF, &[494, 497, 498], 787);
                step(f, Op::AbsF, &[498, 499], 788);
                step(f, Op::Select(ValueType::Float), &[81, 886, 888, 500], 789);
                step(f, Op::AddF, &[499, 500, 505], 790);
                step(f, Op::LengthV, &[169, 501], 791);
                step(f, Op::RemapF, &[501, 886, 899, 886, 888, 125, 502], 792);
                step(f, Op::MinF, &[494, 497, 503], 793);
                step(f, Op::RemapF, &[503, 900, 899, 888, 887, 125, 504], 794);
                step(f, Op::AddF, &[502, 504, 506], 795);
                step(f, Op::AddF, &[505, 506, 507], 796);
                step(f, Op::LessF, &[507, 483, 83], 797);
                step(f, Op::And, &[81, 83, 84], 798);
                step(f, Op::JumpIfFalse, &[84, 806], 799)
            }
            799 => {
                step(f, Op::Copy(ValueType::Float), &[483, 484], 800);
                step(f, Op::Copy(ValueType::Vec3), &[164, 166], 801);
                step(f, Op::Copy(ValueType::Float), &[507, 483], 802);
                step(f, Op::Copy(ValueType::Vec3), &[174, 164], 803);
                step(f, Op::Copy(ValueType::Vec3), &[175, 165], 804);
                step(f, Op::Copy(ValueType::Bool), &[125, 80], 805);
                step(f, Op::Jump, &[811], 806)
            }
            806 => {
                step(f, Op::LessF, &[507, 484, 85], 807);
                step(f, Op::And, &[81, 85, 86], 808);
                step(f, Op::JumpIfFalse, &[86, 811], 809)
            }
            809 => {
                step(f, Op::Copy(ValueType::Float), &[507, 484], 810);
                step(f, Op::Copy(ValueType::Vec3), &[174, 166], 811);
                811
            }
            811 => {
                step(f, Op::Jump, &[765], 812)
            }
            812 => {
                step(f, Op::JumpIfFalse, &[8, 814], 813)
            }
            813 => {
                step(f, Op::DrawSphere, &[164, 56, 481], 814);
                814
            }
            814 => {
                step(f, Op::GreaterF, &[60, 886, 87], 815);
                step(f, Op::SubF, &[483, 484, 508], 816);
                step(f, Op::DivF, &[508, 60, 509], 817);
                step(f, Op::PowF, &[901, 509, 510], 818);
                step(f, Op::Select(ValueType::Float), &[87, 510, 886, 511], 819);
                step(f, Op::ScaleV, &[166, 511, 181], 820);
                step(f, Op::AddV, &[164, 181, 182], 821);
                step(f, Op::AddF, &[511, 888, 512], 822);
                step(f, Op::DivF, &[888, 512, 513], 823);
                step(f, Op::ScaleV, &[182, 513, 183], 824);
                step(f, Op::Copy(ValueType::Vec3), &[183, 162], 825);
                step(f, Op::Copy(ValueType::Vec3), &[165, 163], 826);
                step(f, Op::Copy(ValueType::Bool), &[80, 79], 827);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 27], 828);
                step(f, Op::BreakTransform, &[27, 101, 21, 102], 829);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 410], 830);
                step(f, Op::SubF, &[888, 410, 411], 831);
                step(f, Op::MaxF, &[411, 886, 412], 832);
                step(f, Op::MulF, &[10, 7, 413], 833);
                step(f, Op::MulF, &[412, 413, 414], 834);
                step(f, Op::ScaleV, &[2, 414, 86], 835);
                step(f, Op::SubV, &[162, 86, 100], 836);
                step(f, Op::Select(ValueType::Vec3), &[79, 100, 101, 103], 837);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 3, 28], 838);
                step(f, Op::BreakTransform, &[28, 104, 23, 105], 839);
                step(f, Op::Copy(ValueType::Float), &[49, 442], 840);
                step(f, Op::Copy(ValueType::Float), &[51, 443], 841);
                step(f, Op::SubV, &[103, 104, 110], 842);
                step(f, Op::DeltaTime, &[444], 843);
                step(f, Op::DivF, &[443, 444, 445], 844);
                step(f, Op::ScaleV, &[110, 445, 111], 845);
                step(f, Op::AddV, &[103, 111, 112], 846);
                step(f, Op::AddV, &[104, 111, 113], 847);
                step(f, Op::SubV, &[101, 113, 114], 848);
                step(f, Op::FloatLerp, &[886, 888, 442, 446], 849);
                step(f, Op::SubF, &[888, 446, 447], 850);
                step(f, Op::ScaleV, &[114, 447, 115], 851);
                step(f, Op::AddV, &[112, 115, 117], 852);
                step(f, Op::MulF, &[442, 444, 448], 853);
                step(f, Op::GreaterF, &[448, 886, 57], 854);
                step(f, Op::DivF, &[446, 448, 449], 855);
                step(f, Op::Select(ValueType::Float), &[57, 449, 888, 450], 856);
                step(f, Op::ScaleV, &[110, 450, 116], 857);
                step(f, Op::SubV, &[117, 116, 118], 858);
                step(f, Op::Copy(ValueType::Vec3), &[118, 109], 859);
                step(f, Op::BreakVector, &[109, 451, 452, 453], 860);
                step(f, Op::ClampF, &[453, 62, 63, 454], 861);
                step(f, Op::MakeVector, &[451, 452, 454, 119], 862);
                step(f, Op::RotationFromNormal, &[163, 440, 441, 19], 863);
                step(f, Op::PerFootRotationFactor, &[14, 104, 105, 437], 864);
                step(f, Op::MulF, &[14, 437, 438], 865);
                step(f, Op::SubF, &[888, 15, 419], 866);
                step(f, Op::MulF, &[438, 419, 439], 867);
                step(f, Op::QuatFromAxisAngle, &[480, 439, 18], 868);
                step(f, Op::MulQ, &[19, 18, 20], 869);
                step(f, Op::Select(ValueType::Quat), &[79, 20, 21, 22], 870);
                step(f, Op::MakeTransform, &[119, 22, 477, 30], 871);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 3, 30], 872);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 27], 873);
                step(f, Op::BreakTransform, &[27, 101, 21, 102], 874);
                step(f, Op::Select(ValueType::Vec3), &[79, 100, 101, 103], 875);
                step(f, Op::MakeTransform, &[103, 94, 477, 29], 876);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 3, 29], 877);
                step(f, Op::GetTransform, &[34, 71, 125, 25], 878);
                step(f, Op::BreakTransform, &[25, 88, 15, 89], 879);
                step(f, Op::BreakVector, &[88, 421, 422, 423], 880);
                step(f, Op::MulF, &[14, 419, 420], 881);
                step(f, Op::QuatFromAxisAngle, &[480, 420, 17], 882);
                step(f, Op::GetTransform, &[0, 71, 125, 26], 883);
                step(f, Op::BreakTransform, &[26, 90, 16, 91], 884);
                step(f, Op::SubV, &[90, 88, 92], 885);
                step(f, Op::BreakVector, &[92, 416, 417, 418], 886);
                step(f, Op::MakeVector, &[416, 417, 886, 93], 887);
                step(f, Op::RotateVector, &[17, 93, 94], 888);
                step(f, Op::BreakVector, &[94, 424, 425, 426], 889);
                step(f, Op::MulF, &[46, 15, 427], 890);
                step(f, Op::MulF, &[427, 436, 428], 891);
                step(f, Op::AddF, &[424, 428, 429], 892);
                step(f, Op::AddF, &[421, 429, 430], 893);
                step(f, Op::AddF, &[422, 425, 431], 894);
                step(f, Op::BreakVector, &[90, 432, 433, 434], 895);
                step(f, Op::SubF, &[434, 52, 435], 896);
                step(f, Op::MakeVector, &[430, 431, 435, 95], 897);
                step(f, Op::MulF, &[6, 887, 415], 898);
                step(f, Op::ScaleV, &[2, 415, 87], 899);
                step(f, Op::AddV, &[95, 87, 98], 900);
                step(f, Op::SubV, &[103, 98, 120], 901);
                step(f, Op::ArraySetAt(Elem::Vec3), &[0, 3, 120], 902);
                step(f, Op::ArraySetAt(Elem::Bool), &[1, 3, 79], 903);
                step(f, Op::GreaterEqualF, &[410, 888, 59], 904);
                step(f, Op::JumpIfFalse, &[59, 921], 905)
            }
            905 => {
                step(f, Op::MakeVector, &[886, 886, 57, 123], 906);
                step(f, Op::AddV, &[98, 123, 124], 907);
                step(f, Op::RotateVector, &[0, 481, 99], 908);
                step(f, Op::ScaleV, &[99, 61, 128], 909);
                step(f, Op::AddV, &[124, 128, 129], 910);
                step(f, Op::SubV, &[98, 123, 125], 911);
                step(f, Op::AddV, &[125, 128, 130], 912);
                step(f, Op::SphereTrace, &[129, 130, 56, 68, 131, 132, 456], 913);
                step(f, Op::SubV, &[131, 98, 141], 914);
                step(f, Op::ArraySetAt(Elem::Vec3), &[1, 3, 141], 915);
                step(f, Op::ScaleV, &[99, 58, 133], 916);
                step(f, Op::AddV, &[129, 133, 134], 917);
                step(f, Op::AddV, &[130, 133, 135], 918);
                step(f, Op::SphereTrace, &[134, 135, 56, 69, 136, 137, 457], 919);
                step(f, Op::SubV, &[136, 98, 138], 920);
                step(f, Op::ArraySetAt(Elem::Vec3), &[2, 3, 138], 921);
                921
            }
            921 => {
                step(f, Op::JumpIfFalse, &[79, 923], 922)
            }
            922 => {
                step(f, Op::Copy(ValueType::Bool), &[125, 7], 923);
                923
            }
            923 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 3, 35], 924);
                step(f, Op::GreaterF, &[21, 886, 91], 925);
                step(f, Op::InterpolateTransform, &[2, 121, 22, 33], 926);
                step(f, Op::Select(ValueType::Transform), &[91, 33, 2, 34], 927);
                step(f, Op::MakeAbsolute, &[35, 34, 36], 928);
                step(f, Op::BreakTransform, &[36, 184, 24, 185], 929);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 3, 37], 930);
                step(f, Op::BreakTransform, &[37, 186, 25, 187], 931);
                step(f, Op::AddF, &[66, 67, 515], 932);
                step(f, Op::ClampSpatially, &[184, 186, 886, 515, 188], 933);
                step(f, Op::SubF, &[888, 15, 541], 934);
                step(f, Op::MulF, &[14, 541, 516], 935);
                step(f, Op::LimitRotationAroundZ, &[24, 516, 100, 26], 936);
                step(f, Op::MakeTransform, &[188, 26, 477, 38], 937);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 3, 38], 938);
                step(f, Op::ArrayAt(Elem::Float), &[4, 3, 524], 939);
                step(f, Op::FloatLerp, &[524, 886, 103, 525], 940);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 3, 88], 941);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 514], 942);
                step(f, Op::GreaterEqualF, &[514, 888, 89], 943);
                step(f, Op::And, &[88, 89, 92], 944);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 3, 35], 945);
                step(f, Op::MakeAbsolute, &[35, 34, 36], 946);
                step(f, Op::BreakTransform, &[36, 184, 24, 185], 947);
                step(f, Op::RotateVector, &[24, 481, 189], 948);
                step(f, Op::LimitRotationAroundZ, &[24, 516, 100, 26], 949);
                step(f, Op::RotateVector, &[26, 481, 190], 950);
                step(f, Op::CrossV, &[189, 190, 191], 951);
                step(f, Op::BreakVector, &[191, 517, 518, 519], 952);
                step(f, Op::DotV, &[189, 190, 520], 953);
                step(f, Op::Atan2F, &[519, 520, 521], 954);
                step(f, Op::AbsF, &[521, 522], 955);
                step(f, Op::Select(ValueType::Float), &[92, 522, 886, 523], 956);
                step(f, Op::AddF, &[525, 523, 526], 957);
                step(f, Op::ArraySetAt(Elem::Float), &[4, 3, 526], 958);
                step(f, Op::JumpIfFalse, &[88, 1023], 959)
            }
            959 => {
                step(f, Op::JumpIfFalse, &[89, 961], 960)
            }
            960 => {
                step(f, Op::Jump, &[1022], 961)
            }
            961 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 41], 962);
                step(f, Op::BreakTransform, &[41, 197, 28, 198], 963);
                step(f, Op::SubF, &[888, 514, 537], 964);
                step(f, Op::MulF, &[10, 7, 538], 965);
                step(f, Op::MulF, &[537, 538, 539], 966);
                step(f, Op::ScaleV, &[2, 539, 199], 967);
                step(f, Op::AddV, &[197, 199, 200], 968);
                step(f, Op::Equals(Elem::Int), &[3, 71, 90], 969);
                step(f, Op::Select(ValueType::Int), &[90, 72, 71, 59], 970);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 59, 93], 971);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 59, 42], 972);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 59, 43], 973);
                step(f, Op::Select(ValueType::Transform), &[93, 42, 43, 44], 974);
                step(f, Op::MakeAbsolute, &[44, 34, 45], 975);
                step(f, Op::Select(ValueType::Transform), &[90, 45, 44, 46], 976);
                step(f, Op::BreakTransform, &[46, 201, 29, 202], 977);
                step(f, Op::MulF, &[14, 541, 542], 978);
                step(f, Op::FootAvoidance, &[200, 201, 542, 90, 83, 203], 979);
                step(f, Op::RemapF, &[15, 86, 888, 886, 888, 125, 540], 980);
                step(f, Op::LerpV, &[200, 203, 540, 204], 981);
                step(f, Op::MakeTransform, &[204, 28, 477, 53], 982);
                step(f, Op::BreakTransform, &[53, 232, 34, 233], 983);
                step(f, Op::MakeVector, &[886, 886, 57, 234], 984);
                step(f, Op::AddV, &[232, 234, 235], 985);
                step(f, Op::SubV, &[232, 234, 236], 986);
                step(f, Op::LineTrace, &[235, 236, 97, 237, 238, 568], 987);
                step(f, Op::RotateVector, &[34, 480, 239], 988);
                step(f, Op::FindQuatBetween, &[239, 238, 35], 989);
                step(f, Op::MulQ, &[35, 34, 36], 990);
                step(f, Op::MulF, &[55, 54, 569], 991);
                step(f, Op::AddF, &[569, 65, 570], 992);
                step(f, Op::NegF, &[570, 571], 993);
                step(f, Op::MakeVector, &[886, 571, 886, 240], 994);
                step(f, Op::RotateVector, &[36, 240, 242], 995);
                step(f, Op::AddV, &[237, 242, 244], 996);
                step(f, Op::AddV, &[244, 234, 246], 997);
                step(f, Op::SubV, &[244, 234, 247], 998);
                step(f, Op::LineTrace, &[246, 247, 98, 250, 251, 573], 999);
                step(f, Op::BreakVector, &[250, 575, 576, 577], 1000);
                step(f, Op::BreakVector, &[244, 581, 582, 583], 1001);
                step(f, Op::SubF, &[577, 583, 587], 1002);
                step(f, Op::Select(ValueType::Float), &[98, 587, 886, 589], 1003);
                step(f, Op::AddF, &[61, 65, 572], 1004);
                step(f, Op::MakeVector, &[886, 572, 886, 241], 1005);
                step(f, Op::RotateVector, &[36, 241, 243], 1006);
                step(f, Op::AddV, &[237, 243, 245], 1007);
                step(f, Op::AddV, &[245, 234, 248], 1008);
                step(f, Op::SubV, &[245, 234, 249], 1009);
                step(f, Op::LineTrace, &[248, 249, 99, 252, 253, 574], 1010);
                step(f, Op::BreakVector, &[252, 578, 579, 580], 1011);
                step(f, Op::BreakVector, &[245, 584, 585, 586], 1012);
                step(f, Op::SubF, &[580, 586, 588], 1013);
                step(f, Op::Select(ValueType::Float), &[99, 588, 886, 590], 1014);
                step(f, Op::MaxF, &[589, 590, 591], 1015);
                step(f, Op::ClampF, &[591, 886, 64, 592], 1016);
                step(f, Op::MakeVector, &[886, 886, 592, 254], 1017);
                step(f, Op::AddV, &[237, 254, 255], 1018);
                step(f, Op::MakeTransform, &[255, 36, 477, 56], 1019);
                step(f, Op::Select(ValueType::Transform), &[97, 56, 53, 57], 1020);
                step(f, Op::Copy(ValueType::Transform), &[57, 55], 1021);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 3, 55], 1022);
                1022
            }
            1022 => {
                step(f, Op::Jump, &[1127], 1023)
            }
            1023 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 3, 58], 1024);
                step(f, Op::MakeAbsolute, &[58, 34, 59], 1025);
                step(f, Op::BreakTransform, &[59, 256, 37, 257], 1026);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 41], 1027);
                step(f, Op::BreakTransform, &[41, 197, 28, 198], 1028);
                step(f, Op::SubF, &[888, 514, 537], 1029);
                step(f, Op::MulF, &[10, 7, 538], 1030);
                step(f, Op::MulF, &[537, 538, 539], 1031);
                step(f, Op::ScaleV, &[2, 539, 199], 1032);
                step(f, Op::AddV, &[197, 199, 200], 1033);
                step(f, Op::Equals(Elem::Int), &[3, 71, 90], 1034);
                step(f, Op::Select(ValueType::Int), &[90, 72, 71, 59], 1035);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 59, 93], 1036);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 59, 42], 1037);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 59, 43], 1038);
                step(f, Op::Select(ValueType::Transform), &[93, 42, 43, 44], 1039);
                step(f, Op::MakeAbsolute, &[44, 34, 45], 1040);
                step(f, Op::Select(ValueType::Transform), &[90, 45, 44, 46], 1041);
                step(f, Op::BreakTransform, &[46, 201, 29, 202], 1042);
                step(f, Op::MulF, &[14, 541, 542], 1043);
                step(f, Op::FootAvoidance, &[200, 201, 542, 90, 83, 203], 1044);
                step(f, Op::RemapF, &[15, 86, 888, 886, 888, 125, 540], 1045);
                step(f, Op::LerpV, &[200, 203, 540, 204], 1046);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 3, 60], 1047);
                step(f, Op::MakeAbsolute, &[60, 34, 61], 1048);
                step(f, Op::BreakTransform, &[61, 258, 38, 259], 1049);
                step(f, Op::ArrayAt(Elem::Float), &[3, 3, 593], 1050);
                step(f, Op::SubF, &[514, 593, 594], 1051);
                step(f, Op::DeltaTime, &[609], 1052);
                step(f, Op::DivF, &[51, 609, 595], 1053);
                step(f, Op::MulF, &[594, 595, 596], 1054);
                step(f, Op::AddF, &[593, 596, 597], 1055);
                step(f, Op::ClampF, &[597, 886, 888, 599], 1056);
                step(f, Op::AddF, &[514, 596, 598], 1057);
                step(f, Op::ClampF, &[598, 886, 888, 600], 1058);
                step(f, Op::AddF, &[599, 600, 601], 1059);
                step(f, Op::MulF, &[601, 887, 602], 1060);
                step(f, Op::SubF, &[888, 602, 603], 1061);
                step(f, Op::GreaterF, &[594, 886, 100], 1062);
                step(f, Op::SubF, &[600, 599, 604], 1063);
                step(f, Op::DivF, &[604, 594, 605], 1064);
                step(f, Op::Select(ValueType::Float), &[100, 605, 888, 606], 1065);
                step(f, Op::MulF, &[603, 606, 607], 1066);
                step(f, Op::MulF, &[82, 607, 608], 1067);
                step(f, Op::Copy(ValueType::Float), &[51, 611], 1068);
                step(f, Op::SubV, &[204, 258, 264], 1069);
                step(f, Op::DeltaTime, &[612], 1070);
                step(f, Op::DivF, &[611, 612, 613], 1071);
                step(f, Op::ScaleV, &[264, 613, 265], 1072);
                step(f, Op::AddV, &[204, 265, 266], 1073);
                step(f, Op::AddV, &[258, 265, 267], 1074);
                step(f, Op::SubV, &[256, 267, 268], 1075);
                step(f, Op::FloatLerp, &[886, 888, 608, 614], 1076);
                step(f, Op::SubF, &[888, 614, 615], 1077);
                step(f, Op::ScaleV, &[268, 615, 269], 1078);
                step(f, Op::AddV, &[266, 269, 271], 1079);
                step(f, Op::MulF, &[608, 612, 616], 1080);
                step(f, Op::GreaterF, &[616, 886, 101], 1081);
                step(f, Op::DivF, &[614, 616, 617], 1082);
                step(f, Op::Select(ValueType::Float), &[101, 617, 888, 618], 1083);
                step(f, Op::ScaleV, &[264, 618, 270], 1084);
                step(f, Op::SubV, &[271, 270, 272], 1085);
                step(f, Op::Copy(ValueType::Vec3), &[272, 263], 1086);
                step(f, Op::MakeTransform, &[263, 28, 477, 63], 1087);
                step(f, Op::BreakTransform, &[63, 273, 39, 274], 1088);
                step(f, Op::MakeVector, &[886, 886, 57, 275], 1089);
                step(f, Op::AddV, &[273, 275, 276], 1090);
                step(f, Op::SubV, &[273, 275, 277], 1091);
                step(f, Op::LineTrace, &[276, 277, 102, 278, 279, 619], 1092);
                step(f, Op::RotateVector, &[39, 480, 280], 1093);
                step(f, Op::FindQuatBetween, &[280, 279, 40], 1094);
                step(f, Op::MulQ, &[40, 39, 41], 1095);
                step(f, Op::MulF, &[55, 54, 620], 1096);
                step(f, Op::AddF, &[620, 65, 621], 1097);
                step(f, Op::NegF, &[621, 622], 1098);
                step(f, Op::MakeVector, &[886, 622, 886, 281], 1099);
                step(f, Op::RotateVector, &[41, 281, 283], 1100);
                step(f, Op::AddV, &[278, 283, 285], 1101);
                step(f, Op::AddV, &[285, 275, 287], 1102);
                step(f, Op::SubV, &[285, 275, 288], 1103);
                step(f, Op::LineTrace, &[287, 288, 103, 291, 292, 624], 1104);
                step(f, Op::BreakVector, &[291, 626, 627, 628], 1105);
                step(f, Op::BreakVector, &[285, 632, 633, 634], 1106);
                step(f, Op::SubF, &[628, 634, 638], 1107);
                step(f, Op::Select(ValueType::Float), &[103, 638, 886, 640], 1108);
                step(f, Op::AddF, &[61, 65, 623], 1109);
                step(f, Op::MakeVector, &[886, 623, 886, 282], 1110);
                step(f, Op::RotateVector, &[41, 282, 284], 1111);
                step(f, Op::AddV, &[278, 284, 286], 1112);
                step(f, Op::AddV, &[286, 275, 289], 1113);
                step(f, Op::SubV, &[286, 275, 290], 1114);
                step(f, Op::LineTrace, &[289, 290, 104, 293, 294, 625], 1115);
                step(f, Op::BreakVector, &[293, 629, 630, 631], 1116);
                step(f, Op::BreakVector, &[286, 635, 636, 637], 1117);
                step(f, Op::SubF, &[631, 637, 639], 1118);
                step(f, Op::Select(ValueType::Float), &[104, 639, 886, 641], 1119);
                step(f, Op::MaxF, &[640, 641, 642], 1120);
                step(f, Op::ClampF, &[642, 886, 64, 643], 1121);
                step(f, Op::MakeVector, &[886, 886, 643, 295], 1122);
                step(f, Op::AddV, &[278, 295, 296], 1123);
                step(f, Op::MakeTransform, &[296, 41, 477, 66], 1124);
                step(f, Op::Select(ValueType::Transform), &[102, 66, 63, 67], 1125);
                step(f, Op::Copy(ValueType::Transform), &[67, 65], 1126);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 3, 65], 1127);
                1127
            }
            1127 => {
                step(f, Op::JumpIfFalse, &[89, 1198], 1128)
            }
            1128 => {
                step(f, Op::JumpIfFalse, &[88, 1130], 1129)
            }
            1129 => {
                step(f, Op::Jump, &[1179], 1130)
            }
            1130 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 3, 68], 1131);
                step(f, Op::BreakTransform, &[68, 297, 42, 298], 1132);
                step(f, Op::Equals(Elem::Int), &[3, 71, 90], 1133);
                step(f, Op::Select(ValueType::Int), &[90, 72, 71, 59], 1134);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 59, 47], 1135);
                step(f, Op::BreakTransform, &[47, 205, 30, 206], 1136);
                step(f, Op::MulF, &[14, 541, 542], 1137);
                step(f, Op::FootAvoidance, &[297, 205, 542, 90, 83, 207], 1138);
                step(f, Op::MakeTransform, &[207, 42, 477, 48], 1139);
                step(f, Op::BreakTransform, &[48, 208, 31, 209], 1140);
                step(f, Op::MakeVector, &[886, 886, 57, 210], 1141);
                step(f, Op::AddV, &[208, 210, 211], 1142);
                step(f, Op::SubV, &[208, 210, 212], 1143);
                step(f, Op::LineTrace, &[211, 212, 94, 213, 214, 543], 1144);
                step(f, Op::RotateVector, &[31, 480, 215], 1145);
                step(f, Op::FindQuatBetween, &[215, 214, 32], 1146);
                step(f, Op::MulQ, &[32, 31, 33], 1147);
                step(f, Op::MulF, &[55, 54, 544], 1148);
                step(f, Op::AddF, &[544, 65, 545], 1149);
                step(f, Op::NegF, &[545, 546], 1150);
                step(f, Op::MakeVector, &[886, 546, 886, 216], 1151);
                step(f, Op::RotateVector, &[33, 216, 218], 1152);
                step(f, Op::AddV, &[213, 218, 220], 1153);
                step(f, Op::AddV, &[220, 210, 222], 1154);
                step(f, Op::SubV, &[220, 210, 223], 1155);
                step(f, Op::LineTrace, &[222, 223, 95, 226, 227, 548], 1156);
                step(f, Op::BreakVector, &[226, 550, 551, 552], 1157);
                step(f, Op::BreakVector, &[220, 556, 557, 558], 1158);
                step(f, Op::SubF, &[552, 558, 562], 1159);
                step(f, Op::Select(ValueType::Float), &[95, 562, 886, 564], 1160);
                step(f, Op::AddF, &[61, 65, 547], 1161);
                step(f, Op::MakeVector, &[886, 547, 886, 217], 1162);
                step(f, Op::RotateVector, &[33, 217, 219], 1163);
                step(f, Op::AddV, &[213, 219, 221], 1164);
                step(f, Op::AddV, &[221, 210, 224], 1165);
                step(f, Op::SubV, &[221, 210, 225], 1166);
                step(f, Op::LineTrace, &[224, 225, 96, 228, 229, 549], 1167);
                step(f, Op::BreakVector, &[228, 553, 554, 555], 1168);
                step(f, Op::BreakVector, &[221, 559, 560, 561], 1169);
                step(f, Op::SubF, &[555, 561, 563], 1170);
                step(f, Op::Select(ValueType::Float), &[96, 563, 886, 565], 1171);
                step(f, Op::MaxF, &[564, 565, 566], 1172);
                step(f, Op::ClampF, &[566, 886, 64, 567], 1173);
                step(f, Op::MakeVector, &[886, 886, 567, 230], 1174);
                step(f, Op::AddV, &[213, 230, 231], 1175);
                step(f, Op::MakeTransform, &[231, 33, 477, 51], 1176);
                step(f, Op::Select(ValueType::Transform), &[94, 51, 48, 52], 1177);
                step(f, Op::Copy(ValueType::Transform), &[52, 50], 1178);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 3, 50], 1179);
                1179
            }
            1179 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 3, 39], 1180);
                step(f, Op::BreakTransform, &[39, 192, 27, 193], 1181);
                step(f, Op::SubV, &[192, 186, 194], 1182);
                step(f, Op::LengthV, &[194, 527], 1183);
                step(f, Op::SubF, &[66, 67, 528], 1184);
                step(f, Op::SubF, &[527, 528, 529], 1185);
                step(f, Op::MulF, &[67, 891, 530], 1186);
                step(f, Op::ClampF, &[529, 886, 530, 531], 1187);
                step(f, Op::MulF, &[531, 531, 532], 1188);
                step(f, Op::MulF, &[67, 902, 533], 1189);
                step(f, Op::DivF, &[532, 533, 534], 1190);
                step(f, Op::SubF, &[527, 534, 535], 1191);
                step(f, Op::DivF, &[535, 527, 536], 1192);
                step(f, Op::ScaleV, &[194, 536, 195], 1193);
                step(f, Op::AddV, &[186, 195, 196], 1194);
                step(f, Op::MakeTransform, &[196, 27, 477, 40], 1195);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 3, 40], 1196);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 3, 40], 1197);
                step(f, Op::Jump, &[1340], 1198)
            }
            1198 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 3, 39], 1199);
                step(f, Op::BreakTransform, &[39, 192, 27, 193], 1200);
                step(f, Op::SubV, &[192, 186, 194], 1201);
                step(f, Op::LengthV, &[194, 527], 1202);
                step(f, Op::SubF, &[66, 67, 528], 1203);
                step(f, Op::SubF, &[527, 528, 529], 1204);
                step(f, Op::MulF, &[67, 891, 530], 1205);
                step(f, Op::ClampF, &[529, 886, 530, 531], 1206);
                step(f, Op::MulF, &[531, 531, 532], 1207);
                step(f, Op::MulF, &[67, 902, 533], 1208);
                step(f, Op::DivF, &[532, 533, 534], 1209);
                step(f, Op::SubF, &[527, 534, 535], 1210);
                step(f, Op::DivF, &[535, 527, 536], 1211);
                step(f, Op::ScaleV, &[194, 536, 195], 1212);
                step(f, Op::AddV, &[186, 195, 196], 1213);
                step(f, Op::MakeTransform, &[196, 27, 477, 40], 1214);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 3, 68], 1215);
                step(f, Op::ClampF, &[514, 886, 888, 644], 1216);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[6, 5], 1217);
                step(f, Op::ArrayReset(Elem::Vec3), &[5], 1218);
                step(f, Op::BreakTransform, &[40, 318, 47, 319], 1219);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 318], 1220);
                step(f, Op::UnitV, &[2, 317], 1221);
                step(f, Op::LengthV, &[2, 672], 1222);
                step(f, Op::RemapF, &[672, 886, 68, 886, 69, 125, 673], 1223);
                step(f, Op::ScaleV, &[317, 673, 322], 1224);
                step(f, Op::SubV, &[318, 322, 328], 1225);
                step(f, Op::MakeVector, &[886, 886, 71, 326], 1226);
                step(f, Op::AddV, &[328, 326, 330], 1227);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 330], 1228);
                step(f, Op::RemapF, &[672, 886, 68, 886, 73, 125, 675], 1229);
                step(f, Op::MakeVector, &[886, 886, 675, 324], 1230);
                step(f, Op::AddV, &[330, 324, 334], 1231);
                step(f, Op::BreakTransform, &[68, 320, 48, 321], 1232);
                step(f, Op::BreakVector, &[320, 680, 681, 682], 1233);
                step(f, Op::BreakVector, &[318, 677, 678, 679], 1234);
                step(f, Op::SubF, &[682, 679, 683], 1235);
                step(f, Op::MaxF, &[683, 886, 685], 1236);
                step(f, Op::MulF, &[685, 75, 689], 1237);
                step(f, Op::MinF, &[689, 76, 690], 1238);
                step(f, Op::AbsF, &[683, 687], 1239);
                step(f, Op::RemapF, &[687, 886, 79, 886, 78, 125, 688], 1240);
                step(f, Op::AddF, &[690, 688, 692], 1241);
                step(f, Op::MakeVector, &[886, 886, 692, 332], 1242);
                step(f, Op::AddV, &[334, 332, 336], 1243);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 336], 1244);
                step(f, Op::RemapF, &[672, 886, 68, 886, 70, 125, 674], 1245);
                step(f, Op::ScaleV, &[317, 674, 323], 1246);
                step(f, Op::AddV, &[320, 323, 329], 1247);
                step(f, Op::MakeVector, &[886, 886, 72, 327], 1248);
                step(f, Op::AddV, &[329, 327, 331], 1249);
                step(f, Op::RemapF, &[672, 886, 68, 886, 74, 125, 676], 1250);
                step(f, Op::MakeVector, &[886, 886, 676, 325], 1251);
                step(f, Op::AddV, &[331, 325, 335], 1252);
                step(f, Op::NegF, &[683, 684], 1253);
                step(f, Op::MaxF, &[684, 886, 686], 1254);
                step(f, Op::MulF, &[686, 77, 691], 1255);
                step(f, Op::AddF, &[691, 688, 693], 1256);
                step(f, Op::MakeVector, &[886, 886, 693, 333], 1257);
                step(f, Op::AddV, &[335, 333, 337], 1258);
                step(f, Op::LerpV, &[336, 337, 887, 338], 1259);
                step(f, Op::GetTransform, &[35, 71, 125, 77], 1260);
                step(f, Op::BreakTransform, &[77, 339, 49, 340], 1261);
                step(f, Op::BreakVector, &[339, 703, 704, 705], 1262);
                step(f, Op::SubF, &[888, 15, 697], 1263);
                step(f, Op::MulF, &[80, 697, 698], 1264);
                step(f, Op::MulF, &[14, 698, 699], 1265);
                step(f, Op::QuatFromAxisAngle, &[480, 699, 50], 1266);
                step(f, Op::SubV, &[338, 339, 341], 1267);
                step(f, Op::BreakVector, &[341, 694, 695, 696], 1268);
                step(f, Op::MakeVector, &[694, 695, 886, 342], 1269);
                step(f, Op::RotateVector, &[50, 342, 343], 1270);
                step(f, Op::BreakVector, &[343, 700, 701, 702], 1271);
                step(f, Op::AddF, &[703, 700, 709], 1272);
                step(f, Op::AddF, &[704, 701, 710], 1273);
                step(f, Op::BreakVector, &[338, 706, 707, 708], 1274);
                step(f, Op::MakeVector, &[709, 710, 708, 344], 1275);
                step(f, Op::DistanceV, &[318, 320, 711], 1276);
                step(f, Op::RemapF, &[711, 891, 903, 886, 888, 125, 712], 1277);
                step(f, Op::LerpV, &[338, 344, 712, 345], 1278);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 345], 1279);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 337], 1280);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 331], 1281);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 320], 1282);
                step(f, Op::JumpIfFalse, &[8, 1284], 1283)
            }
            1283 => {
                step(f, Op::DrawSpline, &[5, 71, 74, 887, 483], 1284);
                1284
            }
            1284 => {
                step(f, Op::Spline, &[5, 644, 71, 346, 347], 1285);
                step(f, Op::SlerpQ, &[47, 48, 644, 51], 1286);
                step(f, Op::MulF, &[644, 896, 714], 1287);
                step(f, Op::SinF, &[714, 715], 1288);
                step(f, Op::SmoothStepF, &[644, 886, 93, 713], 1289);
                step(f, Op::MulF, &[715, 713, 716], 1290);
                step(f, Op::MulF, &[716, 81, 717], 1291);
                step(f, Op::SlerpQ, &[51, 94, 717, 52], 1292);
                step(f, Op::MakeTransform, &[346, 52, 477, 78], 1293);
                step(f, Op::Copy(ValueType::Transform), &[78, 76], 1294);
                step(f, Op::BreakTransform, &[76, 299, 43, 300], 1295);
                step(f, Op::Equals(Elem::Int), &[3, 71, 90], 1296);
                step(f, Op::Select(ValueType::Int), &[90, 72, 71, 59], 1297);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 59, 47], 1298);
                step(f, Op::BreakTransform, &[47, 205, 30, 206], 1299);
                step(f, Op::SubF, &[888, 15, 541], 1300);
                step(f, Op::MulF, &[14, 541, 542], 1301);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 59, 105], 1302);
                step(f, Op::Select(ValueType::Float), &[105, 84, 886, 647], 1303);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 514], 1304);
                step(f, Op::ClampF, &[514, 886, 888, 644], 1305);
                step(f, Op::MulF, &[644, 896, 645], 1306);
                step(f, Op::SinF, &[645, 646], 1307);
                step(f, Op::MulF, &[646, 646, 648], 1308);
                step(f, Op::MulF, &[647, 648, 649], 1309);
                step(f, Op::AddF, &[83, 649, 650], 1310);
                step(f, Op::FootAvoidance, &[299, 205, 542, 90, 650, 301], 1311);
                step(f, Op::SubV, &[301, 299, 302], 1312);
                step(f, Op::LengthV, &[302, 651], 1313);
                step(f, Op::AddF, &[651, 649, 652], 1314);
                step(f, Op::DivF, &[651, 652, 653], 1315);
                step(f, Op::ArrayAt(Elem::Float), &[2, 59, 656], 1316);
                step(f, Op::LessF, &[656, 514, 107], 1317);
                step(f, Op::LessEqualF, &[85, 886, 106], 1318);
                step(f, Op::SmoothStepF, &[656, 886, 85, 657], 1319);
                step(f, Op::MulF, &[657, 15, 658], 1320);
                step(f, Op::SubF, &[888, 658, 659], 1321);
                step(f, Op::Select(ValueType::Float), &[106, 888, 659, 660], 1322);
                step(f, Op::Select(ValueType::Float), &[107, 660, 888, 661], 1323);
                step(f, Op::MulF, &[653, 661, 662], 1324);
                step(f, Op::SmoothStepF, &[644, 886, 85, 654], 1325);
                step(f, Op::Select(ValueType::Float), &[106, 888, 654, 655], 1326);
                step(f, Op::MulF, &[662, 655, 663], 1327);
                step(f, Op::ScaleV, &[302, 663, 303], 1328);
                step(f, Op::AddV, &[299, 303, 304], 1329);
                step(f, Op::MulF, &[3, 133, 664], 1330);
                step(f, Op::MulF, &[664, 648, 665], 1331);
                step(f, Op::MakeVector, &[886, 886, 665, 305], 1332);
                step(f, Op::AddV, &[304, 305, 306], 1333);
                step(f, Op::MakeTransform, &[306, 43, 477, 69], 1334);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 3, 69], 1335);
                step(f, Op::ScaleV, &[302, 662, 307], 1336);
                step(f, Op::AddV, &[299, 307, 308], 1337);
                step(f, Op::AddV, &[308, 305, 309], 1338);
                step(f, Op::MakeTransform, &[309, 43, 477, 70], 1339);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 3, 70], 1340);
                1340
            }
            1340 => {
                step(f, Op::GreaterF, &[21, 886, 91], 1341);
                step(f, Op::JumpIfFalse, &[91, 1364], 1342)
            }
            1342 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 3, 71], 1343);
                step(f, Op::BreakTransform, &[71, 310, 44, 311], 1344);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 3, 72], 1345);
                step(f, Op::BreakTransform, &[72, 312, 45, 313], 1346);
                step(f, Op::MulF, &[21, 21, 666], 1347);
                step(f, Op::LerpV, &[310, 312, 666, 314], 1348);
                step(f, Op::SubF, &[888, 21, 667], 1349);
                step(f, Op::MulF, &[21, 667, 668], 1350);
                step(f, Op::MulF, &[135, 891, 669], 1351);
                step(f, Op::MulF, &[668, 669, 670], 1352);
                step(f, Op::MakeVector, &[886, 886, 670, 315], 1353);
                step(f, Op::AddV, &[314, 315, 316], 1354);
                step(f, Op::SlerpQ, &[44, 45, 21, 46], 1355);
                step(f, Op::MakeTransform, &[316, 46, 477, 73], 1356);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 3, 73], 1357);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 3, 71], 1358);
                step(f, Op::BreakTransform, &[71, 310, 44, 311], 1359);
                step(f, Op::LerpV, &[310, 312, 666, 314], 1360);
                step(f, Op::AddV, &[314, 315, 316], 1361);
                step(f, Op::SlerpQ, &[44, 45, 21, 46], 1362);
                step(f, Op::MakeTransform, &[316, 46, 477, 73], 1363);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 3, 73], 1364);
                1364
            }
            1364 => {
                step(f, Op::GreaterEqualF, &[514, 888, 89], 1365);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 3, 89], 1366);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 41], 1367);
                step(f, Op::BreakTransform, &[41, 197, 28, 198], 1368);
                step(f, Op::SubF, &[888, 514, 537], 1369);
                step(f, Op::MulF, &[10, 7, 538], 1370);
                step(f, Op::MulF, &[537, 538, 539], 1371);
                step(f, Op::ScaleV, &[2, 539, 199], 1372);
                step(f, Op::AddV, &[197, 199, 200], 1373);
                step(f, Op::Equals(Elem::Int), &[3, 71, 90], 1374);
                step(f, Op::Select(ValueType::Int), &[90, 72, 71, 59], 1375);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 59, 93], 1376);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 59, 42], 1377);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 59, 43], 1378);
                step(f, Op::Select(ValueType::Transform), &[93, 42, 43, 44], 1379);
                step(f, Op::InterpolateTransform, &[2, 121, 22, 33], 1380);
                step(f, Op::Select(ValueType::Transform), &[91, 33, 2, 34], 1381);
                step(f, Op::MakeAbsolute, &[44, 34, 45], 1382);
                step(f, Op::Select(ValueType::Transform), &[90, 45, 44, 46], 1383);
                step(f, Op::BreakTransform, &[46, 201, 29, 202], 1384);
                step(f, Op::MulF, &[14, 541, 542], 1385);
                step(f, Op::FootAvoidance, &[200, 201, 542, 90, 83, 203], 1386);
                step(f, Op::RemapF, &[15, 86, 888, 886, 888, 125, 540], 1387);
                step(f, Op::LerpV, &[200, 203, 540, 204], 1388);
                step(f, Op::MakeTransform, &[204, 94, 477, 62], 1389);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 3, 62], 1390);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 3, 79], 1391);
                step(f, Op::BreakTransform, &[79, 348, 53, 349], 1392);
                step(f, Op::MakeVector, &[886, 886, 52, 358], 1393);
                step(f, Op::AddV, &[348, 358, 359], 1394);
                step(f, Op::GetTransform, &[0, 71, 125, 81], 1395);
                step(f, Op::BreakTransform, &[81, 353, 55, 354], 1396);
                step(f, Op::MakeTransform, &[359, 55, 477, 83], 1397);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 3, 20], 1398);
                step(f, Op::GetTransform, &[20, 71, 125, 82], 1399);
                step(f, Op::BreakTransform, &[82, 355, 56, 356], 1400);
                step(f, Op::SubV, &[355, 353, 357], 1401);
                step(f, Op::AddV, &[359, 357, 360], 1402);
                step(f, Op::FootPivots, &[359, 360, 54, 53, 52, 55, 361, 362, 363], 1403);
                step(f, Op::GetParent, &[0, 18], 1404);
                step(f, Op::GetParent, &[18, 19], 1405);
                step(f, Op::GetTransform, &[19, 71, 126, 80], 1406);
                step(f, Op::BreakTransform, &[80, 350, 54, 351], 1407);
                step(f, Op::SubV, &[348, 350, 352], 1408);
                step(f, Op::DotV, &[352, 481, 718], 1409);
                step(f, Op::RemapF, &[718, 88, 87, 89, 886, 125, 721], 1410);
                step(f, Op::LengthV, &[2, 719], 1411);
                step(f, Op::RemapF, &[719, 886, 99, 886, 888, 125, 720], 1412);
                step(f, Op::MulF, &[721, 720, 722], 1413);
                step(f, Op::QuatFromAxisAngle, &[484, 722, 57], 1414);
                step(f, Op::RotateAroundPoint, &[83, 361, 57, 84], 1415);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 723], 1416);
                step(f, Op::SmoothStepF, &[723, 886, 93, 725], 1417);
                step(f, Op::SubF, &[888, 723, 724], 1418);
                step(f, Op::SmoothStepF, &[724, 886, 93, 726], 1419);
                step(f, Op::MulF, &[725, 726, 727], 1420);
                step(f, Op::LerpF, &[92, 888, 727, 728], 1421);
                step(f, Op::MulF, &[722, 728, 729], 1422);
                step(f, Op::QuatFromAxisAngle, &[484, 729, 58], 1423);
                step(f, Op::SubV, &[362, 361, 364], 1424);
                step(f, Op::RotateVector, &[58, 364, 365], 1425);
                step(f, Op::AddV, &[361, 365, 366], 1426);
                step(f, Op::RemapF, &[718, 90, 88, 91, 886, 125, 730], 1427);
                step(f, Op::MulF, &[730, 720, 731], 1428);
                step(f, Op::QuatFromAxisAngle, &[484, 731, 59], 1429);
                step(f, Op::RotateAroundPoint, &[84, 366, 59, 85], 1430);
                step(f, Op::RemapF, &[718, 94, 95, 886, 96, 125, 732], 1431);
                step(f, Op::RotateVector, &[53, 480, 367], 1432);
                step(f, Op::BreakVector, &[367, 733, 734, 735], 1433);
                step(f, Op::CosF, &[98, 737], 1434);
                step(f, Op::CosF, &[97, 736], 1435);
                step(f, Op::RemapF, &[735, 737, 736, 886, 888, 125, 738], 1436);
                step(f, Op::MulF, &[720, 738, 739], 1437);
                step(f, Op::MulF, &[732, 739, 740], 1438);
                step(f, Op::QuatFromAxisAngle, &[484, 740, 60], 1439);
                step(f, Op::RotateAroundPoint, &[85, 363, 60, 86], 1440);
                step(f, Op::SubF, &[888, 15, 741], 1441);
                step(f, Op::MulF, &[14, 741, 742], 1442);
                step(f, Op::LimitRotationAroundZ, &[53, 742, 100, 61], 1443);
                step(f, Op::RotateAroundPoint, &[86, 348, 61, 87], 1444);
                step(f, Op::BreakTransform, &[87, 368, 62, 369], 1445);
                step(f, Op::ArrayAt(Elem::Float), &[4, 3, 743], 1446);
                step(f, Op::MulF, &[743, 101, 744], 1447);
                step(f, Op::MulF, &[744, 102, 745], 1448);
                step(f, Op::AddF, &[744, 102, 746], 1449);
                step(f, Op::DivF, &[745, 746, 747], 1450);
                step(f, Op::MakeVector, &[886, 886, 747, 370], 1451);
                step(f, Op::AddV, &[368, 370, 371], 1452);
                step(f, Op::MakeTransform, &[371, 62, 369, 88], 1453);
                step(f, Op::ArraySetAt(Elem::Transform), &[7, 3, 88], 1454);
                step(f, Op::JumpIfFalse, &[8, 1459], 1455)
            }
            1455 => {
                step(f, Op::DrawPoint, &[363, 904, 484], 1456);
                step(f, Op::DrawPoint, &[361, 904, 481], 1457);
                step(f, Op::DrawPoint, &[366, 904, 480], 1458);
                step(f, Op::DrawTransform, &[79, 903, 887], 1459);
                1459
            }
            1459 => {
                step(f, Op::Jump, &[596], 1460)
            }
            1460 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1461);
                step(f, Op::Copy(ValueType::Int), &[71, 5], 1462);
                1462
            }
            1462 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 5, 1, 6, 7, 1501], 1463)
            }
            1463 => {
                step(f, Op::GetParent, &[1, 22], 1464);
                step(f, Op::GetParent, &[22, 23], 1465);
                step(f, Op::GetParent, &[23, 24], 1466);
                step(f, Op::GetTransform, &[24, 71, 126, 89], 1467);
                step(f, Op::BreakTransform, &[89, 372, 63, 373], 1468);
                step(f, Op::LengthV, &[1, 749], 1469);
                step(f, Op::ClavicleOffset, &[12, 749, 108, 112, 750], 1470);
                step(f, Op::MakeVector, &[886, 886, 750, 374], 1471);
                step(f, Op::AddV, &[372, 374, 375], 1472);
                step(f, Op::MakeTransform, &[375, 63, 477, 90], 1473);
                step(f, Op::SetTransform, &[24, 90, 71, 125, 888], 1474);
                step(f, Op::GetTransform, &[1, 71, 126, 91], 1475);
                step(f, Op::GetTransform, &[23, 71, 126, 92], 1476);
                step(f, Op::BreakTransform, &[92, 376, 65, 377], 1477);
                step(f, Op::Equals(Elem::Int), &[6, 71, 108], 1478);
                step(f, Op::Select(ValueType::Int), &[108, 72, 71, 62], 1479);
                step(f, Op::ArrayAt(Elem::Float), &[0, 62, 748], 1480);
                step(f, Op::ArmSwingRotation, &[748, 1, 0, 109, 895, 905, 888, 108, 106, 107, 110, 895, 888, 751], 1481);
                step(f, Op::QuatFromAxisAngle, &[484, 751, 64], 1482);
                step(f, Op::RotateAroundPoint, &[91, 376, 64, 93], 1483);
                step(f, Op::BreakTransform, &[93, 378, 66, 379], 1484);
                step(f, Op::RemapF, &[749, 886, 108, 886, 111, 125, 752], 1485);
                step(f, Op::MakeVector, &[886, 886, 752, 380], 1486);
                step(f, Op::AddV, &[378, 380, 381], 1487);
                step(f, Op::MakeTransform, &[381, 66, 477, 94], 1488);
                step(f, Op::Select(ValueType::Vec3), &[108, 485, 484, 383], 1489);
                step(f, Op::Select(ValueType::Vec3), &[108, 481, 486, 384], 1490);
                step(f, Op::ArrayAt(Elem::Vec3), &[4, 6, 382], 1491);
                step(f, Op::TwoBoneIK, &[23, 22, 1, 94, 383, 384, 382, 71, 888, 126, 906, 907, 125, 109, 753], 1492);
                step(f, Op::JumpIfFalse, &[8, 1500], 1493)
            }
            1493 => {
                step(f, Op::GetTransform, &[23, 71, 126, 92], 1494);
                step(f, Op::BreakTransform, &[92, 376, 65, 377], 1495);
                step(f, Op::GetTransform, &[1, 71, 126, 91], 1496);
                step(f, Op::RotateAroundPoint, &[91, 376, 64, 93], 1497);
                step(f, Op::BreakTransform, &[93, 378, 66, 379], 1498);
                step(f, Op::AddV, &[378, 380, 381], 1499);
                step(f, Op::DrawLine, &[376, 381, 887, 481], 1500);
                1500
            }
            1500 => {
                step(f, Op::Jump, &[1462], 1501)
            }
            1501 => {
                step(f, Op::NegF, &[3, 864], 1502);
                step(f, Op::MakeVector, &[886, 886, 864, 459], 1503);
                step(f, Op::MakeTransform, &[459, 94, 477, 115], 1504);
                step(f, Op::SetTransform, &[36, 115, 71, 125, 888], 1505);
                step(f, Op::Copy(ValueType::Float), &[893, 757], 1506);
                step(f, Op::Copy(ValueType::Bool), &[126, 110], 1507);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 11], 1508);
                step(f, Op::Copy(ValueType::Int), &[71, 63], 1509);
                step(f, Op::MakeVector, &[886, 886, 57, 387], 1510);
                1510
            }
            1510 => {
                step(f, Op::ForEachNext(Elem::Transform), &[11, 63, 95, 64, 65, 1522], 1511)
            }
            1511 => {
                step(f, Op::BreakTransform, &[95, 385, 67, 386], 1512);
                step(f, Op::AddV, &[385, 387, 388], 1513);
                step(f, Op::SubV, &[385, 387, 389], 1514);
                step(f, Op::SphereTrace, &[388, 389, 56, 111, 390, 391, 758], 1515);
                step(f, Op::BreakVector, &[390, 759, 760, 761], 1516);
                step(f, Op::LessF, &[761, 757, 112], 1517);
                step(f, Op::And, &[111, 112, 113], 1518);
                step(f, Op::JumpIfFalse, &[113, 1521], 1519)
            }
            1519 => {
                step(f, Op::Copy(ValueType::Float), &[761, 757], 1520);
                step(f, Op::Copy(ValueType::Bool), &[125, 110], 1521);
                1521
            }
            1521 => {
                step(f, Op::Jump, &[1510], 1522)
            }
            1522 => {
                step(f, Op::Select(ValueType::Float), &[110, 757, 886, 762], 1523);
                step(f, Op::ClampF, &[762, 62, 63, 763], 1524);
                step(f, Op::Copy(ValueType::Float), &[763, 756], 1525);
                step(f, Op::SubF, &[888, 21, 755], 1526);
                step(f, Op::MulF, &[756, 755, 764], 1527);
                step(f, Op::SubF, &[888, 132, 765], 1528);
                step(f, Op::MulF, &[3, 765, 766], 1529);
                step(f, Op::AddF, &[764, 766, 767], 1530);
                step(f, Op::MakeVector, &[16, 886, 886, 392], 1531);
                step(f, Op::MakeVector, &[767, 886, 886, 393], 1532);
                step(f, Op::Select(ValueType::Float), &[2, 767, 17, 768], 1533);
                step(f, Op::MakeVector, &[768, 886, 886, 394], 1534);
                step(f, Op::Copy(ValueType::Float), &[50, 769], 1535);
                step(f, Op::Copy(ValueType::Float), &[51, 770], 1536);
                step(f, Op::SubV, &[393, 394, 399], 1537);
                step(f, Op::DeltaTime, &[771], 1538);
                step(f, Op::DivF, &[770, 771, 772], 1539);
                step(f, Op::ScaleV, &[399, 772, 400], 1540);
                step(f, Op::AddV, &[393, 400, 401], 1541);
                step(f, Op::AddV, &[394, 400, 402], 1542);
                step(f, Op::SubV, &[392, 402, 403], 1543);
                step(f, Op::FloatLerp, &[886, 888, 769, 773], 1544);
                step(f, Op::SubF, &[888, 773, 774], 1545);
                step(f, Op::ScaleV, &[403, 774, 404], 1546);
                step(f, Op::AddV, &[401, 404, 406], 1547);
                step(f, Op::MulF, &[769, 771, 775], 1548);
                step(f, Op::GreaterF, &[775, 886, 114], 1549);
                step(f, Op::DivF, &[773, 775, 776], 1550);
                step(f, Op::Select(ValueType::Float), &[114, 776, 888, 777], 1551);
                step(f, Op::ScaleV, &[399, 777, 405], 1552);
                step(f, Op::SubV, &[406, 405, 407], 1553);
                step(f, Op::Copy(ValueType::Vec3), &[407, 398], 1554);
                step(f, Op::BreakVector, &[398, 778, 779, 780], 1555);
                step(f, Op::Select(ValueType::Float), &[1, 767, 778, 781], 1556);
                step(f, Op::Copy(ValueType::Float), &[781, 16], 1557);
                step(f, Op::Copy(ValueType::Float), &[767, 17], 1558);
                step(f, Op::GetTransform, &[37, 71, 125, 100], 1559);
                step(f, Op::BreakTransform, &[100, 420, 74, 421], 1560);
                step(f, Op::PelvisLean, &[1, 115, 120, 121, 799, 800], 1561);
                step(f, Op::LengthV, &[2, 754], 1562);
                step(f, Op::RemapF, &[754, 886, 115, 886, 113, 125, 782], 1563);
                step(f, Op::MulF, &[15, 114, 785], 1564);
                step(f, Op::SubF, &[888, 785, 786], 1565);
                step(f, Op::MulF, &[782, 786, 787], 1566);
                step(f, Op::MulF, &[12, 908, 783], 1567);
                step(f, Op::SinF, &[783, 784], 1568);
                step(f, Op::MulF, &[787, 784, 788], 1569);
                step(f, Op::MulF, &[788, 755, 789], 1570);
                step(f, Op::AddF, &[789, 16, 790], 1571);
                step(f, Op::SubF, &[790, 3, 791], 1572);
                step(f, Op::MakeVector, &[886, 800, 791, 422], 1573);
                step(f, Op::AddV, &[420, 422, 423], 1574);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 71, 96], 1575);
                step(f, Op::BreakTransform, &[96, 408, 68, 409], 1576);
                step(f, Op::BreakVector, &[408, 801, 802, 803], 1577);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 72, 97], 1578);
                step(f, Op::BreakTransform, &[97, 410, 69, 411], 1579);
                step(f, Op::BreakVector, &[410, 804, 805, 806], 1580);
                step(f, Op::SubF, &[803, 806, 807], 1581);
                step(f, Op::PelvisSideLean, &[807, 122, 123, 808], 1582);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 71, 98], 1583);
                step(f, Op::BreakTransform, &[98, 414, 70, 415], 1584);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 72, 99], 1585);
                step(f, Op::BreakTransform, &[99, 416, 71, 417], 1586);
                step(f, Op::SlerpQ, &[70, 71, 887, 72], 1587);
                step(f, Op::EulerFromQuat, &[72, 71, 418], 1588);
                step(f, Op::BreakVector, &[418, 795, 796, 797], 1589);
                step(f, Op::RemapF, &[754, 116, 115, 886, 117, 125, 793], 1590);
                step(f, Op::SubV, &[408, 410, 412], 1591);
                step(f, Op::RotateVector, &[0, 481, 413], 1592);
                step(f, Op::DotV, &[412, 413, 792], 1593);
                step(f, Op::MulF, &[793, 792, 794], 1594);
                step(f, Op::AddF, &[797, 794, 798], 1595);
                step(f, Op::MakeVector, &[799, 808, 798, 419], 1596);
                step(f, Op::QuatFromEuler, &[419, 71, 73], 1597);
                step(f, Op::MakeTransform, &[423, 73, 477, 101], 1598);
                step(f, Op::SetTransform, &[38, 101, 71, 125, 888], 1599);
                step(f, Op::GetTransform, &[39, 72, 125, 102], 1600);
                step(f, Op::BreakTransform, &[102, 424, 78, 425], 1601);
                step(f, Op::QuatFromAxisAngle, &[480, 794, 75], 1602);
                step(f, Op::DivF, &[118, 904, 809], 1603);
                step(f, Op::QuatScale, &[75, 809, 76], 1604);
                step(f, Op::MulQ, &[78, 76, 82], 1605);
                step(f, Op::MakeTransform, &[424, 82, 477, 106], 1606);
                step(f, Op::SetTransform, &[40, 106, 72, 125, 888], 1607);
                step(f, Op::GetTransform, &[41, 72, 125, 103], 1608);
                step(f, Op::BreakTransform, &[103, 426, 79, 427], 1609);
                step(f, Op::MulQ, &[79, 76, 83], 1610);
                step(f, Op::MakeTransform, &[426, 83, 477, 107], 1611);
                step(f, Op::SetTransform, &[42, 107, 72, 125, 888], 1612);
                step(f, Op::GetTransform, &[43, 72, 125, 104], 1613);
                step(f, Op::BreakTransform, &[104, 428, 80, 429], 1614);
                step(f, Op::MulQ, &[80, 76, 84], 1615);
                step(f, Op::MakeTransform, &[428, 84, 477, 108], 1616);
                step(f, Op::SetTransform, &[44, 108, 72, 125, 888], 1617);
                step(f, Op::GetTransform, &[45, 72, 125, 105], 1618);
                step(f, Op::BreakTransform, &[105, 430, 81, 431], 1619);
                step(f, Op::QuatScale, &[75, 119, 77], 1620);
                step(f, Op::MulQ, &[81, 77, 85], 1621);
                step(f, Op::MakeTransform, &[430, 85, 477, 109], 1622);
                step(f, Op::SetTransform, &[46, 109, 72, 125, 888], 1623);
                step(f, Op::Or, &[1, 2, 120], 1624);
                step(f, Op::Copy(ValueType::Float), &[886, 811], 1625);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1626);
                step(f, Op::Copy(ValueType::Int), &[71, 66], 1627);
                1627
            }
            1627 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 66, 25, 67, 68, 1674], 1628)
            }
            1628 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 67, 115], 1629);
                step(f, Op::GetParent, &[25, 26], 1630);
                step(f, Op::GetParent, &[26, 27], 1631);
                step(f, Op::GetTransform, &[27, 71, 126, 110], 1632);
                step(f, Op::BreakTransform, &[110, 432, 86, 433], 1633);
                step(f, Op::BreakVector, &[432, 812, 813, 814], 1634);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 67, 111], 1635);
                step(f, Op::BreakTransform, &[111, 434, 87, 435], 1636);
                step(f, Op::BreakVector, &[434, 815, 816, 817], 1637);
                step(f, Op::ArrayAt(Elem::Float), &[1, 67, 821], 1638);
                step(f, Op::MulF, &[821, 124, 822], 1639);
                step(f, Op::MulF, &[822, 822, 823], 1640);
                step(f, Op::SubF, &[812, 815, 818], 1641);
                step(f, Op::SubF, &[813, 816, 819], 1642);
                step(f, Op::MakeVector, &[818, 819, 886, 436], 1643);
                step(f, Op::DotV, &[436, 436, 820], 1644);
                step(f, Op::SubF, &[823, 820, 824], 1645);
                step(f, Op::SqrtF, &[824, 825], 1646);
                step(f, Op::AddF, &[817, 825, 826], 1647);
                step(f, Op::SubF, &[814, 826, 827], 1648);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 67, 112], 1649);
                step(f, Op::BreakTransform, &[112, 437, 88, 438], 1650);
                step(f, Op::BreakVector, &[437, 828, 829, 830], 1651);
                step(f, Op::AddF, &[830, 52, 831], 1652);
                step(f, Op::MinF, &[817, 831, 832], 1653);
                step(f, Op::AddF, &[832, 825, 833], 1654);
                step(f, Op::SubF, &[814, 833, 834], 1655);
                step(f, Op::Equals(Elem::Int), &[67, 71, 116], 1656);
                step(f, Op::Select(ValueType::Int), &[116, 72, 71, 69], 1657);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 69, 117], 1658);
                step(f, Op::ArrayAt(Elem::Float), &[2, 69, 838], 1659);
                step(f, Op::RemapF, &[838, 887, 888, 886, 888, 125, 839], 1660);
                step(f, Op::RemapF, &[838, 886, 127, 888, 886, 125, 840], 1661);
                step(f, Op::MaxF, &[839, 840, 841], 1662);
                step(f, Op::Select(ValueType::Float), &[117, 888, 841, 842], 1663);
                step(f, Op::LerpF, &[827, 834, 842, 843], 1664);
                step(f, Op::ArrayAt(Elem::Float), &[2, 67, 835], 1665);
                step(f, Op::RemapF, &[835, 887, 888, 886, 888, 125, 836], 1666);
                step(f, Op::MulF, &[843, 836, 844], 1667);
                step(f, Op::RemapF, &[835, 886, 127, 888, 886, 125, 837], 1668);
                step(f, Op::MulF, &[827, 837, 845], 1669);
                step(f, Op::MaxF, &[844, 845, 846], 1670);
                step(f, Op::Select(ValueType::Float), &[115, 827, 846, 847], 1671);
                step(f, Op::MaxF, &[811, 847, 848], 1672);
                step(f, Op::Copy(ValueType::Float), &[848, 811], 1673);
                step(f, Op::Jump, &[1627], 1674)
            }
            1674 => {
                step(f, Op::ClampF, &[811, 886, 125, 849], 1675);
                step(f, Op::Copy(ValueType::Float), &[849, 810], 1676);
                step(f, Op::MakeVector, &[18, 886, 886, 439], 1677);
                step(f, Op::MakeVector, &[810, 886, 886, 440], 1678);
                step(f, Op::MakeVector, &[19, 886, 886, 441], 1679);
                step(f, Op::GreaterF, &[810, 18, 118], 1680);
                step(f, Op::Select(ValueType::Float), &[118, 129, 126, 850], 1681);
                step(f, Op::Copy(ValueType::Float), &[51, 852], 1682);
                step(f, Op::SubV, &[440, 441, 446], 1683);
                step(f, Op::DeltaTime, &[853], 1684);
                step(f, Op::DivF, &[852, 853, 854], 1685);
                step(f, Op::ScaleV, &[446, 854, 447], 1686);
                step(f, Op::AddV, &[440, 447, 448], 1687);
                step(f, Op::AddV, &[441, 447, 449], 1688);
                step(f, Op::SubV, &[439, 449, 450], 1689);
                step(f, Op::FloatLerp, &[886, 888, 850, 855], 1690);
                step(f, Op::SubF, &[888, 855, 856], 1691);
                step(f, Op::ScaleV, &[450, 856, 451], 1692);
                step(f, Op::AddV, &[448, 451, 453], 1693);
                step(f, Op::MulF, &[850, 853, 857], 1694);
                step(f, Op::GreaterF, &[857, 886, 119], 1695);
                step(f, Op::DivF, &[855, 857, 858], 1696);
                step(f, Op::Select(ValueType::Float), &[119, 858, 888, 859], 1697);
                step(f, Op::ScaleV, &[446, 859, 452], 1698);
                step(f, Op::SubV, &[453, 452, 454], 1699);
                step(f, Op::Copy(ValueType::Vec3), &[454, 445], 1700);
                step(f, Op::BreakVector, &[445, 860, 861, 862], 1701);
                step(f, Op::Select(ValueType::Float), &[120, 810, 860, 863], 1702);
                step(f, Op::Copy(ValueType::Float), &[863, 18], 1703);
                step(f, Op::Copy(ValueType::Float), &[810, 19], 1704);
                step(f, Op::GetTransform, &[47, 71, 126, 113], 1705);
                step(f, Op::BreakTransform, &[113, 455, 89, 456], 1706);
                step(f, Op::MakeVector, &[886, 886, 18, 457], 1707);
                step(f, Op::SubV, &[455, 457, 458], 1708);
                step(f, Op::MakeTransform, &[458, 89, 477, 114], 1709);
                step(f, Op::SetTransform, &[48, 114, 71, 125, 888], 1710);
                step(f, Op::JumpIfFalse, &[8, 1716], 1711)
            }
            1711 => {
                step(f, Op::GetTransform, &[47, 71, 126, 113], 1712);
                step(f, Op::BreakTransform, &[113, 455, 89, 456], 1713);
                step(f, Op::SubV, &[455, 457, 458], 1714);
                step(f, Op::MakeTransform, &[458, 89, 477, 114], 1715);
                step(f, Op::DrawTransform, &[114, 909, 887], 1716);
                1716
            }
            1716 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1717);
                step(f, Op::Copy(ValueType::Int), &[71, 8], 1718);
                1718
            }
            1718 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 8, 2, 9, 10, 1766], 1719)
            }
            1719 => {
                step(f, Op::GetParent, &[2, 29], 1720);
                step(f, Op::GetParent, &[29, 30], 1721);
                step(f, Op::GetTransform, &[30, 71, 126, 116], 1722);
                step(f, Op::BreakTransform, &[116, 460, 90, 461], 1723);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 9, 117], 1724);
                step(f, Op::BreakTransform, &[117, 462, 91, 463], 1725);
                step(f, Op::SubV, &[462, 460, 464], 1726);
                step(f, Op::LengthV, &[464, 876], 1727);
                step(f, Op::ArrayAt(Elem::Float), &[1, 9, 865], 1728);
                step(f, Op::MulF, &[865, 136, 866], 1729);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 9, 121], 1730);
                step(f, Op::ArrayAt(Elem::Float), &[2, 9, 867], 1731);
                step(f, Op::ClampF, &[867, 886, 888, 868], 1732);
                step(f, Op::LessF, &[868, 887, 122], 1733);
                step(f, Op::SmoothStepF, &[868, 138, 139, 871], 1734);
                step(f, Op::MulF, &[868, 896, 869], 1735);
                step(f, Op::SinF, &[869, 870], 1736);
                step(f, Op::MaxF, &[871, 870, 872], 1737);
                step(f, Op::Select(ValueType::Float), &[122, 872, 870, 873], 1738);
                step(f, Op::MulF, &[873, 137, 874], 1739);
                step(f, Op::Select(ValueType::Float), &[121, 886, 874, 875], 1740);
                step(f, Op::SubF, &[866, 875, 877], 1741);
                step(f, Op::SubF, &[876, 877, 878], 1742);
                step(f, Op::MaxF, &[878, 886, 879], 1743);
                step(f, Op::MulF, &[879, 879, 880], 1744);
                step(f, Op::AddF, &[879, 875, 881], 1745);
                step(f, Op::DivF, &[880, 881, 882], 1746);
                step(f, Op::SubF, &[876, 882, 883], 1747);
                step(f, Op::DivF, &[883, 876, 884], 1748);
                step(f, Op::ScaleV, &[464, 884, 465], 1749);
                step(f, Op::AddV, &[460, 465, 466], 1750);
                step(f, Op::ClampSpatially, &[466, 460, 886, 866, 467], 1751);
                step(f, Op::MakeTransform, &[467, 91, 477, 118], 1752);
                step(f, Op::Equals(Elem::Int), &[9, 71, 123], 1753);
                step(f, Op::Select(ValueType::Vec3), &[123, 485, 484, 472], 1754);
                step(f, Op::Select(ValueType::Vec3), &[123, 481, 486, 473], 1755);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 9, 119], 1756);
                step(f, Op::BreakTransform, &[119, 468, 92, 469], 1757);
                step(f, Op::ArrayAt(Elem::Vec3), &[3, 9, 470], 1758);
                step(f, Op::KneeVector, &[92, 0, 470, 140, 141, 471], 1759);
                step(f, Op::TwoBoneIK, &[30, 29, 2, 118, 472, 473, 471, 71, 888, 126, 906, 907, 125, 124, 885], 1760);
                step(f, Op::JumpIfFalse, &[8, 1765], 1761)
            }
            1761 => {
                step(f, Op::GetTransform, &[29, 71, 126, 120], 1762);
                step(f, Op::BreakTransform, &[120, 474, 93, 475], 1763);
                step(f, Op::AddV, &[474, 471, 476], 1764);
                step(f, Op::DrawLine, &[474, 476, 887, 487], 1765);
                1765
            }
            1765 => {
                step(f, Op::Jump, &[1718], 1766)
            }
            1766 => {
                step(f, Op::End, &[], 1767)
            }
            _ => return,
        } };
    }
}
