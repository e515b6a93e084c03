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
    fingerprint: 0x2a003b609a112d0c,
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
                step(f, Op::LengthV, &[37, 151], 113);
                step(f, Op::GreaterF, &[151, 35, 10], 114);
                step(f, Op::Copy(ValueType::Bool), &[10, 2], 115);
                step(f, Op::MakeRelative, &[13, 12, 17], 116);
                step(f, Op::Select(ValueType::Transform), &[10, 124, 17, 18], 117);
                step(f, Op::Copy(ValueType::Transform), &[18, 2], 118);
                step(f, Op::InverseT, &[13, 15], 119);
                step(f, Op::MulT, &[12, 15, 16], 120);
                step(f, Op::Copy(ValueType::Transform), &[16, 1], 121);
                step(f, Op::TransformVector, &[2, 0, 42], 122);
                step(f, Op::InverseT, &[12, 14], 123);
                step(f, Op::DeltaTime, &[150], 124);
                step(f, Op::DivF, &[915, 150, 152], 125);
                step(f, Op::ScaleV, &[37, 152, 38], 126);
                step(f, Op::TransformVector, &[14, 38, 39], 127);
                step(f, Op::BreakVector, &[39, 153, 154, 155], 128);
                step(f, Op::MakeVector, &[153, 154, 913, 40], 129);
                step(f, Op::LengthV, &[40, 156], 130);
                step(f, Op::MulF, &[156, 132, 157], 131);
                step(f, Op::NegF, &[157, 158], 132);
                step(f, Op::ClampF, &[155, 158, 157, 159], 133);
                step(f, Op::MakeVector, &[153, 154, 159, 41], 134);
                step(f, Op::Select(ValueType::Vec3), &[2, 42, 41, 44], 135);
                step(f, Op::VectorLerp, &[42, 44, 36, 913, 45], 136);
                step(f, Op::Copy(ValueType::Vec3), &[45, 0], 137);
                step(f, Op::TransformVector, &[2, 1, 43], 138);
                step(f, Op::TransformVector, &[2, 0, 42], 139);
                step(f, Op::Select(ValueType::Vec3), &[2, 42, 41, 44], 140);
                step(f, Op::VectorLerp, &[43, 44, 37, 913, 46], 141);
                step(f, Op::Copy(ValueType::Vec3), &[46, 1], 142);
                step(f, Op::LengthV, &[44, 166], 143);
                step(f, Op::Copy(ValueType::Float), &[166, 0], 144);
                step(f, Op::BreakVector, &[37, 160, 161, 162], 145);
                step(f, Op::MulF, &[159, 150, 163], 146);
                step(f, Op::SubF, &[162, 163, 164], 147);
                step(f, Op::Select(ValueType::Float), &[10, 913, 164, 165], 148);
                step(f, Op::Copy(ValueType::Float), &[165, 1], 149);
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
                step(f, Op::Copy(ValueType::Float), &[913, 16], 163);
                163
            }
            163 => {
                step(f, Op::Copy(ValueType::Transform), &[12, 0], 164);
                step(f, Op::Copy(ValueType::Bool), &[129, 0], 165);
                step(f, Op::JumpIfFalse, &[8, 171], 166)
            }
            166 => {
                step(f, Op::GetTransform, &[33, 71, 129, 19], 167);
                step(f, Op::BreakTransform, &[19, 47, 9, 48], 168);
                step(f, Op::ScaleV, &[0, 916, 49], 169);
                step(f, Op::AddV, &[47, 49, 50], 170);
                step(f, Op::DrawArrow, &[47, 50, 914, 489], 171);
                171
            }
            171 => {
                step(f, Op::Copy(ValueType::Float), &[913, 167], 172);
                step(f, Op::Copy(ValueType::Float), &[915, 168], 173);
                step(f, Op::Copy(ValueType::Bool), &[130, 12], 174);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[8, 9], 175);
                step(f, Op::Copy(ValueType::Int), &[71, 25], 176);
                step(f, Op::MakeVector, &[913, 913, 58, 55], 177);
                177
            }
            177 => {
                step(f, Op::ForEachNext(Elem::Transform), &[9, 25, 21, 26, 27, 187], 178)
            }
            178 => {
                step(f, Op::BreakTransform, &[21, 51, 10, 52], 179);
                step(f, Op::TransformPoint, &[2, 51, 53], 180);
                step(f, Op::LerpV, &[53, 51, 915, 54], 181);
                step(f, Op::AddV, &[54, 55, 56], 182);
                step(f, Op::SubV, &[54, 55, 57], 183);
                step(f, Op::LineTrace, &[56, 57, 13, 58, 59, 170], 184);
                step(f, Op::JumpIfFalse, &[13, 186], 185)
            }
            185 => {
                step(f, Op::Copy(ValueType::Bool), &[129, 12], 186);
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
                step(f, Op::AddF, &[167, 168, 171], 197);
                step(f, Op::MulF, &[171, 914, 172], 198);
                step(f, Op::Copy(ValueType::Bool), &[130, 18], 199);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[8, 10], 200);
                step(f, Op::Copy(ValueType::Int), &[71, 28], 201);
                step(f, Op::MakeVector, &[913, 913, 58, 64], 202);
                202
            }
            202 => {
                step(f, Op::ForEachNext(Elem::Transform), &[10, 28, 22, 29, 30, 212], 203)
            }
            203 => {
                step(f, Op::BreakTransform, &[22, 60, 11, 61], 204);
                step(f, Op::TransformPoint, &[2, 60, 62], 205);
                step(f, Op::LerpV, &[62, 60, 172, 63], 206);
                step(f, Op::AddV, &[63, 64, 65], 207);
                step(f, Op::SubV, &[63, 64, 66], 208);
                step(f, Op::LineTrace, &[65, 66, 19, 67, 68, 174], 209);
                step(f, Op::JumpIfFalse, &[19, 211], 210)
            }
            210 => {
                step(f, Op::Copy(ValueType::Bool), &[129, 18], 211);
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
                step(f, Op::Copy(ValueType::Float), &[172, 167], 216);
                step(f, Op::Jump, &[218], 217)
            }
            217 => {
                step(f, Op::Copy(ValueType::Float), &[172, 168], 218);
                218
            }
            218 => {
                step(f, Op::Jump, &[195], 219)
            }
            219 => {
                step(f, Op::Select(ValueType::Float), &[5, 917, 915, 180], 220);
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 221);
                step(f, Op::AddF, &[167, 168, 171], 222);
                step(f, Op::MulF, &[171, 914, 175], 223);
                step(f, Op::Select(ValueType::Float), &[16, 175, 914, 176], 224);
                step(f, Op::Select(ValueType::Float), &[15, 176, 913, 182], 225);
                step(f, Op::MulF, &[180, 182, 184], 226);
                step(f, Op::DeltaTime, &[178], 227);
                step(f, Op::DivF, &[178, 136, 179], 228);
                step(f, Op::MulF, &[184, 179, 185], 229);
                step(f, Op::AddF, &[20, 185, 186], 230);
                step(f, Op::ClampF, &[186, 913, 915, 187], 231);
                step(f, Op::Select(ValueType::Float), &[14, 917, 915, 181], 232);
                step(f, Op::SubF, &[915, 176, 177], 233);
                step(f, Op::Select(ValueType::Float), &[15, 177, 915, 183], 234);
                step(f, Op::MulF, &[181, 183, 188], 235);
                step(f, Op::MulF, &[188, 179, 189], 236);
                step(f, Op::AddF, &[187, 189, 190], 237);
                step(f, Op::ClampF, &[190, 913, 915, 191], 238);
                step(f, Op::SmoothStepF, &[191, 913, 915, 192], 239);
                step(f, Op::AddF, &[21, 192, 193], 240);
                step(f, Op::MulF, &[193, 914, 194], 241);
                step(f, Op::SubF, &[915, 194, 195], 242);
                step(f, Op::MulF, &[195, 195, 196], 243);
                step(f, Op::SubF, &[915, 196, 197], 244);
                step(f, Op::Copy(ValueType::Float), &[197, 22], 245);
                step(f, Op::Copy(ValueType::Float), &[192, 21], 246);
                step(f, Op::Copy(ValueType::Float), &[191, 20], 247);
                step(f, Op::GreaterF, &[21, 913, 21], 248);
                step(f, Op::TransformVector, &[2, 3, 69], 249);
                step(f, Op::Select(ValueType::Vec3), &[21, 69, 0, 70], 250);
                step(f, Op::Copy(ValueType::Vec3), &[70, 3], 251);
                step(f, Op::LerpV, &[0, 3, 21, 71], 252);
                step(f, Op::Select(ValueType::Vec3), &[21, 71, 0, 72], 253);
                step(f, Op::Copy(ValueType::Vec3), &[72, 2], 254);
                step(f, Op::Copy(ValueType::Bool), &[14, 5], 255);
                step(f, Op::Copy(ValueType::Bool), &[11, 6], 256);
                step(f, Op::Copy(ValueType::Bool), &[130, 7], 257);
                step(f, Op::SubF, &[915, 22, 198], 258);
                step(f, Op::MulF, &[1, 198, 199], 259);
                step(f, Op::AddF, &[2, 199, 200], 260);
                step(f, Op::Copy(ValueType::Float), &[4, 201], 261);
                step(f, Op::Copy(ValueType::Float), &[5, 202], 262);
                step(f, Op::Copy(ValueType::Float), &[2, 204], 263);
                step(f, Op::Copy(ValueType::Float), &[133, 205], 264);
                step(f, Op::Copy(ValueType::Float), &[52, 206], 265);
                step(f, Op::SubF, &[200, 204, 211], 266);
                step(f, Op::DeltaTime, &[209], 267);
                step(f, Op::DivF, &[211, 209, 212], 268);
                step(f, Op::MulF, &[212, 206, 213], 269);
                step(f, Op::AddF, &[200, 213, 215], 270);
                step(f, Op::MulF, &[212, 918, 216], 271);
                step(f, Op::DivF, &[919, 205, 210], 272);
                step(f, Op::DivF, &[216, 210, 217], 273);
                step(f, Op::SubF, &[215, 217, 231], 274);
                step(f, Op::AddF, &[204, 213, 214], 275);
                step(f, Op::SubF, &[201, 214, 218], 276);
                step(f, Op::AddF, &[218, 217, 219], 277);
                step(f, Op::SubF, &[202, 212, 220], 278);
                step(f, Op::MulF, &[210, 219, 221], 279);
                step(f, Op::AddF, &[220, 221, 222], 280);
                step(f, Op::MulF, &[222, 209, 225], 281);
                step(f, Op::AddF, &[219, 225, 226], 282);
                step(f, Op::FloatLerp, &[913, 915, 210, 223], 283);
                step(f, Op::SubF, &[915, 223, 224], 284);
                step(f, Op::MulF, &[226, 224, 227], 285);
                step(f, Op::AddF, &[231, 227, 232], 286);
                step(f, Op::Copy(ValueType::Float), &[232, 207], 287);
                step(f, Op::MulF, &[210, 225, 228], 288);
                step(f, Op::SubF, &[220, 228, 229], 289);
                step(f, Op::MulF, &[229, 224, 230], 290);
                step(f, Op::AddF, &[212, 230, 233], 291);
                step(f, Op::Copy(ValueType::Float), &[233, 208], 292);
                step(f, Op::SubF, &[200, 207, 234], 293);
                step(f, Op::Copy(ValueType::Float), &[234, 3], 294);
                step(f, Op::Copy(ValueType::Float), &[207, 4], 295);
                step(f, Op::Copy(ValueType::Float), &[4, 201], 296);
                step(f, Op::Copy(ValueType::Float), &[5, 202], 297);
                step(f, Op::Copy(ValueType::Float), &[2, 204], 298);
                step(f, Op::Copy(ValueType::Float), &[133, 205], 299);
                step(f, Op::Copy(ValueType::Float), &[52, 206], 300);
                step(f, Op::SubF, &[200, 204, 211], 301);
                step(f, Op::DeltaTime, &[209], 302);
                step(f, Op::DivF, &[211, 209, 212], 303);
                step(f, Op::MulF, &[212, 206, 213], 304);
                step(f, Op::AddF, &[200, 213, 215], 305);
                step(f, Op::MulF, &[212, 918, 216], 306);
                step(f, Op::DivF, &[919, 205, 210], 307);
                step(f, Op::DivF, &[216, 210, 217], 308);
                step(f, Op::SubF, &[215, 217, 231], 309);
                step(f, Op::AddF, &[204, 213, 214], 310);
                step(f, Op::SubF, &[201, 214, 218], 311);
                step(f, Op::AddF, &[218, 217, 219], 312);
                step(f, Op::SubF, &[202, 212, 220], 313);
                step(f, Op::MulF, &[210, 219, 221], 314);
                step(f, Op::AddF, &[220, 221, 222], 315);
                step(f, Op::MulF, &[222, 209, 225], 316);
                step(f, Op::AddF, &[219, 225, 226], 317);
                step(f, Op::FloatLerp, &[913, 915, 210, 223], 318);
                step(f, Op::SubF, &[915, 223, 224], 319);
                step(f, Op::MulF, &[226, 224, 227], 320);
                step(f, Op::AddF, &[231, 227, 232], 321);
                step(f, Op::Copy(ValueType::Float), &[232, 207], 322);
                step(f, Op::MulF, &[210, 225, 228], 323);
                step(f, Op::SubF, &[220, 228, 229], 324);
                step(f, Op::MulF, &[229, 224, 230], 325);
                step(f, Op::AddF, &[212, 230, 233], 326);
                step(f, Op::Copy(ValueType::Float), &[233, 208], 327);
                step(f, Op::Copy(ValueType::Float), &[208, 5], 328);
                step(f, Op::Copy(ValueType::Float), &[200, 2], 329);
                step(f, Op::LengthV, &[4, 236], 330);
                step(f, Op::GreaterF, &[236, 29, 22], 331);
                step(f, Op::LengthV, &[2, 237], 332);
                step(f, Op::GreaterF, &[237, 29, 23], 333);
                step(f, Op::And, &[22, 23, 25], 334);
                step(f, Op::Select(ValueType::Vec3), &[22, 4, 488, 73], 335);
                step(f, Op::MovementAngleOffset, &[73, 14, 913, 920, 920, 921, 40, 922, 238], 336);
                step(f, Op::Copy(ValueType::Float), &[14, 241], 337);
                step(f, Op::SubF, &[238, 241, 243], 338);
                step(f, Op::AddF, &[243, 923, 244], 339);
                step(f, Op::DivF, &[244, 924, 245], 340);
                step(f, Op::FractF, &[245, 246], 341);
                step(f, Op::MulF, &[246, 924, 247], 342);
                step(f, Op::SubF, &[247, 923, 248], 343);
                step(f, Op::Copy(ValueType::Float), &[248, 242], 344);
                step(f, Op::AbsF, &[242, 267], 345);
                step(f, Op::Select(ValueType::Vec3), &[23, 2, 488, 74], 346);
                step(f, Op::MovementAngleOffset, &[74, 14, 913, 920, 920, 921, 40, 922, 239], 347);
                step(f, Op::Copy(ValueType::Float), &[14, 250], 348);
                step(f, Op::SubF, &[239, 250, 252], 349);
                step(f, Op::AddF, &[252, 923, 253], 350);
                step(f, Op::DivF, &[253, 924, 254], 351);
                step(f, Op::FractF, &[254, 255], 352);
                step(f, Op::MulF, &[255, 924, 256], 353);
                step(f, Op::SubF, &[256, 923, 257], 354);
                step(f, Op::Copy(ValueType::Float), &[257, 251], 355);
                step(f, Op::AbsF, &[251, 268], 356);
                step(f, Op::MaxF, &[267, 268, 270], 357);
                step(f, Op::SubF, &[239, 238, 261], 358);
                step(f, Op::AddF, &[261, 923, 262], 359);
                step(f, Op::DivF, &[262, 924, 263], 360);
                step(f, Op::FractF, &[263, 264], 361);
                step(f, Op::MulF, &[264, 924, 265], 362);
                step(f, Op::SubF, &[265, 923, 266], 363);
                step(f, Op::Copy(ValueType::Float), &[266, 260], 364);
                step(f, Op::AbsF, &[260, 269], 365);
                step(f, Op::MaxF, &[270, 269, 271], 366);
                step(f, Op::LessF, &[271, 925, 24], 367);
                step(f, Op::And, &[25, 24, 26], 368);
                step(f, Op::Not, &[22, 27], 369);
                step(f, Op::Not, &[23, 28], 370);
                step(f, Op::And, &[27, 28, 29], 371);
                step(f, Op::Or, &[26, 29, 30], 372);
                step(f, Op::JumpIfFalse, &[30, 394], 373)
            }
            373 => {
                step(f, Op::DeltaTime, &[235], 374);
                step(f, Op::MulF, &[38, 235, 275], 375);
                step(f, Op::GreaterF, &[275, 913, 31], 376);
                step(f, Op::DivF, &[52, 235, 272], 377);
                step(f, Op::FloatLerp, &[913, 915, 38, 273], 378);
                step(f, Op::SubF, &[915, 273, 274], 379);
                step(f, Op::DivF, &[274, 273, 276], 380);
                step(f, Op::DivF, &[915, 275, 277], 381);
                step(f, Op::SubF, &[276, 277, 278], 382);
                step(f, Op::AddF, &[272, 278, 279], 383);
                step(f, Op::Select(ValueType::Float), &[31, 279, 913, 280], 384);
                step(f, Op::MulF, &[260, 280, 281], 385);
                step(f, Op::AddF, &[239, 281, 282], 386);
                step(f, Op::SinF, &[282, 283], 387);
                step(f, Op::NegF, &[283, 284], 388);
                step(f, Op::CosF, &[282, 285], 389);
                step(f, Op::MakeVector, &[284, 285, 913, 75], 390);
                step(f, Op::Select(ValueType::Vec3), &[23, 75, 488, 76], 391);
                step(f, Op::MovementAngleOffset, &[76, 14, 913, 38, 39, 921, 923, 922, 286], 392);
                step(f, Op::Copy(ValueType::Float), &[286, 14], 393);
                step(f, Op::Jump, &[450], 394)
            }
            394 => {
                step(f, Op::DeltaTime, &[235], 395);
                step(f, Op::DivF, &[235, 42, 287], 396);
                step(f, Op::AddF, &[287, 914, 288], 397);
                step(f, Op::FloorF, &[288, 289], 398);
                step(f, Op::MaxF, &[289, 915, 290], 399);
                step(f, Op::ToInt, &[290, 36], 400);
                step(f, Op::Copy(ValueType::Int), &[36, 35], 401);
                step(f, Op::Copy(ValueType::Int), &[71, 31], 402);
                step(f, Op::MulF, &[42, 914, 294], 403);
                step(f, Op::SubF, &[52, 294, 295], 404);
                step(f, Op::DivF, &[295, 235, 296], 405);
                step(f, Op::FloatLerp, &[913, 915, 36, 298], 406);
                step(f, Op::GreaterF, &[298, 913, 32], 407);
                step(f, Op::DivF, &[38, 290, 308], 408);
                step(f, Op::DivF, &[39, 290, 309], 409);
                step(f, Op::SubF, &[921, 41, 321], 410);
                step(f, Op::GreaterF, &[41, 913, 35], 411);
                411
            }
            411 => {
                step(f, Op::ForNext, &[31, 35, 33, 450], 412)
            }
            412 => {
                step(f, Op::ToFloat, &[33, 291], 413);
                step(f, Op::AddF, &[291, 915, 292], 414);
                step(f, Op::DivF, &[292, 290, 293], 415);
                step(f, Op::AddF, &[293, 296, 297], 416);
                step(f, Op::MulF, &[36, 297, 299], 417);
                step(f, Op::FloatLerp, &[913, 915, 299, 300], 418);
                step(f, Op::DivF, &[300, 298, 301], 419);
                step(f, Op::Select(ValueType::Float), &[32, 301, 297, 302], 420);
                step(f, Op::LerpV, &[4, 2, 302, 77], 421);
                step(f, Op::LengthV, &[77, 303], 422);
                step(f, Op::GreaterF, &[303, 29, 33], 423);
                step(f, Op::Select(ValueType::Vec3), &[33, 77, 488, 78], 424);
                step(f, Op::MulF, &[235, 297, 304], 425);
                step(f, Op::MulF, &[8, 304, 305], 426);
                step(f, Op::AddF, &[12, 305, 306], 427);
                step(f, Op::FractF, &[306, 307], 428);
                step(f, Op::MulF, &[307, 918, 325], 429);
                step(f, Op::FractF, &[325, 326], 430);
                step(f, Op::LessF, &[326, 922, 36], 431);
                step(f, Op::MovementAngleOffset, &[78, 14, 913, 920, 920, 921, 40, 922, 310], 432);
                step(f, Op::Copy(ValueType::Float), &[14, 312], 433);
                step(f, Op::SubF, &[310, 312, 314], 434);
                step(f, Op::AddF, &[314, 923, 315], 435);
                step(f, Op::DivF, &[315, 924, 316], 436);
                step(f, Op::FractF, &[316, 317], 437);
                step(f, Op::MulF, &[317, 924, 318], 438);
                step(f, Op::SubF, &[318, 923, 319], 439);
                step(f, Op::Copy(ValueType::Float), &[319, 313], 440);
                step(f, Op::AbsF, &[313, 320], 441);
                step(f, Op::SmoothStepF, &[320, 321, 921, 322], 442);
                step(f, Op::GreaterF, &[320, 921, 34], 443);
                step(f, Op::Select(ValueType::Float), &[34, 915, 913, 323], 444);
                step(f, Op::Select(ValueType::Float), &[35, 322, 323, 324], 445);
                step(f, Op::Select(ValueType::Float), &[36, 913, 324, 327], 446);
                step(f, Op::LerpF, &[308, 309, 327, 328], 447);
                step(f, Op::MovementAngleOffset, &[78, 14, 307, 328, 328, 921, 40, 922, 329], 448);
                step(f, Op::Copy(ValueType::Float), &[329, 14], 449);
                step(f, Op::Jump, &[411], 450)
            }
            450 => {
                step(f, Op::QuatFromAxisAngle, &[490, 14, 12], 451);
                step(f, Op::Copy(ValueType::Quat), &[12, 0], 452);
                step(f, Op::SinF, &[14, 330], 453);
                step(f, Op::AbsF, &[330, 331], 454);
                step(f, Op::RemapF, &[331, 43, 44, 913, 915, 129, 332], 455);
                step(f, Op::BreakVector, &[74, 333, 334, 335], 456);
                step(f, Op::AbsF, &[333, 336], 457);
                step(f, Op::DivF, &[336, 237, 337], 458);
                step(f, Op::RemapF, &[337, 43, 44, 913, 915, 129, 338], 459);
                step(f, Op::TransformVector, &[2, 491, 79], 460);
                step(f, Op::DistanceV, &[79, 491, 339], 461);
                step(f, Op::DivF, &[339, 235, 340], 462);
                step(f, Op::RemapF, &[340, 48, 49, 915, 913, 129, 341], 463);
                step(f, Op::MulF, &[338, 341, 342], 464);
                step(f, Op::MaxF, &[332, 342, 343], 465);
                step(f, Op::Copy(ValueType::Float), &[343, 15], 466);
                step(f, Op::Copy(ValueType::Vec3), &[2, 4], 467);
                step(f, Op::Copy(ValueType::Bool), &[129, 39], 468);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 2], 469);
                step(f, Op::Copy(ValueType::Int), &[71, 40], 470);
                470
            }
            470 => {
                step(f, Op::ForEachNext(Elem::Bool), &[2, 40, 40, 41, 42, 475], 471)
            }
            471 => {
                step(f, Op::Not, &[40, 41], 472);
                step(f, Op::JumpIfFalse, &[41, 474], 473)
            }
            473 => {
                step(f, Op::Copy(ValueType::Bool), &[130, 39], 474);
                474
            }
            474 => {
                step(f, Op::Jump, &[470], 475)
            }
            475 => {
                step(f, Op::Copy(ValueType::Bool), &[39, 38], 476);
                step(f, Op::Copy(ValueType::Bool), &[129, 43], 477);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 478);
                step(f, Op::Copy(ValueType::Int), &[71, 43], 479);
                479
            }
            479 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 43, 15, 44, 45, 493], 480)
            }
            480 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 44, 23], 481);
                step(f, Op::BreakTransform, &[23, 80, 13, 81], 482);
                step(f, Op::BreakVector, &[80, 352, 353, 354], 483);
                step(f, Op::MakeVector, &[352, 353, 913, 84], 484);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 44, 24], 485);
                step(f, Op::BreakTransform, &[24, 82, 14, 83], 486);
                step(f, Op::BreakVector, &[82, 355, 356, 357], 487);
                step(f, Op::MakeVector, &[355, 356, 913, 85], 488);
                step(f, Op::DistanceV, &[84, 85, 358], 489);
                step(f, Op::GreaterF, &[358, 31, 44], 490);
                step(f, Op::JumpIfFalse, &[44, 492], 491)
            }
            491 => {
                step(f, Op::Copy(ValueType::Bool), &[130, 43], 492);
                492
            }
            492 => {
                step(f, Op::Jump, &[479], 493)
            }
            493 => {
                step(f, Op::Copy(ValueType::Bool), &[43, 42], 494);
                step(f, Op::And, &[38, 42, 45], 495);
                step(f, Op::LengthV, &[2, 344], 496);
                step(f, Op::GreaterF, &[344, 29, 37], 497);
                step(f, Op::GreaterF, &[0, 29, 46], 498);
                step(f, Op::Or, &[37, 46, 47], 499);
                step(f, Op::Not, &[47, 48], 500);
                step(f, Op::And, &[45, 48, 53], 501);
                step(f, Op::DeltaTime, &[383], 502);
                step(f, Op::MulF, &[383, 34, 384], 503);
                step(f, Op::AddF, &[12, 384, 385], 504);
                step(f, Op::GreaterF, &[12, 914, 54], 505);
                step(f, Op::AddF, &[33, 914, 381], 506);
                step(f, Op::Select(ValueType::Float), &[54, 381, 33, 382], 507);
                step(f, Op::MinF, &[385, 382, 386], 508);
                step(f, Op::NotEquals(Elem::Bool), &[48, 4, 49], 509);
                step(f, Op::Not, &[45, 50], 510);
                step(f, Op::And, &[49, 50, 51], 511);
                step(f, Op::SubF, &[13, 29, 367], 512);
                step(f, Op::SubF, &[13, 344, 368], 513);
                step(f, Op::DivF, &[367, 368, 369], 514);
                step(f, Op::ClampF, &[369, 913, 915, 370], 515);
                step(f, Op::MulF, &[8, 370, 372], 516);
                step(f, Op::RemapF, &[344, 29, 30, 913, 915, 129, 359], 517);
                step(f, Op::MaxF, &[359, 9, 360], 518);
                step(f, Op::Select(ValueType::Float), &[38, 915, 360, 361], 519);
                step(f, Op::Select(ValueType::Float), &[48, 32, 361, 362], 520);
                step(f, Op::Select(ValueType::Float), &[45, 359, 362, 363], 521);
                step(f, Op::SubF, &[915, 21, 364], 522);
                step(f, Op::MulF, &[363, 364, 365], 523);
                step(f, Op::LerpF, &[23, 46, 15, 347], 524);
                step(f, Op::RemapF, &[344, 26, 27, 24, 25, 129, 345], 525);
                step(f, Op::LerpF, &[345, 45, 15, 346], 526);
                step(f, Op::MaxF, &[344, 28, 348], 527);
                step(f, Op::DivF, &[346, 348, 349], 528);
                step(f, Op::AddF, &[347, 349, 350], 529);
                step(f, Op::DivF, &[365, 350, 366], 530);
                step(f, Op::SubF, &[915, 370, 371], 531);
                step(f, Op::MulF, &[366, 371, 373], 532);
                step(f, Op::AddF, &[372, 373, 374], 533);
                step(f, Op::MulF, &[374, 918, 375], 534);
                step(f, Op::AddF, &[8, 366, 376], 535);
                step(f, Op::Select(ValueType::Float), &[51, 375, 376, 377], 536);
                step(f, Op::DivF, &[918, 377, 378], 537);
                step(f, Op::GreaterF, &[377, 913, 52], 538);
                step(f, Op::CycleStep, &[12, 378, 913, 52, 379, 380], 539);
                step(f, Op::Select(ValueType::Float), &[53, 386, 379, 387], 540);
                step(f, Op::Copy(ValueType::Float), &[387, 12], 541);
                step(f, Op::Copy(ValueType::Float), &[366, 8], 542);
                step(f, Op::Copy(ValueType::Bool), &[37, 3], 543);
                step(f, Op::Copy(ValueType::Float), &[349, 6], 544);
                step(f, Op::Copy(ValueType::Float), &[350, 7], 545);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 546);
                step(f, Op::Copy(ValueType::Int), &[71, 37], 547);
                step(f, Op::DivF, &[347, 350, 351], 548);
                step(f, Op::MulF, &[11, 370, 393], 549);
                step(f, Op::MulF, &[383, 914, 399], 550);
                step(f, Op::SubF, &[351, 10, 404], 551);
                step(f, Op::MaxF, &[404, 913, 405], 552);
                step(f, Op::DivF, &[405, 351, 406], 553);
                step(f, Op::SubF, &[915, 15, 408], 554);
                step(f, Op::DivF, &[52, 383, 413], 555);
                step(f, Op::SubF, &[914, 413, 414], 556);
                step(f, Op::MulF, &[406, 408, 415], 557);
                step(f, Op::MulF, &[415, 364, 416], 558);
                step(f, Op::MulF, &[416, 130, 417], 559);
                step(f, Op::MulF, &[417, 414, 418], 560);
                step(f, Op::SubF, &[915, 418, 419], 561);
                561
            }
            561 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 37, 14, 38, 39, 605], 562)
            }
            562 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 38, 401], 563);
                step(f, Op::ToFloat, &[38, 388], 564);
                step(f, Op::MulF, &[388, 914, 389], 565);
                step(f, Op::AddF, &[12, 389, 390], 566);
                step(f, Op::FractF, &[390, 391], 567);
                step(f, Op::SubF, &[401, 391, 403], 568);
                step(f, Op::GreaterF, &[403, 914, 55], 569);
                step(f, Op::ArrayAt(Elem::Float), &[2, 38, 402], 570);
                step(f, Op::Select(ValueType::Float), &[55, 913, 402, 430], 571);
                step(f, Op::ArraySetAt(Elem::Float), &[3, 38, 430], 572);
                step(f, Op::SubF, &[915, 401, 424], 573);
                step(f, Op::AddF, &[391, 424, 425], 574);
                step(f, Op::DivF, &[391, 425, 426], 575);
                step(f, Op::MaxF, &[359, 9, 360], 576);
                step(f, Op::Select(ValueType::Float), &[38, 915, 360, 361], 577);
                step(f, Op::Select(ValueType::Float), &[48, 32, 361, 362], 578);
                step(f, Op::Select(ValueType::Float), &[45, 359, 362, 363], 579);
                step(f, Op::MulF, &[363, 364, 365], 580);
                step(f, Op::DivF, &[365, 347, 392], 581);
                step(f, Op::MulF, &[392, 371, 394], 582);
                step(f, Op::AddF, &[393, 394, 395], 583);
                step(f, Op::MulF, &[395, 918, 396], 584);
                step(f, Op::AddF, &[11, 392, 397], 585);
                step(f, Op::Select(ValueType::Float), &[51, 396, 397, 398], 586);
                step(f, Op::MulF, &[398, 399, 400], 587);
                step(f, Op::MulF, &[426, 400, 427], 588);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 38, 56], 589);
                step(f, Op::MulF, &[400, 419, 420], 590);
                step(f, Op::Select(ValueType::Float), &[56, 400, 420, 421], 591);
                step(f, Op::MulF, &[406, 402, 407], 592);
                step(f, Op::MulF, &[407, 408, 409], 593);
                step(f, Op::MulF, &[409, 364, 410], 594);
                step(f, Op::MulF, &[410, 130, 411], 595);
                step(f, Op::Select(ValueType::Float), &[56, 913, 411, 412], 596);
                step(f, Op::SubF, &[421, 412, 422], 597);
                step(f, Op::AddF, &[402, 422, 423], 598);
                step(f, Op::Select(ValueType::Float), &[55, 427, 423, 428], 599);
                step(f, Op::MinF, &[428, 918, 429], 600);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 38, 429], 601);
                step(f, Op::JumpIfFalse, &[55, 603], 602)
            }
            602 => {
                step(f, Op::Copy(ValueType::Float), &[363, 9], 603);
                603
            }
            603 => {
                step(f, Op::ArraySetAt(Elem::Float), &[0, 38, 391], 604);
                step(f, Op::Jump, &[561], 605)
            }
            605 => {
                step(f, Op::Copy(ValueType::Float), &[351, 10], 606);
                step(f, Op::Copy(ValueType::Bool), &[48, 4], 607);
                step(f, Op::Copy(ValueType::Float), &[344, 13], 608);
                step(f, Op::MaxF, &[359, 9, 360], 609);
                step(f, Op::Select(ValueType::Float), &[38, 915, 360, 361], 610);
                step(f, Op::Select(ValueType::Float), &[48, 32, 361, 362], 611);
                step(f, Op::Select(ValueType::Float), &[45, 359, 362, 363], 612);
                step(f, Op::MulF, &[363, 364, 365], 613);
                step(f, Op::DivF, &[365, 347, 392], 614);
                step(f, Op::Copy(ValueType::Float), &[392, 11], 615);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 616);
                step(f, Op::Copy(ValueType::Int), &[71, 2], 617);
                617
            }
            617 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 2, 0, 3, 4, 1524], 618)
            }
            618 => {
                step(f, Op::Copy(ValueType::Bool), &[129, 57], 619);
                step(f, Op::Copy(ValueType::Bool), &[130, 58], 620);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 3, 61], 621);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 431], 622);
                step(f, Op::GreaterEqualF, &[431, 915, 62], 623);
                step(f, Op::And, &[61, 62, 63], 624);
                step(f, Op::Or, &[1, 2, 65], 625);
                step(f, Op::GreaterF, &[21, 913, 64], 626);
                step(f, Op::Or, &[65, 64, 66], 627);
                step(f, Op::Not, &[66, 67], 628);
                step(f, Op::And, &[63, 67, 68], 629);
                step(f, Op::JumpIfFalse, &[68, 739], 630)
            }
            630 => {
                step(f, Op::ArrayAt(Elem::Transform), &[2, 3, 28], 631);
                step(f, Op::BreakTransform, &[28, 104, 23, 105], 632);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 3, 121], 633);
                step(f, Op::SubV, &[104, 121, 142], 634);
                step(f, Op::TransformPoint, &[2, 142, 143], 635);
                step(f, Op::GetTransform, &[34, 71, 129, 25], 636);
                step(f, Op::BreakTransform, &[25, 88, 15, 89], 637);
                step(f, Op::BreakVector, &[88, 442, 443, 444], 638);
                step(f, Op::SubF, &[915, 15, 440], 639);
                step(f, Op::MulF, &[14, 440, 441], 640);
                step(f, Op::QuatFromAxisAngle, &[490, 441, 17], 641);
                step(f, Op::GetTransform, &[0, 71, 129, 26], 642);
                step(f, Op::BreakTransform, &[26, 90, 16, 91], 643);
                step(f, Op::SubV, &[90, 88, 92], 644);
                step(f, Op::BreakVector, &[92, 437, 438, 439], 645);
                step(f, Op::MakeVector, &[437, 438, 913, 93], 646);
                step(f, Op::RotateVector, &[17, 93, 94], 647);
                step(f, Op::BreakVector, &[94, 445, 446, 447], 648);
                step(f, Op::MulF, &[47, 15, 448], 649);
                step(f, Op::Equals(Elem::Int), &[3, 71, 59], 650);
                step(f, Op::Select(ValueType::Float), &[59, 915, 917, 457], 651);
                step(f, Op::MulF, &[448, 457, 449], 652);
                step(f, Op::AddF, &[445, 449, 450], 653);
                step(f, Op::AddF, &[442, 450, 451], 654);
                step(f, Op::AddF, &[443, 446, 452], 655);
                step(f, Op::BreakVector, &[90, 453, 454, 455], 656);
                step(f, Op::SubF, &[455, 53, 456], 657);
                step(f, Op::MakeVector, &[451, 452, 456, 95], 658);
                step(f, Op::MulF, &[6, 914, 436], 659);
                step(f, Op::ScaleV, &[2, 436, 87], 660);
                step(f, Op::AddV, &[95, 87, 98], 661);
                step(f, Op::DistanceV, &[143, 98, 484], 662);
                step(f, Op::TransformVector, &[2, 492, 144], 663);
                step(f, Op::DistanceV, &[144, 492, 485], 664);
                step(f, Op::MaxF, &[484, 485, 486], 665);
                step(f, Op::LessEqualF, &[486, 60, 77], 666);
                step(f, Op::LengthV, &[2, 487], 667);
                step(f, Op::LengthV, &[4, 488], 668);
                step(f, Op::MaxF, &[487, 488, 489], 669);
                step(f, Op::LessEqualF, &[489, 29, 78], 670);
                step(f, Op::And, &[77, 78, 79], 671);
                step(f, Op::ArrayAt(Elem::Bool), &[1, 3, 69], 672);
                step(f, Op::And, &[79, 69, 80], 673);
                step(f, Op::JumpIfFalse, &[80, 676], 674)
            }
            674 => {
                step(f, Op::Copy(ValueType::Bool), &[129, 58], 675);
                step(f, Op::Jump, &[705], 676)
            }
            676 => {
                step(f, Op::MakeVector, &[913, 913, 58, 123], 677);
                step(f, Op::AddV, &[98, 123, 124], 678);
                step(f, Op::SubV, &[98, 123, 125], 679);
                step(f, Op::SphereTrace, &[124, 125, 57, 70, 126, 127, 476], 680);
                step(f, Op::SubV, &[126, 98, 140], 681);
                step(f, Op::DistanceV, &[140, 121, 480], 682);
                step(f, Op::RotateVector, &[0, 491, 99], 683);
                step(f, Op::ScaleV, &[99, 62, 128], 684);
                step(f, Op::AddV, &[124, 128, 129], 685);
                step(f, Op::AddV, &[125, 128, 130], 686);
                step(f, Op::SphereTrace, &[129, 130, 57, 71, 131, 132, 477], 687);
                step(f, Op::SubV, &[131, 98, 141], 688);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 3, 122], 689);
                step(f, Op::DistanceV, &[141, 122, 481], 690);
                step(f, Op::MaxF, &[480, 481, 482], 691);
                step(f, Op::ScaleV, &[99, 59, 133], 692);
                step(f, Op::AddV, &[129, 133, 134], 693);
                step(f, Op::AddV, &[130, 133, 135], 694);
                step(f, Op::SphereTrace, &[134, 135, 57, 72, 136, 137, 478], 695);
                step(f, Op::SubV, &[136, 98, 138], 696);
                step(f, Op::ArrayAt(Elem::Vec3), &[2, 3, 139], 697);
                step(f, Op::DistanceV, &[138, 139, 479], 698);
                step(f, Op::MaxF, &[482, 479, 483], 699);
                step(f, Op::LessEqualF, &[483, 60, 73], 700);
                step(f, Op::And, &[70, 71, 74], 701);
                step(f, Op::And, &[74, 69, 75], 702);
                step(f, Op::And, &[73, 75, 76], 703);
                step(f, Op::JumpIfFalse, &[76, 705], 704)
            }
            704 => {
                step(f, Op::Copy(ValueType::Bool), &[129, 58], 705);
                705
            }
            705 => {
                step(f, Op::JumpIfFalse, &[58, 739], 706)
            }
            706 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 27], 707);
                step(f, Op::BreakTransform, &[27, 101, 21, 102], 708);
                step(f, Op::AddV, &[98, 121, 145], 709);
                step(f, Op::Copy(ValueType::Float), &[50, 490], 710);
                step(f, Op::Copy(ValueType::Float), &[52, 491], 711);
                step(f, Op::SubV, &[145, 104, 150], 712);
                step(f, Op::DeltaTime, &[492], 713);
                step(f, Op::DivF, &[491, 492, 493], 714);
                step(f, Op::ScaleV, &[150, 493, 151], 715);
                step(f, Op::AddV, &[145, 151, 152], 716);
                step(f, Op::AddV, &[104, 151, 153], 717);
                step(f, Op::SubV, &[101, 153, 154], 718);
                step(f, Op::FloatLerp, &[913, 915, 490, 494], 719);
                step(f, Op::SubF, &[915, 494, 495], 720);
                step(f, Op::ScaleV, &[154, 495, 155], 721);
                step(f, Op::AddV, &[152, 155, 157], 722);
                step(f, Op::MulF, &[490, 492, 496], 723);
                step(f, Op::GreaterF, &[496, 913, 81], 724);
                step(f, Op::DivF, &[494, 496, 497], 725);
                step(f, Op::Select(ValueType::Float), &[81, 497, 915, 498], 726);
                step(f, Op::ScaleV, &[150, 498, 156], 727);
                step(f, Op::SubV, &[157, 156, 158], 728);
                step(f, Op::Copy(ValueType::Vec3), &[158, 149], 729);
                step(f, Op::BreakVector, &[149, 499, 500, 501], 730);
                step(f, Op::ClampF, &[501, 63, 64, 502], 731);
                step(f, Op::MakeVector, &[499, 500, 502, 159], 732);
                step(f, Op::MakeTransform, &[159, 21, 487, 31], 733);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 3, 31], 734);
                step(f, Op::MakeTransform, &[145, 98, 487, 32], 735);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 3, 32], 736);
                step(f, Op::JumpIfFalse, &[69, 738], 737)
            }
            737 => {
                step(f, Op::Copy(ValueType::Bool), &[129, 7], 738);
                738
            }
            738 => {
                step(f, Op::Copy(ValueType::Bool), &[130, 57], 739);
                739
            }
            739 => {
                step(f, Op::JumpIfFalse, &[57, 944], 740)
            }
            740 => {
                step(f, Op::GetTransform, &[34, 71, 129, 25], 741);
                step(f, Op::BreakTransform, &[25, 88, 15, 89], 742);
                step(f, Op::BreakVector, &[88, 442, 443, 444], 743);
                step(f, Op::SubF, &[915, 15, 440], 744);
                step(f, Op::MulF, &[14, 440, 441], 745);
                step(f, Op::QuatFromAxisAngle, &[490, 441, 17], 746);
                step(f, Op::GetTransform, &[0, 71, 129, 26], 747);
                step(f, Op::BreakTransform, &[26, 90, 16, 91], 748);
                step(f, Op::SubV, &[90, 88, 92], 749);
                step(f, Op::BreakVector, &[92, 437, 438, 439], 750);
                step(f, Op::MakeVector, &[437, 438, 913, 93], 751);
                step(f, Op::RotateVector, &[17, 93, 94], 752);
                step(f, Op::BreakVector, &[94, 445, 446, 447], 753);
                step(f, Op::MulF, &[47, 15, 448], 754);
                step(f, Op::Equals(Elem::Int), &[3, 71, 59], 755);
                step(f, Op::Select(ValueType::Float), &[59, 915, 917, 457], 756);
                step(f, Op::MulF, &[448, 457, 449], 757);
                step(f, Op::AddF, &[445, 449, 450], 758);
                step(f, Op::AddF, &[442, 450, 451], 759);
                step(f, Op::AddF, &[443, 446, 452], 760);
                step(f, Op::BreakVector, &[90, 453, 454, 455], 761);
                step(f, Op::SubF, &[455, 53, 456], 762);
                step(f, Op::MakeVector, &[451, 452, 456, 95], 763);
                step(f, Op::SubF, &[915, 431, 432], 764);
                step(f, Op::MaxF, &[432, 913, 433], 765);
                step(f, Op::MulF, &[10, 7, 434], 766);
                step(f, Op::MulF, &[433, 434, 435], 767);
                step(f, Op::ScaleV, &[2, 435, 86], 768);
                step(f, Op::AddV, &[95, 86, 96], 769);
                step(f, Op::MulF, &[6, 914, 436], 770);
                step(f, Op::ScaleV, &[2, 436, 87], 771);
                step(f, Op::AddV, &[96, 87, 97], 772);
                step(f, Op::RotateVector, &[0, 491, 99], 773);
                step(f, Op::Copy(ValueType::Float), &[920, 504], 774);
                step(f, Op::Copy(ValueType::Vec3), &[488, 164], 775);
                step(f, Op::Copy(ValueType::Vec3), &[490, 165], 776);
                step(f, Op::Copy(ValueType::Bool), &[130, 83], 777);
                step(f, Op::Copy(ValueType::Float), &[920, 505], 778);
                step(f, Op::Copy(ValueType::Vec3), &[488, 166], 779);
                step(f, Op::MulI, &[0, 0, 52], 780);
                step(f, Op::Copy(ValueType::Int), &[52, 51], 781);
                step(f, Op::Copy(ValueType::Int), &[71, 47], 782);
                step(f, Op::SubI, &[0, 72, 55], 783);
                step(f, Op::DivI, &[55, 73, 56], 784);
                step(f, Op::MakeVector, &[913, 913, 58, 171], 785);
                step(f, Op::ScaleV, &[99, 62, 176], 786);
                786
            }
            786 => {
                step(f, Op::ForNext, &[47, 51, 49, 833], 787)
            }
            787 => {
                step(f, Op::ModI, &[49, 0, 53], 788);
                step(f, Op::ToFloat, &[53, 506], 789);
                step(f, Op::MulF, &[506, 59, 508], 790);
                step(f, Op::MulF, &[508, 457, 509], 791);
                step(f, Op::MakeVector, &[509, 913, 913, 167], 792);
                step(f, Op::DivI, &[49, 0, 54], 793);
                step(f, Op::SubI, &[54, 56, 57], 794);
                step(f, Op::ToFloat, &[57, 507], 795);
                step(f, Op::MulF, &[507, 59, 510], 796);
                step(f, Op::ScaleV, &[99, 510, 168], 797);
                step(f, Op::AddV, &[167, 168, 169], 798);
                step(f, Op::AddV, &[97, 169, 170], 799);
                step(f, Op::AddV, &[170, 171, 172], 800);
                step(f, Op::SubV, &[170, 171, 173], 801);
                step(f, Op::SphereTrace, &[172, 173, 57, 84, 174, 175, 511], 802);
                step(f, Op::BreakVector, &[174, 513, 514, 515], 803);
                step(f, Op::AddV, &[172, 176, 177], 804);
                step(f, Op::AddV, &[173, 176, 178], 805);
                step(f, Op::SphereTrace, &[177, 178, 57, 85, 179, 180, 512], 806);
                step(f, Op::BreakVector, &[179, 516, 517, 518], 807);
                step(f, Op::SubF, &[515, 518, 519], 808);
                step(f, Op::AbsF, &[519, 520], 809);
                step(f, Op::Select(ValueType::Float), &[84, 913, 915, 521], 810);
                step(f, Op::AddF, &[520, 521, 526], 811);
                step(f, Op::LengthV, &[169, 522], 812);
                step(f, Op::RemapF, &[522, 913, 926, 913, 915, 129, 523], 813);
                step(f, Op::MinF, &[515, 518, 524], 814);
                step(f, Op::RemapF, &[524, 927, 926, 915, 914, 129, 525], 815);
                step(f, Op::AddF, &[523, 525, 527], 816);
                step(f, Op::AddF, &[526, 527, 528], 817);
                step(f, Op::LessF, &[528, 504, 86], 818);
                step(f, Op::And, &[84, 86, 87], 819);
                step(f, Op::JumpIfFalse, &[87, 827], 820)
            }
            820 => {
                step(f, Op::Copy(ValueType::Float), &[504, 505], 821);
                step(f, Op::Copy(ValueType::Vec3), &[164, 166], 822);
                step(f, Op::Copy(ValueType::Float), &[528, 504], 823);
                step(f, Op::Copy(ValueType::Vec3), &[174, 164], 824);
                step(f, Op::Copy(ValueType::Vec3), &[175, 165], 825);
                step(f, Op::Copy(ValueType::Bool), &[129, 83], 826);
                step(f, Op::Jump, &[832], 827)
            }
            827 => {
                step(f, Op::LessF, &[528, 505, 88], 828);
                step(f, Op::And, &[84, 88, 89], 829);
                step(f, Op::JumpIfFalse, &[89, 832], 830)
            }
            830 => {
                step(f, Op::Copy(ValueType::Float), &[528, 505], 831);
                step(f, Op::Copy(ValueType::Vec3), &[174, 166], 832);
                832
            }
            832 => {
                step(f, Op::Jump, &[786], 833)
            }
            833 => {
                step(f, Op::JumpIfFalse, &[8, 835], 834)
            }
            834 => {
                step(f, Op::DrawSphere, &[164, 57, 491], 835);
                835
            }
            835 => {
                step(f, Op::GreaterF, &[61, 913, 90], 836);
                step(f, Op::SubF, &[504, 505, 529], 837);
                step(f, Op::DivF, &[529, 61, 530], 838);
                step(f, Op::PowF, &[928, 530, 531], 839);
                step(f, Op::Select(ValueType::Float), &[90, 531, 913, 532], 840);
                step(f, Op::ScaleV, &[166, 532, 181], 841);
                step(f, Op::AddV, &[164, 181, 182], 842);
                step(f, Op::AddF, &[532, 915, 533], 843);
                step(f, Op::DivF, &[915, 533, 534], 844);
                step(f, Op::ScaleV, &[182, 534, 183], 845);
                step(f, Op::Copy(ValueType::Vec3), &[183, 162], 846);
                step(f, Op::Copy(ValueType::Vec3), &[165, 163], 847);
                step(f, Op::Copy(ValueType::Bool), &[83, 82], 848);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 27], 849);
                step(f, Op::BreakTransform, &[27, 101, 21, 102], 850);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 431], 851);
                step(f, Op::SubF, &[915, 431, 432], 852);
                step(f, Op::MaxF, &[432, 913, 433], 853);
                step(f, Op::MulF, &[10, 7, 434], 854);
                step(f, Op::MulF, &[433, 434, 435], 855);
                step(f, Op::ScaleV, &[2, 435, 86], 856);
                step(f, Op::SubV, &[162, 86, 100], 857);
                step(f, Op::Select(ValueType::Vec3), &[82, 100, 101, 103], 858);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 3, 28], 859);
                step(f, Op::BreakTransform, &[28, 104, 23, 105], 860);
                step(f, Op::Copy(ValueType::Float), &[50, 463], 861);
                step(f, Op::Copy(ValueType::Float), &[52, 464], 862);
                step(f, Op::SubV, &[103, 104, 110], 863);
                step(f, Op::DeltaTime, &[465], 864);
                step(f, Op::DivF, &[464, 465, 466], 865);
                step(f, Op::ScaleV, &[110, 466, 111], 866);
                step(f, Op::AddV, &[103, 111, 112], 867);
                step(f, Op::AddV, &[104, 111, 113], 868);
                step(f, Op::SubV, &[101, 113, 114], 869);
                step(f, Op::FloatLerp, &[913, 915, 463, 467], 870);
                step(f, Op::SubF, &[915, 467, 468], 871);
                step(f, Op::ScaleV, &[114, 468, 115], 872);
                step(f, Op::AddV, &[112, 115, 117], 873);
                step(f, Op::MulF, &[463, 465, 469], 874);
                step(f, Op::GreaterF, &[469, 913, 60], 875);
                step(f, Op::DivF, &[467, 469, 470], 876);
                step(f, Op::Select(ValueType::Float), &[60, 470, 915, 471], 877);
                step(f, Op::ScaleV, &[110, 471, 116], 878);
                step(f, Op::SubV, &[117, 116, 118], 879);
                step(f, Op::Copy(ValueType::Vec3), &[118, 109], 880);
                step(f, Op::BreakVector, &[109, 472, 473, 474], 881);
                step(f, Op::ClampF, &[474, 63, 64, 475], 882);
                step(f, Op::MakeVector, &[472, 473, 475, 119], 883);
                step(f, Op::RotationFromNormal, &[163, 461, 462, 19], 884);
                step(f, Op::PerFootRotationFactor, &[14, 106, 107, 458], 885);
                step(f, Op::MulF, &[14, 458, 459], 886);
                step(f, Op::SubF, &[915, 15, 440], 887);
                step(f, Op::MulF, &[459, 440, 460], 888);
                step(f, Op::QuatFromAxisAngle, &[490, 460, 18], 889);
                step(f, Op::MulQ, &[19, 18, 20], 890);
                step(f, Op::Select(ValueType::Quat), &[82, 20, 21, 22], 891);
                step(f, Op::MakeTransform, &[119, 22, 487, 30], 892);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 3, 30], 893);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 27], 894);
                step(f, Op::BreakTransform, &[27, 101, 21, 102], 895);
                step(f, Op::Select(ValueType::Vec3), &[82, 100, 101, 103], 896);
                step(f, Op::MakeTransform, &[103, 98, 487, 29], 897);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 3, 29], 898);
                step(f, Op::GetTransform, &[34, 71, 129, 25], 899);
                step(f, Op::BreakTransform, &[25, 88, 15, 89], 900);
                step(f, Op::BreakVector, &[88, 442, 443, 444], 901);
                step(f, Op::MulF, &[14, 440, 441], 902);
                step(f, Op::QuatFromAxisAngle, &[490, 441, 17], 903);
                step(f, Op::GetTransform, &[0, 71, 129, 26], 904);
                step(f, Op::BreakTransform, &[26, 90, 16, 91], 905);
                step(f, Op::SubV, &[90, 88, 92], 906);
                step(f, Op::BreakVector, &[92, 437, 438, 439], 907);
                step(f, Op::MakeVector, &[437, 438, 913, 93], 908);
                step(f, Op::RotateVector, &[17, 93, 94], 909);
                step(f, Op::BreakVector, &[94, 445, 446, 447], 910);
                step(f, Op::MulF, &[47, 15, 448], 911);
                step(f, Op::MulF, &[448, 457, 449], 912);
                step(f, Op::AddF, &[445, 449, 450], 913);
                step(f, Op::AddF, &[442, 450, 451], 914);
                step(f, Op::AddF, &[443, 446, 452], 915);
                step(f, Op::BreakVector, &[90, 453, 454, 455], 916);
                step(f, Op::SubF, &[455, 53, 456], 917);
                step(f, Op::MakeVector, &[451, 452, 456, 95], 918);
                step(f, Op::MulF, &[6, 914, 436], 919);
                step(f, Op::ScaleV, &[2, 436, 87], 920);
                step(f, Op::AddV, &[95, 87, 98], 921);
                step(f, Op::SubV, &[103, 98, 120], 922);
                step(f, Op::ArraySetAt(Elem::Vec3), &[0, 3, 120], 923);
                step(f, Op::ArraySetAt(Elem::Bool), &[1, 3, 82], 924);
                step(f, Op::GreaterEqualF, &[431, 915, 62], 925);
                step(f, Op::JumpIfFalse, &[62, 942], 926)
            }
            926 => {
                step(f, Op::MakeVector, &[913, 913, 58, 123], 927);
                step(f, Op::AddV, &[98, 123, 124], 928);
                step(f, Op::RotateVector, &[0, 491, 99], 929);
                step(f, Op::ScaleV, &[99, 62, 128], 930);
                step(f, Op::AddV, &[124, 128, 129], 931);
                step(f, Op::SubV, &[98, 123, 125], 932);
                step(f, Op::AddV, &[125, 128, 130], 933);
                step(f, Op::SphereTrace, &[129, 130, 57, 71, 131, 132, 477], 934);
                step(f, Op::SubV, &[131, 98, 141], 935);
                step(f, Op::ArraySetAt(Elem::Vec3), &[1, 3, 141], 936);
                step(f, Op::ScaleV, &[99, 59, 133], 937);
                step(f, Op::AddV, &[129, 133, 134], 938);
                step(f, Op::AddV, &[130, 133, 135], 939);
                step(f, Op::SphereTrace, &[134, 135, 57, 72, 136, 137, 478], 940);
                step(f, Op::SubV, &[136, 98, 138], 941);
                step(f, Op::ArraySetAt(Elem::Vec3), &[2, 3, 138], 942);
                942
            }
            942 => {
                step(f, Op::JumpIfFalse, &[82, 944], 943)
            }
            943 => {
                step(f, Op::Copy(ValueType::Bool), &[129, 7], 944);
                944
            }
            944 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 3, 35], 945);
                step(f, Op::GreaterF, &[21, 913, 94], 946);
                step(f, Op::InterpolateTransform, &[2, 124, 22, 33], 947);
                step(f, Op::Select(ValueType::Transform), &[94, 33, 2, 34], 948);
                step(f, Op::MakeAbsolute, &[35, 34, 36], 949);
                step(f, Op::BreakTransform, &[36, 184, 24, 185], 950);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 3, 37], 951);
                step(f, Op::BreakTransform, &[37, 186, 25, 187], 952);
                step(f, Op::AddF, &[67, 68, 536], 953);
                step(f, Op::ClampSpatially, &[184, 186, 913, 536, 188], 954);
                step(f, Op::SubF, &[915, 15, 568], 955);
                step(f, Op::MulF, &[14, 568, 537], 956);
                step(f, Op::LimitRotationAroundZ, &[24, 537, 102, 26], 957);
                step(f, Op::MakeTransform, &[188, 26, 487, 38], 958);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 3, 38], 959);
                step(f, Op::ArrayAt(Elem::Float), &[4, 3, 545], 960);
                step(f, Op::FloatLerp, &[545, 913, 105, 546], 961);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 3, 91], 962);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 535], 963);
                step(f, Op::GreaterEqualF, &[535, 915, 92], 964);
                step(f, Op::And, &[91, 92, 95], 965);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 3, 35], 966);
                step(f, Op::MakeAbsolute, &[35, 34, 36], 967);
                step(f, Op::BreakTransform, &[36, 184, 24, 185], 968);
                step(f, Op::RotateVector, &[24, 491, 189], 969);
                step(f, Op::LimitRotationAroundZ, &[24, 537, 102, 26], 970);
                step(f, Op::RotateVector, &[26, 491, 190], 971);
                step(f, Op::CrossV, &[189, 190, 191], 972);
                step(f, Op::BreakVector, &[191, 538, 539, 540], 973);
                step(f, Op::DotV, &[189, 190, 541], 974);
                step(f, Op::Atan2F, &[540, 541, 542], 975);
                step(f, Op::AbsF, &[542, 543], 976);
                step(f, Op::Select(ValueType::Float), &[95, 543, 913, 544], 977);
                step(f, Op::AddF, &[546, 544, 547], 978);
                step(f, Op::ArraySetAt(Elem::Float), &[4, 3, 547], 979);
                step(f, Op::JumpIfFalse, &[91, 1052], 980)
            }
            980 => {
                step(f, Op::JumpIfFalse, &[92, 982], 981)
            }
            981 => {
                step(f, Op::Jump, &[1051], 982)
            }
            982 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 41], 983);
                step(f, Op::BreakTransform, &[41, 197, 28, 198], 984);
                step(f, Op::SubF, &[915, 535, 558], 985);
                step(f, Op::MulF, &[10, 7, 559], 986);
                step(f, Op::MulF, &[558, 559, 560], 987);
                step(f, Op::ScaleV, &[2, 560, 199], 988);
                step(f, Op::AddV, &[197, 199, 200], 989);
                step(f, Op::Equals(Elem::Int), &[3, 71, 93], 990);
                step(f, Op::Select(ValueType::Int), &[93, 72, 71, 59], 991);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 59, 96], 992);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 59, 42], 993);
                step(f, Op::BreakTransform, &[42, 201, 29, 202], 994);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 59, 43], 995);
                step(f, Op::BreakTransform, &[43, 203, 30, 204], 996);
                step(f, Op::LessEqualF, &[88, 913, 97], 997);
                step(f, Op::ArrayAt(Elem::Float), &[2, 59, 683], 998);
                step(f, Op::SmoothStepF, &[683, 913, 88, 561], 999);
                step(f, Op::Select(ValueType::Float), &[97, 915, 561, 562], 1000);
                step(f, Op::LerpV, &[201, 203, 562, 205], 1001);
                step(f, Op::MakeTransform, &[205, 98, 487, 44], 1002);
                step(f, Op::Select(ValueType::Transform), &[96, 42, 44, 45], 1003);
                step(f, Op::MakeAbsolute, &[45, 34, 46], 1004);
                step(f, Op::Select(ValueType::Transform), &[93, 46, 45, 47], 1005);
                step(f, Op::BreakTransform, &[47, 206, 31, 207], 1006);
                step(f, Op::MulF, &[14, 568, 569], 1007);
                step(f, Op::FootAvoidance, &[200, 206, 569, 93, 84, 208], 1008);
                step(f, Op::RemapF, &[15, 87, 915, 913, 915, 129, 563], 1009);
                step(f, Op::LerpV, &[200, 208, 563, 209], 1010);
                step(f, Op::MakeTransform, &[209, 28, 487, 56], 1011);
                step(f, Op::BreakTransform, &[56, 242, 38, 243], 1012);
                step(f, Op::MakeVector, &[913, 913, 58, 244], 1013);
                step(f, Op::AddV, &[242, 244, 245], 1014);
                step(f, Op::SubV, &[242, 244, 246], 1015);
                step(f, Op::LineTrace, &[245, 246, 101, 247, 248, 595], 1016);
                step(f, Op::RotateVector, &[38, 490, 249], 1017);
                step(f, Op::FindQuatBetween, &[249, 248, 39], 1018);
                step(f, Op::MulQ, &[39, 38, 40], 1019);
                step(f, Op::MulF, &[56, 55, 596], 1020);
                step(f, Op::AddF, &[596, 66, 597], 1021);
                step(f, Op::NegF, &[597, 598], 1022);
                step(f, Op::MakeVector, &[913, 598, 913, 250], 1023);
                step(f, Op::RotateVector, &[40, 250, 252], 1024);
                step(f, Op::AddV, &[247, 252, 254], 1025);
                step(f, Op::AddV, &[254, 244, 256], 1026);
                step(f, Op::SubV, &[254, 244, 257], 1027);
                step(f, Op::LineTrace, &[256, 257, 102, 260, 261, 600], 1028);
                step(f, Op::BreakVector, &[260, 602, 603, 604], 1029);
                step(f, Op::BreakVector, &[254, 608, 609, 610], 1030);
                step(f, Op::SubF, &[604, 610, 614], 1031);
                step(f, Op::Select(ValueType::Float), &[102, 614, 913, 616], 1032);
                step(f, Op::AddF, &[62, 66, 599], 1033);
                step(f, Op::MakeVector, &[913, 599, 913, 251], 1034);
                step(f, Op::RotateVector, &[40, 251, 253], 1035);
                step(f, Op::AddV, &[247, 253, 255], 1036);
                step(f, Op::AddV, &[255, 244, 258], 1037);
                step(f, Op::SubV, &[255, 244, 259], 1038);
                step(f, Op::LineTrace, &[258, 259, 103, 262, 263, 601], 1039);
                step(f, Op::BreakVector, &[262, 605, 606, 607], 1040);
                step(f, Op::BreakVector, &[255, 611, 612, 613], 1041);
                step(f, Op::SubF, &[607, 613, 615], 1042);
                step(f, Op::Select(ValueType::Float), &[103, 615, 913, 617], 1043);
                step(f, Op::MaxF, &[616, 617, 618], 1044);
                step(f, Op::ClampF, &[618, 913, 65, 619], 1045);
                step(f, Op::MakeVector, &[913, 913, 619, 264], 1046);
                step(f, Op::AddV, &[247, 264, 265], 1047);
                step(f, Op::MakeTransform, &[265, 40, 487, 59], 1048);
                step(f, Op::Select(ValueType::Transform), &[101, 59, 56, 60], 1049);
                step(f, Op::Copy(ValueType::Transform), &[60, 58], 1050);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 3, 58], 1051);
                1051
            }
            1051 => {
                step(f, Op::Jump, &[1164], 1052)
            }
            1052 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 3, 61], 1053);
                step(f, Op::MakeAbsolute, &[61, 34, 62], 1054);
                step(f, Op::BreakTransform, &[62, 266, 41, 267], 1055);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 41], 1056);
                step(f, Op::BreakTransform, &[41, 197, 28, 198], 1057);
                step(f, Op::SubF, &[915, 535, 558], 1058);
                step(f, Op::MulF, &[10, 7, 559], 1059);
                step(f, Op::MulF, &[558, 559, 560], 1060);
                step(f, Op::ScaleV, &[2, 560, 199], 1061);
                step(f, Op::AddV, &[197, 199, 200], 1062);
                step(f, Op::Equals(Elem::Int), &[3, 71, 93], 1063);
                step(f, Op::Select(ValueType::Int), &[93, 72, 71, 59], 1064);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 59, 96], 1065);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 59, 42], 1066);
                step(f, Op::BreakTransform, &[42, 201, 29, 202], 1067);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 59, 43], 1068);
                step(f, Op::BreakTransform, &[43, 203, 30, 204], 1069);
                step(f, Op::LessEqualF, &[88, 913, 97], 1070);
                step(f, Op::ArrayAt(Elem::Float), &[2, 59, 683], 1071);
                step(f, Op::SmoothStepF, &[683, 913, 88, 561], 1072);
                step(f, Op::Select(ValueType::Float), &[97, 915, 561, 562], 1073);
                step(f, Op::LerpV, &[201, 203, 562, 205], 1074);
                step(f, Op::MakeTransform, &[205, 98, 487, 44], 1075);
                step(f, Op::Select(ValueType::Transform), &[96, 42, 44, 45], 1076);
                step(f, Op::MakeAbsolute, &[45, 34, 46], 1077);
                step(f, Op::Select(ValueType::Transform), &[93, 46, 45, 47], 1078);
                step(f, Op::BreakTransform, &[47, 206, 31, 207], 1079);
                step(f, Op::MulF, &[14, 568, 569], 1080);
                step(f, Op::FootAvoidance, &[200, 206, 569, 93, 84, 208], 1081);
                step(f, Op::RemapF, &[15, 87, 915, 913, 915, 129, 563], 1082);
                step(f, Op::LerpV, &[200, 208, 563, 209], 1083);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 3, 63], 1084);
                step(f, Op::MakeAbsolute, &[63, 34, 64], 1085);
                step(f, Op::BreakTransform, &[64, 268, 42, 269], 1086);
                step(f, Op::ArrayAt(Elem::Float), &[3, 3, 620], 1087);
                step(f, Op::SubF, &[535, 620, 621], 1088);
                step(f, Op::DeltaTime, &[636], 1089);
                step(f, Op::DivF, &[52, 636, 622], 1090);
                step(f, Op::MulF, &[621, 622, 623], 1091);
                step(f, Op::AddF, &[620, 623, 624], 1092);
                step(f, Op::ClampF, &[624, 913, 915, 626], 1093);
                step(f, Op::AddF, &[535, 623, 625], 1094);
                step(f, Op::ClampF, &[625, 913, 915, 627], 1095);
                step(f, Op::AddF, &[626, 627, 628], 1096);
                step(f, Op::MulF, &[628, 914, 629], 1097);
                step(f, Op::SubF, &[915, 629, 630], 1098);
                step(f, Op::GreaterF, &[621, 913, 104], 1099);
                step(f, Op::SubF, &[627, 626, 631], 1100);
                step(f, Op::DivF, &[631, 621, 632], 1101);
                step(f, Op::Select(ValueType::Float), &[104, 632, 915, 633], 1102);
                step(f, Op::MulF, &[630, 633, 634], 1103);
                step(f, Op::MulF, &[83, 634, 635], 1104);
                step(f, Op::Copy(ValueType::Float), &[52, 638], 1105);
                step(f, Op::SubV, &[209, 268, 274], 1106);
                step(f, Op::DeltaTime, &[639], 1107);
                step(f, Op::DivF, &[638, 639, 640], 1108);
                step(f, Op::ScaleV, &[274, 640, 275], 1109);
                step(f, Op::AddV, &[209, 275, 276], 1110);
                step(f, Op::AddV, &[268, 275, 277], 1111);
                step(f, Op::SubV, &[266, 277, 278], 1112);
                step(f, Op::FloatLerp, &[913, 915, 635, 641], 1113);
                step(f, Op::SubF, &[915, 641, 642], 1114);
                step(f, Op::ScaleV, &[278, 642, 279], 1115);
                step(f, Op::AddV, &[276, 279, 281], 1116);
                step(f, Op::MulF, &[635, 639, 643], 1117);
                step(f, Op::GreaterF, &[643, 913, 105], 1118);
                step(f, Op::DivF, &[641, 643, 644], 1119);
                step(f, Op::Select(ValueType::Float), &[105, 644, 915, 645], 1120);
                step(f, Op::ScaleV, &[274, 645, 280], 1121);
                step(f, Op::SubV, &[281, 280, 282], 1122);
                step(f, Op::Copy(ValueType::Vec3), &[282, 273], 1123);
                step(f, Op::MakeTransform, &[273, 28, 487, 66], 1124);
                step(f, Op::BreakTransform, &[66, 283, 43, 284], 1125);
                step(f, Op::MakeVector, &[913, 913, 58, 285], 1126);
                step(f, Op::AddV, &[283, 285, 286], 1127);
                step(f, Op::SubV, &[283, 285, 287], 1128);
                step(f, Op::LineTrace, &[286, 287, 106, 288, 289, 646], 1129);
                step(f, Op::RotateVector, &[43, 490, 290], 1130);
                step(f, Op::FindQuatBetween, &[290, 289, 44], 1131);
                step(f, Op::MulQ, &[44, 43, 45], 1132);
                step(f, Op::MulF, &[56, 55, 647], 1133);
                step(f, Op::AddF, &[647, 66, 648], 1134);
                step(f, Op::NegF, &[648, 649], 1135);
                step(f, Op::MakeVector, &[913, 649, 913, 291], 1136);
                step(f, Op::RotateVector, &[45, 291, 293], 1137);
                step(f, Op::AddV, &[288, 293, 295], 1138);
                step(f, Op::AddV, &[295, 285, 297], 1139);
                step(f, Op::SubV, &[295, 285, 298], 1140);
                step(f, Op::LineTrace, &[297, 298, 107, 301, 302, 651], 1141);
                step(f, Op::BreakVector, &[301, 653, 654, 655], 1142);
                step(f, Op::BreakVector, &[295, 659, 660, 661], 1143);
                step(f, Op::SubF, &[655, 661, 665], 1144);
                step(f, Op::Select(ValueType::Float), &[107, 665, 913, 667], 1145);
                step(f, Op::AddF, &[62, 66, 650], 1146);
                step(f, Op::MakeVector, &[913, 650, 913, 292], 1147);
                step(f, Op::RotateVector, &[45, 292, 294], 1148);
                step(f, Op::AddV, &[288, 294, 296], 1149);
                step(f, Op::AddV, &[296, 285, 299], 1150);
                step(f, Op::SubV, &[296, 285, 300], 1151);
                step(f, Op::LineTrace, &[299, 300, 108, 303, 304, 652], 1152);
                step(f, Op::BreakVector, &[303, 656, 657, 658], 1153);
                step(f, Op::BreakVector, &[296, 662, 663, 664], 1154);
                step(f, Op::SubF, &[658, 664, 666], 1155);
                step(f, Op::Select(ValueType::Float), &[108, 666, 913, 668], 1156);
                step(f, Op::MaxF, &[667, 668, 669], 1157);
                step(f, Op::ClampF, &[669, 913, 65, 670], 1158);
                step(f, Op::MakeVector, &[913, 913, 670, 305], 1159);
                step(f, Op::AddV, &[288, 305, 306], 1160);
                step(f, Op::MakeTransform, &[306, 45, 487, 69], 1161);
                step(f, Op::Select(ValueType::Transform), &[106, 69, 66, 70], 1162);
                step(f, Op::Copy(ValueType::Transform), &[70, 68], 1163);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 3, 68], 1164);
                1164
            }
            1164 => {
                step(f, Op::JumpIfFalse, &[92, 1245], 1165)
            }
            1165 => {
                step(f, Op::JumpIfFalse, &[91, 1167], 1166)
            }
            1166 => {
                step(f, Op::Jump, &[1226], 1167)
            }
            1167 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 3, 71], 1168);
                step(f, Op::BreakTransform, &[71, 307, 46, 308], 1169);
                step(f, Op::Equals(Elem::Int), &[3, 71, 93], 1170);
                step(f, Op::Select(ValueType::Int), &[93, 72, 71, 59], 1171);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 59, 48], 1172);
                step(f, Op::BreakTransform, &[48, 210, 32, 211], 1173);
                step(f, Op::MakeAbsolute, &[48, 34, 49], 1174);
                step(f, Op::BreakTransform, &[49, 212, 33, 213], 1175);
                step(f, Op::ArrayAt(Elem::Float), &[2, 59, 683], 1176);
                step(f, Op::SmoothStepF, &[683, 913, 915, 564], 1177);
                step(f, Op::RemapF, &[15, 913, 87, 913, 915, 129, 565], 1178);
                step(f, Op::MulF, &[564, 565, 566], 1179);
                step(f, Op::Select(ValueType::Float), &[93, 566, 913, 567], 1180);
                step(f, Op::LerpV, &[210, 212, 567, 214], 1181);
                step(f, Op::MakeTransform, &[214, 98, 487, 50], 1182);
                step(f, Op::BreakTransform, &[50, 215, 34, 216], 1183);
                step(f, Op::MulF, &[14, 568, 569], 1184);
                step(f, Op::FootAvoidance, &[307, 215, 569, 93, 84, 217], 1185);
                step(f, Op::MakeTransform, &[217, 46, 487, 51], 1186);
                step(f, Op::BreakTransform, &[51, 218, 35, 219], 1187);
                step(f, Op::MakeVector, &[913, 913, 58, 220], 1188);
                step(f, Op::AddV, &[218, 220, 221], 1189);
                step(f, Op::SubV, &[218, 220, 222], 1190);
                step(f, Op::LineTrace, &[221, 222, 98, 223, 224, 570], 1191);
                step(f, Op::RotateVector, &[35, 490, 225], 1192);
                step(f, Op::FindQuatBetween, &[225, 224, 36], 1193);
                step(f, Op::MulQ, &[36, 35, 37], 1194);
                step(f, Op::MulF, &[56, 55, 571], 1195);
                step(f, Op::AddF, &[571, 66, 572], 1196);
                step(f, Op::NegF, &[572, 573], 1197);
                step(f, Op::MakeVector, &[913, 573, 913, 226], 1198);
                step(f, Op::RotateVector, &[37, 226, 228], 1199);
                step(f, Op::AddV, &[223, 228, 230], 1200);
                step(f, Op::AddV, &[230, 220, 232], 1201);
                step(f, Op::SubV, &[230, 220, 233], 1202);
                step(f, Op::LineTrace, &[232, 233, 99, 236, 237, 575], 1203);
                step(f, Op::BreakVector, &[236, 577, 578, 579], 1204);
                step(f, Op::BreakVector, &[230, 583, 584, 585], 1205);
                step(f, Op::SubF, &[579, 585, 589], 1206);
                step(f, Op::Select(ValueType::Float), &[99, 589, 913, 591], 1207);
                step(f, Op::AddF, &[62, 66, 574], 1208);
                step(f, Op::MakeVector, &[913, 574, 913, 227], 1209);
                step(f, Op::RotateVector, &[37, 227, 229], 1210);
                step(f, Op::AddV, &[223, 229, 231], 1211);
                step(f, Op::AddV, &[231, 220, 234], 1212);
                step(f, Op::SubV, &[231, 220, 235], 1213);
                step(f, Op::LineTrace, &[234, 235, 100, 238, 239, 576], 1214);
                step(f, Op::BreakVector, &[238, 580, 581, 582], 1215);
                step(f, Op::BreakVector, &[231, 586, 587, 588], 1216);
                step(f, Op::SubF, &[582, 588, 590], 1217);
                step(f, Op::Select(ValueType::Float), &[100, 590, 913, 592], 1218);
                step(f, Op::MaxF, &[591, 592, 593], 1219);
                step(f, Op::ClampF, &[593, 913, 65, 594], 1220);
                step(f, Op::MakeVector, &[913, 913, 594, 240], 1221);
                step(f, Op::AddV, &[223, 240, 241], 1222);
                step(f, Op::MakeTransform, &[241, 37, 487, 54], 1223);
                step(f, Op::Select(ValueType::Transform), &[98, 54, 51, 55], 1224);
                step(f, Op::Copy(ValueType::Transform), &[55, 53], 1225);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 3, 53], 1226);
                1226
            }
            1226 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 3, 39], 1227);
                step(f, Op::BreakTransform, &[39, 192, 27, 193], 1228);
                step(f, Op::SubV, &[192, 186, 194], 1229);
                step(f, Op::LengthV, &[194, 548], 1230);
                step(f, Op::SubF, &[67, 68, 549], 1231);
                step(f, Op::SubF, &[548, 549, 550], 1232);
                step(f, Op::MulF, &[68, 918, 551], 1233);
                step(f, Op::ClampF, &[550, 913, 551, 552], 1234);
                step(f, Op::MulF, &[552, 552, 553], 1235);
                step(f, Op::MulF, &[68, 929, 554], 1236);
                step(f, Op::DivF, &[553, 554, 555], 1237);
                step(f, Op::SubF, &[548, 555, 556], 1238);
                step(f, Op::DivF, &[556, 548, 557], 1239);
                step(f, Op::ScaleV, &[194, 557, 195], 1240);
                step(f, Op::AddV, &[186, 195, 196], 1241);
                step(f, Op::MakeTransform, &[196, 27, 487, 40], 1242);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 3, 40], 1243);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 3, 40], 1244);
                step(f, Op::Jump, &[1399], 1245)
            }
            1245 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 3, 39], 1246);
                step(f, Op::BreakTransform, &[39, 192, 27, 193], 1247);
                step(f, Op::SubV, &[192, 186, 194], 1248);
                step(f, Op::LengthV, &[194, 548], 1249);
                step(f, Op::SubF, &[67, 68, 549], 1250);
                step(f, Op::SubF, &[548, 549, 550], 1251);
                step(f, Op::MulF, &[68, 918, 551], 1252);
                step(f, Op::ClampF, &[550, 913, 551, 552], 1253);
                step(f, Op::MulF, &[552, 552, 553], 1254);
                step(f, Op::MulF, &[68, 929, 554], 1255);
                step(f, Op::DivF, &[553, 554, 555], 1256);
                step(f, Op::SubF, &[548, 555, 556], 1257);
                step(f, Op::DivF, &[556, 548, 557], 1258);
                step(f, Op::ScaleV, &[194, 557, 195], 1259);
                step(f, Op::AddV, &[186, 195, 196], 1260);
                step(f, Op::MakeTransform, &[196, 27, 487, 40], 1261);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 3, 71], 1262);
                step(f, Op::ClampF, &[535, 913, 915, 671], 1263);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[6, 5], 1264);
                step(f, Op::ArrayReset(Elem::Vec3), &[5], 1265);
                step(f, Op::BreakTransform, &[40, 328, 51, 329], 1266);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 328], 1267);
                step(f, Op::UnitV, &[2, 327], 1268);
                step(f, Op::LengthV, &[2, 699], 1269);
                step(f, Op::RemapF, &[699, 913, 69, 913, 70, 129, 700], 1270);
                step(f, Op::ScaleV, &[327, 700, 332], 1271);
                step(f, Op::SubV, &[328, 332, 338], 1272);
                step(f, Op::MakeVector, &[913, 913, 72, 336], 1273);
                step(f, Op::AddV, &[338, 336, 340], 1274);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 340], 1275);
                step(f, Op::RemapF, &[699, 913, 69, 913, 74, 129, 702], 1276);
                step(f, Op::MakeVector, &[913, 913, 702, 334], 1277);
                step(f, Op::AddV, &[340, 334, 344], 1278);
                step(f, Op::BreakTransform, &[71, 330, 52, 331], 1279);
                step(f, Op::BreakVector, &[330, 707, 708, 709], 1280);
                step(f, Op::BreakVector, &[328, 704, 705, 706], 1281);
                step(f, Op::SubF, &[709, 706, 710], 1282);
                step(f, Op::MaxF, &[710, 913, 712], 1283);
                step(f, Op::MulF, &[712, 76, 716], 1284);
                step(f, Op::MinF, &[716, 77, 717], 1285);
                step(f, Op::AbsF, &[710, 714], 1286);
                step(f, Op::RemapF, &[714, 913, 80, 913, 79, 129, 715], 1287);
                step(f, Op::AddF, &[717, 715, 719], 1288);
                step(f, Op::MakeVector, &[913, 913, 719, 342], 1289);
                step(f, Op::AddV, &[344, 342, 346], 1290);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 346], 1291);
                step(f, Op::RemapF, &[699, 913, 69, 913, 71, 129, 701], 1292);
                step(f, Op::ScaleV, &[327, 701, 333], 1293);
                step(f, Op::AddV, &[330, 333, 339], 1294);
                step(f, Op::MakeVector, &[913, 913, 73, 337], 1295);
                step(f, Op::AddV, &[339, 337, 341], 1296);
                step(f, Op::RemapF, &[699, 913, 69, 913, 75, 129, 703], 1297);
                step(f, Op::MakeVector, &[913, 913, 703, 335], 1298);
                step(f, Op::AddV, &[341, 335, 345], 1299);
                step(f, Op::NegF, &[710, 711], 1300);
                step(f, Op::MaxF, &[711, 913, 713], 1301);
                step(f, Op::MulF, &[713, 78, 718], 1302);
                step(f, Op::AddF, &[718, 715, 720], 1303);
                step(f, Op::MakeVector, &[913, 913, 720, 343], 1304);
                step(f, Op::AddV, &[345, 343, 347], 1305);
                step(f, Op::LerpV, &[346, 347, 914, 348], 1306);
                step(f, Op::GetTransform, &[35, 71, 129, 80], 1307);
                step(f, Op::BreakTransform, &[80, 349, 53, 350], 1308);
                step(f, Op::BreakVector, &[349, 730, 731, 732], 1309);
                step(f, Op::SubF, &[915, 15, 724], 1310);
                step(f, Op::MulF, &[81, 724, 725], 1311);
                step(f, Op::MulF, &[14, 725, 726], 1312);
                step(f, Op::QuatFromAxisAngle, &[490, 726, 54], 1313);
                step(f, Op::SubV, &[348, 349, 351], 1314);
                step(f, Op::BreakVector, &[351, 721, 722, 723], 1315);
                step(f, Op::MakeVector, &[721, 722, 913, 352], 1316);
                step(f, Op::RotateVector, &[54, 352, 353], 1317);
                step(f, Op::BreakVector, &[353, 727, 728, 729], 1318);
                step(f, Op::AddF, &[730, 727, 736], 1319);
                step(f, Op::AddF, &[731, 728, 737], 1320);
                step(f, Op::BreakVector, &[348, 733, 734, 735], 1321);
                step(f, Op::MakeVector, &[736, 737, 735, 354], 1322);
                step(f, Op::DistanceV, &[328, 330, 738], 1323);
                step(f, Op::RemapF, &[738, 918, 930, 913, 915, 129, 739], 1324);
                step(f, Op::LerpV, &[348, 354, 739, 355], 1325);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 355], 1326);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 347], 1327);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 341], 1328);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 330], 1329);
                step(f, Op::JumpIfFalse, &[8, 1331], 1330)
            }
            1330 => {
                step(f, Op::DrawSpline, &[5, 71, 74, 914, 493], 1331);
                1331
            }
            1331 => {
                step(f, Op::Spline, &[5, 671, 71, 356, 357], 1332);
                step(f, Op::SlerpQ, &[51, 52, 671, 55], 1333);
                step(f, Op::MulF, &[671, 923, 741], 1334);
                step(f, Op::SinF, &[741, 742], 1335);
                step(f, Op::SmoothStepF, &[671, 913, 95, 740], 1336);
                step(f, Op::MulF, &[742, 740, 743], 1337);
                step(f, Op::MulF, &[743, 82, 744], 1338);
                step(f, Op::SlerpQ, &[55, 98, 744, 56], 1339);
                step(f, Op::MakeTransform, &[356, 56, 487, 81], 1340);
                step(f, Op::Copy(ValueType::Transform), &[81, 79], 1341);
                step(f, Op::BreakTransform, &[79, 309, 47, 310], 1342);
                step(f, Op::Equals(Elem::Int), &[3, 71, 93], 1343);
                step(f, Op::Select(ValueType::Int), &[93, 72, 71, 59], 1344);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 59, 48], 1345);
                step(f, Op::BreakTransform, &[48, 210, 32, 211], 1346);
                step(f, Op::GreaterF, &[21, 913, 94], 1347);
                step(f, Op::InterpolateTransform, &[2, 124, 22, 33], 1348);
                step(f, Op::Select(ValueType::Transform), &[94, 33, 2, 34], 1349);
                step(f, Op::MakeAbsolute, &[48, 34, 49], 1350);
                step(f, Op::BreakTransform, &[49, 212, 33, 213], 1351);
                step(f, Op::ArrayAt(Elem::Float), &[2, 59, 683], 1352);
                step(f, Op::SmoothStepF, &[683, 913, 915, 564], 1353);
                step(f, Op::RemapF, &[15, 913, 87, 913, 915, 129, 565], 1354);
                step(f, Op::MulF, &[564, 565, 566], 1355);
                step(f, Op::Select(ValueType::Float), &[93, 566, 913, 567], 1356);
                step(f, Op::LerpV, &[210, 212, 567, 214], 1357);
                step(f, Op::MakeTransform, &[214, 98, 487, 50], 1358);
                step(f, Op::BreakTransform, &[50, 215, 34, 216], 1359);
                step(f, Op::SubF, &[915, 15, 568], 1360);
                step(f, Op::MulF, &[14, 568, 569], 1361);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 59, 109], 1362);
                step(f, Op::Select(ValueType::Float), &[109, 85, 913, 674], 1363);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 535], 1364);
                step(f, Op::ClampF, &[535, 913, 915, 671], 1365);
                step(f, Op::MulF, &[671, 923, 672], 1366);
                step(f, Op::SinF, &[672, 673], 1367);
                step(f, Op::MulF, &[673, 673, 675], 1368);
                step(f, Op::MulF, &[674, 675, 676], 1369);
                step(f, Op::AddF, &[84, 676, 677], 1370);
                step(f, Op::FootAvoidance, &[309, 215, 569, 93, 677, 311], 1371);
                step(f, Op::SubV, &[311, 309, 312], 1372);
                step(f, Op::LengthV, &[312, 678], 1373);
                step(f, Op::AddF, &[678, 676, 679], 1374);
                step(f, Op::DivF, &[678, 679, 680], 1375);
                step(f, Op::LessF, &[683, 535, 111], 1376);
                step(f, Op::LessEqualF, &[86, 913, 110], 1377);
                step(f, Op::SmoothStepF, &[683, 913, 86, 684], 1378);
                step(f, Op::MulF, &[684, 15, 685], 1379);
                step(f, Op::SubF, &[915, 685, 686], 1380);
                step(f, Op::Select(ValueType::Float), &[110, 915, 686, 687], 1381);
                step(f, Op::Select(ValueType::Float), &[111, 687, 915, 688], 1382);
                step(f, Op::MulF, &[680, 688, 689], 1383);
                step(f, Op::SmoothStepF, &[671, 913, 86, 681], 1384);
                step(f, Op::Select(ValueType::Float), &[110, 915, 681, 682], 1385);
                step(f, Op::MulF, &[689, 682, 690], 1386);
                step(f, Op::ScaleV, &[312, 690, 313], 1387);
                step(f, Op::AddV, &[309, 313, 314], 1388);
                step(f, Op::MulF, &[3, 135, 691], 1389);
                step(f, Op::MulF, &[691, 675, 692], 1390);
                step(f, Op::MakeVector, &[913, 913, 692, 315], 1391);
                step(f, Op::AddV, &[314, 315, 316], 1392);
                step(f, Op::MakeTransform, &[316, 47, 487, 72], 1393);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 3, 72], 1394);
                step(f, Op::ScaleV, &[312, 689, 317], 1395);
                step(f, Op::AddV, &[309, 317, 318], 1396);
                step(f, Op::AddV, &[318, 315, 319], 1397);
                step(f, Op::MakeTransform, &[319, 47, 487, 73], 1398);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 3, 73], 1399);
                1399
            }
            1399 => {
                step(f, Op::JumpIfFalse, &[94, 1422], 1400)
            }
            1400 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 3, 74], 1401);
                step(f, Op::BreakTransform, &[74, 320, 48, 321], 1402);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 3, 75], 1403);
                step(f, Op::BreakTransform, &[75, 322, 49, 323], 1404);
                step(f, Op::MulF, &[21, 21, 693], 1405);
                step(f, Op::LerpV, &[320, 322, 693, 324], 1406);
                step(f, Op::SubF, &[915, 21, 694], 1407);
                step(f, Op::MulF, &[21, 694, 695], 1408);
                step(f, Op::MulF, &[137, 918, 696], 1409);
                step(f, Op::MulF, &[695, 696, 697], 1410);
                step(f, Op::MakeVector, &[913, 913, 697, 325], 1411);
                step(f, Op::AddV, &[324, 325, 326], 1412);
                step(f, Op::SlerpQ, &[48, 49, 21, 50], 1413);
                step(f, Op::MakeTransform, &[326, 50, 487, 76], 1414);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 3, 76], 1415);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 3, 74], 1416);
                step(f, Op::BreakTransform, &[74, 320, 48, 321], 1417);
                step(f, Op::LerpV, &[320, 322, 693, 324], 1418);
                step(f, Op::AddV, &[324, 325, 326], 1419);
                step(f, Op::SlerpQ, &[48, 49, 21, 50], 1420);
                step(f, Op::MakeTransform, &[326, 50, 487, 76], 1421);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 3, 76], 1422);
                1422
            }
            1422 => {
                step(f, Op::GreaterEqualF, &[535, 915, 92], 1423);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 3, 92], 1424);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 41], 1425);
                step(f, Op::BreakTransform, &[41, 197, 28, 198], 1426);
                step(f, Op::SubF, &[915, 535, 558], 1427);
                step(f, Op::MulF, &[10, 7, 559], 1428);
                step(f, Op::MulF, &[558, 559, 560], 1429);
                step(f, Op::ScaleV, &[2, 560, 199], 1430);
                step(f, Op::AddV, &[197, 199, 200], 1431);
                step(f, Op::Equals(Elem::Int), &[3, 71, 93], 1432);
                step(f, Op::Select(ValueType::Int), &[93, 72, 71, 59], 1433);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 59, 96], 1434);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 59, 42], 1435);
                step(f, Op::BreakTransform, &[42, 201, 29, 202], 1436);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 59, 43], 1437);
                step(f, Op::BreakTransform, &[43, 203, 30, 204], 1438);
                step(f, Op::LessEqualF, &[88, 913, 97], 1439);
                step(f, Op::ArrayAt(Elem::Float), &[2, 59, 683], 1440);
                step(f, Op::SmoothStepF, &[683, 913, 88, 561], 1441);
                step(f, Op::Select(ValueType::Float), &[97, 915, 561, 562], 1442);
                step(f, Op::LerpV, &[201, 203, 562, 205], 1443);
                step(f, Op::MakeTransform, &[205, 98, 487, 44], 1444);
                step(f, Op::Select(ValueType::Transform), &[96, 42, 44, 45], 1445);
                step(f, Op::MakeAbsolute, &[45, 34, 46], 1446);
                step(f, Op::Select(ValueType::Transform), &[93, 46, 45, 47], 1447);
                step(f, Op::BreakTransform, &[47, 206, 31, 207], 1448);
                step(f, Op::MulF, &[14, 568, 569], 1449);
                step(f, Op::FootAvoidance, &[200, 206, 569, 93, 84, 208], 1450);
                step(f, Op::RemapF, &[15, 87, 915, 913, 915, 129, 563], 1451);
                step(f, Op::LerpV, &[200, 208, 563, 209], 1452);
                step(f, Op::MakeTransform, &[209, 98, 487, 65], 1453);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 3, 65], 1454);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 3, 82], 1455);
                step(f, Op::BreakTransform, &[82, 358, 57, 359], 1456);
                step(f, Op::MakeVector, &[913, 913, 53, 368], 1457);
                step(f, Op::AddV, &[358, 368, 369], 1458);
                step(f, Op::GetTransform, &[0, 71, 129, 84], 1459);
                step(f, Op::BreakTransform, &[84, 363, 59, 364], 1460);
                step(f, Op::MakeTransform, &[369, 59, 487, 86], 1461);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 3, 20], 1462);
                step(f, Op::GetTransform, &[20, 71, 129, 85], 1463);
                step(f, Op::BreakTransform, &[85, 365, 60, 366], 1464);
                step(f, Op::SubV, &[365, 363, 367], 1465);
                step(f, Op::AddV, &[369, 367, 370], 1466);
                step(f, Op::FootPivots, &[369, 370, 55, 54, 53, 56, 371, 372, 373], 1467);
                step(f, Op::GetParent, &[0, 18], 1468);
                step(f, Op::GetParent, &[18, 19], 1469);
                step(f, Op::GetTransform, &[19, 71, 130, 83], 1470);
                step(f, Op::BreakTransform, &[83, 360, 58, 361], 1471);
                step(f, Op::SubV, &[358, 360, 362], 1472);
                step(f, Op::DotV, &[362, 491, 745], 1473);
                step(f, Op::RemapF, &[745, 90, 89, 91, 913, 129, 748], 1474);
                step(f, Op::LengthV, &[2, 746], 1475);
                step(f, Op::RemapF, &[746, 913, 101, 913, 915, 129, 747], 1476);
                step(f, Op::MulF, &[748, 747, 749], 1477);
                step(f, Op::QuatFromAxisAngle, &[494, 749, 61], 1478);
                step(f, Op::RotateAroundPoint, &[86, 371, 61, 87], 1479);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 750], 1480);
                step(f, Op::SmoothStepF, &[750, 913, 95, 752], 1481);
                step(f, Op::SubF, &[915, 750, 751], 1482);
                step(f, Op::SmoothStepF, &[751, 913, 95, 753], 1483);
                step(f, Op::MulF, &[752, 753, 754], 1484);
                step(f, Op::LerpF, &[94, 915, 754, 755], 1485);
                step(f, Op::MulF, &[749, 755, 756], 1486);
                step(f, Op::QuatFromAxisAngle, &[494, 756, 62], 1487);
                step(f, Op::SubV, &[372, 371, 374], 1488);
                step(f, Op::RotateVector, &[62, 374, 375], 1489);
                step(f, Op::AddV, &[371, 375, 376], 1490);
                step(f, Op::RemapF, &[745, 92, 90, 93, 913, 129, 757], 1491);
                step(f, Op::MulF, &[757, 747, 758], 1492);
                step(f, Op::QuatFromAxisAngle, &[494, 758, 63], 1493);
                step(f, Op::RotateAroundPoint, &[87, 376, 63, 88], 1494);
                step(f, Op::RemapF, &[745, 96, 97, 913, 98, 129, 759], 1495);
                step(f, Op::RotateVector, &[57, 490, 377], 1496);
                step(f, Op::BreakVector, &[377, 760, 761, 762], 1497);
                step(f, Op::CosF, &[100, 764], 1498);
                step(f, Op::CosF, &[99, 763], 1499);
                step(f, Op::RemapF, &[762, 764, 763, 913, 915, 129, 765], 1500);
                step(f, Op::MulF, &[747, 765, 766], 1501);
                step(f, Op::MulF, &[759, 766, 767], 1502);
                step(f, Op::QuatFromAxisAngle, &[494, 767, 64], 1503);
                step(f, Op::RotateAroundPoint, &[88, 373, 64, 89], 1504);
                step(f, Op::SubF, &[915, 15, 768], 1505);
                step(f, Op::MulF, &[14, 768, 769], 1506);
                step(f, Op::LimitRotationAroundZ, &[57, 769, 102, 65], 1507);
                step(f, Op::RotateAroundPoint, &[89, 358, 65, 90], 1508);
                step(f, Op::BreakTransform, &[90, 378, 66, 379], 1509);
                step(f, Op::ArrayAt(Elem::Float), &[4, 3, 770], 1510);
                step(f, Op::MulF, &[770, 103, 771], 1511);
                step(f, Op::MulF, &[771, 104, 772], 1512);
                step(f, Op::AddF, &[771, 104, 773], 1513);
                step(f, Op::DivF, &[772, 773, 774], 1514);
                step(f, Op::MakeVector, &[913, 913, 774, 380], 1515);
                step(f, Op::AddV, &[378, 380, 381], 1516);
                step(f, Op::MakeTransform, &[381, 66, 379, 91], 1517);
                step(f, Op::ArraySetAt(Elem::Transform), &[7, 3, 91], 1518);
                step(f, Op::JumpIfFalse, &[8, 1523], 1519)
            }
            1519 => {
                step(f, Op::DrawPoint, &[373, 931, 494], 1520);
                step(f, Op::DrawPoint, &[371, 931, 491], 1521);
                step(f, Op::DrawPoint, &[376, 931, 490], 1522);
                step(f, Op::DrawTransform, &[82, 930, 914], 1523);
                1523
            }
            1523 => {
                step(f, Op::Jump, &[617], 1524)
            }
            1524 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1525);
                step(f, Op::Copy(ValueType::Int), &[71, 5], 1526);
                1526
            }
            1526 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 5, 1, 6, 7, 1565], 1527)
            }
            1527 => {
                step(f, Op::GetParent, &[1, 22], 1528);
                step(f, Op::GetParent, &[22, 23], 1529);
                step(f, Op::GetParent, &[23, 24], 1530);
                step(f, Op::GetTransform, &[24, 71, 130, 92], 1531);
                step(f, Op::BreakTransform, &[92, 382, 67, 383], 1532);
                step(f, Op::LengthV, &[1, 776], 1533);
                step(f, Op::ClavicleOffset, &[12, 776, 110, 114, 777], 1534);
                step(f, Op::MakeVector, &[913, 913, 777, 384], 1535);
                step(f, Op::AddV, &[382, 384, 385], 1536);
                step(f, Op::MakeTransform, &[385, 67, 487, 93], 1537);
                step(f, Op::SetTransform, &[24, 93, 71, 129, 915], 1538);
                step(f, Op::GetTransform, &[1, 71, 130, 94], 1539);
                step(f, Op::GetTransform, &[23, 71, 130, 95], 1540);
                step(f, Op::BreakTransform, &[95, 386, 69, 387], 1541);
                step(f, Op::Equals(Elem::Int), &[6, 71, 112], 1542);
                step(f, Op::Select(ValueType::Int), &[112, 72, 71, 62], 1543);
                step(f, Op::ArrayAt(Elem::Float), &[0, 62, 775], 1544);
                step(f, Op::ArmSwingRotation, &[775, 1, 0, 111, 922, 932, 915, 110, 108, 109, 112, 922, 915, 778], 1545);
                step(f, Op::QuatFromAxisAngle, &[494, 778, 68], 1546);
                step(f, Op::RotateAroundPoint, &[94, 386, 68, 96], 1547);
                step(f, Op::BreakTransform, &[96, 388, 70, 389], 1548);
                step(f, Op::RemapF, &[776, 913, 110, 913, 113, 129, 779], 1549);
                step(f, Op::MakeVector, &[913, 913, 779, 390], 1550);
                step(f, Op::AddV, &[388, 390, 391], 1551);
                step(f, Op::MakeTransform, &[391, 70, 487, 97], 1552);
                step(f, Op::Select(ValueType::Vec3), &[112, 495, 494, 393], 1553);
                step(f, Op::Select(ValueType::Vec3), &[112, 491, 496, 394], 1554);
                step(f, Op::ArrayAt(Elem::Vec3), &[4, 6, 392], 1555);
                step(f, Op::TwoBoneIK, &[23, 22, 1, 97, 393, 394, 392, 71, 915, 130, 933, 934, 129, 113, 780], 1556);
                step(f, Op::JumpIfFalse, &[8, 1564], 1557)
            }
            1557 => {
                step(f, Op::GetTransform, &[23, 71, 130, 95], 1558);
                step(f, Op::BreakTransform, &[95, 386, 69, 387], 1559);
                step(f, Op::GetTransform, &[1, 71, 130, 94], 1560);
                step(f, Op::RotateAroundPoint, &[94, 386, 68, 96], 1561);
                step(f, Op::BreakTransform, &[96, 388, 70, 389], 1562);
                step(f, Op::AddV, &[388, 390, 391], 1563);
                step(f, Op::DrawLine, &[386, 391, 914, 491], 1564);
                1564
            }
            1564 => {
                step(f, Op::Jump, &[1526], 1565)
            }
            1565 => {
                step(f, Op::NegF, &[3, 891], 1566);
                step(f, Op::MakeVector, &[913, 913, 891, 469], 1567);
                step(f, Op::MakeTransform, &[469, 98, 487, 118], 1568);
                step(f, Op::SetTransform, &[36, 118, 71, 129, 915], 1569);
                step(f, Op::Copy(ValueType::Float), &[920, 784], 1570);
                step(f, Op::Copy(ValueType::Bool), &[130, 114], 1571);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 11], 1572);
                step(f, Op::Copy(ValueType::Int), &[71, 63], 1573);
                step(f, Op::MakeVector, &[913, 913, 58, 397], 1574);
                1574
            }
            1574 => {
                step(f, Op::ForEachNext(Elem::Transform), &[11, 63, 98, 64, 65, 1586], 1575)
            }
            1575 => {
                step(f, Op::BreakTransform, &[98, 395, 71, 396], 1576);
                step(f, Op::AddV, &[395, 397, 398], 1577);
                step(f, Op::SubV, &[395, 397, 399], 1578);
                step(f, Op::SphereTrace, &[398, 399, 57, 115, 400, 401, 785], 1579);
                step(f, Op::BreakVector, &[400, 786, 787, 788], 1580);
                step(f, Op::LessF, &[788, 784, 116], 1581);
                step(f, Op::And, &[115, 116, 117], 1582);
                step(f, Op::JumpIfFalse, &[117, 1585], 1583)
            }
            1583 => {
                step(f, Op::Copy(ValueType::Float), &[788, 784], 1584);
                step(f, Op::Copy(ValueType::Bool), &[129, 114], 1585);
                1585
            }
            1585 => {
                step(f, Op::Jump, &[1574], 1586)
            }
            1586 => {
                step(f, Op::Select(ValueType::Float), &[114, 784, 913, 789], 1587);
                step(f, Op::ClampF, &[789, 63, 64, 790], 1588);
                step(f, Op::Copy(ValueType::Float), &[790, 783], 1589);
                step(f, Op::SubF, &[915, 21, 782], 1590);
                step(f, Op::MulF, &[783, 782, 791], 1591);
                step(f, Op::SubF, &[915, 134, 792], 1592);
                step(f, Op::MulF, &[3, 792, 793], 1593);
                step(f, Op::AddF, &[791, 793, 794], 1594);
                step(f, Op::MakeVector, &[16, 913, 913, 402], 1595);
                step(f, Op::MakeVector, &[794, 913, 913, 403], 1596);
                step(f, Op::Select(ValueType::Float), &[2, 794, 17, 795], 1597);
                step(f, Op::MakeVector, &[795, 913, 913, 404], 1598);
                step(f, Op::Copy(ValueType::Float), &[51, 796], 1599);
                step(f, Op::Copy(ValueType::Float), &[52, 797], 1600);
                step(f, Op::SubV, &[403, 404, 409], 1601);
                step(f, Op::DeltaTime, &[798], 1602);
                step(f, Op::DivF, &[797, 798, 799], 1603);
                step(f, Op::ScaleV, &[409, 799, 410], 1604);
                step(f, Op::AddV, &[403, 410, 411], 1605);
                step(f, Op::AddV, &[404, 410, 412], 1606);
                step(f, Op::SubV, &[402, 412, 413], 1607);
                step(f, Op::FloatLerp, &[913, 915, 796, 800], 1608);
                step(f, Op::SubF, &[915, 800, 801], 1609);
                step(f, Op::ScaleV, &[413, 801, 414], 1610);
                step(f, Op::AddV, &[411, 414, 416], 1611);
                step(f, Op::MulF, &[796, 798, 802], 1612);
                step(f, Op::GreaterF, &[802, 913, 118], 1613);
                step(f, Op::DivF, &[800, 802, 803], 1614);
                step(f, Op::Select(ValueType::Float), &[118, 803, 915, 804], 1615);
                step(f, Op::ScaleV, &[409, 804, 415], 1616);
                step(f, Op::SubV, &[416, 415, 417], 1617);
                step(f, Op::Copy(ValueType::Vec3), &[417, 408], 1618);
                step(f, Op::BreakVector, &[408, 805, 806, 807], 1619);
                step(f, Op::Select(ValueType::Float), &[1, 794, 805, 808], 1620);
                step(f, Op::Copy(ValueType::Float), &[808, 16], 1621);
                step(f, Op::Copy(ValueType::Float), &[794, 17], 1622);
                step(f, Op::GetTransform, &[37, 71, 129, 103], 1623);
                step(f, Op::BreakTransform, &[103, 430, 78, 431], 1624);
                step(f, Op::PelvisLean, &[1, 117, 122, 123, 826, 827], 1625);
                step(f, Op::LengthV, &[2, 781], 1626);
                step(f, Op::RemapF, &[781, 913, 117, 913, 115, 129, 809], 1627);
                step(f, Op::MulF, &[15, 116, 812], 1628);
                step(f, Op::SubF, &[915, 812, 813], 1629);
                step(f, Op::MulF, &[809, 813, 814], 1630);
                step(f, Op::MulF, &[12, 935, 810], 1631);
                step(f, Op::SinF, &[810, 811], 1632);
                step(f, Op::MulF, &[814, 811, 815], 1633);
                step(f, Op::MulF, &[815, 782, 816], 1634);
                step(f, Op::AddF, &[816, 16, 817], 1635);
                step(f, Op::SubF, &[817, 3, 818], 1636);
                step(f, Op::MakeVector, &[913, 827, 818, 432], 1637);
                step(f, Op::AddV, &[430, 432, 433], 1638);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 71, 99], 1639);
                step(f, Op::BreakTransform, &[99, 418, 72, 419], 1640);
                step(f, Op::BreakVector, &[418, 828, 829, 830], 1641);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 72, 100], 1642);
                step(f, Op::BreakTransform, &[100, 420, 73, 421], 1643);
                step(f, Op::BreakVector, &[420, 831, 832, 833], 1644);
                step(f, Op::SubF, &[830, 833, 834], 1645);
                step(f, Op::PelvisSideLean, &[834, 124, 125, 835], 1646);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 71, 101], 1647);
                step(f, Op::BreakTransform, &[101, 424, 74, 425], 1648);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 72, 102], 1649);
                step(f, Op::BreakTransform, &[102, 426, 75, 427], 1650);
                step(f, Op::SlerpQ, &[74, 75, 914, 76], 1651);
                step(f, Op::EulerFromQuat, &[76, 71, 428], 1652);
                step(f, Op::BreakVector, &[428, 822, 823, 824], 1653);
                step(f, Op::RemapF, &[781, 118, 117, 913, 119, 129, 820], 1654);
                step(f, Op::SubV, &[418, 420, 422], 1655);
                step(f, Op::RotateVector, &[0, 491, 423], 1656);
                step(f, Op::DotV, &[422, 423, 819], 1657);
                step(f, Op::MulF, &[820, 819, 821], 1658);
                step(f, Op::AddF, &[824, 821, 825], 1659);
                step(f, Op::MakeVector, &[826, 835, 825, 429], 1660);
                step(f, Op::QuatFromEuler, &[429, 71, 77], 1661);
                step(f, Op::MakeTransform, &[433, 77, 487, 104], 1662);
                step(f, Op::SetTransform, &[38, 104, 71, 129, 915], 1663);
                step(f, Op::GetTransform, &[39, 72, 129, 105], 1664);
                step(f, Op::BreakTransform, &[105, 434, 82, 435], 1665);
                step(f, Op::QuatFromAxisAngle, &[490, 821, 79], 1666);
                step(f, Op::DivF, &[120, 931, 836], 1667);
                step(f, Op::QuatScale, &[79, 836, 80], 1668);
                step(f, Op::MulQ, &[82, 80, 86], 1669);
                step(f, Op::MakeTransform, &[434, 86, 487, 109], 1670);
                step(f, Op::SetTransform, &[40, 109, 72, 129, 915], 1671);
                step(f, Op::GetTransform, &[41, 72, 129, 106], 1672);
                step(f, Op::BreakTransform, &[106, 436, 83, 437], 1673);
                step(f, Op::MulQ, &[83, 80, 87], 1674);
                step(f, Op::MakeTransform, &[436, 87, 487, 110], 1675);
                step(f, Op::SetTransform, &[42, 110, 72, 129, 915], 1676);
                step(f, Op::GetTransform, &[43, 72, 129, 107], 1677);
                step(f, Op::BreakTransform, &[107, 438, 84, 439], 1678);
                step(f, Op::MulQ, &[84, 80, 88], 1679);
                step(f, Op::MakeTransform, &[438, 88, 487, 111], 1680);
                step(f, Op::SetTransform, &[44, 111, 72, 129, 915], 1681);
                step(f, Op::GetTransform, &[45, 72, 129, 108], 1682);
                step(f, Op::BreakTransform, &[108, 440, 85, 441], 1683);
                step(f, Op::QuatScale, &[79, 121, 81], 1684);
                step(f, Op::MulQ, &[85, 81, 89], 1685);
                step(f, Op::MakeTransform, &[440, 89, 487, 112], 1686);
                step(f, Op::SetTransform, &[46, 112, 72, 129, 915], 1687);
                step(f, Op::Or, &[1, 2, 124], 1688);
                step(f, Op::Copy(ValueType::Float), &[913, 838], 1689);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1690);
                step(f, Op::Copy(ValueType::Int), &[71, 66], 1691);
                1691
            }
            1691 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 66, 25, 67, 68, 1738], 1692)
            }
            1692 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 67, 119], 1693);
                step(f, Op::GetParent, &[25, 26], 1694);
                step(f, Op::GetParent, &[26, 27], 1695);
                step(f, Op::GetTransform, &[27, 71, 130, 113], 1696);
                step(f, Op::BreakTransform, &[113, 442, 90, 443], 1697);
                step(f, Op::BreakVector, &[442, 839, 840, 841], 1698);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 67, 114], 1699);
                step(f, Op::BreakTransform, &[114, 444, 91, 445], 1700);
                step(f, Op::BreakVector, &[444, 842, 843, 844], 1701);
                step(f, Op::ArrayAt(Elem::Float), &[1, 67, 848], 1702);
                step(f, Op::MulF, &[848, 126, 849], 1703);
                step(f, Op::MulF, &[849, 849, 850], 1704);
                step(f, Op::SubF, &[839, 842, 845], 1705);
                step(f, Op::SubF, &[840, 843, 846], 1706);
                step(f, Op::MakeVector, &[845, 846, 913, 446], 1707);
                step(f, Op::DotV, &[446, 446, 847], 1708);
                step(f, Op::SubF, &[850, 847, 851], 1709);
                step(f, Op::SqrtF, &[851, 852], 1710);
                step(f, Op::AddF, &[844, 852, 853], 1711);
                step(f, Op::SubF, &[841, 853, 854], 1712);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 67, 115], 1713);
                step(f, Op::BreakTransform, &[115, 447, 92, 448], 1714);
                step(f, Op::BreakVector, &[447, 855, 856, 857], 1715);
                step(f, Op::AddF, &[857, 53, 858], 1716);
                step(f, Op::MinF, &[844, 858, 859], 1717);
                step(f, Op::AddF, &[859, 852, 860], 1718);
                step(f, Op::SubF, &[841, 860, 861], 1719);
                step(f, Op::Equals(Elem::Int), &[67, 71, 120], 1720);
                step(f, Op::Select(ValueType::Int), &[120, 72, 71, 69], 1721);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 69, 121], 1722);
                step(f, Op::ArrayAt(Elem::Float), &[2, 69, 865], 1723);
                step(f, Op::RemapF, &[865, 914, 915, 913, 915, 129, 866], 1724);
                step(f, Op::RemapF, &[865, 913, 129, 915, 913, 129, 867], 1725);
                step(f, Op::MaxF, &[866, 867, 868], 1726);
                step(f, Op::Select(ValueType::Float), &[121, 915, 868, 869], 1727);
                step(f, Op::LerpF, &[854, 861, 869, 870], 1728);
                step(f, Op::ArrayAt(Elem::Float), &[2, 67, 862], 1729);
                step(f, Op::RemapF, &[862, 914, 915, 913, 915, 129, 863], 1730);
                step(f, Op::MulF, &[870, 863, 871], 1731);
                step(f, Op::RemapF, &[862, 913, 129, 915, 913, 129, 864], 1732);
                step(f, Op::MulF, &[854, 864, 872], 1733);
                step(f, Op::MaxF, &[871, 872, 873], 1734);
                step(f, Op::Select(ValueType::Float), &[119, 854, 873, 874], 1735);
                step(f, Op::MaxF, &[838, 874, 875], 1736);
                step(f, Op::Copy(ValueType::Float), &[875, 838], 1737);
                step(f, Op::Jump, &[1691], 1738)
            }
            1738 => {
                step(f, Op::ClampF, &[838, 913, 127, 876], 1739);
                step(f, Op::Copy(ValueType::Float), &[876, 837], 1740);
                step(f, Op::MakeVector, &[18, 913, 913, 449], 1741);
                step(f, Op::MakeVector, &[837, 913, 913, 450], 1742);
                step(f, Op::MakeVector, &[19, 913, 913, 451], 1743);
                step(f, Op::GreaterF, &[837, 18, 122], 1744);
                step(f, Op::Select(ValueType::Float), &[122, 131, 128, 877], 1745);
                step(f, Op::Copy(ValueType::Float), &[52, 879], 1746);
                step(f, Op::SubV, &[450, 451, 456], 1747);
                step(f, Op::DeltaTime, &[880], 1748);
                step(f, Op::DivF, &[879, 880, 881], 1749);
                step(f, Op::ScaleV, &[456, 881, 457], 1750);
                step(f, Op::AddV, &[450, 457, 458], 1751);
                step(f, Op::AddV, &[451, 457, 459], 1752);
                step(f, Op::SubV, &[449, 459, 460], 1753);
                step(f, Op::FloatLerp, &[913, 915, 877, 882], 1754);
                step(f, Op::SubF, &[915, 882, 883], 1755);
                step(f, Op::ScaleV, &[460, 883, 461], 1756);
                step(f, Op::AddV, &[458, 461, 463], 1757);
                step(f, Op::MulF, &[877, 880, 884], 1758);
                step(f, Op::GreaterF, &[884, 913, 123], 1759);
                step(f, Op::DivF, &[882, 884, 885], 1760);
                step(f, Op::Select(ValueType::Float), &[123, 885, 915, 886], 1761);
                step(f, Op::ScaleV, &[456, 886, 462], 1762);
                step(f, Op::SubV, &[463, 462, 464], 1763);
                step(f, Op::Copy(ValueType::Vec3), &[464, 455], 1764);
                step(f, Op::BreakVector, &[455, 887, 888, 889], 1765);
                step(f, Op::Select(ValueType::Float), &[124, 837, 887, 890], 1766);
                step(f, Op::Copy(ValueType::Float), &[890, 18], 1767);
                step(f, Op::Copy(ValueType::Float), &[837, 19], 1768);
                step(f, Op::GetTransform, &[47, 71, 130, 116], 1769);
                step(f, Op::BreakTransform, &[116, 465, 93, 466], 1770);
                step(f, Op::MakeVector, &[913, 913, 18, 467], 1771);
                step(f, Op::SubV, &[465, 467, 468], 1772);
                step(f, Op::MakeTransform, &[468, 93, 487, 117], 1773);
                step(f, Op::SetTransform, &[48, 117, 71, 129, 915], 1774);
                step(f, Op::JumpIfFalse, &[8, 1780], 1775)
            }
            1775 => {
                step(f, Op::GetTransform, &[47, 71, 130, 116], 1776);
                step(f, Op::BreakTransform, &[116, 465, 93, 466], 1777);
                step(f, Op::SubV, &[465, 467, 468], 1778);
                step(f, Op::MakeTransform, &[468, 93, 487, 117], 1779);
                step(f, Op::DrawTransform, &[117, 936, 914], 1780);
                1780
            }
            1780 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1781);
                step(f, Op::Copy(ValueType::Int), &[71, 8], 1782);
                1782
            }
            1782 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 8, 2, 9, 10, 1830], 1783)
            }
            1783 => {
                step(f, Op::GetParent, &[2, 29], 1784);
                step(f, Op::GetParent, &[29, 30], 1785);
                step(f, Op::GetTransform, &[30, 71, 130, 119], 1786);
                step(f, Op::BreakTransform, &[119, 470, 94, 471], 1787);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 9, 120], 1788);
                step(f, Op::BreakTransform, &[120, 472, 95, 473], 1789);
                step(f, Op::SubV, &[472, 470, 474], 1790);
                step(f, Op::LengthV, &[474, 903], 1791);
                step(f, Op::ArrayAt(Elem::Float), &[1, 9, 892], 1792);
                step(f, Op::MulF, &[892, 138, 893], 1793);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 9, 125], 1794);
                step(f, Op::ArrayAt(Elem::Float), &[2, 9, 894], 1795);
                step(f, Op::ClampF, &[894, 913, 915, 895], 1796);
                step(f, Op::LessF, &[895, 914, 126], 1797);
                step(f, Op::SmoothStepF, &[895, 140, 141, 898], 1798);
                step(f, Op::MulF, &[895, 923, 896], 1799);
                step(f, Op::SinF, &[896, 897], 1800);
                step(f, Op::MaxF, &[898, 897, 899], 1801);
                step(f, Op::Select(ValueType::Float), &[126, 899, 897, 900], 1802);
                step(f, Op::MulF, &[900, 139, 901], 1803);
                step(f, Op::Select(ValueType::Float), &[125, 913, 901, 902], 1804);
                step(f, Op::SubF, &[893, 902, 904], 1805);
                step(f, Op::SubF, &[903, 904, 905], 1806);
                step(f, Op::MaxF, &[905, 913, 906], 1807);
                step(f, Op::MulF, &[906, 906, 907], 1808);
                step(f, Op::AddF, &[906, 902, 908], 1809);
                step(f, Op::DivF, &[907, 908, 909], 1810);
                step(f, Op::SubF, &[903, 909, 910], 1811);
                step(f, Op::DivF, &[910, 903, 911], 1812);
                step(f, Op::ScaleV, &[474, 911, 475], 1813);
                step(f, Op::AddV, &[470, 475, 476], 1814);
                step(f, Op::ClampSpatially, &[476, 470, 913, 893, 477], 1815);
                step(f, Op::MakeTransform, &[477, 95, 487, 121], 1816);
                step(f, Op::Equals(Elem::Int), &[9, 71, 127], 1817);
                step(f, Op::Select(ValueType::Vec3), &[127, 495, 494, 482], 1818);
                step(f, Op::Select(ValueType::Vec3), &[127, 491, 496, 483], 1819);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 9, 122], 1820);
                step(f, Op::BreakTransform, &[122, 478, 96, 479], 1821);
                step(f, Op::ArrayAt(Elem::Vec3), &[3, 9, 480], 1822);
                step(f, Op::KneeVector, &[96, 0, 480, 142, 143, 481], 1823);
                step(f, Op::TwoBoneIK, &[30, 29, 2, 121, 482, 483, 481, 71, 915, 130, 933, 934, 129, 128, 912], 1824);
                step(f, Op::JumpIfFalse, &[8, 1829], 1825)
            }
            1825 => {
                step(f, Op::GetTransform, &[29, 71, 130, 123], 1826);
                step(f, Op::BreakTransform, &[123, 484, 97, 485], 1827);
                step(f, Op::AddV, &[484, 481, 486], 1828);
                step(f, Op::DrawLine, &[484, 486, 914, 497], 1829);
                1829
            }
            1829 => {
                step(f, Op::Jump, &[1782], 1830)
            }
            1830 => {
                step(f, Op::End, &[], 1831)
            }
            _ => return,
        } };
    }
}
