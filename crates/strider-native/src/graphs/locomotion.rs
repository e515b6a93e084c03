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
    fingerprint: 0xa0aa197e6cbb1985,
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
                step(f, Op::DivF, &[694, 129, 131], 473);
                step(f, Op::ScaleV, &[36, 131, 37], 474);
                step(f, Op::TransformVector, &[14, 37, 38], 475);
                step(f, Op::BreakVector, &[38, 132, 133, 134], 476);
                step(f, Op::MakeVector, &[132, 133, 692, 39], 477);
                step(f, Op::LengthV, &[39, 135], 478);
                step(f, Op::MulF, &[135, 112, 136], 479);
                step(f, Op::NegF, &[136, 137], 480);
                step(f, Op::ClampF, &[134, 137, 136, 138], 481);
                step(f, Op::MakeVector, &[132, 133, 138, 40], 482);
                step(f, Op::Select(ValueType::Vec3), &[2, 41, 40, 43], 483);
                step(f, Op::VectorLerp, &[41, 43, 33, 692, 44], 484);
                step(f, Op::Copy(ValueType::Vec3), &[44, 0], 485);
                step(f, Op::TransformVector, &[2, 1, 42], 486);
                step(f, Op::TransformVector, &[2, 0, 41], 487);
                step(f, Op::Select(ValueType::Vec3), &[2, 41, 40, 43], 488);
                step(f, Op::VectorLerp, &[42, 43, 34, 692, 45], 489);
                step(f, Op::Copy(ValueType::Vec3), &[45, 1], 490);
                step(f, Op::LengthV, &[43, 145], 491);
                step(f, Op::Copy(ValueType::Float), &[145, 0], 492);
                step(f, Op::BreakVector, &[36, 139, 140, 141], 493);
                step(f, Op::MulF, &[138, 129, 142], 494);
                step(f, Op::SubF, &[141, 142, 143], 495);
                step(f, Op::Select(ValueType::Float), &[10, 692, 143, 144], 496);
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
                step(f, Op::Copy(ValueType::Float), &[692, 14], 515);
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
                step(f, Op::ScaleV, &[0, 695, 48], 523);
                step(f, Op::AddV, &[46, 48, 49], 524);
                step(f, Op::DrawArrow, &[46, 49, 693, 393], 525);
                step(f, Op::Jump, &[526], 526)
            }
            526 => {
                step(f, Op::Copy(ValueType::Float), &[692, 146], 527);
                step(f, Op::Copy(ValueType::Float), &[694, 147], 528);
                step(f, Op::Copy(ValueType::Float), &[694, 148], 529);
                step(f, Op::Copy(ValueType::Bool), &[80, 11], 530);
                step(f, Op::Copy(ValueType::Bool), &[80, 12], 531);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[7, 8], 532);
                step(f, Op::Copy(ValueType::Int), &[65, 25], 533);
                step(f, Op::MakeVector, &[692, 692, 51, 54], 534);
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
                step(f, Op::MulF, &[150, 693, 151], 557);
                step(f, Op::Copy(ValueType::Float), &[151, 152], 558);
                step(f, Op::Copy(ValueType::Bool), &[80, 17], 559);
                step(f, Op::Copy(ValueType::Bool), &[80, 18], 560);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[7, 9], 561);
                step(f, Op::Copy(ValueType::Int), &[65, 28], 562);
                step(f, Op::MakeVector, &[692, 692, 51, 63], 563);
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
                step(f, Op::Select(ValueType::Float), &[5, 696, 694, 159], 585);
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 586);
                step(f, Op::AddF, &[146, 147, 150], 587);
                step(f, Op::MulF, &[150, 693, 154], 588);
                step(f, Op::Select(ValueType::Float), &[16, 154, 693, 155], 589);
                step(f, Op::Select(ValueType::Float), &[15, 155, 692, 161], 590);
                step(f, Op::MulF, &[159, 161, 163], 591);
                step(f, Op::DeltaTime, &[157], 592);
                step(f, Op::DivF, &[157, 115, 158], 593);
                step(f, Op::MulF, &[163, 158, 164], 594);
                step(f, Op::AddF, &[17, 164, 165], 595);
                step(f, Op::ClampF, &[165, 692, 694, 166], 596);
                step(f, Op::Select(ValueType::Float), &[14, 696, 694, 160], 597);
                step(f, Op::SubF, &[694, 155, 156], 598);
                step(f, Op::Select(ValueType::Float), &[15, 156, 694, 162], 599);
                step(f, Op::MulF, &[160, 162, 167], 600);
                step(f, Op::MulF, &[167, 158, 168], 601);
                step(f, Op::AddF, &[166, 168, 169], 602);
                step(f, Op::ClampF, &[169, 692, 694, 170], 603);
                step(f, Op::Copy(ValueType::Float), &[170, 171], 604);
                step(f, Op::Copy(ValueType::Float), &[692, 172], 605);
                step(f, Op::ClampF, &[171, 692, 694, 173], 606);
                step(f, Op::MulF, &[173, 173, 174], 607);
                step(f, Op::MulF, &[173, 697, 175], 608);
                step(f, Op::SubF, &[698, 175, 176], 609);
                step(f, Op::MulF, &[174, 176, 177], 610);
                step(f, Op::Copy(ValueType::Float), &[177, 172], 611);
                step(f, Op::Jump, &[612], 612)
            }
            612 => {
                step(f, Op::AddF, &[18, 172, 178], 613);
                step(f, Op::MulF, &[178, 693, 179], 614);
                step(f, Op::SubF, &[694, 179, 180], 615);
                step(f, Op::MulF, &[180, 180, 181], 616);
                step(f, Op::SubF, &[694, 181, 182], 617);
                step(f, Op::Copy(ValueType::Float), &[182, 19], 618);
                step(f, Op::Copy(ValueType::Float), &[172, 18], 619);
                step(f, Op::Copy(ValueType::Float), &[170, 17], 620);
                step(f, Op::GreaterF, &[18, 692, 21], 621);
                step(f, Op::TransformVector, &[2, 3, 68], 622);
                step(f, Op::Select(ValueType::Vec3), &[21, 68, 0, 69], 623);
                step(f, Op::Copy(ValueType::Vec3), &[69, 3], 624);
                step(f, Op::LerpV, &[0, 3, 18, 70], 625);
                step(f, Op::Select(ValueType::Vec3), &[21, 70, 0, 71], 626);
                step(f, Op::Copy(ValueType::Vec3), &[71, 2], 627);
                step(f, Op::Copy(ValueType::Bool), &[14, 5], 628);
                step(f, Op::Copy(ValueType::Bool), &[11, 6], 629);
                step(f, Op::Copy(ValueType::Bool), &[80, 7], 630);
                step(f, Op::SubF, &[694, 19, 183], 631);
                step(f, Op::MulF, &[1, 183, 184], 632);
                step(f, Op::AddF, &[2, 184, 185], 633);
                step(f, Op::SpringF, &[185, 113, 188, 31, 186, 187], 634);
                step(f, Op::SubF, &[185, 188, 189], 635);
                step(f, Op::Copy(ValueType::Float), &[189, 3], 636);
                step(f, Op::Copy(ValueType::Float), &[185, 2], 637);
                step(f, Op::Copy(ValueType::Bool), &[80, 23], 638);
                step(f, Op::Copy(ValueType::Bool), &[79, 24], 639);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 640);
                step(f, Op::Copy(ValueType::Int), &[65, 35], 641);
                641
            }
            641 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 35, 25, 36, 37, 647], 642)
            }
            642 => {
                step(f, Op::Not, &[25, 26], 643);
                step(f, Op::JumpIfFalse, &[26, 646], 644)
            }
            644 => {
                step(f, Op::Copy(ValueType::Bool), &[80, 24], 645);
                step(f, Op::Jump, &[646], 646)
            }
            646 => {
                step(f, Op::Jump, &[641], 647)
            }
            647 => {
                step(f, Op::Copy(ValueType::Bool), &[24, 23], 648);
                step(f, Op::Jump, &[649], 649)
            }
            649 => {
                step(f, Op::Copy(ValueType::Bool), &[80, 27], 650);
                step(f, Op::Copy(ValueType::Bool), &[79, 28], 651);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 652);
                step(f, Op::Copy(ValueType::Int), &[65, 38], 653);
                653
            }
            653 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 38, 15, 39, 40, 668], 654)
            }
            654 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 39, 23], 655);
                step(f, Op::BreakTransform, &[23, 72, 12, 73], 656);
                step(f, Op::BreakVector, &[72, 198, 199, 200], 657);
                step(f, Op::MakeVector, &[198, 199, 692, 76], 658);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 39, 24], 659);
                step(f, Op::BreakTransform, &[24, 74, 13, 75], 660);
                step(f, Op::BreakVector, &[74, 201, 202, 203], 661);
                step(f, Op::MakeVector, &[201, 202, 692, 77], 662);
                step(f, Op::DistanceV, &[76, 77, 204], 663);
                step(f, Op::GreaterF, &[204, 28, 29], 664);
                step(f, Op::JumpIfFalse, &[29, 667], 665)
            }
            665 => {
                step(f, Op::Copy(ValueType::Bool), &[80, 28], 666);
                step(f, Op::Jump, &[667], 667)
            }
            667 => {
                step(f, Op::Jump, &[653], 668)
            }
            668 => {
                step(f, Op::Copy(ValueType::Bool), &[28, 27], 669);
                step(f, Op::Jump, &[670], 670)
            }
            670 => {
                step(f, Op::And, &[23, 27, 30], 671);
                step(f, Op::LengthV, &[2, 190], 672);
                step(f, Op::GreaterF, &[190, 26, 22], 673);
                step(f, Op::GreaterF, &[0, 26, 31], 674);
                step(f, Op::Or, &[22, 31, 32], 675);
                step(f, Op::Not, &[32, 33], 676);
                step(f, Op::And, &[30, 33, 38], 677);
                step(f, Op::DeltaTime, &[229], 678);
                step(f, Op::MulF, &[229, 31, 230], 679);
                step(f, Op::AddF, &[10, 230, 231], 680);
                step(f, Op::GreaterF, &[10, 693, 39], 681);
                step(f, Op::AddF, &[30, 693, 227], 682);
                step(f, Op::Select(ValueType::Float), &[39, 227, 30, 228], 683);
                step(f, Op::MinF, &[231, 228, 232], 684);
                step(f, Op::NotEquals(Elem::Bool), &[33, 4, 34], 685);
                step(f, Op::Not, &[30, 35], 686);
                step(f, Op::And, &[34, 35, 36], 687);
                step(f, Op::SubF, &[11, 26, 213], 688);
                step(f, Op::SubF, &[11, 190, 214], 689);
                step(f, Op::DivF, &[213, 214, 215], 690);
                step(f, Op::ClampF, &[215, 692, 694, 216], 691);
                step(f, Op::MulF, &[6, 216, 218], 692);
                step(f, Op::RemapF, &[190, 26, 27, 692, 694, 79, 205], 693);
                step(f, Op::MaxF, &[205, 7, 206], 694);
                step(f, Op::Select(ValueType::Float), &[23, 694, 206, 207], 695);
                step(f, Op::Select(ValueType::Float), &[33, 29, 207, 208], 696);
                step(f, Op::Select(ValueType::Float), &[30, 205, 208, 209], 697);
                step(f, Op::SubF, &[694, 18, 210], 698);
                step(f, Op::MulF, &[209, 210, 211], 699);
                step(f, Op::LerpF, &[20, 41, 13, 193], 700);
                step(f, Op::RemapF, &[190, 23, 24, 21, 22, 79, 191], 701);
                step(f, Op::LerpF, &[191, 40, 13, 192], 702);
                step(f, Op::MaxF, &[190, 25, 194], 703);
                step(f, Op::DivF, &[192, 194, 195], 704);
                step(f, Op::AddF, &[193, 195, 196], 705);
                step(f, Op::DivF, &[211, 196, 212], 706);
                step(f, Op::SubF, &[694, 216, 217], 707);
                step(f, Op::MulF, &[212, 217, 219], 708);
                step(f, Op::AddF, &[218, 219, 220], 709);
                step(f, Op::MulF, &[220, 697, 221], 710);
                step(f, Op::AddF, &[6, 212, 222], 711);
                step(f, Op::Select(ValueType::Float), &[36, 221, 222, 223], 712);
                step(f, Op::DivF, &[697, 223, 224], 713);
                step(f, Op::GreaterF, &[223, 692, 37], 714);
                step(f, Op::CycleStep, &[10, 224, 692, 37, 225, 226], 715);
                step(f, Op::Select(ValueType::Float), &[38, 232, 225, 233], 716);
                step(f, Op::Copy(ValueType::Float), &[233, 10], 717);
                step(f, Op::Copy(ValueType::Float), &[212, 6], 718);
                step(f, Op::Copy(ValueType::Bool), &[22, 3], 719);
                step(f, Op::Copy(ValueType::Float), &[195, 4], 720);
                step(f, Op::Copy(ValueType::Float), &[196, 5], 721);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 722);
                step(f, Op::Copy(ValueType::Int), &[65, 32], 723);
                723
            }
            723 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 32, 14, 33, 34, 897], 724)
            }
            724 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 33, 247], 725);
                step(f, Op::ToFloat, &[33, 234], 726);
                step(f, Op::MulF, &[234, 693, 235], 727);
                step(f, Op::AddF, &[10, 235, 236], 728);
                step(f, Op::FractF, &[236, 237], 729);
                step(f, Op::SubF, &[247, 237, 249], 730);
                step(f, Op::GreaterF, &[249, 693, 40], 731);
                step(f, Op::ArrayAt(Elem::Float), &[2, 33, 248], 732);
                step(f, Op::Select(ValueType::Float), &[40, 692, 248, 276], 733);
                step(f, Op::ArraySetAt(Elem::Float), &[3, 33, 276], 734);
                step(f, Op::ArrayAt(Elem::Float), &[0, 33, 247], 735);
                step(f, Op::ToFloat, &[33, 234], 736);
                step(f, Op::MulF, &[234, 693, 235], 737);
                step(f, Op::AddF, &[10, 235, 236], 738);
                step(f, Op::FractF, &[236, 237], 739);
                step(f, Op::SubF, &[247, 237, 249], 740);
                step(f, Op::GreaterF, &[249, 693, 40], 741);
                step(f, Op::SubF, &[694, 247, 270], 742);
                step(f, Op::AddF, &[237, 270, 271], 743);
                step(f, Op::DivF, &[237, 271, 272], 744);
                step(f, Op::LengthV, &[2, 190], 745);
                step(f, Op::GreaterF, &[190, 26, 22], 746);
                step(f, Op::GreaterF, &[0, 26, 31], 747);
                step(f, Op::Or, &[22, 31, 32], 748);
                step(f, Op::Not, &[32, 33], 749);
                step(f, Op::NotEquals(Elem::Bool), &[33, 4, 34], 750);
                step(f, Op::Copy(ValueType::Bool), &[80, 23], 751);
                step(f, Op::Copy(ValueType::Bool), &[79, 24], 752);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 753);
                step(f, Op::Copy(ValueType::Int), &[65, 35], 754);
                754
            }
            754 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 35, 25, 36, 37, 760], 755)
            }
            755 => {
                step(f, Op::Not, &[25, 26], 756);
                step(f, Op::JumpIfFalse, &[26, 759], 757)
            }
            757 => {
                step(f, Op::Copy(ValueType::Bool), &[80, 24], 758);
                step(f, Op::Jump, &[759], 759)
            }
            759 => {
                step(f, Op::Jump, &[754], 760)
            }
            760 => {
                step(f, Op::Copy(ValueType::Bool), &[24, 23], 761);
                step(f, Op::Jump, &[762], 762)
            }
            762 => {
                step(f, Op::Copy(ValueType::Bool), &[80, 27], 763);
                step(f, Op::Copy(ValueType::Bool), &[79, 28], 764);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 765);
                step(f, Op::Copy(ValueType::Int), &[65, 38], 766);
                766
            }
            766 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 38, 15, 39, 40, 781], 767)
            }
            767 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 39, 23], 768);
                step(f, Op::BreakTransform, &[23, 72, 12, 73], 769);
                step(f, Op::BreakVector, &[72, 198, 199, 200], 770);
                step(f, Op::MakeVector, &[198, 199, 692, 76], 771);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 39, 24], 772);
                step(f, Op::BreakTransform, &[24, 74, 13, 75], 773);
                step(f, Op::BreakVector, &[74, 201, 202, 203], 774);
                step(f, Op::MakeVector, &[201, 202, 692, 77], 775);
                step(f, Op::DistanceV, &[76, 77, 204], 776);
                step(f, Op::GreaterF, &[204, 28, 29], 777);
                step(f, Op::JumpIfFalse, &[29, 780], 778)
            }
            778 => {
                step(f, Op::Copy(ValueType::Bool), &[80, 28], 779);
                step(f, Op::Jump, &[780], 780)
            }
            780 => {
                step(f, Op::Jump, &[766], 781)
            }
            781 => {
                step(f, Op::Copy(ValueType::Bool), &[28, 27], 782);
                step(f, Op::Jump, &[783], 783)
            }
            783 => {
                step(f, Op::And, &[23, 27, 30], 784);
                step(f, Op::Not, &[30, 35], 785);
                step(f, Op::And, &[34, 35, 36], 786);
                step(f, Op::SubF, &[11, 26, 213], 787);
                step(f, Op::SubF, &[11, 190, 214], 788);
                step(f, Op::DivF, &[213, 214, 215], 789);
                step(f, Op::ClampF, &[215, 692, 694, 216], 790);
                step(f, Op::MulF, &[9, 216, 239], 791);
                step(f, Op::RemapF, &[190, 26, 27, 692, 694, 79, 205], 792);
                step(f, Op::MaxF, &[205, 7, 206], 793);
                step(f, Op::Select(ValueType::Float), &[23, 694, 206, 207], 794);
                step(f, Op::Select(ValueType::Float), &[33, 29, 207, 208], 795);
                step(f, Op::Select(ValueType::Float), &[30, 205, 208, 209], 796);
                step(f, Op::SubF, &[694, 18, 210], 797);
                step(f, Op::MulF, &[209, 210, 211], 798);
                step(f, Op::LerpF, &[20, 41, 13, 193], 799);
                step(f, Op::DivF, &[211, 193, 238], 800);
                step(f, Op::SubF, &[694, 216, 217], 801);
                step(f, Op::MulF, &[238, 217, 240], 802);
                step(f, Op::AddF, &[239, 240, 241], 803);
                step(f, Op::MulF, &[241, 697, 242], 804);
                step(f, Op::AddF, &[9, 238, 243], 805);
                step(f, Op::Select(ValueType::Float), &[36, 242, 243, 244], 806);
                step(f, Op::DeltaTime, &[229], 807);
                step(f, Op::MulF, &[229, 693, 245], 808);
                step(f, Op::MulF, &[244, 245, 246], 809);
                step(f, Op::MulF, &[272, 246, 273], 810);
                step(f, Op::ArrayAt(Elem::Float), &[2, 33, 248], 811);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 33, 41], 812);
                step(f, Op::RemapF, &[190, 23, 24, 21, 22, 79, 191], 813);
                step(f, Op::LerpF, &[191, 40, 13, 192], 814);
                step(f, Op::MaxF, &[190, 25, 194], 815);
                step(f, Op::DivF, &[192, 194, 195], 816);
                step(f, Op::AddF, &[193, 195, 196], 817);
                step(f, Op::DivF, &[193, 196, 197], 818);
                step(f, Op::SubF, &[197, 8, 250], 819);
                step(f, Op::MaxF, &[250, 692, 251], 820);
                step(f, Op::DivF, &[251, 197, 252], 821);
                step(f, Op::SubF, &[694, 13, 254], 822);
                step(f, Op::MulF, &[252, 254, 261], 823);
                step(f, Op::MulF, &[261, 210, 262], 824);
                step(f, Op::MulF, &[262, 110, 263], 825);
                step(f, Op::DivF, &[45, 229, 259], 826);
                step(f, Op::SubF, &[693, 259, 260], 827);
                step(f, Op::MulF, &[263, 260, 264], 828);
                step(f, Op::SubF, &[694, 264, 265], 829);
                step(f, Op::MulF, &[246, 265, 266], 830);
                step(f, Op::Select(ValueType::Float), &[41, 246, 266, 267], 831);
                step(f, Op::MulF, &[252, 248, 253], 832);
                step(f, Op::MulF, &[253, 254, 255], 833);
                step(f, Op::MulF, &[255, 210, 256], 834);
                step(f, Op::MulF, &[256, 110, 257], 835);
                step(f, Op::Select(ValueType::Float), &[41, 692, 257, 258], 836);
                step(f, Op::SubF, &[267, 258, 268], 837);
                step(f, Op::AddF, &[248, 268, 269], 838);
                step(f, Op::Select(ValueType::Float), &[40, 273, 269, 274], 839);
                step(f, Op::MinF, &[274, 697, 275], 840);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 33, 275], 841);
                step(f, Op::ArrayAt(Elem::Float), &[0, 33, 247], 842);
                step(f, Op::ToFloat, &[33, 234], 843);
                step(f, Op::MulF, &[234, 693, 235], 844);
                step(f, Op::AddF, &[10, 235, 236], 845);
                step(f, Op::FractF, &[236, 237], 846);
                step(f, Op::SubF, &[247, 237, 249], 847);
                step(f, Op::GreaterF, &[249, 693, 40], 848);
                step(f, Op::JumpIfFalse, &[40, 895], 849)
            }
            849 => {
                step(f, Op::Copy(ValueType::Bool), &[80, 23], 850);
                step(f, Op::Copy(ValueType::Bool), &[79, 24], 851);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 852);
                step(f, Op::Copy(ValueType::Int), &[65, 35], 853);
                853
            }
            853 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 35, 25, 36, 37, 859], 854)
            }
            854 => {
                step(f, Op::Not, &[25, 26], 855);
                step(f, Op::JumpIfFalse, &[26, 858], 856)
            }
            856 => {
                step(f, Op::Copy(ValueType::Bool), &[80, 24], 857);
                step(f, Op::Jump, &[858], 858)
            }
            858 => {
                step(f, Op::Jump, &[853], 859)
            }
            859 => {
                step(f, Op::Copy(ValueType::Bool), &[24, 23], 860);
                step(f, Op::Jump, &[861], 861)
            }
            861 => {
                step(f, Op::Copy(ValueType::Bool), &[80, 27], 862);
                step(f, Op::Copy(ValueType::Bool), &[79, 28], 863);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 864);
                step(f, Op::Copy(ValueType::Int), &[65, 38], 865);
                865
            }
            865 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 38, 15, 39, 40, 880], 866)
            }
            866 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 39, 23], 867);
                step(f, Op::BreakTransform, &[23, 72, 12, 73], 868);
                step(f, Op::BreakVector, &[72, 198, 199, 200], 869);
                step(f, Op::MakeVector, &[198, 199, 692, 76], 870);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 39, 24], 871);
                step(f, Op::BreakTransform, &[24, 74, 13, 75], 872);
                step(f, Op::BreakVector, &[74, 201, 202, 203], 873);
                step(f, Op::MakeVector, &[201, 202, 692, 77], 874);
                step(f, Op::DistanceV, &[76, 77, 204], 875);
                step(f, Op::GreaterF, &[204, 28, 29], 876);
                step(f, Op::JumpIfFalse, &[29, 879], 877)
            }
            877 => {
                step(f, Op::Copy(ValueType::Bool), &[80, 28], 878);
                step(f, Op::Jump, &[879], 879)
            }
            879 => {
                step(f, Op::Jump, &[865], 880)
            }
            880 => {
                step(f, Op::Copy(ValueType::Bool), &[28, 27], 881);
                step(f, Op::Jump, &[882], 882)
            }
            882 => {
                step(f, Op::And, &[23, 27, 30], 883);
                step(f, Op::LengthV, &[2, 190], 884);
                step(f, Op::RemapF, &[190, 26, 27, 692, 694, 79, 205], 885);
                step(f, Op::GreaterF, &[190, 26, 22], 886);
                step(f, Op::GreaterF, &[0, 26, 31], 887);
                step(f, Op::Or, &[22, 31, 32], 888);
                step(f, Op::Not, &[32, 33], 889);
                step(f, Op::MaxF, &[205, 7, 206], 890);
                step(f, Op::Select(ValueType::Float), &[23, 694, 206, 207], 891);
                step(f, Op::Select(ValueType::Float), &[33, 29, 207, 208], 892);
                step(f, Op::Select(ValueType::Float), &[30, 205, 208, 209], 893);
                step(f, Op::Copy(ValueType::Float), &[209, 7], 894);
                step(f, Op::Jump, &[895], 895)
            }
            895 => {
                step(f, Op::ArraySetAt(Elem::Float), &[0, 33, 237], 896);
                step(f, Op::Jump, &[723], 897)
            }
            897 => {
                step(f, Op::LerpF, &[20, 41, 13, 193], 898);
                step(f, Op::LengthV, &[2, 190], 899);
                step(f, Op::RemapF, &[190, 23, 24, 21, 22, 79, 191], 900);
                step(f, Op::LerpF, &[191, 40, 13, 192], 901);
                step(f, Op::MaxF, &[190, 25, 194], 902);
                step(f, Op::DivF, &[192, 194, 195], 903);
                step(f, Op::AddF, &[193, 195, 196], 904);
                step(f, Op::DivF, &[193, 196, 197], 905);
                step(f, Op::Copy(ValueType::Float), &[197, 8], 906);
                step(f, Op::GreaterF, &[190, 26, 22], 907);
                step(f, Op::GreaterF, &[0, 26, 31], 908);
                step(f, Op::Or, &[22, 31, 32], 909);
                step(f, Op::Not, &[32, 33], 910);
                step(f, Op::Copy(ValueType::Bool), &[33, 4], 911);
                step(f, Op::Copy(ValueType::Float), &[190, 11], 912);
                step(f, Op::Copy(ValueType::Bool), &[80, 23], 913);
                step(f, Op::Copy(ValueType::Bool), &[79, 24], 914);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 915);
                step(f, Op::Copy(ValueType::Int), &[65, 35], 916);
                916
            }
            916 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 35, 25, 36, 37, 922], 917)
            }
            917 => {
                step(f, Op::Not, &[25, 26], 918);
                step(f, Op::JumpIfFalse, &[26, 921], 919)
            }
            919 => {
                step(f, Op::Copy(ValueType::Bool), &[80, 24], 920);
                step(f, Op::Jump, &[921], 921)
            }
            921 => {
                step(f, Op::Jump, &[916], 922)
            }
            922 => {
                step(f, Op::Copy(ValueType::Bool), &[24, 23], 923);
                step(f, Op::Jump, &[924], 924)
            }
            924 => {
                step(f, Op::Copy(ValueType::Bool), &[80, 27], 925);
                step(f, Op::Copy(ValueType::Bool), &[79, 28], 926);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 927);
                step(f, Op::Copy(ValueType::Int), &[65, 38], 928);
                928
            }
            928 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 38, 15, 39, 40, 943], 929)
            }
            929 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 39, 23], 930);
                step(f, Op::BreakTransform, &[23, 72, 12, 73], 931);
                step(f, Op::BreakVector, &[72, 198, 199, 200], 932);
                step(f, Op::MakeVector, &[198, 199, 692, 76], 933);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 39, 24], 934);
                step(f, Op::BreakTransform, &[24, 74, 13, 75], 935);
                step(f, Op::BreakVector, &[74, 201, 202, 203], 936);
                step(f, Op::MakeVector, &[201, 202, 692, 77], 937);
                step(f, Op::DistanceV, &[76, 77, 204], 938);
                step(f, Op::GreaterF, &[204, 28, 29], 939);
                step(f, Op::JumpIfFalse, &[29, 942], 940)
            }
            940 => {
                step(f, Op::Copy(ValueType::Bool), &[80, 28], 941);
                step(f, Op::Jump, &[942], 942)
            }
            942 => {
                step(f, Op::Jump, &[928], 943)
            }
            943 => {
                step(f, Op::Copy(ValueType::Bool), &[28, 27], 944);
                step(f, Op::Jump, &[945], 945)
            }
            945 => {
                step(f, Op::And, &[23, 27, 30], 946);
                step(f, Op::RemapF, &[190, 26, 27, 692, 694, 79, 205], 947);
                step(f, Op::MaxF, &[205, 7, 206], 948);
                step(f, Op::Select(ValueType::Float), &[23, 694, 206, 207], 949);
                step(f, Op::Select(ValueType::Float), &[33, 29, 207, 208], 950);
                step(f, Op::Select(ValueType::Float), &[30, 205, 208, 209], 951);
                step(f, Op::SubF, &[694, 18, 210], 952);
                step(f, Op::MulF, &[209, 210, 211], 953);
                step(f, Op::DivF, &[211, 193, 238], 954);
                step(f, Op::Copy(ValueType::Float), &[238, 9], 955);
                step(f, Op::Select(ValueType::Vec3), &[3, 2, 391, 78], 956);
                step(f, Op::MovementAngleOffset, &[78, 12, 10, 35, 36, 699, 37, 700, 277], 957);
                step(f, Op::Copy(ValueType::Float), &[277, 12], 958);
                step(f, Op::QuatFromAxisAngle, &[394, 12, 14], 959);
                step(f, Op::Copy(ValueType::Quat), &[14, 0], 960);
                step(f, Op::SinF, &[12, 278], 961);
                step(f, Op::AbsF, &[278, 279], 962);
                step(f, Op::RemapF, &[279, 38, 39, 692, 694, 79, 280], 963);
                step(f, Op::Copy(ValueType::Float), &[280, 13], 964);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 965);
                step(f, Op::Copy(ValueType::Int), &[65, 2], 966);
                966
            }
            966 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 2, 0, 3, 4, 1796], 967)
            }
            967 => {
                step(f, Op::Copy(ValueType::Bone), &[0, 16], 968);
                step(f, Op::Copy(ValueType::Int), &[3, 41], 969);
                step(f, Op::GetTransform, &[35, 65, 79, 25], 970);
                step(f, Op::BreakTransform, &[25, 81, 15, 82], 971);
                step(f, Op::BreakVector, &[81, 292, 293, 294], 972);
                step(f, Op::SubF, &[694, 13, 290], 973);
                step(f, Op::MulF, &[12, 290, 291], 974);
                step(f, Op::QuatFromAxisAngle, &[394, 291, 17], 975);
                step(f, Op::GetTransform, &[16, 65, 79, 26], 976);
                step(f, Op::BreakTransform, &[26, 83, 16, 84], 977);
                step(f, Op::SubV, &[83, 81, 85], 978);
                step(f, Op::BreakVector, &[85, 287, 288, 289], 979);
                step(f, Op::MakeVector, &[287, 288, 692, 86], 980);
                step(f, Op::RotateVector, &[17, 86, 87], 981);
                step(f, Op::BreakVector, &[87, 295, 296, 297], 982);
                step(f, Op::MulF, &[42, 13, 298], 983);
                step(f, Op::Equals(Elem::Int), &[41, 65, 42], 984);
                step(f, Op::Select(ValueType::Float), &[42, 694, 696, 307], 985);
                step(f, Op::MulF, &[298, 307, 299], 986);
                step(f, Op::AddF, &[295, 299, 300], 987);
                step(f, Op::AddF, &[292, 300, 301], 988);
                step(f, Op::AddF, &[293, 296, 302], 989);
                step(f, Op::BreakVector, &[83, 303, 304, 305], 990);
                step(f, Op::SubF, &[305, 46, 306], 991);
                step(f, Op::MakeVector, &[301, 302, 306, 88], 992);
                step(f, Op::ArrayAt(Elem::Float), &[2, 41, 281], 993);
                step(f, Op::SubF, &[694, 281, 282], 994);
                step(f, Op::MaxF, &[282, 692, 283], 995);
                step(f, Op::MulF, &[8, 5, 284], 996);
                step(f, Op::MulF, &[283, 284, 285], 997);
                step(f, Op::ScaleV, &[2, 285, 79], 998);
                step(f, Op::AddV, &[88, 79, 89], 999);
                step(f, Op::MulF, &[4, 693, 286], 1000);
                step(f, Op::ScaleV, &[2, 286, 80], 1001);
                step(f, Op::AddV, &[89, 80, 90], 1002);
                step(f, Op::RotateVector, &[0, 395, 91], 1003);
                step(f, Op::Copy(ValueType::Vec3), &[90, 112], 1004);
                step(f, Op::Copy(ValueType::Vec3), &[91, 113], 1005);
                step(f, Op::Copy(ValueType::Float), &[307, 326], 1006);
                step(f, Op::Copy(ValueType::Vec3), &[391, 114], 1007);
                step(f, Op::Copy(ValueType::Vec3), &[391, 115], 1008);
                step(f, Op::Copy(ValueType::Bool), &[80, 44], 1009);
                step(f, Op::Copy(ValueType::Float), &[701, 327], 1010);
                step(f, Op::Copy(ValueType::Vec3), &[391, 116], 1011);
                step(f, Op::Copy(ValueType::Vec3), &[394, 117], 1012);
                step(f, Op::Copy(ValueType::Bool), &[80, 45], 1013);
                step(f, Op::MulI, &[0, 0, 47], 1014);
                step(f, Op::Copy(ValueType::Int), &[47, 46], 1015);
                step(f, Op::Copy(ValueType::Int), &[65, 42], 1016);
                step(f, Op::SubI, &[0, 66, 50], 1017);
                step(f, Op::DivI, &[50, 67, 51], 1018);
                step(f, Op::MakeVector, &[692, 692, 51, 122], 1019);
                step(f, Op::ScaleV, &[113, 53, 127], 1020);
                1020
            }
            1020 => {
                step(f, Op::ForNext, &[42, 46, 44, 1060], 1021)
            }
            1021 => {
                step(f, Op::ModI, &[44, 0, 48], 1022);
                step(f, Op::ToFloat, &[48, 328], 1023);
                step(f, Op::MulF, &[328, 52, 330], 1024);
                step(f, Op::MulF, &[330, 326, 331], 1025);
                step(f, Op::MakeVector, &[331, 692, 692, 118], 1026);
                step(f, Op::DivI, &[44, 0, 49], 1027);
                step(f, Op::SubI, &[49, 51, 52], 1028);
                step(f, Op::ToFloat, &[52, 329], 1029);
                step(f, Op::MulF, &[329, 52, 332], 1030);
                step(f, Op::ScaleV, &[113, 332, 119], 1031);
                step(f, Op::AddV, &[118, 119, 120], 1032);
                step(f, Op::AddV, &[112, 120, 121], 1033);
                step(f, Op::AddV, &[121, 122, 123], 1034);
                step(f, Op::SubV, &[121, 122, 124], 1035);
                step(f, Op::SphereTrace, &[123, 124, 50, 46, 125, 126, 333], 1036);
                step(f, Op::BreakVector, &[125, 335, 336, 337], 1037);
                step(f, Op::AddV, &[123, 127, 128], 1038);
                step(f, Op::AddV, &[124, 127, 129], 1039);
                step(f, Op::SphereTrace, &[128, 129, 50, 47, 130, 131, 334], 1040);
                step(f, Op::BreakVector, &[130, 338, 339, 340], 1041);
                step(f, Op::SubF, &[337, 340, 341], 1042);
                step(f, Op::AbsF, &[341, 342], 1043);
                step(f, Op::Select(ValueType::Float), &[46, 692, 694, 343], 1044);
                step(f, Op::AddF, &[342, 343, 348], 1045);
                step(f, Op::LengthV, &[120, 344], 1046);
                step(f, Op::RemapF, &[344, 692, 702, 692, 694, 79, 345], 1047);
                step(f, Op::MinF, &[337, 340, 346], 1048);
                step(f, Op::RemapF, &[346, 703, 702, 694, 693, 79, 347], 1049);
                step(f, Op::AddF, &[345, 347, 349], 1050);
                step(f, Op::AddF, &[348, 349, 350], 1051);
                step(f, Op::LessF, &[350, 327, 48], 1052);
                step(f, Op::And, &[46, 48, 49], 1053);
                step(f, Op::JumpIfFalse, &[49, 1059], 1054)
            }
            1054 => {
                step(f, Op::Copy(ValueType::Float), &[350, 327], 1055);
                step(f, Op::Copy(ValueType::Vec3), &[125, 116], 1056);
                step(f, Op::Copy(ValueType::Vec3), &[126, 117], 1057);
                step(f, Op::Copy(ValueType::Bool), &[79, 45], 1058);
                step(f, Op::Jump, &[1059], 1059)
            }
            1059 => {
                step(f, Op::Jump, &[1020], 1060)
            }
            1060 => {
                step(f, Op::JumpIfFalse, &[8, 1063], 1061)
            }
            1061 => {
                step(f, Op::DrawSphere, &[116, 50, 395], 1062);
                step(f, Op::Jump, &[1063], 1063)
            }
            1063 => {
                step(f, Op::Copy(ValueType::Vec3), &[116, 114], 1064);
                step(f, Op::Copy(ValueType::Vec3), &[117, 115], 1065);
                step(f, Op::Copy(ValueType::Bool), &[45, 44], 1066);
                step(f, Op::Jump, &[1067], 1067)
            }
            1067 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 41, 27], 1068);
                step(f, Op::BreakTransform, &[27, 93, 21, 94], 1069);
                step(f, Op::ArrayAt(Elem::Float), &[2, 41, 281], 1070);
                step(f, Op::SubF, &[694, 281, 282], 1071);
                step(f, Op::MaxF, &[282, 692, 283], 1072);
                step(f, Op::MulF, &[8, 5, 284], 1073);
                step(f, Op::MulF, &[283, 284, 285], 1074);
                step(f, Op::ScaleV, &[2, 285, 79], 1075);
                step(f, Op::SubV, &[114, 79, 92], 1076);
                step(f, Op::Select(ValueType::Vec3), &[44, 92, 93, 95], 1077);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 41, 28], 1078);
                step(f, Op::BreakTransform, &[28, 96, 23, 97], 1079);
                step(f, Op::Copy(ValueType::Vec3), &[93, 98], 1080);
                step(f, Op::Copy(ValueType::Vec3), &[95, 99], 1081);
                step(f, Op::Copy(ValueType::Vec3), &[96, 100], 1082);
                step(f, Op::Copy(ValueType::Float), &[43, 313], 1083);
                step(f, Op::Copy(ValueType::Float), &[45, 314], 1084);
                step(f, Op::Copy(ValueType::Vec3), &[391, 101], 1085);
                step(f, Op::SubV, &[99, 100, 102], 1086);
                step(f, Op::DeltaTime, &[315], 1087);
                step(f, Op::DivF, &[314, 315, 316], 1088);
                step(f, Op::ScaleV, &[102, 316, 103], 1089);
                step(f, Op::AddV, &[99, 103, 104], 1090);
                step(f, Op::AddV, &[100, 103, 105], 1091);
                step(f, Op::SubV, &[98, 105, 106], 1092);
                step(f, Op::FloatLerp, &[692, 694, 313, 317], 1093);
                step(f, Op::SubF, &[694, 317, 318], 1094);
                step(f, Op::ScaleV, &[106, 318, 107], 1095);
                step(f, Op::AddV, &[104, 107, 109], 1096);
                step(f, Op::MulF, &[313, 315, 319], 1097);
                step(f, Op::GreaterF, &[319, 692, 43], 1098);
                step(f, Op::DivF, &[317, 319, 320], 1099);
                step(f, Op::Select(ValueType::Float), &[43, 320, 694, 321], 1100);
                step(f, Op::ScaleV, &[102, 321, 108], 1101);
                step(f, Op::SubV, &[109, 108, 110], 1102);
                step(f, Op::Copy(ValueType::Vec3), &[110, 101], 1103);
                step(f, Op::Jump, &[1104], 1104)
            }
            1104 => {
                step(f, Op::BreakVector, &[101, 322, 323, 324], 1105);
                step(f, Op::ClampF, &[324, 54, 55, 325], 1106);
                step(f, Op::MakeVector, &[322, 323, 325, 111], 1107);
                step(f, Op::RotationFromNormal, &[115, 311, 312, 19], 1108);
                step(f, Op::PerFootRotationFactor, &[12, 88, 89, 308], 1109);
                step(f, Op::MulF, &[12, 308, 309], 1110);
                step(f, Op::SubF, &[694, 13, 290], 1111);
                step(f, Op::MulF, &[309, 290, 310], 1112);
                step(f, Op::QuatFromAxisAngle, &[394, 310, 18], 1113);
                step(f, Op::MulQ, &[19, 18, 20], 1114);
                step(f, Op::Select(ValueType::Quat), &[44, 20, 21, 22], 1115);
                step(f, Op::MakeTransform, &[111, 22, 392, 30], 1116);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 41, 30], 1117);
                step(f, Op::ArrayAt(Elem::Float), &[2, 41, 281], 1118);
                step(f, Op::SubF, &[694, 281, 282], 1119);
                step(f, Op::MaxF, &[282, 692, 283], 1120);
                step(f, Op::MulF, &[8, 5, 284], 1121);
                step(f, Op::MulF, &[283, 284, 285], 1122);
                step(f, Op::ScaleV, &[2, 285, 79], 1123);
                step(f, Op::SubV, &[114, 79, 92], 1124);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 41, 27], 1125);
                step(f, Op::BreakTransform, &[27, 93, 21, 94], 1126);
                step(f, Op::Select(ValueType::Vec3), &[44, 92, 93, 95], 1127);
                step(f, Op::MakeTransform, &[95, 91, 392, 29], 1128);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 41, 29], 1129);
                step(f, Op::JumpIfFalse, &[44, 1132], 1130)
            }
            1130 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 7], 1131);
                step(f, Op::Jump, &[1132], 1132)
            }
            1132 => {
                step(f, Op::Copy(ValueType::Int), &[3, 53], 1133);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 53, 33], 1134);
                step(f, Op::GreaterF, &[18, 692, 53], 1135);
                step(f, Op::InterpolateTransform, &[2, 110, 19, 31], 1136);
                step(f, Op::Select(ValueType::Transform), &[53, 31, 2, 32], 1137);
                step(f, Op::MakeAbsolute, &[33, 32, 34], 1138);
                step(f, Op::BreakTransform, &[34, 132, 24, 133], 1139);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 53, 35], 1140);
                step(f, Op::BreakTransform, &[35, 134, 25, 135], 1141);
                step(f, Op::AddF, &[58, 59, 352], 1142);
                step(f, Op::ClampSpatially, &[132, 134, 692, 352, 136], 1143);
                step(f, Op::SubF, &[694, 13, 367], 1144);
                step(f, Op::MulF, &[12, 367, 353], 1145);
                step(f, Op::LimitRotationAroundZ, &[24, 353, 87, 26], 1146);
                step(f, Op::MakeTransform, &[136, 26, 392, 36], 1147);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 53, 36], 1148);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 53, 50], 1149);
                step(f, Op::JumpIfFalse, &[50, 1203], 1150)
            }
            1150 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 53, 39], 1151);
                step(f, Op::BreakTransform, &[39, 142, 28, 143], 1152);
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 351], 1153);
                step(f, Op::SubF, &[694, 351, 364], 1154);
                step(f, Op::MulF, &[8, 5, 365], 1155);
                step(f, Op::MulF, &[364, 365, 366], 1156);
                step(f, Op::ScaleV, &[2, 366, 144], 1157);
                step(f, Op::AddV, &[142, 144, 145], 1158);
                step(f, Op::MakeTransform, &[145, 28, 392, 46], 1159);
                step(f, Op::Copy(ValueType::Transform), &[46, 47], 1160);
                step(f, Op::Copy(ValueType::Transform), &[110, 48], 1161);
                step(f, Op::BreakTransform, &[47, 173, 33, 174], 1162);
                step(f, Op::MakeVector, &[692, 692, 51, 175], 1163);
                step(f, Op::AddV, &[173, 175, 176], 1164);
                step(f, Op::SubV, &[173, 175, 177], 1165);
                step(f, Op::LineTrace, &[176, 177, 57, 178, 179, 394], 1166);
                step(f, Op::RotateVector, &[33, 394, 180], 1167);
                step(f, Op::FindQuatBetween, &[180, 179, 34], 1168);
                step(f, Op::MulQ, &[34, 33, 35], 1169);
                step(f, Op::MulF, &[49, 48, 395], 1170);
                step(f, Op::AddF, &[395, 57, 396], 1171);
                step(f, Op::NegF, &[396, 397], 1172);
                step(f, Op::MakeVector, &[692, 397, 692, 181], 1173);
                step(f, Op::RotateVector, &[35, 181, 183], 1174);
                step(f, Op::AddV, &[178, 183, 185], 1175);
                step(f, Op::AddV, &[185, 175, 187], 1176);
                step(f, Op::SubV, &[185, 175, 188], 1177);
                step(f, Op::LineTrace, &[187, 188, 58, 191, 192, 399], 1178);
                step(f, Op::BreakVector, &[191, 401, 402, 403], 1179);
                step(f, Op::BreakVector, &[185, 407, 408, 409], 1180);
                step(f, Op::SubF, &[403, 409, 413], 1181);
                step(f, Op::Select(ValueType::Float), &[58, 413, 692, 415], 1182);
                step(f, Op::AddF, &[53, 57, 398], 1183);
                step(f, Op::MakeVector, &[692, 398, 692, 182], 1184);
                step(f, Op::RotateVector, &[35, 182, 184], 1185);
                step(f, Op::AddV, &[178, 184, 186], 1186);
                step(f, Op::AddV, &[186, 175, 189], 1187);
                step(f, Op::SubV, &[186, 175, 190], 1188);
                step(f, Op::LineTrace, &[189, 190, 59, 193, 194, 400], 1189);
                step(f, Op::BreakVector, &[193, 404, 405, 406], 1190);
                step(f, Op::BreakVector, &[186, 410, 411, 412], 1191);
                step(f, Op::SubF, &[406, 412, 414], 1192);
                step(f, Op::Select(ValueType::Float), &[59, 414, 692, 416], 1193);
                step(f, Op::MaxF, &[415, 416, 417], 1194);
                step(f, Op::ClampF, &[417, 692, 56, 418], 1195);
                step(f, Op::MakeVector, &[692, 692, 418, 195], 1196);
                step(f, Op::AddV, &[178, 195, 196], 1197);
                step(f, Op::MakeTransform, &[196, 35, 392, 49], 1198);
                step(f, Op::Select(ValueType::Transform), &[57, 49, 47, 50], 1199);
                step(f, Op::Copy(ValueType::Transform), &[50, 48], 1200);
                step(f, Op::Jump, &[1201], 1201)
            }
            1201 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 53, 48], 1202);
                step(f, Op::Jump, &[1307], 1203)
            }
            1203 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 53, 51], 1204);
                step(f, Op::GreaterF, &[18, 692, 53], 1205);
                step(f, Op::InterpolateTransform, &[2, 110, 19, 31], 1206);
                step(f, Op::Select(ValueType::Transform), &[53, 31, 2, 32], 1207);
                step(f, Op::MakeAbsolute, &[51, 32, 52], 1208);
                step(f, Op::BreakTransform, &[52, 197, 36, 198], 1209);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 53, 39], 1210);
                step(f, Op::BreakTransform, &[39, 142, 28, 143], 1211);
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 351], 1212);
                step(f, Op::SubF, &[694, 351, 364], 1213);
                step(f, Op::MulF, &[8, 5, 365], 1214);
                step(f, Op::MulF, &[364, 365, 366], 1215);
                step(f, Op::ScaleV, &[2, 366, 144], 1216);
                step(f, Op::AddV, &[142, 144, 145], 1217);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 53, 53], 1218);
                step(f, Op::MakeAbsolute, &[53, 32, 54], 1219);
                step(f, Op::BreakTransform, &[54, 199, 37, 200], 1220);
                step(f, Op::ArrayAt(Elem::Float), &[3, 53, 419], 1221);
                step(f, Op::SubF, &[351, 419, 420], 1222);
                step(f, Op::DeltaTime, &[435], 1223);
                step(f, Op::DivF, &[45, 435, 421], 1224);
                step(f, Op::MulF, &[420, 421, 422], 1225);
                step(f, Op::AddF, &[419, 422, 423], 1226);
                step(f, Op::ClampF, &[423, 692, 694, 425], 1227);
                step(f, Op::AddF, &[351, 422, 424], 1228);
                step(f, Op::ClampF, &[424, 692, 694, 426], 1229);
                step(f, Op::AddF, &[425, 426, 427], 1230);
                step(f, Op::MulF, &[427, 693, 428], 1231);
                step(f, Op::SubF, &[694, 428, 429], 1232);
                step(f, Op::GreaterF, &[420, 692, 60], 1233);
                step(f, Op::SubF, &[426, 425, 430], 1234);
                step(f, Op::DivF, &[430, 420, 431], 1235);
                step(f, Op::Select(ValueType::Float), &[60, 431, 694, 432], 1236);
                step(f, Op::MulF, &[429, 432, 433], 1237);
                step(f, Op::MulF, &[73, 433, 434], 1238);
                step(f, Op::Copy(ValueType::Vec3), &[197, 201], 1239);
                step(f, Op::Copy(ValueType::Vec3), &[145, 202], 1240);
                step(f, Op::Copy(ValueType::Vec3), &[199, 203], 1241);
                step(f, Op::Copy(ValueType::Float), &[434, 436], 1242);
                step(f, Op::Copy(ValueType::Float), &[45, 437], 1243);
                step(f, Op::Copy(ValueType::Vec3), &[391, 204], 1244);
                step(f, Op::SubV, &[202, 203, 205], 1245);
                step(f, Op::DeltaTime, &[438], 1246);
                step(f, Op::DivF, &[437, 438, 439], 1247);
                step(f, Op::ScaleV, &[205, 439, 206], 1248);
                step(f, Op::AddV, &[202, 206, 207], 1249);
                step(f, Op::AddV, &[203, 206, 208], 1250);
                step(f, Op::SubV, &[201, 208, 209], 1251);
                step(f, Op::FloatLerp, &[692, 694, 436, 440], 1252);
                step(f, Op::SubF, &[694, 440, 441], 1253);
                step(f, Op::ScaleV, &[209, 441, 210], 1254);
                step(f, Op::AddV, &[207, 210, 212], 1255);
                step(f, Op::MulF, &[436, 438, 442], 1256);
                step(f, Op::GreaterF, &[442, 692, 61], 1257);
                step(f, Op::DivF, &[440, 442, 443], 1258);
                step(f, Op::Select(ValueType::Float), &[61, 443, 694, 444], 1259);
                step(f, Op::ScaleV, &[205, 444, 211], 1260);
                step(f, Op::SubV, &[212, 211, 213], 1261);
                step(f, Op::Copy(ValueType::Vec3), &[213, 204], 1262);
                step(f, Op::Jump, &[1263], 1263)
            }
            1263 => {
                step(f, Op::MakeTransform, &[204, 28, 392, 56], 1264);
                step(f, Op::Copy(ValueType::Transform), &[56, 57], 1265);
                step(f, Op::Copy(ValueType::Transform), &[110, 58], 1266);
                step(f, Op::BreakTransform, &[57, 214, 38, 215], 1267);
                step(f, Op::MakeVector, &[692, 692, 51, 216], 1268);
                step(f, Op::AddV, &[214, 216, 217], 1269);
                step(f, Op::SubV, &[214, 216, 218], 1270);
                step(f, Op::LineTrace, &[217, 218, 62, 219, 220, 445], 1271);
                step(f, Op::RotateVector, &[38, 394, 221], 1272);
                step(f, Op::FindQuatBetween, &[221, 220, 39], 1273);
                step(f, Op::MulQ, &[39, 38, 40], 1274);
                step(f, Op::MulF, &[49, 48, 446], 1275);
                step(f, Op::AddF, &[446, 57, 447], 1276);
                step(f, Op::NegF, &[447, 448], 1277);
                step(f, Op::MakeVector, &[692, 448, 692, 222], 1278);
                step(f, Op::RotateVector, &[40, 222, 224], 1279);
                step(f, Op::AddV, &[219, 224, 226], 1280);
                step(f, Op::AddV, &[226, 216, 228], 1281);
                step(f, Op::SubV, &[226, 216, 229], 1282);
                step(f, Op::LineTrace, &[228, 229, 63, 232, 233, 450], 1283);
                step(f, Op::BreakVector, &[232, 452, 453, 454], 1284);
                step(f, Op::BreakVector, &[226, 458, 459, 460], 1285);
                step(f, Op::SubF, &[454, 460, 464], 1286);
                step(f, Op::Select(ValueType::Float), &[63, 464, 692, 466], 1287);
                step(f, Op::AddF, &[53, 57, 449], 1288);
                step(f, Op::MakeVector, &[692, 449, 692, 223], 1289);
                step(f, Op::RotateVector, &[40, 223, 225], 1290);
                step(f, Op::AddV, &[219, 225, 227], 1291);
                step(f, Op::AddV, &[227, 216, 230], 1292);
                step(f, Op::SubV, &[227, 216, 231], 1293);
                step(f, Op::LineTrace, &[230, 231, 64, 234, 235, 451], 1294);
                step(f, Op::BreakVector, &[234, 455, 456, 457], 1295);
                step(f, Op::BreakVector, &[227, 461, 462, 463], 1296);
                step(f, Op::SubF, &[457, 463, 465], 1297);
                step(f, Op::Select(ValueType::Float), &[64, 465, 692, 467], 1298);
                step(f, Op::MaxF, &[466, 467, 468], 1299);
                step(f, Op::ClampF, &[468, 692, 56, 469], 1300);
                step(f, Op::MakeVector, &[692, 692, 469, 236], 1301);
                step(f, Op::AddV, &[219, 236, 237], 1302);
                step(f, Op::MakeTransform, &[237, 40, 392, 59], 1303);
                step(f, Op::Select(ValueType::Transform), &[62, 59, 57, 60], 1304);
                step(f, Op::Copy(ValueType::Transform), &[60, 58], 1305);
                step(f, Op::Jump, &[1306], 1306)
            }
            1306 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 53, 58], 1307);
                1307
            }
            1307 => {
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 351], 1308);
                step(f, Op::GreaterEqualF, &[351, 694, 51], 1309);
                step(f, Op::JumpIfFalse, &[51, 1386], 1310)
            }
            1310 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 53, 50], 1311);
                step(f, Op::JumpIfFalse, &[50, 1313], 1312)
            }
            1312 => {
                step(f, Op::Jump, &[1366], 1313)
            }
            1313 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 53, 61], 1314);
                step(f, Op::BreakTransform, &[61, 238, 41, 239], 1315);
                step(f, Op::Equals(Elem::Int), &[53, 65, 52], 1316);
                step(f, Op::Select(ValueType::Int), &[52, 66, 65, 54], 1317);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 54, 40], 1318);
                step(f, Op::BreakTransform, &[40, 146, 29, 147], 1319);
                step(f, Op::SubF, &[694, 13, 367], 1320);
                step(f, Op::MulF, &[12, 367, 368], 1321);
                step(f, Op::FootAvoidance, &[238, 146, 368, 52, 74, 148], 1322);
                step(f, Op::MakeTransform, &[148, 41, 392, 41], 1323);
                step(f, Op::Copy(ValueType::Transform), &[41, 42], 1324);
                step(f, Op::Copy(ValueType::Transform), &[110, 43], 1325);
                step(f, Op::BreakTransform, &[42, 149, 30, 150], 1326);
                step(f, Op::MakeVector, &[692, 692, 51, 151], 1327);
                step(f, Op::AddV, &[149, 151, 152], 1328);
                step(f, Op::SubV, &[149, 151, 153], 1329);
                step(f, Op::LineTrace, &[152, 153, 54, 154, 155, 369], 1330);
                step(f, Op::RotateVector, &[30, 394, 156], 1331);
                step(f, Op::FindQuatBetween, &[156, 155, 31], 1332);
                step(f, Op::MulQ, &[31, 30, 32], 1333);
                step(f, Op::MulF, &[49, 48, 370], 1334);
                step(f, Op::AddF, &[370, 57, 371], 1335);
                step(f, Op::NegF, &[371, 372], 1336);
                step(f, Op::MakeVector, &[692, 372, 692, 157], 1337);
                step(f, Op::RotateVector, &[32, 157, 159], 1338);
                step(f, Op::AddV, &[154, 159, 161], 1339);
                step(f, Op::AddV, &[161, 151, 163], 1340);
                step(f, Op::SubV, &[161, 151, 164], 1341);
                step(f, Op::LineTrace, &[163, 164, 55, 167, 168, 374], 1342);
                step(f, Op::BreakVector, &[167, 376, 377, 378], 1343);
                step(f, Op::BreakVector, &[161, 382, 383, 384], 1344);
                step(f, Op::SubF, &[378, 384, 388], 1345);
                step(f, Op::Select(ValueType::Float), &[55, 388, 692, 390], 1346);
                step(f, Op::AddF, &[53, 57, 373], 1347);
                step(f, Op::MakeVector, &[692, 373, 692, 158], 1348);
                step(f, Op::RotateVector, &[32, 158, 160], 1349);
                step(f, Op::AddV, &[154, 160, 162], 1350);
                step(f, Op::AddV, &[162, 151, 165], 1351);
                step(f, Op::SubV, &[162, 151, 166], 1352);
                step(f, Op::LineTrace, &[165, 166, 56, 169, 170, 375], 1353);
                step(f, Op::BreakVector, &[169, 379, 380, 381], 1354);
                step(f, Op::BreakVector, &[162, 385, 386, 387], 1355);
                step(f, Op::SubF, &[381, 387, 389], 1356);
                step(f, Op::Select(ValueType::Float), &[56, 389, 692, 391], 1357);
                step(f, Op::MaxF, &[390, 391, 392], 1358);
                step(f, Op::ClampF, &[392, 692, 56, 393], 1359);
                step(f, Op::MakeVector, &[692, 692, 393, 171], 1360);
                step(f, Op::AddV, &[154, 171, 172], 1361);
                step(f, Op::MakeTransform, &[172, 32, 392, 44], 1362);
                step(f, Op::Select(ValueType::Transform), &[54, 44, 42, 45], 1363);
                step(f, Op::Copy(ValueType::Transform), &[45, 43], 1364);
                step(f, Op::Jump, &[1365], 1365)
            }
            1365 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 53, 43], 1366);
                1366
            }
            1366 => {
                step(f, Op::ArrayAt(Elem::Transform), &[7, 53, 35], 1367);
                step(f, Op::BreakTransform, &[35, 134, 25, 135], 1368);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 53, 37], 1369);
                step(f, Op::BreakTransform, &[37, 137, 27, 138], 1370);
                step(f, Op::SubV, &[137, 134, 139], 1371);
                step(f, Op::LengthV, &[139, 354], 1372);
                step(f, Op::SubF, &[58, 59, 355], 1373);
                step(f, Op::SubF, &[354, 355, 356], 1374);
                step(f, Op::MulF, &[59, 697, 357], 1375);
                step(f, Op::ClampF, &[356, 692, 357, 358], 1376);
                step(f, Op::MulF, &[358, 358, 359], 1377);
                step(f, Op::MulF, &[59, 704, 360], 1378);
                step(f, Op::DivF, &[359, 360, 361], 1379);
                step(f, Op::SubF, &[354, 361, 362], 1380);
                step(f, Op::DivF, &[362, 354, 363], 1381);
                step(f, Op::ScaleV, &[139, 363, 140], 1382);
                step(f, Op::AddV, &[134, 140, 141], 1383);
                step(f, Op::MakeTransform, &[141, 27, 392, 38], 1384);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 53, 38], 1385);
                step(f, Op::Jump, &[1597], 1386)
            }
            1386 => {
                step(f, Op::ArrayAt(Elem::Transform), &[7, 53, 35], 1387);
                step(f, Op::BreakTransform, &[35, 134, 25, 135], 1388);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 53, 37], 1389);
                step(f, Op::BreakTransform, &[37, 137, 27, 138], 1390);
                step(f, Op::SubV, &[137, 134, 139], 1391);
                step(f, Op::LengthV, &[139, 354], 1392);
                step(f, Op::SubF, &[58, 59, 355], 1393);
                step(f, Op::SubF, &[354, 355, 356], 1394);
                step(f, Op::MulF, &[59, 697, 357], 1395);
                step(f, Op::ClampF, &[356, 692, 357, 358], 1396);
                step(f, Op::MulF, &[358, 358, 359], 1397);
                step(f, Op::MulF, &[59, 704, 360], 1398);
                step(f, Op::DivF, &[359, 360, 361], 1399);
                step(f, Op::SubF, &[354, 361, 362], 1400);
                step(f, Op::DivF, &[362, 354, 363], 1401);
                step(f, Op::ScaleV, &[139, 363, 140], 1402);
                step(f, Op::AddV, &[134, 140, 141], 1403);
                step(f, Op::MakeTransform, &[141, 27, 392, 38], 1404);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 53, 61], 1405);
                step(f, Op::ClampF, &[351, 692, 694, 470], 1406);
                step(f, Op::Copy(ValueType::Transform), &[38, 66], 1407);
                step(f, Op::Copy(ValueType::Transform), &[61, 67], 1408);
                step(f, Op::Copy(ValueType::Float), &[470, 488], 1409);
                step(f, Op::Copy(ValueType::Transform), &[110, 68], 1410);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[3, 2], 1411);
                step(f, Op::ArrayReset(Elem::Vec3), &[2], 1412);
                step(f, Op::BreakTransform, &[66, 256, 46, 257], 1413);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 256], 1414);
                step(f, Op::BreakTransform, &[66, 256, 46, 257], 1415);
                step(f, Op::UnitV, &[2, 255], 1416);
                step(f, Op::LengthV, &[2, 489], 1417);
                step(f, Op::RemapF, &[489, 692, 60, 692, 61, 79, 490], 1418);
                step(f, Op::ScaleV, &[255, 490, 260], 1419);
                step(f, Op::SubV, &[256, 260, 266], 1420);
                step(f, Op::MakeVector, &[692, 692, 63, 264], 1421);
                step(f, Op::AddV, &[266, 264, 268], 1422);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 268], 1423);
                step(f, Op::BreakTransform, &[66, 256, 46, 257], 1424);
                step(f, Op::UnitV, &[2, 255], 1425);
                step(f, Op::LengthV, &[2, 489], 1426);
                step(f, Op::RemapF, &[489, 692, 60, 692, 61, 79, 490], 1427);
                step(f, Op::ScaleV, &[255, 490, 260], 1428);
                step(f, Op::SubV, &[256, 260, 266], 1429);
                step(f, Op::MakeVector, &[692, 692, 63, 264], 1430);
                step(f, Op::AddV, &[266, 264, 268], 1431);
                step(f, Op::RemapF, &[489, 692, 60, 692, 65, 79, 492], 1432);
                step(f, Op::MakeVector, &[692, 692, 492, 262], 1433);
                step(f, Op::AddV, &[268, 262, 272], 1434);
                step(f, Op::BreakTransform, &[67, 258, 47, 259], 1435);
                step(f, Op::BreakVector, &[258, 497, 498, 499], 1436);
                step(f, Op::BreakVector, &[256, 494, 495, 496], 1437);
                step(f, Op::SubF, &[499, 496, 500], 1438);
                step(f, Op::MaxF, &[500, 692, 502], 1439);
                step(f, Op::MulF, &[502, 67, 506], 1440);
                step(f, Op::AbsF, &[500, 504], 1441);
                step(f, Op::RemapF, &[504, 692, 70, 692, 69, 79, 505], 1442);
                step(f, Op::AddF, &[506, 505, 508], 1443);
                step(f, Op::MakeVector, &[692, 692, 508, 270], 1444);
                step(f, Op::AddV, &[272, 270, 274], 1445);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 274], 1446);
                step(f, Op::BreakTransform, &[66, 256, 46, 257], 1447);
                step(f, Op::UnitV, &[2, 255], 1448);
                step(f, Op::LengthV, &[2, 489], 1449);
                step(f, Op::RemapF, &[489, 692, 60, 692, 61, 79, 490], 1450);
                step(f, Op::ScaleV, &[255, 490, 260], 1451);
                step(f, Op::SubV, &[256, 260, 266], 1452);
                step(f, Op::MakeVector, &[692, 692, 63, 264], 1453);
                step(f, Op::AddV, &[266, 264, 268], 1454);
                step(f, Op::RemapF, &[489, 692, 60, 692, 65, 79, 492], 1455);
                step(f, Op::MakeVector, &[692, 692, 492, 262], 1456);
                step(f, Op::AddV, &[268, 262, 272], 1457);
                step(f, Op::BreakTransform, &[67, 258, 47, 259], 1458);
                step(f, Op::BreakVector, &[258, 497, 498, 499], 1459);
                step(f, Op::BreakVector, &[256, 494, 495, 496], 1460);
                step(f, Op::SubF, &[499, 496, 500], 1461);
                step(f, Op::MaxF, &[500, 692, 502], 1462);
                step(f, Op::MulF, &[502, 67, 506], 1463);
                step(f, Op::AbsF, &[500, 504], 1464);
                step(f, Op::RemapF, &[504, 692, 70, 692, 69, 79, 505], 1465);
                step(f, Op::AddF, &[506, 505, 508], 1466);
                step(f, Op::MakeVector, &[692, 692, 508, 270], 1467);
                step(f, Op::AddV, &[272, 270, 274], 1468);
                step(f, Op::RemapF, &[489, 692, 60, 692, 62, 79, 491], 1469);
                step(f, Op::ScaleV, &[255, 491, 261], 1470);
                step(f, Op::AddV, &[258, 261, 267], 1471);
                step(f, Op::MakeVector, &[692, 692, 64, 265], 1472);
                step(f, Op::AddV, &[267, 265, 269], 1473);
                step(f, Op::RemapF, &[489, 692, 60, 692, 66, 79, 493], 1474);
                step(f, Op::MakeVector, &[692, 692, 493, 263], 1475);
                step(f, Op::AddV, &[269, 263, 273], 1476);
                step(f, Op::NegF, &[500, 501], 1477);
                step(f, Op::MaxF, &[501, 692, 503], 1478);
                step(f, Op::MulF, &[503, 68, 507], 1479);
                step(f, Op::AddF, &[507, 505, 509], 1480);
                step(f, Op::MakeVector, &[692, 692, 509, 271], 1481);
                step(f, Op::AddV, &[273, 271, 275], 1482);
                step(f, Op::LerpV, &[274, 275, 693, 276], 1483);
                step(f, Op::GetTransform, &[36, 65, 79, 69], 1484);
                step(f, Op::BreakTransform, &[69, 277, 48, 278], 1485);
                step(f, Op::BreakVector, &[277, 519, 520, 521], 1486);
                step(f, Op::SubF, &[694, 13, 513], 1487);
                step(f, Op::MulF, &[71, 513, 514], 1488);
                step(f, Op::MulF, &[12, 514, 515], 1489);
                step(f, Op::QuatFromAxisAngle, &[394, 515, 49], 1490);
                step(f, Op::SubV, &[276, 277, 279], 1491);
                step(f, Op::BreakVector, &[279, 510, 511, 512], 1492);
                step(f, Op::MakeVector, &[510, 511, 692, 280], 1493);
                step(f, Op::RotateVector, &[49, 280, 281], 1494);
                step(f, Op::BreakVector, &[281, 516, 517, 518], 1495);
                step(f, Op::AddF, &[519, 516, 525], 1496);
                step(f, Op::AddF, &[520, 517, 526], 1497);
                step(f, Op::BreakVector, &[276, 522, 523, 524], 1498);
                step(f, Op::MakeVector, &[525, 526, 524, 282], 1499);
                step(f, Op::DistanceV, &[256, 258, 527], 1500);
                step(f, Op::RemapF, &[527, 697, 705, 692, 694, 79, 528], 1501);
                step(f, Op::LerpV, &[276, 282, 528, 283], 1502);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 283], 1503);
                step(f, Op::BreakTransform, &[67, 258, 47, 259], 1504);
                step(f, Op::UnitV, &[2, 255], 1505);
                step(f, Op::LengthV, &[2, 489], 1506);
                step(f, Op::RemapF, &[489, 692, 60, 692, 62, 79, 491], 1507);
                step(f, Op::ScaleV, &[255, 491, 261], 1508);
                step(f, Op::AddV, &[258, 261, 267], 1509);
                step(f, Op::MakeVector, &[692, 692, 64, 265], 1510);
                step(f, Op::AddV, &[267, 265, 269], 1511);
                step(f, Op::RemapF, &[489, 692, 60, 692, 66, 79, 493], 1512);
                step(f, Op::MakeVector, &[692, 692, 493, 263], 1513);
                step(f, Op::AddV, &[269, 263, 273], 1514);
                step(f, Op::BreakVector, &[258, 497, 498, 499], 1515);
                step(f, Op::BreakTransform, &[66, 256, 46, 257], 1516);
                step(f, Op::BreakVector, &[256, 494, 495, 496], 1517);
                step(f, Op::SubF, &[499, 496, 500], 1518);
                step(f, Op::NegF, &[500, 501], 1519);
                step(f, Op::MaxF, &[501, 692, 503], 1520);
                step(f, Op::MulF, &[503, 68, 507], 1521);
                step(f, Op::AbsF, &[500, 504], 1522);
                step(f, Op::RemapF, &[504, 692, 70, 692, 69, 79, 505], 1523);
                step(f, Op::AddF, &[507, 505, 509], 1524);
                step(f, Op::MakeVector, &[692, 692, 509, 271], 1525);
                step(f, Op::AddV, &[273, 271, 275], 1526);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 275], 1527);
                step(f, Op::BreakTransform, &[67, 258, 47, 259], 1528);
                step(f, Op::UnitV, &[2, 255], 1529);
                step(f, Op::LengthV, &[2, 489], 1530);
                step(f, Op::RemapF, &[489, 692, 60, 692, 62, 79, 491], 1531);
                step(f, Op::ScaleV, &[255, 491, 261], 1532);
                step(f, Op::AddV, &[258, 261, 267], 1533);
                step(f, Op::MakeVector, &[692, 692, 64, 265], 1534);
                step(f, Op::AddV, &[267, 265, 269], 1535);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 269], 1536);
                step(f, Op::BreakTransform, &[67, 258, 47, 259], 1537);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 258], 1538);
                step(f, Op::JumpIfFalse, &[8, 1541], 1539)
            }
            1539 => {
                step(f, Op::DrawSpline, &[2, 65, 68, 693, 396], 1540);
                step(f, Op::Jump, &[1541], 1541)
            }
            1541 => {
                step(f, Op::Spline, &[2, 488, 65, 284, 285], 1542);
                step(f, Op::BreakTransform, &[66, 256, 46, 257], 1543);
                step(f, Op::BreakTransform, &[67, 258, 47, 259], 1544);
                step(f, Op::SlerpQ, &[46, 47, 488, 50], 1545);
                step(f, Op::MulF, &[488, 706, 539], 1546);
                step(f, Op::SinF, &[539, 540], 1547);
                step(f, Op::Copy(ValueType::Float), &[488, 529], 1548);
                step(f, Op::Copy(ValueType::Float), &[692, 530], 1549);
                step(f, Op::DivF, &[529, 82, 531], 1550);
                step(f, Op::Copy(ValueType::Float), &[531, 532], 1551);
                step(f, Op::Copy(ValueType::Float), &[692, 533], 1552);
                step(f, Op::ClampF, &[532, 692, 694, 534], 1553);
                step(f, Op::MulF, &[534, 534, 535], 1554);
                step(f, Op::MulF, &[534, 697, 536], 1555);
                step(f, Op::SubF, &[698, 536, 537], 1556);
                step(f, Op::MulF, &[535, 537, 538], 1557);
                step(f, Op::Copy(ValueType::Float), &[538, 533], 1558);
                step(f, Op::Jump, &[1559], 1559)
            }
            1559 => {
                step(f, Op::Copy(ValueType::Float), &[533, 530], 1560);
                step(f, Op::Jump, &[1561], 1561)
            }
            1561 => {
                step(f, Op::MulF, &[540, 530, 541], 1562);
                step(f, Op::MulF, &[541, 72, 542], 1563);
                step(f, Op::SlerpQ, &[50, 91, 542, 51], 1564);
                step(f, Op::MakeTransform, &[284, 51, 392, 70], 1565);
                step(f, Op::Copy(ValueType::Transform), &[70, 68], 1566);
                step(f, Op::Jump, &[1567], 1567)
            }
            1567 => {
                step(f, Op::BreakTransform, &[68, 240, 42, 241], 1568);
                step(f, Op::Equals(Elem::Int), &[53, 65, 52], 1569);
                step(f, Op::Select(ValueType::Int), &[52, 66, 65, 54], 1570);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 54, 40], 1571);
                step(f, Op::BreakTransform, &[40, 146, 29, 147], 1572);
                step(f, Op::SubF, &[694, 13, 367], 1573);
                step(f, Op::MulF, &[12, 367, 368], 1574);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 54, 65], 1575);
                step(f, Op::Select(ValueType::Float), &[65, 75, 692, 473], 1576);
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 351], 1577);
                step(f, Op::ClampF, &[351, 692, 694, 470], 1578);
                step(f, Op::MulF, &[470, 706, 471], 1579);
                step(f, Op::SinF, &[471, 472], 1580);
                step(f, Op::MulF, &[472, 472, 474], 1581);
                step(f, Op::MulF, &[473, 474, 475], 1582);
                step(f, Op::AddF, &[74, 475, 476], 1583);
                step(f, Op::FootAvoidance, &[240, 146, 368, 52, 476, 242], 1584);
                step(f, Op::SubV, &[242, 240, 243], 1585);
                step(f, Op::LengthV, &[243, 477], 1586);
                step(f, Op::AddF, &[477, 475, 478], 1587);
                step(f, Op::DivF, &[477, 478, 479], 1588);
                step(f, Op::ScaleV, &[243, 479, 244], 1589);
                step(f, Op::AddV, &[240, 244, 245], 1590);
                step(f, Op::SubF, &[694, 114, 480], 1591);
                step(f, Op::MulF, &[3, 480, 481], 1592);
                step(f, Op::MulF, &[481, 474, 482], 1593);
                step(f, Op::MakeVector, &[692, 692, 482, 246], 1594);
                step(f, Op::AddV, &[245, 246, 247], 1595);
                step(f, Op::MakeTransform, &[247, 42, 392, 62], 1596);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 53, 62], 1597);
                1597
            }
            1597 => {
                step(f, Op::GreaterF, &[18, 692, 53], 1598);
                step(f, Op::JumpIfFalse, &[53, 1615], 1599)
            }
            1599 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 53, 63], 1600);
                step(f, Op::BreakTransform, &[63, 248, 43, 249], 1601);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 53, 64], 1602);
                step(f, Op::BreakTransform, &[64, 250, 44, 251], 1603);
                step(f, Op::MulF, &[18, 18, 483], 1604);
                step(f, Op::LerpV, &[248, 250, 483, 252], 1605);
                step(f, Op::SubF, &[694, 18, 484], 1606);
                step(f, Op::MulF, &[18, 484, 485], 1607);
                step(f, Op::MulF, &[116, 697, 486], 1608);
                step(f, Op::MulF, &[485, 486, 487], 1609);
                step(f, Op::MakeVector, &[692, 692, 487, 253], 1610);
                step(f, Op::AddV, &[252, 253, 254], 1611);
                step(f, Op::SlerpQ, &[43, 44, 18, 45], 1612);
                step(f, Op::MakeTransform, &[254, 45, 392, 65], 1613);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 53, 65], 1614);
                step(f, Op::Jump, &[1615], 1615)
            }
            1615 => {
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 351], 1616);
                step(f, Op::GreaterEqualF, &[351, 694, 51], 1617);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 53, 51], 1618);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 53, 39], 1619);
                step(f, Op::BreakTransform, &[39, 142, 28, 143], 1620);
                step(f, Op::ArrayAt(Elem::Float), &[2, 53, 351], 1621);
                step(f, Op::SubF, &[694, 351, 364], 1622);
                step(f, Op::MulF, &[8, 5, 365], 1623);
                step(f, Op::MulF, &[364, 365, 366], 1624);
                step(f, Op::ScaleV, &[2, 366, 144], 1625);
                step(f, Op::AddV, &[142, 144, 145], 1626);
                step(f, Op::MakeTransform, &[145, 91, 392, 55], 1627);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 53, 55], 1628);
                step(f, Op::Copy(ValueType::Bone), &[0, 17], 1629);
                step(f, Op::Copy(ValueType::Int), &[3, 55], 1630);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 55, 71], 1631);
                step(f, Op::BreakTransform, &[71, 286, 52, 287], 1632);
                step(f, Op::MakeVector, &[692, 692, 46, 296], 1633);
                step(f, Op::AddV, &[286, 296, 297], 1634);
                step(f, Op::GetTransform, &[17, 65, 79, 73], 1635);
                step(f, Op::BreakTransform, &[73, 291, 54, 292], 1636);
                step(f, Op::MakeTransform, &[297, 54, 392, 75], 1637);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 55, 20], 1638);
                step(f, Op::GetTransform, &[20, 65, 79, 74], 1639);
                step(f, Op::BreakTransform, &[74, 293, 55, 294], 1640);
                step(f, Op::SubV, &[293, 291, 295], 1641);
                step(f, Op::AddV, &[297, 295, 298], 1642);
                step(f, Op::FootPivots, &[297, 298, 48, 47, 46, 49, 299, 300, 301], 1643);
                step(f, Op::GetParent, &[17, 18], 1644);
                step(f, Op::GetParent, &[18, 19], 1645);
                step(f, Op::GetTransform, &[19, 65, 80, 72], 1646);
                step(f, Op::BreakTransform, &[72, 288, 53, 289], 1647);
                step(f, Op::SubV, &[286, 288, 290], 1648);
                step(f, Op::DotV, &[290, 395, 543], 1649);
                step(f, Op::RemapF, &[543, 77, 76, 78, 692, 79, 546], 1650);
                step(f, Op::LengthV, &[2, 544], 1651);
                step(f, Op::RemapF, &[544, 692, 86, 692, 694, 79, 545], 1652);
                step(f, Op::MulF, &[546, 545, 547], 1653);
                step(f, Op::QuatFromAxisAngle, &[397, 547, 56], 1654);
                step(f, Op::RotateAroundPoint, &[75, 299, 56, 76], 1655);
                step(f, Op::ArrayAt(Elem::Float), &[2, 55, 548], 1656);
                step(f, Op::Copy(ValueType::Float), &[548, 550], 1657);
                step(f, Op::Copy(ValueType::Float), &[692, 551], 1658);
                step(f, Op::DivF, &[550, 82, 552], 1659);
                step(f, Op::Copy(ValueType::Float), &[552, 553], 1660);
                step(f, Op::Copy(ValueType::Float), &[692, 554], 1661);
                step(f, Op::ClampF, &[553, 692, 694, 555], 1662);
                step(f, Op::MulF, &[555, 555, 556], 1663);
                step(f, Op::MulF, &[555, 697, 557], 1664);
                step(f, Op::SubF, &[698, 557, 558], 1665);
                step(f, Op::MulF, &[556, 558, 559], 1666);
                step(f, Op::Copy(ValueType::Float), &[559, 554], 1667);
                step(f, Op::Jump, &[1668], 1668)
            }
            1668 => {
                step(f, Op::Copy(ValueType::Float), &[554, 551], 1669);
                step(f, Op::Jump, &[1670], 1670)
            }
            1670 => {
                step(f, Op::SubF, &[694, 548, 549], 1671);
                step(f, Op::Copy(ValueType::Float), &[549, 560], 1672);
                step(f, Op::Copy(ValueType::Float), &[692, 561], 1673);
                step(f, Op::DivF, &[560, 82, 562], 1674);
                step(f, Op::Copy(ValueType::Float), &[562, 563], 1675);
                step(f, Op::Copy(ValueType::Float), &[692, 564], 1676);
                step(f, Op::ClampF, &[563, 692, 694, 565], 1677);
                step(f, Op::MulF, &[565, 565, 566], 1678);
                step(f, Op::MulF, &[565, 697, 567], 1679);
                step(f, Op::SubF, &[698, 567, 568], 1680);
                step(f, Op::MulF, &[566, 568, 569], 1681);
                step(f, Op::Copy(ValueType::Float), &[569, 564], 1682);
                step(f, Op::Jump, &[1683], 1683)
            }
            1683 => {
                step(f, Op::Copy(ValueType::Float), &[564, 561], 1684);
                step(f, Op::Jump, &[1685], 1685)
            }
            1685 => {
                step(f, Op::MulF, &[551, 561, 570], 1686);
                step(f, Op::LerpF, &[81, 694, 570, 571], 1687);
                step(f, Op::MulF, &[547, 571, 572], 1688);
                step(f, Op::QuatFromAxisAngle, &[397, 572, 57], 1689);
                step(f, Op::SubV, &[300, 299, 302], 1690);
                step(f, Op::RotateVector, &[57, 302, 303], 1691);
                step(f, Op::AddV, &[299, 303, 304], 1692);
                step(f, Op::RemapF, &[543, 79, 77, 80, 692, 79, 573], 1693);
                step(f, Op::MulF, &[573, 545, 574], 1694);
                step(f, Op::QuatFromAxisAngle, &[397, 574, 58], 1695);
                step(f, Op::RotateAroundPoint, &[76, 304, 58, 77], 1696);
                step(f, Op::RemapF, &[543, 83, 84, 692, 85, 79, 575], 1697);
                step(f, Op::MulF, &[575, 545, 576], 1698);
                step(f, Op::QuatFromAxisAngle, &[397, 576, 59], 1699);
                step(f, Op::RotateAroundPoint, &[77, 301, 59, 78], 1700);
                step(f, Op::SubF, &[694, 13, 577], 1701);
                step(f, Op::MulF, &[12, 577, 578], 1702);
                step(f, Op::LimitRotationAroundZ, &[52, 578, 87, 60], 1703);
                step(f, Op::RotateAroundPoint, &[78, 286, 60, 79], 1704);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 55, 79], 1705);
                step(f, Op::JumpIfFalse, &[8, 1795], 1706)
            }
            1706 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 55, 71], 1707);
                step(f, Op::BreakTransform, &[71, 286, 52, 287], 1708);
                step(f, Op::MakeVector, &[692, 692, 46, 296], 1709);
                step(f, Op::AddV, &[286, 296, 297], 1710);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 55, 20], 1711);
                step(f, Op::GetTransform, &[20, 65, 79, 74], 1712);
                step(f, Op::BreakTransform, &[74, 293, 55, 294], 1713);
                step(f, Op::GetTransform, &[17, 65, 79, 73], 1714);
                step(f, Op::BreakTransform, &[73, 291, 54, 292], 1715);
                step(f, Op::SubV, &[293, 291, 295], 1716);
                step(f, Op::AddV, &[297, 295, 298], 1717);
                step(f, Op::FootPivots, &[297, 298, 48, 47, 46, 49, 299, 300, 301], 1718);
                step(f, Op::DrawPoint, &[301, 698, 397], 1719);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 55, 71], 1720);
                step(f, Op::BreakTransform, &[71, 286, 52, 287], 1721);
                step(f, Op::MakeVector, &[692, 692, 46, 296], 1722);
                step(f, Op::AddV, &[286, 296, 297], 1723);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 55, 20], 1724);
                step(f, Op::GetTransform, &[20, 65, 79, 74], 1725);
                step(f, Op::BreakTransform, &[74, 293, 55, 294], 1726);
                step(f, Op::GetTransform, &[17, 65, 79, 73], 1727);
                step(f, Op::BreakTransform, &[73, 291, 54, 292], 1728);
                step(f, Op::SubV, &[293, 291, 295], 1729);
                step(f, Op::AddV, &[297, 295, 298], 1730);
                step(f, Op::FootPivots, &[297, 298, 48, 47, 46, 49, 299, 300, 301], 1731);
                step(f, Op::DrawPoint, &[299, 698, 395], 1732);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 55, 71], 1733);
                step(f, Op::BreakTransform, &[71, 286, 52, 287], 1734);
                step(f, Op::MakeVector, &[692, 692, 46, 296], 1735);
                step(f, Op::AddV, &[286, 296, 297], 1736);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 55, 20], 1737);
                step(f, Op::GetTransform, &[20, 65, 79, 74], 1738);
                step(f, Op::BreakTransform, &[74, 293, 55, 294], 1739);
                step(f, Op::GetTransform, &[17, 65, 79, 73], 1740);
                step(f, Op::BreakTransform, &[73, 291, 54, 292], 1741);
                step(f, Op::SubV, &[293, 291, 295], 1742);
                step(f, Op::AddV, &[297, 295, 298], 1743);
                step(f, Op::FootPivots, &[297, 298, 48, 47, 46, 49, 299, 300, 301], 1744);
                step(f, Op::GetParent, &[17, 18], 1745);
                step(f, Op::GetParent, &[18, 19], 1746);
                step(f, Op::GetTransform, &[19, 65, 80, 72], 1747);
                step(f, Op::BreakTransform, &[72, 288, 53, 289], 1748);
                step(f, Op::SubV, &[286, 288, 290], 1749);
                step(f, Op::DotV, &[290, 395, 543], 1750);
                step(f, Op::RemapF, &[543, 77, 76, 78, 692, 79, 546], 1751);
                step(f, Op::LengthV, &[2, 544], 1752);
                step(f, Op::RemapF, &[544, 692, 86, 692, 694, 79, 545], 1753);
                step(f, Op::MulF, &[546, 545, 547], 1754);
                step(f, Op::ArrayAt(Elem::Float), &[2, 55, 548], 1755);
                step(f, Op::Copy(ValueType::Float), &[548, 550], 1756);
                step(f, Op::Copy(ValueType::Float), &[692, 551], 1757);
                step(f, Op::DivF, &[550, 82, 552], 1758);
                step(f, Op::Copy(ValueType::Float), &[552, 553], 1759);
                step(f, Op::Copy(ValueType::Float), &[692, 554], 1760);
                step(f, Op::ClampF, &[553, 692, 694, 555], 1761);
                step(f, Op::MulF, &[555, 555, 556], 1762);
                step(f, Op::MulF, &[555, 697, 557], 1763);
                step(f, Op::SubF, &[698, 557, 558], 1764);
                step(f, Op::MulF, &[556, 558, 559], 1765);
                step(f, Op::Copy(ValueType::Float), &[559, 554], 1766);
                step(f, Op::Jump, &[1767], 1767)
            }
            1767 => {
                step(f, Op::Copy(ValueType::Float), &[554, 551], 1768);
                step(f, Op::Jump, &[1769], 1769)
            }
            1769 => {
                step(f, Op::SubF, &[694, 548, 549], 1770);
                step(f, Op::Copy(ValueType::Float), &[549, 560], 1771);
                step(f, Op::Copy(ValueType::Float), &[692, 561], 1772);
                step(f, Op::DivF, &[560, 82, 562], 1773);
                step(f, Op::Copy(ValueType::Float), &[562, 563], 1774);
                step(f, Op::Copy(ValueType::Float), &[692, 564], 1775);
                step(f, Op::ClampF, &[563, 692, 694, 565], 1776);
                step(f, Op::MulF, &[565, 565, 566], 1777);
                step(f, Op::MulF, &[565, 697, 567], 1778);
                step(f, Op::SubF, &[698, 567, 568], 1779);
                step(f, Op::MulF, &[566, 568, 569], 1780);
                step(f, Op::Copy(ValueType::Float), &[569, 564], 1781);
                step(f, Op::Jump, &[1782], 1782)
            }
            1782 => {
                step(f, Op::Copy(ValueType::Float), &[564, 561], 1783);
                step(f, Op::Jump, &[1784], 1784)
            }
            1784 => {
                step(f, Op::MulF, &[551, 561, 570], 1785);
                step(f, Op::LerpF, &[81, 694, 570, 571], 1786);
                step(f, Op::MulF, &[547, 571, 572], 1787);
                step(f, Op::QuatFromAxisAngle, &[397, 572, 57], 1788);
                step(f, Op::SubV, &[300, 299, 302], 1789);
                step(f, Op::RotateVector, &[57, 302, 303], 1790);
                step(f, Op::AddV, &[299, 303, 304], 1791);
                step(f, Op::DrawPoint, &[304, 698, 394], 1792);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 55, 71], 1793);
                step(f, Op::DrawTransform, &[71, 705, 693], 1794);
                step(f, Op::Jump, &[1795], 1795)
            }
            1795 => {
                step(f, Op::Jump, &[966], 1796)
            }
            1796 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1797);
                step(f, Op::Copy(ValueType::Int), &[65, 5], 1798);
                1798
            }
            1798 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 5, 1, 6, 7, 1853], 1799)
            }
            1799 => {
                step(f, Op::Copy(ValueType::Bone), &[1, 21], 1800);
                step(f, Op::Copy(ValueType::Int), &[6, 56], 1801);
                step(f, Op::GetParent, &[21, 22], 1802);
                step(f, Op::GetParent, &[22, 23], 1803);
                step(f, Op::GetParent, &[23, 24], 1804);
                step(f, Op::GetTransform, &[24, 65, 80, 80], 1805);
                step(f, Op::BreakTransform, &[80, 305, 61, 306], 1806);
                step(f, Op::LengthV, &[1, 580], 1807);
                step(f, Op::ClavicleOffset, &[10, 580, 92, 95, 581], 1808);
                step(f, Op::MakeVector, &[692, 692, 581, 307], 1809);
                step(f, Op::AddV, &[305, 307, 308], 1810);
                step(f, Op::MakeTransform, &[308, 61, 392, 81], 1811);
                step(f, Op::SetTransform, &[24, 81, 65, 79, 694], 1812);
                step(f, Op::GetParent, &[21, 22], 1813);
                step(f, Op::GetParent, &[22, 23], 1814);
                step(f, Op::GetTransform, &[21, 65, 80, 82], 1815);
                step(f, Op::GetTransform, &[23, 65, 80, 83], 1816);
                step(f, Op::BreakTransform, &[83, 309, 63, 310], 1817);
                step(f, Op::Equals(Elem::Int), &[56, 65, 66], 1818);
                step(f, Op::Select(ValueType::Int), &[66, 66, 65, 57], 1819);
                step(f, Op::ArrayAt(Elem::Float), &[0, 57, 579], 1820);
                step(f, Op::ArmSwingRotation, &[579, 1, 0, 93, 700, 707, 694, 92, 90, 91, 700, 700, 694, 582], 1821);
                step(f, Op::QuatFromAxisAngle, &[397, 582, 62], 1822);
                step(f, Op::RotateAroundPoint, &[82, 309, 62, 84], 1823);
                step(f, Op::BreakTransform, &[84, 311, 64, 312], 1824);
                step(f, Op::LengthV, &[1, 580], 1825);
                step(f, Op::RemapF, &[580, 692, 92, 692, 94, 79, 583], 1826);
                step(f, Op::MakeVector, &[692, 692, 583, 313], 1827);
                step(f, Op::AddV, &[311, 313, 314], 1828);
                step(f, Op::MakeTransform, &[314, 64, 392, 85], 1829);
                step(f, Op::Select(ValueType::Vec3), &[66, 398, 397, 316], 1830);
                step(f, Op::Select(ValueType::Vec3), &[66, 395, 399, 317], 1831);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 56, 315], 1832);
                step(f, Op::TwoBoneIK, &[23, 22, 21, 85, 316, 317, 315, 65, 694, 80, 708, 709, 79, 67, 584], 1833);
                step(f, Op::JumpIfFalse, &[8, 1852], 1834)
            }
            1834 => {
                step(f, Op::GetParent, &[21, 22], 1835);
                step(f, Op::GetParent, &[22, 23], 1836);
                step(f, Op::GetTransform, &[23, 65, 80, 83], 1837);
                step(f, Op::BreakTransform, &[83, 309, 63, 310], 1838);
                step(f, Op::GetTransform, &[21, 65, 80, 82], 1839);
                step(f, Op::Equals(Elem::Int), &[56, 65, 66], 1840);
                step(f, Op::Select(ValueType::Int), &[66, 66, 65, 57], 1841);
                step(f, Op::ArrayAt(Elem::Float), &[0, 57, 579], 1842);
                step(f, Op::ArmSwingRotation, &[579, 1, 0, 93, 700, 707, 694, 92, 90, 91, 700, 700, 694, 582], 1843);
                step(f, Op::QuatFromAxisAngle, &[397, 582, 62], 1844);
                step(f, Op::RotateAroundPoint, &[82, 309, 62, 84], 1845);
                step(f, Op::BreakTransform, &[84, 311, 64, 312], 1846);
                step(f, Op::LengthV, &[1, 580], 1847);
                step(f, Op::RemapF, &[580, 692, 92, 692, 94, 79, 583], 1848);
                step(f, Op::MakeVector, &[692, 692, 583, 313], 1849);
                step(f, Op::AddV, &[311, 313, 314], 1850);
                step(f, Op::DrawLine, &[309, 314, 693, 395], 1851);
                step(f, Op::Jump, &[1852], 1852)
            }
            1852 => {
                step(f, Op::Jump, &[1798], 1853)
            }
            1853 => {
                step(f, Op::Copy(ValueType::Float), &[692, 587], 1854);
                step(f, Op::Copy(ValueType::Float), &[701, 588], 1855);
                step(f, Op::Copy(ValueType::Bool), &[80, 68], 1856);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 10], 1857);
                step(f, Op::Copy(ValueType::Int), &[65, 58], 1858);
                step(f, Op::MakeVector, &[692, 692, 51, 320], 1859);
                1859
            }
            1859 => {
                step(f, Op::ForEachNext(Elem::Transform), &[10, 58, 86, 59, 60, 1872], 1860)
            }
            1860 => {
                step(f, Op::BreakTransform, &[86, 318, 65, 319], 1861);
                step(f, Op::AddV, &[318, 320, 321], 1862);
                step(f, Op::SubV, &[318, 320, 322], 1863);
                step(f, Op::SphereTrace, &[321, 322, 50, 69, 323, 324, 589], 1864);
                step(f, Op::BreakVector, &[323, 590, 591, 592], 1865);
                step(f, Op::LessF, &[592, 588, 70], 1866);
                step(f, Op::And, &[69, 70, 71], 1867);
                step(f, Op::JumpIfFalse, &[71, 1871], 1868)
            }
            1868 => {
                step(f, Op::Copy(ValueType::Float), &[592, 588], 1869);
                step(f, Op::Copy(ValueType::Bool), &[79, 68], 1870);
                step(f, Op::Jump, &[1871], 1871)
            }
            1871 => {
                step(f, Op::Jump, &[1859], 1872)
            }
            1872 => {
                step(f, Op::Select(ValueType::Float), &[68, 588, 692, 593], 1873);
                step(f, Op::ClampF, &[593, 54, 55, 594], 1874);
                step(f, Op::Copy(ValueType::Float), &[594, 587], 1875);
                step(f, Op::Jump, &[1876], 1876)
            }
            1876 => {
                step(f, Op::SubF, &[694, 18, 586], 1877);
                step(f, Op::MulF, &[587, 586, 595], 1878);
                step(f, Op::FloatLerp, &[14, 595, 44, 596], 1879);
                step(f, Op::Select(ValueType::Float), &[1, 595, 596, 597], 1880);
                step(f, Op::Copy(ValueType::Float), &[597, 14], 1881);
                step(f, Op::GetTransform, &[37, 65, 79, 91], 1882);
                step(f, Op::BreakTransform, &[91, 337, 72, 338], 1883);
                step(f, Op::PelvisLean, &[1, 97, 102, 103, 613, 614], 1884);
                step(f, Op::LengthV, &[2, 585], 1885);
                step(f, Op::RemapF, &[585, 692, 97, 692, 96, 79, 598], 1886);
                step(f, Op::MulF, &[10, 710, 599], 1887);
                step(f, Op::SinF, &[599, 600], 1888);
                step(f, Op::MulF, &[598, 600, 601], 1889);
                step(f, Op::MulF, &[601, 586, 602], 1890);
                step(f, Op::AddF, &[602, 14, 603], 1891);
                step(f, Op::MulF, &[3, 114, 604], 1892);
                step(f, Op::SubF, &[603, 604, 605], 1893);
                step(f, Op::MakeVector, &[692, 614, 605, 339], 1894);
                step(f, Op::AddV, &[337, 339, 340], 1895);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 87], 1896);
                step(f, Op::BreakTransform, &[87, 325, 66, 326], 1897);
                step(f, Op::BreakVector, &[325, 615, 616, 617], 1898);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 66, 88], 1899);
                step(f, Op::BreakTransform, &[88, 327, 67, 328], 1900);
                step(f, Op::BreakVector, &[327, 618, 619, 620], 1901);
                step(f, Op::SubF, &[617, 620, 621], 1902);
                step(f, Op::PelvisSideLean, &[621, 104, 105, 622], 1903);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 65, 89], 1904);
                step(f, Op::BreakTransform, &[89, 331, 68, 332], 1905);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 66, 90], 1906);
                step(f, Op::BreakTransform, &[90, 333, 69, 334], 1907);
                step(f, Op::SlerpQ, &[68, 69, 693, 70], 1908);
                step(f, Op::EulerFromQuat, &[70, 65, 335], 1909);
                step(f, Op::BreakVector, &[335, 609, 610, 611], 1910);
                step(f, Op::RemapF, &[585, 98, 97, 692, 99, 79, 607], 1911);
                step(f, Op::SubV, &[325, 327, 329], 1912);
                step(f, Op::RotateVector, &[0, 395, 330], 1913);
                step(f, Op::DotV, &[329, 330, 606], 1914);
                step(f, Op::MulF, &[607, 606, 608], 1915);
                step(f, Op::AddF, &[611, 608, 612], 1916);
                step(f, Op::MakeVector, &[613, 622, 612, 336], 1917);
                step(f, Op::QuatFromEuler, &[336, 65, 71], 1918);
                step(f, Op::MakeTransform, &[340, 71, 392, 92], 1919);
                step(f, Op::SetTransform, &[38, 92, 65, 79, 694], 1920);
                step(f, Op::GetTransform, &[39, 66, 79, 93], 1921);
                step(f, Op::BreakTransform, &[93, 341, 76, 342], 1922);
                step(f, Op::LengthV, &[2, 585], 1923);
                step(f, Op::RemapF, &[585, 98, 97, 692, 99, 79, 607], 1924);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 87], 1925);
                step(f, Op::BreakTransform, &[87, 325, 66, 326], 1926);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 66, 88], 1927);
                step(f, Op::BreakTransform, &[88, 327, 67, 328], 1928);
                step(f, Op::SubV, &[325, 327, 329], 1929);
                step(f, Op::RotateVector, &[0, 395, 330], 1930);
                step(f, Op::DotV, &[329, 330, 606], 1931);
                step(f, Op::MulF, &[607, 606, 608], 1932);
                step(f, Op::QuatFromAxisAngle, &[394, 608, 73], 1933);
                step(f, Op::DivF, &[100, 698, 623], 1934);
                step(f, Op::QuatScale, &[73, 623, 74], 1935);
                step(f, Op::MulQ, &[76, 74, 80], 1936);
                step(f, Op::MakeTransform, &[341, 80, 392, 97], 1937);
                step(f, Op::SetTransform, &[40, 97, 66, 79, 694], 1938);
                step(f, Op::GetTransform, &[41, 66, 79, 94], 1939);
                step(f, Op::BreakTransform, &[94, 343, 77, 344], 1940);
                step(f, Op::LengthV, &[2, 585], 1941);
                step(f, Op::RemapF, &[585, 98, 97, 692, 99, 79, 607], 1942);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 87], 1943);
                step(f, Op::BreakTransform, &[87, 325, 66, 326], 1944);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 66, 88], 1945);
                step(f, Op::BreakTransform, &[88, 327, 67, 328], 1946);
                step(f, Op::SubV, &[325, 327, 329], 1947);
                step(f, Op::RotateVector, &[0, 395, 330], 1948);
                step(f, Op::DotV, &[329, 330, 606], 1949);
                step(f, Op::MulF, &[607, 606, 608], 1950);
                step(f, Op::QuatFromAxisAngle, &[394, 608, 73], 1951);
                step(f, Op::DivF, &[100, 698, 623], 1952);
                step(f, Op::QuatScale, &[73, 623, 74], 1953);
                step(f, Op::MulQ, &[77, 74, 81], 1954);
                step(f, Op::MakeTransform, &[343, 81, 392, 98], 1955);
                step(f, Op::SetTransform, &[42, 98, 66, 79, 694], 1956);
                step(f, Op::GetTransform, &[43, 66, 79, 95], 1957);
                step(f, Op::BreakTransform, &[95, 345, 78, 346], 1958);
                step(f, Op::LengthV, &[2, 585], 1959);
                step(f, Op::RemapF, &[585, 98, 97, 692, 99, 79, 607], 1960);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 87], 1961);
                step(f, Op::BreakTransform, &[87, 325, 66, 326], 1962);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 66, 88], 1963);
                step(f, Op::BreakTransform, &[88, 327, 67, 328], 1964);
                step(f, Op::SubV, &[325, 327, 329], 1965);
                step(f, Op::RotateVector, &[0, 395, 330], 1966);
                step(f, Op::DotV, &[329, 330, 606], 1967);
                step(f, Op::MulF, &[607, 606, 608], 1968);
                step(f, Op::QuatFromAxisAngle, &[394, 608, 73], 1969);
                step(f, Op::DivF, &[100, 698, 623], 1970);
                step(f, Op::QuatScale, &[73, 623, 74], 1971);
                step(f, Op::MulQ, &[78, 74, 82], 1972);
                step(f, Op::MakeTransform, &[345, 82, 392, 99], 1973);
                step(f, Op::SetTransform, &[44, 99, 66, 79, 694], 1974);
                step(f, Op::GetTransform, &[45, 66, 79, 96], 1975);
                step(f, Op::BreakTransform, &[96, 347, 79, 348], 1976);
                step(f, Op::LengthV, &[2, 585], 1977);
                step(f, Op::RemapF, &[585, 98, 97, 692, 99, 79, 607], 1978);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 87], 1979);
                step(f, Op::BreakTransform, &[87, 325, 66, 326], 1980);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 66, 88], 1981);
                step(f, Op::BreakTransform, &[88, 327, 67, 328], 1982);
                step(f, Op::SubV, &[325, 327, 329], 1983);
                step(f, Op::RotateVector, &[0, 395, 330], 1984);
                step(f, Op::DotV, &[329, 330, 606], 1985);
                step(f, Op::MulF, &[607, 606, 608], 1986);
                step(f, Op::QuatFromAxisAngle, &[394, 608, 73], 1987);
                step(f, Op::QuatScale, &[73, 101, 75], 1988);
                step(f, Op::MulQ, &[79, 75, 83], 1989);
                step(f, Op::MakeTransform, &[347, 83, 392, 100], 1990);
                step(f, Op::SetTransform, &[46, 100, 66, 79, 694], 1991);
                step(f, Op::Copy(ValueType::Float), &[692, 624], 1992);
                step(f, Op::Copy(ValueType::Float), &[692, 625], 1993);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1994);
                step(f, Op::Copy(ValueType::Int), &[65, 61], 1995);
                1995
            }
            1995 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 61, 25, 62, 63, 2025], 1996)
            }
            1996 => {
                step(f, Op::GetParent, &[25, 26], 1997);
                step(f, Op::GetParent, &[26, 27], 1998);
                step(f, Op::GetTransform, &[27, 65, 80, 101], 1999);
                step(f, Op::BreakTransform, &[101, 349, 84, 350], 2000);
                step(f, Op::BreakVector, &[349, 626, 627, 628], 2001);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 62, 102], 2002);
                step(f, Op::BreakTransform, &[102, 351, 85, 352], 2003);
                step(f, Op::BreakVector, &[351, 629, 630, 631], 2004);
                step(f, Op::ArrayAt(Elem::Float), &[1, 62, 635], 2005);
                step(f, Op::MulF, &[635, 106, 636], 2006);
                step(f, Op::MulF, &[636, 636, 637], 2007);
                step(f, Op::SubF, &[626, 629, 632], 2008);
                step(f, Op::SubF, &[627, 630, 633], 2009);
                step(f, Op::MakeVector, &[632, 633, 692, 353], 2010);
                step(f, Op::DotV, &[353, 353, 634], 2011);
                step(f, Op::SubF, &[637, 634, 638], 2012);
                step(f, Op::SqrtF, &[638, 639], 2013);
                step(f, Op::AddF, &[631, 639, 640], 2014);
                step(f, Op::SubF, &[628, 640, 641], 2015);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 62, 72], 2016);
                step(f, Op::ArrayAt(Elem::Float), &[2, 62, 642], 2017);
                step(f, Op::RemapF, &[642, 693, 694, 692, 694, 79, 643], 2018);
                step(f, Op::RemapF, &[642, 692, 109, 694, 692, 79, 644], 2019);
                step(f, Op::MaxF, &[643, 644, 645], 2020);
                step(f, Op::Select(ValueType::Float), &[72, 694, 645, 646], 2021);
                step(f, Op::MulF, &[641, 646, 647], 2022);
                step(f, Op::MaxF, &[625, 647, 648], 2023);
                step(f, Op::Copy(ValueType::Float), &[648, 625], 2024);
                step(f, Op::Jump, &[1995], 2025)
            }
            2025 => {
                step(f, Op::ClampF, &[625, 692, 107, 649], 2026);
                step(f, Op::Copy(ValueType::Float), &[649, 624], 2027);
                step(f, Op::Jump, &[2028], 2028)
            }
            2028 => {
                step(f, Op::MakeVector, &[15, 692, 692, 354], 2029);
                step(f, Op::MakeVector, &[624, 692, 692, 355], 2030);
                step(f, Op::MakeVector, &[16, 692, 692, 356], 2031);
                step(f, Op::GreaterF, &[624, 15, 73], 2032);
                step(f, Op::Select(ValueType::Float), &[73, 111, 108, 650], 2033);
                step(f, Op::Copy(ValueType::Vec3), &[354, 357], 2034);
                step(f, Op::Copy(ValueType::Vec3), &[355, 358], 2035);
                step(f, Op::Copy(ValueType::Vec3), &[356, 359], 2036);
                step(f, Op::Copy(ValueType::Float), &[650, 651], 2037);
                step(f, Op::Copy(ValueType::Float), &[45, 652], 2038);
                step(f, Op::Copy(ValueType::Vec3), &[391, 360], 2039);
                step(f, Op::SubV, &[358, 359, 361], 2040);
                step(f, Op::DeltaTime, &[653], 2041);
                step(f, Op::DivF, &[652, 653, 654], 2042);
                step(f, Op::ScaleV, &[361, 654, 362], 2043);
                step(f, Op::AddV, &[358, 362, 363], 2044);
                step(f, Op::AddV, &[359, 362, 364], 2045);
                step(f, Op::SubV, &[357, 364, 365], 2046);
                step(f, Op::FloatLerp, &[692, 694, 651, 655], 2047);
                step(f, Op::SubF, &[694, 655, 656], 2048);
                step(f, Op::ScaleV, &[365, 656, 366], 2049);
                step(f, Op::AddV, &[363, 366, 368], 2050);
                step(f, Op::MulF, &[651, 653, 657], 2051);
                step(f, Op::GreaterF, &[657, 692, 74], 2052);
                step(f, Op::DivF, &[655, 657, 658], 2053);
                step(f, Op::Select(ValueType::Float), &[74, 658, 694, 659], 2054);
                step(f, Op::ScaleV, &[361, 659, 367], 2055);
                step(f, Op::SubV, &[368, 367, 369], 2056);
                step(f, Op::Copy(ValueType::Vec3), &[369, 360], 2057);
                step(f, Op::Jump, &[2058], 2058)
            }
            2058 => {
                step(f, Op::BreakVector, &[360, 660, 661, 662], 2059);
                step(f, Op::Select(ValueType::Float), &[1, 624, 660, 663], 2060);
                step(f, Op::Copy(ValueType::Float), &[663, 15], 2061);
                step(f, Op::Copy(ValueType::Float), &[624, 16], 2062);
                step(f, Op::GetTransform, &[47, 65, 80, 103], 2063);
                step(f, Op::BreakTransform, &[103, 370, 86, 371], 2064);
                step(f, Op::MakeVector, &[692, 692, 15, 372], 2065);
                step(f, Op::SubV, &[370, 372, 373], 2066);
                step(f, Op::MakeTransform, &[373, 86, 392, 104], 2067);
                step(f, Op::SetTransform, &[48, 104, 65, 79, 694], 2068);
                step(f, Op::JumpIfFalse, &[8, 2076], 2069)
            }
            2069 => {
                step(f, Op::GetTransform, &[47, 65, 80, 103], 2070);
                step(f, Op::BreakTransform, &[103, 370, 86, 371], 2071);
                step(f, Op::MakeVector, &[692, 692, 15, 372], 2072);
                step(f, Op::SubV, &[370, 372, 373], 2073);
                step(f, Op::MakeTransform, &[373, 86, 392, 104], 2074);
                step(f, Op::DrawTransform, &[104, 711, 693], 2075);
                step(f, Op::Jump, &[2076], 2076)
            }
            2076 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 2077);
                step(f, Op::Copy(ValueType::Int), &[65, 8], 2078);
                2078
            }
            2078 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 8, 2, 9, 10, 2143], 2079)
            }
            2079 => {
                step(f, Op::Copy(ValueType::Bone), &[2, 28], 2080);
                step(f, Op::Copy(ValueType::Int), &[9, 64], 2081);
                step(f, Op::GetParent, &[28, 29], 2082);
                step(f, Op::GetParent, &[29, 30], 2083);
                step(f, Op::GetTransform, &[30, 65, 80, 105], 2084);
                step(f, Op::BreakTransform, &[105, 374, 87, 375], 2085);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 64, 106], 2086);
                step(f, Op::BreakTransform, &[106, 376, 88, 377], 2087);
                step(f, Op::SubV, &[376, 374, 378], 2088);
                step(f, Op::LengthV, &[378, 682], 2089);
                step(f, Op::ArrayAt(Elem::Float), &[1, 64, 664], 2090);
                step(f, Op::MulF, &[664, 117, 665], 2091);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 64, 75], 2092);
                step(f, Op::ArrayAt(Elem::Float), &[2, 64, 666], 2093);
                step(f, Op::ClampF, &[666, 692, 694, 667], 2094);
                step(f, Op::LessF, &[667, 693, 76], 2095);
                step(f, Op::RemapF, &[667, 119, 120, 692, 694, 79, 670], 2096);
                step(f, Op::Copy(ValueType::Float), &[670, 671], 2097);
                step(f, Op::Copy(ValueType::Float), &[692, 672], 2098);
                step(f, Op::ClampF, &[671, 692, 694, 673], 2099);
                step(f, Op::MulF, &[673, 673, 674], 2100);
                step(f, Op::MulF, &[673, 697, 675], 2101);
                step(f, Op::SubF, &[698, 675, 676], 2102);
                step(f, Op::MulF, &[674, 676, 677], 2103);
                step(f, Op::Copy(ValueType::Float), &[677, 672], 2104);
                step(f, Op::Jump, &[2105], 2105)
            }
            2105 => {
                step(f, Op::MulF, &[667, 706, 668], 2106);
                step(f, Op::SinF, &[668, 669], 2107);
                step(f, Op::MaxF, &[672, 669, 678], 2108);
                step(f, Op::Select(ValueType::Float), &[76, 678, 669, 679], 2109);
                step(f, Op::MulF, &[679, 118, 680], 2110);
                step(f, Op::Select(ValueType::Float), &[75, 692, 680, 681], 2111);
                step(f, Op::SubF, &[665, 681, 683], 2112);
                step(f, Op::SubF, &[682, 683, 684], 2113);
                step(f, Op::MaxF, &[684, 692, 685], 2114);
                step(f, Op::MulF, &[685, 685, 686], 2115);
                step(f, Op::AddF, &[685, 681, 687], 2116);
                step(f, Op::DivF, &[686, 687, 688], 2117);
                step(f, Op::SubF, &[682, 688, 689], 2118);
                step(f, Op::DivF, &[689, 682, 690], 2119);
                step(f, Op::ScaleV, &[378, 690, 379], 2120);
                step(f, Op::AddV, &[374, 379, 380], 2121);
                step(f, Op::ClampSpatially, &[380, 374, 692, 665, 381], 2122);
                step(f, Op::MakeTransform, &[381, 88, 392, 107], 2123);
                step(f, Op::Equals(Elem::Int), &[64, 65, 77], 2124);
                step(f, Op::Select(ValueType::Vec3), &[77, 398, 397, 386], 2125);
                step(f, Op::Select(ValueType::Vec3), &[77, 395, 399, 387], 2126);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 64, 108], 2127);
                step(f, Op::BreakTransform, &[108, 382, 89, 383], 2128);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 64, 384], 2129);
                step(f, Op::KneeVector, &[89, 0, 384, 121, 122, 385], 2130);
                step(f, Op::TwoBoneIK, &[30, 29, 28, 107, 386, 387, 385, 65, 694, 80, 708, 709, 79, 78, 691], 2131);
                step(f, Op::JumpIfFalse, &[8, 2142], 2132)
            }
            2132 => {
                step(f, Op::GetParent, &[28, 29], 2133);
                step(f, Op::GetTransform, &[29, 65, 80, 109], 2134);
                step(f, Op::BreakTransform, &[109, 388, 90, 389], 2135);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 64, 108], 2136);
                step(f, Op::BreakTransform, &[108, 382, 89, 383], 2137);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 64, 384], 2138);
                step(f, Op::KneeVector, &[89, 0, 384, 121, 122, 385], 2139);
                step(f, Op::AddV, &[388, 385, 390], 2140);
                step(f, Op::DrawLine, &[388, 390, 693, 400], 2141);
                step(f, Op::Jump, &[2142], 2142)
            }
            2142 => {
                step(f, Op::Jump, &[2078], 2143)
            }
            2143 => {
                step(f, Op::End, &[], 2144)
            }
            _ => return,
        } };
    }
}
