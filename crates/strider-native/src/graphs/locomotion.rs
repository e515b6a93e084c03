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
    fingerprint: 0x37063e18f509e233,
    forward,
};

fn forward(f: &mut Frame<'_>) {
    let mut pc: usize = 377;
    loop {
        // SAFETY: each `step` is an instruction of the program this code was generated
        // from, with its own operands; `NATIVE` runs only on that program (fingerprint).
        pc = unsafe { match pc {
            377 => {
                step(f, Op::Not, &[0, 9], 378);
                step(f, Op::Copy(ValueType::Bool), &[9, 1], 379);
                step(f, Op::WorldTransform, &[12], 380);
                step(f, Op::BreakTransform, &[12, 32, 7, 33], 381);
                step(f, Op::Select(ValueType::Transform), &[0, 0, 12, 13], 382);
                step(f, Op::BreakTransform, &[13, 34, 8, 35], 383);
                step(f, Op::SubV, &[32, 34, 36], 384);
                step(f, Op::LengthV, &[36, 122], 385);
                step(f, Op::GreaterF, &[122, 30, 10], 386);
                step(f, Op::Copy(ValueType::Bool), &[10, 2], 387);
                step(f, Op::MakeRelative, &[13, 12, 17], 388);
                step(f, Op::Select(ValueType::Transform), &[10, 103, 17, 18], 389);
                step(f, Op::Copy(ValueType::Transform), &[18, 2], 390);
                step(f, Op::InverseT, &[13, 15], 391);
                step(f, Op::MulT, &[12, 15, 16], 392);
                step(f, Op::Copy(ValueType::Transform), &[16, 1], 393);
                step(f, Op::TransformVector, &[2, 0, 41], 394);
                step(f, Op::InverseT, &[12, 14], 395);
                step(f, Op::DeltaTime, &[121], 396);
                step(f, Op::DivF, &[570, 121, 123], 397);
                step(f, Op::ScaleV, &[36, 123, 37], 398);
                step(f, Op::TransformVector, &[14, 37, 38], 399);
                step(f, Op::BreakVector, &[38, 124, 125, 126], 400);
                step(f, Op::MakeVector, &[124, 125, 568, 39], 401);
                step(f, Op::LengthV, &[39, 127], 402);
                step(f, Op::MulF, &[127, 106, 128], 403);
                step(f, Op::NegF, &[128, 129], 404);
                step(f, Op::ClampF, &[126, 129, 128, 130], 405);
                step(f, Op::MakeVector, &[124, 125, 130, 40], 406);
                step(f, Op::Select(ValueType::Vec3), &[2, 41, 40, 43], 407);
                step(f, Op::VectorLerp, &[41, 43, 31, 568, 44], 408);
                step(f, Op::Copy(ValueType::Vec3), &[44, 0], 409);
                step(f, Op::TransformVector, &[2, 1, 42], 410);
                step(f, Op::TransformVector, &[2, 0, 41], 411);
                step(f, Op::Select(ValueType::Vec3), &[2, 41, 40, 43], 412);
                step(f, Op::VectorLerp, &[42, 43, 32, 568, 45], 413);
                step(f, Op::Copy(ValueType::Vec3), &[45, 1], 414);
                step(f, Op::LengthV, &[43, 137], 415);
                step(f, Op::Copy(ValueType::Float), &[137, 0], 416);
                step(f, Op::BreakVector, &[36, 131, 132, 133], 417);
                step(f, Op::MulF, &[130, 121, 134], 418);
                step(f, Op::SubF, &[133, 134, 135], 419);
                step(f, Op::Select(ValueType::Float), &[10, 568, 135, 136], 420);
                step(f, Op::Copy(ValueType::Float), &[136, 1], 421);
                step(f, Op::JumpIfFalse, &[2, 436], 422)
            }
            422 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 12], 423);
                step(f, Op::Copy(ValueType::Int), &[65, 17], 424);
                424
            }
            424 => {
                step(f, Op::ForEachNext(Elem::Bone), &[12, 17, 13, 18, 19, 434], 425)
            }
            425 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 18, 20], 426);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 18, 20], 427);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 18, 20], 428);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 18, 20], 429);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 18, 20], 430);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 18, 20], 431);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 18, 20], 432);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 18, 20], 433);
                step(f, Op::Jump, &[424], 434)
            }
            434 => {
                step(f, Op::Copy(ValueType::Float), &[568, 13], 435);
                step(f, Op::Jump, &[436], 436)
            }
            436 => {
                step(f, Op::WorldTransform, &[12], 437);
                step(f, Op::Copy(ValueType::Transform), &[12, 0], 438);
                step(f, Op::Copy(ValueType::Bool), &[74, 0], 439);
                step(f, Op::JumpIfFalse, &[8, 446], 440)
            }
            440 => {
                step(f, Op::GetTransform, &[34, 65, 74, 19], 441);
                step(f, Op::BreakTransform, &[19, 46, 9, 47], 442);
                step(f, Op::ScaleV, &[0, 571, 48], 443);
                step(f, Op::AddV, &[46, 48, 49], 444);
                step(f, Op::DrawArrow, &[46, 49, 569, 342], 445);
                step(f, Op::Jump, &[446], 446)
            }
            446 => {
                step(f, Op::Copy(ValueType::Float), &[568, 138], 447);
                step(f, Op::Copy(ValueType::Float), &[570, 139], 448);
                step(f, Op::Copy(ValueType::Float), &[570, 140], 449);
                step(f, Op::Copy(ValueType::Bool), &[75, 11], 450);
                step(f, Op::Copy(ValueType::Bool), &[75, 12], 451);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 6], 452);
                step(f, Op::Copy(ValueType::Int), &[65, 25], 453);
                step(f, Op::MakeVector, &[568, 568, 48, 54], 454);
                454
            }
            454 => {
                step(f, Op::ForEachNext(Elem::Transform), &[6, 25, 21, 26, 27, 465], 455)
            }
            455 => {
                step(f, Op::BreakTransform, &[21, 50, 10, 51], 456);
                step(f, Op::TransformPoint, &[2, 50, 52], 457);
                step(f, Op::LerpV, &[52, 50, 140, 53], 458);
                step(f, Op::AddV, &[53, 54, 55], 459);
                step(f, Op::SubV, &[53, 54, 56], 460);
                step(f, Op::LineTrace, &[55, 56, 13, 57, 58, 141], 461);
                step(f, Op::JumpIfFalse, &[13, 464], 462)
            }
            462 => {
                step(f, Op::Copy(ValueType::Bool), &[74, 12], 463);
                step(f, Op::Jump, &[464], 464)
            }
            464 => {
                step(f, Op::Jump, &[454], 465)
            }
            465 => {
                step(f, Op::Copy(ValueType::Bool), &[12, 11], 466);
                step(f, Op::Jump, &[467], 467)
            }
            467 => {
                step(f, Op::Or, &[11, 7, 14], 468);
                step(f, Op::NotEquals(Elem::Bool), &[14, 5, 15], 469);
                step(f, Op::JumpIfFalse, &[15, 504], 470)
            }
            470 => {
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 471);
                step(f, Op::JumpIfFalse, &[16, 503], 472)
            }
            472 => {
                step(f, Op::Copy(ValueType::Int), &[1, 24], 473);
                step(f, Op::Copy(ValueType::Int), &[65, 20], 474);
                474
            }
            474 => {
                step(f, Op::ForNext, &[20, 24, 22, 502], 475)
            }
            475 => {
                step(f, Op::AddF, &[138, 139, 142], 476);
                step(f, Op::MulF, &[142, 569, 143], 477);
                step(f, Op::Copy(ValueType::Float), &[143, 144], 478);
                step(f, Op::Copy(ValueType::Bool), &[75, 17], 479);
                step(f, Op::Copy(ValueType::Bool), &[75, 18], 480);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 7], 481);
                step(f, Op::Copy(ValueType::Int), &[65, 28], 482);
                step(f, Op::MakeVector, &[568, 568, 48, 63], 483);
                483
            }
            483 => {
                step(f, Op::ForEachNext(Elem::Transform), &[7, 28, 22, 29, 30, 494], 484)
            }
            484 => {
                step(f, Op::BreakTransform, &[22, 59, 11, 60], 485);
                step(f, Op::TransformPoint, &[2, 59, 61], 486);
                step(f, Op::LerpV, &[61, 59, 144, 62], 487);
                step(f, Op::AddV, &[62, 63, 64], 488);
                step(f, Op::SubV, &[62, 63, 65], 489);
                step(f, Op::LineTrace, &[64, 65, 19, 66, 67, 145], 490);
                step(f, Op::JumpIfFalse, &[19, 493], 491)
            }
            491 => {
                step(f, Op::Copy(ValueType::Bool), &[74, 18], 492);
                step(f, Op::Jump, &[493], 493)
            }
            493 => {
                step(f, Op::Jump, &[483], 494)
            }
            494 => {
                step(f, Op::Copy(ValueType::Bool), &[18, 17], 495);
                step(f, Op::Jump, &[496], 496)
            }
            496 => {
                step(f, Op::Equals(Elem::Bool), &[17, 6, 20], 497);
                step(f, Op::JumpIfFalse, &[20, 500], 498)
            }
            498 => {
                step(f, Op::Copy(ValueType::Float), &[143, 138], 499);
                step(f, Op::Jump, &[501], 500)
            }
            500 => {
                step(f, Op::Copy(ValueType::Float), &[143, 139], 501);
                501
            }
            501 => {
                step(f, Op::Jump, &[474], 502)
            }
            502 => {
                step(f, Op::Jump, &[503], 503)
            }
            503 => {
                step(f, Op::Jump, &[504], 504)
            }
            504 => {
                step(f, Op::Select(ValueType::Float), &[5, 572, 570, 151], 505);
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 506);
                step(f, Op::AddF, &[138, 139, 142], 507);
                step(f, Op::MulF, &[142, 569, 146], 508);
                step(f, Op::Select(ValueType::Float), &[16, 146, 569, 147], 509);
                step(f, Op::Select(ValueType::Float), &[15, 147, 568, 153], 510);
                step(f, Op::MulF, &[151, 153, 155], 511);
                step(f, Op::DeltaTime, &[149], 512);
                step(f, Op::DivF, &[149, 109, 150], 513);
                step(f, Op::MulF, &[155, 150, 156], 514);
                step(f, Op::AddF, &[15, 156, 157], 515);
                step(f, Op::ClampF, &[157, 568, 570, 158], 516);
                step(f, Op::Select(ValueType::Float), &[14, 572, 570, 152], 517);
                step(f, Op::SubF, &[570, 147, 148], 518);
                step(f, Op::Select(ValueType::Float), &[15, 148, 570, 154], 519);
                step(f, Op::MulF, &[152, 154, 159], 520);
                step(f, Op::MulF, &[159, 150, 160], 521);
                step(f, Op::AddF, &[158, 160, 161], 522);
                step(f, Op::ClampF, &[161, 568, 570, 162], 523);
                step(f, Op::MulF, &[162, 162, 163], 524);
                step(f, Op::MulF, &[162, 573, 164], 525);
                step(f, Op::SubF, &[574, 164, 165], 526);
                step(f, Op::MulF, &[163, 165, 166], 527);
                step(f, Op::AddF, &[16, 166, 167], 528);
                step(f, Op::MulF, &[167, 569, 168], 529);
                step(f, Op::SubF, &[570, 168, 169], 530);
                step(f, Op::MulF, &[169, 169, 170], 531);
                step(f, Op::SubF, &[570, 170, 171], 532);
                step(f, Op::Copy(ValueType::Float), &[171, 17], 533);
                step(f, Op::Copy(ValueType::Float), &[166, 16], 534);
                step(f, Op::Copy(ValueType::Float), &[162, 15], 535);
                step(f, Op::GreaterF, &[16, 568, 21], 536);
                step(f, Op::TransformVector, &[2, 3, 68], 537);
                step(f, Op::Select(ValueType::Vec3), &[21, 68, 0, 69], 538);
                step(f, Op::Copy(ValueType::Vec3), &[69, 3], 539);
                step(f, Op::LerpV, &[0, 3, 16, 70], 540);
                step(f, Op::Select(ValueType::Vec3), &[21, 70, 0, 71], 541);
                step(f, Op::Copy(ValueType::Vec3), &[71, 2], 542);
                step(f, Op::Copy(ValueType::Bool), &[14, 5], 543);
                step(f, Op::Copy(ValueType::Bool), &[11, 6], 544);
                step(f, Op::Copy(ValueType::Bool), &[75, 7], 545);
                step(f, Op::SubF, &[570, 17, 172], 546);
                step(f, Op::MulF, &[1, 172, 173], 547);
                step(f, Op::AddF, &[2, 173, 174], 548);
                step(f, Op::SpringF, &[174, 107, 177, 31, 175, 176], 549);
                step(f, Op::SubF, &[174, 177, 178], 550);
                step(f, Op::Copy(ValueType::Float), &[178, 3], 551);
                step(f, Op::Copy(ValueType::Float), &[174, 2], 552);
                step(f, Op::Copy(ValueType::Bool), &[75, 23], 553);
                step(f, Op::Copy(ValueType::Bool), &[74, 24], 554);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 555);
                step(f, Op::Copy(ValueType::Int), &[65, 35], 556);
                556
            }
            556 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 35, 25, 36, 37, 562], 557)
            }
            557 => {
                step(f, Op::Not, &[25, 26], 558);
                step(f, Op::JumpIfFalse, &[26, 561], 559)
            }
            559 => {
                step(f, Op::Copy(ValueType::Bool), &[75, 24], 560);
                step(f, Op::Jump, &[561], 561)
            }
            561 => {
                step(f, Op::Jump, &[556], 562)
            }
            562 => {
                step(f, Op::Copy(ValueType::Bool), &[24, 23], 563);
                step(f, Op::Jump, &[564], 564)
            }
            564 => {
                step(f, Op::Copy(ValueType::Bool), &[75, 27], 565);
                step(f, Op::Copy(ValueType::Bool), &[74, 28], 566);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 567);
                step(f, Op::Copy(ValueType::Int), &[65, 38], 568);
                568
            }
            568 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 38, 15, 39, 40, 583], 569)
            }
            569 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 39, 23], 570);
                step(f, Op::BreakTransform, &[23, 72, 12, 73], 571);
                step(f, Op::BreakVector, &[72, 187, 188, 189], 572);
                step(f, Op::MakeVector, &[187, 188, 568, 76], 573);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 39, 24], 574);
                step(f, Op::BreakTransform, &[24, 74, 13, 75], 575);
                step(f, Op::BreakVector, &[74, 190, 191, 192], 576);
                step(f, Op::MakeVector, &[190, 191, 568, 77], 577);
                step(f, Op::DistanceV, &[76, 77, 193], 578);
                step(f, Op::GreaterF, &[193, 26, 29], 579);
                step(f, Op::JumpIfFalse, &[29, 582], 580)
            }
            580 => {
                step(f, Op::Copy(ValueType::Bool), &[75, 28], 581);
                step(f, Op::Jump, &[582], 582)
            }
            582 => {
                step(f, Op::Jump, &[568], 583)
            }
            583 => {
                step(f, Op::Copy(ValueType::Bool), &[28, 27], 584);
                step(f, Op::Jump, &[585], 585)
            }
            585 => {
                step(f, Op::And, &[23, 27, 30], 586);
                step(f, Op::LengthV, &[2, 179], 587);
                step(f, Op::GreaterF, &[179, 24, 22], 588);
                step(f, Op::GreaterF, &[0, 24, 31], 589);
                step(f, Op::Or, &[22, 31, 32], 590);
                step(f, Op::Not, &[32, 33], 591);
                step(f, Op::And, &[30, 33, 38], 592);
                step(f, Op::DeltaTime, &[216], 593);
                step(f, Op::MulF, &[216, 29, 217], 594);
                step(f, Op::AddF, &[9, 217, 218], 595);
                step(f, Op::GreaterF, &[9, 569, 39], 596);
                step(f, Op::AddF, &[28, 569, 214], 597);
                step(f, Op::Select(ValueType::Float), &[39, 214, 28, 215], 598);
                step(f, Op::MinF, &[218, 215, 219], 599);
                step(f, Op::NotEquals(Elem::Bool), &[33, 4, 34], 600);
                step(f, Op::Not, &[30, 35], 601);
                step(f, Op::And, &[34, 35, 36], 602);
                step(f, Op::SubF, &[10, 24, 200], 603);
                step(f, Op::SubF, &[10, 179, 201], 604);
                step(f, Op::DivF, &[200, 201, 202], 605);
                step(f, Op::ClampF, &[202, 568, 570, 203], 606);
                step(f, Op::MulF, &[6, 203, 205], 607);
                step(f, Op::RemapF, &[179, 24, 25, 568, 570, 74, 194], 608);
                step(f, Op::Select(ValueType::Float), &[33, 27, 570, 195], 609);
                step(f, Op::Select(ValueType::Float), &[30, 194, 195, 196], 610);
                step(f, Op::SubF, &[570, 16, 197], 611);
                step(f, Op::MulF, &[196, 197, 198], 612);
                step(f, Op::LerpF, &[18, 39, 12, 182], 613);
                step(f, Op::RemapF, &[179, 21, 22, 19, 20, 74, 180], 614);
                step(f, Op::LerpF, &[180, 38, 12, 181], 615);
                step(f, Op::MaxF, &[179, 23, 183], 616);
                step(f, Op::DivF, &[181, 183, 184], 617);
                step(f, Op::AddF, &[182, 184, 185], 618);
                step(f, Op::DivF, &[198, 185, 199], 619);
                step(f, Op::SubF, &[570, 203, 204], 620);
                step(f, Op::MulF, &[199, 204, 206], 621);
                step(f, Op::AddF, &[205, 206, 207], 622);
                step(f, Op::MulF, &[207, 573, 208], 623);
                step(f, Op::AddF, &[6, 199, 209], 624);
                step(f, Op::Select(ValueType::Float), &[36, 208, 209, 210], 625);
                step(f, Op::DivF, &[573, 210, 211], 626);
                step(f, Op::GreaterF, &[210, 568, 37], 627);
                step(f, Op::CycleStep, &[9, 211, 568, 37, 212, 213], 628);
                step(f, Op::Select(ValueType::Float), &[38, 219, 212, 220], 629);
                step(f, Op::Copy(ValueType::Float), &[220, 9], 630);
                step(f, Op::Copy(ValueType::Float), &[199, 6], 631);
                step(f, Op::Copy(ValueType::Bool), &[22, 3], 632);
                step(f, Op::Copy(ValueType::Float), &[184, 4], 633);
                step(f, Op::Copy(ValueType::Float), &[185, 5], 634);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 635);
                step(f, Op::Copy(ValueType::Int), &[65, 32], 636);
                636
            }
            636 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 32, 14, 33, 34, 739], 637)
            }
            637 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 33, 234], 638);
                step(f, Op::ToFloat, &[33, 221], 639);
                step(f, Op::MulF, &[221, 569, 222], 640);
                step(f, Op::AddF, &[9, 222, 223], 641);
                step(f, Op::FractF, &[223, 224], 642);
                step(f, Op::SubF, &[234, 224, 236], 643);
                step(f, Op::GreaterF, &[236, 569, 40], 644);
                step(f, Op::SubF, &[570, 234, 248], 645);
                step(f, Op::AddF, &[224, 248, 249], 646);
                step(f, Op::DivF, &[224, 249, 250], 647);
                step(f, Op::LengthV, &[2, 179], 648);
                step(f, Op::GreaterF, &[179, 24, 22], 649);
                step(f, Op::GreaterF, &[0, 24, 31], 650);
                step(f, Op::Or, &[22, 31, 32], 651);
                step(f, Op::Not, &[32, 33], 652);
                step(f, Op::NotEquals(Elem::Bool), &[33, 4, 34], 653);
                step(f, Op::Copy(ValueType::Bool), &[75, 23], 654);
                step(f, Op::Copy(ValueType::Bool), &[74, 24], 655);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 656);
                step(f, Op::Copy(ValueType::Int), &[65, 35], 657);
                657
            }
            657 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 35, 25, 36, 37, 663], 658)
            }
            658 => {
                step(f, Op::Not, &[25, 26], 659);
                step(f, Op::JumpIfFalse, &[26, 662], 660)
            }
            660 => {
                step(f, Op::Copy(ValueType::Bool), &[75, 24], 661);
                step(f, Op::Jump, &[662], 662)
            }
            662 => {
                step(f, Op::Jump, &[657], 663)
            }
            663 => {
                step(f, Op::Copy(ValueType::Bool), &[24, 23], 664);
                step(f, Op::Jump, &[665], 665)
            }
            665 => {
                step(f, Op::Copy(ValueType::Bool), &[75, 27], 666);
                step(f, Op::Copy(ValueType::Bool), &[74, 28], 667);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 668);
                step(f, Op::Copy(ValueType::Int), &[65, 38], 669);
                669
            }
            669 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 38, 15, 39, 40, 684], 670)
            }
            670 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 39, 23], 671);
                step(f, Op::BreakTransform, &[23, 72, 12, 73], 672);
                step(f, Op::BreakVector, &[72, 187, 188, 189], 673);
                step(f, Op::MakeVector, &[187, 188, 568, 76], 674);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 39, 24], 675);
                step(f, Op::BreakTransform, &[24, 74, 13, 75], 676);
                step(f, Op::BreakVector, &[74, 190, 191, 192], 677);
                step(f, Op::MakeVector, &[190, 191, 568, 77], 678);
                step(f, Op::DistanceV, &[76, 77, 193], 679);
                step(f, Op::GreaterF, &[193, 26, 29], 680);
                step(f, Op::JumpIfFalse, &[29, 683], 681)
            }
            681 => {
                step(f, Op::Copy(ValueType::Bool), &[75, 28], 682);
                step(f, Op::Jump, &[683], 683)
            }
            683 => {
                step(f, Op::Jump, &[669], 684)
            }
            684 => {
                step(f, Op::Copy(ValueType::Bool), &[28, 27], 685);
                step(f, Op::Jump, &[686], 686)
            }
            686 => {
                step(f, Op::And, &[23, 27, 30], 687);
                step(f, Op::Not, &[30, 35], 688);
                step(f, Op::And, &[34, 35, 36], 689);
                step(f, Op::SubF, &[10, 24, 200], 690);
                step(f, Op::SubF, &[10, 179, 201], 691);
                step(f, Op::DivF, &[200, 201, 202], 692);
                step(f, Op::ClampF, &[202, 568, 570, 203], 693);
                step(f, Op::MulF, &[8, 203, 226], 694);
                step(f, Op::RemapF, &[179, 24, 25, 568, 570, 74, 194], 695);
                step(f, Op::Select(ValueType::Float), &[33, 27, 570, 195], 696);
                step(f, Op::Select(ValueType::Float), &[30, 194, 195, 196], 697);
                step(f, Op::SubF, &[570, 16, 197], 698);
                step(f, Op::MulF, &[196, 197, 198], 699);
                step(f, Op::LerpF, &[18, 39, 12, 182], 700);
                step(f, Op::DivF, &[198, 182, 225], 701);
                step(f, Op::SubF, &[570, 203, 204], 702);
                step(f, Op::MulF, &[225, 204, 227], 703);
                step(f, Op::AddF, &[226, 227, 228], 704);
                step(f, Op::MulF, &[228, 573, 229], 705);
                step(f, Op::AddF, &[8, 225, 230], 706);
                step(f, Op::Select(ValueType::Float), &[36, 229, 230, 231], 707);
                step(f, Op::DeltaTime, &[216], 708);
                step(f, Op::MulF, &[216, 569, 232], 709);
                step(f, Op::MulF, &[231, 232, 233], 710);
                step(f, Op::MulF, &[250, 233, 251], 711);
                step(f, Op::ArrayAt(Elem::Float), &[2, 33, 235], 712);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 33, 41], 713);
                step(f, Op::RemapF, &[179, 21, 22, 19, 20, 74, 180], 714);
                step(f, Op::LerpF, &[180, 38, 12, 181], 715);
                step(f, Op::MaxF, &[179, 23, 183], 716);
                step(f, Op::DivF, &[181, 183, 184], 717);
                step(f, Op::AddF, &[182, 184, 185], 718);
                step(f, Op::DivF, &[182, 185, 186], 719);
                step(f, Op::SubF, &[186, 7, 237], 720);
                step(f, Op::MaxF, &[237, 568, 238], 721);
                step(f, Op::DivF, &[238, 186, 239], 722);
                step(f, Op::MulF, &[239, 235, 240], 723);
                step(f, Op::SubF, &[570, 12, 241], 724);
                step(f, Op::MulF, &[240, 241, 242], 725);
                step(f, Op::MulF, &[242, 197, 243], 726);
                step(f, Op::MulF, &[243, 104, 244], 727);
                step(f, Op::Select(ValueType::Float), &[41, 568, 244, 245], 728);
                step(f, Op::SubF, &[233, 245, 246], 729);
                step(f, Op::AddF, &[235, 246, 247], 730);
                step(f, Op::Select(ValueType::Float), &[40, 251, 247, 252], 731);
                step(f, Op::MinF, &[252, 573, 253], 732);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 33, 253], 733);
                step(f, Op::ToFloat, &[33, 221], 734);
                step(f, Op::MulF, &[221, 569, 222], 735);
                step(f, Op::AddF, &[9, 222, 223], 736);
                step(f, Op::FractF, &[223, 224], 737);
                step(f, Op::ArraySetAt(Elem::Float), &[0, 33, 224], 738);
                step(f, Op::Jump, &[636], 739)
            }
            739 => {
                step(f, Op::LerpF, &[18, 39, 12, 182], 740);
                step(f, Op::LengthV, &[2, 179], 741);
                step(f, Op::RemapF, &[179, 21, 22, 19, 20, 74, 180], 742);
                step(f, Op::LerpF, &[180, 38, 12, 181], 743);
                step(f, Op::MaxF, &[179, 23, 183], 744);
                step(f, Op::DivF, &[181, 183, 184], 745);
                step(f, Op::AddF, &[182, 184, 185], 746);
                step(f, Op::DivF, &[182, 185, 186], 747);
                step(f, Op::Copy(ValueType::Float), &[186, 7], 748);
                step(f, Op::GreaterF, &[179, 24, 22], 749);
                step(f, Op::GreaterF, &[0, 24, 31], 750);
                step(f, Op::Or, &[22, 31, 32], 751);
                step(f, Op::Not, &[32, 33], 752);
                step(f, Op::Copy(ValueType::Bool), &[33, 4], 753);
                step(f, Op::Copy(ValueType::Float), &[179, 10], 754);
                step(f, Op::Copy(ValueType::Bool), &[75, 23], 755);
                step(f, Op::Copy(ValueType::Bool), &[74, 24], 756);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 757);
                step(f, Op::Copy(ValueType::Int), &[65, 35], 758);
                758
            }
            758 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 35, 25, 36, 37, 764], 759)
            }
            759 => {
                step(f, Op::Not, &[25, 26], 760);
                step(f, Op::JumpIfFalse, &[26, 763], 761)
            }
            761 => {
                step(f, Op::Copy(ValueType::Bool), &[75, 24], 762);
                step(f, Op::Jump, &[763], 763)
            }
            763 => {
                step(f, Op::Jump, &[758], 764)
            }
            764 => {
                step(f, Op::Copy(ValueType::Bool), &[24, 23], 765);
                step(f, Op::Jump, &[766], 766)
            }
            766 => {
                step(f, Op::Copy(ValueType::Bool), &[75, 27], 767);
                step(f, Op::Copy(ValueType::Bool), &[74, 28], 768);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 769);
                step(f, Op::Copy(ValueType::Int), &[65, 38], 770);
                770
            }
            770 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 38, 15, 39, 40, 785], 771)
            }
            771 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 39, 23], 772);
                step(f, Op::BreakTransform, &[23, 72, 12, 73], 773);
                step(f, Op::BreakVector, &[72, 187, 188, 189], 774);
                step(f, Op::MakeVector, &[187, 188, 568, 76], 775);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 39, 24], 776);
                step(f, Op::BreakTransform, &[24, 74, 13, 75], 777);
                step(f, Op::BreakVector, &[74, 190, 191, 192], 778);
                step(f, Op::MakeVector, &[190, 191, 568, 77], 779);
                step(f, Op::DistanceV, &[76, 77, 193], 780);
                step(f, Op::GreaterF, &[193, 26, 29], 781);
                step(f, Op::JumpIfFalse, &[29, 784], 782)
            }
            782 => {
                step(f, Op::Copy(ValueType::Bool), &[75, 28], 783);
                step(f, Op::Jump, &[784], 784)
            }
            784 => {
                step(f, Op::Jump, &[770], 785)
            }
            785 => {
                step(f, Op::Copy(ValueType::Bool), &[28, 27], 786);
                step(f, Op::Jump, &[787], 787)
            }
            787 => {
                step(f, Op::And, &[23, 27, 30], 788);
                step(f, Op::RemapF, &[179, 24, 25, 568, 570, 74, 194], 789);
                step(f, Op::Select(ValueType::Float), &[33, 27, 570, 195], 790);
                step(f, Op::Select(ValueType::Float), &[30, 194, 195, 196], 791);
                step(f, Op::SubF, &[570, 16, 197], 792);
                step(f, Op::MulF, &[196, 197, 198], 793);
                step(f, Op::DivF, &[198, 182, 225], 794);
                step(f, Op::Copy(ValueType::Float), &[225, 8], 795);
                step(f, Op::Select(ValueType::Vec3), &[3, 2, 340, 78], 796);
                step(f, Op::MovementAngleOffset, &[78, 11, 9, 33, 34, 575, 35, 576, 254], 797);
                step(f, Op::Copy(ValueType::Float), &[254, 11], 798);
                step(f, Op::QuatFromAxisAngle, &[343, 11, 14], 799);
                step(f, Op::Copy(ValueType::Quat), &[14, 0], 800);
                step(f, Op::SinF, &[11, 255], 801);
                step(f, Op::AbsF, &[255, 256], 802);
                step(f, Op::RemapF, &[256, 36, 37, 568, 570, 74, 257], 803);
                step(f, Op::Copy(ValueType::Float), &[257, 12], 804);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 805);
                step(f, Op::Copy(ValueType::Int), &[65, 2], 806);
                806
            }
            806 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 2, 0, 3, 4, 1427], 807)
            }
            807 => {
                step(f, Op::Copy(ValueType::Bone), &[0, 16], 808);
                step(f, Op::Copy(ValueType::Int), &[3, 41], 809);
                step(f, Op::GetTransform, &[35, 65, 74, 25], 810);
                step(f, Op::BreakTransform, &[25, 81, 15, 82], 811);
                step(f, Op::BreakVector, &[81, 269, 270, 271], 812);
                step(f, Op::SubF, &[570, 12, 267], 813);
                step(f, Op::MulF, &[11, 267, 268], 814);
                step(f, Op::QuatFromAxisAngle, &[343, 268, 17], 815);
                step(f, Op::GetTransform, &[16, 65, 74, 26], 816);
                step(f, Op::BreakTransform, &[26, 83, 16, 84], 817);
                step(f, Op::SubV, &[83, 81, 85], 818);
                step(f, Op::BreakVector, &[85, 264, 265, 266], 819);
                step(f, Op::MakeVector, &[264, 265, 568, 86], 820);
                step(f, Op::RotateVector, &[17, 86, 87], 821);
                step(f, Op::BreakVector, &[87, 272, 273, 274], 822);
                step(f, Op::MulF, &[40, 12, 275], 823);
                step(f, Op::Equals(Elem::Int), &[41, 65, 42], 824);
                step(f, Op::Select(ValueType::Float), &[42, 570, 572, 284], 825);
                step(f, Op::MulF, &[275, 284, 276], 826);
                step(f, Op::AddF, &[272, 276, 277], 827);
                step(f, Op::AddF, &[269, 277, 278], 828);
                step(f, Op::AddF, &[270, 273, 279], 829);
                step(f, Op::BreakVector, &[83, 280, 281, 282], 830);
                step(f, Op::SubF, &[282, 43, 283], 831);
                step(f, Op::MakeVector, &[278, 279, 283, 88], 832);
                step(f, Op::ArrayAt(Elem::Float), &[2, 41, 258], 833);
                step(f, Op::SubF, &[570, 258, 259], 834);
                step(f, Op::MaxF, &[259, 568, 260], 835);
                step(f, Op::MulF, &[7, 5, 261], 836);
                step(f, Op::MulF, &[260, 261, 262], 837);
                step(f, Op::ScaleV, &[2, 262, 79], 838);
                step(f, Op::AddV, &[88, 79, 89], 839);
                step(f, Op::MulF, &[4, 569, 263], 840);
                step(f, Op::ScaleV, &[2, 263, 80], 841);
                step(f, Op::AddV, &[89, 80, 90], 842);
                step(f, Op::RotateVector, &[0, 344, 91], 843);
                step(f, Op::Copy(ValueType::Vec3), &[90, 98], 844);
                step(f, Op::Copy(ValueType::Vec3), &[91, 99], 845);
                step(f, Op::Copy(ValueType::Float), &[284, 294], 846);
                step(f, Op::Copy(ValueType::Vec3), &[340, 100], 847);
                step(f, Op::Copy(ValueType::Vec3), &[340, 101], 848);
                step(f, Op::Copy(ValueType::Bool), &[75, 43], 849);
                step(f, Op::Copy(ValueType::Float), &[577, 295], 850);
                step(f, Op::Copy(ValueType::Vec3), &[340, 102], 851);
                step(f, Op::Copy(ValueType::Vec3), &[343, 103], 852);
                step(f, Op::Copy(ValueType::Bool), &[75, 44], 853);
                step(f, Op::MulI, &[0, 0, 47], 854);
                step(f, Op::Copy(ValueType::Int), &[47, 46], 855);
                step(f, Op::Copy(ValueType::Int), &[65, 42], 856);
                step(f, Op::SubI, &[0, 66, 50], 857);
                step(f, Op::DivI, &[50, 67, 51], 858);
                step(f, Op::MakeVector, &[568, 568, 48, 108], 859);
                step(f, Op::ScaleV, &[99, 50, 113], 860);
                860
            }
            860 => {
                step(f, Op::ForNext, &[42, 46, 44, 900], 861)
            }
            861 => {
                step(f, Op::ModI, &[44, 0, 48], 862);
                step(f, Op::ToFloat, &[48, 296], 863);
                step(f, Op::MulF, &[296, 49, 298], 864);
                step(f, Op::MulF, &[298, 294, 299], 865);
                step(f, Op::MakeVector, &[299, 568, 568, 104], 866);
                step(f, Op::DivI, &[44, 0, 49], 867);
                step(f, Op::SubI, &[49, 51, 52], 868);
                step(f, Op::ToFloat, &[52, 297], 869);
                step(f, Op::MulF, &[297, 49, 300], 870);
                step(f, Op::ScaleV, &[99, 300, 105], 871);
                step(f, Op::AddV, &[104, 105, 106], 872);
                step(f, Op::AddV, &[98, 106, 107], 873);
                step(f, Op::AddV, &[107, 108, 109], 874);
                step(f, Op::SubV, &[107, 108, 110], 875);
                step(f, Op::SphereTrace, &[109, 110, 47, 45, 111, 112, 301], 876);
                step(f, Op::BreakVector, &[111, 303, 304, 305], 877);
                step(f, Op::AddV, &[109, 113, 114], 878);
                step(f, Op::AddV, &[110, 113, 115], 879);
                step(f, Op::SphereTrace, &[114, 115, 47, 46, 116, 117, 302], 880);
                step(f, Op::BreakVector, &[116, 306, 307, 308], 881);
                step(f, Op::SubF, &[305, 308, 309], 882);
                step(f, Op::AbsF, &[309, 310], 883);
                step(f, Op::Select(ValueType::Float), &[45, 568, 570, 311], 884);
                step(f, Op::AddF, &[310, 311, 316], 885);
                step(f, Op::LengthV, &[106, 312], 886);
                step(f, Op::RemapF, &[312, 568, 578, 568, 570, 74, 313], 887);
                step(f, Op::MinF, &[305, 308, 314], 888);
                step(f, Op::RemapF, &[314, 579, 578, 570, 569, 74, 315], 889);
                step(f, Op::AddF, &[313, 315, 317], 890);
                step(f, Op::AddF, &[316, 317, 318], 891);
                step(f, Op::LessF, &[318, 295, 47], 892);
                step(f, Op::And, &[45, 47, 48], 893);
                step(f, Op::JumpIfFalse, &[48, 899], 894)
            }
            894 => {
                step(f, Op::Copy(ValueType::Float), &[318, 295], 895);
                step(f, Op::Copy(ValueType::Vec3), &[111, 102], 896);
                step(f, Op::Copy(ValueType::Vec3), &[112, 103], 897);
                step(f, Op::Copy(ValueType::Bool), &[74, 44], 898);
                step(f, Op::Jump, &[899], 899)
            }
            899 => {
                step(f, Op::Jump, &[860], 900)
            }
            900 => {
                step(f, Op::JumpIfFalse, &[8, 903], 901)
            }
            901 => {
                step(f, Op::DrawSphere, &[102, 47, 344], 902);
                step(f, Op::Jump, &[903], 903)
            }
            903 => {
                step(f, Op::Copy(ValueType::Vec3), &[102, 100], 904);
                step(f, Op::Copy(ValueType::Vec3), &[103, 101], 905);
                step(f, Op::Copy(ValueType::Bool), &[44, 43], 906);
                step(f, Op::Jump, &[907], 907)
            }
            907 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 41, 27], 908);
                step(f, Op::BreakTransform, &[27, 93, 21, 94], 909);
                step(f, Op::ArrayAt(Elem::Float), &[2, 41, 258], 910);
                step(f, Op::SubF, &[570, 258, 259], 911);
                step(f, Op::MaxF, &[259, 568, 260], 912);
                step(f, Op::MulF, &[7, 5, 261], 913);
                step(f, Op::MulF, &[260, 261, 262], 914);
                step(f, Op::ScaleV, &[2, 262, 79], 915);
                step(f, Op::SubV, &[100, 79, 92], 916);
                step(f, Op::Select(ValueType::Vec3), &[43, 92, 93, 95], 917);
                step(f, Op::VectorLerp, &[93, 95, 41, 568, 96], 918);
                step(f, Op::BreakVector, &[96, 290, 291, 292], 919);
                step(f, Op::ClampF, &[292, 51, 52, 293], 920);
                step(f, Op::MakeVector, &[290, 291, 293, 97], 921);
                step(f, Op::RotationFromNormal, &[101, 288, 289, 19], 922);
                step(f, Op::PerFootRotationFactor, &[11, 82, 83, 285], 923);
                step(f, Op::MulF, &[11, 285, 286], 924);
                step(f, Op::SubF, &[570, 12, 267], 925);
                step(f, Op::MulF, &[286, 267, 287], 926);
                step(f, Op::QuatFromAxisAngle, &[343, 287, 18], 927);
                step(f, Op::MulQ, &[19, 18, 20], 928);
                step(f, Op::Select(ValueType::Quat), &[43, 20, 21, 22], 929);
                step(f, Op::MakeTransform, &[97, 22, 341, 28], 930);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 41, 28], 931);
                step(f, Op::JumpIfFalse, &[43, 934], 932)
            }
            932 => {
                step(f, Op::Copy(ValueType::Bool), &[74, 7], 933);
                step(f, Op::Jump, &[934], 934)
            }
            934 => {
                step(f, Op::Copy(ValueType::Int), &[3, 53], 935);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 53, 31], 936);
                step(f, Op::GreaterF, &[16, 568, 52], 937);
                step(f, Op::InterpolateTransform, &[2, 103, 17, 29], 938);
                step(f, Op::Select(ValueType::Transform), &[52, 29, 2, 30], 939);
                step(f, Op::MakeAbsolute, &[31, 30, 32], 940);
                step(f, Op::BreakTransform, &[32, 118, 23, 119], 941);
                step(f, Op::ClampSpatially, &[118, 340, 568, 55, 120], 942);
                step(f, Op::SubF, &[570, 12, 324], 943);
                step(f, Op::MulF, &[11, 324, 320], 944);
                step(f, Op::LimitRotationAroundZ, &[23, 320, 81, 24], 945);
                step(f, Op::MakeTransform, &[120, 24, 341, 33], 946);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 53, 33], 947);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 53, 49], 948);
                step(f, Op::JumpIfFalse, &[49, 1002], 949)
            }
            949 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 53, 35], 950);
                step(f, Op::BreakTransform, &[35, 121, 25, 122], 951);
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 319], 952);
                step(f, Op::SubF, &[570, 319, 321], 953);
                step(f, Op::MulF, &[7, 5, 322], 954);
                step(f, Op::MulF, &[321, 322, 323], 955);
                step(f, Op::ScaleV, &[2, 323, 123], 956);
                step(f, Op::AddV, &[121, 123, 124], 957);
                step(f, Op::MakeTransform, &[124, 25, 341, 42], 958);
                step(f, Op::Copy(ValueType::Transform), &[42, 43], 959);
                step(f, Op::Copy(ValueType::Transform), &[103, 44], 960);
                step(f, Op::BreakTransform, &[43, 152, 30, 153], 961);
                step(f, Op::MakeVector, &[568, 568, 48, 154], 962);
                step(f, Op::AddV, &[152, 154, 155], 963);
                step(f, Op::SubV, &[152, 154, 156], 964);
                step(f, Op::LineTrace, &[155, 156, 56, 157, 158, 351], 965);
                step(f, Op::RotateVector, &[30, 343, 159], 966);
                step(f, Op::FindQuatBetween, &[159, 158, 31], 967);
                step(f, Op::MulQ, &[31, 30, 32], 968);
                step(f, Op::MulF, &[46, 45, 352], 969);
                step(f, Op::AddF, &[352, 54, 353], 970);
                step(f, Op::NegF, &[353, 354], 971);
                step(f, Op::MakeVector, &[568, 354, 568, 160], 972);
                step(f, Op::RotateVector, &[32, 160, 162], 973);
                step(f, Op::AddV, &[157, 162, 164], 974);
                step(f, Op::AddV, &[164, 154, 166], 975);
                step(f, Op::SubV, &[164, 154, 167], 976);
                step(f, Op::LineTrace, &[166, 167, 57, 170, 171, 356], 977);
                step(f, Op::BreakVector, &[170, 358, 359, 360], 978);
                step(f, Op::BreakVector, &[164, 364, 365, 366], 979);
                step(f, Op::SubF, &[360, 366, 370], 980);
                step(f, Op::Select(ValueType::Float), &[57, 370, 568, 372], 981);
                step(f, Op::AddF, &[50, 54, 355], 982);
                step(f, Op::MakeVector, &[568, 355, 568, 161], 983);
                step(f, Op::RotateVector, &[32, 161, 163], 984);
                step(f, Op::AddV, &[157, 163, 165], 985);
                step(f, Op::AddV, &[165, 154, 168], 986);
                step(f, Op::SubV, &[165, 154, 169], 987);
                step(f, Op::LineTrace, &[168, 169, 58, 172, 173, 357], 988);
                step(f, Op::BreakVector, &[172, 361, 362, 363], 989);
                step(f, Op::BreakVector, &[165, 367, 368, 369], 990);
                step(f, Op::SubF, &[363, 369, 371], 991);
                step(f, Op::Select(ValueType::Float), &[58, 371, 568, 373], 992);
                step(f, Op::MaxF, &[372, 373, 374], 993);
                step(f, Op::ClampF, &[374, 568, 53, 375], 994);
                step(f, Op::MakeVector, &[568, 568, 375, 174], 995);
                step(f, Op::AddV, &[157, 174, 175], 996);
                step(f, Op::MakeTransform, &[175, 32, 341, 45], 997);
                step(f, Op::Select(ValueType::Transform), &[56, 45, 43, 46], 998);
                step(f, Op::Copy(ValueType::Transform), &[46, 44], 999);
                step(f, Op::Jump, &[1000], 1000)
            }
            1000 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 53, 44], 1001);
                step(f, Op::Jump, &[1064], 1002)
            }
            1002 => {
                step(f, Op::ArrayAt(Elem::Transform), &[2, 53, 47], 1003);
                step(f, Op::GreaterF, &[16, 568, 52], 1004);
                step(f, Op::InterpolateTransform, &[2, 103, 17, 29], 1005);
                step(f, Op::Select(ValueType::Transform), &[52, 29, 2, 30], 1006);
                step(f, Op::MakeAbsolute, &[47, 30, 48], 1007);
                step(f, Op::BreakTransform, &[48, 176, 33, 177], 1008);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 53, 35], 1009);
                step(f, Op::BreakTransform, &[35, 121, 25, 122], 1010);
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 319], 1011);
                step(f, Op::SubF, &[570, 319, 321], 1012);
                step(f, Op::MulF, &[7, 5, 322], 1013);
                step(f, Op::MulF, &[321, 322, 323], 1014);
                step(f, Op::ScaleV, &[2, 323, 123], 1015);
                step(f, Op::AddV, &[121, 123, 124], 1016);
                step(f, Op::ClampF, &[319, 568, 570, 403], 1017);
                step(f, Op::SubF, &[570, 403, 376], 1018);
                step(f, Op::MulF, &[69, 376, 377], 1019);
                step(f, Op::VectorLerp, &[176, 124, 377, 568, 178], 1020);
                step(f, Op::MakeTransform, &[178, 25, 341, 49], 1021);
                step(f, Op::Copy(ValueType::Transform), &[49, 50], 1022);
                step(f, Op::Copy(ValueType::Transform), &[103, 51], 1023);
                step(f, Op::BreakTransform, &[50, 179, 34, 180], 1024);
                step(f, Op::MakeVector, &[568, 568, 48, 181], 1025);
                step(f, Op::AddV, &[179, 181, 182], 1026);
                step(f, Op::SubV, &[179, 181, 183], 1027);
                step(f, Op::LineTrace, &[182, 183, 59, 184, 185, 378], 1028);
                step(f, Op::RotateVector, &[34, 343, 186], 1029);
                step(f, Op::FindQuatBetween, &[186, 185, 35], 1030);
                step(f, Op::MulQ, &[35, 34, 36], 1031);
                step(f, Op::MulF, &[46, 45, 379], 1032);
                step(f, Op::AddF, &[379, 54, 380], 1033);
                step(f, Op::NegF, &[380, 381], 1034);
                step(f, Op::MakeVector, &[568, 381, 568, 187], 1035);
                step(f, Op::RotateVector, &[36, 187, 189], 1036);
                step(f, Op::AddV, &[184, 189, 191], 1037);
                step(f, Op::AddV, &[191, 181, 193], 1038);
                step(f, Op::SubV, &[191, 181, 194], 1039);
                step(f, Op::LineTrace, &[193, 194, 60, 197, 198, 383], 1040);
                step(f, Op::BreakVector, &[197, 385, 386, 387], 1041);
                step(f, Op::BreakVector, &[191, 391, 392, 393], 1042);
                step(f, Op::SubF, &[387, 393, 397], 1043);
                step(f, Op::Select(ValueType::Float), &[60, 397, 568, 399], 1044);
                step(f, Op::AddF, &[50, 54, 382], 1045);
                step(f, Op::MakeVector, &[568, 382, 568, 188], 1046);
                step(f, Op::RotateVector, &[36, 188, 190], 1047);
                step(f, Op::AddV, &[184, 190, 192], 1048);
                step(f, Op::AddV, &[192, 181, 195], 1049);
                step(f, Op::SubV, &[192, 181, 196], 1050);
                step(f, Op::LineTrace, &[195, 196, 61, 199, 200, 384], 1051);
                step(f, Op::BreakVector, &[199, 388, 389, 390], 1052);
                step(f, Op::BreakVector, &[192, 394, 395, 396], 1053);
                step(f, Op::SubF, &[390, 396, 398], 1054);
                step(f, Op::Select(ValueType::Float), &[61, 398, 568, 400], 1055);
                step(f, Op::MaxF, &[399, 400, 401], 1056);
                step(f, Op::ClampF, &[401, 568, 53, 402], 1057);
                step(f, Op::MakeVector, &[568, 568, 402, 201], 1058);
                step(f, Op::AddV, &[184, 201, 202], 1059);
                step(f, Op::MakeTransform, &[202, 36, 341, 52], 1060);
                step(f, Op::Select(ValueType::Transform), &[59, 52, 50, 53], 1061);
                step(f, Op::Copy(ValueType::Transform), &[53, 51], 1062);
                step(f, Op::Jump, &[1063], 1063)
            }
            1063 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 53, 51], 1064);
                1064
            }
            1064 => {
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 319], 1065);
                step(f, Op::GreaterEqualF, &[319, 570, 50], 1066);
                step(f, Op::JumpIfFalse, &[50, 1126], 1067)
            }
            1067 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 53, 49], 1068);
                step(f, Op::JumpIfFalse, &[49, 1070], 1069)
            }
            1069 => {
                step(f, Op::Jump, &[1123], 1070)
            }
            1070 => {
                step(f, Op::ArrayAt(Elem::Transform), &[2, 53, 54], 1071);
                step(f, Op::BreakTransform, &[54, 203, 37, 204], 1072);
                step(f, Op::Equals(Elem::Int), &[53, 65, 51], 1073);
                step(f, Op::Select(ValueType::Int), &[51, 66, 65, 54], 1074);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 54, 36], 1075);
                step(f, Op::BreakTransform, &[36, 125, 26, 126], 1076);
                step(f, Op::SubF, &[570, 12, 324], 1077);
                step(f, Op::MulF, &[11, 324, 325], 1078);
                step(f, Op::FootAvoidance, &[203, 125, 325, 51, 70, 127], 1079);
                step(f, Op::MakeTransform, &[127, 37, 341, 37], 1080);
                step(f, Op::Copy(ValueType::Transform), &[37, 38], 1081);
                step(f, Op::Copy(ValueType::Transform), &[103, 39], 1082);
                step(f, Op::BreakTransform, &[38, 128, 27, 129], 1083);
                step(f, Op::MakeVector, &[568, 568, 48, 130], 1084);
                step(f, Op::AddV, &[128, 130, 131], 1085);
                step(f, Op::SubV, &[128, 130, 132], 1086);
                step(f, Op::LineTrace, &[131, 132, 53, 133, 134, 326], 1087);
                step(f, Op::RotateVector, &[27, 343, 135], 1088);
                step(f, Op::FindQuatBetween, &[135, 134, 28], 1089);
                step(f, Op::MulQ, &[28, 27, 29], 1090);
                step(f, Op::MulF, &[46, 45, 327], 1091);
                step(f, Op::AddF, &[327, 54, 328], 1092);
                step(f, Op::NegF, &[328, 329], 1093);
                step(f, Op::MakeVector, &[568, 329, 568, 136], 1094);
                step(f, Op::RotateVector, &[29, 136, 138], 1095);
                step(f, Op::AddV, &[133, 138, 140], 1096);
                step(f, Op::AddV, &[140, 130, 142], 1097);
                step(f, Op::SubV, &[140, 130, 143], 1098);
                step(f, Op::LineTrace, &[142, 143, 54, 146, 147, 331], 1099);
                step(f, Op::BreakVector, &[146, 333, 334, 335], 1100);
                step(f, Op::BreakVector, &[140, 339, 340, 341], 1101);
                step(f, Op::SubF, &[335, 341, 345], 1102);
                step(f, Op::Select(ValueType::Float), &[54, 345, 568, 347], 1103);
                step(f, Op::AddF, &[50, 54, 330], 1104);
                step(f, Op::MakeVector, &[568, 330, 568, 137], 1105);
                step(f, Op::RotateVector, &[29, 137, 139], 1106);
                step(f, Op::AddV, &[133, 139, 141], 1107);
                step(f, Op::AddV, &[141, 130, 144], 1108);
                step(f, Op::SubV, &[141, 130, 145], 1109);
                step(f, Op::LineTrace, &[144, 145, 55, 148, 149, 332], 1110);
                step(f, Op::BreakVector, &[148, 336, 337, 338], 1111);
                step(f, Op::BreakVector, &[141, 342, 343, 344], 1112);
                step(f, Op::SubF, &[338, 344, 346], 1113);
                step(f, Op::Select(ValueType::Float), &[55, 346, 568, 348], 1114);
                step(f, Op::MaxF, &[347, 348, 349], 1115);
                step(f, Op::ClampF, &[349, 568, 53, 350], 1116);
                step(f, Op::MakeVector, &[568, 568, 350, 150], 1117);
                step(f, Op::AddV, &[133, 150, 151], 1118);
                step(f, Op::MakeTransform, &[151, 29, 341, 40], 1119);
                step(f, Op::Select(ValueType::Transform), &[53, 40, 38, 41], 1120);
                step(f, Op::Copy(ValueType::Transform), &[41, 39], 1121);
                step(f, Op::Jump, &[1122], 1122)
            }
            1122 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 53, 39], 1123);
                1123
            }
            1123 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 53, 34], 1124);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 53, 34], 1125);
                step(f, Op::Jump, &[1305], 1126)
            }
            1126 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 53, 34], 1127);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 53, 54], 1128);
                step(f, Op::ClampF, &[319, 568, 570, 403], 1129);
                step(f, Op::Copy(ValueType::Transform), &[34, 59], 1130);
                step(f, Op::Copy(ValueType::Transform), &[54, 60], 1131);
                step(f, Op::Copy(ValueType::Float), &[403, 421], 1132);
                step(f, Op::Copy(ValueType::Transform), &[103, 61], 1133);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[3, 2], 1134);
                step(f, Op::ArrayReset(Elem::Vec3), &[2], 1135);
                step(f, Op::BreakTransform, &[59, 221, 42, 222], 1136);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 221], 1137);
                step(f, Op::BreakTransform, &[59, 221, 42, 222], 1138);
                step(f, Op::UnitV, &[2, 220], 1139);
                step(f, Op::LengthV, &[2, 422], 1140);
                step(f, Op::RemapF, &[422, 568, 56, 568, 57, 74, 423], 1141);
                step(f, Op::ScaleV, &[220, 423, 225], 1142);
                step(f, Op::SubV, &[221, 225, 231], 1143);
                step(f, Op::MakeVector, &[568, 568, 59, 229], 1144);
                step(f, Op::AddV, &[231, 229, 233], 1145);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 233], 1146);
                step(f, Op::BreakTransform, &[59, 221, 42, 222], 1147);
                step(f, Op::UnitV, &[2, 220], 1148);
                step(f, Op::LengthV, &[2, 422], 1149);
                step(f, Op::RemapF, &[422, 568, 56, 568, 57, 74, 423], 1150);
                step(f, Op::ScaleV, &[220, 423, 225], 1151);
                step(f, Op::SubV, &[221, 225, 231], 1152);
                step(f, Op::MakeVector, &[568, 568, 59, 229], 1153);
                step(f, Op::AddV, &[231, 229, 233], 1154);
                step(f, Op::RemapF, &[422, 568, 56, 568, 61, 74, 425], 1155);
                step(f, Op::MakeVector, &[568, 568, 425, 227], 1156);
                step(f, Op::AddV, &[233, 227, 237], 1157);
                step(f, Op::BreakTransform, &[60, 223, 43, 224], 1158);
                step(f, Op::BreakVector, &[223, 430, 431, 432], 1159);
                step(f, Op::BreakVector, &[221, 427, 428, 429], 1160);
                step(f, Op::SubF, &[432, 429, 433], 1161);
                step(f, Op::MaxF, &[433, 568, 435], 1162);
                step(f, Op::MulF, &[435, 63, 439], 1163);
                step(f, Op::AbsF, &[433, 437], 1164);
                step(f, Op::RemapF, &[437, 568, 66, 568, 65, 74, 438], 1165);
                step(f, Op::AddF, &[439, 438, 441], 1166);
                step(f, Op::MakeVector, &[568, 568, 441, 235], 1167);
                step(f, Op::AddV, &[237, 235, 239], 1168);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 239], 1169);
                step(f, Op::BreakTransform, &[59, 221, 42, 222], 1170);
                step(f, Op::UnitV, &[2, 220], 1171);
                step(f, Op::LengthV, &[2, 422], 1172);
                step(f, Op::RemapF, &[422, 568, 56, 568, 57, 74, 423], 1173);
                step(f, Op::ScaleV, &[220, 423, 225], 1174);
                step(f, Op::SubV, &[221, 225, 231], 1175);
                step(f, Op::MakeVector, &[568, 568, 59, 229], 1176);
                step(f, Op::AddV, &[231, 229, 233], 1177);
                step(f, Op::RemapF, &[422, 568, 56, 568, 61, 74, 425], 1178);
                step(f, Op::MakeVector, &[568, 568, 425, 227], 1179);
                step(f, Op::AddV, &[233, 227, 237], 1180);
                step(f, Op::BreakTransform, &[60, 223, 43, 224], 1181);
                step(f, Op::BreakVector, &[223, 430, 431, 432], 1182);
                step(f, Op::BreakVector, &[221, 427, 428, 429], 1183);
                step(f, Op::SubF, &[432, 429, 433], 1184);
                step(f, Op::MaxF, &[433, 568, 435], 1185);
                step(f, Op::MulF, &[435, 63, 439], 1186);
                step(f, Op::AbsF, &[433, 437], 1187);
                step(f, Op::RemapF, &[437, 568, 66, 568, 65, 74, 438], 1188);
                step(f, Op::AddF, &[439, 438, 441], 1189);
                step(f, Op::MakeVector, &[568, 568, 441, 235], 1190);
                step(f, Op::AddV, &[237, 235, 239], 1191);
                step(f, Op::RemapF, &[422, 568, 56, 568, 58, 74, 424], 1192);
                step(f, Op::ScaleV, &[220, 424, 226], 1193);
                step(f, Op::AddV, &[223, 226, 232], 1194);
                step(f, Op::MakeVector, &[568, 568, 60, 230], 1195);
                step(f, Op::AddV, &[232, 230, 234], 1196);
                step(f, Op::RemapF, &[422, 568, 56, 568, 62, 74, 426], 1197);
                step(f, Op::MakeVector, &[568, 568, 426, 228], 1198);
                step(f, Op::AddV, &[234, 228, 238], 1199);
                step(f, Op::NegF, &[433, 434], 1200);
                step(f, Op::MaxF, &[434, 568, 436], 1201);
                step(f, Op::MulF, &[436, 64, 440], 1202);
                step(f, Op::AddF, &[440, 438, 442], 1203);
                step(f, Op::MakeVector, &[568, 568, 442, 236], 1204);
                step(f, Op::AddV, &[238, 236, 240], 1205);
                step(f, Op::LerpV, &[239, 240, 569, 241], 1206);
                step(f, Op::GetTransform, &[36, 65, 74, 62], 1207);
                step(f, Op::BreakTransform, &[62, 242, 44, 243], 1208);
                step(f, Op::BreakVector, &[242, 452, 453, 454], 1209);
                step(f, Op::SubF, &[570, 12, 446], 1210);
                step(f, Op::MulF, &[67, 446, 447], 1211);
                step(f, Op::MulF, &[11, 447, 448], 1212);
                step(f, Op::QuatFromAxisAngle, &[343, 448, 45], 1213);
                step(f, Op::SubV, &[241, 242, 244], 1214);
                step(f, Op::BreakVector, &[244, 443, 444, 445], 1215);
                step(f, Op::MakeVector, &[443, 444, 568, 245], 1216);
                step(f, Op::RotateVector, &[45, 245, 246], 1217);
                step(f, Op::BreakVector, &[246, 449, 450, 451], 1218);
                step(f, Op::AddF, &[452, 449, 458], 1219);
                step(f, Op::AddF, &[453, 450, 459], 1220);
                step(f, Op::BreakVector, &[241, 455, 456, 457], 1221);
                step(f, Op::MakeVector, &[458, 459, 457, 247], 1222);
                step(f, Op::DistanceV, &[221, 223, 460], 1223);
                step(f, Op::RemapF, &[460, 573, 580, 568, 570, 74, 461], 1224);
                step(f, Op::LerpV, &[241, 247, 461, 248], 1225);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 248], 1226);
                step(f, Op::BreakTransform, &[60, 223, 43, 224], 1227);
                step(f, Op::UnitV, &[2, 220], 1228);
                step(f, Op::LengthV, &[2, 422], 1229);
                step(f, Op::RemapF, &[422, 568, 56, 568, 58, 74, 424], 1230);
                step(f, Op::ScaleV, &[220, 424, 226], 1231);
                step(f, Op::AddV, &[223, 226, 232], 1232);
                step(f, Op::MakeVector, &[568, 568, 60, 230], 1233);
                step(f, Op::AddV, &[232, 230, 234], 1234);
                step(f, Op::RemapF, &[422, 568, 56, 568, 62, 74, 426], 1235);
                step(f, Op::MakeVector, &[568, 568, 426, 228], 1236);
                step(f, Op::AddV, &[234, 228, 238], 1237);
                step(f, Op::BreakVector, &[223, 430, 431, 432], 1238);
                step(f, Op::BreakTransform, &[59, 221, 42, 222], 1239);
                step(f, Op::BreakVector, &[221, 427, 428, 429], 1240);
                step(f, Op::SubF, &[432, 429, 433], 1241);
                step(f, Op::NegF, &[433, 434], 1242);
                step(f, Op::MaxF, &[434, 568, 436], 1243);
                step(f, Op::MulF, &[436, 64, 440], 1244);
                step(f, Op::AbsF, &[433, 437], 1245);
                step(f, Op::RemapF, &[437, 568, 66, 568, 65, 74, 438], 1246);
                step(f, Op::AddF, &[440, 438, 442], 1247);
                step(f, Op::MakeVector, &[568, 568, 442, 236], 1248);
                step(f, Op::AddV, &[238, 236, 240], 1249);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 240], 1250);
                step(f, Op::BreakTransform, &[60, 223, 43, 224], 1251);
                step(f, Op::UnitV, &[2, 220], 1252);
                step(f, Op::LengthV, &[2, 422], 1253);
                step(f, Op::RemapF, &[422, 568, 56, 568, 58, 74, 424], 1254);
                step(f, Op::ScaleV, &[220, 424, 226], 1255);
                step(f, Op::AddV, &[223, 226, 232], 1256);
                step(f, Op::MakeVector, &[568, 568, 60, 230], 1257);
                step(f, Op::AddV, &[232, 230, 234], 1258);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 234], 1259);
                step(f, Op::BreakTransform, &[60, 223, 43, 224], 1260);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 223], 1261);
                step(f, Op::JumpIfFalse, &[8, 1264], 1262)
            }
            1262 => {
                step(f, Op::DrawSpline, &[2, 65, 68, 569, 345], 1263);
                step(f, Op::Jump, &[1264], 1264)
            }
            1264 => {
                step(f, Op::Spline, &[2, 421, 65, 249, 250], 1265);
                step(f, Op::BreakTransform, &[59, 221, 42, 222], 1266);
                step(f, Op::BreakTransform, &[60, 223, 43, 224], 1267);
                step(f, Op::SlerpQ, &[42, 43, 421, 46], 1268);
                step(f, Op::MulF, &[421, 581, 462], 1269);
                step(f, Op::SinF, &[462, 463], 1270);
                step(f, Op::MulF, &[463, 68, 464], 1271);
                step(f, Op::SlerpQ, &[46, 86, 464, 47], 1272);
                step(f, Op::MakeTransform, &[249, 47, 341, 63], 1273);
                step(f, Op::Copy(ValueType::Transform), &[63, 61], 1274);
                step(f, Op::Jump, &[1275], 1275)
            }
            1275 => {
                step(f, Op::BreakTransform, &[61, 205, 38, 206], 1276);
                step(f, Op::Equals(Elem::Int), &[53, 65, 51], 1277);
                step(f, Op::Select(ValueType::Int), &[51, 66, 65, 54], 1278);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 54, 36], 1279);
                step(f, Op::BreakTransform, &[36, 125, 26, 126], 1280);
                step(f, Op::SubF, &[570, 12, 324], 1281);
                step(f, Op::MulF, &[11, 324, 325], 1282);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 54, 62], 1283);
                step(f, Op::Select(ValueType::Float), &[62, 71, 568, 406], 1284);
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 319], 1285);
                step(f, Op::ClampF, &[319, 568, 570, 403], 1286);
                step(f, Op::MulF, &[403, 581, 404], 1287);
                step(f, Op::SinF, &[404, 405], 1288);
                step(f, Op::MulF, &[405, 405, 407], 1289);
                step(f, Op::MulF, &[406, 407, 408], 1290);
                step(f, Op::AddF, &[70, 408, 409], 1291);
                step(f, Op::FootAvoidance, &[205, 125, 325, 51, 409, 207], 1292);
                step(f, Op::SubV, &[207, 205, 208], 1293);
                step(f, Op::LengthV, &[208, 410], 1294);
                step(f, Op::AddF, &[410, 408, 411], 1295);
                step(f, Op::DivF, &[410, 411, 412], 1296);
                step(f, Op::ScaleV, &[208, 412, 209], 1297);
                step(f, Op::AddV, &[205, 209, 210], 1298);
                step(f, Op::SubF, &[570, 108, 413], 1299);
                step(f, Op::MulF, &[3, 413, 414], 1300);
                step(f, Op::MulF, &[414, 407, 415], 1301);
                step(f, Op::MakeVector, &[568, 568, 415, 211], 1302);
                step(f, Op::AddV, &[210, 211, 212], 1303);
                step(f, Op::MakeTransform, &[212, 38, 341, 55], 1304);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 53, 55], 1305);
                1305
            }
            1305 => {
                step(f, Op::GreaterF, &[16, 568, 52], 1306);
                step(f, Op::JumpIfFalse, &[52, 1323], 1307)
            }
            1307 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 53, 56], 1308);
                step(f, Op::BreakTransform, &[56, 213, 39, 214], 1309);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 53, 57], 1310);
                step(f, Op::BreakTransform, &[57, 215, 40, 216], 1311);
                step(f, Op::MulF, &[16, 16, 416], 1312);
                step(f, Op::LerpV, &[213, 215, 416, 217], 1313);
                step(f, Op::SubF, &[570, 16, 417], 1314);
                step(f, Op::MulF, &[16, 417, 418], 1315);
                step(f, Op::MulF, &[110, 573, 419], 1316);
                step(f, Op::MulF, &[418, 419, 420], 1317);
                step(f, Op::MakeVector, &[568, 568, 420, 218], 1318);
                step(f, Op::AddV, &[217, 218, 219], 1319);
                step(f, Op::SlerpQ, &[39, 40, 16, 41], 1320);
                step(f, Op::MakeTransform, &[219, 41, 341, 58], 1321);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 53, 58], 1322);
                step(f, Op::Jump, &[1323], 1323)
            }
            1323 => {
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 319], 1324);
                step(f, Op::GreaterEqualF, &[319, 570, 50], 1325);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 53, 50], 1326);
                step(f, Op::Copy(ValueType::Bone), &[0, 17], 1327);
                step(f, Op::Copy(ValueType::Int), &[3, 55], 1328);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 55, 64], 1329);
                step(f, Op::BreakTransform, &[64, 251, 48, 252], 1330);
                step(f, Op::MakeVector, &[568, 568, 43, 261], 1331);
                step(f, Op::AddV, &[251, 261, 262], 1332);
                step(f, Op::GetTransform, &[17, 65, 74, 66], 1333);
                step(f, Op::BreakTransform, &[66, 256, 50, 257], 1334);
                step(f, Op::MakeTransform, &[262, 50, 341, 68], 1335);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 55, 20], 1336);
                step(f, Op::GetTransform, &[20, 65, 74, 67], 1337);
                step(f, Op::BreakTransform, &[67, 258, 51, 259], 1338);
                step(f, Op::SubV, &[258, 256, 260], 1339);
                step(f, Op::AddV, &[262, 260, 263], 1340);
                step(f, Op::FootPivots, &[262, 263, 45, 44, 43, 46, 264, 265, 266], 1341);
                step(f, Op::GetParent, &[17, 18], 1342);
                step(f, Op::GetParent, &[18, 19], 1343);
                step(f, Op::GetTransform, &[19, 65, 75, 65], 1344);
                step(f, Op::BreakTransform, &[65, 253, 49, 254], 1345);
                step(f, Op::SubV, &[251, 253, 255], 1346);
                step(f, Op::DotV, &[255, 344, 465], 1347);
                step(f, Op::RemapF, &[465, 73, 72, 74, 568, 74, 468], 1348);
                step(f, Op::LengthV, &[2, 466], 1349);
                step(f, Op::RemapF, &[466, 568, 80, 568, 570, 74, 467], 1350);
                step(f, Op::MulF, &[468, 467, 469], 1351);
                step(f, Op::QuatFromAxisAngle, &[346, 469, 52], 1352);
                step(f, Op::RotateAroundPoint, &[68, 264, 52, 69], 1353);
                step(f, Op::SubV, &[265, 264, 267], 1354);
                step(f, Op::RotateVector, &[52, 267, 268], 1355);
                step(f, Op::AddV, &[264, 268, 269], 1356);
                step(f, Op::RemapF, &[465, 75, 73, 76, 568, 74, 470], 1357);
                step(f, Op::MulF, &[470, 467, 471], 1358);
                step(f, Op::QuatFromAxisAngle, &[346, 471, 53], 1359);
                step(f, Op::RotateAroundPoint, &[69, 269, 53, 70], 1360);
                step(f, Op::RemapF, &[465, 77, 78, 568, 79, 74, 472], 1361);
                step(f, Op::MulF, &[472, 467, 473], 1362);
                step(f, Op::QuatFromAxisAngle, &[346, 473, 54], 1363);
                step(f, Op::RotateAroundPoint, &[70, 266, 54, 71], 1364);
                step(f, Op::SubF, &[570, 12, 474], 1365);
                step(f, Op::MulF, &[11, 474, 475], 1366);
                step(f, Op::LimitRotationAroundZ, &[48, 475, 81, 55], 1367);
                step(f, Op::RotateAroundPoint, &[71, 251, 55, 72], 1368);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 55, 72], 1369);
                step(f, Op::JumpIfFalse, &[8, 1426], 1370)
            }
            1370 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 55, 64], 1371);
                step(f, Op::BreakTransform, &[64, 251, 48, 252], 1372);
                step(f, Op::MakeVector, &[568, 568, 43, 261], 1373);
                step(f, Op::AddV, &[251, 261, 262], 1374);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 55, 20], 1375);
                step(f, Op::GetTransform, &[20, 65, 74, 67], 1376);
                step(f, Op::BreakTransform, &[67, 258, 51, 259], 1377);
                step(f, Op::GetTransform, &[17, 65, 74, 66], 1378);
                step(f, Op::BreakTransform, &[66, 256, 50, 257], 1379);
                step(f, Op::SubV, &[258, 256, 260], 1380);
                step(f, Op::AddV, &[262, 260, 263], 1381);
                step(f, Op::FootPivots, &[262, 263, 45, 44, 43, 46, 264, 265, 266], 1382);
                step(f, Op::DrawPoint, &[266, 574, 346], 1383);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 55, 64], 1384);
                step(f, Op::BreakTransform, &[64, 251, 48, 252], 1385);
                step(f, Op::MakeVector, &[568, 568, 43, 261], 1386);
                step(f, Op::AddV, &[251, 261, 262], 1387);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 55, 20], 1388);
                step(f, Op::GetTransform, &[20, 65, 74, 67], 1389);
                step(f, Op::BreakTransform, &[67, 258, 51, 259], 1390);
                step(f, Op::GetTransform, &[17, 65, 74, 66], 1391);
                step(f, Op::BreakTransform, &[66, 256, 50, 257], 1392);
                step(f, Op::SubV, &[258, 256, 260], 1393);
                step(f, Op::AddV, &[262, 260, 263], 1394);
                step(f, Op::FootPivots, &[262, 263, 45, 44, 43, 46, 264, 265, 266], 1395);
                step(f, Op::DrawPoint, &[264, 574, 344], 1396);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 55, 64], 1397);
                step(f, Op::BreakTransform, &[64, 251, 48, 252], 1398);
                step(f, Op::MakeVector, &[568, 568, 43, 261], 1399);
                step(f, Op::AddV, &[251, 261, 262], 1400);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 55, 20], 1401);
                step(f, Op::GetTransform, &[20, 65, 74, 67], 1402);
                step(f, Op::BreakTransform, &[67, 258, 51, 259], 1403);
                step(f, Op::GetTransform, &[17, 65, 74, 66], 1404);
                step(f, Op::BreakTransform, &[66, 256, 50, 257], 1405);
                step(f, Op::SubV, &[258, 256, 260], 1406);
                step(f, Op::AddV, &[262, 260, 263], 1407);
                step(f, Op::FootPivots, &[262, 263, 45, 44, 43, 46, 264, 265, 266], 1408);
                step(f, Op::GetParent, &[17, 18], 1409);
                step(f, Op::GetParent, &[18, 19], 1410);
                step(f, Op::GetTransform, &[19, 65, 75, 65], 1411);
                step(f, Op::BreakTransform, &[65, 253, 49, 254], 1412);
                step(f, Op::SubV, &[251, 253, 255], 1413);
                step(f, Op::DotV, &[255, 344, 465], 1414);
                step(f, Op::RemapF, &[465, 73, 72, 74, 568, 74, 468], 1415);
                step(f, Op::LengthV, &[2, 466], 1416);
                step(f, Op::RemapF, &[466, 568, 80, 568, 570, 74, 467], 1417);
                step(f, Op::MulF, &[468, 467, 469], 1418);
                step(f, Op::QuatFromAxisAngle, &[346, 469, 52], 1419);
                step(f, Op::SubV, &[265, 264, 267], 1420);
                step(f, Op::RotateVector, &[52, 267, 268], 1421);
                step(f, Op::AddV, &[264, 268, 269], 1422);
                step(f, Op::DrawPoint, &[269, 574, 343], 1423);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 55, 64], 1424);
                step(f, Op::DrawTransform, &[64, 580, 569], 1425);
                step(f, Op::Jump, &[1426], 1426)
            }
            1426 => {
                step(f, Op::Jump, &[806], 1427)
            }
            1427 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1428);
                step(f, Op::Copy(ValueType::Int), &[65, 5], 1429);
                1429
            }
            1429 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 5, 1, 6, 7, 1484], 1430)
            }
            1430 => {
                step(f, Op::Copy(ValueType::Bone), &[1, 21], 1431);
                step(f, Op::Copy(ValueType::Int), &[6, 56], 1432);
                step(f, Op::GetParent, &[21, 22], 1433);
                step(f, Op::GetParent, &[22, 23], 1434);
                step(f, Op::GetParent, &[23, 24], 1435);
                step(f, Op::GetTransform, &[24, 65, 75, 73], 1436);
                step(f, Op::BreakTransform, &[73, 270, 56, 271], 1437);
                step(f, Op::LengthV, &[1, 477], 1438);
                step(f, Op::ClavicleOffset, &[9, 477, 86, 89, 478], 1439);
                step(f, Op::MakeVector, &[568, 568, 478, 272], 1440);
                step(f, Op::AddV, &[270, 272, 273], 1441);
                step(f, Op::MakeTransform, &[273, 56, 341, 74], 1442);
                step(f, Op::SetTransform, &[24, 74, 65, 74, 570], 1443);
                step(f, Op::GetParent, &[21, 22], 1444);
                step(f, Op::GetParent, &[22, 23], 1445);
                step(f, Op::GetTransform, &[21, 65, 75, 75], 1446);
                step(f, Op::GetTransform, &[23, 65, 75, 76], 1447);
                step(f, Op::BreakTransform, &[76, 274, 58, 275], 1448);
                step(f, Op::Equals(Elem::Int), &[56, 65, 63], 1449);
                step(f, Op::Select(ValueType::Int), &[63, 66, 65, 57], 1450);
                step(f, Op::ArrayAt(Elem::Float), &[0, 57, 476], 1451);
                step(f, Op::ArmSwingRotation, &[476, 1, 0, 87, 576, 582, 570, 86, 84, 85, 576, 576, 570, 479], 1452);
                step(f, Op::QuatFromAxisAngle, &[346, 479, 57], 1453);
                step(f, Op::RotateAroundPoint, &[75, 274, 57, 77], 1454);
                step(f, Op::BreakTransform, &[77, 276, 59, 277], 1455);
                step(f, Op::LengthV, &[1, 477], 1456);
                step(f, Op::RemapF, &[477, 568, 86, 568, 88, 74, 480], 1457);
                step(f, Op::MakeVector, &[568, 568, 480, 278], 1458);
                step(f, Op::AddV, &[276, 278, 279], 1459);
                step(f, Op::MakeTransform, &[279, 59, 341, 78], 1460);
                step(f, Op::Select(ValueType::Vec3), &[63, 347, 346, 281], 1461);
                step(f, Op::Select(ValueType::Vec3), &[63, 344, 348, 282], 1462);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 56, 280], 1463);
                step(f, Op::TwoBoneIK, &[23, 22, 21, 78, 281, 282, 280, 65, 570, 75, 583, 584, 74, 64, 481], 1464);
                step(f, Op::JumpIfFalse, &[8, 1483], 1465)
            }
            1465 => {
                step(f, Op::GetParent, &[21, 22], 1466);
                step(f, Op::GetParent, &[22, 23], 1467);
                step(f, Op::GetTransform, &[23, 65, 75, 76], 1468);
                step(f, Op::BreakTransform, &[76, 274, 58, 275], 1469);
                step(f, Op::GetTransform, &[21, 65, 75, 75], 1470);
                step(f, Op::Equals(Elem::Int), &[56, 65, 63], 1471);
                step(f, Op::Select(ValueType::Int), &[63, 66, 65, 57], 1472);
                step(f, Op::ArrayAt(Elem::Float), &[0, 57, 476], 1473);
                step(f, Op::ArmSwingRotation, &[476, 1, 0, 87, 576, 582, 570, 86, 84, 85, 576, 576, 570, 479], 1474);
                step(f, Op::QuatFromAxisAngle, &[346, 479, 57], 1475);
                step(f, Op::RotateAroundPoint, &[75, 274, 57, 77], 1476);
                step(f, Op::BreakTransform, &[77, 276, 59, 277], 1477);
                step(f, Op::LengthV, &[1, 477], 1478);
                step(f, Op::RemapF, &[477, 568, 86, 568, 88, 74, 480], 1479);
                step(f, Op::MakeVector, &[568, 568, 480, 278], 1480);
                step(f, Op::AddV, &[276, 278, 279], 1481);
                step(f, Op::DrawLine, &[274, 279, 569, 344], 1482);
                step(f, Op::Jump, &[1483], 1483)
            }
            1483 => {
                step(f, Op::Jump, &[1429], 1484)
            }
            1484 => {
                step(f, Op::Copy(ValueType::Float), &[568, 484], 1485);
                step(f, Op::Copy(ValueType::Float), &[577, 485], 1486);
                step(f, Op::Copy(ValueType::Bool), &[75, 65], 1487);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[3, 8], 1488);
                step(f, Op::Copy(ValueType::Int), &[65, 58], 1489);
                step(f, Op::MakeVector, &[568, 568, 48, 285], 1490);
                1490
            }
            1490 => {
                step(f, Op::ForEachNext(Elem::Transform), &[8, 58, 79, 59, 60, 1503], 1491)
            }
            1491 => {
                step(f, Op::BreakTransform, &[79, 283, 60, 284], 1492);
                step(f, Op::AddV, &[283, 285, 286], 1493);
                step(f, Op::SubV, &[283, 285, 287], 1494);
                step(f, Op::SphereTrace, &[286, 287, 47, 66, 288, 289, 486], 1495);
                step(f, Op::BreakVector, &[288, 487, 488, 489], 1496);
                step(f, Op::LessF, &[489, 485, 67], 1497);
                step(f, Op::And, &[66, 67, 68], 1498);
                step(f, Op::JumpIfFalse, &[68, 1502], 1499)
            }
            1499 => {
                step(f, Op::Copy(ValueType::Float), &[489, 485], 1500);
                step(f, Op::Copy(ValueType::Bool), &[74, 65], 1501);
                step(f, Op::Jump, &[1502], 1502)
            }
            1502 => {
                step(f, Op::Jump, &[1490], 1503)
            }
            1503 => {
                step(f, Op::Select(ValueType::Float), &[65, 485, 568, 490], 1504);
                step(f, Op::ClampF, &[490, 51, 52, 491], 1505);
                step(f, Op::Copy(ValueType::Float), &[491, 484], 1506);
                step(f, Op::Jump, &[1507], 1507)
            }
            1507 => {
                step(f, Op::SubF, &[570, 16, 483], 1508);
                step(f, Op::MulF, &[484, 483, 492], 1509);
                step(f, Op::FloatLerp, &[13, 492, 42, 493], 1510);
                step(f, Op::Select(ValueType::Float), &[1, 492, 493, 494], 1511);
                step(f, Op::Copy(ValueType::Float), &[494, 13], 1512);
                step(f, Op::GetTransform, &[37, 65, 74, 84], 1513);
                step(f, Op::BreakTransform, &[84, 302, 67, 303], 1514);
                step(f, Op::PelvisLean, &[1, 91, 96, 97, 510, 511], 1515);
                step(f, Op::LengthV, &[2, 482], 1516);
                step(f, Op::RemapF, &[482, 568, 91, 568, 90, 74, 495], 1517);
                step(f, Op::MulF, &[9, 585, 496], 1518);
                step(f, Op::SinF, &[496, 497], 1519);
                step(f, Op::MulF, &[495, 497, 498], 1520);
                step(f, Op::MulF, &[498, 483, 499], 1521);
                step(f, Op::AddF, &[499, 13, 500], 1522);
                step(f, Op::MulF, &[3, 108, 501], 1523);
                step(f, Op::SubF, &[500, 501, 502], 1524);
                step(f, Op::MakeVector, &[568, 511, 502, 304], 1525);
                step(f, Op::AddV, &[302, 304, 305], 1526);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 65, 80], 1527);
                step(f, Op::BreakTransform, &[80, 290, 61, 291], 1528);
                step(f, Op::BreakVector, &[290, 512, 513, 514], 1529);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 66, 81], 1530);
                step(f, Op::BreakTransform, &[81, 292, 62, 293], 1531);
                step(f, Op::BreakVector, &[292, 515, 516, 517], 1532);
                step(f, Op::SubF, &[514, 517, 518], 1533);
                step(f, Op::PelvisSideLean, &[518, 98, 99, 519], 1534);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 65, 82], 1535);
                step(f, Op::BreakTransform, &[82, 296, 63, 297], 1536);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 66, 83], 1537);
                step(f, Op::BreakTransform, &[83, 298, 64, 299], 1538);
                step(f, Op::SlerpQ, &[63, 64, 569, 65], 1539);
                step(f, Op::EulerFromQuat, &[65, 65, 300], 1540);
                step(f, Op::BreakVector, &[300, 506, 507, 508], 1541);
                step(f, Op::RemapF, &[482, 92, 91, 568, 93, 74, 504], 1542);
                step(f, Op::SubV, &[290, 292, 294], 1543);
                step(f, Op::RotateVector, &[0, 344, 295], 1544);
                step(f, Op::DotV, &[294, 295, 503], 1545);
                step(f, Op::MulF, &[504, 503, 505], 1546);
                step(f, Op::AddF, &[508, 505, 509], 1547);
                step(f, Op::MakeVector, &[510, 519, 509, 301], 1548);
                step(f, Op::QuatFromEuler, &[301, 65, 66], 1549);
                step(f, Op::MakeTransform, &[305, 66, 341, 85], 1550);
                step(f, Op::SetTransform, &[38, 85, 65, 74, 570], 1551);
                step(f, Op::GetTransform, &[39, 66, 74, 86], 1552);
                step(f, Op::BreakTransform, &[86, 306, 71, 307], 1553);
                step(f, Op::LengthV, &[2, 482], 1554);
                step(f, Op::RemapF, &[482, 92, 91, 568, 93, 74, 504], 1555);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 65, 80], 1556);
                step(f, Op::BreakTransform, &[80, 290, 61, 291], 1557);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 66, 81], 1558);
                step(f, Op::BreakTransform, &[81, 292, 62, 293], 1559);
                step(f, Op::SubV, &[290, 292, 294], 1560);
                step(f, Op::RotateVector, &[0, 344, 295], 1561);
                step(f, Op::DotV, &[294, 295, 503], 1562);
                step(f, Op::MulF, &[504, 503, 505], 1563);
                step(f, Op::QuatFromAxisAngle, &[343, 505, 68], 1564);
                step(f, Op::DivF, &[94, 574, 520], 1565);
                step(f, Op::QuatScale, &[68, 520, 69], 1566);
                step(f, Op::MulQ, &[71, 69, 75], 1567);
                step(f, Op::MakeTransform, &[306, 75, 341, 90], 1568);
                step(f, Op::SetTransform, &[40, 90, 66, 74, 570], 1569);
                step(f, Op::GetTransform, &[41, 66, 74, 87], 1570);
                step(f, Op::BreakTransform, &[87, 308, 72, 309], 1571);
                step(f, Op::LengthV, &[2, 482], 1572);
                step(f, Op::RemapF, &[482, 92, 91, 568, 93, 74, 504], 1573);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 65, 80], 1574);
                step(f, Op::BreakTransform, &[80, 290, 61, 291], 1575);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 66, 81], 1576);
                step(f, Op::BreakTransform, &[81, 292, 62, 293], 1577);
                step(f, Op::SubV, &[290, 292, 294], 1578);
                step(f, Op::RotateVector, &[0, 344, 295], 1579);
                step(f, Op::DotV, &[294, 295, 503], 1580);
                step(f, Op::MulF, &[504, 503, 505], 1581);
                step(f, Op::QuatFromAxisAngle, &[343, 505, 68], 1582);
                step(f, Op::DivF, &[94, 574, 520], 1583);
                step(f, Op::QuatScale, &[68, 520, 69], 1584);
                step(f, Op::MulQ, &[72, 69, 76], 1585);
                step(f, Op::MakeTransform, &[308, 76, 341, 91], 1586);
                step(f, Op::SetTransform, &[42, 91, 66, 74, 570], 1587);
                step(f, Op::GetTransform, &[43, 66, 74, 88], 1588);
                step(f, Op::BreakTransform, &[88, 310, 73, 311], 1589);
                step(f, Op::LengthV, &[2, 482], 1590);
                step(f, Op::RemapF, &[482, 92, 91, 568, 93, 74, 504], 1591);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 65, 80], 1592);
                step(f, Op::BreakTransform, &[80, 290, 61, 291], 1593);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 66, 81], 1594);
                step(f, Op::BreakTransform, &[81, 292, 62, 293], 1595);
                step(f, Op::SubV, &[290, 292, 294], 1596);
                step(f, Op::RotateVector, &[0, 344, 295], 1597);
                step(f, Op::DotV, &[294, 295, 503], 1598);
                step(f, Op::MulF, &[504, 503, 505], 1599);
                step(f, Op::QuatFromAxisAngle, &[343, 505, 68], 1600);
                step(f, Op::DivF, &[94, 574, 520], 1601);
                step(f, Op::QuatScale, &[68, 520, 69], 1602);
                step(f, Op::MulQ, &[73, 69, 77], 1603);
                step(f, Op::MakeTransform, &[310, 77, 341, 92], 1604);
                step(f, Op::SetTransform, &[44, 92, 66, 74, 570], 1605);
                step(f, Op::GetTransform, &[45, 66, 74, 89], 1606);
                step(f, Op::BreakTransform, &[89, 312, 74, 313], 1607);
                step(f, Op::LengthV, &[2, 482], 1608);
                step(f, Op::RemapF, &[482, 92, 91, 568, 93, 74, 504], 1609);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 65, 80], 1610);
                step(f, Op::BreakTransform, &[80, 290, 61, 291], 1611);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 66, 81], 1612);
                step(f, Op::BreakTransform, &[81, 292, 62, 293], 1613);
                step(f, Op::SubV, &[290, 292, 294], 1614);
                step(f, Op::RotateVector, &[0, 344, 295], 1615);
                step(f, Op::DotV, &[294, 295, 503], 1616);
                step(f, Op::MulF, &[504, 503, 505], 1617);
                step(f, Op::QuatFromAxisAngle, &[343, 505, 68], 1618);
                step(f, Op::QuatScale, &[68, 95, 70], 1619);
                step(f, Op::MulQ, &[74, 70, 78], 1620);
                step(f, Op::MakeTransform, &[312, 78, 341, 93], 1621);
                step(f, Op::SetTransform, &[46, 93, 66, 74, 570], 1622);
                step(f, Op::Copy(ValueType::Float), &[568, 521], 1623);
                step(f, Op::Copy(ValueType::Float), &[568, 522], 1624);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1625);
                step(f, Op::Copy(ValueType::Int), &[65, 61], 1626);
                1626
            }
            1626 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 61, 25, 62, 63, 1656], 1627)
            }
            1627 => {
                step(f, Op::GetParent, &[25, 26], 1628);
                step(f, Op::GetParent, &[26, 27], 1629);
                step(f, Op::GetTransform, &[27, 65, 75, 94], 1630);
                step(f, Op::BreakTransform, &[94, 314, 79, 315], 1631);
                step(f, Op::BreakVector, &[314, 523, 524, 525], 1632);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 62, 95], 1633);
                step(f, Op::BreakTransform, &[95, 316, 80, 317], 1634);
                step(f, Op::BreakVector, &[316, 526, 527, 528], 1635);
                step(f, Op::ArrayAt(Elem::Float), &[1, 62, 532], 1636);
                step(f, Op::MulF, &[532, 100, 533], 1637);
                step(f, Op::MulF, &[533, 533, 534], 1638);
                step(f, Op::SubF, &[523, 526, 529], 1639);
                step(f, Op::SubF, &[524, 527, 530], 1640);
                step(f, Op::MakeVector, &[529, 530, 568, 318], 1641);
                step(f, Op::DotV, &[318, 318, 531], 1642);
                step(f, Op::SubF, &[534, 531, 535], 1643);
                step(f, Op::SqrtF, &[535, 536], 1644);
                step(f, Op::AddF, &[528, 536, 537], 1645);
                step(f, Op::SubF, &[525, 537, 538], 1646);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 62, 69], 1647);
                step(f, Op::ArrayAt(Elem::Float), &[2, 62, 539], 1648);
                step(f, Op::RemapF, &[539, 569, 570, 568, 570, 74, 540], 1649);
                step(f, Op::RemapF, &[539, 568, 103, 570, 568, 74, 541], 1650);
                step(f, Op::MaxF, &[540, 541, 542], 1651);
                step(f, Op::Select(ValueType::Float), &[69, 570, 542, 543], 1652);
                step(f, Op::MulF, &[538, 543, 544], 1653);
                step(f, Op::MaxF, &[522, 544, 545], 1654);
                step(f, Op::Copy(ValueType::Float), &[545, 522], 1655);
                step(f, Op::Jump, &[1626], 1656)
            }
            1656 => {
                step(f, Op::ClampF, &[522, 568, 101, 546], 1657);
                step(f, Op::Copy(ValueType::Float), &[546, 521], 1658);
                step(f, Op::Jump, &[1659], 1659)
            }
            1659 => {
                step(f, Op::GreaterF, &[521, 14, 70], 1660);
                step(f, Op::Select(ValueType::Float), &[70, 105, 102, 547], 1661);
                step(f, Op::FloatLerp, &[14, 521, 547, 548], 1662);
                step(f, Op::Select(ValueType::Float), &[1, 521, 548, 549], 1663);
                step(f, Op::Copy(ValueType::Float), &[549, 14], 1664);
                step(f, Op::GetTransform, &[47, 65, 75, 96], 1665);
                step(f, Op::BreakTransform, &[96, 319, 81, 320], 1666);
                step(f, Op::MakeVector, &[568, 568, 14, 321], 1667);
                step(f, Op::SubV, &[319, 321, 322], 1668);
                step(f, Op::MakeTransform, &[322, 81, 341, 97], 1669);
                step(f, Op::SetTransform, &[48, 97, 65, 74, 570], 1670);
                step(f, Op::JumpIfFalse, &[8, 1678], 1671)
            }
            1671 => {
                step(f, Op::GetTransform, &[47, 65, 75, 96], 1672);
                step(f, Op::BreakTransform, &[96, 319, 81, 320], 1673);
                step(f, Op::MakeVector, &[568, 568, 14, 321], 1674);
                step(f, Op::SubV, &[319, 321, 322], 1675);
                step(f, Op::MakeTransform, &[322, 81, 341, 97], 1676);
                step(f, Op::DrawTransform, &[97, 586, 569], 1677);
                step(f, Op::Jump, &[1678], 1678)
            }
            1678 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1679);
                step(f, Op::Copy(ValueType::Int), &[65, 8], 1680);
                1680
            }
            1680 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 8, 2, 9, 10, 1732], 1681)
            }
            1681 => {
                step(f, Op::Copy(ValueType::Bone), &[2, 28], 1682);
                step(f, Op::Copy(ValueType::Int), &[9, 64], 1683);
                step(f, Op::GetParent, &[28, 29], 1684);
                step(f, Op::GetParent, &[29, 30], 1685);
                step(f, Op::GetTransform, &[30, 65, 75, 98], 1686);
                step(f, Op::BreakTransform, &[98, 323, 82, 324], 1687);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 64, 99], 1688);
                step(f, Op::BreakTransform, &[99, 325, 83, 326], 1689);
                step(f, Op::SubV, &[325, 323, 327], 1690);
                step(f, Op::LengthV, &[327, 558], 1691);
                step(f, Op::ArrayAt(Elem::Float), &[1, 64, 550], 1692);
                step(f, Op::MulF, &[550, 111, 551], 1693);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 64, 71], 1694);
                step(f, Op::ArrayAt(Elem::Float), &[2, 64, 552], 1695);
                step(f, Op::ClampF, &[552, 568, 570, 553], 1696);
                step(f, Op::MulF, &[553, 581, 554], 1697);
                step(f, Op::SinF, &[554, 555], 1698);
                step(f, Op::MulF, &[555, 112, 556], 1699);
                step(f, Op::Select(ValueType::Float), &[71, 568, 556, 557], 1700);
                step(f, Op::SubF, &[551, 557, 559], 1701);
                step(f, Op::SubF, &[558, 559, 560], 1702);
                step(f, Op::MaxF, &[560, 568, 561], 1703);
                step(f, Op::MulF, &[561, 561, 562], 1704);
                step(f, Op::AddF, &[561, 557, 563], 1705);
                step(f, Op::DivF, &[562, 563, 564], 1706);
                step(f, Op::SubF, &[558, 564, 565], 1707);
                step(f, Op::DivF, &[565, 558, 566], 1708);
                step(f, Op::ScaleV, &[327, 566, 328], 1709);
                step(f, Op::AddV, &[323, 328, 329], 1710);
                step(f, Op::ClampSpatially, &[329, 323, 568, 551, 330], 1711);
                step(f, Op::MakeTransform, &[330, 83, 341, 100], 1712);
                step(f, Op::Equals(Elem::Int), &[64, 65, 72], 1713);
                step(f, Op::Select(ValueType::Vec3), &[72, 347, 346, 335], 1714);
                step(f, Op::Select(ValueType::Vec3), &[72, 344, 348, 336], 1715);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 64, 101], 1716);
                step(f, Op::BreakTransform, &[101, 331, 84, 332], 1717);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 64, 333], 1718);
                step(f, Op::KneeVector, &[84, 0, 333, 113, 114, 334], 1719);
                step(f, Op::TwoBoneIK, &[30, 29, 28, 100, 335, 336, 334, 65, 570, 75, 583, 584, 74, 73, 567], 1720);
                step(f, Op::JumpIfFalse, &[8, 1731], 1721)
            }
            1721 => {
                step(f, Op::GetParent, &[28, 29], 1722);
                step(f, Op::GetTransform, &[29, 65, 75, 102], 1723);
                step(f, Op::BreakTransform, &[102, 337, 85, 338], 1724);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 64, 101], 1725);
                step(f, Op::BreakTransform, &[101, 331, 84, 332], 1726);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 64, 333], 1727);
                step(f, Op::KneeVector, &[84, 0, 333, 113, 114, 334], 1728);
                step(f, Op::AddV, &[337, 334, 339], 1729);
                step(f, Op::DrawLine, &[337, 339, 569, 349], 1730);
                step(f, Op::Jump, &[1731], 1731)
            }
            1731 => {
                step(f, Op::Jump, &[1680], 1732)
            }
            1732 => {
                step(f, Op::End, &[], 1733)
            }
            _ => return,
        } };
    }
}
