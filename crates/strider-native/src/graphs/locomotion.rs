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
    fingerprint: 0xcdaf0c0c2c73514d,
    forward,
};

fn forward(f: &mut Frame<'_>) {
    let mut pc: usize = 453;
    loop {
        // SAFETY: each `step` is an instruction of the program this code was generated
        // from, with its own operands; `NATIVE` runs only on that program (fingerprint).
        pc = unsafe { match pc {
            453 => {
                step(f, Op::Not, &[0, 9], 454);
                step(f, Op::Copy(ValueType::Bool), &[9, 1], 455);
                step(f, Op::WorldTransform, &[12], 456);
                step(f, Op::BreakTransform, &[12, 32, 7, 33], 457);
                step(f, Op::Select(ValueType::Transform), &[0, 0, 12, 13], 458);
                step(f, Op::BreakTransform, &[13, 34, 8, 35], 459);
                step(f, Op::SubV, &[32, 34, 36], 460);
                step(f, Op::LengthV, &[36, 125], 461);
                step(f, Op::GreaterF, &[125, 32, 10], 462);
                step(f, Op::Copy(ValueType::Bool), &[10, 2], 463);
                step(f, Op::MakeRelative, &[13, 12, 17], 464);
                step(f, Op::Select(ValueType::Transform), &[10, 108, 17, 18], 465);
                step(f, Op::Copy(ValueType::Transform), &[18, 2], 466);
                step(f, Op::InverseT, &[13, 15], 467);
                step(f, Op::MulT, &[12, 15, 16], 468);
                step(f, Op::Copy(ValueType::Transform), &[16, 1], 469);
                step(f, Op::TransformVector, &[2, 0, 41], 470);
                step(f, Op::InverseT, &[12, 14], 471);
                step(f, Op::DeltaTime, &[124], 472);
                step(f, Op::DivF, &[629, 124, 126], 473);
                step(f, Op::ScaleV, &[36, 126, 37], 474);
                step(f, Op::TransformVector, &[14, 37, 38], 475);
                step(f, Op::BreakVector, &[38, 127, 128, 129], 476);
                step(f, Op::MakeVector, &[127, 128, 627, 39], 477);
                step(f, Op::LengthV, &[39, 130], 478);
                step(f, Op::MulF, &[130, 109, 131], 479);
                step(f, Op::NegF, &[131, 132], 480);
                step(f, Op::ClampF, &[129, 132, 131, 133], 481);
                step(f, Op::MakeVector, &[127, 128, 133, 40], 482);
                step(f, Op::Select(ValueType::Vec3), &[2, 41, 40, 43], 483);
                step(f, Op::VectorLerp, &[41, 43, 33, 627, 44], 484);
                step(f, Op::Copy(ValueType::Vec3), &[44, 0], 485);
                step(f, Op::TransformVector, &[2, 1, 42], 486);
                step(f, Op::TransformVector, &[2, 0, 41], 487);
                step(f, Op::Select(ValueType::Vec3), &[2, 41, 40, 43], 488);
                step(f, Op::VectorLerp, &[42, 43, 34, 627, 45], 489);
                step(f, Op::Copy(ValueType::Vec3), &[45, 1], 490);
                step(f, Op::LengthV, &[43, 140], 491);
                step(f, Op::Copy(ValueType::Float), &[140, 0], 492);
                step(f, Op::BreakVector, &[36, 134, 135, 136], 493);
                step(f, Op::MulF, &[133, 124, 137], 494);
                step(f, Op::SubF, &[136, 137, 138], 495);
                step(f, Op::Select(ValueType::Float), &[10, 627, 138, 139], 496);
                step(f, Op::Copy(ValueType::Float), &[139, 1], 497);
                step(f, Op::JumpIfFalse, &[2, 516], 498)
            }
            498 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 12], 499);
                step(f, Op::Copy(ValueType::Int), &[65, 17], 500);
                500
            }
            500 => {
                step(f, Op::ForEachNext(Elem::Bone), &[12, 17, 13, 18, 19, 514], 501)
            }
            501 => {
                step(f, Op::ArrayAt(Elem::Transform), &[7, 18, 20], 502);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 18, 20], 503);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 18, 20], 504);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 18, 20], 505);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 18, 20], 506);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 18, 20], 507);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 18, 20], 508);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 18, 20], 509);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 18, 20], 510);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 18, 20], 511);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 18, 20], 512);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 18, 20], 513);
                step(f, Op::Jump, &[500], 514)
            }
            514 => {
                step(f, Op::Copy(ValueType::Float), &[627, 14], 515);
                step(f, Op::Jump, &[516], 516)
            }
            516 => {
                step(f, Op::WorldTransform, &[12], 517);
                step(f, Op::Copy(ValueType::Transform), &[12, 0], 518);
                step(f, Op::Copy(ValueType::Bool), &[78, 0], 519);
                step(f, Op::JumpIfFalse, &[8, 526], 520)
            }
            520 => {
                step(f, Op::GetTransform, &[34, 65, 78, 19], 521);
                step(f, Op::BreakTransform, &[19, 46, 9, 47], 522);
                step(f, Op::ScaleV, &[0, 630, 48], 523);
                step(f, Op::AddV, &[46, 48, 49], 524);
                step(f, Op::DrawArrow, &[46, 49, 628, 386], 525);
                step(f, Op::Jump, &[526], 526)
            }
            526 => {
                step(f, Op::Copy(ValueType::Float), &[627, 141], 527);
                step(f, Op::Copy(ValueType::Float), &[629, 142], 528);
                step(f, Op::Copy(ValueType::Float), &[629, 143], 529);
                step(f, Op::Copy(ValueType::Bool), &[79, 11], 530);
                step(f, Op::Copy(ValueType::Bool), &[79, 12], 531);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[7, 8], 532);
                step(f, Op::Copy(ValueType::Int), &[65, 25], 533);
                step(f, Op::MakeVector, &[627, 627, 51, 54], 534);
                534
            }
            534 => {
                step(f, Op::ForEachNext(Elem::Transform), &[8, 25, 21, 26, 27, 545], 535)
            }
            535 => {
                step(f, Op::BreakTransform, &[21, 50, 10, 51], 536);
                step(f, Op::TransformPoint, &[2, 50, 52], 537);
                step(f, Op::LerpV, &[52, 50, 143, 53], 538);
                step(f, Op::AddV, &[53, 54, 55], 539);
                step(f, Op::SubV, &[53, 54, 56], 540);
                step(f, Op::LineTrace, &[55, 56, 13, 57, 58, 144], 541);
                step(f, Op::JumpIfFalse, &[13, 544], 542)
            }
            542 => {
                step(f, Op::Copy(ValueType::Bool), &[78, 12], 543);
                step(f, Op::Jump, &[544], 544)
            }
            544 => {
                step(f, Op::Jump, &[534], 545)
            }
            545 => {
                step(f, Op::Copy(ValueType::Bool), &[12, 11], 546);
                step(f, Op::Jump, &[547], 547)
            }
            547 => {
                step(f, Op::Or, &[11, 7, 14], 548);
                step(f, Op::NotEquals(Elem::Bool), &[14, 5, 15], 549);
                step(f, Op::JumpIfFalse, &[15, 584], 550)
            }
            550 => {
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 551);
                step(f, Op::JumpIfFalse, &[16, 583], 552)
            }
            552 => {
                step(f, Op::Copy(ValueType::Int), &[1, 24], 553);
                step(f, Op::Copy(ValueType::Int), &[65, 20], 554);
                554
            }
            554 => {
                step(f, Op::ForNext, &[20, 24, 22, 582], 555)
            }
            555 => {
                step(f, Op::AddF, &[141, 142, 145], 556);
                step(f, Op::MulF, &[145, 628, 146], 557);
                step(f, Op::Copy(ValueType::Float), &[146, 147], 558);
                step(f, Op::Copy(ValueType::Bool), &[79, 17], 559);
                step(f, Op::Copy(ValueType::Bool), &[79, 18], 560);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[7, 9], 561);
                step(f, Op::Copy(ValueType::Int), &[65, 28], 562);
                step(f, Op::MakeVector, &[627, 627, 51, 63], 563);
                563
            }
            563 => {
                step(f, Op::ForEachNext(Elem::Transform), &[9, 28, 22, 29, 30, 574], 564)
            }
            564 => {
                step(f, Op::BreakTransform, &[22, 59, 11, 60], 565);
                step(f, Op::TransformPoint, &[2, 59, 61], 566);
                step(f, Op::LerpV, &[61, 59, 147, 62], 567);
                step(f, Op::AddV, &[62, 63, 64], 568);
                step(f, Op::SubV, &[62, 63, 65], 569);
                step(f, Op::LineTrace, &[64, 65, 19, 66, 67, 148], 570);
                step(f, Op::JumpIfFalse, &[19, 573], 571)
            }
            571 => {
                step(f, Op::Copy(ValueType::Bool), &[78, 18], 572);
                step(f, Op::Jump, &[573], 573)
            }
            573 => {
                step(f, Op::Jump, &[563], 574)
            }
            574 => {
                step(f, Op::Copy(ValueType::Bool), &[18, 17], 575);
                step(f, Op::Jump, &[576], 576)
            }
            576 => {
                step(f, Op::Equals(Elem::Bool), &[17, 6, 20], 577);
                step(f, Op::JumpIfFalse, &[20, 580], 578)
            }
            578 => {
                step(f, Op::Copy(ValueType::Float), &[146, 141], 579);
                step(f, Op::Jump, &[581], 580)
            }
            580 => {
                step(f, Op::Copy(ValueType::Float), &[146, 142], 581);
                581
            }
            581 => {
                step(f, Op::Jump, &[554], 582)
            }
            582 => {
                step(f, Op::Jump, &[583], 583)
            }
            583 => {
                step(f, Op::Jump, &[584], 584)
            }
            584 => {
                step(f, Op::Select(ValueType::Float), &[5, 631, 629, 154], 585);
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 586);
                step(f, Op::AddF, &[141, 142, 145], 587);
                step(f, Op::MulF, &[145, 628, 149], 588);
                step(f, Op::Select(ValueType::Float), &[16, 149, 628, 150], 589);
                step(f, Op::Select(ValueType::Float), &[15, 150, 627, 156], 590);
                step(f, Op::MulF, &[154, 156, 158], 591);
                step(f, Op::DeltaTime, &[152], 592);
                step(f, Op::DivF, &[152, 112, 153], 593);
                step(f, Op::MulF, &[158, 153, 159], 594);
                step(f, Op::AddF, &[17, 159, 160], 595);
                step(f, Op::ClampF, &[160, 627, 629, 161], 596);
                step(f, Op::Select(ValueType::Float), &[14, 631, 629, 155], 597);
                step(f, Op::SubF, &[629, 150, 151], 598);
                step(f, Op::Select(ValueType::Float), &[15, 151, 629, 157], 599);
                step(f, Op::MulF, &[155, 157, 162], 600);
                step(f, Op::MulF, &[162, 153, 163], 601);
                step(f, Op::AddF, &[161, 163, 164], 602);
                step(f, Op::ClampF, &[164, 627, 629, 165], 603);
                step(f, Op::MulF, &[165, 165, 166], 604);
                step(f, Op::MulF, &[165, 632, 167], 605);
                step(f, Op::SubF, &[633, 167, 168], 606);
                step(f, Op::MulF, &[166, 168, 169], 607);
                step(f, Op::AddF, &[18, 169, 170], 608);
                step(f, Op::MulF, &[170, 628, 171], 609);
                step(f, Op::SubF, &[629, 171, 172], 610);
                step(f, Op::MulF, &[172, 172, 173], 611);
                step(f, Op::SubF, &[629, 173, 174], 612);
                step(f, Op::Copy(ValueType::Float), &[174, 19], 613);
                step(f, Op::Copy(ValueType::Float), &[169, 18], 614);
                step(f, Op::Copy(ValueType::Float), &[165, 17], 615);
                step(f, Op::GreaterF, &[18, 627, 21], 616);
                step(f, Op::TransformVector, &[2, 3, 68], 617);
                step(f, Op::Select(ValueType::Vec3), &[21, 68, 0, 69], 618);
                step(f, Op::Copy(ValueType::Vec3), &[69, 3], 619);
                step(f, Op::LerpV, &[0, 3, 18, 70], 620);
                step(f, Op::Select(ValueType::Vec3), &[21, 70, 0, 71], 621);
                step(f, Op::Copy(ValueType::Vec3), &[71, 2], 622);
                step(f, Op::Copy(ValueType::Bool), &[14, 5], 623);
                step(f, Op::Copy(ValueType::Bool), &[11, 6], 624);
                step(f, Op::Copy(ValueType::Bool), &[79, 7], 625);
                step(f, Op::SubF, &[629, 19, 175], 626);
                step(f, Op::MulF, &[1, 175, 176], 627);
                step(f, Op::AddF, &[2, 176, 177], 628);
                step(f, Op::SpringF, &[177, 110, 180, 31, 178, 179], 629);
                step(f, Op::SubF, &[177, 180, 181], 630);
                step(f, Op::Copy(ValueType::Float), &[181, 3], 631);
                step(f, Op::Copy(ValueType::Float), &[177, 2], 632);
                step(f, Op::Copy(ValueType::Bool), &[79, 23], 633);
                step(f, Op::Copy(ValueType::Bool), &[78, 24], 634);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 635);
                step(f, Op::Copy(ValueType::Int), &[65, 35], 636);
                636
            }
            636 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 35, 25, 36, 37, 642], 637)
            }
            637 => {
                step(f, Op::Not, &[25, 26], 638);
                step(f, Op::JumpIfFalse, &[26, 641], 639)
            }
            639 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 24], 640);
                step(f, Op::Jump, &[641], 641)
            }
            641 => {
                step(f, Op::Jump, &[636], 642)
            }
            642 => {
                step(f, Op::Copy(ValueType::Bool), &[24, 23], 643);
                step(f, Op::Jump, &[644], 644)
            }
            644 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 27], 645);
                step(f, Op::Copy(ValueType::Bool), &[78, 28], 646);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 647);
                step(f, Op::Copy(ValueType::Int), &[65, 38], 648);
                648
            }
            648 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 38, 15, 39, 40, 663], 649)
            }
            649 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 39, 23], 650);
                step(f, Op::BreakTransform, &[23, 72, 12, 73], 651);
                step(f, Op::BreakVector, &[72, 190, 191, 192], 652);
                step(f, Op::MakeVector, &[190, 191, 627, 76], 653);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 39, 24], 654);
                step(f, Op::BreakTransform, &[24, 74, 13, 75], 655);
                step(f, Op::BreakVector, &[74, 193, 194, 195], 656);
                step(f, Op::MakeVector, &[193, 194, 627, 77], 657);
                step(f, Op::DistanceV, &[76, 77, 196], 658);
                step(f, Op::GreaterF, &[196, 28, 29], 659);
                step(f, Op::JumpIfFalse, &[29, 662], 660)
            }
            660 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 28], 661);
                step(f, Op::Jump, &[662], 662)
            }
            662 => {
                step(f, Op::Jump, &[648], 663)
            }
            663 => {
                step(f, Op::Copy(ValueType::Bool), &[28, 27], 664);
                step(f, Op::Jump, &[665], 665)
            }
            665 => {
                step(f, Op::And, &[23, 27, 30], 666);
                step(f, Op::LengthV, &[2, 182], 667);
                step(f, Op::GreaterF, &[182, 26, 22], 668);
                step(f, Op::GreaterF, &[0, 26, 31], 669);
                step(f, Op::Or, &[22, 31, 32], 670);
                step(f, Op::Not, &[32, 33], 671);
                step(f, Op::And, &[30, 33, 38], 672);
                step(f, Op::DeltaTime, &[221], 673);
                step(f, Op::MulF, &[221, 31, 222], 674);
                step(f, Op::AddF, &[10, 222, 223], 675);
                step(f, Op::GreaterF, &[10, 628, 39], 676);
                step(f, Op::AddF, &[30, 628, 219], 677);
                step(f, Op::Select(ValueType::Float), &[39, 219, 30, 220], 678);
                step(f, Op::MinF, &[223, 220, 224], 679);
                step(f, Op::NotEquals(Elem::Bool), &[33, 4, 34], 680);
                step(f, Op::Not, &[30, 35], 681);
                step(f, Op::And, &[34, 35, 36], 682);
                step(f, Op::SubF, &[11, 26, 205], 683);
                step(f, Op::SubF, &[11, 182, 206], 684);
                step(f, Op::DivF, &[205, 206, 207], 685);
                step(f, Op::ClampF, &[207, 627, 629, 208], 686);
                step(f, Op::MulF, &[6, 208, 210], 687);
                step(f, Op::RemapF, &[182, 26, 27, 627, 629, 78, 197], 688);
                step(f, Op::MaxF, &[197, 7, 198], 689);
                step(f, Op::Select(ValueType::Float), &[23, 629, 198, 199], 690);
                step(f, Op::Select(ValueType::Float), &[33, 29, 199, 200], 691);
                step(f, Op::Select(ValueType::Float), &[30, 197, 200, 201], 692);
                step(f, Op::SubF, &[629, 18, 202], 693);
                step(f, Op::MulF, &[201, 202, 203], 694);
                step(f, Op::LerpF, &[20, 41, 13, 185], 695);
                step(f, Op::RemapF, &[182, 23, 24, 21, 22, 78, 183], 696);
                step(f, Op::LerpF, &[183, 40, 13, 184], 697);
                step(f, Op::MaxF, &[182, 25, 186], 698);
                step(f, Op::DivF, &[184, 186, 187], 699);
                step(f, Op::AddF, &[185, 187, 188], 700);
                step(f, Op::DivF, &[203, 188, 204], 701);
                step(f, Op::SubF, &[629, 208, 209], 702);
                step(f, Op::MulF, &[204, 209, 211], 703);
                step(f, Op::AddF, &[210, 211, 212], 704);
                step(f, Op::MulF, &[212, 632, 213], 705);
                step(f, Op::AddF, &[6, 204, 214], 706);
                step(f, Op::Select(ValueType::Float), &[36, 213, 214, 215], 707);
                step(f, Op::DivF, &[632, 215, 216], 708);
                step(f, Op::GreaterF, &[215, 627, 37], 709);
                step(f, Op::CycleStep, &[10, 216, 627, 37, 217, 218], 710);
                step(f, Op::Select(ValueType::Float), &[38, 224, 217, 225], 711);
                step(f, Op::Copy(ValueType::Float), &[225, 10], 712);
                step(f, Op::Copy(ValueType::Float), &[204, 6], 713);
                step(f, Op::Copy(ValueType::Bool), &[22, 3], 714);
                step(f, Op::Copy(ValueType::Float), &[187, 4], 715);
                step(f, Op::Copy(ValueType::Float), &[188, 5], 716);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 717);
                step(f, Op::Copy(ValueType::Int), &[65, 32], 718);
                718
            }
            718 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 32, 14, 33, 34, 892], 719)
            }
            719 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 33, 239], 720);
                step(f, Op::ToFloat, &[33, 226], 721);
                step(f, Op::MulF, &[226, 628, 227], 722);
                step(f, Op::AddF, &[10, 227, 228], 723);
                step(f, Op::FractF, &[228, 229], 724);
                step(f, Op::SubF, &[239, 229, 241], 725);
                step(f, Op::GreaterF, &[241, 628, 40], 726);
                step(f, Op::ArrayAt(Elem::Float), &[2, 33, 240], 727);
                step(f, Op::Select(ValueType::Float), &[40, 627, 240, 268], 728);
                step(f, Op::ArraySetAt(Elem::Float), &[3, 33, 268], 729);
                step(f, Op::ArrayAt(Elem::Float), &[0, 33, 239], 730);
                step(f, Op::ToFloat, &[33, 226], 731);
                step(f, Op::MulF, &[226, 628, 227], 732);
                step(f, Op::AddF, &[10, 227, 228], 733);
                step(f, Op::FractF, &[228, 229], 734);
                step(f, Op::SubF, &[239, 229, 241], 735);
                step(f, Op::GreaterF, &[241, 628, 40], 736);
                step(f, Op::SubF, &[629, 239, 262], 737);
                step(f, Op::AddF, &[229, 262, 263], 738);
                step(f, Op::DivF, &[229, 263, 264], 739);
                step(f, Op::LengthV, &[2, 182], 740);
                step(f, Op::GreaterF, &[182, 26, 22], 741);
                step(f, Op::GreaterF, &[0, 26, 31], 742);
                step(f, Op::Or, &[22, 31, 32], 743);
                step(f, Op::Not, &[32, 33], 744);
                step(f, Op::NotEquals(Elem::Bool), &[33, 4, 34], 745);
                step(f, Op::Copy(ValueType::Bool), &[79, 23], 746);
                step(f, Op::Copy(ValueType::Bool), &[78, 24], 747);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 748);
                step(f, Op::Copy(ValueType::Int), &[65, 35], 749);
                749
            }
            749 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 35, 25, 36, 37, 755], 750)
            }
            750 => {
                step(f, Op::Not, &[25, 26], 751);
                step(f, Op::JumpIfFalse, &[26, 754], 752)
            }
            752 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 24], 753);
                step(f, Op::Jump, &[754], 754)
            }
            754 => {
                step(f, Op::Jump, &[749], 755)
            }
            755 => {
                step(f, Op::Copy(ValueType::Bool), &[24, 23], 756);
                step(f, Op::Jump, &[757], 757)
            }
            757 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 27], 758);
                step(f, Op::Copy(ValueType::Bool), &[78, 28], 759);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 760);
                step(f, Op::Copy(ValueType::Int), &[65, 38], 761);
                761
            }
            761 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 38, 15, 39, 40, 776], 762)
            }
            762 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 39, 23], 763);
                step(f, Op::BreakTransform, &[23, 72, 12, 73], 764);
                step(f, Op::BreakVector, &[72, 190, 191, 192], 765);
                step(f, Op::MakeVector, &[190, 191, 627, 76], 766);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 39, 24], 767);
                step(f, Op::BreakTransform, &[24, 74, 13, 75], 768);
                step(f, Op::BreakVector, &[74, 193, 194, 195], 769);
                step(f, Op::MakeVector, &[193, 194, 627, 77], 770);
                step(f, Op::DistanceV, &[76, 77, 196], 771);
                step(f, Op::GreaterF, &[196, 28, 29], 772);
                step(f, Op::JumpIfFalse, &[29, 775], 773)
            }
            773 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 28], 774);
                step(f, Op::Jump, &[775], 775)
            }
            775 => {
                step(f, Op::Jump, &[761], 776)
            }
            776 => {
                step(f, Op::Copy(ValueType::Bool), &[28, 27], 777);
                step(f, Op::Jump, &[778], 778)
            }
            778 => {
                step(f, Op::And, &[23, 27, 30], 779);
                step(f, Op::Not, &[30, 35], 780);
                step(f, Op::And, &[34, 35, 36], 781);
                step(f, Op::SubF, &[11, 26, 205], 782);
                step(f, Op::SubF, &[11, 182, 206], 783);
                step(f, Op::DivF, &[205, 206, 207], 784);
                step(f, Op::ClampF, &[207, 627, 629, 208], 785);
                step(f, Op::MulF, &[9, 208, 231], 786);
                step(f, Op::RemapF, &[182, 26, 27, 627, 629, 78, 197], 787);
                step(f, Op::MaxF, &[197, 7, 198], 788);
                step(f, Op::Select(ValueType::Float), &[23, 629, 198, 199], 789);
                step(f, Op::Select(ValueType::Float), &[33, 29, 199, 200], 790);
                step(f, Op::Select(ValueType::Float), &[30, 197, 200, 201], 791);
                step(f, Op::SubF, &[629, 18, 202], 792);
                step(f, Op::MulF, &[201, 202, 203], 793);
                step(f, Op::LerpF, &[20, 41, 13, 185], 794);
                step(f, Op::DivF, &[203, 185, 230], 795);
                step(f, Op::SubF, &[629, 208, 209], 796);
                step(f, Op::MulF, &[230, 209, 232], 797);
                step(f, Op::AddF, &[231, 232, 233], 798);
                step(f, Op::MulF, &[233, 632, 234], 799);
                step(f, Op::AddF, &[9, 230, 235], 800);
                step(f, Op::Select(ValueType::Float), &[36, 234, 235, 236], 801);
                step(f, Op::DeltaTime, &[221], 802);
                step(f, Op::MulF, &[221, 628, 237], 803);
                step(f, Op::MulF, &[236, 237, 238], 804);
                step(f, Op::MulF, &[264, 238, 265], 805);
                step(f, Op::ArrayAt(Elem::Float), &[2, 33, 240], 806);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 33, 41], 807);
                step(f, Op::RemapF, &[182, 23, 24, 21, 22, 78, 183], 808);
                step(f, Op::LerpF, &[183, 40, 13, 184], 809);
                step(f, Op::MaxF, &[182, 25, 186], 810);
                step(f, Op::DivF, &[184, 186, 187], 811);
                step(f, Op::AddF, &[185, 187, 188], 812);
                step(f, Op::DivF, &[185, 188, 189], 813);
                step(f, Op::SubF, &[189, 8, 242], 814);
                step(f, Op::MaxF, &[242, 627, 243], 815);
                step(f, Op::DivF, &[243, 189, 244], 816);
                step(f, Op::SubF, &[629, 13, 246], 817);
                step(f, Op::MulF, &[244, 246, 253], 818);
                step(f, Op::MulF, &[253, 202, 254], 819);
                step(f, Op::MulF, &[254, 107, 255], 820);
                step(f, Op::DivF, &[45, 221, 251], 821);
                step(f, Op::SubF, &[628, 251, 252], 822);
                step(f, Op::MulF, &[255, 252, 256], 823);
                step(f, Op::SubF, &[629, 256, 257], 824);
                step(f, Op::MulF, &[238, 257, 258], 825);
                step(f, Op::Select(ValueType::Float), &[41, 238, 258, 259], 826);
                step(f, Op::MulF, &[244, 240, 245], 827);
                step(f, Op::MulF, &[245, 246, 247], 828);
                step(f, Op::MulF, &[247, 202, 248], 829);
                step(f, Op::MulF, &[248, 107, 249], 830);
                step(f, Op::Select(ValueType::Float), &[41, 627, 249, 250], 831);
                step(f, Op::SubF, &[259, 250, 260], 832);
                step(f, Op::AddF, &[240, 260, 261], 833);
                step(f, Op::Select(ValueType::Float), &[40, 265, 261, 266], 834);
                step(f, Op::MinF, &[266, 632, 267], 835);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 33, 267], 836);
                step(f, Op::ArrayAt(Elem::Float), &[0, 33, 239], 837);
                step(f, Op::ToFloat, &[33, 226], 838);
                step(f, Op::MulF, &[226, 628, 227], 839);
                step(f, Op::AddF, &[10, 227, 228], 840);
                step(f, Op::FractF, &[228, 229], 841);
                step(f, Op::SubF, &[239, 229, 241], 842);
                step(f, Op::GreaterF, &[241, 628, 40], 843);
                step(f, Op::JumpIfFalse, &[40, 890], 844)
            }
            844 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 23], 845);
                step(f, Op::Copy(ValueType::Bool), &[78, 24], 846);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 847);
                step(f, Op::Copy(ValueType::Int), &[65, 35], 848);
                848
            }
            848 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 35, 25, 36, 37, 854], 849)
            }
            849 => {
                step(f, Op::Not, &[25, 26], 850);
                step(f, Op::JumpIfFalse, &[26, 853], 851)
            }
            851 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 24], 852);
                step(f, Op::Jump, &[853], 853)
            }
            853 => {
                step(f, Op::Jump, &[848], 854)
            }
            854 => {
                step(f, Op::Copy(ValueType::Bool), &[24, 23], 855);
                step(f, Op::Jump, &[856], 856)
            }
            856 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 27], 857);
                step(f, Op::Copy(ValueType::Bool), &[78, 28], 858);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 859);
                step(f, Op::Copy(ValueType::Int), &[65, 38], 860);
                860
            }
            860 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 38, 15, 39, 40, 875], 861)
            }
            861 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 39, 23], 862);
                step(f, Op::BreakTransform, &[23, 72, 12, 73], 863);
                step(f, Op::BreakVector, &[72, 190, 191, 192], 864);
                step(f, Op::MakeVector, &[190, 191, 627, 76], 865);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 39, 24], 866);
                step(f, Op::BreakTransform, &[24, 74, 13, 75], 867);
                step(f, Op::BreakVector, &[74, 193, 194, 195], 868);
                step(f, Op::MakeVector, &[193, 194, 627, 77], 869);
                step(f, Op::DistanceV, &[76, 77, 196], 870);
                step(f, Op::GreaterF, &[196, 28, 29], 871);
                step(f, Op::JumpIfFalse, &[29, 874], 872)
            }
            872 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 28], 873);
                step(f, Op::Jump, &[874], 874)
            }
            874 => {
                step(f, Op::Jump, &[860], 875)
            }
            875 => {
                step(f, Op::Copy(ValueType::Bool), &[28, 27], 876);
                step(f, Op::Jump, &[877], 877)
            }
            877 => {
                step(f, Op::And, &[23, 27, 30], 878);
                step(f, Op::LengthV, &[2, 182], 879);
                step(f, Op::RemapF, &[182, 26, 27, 627, 629, 78, 197], 880);
                step(f, Op::GreaterF, &[182, 26, 22], 881);
                step(f, Op::GreaterF, &[0, 26, 31], 882);
                step(f, Op::Or, &[22, 31, 32], 883);
                step(f, Op::Not, &[32, 33], 884);
                step(f, Op::MaxF, &[197, 7, 198], 885);
                step(f, Op::Select(ValueType::Float), &[23, 629, 198, 199], 886);
                step(f, Op::Select(ValueType::Float), &[33, 29, 199, 200], 887);
                step(f, Op::Select(ValueType::Float), &[30, 197, 200, 201], 888);
                step(f, Op::Copy(ValueType::Float), &[201, 7], 889);
                step(f, Op::Jump, &[890], 890)
            }
            890 => {
                step(f, Op::ArraySetAt(Elem::Float), &[0, 33, 229], 891);
                step(f, Op::Jump, &[718], 892)
            }
            892 => {
                step(f, Op::LerpF, &[20, 41, 13, 185], 893);
                step(f, Op::LengthV, &[2, 182], 894);
                step(f, Op::RemapF, &[182, 23, 24, 21, 22, 78, 183], 895);
                step(f, Op::LerpF, &[183, 40, 13, 184], 896);
                step(f, Op::MaxF, &[182, 25, 186], 897);
                step(f, Op::DivF, &[184, 186, 187], 898);
                step(f, Op::AddF, &[185, 187, 188], 899);
                step(f, Op::DivF, &[185, 188, 189], 900);
                step(f, Op::Copy(ValueType::Float), &[189, 8], 901);
                step(f, Op::GreaterF, &[182, 26, 22], 902);
                step(f, Op::GreaterF, &[0, 26, 31], 903);
                step(f, Op::Or, &[22, 31, 32], 904);
                step(f, Op::Not, &[32, 33], 905);
                step(f, Op::Copy(ValueType::Bool), &[33, 4], 906);
                step(f, Op::Copy(ValueType::Float), &[182, 11], 907);
                step(f, Op::Copy(ValueType::Bool), &[79, 23], 908);
                step(f, Op::Copy(ValueType::Bool), &[78, 24], 909);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 910);
                step(f, Op::Copy(ValueType::Int), &[65, 35], 911);
                911
            }
            911 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 35, 25, 36, 37, 917], 912)
            }
            912 => {
                step(f, Op::Not, &[25, 26], 913);
                step(f, Op::JumpIfFalse, &[26, 916], 914)
            }
            914 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 24], 915);
                step(f, Op::Jump, &[916], 916)
            }
            916 => {
                step(f, Op::Jump, &[911], 917)
            }
            917 => {
                step(f, Op::Copy(ValueType::Bool), &[24, 23], 918);
                step(f, Op::Jump, &[919], 919)
            }
            919 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 27], 920);
                step(f, Op::Copy(ValueType::Bool), &[78, 28], 921);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 922);
                step(f, Op::Copy(ValueType::Int), &[65, 38], 923);
                923
            }
            923 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 38, 15, 39, 40, 938], 924)
            }
            924 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 39, 23], 925);
                step(f, Op::BreakTransform, &[23, 72, 12, 73], 926);
                step(f, Op::BreakVector, &[72, 190, 191, 192], 927);
                step(f, Op::MakeVector, &[190, 191, 627, 76], 928);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 39, 24], 929);
                step(f, Op::BreakTransform, &[24, 74, 13, 75], 930);
                step(f, Op::BreakVector, &[74, 193, 194, 195], 931);
                step(f, Op::MakeVector, &[193, 194, 627, 77], 932);
                step(f, Op::DistanceV, &[76, 77, 196], 933);
                step(f, Op::GreaterF, &[196, 28, 29], 934);
                step(f, Op::JumpIfFalse, &[29, 937], 935)
            }
            935 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 28], 936);
                step(f, Op::Jump, &[937], 937)
            }
            937 => {
                step(f, Op::Jump, &[923], 938)
            }
            938 => {
                step(f, Op::Copy(ValueType::Bool), &[28, 27], 939);
                step(f, Op::Jump, &[940], 940)
            }
            940 => {
                step(f, Op::And, &[23, 27, 30], 941);
                step(f, Op::RemapF, &[182, 26, 27, 627, 629, 78, 197], 942);
                step(f, Op::MaxF, &[197, 7, 198], 943);
                step(f, Op::Select(ValueType::Float), &[23, 629, 198, 199], 944);
                step(f, Op::Select(ValueType::Float), &[33, 29, 199, 200], 945);
                step(f, Op::Select(ValueType::Float), &[30, 197, 200, 201], 946);
                step(f, Op::SubF, &[629, 18, 202], 947);
                step(f, Op::MulF, &[201, 202, 203], 948);
                step(f, Op::DivF, &[203, 185, 230], 949);
                step(f, Op::Copy(ValueType::Float), &[230, 9], 950);
                step(f, Op::Select(ValueType::Vec3), &[3, 2, 384, 78], 951);
                step(f, Op::MovementAngleOffset, &[78, 12, 10, 35, 36, 634, 37, 635, 269], 952);
                step(f, Op::Copy(ValueType::Float), &[269, 12], 953);
                step(f, Op::QuatFromAxisAngle, &[387, 12, 14], 954);
                step(f, Op::Copy(ValueType::Quat), &[14, 0], 955);
                step(f, Op::SinF, &[12, 270], 956);
                step(f, Op::AbsF, &[270, 271], 957);
                step(f, Op::RemapF, &[271, 38, 39, 627, 629, 78, 272], 958);
                step(f, Op::Copy(ValueType::Float), &[272, 13], 959);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 960);
                step(f, Op::Copy(ValueType::Int), &[65, 2], 961);
                961
            }
            961 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 2, 0, 3, 4, 1672], 962)
            }
            962 => {
                step(f, Op::Copy(ValueType::Bone), &[0, 16], 963);
                step(f, Op::Copy(ValueType::Int), &[3, 41], 964);
                step(f, Op::GetTransform, &[35, 65, 78, 25], 965);
                step(f, Op::BreakTransform, &[25, 81, 15, 82], 966);
                step(f, Op::BreakVector, &[81, 284, 285, 286], 967);
                step(f, Op::SubF, &[629, 13, 282], 968);
                step(f, Op::MulF, &[12, 282, 283], 969);
                step(f, Op::QuatFromAxisAngle, &[387, 283, 17], 970);
                step(f, Op::GetTransform, &[16, 65, 78, 26], 971);
                step(f, Op::BreakTransform, &[26, 83, 16, 84], 972);
                step(f, Op::SubV, &[83, 81, 85], 973);
                step(f, Op::BreakVector, &[85, 279, 280, 281], 974);
                step(f, Op::MakeVector, &[279, 280, 627, 86], 975);
                step(f, Op::RotateVector, &[17, 86, 87], 976);
                step(f, Op::BreakVector, &[87, 287, 288, 289], 977);
                step(f, Op::MulF, &[42, 13, 290], 978);
                step(f, Op::Equals(Elem::Int), &[41, 65, 42], 979);
                step(f, Op::Select(ValueType::Float), &[42, 629, 631, 299], 980);
                step(f, Op::MulF, &[290, 299, 291], 981);
                step(f, Op::AddF, &[287, 291, 292], 982);
                step(f, Op::AddF, &[284, 292, 293], 983);
                step(f, Op::AddF, &[285, 288, 294], 984);
                step(f, Op::BreakVector, &[83, 295, 296, 297], 985);
                step(f, Op::SubF, &[297, 46, 298], 986);
                step(f, Op::MakeVector, &[293, 294, 298, 88], 987);
                step(f, Op::ArrayAt(Elem::Float), &[2, 41, 273], 988);
                step(f, Op::SubF, &[629, 273, 274], 989);
                step(f, Op::MaxF, &[274, 627, 275], 990);
                step(f, Op::MulF, &[8, 5, 276], 991);
                step(f, Op::MulF, &[275, 276, 277], 992);
                step(f, Op::ScaleV, &[2, 277, 79], 993);
                step(f, Op::AddV, &[88, 79, 89], 994);
                step(f, Op::MulF, &[4, 628, 278], 995);
                step(f, Op::ScaleV, &[2, 278, 80], 996);
                step(f, Op::AddV, &[89, 80, 90], 997);
                step(f, Op::RotateVector, &[0, 388, 91], 998);
                step(f, Op::Copy(ValueType::Vec3), &[90, 112], 999);
                step(f, Op::Copy(ValueType::Vec3), &[91, 113], 1000);
                step(f, Op::Copy(ValueType::Float), &[299, 318], 1001);
                step(f, Op::Copy(ValueType::Vec3), &[384, 114], 1002);
                step(f, Op::Copy(ValueType::Vec3), &[384, 115], 1003);
                step(f, Op::Copy(ValueType::Bool), &[79, 44], 1004);
                step(f, Op::Copy(ValueType::Float), &[636, 319], 1005);
                step(f, Op::Copy(ValueType::Vec3), &[384, 116], 1006);
                step(f, Op::Copy(ValueType::Vec3), &[387, 117], 1007);
                step(f, Op::Copy(ValueType::Bool), &[79, 45], 1008);
                step(f, Op::MulI, &[0, 0, 47], 1009);
                step(f, Op::Copy(ValueType::Int), &[47, 46], 1010);
                step(f, Op::Copy(ValueType::Int), &[65, 42], 1011);
                step(f, Op::SubI, &[0, 66, 50], 1012);
                step(f, Op::DivI, &[50, 67, 51], 1013);
                step(f, Op::MakeVector, &[627, 627, 51, 122], 1014);
                step(f, Op::ScaleV, &[113, 53, 127], 1015);
                1015
            }
            1015 => {
                step(f, Op::ForNext, &[42, 46, 44, 1055], 1016)
            }
            1016 => {
                step(f, Op::ModI, &[44, 0, 48], 1017);
                step(f, Op::ToFloat, &[48, 320], 1018);
                step(f, Op::MulF, &[320, 52, 322], 1019);
                step(f, Op::MulF, &[322, 318, 323], 1020);
                step(f, Op::MakeVector, &[323, 627, 627, 118], 1021);
                step(f, Op::DivI, &[44, 0, 49], 1022);
                step(f, Op::SubI, &[49, 51, 52], 1023);
                step(f, Op::ToFloat, &[52, 321], 1024);
                step(f, Op::MulF, &[321, 52, 324], 1025);
                step(f, Op::ScaleV, &[113, 324, 119], 1026);
                step(f, Op::AddV, &[118, 119, 120], 1027);
                step(f, Op::AddV, &[112, 120, 121], 1028);
                step(f, Op::AddV, &[121, 122, 123], 1029);
                step(f, Op::SubV, &[121, 122, 124], 1030);
                step(f, Op::SphereTrace, &[123, 124, 50, 46, 125, 126, 325], 1031);
                step(f, Op::BreakVector, &[125, 327, 328, 329], 1032);
                step(f, Op::AddV, &[123, 127, 128], 1033);
                step(f, Op::AddV, &[124, 127, 129], 1034);
                step(f, Op::SphereTrace, &[128, 129, 50, 47, 130, 131, 326], 1035);
                step(f, Op::BreakVector, &[130, 330, 331, 332], 1036);
                step(f, Op::SubF, &[329, 332, 333], 1037);
                step(f, Op::AbsF, &[333, 334], 1038);
                step(f, Op::Select(ValueType::Float), &[46, 627, 629, 335], 1039);
                step(f, Op::AddF, &[334, 335, 340], 1040);
                step(f, Op::LengthV, &[120, 336], 1041);
                step(f, Op::RemapF, &[336, 627, 637, 627, 629, 78, 337], 1042);
                step(f, Op::MinF, &[329, 332, 338], 1043);
                step(f, Op::RemapF, &[338, 638, 637, 629, 628, 78, 339], 1044);
                step(f, Op::AddF, &[337, 339, 341], 1045);
                step(f, Op::AddF, &[340, 341, 342], 1046);
                step(f, Op::LessF, &[342, 319, 48], 1047);
                step(f, Op::And, &[46, 48, 49], 1048);
                step(f, Op::JumpIfFalse, &[49, 1054], 1049)
            }
            1049 => {
                step(f, Op::Copy(ValueType::Float), &[342, 319], 1050);
                step(f, Op::Copy(ValueType::Vec3), &[125, 116], 1051);
                step(f, Op::Copy(ValueType::Vec3), &[126, 117], 1052);
                step(f, Op::Copy(ValueType::Bool), &[78, 45], 1053);
                step(f, Op::Jump, &[1054], 1054)
            }
            1054 => {
                step(f, Op::Jump, &[1015], 1055)
            }
            1055 => {
                step(f, Op::JumpIfFalse, &[8, 1058], 1056)
            }
            1056 => {
                step(f, Op::DrawSphere, &[116, 50, 388], 1057);
                step(f, Op::Jump, &[1058], 1058)
            }
            1058 => {
                step(f, Op::Copy(ValueType::Vec3), &[116, 114], 1059);
                step(f, Op::Copy(ValueType::Vec3), &[117, 115], 1060);
                step(f, Op::Copy(ValueType::Bool), &[45, 44], 1061);
                step(f, Op::Jump, &[1062], 1062)
            }
            1062 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 41, 27], 1063);
                step(f, Op::BreakTransform, &[27, 93, 21, 94], 1064);
                step(f, Op::ArrayAt(Elem::Float), &[2, 41, 273], 1065);
                step(f, Op::SubF, &[629, 273, 274], 1066);
                step(f, Op::MaxF, &[274, 627, 275], 1067);
                step(f, Op::MulF, &[8, 5, 276], 1068);
                step(f, Op::MulF, &[275, 276, 277], 1069);
                step(f, Op::ScaleV, &[2, 277, 79], 1070);
                step(f, Op::SubV, &[114, 79, 92], 1071);
                step(f, Op::Select(ValueType::Vec3), &[44, 92, 93, 95], 1072);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 41, 28], 1073);
                step(f, Op::BreakTransform, &[28, 96, 23, 97], 1074);
                step(f, Op::Copy(ValueType::Vec3), &[93, 98], 1075);
                step(f, Op::Copy(ValueType::Vec3), &[95, 99], 1076);
                step(f, Op::Copy(ValueType::Vec3), &[96, 100], 1077);
                step(f, Op::Copy(ValueType::Float), &[43, 305], 1078);
                step(f, Op::Copy(ValueType::Float), &[45, 306], 1079);
                step(f, Op::Copy(ValueType::Vec3), &[384, 101], 1080);
                step(f, Op::SubV, &[99, 100, 102], 1081);
                step(f, Op::DeltaTime, &[307], 1082);
                step(f, Op::DivF, &[306, 307, 308], 1083);
                step(f, Op::ScaleV, &[102, 308, 103], 1084);
                step(f, Op::AddV, &[99, 103, 104], 1085);
                step(f, Op::AddV, &[100, 103, 105], 1086);
                step(f, Op::SubV, &[98, 105, 106], 1087);
                step(f, Op::FloatLerp, &[627, 629, 305, 309], 1088);
                step(f, Op::SubF, &[629, 309, 310], 1089);
                step(f, Op::ScaleV, &[106, 310, 107], 1090);
                step(f, Op::AddV, &[104, 107, 109], 1091);
                step(f, Op::MulF, &[305, 307, 311], 1092);
                step(f, Op::GreaterF, &[311, 627, 43], 1093);
                step(f, Op::DivF, &[309, 311, 312], 1094);
                step(f, Op::Select(ValueType::Float), &[43, 312, 629, 313], 1095);
                step(f, Op::ScaleV, &[102, 313, 108], 1096);
                step(f, Op::SubV, &[109, 108, 110], 1097);
                step(f, Op::Copy(ValueType::Vec3), &[110, 101], 1098);
                step(f, Op::Jump, &[1099], 1099)
            }
            1099 => {
                step(f, Op::BreakVector, &[101, 314, 315, 316], 1100);
                step(f, Op::ClampF, &[316, 54, 55, 317], 1101);
                step(f, Op::MakeVector, &[314, 315, 317, 111], 1102);
                step(f, Op::RotationFromNormal, &[115, 303, 304, 19], 1103);
                step(f, Op::PerFootRotationFactor, &[12, 85, 86, 300], 1104);
                step(f, Op::MulF, &[12, 300, 301], 1105);
                step(f, Op::SubF, &[629, 13, 282], 1106);
                step(f, Op::MulF, &[301, 282, 302], 1107);
                step(f, Op::QuatFromAxisAngle, &[387, 302, 18], 1108);
                step(f, Op::MulQ, &[19, 18, 20], 1109);
                step(f, Op::Select(ValueType::Quat), &[44, 20, 21, 22], 1110);
                step(f, Op::MakeTransform, &[111, 22, 385, 30], 1111);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 41, 30], 1112);
                step(f, Op::ArrayAt(Elem::Float), &[2, 41, 273], 1113);
                step(f, Op::SubF, &[629, 273, 274], 1114);
                step(f, Op::MaxF, &[274, 627, 275], 1115);
                step(f, Op::MulF, &[8, 5, 276], 1116);
                step(f, Op::MulF, &[275, 276, 277], 1117);
                step(f, Op::ScaleV, &[2, 277, 79], 1118);
                step(f, Op::SubV, &[114, 79, 92], 1119);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 41, 27], 1120);
                step(f, Op::BreakTransform, &[27, 93, 21, 94], 1121);
                step(f, Op::Select(ValueType::Vec3), &[44, 92, 93, 95], 1122);
                step(f, Op::MakeTransform, &[95, 88, 385, 29], 1123);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 41, 29], 1124);
                step(f, Op::JumpIfFalse, &[44, 1127], 1125)
            }
            1125 => {
                step(f, Op::Copy(ValueType::Bool), &[78, 7], 1126);
                step(f, Op::Jump, &[1127], 1127)
            }
            1127 => {
                step(f, Op::Copy(ValueType::Int), &[3, 53], 1128);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 53, 33], 1129);
                step(f, Op::GreaterF, &[18, 627, 53], 1130);
                step(f, Op::InterpolateTransform, &[2, 108, 19, 31], 1131);
                step(f, Op::Select(ValueType::Transform), &[53, 31, 2, 32], 1132);
                step(f, Op::MakeAbsolute, &[33, 32, 34], 1133);
                step(f, Op::BreakTransform, &[34, 132, 24, 133], 1134);
                step(f, Op::ClampSpatially, &[132, 384, 627, 58, 134], 1135);
                step(f, Op::SubF, &[629, 13, 348], 1136);
                step(f, Op::MulF, &[12, 348, 344], 1137);
                step(f, Op::LimitRotationAroundZ, &[24, 344, 84, 25], 1138);
                step(f, Op::MakeTransform, &[134, 25, 385, 35], 1139);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 53, 35], 1140);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 53, 50], 1141);
                step(f, Op::JumpIfFalse, &[50, 1195], 1142)
            }
            1142 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 53, 37], 1143);
                step(f, Op::BreakTransform, &[37, 135, 26, 136], 1144);
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 343], 1145);
                step(f, Op::SubF, &[629, 343, 345], 1146);
                step(f, Op::MulF, &[8, 5, 346], 1147);
                step(f, Op::MulF, &[345, 346, 347], 1148);
                step(f, Op::ScaleV, &[2, 347, 137], 1149);
                step(f, Op::AddV, &[135, 137, 138], 1150);
                step(f, Op::MakeTransform, &[138, 26, 385, 44], 1151);
                step(f, Op::Copy(ValueType::Transform), &[44, 45], 1152);
                step(f, Op::Copy(ValueType::Transform), &[108, 46], 1153);
                step(f, Op::BreakTransform, &[45, 166, 31, 167], 1154);
                step(f, Op::MakeVector, &[627, 627, 51, 168], 1155);
                step(f, Op::AddV, &[166, 168, 169], 1156);
                step(f, Op::SubV, &[166, 168, 170], 1157);
                step(f, Op::LineTrace, &[169, 170, 57, 171, 172, 375], 1158);
                step(f, Op::RotateVector, &[31, 387, 173], 1159);
                step(f, Op::FindQuatBetween, &[173, 172, 32], 1160);
                step(f, Op::MulQ, &[32, 31, 33], 1161);
                step(f, Op::MulF, &[49, 48, 376], 1162);
                step(f, Op::AddF, &[376, 57, 377], 1163);
                step(f, Op::NegF, &[377, 378], 1164);
                step(f, Op::MakeVector, &[627, 378, 627, 174], 1165);
                step(f, Op::RotateVector, &[33, 174, 176], 1166);
                step(f, Op::AddV, &[171, 176, 178], 1167);
                step(f, Op::AddV, &[178, 168, 180], 1168);
                step(f, Op::SubV, &[178, 168, 181], 1169);
                step(f, Op::LineTrace, &[180, 181, 58, 184, 185, 380], 1170);
                step(f, Op::BreakVector, &[184, 382, 383, 384], 1171);
                step(f, Op::BreakVector, &[178, 388, 389, 390], 1172);
                step(f, Op::SubF, &[384, 390, 394], 1173);
                step(f, Op::Select(ValueType::Float), &[58, 394, 627, 396], 1174);
                step(f, Op::AddF, &[53, 57, 379], 1175);
                step(f, Op::MakeVector, &[627, 379, 627, 175], 1176);
                step(f, Op::RotateVector, &[33, 175, 177], 1177);
                step(f, Op::AddV, &[171, 177, 179], 1178);
                step(f, Op::AddV, &[179, 168, 182], 1179);
                step(f, Op::SubV, &[179, 168, 183], 1180);
                step(f, Op::LineTrace, &[182, 183, 59, 186, 187, 381], 1181);
                step(f, Op::BreakVector, &[186, 385, 386, 387], 1182);
                step(f, Op::BreakVector, &[179, 391, 392, 393], 1183);
                step(f, Op::SubF, &[387, 393, 395], 1184);
                step(f, Op::Select(ValueType::Float), &[59, 395, 627, 397], 1185);
                step(f, Op::MaxF, &[396, 397, 398], 1186);
                step(f, Op::ClampF, &[398, 627, 56, 399], 1187);
                step(f, Op::MakeVector, &[627, 627, 399, 188], 1188);
                step(f, Op::AddV, &[171, 188, 189], 1189);
                step(f, Op::MakeTransform, &[189, 33, 385, 47], 1190);
                step(f, Op::Select(ValueType::Transform), &[57, 47, 45, 48], 1191);
                step(f, Op::Copy(ValueType::Transform), &[48, 46], 1192);
                step(f, Op::Jump, &[1193], 1193)
            }
            1193 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 53, 46], 1194);
                step(f, Op::Jump, &[1299], 1195)
            }
            1195 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 53, 49], 1196);
                step(f, Op::GreaterF, &[18, 627, 53], 1197);
                step(f, Op::InterpolateTransform, &[2, 108, 19, 31], 1198);
                step(f, Op::Select(ValueType::Transform), &[53, 31, 2, 32], 1199);
                step(f, Op::MakeAbsolute, &[49, 32, 50], 1200);
                step(f, Op::BreakTransform, &[50, 190, 34, 191], 1201);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 53, 37], 1202);
                step(f, Op::BreakTransform, &[37, 135, 26, 136], 1203);
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 343], 1204);
                step(f, Op::SubF, &[629, 343, 345], 1205);
                step(f, Op::MulF, &[8, 5, 346], 1206);
                step(f, Op::MulF, &[345, 346, 347], 1207);
                step(f, Op::ScaleV, &[2, 347, 137], 1208);
                step(f, Op::AddV, &[135, 137, 138], 1209);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 53, 51], 1210);
                step(f, Op::MakeAbsolute, &[51, 32, 52], 1211);
                step(f, Op::BreakTransform, &[52, 192, 35, 193], 1212);
                step(f, Op::ArrayAt(Elem::Float), &[3, 53, 400], 1213);
                step(f, Op::SubF, &[343, 400, 401], 1214);
                step(f, Op::DeltaTime, &[416], 1215);
                step(f, Op::DivF, &[45, 416, 402], 1216);
                step(f, Op::MulF, &[401, 402, 403], 1217);
                step(f, Op::AddF, &[400, 403, 404], 1218);
                step(f, Op::ClampF, &[404, 627, 629, 406], 1219);
                step(f, Op::AddF, &[343, 403, 405], 1220);
                step(f, Op::ClampF, &[405, 627, 629, 407], 1221);
                step(f, Op::AddF, &[406, 407, 408], 1222);
                step(f, Op::MulF, &[408, 628, 409], 1223);
                step(f, Op::SubF, &[629, 409, 410], 1224);
                step(f, Op::GreaterF, &[401, 627, 60], 1225);
                step(f, Op::SubF, &[407, 406, 411], 1226);
                step(f, Op::DivF, &[411, 401, 412], 1227);
                step(f, Op::Select(ValueType::Float), &[60, 412, 629, 413], 1228);
                step(f, Op::MulF, &[410, 413, 414], 1229);
                step(f, Op::MulF, &[72, 414, 415], 1230);
                step(f, Op::Copy(ValueType::Vec3), &[190, 194], 1231);
                step(f, Op::Copy(ValueType::Vec3), &[138, 195], 1232);
                step(f, Op::Copy(ValueType::Vec3), &[192, 196], 1233);
                step(f, Op::Copy(ValueType::Float), &[415, 417], 1234);
                step(f, Op::Copy(ValueType::Float), &[45, 418], 1235);
                step(f, Op::Copy(ValueType::Vec3), &[384, 197], 1236);
                step(f, Op::SubV, &[195, 196, 198], 1237);
                step(f, Op::DeltaTime, &[419], 1238);
                step(f, Op::DivF, &[418, 419, 420], 1239);
                step(f, Op::ScaleV, &[198, 420, 199], 1240);
                step(f, Op::AddV, &[195, 199, 200], 1241);
                step(f, Op::AddV, &[196, 199, 201], 1242);
                step(f, Op::SubV, &[194, 201, 202], 1243);
                step(f, Op::FloatLerp, &[627, 629, 417, 421], 1244);
                step(f, Op::SubF, &[629, 421, 422], 1245);
                step(f, Op::ScaleV, &[202, 422, 203], 1246);
                step(f, Op::AddV, &[200, 203, 205], 1247);
                step(f, Op::MulF, &[417, 419, 423], 1248);
                step(f, Op::GreaterF, &[423, 627, 61], 1249);
                step(f, Op::DivF, &[421, 423, 424], 1250);
                step(f, Op::Select(ValueType::Float), &[61, 424, 629, 425], 1251);
                step(f, Op::ScaleV, &[198, 425, 204], 1252);
                step(f, Op::SubV, &[205, 204, 206], 1253);
                step(f, Op::Copy(ValueType::Vec3), &[206, 197], 1254);
                step(f, Op::Jump, &[1255], 1255)
            }
            1255 => {
                step(f, Op::MakeTransform, &[197, 26, 385, 54], 1256);
                step(f, Op::Copy(ValueType::Transform), &[54, 55], 1257);
                step(f, Op::Copy(ValueType::Transform), &[108, 56], 1258);
                step(f, Op::BreakTransform, &[55, 207, 36, 208], 1259);
                step(f, Op::MakeVector, &[627, 627, 51, 209], 1260);
                step(f, Op::AddV, &[207, 209, 210], 1261);
                step(f, Op::SubV, &[207, 209, 211], 1262);
                step(f, Op::LineTrace, &[210, 211, 62, 212, 213, 426], 1263);
                step(f, Op::RotateVector, &[36, 387, 214], 1264);
                step(f, Op::FindQuatBetween, &[214, 213, 37], 1265);
                step(f, Op::MulQ, &[37, 36, 38], 1266);
                step(f, Op::MulF, &[49, 48, 427], 1267);
                step(f, Op::AddF, &[427, 57, 428], 1268);
                step(f, Op::NegF, &[428, 429], 1269);
                step(f, Op::MakeVector, &[627, 429, 627, 215], 1270);
                step(f, Op::RotateVector, &[38, 215, 217], 1271);
                step(f, Op::AddV, &[212, 217, 219], 1272);
                step(f, Op::AddV, &[219, 209, 221], 1273);
                step(f, Op::SubV, &[219, 209, 222], 1274);
                step(f, Op::LineTrace, &[221, 222, 63, 225, 226, 431], 1275);
                step(f, Op::BreakVector, &[225, 433, 434, 435], 1276);
                step(f, Op::BreakVector, &[219, 439, 440, 441], 1277);
                step(f, Op::SubF, &[435, 441, 445], 1278);
                step(f, Op::Select(ValueType::Float), &[63, 445, 627, 447], 1279);
                step(f, Op::AddF, &[53, 57, 430], 1280);
                step(f, Op::MakeVector, &[627, 430, 627, 216], 1281);
                step(f, Op::RotateVector, &[38, 216, 218], 1282);
                step(f, Op::AddV, &[212, 218, 220], 1283);
                step(f, Op::AddV, &[220, 209, 223], 1284);
                step(f, Op::SubV, &[220, 209, 224], 1285);
                step(f, Op::LineTrace, &[223, 224, 64, 227, 228, 432], 1286);
                step(f, Op::BreakVector, &[227, 436, 437, 438], 1287);
                step(f, Op::BreakVector, &[220, 442, 443, 444], 1288);
                step(f, Op::SubF, &[438, 444, 446], 1289);
                step(f, Op::Select(ValueType::Float), &[64, 446, 627, 448], 1290);
                step(f, Op::MaxF, &[447, 448, 449], 1291);
                step(f, Op::ClampF, &[449, 627, 56, 450], 1292);
                step(f, Op::MakeVector, &[627, 627, 450, 229], 1293);
                step(f, Op::AddV, &[212, 229, 230], 1294);
                step(f, Op::MakeTransform, &[230, 38, 385, 57], 1295);
                step(f, Op::Select(ValueType::Transform), &[62, 57, 55, 58], 1296);
                step(f, Op::Copy(ValueType::Transform), &[58, 56], 1297);
                step(f, Op::Jump, &[1298], 1298)
            }
            1298 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 53, 56], 1299);
                1299
            }
            1299 => {
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 343], 1300);
                step(f, Op::GreaterEqualF, &[343, 629, 51], 1301);
                step(f, Op::JumpIfFalse, &[51, 1361], 1302)
            }
            1302 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 53, 50], 1303);
                step(f, Op::JumpIfFalse, &[50, 1305], 1304)
            }
            1304 => {
                step(f, Op::Jump, &[1358], 1305)
            }
            1305 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 53, 59], 1306);
                step(f, Op::BreakTransform, &[59, 231, 39, 232], 1307);
                step(f, Op::Equals(Elem::Int), &[53, 65, 52], 1308);
                step(f, Op::Select(ValueType::Int), &[52, 66, 65, 54], 1309);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 54, 38], 1310);
                step(f, Op::BreakTransform, &[38, 139, 27, 140], 1311);
                step(f, Op::SubF, &[629, 13, 348], 1312);
                step(f, Op::MulF, &[12, 348, 349], 1313);
                step(f, Op::FootAvoidance, &[231, 139, 349, 52, 73, 141], 1314);
                step(f, Op::MakeTransform, &[141, 39, 385, 39], 1315);
                step(f, Op::Copy(ValueType::Transform), &[39, 40], 1316);
                step(f, Op::Copy(ValueType::Transform), &[108, 41], 1317);
                step(f, Op::BreakTransform, &[40, 142, 28, 143], 1318);
                step(f, Op::MakeVector, &[627, 627, 51, 144], 1319);
                step(f, Op::AddV, &[142, 144, 145], 1320);
                step(f, Op::SubV, &[142, 144, 146], 1321);
                step(f, Op::LineTrace, &[145, 146, 54, 147, 148, 350], 1322);
                step(f, Op::RotateVector, &[28, 387, 149], 1323);
                step(f, Op::FindQuatBetween, &[149, 148, 29], 1324);
                step(f, Op::MulQ, &[29, 28, 30], 1325);
                step(f, Op::MulF, &[49, 48, 351], 1326);
                step(f, Op::AddF, &[351, 57, 352], 1327);
                step(f, Op::NegF, &[352, 353], 1328);
                step(f, Op::MakeVector, &[627, 353, 627, 150], 1329);
                step(f, Op::RotateVector, &[30, 150, 152], 1330);
                step(f, Op::AddV, &[147, 152, 154], 1331);
                step(f, Op::AddV, &[154, 144, 156], 1332);
                step(f, Op::SubV, &[154, 144, 157], 1333);
                step(f, Op::LineTrace, &[156, 157, 55, 160, 161, 355], 1334);
                step(f, Op::BreakVector, &[160, 357, 358, 359], 1335);
                step(f, Op::BreakVector, &[154, 363, 364, 365], 1336);
                step(f, Op::SubF, &[359, 365, 369], 1337);
                step(f, Op::Select(ValueType::Float), &[55, 369, 627, 371], 1338);
                step(f, Op::AddF, &[53, 57, 354], 1339);
                step(f, Op::MakeVector, &[627, 354, 627, 151], 1340);
                step(f, Op::RotateVector, &[30, 151, 153], 1341);
                step(f, Op::AddV, &[147, 153, 155], 1342);
                step(f, Op::AddV, &[155, 144, 158], 1343);
                step(f, Op::SubV, &[155, 144, 159], 1344);
                step(f, Op::LineTrace, &[158, 159, 56, 162, 163, 356], 1345);
                step(f, Op::BreakVector, &[162, 360, 361, 362], 1346);
                step(f, Op::BreakVector, &[155, 366, 367, 368], 1347);
                step(f, Op::SubF, &[362, 368, 370], 1348);
                step(f, Op::Select(ValueType::Float), &[56, 370, 627, 372], 1349);
                step(f, Op::MaxF, &[371, 372, 373], 1350);
                step(f, Op::ClampF, &[373, 627, 56, 374], 1351);
                step(f, Op::MakeVector, &[627, 627, 374, 164], 1352);
                step(f, Op::AddV, &[147, 164, 165], 1353);
                step(f, Op::MakeTransform, &[165, 30, 385, 42], 1354);
                step(f, Op::Select(ValueType::Transform), &[54, 42, 40, 43], 1355);
                step(f, Op::Copy(ValueType::Transform), &[43, 41], 1356);
                step(f, Op::Jump, &[1357], 1357)
            }
            1357 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 53, 41], 1358);
                1358
            }
            1358 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 53, 36], 1359);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 53, 36], 1360);
                step(f, Op::Jump, &[1540], 1361)
            }
            1361 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 53, 36], 1362);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 53, 59], 1363);
                step(f, Op::ClampF, &[343, 627, 629, 451], 1364);
                step(f, Op::Copy(ValueType::Transform), &[36, 64], 1365);
                step(f, Op::Copy(ValueType::Transform), &[59, 65], 1366);
                step(f, Op::Copy(ValueType::Float), &[451, 469], 1367);
                step(f, Op::Copy(ValueType::Transform), &[108, 66], 1368);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[3, 2], 1369);
                step(f, Op::ArrayReset(Elem::Vec3), &[2], 1370);
                step(f, Op::BreakTransform, &[64, 249, 44, 250], 1371);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 249], 1372);
                step(f, Op::BreakTransform, &[64, 249, 44, 250], 1373);
                step(f, Op::UnitV, &[2, 248], 1374);
                step(f, Op::LengthV, &[2, 470], 1375);
                step(f, Op::RemapF, &[470, 627, 59, 627, 60, 78, 471], 1376);
                step(f, Op::ScaleV, &[248, 471, 253], 1377);
                step(f, Op::SubV, &[249, 253, 259], 1378);
                step(f, Op::MakeVector, &[627, 627, 62, 257], 1379);
                step(f, Op::AddV, &[259, 257, 261], 1380);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 261], 1381);
                step(f, Op::BreakTransform, &[64, 249, 44, 250], 1382);
                step(f, Op::UnitV, &[2, 248], 1383);
                step(f, Op::LengthV, &[2, 470], 1384);
                step(f, Op::RemapF, &[470, 627, 59, 627, 60, 78, 471], 1385);
                step(f, Op::ScaleV, &[248, 471, 253], 1386);
                step(f, Op::SubV, &[249, 253, 259], 1387);
                step(f, Op::MakeVector, &[627, 627, 62, 257], 1388);
                step(f, Op::AddV, &[259, 257, 261], 1389);
                step(f, Op::RemapF, &[470, 627, 59, 627, 64, 78, 473], 1390);
                step(f, Op::MakeVector, &[627, 627, 473, 255], 1391);
                step(f, Op::AddV, &[261, 255, 265], 1392);
                step(f, Op::BreakTransform, &[65, 251, 45, 252], 1393);
                step(f, Op::BreakVector, &[251, 478, 479, 480], 1394);
                step(f, Op::BreakVector, &[249, 475, 476, 477], 1395);
                step(f, Op::SubF, &[480, 477, 481], 1396);
                step(f, Op::MaxF, &[481, 627, 483], 1397);
                step(f, Op::MulF, &[483, 66, 487], 1398);
                step(f, Op::AbsF, &[481, 485], 1399);
                step(f, Op::RemapF, &[485, 627, 69, 627, 68, 78, 486], 1400);
                step(f, Op::AddF, &[487, 486, 489], 1401);
                step(f, Op::MakeVector, &[627, 627, 489, 263], 1402);
                step(f, Op::AddV, &[265, 263, 267], 1403);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 267], 1404);
                step(f, Op::BreakTransform, &[64, 249, 44, 250], 1405);
                step(f, Op::UnitV, &[2, 248], 1406);
                step(f, Op::LengthV, &[2, 470], 1407);
                step(f, Op::RemapF, &[470, 627, 59, 627, 60, 78, 471], 1408);
                step(f, Op::ScaleV, &[248, 471, 253], 1409);
                step(f, Op::SubV, &[249, 253, 259], 1410);
                step(f, Op::MakeVector, &[627, 627, 62, 257], 1411);
                step(f, Op::AddV, &[259, 257, 261], 1412);
                step(f, Op::RemapF, &[470, 627, 59, 627, 64, 78, 473], 1413);
                step(f, Op::MakeVector, &[627, 627, 473, 255], 1414);
                step(f, Op::AddV, &[261, 255, 265], 1415);
                step(f, Op::BreakTransform, &[65, 251, 45, 252], 1416);
                step(f, Op::BreakVector, &[251, 478, 479, 480], 1417);
                step(f, Op::BreakVector, &[249, 475, 476, 477], 1418);
                step(f, Op::SubF, &[480, 477, 481], 1419);
                step(f, Op::MaxF, &[481, 627, 483], 1420);
                step(f, Op::MulF, &[483, 66, 487], 1421);
                step(f, Op::AbsF, &[481, 485], 1422);
                step(f, Op::RemapF, &[485, 627, 69, 627, 68, 78, 486], 1423);
                step(f, Op::AddF, &[487, 486, 489], 1424);
                step(f, Op::MakeVector, &[627, 627, 489, 263], 1425);
                step(f, Op::AddV, &[265, 263, 267], 1426);
                step(f, Op::RemapF, &[470, 627, 59, 627, 61, 78, 472], 1427);
                step(f, Op::ScaleV, &[248, 472, 254], 1428);
                step(f, Op::AddV, &[251, 254, 260], 1429);
                step(f, Op::MakeVector, &[627, 627, 63, 258], 1430);
                step(f, Op::AddV, &[260, 258, 262], 1431);
                step(f, Op::RemapF, &[470, 627, 59, 627, 65, 78, 474], 1432);
                step(f, Op::MakeVector, &[627, 627, 474, 256], 1433);
                step(f, Op::AddV, &[262, 256, 266], 1434);
                step(f, Op::NegF, &[481, 482], 1435);
                step(f, Op::MaxF, &[482, 627, 484], 1436);
                step(f, Op::MulF, &[484, 67, 488], 1437);
                step(f, Op::AddF, &[488, 486, 490], 1438);
                step(f, Op::MakeVector, &[627, 627, 490, 264], 1439);
                step(f, Op::AddV, &[266, 264, 268], 1440);
                step(f, Op::LerpV, &[267, 268, 628, 269], 1441);
                step(f, Op::GetTransform, &[36, 65, 78, 67], 1442);
                step(f, Op::BreakTransform, &[67, 270, 46, 271], 1443);
                step(f, Op::BreakVector, &[270, 500, 501, 502], 1444);
                step(f, Op::SubF, &[629, 13, 494], 1445);
                step(f, Op::MulF, &[70, 494, 495], 1446);
                step(f, Op::MulF, &[12, 495, 496], 1447);
                step(f, Op::QuatFromAxisAngle, &[387, 496, 47], 1448);
                step(f, Op::SubV, &[269, 270, 272], 1449);
                step(f, Op::BreakVector, &[272, 491, 492, 493], 1450);
                step(f, Op::MakeVector, &[491, 492, 627, 273], 1451);
                step(f, Op::RotateVector, &[47, 273, 274], 1452);
                step(f, Op::BreakVector, &[274, 497, 498, 499], 1453);
                step(f, Op::AddF, &[500, 497, 506], 1454);
                step(f, Op::AddF, &[501, 498, 507], 1455);
                step(f, Op::BreakVector, &[269, 503, 504, 505], 1456);
                step(f, Op::MakeVector, &[506, 507, 505, 275], 1457);
                step(f, Op::DistanceV, &[249, 251, 508], 1458);
                step(f, Op::RemapF, &[508, 632, 639, 627, 629, 78, 509], 1459);
                step(f, Op::LerpV, &[269, 275, 509, 276], 1460);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 276], 1461);
                step(f, Op::BreakTransform, &[65, 251, 45, 252], 1462);
                step(f, Op::UnitV, &[2, 248], 1463);
                step(f, Op::LengthV, &[2, 470], 1464);
                step(f, Op::RemapF, &[470, 627, 59, 627, 61, 78, 472], 1465);
                step(f, Op::ScaleV, &[248, 472, 254], 1466);
                step(f, Op::AddV, &[251, 254, 260], 1467);
                step(f, Op::MakeVector, &[627, 627, 63, 258], 1468);
                step(f, Op::AddV, &[260, 258, 262], 1469);
                step(f, Op::RemapF, &[470, 627, 59, 627, 65, 78, 474], 1470);
                step(f, Op::MakeVector, &[627, 627, 474, 256], 1471);
                step(f, Op::AddV, &[262, 256, 266], 1472);
                step(f, Op::BreakVector, &[251, 478, 479, 480], 1473);
                step(f, Op::BreakTransform, &[64, 249, 44, 250], 1474);
                step(f, Op::BreakVector, &[249, 475, 476, 477], 1475);
                step(f, Op::SubF, &[480, 477, 481], 1476);
                step(f, Op::NegF, &[481, 482], 1477);
                step(f, Op::MaxF, &[482, 627, 484], 1478);
                step(f, Op::MulF, &[484, 67, 488], 1479);
                step(f, Op::AbsF, &[481, 485], 1480);
                step(f, Op::RemapF, &[485, 627, 69, 627, 68, 78, 486], 1481);
                step(f, Op::AddF, &[488, 486, 490], 1482);
                step(f, Op::MakeVector, &[627, 627, 490, 264], 1483);
                step(f, Op::AddV, &[266, 264, 268], 1484);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 268], 1485);
                step(f, Op::BreakTransform, &[65, 251, 45, 252], 1486);
                step(f, Op::UnitV, &[2, 248], 1487);
                step(f, Op::LengthV, &[2, 470], 1488);
                step(f, Op::RemapF, &[470, 627, 59, 627, 61, 78, 472], 1489);
                step(f, Op::ScaleV, &[248, 472, 254], 1490);
                step(f, Op::AddV, &[251, 254, 260], 1491);
                step(f, Op::MakeVector, &[627, 627, 63, 258], 1492);
                step(f, Op::AddV, &[260, 258, 262], 1493);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 262], 1494);
                step(f, Op::BreakTransform, &[65, 251, 45, 252], 1495);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 251], 1496);
                step(f, Op::JumpIfFalse, &[8, 1499], 1497)
            }
            1497 => {
                step(f, Op::DrawSpline, &[2, 65, 68, 628, 389], 1498);
                step(f, Op::Jump, &[1499], 1499)
            }
            1499 => {
                step(f, Op::Spline, &[2, 469, 65, 277, 278], 1500);
                step(f, Op::BreakTransform, &[64, 249, 44, 250], 1501);
                step(f, Op::BreakTransform, &[65, 251, 45, 252], 1502);
                step(f, Op::SlerpQ, &[44, 45, 469, 48], 1503);
                step(f, Op::MulF, &[469, 640, 510], 1504);
                step(f, Op::SinF, &[510, 511], 1505);
                step(f, Op::MulF, &[511, 71, 512], 1506);
                step(f, Op::SlerpQ, &[48, 88, 512, 49], 1507);
                step(f, Op::MakeTransform, &[277, 49, 385, 68], 1508);
                step(f, Op::Copy(ValueType::Transform), &[68, 66], 1509);
                step(f, Op::Jump, &[1510], 1510)
            }
            1510 => {
                step(f, Op::BreakTransform, &[66, 233, 40, 234], 1511);
                step(f, Op::Equals(Elem::Int), &[53, 65, 52], 1512);
                step(f, Op::Select(ValueType::Int), &[52, 66, 65, 54], 1513);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 54, 38], 1514);
                step(f, Op::BreakTransform, &[38, 139, 27, 140], 1515);
                step(f, Op::SubF, &[629, 13, 348], 1516);
                step(f, Op::MulF, &[12, 348, 349], 1517);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 54, 65], 1518);
                step(f, Op::Select(ValueType::Float), &[65, 74, 627, 454], 1519);
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 343], 1520);
                step(f, Op::ClampF, &[343, 627, 629, 451], 1521);
                step(f, Op::MulF, &[451, 640, 452], 1522);
                step(f, Op::SinF, &[452, 453], 1523);
                step(f, Op::MulF, &[453, 453, 455], 1524);
                step(f, Op::MulF, &[454, 455, 456], 1525);
                step(f, Op::AddF, &[73, 456, 457], 1526);
                step(f, Op::FootAvoidance, &[233, 139, 349, 52, 457, 235], 1527);
                step(f, Op::SubV, &[235, 233, 236], 1528);
                step(f, Op::LengthV, &[236, 458], 1529);
                step(f, Op::AddF, &[458, 456, 459], 1530);
                step(f, Op::DivF, &[458, 459, 460], 1531);
                step(f, Op::ScaleV, &[236, 460, 237], 1532);
                step(f, Op::AddV, &[233, 237, 238], 1533);
                step(f, Op::SubF, &[629, 111, 461], 1534);
                step(f, Op::MulF, &[3, 461, 462], 1535);
                step(f, Op::MulF, &[462, 455, 463], 1536);
                step(f, Op::MakeVector, &[627, 627, 463, 239], 1537);
                step(f, Op::AddV, &[238, 239, 240], 1538);
                step(f, Op::MakeTransform, &[240, 40, 385, 60], 1539);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 53, 60], 1540);
                1540
            }
            1540 => {
                step(f, Op::GreaterF, &[18, 627, 53], 1541);
                step(f, Op::JumpIfFalse, &[53, 1558], 1542)
            }
            1542 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 53, 61], 1543);
                step(f, Op::BreakTransform, &[61, 241, 41, 242], 1544);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 53, 62], 1545);
                step(f, Op::BreakTransform, &[62, 243, 42, 244], 1546);
                step(f, Op::MulF, &[18, 18, 464], 1547);
                step(f, Op::LerpV, &[241, 243, 464, 245], 1548);
                step(f, Op::SubF, &[629, 18, 465], 1549);
                step(f, Op::MulF, &[18, 465, 466], 1550);
                step(f, Op::MulF, &[113, 632, 467], 1551);
                step(f, Op::MulF, &[466, 467, 468], 1552);
                step(f, Op::MakeVector, &[627, 627, 468, 246], 1553);
                step(f, Op::AddV, &[245, 246, 247], 1554);
                step(f, Op::SlerpQ, &[41, 42, 18, 43], 1555);
                step(f, Op::MakeTransform, &[247, 43, 385, 63], 1556);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 53, 63], 1557);
                step(f, Op::Jump, &[1558], 1558)
            }
            1558 => {
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 343], 1559);
                step(f, Op::GreaterEqualF, &[343, 629, 51], 1560);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 53, 51], 1561);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 53, 37], 1562);
                step(f, Op::BreakTransform, &[37, 135, 26, 136], 1563);
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 343], 1564);
                step(f, Op::SubF, &[629, 343, 345], 1565);
                step(f, Op::MulF, &[8, 5, 346], 1566);
                step(f, Op::MulF, &[345, 346, 347], 1567);
                step(f, Op::ScaleV, &[2, 347, 137], 1568);
                step(f, Op::AddV, &[135, 137, 138], 1569);
                step(f, Op::MakeTransform, &[138, 88, 385, 53], 1570);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 53, 53], 1571);
                step(f, Op::Copy(ValueType::Bone), &[0, 17], 1572);
                step(f, Op::Copy(ValueType::Int), &[3, 55], 1573);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 55, 69], 1574);
                step(f, Op::BreakTransform, &[69, 279, 50, 280], 1575);
                step(f, Op::MakeVector, &[627, 627, 46, 289], 1576);
                step(f, Op::AddV, &[279, 289, 290], 1577);
                step(f, Op::GetTransform, &[17, 65, 78, 71], 1578);
                step(f, Op::BreakTransform, &[71, 284, 52, 285], 1579);
                step(f, Op::MakeTransform, &[290, 52, 385, 73], 1580);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 55, 20], 1581);
                step(f, Op::GetTransform, &[20, 65, 78, 72], 1582);
                step(f, Op::BreakTransform, &[72, 286, 53, 287], 1583);
                step(f, Op::SubV, &[286, 284, 288], 1584);
                step(f, Op::AddV, &[290, 288, 291], 1585);
                step(f, Op::FootPivots, &[290, 291, 48, 47, 46, 49, 292, 293, 294], 1586);
                step(f, Op::GetParent, &[17, 18], 1587);
                step(f, Op::GetParent, &[18, 19], 1588);
                step(f, Op::GetTransform, &[19, 65, 79, 70], 1589);
                step(f, Op::BreakTransform, &[70, 281, 51, 282], 1590);
                step(f, Op::SubV, &[279, 281, 283], 1591);
                step(f, Op::DotV, &[283, 388, 513], 1592);
                step(f, Op::RemapF, &[513, 76, 75, 77, 627, 78, 516], 1593);
                step(f, Op::LengthV, &[2, 514], 1594);
                step(f, Op::RemapF, &[514, 627, 83, 627, 629, 78, 515], 1595);
                step(f, Op::MulF, &[516, 515, 517], 1596);
                step(f, Op::QuatFromAxisAngle, &[390, 517, 54], 1597);
                step(f, Op::RotateAroundPoint, &[73, 292, 54, 74], 1598);
                step(f, Op::SubV, &[293, 292, 295], 1599);
                step(f, Op::RotateVector, &[54, 295, 296], 1600);
                step(f, Op::AddV, &[292, 296, 297], 1601);
                step(f, Op::RemapF, &[513, 78, 76, 79, 627, 78, 518], 1602);
                step(f, Op::MulF, &[518, 515, 519], 1603);
                step(f, Op::QuatFromAxisAngle, &[390, 519, 55], 1604);
                step(f, Op::RotateAroundPoint, &[74, 297, 55, 75], 1605);
                step(f, Op::RemapF, &[513, 80, 81, 627, 82, 78, 520], 1606);
                step(f, Op::MulF, &[520, 515, 521], 1607);
                step(f, Op::QuatFromAxisAngle, &[390, 521, 56], 1608);
                step(f, Op::RotateAroundPoint, &[75, 294, 56, 76], 1609);
                step(f, Op::SubF, &[629, 13, 522], 1610);
                step(f, Op::MulF, &[12, 522, 523], 1611);
                step(f, Op::LimitRotationAroundZ, &[50, 523, 84, 57], 1612);
                step(f, Op::RotateAroundPoint, &[76, 279, 57, 77], 1613);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 55, 77], 1614);
                step(f, Op::JumpIfFalse, &[8, 1671], 1615)
            }
            1615 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 55, 69], 1616);
                step(f, Op::BreakTransform, &[69, 279, 50, 280], 1617);
                step(f, Op::MakeVector, &[627, 627, 46, 289], 1618);
                step(f, Op::AddV, &[279, 289, 290], 1619);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 55, 20], 1620);
                step(f, Op::GetTransform, &[20, 65, 78, 72], 1621);
                step(f, Op::BreakTransform, &[72, 286, 53, 287], 1622);
                step(f, Op::GetTransform, &[17, 65, 78, 71], 1623);
                step(f, Op::BreakTransform, &[71, 284, 52, 285], 1624);
                step(f, Op::SubV, &[286, 284, 288], 1625);
                step(f, Op::AddV, &[290, 288, 291], 1626);
                step(f, Op::FootPivots, &[290, 291, 48, 47, 46, 49, 292, 293, 294], 1627);
                step(f, Op::DrawPoint, &[294, 633, 390], 1628);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 55, 69], 1629);
                step(f, Op::BreakTransform, &[69, 279, 50, 280], 1630);
                step(f, Op::MakeVector, &[627, 627, 46, 289], 1631);
                step(f, Op::AddV, &[279, 289, 290], 1632);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 55, 20], 1633);
                step(f, Op::GetTransform, &[20, 65, 78, 72], 1634);
                step(f, Op::BreakTransform, &[72, 286, 53, 287], 1635);
                step(f, Op::GetTransform, &[17, 65, 78, 71], 1636);
                step(f, Op::BreakTransform, &[71, 284, 52, 285], 1637);
                step(f, Op::SubV, &[286, 284, 288], 1638);
                step(f, Op::AddV, &[290, 288, 291], 1639);
                step(f, Op::FootPivots, &[290, 291, 48, 47, 46, 49, 292, 293, 294], 1640);
                step(f, Op::DrawPoint, &[292, 633, 388], 1641);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 55, 69], 1642);
                step(f, Op::BreakTransform, &[69, 279, 50, 280], 1643);
                step(f, Op::MakeVector, &[627, 627, 46, 289], 1644);
                step(f, Op::AddV, &[279, 289, 290], 1645);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 55, 20], 1646);
                step(f, Op::GetTransform, &[20, 65, 78, 72], 1647);
                step(f, Op::BreakTransform, &[72, 286, 53, 287], 1648);
                step(f, Op::GetTransform, &[17, 65, 78, 71], 1649);
                step(f, Op::BreakTransform, &[71, 284, 52, 285], 1650);
                step(f, Op::SubV, &[286, 284, 288], 1651);
                step(f, Op::AddV, &[290, 288, 291], 1652);
                step(f, Op::FootPivots, &[290, 291, 48, 47, 46, 49, 292, 293, 294], 1653);
                step(f, Op::GetParent, &[17, 18], 1654);
                step(f, Op::GetParent, &[18, 19], 1655);
                step(f, Op::GetTransform, &[19, 65, 79, 70], 1656);
                step(f, Op::BreakTransform, &[70, 281, 51, 282], 1657);
                step(f, Op::SubV, &[279, 281, 283], 1658);
                step(f, Op::DotV, &[283, 388, 513], 1659);
                step(f, Op::RemapF, &[513, 76, 75, 77, 627, 78, 516], 1660);
                step(f, Op::LengthV, &[2, 514], 1661);
                step(f, Op::RemapF, &[514, 627, 83, 627, 629, 78, 515], 1662);
                step(f, Op::MulF, &[516, 515, 517], 1663);
                step(f, Op::QuatFromAxisAngle, &[390, 517, 54], 1664);
                step(f, Op::SubV, &[293, 292, 295], 1665);
                step(f, Op::RotateVector, &[54, 295, 296], 1666);
                step(f, Op::AddV, &[292, 296, 297], 1667);
                step(f, Op::DrawPoint, &[297, 633, 387], 1668);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 55, 69], 1669);
                step(f, Op::DrawTransform, &[69, 639, 628], 1670);
                step(f, Op::Jump, &[1671], 1671)
            }
            1671 => {
                step(f, Op::Jump, &[961], 1672)
            }
            1672 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1673);
                step(f, Op::Copy(ValueType::Int), &[65, 5], 1674);
                1674
            }
            1674 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 5, 1, 6, 7, 1729], 1675)
            }
            1675 => {
                step(f, Op::Copy(ValueType::Bone), &[1, 21], 1676);
                step(f, Op::Copy(ValueType::Int), &[6, 56], 1677);
                step(f, Op::GetParent, &[21, 22], 1678);
                step(f, Op::GetParent, &[22, 23], 1679);
                step(f, Op::GetParent, &[23, 24], 1680);
                step(f, Op::GetTransform, &[24, 65, 79, 78], 1681);
                step(f, Op::BreakTransform, &[78, 298, 58, 299], 1682);
                step(f, Op::LengthV, &[1, 525], 1683);
                step(f, Op::ClavicleOffset, &[10, 525, 89, 92, 526], 1684);
                step(f, Op::MakeVector, &[627, 627, 526, 300], 1685);
                step(f, Op::AddV, &[298, 300, 301], 1686);
                step(f, Op::MakeTransform, &[301, 58, 385, 79], 1687);
                step(f, Op::SetTransform, &[24, 79, 65, 78, 629], 1688);
                step(f, Op::GetParent, &[21, 22], 1689);
                step(f, Op::GetParent, &[22, 23], 1690);
                step(f, Op::GetTransform, &[21, 65, 79, 80], 1691);
                step(f, Op::GetTransform, &[23, 65, 79, 81], 1692);
                step(f, Op::BreakTransform, &[81, 302, 60, 303], 1693);
                step(f, Op::Equals(Elem::Int), &[56, 65, 66], 1694);
                step(f, Op::Select(ValueType::Int), &[66, 66, 65, 57], 1695);
                step(f, Op::ArrayAt(Elem::Float), &[0, 57, 524], 1696);
                step(f, Op::ArmSwingRotation, &[524, 1, 0, 90, 635, 641, 629, 89, 87, 88, 635, 635, 629, 527], 1697);
                step(f, Op::QuatFromAxisAngle, &[390, 527, 59], 1698);
                step(f, Op::RotateAroundPoint, &[80, 302, 59, 82], 1699);
                step(f, Op::BreakTransform, &[82, 304, 61, 305], 1700);
                step(f, Op::LengthV, &[1, 525], 1701);
                step(f, Op::RemapF, &[525, 627, 89, 627, 91, 78, 528], 1702);
                step(f, Op::MakeVector, &[627, 627, 528, 306], 1703);
                step(f, Op::AddV, &[304, 306, 307], 1704);
                step(f, Op::MakeTransform, &[307, 61, 385, 83], 1705);
                step(f, Op::Select(ValueType::Vec3), &[66, 391, 390, 309], 1706);
                step(f, Op::Select(ValueType::Vec3), &[66, 388, 392, 310], 1707);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 56, 308], 1708);
                step(f, Op::TwoBoneIK, &[23, 22, 21, 83, 309, 310, 308, 65, 629, 79, 642, 643, 78, 67, 529], 1709);
                step(f, Op::JumpIfFalse, &[8, 1728], 1710)
            }
            1710 => {
                step(f, Op::GetParent, &[21, 22], 1711);
                step(f, Op::GetParent, &[22, 23], 1712);
                step(f, Op::GetTransform, &[23, 65, 79, 81], 1713);
                step(f, Op::BreakTransform, &[81, 302, 60, 303], 1714);
                step(f, Op::GetTransform, &[21, 65, 79, 80], 1715);
                step(f, Op::Equals(Elem::Int), &[56, 65, 66], 1716);
                step(f, Op::Select(ValueType::Int), &[66, 66, 65, 57], 1717);
                step(f, Op::ArrayAt(Elem::Float), &[0, 57, 524], 1718);
                step(f, Op::ArmSwingRotation, &[524, 1, 0, 90, 635, 641, 629, 89, 87, 88, 635, 635, 629, 527], 1719);
                step(f, Op::QuatFromAxisAngle, &[390, 527, 59], 1720);
                step(f, Op::RotateAroundPoint, &[80, 302, 59, 82], 1721);
                step(f, Op::BreakTransform, &[82, 304, 61, 305], 1722);
                step(f, Op::LengthV, &[1, 525], 1723);
                step(f, Op::RemapF, &[525, 627, 89, 627, 91, 78, 528], 1724);
                step(f, Op::MakeVector, &[627, 627, 528, 306], 1725);
                step(f, Op::AddV, &[304, 306, 307], 1726);
                step(f, Op::DrawLine, &[302, 307, 628, 388], 1727);
                step(f, Op::Jump, &[1728], 1728)
            }
            1728 => {
                step(f, Op::Jump, &[1674], 1729)
            }
            1729 => {
                step(f, Op::Copy(ValueType::Float), &[627, 532], 1730);
                step(f, Op::Copy(ValueType::Float), &[636, 533], 1731);
                step(f, Op::Copy(ValueType::Bool), &[79, 68], 1732);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 10], 1733);
                step(f, Op::Copy(ValueType::Int), &[65, 58], 1734);
                step(f, Op::MakeVector, &[627, 627, 51, 313], 1735);
                1735
            }
            1735 => {
                step(f, Op::ForEachNext(Elem::Transform), &[10, 58, 84, 59, 60, 1748], 1736)
            }
            1736 => {
                step(f, Op::BreakTransform, &[84, 311, 62, 312], 1737);
                step(f, Op::AddV, &[311, 313, 314], 1738);
                step(f, Op::SubV, &[311, 313, 315], 1739);
                step(f, Op::SphereTrace, &[314, 315, 50, 69, 316, 317, 534], 1740);
                step(f, Op::BreakVector, &[316, 535, 536, 537], 1741);
                step(f, Op::LessF, &[537, 533, 70], 1742);
                step(f, Op::And, &[69, 70, 71], 1743);
                step(f, Op::JumpIfFalse, &[71, 1747], 1744)
            }
            1744 => {
                step(f, Op::Copy(ValueType::Float), &[537, 533], 1745);
                step(f, Op::Copy(ValueType::Bool), &[78, 68], 1746);
                step(f, Op::Jump, &[1747], 1747)
            }
            1747 => {
                step(f, Op::Jump, &[1735], 1748)
            }
            1748 => {
                step(f, Op::Select(ValueType::Float), &[68, 533, 627, 538], 1749);
                step(f, Op::ClampF, &[538, 54, 55, 539], 1750);
                step(f, Op::Copy(ValueType::Float), &[539, 532], 1751);
                step(f, Op::Jump, &[1752], 1752)
            }
            1752 => {
                step(f, Op::SubF, &[629, 18, 531], 1753);
                step(f, Op::MulF, &[532, 531, 540], 1754);
                step(f, Op::FloatLerp, &[14, 540, 44, 541], 1755);
                step(f, Op::Select(ValueType::Float), &[1, 540, 541, 542], 1756);
                step(f, Op::Copy(ValueType::Float), &[542, 14], 1757);
                step(f, Op::GetTransform, &[37, 65, 78, 89], 1758);
                step(f, Op::BreakTransform, &[89, 330, 69, 331], 1759);
                step(f, Op::PelvisLean, &[1, 94, 99, 100, 558, 559], 1760);
                step(f, Op::LengthV, &[2, 530], 1761);
                step(f, Op::RemapF, &[530, 627, 94, 627, 93, 78, 543], 1762);
                step(f, Op::MulF, &[10, 644, 544], 1763);
                step(f, Op::SinF, &[544, 545], 1764);
                step(f, Op::MulF, &[543, 545, 546], 1765);
                step(f, Op::MulF, &[546, 531, 547], 1766);
                step(f, Op::AddF, &[547, 14, 548], 1767);
                step(f, Op::MulF, &[3, 111, 549], 1768);
                step(f, Op::SubF, &[548, 549, 550], 1769);
                step(f, Op::MakeVector, &[627, 559, 550, 332], 1770);
                step(f, Op::AddV, &[330, 332, 333], 1771);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 85], 1772);
                step(f, Op::BreakTransform, &[85, 318, 63, 319], 1773);
                step(f, Op::BreakVector, &[318, 560, 561, 562], 1774);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 66, 86], 1775);
                step(f, Op::BreakTransform, &[86, 320, 64, 321], 1776);
                step(f, Op::BreakVector, &[320, 563, 564, 565], 1777);
                step(f, Op::SubF, &[562, 565, 566], 1778);
                step(f, Op::PelvisSideLean, &[566, 101, 102, 567], 1779);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 65, 87], 1780);
                step(f, Op::BreakTransform, &[87, 324, 65, 325], 1781);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 66, 88], 1782);
                step(f, Op::BreakTransform, &[88, 326, 66, 327], 1783);
                step(f, Op::SlerpQ, &[65, 66, 628, 67], 1784);
                step(f, Op::EulerFromQuat, &[67, 65, 328], 1785);
                step(f, Op::BreakVector, &[328, 554, 555, 556], 1786);
                step(f, Op::RemapF, &[530, 95, 94, 627, 96, 78, 552], 1787);
                step(f, Op::SubV, &[318, 320, 322], 1788);
                step(f, Op::RotateVector, &[0, 388, 323], 1789);
                step(f, Op::DotV, &[322, 323, 551], 1790);
                step(f, Op::MulF, &[552, 551, 553], 1791);
                step(f, Op::AddF, &[556, 553, 557], 1792);
                step(f, Op::MakeVector, &[558, 567, 557, 329], 1793);
                step(f, Op::QuatFromEuler, &[329, 65, 68], 1794);
                step(f, Op::MakeTransform, &[333, 68, 385, 90], 1795);
                step(f, Op::SetTransform, &[38, 90, 65, 78, 629], 1796);
                step(f, Op::GetTransform, &[39, 66, 78, 91], 1797);
                step(f, Op::BreakTransform, &[91, 334, 73, 335], 1798);
                step(f, Op::LengthV, &[2, 530], 1799);
                step(f, Op::RemapF, &[530, 95, 94, 627, 96, 78, 552], 1800);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 85], 1801);
                step(f, Op::BreakTransform, &[85, 318, 63, 319], 1802);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 66, 86], 1803);
                step(f, Op::BreakTransform, &[86, 320, 64, 321], 1804);
                step(f, Op::SubV, &[318, 320, 322], 1805);
                step(f, Op::RotateVector, &[0, 388, 323], 1806);
                step(f, Op::DotV, &[322, 323, 551], 1807);
                step(f, Op::MulF, &[552, 551, 553], 1808);
                step(f, Op::QuatFromAxisAngle, &[387, 553, 70], 1809);
                step(f, Op::DivF, &[97, 633, 568], 1810);
                step(f, Op::QuatScale, &[70, 568, 71], 1811);
                step(f, Op::MulQ, &[73, 71, 77], 1812);
                step(f, Op::MakeTransform, &[334, 77, 385, 95], 1813);
                step(f, Op::SetTransform, &[40, 95, 66, 78, 629], 1814);
                step(f, Op::GetTransform, &[41, 66, 78, 92], 1815);
                step(f, Op::BreakTransform, &[92, 336, 74, 337], 1816);
                step(f, Op::LengthV, &[2, 530], 1817);
                step(f, Op::RemapF, &[530, 95, 94, 627, 96, 78, 552], 1818);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 85], 1819);
                step(f, Op::BreakTransform, &[85, 318, 63, 319], 1820);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 66, 86], 1821);
                step(f, Op::BreakTransform, &[86, 320, 64, 321], 1822);
                step(f, Op::SubV, &[318, 320, 322], 1823);
                step(f, Op::RotateVector, &[0, 388, 323], 1824);
                step(f, Op::DotV, &[322, 323, 551], 1825);
                step(f, Op::MulF, &[552, 551, 553], 1826);
                step(f, Op::QuatFromAxisAngle, &[387, 553, 70], 1827);
                step(f, Op::DivF, &[97, 633, 568], 1828);
                step(f, Op::QuatScale, &[70, 568, 71], 1829);
                step(f, Op::MulQ, &[74, 71, 78], 1830);
                step(f, Op::MakeTransform, &[336, 78, 385, 96], 1831);
                step(f, Op::SetTransform, &[42, 96, 66, 78, 629], 1832);
                step(f, Op::GetTransform, &[43, 66, 78, 93], 1833);
                step(f, Op::BreakTransform, &[93, 338, 75, 339], 1834);
                step(f, Op::LengthV, &[2, 530], 1835);
                step(f, Op::RemapF, &[530, 95, 94, 627, 96, 78, 552], 1836);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 85], 1837);
                step(f, Op::BreakTransform, &[85, 318, 63, 319], 1838);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 66, 86], 1839);
                step(f, Op::BreakTransform, &[86, 320, 64, 321], 1840);
                step(f, Op::SubV, &[318, 320, 322], 1841);
                step(f, Op::RotateVector, &[0, 388, 323], 1842);
                step(f, Op::DotV, &[322, 323, 551], 1843);
                step(f, Op::MulF, &[552, 551, 553], 1844);
                step(f, Op::QuatFromAxisAngle, &[387, 553, 70], 1845);
                step(f, Op::DivF, &[97, 633, 568], 1846);
                step(f, Op::QuatScale, &[70, 568, 71], 1847);
                step(f, Op::MulQ, &[75, 71, 79], 1848);
                step(f, Op::MakeTransform, &[338, 79, 385, 97], 1849);
                step(f, Op::SetTransform, &[44, 97, 66, 78, 629], 1850);
                step(f, Op::GetTransform, &[45, 66, 78, 94], 1851);
                step(f, Op::BreakTransform, &[94, 340, 76, 341], 1852);
                step(f, Op::LengthV, &[2, 530], 1853);
                step(f, Op::RemapF, &[530, 95, 94, 627, 96, 78, 552], 1854);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 85], 1855);
                step(f, Op::BreakTransform, &[85, 318, 63, 319], 1856);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 66, 86], 1857);
                step(f, Op::BreakTransform, &[86, 320, 64, 321], 1858);
                step(f, Op::SubV, &[318, 320, 322], 1859);
                step(f, Op::RotateVector, &[0, 388, 323], 1860);
                step(f, Op::DotV, &[322, 323, 551], 1861);
                step(f, Op::MulF, &[552, 551, 553], 1862);
                step(f, Op::QuatFromAxisAngle, &[387, 553, 70], 1863);
                step(f, Op::QuatScale, &[70, 98, 72], 1864);
                step(f, Op::MulQ, &[76, 72, 80], 1865);
                step(f, Op::MakeTransform, &[340, 80, 385, 98], 1866);
                step(f, Op::SetTransform, &[46, 98, 66, 78, 629], 1867);
                step(f, Op::Copy(ValueType::Float), &[627, 569], 1868);
                step(f, Op::Copy(ValueType::Float), &[627, 570], 1869);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1870);
                step(f, Op::Copy(ValueType::Int), &[65, 61], 1871);
                1871
            }
            1871 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 61, 25, 62, 63, 1901], 1872)
            }
            1872 => {
                step(f, Op::GetParent, &[25, 26], 1873);
                step(f, Op::GetParent, &[26, 27], 1874);
                step(f, Op::GetTransform, &[27, 65, 79, 99], 1875);
                step(f, Op::BreakTransform, &[99, 342, 81, 343], 1876);
                step(f, Op::BreakVector, &[342, 571, 572, 573], 1877);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 62, 100], 1878);
                step(f, Op::BreakTransform, &[100, 344, 82, 345], 1879);
                step(f, Op::BreakVector, &[344, 574, 575, 576], 1880);
                step(f, Op::ArrayAt(Elem::Float), &[1, 62, 580], 1881);
                step(f, Op::MulF, &[580, 103, 581], 1882);
                step(f, Op::MulF, &[581, 581, 582], 1883);
                step(f, Op::SubF, &[571, 574, 577], 1884);
                step(f, Op::SubF, &[572, 575, 578], 1885);
                step(f, Op::MakeVector, &[577, 578, 627, 346], 1886);
                step(f, Op::DotV, &[346, 346, 579], 1887);
                step(f, Op::SubF, &[582, 579, 583], 1888);
                step(f, Op::SqrtF, &[583, 584], 1889);
                step(f, Op::AddF, &[576, 584, 585], 1890);
                step(f, Op::SubF, &[573, 585, 586], 1891);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 62, 72], 1892);
                step(f, Op::ArrayAt(Elem::Float), &[2, 62, 587], 1893);
                step(f, Op::RemapF, &[587, 628, 629, 627, 629, 78, 588], 1894);
                step(f, Op::RemapF, &[587, 627, 106, 629, 627, 78, 589], 1895);
                step(f, Op::MaxF, &[588, 589, 590], 1896);
                step(f, Op::Select(ValueType::Float), &[72, 629, 590, 591], 1897);
                step(f, Op::MulF, &[586, 591, 592], 1898);
                step(f, Op::MaxF, &[570, 592, 593], 1899);
                step(f, Op::Copy(ValueType::Float), &[593, 570], 1900);
                step(f, Op::Jump, &[1871], 1901)
            }
            1901 => {
                step(f, Op::ClampF, &[570, 627, 104, 594], 1902);
                step(f, Op::Copy(ValueType::Float), &[594, 569], 1903);
                step(f, Op::Jump, &[1904], 1904)
            }
            1904 => {
                step(f, Op::MakeVector, &[15, 627, 627, 347], 1905);
                step(f, Op::MakeVector, &[569, 627, 627, 348], 1906);
                step(f, Op::MakeVector, &[16, 627, 627, 349], 1907);
                step(f, Op::GreaterF, &[569, 15, 73], 1908);
                step(f, Op::Select(ValueType::Float), &[73, 108, 105, 595], 1909);
                step(f, Op::Copy(ValueType::Vec3), &[347, 350], 1910);
                step(f, Op::Copy(ValueType::Vec3), &[348, 351], 1911);
                step(f, Op::Copy(ValueType::Vec3), &[349, 352], 1912);
                step(f, Op::Copy(ValueType::Float), &[595, 596], 1913);
                step(f, Op::Copy(ValueType::Float), &[45, 597], 1914);
                step(f, Op::Copy(ValueType::Vec3), &[384, 353], 1915);
                step(f, Op::SubV, &[351, 352, 354], 1916);
                step(f, Op::DeltaTime, &[598], 1917);
                step(f, Op::DivF, &[597, 598, 599], 1918);
                step(f, Op::ScaleV, &[354, 599, 355], 1919);
                step(f, Op::AddV, &[351, 355, 356], 1920);
                step(f, Op::AddV, &[352, 355, 357], 1921);
                step(f, Op::SubV, &[350, 357, 358], 1922);
                step(f, Op::FloatLerp, &[627, 629, 596, 600], 1923);
                step(f, Op::SubF, &[629, 600, 601], 1924);
                step(f, Op::ScaleV, &[358, 601, 359], 1925);
                step(f, Op::AddV, &[356, 359, 361], 1926);
                step(f, Op::MulF, &[596, 598, 602], 1927);
                step(f, Op::GreaterF, &[602, 627, 74], 1928);
                step(f, Op::DivF, &[600, 602, 603], 1929);
                step(f, Op::Select(ValueType::Float), &[74, 603, 629, 604], 1930);
                step(f, Op::ScaleV, &[354, 604, 360], 1931);
                step(f, Op::SubV, &[361, 360, 362], 1932);
                step(f, Op::Copy(ValueType::Vec3), &[362, 353], 1933);
                step(f, Op::Jump, &[1934], 1934)
            }
            1934 => {
                step(f, Op::BreakVector, &[353, 605, 606, 607], 1935);
                step(f, Op::Select(ValueType::Float), &[1, 569, 605, 608], 1936);
                step(f, Op::Copy(ValueType::Float), &[608, 15], 1937);
                step(f, Op::Copy(ValueType::Float), &[569, 16], 1938);
                step(f, Op::GetTransform, &[47, 65, 79, 101], 1939);
                step(f, Op::BreakTransform, &[101, 363, 83, 364], 1940);
                step(f, Op::MakeVector, &[627, 627, 15, 365], 1941);
                step(f, Op::SubV, &[363, 365, 366], 1942);
                step(f, Op::MakeTransform, &[366, 83, 385, 102], 1943);
                step(f, Op::SetTransform, &[48, 102, 65, 78, 629], 1944);
                step(f, Op::JumpIfFalse, &[8, 1952], 1945)
            }
            1945 => {
                step(f, Op::GetTransform, &[47, 65, 79, 101], 1946);
                step(f, Op::BreakTransform, &[101, 363, 83, 364], 1947);
                step(f, Op::MakeVector, &[627, 627, 15, 365], 1948);
                step(f, Op::SubV, &[363, 365, 366], 1949);
                step(f, Op::MakeTransform, &[366, 83, 385, 102], 1950);
                step(f, Op::DrawTransform, &[102, 645, 628], 1951);
                step(f, Op::Jump, &[1952], 1952)
            }
            1952 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1953);
                step(f, Op::Copy(ValueType::Int), &[65, 8], 1954);
                1954
            }
            1954 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 8, 2, 9, 10, 2006], 1955)
            }
            1955 => {
                step(f, Op::Copy(ValueType::Bone), &[2, 28], 1956);
                step(f, Op::Copy(ValueType::Int), &[9, 64], 1957);
                step(f, Op::GetParent, &[28, 29], 1958);
                step(f, Op::GetParent, &[29, 30], 1959);
                step(f, Op::GetTransform, &[30, 65, 79, 103], 1960);
                step(f, Op::BreakTransform, &[103, 367, 84, 368], 1961);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 64, 104], 1962);
                step(f, Op::BreakTransform, &[104, 369, 85, 370], 1963);
                step(f, Op::SubV, &[369, 367, 371], 1964);
                step(f, Op::LengthV, &[371, 617], 1965);
                step(f, Op::ArrayAt(Elem::Float), &[1, 64, 609], 1966);
                step(f, Op::MulF, &[609, 114, 610], 1967);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 64, 75], 1968);
                step(f, Op::ArrayAt(Elem::Float), &[2, 64, 611], 1969);
                step(f, Op::ClampF, &[611, 627, 629, 612], 1970);
                step(f, Op::MulF, &[612, 640, 613], 1971);
                step(f, Op::SinF, &[613, 614], 1972);
                step(f, Op::MulF, &[614, 115, 615], 1973);
                step(f, Op::Select(ValueType::Float), &[75, 627, 615, 616], 1974);
                step(f, Op::SubF, &[610, 616, 618], 1975);
                step(f, Op::SubF, &[617, 618, 619], 1976);
                step(f, Op::MaxF, &[619, 627, 620], 1977);
                step(f, Op::MulF, &[620, 620, 621], 1978);
                step(f, Op::AddF, &[620, 616, 622], 1979);
                step(f, Op::DivF, &[621, 622, 623], 1980);
                step(f, Op::SubF, &[617, 623, 624], 1981);
                step(f, Op::DivF, &[624, 617, 625], 1982);
                step(f, Op::ScaleV, &[371, 625, 372], 1983);
                step(f, Op::AddV, &[367, 372, 373], 1984);
                step(f, Op::ClampSpatially, &[373, 367, 627, 610, 374], 1985);
                step(f, Op::MakeTransform, &[374, 85, 385, 105], 1986);
                step(f, Op::Equals(Elem::Int), &[64, 65, 76], 1987);
                step(f, Op::Select(ValueType::Vec3), &[76, 391, 390, 379], 1988);
                step(f, Op::Select(ValueType::Vec3), &[76, 388, 392, 380], 1989);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 64, 106], 1990);
                step(f, Op::BreakTransform, &[106, 375, 86, 376], 1991);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 64, 377], 1992);
                step(f, Op::KneeVector, &[86, 0, 377, 116, 117, 378], 1993);
                step(f, Op::TwoBoneIK, &[30, 29, 28, 105, 379, 380, 378, 65, 629, 79, 642, 643, 78, 77, 626], 1994);
                step(f, Op::JumpIfFalse, &[8, 2005], 1995)
            }
            1995 => {
                step(f, Op::GetParent, &[28, 29], 1996);
                step(f, Op::GetTransform, &[29, 65, 79, 107], 1997);
                step(f, Op::BreakTransform, &[107, 381, 87, 382], 1998);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 64, 106], 1999);
                step(f, Op::BreakTransform, &[106, 375, 86, 376], 2000);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 64, 377], 2001);
                step(f, Op::KneeVector, &[86, 0, 377, 116, 117, 378], 2002);
                step(f, Op::AddV, &[381, 378, 383], 2003);
                step(f, Op::DrawLine, &[381, 383, 628, 393], 2004);
                step(f, Op::Jump, &[2005], 2005)
            }
            2005 => {
                step(f, Op::Jump, &[1954], 2006)
            }
            2006 => {
                step(f, Op::End, &[], 2007)
            }
            _ => return,
        } };
    }
}
