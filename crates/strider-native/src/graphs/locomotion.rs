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
    fingerprint: 0x1e548faabcffbc45,
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
                step(f, Op::LengthV, &[37, 142], 111);
                step(f, Op::GreaterF, &[142, 35, 10], 112);
                step(f, Op::Copy(ValueType::Bool), &[10, 2], 113);
                step(f, Op::MakeRelative, &[13, 12, 17], 114);
                step(f, Op::Select(ValueType::Transform), &[10, 115, 17, 18], 115);
                step(f, Op::Copy(ValueType::Transform), &[18, 2], 116);
                step(f, Op::InverseT, &[13, 15], 117);
                step(f, Op::MulT, &[12, 15, 16], 118);
                step(f, Op::Copy(ValueType::Transform), &[16, 1], 119);
                step(f, Op::TransformVector, &[2, 0, 42], 120);
                step(f, Op::InverseT, &[12, 14], 121);
                step(f, Op::DeltaTime, &[141], 122);
                step(f, Op::DivF, &[847, 141, 143], 123);
                step(f, Op::ScaleV, &[37, 143, 38], 124);
                step(f, Op::TransformVector, &[14, 38, 39], 125);
                step(f, Op::BreakVector, &[39, 144, 145, 146], 126);
                step(f, Op::MakeVector, &[144, 145, 845, 40], 127);
                step(f, Op::LengthV, &[40, 147], 128);
                step(f, Op::MulF, &[147, 123, 148], 129);
                step(f, Op::NegF, &[148, 149], 130);
                step(f, Op::ClampF, &[146, 149, 148, 150], 131);
                step(f, Op::MakeVector, &[144, 145, 150, 41], 132);
                step(f, Op::Select(ValueType::Vec3), &[2, 42, 41, 44], 133);
                step(f, Op::VectorLerp, &[42, 44, 36, 845, 45], 134);
                step(f, Op::Copy(ValueType::Vec3), &[45, 0], 135);
                step(f, Op::TransformVector, &[2, 1, 43], 136);
                step(f, Op::TransformVector, &[2, 0, 42], 137);
                step(f, Op::Select(ValueType::Vec3), &[2, 42, 41, 44], 138);
                step(f, Op::VectorLerp, &[43, 44, 37, 845, 46], 139);
                step(f, Op::Copy(ValueType::Vec3), &[46, 1], 140);
                step(f, Op::LengthV, &[44, 157], 141);
                step(f, Op::Copy(ValueType::Float), &[157, 0], 142);
                step(f, Op::BreakVector, &[37, 151, 152, 153], 143);
                step(f, Op::MulF, &[150, 141, 154], 144);
                step(f, Op::SubF, &[153, 154, 155], 145);
                step(f, Op::Select(ValueType::Float), &[10, 845, 155, 156], 146);
                step(f, Op::Copy(ValueType::Float), &[156, 1], 147);
                step(f, Op::JumpIfFalse, &[2, 162], 148)
            }
            148 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 12], 149);
                step(f, Op::Copy(ValueType::Int), &[71, 17], 150);
                150
            }
            150 => {
                step(f, Op::ForEachNext(Elem::Bone), &[12, 17, 13, 18, 19, 160], 151)
            }
            151 => {
                step(f, Op::ArrayAt(Elem::Transform), &[8, 18, 20], 152);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 18, 20], 153);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 18, 20], 154);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 18, 20], 155);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 18, 20], 156);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 18, 20], 157);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 18, 20], 158);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 18, 20], 159);
                step(f, Op::Jump, &[150], 160)
            }
            160 => {
                step(f, Op::Copy(ValueType::Float), &[845, 16], 161);
                step(f, Op::Jump, &[162], 162)
            }
            162 => {
                step(f, Op::Copy(ValueType::Transform), &[12, 0], 163);
                step(f, Op::Copy(ValueType::Bool), &[122, 0], 164);
                step(f, Op::JumpIfFalse, &[8, 171], 165)
            }
            165 => {
                step(f, Op::GetTransform, &[33, 71, 122, 19], 166);
                step(f, Op::BreakTransform, &[19, 47, 9, 48], 167);
                step(f, Op::ScaleV, &[0, 848, 49], 168);
                step(f, Op::AddV, &[47, 49, 50], 169);
                step(f, Op::DrawArrow, &[47, 50, 846, 467], 170);
                step(f, Op::Jump, &[171], 171)
            }
            171 => {
                step(f, Op::Copy(ValueType::Float), &[845, 158], 172);
                step(f, Op::Copy(ValueType::Float), &[847, 159], 173);
                step(f, Op::Copy(ValueType::Bool), &[123, 12], 174);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[8, 9], 175);
                step(f, Op::Copy(ValueType::Int), &[71, 25], 176);
                step(f, Op::MakeVector, &[845, 845, 55, 55], 177);
                177
            }
            177 => {
                step(f, Op::ForEachNext(Elem::Transform), &[9, 25, 21, 26, 27, 188], 178)
            }
            178 => {
                step(f, Op::BreakTransform, &[21, 51, 10, 52], 179);
                step(f, Op::TransformPoint, &[2, 51, 53], 180);
                step(f, Op::LerpV, &[53, 51, 847, 54], 181);
                step(f, Op::AddV, &[54, 55, 56], 182);
                step(f, Op::SubV, &[54, 55, 57], 183);
                step(f, Op::LineTrace, &[56, 57, 13, 58, 59, 161], 184);
                step(f, Op::JumpIfFalse, &[13, 187], 185)
            }
            185 => {
                step(f, Op::Copy(ValueType::Bool), &[122, 12], 186);
                step(f, Op::Jump, &[187], 187)
            }
            187 => {
                step(f, Op::Jump, &[177], 188)
            }
            188 => {
                step(f, Op::Copy(ValueType::Bool), &[12, 11], 189);
                step(f, Op::Or, &[11, 7, 14], 190);
                step(f, Op::NotEquals(Elem::Bool), &[14, 5, 15], 191);
                step(f, Op::JumpIfFalse, &[15, 223], 192)
            }
            192 => {
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 193);
                step(f, Op::JumpIfFalse, &[16, 222], 194)
            }
            194 => {
                step(f, Op::Copy(ValueType::Int), &[1, 24], 195);
                step(f, Op::Copy(ValueType::Int), &[71, 20], 196);
                196
            }
            196 => {
                step(f, Op::ForNext, &[20, 24, 22, 221], 197)
            }
            197 => {
                step(f, Op::AddF, &[158, 159, 162], 198);
                step(f, Op::MulF, &[162, 846, 163], 199);
                step(f, Op::Copy(ValueType::Bool), &[123, 18], 200);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[8, 10], 201);
                step(f, Op::Copy(ValueType::Int), &[71, 28], 202);
                step(f, Op::MakeVector, &[845, 845, 55, 64], 203);
                203
            }
            203 => {
                step(f, Op::ForEachNext(Elem::Transform), &[10, 28, 22, 29, 30, 214], 204)
            }
            204 => {
                step(f, Op::BreakTransform, &[22, 60, 11, 61], 205);
                step(f, Op::TransformPoint, &[2, 60, 62], 206);
                step(f, Op::LerpV, &[62, 60, 163, 63], 207);
                step(f, Op::AddV, &[63, 64, 65], 208);
                step(f, Op::SubV, &[63, 64, 66], 209);
                step(f, Op::LineTrace, &[65, 66, 19, 67, 68, 165], 210);
                step(f, Op::JumpIfFalse, &[19, 213], 211)
            }
            211 => {
                step(f, Op::Copy(ValueType::Bool), &[122, 18], 212);
                step(f, Op::Jump, &[213], 213)
            }
            213 => {
                step(f, Op::Jump, &[203], 214)
            }
            214 => {
                step(f, Op::Copy(ValueType::Bool), &[18, 17], 215);
                step(f, Op::Equals(Elem::Bool), &[17, 6, 20], 216);
                step(f, Op::JumpIfFalse, &[20, 219], 217)
            }
            217 => {
                step(f, Op::Copy(ValueType::Float), &[163, 158], 218);
                step(f, Op::Jump, &[220], 219)
            }
            219 => {
                step(f, Op::Copy(ValueType::Float), &[163, 159], 220);
                220
            }
            220 => {
                step(f, Op::Jump, &[196], 221)
            }
            221 => {
                step(f, Op::Jump, &[222], 222)
            }
            222 => {
                step(f, Op::Jump, &[223], 223)
            }
            223 => {
                step(f, Op::Select(ValueType::Float), &[5, 849, 847, 171], 224);
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 225);
                step(f, Op::AddF, &[158, 159, 162], 226);
                step(f, Op::MulF, &[162, 846, 166], 227);
                step(f, Op::Select(ValueType::Float), &[16, 166, 846, 167], 228);
                step(f, Op::Select(ValueType::Float), &[15, 167, 845, 173], 229);
                step(f, Op::MulF, &[171, 173, 175], 230);
                step(f, Op::DeltaTime, &[169], 231);
                step(f, Op::DivF, &[169, 127, 170], 232);
                step(f, Op::MulF, &[175, 170, 176], 233);
                step(f, Op::AddF, &[20, 176, 177], 234);
                step(f, Op::ClampF, &[177, 845, 847, 178], 235);
                step(f, Op::Select(ValueType::Float), &[14, 849, 847, 172], 236);
                step(f, Op::SubF, &[847, 167, 168], 237);
                step(f, Op::Select(ValueType::Float), &[15, 168, 847, 174], 238);
                step(f, Op::MulF, &[172, 174, 179], 239);
                step(f, Op::MulF, &[179, 170, 180], 240);
                step(f, Op::AddF, &[178, 180, 181], 241);
                step(f, Op::ClampF, &[181, 845, 847, 182], 242);
                step(f, Op::SmoothStepF, &[182, 845, 847, 183], 243);
                step(f, Op::AddF, &[21, 183, 184], 244);
                step(f, Op::MulF, &[184, 846, 185], 245);
                step(f, Op::SubF, &[847, 185, 186], 246);
                step(f, Op::MulF, &[186, 186, 187], 247);
                step(f, Op::SubF, &[847, 187, 188], 248);
                step(f, Op::Copy(ValueType::Float), &[188, 22], 249);
                step(f, Op::Copy(ValueType::Float), &[183, 21], 250);
                step(f, Op::Copy(ValueType::Float), &[182, 20], 251);
                step(f, Op::GreaterF, &[21, 845, 21], 252);
                step(f, Op::TransformVector, &[2, 3, 69], 253);
                step(f, Op::Select(ValueType::Vec3), &[21, 69, 0, 70], 254);
                step(f, Op::Copy(ValueType::Vec3), &[70, 3], 255);
                step(f, Op::LerpV, &[0, 3, 21, 71], 256);
                step(f, Op::Select(ValueType::Vec3), &[21, 71, 0, 72], 257);
                step(f, Op::Copy(ValueType::Vec3), &[72, 2], 258);
                step(f, Op::Copy(ValueType::Bool), &[14, 5], 259);
                step(f, Op::Copy(ValueType::Bool), &[11, 6], 260);
                step(f, Op::Copy(ValueType::Bool), &[123, 7], 261);
                step(f, Op::SubF, &[847, 22, 189], 262);
                step(f, Op::MulF, &[1, 189, 190], 263);
                step(f, Op::AddF, &[2, 190, 191], 264);
                step(f, Op::Copy(ValueType::Float), &[4, 192], 265);
                step(f, Op::Copy(ValueType::Float), &[5, 193], 266);
                step(f, Op::Copy(ValueType::Float), &[2, 195], 267);
                step(f, Op::Copy(ValueType::Float), &[124, 196], 268);
                step(f, Op::Copy(ValueType::Float), &[49, 197], 269);
                step(f, Op::SubF, &[191, 195, 202], 270);
                step(f, Op::DeltaTime, &[200], 271);
                step(f, Op::DivF, &[202, 200, 203], 272);
                step(f, Op::MulF, &[203, 197, 204], 273);
                step(f, Op::AddF, &[191, 204, 206], 274);
                step(f, Op::MulF, &[203, 850, 207], 275);
                step(f, Op::DivF, &[851, 196, 201], 276);
                step(f, Op::DivF, &[207, 201, 208], 277);
                step(f, Op::SubF, &[206, 208, 222], 278);
                step(f, Op::AddF, &[195, 204, 205], 279);
                step(f, Op::SubF, &[192, 205, 209], 280);
                step(f, Op::AddF, &[209, 208, 210], 281);
                step(f, Op::SubF, &[193, 203, 211], 282);
                step(f, Op::MulF, &[201, 210, 212], 283);
                step(f, Op::AddF, &[211, 212, 213], 284);
                step(f, Op::MulF, &[213, 200, 216], 285);
                step(f, Op::AddF, &[210, 216, 217], 286);
                step(f, Op::FloatLerp, &[845, 847, 201, 214], 287);
                step(f, Op::SubF, &[847, 214, 215], 288);
                step(f, Op::MulF, &[217, 215, 218], 289);
                step(f, Op::AddF, &[222, 218, 223], 290);
                step(f, Op::Copy(ValueType::Float), &[223, 198], 291);
                step(f, Op::MulF, &[201, 216, 219], 292);
                step(f, Op::SubF, &[211, 219, 220], 293);
                step(f, Op::MulF, &[220, 215, 221], 294);
                step(f, Op::AddF, &[203, 221, 224], 295);
                step(f, Op::Copy(ValueType::Float), &[224, 199], 296);
                step(f, Op::SubF, &[191, 198, 225], 297);
                step(f, Op::Copy(ValueType::Float), &[225, 3], 298);
                step(f, Op::Copy(ValueType::Float), &[198, 4], 299);
                step(f, Op::Copy(ValueType::Float), &[4, 192], 300);
                step(f, Op::Copy(ValueType::Float), &[5, 193], 301);
                step(f, Op::Copy(ValueType::Float), &[2, 195], 302);
                step(f, Op::Copy(ValueType::Float), &[124, 196], 303);
                step(f, Op::Copy(ValueType::Float), &[49, 197], 304);
                step(f, Op::SubF, &[191, 195, 202], 305);
                step(f, Op::DeltaTime, &[200], 306);
                step(f, Op::DivF, &[202, 200, 203], 307);
                step(f, Op::MulF, &[203, 197, 204], 308);
                step(f, Op::AddF, &[191, 204, 206], 309);
                step(f, Op::MulF, &[203, 850, 207], 310);
                step(f, Op::DivF, &[851, 196, 201], 311);
                step(f, Op::DivF, &[207, 201, 208], 312);
                step(f, Op::SubF, &[206, 208, 222], 313);
                step(f, Op::AddF, &[195, 204, 205], 314);
                step(f, Op::SubF, &[192, 205, 209], 315);
                step(f, Op::AddF, &[209, 208, 210], 316);
                step(f, Op::SubF, &[193, 203, 211], 317);
                step(f, Op::MulF, &[201, 210, 212], 318);
                step(f, Op::AddF, &[211, 212, 213], 319);
                step(f, Op::MulF, &[213, 200, 216], 320);
                step(f, Op::AddF, &[210, 216, 217], 321);
                step(f, Op::FloatLerp, &[845, 847, 201, 214], 322);
                step(f, Op::SubF, &[847, 214, 215], 323);
                step(f, Op::MulF, &[217, 215, 218], 324);
                step(f, Op::AddF, &[222, 218, 223], 325);
                step(f, Op::Copy(ValueType::Float), &[223, 198], 326);
                step(f, Op::MulF, &[201, 216, 219], 327);
                step(f, Op::SubF, &[211, 219, 220], 328);
                step(f, Op::MulF, &[220, 215, 221], 329);
                step(f, Op::AddF, &[203, 221, 224], 330);
                step(f, Op::Copy(ValueType::Float), &[224, 199], 331);
                step(f, Op::Copy(ValueType::Float), &[199, 5], 332);
                step(f, Op::Copy(ValueType::Float), &[191, 2], 333);
                step(f, Op::LengthV, &[4, 227], 334);
                step(f, Op::GreaterF, &[227, 29, 22], 335);
                step(f, Op::LengthV, &[2, 228], 336);
                step(f, Op::GreaterF, &[228, 29, 23], 337);
                step(f, Op::And, &[22, 23, 25], 338);
                step(f, Op::Select(ValueType::Vec3), &[22, 4, 466, 73], 339);
                step(f, Op::MovementAngleOffset, &[73, 14, 845, 852, 852, 853, 40, 854, 229], 340);
                step(f, Op::Copy(ValueType::Float), &[14, 232], 341);
                step(f, Op::SubF, &[229, 232, 234], 342);
                step(f, Op::AddF, &[234, 855, 235], 343);
                step(f, Op::DivF, &[235, 856, 236], 344);
                step(f, Op::FractF, &[236, 237], 345);
                step(f, Op::MulF, &[237, 856, 238], 346);
                step(f, Op::SubF, &[238, 855, 239], 347);
                step(f, Op::Copy(ValueType::Float), &[239, 233], 348);
                step(f, Op::AbsF, &[233, 258], 349);
                step(f, Op::Select(ValueType::Vec3), &[23, 2, 466, 74], 350);
                step(f, Op::MovementAngleOffset, &[74, 14, 845, 852, 852, 853, 40, 854, 230], 351);
                step(f, Op::Copy(ValueType::Float), &[14, 241], 352);
                step(f, Op::SubF, &[230, 241, 243], 353);
                step(f, Op::AddF, &[243, 855, 244], 354);
                step(f, Op::DivF, &[244, 856, 245], 355);
                step(f, Op::FractF, &[245, 246], 356);
                step(f, Op::MulF, &[246, 856, 247], 357);
                step(f, Op::SubF, &[247, 855, 248], 358);
                step(f, Op::Copy(ValueType::Float), &[248, 242], 359);
                step(f, Op::AbsF, &[242, 259], 360);
                step(f, Op::MaxF, &[258, 259, 261], 361);
                step(f, Op::SubF, &[230, 229, 252], 362);
                step(f, Op::AddF, &[252, 855, 253], 363);
                step(f, Op::DivF, &[253, 856, 254], 364);
                step(f, Op::FractF, &[254, 255], 365);
                step(f, Op::MulF, &[255, 856, 256], 366);
                step(f, Op::SubF, &[256, 855, 257], 367);
                step(f, Op::Copy(ValueType::Float), &[257, 251], 368);
                step(f, Op::AbsF, &[251, 260], 369);
                step(f, Op::MaxF, &[261, 260, 262], 370);
                step(f, Op::LessF, &[262, 857, 24], 371);
                step(f, Op::And, &[25, 24, 26], 372);
                step(f, Op::Not, &[22, 27], 373);
                step(f, Op::Not, &[23, 28], 374);
                step(f, Op::And, &[27, 28, 29], 375);
                step(f, Op::Or, &[26, 29, 30], 376);
                step(f, Op::JumpIfFalse, &[30, 398], 377)
            }
            377 => {
                step(f, Op::DeltaTime, &[226], 378);
                step(f, Op::MulF, &[38, 226, 266], 379);
                step(f, Op::GreaterF, &[266, 845, 31], 380);
                step(f, Op::DivF, &[49, 226, 263], 381);
                step(f, Op::FloatLerp, &[845, 847, 38, 264], 382);
                step(f, Op::SubF, &[847, 264, 265], 383);
                step(f, Op::DivF, &[265, 264, 267], 384);
                step(f, Op::DivF, &[847, 266, 268], 385);
                step(f, Op::SubF, &[267, 268, 269], 386);
                step(f, Op::AddF, &[263, 269, 270], 387);
                step(f, Op::Select(ValueType::Float), &[31, 270, 845, 271], 388);
                step(f, Op::MulF, &[251, 271, 272], 389);
                step(f, Op::AddF, &[230, 272, 273], 390);
                step(f, Op::SinF, &[273, 274], 391);
                step(f, Op::NegF, &[274, 275], 392);
                step(f, Op::CosF, &[273, 276], 393);
                step(f, Op::MakeVector, &[275, 276, 845, 75], 394);
                step(f, Op::Select(ValueType::Vec3), &[23, 75, 466, 76], 395);
                step(f, Op::MovementAngleOffset, &[76, 14, 845, 38, 39, 853, 855, 854, 277], 396);
                step(f, Op::Copy(ValueType::Float), &[277, 14], 397);
                step(f, Op::Jump, &[433], 398)
            }
            398 => {
                step(f, Op::DeltaTime, &[226], 399);
                step(f, Op::DivF, &[226, 41, 278], 400);
                step(f, Op::AddF, &[278, 846, 279], 401);
                step(f, Op::FloorF, &[279, 280], 402);
                step(f, Op::MaxF, &[280, 847, 281], 403);
                step(f, Op::ToInt, &[281, 36], 404);
                step(f, Op::Copy(ValueType::Int), &[36, 35], 405);
                step(f, Op::Copy(ValueType::Int), &[71, 31], 406);
                step(f, Op::MulF, &[41, 846, 285], 407);
                step(f, Op::SubF, &[49, 285, 286], 408);
                step(f, Op::DivF, &[286, 226, 287], 409);
                step(f, Op::FloatLerp, &[845, 847, 36, 289], 410);
                step(f, Op::GreaterF, &[289, 845, 32], 411);
                step(f, Op::DivF, &[38, 281, 299], 412);
                step(f, Op::DivF, &[39, 281, 300], 413);
                413
            }
            413 => {
                step(f, Op::ForNext, &[31, 35, 33, 433], 414)
            }
            414 => {
                step(f, Op::ToFloat, &[33, 282], 415);
                step(f, Op::AddF, &[282, 847, 283], 416);
                step(f, Op::DivF, &[283, 281, 284], 417);
                step(f, Op::AddF, &[284, 287, 288], 418);
                step(f, Op::MulF, &[36, 288, 290], 419);
                step(f, Op::FloatLerp, &[845, 847, 290, 291], 420);
                step(f, Op::DivF, &[291, 289, 292], 421);
                step(f, Op::Select(ValueType::Float), &[32, 292, 288, 293], 422);
                step(f, Op::LerpV, &[4, 2, 293, 77], 423);
                step(f, Op::LengthV, &[77, 294], 424);
                step(f, Op::GreaterF, &[294, 29, 33], 425);
                step(f, Op::Select(ValueType::Vec3), &[33, 77, 466, 78], 426);
                step(f, Op::MulF, &[226, 288, 295], 427);
                step(f, Op::MulF, &[8, 295, 296], 428);
                step(f, Op::AddF, &[12, 296, 297], 429);
                step(f, Op::FractF, &[297, 298], 430);
                step(f, Op::MovementAngleOffset, &[78, 14, 298, 299, 300, 853, 40, 854, 301], 431);
                step(f, Op::Copy(ValueType::Float), &[301, 14], 432);
                step(f, Op::Jump, &[413], 433)
            }
            433 => {
                step(f, Op::QuatFromAxisAngle, &[468, 14, 12], 434);
                step(f, Op::Copy(ValueType::Quat), &[12, 0], 435);
                step(f, Op::SinF, &[14, 302], 436);
                step(f, Op::AbsF, &[302, 303], 437);
                step(f, Op::RemapF, &[303, 42, 43, 845, 847, 122, 304], 438);
                step(f, Op::Copy(ValueType::Float), &[304, 15], 439);
                step(f, Op::Copy(ValueType::Vec3), &[2, 4], 440);
                step(f, Op::Copy(ValueType::Bool), &[122, 36], 441);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 2], 442);
                step(f, Op::Copy(ValueType::Int), &[71, 40], 443);
                443
            }
            443 => {
                step(f, Op::ForEachNext(Elem::Bool), &[2, 40, 37, 41, 42, 449], 444)
            }
            444 => {
                step(f, Op::Not, &[37, 38], 445);
                step(f, Op::JumpIfFalse, &[38, 448], 446)
            }
            446 => {
                step(f, Op::Copy(ValueType::Bool), &[123, 36], 447);
                step(f, Op::Jump, &[448], 448)
            }
            448 => {
                step(f, Op::Jump, &[443], 449)
            }
            449 => {
                step(f, Op::Copy(ValueType::Bool), &[36, 35], 450);
                step(f, Op::Copy(ValueType::Bool), &[122, 40], 451);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 452);
                step(f, Op::Copy(ValueType::Int), &[71, 43], 453);
                453
            }
            453 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 43, 15, 44, 45, 468], 454)
            }
            454 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 44, 23], 455);
                step(f, Op::BreakTransform, &[23, 79, 13, 80], 456);
                step(f, Op::BreakVector, &[79, 313, 314, 315], 457);
                step(f, Op::MakeVector, &[313, 314, 845, 83], 458);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 44, 24], 459);
                step(f, Op::BreakTransform, &[24, 81, 14, 82], 460);
                step(f, Op::BreakVector, &[81, 316, 317, 318], 461);
                step(f, Op::MakeVector, &[316, 317, 845, 84], 462);
                step(f, Op::DistanceV, &[83, 84, 319], 463);
                step(f, Op::GreaterF, &[319, 31, 41], 464);
                step(f, Op::JumpIfFalse, &[41, 467], 465)
            }
            465 => {
                step(f, Op::Copy(ValueType::Bool), &[123, 40], 466);
                step(f, Op::Jump, &[467], 467)
            }
            467 => {
                step(f, Op::Jump, &[453], 468)
            }
            468 => {
                step(f, Op::Copy(ValueType::Bool), &[40, 39], 469);
                step(f, Op::And, &[35, 39, 42], 470);
                step(f, Op::LengthV, &[2, 305], 471);
                step(f, Op::GreaterF, &[305, 29, 34], 472);
                step(f, Op::GreaterF, &[0, 29, 43], 473);
                step(f, Op::Or, &[34, 43, 44], 474);
                step(f, Op::Not, &[44, 45], 475);
                step(f, Op::And, &[42, 45, 50], 476);
                step(f, Op::DeltaTime, &[344], 477);
                step(f, Op::MulF, &[344, 34, 345], 478);
                step(f, Op::AddF, &[12, 345, 346], 479);
                step(f, Op::GreaterF, &[12, 846, 51], 480);
                step(f, Op::AddF, &[33, 846, 342], 481);
                step(f, Op::Select(ValueType::Float), &[51, 342, 33, 343], 482);
                step(f, Op::MinF, &[346, 343, 347], 483);
                step(f, Op::NotEquals(Elem::Bool), &[45, 4, 46], 484);
                step(f, Op::Not, &[42, 47], 485);
                step(f, Op::And, &[46, 47, 48], 486);
                step(f, Op::SubF, &[13, 29, 328], 487);
                step(f, Op::SubF, &[13, 305, 329], 488);
                step(f, Op::DivF, &[328, 329, 330], 489);
                step(f, Op::ClampF, &[330, 845, 847, 331], 490);
                step(f, Op::MulF, &[8, 331, 333], 491);
                step(f, Op::RemapF, &[305, 29, 30, 845, 847, 122, 320], 492);
                step(f, Op::MaxF, &[320, 9, 321], 493);
                step(f, Op::Select(ValueType::Float), &[35, 847, 321, 322], 494);
                step(f, Op::Select(ValueType::Float), &[45, 32, 322, 323], 495);
                step(f, Op::Select(ValueType::Float), &[42, 320, 323, 324], 496);
                step(f, Op::SubF, &[847, 21, 325], 497);
                step(f, Op::MulF, &[324, 325, 326], 498);
                step(f, Op::LerpF, &[23, 45, 15, 308], 499);
                step(f, Op::RemapF, &[305, 26, 27, 24, 25, 122, 306], 500);
                step(f, Op::LerpF, &[306, 44, 15, 307], 501);
                step(f, Op::MaxF, &[305, 28, 309], 502);
                step(f, Op::DivF, &[307, 309, 310], 503);
                step(f, Op::AddF, &[308, 310, 311], 504);
                step(f, Op::DivF, &[326, 311, 327], 505);
                step(f, Op::SubF, &[847, 331, 332], 506);
                step(f, Op::MulF, &[327, 332, 334], 507);
                step(f, Op::AddF, &[333, 334, 335], 508);
                step(f, Op::MulF, &[335, 850, 336], 509);
                step(f, Op::AddF, &[8, 327, 337], 510);
                step(f, Op::Select(ValueType::Float), &[48, 336, 337, 338], 511);
                step(f, Op::DivF, &[850, 338, 339], 512);
                step(f, Op::GreaterF, &[338, 845, 49], 513);
                step(f, Op::CycleStep, &[12, 339, 845, 49, 340, 341], 514);
                step(f, Op::Select(ValueType::Float), &[50, 347, 340, 348], 515);
                step(f, Op::Copy(ValueType::Float), &[348, 12], 516);
                step(f, Op::Copy(ValueType::Float), &[327, 8], 517);
                step(f, Op::Copy(ValueType::Bool), &[34, 3], 518);
                step(f, Op::Copy(ValueType::Float), &[310, 6], 519);
                step(f, Op::Copy(ValueType::Float), &[311, 7], 520);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 521);
                step(f, Op::Copy(ValueType::Int), &[71, 37], 522);
                step(f, Op::DivF, &[308, 311, 312], 523);
                step(f, Op::MulF, &[11, 331, 354], 524);
                step(f, Op::MulF, &[344, 846, 360], 525);
                step(f, Op::SubF, &[312, 10, 365], 526);
                step(f, Op::MaxF, &[365, 845, 366], 527);
                step(f, Op::DivF, &[366, 312, 367], 528);
                step(f, Op::SubF, &[847, 15, 369], 529);
                step(f, Op::DivF, &[49, 344, 374], 530);
                step(f, Op::SubF, &[846, 374, 375], 531);
                step(f, Op::MulF, &[367, 369, 376], 532);
                step(f, Op::MulF, &[376, 325, 377], 533);
                step(f, Op::MulF, &[377, 121, 378], 534);
                step(f, Op::MulF, &[378, 375, 379], 535);
                step(f, Op::SubF, &[847, 379, 380], 536);
                536
            }
            536 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 37, 14, 38, 39, 581], 537)
            }
            537 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 38, 362], 538);
                step(f, Op::ToFloat, &[38, 349], 539);
                step(f, Op::MulF, &[349, 846, 350], 540);
                step(f, Op::AddF, &[12, 350, 351], 541);
                step(f, Op::FractF, &[351, 352], 542);
                step(f, Op::SubF, &[362, 352, 364], 543);
                step(f, Op::GreaterF, &[364, 846, 52], 544);
                step(f, Op::ArrayAt(Elem::Float), &[2, 38, 363], 545);
                step(f, Op::Select(ValueType::Float), &[52, 845, 363, 391], 546);
                step(f, Op::ArraySetAt(Elem::Float), &[3, 38, 391], 547);
                step(f, Op::SubF, &[847, 362, 385], 548);
                step(f, Op::AddF, &[352, 385, 386], 549);
                step(f, Op::DivF, &[352, 386, 387], 550);
                step(f, Op::MaxF, &[320, 9, 321], 551);
                step(f, Op::Select(ValueType::Float), &[35, 847, 321, 322], 552);
                step(f, Op::Select(ValueType::Float), &[45, 32, 322, 323], 553);
                step(f, Op::Select(ValueType::Float), &[42, 320, 323, 324], 554);
                step(f, Op::MulF, &[324, 325, 326], 555);
                step(f, Op::DivF, &[326, 308, 353], 556);
                step(f, Op::MulF, &[353, 332, 355], 557);
                step(f, Op::AddF, &[354, 355, 356], 558);
                step(f, Op::MulF, &[356, 850, 357], 559);
                step(f, Op::AddF, &[11, 353, 358], 560);
                step(f, Op::Select(ValueType::Float), &[48, 357, 358, 359], 561);
                step(f, Op::MulF, &[359, 360, 361], 562);
                step(f, Op::MulF, &[387, 361, 388], 563);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 38, 53], 564);
                step(f, Op::MulF, &[361, 380, 381], 565);
                step(f, Op::Select(ValueType::Float), &[53, 361, 381, 382], 566);
                step(f, Op::MulF, &[367, 363, 368], 567);
                step(f, Op::MulF, &[368, 369, 370], 568);
                step(f, Op::MulF, &[370, 325, 371], 569);
                step(f, Op::MulF, &[371, 121, 372], 570);
                step(f, Op::Select(ValueType::Float), &[53, 845, 372, 373], 571);
                step(f, Op::SubF, &[382, 373, 383], 572);
                step(f, Op::AddF, &[363, 383, 384], 573);
                step(f, Op::Select(ValueType::Float), &[52, 388, 384, 389], 574);
                step(f, Op::MinF, &[389, 850, 390], 575);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 38, 390], 576);
                step(f, Op::JumpIfFalse, &[52, 579], 577)
            }
            577 => {
                step(f, Op::Copy(ValueType::Float), &[324, 9], 578);
                step(f, Op::Jump, &[579], 579)
            }
            579 => {
                step(f, Op::ArraySetAt(Elem::Float), &[0, 38, 352], 580);
                step(f, Op::Jump, &[536], 581)
            }
            581 => {
                step(f, Op::Copy(ValueType::Float), &[312, 10], 582);
                step(f, Op::Copy(ValueType::Bool), &[45, 4], 583);
                step(f, Op::Copy(ValueType::Float), &[305, 13], 584);
                step(f, Op::MaxF, &[320, 9, 321], 585);
                step(f, Op::Select(ValueType::Float), &[35, 847, 321, 322], 586);
                step(f, Op::Select(ValueType::Float), &[45, 32, 322, 323], 587);
                step(f, Op::Select(ValueType::Float), &[42, 320, 323, 324], 588);
                step(f, Op::MulF, &[324, 325, 326], 589);
                step(f, Op::DivF, &[326, 308, 353], 590);
                step(f, Op::Copy(ValueType::Float), &[353, 11], 591);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 592);
                step(f, Op::Copy(ValueType::Int), &[71, 2], 593);
                593
            }
            593 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 2, 0, 3, 4, 1396], 594)
            }
            594 => {
                step(f, Op::Copy(ValueType::Bool), &[122, 54], 595);
                step(f, Op::Copy(ValueType::Bool), &[123, 55], 596);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 3, 58], 597);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 392], 598);
                step(f, Op::GreaterEqualF, &[392, 847, 59], 599);
                step(f, Op::And, &[58, 59, 60], 600);
                step(f, Op::Or, &[1, 2, 62], 601);
                step(f, Op::GreaterF, &[21, 845, 61], 602);
                step(f, Op::Or, &[62, 61, 63], 603);
                step(f, Op::Not, &[63, 64], 604);
                step(f, Op::And, &[60, 64, 65], 605);
                step(f, Op::JumpIfFalse, &[65, 719], 606)
            }
            606 => {
                step(f, Op::ArrayAt(Elem::Transform), &[2, 3, 28], 607);
                step(f, Op::BreakTransform, &[28, 103, 23, 104], 608);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 3, 120], 609);
                step(f, Op::SubV, &[103, 120, 141], 610);
                step(f, Op::TransformPoint, &[2, 141, 142], 611);
                step(f, Op::GetTransform, &[34, 71, 122, 25], 612);
                step(f, Op::BreakTransform, &[25, 87, 15, 88], 613);
                step(f, Op::BreakVector, &[87, 403, 404, 405], 614);
                step(f, Op::SubF, &[847, 15, 401], 615);
                step(f, Op::MulF, &[14, 401, 402], 616);
                step(f, Op::QuatFromAxisAngle, &[468, 402, 17], 617);
                step(f, Op::GetTransform, &[0, 71, 122, 26], 618);
                step(f, Op::BreakTransform, &[26, 89, 16, 90], 619);
                step(f, Op::SubV, &[89, 87, 91], 620);
                step(f, Op::BreakVector, &[91, 398, 399, 400], 621);
                step(f, Op::MakeVector, &[398, 399, 845, 92], 622);
                step(f, Op::RotateVector, &[17, 92, 93], 623);
                step(f, Op::BreakVector, &[93, 406, 407, 408], 624);
                step(f, Op::MulF, &[46, 15, 409], 625);
                step(f, Op::Equals(Elem::Int), &[3, 71, 56], 626);
                step(f, Op::Select(ValueType::Float), &[56, 847, 849, 418], 627);
                step(f, Op::MulF, &[409, 418, 410], 628);
                step(f, Op::AddF, &[406, 410, 411], 629);
                step(f, Op::AddF, &[403, 411, 412], 630);
                step(f, Op::AddF, &[404, 407, 413], 631);
                step(f, Op::BreakVector, &[89, 414, 415, 416], 632);
                step(f, Op::SubF, &[416, 50, 417], 633);
                step(f, Op::MakeVector, &[412, 413, 417, 94], 634);
                step(f, Op::MulF, &[6, 846, 397], 635);
                step(f, Op::ScaleV, &[2, 397, 86], 636);
                step(f, Op::AddV, &[94, 86, 97], 637);
                step(f, Op::DistanceV, &[142, 97, 445], 638);
                step(f, Op::TransformVector, &[2, 469, 143], 639);
                step(f, Op::DistanceV, &[143, 469, 446], 640);
                step(f, Op::MaxF, &[445, 446, 447], 641);
                step(f, Op::LessEqualF, &[447, 57, 74], 642);
                step(f, Op::LengthV, &[2, 448], 643);
                step(f, Op::LengthV, &[4, 449], 644);
                step(f, Op::MaxF, &[448, 449, 450], 645);
                step(f, Op::LessEqualF, &[450, 29, 75], 646);
                step(f, Op::And, &[74, 75, 76], 647);
                step(f, Op::ArrayAt(Elem::Bool), &[1, 3, 66], 648);
                step(f, Op::And, &[76, 66, 77], 649);
                step(f, Op::JumpIfFalse, &[77, 652], 650)
            }
            650 => {
                step(f, Op::Copy(ValueType::Bool), &[122, 55], 651);
                step(f, Op::Jump, &[682], 652)
            }
            652 => {
                step(f, Op::MakeVector, &[845, 845, 55, 122], 653);
                step(f, Op::AddV, &[97, 122, 123], 654);
                step(f, Op::SubV, &[97, 122, 124], 655);
                step(f, Op::SphereTrace, &[123, 124, 54, 67, 125, 126, 437], 656);
                step(f, Op::SubV, &[125, 97, 139], 657);
                step(f, Op::DistanceV, &[139, 120, 441], 658);
                step(f, Op::RotateVector, &[0, 470, 98], 659);
                step(f, Op::ScaleV, &[98, 59, 127], 660);
                step(f, Op::AddV, &[123, 127, 128], 661);
                step(f, Op::AddV, &[124, 127, 129], 662);
                step(f, Op::SphereTrace, &[128, 129, 54, 68, 130, 131, 438], 663);
                step(f, Op::SubV, &[130, 97, 140], 664);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 3, 121], 665);
                step(f, Op::DistanceV, &[140, 121, 442], 666);
                step(f, Op::MaxF, &[441, 442, 443], 667);
                step(f, Op::ScaleV, &[98, 56, 132], 668);
                step(f, Op::AddV, &[128, 132, 133], 669);
                step(f, Op::AddV, &[129, 132, 134], 670);
                step(f, Op::SphereTrace, &[133, 134, 54, 69, 135, 136, 439], 671);
                step(f, Op::SubV, &[135, 97, 137], 672);
                step(f, Op::ArrayAt(Elem::Vec3), &[2, 3, 138], 673);
                step(f, Op::DistanceV, &[137, 138, 440], 674);
                step(f, Op::MaxF, &[443, 440, 444], 675);
                step(f, Op::LessEqualF, &[444, 57, 70], 676);
                step(f, Op::And, &[67, 68, 71], 677);
                step(f, Op::And, &[71, 66, 72], 678);
                step(f, Op::And, &[70, 72, 73], 679);
                step(f, Op::JumpIfFalse, &[73, 682], 680)
            }
            680 => {
                step(f, Op::Copy(ValueType::Bool), &[122, 55], 681);
                step(f, Op::Jump, &[682], 682)
            }
            682 => {
                step(f, Op::JumpIfFalse, &[55, 718], 683)
            }
            683 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 27], 684);
                step(f, Op::BreakTransform, &[27, 100, 21, 101], 685);
                step(f, Op::AddV, &[97, 120, 144], 686);
                step(f, Op::Copy(ValueType::Float), &[47, 451], 687);
                step(f, Op::Copy(ValueType::Float), &[49, 452], 688);
                step(f, Op::SubV, &[144, 103, 149], 689);
                step(f, Op::DeltaTime, &[453], 690);
                step(f, Op::DivF, &[452, 453, 454], 691);
                step(f, Op::ScaleV, &[149, 454, 150], 692);
                step(f, Op::AddV, &[144, 150, 151], 693);
                step(f, Op::AddV, &[103, 150, 152], 694);
                step(f, Op::SubV, &[100, 152, 153], 695);
                step(f, Op::FloatLerp, &[845, 847, 451, 455], 696);
                step(f, Op::SubF, &[847, 455, 456], 697);
                step(f, Op::ScaleV, &[153, 456, 154], 698);
                step(f, Op::AddV, &[151, 154, 156], 699);
                step(f, Op::MulF, &[451, 453, 457], 700);
                step(f, Op::GreaterF, &[457, 845, 78], 701);
                step(f, Op::DivF, &[455, 457, 458], 702);
                step(f, Op::Select(ValueType::Float), &[78, 458, 847, 459], 703);
                step(f, Op::ScaleV, &[149, 459, 155], 704);
                step(f, Op::SubV, &[156, 155, 157], 705);
                step(f, Op::Copy(ValueType::Vec3), &[157, 148], 706);
                step(f, Op::BreakVector, &[148, 460, 461, 462], 707);
                step(f, Op::ClampF, &[462, 60, 61, 463], 708);
                step(f, Op::MakeVector, &[460, 461, 463, 158], 709);
                step(f, Op::MakeTransform, &[158, 21, 465, 31], 710);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 3, 31], 711);
                step(f, Op::MakeTransform, &[144, 92, 465, 32], 712);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 3, 32], 713);
                step(f, Op::JumpIfFalse, &[66, 716], 714)
            }
            714 => {
                step(f, Op::Copy(ValueType::Bool), &[122, 7], 715);
                step(f, Op::Jump, &[716], 716)
            }
            716 => {
                step(f, Op::Copy(ValueType::Bool), &[123, 54], 717);
                step(f, Op::Jump, &[718], 718)
            }
            718 => {
                step(f, Op::Jump, &[719], 719)
            }
            719 => {
                step(f, Op::JumpIfFalse, &[54, 929], 720)
            }
            720 => {
                step(f, Op::GetTransform, &[34, 71, 122, 25], 721);
                step(f, Op::BreakTransform, &[25, 87, 15, 88], 722);
                step(f, Op::BreakVector, &[87, 403, 404, 405], 723);
                step(f, Op::SubF, &[847, 15, 401], 724);
                step(f, Op::MulF, &[14, 401, 402], 725);
                step(f, Op::QuatFromAxisAngle, &[468, 402, 17], 726);
                step(f, Op::GetTransform, &[0, 71, 122, 26], 727);
                step(f, Op::BreakTransform, &[26, 89, 16, 90], 728);
                step(f, Op::SubV, &[89, 87, 91], 729);
                step(f, Op::BreakVector, &[91, 398, 399, 400], 730);
                step(f, Op::MakeVector, &[398, 399, 845, 92], 731);
                step(f, Op::RotateVector, &[17, 92, 93], 732);
                step(f, Op::BreakVector, &[93, 406, 407, 408], 733);
                step(f, Op::MulF, &[46, 15, 409], 734);
                step(f, Op::Equals(Elem::Int), &[3, 71, 56], 735);
                step(f, Op::Select(ValueType::Float), &[56, 847, 849, 418], 736);
                step(f, Op::MulF, &[409, 418, 410], 737);
                step(f, Op::AddF, &[406, 410, 411], 738);
                step(f, Op::AddF, &[403, 411, 412], 739);
                step(f, Op::AddF, &[404, 407, 413], 740);
                step(f, Op::BreakVector, &[89, 414, 415, 416], 741);
                step(f, Op::SubF, &[416, 50, 417], 742);
                step(f, Op::MakeVector, &[412, 413, 417, 94], 743);
                step(f, Op::SubF, &[847, 392, 393], 744);
                step(f, Op::MaxF, &[393, 845, 394], 745);
                step(f, Op::MulF, &[10, 7, 395], 746);
                step(f, Op::MulF, &[394, 395, 396], 747);
                step(f, Op::ScaleV, &[2, 396, 85], 748);
                step(f, Op::AddV, &[94, 85, 95], 749);
                step(f, Op::MulF, &[6, 846, 397], 750);
                step(f, Op::ScaleV, &[2, 397, 86], 751);
                step(f, Op::AddV, &[95, 86, 96], 752);
                step(f, Op::RotateVector, &[0, 470, 98], 753);
                step(f, Op::Copy(ValueType::Float), &[852, 465], 754);
                step(f, Op::Copy(ValueType::Vec3), &[466, 163], 755);
                step(f, Op::Copy(ValueType::Vec3), &[468, 164], 756);
                step(f, Op::Copy(ValueType::Bool), &[123, 80], 757);
                step(f, Op::Copy(ValueType::Float), &[852, 466], 758);
                step(f, Op::Copy(ValueType::Vec3), &[466, 165], 759);
                step(f, Op::MulI, &[0, 0, 52], 760);
                step(f, Op::Copy(ValueType::Int), &[52, 51], 761);
                step(f, Op::Copy(ValueType::Int), &[71, 47], 762);
                step(f, Op::SubI, &[0, 72, 55], 763);
                step(f, Op::DivI, &[55, 73, 56], 764);
                step(f, Op::MakeVector, &[845, 845, 55, 170], 765);
                step(f, Op::ScaleV, &[98, 59, 175], 766);
                766
            }
            766 => {
                step(f, Op::ForNext, &[47, 51, 49, 814], 767)
            }
            767 => {
                step(f, Op::ModI, &[49, 0, 53], 768);
                step(f, Op::ToFloat, &[53, 467], 769);
                step(f, Op::MulF, &[467, 56, 469], 770);
                step(f, Op::MulF, &[469, 418, 470], 771);
                step(f, Op::MakeVector, &[470, 845, 845, 166], 772);
                step(f, Op::DivI, &[49, 0, 54], 773);
                step(f, Op::SubI, &[54, 56, 57], 774);
                step(f, Op::ToFloat, &[57, 468], 775);
                step(f, Op::MulF, &[468, 56, 471], 776);
                step(f, Op::ScaleV, &[98, 471, 167], 777);
                step(f, Op::AddV, &[166, 167, 168], 778);
                step(f, Op::AddV, &[96, 168, 169], 779);
                step(f, Op::AddV, &[169, 170, 171], 780);
                step(f, Op::SubV, &[169, 170, 172], 781);
                step(f, Op::SphereTrace, &[171, 172, 54, 81, 173, 174, 472], 782);
                step(f, Op::BreakVector, &[173, 474, 475, 476], 783);
                step(f, Op::AddV, &[171, 175, 176], 784);
                step(f, Op::AddV, &[172, 175, 177], 785);
                step(f, Op::SphereTrace, &[176, 177, 54, 82, 178, 179, 473], 786);
                step(f, Op::BreakVector, &[178, 477, 478, 479], 787);
                step(f, Op::SubF, &[476, 479, 480], 788);
                step(f, Op::AbsF, &[480, 481], 789);
                step(f, Op::Select(ValueType::Float), &[81, 845, 847, 482], 790);
                step(f, Op::AddF, &[481, 482, 487], 791);
                step(f, Op::LengthV, &[168, 483], 792);
                step(f, Op::RemapF, &[483, 845, 858, 845, 847, 122, 484], 793);
                step(f, Op::MinF, &[476, 479, 485], 794);
                step(f, Op::RemapF, &[485, 859, 858, 847, 846, 122, 486], 795);
                step(f, Op::AddF, &[484, 486, 488], 796);
                step(f, Op::AddF, &[487, 488, 489], 797);
                step(f, Op::LessF, &[489, 465, 83], 798);
                step(f, Op::And, &[81, 83, 84], 799);
                step(f, Op::JumpIfFalse, &[84, 807], 800)
            }
            800 => {
                step(f, Op::Copy(ValueType::Float), &[465, 466], 801);
                step(f, Op::Copy(ValueType::Vec3), &[163, 165], 802);
                step(f, Op::Copy(ValueType::Float), &[489, 465], 803);
                step(f, Op::Copy(ValueType::Vec3), &[173, 163], 804);
                step(f, Op::Copy(ValueType::Vec3), &[174, 164], 805);
                step(f, Op::Copy(ValueType::Bool), &[122, 80], 806);
                step(f, Op::Jump, &[813], 807)
            }
            807 => {
                step(f, Op::LessF, &[489, 466, 85], 808);
                step(f, Op::And, &[81, 85, 86], 809);
                step(f, Op::JumpIfFalse, &[86, 813], 810)
            }
            810 => {
                step(f, Op::Copy(ValueType::Float), &[489, 466], 811);
                step(f, Op::Copy(ValueType::Vec3), &[173, 165], 812);
                step(f, Op::Jump, &[813], 813)
            }
            813 => {
                step(f, Op::Jump, &[766], 814)
            }
            814 => {
                step(f, Op::JumpIfFalse, &[8, 817], 815)
            }
            815 => {
                step(f, Op::DrawSphere, &[163, 54, 470], 816);
                step(f, Op::Jump, &[817], 817)
            }
            817 => {
                step(f, Op::GreaterF, &[58, 845, 87], 818);
                step(f, Op::SubF, &[465, 466, 490], 819);
                step(f, Op::DivF, &[490, 58, 491], 820);
                step(f, Op::PowF, &[860, 491, 492], 821);
                step(f, Op::Select(ValueType::Float), &[87, 492, 845, 493], 822);
                step(f, Op::ScaleV, &[165, 493, 180], 823);
                step(f, Op::AddV, &[163, 180, 181], 824);
                step(f, Op::AddF, &[493, 847, 494], 825);
                step(f, Op::DivF, &[847, 494, 495], 826);
                step(f, Op::ScaleV, &[181, 495, 182], 827);
                step(f, Op::Copy(ValueType::Vec3), &[182, 161], 828);
                step(f, Op::Copy(ValueType::Vec3), &[164, 162], 829);
                step(f, Op::Copy(ValueType::Bool), &[80, 79], 830);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 27], 831);
                step(f, Op::BreakTransform, &[27, 100, 21, 101], 832);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 392], 833);
                step(f, Op::SubF, &[847, 392, 393], 834);
                step(f, Op::MaxF, &[393, 845, 394], 835);
                step(f, Op::MulF, &[10, 7, 395], 836);
                step(f, Op::MulF, &[394, 395, 396], 837);
                step(f, Op::ScaleV, &[2, 396, 85], 838);
                step(f, Op::SubV, &[161, 85, 99], 839);
                step(f, Op::Select(ValueType::Vec3), &[79, 99, 100, 102], 840);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 3, 28], 841);
                step(f, Op::BreakTransform, &[28, 103, 23, 104], 842);
                step(f, Op::Copy(ValueType::Float), &[47, 424], 843);
                step(f, Op::Copy(ValueType::Float), &[49, 425], 844);
                step(f, Op::SubV, &[102, 103, 109], 845);
                step(f, Op::DeltaTime, &[426], 846);
                step(f, Op::DivF, &[425, 426, 427], 847);
                step(f, Op::ScaleV, &[109, 427, 110], 848);
                step(f, Op::AddV, &[102, 110, 111], 849);
                step(f, Op::AddV, &[103, 110, 112], 850);
                step(f, Op::SubV, &[100, 112, 113], 851);
                step(f, Op::FloatLerp, &[845, 847, 424, 428], 852);
                step(f, Op::SubF, &[847, 428, 429], 853);
                step(f, Op::ScaleV, &[113, 429, 114], 854);
                step(f, Op::AddV, &[111, 114, 116], 855);
                step(f, Op::MulF, &[424, 426, 430], 856);
                step(f, Op::GreaterF, &[430, 845, 57], 857);
                step(f, Op::DivF, &[428, 430, 431], 858);
                step(f, Op::Select(ValueType::Float), &[57, 431, 847, 432], 859);
                step(f, Op::ScaleV, &[109, 432, 115], 860);
                step(f, Op::SubV, &[116, 115, 117], 861);
                step(f, Op::Copy(ValueType::Vec3), &[117, 108], 862);
                step(f, Op::BreakVector, &[108, 433, 434, 435], 863);
                step(f, Op::ClampF, &[435, 60, 61, 436], 864);
                step(f, Op::MakeVector, &[433, 434, 436, 118], 865);
                step(f, Op::RotationFromNormal, &[162, 422, 423, 19], 866);
                step(f, Op::PerFootRotationFactor, &[14, 98, 99, 419], 867);
                step(f, Op::MulF, &[14, 419, 420], 868);
                step(f, Op::SubF, &[847, 15, 401], 869);
                step(f, Op::MulF, &[420, 401, 421], 870);
                step(f, Op::QuatFromAxisAngle, &[468, 421, 18], 871);
                step(f, Op::MulQ, &[19, 18, 20], 872);
                step(f, Op::Select(ValueType::Quat), &[79, 20, 21, 22], 873);
                step(f, Op::MakeTransform, &[118, 22, 465, 30], 874);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 3, 30], 875);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 27], 876);
                step(f, Op::BreakTransform, &[27, 100, 21, 101], 877);
                step(f, Op::Select(ValueType::Vec3), &[79, 99, 100, 102], 878);
                step(f, Op::MakeTransform, &[102, 92, 465, 29], 879);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 3, 29], 880);
                step(f, Op::GetTransform, &[34, 71, 122, 25], 881);
                step(f, Op::BreakTransform, &[25, 87, 15, 88], 882);
                step(f, Op::BreakVector, &[87, 403, 404, 405], 883);
                step(f, Op::MulF, &[14, 401, 402], 884);
                step(f, Op::QuatFromAxisAngle, &[468, 402, 17], 885);
                step(f, Op::GetTransform, &[0, 71, 122, 26], 886);
                step(f, Op::BreakTransform, &[26, 89, 16, 90], 887);
                step(f, Op::SubV, &[89, 87, 91], 888);
                step(f, Op::BreakVector, &[91, 398, 399, 400], 889);
                step(f, Op::MakeVector, &[398, 399, 845, 92], 890);
                step(f, Op::RotateVector, &[17, 92, 93], 891);
                step(f, Op::BreakVector, &[93, 406, 407, 408], 892);
                step(f, Op::MulF, &[46, 15, 409], 893);
                step(f, Op::MulF, &[409, 418, 410], 894);
                step(f, Op::AddF, &[406, 410, 411], 895);
                step(f, Op::AddF, &[403, 411, 412], 896);
                step(f, Op::AddF, &[404, 407, 413], 897);
                step(f, Op::BreakVector, &[89, 414, 415, 416], 898);
                step(f, Op::SubF, &[416, 50, 417], 899);
                step(f, Op::MakeVector, &[412, 413, 417, 94], 900);
                step(f, Op::MulF, &[6, 846, 397], 901);
                step(f, Op::ScaleV, &[2, 397, 86], 902);
                step(f, Op::AddV, &[94, 86, 97], 903);
                step(f, Op::SubV, &[102, 97, 119], 904);
                step(f, Op::ArraySetAt(Elem::Vec3), &[0, 3, 119], 905);
                step(f, Op::ArraySetAt(Elem::Bool), &[1, 3, 79], 906);
                step(f, Op::GreaterEqualF, &[392, 847, 59], 907);
                step(f, Op::JumpIfFalse, &[59, 925], 908)
            }
            908 => {
                step(f, Op::MakeVector, &[845, 845, 55, 122], 909);
                step(f, Op::AddV, &[97, 122, 123], 910);
                step(f, Op::RotateVector, &[0, 470, 98], 911);
                step(f, Op::ScaleV, &[98, 59, 127], 912);
                step(f, Op::AddV, &[123, 127, 128], 913);
                step(f, Op::SubV, &[97, 122, 124], 914);
                step(f, Op::AddV, &[124, 127, 129], 915);
                step(f, Op::SphereTrace, &[128, 129, 54, 68, 130, 131, 438], 916);
                step(f, Op::SubV, &[130, 97, 140], 917);
                step(f, Op::ArraySetAt(Elem::Vec3), &[1, 3, 140], 918);
                step(f, Op::ScaleV, &[98, 56, 132], 919);
                step(f, Op::AddV, &[128, 132, 133], 920);
                step(f, Op::AddV, &[129, 132, 134], 921);
                step(f, Op::SphereTrace, &[133, 134, 54, 69, 135, 136, 439], 922);
                step(f, Op::SubV, &[135, 97, 137], 923);
                step(f, Op::ArraySetAt(Elem::Vec3), &[2, 3, 137], 924);
                step(f, Op::Jump, &[925], 925)
            }
            925 => {
                step(f, Op::JumpIfFalse, &[79, 928], 926)
            }
            926 => {
                step(f, Op::Copy(ValueType::Bool), &[122, 7], 927);
                step(f, Op::Jump, &[928], 928)
            }
            928 => {
                step(f, Op::Jump, &[929], 929)
            }
            929 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 3, 35], 930);
                step(f, Op::GreaterF, &[21, 845, 91], 931);
                step(f, Op::InterpolateTransform, &[2, 115, 22, 33], 932);
                step(f, Op::Select(ValueType::Transform), &[91, 33, 2, 34], 933);
                step(f, Op::MakeAbsolute, &[35, 34, 36], 934);
                step(f, Op::BreakTransform, &[36, 183, 24, 184], 935);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 3, 37], 936);
                step(f, Op::BreakTransform, &[37, 185, 25, 186], 937);
                step(f, Op::AddF, &[64, 65, 497], 938);
                step(f, Op::ClampSpatially, &[183, 185, 845, 497, 187], 939);
                step(f, Op::SubF, &[847, 15, 512], 940);
                step(f, Op::MulF, &[14, 512, 498], 941);
                step(f, Op::LimitRotationAroundZ, &[24, 498, 97, 26], 942);
                step(f, Op::MakeTransform, &[187, 26, 465, 38], 943);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 3, 38], 944);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 3, 88], 945);
                step(f, Op::JumpIfFalse, &[88, 999], 946)
            }
            946 => {
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 496], 947);
                step(f, Op::GreaterEqualF, &[496, 847, 89], 948);
                step(f, Op::JumpIfFalse, &[89, 950], 949)
            }
            949 => {
                step(f, Op::Jump, &[998], 950)
            }
            950 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 41], 951);
                step(f, Op::BreakTransform, &[41, 193, 28, 194], 952);
                step(f, Op::SubF, &[847, 496, 509], 953);
                step(f, Op::MulF, &[10, 7, 510], 954);
                step(f, Op::MulF, &[509, 510, 511], 955);
                step(f, Op::ScaleV, &[2, 511, 195], 956);
                step(f, Op::AddV, &[193, 195, 196], 957);
                step(f, Op::MakeTransform, &[196, 28, 465, 48], 958);
                step(f, Op::BreakTransform, &[48, 224, 33, 225], 959);
                step(f, Op::MakeVector, &[845, 845, 55, 226], 960);
                step(f, Op::AddV, &[224, 226, 227], 961);
                step(f, Op::SubV, &[224, 226, 228], 962);
                step(f, Op::LineTrace, &[227, 228, 95, 229, 230, 539], 963);
                step(f, Op::RotateVector, &[33, 468, 231], 964);
                step(f, Op::FindQuatBetween, &[231, 230, 34], 965);
                step(f, Op::MulQ, &[34, 33, 35], 966);
                step(f, Op::MulF, &[53, 52, 540], 967);
                step(f, Op::AddF, &[540, 63, 541], 968);
                step(f, Op::NegF, &[541, 542], 969);
                step(f, Op::MakeVector, &[845, 542, 845, 232], 970);
                step(f, Op::RotateVector, &[35, 232, 234], 971);
                step(f, Op::AddV, &[229, 234, 236], 972);
                step(f, Op::AddV, &[236, 226, 238], 973);
                step(f, Op::SubV, &[236, 226, 239], 974);
                step(f, Op::LineTrace, &[238, 239, 96, 242, 243, 544], 975);
                step(f, Op::BreakVector, &[242, 546, 547, 548], 976);
                step(f, Op::BreakVector, &[236, 552, 553, 554], 977);
                step(f, Op::SubF, &[548, 554, 558], 978);
                step(f, Op::Select(ValueType::Float), &[96, 558, 845, 560], 979);
                step(f, Op::AddF, &[59, 63, 543], 980);
                step(f, Op::MakeVector, &[845, 543, 845, 233], 981);
                step(f, Op::RotateVector, &[35, 233, 235], 982);
                step(f, Op::AddV, &[229, 235, 237], 983);
                step(f, Op::AddV, &[237, 226, 240], 984);
                step(f, Op::SubV, &[237, 226, 241], 985);
                step(f, Op::LineTrace, &[240, 241, 97, 244, 245, 545], 986);
                step(f, Op::BreakVector, &[244, 549, 550, 551], 987);
                step(f, Op::BreakVector, &[237, 555, 556, 557], 988);
                step(f, Op::SubF, &[551, 557, 559], 989);
                step(f, Op::Select(ValueType::Float), &[97, 559, 845, 561], 990);
                step(f, Op::MaxF, &[560, 561, 562], 991);
                step(f, Op::ClampF, &[562, 845, 62, 563], 992);
                step(f, Op::MakeVector, &[845, 845, 563, 246], 993);
                step(f, Op::AddV, &[229, 246, 247], 994);
                step(f, Op::MakeTransform, &[247, 35, 465, 51], 995);
                step(f, Op::Select(ValueType::Transform), &[95, 51, 48, 52], 996);
                step(f, Op::Copy(ValueType::Transform), &[52, 50], 997);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 3, 50], 998);
                998
            }
            998 => {
                step(f, Op::Jump, &[1091], 999)
            }
            999 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 3, 53], 1000);
                step(f, Op::MakeAbsolute, &[53, 34, 54], 1001);
                step(f, Op::BreakTransform, &[54, 248, 36, 249], 1002);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 41], 1003);
                step(f, Op::BreakTransform, &[41, 193, 28, 194], 1004);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 496], 1005);
                step(f, Op::SubF, &[847, 496, 509], 1006);
                step(f, Op::MulF, &[10, 7, 510], 1007);
                step(f, Op::MulF, &[509, 510, 511], 1008);
                step(f, Op::ScaleV, &[2, 511, 195], 1009);
                step(f, Op::AddV, &[193, 195, 196], 1010);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 3, 55], 1011);
                step(f, Op::MakeAbsolute, &[55, 34, 56], 1012);
                step(f, Op::BreakTransform, &[56, 250, 37, 251], 1013);
                step(f, Op::ArrayAt(Elem::Float), &[3, 3, 564], 1014);
                step(f, Op::SubF, &[496, 564, 565], 1015);
                step(f, Op::DeltaTime, &[580], 1016);
                step(f, Op::DivF, &[49, 580, 566], 1017);
                step(f, Op::MulF, &[565, 566, 567], 1018);
                step(f, Op::AddF, &[564, 567, 568], 1019);
                step(f, Op::ClampF, &[568, 845, 847, 570], 1020);
                step(f, Op::AddF, &[496, 567, 569], 1021);
                step(f, Op::ClampF, &[569, 845, 847, 571], 1022);
                step(f, Op::AddF, &[570, 571, 572], 1023);
                step(f, Op::MulF, &[572, 846, 573], 1024);
                step(f, Op::SubF, &[847, 573, 574], 1025);
                step(f, Op::GreaterF, &[565, 845, 98], 1026);
                step(f, Op::SubF, &[571, 570, 575], 1027);
                step(f, Op::DivF, &[575, 565, 576], 1028);
                step(f, Op::Select(ValueType::Float), &[98, 576, 847, 577], 1029);
                step(f, Op::MulF, &[574, 577, 578], 1030);
                step(f, Op::MulF, &[80, 578, 579], 1031);
                step(f, Op::Copy(ValueType::Float), &[49, 582], 1032);
                step(f, Op::SubV, &[196, 250, 256], 1033);
                step(f, Op::DeltaTime, &[583], 1034);
                step(f, Op::DivF, &[582, 583, 584], 1035);
                step(f, Op::ScaleV, &[256, 584, 257], 1036);
                step(f, Op::AddV, &[196, 257, 258], 1037);
                step(f, Op::AddV, &[250, 257, 259], 1038);
                step(f, Op::SubV, &[248, 259, 260], 1039);
                step(f, Op::FloatLerp, &[845, 847, 579, 585], 1040);
                step(f, Op::SubF, &[847, 585, 586], 1041);
                step(f, Op::ScaleV, &[260, 586, 261], 1042);
                step(f, Op::AddV, &[258, 261, 263], 1043);
                step(f, Op::MulF, &[579, 583, 587], 1044);
                step(f, Op::GreaterF, &[587, 845, 99], 1045);
                step(f, Op::DivF, &[585, 587, 588], 1046);
                step(f, Op::Select(ValueType::Float), &[99, 588, 847, 589], 1047);
                step(f, Op::ScaleV, &[256, 589, 262], 1048);
                step(f, Op::SubV, &[263, 262, 264], 1049);
                step(f, Op::Copy(ValueType::Vec3), &[264, 255], 1050);
                step(f, Op::MakeTransform, &[255, 28, 465, 58], 1051);
                step(f, Op::BreakTransform, &[58, 265, 38, 266], 1052);
                step(f, Op::MakeVector, &[845, 845, 55, 267], 1053);
                step(f, Op::AddV, &[265, 267, 268], 1054);
                step(f, Op::SubV, &[265, 267, 269], 1055);
                step(f, Op::LineTrace, &[268, 269, 100, 270, 271, 590], 1056);
                step(f, Op::RotateVector, &[38, 468, 272], 1057);
                step(f, Op::FindQuatBetween, &[272, 271, 39], 1058);
                step(f, Op::MulQ, &[39, 38, 40], 1059);
                step(f, Op::MulF, &[53, 52, 591], 1060);
                step(f, Op::AddF, &[591, 63, 592], 1061);
                step(f, Op::NegF, &[592, 593], 1062);
                step(f, Op::MakeVector, &[845, 593, 845, 273], 1063);
                step(f, Op::RotateVector, &[40, 273, 275], 1064);
                step(f, Op::AddV, &[270, 275, 277], 1065);
                step(f, Op::AddV, &[277, 267, 279], 1066);
                step(f, Op::SubV, &[277, 267, 280], 1067);
                step(f, Op::LineTrace, &[279, 280, 101, 283, 284, 595], 1068);
                step(f, Op::BreakVector, &[283, 597, 598, 599], 1069);
                step(f, Op::BreakVector, &[277, 603, 604, 605], 1070);
                step(f, Op::SubF, &[599, 605, 609], 1071);
                step(f, Op::Select(ValueType::Float), &[101, 609, 845, 611], 1072);
                step(f, Op::AddF, &[59, 63, 594], 1073);
                step(f, Op::MakeVector, &[845, 594, 845, 274], 1074);
                step(f, Op::RotateVector, &[40, 274, 276], 1075);
                step(f, Op::AddV, &[270, 276, 278], 1076);
                step(f, Op::AddV, &[278, 267, 281], 1077);
                step(f, Op::SubV, &[278, 267, 282], 1078);
                step(f, Op::LineTrace, &[281, 282, 102, 285, 286, 596], 1079);
                step(f, Op::BreakVector, &[285, 600, 601, 602], 1080);
                step(f, Op::BreakVector, &[278, 606, 607, 608], 1081);
                step(f, Op::SubF, &[602, 608, 610], 1082);
                step(f, Op::Select(ValueType::Float), &[102, 610, 845, 612], 1083);
                step(f, Op::MaxF, &[611, 612, 613], 1084);
                step(f, Op::ClampF, &[613, 845, 62, 614], 1085);
                step(f, Op::MakeVector, &[845, 845, 614, 287], 1086);
                step(f, Op::AddV, &[270, 287, 288], 1087);
                step(f, Op::MakeTransform, &[288, 40, 465, 61], 1088);
                step(f, Op::Select(ValueType::Transform), &[100, 61, 58, 62], 1089);
                step(f, Op::Copy(ValueType::Transform), &[62, 60], 1090);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 3, 60], 1091);
                1091
            }
            1091 => {
                step(f, Op::GreaterEqualF, &[496, 847, 89], 1092);
                step(f, Op::JumpIfFalse, &[89, 1163], 1093)
            }
            1093 => {
                step(f, Op::JumpIfFalse, &[88, 1095], 1094)
            }
            1094 => {
                step(f, Op::Jump, &[1144], 1095)
            }
            1095 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 3, 63], 1096);
                step(f, Op::BreakTransform, &[63, 289, 41, 290], 1097);
                step(f, Op::Equals(Elem::Int), &[3, 71, 90], 1098);
                step(f, Op::Select(ValueType::Int), &[90, 72, 71, 59], 1099);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 59, 42], 1100);
                step(f, Op::BreakTransform, &[42, 197, 29, 198], 1101);
                step(f, Op::MulF, &[14, 512, 513], 1102);
                step(f, Op::FootAvoidance, &[289, 197, 513, 90, 81, 199], 1103);
                step(f, Op::MakeTransform, &[199, 41, 465, 43], 1104);
                step(f, Op::BreakTransform, &[43, 200, 30, 201], 1105);
                step(f, Op::MakeVector, &[845, 845, 55, 202], 1106);
                step(f, Op::AddV, &[200, 202, 203], 1107);
                step(f, Op::SubV, &[200, 202, 204], 1108);
                step(f, Op::LineTrace, &[203, 204, 92, 205, 206, 514], 1109);
                step(f, Op::RotateVector, &[30, 468, 207], 1110);
                step(f, Op::FindQuatBetween, &[207, 206, 31], 1111);
                step(f, Op::MulQ, &[31, 30, 32], 1112);
                step(f, Op::MulF, &[53, 52, 515], 1113);
                step(f, Op::AddF, &[515, 63, 516], 1114);
                step(f, Op::NegF, &[516, 517], 1115);
                step(f, Op::MakeVector, &[845, 517, 845, 208], 1116);
                step(f, Op::RotateVector, &[32, 208, 210], 1117);
                step(f, Op::AddV, &[205, 210, 212], 1118);
                step(f, Op::AddV, &[212, 202, 214], 1119);
                step(f, Op::SubV, &[212, 202, 215], 1120);
                step(f, Op::LineTrace, &[214, 215, 93, 218, 219, 519], 1121);
                step(f, Op::BreakVector, &[218, 521, 522, 523], 1122);
                step(f, Op::BreakVector, &[212, 527, 528, 529], 1123);
                step(f, Op::SubF, &[523, 529, 533], 1124);
                step(f, Op::Select(ValueType::Float), &[93, 533, 845, 535], 1125);
                step(f, Op::AddF, &[59, 63, 518], 1126);
                step(f, Op::MakeVector, &[845, 518, 845, 209], 1127);
                step(f, Op::RotateVector, &[32, 209, 211], 1128);
                step(f, Op::AddV, &[205, 211, 213], 1129);
                step(f, Op::AddV, &[213, 202, 216], 1130);
                step(f, Op::SubV, &[213, 202, 217], 1131);
                step(f, Op::LineTrace, &[216, 217, 94, 220, 221, 520], 1132);
                step(f, Op::BreakVector, &[220, 524, 525, 526], 1133);
                step(f, Op::BreakVector, &[213, 530, 531, 532], 1134);
                step(f, Op::SubF, &[526, 532, 534], 1135);
                step(f, Op::Select(ValueType::Float), &[94, 534, 845, 536], 1136);
                step(f, Op::MaxF, &[535, 536, 537], 1137);
                step(f, Op::ClampF, &[537, 845, 62, 538], 1138);
                step(f, Op::MakeVector, &[845, 845, 538, 222], 1139);
                step(f, Op::AddV, &[205, 222, 223], 1140);
                step(f, Op::MakeTransform, &[223, 32, 465, 46], 1141);
                step(f, Op::Select(ValueType::Transform), &[92, 46, 43, 47], 1142);
                step(f, Op::Copy(ValueType::Transform), &[47, 45], 1143);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 3, 45], 1144);
                1144
            }
            1144 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 3, 39], 1145);
                step(f, Op::BreakTransform, &[39, 188, 27, 189], 1146);
                step(f, Op::SubV, &[188, 185, 190], 1147);
                step(f, Op::LengthV, &[190, 499], 1148);
                step(f, Op::SubF, &[64, 65, 500], 1149);
                step(f, Op::SubF, &[499, 500, 501], 1150);
                step(f, Op::MulF, &[65, 850, 502], 1151);
                step(f, Op::ClampF, &[501, 845, 502, 503], 1152);
                step(f, Op::MulF, &[503, 503, 504], 1153);
                step(f, Op::MulF, &[65, 861, 505], 1154);
                step(f, Op::DivF, &[504, 505, 506], 1155);
                step(f, Op::SubF, &[499, 506, 507], 1156);
                step(f, Op::DivF, &[507, 499, 508], 1157);
                step(f, Op::ScaleV, &[190, 508, 191], 1158);
                step(f, Op::AddV, &[185, 191, 192], 1159);
                step(f, Op::MakeTransform, &[192, 27, 465, 40], 1160);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 3, 40], 1161);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 3, 40], 1162);
                step(f, Op::Jump, &[1298], 1163)
            }
            1163 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 3, 39], 1164);
                step(f, Op::BreakTransform, &[39, 188, 27, 189], 1165);
                step(f, Op::SubV, &[188, 185, 190], 1166);
                step(f, Op::LengthV, &[190, 499], 1167);
                step(f, Op::SubF, &[64, 65, 500], 1168);
                step(f, Op::SubF, &[499, 500, 501], 1169);
                step(f, Op::MulF, &[65, 850, 502], 1170);
                step(f, Op::ClampF, &[501, 845, 502, 503], 1171);
                step(f, Op::MulF, &[503, 503, 504], 1172);
                step(f, Op::MulF, &[65, 861, 505], 1173);
                step(f, Op::DivF, &[504, 505, 506], 1174);
                step(f, Op::SubF, &[499, 506, 507], 1175);
                step(f, Op::DivF, &[507, 499, 508], 1176);
                step(f, Op::ScaleV, &[190, 508, 191], 1177);
                step(f, Op::AddV, &[185, 191, 192], 1178);
                step(f, Op::MakeTransform, &[192, 27, 465, 40], 1179);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 3, 63], 1180);
                step(f, Op::ClampF, &[496, 845, 847, 615], 1181);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[6, 5], 1182);
                step(f, Op::ArrayReset(Elem::Vec3), &[5], 1183);
                step(f, Op::BreakTransform, &[40, 310, 46, 311], 1184);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 310], 1185);
                step(f, Op::UnitV, &[2, 309], 1186);
                step(f, Op::LengthV, &[2, 636], 1187);
                step(f, Op::RemapF, &[636, 845, 66, 845, 67, 122, 637], 1188);
                step(f, Op::ScaleV, &[309, 637, 314], 1189);
                step(f, Op::SubV, &[310, 314, 320], 1190);
                step(f, Op::MakeVector, &[845, 845, 69, 318], 1191);
                step(f, Op::AddV, &[320, 318, 322], 1192);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 322], 1193);
                step(f, Op::RemapF, &[636, 845, 66, 845, 71, 122, 639], 1194);
                step(f, Op::MakeVector, &[845, 845, 639, 316], 1195);
                step(f, Op::AddV, &[322, 316, 326], 1196);
                step(f, Op::BreakTransform, &[63, 312, 47, 313], 1197);
                step(f, Op::BreakVector, &[312, 644, 645, 646], 1198);
                step(f, Op::BreakVector, &[310, 641, 642, 643], 1199);
                step(f, Op::SubF, &[646, 643, 647], 1200);
                step(f, Op::MaxF, &[647, 845, 649], 1201);
                step(f, Op::MulF, &[649, 73, 653], 1202);
                step(f, Op::MinF, &[653, 74, 654], 1203);
                step(f, Op::AbsF, &[647, 651], 1204);
                step(f, Op::RemapF, &[651, 845, 77, 845, 76, 122, 652], 1205);
                step(f, Op::AddF, &[654, 652, 656], 1206);
                step(f, Op::MakeVector, &[845, 845, 656, 324], 1207);
                step(f, Op::AddV, &[326, 324, 328], 1208);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 328], 1209);
                step(f, Op::RemapF, &[636, 845, 66, 845, 68, 122, 638], 1210);
                step(f, Op::ScaleV, &[309, 638, 315], 1211);
                step(f, Op::AddV, &[312, 315, 321], 1212);
                step(f, Op::MakeVector, &[845, 845, 70, 319], 1213);
                step(f, Op::AddV, &[321, 319, 323], 1214);
                step(f, Op::RemapF, &[636, 845, 66, 845, 72, 122, 640], 1215);
                step(f, Op::MakeVector, &[845, 845, 640, 317], 1216);
                step(f, Op::AddV, &[323, 317, 327], 1217);
                step(f, Op::NegF, &[647, 648], 1218);
                step(f, Op::MaxF, &[648, 845, 650], 1219);
                step(f, Op::MulF, &[650, 75, 655], 1220);
                step(f, Op::AddF, &[655, 652, 657], 1221);
                step(f, Op::MakeVector, &[845, 845, 657, 325], 1222);
                step(f, Op::AddV, &[327, 325, 329], 1223);
                step(f, Op::LerpV, &[328, 329, 846, 330], 1224);
                step(f, Op::GetTransform, &[35, 71, 122, 72], 1225);
                step(f, Op::BreakTransform, &[72, 331, 48, 332], 1226);
                step(f, Op::BreakVector, &[331, 667, 668, 669], 1227);
                step(f, Op::SubF, &[847, 15, 661], 1228);
                step(f, Op::MulF, &[78, 661, 662], 1229);
                step(f, Op::MulF, &[14, 662, 663], 1230);
                step(f, Op::QuatFromAxisAngle, &[468, 663, 49], 1231);
                step(f, Op::SubV, &[330, 331, 333], 1232);
                step(f, Op::BreakVector, &[333, 658, 659, 660], 1233);
                step(f, Op::MakeVector, &[658, 659, 845, 334], 1234);
                step(f, Op::RotateVector, &[49, 334, 335], 1235);
                step(f, Op::BreakVector, &[335, 664, 665, 666], 1236);
                step(f, Op::AddF, &[667, 664, 673], 1237);
                step(f, Op::AddF, &[668, 665, 674], 1238);
                step(f, Op::BreakVector, &[330, 670, 671, 672], 1239);
                step(f, Op::MakeVector, &[673, 674, 672, 336], 1240);
                step(f, Op::DistanceV, &[310, 312, 675], 1241);
                step(f, Op::RemapF, &[675, 850, 862, 845, 847, 122, 676], 1242);
                step(f, Op::LerpV, &[330, 336, 676, 337], 1243);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 337], 1244);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 329], 1245);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 323], 1246);
                step(f, Op::ArrayAdd(Elem::Vec3), &[5, 312], 1247);
                step(f, Op::JumpIfFalse, &[8, 1250], 1248)
            }
            1248 => {
                step(f, Op::DrawSpline, &[5, 71, 74, 846, 471], 1249);
                step(f, Op::Jump, &[1250], 1250)
            }
            1250 => {
                step(f, Op::Spline, &[5, 615, 71, 338, 339], 1251);
                step(f, Op::SlerpQ, &[46, 47, 615, 50], 1252);
                step(f, Op::MulF, &[615, 855, 678], 1253);
                step(f, Op::SinF, &[678, 679], 1254);
                step(f, Op::SmoothStepF, &[615, 845, 90, 677], 1255);
                step(f, Op::MulF, &[679, 677, 680], 1256);
                step(f, Op::MulF, &[680, 79, 681], 1257);
                step(f, Op::SlerpQ, &[50, 92, 681, 51], 1258);
                step(f, Op::MakeTransform, &[338, 51, 465, 73], 1259);
                step(f, Op::Copy(ValueType::Transform), &[73, 71], 1260);
                step(f, Op::BreakTransform, &[71, 291, 42, 292], 1261);
                step(f, Op::Equals(Elem::Int), &[3, 71, 90], 1262);
                step(f, Op::Select(ValueType::Int), &[90, 72, 71, 59], 1263);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 59, 42], 1264);
                step(f, Op::BreakTransform, &[42, 197, 29, 198], 1265);
                step(f, Op::SubF, &[847, 15, 512], 1266);
                step(f, Op::MulF, &[14, 512, 513], 1267);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 59, 103], 1268);
                step(f, Op::Select(ValueType::Float), &[103, 82, 845, 618], 1269);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 496], 1270);
                step(f, Op::ClampF, &[496, 845, 847, 615], 1271);
                step(f, Op::MulF, &[615, 855, 616], 1272);
                step(f, Op::SinF, &[616, 617], 1273);
                step(f, Op::MulF, &[617, 617, 619], 1274);
                step(f, Op::MulF, &[618, 619, 620], 1275);
                step(f, Op::AddF, &[81, 620, 621], 1276);
                step(f, Op::FootAvoidance, &[291, 197, 513, 90, 621, 293], 1277);
                step(f, Op::SubV, &[293, 291, 294], 1278);
                step(f, Op::LengthV, &[294, 622], 1279);
                step(f, Op::AddF, &[622, 620, 623], 1280);
                step(f, Op::DivF, &[622, 623, 624], 1281);
                step(f, Op::LessEqualF, &[83, 845, 104], 1282);
                step(f, Op::SmoothStepF, &[615, 845, 83, 625], 1283);
                step(f, Op::Select(ValueType::Float), &[104, 847, 625, 626], 1284);
                step(f, Op::MulF, &[624, 626, 627], 1285);
                step(f, Op::ScaleV, &[294, 627, 295], 1286);
                step(f, Op::AddV, &[291, 295, 296], 1287);
                step(f, Op::MulF, &[3, 126, 628], 1288);
                step(f, Op::MulF, &[628, 619, 629], 1289);
                step(f, Op::MakeVector, &[845, 845, 629, 297], 1290);
                step(f, Op::AddV, &[296, 297, 298], 1291);
                step(f, Op::MakeTransform, &[298, 42, 465, 64], 1292);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 3, 64], 1293);
                step(f, Op::ScaleV, &[294, 624, 299], 1294);
                step(f, Op::AddV, &[291, 299, 300], 1295);
                step(f, Op::AddV, &[300, 297, 301], 1296);
                step(f, Op::MakeTransform, &[301, 42, 465, 65], 1297);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 3, 65], 1298);
                1298
            }
            1298 => {
                step(f, Op::GreaterF, &[21, 845, 91], 1299);
                step(f, Op::JumpIfFalse, &[91, 1323], 1300)
            }
            1300 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 3, 66], 1301);
                step(f, Op::BreakTransform, &[66, 302, 43, 303], 1302);
                step(f, Op::ArrayAt(Elem::Transform), &[8, 3, 67], 1303);
                step(f, Op::BreakTransform, &[67, 304, 44, 305], 1304);
                step(f, Op::MulF, &[21, 21, 630], 1305);
                step(f, Op::LerpV, &[302, 304, 630, 306], 1306);
                step(f, Op::SubF, &[847, 21, 631], 1307);
                step(f, Op::MulF, &[21, 631, 632], 1308);
                step(f, Op::MulF, &[128, 850, 633], 1309);
                step(f, Op::MulF, &[632, 633, 634], 1310);
                step(f, Op::MakeVector, &[845, 845, 634, 307], 1311);
                step(f, Op::AddV, &[306, 307, 308], 1312);
                step(f, Op::SlerpQ, &[43, 44, 21, 45], 1313);
                step(f, Op::MakeTransform, &[308, 45, 465, 68], 1314);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 3, 68], 1315);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 3, 66], 1316);
                step(f, Op::BreakTransform, &[66, 302, 43, 303], 1317);
                step(f, Op::LerpV, &[302, 304, 630, 306], 1318);
                step(f, Op::AddV, &[306, 307, 308], 1319);
                step(f, Op::SlerpQ, &[43, 44, 21, 45], 1320);
                step(f, Op::MakeTransform, &[308, 45, 465, 68], 1321);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 3, 68], 1322);
                step(f, Op::Jump, &[1323], 1323)
            }
            1323 => {
                step(f, Op::GreaterEqualF, &[496, 847, 89], 1324);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 3, 89], 1325);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 3, 41], 1326);
                step(f, Op::BreakTransform, &[41, 193, 28, 194], 1327);
                step(f, Op::SubF, &[847, 496, 509], 1328);
                step(f, Op::MulF, &[10, 7, 510], 1329);
                step(f, Op::MulF, &[509, 510, 511], 1330);
                step(f, Op::ScaleV, &[2, 511, 195], 1331);
                step(f, Op::AddV, &[193, 195, 196], 1332);
                step(f, Op::MakeTransform, &[196, 92, 465, 57], 1333);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 3, 57], 1334);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 3, 74], 1335);
                step(f, Op::BreakTransform, &[74, 340, 52, 341], 1336);
                step(f, Op::MakeVector, &[845, 845, 50, 350], 1337);
                step(f, Op::AddV, &[340, 350, 351], 1338);
                step(f, Op::GetTransform, &[0, 71, 122, 76], 1339);
                step(f, Op::BreakTransform, &[76, 345, 54, 346], 1340);
                step(f, Op::MakeTransform, &[351, 54, 465, 78], 1341);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 3, 20], 1342);
                step(f, Op::GetTransform, &[20, 71, 122, 77], 1343);
                step(f, Op::BreakTransform, &[77, 347, 55, 348], 1344);
                step(f, Op::SubV, &[347, 345, 349], 1345);
                step(f, Op::AddV, &[351, 349, 352], 1346);
                step(f, Op::FootPivots, &[351, 352, 52, 51, 50, 53, 353, 354, 355], 1347);
                step(f, Op::GetParent, &[0, 18], 1348);
                step(f, Op::GetParent, &[18, 19], 1349);
                step(f, Op::GetTransform, &[19, 71, 123, 75], 1350);
                step(f, Op::BreakTransform, &[75, 342, 53, 343], 1351);
                step(f, Op::SubV, &[340, 342, 344], 1352);
                step(f, Op::DotV, &[344, 470, 682], 1353);
                step(f, Op::RemapF, &[682, 85, 84, 86, 845, 122, 685], 1354);
                step(f, Op::LengthV, &[2, 683], 1355);
                step(f, Op::RemapF, &[683, 845, 96, 845, 847, 122, 684], 1356);
                step(f, Op::MulF, &[685, 684, 686], 1357);
                step(f, Op::QuatFromAxisAngle, &[472, 686, 56], 1358);
                step(f, Op::RotateAroundPoint, &[78, 353, 56, 79], 1359);
                step(f, Op::ArrayAt(Elem::Float), &[2, 3, 687], 1360);
                step(f, Op::SmoothStepF, &[687, 845, 90, 689], 1361);
                step(f, Op::SubF, &[847, 687, 688], 1362);
                step(f, Op::SmoothStepF, &[688, 845, 90, 690], 1363);
                step(f, Op::MulF, &[689, 690, 691], 1364);
                step(f, Op::LerpF, &[89, 847, 691, 692], 1365);
                step(f, Op::MulF, &[686, 692, 693], 1366);
                step(f, Op::QuatFromAxisAngle, &[472, 693, 57], 1367);
                step(f, Op::SubV, &[354, 353, 356], 1368);
                step(f, Op::RotateVector, &[57, 356, 357], 1369);
                step(f, Op::AddV, &[353, 357, 358], 1370);
                step(f, Op::RemapF, &[682, 87, 85, 88, 845, 122, 694], 1371);
                step(f, Op::MulF, &[694, 684, 695], 1372);
                step(f, Op::QuatFromAxisAngle, &[472, 695, 58], 1373);
                step(f, Op::RotateAroundPoint, &[79, 358, 58, 80], 1374);
                step(f, Op::RemapF, &[682, 91, 92, 845, 93, 122, 696], 1375);
                step(f, Op::RotateVector, &[52, 468, 359], 1376);
                step(f, Op::BreakVector, &[359, 697, 698, 699], 1377);
                step(f, Op::CosF, &[95, 701], 1378);
                step(f, Op::CosF, &[94, 700], 1379);
                step(f, Op::RemapF, &[699, 701, 700, 845, 847, 122, 702], 1380);
                step(f, Op::MulF, &[684, 702, 703], 1381);
                step(f, Op::MulF, &[696, 703, 704], 1382);
                step(f, Op::QuatFromAxisAngle, &[472, 704, 59], 1383);
                step(f, Op::RotateAroundPoint, &[80, 355, 59, 81], 1384);
                step(f, Op::SubF, &[847, 15, 705], 1385);
                step(f, Op::MulF, &[14, 705, 706], 1386);
                step(f, Op::LimitRotationAroundZ, &[52, 706, 97, 60], 1387);
                step(f, Op::RotateAroundPoint, &[81, 340, 60, 82], 1388);
                step(f, Op::ArraySetAt(Elem::Transform), &[7, 3, 82], 1389);
                step(f, Op::JumpIfFalse, &[8, 1395], 1390)
            }
            1390 => {
                step(f, Op::DrawPoint, &[355, 863, 472], 1391);
                step(f, Op::DrawPoint, &[353, 863, 470], 1392);
                step(f, Op::DrawPoint, &[358, 863, 468], 1393);
                step(f, Op::DrawTransform, &[74, 862, 846], 1394);
                step(f, Op::Jump, &[1395], 1395)
            }
            1395 => {
                step(f, Op::Jump, &[593], 1396)
            }
            1396 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1397);
                step(f, Op::Copy(ValueType::Int), &[71, 5], 1398);
                1398
            }
            1398 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 5, 1, 6, 7, 1438], 1399)
            }
            1399 => {
                step(f, Op::GetParent, &[1, 22], 1400);
                step(f, Op::GetParent, &[22, 23], 1401);
                step(f, Op::GetParent, &[23, 24], 1402);
                step(f, Op::GetTransform, &[24, 71, 123, 83], 1403);
                step(f, Op::BreakTransform, &[83, 360, 61, 361], 1404);
                step(f, Op::LengthV, &[1, 708], 1405);
                step(f, Op::ClavicleOffset, &[12, 708, 102, 105, 709], 1406);
                step(f, Op::MakeVector, &[845, 845, 709, 362], 1407);
                step(f, Op::AddV, &[360, 362, 363], 1408);
                step(f, Op::MakeTransform, &[363, 61, 465, 84], 1409);
                step(f, Op::SetTransform, &[24, 84, 71, 122, 847], 1410);
                step(f, Op::GetTransform, &[1, 71, 123, 85], 1411);
                step(f, Op::GetTransform, &[23, 71, 123, 86], 1412);
                step(f, Op::BreakTransform, &[86, 364, 63, 365], 1413);
                step(f, Op::Equals(Elem::Int), &[6, 71, 105], 1414);
                step(f, Op::Select(ValueType::Int), &[105, 72, 71, 62], 1415);
                step(f, Op::ArrayAt(Elem::Float), &[0, 62, 707], 1416);
                step(f, Op::ArmSwingRotation, &[707, 1, 0, 103, 854, 864, 847, 102, 100, 101, 854, 854, 847, 710], 1417);
                step(f, Op::QuatFromAxisAngle, &[472, 710, 62], 1418);
                step(f, Op::RotateAroundPoint, &[85, 364, 62, 87], 1419);
                step(f, Op::BreakTransform, &[87, 366, 64, 367], 1420);
                step(f, Op::RemapF, &[708, 845, 102, 845, 104, 122, 711], 1421);
                step(f, Op::MakeVector, &[845, 845, 711, 368], 1422);
                step(f, Op::AddV, &[366, 368, 369], 1423);
                step(f, Op::MakeTransform, &[369, 64, 465, 88], 1424);
                step(f, Op::Select(ValueType::Vec3), &[105, 473, 472, 371], 1425);
                step(f, Op::Select(ValueType::Vec3), &[105, 470, 474, 372], 1426);
                step(f, Op::ArrayAt(Elem::Vec3), &[4, 6, 370], 1427);
                step(f, Op::TwoBoneIK, &[23, 22, 1, 88, 371, 372, 370, 71, 847, 123, 865, 866, 122, 106, 712], 1428);
                step(f, Op::JumpIfFalse, &[8, 1437], 1429)
            }
            1429 => {
                step(f, Op::GetTransform, &[23, 71, 123, 86], 1430);
                step(f, Op::BreakTransform, &[86, 364, 63, 365], 1431);
                step(f, Op::GetTransform, &[1, 71, 123, 85], 1432);
                step(f, Op::RotateAroundPoint, &[85, 364, 62, 87], 1433);
                step(f, Op::BreakTransform, &[87, 366, 64, 367], 1434);
                step(f, Op::AddV, &[366, 368, 369], 1435);
                step(f, Op::DrawLine, &[364, 369, 846, 470], 1436);
                step(f, Op::Jump, &[1437], 1437)
            }
            1437 => {
                step(f, Op::Jump, &[1398], 1438)
            }
            1438 => {
                step(f, Op::NegF, &[3, 823], 1439);
                step(f, Op::MakeVector, &[845, 845, 823, 447], 1440);
                step(f, Op::MakeTransform, &[447, 92, 465, 109], 1441);
                step(f, Op::SetTransform, &[36, 109, 71, 122, 847], 1442);
                step(f, Op::Copy(ValueType::Float), &[852, 716], 1443);
                step(f, Op::Copy(ValueType::Bool), &[123, 107], 1444);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 11], 1445);
                step(f, Op::Copy(ValueType::Int), &[71, 63], 1446);
                step(f, Op::MakeVector, &[845, 845, 55, 375], 1447);
                1447
            }
            1447 => {
                step(f, Op::ForEachNext(Elem::Transform), &[11, 63, 89, 64, 65, 1460], 1448)
            }
            1448 => {
                step(f, Op::BreakTransform, &[89, 373, 65, 374], 1449);
                step(f, Op::AddV, &[373, 375, 376], 1450);
                step(f, Op::SubV, &[373, 375, 377], 1451);
                step(f, Op::SphereTrace, &[376, 377, 54, 108, 378, 379, 717], 1452);
                step(f, Op::BreakVector, &[378, 718, 719, 720], 1453);
                step(f, Op::LessF, &[720, 716, 109], 1454);
                step(f, Op::And, &[108, 109, 110], 1455);
                step(f, Op::JumpIfFalse, &[110, 1459], 1456)
            }
            1456 => {
                step(f, Op::Copy(ValueType::Float), &[720, 716], 1457);
                step(f, Op::Copy(ValueType::Bool), &[122, 107], 1458);
                step(f, Op::Jump, &[1459], 1459)
            }
            1459 => {
                step(f, Op::Jump, &[1447], 1460)
            }
            1460 => {
                step(f, Op::Select(ValueType::Float), &[107, 716, 845, 721], 1461);
                step(f, Op::ClampF, &[721, 60, 61, 722], 1462);
                step(f, Op::Copy(ValueType::Float), &[722, 715], 1463);
                step(f, Op::SubF, &[847, 21, 714], 1464);
                step(f, Op::MulF, &[715, 714, 723], 1465);
                step(f, Op::SubF, &[847, 125, 724], 1466);
                step(f, Op::MulF, &[3, 724, 725], 1467);
                step(f, Op::AddF, &[723, 725, 726], 1468);
                step(f, Op::MakeVector, &[16, 845, 845, 380], 1469);
                step(f, Op::MakeVector, &[726, 845, 845, 381], 1470);
                step(f, Op::Select(ValueType::Float), &[2, 726, 17, 727], 1471);
                step(f, Op::MakeVector, &[727, 845, 845, 382], 1472);
                step(f, Op::Copy(ValueType::Float), &[48, 728], 1473);
                step(f, Op::Copy(ValueType::Float), &[49, 729], 1474);
                step(f, Op::SubV, &[381, 382, 387], 1475);
                step(f, Op::DeltaTime, &[730], 1476);
                step(f, Op::DivF, &[729, 730, 731], 1477);
                step(f, Op::ScaleV, &[387, 731, 388], 1478);
                step(f, Op::AddV, &[381, 388, 389], 1479);
                step(f, Op::AddV, &[382, 388, 390], 1480);
                step(f, Op::SubV, &[380, 390, 391], 1481);
                step(f, Op::FloatLerp, &[845, 847, 728, 732], 1482);
                step(f, Op::SubF, &[847, 732, 733], 1483);
                step(f, Op::ScaleV, &[391, 733, 392], 1484);
                step(f, Op::AddV, &[389, 392, 394], 1485);
                step(f, Op::MulF, &[728, 730, 734], 1486);
                step(f, Op::GreaterF, &[734, 845, 111], 1487);
                step(f, Op::DivF, &[732, 734, 735], 1488);
                step(f, Op::Select(ValueType::Float), &[111, 735, 847, 736], 1489);
                step(f, Op::ScaleV, &[387, 736, 393], 1490);
                step(f, Op::SubV, &[394, 393, 395], 1491);
                step(f, Op::Copy(ValueType::Vec3), &[395, 386], 1492);
                step(f, Op::BreakVector, &[386, 737, 738, 739], 1493);
                step(f, Op::Select(ValueType::Float), &[1, 726, 737, 740], 1494);
                step(f, Op::Copy(ValueType::Float), &[740, 16], 1495);
                step(f, Op::Copy(ValueType::Float), &[726, 17], 1496);
                step(f, Op::GetTransform, &[37, 71, 122, 94], 1497);
                step(f, Op::BreakTransform, &[94, 408, 72, 409], 1498);
                step(f, Op::PelvisLean, &[1, 108, 113, 114, 758, 759], 1499);
                step(f, Op::LengthV, &[2, 713], 1500);
                step(f, Op::RemapF, &[713, 845, 108, 845, 106, 122, 741], 1501);
                step(f, Op::MulF, &[15, 107, 744], 1502);
                step(f, Op::SubF, &[847, 744, 745], 1503);
                step(f, Op::MulF, &[741, 745, 746], 1504);
                step(f, Op::MulF, &[12, 867, 742], 1505);
                step(f, Op::SinF, &[742, 743], 1506);
                step(f, Op::MulF, &[746, 743, 747], 1507);
                step(f, Op::MulF, &[747, 714, 748], 1508);
                step(f, Op::AddF, &[748, 16, 749], 1509);
                step(f, Op::SubF, &[749, 3, 750], 1510);
                step(f, Op::MakeVector, &[845, 759, 750, 410], 1511);
                step(f, Op::AddV, &[408, 410, 411], 1512);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 71, 90], 1513);
                step(f, Op::BreakTransform, &[90, 396, 66, 397], 1514);
                step(f, Op::BreakVector, &[396, 760, 761, 762], 1515);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 72, 91], 1516);
                step(f, Op::BreakTransform, &[91, 398, 67, 399], 1517);
                step(f, Op::BreakVector, &[398, 763, 764, 765], 1518);
                step(f, Op::SubF, &[762, 765, 766], 1519);
                step(f, Op::PelvisSideLean, &[766, 115, 116, 767], 1520);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 71, 92], 1521);
                step(f, Op::BreakTransform, &[92, 402, 68, 403], 1522);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 72, 93], 1523);
                step(f, Op::BreakTransform, &[93, 404, 69, 405], 1524);
                step(f, Op::SlerpQ, &[68, 69, 846, 70], 1525);
                step(f, Op::EulerFromQuat, &[70, 71, 406], 1526);
                step(f, Op::BreakVector, &[406, 754, 755, 756], 1527);
                step(f, Op::RemapF, &[713, 109, 108, 845, 110, 122, 752], 1528);
                step(f, Op::SubV, &[396, 398, 400], 1529);
                step(f, Op::RotateVector, &[0, 470, 401], 1530);
                step(f, Op::DotV, &[400, 401, 751], 1531);
                step(f, Op::MulF, &[752, 751, 753], 1532);
                step(f, Op::AddF, &[756, 753, 757], 1533);
                step(f, Op::MakeVector, &[758, 767, 757, 407], 1534);
                step(f, Op::QuatFromEuler, &[407, 71, 71], 1535);
                step(f, Op::MakeTransform, &[411, 71, 465, 95], 1536);
                step(f, Op::SetTransform, &[38, 95, 71, 122, 847], 1537);
                step(f, Op::GetTransform, &[39, 72, 122, 96], 1538);
                step(f, Op::BreakTransform, &[96, 412, 76, 413], 1539);
                step(f, Op::QuatFromAxisAngle, &[468, 753, 73], 1540);
                step(f, Op::DivF, &[111, 863, 768], 1541);
                step(f, Op::QuatScale, &[73, 768, 74], 1542);
                step(f, Op::MulQ, &[76, 74, 80], 1543);
                step(f, Op::MakeTransform, &[412, 80, 465, 100], 1544);
                step(f, Op::SetTransform, &[40, 100, 72, 122, 847], 1545);
                step(f, Op::GetTransform, &[41, 72, 122, 97], 1546);
                step(f, Op::BreakTransform, &[97, 414, 77, 415], 1547);
                step(f, Op::MulQ, &[77, 74, 81], 1548);
                step(f, Op::MakeTransform, &[414, 81, 465, 101], 1549);
                step(f, Op::SetTransform, &[42, 101, 72, 122, 847], 1550);
                step(f, Op::GetTransform, &[43, 72, 122, 98], 1551);
                step(f, Op::BreakTransform, &[98, 416, 78, 417], 1552);
                step(f, Op::MulQ, &[78, 74, 82], 1553);
                step(f, Op::MakeTransform, &[416, 82, 465, 102], 1554);
                step(f, Op::SetTransform, &[44, 102, 72, 122, 847], 1555);
                step(f, Op::GetTransform, &[45, 72, 122, 99], 1556);
                step(f, Op::BreakTransform, &[99, 418, 79, 419], 1557);
                step(f, Op::QuatScale, &[73, 112, 75], 1558);
                step(f, Op::MulQ, &[79, 75, 83], 1559);
                step(f, Op::MakeTransform, &[418, 83, 465, 103], 1560);
                step(f, Op::SetTransform, &[46, 103, 72, 122, 847], 1561);
                step(f, Op::Or, &[1, 2, 117], 1562);
                step(f, Op::Copy(ValueType::Float), &[845, 770], 1563);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1564);
                step(f, Op::Copy(ValueType::Int), &[71, 66], 1565);
                1565
            }
            1565 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 66, 25, 67, 68, 1612], 1566)
            }
            1566 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 67, 112], 1567);
                step(f, Op::GetParent, &[25, 26], 1568);
                step(f, Op::GetParent, &[26, 27], 1569);
                step(f, Op::GetTransform, &[27, 71, 123, 104], 1570);
                step(f, Op::BreakTransform, &[104, 420, 84, 421], 1571);
                step(f, Op::BreakVector, &[420, 771, 772, 773], 1572);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 67, 105], 1573);
                step(f, Op::BreakTransform, &[105, 422, 85, 423], 1574);
                step(f, Op::BreakVector, &[422, 774, 775, 776], 1575);
                step(f, Op::ArrayAt(Elem::Float), &[1, 67, 780], 1576);
                step(f, Op::MulF, &[780, 117, 781], 1577);
                step(f, Op::MulF, &[781, 781, 782], 1578);
                step(f, Op::SubF, &[771, 774, 777], 1579);
                step(f, Op::SubF, &[772, 775, 778], 1580);
                step(f, Op::MakeVector, &[777, 778, 845, 424], 1581);
                step(f, Op::DotV, &[424, 424, 779], 1582);
                step(f, Op::SubF, &[782, 779, 783], 1583);
                step(f, Op::SqrtF, &[783, 784], 1584);
                step(f, Op::AddF, &[776, 784, 785], 1585);
                step(f, Op::SubF, &[773, 785, 786], 1586);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 67, 106], 1587);
                step(f, Op::BreakTransform, &[106, 425, 86, 426], 1588);
                step(f, Op::BreakVector, &[425, 787, 788, 789], 1589);
                step(f, Op::AddF, &[789, 50, 790], 1590);
                step(f, Op::MinF, &[776, 790, 791], 1591);
                step(f, Op::AddF, &[791, 784, 792], 1592);
                step(f, Op::SubF, &[773, 792, 793], 1593);
                step(f, Op::Equals(Elem::Int), &[67, 71, 113], 1594);
                step(f, Op::Select(ValueType::Int), &[113, 72, 71, 69], 1595);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 69, 114], 1596);
                step(f, Op::ArrayAt(Elem::Float), &[2, 69, 797], 1597);
                step(f, Op::RemapF, &[797, 846, 847, 845, 847, 122, 798], 1598);
                step(f, Op::RemapF, &[797, 845, 120, 847, 845, 122, 799], 1599);
                step(f, Op::MaxF, &[798, 799, 800], 1600);
                step(f, Op::Select(ValueType::Float), &[114, 847, 800, 801], 1601);
                step(f, Op::LerpF, &[786, 793, 801, 802], 1602);
                step(f, Op::ArrayAt(Elem::Float), &[2, 67, 794], 1603);
                step(f, Op::RemapF, &[794, 846, 847, 845, 847, 122, 795], 1604);
                step(f, Op::MulF, &[802, 795, 803], 1605);
                step(f, Op::RemapF, &[794, 845, 120, 847, 845, 122, 796], 1606);
                step(f, Op::MulF, &[786, 796, 804], 1607);
                step(f, Op::MaxF, &[803, 804, 805], 1608);
                step(f, Op::Select(ValueType::Float), &[112, 786, 805, 806], 1609);
                step(f, Op::MaxF, &[770, 806, 807], 1610);
                step(f, Op::Copy(ValueType::Float), &[807, 770], 1611);
                step(f, Op::Jump, &[1565], 1612)
            }
            1612 => {
                step(f, Op::ClampF, &[770, 845, 118, 808], 1613);
                step(f, Op::Copy(ValueType::Float), &[808, 769], 1614);
                step(f, Op::MakeVector, &[18, 845, 845, 427], 1615);
                step(f, Op::MakeVector, &[769, 845, 845, 428], 1616);
                step(f, Op::MakeVector, &[19, 845, 845, 429], 1617);
                step(f, Op::GreaterF, &[769, 18, 115], 1618);
                step(f, Op::Select(ValueType::Float), &[115, 122, 119, 809], 1619);
                step(f, Op::Copy(ValueType::Float), &[49, 811], 1620);
                step(f, Op::SubV, &[428, 429, 434], 1621);
                step(f, Op::DeltaTime, &[812], 1622);
                step(f, Op::DivF, &[811, 812, 813], 1623);
                step(f, Op::ScaleV, &[434, 813, 435], 1624);
                step(f, Op::AddV, &[428, 435, 436], 1625);
                step(f, Op::AddV, &[429, 435, 437], 1626);
                step(f, Op::SubV, &[427, 437, 438], 1627);
                step(f, Op::FloatLerp, &[845, 847, 809, 814], 1628);
                step(f, Op::SubF, &[847, 814, 815], 1629);
                step(f, Op::ScaleV, &[438, 815, 439], 1630);
                step(f, Op::AddV, &[436, 439, 441], 1631);
                step(f, Op::MulF, &[809, 812, 816], 1632);
                step(f, Op::GreaterF, &[816, 845, 116], 1633);
                step(f, Op::DivF, &[814, 816, 817], 1634);
                step(f, Op::Select(ValueType::Float), &[116, 817, 847, 818], 1635);
                step(f, Op::ScaleV, &[434, 818, 440], 1636);
                step(f, Op::SubV, &[441, 440, 442], 1637);
                step(f, Op::Copy(ValueType::Vec3), &[442, 433], 1638);
                step(f, Op::BreakVector, &[433, 819, 820, 821], 1639);
                step(f, Op::Select(ValueType::Float), &[117, 769, 819, 822], 1640);
                step(f, Op::Copy(ValueType::Float), &[822, 18], 1641);
                step(f, Op::Copy(ValueType::Float), &[769, 19], 1642);
                step(f, Op::GetTransform, &[47, 71, 123, 107], 1643);
                step(f, Op::BreakTransform, &[107, 443, 87, 444], 1644);
                step(f, Op::MakeVector, &[845, 845, 18, 445], 1645);
                step(f, Op::SubV, &[443, 445, 446], 1646);
                step(f, Op::MakeTransform, &[446, 87, 465, 108], 1647);
                step(f, Op::SetTransform, &[48, 108, 71, 122, 847], 1648);
                step(f, Op::JumpIfFalse, &[8, 1655], 1649)
            }
            1649 => {
                step(f, Op::GetTransform, &[47, 71, 123, 107], 1650);
                step(f, Op::BreakTransform, &[107, 443, 87, 444], 1651);
                step(f, Op::SubV, &[443, 445, 446], 1652);
                step(f, Op::MakeTransform, &[446, 87, 465, 108], 1653);
                step(f, Op::DrawTransform, &[108, 868, 846], 1654);
                step(f, Op::Jump, &[1655], 1655)
            }
            1655 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1656);
                step(f, Op::Copy(ValueType::Int), &[71, 8], 1657);
                1657
            }
            1657 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 8, 2, 9, 10, 1706], 1658)
            }
            1658 => {
                step(f, Op::GetParent, &[2, 29], 1659);
                step(f, Op::GetParent, &[29, 30], 1660);
                step(f, Op::GetTransform, &[30, 71, 123, 110], 1661);
                step(f, Op::BreakTransform, &[110, 448, 88, 449], 1662);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 9, 111], 1663);
                step(f, Op::BreakTransform, &[111, 450, 89, 451], 1664);
                step(f, Op::SubV, &[450, 448, 452], 1665);
                step(f, Op::LengthV, &[452, 835], 1666);
                step(f, Op::ArrayAt(Elem::Float), &[1, 9, 824], 1667);
                step(f, Op::MulF, &[824, 129, 825], 1668);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 9, 118], 1669);
                step(f, Op::ArrayAt(Elem::Float), &[2, 9, 826], 1670);
                step(f, Op::ClampF, &[826, 845, 847, 827], 1671);
                step(f, Op::LessF, &[827, 846, 119], 1672);
                step(f, Op::SmoothStepF, &[827, 131, 132, 830], 1673);
                step(f, Op::MulF, &[827, 855, 828], 1674);
                step(f, Op::SinF, &[828, 829], 1675);
                step(f, Op::MaxF, &[830, 829, 831], 1676);
                step(f, Op::Select(ValueType::Float), &[119, 831, 829, 832], 1677);
                step(f, Op::MulF, &[832, 130, 833], 1678);
                step(f, Op::Select(ValueType::Float), &[118, 845, 833, 834], 1679);
                step(f, Op::SubF, &[825, 834, 836], 1680);
                step(f, Op::SubF, &[835, 836, 837], 1681);
                step(f, Op::MaxF, &[837, 845, 838], 1682);
                step(f, Op::MulF, &[838, 838, 839], 1683);
                step(f, Op::AddF, &[838, 834, 840], 1684);
                step(f, Op::DivF, &[839, 840, 841], 1685);
                step(f, Op::SubF, &[835, 841, 842], 1686);
                step(f, Op::DivF, &[842, 835, 843], 1687);
                step(f, Op::ScaleV, &[452, 843, 453], 1688);
                step(f, Op::AddV, &[448, 453, 454], 1689);
                step(f, Op::ClampSpatially, &[454, 448, 845, 825, 455], 1690);
                step(f, Op::MakeTransform, &[455, 89, 465, 112], 1691);
                step(f, Op::Equals(Elem::Int), &[9, 71, 120], 1692);
                step(f, Op::Select(ValueType::Vec3), &[120, 473, 472, 460], 1693);
                step(f, Op::Select(ValueType::Vec3), &[120, 470, 474, 461], 1694);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 9, 113], 1695);
                step(f, Op::BreakTransform, &[113, 456, 90, 457], 1696);
                step(f, Op::ArrayAt(Elem::Vec3), &[3, 9, 458], 1697);
                step(f, Op::KneeVector, &[90, 0, 458, 133, 134, 459], 1698);
                step(f, Op::TwoBoneIK, &[30, 29, 2, 112, 460, 461, 459, 71, 847, 123, 865, 866, 122, 121, 844], 1699);
                step(f, Op::JumpIfFalse, &[8, 1705], 1700)
            }
            1700 => {
                step(f, Op::GetTransform, &[29, 71, 123, 114], 1701);
                step(f, Op::BreakTransform, &[114, 462, 91, 463], 1702);
                step(f, Op::AddV, &[462, 459, 464], 1703);
                step(f, Op::DrawLine, &[462, 464, 846, 475], 1704);
                step(f, Op::Jump, &[1705], 1705)
            }
            1705 => {
                step(f, Op::Jump, &[1657], 1706)
            }
            1706 => {
                step(f, Op::End, &[], 1707)
            }
            _ => return,
        } };
    }
}
