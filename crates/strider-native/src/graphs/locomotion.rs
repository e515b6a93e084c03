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
    fingerprint: 0xd38035e4ee93ca38,
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
                step(f, Op::LengthV, &[36, 130], 461);
                step(f, Op::GreaterF, &[130, 32, 10], 462);
                step(f, Op::Copy(ValueType::Bool), &[10, 2], 463);
                step(f, Op::MakeRelative, &[13, 12, 17], 464);
                step(f, Op::Select(ValueType::Transform), &[10, 110, 17, 18], 465);
                step(f, Op::Copy(ValueType::Transform), &[18, 2], 466);
                step(f, Op::InverseT, &[13, 15], 467);
                step(f, Op::MulT, &[12, 15, 16], 468);
                step(f, Op::Copy(ValueType::Transform), &[16, 1], 469);
                step(f, Op::TransformVector, &[2, 0, 41], 470);
                step(f, Op::InverseT, &[12, 14], 471);
                step(f, Op::DeltaTime, &[129], 472);
                step(f, Op::DivF, &[682, 129, 131], 473);
                step(f, Op::ScaleV, &[36, 131, 37], 474);
                step(f, Op::TransformVector, &[14, 37, 38], 475);
                step(f, Op::BreakVector, &[38, 132, 133, 134], 476);
                step(f, Op::MakeVector, &[132, 133, 680, 39], 477);
                step(f, Op::LengthV, &[39, 135], 478);
                step(f, Op::MulF, &[135, 112, 136], 479);
                step(f, Op::NegF, &[136, 137], 480);
                step(f, Op::ClampF, &[134, 137, 136, 138], 481);
                step(f, Op::MakeVector, &[132, 133, 138, 40], 482);
                step(f, Op::Select(ValueType::Vec3), &[2, 41, 40, 43], 483);
                step(f, Op::VectorLerp, &[41, 43, 33, 680, 44], 484);
                step(f, Op::Copy(ValueType::Vec3), &[44, 0], 485);
                step(f, Op::TransformVector, &[2, 1, 42], 486);
                step(f, Op::TransformVector, &[2, 0, 41], 487);
                step(f, Op::Select(ValueType::Vec3), &[2, 41, 40, 43], 488);
                step(f, Op::VectorLerp, &[42, 43, 34, 680, 45], 489);
                step(f, Op::Copy(ValueType::Vec3), &[45, 1], 490);
                step(f, Op::LengthV, &[43, 145], 491);
                step(f, Op::Copy(ValueType::Float), &[145, 0], 492);
                step(f, Op::BreakVector, &[36, 139, 140, 141], 493);
                step(f, Op::MulF, &[138, 129, 142], 494);
                step(f, Op::SubF, &[141, 142, 143], 495);
                step(f, Op::Select(ValueType::Float), &[10, 680, 143, 144], 496);
                step(f, Op::Copy(ValueType::Float), &[144, 1], 497);
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
                step(f, Op::Copy(ValueType::Float), &[680, 14], 515);
                step(f, Op::Jump, &[516], 516)
            }
            516 => {
                step(f, Op::WorldTransform, &[12], 517);
                step(f, Op::Copy(ValueType::Transform), &[12, 0], 518);
                step(f, Op::Copy(ValueType::Bool), &[79, 0], 519);
                step(f, Op::JumpIfFalse, &[8, 526], 520)
            }
            520 => {
                step(f, Op::GetTransform, &[34, 65, 79, 19], 521);
                step(f, Op::BreakTransform, &[19, 46, 9, 47], 522);
                step(f, Op::ScaleV, &[0, 683, 48], 523);
                step(f, Op::AddV, &[46, 48, 49], 524);
                step(f, Op::DrawArrow, &[46, 49, 681, 393], 525);
                step(f, Op::Jump, &[526], 526)
            }
            526 => {
                step(f, Op::Copy(ValueType::Float), &[680, 146], 527);
                step(f, Op::Copy(ValueType::Float), &[682, 147], 528);
                step(f, Op::Copy(ValueType::Float), &[682, 148], 529);
                step(f, Op::Copy(ValueType::Bool), &[80, 11], 530);
                step(f, Op::Copy(ValueType::Bool), &[80, 12], 531);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[7, 8], 532);
                step(f, Op::Copy(ValueType::Int), &[65, 25], 533);
                step(f, Op::MakeVector, &[680, 680, 51, 54], 534);
                534
            }
            534 => {
                step(f, Op::ForEachNext(Elem::Transform), &[8, 25, 21, 26, 27, 545], 535)
            }
            535 => {
                step(f, Op::BreakTransform, &[21, 50, 10, 51], 536);
                step(f, Op::TransformPoint, &[2, 50, 52], 537);
                step(f, Op::LerpV, &[52, 50, 148, 53], 538);
                step(f, Op::AddV, &[53, 54, 55], 539);
                step(f, Op::SubV, &[53, 54, 56], 540);
                step(f, Op::LineTrace, &[55, 56, 13, 57, 58, 149], 541);
                step(f, Op::JumpIfFalse, &[13, 544], 542)
            }
            542 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 12], 543);
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
                step(f, Op::AddF, &[146, 147, 150], 556);
                step(f, Op::MulF, &[150, 681, 151], 557);
                step(f, Op::Copy(ValueType::Float), &[151, 152], 558);
                step(f, Op::Copy(ValueType::Bool), &[80, 17], 559);
                step(f, Op::Copy(ValueType::Bool), &[80, 18], 560);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[7, 9], 561);
                step(f, Op::Copy(ValueType::Int), &[65, 28], 562);
                step(f, Op::MakeVector, &[680, 680, 51, 63], 563);
                563
            }
            563 => {
                step(f, Op::ForEachNext(Elem::Transform), &[9, 28, 22, 29, 30, 574], 564)
            }
            564 => {
                step(f, Op::BreakTransform, &[22, 59, 11, 60], 565);
                step(f, Op::TransformPoint, &[2, 59, 61], 566);
                step(f, Op::LerpV, &[61, 59, 152, 62], 567);
                step(f, Op::AddV, &[62, 63, 64], 568);
                step(f, Op::SubV, &[62, 63, 65], 569);
                step(f, Op::LineTrace, &[64, 65, 19, 66, 67, 153], 570);
                step(f, Op::JumpIfFalse, &[19, 573], 571)
            }
            571 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 18], 572);
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
                step(f, Op::Copy(ValueType::Float), &[151, 146], 579);
                step(f, Op::Jump, &[581], 580)
            }
            580 => {
                step(f, Op::Copy(ValueType::Float), &[151, 147], 581);
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
                step(f, Op::Select(ValueType::Float), &[5, 684, 682, 159], 585);
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 586);
                step(f, Op::AddF, &[146, 147, 150], 587);
                step(f, Op::MulF, &[150, 681, 154], 588);
                step(f, Op::Select(ValueType::Float), &[16, 154, 681, 155], 589);
                step(f, Op::Select(ValueType::Float), &[15, 155, 680, 161], 590);
                step(f, Op::MulF, &[159, 161, 163], 591);
                step(f, Op::DeltaTime, &[157], 592);
                step(f, Op::DivF, &[157, 115, 158], 593);
                step(f, Op::MulF, &[163, 158, 164], 594);
                step(f, Op::AddF, &[17, 164, 165], 595);
                step(f, Op::ClampF, &[165, 680, 682, 166], 596);
                step(f, Op::Select(ValueType::Float), &[14, 684, 682, 160], 597);
                step(f, Op::SubF, &[682, 155, 156], 598);
                step(f, Op::Select(ValueType::Float), &[15, 156, 682, 162], 599);
                step(f, Op::MulF, &[160, 162, 167], 600);
                step(f, Op::MulF, &[167, 158, 168], 601);
                step(f, Op::AddF, &[166, 168, 169], 602);
                step(f, Op::ClampF, &[169, 680, 682, 170], 603);
                step(f, Op::MulF, &[170, 170, 171], 604);
                step(f, Op::MulF, &[170, 685, 172], 605);
                step(f, Op::SubF, &[686, 172, 173], 606);
                step(f, Op::MulF, &[171, 173, 174], 607);
                step(f, Op::AddF, &[18, 174, 175], 608);
                step(f, Op::MulF, &[175, 681, 176], 609);
                step(f, Op::SubF, &[682, 176, 177], 610);
                step(f, Op::MulF, &[177, 177, 178], 611);
                step(f, Op::SubF, &[682, 178, 179], 612);
                step(f, Op::Copy(ValueType::Float), &[179, 19], 613);
                step(f, Op::Copy(ValueType::Float), &[174, 18], 614);
                step(f, Op::Copy(ValueType::Float), &[170, 17], 615);
                step(f, Op::GreaterF, &[18, 680, 21], 616);
                step(f, Op::TransformVector, &[2, 3, 68], 617);
                step(f, Op::Select(ValueType::Vec3), &[21, 68, 0, 69], 618);
                step(f, Op::Copy(ValueType::Vec3), &[69, 3], 619);
                step(f, Op::LerpV, &[0, 3, 18, 70], 620);
                step(f, Op::Select(ValueType::Vec3), &[21, 70, 0, 71], 621);
                step(f, Op::Copy(ValueType::Vec3), &[71, 2], 622);
                step(f, Op::Copy(ValueType::Bool), &[14, 5], 623);
                step(f, Op::Copy(ValueType::Bool), &[11, 6], 624);
                step(f, Op::Copy(ValueType::Bool), &[80, 7], 625);
                step(f, Op::SubF, &[682, 19, 180], 626);
                step(f, Op::MulF, &[1, 180, 181], 627);
                step(f, Op::AddF, &[2, 181, 182], 628);
                step(f, Op::SpringF, &[182, 113, 185, 31, 183, 184], 629);
                step(f, Op::SubF, &[182, 185, 186], 630);
                step(f, Op::Copy(ValueType::Float), &[186, 3], 631);
                step(f, Op::Copy(ValueType::Float), &[182, 2], 632);
                step(f, Op::Copy(ValueType::Bool), &[80, 23], 633);
                step(f, Op::Copy(ValueType::Bool), &[79, 24], 634);
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
                step(f, Op::Copy(ValueType::Bool), &[80, 24], 640);
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
                step(f, Op::Copy(ValueType::Bool), &[80, 27], 645);
                step(f, Op::Copy(ValueType::Bool), &[79, 28], 646);
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
                step(f, Op::BreakVector, &[72, 195, 196, 197], 652);
                step(f, Op::MakeVector, &[195, 196, 680, 76], 653);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 39, 24], 654);
                step(f, Op::BreakTransform, &[24, 74, 13, 75], 655);
                step(f, Op::BreakVector, &[74, 198, 199, 200], 656);
                step(f, Op::MakeVector, &[198, 199, 680, 77], 657);
                step(f, Op::DistanceV, &[76, 77, 201], 658);
                step(f, Op::GreaterF, &[201, 28, 29], 659);
                step(f, Op::JumpIfFalse, &[29, 662], 660)
            }
            660 => {
                step(f, Op::Copy(ValueType::Bool), &[80, 28], 661);
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
                step(f, Op::LengthV, &[2, 187], 667);
                step(f, Op::GreaterF, &[187, 26, 22], 668);
                step(f, Op::GreaterF, &[0, 26, 31], 669);
                step(f, Op::Or, &[22, 31, 32], 670);
                step(f, Op::Not, &[32, 33], 671);
                step(f, Op::And, &[30, 33, 38], 672);
                step(f, Op::DeltaTime, &[226], 673);
                step(f, Op::MulF, &[226, 31, 227], 674);
                step(f, Op::AddF, &[10, 227, 228], 675);
                step(f, Op::GreaterF, &[10, 681, 39], 676);
                step(f, Op::AddF, &[30, 681, 224], 677);
                step(f, Op::Select(ValueType::Float), &[39, 224, 30, 225], 678);
                step(f, Op::MinF, &[228, 225, 229], 679);
                step(f, Op::NotEquals(Elem::Bool), &[33, 4, 34], 680);
                step(f, Op::Not, &[30, 35], 681);
                step(f, Op::And, &[34, 35, 36], 682);
                step(f, Op::SubF, &[11, 26, 210], 683);
                step(f, Op::SubF, &[11, 187, 211], 684);
                step(f, Op::DivF, &[210, 211, 212], 685);
                step(f, Op::ClampF, &[212, 680, 682, 213], 686);
                step(f, Op::MulF, &[6, 213, 215], 687);
                step(f, Op::RemapF, &[187, 26, 27, 680, 682, 79, 202], 688);
                step(f, Op::MaxF, &[202, 7, 203], 689);
                step(f, Op::Select(ValueType::Float), &[23, 682, 203, 204], 690);
                step(f, Op::Select(ValueType::Float), &[33, 29, 204, 205], 691);
                step(f, Op::Select(ValueType::Float), &[30, 202, 205, 206], 692);
                step(f, Op::SubF, &[682, 18, 207], 693);
                step(f, Op::MulF, &[206, 207, 208], 694);
                step(f, Op::LerpF, &[20, 41, 13, 190], 695);
                step(f, Op::RemapF, &[187, 23, 24, 21, 22, 79, 188], 696);
                step(f, Op::LerpF, &[188, 40, 13, 189], 697);
                step(f, Op::MaxF, &[187, 25, 191], 698);
                step(f, Op::DivF, &[189, 191, 192], 699);
                step(f, Op::AddF, &[190, 192, 193], 700);
                step(f, Op::DivF, &[208, 193, 209], 701);
                step(f, Op::SubF, &[682, 213, 214], 702);
                step(f, Op::MulF, &[209, 214, 216], 703);
                step(f, Op::AddF, &[215, 216, 217], 704);
                step(f, Op::MulF, &[217, 685, 218], 705);
                step(f, Op::AddF, &[6, 209, 219], 706);
                step(f, Op::Select(ValueType::Float), &[36, 218, 219, 220], 707);
                step(f, Op::DivF, &[685, 220, 221], 708);
                step(f, Op::GreaterF, &[220, 680, 37], 709);
                step(f, Op::CycleStep, &[10, 221, 680, 37, 222, 223], 710);
                step(f, Op::Select(ValueType::Float), &[38, 229, 222, 230], 711);
                step(f, Op::Copy(ValueType::Float), &[230, 10], 712);
                step(f, Op::Copy(ValueType::Float), &[209, 6], 713);
                step(f, Op::Copy(ValueType::Bool), &[22, 3], 714);
                step(f, Op::Copy(ValueType::Float), &[192, 4], 715);
                step(f, Op::Copy(ValueType::Float), &[193, 5], 716);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 717);
                step(f, Op::Copy(ValueType::Int), &[65, 32], 718);
                718
            }
            718 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 32, 14, 33, 34, 892], 719)
            }
            719 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 33, 244], 720);
                step(f, Op::ToFloat, &[33, 231], 721);
                step(f, Op::MulF, &[231, 681, 232], 722);
                step(f, Op::AddF, &[10, 232, 233], 723);
                step(f, Op::FractF, &[233, 234], 724);
                step(f, Op::SubF, &[244, 234, 246], 725);
                step(f, Op::GreaterF, &[246, 681, 40], 726);
                step(f, Op::ArrayAt(Elem::Float), &[2, 33, 245], 727);
                step(f, Op::Select(ValueType::Float), &[40, 680, 245, 273], 728);
                step(f, Op::ArraySetAt(Elem::Float), &[3, 33, 273], 729);
                step(f, Op::ArrayAt(Elem::Float), &[0, 33, 244], 730);
                step(f, Op::ToFloat, &[33, 231], 731);
                step(f, Op::MulF, &[231, 681, 232], 732);
                step(f, Op::AddF, &[10, 232, 233], 733);
                step(f, Op::FractF, &[233, 234], 734);
                step(f, Op::SubF, &[244, 234, 246], 735);
                step(f, Op::GreaterF, &[246, 681, 40], 736);
                step(f, Op::SubF, &[682, 244, 267], 737);
                step(f, Op::AddF, &[234, 267, 268], 738);
                step(f, Op::DivF, &[234, 268, 269], 739);
                step(f, Op::LengthV, &[2, 187], 740);
                step(f, Op::GreaterF, &[187, 26, 22], 741);
                step(f, Op::GreaterF, &[0, 26, 31], 742);
                step(f, Op::Or, &[22, 31, 32], 743);
                step(f, Op::Not, &[32, 33], 744);
                step(f, Op::NotEquals(Elem::Bool), &[33, 4, 34], 745);
                step(f, Op::Copy(ValueType::Bool), &[80, 23], 746);
                step(f, Op::Copy(ValueType::Bool), &[79, 24], 747);
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
                step(f, Op::Copy(ValueType::Bool), &[80, 24], 753);
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
                step(f, Op::Copy(ValueType::Bool), &[80, 27], 758);
                step(f, Op::Copy(ValueType::Bool), &[79, 28], 759);
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
                step(f, Op::BreakVector, &[72, 195, 196, 197], 765);
                step(f, Op::MakeVector, &[195, 196, 680, 76], 766);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 39, 24], 767);
                step(f, Op::BreakTransform, &[24, 74, 13, 75], 768);
                step(f, Op::BreakVector, &[74, 198, 199, 200], 769);
                step(f, Op::MakeVector, &[198, 199, 680, 77], 770);
                step(f, Op::DistanceV, &[76, 77, 201], 771);
                step(f, Op::GreaterF, &[201, 28, 29], 772);
                step(f, Op::JumpIfFalse, &[29, 775], 773)
            }
            773 => {
                step(f, Op::Copy(ValueType::Bool), &[80, 28], 774);
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
                step(f, Op::SubF, &[11, 26, 210], 782);
                step(f, Op::SubF, &[11, 187, 211], 783);
                step(f, Op::DivF, &[210, 211, 212], 784);
                step(f, Op::ClampF, &[212, 680, 682, 213], 785);
                step(f, Op::MulF, &[9, 213, 236], 786);
                step(f, Op::RemapF, &[187, 26, 27, 680, 682, 79, 202], 787);
                step(f, Op::MaxF, &[202, 7, 203], 788);
                step(f, Op::Select(ValueType::Float), &[23, 682, 203, 204], 789);
                step(f, Op::Select(ValueType::Float), &[33, 29, 204, 205], 790);
                step(f, Op::Select(ValueType::Float), &[30, 202, 205, 206], 791);
                step(f, Op::SubF, &[682, 18, 207], 792);
                step(f, Op::MulF, &[206, 207, 208], 793);
                step(f, Op::LerpF, &[20, 41, 13, 190], 794);
                step(f, Op::DivF, &[208, 190, 235], 795);
                step(f, Op::SubF, &[682, 213, 214], 796);
                step(f, Op::MulF, &[235, 214, 237], 797);
                step(f, Op::AddF, &[236, 237, 238], 798);
                step(f, Op::MulF, &[238, 685, 239], 799);
                step(f, Op::AddF, &[9, 235, 240], 800);
                step(f, Op::Select(ValueType::Float), &[36, 239, 240, 241], 801);
                step(f, Op::DeltaTime, &[226], 802);
                step(f, Op::MulF, &[226, 681, 242], 803);
                step(f, Op::MulF, &[241, 242, 243], 804);
                step(f, Op::MulF, &[269, 243, 270], 805);
                step(f, Op::ArrayAt(Elem::Float), &[2, 33, 245], 806);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 33, 41], 807);
                step(f, Op::RemapF, &[187, 23, 24, 21, 22, 79, 188], 808);
                step(f, Op::LerpF, &[188, 40, 13, 189], 809);
                step(f, Op::MaxF, &[187, 25, 191], 810);
                step(f, Op::DivF, &[189, 191, 192], 811);
                step(f, Op::AddF, &[190, 192, 193], 812);
                step(f, Op::DivF, &[190, 193, 194], 813);
                step(f, Op::SubF, &[194, 8, 247], 814);
                step(f, Op::MaxF, &[247, 680, 248], 815);
                step(f, Op::DivF, &[248, 194, 249], 816);
                step(f, Op::SubF, &[682, 13, 251], 817);
                step(f, Op::MulF, &[249, 251, 258], 818);
                step(f, Op::MulF, &[258, 207, 259], 819);
                step(f, Op::MulF, &[259, 110, 260], 820);
                step(f, Op::DivF, &[45, 226, 256], 821);
                step(f, Op::SubF, &[681, 256, 257], 822);
                step(f, Op::MulF, &[260, 257, 261], 823);
                step(f, Op::SubF, &[682, 261, 262], 824);
                step(f, Op::MulF, &[243, 262, 263], 825);
                step(f, Op::Select(ValueType::Float), &[41, 243, 263, 264], 826);
                step(f, Op::MulF, &[249, 245, 250], 827);
                step(f, Op::MulF, &[250, 251, 252], 828);
                step(f, Op::MulF, &[252, 207, 253], 829);
                step(f, Op::MulF, &[253, 110, 254], 830);
                step(f, Op::Select(ValueType::Float), &[41, 680, 254, 255], 831);
                step(f, Op::SubF, &[264, 255, 265], 832);
                step(f, Op::AddF, &[245, 265, 266], 833);
                step(f, Op::Select(ValueType::Float), &[40, 270, 266, 271], 834);
                step(f, Op::MinF, &[271, 685, 272], 835);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 33, 272], 836);
                step(f, Op::ArrayAt(Elem::Float), &[0, 33, 244], 837);
                step(f, Op::ToFloat, &[33, 231], 838);
                step(f, Op::MulF, &[231, 681, 232], 839);
                step(f, Op::AddF, &[10, 232, 233], 840);
                step(f, Op::FractF, &[233, 234], 841);
                step(f, Op::SubF, &[244, 234, 246], 842);
                step(f, Op::GreaterF, &[246, 681, 40], 843);
                step(f, Op::JumpIfFalse, &[40, 890], 844)
            }
            844 => {
                step(f, Op::Copy(ValueType::Bool), &[80, 23], 845);
                step(f, Op::Copy(ValueType::Bool), &[79, 24], 846);
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
                step(f, Op::Copy(ValueType::Bool), &[80, 24], 852);
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
                step(f, Op::Copy(ValueType::Bool), &[80, 27], 857);
                step(f, Op::Copy(ValueType::Bool), &[79, 28], 858);
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
                step(f, Op::BreakVector, &[72, 195, 196, 197], 864);
                step(f, Op::MakeVector, &[195, 196, 680, 76], 865);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 39, 24], 866);
                step(f, Op::BreakTransform, &[24, 74, 13, 75], 867);
                step(f, Op::BreakVector, &[74, 198, 199, 200], 868);
                step(f, Op::MakeVector, &[198, 199, 680, 77], 869);
                step(f, Op::DistanceV, &[76, 77, 201], 870);
                step(f, Op::GreaterF, &[201, 28, 29], 871);
                step(f, Op::JumpIfFalse, &[29, 874], 872)
            }
            872 => {
                step(f, Op::Copy(ValueType::Bool), &[80, 28], 873);
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
                step(f, Op::LengthV, &[2, 187], 879);
                step(f, Op::RemapF, &[187, 26, 27, 680, 682, 79, 202], 880);
                step(f, Op::GreaterF, &[187, 26, 22], 881);
                step(f, Op::GreaterF, &[0, 26, 31], 882);
                step(f, Op::Or, &[22, 31, 32], 883);
                step(f, Op::Not, &[32, 33], 884);
                step(f, Op::MaxF, &[202, 7, 203], 885);
                step(f, Op::Select(ValueType::Float), &[23, 682, 203, 204], 886);
                step(f, Op::Select(ValueType::Float), &[33, 29, 204, 205], 887);
                step(f, Op::Select(ValueType::Float), &[30, 202, 205, 206], 888);
                step(f, Op::Copy(ValueType::Float), &[206, 7], 889);
                step(f, Op::Jump, &[890], 890)
            }
            890 => {
                step(f, Op::ArraySetAt(Elem::Float), &[0, 33, 234], 891);
                step(f, Op::Jump, &[718], 892)
            }
            892 => {
                step(f, Op::LerpF, &[20, 41, 13, 190], 893);
                step(f, Op::LengthV, &[2, 187], 894);
                step(f, Op::RemapF, &[187, 23, 24, 21, 22, 79, 188], 895);
                step(f, Op::LerpF, &[188, 40, 13, 189], 896);
                step(f, Op::MaxF, &[187, 25, 191], 897);
                step(f, Op::DivF, &[189, 191, 192], 898);
                step(f, Op::AddF, &[190, 192, 193], 899);
                step(f, Op::DivF, &[190, 193, 194], 900);
                step(f, Op::Copy(ValueType::Float), &[194, 8], 901);
                step(f, Op::GreaterF, &[187, 26, 22], 902);
                step(f, Op::GreaterF, &[0, 26, 31], 903);
                step(f, Op::Or, &[22, 31, 32], 904);
                step(f, Op::Not, &[32, 33], 905);
                step(f, Op::Copy(ValueType::Bool), &[33, 4], 906);
                step(f, Op::Copy(ValueType::Float), &[187, 11], 907);
                step(f, Op::Copy(ValueType::Bool), &[80, 23], 908);
                step(f, Op::Copy(ValueType::Bool), &[79, 24], 909);
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
                step(f, Op::Copy(ValueType::Bool), &[80, 24], 915);
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
                step(f, Op::Copy(ValueType::Bool), &[80, 27], 920);
                step(f, Op::Copy(ValueType::Bool), &[79, 28], 921);
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
                step(f, Op::BreakVector, &[72, 195, 196, 197], 927);
                step(f, Op::MakeVector, &[195, 196, 680, 76], 928);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 39, 24], 929);
                step(f, Op::BreakTransform, &[24, 74, 13, 75], 930);
                step(f, Op::BreakVector, &[74, 198, 199, 200], 931);
                step(f, Op::MakeVector, &[198, 199, 680, 77], 932);
                step(f, Op::DistanceV, &[76, 77, 201], 933);
                step(f, Op::GreaterF, &[201, 28, 29], 934);
                step(f, Op::JumpIfFalse, &[29, 937], 935)
            }
            935 => {
                step(f, Op::Copy(ValueType::Bool), &[80, 28], 936);
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
                step(f, Op::RemapF, &[187, 26, 27, 680, 682, 79, 202], 942);
                step(f, Op::MaxF, &[202, 7, 203], 943);
                step(f, Op::Select(ValueType::Float), &[23, 682, 203, 204], 944);
                step(f, Op::Select(ValueType::Float), &[33, 29, 204, 205], 945);
                step(f, Op::Select(ValueType::Float), &[30, 202, 205, 206], 946);
                step(f, Op::SubF, &[682, 18, 207], 947);
                step(f, Op::MulF, &[206, 207, 208], 948);
                step(f, Op::DivF, &[208, 190, 235], 949);
                step(f, Op::Copy(ValueType::Float), &[235, 9], 950);
                step(f, Op::Select(ValueType::Vec3), &[3, 2, 391, 78], 951);
                step(f, Op::MovementAngleOffset, &[78, 12, 10, 35, 36, 687, 37, 688, 274], 952);
                step(f, Op::Copy(ValueType::Float), &[274, 12], 953);
                step(f, Op::QuatFromAxisAngle, &[394, 12, 14], 954);
                step(f, Op::Copy(ValueType::Quat), &[14, 0], 955);
                step(f, Op::SinF, &[12, 275], 956);
                step(f, Op::AbsF, &[275, 276], 957);
                step(f, Op::RemapF, &[276, 38, 39, 680, 682, 79, 277], 958);
                step(f, Op::Copy(ValueType::Float), &[277, 13], 959);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 960);
                step(f, Op::Copy(ValueType::Int), &[65, 2], 961);
                961
            }
            961 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 2, 0, 3, 4, 1771], 962)
            }
            962 => {
                step(f, Op::Copy(ValueType::Bone), &[0, 16], 963);
                step(f, Op::Copy(ValueType::Int), &[3, 41], 964);
                step(f, Op::GetTransform, &[35, 65, 79, 25], 965);
                step(f, Op::BreakTransform, &[25, 81, 15, 82], 966);
                step(f, Op::BreakVector, &[81, 289, 290, 291], 967);
                step(f, Op::SubF, &[682, 13, 287], 968);
                step(f, Op::MulF, &[12, 287, 288], 969);
                step(f, Op::QuatFromAxisAngle, &[394, 288, 17], 970);
                step(f, Op::GetTransform, &[16, 65, 79, 26], 971);
                step(f, Op::BreakTransform, &[26, 83, 16, 84], 972);
                step(f, Op::SubV, &[83, 81, 85], 973);
                step(f, Op::BreakVector, &[85, 284, 285, 286], 974);
                step(f, Op::MakeVector, &[284, 285, 680, 86], 975);
                step(f, Op::RotateVector, &[17, 86, 87], 976);
                step(f, Op::BreakVector, &[87, 292, 293, 294], 977);
                step(f, Op::MulF, &[42, 13, 295], 978);
                step(f, Op::Equals(Elem::Int), &[41, 65, 42], 979);
                step(f, Op::Select(ValueType::Float), &[42, 682, 684, 304], 980);
                step(f, Op::MulF, &[295, 304, 296], 981);
                step(f, Op::AddF, &[292, 296, 297], 982);
                step(f, Op::AddF, &[289, 297, 298], 983);
                step(f, Op::AddF, &[290, 293, 299], 984);
                step(f, Op::BreakVector, &[83, 300, 301, 302], 985);
                step(f, Op::SubF, &[302, 46, 303], 986);
                step(f, Op::MakeVector, &[298, 299, 303, 88], 987);
                step(f, Op::ArrayAt(Elem::Float), &[2, 41, 278], 988);
                step(f, Op::SubF, &[682, 278, 279], 989);
                step(f, Op::MaxF, &[279, 680, 280], 990);
                step(f, Op::MulF, &[8, 5, 281], 991);
                step(f, Op::MulF, &[280, 281, 282], 992);
                step(f, Op::ScaleV, &[2, 282, 79], 993);
                step(f, Op::AddV, &[88, 79, 89], 994);
                step(f, Op::MulF, &[4, 681, 283], 995);
                step(f, Op::ScaleV, &[2, 283, 80], 996);
                step(f, Op::AddV, &[89, 80, 90], 997);
                step(f, Op::RotateVector, &[0, 395, 91], 998);
                step(f, Op::Copy(ValueType::Vec3), &[90, 112], 999);
                step(f, Op::Copy(ValueType::Vec3), &[91, 113], 1000);
                step(f, Op::Copy(ValueType::Float), &[304, 323], 1001);
                step(f, Op::Copy(ValueType::Vec3), &[391, 114], 1002);
                step(f, Op::Copy(ValueType::Vec3), &[391, 115], 1003);
                step(f, Op::Copy(ValueType::Bool), &[80, 44], 1004);
                step(f, Op::Copy(ValueType::Float), &[689, 324], 1005);
                step(f, Op::Copy(ValueType::Vec3), &[391, 116], 1006);
                step(f, Op::Copy(ValueType::Vec3), &[394, 117], 1007);
                step(f, Op::Copy(ValueType::Bool), &[80, 45], 1008);
                step(f, Op::MulI, &[0, 0, 47], 1009);
                step(f, Op::Copy(ValueType::Int), &[47, 46], 1010);
                step(f, Op::Copy(ValueType::Int), &[65, 42], 1011);
                step(f, Op::SubI, &[0, 66, 50], 1012);
                step(f, Op::DivI, &[50, 67, 51], 1013);
                step(f, Op::MakeVector, &[680, 680, 51, 122], 1014);
                step(f, Op::ScaleV, &[113, 53, 127], 1015);
                1015
            }
            1015 => {
                step(f, Op::ForNext, &[42, 46, 44, 1055], 1016)
            }
            1016 => {
                step(f, Op::ModI, &[44, 0, 48], 1017);
                step(f, Op::ToFloat, &[48, 325], 1018);
                step(f, Op::MulF, &[325, 52, 327], 1019);
                step(f, Op::MulF, &[327, 323, 328], 1020);
                step(f, Op::MakeVector, &[328, 680, 680, 118], 1021);
                step(f, Op::DivI, &[44, 0, 49], 1022);
                step(f, Op::SubI, &[49, 51, 52], 1023);
                step(f, Op::ToFloat, &[52, 326], 1024);
                step(f, Op::MulF, &[326, 52, 329], 1025);
                step(f, Op::ScaleV, &[113, 329, 119], 1026);
                step(f, Op::AddV, &[118, 119, 120], 1027);
                step(f, Op::AddV, &[112, 120, 121], 1028);
                step(f, Op::AddV, &[121, 122, 123], 1029);
                step(f, Op::SubV, &[121, 122, 124], 1030);
                step(f, Op::SphereTrace, &[123, 124, 50, 46, 125, 126, 330], 1031);
                step(f, Op::BreakVector, &[125, 332, 333, 334], 1032);
                step(f, Op::AddV, &[123, 127, 128], 1033);
                step(f, Op::AddV, &[124, 127, 129], 1034);
                step(f, Op::SphereTrace, &[128, 129, 50, 47, 130, 131, 331], 1035);
                step(f, Op::BreakVector, &[130, 335, 336, 337], 1036);
                step(f, Op::SubF, &[334, 337, 338], 1037);
                step(f, Op::AbsF, &[338, 339], 1038);
                step(f, Op::Select(ValueType::Float), &[46, 680, 682, 340], 1039);
                step(f, Op::AddF, &[339, 340, 345], 1040);
                step(f, Op::LengthV, &[120, 341], 1041);
                step(f, Op::RemapF, &[341, 680, 690, 680, 682, 79, 342], 1042);
                step(f, Op::MinF, &[334, 337, 343], 1043);
                step(f, Op::RemapF, &[343, 691, 690, 682, 681, 79, 344], 1044);
                step(f, Op::AddF, &[342, 344, 346], 1045);
                step(f, Op::AddF, &[345, 346, 347], 1046);
                step(f, Op::LessF, &[347, 324, 48], 1047);
                step(f, Op::And, &[46, 48, 49], 1048);
                step(f, Op::JumpIfFalse, &[49, 1054], 1049)
            }
            1049 => {
                step(f, Op::Copy(ValueType::Float), &[347, 324], 1050);
                step(f, Op::Copy(ValueType::Vec3), &[125, 116], 1051);
                step(f, Op::Copy(ValueType::Vec3), &[126, 117], 1052);
                step(f, Op::Copy(ValueType::Bool), &[79, 45], 1053);
                step(f, Op::Jump, &[1054], 1054)
            }
            1054 => {
                step(f, Op::Jump, &[1015], 1055)
            }
            1055 => {
                step(f, Op::JumpIfFalse, &[8, 1058], 1056)
            }
            1056 => {
                step(f, Op::DrawSphere, &[116, 50, 395], 1057);
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
                step(f, Op::ArrayAt(Elem::Float), &[2, 41, 278], 1065);
                step(f, Op::SubF, &[682, 278, 279], 1066);
                step(f, Op::MaxF, &[279, 680, 280], 1067);
                step(f, Op::MulF, &[8, 5, 281], 1068);
                step(f, Op::MulF, &[280, 281, 282], 1069);
                step(f, Op::ScaleV, &[2, 282, 79], 1070);
                step(f, Op::SubV, &[114, 79, 92], 1071);
                step(f, Op::Select(ValueType::Vec3), &[44, 92, 93, 95], 1072);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 41, 28], 1073);
                step(f, Op::BreakTransform, &[28, 96, 23, 97], 1074);
                step(f, Op::Copy(ValueType::Vec3), &[93, 98], 1075);
                step(f, Op::Copy(ValueType::Vec3), &[95, 99], 1076);
                step(f, Op::Copy(ValueType::Vec3), &[96, 100], 1077);
                step(f, Op::Copy(ValueType::Float), &[43, 310], 1078);
                step(f, Op::Copy(ValueType::Float), &[45, 311], 1079);
                step(f, Op::Copy(ValueType::Vec3), &[391, 101], 1080);
                step(f, Op::SubV, &[99, 100, 102], 1081);
                step(f, Op::DeltaTime, &[312], 1082);
                step(f, Op::DivF, &[311, 312, 313], 1083);
                step(f, Op::ScaleV, &[102, 313, 103], 1084);
                step(f, Op::AddV, &[99, 103, 104], 1085);
                step(f, Op::AddV, &[100, 103, 105], 1086);
                step(f, Op::SubV, &[98, 105, 106], 1087);
                step(f, Op::FloatLerp, &[680, 682, 310, 314], 1088);
                step(f, Op::SubF, &[682, 314, 315], 1089);
                step(f, Op::ScaleV, &[106, 315, 107], 1090);
                step(f, Op::AddV, &[104, 107, 109], 1091);
                step(f, Op::MulF, &[310, 312, 316], 1092);
                step(f, Op::GreaterF, &[316, 680, 43], 1093);
                step(f, Op::DivF, &[314, 316, 317], 1094);
                step(f, Op::Select(ValueType::Float), &[43, 317, 682, 318], 1095);
                step(f, Op::ScaleV, &[102, 318, 108], 1096);
                step(f, Op::SubV, &[109, 108, 110], 1097);
                step(f, Op::Copy(ValueType::Vec3), &[110, 101], 1098);
                step(f, Op::Jump, &[1099], 1099)
            }
            1099 => {
                step(f, Op::BreakVector, &[101, 319, 320, 321], 1100);
                step(f, Op::ClampF, &[321, 54, 55, 322], 1101);
                step(f, Op::MakeVector, &[319, 320, 322, 111], 1102);
                step(f, Op::RotationFromNormal, &[115, 308, 309, 19], 1103);
                step(f, Op::PerFootRotationFactor, &[12, 88, 89, 305], 1104);
                step(f, Op::MulF, &[12, 305, 306], 1105);
                step(f, Op::SubF, &[682, 13, 287], 1106);
                step(f, Op::MulF, &[306, 287, 307], 1107);
                step(f, Op::QuatFromAxisAngle, &[394, 307, 18], 1108);
                step(f, Op::MulQ, &[19, 18, 20], 1109);
                step(f, Op::Select(ValueType::Quat), &[44, 20, 21, 22], 1110);
                step(f, Op::MakeTransform, &[111, 22, 392, 30], 1111);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 41, 30], 1112);
                step(f, Op::ArrayAt(Elem::Float), &[2, 41, 278], 1113);
                step(f, Op::SubF, &[682, 278, 279], 1114);
                step(f, Op::MaxF, &[279, 680, 280], 1115);
                step(f, Op::MulF, &[8, 5, 281], 1116);
                step(f, Op::MulF, &[280, 281, 282], 1117);
                step(f, Op::ScaleV, &[2, 282, 79], 1118);
                step(f, Op::SubV, &[114, 79, 92], 1119);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 41, 27], 1120);
                step(f, Op::BreakTransform, &[27, 93, 21, 94], 1121);
                step(f, Op::Select(ValueType::Vec3), &[44, 92, 93, 95], 1122);
                step(f, Op::MakeTransform, &[95, 91, 392, 29], 1123);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 41, 29], 1124);
                step(f, Op::JumpIfFalse, &[44, 1127], 1125)
            }
            1125 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 7], 1126);
                step(f, Op::Jump, &[1127], 1127)
            }
            1127 => {
                step(f, Op::Copy(ValueType::Int), &[3, 53], 1128);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 53, 33], 1129);
                step(f, Op::GreaterF, &[18, 680, 53], 1130);
                step(f, Op::InterpolateTransform, &[2, 110, 19, 31], 1131);
                step(f, Op::Select(ValueType::Transform), &[53, 31, 2, 32], 1132);
                step(f, Op::MakeAbsolute, &[33, 32, 34], 1133);
                step(f, Op::BreakTransform, &[34, 132, 24, 133], 1134);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 53, 35], 1135);
                step(f, Op::BreakTransform, &[35, 134, 25, 135], 1136);
                step(f, Op::AddF, &[58, 59, 349], 1137);
                step(f, Op::ClampSpatially, &[132, 134, 680, 349, 136], 1138);
                step(f, Op::SubF, &[682, 13, 364], 1139);
                step(f, Op::MulF, &[12, 364, 350], 1140);
                step(f, Op::LimitRotationAroundZ, &[24, 350, 87, 26], 1141);
                step(f, Op::MakeTransform, &[136, 26, 392, 36], 1142);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 53, 36], 1143);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 53, 50], 1144);
                step(f, Op::JumpIfFalse, &[50, 1198], 1145)
            }
            1145 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 53, 39], 1146);
                step(f, Op::BreakTransform, &[39, 142, 28, 143], 1147);
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 348], 1148);
                step(f, Op::SubF, &[682, 348, 361], 1149);
                step(f, Op::MulF, &[8, 5, 362], 1150);
                step(f, Op::MulF, &[361, 362, 363], 1151);
                step(f, Op::ScaleV, &[2, 363, 144], 1152);
                step(f, Op::AddV, &[142, 144, 145], 1153);
                step(f, Op::MakeTransform, &[145, 28, 392, 46], 1154);
                step(f, Op::Copy(ValueType::Transform), &[46, 47], 1155);
                step(f, Op::Copy(ValueType::Transform), &[110, 48], 1156);
                step(f, Op::BreakTransform, &[47, 173, 33, 174], 1157);
                step(f, Op::MakeVector, &[680, 680, 51, 175], 1158);
                step(f, Op::AddV, &[173, 175, 176], 1159);
                step(f, Op::SubV, &[173, 175, 177], 1160);
                step(f, Op::LineTrace, &[176, 177, 57, 178, 179, 391], 1161);
                step(f, Op::RotateVector, &[33, 394, 180], 1162);
                step(f, Op::FindQuatBetween, &[180, 179, 34], 1163);
                step(f, Op::MulQ, &[34, 33, 35], 1164);
                step(f, Op::MulF, &[49, 48, 392], 1165);
                step(f, Op::AddF, &[392, 57, 393], 1166);
                step(f, Op::NegF, &[393, 394], 1167);
                step(f, Op::MakeVector, &[680, 394, 680, 181], 1168);
                step(f, Op::RotateVector, &[35, 181, 183], 1169);
                step(f, Op::AddV, &[178, 183, 185], 1170);
                step(f, Op::AddV, &[185, 175, 187], 1171);
                step(f, Op::SubV, &[185, 175, 188], 1172);
                step(f, Op::LineTrace, &[187, 188, 58, 191, 192, 396], 1173);
                step(f, Op::BreakVector, &[191, 398, 399, 400], 1174);
                step(f, Op::BreakVector, &[185, 404, 405, 406], 1175);
                step(f, Op::SubF, &[400, 406, 410], 1176);
                step(f, Op::Select(ValueType::Float), &[58, 410, 680, 412], 1177);
                step(f, Op::AddF, &[53, 57, 395], 1178);
                step(f, Op::MakeVector, &[680, 395, 680, 182], 1179);
                step(f, Op::RotateVector, &[35, 182, 184], 1180);
                step(f, Op::AddV, &[178, 184, 186], 1181);
                step(f, Op::AddV, &[186, 175, 189], 1182);
                step(f, Op::SubV, &[186, 175, 190], 1183);
                step(f, Op::LineTrace, &[189, 190, 59, 193, 194, 397], 1184);
                step(f, Op::BreakVector, &[193, 401, 402, 403], 1185);
                step(f, Op::BreakVector, &[186, 407, 408, 409], 1186);
                step(f, Op::SubF, &[403, 409, 411], 1187);
                step(f, Op::Select(ValueType::Float), &[59, 411, 680, 413], 1188);
                step(f, Op::MaxF, &[412, 413, 414], 1189);
                step(f, Op::ClampF, &[414, 680, 56, 415], 1190);
                step(f, Op::MakeVector, &[680, 680, 415, 195], 1191);
                step(f, Op::AddV, &[178, 195, 196], 1192);
                step(f, Op::MakeTransform, &[196, 35, 392, 49], 1193);
                step(f, Op::Select(ValueType::Transform), &[57, 49, 47, 50], 1194);
                step(f, Op::Copy(ValueType::Transform), &[50, 48], 1195);
                step(f, Op::Jump, &[1196], 1196)
            }
            1196 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 53, 48], 1197);
                step(f, Op::Jump, &[1302], 1198)
            }
            1198 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 53, 51], 1199);
                step(f, Op::GreaterF, &[18, 680, 53], 1200);
                step(f, Op::InterpolateTransform, &[2, 110, 19, 31], 1201);
                step(f, Op::Select(ValueType::Transform), &[53, 31, 2, 32], 1202);
                step(f, Op::MakeAbsolute, &[51, 32, 52], 1203);
                step(f, Op::BreakTransform, &[52, 197, 36, 198], 1204);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 53, 39], 1205);
                step(f, Op::BreakTransform, &[39, 142, 28, 143], 1206);
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 348], 1207);
                step(f, Op::SubF, &[682, 348, 361], 1208);
                step(f, Op::MulF, &[8, 5, 362], 1209);
                step(f, Op::MulF, &[361, 362, 363], 1210);
                step(f, Op::ScaleV, &[2, 363, 144], 1211);
                step(f, Op::AddV, &[142, 144, 145], 1212);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 53, 53], 1213);
                step(f, Op::MakeAbsolute, &[53, 32, 54], 1214);
                step(f, Op::BreakTransform, &[54, 199, 37, 200], 1215);
                step(f, Op::ArrayAt(Elem::Float), &[3, 53, 416], 1216);
                step(f, Op::SubF, &[348, 416, 417], 1217);
                step(f, Op::DeltaTime, &[432], 1218);
                step(f, Op::DivF, &[45, 432, 418], 1219);
                step(f, Op::MulF, &[417, 418, 419], 1220);
                step(f, Op::AddF, &[416, 419, 420], 1221);
                step(f, Op::ClampF, &[420, 680, 682, 422], 1222);
                step(f, Op::AddF, &[348, 419, 421], 1223);
                step(f, Op::ClampF, &[421, 680, 682, 423], 1224);
                step(f, Op::AddF, &[422, 423, 424], 1225);
                step(f, Op::MulF, &[424, 681, 425], 1226);
                step(f, Op::SubF, &[682, 425, 426], 1227);
                step(f, Op::GreaterF, &[417, 680, 60], 1228);
                step(f, Op::SubF, &[423, 422, 427], 1229);
                step(f, Op::DivF, &[427, 417, 428], 1230);
                step(f, Op::Select(ValueType::Float), &[60, 428, 682, 429], 1231);
                step(f, Op::MulF, &[426, 429, 430], 1232);
                step(f, Op::MulF, &[73, 430, 431], 1233);
                step(f, Op::Copy(ValueType::Vec3), &[197, 201], 1234);
                step(f, Op::Copy(ValueType::Vec3), &[145, 202], 1235);
                step(f, Op::Copy(ValueType::Vec3), &[199, 203], 1236);
                step(f, Op::Copy(ValueType::Float), &[431, 433], 1237);
                step(f, Op::Copy(ValueType::Float), &[45, 434], 1238);
                step(f, Op::Copy(ValueType::Vec3), &[391, 204], 1239);
                step(f, Op::SubV, &[202, 203, 205], 1240);
                step(f, Op::DeltaTime, &[435], 1241);
                step(f, Op::DivF, &[434, 435, 436], 1242);
                step(f, Op::ScaleV, &[205, 436, 206], 1243);
                step(f, Op::AddV, &[202, 206, 207], 1244);
                step(f, Op::AddV, &[203, 206, 208], 1245);
                step(f, Op::SubV, &[201, 208, 209], 1246);
                step(f, Op::FloatLerp, &[680, 682, 433, 437], 1247);
                step(f, Op::SubF, &[682, 437, 438], 1248);
                step(f, Op::ScaleV, &[209, 438, 210], 1249);
                step(f, Op::AddV, &[207, 210, 212], 1250);
                step(f, Op::MulF, &[433, 435, 439], 1251);
                step(f, Op::GreaterF, &[439, 680, 61], 1252);
                step(f, Op::DivF, &[437, 439, 440], 1253);
                step(f, Op::Select(ValueType::Float), &[61, 440, 682, 441], 1254);
                step(f, Op::ScaleV, &[205, 441, 211], 1255);
                step(f, Op::SubV, &[212, 211, 213], 1256);
                step(f, Op::Copy(ValueType::Vec3), &[213, 204], 1257);
                step(f, Op::Jump, &[1258], 1258)
            }
            1258 => {
                step(f, Op::MakeTransform, &[204, 28, 392, 56], 1259);
                step(f, Op::Copy(ValueType::Transform), &[56, 57], 1260);
                step(f, Op::Copy(ValueType::Transform), &[110, 58], 1261);
                step(f, Op::BreakTransform, &[57, 214, 38, 215], 1262);
                step(f, Op::MakeVector, &[680, 680, 51, 216], 1263);
                step(f, Op::AddV, &[214, 216, 217], 1264);
                step(f, Op::SubV, &[214, 216, 218], 1265);
                step(f, Op::LineTrace, &[217, 218, 62, 219, 220, 442], 1266);
                step(f, Op::RotateVector, &[38, 394, 221], 1267);
                step(f, Op::FindQuatBetween, &[221, 220, 39], 1268);
                step(f, Op::MulQ, &[39, 38, 40], 1269);
                step(f, Op::MulF, &[49, 48, 443], 1270);
                step(f, Op::AddF, &[443, 57, 444], 1271);
                step(f, Op::NegF, &[444, 445], 1272);
                step(f, Op::MakeVector, &[680, 445, 680, 222], 1273);
                step(f, Op::RotateVector, &[40, 222, 224], 1274);
                step(f, Op::AddV, &[219, 224, 226], 1275);
                step(f, Op::AddV, &[226, 216, 228], 1276);
                step(f, Op::SubV, &[226, 216, 229], 1277);
                step(f, Op::LineTrace, &[228, 229, 63, 232, 233, 447], 1278);
                step(f, Op::BreakVector, &[232, 449, 450, 451], 1279);
                step(f, Op::BreakVector, &[226, 455, 456, 457], 1280);
                step(f, Op::SubF, &[451, 457, 461], 1281);
                step(f, Op::Select(ValueType::Float), &[63, 461, 680, 463], 1282);
                step(f, Op::AddF, &[53, 57, 446], 1283);
                step(f, Op::MakeVector, &[680, 446, 680, 223], 1284);
                step(f, Op::RotateVector, &[40, 223, 225], 1285);
                step(f, Op::AddV, &[219, 225, 227], 1286);
                step(f, Op::AddV, &[227, 216, 230], 1287);
                step(f, Op::SubV, &[227, 216, 231], 1288);
                step(f, Op::LineTrace, &[230, 231, 64, 234, 235, 448], 1289);
                step(f, Op::BreakVector, &[234, 452, 453, 454], 1290);
                step(f, Op::BreakVector, &[227, 458, 459, 460], 1291);
                step(f, Op::SubF, &[454, 460, 462], 1292);
                step(f, Op::Select(ValueType::Float), &[64, 462, 680, 464], 1293);
                step(f, Op::MaxF, &[463, 464, 465], 1294);
                step(f, Op::ClampF, &[465, 680, 56, 466], 1295);
                step(f, Op::MakeVector, &[680, 680, 466, 236], 1296);
                step(f, Op::AddV, &[219, 236, 237], 1297);
                step(f, Op::MakeTransform, &[237, 40, 392, 59], 1298);
                step(f, Op::Select(ValueType::Transform), &[62, 59, 57, 60], 1299);
                step(f, Op::Copy(ValueType::Transform), &[60, 58], 1300);
                step(f, Op::Jump, &[1301], 1301)
            }
            1301 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 53, 58], 1302);
                1302
            }
            1302 => {
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 348], 1303);
                step(f, Op::GreaterEqualF, &[348, 682, 51], 1304);
                step(f, Op::JumpIfFalse, &[51, 1381], 1305)
            }
            1305 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 53, 50], 1306);
                step(f, Op::JumpIfFalse, &[50, 1308], 1307)
            }
            1307 => {
                step(f, Op::Jump, &[1361], 1308)
            }
            1308 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 53, 61], 1309);
                step(f, Op::BreakTransform, &[61, 238, 41, 239], 1310);
                step(f, Op::Equals(Elem::Int), &[53, 65, 52], 1311);
                step(f, Op::Select(ValueType::Int), &[52, 66, 65, 54], 1312);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 54, 40], 1313);
                step(f, Op::BreakTransform, &[40, 146, 29, 147], 1314);
                step(f, Op::SubF, &[682, 13, 364], 1315);
                step(f, Op::MulF, &[12, 364, 365], 1316);
                step(f, Op::FootAvoidance, &[238, 146, 365, 52, 74, 148], 1317);
                step(f, Op::MakeTransform, &[148, 41, 392, 41], 1318);
                step(f, Op::Copy(ValueType::Transform), &[41, 42], 1319);
                step(f, Op::Copy(ValueType::Transform), &[110, 43], 1320);
                step(f, Op::BreakTransform, &[42, 149, 30, 150], 1321);
                step(f, Op::MakeVector, &[680, 680, 51, 151], 1322);
                step(f, Op::AddV, &[149, 151, 152], 1323);
                step(f, Op::SubV, &[149, 151, 153], 1324);
                step(f, Op::LineTrace, &[152, 153, 54, 154, 155, 366], 1325);
                step(f, Op::RotateVector, &[30, 394, 156], 1326);
                step(f, Op::FindQuatBetween, &[156, 155, 31], 1327);
                step(f, Op::MulQ, &[31, 30, 32], 1328);
                step(f, Op::MulF, &[49, 48, 367], 1329);
                step(f, Op::AddF, &[367, 57, 368], 1330);
                step(f, Op::NegF, &[368, 369], 1331);
                step(f, Op::MakeVector, &[680, 369, 680, 157], 1332);
                step(f, Op::RotateVector, &[32, 157, 159], 1333);
                step(f, Op::AddV, &[154, 159, 161], 1334);
                step(f, Op::AddV, &[161, 151, 163], 1335);
                step(f, Op::SubV, &[161, 151, 164], 1336);
                step(f, Op::LineTrace, &[163, 164, 55, 167, 168, 371], 1337);
                step(f, Op::BreakVector, &[167, 373, 374, 375], 1338);
                step(f, Op::BreakVector, &[161, 379, 380, 381], 1339);
                step(f, Op::SubF, &[375, 381, 385], 1340);
                step(f, Op::Select(ValueType::Float), &[55, 385, 680, 387], 1341);
                step(f, Op::AddF, &[53, 57, 370], 1342);
                step(f, Op::MakeVector, &[680, 370, 680, 158], 1343);
                step(f, Op::RotateVector, &[32, 158, 160], 1344);
                step(f, Op::AddV, &[154, 160, 162], 1345);
                step(f, Op::AddV, &[162, 151, 165], 1346);
                step(f, Op::SubV, &[162, 151, 166], 1347);
                step(f, Op::LineTrace, &[165, 166, 56, 169, 170, 372], 1348);
                step(f, Op::BreakVector, &[169, 376, 377, 378], 1349);
                step(f, Op::BreakVector, &[162, 382, 383, 384], 1350);
                step(f, Op::SubF, &[378, 384, 386], 1351);
                step(f, Op::Select(ValueType::Float), &[56, 386, 680, 388], 1352);
                step(f, Op::MaxF, &[387, 388, 389], 1353);
                step(f, Op::ClampF, &[389, 680, 56, 390], 1354);
                step(f, Op::MakeVector, &[680, 680, 390, 171], 1355);
                step(f, Op::AddV, &[154, 171, 172], 1356);
                step(f, Op::MakeTransform, &[172, 32, 392, 44], 1357);
                step(f, Op::Select(ValueType::Transform), &[54, 44, 42, 45], 1358);
                step(f, Op::Copy(ValueType::Transform), &[45, 43], 1359);
                step(f, Op::Jump, &[1360], 1360)
            }
            1360 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 53, 43], 1361);
                1361
            }
            1361 => {
                step(f, Op::ArrayAt(Elem::Transform), &[7, 53, 35], 1362);
                step(f, Op::BreakTransform, &[35, 134, 25, 135], 1363);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 53, 37], 1364);
                step(f, Op::BreakTransform, &[37, 137, 27, 138], 1365);
                step(f, Op::SubV, &[137, 134, 139], 1366);
                step(f, Op::LengthV, &[139, 351], 1367);
                step(f, Op::SubF, &[58, 59, 352], 1368);
                step(f, Op::SubF, &[351, 352, 353], 1369);
                step(f, Op::MulF, &[59, 685, 354], 1370);
                step(f, Op::ClampF, &[353, 680, 354, 355], 1371);
                step(f, Op::MulF, &[355, 355, 356], 1372);
                step(f, Op::MulF, &[59, 692, 357], 1373);
                step(f, Op::DivF, &[356, 357, 358], 1374);
                step(f, Op::SubF, &[351, 358, 359], 1375);
                step(f, Op::DivF, &[359, 351, 360], 1376);
                step(f, Op::ScaleV, &[139, 360, 140], 1377);
                step(f, Op::AddV, &[134, 140, 141], 1378);
                step(f, Op::MakeTransform, &[141, 27, 392, 38], 1379);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 53, 38], 1380);
                step(f, Op::Jump, &[1588], 1381)
            }
            1381 => {
                step(f, Op::ArrayAt(Elem::Transform), &[7, 53, 35], 1382);
                step(f, Op::BreakTransform, &[35, 134, 25, 135], 1383);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 53, 37], 1384);
                step(f, Op::BreakTransform, &[37, 137, 27, 138], 1385);
                step(f, Op::SubV, &[137, 134, 139], 1386);
                step(f, Op::LengthV, &[139, 351], 1387);
                step(f, Op::SubF, &[58, 59, 352], 1388);
                step(f, Op::SubF, &[351, 352, 353], 1389);
                step(f, Op::MulF, &[59, 685, 354], 1390);
                step(f, Op::ClampF, &[353, 680, 354, 355], 1391);
                step(f, Op::MulF, &[355, 355, 356], 1392);
                step(f, Op::MulF, &[59, 692, 357], 1393);
                step(f, Op::DivF, &[356, 357, 358], 1394);
                step(f, Op::SubF, &[351, 358, 359], 1395);
                step(f, Op::DivF, &[359, 351, 360], 1396);
                step(f, Op::ScaleV, &[139, 360, 140], 1397);
                step(f, Op::AddV, &[134, 140, 141], 1398);
                step(f, Op::MakeTransform, &[141, 27, 392, 38], 1399);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 53, 61], 1400);
                step(f, Op::ClampF, &[348, 680, 682, 467], 1401);
                step(f, Op::Copy(ValueType::Transform), &[38, 66], 1402);
                step(f, Op::Copy(ValueType::Transform), &[61, 67], 1403);
                step(f, Op::Copy(ValueType::Float), &[467, 485], 1404);
                step(f, Op::Copy(ValueType::Transform), &[110, 68], 1405);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[3, 2], 1406);
                step(f, Op::ArrayReset(Elem::Vec3), &[2], 1407);
                step(f, Op::BreakTransform, &[66, 256, 46, 257], 1408);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 256], 1409);
                step(f, Op::BreakTransform, &[66, 256, 46, 257], 1410);
                step(f, Op::UnitV, &[2, 255], 1411);
                step(f, Op::LengthV, &[2, 486], 1412);
                step(f, Op::RemapF, &[486, 680, 60, 680, 61, 79, 487], 1413);
                step(f, Op::ScaleV, &[255, 487, 260], 1414);
                step(f, Op::SubV, &[256, 260, 266], 1415);
                step(f, Op::MakeVector, &[680, 680, 63, 264], 1416);
                step(f, Op::AddV, &[266, 264, 268], 1417);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 268], 1418);
                step(f, Op::BreakTransform, &[66, 256, 46, 257], 1419);
                step(f, Op::UnitV, &[2, 255], 1420);
                step(f, Op::LengthV, &[2, 486], 1421);
                step(f, Op::RemapF, &[486, 680, 60, 680, 61, 79, 487], 1422);
                step(f, Op::ScaleV, &[255, 487, 260], 1423);
                step(f, Op::SubV, &[256, 260, 266], 1424);
                step(f, Op::MakeVector, &[680, 680, 63, 264], 1425);
                step(f, Op::AddV, &[266, 264, 268], 1426);
                step(f, Op::RemapF, &[486, 680, 60, 680, 65, 79, 489], 1427);
                step(f, Op::MakeVector, &[680, 680, 489, 262], 1428);
                step(f, Op::AddV, &[268, 262, 272], 1429);
                step(f, Op::BreakTransform, &[67, 258, 47, 259], 1430);
                step(f, Op::BreakVector, &[258, 494, 495, 496], 1431);
                step(f, Op::BreakVector, &[256, 491, 492, 493], 1432);
                step(f, Op::SubF, &[496, 493, 497], 1433);
                step(f, Op::MaxF, &[497, 680, 499], 1434);
                step(f, Op::MulF, &[499, 67, 503], 1435);
                step(f, Op::AbsF, &[497, 501], 1436);
                step(f, Op::RemapF, &[501, 680, 70, 680, 69, 79, 502], 1437);
                step(f, Op::AddF, &[503, 502, 505], 1438);
                step(f, Op::MakeVector, &[680, 680, 505, 270], 1439);
                step(f, Op::AddV, &[272, 270, 274], 1440);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 274], 1441);
                step(f, Op::BreakTransform, &[66, 256, 46, 257], 1442);
                step(f, Op::UnitV, &[2, 255], 1443);
                step(f, Op::LengthV, &[2, 486], 1444);
                step(f, Op::RemapF, &[486, 680, 60, 680, 61, 79, 487], 1445);
                step(f, Op::ScaleV, &[255, 487, 260], 1446);
                step(f, Op::SubV, &[256, 260, 266], 1447);
                step(f, Op::MakeVector, &[680, 680, 63, 264], 1448);
                step(f, Op::AddV, &[266, 264, 268], 1449);
                step(f, Op::RemapF, &[486, 680, 60, 680, 65, 79, 489], 1450);
                step(f, Op::MakeVector, &[680, 680, 489, 262], 1451);
                step(f, Op::AddV, &[268, 262, 272], 1452);
                step(f, Op::BreakTransform, &[67, 258, 47, 259], 1453);
                step(f, Op::BreakVector, &[258, 494, 495, 496], 1454);
                step(f, Op::BreakVector, &[256, 491, 492, 493], 1455);
                step(f, Op::SubF, &[496, 493, 497], 1456);
                step(f, Op::MaxF, &[497, 680, 499], 1457);
                step(f, Op::MulF, &[499, 67, 503], 1458);
                step(f, Op::AbsF, &[497, 501], 1459);
                step(f, Op::RemapF, &[501, 680, 70, 680, 69, 79, 502], 1460);
                step(f, Op::AddF, &[503, 502, 505], 1461);
                step(f, Op::MakeVector, &[680, 680, 505, 270], 1462);
                step(f, Op::AddV, &[272, 270, 274], 1463);
                step(f, Op::RemapF, &[486, 680, 60, 680, 62, 79, 488], 1464);
                step(f, Op::ScaleV, &[255, 488, 261], 1465);
                step(f, Op::AddV, &[258, 261, 267], 1466);
                step(f, Op::MakeVector, &[680, 680, 64, 265], 1467);
                step(f, Op::AddV, &[267, 265, 269], 1468);
                step(f, Op::RemapF, &[486, 680, 60, 680, 66, 79, 490], 1469);
                step(f, Op::MakeVector, &[680, 680, 490, 263], 1470);
                step(f, Op::AddV, &[269, 263, 273], 1471);
                step(f, Op::NegF, &[497, 498], 1472);
                step(f, Op::MaxF, &[498, 680, 500], 1473);
                step(f, Op::MulF, &[500, 68, 504], 1474);
                step(f, Op::AddF, &[504, 502, 506], 1475);
                step(f, Op::MakeVector, &[680, 680, 506, 271], 1476);
                step(f, Op::AddV, &[273, 271, 275], 1477);
                step(f, Op::LerpV, &[274, 275, 681, 276], 1478);
                step(f, Op::GetTransform, &[36, 65, 79, 69], 1479);
                step(f, Op::BreakTransform, &[69, 277, 48, 278], 1480);
                step(f, Op::BreakVector, &[277, 516, 517, 518], 1481);
                step(f, Op::SubF, &[682, 13, 510], 1482);
                step(f, Op::MulF, &[71, 510, 511], 1483);
                step(f, Op::MulF, &[12, 511, 512], 1484);
                step(f, Op::QuatFromAxisAngle, &[394, 512, 49], 1485);
                step(f, Op::SubV, &[276, 277, 279], 1486);
                step(f, Op::BreakVector, &[279, 507, 508, 509], 1487);
                step(f, Op::MakeVector, &[507, 508, 680, 280], 1488);
                step(f, Op::RotateVector, &[49, 280, 281], 1489);
                step(f, Op::BreakVector, &[281, 513, 514, 515], 1490);
                step(f, Op::AddF, &[516, 513, 522], 1491);
                step(f, Op::AddF, &[517, 514, 523], 1492);
                step(f, Op::BreakVector, &[276, 519, 520, 521], 1493);
                step(f, Op::MakeVector, &[522, 523, 521, 282], 1494);
                step(f, Op::DistanceV, &[256, 258, 524], 1495);
                step(f, Op::RemapF, &[524, 685, 693, 680, 682, 79, 525], 1496);
                step(f, Op::LerpV, &[276, 282, 525, 283], 1497);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 283], 1498);
                step(f, Op::BreakTransform, &[67, 258, 47, 259], 1499);
                step(f, Op::UnitV, &[2, 255], 1500);
                step(f, Op::LengthV, &[2, 486], 1501);
                step(f, Op::RemapF, &[486, 680, 60, 680, 62, 79, 488], 1502);
                step(f, Op::ScaleV, &[255, 488, 261], 1503);
                step(f, Op::AddV, &[258, 261, 267], 1504);
                step(f, Op::MakeVector, &[680, 680, 64, 265], 1505);
                step(f, Op::AddV, &[267, 265, 269], 1506);
                step(f, Op::RemapF, &[486, 680, 60, 680, 66, 79, 490], 1507);
                step(f, Op::MakeVector, &[680, 680, 490, 263], 1508);
                step(f, Op::AddV, &[269, 263, 273], 1509);
                step(f, Op::BreakVector, &[258, 494, 495, 496], 1510);
                step(f, Op::BreakTransform, &[66, 256, 46, 257], 1511);
                step(f, Op::BreakVector, &[256, 491, 492, 493], 1512);
                step(f, Op::SubF, &[496, 493, 497], 1513);
                step(f, Op::NegF, &[497, 498], 1514);
                step(f, Op::MaxF, &[498, 680, 500], 1515);
                step(f, Op::MulF, &[500, 68, 504], 1516);
                step(f, Op::AbsF, &[497, 501], 1517);
                step(f, Op::RemapF, &[501, 680, 70, 680, 69, 79, 502], 1518);
                step(f, Op::AddF, &[504, 502, 506], 1519);
                step(f, Op::MakeVector, &[680, 680, 506, 271], 1520);
                step(f, Op::AddV, &[273, 271, 275], 1521);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 275], 1522);
                step(f, Op::BreakTransform, &[67, 258, 47, 259], 1523);
                step(f, Op::UnitV, &[2, 255], 1524);
                step(f, Op::LengthV, &[2, 486], 1525);
                step(f, Op::RemapF, &[486, 680, 60, 680, 62, 79, 488], 1526);
                step(f, Op::ScaleV, &[255, 488, 261], 1527);
                step(f, Op::AddV, &[258, 261, 267], 1528);
                step(f, Op::MakeVector, &[680, 680, 64, 265], 1529);
                step(f, Op::AddV, &[267, 265, 269], 1530);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 269], 1531);
                step(f, Op::BreakTransform, &[67, 258, 47, 259], 1532);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 258], 1533);
                step(f, Op::JumpIfFalse, &[8, 1536], 1534)
            }
            1534 => {
                step(f, Op::DrawSpline, &[2, 65, 68, 681, 396], 1535);
                step(f, Op::Jump, &[1536], 1536)
            }
            1536 => {
                step(f, Op::Spline, &[2, 485, 65, 284, 285], 1537);
                step(f, Op::BreakTransform, &[66, 256, 46, 257], 1538);
                step(f, Op::BreakTransform, &[67, 258, 47, 259], 1539);
                step(f, Op::SlerpQ, &[46, 47, 485, 50], 1540);
                step(f, Op::MulF, &[485, 694, 534], 1541);
                step(f, Op::SinF, &[534, 535], 1542);
                step(f, Op::Copy(ValueType::Float), &[485, 526], 1543);
                step(f, Op::Copy(ValueType::Float), &[680, 527], 1544);
                step(f, Op::DivF, &[526, 82, 528], 1545);
                step(f, Op::ClampF, &[528, 680, 682, 529], 1546);
                step(f, Op::MulF, &[529, 529, 530], 1547);
                step(f, Op::MulF, &[529, 685, 531], 1548);
                step(f, Op::SubF, &[686, 531, 532], 1549);
                step(f, Op::MulF, &[530, 532, 533], 1550);
                step(f, Op::Copy(ValueType::Float), &[533, 527], 1551);
                step(f, Op::Jump, &[1552], 1552)
            }
            1552 => {
                step(f, Op::MulF, &[535, 527, 536], 1553);
                step(f, Op::MulF, &[536, 72, 537], 1554);
                step(f, Op::SlerpQ, &[50, 91, 537, 51], 1555);
                step(f, Op::MakeTransform, &[284, 51, 392, 70], 1556);
                step(f, Op::Copy(ValueType::Transform), &[70, 68], 1557);
                step(f, Op::Jump, &[1558], 1558)
            }
            1558 => {
                step(f, Op::BreakTransform, &[68, 240, 42, 241], 1559);
                step(f, Op::Equals(Elem::Int), &[53, 65, 52], 1560);
                step(f, Op::Select(ValueType::Int), &[52, 66, 65, 54], 1561);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 54, 40], 1562);
                step(f, Op::BreakTransform, &[40, 146, 29, 147], 1563);
                step(f, Op::SubF, &[682, 13, 364], 1564);
                step(f, Op::MulF, &[12, 364, 365], 1565);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 54, 65], 1566);
                step(f, Op::Select(ValueType::Float), &[65, 75, 680, 470], 1567);
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 348], 1568);
                step(f, Op::ClampF, &[348, 680, 682, 467], 1569);
                step(f, Op::MulF, &[467, 694, 468], 1570);
                step(f, Op::SinF, &[468, 469], 1571);
                step(f, Op::MulF, &[469, 469, 471], 1572);
                step(f, Op::MulF, &[470, 471, 472], 1573);
                step(f, Op::AddF, &[74, 472, 473], 1574);
                step(f, Op::FootAvoidance, &[240, 146, 365, 52, 473, 242], 1575);
                step(f, Op::SubV, &[242, 240, 243], 1576);
                step(f, Op::LengthV, &[243, 474], 1577);
                step(f, Op::AddF, &[474, 472, 475], 1578);
                step(f, Op::DivF, &[474, 475, 476], 1579);
                step(f, Op::ScaleV, &[243, 476, 244], 1580);
                step(f, Op::AddV, &[240, 244, 245], 1581);
                step(f, Op::SubF, &[682, 114, 477], 1582);
                step(f, Op::MulF, &[3, 477, 478], 1583);
                step(f, Op::MulF, &[478, 471, 479], 1584);
                step(f, Op::MakeVector, &[680, 680, 479, 246], 1585);
                step(f, Op::AddV, &[245, 246, 247], 1586);
                step(f, Op::MakeTransform, &[247, 42, 392, 62], 1587);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 53, 62], 1588);
                1588
            }
            1588 => {
                step(f, Op::GreaterF, &[18, 680, 53], 1589);
                step(f, Op::JumpIfFalse, &[53, 1606], 1590)
            }
            1590 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 53, 63], 1591);
                step(f, Op::BreakTransform, &[63, 248, 43, 249], 1592);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 53, 64], 1593);
                step(f, Op::BreakTransform, &[64, 250, 44, 251], 1594);
                step(f, Op::MulF, &[18, 18, 480], 1595);
                step(f, Op::LerpV, &[248, 250, 480, 252], 1596);
                step(f, Op::SubF, &[682, 18, 481], 1597);
                step(f, Op::MulF, &[18, 481, 482], 1598);
                step(f, Op::MulF, &[116, 685, 483], 1599);
                step(f, Op::MulF, &[482, 483, 484], 1600);
                step(f, Op::MakeVector, &[680, 680, 484, 253], 1601);
                step(f, Op::AddV, &[252, 253, 254], 1602);
                step(f, Op::SlerpQ, &[43, 44, 18, 45], 1603);
                step(f, Op::MakeTransform, &[254, 45, 392, 65], 1604);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 53, 65], 1605);
                step(f, Op::Jump, &[1606], 1606)
            }
            1606 => {
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 348], 1607);
                step(f, Op::GreaterEqualF, &[348, 682, 51], 1608);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 53, 51], 1609);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 53, 39], 1610);
                step(f, Op::BreakTransform, &[39, 142, 28, 143], 1611);
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 348], 1612);
                step(f, Op::SubF, &[682, 348, 361], 1613);
                step(f, Op::MulF, &[8, 5, 362], 1614);
                step(f, Op::MulF, &[361, 362, 363], 1615);
                step(f, Op::ScaleV, &[2, 363, 144], 1616);
                step(f, Op::AddV, &[142, 144, 145], 1617);
                step(f, Op::MakeTransform, &[145, 91, 392, 55], 1618);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 53, 55], 1619);
                step(f, Op::Copy(ValueType::Bone), &[0, 17], 1620);
                step(f, Op::Copy(ValueType::Int), &[3, 55], 1621);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 55, 71], 1622);
                step(f, Op::BreakTransform, &[71, 286, 52, 287], 1623);
                step(f, Op::MakeVector, &[680, 680, 46, 296], 1624);
                step(f, Op::AddV, &[286, 296, 297], 1625);
                step(f, Op::GetTransform, &[17, 65, 79, 73], 1626);
                step(f, Op::BreakTransform, &[73, 291, 54, 292], 1627);
                step(f, Op::MakeTransform, &[297, 54, 392, 75], 1628);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 55, 20], 1629);
                step(f, Op::GetTransform, &[20, 65, 79, 74], 1630);
                step(f, Op::BreakTransform, &[74, 293, 55, 294], 1631);
                step(f, Op::SubV, &[293, 291, 295], 1632);
                step(f, Op::AddV, &[297, 295, 298], 1633);
                step(f, Op::FootPivots, &[297, 298, 48, 47, 46, 49, 299, 300, 301], 1634);
                step(f, Op::GetParent, &[17, 18], 1635);
                step(f, Op::GetParent, &[18, 19], 1636);
                step(f, Op::GetTransform, &[19, 65, 80, 72], 1637);
                step(f, Op::BreakTransform, &[72, 288, 53, 289], 1638);
                step(f, Op::SubV, &[286, 288, 290], 1639);
                step(f, Op::DotV, &[290, 395, 538], 1640);
                step(f, Op::RemapF, &[538, 77, 76, 78, 680, 79, 541], 1641);
                step(f, Op::LengthV, &[2, 539], 1642);
                step(f, Op::RemapF, &[539, 680, 86, 680, 682, 79, 540], 1643);
                step(f, Op::MulF, &[541, 540, 542], 1644);
                step(f, Op::QuatFromAxisAngle, &[397, 542, 56], 1645);
                step(f, Op::RotateAroundPoint, &[75, 299, 56, 76], 1646);
                step(f, Op::ArrayAt(Elem::Float), &[2, 55, 543], 1647);
                step(f, Op::Copy(ValueType::Float), &[543, 545], 1648);
                step(f, Op::Copy(ValueType::Float), &[680, 546], 1649);
                step(f, Op::DivF, &[545, 82, 547], 1650);
                step(f, Op::ClampF, &[547, 680, 682, 548], 1651);
                step(f, Op::MulF, &[548, 548, 549], 1652);
                step(f, Op::MulF, &[548, 685, 550], 1653);
                step(f, Op::SubF, &[686, 550, 551], 1654);
                step(f, Op::MulF, &[549, 551, 552], 1655);
                step(f, Op::Copy(ValueType::Float), &[552, 546], 1656);
                step(f, Op::Jump, &[1657], 1657)
            }
            1657 => {
                step(f, Op::SubF, &[682, 543, 544], 1658);
                step(f, Op::Copy(ValueType::Float), &[544, 553], 1659);
                step(f, Op::Copy(ValueType::Float), &[680, 554], 1660);
                step(f, Op::DivF, &[553, 82, 555], 1661);
                step(f, Op::ClampF, &[555, 680, 682, 556], 1662);
                step(f, Op::MulF, &[556, 556, 557], 1663);
                step(f, Op::MulF, &[556, 685, 558], 1664);
                step(f, Op::SubF, &[686, 558, 559], 1665);
                step(f, Op::MulF, &[557, 559, 560], 1666);
                step(f, Op::Copy(ValueType::Float), &[560, 554], 1667);
                step(f, Op::Jump, &[1668], 1668)
            }
            1668 => {
                step(f, Op::MulF, &[546, 554, 561], 1669);
                step(f, Op::LerpF, &[81, 682, 561, 562], 1670);
                step(f, Op::MulF, &[542, 562, 563], 1671);
                step(f, Op::QuatFromAxisAngle, &[397, 563, 57], 1672);
                step(f, Op::SubV, &[300, 299, 302], 1673);
                step(f, Op::RotateVector, &[57, 302, 303], 1674);
                step(f, Op::AddV, &[299, 303, 304], 1675);
                step(f, Op::RemapF, &[538, 79, 77, 80, 680, 79, 564], 1676);
                step(f, Op::MulF, &[564, 540, 565], 1677);
                step(f, Op::QuatFromAxisAngle, &[397, 565, 58], 1678);
                step(f, Op::RotateAroundPoint, &[76, 304, 58, 77], 1679);
                step(f, Op::RemapF, &[538, 83, 84, 680, 85, 79, 566], 1680);
                step(f, Op::MulF, &[566, 540, 567], 1681);
                step(f, Op::QuatFromAxisAngle, &[397, 567, 59], 1682);
                step(f, Op::RotateAroundPoint, &[77, 301, 59, 78], 1683);
                step(f, Op::SubF, &[682, 13, 568], 1684);
                step(f, Op::MulF, &[12, 568, 569], 1685);
                step(f, Op::LimitRotationAroundZ, &[52, 569, 87, 60], 1686);
                step(f, Op::RotateAroundPoint, &[78, 286, 60, 79], 1687);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 55, 79], 1688);
                step(f, Op::JumpIfFalse, &[8, 1770], 1689)
            }
            1689 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 55, 71], 1690);
                step(f, Op::BreakTransform, &[71, 286, 52, 287], 1691);
                step(f, Op::MakeVector, &[680, 680, 46, 296], 1692);
                step(f, Op::AddV, &[286, 296, 297], 1693);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 55, 20], 1694);
                step(f, Op::GetTransform, &[20, 65, 79, 74], 1695);
                step(f, Op::BreakTransform, &[74, 293, 55, 294], 1696);
                step(f, Op::GetTransform, &[17, 65, 79, 73], 1697);
                step(f, Op::BreakTransform, &[73, 291, 54, 292], 1698);
                step(f, Op::SubV, &[293, 291, 295], 1699);
                step(f, Op::AddV, &[297, 295, 298], 1700);
                step(f, Op::FootPivots, &[297, 298, 48, 47, 46, 49, 299, 300, 301], 1701);
                step(f, Op::DrawPoint, &[301, 686, 397], 1702);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 55, 71], 1703);
                step(f, Op::BreakTransform, &[71, 286, 52, 287], 1704);
                step(f, Op::MakeVector, &[680, 680, 46, 296], 1705);
                step(f, Op::AddV, &[286, 296, 297], 1706);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 55, 20], 1707);
                step(f, Op::GetTransform, &[20, 65, 79, 74], 1708);
                step(f, Op::BreakTransform, &[74, 293, 55, 294], 1709);
                step(f, Op::GetTransform, &[17, 65, 79, 73], 1710);
                step(f, Op::BreakTransform, &[73, 291, 54, 292], 1711);
                step(f, Op::SubV, &[293, 291, 295], 1712);
                step(f, Op::AddV, &[297, 295, 298], 1713);
                step(f, Op::FootPivots, &[297, 298, 48, 47, 46, 49, 299, 300, 301], 1714);
                step(f, Op::DrawPoint, &[299, 686, 395], 1715);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 55, 71], 1716);
                step(f, Op::BreakTransform, &[71, 286, 52, 287], 1717);
                step(f, Op::MakeVector, &[680, 680, 46, 296], 1718);
                step(f, Op::AddV, &[286, 296, 297], 1719);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 55, 20], 1720);
                step(f, Op::GetTransform, &[20, 65, 79, 74], 1721);
                step(f, Op::BreakTransform, &[74, 293, 55, 294], 1722);
                step(f, Op::GetTransform, &[17, 65, 79, 73], 1723);
                step(f, Op::BreakTransform, &[73, 291, 54, 292], 1724);
                step(f, Op::SubV, &[293, 291, 295], 1725);
                step(f, Op::AddV, &[297, 295, 298], 1726);
                step(f, Op::FootPivots, &[297, 298, 48, 47, 46, 49, 299, 300, 301], 1727);
                step(f, Op::GetParent, &[17, 18], 1728);
                step(f, Op::GetParent, &[18, 19], 1729);
                step(f, Op::GetTransform, &[19, 65, 80, 72], 1730);
                step(f, Op::BreakTransform, &[72, 288, 53, 289], 1731);
                step(f, Op::SubV, &[286, 288, 290], 1732);
                step(f, Op::DotV, &[290, 395, 538], 1733);
                step(f, Op::RemapF, &[538, 77, 76, 78, 680, 79, 541], 1734);
                step(f, Op::LengthV, &[2, 539], 1735);
                step(f, Op::RemapF, &[539, 680, 86, 680, 682, 79, 540], 1736);
                step(f, Op::MulF, &[541, 540, 542], 1737);
                step(f, Op::ArrayAt(Elem::Float), &[2, 55, 543], 1738);
                step(f, Op::Copy(ValueType::Float), &[543, 545], 1739);
                step(f, Op::Copy(ValueType::Float), &[680, 546], 1740);
                step(f, Op::DivF, &[545, 82, 547], 1741);
                step(f, Op::ClampF, &[547, 680, 682, 548], 1742);
                step(f, Op::MulF, &[548, 548, 549], 1743);
                step(f, Op::MulF, &[548, 685, 550], 1744);
                step(f, Op::SubF, &[686, 550, 551], 1745);
                step(f, Op::MulF, &[549, 551, 552], 1746);
                step(f, Op::Copy(ValueType::Float), &[552, 546], 1747);
                step(f, Op::Jump, &[1748], 1748)
            }
            1748 => {
                step(f, Op::SubF, &[682, 543, 544], 1749);
                step(f, Op::Copy(ValueType::Float), &[544, 553], 1750);
                step(f, Op::Copy(ValueType::Float), &[680, 554], 1751);
                step(f, Op::DivF, &[553, 82, 555], 1752);
                step(f, Op::ClampF, &[555, 680, 682, 556], 1753);
                step(f, Op::MulF, &[556, 556, 557], 1754);
                step(f, Op::MulF, &[556, 685, 558], 1755);
                step(f, Op::SubF, &[686, 558, 559], 1756);
                step(f, Op::MulF, &[557, 559, 560], 1757);
                step(f, Op::Copy(ValueType::Float), &[560, 554], 1758);
                step(f, Op::Jump, &[1759], 1759)
            }
            1759 => {
                step(f, Op::MulF, &[546, 554, 561], 1760);
                step(f, Op::LerpF, &[81, 682, 561, 562], 1761);
                step(f, Op::MulF, &[542, 562, 563], 1762);
                step(f, Op::QuatFromAxisAngle, &[397, 563, 57], 1763);
                step(f, Op::SubV, &[300, 299, 302], 1764);
                step(f, Op::RotateVector, &[57, 302, 303], 1765);
                step(f, Op::AddV, &[299, 303, 304], 1766);
                step(f, Op::DrawPoint, &[304, 686, 394], 1767);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 55, 71], 1768);
                step(f, Op::DrawTransform, &[71, 693, 681], 1769);
                step(f, Op::Jump, &[1770], 1770)
            }
            1770 => {
                step(f, Op::Jump, &[961], 1771)
            }
            1771 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1772);
                step(f, Op::Copy(ValueType::Int), &[65, 5], 1773);
                1773
            }
            1773 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 5, 1, 6, 7, 1828], 1774)
            }
            1774 => {
                step(f, Op::Copy(ValueType::Bone), &[1, 21], 1775);
                step(f, Op::Copy(ValueType::Int), &[6, 56], 1776);
                step(f, Op::GetParent, &[21, 22], 1777);
                step(f, Op::GetParent, &[22, 23], 1778);
                step(f, Op::GetParent, &[23, 24], 1779);
                step(f, Op::GetTransform, &[24, 65, 80, 80], 1780);
                step(f, Op::BreakTransform, &[80, 305, 61, 306], 1781);
                step(f, Op::LengthV, &[1, 571], 1782);
                step(f, Op::ClavicleOffset, &[10, 571, 92, 95, 572], 1783);
                step(f, Op::MakeVector, &[680, 680, 572, 307], 1784);
                step(f, Op::AddV, &[305, 307, 308], 1785);
                step(f, Op::MakeTransform, &[308, 61, 392, 81], 1786);
                step(f, Op::SetTransform, &[24, 81, 65, 79, 682], 1787);
                step(f, Op::GetParent, &[21, 22], 1788);
                step(f, Op::GetParent, &[22, 23], 1789);
                step(f, Op::GetTransform, &[21, 65, 80, 82], 1790);
                step(f, Op::GetTransform, &[23, 65, 80, 83], 1791);
                step(f, Op::BreakTransform, &[83, 309, 63, 310], 1792);
                step(f, Op::Equals(Elem::Int), &[56, 65, 66], 1793);
                step(f, Op::Select(ValueType::Int), &[66, 66, 65, 57], 1794);
                step(f, Op::ArrayAt(Elem::Float), &[0, 57, 570], 1795);
                step(f, Op::ArmSwingRotation, &[570, 1, 0, 93, 688, 695, 682, 92, 90, 91, 688, 688, 682, 573], 1796);
                step(f, Op::QuatFromAxisAngle, &[397, 573, 62], 1797);
                step(f, Op::RotateAroundPoint, &[82, 309, 62, 84], 1798);
                step(f, Op::BreakTransform, &[84, 311, 64, 312], 1799);
                step(f, Op::LengthV, &[1, 571], 1800);
                step(f, Op::RemapF, &[571, 680, 92, 680, 94, 79, 574], 1801);
                step(f, Op::MakeVector, &[680, 680, 574, 313], 1802);
                step(f, Op::AddV, &[311, 313, 314], 1803);
                step(f, Op::MakeTransform, &[314, 64, 392, 85], 1804);
                step(f, Op::Select(ValueType::Vec3), &[66, 398, 397, 316], 1805);
                step(f, Op::Select(ValueType::Vec3), &[66, 395, 399, 317], 1806);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 56, 315], 1807);
                step(f, Op::TwoBoneIK, &[23, 22, 21, 85, 316, 317, 315, 65, 682, 80, 696, 697, 79, 67, 575], 1808);
                step(f, Op::JumpIfFalse, &[8, 1827], 1809)
            }
            1809 => {
                step(f, Op::GetParent, &[21, 22], 1810);
                step(f, Op::GetParent, &[22, 23], 1811);
                step(f, Op::GetTransform, &[23, 65, 80, 83], 1812);
                step(f, Op::BreakTransform, &[83, 309, 63, 310], 1813);
                step(f, Op::GetTransform, &[21, 65, 80, 82], 1814);
                step(f, Op::Equals(Elem::Int), &[56, 65, 66], 1815);
                step(f, Op::Select(ValueType::Int), &[66, 66, 65, 57], 1816);
                step(f, Op::ArrayAt(Elem::Float), &[0, 57, 570], 1817);
                step(f, Op::ArmSwingRotation, &[570, 1, 0, 93, 688, 695, 682, 92, 90, 91, 688, 688, 682, 573], 1818);
                step(f, Op::QuatFromAxisAngle, &[397, 573, 62], 1819);
                step(f, Op::RotateAroundPoint, &[82, 309, 62, 84], 1820);
                step(f, Op::BreakTransform, &[84, 311, 64, 312], 1821);
                step(f, Op::LengthV, &[1, 571], 1822);
                step(f, Op::RemapF, &[571, 680, 92, 680, 94, 79, 574], 1823);
                step(f, Op::MakeVector, &[680, 680, 574, 313], 1824);
                step(f, Op::AddV, &[311, 313, 314], 1825);
                step(f, Op::DrawLine, &[309, 314, 681, 395], 1826);
                step(f, Op::Jump, &[1827], 1827)
            }
            1827 => {
                step(f, Op::Jump, &[1773], 1828)
            }
            1828 => {
                step(f, Op::Copy(ValueType::Float), &[680, 578], 1829);
                step(f, Op::Copy(ValueType::Float), &[689, 579], 1830);
                step(f, Op::Copy(ValueType::Bool), &[80, 68], 1831);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 10], 1832);
                step(f, Op::Copy(ValueType::Int), &[65, 58], 1833);
                step(f, Op::MakeVector, &[680, 680, 51, 320], 1834);
                1834
            }
            1834 => {
                step(f, Op::ForEachNext(Elem::Transform), &[10, 58, 86, 59, 60, 1847], 1835)
            }
            1835 => {
                step(f, Op::BreakTransform, &[86, 318, 65, 319], 1836);
                step(f, Op::AddV, &[318, 320, 321], 1837);
                step(f, Op::SubV, &[318, 320, 322], 1838);
                step(f, Op::SphereTrace, &[321, 322, 50, 69, 323, 324, 580], 1839);
                step(f, Op::BreakVector, &[323, 581, 582, 583], 1840);
                step(f, Op::LessF, &[583, 579, 70], 1841);
                step(f, Op::And, &[69, 70, 71], 1842);
                step(f, Op::JumpIfFalse, &[71, 1846], 1843)
            }
            1843 => {
                step(f, Op::Copy(ValueType::Float), &[583, 579], 1844);
                step(f, Op::Copy(ValueType::Bool), &[79, 68], 1845);
                step(f, Op::Jump, &[1846], 1846)
            }
            1846 => {
                step(f, Op::Jump, &[1834], 1847)
            }
            1847 => {
                step(f, Op::Select(ValueType::Float), &[68, 579, 680, 584], 1848);
                step(f, Op::ClampF, &[584, 54, 55, 585], 1849);
                step(f, Op::Copy(ValueType::Float), &[585, 578], 1850);
                step(f, Op::Jump, &[1851], 1851)
            }
            1851 => {
                step(f, Op::SubF, &[682, 18, 577], 1852);
                step(f, Op::MulF, &[578, 577, 586], 1853);
                step(f, Op::FloatLerp, &[14, 586, 44, 587], 1854);
                step(f, Op::Select(ValueType::Float), &[1, 586, 587, 588], 1855);
                step(f, Op::Copy(ValueType::Float), &[588, 14], 1856);
                step(f, Op::GetTransform, &[37, 65, 79, 91], 1857);
                step(f, Op::BreakTransform, &[91, 337, 72, 338], 1858);
                step(f, Op::PelvisLean, &[1, 97, 102, 103, 604, 605], 1859);
                step(f, Op::LengthV, &[2, 576], 1860);
                step(f, Op::RemapF, &[576, 680, 97, 680, 96, 79, 589], 1861);
                step(f, Op::MulF, &[10, 698, 590], 1862);
                step(f, Op::SinF, &[590, 591], 1863);
                step(f, Op::MulF, &[589, 591, 592], 1864);
                step(f, Op::MulF, &[592, 577, 593], 1865);
                step(f, Op::AddF, &[593, 14, 594], 1866);
                step(f, Op::MulF, &[3, 114, 595], 1867);
                step(f, Op::SubF, &[594, 595, 596], 1868);
                step(f, Op::MakeVector, &[680, 605, 596, 339], 1869);
                step(f, Op::AddV, &[337, 339, 340], 1870);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 87], 1871);
                step(f, Op::BreakTransform, &[87, 325, 66, 326], 1872);
                step(f, Op::BreakVector, &[325, 606, 607, 608], 1873);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 66, 88], 1874);
                step(f, Op::BreakTransform, &[88, 327, 67, 328], 1875);
                step(f, Op::BreakVector, &[327, 609, 610, 611], 1876);
                step(f, Op::SubF, &[608, 611, 612], 1877);
                step(f, Op::PelvisSideLean, &[612, 104, 105, 613], 1878);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 65, 89], 1879);
                step(f, Op::BreakTransform, &[89, 331, 68, 332], 1880);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 66, 90], 1881);
                step(f, Op::BreakTransform, &[90, 333, 69, 334], 1882);
                step(f, Op::SlerpQ, &[68, 69, 681, 70], 1883);
                step(f, Op::EulerFromQuat, &[70, 65, 335], 1884);
                step(f, Op::BreakVector, &[335, 600, 601, 602], 1885);
                step(f, Op::RemapF, &[576, 98, 97, 680, 99, 79, 598], 1886);
                step(f, Op::SubV, &[325, 327, 329], 1887);
                step(f, Op::RotateVector, &[0, 395, 330], 1888);
                step(f, Op::DotV, &[329, 330, 597], 1889);
                step(f, Op::MulF, &[598, 597, 599], 1890);
                step(f, Op::AddF, &[602, 599, 603], 1891);
                step(f, Op::MakeVector, &[604, 613, 603, 336], 1892);
                step(f, Op::QuatFromEuler, &[336, 65, 71], 1893);
                step(f, Op::MakeTransform, &[340, 71, 392, 92], 1894);
                step(f, Op::SetTransform, &[38, 92, 65, 79, 682], 1895);
                step(f, Op::GetTransform, &[39, 66, 79, 93], 1896);
                step(f, Op::BreakTransform, &[93, 341, 76, 342], 1897);
                step(f, Op::LengthV, &[2, 576], 1898);
                step(f, Op::RemapF, &[576, 98, 97, 680, 99, 79, 598], 1899);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 87], 1900);
                step(f, Op::BreakTransform, &[87, 325, 66, 326], 1901);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 66, 88], 1902);
                step(f, Op::BreakTransform, &[88, 327, 67, 328], 1903);
                step(f, Op::SubV, &[325, 327, 329], 1904);
                step(f, Op::RotateVector, &[0, 395, 330], 1905);
                step(f, Op::DotV, &[329, 330, 597], 1906);
                step(f, Op::MulF, &[598, 597, 599], 1907);
                step(f, Op::QuatFromAxisAngle, &[394, 599, 73], 1908);
                step(f, Op::DivF, &[100, 686, 614], 1909);
                step(f, Op::QuatScale, &[73, 614, 74], 1910);
                step(f, Op::MulQ, &[76, 74, 80], 1911);
                step(f, Op::MakeTransform, &[341, 80, 392, 97], 1912);
                step(f, Op::SetTransform, &[40, 97, 66, 79, 682], 1913);
                step(f, Op::GetTransform, &[41, 66, 79, 94], 1914);
                step(f, Op::BreakTransform, &[94, 343, 77, 344], 1915);
                step(f, Op::LengthV, &[2, 576], 1916);
                step(f, Op::RemapF, &[576, 98, 97, 680, 99, 79, 598], 1917);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 87], 1918);
                step(f, Op::BreakTransform, &[87, 325, 66, 326], 1919);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 66, 88], 1920);
                step(f, Op::BreakTransform, &[88, 327, 67, 328], 1921);
                step(f, Op::SubV, &[325, 327, 329], 1922);
                step(f, Op::RotateVector, &[0, 395, 330], 1923);
                step(f, Op::DotV, &[329, 330, 597], 1924);
                step(f, Op::MulF, &[598, 597, 599], 1925);
                step(f, Op::QuatFromAxisAngle, &[394, 599, 73], 1926);
                step(f, Op::DivF, &[100, 686, 614], 1927);
                step(f, Op::QuatScale, &[73, 614, 74], 1928);
                step(f, Op::MulQ, &[77, 74, 81], 1929);
                step(f, Op::MakeTransform, &[343, 81, 392, 98], 1930);
                step(f, Op::SetTransform, &[42, 98, 66, 79, 682], 1931);
                step(f, Op::GetTransform, &[43, 66, 79, 95], 1932);
                step(f, Op::BreakTransform, &[95, 345, 78, 346], 1933);
                step(f, Op::LengthV, &[2, 576], 1934);
                step(f, Op::RemapF, &[576, 98, 97, 680, 99, 79, 598], 1935);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 87], 1936);
                step(f, Op::BreakTransform, &[87, 325, 66, 326], 1937);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 66, 88], 1938);
                step(f, Op::BreakTransform, &[88, 327, 67, 328], 1939);
                step(f, Op::SubV, &[325, 327, 329], 1940);
                step(f, Op::RotateVector, &[0, 395, 330], 1941);
                step(f, Op::DotV, &[329, 330, 597], 1942);
                step(f, Op::MulF, &[598, 597, 599], 1943);
                step(f, Op::QuatFromAxisAngle, &[394, 599, 73], 1944);
                step(f, Op::DivF, &[100, 686, 614], 1945);
                step(f, Op::QuatScale, &[73, 614, 74], 1946);
                step(f, Op::MulQ, &[78, 74, 82], 1947);
                step(f, Op::MakeTransform, &[345, 82, 392, 99], 1948);
                step(f, Op::SetTransform, &[44, 99, 66, 79, 682], 1949);
                step(f, Op::GetTransform, &[45, 66, 79, 96], 1950);
                step(f, Op::BreakTransform, &[96, 347, 79, 348], 1951);
                step(f, Op::LengthV, &[2, 576], 1952);
                step(f, Op::RemapF, &[576, 98, 97, 680, 99, 79, 598], 1953);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 87], 1954);
                step(f, Op::BreakTransform, &[87, 325, 66, 326], 1955);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 66, 88], 1956);
                step(f, Op::BreakTransform, &[88, 327, 67, 328], 1957);
                step(f, Op::SubV, &[325, 327, 329], 1958);
                step(f, Op::RotateVector, &[0, 395, 330], 1959);
                step(f, Op::DotV, &[329, 330, 597], 1960);
                step(f, Op::MulF, &[598, 597, 599], 1961);
                step(f, Op::QuatFromAxisAngle, &[394, 599, 73], 1962);
                step(f, Op::QuatScale, &[73, 101, 75], 1963);
                step(f, Op::MulQ, &[79, 75, 83], 1964);
                step(f, Op::MakeTransform, &[347, 83, 392, 100], 1965);
                step(f, Op::SetTransform, &[46, 100, 66, 79, 682], 1966);
                step(f, Op::Copy(ValueType::Float), &[680, 615], 1967);
                step(f, Op::Copy(ValueType::Float), &[680, 616], 1968);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1969);
                step(f, Op::Copy(ValueType::Int), &[65, 61], 1970);
                1970
            }
            1970 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 61, 25, 62, 63, 2000], 1971)
            }
            1971 => {
                step(f, Op::GetParent, &[25, 26], 1972);
                step(f, Op::GetParent, &[26, 27], 1973);
                step(f, Op::GetTransform, &[27, 65, 80, 101], 1974);
                step(f, Op::BreakTransform, &[101, 349, 84, 350], 1975);
                step(f, Op::BreakVector, &[349, 617, 618, 619], 1976);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 62, 102], 1977);
                step(f, Op::BreakTransform, &[102, 351, 85, 352], 1978);
                step(f, Op::BreakVector, &[351, 620, 621, 622], 1979);
                step(f, Op::ArrayAt(Elem::Float), &[1, 62, 626], 1980);
                step(f, Op::MulF, &[626, 106, 627], 1981);
                step(f, Op::MulF, &[627, 627, 628], 1982);
                step(f, Op::SubF, &[617, 620, 623], 1983);
                step(f, Op::SubF, &[618, 621, 624], 1984);
                step(f, Op::MakeVector, &[623, 624, 680, 353], 1985);
                step(f, Op::DotV, &[353, 353, 625], 1986);
                step(f, Op::SubF, &[628, 625, 629], 1987);
                step(f, Op::SqrtF, &[629, 630], 1988);
                step(f, Op::AddF, &[622, 630, 631], 1989);
                step(f, Op::SubF, &[619, 631, 632], 1990);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 62, 72], 1991);
                step(f, Op::ArrayAt(Elem::Float), &[2, 62, 633], 1992);
                step(f, Op::RemapF, &[633, 681, 682, 680, 682, 79, 634], 1993);
                step(f, Op::RemapF, &[633, 680, 109, 682, 680, 79, 635], 1994);
                step(f, Op::MaxF, &[634, 635, 636], 1995);
                step(f, Op::Select(ValueType::Float), &[72, 682, 636, 637], 1996);
                step(f, Op::MulF, &[632, 637, 638], 1997);
                step(f, Op::MaxF, &[616, 638, 639], 1998);
                step(f, Op::Copy(ValueType::Float), &[639, 616], 1999);
                step(f, Op::Jump, &[1970], 2000)
            }
            2000 => {
                step(f, Op::ClampF, &[616, 680, 107, 640], 2001);
                step(f, Op::Copy(ValueType::Float), &[640, 615], 2002);
                step(f, Op::Jump, &[2003], 2003)
            }
            2003 => {
                step(f, Op::MakeVector, &[15, 680, 680, 354], 2004);
                step(f, Op::MakeVector, &[615, 680, 680, 355], 2005);
                step(f, Op::MakeVector, &[16, 680, 680, 356], 2006);
                step(f, Op::GreaterF, &[615, 15, 73], 2007);
                step(f, Op::Select(ValueType::Float), &[73, 111, 108, 641], 2008);
                step(f, Op::Copy(ValueType::Vec3), &[354, 357], 2009);
                step(f, Op::Copy(ValueType::Vec3), &[355, 358], 2010);
                step(f, Op::Copy(ValueType::Vec3), &[356, 359], 2011);
                step(f, Op::Copy(ValueType::Float), &[641, 642], 2012);
                step(f, Op::Copy(ValueType::Float), &[45, 643], 2013);
                step(f, Op::Copy(ValueType::Vec3), &[391, 360], 2014);
                step(f, Op::SubV, &[358, 359, 361], 2015);
                step(f, Op::DeltaTime, &[644], 2016);
                step(f, Op::DivF, &[643, 644, 645], 2017);
                step(f, Op::ScaleV, &[361, 645, 362], 2018);
                step(f, Op::AddV, &[358, 362, 363], 2019);
                step(f, Op::AddV, &[359, 362, 364], 2020);
                step(f, Op::SubV, &[357, 364, 365], 2021);
                step(f, Op::FloatLerp, &[680, 682, 642, 646], 2022);
                step(f, Op::SubF, &[682, 646, 647], 2023);
                step(f, Op::ScaleV, &[365, 647, 366], 2024);
                step(f, Op::AddV, &[363, 366, 368], 2025);
                step(f, Op::MulF, &[642, 644, 648], 2026);
                step(f, Op::GreaterF, &[648, 680, 74], 2027);
                step(f, Op::DivF, &[646, 648, 649], 2028);
                step(f, Op::Select(ValueType::Float), &[74, 649, 682, 650], 2029);
                step(f, Op::ScaleV, &[361, 650, 367], 2030);
                step(f, Op::SubV, &[368, 367, 369], 2031);
                step(f, Op::Copy(ValueType::Vec3), &[369, 360], 2032);
                step(f, Op::Jump, &[2033], 2033)
            }
            2033 => {
                step(f, Op::BreakVector, &[360, 651, 652, 653], 2034);
                step(f, Op::Select(ValueType::Float), &[1, 615, 651, 654], 2035);
                step(f, Op::Copy(ValueType::Float), &[654, 15], 2036);
                step(f, Op::Copy(ValueType::Float), &[615, 16], 2037);
                step(f, Op::GetTransform, &[47, 65, 80, 103], 2038);
                step(f, Op::BreakTransform, &[103, 370, 86, 371], 2039);
                step(f, Op::MakeVector, &[680, 680, 15, 372], 2040);
                step(f, Op::SubV, &[370, 372, 373], 2041);
                step(f, Op::MakeTransform, &[373, 86, 392, 104], 2042);
                step(f, Op::SetTransform, &[48, 104, 65, 79, 682], 2043);
                step(f, Op::JumpIfFalse, &[8, 2051], 2044)
            }
            2044 => {
                step(f, Op::GetTransform, &[47, 65, 80, 103], 2045);
                step(f, Op::BreakTransform, &[103, 370, 86, 371], 2046);
                step(f, Op::MakeVector, &[680, 680, 15, 372], 2047);
                step(f, Op::SubV, &[370, 372, 373], 2048);
                step(f, Op::MakeTransform, &[373, 86, 392, 104], 2049);
                step(f, Op::DrawTransform, &[104, 699, 681], 2050);
                step(f, Op::Jump, &[2051], 2051)
            }
            2051 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 2052);
                step(f, Op::Copy(ValueType::Int), &[65, 8], 2053);
                2053
            }
            2053 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 8, 2, 9, 10, 2113], 2054)
            }
            2054 => {
                step(f, Op::Copy(ValueType::Bone), &[2, 28], 2055);
                step(f, Op::Copy(ValueType::Int), &[9, 64], 2056);
                step(f, Op::GetParent, &[28, 29], 2057);
                step(f, Op::GetParent, &[29, 30], 2058);
                step(f, Op::GetTransform, &[30, 65, 80, 105], 2059);
                step(f, Op::BreakTransform, &[105, 374, 87, 375], 2060);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 64, 106], 2061);
                step(f, Op::BreakTransform, &[106, 376, 88, 377], 2062);
                step(f, Op::SubV, &[376, 374, 378], 2063);
                step(f, Op::LengthV, &[378, 670], 2064);
                step(f, Op::ArrayAt(Elem::Float), &[1, 64, 655], 2065);
                step(f, Op::MulF, &[655, 117, 656], 2066);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 64, 75], 2067);
                step(f, Op::ArrayAt(Elem::Float), &[2, 64, 657], 2068);
                step(f, Op::ClampF, &[657, 680, 682, 658], 2069);
                step(f, Op::LessF, &[658, 681, 76], 2070);
                step(f, Op::RemapF, &[658, 119, 120, 680, 682, 79, 661], 2071);
                step(f, Op::MulF, &[661, 661, 662], 2072);
                step(f, Op::MulF, &[661, 685, 663], 2073);
                step(f, Op::SubF, &[686, 663, 664], 2074);
                step(f, Op::MulF, &[662, 664, 665], 2075);
                step(f, Op::MulF, &[658, 694, 659], 2076);
                step(f, Op::SinF, &[659, 660], 2077);
                step(f, Op::MaxF, &[665, 660, 666], 2078);
                step(f, Op::Select(ValueType::Float), &[76, 666, 660, 667], 2079);
                step(f, Op::MulF, &[667, 118, 668], 2080);
                step(f, Op::Select(ValueType::Float), &[75, 680, 668, 669], 2081);
                step(f, Op::SubF, &[656, 669, 671], 2082);
                step(f, Op::SubF, &[670, 671, 672], 2083);
                step(f, Op::MaxF, &[672, 680, 673], 2084);
                step(f, Op::MulF, &[673, 673, 674], 2085);
                step(f, Op::AddF, &[673, 669, 675], 2086);
                step(f, Op::DivF, &[674, 675, 676], 2087);
                step(f, Op::SubF, &[670, 676, 677], 2088);
                step(f, Op::DivF, &[677, 670, 678], 2089);
                step(f, Op::ScaleV, &[378, 678, 379], 2090);
                step(f, Op::AddV, &[374, 379, 380], 2091);
                step(f, Op::ClampSpatially, &[380, 374, 680, 656, 381], 2092);
                step(f, Op::MakeTransform, &[381, 88, 392, 107], 2093);
                step(f, Op::Equals(Elem::Int), &[64, 65, 77], 2094);
                step(f, Op::Select(ValueType::Vec3), &[77, 398, 397, 386], 2095);
                step(f, Op::Select(ValueType::Vec3), &[77, 395, 399, 387], 2096);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 64, 108], 2097);
                step(f, Op::BreakTransform, &[108, 382, 89, 383], 2098);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 64, 384], 2099);
                step(f, Op::KneeVector, &[89, 0, 384, 121, 122, 385], 2100);
                step(f, Op::TwoBoneIK, &[30, 29, 28, 107, 386, 387, 385, 65, 682, 80, 696, 697, 79, 78, 679], 2101);
                step(f, Op::JumpIfFalse, &[8, 2112], 2102)
            }
            2102 => {
                step(f, Op::GetParent, &[28, 29], 2103);
                step(f, Op::GetTransform, &[29, 65, 80, 109], 2104);
                step(f, Op::BreakTransform, &[109, 388, 90, 389], 2105);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 64, 108], 2106);
                step(f, Op::BreakTransform, &[108, 382, 89, 383], 2107);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 64, 384], 2108);
                step(f, Op::KneeVector, &[89, 0, 384, 121, 122, 385], 2109);
                step(f, Op::AddV, &[388, 385, 390], 2110);
                step(f, Op::DrawLine, &[388, 390, 681, 400], 2111);
                step(f, Op::Jump, &[2112], 2112)
            }
            2112 => {
                step(f, Op::Jump, &[2053], 2113)
            }
            2113 => {
                step(f, Op::End, &[], 2114)
            }
            _ => return,
        } };
    }
}
