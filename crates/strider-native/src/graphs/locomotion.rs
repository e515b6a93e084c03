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
    fingerprint: 0x75642ecf47bc6fd8,
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
                step(f, Op::LengthV, &[37, 159], 113);
                step(f, Op::GreaterF, &[159, 37, 10], 114);
                step(f, Op::Copy(ValueType::Bool), &[10, 2], 115);
                step(f, Op::MakeRelative, &[13, 12, 17], 116);
                step(f, Op::Select(ValueType::Transform), &[10, 124, 17, 18], 117);
                step(f, Op::Copy(ValueType::Transform), &[18, 2], 118);
                step(f, Op::InverseT, &[13, 15], 119);
                step(f, Op::MulT, &[12, 15, 16], 120);
                step(f, Op::Copy(ValueType::Transform), &[16, 1], 121);
                step(f, Op::TransformVector, &[2, 0, 42], 122);
                step(f, Op::InverseT, &[12, 14], 123);
                step(f, Op::DeltaTime, &[158], 124);
                step(f, Op::DivF, &[948, 158, 160], 125);
                step(f, Op::ScaleV, &[37, 160, 38], 126);
                step(f, Op::TransformVector, &[14, 38, 39], 127);
                step(f, Op::BreakVector, &[39, 161, 162, 163], 128);
                step(f, Op::MakeVector, &[161, 162, 946, 40], 129);
                step(f, Op::LengthV, &[40, 164], 130);
                step(f, Op::MulF, &[164, 140, 165], 131);
                step(f, Op::NegF, &[165, 166], 132);
                step(f, Op::ClampF, &[163, 166, 165, 167], 133);
                step(f, Op::MakeVector, &[161, 162, 167, 41], 134);
                step(f, Op::Select(ValueType::Vec3), &[2, 42, 41, 44], 135);
                step(f, Op::VectorLerp, &[42, 44, 38, 946, 45], 136);
                step(f, Op::Copy(ValueType::Vec3), &[45, 0], 137);
                step(f, Op::TransformVector, &[2, 1, 43], 138);
                step(f, Op::TransformVector, &[2, 0, 42], 139);
                step(f, Op::Select(ValueType::Vec3), &[2, 42, 41, 44], 140);
                step(f, Op::VectorLerp, &[43, 44, 39, 946, 46], 141);
                step(f, Op::Copy(ValueType::Vec3), &[46, 1], 142);
                step(f, Op::LengthV, &[44, 174], 143);
                step(f, Op::Copy(ValueType::Float), &[174, 0], 144);
                step(f, Op::BreakVector, &[37, 168, 169, 170], 145);
                step(f, Op::MulF, &[167, 158, 171], 146);
                step(f, Op::SubF, &[170, 171, 172], 147);
                step(f, Op::Select(ValueType::Float), &[10, 946, 172, 173], 148);
                step(f, Op::Copy(ValueType::Float), &[173, 1], 149);
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
                step(f, Op::Copy(ValueType::Float), &[946, 18], 163);
                163
            }
            163 => {
                step(f, Op::Copy(ValueType::Transform), &[12, 0], 164);
                step(f, Op::Copy(ValueType::Bool), &[131, 0], 165);
                step(f, Op::JumpIfFalse, &[8, 171], 166)
            }
            166 => {
                step(f, Op::GetTransform, &[33, 71, 131, 19], 167);
                step(f, Op::BreakTransform, &[19, 47, 9, 48], 168);
                step(f, Op::ScaleV, &[0, 949, 49], 169);
                step(f, Op::AddV, &[47, 49, 50], 170);
                step(f, Op::DrawArrow, &[47, 50, 947, 494], 171);
                171
            }
            171 => {
                step(f, Op::Copy(ValueType::Float), &[946, 175], 172);
                step(f, Op::Copy(ValueType::Float), &[948, 176], 173);
                step(f, Op::Copy(ValueType::Bool), &[132, 12], 174);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[8, 9], 175);
                step(f, Op::Copy(ValueType::Int), &[71, 25], 176);
                step(f, Op::MakeVector, &[946, 946, 60, 55], 177);
                177
            }
            177 => {
                step(f, Op::ForEachNext(Elem::Transform), &[9, 25, 21, 26, 27, 187], 178)
            }
            178 => {
                step(f, Op::BreakTransform, &[21, 51, 10, 52], 179);
                step(f, Op::TransformPoint, &[2, 51, 53], 180);
                step(f, Op::LerpV, &[53, 51, 948, 54], 181);
                step(f, Op::AddV, &[54, 55, 56], 182);
                step(f, Op::SubV, &[54, 55, 57], 183);
                step(f, Op::LineTrace, &[56, 57, 13, 58, 59, 178], 184);
                step(f, Op::JumpIfFalse, &[13, 186], 185)
            }
            185 => {
                step(f, Op::Copy(ValueType::Bool), &[131, 12], 186);
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
                step(f, Op::AddF, &[175, 176, 179], 197);
                step(f, Op::MulF, &[179, 947, 180], 198);
                step(f, Op::Copy(ValueType::Bool), &[132, 18], 199);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[8, 10], 200);
                step(f, Op::Copy(ValueType::Int), &[71, 28], 201);
                step(f, Op::MakeVector, &[946, 946, 60, 64], 202);
                202
            }
            202 => {
                step(f, Op::ForEachNext(Elem::Transform), &[10, 28, 22, 29, 30, 212], 203)
            }
            203 => {
                step(f, Op::BreakTransform, &[22, 60, 11, 61], 204);
                step(f, Op::TransformPoint, &[2, 60, 62], 205);
                step(f, Op::LerpV, &[62, 60, 180, 63], 206);
                step(f, Op::AddV, &[63, 64, 65], 207);
                step(f, Op::SubV, &[63, 64, 66], 208);
                step(f, Op::LineTrace, &[65, 66, 19, 67, 68, 182], 209);
                step(f, Op::JumpIfFalse, &[19, 211], 210)
            }
            210 => {
                step(f, Op::Copy(ValueType::Bool), &[131, 18], 211);
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
                step(f, Op::Copy(ValueType::Float), &[180, 175], 216);
                step(f, Op::Jump, &[218], 217)
            }
            217 => {
                step(f, Op::Copy(ValueType::Float), &[180, 176], 218);
                218
            }
            218 => {
                step(f, Op::Jump, &[195], 219)
            }
            219 => {
                step(f, Op::Select(ValueType::Float), &[5, 950, 948, 188], 220);
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 221);
                step(f, Op::AddF, &[175, 176, 179], 222);
                step(f, Op::MulF, &[179, 947, 183], 223);
                step(f, Op::Select(ValueType::Float), &[16, 183, 947, 184], 224);
                step(f, Op::Select(ValueType::Float), &[15, 184, 946, 190], 225);
                step(f, Op::MulF, &[188, 190, 192], 226);
                step(f, Op::DeltaTime, &[186], 227);
                step(f, Op::DivF, &[186, 144, 187], 228);
                step(f, Op::MulF, &[192, 187, 193], 229);
                step(f, Op::AddF, &[22, 193, 194], 230);
                step(f, Op::ClampF, &[194, 946, 948, 195], 231);
                step(f, Op::Select(ValueType::Float), &[14, 950, 948, 189], 232);
                step(f, Op::SubF, &[948, 184, 185], 233);
                step(f, Op::Select(ValueType::Float), &[15, 185, 948, 191], 234);
                step(f, Op::MulF, &[189, 191, 196], 235);
                step(f, Op::MulF, &[196, 187, 197], 236);
                step(f, Op::AddF, &[195, 197, 198], 237);
                step(f, Op::ClampF, &[198, 946, 948, 199], 238);
                step(f, Op::SmoothStepF, &[199, 946, 948, 200], 239);
                step(f, Op::AddF, &[23, 200, 201], 240);
                step(f, Op::MulF, &[201, 947, 202], 241);
                step(f, Op::SubF, &[948, 202, 203], 242);
                step(f, Op::MulF, &[203, 203, 204], 243);
                step(f, Op::SubF, &[948, 204, 205], 244);
                step(f, Op::Copy(ValueType::Float), &[205, 24], 245);
                step(f, Op::Copy(ValueType::Float), &[200, 23], 246);
                step(f, Op::Copy(ValueType::Float), &[199, 22], 247);
                step(f, Op::GreaterF, &[23, 946, 21], 248);
                step(f, Op::TransformVector, &[2, 3, 69], 249);
                step(f, Op::Select(ValueType::Vec3), &[21, 69, 0, 70], 250);
                step(f, Op::Copy(ValueType::Vec3), &[70, 3], 251);
                step(f, Op::LerpV, &[0, 3, 23, 71], 252);
                step(f, Op::Select(ValueType::Vec3), &[21, 71, 0, 72], 253);
                step(f, Op::Copy(ValueType::Vec3), &[72, 2], 254);
                step(f, Op::Copy(ValueType::Bool), &[14, 5], 255);
                step(f, Op::Copy(ValueType::Bool), &[11, 6], 256);
                step(f, Op::Copy(ValueType::Bool), &[132, 7], 257);
                step(f, Op::SubF, &[948, 24, 206], 258);
                step(f, Op::MulF, &[1, 206, 207], 259);
                step(f, Op::AddF, &[2, 207, 208], 260);
                step(f, Op::Copy(ValueType::Float), &[4, 209], 261);
                step(f, Op::Copy(ValueType::Float), &[5, 210], 262);
                step(f, Op::Copy(ValueType::Float), &[2, 212], 263);
                step(f, Op::Copy(ValueType::Float), &[141, 213], 264);
                step(f, Op::Copy(ValueType::Float), &[54, 214], 265);
                step(f, Op::SubF, &[208, 212, 219], 266);
                step(f, Op::DeltaTime, &[217], 267);
                step(f, Op::DivF, &[219, 217, 220], 268);
                step(f, Op::MulF, &[220, 214, 221], 269);
                step(f, Op::AddF, &[208, 221, 223], 270);
                step(f, Op::MulF, &[220, 951, 224], 271);
                step(f, Op::DivF, &[952, 213, 218], 272);
                step(f, Op::DivF, &[224, 218, 225], 273);
                step(f, Op::SubF, &[223, 225, 239], 274);
                step(f, Op::AddF, &[212, 221, 222], 275);
                step(f, Op::SubF, &[209, 222, 226], 276);
                step(f, Op::AddF, &[226, 225, 227], 277);
                step(f, Op::SubF, &[210, 220, 228], 278);
                step(f, Op::MulF, &[218, 227, 229], 279);
                step(f, Op::AddF, &[228, 229, 230], 280);
                step(f, Op::MulF, &[230, 217, 233], 281);
                step(f, Op::AddF, &[227, 233, 234], 282);
                step(f, Op::FloatLerp, &[946, 948, 218, 231], 283);
                step(f, Op::SubF, &[948, 231, 232], 284);
                step(f, Op::MulF, &[234, 232, 235], 285);
                step(f, Op::AddF, &[239, 235, 240], 286);
                step(f, Op::Copy(ValueType::Float), &[240, 215], 287);
                step(f, Op::MulF, &[218, 233, 236], 288);
                step(f, Op::SubF, &[228, 236, 237], 289);
                step(f, Op::MulF, &[237, 232, 238], 290);
                step(f, Op::AddF, &[220, 238, 241], 291);
                step(f, Op::Copy(ValueType::Float), &[241, 216], 292);
                step(f, Op::SubF, &[208, 215, 242], 293);
                step(f, Op::Copy(ValueType::Float), &[242, 3], 294);
                step(f, Op::Copy(ValueType::Float), &[215, 4], 295);
                step(f, Op::Copy(ValueType::Float), &[4, 209], 296);
                step(f, Op::Copy(ValueType::Float), &[5, 210], 297);
                step(f, Op::Copy(ValueType::Float), &[2, 212], 298);
                step(f, Op::Copy(ValueType::Float), &[141, 213], 299);
                step(f, Op::Copy(ValueType::Float), &[54, 214], 300);
                step(f, Op::SubF, &[208, 212, 219], 301);
                step(f, Op::DeltaTime, &[217], 302);
                step(f, Op::DivF, &[219, 217, 220], 303);
                step(f, Op::MulF, &[220, 214, 221], 304);
                step(f, Op::AddF, &[208, 221, 223], 305);
                step(f, Op::MulF, &[220, 951, 224], 306);
                step(f, Op::DivF, &[952, 213, 218], 307);
                step(f, Op::DivF, &[224, 218, 225], 308);
                step(f, Op::SubF, &[223, 225, 239], 309);
                step(f, Op::AddF, &[212, 221, 222], 310);
                step(f, Op::SubF, &[209, 222, 226], 311);
                step(f, Op::AddF, &[226, 225, 227], 312);
                step(f, Op::SubF, &[210, 220, 228], 313);
                step(f, Op::MulF, &[218, 227, 229], 314);
                step(f, Op::AddF, &[228, 229, 230], 315);
                step(f, Op::MulF, &[230, 217, 233], 316);
                step(f, Op::AddF, &[227, 233, 234], 317);
                step(f, Op::FloatLerp, &[946, 948, 218, 231], 318);
                step(f, Op::SubF, &[948, 231, 232], 319);
                step(f, Op::MulF, &[234, 232, 235], 320);
                step(f, Op::AddF, &[239, 235, 240], 321);
                step(f, Op::Copy(ValueType::Float), &[240, 215], 322);
                step(f, Op::MulF, &[218, 233, 236], 323);
                step(f, Op::SubF, &[228, 236, 237], 324);
                step(f, Op::MulF, &[237, 232, 238], 325);
                step(f, Op::AddF, &[220, 238, 241], 326);
                step(f, Op::Copy(ValueType::Float), &[241, 216], 327);
                step(f, Op::Copy(ValueType::Float), &[216, 5], 328);
                step(f, Op::Copy(ValueType::Float), &[208, 2], 329);
                step(f, Op::LengthV, &[4, 244], 330);
                step(f, Op::GreaterF, &[244, 31, 22], 331);
                step(f, Op::LengthV, &[2, 245], 332);
                step(f, Op::GreaterF, &[245, 31, 23], 333);
                step(f, Op::And, &[22, 23, 25], 334);
                step(f, Op::Select(ValueType::Vec3), &[22, 4, 493, 73], 335);
                step(f, Op::MovementAngleOffset, &[73, 14, 946, 953, 953, 954, 42, 955, 246], 336);
                step(f, Op::Copy(ValueType::Float), &[14, 249], 337);
                step(f, Op::SubF, &[246, 249, 251], 338);
                step(f, Op::AddF, &[251, 956, 252], 339);
                step(f, Op::DivF, &[252, 957, 253], 340);
                step(f, Op::FractF, &[253, 254], 341);
                step(f, Op::MulF, &[254, 957, 255], 342);
                step(f, Op::SubF, &[255, 956, 256], 343);
                step(f, Op::Copy(ValueType::Float), &[256, 250], 344);
                step(f, Op::AbsF, &[250, 275], 345);
                step(f, Op::Select(ValueType::Vec3), &[23, 2, 493, 74], 346);
                step(f, Op::MovementAngleOffset, &[74, 14, 946, 953, 953, 954, 42, 955, 247], 347);
                step(f, Op::Copy(ValueType::Float), &[14, 258], 348);
                step(f, Op::SubF, &[247, 258, 260], 349);
                step(f, Op::AddF, &[260, 956, 261], 350);
                step(f, Op::DivF, &[261, 957, 262], 351);
                step(f, Op::FractF, &[262, 263], 352);
                step(f, Op::MulF, &[263, 957, 264], 353);
                step(f, Op::SubF, &[264, 956, 265], 354);
                step(f, Op::Copy(ValueType::Float), &[265, 259], 355);
                step(f, Op::AbsF, &[259, 276], 356);
                step(f, Op::MaxF, &[275, 276, 278], 357);
                step(f, Op::SubF, &[247, 246, 269], 358);
                step(f, Op::AddF, &[269, 956, 270], 359);
                step(f, Op::DivF, &[270, 957, 271], 360);
                step(f, Op::FractF, &[271, 272], 361);
                step(f, Op::MulF, &[272, 957, 273], 362);
                step(f, Op::SubF, &[273, 956, 274], 363);
                step(f, Op::Copy(ValueType::Float), &[274, 268], 364);
                step(f, Op::AbsF, &[268, 277], 365);
                step(f, Op::MaxF, &[278, 277, 279], 366);
                step(f, Op::LessF, &[279, 958, 24], 367);
                step(f, Op::And, &[25, 24, 26], 368);
                step(f, Op::Not, &[22, 27], 369);
                step(f, Op::Not, &[23, 28], 370);
                step(f, Op::And, &[27, 28, 29], 371);
                step(f, Op::Or, &[26, 29, 30], 372);
                step(f, Op::JumpIfFalse, &[30, 394], 373)
            }
            373 => {
                step(f, Op::DeltaTime, &[243], 374);
                step(f, Op::MulF, &[40, 243, 283], 375);
                step(f, Op::GreaterF, &[283, 946, 31], 376);
                step(f, Op::DivF, &[54, 243, 280], 377);
                step(f, Op::FloatLerp, &[946, 948, 40, 281], 378);
                step(f, Op::SubF, &[948, 281, 282], 379);
                step(f, Op::DivF, &[282, 281, 284], 380);
                step(f, Op::DivF, &[948, 283, 285], 381);
                step(f, Op::SubF, &[284, 285, 286], 382);
                step(f, Op::AddF, &[280, 286, 287], 383);
                step(f, Op::Select(ValueType::Float), &[31, 287, 946, 288], 384);
                step(f, Op::MulF, &[268, 288, 289], 385);
                step(f, Op::AddF, &[247, 289, 290], 386);
                step(f, Op::SinF, &[290, 291], 387);
                step(f, Op::NegF, &[291, 292], 388);
                step(f, Op::CosF, &[290, 293], 389);
                step(f, Op::MakeVector, &[292, 293, 946, 75], 390);
                step(f, Op::Select(ValueType::Vec3), &[23, 75, 493, 76], 391);
                step(f, Op::MovementAngleOffset, &[76, 14, 946, 40, 41, 954, 956, 955, 294], 392);
                step(f, Op::Copy(ValueType::Float), &[294, 14], 393);
                step(f, Op::Jump, &[450], 394)
            }
            394 => {
                step(f, Op::DeltaTime, &[243], 395);
                step(f, Op::DivF, &[243, 44, 295], 396);
                step(f, Op::AddF, &[295, 947, 296], 397);
                step(f, Op::FloorF, &[296, 297], 398);
                step(f, Op::MaxF, &[297, 948, 298], 399);
                step(f, Op::ToInt, &[298, 36], 400);
                step(f, Op::Copy(ValueType::Int), &[36, 35], 401);
                step(f, Op::Copy(ValueType::Int), &[71, 31], 402);
                step(f, Op::MulF, &[44, 947, 302], 403);
                step(f, Op::SubF, &[54, 302, 303], 404);
                step(f, Op::DivF, &[303, 243, 304], 405);
                step(f, Op::FloatLerp, &[946, 948, 38, 306], 406);
                step(f, Op::GreaterF, &[306, 946, 32], 407);
                step(f, Op::DivF, &[40, 298, 316], 408);
                step(f, Op::DivF, &[41, 298, 317], 409);
                step(f, Op::SubF, &[954, 43, 329], 410);
                step(f, Op::GreaterF, &[43, 946, 35], 411);
                411
            }
            411 => {
                step(f, Op::ForNext, &[31, 35, 33, 450], 412)
            }
            412 => {
                step(f, Op::ToFloat, &[33, 299], 413);
                step(f, Op::AddF, &[299, 948, 300], 414);
                step(f, Op::DivF, &[300, 298, 301], 415);
                step(f, Op::AddF, &[301, 304, 305], 416);
                step(f, Op::MulF, &[38, 305, 307], 417);
                step(f, Op::FloatLerp, &[946, 948, 307, 308], 418);
                step(f, Op::DivF, &[308, 306, 309], 419);
                step(f, Op::Select(ValueType::Float), &[32, 309, 305, 310], 420);
                step(f, Op::LerpV, &[4, 2, 310, 77], 421);
                step(f, Op::LengthV, &[77, 311], 422);
                step(f, Op::GreaterF, &[311, 31, 33], 423);
                step(f, Op::Select(ValueType::Vec3), &[33, 77, 493, 78], 424);
                step(f, Op::MulF, &[243, 305, 312], 425);
                step(f, Op::MulF, &[8, 312, 313], 426);
                step(f, Op::AddF, &[12, 313, 314], 427);
                step(f, Op::FractF, &[314, 315], 428);
                step(f, Op::MulF, &[315, 951, 333], 429);
                step(f, Op::FractF, &[333, 334], 430);
                step(f, Op::LessF, &[334, 955, 36], 431);
                step(f, Op::MovementAngleOffset, &[78, 14, 946, 953, 953, 954, 42, 955, 318], 432);
                step(f, Op::Copy(ValueType::Float), &[14, 320], 433);
                step(f, Op::SubF, &[318, 320, 322], 434);
                step(f, Op::AddF, &[322, 956, 323], 435);
                step(f, Op::DivF, &[323, 957, 324], 436);
                step(f, Op::FractF, &[324, 325], 437);
                step(f, Op::MulF, &[325, 957, 326], 438);
                step(f, Op::SubF, &[326, 956, 327], 439);
                step(f, Op::Copy(ValueType::Float), &[327, 321], 440);
                step(f, Op::AbsF, &[321, 328], 441);
                step(f, Op::SmoothStepF, &[328, 329, 954, 330], 442);
                step(f, Op::GreaterF, &[328, 954, 34], 443);
                step(f, Op::Select(ValueType::Float), &[34, 948, 946, 331], 444);
                step(f, Op::Select(ValueType::Float), &[35, 330, 331, 332], 445);
                step(f, Op::Select(ValueType::Float), &[36, 946, 332, 335], 446);
                step(f, Op::LerpF, &[316, 317, 335, 336], 447);
                step(f, Op::MovementAngleOffset, &[78, 14, 315, 336, 336, 954, 42, 955, 337], 448);
                step(f, Op::Copy(ValueType::Float), &[337, 14], 449);
                step(f, Op::Jump, &[411], 450)
            }
            450 => {
                step(f, Op::QuatFromAxisAngle, &[495, 14, 12], 451);
                step(f, Op::Copy(ValueType::Quat), &[12, 0], 452);
                step(f, Op::SinF, &[14, 338], 453);
                step(f, Op::AbsF, &[338, 339], 454);
                step(f, Op::RemapF, &[339, 45, 46, 946, 948, 131, 340], 455);
                step(f, Op::BreakVector, &[74, 341, 342, 343], 456);
                step(f, Op::AbsF, &[341, 344], 457);
                step(f, Op::DivF, &[344, 245, 345], 458);
                step(f, Op::RemapF, &[345, 45, 46, 946, 948, 131, 346], 459);
                step(f, Op::TransformVector, &[2, 496, 79], 460);
                step(f, Op::DistanceV, &[79, 496, 347], 461);
                step(f, Op::DivF, &[347, 243, 348], 462);
                step(f, Op::RemapF, &[348, 50, 51, 948, 946, 131, 349], 463);
                step(f, Op::MulF, &[346, 349, 350], 464);
                step(f, Op::MaxF, &[340, 350, 351], 465);
                step(f, Op::Copy(ValueType::Float), &[351, 15], 466);
                step(f, Op::Copy(ValueType::Vec3), &[2, 4], 467);
                step(f, Op::Copy(ValueType::Bool), &[131, 39], 468);
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
                step(f, Op::Copy(ValueType::Bool), &[132, 39], 474);
                474
            }
            474 => {
                step(f, Op::Jump, &[470], 475)
            }
            475 => {
                step(f, Op::Copy(ValueType::Bool), &[39, 38], 476);
                step(f, Op::Copy(ValueType::Bool), &[131, 43], 477);
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
                step(f, Op::BreakVector, &[80, 360, 361, 362], 483);
                step(f, Op::MakeVector, &[360, 361, 946, 84], 484);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 44, 24], 485);
                step(f, Op::BreakTransform, &[24, 82, 14, 83], 486);
                step(f, Op::BreakVector, &[82, 363, 364, 365], 487);
                step(f, Op::MakeVector, &[363, 364, 946, 85], 488);
                step(f, Op::DistanceV, &[84, 85, 366], 489);
                step(f, Op::GreaterF, &[366, 33, 44], 490);
                step(f, Op::JumpIfFalse, &[44, 492], 491)
            }
            491 => {
                step(f, Op::Copy(ValueType::Bool), &[132, 43], 492);
                492
            }
            492 => {
                step(f, Op::Jump, &[479], 493)
            }
            493 => {
                step(f, Op::Copy(ValueType::Bool), &[43, 42], 494);
                step(f, Op::And, &[38, 42, 45], 495);
                step(f, Op::LengthV, &[2, 352], 496);
                step(f, Op::GreaterF, &[352, 31, 37], 497);
                step(f, Op::GreaterF, &[0, 31, 46], 498);
                step(f, Op::Or, &[37, 46, 47], 499);
                step(f, Op::Not, &[47, 48], 500);
                step(f, Op::And, &[45, 48, 53], 501);
                step(f, Op::DeltaTime, &[391], 502);
                step(f, Op::MulF, &[391, 36, 392], 503);
                step(f, Op::AddF, &[12, 392, 393], 504);
                step(f, Op::GreaterF, &[12, 947, 54], 505);
                step(f, Op::AddF, &[35, 947, 389], 506);
                step(f, Op::Select(ValueType::Float), &[54, 389, 35, 390], 507);
                step(f, Op::MinF, &[393, 390, 394], 508);
                step(f, Op::NotEquals(Elem::Bool), &[48, 4, 49], 509);
                step(f, Op::Not, &[45, 50], 510);
                step(f, Op::And, &[49, 50, 51], 511);
                step(f, Op::SubF, &[13, 31, 375], 512);
                step(f, Op::SubF, &[13, 352, 376], 513);
                step(f, Op::DivF, &[375, 376, 377], 514);
                step(f, Op::ClampF, &[377, 946, 948, 378], 515);
                step(f, Op::MulF, &[8, 378, 380], 516);
                step(f, Op::RemapF, &[352, 31, 32, 946, 948, 131, 367], 517);
                step(f, Op::MaxF, &[367, 9, 368], 518);
                step(f, Op::Select(ValueType::Float), &[38, 948, 368, 369], 519);
                step(f, Op::Select(ValueType::Float), &[48, 34, 369, 370], 520);
                step(f, Op::Select(ValueType::Float), &[45, 367, 370, 371], 521);
                step(f, Op::SubF, &[948, 23, 372], 522);
                step(f, Op::MulF, &[371, 372, 373], 523);
                step(f, Op::LerpF, &[25, 48, 15, 355], 524);
                step(f, Op::RemapF, &[352, 28, 29, 26, 27, 131, 353], 525);
                step(f, Op::LerpF, &[353, 47, 15, 354], 526);
                step(f, Op::MaxF, &[352, 30, 356], 527);
                step(f, Op::DivF, &[354, 356, 357], 528);
                step(f, Op::AddF, &[355, 357, 358], 529);
                step(f, Op::DivF, &[373, 358, 374], 530);
                step(f, Op::SubF, &[948, 378, 379], 531);
                step(f, Op::MulF, &[374, 379, 381], 532);
                step(f, Op::AddF, &[380, 381, 382], 533);
                step(f, Op::MulF, &[382, 951, 383], 534);
                step(f, Op::AddF, &[8, 374, 384], 535);
                step(f, Op::Select(ValueType::Float), &[51, 383, 384, 385], 536);
                step(f, Op::DivF, &[951, 385, 386], 537);
                step(f, Op::GreaterF, &[385, 946, 52], 538);
                step(f, Op::CycleStep, &[12, 386, 946, 52, 387, 388], 539);
                step(f, Op::Select(ValueType::Float), &[53, 394, 387, 395], 540);
                step(f, Op::Copy(ValueType::Float), &[395, 12], 541);
                step(f, Op::Copy(ValueType::Float), &[374, 8], 542);
                step(f, Op::Copy(ValueType::Bool), &[37, 3], 543);
                step(f, Op::Copy(ValueType::Float), &[357, 6], 544);
                step(f, Op::Copy(ValueType::Float), &[358, 7], 545);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 546);
                step(f, Op::Copy(ValueType::Int), &[71, 37], 547);
                step(f, Op::DivF, &[355, 358, 359], 548);
                step(f, Op::MulF, &[11, 378, 401], 549);
                step(f, Op::MulF, &[391, 947, 407], 550);
                step(f, Op::SubF, &[359, 10, 412], 551);
                step(f, Op::MaxF, &[412, 946, 413], 552);
                step(f, Op::DivF, &[413, 359, 414], 553);
                step(f, Op::SubF, &[948, 15, 416], 554);
                step(f, Op::DivF, &[54, 391, 421], 555);
                step(f, Op::SubF, &[947, 421, 422], 556);
                step(f, Op::MulF, &[414, 416, 423], 557);
                step(f, Op::MulF, &[423, 372, 424], 558);
                step(f, Op::MulF, &[424, 138, 425], 559);
                step(f, Op::MulF, &[425, 422, 426], 560);
                step(f, Op::SubF, &[948, 426, 427], 561);
                561
            }
            561 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 37, 14, 38, 39, 605], 562)
            }
            562 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 38, 409], 563);
                step(f, Op::ToFloat, &[38, 396], 564);
                step(f, Op::MulF, &[396, 947, 397], 565);
                step(f, Op::AddF, &[12, 397, 398], 566);
                step(f, Op::FractF, &[398, 399], 567);
                step(f, Op::SubF, &[409, 399, 411], 568);
                step(f, Op::GreaterF, &[411, 947, 55], 569);
                step(f, Op::ArrayAt(Elem::Float), &[2, 38, 410], 570);
                step(f, Op::Select(ValueType::Float), &[55, 946, 410, 438], 571);
                step(f, Op::ArraySetAt(Elem::Float), &[3, 38, 438], 572);
                step(f, Op::SubF, &[948, 409, 432], 573);
                step(f, Op::AddF, &[399, 432, 433], 574);
                step(f, Op::DivF, &[399, 433, 434], 575);
                step(f, Op::MaxF, &[367, 9, 368], 576);
                step(f, Op::Select(ValueType::Float), &[38, 948, 368, 369], 577);
                step(f, Op::Select(ValueType::Float), &[48, 34, 369, 370], 578);
                step(f, Op::Select(ValueType::Float), &[45, 367, 370, 371], 579);
                step(f, Op::MulF, &[371, 372, 373], 580);
                step(f, Op::DivF, &[373, 355, 400], 581);
                step(f, Op::MulF, &[400, 379, 402], 582);
                step(f, Op::AddF, &[401, 402, 403], 583);
                step(f, Op::MulF, &[403, 951, 404], 584);
                step(f, Op::AddF, &[11, 400, 405], 585);
                step(f, Op::Select(ValueType::Float), &[51, 404, 405, 406], 586);
                step(f, Op::MulF, &[406, 407, 408], 587);
                step(f, Op::MulF, &[434, 408, 435], 588);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 38, 56], 589);
                step(f, Op::MulF, &[408, 427, 428], 590);
                step(f, Op::Select(ValueType::Float), &[56, 408, 428, 429], 591);
                step(f, Op::MulF, &[414, 410, 415], 592);
                step(f, Op::MulF, &[415, 416, 417], 593);
                step(f, Op::MulF, &[417, 372, 418], 594);
                step(f, Op::MulF, &[418, 138, 419], 595);
                step(f, Op::Select(ValueType::Float), &[56, 946, 419, 420], 596);
                step(f, Op::SubF, &[429, 420, 430], 597);
                step(f, Op::AddF, &[410, 430, 431], 598);
                step(f, Op::Select(ValueType::Float), &[55, 435, 431, 436], 599);
                step(f, Op::MinF, &[436, 951, 437], 600);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 38, 437], 601);
                step(f, Op::JumpIfFalse, &[55, 603], 602)
            }
            602 => {
                step(f, Op::Copy(ValueType::Float), &[371, 9], 603);
                603
            }
            603 => {
                step(f, Op::ArraySetAt(Elem::Float), &[0, 38, 399], 604);
                step(f, Op::Jump, &[561], 605)
            }
            605 => {
                step(f, Op::Copy(ValueType::Float), &[359, 10], 606);
                step(f, Op::Copy(ValueType::Bool), &[48, 4], 607);
                step(f, Op::Copy(ValueType::Float), &[352, 13], 608);
                step(f, Op::MaxF, &[367, 9, 368], 609);
                step(f, Op::Select(ValueType::Float), &[38, 948, 368, 369], 610);
                step(f, Op::Select(ValueType::Float), &[48, 34, 369, 370], 611);
                step(f, Op::Select(ValueType::Float), &[45, 367, 370, 371], 612);
                step(f, Op::MulF, &[371, 372, 373], 613);
                step(f, Op::DivF, &[373, 355, 400], 614);
                step(f, Op::Copy(ValueType::Float), &[400, 11], 615);
                step(f, Op::TransformVector, &[2, 496, 86], 616);
                step(f, Op::DistanceV, &[86, 496, 440], 617);
                step(f, Op::DeltaTime, &[439], 618);
                step(f, Op::DivF, &[440, 439, 441], 619);
                step(f, Op::RemapF, &[441, 50, 51, 946, 948, 131, 442], 620);
                step(f, Op::BreakTransform, &[2, 87, 15, 88], 621);
                step(f, Op::BreakVector, &[87, 443, 444, 445], 622);
                step(f, Op::NegF, &[444, 446], 623);
                step(f, Op::Atan2F, &[443, 446, 447], 624);
                step(f, Op::AbsF, &[447, 448], 625);
                step(f, Op::RemapF, &[448, 108, 109, 946, 948, 131, 449], 626);
                step(f, Op::MulF, &[442, 449, 450], 627);
                step(f, Op::FloatLerp, &[16, 946, 110, 451], 628);
                step(f, Op::MaxF, &[450, 451, 452], 629);
                step(f, Op::Copy(ValueType::Float), &[452, 16], 630);
                step(f, Op::Copy(ValueType::Float), &[447, 17], 631);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 632);
                step(f, Op::Copy(ValueType::Int), &[71, 2], 633);
                633
            }
            633 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 2, 0, 3, 4, 1566], 634)
            }
            634 => {
                step(f, Op::Copy(ValueType::Bool), &[131, 57], 635);
                step(f, Op::Copy(ValueType::Bool), &[132, 58], 636);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 3, 61], 637);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 453], 638);
                step(f, Op::GreaterEqualF, &[453, 948, 62], 639);
                step(f, Op::And, &[61, 62, 63], 640);
                step(f, Op::Or, &[1, 2, 65], 641);
                step(f, Op::GreaterF, &[23, 946, 64], 642);
                step(f, Op::Or, &[65, 64, 66], 643);
                step(f, Op::Not, &[66, 67], 644);
                step(f, Op::And, &[63, 67, 68], 645);
                step(f, Op::JumpIfFalse, &[68, 755], 646)
            }
            646 => {
                step(f, Op::ArrayAt(Elem::Transform), &[2, 3, 28], 647);
                step(f, Op::BreakTransform, &[28, 107, 24, 108], 648);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 3, 124], 649);
                step(f, Op::SubV, &[107, 124, 145], 650);
                step(f, Op::TransformPoint, &[2, 145, 146], 651);
                step(f, Op::GetTransform, &[34, 71, 131, 25], 652);
                step(f, Op::BreakTransform, &[25, 91, 16, 92], 653);
                step(f, Op::BreakVector, &[91, 464, 465, 466], 654);
                step(f, Op::SubF, &[948, 15, 462], 655);
                step(f, Op::MulF, &[14, 462, 463], 656);
                step(f, Op::QuatFromAxisAngle, &[495, 463, 18], 657);
                step(f, Op::GetTransform, &[0, 71, 131, 26], 658);
                step(f, Op::BreakTransform, &[26, 93, 17, 94], 659);
                step(f, Op::SubV, &[93, 91, 95], 660);
                step(f, Op::BreakVector, &[95, 459, 460, 461], 661);
                step(f, Op::MakeVector, &[459, 460, 946, 96], 662);
                step(f, Op::RotateVector, &[18, 96, 97], 663);
                step(f, Op::BreakVector, &[97, 467, 468, 469], 664);
                step(f, Op::MulF, &[49, 15, 470], 665);
                step(f, Op::Equals(Elem::Int), &[3, 71, 59], 666);
                step(f, Op::Select(ValueType::Float), &[59, 948, 950, 479], 667);
                step(f, Op::MulF, &[470, 479, 471], 668);
                step(f, Op::AddF, &[467, 471, 472], 669);
                step(f, Op::AddF, &[464, 472, 473], 670);
                step(f, Op::AddF, &[465, 468, 474], 671);
                step(f, Op::BreakVector, &[93, 475, 476, 477], 672);
                step(f, Op::SubF, &[477, 55, 478], 673);
                step(f, Op::MakeVector, &[473, 474, 478, 98], 674);
                step(f, Op::MulF, &[6, 947, 458], 675);
                step(f, Op::ScaleV, &[2, 458, 90], 676);
                step(f, Op::AddV, &[98, 90, 101], 677);
                step(f, Op::DistanceV, &[146, 101, 506], 678);
                step(f, Op::TransformVector, &[2, 497, 147], 679);
                step(f, Op::DistanceV, &[147, 497, 507], 680);
                step(f, Op::MaxF, &[506, 507, 508], 681);
                step(f, Op::LessEqualF, &[508, 62, 77], 682);
                step(f, Op::LengthV, &[2, 509], 683);
                step(f, Op::LengthV, &[4, 510], 684);
                step(f, Op::MaxF, &[509, 510, 511], 685);
                step(f, Op::LessEqualF, &[511, 31, 78], 686);
                step(f, Op::And, &[77, 78, 79], 687);
                step(f, Op::ArrayAt(Elem::Bool), &[1, 3, 69], 688);
                step(f, Op::And, &[79, 69, 80], 689);
                step(f, Op::JumpIfFalse, &[80, 692], 690)
            }
            690 => {
                step(f, Op::Copy(ValueType::Bool), &[131, 58], 691);
                step(f, Op::Jump, &[721], 692)
            }
            692 => {
                step(f, Op::MakeVector, &[946, 946, 60, 126], 693);
                step(f, Op::AddV, &[101, 126, 127], 694);
                step(f, Op::SubV, &[101, 126, 128], 695);
                step(f, Op::SphereTrace, &[127, 128, 59, 70, 129, 130, 498], 696);
                step(f, Op::SubV, &[129, 101, 143], 697);
                step(f, Op::DistanceV, &[143, 124, 502], 698);
                step(f, Op::RotateVector, &[0, 496, 102], 699);
                step(f, Op::ScaleV, &[102, 64, 131], 700);
                step(f, Op::AddV, &[127, 131, 132], 701);
                step(f, Op::AddV, &[128, 131, 133], 702);
                step(f, Op::SphereTrace, &[132, 133, 59, 71, 134, 135, 499], 703);
                step(f, Op::SubV, &[134, 101, 144], 704);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 3, 125], 705);
                step(f, Op::DistanceV, &[144, 125, 503], 706);
                step(f, Op::MaxF, &[502, 503, 504], 707);
                step(f, Op::ScaleV, &[102, 61, 136], 708);
                step(f, Op::AddV, &[132, 136, 137], 709);
                step(f, Op::AddV, &[133, 136, 138], 710);
                step(f, Op::SphereTrace, &[137, 138, 59, 72, 139, 140, 500], 711);
                step(f, Op::SubV, &[139, 101, 141], 712);
                step(f, Op::ArrayAt(Elem::Vec3), &[2, 3, 142], 713);
                step(f, Op::DistanceV, &[141, 142, 501], 714);
                step(f, Op::MaxF, &[504, 501, 505], 715);
                step(f, Op::LessEqualF, &[505, 62, 73], 716);
                step(f, Op::And, &[70, 71, 74], 717);
                step(f, Op::And, &[74, 69, 75], 718);
                step(f, Op::And, &[73, 75, 76], 719);
                step(f, Op::JumpIfFalse, &[76, 721], 720)
            }
            720 => {
                step(f, Op::Copy(ValueType::Bool), &[131, 58], 721);
                721
            }
            721 => {
                step(f, Op::JumpIfFalse, &[58, 755], 722)
            }
            722 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 27], 723);
                step(f, Op::BreakTransform, &[27, 104, 22, 105], 724);
                step(f, Op::AddV, &[101, 124, 148], 725);
                step(f, Op::Copy(ValueType::Float), &[52, 512], 726);
                step(f, Op::Copy(ValueType::Float), &[54, 513], 727);
                step(f, Op::SubV, &[148, 107, 153], 728);
                step(f, Op::DeltaTime, &[514], 729);
                step(f, Op::DivF, &[513, 514, 515], 730);
                step(f, Op::ScaleV, &[153, 515, 154], 731);
                step(f, Op::AddV, &[148, 154, 155], 732);
                step(f, Op::AddV, &[107, 154, 156], 733);
                step(f, Op::SubV, &[104, 156, 157], 734);
                step(f, Op::FloatLerp, &[946, 948, 512, 516], 735);
                step(f, Op::SubF, &[948, 516, 517], 736);
                step(f, Op::ScaleV, &[157, 517, 158], 737);
                step(f, Op::AddV, &[155, 158, 160], 738);
                step(f, Op::MulF, &[512, 514, 518], 739);
                step(f, Op::GreaterF, &[518, 946, 81], 740);
                step(f, Op::DivF, &[516, 518, 519], 741);
                step(f, Op::Select(ValueType::Float), &[81, 519, 948, 520], 742);
                step(f, Op::ScaleV, &[153, 520, 159], 743);
                step(f, Op::SubV, &[160, 159, 161], 744);
                step(f, Op::Copy(ValueType::Vec3), &[161, 152], 745);
                step(f, Op::BreakVector, &[152, 521, 522, 523], 746);
                step(f, Op::ClampF, &[523, 65, 66, 524], 747);
                step(f, Op::MakeVector, &[521, 522, 524, 162], 748);
                step(f, Op::MakeTransform, &[162, 22, 492, 31], 749);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 3, 31], 750);
                step(f, Op::MakeTransform, &[148, 99, 492, 32], 751);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 3, 32], 752);
                step(f, Op::JumpIfFalse, &[69, 754], 753)
            }
            753 => {
                step(f, Op::Copy(ValueType::Bool), &[131, 7], 754);
                754
            }
            754 => {
                step(f, Op::Copy(ValueType::Bool), &[132, 57], 755);
                755
            }
            755 => {
                step(f, Op::JumpIfFalse, &[57, 960], 756)
            }
            756 => {
                step(f, Op::GetTransform, &[34, 71, 131, 25], 757);
                step(f, Op::BreakTransform, &[25, 91, 16, 92], 758);
                step(f, Op::BreakVector, &[91, 464, 465, 466], 759);
                step(f, Op::SubF, &[948, 15, 462], 760);
                step(f, Op::MulF, &[14, 462, 463], 761);
                step(f, Op::QuatFromAxisAngle, &[495, 463, 18], 762);
                step(f, Op::GetTransform, &[0, 71, 131, 26], 763);
                step(f, Op::BreakTransform, &[26, 93, 17, 94], 764);
                step(f, Op::SubV, &[93, 91, 95], 765);
                step(f, Op::BreakVector, &[95, 459, 460, 461], 766);
                step(f, Op::MakeVector, &[459, 460, 946, 96], 767);
                step(f, Op::RotateVector, &[18, 96, 97], 768);
                step(f, Op::BreakVector, &[97, 467, 468, 469], 769);
                step(f, Op::MulF, &[49, 15, 470], 770);
                step(f, Op::Equals(Elem::Int), &[3, 71, 59], 771);
                step(f, Op::Select(ValueType::Float), &[59, 948, 950, 479], 772);
                step(f, Op::MulF, &[470, 479, 471], 773);
                step(f, Op::AddF, &[467, 471, 472], 774);
                step(f, Op::AddF, &[464, 472, 473], 775);
                step(f, Op::AddF, &[465, 468, 474], 776);
                step(f, Op::BreakVector, &[93, 475, 476, 477], 777);
                step(f, Op::SubF, &[477, 55, 478], 778);
                step(f, Op::MakeVector, &[473, 474, 478, 98], 779);
                step(f, Op::SubF, &[948, 453, 454], 780);
                step(f, Op::MaxF, &[454, 946, 455], 781);
                step(f, Op::MulF, &[10, 7, 456], 782);
                step(f, Op::MulF, &[455, 456, 457], 783);
                step(f, Op::ScaleV, &[2, 457, 89], 784);
                step(f, Op::AddV, &[98, 89, 99], 785);
                step(f, Op::MulF, &[6, 947, 458], 786);
                step(f, Op::ScaleV, &[2, 458, 90], 787);
                step(f, Op::AddV, &[99, 90, 100], 788);
                step(f, Op::RotateVector, &[0, 496, 102], 789);
                step(f, Op::Copy(ValueType::Float), &[953, 526], 790);
                step(f, Op::Copy(ValueType::Vec3), &[493, 167], 791);
                step(f, Op::Copy(ValueType::Vec3), &[495, 168], 792);
                step(f, Op::Copy(ValueType::Bool), &[132, 83], 793);
                step(f, Op::Copy(ValueType::Float), &[953, 527], 794);
                step(f, Op::Copy(ValueType::Vec3), &[493, 169], 795);
                step(f, Op::MulI, &[0, 0, 52], 796);
                step(f, Op::Copy(ValueType::Int), &[52, 51], 797);
                step(f, Op::Copy(ValueType::Int), &[71, 47], 798);
                step(f, Op::SubI, &[0, 72, 55], 799);
                step(f, Op::DivI, &[55, 73, 56], 800);
                step(f, Op::MakeVector, &[946, 946, 60, 174], 801);
                step(f, Op::ScaleV, &[102, 64, 179], 802);
                802
            }
            802 => {
                step(f, Op::ForNext, &[47, 51, 49, 849], 803)
            }
            803 => {
                step(f, Op::ModI, &[49, 0, 53], 804);
                step(f, Op::ToFloat, &[53, 528], 805);
                step(f, Op::MulF, &[528, 61, 530], 806);
                step(f, Op::MulF, &[530, 479, 531], 807);
                step(f, Op::MakeVector, &[531, 946, 946, 170], 808);
                step(f, Op::DivI, &[49, 0, 54], 809);
                step(f, Op::SubI, &[54, 56, 57], 810);
                step(f, Op::ToFloat, &[57, 529], 811);
                step(f, Op::MulF, &[529, 61, 532], 812);
                step(f, Op::ScaleV, &[102, 532, 171], 813);
                step(f, Op::AddV, &[170, 171, 172], 814);
                step(f, Op::AddV, &[100, 172, 173], 815);
                step(f, Op::AddV, &[173, 174, 175], 816);
                step(f, Op::SubV, &[173, 174, 176], 817);
                step(f, Op::SphereTrace, &[175, 176, 59, 84, 177, 178, 533], 818);
                step(f, Op::BreakVector, &[177, 535, 536, 537], 819);
                step(f, Op::AddV, &[175, 179, 180], 820);
                step(f, Op::AddV, &[176, 179, 181], 821);
                step(f, Op::SphereTrace, &[180, 181, 59, 85, 182, 183, 534], 822);
                step(f, Op::BreakVector, &[182, 538, 539, 540], 823);
                step(f, Op::SubF, &[537, 540, 541], 824);
                step(f, Op::AbsF, &[541, 542], 825);
                step(f, Op::Select(ValueType::Float), &[84, 946, 948, 543], 826);
                step(f, Op::AddF, &[542, 543, 548], 827);
                step(f, Op::LengthV, &[172, 544], 828);
                step(f, Op::RemapF, &[544, 946, 959, 946, 948, 131, 545], 829);
                step(f, Op::MinF, &[537, 540, 546], 830);
                step(f, Op::RemapF, &[546, 960, 959, 948, 947, 131, 547], 831);
                step(f, Op::AddF, &[545, 547, 549], 832);
                step(f, Op::AddF, &[548, 549, 550], 833);
                step(f, Op::LessF, &[550, 526, 86], 834);
                step(f, Op::And, &[84, 86, 87], 835);
                step(f, Op::JumpIfFalse, &[87, 843], 836)
            }
            836 => {
                step(f, Op::Copy(ValueType::Float), &[526, 527], 837);
                step(f, Op::Copy(ValueType::Vec3), &[167, 169], 838);
                step(f, Op::Copy(ValueType::Float), &[550, 526], 839);
                step(f, Op::Copy(ValueType::Vec3), &[177, 167], 840);
                step(f, Op::Copy(ValueType::Vec3), &[178, 168], 841);
                step(f, Op::Copy(ValueType::Bool), &[131, 83], 842);
                step(f, Op::Jump, &[848], 843)
            }
            843 => {
                step(f, Op::LessF, &[550, 527, 88], 844);
                step(f, Op::And, &[84, 88, 89], 845);
                step(f, Op::JumpIfFalse, &[89, 848], 846)
            }
            846 => {
                step(f, Op::Copy(ValueType::Float), &[550, 527], 847);
                step(f, Op::Copy(ValueType::Vec3), &[177, 169], 848);
                848
            }
            848 => {
                step(f, Op::Jump, &[802], 849)
            }
            849 => {
                step(f, Op::JumpIfFalse, &[8, 851], 850)
            }
            850 => {
                step(f, Op::DrawSphere, &[167, 59, 496], 851);
                851
            }
            851 => {
                step(f, Op::GreaterF, &[63, 946, 90], 852);
                step(f, Op::SubF, &[526, 527, 551], 853);
                step(f, Op::DivF, &[551, 63, 552], 854);
                step(f, Op::PowF, &[961, 552, 553], 855);
                step(f, Op::Select(ValueType::Float), &[90, 553, 946, 554], 856);
                step(f, Op::ScaleV, &[169, 554, 184], 857);
                step(f, Op::AddV, &[167, 184, 185], 858);
                step(f, Op::AddF, &[554, 948, 555], 859);
                step(f, Op::DivF, &[948, 555, 556], 860);
                step(f, Op::ScaleV, &[185, 556, 186], 861);
                step(f, Op::Copy(ValueType::Vec3), &[186, 165], 862);
                step(f, Op::Copy(ValueType::Vec3), &[168, 166], 863);
                step(f, Op::Copy(ValueType::Bool), &[83, 82], 864);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 27], 865);
                step(f, Op::BreakTransform, &[27, 104, 22, 105], 866);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 453], 867);
                step(f, Op::SubF, &[948, 453, 454], 868);
                step(f, Op::MaxF, &[454, 946, 455], 869);
                step(f, Op::MulF, &[10, 7, 456], 870);
                step(f, Op::MulF, &[455, 456, 457], 871);
                step(f, Op::ScaleV, &[2, 457, 89], 872);
                step(f, Op::SubV, &[165, 89, 103], 873);
                step(f, Op::Select(ValueType::Vec3), &[82, 103, 104, 106], 874);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 3, 28], 875);
                step(f, Op::BreakTransform, &[28, 107, 24, 108], 876);
                step(f, Op::Copy(ValueType::Float), &[52, 485], 877);
                step(f, Op::Copy(ValueType::Float), &[54, 486], 878);
                step(f, Op::SubV, &[106, 107, 113], 879);
                step(f, Op::DeltaTime, &[487], 880);
                step(f, Op::DivF, &[486, 487, 488], 881);
                step(f, Op::ScaleV, &[113, 488, 114], 882);
                step(f, Op::AddV, &[106, 114, 115], 883);
                step(f, Op::AddV, &[107, 114, 116], 884);
                step(f, Op::SubV, &[104, 116, 117], 885);
                step(f, Op::FloatLerp, &[946, 948, 485, 489], 886);
                step(f, Op::SubF, &[948, 489, 490], 887);
                step(f, Op::ScaleV, &[117, 490, 118], 888);
                step(f, Op::AddV, &[115, 118, 120], 889);
                step(f, Op::MulF, &[485, 487, 491], 890);
                step(f, Op::GreaterF, &[491, 946, 60], 891);
                step(f, Op::DivF, &[489, 491, 492], 892);
                step(f, Op::Select(ValueType::Float), &[60, 492, 948, 493], 893);
                step(f, Op::ScaleV, &[113, 493, 119], 894);
                step(f, Op::SubV, &[120, 119, 121], 895);
                step(f, Op::Copy(ValueType::Vec3), &[121, 112], 896);
                step(f, Op::BreakVector, &[112, 494, 495, 496], 897);
                step(f, Op::ClampF, &[496, 65, 66, 497], 898);
                step(f, Op::MakeVector, &[494, 495, 497, 122], 899);
                step(f, Op::RotationFromNormal, &[166, 483, 484, 20], 900);
                step(f, Op::PerFootRotationFactor, &[14, 114, 115, 480], 901);
                step(f, Op::MulF, &[14, 480, 481], 902);
                step(f, Op::SubF, &[948, 15, 462], 903);
                step(f, Op::MulF, &[481, 462, 482], 904);
                step(f, Op::QuatFromAxisAngle, &[495, 482, 19], 905);
                step(f, Op::MulQ, &[20, 19, 21], 906);
                step(f, Op::Select(ValueType::Quat), &[82, 21, 22, 23], 907);
                step(f, Op::MakeTransform, &[122, 23, 492, 30], 908);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 3, 30], 909);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 27], 910);
                step(f, Op::BreakTransform, &[27, 104, 22, 105], 911);
                step(f, Op::Select(ValueType::Vec3), &[82, 103, 104, 106], 912);
                step(f, Op::MakeTransform, &[106, 99, 492, 29], 913);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 3, 29], 914);
                step(f, Op::GetTransform, &[34, 71, 131, 25], 915);
                step(f, Op::BreakTransform, &[25, 91, 16, 92], 916);
                step(f, Op::BreakVector, &[91, 464, 465, 466], 917);
                step(f, Op::MulF, &[14, 462, 463], 918);
                step(f, Op::QuatFromAxisAngle, &[495, 463, 18], 919);
                step(f, Op::GetTransform, &[0, 71, 131, 26], 920);
                step(f, Op::BreakTransform, &[26, 93, 17, 94], 921);
                step(f, Op::SubV, &[93, 91, 95], 922);
                step(f, Op::BreakVector, &[95, 459, 460, 461], 923);
                step(f, Op::MakeVector, &[459, 460, 946, 96], 924);
                step(f, Op::RotateVector, &[18, 96, 97], 925);
                step(f, Op::BreakVector, &[97, 467, 468, 469], 926);
                step(f, Op::MulF, &[49, 15, 470], 927);
                step(f, Op::MulF, &[470, 479, 471], 928);
                step(f, Op::AddF, &[467, 471, 472], 929);
                step(f, Op::AddF, &[464, 472, 473], 930);
                step(f, Op::AddF, &[465, 468, 474], 931);
                step(f, Op::BreakVector, &[93, 475, 476, 477], 932);
                step(f, Op::SubF, &[477, 55, 478], 933);
                step(f, Op::MakeVector, &[473, 474, 478, 98], 934);
                step(f, Op::MulF, &[6, 947, 458], 935);
                step(f, Op::ScaleV, &[2, 458, 90], 936);
                step(f, Op::AddV, &[98, 90, 101], 937);
                step(f, Op::SubV, &[106, 101, 123], 938);
                step(f, Op::ArraySetAt(Elem::Vec3), &[0, 3, 123], 939);
                step(f, Op::ArraySetAt(Elem::Bool), &[1, 3, 82], 940);
                step(f, Op::GreaterEqualF, &[453, 948, 62], 941);
                step(f, Op::JumpIfFalse, &[62, 958], 942)
            }
            942 => {
                step(f, Op::MakeVector, &[946, 946, 60, 126], 943);
                step(f, Op::AddV, &[101, 126, 127], 944);
                step(f, Op::RotateVector, &[0, 496, 102], 945);
                step(f, Op::ScaleV, &[102, 64, 131], 946);
                step(f, Op::AddV, &[127, 131, 132], 947);
                step(f, Op::SubV, &[101, 126, 128], 948);
                step(f, Op::AddV, &[128, 131, 133], 949);
                step(f, Op::SphereTrace, &[132, 133, 59, 71, 134, 135, 499], 950);
                step(f, Op::SubV, &[134, 101, 144], 951);
                step(f, Op::ArraySetAt(Elem::Vec3), &[1, 3, 144], 952);
                step(f, Op::ScaleV, &[102, 61, 136], 953);
                step(f, Op::AddV, &[132, 136, 137], 954);
                step(f, Op::AddV, &[133, 136, 138], 955);
                step(f, Op::SphereTrace, &[137, 138, 59, 72, 139, 140, 500], 956);
                step(f, Op::SubV, &[139, 101, 141], 957);
                step(f, Op::ArraySetAt(Elem::Vec3), &[2, 3, 141], 958);
                958
            }
            958 => {
                step(f, Op::JumpIfFalse, &[82, 960], 959)
            }
            959 => {
                step(f, Op::Copy(ValueType::Bool), &[131, 7], 960);
                960
            }
            960 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 3, 35], 961);
                step(f, Op::GreaterF, &[23, 946, 94], 962);
                step(f, Op::InterpolateTransform, &[2, 124, 24, 33], 963);
                step(f, Op::Select(ValueType::Transform), &[94, 33, 2, 34], 964);
                step(f, Op::MakeAbsolute, &[35, 34, 36], 965);
                step(f, Op::BreakTransform, &[36, 187, 25, 188], 966);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 3, 37], 967);
                step(f, Op::BreakTransform, &[37, 189, 26, 190], 968);
                step(f, Op::AddF, &[69, 70, 558], 969);
                step(f, Op::ClampSpatially, &[187, 189, 946, 558, 191], 970);
                step(f, Op::SubF, &[948, 15, 590], 971);
                step(f, Op::MulF, &[14, 590, 559], 972);
                step(f, Op::LimitRotationAroundZ, &[25, 559, 104, 27], 973);
                step(f, Op::MakeTransform, &[191, 27, 492, 38], 974);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 3, 38], 975);
                step(f, Op::ArrayAt(Elem::Float), &[4, 3, 567], 976);
                step(f, Op::FloatLerp, &[567, 946, 107, 568], 977);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 3, 91], 978);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 557], 979);
                step(f, Op::GreaterEqualF, &[557, 948, 92], 980);
                step(f, Op::And, &[91, 92, 95], 981);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 3, 35], 982);
                step(f, Op::MakeAbsolute, &[35, 34, 36], 983);
                step(f, Op::BreakTransform, &[36, 187, 25, 188], 984);
                step(f, Op::RotateVector, &[25, 496, 192], 985);
                step(f, Op::LimitRotationAroundZ, &[25, 559, 104, 27], 986);
                step(f, Op::RotateVector, &[27, 496, 193], 987);
                step(f, Op::CrossV, &[192, 193, 194], 988);
                step(f, Op::BreakVector, &[194, 560, 561, 562], 989);
                step(f, Op::DotV, &[192, 193, 563], 990);
                step(f, Op::Atan2F, &[562, 563, 564], 991);
                step(f, Op::AbsF, &[564, 565], 992);
                step(f, Op::Select(ValueType::Float), &[95, 565, 946, 566], 993);
                step(f, Op::AddF, &[568, 566, 569], 994);
                step(f, Op::ArraySetAt(Elem::Float), &[4, 3, 569], 995);
                step(f, Op::JumpIfFalse, &[91, 1072], 996)
            }
            996 => {
                step(f, Op::JumpIfFalse, &[92, 998], 997)
            }
            997 => {
                step(f, Op::Jump, &[1071], 998)
            }
            998 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 41], 999);
                step(f, Op::BreakTransform, &[41, 200, 29, 201], 1000);
                step(f, Op::SubF, &[948, 557, 580], 1001);
                step(f, Op::MulF, &[10, 7, 581], 1002);
                step(f, Op::MulF, &[580, 581, 582], 1003);
                step(f, Op::ScaleV, &[2, 582, 202], 1004);
                step(f, Op::AddV, &[200, 202, 203], 1005);
                step(f, Op::Equals(Elem::Int), &[3, 71, 93], 1006);
                step(f, Op::Select(ValueType::Int), &[93, 72, 71, 59], 1007);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 59, 96], 1008);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 59, 42], 1009);
                step(f, Op::BreakTransform, &[42, 204, 30, 205], 1010);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 59, 43], 1011);
                step(f, Op::BreakTransform, &[43, 206, 31, 207], 1012);
                step(f, Op::LessEqualF, &[90, 946, 97], 1013);
                step(f, Op::ArrayAt(Elem::Float), &[2, 59, 707], 1014);
                step(f, Op::SmoothStepF, &[707, 946, 90, 583], 1015);
                step(f, Op::Select(ValueType::Float), &[97, 948, 583, 584], 1016);
                step(f, Op::LerpV, &[204, 206, 584, 208], 1017);
                step(f, Op::MakeTransform, &[208, 99, 492, 44], 1018);
                step(f, Op::Select(ValueType::Transform), &[96, 42, 44, 45], 1019);
                step(f, Op::MakeAbsolute, &[45, 34, 46], 1020);
                step(f, Op::Select(ValueType::Transform), &[93, 46, 45, 47], 1021);
                step(f, Op::BreakTransform, &[47, 209, 32, 210], 1022);
                step(f, Op::SubF, &[948, 16, 591], 1023);
                step(f, Op::MulF, &[590, 591, 592], 1024);
                step(f, Op::MulF, &[14, 592, 593], 1025);
                step(f, Op::FootAvoidance, &[203, 209, 593, 93, 86, 211], 1026);
                step(f, Op::RemapF, &[15, 89, 948, 946, 948, 131, 585], 1027);
                step(f, Op::LerpV, &[203, 211, 585, 212], 1028);
                step(f, Op::FootAvoidance, &[212, 209, 17, 93, 112, 213], 1029);
                step(f, Op::LerpV, &[212, 213, 16, 214], 1030);
                step(f, Op::MakeTransform, &[214, 29, 492, 56], 1031);
                step(f, Op::BreakTransform, &[56, 247, 39, 248], 1032);
                step(f, Op::MakeVector, &[946, 946, 60, 249], 1033);
                step(f, Op::AddV, &[247, 249, 250], 1034);
                step(f, Op::SubV, &[247, 249, 251], 1035);
                step(f, Op::LineTrace, &[250, 251, 101, 252, 253, 619], 1036);
                step(f, Op::RotateVector, &[39, 495, 254], 1037);
                step(f, Op::FindQuatBetween, &[254, 253, 40], 1038);
                step(f, Op::MulQ, &[40, 39, 41], 1039);
                step(f, Op::MulF, &[58, 57, 620], 1040);
                step(f, Op::AddF, &[620, 68, 621], 1041);
                step(f, Op::NegF, &[621, 622], 1042);
                step(f, Op::MakeVector, &[946, 622, 946, 255], 1043);
                step(f, Op::RotateVector, &[41, 255, 257], 1044);
                step(f, Op::AddV, &[252, 257, 259], 1045);
                step(f, Op::AddV, &[259, 249, 261], 1046);
                step(f, Op::SubV, &[259, 249, 262], 1047);
                step(f, Op::LineTrace, &[261, 262, 102, 265, 266, 624], 1048);
                step(f, Op::BreakVector, &[265, 626, 627, 628], 1049);
                step(f, Op::BreakVector, &[259, 632, 633, 634], 1050);
                step(f, Op::SubF, &[628, 634, 638], 1051);
                step(f, Op::Select(ValueType::Float), &[102, 638, 946, 640], 1052);
                step(f, Op::AddF, &[64, 68, 623], 1053);
                step(f, Op::MakeVector, &[946, 623, 946, 256], 1054);
                step(f, Op::RotateVector, &[41, 256, 258], 1055);
                step(f, Op::AddV, &[252, 258, 260], 1056);
                step(f, Op::AddV, &[260, 249, 263], 1057);
                step(f, Op::SubV, &[260, 249, 264], 1058);
                step(f, Op::LineTrace, &[263, 264, 103, 267, 268, 625], 1059);
                step(f, Op::BreakVector, &[267, 629, 630, 631], 1060);
                step(f, Op::BreakVector, &[260, 635, 636, 637], 1061);
                step(f, Op::SubF, &[631, 637, 639], 1062);
                step(f, Op::Select(ValueType::Float), &[103, 639, 946, 641], 1063);
                step(f, Op::MaxF, &[640, 641, 642], 1064);
                step(f, Op::ClampF, &[642, 946, 67, 643], 1065);
                step(f, Op::MakeVector, &[946, 946, 643, 269], 1066);
                step(f, Op::AddV, &[252, 269, 270], 1067);
                step(f, Op::MakeTransform, &[270, 41, 492, 59], 1068);
                step(f, Op::Select(ValueType::Transform), &[101, 59, 56, 60], 1069);
                step(f, Op::Copy(ValueType::Transform), &[60, 58], 1070);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 3, 58], 1071);
                1071
            }
            1071 => {
                step(f, Op::Jump, &[1188], 1072)
            }
            1072 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 3, 61], 1073);
                step(f, Op::MakeAbsolute, &[61, 34, 62], 1074);
                step(f, Op::BreakTransform, &[62, 271, 42, 272], 1075);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 41], 1076);
                step(f, Op::BreakTransform, &[41, 200, 29, 201], 1077);
                step(f, Op::SubF, &[948, 557, 580], 1078);
                step(f, Op::MulF, &[10, 7, 581], 1079);
                step(f, Op::MulF, &[580, 581, 582], 1080);
                step(f, Op::ScaleV, &[2, 582, 202], 1081);
                step(f, Op::AddV, &[200, 202, 203], 1082);
                step(f, Op::Equals(Elem::Int), &[3, 71, 93], 1083);
                step(f, Op::Select(ValueType::Int), &[93, 72, 71, 59], 1084);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 59, 96], 1085);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 59, 42], 1086);
                step(f, Op::BreakTransform, &[42, 204, 30, 205], 1087);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 59, 43], 1088);
                step(f, Op::BreakTransform, &[43, 206, 31, 207], 1089);
                step(f, Op::LessEqualF, &[90, 946, 97], 1090);
                step(f, Op::ArrayAt(Elem::Float), &[2, 59, 707], 1091);
                step(f, Op::SmoothStepF, &[707, 946, 90, 583], 1092);
                step(f, Op::Select(ValueType::Float), &[97, 948, 583, 584], 1093);
                step(f, Op::LerpV, &[204, 206, 584, 208], 1094);
                step(f, Op::MakeTransform, &[208, 99, 492, 44], 1095);
                step(f, Op::Select(ValueType::Transform), &[96, 42, 44, 45], 1096);
                step(f, Op::MakeAbsolute, &[45, 34, 46], 1097);
                step(f, Op::Select(ValueType::Transform), &[93, 46, 45, 47], 1098);
                step(f, Op::BreakTransform, &[47, 209, 32, 210], 1099);
                step(f, Op::SubF, &[948, 16, 591], 1100);
                step(f, Op::MulF, &[590, 591, 592], 1101);
                step(f, Op::MulF, &[14, 592, 593], 1102);
                step(f, Op::FootAvoidance, &[203, 209, 593, 93, 86, 211], 1103);
                step(f, Op::RemapF, &[15, 89, 948, 946, 948, 131, 585], 1104);
                step(f, Op::LerpV, &[203, 211, 585, 212], 1105);
                step(f, Op::FootAvoidance, &[212, 209, 17, 93, 112, 213], 1106);
                step(f, Op::LerpV, &[212, 213, 16, 214], 1107);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 3, 63], 1108);
                step(f, Op::MakeAbsolute, &[63, 34, 64], 1109);
                step(f, Op::BreakTransform, &[64, 273, 43, 274], 1110);
                step(f, Op::ArrayAt(Elem::Float), &[3, 3, 644], 1111);
                step(f, Op::SubF, &[557, 644, 645], 1112);
                step(f, Op::DeltaTime, &[660], 1113);
                step(f, Op::DivF, &[54, 660, 646], 1114);
                step(f, Op::MulF, &[645, 646, 647], 1115);
                step(f, Op::AddF, &[644, 647, 648], 1116);
                step(f, Op::ClampF, &[648, 946, 948, 650], 1117);
                step(f, Op::AddF, &[557, 647, 649], 1118);
                step(f, Op::ClampF, &[649, 946, 948, 651], 1119);
                step(f, Op::AddF, &[650, 651, 652], 1120);
                step(f, Op::MulF, &[652, 947, 653], 1121);
                step(f, Op::SubF, &[948, 653, 654], 1122);
                step(f, Op::GreaterF, &[645, 946, 104], 1123);
                step(f, Op::SubF, &[651, 650, 655], 1124);
                step(f, Op::DivF, &[655, 645, 656], 1125);
                step(f, Op::Select(ValueType::Float), &[104, 656, 948, 657], 1126);
                step(f, Op::MulF, &[654, 657, 658], 1127);
                step(f, Op::MulF, &[85, 658, 659], 1128);
                step(f, Op::Copy(ValueType::Float), &[54, 662], 1129);
                step(f, Op::SubV, &[214, 273, 279], 1130);
                step(f, Op::DeltaTime, &[663], 1131);
                step(f, Op::DivF, &[662, 663, 664], 1132);
                step(f, Op::ScaleV, &[279, 664, 280], 1133);
                step(f, Op::AddV, &[214, 280, 281], 1134);
                step(f, Op::AddV, &[273, 280, 282], 1135);
                step(f, Op::SubV, &[271, 282, 283], 1136);
                step(f, Op::FloatLerp, &[946, 948, 659, 665], 1137);
                step(f, Op::SubF, &[948, 665, 666], 1138);
                step(f, Op::ScaleV, &[283, 666, 284], 1139);
                step(f, Op::AddV, &[281, 284, 286], 1140);
                step(f, Op::MulF, &[659, 663, 667], 1141);
                step(f, Op::GreaterF, &[667, 946, 105], 1142);
                step(f, Op::DivF, &[665, 667, 668], 1143);
                step(f, Op::Select(ValueType::Float), &[105, 668, 948, 669], 1144);
                step(f, Op::ScaleV, &[279, 669, 285], 1145);
                step(f, Op::SubV, &[286, 285, 287], 1146);
                step(f, Op::Copy(ValueType::Vec3), &[287, 278], 1147);
                step(f, Op::MakeTransform, &[278, 29, 492, 66], 1148);
                step(f, Op::BreakTransform, &[66, 288, 44, 289], 1149);
                step(f, Op::MakeVector, &[946, 946, 60, 290], 1150);
                step(f, Op::AddV, &[288, 290, 291], 1151);
                step(f, Op::SubV, &[288, 290, 292], 1152);
                step(f, Op::LineTrace, &[291, 292, 106, 293, 294, 670], 1153);
                step(f, Op::RotateVector, &[44, 495, 295], 1154);
                step(f, Op::FindQuatBetween, &[295, 294, 45], 1155);
                step(f, Op::MulQ, &[45, 44, 46], 1156);
                step(f, Op::MulF, &[58, 57, 671], 1157);
                step(f, Op::AddF, &[671, 68, 672], 1158);
                step(f, Op::NegF, &[672, 673], 1159);
                step(f, Op::MakeVector, &[946, 673, 946, 296], 1160);
                step(f, Op::RotateVector, &[46, 296, 298], 1161);
                step(f, Op::AddV, &[293, 298, 300], 1162);
                step(f, Op::AddV, &[300, 290, 302], 1163);
                step(f, Op::SubV, &[300, 290, 303], 1164);
                step(f, Op::LineTrace, &[302, 303, 107, 306, 307, 675], 1165);
                step(f, Op::BreakVector, &[306, 677, 678, 679], 1166);
                step(f, Op::BreakVector, &[300, 683, 684, 685], 1167);
                step(f, Op::SubF, &[679, 685, 689], 1168);
                step(f, Op::Select(ValueType::Float), &[107, 689, 946, 691], 1169);
                step(f, Op::AddF, &[64, 68, 674], 1170);
                step(f, Op::MakeVector, &[946, 674, 946, 297], 1171);
                step(f, Op::RotateVector, &[46, 297, 299], 1172);
                step(f, Op::AddV, &[293, 299, 301], 1173);
                step(f, Op::AddV, &[301, 290, 304], 1174);
                step(f, Op::SubV, &[301, 290, 305], 1175);
                step(f, Op::LineTrace, &[304, 305, 108, 308, 309, 676], 1176);
                step(f, Op::BreakVector, &[308, 680, 681, 682], 1177);
                step(f, Op::BreakVector, &[301, 686, 687, 688], 1178);
                step(f, Op::SubF, &[682, 688, 690], 1179);
                step(f, Op::Select(ValueType::Float), &[108, 690, 946, 692], 1180);
                step(f, Op::MaxF, &[691, 692, 693], 1181);
                step(f, Op::ClampF, &[693, 946, 67, 694], 1182);
                step(f, Op::MakeVector, &[946, 946, 694, 310], 1183);
                step(f, Op::AddV, &[293, 310, 311], 1184);
                step(f, Op::MakeTransform, &[311, 46, 492, 69], 1185);
                step(f, Op::Select(ValueType::Transform), &[106, 69, 66, 70], 1186);
                step(f, Op::Copy(ValueType::Transform), &[70, 68], 1187);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 3, 68], 1188);
                1188
            }
            1188 => {
                step(f, Op::JumpIfFalse, &[92, 1271], 1189)
            }
            1189 => {
                step(f, Op::JumpIfFalse, &[91, 1191], 1190)
            }
            1190 => {
                step(f, Op::Jump, &[1252], 1191)
            }
            1191 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 3, 71], 1192);
                step(f, Op::BreakTransform, &[71, 312, 47, 313], 1193);
                step(f, Op::Equals(Elem::Int), &[3, 71, 93], 1194);
                step(f, Op::Select(ValueType::Int), &[93, 72, 71, 59], 1195);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 59, 48], 1196);
                step(f, Op::BreakTransform, &[48, 215, 33, 216], 1197);
                step(f, Op::MakeAbsolute, &[48, 34, 49], 1198);
                step(f, Op::BreakTransform, &[49, 217, 34, 218], 1199);
                step(f, Op::ArrayAt(Elem::Float), &[2, 59, 707], 1200);
                step(f, Op::SmoothStepF, &[707, 946, 948, 586], 1201);
                step(f, Op::RemapF, &[15, 946, 89, 946, 948, 131, 587], 1202);
                step(f, Op::MulF, &[586, 587, 588], 1203);
                step(f, Op::Select(ValueType::Float), &[93, 588, 946, 589], 1204);
                step(f, Op::LerpV, &[215, 217, 589, 219], 1205);
                step(f, Op::MakeTransform, &[219, 99, 492, 50], 1206);
                step(f, Op::BreakTransform, &[50, 220, 35, 221], 1207);
                step(f, Op::SubF, &[948, 16, 591], 1208);
                step(f, Op::MulF, &[590, 591, 592], 1209);
                step(f, Op::MulF, &[14, 592, 593], 1210);
                step(f, Op::FootAvoidance, &[312, 220, 593, 93, 86, 222], 1211);
                step(f, Op::MakeTransform, &[222, 47, 492, 51], 1212);
                step(f, Op::BreakTransform, &[51, 223, 36, 224], 1213);
                step(f, Op::MakeVector, &[946, 946, 60, 225], 1214);
                step(f, Op::AddV, &[223, 225, 226], 1215);
                step(f, Op::SubV, &[223, 225, 227], 1216);
                step(f, Op::LineTrace, &[226, 227, 98, 228, 229, 594], 1217);
                step(f, Op::RotateVector, &[36, 495, 230], 1218);
                step(f, Op::FindQuatBetween, &[230, 229, 37], 1219);
                step(f, Op::MulQ, &[37, 36, 38], 1220);
                step(f, Op::MulF, &[58, 57, 595], 1221);
                step(f, Op::AddF, &[595, 68, 596], 1222);
                step(f, Op::NegF, &[596, 597], 1223);
                step(f, Op::MakeVector, &[946, 597, 946, 231], 1224);
                step(f, Op::RotateVector, &[38, 231, 233], 1225);
                step(f, Op::AddV, &[228, 233, 235], 1226);
                step(f, Op::AddV, &[235, 225, 237], 1227);
                step(f, Op::SubV, &[235, 225, 238], 1228);
                step(f, Op::LineTrace, &[237, 238, 99, 241, 242, 599], 1229);
                step(f, Op::BreakVector, &[241, 601, 602, 603], 1230);
                step(f, Op::BreakVector, &[235, 607, 608, 609], 1231);
                step(f, Op::SubF, &[603, 609, 613], 1232);
                step(f, Op::Select(ValueType::Float), &[99, 613, 946, 615], 1233);
                step(f, Op::AddF, &[64, 68, 598], 1234);
                step(f, Op::MakeVector, &[946, 598, 946, 232], 1235);
                step(f, Op::RotateVector, &[38, 232, 234], 1236);
                step(f, Op::AddV, &[228, 234, 236], 1237);
                step(f, Op::AddV, &[236, 225, 239], 1238);
                step(f, Op::SubV, &[236, 225, 240], 1239);
                step(f, Op::LineTrace, &[239, 240, 100, 243, 244, 600], 1240);
                step(f, Op::BreakVector, &[243, 604, 605, 606], 1241);
                step(f, Op::BreakVector, &[236, 610, 611, 612], 1242);
                step(f, Op::SubF, &[606, 612, 614], 1243);
                step(f, Op::Select(ValueType::Float), &[100, 614, 946, 616], 1244);
                step(f, Op::MaxF, &[615, 616, 617], 1245);
                step(f, Op::ClampF, &[617, 946, 67, 618], 1246);
                step(f, Op::MakeVector, &[946, 946, 618, 245], 1247);
                step(f, Op::AddV, &[228, 245, 246], 1248);
                step(f, Op::MakeTransform, &[246, 38, 492, 54], 1249);
                step(f, Op::Select(ValueType::Transform), &[98, 54, 51, 55], 1250);
                step(f, Op::Copy(ValueType::Transform), &[55, 53], 1251);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 3, 53], 1252);
                1252
            }
            1252 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 3, 39], 1253);
                step(f, Op::BreakTransform, &[39, 195, 28, 196], 1254);
                step(f, Op::SubV, &[195, 189, 197], 1255);
                step(f, Op::LengthV, &[197, 570], 1256);
                step(f, Op::SubF, &[69, 70, 571], 1257);
                step(f, Op::SubF, &[570, 571, 572], 1258);
                step(f, Op::MulF, &[70, 951, 573], 1259);
                step(f, Op::ClampF, &[572, 946, 573, 574], 1260);
                step(f, Op::MulF, &[574, 574, 575], 1261);
                step(f, Op::MulF, &[70, 962, 576], 1262);
                step(f, Op::DivF, &[575, 576, 577], 1263);
                step(f, Op::SubF, &[570, 577, 578], 1264);
                step(f, Op::DivF, &[578, 570, 579], 1265);
                step(f, Op::ScaleV, &[197, 579, 198], 1266);
                step(f, Op::AddV, &[189, 198, 199], 1267);
                step(f, Op::MakeTransform, &[199, 28, 492, 40], 1268);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 3, 40], 1269);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 3, 40], 1270);
                step(f, Op::Jump, &[1437], 1271)
            }
            1271 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 3, 39], 1272);
                step(f, Op::BreakTransform, &[39, 195, 28, 196], 1273);
                step(f, Op::SubV, &[195, 189, 197], 1274);
                step(f, Op::LengthV, &[197, 570], 1275);
                step(f, Op::SubF, &[69, 70, 571], 1276);
                step(f, Op::SubF, &[570, 571, 572], 1277);
                step(f, Op::MulF, &[70, 951, 573], 1278);
                step(f, Op::ClampF, &[572, 946, 573, 574], 1279);
                step(f, Op::MulF, &[574, 574, 575], 1280);
                step(f, Op::MulF, &[70, 962, 576], 1281);
                step(f, Op::DivF, &[575, 576, 577], 1282);
                step(f, Op::SubF, &[570, 577, 578], 1283);
                step(f, Op::DivF, &[578, 570, 579], 1284);
                step(f, Op::ScaleV, &[197, 579, 198], 1285);
                step(f, Op::AddV, &[189, 198, 199], 1286);
                step(f, Op::MakeTransform, &[199, 28, 492, 40], 1287);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 3, 71], 1288);
                step(f, Op::ClampF, &[557, 946, 948, 695], 1289);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[6, 5], 1290);
                step(f, Op::ArrayReset(Elem::Vec3), &[5], 1291);
                step(f, Op::BreakTransform, &[40, 333, 52, 334], 1292);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 333], 1293);
                step(f, Op::UnitV, &[2, 332], 1294);
                step(f, Op::LengthV, &[2, 731], 1295);
                step(f, Op::RemapF, &[731, 946, 71, 946, 72, 131, 732], 1296);
                step(f, Op::ScaleV, &[332, 732, 337], 1297);
                step(f, Op::SubV, &[333, 337, 343], 1298);
                step(f, Op::MakeVector, &[946, 946, 74, 341], 1299);
                step(f, Op::AddV, &[343, 341, 345], 1300);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 345], 1301);
                step(f, Op::RemapF, &[731, 946, 71, 946, 76, 131, 734], 1302);
                step(f, Op::MakeVector, &[946, 946, 734, 339], 1303);
                step(f, Op::AddV, &[345, 339, 349], 1304);
                step(f, Op::BreakTransform, &[71, 335, 53, 336], 1305);
                step(f, Op::BreakVector, &[335, 739, 740, 741], 1306);
                step(f, Op::BreakVector, &[333, 736, 737, 738], 1307);
                step(f, Op::SubF, &[741, 738, 742], 1308);
                step(f, Op::MaxF, &[742, 946, 744], 1309);
                step(f, Op::MulF, &[744, 78, 748], 1310);
                step(f, Op::MinF, &[748, 79, 749], 1311);
                step(f, Op::AbsF, &[742, 746], 1312);
                step(f, Op::RemapF, &[746, 946, 82, 946, 81, 131, 747], 1313);
                step(f, Op::AddF, &[749, 747, 751], 1314);
                step(f, Op::MakeVector, &[946, 946, 751, 347], 1315);
                step(f, Op::AddV, &[349, 347, 351], 1316);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 351], 1317);
                step(f, Op::RemapF, &[731, 946, 71, 946, 73, 131, 733], 1318);
                step(f, Op::ScaleV, &[332, 733, 338], 1319);
                step(f, Op::AddV, &[335, 338, 344], 1320);
                step(f, Op::MakeVector, &[946, 946, 75, 342], 1321);
                step(f, Op::AddV, &[344, 342, 346], 1322);
                step(f, Op::RemapF, &[731, 946, 71, 946, 77, 131, 735], 1323);
                step(f, Op::MakeVector, &[946, 946, 735, 340], 1324);
                step(f, Op::AddV, &[346, 340, 350], 1325);
                step(f, Op::NegF, &[742, 743], 1326);
                step(f, Op::MaxF, &[743, 946, 745], 1327);
                step(f, Op::MulF, &[745, 80, 750], 1328);
                step(f, Op::AddF, &[750, 747, 752], 1329);
                step(f, Op::MakeVector, &[946, 946, 752, 348], 1330);
                step(f, Op::AddV, &[350, 348, 352], 1331);
                step(f, Op::LerpV, &[351, 352, 947, 353], 1332);
                step(f, Op::GetTransform, &[35, 71, 131, 80], 1333);
                step(f, Op::BreakTransform, &[80, 354, 54, 355], 1334);
                step(f, Op::BreakVector, &[354, 762, 763, 764], 1335);
                step(f, Op::SubF, &[948, 15, 756], 1336);
                step(f, Op::MulF, &[83, 756, 757], 1337);
                step(f, Op::MulF, &[14, 757, 758], 1338);
                step(f, Op::QuatFromAxisAngle, &[495, 758, 55], 1339);
                step(f, Op::SubV, &[353, 354, 356], 1340);
                step(f, Op::BreakVector, &[356, 753, 754, 755], 1341);
                step(f, Op::MakeVector, &[753, 754, 946, 357], 1342);
                step(f, Op::RotateVector, &[55, 357, 358], 1343);
                step(f, Op::BreakVector, &[358, 759, 760, 761], 1344);
                step(f, Op::AddF, &[762, 759, 768], 1345);
                step(f, Op::AddF, &[763, 760, 769], 1346);
                step(f, Op::BreakVector, &[353, 765, 766, 767], 1347);
                step(f, Op::MakeVector, &[768, 769, 767, 359], 1348);
                step(f, Op::DistanceV, &[333, 335, 770], 1349);
                step(f, Op::RemapF, &[770, 951, 963, 946, 948, 131, 771], 1350);
                step(f, Op::LerpV, &[353, 359, 771, 360], 1351);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 360], 1352);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 352], 1353);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 346], 1354);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 335], 1355);
                step(f, Op::JumpIfFalse, &[8, 1357], 1356)
            }
            1356 => {
                step(f, Op::DrawSpline, &[5, 71, 74, 947, 498], 1357);
                1357
            }
            1357 => {
                step(f, Op::Spline, &[5, 695, 71, 361, 362], 1358);
                step(f, Op::SlerpQ, &[52, 53, 695, 56], 1359);
                step(f, Op::MulF, &[695, 956, 773], 1360);
                step(f, Op::SinF, &[773, 774], 1361);
                step(f, Op::SmoothStepF, &[695, 946, 97, 772], 1362);
                step(f, Op::MulF, &[774, 772, 775], 1363);
                step(f, Op::MulF, &[775, 84, 776], 1364);
                step(f, Op::SlerpQ, &[56, 99, 776, 57], 1365);
                step(f, Op::MakeTransform, &[361, 57, 492, 81], 1366);
                step(f, Op::Copy(ValueType::Transform), &[81, 79], 1367);
                step(f, Op::BreakTransform, &[79, 314, 48, 315], 1368);
                step(f, Op::Equals(Elem::Int), &[3, 71, 93], 1369);
                step(f, Op::Select(ValueType::Int), &[93, 72, 71, 59], 1370);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 59, 48], 1371);
                step(f, Op::BreakTransform, &[48, 215, 33, 216], 1372);
                step(f, Op::GreaterF, &[23, 946, 94], 1373);
                step(f, Op::InterpolateTransform, &[2, 124, 24, 33], 1374);
                step(f, Op::Select(ValueType::Transform), &[94, 33, 2, 34], 1375);
                step(f, Op::MakeAbsolute, &[48, 34, 49], 1376);
                step(f, Op::BreakTransform, &[49, 217, 34, 218], 1377);
                step(f, Op::ArrayAt(Elem::Float), &[2, 59, 707], 1378);
                step(f, Op::SmoothStepF, &[707, 946, 948, 586], 1379);
                step(f, Op::RemapF, &[15, 946, 89, 946, 948, 131, 587], 1380);
                step(f, Op::MulF, &[586, 587, 588], 1381);
                step(f, Op::Select(ValueType::Float), &[93, 588, 946, 589], 1382);
                step(f, Op::LerpV, &[215, 217, 589, 219], 1383);
                step(f, Op::MakeTransform, &[219, 99, 492, 50], 1384);
                step(f, Op::BreakTransform, &[50, 220, 35, 221], 1385);
                step(f, Op::SubF, &[948, 15, 590], 1386);
                step(f, Op::SubF, &[948, 16, 591], 1387);
                step(f, Op::MulF, &[590, 591, 592], 1388);
                step(f, Op::MulF, &[14, 592, 593], 1389);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 59, 109], 1390);
                step(f, Op::Select(ValueType::Float), &[109, 87, 946, 698], 1391);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 557], 1392);
                step(f, Op::ClampF, &[557, 946, 948, 695], 1393);
                step(f, Op::MulF, &[695, 956, 696], 1394);
                step(f, Op::SinF, &[696, 697], 1395);
                step(f, Op::MulF, &[697, 697, 699], 1396);
                step(f, Op::MulF, &[698, 699, 700], 1397);
                step(f, Op::AddF, &[86, 700, 701], 1398);
                step(f, Op::FootAvoidance, &[314, 220, 593, 93, 701, 316], 1399);
                step(f, Op::SubV, &[316, 314, 317], 1400);
                step(f, Op::LengthV, &[317, 702], 1401);
                step(f, Op::AddF, &[702, 700, 703], 1402);
                step(f, Op::DivF, &[702, 703, 704], 1403);
                step(f, Op::MulF, &[111, 951, 713], 1404);
                step(f, Op::LessEqualF, &[702, 713, 112], 1405);
                step(f, Op::MulF, &[111, 962, 714], 1406);
                step(f, Op::DivF, &[702, 714, 715], 1407);
                step(f, Op::DivF, &[111, 702, 716], 1408);
                step(f, Op::SubF, &[948, 716, 717], 1409);
                step(f, Op::Select(ValueType::Float), &[112, 715, 717, 718], 1410);
                step(f, Op::GreaterF, &[111, 946, 113], 1411);
                step(f, Op::Select(ValueType::Float), &[113, 16, 946, 719], 1412);
                step(f, Op::LerpF, &[704, 718, 719, 720], 1413);
                step(f, Op::LessF, &[707, 557, 111], 1414);
                step(f, Op::LessEqualF, &[88, 946, 110], 1415);
                step(f, Op::SmoothStepF, &[707, 946, 88, 708], 1416);
                step(f, Op::MulF, &[708, 15, 709], 1417);
                step(f, Op::SubF, &[948, 709, 710], 1418);
                step(f, Op::Select(ValueType::Float), &[110, 948, 710, 711], 1419);
                step(f, Op::Select(ValueType::Float), &[111, 711, 948, 712], 1420);
                step(f, Op::MulF, &[720, 712, 721], 1421);
                step(f, Op::SmoothStepF, &[695, 946, 88, 705], 1422);
                step(f, Op::Select(ValueType::Float), &[110, 948, 705, 706], 1423);
                step(f, Op::MulF, &[721, 706, 722], 1424);
                step(f, Op::ScaleV, &[317, 722, 318], 1425);
                step(f, Op::AddV, &[314, 318, 319], 1426);
                step(f, Op::MulF, &[3, 143, 723], 1427);
                step(f, Op::MulF, &[723, 699, 724], 1428);
                step(f, Op::MakeVector, &[946, 946, 724, 320], 1429);
                step(f, Op::AddV, &[319, 320, 321], 1430);
                step(f, Op::MakeTransform, &[321, 48, 492, 72], 1431);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 3, 72], 1432);
                step(f, Op::ScaleV, &[317, 721, 322], 1433);
                step(f, Op::AddV, &[314, 322, 323], 1434);
                step(f, Op::AddV, &[323, 320, 324], 1435);
                step(f, Op::MakeTransform, &[324, 48, 492, 73], 1436);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 3, 73], 1437);
                1437
            }
            1437 => {
                step(f, Op::JumpIfFalse, &[94, 1460], 1438)
            }
            1438 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 3, 74], 1439);
                step(f, Op::BreakTransform, &[74, 325, 49, 326], 1440);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 3, 75], 1441);
                step(f, Op::BreakTransform, &[75, 327, 50, 328], 1442);
                step(f, Op::MulF, &[23, 23, 725], 1443);
                step(f, Op::LerpV, &[325, 327, 725, 329], 1444);
                step(f, Op::SubF, &[948, 23, 726], 1445);
                step(f, Op::MulF, &[23, 726, 727], 1446);
                step(f, Op::MulF, &[145, 951, 728], 1447);
                step(f, Op::MulF, &[727, 728, 729], 1448);
                step(f, Op::MakeVector, &[946, 946, 729, 330], 1449);
                step(f, Op::AddV, &[329, 330, 331], 1450);
                step(f, Op::SlerpQ, &[49, 50, 23, 51], 1451);
                step(f, Op::MakeTransform, &[331, 51, 492, 76], 1452);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 3, 76], 1453);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 3, 74], 1454);
                step(f, Op::BreakTransform, &[74, 325, 49, 326], 1455);
                step(f, Op::LerpV, &[325, 327, 725, 329], 1456);
                step(f, Op::AddV, &[329, 330, 331], 1457);
                step(f, Op::SlerpQ, &[49, 50, 23, 51], 1458);
                step(f, Op::MakeTransform, &[331, 51, 492, 76], 1459);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 3, 76], 1460);
                1460
            }
            1460 => {
                step(f, Op::GreaterEqualF, &[557, 948, 92], 1461);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 3, 92], 1462);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 41], 1463);
                step(f, Op::BreakTransform, &[41, 200, 29, 201], 1464);
                step(f, Op::SubF, &[948, 557, 580], 1465);
                step(f, Op::MulF, &[10, 7, 581], 1466);
                step(f, Op::MulF, &[580, 581, 582], 1467);
                step(f, Op::ScaleV, &[2, 582, 202], 1468);
                step(f, Op::AddV, &[200, 202, 203], 1469);
                step(f, Op::Equals(Elem::Int), &[3, 71, 93], 1470);
                step(f, Op::Select(ValueType::Int), &[93, 72, 71, 59], 1471);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 59, 96], 1472);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 59, 42], 1473);
                step(f, Op::BreakTransform, &[42, 204, 30, 205], 1474);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 59, 43], 1475);
                step(f, Op::BreakTransform, &[43, 206, 31, 207], 1476);
                step(f, Op::LessEqualF, &[90, 946, 97], 1477);
                step(f, Op::ArrayAt(Elem::Float), &[2, 59, 707], 1478);
                step(f, Op::SmoothStepF, &[707, 946, 90, 583], 1479);
                step(f, Op::Select(ValueType::Float), &[97, 948, 583, 584], 1480);
                step(f, Op::LerpV, &[204, 206, 584, 208], 1481);
                step(f, Op::MakeTransform, &[208, 99, 492, 44], 1482);
                step(f, Op::Select(ValueType::Transform), &[96, 42, 44, 45], 1483);
                step(f, Op::MakeAbsolute, &[45, 34, 46], 1484);
                step(f, Op::Select(ValueType::Transform), &[93, 46, 45, 47], 1485);
                step(f, Op::BreakTransform, &[47, 209, 32, 210], 1486);
                step(f, Op::SubF, &[948, 16, 591], 1487);
                step(f, Op::MulF, &[590, 591, 592], 1488);
                step(f, Op::MulF, &[14, 592, 593], 1489);
                step(f, Op::FootAvoidance, &[203, 209, 593, 93, 86, 211], 1490);
                step(f, Op::RemapF, &[15, 89, 948, 946, 948, 131, 585], 1491);
                step(f, Op::LerpV, &[203, 211, 585, 212], 1492);
                step(f, Op::FootAvoidance, &[212, 209, 17, 93, 112, 213], 1493);
                step(f, Op::LerpV, &[212, 213, 16, 214], 1494);
                step(f, Op::MakeTransform, &[214, 99, 492, 65], 1495);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 3, 65], 1496);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 3, 82], 1497);
                step(f, Op::BreakTransform, &[82, 363, 58, 364], 1498);
                step(f, Op::MakeVector, &[946, 946, 55, 373], 1499);
                step(f, Op::AddV, &[363, 373, 374], 1500);
                step(f, Op::GetTransform, &[0, 71, 131, 84], 1501);
                step(f, Op::BreakTransform, &[84, 368, 60, 369], 1502);
                step(f, Op::MakeTransform, &[374, 60, 492, 86], 1503);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 3, 20], 1504);
                step(f, Op::GetTransform, &[20, 71, 131, 85], 1505);
                step(f, Op::BreakTransform, &[85, 370, 61, 371], 1506);
                step(f, Op::SubV, &[370, 368, 372], 1507);
                step(f, Op::AddV, &[374, 372, 375], 1508);
                step(f, Op::FootPivots, &[374, 375, 57, 56, 55, 58, 376, 377, 378], 1509);
                step(f, Op::GetParent, &[0, 18], 1510);
                step(f, Op::GetParent, &[18, 19], 1511);
                step(f, Op::GetTransform, &[19, 71, 132, 83], 1512);
                step(f, Op::BreakTransform, &[83, 365, 59, 366], 1513);
                step(f, Op::SubV, &[363, 365, 367], 1514);
                step(f, Op::DotV, &[367, 496, 777], 1515);
                step(f, Op::RemapF, &[777, 92, 91, 93, 946, 131, 780], 1516);
                step(f, Op::LengthV, &[2, 778], 1517);
                step(f, Op::RemapF, &[778, 946, 103, 946, 948, 131, 779], 1518);
                step(f, Op::MulF, &[780, 779, 781], 1519);
                step(f, Op::QuatFromAxisAngle, &[499, 781, 62], 1520);
                step(f, Op::RotateAroundPoint, &[86, 376, 62, 87], 1521);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 782], 1522);
                step(f, Op::SmoothStepF, &[782, 946, 97, 784], 1523);
                step(f, Op::SubF, &[948, 782, 783], 1524);
                step(f, Op::SmoothStepF, &[783, 946, 97, 785], 1525);
                step(f, Op::MulF, &[784, 785, 786], 1526);
                step(f, Op::LerpF, &[96, 948, 786, 787], 1527);
                step(f, Op::MulF, &[781, 787, 788], 1528);
                step(f, Op::QuatFromAxisAngle, &[499, 788, 63], 1529);
                step(f, Op::SubV, &[377, 376, 379], 1530);
                step(f, Op::RotateVector, &[63, 379, 380], 1531);
                step(f, Op::AddV, &[376, 380, 381], 1532);
                step(f, Op::RemapF, &[777, 94, 92, 95, 946, 131, 789], 1533);
                step(f, Op::MulF, &[789, 779, 790], 1534);
                step(f, Op::QuatFromAxisAngle, &[499, 790, 64], 1535);
                step(f, Op::RotateAroundPoint, &[87, 381, 64, 88], 1536);
                step(f, Op::RemapF, &[777, 98, 99, 946, 100, 131, 791], 1537);
                step(f, Op::RotateVector, &[58, 495, 382], 1538);
                step(f, Op::BreakVector, &[382, 792, 793, 794], 1539);
                step(f, Op::CosF, &[102, 796], 1540);
                step(f, Op::CosF, &[101, 795], 1541);
                step(f, Op::RemapF, &[794, 796, 795, 946, 948, 131, 797], 1542);
                step(f, Op::MulF, &[779, 797, 798], 1543);
                step(f, Op::MulF, &[791, 798, 799], 1544);
                step(f, Op::QuatFromAxisAngle, &[499, 799, 65], 1545);
                step(f, Op::RotateAroundPoint, &[88, 378, 65, 89], 1546);
                step(f, Op::SubF, &[948, 15, 800], 1547);
                step(f, Op::MulF, &[14, 800, 801], 1548);
                step(f, Op::LimitRotationAroundZ, &[58, 801, 104, 66], 1549);
                step(f, Op::RotateAroundPoint, &[89, 363, 66, 90], 1550);
                step(f, Op::BreakTransform, &[90, 383, 67, 384], 1551);
                step(f, Op::ArrayAt(Elem::Float), &[4, 3, 802], 1552);
                step(f, Op::MulF, &[802, 105, 803], 1553);
                step(f, Op::MulF, &[803, 106, 804], 1554);
                step(f, Op::AddF, &[803, 106, 805], 1555);
                step(f, Op::DivF, &[804, 805, 806], 1556);
                step(f, Op::MakeVector, &[946, 946, 806, 385], 1557);
                step(f, Op::AddV, &[383, 385, 386], 1558);
                step(f, Op::MakeTransform, &[386, 67, 384, 91], 1559);
                step(f, Op::ArraySetAt(Elem::Transform), &[7, 3, 91], 1560);
                step(f, Op::JumpIfFalse, &[8, 1565], 1561)
            }
            1561 => {
                step(f, Op::DrawPoint, &[378, 964, 499], 1562);
                step(f, Op::DrawPoint, &[376, 964, 496], 1563);
                step(f, Op::DrawPoint, &[381, 964, 495], 1564);
                step(f, Op::DrawTransform, &[82, 963, 947], 1565);
                1565
            }
            1565 => {
                step(f, Op::Jump, &[633], 1566)
            }
            1566 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1567);
                step(f, Op::Copy(ValueType::Int), &[71, 5], 1568);
                1568
            }
            1568 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 5, 1, 6, 7, 1607], 1569)
            }
            1569 => {
                step(f, Op::GetParent, &[1, 22], 1570);
                step(f, Op::GetParent, &[22, 23], 1571);
                step(f, Op::GetParent, &[23, 24], 1572);
                step(f, Op::GetTransform, &[24, 71, 132, 92], 1573);
                step(f, Op::BreakTransform, &[92, 387, 68, 388], 1574);
                step(f, Op::LengthV, &[1, 808], 1575);
                step(f, Op::ClavicleOffset, &[12, 808, 118, 122, 809], 1576);
                step(f, Op::MakeVector, &[946, 946, 809, 389], 1577);
                step(f, Op::AddV, &[387, 389, 390], 1578);
                step(f, Op::MakeTransform, &[390, 68, 492, 93], 1579);
                step(f, Op::SetTransform, &[24, 93, 71, 131, 948], 1580);
                step(f, Op::GetTransform, &[1, 71, 132, 94], 1581);
                step(f, Op::GetTransform, &[23, 71, 132, 95], 1582);
                step(f, Op::BreakTransform, &[95, 391, 70, 392], 1583);
                step(f, Op::Equals(Elem::Int), &[6, 71, 114], 1584);
                step(f, Op::Select(ValueType::Int), &[114, 72, 71, 62], 1585);
                step(f, Op::ArrayAt(Elem::Float), &[0, 62, 807], 1586);
                step(f, Op::ArmSwingRotation, &[807, 1, 0, 119, 955, 965, 948, 118, 116, 117, 120, 955, 948, 810], 1587);
                step(f, Op::QuatFromAxisAngle, &[499, 810, 69], 1588);
                step(f, Op::RotateAroundPoint, &[94, 391, 69, 96], 1589);
                step(f, Op::BreakTransform, &[96, 393, 71, 394], 1590);
                step(f, Op::RemapF, &[808, 946, 118, 946, 121, 131, 811], 1591);
                step(f, Op::MakeVector, &[946, 946, 811, 395], 1592);
                step(f, Op::AddV, &[393, 395, 396], 1593);
                step(f, Op::MakeTransform, &[396, 71, 492, 97], 1594);
                step(f, Op::Select(ValueType::Vec3), &[114, 500, 499, 398], 1595);
                step(f, Op::Select(ValueType::Vec3), &[114, 496, 501, 399], 1596);
                step(f, Op::ArrayAt(Elem::Vec3), &[4, 6, 397], 1597);
                step(f, Op::TwoBoneIK, &[23, 22, 1, 97, 398, 399, 397, 71, 948, 132, 966, 967, 131, 115, 812], 1598);
                step(f, Op::JumpIfFalse, &[8, 1606], 1599)
            }
            1599 => {
                step(f, Op::GetTransform, &[23, 71, 132, 95], 1600);
                step(f, Op::BreakTransform, &[95, 391, 70, 392], 1601);
                step(f, Op::GetTransform, &[1, 71, 132, 94], 1602);
                step(f, Op::RotateAroundPoint, &[94, 391, 69, 96], 1603);
                step(f, Op::BreakTransform, &[96, 393, 71, 394], 1604);
                step(f, Op::AddV, &[393, 395, 396], 1605);
                step(f, Op::DrawLine, &[391, 396, 947, 496], 1606);
                1606
            }
            1606 => {
                step(f, Op::Jump, &[1568], 1607)
            }
            1607 => {
                step(f, Op::NegF, &[3, 923], 1608);
                step(f, Op::MakeVector, &[946, 946, 923, 474], 1609);
                step(f, Op::MakeTransform, &[474, 99, 492, 118], 1610);
                step(f, Op::SetTransform, &[36, 118, 71, 131, 948], 1611);
                step(f, Op::Copy(ValueType::Float), &[953, 816], 1612);
                step(f, Op::Copy(ValueType::Bool), &[132, 116], 1613);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 11], 1614);
                step(f, Op::Copy(ValueType::Int), &[71, 63], 1615);
                step(f, Op::MakeVector, &[946, 946, 60, 402], 1616);
                1616
            }
            1616 => {
                step(f, Op::ForEachNext(Elem::Transform), &[11, 63, 98, 64, 65, 1628], 1617)
            }
            1617 => {
                step(f, Op::BreakTransform, &[98, 400, 72, 401], 1618);
                step(f, Op::AddV, &[400, 402, 403], 1619);
                step(f, Op::SubV, &[400, 402, 404], 1620);
                step(f, Op::SphereTrace, &[403, 404, 59, 117, 405, 406, 817], 1621);
                step(f, Op::BreakVector, &[405, 818, 819, 820], 1622);
                step(f, Op::LessF, &[820, 816, 118], 1623);
                step(f, Op::And, &[117, 118, 119], 1624);
                step(f, Op::JumpIfFalse, &[119, 1627], 1625)
            }
            1625 => {
                step(f, Op::Copy(ValueType::Float), &[820, 816], 1626);
                step(f, Op::Copy(ValueType::Bool), &[131, 116], 1627);
                1627
            }
            1627 => {
                step(f, Op::Jump, &[1616], 1628)
            }
            1628 => {
                step(f, Op::Select(ValueType::Float), &[116, 816, 946, 821], 1629);
                step(f, Op::ClampF, &[821, 65, 66, 822], 1630);
                step(f, Op::Copy(ValueType::Float), &[822, 815], 1631);
                step(f, Op::SubF, &[948, 23, 814], 1632);
                step(f, Op::MulF, &[815, 814, 823], 1633);
                step(f, Op::SubF, &[948, 142, 824], 1634);
                step(f, Op::MulF, &[3, 824, 825], 1635);
                step(f, Op::AddF, &[823, 825, 826], 1636);
                step(f, Op::MakeVector, &[18, 946, 946, 407], 1637);
                step(f, Op::MakeVector, &[826, 946, 946, 408], 1638);
                step(f, Op::Select(ValueType::Float), &[2, 826, 19, 827], 1639);
                step(f, Op::MakeVector, &[827, 946, 946, 409], 1640);
                step(f, Op::Copy(ValueType::Float), &[53, 828], 1641);
                step(f, Op::Copy(ValueType::Float), &[54, 829], 1642);
                step(f, Op::SubV, &[408, 409, 414], 1643);
                step(f, Op::DeltaTime, &[830], 1644);
                step(f, Op::DivF, &[829, 830, 831], 1645);
                step(f, Op::ScaleV, &[414, 831, 415], 1646);
                step(f, Op::AddV, &[408, 415, 416], 1647);
                step(f, Op::AddV, &[409, 415, 417], 1648);
                step(f, Op::SubV, &[407, 417, 418], 1649);
                step(f, Op::FloatLerp, &[946, 948, 828, 832], 1650);
                step(f, Op::SubF, &[948, 832, 833], 1651);
                step(f, Op::ScaleV, &[418, 833, 419], 1652);
                step(f, Op::AddV, &[416, 419, 421], 1653);
                step(f, Op::MulF, &[828, 830, 834], 1654);
                step(f, Op::GreaterF, &[834, 946, 120], 1655);
                step(f, Op::DivF, &[832, 834, 835], 1656);
                step(f, Op::Select(ValueType::Float), &[120, 835, 948, 836], 1657);
                step(f, Op::ScaleV, &[414, 836, 420], 1658);
                step(f, Op::SubV, &[421, 420, 422], 1659);
                step(f, Op::Copy(ValueType::Vec3), &[422, 413], 1660);
                step(f, Op::BreakVector, &[413, 837, 838, 839], 1661);
                step(f, Op::Select(ValueType::Float), &[1, 826, 837, 840], 1662);
                step(f, Op::Copy(ValueType::Float), &[840, 18], 1663);
                step(f, Op::Copy(ValueType::Float), &[826, 19], 1664);
                step(f, Op::GetTransform, &[37, 71, 131, 103], 1665);
                step(f, Op::BreakTransform, &[103, 435, 79, 436], 1666);
                step(f, Op::PelvisLean, &[1, 125, 130, 131, 858, 859], 1667);
                step(f, Op::LengthV, &[2, 813], 1668);
                step(f, Op::RemapF, &[813, 946, 125, 946, 123, 131, 841], 1669);
                step(f, Op::MulF, &[15, 124, 844], 1670);
                step(f, Op::SubF, &[948, 844, 845], 1671);
                step(f, Op::MulF, &[841, 845, 846], 1672);
                step(f, Op::MulF, &[12, 968, 842], 1673);
                step(f, Op::SinF, &[842, 843], 1674);
                step(f, Op::MulF, &[846, 843, 847], 1675);
                step(f, Op::MulF, &[847, 814, 848], 1676);
                step(f, Op::AddF, &[848, 18, 849], 1677);
                step(f, Op::SubF, &[849, 3, 850], 1678);
                step(f, Op::MakeVector, &[946, 859, 850, 437], 1679);
                step(f, Op::AddV, &[435, 437, 438], 1680);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 71, 99], 1681);
                step(f, Op::BreakTransform, &[99, 423, 73, 424], 1682);
                step(f, Op::BreakVector, &[423, 860, 861, 862], 1683);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 72, 100], 1684);
                step(f, Op::BreakTransform, &[100, 425, 74, 426], 1685);
                step(f, Op::BreakVector, &[425, 863, 864, 865], 1686);
                step(f, Op::SubF, &[862, 865, 866], 1687);
                step(f, Op::PelvisSideLean, &[866, 132, 133, 867], 1688);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 71, 101], 1689);
                step(f, Op::BreakTransform, &[101, 429, 75, 430], 1690);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 72, 102], 1691);
                step(f, Op::BreakTransform, &[102, 431, 76, 432], 1692);
                step(f, Op::SlerpQ, &[75, 76, 947, 77], 1693);
                step(f, Op::EulerFromQuat, &[77, 71, 433], 1694);
                step(f, Op::BreakVector, &[433, 854, 855, 856], 1695);
                step(f, Op::RemapF, &[813, 126, 125, 946, 127, 131, 852], 1696);
                step(f, Op::SubV, &[423, 425, 427], 1697);
                step(f, Op::RotateVector, &[0, 496, 428], 1698);
                step(f, Op::DotV, &[427, 428, 851], 1699);
                step(f, Op::MulF, &[852, 851, 853], 1700);
                step(f, Op::AddF, &[856, 853, 857], 1701);
                step(f, Op::MakeVector, &[858, 867, 857, 434], 1702);
                step(f, Op::QuatFromEuler, &[434, 71, 78], 1703);
                step(f, Op::MakeTransform, &[438, 78, 492, 104], 1704);
                step(f, Op::SetTransform, &[38, 104, 71, 131, 948], 1705);
                step(f, Op::GetTransform, &[39, 72, 131, 105], 1706);
                step(f, Op::BreakTransform, &[105, 439, 83, 440], 1707);
                step(f, Op::QuatFromAxisAngle, &[495, 853, 80], 1708);
                step(f, Op::DivF, &[128, 964, 868], 1709);
                step(f, Op::QuatScale, &[80, 868, 81], 1710);
                step(f, Op::MulQ, &[83, 81, 87], 1711);
                step(f, Op::MakeTransform, &[439, 87, 492, 109], 1712);
                step(f, Op::SetTransform, &[40, 109, 72, 131, 948], 1713);
                step(f, Op::GetTransform, &[41, 72, 131, 106], 1714);
                step(f, Op::BreakTransform, &[106, 441, 84, 442], 1715);
                step(f, Op::MulQ, &[84, 81, 88], 1716);
                step(f, Op::MakeTransform, &[441, 88, 492, 110], 1717);
                step(f, Op::SetTransform, &[42, 110, 72, 131, 948], 1718);
                step(f, Op::GetTransform, &[43, 72, 131, 107], 1719);
                step(f, Op::BreakTransform, &[107, 443, 85, 444], 1720);
                step(f, Op::MulQ, &[85, 81, 89], 1721);
                step(f, Op::MakeTransform, &[443, 89, 492, 111], 1722);
                step(f, Op::SetTransform, &[44, 111, 72, 131, 948], 1723);
                step(f, Op::GetTransform, &[45, 72, 131, 108], 1724);
                step(f, Op::BreakTransform, &[108, 445, 86, 446], 1725);
                step(f, Op::QuatScale, &[80, 129, 82], 1726);
                step(f, Op::MulQ, &[86, 82, 90], 1727);
                step(f, Op::MakeTransform, &[445, 90, 492, 112], 1728);
                step(f, Op::SetTransform, &[46, 112, 72, 131, 948], 1729);
                step(f, Op::Or, &[1, 2, 126], 1730);
                step(f, Op::Copy(ValueType::Float), &[946, 870], 1731);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1732);
                step(f, Op::Copy(ValueType::Int), &[71, 66], 1733);
                1733
            }
            1733 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 66, 25, 67, 68, 1780], 1734)
            }
            1734 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 67, 121], 1735);
                step(f, Op::GetParent, &[25, 26], 1736);
                step(f, Op::GetParent, &[26, 27], 1737);
                step(f, Op::GetTransform, &[27, 71, 132, 113], 1738);
                step(f, Op::BreakTransform, &[113, 447, 91, 448], 1739);
                step(f, Op::BreakVector, &[447, 871, 872, 873], 1740);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 67, 114], 1741);
                step(f, Op::BreakTransform, &[114, 449, 92, 450], 1742);
                step(f, Op::BreakVector, &[449, 874, 875, 876], 1743);
                step(f, Op::ArrayAt(Elem::Float), &[1, 67, 880], 1744);
                step(f, Op::MulF, &[880, 134, 881], 1745);
                step(f, Op::MulF, &[881, 881, 882], 1746);
                step(f, Op::SubF, &[871, 874, 877], 1747);
                step(f, Op::SubF, &[872, 875, 878], 1748);
                step(f, Op::MakeVector, &[877, 878, 946, 451], 1749);
                step(f, Op::DotV, &[451, 451, 879], 1750);
                step(f, Op::SubF, &[882, 879, 883], 1751);
                step(f, Op::SqrtF, &[883, 884], 1752);
                step(f, Op::AddF, &[876, 884, 885], 1753);
                step(f, Op::SubF, &[873, 885, 886], 1754);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 67, 115], 1755);
                step(f, Op::BreakTransform, &[115, 452, 93, 453], 1756);
                step(f, Op::BreakVector, &[452, 887, 888, 889], 1757);
                step(f, Op::AddF, &[889, 55, 890], 1758);
                step(f, Op::MinF, &[876, 890, 891], 1759);
                step(f, Op::AddF, &[891, 884, 892], 1760);
                step(f, Op::SubF, &[873, 892, 893], 1761);
                step(f, Op::Equals(Elem::Int), &[67, 71, 122], 1762);
                step(f, Op::Select(ValueType::Int), &[122, 72, 71, 69], 1763);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 69, 123], 1764);
                step(f, Op::ArrayAt(Elem::Float), &[2, 69, 897], 1765);
                step(f, Op::RemapF, &[897, 947, 948, 946, 948, 131, 898], 1766);
                step(f, Op::RemapF, &[897, 946, 137, 948, 946, 131, 899], 1767);
                step(f, Op::MaxF, &[898, 899, 900], 1768);
                step(f, Op::Select(ValueType::Float), &[123, 948, 900, 901], 1769);
                step(f, Op::LerpF, &[886, 893, 901, 902], 1770);
                step(f, Op::ArrayAt(Elem::Float), &[2, 67, 894], 1771);
                step(f, Op::RemapF, &[894, 947, 948, 946, 948, 131, 895], 1772);
                step(f, Op::MulF, &[902, 895, 903], 1773);
                step(f, Op::RemapF, &[894, 946, 137, 948, 946, 131, 896], 1774);
                step(f, Op::MulF, &[886, 896, 904], 1775);
                step(f, Op::MaxF, &[903, 904, 905], 1776);
                step(f, Op::Select(ValueType::Float), &[121, 886, 905, 906], 1777);
                step(f, Op::MaxF, &[870, 906, 907], 1778);
                step(f, Op::Copy(ValueType::Float), &[907, 870], 1779);
                step(f, Op::Jump, &[1733], 1780)
            }
            1780 => {
                step(f, Op::ClampF, &[870, 946, 135, 908], 1781);
                step(f, Op::Copy(ValueType::Float), &[908, 869], 1782);
                step(f, Op::MakeVector, &[20, 946, 946, 454], 1783);
                step(f, Op::MakeVector, &[869, 946, 946, 455], 1784);
                step(f, Op::MakeVector, &[21, 946, 946, 456], 1785);
                step(f, Op::GreaterF, &[869, 20, 124], 1786);
                step(f, Op::Select(ValueType::Float), &[124, 139, 136, 909], 1787);
                step(f, Op::Copy(ValueType::Float), &[54, 911], 1788);
                step(f, Op::SubV, &[455, 456, 461], 1789);
                step(f, Op::DeltaTime, &[912], 1790);
                step(f, Op::DivF, &[911, 912, 913], 1791);
                step(f, Op::ScaleV, &[461, 913, 462], 1792);
                step(f, Op::AddV, &[455, 462, 463], 1793);
                step(f, Op::AddV, &[456, 462, 464], 1794);
                step(f, Op::SubV, &[454, 464, 465], 1795);
                step(f, Op::FloatLerp, &[946, 948, 909, 914], 1796);
                step(f, Op::SubF, &[948, 914, 915], 1797);
                step(f, Op::ScaleV, &[465, 915, 466], 1798);
                step(f, Op::AddV, &[463, 466, 468], 1799);
                step(f, Op::MulF, &[909, 912, 916], 1800);
                step(f, Op::GreaterF, &[916, 946, 125], 1801);
                step(f, Op::DivF, &[914, 916, 917], 1802);
                step(f, Op::Select(ValueType::Float), &[125, 917, 948, 918], 1803);
                step(f, Op::ScaleV, &[461, 918, 467], 1804);
                step(f, Op::SubV, &[468, 467, 469], 1805);
                step(f, Op::Copy(ValueType::Vec3), &[469, 460], 1806);
                step(f, Op::BreakVector, &[460, 919, 920, 921], 1807);
                step(f, Op::Select(ValueType::Float), &[126, 869, 919, 922], 1808);
                step(f, Op::Copy(ValueType::Float), &[922, 20], 1809);
                step(f, Op::Copy(ValueType::Float), &[869, 21], 1810);
                step(f, Op::GetTransform, &[47, 71, 132, 116], 1811);
                step(f, Op::BreakTransform, &[116, 470, 94, 471], 1812);
                step(f, Op::MakeVector, &[946, 946, 20, 472], 1813);
                step(f, Op::SubV, &[470, 472, 473], 1814);
                step(f, Op::MakeTransform, &[473, 94, 492, 117], 1815);
                step(f, Op::SetTransform, &[48, 117, 71, 131, 948], 1816);
                step(f, Op::JumpIfFalse, &[8, 1822], 1817)
            }
            1817 => {
                step(f, Op::GetTransform, &[47, 71, 132, 116], 1818);
                step(f, Op::BreakTransform, &[116, 470, 94, 471], 1819);
                step(f, Op::SubV, &[470, 472, 473], 1820);
                step(f, Op::MakeTransform, &[473, 94, 492, 117], 1821);
                step(f, Op::DrawTransform, &[117, 969, 947], 1822);
                1822
            }
            1822 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1823);
                step(f, Op::Copy(ValueType::Int), &[71, 8], 1824);
                1824
            }
            1824 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 8, 2, 9, 10, 1873], 1825)
            }
            1825 => {
                step(f, Op::GetParent, &[2, 29], 1826);
                step(f, Op::GetParent, &[29, 30], 1827);
                step(f, Op::GetTransform, &[30, 71, 132, 119], 1828);
                step(f, Op::BreakTransform, &[119, 475, 95, 476], 1829);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 9, 120], 1830);
                step(f, Op::BreakTransform, &[120, 477, 96, 478], 1831);
                step(f, Op::SubV, &[477, 475, 479], 1832);
                step(f, Op::LengthV, &[479, 936], 1833);
                step(f, Op::ArrayAt(Elem::Float), &[1, 9, 924], 1834);
                step(f, Op::MulF, &[924, 146, 925], 1835);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 9, 127], 1836);
                step(f, Op::MulF, &[16, 113, 934], 1837);
                step(f, Op::ArrayAt(Elem::Float), &[2, 9, 926], 1838);
                step(f, Op::ClampF, &[926, 946, 948, 927], 1839);
                step(f, Op::LessF, &[927, 947, 128], 1840);
                step(f, Op::SmoothStepF, &[927, 148, 149, 930], 1841);
                step(f, Op::MulF, &[927, 956, 928], 1842);
                step(f, Op::SinF, &[928, 929], 1843);
                step(f, Op::MaxF, &[930, 929, 931], 1844);
                step(f, Op::Select(ValueType::Float), &[128, 931, 929, 932], 1845);
                step(f, Op::MulF, &[932, 147, 933], 1846);
                step(f, Op::Select(ValueType::Float), &[127, 934, 933, 935], 1847);
                step(f, Op::SubF, &[925, 935, 937], 1848);
                step(f, Op::SubF, &[936, 937, 938], 1849);
                step(f, Op::MaxF, &[938, 946, 939], 1850);
                step(f, Op::MulF, &[939, 939, 940], 1851);
                step(f, Op::AddF, &[939, 935, 941], 1852);
                step(f, Op::DivF, &[940, 941, 942], 1853);
                step(f, Op::SubF, &[936, 942, 943], 1854);
                step(f, Op::DivF, &[943, 936, 944], 1855);
                step(f, Op::ScaleV, &[479, 944, 480], 1856);
                step(f, Op::AddV, &[475, 480, 481], 1857);
                step(f, Op::ClampSpatially, &[481, 475, 946, 925, 482], 1858);
                step(f, Op::MakeTransform, &[482, 96, 492, 121], 1859);
                step(f, Op::Equals(Elem::Int), &[9, 71, 129], 1860);
                step(f, Op::Select(ValueType::Vec3), &[129, 500, 499, 487], 1861);
                step(f, Op::Select(ValueType::Vec3), &[129, 496, 501, 488], 1862);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 9, 122], 1863);
                step(f, Op::BreakTransform, &[122, 483, 97, 484], 1864);
                step(f, Op::ArrayAt(Elem::Vec3), &[3, 9, 485], 1865);
                step(f, Op::KneeVector, &[97, 0, 485, 150, 151, 486], 1866);
                step(f, Op::TwoBoneIK, &[30, 29, 2, 121, 487, 488, 486, 71, 948, 132, 966, 967, 131, 130, 945], 1867);
                step(f, Op::JumpIfFalse, &[8, 1872], 1868)
            }
            1868 => {
                step(f, Op::GetTransform, &[29, 71, 132, 123], 1869);
                step(f, Op::BreakTransform, &[123, 489, 98, 490], 1870);
                step(f, Op::AddV, &[489, 486, 491], 1871);
                step(f, Op::DrawLine, &[489, 491, 947, 502], 1872);
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
