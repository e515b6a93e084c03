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
    fingerprint: 0x3c2ea51a675bbfda,
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
                step(f, Op::LengthV, &[37, 150], 113);
                step(f, Op::GreaterF, &[150, 35, 10], 114);
                step(f, Op::Copy(ValueType::Bool), &[10, 2], 115);
                step(f, Op::MakeRelative, &[13, 12, 17], 116);
                step(f, Op::Select(ValueType::Transform), &[10, 121, 17, 18], 117);
                step(f, Op::Copy(ValueType::Transform), &[18, 2], 118);
                step(f, Op::InverseT, &[13, 15], 119);
                step(f, Op::MulT, &[12, 15, 16], 120);
                step(f, Op::Copy(ValueType::Transform), &[16, 1], 121);
                step(f, Op::TransformVector, &[2, 0, 42], 122);
                step(f, Op::InverseT, &[12, 14], 123);
                step(f, Op::DeltaTime, &[149], 124);
                step(f, Op::DivF, &[908, 149, 151], 125);
                step(f, Op::ScaleV, &[37, 151, 38], 126);
                step(f, Op::TransformVector, &[14, 38, 39], 127);
                step(f, Op::BreakVector, &[39, 152, 153, 154], 128);
                step(f, Op::MakeVector, &[152, 153, 906, 40], 129);
                step(f, Op::LengthV, &[40, 155], 130);
                step(f, Op::MulF, &[155, 131, 156], 131);
                step(f, Op::NegF, &[156, 157], 132);
                step(f, Op::ClampF, &[154, 157, 156, 158], 133);
                step(f, Op::MakeVector, &[152, 153, 158, 41], 134);
                step(f, Op::Select(ValueType::Vec3), &[2, 42, 41, 44], 135);
                step(f, Op::VectorLerp, &[42, 44, 36, 906, 45], 136);
                step(f, Op::Copy(ValueType::Vec3), &[45, 0], 137);
                step(f, Op::TransformVector, &[2, 1, 43], 138);
                step(f, Op::TransformVector, &[2, 0, 42], 139);
                step(f, Op::Select(ValueType::Vec3), &[2, 42, 41, 44], 140);
                step(f, Op::VectorLerp, &[43, 44, 37, 906, 46], 141);
                step(f, Op::Copy(ValueType::Vec3), &[46, 1], 142);
                step(f, Op::LengthV, &[44, 165], 143);
                step(f, Op::Copy(ValueType::Float), &[165, 0], 144);
                step(f, Op::BreakVector, &[37, 159, 160, 161], 145);
                step(f, Op::MulF, &[158, 149, 162], 146);
                step(f, Op::SubF, &[161, 162, 163], 147);
                step(f, Op::Select(ValueType::Float), &[10, 906, 163, 164], 148);
                step(f, Op::Copy(ValueType::Float), &[164, 1], 149);
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
                step(f, Op::Copy(ValueType::Float), &[906, 16], 163);
                163
            }
            163 => {
                step(f, Op::Copy(ValueType::Transform), &[12, 0], 164);
                step(f, Op::Copy(ValueType::Bool), &[128, 0], 165);
                step(f, Op::JumpIfFalse, &[8, 171], 166)
            }
            166 => {
                step(f, Op::GetTransform, &[33, 71, 128, 19], 167);
                step(f, Op::BreakTransform, &[19, 47, 9, 48], 168);
                step(f, Op::ScaleV, &[0, 909, 49], 169);
                step(f, Op::AddV, &[47, 49, 50], 170);
                step(f, Op::DrawArrow, &[47, 50, 907, 479], 171);
                171
            }
            171 => {
                step(f, Op::Copy(ValueType::Float), &[906, 166], 172);
                step(f, Op::Copy(ValueType::Float), &[908, 167], 173);
                step(f, Op::Copy(ValueType::Bool), &[129, 12], 174);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[8, 9], 175);
                step(f, Op::Copy(ValueType::Int), &[71, 25], 176);
                step(f, Op::MakeVector, &[906, 906, 58, 55], 177);
                177
            }
            177 => {
                step(f, Op::ForEachNext(Elem::Transform), &[9, 25, 21, 26, 27, 187], 178)
            }
            178 => {
                step(f, Op::BreakTransform, &[21, 51, 10, 52], 179);
                step(f, Op::TransformPoint, &[2, 51, 53], 180);
                step(f, Op::LerpV, &[53, 51, 908, 54], 181);
                step(f, Op::AddV, &[54, 55, 56], 182);
                step(f, Op::SubV, &[54, 55, 57], 183);
                step(f, Op::LineTrace, &[56, 57, 13, 58, 59, 169], 184);
                step(f, Op::JumpIfFalse, &[13, 186], 185)
            }
            185 => {
                step(f, Op::Copy(ValueType::Bool), &[128, 12], 186);
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
                step(f, Op::AddF, &[166, 167, 170], 197);
                step(f, Op::MulF, &[170, 907, 171], 198);
                step(f, Op::Copy(ValueType::Bool), &[129, 18], 199);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[8, 10], 200);
                step(f, Op::Copy(ValueType::Int), &[71, 28], 201);
                step(f, Op::MakeVector, &[906, 906, 58, 64], 202);
                202
            }
            202 => {
                step(f, Op::ForEachNext(Elem::Transform), &[10, 28, 22, 29, 30, 212], 203)
            }
            203 => {
                step(f, Op::BreakTransform, &[22, 60, 11, 61], 204);
                step(f, Op::TransformPoint, &[2, 60, 62], 205);
                step(f, Op::LerpV, &[62, 60, 171, 63], 206);
                step(f, Op::AddV, &[63, 64, 65], 207);
                step(f, Op::SubV, &[63, 64, 66], 208);
                step(f, Op::LineTrace, &[65, 66, 19, 67, 68, 173], 209);
                step(f, Op::JumpIfFalse, &[19, 211], 210)
            }
            210 => {
                step(f, Op::Copy(ValueType::Bool), &[128, 18], 211);
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
                step(f, Op::Copy(ValueType::Float), &[171, 166], 216);
                step(f, Op::Jump, &[218], 217)
            }
            217 => {
                step(f, Op::Copy(ValueType::Float), &[171, 167], 218);
                218
            }
            218 => {
                step(f, Op::Jump, &[195], 219)
            }
            219 => {
                step(f, Op::Select(ValueType::Float), &[5, 910, 908, 179], 220);
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 221);
                step(f, Op::AddF, &[166, 167, 170], 222);
                step(f, Op::MulF, &[170, 907, 174], 223);
                step(f, Op::Select(ValueType::Float), &[16, 174, 907, 175], 224);
                step(f, Op::Select(ValueType::Float), &[15, 175, 906, 181], 225);
                step(f, Op::MulF, &[179, 181, 183], 226);
                step(f, Op::DeltaTime, &[177], 227);
                step(f, Op::DivF, &[177, 135, 178], 228);
                step(f, Op::MulF, &[183, 178, 184], 229);
                step(f, Op::AddF, &[20, 184, 185], 230);
                step(f, Op::ClampF, &[185, 906, 908, 186], 231);
                step(f, Op::Select(ValueType::Float), &[14, 910, 908, 180], 232);
                step(f, Op::SubF, &[908, 175, 176], 233);
                step(f, Op::Select(ValueType::Float), &[15, 176, 908, 182], 234);
                step(f, Op::MulF, &[180, 182, 187], 235);
                step(f, Op::MulF, &[187, 178, 188], 236);
                step(f, Op::AddF, &[186, 188, 189], 237);
                step(f, Op::ClampF, &[189, 906, 908, 190], 238);
                step(f, Op::SmoothStepF, &[190, 906, 908, 191], 239);
                step(f, Op::AddF, &[21, 191, 192], 240);
                step(f, Op::MulF, &[192, 907, 193], 241);
                step(f, Op::SubF, &[908, 193, 194], 242);
                step(f, Op::MulF, &[194, 194, 195], 243);
                step(f, Op::SubF, &[908, 195, 196], 244);
                step(f, Op::Copy(ValueType::Float), &[196, 22], 245);
                step(f, Op::Copy(ValueType::Float), &[191, 21], 246);
                step(f, Op::Copy(ValueType::Float), &[190, 20], 247);
                step(f, Op::GreaterF, &[21, 906, 21], 248);
                step(f, Op::TransformVector, &[2, 3, 69], 249);
                step(f, Op::Select(ValueType::Vec3), &[21, 69, 0, 70], 250);
                step(f, Op::Copy(ValueType::Vec3), &[70, 3], 251);
                step(f, Op::LerpV, &[0, 3, 21, 71], 252);
                step(f, Op::Select(ValueType::Vec3), &[21, 71, 0, 72], 253);
                step(f, Op::Copy(ValueType::Vec3), &[72, 2], 254);
                step(f, Op::Copy(ValueType::Bool), &[14, 5], 255);
                step(f, Op::Copy(ValueType::Bool), &[11, 6], 256);
                step(f, Op::Copy(ValueType::Bool), &[129, 7], 257);
                step(f, Op::SubF, &[908, 22, 197], 258);
                step(f, Op::MulF, &[1, 197, 198], 259);
                step(f, Op::AddF, &[2, 198, 199], 260);
                step(f, Op::Copy(ValueType::Float), &[4, 200], 261);
                step(f, Op::Copy(ValueType::Float), &[5, 201], 262);
                step(f, Op::Copy(ValueType::Float), &[2, 203], 263);
                step(f, Op::Copy(ValueType::Float), &[132, 204], 264);
                step(f, Op::Copy(ValueType::Float), &[52, 205], 265);
                step(f, Op::SubF, &[199, 203, 210], 266);
                step(f, Op::DeltaTime, &[208], 267);
                step(f, Op::DivF, &[210, 208, 211], 268);
                step(f, Op::MulF, &[211, 205, 212], 269);
                step(f, Op::AddF, &[199, 212, 214], 270);
                step(f, Op::MulF, &[211, 911, 215], 271);
                step(f, Op::DivF, &[912, 204, 209], 272);
                step(f, Op::DivF, &[215, 209, 216], 273);
                step(f, Op::SubF, &[214, 216, 230], 274);
                step(f, Op::AddF, &[203, 212, 213], 275);
                step(f, Op::SubF, &[200, 213, 217], 276);
                step(f, Op::AddF, &[217, 216, 218], 277);
                step(f, Op::SubF, &[201, 211, 219], 278);
                step(f, Op::MulF, &[209, 218, 220], 279);
                step(f, Op::AddF, &[219, 220, 221], 280);
                step(f, Op::MulF, &[221, 208, 224], 281);
                step(f, Op::AddF, &[218, 224, 225], 282);
                step(f, Op::FloatLerp, &[906, 908, 209, 222], 283);
                step(f, Op::SubF, &[908, 222, 223], 284);
                step(f, Op::MulF, &[225, 223, 226], 285);
                step(f, Op::AddF, &[230, 226, 231], 286);
                step(f, Op::Copy(ValueType::Float), &[231, 206], 287);
                step(f, Op::MulF, &[209, 224, 227], 288);
                step(f, Op::SubF, &[219, 227, 228], 289);
                step(f, Op::MulF, &[228, 223, 229], 290);
                step(f, Op::AddF, &[211, 229, 232], 291);
                step(f, Op::Copy(ValueType::Float), &[232, 207], 292);
                step(f, Op::SubF, &[199, 206, 233], 293);
                step(f, Op::Copy(ValueType::Float), &[233, 3], 294);
                step(f, Op::Copy(ValueType::Float), &[206, 4], 295);
                step(f, Op::Copy(ValueType::Float), &[4, 200], 296);
                step(f, Op::Copy(ValueType::Float), &[5, 201], 297);
                step(f, Op::Copy(ValueType::Float), &[2, 203], 298);
                step(f, Op::Copy(ValueType::Float), &[132, 204], 299);
                step(f, Op::Copy(ValueType::Float), &[52, 205], 300);
                step(f, Op::SubF, &[199, 203, 210], 301);
                step(f, Op::DeltaTime, &[208], 302);
                step(f, Op::DivF, &[210, 208, 211], 303);
                step(f, Op::MulF, &[211, 205, 212], 304);
                step(f, Op::AddF, &[199, 212, 214], 305);
                step(f, Op::MulF, &[211, 911, 215], 306);
                step(f, Op::DivF, &[912, 204, 209], 307);
                step(f, Op::DivF, &[215, 209, 216], 308);
                step(f, Op::SubF, &[214, 216, 230], 309);
                step(f, Op::AddF, &[203, 212, 213], 310);
                step(f, Op::SubF, &[200, 213, 217], 311);
                step(f, Op::AddF, &[217, 216, 218], 312);
                step(f, Op::SubF, &[201, 211, 219], 313);
                step(f, Op::MulF, &[209, 218, 220], 314);
                step(f, Op::AddF, &[219, 220, 221], 315);
                step(f, Op::MulF, &[221, 208, 224], 316);
                step(f, Op::AddF, &[218, 224, 225], 317);
                step(f, Op::FloatLerp, &[906, 908, 209, 222], 318);
                step(f, Op::SubF, &[908, 222, 223], 319);
                step(f, Op::MulF, &[225, 223, 226], 320);
                step(f, Op::AddF, &[230, 226, 231], 321);
                step(f, Op::Copy(ValueType::Float), &[231, 206], 322);
                step(f, Op::MulF, &[209, 224, 227], 323);
                step(f, Op::SubF, &[219, 227, 228], 324);
                step(f, Op::MulF, &[228, 223, 229], 325);
                step(f, Op::AddF, &[211, 229, 232], 326);
                step(f, Op::Copy(ValueType::Float), &[232, 207], 327);
                step(f, Op::Copy(ValueType::Float), &[207, 5], 328);
                step(f, Op::Copy(ValueType::Float), &[199, 2], 329);
                step(f, Op::LengthV, &[4, 235], 330);
                step(f, Op::GreaterF, &[235, 29, 22], 331);
                step(f, Op::LengthV, &[2, 236], 332);
                step(f, Op::GreaterF, &[236, 29, 23], 333);
                step(f, Op::And, &[22, 23, 25], 334);
                step(f, Op::Select(ValueType::Vec3), &[22, 4, 478, 73], 335);
                step(f, Op::MovementAngleOffset, &[73, 14, 906, 913, 913, 914, 40, 915, 237], 336);
                step(f, Op::Copy(ValueType::Float), &[14, 240], 337);
                step(f, Op::SubF, &[237, 240, 242], 338);
                step(f, Op::AddF, &[242, 916, 243], 339);
                step(f, Op::DivF, &[243, 917, 244], 340);
                step(f, Op::FractF, &[244, 245], 341);
                step(f, Op::MulF, &[245, 917, 246], 342);
                step(f, Op::SubF, &[246, 916, 247], 343);
                step(f, Op::Copy(ValueType::Float), &[247, 241], 344);
                step(f, Op::AbsF, &[241, 266], 345);
                step(f, Op::Select(ValueType::Vec3), &[23, 2, 478, 74], 346);
                step(f, Op::MovementAngleOffset, &[74, 14, 906, 913, 913, 914, 40, 915, 238], 347);
                step(f, Op::Copy(ValueType::Float), &[14, 249], 348);
                step(f, Op::SubF, &[238, 249, 251], 349);
                step(f, Op::AddF, &[251, 916, 252], 350);
                step(f, Op::DivF, &[252, 917, 253], 351);
                step(f, Op::FractF, &[253, 254], 352);
                step(f, Op::MulF, &[254, 917, 255], 353);
                step(f, Op::SubF, &[255, 916, 256], 354);
                step(f, Op::Copy(ValueType::Float), &[256, 250], 355);
                step(f, Op::AbsF, &[250, 267], 356);
                step(f, Op::MaxF, &[266, 267, 269], 357);
                step(f, Op::SubF, &[238, 237, 260], 358);
                step(f, Op::AddF, &[260, 916, 261], 359);
                step(f, Op::DivF, &[261, 917, 262], 360);
                step(f, Op::FractF, &[262, 263], 361);
                step(f, Op::MulF, &[263, 917, 264], 362);
                step(f, Op::SubF, &[264, 916, 265], 363);
                step(f, Op::Copy(ValueType::Float), &[265, 259], 364);
                step(f, Op::AbsF, &[259, 268], 365);
                step(f, Op::MaxF, &[269, 268, 270], 366);
                step(f, Op::LessF, &[270, 918, 24], 367);
                step(f, Op::And, &[25, 24, 26], 368);
                step(f, Op::Not, &[22, 27], 369);
                step(f, Op::Not, &[23, 28], 370);
                step(f, Op::And, &[27, 28, 29], 371);
                step(f, Op::Or, &[26, 29, 30], 372);
                step(f, Op::JumpIfFalse, &[30, 394], 373)
            }
            373 => {
                step(f, Op::DeltaTime, &[234], 374);
                step(f, Op::MulF, &[38, 234, 274], 375);
                step(f, Op::GreaterF, &[274, 906, 31], 376);
                step(f, Op::DivF, &[52, 234, 271], 377);
                step(f, Op::FloatLerp, &[906, 908, 38, 272], 378);
                step(f, Op::SubF, &[908, 272, 273], 379);
                step(f, Op::DivF, &[273, 272, 275], 380);
                step(f, Op::DivF, &[908, 274, 276], 381);
                step(f, Op::SubF, &[275, 276, 277], 382);
                step(f, Op::AddF, &[271, 277, 278], 383);
                step(f, Op::Select(ValueType::Float), &[31, 278, 906, 279], 384);
                step(f, Op::MulF, &[259, 279, 280], 385);
                step(f, Op::AddF, &[238, 280, 281], 386);
                step(f, Op::SinF, &[281, 282], 387);
                step(f, Op::NegF, &[282, 283], 388);
                step(f, Op::CosF, &[281, 284], 389);
                step(f, Op::MakeVector, &[283, 284, 906, 75], 390);
                step(f, Op::Select(ValueType::Vec3), &[23, 75, 478, 76], 391);
                step(f, Op::MovementAngleOffset, &[76, 14, 906, 38, 39, 914, 916, 915, 285], 392);
                step(f, Op::Copy(ValueType::Float), &[285, 14], 393);
                step(f, Op::Jump, &[450], 394)
            }
            394 => {
                step(f, Op::DeltaTime, &[234], 395);
                step(f, Op::DivF, &[234, 42, 286], 396);
                step(f, Op::AddF, &[286, 907, 287], 397);
                step(f, Op::FloorF, &[287, 288], 398);
                step(f, Op::MaxF, &[288, 908, 289], 399);
                step(f, Op::ToInt, &[289, 36], 400);
                step(f, Op::Copy(ValueType::Int), &[36, 35], 401);
                step(f, Op::Copy(ValueType::Int), &[71, 31], 402);
                step(f, Op::MulF, &[42, 907, 293], 403);
                step(f, Op::SubF, &[52, 293, 294], 404);
                step(f, Op::DivF, &[294, 234, 295], 405);
                step(f, Op::FloatLerp, &[906, 908, 36, 297], 406);
                step(f, Op::GreaterF, &[297, 906, 32], 407);
                step(f, Op::DivF, &[38, 289, 307], 408);
                step(f, Op::DivF, &[39, 289, 308], 409);
                step(f, Op::SubF, &[914, 41, 320], 410);
                step(f, Op::GreaterF, &[41, 906, 35], 411);
                411
            }
            411 => {
                step(f, Op::ForNext, &[31, 35, 33, 450], 412)
            }
            412 => {
                step(f, Op::ToFloat, &[33, 290], 413);
                step(f, Op::AddF, &[290, 908, 291], 414);
                step(f, Op::DivF, &[291, 289, 292], 415);
                step(f, Op::AddF, &[292, 295, 296], 416);
                step(f, Op::MulF, &[36, 296, 298], 417);
                step(f, Op::FloatLerp, &[906, 908, 298, 299], 418);
                step(f, Op::DivF, &[299, 297, 300], 419);
                step(f, Op::Select(ValueType::Float), &[32, 300, 296, 301], 420);
                step(f, Op::LerpV, &[4, 2, 301, 77], 421);
                step(f, Op::LengthV, &[77, 302], 422);
                step(f, Op::GreaterF, &[302, 29, 33], 423);
                step(f, Op::Select(ValueType::Vec3), &[33, 77, 478, 78], 424);
                step(f, Op::MulF, &[234, 296, 303], 425);
                step(f, Op::MulF, &[8, 303, 304], 426);
                step(f, Op::AddF, &[12, 304, 305], 427);
                step(f, Op::FractF, &[305, 306], 428);
                step(f, Op::MulF, &[306, 911, 324], 429);
                step(f, Op::FractF, &[324, 325], 430);
                step(f, Op::LessF, &[325, 915, 36], 431);
                step(f, Op::MovementAngleOffset, &[78, 14, 906, 913, 913, 914, 40, 915, 309], 432);
                step(f, Op::Copy(ValueType::Float), &[14, 311], 433);
                step(f, Op::SubF, &[309, 311, 313], 434);
                step(f, Op::AddF, &[313, 916, 314], 435);
                step(f, Op::DivF, &[314, 917, 315], 436);
                step(f, Op::FractF, &[315, 316], 437);
                step(f, Op::MulF, &[316, 917, 317], 438);
                step(f, Op::SubF, &[317, 916, 318], 439);
                step(f, Op::Copy(ValueType::Float), &[318, 312], 440);
                step(f, Op::AbsF, &[312, 319], 441);
                step(f, Op::SmoothStepF, &[319, 320, 914, 321], 442);
                step(f, Op::GreaterF, &[319, 914, 34], 443);
                step(f, Op::Select(ValueType::Float), &[34, 908, 906, 322], 444);
                step(f, Op::Select(ValueType::Float), &[35, 321, 322, 323], 445);
                step(f, Op::Select(ValueType::Float), &[36, 906, 323, 326], 446);
                step(f, Op::LerpF, &[307, 308, 326, 327], 447);
                step(f, Op::MovementAngleOffset, &[78, 14, 306, 327, 327, 914, 40, 915, 328], 448);
                step(f, Op::Copy(ValueType::Float), &[328, 14], 449);
                step(f, Op::Jump, &[411], 450)
            }
            450 => {
                step(f, Op::QuatFromAxisAngle, &[480, 14, 12], 451);
                step(f, Op::Copy(ValueType::Quat), &[12, 0], 452);
                step(f, Op::SinF, &[14, 329], 453);
                step(f, Op::AbsF, &[329, 330], 454);
                step(f, Op::RemapF, &[330, 43, 44, 906, 908, 128, 331], 455);
                step(f, Op::BreakVector, &[74, 332, 333, 334], 456);
                step(f, Op::AbsF, &[332, 335], 457);
                step(f, Op::DivF, &[335, 236, 336], 458);
                step(f, Op::RemapF, &[336, 43, 44, 906, 908, 128, 337], 459);
                step(f, Op::TransformVector, &[2, 481, 79], 460);
                step(f, Op::DistanceV, &[79, 481, 338], 461);
                step(f, Op::DivF, &[338, 234, 339], 462);
                step(f, Op::RemapF, &[339, 48, 49, 908, 906, 128, 340], 463);
                step(f, Op::MulF, &[337, 340, 341], 464);
                step(f, Op::MaxF, &[331, 341, 342], 465);
                step(f, Op::Copy(ValueType::Float), &[342, 15], 466);
                step(f, Op::Copy(ValueType::Vec3), &[2, 4], 467);
                step(f, Op::Copy(ValueType::Bool), &[128, 39], 468);
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
                step(f, Op::Copy(ValueType::Bool), &[129, 39], 474);
                474
            }
            474 => {
                step(f, Op::Jump, &[470], 475)
            }
            475 => {
                step(f, Op::Copy(ValueType::Bool), &[39, 38], 476);
                step(f, Op::Copy(ValueType::Bool), &[128, 43], 477);
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
                step(f, Op::BreakVector, &[80, 351, 352, 353], 483);
                step(f, Op::MakeVector, &[351, 352, 906, 84], 484);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 44, 24], 485);
                step(f, Op::BreakTransform, &[24, 82, 14, 83], 486);
                step(f, Op::BreakVector, &[82, 354, 355, 356], 487);
                step(f, Op::MakeVector, &[354, 355, 906, 85], 488);
                step(f, Op::DistanceV, &[84, 85, 357], 489);
                step(f, Op::GreaterF, &[357, 31, 44], 490);
                step(f, Op::JumpIfFalse, &[44, 492], 491)
            }
            491 => {
                step(f, Op::Copy(ValueType::Bool), &[129, 43], 492);
                492
            }
            492 => {
                step(f, Op::Jump, &[479], 493)
            }
            493 => {
                step(f, Op::Copy(ValueType::Bool), &[43, 42], 494);
                step(f, Op::And, &[38, 42, 45], 495);
                step(f, Op::LengthV, &[2, 343], 496);
                step(f, Op::GreaterF, &[343, 29, 37], 497);
                step(f, Op::GreaterF, &[0, 29, 46], 498);
                step(f, Op::Or, &[37, 46, 47], 499);
                step(f, Op::Not, &[47, 48], 500);
                step(f, Op::And, &[45, 48, 53], 501);
                step(f, Op::DeltaTime, &[382], 502);
                step(f, Op::MulF, &[382, 34, 383], 503);
                step(f, Op::AddF, &[12, 383, 384], 504);
                step(f, Op::GreaterF, &[12, 907, 54], 505);
                step(f, Op::AddF, &[33, 907, 380], 506);
                step(f, Op::Select(ValueType::Float), &[54, 380, 33, 381], 507);
                step(f, Op::MinF, &[384, 381, 385], 508);
                step(f, Op::NotEquals(Elem::Bool), &[48, 4, 49], 509);
                step(f, Op::Not, &[45, 50], 510);
                step(f, Op::And, &[49, 50, 51], 511);
                step(f, Op::SubF, &[13, 29, 366], 512);
                step(f, Op::SubF, &[13, 343, 367], 513);
                step(f, Op::DivF, &[366, 367, 368], 514);
                step(f, Op::ClampF, &[368, 906, 908, 369], 515);
                step(f, Op::MulF, &[8, 369, 371], 516);
                step(f, Op::RemapF, &[343, 29, 30, 906, 908, 128, 358], 517);
                step(f, Op::MaxF, &[358, 9, 359], 518);
                step(f, Op::Select(ValueType::Float), &[38, 908, 359, 360], 519);
                step(f, Op::Select(ValueType::Float), &[48, 32, 360, 361], 520);
                step(f, Op::Select(ValueType::Float), &[45, 358, 361, 362], 521);
                step(f, Op::SubF, &[908, 21, 363], 522);
                step(f, Op::MulF, &[362, 363, 364], 523);
                step(f, Op::LerpF, &[23, 46, 15, 346], 524);
                step(f, Op::RemapF, &[343, 26, 27, 24, 25, 128, 344], 525);
                step(f, Op::LerpF, &[344, 45, 15, 345], 526);
                step(f, Op::MaxF, &[343, 28, 347], 527);
                step(f, Op::DivF, &[345, 347, 348], 528);
                step(f, Op::AddF, &[346, 348, 349], 529);
                step(f, Op::DivF, &[364, 349, 365], 530);
                step(f, Op::SubF, &[908, 369, 370], 531);
                step(f, Op::MulF, &[365, 370, 372], 532);
                step(f, Op::AddF, &[371, 372, 373], 533);
                step(f, Op::MulF, &[373, 911, 374], 534);
                step(f, Op::AddF, &[8, 365, 375], 535);
                step(f, Op::Select(ValueType::Float), &[51, 374, 375, 376], 536);
                step(f, Op::DivF, &[911, 376, 377], 537);
                step(f, Op::GreaterF, &[376, 906, 52], 538);
                step(f, Op::CycleStep, &[12, 377, 906, 52, 378, 379], 539);
                step(f, Op::Select(ValueType::Float), &[53, 385, 378, 386], 540);
                step(f, Op::Copy(ValueType::Float), &[386, 12], 541);
                step(f, Op::Copy(ValueType::Float), &[365, 8], 542);
                step(f, Op::Copy(ValueType::Bool), &[37, 3], 543);
                step(f, Op::Copy(ValueType::Float), &[348, 6], 544);
                step(f, Op::Copy(ValueType::Float), &[349, 7], 545);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 546);
                step(f, Op::Copy(ValueType::Int), &[71, 37], 547);
                step(f, Op::DivF, &[346, 349, 350], 548);
                step(f, Op::MulF, &[11, 369, 392], 549);
                step(f, Op::MulF, &[382, 907, 398], 550);
                step(f, Op::SubF, &[350, 10, 403], 551);
                step(f, Op::MaxF, &[403, 906, 404], 552);
                step(f, Op::DivF, &[404, 350, 405], 553);
                step(f, Op::SubF, &[908, 15, 407], 554);
                step(f, Op::DivF, &[52, 382, 412], 555);
                step(f, Op::SubF, &[907, 412, 413], 556);
                step(f, Op::MulF, &[405, 407, 414], 557);
                step(f, Op::MulF, &[414, 363, 415], 558);
                step(f, Op::MulF, &[415, 129, 416], 559);
                step(f, Op::MulF, &[416, 413, 417], 560);
                step(f, Op::SubF, &[908, 417, 418], 561);
                561
            }
            561 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 37, 14, 38, 39, 605], 562)
            }
            562 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 38, 400], 563);
                step(f, Op::ToFloat, &[38, 387], 564);
                step(f, Op::MulF, &[387, 907, 388], 565);
                step(f, Op::AddF, &[12, 388, 389], 566);
                step(f, Op::FractF, &[389, 390], 567);
                step(f, Op::SubF, &[400, 390, 402], 568);
                step(f, Op::GreaterF, &[402, 907, 55], 569);
                step(f, Op::ArrayAt(Elem::Float), &[2, 38, 401], 570);
                step(f, Op::Select(ValueType::Float), &[55, 906, 401, 429], 571);
                step(f, Op::ArraySetAt(Elem::Float), &[3, 38, 429], 572);
                step(f, Op::SubF, &[908, 400, 423], 573);
                step(f, Op::AddF, &[390, 423, 424], 574);
                step(f, Op::DivF, &[390, 424, 425], 575);
                step(f, Op::MaxF, &[358, 9, 359], 576);
                step(f, Op::Select(ValueType::Float), &[38, 908, 359, 360], 577);
                step(f, Op::Select(ValueType::Float), &[48, 32, 360, 361], 578);
                step(f, Op::Select(ValueType::Float), &[45, 358, 361, 362], 579);
                step(f, Op::MulF, &[362, 363, 364], 580);
                step(f, Op::DivF, &[364, 346, 391], 581);
                step(f, Op::MulF, &[391, 370, 393], 582);
                step(f, Op::AddF, &[392, 393, 394], 583);
                step(f, Op::MulF, &[394, 911, 395], 584);
                step(f, Op::AddF, &[11, 391, 396], 585);
                step(f, Op::Select(ValueType::Float), &[51, 395, 396, 397], 586);
                step(f, Op::MulF, &[397, 398, 399], 587);
                step(f, Op::MulF, &[425, 399, 426], 588);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 38, 56], 589);
                step(f, Op::MulF, &[399, 418, 419], 590);
                step(f, Op::Select(ValueType::Float), &[56, 399, 419, 420], 591);
                step(f, Op::MulF, &[405, 401, 406], 592);
                step(f, Op::MulF, &[406, 407, 408], 593);
                step(f, Op::MulF, &[408, 363, 409], 594);
                step(f, Op::MulF, &[409, 129, 410], 595);
                step(f, Op::Select(ValueType::Float), &[56, 906, 410, 411], 596);
                step(f, Op::SubF, &[420, 411, 421], 597);
                step(f, Op::AddF, &[401, 421, 422], 598);
                step(f, Op::Select(ValueType::Float), &[55, 426, 422, 427], 599);
                step(f, Op::MinF, &[427, 911, 428], 600);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 38, 428], 601);
                step(f, Op::JumpIfFalse, &[55, 603], 602)
            }
            602 => {
                step(f, Op::Copy(ValueType::Float), &[362, 9], 603);
                603
            }
            603 => {
                step(f, Op::ArraySetAt(Elem::Float), &[0, 38, 390], 604);
                step(f, Op::Jump, &[561], 605)
            }
            605 => {
                step(f, Op::Copy(ValueType::Float), &[350, 10], 606);
                step(f, Op::Copy(ValueType::Bool), &[48, 4], 607);
                step(f, Op::Copy(ValueType::Float), &[343, 13], 608);
                step(f, Op::MaxF, &[358, 9, 359], 609);
                step(f, Op::Select(ValueType::Float), &[38, 908, 359, 360], 610);
                step(f, Op::Select(ValueType::Float), &[48, 32, 360, 361], 611);
                step(f, Op::Select(ValueType::Float), &[45, 358, 361, 362], 612);
                step(f, Op::MulF, &[362, 363, 364], 613);
                step(f, Op::DivF, &[364, 346, 391], 614);
                step(f, Op::Copy(ValueType::Float), &[391, 11], 615);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 616);
                step(f, Op::Copy(ValueType::Int), &[71, 2], 617);
                617
            }
            617 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 2, 0, 3, 4, 1481], 618)
            }
            618 => {
                step(f, Op::Copy(ValueType::Bool), &[128, 57], 619);
                step(f, Op::Copy(ValueType::Bool), &[129, 58], 620);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 3, 61], 621);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 430], 622);
                step(f, Op::GreaterEqualF, &[430, 908, 62], 623);
                step(f, Op::And, &[61, 62, 63], 624);
                step(f, Op::Or, &[1, 2, 65], 625);
                step(f, Op::GreaterF, &[21, 906, 64], 626);
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
                step(f, Op::GetTransform, &[34, 71, 128, 25], 636);
                step(f, Op::BreakTransform, &[25, 88, 15, 89], 637);
                step(f, Op::BreakVector, &[88, 441, 442, 443], 638);
                step(f, Op::SubF, &[908, 15, 439], 639);
                step(f, Op::MulF, &[14, 439, 440], 640);
                step(f, Op::QuatFromAxisAngle, &[480, 440, 17], 641);
                step(f, Op::GetTransform, &[0, 71, 128, 26], 642);
                step(f, Op::BreakTransform, &[26, 90, 16, 91], 643);
                step(f, Op::SubV, &[90, 88, 92], 644);
                step(f, Op::BreakVector, &[92, 436, 437, 438], 645);
                step(f, Op::MakeVector, &[436, 437, 906, 93], 646);
                step(f, Op::RotateVector, &[17, 93, 94], 647);
                step(f, Op::BreakVector, &[94, 444, 445, 446], 648);
                step(f, Op::MulF, &[47, 15, 447], 649);
                step(f, Op::Equals(Elem::Int), &[3, 71, 59], 650);
                step(f, Op::Select(ValueType::Float), &[59, 908, 910, 456], 651);
                step(f, Op::MulF, &[447, 456, 448], 652);
                step(f, Op::AddF, &[444, 448, 449], 653);
                step(f, Op::AddF, &[441, 449, 450], 654);
                step(f, Op::AddF, &[442, 445, 451], 655);
                step(f, Op::BreakVector, &[90, 452, 453, 454], 656);
                step(f, Op::SubF, &[454, 53, 455], 657);
                step(f, Op::MakeVector, &[450, 451, 455, 95], 658);
                step(f, Op::MulF, &[6, 907, 435], 659);
                step(f, Op::ScaleV, &[2, 435, 87], 660);
                step(f, Op::AddV, &[95, 87, 98], 661);
                step(f, Op::DistanceV, &[143, 98, 483], 662);
                step(f, Op::TransformVector, &[2, 482, 144], 663);
                step(f, Op::DistanceV, &[144, 482, 484], 664);
                step(f, Op::MaxF, &[483, 484, 485], 665);
                step(f, Op::LessEqualF, &[485, 60, 77], 666);
                step(f, Op::LengthV, &[2, 486], 667);
                step(f, Op::LengthV, &[4, 487], 668);
                step(f, Op::MaxF, &[486, 487, 488], 669);
                step(f, Op::LessEqualF, &[488, 29, 78], 670);
                step(f, Op::And, &[77, 78, 79], 671);
                step(f, Op::ArrayAt(Elem::Bool), &[1, 3, 69], 672);
                step(f, Op::And, &[79, 69, 80], 673);
                step(f, Op::JumpIfFalse, &[80, 676], 674)
            }
            674 => {
                step(f, Op::Copy(ValueType::Bool), &[128, 58], 675);
                step(f, Op::Jump, &[705], 676)
            }
            676 => {
                step(f, Op::MakeVector, &[906, 906, 58, 123], 677);
                step(f, Op::AddV, &[98, 123, 124], 678);
                step(f, Op::SubV, &[98, 123, 125], 679);
                step(f, Op::SphereTrace, &[124, 125, 57, 70, 126, 127, 475], 680);
                step(f, Op::SubV, &[126, 98, 140], 681);
                step(f, Op::DistanceV, &[140, 121, 479], 682);
                step(f, Op::RotateVector, &[0, 481, 99], 683);
                step(f, Op::ScaleV, &[99, 62, 128], 684);
                step(f, Op::AddV, &[124, 128, 129], 685);
                step(f, Op::AddV, &[125, 128, 130], 686);
                step(f, Op::SphereTrace, &[129, 130, 57, 71, 131, 132, 476], 687);
                step(f, Op::SubV, &[131, 98, 141], 688);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 3, 122], 689);
                step(f, Op::DistanceV, &[141, 122, 480], 690);
                step(f, Op::MaxF, &[479, 480, 481], 691);
                step(f, Op::ScaleV, &[99, 59, 133], 692);
                step(f, Op::AddV, &[129, 133, 134], 693);
                step(f, Op::AddV, &[130, 133, 135], 694);
                step(f, Op::SphereTrace, &[134, 135, 57, 72, 136, 137, 477], 695);
                step(f, Op::SubV, &[136, 98, 138], 696);
                step(f, Op::ArrayAt(Elem::Vec3), &[2, 3, 139], 697);
                step(f, Op::DistanceV, &[138, 139, 478], 698);
                step(f, Op::MaxF, &[481, 478, 482], 699);
                step(f, Op::LessEqualF, &[482, 60, 73], 700);
                step(f, Op::And, &[70, 71, 74], 701);
                step(f, Op::And, &[74, 69, 75], 702);
                step(f, Op::And, &[73, 75, 76], 703);
                step(f, Op::JumpIfFalse, &[76, 705], 704)
            }
            704 => {
                step(f, Op::Copy(ValueType::Bool), &[128, 58], 705);
                705
            }
            705 => {
                step(f, Op::JumpIfFalse, &[58, 739], 706)
            }
            706 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 27], 707);
                step(f, Op::BreakTransform, &[27, 101, 21, 102], 708);
                step(f, Op::AddV, &[98, 121, 145], 709);
                step(f, Op::Copy(ValueType::Float), &[50, 489], 710);
                step(f, Op::Copy(ValueType::Float), &[52, 490], 711);
                step(f, Op::SubV, &[145, 104, 150], 712);
                step(f, Op::DeltaTime, &[491], 713);
                step(f, Op::DivF, &[490, 491, 492], 714);
                step(f, Op::ScaleV, &[150, 492, 151], 715);
                step(f, Op::AddV, &[145, 151, 152], 716);
                step(f, Op::AddV, &[104, 151, 153], 717);
                step(f, Op::SubV, &[101, 153, 154], 718);
                step(f, Op::FloatLerp, &[906, 908, 489, 493], 719);
                step(f, Op::SubF, &[908, 493, 494], 720);
                step(f, Op::ScaleV, &[154, 494, 155], 721);
                step(f, Op::AddV, &[152, 155, 157], 722);
                step(f, Op::MulF, &[489, 491, 495], 723);
                step(f, Op::GreaterF, &[495, 906, 81], 724);
                step(f, Op::DivF, &[493, 495, 496], 725);
                step(f, Op::Select(ValueType::Float), &[81, 496, 908, 497], 726);
                step(f, Op::ScaleV, &[150, 497, 156], 727);
                step(f, Op::SubV, &[157, 156, 158], 728);
                step(f, Op::Copy(ValueType::Vec3), &[158, 149], 729);
                step(f, Op::BreakVector, &[149, 498, 499, 500], 730);
                step(f, Op::ClampF, &[500, 63, 64, 501], 731);
                step(f, Op::MakeVector, &[498, 499, 501, 159], 732);
                step(f, Op::MakeTransform, &[159, 21, 477, 31], 733);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 3, 31], 734);
                step(f, Op::MakeTransform, &[145, 94, 477, 32], 735);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 3, 32], 736);
                step(f, Op::JumpIfFalse, &[69, 738], 737)
            }
            737 => {
                step(f, Op::Copy(ValueType::Bool), &[128, 7], 738);
                738
            }
            738 => {
                step(f, Op::Copy(ValueType::Bool), &[129, 57], 739);
                739
            }
            739 => {
                step(f, Op::JumpIfFalse, &[57, 944], 740)
            }
            740 => {
                step(f, Op::GetTransform, &[34, 71, 128, 25], 741);
                step(f, Op::BreakTransform, &[25, 88, 15, 89], 742);
                step(f, Op::BreakVector, &[88, 441, 442, 443], 743);
                step(f, Op::SubF, &[908, 15, 439], 744);
                step(f, Op::MulF, &[14, 439, 440], 745);
                step(f, Op::QuatFromAxisAngle, &[480, 440, 17], 746);
                step(f, Op::GetTransform, &[0, 71, 128, 26], 747);
                step(f, Op::BreakTransform, &[26, 90, 16, 91], 748);
                step(f, Op::SubV, &[90, 88, 92], 749);
                step(f, Op::BreakVector, &[92, 436, 437, 438], 750);
                step(f, Op::MakeVector, &[436, 437, 906, 93], 751);
                step(f, Op::RotateVector, &[17, 93, 94], 752);
                step(f, Op::BreakVector, &[94, 444, 445, 446], 753);
                step(f, Op::MulF, &[47, 15, 447], 754);
                step(f, Op::Equals(Elem::Int), &[3, 71, 59], 755);
                step(f, Op::Select(ValueType::Float), &[59, 908, 910, 456], 756);
                step(f, Op::MulF, &[447, 456, 448], 757);
                step(f, Op::AddF, &[444, 448, 449], 758);
                step(f, Op::AddF, &[441, 449, 450], 759);
                step(f, Op::AddF, &[442, 445, 451], 760);
                step(f, Op::BreakVector, &[90, 452, 453, 454], 761);
                step(f, Op::SubF, &[454, 53, 455], 762);
                step(f, Op::MakeVector, &[450, 451, 455, 95], 763);
                step(f, Op::SubF, &[908, 430, 431], 764);
                step(f, Op::MaxF, &[431, 906, 432], 765);
                step(f, Op::MulF, &[10, 7, 433], 766);
                step(f, Op::MulF, &[432, 433, 434], 767);
                step(f, Op::ScaleV, &[2, 434, 86], 768);
                step(f, Op::AddV, &[95, 86, 96], 769);
                step(f, Op::MulF, &[6, 907, 435], 770);
                step(f, Op::ScaleV, &[2, 435, 87], 771);
                step(f, Op::AddV, &[96, 87, 97], 772);
                step(f, Op::RotateVector, &[0, 481, 99], 773);
                step(f, Op::Copy(ValueType::Float), &[913, 503], 774);
                step(f, Op::Copy(ValueType::Vec3), &[478, 164], 775);
                step(f, Op::Copy(ValueType::Vec3), &[480, 165], 776);
                step(f, Op::Copy(ValueType::Bool), &[129, 83], 777);
                step(f, Op::Copy(ValueType::Float), &[913, 504], 778);
                step(f, Op::Copy(ValueType::Vec3), &[478, 166], 779);
                step(f, Op::MulI, &[0, 0, 52], 780);
                step(f, Op::Copy(ValueType::Int), &[52, 51], 781);
                step(f, Op::Copy(ValueType::Int), &[71, 47], 782);
                step(f, Op::SubI, &[0, 72, 55], 783);
                step(f, Op::DivI, &[55, 73, 56], 784);
                step(f, Op::MakeVector, &[906, 906, 58, 171], 785);
                step(f, Op::ScaleV, &[99, 62, 176], 786);
                786
            }
            786 => {
                step(f, Op::ForNext, &[47, 51, 49, 833], 787)
            }
            787 => {
                step(f, Op::ModI, &[49, 0, 53], 788);
                step(f, Op::ToFloat, &[53, 505], 789);
                step(f, Op::MulF, &[505, 59, 507], 790);
                step(f, Op::MulF, &[507, 456, 508], 791);
                step(f, Op::MakeVector, &[508, 906, 906, 167], 792);
                step(f, Op::DivI, &[49, 0, 54], 793);
                step(f, Op::SubI, &[54, 56, 57], 794);
                step(f, Op::ToFloat, &[57, 506], 795);
                step(f, Op::MulF, &[506, 59, 509], 796);
                step(f, Op::ScaleV, &[99, 509, 168], 797);
                step(f, Op::AddV, &[167, 168, 169], 798);
                step(f, Op::AddV, &[97, 169, 170], 799);
                step(f, Op::AddV, &[170, 171, 172], 800);
                step(f, Op::SubV, &[170, 171, 173], 801);
                step(f, Op::SphereTrace, &[172, 173, 57, 84, 174, 175, 510], 802);
                step(f, Op::BreakVector, &[174, 512, 513, 514], 803);
                step(f, Op::AddV, &[172, 176, 177], 804);
                step(f, Op::AddV, &[173, 176, 178], 805);
                step(f, Op::SphereTrace, &[177, 178, 57, 85, 179, 180, 511], 806);
                step(f, Op::BreakVector, &[179, 515, 516, 517], 807);
                step(f, Op::SubF, &[514, 517, 518], 808);
                step(f, Op::AbsF, &[518, 519], 809);
                step(f, Op::Select(ValueType::Float), &[84, 906, 908, 520], 810);
                step(f, Op::AddF, &[519, 520, 525], 811);
                step(f, Op::LengthV, &[169, 521], 812);
                step(f, Op::RemapF, &[521, 906, 919, 906, 908, 128, 522], 813);
                step(f, Op::MinF, &[514, 517, 523], 814);
                step(f, Op::RemapF, &[523, 920, 919, 908, 907, 128, 524], 815);
                step(f, Op::AddF, &[522, 524, 526], 816);
                step(f, Op::AddF, &[525, 526, 527], 817);
                step(f, Op::LessF, &[527, 503, 86], 818);
                step(f, Op::And, &[84, 86, 87], 819);
                step(f, Op::JumpIfFalse, &[87, 827], 820)
            }
            820 => {
                step(f, Op::Copy(ValueType::Float), &[503, 504], 821);
                step(f, Op::Copy(ValueType::Vec3), &[164, 166], 822);
                step(f, Op::Copy(ValueType::Float), &[527, 503], 823);
                step(f, Op::Copy(ValueType::Vec3), &[174, 164], 824);
                step(f, Op::Copy(ValueType::Vec3), &[175, 165], 825);
                step(f, Op::Copy(ValueType::Bool), &[128, 83], 826);
                step(f, Op::Jump, &[832], 827)
            }
            827 => {
                step(f, Op::LessF, &[527, 504, 88], 828);
                step(f, Op::And, &[84, 88, 89], 829);
                step(f, Op::JumpIfFalse, &[89, 832], 830)
            }
            830 => {
                step(f, Op::Copy(ValueType::Float), &[527, 504], 831);
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
                step(f, Op::DrawSphere, &[164, 57, 481], 835);
                835
            }
            835 => {
                step(f, Op::GreaterF, &[61, 906, 90], 836);
                step(f, Op::SubF, &[503, 504, 528], 837);
                step(f, Op::DivF, &[528, 61, 529], 838);
                step(f, Op::PowF, &[921, 529, 530], 839);
                step(f, Op::Select(ValueType::Float), &[90, 530, 906, 531], 840);
                step(f, Op::ScaleV, &[166, 531, 181], 841);
                step(f, Op::AddV, &[164, 181, 182], 842);
                step(f, Op::AddF, &[531, 908, 532], 843);
                step(f, Op::DivF, &[908, 532, 533], 844);
                step(f, Op::ScaleV, &[182, 533, 183], 845);
                step(f, Op::Copy(ValueType::Vec3), &[183, 162], 846);
                step(f, Op::Copy(ValueType::Vec3), &[165, 163], 847);
                step(f, Op::Copy(ValueType::Bool), &[83, 82], 848);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 27], 849);
                step(f, Op::BreakTransform, &[27, 101, 21, 102], 850);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 430], 851);
                step(f, Op::SubF, &[908, 430, 431], 852);
                step(f, Op::MaxF, &[431, 906, 432], 853);
                step(f, Op::MulF, &[10, 7, 433], 854);
                step(f, Op::MulF, &[432, 433, 434], 855);
                step(f, Op::ScaleV, &[2, 434, 86], 856);
                step(f, Op::SubV, &[162, 86, 100], 857);
                step(f, Op::Select(ValueType::Vec3), &[82, 100, 101, 103], 858);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 3, 28], 859);
                step(f, Op::BreakTransform, &[28, 104, 23, 105], 860);
                step(f, Op::Copy(ValueType::Float), &[50, 462], 861);
                step(f, Op::Copy(ValueType::Float), &[52, 463], 862);
                step(f, Op::SubV, &[103, 104, 110], 863);
                step(f, Op::DeltaTime, &[464], 864);
                step(f, Op::DivF, &[463, 464, 465], 865);
                step(f, Op::ScaleV, &[110, 465, 111], 866);
                step(f, Op::AddV, &[103, 111, 112], 867);
                step(f, Op::AddV, &[104, 111, 113], 868);
                step(f, Op::SubV, &[101, 113, 114], 869);
                step(f, Op::FloatLerp, &[906, 908, 462, 466], 870);
                step(f, Op::SubF, &[908, 466, 467], 871);
                step(f, Op::ScaleV, &[114, 467, 115], 872);
                step(f, Op::AddV, &[112, 115, 117], 873);
                step(f, Op::MulF, &[462, 464, 468], 874);
                step(f, Op::GreaterF, &[468, 906, 60], 875);
                step(f, Op::DivF, &[466, 468, 469], 876);
                step(f, Op::Select(ValueType::Float), &[60, 469, 908, 470], 877);
                step(f, Op::ScaleV, &[110, 470, 116], 878);
                step(f, Op::SubV, &[117, 116, 118], 879);
                step(f, Op::Copy(ValueType::Vec3), &[118, 109], 880);
                step(f, Op::BreakVector, &[109, 471, 472, 473], 881);
                step(f, Op::ClampF, &[473, 63, 64, 474], 882);
                step(f, Op::MakeVector, &[471, 472, 474, 119], 883);
                step(f, Op::RotationFromNormal, &[163, 460, 461, 19], 884);
                step(f, Op::PerFootRotationFactor, &[14, 105, 106, 457], 885);
                step(f, Op::MulF, &[14, 457, 458], 886);
                step(f, Op::SubF, &[908, 15, 439], 887);
                step(f, Op::MulF, &[458, 439, 459], 888);
                step(f, Op::QuatFromAxisAngle, &[480, 459, 18], 889);
                step(f, Op::MulQ, &[19, 18, 20], 890);
                step(f, Op::Select(ValueType::Quat), &[82, 20, 21, 22], 891);
                step(f, Op::MakeTransform, &[119, 22, 477, 30], 892);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 3, 30], 893);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 27], 894);
                step(f, Op::BreakTransform, &[27, 101, 21, 102], 895);
                step(f, Op::Select(ValueType::Vec3), &[82, 100, 101, 103], 896);
                step(f, Op::MakeTransform, &[103, 94, 477, 29], 897);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 3, 29], 898);
                step(f, Op::GetTransform, &[34, 71, 128, 25], 899);
                step(f, Op::BreakTransform, &[25, 88, 15, 89], 900);
                step(f, Op::BreakVector, &[88, 441, 442, 443], 901);
                step(f, Op::MulF, &[14, 439, 440], 902);
                step(f, Op::QuatFromAxisAngle, &[480, 440, 17], 903);
                step(f, Op::GetTransform, &[0, 71, 128, 26], 904);
                step(f, Op::BreakTransform, &[26, 90, 16, 91], 905);
                step(f, Op::SubV, &[90, 88, 92], 906);
                step(f, Op::BreakVector, &[92, 436, 437, 438], 907);
                step(f, Op::MakeVector, &[436, 437, 906, 93], 908);
                step(f, Op::RotateVector, &[17, 93, 94], 909);
                step(f, Op::BreakVector, &[94, 444, 445, 446], 910);
                step(f, Op::MulF, &[47, 15, 447], 911);
                step(f, Op::MulF, &[447, 456, 448], 912);
                step(f, Op::AddF, &[444, 448, 449], 913);
                step(f, Op::AddF, &[441, 449, 450], 914);
                step(f, Op::AddF, &[442, 445, 451], 915);
                step(f, Op::BreakVector, &[90, 452, 453, 454], 916);
                step(f, Op::SubF, &[454, 53, 455], 917);
                step(f, Op::MakeVector, &[450, 451, 455, 95], 918);
                step(f, Op::MulF, &[6, 907, 435], 919);
                step(f, Op::ScaleV, &[2, 435, 87], 920);
                step(f, Op::AddV, &[95, 87, 98], 921);
                step(f, Op::SubV, &[103, 98, 120], 922);
                step(f, Op::ArraySetAt(Elem::Vec3), &[0, 3, 120], 923);
                step(f, Op::ArraySetAt(Elem::Bool), &[1, 3, 82], 924);
                step(f, Op::GreaterEqualF, &[430, 908, 62], 925);
                step(f, Op::JumpIfFalse, &[62, 942], 926)
            }
            926 => {
                step(f, Op::MakeVector, &[906, 906, 58, 123], 927);
                step(f, Op::AddV, &[98, 123, 124], 928);
                step(f, Op::RotateVector, &[0, 481, 99], 929);
                step(f, Op::ScaleV, &[99, 62, 128], 930);
                step(f, Op::AddV, &[124, 128, 129], 931);
                step(f, Op::SubV, &[98, 123, 125], 932);
                step(f, Op::AddV, &[125, 128, 130], 933);
                step(f, Op::SphereTrace, &[129, 130, 57, 71, 131, 132, 476], 934);
                step(f, Op::SubV, &[131, 98, 141], 935);
                step(f, Op::ArraySetAt(Elem::Vec3), &[1, 3, 141], 936);
                step(f, Op::ScaleV, &[99, 59, 133], 937);
                step(f, Op::AddV, &[129, 133, 134], 938);
                step(f, Op::AddV, &[130, 133, 135], 939);
                step(f, Op::SphereTrace, &[134, 135, 57, 72, 136, 137, 477], 940);
                step(f, Op::SubV, &[136, 98, 138], 941);
                step(f, Op::ArraySetAt(Elem::Vec3), &[2, 3, 138], 942);
                942
            }
            942 => {
                step(f, Op::JumpIfFalse, &[82, 944], 943)
            }
            943 => {
                step(f, Op::Copy(ValueType::Bool), &[128, 7], 944);
                944
            }
            944 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 3, 35], 945);
                step(f, Op::GreaterF, &[21, 906, 94], 946);
                step(f, Op::InterpolateTransform, &[2, 121, 22, 33], 947);
                step(f, Op::Select(ValueType::Transform), &[94, 33, 2, 34], 948);
                step(f, Op::MakeAbsolute, &[35, 34, 36], 949);
                step(f, Op::BreakTransform, &[36, 184, 24, 185], 950);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 3, 37], 951);
                step(f, Op::BreakTransform, &[37, 186, 25, 187], 952);
                step(f, Op::AddF, &[67, 68, 535], 953);
                step(f, Op::ClampSpatially, &[184, 186, 906, 535, 188], 954);
                step(f, Op::SubF, &[908, 15, 561], 955);
                step(f, Op::MulF, &[14, 561, 536], 956);
                step(f, Op::LimitRotationAroundZ, &[24, 536, 101, 26], 957);
                step(f, Op::MakeTransform, &[188, 26, 477, 38], 958);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 3, 38], 959);
                step(f, Op::ArrayAt(Elem::Float), &[4, 3, 544], 960);
                step(f, Op::FloatLerp, &[544, 906, 104, 545], 961);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 3, 91], 962);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 534], 963);
                step(f, Op::GreaterEqualF, &[534, 908, 92], 964);
                step(f, Op::And, &[91, 92, 95], 965);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 3, 35], 966);
                step(f, Op::MakeAbsolute, &[35, 34, 36], 967);
                step(f, Op::BreakTransform, &[36, 184, 24, 185], 968);
                step(f, Op::RotateVector, &[24, 481, 189], 969);
                step(f, Op::LimitRotationAroundZ, &[24, 536, 101, 26], 970);
                step(f, Op::RotateVector, &[26, 481, 190], 971);
                step(f, Op::CrossV, &[189, 190, 191], 972);
                step(f, Op::BreakVector, &[191, 537, 538, 539], 973);
                step(f, Op::DotV, &[189, 190, 540], 974);
                step(f, Op::Atan2F, &[539, 540, 541], 975);
                step(f, Op::AbsF, &[541, 542], 976);
                step(f, Op::Select(ValueType::Float), &[95, 542, 906, 543], 977);
                step(f, Op::AddF, &[545, 543, 546], 978);
                step(f, Op::ArraySetAt(Elem::Float), &[4, 3, 546], 979);
                step(f, Op::JumpIfFalse, &[91, 1044], 980)
            }
            980 => {
                step(f, Op::JumpIfFalse, &[92, 982], 981)
            }
            981 => {
                step(f, Op::Jump, &[1043], 982)
            }
            982 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 41], 983);
                step(f, Op::BreakTransform, &[41, 197, 28, 198], 984);
                step(f, Op::SubF, &[908, 534, 557], 985);
                step(f, Op::MulF, &[10, 7, 558], 986);
                step(f, Op::MulF, &[557, 558, 559], 987);
                step(f, Op::ScaleV, &[2, 559, 199], 988);
                step(f, Op::AddV, &[197, 199, 200], 989);
                step(f, Op::Equals(Elem::Int), &[3, 71, 93], 990);
                step(f, Op::Select(ValueType::Int), &[93, 72, 71, 59], 991);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 59, 96], 992);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 59, 42], 993);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 59, 43], 994);
                step(f, Op::Select(ValueType::Transform), &[96, 42, 43, 44], 995);
                step(f, Op::MakeAbsolute, &[44, 34, 45], 996);
                step(f, Op::Select(ValueType::Transform), &[93, 45, 44, 46], 997);
                step(f, Op::BreakTransform, &[46, 201, 29, 202], 998);
                step(f, Op::MulF, &[14, 561, 562], 999);
                step(f, Op::FootAvoidance, &[200, 201, 562, 93, 84, 203], 1000);
                step(f, Op::RemapF, &[15, 87, 908, 906, 908, 128, 560], 1001);
                step(f, Op::LerpV, &[200, 203, 560, 204], 1002);
                step(f, Op::MakeTransform, &[204, 28, 477, 53], 1003);
                step(f, Op::BreakTransform, &[53, 232, 34, 233], 1004);
                step(f, Op::MakeVector, &[906, 906, 58, 234], 1005);
                step(f, Op::AddV, &[232, 234, 235], 1006);
                step(f, Op::SubV, &[232, 234, 236], 1007);
                step(f, Op::LineTrace, &[235, 236, 100, 237, 238, 588], 1008);
                step(f, Op::RotateVector, &[34, 480, 239], 1009);
                step(f, Op::FindQuatBetween, &[239, 238, 35], 1010);
                step(f, Op::MulQ, &[35, 34, 36], 1011);
                step(f, Op::MulF, &[56, 55, 589], 1012);
                step(f, Op::AddF, &[589, 66, 590], 1013);
                step(f, Op::NegF, &[590, 591], 1014);
                step(f, Op::MakeVector, &[906, 591, 906, 240], 1015);
                step(f, Op::RotateVector, &[36, 240, 242], 1016);
                step(f, Op::AddV, &[237, 242, 244], 1017);
                step(f, Op::AddV, &[244, 234, 246], 1018);
                step(f, Op::SubV, &[244, 234, 247], 1019);
                step(f, Op::LineTrace, &[246, 247, 101, 250, 251, 593], 1020);
                step(f, Op::BreakVector, &[250, 595, 596, 597], 1021);
                step(f, Op::BreakVector, &[244, 601, 602, 603], 1022);
                step(f, Op::SubF, &[597, 603, 607], 1023);
                step(f, Op::Select(ValueType::Float), &[101, 607, 906, 609], 1024);
                step(f, Op::AddF, &[62, 66, 592], 1025);
                step(f, Op::MakeVector, &[906, 592, 906, 241], 1026);
                step(f, Op::RotateVector, &[36, 241, 243], 1027);
                step(f, Op::AddV, &[237, 243, 245], 1028);
                step(f, Op::AddV, &[245, 234, 248], 1029);
                step(f, Op::SubV, &[245, 234, 249], 1030);
                step(f, Op::LineTrace, &[248, 249, 102, 252, 253, 594], 1031);
                step(f, Op::BreakVector, &[252, 598, 599, 600], 1032);
                step(f, Op::BreakVector, &[245, 604, 605, 606], 1033);
                step(f, Op::SubF, &[600, 606, 608], 1034);
                step(f, Op::Select(ValueType::Float), &[102, 608, 906, 610], 1035);
                step(f, Op::MaxF, &[609, 610, 611], 1036);
                step(f, Op::ClampF, &[611, 906, 65, 612], 1037);
                step(f, Op::MakeVector, &[906, 906, 612, 254], 1038);
                step(f, Op::AddV, &[237, 254, 255], 1039);
                step(f, Op::MakeTransform, &[255, 36, 477, 56], 1040);
                step(f, Op::Select(ValueType::Transform), &[100, 56, 53, 57], 1041);
                step(f, Op::Copy(ValueType::Transform), &[57, 55], 1042);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 3, 55], 1043);
                1043
            }
            1043 => {
                step(f, Op::Jump, &[1148], 1044)
            }
            1044 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 3, 58], 1045);
                step(f, Op::MakeAbsolute, &[58, 34, 59], 1046);
                step(f, Op::BreakTransform, &[59, 256, 37, 257], 1047);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 41], 1048);
                step(f, Op::BreakTransform, &[41, 197, 28, 198], 1049);
                step(f, Op::SubF, &[908, 534, 557], 1050);
                step(f, Op::MulF, &[10, 7, 558], 1051);
                step(f, Op::MulF, &[557, 558, 559], 1052);
                step(f, Op::ScaleV, &[2, 559, 199], 1053);
                step(f, Op::AddV, &[197, 199, 200], 1054);
                step(f, Op::Equals(Elem::Int), &[3, 71, 93], 1055);
                step(f, Op::Select(ValueType::Int), &[93, 72, 71, 59], 1056);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 59, 96], 1057);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 59, 42], 1058);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 59, 43], 1059);
                step(f, Op::Select(ValueType::Transform), &[96, 42, 43, 44], 1060);
                step(f, Op::MakeAbsolute, &[44, 34, 45], 1061);
                step(f, Op::Select(ValueType::Transform), &[93, 45, 44, 46], 1062);
                step(f, Op::BreakTransform, &[46, 201, 29, 202], 1063);
                step(f, Op::MulF, &[14, 561, 562], 1064);
                step(f, Op::FootAvoidance, &[200, 201, 562, 93, 84, 203], 1065);
                step(f, Op::RemapF, &[15, 87, 908, 906, 908, 128, 560], 1066);
                step(f, Op::LerpV, &[200, 203, 560, 204], 1067);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 3, 60], 1068);
                step(f, Op::MakeAbsolute, &[60, 34, 61], 1069);
                step(f, Op::BreakTransform, &[61, 258, 38, 259], 1070);
                step(f, Op::ArrayAt(Elem::Float), &[3, 3, 613], 1071);
                step(f, Op::SubF, &[534, 613, 614], 1072);
                step(f, Op::DeltaTime, &[629], 1073);
                step(f, Op::DivF, &[52, 629, 615], 1074);
                step(f, Op::MulF, &[614, 615, 616], 1075);
                step(f, Op::AddF, &[613, 616, 617], 1076);
                step(f, Op::ClampF, &[617, 906, 908, 619], 1077);
                step(f, Op::AddF, &[534, 616, 618], 1078);
                step(f, Op::ClampF, &[618, 906, 908, 620], 1079);
                step(f, Op::AddF, &[619, 620, 621], 1080);
                step(f, Op::MulF, &[621, 907, 622], 1081);
                step(f, Op::SubF, &[908, 622, 623], 1082);
                step(f, Op::GreaterF, &[614, 906, 103], 1083);
                step(f, Op::SubF, &[620, 619, 624], 1084);
                step(f, Op::DivF, &[624, 614, 625], 1085);
                step(f, Op::Select(ValueType::Float), &[103, 625, 908, 626], 1086);
                step(f, Op::MulF, &[623, 626, 627], 1087);
                step(f, Op::MulF, &[83, 627, 628], 1088);
                step(f, Op::Copy(ValueType::Float), &[52, 631], 1089);
                step(f, Op::SubV, &[204, 258, 264], 1090);
                step(f, Op::DeltaTime, &[632], 1091);
                step(f, Op::DivF, &[631, 632, 633], 1092);
                step(f, Op::ScaleV, &[264, 633, 265], 1093);
                step(f, Op::AddV, &[204, 265, 266], 1094);
                step(f, Op::AddV, &[258, 265, 267], 1095);
                step(f, Op::SubV, &[256, 267, 268], 1096);
                step(f, Op::FloatLerp, &[906, 908, 628, 634], 1097);
                step(f, Op::SubF, &[908, 634, 635], 1098);
                step(f, Op::ScaleV, &[268, 635, 269], 1099);
                step(f, Op::AddV, &[266, 269, 271], 1100);
                step(f, Op::MulF, &[628, 632, 636], 1101);
                step(f, Op::GreaterF, &[636, 906, 104], 1102);
                step(f, Op::DivF, &[634, 636, 637], 1103);
                step(f, Op::Select(ValueType::Float), &[104, 637, 908, 638], 1104);
                step(f, Op::ScaleV, &[264, 638, 270], 1105);
                step(f, Op::SubV, &[271, 270, 272], 1106);
                step(f, Op::Copy(ValueType::Vec3), &[272, 263], 1107);
                step(f, Op::MakeTransform, &[263, 28, 477, 63], 1108);
                step(f, Op::BreakTransform, &[63, 273, 39, 274], 1109);
                step(f, Op::MakeVector, &[906, 906, 58, 275], 1110);
                step(f, Op::AddV, &[273, 275, 276], 1111);
                step(f, Op::SubV, &[273, 275, 277], 1112);
                step(f, Op::LineTrace, &[276, 277, 105, 278, 279, 639], 1113);
                step(f, Op::RotateVector, &[39, 480, 280], 1114);
                step(f, Op::FindQuatBetween, &[280, 279, 40], 1115);
                step(f, Op::MulQ, &[40, 39, 41], 1116);
                step(f, Op::MulF, &[56, 55, 640], 1117);
                step(f, Op::AddF, &[640, 66, 641], 1118);
                step(f, Op::NegF, &[641, 642], 1119);
                step(f, Op::MakeVector, &[906, 642, 906, 281], 1120);
                step(f, Op::RotateVector, &[41, 281, 283], 1121);
                step(f, Op::AddV, &[278, 283, 285], 1122);
                step(f, Op::AddV, &[285, 275, 287], 1123);
                step(f, Op::SubV, &[285, 275, 288], 1124);
                step(f, Op::LineTrace, &[287, 288, 106, 291, 292, 644], 1125);
                step(f, Op::BreakVector, &[291, 646, 647, 648], 1126);
                step(f, Op::BreakVector, &[285, 652, 653, 654], 1127);
                step(f, Op::SubF, &[648, 654, 658], 1128);
                step(f, Op::Select(ValueType::Float), &[106, 658, 906, 660], 1129);
                step(f, Op::AddF, &[62, 66, 643], 1130);
                step(f, Op::MakeVector, &[906, 643, 906, 282], 1131);
                step(f, Op::RotateVector, &[41, 282, 284], 1132);
                step(f, Op::AddV, &[278, 284, 286], 1133);
                step(f, Op::AddV, &[286, 275, 289], 1134);
                step(f, Op::SubV, &[286, 275, 290], 1135);
                step(f, Op::LineTrace, &[289, 290, 107, 293, 294, 645], 1136);
                step(f, Op::BreakVector, &[293, 649, 650, 651], 1137);
                step(f, Op::BreakVector, &[286, 655, 656, 657], 1138);
                step(f, Op::SubF, &[651, 657, 659], 1139);
                step(f, Op::Select(ValueType::Float), &[107, 659, 906, 661], 1140);
                step(f, Op::MaxF, &[660, 661, 662], 1141);
                step(f, Op::ClampF, &[662, 906, 65, 663], 1142);
                step(f, Op::MakeVector, &[906, 906, 663, 295], 1143);
                step(f, Op::AddV, &[278, 295, 296], 1144);
                step(f, Op::MakeTransform, &[296, 41, 477, 66], 1145);
                step(f, Op::Select(ValueType::Transform), &[105, 66, 63, 67], 1146);
                step(f, Op::Copy(ValueType::Transform), &[67, 65], 1147);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 3, 65], 1148);
                1148
            }
            1148 => {
                step(f, Op::JumpIfFalse, &[92, 1219], 1149)
            }
            1149 => {
                step(f, Op::JumpIfFalse, &[91, 1151], 1150)
            }
            1150 => {
                step(f, Op::Jump, &[1200], 1151)
            }
            1151 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 3, 68], 1152);
                step(f, Op::BreakTransform, &[68, 297, 42, 298], 1153);
                step(f, Op::Equals(Elem::Int), &[3, 71, 93], 1154);
                step(f, Op::Select(ValueType::Int), &[93, 72, 71, 59], 1155);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 59, 47], 1156);
                step(f, Op::BreakTransform, &[47, 205, 30, 206], 1157);
                step(f, Op::MulF, &[14, 561, 562], 1158);
                step(f, Op::FootAvoidance, &[297, 205, 562, 93, 84, 207], 1159);
                step(f, Op::MakeTransform, &[207, 42, 477, 48], 1160);
                step(f, Op::BreakTransform, &[48, 208, 31, 209], 1161);
                step(f, Op::MakeVector, &[906, 906, 58, 210], 1162);
                step(f, Op::AddV, &[208, 210, 211], 1163);
                step(f, Op::SubV, &[208, 210, 212], 1164);
                step(f, Op::LineTrace, &[211, 212, 97, 213, 214, 563], 1165);
                step(f, Op::RotateVector, &[31, 480, 215], 1166);
                step(f, Op::FindQuatBetween, &[215, 214, 32], 1167);
                step(f, Op::MulQ, &[32, 31, 33], 1168);
                step(f, Op::MulF, &[56, 55, 564], 1169);
                step(f, Op::AddF, &[564, 66, 565], 1170);
                step(f, Op::NegF, &[565, 566], 1171);
                step(f, Op::MakeVector, &[906, 566, 906, 216], 1172);
                step(f, Op::RotateVector, &[33, 216, 218], 1173);
                step(f, Op::AddV, &[213, 218, 220], 1174);
                step(f, Op::AddV, &[220, 210, 222], 1175);
                step(f, Op::SubV, &[220, 210, 223], 1176);
                step(f, Op::LineTrace, &[222, 223, 98, 226, 227, 568], 1177);
                step(f, Op::BreakVector, &[226, 570, 571, 572], 1178);
                step(f, Op::BreakVector, &[220, 576, 577, 578], 1179);
                step(f, Op::SubF, &[572, 578, 582], 1180);
                step(f, Op::Select(ValueType::Float), &[98, 582, 906, 584], 1181);
                step(f, Op::AddF, &[62, 66, 567], 1182);
                step(f, Op::MakeVector, &[906, 567, 906, 217], 1183);
                step(f, Op::RotateVector, &[33, 217, 219], 1184);
                step(f, Op::AddV, &[213, 219, 221], 1185);
                step(f, Op::AddV, &[221, 210, 224], 1186);
                step(f, Op::SubV, &[221, 210, 225], 1187);
                step(f, Op::LineTrace, &[224, 225, 99, 228, 229, 569], 1188);
                step(f, Op::BreakVector, &[228, 573, 574, 575], 1189);
                step(f, Op::BreakVector, &[221, 579, 580, 581], 1190);
                step(f, Op::SubF, &[575, 581, 583], 1191);
                step(f, Op::Select(ValueType::Float), &[99, 583, 906, 585], 1192);
                step(f, Op::MaxF, &[584, 585, 586], 1193);
                step(f, Op::ClampF, &[586, 906, 65, 587], 1194);
                step(f, Op::MakeVector, &[906, 906, 587, 230], 1195);
                step(f, Op::AddV, &[213, 230, 231], 1196);
                step(f, Op::MakeTransform, &[231, 33, 477, 51], 1197);
                step(f, Op::Select(ValueType::Transform), &[97, 51, 48, 52], 1198);
                step(f, Op::Copy(ValueType::Transform), &[52, 50], 1199);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 3, 50], 1200);
                1200
            }
            1200 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 3, 39], 1201);
                step(f, Op::BreakTransform, &[39, 192, 27, 193], 1202);
                step(f, Op::SubV, &[192, 186, 194], 1203);
                step(f, Op::LengthV, &[194, 547], 1204);
                step(f, Op::SubF, &[67, 68, 548], 1205);
                step(f, Op::SubF, &[547, 548, 549], 1206);
                step(f, Op::MulF, &[68, 911, 550], 1207);
                step(f, Op::ClampF, &[549, 906, 550, 551], 1208);
                step(f, Op::MulF, &[551, 551, 552], 1209);
                step(f, Op::MulF, &[68, 922, 553], 1210);
                step(f, Op::DivF, &[552, 553, 554], 1211);
                step(f, Op::SubF, &[547, 554, 555], 1212);
                step(f, Op::DivF, &[555, 547, 556], 1213);
                step(f, Op::ScaleV, &[194, 556, 195], 1214);
                step(f, Op::AddV, &[186, 195, 196], 1215);
                step(f, Op::MakeTransform, &[196, 27, 477, 40], 1216);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 3, 40], 1217);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 3, 40], 1218);
                step(f, Op::Jump, &[1361], 1219)
            }
            1219 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 3, 39], 1220);
                step(f, Op::BreakTransform, &[39, 192, 27, 193], 1221);
                step(f, Op::SubV, &[192, 186, 194], 1222);
                step(f, Op::LengthV, &[194, 547], 1223);
                step(f, Op::SubF, &[67, 68, 548], 1224);
                step(f, Op::SubF, &[547, 548, 549], 1225);
                step(f, Op::MulF, &[68, 911, 550], 1226);
                step(f, Op::ClampF, &[549, 906, 550, 551], 1227);
                step(f, Op::MulF, &[551, 551, 552], 1228);
                step(f, Op::MulF, &[68, 922, 553], 1229);
                step(f, Op::DivF, &[552, 553, 554], 1230);
                step(f, Op::SubF, &[547, 554, 555], 1231);
                step(f, Op::DivF, &[555, 547, 556], 1232);
                step(f, Op::ScaleV, &[194, 556, 195], 1233);
                step(f, Op::AddV, &[186, 195, 196], 1234);
                step(f, Op::MakeTransform, &[196, 27, 477, 40], 1235);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 3, 68], 1236);
                step(f, Op::ClampF, &[534, 906, 908, 664], 1237);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[6, 5], 1238);
                step(f, Op::ArrayReset(Elem::Vec3), &[5], 1239);
                step(f, Op::BreakTransform, &[40, 318, 47, 319], 1240);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 318], 1241);
                step(f, Op::UnitV, &[2, 317], 1242);
                step(f, Op::LengthV, &[2, 692], 1243);
                step(f, Op::RemapF, &[692, 906, 69, 906, 70, 128, 693], 1244);
                step(f, Op::ScaleV, &[317, 693, 322], 1245);
                step(f, Op::SubV, &[318, 322, 328], 1246);
                step(f, Op::MakeVector, &[906, 906, 72, 326], 1247);
                step(f, Op::AddV, &[328, 326, 330], 1248);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 330], 1249);
                step(f, Op::RemapF, &[692, 906, 69, 906, 74, 128, 695], 1250);
                step(f, Op::MakeVector, &[906, 906, 695, 324], 1251);
                step(f, Op::AddV, &[330, 324, 334], 1252);
                step(f, Op::BreakTransform, &[68, 320, 48, 321], 1253);
                step(f, Op::BreakVector, &[320, 700, 701, 702], 1254);
                step(f, Op::BreakVector, &[318, 697, 698, 699], 1255);
                step(f, Op::SubF, &[702, 699, 703], 1256);
                step(f, Op::MaxF, &[703, 906, 705], 1257);
                step(f, Op::MulF, &[705, 76, 709], 1258);
                step(f, Op::MinF, &[709, 77, 710], 1259);
                step(f, Op::AbsF, &[703, 707], 1260);
                step(f, Op::RemapF, &[707, 906, 80, 906, 79, 128, 708], 1261);
                step(f, Op::AddF, &[710, 708, 712], 1262);
                step(f, Op::MakeVector, &[906, 906, 712, 332], 1263);
                step(f, Op::AddV, &[334, 332, 336], 1264);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 336], 1265);
                step(f, Op::RemapF, &[692, 906, 69, 906, 71, 128, 694], 1266);
                step(f, Op::ScaleV, &[317, 694, 323], 1267);
                step(f, Op::AddV, &[320, 323, 329], 1268);
                step(f, Op::MakeVector, &[906, 906, 73, 327], 1269);
                step(f, Op::AddV, &[329, 327, 331], 1270);
                step(f, Op::RemapF, &[692, 906, 69, 906, 75, 128, 696], 1271);
                step(f, Op::MakeVector, &[906, 906, 696, 325], 1272);
                step(f, Op::AddV, &[331, 325, 335], 1273);
                step(f, Op::NegF, &[703, 704], 1274);
                step(f, Op::MaxF, &[704, 906, 706], 1275);
                step(f, Op::MulF, &[706, 78, 711], 1276);
                step(f, Op::AddF, &[711, 708, 713], 1277);
                step(f, Op::MakeVector, &[906, 906, 713, 333], 1278);
                step(f, Op::AddV, &[335, 333, 337], 1279);
                step(f, Op::LerpV, &[336, 337, 907, 338], 1280);
                step(f, Op::GetTransform, &[35, 71, 128, 77], 1281);
                step(f, Op::BreakTransform, &[77, 339, 49, 340], 1282);
                step(f, Op::BreakVector, &[339, 723, 724, 725], 1283);
                step(f, Op::SubF, &[908, 15, 717], 1284);
                step(f, Op::MulF, &[81, 717, 718], 1285);
                step(f, Op::MulF, &[14, 718, 719], 1286);
                step(f, Op::QuatFromAxisAngle, &[480, 719, 50], 1287);
                step(f, Op::SubV, &[338, 339, 341], 1288);
                step(f, Op::BreakVector, &[341, 714, 715, 716], 1289);
                step(f, Op::MakeVector, &[714, 715, 906, 342], 1290);
                step(f, Op::RotateVector, &[50, 342, 343], 1291);
                step(f, Op::BreakVector, &[343, 720, 721, 722], 1292);
                step(f, Op::AddF, &[723, 720, 729], 1293);
                step(f, Op::AddF, &[724, 721, 730], 1294);
                step(f, Op::BreakVector, &[338, 726, 727, 728], 1295);
                step(f, Op::MakeVector, &[729, 730, 728, 344], 1296);
                step(f, Op::DistanceV, &[318, 320, 731], 1297);
                step(f, Op::RemapF, &[731, 911, 923, 906, 908, 128, 732], 1298);
                step(f, Op::LerpV, &[338, 344, 732, 345], 1299);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 345], 1300);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 337], 1301);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 331], 1302);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 320], 1303);
                step(f, Op::JumpIfFalse, &[8, 1305], 1304)
            }
            1304 => {
                step(f, Op::DrawSpline, &[5, 71, 74, 907, 483], 1305);
                1305
            }
            1305 => {
                step(f, Op::Spline, &[5, 664, 71, 346, 347], 1306);
                step(f, Op::SlerpQ, &[47, 48, 664, 51], 1307);
                step(f, Op::MulF, &[664, 916, 734], 1308);
                step(f, Op::SinF, &[734, 735], 1309);
                step(f, Op::SmoothStepF, &[664, 906, 94, 733], 1310);
                step(f, Op::MulF, &[735, 733, 736], 1311);
                step(f, Op::MulF, &[736, 82, 737], 1312);
                step(f, Op::SlerpQ, &[51, 94, 737, 52], 1313);
                step(f, Op::MakeTransform, &[346, 52, 477, 78], 1314);
                step(f, Op::Copy(ValueType::Transform), &[78, 76], 1315);
                step(f, Op::BreakTransform, &[76, 299, 43, 300], 1316);
                step(f, Op::Equals(Elem::Int), &[3, 71, 93], 1317);
                step(f, Op::Select(ValueType::Int), &[93, 72, 71, 59], 1318);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 59, 47], 1319);
                step(f, Op::BreakTransform, &[47, 205, 30, 206], 1320);
                step(f, Op::SubF, &[908, 15, 561], 1321);
                step(f, Op::MulF, &[14, 561, 562], 1322);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 59, 108], 1323);
                step(f, Op::Select(ValueType::Float), &[108, 85, 906, 667], 1324);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 534], 1325);
                step(f, Op::ClampF, &[534, 906, 908, 664], 1326);
                step(f, Op::MulF, &[664, 916, 665], 1327);
                step(f, Op::SinF, &[665, 666], 1328);
                step(f, Op::MulF, &[666, 666, 668], 1329);
                step(f, Op::MulF, &[667, 668, 669], 1330);
                step(f, Op::AddF, &[84, 669, 670], 1331);
                step(f, Op::FootAvoidance, &[299, 205, 562, 93, 670, 301], 1332);
                step(f, Op::SubV, &[301, 299, 302], 1333);
                step(f, Op::LengthV, &[302, 671], 1334);
                step(f, Op::AddF, &[671, 669, 672], 1335);
                step(f, Op::DivF, &[671, 672, 673], 1336);
                step(f, Op::ArrayAt(Elem::Float), &[2, 59, 676], 1337);
                step(f, Op::LessF, &[676, 534, 110], 1338);
                step(f, Op::LessEqualF, &[86, 906, 109], 1339);
                step(f, Op::SmoothStepF, &[676, 906, 86, 677], 1340);
                step(f, Op::MulF, &[677, 15, 678], 1341);
                step(f, Op::SubF, &[908, 678, 679], 1342);
                step(f, Op::Select(ValueType::Float), &[109, 908, 679, 680], 1343);
                step(f, Op::Select(ValueType::Float), &[110, 680, 908, 681], 1344);
                step(f, Op::MulF, &[673, 681, 682], 1345);
                step(f, Op::SmoothStepF, &[664, 906, 86, 674], 1346);
                step(f, Op::Select(ValueType::Float), &[109, 908, 674, 675], 1347);
                step(f, Op::MulF, &[682, 675, 683], 1348);
                step(f, Op::ScaleV, &[302, 683, 303], 1349);
                step(f, Op::AddV, &[299, 303, 304], 1350);
                step(f, Op::MulF, &[3, 134, 684], 1351);
                step(f, Op::MulF, &[684, 668, 685], 1352);
                step(f, Op::MakeVector, &[906, 906, 685, 305], 1353);
                step(f, Op::AddV, &[304, 305, 306], 1354);
                step(f, Op::MakeTransform, &[306, 43, 477, 69], 1355);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 3, 69], 1356);
                step(f, Op::ScaleV, &[302, 682, 307], 1357);
                step(f, Op::AddV, &[299, 307, 308], 1358);
                step(f, Op::AddV, &[308, 305, 309], 1359);
                step(f, Op::MakeTransform, &[309, 43, 477, 70], 1360);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 3, 70], 1361);
                1361
            }
            1361 => {
                step(f, Op::GreaterF, &[21, 906, 94], 1362);
                step(f, Op::JumpIfFalse, &[94, 1385], 1363)
            }
            1363 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 3, 71], 1364);
                step(f, Op::BreakTransform, &[71, 310, 44, 311], 1365);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 3, 72], 1366);
                step(f, Op::BreakTransform, &[72, 312, 45, 313], 1367);
                step(f, Op::MulF, &[21, 21, 686], 1368);
                step(f, Op::LerpV, &[310, 312, 686, 314], 1369);
                step(f, Op::SubF, &[908, 21, 687], 1370);
                step(f, Op::MulF, &[21, 687, 688], 1371);
                step(f, Op::MulF, &[136, 911, 689], 1372);
                step(f, Op::MulF, &[688, 689, 690], 1373);
                step(f, Op::MakeVector, &[906, 906, 690, 315], 1374);
                step(f, Op::AddV, &[314, 315, 316], 1375);
                step(f, Op::SlerpQ, &[44, 45, 21, 46], 1376);
                step(f, Op::MakeTransform, &[316, 46, 477, 73], 1377);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 3, 73], 1378);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 3, 71], 1379);
                step(f, Op::BreakTransform, &[71, 310, 44, 311], 1380);
                step(f, Op::LerpV, &[310, 312, 686, 314], 1381);
                step(f, Op::AddV, &[314, 315, 316], 1382);
                step(f, Op::SlerpQ, &[44, 45, 21, 46], 1383);
                step(f, Op::MakeTransform, &[316, 46, 477, 73], 1384);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 3, 73], 1385);
                1385
            }
            1385 => {
                step(f, Op::GreaterEqualF, &[534, 908, 92], 1386);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 3, 92], 1387);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 41], 1388);
                step(f, Op::BreakTransform, &[41, 197, 28, 198], 1389);
                step(f, Op::SubF, &[908, 534, 557], 1390);
                step(f, Op::MulF, &[10, 7, 558], 1391);
                step(f, Op::MulF, &[557, 558, 559], 1392);
                step(f, Op::ScaleV, &[2, 559, 199], 1393);
                step(f, Op::AddV, &[197, 199, 200], 1394);
                step(f, Op::Equals(Elem::Int), &[3, 71, 93], 1395);
                step(f, Op::Select(ValueType::Int), &[93, 72, 71, 59], 1396);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 59, 96], 1397);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 59, 42], 1398);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 59, 43], 1399);
                step(f, Op::Select(ValueType::Transform), &[96, 42, 43, 44], 1400);
                step(f, Op::InterpolateTransform, &[2, 121, 22, 33], 1401);
                step(f, Op::Select(ValueType::Transform), &[94, 33, 2, 34], 1402);
                step(f, Op::MakeAbsolute, &[44, 34, 45], 1403);
                step(f, Op::Select(ValueType::Transform), &[93, 45, 44, 46], 1404);
                step(f, Op::BreakTransform, &[46, 201, 29, 202], 1405);
                step(f, Op::MulF, &[14, 561, 562], 1406);
                step(f, Op::FootAvoidance, &[200, 201, 562, 93, 84, 203], 1407);
                step(f, Op::RemapF, &[15, 87, 908, 906, 908, 128, 560], 1408);
                step(f, Op::LerpV, &[200, 203, 560, 204], 1409);
                step(f, Op::MakeTransform, &[204, 94, 477, 62], 1410);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 3, 62], 1411);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 3, 79], 1412);
                step(f, Op::BreakTransform, &[79, 348, 53, 349], 1413);
                step(f, Op::MakeVector, &[906, 906, 53, 358], 1414);
                step(f, Op::AddV, &[348, 358, 359], 1415);
                step(f, Op::GetTransform, &[0, 71, 128, 81], 1416);
                step(f, Op::BreakTransform, &[81, 353, 55, 354], 1417);
                step(f, Op::MakeTransform, &[359, 55, 477, 83], 1418);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 3, 20], 1419);
                step(f, Op::GetTransform, &[20, 71, 128, 82], 1420);
                step(f, Op::BreakTransform, &[82, 355, 56, 356], 1421);
                step(f, Op::SubV, &[355, 353, 357], 1422);
                step(f, Op::AddV, &[359, 357, 360], 1423);
                step(f, Op::FootPivots, &[359, 360, 55, 54, 53, 56, 361, 362, 363], 1424);
                step(f, Op::GetParent, &[0, 18], 1425);
                step(f, Op::GetParent, &[18, 19], 1426);
                step(f, Op::GetTransform, &[19, 71, 129, 80], 1427);
                step(f, Op::BreakTransform, &[80, 350, 54, 351], 1428);
                step(f, Op::SubV, &[348, 350, 352], 1429);
                step(f, Op::DotV, &[352, 481, 738], 1430);
                step(f, Op::RemapF, &[738, 89, 88, 90, 906, 128, 741], 1431);
                step(f, Op::LengthV, &[2, 739], 1432);
                step(f, Op::RemapF, &[739, 906, 100, 906, 908, 128, 740], 1433);
                step(f, Op::MulF, &[741, 740, 742], 1434);
                step(f, Op::QuatFromAxisAngle, &[484, 742, 57], 1435);
                step(f, Op::RotateAroundPoint, &[83, 361, 57, 84], 1436);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 743], 1437);
                step(f, Op::SmoothStepF, &[743, 906, 94, 745], 1438);
                step(f, Op::SubF, &[908, 743, 744], 1439);
                step(f, Op::SmoothStepF, &[744, 906, 94, 746], 1440);
                step(f, Op::MulF, &[745, 746, 747], 1441);
                step(f, Op::LerpF, &[93, 908, 747, 748], 1442);
                step(f, Op::MulF, &[742, 748, 749], 1443);
                step(f, Op::QuatFromAxisAngle, &[484, 749, 58], 1444);
                step(f, Op::SubV, &[362, 361, 364], 1445);
                step(f, Op::RotateVector, &[58, 364, 365], 1446);
                step(f, Op::AddV, &[361, 365, 366], 1447);
                step(f, Op::RemapF, &[738, 91, 89, 92, 906, 128, 750], 1448);
                step(f, Op::MulF, &[750, 740, 751], 1449);
                step(f, Op::QuatFromAxisAngle, &[484, 751, 59], 1450);
                step(f, Op::RotateAroundPoint, &[84, 366, 59, 85], 1451);
                step(f, Op::RemapF, &[738, 95, 96, 906, 97, 128, 752], 1452);
                step(f, Op::RotateVector, &[53, 480, 367], 1453);
                step(f, Op::BreakVector, &[367, 753, 754, 755], 1454);
                step(f, Op::CosF, &[99, 757], 1455);
                step(f, Op::CosF, &[98, 756], 1456);
                step(f, Op::RemapF, &[755, 757, 756, 906, 908, 128, 758], 1457);
                step(f, Op::MulF, &[740, 758, 759], 1458);
                step(f, Op::MulF, &[752, 759, 760], 1459);
                step(f, Op::QuatFromAxisAngle, &[484, 760, 60], 1460);
                step(f, Op::RotateAroundPoint, &[85, 363, 60, 86], 1461);
                step(f, Op::SubF, &[908, 15, 761], 1462);
                step(f, Op::MulF, &[14, 761, 762], 1463);
                step(f, Op::LimitRotationAroundZ, &[53, 762, 101, 61], 1464);
                step(f, Op::RotateAroundPoint, &[86, 348, 61, 87], 1465);
                step(f, Op::BreakTransform, &[87, 368, 62, 369], 1466);
                step(f, Op::ArrayAt(Elem::Float), &[4, 3, 763], 1467);
                step(f, Op::MulF, &[763, 102, 764], 1468);
                step(f, Op::MulF, &[764, 103, 765], 1469);
                step(f, Op::AddF, &[764, 103, 766], 1470);
                step(f, Op::DivF, &[765, 766, 767], 1471);
                step(f, Op::MakeVector, &[906, 906, 767, 370], 1472);
                step(f, Op::AddV, &[368, 370, 371], 1473);
                step(f, Op::MakeTransform, &[371, 62, 369, 88], 1474);
                step(f, Op::ArraySetAt(Elem::Transform), &[7, 3, 88], 1475);
                step(f, Op::JumpIfFalse, &[8, 1480], 1476)
            }
            1476 => {
                step(f, Op::DrawPoint, &[363, 924, 484], 1477);
                step(f, Op::DrawPoint, &[361, 924, 481], 1478);
                step(f, Op::DrawPoint, &[366, 924, 480], 1479);
                step(f, Op::DrawTransform, &[79, 923, 907], 1480);
                1480
            }
            1480 => {
                step(f, Op::Jump, &[617], 1481)
            }
            1481 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1482);
                step(f, Op::Copy(ValueType::Int), &[71, 5], 1483);
                1483
            }
            1483 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 5, 1, 6, 7, 1522], 1484)
            }
            1484 => {
                step(f, Op::GetParent, &[1, 22], 1485);
                step(f, Op::GetParent, &[22, 23], 1486);
                step(f, Op::GetParent, &[23, 24], 1487);
                step(f, Op::GetTransform, &[24, 71, 129, 89], 1488);
                step(f, Op::BreakTransform, &[89, 372, 63, 373], 1489);
                step(f, Op::LengthV, &[1, 769], 1490);
                step(f, Op::ClavicleOffset, &[12, 769, 109, 113, 770], 1491);
                step(f, Op::MakeVector, &[906, 906, 770, 374], 1492);
                step(f, Op::AddV, &[372, 374, 375], 1493);
                step(f, Op::MakeTransform, &[375, 63, 477, 90], 1494);
                step(f, Op::SetTransform, &[24, 90, 71, 128, 908], 1495);
                step(f, Op::GetTransform, &[1, 71, 129, 91], 1496);
                step(f, Op::GetTransform, &[23, 71, 129, 92], 1497);
                step(f, Op::BreakTransform, &[92, 376, 65, 377], 1498);
                step(f, Op::Equals(Elem::Int), &[6, 71, 111], 1499);
                step(f, Op::Select(ValueType::Int), &[111, 72, 71, 62], 1500);
                step(f, Op::ArrayAt(Elem::Float), &[0, 62, 768], 1501);
                step(f, Op::ArmSwingRotation, &[768, 1, 0, 110, 915, 925, 908, 109, 107, 108, 111, 915, 908, 771], 1502);
                step(f, Op::QuatFromAxisAngle, &[484, 771, 64], 1503);
                step(f, Op::RotateAroundPoint, &[91, 376, 64, 93], 1504);
                step(f, Op::BreakTransform, &[93, 378, 66, 379], 1505);
                step(f, Op::RemapF, &[769, 906, 109, 906, 112, 128, 772], 1506);
                step(f, Op::MakeVector, &[906, 906, 772, 380], 1507);
                step(f, Op::AddV, &[378, 380, 381], 1508);
                step(f, Op::MakeTransform, &[381, 66, 477, 94], 1509);
                step(f, Op::Select(ValueType::Vec3), &[111, 485, 484, 383], 1510);
                step(f, Op::Select(ValueType::Vec3), &[111, 481, 486, 384], 1511);
                step(f, Op::ArrayAt(Elem::Vec3), &[4, 6, 382], 1512);
                step(f, Op::TwoBoneIK, &[23, 22, 1, 94, 383, 384, 382, 71, 908, 129, 926, 927, 128, 112, 773], 1513);
                step(f, Op::JumpIfFalse, &[8, 1521], 1514)
            }
            1514 => {
                step(f, Op::GetTransform, &[23, 71, 129, 92], 1515);
                step(f, Op::BreakTransform, &[92, 376, 65, 377], 1516);
                step(f, Op::GetTransform, &[1, 71, 129, 91], 1517);
                step(f, Op::RotateAroundPoint, &[91, 376, 64, 93], 1518);
                step(f, Op::BreakTransform, &[93, 378, 66, 379], 1519);
                step(f, Op::AddV, &[378, 380, 381], 1520);
                step(f, Op::DrawLine, &[376, 381, 907, 481], 1521);
                1521
            }
            1521 => {
                step(f, Op::Jump, &[1483], 1522)
            }
            1522 => {
                step(f, Op::NegF, &[3, 884], 1523);
                step(f, Op::MakeVector, &[906, 906, 884, 459], 1524);
                step(f, Op::MakeTransform, &[459, 94, 477, 115], 1525);
                step(f, Op::SetTransform, &[36, 115, 71, 128, 908], 1526);
                step(f, Op::Copy(ValueType::Float), &[913, 777], 1527);
                step(f, Op::Copy(ValueType::Bool), &[129, 113], 1528);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 11], 1529);
                step(f, Op::Copy(ValueType::Int), &[71, 63], 1530);
                step(f, Op::MakeVector, &[906, 906, 58, 387], 1531);
                1531
            }
            1531 => {
                step(f, Op::ForEachNext(Elem::Transform), &[11, 63, 95, 64, 65, 1543], 1532)
            }
            1532 => {
                step(f, Op::BreakTransform, &[95, 385, 67, 386], 1533);
                step(f, Op::AddV, &[385, 387, 388], 1534);
                step(f, Op::SubV, &[385, 387, 389], 1535);
                step(f, Op::SphereTrace, &[388, 389, 57, 114, 390, 391, 778], 1536);
                step(f, Op::BreakVector, &[390, 779, 780, 781], 1537);
                step(f, Op::LessF, &[781, 777, 115], 1538);
                step(f, Op::And, &[114, 115, 116], 1539);
                step(f, Op::JumpIfFalse, &[116, 1542], 1540)
            }
            1540 => {
                step(f, Op::Copy(ValueType::Float), &[781, 777], 1541);
                step(f, Op::Copy(ValueType::Bool), &[128, 113], 1542);
                1542
            }
            1542 => {
                step(f, Op::Jump, &[1531], 1543)
            }
            1543 => {
                step(f, Op::Select(ValueType::Float), &[113, 777, 906, 782], 1544);
                step(f, Op::ClampF, &[782, 63, 64, 783], 1545);
                step(f, Op::Copy(ValueType::Float), &[783, 776], 1546);
                step(f, Op::SubF, &[908, 21, 775], 1547);
                step(f, Op::MulF, &[776, 775, 784], 1548);
                step(f, Op::SubF, &[908, 133, 785], 1549);
                step(f, Op::MulF, &[3, 785, 786], 1550);
                step(f, Op::AddF, &[784, 786, 787], 1551);
                step(f, Op::MakeVector, &[16, 906, 906, 392], 1552);
                step(f, Op::MakeVector, &[787, 906, 906, 393], 1553);
                step(f, Op::Select(ValueType::Float), &[2, 787, 17, 788], 1554);
                step(f, Op::MakeVector, &[788, 906, 906, 394], 1555);
                step(f, Op::Copy(ValueType::Float), &[51, 789], 1556);
                step(f, Op::Copy(ValueType::Float), &[52, 790], 1557);
                step(f, Op::SubV, &[393, 394, 399], 1558);
                step(f, Op::DeltaTime, &[791], 1559);
                step(f, Op::DivF, &[790, 791, 792], 1560);
                step(f, Op::ScaleV, &[399, 792, 400], 1561);
                step(f, Op::AddV, &[393, 400, 401], 1562);
                step(f, Op::AddV, &[394, 400, 402], 1563);
                step(f, Op::SubV, &[392, 402, 403], 1564);
                step(f, Op::FloatLerp, &[906, 908, 789, 793], 1565);
                step(f, Op::SubF, &[908, 793, 794], 1566);
                step(f, Op::ScaleV, &[403, 794, 404], 1567);
                step(f, Op::AddV, &[401, 404, 406], 1568);
                step(f, Op::MulF, &[789, 791, 795], 1569);
                step(f, Op::GreaterF, &[795, 906, 117], 1570);
                step(f, Op::DivF, &[793, 795, 796], 1571);
                step(f, Op::Select(ValueType::Float), &[117, 796, 908, 797], 1572);
                step(f, Op::ScaleV, &[399, 797, 405], 1573);
                step(f, Op::SubV, &[406, 405, 407], 1574);
                step(f, Op::Copy(ValueType::Vec3), &[407, 398], 1575);
                step(f, Op::BreakVector, &[398, 798, 799, 800], 1576);
                step(f, Op::Select(ValueType::Float), &[1, 787, 798, 801], 1577);
                step(f, Op::Copy(ValueType::Float), &[801, 16], 1578);
                step(f, Op::Copy(ValueType::Float), &[787, 17], 1579);
                step(f, Op::GetTransform, &[37, 71, 128, 100], 1580);
                step(f, Op::BreakTransform, &[100, 420, 74, 421], 1581);
                step(f, Op::PelvisLean, &[1, 116, 121, 122, 819, 820], 1582);
                step(f, Op::LengthV, &[2, 774], 1583);
                step(f, Op::RemapF, &[774, 906, 116, 906, 114, 128, 802], 1584);
                step(f, Op::MulF, &[15, 115, 805], 1585);
                step(f, Op::SubF, &[908, 805, 806], 1586);
                step(f, Op::MulF, &[802, 806, 807], 1587);
                step(f, Op::MulF, &[12, 928, 803], 1588);
                step(f, Op::SinF, &[803, 804], 1589);
                step(f, Op::MulF, &[807, 804, 808], 1590);
                step(f, Op::MulF, &[808, 775, 809], 1591);
                step(f, Op::AddF, &[809, 16, 810], 1592);
                step(f, Op::SubF, &[810, 3, 811], 1593);
                step(f, Op::MakeVector, &[906, 820, 811, 422], 1594);
                step(f, Op::AddV, &[420, 422, 423], 1595);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 71, 96], 1596);
                step(f, Op::BreakTransform, &[96, 408, 68, 409], 1597);
                step(f, Op::BreakVector, &[408, 821, 822, 823], 1598);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 72, 97], 1599);
                step(f, Op::BreakTransform, &[97, 410, 69, 411], 1600);
                step(f, Op::BreakVector, &[410, 824, 825, 826], 1601);
                step(f, Op::SubF, &[823, 826, 827], 1602);
                step(f, Op::PelvisSideLean, &[827, 123, 124, 828], 1603);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 71, 98], 1604);
                step(f, Op::BreakTransform, &[98, 414, 70, 415], 1605);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 72, 99], 1606);
                step(f, Op::BreakTransform, &[99, 416, 71, 417], 1607);
                step(f, Op::SlerpQ, &[70, 71, 907, 72], 1608);
                step(f, Op::EulerFromQuat, &[72, 71, 418], 1609);
                step(f, Op::BreakVector, &[418, 815, 816, 817], 1610);
                step(f, Op::RemapF, &[774, 117, 116, 906, 118, 128, 813], 1611);
                step(f, Op::SubV, &[408, 410, 412], 1612);
                step(f, Op::RotateVector, &[0, 481, 413], 1613);
                step(f, Op::DotV, &[412, 413, 812], 1614);
                step(f, Op::MulF, &[813, 812, 814], 1615);
                step(f, Op::AddF, &[817, 814, 818], 1616);
                step(f, Op::MakeVector, &[819, 828, 818, 419], 1617);
                step(f, Op::QuatFromEuler, &[419, 71, 73], 1618);
                step(f, Op::MakeTransform, &[423, 73, 477, 101], 1619);
                step(f, Op::SetTransform, &[38, 101, 71, 128, 908], 1620);
                step(f, Op::GetTransform, &[39, 72, 128, 102], 1621);
                step(f, Op::BreakTransform, &[102, 424, 78, 425], 1622);
                step(f, Op::QuatFromAxisAngle, &[480, 814, 75], 1623);
                step(f, Op::DivF, &[119, 924, 829], 1624);
                step(f, Op::QuatScale, &[75, 829, 76], 1625);
                step(f, Op::MulQ, &[78, 76, 82], 1626);
                step(f, Op::MakeTransform, &[424, 82, 477, 106], 1627);
                step(f, Op::SetTransform, &[40, 106, 72, 128, 908], 1628);
                step(f, Op::GetTransform, &[41, 72, 128, 103], 1629);
                step(f, Op::BreakTransform, &[103, 426, 79, 427], 1630);
                step(f, Op::MulQ, &[79, 76, 83], 1631);
                step(f, Op::MakeTransform, &[426, 83, 477, 107], 1632);
                step(f, Op::SetTransform, &[42, 107, 72, 128, 908], 1633);
                step(f, Op::GetTransform, &[43, 72, 128, 104], 1634);
                step(f, Op::BreakTransform, &[104, 428, 80, 429], 1635);
                step(f, Op::MulQ, &[80, 76, 84], 1636);
                step(f, Op::MakeTransform, &[428, 84, 477, 108], 1637);
                step(f, Op::SetTransform, &[44, 108, 72, 128, 908], 1638);
                step(f, Op::GetTransform, &[45, 72, 128, 105], 1639);
                step(f, Op::BreakTransform, &[105, 430, 81, 431], 1640);
                step(f, Op::QuatScale, &[75, 120, 77], 1641);
                step(f, Op::MulQ, &[81, 77, 85], 1642);
                step(f, Op::MakeTransform, &[430, 85, 477, 109], 1643);
                step(f, Op::SetTransform, &[46, 109, 72, 128, 908], 1644);
                step(f, Op::Or, &[1, 2, 123], 1645);
                step(f, Op::Copy(ValueType::Float), &[906, 831], 1646);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1647);
                step(f, Op::Copy(ValueType::Int), &[71, 66], 1648);
                1648
            }
            1648 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 66, 25, 67, 68, 1695], 1649)
            }
            1649 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 67, 118], 1650);
                step(f, Op::GetParent, &[25, 26], 1651);
                step(f, Op::GetParent, &[26, 27], 1652);
                step(f, Op::GetTransform, &[27, 71, 129, 110], 1653);
                step(f, Op::BreakTransform, &[110, 432, 86, 433], 1654);
                step(f, Op::BreakVector, &[432, 832, 833, 834], 1655);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 67, 111], 1656);
                step(f, Op::BreakTransform, &[111, 434, 87, 435], 1657);
                step(f, Op::BreakVector, &[434, 835, 836, 837], 1658);
                step(f, Op::ArrayAt(Elem::Float), &[1, 67, 841], 1659);
                step(f, Op::MulF, &[841, 125, 842], 1660);
                step(f, Op::MulF, &[842, 842, 843], 1661);
                step(f, Op::SubF, &[832, 835, 838], 1662);
                step(f, Op::SubF, &[833, 836, 839], 1663);
                step(f, Op::MakeVector, &[838, 839, 906, 436], 1664);
                step(f, Op::DotV, &[436, 436, 840], 1665);
                step(f, Op::SubF, &[843, 840, 844], 1666);
                step(f, Op::SqrtF, &[844, 845], 1667);
                step(f, Op::AddF, &[837, 845, 846], 1668);
                step(f, Op::SubF, &[834, 846, 847], 1669);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 67, 112], 1670);
                step(f, Op::BreakTransform, &[112, 437, 88, 438], 1671);
                step(f, Op::BreakVector, &[437, 848, 849, 850], 1672);
                step(f, Op::AddF, &[850, 53, 851], 1673);
                step(f, Op::MinF, &[837, 851, 852], 1674);
                step(f, Op::AddF, &[852, 845, 853], 1675);
                step(f, Op::SubF, &[834, 853, 854], 1676);
                step(f, Op::Equals(Elem::Int), &[67, 71, 119], 1677);
                step(f, Op::Select(ValueType::Int), &[119, 72, 71, 69], 1678);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 69, 120], 1679);
                step(f, Op::ArrayAt(Elem::Float), &[2, 69, 858], 1680);
                step(f, Op::RemapF, &[858, 907, 908, 906, 908, 128, 859], 1681);
                step(f, Op::RemapF, &[858, 906, 128, 908, 906, 128, 860], 1682);
                step(f, Op::MaxF, &[859, 860, 861], 1683);
                step(f, Op::Select(ValueType::Float), &[120, 908, 861, 862], 1684);
                step(f, Op::LerpF, &[847, 854, 862, 863], 1685);
                step(f, Op::ArrayAt(Elem::Float), &[2, 67, 855], 1686);
                step(f, Op::RemapF, &[855, 907, 908, 906, 908, 128, 856], 1687);
                step(f, Op::MulF, &[863, 856, 864], 1688);
                step(f, Op::RemapF, &[855, 906, 128, 908, 906, 128, 857], 1689);
                step(f, Op::MulF, &[847, 857, 865], 1690);
                step(f, Op::MaxF, &[864, 865, 866], 1691);
                step(f, Op::Select(ValueType::Float), &[118, 847, 866, 867], 1692);
                step(f, Op::MaxF, &[831, 867, 868], 1693);
                step(f, Op::Copy(ValueType::Float), &[868, 831], 1694);
                step(f, Op::Jump, &[1648], 1695)
            }
            1695 => {
                step(f, Op::ClampF, &[831, 906, 126, 869], 1696);
                step(f, Op::Copy(ValueType::Float), &[869, 830], 1697);
                step(f, Op::MakeVector, &[18, 906, 906, 439], 1698);
                step(f, Op::MakeVector, &[830, 906, 906, 440], 1699);
                step(f, Op::MakeVector, &[19, 906, 906, 441], 1700);
                step(f, Op::GreaterF, &[830, 18, 121], 1701);
                step(f, Op::Select(ValueType::Float), &[121, 130, 127, 870], 1702);
                step(f, Op::Copy(ValueType::Float), &[52, 872], 1703);
                step(f, Op::SubV, &[440, 441, 446], 1704);
                step(f, Op::DeltaTime, &[873], 1705);
                step(f, Op::DivF, &[872, 873, 874], 1706);
                step(f, Op::ScaleV, &[446, 874, 447], 1707);
                step(f, Op::AddV, &[440, 447, 448], 1708);
                step(f, Op::AddV, &[441, 447, 449], 1709);
                step(f, Op::SubV, &[439, 449, 450], 1710);
                step(f, Op::FloatLerp, &[906, 908, 870, 875], 1711);
                step(f, Op::SubF, &[908, 875, 876], 1712);
                step(f, Op::ScaleV, &[450, 876, 451], 1713);
                step(f, Op::AddV, &[448, 451, 453], 1714);
                step(f, Op::MulF, &[870, 873, 877], 1715);
                step(f, Op::GreaterF, &[877, 906, 122], 1716);
                step(f, Op::DivF, &[875, 877, 878], 1717);
                step(f, Op::Select(ValueType::Float), &[122, 878, 908, 879], 1718);
                step(f, Op::ScaleV, &[446, 879, 452], 1719);
                step(f, Op::SubV, &[453, 452, 454], 1720);
                step(f, Op::Copy(ValueType::Vec3), &[454, 445], 1721);
                step(f, Op::BreakVector, &[445, 880, 881, 882], 1722);
                step(f, Op::Select(ValueType::Float), &[123, 830, 880, 883], 1723);
                step(f, Op::Copy(ValueType::Float), &[883, 18], 1724);
                step(f, Op::Copy(ValueType::Float), &[830, 19], 1725);
                step(f, Op::GetTransform, &[47, 71, 129, 113], 1726);
                step(f, Op::BreakTransform, &[113, 455, 89, 456], 1727);
                step(f, Op::MakeVector, &[906, 906, 18, 457], 1728);
                step(f, Op::SubV, &[455, 457, 458], 1729);
                step(f, Op::MakeTransform, &[458, 89, 477, 114], 1730);
                step(f, Op::SetTransform, &[48, 114, 71, 128, 908], 1731);
                step(f, Op::JumpIfFalse, &[8, 1737], 1732)
            }
            1732 => {
                step(f, Op::GetTransform, &[47, 71, 129, 113], 1733);
                step(f, Op::BreakTransform, &[113, 455, 89, 456], 1734);
                step(f, Op::SubV, &[455, 457, 458], 1735);
                step(f, Op::MakeTransform, &[458, 89, 477, 114], 1736);
                step(f, Op::DrawTransform, &[114, 929, 907], 1737);
                1737
            }
            1737 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1738);
                step(f, Op::Copy(ValueType::Int), &[71, 8], 1739);
                1739
            }
            1739 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 8, 2, 9, 10, 1787], 1740)
            }
            1740 => {
                step(f, Op::GetParent, &[2, 29], 1741);
                step(f, Op::GetParent, &[29, 30], 1742);
                step(f, Op::GetTransform, &[30, 71, 129, 116], 1743);
                step(f, Op::BreakTransform, &[116, 460, 90, 461], 1744);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 9, 117], 1745);
                step(f, Op::BreakTransform, &[117, 462, 91, 463], 1746);
                step(f, Op::SubV, &[462, 460, 464], 1747);
                step(f, Op::LengthV, &[464, 896], 1748);
                step(f, Op::ArrayAt(Elem::Float), &[1, 9, 885], 1749);
                step(f, Op::MulF, &[885, 137, 886], 1750);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 9, 124], 1751);
                step(f, Op::ArrayAt(Elem::Float), &[2, 9, 887], 1752);
                step(f, Op::ClampF, &[887, 906, 908, 888], 1753);
                step(f, Op::LessF, &[888, 907, 125], 1754);
                step(f, Op::SmoothStepF, &[888, 139, 140, 891], 1755);
                step(f, Op::MulF, &[888, 916, 889], 1756);
                step(f, Op::SinF, &[889, 890], 1757);
                step(f, Op::MaxF, &[891, 890, 892], 1758);
                step(f, Op::Select(ValueType::Float), &[125, 892, 890, 893], 1759);
                step(f, Op::MulF, &[893, 138, 894], 1760);
                step(f, Op::Select(ValueType::Float), &[124, 906, 894, 895], 1761);
                step(f, Op::SubF, &[886, 895, 897], 1762);
                step(f, Op::SubF, &[896, 897, 898], 1763);
                step(f, Op::MaxF, &[898, 906, 899], 1764);
                step(f, Op::MulF, &[899, 899, 900], 1765);
                step(f, Op::AddF, &[899, 895, 901], 1766);
                step(f, Op::DivF, &[900, 901, 902], 1767);
                step(f, Op::SubF, &[896, 902, 903], 1768);
                step(f, Op::DivF, &[903, 896, 904], 1769);
                step(f, Op::ScaleV, &[464, 904, 465], 1770);
                step(f, Op::AddV, &[460, 465, 466], 1771);
                step(f, Op::ClampSpatially, &[466, 460, 906, 886, 467], 1772);
                step(f, Op::MakeTransform, &[467, 91, 477, 118], 1773);
                step(f, Op::Equals(Elem::Int), &[9, 71, 126], 1774);
                step(f, Op::Select(ValueType::Vec3), &[126, 485, 484, 472], 1775);
                step(f, Op::Select(ValueType::Vec3), &[126, 481, 486, 473], 1776);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 9, 119], 1777);
                step(f, Op::BreakTransform, &[119, 468, 92, 469], 1778);
                step(f, Op::ArrayAt(Elem::Vec3), &[3, 9, 470], 1779);
                step(f, Op::KneeVector, &[92, 0, 470, 141, 142, 471], 1780);
                step(f, Op::TwoBoneIK, &[30, 29, 2, 118, 472, 473, 471, 71, 908, 129, 926, 927, 128, 127, 905], 1781);
                step(f, Op::JumpIfFalse, &[8, 1786], 1782)
            }
            1782 => {
                step(f, Op::GetTransform, &[29, 71, 129, 120], 1783);
                step(f, Op::BreakTransform, &[120, 474, 93, 475], 1784);
                step(f, Op::AddV, &[474, 471, 476], 1785);
                step(f, Op::DrawLine, &[474, 476, 907, 487], 1786);
                1786
            }
            1786 => {
                step(f, Op::Jump, &[1739], 1787)
            }
            1787 => {
                step(f, Op::End, &[], 1788)
            }
            _ => return,
        } };
    }
}
