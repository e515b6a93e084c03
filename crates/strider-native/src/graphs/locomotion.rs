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
    fingerprint: 0xf915278dae45b098,
    forward,
};

fn forward(f: &mut Frame<'_>) {
    let mut pc: usize = 113;
    loop {
        // SAFETY: each `step` is an instruction of the program this code was generated
        // from, with its own operands; `NATIVE` runs only on that program (fingerprint).
        pc = unsafe { match pc {
            113 => {
                step(f, Op::Not, &[0, 9], 114);
                step(f, Op::Copy(ValueType::Bool), &[9, 1], 115);
                step(f, Op::WorldTransform, &[12], 116);
                step(f, Op::BreakTransform, &[12, 33, 7, 34], 117);
                step(f, Op::Select(ValueType::Transform), &[0, 0, 12, 13], 118);
                step(f, Op::BreakTransform, &[13, 35, 8, 36], 119);
                step(f, Op::SubV, &[33, 35, 37], 120);
                step(f, Op::LengthV, &[37, 142], 121);
                step(f, Op::GreaterF, &[142, 35, 10], 122);
                step(f, Op::Copy(ValueType::Bool), &[10, 2], 123);
                step(f, Op::MakeRelative, &[13, 12, 17], 124);
                step(f, Op::Select(ValueType::Transform), &[10, 115, 17, 18], 125);
                step(f, Op::Copy(ValueType::Transform), &[18, 2], 126);
                step(f, Op::InverseT, &[13, 15], 127);
                step(f, Op::MulT, &[12, 15, 16], 128);
                step(f, Op::Copy(ValueType::Transform), &[16, 1], 129);
                step(f, Op::TransformVector, &[2, 0, 42], 130);
                step(f, Op::InverseT, &[12, 14], 131);
                step(f, Op::DeltaTime, &[141], 132);
                step(f, Op::DivF, &[847, 141, 143], 133);
                step(f, Op::ScaleV, &[37, 143, 38], 134);
                step(f, Op::TransformVector, &[14, 38, 39], 135);
                step(f, Op::BreakVector, &[39, 144, 145, 146], 136);
                step(f, Op::MakeVector, &[144, 145, 845, 40], 137);
                step(f, Op::LengthV, &[40, 147], 138);
                step(f, Op::MulF, &[147, 123, 148], 139);
                step(f, Op::NegF, &[148, 149], 140);
                step(f, Op::ClampF, &[146, 149, 148, 150], 141);
                step(f, Op::MakeVector, &[144, 145, 150, 41], 142);
                step(f, Op::Select(ValueType::Vec3), &[2, 42, 41, 44], 143);
                step(f, Op::VectorLerp, &[42, 44, 36, 845, 45], 144);
                step(f, Op::Copy(ValueType::Vec3), &[45, 0], 145);
                step(f, Op::TransformVector, &[2, 1, 43], 146);
                step(f, Op::TransformVector, &[2, 0, 42], 147);
                step(f, Op::Select(ValueType::Vec3), &[2, 42, 41, 44], 148);
                step(f, Op::VectorLerp, &[43, 44, 37, 845, 46], 149);
                step(f, Op::Copy(ValueType::Vec3), &[46, 1], 150);
                step(f, Op::LengthV, &[44, 157], 151);
                step(f, Op::Copy(ValueType::Float), &[157, 0], 152);
                step(f, Op::BreakVector, &[37, 151, 152, 153], 153);
                step(f, Op::MulF, &[150, 141, 154], 154);
                step(f, Op::SubF, &[153, 154, 155], 155);
                step(f, Op::Select(ValueType::Float), &[10, 845, 155, 156], 156);
                step(f, Op::Copy(ValueType::Float), &[156, 1], 157);
                step(f, Op::JumpIfFalse, &[2, 172], 158)
            }
            158 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 12], 159);
                step(f, Op::Copy(ValueType::Int), &[71, 17], 160);
                160
            }
            160 => {
                step(f, Op::ForEachNext(Elem::Bone), &[12, 17, 13, 18, 19, 170], 161)
            }
            161 => {
                step(f, Op::ArrayAt(Elem::Transform), &[8, 18, 20], 162);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 18, 20], 163);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 18, 20], 164);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 18, 20], 165);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 18, 20], 166);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 18, 20], 167);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 18, 20], 168);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 18, 20], 169);
                step(f, Op::Jump, &[160], 170)
            }
            170 => {
                step(f, Op::Copy(ValueType::Float), &[845, 16], 171);
                step(f, Op::Jump, &[172], 172)
            }
            172 => {
                step(f, Op::Copy(ValueType::Transform), &[12, 0], 173);
                step(f, Op::Copy(ValueType::Bool), &[122, 0], 174);
                step(f, Op::JumpIfFalse, &[8, 181], 175)
            }
            175 => {
                step(f, Op::GetTransform, &[34, 71, 122, 19], 176);
                step(f, Op::BreakTransform, &[19, 47, 9, 48], 177);
                step(f, Op::ScaleV, &[0, 848, 49], 178);
                step(f, Op::AddV, &[47, 49, 50], 179);
                step(f, Op::DrawArrow, &[47, 50, 846, 467], 180);
                step(f, Op::Jump, &[181], 181)
            }
            181 => {
                step(f, Op::Copy(ValueType::Float), &[845, 158], 182);
                step(f, Op::Copy(ValueType::Float), &[847, 159], 183);
                step(f, Op::Copy(ValueType::Float), &[847, 160], 184);
                step(f, Op::Copy(ValueType::Bool), &[123, 11], 185);
                step(f, Op::Copy(ValueType::Bool), &[123, 12], 186);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[8, 9], 187);
                step(f, Op::Copy(ValueType::Int), &[71, 25], 188);
                step(f, Op::MakeVector, &[845, 845, 55, 55], 189);
                189
            }
            189 => {
                step(f, Op::ForEachNext(Elem::Transform), &[9, 25, 21, 26, 27, 200], 190)
            }
            190 => {
                step(f, Op::BreakTransform, &[21, 51, 10, 52], 191);
                step(f, Op::TransformPoint, &[2, 51, 53], 192);
                step(f, Op::LerpV, &[53, 51, 160, 54], 193);
                step(f, Op::AddV, &[54, 55, 56], 194);
                step(f, Op::SubV, &[54, 55, 57], 195);
                step(f, Op::LineTrace, &[56, 57, 13, 58, 59, 161], 196);
                step(f, Op::JumpIfFalse, &[13, 199], 197)
            }
            197 => {
                step(f, Op::Copy(ValueType::Bool), &[122, 12], 198);
                step(f, Op::Jump, &[199], 199)
            }
            199 => {
                step(f, Op::Jump, &[189], 200)
            }
            200 => {
                step(f, Op::Copy(ValueType::Bool), &[12, 11], 201);
                step(f, Op::Jump, &[202], 202)
            }
            202 => {
                step(f, Op::Or, &[11, 7, 14], 203);
                step(f, Op::NotEquals(Elem::Bool), &[14, 5, 15], 204);
                step(f, Op::JumpIfFalse, &[15, 239], 205)
            }
            205 => {
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 206);
                step(f, Op::JumpIfFalse, &[16, 238], 207)
            }
            207 => {
                step(f, Op::Copy(ValueType::Int), &[1, 24], 208);
                step(f, Op::Copy(ValueType::Int), &[71, 20], 209);
                209
            }
            209 => {
                step(f, Op::ForNext, &[20, 24, 22, 237], 210)
            }
            210 => {
                step(f, Op::AddF, &[158, 159, 162], 211);
                step(f, Op::MulF, &[162, 846, 163], 212);
                step(f, Op::Copy(ValueType::Float), &[163, 164], 213);
                step(f, Op::Copy(ValueType::Bool), &[123, 17], 214);
                step(f, Op::Copy(ValueType::Bool), &[123, 18], 215);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[8, 10], 216);
                step(f, Op::Copy(ValueType::Int), &[71, 28], 217);
                step(f, Op::MakeVector, &[845, 845, 55, 64], 218);
                218
            }
            218 => {
                step(f, Op::ForEachNext(Elem::Transform), &[10, 28, 22, 29, 30, 229], 219)
            }
            219 => {
                step(f, Op::BreakTransform, &[22, 60, 11, 61], 220);
                step(f, Op::TransformPoint, &[2, 60, 62], 221);
                step(f, Op::LerpV, &[62, 60, 164, 63], 222);
                step(f, Op::AddV, &[63, 64, 65], 223);
                step(f, Op::SubV, &[63, 64, 66], 224);
                step(f, Op::LineTrace, &[65, 66, 19, 67, 68, 165], 225);
                step(f, Op::JumpIfFalse, &[19, 228], 226)
            }
            226 => {
                step(f, Op::Copy(ValueType::Bool), &[122, 18], 227);
                step(f, Op::Jump, &[228], 228)
            }
            228 => {
                step(f, Op::Jump, &[218], 229)
            }
            229 => {
                step(f, Op::Copy(ValueType::Bool), &[18, 17], 230);
                step(f, Op::Jump, &[231], 231)
            }
            231 => {
                step(f, Op::Equals(Elem::Bool), &[17, 6, 20], 232);
                step(f, Op::JumpIfFalse, &[20, 235], 233)
            }
            233 => {
                step(f, Op::Copy(ValueType::Float), &[163, 158], 234);
                step(f, Op::Jump, &[236], 235)
            }
            235 => {
                step(f, Op::Copy(ValueType::Float), &[163, 159], 236);
                236
            }
            236 => {
                step(f, Op::Jump, &[209], 237)
            }
            237 => {
                step(f, Op::Jump, &[238], 238)
            }
            238 => {
                step(f, Op::Jump, &[239], 239)
            }
            239 => {
                step(f, Op::Select(ValueType::Float), &[5, 849, 847, 171], 240);
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 241);
                step(f, Op::AddF, &[158, 159, 162], 242);
                step(f, Op::MulF, &[162, 846, 166], 243);
                step(f, Op::Select(ValueType::Float), &[16, 166, 846, 167], 244);
                step(f, Op::Select(ValueType::Float), &[15, 167, 845, 173], 245);
                step(f, Op::MulF, &[171, 173, 175], 246);
                step(f, Op::DeltaTime, &[169], 247);
                step(f, Op::DivF, &[169, 127, 170], 248);
                step(f, Op::MulF, &[175, 170, 176], 249);
                step(f, Op::AddF, &[20, 176, 177], 250);
                step(f, Op::ClampF, &[177, 845, 847, 178], 251);
                step(f, Op::Select(ValueType::Float), &[14, 849, 847, 172], 252);
                step(f, Op::SubF, &[847, 167, 168], 253);
                step(f, Op::Select(ValueType::Float), &[15, 168, 847, 174], 254);
                step(f, Op::MulF, &[172, 174, 179], 255);
                step(f, Op::MulF, &[179, 170, 180], 256);
                step(f, Op::AddF, &[178, 180, 181], 257);
                step(f, Op::ClampF, &[181, 845, 847, 182], 258);
                step(f, Op::SmoothStepF, &[182, 845, 847, 183], 259);
                step(f, Op::AddF, &[21, 183, 184], 260);
                step(f, Op::MulF, &[184, 846, 185], 261);
                step(f, Op::SubF, &[847, 185, 186], 262);
                step(f, Op::MulF, &[186, 186, 187], 263);
                step(f, Op::SubF, &[847, 187, 188], 264);
                step(f, Op::Copy(ValueType::Float), &[188, 22], 265);
                step(f, Op::Copy(ValueType::Float), &[183, 21], 266);
                step(f, Op::Copy(ValueType::Float), &[182, 20], 267);
                step(f, Op::GreaterF, &[21, 845, 21], 268);
                step(f, Op::TransformVector, &[2, 3, 69], 269);
                step(f, Op::Select(ValueType::Vec3), &[21, 69, 0, 70], 270);
                step(f, Op::Copy(ValueType::Vec3), &[70, 3], 271);
                step(f, Op::LerpV, &[0, 3, 21, 71], 272);
                step(f, Op::Select(ValueType::Vec3), &[21, 71, 0, 72], 273);
                step(f, Op::Copy(ValueType::Vec3), &[72, 2], 274);
                step(f, Op::Copy(ValueType::Bool), &[14, 5], 275);
                step(f, Op::Copy(ValueType::Bool), &[11, 6], 276);
                step(f, Op::Copy(ValueType::Bool), &[123, 7], 277);
                step(f, Op::SubF, &[847, 22, 189], 278);
                step(f, Op::MulF, &[1, 189, 190], 279);
                step(f, Op::AddF, &[2, 190, 191], 280);
                step(f, Op::Copy(ValueType::Float), &[4, 192], 281);
                step(f, Op::Copy(ValueType::Float), &[5, 193], 282);
                step(f, Op::Copy(ValueType::Float), &[191, 194], 283);
                step(f, Op::Copy(ValueType::Float), &[2, 195], 284);
                step(f, Op::Copy(ValueType::Float), &[124, 196], 285);
                step(f, Op::Copy(ValueType::Float), &[49, 197], 286);
                step(f, Op::Copy(ValueType::Float), &[845, 198], 287);
                step(f, Op::Copy(ValueType::Float), &[845, 199], 288);
                step(f, Op::SubF, &[194, 195, 202], 289);
                step(f, Op::DeltaTime, &[200], 290);
                step(f, Op::DivF, &[202, 200, 203], 291);
                step(f, Op::MulF, &[203, 197, 204], 292);
                step(f, Op::AddF, &[194, 204, 206], 293);
                step(f, Op::MulF, &[203, 850, 207], 294);
                step(f, Op::DivF, &[851, 196, 201], 295);
                step(f, Op::DivF, &[207, 201, 208], 296);
                step(f, Op::SubF, &[206, 208, 222], 297);
                step(f, Op::AddF, &[195, 204, 205], 298);
                step(f, Op::SubF, &[192, 205, 209], 299);
                step(f, Op::AddF, &[209, 208, 210], 300);
                step(f, Op::SubF, &[193, 203, 211], 301);
                step(f, Op::MulF, &[201, 210, 212], 302);
                step(f, Op::AddF, &[211, 212, 213], 303);
                step(f, Op::MulF, &[213, 200, 216], 304);
                step(f, Op::AddF, &[210, 216, 217], 305);
                step(f, Op::FloatLerp, &[845, 847, 201, 214], 306);
                step(f, Op::SubF, &[847, 214, 215], 307);
                step(f, Op::MulF, &[217, 215, 218], 308);
                step(f, Op::AddF, &[222, 218, 223], 309);
                step(f, Op::Copy(ValueType::Float), &[223, 198], 310);
                step(f, Op::MulF, &[201, 216, 219], 311);
                step(f, Op::SubF, &[211, 219, 220], 312);
                step(f, Op::MulF, &[220, 215, 221], 313);
                step(f, Op::AddF, &[203, 221, 224], 314);
                step(f, Op::Copy(ValueType::Float), &[224, 199], 315);
                step(f, Op::Jump, &[316], 316)
            }
            316 => {
                step(f, Op::SubF, &[191, 198, 225], 317);
                step(f, Op::Copy(ValueType::Float), &[225, 3], 318);
                step(f, Op::Copy(ValueType::Float), &[198, 4], 319);
                step(f, Op::Copy(ValueType::Float), &[4, 192], 320);
                step(f, Op::Copy(ValueType::Float), &[5, 193], 321);
                step(f, Op::Copy(ValueType::Float), &[191, 194], 322);
                step(f, Op::Copy(ValueType::Float), &[2, 195], 323);
                step(f, Op::Copy(ValueType::Float), &[124, 196], 324);
                step(f, Op::Copy(ValueType::Float), &[49, 197], 325);
                step(f, Op::Copy(ValueType::Float), &[845, 198], 326);
                step(f, Op::Copy(ValueType::Float), &[845, 199], 327);
                step(f, Op::SubF, &[194, 195, 202], 328);
                step(f, Op::DeltaTime, &[200], 329);
                step(f, Op::DivF, &[202, 200, 203], 330);
                step(f, Op::MulF, &[203, 197, 204], 331);
                step(f, Op::AddF, &[194, 204, 206], 332);
                step(f, Op::MulF, &[203, 850, 207], 333);
                step(f, Op::DivF, &[851, 196, 201], 334);
                step(f, Op::DivF, &[207, 201, 208], 335);
                step(f, Op::SubF, &[206, 208, 222], 336);
                step(f, Op::AddF, &[195, 204, 205], 337);
                step(f, Op::SubF, &[192, 205, 209], 338);
                step(f, Op::AddF, &[209, 208, 210], 339);
                step(f, Op::SubF, &[193, 203, 211], 340);
                step(f, Op::MulF, &[201, 210, 212], 341);
                step(f, Op::AddF, &[211, 212, 213], 342);
                step(f, Op::MulF, &[213, 200, 216], 343);
                step(f, Op::AddF, &[210, 216, 217], 344);
                step(f, Op::FloatLerp, &[845, 847, 201, 214], 345);
                step(f, Op::SubF, &[847, 214, 215], 346);
                step(f, Op::MulF, &[217, 215, 218], 347);
                step(f, Op::AddF, &[222, 218, 223], 348);
                step(f, Op::Copy(ValueType::Float), &[223, 198], 349);
                step(f, Op::MulF, &[201, 216, 219], 350);
                step(f, Op::SubF, &[211, 219, 220], 351);
                step(f, Op::MulF, &[220, 215, 221], 352);
                step(f, Op::AddF, &[203, 221, 224], 353);
                step(f, Op::Copy(ValueType::Float), &[224, 199], 354);
                step(f, Op::Jump, &[355], 355)
            }
            355 => {
                step(f, Op::Copy(ValueType::Float), &[199, 5], 356);
                step(f, Op::Copy(ValueType::Float), &[191, 2], 357);
                step(f, Op::LengthV, &[4, 227], 358);
                step(f, Op::GreaterF, &[227, 29, 22], 359);
                step(f, Op::LengthV, &[2, 228], 360);
                step(f, Op::GreaterF, &[228, 29, 23], 361);
                step(f, Op::And, &[22, 23, 25], 362);
                step(f, Op::Select(ValueType::Vec3), &[22, 4, 465, 73], 363);
                step(f, Op::MovementAngleOffset, &[73, 14, 845, 852, 852, 853, 40, 854, 229], 364);
                step(f, Op::Copy(ValueType::Float), &[229, 231], 365);
                step(f, Op::Copy(ValueType::Float), &[14, 232], 366);
                step(f, Op::Copy(ValueType::Float), &[845, 233], 367);
                step(f, Op::SubF, &[231, 232, 234], 368);
                step(f, Op::AddF, &[234, 855, 235], 369);
                step(f, Op::DivF, &[235, 856, 236], 370);
                step(f, Op::FractF, &[236, 237], 371);
                step(f, Op::MulF, &[237, 856, 238], 372);
                step(f, Op::SubF, &[238, 855, 239], 373);
                step(f, Op::Copy(ValueType::Float), &[239, 233], 374);
                step(f, Op::Jump, &[375], 375)
            }
            375 => {
                step(f, Op::AbsF, &[233, 258], 376);
                step(f, Op::Select(ValueType::Vec3), &[23, 2, 465, 74], 377);
                step(f, Op::MovementAngleOffset, &[74, 14, 845, 852, 852, 853, 40, 854, 230], 378);
                step(f, Op::Copy(ValueType::Float), &[230, 240], 379);
                step(f, Op::Copy(ValueType::Float), &[14, 241], 380);
                step(f, Op::Copy(ValueType::Float), &[845, 242], 381);
                step(f, Op::SubF, &[240, 241, 243], 382);
                step(f, Op::AddF, &[243, 855, 244], 383);
                step(f, Op::DivF, &[244, 856, 245], 384);
                step(f, Op::FractF, &[245, 246], 385);
                step(f, Op::MulF, &[246, 856, 247], 386);
                step(f, Op::SubF, &[247, 855, 248], 387);
                step(f, Op::Copy(ValueType::Float), &[248, 242], 388);
                step(f, Op::Jump, &[389], 389)
            }
            389 => {
                step(f, Op::AbsF, &[242, 259], 390);
                step(f, Op::MaxF, &[258, 259, 261], 391);
                step(f, Op::Copy(ValueType::Float), &[230, 249], 392);
                step(f, Op::Copy(ValueType::Float), &[229, 250], 393);
                step(f, Op::Copy(ValueType::Float), &[845, 251], 394);
                step(f, Op::SubF, &[249, 250, 252], 395);
                step(f, Op::AddF, &[252, 855, 253], 396);
                step(f, Op::DivF, &[253, 856, 254], 397);
                step(f, Op::FractF, &[254, 255], 398);
                step(f, Op::MulF, &[255, 856, 256], 399);
                step(f, Op::SubF, &[256, 855, 257], 400);
                step(f, Op::Copy(ValueType::Float), &[257, 251], 401);
                step(f, Op::Jump, &[402], 402)
            }
            402 => {
                step(f, Op::AbsF, &[251, 260], 403);
                step(f, Op::MaxF, &[261, 260, 262], 404);
                step(f, Op::LessF, &[262, 857, 24], 405);
                step(f, Op::And, &[25, 24, 26], 406);
                step(f, Op::Not, &[22, 27], 407);
                step(f, Op::Not, &[23, 28], 408);
                step(f, Op::And, &[27, 28, 29], 409);
                step(f, Op::Or, &[26, 29, 30], 410);
                step(f, Op::JumpIfFalse, &[30, 432], 411)
            }
            411 => {
                step(f, Op::DeltaTime, &[226], 412);
                step(f, Op::MulF, &[38, 226, 266], 413);
                step(f, Op::GreaterF, &[266, 845, 31], 414);
                step(f, Op::DivF, &[49, 226, 263], 415);
                step(f, Op::FloatLerp, &[845, 847, 38, 264], 416);
                step(f, Op::SubF, &[847, 264, 265], 417);
                step(f, Op::DivF, &[265, 264, 267], 418);
                step(f, Op::DivF, &[847, 266, 268], 419);
                step(f, Op::SubF, &[267, 268, 269], 420);
                step(f, Op::AddF, &[263, 269, 270], 421);
                step(f, Op::Select(ValueType::Float), &[31, 270, 845, 271], 422);
                step(f, Op::MulF, &[251, 271, 272], 423);
                step(f, Op::AddF, &[230, 272, 273], 424);
                step(f, Op::SinF, &[273, 274], 425);
                step(f, Op::NegF, &[274, 275], 426);
                step(f, Op::CosF, &[273, 276], 427);
                step(f, Op::MakeVector, &[275, 276, 845, 75], 428);
                step(f, Op::Select(ValueType::Vec3), &[23, 75, 465, 76], 429);
                step(f, Op::MovementAngleOffset, &[76, 14, 845, 38, 39, 853, 855, 854, 277], 430);
                step(f, Op::Copy(ValueType::Float), &[277, 14], 431);
                step(f, Op::Jump, &[467], 432)
            }
            432 => {
                step(f, Op::DeltaTime, &[226], 433);
                step(f, Op::DivF, &[226, 41, 278], 434);
                step(f, Op::AddF, &[278, 846, 279], 435);
                step(f, Op::FloorF, &[279, 280], 436);
                step(f, Op::MaxF, &[280, 847, 281], 437);
                step(f, Op::ToInt, &[281, 36], 438);
                step(f, Op::Copy(ValueType::Int), &[36, 35], 439);
                step(f, Op::Copy(ValueType::Int), &[71, 31], 440);
                step(f, Op::MulF, &[41, 846, 285], 441);
                step(f, Op::SubF, &[49, 285, 286], 442);
                step(f, Op::DivF, &[286, 226, 287], 443);
                step(f, Op::FloatLerp, &[845, 847, 36, 289], 444);
                step(f, Op::GreaterF, &[289, 845, 32], 445);
                step(f, Op::DivF, &[38, 281, 299], 446);
                step(f, Op::DivF, &[39, 281, 300], 447);
                447
            }
            447 => {
                step(f, Op::ForNext, &[31, 35, 33, 467], 448)
            }
            448 => {
                step(f, Op::ToFloat, &[33, 282], 449);
                step(f, Op::AddF, &[282, 847, 283], 450);
                step(f, Op::DivF, &[283, 281, 284], 451);
                step(f, Op::AddF, &[284, 287, 288], 452);
                step(f, Op::MulF, &[36, 288, 290], 453);
                step(f, Op::FloatLerp, &[845, 847, 290, 291], 454);
                step(f, Op::DivF, &[291, 289, 292], 455);
                step(f, Op::Select(ValueType::Float), &[32, 292, 288, 293], 456);
                step(f, Op::LerpV, &[4, 2, 293, 77], 457);
                step(f, Op::LengthV, &[77, 294], 458);
                step(f, Op::GreaterF, &[294, 29, 33], 459);
                step(f, Op::Select(ValueType::Vec3), &[33, 77, 465, 78], 460);
                step(f, Op::MulF, &[226, 288, 295], 461);
                step(f, Op::MulF, &[8, 295, 296], 462);
                step(f, Op::AddF, &[12, 296, 297], 463);
                step(f, Op::FractF, &[297, 298], 464);
                step(f, Op::MovementAngleOffset, &[78, 14, 298, 299, 300, 853, 40, 854, 301], 465);
                step(f, Op::Copy(ValueType::Float), &[301, 14], 466);
                step(f, Op::Jump, &[447], 467)
            }
            467 => {
                step(f, Op::QuatFromAxisAngle, &[468, 14, 12], 468);
                step(f, Op::Copy(ValueType::Quat), &[12, 0], 469);
                step(f, Op::SinF, &[14, 302], 470);
                step(f, Op::AbsF, &[302, 303], 471);
                step(f, Op::RemapF, &[303, 42, 43, 845, 847, 122, 304], 472);
                step(f, Op::Copy(ValueType::Float), &[304, 15], 473);
                step(f, Op::Copy(ValueType::Vec3), &[2, 4], 474);
                step(f, Op::Copy(ValueType::Bool), &[123, 35], 475);
                step(f, Op::Copy(ValueType::Bool), &[122, 36], 476);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 2], 477);
                step(f, Op::Copy(ValueType::Int), &[71, 40], 478);
                478
            }
            478 => {
                step(f, Op::ForEachNext(Elem::Bool), &[2, 40, 37, 41, 42, 484], 479)
            }
            479 => {
                step(f, Op::Not, &[37, 38], 480);
                step(f, Op::JumpIfFalse, &[38, 483], 481)
            }
            481 => {
                step(f, Op::Copy(ValueType::Bool), &[123, 36], 482);
                step(f, Op::Jump, &[483], 483)
            }
            483 => {
                step(f, Op::Jump, &[478], 484)
            }
            484 => {
                step(f, Op::Copy(ValueType::Bool), &[36, 35], 485);
                step(f, Op::Jump, &[486], 486)
            }
            486 => {
                step(f, Op::Copy(ValueType::Bool), &[123, 39], 487);
                step(f, Op::Copy(ValueType::Bool), &[122, 40], 488);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 489);
                step(f, Op::Copy(ValueType::Int), &[71, 43], 490);
                490
            }
            490 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 43, 15, 44, 45, 505], 491)
            }
            491 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 44, 23], 492);
                step(f, Op::BreakTransform, &[23, 79, 13, 80], 493);
                step(f, Op::BreakVector, &[79, 313, 314, 315], 494);
                step(f, Op::MakeVector, &[313, 314, 845, 83], 495);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 44, 24], 496);
                step(f, Op::BreakTransform, &[24, 81, 14, 82], 497);
                step(f, Op::BreakVector, &[81, 316, 317, 318], 498);
                step(f, Op::MakeVector, &[316, 317, 845, 84], 499);
                step(f, Op::DistanceV, &[83, 84, 319], 500);
                step(f, Op::GreaterF, &[319, 31, 41], 501);
                step(f, Op::JumpIfFalse, &[41, 504], 502)
            }
            502 => {
                step(f, Op::Copy(ValueType::Bool), &[123, 40], 503);
                step(f, Op::Jump, &[504], 504)
            }
            504 => {
                step(f, Op::Jump, &[490], 505)
            }
            505 => {
                step(f, Op::Copy(ValueType::Bool), &[40, 39], 506);
                step(f, Op::Jump, &[507], 507)
            }
            507 => {
                step(f, Op::And, &[35, 39, 42], 508);
                step(f, Op::LengthV, &[2, 305], 509);
                step(f, Op::GreaterF, &[305, 29, 34], 510);
                step(f, Op::GreaterF, &[0, 29, 43], 511);
                step(f, Op::Or, &[34, 43, 44], 512);
                step(f, Op::Not, &[44, 45], 513);
                step(f, Op::And, &[42, 45, 50], 514);
                step(f, Op::DeltaTime, &[344], 515);
                step(f, Op::MulF, &[344, 34, 345], 516);
                step(f, Op::AddF, &[12, 345, 346], 517);
                step(f, Op::GreaterF, &[12, 846, 51], 518);
                step(f, Op::AddF, &[33, 846, 342], 519);
                step(f, Op::Select(ValueType::Float), &[51, 342, 33, 343], 520);
                step(f, Op::MinF, &[346, 343, 347], 521);
                step(f, Op::NotEquals(Elem::Bool), &[45, 4, 46], 522);
                step(f, Op::Not, &[42, 47], 523);
                step(f, Op::And, &[46, 47, 48], 524);
                step(f, Op::SubF, &[13, 29, 328], 525);
                step(f, Op::SubF, &[13, 305, 329], 526);
                step(f, Op::DivF, &[328, 329, 330], 527);
                step(f, Op::ClampF, &[330, 845, 847, 331], 528);
                step(f, Op::MulF, &[8, 331, 333], 529);
                step(f, Op::RemapF, &[305, 29, 30, 845, 847, 122, 320], 530);
                step(f, Op::MaxF, &[320, 9, 321], 531);
                step(f, Op::Select(ValueType::Float), &[35, 847, 321, 322], 532);
                step(f, Op::Select(ValueType::Float), &[45, 32, 322, 323], 533);
                step(f, Op::Select(ValueType::Float), &[42, 320, 323, 324], 534);
                step(f, Op::SubF, &[847, 21, 325], 535);
                step(f, Op::MulF, &[324, 325, 326], 536);
                step(f, Op::LerpF, &[23, 45, 15, 308], 537);
                step(f, Op::RemapF, &[305, 26, 27, 24, 25, 122, 306], 538);
                step(f, Op::LerpF, &[306, 44, 15, 307], 539);
                step(f, Op::MaxF, &[305, 28, 309], 540);
                step(f, Op::DivF, &[307, 309, 310], 541);
                step(f, Op::AddF, &[308, 310, 311], 542);
                step(f, Op::DivF, &[326, 311, 327], 543);
                step(f, Op::SubF, &[847, 331, 332], 544);
                step(f, Op::MulF, &[327, 332, 334], 545);
                step(f, Op::AddF, &[333, 334, 335], 546);
                step(f, Op::MulF, &[335, 850, 336], 547);
                step(f, Op::AddF, &[8, 327, 337], 548);
                step(f, Op::Select(ValueType::Float), &[48, 336, 337, 338], 549);
                step(f, Op::DivF, &[850, 338, 339], 550);
                step(f, Op::GreaterF, &[338, 845, 49], 551);
                step(f, Op::CycleStep, &[12, 339, 845, 49, 340, 341], 552);
                step(f, Op::Select(ValueType::Float), &[50, 347, 340, 348], 553);
                step(f, Op::Copy(ValueType::Float), &[348, 12], 554);
                step(f, Op::Copy(ValueType::Float), &[327, 8], 555);
                step(f, Op::Copy(ValueType::Bool), &[34, 3], 556);
                step(f, Op::Copy(ValueType::Float), &[310, 6], 557);
                step(f, Op::Copy(ValueType::Float), &[311, 7], 558);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 559);
                step(f, Op::Copy(ValueType::Int), &[71, 37], 560);
                step(f, Op::DivF, &[308, 311, 312], 561);
                step(f, Op::MulF, &[11, 331, 354], 562);
                step(f, Op::MulF, &[344, 846, 360], 563);
                step(f, Op::SubF, &[312, 10, 365], 564);
                step(f, Op::MaxF, &[365, 845, 366], 565);
                step(f, Op::DivF, &[366, 312, 367], 566);
                step(f, Op::SubF, &[847, 15, 369], 567);
                step(f, Op::DivF, &[49, 344, 374], 568);
                step(f, Op::SubF, &[846, 374, 375], 569);
                step(f, Op::MulF, &[367, 369, 376], 570);
                step(f, Op::MulF, &[376, 325, 377], 571);
                step(f, Op::MulF, &[377, 121, 378], 572);
                step(f, Op::MulF, &[378, 375, 379], 573);
                step(f, Op::SubF, &[847, 379, 380], 574);
                574
            }
            574 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 37, 14, 38, 39, 619], 575)
            }
            575 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 38, 362], 576);
                step(f, Op::ToFloat, &[38, 349], 577);
                step(f, Op::MulF, &[349, 846, 350], 578);
                step(f, Op::AddF, &[12, 350, 351], 579);
                step(f, Op::FractF, &[351, 352], 580);
                step(f, Op::SubF, &[362, 352, 364], 581);
                step(f, Op::GreaterF, &[364, 846, 52], 582);
                step(f, Op::ArrayAt(Elem::Float), &[2, 38, 363], 583);
                step(f, Op::Select(ValueType::Float), &[52, 845, 363, 391], 584);
                step(f, Op::ArraySetAt(Elem::Float), &[3, 38, 391], 585);
                step(f, Op::SubF, &[847, 362, 385], 586);
                step(f, Op::AddF, &[352, 385, 386], 587);
                step(f, Op::DivF, &[352, 386, 387], 588);
                step(f, Op::MaxF, &[320, 9, 321], 589);
                step(f, Op::Select(ValueType::Float), &[35, 847, 321, 322], 590);
                step(f, Op::Select(ValueType::Float), &[45, 32, 322, 323], 591);
                step(f, Op::Select(ValueType::Float), &[42, 320, 323, 324], 592);
                step(f, Op::MulF, &[324, 325, 326], 593);
                step(f, Op::DivF, &[326, 308, 353], 594);
                step(f, Op::MulF, &[353, 332, 355], 595);
                step(f, Op::AddF, &[354, 355, 356], 596);
                step(f, Op::MulF, &[356, 850, 357], 597);
                step(f, Op::AddF, &[11, 353, 358], 598);
                step(f, Op::Select(ValueType::Float), &[48, 357, 358, 359], 599);
                step(f, Op::MulF, &[359, 360, 361], 600);
                step(f, Op::MulF, &[387, 361, 388], 601);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 38, 53], 602);
                step(f, Op::MulF, &[361, 380, 381], 603);
                step(f, Op::Select(ValueType::Float), &[53, 361, 381, 382], 604);
                step(f, Op::MulF, &[367, 363, 368], 605);
                step(f, Op::MulF, &[368, 369, 370], 606);
                step(f, Op::MulF, &[370, 325, 371], 607);
                step(f, Op::MulF, &[371, 121, 372], 608);
                step(f, Op::Select(ValueType::Float), &[53, 845, 372, 373], 609);
                step(f, Op::SubF, &[382, 373, 383], 610);
                step(f, Op::AddF, &[363, 383, 384], 611);
                step(f, Op::Select(ValueType::Float), &[52, 388, 384, 389], 612);
                step(f, Op::MinF, &[389, 850, 390], 613);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 38, 390], 614);
                step(f, Op::JumpIfFalse, &[52, 617], 615)
            }
            615 => {
                step(f, Op::Copy(ValueType::Float), &[324, 9], 616);
                step(f, Op::Jump, &[617], 617)
            }
            617 => {
                step(f, Op::ArraySetAt(Elem::Float), &[0, 38, 352], 618);
                step(f, Op::Jump, &[574], 619)
            }
            619 => {
                step(f, Op::Copy(ValueType::Float), &[312, 10], 620);
                step(f, Op::Copy(ValueType::Bool), &[45, 4], 621);
                step(f, Op::Copy(ValueType::Float), &[305, 13], 622);
                step(f, Op::MaxF, &[320, 9, 321], 623);
                step(f, Op::Select(ValueType::Float), &[35, 847, 321, 322], 624);
                step(f, Op::Select(ValueType::Float), &[45, 32, 322, 323], 625);
                step(f, Op::Select(ValueType::Float), &[42, 320, 323, 324], 626);
                step(f, Op::MulF, &[324, 325, 326], 627);
                step(f, Op::DivF, &[326, 308, 353], 628);
                step(f, Op::Copy(ValueType::Float), &[353, 11], 629);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 630);
                step(f, Op::Copy(ValueType::Int), &[71, 2], 631);
                631
            }
            631 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 2, 0, 3, 4, 1476], 632)
            }
            632 => {
                step(f, Op::Copy(ValueType::Bone), &[0, 16], 633);
                step(f, Op::Copy(ValueType::Int), &[3, 46], 634);
                step(f, Op::Copy(ValueType::Bool), &[122, 54], 635);
                step(f, Op::Copy(ValueType::Bool), &[123, 55], 636);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 46, 58], 637);
                step(f, Op::ArrayAt(Elem::Float), &[2, 46, 392], 638);
                step(f, Op::GreaterEqualF, &[392, 847, 59], 639);
                step(f, Op::And, &[58, 59, 60], 640);
                step(f, Op::Or, &[1, 2, 62], 641);
                step(f, Op::GreaterF, &[21, 845, 61], 642);
                step(f, Op::Or, &[62, 61, 63], 643);
                step(f, Op::Not, &[63, 64], 644);
                step(f, Op::And, &[60, 64, 65], 645);
                step(f, Op::JumpIfFalse, &[65, 764], 646)
            }
            646 => {
                step(f, Op::ArrayAt(Elem::Transform), &[2, 46, 28], 647);
                step(f, Op::BreakTransform, &[28, 103, 23, 104], 648);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 46, 120], 649);
                step(f, Op::SubV, &[103, 120, 141], 650);
                step(f, Op::TransformPoint, &[2, 141, 142], 651);
                step(f, Op::GetTransform, &[35, 71, 122, 25], 652);
                step(f, Op::BreakTransform, &[25, 87, 15, 88], 653);
                step(f, Op::BreakVector, &[87, 403, 404, 405], 654);
                step(f, Op::SubF, &[847, 15, 401], 655);
                step(f, Op::MulF, &[14, 401, 402], 656);
                step(f, Op::QuatFromAxisAngle, &[468, 402, 17], 657);
                step(f, Op::GetTransform, &[16, 71, 122, 26], 658);
                step(f, Op::BreakTransform, &[26, 89, 16, 90], 659);
                step(f, Op::SubV, &[89, 87, 91], 660);
                step(f, Op::BreakVector, &[91, 398, 399, 400], 661);
                step(f, Op::MakeVector, &[398, 399, 845, 92], 662);
                step(f, Op::RotateVector, &[17, 92, 93], 663);
                step(f, Op::BreakVector, &[93, 406, 407, 408], 664);
                step(f, Op::MulF, &[46, 15, 409], 665);
                step(f, Op::Equals(Elem::Int), &[46, 71, 56], 666);
                step(f, Op::Select(ValueType::Float), &[56, 847, 849, 418], 667);
                step(f, Op::MulF, &[409, 418, 410], 668);
                step(f, Op::AddF, &[406, 410, 411], 669);
                step(f, Op::AddF, &[403, 411, 412], 670);
                step(f, Op::AddF, &[404, 407, 413], 671);
                step(f, Op::BreakVector, &[89, 414, 415, 416], 672);
                step(f, Op::SubF, &[416, 50, 417], 673);
                step(f, Op::MakeVector, &[412, 413, 417, 94], 674);
                step(f, Op::MulF, &[6, 846, 397], 675);
                step(f, Op::ScaleV, &[2, 397, 86], 676);
                step(f, Op::AddV, &[94, 86, 97], 677);
                step(f, Op::DistanceV, &[142, 97, 445], 678);
                step(f, Op::TransformVector, &[2, 469, 143], 679);
                step(f, Op::DistanceV, &[143, 469, 446], 680);
                step(f, Op::MaxF, &[445, 446, 447], 681);
                step(f, Op::LessEqualF, &[447, 57, 74], 682);
                step(f, Op::LengthV, &[2, 448], 683);
                step(f, Op::LengthV, &[4, 449], 684);
                step(f, Op::MaxF, &[448, 449, 450], 685);
                step(f, Op::LessEqualF, &[450, 29, 75], 686);
                step(f, Op::And, &[74, 75, 76], 687);
                step(f, Op::ArrayAt(Elem::Bool), &[1, 46, 66], 688);
                step(f, Op::And, &[76, 66, 77], 689);
                step(f, Op::JumpIfFalse, &[77, 692], 690)
            }
            690 => {
                step(f, Op::Copy(ValueType::Bool), &[122, 55], 691);
                step(f, Op::Jump, &[722], 692)
            }
            692 => {
                step(f, Op::MakeVector, &[845, 845, 55, 122], 693);
                step(f, Op::AddV, &[97, 122, 123], 694);
                step(f, Op::SubV, &[97, 122, 124], 695);
                step(f, Op::SphereTrace, &[123, 124, 54, 67, 125, 126, 437], 696);
                step(f, Op::SubV, &[125, 97, 139], 697);
                step(f, Op::DistanceV, &[139, 120, 441], 698);
                step(f, Op::RotateVector, &[0, 470, 98], 699);
                step(f, Op::ScaleV, &[98, 59, 127], 700);
                step(f, Op::AddV, &[123, 127, 128], 701);
                step(f, Op::AddV, &[124, 127, 129], 702);
                step(f, Op::SphereTrace, &[128, 129, 54, 68, 130, 131, 438], 703);
                step(f, Op::SubV, &[130, 97, 140], 704);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 46, 121], 705);
                step(f, Op::DistanceV, &[140, 121, 442], 706);
                step(f, Op::MaxF, &[441, 442, 443], 707);
                step(f, Op::ScaleV, &[98, 56, 132], 708);
                step(f, Op::AddV, &[128, 132, 133], 709);
                step(f, Op::AddV, &[129, 132, 134], 710);
                step(f, Op::SphereTrace, &[133, 134, 54, 69, 135, 136, 439], 711);
                step(f, Op::SubV, &[135, 97, 137], 712);
                step(f, Op::ArrayAt(Elem::Vec3), &[2, 46, 138], 713);
                step(f, Op::DistanceV, &[137, 138, 440], 714);
                step(f, Op::MaxF, &[443, 440, 444], 715);
                step(f, Op::LessEqualF, &[444, 57, 70], 716);
                step(f, Op::And, &[67, 68, 71], 717);
                step(f, Op::And, &[71, 66, 72], 718);
                step(f, Op::And, &[70, 72, 73], 719);
                step(f, Op::JumpIfFalse, &[73, 722], 720)
            }
            720 => {
                step(f, Op::Copy(ValueType::Bool), &[122, 55], 721);
                step(f, Op::Jump, &[722], 722)
            }
            722 => {
                step(f, Op::JumpIfFalse, &[55, 763], 723)
            }
            723 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 46, 27], 724);
                step(f, Op::BreakTransform, &[27, 100, 21, 101], 725);
                step(f, Op::AddV, &[97, 120, 144], 726);
                step(f, Op::Copy(ValueType::Vec3), &[100, 145], 727);
                step(f, Op::Copy(ValueType::Vec3), &[144, 146], 728);
                step(f, Op::Copy(ValueType::Vec3), &[103, 147], 729);
                step(f, Op::Copy(ValueType::Float), &[47, 451], 730);
                step(f, Op::Copy(ValueType::Float), &[49, 452], 731);
                step(f, Op::Copy(ValueType::Vec3), &[465, 148], 732);
                step(f, Op::SubV, &[146, 147, 149], 733);
                step(f, Op::DeltaTime, &[453], 734);
                step(f, Op::DivF, &[452, 453, 454], 735);
                step(f, Op::ScaleV, &[149, 454, 150], 736);
                step(f, Op::AddV, &[146, 150, 151], 737);
                step(f, Op::AddV, &[147, 150, 152], 738);
                step(f, Op::SubV, &[145, 152, 153], 739);
                step(f, Op::FloatLerp, &[845, 847, 451, 455], 740);
                step(f, Op::SubF, &[847, 455, 456], 741);
                step(f, Op::ScaleV, &[153, 456, 154], 742);
                step(f, Op::AddV, &[151, 154, 156], 743);
                step(f, Op::MulF, &[451, 453, 457], 744);
                step(f, Op::GreaterF, &[457, 845, 78], 745);
                step(f, Op::DivF, &[455, 457, 458], 746);
                step(f, Op::Select(ValueType::Float), &[78, 458, 847, 459], 747);
                step(f, Op::ScaleV, &[149, 459, 155], 748);
                step(f, Op::SubV, &[156, 155, 157], 749);
                step(f, Op::Copy(ValueType::Vec3), &[157, 148], 750);
                step(f, Op::Jump, &[751], 751)
            }
            751 => {
                step(f, Op::BreakVector, &[148, 460, 461, 462], 752);
                step(f, Op::ClampF, &[462, 60, 61, 463], 753);
                step(f, Op::MakeVector, &[460, 461, 463, 158], 754);
                step(f, Op::MakeTransform, &[158, 21, 466, 31], 755);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 46, 31], 756);
                step(f, Op::MakeTransform, &[144, 92, 466, 32], 757);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 46, 32], 758);
                step(f, Op::JumpIfFalse, &[66, 761], 759)
            }
            759 => {
                step(f, Op::Copy(ValueType::Bool), &[122, 7], 760);
                step(f, Op::Jump, &[761], 761)
            }
            761 => {
                step(f, Op::Copy(ValueType::Bool), &[123, 54], 762);
                step(f, Op::Jump, &[763], 763)
            }
            763 => {
                step(f, Op::Jump, &[764], 764)
            }
            764 => {
                step(f, Op::JumpIfFalse, &[54, 986], 765)
            }
            765 => {
                step(f, Op::GetTransform, &[35, 71, 122, 25], 766);
                step(f, Op::BreakTransform, &[25, 87, 15, 88], 767);
                step(f, Op::BreakVector, &[87, 403, 404, 405], 768);
                step(f, Op::SubF, &[847, 15, 401], 769);
                step(f, Op::MulF, &[14, 401, 402], 770);
                step(f, Op::QuatFromAxisAngle, &[468, 402, 17], 771);
                step(f, Op::GetTransform, &[16, 71, 122, 26], 772);
                step(f, Op::BreakTransform, &[26, 89, 16, 90], 773);
                step(f, Op::SubV, &[89, 87, 91], 774);
                step(f, Op::BreakVector, &[91, 398, 399, 400], 775);
                step(f, Op::MakeVector, &[398, 399, 845, 92], 776);
                step(f, Op::RotateVector, &[17, 92, 93], 777);
                step(f, Op::BreakVector, &[93, 406, 407, 408], 778);
                step(f, Op::MulF, &[46, 15, 409], 779);
                step(f, Op::Equals(Elem::Int), &[46, 71, 56], 780);
                step(f, Op::Select(ValueType::Float), &[56, 847, 849, 418], 781);
                step(f, Op::MulF, &[409, 418, 410], 782);
                step(f, Op::AddF, &[406, 410, 411], 783);
                step(f, Op::AddF, &[403, 411, 412], 784);
                step(f, Op::AddF, &[404, 407, 413], 785);
                step(f, Op::BreakVector, &[89, 414, 415, 416], 786);
                step(f, Op::SubF, &[416, 50, 417], 787);
                step(f, Op::MakeVector, &[412, 413, 417, 94], 788);
                step(f, Op::SubF, &[847, 392, 393], 789);
                step(f, Op::MaxF, &[393, 845, 394], 790);
                step(f, Op::MulF, &[10, 7, 395], 791);
                step(f, Op::MulF, &[394, 395, 396], 792);
                step(f, Op::ScaleV, &[2, 396, 85], 793);
                step(f, Op::AddV, &[94, 85, 95], 794);
                step(f, Op::MulF, &[6, 846, 397], 795);
                step(f, Op::ScaleV, &[2, 397, 86], 796);
                step(f, Op::AddV, &[95, 86, 96], 797);
                step(f, Op::RotateVector, &[0, 470, 98], 798);
                step(f, Op::Copy(ValueType::Vec3), &[96, 159], 799);
                step(f, Op::Copy(ValueType::Vec3), &[98, 160], 800);
                step(f, Op::Copy(ValueType::Float), &[418, 464], 801);
                step(f, Op::Copy(ValueType::Vec3), &[465, 161], 802);
                step(f, Op::Copy(ValueType::Vec3), &[465, 162], 803);
                step(f, Op::Copy(ValueType::Bool), &[123, 79], 804);
                step(f, Op::Copy(ValueType::Float), &[852, 465], 805);
                step(f, Op::Copy(ValueType::Vec3), &[465, 163], 806);
                step(f, Op::Copy(ValueType::Vec3), &[468, 164], 807);
                step(f, Op::Copy(ValueType::Bool), &[123, 80], 808);
                step(f, Op::Copy(ValueType::Float), &[852, 466], 809);
                step(f, Op::Copy(ValueType::Vec3), &[465, 165], 810);
                step(f, Op::MulI, &[0, 0, 52], 811);
                step(f, Op::Copy(ValueType::Int), &[52, 51], 812);
                step(f, Op::Copy(ValueType::Int), &[71, 47], 813);
                step(f, Op::SubI, &[0, 72, 55], 814);
                step(f, Op::DivI, &[55, 73, 56], 815);
                step(f, Op::MakeVector, &[845, 845, 55, 170], 816);
                step(f, Op::ScaleV, &[160, 59, 175], 817);
                817
            }
            817 => {
                step(f, Op::ForNext, &[47, 51, 49, 865], 818)
            }
            818 => {
                step(f, Op::ModI, &[49, 0, 53], 819);
                step(f, Op::ToFloat, &[53, 467], 820);
                step(f, Op::MulF, &[467, 56, 469], 821);
                step(f, Op::MulF, &[469, 464, 470], 822);
                step(f, Op::MakeVector, &[470, 845, 845, 166], 823);
                step(f, Op::DivI, &[49, 0, 54], 824);
                step(f, Op::SubI, &[54, 56, 57], 825);
                step(f, Op::ToFloat, &[57, 468], 826);
                step(f, Op::MulF, &[468, 56, 471], 827);
                step(f, Op::ScaleV, &[160, 471, 167], 828);
                step(f, Op::AddV, &[166, 167, 168], 829);
                step(f, Op::AddV, &[159, 168, 169], 830);
                step(f, Op::AddV, &[169, 170, 171], 831);
                step(f, Op::SubV, &[169, 170, 172], 832);
                step(f, Op::SphereTrace, &[171, 172, 54, 81, 173, 174, 472], 833);
                step(f, Op::BreakVector, &[173, 474, 475, 476], 834);
                step(f, Op::AddV, &[171, 175, 176], 835);
                step(f, Op::AddV, &[172, 175, 177], 836);
                step(f, Op::SphereTrace, &[176, 177, 54, 82, 178, 179, 473], 837);
                step(f, Op::BreakVector, &[178, 477, 478, 479], 838);
                step(f, Op::SubF, &[476, 479, 480], 839);
                step(f, Op::AbsF, &[480, 481], 840);
                step(f, Op::Select(ValueType::Float), &[81, 845, 847, 482], 841);
                step(f, Op::AddF, &[481, 482, 487], 842);
                step(f, Op::LengthV, &[168, 483], 843);
                step(f, Op::RemapF, &[483, 845, 858, 845, 847, 122, 484], 844);
                step(f, Op::MinF, &[476, 479, 485], 845);
                step(f, Op::RemapF, &[485, 859, 858, 847, 846, 122, 486], 846);
                step(f, Op::AddF, &[484, 486, 488], 847);
                step(f, Op::AddF, &[487, 488, 489], 848);
                step(f, Op::LessF, &[489, 465, 83], 849);
                step(f, Op::And, &[81, 83, 84], 850);
                step(f, Op::JumpIfFalse, &[84, 858], 851)
            }
            851 => {
                step(f, Op::Copy(ValueType::Float), &[465, 466], 852);
                step(f, Op::Copy(ValueType::Vec3), &[163, 165], 853);
                step(f, Op::Copy(ValueType::Float), &[489, 465], 854);
                step(f, Op::Copy(ValueType::Vec3), &[173, 163], 855);
                step(f, Op::Copy(ValueType::Vec3), &[174, 164], 856);
                step(f, Op::Copy(ValueType::Bool), &[122, 80], 857);
                step(f, Op::Jump, &[864], 858)
            }
            858 => {
                step(f, Op::LessF, &[489, 466, 85], 859);
                step(f, Op::And, &[81, 85, 86], 860);
                step(f, Op::JumpIfFalse, &[86, 864], 861)
            }
            861 => {
                step(f, Op::Copy(ValueType::Float), &[489, 466], 862);
                step(f, Op::Copy(ValueType::Vec3), &[173, 165], 863);
                step(f, Op::Jump, &[864], 864)
            }
            864 => {
                step(f, Op::Jump, &[817], 865)
            }
            865 => {
                step(f, Op::JumpIfFalse, &[8, 868], 866)
            }
            866 => {
                step(f, Op::DrawSphere, &[163, 54, 470], 867);
                step(f, Op::Jump, &[868], 868)
            }
            868 => {
                step(f, Op::GreaterF, &[58, 845, 87], 869);
                step(f, Op::SubF, &[465, 466, 490], 870);
                step(f, Op::DivF, &[490, 58, 491], 871);
                step(f, Op::PowF, &[860, 491, 492], 872);
                step(f, Op::Select(ValueType::Float), &[87, 492, 845, 493], 873);
                step(f, Op::ScaleV, &[165, 493, 180], 874);
                step(f, Op::AddV, &[163, 180, 181], 875);
                step(f, Op::AddF, &[493, 847, 494], 876);
                step(f, Op::DivF, &[847, 494, 495], 877);
                step(f, Op::ScaleV, &[181, 495, 182], 878);
                step(f, Op::Copy(ValueType::Vec3), &[182, 161], 879);
                step(f, Op::Copy(ValueType::Vec3), &[164, 162], 880);
                step(f, Op::Copy(ValueType::Bool), &[80, 79], 881);
                step(f, Op::Jump, &[882], 882)
            }
            882 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 46, 27], 883);
                step(f, Op::BreakTransform, &[27, 100, 21, 101], 884);
                step(f, Op::ArrayAt(Elem::Float), &[2, 46, 392], 885);
                step(f, Op::SubF, &[847, 392, 393], 886);
                step(f, Op::MaxF, &[393, 845, 394], 887);
                step(f, Op::MulF, &[10, 7, 395], 888);
                step(f, Op::MulF, &[394, 395, 396], 889);
                step(f, Op::ScaleV, &[2, 396, 85], 890);
                step(f, Op::SubV, &[161, 85, 99], 891);
                step(f, Op::Select(ValueType::Vec3), &[79, 99, 100, 102], 892);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 46, 28], 893);
                step(f, Op::BreakTransform, &[28, 103, 23, 104], 894);
                step(f, Op::Copy(ValueType::Vec3), &[100, 105], 895);
                step(f, Op::Copy(ValueType::Vec3), &[102, 106], 896);
                step(f, Op::Copy(ValueType::Vec3), &[103, 107], 897);
                step(f, Op::Copy(ValueType::Float), &[47, 424], 898);
                step(f, Op::Copy(ValueType::Float), &[49, 425], 899);
                step(f, Op::Copy(ValueType::Vec3), &[465, 108], 900);
                step(f, Op::SubV, &[106, 107, 109], 901);
                step(f, Op::DeltaTime, &[426], 902);
                step(f, Op::DivF, &[425, 426, 427], 903);
                step(f, Op::ScaleV, &[109, 427, 110], 904);
                step(f, Op::AddV, &[106, 110, 111], 905);
                step(f, Op::AddV, &[107, 110, 112], 906);
                step(f, Op::SubV, &[105, 112, 113], 907);
                step(f, Op::FloatLerp, &[845, 847, 424, 428], 908);
                step(f, Op::SubF, &[847, 428, 429], 909);
                step(f, Op::ScaleV, &[113, 429, 114], 910);
                step(f, Op::AddV, &[111, 114, 116], 911);
                step(f, Op::MulF, &[424, 426, 430], 912);
                step(f, Op::GreaterF, &[430, 845, 57], 913);
                step(f, Op::DivF, &[428, 430, 431], 914);
                step(f, Op::Select(ValueType::Float), &[57, 431, 847, 432], 915);
                step(f, Op::ScaleV, &[109, 432, 115], 916);
                step(f, Op::SubV, &[116, 115, 117], 917);
                step(f, Op::Copy(ValueType::Vec3), &[117, 108], 918);
                step(f, Op::Jump, &[919], 919)
            }
            919 => {
                step(f, Op::BreakVector, &[108, 433, 434, 435], 920);
                step(f, Op::ClampF, &[435, 60, 61, 436], 921);
                step(f, Op::MakeVector, &[433, 434, 436, 118], 922);
                step(f, Op::RotationFromNormal, &[162, 422, 423, 19], 923);
                step(f, Op::PerFootRotationFactor, &[14, 98, 99, 419], 924);
                step(f, Op::MulF, &[14, 419, 420], 925);
                step(f, Op::SubF, &[847, 15, 401], 926);
                step(f, Op::MulF, &[420, 401, 421], 927);
                step(f, Op::QuatFromAxisAngle, &[468, 421, 18], 928);
                step(f, Op::MulQ, &[19, 18, 20], 929);
                step(f, Op::Select(ValueType::Quat), &[79, 20, 21, 22], 930);
                step(f, Op::MakeTransform, &[118, 22, 466, 30], 931);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 46, 30], 932);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 46, 27], 933);
                step(f, Op::BreakTransform, &[27, 100, 21, 101], 934);
                step(f, Op::Select(ValueType::Vec3), &[79, 99, 100, 102], 935);
                step(f, Op::MakeTransform, &[102, 92, 466, 29], 936);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 46, 29], 937);
                step(f, Op::GetTransform, &[35, 71, 122, 25], 938);
                step(f, Op::BreakTransform, &[25, 87, 15, 88], 939);
                step(f, Op::BreakVector, &[87, 403, 404, 405], 940);
                step(f, Op::MulF, &[14, 401, 402], 941);
                step(f, Op::QuatFromAxisAngle, &[468, 402, 17], 942);
                step(f, Op::GetTransform, &[16, 71, 122, 26], 943);
                step(f, Op::BreakTransform, &[26, 89, 16, 90], 944);
                step(f, Op::SubV, &[89, 87, 91], 945);
                step(f, Op::BreakVector, &[91, 398, 399, 400], 946);
                step(f, Op::MakeVector, &[398, 399, 845, 92], 947);
                step(f, Op::RotateVector, &[17, 92, 93], 948);
                step(f, Op::BreakVector, &[93, 406, 407, 408], 949);
                step(f, Op::MulF, &[46, 15, 409], 950);
                step(f, Op::MulF, &[409, 418, 410], 951);
                step(f, Op::AddF, &[406, 410, 411], 952);
                step(f, Op::AddF, &[403, 411, 412], 953);
                step(f, Op::AddF, &[404, 407, 413], 954);
                step(f, Op::BreakVector, &[89, 414, 415, 416], 955);
                step(f, Op::SubF, &[416, 50, 417], 956);
                step(f, Op::MakeVector, &[412, 413, 417, 94], 957);
                step(f, Op::MulF, &[6, 846, 397], 958);
                step(f, Op::ScaleV, &[2, 397, 86], 959);
                step(f, Op::AddV, &[94, 86, 97], 960);
                step(f, Op::SubV, &[102, 97, 119], 961);
                step(f, Op::ArraySetAt(Elem::Vec3), &[0, 46, 119], 962);
                step(f, Op::ArraySetAt(Elem::Bool), &[1, 46, 79], 963);
                step(f, Op::GreaterEqualF, &[392, 847, 59], 964);
                step(f, Op::JumpIfFalse, &[59, 982], 965)
            }
            965 => {
                step(f, Op::MakeVector, &[845, 845, 55, 122], 966);
                step(f, Op::AddV, &[97, 122, 123], 967);
                step(f, Op::RotateVector, &[0, 470, 98], 968);
                step(f, Op::ScaleV, &[98, 59, 127], 969);
                step(f, Op::AddV, &[123, 127, 128], 970);
                step(f, Op::SubV, &[97, 122, 124], 971);
                step(f, Op::AddV, &[124, 127, 129], 972);
                step(f, Op::SphereTrace, &[128, 129, 54, 68, 130, 131, 438], 973);
                step(f, Op::SubV, &[130, 97, 140], 974);
                step(f, Op::ArraySetAt(Elem::Vec3), &[1, 46, 140], 975);
                step(f, Op::ScaleV, &[98, 56, 132], 976);
                step(f, Op::AddV, &[128, 132, 133], 977);
                step(f, Op::AddV, &[129, 132, 134], 978);
                step(f, Op::SphereTrace, &[133, 134, 54, 69, 135, 136, 439], 979);
                step(f, Op::SubV, &[135, 97, 137], 980);
                step(f, Op::ArraySetAt(Elem::Vec3), &[2, 46, 137], 981);
                step(f, Op::Jump, &[982], 982)
            }
            982 => {
                step(f, Op::JumpIfFalse, &[79, 985], 983)
            }
            983 => {
                step(f, Op::Copy(ValueType::Bool), &[122, 7], 984);
                step(f, Op::Jump, &[985], 985)
            }
            985 => {
                step(f, Op::Jump, &[986], 986)
            }
            986 => {
                step(f, Op::Copy(ValueType::Int), &[3, 58], 987);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 58, 35], 988);
                step(f, Op::GreaterF, &[21, 845, 91], 989);
                step(f, Op::InterpolateTransform, &[2, 115, 22, 33], 990);
                step(f, Op::Select(ValueType::Transform), &[91, 33, 2, 34], 991);
                step(f, Op::MakeAbsolute, &[35, 34, 36], 992);
                step(f, Op::BreakTransform, &[36, 183, 24, 184], 993);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 58, 37], 994);
                step(f, Op::BreakTransform, &[37, 185, 25, 186], 995);
                step(f, Op::AddF, &[64, 65, 497], 996);
                step(f, Op::ClampSpatially, &[183, 185, 845, 497, 187], 997);
                step(f, Op::SubF, &[847, 15, 512], 998);
                step(f, Op::MulF, &[14, 512, 498], 999);
                step(f, Op::LimitRotationAroundZ, &[24, 498, 97, 26], 1000);
                step(f, Op::MakeTransform, &[187, 26, 466, 38], 1001);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 58, 38], 1002);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 58, 88], 1003);
                step(f, Op::JumpIfFalse, &[88, 1060], 1004)
            }
            1004 => {
                step(f, Op::ArrayAt(Elem::Float), &[2, 58, 496], 1005);
                step(f, Op::GreaterEqualF, &[496, 847, 89], 1006);
                step(f, Op::JumpIfFalse, &[89, 1008], 1007)
            }
            1007 => {
                step(f, Op::Jump, &[1059], 1008)
            }
            1008 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 58, 41], 1009);
                step(f, Op::BreakTransform, &[41, 193, 28, 194], 1010);
                step(f, Op::SubF, &[847, 496, 509], 1011);
                step(f, Op::MulF, &[10, 7, 510], 1012);
                step(f, Op::MulF, &[509, 510, 511], 1013);
                step(f, Op::ScaleV, &[2, 511, 195], 1014);
                step(f, Op::AddV, &[193, 195, 196], 1015);
                step(f, Op::MakeTransform, &[196, 28, 466, 48], 1016);
                step(f, Op::Copy(ValueType::Transform), &[48, 49], 1017);
                step(f, Op::Copy(ValueType::Transform), &[115, 50], 1018);
                step(f, Op::BreakTransform, &[49, 224, 33, 225], 1019);
                step(f, Op::MakeVector, &[845, 845, 55, 226], 1020);
                step(f, Op::AddV, &[224, 226, 227], 1021);
                step(f, Op::SubV, &[224, 226, 228], 1022);
                step(f, Op::LineTrace, &[227, 228, 95, 229, 230, 539], 1023);
                step(f, Op::RotateVector, &[33, 468, 231], 1024);
                step(f, Op::FindQuatBetween, &[231, 230, 34], 1025);
                step(f, Op::MulQ, &[34, 33, 35], 1026);
                step(f, Op::MulF, &[53, 52, 540], 1027);
                step(f, Op::AddF, &[540, 63, 541], 1028);
                step(f, Op::NegF, &[541, 542], 1029);
                step(f, Op::MakeVector, &[845, 542, 845, 232], 1030);
                step(f, Op::RotateVector, &[35, 232, 234], 1031);
                step(f, Op::AddV, &[229, 234, 236], 1032);
                step(f, Op::AddV, &[236, 226, 238], 1033);
                step(f, Op::SubV, &[236, 226, 239], 1034);
                step(f, Op::LineTrace, &[238, 239, 96, 242, 243, 544], 1035);
                step(f, Op::BreakVector, &[242, 546, 547, 548], 1036);
                step(f, Op::BreakVector, &[236, 552, 553, 554], 1037);
                step(f, Op::SubF, &[548, 554, 558], 1038);
                step(f, Op::Select(ValueType::Float), &[96, 558, 845, 560], 1039);
                step(f, Op::AddF, &[59, 63, 543], 1040);
                step(f, Op::MakeVector, &[845, 543, 845, 233], 1041);
                step(f, Op::RotateVector, &[35, 233, 235], 1042);
                step(f, Op::AddV, &[229, 235, 237], 1043);
                step(f, Op::AddV, &[237, 226, 240], 1044);
                step(f, Op::SubV, &[237, 226, 241], 1045);
                step(f, Op::LineTrace, &[240, 241, 97, 244, 245, 545], 1046);
                step(f, Op::BreakVector, &[244, 549, 550, 551], 1047);
                step(f, Op::BreakVector, &[237, 555, 556, 557], 1048);
                step(f, Op::SubF, &[551, 557, 559], 1049);
                step(f, Op::Select(ValueType::Float), &[97, 559, 845, 561], 1050);
                step(f, Op::MaxF, &[560, 561, 562], 1051);
                step(f, Op::ClampF, &[562, 845, 62, 563], 1052);
                step(f, Op::MakeVector, &[845, 845, 563, 246], 1053);
                step(f, Op::AddV, &[229, 246, 247], 1054);
                step(f, Op::MakeTransform, &[247, 35, 466, 51], 1055);
                step(f, Op::Select(ValueType::Transform), &[95, 51, 49, 52], 1056);
                step(f, Op::Copy(ValueType::Transform), &[52, 50], 1057);
                step(f, Op::Jump, &[1058], 1058)
            }
            1058 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 58, 50], 1059);
                1059
            }
            1059 => {
                step(f, Op::Jump, &[1161], 1060)
            }
            1060 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 58, 53], 1061);
                step(f, Op::MakeAbsolute, &[53, 34, 54], 1062);
                step(f, Op::BreakTransform, &[54, 248, 36, 249], 1063);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 58, 41], 1064);
                step(f, Op::BreakTransform, &[41, 193, 28, 194], 1065);
                step(f, Op::ArrayAt(Elem::Float), &[2, 58, 496], 1066);
                step(f, Op::SubF, &[847, 496, 509], 1067);
                step(f, Op::MulF, &[10, 7, 510], 1068);
                step(f, Op::MulF, &[509, 510, 511], 1069);
                step(f, Op::ScaleV, &[2, 511, 195], 1070);
                step(f, Op::AddV, &[193, 195, 196], 1071);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 58, 55], 1072);
                step(f, Op::MakeAbsolute, &[55, 34, 56], 1073);
                step(f, Op::BreakTransform, &[56, 250, 37, 251], 1074);
                step(f, Op::ArrayAt(Elem::Float), &[3, 58, 564], 1075);
                step(f, Op::SubF, &[496, 564, 565], 1076);
                step(f, Op::DeltaTime, &[580], 1077);
                step(f, Op::DivF, &[49, 580, 566], 1078);
                step(f, Op::MulF, &[565, 566, 567], 1079);
                step(f, Op::AddF, &[564, 567, 568], 1080);
                step(f, Op::ClampF, &[568, 845, 847, 570], 1081);
                step(f, Op::AddF, &[496, 567, 569], 1082);
                step(f, Op::ClampF, &[569, 845, 847, 571], 1083);
                step(f, Op::AddF, &[570, 571, 572], 1084);
                step(f, Op::MulF, &[572, 846, 573], 1085);
                step(f, Op::SubF, &[847, 573, 574], 1086);
                step(f, Op::GreaterF, &[565, 845, 98], 1087);
                step(f, Op::SubF, &[571, 570, 575], 1088);
                step(f, Op::DivF, &[575, 565, 576], 1089);
                step(f, Op::Select(ValueType::Float), &[98, 576, 847, 577], 1090);
                step(f, Op::MulF, &[574, 577, 578], 1091);
                step(f, Op::MulF, &[80, 578, 579], 1092);
                step(f, Op::Copy(ValueType::Vec3), &[248, 252], 1093);
                step(f, Op::Copy(ValueType::Vec3), &[196, 253], 1094);
                step(f, Op::Copy(ValueType::Vec3), &[250, 254], 1095);
                step(f, Op::Copy(ValueType::Float), &[579, 581], 1096);
                step(f, Op::Copy(ValueType::Float), &[49, 582], 1097);
                step(f, Op::Copy(ValueType::Vec3), &[465, 255], 1098);
                step(f, Op::SubV, &[253, 254, 256], 1099);
                step(f, Op::DeltaTime, &[583], 1100);
                step(f, Op::DivF, &[582, 583, 584], 1101);
                step(f, Op::ScaleV, &[256, 584, 257], 1102);
                step(f, Op::AddV, &[253, 257, 258], 1103);
                step(f, Op::AddV, &[254, 257, 259], 1104);
                step(f, Op::SubV, &[252, 259, 260], 1105);
                step(f, Op::FloatLerp, &[845, 847, 581, 585], 1106);
                step(f, Op::SubF, &[847, 585, 586], 1107);
                step(f, Op::ScaleV, &[260, 586, 261], 1108);
                step(f, Op::AddV, &[258, 261, 263], 1109);
                step(f, Op::MulF, &[581, 583, 587], 1110);
                step(f, Op::GreaterF, &[587, 845, 99], 1111);
                step(f, Op::DivF, &[585, 587, 588], 1112);
                step(f, Op::Select(ValueType::Float), &[99, 588, 847, 589], 1113);
                step(f, Op::ScaleV, &[256, 589, 262], 1114);
                step(f, Op::SubV, &[263, 262, 264], 1115);
                step(f, Op::Copy(ValueType::Vec3), &[264, 255], 1116);
                step(f, Op::Jump, &[1117], 1117)
            }
            1117 => {
                step(f, Op::MakeTransform, &[255, 28, 466, 58], 1118);
                step(f, Op::Copy(ValueType::Transform), &[58, 59], 1119);
                step(f, Op::Copy(ValueType::Transform), &[115, 60], 1120);
                step(f, Op::BreakTransform, &[59, 265, 38, 266], 1121);
                step(f, Op::MakeVector, &[845, 845, 55, 267], 1122);
                step(f, Op::AddV, &[265, 267, 268], 1123);
                step(f, Op::SubV, &[265, 267, 269], 1124);
                step(f, Op::LineTrace, &[268, 269, 100, 270, 271, 590], 1125);
                step(f, Op::RotateVector, &[38, 468, 272], 1126);
                step(f, Op::FindQuatBetween, &[272, 271, 39], 1127);
                step(f, Op::MulQ, &[39, 38, 40], 1128);
                step(f, Op::MulF, &[53, 52, 591], 1129);
                step(f, Op::AddF, &[591, 63, 592], 1130);
                step(f, Op::NegF, &[592, 593], 1131);
                step(f, Op::MakeVector, &[845, 593, 845, 273], 1132);
                step(f, Op::RotateVector, &[40, 273, 275], 1133);
                step(f, Op::AddV, &[270, 275, 277], 1134);
                step(f, Op::AddV, &[277, 267, 279], 1135);
                step(f, Op::SubV, &[277, 267, 280], 1136);
                step(f, Op::LineTrace, &[279, 280, 101, 283, 284, 595], 1137);
                step(f, Op::BreakVector, &[283, 597, 598, 599], 1138);
                step(f, Op::BreakVector, &[277, 603, 604, 605], 1139);
                step(f, Op::SubF, &[599, 605, 609], 1140);
                step(f, Op::Select(ValueType::Float), &[101, 609, 845, 611], 1141);
                step(f, Op::AddF, &[59, 63, 594], 1142);
                step(f, Op::MakeVector, &[845, 594, 845, 274], 1143);
                step(f, Op::RotateVector, &[40, 274, 276], 1144);
                step(f, Op::AddV, &[270, 276, 278], 1145);
                step(f, Op::AddV, &[278, 267, 281], 1146);
                step(f, Op::SubV, &[278, 267, 282], 1147);
                step(f, Op::LineTrace, &[281, 282, 102, 285, 286, 596], 1148);
                step(f, Op::BreakVector, &[285, 600, 601, 602], 1149);
                step(f, Op::BreakVector, &[278, 606, 607, 608], 1150);
                step(f, Op::SubF, &[602, 608, 610], 1151);
                step(f, Op::Select(ValueType::Float), &[102, 610, 845, 612], 1152);
                step(f, Op::MaxF, &[611, 612, 613], 1153);
                step(f, Op::ClampF, &[613, 845, 62, 614], 1154);
                step(f, Op::MakeVector, &[845, 845, 614, 287], 1155);
                step(f, Op::AddV, &[270, 287, 288], 1156);
                step(f, Op::MakeTransform, &[288, 40, 466, 61], 1157);
                step(f, Op::Select(ValueType::Transform), &[100, 61, 59, 62], 1158);
                step(f, Op::Copy(ValueType::Transform), &[62, 60], 1159);
                step(f, Op::Jump, &[1160], 1160)
            }
            1160 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 58, 60], 1161);
                1161
            }
            1161 => {
                step(f, Op::GreaterEqualF, &[496, 847, 89], 1162);
                step(f, Op::JumpIfFalse, &[89, 1236], 1163)
            }
            1163 => {
                step(f, Op::JumpIfFalse, &[88, 1165], 1164)
            }
            1164 => {
                step(f, Op::Jump, &[1217], 1165)
            }
            1165 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 58, 63], 1166);
                step(f, Op::BreakTransform, &[63, 289, 41, 290], 1167);
                step(f, Op::Equals(Elem::Int), &[58, 71, 90], 1168);
                step(f, Op::Select(ValueType::Int), &[90, 72, 71, 59], 1169);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 59, 42], 1170);
                step(f, Op::BreakTransform, &[42, 197, 29, 198], 1171);
                step(f, Op::MulF, &[14, 512, 513], 1172);
                step(f, Op::FootAvoidance, &[289, 197, 513, 90, 81, 199], 1173);
                step(f, Op::MakeTransform, &[199, 41, 466, 43], 1174);
                step(f, Op::Copy(ValueType::Transform), &[43, 44], 1175);
                step(f, Op::Copy(ValueType::Transform), &[115, 45], 1176);
                step(f, Op::BreakTransform, &[44, 200, 30, 201], 1177);
                step(f, Op::MakeVector, &[845, 845, 55, 202], 1178);
                step(f, Op::AddV, &[200, 202, 203], 1179);
                step(f, Op::SubV, &[200, 202, 204], 1180);
                step(f, Op::LineTrace, &[203, 204, 92, 205, 206, 514], 1181);
                step(f, Op::RotateVector, &[30, 468, 207], 1182);
                step(f, Op::FindQuatBetween, &[207, 206, 31], 1183);
                step(f, Op::MulQ, &[31, 30, 32], 1184);
                step(f, Op::MulF, &[53, 52, 515], 1185);
                step(f, Op::AddF, &[515, 63, 516], 1186);
                step(f, Op::NegF, &[516, 517], 1187);
                step(f, Op::MakeVector, &[845, 517, 845, 208], 1188);
                step(f, Op::RotateVector, &[32, 208, 210], 1189);
                step(f, Op::AddV, &[205, 210, 212], 1190);
                step(f, Op::AddV, &[212, 202, 214], 1191);
                step(f, Op::SubV, &[212, 202, 215], 1192);
                step(f, Op::LineTrace, &[214, 215, 93, 218, 219, 519], 1193);
                step(f, Op::BreakVector, &[218, 521, 522, 523], 1194);
                step(f, Op::BreakVector, &[212, 527, 528, 529], 1195);
                step(f, Op::SubF, &[523, 529, 533], 1196);
                step(f, Op::Select(ValueType::Float), &[93, 533, 845, 535], 1197);
                step(f, Op::AddF, &[59, 63, 518], 1198);
                step(f, Op::MakeVector, &[845, 518, 845, 209], 1199);
                step(f, Op::RotateVector, &[32, 209, 211], 1200);
                step(f, Op::AddV, &[205, 211, 213], 1201);
                step(f, Op::AddV, &[213, 202, 216], 1202);
                step(f, Op::SubV, &[213, 202, 217], 1203);
                step(f, Op::LineTrace, &[216, 217, 94, 220, 221, 520], 1204);
                step(f, Op::BreakVector, &[220, 524, 525, 526], 1205);
                step(f, Op::BreakVector, &[213, 530, 531, 532], 1206);
                step(f, Op::SubF, &[526, 532, 534], 1207);
                step(f, Op::Select(ValueType::Float), &[94, 534, 845, 536], 1208);
                step(f, Op::MaxF, &[535, 536, 537], 1209);
                step(f, Op::ClampF, &[537, 845, 62, 538], 1210);
                step(f, Op::MakeVector, &[845, 845, 538, 222], 1211);
                step(f, Op::AddV, &[205, 222, 223], 1212);
                step(f, Op::MakeTransform, &[223, 32, 466, 46], 1213);
                step(f, Op::Select(ValueType::Transform), &[92, 46, 44, 47], 1214);
                step(f, Op::Copy(ValueType::Transform), &[47, 45], 1215);
                step(f, Op::Jump, &[1216], 1216)
            }
            1216 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 58, 45], 1217);
                1217
            }
            1217 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 58, 39], 1218);
                step(f, Op::BreakTransform, &[39, 188, 27, 189], 1219);
                step(f, Op::SubV, &[188, 185, 190], 1220);
                step(f, Op::LengthV, &[190, 499], 1221);
                step(f, Op::SubF, &[64, 65, 500], 1222);
                step(f, Op::SubF, &[499, 500, 501], 1223);
                step(f, Op::MulF, &[65, 850, 502], 1224);
                step(f, Op::ClampF, &[501, 845, 502, 503], 1225);
                step(f, Op::MulF, &[503, 503, 504], 1226);
                step(f, Op::MulF, &[65, 861, 505], 1227);
                step(f, Op::DivF, &[504, 505, 506], 1228);
                step(f, Op::SubF, &[499, 506, 507], 1229);
                step(f, Op::DivF, &[507, 499, 508], 1230);
                step(f, Op::ScaleV, &[190, 508, 191], 1231);
                step(f, Op::AddV, &[185, 191, 192], 1232);
                step(f, Op::MakeTransform, &[192, 27, 466, 40], 1233);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 58, 40], 1234);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 58, 40], 1235);
                step(f, Op::Jump, &[1376], 1236)
            }
            1236 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 58, 39], 1237);
                step(f, Op::BreakTransform, &[39, 188, 27, 189], 1238);
                step(f, Op::SubV, &[188, 185, 190], 1239);
                step(f, Op::LengthV, &[190, 499], 1240);
                step(f, Op::SubF, &[64, 65, 500], 1241);
                step(f, Op::SubF, &[499, 500, 501], 1242);
                step(f, Op::MulF, &[65, 850, 502], 1243);
                step(f, Op::ClampF, &[501, 845, 502, 503], 1244);
                step(f, Op::MulF, &[503, 503, 504], 1245);
                step(f, Op::MulF, &[65, 861, 505], 1246);
                step(f, Op::DivF, &[504, 505, 506], 1247);
                step(f, Op::SubF, &[499, 506, 507], 1248);
                step(f, Op::DivF, &[507, 499, 508], 1249);
                step(f, Op::ScaleV, &[190, 508, 191], 1250);
                step(f, Op::AddV, &[185, 191, 192], 1251);
                step(f, Op::MakeTransform, &[192, 27, 466, 40], 1252);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 58, 63], 1253);
                step(f, Op::ClampF, &[496, 845, 847, 615], 1254);
                step(f, Op::Copy(ValueType::Transform), &[40, 69], 1255);
                step(f, Op::Copy(ValueType::Transform), &[63, 70], 1256);
                step(f, Op::Copy(ValueType::Float), &[615, 635], 1257);
                step(f, Op::Copy(ValueType::Transform), &[115, 71], 1258);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[6, 5], 1259);
                step(f, Op::ArrayReset(Elem::Vec3), &[5], 1260);
                step(f, Op::BreakTransform, &[69, 310, 46, 311], 1261);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 310], 1262);
                step(f, Op::UnitV, &[2, 309], 1263);
                step(f, Op::LengthV, &[2, 636], 1264);
                step(f, Op::RemapF, &[636, 845, 66, 845, 67, 122, 637], 1265);
                step(f, Op::ScaleV, &[309, 637, 314], 1266);
                step(f, Op::SubV, &[310, 314, 320], 1267);
                step(f, Op::MakeVector, &[845, 845, 69, 318], 1268);
                step(f, Op::AddV, &[320, 318, 322], 1269);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 322], 1270);
                step(f, Op::RemapF, &[636, 845, 66, 845, 71, 122, 639], 1271);
                step(f, Op::MakeVector, &[845, 845, 639, 316], 1272);
                step(f, Op::AddV, &[322, 316, 326], 1273);
                step(f, Op::BreakTransform, &[70, 312, 47, 313], 1274);
                step(f, Op::BreakVector, &[312, 644, 645, 646], 1275);
                step(f, Op::BreakVector, &[310, 641, 642, 643], 1276);
                step(f, Op::SubF, &[646, 643, 647], 1277);
                step(f, Op::MaxF, &[647, 845, 649], 1278);
                step(f, Op::MulF, &[649, 73, 653], 1279);
                step(f, Op::MinF, &[653, 74, 654], 1280);
                step(f, Op::AbsF, &[647, 651], 1281);
                step(f, Op::RemapF, &[651, 845, 77, 845, 76, 122, 652], 1282);
                step(f, Op::AddF, &[654, 652, 656], 1283);
                step(f, Op::MakeVector, &[845, 845, 656, 324], 1284);
                step(f, Op::AddV, &[326, 324, 328], 1285);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 328], 1286);
                step(f, Op::RemapF, &[636, 845, 66, 845, 68, 122, 638], 1287);
                step(f, Op::ScaleV, &[309, 638, 315], 1288);
                step(f, Op::AddV, &[312, 315, 321], 1289);
                step(f, Op::MakeVector, &[845, 845, 70, 319], 1290);
                step(f, Op::AddV, &[321, 319, 323], 1291);
                step(f, Op::RemapF, &[636, 845, 66, 845, 72, 122, 640], 1292);
                step(f, Op::MakeVector, &[845, 845, 640, 317], 1293);
                step(f, Op::AddV, &[323, 317, 327], 1294);
                step(f, Op::NegF, &[647, 648], 1295);
                step(f, Op::MaxF, &[648, 845, 650], 1296);
                step(f, Op::MulF, &[650, 75, 655], 1297);
                step(f, Op::AddF, &[655, 652, 657], 1298);
                step(f, Op::MakeVector, &[845, 845, 657, 325], 1299);
                step(f, Op::AddV, &[327, 325, 329], 1300);
                step(f, Op::LerpV, &[328, 329, 846, 330], 1301);
                step(f, Op::GetTransform, &[36, 71, 122, 72], 1302);
                step(f, Op::BreakTransform, &[72, 331, 48, 332], 1303);
                step(f, Op::BreakVector, &[331, 667, 668, 669], 1304);
                step(f, Op::SubF, &[847, 15, 661], 1305);
                step(f, Op::MulF, &[78, 661, 662], 1306);
                step(f, Op::MulF, &[14, 662, 663], 1307);
                step(f, Op::QuatFromAxisAngle, &[468, 663, 49], 1308);
                step(f, Op::SubV, &[330, 331, 333], 1309);
                step(f, Op::BreakVector, &[333, 658, 659, 660], 1310);
                step(f, Op::MakeVector, &[658, 659, 845, 334], 1311);
                step(f, Op::RotateVector, &[49, 334, 335], 1312);
                step(f, Op::BreakVector, &[335, 664, 665, 666], 1313);
                step(f, Op::AddF, &[667, 664, 673], 1314);
                step(f, Op::AddF, &[668, 665, 674], 1315);
                step(f, Op::BreakVector, &[330, 670, 671, 672], 1316);
                step(f, Op::MakeVector, &[673, 674, 672, 336], 1317);
                step(f, Op::DistanceV, &[310, 312, 675], 1318);
                step(f, Op::RemapF, &[675, 850, 862, 845, 847, 122, 676], 1319);
                step(f, Op::LerpV, &[330, 336, 676, 337], 1320);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 337], 1321);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 329], 1322);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 323], 1323);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 312], 1324);
                step(f, Op::JumpIfFalse, &[8, 1327], 1325)
            }
            1325 => {
                step(f, Op::DrawSpline, &[5, 71, 74, 846, 471], 1326);
                step(f, Op::Jump, &[1327], 1327)
            }
            1327 => {
                step(f, Op::Spline, &[5, 635, 71, 338, 339], 1328);
                step(f, Op::SlerpQ, &[46, 47, 635, 50], 1329);
                step(f, Op::MulF, &[635, 855, 678], 1330);
                step(f, Op::SinF, &[678, 679], 1331);
                step(f, Op::SmoothStepF, &[635, 845, 90, 677], 1332);
                step(f, Op::MulF, &[679, 677, 680], 1333);
                step(f, Op::MulF, &[680, 79, 681], 1334);
                step(f, Op::SlerpQ, &[50, 92, 681, 51], 1335);
                step(f, Op::MakeTransform, &[338, 51, 466, 73], 1336);
                step(f, Op::Copy(ValueType::Transform), &[73, 71], 1337);
                step(f, Op::Jump, &[1338], 1338)
            }
            1338 => {
                step(f, Op::BreakTransform, &[71, 291, 42, 292], 1339);
                step(f, Op::Equals(Elem::Int), &[58, 71, 90], 1340);
                step(f, Op::Select(ValueType::Int), &[90, 72, 71, 59], 1341);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 59, 42], 1342);
                step(f, Op::BreakTransform, &[42, 197, 29, 198], 1343);
                step(f, Op::SubF, &[847, 15, 512], 1344);
                step(f, Op::MulF, &[14, 512, 513], 1345);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 59, 103], 1346);
                step(f, Op::Select(ValueType::Float), &[103, 82, 845, 618], 1347);
                step(f, Op::ArrayAt(Elem::Float), &[2, 58, 496], 1348);
                step(f, Op::ClampF, &[496, 845, 847, 615], 1349);
                step(f, Op::MulF, &[615, 855, 616], 1350);
                step(f, Op::SinF, &[616, 617], 1351);
                step(f, Op::MulF, &[617, 617, 619], 1352);
                step(f, Op::MulF, &[618, 619, 620], 1353);
                step(f, Op::AddF, &[81, 620, 621], 1354);
                step(f, Op::FootAvoidance, &[291, 197, 513, 90, 621, 293], 1355);
                step(f, Op::SubV, &[293, 291, 294], 1356);
                step(f, Op::LengthV, &[294, 622], 1357);
                step(f, Op::AddF, &[622, 620, 623], 1358);
                step(f, Op::DivF, &[622, 623, 624], 1359);
                step(f, Op::LessEqualF, &[83, 845, 104], 1360);
                step(f, Op::SmoothStepF, &[615, 845, 83, 625], 1361);
                step(f, Op::Select(ValueType::Float), &[104, 847, 625, 626], 1362);
                step(f, Op::MulF, &[624, 626, 627], 1363);
                step(f, Op::ScaleV, &[294, 627, 295], 1364);
                step(f, Op::AddV, &[291, 295, 296], 1365);
                step(f, Op::MulF, &[3, 126, 628], 1366);
                step(f, Op::MulF, &[628, 619, 629], 1367);
                step(f, Op::MakeVector, &[845, 845, 629, 297], 1368);
                step(f, Op::AddV, &[296, 297, 298], 1369);
                step(f, Op::MakeTransform, &[298, 42, 466, 64], 1370);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 58, 64], 1371);
                step(f, Op::ScaleV, &[294, 624, 299], 1372);
                step(f, Op::AddV, &[291, 299, 300], 1373);
                step(f, Op::AddV, &[300, 297, 301], 1374);
                step(f, Op::MakeTransform, &[301, 42, 466, 65], 1375);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 58, 65], 1376);
                1376
            }
            1376 => {
                step(f, Op::GreaterF, &[21, 845, 91], 1377);
                step(f, Op::JumpIfFalse, &[91, 1401], 1378)
            }
            1378 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 58, 66], 1379);
                step(f, Op::BreakTransform, &[66, 302, 43, 303], 1380);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 58, 67], 1381);
                step(f, Op::BreakTransform, &[67, 304, 44, 305], 1382);
                step(f, Op::MulF, &[21, 21, 630], 1383);
                step(f, Op::LerpV, &[302, 304, 630, 306], 1384);
                step(f, Op::SubF, &[847, 21, 631], 1385);
                step(f, Op::MulF, &[21, 631, 632], 1386);
                step(f, Op::MulF, &[128, 850, 633], 1387);
                step(f, Op::MulF, &[632, 633, 634], 1388);
                step(f, Op::MakeVector, &[845, 845, 634, 307], 1389);
                step(f, Op::AddV, &[306, 307, 308], 1390);
                step(f, Op::SlerpQ, &[43, 44, 21, 45], 1391);
                step(f, Op::MakeTransform, &[308, 45, 466, 68], 1392);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 58, 68], 1393);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 58, 66], 1394);
                step(f, Op::BreakTransform, &[66, 302, 43, 303], 1395);
                step(f, Op::LerpV, &[302, 304, 630, 306], 1396);
                step(f, Op::AddV, &[306, 307, 308], 1397);
                step(f, Op::SlerpQ, &[43, 44, 21, 45], 1398);
                step(f, Op::MakeTransform, &[308, 45, 466, 68], 1399);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 58, 68], 1400);
                step(f, Op::Jump, &[1401], 1401)
            }
            1401 => {
                step(f, Op::GreaterEqualF, &[496, 847, 89], 1402);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 58, 89], 1403);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 58, 41], 1404);
                step(f, Op::BreakTransform, &[41, 193, 28, 194], 1405);
                step(f, Op::SubF, &[847, 496, 509], 1406);
                step(f, Op::MulF, &[10, 7, 510], 1407);
                step(f, Op::MulF, &[509, 510, 511], 1408);
                step(f, Op::ScaleV, &[2, 511, 195], 1409);
                step(f, Op::AddV, &[193, 195, 196], 1410);
                step(f, Op::MakeTransform, &[196, 92, 466, 57], 1411);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 58, 57], 1412);
                step(f, Op::Copy(ValueType::Bone), &[0, 17], 1413);
                step(f, Op::Copy(ValueType::Int), &[3, 60], 1414);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 60, 74], 1415);
                step(f, Op::BreakTransform, &[74, 340, 52, 341], 1416);
                step(f, Op::MakeVector, &[845, 845, 50, 350], 1417);
                step(f, Op::AddV, &[340, 350, 351], 1418);
                step(f, Op::GetTransform, &[17, 71, 122, 76], 1419);
                step(f, Op::BreakTransform, &[76, 345, 54, 346], 1420);
                step(f, Op::MakeTransform, &[351, 54, 466, 78], 1421);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 60, 20], 1422);
                step(f, Op::GetTransform, &[20, 71, 122, 77], 1423);
                step(f, Op::BreakTransform, &[77, 347, 55, 348], 1424);
                step(f, Op::SubV, &[347, 345, 349], 1425);
                step(f, Op::AddV, &[351, 349, 352], 1426);
                step(f, Op::FootPivots, &[351, 352, 52, 51, 50, 53, 353, 354, 355], 1427);
                step(f, Op::GetParent, &[17, 18], 1428);
                step(f, Op::GetParent, &[18, 19], 1429);
                step(f, Op::GetTransform, &[19, 71, 123, 75], 1430);
                step(f, Op::BreakTransform, &[75, 342, 53, 343], 1431);
                step(f, Op::SubV, &[340, 342, 344], 1432);
                step(f, Op::DotV, &[344, 470, 682], 1433);
                step(f, Op::RemapF, &[682, 85, 84, 86, 845, 122, 685], 1434);
                step(f, Op::LengthV, &[2, 683], 1435);
                step(f, Op::RemapF, &[683, 845, 96, 845, 847, 122, 684], 1436);
                step(f, Op::MulF, &[685, 684, 686], 1437);
                step(f, Op::QuatFromAxisAngle, &[472, 686, 56], 1438);
                step(f, Op::RotateAroundPoint, &[78, 353, 56, 79], 1439);
                step(f, Op::ArrayAt(Elem::Float), &[2, 60, 687], 1440);
                step(f, Op::SmoothStepF, &[687, 845, 90, 689], 1441);
                step(f, Op::SubF, &[847, 687, 688], 1442);
                step(f, Op::SmoothStepF, &[688, 845, 90, 690], 1443);
                step(f, Op::MulF, &[689, 690, 691], 1444);
                step(f, Op::LerpF, &[89, 847, 691, 692], 1445);
                step(f, Op::MulF, &[686, 692, 693], 1446);
                step(f, Op::QuatFromAxisAngle, &[472, 693, 57], 1447);
                step(f, Op::SubV, &[354, 353, 356], 1448);
                step(f, Op::RotateVector, &[57, 356, 357], 1449);
                step(f, Op::AddV, &[353, 357, 358], 1450);
                step(f, Op::RemapF, &[682, 87, 85, 88, 845, 122, 694], 1451);
                step(f, Op::MulF, &[694, 684, 695], 1452);
                step(f, Op::QuatFromAxisAngle, &[472, 695, 58], 1453);
                step(f, Op::RotateAroundPoint, &[79, 358, 58, 80], 1454);
                step(f, Op::RemapF, &[682, 91, 92, 845, 93, 122, 696], 1455);
                step(f, Op::RotateVector, &[52, 468, 359], 1456);
                step(f, Op::BreakVector, &[359, 697, 698, 699], 1457);
                step(f, Op::CosF, &[95, 701], 1458);
                step(f, Op::CosF, &[94, 700], 1459);
                step(f, Op::RemapF, &[699, 701, 700, 845, 847, 122, 702], 1460);
                step(f, Op::MulF, &[684, 702, 703], 1461);
                step(f, Op::MulF, &[696, 703, 704], 1462);
                step(f, Op::QuatFromAxisAngle, &[472, 704, 59], 1463);
                step(f, Op::RotateAroundPoint, &[80, 355, 59, 81], 1464);
                step(f, Op::SubF, &[847, 15, 705], 1465);
                step(f, Op::MulF, &[14, 705, 706], 1466);
                step(f, Op::LimitRotationAroundZ, &[52, 706, 97, 60], 1467);
                step(f, Op::RotateAroundPoint, &[81, 340, 60, 82], 1468);
                step(f, Op::ArraySetAt(Elem::Transform), &[7, 60, 82], 1469);
                step(f, Op::JumpIfFalse, &[8, 1475], 1470)
            }
            1470 => {
                step(f, Op::DrawPoint, &[355, 863, 472], 1471);
                step(f, Op::DrawPoint, &[353, 863, 470], 1472);
                step(f, Op::DrawPoint, &[358, 863, 468], 1473);
                step(f, Op::DrawTransform, &[74, 862, 846], 1474);
                step(f, Op::Jump, &[1475], 1475)
            }
            1475 => {
                step(f, Op::Jump, &[631], 1476)
            }
            1476 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1477);
                step(f, Op::Copy(ValueType::Int), &[71, 5], 1478);
                1478
            }
            1478 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 5, 1, 6, 7, 1520], 1479)
            }
            1479 => {
                step(f, Op::Copy(ValueType::Bone), &[1, 21], 1480);
                step(f, Op::Copy(ValueType::Int), &[6, 61], 1481);
                step(f, Op::GetParent, &[21, 22], 1482);
                step(f, Op::GetParent, &[22, 23], 1483);
                step(f, Op::GetParent, &[23, 24], 1484);
                step(f, Op::GetTransform, &[24, 71, 123, 83], 1485);
                step(f, Op::BreakTransform, &[83, 360, 61, 361], 1486);
                step(f, Op::LengthV, &[1, 708], 1487);
                step(f, Op::ClavicleOffset, &[12, 708, 102, 105, 709], 1488);
                step(f, Op::MakeVector, &[845, 845, 709, 362], 1489);
                step(f, Op::AddV, &[360, 362, 363], 1490);
                step(f, Op::MakeTransform, &[363, 61, 466, 84], 1491);
                step(f, Op::SetTransform, &[24, 84, 71, 122, 847], 1492);
                step(f, Op::GetTransform, &[21, 71, 123, 85], 1493);
                step(f, Op::GetTransform, &[23, 71, 123, 86], 1494);
                step(f, Op::BreakTransform, &[86, 364, 63, 365], 1495);
                step(f, Op::Equals(Elem::Int), &[61, 71, 105], 1496);
                step(f, Op::Select(ValueType::Int), &[105, 72, 71, 62], 1497);
                step(f, Op::ArrayAt(Elem::Float), &[0, 62, 707], 1498);
                step(f, Op::ArmSwingRotation, &[707, 1, 0, 103, 854, 864, 847, 102, 100, 101, 854, 854, 847, 710], 1499);
                step(f, Op::QuatFromAxisAngle, &[472, 710, 62], 1500);
                step(f, Op::RotateAroundPoint, &[85, 364, 62, 87], 1501);
                step(f, Op::BreakTransform, &[87, 366, 64, 367], 1502);
                step(f, Op::RemapF, &[708, 845, 102, 845, 104, 122, 711], 1503);
                step(f, Op::MakeVector, &[845, 845, 711, 368], 1504);
                step(f, Op::AddV, &[366, 368, 369], 1505);
                step(f, Op::MakeTransform, &[369, 64, 466, 88], 1506);
                step(f, Op::Select(ValueType::Vec3), &[105, 473, 472, 371], 1507);
                step(f, Op::Select(ValueType::Vec3), &[105, 470, 474, 372], 1508);
                step(f, Op::ArrayAt(Elem::Vec3), &[4, 61, 370], 1509);
                step(f, Op::TwoBoneIK, &[23, 22, 21, 88, 371, 372, 370, 71, 847, 123, 865, 866, 122, 106, 712], 1510);
                step(f, Op::JumpIfFalse, &[8, 1519], 1511)
            }
            1511 => {
                step(f, Op::GetTransform, &[23, 71, 123, 86], 1512);
                step(f, Op::BreakTransform, &[86, 364, 63, 365], 1513);
                step(f, Op::GetTransform, &[21, 71, 123, 85], 1514);
                step(f, Op::RotateAroundPoint, &[85, 364, 62, 87], 1515);
                step(f, Op::BreakTransform, &[87, 366, 64, 367], 1516);
                step(f, Op::AddV, &[366, 368, 369], 1517);
                step(f, Op::DrawLine, &[364, 369, 846, 470], 1518);
                step(f, Op::Jump, &[1519], 1519)
            }
            1519 => {
                step(f, Op::Jump, &[1478], 1520)
            }
            1520 => {
                step(f, Op::NegF, &[3, 823], 1521);
                step(f, Op::MakeVector, &[845, 845, 823, 447], 1522);
                step(f, Op::MakeTransform, &[447, 92, 466, 109], 1523);
                step(f, Op::SetTransform, &[37, 109, 71, 122, 847], 1524);
                step(f, Op::Copy(ValueType::Float), &[845, 715], 1525);
                step(f, Op::Copy(ValueType::Float), &[852, 716], 1526);
                step(f, Op::Copy(ValueType::Bool), &[123, 107], 1527);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 11], 1528);
                step(f, Op::Copy(ValueType::Int), &[71, 63], 1529);
                step(f, Op::MakeVector, &[845, 845, 55, 375], 1530);
                1530
            }
            1530 => {
                step(f, Op::ForEachNext(Elem::Transform), &[11, 63, 89, 64, 65, 1543], 1531)
            }
            1531 => {
                step(f, Op::BreakTransform, &[89, 373, 65, 374], 1532);
                step(f, Op::AddV, &[373, 375, 376], 1533);
                step(f, Op::SubV, &[373, 375, 377], 1534);
                step(f, Op::SphereTrace, &[376, 377, 54, 108, 378, 379, 717], 1535);
                step(f, Op::BreakVector, &[378, 718, 719, 720], 1536);
                step(f, Op::LessF, &[720, 716, 109], 1537);
                step(f, Op::And, &[108, 109, 110], 1538);
                step(f, Op::JumpIfFalse, &[110, 1542], 1539)
            }
            1539 => {
                step(f, Op::Copy(ValueType::Float), &[720, 716], 1540);
                step(f, Op::Copy(ValueType::Bool), &[122, 107], 1541);
                step(f, Op::Jump, &[1542], 1542)
            }
            1542 => {
                step(f, Op::Jump, &[1530], 1543)
            }
            1543 => {
                step(f, Op::Select(ValueType::Float), &[107, 716, 845, 721], 1544);
                step(f, Op::ClampF, &[721, 60, 61, 722], 1545);
                step(f, Op::Copy(ValueType::Float), &[722, 715], 1546);
                step(f, Op::Jump, &[1547], 1547)
            }
            1547 => {
                step(f, Op::SubF, &[847, 21, 714], 1548);
                step(f, Op::MulF, &[715, 714, 723], 1549);
                step(f, Op::SubF, &[847, 125, 724], 1550);
                step(f, Op::MulF, &[3, 724, 725], 1551);
                step(f, Op::AddF, &[723, 725, 726], 1552);
                step(f, Op::MakeVector, &[16, 845, 845, 380], 1553);
                step(f, Op::MakeVector, &[726, 845, 845, 381], 1554);
                step(f, Op::Select(ValueType::Float), &[2, 726, 17, 727], 1555);
                step(f, Op::MakeVector, &[727, 845, 845, 382], 1556);
                step(f, Op::Copy(ValueType::Vec3), &[380, 383], 1557);
                step(f, Op::Copy(ValueType::Vec3), &[381, 384], 1558);
                step(f, Op::Copy(ValueType::Vec3), &[382, 385], 1559);
                step(f, Op::Copy(ValueType::Float), &[48, 728], 1560);
                step(f, Op::Copy(ValueType::Float), &[49, 729], 1561);
                step(f, Op::Copy(ValueType::Vec3), &[465, 386], 1562);
                step(f, Op::SubV, &[384, 385, 387], 1563);
                step(f, Op::DeltaTime, &[730], 1564);
                step(f, Op::DivF, &[729, 730, 731], 1565);
                step(f, Op::ScaleV, &[387, 731, 388], 1566);
                step(f, Op::AddV, &[384, 388, 389], 1567);
                step(f, Op::AddV, &[385, 388, 390], 1568);
                step(f, Op::SubV, &[383, 390, 391], 1569);
                step(f, Op::FloatLerp, &[845, 847, 728, 732], 1570);
                step(f, Op::SubF, &[847, 732, 733], 1571);
                step(f, Op::ScaleV, &[391, 733, 392], 1572);
                step(f, Op::AddV, &[389, 392, 394], 1573);
                step(f, Op::MulF, &[728, 730, 734], 1574);
                step(f, Op::GreaterF, &[734, 845, 111], 1575);
                step(f, Op::DivF, &[732, 734, 735], 1576);
                step(f, Op::Select(ValueType::Float), &[111, 735, 847, 736], 1577);
                step(f, Op::ScaleV, &[387, 736, 393], 1578);
                step(f, Op::SubV, &[394, 393, 395], 1579);
                step(f, Op::Copy(ValueType::Vec3), &[395, 386], 1580);
                step(f, Op::Jump, &[1581], 1581)
            }
            1581 => {
                step(f, Op::BreakVector, &[386, 737, 738, 739], 1582);
                step(f, Op::Select(ValueType::Float), &[1, 726, 737, 740], 1583);
                step(f, Op::Copy(ValueType::Float), &[740, 16], 1584);
                step(f, Op::Copy(ValueType::Float), &[726, 17], 1585);
                step(f, Op::GetTransform, &[38, 71, 122, 94], 1586);
                step(f, Op::BreakTransform, &[94, 408, 72, 409], 1587);
                step(f, Op::PelvisLean, &[1, 108, 113, 114, 758, 759], 1588);
                step(f, Op::LengthV, &[2, 713], 1589);
                step(f, Op::RemapF, &[713, 845, 108, 845, 106, 122, 741], 1590);
                step(f, Op::MulF, &[15, 107, 744], 1591);
                step(f, Op::SubF, &[847, 744, 745], 1592);
                step(f, Op::MulF, &[741, 745, 746], 1593);
                step(f, Op::MulF, &[12, 867, 742], 1594);
                step(f, Op::SinF, &[742, 743], 1595);
                step(f, Op::MulF, &[746, 743, 747], 1596);
                step(f, Op::MulF, &[747, 714, 748], 1597);
                step(f, Op::AddF, &[748, 16, 749], 1598);
                step(f, Op::SubF, &[749, 3, 750], 1599);
                step(f, Op::MakeVector, &[845, 759, 750, 410], 1600);
                step(f, Op::AddV, &[408, 410, 411], 1601);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 71, 90], 1602);
                step(f, Op::BreakTransform, &[90, 396, 66, 397], 1603);
                step(f, Op::BreakVector, &[396, 760, 761, 762], 1604);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 72, 91], 1605);
                step(f, Op::BreakTransform, &[91, 398, 67, 399], 1606);
                step(f, Op::BreakVector, &[398, 763, 764, 765], 1607);
                step(f, Op::SubF, &[762, 765, 766], 1608);
                step(f, Op::PelvisSideLean, &[766, 115, 116, 767], 1609);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 71, 92], 1610);
                step(f, Op::BreakTransform, &[92, 402, 68, 403], 1611);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 72, 93], 1612);
                step(f, Op::BreakTransform, &[93, 404, 69, 405], 1613);
                step(f, Op::SlerpQ, &[68, 69, 846, 70], 1614);
                step(f, Op::EulerFromQuat, &[70, 71, 406], 1615);
                step(f, Op::BreakVector, &[406, 754, 755, 756], 1616);
                step(f, Op::RemapF, &[713, 109, 108, 845, 110, 122, 752], 1617);
                step(f, Op::SubV, &[396, 398, 400], 1618);
                step(f, Op::RotateVector, &[0, 470, 401], 1619);
                step(f, Op::DotV, &[400, 401, 751], 1620);
                step(f, Op::MulF, &[752, 751, 753], 1621);
                step(f, Op::AddF, &[756, 753, 757], 1622);
                step(f, Op::MakeVector, &[758, 767, 757, 407], 1623);
                step(f, Op::QuatFromEuler, &[407, 71, 71], 1624);
                step(f, Op::MakeTransform, &[411, 71, 466, 95], 1625);
                step(f, Op::SetTransform, &[39, 95, 71, 122, 847], 1626);
                step(f, Op::GetTransform, &[40, 72, 122, 96], 1627);
                step(f, Op::BreakTransform, &[96, 412, 76, 413], 1628);
                step(f, Op::QuatFromAxisAngle, &[468, 753, 73], 1629);
                step(f, Op::DivF, &[111, 863, 768], 1630);
                step(f, Op::QuatScale, &[73, 768, 74], 1631);
                step(f, Op::MulQ, &[76, 74, 80], 1632);
                step(f, Op::MakeTransform, &[412, 80, 466, 100], 1633);
                step(f, Op::SetTransform, &[41, 100, 72, 122, 847], 1634);
                step(f, Op::GetTransform, &[42, 72, 122, 97], 1635);
                step(f, Op::BreakTransform, &[97, 414, 77, 415], 1636);
                step(f, Op::MulQ, &[77, 74, 81], 1637);
                step(f, Op::MakeTransform, &[414, 81, 466, 101], 1638);
                step(f, Op::SetTransform, &[43, 101, 72, 122, 847], 1639);
                step(f, Op::GetTransform, &[44, 72, 122, 98], 1640);
                step(f, Op::BreakTransform, &[98, 416, 78, 417], 1641);
                step(f, Op::MulQ, &[78, 74, 82], 1642);
                step(f, Op::MakeTransform, &[416, 82, 466, 102], 1643);
                step(f, Op::SetTransform, &[45, 102, 72, 122, 847], 1644);
                step(f, Op::GetTransform, &[46, 72, 122, 99], 1645);
                step(f, Op::BreakTransform, &[99, 418, 79, 419], 1646);
                step(f, Op::QuatScale, &[73, 112, 75], 1647);
                step(f, Op::MulQ, &[79, 75, 83], 1648);
                step(f, Op::MakeTransform, &[418, 83, 466, 103], 1649);
                step(f, Op::SetTransform, &[47, 103, 72, 122, 847], 1650);
                step(f, Op::Or, &[1, 2, 117], 1651);
                step(f, Op::Copy(ValueType::Float), &[845, 769], 1652);
                step(f, Op::Copy(ValueType::Float), &[845, 770], 1653);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1654);
                step(f, Op::Copy(ValueType::Int), &[71, 66], 1655);
                1655
            }
            1655 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 66, 25, 67, 68, 1702], 1656)
            }
            1656 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 67, 112], 1657);
                step(f, Op::GetParent, &[25, 26], 1658);
                step(f, Op::GetParent, &[26, 27], 1659);
                step(f, Op::GetTransform, &[27, 71, 123, 104], 1660);
                step(f, Op::BreakTransform, &[104, 420, 84, 421], 1661);
                step(f, Op::BreakVector, &[420, 771, 772, 773], 1662);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 67, 105], 1663);
                step(f, Op::BreakTransform, &[105, 422, 85, 423], 1664);
                step(f, Op::BreakVector, &[422, 774, 775, 776], 1665);
                step(f, Op::ArrayAt(Elem::Float), &[1, 67, 780], 1666);
                step(f, Op::MulF, &[780, 117, 781], 1667);
                step(f, Op::MulF, &[781, 781, 782], 1668);
                step(f, Op::SubF, &[771, 774, 777], 1669);
                step(f, Op::SubF, &[772, 775, 778], 1670);
                step(f, Op::MakeVector, &[777, 778, 845, 424], 1671);
                step(f, Op::DotV, &[424, 424, 779], 1672);
                step(f, Op::SubF, &[782, 779, 783], 1673);
                step(f, Op::SqrtF, &[783, 784], 1674);
                step(f, Op::AddF, &[776, 784, 785], 1675);
                step(f, Op::SubF, &[773, 785, 786], 1676);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 67, 106], 1677);
                step(f, Op::BreakTransform, &[106, 425, 86, 426], 1678);
                step(f, Op::BreakVector, &[425, 787, 788, 789], 1679);
                step(f, Op::AddF, &[789, 50, 790], 1680);
                step(f, Op::MinF, &[776, 790, 791], 1681);
                step(f, Op::AddF, &[791, 784, 792], 1682);
                step(f, Op::SubF, &[773, 792, 793], 1683);
                step(f, Op::Equals(Elem::Int), &[67, 71, 113], 1684);
                step(f, Op::Select(ValueType::Int), &[113, 72, 71, 69], 1685);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 69, 114], 1686);
                step(f, Op::ArrayAt(Elem::Float), &[2, 69, 797], 1687);
                step(f, Op::RemapF, &[797, 846, 847, 845, 847, 122, 798], 1688);
                step(f, Op::RemapF, &[797, 845, 120, 847, 845, 122, 799], 1689);
                step(f, Op::MaxF, &[798, 799, 800], 1690);
                step(f, Op::Select(ValueType::Float), &[114, 847, 800, 801], 1691);
                step(f, Op::LerpF, &[786, 793, 801, 802], 1692);
                step(f, Op::ArrayAt(Elem::Float), &[2, 67, 794], 1693);
                step(f, Op::RemapF, &[794, 846, 847, 845, 847, 122, 795], 1694);
                step(f, Op::MulF, &[802, 795, 803], 1695);
                step(f, Op::RemapF, &[794, 845, 120, 847, 845, 122, 796], 1696);
                step(f, Op::MulF, &[786, 796, 804], 1697);
                step(f, Op::MaxF, &[803, 804, 805], 1698);
                step(f, Op::Select(ValueType::Float), &[112, 786, 805, 806], 1699);
                step(f, Op::MaxF, &[770, 806, 807], 1700);
                step(f, Op::Copy(ValueType::Float), &[807, 770], 1701);
                step(f, Op::Jump, &[1655], 1702)
            }
            1702 => {
                step(f, Op::ClampF, &[770, 845, 118, 808], 1703);
                step(f, Op::Copy(ValueType::Float), &[808, 769], 1704);
                step(f, Op::Jump, &[1705], 1705)
            }
            1705 => {
                step(f, Op::MakeVector, &[18, 845, 845, 427], 1706);
                step(f, Op::MakeVector, &[769, 845, 845, 428], 1707);
                step(f, Op::MakeVector, &[19, 845, 845, 429], 1708);
                step(f, Op::GreaterF, &[769, 18, 115], 1709);
                step(f, Op::Select(ValueType::Float), &[115, 122, 119, 809], 1710);
                step(f, Op::Copy(ValueType::Vec3), &[427, 430], 1711);
                step(f, Op::Copy(ValueType::Vec3), &[428, 431], 1712);
                step(f, Op::Copy(ValueType::Vec3), &[429, 432], 1713);
                step(f, Op::Copy(ValueType::Float), &[809, 810], 1714);
                step(f, Op::Copy(ValueType::Float), &[49, 811], 1715);
                step(f, Op::Copy(ValueType::Vec3), &[465, 433], 1716);
                step(f, Op::SubV, &[431, 432, 434], 1717);
                step(f, Op::DeltaTime, &[812], 1718);
                step(f, Op::DivF, &[811, 812, 813], 1719);
                step(f, Op::ScaleV, &[434, 813, 435], 1720);
                step(f, Op::AddV, &[431, 435, 436], 1721);
                step(f, Op::AddV, &[432, 435, 437], 1722);
                step(f, Op::SubV, &[430, 437, 438], 1723);
                step(f, Op::FloatLerp, &[845, 847, 810, 814], 1724);
                step(f, Op::SubF, &[847, 814, 815], 1725);
                step(f, Op::ScaleV, &[438, 815, 439], 1726);
                step(f, Op::AddV, &[436, 439, 441], 1727);
                step(f, Op::MulF, &[810, 812, 816], 1728);
                step(f, Op::GreaterF, &[816, 845, 116], 1729);
                step(f, Op::DivF, &[814, 816, 817], 1730);
                step(f, Op::Select(ValueType::Float), &[116, 817, 847, 818], 1731);
                step(f, Op::ScaleV, &[434, 818, 440], 1732);
                step(f, Op::SubV, &[441, 440, 442], 1733);
                step(f, Op::Copy(ValueType::Vec3), &[442, 433], 1734);
                step(f, Op::Jump, &[1735], 1735)
            }
            1735 => {
                step(f, Op::BreakVector, &[433, 819, 820, 821], 1736);
                step(f, Op::Select(ValueType::Float), &[117, 769, 819, 822], 1737);
                step(f, Op::Copy(ValueType::Float), &[822, 18], 1738);
                step(f, Op::Copy(ValueType::Float), &[769, 19], 1739);
                step(f, Op::GetTransform, &[48, 71, 123, 107], 1740);
                step(f, Op::BreakTransform, &[107, 443, 87, 444], 1741);
                step(f, Op::MakeVector, &[845, 845, 18, 445], 1742);
                step(f, Op::SubV, &[443, 445, 446], 1743);
                step(f, Op::MakeTransform, &[446, 87, 466, 108], 1744);
                step(f, Op::SetTransform, &[49, 108, 71, 122, 847], 1745);
                step(f, Op::JumpIfFalse, &[8, 1752], 1746)
            }
            1746 => {
                step(f, Op::GetTransform, &[48, 71, 123, 107], 1747);
                step(f, Op::BreakTransform, &[107, 443, 87, 444], 1748);
                step(f, Op::SubV, &[443, 445, 446], 1749);
                step(f, Op::MakeTransform, &[446, 87, 466, 108], 1750);
                step(f, Op::DrawTransform, &[108, 868, 846], 1751);
                step(f, Op::Jump, &[1752], 1752)
            }
            1752 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1753);
                step(f, Op::Copy(ValueType::Int), &[71, 8], 1754);
                1754
            }
            1754 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 8, 2, 9, 10, 1805], 1755)
            }
            1755 => {
                step(f, Op::Copy(ValueType::Bone), &[2, 28], 1756);
                step(f, Op::Copy(ValueType::Int), &[9, 70], 1757);
                step(f, Op::GetParent, &[28, 29], 1758);
                step(f, Op::GetParent, &[29, 30], 1759);
                step(f, Op::GetTransform, &[30, 71, 123, 110], 1760);
                step(f, Op::BreakTransform, &[110, 448, 88, 449], 1761);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 70, 111], 1762);
                step(f, Op::BreakTransform, &[111, 450, 89, 451], 1763);
                step(f, Op::SubV, &[450, 448, 452], 1764);
                step(f, Op::LengthV, &[452, 835], 1765);
                step(f, Op::ArrayAt(Elem::Float), &[1, 70, 824], 1766);
                step(f, Op::MulF, &[824, 129, 825], 1767);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 70, 118], 1768);
                step(f, Op::ArrayAt(Elem::Float), &[2, 70, 826], 1769);
                step(f, Op::ClampF, &[826, 845, 847, 827], 1770);
                step(f, Op::LessF, &[827, 846, 119], 1771);
                step(f, Op::SmoothStepF, &[827, 131, 132, 830], 1772);
                step(f, Op::MulF, &[827, 855, 828], 1773);
                step(f, Op::SinF, &[828, 829], 1774);
                step(f, Op::MaxF, &[830, 829, 831], 1775);
                step(f, Op::Select(ValueType::Float), &[119, 831, 829, 832], 1776);
                step(f, Op::MulF, &[832, 130, 833], 1777);
                step(f, Op::Select(ValueType::Float), &[118, 845, 833, 834], 1778);
                step(f, Op::SubF, &[825, 834, 836], 1779);
                step(f, Op::SubF, &[835, 836, 837], 1780);
                step(f, Op::MaxF, &[837, 845, 838], 1781);
                step(f, Op::MulF, &[838, 838, 839], 1782);
                step(f, Op::AddF, &[838, 834, 840], 1783);
                step(f, Op::DivF, &[839, 840, 841], 1784);
                step(f, Op::SubF, &[835, 841, 842], 1785);
                step(f, Op::DivF, &[842, 835, 843], 1786);
                step(f, Op::ScaleV, &[452, 843, 453], 1787);
                step(f, Op::AddV, &[448, 453, 454], 1788);
                step(f, Op::ClampSpatially, &[454, 448, 845, 825, 455], 1789);
                step(f, Op::MakeTransform, &[455, 89, 466, 112], 1790);
                step(f, Op::Equals(Elem::Int), &[70, 71, 120], 1791);
                step(f, Op::Select(ValueType::Vec3), &[120, 473, 472, 460], 1792);
                step(f, Op::Select(ValueType::Vec3), &[120, 470, 474, 461], 1793);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 70, 113], 1794);
                step(f, Op::BreakTransform, &[113, 456, 90, 457], 1795);
                step(f, Op::ArrayAt(Elem::Vec3), &[3, 70, 458], 1796);
                step(f, Op::KneeVector, &[90, 0, 458, 133, 134, 459], 1797);
                step(f, Op::TwoBoneIK, &[30, 29, 28, 112, 460, 461, 459, 71, 847, 123, 865, 866, 122, 121, 844], 1798);
                step(f, Op::JumpIfFalse, &[8, 1804], 1799)
            }
            1799 => {
                step(f, Op::GetTransform, &[29, 71, 123, 114], 1800);
                step(f, Op::BreakTransform, &[114, 462, 91, 463], 1801);
                step(f, Op::AddV, &[462, 459, 464], 1802);
                step(f, Op::DrawLine, &[462, 464, 846, 475], 1803);
                step(f, Op::Jump, &[1804], 1804)
            }
            1804 => {
                step(f, Op::Jump, &[1754], 1805)
            }
            1805 => {
                step(f, Op::End, &[], 1806)
            }
            _ => return,
        } };
    }
}
