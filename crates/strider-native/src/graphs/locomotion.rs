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
    fingerprint: 0x1a2fc6872d0642f9,
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
                step(f, Op::BreakTransform, &[12, 33, 7, 34], 457);
                step(f, Op::Select(ValueType::Transform), &[0, 0, 12, 13], 458);
                step(f, Op::BreakTransform, &[13, 35, 8, 36], 459);
                step(f, Op::SubV, &[33, 35, 37], 460);
                step(f, Op::LengthV, &[37, 136], 461);
                step(f, Op::GreaterF, &[136, 33, 10], 462);
                step(f, Op::Copy(ValueType::Bool), &[10, 2], 463);
                step(f, Op::MakeRelative, &[13, 12, 17], 464);
                step(f, Op::Select(ValueType::Transform), &[10, 111, 17, 18], 465);
                step(f, Op::Copy(ValueType::Transform), &[18, 2], 466);
                step(f, Op::InverseT, &[13, 15], 467);
                step(f, Op::MulT, &[12, 15, 16], 468);
                step(f, Op::Copy(ValueType::Transform), &[16, 1], 469);
                step(f, Op::TransformVector, &[2, 0, 42], 470);
                step(f, Op::InverseT, &[12, 14], 471);
                step(f, Op::DeltaTime, &[135], 472);
                step(f, Op::DivF, &[806, 135, 137], 473);
                step(f, Op::ScaleV, &[37, 137, 38], 474);
                step(f, Op::TransformVector, &[14, 38, 39], 475);
                step(f, Op::BreakVector, &[39, 138, 139, 140], 476);
                step(f, Op::MakeVector, &[138, 139, 804, 40], 477);
                step(f, Op::LengthV, &[40, 141], 478);
                step(f, Op::MulF, &[141, 118, 142], 479);
                step(f, Op::NegF, &[142, 143], 480);
                step(f, Op::ClampF, &[140, 143, 142, 144], 481);
                step(f, Op::MakeVector, &[138, 139, 144, 41], 482);
                step(f, Op::Select(ValueType::Vec3), &[2, 42, 41, 44], 483);
                step(f, Op::VectorLerp, &[42, 44, 34, 804, 45], 484);
                step(f, Op::Copy(ValueType::Vec3), &[45, 0], 485);
                step(f, Op::TransformVector, &[2, 1, 43], 486);
                step(f, Op::TransformVector, &[2, 0, 42], 487);
                step(f, Op::Select(ValueType::Vec3), &[2, 42, 41, 44], 488);
                step(f, Op::VectorLerp, &[43, 44, 35, 804, 46], 489);
                step(f, Op::Copy(ValueType::Vec3), &[46, 1], 490);
                step(f, Op::LengthV, &[44, 151], 491);
                step(f, Op::Copy(ValueType::Float), &[151, 0], 492);
                step(f, Op::BreakVector, &[37, 145, 146, 147], 493);
                step(f, Op::MulF, &[144, 135, 148], 494);
                step(f, Op::SubF, &[147, 148, 149], 495);
                step(f, Op::Select(ValueType::Float), &[10, 804, 149, 150], 496);
                step(f, Op::Copy(ValueType::Float), &[150, 1], 497);
                step(f, Op::JumpIfFalse, &[2, 516], 498)
            }
            498 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 12], 499);
                step(f, Op::Copy(ValueType::Int), &[72, 17], 500);
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
                step(f, Op::Copy(ValueType::Float), &[804, 14], 515);
                step(f, Op::Jump, &[516], 516)
            }
            516 => {
                step(f, Op::WorldTransform, &[12], 517);
                step(f, Op::Copy(ValueType::Transform), &[12, 0], 518);
                step(f, Op::Copy(ValueType::Bool), &[98, 0], 519);
                step(f, Op::JumpIfFalse, &[8, 526], 520)
            }
            520 => {
                step(f, Op::GetTransform, &[34, 72, 98, 19], 521);
                step(f, Op::BreakTransform, &[19, 47, 9, 48], 522);
                step(f, Op::ScaleV, &[0, 807, 49], 523);
                step(f, Op::AddV, &[47, 49, 50], 524);
                step(f, Op::DrawArrow, &[47, 50, 805, 422], 525);
                step(f, Op::Jump, &[526], 526)
            }
            526 => {
                step(f, Op::Copy(ValueType::Float), &[804, 152], 527);
                step(f, Op::Copy(ValueType::Float), &[806, 153], 528);
                step(f, Op::Copy(ValueType::Float), &[806, 154], 529);
                step(f, Op::Copy(ValueType::Bool), &[99, 11], 530);
                step(f, Op::Copy(ValueType::Bool), &[99, 12], 531);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[7, 8], 532);
                step(f, Op::Copy(ValueType::Int), &[72, 25], 533);
                step(f, Op::MakeVector, &[804, 804, 53, 55], 534);
                534
            }
            534 => {
                step(f, Op::ForEachNext(Elem::Transform), &[8, 25, 21, 26, 27, 545], 535)
            }
            535 => {
                step(f, Op::BreakTransform, &[21, 51, 10, 52], 536);
                step(f, Op::TransformPoint, &[2, 51, 53], 537);
                step(f, Op::LerpV, &[53, 51, 154, 54], 538);
                step(f, Op::AddV, &[54, 55, 56], 539);
                step(f, Op::SubV, &[54, 55, 57], 540);
                step(f, Op::LineTrace, &[56, 57, 13, 58, 59, 155], 541);
                step(f, Op::JumpIfFalse, &[13, 544], 542)
            }
            542 => {
                step(f, Op::Copy(ValueType::Bool), &[98, 12], 543);
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
                step(f, Op::Copy(ValueType::Int), &[72, 20], 554);
                554
            }
            554 => {
                step(f, Op::ForNext, &[20, 24, 22, 582], 555)
            }
            555 => {
                step(f, Op::AddF, &[152, 153, 156], 556);
                step(f, Op::MulF, &[156, 805, 157], 557);
                step(f, Op::Copy(ValueType::Float), &[157, 158], 558);
                step(f, Op::Copy(ValueType::Bool), &[99, 17], 559);
                step(f, Op::Copy(ValueType::Bool), &[99, 18], 560);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[7, 9], 561);
                step(f, Op::Copy(ValueType::Int), &[72, 28], 562);
                step(f, Op::MakeVector, &[804, 804, 53, 64], 563);
                563
            }
            563 => {
                step(f, Op::ForEachNext(Elem::Transform), &[9, 28, 22, 29, 30, 574], 564)
            }
            564 => {
                step(f, Op::BreakTransform, &[22, 60, 11, 61], 565);
                step(f, Op::TransformPoint, &[2, 60, 62], 566);
                step(f, Op::LerpV, &[62, 60, 158, 63], 567);
                step(f, Op::AddV, &[63, 64, 65], 568);
                step(f, Op::SubV, &[63, 64, 66], 569);
                step(f, Op::LineTrace, &[65, 66, 19, 67, 68, 159], 570);
                step(f, Op::JumpIfFalse, &[19, 573], 571)
            }
            571 => {
                step(f, Op::Copy(ValueType::Bool), &[98, 18], 572);
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
                step(f, Op::Copy(ValueType::Float), &[157, 152], 579);
                step(f, Op::Jump, &[581], 580)
            }
            580 => {
                step(f, Op::Copy(ValueType::Float), &[157, 153], 581);
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
                step(f, Op::Select(ValueType::Float), &[5, 808, 806, 165], 585);
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 586);
                step(f, Op::AddF, &[152, 153, 156], 587);
                step(f, Op::MulF, &[156, 805, 160], 588);
                step(f, Op::Select(ValueType::Float), &[16, 160, 805, 161], 589);
                step(f, Op::Select(ValueType::Float), &[15, 161, 804, 167], 590);
                step(f, Op::MulF, &[165, 167, 169], 591);
                step(f, Op::DeltaTime, &[163], 592);
                step(f, Op::DivF, &[163, 121, 164], 593);
                step(f, Op::MulF, &[169, 164, 170], 594);
                step(f, Op::AddF, &[18, 170, 171], 595);
                step(f, Op::ClampF, &[171, 804, 806, 172], 596);
                step(f, Op::Select(ValueType::Float), &[14, 808, 806, 166], 597);
                step(f, Op::SubF, &[806, 161, 162], 598);
                step(f, Op::Select(ValueType::Float), &[15, 162, 806, 168], 599);
                step(f, Op::MulF, &[166, 168, 173], 600);
                step(f, Op::MulF, &[173, 164, 174], 601);
                step(f, Op::AddF, &[172, 174, 175], 602);
                step(f, Op::ClampF, &[175, 804, 806, 176], 603);
                step(f, Op::MulF, &[176, 176, 177], 604);
                step(f, Op::MulF, &[176, 809, 178], 605);
                step(f, Op::SubF, &[810, 178, 179], 606);
                step(f, Op::MulF, &[177, 179, 180], 607);
                step(f, Op::AddF, &[19, 180, 181], 608);
                step(f, Op::MulF, &[181, 805, 182], 609);
                step(f, Op::SubF, &[806, 182, 183], 610);
                step(f, Op::MulF, &[183, 183, 184], 611);
                step(f, Op::SubF, &[806, 184, 185], 612);
                step(f, Op::Copy(ValueType::Float), &[185, 20], 613);
                step(f, Op::Copy(ValueType::Float), &[180, 19], 614);
                step(f, Op::Copy(ValueType::Float), &[176, 18], 615);
                step(f, Op::GreaterF, &[19, 804, 21], 616);
                step(f, Op::TransformVector, &[2, 3, 69], 617);
                step(f, Op::Select(ValueType::Vec3), &[21, 69, 0, 70], 618);
                step(f, Op::Copy(ValueType::Vec3), &[70, 3], 619);
                step(f, Op::LerpV, &[0, 3, 19, 71], 620);
                step(f, Op::Select(ValueType::Vec3), &[21, 71, 0, 72], 621);
                step(f, Op::Copy(ValueType::Vec3), &[72, 2], 622);
                step(f, Op::Copy(ValueType::Bool), &[14, 5], 623);
                step(f, Op::Copy(ValueType::Bool), &[11, 6], 624);
                step(f, Op::Copy(ValueType::Bool), &[99, 7], 625);
                step(f, Op::SubF, &[806, 20, 186], 626);
                step(f, Op::MulF, &[1, 186, 187], 627);
                step(f, Op::AddF, &[2, 187, 188], 628);
                step(f, Op::SpringF, &[188, 119, 191, 31, 189, 190], 629);
                step(f, Op::SubF, &[188, 191, 192], 630);
                step(f, Op::Copy(ValueType::Float), &[192, 3], 631);
                step(f, Op::Copy(ValueType::Float), &[188, 2], 632);
                step(f, Op::LengthV, &[4, 194], 633);
                step(f, Op::GreaterF, &[194, 27, 22], 634);
                step(f, Op::LengthV, &[2, 195], 635);
                step(f, Op::GreaterF, &[195, 27, 23], 636);
                step(f, Op::And, &[22, 23, 25], 637);
                step(f, Op::Select(ValueType::Vec3), &[22, 4, 420, 73], 638);
                step(f, Op::MovementAngleOffset, &[73, 12, 804, 811, 811, 812, 38, 813, 196], 639);
                step(f, Op::Copy(ValueType::Float), &[196, 198], 640);
                step(f, Op::Copy(ValueType::Float), &[12, 199], 641);
                step(f, Op::Copy(ValueType::Float), &[804, 200], 642);
                step(f, Op::SubF, &[198, 199, 201], 643);
                step(f, Op::AddF, &[201, 814, 202], 644);
                step(f, Op::DivF, &[202, 815, 203], 645);
                step(f, Op::FractF, &[203, 204], 646);
                step(f, Op::MulF, &[204, 815, 205], 647);
                step(f, Op::SubF, &[205, 814, 206], 648);
                step(f, Op::Copy(ValueType::Float), &[206, 200], 649);
                step(f, Op::Jump, &[650], 650)
            }
            650 => {
                step(f, Op::AbsF, &[200, 225], 651);
                step(f, Op::Select(ValueType::Vec3), &[23, 2, 420, 74], 652);
                step(f, Op::MovementAngleOffset, &[74, 12, 804, 811, 811, 812, 38, 813, 197], 653);
                step(f, Op::Copy(ValueType::Float), &[197, 207], 654);
                step(f, Op::Copy(ValueType::Float), &[12, 208], 655);
                step(f, Op::Copy(ValueType::Float), &[804, 209], 656);
                step(f, Op::SubF, &[207, 208, 210], 657);
                step(f, Op::AddF, &[210, 814, 211], 658);
                step(f, Op::DivF, &[211, 815, 212], 659);
                step(f, Op::FractF, &[212, 213], 660);
                step(f, Op::MulF, &[213, 815, 214], 661);
                step(f, Op::SubF, &[214, 814, 215], 662);
                step(f, Op::Copy(ValueType::Float), &[215, 209], 663);
                step(f, Op::Jump, &[664], 664)
            }
            664 => {
                step(f, Op::AbsF, &[209, 226], 665);
                step(f, Op::MaxF, &[225, 226, 228], 666);
                step(f, Op::Copy(ValueType::Float), &[197, 216], 667);
                step(f, Op::Copy(ValueType::Float), &[196, 217], 668);
                step(f, Op::Copy(ValueType::Float), &[804, 218], 669);
                step(f, Op::SubF, &[216, 217, 219], 670);
                step(f, Op::AddF, &[219, 814, 220], 671);
                step(f, Op::DivF, &[220, 815, 221], 672);
                step(f, Op::FractF, &[221, 222], 673);
                step(f, Op::MulF, &[222, 815, 223], 674);
                step(f, Op::SubF, &[223, 814, 224], 675);
                step(f, Op::Copy(ValueType::Float), &[224, 218], 676);
                step(f, Op::Jump, &[677], 677)
            }
            677 => {
                step(f, Op::AbsF, &[218, 227], 678);
                step(f, Op::MaxF, &[228, 227, 229], 679);
                step(f, Op::LessF, &[229, 816, 24], 680);
                step(f, Op::And, &[25, 24, 26], 681);
                step(f, Op::Not, &[22, 27], 682);
                step(f, Op::Not, &[23, 28], 683);
                step(f, Op::And, &[27, 28, 29], 684);
                step(f, Op::Or, &[26, 29, 30], 685);
                step(f, Op::JumpIfFalse, &[30, 707], 686)
            }
            686 => {
                step(f, Op::DeltaTime, &[193], 687);
                step(f, Op::MulF, &[36, 193, 233], 688);
                step(f, Op::GreaterF, &[233, 804, 31], 689);
                step(f, Op::DivF, &[47, 193, 230], 690);
                step(f, Op::FloatLerp, &[804, 806, 36, 231], 691);
                step(f, Op::SubF, &[806, 231, 232], 692);
                step(f, Op::DivF, &[232, 231, 234], 693);
                step(f, Op::DivF, &[806, 233, 235], 694);
                step(f, Op::SubF, &[234, 235, 236], 695);
                step(f, Op::AddF, &[230, 236, 237], 696);
                step(f, Op::Select(ValueType::Float), &[31, 237, 804, 238], 697);
                step(f, Op::MulF, &[218, 238, 239], 698);
                step(f, Op::AddF, &[197, 239, 240], 699);
                step(f, Op::SinF, &[240, 241], 700);
                step(f, Op::NegF, &[241, 242], 701);
                step(f, Op::CosF, &[240, 243], 702);
                step(f, Op::MakeVector, &[242, 243, 804, 75], 703);
                step(f, Op::Select(ValueType::Vec3), &[23, 75, 420, 76], 704);
                step(f, Op::MovementAngleOffset, &[76, 12, 804, 36, 37, 812, 814, 813, 244], 705);
                step(f, Op::Copy(ValueType::Float), &[244, 12], 706);
                step(f, Op::Jump, &[742], 707)
            }
            707 => {
                step(f, Op::DeltaTime, &[193], 708);
                step(f, Op::DivF, &[193, 39, 245], 709);
                step(f, Op::AddF, &[245, 805, 246], 710);
                step(f, Op::FloorF, &[246, 247], 711);
                step(f, Op::MaxF, &[247, 806, 248], 712);
                step(f, Op::ToInt, &[248, 37], 713);
                step(f, Op::Copy(ValueType::Int), &[37, 36], 714);
                step(f, Op::Copy(ValueType::Int), &[72, 32], 715);
                step(f, Op::MulF, &[39, 805, 252], 716);
                step(f, Op::SubF, &[47, 252, 253], 717);
                step(f, Op::DivF, &[253, 193, 254], 718);
                step(f, Op::FloatLerp, &[804, 806, 34, 256], 719);
                step(f, Op::GreaterF, &[256, 804, 32], 720);
                step(f, Op::DivF, &[36, 248, 266], 721);
                step(f, Op::DivF, &[37, 248, 267], 722);
                722
            }
            722 => {
                step(f, Op::ForNext, &[32, 36, 34, 742], 723)
            }
            723 => {
                step(f, Op::ToFloat, &[34, 249], 724);
                step(f, Op::AddF, &[249, 806, 250], 725);
                step(f, Op::DivF, &[250, 248, 251], 726);
                step(f, Op::AddF, &[251, 254, 255], 727);
                step(f, Op::MulF, &[34, 255, 257], 728);
                step(f, Op::FloatLerp, &[804, 806, 257, 258], 729);
                step(f, Op::DivF, &[258, 256, 259], 730);
                step(f, Op::Select(ValueType::Float), &[32, 259, 255, 260], 731);
                step(f, Op::LerpV, &[4, 2, 260, 77], 732);
                step(f, Op::LengthV, &[77, 261], 733);
                step(f, Op::GreaterF, &[261, 27, 33], 734);
                step(f, Op::Select(ValueType::Vec3), &[33, 77, 420, 78], 735);
                step(f, Op::MulF, &[193, 255, 262], 736);
                step(f, Op::MulF, &[6, 262, 263], 737);
                step(f, Op::AddF, &[10, 263, 264], 738);
                step(f, Op::FractF, &[264, 265], 739);
                step(f, Op::MovementAngleOffset, &[78, 12, 265, 266, 267, 812, 38, 813, 268], 740);
                step(f, Op::Copy(ValueType::Float), &[268, 12], 741);
                step(f, Op::Jump, &[722], 742)
            }
            742 => {
                step(f, Op::QuatFromAxisAngle, &[423, 12, 12], 743);
                step(f, Op::Copy(ValueType::Quat), &[12, 0], 744);
                step(f, Op::SinF, &[12, 269], 745);
                step(f, Op::AbsF, &[269, 270], 746);
                step(f, Op::RemapF, &[270, 40, 41, 804, 806, 98, 271], 747);
                step(f, Op::Copy(ValueType::Float), &[271, 13], 748);
                step(f, Op::Copy(ValueType::Vec3), &[2, 4], 749);
                step(f, Op::Copy(ValueType::Bool), &[99, 35], 750);
                step(f, Op::Copy(ValueType::Bool), &[98, 36], 751);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 752);
                step(f, Op::Copy(ValueType::Int), &[72, 41], 753);
                753
            }
            753 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 41, 37, 42, 43, 759], 754)
            }
            754 => {
                step(f, Op::Not, &[37, 38], 755);
                step(f, Op::JumpIfFalse, &[38, 758], 756)
            }
            756 => {
                step(f, Op::Copy(ValueType::Bool), &[99, 36], 757);
                step(f, Op::Jump, &[758], 758)
            }
            758 => {
                step(f, Op::Jump, &[753], 759)
            }
            759 => {
                step(f, Op::Copy(ValueType::Bool), &[36, 35], 760);
                step(f, Op::Jump, &[761], 761)
            }
            761 => {
                step(f, Op::Copy(ValueType::Bool), &[99, 39], 762);
                step(f, Op::Copy(ValueType::Bool), &[98, 40], 763);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 764);
                step(f, Op::Copy(ValueType::Int), &[72, 44], 765);
                765
            }
            765 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 44, 15, 45, 46, 780], 766)
            }
            766 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 45, 23], 767);
                step(f, Op::BreakTransform, &[23, 79, 13, 80], 768);
                step(f, Op::BreakVector, &[79, 280, 281, 282], 769);
                step(f, Op::MakeVector, &[280, 281, 804, 83], 770);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 45, 24], 771);
                step(f, Op::BreakTransform, &[24, 81, 14, 82], 772);
                step(f, Op::BreakVector, &[81, 283, 284, 285], 773);
                step(f, Op::MakeVector, &[283, 284, 804, 84], 774);
                step(f, Op::DistanceV, &[83, 84, 286], 775);
                step(f, Op::GreaterF, &[286, 29, 41], 776);
                step(f, Op::JumpIfFalse, &[41, 779], 777)
            }
            777 => {
                step(f, Op::Copy(ValueType::Bool), &[99, 40], 778);
                step(f, Op::Jump, &[779], 779)
            }
            779 => {
                step(f, Op::Jump, &[765], 780)
            }
            780 => {
                step(f, Op::Copy(ValueType::Bool), &[40, 39], 781);
                step(f, Op::Jump, &[782], 782)
            }
            782 => {
                step(f, Op::And, &[35, 39, 42], 783);
                step(f, Op::LengthV, &[2, 272], 784);
                step(f, Op::GreaterF, &[272, 27, 34], 785);
                step(f, Op::GreaterF, &[0, 27, 43], 786);
                step(f, Op::Or, &[34, 43, 44], 787);
                step(f, Op::Not, &[44, 45], 788);
                step(f, Op::And, &[42, 45, 50], 789);
                step(f, Op::DeltaTime, &[311], 790);
                step(f, Op::MulF, &[311, 32, 312], 791);
                step(f, Op::AddF, &[10, 312, 313], 792);
                step(f, Op::GreaterF, &[10, 805, 51], 793);
                step(f, Op::AddF, &[31, 805, 309], 794);
                step(f, Op::Select(ValueType::Float), &[51, 309, 31, 310], 795);
                step(f, Op::MinF, &[313, 310, 314], 796);
                step(f, Op::NotEquals(Elem::Bool), &[45, 4, 46], 797);
                step(f, Op::Not, &[42, 47], 798);
                step(f, Op::And, &[46, 47, 48], 799);
                step(f, Op::SubF, &[11, 27, 295], 800);
                step(f, Op::SubF, &[11, 272, 296], 801);
                step(f, Op::DivF, &[295, 296, 297], 802);
                step(f, Op::ClampF, &[297, 804, 806, 298], 803);
                step(f, Op::MulF, &[6, 298, 300], 804);
                step(f, Op::RemapF, &[272, 27, 28, 804, 806, 98, 287], 805);
                step(f, Op::MaxF, &[287, 7, 288], 806);
                step(f, Op::Select(ValueType::Float), &[35, 806, 288, 289], 807);
                step(f, Op::Select(ValueType::Float), &[45, 30, 289, 290], 808);
                step(f, Op::Select(ValueType::Float), &[42, 287, 290, 291], 809);
                step(f, Op::SubF, &[806, 19, 292], 810);
                step(f, Op::MulF, &[291, 292, 293], 811);
                step(f, Op::LerpF, &[21, 43, 13, 275], 812);
                step(f, Op::RemapF, &[272, 24, 25, 22, 23, 98, 273], 813);
                step(f, Op::LerpF, &[273, 42, 13, 274], 814);
                step(f, Op::MaxF, &[272, 26, 276], 815);
                step(f, Op::DivF, &[274, 276, 277], 816);
                step(f, Op::AddF, &[275, 277, 278], 817);
                step(f, Op::DivF, &[293, 278, 294], 818);
                step(f, Op::SubF, &[806, 298, 299], 819);
                step(f, Op::MulF, &[294, 299, 301], 820);
                step(f, Op::AddF, &[300, 301, 302], 821);
                step(f, Op::MulF, &[302, 809, 303], 822);
                step(f, Op::AddF, &[6, 294, 304], 823);
                step(f, Op::Select(ValueType::Float), &[48, 303, 304, 305], 824);
                step(f, Op::DivF, &[809, 305, 306], 825);
                step(f, Op::GreaterF, &[305, 804, 49], 826);
                step(f, Op::CycleStep, &[10, 306, 804, 49, 307, 308], 827);
                step(f, Op::Select(ValueType::Float), &[50, 314, 307, 315], 828);
                step(f, Op::Copy(ValueType::Float), &[315, 10], 829);
                step(f, Op::Copy(ValueType::Float), &[294, 6], 830);
                step(f, Op::Copy(ValueType::Bool), &[34, 3], 831);
                step(f, Op::Copy(ValueType::Float), &[277, 4], 832);
                step(f, Op::Copy(ValueType::Float), &[278, 5], 833);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 834);
                step(f, Op::Copy(ValueType::Int), &[72, 38], 835);
                835
            }
            835 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 38, 14, 39, 40, 1009], 836)
            }
            836 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 39, 329], 837);
                step(f, Op::ToFloat, &[39, 316], 838);
                step(f, Op::MulF, &[316, 805, 317], 839);
                step(f, Op::AddF, &[10, 317, 318], 840);
                step(f, Op::FractF, &[318, 319], 841);
                step(f, Op::SubF, &[329, 319, 331], 842);
                step(f, Op::GreaterF, &[331, 805, 52], 843);
                step(f, Op::ArrayAt(Elem::Float), &[2, 39, 330], 844);
                step(f, Op::Select(ValueType::Float), &[52, 804, 330, 358], 845);
                step(f, Op::ArraySetAt(Elem::Float), &[3, 39, 358], 846);
                step(f, Op::ArrayAt(Elem::Float), &[0, 39, 329], 847);
                step(f, Op::ToFloat, &[39, 316], 848);
                step(f, Op::MulF, &[316, 805, 317], 849);
                step(f, Op::AddF, &[10, 317, 318], 850);
                step(f, Op::FractF, &[318, 319], 851);
                step(f, Op::SubF, &[329, 319, 331], 852);
                step(f, Op::GreaterF, &[331, 805, 52], 853);
                step(f, Op::SubF, &[806, 329, 352], 854);
                step(f, Op::AddF, &[319, 352, 353], 855);
                step(f, Op::DivF, &[319, 353, 354], 856);
                step(f, Op::LengthV, &[2, 272], 857);
                step(f, Op::GreaterF, &[272, 27, 34], 858);
                step(f, Op::GreaterF, &[0, 27, 43], 859);
                step(f, Op::Or, &[34, 43, 44], 860);
                step(f, Op::Not, &[44, 45], 861);
                step(f, Op::NotEquals(Elem::Bool), &[45, 4, 46], 862);
                step(f, Op::Copy(ValueType::Bool), &[99, 35], 863);
                step(f, Op::Copy(ValueType::Bool), &[98, 36], 864);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 865);
                step(f, Op::Copy(ValueType::Int), &[72, 41], 866);
                866
            }
            866 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 41, 37, 42, 43, 872], 867)
            }
            867 => {
                step(f, Op::Not, &[37, 38], 868);
                step(f, Op::JumpIfFalse, &[38, 871], 869)
            }
            869 => {
                step(f, Op::Copy(ValueType::Bool), &[99, 36], 870);
                step(f, Op::Jump, &[871], 871)
            }
            871 => {
                step(f, Op::Jump, &[866], 872)
            }
            872 => {
                step(f, Op::Copy(ValueType::Bool), &[36, 35], 873);
                step(f, Op::Jump, &[874], 874)
            }
            874 => {
                step(f, Op::Copy(ValueType::Bool), &[99, 39], 875);
                step(f, Op::Copy(ValueType::Bool), &[98, 40], 876);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 877);
                step(f, Op::Copy(ValueType::Int), &[72, 44], 878);
                878
            }
            878 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 44, 15, 45, 46, 893], 879)
            }
            879 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 45, 23], 880);
                step(f, Op::BreakTransform, &[23, 79, 13, 80], 881);
                step(f, Op::BreakVector, &[79, 280, 281, 282], 882);
                step(f, Op::MakeVector, &[280, 281, 804, 83], 883);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 45, 24], 884);
                step(f, Op::BreakTransform, &[24, 81, 14, 82], 885);
                step(f, Op::BreakVector, &[81, 283, 284, 285], 886);
                step(f, Op::MakeVector, &[283, 284, 804, 84], 887);
                step(f, Op::DistanceV, &[83, 84, 286], 888);
                step(f, Op::GreaterF, &[286, 29, 41], 889);
                step(f, Op::JumpIfFalse, &[41, 892], 890)
            }
            890 => {
                step(f, Op::Copy(ValueType::Bool), &[99, 40], 891);
                step(f, Op::Jump, &[892], 892)
            }
            892 => {
                step(f, Op::Jump, &[878], 893)
            }
            893 => {
                step(f, Op::Copy(ValueType::Bool), &[40, 39], 894);
                step(f, Op::Jump, &[895], 895)
            }
            895 => {
                step(f, Op::And, &[35, 39, 42], 896);
                step(f, Op::Not, &[42, 47], 897);
                step(f, Op::And, &[46, 47, 48], 898);
                step(f, Op::SubF, &[11, 27, 295], 899);
                step(f, Op::SubF, &[11, 272, 296], 900);
                step(f, Op::DivF, &[295, 296, 297], 901);
                step(f, Op::ClampF, &[297, 804, 806, 298], 902);
                step(f, Op::MulF, &[9, 298, 321], 903);
                step(f, Op::RemapF, &[272, 27, 28, 804, 806, 98, 287], 904);
                step(f, Op::MaxF, &[287, 7, 288], 905);
                step(f, Op::Select(ValueType::Float), &[35, 806, 288, 289], 906);
                step(f, Op::Select(ValueType::Float), &[45, 30, 289, 290], 907);
                step(f, Op::Select(ValueType::Float), &[42, 287, 290, 291], 908);
                step(f, Op::SubF, &[806, 19, 292], 909);
                step(f, Op::MulF, &[291, 292, 293], 910);
                step(f, Op::LerpF, &[21, 43, 13, 275], 911);
                step(f, Op::DivF, &[293, 275, 320], 912);
                step(f, Op::SubF, &[806, 298, 299], 913);
                step(f, Op::MulF, &[320, 299, 322], 914);
                step(f, Op::AddF, &[321, 322, 323], 915);
                step(f, Op::MulF, &[323, 809, 324], 916);
                step(f, Op::AddF, &[9, 320, 325], 917);
                step(f, Op::Select(ValueType::Float), &[48, 324, 325, 326], 918);
                step(f, Op::DeltaTime, &[311], 919);
                step(f, Op::MulF, &[311, 805, 327], 920);
                step(f, Op::MulF, &[326, 327, 328], 921);
                step(f, Op::MulF, &[354, 328, 355], 922);
                step(f, Op::ArrayAt(Elem::Float), &[2, 39, 330], 923);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 39, 53], 924);
                step(f, Op::RemapF, &[272, 24, 25, 22, 23, 98, 273], 925);
                step(f, Op::LerpF, &[273, 42, 13, 274], 926);
                step(f, Op::MaxF, &[272, 26, 276], 927);
                step(f, Op::DivF, &[274, 276, 277], 928);
                step(f, Op::AddF, &[275, 277, 278], 929);
                step(f, Op::DivF, &[275, 278, 279], 930);
                step(f, Op::SubF, &[279, 8, 332], 931);
                step(f, Op::MaxF, &[332, 804, 333], 932);
                step(f, Op::DivF, &[333, 279, 334], 933);
                step(f, Op::SubF, &[806, 13, 336], 934);
                step(f, Op::MulF, &[334, 336, 343], 935);
                step(f, Op::MulF, &[343, 292, 344], 936);
                step(f, Op::MulF, &[344, 116, 345], 937);
                step(f, Op::DivF, &[47, 311, 341], 938);
                step(f, Op::SubF, &[805, 341, 342], 939);
                step(f, Op::MulF, &[345, 342, 346], 940);
                step(f, Op::SubF, &[806, 346, 347], 941);
                step(f, Op::MulF, &[328, 347, 348], 942);
                step(f, Op::Select(ValueType::Float), &[53, 328, 348, 349], 943);
                step(f, Op::MulF, &[334, 330, 335], 944);
                step(f, Op::MulF, &[335, 336, 337], 945);
                step(f, Op::MulF, &[337, 292, 338], 946);
                step(f, Op::MulF, &[338, 116, 339], 947);
                step(f, Op::Select(ValueType::Float), &[53, 804, 339, 340], 948);
                step(f, Op::SubF, &[349, 340, 350], 949);
                step(f, Op::AddF, &[330, 350, 351], 950);
                step(f, Op::Select(ValueType::Float), &[52, 355, 351, 356], 951);
                step(f, Op::MinF, &[356, 809, 357], 952);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 39, 357], 953);
                step(f, Op::ArrayAt(Elem::Float), &[0, 39, 329], 954);
                step(f, Op::ToFloat, &[39, 316], 955);
                step(f, Op::MulF, &[316, 805, 317], 956);
                step(f, Op::AddF, &[10, 317, 318], 957);
                step(f, Op::FractF, &[318, 319], 958);
                step(f, Op::SubF, &[329, 319, 331], 959);
                step(f, Op::GreaterF, &[331, 805, 52], 960);
                step(f, Op::JumpIfFalse, &[52, 1007], 961)
            }
            961 => {
                step(f, Op::Copy(ValueType::Bool), &[99, 35], 962);
                step(f, Op::Copy(ValueType::Bool), &[98, 36], 963);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 964);
                step(f, Op::Copy(ValueType::Int), &[72, 41], 965);
                965
            }
            965 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 41, 37, 42, 43, 971], 966)
            }
            966 => {
                step(f, Op::Not, &[37, 38], 967);
                step(f, Op::JumpIfFalse, &[38, 970], 968)
            }
            968 => {
                step(f, Op::Copy(ValueType::Bool), &[99, 36], 969);
                step(f, Op::Jump, &[970], 970)
            }
            970 => {
                step(f, Op::Jump, &[965], 971)
            }
            971 => {
                step(f, Op::Copy(ValueType::Bool), &[36, 35], 972);
                step(f, Op::Jump, &[973], 973)
            }
            973 => {
                step(f, Op::Copy(ValueType::Bool), &[99, 39], 974);
                step(f, Op::Copy(ValueType::Bool), &[98, 40], 975);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 976);
                step(f, Op::Copy(ValueType::Int), &[72, 44], 977);
                977
            }
            977 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 44, 15, 45, 46, 992], 978)
            }
            978 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 45, 23], 979);
                step(f, Op::BreakTransform, &[23, 79, 13, 80], 980);
                step(f, Op::BreakVector, &[79, 280, 281, 282], 981);
                step(f, Op::MakeVector, &[280, 281, 804, 83], 982);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 45, 24], 983);
                step(f, Op::BreakTransform, &[24, 81, 14, 82], 984);
                step(f, Op::BreakVector, &[81, 283, 284, 285], 985);
                step(f, Op::MakeVector, &[283, 284, 804, 84], 986);
                step(f, Op::DistanceV, &[83, 84, 286], 987);
                step(f, Op::GreaterF, &[286, 29, 41], 988);
                step(f, Op::JumpIfFalse, &[41, 991], 989)
            }
            989 => {
                step(f, Op::Copy(ValueType::Bool), &[99, 40], 990);
                step(f, Op::Jump, &[991], 991)
            }
            991 => {
                step(f, Op::Jump, &[977], 992)
            }
            992 => {
                step(f, Op::Copy(ValueType::Bool), &[40, 39], 993);
                step(f, Op::Jump, &[994], 994)
            }
            994 => {
                step(f, Op::And, &[35, 39, 42], 995);
                step(f, Op::LengthV, &[2, 272], 996);
                step(f, Op::RemapF, &[272, 27, 28, 804, 806, 98, 287], 997);
                step(f, Op::GreaterF, &[272, 27, 34], 998);
                step(f, Op::GreaterF, &[0, 27, 43], 999);
                step(f, Op::Or, &[34, 43, 44], 1000);
                step(f, Op::Not, &[44, 45], 1001);
                step(f, Op::MaxF, &[287, 7, 288], 1002);
                step(f, Op::Select(ValueType::Float), &[35, 806, 288, 289], 1003);
                step(f, Op::Select(ValueType::Float), &[45, 30, 289, 290], 1004);
                step(f, Op::Select(ValueType::Float), &[42, 287, 290, 291], 1005);
                step(f, Op::Copy(ValueType::Float), &[291, 7], 1006);
                step(f, Op::Jump, &[1007], 1007)
            }
            1007 => {
                step(f, Op::ArraySetAt(Elem::Float), &[0, 39, 319], 1008);
                step(f, Op::Jump, &[835], 1009)
            }
            1009 => {
                step(f, Op::LerpF, &[21, 43, 13, 275], 1010);
                step(f, Op::LengthV, &[2, 272], 1011);
                step(f, Op::RemapF, &[272, 24, 25, 22, 23, 98, 273], 1012);
                step(f, Op::LerpF, &[273, 42, 13, 274], 1013);
                step(f, Op::MaxF, &[272, 26, 276], 1014);
                step(f, Op::DivF, &[274, 276, 277], 1015);
                step(f, Op::AddF, &[275, 277, 278], 1016);
                step(f, Op::DivF, &[275, 278, 279], 1017);
                step(f, Op::Copy(ValueType::Float), &[279, 8], 1018);
                step(f, Op::GreaterF, &[272, 27, 34], 1019);
                step(f, Op::GreaterF, &[0, 27, 43], 1020);
                step(f, Op::Or, &[34, 43, 44], 1021);
                step(f, Op::Not, &[44, 45], 1022);
                step(f, Op::Copy(ValueType::Bool), &[45, 4], 1023);
                step(f, Op::Copy(ValueType::Float), &[272, 11], 1024);
                step(f, Op::Copy(ValueType::Bool), &[99, 35], 1025);
                step(f, Op::Copy(ValueType::Bool), &[98, 36], 1026);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 1027);
                step(f, Op::Copy(ValueType::Int), &[72, 41], 1028);
                1028
            }
            1028 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 41, 37, 42, 43, 1034], 1029)
            }
            1029 => {
                step(f, Op::Not, &[37, 38], 1030);
                step(f, Op::JumpIfFalse, &[38, 1033], 1031)
            }
            1031 => {
                step(f, Op::Copy(ValueType::Bool), &[99, 36], 1032);
                step(f, Op::Jump, &[1033], 1033)
            }
            1033 => {
                step(f, Op::Jump, &[1028], 1034)
            }
            1034 => {
                step(f, Op::Copy(ValueType::Bool), &[36, 35], 1035);
                step(f, Op::Jump, &[1036], 1036)
            }
            1036 => {
                step(f, Op::Copy(ValueType::Bool), &[99, 39], 1037);
                step(f, Op::Copy(ValueType::Bool), &[98, 40], 1038);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 1039);
                step(f, Op::Copy(ValueType::Int), &[72, 44], 1040);
                1040
            }
            1040 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 44, 15, 45, 46, 1055], 1041)
            }
            1041 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 45, 23], 1042);
                step(f, Op::BreakTransform, &[23, 79, 13, 80], 1043);
                step(f, Op::BreakVector, &[79, 280, 281, 282], 1044);
                step(f, Op::MakeVector, &[280, 281, 804, 83], 1045);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 45, 24], 1046);
                step(f, Op::BreakTransform, &[24, 81, 14, 82], 1047);
                step(f, Op::BreakVector, &[81, 283, 284, 285], 1048);
                step(f, Op::MakeVector, &[283, 284, 804, 84], 1049);
                step(f, Op::DistanceV, &[83, 84, 286], 1050);
                step(f, Op::GreaterF, &[286, 29, 41], 1051);
                step(f, Op::JumpIfFalse, &[41, 1054], 1052)
            }
            1052 => {
                step(f, Op::Copy(ValueType::Bool), &[99, 40], 1053);
                step(f, Op::Jump, &[1054], 1054)
            }
            1054 => {
                step(f, Op::Jump, &[1040], 1055)
            }
            1055 => {
                step(f, Op::Copy(ValueType::Bool), &[40, 39], 1056);
                step(f, Op::Jump, &[1057], 1057)
            }
            1057 => {
                step(f, Op::And, &[35, 39, 42], 1058);
                step(f, Op::RemapF, &[272, 27, 28, 804, 806, 98, 287], 1059);
                step(f, Op::MaxF, &[287, 7, 288], 1060);
                step(f, Op::Select(ValueType::Float), &[35, 806, 288, 289], 1061);
                step(f, Op::Select(ValueType::Float), &[45, 30, 289, 290], 1062);
                step(f, Op::Select(ValueType::Float), &[42, 287, 290, 291], 1063);
                step(f, Op::SubF, &[806, 19, 292], 1064);
                step(f, Op::MulF, &[291, 292, 293], 1065);
                step(f, Op::DivF, &[293, 275, 320], 1066);
                step(f, Op::Copy(ValueType::Float), &[320, 9], 1067);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 1068);
                step(f, Op::Copy(ValueType::Int), &[72, 2], 1069);
                1069
            }
            1069 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 2, 0, 3, 4, 1907], 1070)
            }
            1070 => {
                step(f, Op::Copy(ValueType::Bone), &[0, 16], 1071);
                step(f, Op::Copy(ValueType::Int), &[3, 47], 1072);
                step(f, Op::GetTransform, &[35, 72, 98, 25], 1073);
                step(f, Op::BreakTransform, &[25, 87, 15, 88], 1074);
                step(f, Op::BreakVector, &[87, 370, 371, 372], 1075);
                step(f, Op::SubF, &[806, 13, 368], 1076);
                step(f, Op::MulF, &[12, 368, 369], 1077);
                step(f, Op::QuatFromAxisAngle, &[423, 369, 17], 1078);
                step(f, Op::GetTransform, &[16, 72, 98, 26], 1079);
                step(f, Op::BreakTransform, &[26, 89, 16, 90], 1080);
                step(f, Op::SubV, &[89, 87, 91], 1081);
                step(f, Op::BreakVector, &[91, 365, 366, 367], 1082);
                step(f, Op::MakeVector, &[365, 366, 804, 92], 1083);
                step(f, Op::RotateVector, &[17, 92, 93], 1084);
                step(f, Op::BreakVector, &[93, 373, 374, 375], 1085);
                step(f, Op::MulF, &[44, 13, 376], 1086);
                step(f, Op::Equals(Elem::Int), &[47, 72, 54], 1087);
                step(f, Op::Select(ValueType::Float), &[54, 806, 808, 385], 1088);
                step(f, Op::MulF, &[376, 385, 377], 1089);
                step(f, Op::AddF, &[373, 377, 378], 1090);
                step(f, Op::AddF, &[370, 378, 379], 1091);
                step(f, Op::AddF, &[371, 374, 380], 1092);
                step(f, Op::BreakVector, &[89, 381, 382, 383], 1093);
                step(f, Op::SubF, &[383, 48, 384], 1094);
                step(f, Op::MakeVector, &[379, 380, 384, 94], 1095);
                step(f, Op::ArrayAt(Elem::Float), &[2, 47, 359], 1096);
                step(f, Op::SubF, &[806, 359, 360], 1097);
                step(f, Op::MaxF, &[360, 804, 361], 1098);
                step(f, Op::MulF, &[8, 5, 362], 1099);
                step(f, Op::MulF, &[361, 362, 363], 1100);
                step(f, Op::ScaleV, &[2, 363, 85], 1101);
                step(f, Op::AddV, &[94, 85, 95], 1102);
                step(f, Op::MulF, &[4, 805, 364], 1103);
                step(f, Op::ScaleV, &[2, 364, 86], 1104);
                step(f, Op::AddV, &[95, 86, 96], 1105);
                step(f, Op::RotateVector, &[0, 424, 97], 1106);
                step(f, Op::Copy(ValueType::Vec3), &[96, 118], 1107);
                step(f, Op::Copy(ValueType::Vec3), &[97, 119], 1108);
                step(f, Op::Copy(ValueType::Float), &[385, 404], 1109);
                step(f, Op::Copy(ValueType::Vec3), &[420, 120], 1110);
                step(f, Op::Copy(ValueType::Vec3), &[420, 121], 1111);
                step(f, Op::Copy(ValueType::Bool), &[99, 56], 1112);
                step(f, Op::Copy(ValueType::Float), &[811, 405], 1113);
                step(f, Op::Copy(ValueType::Vec3), &[420, 122], 1114);
                step(f, Op::Copy(ValueType::Vec3), &[423, 123], 1115);
                step(f, Op::Copy(ValueType::Bool), &[99, 57], 1116);
                step(f, Op::Copy(ValueType::Float), &[811, 406], 1117);
                step(f, Op::Copy(ValueType::Vec3), &[420, 124], 1118);
                step(f, Op::MulI, &[0, 0, 53], 1119);
                step(f, Op::Copy(ValueType::Int), &[53, 52], 1120);
                step(f, Op::Copy(ValueType::Int), &[72, 48], 1121);
                step(f, Op::SubI, &[0, 73, 56], 1122);
                step(f, Op::DivI, &[56, 74, 57], 1123);
                step(f, Op::MakeVector, &[804, 804, 53, 129], 1124);
                step(f, Op::ScaleV, &[119, 56, 134], 1125);
                1125
            }
            1125 => {
                step(f, Op::ForNext, &[48, 52, 50, 1173], 1126)
            }
            1126 => {
                step(f, Op::ModI, &[50, 0, 54], 1127);
                step(f, Op::ToFloat, &[54, 407], 1128);
                step(f, Op::MulF, &[407, 54, 409], 1129);
                step(f, Op::MulF, &[409, 404, 410], 1130);
                step(f, Op::MakeVector, &[410, 804, 804, 125], 1131);
                step(f, Op::DivI, &[50, 0, 55], 1132);
                step(f, Op::SubI, &[55, 57, 58], 1133);
                step(f, Op::ToFloat, &[58, 408], 1134);
                step(f, Op::MulF, &[408, 54, 411], 1135);
                step(f, Op::ScaleV, &[119, 411, 126], 1136);
                step(f, Op::AddV, &[125, 126, 127], 1137);
                step(f, Op::AddV, &[118, 127, 128], 1138);
                step(f, Op::AddV, &[128, 129, 130], 1139);
                step(f, Op::SubV, &[128, 129, 131], 1140);
                step(f, Op::SphereTrace, &[130, 131, 52, 58, 132, 133, 412], 1141);
                step(f, Op::BreakVector, &[132, 414, 415, 416], 1142);
                step(f, Op::AddV, &[130, 134, 135], 1143);
                step(f, Op::AddV, &[131, 134, 136], 1144);
                step(f, Op::SphereTrace, &[135, 136, 52, 59, 137, 138, 413], 1145);
                step(f, Op::BreakVector, &[137, 417, 418, 419], 1146);
                step(f, Op::SubF, &[416, 419, 420], 1147);
                step(f, Op::AbsF, &[420, 421], 1148);
                step(f, Op::Select(ValueType::Float), &[58, 804, 806, 422], 1149);
                step(f, Op::AddF, &[421, 422, 427], 1150);
                step(f, Op::LengthV, &[127, 423], 1151);
                step(f, Op::RemapF, &[423, 804, 817, 804, 806, 98, 424], 1152);
                step(f, Op::MinF, &[416, 419, 425], 1153);
                step(f, Op::RemapF, &[425, 818, 817, 806, 805, 98, 426], 1154);
                step(f, Op::AddF, &[424, 426, 428], 1155);
                step(f, Op::AddF, &[427, 428, 429], 1156);
                step(f, Op::LessF, &[429, 405, 60], 1157);
                step(f, Op::And, &[58, 60, 61], 1158);
                step(f, Op::JumpIfFalse, &[61, 1166], 1159)
            }
            1159 => {
                step(f, Op::Copy(ValueType::Float), &[405, 406], 1160);
                step(f, Op::Copy(ValueType::Vec3), &[122, 124], 1161);
                step(f, Op::Copy(ValueType::Float), &[429, 405], 1162);
                step(f, Op::Copy(ValueType::Vec3), &[132, 122], 1163);
                step(f, Op::Copy(ValueType::Vec3), &[133, 123], 1164);
                step(f, Op::Copy(ValueType::Bool), &[98, 57], 1165);
                step(f, Op::Jump, &[1172], 1166)
            }
            1166 => {
                step(f, Op::LessF, &[429, 406, 62], 1167);
                step(f, Op::And, &[58, 62, 63], 1168);
                step(f, Op::JumpIfFalse, &[63, 1172], 1169)
            }
            1169 => {
                step(f, Op::Copy(ValueType::Float), &[429, 406], 1170);
                step(f, Op::Copy(ValueType::Vec3), &[132, 124], 1171);
                step(f, Op::Jump, &[1172], 1172)
            }
            1172 => {
                step(f, Op::Jump, &[1125], 1173)
            }
            1173 => {
                step(f, Op::JumpIfFalse, &[8, 1176], 1174)
            }
            1174 => {
                step(f, Op::DrawSphere, &[122, 52, 424], 1175);
                step(f, Op::Jump, &[1176], 1176)
            }
            1176 => {
                step(f, Op::GreaterF, &[55, 804, 64], 1177);
                step(f, Op::SubF, &[405, 406, 430], 1178);
                step(f, Op::DivF, &[430, 55, 431], 1179);
                step(f, Op::PowF, &[819, 431, 432], 1180);
                step(f, Op::Select(ValueType::Float), &[64, 432, 804, 433], 1181);
                step(f, Op::ScaleV, &[124, 433, 139], 1182);
                step(f, Op::AddV, &[122, 139, 140], 1183);
                step(f, Op::AddF, &[433, 806, 434], 1184);
                step(f, Op::DivF, &[806, 434, 435], 1185);
                step(f, Op::ScaleV, &[140, 435, 141], 1186);
                step(f, Op::Copy(ValueType::Vec3), &[141, 120], 1187);
                step(f, Op::Copy(ValueType::Vec3), &[123, 121], 1188);
                step(f, Op::Copy(ValueType::Bool), &[57, 56], 1189);
                step(f, Op::Jump, &[1190], 1190)
            }
            1190 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 47, 27], 1191);
                step(f, Op::BreakTransform, &[27, 99, 21, 100], 1192);
                step(f, Op::ArrayAt(Elem::Float), &[2, 47, 359], 1193);
                step(f, Op::SubF, &[806, 359, 360], 1194);
                step(f, Op::MaxF, &[360, 804, 361], 1195);
                step(f, Op::MulF, &[8, 5, 362], 1196);
                step(f, Op::MulF, &[361, 362, 363], 1197);
                step(f, Op::ScaleV, &[2, 363, 85], 1198);
                step(f, Op::SubV, &[120, 85, 98], 1199);
                step(f, Op::Select(ValueType::Vec3), &[56, 98, 99, 101], 1200);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 47, 28], 1201);
                step(f, Op::BreakTransform, &[28, 102, 23, 103], 1202);
                step(f, Op::Copy(ValueType::Vec3), &[99, 104], 1203);
                step(f, Op::Copy(ValueType::Vec3), &[101, 105], 1204);
                step(f, Op::Copy(ValueType::Vec3), &[102, 106], 1205);
                step(f, Op::Copy(ValueType::Float), &[45, 391], 1206);
                step(f, Op::Copy(ValueType::Float), &[47, 392], 1207);
                step(f, Op::Copy(ValueType::Vec3), &[420, 107], 1208);
                step(f, Op::SubV, &[105, 106, 108], 1209);
                step(f, Op::DeltaTime, &[393], 1210);
                step(f, Op::DivF, &[392, 393, 394], 1211);
                step(f, Op::ScaleV, &[108, 394, 109], 1212);
                step(f, Op::AddV, &[105, 109, 110], 1213);
                step(f, Op::AddV, &[106, 109, 111], 1214);
                step(f, Op::SubV, &[104, 111, 112], 1215);
                step(f, Op::FloatLerp, &[804, 806, 391, 395], 1216);
                step(f, Op::SubF, &[806, 395, 396], 1217);
                step(f, Op::ScaleV, &[112, 396, 113], 1218);
                step(f, Op::AddV, &[110, 113, 115], 1219);
                step(f, Op::MulF, &[391, 393, 397], 1220);
                step(f, Op::GreaterF, &[397, 804, 55], 1221);
                step(f, Op::DivF, &[395, 397, 398], 1222);
                step(f, Op::Select(ValueType::Float), &[55, 398, 806, 399], 1223);
                step(f, Op::ScaleV, &[108, 399, 114], 1224);
                step(f, Op::SubV, &[115, 114, 116], 1225);
                step(f, Op::Copy(ValueType::Vec3), &[116, 107], 1226);
                step(f, Op::Jump, &[1227], 1227)
            }
            1227 => {
                step(f, Op::BreakVector, &[107, 400, 401, 402], 1228);
                step(f, Op::ClampF, &[402, 57, 58, 403], 1229);
                step(f, Op::MakeVector, &[400, 401, 403, 117], 1230);
                step(f, Op::RotationFromNormal, &[121, 389, 390, 19], 1231);
                step(f, Op::PerFootRotationFactor, &[12, 94, 95, 386], 1232);
                step(f, Op::MulF, &[12, 386, 387], 1233);
                step(f, Op::SubF, &[806, 13, 368], 1234);
                step(f, Op::MulF, &[387, 368, 388], 1235);
                step(f, Op::QuatFromAxisAngle, &[423, 388, 18], 1236);
                step(f, Op::MulQ, &[19, 18, 20], 1237);
                step(f, Op::Select(ValueType::Quat), &[56, 20, 21, 22], 1238);
                step(f, Op::MakeTransform, &[117, 22, 421, 30], 1239);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 47, 30], 1240);
                step(f, Op::ArrayAt(Elem::Float), &[2, 47, 359], 1241);
                step(f, Op::SubF, &[806, 359, 360], 1242);
                step(f, Op::MaxF, &[360, 804, 361], 1243);
                step(f, Op::MulF, &[8, 5, 362], 1244);
                step(f, Op::MulF, &[361, 362, 363], 1245);
                step(f, Op::ScaleV, &[2, 363, 85], 1246);
                step(f, Op::SubV, &[120, 85, 98], 1247);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 47, 27], 1248);
                step(f, Op::BreakTransform, &[27, 99, 21, 100], 1249);
                step(f, Op::Select(ValueType::Vec3), &[56, 98, 99, 101], 1250);
                step(f, Op::MakeTransform, &[101, 92, 421, 29], 1251);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 47, 29], 1252);
                step(f, Op::JumpIfFalse, &[56, 1255], 1253)
            }
            1253 => {
                step(f, Op::Copy(ValueType::Bool), &[98, 7], 1254);
                step(f, Op::Jump, &[1255], 1255)
            }
            1255 => {
                step(f, Op::Copy(ValueType::Int), &[3, 59], 1256);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 59, 33], 1257);
                step(f, Op::GreaterF, &[19, 804, 68], 1258);
                step(f, Op::InterpolateTransform, &[2, 111, 20, 31], 1259);
                step(f, Op::Select(ValueType::Transform), &[68, 31, 2, 32], 1260);
                step(f, Op::MakeAbsolute, &[33, 32, 34], 1261);
                step(f, Op::BreakTransform, &[34, 142, 24, 143], 1262);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 59, 35], 1263);
                step(f, Op::BreakTransform, &[35, 144, 25, 145], 1264);
                step(f, Op::AddF, &[61, 62, 437], 1265);
                step(f, Op::ClampSpatially, &[142, 144, 804, 437, 146], 1266);
                step(f, Op::SubF, &[806, 13, 452], 1267);
                step(f, Op::MulF, &[12, 452, 438], 1268);
                step(f, Op::LimitRotationAroundZ, &[24, 438, 93, 26], 1269);
                step(f, Op::MakeTransform, &[146, 26, 421, 36], 1270);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 59, 36], 1271);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 59, 65], 1272);
                step(f, Op::JumpIfFalse, &[65, 1326], 1273)
            }
            1273 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 59, 39], 1274);
                step(f, Op::BreakTransform, &[39, 152, 28, 153], 1275);
                step(f, Op::ArrayAt(Elem::Float), &[2, 59, 436], 1276);
                step(f, Op::SubF, &[806, 436, 449], 1277);
                step(f, Op::MulF, &[8, 5, 450], 1278);
                step(f, Op::MulF, &[449, 450, 451], 1279);
                step(f, Op::ScaleV, &[2, 451, 154], 1280);
                step(f, Op::AddV, &[152, 154, 155], 1281);
                step(f, Op::MakeTransform, &[155, 28, 421, 46], 1282);
                step(f, Op::Copy(ValueType::Transform), &[46, 47], 1283);
                step(f, Op::Copy(ValueType::Transform), &[111, 48], 1284);
                step(f, Op::BreakTransform, &[47, 183, 33, 184], 1285);
                step(f, Op::MakeVector, &[804, 804, 53, 185], 1286);
                step(f, Op::AddV, &[183, 185, 186], 1287);
                step(f, Op::SubV, &[183, 185, 187], 1288);
                step(f, Op::LineTrace, &[186, 187, 72, 188, 189, 479], 1289);
                step(f, Op::RotateVector, &[33, 423, 190], 1290);
                step(f, Op::FindQuatBetween, &[190, 189, 34], 1291);
                step(f, Op::MulQ, &[34, 33, 35], 1292);
                step(f, Op::MulF, &[51, 50, 480], 1293);
                step(f, Op::AddF, &[480, 60, 481], 1294);
                step(f, Op::NegF, &[481, 482], 1295);
                step(f, Op::MakeVector, &[804, 482, 804, 191], 1296);
                step(f, Op::RotateVector, &[35, 191, 193], 1297);
                step(f, Op::AddV, &[188, 193, 195], 1298);
                step(f, Op::AddV, &[195, 185, 197], 1299);
                step(f, Op::SubV, &[195, 185, 198], 1300);
                step(f, Op::LineTrace, &[197, 198, 73, 201, 202, 484], 1301);
                step(f, Op::BreakVector, &[201, 486, 487, 488], 1302);
                step(f, Op::BreakVector, &[195, 492, 493, 494], 1303);
                step(f, Op::SubF, &[488, 494, 498], 1304);
                step(f, Op::Select(ValueType::Float), &[73, 498, 804, 500], 1305);
                step(f, Op::AddF, &[56, 60, 483], 1306);
                step(f, Op::MakeVector, &[804, 483, 804, 192], 1307);
                step(f, Op::RotateVector, &[35, 192, 194], 1308);
                step(f, Op::AddV, &[188, 194, 196], 1309);
                step(f, Op::AddV, &[196, 185, 199], 1310);
                step(f, Op::SubV, &[196, 185, 200], 1311);
                step(f, Op::LineTrace, &[199, 200, 74, 203, 204, 485], 1312);
                step(f, Op::BreakVector, &[203, 489, 490, 491], 1313);
                step(f, Op::BreakVector, &[196, 495, 496, 497], 1314);
                step(f, Op::SubF, &[491, 497, 499], 1315);
                step(f, Op::Select(ValueType::Float), &[74, 499, 804, 501], 1316);
                step(f, Op::MaxF, &[500, 501, 502], 1317);
                step(f, Op::ClampF, &[502, 804, 59, 503], 1318);
                step(f, Op::MakeVector, &[804, 804, 503, 205], 1319);
                step(f, Op::AddV, &[188, 205, 206], 1320);
                step(f, Op::MakeTransform, &[206, 35, 421, 49], 1321);
                step(f, Op::Select(ValueType::Transform), &[72, 49, 47, 50], 1322);
                step(f, Op::Copy(ValueType::Transform), &[50, 48], 1323);
                step(f, Op::Jump, &[1324], 1324)
            }
            1324 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 59, 48], 1325);
                step(f, Op::Jump, &[1430], 1326)
            }
            1326 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 59, 51], 1327);
                step(f, Op::GreaterF, &[19, 804, 68], 1328);
                step(f, Op::InterpolateTransform, &[2, 111, 20, 31], 1329);
                step(f, Op::Select(ValueType::Transform), &[68, 31, 2, 32], 1330);
                step(f, Op::MakeAbsolute, &[51, 32, 52], 1331);
                step(f, Op::BreakTransform, &[52, 207, 36, 208], 1332);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 59, 39], 1333);
                step(f, Op::BreakTransform, &[39, 152, 28, 153], 1334);
                step(f, Op::ArrayAt(Elem::Float), &[2, 59, 436], 1335);
                step(f, Op::SubF, &[806, 436, 449], 1336);
                step(f, Op::MulF, &[8, 5, 450], 1337);
                step(f, Op::MulF, &[449, 450, 451], 1338);
                step(f, Op::ScaleV, &[2, 451, 154], 1339);
                step(f, Op::AddV, &[152, 154, 155], 1340);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 59, 53], 1341);
                step(f, Op::MakeAbsolute, &[53, 32, 54], 1342);
                step(f, Op::BreakTransform, &[54, 209, 37, 210], 1343);
                step(f, Op::ArrayAt(Elem::Float), &[3, 59, 504], 1344);
                step(f, Op::SubF, &[436, 504, 505], 1345);
                step(f, Op::DeltaTime, &[520], 1346);
                step(f, Op::DivF, &[47, 520, 506], 1347);
                step(f, Op::MulF, &[505, 506, 507], 1348);
                step(f, Op::AddF, &[504, 507, 508], 1349);
                step(f, Op::ClampF, &[508, 804, 806, 510], 1350);
                step(f, Op::AddF, &[436, 507, 509], 1351);
                step(f, Op::ClampF, &[509, 804, 806, 511], 1352);
                step(f, Op::AddF, &[510, 511, 512], 1353);
                step(f, Op::MulF, &[512, 805, 513], 1354);
                step(f, Op::SubF, &[806, 513, 514], 1355);
                step(f, Op::GreaterF, &[505, 804, 75], 1356);
                step(f, Op::SubF, &[511, 510, 515], 1357);
                step(f, Op::DivF, &[515, 505, 516], 1358);
                step(f, Op::Select(ValueType::Float), &[75, 516, 806, 517], 1359);
                step(f, Op::MulF, &[514, 517, 518], 1360);
                step(f, Op::MulF, &[77, 518, 519], 1361);
                step(f, Op::Copy(ValueType::Vec3), &[207, 211], 1362);
                step(f, Op::Copy(ValueType::Vec3), &[155, 212], 1363);
                step(f, Op::Copy(ValueType::Vec3), &[209, 213], 1364);
                step(f, Op::Copy(ValueType::Float), &[519, 521], 1365);
                step(f, Op::Copy(ValueType::Float), &[47, 522], 1366);
                step(f, Op::Copy(ValueType::Vec3), &[420, 214], 1367);
                step(f, Op::SubV, &[212, 213, 215], 1368);
                step(f, Op::DeltaTime, &[523], 1369);
                step(f, Op::DivF, &[522, 523, 524], 1370);
                step(f, Op::ScaleV, &[215, 524, 216], 1371);
                step(f, Op::AddV, &[212, 216, 217], 1372);
                step(f, Op::AddV, &[213, 216, 218], 1373);
                step(f, Op::SubV, &[211, 218, 219], 1374);
                step(f, Op::FloatLerp, &[804, 806, 521, 525], 1375);
                step(f, Op::SubF, &[806, 525, 526], 1376);
                step(f, Op::ScaleV, &[219, 526, 220], 1377);
                step(f, Op::AddV, &[217, 220, 222], 1378);
                step(f, Op::MulF, &[521, 523, 527], 1379);
                step(f, Op::GreaterF, &[527, 804, 76], 1380);
                step(f, Op::DivF, &[525, 527, 528], 1381);
                step(f, Op::Select(ValueType::Float), &[76, 528, 806, 529], 1382);
                step(f, Op::ScaleV, &[215, 529, 221], 1383);
                step(f, Op::SubV, &[222, 221, 223], 1384);
                step(f, Op::Copy(ValueType::Vec3), &[223, 214], 1385);
                step(f, Op::Jump, &[1386], 1386)
            }
            1386 => {
                step(f, Op::MakeTransform, &[214, 28, 421, 56], 1387);
                step(f, Op::Copy(ValueType::Transform), &[56, 57], 1388);
                step(f, Op::Copy(ValueType::Transform), &[111, 58], 1389);
                step(f, Op::BreakTransform, &[57, 224, 38, 225], 1390);
                step(f, Op::MakeVector, &[804, 804, 53, 226], 1391);
                step(f, Op::AddV, &[224, 226, 227], 1392);
                step(f, Op::SubV, &[224, 226, 228], 1393);
                step(f, Op::LineTrace, &[227, 228, 77, 229, 230, 530], 1394);
                step(f, Op::RotateVector, &[38, 423, 231], 1395);
                step(f, Op::FindQuatBetween, &[231, 230, 39], 1396);
                step(f, Op::MulQ, &[39, 38, 40], 1397);
                step(f, Op::MulF, &[51, 50, 531], 1398);
                step(f, Op::AddF, &[531, 60, 532], 1399);
                step(f, Op::NegF, &[532, 533], 1400);
                step(f, Op::MakeVector, &[804, 533, 804, 232], 1401);
                step(f, Op::RotateVector, &[40, 232, 234], 1402);
                step(f, Op::AddV, &[229, 234, 236], 1403);
                step(f, Op::AddV, &[236, 226, 238], 1404);
                step(f, Op::SubV, &[236, 226, 239], 1405);
                step(f, Op::LineTrace, &[238, 239, 78, 242, 243, 535], 1406);
                step(f, Op::BreakVector, &[242, 537, 538, 539], 1407);
                step(f, Op::BreakVector, &[236, 543, 544, 545], 1408);
                step(f, Op::SubF, &[539, 545, 549], 1409);
                step(f, Op::Select(ValueType::Float), &[78, 549, 804, 551], 1410);
                step(f, Op::AddF, &[56, 60, 534], 1411);
                step(f, Op::MakeVector, &[804, 534, 804, 233], 1412);
                step(f, Op::RotateVector, &[40, 233, 235], 1413);
                step(f, Op::AddV, &[229, 235, 237], 1414);
                step(f, Op::AddV, &[237, 226, 240], 1415);
                step(f, Op::SubV, &[237, 226, 241], 1416);
                step(f, Op::LineTrace, &[240, 241, 79, 244, 245, 536], 1417);
                step(f, Op::BreakVector, &[244, 540, 541, 542], 1418);
                step(f, Op::BreakVector, &[237, 546, 547, 548], 1419);
                step(f, Op::SubF, &[542, 548, 550], 1420);
                step(f, Op::Select(ValueType::Float), &[79, 550, 804, 552], 1421);
                step(f, Op::MaxF, &[551, 552, 553], 1422);
                step(f, Op::ClampF, &[553, 804, 59, 554], 1423);
                step(f, Op::MakeVector, &[804, 804, 554, 246], 1424);
                step(f, Op::AddV, &[229, 246, 247], 1425);
                step(f, Op::MakeTransform, &[247, 40, 421, 59], 1426);
                step(f, Op::Select(ValueType::Transform), &[77, 59, 57, 60], 1427);
                step(f, Op::Copy(ValueType::Transform), &[60, 58], 1428);
                step(f, Op::Jump, &[1429], 1429)
            }
            1429 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 59, 58], 1430);
                1430
            }
            1430 => {
                step(f, Op::ArrayAt(Elem::Float), &[2, 59, 436], 1431);
                step(f, Op::GreaterEqualF, &[436, 806, 66], 1432);
                step(f, Op::JumpIfFalse, &[66, 1509], 1433)
            }
            1433 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 59, 65], 1434);
                step(f, Op::JumpIfFalse, &[65, 1436], 1435)
            }
            1435 => {
                step(f, Op::Jump, &[1489], 1436)
            }
            1436 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 59, 61], 1437);
                step(f, Op::BreakTransform, &[61, 248, 41, 249], 1438);
                step(f, Op::Equals(Elem::Int), &[59, 72, 67], 1439);
                step(f, Op::Select(ValueType::Int), &[67, 73, 72, 60], 1440);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 60, 40], 1441);
                step(f, Op::BreakTransform, &[40, 156, 29, 157], 1442);
                step(f, Op::SubF, &[806, 13, 452], 1443);
                step(f, Op::MulF, &[12, 452, 453], 1444);
                step(f, Op::FootAvoidance, &[248, 156, 453, 67, 78, 158], 1445);
                step(f, Op::MakeTransform, &[158, 41, 421, 41], 1446);
                step(f, Op::Copy(ValueType::Transform), &[41, 42], 1447);
                step(f, Op::Copy(ValueType::Transform), &[111, 43], 1448);
                step(f, Op::BreakTransform, &[42, 159, 30, 160], 1449);
                step(f, Op::MakeVector, &[804, 804, 53, 161], 1450);
                step(f, Op::AddV, &[159, 161, 162], 1451);
                step(f, Op::SubV, &[159, 161, 163], 1452);
                step(f, Op::LineTrace, &[162, 163, 69, 164, 165, 454], 1453);
                step(f, Op::RotateVector, &[30, 423, 166], 1454);
                step(f, Op::FindQuatBetween, &[166, 165, 31], 1455);
                step(f, Op::MulQ, &[31, 30, 32], 1456);
                step(f, Op::MulF, &[51, 50, 455], 1457);
                step(f, Op::AddF, &[455, 60, 456], 1458);
                step(f, Op::NegF, &[456, 457], 1459);
                step(f, Op::MakeVector, &[804, 457, 804, 167], 1460);
                step(f, Op::RotateVector, &[32, 167, 169], 1461);
                step(f, Op::AddV, &[164, 169, 171], 1462);
                step(f, Op::AddV, &[171, 161, 173], 1463);
                step(f, Op::SubV, &[171, 161, 174], 1464);
                step(f, Op::LineTrace, &[173, 174, 70, 177, 178, 459], 1465);
                step(f, Op::BreakVector, &[177, 461, 462, 463], 1466);
                step(f, Op::BreakVector, &[171, 467, 468, 469], 1467);
                step(f, Op::SubF, &[463, 469, 473], 1468);
                step(f, Op::Select(ValueType::Float), &[70, 473, 804, 475], 1469);
                step(f, Op::AddF, &[56, 60, 458], 1470);
                step(f, Op::MakeVector, &[804, 458, 804, 168], 1471);
                step(f, Op::RotateVector, &[32, 168, 170], 1472);
                step(f, Op::AddV, &[164, 170, 172], 1473);
                step(f, Op::AddV, &[172, 161, 175], 1474);
                step(f, Op::SubV, &[172, 161, 176], 1475);
                step(f, Op::LineTrace, &[175, 176, 71, 179, 180, 460], 1476);
                step(f, Op::BreakVector, &[179, 464, 465, 466], 1477);
                step(f, Op::BreakVector, &[172, 470, 471, 472], 1478);
                step(f, Op::SubF, &[466, 472, 474], 1479);
                step(f, Op::Select(ValueType::Float), &[71, 474, 804, 476], 1480);
                step(f, Op::MaxF, &[475, 476, 477], 1481);
                step(f, Op::ClampF, &[477, 804, 59, 478], 1482);
                step(f, Op::MakeVector, &[804, 804, 478, 181], 1483);
                step(f, Op::AddV, &[164, 181, 182], 1484);
                step(f, Op::MakeTransform, &[182, 32, 421, 44], 1485);
                step(f, Op::Select(ValueType::Transform), &[69, 44, 42, 45], 1486);
                step(f, Op::Copy(ValueType::Transform), &[45, 43], 1487);
                step(f, Op::Jump, &[1488], 1488)
            }
            1488 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 59, 43], 1489);
                1489
            }
            1489 => {
                step(f, Op::ArrayAt(Elem::Transform), &[7, 59, 35], 1490);
                step(f, Op::BreakTransform, &[35, 144, 25, 145], 1491);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 59, 37], 1492);
                step(f, Op::BreakTransform, &[37, 147, 27, 148], 1493);
                step(f, Op::SubV, &[147, 144, 149], 1494);
                step(f, Op::LengthV, &[149, 439], 1495);
                step(f, Op::SubF, &[61, 62, 440], 1496);
                step(f, Op::SubF, &[439, 440, 441], 1497);
                step(f, Op::MulF, &[62, 809, 442], 1498);
                step(f, Op::ClampF, &[441, 804, 442, 443], 1499);
                step(f, Op::MulF, &[443, 443, 444], 1500);
                step(f, Op::MulF, &[62, 820, 445], 1501);
                step(f, Op::DivF, &[444, 445, 446], 1502);
                step(f, Op::SubF, &[439, 446, 447], 1503);
                step(f, Op::DivF, &[447, 439, 448], 1504);
                step(f, Op::ScaleV, &[149, 448, 150], 1505);
                step(f, Op::AddV, &[144, 150, 151], 1506);
                step(f, Op::MakeTransform, &[151, 27, 421, 38], 1507);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 59, 38], 1508);
                step(f, Op::Jump, &[1718], 1509)
            }
            1509 => {
                step(f, Op::ArrayAt(Elem::Transform), &[7, 59, 35], 1510);
                step(f, Op::BreakTransform, &[35, 144, 25, 145], 1511);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 59, 37], 1512);
                step(f, Op::BreakTransform, &[37, 147, 27, 148], 1513);
                step(f, Op::SubV, &[147, 144, 149], 1514);
                step(f, Op::LengthV, &[149, 439], 1515);
                step(f, Op::SubF, &[61, 62, 440], 1516);
                step(f, Op::SubF, &[439, 440, 441], 1517);
                step(f, Op::MulF, &[62, 809, 442], 1518);
                step(f, Op::ClampF, &[441, 804, 442, 443], 1519);
                step(f, Op::MulF, &[443, 443, 444], 1520);
                step(f, Op::MulF, &[62, 820, 445], 1521);
                step(f, Op::DivF, &[444, 445, 446], 1522);
                step(f, Op::SubF, &[439, 446, 447], 1523);
                step(f, Op::DivF, &[447, 439, 448], 1524);
                step(f, Op::ScaleV, &[149, 448, 150], 1525);
                step(f, Op::AddV, &[144, 150, 151], 1526);
                step(f, Op::MakeTransform, &[151, 27, 421, 38], 1527);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 59, 61], 1528);
                step(f, Op::ClampF, &[436, 804, 806, 555], 1529);
                step(f, Op::Copy(ValueType::Transform), &[38, 66], 1530);
                step(f, Op::Copy(ValueType::Transform), &[61, 67], 1531);
                step(f, Op::Copy(ValueType::Float), &[555, 573], 1532);
                step(f, Op::Copy(ValueType::Transform), &[111, 68], 1533);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[3, 2], 1534);
                step(f, Op::ArrayReset(Elem::Vec3), &[2], 1535);
                step(f, Op::BreakTransform, &[66, 266, 46, 267], 1536);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 266], 1537);
                step(f, Op::BreakTransform, &[66, 266, 46, 267], 1538);
                step(f, Op::UnitV, &[2, 265], 1539);
                step(f, Op::LengthV, &[2, 574], 1540);
                step(f, Op::RemapF, &[574, 804, 63, 804, 64, 98, 575], 1541);
                step(f, Op::ScaleV, &[265, 575, 270], 1542);
                step(f, Op::SubV, &[266, 270, 276], 1543);
                step(f, Op::MakeVector, &[804, 804, 66, 274], 1544);
                step(f, Op::AddV, &[276, 274, 278], 1545);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 278], 1546);
                step(f, Op::BreakTransform, &[66, 266, 46, 267], 1547);
                step(f, Op::UnitV, &[2, 265], 1548);
                step(f, Op::LengthV, &[2, 574], 1549);
                step(f, Op::RemapF, &[574, 804, 63, 804, 64, 98, 575], 1550);
                step(f, Op::ScaleV, &[265, 575, 270], 1551);
                step(f, Op::SubV, &[266, 270, 276], 1552);
                step(f, Op::MakeVector, &[804, 804, 66, 274], 1553);
                step(f, Op::AddV, &[276, 274, 278], 1554);
                step(f, Op::RemapF, &[574, 804, 63, 804, 68, 98, 577], 1555);
                step(f, Op::MakeVector, &[804, 804, 577, 272], 1556);
                step(f, Op::AddV, &[278, 272, 282], 1557);
                step(f, Op::BreakTransform, &[67, 268, 47, 269], 1558);
                step(f, Op::BreakVector, &[268, 582, 583, 584], 1559);
                step(f, Op::BreakVector, &[266, 579, 580, 581], 1560);
                step(f, Op::SubF, &[584, 581, 585], 1561);
                step(f, Op::MaxF, &[585, 804, 587], 1562);
                step(f, Op::MulF, &[587, 70, 591], 1563);
                step(f, Op::MinF, &[591, 71, 592], 1564);
                step(f, Op::AbsF, &[585, 589], 1565);
                step(f, Op::RemapF, &[589, 804, 74, 804, 73, 98, 590], 1566);
                step(f, Op::AddF, &[592, 590, 594], 1567);
                step(f, Op::MakeVector, &[804, 804, 594, 280], 1568);
                step(f, Op::AddV, &[282, 280, 284], 1569);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 284], 1570);
                step(f, Op::BreakTransform, &[66, 266, 46, 267], 1571);
                step(f, Op::UnitV, &[2, 265], 1572);
                step(f, Op::LengthV, &[2, 574], 1573);
                step(f, Op::RemapF, &[574, 804, 63, 804, 64, 98, 575], 1574);
                step(f, Op::ScaleV, &[265, 575, 270], 1575);
                step(f, Op::SubV, &[266, 270, 276], 1576);
                step(f, Op::MakeVector, &[804, 804, 66, 274], 1577);
                step(f, Op::AddV, &[276, 274, 278], 1578);
                step(f, Op::RemapF, &[574, 804, 63, 804, 68, 98, 577], 1579);
                step(f, Op::MakeVector, &[804, 804, 577, 272], 1580);
                step(f, Op::AddV, &[278, 272, 282], 1581);
                step(f, Op::BreakTransform, &[67, 268, 47, 269], 1582);
                step(f, Op::BreakVector, &[268, 582, 583, 584], 1583);
                step(f, Op::BreakVector, &[266, 579, 580, 581], 1584);
                step(f, Op::SubF, &[584, 581, 585], 1585);
                step(f, Op::MaxF, &[585, 804, 587], 1586);
                step(f, Op::MulF, &[587, 70, 591], 1587);
                step(f, Op::MinF, &[591, 71, 592], 1588);
                step(f, Op::AbsF, &[585, 589], 1589);
                step(f, Op::RemapF, &[589, 804, 74, 804, 73, 98, 590], 1590);
                step(f, Op::AddF, &[592, 590, 594], 1591);
                step(f, Op::MakeVector, &[804, 804, 594, 280], 1592);
                step(f, Op::AddV, &[282, 280, 284], 1593);
                step(f, Op::RemapF, &[574, 804, 63, 804, 65, 98, 576], 1594);
                step(f, Op::ScaleV, &[265, 576, 271], 1595);
                step(f, Op::AddV, &[268, 271, 277], 1596);
                step(f, Op::MakeVector, &[804, 804, 67, 275], 1597);
                step(f, Op::AddV, &[277, 275, 279], 1598);
                step(f, Op::RemapF, &[574, 804, 63, 804, 69, 98, 578], 1599);
                step(f, Op::MakeVector, &[804, 804, 578, 273], 1600);
                step(f, Op::AddV, &[279, 273, 283], 1601);
                step(f, Op::NegF, &[585, 586], 1602);
                step(f, Op::MaxF, &[586, 804, 588], 1603);
                step(f, Op::MulF, &[588, 72, 593], 1604);
                step(f, Op::AddF, &[593, 590, 595], 1605);
                step(f, Op::MakeVector, &[804, 804, 595, 281], 1606);
                step(f, Op::AddV, &[283, 281, 285], 1607);
                step(f, Op::LerpV, &[284, 285, 805, 286], 1608);
                step(f, Op::GetTransform, &[36, 72, 98, 69], 1609);
                step(f, Op::BreakTransform, &[69, 287, 48, 288], 1610);
                step(f, Op::BreakVector, &[287, 605, 606, 607], 1611);
                step(f, Op::SubF, &[806, 13, 599], 1612);
                step(f, Op::MulF, &[75, 599, 600], 1613);
                step(f, Op::MulF, &[12, 600, 601], 1614);
                step(f, Op::QuatFromAxisAngle, &[423, 601, 49], 1615);
                step(f, Op::SubV, &[286, 287, 289], 1616);
                step(f, Op::BreakVector, &[289, 596, 597, 598], 1617);
                step(f, Op::MakeVector, &[596, 597, 804, 290], 1618);
                step(f, Op::RotateVector, &[49, 290, 291], 1619);
                step(f, Op::BreakVector, &[291, 602, 603, 604], 1620);
                step(f, Op::AddF, &[605, 602, 611], 1621);
                step(f, Op::AddF, &[606, 603, 612], 1622);
                step(f, Op::BreakVector, &[286, 608, 609, 610], 1623);
                step(f, Op::MakeVector, &[611, 612, 610, 292], 1624);
                step(f, Op::DistanceV, &[266, 268, 613], 1625);
                step(f, Op::RemapF, &[613, 809, 821, 804, 806, 98, 614], 1626);
                step(f, Op::LerpV, &[286, 292, 614, 293], 1627);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 293], 1628);
                step(f, Op::BreakTransform, &[67, 268, 47, 269], 1629);
                step(f, Op::UnitV, &[2, 265], 1630);
                step(f, Op::LengthV, &[2, 574], 1631);
                step(f, Op::RemapF, &[574, 804, 63, 804, 65, 98, 576], 1632);
                step(f, Op::ScaleV, &[265, 576, 271], 1633);
                step(f, Op::AddV, &[268, 271, 277], 1634);
                step(f, Op::MakeVector, &[804, 804, 67, 275], 1635);
                step(f, Op::AddV, &[277, 275, 279], 1636);
                step(f, Op::RemapF, &[574, 804, 63, 804, 69, 98, 578], 1637);
                step(f, Op::MakeVector, &[804, 804, 578, 273], 1638);
                step(f, Op::AddV, &[279, 273, 283], 1639);
                step(f, Op::BreakVector, &[268, 582, 583, 584], 1640);
                step(f, Op::BreakTransform, &[66, 266, 46, 267], 1641);
                step(f, Op::BreakVector, &[266, 579, 580, 581], 1642);
                step(f, Op::SubF, &[584, 581, 585], 1643);
                step(f, Op::NegF, &[585, 586], 1644);
                step(f, Op::MaxF, &[586, 804, 588], 1645);
                step(f, Op::MulF, &[588, 72, 593], 1646);
                step(f, Op::AbsF, &[585, 589], 1647);
                step(f, Op::RemapF, &[589, 804, 74, 804, 73, 98, 590], 1648);
                step(f, Op::AddF, &[593, 590, 595], 1649);
                step(f, Op::MakeVector, &[804, 804, 595, 281], 1650);
                step(f, Op::AddV, &[283, 281, 285], 1651);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 285], 1652);
                step(f, Op::BreakTransform, &[67, 268, 47, 269], 1653);
                step(f, Op::UnitV, &[2, 265], 1654);
                step(f, Op::LengthV, &[2, 574], 1655);
                step(f, Op::RemapF, &[574, 804, 63, 804, 65, 98, 576], 1656);
                step(f, Op::ScaleV, &[265, 576, 271], 1657);
                step(f, Op::AddV, &[268, 271, 277], 1658);
                step(f, Op::MakeVector, &[804, 804, 67, 275], 1659);
                step(f, Op::AddV, &[277, 275, 279], 1660);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 279], 1661);
                step(f, Op::BreakTransform, &[67, 268, 47, 269], 1662);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 268], 1663);
                step(f, Op::JumpIfFalse, &[8, 1666], 1664)
            }
            1664 => {
                step(f, Op::DrawSpline, &[2, 72, 75, 805, 425], 1665);
                step(f, Op::Jump, &[1666], 1666)
            }
            1666 => {
                step(f, Op::Spline, &[2, 573, 72, 294, 295], 1667);
                step(f, Op::BreakTransform, &[66, 266, 46, 267], 1668);
                step(f, Op::BreakTransform, &[67, 268, 47, 269], 1669);
                step(f, Op::SlerpQ, &[46, 47, 573, 50], 1670);
                step(f, Op::MulF, &[573, 814, 623], 1671);
                step(f, Op::SinF, &[623, 624], 1672);
                step(f, Op::Copy(ValueType::Float), &[573, 615], 1673);
                step(f, Op::Copy(ValueType::Float), &[804, 616], 1674);
                step(f, Op::DivF, &[615, 86, 617], 1675);
                step(f, Op::ClampF, &[617, 804, 806, 618], 1676);
                step(f, Op::MulF, &[618, 618, 619], 1677);
                step(f, Op::MulF, &[618, 809, 620], 1678);
                step(f, Op::SubF, &[810, 620, 621], 1679);
                step(f, Op::MulF, &[619, 621, 622], 1680);
                step(f, Op::Copy(ValueType::Float), &[622, 616], 1681);
                step(f, Op::Jump, &[1682], 1682)
            }
            1682 => {
                step(f, Op::MulF, &[624, 616, 625], 1683);
                step(f, Op::MulF, &[625, 76, 626], 1684);
                step(f, Op::SlerpQ, &[50, 92, 626, 51], 1685);
                step(f, Op::MakeTransform, &[294, 51, 421, 70], 1686);
                step(f, Op::Copy(ValueType::Transform), &[70, 68], 1687);
                step(f, Op::Jump, &[1688], 1688)
            }
            1688 => {
                step(f, Op::BreakTransform, &[68, 250, 42, 251], 1689);
                step(f, Op::Equals(Elem::Int), &[59, 72, 67], 1690);
                step(f, Op::Select(ValueType::Int), &[67, 73, 72, 60], 1691);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 60, 40], 1692);
                step(f, Op::BreakTransform, &[40, 156, 29, 157], 1693);
                step(f, Op::SubF, &[806, 13, 452], 1694);
                step(f, Op::MulF, &[12, 452, 453], 1695);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 60, 80], 1696);
                step(f, Op::Select(ValueType::Float), &[80, 79, 804, 558], 1697);
                step(f, Op::ArrayAt(Elem::Float), &[2, 59, 436], 1698);
                step(f, Op::ClampF, &[436, 804, 806, 555], 1699);
                step(f, Op::MulF, &[555, 814, 556], 1700);
                step(f, Op::SinF, &[556, 557], 1701);
                step(f, Op::MulF, &[557, 557, 559], 1702);
                step(f, Op::MulF, &[558, 559, 560], 1703);
                step(f, Op::AddF, &[78, 560, 561], 1704);
                step(f, Op::FootAvoidance, &[250, 156, 453, 67, 561, 252], 1705);
                step(f, Op::SubV, &[252, 250, 253], 1706);
                step(f, Op::LengthV, &[253, 562], 1707);
                step(f, Op::AddF, &[562, 560, 563], 1708);
                step(f, Op::DivF, &[562, 563, 564], 1709);
                step(f, Op::ScaleV, &[253, 564, 254], 1710);
                step(f, Op::AddV, &[250, 254, 255], 1711);
                step(f, Op::SubF, &[806, 120, 565], 1712);
                step(f, Op::MulF, &[3, 565, 566], 1713);
                step(f, Op::MulF, &[566, 559, 567], 1714);
                step(f, Op::MakeVector, &[804, 804, 567, 256], 1715);
                step(f, Op::AddV, &[255, 256, 257], 1716);
                step(f, Op::MakeTransform, &[257, 42, 421, 62], 1717);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 59, 62], 1718);
                1718
            }
            1718 => {
                step(f, Op::GreaterF, &[19, 804, 68], 1719);
                step(f, Op::JumpIfFalse, &[68, 1736], 1720)
            }
            1720 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 59, 63], 1721);
                step(f, Op::BreakTransform, &[63, 258, 43, 259], 1722);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 59, 64], 1723);
                step(f, Op::BreakTransform, &[64, 260, 44, 261], 1724);
                step(f, Op::MulF, &[19, 19, 568], 1725);
                step(f, Op::LerpV, &[258, 260, 568, 262], 1726);
                step(f, Op::SubF, &[806, 19, 569], 1727);
                step(f, Op::MulF, &[19, 569, 570], 1728);
                step(f, Op::MulF, &[122, 809, 571], 1729);
                step(f, Op::MulF, &[570, 571, 572], 1730);
                step(f, Op::MakeVector, &[804, 804, 572, 263], 1731);
                step(f, Op::AddV, &[262, 263, 264], 1732);
                step(f, Op::SlerpQ, &[43, 44, 19, 45], 1733);
                step(f, Op::MakeTransform, &[264, 45, 421, 65], 1734);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 59, 65], 1735);
                step(f, Op::Jump, &[1736], 1736)
            }
            1736 => {
                step(f, Op::ArrayAt(Elem::Float), &[2, 59, 436], 1737);
                step(f, Op::GreaterEqualF, &[436, 806, 66], 1738);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 59, 66], 1739);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 59, 39], 1740);
                step(f, Op::BreakTransform, &[39, 152, 28, 153], 1741);
                step(f, Op::ArrayAt(Elem::Float), &[2, 59, 436], 1742);
                step(f, Op::SubF, &[806, 436, 449], 1743);
                step(f, Op::MulF, &[8, 5, 450], 1744);
                step(f, Op::MulF, &[449, 450, 451], 1745);
                step(f, Op::ScaleV, &[2, 451, 154], 1746);
                step(f, Op::AddV, &[152, 154, 155], 1747);
                step(f, Op::MakeTransform, &[155, 92, 421, 55], 1748);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 59, 55], 1749);
                step(f, Op::Copy(ValueType::Bone), &[0, 17], 1750);
                step(f, Op::Copy(ValueType::Int), &[3, 61], 1751);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 61, 71], 1752);
                step(f, Op::BreakTransform, &[71, 296, 52, 297], 1753);
                step(f, Op::MakeVector, &[804, 804, 48, 306], 1754);
                step(f, Op::AddV, &[296, 306, 307], 1755);
                step(f, Op::GetTransform, &[17, 72, 98, 73], 1756);
                step(f, Op::BreakTransform, &[73, 301, 54, 302], 1757);
                step(f, Op::MakeTransform, &[307, 54, 421, 75], 1758);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 61, 20], 1759);
                step(f, Op::GetTransform, &[20, 72, 98, 74], 1760);
                step(f, Op::BreakTransform, &[74, 303, 55, 304], 1761);
                step(f, Op::SubV, &[303, 301, 305], 1762);
                step(f, Op::AddV, &[307, 305, 308], 1763);
                step(f, Op::FootPivots, &[307, 308, 50, 49, 48, 51, 309, 310, 311], 1764);
                step(f, Op::GetParent, &[17, 18], 1765);
                step(f, Op::GetParent, &[18, 19], 1766);
                step(f, Op::GetTransform, &[19, 72, 99, 72], 1767);
                step(f, Op::BreakTransform, &[72, 298, 53, 299], 1768);
                step(f, Op::SubV, &[296, 298, 300], 1769);
                step(f, Op::DotV, &[300, 424, 627], 1770);
                step(f, Op::RemapF, &[627, 81, 80, 82, 804, 98, 630], 1771);
                step(f, Op::LengthV, &[2, 628], 1772);
                step(f, Op::RemapF, &[628, 804, 92, 804, 806, 98, 629], 1773);
                step(f, Op::MulF, &[630, 629, 631], 1774);
                step(f, Op::QuatFromAxisAngle, &[426, 631, 56], 1775);
                step(f, Op::RotateAroundPoint, &[75, 309, 56, 76], 1776);
                step(f, Op::ArrayAt(Elem::Float), &[2, 61, 632], 1777);
                step(f, Op::Copy(ValueType::Float), &[632, 634], 1778);
                step(f, Op::Copy(ValueType::Float), &[804, 635], 1779);
                step(f, Op::DivF, &[634, 86, 636], 1780);
                step(f, Op::ClampF, &[636, 804, 806, 637], 1781);
                step(f, Op::MulF, &[637, 637, 638], 1782);
                step(f, Op::MulF, &[637, 809, 639], 1783);
                step(f, Op::SubF, &[810, 639, 640], 1784);
                step(f, Op::MulF, &[638, 640, 641], 1785);
                step(f, Op::Copy(ValueType::Float), &[641, 635], 1786);
                step(f, Op::Jump, &[1787], 1787)
            }
            1787 => {
                step(f, Op::SubF, &[806, 632, 633], 1788);
                step(f, Op::Copy(ValueType::Float), &[633, 642], 1789);
                step(f, Op::Copy(ValueType::Float), &[804, 643], 1790);
                step(f, Op::DivF, &[642, 86, 644], 1791);
                step(f, Op::ClampF, &[644, 804, 806, 645], 1792);
                step(f, Op::MulF, &[645, 645, 646], 1793);
                step(f, Op::MulF, &[645, 809, 647], 1794);
                step(f, Op::SubF, &[810, 647, 648], 1795);
                step(f, Op::MulF, &[646, 648, 649], 1796);
                step(f, Op::Copy(ValueType::Float), &[649, 643], 1797);
                step(f, Op::Jump, &[1798], 1798)
            }
            1798 => {
                step(f, Op::MulF, &[635, 643, 650], 1799);
                step(f, Op::LerpF, &[85, 806, 650, 651], 1800);
                step(f, Op::MulF, &[631, 651, 652], 1801);
                step(f, Op::QuatFromAxisAngle, &[426, 652, 57], 1802);
                step(f, Op::SubV, &[310, 309, 312], 1803);
                step(f, Op::RotateVector, &[57, 312, 313], 1804);
                step(f, Op::AddV, &[309, 313, 314], 1805);
                step(f, Op::RemapF, &[627, 83, 81, 84, 804, 98, 653], 1806);
                step(f, Op::MulF, &[653, 629, 654], 1807);
                step(f, Op::QuatFromAxisAngle, &[426, 654, 58], 1808);
                step(f, Op::RotateAroundPoint, &[76, 314, 58, 77], 1809);
                step(f, Op::RemapF, &[627, 87, 88, 804, 89, 98, 655], 1810);
                step(f, Op::RotateVector, &[52, 423, 315], 1811);
                step(f, Op::BreakVector, &[315, 656, 657, 658], 1812);
                step(f, Op::CosF, &[91, 660], 1813);
                step(f, Op::CosF, &[90, 659], 1814);
                step(f, Op::RemapF, &[658, 660, 659, 804, 806, 98, 661], 1815);
                step(f, Op::MulF, &[629, 661, 662], 1816);
                step(f, Op::MulF, &[655, 662, 663], 1817);
                step(f, Op::QuatFromAxisAngle, &[426, 663, 59], 1818);
                step(f, Op::RotateAroundPoint, &[77, 311, 59, 78], 1819);
                step(f, Op::SubF, &[806, 13, 664], 1820);
                step(f, Op::MulF, &[12, 664, 665], 1821);
                step(f, Op::LimitRotationAroundZ, &[52, 665, 93, 60], 1822);
                step(f, Op::RotateAroundPoint, &[78, 296, 60, 79], 1823);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 61, 79], 1824);
                step(f, Op::JumpIfFalse, &[8, 1906], 1825)
            }
            1825 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 61, 71], 1826);
                step(f, Op::BreakTransform, &[71, 296, 52, 297], 1827);
                step(f, Op::MakeVector, &[804, 804, 48, 306], 1828);
                step(f, Op::AddV, &[296, 306, 307], 1829);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 61, 20], 1830);
                step(f, Op::GetTransform, &[20, 72, 98, 74], 1831);
                step(f, Op::BreakTransform, &[74, 303, 55, 304], 1832);
                step(f, Op::GetTransform, &[17, 72, 98, 73], 1833);
                step(f, Op::BreakTransform, &[73, 301, 54, 302], 1834);
                step(f, Op::SubV, &[303, 301, 305], 1835);
                step(f, Op::AddV, &[307, 305, 308], 1836);
                step(f, Op::FootPivots, &[307, 308, 50, 49, 48, 51, 309, 310, 311], 1837);
                step(f, Op::DrawPoint, &[311, 810, 426], 1838);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 61, 71], 1839);
                step(f, Op::BreakTransform, &[71, 296, 52, 297], 1840);
                step(f, Op::MakeVector, &[804, 804, 48, 306], 1841);
                step(f, Op::AddV, &[296, 306, 307], 1842);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 61, 20], 1843);
                step(f, Op::GetTransform, &[20, 72, 98, 74], 1844);
                step(f, Op::BreakTransform, &[74, 303, 55, 304], 1845);
                step(f, Op::GetTransform, &[17, 72, 98, 73], 1846);
                step(f, Op::BreakTransform, &[73, 301, 54, 302], 1847);
                step(f, Op::SubV, &[303, 301, 305], 1848);
                step(f, Op::AddV, &[307, 305, 308], 1849);
                step(f, Op::FootPivots, &[307, 308, 50, 49, 48, 51, 309, 310, 311], 1850);
                step(f, Op::DrawPoint, &[309, 810, 424], 1851);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 61, 71], 1852);
                step(f, Op::BreakTransform, &[71, 296, 52, 297], 1853);
                step(f, Op::MakeVector, &[804, 804, 48, 306], 1854);
                step(f, Op::AddV, &[296, 306, 307], 1855);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 61, 20], 1856);
                step(f, Op::GetTransform, &[20, 72, 98, 74], 1857);
                step(f, Op::BreakTransform, &[74, 303, 55, 304], 1858);
                step(f, Op::GetTransform, &[17, 72, 98, 73], 1859);
                step(f, Op::BreakTransform, &[73, 301, 54, 302], 1860);
                step(f, Op::SubV, &[303, 301, 305], 1861);
                step(f, Op::AddV, &[307, 305, 308], 1862);
                step(f, Op::FootPivots, &[307, 308, 50, 49, 48, 51, 309, 310, 311], 1863);
                step(f, Op::GetParent, &[17, 18], 1864);
                step(f, Op::GetParent, &[18, 19], 1865);
                step(f, Op::GetTransform, &[19, 72, 99, 72], 1866);
                step(f, Op::BreakTransform, &[72, 298, 53, 299], 1867);
                step(f, Op::SubV, &[296, 298, 300], 1868);
                step(f, Op::DotV, &[300, 424, 627], 1869);
                step(f, Op::RemapF, &[627, 81, 80, 82, 804, 98, 630], 1870);
                step(f, Op::LengthV, &[2, 628], 1871);
                step(f, Op::RemapF, &[628, 804, 92, 804, 806, 98, 629], 1872);
                step(f, Op::MulF, &[630, 629, 631], 1873);
                step(f, Op::ArrayAt(Elem::Float), &[2, 61, 632], 1874);
                step(f, Op::Copy(ValueType::Float), &[632, 634], 1875);
                step(f, Op::Copy(ValueType::Float), &[804, 635], 1876);
                step(f, Op::DivF, &[634, 86, 636], 1877);
                step(f, Op::ClampF, &[636, 804, 806, 637], 1878);
                step(f, Op::MulF, &[637, 637, 638], 1879);
                step(f, Op::MulF, &[637, 809, 639], 1880);
                step(f, Op::SubF, &[810, 639, 640], 1881);
                step(f, Op::MulF, &[638, 640, 641], 1882);
                step(f, Op::Copy(ValueType::Float), &[641, 635], 1883);
                step(f, Op::Jump, &[1884], 1884)
            }
            1884 => {
                step(f, Op::SubF, &[806, 632, 633], 1885);
                step(f, Op::Copy(ValueType::Float), &[633, 642], 1886);
                step(f, Op::Copy(ValueType::Float), &[804, 643], 1887);
                step(f, Op::DivF, &[642, 86, 644], 1888);
                step(f, Op::ClampF, &[644, 804, 806, 645], 1889);
                step(f, Op::MulF, &[645, 645, 646], 1890);
                step(f, Op::MulF, &[645, 809, 647], 1891);
                step(f, Op::SubF, &[810, 647, 648], 1892);
                step(f, Op::MulF, &[646, 648, 649], 1893);
                step(f, Op::Copy(ValueType::Float), &[649, 643], 1894);
                step(f, Op::Jump, &[1895], 1895)
            }
            1895 => {
                step(f, Op::MulF, &[635, 643, 650], 1896);
                step(f, Op::LerpF, &[85, 806, 650, 651], 1897);
                step(f, Op::MulF, &[631, 651, 652], 1898);
                step(f, Op::QuatFromAxisAngle, &[426, 652, 57], 1899);
                step(f, Op::SubV, &[310, 309, 312], 1900);
                step(f, Op::RotateVector, &[57, 312, 313], 1901);
                step(f, Op::AddV, &[309, 313, 314], 1902);
                step(f, Op::DrawPoint, &[314, 810, 423], 1903);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 61, 71], 1904);
                step(f, Op::DrawTransform, &[71, 821, 805], 1905);
                step(f, Op::Jump, &[1906], 1906)
            }
            1906 => {
                step(f, Op::Jump, &[1069], 1907)
            }
            1907 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1908);
                step(f, Op::Copy(ValueType::Int), &[72, 5], 1909);
                1909
            }
            1909 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 5, 1, 6, 7, 1964], 1910)
            }
            1910 => {
                step(f, Op::Copy(ValueType::Bone), &[1, 21], 1911);
                step(f, Op::Copy(ValueType::Int), &[6, 62], 1912);
                step(f, Op::GetParent, &[21, 22], 1913);
                step(f, Op::GetParent, &[22, 23], 1914);
                step(f, Op::GetParent, &[23, 24], 1915);
                step(f, Op::GetTransform, &[24, 72, 99, 80], 1916);
                step(f, Op::BreakTransform, &[80, 316, 61, 317], 1917);
                step(f, Op::LengthV, &[1, 667], 1918);
                step(f, Op::ClavicleOffset, &[10, 667, 98, 101, 668], 1919);
                step(f, Op::MakeVector, &[804, 804, 668, 318], 1920);
                step(f, Op::AddV, &[316, 318, 319], 1921);
                step(f, Op::MakeTransform, &[319, 61, 421, 81], 1922);
                step(f, Op::SetTransform, &[24, 81, 72, 98, 806], 1923);
                step(f, Op::GetParent, &[21, 22], 1924);
                step(f, Op::GetParent, &[22, 23], 1925);
                step(f, Op::GetTransform, &[21, 72, 99, 82], 1926);
                step(f, Op::GetTransform, &[23, 72, 99, 83], 1927);
                step(f, Op::BreakTransform, &[83, 320, 63, 321], 1928);
                step(f, Op::Equals(Elem::Int), &[62, 72, 81], 1929);
                step(f, Op::Select(ValueType::Int), &[81, 73, 72, 63], 1930);
                step(f, Op::ArrayAt(Elem::Float), &[0, 63, 666], 1931);
                step(f, Op::ArmSwingRotation, &[666, 1, 0, 99, 813, 822, 806, 98, 96, 97, 813, 813, 806, 669], 1932);
                step(f, Op::QuatFromAxisAngle, &[426, 669, 62], 1933);
                step(f, Op::RotateAroundPoint, &[82, 320, 62, 84], 1934);
                step(f, Op::BreakTransform, &[84, 322, 64, 323], 1935);
                step(f, Op::LengthV, &[1, 667], 1936);
                step(f, Op::RemapF, &[667, 804, 98, 804, 100, 98, 670], 1937);
                step(f, Op::MakeVector, &[804, 804, 670, 324], 1938);
                step(f, Op::AddV, &[322, 324, 325], 1939);
                step(f, Op::MakeTransform, &[325, 64, 421, 85], 1940);
                step(f, Op::Select(ValueType::Vec3), &[81, 427, 426, 327], 1941);
                step(f, Op::Select(ValueType::Vec3), &[81, 424, 428, 328], 1942);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 62, 326], 1943);
                step(f, Op::TwoBoneIK, &[23, 22, 21, 85, 327, 328, 326, 72, 806, 99, 823, 824, 98, 82, 671], 1944);
                step(f, Op::JumpIfFalse, &[8, 1963], 1945)
            }
            1945 => {
                step(f, Op::GetParent, &[21, 22], 1946);
                step(f, Op::GetParent, &[22, 23], 1947);
                step(f, Op::GetTransform, &[23, 72, 99, 83], 1948);
                step(f, Op::BreakTransform, &[83, 320, 63, 321], 1949);
                step(f, Op::GetTransform, &[21, 72, 99, 82], 1950);
                step(f, Op::Equals(Elem::Int), &[62, 72, 81], 1951);
                step(f, Op::Select(ValueType::Int), &[81, 73, 72, 63], 1952);
                step(f, Op::ArrayAt(Elem::Float), &[0, 63, 666], 1953);
                step(f, Op::ArmSwingRotation, &[666, 1, 0, 99, 813, 822, 806, 98, 96, 97, 813, 813, 806, 669], 1954);
                step(f, Op::QuatFromAxisAngle, &[426, 669, 62], 1955);
                step(f, Op::RotateAroundPoint, &[82, 320, 62, 84], 1956);
                step(f, Op::BreakTransform, &[84, 322, 64, 323], 1957);
                step(f, Op::LengthV, &[1, 667], 1958);
                step(f, Op::RemapF, &[667, 804, 98, 804, 100, 98, 670], 1959);
                step(f, Op::MakeVector, &[804, 804, 670, 324], 1960);
                step(f, Op::AddV, &[322, 324, 325], 1961);
                step(f, Op::DrawLine, &[320, 325, 805, 424], 1962);
                step(f, Op::Jump, &[1963], 1963)
            }
            1963 => {
                step(f, Op::Jump, &[1909], 1964)
            }
            1964 => {
                step(f, Op::Copy(ValueType::Float), &[804, 674], 1965);
                step(f, Op::Copy(ValueType::Float), &[811, 675], 1966);
                step(f, Op::Copy(ValueType::Bool), &[99, 83], 1967);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 10], 1968);
                step(f, Op::Copy(ValueType::Int), &[72, 64], 1969);
                step(f, Op::MakeVector, &[804, 804, 53, 331], 1970);
                1970
            }
            1970 => {
                step(f, Op::ForEachNext(Elem::Transform), &[10, 64, 86, 65, 66, 1983], 1971)
            }
            1971 => {
                step(f, Op::BreakTransform, &[86, 329, 65, 330], 1972);
                step(f, Op::AddV, &[329, 331, 332], 1973);
                step(f, Op::SubV, &[329, 331, 333], 1974);
                step(f, Op::SphereTrace, &[332, 333, 52, 84, 334, 335, 676], 1975);
                step(f, Op::BreakVector, &[334, 677, 678, 679], 1976);
                step(f, Op::LessF, &[679, 675, 85], 1977);
                step(f, Op::And, &[84, 85, 86], 1978);
                step(f, Op::JumpIfFalse, &[86, 1982], 1979)
            }
            1979 => {
                step(f, Op::Copy(ValueType::Float), &[679, 675], 1980);
                step(f, Op::Copy(ValueType::Bool), &[98, 83], 1981);
                step(f, Op::Jump, &[1982], 1982)
            }
            1982 => {
                step(f, Op::Jump, &[1970], 1983)
            }
            1983 => {
                step(f, Op::Select(ValueType::Float), &[83, 675, 804, 680], 1984);
                step(f, Op::ClampF, &[680, 57, 58, 681], 1985);
                step(f, Op::Copy(ValueType::Float), &[681, 674], 1986);
                step(f, Op::Jump, &[1987], 1987)
            }
            1987 => {
                step(f, Op::SubF, &[806, 19, 673], 1988);
                step(f, Op::MulF, &[674, 673, 682], 1989);
                step(f, Op::MakeVector, &[14, 804, 804, 336], 1990);
                step(f, Op::MakeVector, &[682, 804, 804, 337], 1991);
                step(f, Op::Select(ValueType::Float), &[2, 682, 15, 683], 1992);
                step(f, Op::MakeVector, &[683, 804, 804, 338], 1993);
                step(f, Op::Copy(ValueType::Vec3), &[336, 339], 1994);
                step(f, Op::Copy(ValueType::Vec3), &[337, 340], 1995);
                step(f, Op::Copy(ValueType::Vec3), &[338, 341], 1996);
                step(f, Op::Copy(ValueType::Float), &[46, 684], 1997);
                step(f, Op::Copy(ValueType::Float), &[47, 685], 1998);
                step(f, Op::Copy(ValueType::Vec3), &[420, 342], 1999);
                step(f, Op::SubV, &[340, 341, 343], 2000);
                step(f, Op::DeltaTime, &[686], 2001);
                step(f, Op::DivF, &[685, 686, 687], 2002);
                step(f, Op::ScaleV, &[343, 687, 344], 2003);
                step(f, Op::AddV, &[340, 344, 345], 2004);
                step(f, Op::AddV, &[341, 344, 346], 2005);
                step(f, Op::SubV, &[339, 346, 347], 2006);
                step(f, Op::FloatLerp, &[804, 806, 684, 688], 2007);
                step(f, Op::SubF, &[806, 688, 689], 2008);
                step(f, Op::ScaleV, &[347, 689, 348], 2009);
                step(f, Op::AddV, &[345, 348, 350], 2010);
                step(f, Op::MulF, &[684, 686, 690], 2011);
                step(f, Op::GreaterF, &[690, 804, 87], 2012);
                step(f, Op::DivF, &[688, 690, 691], 2013);
                step(f, Op::Select(ValueType::Float), &[87, 691, 806, 692], 2014);
                step(f, Op::ScaleV, &[343, 692, 349], 2015);
                step(f, Op::SubV, &[350, 349, 351], 2016);
                step(f, Op::Copy(ValueType::Vec3), &[351, 342], 2017);
                step(f, Op::Jump, &[2018], 2018)
            }
            2018 => {
                step(f, Op::BreakVector, &[342, 693, 694, 695], 2019);
                step(f, Op::Select(ValueType::Float), &[1, 682, 693, 696], 2020);
                step(f, Op::Copy(ValueType::Float), &[696, 14], 2021);
                step(f, Op::Copy(ValueType::Float), &[682, 15], 2022);
                step(f, Op::GetTransform, &[37, 72, 98, 91], 2023);
                step(f, Op::BreakTransform, &[91, 364, 72, 365], 2024);
                step(f, Op::PelvisLean, &[1, 103, 108, 109, 712, 713], 2025);
                step(f, Op::LengthV, &[2, 672], 2026);
                step(f, Op::RemapF, &[672, 804, 103, 804, 102, 98, 697], 2027);
                step(f, Op::MulF, &[10, 825, 698], 2028);
                step(f, Op::SinF, &[698, 699], 2029);
                step(f, Op::MulF, &[697, 699, 700], 2030);
                step(f, Op::MulF, &[700, 673, 701], 2031);
                step(f, Op::AddF, &[701, 14, 702], 2032);
                step(f, Op::MulF, &[3, 120, 703], 2033);
                step(f, Op::SubF, &[702, 703, 704], 2034);
                step(f, Op::MakeVector, &[804, 713, 704, 366], 2035);
                step(f, Op::AddV, &[364, 366, 367], 2036);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 72, 87], 2037);
                step(f, Op::BreakTransform, &[87, 352, 66, 353], 2038);
                step(f, Op::BreakVector, &[352, 714, 715, 716], 2039);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 73, 88], 2040);
                step(f, Op::BreakTransform, &[88, 354, 67, 355], 2041);
                step(f, Op::BreakVector, &[354, 717, 718, 719], 2042);
                step(f, Op::SubF, &[716, 719, 720], 2043);
                step(f, Op::PelvisSideLean, &[720, 110, 111, 721], 2044);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 72, 89], 2045);
                step(f, Op::BreakTransform, &[89, 358, 68, 359], 2046);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 73, 90], 2047);
                step(f, Op::BreakTransform, &[90, 360, 69, 361], 2048);
                step(f, Op::SlerpQ, &[68, 69, 805, 70], 2049);
                step(f, Op::EulerFromQuat, &[70, 72, 362], 2050);
                step(f, Op::BreakVector, &[362, 708, 709, 710], 2051);
                step(f, Op::RemapF, &[672, 104, 103, 804, 105, 98, 706], 2052);
                step(f, Op::SubV, &[352, 354, 356], 2053);
                step(f, Op::RotateVector, &[0, 424, 357], 2054);
                step(f, Op::DotV, &[356, 357, 705], 2055);
                step(f, Op::MulF, &[706, 705, 707], 2056);
                step(f, Op::AddF, &[710, 707, 711], 2057);
                step(f, Op::MakeVector, &[712, 721, 711, 363], 2058);
                step(f, Op::QuatFromEuler, &[363, 72, 71], 2059);
                step(f, Op::MakeTransform, &[367, 71, 421, 92], 2060);
                step(f, Op::SetTransform, &[38, 92, 72, 98, 806], 2061);
                step(f, Op::GetTransform, &[39, 73, 98, 93], 2062);
                step(f, Op::BreakTransform, &[93, 368, 76, 369], 2063);
                step(f, Op::LengthV, &[2, 672], 2064);
                step(f, Op::RemapF, &[672, 104, 103, 804, 105, 98, 706], 2065);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 72, 87], 2066);
                step(f, Op::BreakTransform, &[87, 352, 66, 353], 2067);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 73, 88], 2068);
                step(f, Op::BreakTransform, &[88, 354, 67, 355], 2069);
                step(f, Op::SubV, &[352, 354, 356], 2070);
                step(f, Op::RotateVector, &[0, 424, 357], 2071);
                step(f, Op::DotV, &[356, 357, 705], 2072);
                step(f, Op::MulF, &[706, 705, 707], 2073);
                step(f, Op::QuatFromAxisAngle, &[423, 707, 73], 2074);
                step(f, Op::DivF, &[106, 810, 722], 2075);
                step(f, Op::QuatScale, &[73, 722, 74], 2076);
                step(f, Op::MulQ, &[76, 74, 80], 2077);
                step(f, Op::MakeTransform, &[368, 80, 421, 97], 2078);
                step(f, Op::SetTransform, &[40, 97, 73, 98, 806], 2079);
                step(f, Op::GetTransform, &[41, 73, 98, 94], 2080);
                step(f, Op::BreakTransform, &[94, 370, 77, 371], 2081);
                step(f, Op::LengthV, &[2, 672], 2082);
                step(f, Op::RemapF, &[672, 104, 103, 804, 105, 98, 706], 2083);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 72, 87], 2084);
                step(f, Op::BreakTransform, &[87, 352, 66, 353], 2085);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 73, 88], 2086);
                step(f, Op::BreakTransform, &[88, 354, 67, 355], 2087);
                step(f, Op::SubV, &[352, 354, 356], 2088);
                step(f, Op::RotateVector, &[0, 424, 357], 2089);
                step(f, Op::DotV, &[356, 357, 705], 2090);
                step(f, Op::MulF, &[706, 705, 707], 2091);
                step(f, Op::QuatFromAxisAngle, &[423, 707, 73], 2092);
                step(f, Op::DivF, &[106, 810, 722], 2093);
                step(f, Op::QuatScale, &[73, 722, 74], 2094);
                step(f, Op::MulQ, &[77, 74, 81], 2095);
                step(f, Op::MakeTransform, &[370, 81, 421, 98], 2096);
                step(f, Op::SetTransform, &[42, 98, 73, 98, 806], 2097);
                step(f, Op::GetTransform, &[43, 73, 98, 95], 2098);
                step(f, Op::BreakTransform, &[95, 372, 78, 373], 2099);
                step(f, Op::LengthV, &[2, 672], 2100);
                step(f, Op::RemapF, &[672, 104, 103, 804, 105, 98, 706], 2101);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 72, 87], 2102);
                step(f, Op::BreakTransform, &[87, 352, 66, 353], 2103);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 73, 88], 2104);
                step(f, Op::BreakTransform, &[88, 354, 67, 355], 2105);
                step(f, Op::SubV, &[352, 354, 356], 2106);
                step(f, Op::RotateVector, &[0, 424, 357], 2107);
                step(f, Op::DotV, &[356, 357, 705], 2108);
                step(f, Op::MulF, &[706, 705, 707], 2109);
                step(f, Op::QuatFromAxisAngle, &[423, 707, 73], 2110);
                step(f, Op::DivF, &[106, 810, 722], 2111);
                step(f, Op::QuatScale, &[73, 722, 74], 2112);
                step(f, Op::MulQ, &[78, 74, 82], 2113);
                step(f, Op::MakeTransform, &[372, 82, 421, 99], 2114);
                step(f, Op::SetTransform, &[44, 99, 73, 98, 806], 2115);
                step(f, Op::GetTransform, &[45, 73, 98, 96], 2116);
                step(f, Op::BreakTransform, &[96, 374, 79, 375], 2117);
                step(f, Op::LengthV, &[2, 672], 2118);
                step(f, Op::RemapF, &[672, 104, 103, 804, 105, 98, 706], 2119);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 72, 87], 2120);
                step(f, Op::BreakTransform, &[87, 352, 66, 353], 2121);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 73, 88], 2122);
                step(f, Op::BreakTransform, &[88, 354, 67, 355], 2123);
                step(f, Op::SubV, &[352, 354, 356], 2124);
                step(f, Op::RotateVector, &[0, 424, 357], 2125);
                step(f, Op::DotV, &[356, 357, 705], 2126);
                step(f, Op::MulF, &[706, 705, 707], 2127);
                step(f, Op::QuatFromAxisAngle, &[423, 707, 73], 2128);
                step(f, Op::QuatScale, &[73, 107, 75], 2129);
                step(f, Op::MulQ, &[79, 75, 83], 2130);
                step(f, Op::MakeTransform, &[374, 83, 421, 100], 2131);
                step(f, Op::SetTransform, &[46, 100, 73, 98, 806], 2132);
                step(f, Op::Or, &[1, 2, 93], 2133);
                step(f, Op::Copy(ValueType::Float), &[804, 723], 2134);
                step(f, Op::Copy(ValueType::Float), &[804, 724], 2135);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 2136);
                step(f, Op::Copy(ValueType::Int), &[72, 67], 2137);
                step(f, Op::SubF, &[806, 13, 756], 2138);
                2138
            }
            2138 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 67, 25, 68, 69, 2186], 2139)
            }
            2139 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 68, 88], 2140);
                step(f, Op::GetParent, &[25, 26], 2141);
                step(f, Op::GetParent, &[26, 27], 2142);
                step(f, Op::GetTransform, &[27, 72, 99, 101], 2143);
                step(f, Op::BreakTransform, &[101, 376, 84, 377], 2144);
                step(f, Op::BreakVector, &[376, 725, 726, 727], 2145);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 68, 102], 2146);
                step(f, Op::BreakTransform, &[102, 378, 85, 379], 2147);
                step(f, Op::BreakVector, &[378, 728, 729, 730], 2148);
                step(f, Op::ArrayAt(Elem::Float), &[1, 68, 734], 2149);
                step(f, Op::MulF, &[734, 112, 735], 2150);
                step(f, Op::MulF, &[735, 735, 736], 2151);
                step(f, Op::SubF, &[725, 728, 731], 2152);
                step(f, Op::SubF, &[726, 729, 732], 2153);
                step(f, Op::MakeVector, &[731, 732, 804, 380], 2154);
                step(f, Op::DotV, &[380, 380, 733], 2155);
                step(f, Op::SubF, &[736, 733, 737], 2156);
                step(f, Op::SqrtF, &[737, 738], 2157);
                step(f, Op::AddF, &[730, 738, 739], 2158);
                step(f, Op::SubF, &[727, 739, 740], 2159);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 68, 103], 2160);
                step(f, Op::BreakTransform, &[103, 381, 86, 382], 2161);
                step(f, Op::BreakVector, &[381, 741, 742, 743], 2162);
                step(f, Op::AddF, &[743, 48, 744], 2163);
                step(f, Op::MinF, &[730, 744, 745], 2164);
                step(f, Op::AddF, &[745, 738, 746], 2165);
                step(f, Op::SubF, &[727, 746, 747], 2166);
                step(f, Op::Equals(Elem::Int), &[68, 72, 89], 2167);
                step(f, Op::Select(ValueType::Int), &[89, 73, 72, 70], 2168);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 70, 90], 2169);
                step(f, Op::ArrayAt(Elem::Float), &[2, 70, 751], 2170);
                step(f, Op::RemapF, &[751, 805, 806, 804, 806, 98, 752], 2171);
                step(f, Op::RemapF, &[751, 804, 115, 806, 804, 98, 753], 2172);
                step(f, Op::MaxF, &[752, 753, 754], 2173);
                step(f, Op::Select(ValueType::Float), &[90, 806, 754, 755], 2174);
                step(f, Op::MulF, &[755, 756, 757], 2175);
                step(f, Op::LerpF, &[740, 747, 757, 758], 2176);
                step(f, Op::ArrayAt(Elem::Float), &[2, 68, 748], 2177);
                step(f, Op::RemapF, &[748, 805, 806, 804, 806, 98, 749], 2178);
                step(f, Op::MulF, &[758, 749, 759], 2179);
                step(f, Op::RemapF, &[748, 804, 115, 806, 804, 98, 750], 2180);
                step(f, Op::MulF, &[740, 750, 760], 2181);
                step(f, Op::MaxF, &[759, 760, 761], 2182);
                step(f, Op::Select(ValueType::Float), &[88, 740, 761, 762], 2183);
                step(f, Op::MaxF, &[724, 762, 763], 2184);
                step(f, Op::Copy(ValueType::Float), &[763, 724], 2185);
                step(f, Op::Jump, &[2138], 2186)
            }
            2186 => {
                step(f, Op::ClampF, &[724, 804, 113, 764], 2187);
                step(f, Op::Copy(ValueType::Float), &[764, 723], 2188);
                step(f, Op::Jump, &[2189], 2189)
            }
            2189 => {
                step(f, Op::MakeVector, &[16, 804, 804, 383], 2190);
                step(f, Op::MakeVector, &[723, 804, 804, 384], 2191);
                step(f, Op::MakeVector, &[17, 804, 804, 385], 2192);
                step(f, Op::GreaterF, &[723, 16, 91], 2193);
                step(f, Op::Select(ValueType::Float), &[91, 117, 114, 765], 2194);
                step(f, Op::Copy(ValueType::Vec3), &[383, 386], 2195);
                step(f, Op::Copy(ValueType::Vec3), &[384, 387], 2196);
                step(f, Op::Copy(ValueType::Vec3), &[385, 388], 2197);
                step(f, Op::Copy(ValueType::Float), &[765, 766], 2198);
                step(f, Op::Copy(ValueType::Float), &[47, 767], 2199);
                step(f, Op::Copy(ValueType::Vec3), &[420, 389], 2200);
                step(f, Op::SubV, &[387, 388, 390], 2201);
                step(f, Op::DeltaTime, &[768], 2202);
                step(f, Op::DivF, &[767, 768, 769], 2203);
                step(f, Op::ScaleV, &[390, 769, 391], 2204);
                step(f, Op::AddV, &[387, 391, 392], 2205);
                step(f, Op::AddV, &[388, 391, 393], 2206);
                step(f, Op::SubV, &[386, 393, 394], 2207);
                step(f, Op::FloatLerp, &[804, 806, 766, 770], 2208);
                step(f, Op::SubF, &[806, 770, 771], 2209);
                step(f, Op::ScaleV, &[394, 771, 395], 2210);
                step(f, Op::AddV, &[392, 395, 397], 2211);
                step(f, Op::MulF, &[766, 768, 772], 2212);
                step(f, Op::GreaterF, &[772, 804, 92], 2213);
                step(f, Op::DivF, &[770, 772, 773], 2214);
                step(f, Op::Select(ValueType::Float), &[92, 773, 806, 774], 2215);
                step(f, Op::ScaleV, &[390, 774, 396], 2216);
                step(f, Op::SubV, &[397, 396, 398], 2217);
                step(f, Op::Copy(ValueType::Vec3), &[398, 389], 2218);
                step(f, Op::Jump, &[2219], 2219)
            }
            2219 => {
                step(f, Op::BreakVector, &[389, 775, 776, 777], 2220);
                step(f, Op::Select(ValueType::Float), &[93, 723, 775, 778], 2221);
                step(f, Op::Copy(ValueType::Float), &[778, 16], 2222);
                step(f, Op::Copy(ValueType::Float), &[723, 17], 2223);
                step(f, Op::GetTransform, &[47, 72, 99, 104], 2224);
                step(f, Op::BreakTransform, &[104, 399, 87, 400], 2225);
                step(f, Op::MakeVector, &[804, 804, 16, 401], 2226);
                step(f, Op::SubV, &[399, 401, 402], 2227);
                step(f, Op::MakeTransform, &[402, 87, 421, 105], 2228);
                step(f, Op::SetTransform, &[48, 105, 72, 98, 806], 2229);
                step(f, Op::JumpIfFalse, &[8, 2237], 2230)
            }
            2230 => {
                step(f, Op::GetTransform, &[47, 72, 99, 104], 2231);
                step(f, Op::BreakTransform, &[104, 399, 87, 400], 2232);
                step(f, Op::MakeVector, &[804, 804, 16, 401], 2233);
                step(f, Op::SubV, &[399, 401, 402], 2234);
                step(f, Op::MakeTransform, &[402, 87, 421, 105], 2235);
                step(f, Op::DrawTransform, &[105, 826, 805], 2236);
                step(f, Op::Jump, &[2237], 2237)
            }
            2237 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 2238);
                step(f, Op::Copy(ValueType::Int), &[72, 8], 2239);
                2239
            }
            2239 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 8, 2, 9, 10, 2299], 2240)
            }
            2240 => {
                step(f, Op::Copy(ValueType::Bone), &[2, 28], 2241);
                step(f, Op::Copy(ValueType::Int), &[9, 71], 2242);
                step(f, Op::GetParent, &[28, 29], 2243);
                step(f, Op::GetParent, &[29, 30], 2244);
                step(f, Op::GetTransform, &[30, 72, 99, 106], 2245);
                step(f, Op::BreakTransform, &[106, 403, 88, 404], 2246);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 71, 107], 2247);
                step(f, Op::BreakTransform, &[107, 405, 89, 406], 2248);
                step(f, Op::SubV, &[405, 403, 407], 2249);
                step(f, Op::LengthV, &[407, 794], 2250);
                step(f, Op::ArrayAt(Elem::Float), &[1, 71, 779], 2251);
                step(f, Op::MulF, &[779, 123, 780], 2252);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 71, 94], 2253);
                step(f, Op::ArrayAt(Elem::Float), &[2, 71, 781], 2254);
                step(f, Op::ClampF, &[781, 804, 806, 782], 2255);
                step(f, Op::LessF, &[782, 805, 95], 2256);
                step(f, Op::RemapF, &[782, 125, 126, 804, 806, 98, 785], 2257);
                step(f, Op::MulF, &[785, 785, 786], 2258);
                step(f, Op::MulF, &[785, 809, 787], 2259);
                step(f, Op::SubF, &[810, 787, 788], 2260);
                step(f, Op::MulF, &[786, 788, 789], 2261);
                step(f, Op::MulF, &[782, 814, 783], 2262);
                step(f, Op::SinF, &[783, 784], 2263);
                step(f, Op::MaxF, &[789, 784, 790], 2264);
                step(f, Op::Select(ValueType::Float), &[95, 790, 784, 791], 2265);
                step(f, Op::MulF, &[791, 124, 792], 2266);
                step(f, Op::Select(ValueType::Float), &[94, 804, 792, 793], 2267);
                step(f, Op::SubF, &[780, 793, 795], 2268);
                step(f, Op::SubF, &[794, 795, 796], 2269);
                step(f, Op::MaxF, &[796, 804, 797], 2270);
                step(f, Op::MulF, &[797, 797, 798], 2271);
                step(f, Op::AddF, &[797, 793, 799], 2272);
                step(f, Op::DivF, &[798, 799, 800], 2273);
                step(f, Op::SubF, &[794, 800, 801], 2274);
                step(f, Op::DivF, &[801, 794, 802], 2275);
                step(f, Op::ScaleV, &[407, 802, 408], 2276);
                step(f, Op::AddV, &[403, 408, 409], 2277);
                step(f, Op::ClampSpatially, &[409, 403, 804, 780, 410], 2278);
                step(f, Op::MakeTransform, &[410, 89, 421, 108], 2279);
                step(f, Op::Equals(Elem::Int), &[71, 72, 96], 2280);
                step(f, Op::Select(ValueType::Vec3), &[96, 427, 426, 415], 2281);
                step(f, Op::Select(ValueType::Vec3), &[96, 424, 428, 416], 2282);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 71, 109], 2283);
                step(f, Op::BreakTransform, &[109, 411, 90, 412], 2284);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 71, 413], 2285);
                step(f, Op::KneeVector, &[90, 0, 413, 127, 128, 414], 2286);
                step(f, Op::TwoBoneIK, &[30, 29, 28, 108, 415, 416, 414, 72, 806, 99, 823, 824, 98, 97, 803], 2287);
                step(f, Op::JumpIfFalse, &[8, 2298], 2288)
            }
            2288 => {
                step(f, Op::GetParent, &[28, 29], 2289);
                step(f, Op::GetTransform, &[29, 72, 99, 110], 2290);
                step(f, Op::BreakTransform, &[110, 417, 91, 418], 2291);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 71, 109], 2292);
                step(f, Op::BreakTransform, &[109, 411, 90, 412], 2293);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 71, 413], 2294);
                step(f, Op::KneeVector, &[90, 0, 413, 127, 128, 414], 2295);
                step(f, Op::AddV, &[417, 414, 419], 2296);
                step(f, Op::DrawLine, &[417, 419, 805, 429], 2297);
                step(f, Op::Jump, &[2298], 2298)
            }
            2298 => {
                step(f, Op::Jump, &[2239], 2299)
            }
            2299 => {
                step(f, Op::End, &[], 2300)
            }
            _ => return,
        } };
    }
}
