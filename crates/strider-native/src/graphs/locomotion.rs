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
    fingerprint: 0x609906a2fc2c9552,
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
                step(f, Op::LengthV, &[36, 126], 461);
                step(f, Op::GreaterF, &[126, 32, 10], 462);
                step(f, Op::Copy(ValueType::Bool), &[10, 2], 463);
                step(f, Op::MakeRelative, &[13, 12, 17], 464);
                step(f, Op::Select(ValueType::Transform), &[10, 110, 17, 18], 465);
                step(f, Op::Copy(ValueType::Transform), &[18, 2], 466);
                step(f, Op::InverseT, &[13, 15], 467);
                step(f, Op::MulT, &[12, 15, 16], 468);
                step(f, Op::Copy(ValueType::Transform), &[16, 1], 469);
                step(f, Op::TransformVector, &[2, 0, 41], 470);
                step(f, Op::InverseT, &[12, 14], 471);
                step(f, Op::DeltaTime, &[125], 472);
                step(f, Op::DivF, &[641, 125, 127], 473);
                step(f, Op::ScaleV, &[36, 127, 37], 474);
                step(f, Op::TransformVector, &[14, 37, 38], 475);
                step(f, Op::BreakVector, &[38, 128, 129, 130], 476);
                step(f, Op::MakeVector, &[128, 129, 639, 39], 477);
                step(f, Op::LengthV, &[39, 131], 478);
                step(f, Op::MulF, &[131, 110, 132], 479);
                step(f, Op::NegF, &[132, 133], 480);
                step(f, Op::ClampF, &[130, 133, 132, 134], 481);
                step(f, Op::MakeVector, &[128, 129, 134, 40], 482);
                step(f, Op::Select(ValueType::Vec3), &[2, 41, 40, 43], 483);
                step(f, Op::VectorLerp, &[41, 43, 33, 639, 44], 484);
                step(f, Op::Copy(ValueType::Vec3), &[44, 0], 485);
                step(f, Op::TransformVector, &[2, 1, 42], 486);
                step(f, Op::TransformVector, &[2, 0, 41], 487);
                step(f, Op::Select(ValueType::Vec3), &[2, 41, 40, 43], 488);
                step(f, Op::VectorLerp, &[42, 43, 34, 639, 45], 489);
                step(f, Op::Copy(ValueType::Vec3), &[45, 1], 490);
                step(f, Op::LengthV, &[43, 141], 491);
                step(f, Op::Copy(ValueType::Float), &[141, 0], 492);
                step(f, Op::BreakVector, &[36, 135, 136, 137], 493);
                step(f, Op::MulF, &[134, 125, 138], 494);
                step(f, Op::SubF, &[137, 138, 139], 495);
                step(f, Op::Select(ValueType::Float), &[10, 639, 139, 140], 496);
                step(f, Op::Copy(ValueType::Float), &[140, 1], 497);
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
                step(f, Op::Copy(ValueType::Float), &[639, 14], 515);
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
                step(f, Op::ScaleV, &[0, 642, 48], 523);
                step(f, Op::AddV, &[46, 48, 49], 524);
                step(f, Op::DrawArrow, &[46, 49, 640, 393], 525);
                step(f, Op::Jump, &[526], 526)
            }
            526 => {
                step(f, Op::Copy(ValueType::Float), &[639, 142], 527);
                step(f, Op::Copy(ValueType::Float), &[641, 143], 528);
                step(f, Op::Copy(ValueType::Float), &[641, 144], 529);
                step(f, Op::Copy(ValueType::Bool), &[79, 11], 530);
                step(f, Op::Copy(ValueType::Bool), &[79, 12], 531);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[7, 8], 532);
                step(f, Op::Copy(ValueType::Int), &[65, 25], 533);
                step(f, Op::MakeVector, &[639, 639, 51, 54], 534);
                534
            }
            534 => {
                step(f, Op::ForEachNext(Elem::Transform), &[8, 25, 21, 26, 27, 545], 535)
            }
            535 => {
                step(f, Op::BreakTransform, &[21, 50, 10, 51], 536);
                step(f, Op::TransformPoint, &[2, 50, 52], 537);
                step(f, Op::LerpV, &[52, 50, 144, 53], 538);
                step(f, Op::AddV, &[53, 54, 55], 539);
                step(f, Op::SubV, &[53, 54, 56], 540);
                step(f, Op::LineTrace, &[55, 56, 13, 57, 58, 145], 541);
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
                step(f, Op::AddF, &[142, 143, 146], 556);
                step(f, Op::MulF, &[146, 640, 147], 557);
                step(f, Op::Copy(ValueType::Float), &[147, 148], 558);
                step(f, Op::Copy(ValueType::Bool), &[79, 17], 559);
                step(f, Op::Copy(ValueType::Bool), &[79, 18], 560);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[7, 9], 561);
                step(f, Op::Copy(ValueType::Int), &[65, 28], 562);
                step(f, Op::MakeVector, &[639, 639, 51, 63], 563);
                563
            }
            563 => {
                step(f, Op::ForEachNext(Elem::Transform), &[9, 28, 22, 29, 30, 574], 564)
            }
            564 => {
                step(f, Op::BreakTransform, &[22, 59, 11, 60], 565);
                step(f, Op::TransformPoint, &[2, 59, 61], 566);
                step(f, Op::LerpV, &[61, 59, 148, 62], 567);
                step(f, Op::AddV, &[62, 63, 64], 568);
                step(f, Op::SubV, &[62, 63, 65], 569);
                step(f, Op::LineTrace, &[64, 65, 19, 66, 67, 149], 570);
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
                step(f, Op::Copy(ValueType::Float), &[147, 142], 579);
                step(f, Op::Jump, &[581], 580)
            }
            580 => {
                step(f, Op::Copy(ValueType::Float), &[147, 143], 581);
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
                step(f, Op::Select(ValueType::Float), &[5, 643, 641, 155], 585);
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 586);
                step(f, Op::AddF, &[142, 143, 146], 587);
                step(f, Op::MulF, &[146, 640, 150], 588);
                step(f, Op::Select(ValueType::Float), &[16, 150, 640, 151], 589);
                step(f, Op::Select(ValueType::Float), &[15, 151, 639, 157], 590);
                step(f, Op::MulF, &[155, 157, 159], 591);
                step(f, Op::DeltaTime, &[153], 592);
                step(f, Op::DivF, &[153, 113, 154], 593);
                step(f, Op::MulF, &[159, 154, 160], 594);
                step(f, Op::AddF, &[17, 160, 161], 595);
                step(f, Op::ClampF, &[161, 639, 641, 162], 596);
                step(f, Op::Select(ValueType::Float), &[14, 643, 641, 156], 597);
                step(f, Op::SubF, &[641, 151, 152], 598);
                step(f, Op::Select(ValueType::Float), &[15, 152, 641, 158], 599);
                step(f, Op::MulF, &[156, 158, 163], 600);
                step(f, Op::MulF, &[163, 154, 164], 601);
                step(f, Op::AddF, &[162, 164, 165], 602);
                step(f, Op::ClampF, &[165, 639, 641, 166], 603);
                step(f, Op::MulF, &[166, 166, 167], 604);
                step(f, Op::MulF, &[166, 644, 168], 605);
                step(f, Op::SubF, &[645, 168, 169], 606);
                step(f, Op::MulF, &[167, 169, 170], 607);
                step(f, Op::AddF, &[18, 170, 171], 608);
                step(f, Op::MulF, &[171, 640, 172], 609);
                step(f, Op::SubF, &[641, 172, 173], 610);
                step(f, Op::MulF, &[173, 173, 174], 611);
                step(f, Op::SubF, &[641, 174, 175], 612);
                step(f, Op::Copy(ValueType::Float), &[175, 19], 613);
                step(f, Op::Copy(ValueType::Float), &[170, 18], 614);
                step(f, Op::Copy(ValueType::Float), &[166, 17], 615);
                step(f, Op::GreaterF, &[18, 639, 21], 616);
                step(f, Op::TransformVector, &[2, 3, 68], 617);
                step(f, Op::Select(ValueType::Vec3), &[21, 68, 0, 69], 618);
                step(f, Op::Copy(ValueType::Vec3), &[69, 3], 619);
                step(f, Op::LerpV, &[0, 3, 18, 70], 620);
                step(f, Op::Select(ValueType::Vec3), &[21, 70, 0, 71], 621);
                step(f, Op::Copy(ValueType::Vec3), &[71, 2], 622);
                step(f, Op::Copy(ValueType::Bool), &[14, 5], 623);
                step(f, Op::Copy(ValueType::Bool), &[11, 6], 624);
                step(f, Op::Copy(ValueType::Bool), &[79, 7], 625);
                step(f, Op::SubF, &[641, 19, 176], 626);
                step(f, Op::MulF, &[1, 176, 177], 627);
                step(f, Op::AddF, &[2, 177, 178], 628);
                step(f, Op::SpringF, &[178, 111, 181, 31, 179, 180], 629);
                step(f, Op::SubF, &[178, 181, 182], 630);
                step(f, Op::Copy(ValueType::Float), &[182, 3], 631);
                step(f, Op::Copy(ValueType::Float), &[178, 2], 632);
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
                step(f, Op::BreakVector, &[72, 191, 192, 193], 652);
                step(f, Op::MakeVector, &[191, 192, 639, 76], 653);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 39, 24], 654);
                step(f, Op::BreakTransform, &[24, 74, 13, 75], 655);
                step(f, Op::BreakVector, &[74, 194, 195, 196], 656);
                step(f, Op::MakeVector, &[194, 195, 639, 77], 657);
                step(f, Op::DistanceV, &[76, 77, 197], 658);
                step(f, Op::GreaterF, &[197, 28, 29], 659);
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
                step(f, Op::LengthV, &[2, 183], 667);
                step(f, Op::GreaterF, &[183, 26, 22], 668);
                step(f, Op::GreaterF, &[0, 26, 31], 669);
                step(f, Op::Or, &[22, 31, 32], 670);
                step(f, Op::Not, &[32, 33], 671);
                step(f, Op::And, &[30, 33, 38], 672);
                step(f, Op::DeltaTime, &[222], 673);
                step(f, Op::MulF, &[222, 31, 223], 674);
                step(f, Op::AddF, &[10, 223, 224], 675);
                step(f, Op::GreaterF, &[10, 640, 39], 676);
                step(f, Op::AddF, &[30, 640, 220], 677);
                step(f, Op::Select(ValueType::Float), &[39, 220, 30, 221], 678);
                step(f, Op::MinF, &[224, 221, 225], 679);
                step(f, Op::NotEquals(Elem::Bool), &[33, 4, 34], 680);
                step(f, Op::Not, &[30, 35], 681);
                step(f, Op::And, &[34, 35, 36], 682);
                step(f, Op::SubF, &[11, 26, 206], 683);
                step(f, Op::SubF, &[11, 183, 207], 684);
                step(f, Op::DivF, &[206, 207, 208], 685);
                step(f, Op::ClampF, &[208, 639, 641, 209], 686);
                step(f, Op::MulF, &[6, 209, 211], 687);
                step(f, Op::RemapF, &[183, 26, 27, 639, 641, 78, 198], 688);
                step(f, Op::MaxF, &[198, 7, 199], 689);
                step(f, Op::Select(ValueType::Float), &[23, 641, 199, 200], 690);
                step(f, Op::Select(ValueType::Float), &[33, 29, 200, 201], 691);
                step(f, Op::Select(ValueType::Float), &[30, 198, 201, 202], 692);
                step(f, Op::SubF, &[641, 18, 203], 693);
                step(f, Op::MulF, &[202, 203, 204], 694);
                step(f, Op::LerpF, &[20, 41, 13, 186], 695);
                step(f, Op::RemapF, &[183, 23, 24, 21, 22, 78, 184], 696);
                step(f, Op::LerpF, &[184, 40, 13, 185], 697);
                step(f, Op::MaxF, &[183, 25, 187], 698);
                step(f, Op::DivF, &[185, 187, 188], 699);
                step(f, Op::AddF, &[186, 188, 189], 700);
                step(f, Op::DivF, &[204, 189, 205], 701);
                step(f, Op::SubF, &[641, 209, 210], 702);
                step(f, Op::MulF, &[205, 210, 212], 703);
                step(f, Op::AddF, &[211, 212, 213], 704);
                step(f, Op::MulF, &[213, 644, 214], 705);
                step(f, Op::AddF, &[6, 205, 215], 706);
                step(f, Op::Select(ValueType::Float), &[36, 214, 215, 216], 707);
                step(f, Op::DivF, &[644, 216, 217], 708);
                step(f, Op::GreaterF, &[216, 639, 37], 709);
                step(f, Op::CycleStep, &[10, 217, 639, 37, 218, 219], 710);
                step(f, Op::Select(ValueType::Float), &[38, 225, 218, 226], 711);
                step(f, Op::Copy(ValueType::Float), &[226, 10], 712);
                step(f, Op::Copy(ValueType::Float), &[205, 6], 713);
                step(f, Op::Copy(ValueType::Bool), &[22, 3], 714);
                step(f, Op::Copy(ValueType::Float), &[188, 4], 715);
                step(f, Op::Copy(ValueType::Float), &[189, 5], 716);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 717);
                step(f, Op::Copy(ValueType::Int), &[65, 32], 718);
                718
            }
            718 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 32, 14, 33, 34, 892], 719)
            }
            719 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 33, 240], 720);
                step(f, Op::ToFloat, &[33, 227], 721);
                step(f, Op::MulF, &[227, 640, 228], 722);
                step(f, Op::AddF, &[10, 228, 229], 723);
                step(f, Op::FractF, &[229, 230], 724);
                step(f, Op::SubF, &[240, 230, 242], 725);
                step(f, Op::GreaterF, &[242, 640, 40], 726);
                step(f, Op::ArrayAt(Elem::Float), &[2, 33, 241], 727);
                step(f, Op::Select(ValueType::Float), &[40, 639, 241, 269], 728);
                step(f, Op::ArraySetAt(Elem::Float), &[3, 33, 269], 729);
                step(f, Op::ArrayAt(Elem::Float), &[0, 33, 240], 730);
                step(f, Op::ToFloat, &[33, 227], 731);
                step(f, Op::MulF, &[227, 640, 228], 732);
                step(f, Op::AddF, &[10, 228, 229], 733);
                step(f, Op::FractF, &[229, 230], 734);
                step(f, Op::SubF, &[240, 230, 242], 735);
                step(f, Op::GreaterF, &[242, 640, 40], 736);
                step(f, Op::SubF, &[641, 240, 263], 737);
                step(f, Op::AddF, &[230, 263, 264], 738);
                step(f, Op::DivF, &[230, 264, 265], 739);
                step(f, Op::LengthV, &[2, 183], 740);
                step(f, Op::GreaterF, &[183, 26, 22], 741);
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
                step(f, Op::BreakVector, &[72, 191, 192, 193], 765);
                step(f, Op::MakeVector, &[191, 192, 639, 76], 766);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 39, 24], 767);
                step(f, Op::BreakTransform, &[24, 74, 13, 75], 768);
                step(f, Op::BreakVector, &[74, 194, 195, 196], 769);
                step(f, Op::MakeVector, &[194, 195, 639, 77], 770);
                step(f, Op::DistanceV, &[76, 77, 197], 771);
                step(f, Op::GreaterF, &[197, 28, 29], 772);
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
                step(f, Op::SubF, &[11, 26, 206], 782);
                step(f, Op::SubF, &[11, 183, 207], 783);
                step(f, Op::DivF, &[206, 207, 208], 784);
                step(f, Op::ClampF, &[208, 639, 641, 209], 785);
                step(f, Op::MulF, &[9, 209, 232], 786);
                step(f, Op::RemapF, &[183, 26, 27, 639, 641, 78, 198], 787);
                step(f, Op::MaxF, &[198, 7, 199], 788);
                step(f, Op::Select(ValueType::Float), &[23, 641, 199, 200], 789);
                step(f, Op::Select(ValueType::Float), &[33, 29, 200, 201], 790);
                step(f, Op::Select(ValueType::Float), &[30, 198, 201, 202], 791);
                step(f, Op::SubF, &[641, 18, 203], 792);
                step(f, Op::MulF, &[202, 203, 204], 793);
                step(f, Op::LerpF, &[20, 41, 13, 186], 794);
                step(f, Op::DivF, &[204, 186, 231], 795);
                step(f, Op::SubF, &[641, 209, 210], 796);
                step(f, Op::MulF, &[231, 210, 233], 797);
                step(f, Op::AddF, &[232, 233, 234], 798);
                step(f, Op::MulF, &[234, 644, 235], 799);
                step(f, Op::AddF, &[9, 231, 236], 800);
                step(f, Op::Select(ValueType::Float), &[36, 235, 236, 237], 801);
                step(f, Op::DeltaTime, &[222], 802);
                step(f, Op::MulF, &[222, 640, 238], 803);
                step(f, Op::MulF, &[237, 238, 239], 804);
                step(f, Op::MulF, &[265, 239, 266], 805);
                step(f, Op::ArrayAt(Elem::Float), &[2, 33, 241], 806);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 33, 41], 807);
                step(f, Op::RemapF, &[183, 23, 24, 21, 22, 78, 184], 808);
                step(f, Op::LerpF, &[184, 40, 13, 185], 809);
                step(f, Op::MaxF, &[183, 25, 187], 810);
                step(f, Op::DivF, &[185, 187, 188], 811);
                step(f, Op::AddF, &[186, 188, 189], 812);
                step(f, Op::DivF, &[186, 189, 190], 813);
                step(f, Op::SubF, &[190, 8, 243], 814);
                step(f, Op::MaxF, &[243, 639, 244], 815);
                step(f, Op::DivF, &[244, 190, 245], 816);
                step(f, Op::SubF, &[641, 13, 247], 817);
                step(f, Op::MulF, &[245, 247, 254], 818);
                step(f, Op::MulF, &[254, 203, 255], 819);
                step(f, Op::MulF, &[255, 108, 256], 820);
                step(f, Op::DivF, &[45, 222, 252], 821);
                step(f, Op::SubF, &[640, 252, 253], 822);
                step(f, Op::MulF, &[256, 253, 257], 823);
                step(f, Op::SubF, &[641, 257, 258], 824);
                step(f, Op::MulF, &[239, 258, 259], 825);
                step(f, Op::Select(ValueType::Float), &[41, 239, 259, 260], 826);
                step(f, Op::MulF, &[245, 241, 246], 827);
                step(f, Op::MulF, &[246, 247, 248], 828);
                step(f, Op::MulF, &[248, 203, 249], 829);
                step(f, Op::MulF, &[249, 108, 250], 830);
                step(f, Op::Select(ValueType::Float), &[41, 639, 250, 251], 831);
                step(f, Op::SubF, &[260, 251, 261], 832);
                step(f, Op::AddF, &[241, 261, 262], 833);
                step(f, Op::Select(ValueType::Float), &[40, 266, 262, 267], 834);
                step(f, Op::MinF, &[267, 644, 268], 835);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 33, 268], 836);
                step(f, Op::ArrayAt(Elem::Float), &[0, 33, 240], 837);
                step(f, Op::ToFloat, &[33, 227], 838);
                step(f, Op::MulF, &[227, 640, 228], 839);
                step(f, Op::AddF, &[10, 228, 229], 840);
                step(f, Op::FractF, &[229, 230], 841);
                step(f, Op::SubF, &[240, 230, 242], 842);
                step(f, Op::GreaterF, &[242, 640, 40], 843);
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
                step(f, Op::BreakVector, &[72, 191, 192, 193], 864);
                step(f, Op::MakeVector, &[191, 192, 639, 76], 865);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 39, 24], 866);
                step(f, Op::BreakTransform, &[24, 74, 13, 75], 867);
                step(f, Op::BreakVector, &[74, 194, 195, 196], 868);
                step(f, Op::MakeVector, &[194, 195, 639, 77], 869);
                step(f, Op::DistanceV, &[76, 77, 197], 870);
                step(f, Op::GreaterF, &[197, 28, 29], 871);
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
                step(f, Op::LengthV, &[2, 183], 879);
                step(f, Op::RemapF, &[183, 26, 27, 639, 641, 78, 198], 880);
                step(f, Op::GreaterF, &[183, 26, 22], 881);
                step(f, Op::GreaterF, &[0, 26, 31], 882);
                step(f, Op::Or, &[22, 31, 32], 883);
                step(f, Op::Not, &[32, 33], 884);
                step(f, Op::MaxF, &[198, 7, 199], 885);
                step(f, Op::Select(ValueType::Float), &[23, 641, 199, 200], 886);
                step(f, Op::Select(ValueType::Float), &[33, 29, 200, 201], 887);
                step(f, Op::Select(ValueType::Float), &[30, 198, 201, 202], 888);
                step(f, Op::Copy(ValueType::Float), &[202, 7], 889);
                step(f, Op::Jump, &[890], 890)
            }
            890 => {
                step(f, Op::ArraySetAt(Elem::Float), &[0, 33, 230], 891);
                step(f, Op::Jump, &[718], 892)
            }
            892 => {
                step(f, Op::LerpF, &[20, 41, 13, 186], 893);
                step(f, Op::LengthV, &[2, 183], 894);
                step(f, Op::RemapF, &[183, 23, 24, 21, 22, 78, 184], 895);
                step(f, Op::LerpF, &[184, 40, 13, 185], 896);
                step(f, Op::MaxF, &[183, 25, 187], 897);
                step(f, Op::DivF, &[185, 187, 188], 898);
                step(f, Op::AddF, &[186, 188, 189], 899);
                step(f, Op::DivF, &[186, 189, 190], 900);
                step(f, Op::Copy(ValueType::Float), &[190, 8], 901);
                step(f, Op::GreaterF, &[183, 26, 22], 902);
                step(f, Op::GreaterF, &[0, 26, 31], 903);
                step(f, Op::Or, &[22, 31, 32], 904);
                step(f, Op::Not, &[32, 33], 905);
                step(f, Op::Copy(ValueType::Bool), &[33, 4], 906);
                step(f, Op::Copy(ValueType::Float), &[183, 11], 907);
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
                step(f, Op::BreakVector, &[72, 191, 192, 193], 927);
                step(f, Op::MakeVector, &[191, 192, 639, 76], 928);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 39, 24], 929);
                step(f, Op::BreakTransform, &[24, 74, 13, 75], 930);
                step(f, Op::BreakVector, &[74, 194, 195, 196], 931);
                step(f, Op::MakeVector, &[194, 195, 639, 77], 932);
                step(f, Op::DistanceV, &[76, 77, 197], 933);
                step(f, Op::GreaterF, &[197, 28, 29], 934);
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
                step(f, Op::RemapF, &[183, 26, 27, 639, 641, 78, 198], 942);
                step(f, Op::MaxF, &[198, 7, 199], 943);
                step(f, Op::Select(ValueType::Float), &[23, 641, 199, 200], 944);
                step(f, Op::Select(ValueType::Float), &[33, 29, 200, 201], 945);
                step(f, Op::Select(ValueType::Float), &[30, 198, 201, 202], 946);
                step(f, Op::SubF, &[641, 18, 203], 947);
                step(f, Op::MulF, &[202, 203, 204], 948);
                step(f, Op::DivF, &[204, 186, 231], 949);
                step(f, Op::Copy(ValueType::Float), &[231, 9], 950);
                step(f, Op::Select(ValueType::Vec3), &[3, 2, 391, 78], 951);
                step(f, Op::MovementAngleOffset, &[78, 12, 10, 35, 36, 646, 37, 647, 270], 952);
                step(f, Op::Copy(ValueType::Float), &[270, 12], 953);
                step(f, Op::QuatFromAxisAngle, &[394, 12, 14], 954);
                step(f, Op::Copy(ValueType::Quat), &[14, 0], 955);
                step(f, Op::SinF, &[12, 271], 956);
                step(f, Op::AbsF, &[271, 272], 957);
                step(f, Op::RemapF, &[272, 38, 39, 639, 641, 78, 273], 958);
                step(f, Op::Copy(ValueType::Float), &[273, 13], 959);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 960);
                step(f, Op::Copy(ValueType::Int), &[65, 2], 961);
                961
            }
            961 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 2, 0, 3, 4, 1709], 962)
            }
            962 => {
                step(f, Op::Copy(ValueType::Bone), &[0, 16], 963);
                step(f, Op::Copy(ValueType::Int), &[3, 41], 964);
                step(f, Op::GetTransform, &[35, 65, 78, 25], 965);
                step(f, Op::BreakTransform, &[25, 81, 15, 82], 966);
                step(f, Op::BreakVector, &[81, 285, 286, 287], 967);
                step(f, Op::SubF, &[641, 13, 283], 968);
                step(f, Op::MulF, &[12, 283, 284], 969);
                step(f, Op::QuatFromAxisAngle, &[394, 284, 17], 970);
                step(f, Op::GetTransform, &[16, 65, 78, 26], 971);
                step(f, Op::BreakTransform, &[26, 83, 16, 84], 972);
                step(f, Op::SubV, &[83, 81, 85], 973);
                step(f, Op::BreakVector, &[85, 280, 281, 282], 974);
                step(f, Op::MakeVector, &[280, 281, 639, 86], 975);
                step(f, Op::RotateVector, &[17, 86, 87], 976);
                step(f, Op::BreakVector, &[87, 288, 289, 290], 977);
                step(f, Op::MulF, &[42, 13, 291], 978);
                step(f, Op::Equals(Elem::Int), &[41, 65, 42], 979);
                step(f, Op::Select(ValueType::Float), &[42, 641, 643, 300], 980);
                step(f, Op::MulF, &[291, 300, 292], 981);
                step(f, Op::AddF, &[288, 292, 293], 982);
                step(f, Op::AddF, &[285, 293, 294], 983);
                step(f, Op::AddF, &[286, 289, 295], 984);
                step(f, Op::BreakVector, &[83, 296, 297, 298], 985);
                step(f, Op::SubF, &[298, 46, 299], 986);
                step(f, Op::MakeVector, &[294, 295, 299, 88], 987);
                step(f, Op::ArrayAt(Elem::Float), &[2, 41, 274], 988);
                step(f, Op::SubF, &[641, 274, 275], 989);
                step(f, Op::MaxF, &[275, 639, 276], 990);
                step(f, Op::MulF, &[8, 5, 277], 991);
                step(f, Op::MulF, &[276, 277, 278], 992);
                step(f, Op::ScaleV, &[2, 278, 79], 993);
                step(f, Op::AddV, &[88, 79, 89], 994);
                step(f, Op::MulF, &[4, 640, 279], 995);
                step(f, Op::ScaleV, &[2, 279, 80], 996);
                step(f, Op::AddV, &[89, 80, 90], 997);
                step(f, Op::RotateVector, &[0, 395, 91], 998);
                step(f, Op::Copy(ValueType::Vec3), &[90, 112], 999);
                step(f, Op::Copy(ValueType::Vec3), &[91, 113], 1000);
                step(f, Op::Copy(ValueType::Float), &[300, 319], 1001);
                step(f, Op::Copy(ValueType::Vec3), &[391, 114], 1002);
                step(f, Op::Copy(ValueType::Vec3), &[391, 115], 1003);
                step(f, Op::Copy(ValueType::Bool), &[79, 44], 1004);
                step(f, Op::Copy(ValueType::Float), &[648, 320], 1005);
                step(f, Op::Copy(ValueType::Vec3), &[391, 116], 1006);
                step(f, Op::Copy(ValueType::Vec3), &[394, 117], 1007);
                step(f, Op::Copy(ValueType::Bool), &[79, 45], 1008);
                step(f, Op::MulI, &[0, 0, 47], 1009);
                step(f, Op::Copy(ValueType::Int), &[47, 46], 1010);
                step(f, Op::Copy(ValueType::Int), &[65, 42], 1011);
                step(f, Op::SubI, &[0, 66, 50], 1012);
                step(f, Op::DivI, &[50, 67, 51], 1013);
                step(f, Op::MakeVector, &[639, 639, 51, 122], 1014);
                step(f, Op::ScaleV, &[113, 53, 127], 1015);
                1015
            }
            1015 => {
                step(f, Op::ForNext, &[42, 46, 44, 1055], 1016)
            }
            1016 => {
                step(f, Op::ModI, &[44, 0, 48], 1017);
                step(f, Op::ToFloat, &[48, 321], 1018);
                step(f, Op::MulF, &[321, 52, 323], 1019);
                step(f, Op::MulF, &[323, 319, 324], 1020);
                step(f, Op::MakeVector, &[324, 639, 639, 118], 1021);
                step(f, Op::DivI, &[44, 0, 49], 1022);
                step(f, Op::SubI, &[49, 51, 52], 1023);
                step(f, Op::ToFloat, &[52, 322], 1024);
                step(f, Op::MulF, &[322, 52, 325], 1025);
                step(f, Op::ScaleV, &[113, 325, 119], 1026);
                step(f, Op::AddV, &[118, 119, 120], 1027);
                step(f, Op::AddV, &[112, 120, 121], 1028);
                step(f, Op::AddV, &[121, 122, 123], 1029);
                step(f, Op::SubV, &[121, 122, 124], 1030);
                step(f, Op::SphereTrace, &[123, 124, 50, 46, 125, 126, 326], 1031);
                step(f, Op::BreakVector, &[125, 328, 329, 330], 1032);
                step(f, Op::AddV, &[123, 127, 128], 1033);
                step(f, Op::AddV, &[124, 127, 129], 1034);
                step(f, Op::SphereTrace, &[128, 129, 50, 47, 130, 131, 327], 1035);
                step(f, Op::BreakVector, &[130, 331, 332, 333], 1036);
                step(f, Op::SubF, &[330, 333, 334], 1037);
                step(f, Op::AbsF, &[334, 335], 1038);
                step(f, Op::Select(ValueType::Float), &[46, 639, 641, 336], 1039);
                step(f, Op::AddF, &[335, 336, 341], 1040);
                step(f, Op::LengthV, &[120, 337], 1041);
                step(f, Op::RemapF, &[337, 639, 649, 639, 641, 78, 338], 1042);
                step(f, Op::MinF, &[330, 333, 339], 1043);
                step(f, Op::RemapF, &[339, 650, 649, 641, 640, 78, 340], 1044);
                step(f, Op::AddF, &[338, 340, 342], 1045);
                step(f, Op::AddF, &[341, 342, 343], 1046);
                step(f, Op::LessF, &[343, 320, 48], 1047);
                step(f, Op::And, &[46, 48, 49], 1048);
                step(f, Op::JumpIfFalse, &[49, 1054], 1049)
            }
            1049 => {
                step(f, Op::Copy(ValueType::Float), &[343, 320], 1050);
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
                step(f, Op::ArrayAt(Elem::Float), &[2, 41, 274], 1065);
                step(f, Op::SubF, &[641, 274, 275], 1066);
                step(f, Op::MaxF, &[275, 639, 276], 1067);
                step(f, Op::MulF, &[8, 5, 277], 1068);
                step(f, Op::MulF, &[276, 277, 278], 1069);
                step(f, Op::ScaleV, &[2, 278, 79], 1070);
                step(f, Op::SubV, &[114, 79, 92], 1071);
                step(f, Op::Select(ValueType::Vec3), &[44, 92, 93, 95], 1072);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 41, 28], 1073);
                step(f, Op::BreakTransform, &[28, 96, 23, 97], 1074);
                step(f, Op::Copy(ValueType::Vec3), &[93, 98], 1075);
                step(f, Op::Copy(ValueType::Vec3), &[95, 99], 1076);
                step(f, Op::Copy(ValueType::Vec3), &[96, 100], 1077);
                step(f, Op::Copy(ValueType::Float), &[43, 306], 1078);
                step(f, Op::Copy(ValueType::Float), &[45, 307], 1079);
                step(f, Op::Copy(ValueType::Vec3), &[391, 101], 1080);
                step(f, Op::SubV, &[99, 100, 102], 1081);
                step(f, Op::DeltaTime, &[308], 1082);
                step(f, Op::DivF, &[307, 308, 309], 1083);
                step(f, Op::ScaleV, &[102, 309, 103], 1084);
                step(f, Op::AddV, &[99, 103, 104], 1085);
                step(f, Op::AddV, &[100, 103, 105], 1086);
                step(f, Op::SubV, &[98, 105, 106], 1087);
                step(f, Op::FloatLerp, &[639, 641, 306, 310], 1088);
                step(f, Op::SubF, &[641, 310, 311], 1089);
                step(f, Op::ScaleV, &[106, 311, 107], 1090);
                step(f, Op::AddV, &[104, 107, 109], 1091);
                step(f, Op::MulF, &[306, 308, 312], 1092);
                step(f, Op::GreaterF, &[312, 639, 43], 1093);
                step(f, Op::DivF, &[310, 312, 313], 1094);
                step(f, Op::Select(ValueType::Float), &[43, 313, 641, 314], 1095);
                step(f, Op::ScaleV, &[102, 314, 108], 1096);
                step(f, Op::SubV, &[109, 108, 110], 1097);
                step(f, Op::Copy(ValueType::Vec3), &[110, 101], 1098);
                step(f, Op::Jump, &[1099], 1099)
            }
            1099 => {
                step(f, Op::BreakVector, &[101, 315, 316, 317], 1100);
                step(f, Op::ClampF, &[317, 54, 55, 318], 1101);
                step(f, Op::MakeVector, &[315, 316, 318, 111], 1102);
                step(f, Op::RotationFromNormal, &[115, 304, 305, 19], 1103);
                step(f, Op::PerFootRotationFactor, &[12, 86, 87, 301], 1104);
                step(f, Op::MulF, &[12, 301, 302], 1105);
                step(f, Op::SubF, &[641, 13, 283], 1106);
                step(f, Op::MulF, &[302, 283, 303], 1107);
                step(f, Op::QuatFromAxisAngle, &[394, 303, 18], 1108);
                step(f, Op::MulQ, &[19, 18, 20], 1109);
                step(f, Op::Select(ValueType::Quat), &[44, 20, 21, 22], 1110);
                step(f, Op::MakeTransform, &[111, 22, 392, 30], 1111);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 41, 30], 1112);
                step(f, Op::ArrayAt(Elem::Float), &[2, 41, 274], 1113);
                step(f, Op::SubF, &[641, 274, 275], 1114);
                step(f, Op::MaxF, &[275, 639, 276], 1115);
                step(f, Op::MulF, &[8, 5, 277], 1116);
                step(f, Op::MulF, &[276, 277, 278], 1117);
                step(f, Op::ScaleV, &[2, 278, 79], 1118);
                step(f, Op::SubV, &[114, 79, 92], 1119);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 41, 27], 1120);
                step(f, Op::BreakTransform, &[27, 93, 21, 94], 1121);
                step(f, Op::Select(ValueType::Vec3), &[44, 92, 93, 95], 1122);
                step(f, Op::MakeTransform, &[95, 90, 392, 29], 1123);
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
                step(f, Op::GreaterF, &[18, 639, 53], 1130);
                step(f, Op::InterpolateTransform, &[2, 110, 19, 31], 1131);
                step(f, Op::Select(ValueType::Transform), &[53, 31, 2, 32], 1132);
                step(f, Op::MakeAbsolute, &[33, 32, 34], 1133);
                step(f, Op::BreakTransform, &[34, 132, 24, 133], 1134);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 53, 35], 1135);
                step(f, Op::BreakTransform, &[35, 134, 25, 135], 1136);
                step(f, Op::AddF, &[58, 59, 345], 1137);
                step(f, Op::ClampSpatially, &[132, 134, 639, 345, 136], 1138);
                step(f, Op::SubF, &[641, 13, 360], 1139);
                step(f, Op::MulF, &[12, 360, 346], 1140);
                step(f, Op::LimitRotationAroundZ, &[24, 346, 85, 26], 1141);
                step(f, Op::MakeTransform, &[136, 26, 392, 36], 1142);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 53, 36], 1143);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 53, 50], 1144);
                step(f, Op::JumpIfFalse, &[50, 1198], 1145)
            }
            1145 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 53, 39], 1146);
                step(f, Op::BreakTransform, &[39, 142, 28, 143], 1147);
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 344], 1148);
                step(f, Op::SubF, &[641, 344, 357], 1149);
                step(f, Op::MulF, &[8, 5, 358], 1150);
                step(f, Op::MulF, &[357, 358, 359], 1151);
                step(f, Op::ScaleV, &[2, 359, 144], 1152);
                step(f, Op::AddV, &[142, 144, 145], 1153);
                step(f, Op::MakeTransform, &[145, 28, 392, 46], 1154);
                step(f, Op::Copy(ValueType::Transform), &[46, 47], 1155);
                step(f, Op::Copy(ValueType::Transform), &[110, 48], 1156);
                step(f, Op::BreakTransform, &[47, 173, 33, 174], 1157);
                step(f, Op::MakeVector, &[639, 639, 51, 175], 1158);
                step(f, Op::AddV, &[173, 175, 176], 1159);
                step(f, Op::SubV, &[173, 175, 177], 1160);
                step(f, Op::LineTrace, &[176, 177, 57, 178, 179, 387], 1161);
                step(f, Op::RotateVector, &[33, 394, 180], 1162);
                step(f, Op::FindQuatBetween, &[180, 179, 34], 1163);
                step(f, Op::MulQ, &[34, 33, 35], 1164);
                step(f, Op::MulF, &[49, 48, 388], 1165);
                step(f, Op::AddF, &[388, 57, 389], 1166);
                step(f, Op::NegF, &[389, 390], 1167);
                step(f, Op::MakeVector, &[639, 390, 639, 181], 1168);
                step(f, Op::RotateVector, &[35, 181, 183], 1169);
                step(f, Op::AddV, &[178, 183, 185], 1170);
                step(f, Op::AddV, &[185, 175, 187], 1171);
                step(f, Op::SubV, &[185, 175, 188], 1172);
                step(f, Op::LineTrace, &[187, 188, 58, 191, 192, 392], 1173);
                step(f, Op::BreakVector, &[191, 394, 395, 396], 1174);
                step(f, Op::BreakVector, &[185, 400, 401, 402], 1175);
                step(f, Op::SubF, &[396, 402, 406], 1176);
                step(f, Op::Select(ValueType::Float), &[58, 406, 639, 408], 1177);
                step(f, Op::AddF, &[53, 57, 391], 1178);
                step(f, Op::MakeVector, &[639, 391, 639, 182], 1179);
                step(f, Op::RotateVector, &[35, 182, 184], 1180);
                step(f, Op::AddV, &[178, 184, 186], 1181);
                step(f, Op::AddV, &[186, 175, 189], 1182);
                step(f, Op::SubV, &[186, 175, 190], 1183);
                step(f, Op::LineTrace, &[189, 190, 59, 193, 194, 393], 1184);
                step(f, Op::BreakVector, &[193, 397, 398, 399], 1185);
                step(f, Op::BreakVector, &[186, 403, 404, 405], 1186);
                step(f, Op::SubF, &[399, 405, 407], 1187);
                step(f, Op::Select(ValueType::Float), &[59, 407, 639, 409], 1188);
                step(f, Op::MaxF, &[408, 409, 410], 1189);
                step(f, Op::ClampF, &[410, 639, 56, 411], 1190);
                step(f, Op::MakeVector, &[639, 639, 411, 195], 1191);
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
                step(f, Op::GreaterF, &[18, 639, 53], 1200);
                step(f, Op::InterpolateTransform, &[2, 110, 19, 31], 1201);
                step(f, Op::Select(ValueType::Transform), &[53, 31, 2, 32], 1202);
                step(f, Op::MakeAbsolute, &[51, 32, 52], 1203);
                step(f, Op::BreakTransform, &[52, 197, 36, 198], 1204);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 53, 39], 1205);
                step(f, Op::BreakTransform, &[39, 142, 28, 143], 1206);
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 344], 1207);
                step(f, Op::SubF, &[641, 344, 357], 1208);
                step(f, Op::MulF, &[8, 5, 358], 1209);
                step(f, Op::MulF, &[357, 358, 359], 1210);
                step(f, Op::ScaleV, &[2, 359, 144], 1211);
                step(f, Op::AddV, &[142, 144, 145], 1212);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 53, 53], 1213);
                step(f, Op::MakeAbsolute, &[53, 32, 54], 1214);
                step(f, Op::BreakTransform, &[54, 199, 37, 200], 1215);
                step(f, Op::ArrayAt(Elem::Float), &[3, 53, 412], 1216);
                step(f, Op::SubF, &[344, 412, 413], 1217);
                step(f, Op::DeltaTime, &[428], 1218);
                step(f, Op::DivF, &[45, 428, 414], 1219);
                step(f, Op::MulF, &[413, 414, 415], 1220);
                step(f, Op::AddF, &[412, 415, 416], 1221);
                step(f, Op::ClampF, &[416, 639, 641, 418], 1222);
                step(f, Op::AddF, &[344, 415, 417], 1223);
                step(f, Op::ClampF, &[417, 639, 641, 419], 1224);
                step(f, Op::AddF, &[418, 419, 420], 1225);
                step(f, Op::MulF, &[420, 640, 421], 1226);
                step(f, Op::SubF, &[641, 421, 422], 1227);
                step(f, Op::GreaterF, &[413, 639, 60], 1228);
                step(f, Op::SubF, &[419, 418, 423], 1229);
                step(f, Op::DivF, &[423, 413, 424], 1230);
                step(f, Op::Select(ValueType::Float), &[60, 424, 641, 425], 1231);
                step(f, Op::MulF, &[422, 425, 426], 1232);
                step(f, Op::MulF, &[73, 426, 427], 1233);
                step(f, Op::Copy(ValueType::Vec3), &[197, 201], 1234);
                step(f, Op::Copy(ValueType::Vec3), &[145, 202], 1235);
                step(f, Op::Copy(ValueType::Vec3), &[199, 203], 1236);
                step(f, Op::Copy(ValueType::Float), &[427, 429], 1237);
                step(f, Op::Copy(ValueType::Float), &[45, 430], 1238);
                step(f, Op::Copy(ValueType::Vec3), &[391, 204], 1239);
                step(f, Op::SubV, &[202, 203, 205], 1240);
                step(f, Op::DeltaTime, &[431], 1241);
                step(f, Op::DivF, &[430, 431, 432], 1242);
                step(f, Op::ScaleV, &[205, 432, 206], 1243);
                step(f, Op::AddV, &[202, 206, 207], 1244);
                step(f, Op::AddV, &[203, 206, 208], 1245);
                step(f, Op::SubV, &[201, 208, 209], 1246);
                step(f, Op::FloatLerp, &[639, 641, 429, 433], 1247);
                step(f, Op::SubF, &[641, 433, 434], 1248);
                step(f, Op::ScaleV, &[209, 434, 210], 1249);
                step(f, Op::AddV, &[207, 210, 212], 1250);
                step(f, Op::MulF, &[429, 431, 435], 1251);
                step(f, Op::GreaterF, &[435, 639, 61], 1252);
                step(f, Op::DivF, &[433, 435, 436], 1253);
                step(f, Op::Select(ValueType::Float), &[61, 436, 641, 437], 1254);
                step(f, Op::ScaleV, &[205, 437, 211], 1255);
                step(f, Op::SubV, &[212, 211, 213], 1256);
                step(f, Op::Copy(ValueType::Vec3), &[213, 204], 1257);
                step(f, Op::Jump, &[1258], 1258)
            }
            1258 => {
                step(f, Op::MakeTransform, &[204, 28, 392, 56], 1259);
                step(f, Op::Copy(ValueType::Transform), &[56, 57], 1260);
                step(f, Op::Copy(ValueType::Transform), &[110, 58], 1261);
                step(f, Op::BreakTransform, &[57, 214, 38, 215], 1262);
                step(f, Op::MakeVector, &[639, 639, 51, 216], 1263);
                step(f, Op::AddV, &[214, 216, 217], 1264);
                step(f, Op::SubV, &[214, 216, 218], 1265);
                step(f, Op::LineTrace, &[217, 218, 62, 219, 220, 438], 1266);
                step(f, Op::RotateVector, &[38, 394, 221], 1267);
                step(f, Op::FindQuatBetween, &[221, 220, 39], 1268);
                step(f, Op::MulQ, &[39, 38, 40], 1269);
                step(f, Op::MulF, &[49, 48, 439], 1270);
                step(f, Op::AddF, &[439, 57, 440], 1271);
                step(f, Op::NegF, &[440, 441], 1272);
                step(f, Op::MakeVector, &[639, 441, 639, 222], 1273);
                step(f, Op::RotateVector, &[40, 222, 224], 1274);
                step(f, Op::AddV, &[219, 224, 226], 1275);
                step(f, Op::AddV, &[226, 216, 228], 1276);
                step(f, Op::SubV, &[226, 216, 229], 1277);
                step(f, Op::LineTrace, &[228, 229, 63, 232, 233, 443], 1278);
                step(f, Op::BreakVector, &[232, 445, 446, 447], 1279);
                step(f, Op::BreakVector, &[226, 451, 452, 453], 1280);
                step(f, Op::SubF, &[447, 453, 457], 1281);
                step(f, Op::Select(ValueType::Float), &[63, 457, 639, 459], 1282);
                step(f, Op::AddF, &[53, 57, 442], 1283);
                step(f, Op::MakeVector, &[639, 442, 639, 223], 1284);
                step(f, Op::RotateVector, &[40, 223, 225], 1285);
                step(f, Op::AddV, &[219, 225, 227], 1286);
                step(f, Op::AddV, &[227, 216, 230], 1287);
                step(f, Op::SubV, &[227, 216, 231], 1288);
                step(f, Op::LineTrace, &[230, 231, 64, 234, 235, 444], 1289);
                step(f, Op::BreakVector, &[234, 448, 449, 450], 1290);
                step(f, Op::BreakVector, &[227, 454, 455, 456], 1291);
                step(f, Op::SubF, &[450, 456, 458], 1292);
                step(f, Op::Select(ValueType::Float), &[64, 458, 639, 460], 1293);
                step(f, Op::MaxF, &[459, 460, 461], 1294);
                step(f, Op::ClampF, &[461, 639, 56, 462], 1295);
                step(f, Op::MakeVector, &[639, 639, 462, 236], 1296);
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
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 344], 1303);
                step(f, Op::GreaterEqualF, &[344, 641, 51], 1304);
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
                step(f, Op::SubF, &[641, 13, 360], 1315);
                step(f, Op::MulF, &[12, 360, 361], 1316);
                step(f, Op::FootAvoidance, &[238, 146, 361, 52, 74, 148], 1317);
                step(f, Op::MakeTransform, &[148, 41, 392, 41], 1318);
                step(f, Op::Copy(ValueType::Transform), &[41, 42], 1319);
                step(f, Op::Copy(ValueType::Transform), &[110, 43], 1320);
                step(f, Op::BreakTransform, &[42, 149, 30, 150], 1321);
                step(f, Op::MakeVector, &[639, 639, 51, 151], 1322);
                step(f, Op::AddV, &[149, 151, 152], 1323);
                step(f, Op::SubV, &[149, 151, 153], 1324);
                step(f, Op::LineTrace, &[152, 153, 54, 154, 155, 362], 1325);
                step(f, Op::RotateVector, &[30, 394, 156], 1326);
                step(f, Op::FindQuatBetween, &[156, 155, 31], 1327);
                step(f, Op::MulQ, &[31, 30, 32], 1328);
                step(f, Op::MulF, &[49, 48, 363], 1329);
                step(f, Op::AddF, &[363, 57, 364], 1330);
                step(f, Op::NegF, &[364, 365], 1331);
                step(f, Op::MakeVector, &[639, 365, 639, 157], 1332);
                step(f, Op::RotateVector, &[32, 157, 159], 1333);
                step(f, Op::AddV, &[154, 159, 161], 1334);
                step(f, Op::AddV, &[161, 151, 163], 1335);
                step(f, Op::SubV, &[161, 151, 164], 1336);
                step(f, Op::LineTrace, &[163, 164, 55, 167, 168, 367], 1337);
                step(f, Op::BreakVector, &[167, 369, 370, 371], 1338);
                step(f, Op::BreakVector, &[161, 375, 376, 377], 1339);
                step(f, Op::SubF, &[371, 377, 381], 1340);
                step(f, Op::Select(ValueType::Float), &[55, 381, 639, 383], 1341);
                step(f, Op::AddF, &[53, 57, 366], 1342);
                step(f, Op::MakeVector, &[639, 366, 639, 158], 1343);
                step(f, Op::RotateVector, &[32, 158, 160], 1344);
                step(f, Op::AddV, &[154, 160, 162], 1345);
                step(f, Op::AddV, &[162, 151, 165], 1346);
                step(f, Op::SubV, &[162, 151, 166], 1347);
                step(f, Op::LineTrace, &[165, 166, 56, 169, 170, 368], 1348);
                step(f, Op::BreakVector, &[169, 372, 373, 374], 1349);
                step(f, Op::BreakVector, &[162, 378, 379, 380], 1350);
                step(f, Op::SubF, &[374, 380, 382], 1351);
                step(f, Op::Select(ValueType::Float), &[56, 382, 639, 384], 1352);
                step(f, Op::MaxF, &[383, 384, 385], 1353);
                step(f, Op::ClampF, &[385, 639, 56, 386], 1354);
                step(f, Op::MakeVector, &[639, 639, 386, 171], 1355);
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
                step(f, Op::LengthV, &[139, 347], 1367);
                step(f, Op::SubF, &[58, 59, 348], 1368);
                step(f, Op::SubF, &[347, 348, 349], 1369);
                step(f, Op::MulF, &[59, 644, 350], 1370);
                step(f, Op::ClampF, &[349, 639, 350, 351], 1371);
                step(f, Op::MulF, &[351, 351, 352], 1372);
                step(f, Op::MulF, &[59, 651, 353], 1373);
                step(f, Op::DivF, &[352, 353, 354], 1374);
                step(f, Op::SubF, &[347, 354, 355], 1375);
                step(f, Op::DivF, &[355, 347, 356], 1376);
                step(f, Op::ScaleV, &[139, 356, 140], 1377);
                step(f, Op::AddV, &[134, 140, 141], 1378);
                step(f, Op::MakeTransform, &[141, 27, 392, 38], 1379);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 53, 38], 1380);
                step(f, Op::Jump, &[1577], 1381)
            }
            1381 => {
                step(f, Op::ArrayAt(Elem::Transform), &[7, 53, 35], 1382);
                step(f, Op::BreakTransform, &[35, 134, 25, 135], 1383);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 53, 37], 1384);
                step(f, Op::BreakTransform, &[37, 137, 27, 138], 1385);
                step(f, Op::SubV, &[137, 134, 139], 1386);
                step(f, Op::LengthV, &[139, 347], 1387);
                step(f, Op::SubF, &[58, 59, 348], 1388);
                step(f, Op::SubF, &[347, 348, 349], 1389);
                step(f, Op::MulF, &[59, 644, 350], 1390);
                step(f, Op::ClampF, &[349, 639, 350, 351], 1391);
                step(f, Op::MulF, &[351, 351, 352], 1392);
                step(f, Op::MulF, &[59, 651, 353], 1393);
                step(f, Op::DivF, &[352, 353, 354], 1394);
                step(f, Op::SubF, &[347, 354, 355], 1395);
                step(f, Op::DivF, &[355, 347, 356], 1396);
                step(f, Op::ScaleV, &[139, 356, 140], 1397);
                step(f, Op::AddV, &[134, 140, 141], 1398);
                step(f, Op::MakeTransform, &[141, 27, 392, 38], 1399);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 53, 61], 1400);
                step(f, Op::ClampF, &[344, 639, 641, 463], 1401);
                step(f, Op::Copy(ValueType::Transform), &[38, 66], 1402);
                step(f, Op::Copy(ValueType::Transform), &[61, 67], 1403);
                step(f, Op::Copy(ValueType::Float), &[463, 481], 1404);
                step(f, Op::Copy(ValueType::Transform), &[110, 68], 1405);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[3, 2], 1406);
                step(f, Op::ArrayReset(Elem::Vec3), &[2], 1407);
                step(f, Op::BreakTransform, &[66, 256, 46, 257], 1408);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 256], 1409);
                step(f, Op::BreakTransform, &[66, 256, 46, 257], 1410);
                step(f, Op::UnitV, &[2, 255], 1411);
                step(f, Op::LengthV, &[2, 482], 1412);
                step(f, Op::RemapF, &[482, 639, 60, 639, 61, 78, 483], 1413);
                step(f, Op::ScaleV, &[255, 483, 260], 1414);
                step(f, Op::SubV, &[256, 260, 266], 1415);
                step(f, Op::MakeVector, &[639, 639, 63, 264], 1416);
                step(f, Op::AddV, &[266, 264, 268], 1417);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 268], 1418);
                step(f, Op::BreakTransform, &[66, 256, 46, 257], 1419);
                step(f, Op::UnitV, &[2, 255], 1420);
                step(f, Op::LengthV, &[2, 482], 1421);
                step(f, Op::RemapF, &[482, 639, 60, 639, 61, 78, 483], 1422);
                step(f, Op::ScaleV, &[255, 483, 260], 1423);
                step(f, Op::SubV, &[256, 260, 266], 1424);
                step(f, Op::MakeVector, &[639, 639, 63, 264], 1425);
                step(f, Op::AddV, &[266, 264, 268], 1426);
                step(f, Op::RemapF, &[482, 639, 60, 639, 65, 78, 485], 1427);
                step(f, Op::MakeVector, &[639, 639, 485, 262], 1428);
                step(f, Op::AddV, &[268, 262, 272], 1429);
                step(f, Op::BreakTransform, &[67, 258, 47, 259], 1430);
                step(f, Op::BreakVector, &[258, 490, 491, 492], 1431);
                step(f, Op::BreakVector, &[256, 487, 488, 489], 1432);
                step(f, Op::SubF, &[492, 489, 493], 1433);
                step(f, Op::MaxF, &[493, 639, 495], 1434);
                step(f, Op::MulF, &[495, 67, 499], 1435);
                step(f, Op::AbsF, &[493, 497], 1436);
                step(f, Op::RemapF, &[497, 639, 70, 639, 69, 78, 498], 1437);
                step(f, Op::AddF, &[499, 498, 501], 1438);
                step(f, Op::MakeVector, &[639, 639, 501, 270], 1439);
                step(f, Op::AddV, &[272, 270, 274], 1440);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 274], 1441);
                step(f, Op::BreakTransform, &[66, 256, 46, 257], 1442);
                step(f, Op::UnitV, &[2, 255], 1443);
                step(f, Op::LengthV, &[2, 482], 1444);
                step(f, Op::RemapF, &[482, 639, 60, 639, 61, 78, 483], 1445);
                step(f, Op::ScaleV, &[255, 483, 260], 1446);
                step(f, Op::SubV, &[256, 260, 266], 1447);
                step(f, Op::MakeVector, &[639, 639, 63, 264], 1448);
                step(f, Op::AddV, &[266, 264, 268], 1449);
                step(f, Op::RemapF, &[482, 639, 60, 639, 65, 78, 485], 1450);
                step(f, Op::MakeVector, &[639, 639, 485, 262], 1451);
                step(f, Op::AddV, &[268, 262, 272], 1452);
                step(f, Op::BreakTransform, &[67, 258, 47, 259], 1453);
                step(f, Op::BreakVector, &[258, 490, 491, 492], 1454);
                step(f, Op::BreakVector, &[256, 487, 488, 489], 1455);
                step(f, Op::SubF, &[492, 489, 493], 1456);
                step(f, Op::MaxF, &[493, 639, 495], 1457);
                step(f, Op::MulF, &[495, 67, 499], 1458);
                step(f, Op::AbsF, &[493, 497], 1459);
                step(f, Op::RemapF, &[497, 639, 70, 639, 69, 78, 498], 1460);
                step(f, Op::AddF, &[499, 498, 501], 1461);
                step(f, Op::MakeVector, &[639, 639, 501, 270], 1462);
                step(f, Op::AddV, &[272, 270, 274], 1463);
                step(f, Op::RemapF, &[482, 639, 60, 639, 62, 78, 484], 1464);
                step(f, Op::ScaleV, &[255, 484, 261], 1465);
                step(f, Op::AddV, &[258, 261, 267], 1466);
                step(f, Op::MakeVector, &[639, 639, 64, 265], 1467);
                step(f, Op::AddV, &[267, 265, 269], 1468);
                step(f, Op::RemapF, &[482, 639, 60, 639, 66, 78, 486], 1469);
                step(f, Op::MakeVector, &[639, 639, 486, 263], 1470);
                step(f, Op::AddV, &[269, 263, 273], 1471);
                step(f, Op::NegF, &[493, 494], 1472);
                step(f, Op::MaxF, &[494, 639, 496], 1473);
                step(f, Op::MulF, &[496, 68, 500], 1474);
                step(f, Op::AddF, &[500, 498, 502], 1475);
                step(f, Op::MakeVector, &[639, 639, 502, 271], 1476);
                step(f, Op::AddV, &[273, 271, 275], 1477);
                step(f, Op::LerpV, &[274, 275, 640, 276], 1478);
                step(f, Op::GetTransform, &[36, 65, 78, 69], 1479);
                step(f, Op::BreakTransform, &[69, 277, 48, 278], 1480);
                step(f, Op::BreakVector, &[277, 512, 513, 514], 1481);
                step(f, Op::SubF, &[641, 13, 506], 1482);
                step(f, Op::MulF, &[71, 506, 507], 1483);
                step(f, Op::MulF, &[12, 507, 508], 1484);
                step(f, Op::QuatFromAxisAngle, &[394, 508, 49], 1485);
                step(f, Op::SubV, &[276, 277, 279], 1486);
                step(f, Op::BreakVector, &[279, 503, 504, 505], 1487);
                step(f, Op::MakeVector, &[503, 504, 639, 280], 1488);
                step(f, Op::RotateVector, &[49, 280, 281], 1489);
                step(f, Op::BreakVector, &[281, 509, 510, 511], 1490);
                step(f, Op::AddF, &[512, 509, 518], 1491);
                step(f, Op::AddF, &[513, 510, 519], 1492);
                step(f, Op::BreakVector, &[276, 515, 516, 517], 1493);
                step(f, Op::MakeVector, &[518, 519, 517, 282], 1494);
                step(f, Op::DistanceV, &[256, 258, 520], 1495);
                step(f, Op::RemapF, &[520, 644, 652, 639, 641, 78, 521], 1496);
                step(f, Op::LerpV, &[276, 282, 521, 283], 1497);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 283], 1498);
                step(f, Op::BreakTransform, &[67, 258, 47, 259], 1499);
                step(f, Op::UnitV, &[2, 255], 1500);
                step(f, Op::LengthV, &[2, 482], 1501);
                step(f, Op::RemapF, &[482, 639, 60, 639, 62, 78, 484], 1502);
                step(f, Op::ScaleV, &[255, 484, 261], 1503);
                step(f, Op::AddV, &[258, 261, 267], 1504);
                step(f, Op::MakeVector, &[639, 639, 64, 265], 1505);
                step(f, Op::AddV, &[267, 265, 269], 1506);
                step(f, Op::RemapF, &[482, 639, 60, 639, 66, 78, 486], 1507);
                step(f, Op::MakeVector, &[639, 639, 486, 263], 1508);
                step(f, Op::AddV, &[269, 263, 273], 1509);
                step(f, Op::BreakVector, &[258, 490, 491, 492], 1510);
                step(f, Op::BreakTransform, &[66, 256, 46, 257], 1511);
                step(f, Op::BreakVector, &[256, 487, 488, 489], 1512);
                step(f, Op::SubF, &[492, 489, 493], 1513);
                step(f, Op::NegF, &[493, 494], 1514);
                step(f, Op::MaxF, &[494, 639, 496], 1515);
                step(f, Op::MulF, &[496, 68, 500], 1516);
                step(f, Op::AbsF, &[493, 497], 1517);
                step(f, Op::RemapF, &[497, 639, 70, 639, 69, 78, 498], 1518);
                step(f, Op::AddF, &[500, 498, 502], 1519);
                step(f, Op::MakeVector, &[639, 639, 502, 271], 1520);
                step(f, Op::AddV, &[273, 271, 275], 1521);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 275], 1522);
                step(f, Op::BreakTransform, &[67, 258, 47, 259], 1523);
                step(f, Op::UnitV, &[2, 255], 1524);
                step(f, Op::LengthV, &[2, 482], 1525);
                step(f, Op::RemapF, &[482, 639, 60, 639, 62, 78, 484], 1526);
                step(f, Op::ScaleV, &[255, 484, 261], 1527);
                step(f, Op::AddV, &[258, 261, 267], 1528);
                step(f, Op::MakeVector, &[639, 639, 64, 265], 1529);
                step(f, Op::AddV, &[267, 265, 269], 1530);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 269], 1531);
                step(f, Op::BreakTransform, &[67, 258, 47, 259], 1532);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 258], 1533);
                step(f, Op::JumpIfFalse, &[8, 1536], 1534)
            }
            1534 => {
                step(f, Op::DrawSpline, &[2, 65, 68, 640, 396], 1535);
                step(f, Op::Jump, &[1536], 1536)
            }
            1536 => {
                step(f, Op::Spline, &[2, 481, 65, 284, 285], 1537);
                step(f, Op::BreakTransform, &[66, 256, 46, 257], 1538);
                step(f, Op::BreakTransform, &[67, 258, 47, 259], 1539);
                step(f, Op::SlerpQ, &[46, 47, 481, 50], 1540);
                step(f, Op::MulF, &[481, 653, 522], 1541);
                step(f, Op::SinF, &[522, 523], 1542);
                step(f, Op::MulF, &[523, 72, 524], 1543);
                step(f, Op::SlerpQ, &[50, 90, 524, 51], 1544);
                step(f, Op::MakeTransform, &[284, 51, 392, 70], 1545);
                step(f, Op::Copy(ValueType::Transform), &[70, 68], 1546);
                step(f, Op::Jump, &[1547], 1547)
            }
            1547 => {
                step(f, Op::BreakTransform, &[68, 240, 42, 241], 1548);
                step(f, Op::Equals(Elem::Int), &[53, 65, 52], 1549);
                step(f, Op::Select(ValueType::Int), &[52, 66, 65, 54], 1550);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 54, 40], 1551);
                step(f, Op::BreakTransform, &[40, 146, 29, 147], 1552);
                step(f, Op::SubF, &[641, 13, 360], 1553);
                step(f, Op::MulF, &[12, 360, 361], 1554);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 54, 65], 1555);
                step(f, Op::Select(ValueType::Float), &[65, 75, 639, 466], 1556);
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 344], 1557);
                step(f, Op::ClampF, &[344, 639, 641, 463], 1558);
                step(f, Op::MulF, &[463, 653, 464], 1559);
                step(f, Op::SinF, &[464, 465], 1560);
                step(f, Op::MulF, &[465, 465, 467], 1561);
                step(f, Op::MulF, &[466, 467, 468], 1562);
                step(f, Op::AddF, &[74, 468, 469], 1563);
                step(f, Op::FootAvoidance, &[240, 146, 361, 52, 469, 242], 1564);
                step(f, Op::SubV, &[242, 240, 243], 1565);
                step(f, Op::LengthV, &[243, 470], 1566);
                step(f, Op::AddF, &[470, 468, 471], 1567);
                step(f, Op::DivF, &[470, 471, 472], 1568);
                step(f, Op::ScaleV, &[243, 472, 244], 1569);
                step(f, Op::AddV, &[240, 244, 245], 1570);
                step(f, Op::SubF, &[641, 112, 473], 1571);
                step(f, Op::MulF, &[3, 473, 474], 1572);
                step(f, Op::MulF, &[474, 467, 475], 1573);
                step(f, Op::MakeVector, &[639, 639, 475, 246], 1574);
                step(f, Op::AddV, &[245, 246, 247], 1575);
                step(f, Op::MakeTransform, &[247, 42, 392, 62], 1576);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 53, 62], 1577);
                1577
            }
            1577 => {
                step(f, Op::GreaterF, &[18, 639, 53], 1578);
                step(f, Op::JumpIfFalse, &[53, 1595], 1579)
            }
            1579 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 53, 63], 1580);
                step(f, Op::BreakTransform, &[63, 248, 43, 249], 1581);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 53, 64], 1582);
                step(f, Op::BreakTransform, &[64, 250, 44, 251], 1583);
                step(f, Op::MulF, &[18, 18, 476], 1584);
                step(f, Op::LerpV, &[248, 250, 476, 252], 1585);
                step(f, Op::SubF, &[641, 18, 477], 1586);
                step(f, Op::MulF, &[18, 477, 478], 1587);
                step(f, Op::MulF, &[114, 644, 479], 1588);
                step(f, Op::MulF, &[478, 479, 480], 1589);
                step(f, Op::MakeVector, &[639, 639, 480, 253], 1590);
                step(f, Op::AddV, &[252, 253, 254], 1591);
                step(f, Op::SlerpQ, &[43, 44, 18, 45], 1592);
                step(f, Op::MakeTransform, &[254, 45, 392, 65], 1593);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 53, 65], 1594);
                step(f, Op::Jump, &[1595], 1595)
            }
            1595 => {
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 344], 1596);
                step(f, Op::GreaterEqualF, &[344, 641, 51], 1597);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 53, 51], 1598);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 53, 39], 1599);
                step(f, Op::BreakTransform, &[39, 142, 28, 143], 1600);
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 344], 1601);
                step(f, Op::SubF, &[641, 344, 357], 1602);
                step(f, Op::MulF, &[8, 5, 358], 1603);
                step(f, Op::MulF, &[357, 358, 359], 1604);
                step(f, Op::ScaleV, &[2, 359, 144], 1605);
                step(f, Op::AddV, &[142, 144, 145], 1606);
                step(f, Op::MakeTransform, &[145, 90, 392, 55], 1607);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 53, 55], 1608);
                step(f, Op::Copy(ValueType::Bone), &[0, 17], 1609);
                step(f, Op::Copy(ValueType::Int), &[3, 55], 1610);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 55, 71], 1611);
                step(f, Op::BreakTransform, &[71, 286, 52, 287], 1612);
                step(f, Op::MakeVector, &[639, 639, 46, 296], 1613);
                step(f, Op::AddV, &[286, 296, 297], 1614);
                step(f, Op::GetTransform, &[17, 65, 78, 73], 1615);
                step(f, Op::BreakTransform, &[73, 291, 54, 292], 1616);
                step(f, Op::MakeTransform, &[297, 54, 392, 75], 1617);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 55, 20], 1618);
                step(f, Op::GetTransform, &[20, 65, 78, 74], 1619);
                step(f, Op::BreakTransform, &[74, 293, 55, 294], 1620);
                step(f, Op::SubV, &[293, 291, 295], 1621);
                step(f, Op::AddV, &[297, 295, 298], 1622);
                step(f, Op::FootPivots, &[297, 298, 48, 47, 46, 49, 299, 300, 301], 1623);
                step(f, Op::GetParent, &[17, 18], 1624);
                step(f, Op::GetParent, &[18, 19], 1625);
                step(f, Op::GetTransform, &[19, 65, 79, 72], 1626);
                step(f, Op::BreakTransform, &[72, 288, 53, 289], 1627);
                step(f, Op::SubV, &[286, 288, 290], 1628);
                step(f, Op::DotV, &[290, 395, 525], 1629);
                step(f, Op::RemapF, &[525, 77, 76, 78, 639, 78, 528], 1630);
                step(f, Op::LengthV, &[2, 526], 1631);
                step(f, Op::RemapF, &[526, 639, 84, 639, 641, 78, 527], 1632);
                step(f, Op::MulF, &[528, 527, 529], 1633);
                step(f, Op::QuatFromAxisAngle, &[397, 529, 56], 1634);
                step(f, Op::RotateAroundPoint, &[75, 299, 56, 76], 1635);
                step(f, Op::SubV, &[300, 299, 302], 1636);
                step(f, Op::RotateVector, &[56, 302, 303], 1637);
                step(f, Op::AddV, &[299, 303, 304], 1638);
                step(f, Op::RemapF, &[525, 79, 77, 80, 639, 78, 530], 1639);
                step(f, Op::MulF, &[530, 527, 531], 1640);
                step(f, Op::QuatFromAxisAngle, &[397, 531, 57], 1641);
                step(f, Op::RotateAroundPoint, &[76, 304, 57, 77], 1642);
                step(f, Op::RemapF, &[525, 81, 82, 639, 83, 78, 532], 1643);
                step(f, Op::MulF, &[532, 527, 533], 1644);
                step(f, Op::QuatFromAxisAngle, &[397, 533, 58], 1645);
                step(f, Op::RotateAroundPoint, &[77, 301, 58, 78], 1646);
                step(f, Op::SubF, &[641, 13, 534], 1647);
                step(f, Op::MulF, &[12, 534, 535], 1648);
                step(f, Op::LimitRotationAroundZ, &[52, 535, 85, 59], 1649);
                step(f, Op::RotateAroundPoint, &[78, 286, 59, 79], 1650);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 55, 79], 1651);
                step(f, Op::JumpIfFalse, &[8, 1708], 1652)
            }
            1652 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 55, 71], 1653);
                step(f, Op::BreakTransform, &[71, 286, 52, 287], 1654);
                step(f, Op::MakeVector, &[639, 639, 46, 296], 1655);
                step(f, Op::AddV, &[286, 296, 297], 1656);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 55, 20], 1657);
                step(f, Op::GetTransform, &[20, 65, 78, 74], 1658);
                step(f, Op::BreakTransform, &[74, 293, 55, 294], 1659);
                step(f, Op::GetTransform, &[17, 65, 78, 73], 1660);
                step(f, Op::BreakTransform, &[73, 291, 54, 292], 1661);
                step(f, Op::SubV, &[293, 291, 295], 1662);
                step(f, Op::AddV, &[297, 295, 298], 1663);
                step(f, Op::FootPivots, &[297, 298, 48, 47, 46, 49, 299, 300, 301], 1664);
                step(f, Op::DrawPoint, &[301, 645, 397], 1665);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 55, 71], 1666);
                step(f, Op::BreakTransform, &[71, 286, 52, 287], 1667);
                step(f, Op::MakeVector, &[639, 639, 46, 296], 1668);
                step(f, Op::AddV, &[286, 296, 297], 1669);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 55, 20], 1670);
                step(f, Op::GetTransform, &[20, 65, 78, 74], 1671);
                step(f, Op::BreakTransform, &[74, 293, 55, 294], 1672);
                step(f, Op::GetTransform, &[17, 65, 78, 73], 1673);
                step(f, Op::BreakTransform, &[73, 291, 54, 292], 1674);
                step(f, Op::SubV, &[293, 291, 295], 1675);
                step(f, Op::AddV, &[297, 295, 298], 1676);
                step(f, Op::FootPivots, &[297, 298, 48, 47, 46, 49, 299, 300, 301], 1677);
                step(f, Op::DrawPoint, &[299, 645, 395], 1678);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 55, 71], 1679);
                step(f, Op::BreakTransform, &[71, 286, 52, 287], 1680);
                step(f, Op::MakeVector, &[639, 639, 46, 296], 1681);
                step(f, Op::AddV, &[286, 296, 297], 1682);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 55, 20], 1683);
                step(f, Op::GetTransform, &[20, 65, 78, 74], 1684);
                step(f, Op::BreakTransform, &[74, 293, 55, 294], 1685);
                step(f, Op::GetTransform, &[17, 65, 78, 73], 1686);
                step(f, Op::BreakTransform, &[73, 291, 54, 292], 1687);
                step(f, Op::SubV, &[293, 291, 295], 1688);
                step(f, Op::AddV, &[297, 295, 298], 1689);
                step(f, Op::FootPivots, &[297, 298, 48, 47, 46, 49, 299, 300, 301], 1690);
                step(f, Op::GetParent, &[17, 18], 1691);
                step(f, Op::GetParent, &[18, 19], 1692);
                step(f, Op::GetTransform, &[19, 65, 79, 72], 1693);
                step(f, Op::BreakTransform, &[72, 288, 53, 289], 1694);
                step(f, Op::SubV, &[286, 288, 290], 1695);
                step(f, Op::DotV, &[290, 395, 525], 1696);
                step(f, Op::RemapF, &[525, 77, 76, 78, 639, 78, 528], 1697);
                step(f, Op::LengthV, &[2, 526], 1698);
                step(f, Op::RemapF, &[526, 639, 84, 639, 641, 78, 527], 1699);
                step(f, Op::MulF, &[528, 527, 529], 1700);
                step(f, Op::QuatFromAxisAngle, &[397, 529, 56], 1701);
                step(f, Op::SubV, &[300, 299, 302], 1702);
                step(f, Op::RotateVector, &[56, 302, 303], 1703);
                step(f, Op::AddV, &[299, 303, 304], 1704);
                step(f, Op::DrawPoint, &[304, 645, 394], 1705);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 55, 71], 1706);
                step(f, Op::DrawTransform, &[71, 652, 640], 1707);
                step(f, Op::Jump, &[1708], 1708)
            }
            1708 => {
                step(f, Op::Jump, &[961], 1709)
            }
            1709 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1710);
                step(f, Op::Copy(ValueType::Int), &[65, 5], 1711);
                1711
            }
            1711 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 5, 1, 6, 7, 1766], 1712)
            }
            1712 => {
                step(f, Op::Copy(ValueType::Bone), &[1, 21], 1713);
                step(f, Op::Copy(ValueType::Int), &[6, 56], 1714);
                step(f, Op::GetParent, &[21, 22], 1715);
                step(f, Op::GetParent, &[22, 23], 1716);
                step(f, Op::GetParent, &[23, 24], 1717);
                step(f, Op::GetTransform, &[24, 65, 79, 80], 1718);
                step(f, Op::BreakTransform, &[80, 305, 60, 306], 1719);
                step(f, Op::LengthV, &[1, 537], 1720);
                step(f, Op::ClavicleOffset, &[10, 537, 90, 93, 538], 1721);
                step(f, Op::MakeVector, &[639, 639, 538, 307], 1722);
                step(f, Op::AddV, &[305, 307, 308], 1723);
                step(f, Op::MakeTransform, &[308, 60, 392, 81], 1724);
                step(f, Op::SetTransform, &[24, 81, 65, 78, 641], 1725);
                step(f, Op::GetParent, &[21, 22], 1726);
                step(f, Op::GetParent, &[22, 23], 1727);
                step(f, Op::GetTransform, &[21, 65, 79, 82], 1728);
                step(f, Op::GetTransform, &[23, 65, 79, 83], 1729);
                step(f, Op::BreakTransform, &[83, 309, 62, 310], 1730);
                step(f, Op::Equals(Elem::Int), &[56, 65, 66], 1731);
                step(f, Op::Select(ValueType::Int), &[66, 66, 65, 57], 1732);
                step(f, Op::ArrayAt(Elem::Float), &[0, 57, 536], 1733);
                step(f, Op::ArmSwingRotation, &[536, 1, 0, 91, 647, 654, 641, 90, 88, 89, 647, 647, 641, 539], 1734);
                step(f, Op::QuatFromAxisAngle, &[397, 539, 61], 1735);
                step(f, Op::RotateAroundPoint, &[82, 309, 61, 84], 1736);
                step(f, Op::BreakTransform, &[84, 311, 63, 312], 1737);
                step(f, Op::LengthV, &[1, 537], 1738);
                step(f, Op::RemapF, &[537, 639, 90, 639, 92, 78, 540], 1739);
                step(f, Op::MakeVector, &[639, 639, 540, 313], 1740);
                step(f, Op::AddV, &[311, 313, 314], 1741);
                step(f, Op::MakeTransform, &[314, 63, 392, 85], 1742);
                step(f, Op::Select(ValueType::Vec3), &[66, 398, 397, 316], 1743);
                step(f, Op::Select(ValueType::Vec3), &[66, 395, 399, 317], 1744);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 56, 315], 1745);
                step(f, Op::TwoBoneIK, &[23, 22, 21, 85, 316, 317, 315, 65, 641, 79, 655, 656, 78, 67, 541], 1746);
                step(f, Op::JumpIfFalse, &[8, 1765], 1747)
            }
            1747 => {
                step(f, Op::GetParent, &[21, 22], 1748);
                step(f, Op::GetParent, &[22, 23], 1749);
                step(f, Op::GetTransform, &[23, 65, 79, 83], 1750);
                step(f, Op::BreakTransform, &[83, 309, 62, 310], 1751);
                step(f, Op::GetTransform, &[21, 65, 79, 82], 1752);
                step(f, Op::Equals(Elem::Int), &[56, 65, 66], 1753);
                step(f, Op::Select(ValueType::Int), &[66, 66, 65, 57], 1754);
                step(f, Op::ArrayAt(Elem::Float), &[0, 57, 536], 1755);
                step(f, Op::ArmSwingRotation, &[536, 1, 0, 91, 647, 654, 641, 90, 88, 89, 647, 647, 641, 539], 1756);
                step(f, Op::QuatFromAxisAngle, &[397, 539, 61], 1757);
                step(f, Op::RotateAroundPoint, &[82, 309, 61, 84], 1758);
                step(f, Op::BreakTransform, &[84, 311, 63, 312], 1759);
                step(f, Op::LengthV, &[1, 537], 1760);
                step(f, Op::RemapF, &[537, 639, 90, 639, 92, 78, 540], 1761);
                step(f, Op::MakeVector, &[639, 639, 540, 313], 1762);
                step(f, Op::AddV, &[311, 313, 314], 1763);
                step(f, Op::DrawLine, &[309, 314, 640, 395], 1764);
                step(f, Op::Jump, &[1765], 1765)
            }
            1765 => {
                step(f, Op::Jump, &[1711], 1766)
            }
            1766 => {
                step(f, Op::Copy(ValueType::Float), &[639, 544], 1767);
                step(f, Op::Copy(ValueType::Float), &[648, 545], 1768);
                step(f, Op::Copy(ValueType::Bool), &[79, 68], 1769);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 10], 1770);
                step(f, Op::Copy(ValueType::Int), &[65, 58], 1771);
                step(f, Op::MakeVector, &[639, 639, 51, 320], 1772);
                1772
            }
            1772 => {
                step(f, Op::ForEachNext(Elem::Transform), &[10, 58, 86, 59, 60, 1785], 1773)
            }
            1773 => {
                step(f, Op::BreakTransform, &[86, 318, 64, 319], 1774);
                step(f, Op::AddV, &[318, 320, 321], 1775);
                step(f, Op::SubV, &[318, 320, 322], 1776);
                step(f, Op::SphereTrace, &[321, 322, 50, 69, 323, 324, 546], 1777);
                step(f, Op::BreakVector, &[323, 547, 548, 549], 1778);
                step(f, Op::LessF, &[549, 545, 70], 1779);
                step(f, Op::And, &[69, 70, 71], 1780);
                step(f, Op::JumpIfFalse, &[71, 1784], 1781)
            }
            1781 => {
                step(f, Op::Copy(ValueType::Float), &[549, 545], 1782);
                step(f, Op::Copy(ValueType::Bool), &[78, 68], 1783);
                step(f, Op::Jump, &[1784], 1784)
            }
            1784 => {
                step(f, Op::Jump, &[1772], 1785)
            }
            1785 => {
                step(f, Op::Select(ValueType::Float), &[68, 545, 639, 550], 1786);
                step(f, Op::ClampF, &[550, 54, 55, 551], 1787);
                step(f, Op::Copy(ValueType::Float), &[551, 544], 1788);
                step(f, Op::Jump, &[1789], 1789)
            }
            1789 => {
                step(f, Op::SubF, &[641, 18, 543], 1790);
                step(f, Op::MulF, &[544, 543, 552], 1791);
                step(f, Op::FloatLerp, &[14, 552, 44, 553], 1792);
                step(f, Op::Select(ValueType::Float), &[1, 552, 553, 554], 1793);
                step(f, Op::Copy(ValueType::Float), &[554, 14], 1794);
                step(f, Op::GetTransform, &[37, 65, 78, 91], 1795);
                step(f, Op::BreakTransform, &[91, 337, 71, 338], 1796);
                step(f, Op::PelvisLean, &[1, 95, 100, 101, 570, 571], 1797);
                step(f, Op::LengthV, &[2, 542], 1798);
                step(f, Op::RemapF, &[542, 639, 95, 639, 94, 78, 555], 1799);
                step(f, Op::MulF, &[10, 657, 556], 1800);
                step(f, Op::SinF, &[556, 557], 1801);
                step(f, Op::MulF, &[555, 557, 558], 1802);
                step(f, Op::MulF, &[558, 543, 559], 1803);
                step(f, Op::AddF, &[559, 14, 560], 1804);
                step(f, Op::MulF, &[3, 112, 561], 1805);
                step(f, Op::SubF, &[560, 561, 562], 1806);
                step(f, Op::MakeVector, &[639, 571, 562, 339], 1807);
                step(f, Op::AddV, &[337, 339, 340], 1808);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 87], 1809);
                step(f, Op::BreakTransform, &[87, 325, 65, 326], 1810);
                step(f, Op::BreakVector, &[325, 572, 573, 574], 1811);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 66, 88], 1812);
                step(f, Op::BreakTransform, &[88, 327, 66, 328], 1813);
                step(f, Op::BreakVector, &[327, 575, 576, 577], 1814);
                step(f, Op::SubF, &[574, 577, 578], 1815);
                step(f, Op::PelvisSideLean, &[578, 102, 103, 579], 1816);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 65, 89], 1817);
                step(f, Op::BreakTransform, &[89, 331, 67, 332], 1818);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 66, 90], 1819);
                step(f, Op::BreakTransform, &[90, 333, 68, 334], 1820);
                step(f, Op::SlerpQ, &[67, 68, 640, 69], 1821);
                step(f, Op::EulerFromQuat, &[69, 65, 335], 1822);
                step(f, Op::BreakVector, &[335, 566, 567, 568], 1823);
                step(f, Op::RemapF, &[542, 96, 95, 639, 97, 78, 564], 1824);
                step(f, Op::SubV, &[325, 327, 329], 1825);
                step(f, Op::RotateVector, &[0, 395, 330], 1826);
                step(f, Op::DotV, &[329, 330, 563], 1827);
                step(f, Op::MulF, &[564, 563, 565], 1828);
                step(f, Op::AddF, &[568, 565, 569], 1829);
                step(f, Op::MakeVector, &[570, 579, 569, 336], 1830);
                step(f, Op::QuatFromEuler, &[336, 65, 70], 1831);
                step(f, Op::MakeTransform, &[340, 70, 392, 92], 1832);
                step(f, Op::SetTransform, &[38, 92, 65, 78, 641], 1833);
                step(f, Op::GetTransform, &[39, 66, 78, 93], 1834);
                step(f, Op::BreakTransform, &[93, 341, 75, 342], 1835);
                step(f, Op::LengthV, &[2, 542], 1836);
                step(f, Op::RemapF, &[542, 96, 95, 639, 97, 78, 564], 1837);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 87], 1838);
                step(f, Op::BreakTransform, &[87, 325, 65, 326], 1839);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 66, 88], 1840);
                step(f, Op::BreakTransform, &[88, 327, 66, 328], 1841);
                step(f, Op::SubV, &[325, 327, 329], 1842);
                step(f, Op::RotateVector, &[0, 395, 330], 1843);
                step(f, Op::DotV, &[329, 330, 563], 1844);
                step(f, Op::MulF, &[564, 563, 565], 1845);
                step(f, Op::QuatFromAxisAngle, &[394, 565, 72], 1846);
                step(f, Op::DivF, &[98, 645, 580], 1847);
                step(f, Op::QuatScale, &[72, 580, 73], 1848);
                step(f, Op::MulQ, &[75, 73, 79], 1849);
                step(f, Op::MakeTransform, &[341, 79, 392, 97], 1850);
                step(f, Op::SetTransform, &[40, 97, 66, 78, 641], 1851);
                step(f, Op::GetTransform, &[41, 66, 78, 94], 1852);
                step(f, Op::BreakTransform, &[94, 343, 76, 344], 1853);
                step(f, Op::LengthV, &[2, 542], 1854);
                step(f, Op::RemapF, &[542, 96, 95, 639, 97, 78, 564], 1855);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 87], 1856);
                step(f, Op::BreakTransform, &[87, 325, 65, 326], 1857);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 66, 88], 1858);
                step(f, Op::BreakTransform, &[88, 327, 66, 328], 1859);
                step(f, Op::SubV, &[325, 327, 329], 1860);
                step(f, Op::RotateVector, &[0, 395, 330], 1861);
                step(f, Op::DotV, &[329, 330, 563], 1862);
                step(f, Op::MulF, &[564, 563, 565], 1863);
                step(f, Op::QuatFromAxisAngle, &[394, 565, 72], 1864);
                step(f, Op::DivF, &[98, 645, 580], 1865);
                step(f, Op::QuatScale, &[72, 580, 73], 1866);
                step(f, Op::MulQ, &[76, 73, 80], 1867);
                step(f, Op::MakeTransform, &[343, 80, 392, 98], 1868);
                step(f, Op::SetTransform, &[42, 98, 66, 78, 641], 1869);
                step(f, Op::GetTransform, &[43, 66, 78, 95], 1870);
                step(f, Op::BreakTransform, &[95, 345, 77, 346], 1871);
                step(f, Op::LengthV, &[2, 542], 1872);
                step(f, Op::RemapF, &[542, 96, 95, 639, 97, 78, 564], 1873);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 87], 1874);
                step(f, Op::BreakTransform, &[87, 325, 65, 326], 1875);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 66, 88], 1876);
                step(f, Op::BreakTransform, &[88, 327, 66, 328], 1877);
                step(f, Op::SubV, &[325, 327, 329], 1878);
                step(f, Op::RotateVector, &[0, 395, 330], 1879);
                step(f, Op::DotV, &[329, 330, 563], 1880);
                step(f, Op::MulF, &[564, 563, 565], 1881);
                step(f, Op::QuatFromAxisAngle, &[394, 565, 72], 1882);
                step(f, Op::DivF, &[98, 645, 580], 1883);
                step(f, Op::QuatScale, &[72, 580, 73], 1884);
                step(f, Op::MulQ, &[77, 73, 81], 1885);
                step(f, Op::MakeTransform, &[345, 81, 392, 99], 1886);
                step(f, Op::SetTransform, &[44, 99, 66, 78, 641], 1887);
                step(f, Op::GetTransform, &[45, 66, 78, 96], 1888);
                step(f, Op::BreakTransform, &[96, 347, 78, 348], 1889);
                step(f, Op::LengthV, &[2, 542], 1890);
                step(f, Op::RemapF, &[542, 96, 95, 639, 97, 78, 564], 1891);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 87], 1892);
                step(f, Op::BreakTransform, &[87, 325, 65, 326], 1893);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 66, 88], 1894);
                step(f, Op::BreakTransform, &[88, 327, 66, 328], 1895);
                step(f, Op::SubV, &[325, 327, 329], 1896);
                step(f, Op::RotateVector, &[0, 395, 330], 1897);
                step(f, Op::DotV, &[329, 330, 563], 1898);
                step(f, Op::MulF, &[564, 563, 565], 1899);
                step(f, Op::QuatFromAxisAngle, &[394, 565, 72], 1900);
                step(f, Op::QuatScale, &[72, 99, 74], 1901);
                step(f, Op::MulQ, &[78, 74, 82], 1902);
                step(f, Op::MakeTransform, &[347, 82, 392, 100], 1903);
                step(f, Op::SetTransform, &[46, 100, 66, 78, 641], 1904);
                step(f, Op::Copy(ValueType::Float), &[639, 581], 1905);
                step(f, Op::Copy(ValueType::Float), &[639, 582], 1906);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1907);
                step(f, Op::Copy(ValueType::Int), &[65, 61], 1908);
                1908
            }
            1908 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 61, 25, 62, 63, 1938], 1909)
            }
            1909 => {
                step(f, Op::GetParent, &[25, 26], 1910);
                step(f, Op::GetParent, &[26, 27], 1911);
                step(f, Op::GetTransform, &[27, 65, 79, 101], 1912);
                step(f, Op::BreakTransform, &[101, 349, 83, 350], 1913);
                step(f, Op::BreakVector, &[349, 583, 584, 585], 1914);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 62, 102], 1915);
                step(f, Op::BreakTransform, &[102, 351, 84, 352], 1916);
                step(f, Op::BreakVector, &[351, 586, 587, 588], 1917);
                step(f, Op::ArrayAt(Elem::Float), &[1, 62, 592], 1918);
                step(f, Op::MulF, &[592, 104, 593], 1919);
                step(f, Op::MulF, &[593, 593, 594], 1920);
                step(f, Op::SubF, &[583, 586, 589], 1921);
                step(f, Op::SubF, &[584, 587, 590], 1922);
                step(f, Op::MakeVector, &[589, 590, 639, 353], 1923);
                step(f, Op::DotV, &[353, 353, 591], 1924);
                step(f, Op::SubF, &[594, 591, 595], 1925);
                step(f, Op::SqrtF, &[595, 596], 1926);
                step(f, Op::AddF, &[588, 596, 597], 1927);
                step(f, Op::SubF, &[585, 597, 598], 1928);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 62, 72], 1929);
                step(f, Op::ArrayAt(Elem::Float), &[2, 62, 599], 1930);
                step(f, Op::RemapF, &[599, 640, 641, 639, 641, 78, 600], 1931);
                step(f, Op::RemapF, &[599, 639, 107, 641, 639, 78, 601], 1932);
                step(f, Op::MaxF, &[600, 601, 602], 1933);
                step(f, Op::Select(ValueType::Float), &[72, 641, 602, 603], 1934);
                step(f, Op::MulF, &[598, 603, 604], 1935);
                step(f, Op::MaxF, &[582, 604, 605], 1936);
                step(f, Op::Copy(ValueType::Float), &[605, 582], 1937);
                step(f, Op::Jump, &[1908], 1938)
            }
            1938 => {
                step(f, Op::ClampF, &[582, 639, 105, 606], 1939);
                step(f, Op::Copy(ValueType::Float), &[606, 581], 1940);
                step(f, Op::Jump, &[1941], 1941)
            }
            1941 => {
                step(f, Op::MakeVector, &[15, 639, 639, 354], 1942);
                step(f, Op::MakeVector, &[581, 639, 639, 355], 1943);
                step(f, Op::MakeVector, &[16, 639, 639, 356], 1944);
                step(f, Op::GreaterF, &[581, 15, 73], 1945);
                step(f, Op::Select(ValueType::Float), &[73, 109, 106, 607], 1946);
                step(f, Op::Copy(ValueType::Vec3), &[354, 357], 1947);
                step(f, Op::Copy(ValueType::Vec3), &[355, 358], 1948);
                step(f, Op::Copy(ValueType::Vec3), &[356, 359], 1949);
                step(f, Op::Copy(ValueType::Float), &[607, 608], 1950);
                step(f, Op::Copy(ValueType::Float), &[45, 609], 1951);
                step(f, Op::Copy(ValueType::Vec3), &[391, 360], 1952);
                step(f, Op::SubV, &[358, 359, 361], 1953);
                step(f, Op::DeltaTime, &[610], 1954);
                step(f, Op::DivF, &[609, 610, 611], 1955);
                step(f, Op::ScaleV, &[361, 611, 362], 1956);
                step(f, Op::AddV, &[358, 362, 363], 1957);
                step(f, Op::AddV, &[359, 362, 364], 1958);
                step(f, Op::SubV, &[357, 364, 365], 1959);
                step(f, Op::FloatLerp, &[639, 641, 608, 612], 1960);
                step(f, Op::SubF, &[641, 612, 613], 1961);
                step(f, Op::ScaleV, &[365, 613, 366], 1962);
                step(f, Op::AddV, &[363, 366, 368], 1963);
                step(f, Op::MulF, &[608, 610, 614], 1964);
                step(f, Op::GreaterF, &[614, 639, 74], 1965);
                step(f, Op::DivF, &[612, 614, 615], 1966);
                step(f, Op::Select(ValueType::Float), &[74, 615, 641, 616], 1967);
                step(f, Op::ScaleV, &[361, 616, 367], 1968);
                step(f, Op::SubV, &[368, 367, 369], 1969);
                step(f, Op::Copy(ValueType::Vec3), &[369, 360], 1970);
                step(f, Op::Jump, &[1971], 1971)
            }
            1971 => {
                step(f, Op::BreakVector, &[360, 617, 618, 619], 1972);
                step(f, Op::Select(ValueType::Float), &[1, 581, 617, 620], 1973);
                step(f, Op::Copy(ValueType::Float), &[620, 15], 1974);
                step(f, Op::Copy(ValueType::Float), &[581, 16], 1975);
                step(f, Op::GetTransform, &[47, 65, 79, 103], 1976);
                step(f, Op::BreakTransform, &[103, 370, 85, 371], 1977);
                step(f, Op::MakeVector, &[639, 639, 15, 372], 1978);
                step(f, Op::SubV, &[370, 372, 373], 1979);
                step(f, Op::MakeTransform, &[373, 85, 392, 104], 1980);
                step(f, Op::SetTransform, &[48, 104, 65, 78, 641], 1981);
                step(f, Op::JumpIfFalse, &[8, 1989], 1982)
            }
            1982 => {
                step(f, Op::GetTransform, &[47, 65, 79, 103], 1983);
                step(f, Op::BreakTransform, &[103, 370, 85, 371], 1984);
                step(f, Op::MakeVector, &[639, 639, 15, 372], 1985);
                step(f, Op::SubV, &[370, 372, 373], 1986);
                step(f, Op::MakeTransform, &[373, 85, 392, 104], 1987);
                step(f, Op::DrawTransform, &[104, 658, 640], 1988);
                step(f, Op::Jump, &[1989], 1989)
            }
            1989 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1990);
                step(f, Op::Copy(ValueType::Int), &[65, 8], 1991);
                1991
            }
            1991 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 8, 2, 9, 10, 2043], 1992)
            }
            1992 => {
                step(f, Op::Copy(ValueType::Bone), &[2, 28], 1993);
                step(f, Op::Copy(ValueType::Int), &[9, 64], 1994);
                step(f, Op::GetParent, &[28, 29], 1995);
                step(f, Op::GetParent, &[29, 30], 1996);
                step(f, Op::GetTransform, &[30, 65, 79, 105], 1997);
                step(f, Op::BreakTransform, &[105, 374, 86, 375], 1998);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 64, 106], 1999);
                step(f, Op::BreakTransform, &[106, 376, 87, 377], 2000);
                step(f, Op::SubV, &[376, 374, 378], 2001);
                step(f, Op::LengthV, &[378, 629], 2002);
                step(f, Op::ArrayAt(Elem::Float), &[1, 64, 621], 2003);
                step(f, Op::MulF, &[621, 115, 622], 2004);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 64, 75], 2005);
                step(f, Op::ArrayAt(Elem::Float), &[2, 64, 623], 2006);
                step(f, Op::ClampF, &[623, 639, 641, 624], 2007);
                step(f, Op::MulF, &[624, 653, 625], 2008);
                step(f, Op::SinF, &[625, 626], 2009);
                step(f, Op::MulF, &[626, 116, 627], 2010);
                step(f, Op::Select(ValueType::Float), &[75, 639, 627, 628], 2011);
                step(f, Op::SubF, &[622, 628, 630], 2012);
                step(f, Op::SubF, &[629, 630, 631], 2013);
                step(f, Op::MaxF, &[631, 639, 632], 2014);
                step(f, Op::MulF, &[632, 632, 633], 2015);
                step(f, Op::AddF, &[632, 628, 634], 2016);
                step(f, Op::DivF, &[633, 634, 635], 2017);
                step(f, Op::SubF, &[629, 635, 636], 2018);
                step(f, Op::DivF, &[636, 629, 637], 2019);
                step(f, Op::ScaleV, &[378, 637, 379], 2020);
                step(f, Op::AddV, &[374, 379, 380], 2021);
                step(f, Op::ClampSpatially, &[380, 374, 639, 622, 381], 2022);
                step(f, Op::MakeTransform, &[381, 87, 392, 107], 2023);
                step(f, Op::Equals(Elem::Int), &[64, 65, 76], 2024);
                step(f, Op::Select(ValueType::Vec3), &[76, 398, 397, 386], 2025);
                step(f, Op::Select(ValueType::Vec3), &[76, 395, 399, 387], 2026);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 64, 108], 2027);
                step(f, Op::BreakTransform, &[108, 382, 88, 383], 2028);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 64, 384], 2029);
                step(f, Op::KneeVector, &[88, 0, 384, 117, 118, 385], 2030);
                step(f, Op::TwoBoneIK, &[30, 29, 28, 107, 386, 387, 385, 65, 641, 79, 655, 656, 78, 77, 638], 2031);
                step(f, Op::JumpIfFalse, &[8, 2042], 2032)
            }
            2032 => {
                step(f, Op::GetParent, &[28, 29], 2033);
                step(f, Op::GetTransform, &[29, 65, 79, 109], 2034);
                step(f, Op::BreakTransform, &[109, 388, 89, 389], 2035);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 64, 108], 2036);
                step(f, Op::BreakTransform, &[108, 382, 88, 383], 2037);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 64, 384], 2038);
                step(f, Op::KneeVector, &[88, 0, 384, 117, 118, 385], 2039);
                step(f, Op::AddV, &[388, 385, 390], 2040);
                step(f, Op::DrawLine, &[388, 390, 640, 400], 2041);
                step(f, Op::Jump, &[2042], 2042)
            }
            2042 => {
                step(f, Op::Jump, &[1991], 2043)
            }
            2043 => {
                step(f, Op::End, &[], 2044)
            }
            _ => return,
        } };
    }
}
