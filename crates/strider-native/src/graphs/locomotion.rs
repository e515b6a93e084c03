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
    fingerprint: 0x35057b99d49fbe6d,
    forward,
};

fn forward(f: &mut Frame<'_>) {
    let mut pc: usize = 375;
    loop {
        // SAFETY: each `step` is an instruction of the program this code was generated
        // from, with its own operands; `NATIVE` runs only on that program (fingerprint).
        pc = unsafe { match pc {
            375 => {
                step(f, Op::WorldTransform, &[12], 376);
                step(f, Op::BreakTransform, &[12, 30, 7, 31], 377);
                step(f, Op::Select(ValueType::Transform), &[0, 0, 12, 13], 378);
                step(f, Op::BreakTransform, &[13, 32, 8, 33], 379);
                step(f, Op::SubV, &[30, 32, 34], 380);
                step(f, Op::LengthV, &[34, 105], 381);
                step(f, Op::GreaterF, &[105, 21, 4], 382);
                step(f, Op::Copy(ValueType::Bool), &[4, 1], 383);
                step(f, Op::MakeRelative, &[13, 12, 17], 384);
                step(f, Op::Select(ValueType::Transform), &[4, 96, 17, 18], 385);
                step(f, Op::Copy(ValueType::Transform), &[18, 2], 386);
                step(f, Op::InverseT, &[13, 15], 387);
                step(f, Op::MulT, &[12, 15, 16], 388);
                step(f, Op::Copy(ValueType::Transform), &[16, 1], 389);
                step(f, Op::TransformVector, &[2, 0, 37], 390);
                step(f, Op::InverseT, &[12, 14], 391);
                step(f, Op::DeltaTime, &[104], 392);
                step(f, Op::DivF, &[432, 104, 106], 393);
                step(f, Op::ScaleV, &[34, 106, 35], 394);
                step(f, Op::TransformVector, &[14, 35, 36], 395);
                step(f, Op::Select(ValueType::Vec3), &[1, 37, 36, 39], 396);
                step(f, Op::VectorLerp, &[37, 39, 22, 430, 40], 397);
                step(f, Op::Copy(ValueType::Vec3), &[40, 0], 398);
                step(f, Op::TransformVector, &[2, 1, 38], 399);
                step(f, Op::TransformVector, &[2, 0, 37], 400);
                step(f, Op::Select(ValueType::Vec3), &[1, 37, 36, 39], 401);
                step(f, Op::VectorLerp, &[38, 39, 23, 430, 41], 402);
                step(f, Op::Copy(ValueType::Vec3), &[41, 1], 403);
                step(f, Op::JumpIfFalse, &[1, 418], 404)
            }
            404 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 12], 405);
                step(f, Op::Copy(ValueType::Int), &[52, 16], 406);
                406
            }
            406 => {
                step(f, Op::ForEachNext(Elem::Bone), &[12, 16, 13, 17, 18, 416], 407)
            }
            407 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 17, 20], 408);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 17, 20], 409);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 17, 20], 410);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 17, 20], 411);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 17, 20], 412);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 17, 20], 413);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 17, 20], 414);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 17, 20], 415);
                step(f, Op::Jump, &[406], 416)
            }
            416 => {
                step(f, Op::Copy(ValueType::Float), &[430, 7], 417);
                step(f, Op::Jump, &[418], 418)
            }
            418 => {
                step(f, Op::WorldTransform, &[12], 419);
                step(f, Op::Copy(ValueType::Transform), &[12, 0], 420);
                step(f, Op::Copy(ValueType::Bool), &[48, 0], 421);
                step(f, Op::JumpIfFalse, &[3, 428], 422)
            }
            422 => {
                step(f, Op::GetTransform, &[34, 52, 48, 19], 423);
                step(f, Op::BreakTransform, &[19, 42, 9, 43], 424);
                step(f, Op::ScaleV, &[0, 433, 44], 425);
                step(f, Op::AddV, &[42, 44, 45], 426);
                step(f, Op::DrawArrow, &[42, 45, 431, 304], 427);
                step(f, Op::Jump, &[428], 428)
            }
            428 => {
                step(f, Op::Copy(ValueType::Bool), &[49, 6], 429);
                step(f, Op::Copy(ValueType::Bool), &[48, 7], 430);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 431);
                step(f, Op::Copy(ValueType::Int), &[52, 22], 432);
                432
            }
            432 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 22, 8, 23, 24, 438], 433)
            }
            433 => {
                step(f, Op::Not, &[8, 9], 434);
                step(f, Op::JumpIfFalse, &[9, 437], 435)
            }
            435 => {
                step(f, Op::Copy(ValueType::Bool), &[49, 7], 436);
                step(f, Op::Jump, &[437], 437)
            }
            437 => {
                step(f, Op::Jump, &[432], 438)
            }
            438 => {
                step(f, Op::Copy(ValueType::Bool), &[7, 6], 439);
                step(f, Op::Jump, &[440], 440)
            }
            440 => {
                step(f, Op::Copy(ValueType::Bool), &[49, 10], 441);
                step(f, Op::Copy(ValueType::Bool), &[48, 11], 442);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 443);
                step(f, Op::Copy(ValueType::Int), &[52, 25], 444);
                444
            }
            444 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 25, 15, 26, 27, 459], 445)
            }
            445 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 26, 21], 446);
                step(f, Op::BreakTransform, &[21, 46, 10, 47], 447);
                step(f, Op::BreakVector, &[46, 115, 116, 117], 448);
                step(f, Op::MakeVector, &[115, 116, 430, 50], 449);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 26, 22], 450);
                step(f, Op::BreakTransform, &[22, 48, 11, 49], 451);
                step(f, Op::BreakVector, &[48, 118, 119, 120], 452);
                step(f, Op::MakeVector, &[118, 119, 430, 51], 453);
                step(f, Op::DistanceV, &[50, 51, 121], 454);
                step(f, Op::GreaterF, &[121, 17, 12], 455);
                step(f, Op::JumpIfFalse, &[12, 458], 456)
            }
            456 => {
                step(f, Op::Copy(ValueType::Bool), &[49, 11], 457);
                step(f, Op::Jump, &[458], 458)
            }
            458 => {
                step(f, Op::Jump, &[444], 459)
            }
            459 => {
                step(f, Op::Copy(ValueType::Bool), &[11, 10], 460);
                step(f, Op::Jump, &[461], 461)
            }
            461 => {
                step(f, Op::And, &[6, 10, 13], 462);
                step(f, Op::LengthV, &[0, 107], 463);
                step(f, Op::GreaterF, &[107, 15, 5], 464);
                step(f, Op::Not, &[5, 14], 465);
                step(f, Op::And, &[13, 14, 16], 466);
                step(f, Op::DeltaTime, &[132], 467);
                step(f, Op::MulF, &[132, 20, 133], 468);
                step(f, Op::AddF, &[4, 133, 134], 469);
                step(f, Op::GreaterF, &[4, 431, 17], 470);
                step(f, Op::AddF, &[19, 431, 130], 471);
                step(f, Op::Select(ValueType::Float), &[17, 130, 19, 131], 472);
                step(f, Op::MinF, &[134, 131, 135], 473);
                step(f, Op::RemapF, &[107, 15, 16, 430, 432, 48, 122], 474);
                step(f, Op::Select(ValueType::Float), &[14, 18, 432, 123], 475);
                step(f, Op::Select(ValueType::Float), &[13, 122, 123, 124], 476);
                step(f, Op::LerpF, &[9, 30, 6, 110], 477);
                step(f, Op::RemapF, &[107, 12, 13, 10, 11, 48, 108], 478);
                step(f, Op::LerpF, &[108, 29, 6, 109], 479);
                step(f, Op::MaxF, &[107, 14, 111], 480);
                step(f, Op::DivF, &[109, 111, 112], 481);
                step(f, Op::AddF, &[110, 112, 113], 482);
                step(f, Op::DivF, &[124, 113, 125], 483);
                step(f, Op::AddF, &[2, 125, 126], 484);
                step(f, Op::DivF, &[434, 126, 127], 485);
                step(f, Op::GreaterF, &[126, 430, 15], 486);
                step(f, Op::CycleStep, &[4, 127, 430, 15, 128, 129], 487);
                step(f, Op::Select(ValueType::Float), &[16, 135, 128, 136], 488);
                step(f, Op::Copy(ValueType::Float), &[136, 4], 489);
                step(f, Op::Copy(ValueType::Float), &[125, 2], 490);
                step(f, Op::Copy(ValueType::Bool), &[5, 2], 491);
                step(f, Op::Copy(ValueType::Float), &[112, 0], 492);
                step(f, Op::Copy(ValueType::Float), &[113, 1], 493);
                step(f, Op::DivF, &[110, 113, 114], 494);
                step(f, Op::Copy(ValueType::Float), &[114, 3], 495);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 496);
                step(f, Op::Copy(ValueType::Int), &[52, 19], 497);
                497
            }
            497 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 19, 14, 20, 21, 504], 498)
            }
            498 => {
                step(f, Op::ToFloat, &[20, 137], 499);
                step(f, Op::MulF, &[137, 431, 138], 500);
                step(f, Op::AddF, &[4, 138, 139], 501);
                step(f, Op::FractF, &[139, 140], 502);
                step(f, Op::ArraySetAt(Elem::Float), &[0, 20, 140], 503);
                step(f, Op::Jump, &[497], 504)
            }
            504 => {
                step(f, Op::Select(ValueType::Vec3), &[2, 0, 302, 52], 505);
                step(f, Op::MovementAngleOffset, &[52, 5, 4, 24, 25, 435, 26, 436, 141], 506);
                step(f, Op::Copy(ValueType::Float), &[141, 5], 507);
                step(f, Op::QuatFromAxisAngle, &[305, 5, 12], 508);
                step(f, Op::Copy(ValueType::Quat), &[12, 0], 509);
                step(f, Op::SinF, &[5, 142], 510);
                step(f, Op::AbsF, &[142, 143], 511);
                step(f, Op::RemapF, &[143, 27, 28, 430, 432, 48, 144], 512);
                step(f, Op::Copy(ValueType::Float), &[144, 6], 513);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 514);
                step(f, Op::Copy(ValueType::Int), &[52, 1], 515);
                515
            }
            515 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 1, 0, 2, 3, 1087], 516)
            }
            516 => {
                step(f, Op::Copy(ValueType::Bone), &[0, 16], 517);
                step(f, Op::Copy(ValueType::Int), &[2, 28], 518);
                step(f, Op::GetTransform, &[35, 52, 48, 23], 519);
                step(f, Op::BreakTransform, &[23, 55, 13, 56], 520);
                step(f, Op::BreakVector, &[55, 155, 156, 157], 521);
                step(f, Op::SubF, &[432, 6, 153], 522);
                step(f, Op::MulF, &[5, 153, 154], 523);
                step(f, Op::QuatFromAxisAngle, &[305, 154, 15], 524);
                step(f, Op::GetTransform, &[16, 52, 48, 24], 525);
                step(f, Op::BreakTransform, &[24, 57, 14, 58], 526);
                step(f, Op::SubV, &[57, 55, 59], 527);
                step(f, Op::BreakVector, &[59, 150, 151, 152], 528);
                step(f, Op::MakeVector, &[150, 151, 430, 60], 529);
                step(f, Op::RotateVector, &[15, 60, 61], 530);
                step(f, Op::BreakVector, &[61, 158, 159, 160], 531);
                step(f, Op::MulF, &[31, 6, 161], 532);
                step(f, Op::Equals(Elem::Int), &[28, 52, 18], 533);
                step(f, Op::Select(ValueType::Float), &[18, 432, 437, 170], 534);
                step(f, Op::MulF, &[161, 170, 162], 535);
                step(f, Op::AddF, &[158, 162, 163], 536);
                step(f, Op::AddF, &[155, 163, 164], 537);
                step(f, Op::AddF, &[156, 159, 165], 538);
                step(f, Op::BreakVector, &[57, 166, 167, 168], 539);
                step(f, Op::SubF, &[168, 34, 169], 540);
                step(f, Op::MakeVector, &[164, 165, 169, 62], 541);
                step(f, Op::ArrayAt(Elem::Float), &[0, 28, 145], 542);
                step(f, Op::SubF, &[3, 145, 146], 543);
                step(f, Op::MaxF, &[146, 430, 147], 544);
                step(f, Op::MulF, &[147, 1, 148], 545);
                step(f, Op::ScaleV, &[0, 148, 53], 546);
                step(f, Op::AddV, &[62, 53, 63], 547);
                step(f, Op::MulF, &[0, 431, 149], 548);
                step(f, Op::ScaleV, &[0, 149, 54], 549);
                step(f, Op::AddV, &[63, 54, 64], 550);
                step(f, Op::RotateVector, &[0, 306, 65], 551);
                step(f, Op::Copy(ValueType::Vec3), &[64, 72], 552);
                step(f, Op::Copy(ValueType::Vec3), &[65, 73], 553);
                step(f, Op::Copy(ValueType::Float), &[170, 180], 554);
                step(f, Op::Copy(ValueType::Vec3), &[302, 74], 555);
                step(f, Op::Copy(ValueType::Vec3), &[302, 75], 556);
                step(f, Op::Copy(ValueType::Bool), &[49, 19], 557);
                step(f, Op::Copy(ValueType::Float), &[438, 181], 558);
                step(f, Op::Copy(ValueType::Vec3), &[302, 76], 559);
                step(f, Op::Copy(ValueType::Vec3), &[305, 77], 560);
                step(f, Op::Copy(ValueType::Bool), &[49, 20], 561);
                step(f, Op::MulI, &[0, 0, 34], 562);
                step(f, Op::Copy(ValueType::Int), &[34, 33], 563);
                step(f, Op::Copy(ValueType::Int), &[52, 29], 564);
                step(f, Op::SubI, &[0, 53, 37], 565);
                step(f, Op::DivI, &[37, 54, 38], 566);
                step(f, Op::MakeVector, &[430, 430, 39, 82], 567);
                step(f, Op::ScaleV, &[73, 41, 87], 568);
                568
            }
            568 => {
                step(f, Op::ForNext, &[29, 33, 31, 608], 569)
            }
            569 => {
                step(f, Op::ModI, &[31, 0, 35], 570);
                step(f, Op::ToFloat, &[35, 182], 571);
                step(f, Op::MulF, &[182, 40, 184], 572);
                step(f, Op::MulF, &[184, 180, 185], 573);
                step(f, Op::MakeVector, &[185, 430, 430, 78], 574);
                step(f, Op::DivI, &[31, 0, 36], 575);
                step(f, Op::SubI, &[36, 38, 39], 576);
                step(f, Op::ToFloat, &[39, 183], 577);
                step(f, Op::MulF, &[183, 40, 186], 578);
                step(f, Op::ScaleV, &[73, 186, 79], 579);
                step(f, Op::AddV, &[78, 79, 80], 580);
                step(f, Op::AddV, &[72, 80, 81], 581);
                step(f, Op::AddV, &[81, 82, 83], 582);
                step(f, Op::SubV, &[81, 82, 84], 583);
                step(f, Op::SphereTrace, &[83, 84, 38, 21, 85, 86, 187], 584);
                step(f, Op::BreakVector, &[85, 189, 190, 191], 585);
                step(f, Op::AddV, &[83, 87, 88], 586);
                step(f, Op::AddV, &[84, 87, 89], 587);
                step(f, Op::SphereTrace, &[88, 89, 38, 22, 90, 91, 188], 588);
                step(f, Op::BreakVector, &[90, 192, 193, 194], 589);
                step(f, Op::SubF, &[191, 194, 195], 590);
                step(f, Op::AbsF, &[195, 196], 591);
                step(f, Op::Select(ValueType::Float), &[21, 430, 432, 197], 592);
                step(f, Op::AddF, &[196, 197, 202], 593);
                step(f, Op::LengthV, &[80, 198], 594);
                step(f, Op::RemapF, &[198, 430, 439, 430, 432, 48, 199], 595);
                step(f, Op::MinF, &[191, 194, 200], 596);
                step(f, Op::RemapF, &[200, 440, 439, 432, 431, 48, 201], 597);
                step(f, Op::AddF, &[199, 201, 203], 598);
                step(f, Op::AddF, &[202, 203, 204], 599);
                step(f, Op::LessF, &[204, 181, 23], 600);
                step(f, Op::And, &[21, 23, 24], 601);
                step(f, Op::JumpIfFalse, &[24, 607], 602)
            }
            602 => {
                step(f, Op::Copy(ValueType::Float), &[204, 181], 603);
                step(f, Op::Copy(ValueType::Vec3), &[85, 76], 604);
                step(f, Op::Copy(ValueType::Vec3), &[86, 77], 605);
                step(f, Op::Copy(ValueType::Bool), &[48, 20], 606);
                step(f, Op::Jump, &[607], 607)
            }
            607 => {
                step(f, Op::Jump, &[568], 608)
            }
            608 => {
                step(f, Op::JumpIfFalse, &[3, 611], 609)
            }
            609 => {
                step(f, Op::DrawSphere, &[76, 38, 306], 610);
                step(f, Op::Jump, &[611], 611)
            }
            611 => {
                step(f, Op::Copy(ValueType::Vec3), &[76, 74], 612);
                step(f, Op::Copy(ValueType::Vec3), &[77, 75], 613);
                step(f, Op::Copy(ValueType::Bool), &[20, 19], 614);
                step(f, Op::Jump, &[615], 615)
            }
            615 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 28, 25], 616);
                step(f, Op::BreakTransform, &[25, 67, 19, 68], 617);
                step(f, Op::ArrayAt(Elem::Float), &[0, 28, 145], 618);
                step(f, Op::SubF, &[3, 145, 146], 619);
                step(f, Op::MaxF, &[146, 430, 147], 620);
                step(f, Op::MulF, &[147, 1, 148], 621);
                step(f, Op::ScaleV, &[0, 148, 53], 622);
                step(f, Op::SubV, &[74, 53, 66], 623);
                step(f, Op::Select(ValueType::Vec3), &[19, 66, 67, 69], 624);
                step(f, Op::VectorLerp, &[67, 69, 32, 430, 70], 625);
                step(f, Op::BreakVector, &[70, 176, 177, 178], 626);
                step(f, Op::ClampF, &[178, 42, 43, 179], 627);
                step(f, Op::MakeVector, &[176, 177, 179, 71], 628);
                step(f, Op::RotationFromNormal, &[75, 174, 175, 17], 629);
                step(f, Op::PerFootRotationFactor, &[5, 72, 73, 171], 630);
                step(f, Op::MulF, &[5, 171, 172], 631);
                step(f, Op::SubF, &[432, 6, 153], 632);
                step(f, Op::MulF, &[172, 153, 173], 633);
                step(f, Op::QuatFromAxisAngle, &[305, 173, 16], 634);
                step(f, Op::MulQ, &[17, 16, 18], 635);
                step(f, Op::Select(ValueType::Quat), &[19, 18, 19, 20], 636);
                step(f, Op::MakeTransform, &[71, 20, 303, 26], 637);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 28, 26], 638);
                step(f, Op::Copy(ValueType::Int), &[2, 40], 639);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 40, 27], 640);
                step(f, Op::MakeAbsolute, &[27, 2, 28], 641);
                step(f, Op::BreakTransform, &[28, 92, 21, 93], 642);
                step(f, Op::ClampSpatially, &[92, 302, 430, 46, 94], 643);
                step(f, Op::SubF, &[432, 6, 209], 644);
                step(f, Op::MulF, &[5, 209, 206], 645);
                step(f, Op::LimitRotationAroundZ, &[21, 206, 71, 22], 646);
                step(f, Op::MakeTransform, &[94, 22, 303, 29], 647);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 40, 29], 648);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 40, 25], 649);
                step(f, Op::JumpIfFalse, &[25, 702], 650)
            }
            650 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 40, 31], 651);
                step(f, Op::BreakTransform, &[31, 95, 23, 96], 652);
                step(f, Op::ArrayAt(Elem::Float), &[0, 40, 205], 653);
                step(f, Op::SubF, &[3, 205, 207], 654);
                step(f, Op::MulF, &[207, 1, 208], 655);
                step(f, Op::ScaleV, &[0, 208, 97], 656);
                step(f, Op::AddV, &[95, 97, 98], 657);
                step(f, Op::MakeTransform, &[98, 23, 303, 38], 658);
                step(f, Op::Copy(ValueType::Transform), &[38, 39], 659);
                step(f, Op::Copy(ValueType::Transform), &[96, 40], 660);
                step(f, Op::BreakTransform, &[39, 126, 28, 127], 661);
                step(f, Op::MakeVector, &[430, 430, 39, 128], 662);
                step(f, Op::AddV, &[126, 128, 129], 663);
                step(f, Op::SubV, &[126, 128, 130], 664);
                step(f, Op::LineTrace, &[129, 130, 31, 131, 132, 236], 665);
                step(f, Op::RotateVector, &[28, 305, 133], 666);
                step(f, Op::FindQuatBetween, &[133, 132, 29], 667);
                step(f, Op::MulQ, &[29, 28, 30], 668);
                step(f, Op::MulF, &[37, 36, 237], 669);
                step(f, Op::AddF, &[237, 45, 238], 670);
                step(f, Op::NegF, &[238, 239], 671);
                step(f, Op::MakeVector, &[430, 239, 430, 134], 672);
                step(f, Op::RotateVector, &[30, 134, 136], 673);
                step(f, Op::AddV, &[131, 136, 138], 674);
                step(f, Op::AddV, &[138, 128, 140], 675);
                step(f, Op::SubV, &[138, 128, 141], 676);
                step(f, Op::LineTrace, &[140, 141, 32, 144, 145, 241], 677);
                step(f, Op::BreakVector, &[144, 243, 244, 245], 678);
                step(f, Op::BreakVector, &[138, 249, 250, 251], 679);
                step(f, Op::SubF, &[245, 251, 255], 680);
                step(f, Op::Select(ValueType::Float), &[32, 255, 430, 257], 681);
                step(f, Op::AddF, &[41, 45, 240], 682);
                step(f, Op::MakeVector, &[430, 240, 430, 135], 683);
                step(f, Op::RotateVector, &[30, 135, 137], 684);
                step(f, Op::AddV, &[131, 137, 139], 685);
                step(f, Op::AddV, &[139, 128, 142], 686);
                step(f, Op::SubV, &[139, 128, 143], 687);
                step(f, Op::LineTrace, &[142, 143, 33, 146, 147, 242], 688);
                step(f, Op::BreakVector, &[146, 246, 247, 248], 689);
                step(f, Op::BreakVector, &[139, 252, 253, 254], 690);
                step(f, Op::SubF, &[248, 254, 256], 691);
                step(f, Op::Select(ValueType::Float), &[33, 256, 430, 258], 692);
                step(f, Op::MaxF, &[257, 258, 259], 693);
                step(f, Op::ClampF, &[259, 430, 44, 260], 694);
                step(f, Op::MakeVector, &[430, 430, 260, 148], 695);
                step(f, Op::AddV, &[131, 148, 149], 696);
                step(f, Op::MakeTransform, &[149, 30, 303, 41], 697);
                step(f, Op::Select(ValueType::Transform), &[31, 41, 39, 42], 698);
                step(f, Op::Copy(ValueType::Transform), &[42, 40], 699);
                step(f, Op::Jump, &[700], 700)
            }
            700 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 40, 40], 701);
                step(f, Op::Jump, &[761], 702)
            }
            702 => {
                step(f, Op::ArrayAt(Elem::Transform), &[2, 40, 43], 703);
                step(f, Op::MakeAbsolute, &[43, 2, 44], 704);
                step(f, Op::BreakTransform, &[44, 150, 31, 151], 705);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 40, 31], 706);
                step(f, Op::BreakTransform, &[31, 95, 23, 96], 707);
                step(f, Op::ArrayAt(Elem::Float), &[0, 40, 205], 708);
                step(f, Op::SubF, &[3, 205, 207], 709);
                step(f, Op::MulF, &[207, 1, 208], 710);
                step(f, Op::ScaleV, &[0, 208, 97], 711);
                step(f, Op::AddV, &[95, 97, 98], 712);
                step(f, Op::DivF, &[205, 3, 288], 713);
                step(f, Op::ClampF, &[288, 430, 432, 289], 714);
                step(f, Op::SubF, &[432, 289, 261], 715);
                step(f, Op::MulF, &[60, 261, 262], 716);
                step(f, Op::VectorLerp, &[150, 98, 262, 430, 152], 717);
                step(f, Op::MakeTransform, &[152, 23, 303, 45], 718);
                step(f, Op::Copy(ValueType::Transform), &[45, 46], 719);
                step(f, Op::Copy(ValueType::Transform), &[96, 47], 720);
                step(f, Op::BreakTransform, &[46, 153, 32, 154], 721);
                step(f, Op::MakeVector, &[430, 430, 39, 155], 722);
                step(f, Op::AddV, &[153, 155, 156], 723);
                step(f, Op::SubV, &[153, 155, 157], 724);
                step(f, Op::LineTrace, &[156, 157, 34, 158, 159, 263], 725);
                step(f, Op::RotateVector, &[32, 305, 160], 726);
                step(f, Op::FindQuatBetween, &[160, 159, 33], 727);
                step(f, Op::MulQ, &[33, 32, 34], 728);
                step(f, Op::MulF, &[37, 36, 264], 729);
                step(f, Op::AddF, &[264, 45, 265], 730);
                step(f, Op::NegF, &[265, 266], 731);
                step(f, Op::MakeVector, &[430, 266, 430, 161], 732);
                step(f, Op::RotateVector, &[34, 161, 163], 733);
                step(f, Op::AddV, &[158, 163, 165], 734);
                step(f, Op::AddV, &[165, 155, 167], 735);
                step(f, Op::SubV, &[165, 155, 168], 736);
                step(f, Op::LineTrace, &[167, 168, 35, 171, 172, 268], 737);
                step(f, Op::BreakVector, &[171, 270, 271, 272], 738);
                step(f, Op::BreakVector, &[165, 276, 277, 278], 739);
                step(f, Op::SubF, &[272, 278, 282], 740);
                step(f, Op::Select(ValueType::Float), &[35, 282, 430, 284], 741);
                step(f, Op::AddF, &[41, 45, 267], 742);
                step(f, Op::MakeVector, &[430, 267, 430, 162], 743);
                step(f, Op::RotateVector, &[34, 162, 164], 744);
                step(f, Op::AddV, &[158, 164, 166], 745);
                step(f, Op::AddV, &[166, 155, 169], 746);
                step(f, Op::SubV, &[166, 155, 170], 747);
                step(f, Op::LineTrace, &[169, 170, 36, 173, 174, 269], 748);
                step(f, Op::BreakVector, &[173, 273, 274, 275], 749);
                step(f, Op::BreakVector, &[166, 279, 280, 281], 750);
                step(f, Op::SubF, &[275, 281, 283], 751);
                step(f, Op::Select(ValueType::Float), &[36, 283, 430, 285], 752);
                step(f, Op::MaxF, &[284, 285, 286], 753);
                step(f, Op::ClampF, &[286, 430, 44, 287], 754);
                step(f, Op::MakeVector, &[430, 430, 287, 175], 755);
                step(f, Op::AddV, &[158, 175, 176], 756);
                step(f, Op::MakeTransform, &[176, 34, 303, 48], 757);
                step(f, Op::Select(ValueType::Transform), &[34, 48, 46, 49], 758);
                step(f, Op::Copy(ValueType::Transform), &[49, 47], 759);
                step(f, Op::Jump, &[760], 760)
            }
            760 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 40, 47], 761);
                761
            }
            761 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 40, 205], 762);
                step(f, Op::GreaterF, &[205, 3, 26], 763);
                step(f, Op::JumpIfFalse, &[26, 823], 764)
            }
            764 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 40, 25], 765);
                step(f, Op::JumpIfFalse, &[25, 767], 766)
            }
            766 => {
                step(f, Op::Jump, &[820], 767)
            }
            767 => {
                step(f, Op::ArrayAt(Elem::Transform), &[2, 40, 50], 768);
                step(f, Op::BreakTransform, &[50, 177, 35, 178], 769);
                step(f, Op::Equals(Elem::Int), &[40, 52, 27], 770);
                step(f, Op::Select(ValueType::Int), &[27, 53, 52, 41], 771);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 41, 32], 772);
                step(f, Op::BreakTransform, &[32, 99, 24, 100], 773);
                step(f, Op::SubF, &[432, 6, 209], 774);
                step(f, Op::MulF, &[5, 209, 210], 775);
                step(f, Op::FootAvoidance, &[177, 99, 210, 27, 61, 101], 776);
                step(f, Op::MakeTransform, &[101, 35, 303, 33], 777);
                step(f, Op::Copy(ValueType::Transform), &[33, 34], 778);
                step(f, Op::Copy(ValueType::Transform), &[96, 35], 779);
                step(f, Op::BreakTransform, &[34, 102, 25, 103], 780);
                step(f, Op::MakeVector, &[430, 430, 39, 104], 781);
                step(f, Op::AddV, &[102, 104, 105], 782);
                step(f, Op::SubV, &[102, 104, 106], 783);
                step(f, Op::LineTrace, &[105, 106, 28, 107, 108, 211], 784);
                step(f, Op::RotateVector, &[25, 305, 109], 785);
                step(f, Op::FindQuatBetween, &[109, 108, 26], 786);
                step(f, Op::MulQ, &[26, 25, 27], 787);
                step(f, Op::MulF, &[37, 36, 212], 788);
                step(f, Op::AddF, &[212, 45, 213], 789);
                step(f, Op::NegF, &[213, 214], 790);
                step(f, Op::MakeVector, &[430, 214, 430, 110], 791);
                step(f, Op::RotateVector, &[27, 110, 112], 792);
                step(f, Op::AddV, &[107, 112, 114], 793);
                step(f, Op::AddV, &[114, 104, 116], 794);
                step(f, Op::SubV, &[114, 104, 117], 795);
                step(f, Op::LineTrace, &[116, 117, 29, 120, 121, 216], 796);
                step(f, Op::BreakVector, &[120, 218, 219, 220], 797);
                step(f, Op::BreakVector, &[114, 224, 225, 226], 798);
                step(f, Op::SubF, &[220, 226, 230], 799);
                step(f, Op::Select(ValueType::Float), &[29, 230, 430, 232], 800);
                step(f, Op::AddF, &[41, 45, 215], 801);
                step(f, Op::MakeVector, &[430, 215, 430, 111], 802);
                step(f, Op::RotateVector, &[27, 111, 113], 803);
                step(f, Op::AddV, &[107, 113, 115], 804);
                step(f, Op::AddV, &[115, 104, 118], 805);
                step(f, Op::SubV, &[115, 104, 119], 806);
                step(f, Op::LineTrace, &[118, 119, 30, 122, 123, 217], 807);
                step(f, Op::BreakVector, &[122, 221, 222, 223], 808);
                step(f, Op::BreakVector, &[115, 227, 228, 229], 809);
                step(f, Op::SubF, &[223, 229, 231], 810);
                step(f, Op::Select(ValueType::Float), &[30, 231, 430, 233], 811);
                step(f, Op::MaxF, &[232, 233, 234], 812);
                step(f, Op::ClampF, &[234, 430, 44, 235], 813);
                step(f, Op::MakeVector, &[430, 430, 235, 124], 814);
                step(f, Op::AddV, &[107, 124, 125], 815);
                step(f, Op::MakeTransform, &[125, 27, 303, 36], 816);
                step(f, Op::Select(ValueType::Transform), &[28, 36, 34, 37], 817);
                step(f, Op::Copy(ValueType::Transform), &[37, 35], 818);
                step(f, Op::Jump, &[819], 819)
            }
            819 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 40, 35], 820);
                820
            }
            820 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 40, 30], 821);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 40, 30], 822);
                step(f, Op::Jump, &[983], 823)
            }
            823 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 40, 30], 824);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 40, 50], 825);
                step(f, Op::DivF, &[205, 3, 288], 826);
                step(f, Op::ClampF, &[288, 430, 432, 289], 827);
                step(f, Op::Copy(ValueType::Transform), &[30, 52], 828);
                step(f, Op::Copy(ValueType::Transform), &[50, 53], 829);
                step(f, Op::Copy(ValueType::Float), &[289, 290], 830);
                step(f, Op::Copy(ValueType::Transform), &[96, 54], 831);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[3, 2], 832);
                step(f, Op::ArrayReset(Elem::Vec3), &[2], 833);
                step(f, Op::BreakTransform, &[52, 183, 37, 184], 834);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 183], 835);
                step(f, Op::BreakTransform, &[52, 183, 37, 184], 836);
                step(f, Op::UnitV, &[0, 182], 837);
                step(f, Op::LengthV, &[0, 291], 838);
                step(f, Op::RemapF, &[291, 430, 47, 430, 48, 48, 292], 839);
                step(f, Op::ScaleV, &[182, 292, 187], 840);
                step(f, Op::SubV, &[183, 187, 193], 841);
                step(f, Op::MakeVector, &[430, 430, 50, 191], 842);
                step(f, Op::AddV, &[193, 191, 195], 843);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 195], 844);
                step(f, Op::BreakTransform, &[52, 183, 37, 184], 845);
                step(f, Op::UnitV, &[0, 182], 846);
                step(f, Op::LengthV, &[0, 291], 847);
                step(f, Op::RemapF, &[291, 430, 47, 430, 48, 48, 292], 848);
                step(f, Op::ScaleV, &[182, 292, 187], 849);
                step(f, Op::SubV, &[183, 187, 193], 850);
                step(f, Op::MakeVector, &[430, 430, 50, 191], 851);
                step(f, Op::AddV, &[193, 191, 195], 852);
                step(f, Op::RemapF, &[291, 430, 47, 430, 52, 48, 294], 853);
                step(f, Op::MakeVector, &[430, 430, 294, 189], 854);
                step(f, Op::AddV, &[195, 189, 199], 855);
                step(f, Op::BreakTransform, &[53, 185, 38, 186], 856);
                step(f, Op::BreakVector, &[185, 299, 300, 301], 857);
                step(f, Op::BreakVector, &[183, 296, 297, 298], 858);
                step(f, Op::SubF, &[301, 298, 302], 859);
                step(f, Op::MaxF, &[302, 430, 304], 860);
                step(f, Op::MulF, &[304, 54, 308], 861);
                step(f, Op::AbsF, &[302, 306], 862);
                step(f, Op::RemapF, &[306, 430, 57, 430, 56, 48, 307], 863);
                step(f, Op::AddF, &[308, 307, 310], 864);
                step(f, Op::MakeVector, &[430, 430, 310, 197], 865);
                step(f, Op::AddV, &[199, 197, 201], 866);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 201], 867);
                step(f, Op::BreakTransform, &[52, 183, 37, 184], 868);
                step(f, Op::UnitV, &[0, 182], 869);
                step(f, Op::LengthV, &[0, 291], 870);
                step(f, Op::RemapF, &[291, 430, 47, 430, 48, 48, 292], 871);
                step(f, Op::ScaleV, &[182, 292, 187], 872);
                step(f, Op::SubV, &[183, 187, 193], 873);
                step(f, Op::MakeVector, &[430, 430, 50, 191], 874);
                step(f, Op::AddV, &[193, 191, 195], 875);
                step(f, Op::RemapF, &[291, 430, 47, 430, 52, 48, 294], 876);
                step(f, Op::MakeVector, &[430, 430, 294, 189], 877);
                step(f, Op::AddV, &[195, 189, 199], 878);
                step(f, Op::BreakTransform, &[53, 185, 38, 186], 879);
                step(f, Op::BreakVector, &[185, 299, 300, 301], 880);
                step(f, Op::BreakVector, &[183, 296, 297, 298], 881);
                step(f, Op::SubF, &[301, 298, 302], 882);
                step(f, Op::MaxF, &[302, 430, 304], 883);
                step(f, Op::MulF, &[304, 54, 308], 884);
                step(f, Op::AbsF, &[302, 306], 885);
                step(f, Op::RemapF, &[306, 430, 57, 430, 56, 48, 307], 886);
                step(f, Op::AddF, &[308, 307, 310], 887);
                step(f, Op::MakeVector, &[430, 430, 310, 197], 888);
                step(f, Op::AddV, &[199, 197, 201], 889);
                step(f, Op::RemapF, &[291, 430, 47, 430, 49, 48, 293], 890);
                step(f, Op::ScaleV, &[182, 293, 188], 891);
                step(f, Op::AddV, &[185, 188, 194], 892);
                step(f, Op::MakeVector, &[430, 430, 51, 192], 893);
                step(f, Op::AddV, &[194, 192, 196], 894);
                step(f, Op::RemapF, &[291, 430, 47, 430, 53, 48, 295], 895);
                step(f, Op::MakeVector, &[430, 430, 295, 190], 896);
                step(f, Op::AddV, &[196, 190, 200], 897);
                step(f, Op::NegF, &[302, 303], 898);
                step(f, Op::MaxF, &[303, 430, 305], 899);
                step(f, Op::MulF, &[305, 55, 309], 900);
                step(f, Op::AddF, &[309, 307, 311], 901);
                step(f, Op::MakeVector, &[430, 430, 311, 198], 902);
                step(f, Op::AddV, &[200, 198, 202], 903);
                step(f, Op::LerpV, &[201, 202, 431, 203], 904);
                step(f, Op::GetTransform, &[36, 52, 48, 55], 905);
                step(f, Op::BreakTransform, &[55, 204, 39, 205], 906);
                step(f, Op::BreakVector, &[204, 321, 322, 323], 907);
                step(f, Op::SubF, &[432, 6, 315], 908);
                step(f, Op::MulF, &[58, 315, 316], 909);
                step(f, Op::MulF, &[5, 316, 317], 910);
                step(f, Op::QuatFromAxisAngle, &[305, 317, 40], 911);
                step(f, Op::SubV, &[203, 204, 206], 912);
                step(f, Op::BreakVector, &[206, 312, 313, 314], 913);
                step(f, Op::MakeVector, &[312, 313, 430, 207], 914);
                step(f, Op::RotateVector, &[40, 207, 208], 915);
                step(f, Op::BreakVector, &[208, 318, 319, 320], 916);
                step(f, Op::AddF, &[321, 318, 327], 917);
                step(f, Op::AddF, &[322, 319, 328], 918);
                step(f, Op::BreakVector, &[203, 324, 325, 326], 919);
                step(f, Op::MakeVector, &[327, 328, 326, 209], 920);
                step(f, Op::DistanceV, &[183, 185, 329], 921);
                step(f, Op::RemapF, &[329, 434, 441, 430, 432, 48, 330], 922);
                step(f, Op::LerpV, &[203, 209, 330, 210], 923);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 210], 924);
                step(f, Op::BreakTransform, &[53, 185, 38, 186], 925);
                step(f, Op::UnitV, &[0, 182], 926);
                step(f, Op::LengthV, &[0, 291], 927);
                step(f, Op::RemapF, &[291, 430, 47, 430, 49, 48, 293], 928);
                step(f, Op::ScaleV, &[182, 293, 188], 929);
                step(f, Op::AddV, &[185, 188, 194], 930);
                step(f, Op::MakeVector, &[430, 430, 51, 192], 931);
                step(f, Op::AddV, &[194, 192, 196], 932);
                step(f, Op::RemapF, &[291, 430, 47, 430, 53, 48, 295], 933);
                step(f, Op::MakeVector, &[430, 430, 295, 190], 934);
                step(f, Op::AddV, &[196, 190, 200], 935);
                step(f, Op::BreakVector, &[185, 299, 300, 301], 936);
                step(f, Op::BreakTransform, &[52, 183, 37, 184], 937);
                step(f, Op::BreakVector, &[183, 296, 297, 298], 938);
                step(f, Op::SubF, &[301, 298, 302], 939);
                step(f, Op::NegF, &[302, 303], 940);
                step(f, Op::MaxF, &[303, 430, 305], 941);
                step(f, Op::MulF, &[305, 55, 309], 942);
                step(f, Op::AbsF, &[302, 306], 943);
                step(f, Op::RemapF, &[306, 430, 57, 430, 56, 48, 307], 944);
                step(f, Op::AddF, &[309, 307, 311], 945);
                step(f, Op::MakeVector, &[430, 430, 311, 198], 946);
                step(f, Op::AddV, &[200, 198, 202], 947);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 202], 948);
                step(f, Op::BreakTransform, &[53, 185, 38, 186], 949);
                step(f, Op::UnitV, &[0, 182], 950);
                step(f, Op::LengthV, &[0, 291], 951);
                step(f, Op::RemapF, &[291, 430, 47, 430, 49, 48, 293], 952);
                step(f, Op::ScaleV, &[182, 293, 188], 953);
                step(f, Op::AddV, &[185, 188, 194], 954);
                step(f, Op::MakeVector, &[430, 430, 51, 192], 955);
                step(f, Op::AddV, &[194, 192, 196], 956);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 196], 957);
                step(f, Op::BreakTransform, &[53, 185, 38, 186], 958);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 185], 959);
                step(f, Op::JumpIfFalse, &[3, 962], 960)
            }
            960 => {
                step(f, Op::DrawSpline, &[2, 52, 55, 431, 307], 961);
                step(f, Op::Jump, &[962], 962)
            }
            962 => {
                step(f, Op::Spline, &[2, 290, 52, 211, 212], 963);
                step(f, Op::BreakTransform, &[52, 183, 37, 184], 964);
                step(f, Op::BreakTransform, &[53, 185, 38, 186], 965);
                step(f, Op::SlerpQ, &[37, 38, 290, 41], 966);
                step(f, Op::MulF, &[290, 442, 331], 967);
                step(f, Op::SinF, &[331, 332], 968);
                step(f, Op::MulF, &[332, 59, 333], 969);
                step(f, Op::SlerpQ, &[41, 81, 333, 42], 970);
                step(f, Op::MakeTransform, &[211, 42, 303, 56], 971);
                step(f, Op::Copy(ValueType::Transform), &[56, 54], 972);
                step(f, Op::Jump, &[973], 973)
            }
            973 => {
                step(f, Op::BreakTransform, &[54, 179, 36, 180], 974);
                step(f, Op::Equals(Elem::Int), &[40, 52, 27], 975);
                step(f, Op::Select(ValueType::Int), &[27, 53, 52, 41], 976);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 41, 32], 977);
                step(f, Op::BreakTransform, &[32, 99, 24, 100], 978);
                step(f, Op::SubF, &[432, 6, 209], 979);
                step(f, Op::MulF, &[5, 209, 210], 980);
                step(f, Op::FootAvoidance, &[179, 99, 210, 27, 61, 181], 981);
                step(f, Op::MakeTransform, &[181, 36, 303, 51], 982);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 40, 51], 983);
                983
            }
            983 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 40, 205], 984);
                step(f, Op::GreaterF, &[205, 3, 26], 985);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 40, 26], 986);
                step(f, Op::Copy(ValueType::Bone), &[0, 17], 987);
                step(f, Op::Copy(ValueType::Int), &[2, 42], 988);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 42, 57], 989);
                step(f, Op::BreakTransform, &[57, 213, 43, 214], 990);
                step(f, Op::MakeVector, &[430, 430, 34, 223], 991);
                step(f, Op::AddV, &[213, 223, 224], 992);
                step(f, Op::GetTransform, &[17, 52, 48, 59], 993);
                step(f, Op::BreakTransform, &[59, 218, 45, 219], 994);
                step(f, Op::MakeTransform, &[224, 45, 303, 61], 995);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 42, 20], 996);
                step(f, Op::GetTransform, &[20, 52, 48, 60], 997);
                step(f, Op::BreakTransform, &[60, 220, 46, 221], 998);
                step(f, Op::SubV, &[220, 218, 222], 999);
                step(f, Op::AddV, &[224, 222, 225], 1000);
                step(f, Op::FootPivots, &[224, 225, 36, 35, 34, 37, 226, 227, 228], 1001);
                step(f, Op::GetParent, &[17, 18], 1002);
                step(f, Op::GetParent, &[18, 19], 1003);
                step(f, Op::GetTransform, &[19, 52, 49, 58], 1004);
                step(f, Op::BreakTransform, &[58, 215, 44, 216], 1005);
                step(f, Op::SubV, &[213, 215, 217], 1006);
                step(f, Op::DotV, &[217, 306, 334], 1007);
                step(f, Op::RemapF, &[334, 63, 62, 64, 430, 48, 337], 1008);
                step(f, Op::LengthV, &[0, 335], 1009);
                step(f, Op::RemapF, &[335, 430, 70, 430, 432, 48, 336], 1010);
                step(f, Op::MulF, &[337, 336, 338], 1011);
                step(f, Op::QuatFromAxisAngle, &[308, 338, 47], 1012);
                step(f, Op::RotateAroundPoint, &[61, 226, 47, 62], 1013);
                step(f, Op::SubV, &[227, 226, 229], 1014);
                step(f, Op::RotateVector, &[47, 229, 230], 1015);
                step(f, Op::AddV, &[226, 230, 231], 1016);
                step(f, Op::RemapF, &[334, 65, 63, 66, 430, 48, 339], 1017);
                step(f, Op::MulF, &[339, 336, 340], 1018);
                step(f, Op::QuatFromAxisAngle, &[308, 340, 48], 1019);
                step(f, Op::RotateAroundPoint, &[62, 231, 48, 63], 1020);
                step(f, Op::RemapF, &[334, 67, 68, 430, 69, 48, 341], 1021);
                step(f, Op::MulF, &[341, 336, 342], 1022);
                step(f, Op::QuatFromAxisAngle, &[308, 342, 49], 1023);
                step(f, Op::RotateAroundPoint, &[63, 228, 49, 64], 1024);
                step(f, Op::SubF, &[432, 6, 343], 1025);
                step(f, Op::MulF, &[5, 343, 344], 1026);
                step(f, Op::LimitRotationAroundZ, &[43, 344, 71, 50], 1027);
                step(f, Op::RotateAroundPoint, &[64, 213, 50, 65], 1028);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 42, 65], 1029);
                step(f, Op::JumpIfFalse, &[3, 1086], 1030)
            }
            1030 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 42, 57], 1031);
                step(f, Op::BreakTransform, &[57, 213, 43, 214], 1032);
                step(f, Op::MakeVector, &[430, 430, 34, 223], 1033);
                step(f, Op::AddV, &[213, 223, 224], 1034);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 42, 20], 1035);
                step(f, Op::GetTransform, &[20, 52, 48, 60], 1036);
                step(f, Op::BreakTransform, &[60, 220, 46, 221], 1037);
                step(f, Op::GetTransform, &[17, 52, 48, 59], 1038);
                step(f, Op::BreakTransform, &[59, 218, 45, 219], 1039);
                step(f, Op::SubV, &[220, 218, 222], 1040);
                step(f, Op::AddV, &[224, 222, 225], 1041);
                step(f, Op::FootPivots, &[224, 225, 36, 35, 34, 37, 226, 227, 228], 1042);
                step(f, Op::DrawPoint, &[228, 443, 308], 1043);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 42, 57], 1044);
                step(f, Op::BreakTransform, &[57, 213, 43, 214], 1045);
                step(f, Op::MakeVector, &[430, 430, 34, 223], 1046);
                step(f, Op::AddV, &[213, 223, 224], 1047);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 42, 20], 1048);
                step(f, Op::GetTransform, &[20, 52, 48, 60], 1049);
                step(f, Op::BreakTransform, &[60, 220, 46, 221], 1050);
                step(f, Op::GetTransform, &[17, 52, 48, 59], 1051);
                step(f, Op::BreakTransform, &[59, 218, 45, 219], 1052);
                step(f, Op::SubV, &[220, 218, 222], 1053);
                step(f, Op::AddV, &[224, 222, 225], 1054);
                step(f, Op::FootPivots, &[224, 225, 36, 35, 34, 37, 226, 227, 228], 1055);
                step(f, Op::DrawPoint, &[226, 443, 306], 1056);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 42, 57], 1057);
                step(f, Op::BreakTransform, &[57, 213, 43, 214], 1058);
                step(f, Op::MakeVector, &[430, 430, 34, 223], 1059);
                step(f, Op::AddV, &[213, 223, 224], 1060);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 42, 20], 1061);
                step(f, Op::GetTransform, &[20, 52, 48, 60], 1062);
                step(f, Op::BreakTransform, &[60, 220, 46, 221], 1063);
                step(f, Op::GetTransform, &[17, 52, 48, 59], 1064);
                step(f, Op::BreakTransform, &[59, 218, 45, 219], 1065);
                step(f, Op::SubV, &[220, 218, 222], 1066);
                step(f, Op::AddV, &[224, 222, 225], 1067);
                step(f, Op::FootPivots, &[224, 225, 36, 35, 34, 37, 226, 227, 228], 1068);
                step(f, Op::GetParent, &[17, 18], 1069);
                step(f, Op::GetParent, &[18, 19], 1070);
                step(f, Op::GetTransform, &[19, 52, 49, 58], 1071);
                step(f, Op::BreakTransform, &[58, 215, 44, 216], 1072);
                step(f, Op::SubV, &[213, 215, 217], 1073);
                step(f, Op::DotV, &[217, 306, 334], 1074);
                step(f, Op::RemapF, &[334, 63, 62, 64, 430, 48, 337], 1075);
                step(f, Op::LengthV, &[0, 335], 1076);
                step(f, Op::RemapF, &[335, 430, 70, 430, 432, 48, 336], 1077);
                step(f, Op::MulF, &[337, 336, 338], 1078);
                step(f, Op::QuatFromAxisAngle, &[308, 338, 47], 1079);
                step(f, Op::SubV, &[227, 226, 229], 1080);
                step(f, Op::RotateVector, &[47, 229, 230], 1081);
                step(f, Op::AddV, &[226, 230, 231], 1082);
                step(f, Op::DrawPoint, &[231, 443, 305], 1083);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 42, 57], 1084);
                step(f, Op::DrawTransform, &[57, 441, 431], 1085);
                step(f, Op::Jump, &[1086], 1086)
            }
            1086 => {
                step(f, Op::Jump, &[515], 1087)
            }
            1087 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1088);
                step(f, Op::Copy(ValueType::Int), &[52, 4], 1089);
                1089
            }
            1089 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 4, 1, 5, 6, 1144], 1090)
            }
            1090 => {
                step(f, Op::Copy(ValueType::Bone), &[1, 21], 1091);
                step(f, Op::Copy(ValueType::Int), &[5, 43], 1092);
                step(f, Op::GetParent, &[21, 22], 1093);
                step(f, Op::GetParent, &[22, 23], 1094);
                step(f, Op::GetParent, &[23, 24], 1095);
                step(f, Op::GetTransform, &[24, 52, 49, 66], 1096);
                step(f, Op::BreakTransform, &[66, 232, 51, 233], 1097);
                step(f, Op::LengthV, &[1, 346], 1098);
                step(f, Op::ClavicleOffset, &[4, 346, 76, 79, 347], 1099);
                step(f, Op::MakeVector, &[430, 430, 347, 234], 1100);
                step(f, Op::AddV, &[232, 234, 235], 1101);
                step(f, Op::MakeTransform, &[235, 51, 303, 67], 1102);
                step(f, Op::SetTransform, &[24, 67, 52, 48, 432], 1103);
                step(f, Op::GetParent, &[21, 22], 1104);
                step(f, Op::GetParent, &[22, 23], 1105);
                step(f, Op::GetTransform, &[21, 52, 49, 68], 1106);
                step(f, Op::GetTransform, &[23, 52, 49, 69], 1107);
                step(f, Op::BreakTransform, &[69, 236, 53, 237], 1108);
                step(f, Op::Equals(Elem::Int), &[43, 52, 37], 1109);
                step(f, Op::Select(ValueType::Int), &[37, 53, 52, 44], 1110);
                step(f, Op::ArrayAt(Elem::Float), &[0, 44, 345], 1111);
                step(f, Op::ArmSwingRotation, &[345, 1, 0, 77, 436, 444, 432, 76, 74, 75, 436, 436, 432, 348], 1112);
                step(f, Op::QuatFromAxisAngle, &[308, 348, 52], 1113);
                step(f, Op::RotateAroundPoint, &[68, 236, 52, 70], 1114);
                step(f, Op::BreakTransform, &[70, 238, 54, 239], 1115);
                step(f, Op::LengthV, &[1, 346], 1116);
                step(f, Op::RemapF, &[346, 430, 76, 430, 78, 48, 349], 1117);
                step(f, Op::MakeVector, &[430, 430, 349, 240], 1118);
                step(f, Op::AddV, &[238, 240, 241], 1119);
                step(f, Op::MakeTransform, &[241, 54, 303, 71], 1120);
                step(f, Op::Select(ValueType::Vec3), &[37, 309, 308, 243], 1121);
                step(f, Op::Select(ValueType::Vec3), &[37, 306, 310, 244], 1122);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 43, 242], 1123);
                step(f, Op::TwoBoneIK, &[23, 22, 21, 71, 243, 244, 242, 52, 432, 49, 445, 446, 48, 38, 350], 1124);
                step(f, Op::JumpIfFalse, &[3, 1143], 1125)
            }
            1125 => {
                step(f, Op::GetParent, &[21, 22], 1126);
                step(f, Op::GetParent, &[22, 23], 1127);
                step(f, Op::GetTransform, &[23, 52, 49, 69], 1128);
                step(f, Op::BreakTransform, &[69, 236, 53, 237], 1129);
                step(f, Op::GetTransform, &[21, 52, 49, 68], 1130);
                step(f, Op::Equals(Elem::Int), &[43, 52, 37], 1131);
                step(f, Op::Select(ValueType::Int), &[37, 53, 52, 44], 1132);
                step(f, Op::ArrayAt(Elem::Float), &[0, 44, 345], 1133);
                step(f, Op::ArmSwingRotation, &[345, 1, 0, 77, 436, 444, 432, 76, 74, 75, 436, 436, 432, 348], 1134);
                step(f, Op::QuatFromAxisAngle, &[308, 348, 52], 1135);
                step(f, Op::RotateAroundPoint, &[68, 236, 52, 70], 1136);
                step(f, Op::BreakTransform, &[70, 238, 54, 239], 1137);
                step(f, Op::LengthV, &[1, 346], 1138);
                step(f, Op::RemapF, &[346, 430, 76, 430, 78, 48, 349], 1139);
                step(f, Op::MakeVector, &[430, 430, 349, 240], 1140);
                step(f, Op::AddV, &[238, 240, 241], 1141);
                step(f, Op::DrawLine, &[236, 241, 431, 306], 1142);
                step(f, Op::Jump, &[1143], 1143)
            }
            1143 => {
                step(f, Op::Jump, &[1089], 1144)
            }
            1144 => {
                step(f, Op::Copy(ValueType::Float), &[430, 352], 1145);
                step(f, Op::Copy(ValueType::Float), &[438, 353], 1146);
                step(f, Op::Copy(ValueType::Bool), &[49, 39], 1147);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[3, 6], 1148);
                step(f, Op::Copy(ValueType::Int), &[52, 45], 1149);
                step(f, Op::MakeVector, &[430, 430, 39, 247], 1150);
                1150
            }
            1150 => {
                step(f, Op::ForEachNext(Elem::Transform), &[6, 45, 72, 46, 47, 1163], 1151)
            }
            1151 => {
                step(f, Op::BreakTransform, &[72, 245, 55, 246], 1152);
                step(f, Op::AddV, &[245, 247, 248], 1153);
                step(f, Op::SubV, &[245, 247, 249], 1154);
                step(f, Op::SphereTrace, &[248, 249, 38, 40, 250, 251, 354], 1155);
                step(f, Op::BreakVector, &[250, 355, 356, 357], 1156);
                step(f, Op::LessF, &[357, 353, 41], 1157);
                step(f, Op::And, &[40, 41, 42], 1158);
                step(f, Op::JumpIfFalse, &[42, 1162], 1159)
            }
            1159 => {
                step(f, Op::Copy(ValueType::Float), &[357, 353], 1160);
                step(f, Op::Copy(ValueType::Bool), &[48, 39], 1161);
                step(f, Op::Jump, &[1162], 1162)
            }
            1162 => {
                step(f, Op::Jump, &[1150], 1163)
            }
            1163 => {
                step(f, Op::Select(ValueType::Float), &[39, 353, 430, 358], 1164);
                step(f, Op::ClampF, &[358, 42, 43, 359], 1165);
                step(f, Op::Copy(ValueType::Float), &[359, 352], 1166);
                step(f, Op::Jump, &[1167], 1167)
            }
            1167 => {
                step(f, Op::FloatLerp, &[7, 352, 33, 360], 1168);
                step(f, Op::Copy(ValueType::Float), &[360, 7], 1169);
                step(f, Op::GetTransform, &[37, 52, 48, 77], 1170);
                step(f, Op::BreakTransform, &[77, 264, 62, 265], 1171);
                step(f, Op::PelvisLean, &[1, 81, 86, 87, 373, 374], 1172);
                step(f, Op::LengthV, &[0, 351], 1173);
                step(f, Op::RemapF, &[351, 430, 81, 430, 80, 48, 361], 1174);
                step(f, Op::MulF, &[4, 447, 362], 1175);
                step(f, Op::SinF, &[362, 363], 1176);
                step(f, Op::MulF, &[361, 363, 364], 1177);
                step(f, Op::AddF, &[364, 7, 365], 1178);
                step(f, Op::MakeVector, &[430, 374, 365, 266], 1179);
                step(f, Op::AddV, &[264, 266, 267], 1180);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 52, 73], 1181);
                step(f, Op::BreakTransform, &[73, 252, 56, 253], 1182);
                step(f, Op::BreakVector, &[252, 375, 376, 377], 1183);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 53, 74], 1184);
                step(f, Op::BreakTransform, &[74, 254, 57, 255], 1185);
                step(f, Op::BreakVector, &[254, 378, 379, 380], 1186);
                step(f, Op::SubF, &[377, 380, 381], 1187);
                step(f, Op::PelvisSideLean, &[381, 88, 89, 382], 1188);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 52, 75], 1189);
                step(f, Op::BreakTransform, &[75, 258, 58, 259], 1190);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 53, 76], 1191);
                step(f, Op::BreakTransform, &[76, 260, 59, 261], 1192);
                step(f, Op::SlerpQ, &[58, 59, 431, 60], 1193);
                step(f, Op::EulerFromQuat, &[60, 52, 262], 1194);
                step(f, Op::BreakVector, &[262, 369, 370, 371], 1195);
                step(f, Op::RemapF, &[351, 82, 81, 430, 83, 48, 367], 1196);
                step(f, Op::SubV, &[252, 254, 256], 1197);
                step(f, Op::RotateVector, &[0, 306, 257], 1198);
                step(f, Op::DotV, &[256, 257, 366], 1199);
                step(f, Op::MulF, &[367, 366, 368], 1200);
                step(f, Op::AddF, &[371, 368, 372], 1201);
                step(f, Op::MakeVector, &[373, 382, 372, 263], 1202);
                step(f, Op::QuatFromEuler, &[263, 52, 61], 1203);
                step(f, Op::MakeTransform, &[267, 61, 303, 78], 1204);
                step(f, Op::SetTransform, &[38, 78, 52, 48, 432], 1205);
                step(f, Op::GetTransform, &[39, 53, 48, 79], 1206);
                step(f, Op::BreakTransform, &[79, 268, 66, 269], 1207);
                step(f, Op::LengthV, &[0, 351], 1208);
                step(f, Op::RemapF, &[351, 82, 81, 430, 83, 48, 367], 1209);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 52, 73], 1210);
                step(f, Op::BreakTransform, &[73, 252, 56, 253], 1211);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 53, 74], 1212);
                step(f, Op::BreakTransform, &[74, 254, 57, 255], 1213);
                step(f, Op::SubV, &[252, 254, 256], 1214);
                step(f, Op::RotateVector, &[0, 306, 257], 1215);
                step(f, Op::DotV, &[256, 257, 366], 1216);
                step(f, Op::MulF, &[367, 366, 368], 1217);
                step(f, Op::QuatFromAxisAngle, &[305, 368, 63], 1218);
                step(f, Op::DivF, &[84, 443, 383], 1219);
                step(f, Op::QuatScale, &[63, 383, 64], 1220);
                step(f, Op::MulQ, &[66, 64, 70], 1221);
                step(f, Op::MakeTransform, &[268, 70, 303, 83], 1222);
                step(f, Op::SetTransform, &[40, 83, 53, 48, 432], 1223);
                step(f, Op::GetTransform, &[41, 53, 48, 80], 1224);
                step(f, Op::BreakTransform, &[80, 270, 67, 271], 1225);
                step(f, Op::LengthV, &[0, 351], 1226);
                step(f, Op::RemapF, &[351, 82, 81, 430, 83, 48, 367], 1227);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 52, 73], 1228);
                step(f, Op::BreakTransform, &[73, 252, 56, 253], 1229);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 53, 74], 1230);
                step(f, Op::BreakTransform, &[74, 254, 57, 255], 1231);
                step(f, Op::SubV, &[252, 254, 256], 1232);
                step(f, Op::RotateVector, &[0, 306, 257], 1233);
                step(f, Op::DotV, &[256, 257, 366], 1234);
                step(f, Op::MulF, &[367, 366, 368], 1235);
                step(f, Op::QuatFromAxisAngle, &[305, 368, 63], 1236);
                step(f, Op::DivF, &[84, 443, 383], 1237);
                step(f, Op::QuatScale, &[63, 383, 64], 1238);
                step(f, Op::MulQ, &[67, 64, 71], 1239);
                step(f, Op::MakeTransform, &[270, 71, 303, 84], 1240);
                step(f, Op::SetTransform, &[42, 84, 53, 48, 432], 1241);
                step(f, Op::GetTransform, &[43, 53, 48, 81], 1242);
                step(f, Op::BreakTransform, &[81, 272, 68, 273], 1243);
                step(f, Op::LengthV, &[0, 351], 1244);
                step(f, Op::RemapF, &[351, 82, 81, 430, 83, 48, 367], 1245);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 52, 73], 1246);
                step(f, Op::BreakTransform, &[73, 252, 56, 253], 1247);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 53, 74], 1248);
                step(f, Op::BreakTransform, &[74, 254, 57, 255], 1249);
                step(f, Op::SubV, &[252, 254, 256], 1250);
                step(f, Op::RotateVector, &[0, 306, 257], 1251);
                step(f, Op::DotV, &[256, 257, 366], 1252);
                step(f, Op::MulF, &[367, 366, 368], 1253);
                step(f, Op::QuatFromAxisAngle, &[305, 368, 63], 1254);
                step(f, Op::DivF, &[84, 443, 383], 1255);
                step(f, Op::QuatScale, &[63, 383, 64], 1256);
                step(f, Op::MulQ, &[68, 64, 72], 1257);
                step(f, Op::MakeTransform, &[272, 72, 303, 85], 1258);
                step(f, Op::SetTransform, &[44, 85, 53, 48, 432], 1259);
                step(f, Op::GetTransform, &[45, 53, 48, 82], 1260);
                step(f, Op::BreakTransform, &[82, 274, 69, 275], 1261);
                step(f, Op::LengthV, &[0, 351], 1262);
                step(f, Op::RemapF, &[351, 82, 81, 430, 83, 48, 367], 1263);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 52, 73], 1264);
                step(f, Op::BreakTransform, &[73, 252, 56, 253], 1265);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 53, 74], 1266);
                step(f, Op::BreakTransform, &[74, 254, 57, 255], 1267);
                step(f, Op::SubV, &[252, 254, 256], 1268);
                step(f, Op::RotateVector, &[0, 306, 257], 1269);
                step(f, Op::DotV, &[256, 257, 366], 1270);
                step(f, Op::MulF, &[367, 366, 368], 1271);
                step(f, Op::QuatFromAxisAngle, &[305, 368, 63], 1272);
                step(f, Op::QuatScale, &[63, 85, 65], 1273);
                step(f, Op::MulQ, &[69, 65, 73], 1274);
                step(f, Op::MakeTransform, &[274, 73, 303, 86], 1275);
                step(f, Op::SetTransform, &[46, 86, 53, 48, 432], 1276);
                step(f, Op::Copy(ValueType::Float), &[430, 384], 1277);
                step(f, Op::Copy(ValueType::Float), &[430, 385], 1278);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1279);
                step(f, Op::Copy(ValueType::Int), &[52, 48], 1280);
                1280
            }
            1280 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 48, 25, 49, 50, 1309], 1281)
            }
            1281 => {
                step(f, Op::GetParent, &[25, 26], 1282);
                step(f, Op::GetParent, &[26, 27], 1283);
                step(f, Op::GetTransform, &[27, 52, 49, 87], 1284);
                step(f, Op::BreakTransform, &[87, 276, 74, 277], 1285);
                step(f, Op::BreakVector, &[276, 386, 387, 388], 1286);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 49, 88], 1287);
                step(f, Op::BreakTransform, &[88, 278, 75, 279], 1288);
                step(f, Op::BreakVector, &[278, 389, 390, 391], 1289);
                step(f, Op::ArrayAt(Elem::Float), &[1, 49, 395], 1290);
                step(f, Op::MulF, &[395, 90, 396], 1291);
                step(f, Op::MulF, &[396, 396, 397], 1292);
                step(f, Op::SubF, &[386, 389, 392], 1293);
                step(f, Op::SubF, &[387, 390, 393], 1294);
                step(f, Op::MakeVector, &[392, 393, 430, 280], 1295);
                step(f, Op::DotV, &[280, 280, 394], 1296);
                step(f, Op::SubF, &[397, 394, 398], 1297);
                step(f, Op::SqrtF, &[398, 399], 1298);
                step(f, Op::AddF, &[391, 399, 400], 1299);
                step(f, Op::SubF, &[388, 400, 401], 1300);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 49, 43], 1301);
                step(f, Op::ArrayAt(Elem::Float), &[0, 49, 402], 1302);
                step(f, Op::DivF, &[402, 3, 403], 1303);
                step(f, Op::RemapF, &[403, 431, 432, 430, 432, 48, 404], 1304);
                step(f, Op::Select(ValueType::Float), &[43, 432, 404, 405], 1305);
                step(f, Op::MulF, &[401, 405, 406], 1306);
                step(f, Op::MaxF, &[385, 406, 407], 1307);
                step(f, Op::Copy(ValueType::Float), &[407, 385], 1308);
                step(f, Op::Jump, &[1280], 1309)
            }
            1309 => {
                step(f, Op::ClampF, &[385, 430, 91, 408], 1310);
                step(f, Op::Copy(ValueType::Float), &[408, 384], 1311);
                step(f, Op::Jump, &[1312], 1312)
            }
            1312 => {
                step(f, Op::GreaterF, &[384, 8, 44], 1313);
                step(f, Op::Select(ValueType::Float), &[44, 93, 92, 409], 1314);
                step(f, Op::FloatLerp, &[8, 384, 409, 410], 1315);
                step(f, Op::Copy(ValueType::Float), &[410, 8], 1316);
                step(f, Op::GetTransform, &[47, 52, 49, 89], 1317);
                step(f, Op::BreakTransform, &[89, 281, 76, 282], 1318);
                step(f, Op::MakeVector, &[430, 430, 8, 283], 1319);
                step(f, Op::SubV, &[281, 283, 284], 1320);
                step(f, Op::MakeTransform, &[284, 76, 303, 90], 1321);
                step(f, Op::SetTransform, &[48, 90, 52, 48, 432], 1322);
                step(f, Op::JumpIfFalse, &[3, 1330], 1323)
            }
            1323 => {
                step(f, Op::GetTransform, &[47, 52, 49, 89], 1324);
                step(f, Op::BreakTransform, &[89, 281, 76, 282], 1325);
                step(f, Op::MakeVector, &[430, 430, 8, 283], 1326);
                step(f, Op::SubV, &[281, 283, 284], 1327);
                step(f, Op::MakeTransform, &[284, 76, 303, 90], 1328);
                step(f, Op::DrawTransform, &[90, 448, 431], 1329);
                step(f, Op::Jump, &[1330], 1330)
            }
            1330 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1331);
                step(f, Op::Copy(ValueType::Int), &[52, 7], 1332);
                1332
            }
            1332 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 7, 2, 8, 9, 1385], 1333)
            }
            1333 => {
                step(f, Op::Copy(ValueType::Bone), &[2, 28], 1334);
                step(f, Op::Copy(ValueType::Int), &[8, 51], 1335);
                step(f, Op::GetParent, &[28, 29], 1336);
                step(f, Op::GetParent, &[29, 30], 1337);
                step(f, Op::GetTransform, &[30, 52, 49, 91], 1338);
                step(f, Op::BreakTransform, &[91, 285, 77, 286], 1339);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 51, 92], 1340);
                step(f, Op::BreakTransform, &[92, 287, 78, 288], 1341);
                step(f, Op::SubV, &[287, 285, 289], 1342);
                step(f, Op::LengthV, &[289, 420], 1343);
                step(f, Op::ArrayAt(Elem::Float), &[1, 51, 411], 1344);
                step(f, Op::MulF, &[411, 94, 412], 1345);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 51, 45], 1346);
                step(f, Op::ArrayAt(Elem::Float), &[0, 51, 413], 1347);
                step(f, Op::DivF, &[413, 3, 414], 1348);
                step(f, Op::ClampF, &[414, 430, 432, 415], 1349);
                step(f, Op::MulF, &[415, 442, 416], 1350);
                step(f, Op::SinF, &[416, 417], 1351);
                step(f, Op::MulF, &[417, 95, 418], 1352);
                step(f, Op::Select(ValueType::Float), &[45, 430, 418, 419], 1353);
                step(f, Op::SubF, &[412, 419, 421], 1354);
                step(f, Op::SubF, &[420, 421, 422], 1355);
                step(f, Op::MaxF, &[422, 430, 423], 1356);
                step(f, Op::MulF, &[423, 423, 424], 1357);
                step(f, Op::AddF, &[423, 419, 425], 1358);
                step(f, Op::DivF, &[424, 425, 426], 1359);
                step(f, Op::SubF, &[420, 426, 427], 1360);
                step(f, Op::DivF, &[427, 420, 428], 1361);
                step(f, Op::ScaleV, &[289, 428, 290], 1362);
                step(f, Op::AddV, &[285, 290, 291], 1363);
                step(f, Op::ClampSpatially, &[291, 285, 430, 412, 292], 1364);
                step(f, Op::MakeTransform, &[292, 78, 303, 93], 1365);
                step(f, Op::Equals(Elem::Int), &[51, 52, 46], 1366);
                step(f, Op::Select(ValueType::Vec3), &[46, 309, 308, 297], 1367);
                step(f, Op::Select(ValueType::Vec3), &[46, 306, 310, 298], 1368);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 51, 94], 1369);
                step(f, Op::BreakTransform, &[94, 293, 79, 294], 1370);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 51, 295], 1371);
                step(f, Op::KneeVector, &[79, 0, 295, 96, 97, 296], 1372);
                step(f, Op::TwoBoneIK, &[30, 29, 28, 93, 297, 298, 296, 52, 432, 49, 445, 446, 48, 47, 429], 1373);
                step(f, Op::JumpIfFalse, &[3, 1384], 1374)
            }
            1374 => {
                step(f, Op::GetParent, &[28, 29], 1375);
                step(f, Op::GetTransform, &[29, 52, 49, 95], 1376);
                step(f, Op::BreakTransform, &[95, 299, 80, 300], 1377);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 51, 94], 1378);
                step(f, Op::BreakTransform, &[94, 293, 79, 294], 1379);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 51, 295], 1380);
                step(f, Op::KneeVector, &[79, 0, 295, 96, 97, 296], 1381);
                step(f, Op::AddV, &[299, 296, 301], 1382);
                step(f, Op::DrawLine, &[299, 301, 431, 311], 1383);
                step(f, Op::Jump, &[1384], 1384)
            }
            1384 => {
                step(f, Op::Jump, &[1332], 1385)
            }
            1385 => {
                step(f, Op::End, &[], 1386)
            }
            _ => return,
        } };
    }
}
