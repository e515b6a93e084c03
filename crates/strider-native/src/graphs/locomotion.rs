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
    fingerprint: 0x8de6a5b94c45cb01,
    forward,
};

fn forward(f: &mut Frame<'_>) {
    let mut pc: usize = 375;
    loop {
        pc = match pc {
            375 => {
                step(f, Op::WorldTransform, &[12], 376);
                step(f, Op::BreakTransform, &[12, 30, 7, 31], 377);
                step(f, Op::Select(ValueType::Transform), &[0, 0, 12, 13], 378);
                step(f, Op::BreakTransform, &[13, 32, 8, 33], 379);
                step(f, Op::SubV, &[30, 32, 34], 380);
                step(f, Op::LengthV, &[34, 104], 381);
                step(f, Op::GreaterF, &[104, 21, 4], 382);
                step(f, Op::Copy(ValueType::Bool), &[4, 1], 383);
                step(f, Op::MakeRelative, &[13, 12, 17], 384);
                step(f, Op::Select(ValueType::Transform), &[4, 96, 17, 18], 385);
                step(f, Op::Copy(ValueType::Transform), &[18, 2], 386);
                step(f, Op::InverseT, &[13, 15], 387);
                step(f, Op::MulT, &[12, 15, 16], 388);
                step(f, Op::Copy(ValueType::Transform), &[16, 1], 389);
                step(f, Op::TransformVector, &[2, 0, 37], 390);
                step(f, Op::InverseT, &[12, 14], 391);
                step(f, Op::DeltaTime, &[103], 392);
                step(f, Op::DivF, &[415, 103, 105], 393);
                step(f, Op::ScaleV, &[34, 105, 35], 394);
                step(f, Op::TransformVector, &[14, 35, 36], 395);
                step(f, Op::Select(ValueType::Vec3), &[1, 37, 36, 39], 396);
                step(f, Op::VectorLerp, &[37, 39, 22, 413, 40], 397);
                step(f, Op::Copy(ValueType::Vec3), &[40, 0], 398);
                step(f, Op::TransformVector, &[2, 1, 38], 399);
                step(f, Op::TransformVector, &[2, 0, 37], 400);
                step(f, Op::Select(ValueType::Vec3), &[1, 37, 36, 39], 401);
                step(f, Op::VectorLerp, &[38, 39, 23, 413, 41], 402);
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
                step(f, Op::Copy(ValueType::Float), &[413, 7], 417);
                step(f, Op::Jump, &[418], 418)
            }
            418 => {
                step(f, Op::WorldTransform, &[12], 419);
                step(f, Op::Copy(ValueType::Transform), &[12, 0], 420);
                step(f, Op::Copy(ValueType::Bool), &[47, 0], 421);
                step(f, Op::JumpIfFalse, &[3, 428], 422)
            }
            422 => {
                step(f, Op::GetTransform, &[34, 52, 47, 19], 423);
                step(f, Op::BreakTransform, &[19, 42, 9, 43], 424);
                step(f, Op::ScaleV, &[0, 416, 44], 425);
                step(f, Op::AddV, &[42, 44, 45], 426);
                step(f, Op::DrawArrow, &[42, 45, 414, 301], 427);
                step(f, Op::Jump, &[428], 428)
            }
            428 => {
                step(f, Op::Copy(ValueType::Bool), &[48, 6], 429);
                step(f, Op::Copy(ValueType::Bool), &[47, 7], 430);
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
                step(f, Op::Copy(ValueType::Bool), &[48, 7], 436);
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
                step(f, Op::Copy(ValueType::Bool), &[48, 10], 441);
                step(f, Op::Copy(ValueType::Bool), &[47, 11], 442);
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
                step(f, Op::BreakVector, &[46, 114, 115, 116], 448);
                step(f, Op::MakeVector, &[114, 115, 413, 50], 449);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 26, 22], 450);
                step(f, Op::BreakTransform, &[22, 48, 11, 49], 451);
                step(f, Op::BreakVector, &[48, 117, 118, 119], 452);
                step(f, Op::MakeVector, &[117, 118, 413, 51], 453);
                step(f, Op::DistanceV, &[50, 51, 120], 454);
                step(f, Op::GreaterF, &[120, 17, 12], 455);
                step(f, Op::JumpIfFalse, &[12, 458], 456)
            }
            456 => {
                step(f, Op::Copy(ValueType::Bool), &[48, 11], 457);
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
                step(f, Op::LengthV, &[0, 106], 463);
                step(f, Op::GreaterF, &[106, 15, 5], 464);
                step(f, Op::Not, &[5, 14], 465);
                step(f, Op::And, &[13, 14, 16], 466);
                step(f, Op::DeltaTime, &[131], 467);
                step(f, Op::MulF, &[131, 20, 132], 468);
                step(f, Op::AddF, &[4, 132, 133], 469);
                step(f, Op::GreaterF, &[4, 414, 17], 470);
                step(f, Op::AddF, &[19, 414, 129], 471);
                step(f, Op::Select(ValueType::Float), &[17, 129, 19, 130], 472);
                step(f, Op::MinF, &[133, 130, 134], 473);
                step(f, Op::RemapF, &[106, 15, 16, 413, 415, 47, 121], 474);
                step(f, Op::Select(ValueType::Float), &[14, 18, 415, 122], 475);
                step(f, Op::Select(ValueType::Float), &[13, 121, 122, 123], 476);
                step(f, Op::LerpF, &[9, 30, 6, 109], 477);
                step(f, Op::RemapF, &[106, 12, 13, 10, 11, 47, 107], 478);
                step(f, Op::LerpF, &[107, 29, 6, 108], 479);
                step(f, Op::MaxF, &[106, 14, 110], 480);
                step(f, Op::DivF, &[108, 110, 111], 481);
                step(f, Op::AddF, &[109, 111, 112], 482);
                step(f, Op::DivF, &[123, 112, 124], 483);
                step(f, Op::AddF, &[2, 124, 125], 484);
                step(f, Op::DivF, &[417, 125, 126], 485);
                step(f, Op::GreaterF, &[125, 413, 15], 486);
                step(f, Op::CycleStep, &[4, 126, 413, 15, 127, 128], 487);
                step(f, Op::Select(ValueType::Float), &[16, 134, 127, 135], 488);
                step(f, Op::Copy(ValueType::Float), &[135, 4], 489);
                step(f, Op::Copy(ValueType::Float), &[124, 2], 490);
                step(f, Op::Copy(ValueType::Bool), &[5, 2], 491);
                step(f, Op::Copy(ValueType::Float), &[111, 0], 492);
                step(f, Op::Copy(ValueType::Float), &[112, 1], 493);
                step(f, Op::DivF, &[109, 112, 113], 494);
                step(f, Op::Copy(ValueType::Float), &[113, 3], 495);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 496);
                step(f, Op::Copy(ValueType::Int), &[52, 19], 497);
                497
            }
            497 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 19, 14, 20, 21, 504], 498)
            }
            498 => {
                step(f, Op::ToFloat, &[20, 136], 499);
                step(f, Op::MulF, &[136, 414, 137], 500);
                step(f, Op::AddF, &[4, 137, 138], 501);
                step(f, Op::FractF, &[138, 139], 502);
                step(f, Op::ArraySetAt(Elem::Float), &[0, 20, 139], 503);
                step(f, Op::Jump, &[497], 504)
            }
            504 => {
                step(f, Op::Select(ValueType::Vec3), &[2, 0, 299, 52], 505);
                step(f, Op::MovementAngleOffset, &[52, 5, 4, 24, 25, 418, 26, 419, 140], 506);
                step(f, Op::Copy(ValueType::Float), &[140, 5], 507);
                step(f, Op::QuatFromAxisAngle, &[302, 5, 12], 508);
                step(f, Op::Copy(ValueType::Quat), &[12, 0], 509);
                step(f, Op::SinF, &[5, 141], 510);
                step(f, Op::AbsF, &[141, 142], 511);
                step(f, Op::RemapF, &[142, 27, 28, 413, 415, 47, 143], 512);
                step(f, Op::Copy(ValueType::Float), &[143, 6], 513);
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
                step(f, Op::GetTransform, &[35, 52, 47, 23], 519);
                step(f, Op::BreakTransform, &[23, 55, 13, 56], 520);
                step(f, Op::BreakVector, &[55, 154, 155, 156], 521);
                step(f, Op::SubF, &[415, 6, 152], 522);
                step(f, Op::MulF, &[5, 152, 153], 523);
                step(f, Op::QuatFromAxisAngle, &[302, 153, 15], 524);
                step(f, Op::GetTransform, &[16, 52, 47, 24], 525);
                step(f, Op::BreakTransform, &[24, 57, 14, 58], 526);
                step(f, Op::SubV, &[57, 55, 59], 527);
                step(f, Op::BreakVector, &[59, 149, 150, 151], 528);
                step(f, Op::MakeVector, &[149, 150, 413, 60], 529);
                step(f, Op::RotateVector, &[15, 60, 61], 530);
                step(f, Op::BreakVector, &[61, 157, 158, 159], 531);
                step(f, Op::MulF, &[31, 6, 160], 532);
                step(f, Op::Equals(Elem::Int), &[28, 52, 18], 533);
                step(f, Op::Select(ValueType::Float), &[18, 415, 420, 169], 534);
                step(f, Op::MulF, &[160, 169, 161], 535);
                step(f, Op::AddF, &[157, 161, 162], 536);
                step(f, Op::AddF, &[154, 162, 163], 537);
                step(f, Op::AddF, &[155, 158, 164], 538);
                step(f, Op::BreakVector, &[57, 165, 166, 167], 539);
                step(f, Op::SubF, &[167, 34, 168], 540);
                step(f, Op::MakeVector, &[163, 164, 168, 62], 541);
                step(f, Op::ArrayAt(Elem::Float), &[0, 28, 144], 542);
                step(f, Op::SubF, &[3, 144, 145], 543);
                step(f, Op::MaxF, &[145, 413, 146], 544);
                step(f, Op::MulF, &[146, 1, 147], 545);
                step(f, Op::ScaleV, &[0, 147, 53], 546);
                step(f, Op::AddV, &[62, 53, 63], 547);
                step(f, Op::MulF, &[0, 414, 148], 548);
                step(f, Op::ScaleV, &[0, 148, 54], 549);
                step(f, Op::AddV, &[63, 54, 64], 550);
                step(f, Op::RotateVector, &[0, 303, 65], 551);
                step(f, Op::Copy(ValueType::Vec3), &[64, 72], 552);
                step(f, Op::Copy(ValueType::Vec3), &[65, 73], 553);
                step(f, Op::Copy(ValueType::Float), &[169, 179], 554);
                step(f, Op::Copy(ValueType::Vec3), &[299, 74], 555);
                step(f, Op::Copy(ValueType::Vec3), &[299, 75], 556);
                step(f, Op::Copy(ValueType::Bool), &[48, 19], 557);
                step(f, Op::Copy(ValueType::Float), &[421, 180], 558);
                step(f, Op::Copy(ValueType::Vec3), &[299, 76], 559);
                step(f, Op::Copy(ValueType::Vec3), &[302, 77], 560);
                step(f, Op::Copy(ValueType::Bool), &[48, 20], 561);
                step(f, Op::MulI, &[0, 0, 34], 562);
                step(f, Op::Copy(ValueType::Int), &[34, 33], 563);
                step(f, Op::Copy(ValueType::Int), &[52, 29], 564);
                step(f, Op::SubI, &[0, 53, 37], 565);
                step(f, Op::DivI, &[37, 54, 38], 566);
                step(f, Op::MakeVector, &[413, 413, 39, 82], 567);
                step(f, Op::ScaleV, &[73, 41, 87], 568);
                568
            }
            568 => {
                step(f, Op::ForNext, &[29, 33, 31, 608], 569)
            }
            569 => {
                step(f, Op::ModI, &[31, 0, 35], 570);
                step(f, Op::ToFloat, &[35, 181], 571);
                step(f, Op::MulF, &[181, 40, 183], 572);
                step(f, Op::MulF, &[183, 179, 184], 573);
                step(f, Op::MakeVector, &[184, 413, 413, 78], 574);
                step(f, Op::DivI, &[31, 0, 36], 575);
                step(f, Op::SubI, &[36, 38, 39], 576);
                step(f, Op::ToFloat, &[39, 182], 577);
                step(f, Op::MulF, &[182, 40, 185], 578);
                step(f, Op::ScaleV, &[73, 185, 79], 579);
                step(f, Op::AddV, &[78, 79, 80], 580);
                step(f, Op::AddV, &[72, 80, 81], 581);
                step(f, Op::AddV, &[81, 82, 83], 582);
                step(f, Op::SubV, &[81, 82, 84], 583);
                step(f, Op::SphereTrace, &[83, 84, 38, 21, 85, 86, 186], 584);
                step(f, Op::BreakVector, &[85, 188, 189, 190], 585);
                step(f, Op::AddV, &[83, 87, 88], 586);
                step(f, Op::AddV, &[84, 87, 89], 587);
                step(f, Op::SphereTrace, &[88, 89, 38, 22, 90, 91, 187], 588);
                step(f, Op::BreakVector, &[90, 191, 192, 193], 589);
                step(f, Op::SubF, &[190, 193, 194], 590);
                step(f, Op::AbsF, &[194, 195], 591);
                step(f, Op::Select(ValueType::Float), &[21, 413, 415, 196], 592);
                step(f, Op::AddF, &[195, 196, 201], 593);
                step(f, Op::LengthV, &[80, 197], 594);
                step(f, Op::RemapF, &[197, 413, 422, 413, 415, 47, 198], 595);
                step(f, Op::MinF, &[190, 193, 199], 596);
                step(f, Op::RemapF, &[199, 423, 422, 415, 414, 47, 200], 597);
                step(f, Op::AddF, &[198, 200, 202], 598);
                step(f, Op::AddF, &[201, 202, 203], 599);
                step(f, Op::LessF, &[203, 180, 23], 600);
                step(f, Op::And, &[21, 23, 24], 601);
                step(f, Op::JumpIfFalse, &[24, 607], 602)
            }
            602 => {
                step(f, Op::Copy(ValueType::Float), &[203, 180], 603);
                step(f, Op::Copy(ValueType::Vec3), &[85, 76], 604);
                step(f, Op::Copy(ValueType::Vec3), &[86, 77], 605);
                step(f, Op::Copy(ValueType::Bool), &[47, 20], 606);
                step(f, Op::Jump, &[607], 607)
            }
            607 => {
                step(f, Op::Jump, &[568], 608)
            }
            608 => {
                step(f, Op::JumpIfFalse, &[3, 611], 609)
            }
            609 => {
                step(f, Op::DrawSphere, &[76, 38, 303], 610);
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
                step(f, Op::ArrayAt(Elem::Float), &[0, 28, 144], 618);
                step(f, Op::SubF, &[3, 144, 145], 619);
                step(f, Op::MaxF, &[145, 413, 146], 620);
                step(f, Op::MulF, &[146, 1, 147], 621);
                step(f, Op::ScaleV, &[0, 147, 53], 622);
                step(f, Op::SubV, &[74, 53, 66], 623);
                step(f, Op::Select(ValueType::Vec3), &[19, 66, 67, 69], 624);
                step(f, Op::VectorLerp, &[67, 69, 32, 413, 70], 625);
                step(f, Op::BreakVector, &[70, 175, 176, 177], 626);
                step(f, Op::ClampF, &[177, 42, 43, 178], 627);
                step(f, Op::MakeVector, &[175, 176, 178, 71], 628);
                step(f, Op::RotationFromNormal, &[75, 173, 174, 17], 629);
                step(f, Op::PerFootRotationFactor, &[5, 72, 73, 170], 630);
                step(f, Op::MulF, &[5, 170, 171], 631);
                step(f, Op::SubF, &[415, 6, 152], 632);
                step(f, Op::MulF, &[171, 152, 172], 633);
                step(f, Op::QuatFromAxisAngle, &[302, 172, 16], 634);
                step(f, Op::MulQ, &[17, 16, 18], 635);
                step(f, Op::Select(ValueType::Quat), &[19, 18, 19, 20], 636);
                step(f, Op::MakeTransform, &[71, 20, 300, 26], 637);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 28, 26], 638);
                step(f, Op::Copy(ValueType::Int), &[2, 40], 639);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 40, 27], 640);
                step(f, Op::MakeAbsolute, &[27, 2, 28], 641);
                step(f, Op::BreakTransform, &[28, 92, 21, 93], 642);
                step(f, Op::ClampSpatially, &[92, 299, 413, 46, 94], 643);
                step(f, Op::SubF, &[415, 6, 208], 644);
                step(f, Op::MulF, &[5, 208, 205], 645);
                step(f, Op::LimitRotationAroundZ, &[21, 205, 71, 22], 646);
                step(f, Op::MakeTransform, &[94, 22, 300, 29], 647);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 40, 29], 648);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 40, 25], 649);
                step(f, Op::JumpIfFalse, &[25, 702], 650)
            }
            650 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 40, 31], 651);
                step(f, Op::BreakTransform, &[31, 95, 23, 96], 652);
                step(f, Op::ArrayAt(Elem::Float), &[0, 40, 204], 653);
                step(f, Op::SubF, &[3, 204, 206], 654);
                step(f, Op::MulF, &[206, 1, 207], 655);
                step(f, Op::ScaleV, &[0, 207, 97], 656);
                step(f, Op::AddV, &[95, 97, 98], 657);
                step(f, Op::MakeTransform, &[98, 23, 300, 38], 658);
                step(f, Op::Copy(ValueType::Transform), &[38, 39], 659);
                step(f, Op::Copy(ValueType::Transform), &[96, 40], 660);
                step(f, Op::BreakTransform, &[39, 126, 28, 127], 661);
                step(f, Op::MakeVector, &[413, 413, 39, 128], 662);
                step(f, Op::AddV, &[126, 128, 129], 663);
                step(f, Op::SubV, &[126, 128, 130], 664);
                step(f, Op::LineTrace, &[129, 130, 31, 131, 132, 235], 665);
                step(f, Op::RotateVector, &[28, 302, 133], 666);
                step(f, Op::FindQuatBetween, &[133, 132, 29], 667);
                step(f, Op::MulQ, &[29, 28, 30], 668);
                step(f, Op::MulF, &[37, 36, 236], 669);
                step(f, Op::AddF, &[236, 45, 237], 670);
                step(f, Op::NegF, &[237, 238], 671);
                step(f, Op::MakeVector, &[413, 238, 413, 134], 672);
                step(f, Op::RotateVector, &[30, 134, 136], 673);
                step(f, Op::AddV, &[131, 136, 138], 674);
                step(f, Op::AddV, &[138, 128, 140], 675);
                step(f, Op::SubV, &[138, 128, 141], 676);
                step(f, Op::LineTrace, &[140, 141, 32, 144, 145, 240], 677);
                step(f, Op::BreakVector, &[144, 242, 243, 244], 678);
                step(f, Op::BreakVector, &[138, 248, 249, 250], 679);
                step(f, Op::SubF, &[244, 250, 254], 680);
                step(f, Op::Select(ValueType::Float), &[32, 254, 413, 256], 681);
                step(f, Op::AddF, &[41, 45, 239], 682);
                step(f, Op::MakeVector, &[413, 239, 413, 135], 683);
                step(f, Op::RotateVector, &[30, 135, 137], 684);
                step(f, Op::AddV, &[131, 137, 139], 685);
                step(f, Op::AddV, &[139, 128, 142], 686);
                step(f, Op::SubV, &[139, 128, 143], 687);
                step(f, Op::LineTrace, &[142, 143, 33, 146, 147, 241], 688);
                step(f, Op::BreakVector, &[146, 245, 246, 247], 689);
                step(f, Op::BreakVector, &[139, 251, 252, 253], 690);
                step(f, Op::SubF, &[247, 253, 255], 691);
                step(f, Op::Select(ValueType::Float), &[33, 255, 413, 257], 692);
                step(f, Op::MaxF, &[256, 257, 258], 693);
                step(f, Op::ClampF, &[258, 413, 44, 259], 694);
                step(f, Op::MakeVector, &[413, 413, 259, 148], 695);
                step(f, Op::AddV, &[131, 148, 149], 696);
                step(f, Op::MakeTransform, &[149, 30, 300, 41], 697);
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
                step(f, Op::ArrayAt(Elem::Float), &[0, 40, 204], 708);
                step(f, Op::SubF, &[3, 204, 206], 709);
                step(f, Op::MulF, &[206, 1, 207], 710);
                step(f, Op::ScaleV, &[0, 207, 97], 711);
                step(f, Op::AddV, &[95, 97, 98], 712);
                step(f, Op::DivF, &[204, 3, 287], 713);
                step(f, Op::ClampF, &[287, 413, 415, 288], 714);
                step(f, Op::SubF, &[415, 288, 260], 715);
                step(f, Op::MulF, &[60, 260, 261], 716);
                step(f, Op::VectorLerp, &[150, 98, 261, 413, 152], 717);
                step(f, Op::MakeTransform, &[152, 23, 300, 45], 718);
                step(f, Op::Copy(ValueType::Transform), &[45, 46], 719);
                step(f, Op::Copy(ValueType::Transform), &[96, 47], 720);
                step(f, Op::BreakTransform, &[46, 153, 32, 154], 721);
                step(f, Op::MakeVector, &[413, 413, 39, 155], 722);
                step(f, Op::AddV, &[153, 155, 156], 723);
                step(f, Op::SubV, &[153, 155, 157], 724);
                step(f, Op::LineTrace, &[156, 157, 34, 158, 159, 262], 725);
                step(f, Op::RotateVector, &[32, 302, 160], 726);
                step(f, Op::FindQuatBetween, &[160, 159, 33], 727);
                step(f, Op::MulQ, &[33, 32, 34], 728);
                step(f, Op::MulF, &[37, 36, 263], 729);
                step(f, Op::AddF, &[263, 45, 264], 730);
                step(f, Op::NegF, &[264, 265], 731);
                step(f, Op::MakeVector, &[413, 265, 413, 161], 732);
                step(f, Op::RotateVector, &[34, 161, 163], 733);
                step(f, Op::AddV, &[158, 163, 165], 734);
                step(f, Op::AddV, &[165, 155, 167], 735);
                step(f, Op::SubV, &[165, 155, 168], 736);
                step(f, Op::LineTrace, &[167, 168, 35, 171, 172, 267], 737);
                step(f, Op::BreakVector, &[171, 269, 270, 271], 738);
                step(f, Op::BreakVector, &[165, 275, 276, 277], 739);
                step(f, Op::SubF, &[271, 277, 281], 740);
                step(f, Op::Select(ValueType::Float), &[35, 281, 413, 283], 741);
                step(f, Op::AddF, &[41, 45, 266], 742);
                step(f, Op::MakeVector, &[413, 266, 413, 162], 743);
                step(f, Op::RotateVector, &[34, 162, 164], 744);
                step(f, Op::AddV, &[158, 164, 166], 745);
                step(f, Op::AddV, &[166, 155, 169], 746);
                step(f, Op::SubV, &[166, 155, 170], 747);
                step(f, Op::LineTrace, &[169, 170, 36, 173, 174, 268], 748);
                step(f, Op::BreakVector, &[173, 272, 273, 274], 749);
                step(f, Op::BreakVector, &[166, 278, 279, 280], 750);
                step(f, Op::SubF, &[274, 280, 282], 751);
                step(f, Op::Select(ValueType::Float), &[36, 282, 413, 284], 752);
                step(f, Op::MaxF, &[283, 284, 285], 753);
                step(f, Op::ClampF, &[285, 413, 44, 286], 754);
                step(f, Op::MakeVector, &[413, 413, 286, 175], 755);
                step(f, Op::AddV, &[158, 175, 176], 756);
                step(f, Op::MakeTransform, &[176, 34, 300, 48], 757);
                step(f, Op::Select(ValueType::Transform), &[34, 48, 46, 49], 758);
                step(f, Op::Copy(ValueType::Transform), &[49, 47], 759);
                step(f, Op::Jump, &[760], 760)
            }
            760 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 40, 47], 761);
                761
            }
            761 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 40, 204], 762);
                step(f, Op::GreaterF, &[204, 3, 26], 763);
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
                step(f, Op::SubF, &[415, 6, 208], 774);
                step(f, Op::MulF, &[5, 208, 209], 775);
                step(f, Op::FootAvoidance, &[177, 99, 209, 27, 61, 101], 776);
                step(f, Op::MakeTransform, &[101, 35, 300, 33], 777);
                step(f, Op::Copy(ValueType::Transform), &[33, 34], 778);
                step(f, Op::Copy(ValueType::Transform), &[96, 35], 779);
                step(f, Op::BreakTransform, &[34, 102, 25, 103], 780);
                step(f, Op::MakeVector, &[413, 413, 39, 104], 781);
                step(f, Op::AddV, &[102, 104, 105], 782);
                step(f, Op::SubV, &[102, 104, 106], 783);
                step(f, Op::LineTrace, &[105, 106, 28, 107, 108, 210], 784);
                step(f, Op::RotateVector, &[25, 302, 109], 785);
                step(f, Op::FindQuatBetween, &[109, 108, 26], 786);
                step(f, Op::MulQ, &[26, 25, 27], 787);
                step(f, Op::MulF, &[37, 36, 211], 788);
                step(f, Op::AddF, &[211, 45, 212], 789);
                step(f, Op::NegF, &[212, 213], 790);
                step(f, Op::MakeVector, &[413, 213, 413, 110], 791);
                step(f, Op::RotateVector, &[27, 110, 112], 792);
                step(f, Op::AddV, &[107, 112, 114], 793);
                step(f, Op::AddV, &[114, 104, 116], 794);
                step(f, Op::SubV, &[114, 104, 117], 795);
                step(f, Op::LineTrace, &[116, 117, 29, 120, 121, 215], 796);
                step(f, Op::BreakVector, &[120, 217, 218, 219], 797);
                step(f, Op::BreakVector, &[114, 223, 224, 225], 798);
                step(f, Op::SubF, &[219, 225, 229], 799);
                step(f, Op::Select(ValueType::Float), &[29, 229, 413, 231], 800);
                step(f, Op::AddF, &[41, 45, 214], 801);
                step(f, Op::MakeVector, &[413, 214, 413, 111], 802);
                step(f, Op::RotateVector, &[27, 111, 113], 803);
                step(f, Op::AddV, &[107, 113, 115], 804);
                step(f, Op::AddV, &[115, 104, 118], 805);
                step(f, Op::SubV, &[115, 104, 119], 806);
                step(f, Op::LineTrace, &[118, 119, 30, 122, 123, 216], 807);
                step(f, Op::BreakVector, &[122, 220, 221, 222], 808);
                step(f, Op::BreakVector, &[115, 226, 227, 228], 809);
                step(f, Op::SubF, &[222, 228, 230], 810);
                step(f, Op::Select(ValueType::Float), &[30, 230, 413, 232], 811);
                step(f, Op::MaxF, &[231, 232, 233], 812);
                step(f, Op::ClampF, &[233, 413, 44, 234], 813);
                step(f, Op::MakeVector, &[413, 413, 234, 124], 814);
                step(f, Op::AddV, &[107, 124, 125], 815);
                step(f, Op::MakeTransform, &[125, 27, 300, 36], 816);
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
                step(f, Op::DivF, &[204, 3, 287], 826);
                step(f, Op::ClampF, &[287, 413, 415, 288], 827);
                step(f, Op::Copy(ValueType::Transform), &[30, 52], 828);
                step(f, Op::Copy(ValueType::Transform), &[50, 53], 829);
                step(f, Op::Copy(ValueType::Float), &[288, 289], 830);
                step(f, Op::Copy(ValueType::Transform), &[96, 54], 831);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[3, 2], 832);
                step(f, Op::ArrayReset(Elem::Vec3), &[2], 833);
                step(f, Op::BreakTransform, &[52, 183, 37, 184], 834);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 183], 835);
                step(f, Op::BreakTransform, &[52, 183, 37, 184], 836);
                step(f, Op::UnitV, &[0, 182], 837);
                step(f, Op::LengthV, &[0, 290], 838);
                step(f, Op::RemapF, &[290, 413, 47, 413, 48, 47, 291], 839);
                step(f, Op::ScaleV, &[182, 291, 187], 840);
                step(f, Op::SubV, &[183, 187, 193], 841);
                step(f, Op::MakeVector, &[413, 413, 50, 191], 842);
                step(f, Op::AddV, &[193, 191, 195], 843);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 195], 844);
                step(f, Op::BreakTransform, &[52, 183, 37, 184], 845);
                step(f, Op::UnitV, &[0, 182], 846);
                step(f, Op::LengthV, &[0, 290], 847);
                step(f, Op::RemapF, &[290, 413, 47, 413, 48, 47, 291], 848);
                step(f, Op::ScaleV, &[182, 291, 187], 849);
                step(f, Op::SubV, &[183, 187, 193], 850);
                step(f, Op::MakeVector, &[413, 413, 50, 191], 851);
                step(f, Op::AddV, &[193, 191, 195], 852);
                step(f, Op::RemapF, &[290, 413, 47, 413, 52, 47, 293], 853);
                step(f, Op::MakeVector, &[413, 413, 293, 189], 854);
                step(f, Op::AddV, &[195, 189, 199], 855);
                step(f, Op::BreakTransform, &[53, 185, 38, 186], 856);
                step(f, Op::BreakVector, &[185, 298, 299, 300], 857);
                step(f, Op::BreakVector, &[183, 295, 296, 297], 858);
                step(f, Op::SubF, &[300, 297, 301], 859);
                step(f, Op::MaxF, &[301, 413, 303], 860);
                step(f, Op::MulF, &[303, 54, 307], 861);
                step(f, Op::AbsF, &[301, 305], 862);
                step(f, Op::RemapF, &[305, 413, 57, 413, 56, 47, 306], 863);
                step(f, Op::AddF, &[307, 306, 309], 864);
                step(f, Op::MakeVector, &[413, 413, 309, 197], 865);
                step(f, Op::AddV, &[199, 197, 201], 866);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 201], 867);
                step(f, Op::BreakTransform, &[52, 183, 37, 184], 868);
                step(f, Op::UnitV, &[0, 182], 869);
                step(f, Op::LengthV, &[0, 290], 870);
                step(f, Op::RemapF, &[290, 413, 47, 413, 48, 47, 291], 871);
                step(f, Op::ScaleV, &[182, 291, 187], 872);
                step(f, Op::SubV, &[183, 187, 193], 873);
                step(f, Op::MakeVector, &[413, 413, 50, 191], 874);
                step(f, Op::AddV, &[193, 191, 195], 875);
                step(f, Op::RemapF, &[290, 413, 47, 413, 52, 47, 293], 876);
                step(f, Op::MakeVector, &[413, 413, 293, 189], 877);
                step(f, Op::AddV, &[195, 189, 199], 878);
                step(f, Op::BreakTransform, &[53, 185, 38, 186], 879);
                step(f, Op::BreakVector, &[185, 298, 299, 300], 880);
                step(f, Op::BreakVector, &[183, 295, 296, 297], 881);
                step(f, Op::SubF, &[300, 297, 301], 882);
                step(f, Op::MaxF, &[301, 413, 303], 883);
                step(f, Op::MulF, &[303, 54, 307], 884);
                step(f, Op::AbsF, &[301, 305], 885);
                step(f, Op::RemapF, &[305, 413, 57, 413, 56, 47, 306], 886);
                step(f, Op::AddF, &[307, 306, 309], 887);
                step(f, Op::MakeVector, &[413, 413, 309, 197], 888);
                step(f, Op::AddV, &[199, 197, 201], 889);
                step(f, Op::RemapF, &[290, 413, 47, 413, 49, 47, 292], 890);
                step(f, Op::ScaleV, &[182, 292, 188], 891);
                step(f, Op::AddV, &[185, 188, 194], 892);
                step(f, Op::MakeVector, &[413, 413, 51, 192], 893);
                step(f, Op::AddV, &[194, 192, 196], 894);
                step(f, Op::RemapF, &[290, 413, 47, 413, 53, 47, 294], 895);
                step(f, Op::MakeVector, &[413, 413, 294, 190], 896);
                step(f, Op::AddV, &[196, 190, 200], 897);
                step(f, Op::NegF, &[301, 302], 898);
                step(f, Op::MaxF, &[302, 413, 304], 899);
                step(f, Op::MulF, &[304, 55, 308], 900);
                step(f, Op::AddF, &[308, 306, 310], 901);
                step(f, Op::MakeVector, &[413, 413, 310, 198], 902);
                step(f, Op::AddV, &[200, 198, 202], 903);
                step(f, Op::LerpV, &[201, 202, 414, 203], 904);
                step(f, Op::GetTransform, &[36, 52, 47, 55], 905);
                step(f, Op::BreakTransform, &[55, 204, 39, 205], 906);
                step(f, Op::BreakVector, &[204, 320, 321, 322], 907);
                step(f, Op::SubF, &[415, 6, 314], 908);
                step(f, Op::MulF, &[58, 314, 315], 909);
                step(f, Op::MulF, &[5, 315, 316], 910);
                step(f, Op::QuatFromAxisAngle, &[302, 316, 40], 911);
                step(f, Op::SubV, &[203, 204, 206], 912);
                step(f, Op::BreakVector, &[206, 311, 312, 313], 913);
                step(f, Op::MakeVector, &[311, 312, 413, 207], 914);
                step(f, Op::RotateVector, &[40, 207, 208], 915);
                step(f, Op::BreakVector, &[208, 317, 318, 319], 916);
                step(f, Op::AddF, &[320, 317, 326], 917);
                step(f, Op::AddF, &[321, 318, 327], 918);
                step(f, Op::BreakVector, &[203, 323, 324, 325], 919);
                step(f, Op::MakeVector, &[326, 327, 325, 209], 920);
                step(f, Op::DistanceV, &[183, 185, 328], 921);
                step(f, Op::RemapF, &[328, 417, 424, 413, 415, 47, 329], 922);
                step(f, Op::LerpV, &[203, 209, 329, 210], 923);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 210], 924);
                step(f, Op::BreakTransform, &[53, 185, 38, 186], 925);
                step(f, Op::UnitV, &[0, 182], 926);
                step(f, Op::LengthV, &[0, 290], 927);
                step(f, Op::RemapF, &[290, 413, 47, 413, 49, 47, 292], 928);
                step(f, Op::ScaleV, &[182, 292, 188], 929);
                step(f, Op::AddV, &[185, 188, 194], 930);
                step(f, Op::MakeVector, &[413, 413, 51, 192], 931);
                step(f, Op::AddV, &[194, 192, 196], 932);
                step(f, Op::RemapF, &[290, 413, 47, 413, 53, 47, 294], 933);
                step(f, Op::MakeVector, &[413, 413, 294, 190], 934);
                step(f, Op::AddV, &[196, 190, 200], 935);
                step(f, Op::BreakVector, &[185, 298, 299, 300], 936);
                step(f, Op::BreakTransform, &[52, 183, 37, 184], 937);
                step(f, Op::BreakVector, &[183, 295, 296, 297], 938);
                step(f, Op::SubF, &[300, 297, 301], 939);
                step(f, Op::NegF, &[301, 302], 940);
                step(f, Op::MaxF, &[302, 413, 304], 941);
                step(f, Op::MulF, &[304, 55, 308], 942);
                step(f, Op::AbsF, &[301, 305], 943);
                step(f, Op::RemapF, &[305, 413, 57, 413, 56, 47, 306], 944);
                step(f, Op::AddF, &[308, 306, 310], 945);
                step(f, Op::MakeVector, &[413, 413, 310, 198], 946);
                step(f, Op::AddV, &[200, 198, 202], 947);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 202], 948);
                step(f, Op::BreakTransform, &[53, 185, 38, 186], 949);
                step(f, Op::UnitV, &[0, 182], 950);
                step(f, Op::LengthV, &[0, 290], 951);
                step(f, Op::RemapF, &[290, 413, 47, 413, 49, 47, 292], 952);
                step(f, Op::ScaleV, &[182, 292, 188], 953);
                step(f, Op::AddV, &[185, 188, 194], 954);
                step(f, Op::MakeVector, &[413, 413, 51, 192], 955);
                step(f, Op::AddV, &[194, 192, 196], 956);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 196], 957);
                step(f, Op::BreakTransform, &[53, 185, 38, 186], 958);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 185], 959);
                step(f, Op::JumpIfFalse, &[3, 962], 960)
            }
            960 => {
                step(f, Op::DrawSpline, &[2, 52, 55, 414, 304], 961);
                step(f, Op::Jump, &[962], 962)
            }
            962 => {
                step(f, Op::Spline, &[2, 289, 52, 211, 212], 963);
                step(f, Op::BreakTransform, &[52, 183, 37, 184], 964);
                step(f, Op::BreakTransform, &[53, 185, 38, 186], 965);
                step(f, Op::SlerpQ, &[37, 38, 289, 41], 966);
                step(f, Op::MulF, &[289, 425, 330], 967);
                step(f, Op::SinF, &[330, 331], 968);
                step(f, Op::MulF, &[331, 59, 332], 969);
                step(f, Op::SlerpQ, &[41, 81, 332, 42], 970);
                step(f, Op::MakeTransform, &[211, 42, 300, 56], 971);
                step(f, Op::Copy(ValueType::Transform), &[56, 54], 972);
                step(f, Op::Jump, &[973], 973)
            }
            973 => {
                step(f, Op::BreakTransform, &[54, 179, 36, 180], 974);
                step(f, Op::Equals(Elem::Int), &[40, 52, 27], 975);
                step(f, Op::Select(ValueType::Int), &[27, 53, 52, 41], 976);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 41, 32], 977);
                step(f, Op::BreakTransform, &[32, 99, 24, 100], 978);
                step(f, Op::SubF, &[415, 6, 208], 979);
                step(f, Op::MulF, &[5, 208, 209], 980);
                step(f, Op::FootAvoidance, &[179, 99, 209, 27, 61, 181], 981);
                step(f, Op::MakeTransform, &[181, 36, 300, 51], 982);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 40, 51], 983);
                983
            }
            983 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 40, 204], 984);
                step(f, Op::GreaterF, &[204, 3, 26], 985);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 40, 26], 986);
                step(f, Op::Copy(ValueType::Bone), &[0, 17], 987);
                step(f, Op::Copy(ValueType::Int), &[2, 42], 988);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 42, 57], 989);
                step(f, Op::BreakTransform, &[57, 213, 43, 214], 990);
                step(f, Op::MakeVector, &[413, 413, 34, 223], 991);
                step(f, Op::AddV, &[213, 223, 224], 992);
                step(f, Op::GetTransform, &[17, 52, 47, 59], 993);
                step(f, Op::BreakTransform, &[59, 218, 45, 219], 994);
                step(f, Op::MakeTransform, &[224, 45, 300, 61], 995);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 42, 20], 996);
                step(f, Op::GetTransform, &[20, 52, 47, 60], 997);
                step(f, Op::BreakTransform, &[60, 220, 46, 221], 998);
                step(f, Op::SubV, &[220, 218, 222], 999);
                step(f, Op::AddV, &[224, 222, 225], 1000);
                step(f, Op::FootPivots, &[224, 225, 36, 35, 34, 37, 226, 227, 228], 1001);
                step(f, Op::GetParent, &[17, 18], 1002);
                step(f, Op::GetParent, &[18, 19], 1003);
                step(f, Op::GetTransform, &[19, 52, 48, 58], 1004);
                step(f, Op::BreakTransform, &[58, 215, 44, 216], 1005);
                step(f, Op::SubV, &[213, 215, 217], 1006);
                step(f, Op::DotV, &[217, 303, 333], 1007);
                step(f, Op::RemapF, &[333, 63, 62, 64, 413, 47, 336], 1008);
                step(f, Op::LengthV, &[0, 334], 1009);
                step(f, Op::RemapF, &[334, 413, 70, 413, 415, 47, 335], 1010);
                step(f, Op::MulF, &[336, 335, 337], 1011);
                step(f, Op::QuatFromAxisAngle, &[305, 337, 47], 1012);
                step(f, Op::RotateAroundPoint, &[61, 226, 47, 62], 1013);
                step(f, Op::SubV, &[227, 226, 229], 1014);
                step(f, Op::RotateVector, &[47, 229, 230], 1015);
                step(f, Op::AddV, &[226, 230, 231], 1016);
                step(f, Op::RemapF, &[333, 65, 63, 66, 413, 47, 338], 1017);
                step(f, Op::MulF, &[338, 335, 339], 1018);
                step(f, Op::QuatFromAxisAngle, &[305, 339, 48], 1019);
                step(f, Op::RotateAroundPoint, &[62, 231, 48, 63], 1020);
                step(f, Op::RemapF, &[333, 67, 68, 413, 69, 47, 340], 1021);
                step(f, Op::MulF, &[340, 335, 341], 1022);
                step(f, Op::QuatFromAxisAngle, &[305, 341, 49], 1023);
                step(f, Op::RotateAroundPoint, &[63, 228, 49, 64], 1024);
                step(f, Op::SubF, &[415, 6, 342], 1025);
                step(f, Op::MulF, &[5, 342, 343], 1026);
                step(f, Op::LimitRotationAroundZ, &[43, 343, 71, 50], 1027);
                step(f, Op::RotateAroundPoint, &[64, 213, 50, 65], 1028);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 42, 65], 1029);
                step(f, Op::JumpIfFalse, &[3, 1086], 1030)
            }
            1030 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 42, 57], 1031);
                step(f, Op::BreakTransform, &[57, 213, 43, 214], 1032);
                step(f, Op::MakeVector, &[413, 413, 34, 223], 1033);
                step(f, Op::AddV, &[213, 223, 224], 1034);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 42, 20], 1035);
                step(f, Op::GetTransform, &[20, 52, 47, 60], 1036);
                step(f, Op::BreakTransform, &[60, 220, 46, 221], 1037);
                step(f, Op::GetTransform, &[17, 52, 47, 59], 1038);
                step(f, Op::BreakTransform, &[59, 218, 45, 219], 1039);
                step(f, Op::SubV, &[220, 218, 222], 1040);
                step(f, Op::AddV, &[224, 222, 225], 1041);
                step(f, Op::FootPivots, &[224, 225, 36, 35, 34, 37, 226, 227, 228], 1042);
                step(f, Op::DrawPoint, &[228, 426, 305], 1043);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 42, 57], 1044);
                step(f, Op::BreakTransform, &[57, 213, 43, 214], 1045);
                step(f, Op::MakeVector, &[413, 413, 34, 223], 1046);
                step(f, Op::AddV, &[213, 223, 224], 1047);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 42, 20], 1048);
                step(f, Op::GetTransform, &[20, 52, 47, 60], 1049);
                step(f, Op::BreakTransform, &[60, 220, 46, 221], 1050);
                step(f, Op::GetTransform, &[17, 52, 47, 59], 1051);
                step(f, Op::BreakTransform, &[59, 218, 45, 219], 1052);
                step(f, Op::SubV, &[220, 218, 222], 1053);
                step(f, Op::AddV, &[224, 222, 225], 1054);
                step(f, Op::FootPivots, &[224, 225, 36, 35, 34, 37, 226, 227, 228], 1055);
                step(f, Op::DrawPoint, &[226, 426, 303], 1056);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 42, 57], 1057);
                step(f, Op::BreakTransform, &[57, 213, 43, 214], 1058);
                step(f, Op::MakeVector, &[413, 413, 34, 223], 1059);
                step(f, Op::AddV, &[213, 223, 224], 1060);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 42, 20], 1061);
                step(f, Op::GetTransform, &[20, 52, 47, 60], 1062);
                step(f, Op::BreakTransform, &[60, 220, 46, 221], 1063);
                step(f, Op::GetTransform, &[17, 52, 47, 59], 1064);
                step(f, Op::BreakTransform, &[59, 218, 45, 219], 1065);
                step(f, Op::SubV, &[220, 218, 222], 1066);
                step(f, Op::AddV, &[224, 222, 225], 1067);
                step(f, Op::FootPivots, &[224, 225, 36, 35, 34, 37, 226, 227, 228], 1068);
                step(f, Op::GetParent, &[17, 18], 1069);
                step(f, Op::GetParent, &[18, 19], 1070);
                step(f, Op::GetTransform, &[19, 52, 48, 58], 1071);
                step(f, Op::BreakTransform, &[58, 215, 44, 216], 1072);
                step(f, Op::SubV, &[213, 215, 217], 1073);
                step(f, Op::DotV, &[217, 303, 333], 1074);
                step(f, Op::RemapF, &[333, 63, 62, 64, 413, 47, 336], 1075);
                step(f, Op::LengthV, &[0, 334], 1076);
                step(f, Op::RemapF, &[334, 413, 70, 413, 415, 47, 335], 1077);
                step(f, Op::MulF, &[336, 335, 337], 1078);
                step(f, Op::QuatFromAxisAngle, &[305, 337, 47], 1079);
                step(f, Op::SubV, &[227, 226, 229], 1080);
                step(f, Op::RotateVector, &[47, 229, 230], 1081);
                step(f, Op::AddV, &[226, 230, 231], 1082);
                step(f, Op::DrawPoint, &[231, 426, 302], 1083);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 42, 57], 1084);
                step(f, Op::DrawTransform, &[57, 424, 414], 1085);
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
                step(f, Op::GetTransform, &[24, 52, 48, 66], 1096);
                step(f, Op::BreakTransform, &[66, 232, 51, 233], 1097);
                step(f, Op::LengthV, &[1, 345], 1098);
                step(f, Op::ClavicleOffset, &[4, 345, 76, 79, 346], 1099);
                step(f, Op::MakeVector, &[413, 413, 346, 234], 1100);
                step(f, Op::AddV, &[232, 234, 235], 1101);
                step(f, Op::MakeTransform, &[235, 51, 300, 67], 1102);
                step(f, Op::SetTransform, &[24, 67, 52, 47, 415], 1103);
                step(f, Op::GetParent, &[21, 22], 1104);
                step(f, Op::GetParent, &[22, 23], 1105);
                step(f, Op::GetTransform, &[21, 52, 48, 68], 1106);
                step(f, Op::GetTransform, &[23, 52, 48, 69], 1107);
                step(f, Op::BreakTransform, &[69, 236, 53, 237], 1108);
                step(f, Op::Equals(Elem::Int), &[43, 52, 37], 1109);
                step(f, Op::Select(ValueType::Int), &[37, 53, 52, 44], 1110);
                step(f, Op::ArrayAt(Elem::Float), &[0, 44, 344], 1111);
                step(f, Op::ArmSwingRotation, &[344, 1, 0, 77, 419, 427, 415, 76, 74, 75, 419, 419, 415, 347], 1112);
                step(f, Op::QuatFromAxisAngle, &[305, 347, 52], 1113);
                step(f, Op::RotateAroundPoint, &[68, 236, 52, 70], 1114);
                step(f, Op::BreakTransform, &[70, 238, 54, 239], 1115);
                step(f, Op::LengthV, &[1, 345], 1116);
                step(f, Op::RemapF, &[345, 413, 76, 413, 78, 47, 348], 1117);
                step(f, Op::MakeVector, &[413, 413, 348, 240], 1118);
                step(f, Op::AddV, &[238, 240, 241], 1119);
                step(f, Op::MakeTransform, &[241, 54, 300, 71], 1120);
                step(f, Op::Select(ValueType::Vec3), &[37, 306, 305, 243], 1121);
                step(f, Op::Select(ValueType::Vec3), &[37, 303, 307, 244], 1122);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 43, 242], 1123);
                step(f, Op::TwoBoneIK, &[23, 22, 21, 71, 243, 244, 242, 52, 415, 48, 428, 429, 47, 38, 349], 1124);
                step(f, Op::JumpIfFalse, &[3, 1143], 1125)
            }
            1125 => {
                step(f, Op::GetParent, &[21, 22], 1126);
                step(f, Op::GetParent, &[22, 23], 1127);
                step(f, Op::GetTransform, &[23, 52, 48, 69], 1128);
                step(f, Op::BreakTransform, &[69, 236, 53, 237], 1129);
                step(f, Op::GetTransform, &[21, 52, 48, 68], 1130);
                step(f, Op::Equals(Elem::Int), &[43, 52, 37], 1131);
                step(f, Op::Select(ValueType::Int), &[37, 53, 52, 44], 1132);
                step(f, Op::ArrayAt(Elem::Float), &[0, 44, 344], 1133);
                step(f, Op::ArmSwingRotation, &[344, 1, 0, 77, 419, 427, 415, 76, 74, 75, 419, 419, 415, 347], 1134);
                step(f, Op::QuatFromAxisAngle, &[305, 347, 52], 1135);
                step(f, Op::RotateAroundPoint, &[68, 236, 52, 70], 1136);
                step(f, Op::BreakTransform, &[70, 238, 54, 239], 1137);
                step(f, Op::LengthV, &[1, 345], 1138);
                step(f, Op::RemapF, &[345, 413, 76, 413, 78, 47, 348], 1139);
                step(f, Op::MakeVector, &[413, 413, 348, 240], 1140);
                step(f, Op::AddV, &[238, 240, 241], 1141);
                step(f, Op::DrawLine, &[236, 241, 414, 303], 1142);
                step(f, Op::Jump, &[1143], 1143)
            }
            1143 => {
                step(f, Op::Jump, &[1089], 1144)
            }
            1144 => {
                step(f, Op::Copy(ValueType::Float), &[413, 351], 1145);
                step(f, Op::Copy(ValueType::Float), &[421, 352], 1146);
                step(f, Op::Copy(ValueType::Bool), &[48, 39], 1147);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[3, 6], 1148);
                step(f, Op::Copy(ValueType::Int), &[52, 45], 1149);
                step(f, Op::MakeVector, &[413, 413, 39, 247], 1150);
                1150
            }
            1150 => {
                step(f, Op::ForEachNext(Elem::Transform), &[6, 45, 72, 46, 47, 1163], 1151)
            }
            1151 => {
                step(f, Op::BreakTransform, &[72, 245, 55, 246], 1152);
                step(f, Op::AddV, &[245, 247, 248], 1153);
                step(f, Op::SubV, &[245, 247, 249], 1154);
                step(f, Op::SphereTrace, &[248, 249, 38, 40, 250, 251, 353], 1155);
                step(f, Op::BreakVector, &[250, 354, 355, 356], 1156);
                step(f, Op::LessF, &[356, 352, 41], 1157);
                step(f, Op::And, &[40, 41, 42], 1158);
                step(f, Op::JumpIfFalse, &[42, 1162], 1159)
            }
            1159 => {
                step(f, Op::Copy(ValueType::Float), &[356, 352], 1160);
                step(f, Op::Copy(ValueType::Bool), &[47, 39], 1161);
                step(f, Op::Jump, &[1162], 1162)
            }
            1162 => {
                step(f, Op::Jump, &[1150], 1163)
            }
            1163 => {
                step(f, Op::Select(ValueType::Float), &[39, 352, 413, 357], 1164);
                step(f, Op::ClampF, &[357, 42, 43, 358], 1165);
                step(f, Op::Copy(ValueType::Float), &[358, 351], 1166);
                step(f, Op::Jump, &[1167], 1167)
            }
            1167 => {
                step(f, Op::FloatLerp, &[7, 351, 33, 359], 1168);
                step(f, Op::Copy(ValueType::Float), &[359, 7], 1169);
                step(f, Op::GetTransform, &[37, 52, 47, 77], 1170);
                step(f, Op::BreakTransform, &[77, 264, 62, 265], 1171);
                step(f, Op::PelvisLean, &[1, 81, 86, 87, 372, 373], 1172);
                step(f, Op::LengthV, &[0, 350], 1173);
                step(f, Op::RemapF, &[350, 413, 81, 413, 80, 47, 360], 1174);
                step(f, Op::MulF, &[4, 430, 361], 1175);
                step(f, Op::SinF, &[361, 362], 1176);
                step(f, Op::MulF, &[360, 362, 363], 1177);
                step(f, Op::AddF, &[363, 7, 364], 1178);
                step(f, Op::MakeVector, &[413, 373, 364, 266], 1179);
                step(f, Op::AddV, &[264, 266, 267], 1180);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 52, 73], 1181);
                step(f, Op::BreakTransform, &[73, 252, 56, 253], 1182);
                step(f, Op::BreakVector, &[252, 374, 375, 376], 1183);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 53, 74], 1184);
                step(f, Op::BreakTransform, &[74, 254, 57, 255], 1185);
                step(f, Op::BreakVector, &[254, 377, 378, 379], 1186);
                step(f, Op::SubF, &[376, 379, 380], 1187);
                step(f, Op::PelvisSideLean, &[380, 88, 89, 381], 1188);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 52, 75], 1189);
                step(f, Op::BreakTransform, &[75, 258, 58, 259], 1190);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 53, 76], 1191);
                step(f, Op::BreakTransform, &[76, 260, 59, 261], 1192);
                step(f, Op::SlerpQ, &[58, 59, 414, 60], 1193);
                step(f, Op::EulerFromQuat, &[60, 52, 262], 1194);
                step(f, Op::BreakVector, &[262, 368, 369, 370], 1195);
                step(f, Op::RemapF, &[350, 82, 81, 413, 83, 47, 366], 1196);
                step(f, Op::SubV, &[252, 254, 256], 1197);
                step(f, Op::RotateVector, &[0, 303, 257], 1198);
                step(f, Op::DotV, &[256, 257, 365], 1199);
                step(f, Op::MulF, &[366, 365, 367], 1200);
                step(f, Op::AddF, &[370, 367, 371], 1201);
                step(f, Op::MakeVector, &[372, 381, 371, 263], 1202);
                step(f, Op::QuatFromEuler, &[263, 52, 61], 1203);
                step(f, Op::MakeTransform, &[267, 61, 300, 78], 1204);
                step(f, Op::SetTransform, &[38, 78, 52, 47, 415], 1205);
                step(f, Op::GetTransform, &[39, 53, 47, 79], 1206);
                step(f, Op::BreakTransform, &[79, 268, 66, 269], 1207);
                step(f, Op::LengthV, &[0, 350], 1208);
                step(f, Op::RemapF, &[350, 82, 81, 413, 83, 47, 366], 1209);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 52, 73], 1210);
                step(f, Op::BreakTransform, &[73, 252, 56, 253], 1211);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 53, 74], 1212);
                step(f, Op::BreakTransform, &[74, 254, 57, 255], 1213);
                step(f, Op::SubV, &[252, 254, 256], 1214);
                step(f, Op::RotateVector, &[0, 303, 257], 1215);
                step(f, Op::DotV, &[256, 257, 365], 1216);
                step(f, Op::MulF, &[366, 365, 367], 1217);
                step(f, Op::QuatFromAxisAngle, &[302, 367, 63], 1218);
                step(f, Op::DivF, &[84, 426, 382], 1219);
                step(f, Op::QuatScale, &[63, 382, 64], 1220);
                step(f, Op::MulQ, &[66, 64, 70], 1221);
                step(f, Op::MakeTransform, &[268, 70, 300, 83], 1222);
                step(f, Op::SetTransform, &[40, 83, 53, 47, 415], 1223);
                step(f, Op::GetTransform, &[41, 53, 47, 80], 1224);
                step(f, Op::BreakTransform, &[80, 270, 67, 271], 1225);
                step(f, Op::LengthV, &[0, 350], 1226);
                step(f, Op::RemapF, &[350, 82, 81, 413, 83, 47, 366], 1227);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 52, 73], 1228);
                step(f, Op::BreakTransform, &[73, 252, 56, 253], 1229);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 53, 74], 1230);
                step(f, Op::BreakTransform, &[74, 254, 57, 255], 1231);
                step(f, Op::SubV, &[252, 254, 256], 1232);
                step(f, Op::RotateVector, &[0, 303, 257], 1233);
                step(f, Op::DotV, &[256, 257, 365], 1234);
                step(f, Op::MulF, &[366, 365, 367], 1235);
                step(f, Op::QuatFromAxisAngle, &[302, 367, 63], 1236);
                step(f, Op::DivF, &[84, 426, 382], 1237);
                step(f, Op::QuatScale, &[63, 382, 64], 1238);
                step(f, Op::MulQ, &[67, 64, 71], 1239);
                step(f, Op::MakeTransform, &[270, 71, 300, 84], 1240);
                step(f, Op::SetTransform, &[42, 84, 53, 47, 415], 1241);
                step(f, Op::GetTransform, &[43, 53, 47, 81], 1242);
                step(f, Op::BreakTransform, &[81, 272, 68, 273], 1243);
                step(f, Op::LengthV, &[0, 350], 1244);
                step(f, Op::RemapF, &[350, 82, 81, 413, 83, 47, 366], 1245);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 52, 73], 1246);
                step(f, Op::BreakTransform, &[73, 252, 56, 253], 1247);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 53, 74], 1248);
                step(f, Op::BreakTransform, &[74, 254, 57, 255], 1249);
                step(f, Op::SubV, &[252, 254, 256], 1250);
                step(f, Op::RotateVector, &[0, 303, 257], 1251);
                step(f, Op::DotV, &[256, 257, 365], 1252);
                step(f, Op::MulF, &[366, 365, 367], 1253);
                step(f, Op::QuatFromAxisAngle, &[302, 367, 63], 1254);
                step(f, Op::DivF, &[84, 426, 382], 1255);
                step(f, Op::QuatScale, &[63, 382, 64], 1256);
                step(f, Op::MulQ, &[68, 64, 72], 1257);
                step(f, Op::MakeTransform, &[272, 72, 300, 85], 1258);
                step(f, Op::SetTransform, &[44, 85, 53, 47, 415], 1259);
                step(f, Op::GetTransform, &[45, 53, 47, 82], 1260);
                step(f, Op::BreakTransform, &[82, 274, 69, 275], 1261);
                step(f, Op::LengthV, &[0, 350], 1262);
                step(f, Op::RemapF, &[350, 82, 81, 413, 83, 47, 366], 1263);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 52, 73], 1264);
                step(f, Op::BreakTransform, &[73, 252, 56, 253], 1265);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 53, 74], 1266);
                step(f, Op::BreakTransform, &[74, 254, 57, 255], 1267);
                step(f, Op::SubV, &[252, 254, 256], 1268);
                step(f, Op::RotateVector, &[0, 303, 257], 1269);
                step(f, Op::DotV, &[256, 257, 365], 1270);
                step(f, Op::MulF, &[366, 365, 367], 1271);
                step(f, Op::QuatFromAxisAngle, &[302, 367, 63], 1272);
                step(f, Op::QuatScale, &[63, 85, 65], 1273);
                step(f, Op::MulQ, &[69, 65, 73], 1274);
                step(f, Op::MakeTransform, &[274, 73, 300, 86], 1275);
                step(f, Op::SetTransform, &[46, 86, 53, 47, 415], 1276);
                step(f, Op::Copy(ValueType::Float), &[413, 383], 1277);
                step(f, Op::Copy(ValueType::Float), &[413, 384], 1278);
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
                step(f, Op::GetTransform, &[27, 52, 48, 87], 1284);
                step(f, Op::BreakTransform, &[87, 276, 74, 277], 1285);
                step(f, Op::BreakVector, &[276, 385, 386, 387], 1286);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 49, 88], 1287);
                step(f, Op::BreakTransform, &[88, 278, 75, 279], 1288);
                step(f, Op::BreakVector, &[278, 388, 389, 390], 1289);
                step(f, Op::ArrayAt(Elem::Float), &[1, 49, 394], 1290);
                step(f, Op::MulF, &[394, 90, 395], 1291);
                step(f, Op::MulF, &[395, 395, 396], 1292);
                step(f, Op::SubF, &[385, 388, 391], 1293);
                step(f, Op::SubF, &[386, 389, 392], 1294);
                step(f, Op::MakeVector, &[391, 392, 413, 280], 1295);
                step(f, Op::DotV, &[280, 280, 393], 1296);
                step(f, Op::SubF, &[396, 393, 397], 1297);
                step(f, Op::SqrtF, &[397, 398], 1298);
                step(f, Op::AddF, &[390, 398, 399], 1299);
                step(f, Op::SubF, &[387, 399, 400], 1300);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 49, 43], 1301);
                step(f, Op::ArrayAt(Elem::Float), &[0, 49, 401], 1302);
                step(f, Op::DivF, &[401, 3, 402], 1303);
                step(f, Op::RemapF, &[402, 414, 415, 413, 415, 47, 403], 1304);
                step(f, Op::Select(ValueType::Float), &[43, 415, 403, 404], 1305);
                step(f, Op::MulF, &[400, 404, 405], 1306);
                step(f, Op::MaxF, &[384, 405, 406], 1307);
                step(f, Op::Copy(ValueType::Float), &[406, 384], 1308);
                step(f, Op::Jump, &[1280], 1309)
            }
            1309 => {
                step(f, Op::ClampF, &[384, 413, 91, 407], 1310);
                step(f, Op::Copy(ValueType::Float), &[407, 383], 1311);
                step(f, Op::Jump, &[1312], 1312)
            }
            1312 => {
                step(f, Op::GreaterF, &[383, 8, 44], 1313);
                step(f, Op::Select(ValueType::Float), &[44, 93, 92, 408], 1314);
                step(f, Op::FloatLerp, &[8, 383, 408, 409], 1315);
                step(f, Op::Copy(ValueType::Float), &[409, 8], 1316);
                step(f, Op::GetTransform, &[47, 52, 48, 89], 1317);
                step(f, Op::BreakTransform, &[89, 281, 76, 282], 1318);
                step(f, Op::MakeVector, &[413, 413, 8, 283], 1319);
                step(f, Op::SubV, &[281, 283, 284], 1320);
                step(f, Op::MakeTransform, &[284, 76, 300, 90], 1321);
                step(f, Op::SetTransform, &[48, 90, 52, 47, 415], 1322);
                step(f, Op::JumpIfFalse, &[3, 1330], 1323)
            }
            1323 => {
                step(f, Op::GetTransform, &[47, 52, 48, 89], 1324);
                step(f, Op::BreakTransform, &[89, 281, 76, 282], 1325);
                step(f, Op::MakeVector, &[413, 413, 8, 283], 1326);
                step(f, Op::SubV, &[281, 283, 284], 1327);
                step(f, Op::MakeTransform, &[284, 76, 300, 90], 1328);
                step(f, Op::DrawTransform, &[90, 431, 414], 1329);
                step(f, Op::Jump, &[1330], 1330)
            }
            1330 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1331);
                step(f, Op::Copy(ValueType::Int), &[52, 7], 1332);
                1332
            }
            1332 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 7, 2, 8, 9, 1365], 1333)
            }
            1333 => {
                step(f, Op::Copy(ValueType::Bone), &[2, 28], 1334);
                step(f, Op::Copy(ValueType::Int), &[8, 51], 1335);
                step(f, Op::GetParent, &[28, 29], 1336);
                step(f, Op::GetParent, &[29, 30], 1337);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 51, 92], 1338);
                step(f, Op::BreakTransform, &[92, 287, 78, 288], 1339);
                step(f, Op::GetTransform, &[30, 52, 48, 91], 1340);
                step(f, Op::BreakTransform, &[91, 285, 77, 286], 1341);
                step(f, Op::ArrayAt(Elem::Float), &[1, 51, 410], 1342);
                step(f, Op::MulF, &[410, 94, 411], 1343);
                step(f, Op::ClampSpatially, &[287, 285, 413, 411, 289], 1344);
                step(f, Op::MakeTransform, &[289, 78, 300, 93], 1345);
                step(f, Op::Equals(Elem::Int), &[51, 52, 45], 1346);
                step(f, Op::Select(ValueType::Vec3), &[45, 306, 305, 294], 1347);
                step(f, Op::Select(ValueType::Vec3), &[45, 303, 307, 295], 1348);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 51, 94], 1349);
                step(f, Op::BreakTransform, &[94, 290, 79, 291], 1350);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 51, 292], 1351);
                step(f, Op::KneeVector, &[79, 0, 292, 95, 96, 293], 1352);
                step(f, Op::TwoBoneIK, &[30, 29, 28, 93, 294, 295, 293, 52, 415, 48, 428, 429, 47, 46, 412], 1353);
                step(f, Op::JumpIfFalse, &[3, 1364], 1354)
            }
            1354 => {
                step(f, Op::GetParent, &[28, 29], 1355);
                step(f, Op::GetTransform, &[29, 52, 48, 95], 1356);
                step(f, Op::BreakTransform, &[95, 296, 80, 297], 1357);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 51, 94], 1358);
                step(f, Op::BreakTransform, &[94, 290, 79, 291], 1359);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 51, 292], 1360);
                step(f, Op::KneeVector, &[79, 0, 292, 95, 96, 293], 1361);
                step(f, Op::AddV, &[296, 293, 298], 1362);
                step(f, Op::DrawLine, &[296, 298, 414, 308], 1363);
                step(f, Op::Jump, &[1364], 1364)
            }
            1364 => {
                step(f, Op::Jump, &[1332], 1365)
            }
            1365 => {
                step(f, Op::End, &[], 1366)
            }
            _ => return,
        };
    }
}
