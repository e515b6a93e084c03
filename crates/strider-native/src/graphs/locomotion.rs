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
    fingerprint: 0x91f43b51111f0c6b,
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
                step(f, Op::LengthV, &[36, 121], 461);
                step(f, Op::GreaterF, &[121, 29, 10], 462);
                step(f, Op::Copy(ValueType::Bool), &[10, 2], 463);
                step(f, Op::MakeRelative, &[13, 12, 17], 464);
                step(f, Op::Select(ValueType::Transform), &[10, 108, 17, 18], 465);
                step(f, Op::Copy(ValueType::Transform), &[18, 2], 466);
                step(f, Op::InverseT, &[13, 15], 467);
                step(f, Op::MulT, &[12, 15, 16], 468);
                step(f, Op::Copy(ValueType::Transform), &[16, 1], 469);
                step(f, Op::TransformVector, &[2, 0, 39], 470);
                step(f, Op::InverseT, &[12, 14], 471);
                step(f, Op::DeltaTime, &[120], 472);
                step(f, Op::DivF, &[630, 120, 122], 473);
                step(f, Op::ScaleV, &[36, 122, 37], 474);
                step(f, Op::TransformVector, &[14, 37, 38], 475);
                step(f, Op::Select(ValueType::Vec3), &[2, 39, 38, 41], 476);
                step(f, Op::VectorLerp, &[39, 41, 30, 628, 42], 477);
                step(f, Op::Copy(ValueType::Vec3), &[42, 0], 478);
                step(f, Op::TransformVector, &[2, 1, 40], 479);
                step(f, Op::TransformVector, &[2, 0, 39], 480);
                step(f, Op::Select(ValueType::Vec3), &[2, 39, 38, 41], 481);
                step(f, Op::VectorLerp, &[40, 41, 31, 628, 43], 482);
                step(f, Op::Copy(ValueType::Vec3), &[43, 1], 483);
                step(f, Op::LengthV, &[41, 123], 484);
                step(f, Op::Copy(ValueType::Float), &[123, 0], 485);
                step(f, Op::JumpIfFalse, &[2, 504], 486)
            }
            486 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 12], 487);
                step(f, Op::Copy(ValueType::Int), &[64, 17], 488);
                488
            }
            488 => {
                step(f, Op::ForEachNext(Elem::Bone), &[12, 17, 13, 18, 19, 502], 489)
            }
            489 => {
                step(f, Op::ArrayAt(Elem::Transform), &[7, 18, 20], 490);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 18, 20], 491);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 18, 20], 492);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 18, 20], 493);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 18, 20], 494);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 18, 20], 495);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 18, 20], 496);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 18, 20], 497);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 18, 20], 498);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 18, 20], 499);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 18, 20], 500);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 18, 20], 501);
                step(f, Op::Jump, &[488], 502)
            }
            502 => {
                step(f, Op::Copy(ValueType::Float), &[628, 11], 503);
                step(f, Op::Jump, &[504], 504)
            }
            504 => {
                step(f, Op::WorldTransform, &[12], 505);
                step(f, Op::Copy(ValueType::Transform), &[12, 0], 506);
                step(f, Op::Copy(ValueType::Bool), &[78, 0], 507);
                step(f, Op::JumpIfFalse, &[8, 514], 508)
            }
            508 => {
                step(f, Op::GetTransform, &[34, 64, 78, 19], 509);
                step(f, Op::BreakTransform, &[19, 44, 9, 45], 510);
                step(f, Op::ScaleV, &[0, 631, 46], 511);
                step(f, Op::AddV, &[44, 46, 47], 512);
                step(f, Op::DrawArrow, &[44, 47, 629, 382], 513);
                step(f, Op::Jump, &[514], 514)
            }
            514 => {
                step(f, Op::Copy(ValueType::Float), &[628, 124], 515);
                step(f, Op::Copy(ValueType::Float), &[630, 125], 516);
                step(f, Op::Copy(ValueType::Float), &[630, 126], 517);
                step(f, Op::Copy(ValueType::Bool), &[79, 11], 518);
                step(f, Op::Copy(ValueType::Bool), &[79, 12], 519);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[7, 8], 520);
                step(f, Op::Copy(ValueType::Int), &[64, 25], 521);
                step(f, Op::MakeVector, &[628, 628, 48, 52], 522);
                522
            }
            522 => {
                step(f, Op::ForEachNext(Elem::Transform), &[8, 25, 21, 26, 27, 533], 523)
            }
            523 => {
                step(f, Op::BreakTransform, &[21, 48, 10, 49], 524);
                step(f, Op::TransformPoint, &[2, 48, 50], 525);
                step(f, Op::LerpV, &[50, 48, 126, 51], 526);
                step(f, Op::AddV, &[51, 52, 53], 527);
                step(f, Op::SubV, &[51, 52, 54], 528);
                step(f, Op::LineTrace, &[53, 54, 13, 55, 56, 127], 529);
                step(f, Op::JumpIfFalse, &[13, 532], 530)
            }
            530 => {
                step(f, Op::Copy(ValueType::Bool), &[78, 12], 531);
                step(f, Op::Jump, &[532], 532)
            }
            532 => {
                step(f, Op::Jump, &[522], 533)
            }
            533 => {
                step(f, Op::Copy(ValueType::Bool), &[12, 11], 534);
                step(f, Op::Jump, &[535], 535)
            }
            535 => {
                step(f, Op::Or, &[11, 7, 14], 536);
                step(f, Op::NotEquals(Elem::Bool), &[14, 5, 15], 537);
                step(f, Op::JumpIfFalse, &[15, 572], 538)
            }
            538 => {
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 539);
                step(f, Op::JumpIfFalse, &[16, 571], 540)
            }
            540 => {
                step(f, Op::Copy(ValueType::Int), &[1, 24], 541);
                step(f, Op::Copy(ValueType::Int), &[64, 20], 542);
                542
            }
            542 => {
                step(f, Op::ForNext, &[20, 24, 22, 570], 543)
            }
            543 => {
                step(f, Op::AddF, &[124, 125, 128], 544);
                step(f, Op::MulF, &[128, 629, 129], 545);
                step(f, Op::Copy(ValueType::Float), &[129, 130], 546);
                step(f, Op::Copy(ValueType::Bool), &[79, 17], 547);
                step(f, Op::Copy(ValueType::Bool), &[79, 18], 548);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[7, 9], 549);
                step(f, Op::Copy(ValueType::Int), &[64, 28], 550);
                step(f, Op::MakeVector, &[628, 628, 48, 61], 551);
                551
            }
            551 => {
                step(f, Op::ForEachNext(Elem::Transform), &[9, 28, 22, 29, 30, 562], 552)
            }
            552 => {
                step(f, Op::BreakTransform, &[22, 57, 11, 58], 553);
                step(f, Op::TransformPoint, &[2, 57, 59], 554);
                step(f, Op::LerpV, &[59, 57, 130, 60], 555);
                step(f, Op::AddV, &[60, 61, 62], 556);
                step(f, Op::SubV, &[60, 61, 63], 557);
                step(f, Op::LineTrace, &[62, 63, 19, 64, 65, 131], 558);
                step(f, Op::JumpIfFalse, &[19, 561], 559)
            }
            559 => {
                step(f, Op::Copy(ValueType::Bool), &[78, 18], 560);
                step(f, Op::Jump, &[561], 561)
            }
            561 => {
                step(f, Op::Jump, &[551], 562)
            }
            562 => {
                step(f, Op::Copy(ValueType::Bool), &[18, 17], 563);
                step(f, Op::Jump, &[564], 564)
            }
            564 => {
                step(f, Op::Equals(Elem::Bool), &[17, 6, 20], 565);
                step(f, Op::JumpIfFalse, &[20, 568], 566)
            }
            566 => {
                step(f, Op::Copy(ValueType::Float), &[129, 124], 567);
                step(f, Op::Jump, &[569], 568)
            }
            568 => {
                step(f, Op::Copy(ValueType::Float), &[129, 125], 569);
                569
            }
            569 => {
                step(f, Op::Jump, &[542], 570)
            }
            570 => {
                step(f, Op::Jump, &[571], 571)
            }
            571 => {
                step(f, Op::Jump, &[572], 572)
            }
            572 => {
                step(f, Op::Select(ValueType::Float), &[5, 632, 630, 137], 573);
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 574);
                step(f, Op::AddF, &[124, 125, 128], 575);
                step(f, Op::MulF, &[128, 629, 132], 576);
                step(f, Op::Select(ValueType::Float), &[16, 132, 629, 133], 577);
                step(f, Op::Select(ValueType::Float), &[15, 133, 628, 139], 578);
                step(f, Op::MulF, &[137, 139, 141], 579);
                step(f, Op::DeltaTime, &[135], 580);
                step(f, Op::DivF, &[135, 108, 136], 581);
                step(f, Op::MulF, &[141, 136, 142], 582);
                step(f, Op::AddF, &[14, 142, 143], 583);
                step(f, Op::ClampF, &[143, 628, 630, 144], 584);
                step(f, Op::Select(ValueType::Float), &[14, 632, 630, 138], 585);
                step(f, Op::SubF, &[630, 133, 134], 586);
                step(f, Op::Select(ValueType::Float), &[15, 134, 630, 140], 587);
                step(f, Op::MulF, &[138, 140, 145], 588);
                step(f, Op::MulF, &[145, 136, 146], 589);
                step(f, Op::AddF, &[144, 146, 147], 590);
                step(f, Op::ClampF, &[147, 628, 630, 148], 591);
                step(f, Op::MulF, &[148, 148, 149], 592);
                step(f, Op::MulF, &[148, 633, 150], 593);
                step(f, Op::SubF, &[634, 150, 151], 594);
                step(f, Op::MulF, &[149, 151, 152], 595);
                step(f, Op::AddF, &[15, 152, 153], 596);
                step(f, Op::MulF, &[153, 629, 154], 597);
                step(f, Op::SubF, &[630, 154, 155], 598);
                step(f, Op::MulF, &[155, 155, 156], 599);
                step(f, Op::SubF, &[630, 156, 157], 600);
                step(f, Op::Copy(ValueType::Float), &[157, 16], 601);
                step(f, Op::Copy(ValueType::Float), &[152, 15], 602);
                step(f, Op::Copy(ValueType::Float), &[148, 14], 603);
                step(f, Op::GreaterF, &[15, 628, 21], 604);
                step(f, Op::TransformVector, &[2, 3, 66], 605);
                step(f, Op::Select(ValueType::Vec3), &[21, 66, 0, 67], 606);
                step(f, Op::Copy(ValueType::Vec3), &[67, 3], 607);
                step(f, Op::LerpV, &[0, 3, 15, 68], 608);
                step(f, Op::Select(ValueType::Vec3), &[21, 68, 0, 69], 609);
                step(f, Op::Copy(ValueType::Vec3), &[69, 2], 610);
                step(f, Op::Copy(ValueType::Bool), &[14, 5], 611);
                step(f, Op::Copy(ValueType::Bool), &[11, 6], 612);
                step(f, Op::Copy(ValueType::Bool), &[79, 7], 613);
                step(f, Op::Copy(ValueType::Bool), &[79, 23], 614);
                step(f, Op::Copy(ValueType::Bool), &[78, 24], 615);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 616);
                step(f, Op::Copy(ValueType::Int), &[64, 34], 617);
                617
            }
            617 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 34, 25, 35, 36, 623], 618)
            }
            618 => {
                step(f, Op::Not, &[25, 26], 619);
                step(f, Op::JumpIfFalse, &[26, 622], 620)
            }
            620 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 24], 621);
                step(f, Op::Jump, &[622], 622)
            }
            622 => {
                step(f, Op::Jump, &[617], 623)
            }
            623 => {
                step(f, Op::Copy(ValueType::Bool), &[24, 23], 624);
                step(f, Op::Jump, &[625], 625)
            }
            625 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 27], 626);
                step(f, Op::Copy(ValueType::Bool), &[78, 28], 627);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 628);
                step(f, Op::Copy(ValueType::Int), &[64, 37], 629);
                629
            }
            629 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 37, 15, 38, 39, 644], 630)
            }
            630 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 38, 23], 631);
                step(f, Op::BreakTransform, &[23, 70, 12, 71], 632);
                step(f, Op::BreakVector, &[70, 166, 167, 168], 633);
                step(f, Op::MakeVector, &[166, 167, 628, 74], 634);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 38, 24], 635);
                step(f, Op::BreakTransform, &[24, 72, 13, 73], 636);
                step(f, Op::BreakVector, &[72, 169, 170, 171], 637);
                step(f, Op::MakeVector, &[169, 170, 628, 75], 638);
                step(f, Op::DistanceV, &[74, 75, 172], 639);
                step(f, Op::GreaterF, &[172, 25, 29], 640);
                step(f, Op::JumpIfFalse, &[29, 643], 641)
            }
            641 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 28], 642);
                step(f, Op::Jump, &[643], 643)
            }
            643 => {
                step(f, Op::Jump, &[629], 644)
            }
            644 => {
                step(f, Op::Copy(ValueType::Bool), &[28, 27], 645);
                step(f, Op::Jump, &[646], 646)
            }
            646 => {
                step(f, Op::And, &[23, 27, 30], 647);
                step(f, Op::LengthV, &[2, 158], 648);
                step(f, Op::GreaterF, &[158, 23, 22], 649);
                step(f, Op::GreaterF, &[0, 23, 31], 650);
                step(f, Op::Or, &[22, 31, 32], 651);
                step(f, Op::Not, &[32, 33], 652);
                step(f, Op::And, &[30, 33, 38], 653);
                step(f, Op::DeltaTime, &[197], 654);
                step(f, Op::MulF, &[197, 28, 198], 655);
                step(f, Op::AddF, &[7, 198, 199], 656);
                step(f, Op::GreaterF, &[7, 629, 39], 657);
                step(f, Op::AddF, &[27, 629, 195], 658);
                step(f, Op::Select(ValueType::Float), &[39, 195, 27, 196], 659);
                step(f, Op::MinF, &[199, 196, 200], 660);
                step(f, Op::NotEquals(Elem::Bool), &[33, 4, 34], 661);
                step(f, Op::Not, &[30, 35], 662);
                step(f, Op::And, &[34, 35, 36], 663);
                step(f, Op::SubF, &[8, 23, 181], 664);
                step(f, Op::SubF, &[8, 158, 182], 665);
                step(f, Op::DivF, &[181, 182, 183], 666);
                step(f, Op::ClampF, &[183, 628, 630, 184], 667);
                step(f, Op::MulF, &[3, 184, 186], 668);
                step(f, Op::RemapF, &[158, 23, 24, 628, 630, 78, 173], 669);
                step(f, Op::MaxF, &[173, 4, 174], 670);
                step(f, Op::Select(ValueType::Float), &[23, 630, 174, 175], 671);
                step(f, Op::Select(ValueType::Float), &[33, 26, 175, 176], 672);
                step(f, Op::Select(ValueType::Float), &[30, 173, 176, 177], 673);
                step(f, Op::SubF, &[630, 15, 178], 674);
                step(f, Op::MulF, &[177, 178, 179], 675);
                step(f, Op::LerpF, &[17, 38, 10, 161], 676);
                step(f, Op::RemapF, &[158, 20, 21, 18, 19, 78, 159], 677);
                step(f, Op::LerpF, &[159, 37, 10, 160], 678);
                step(f, Op::MaxF, &[158, 22, 162], 679);
                step(f, Op::DivF, &[160, 162, 163], 680);
                step(f, Op::AddF, &[161, 163, 164], 681);
                step(f, Op::DivF, &[179, 164, 180], 682);
                step(f, Op::SubF, &[630, 184, 185], 683);
                step(f, Op::MulF, &[180, 185, 187], 684);
                step(f, Op::AddF, &[186, 187, 188], 685);
                step(f, Op::MulF, &[188, 633, 189], 686);
                step(f, Op::AddF, &[3, 180, 190], 687);
                step(f, Op::Select(ValueType::Float), &[36, 189, 190, 191], 688);
                step(f, Op::DivF, &[633, 191, 192], 689);
                step(f, Op::GreaterF, &[191, 628, 37], 690);
                step(f, Op::CycleStep, &[7, 192, 628, 37, 193, 194], 691);
                step(f, Op::Select(ValueType::Float), &[38, 200, 193, 201], 692);
                step(f, Op::Copy(ValueType::Float), &[201, 7], 693);
                step(f, Op::Copy(ValueType::Float), &[180, 3], 694);
                step(f, Op::Copy(ValueType::Bool), &[22, 3], 695);
                step(f, Op::Copy(ValueType::Float), &[163, 1], 696);
                step(f, Op::Copy(ValueType::Float), &[164, 2], 697);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 698);
                step(f, Op::Copy(ValueType::Int), &[64, 31], 699);
                699
            }
            699 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 31, 14, 32, 33, 873], 700)
            }
            700 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 32, 215], 701);
                step(f, Op::ToFloat, &[32, 202], 702);
                step(f, Op::MulF, &[202, 629, 203], 703);
                step(f, Op::AddF, &[7, 203, 204], 704);
                step(f, Op::FractF, &[204, 205], 705);
                step(f, Op::SubF, &[215, 205, 217], 706);
                step(f, Op::GreaterF, &[217, 629, 40], 707);
                step(f, Op::ArrayAt(Elem::Float), &[2, 32, 216], 708);
                step(f, Op::Select(ValueType::Float), &[40, 628, 216, 244], 709);
                step(f, Op::ArraySetAt(Elem::Float), &[3, 32, 244], 710);
                step(f, Op::ArrayAt(Elem::Float), &[0, 32, 215], 711);
                step(f, Op::ToFloat, &[32, 202], 712);
                step(f, Op::MulF, &[202, 629, 203], 713);
                step(f, Op::AddF, &[7, 203, 204], 714);
                step(f, Op::FractF, &[204, 205], 715);
                step(f, Op::SubF, &[215, 205, 217], 716);
                step(f, Op::GreaterF, &[217, 629, 40], 717);
                step(f, Op::SubF, &[630, 215, 238], 718);
                step(f, Op::AddF, &[205, 238, 239], 719);
                step(f, Op::DivF, &[205, 239, 240], 720);
                step(f, Op::LengthV, &[2, 158], 721);
                step(f, Op::GreaterF, &[158, 23, 22], 722);
                step(f, Op::GreaterF, &[0, 23, 31], 723);
                step(f, Op::Or, &[22, 31, 32], 724);
                step(f, Op::Not, &[32, 33], 725);
                step(f, Op::NotEquals(Elem::Bool), &[33, 4, 34], 726);
                step(f, Op::Copy(ValueType::Bool), &[79, 23], 727);
                step(f, Op::Copy(ValueType::Bool), &[78, 24], 728);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 729);
                step(f, Op::Copy(ValueType::Int), &[64, 34], 730);
                730
            }
            730 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 34, 25, 35, 36, 736], 731)
            }
            731 => {
                step(f, Op::Not, &[25, 26], 732);
                step(f, Op::JumpIfFalse, &[26, 735], 733)
            }
            733 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 24], 734);
                step(f, Op::Jump, &[735], 735)
            }
            735 => {
                step(f, Op::Jump, &[730], 736)
            }
            736 => {
                step(f, Op::Copy(ValueType::Bool), &[24, 23], 737);
                step(f, Op::Jump, &[738], 738)
            }
            738 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 27], 739);
                step(f, Op::Copy(ValueType::Bool), &[78, 28], 740);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 741);
                step(f, Op::Copy(ValueType::Int), &[64, 37], 742);
                742
            }
            742 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 37, 15, 38, 39, 757], 743)
            }
            743 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 38, 23], 744);
                step(f, Op::BreakTransform, &[23, 70, 12, 71], 745);
                step(f, Op::BreakVector, &[70, 166, 167, 168], 746);
                step(f, Op::MakeVector, &[166, 167, 628, 74], 747);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 38, 24], 748);
                step(f, Op::BreakTransform, &[24, 72, 13, 73], 749);
                step(f, Op::BreakVector, &[72, 169, 170, 171], 750);
                step(f, Op::MakeVector, &[169, 170, 628, 75], 751);
                step(f, Op::DistanceV, &[74, 75, 172], 752);
                step(f, Op::GreaterF, &[172, 25, 29], 753);
                step(f, Op::JumpIfFalse, &[29, 756], 754)
            }
            754 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 28], 755);
                step(f, Op::Jump, &[756], 756)
            }
            756 => {
                step(f, Op::Jump, &[742], 757)
            }
            757 => {
                step(f, Op::Copy(ValueType::Bool), &[28, 27], 758);
                step(f, Op::Jump, &[759], 759)
            }
            759 => {
                step(f, Op::And, &[23, 27, 30], 760);
                step(f, Op::Not, &[30, 35], 761);
                step(f, Op::And, &[34, 35, 36], 762);
                step(f, Op::SubF, &[8, 23, 181], 763);
                step(f, Op::SubF, &[8, 158, 182], 764);
                step(f, Op::DivF, &[181, 182, 183], 765);
                step(f, Op::ClampF, &[183, 628, 630, 184], 766);
                step(f, Op::MulF, &[6, 184, 207], 767);
                step(f, Op::RemapF, &[158, 23, 24, 628, 630, 78, 173], 768);
                step(f, Op::MaxF, &[173, 4, 174], 769);
                step(f, Op::Select(ValueType::Float), &[23, 630, 174, 175], 770);
                step(f, Op::Select(ValueType::Float), &[33, 26, 175, 176], 771);
                step(f, Op::Select(ValueType::Float), &[30, 173, 176, 177], 772);
                step(f, Op::SubF, &[630, 15, 178], 773);
                step(f, Op::MulF, &[177, 178, 179], 774);
                step(f, Op::LerpF, &[17, 38, 10, 161], 775);
                step(f, Op::DivF, &[179, 161, 206], 776);
                step(f, Op::SubF, &[630, 184, 185], 777);
                step(f, Op::MulF, &[206, 185, 208], 778);
                step(f, Op::AddF, &[207, 208, 209], 779);
                step(f, Op::MulF, &[209, 633, 210], 780);
                step(f, Op::AddF, &[6, 206, 211], 781);
                step(f, Op::Select(ValueType::Float), &[36, 210, 211, 212], 782);
                step(f, Op::DeltaTime, &[197], 783);
                step(f, Op::MulF, &[197, 629, 213], 784);
                step(f, Op::MulF, &[212, 213, 214], 785);
                step(f, Op::MulF, &[240, 214, 241], 786);
                step(f, Op::ArrayAt(Elem::Float), &[2, 32, 216], 787);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 32, 41], 788);
                step(f, Op::RemapF, &[158, 20, 21, 18, 19, 78, 159], 789);
                step(f, Op::LerpF, &[159, 37, 10, 160], 790);
                step(f, Op::MaxF, &[158, 22, 162], 791);
                step(f, Op::DivF, &[160, 162, 163], 792);
                step(f, Op::AddF, &[161, 163, 164], 793);
                step(f, Op::DivF, &[161, 164, 165], 794);
                step(f, Op::SubF, &[165, 5, 218], 795);
                step(f, Op::MaxF, &[218, 628, 219], 796);
                step(f, Op::DivF, &[219, 165, 220], 797);
                step(f, Op::SubF, &[630, 10, 222], 798);
                step(f, Op::MulF, &[220, 222, 229], 799);
                step(f, Op::MulF, &[229, 178, 230], 800);
                step(f, Op::MulF, &[230, 106, 231], 801);
                step(f, Op::DivF, &[42, 197, 227], 802);
                step(f, Op::SubF, &[629, 227, 228], 803);
                step(f, Op::MulF, &[231, 228, 232], 804);
                step(f, Op::SubF, &[630, 232, 233], 805);
                step(f, Op::MulF, &[214, 233, 234], 806);
                step(f, Op::Select(ValueType::Float), &[41, 214, 234, 235], 807);
                step(f, Op::MulF, &[220, 216, 221], 808);
                step(f, Op::MulF, &[221, 222, 223], 809);
                step(f, Op::MulF, &[223, 178, 224], 810);
                step(f, Op::MulF, &[224, 106, 225], 811);
                step(f, Op::Select(ValueType::Float), &[41, 628, 225, 226], 812);
                step(f, Op::SubF, &[235, 226, 236], 813);
                step(f, Op::AddF, &[216, 236, 237], 814);
                step(f, Op::Select(ValueType::Float), &[40, 241, 237, 242], 815);
                step(f, Op::MinF, &[242, 633, 243], 816);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 32, 243], 817);
                step(f, Op::ArrayAt(Elem::Float), &[0, 32, 215], 818);
                step(f, Op::ToFloat, &[32, 202], 819);
                step(f, Op::MulF, &[202, 629, 203], 820);
                step(f, Op::AddF, &[7, 203, 204], 821);
                step(f, Op::FractF, &[204, 205], 822);
                step(f, Op::SubF, &[215, 205, 217], 823);
                step(f, Op::GreaterF, &[217, 629, 40], 824);
                step(f, Op::JumpIfFalse, &[40, 871], 825)
            }
            825 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 23], 826);
                step(f, Op::Copy(ValueType::Bool), &[78, 24], 827);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 828);
                step(f, Op::Copy(ValueType::Int), &[64, 34], 829);
                829
            }
            829 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 34, 25, 35, 36, 835], 830)
            }
            830 => {
                step(f, Op::Not, &[25, 26], 831);
                step(f, Op::JumpIfFalse, &[26, 834], 832)
            }
            832 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 24], 833);
                step(f, Op::Jump, &[834], 834)
            }
            834 => {
                step(f, Op::Jump, &[829], 835)
            }
            835 => {
                step(f, Op::Copy(ValueType::Bool), &[24, 23], 836);
                step(f, Op::Jump, &[837], 837)
            }
            837 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 27], 838);
                step(f, Op::Copy(ValueType::Bool), &[78, 28], 839);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 840);
                step(f, Op::Copy(ValueType::Int), &[64, 37], 841);
                841
            }
            841 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 37, 15, 38, 39, 856], 842)
            }
            842 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 38, 23], 843);
                step(f, Op::BreakTransform, &[23, 70, 12, 71], 844);
                step(f, Op::BreakVector, &[70, 166, 167, 168], 845);
                step(f, Op::MakeVector, &[166, 167, 628, 74], 846);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 38, 24], 847);
                step(f, Op::BreakTransform, &[24, 72, 13, 73], 848);
                step(f, Op::BreakVector, &[72, 169, 170, 171], 849);
                step(f, Op::MakeVector, &[169, 170, 628, 75], 850);
                step(f, Op::DistanceV, &[74, 75, 172], 851);
                step(f, Op::GreaterF, &[172, 25, 29], 852);
                step(f, Op::JumpIfFalse, &[29, 855], 853)
            }
            853 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 28], 854);
                step(f, Op::Jump, &[855], 855)
            }
            855 => {
                step(f, Op::Jump, &[841], 856)
            }
            856 => {
                step(f, Op::Copy(ValueType::Bool), &[28, 27], 857);
                step(f, Op::Jump, &[858], 858)
            }
            858 => {
                step(f, Op::And, &[23, 27, 30], 859);
                step(f, Op::LengthV, &[2, 158], 860);
                step(f, Op::RemapF, &[158, 23, 24, 628, 630, 78, 173], 861);
                step(f, Op::GreaterF, &[158, 23, 22], 862);
                step(f, Op::GreaterF, &[0, 23, 31], 863);
                step(f, Op::Or, &[22, 31, 32], 864);
                step(f, Op::Not, &[32, 33], 865);
                step(f, Op::MaxF, &[173, 4, 174], 866);
                step(f, Op::Select(ValueType::Float), &[23, 630, 174, 175], 867);
                step(f, Op::Select(ValueType::Float), &[33, 26, 175, 176], 868);
                step(f, Op::Select(ValueType::Float), &[30, 173, 176, 177], 869);
                step(f, Op::Copy(ValueType::Float), &[177, 4], 870);
                step(f, Op::Jump, &[871], 871)
            }
            871 => {
                step(f, Op::ArraySetAt(Elem::Float), &[0, 32, 205], 872);
                step(f, Op::Jump, &[699], 873)
            }
            873 => {
                step(f, Op::LerpF, &[17, 38, 10, 161], 874);
                step(f, Op::LengthV, &[2, 158], 875);
                step(f, Op::RemapF, &[158, 20, 21, 18, 19, 78, 159], 876);
                step(f, Op::LerpF, &[159, 37, 10, 160], 877);
                step(f, Op::MaxF, &[158, 22, 162], 878);
                step(f, Op::DivF, &[160, 162, 163], 879);
                step(f, Op::AddF, &[161, 163, 164], 880);
                step(f, Op::DivF, &[161, 164, 165], 881);
                step(f, Op::Copy(ValueType::Float), &[165, 5], 882);
                step(f, Op::GreaterF, &[158, 23, 22], 883);
                step(f, Op::GreaterF, &[0, 23, 31], 884);
                step(f, Op::Or, &[22, 31, 32], 885);
                step(f, Op::Not, &[32, 33], 886);
                step(f, Op::Copy(ValueType::Bool), &[33, 4], 887);
                step(f, Op::Copy(ValueType::Float), &[158, 8], 888);
                step(f, Op::Copy(ValueType::Bool), &[79, 23], 889);
                step(f, Op::Copy(ValueType::Bool), &[78, 24], 890);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 891);
                step(f, Op::Copy(ValueType::Int), &[64, 34], 892);
                892
            }
            892 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 34, 25, 35, 36, 898], 893)
            }
            893 => {
                step(f, Op::Not, &[25, 26], 894);
                step(f, Op::JumpIfFalse, &[26, 897], 895)
            }
            895 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 24], 896);
                step(f, Op::Jump, &[897], 897)
            }
            897 => {
                step(f, Op::Jump, &[892], 898)
            }
            898 => {
                step(f, Op::Copy(ValueType::Bool), &[24, 23], 899);
                step(f, Op::Jump, &[900], 900)
            }
            900 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 27], 901);
                step(f, Op::Copy(ValueType::Bool), &[78, 28], 902);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 903);
                step(f, Op::Copy(ValueType::Int), &[64, 37], 904);
                904
            }
            904 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 37, 15, 38, 39, 919], 905)
            }
            905 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 38, 23], 906);
                step(f, Op::BreakTransform, &[23, 70, 12, 71], 907);
                step(f, Op::BreakVector, &[70, 166, 167, 168], 908);
                step(f, Op::MakeVector, &[166, 167, 628, 74], 909);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 38, 24], 910);
                step(f, Op::BreakTransform, &[24, 72, 13, 73], 911);
                step(f, Op::BreakVector, &[72, 169, 170, 171], 912);
                step(f, Op::MakeVector, &[169, 170, 628, 75], 913);
                step(f, Op::DistanceV, &[74, 75, 172], 914);
                step(f, Op::GreaterF, &[172, 25, 29], 915);
                step(f, Op::JumpIfFalse, &[29, 918], 916)
            }
            916 => {
                step(f, Op::Copy(ValueType::Bool), &[79, 28], 917);
                step(f, Op::Jump, &[918], 918)
            }
            918 => {
                step(f, Op::Jump, &[904], 919)
            }
            919 => {
                step(f, Op::Copy(ValueType::Bool), &[28, 27], 920);
                step(f, Op::Jump, &[921], 921)
            }
            921 => {
                step(f, Op::And, &[23, 27, 30], 922);
                step(f, Op::RemapF, &[158, 23, 24, 628, 630, 78, 173], 923);
                step(f, Op::MaxF, &[173, 4, 174], 924);
                step(f, Op::Select(ValueType::Float), &[23, 630, 174, 175], 925);
                step(f, Op::Select(ValueType::Float), &[33, 26, 175, 176], 926);
                step(f, Op::Select(ValueType::Float), &[30, 173, 176, 177], 927);
                step(f, Op::SubF, &[630, 15, 178], 928);
                step(f, Op::MulF, &[177, 178, 179], 929);
                step(f, Op::DivF, &[179, 161, 206], 930);
                step(f, Op::Copy(ValueType::Float), &[206, 6], 931);
                step(f, Op::Select(ValueType::Vec3), &[3, 2, 380, 76], 932);
                step(f, Op::MovementAngleOffset, &[76, 9, 7, 32, 33, 635, 34, 636, 245], 933);
                step(f, Op::Copy(ValueType::Float), &[245, 9], 934);
                step(f, Op::QuatFromAxisAngle, &[383, 9, 14], 935);
                step(f, Op::Copy(ValueType::Quat), &[14, 0], 936);
                step(f, Op::SinF, &[9, 246], 937);
                step(f, Op::AbsF, &[246, 247], 938);
                step(f, Op::RemapF, &[247, 35, 36, 628, 630, 78, 248], 939);
                step(f, Op::Copy(ValueType::Float), &[248, 10], 940);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 941);
                step(f, Op::Copy(ValueType::Int), &[64, 2], 942);
                942
            }
            942 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 2, 0, 3, 4, 1710], 943)
            }
            943 => {
                step(f, Op::Copy(ValueType::Bone), &[0, 16], 944);
                step(f, Op::Copy(ValueType::Int), &[3, 40], 945);
                step(f, Op::GetTransform, &[35, 64, 78, 25], 946);
                step(f, Op::BreakTransform, &[25, 79, 15, 80], 947);
                step(f, Op::BreakVector, &[79, 260, 261, 262], 948);
                step(f, Op::SubF, &[630, 10, 258], 949);
                step(f, Op::MulF, &[9, 258, 259], 950);
                step(f, Op::QuatFromAxisAngle, &[383, 259, 17], 951);
                step(f, Op::GetTransform, &[16, 64, 78, 26], 952);
                step(f, Op::BreakTransform, &[26, 81, 16, 82], 953);
                step(f, Op::SubV, &[81, 79, 83], 954);
                step(f, Op::BreakVector, &[83, 255, 256, 257], 955);
                step(f, Op::MakeVector, &[255, 256, 628, 84], 956);
                step(f, Op::RotateVector, &[17, 84, 85], 957);
                step(f, Op::BreakVector, &[85, 263, 264, 265], 958);
                step(f, Op::MulF, &[39, 10, 266], 959);
                step(f, Op::Equals(Elem::Int), &[40, 64, 42], 960);
                step(f, Op::Select(ValueType::Float), &[42, 630, 632, 275], 961);
                step(f, Op::MulF, &[266, 275, 267], 962);
                step(f, Op::AddF, &[263, 267, 268], 963);
                step(f, Op::AddF, &[260, 268, 269], 964);
                step(f, Op::AddF, &[261, 264, 270], 965);
                step(f, Op::BreakVector, &[81, 271, 272, 273], 966);
                step(f, Op::SubF, &[273, 43, 274], 967);
                step(f, Op::MakeVector, &[269, 270, 274, 86], 968);
                step(f, Op::ArrayAt(Elem::Float), &[2, 40, 249], 969);
                step(f, Op::SubF, &[630, 249, 250], 970);
                step(f, Op::MaxF, &[250, 628, 251], 971);
                step(f, Op::MulF, &[5, 2, 252], 972);
                step(f, Op::MulF, &[251, 252, 253], 973);
                step(f, Op::ScaleV, &[2, 253, 77], 974);
                step(f, Op::AddV, &[86, 77, 87], 975);
                step(f, Op::MulF, &[1, 629, 254], 976);
                step(f, Op::ScaleV, &[2, 254, 78], 977);
                step(f, Op::AddV, &[87, 78, 88], 978);
                step(f, Op::RotateVector, &[0, 384, 89], 979);
                step(f, Op::Copy(ValueType::Vec3), &[88, 110], 980);
                step(f, Op::Copy(ValueType::Vec3), &[89, 111], 981);
                step(f, Op::Copy(ValueType::Float), &[275, 294], 982);
                step(f, Op::Copy(ValueType::Vec3), &[380, 112], 983);
                step(f, Op::Copy(ValueType::Vec3), &[380, 113], 984);
                step(f, Op::Copy(ValueType::Bool), &[79, 44], 985);
                step(f, Op::Copy(ValueType::Float), &[637, 295], 986);
                step(f, Op::Copy(ValueType::Vec3), &[380, 114], 987);
                step(f, Op::Copy(ValueType::Vec3), &[383, 115], 988);
                step(f, Op::Copy(ValueType::Bool), &[79, 45], 989);
                step(f, Op::MulI, &[0, 0, 46], 990);
                step(f, Op::Copy(ValueType::Int), &[46, 45], 991);
                step(f, Op::Copy(ValueType::Int), &[64, 41], 992);
                step(f, Op::SubI, &[0, 65, 49], 993);
                step(f, Op::DivI, &[49, 66, 50], 994);
                step(f, Op::MakeVector, &[628, 628, 48, 120], 995);
                step(f, Op::ScaleV, &[111, 50, 125], 996);
                996
            }
            996 => {
                step(f, Op::ForNext, &[41, 45, 43, 1036], 997)
            }
            997 => {
                step(f, Op::ModI, &[43, 0, 47], 998);
                step(f, Op::ToFloat, &[47, 296], 999);
                step(f, Op::MulF, &[296, 49, 298], 1000);
                step(f, Op::MulF, &[298, 294, 299], 1001);
                step(f, Op::MakeVector, &[299, 628, 628, 116], 1002);
                step(f, Op::DivI, &[43, 0, 48], 1003);
                step(f, Op::SubI, &[48, 50, 51], 1004);
                step(f, Op::ToFloat, &[51, 297], 1005);
                step(f, Op::MulF, &[297, 49, 300], 1006);
                step(f, Op::ScaleV, &[111, 300, 117], 1007);
                step(f, Op::AddV, &[116, 117, 118], 1008);
                step(f, Op::AddV, &[110, 118, 119], 1009);
                step(f, Op::AddV, &[119, 120, 121], 1010);
                step(f, Op::SubV, &[119, 120, 122], 1011);
                step(f, Op::SphereTrace, &[121, 122, 47, 46, 123, 124, 301], 1012);
                step(f, Op::BreakVector, &[123, 303, 304, 305], 1013);
                step(f, Op::AddV, &[121, 125, 126], 1014);
                step(f, Op::AddV, &[122, 125, 127], 1015);
                step(f, Op::SphereTrace, &[126, 127, 47, 47, 128, 129, 302], 1016);
                step(f, Op::BreakVector, &[128, 306, 307, 308], 1017);
                step(f, Op::SubF, &[305, 308, 309], 1018);
                step(f, Op::AbsF, &[309, 310], 1019);
                step(f, Op::Select(ValueType::Float), &[46, 628, 630, 311], 1020);
                step(f, Op::AddF, &[310, 311, 316], 1021);
                step(f, Op::LengthV, &[118, 312], 1022);
                step(f, Op::RemapF, &[312, 628, 638, 628, 630, 78, 313], 1023);
                step(f, Op::MinF, &[305, 308, 314], 1024);
                step(f, Op::RemapF, &[314, 639, 638, 630, 629, 78, 315], 1025);
                step(f, Op::AddF, &[313, 315, 317], 1026);
                step(f, Op::AddF, &[316, 317, 318], 1027);
                step(f, Op::LessF, &[318, 295, 48], 1028);
                step(f, Op::And, &[46, 48, 49], 1029);
                step(f, Op::JumpIfFalse, &[49, 1035], 1030)
            }
            1030 => {
                step(f, Op::Copy(ValueType::Float), &[318, 295], 1031);
                step(f, Op::Copy(ValueType::Vec3), &[123, 114], 1032);
                step(f, Op::Copy(ValueType::Vec3), &[124, 115], 1033);
                step(f, Op::Copy(ValueType::Bool), &[78, 45], 1034);
                step(f, Op::Jump, &[1035], 1035)
            }
            1035 => {
                step(f, Op::Jump, &[996], 1036)
            }
            1036 => {
                step(f, Op::JumpIfFalse, &[8, 1039], 1037)
            }
            1037 => {
                step(f, Op::DrawSphere, &[114, 47, 384], 1038);
                step(f, Op::Jump, &[1039], 1039)
            }
            1039 => {
                step(f, Op::Copy(ValueType::Vec3), &[114, 112], 1040);
                step(f, Op::Copy(ValueType::Vec3), &[115, 113], 1041);
                step(f, Op::Copy(ValueType::Bool), &[45, 44], 1042);
                step(f, Op::Jump, &[1043], 1043)
            }
            1043 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 40, 27], 1044);
                step(f, Op::BreakTransform, &[27, 91, 21, 92], 1045);
                step(f, Op::ArrayAt(Elem::Float), &[2, 40, 249], 1046);
                step(f, Op::SubF, &[630, 249, 250], 1047);
                step(f, Op::MaxF, &[250, 628, 251], 1048);
                step(f, Op::MulF, &[5, 2, 252], 1049);
                step(f, Op::MulF, &[251, 252, 253], 1050);
                step(f, Op::ScaleV, &[2, 253, 77], 1051);
                step(f, Op::SubV, &[112, 77, 90], 1052);
                step(f, Op::Select(ValueType::Vec3), &[44, 90, 91, 93], 1053);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 40, 28], 1054);
                step(f, Op::BreakTransform, &[28, 94, 23, 95], 1055);
                step(f, Op::Copy(ValueType::Vec3), &[91, 96], 1056);
                step(f, Op::Copy(ValueType::Vec3), &[93, 97], 1057);
                step(f, Op::Copy(ValueType::Vec3), &[94, 98], 1058);
                step(f, Op::Copy(ValueType::Float), &[40, 281], 1059);
                step(f, Op::Copy(ValueType::Float), &[42, 282], 1060);
                step(f, Op::Copy(ValueType::Vec3), &[380, 99], 1061);
                step(f, Op::SubV, &[97, 98, 100], 1062);
                step(f, Op::DeltaTime, &[283], 1063);
                step(f, Op::DivF, &[282, 283, 284], 1064);
                step(f, Op::ScaleV, &[100, 284, 101], 1065);
                step(f, Op::AddV, &[97, 101, 102], 1066);
                step(f, Op::AddV, &[98, 101, 103], 1067);
                step(f, Op::SubV, &[96, 103, 104], 1068);
                step(f, Op::FloatLerp, &[628, 630, 281, 285], 1069);
                step(f, Op::SubF, &[630, 285, 286], 1070);
                step(f, Op::ScaleV, &[104, 286, 105], 1071);
                step(f, Op::AddV, &[102, 105, 107], 1072);
                step(f, Op::MulF, &[281, 283, 287], 1073);
                step(f, Op::GreaterF, &[287, 628, 43], 1074);
                step(f, Op::DivF, &[285, 287, 288], 1075);
                step(f, Op::Select(ValueType::Float), &[43, 288, 630, 289], 1076);
                step(f, Op::ScaleV, &[100, 289, 106], 1077);
                step(f, Op::SubV, &[107, 106, 108], 1078);
                step(f, Op::Copy(ValueType::Vec3), &[108, 99], 1079);
                step(f, Op::Jump, &[1080], 1080)
            }
            1080 => {
                step(f, Op::BreakVector, &[99, 290, 291, 292], 1081);
                step(f, Op::ClampF, &[292, 51, 52, 293], 1082);
                step(f, Op::MakeVector, &[290, 291, 293, 109], 1083);
                step(f, Op::RotationFromNormal, &[113, 279, 280, 19], 1084);
                step(f, Op::PerFootRotationFactor, &[9, 84, 85, 276], 1085);
                step(f, Op::MulF, &[9, 276, 277], 1086);
                step(f, Op::SubF, &[630, 10, 258], 1087);
                step(f, Op::MulF, &[277, 258, 278], 1088);
                step(f, Op::QuatFromAxisAngle, &[383, 278, 18], 1089);
                step(f, Op::MulQ, &[19, 18, 20], 1090);
                step(f, Op::Select(ValueType::Quat), &[44, 20, 21, 22], 1091);
                step(f, Op::MakeTransform, &[109, 22, 381, 30], 1092);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 40, 30], 1093);
                step(f, Op::ArrayAt(Elem::Float), &[2, 40, 249], 1094);
                step(f, Op::SubF, &[630, 249, 250], 1095);
                step(f, Op::MaxF, &[250, 628, 251], 1096);
                step(f, Op::MulF, &[5, 2, 252], 1097);
                step(f, Op::MulF, &[251, 252, 253], 1098);
                step(f, Op::ScaleV, &[2, 253, 77], 1099);
                step(f, Op::SubV, &[112, 77, 90], 1100);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 40, 27], 1101);
                step(f, Op::BreakTransform, &[27, 91, 21, 92], 1102);
                step(f, Op::Select(ValueType::Vec3), &[44, 90, 91, 93], 1103);
                step(f, Op::MakeTransform, &[93, 89, 381, 29], 1104);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 40, 29], 1105);
                step(f, Op::JumpIfFalse, &[44, 1108], 1106)
            }
            1106 => {
                step(f, Op::Copy(ValueType::Bool), &[78, 7], 1107);
                step(f, Op::Jump, &[1108], 1108)
            }
            1108 => {
                step(f, Op::Copy(ValueType::Int), &[3, 52], 1109);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 52, 33], 1110);
                step(f, Op::GreaterF, &[15, 628, 53], 1111);
                step(f, Op::InterpolateTransform, &[2, 108, 16, 31], 1112);
                step(f, Op::Select(ValueType::Transform), &[53, 31, 2, 32], 1113);
                step(f, Op::MakeAbsolute, &[33, 32, 34], 1114);
                step(f, Op::BreakTransform, &[34, 130, 24, 131], 1115);
                step(f, Op::ClampSpatially, &[130, 380, 628, 55, 132], 1116);
                step(f, Op::SubF, &[630, 10, 324], 1117);
                step(f, Op::MulF, &[9, 324, 320], 1118);
                step(f, Op::LimitRotationAroundZ, &[24, 320, 83, 25], 1119);
                step(f, Op::MakeTransform, &[132, 25, 381, 35], 1120);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 52, 35], 1121);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 52, 50], 1122);
                step(f, Op::JumpIfFalse, &[50, 1176], 1123)
            }
            1123 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 52, 37], 1124);
                step(f, Op::BreakTransform, &[37, 133, 26, 134], 1125);
                step(f, Op::ArrayAt(Elem::Float), &[2, 52, 319], 1126);
                step(f, Op::SubF, &[630, 319, 321], 1127);
                step(f, Op::MulF, &[5, 2, 322], 1128);
                step(f, Op::MulF, &[321, 322, 323], 1129);
                step(f, Op::ScaleV, &[2, 323, 135], 1130);
                step(f, Op::AddV, &[133, 135, 136], 1131);
                step(f, Op::MakeTransform, &[136, 26, 381, 44], 1132);
                step(f, Op::Copy(ValueType::Transform), &[44, 45], 1133);
                step(f, Op::Copy(ValueType::Transform), &[108, 46], 1134);
                step(f, Op::BreakTransform, &[45, 164, 31, 165], 1135);
                step(f, Op::MakeVector, &[628, 628, 48, 166], 1136);
                step(f, Op::AddV, &[164, 166, 167], 1137);
                step(f, Op::SubV, &[164, 166, 168], 1138);
                step(f, Op::LineTrace, &[167, 168, 57, 169, 170, 351], 1139);
                step(f, Op::RotateVector, &[31, 383, 171], 1140);
                step(f, Op::FindQuatBetween, &[171, 170, 32], 1141);
                step(f, Op::MulQ, &[32, 31, 33], 1142);
                step(f, Op::MulF, &[46, 45, 352], 1143);
                step(f, Op::AddF, &[352, 54, 353], 1144);
                step(f, Op::NegF, &[353, 354], 1145);
                step(f, Op::MakeVector, &[628, 354, 628, 172], 1146);
                step(f, Op::RotateVector, &[33, 172, 174], 1147);
                step(f, Op::AddV, &[169, 174, 176], 1148);
                step(f, Op::AddV, &[176, 166, 178], 1149);
                step(f, Op::SubV, &[176, 166, 179], 1150);
                step(f, Op::LineTrace, &[178, 179, 58, 182, 183, 356], 1151);
                step(f, Op::BreakVector, &[182, 358, 359, 360], 1152);
                step(f, Op::BreakVector, &[176, 364, 365, 366], 1153);
                step(f, Op::SubF, &[360, 366, 370], 1154);
                step(f, Op::Select(ValueType::Float), &[58, 370, 628, 372], 1155);
                step(f, Op::AddF, &[50, 54, 355], 1156);
                step(f, Op::MakeVector, &[628, 355, 628, 173], 1157);
                step(f, Op::RotateVector, &[33, 173, 175], 1158);
                step(f, Op::AddV, &[169, 175, 177], 1159);
                step(f, Op::AddV, &[177, 166, 180], 1160);
                step(f, Op::SubV, &[177, 166, 181], 1161);
                step(f, Op::LineTrace, &[180, 181, 59, 184, 185, 357], 1162);
                step(f, Op::BreakVector, &[184, 361, 362, 363], 1163);
                step(f, Op::BreakVector, &[177, 367, 368, 369], 1164);
                step(f, Op::SubF, &[363, 369, 371], 1165);
                step(f, Op::Select(ValueType::Float), &[59, 371, 628, 373], 1166);
                step(f, Op::MaxF, &[372, 373, 374], 1167);
                step(f, Op::ClampF, &[374, 628, 53, 375], 1168);
                step(f, Op::MakeVector, &[628, 628, 375, 186], 1169);
                step(f, Op::AddV, &[169, 186, 187], 1170);
                step(f, Op::MakeTransform, &[187, 33, 381, 47], 1171);
                step(f, Op::Select(ValueType::Transform), &[57, 47, 45, 48], 1172);
                step(f, Op::Copy(ValueType::Transform), &[48, 46], 1173);
                step(f, Op::Jump, &[1174], 1174)
            }
            1174 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 52, 46], 1175);
                step(f, Op::Jump, &[1280], 1176)
            }
            1176 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 52, 49], 1177);
                step(f, Op::GreaterF, &[15, 628, 53], 1178);
                step(f, Op::InterpolateTransform, &[2, 108, 16, 31], 1179);
                step(f, Op::Select(ValueType::Transform), &[53, 31, 2, 32], 1180);
                step(f, Op::MakeAbsolute, &[49, 32, 50], 1181);
                step(f, Op::BreakTransform, &[50, 188, 34, 189], 1182);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 52, 37], 1183);
                step(f, Op::BreakTransform, &[37, 133, 26, 134], 1184);
                step(f, Op::ArrayAt(Elem::Float), &[2, 52, 319], 1185);
                step(f, Op::SubF, &[630, 319, 321], 1186);
                step(f, Op::MulF, &[5, 2, 322], 1187);
                step(f, Op::MulF, &[321, 322, 323], 1188);
                step(f, Op::ScaleV, &[2, 323, 135], 1189);
                step(f, Op::AddV, &[133, 135, 136], 1190);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 52, 51], 1191);
                step(f, Op::MakeAbsolute, &[51, 32, 52], 1192);
                step(f, Op::BreakTransform, &[52, 190, 35, 191], 1193);
                step(f, Op::ArrayAt(Elem::Float), &[3, 52, 376], 1194);
                step(f, Op::SubF, &[319, 376, 377], 1195);
                step(f, Op::DeltaTime, &[392], 1196);
                step(f, Op::DivF, &[42, 392, 378], 1197);
                step(f, Op::MulF, &[377, 378, 379], 1198);
                step(f, Op::AddF, &[376, 379, 380], 1199);
                step(f, Op::ClampF, &[380, 628, 630, 382], 1200);
                step(f, Op::AddF, &[319, 379, 381], 1201);
                step(f, Op::ClampF, &[381, 628, 630, 383], 1202);
                step(f, Op::AddF, &[382, 383, 384], 1203);
                step(f, Op::MulF, &[384, 629, 385], 1204);
                step(f, Op::SubF, &[630, 385, 386], 1205);
                step(f, Op::GreaterF, &[377, 628, 60], 1206);
                step(f, Op::SubF, &[383, 382, 387], 1207);
                step(f, Op::DivF, &[387, 377, 388], 1208);
                step(f, Op::Select(ValueType::Float), &[60, 388, 630, 389], 1209);
                step(f, Op::MulF, &[386, 389, 390], 1210);
                step(f, Op::MulF, &[69, 390, 391], 1211);
                step(f, Op::Copy(ValueType::Vec3), &[188, 192], 1212);
                step(f, Op::Copy(ValueType::Vec3), &[136, 193], 1213);
                step(f, Op::Copy(ValueType::Vec3), &[190, 194], 1214);
                step(f, Op::Copy(ValueType::Float), &[391, 393], 1215);
                step(f, Op::Copy(ValueType::Float), &[42, 394], 1216);
                step(f, Op::Copy(ValueType::Vec3), &[380, 195], 1217);
                step(f, Op::SubV, &[193, 194, 196], 1218);
                step(f, Op::DeltaTime, &[395], 1219);
                step(f, Op::DivF, &[394, 395, 396], 1220);
                step(f, Op::ScaleV, &[196, 396, 197], 1221);
                step(f, Op::AddV, &[193, 197, 198], 1222);
                step(f, Op::AddV, &[194, 197, 199], 1223);
                step(f, Op::SubV, &[192, 199, 200], 1224);
                step(f, Op::FloatLerp, &[628, 630, 393, 397], 1225);
                step(f, Op::SubF, &[630, 397, 398], 1226);
                step(f, Op::ScaleV, &[200, 398, 201], 1227);
                step(f, Op::AddV, &[198, 201, 203], 1228);
                step(f, Op::MulF, &[393, 395, 399], 1229);
                step(f, Op::GreaterF, &[399, 628, 61], 1230);
                step(f, Op::DivF, &[397, 399, 400], 1231);
                step(f, Op::Select(ValueType::Float), &[61, 400, 630, 401], 1232);
                step(f, Op::ScaleV, &[196, 401, 202], 1233);
                step(f, Op::SubV, &[203, 202, 204], 1234);
                step(f, Op::Copy(ValueType::Vec3), &[204, 195], 1235);
                step(f, Op::Jump, &[1236], 1236)
            }
            1236 => {
                step(f, Op::MakeTransform, &[195, 26, 381, 54], 1237);
                step(f, Op::Copy(ValueType::Transform), &[54, 55], 1238);
                step(f, Op::Copy(ValueType::Transform), &[108, 56], 1239);
                step(f, Op::BreakTransform, &[55, 205, 36, 206], 1240);
                step(f, Op::MakeVector, &[628, 628, 48, 207], 1241);
                step(f, Op::AddV, &[205, 207, 208], 1242);
                step(f, Op::SubV, &[205, 207, 209], 1243);
                step(f, Op::LineTrace, &[208, 209, 62, 210, 211, 402], 1244);
                step(f, Op::RotateVector, &[36, 383, 212], 1245);
                step(f, Op::FindQuatBetween, &[212, 211, 37], 1246);
                step(f, Op::MulQ, &[37, 36, 38], 1247);
                step(f, Op::MulF, &[46, 45, 403], 1248);
                step(f, Op::AddF, &[403, 54, 404], 1249);
                step(f, Op::NegF, &[404, 405], 1250);
                step(f, Op::MakeVector, &[628, 405, 628, 213], 1251);
                step(f, Op::RotateVector, &[38, 213, 215], 1252);
                step(f, Op::AddV, &[210, 215, 217], 1253);
                step(f, Op::AddV, &[217, 207, 219], 1254);
                step(f, Op::SubV, &[217, 207, 220], 1255);
                step(f, Op::LineTrace, &[219, 220, 63, 223, 224, 407], 1256);
                step(f, Op::BreakVector, &[223, 409, 410, 411], 1257);
                step(f, Op::BreakVector, &[217, 415, 416, 417], 1258);
                step(f, Op::SubF, &[411, 417, 421], 1259);
                step(f, Op::Select(ValueType::Float), &[63, 421, 628, 423], 1260);
                step(f, Op::AddF, &[50, 54, 406], 1261);
                step(f, Op::MakeVector, &[628, 406, 628, 214], 1262);
                step(f, Op::RotateVector, &[38, 214, 216], 1263);
                step(f, Op::AddV, &[210, 216, 218], 1264);
                step(f, Op::AddV, &[218, 207, 221], 1265);
                step(f, Op::SubV, &[218, 207, 222], 1266);
                step(f, Op::LineTrace, &[221, 222, 64, 225, 226, 408], 1267);
                step(f, Op::BreakVector, &[225, 412, 413, 414], 1268);
                step(f, Op::BreakVector, &[218, 418, 419, 420], 1269);
                step(f, Op::SubF, &[414, 420, 422], 1270);
                step(f, Op::Select(ValueType::Float), &[64, 422, 628, 424], 1271);
                step(f, Op::MaxF, &[423, 424, 425], 1272);
                step(f, Op::ClampF, &[425, 628, 53, 426], 1273);
                step(f, Op::MakeVector, &[628, 628, 426, 227], 1274);
                step(f, Op::AddV, &[210, 227, 228], 1275);
                step(f, Op::MakeTransform, &[228, 38, 381, 57], 1276);
                step(f, Op::Select(ValueType::Transform), &[62, 57, 55, 58], 1277);
                step(f, Op::Copy(ValueType::Transform), &[58, 56], 1278);
                step(f, Op::Jump, &[1279], 1279)
            }
            1279 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 52, 56], 1280);
                1280
            }
            1280 => {
                step(f, Op::ArrayAt(Elem::Float), &[2, 52, 319], 1281);
                step(f, Op::GreaterEqualF, &[319, 630, 51], 1282);
                step(f, Op::JumpIfFalse, &[51, 1342], 1283)
            }
            1283 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 52, 50], 1284);
                step(f, Op::JumpIfFalse, &[50, 1286], 1285)
            }
            1285 => {
                step(f, Op::Jump, &[1339], 1286)
            }
            1286 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 52, 59], 1287);
                step(f, Op::BreakTransform, &[59, 229, 39, 230], 1288);
                step(f, Op::Equals(Elem::Int), &[52, 64, 52], 1289);
                step(f, Op::Select(ValueType::Int), &[52, 65, 64, 53], 1290);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 53, 38], 1291);
                step(f, Op::BreakTransform, &[38, 137, 27, 138], 1292);
                step(f, Op::SubF, &[630, 10, 324], 1293);
                step(f, Op::MulF, &[9, 324, 325], 1294);
                step(f, Op::FootAvoidance, &[229, 137, 325, 52, 70, 139], 1295);
                step(f, Op::MakeTransform, &[139, 39, 381, 39], 1296);
                step(f, Op::Copy(ValueType::Transform), &[39, 40], 1297);
                step(f, Op::Copy(ValueType::Transform), &[108, 41], 1298);
                step(f, Op::BreakTransform, &[40, 140, 28, 141], 1299);
                step(f, Op::MakeVector, &[628, 628, 48, 142], 1300);
                step(f, Op::AddV, &[140, 142, 143], 1301);
                step(f, Op::SubV, &[140, 142, 144], 1302);
                step(f, Op::LineTrace, &[143, 144, 54, 145, 146, 326], 1303);
                step(f, Op::RotateVector, &[28, 383, 147], 1304);
                step(f, Op::FindQuatBetween, &[147, 146, 29], 1305);
                step(f, Op::MulQ, &[29, 28, 30], 1306);
                step(f, Op::MulF, &[46, 45, 327], 1307);
                step(f, Op::AddF, &[327, 54, 328], 1308);
                step(f, Op::NegF, &[328, 329], 1309);
                step(f, Op::MakeVector, &[628, 329, 628, 148], 1310);
                step(f, Op::RotateVector, &[30, 148, 150], 1311);
                step(f, Op::AddV, &[145, 150, 152], 1312);
                step(f, Op::AddV, &[152, 142, 154], 1313);
                step(f, Op::SubV, &[152, 142, 155], 1314);
                step(f, Op::LineTrace, &[154, 155, 55, 158, 159, 331], 1315);
                step(f, Op::BreakVector, &[158, 333, 334, 335], 1316);
                step(f, Op::BreakVector, &[152, 339, 340, 341], 1317);
                step(f, Op::SubF, &[335, 341, 345], 1318);
                step(f, Op::Select(ValueType::Float), &[55, 345, 628, 347], 1319);
                step(f, Op::AddF, &[50, 54, 330], 1320);
                step(f, Op::MakeVector, &[628, 330, 628, 149], 1321);
                step(f, Op::RotateVector, &[30, 149, 151], 1322);
                step(f, Op::AddV, &[145, 151, 153], 1323);
                step(f, Op::AddV, &[153, 142, 156], 1324);
                step(f, Op::SubV, &[153, 142, 157], 1325);
                step(f, Op::LineTrace, &[156, 157, 56, 160, 161, 332], 1326);
                step(f, Op::BreakVector, &[160, 336, 337, 338], 1327);
                step(f, Op::BreakVector, &[153, 342, 343, 344], 1328);
                step(f, Op::SubF, &[338, 344, 346], 1329);
                step(f, Op::Select(ValueType::Float), &[56, 346, 628, 348], 1330);
                step(f, Op::MaxF, &[347, 348, 349], 1331);
                step(f, Op::ClampF, &[349, 628, 53, 350], 1332);
                step(f, Op::MakeVector, &[628, 628, 350, 162], 1333);
                step(f, Op::AddV, &[145, 162, 163], 1334);
                step(f, Op::MakeTransform, &[163, 30, 381, 42], 1335);
                step(f, Op::Select(ValueType::Transform), &[54, 42, 40, 43], 1336);
                step(f, Op::Copy(ValueType::Transform), &[43, 41], 1337);
                step(f, Op::Jump, &[1338], 1338)
            }
            1338 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 52, 41], 1339);
                1339
            }
            1339 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 52, 36], 1340);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 52, 36], 1341);
                step(f, Op::Jump, &[1527], 1342)
            }
            1342 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 52, 36], 1343);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 52, 59], 1344);
                step(f, Op::ClampF, &[319, 628, 630, 427], 1345);
                step(f, Op::Copy(ValueType::Transform), &[36, 64], 1346);
                step(f, Op::Copy(ValueType::Transform), &[59, 65], 1347);
                step(f, Op::Copy(ValueType::Float), &[427, 442], 1348);
                step(f, Op::Copy(ValueType::Transform), &[108, 66], 1349);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[3, 2], 1350);
                step(f, Op::ArrayReset(Elem::Vec3), &[2], 1351);
                step(f, Op::BreakTransform, &[64, 245, 44, 246], 1352);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 245], 1353);
                step(f, Op::BreakTransform, &[64, 245, 44, 246], 1354);
                step(f, Op::UnitV, &[2, 244], 1355);
                step(f, Op::LengthV, &[2, 443], 1356);
                step(f, Op::RemapF, &[443, 628, 56, 628, 57, 78, 444], 1357);
                step(f, Op::ScaleV, &[244, 444, 249], 1358);
                step(f, Op::SubV, &[245, 249, 255], 1359);
                step(f, Op::MakeVector, &[628, 628, 59, 253], 1360);
                step(f, Op::AddV, &[255, 253, 257], 1361);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 257], 1362);
                step(f, Op::BreakTransform, &[64, 245, 44, 246], 1363);
                step(f, Op::UnitV, &[2, 244], 1364);
                step(f, Op::LengthV, &[2, 443], 1365);
                step(f, Op::RemapF, &[443, 628, 56, 628, 57, 78, 444], 1366);
                step(f, Op::ScaleV, &[244, 444, 249], 1367);
                step(f, Op::SubV, &[245, 249, 255], 1368);
                step(f, Op::MakeVector, &[628, 628, 59, 253], 1369);
                step(f, Op::AddV, &[255, 253, 257], 1370);
                step(f, Op::RemapF, &[443, 628, 56, 628, 61, 78, 446], 1371);
                step(f, Op::MakeVector, &[628, 628, 446, 251], 1372);
                step(f, Op::AddV, &[257, 251, 261], 1373);
                step(f, Op::BreakTransform, &[65, 247, 45, 248], 1374);
                step(f, Op::BreakVector, &[247, 451, 452, 453], 1375);
                step(f, Op::BreakVector, &[245, 448, 449, 450], 1376);
                step(f, Op::SubF, &[453, 450, 454], 1377);
                step(f, Op::MaxF, &[454, 628, 456], 1378);
                step(f, Op::MulF, &[456, 63, 460], 1379);
                step(f, Op::AbsF, &[454, 458], 1380);
                step(f, Op::RemapF, &[458, 628, 66, 628, 65, 78, 459], 1381);
                step(f, Op::AddF, &[460, 459, 462], 1382);
                step(f, Op::MakeVector, &[628, 628, 462, 259], 1383);
                step(f, Op::AddV, &[261, 259, 263], 1384);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 263], 1385);
                step(f, Op::BreakTransform, &[64, 245, 44, 246], 1386);
                step(f, Op::UnitV, &[2, 244], 1387);
                step(f, Op::LengthV, &[2, 443], 1388);
                step(f, Op::RemapF, &[443, 628, 56, 628, 57, 78, 444], 1389);
                step(f, Op::ScaleV, &[244, 444, 249], 1390);
                step(f, Op::SubV, &[245, 249, 255], 1391);
                step(f, Op::MakeVector, &[628, 628, 59, 253], 1392);
                step(f, Op::AddV, &[255, 253, 257], 1393);
                step(f, Op::RemapF, &[443, 628, 56, 628, 61, 78, 446], 1394);
                step(f, Op::MakeVector, &[628, 628, 446, 251], 1395);
                step(f, Op::AddV, &[257, 251, 261], 1396);
                step(f, Op::BreakTransform, &[65, 247, 45, 248], 1397);
                step(f, Op::BreakVector, &[247, 451, 452, 453], 1398);
                step(f, Op::BreakVector, &[245, 448, 449, 450], 1399);
                step(f, Op::SubF, &[453, 450, 454], 1400);
                step(f, Op::MaxF, &[454, 628, 456], 1401);
                step(f, Op::MulF, &[456, 63, 460], 1402);
                step(f, Op::AbsF, &[454, 458], 1403);
                step(f, Op::RemapF, &[458, 628, 66, 628, 65, 78, 459], 1404);
                step(f, Op::AddF, &[460, 459, 462], 1405);
                step(f, Op::MakeVector, &[628, 628, 462, 259], 1406);
                step(f, Op::AddV, &[261, 259, 263], 1407);
                step(f, Op::RemapF, &[443, 628, 56, 628, 58, 78, 445], 1408);
                step(f, Op::ScaleV, &[244, 445, 250], 1409);
                step(f, Op::AddV, &[247, 250, 256], 1410);
                step(f, Op::MakeVector, &[628, 628, 60, 254], 1411);
                step(f, Op::AddV, &[256, 254, 258], 1412);
                step(f, Op::RemapF, &[443, 628, 56, 628, 62, 78, 447], 1413);
                step(f, Op::MakeVector, &[628, 628, 447, 252], 1414);
                step(f, Op::AddV, &[258, 252, 262], 1415);
                step(f, Op::NegF, &[454, 455], 1416);
                step(f, Op::MaxF, &[455, 628, 457], 1417);
                step(f, Op::MulF, &[457, 64, 461], 1418);
                step(f, Op::AddF, &[461, 459, 463], 1419);
                step(f, Op::MakeVector, &[628, 628, 463, 260], 1420);
                step(f, Op::AddV, &[262, 260, 264], 1421);
                step(f, Op::LerpV, &[263, 264, 629, 265], 1422);
                step(f, Op::GetTransform, &[36, 64, 78, 67], 1423);
                step(f, Op::BreakTransform, &[67, 266, 46, 267], 1424);
                step(f, Op::BreakVector, &[266, 473, 474, 475], 1425);
                step(f, Op::SubF, &[630, 10, 467], 1426);
                step(f, Op::MulF, &[67, 467, 468], 1427);
                step(f, Op::MulF, &[9, 468, 469], 1428);
                step(f, Op::QuatFromAxisAngle, &[383, 469, 47], 1429);
                step(f, Op::SubV, &[265, 266, 268], 1430);
                step(f, Op::BreakVector, &[268, 464, 465, 466], 1431);
                step(f, Op::MakeVector, &[464, 465, 628, 269], 1432);
                step(f, Op::RotateVector, &[47, 269, 270], 1433);
                step(f, Op::BreakVector, &[270, 470, 471, 472], 1434);
                step(f, Op::AddF, &[473, 470, 479], 1435);
                step(f, Op::AddF, &[474, 471, 480], 1436);
                step(f, Op::BreakVector, &[265, 476, 477, 478], 1437);
                step(f, Op::MakeVector, &[479, 480, 478, 271], 1438);
                step(f, Op::DistanceV, &[245, 247, 481], 1439);
                step(f, Op::RemapF, &[481, 633, 640, 628, 630, 78, 482], 1440);
                step(f, Op::LerpV, &[265, 271, 482, 272], 1441);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 272], 1442);
                step(f, Op::BreakTransform, &[65, 247, 45, 248], 1443);
                step(f, Op::UnitV, &[2, 244], 1444);
                step(f, Op::LengthV, &[2, 443], 1445);
                step(f, Op::RemapF, &[443, 628, 56, 628, 58, 78, 445], 1446);
                step(f, Op::ScaleV, &[244, 445, 250], 1447);
                step(f, Op::AddV, &[247, 250, 256], 1448);
                step(f, Op::MakeVector, &[628, 628, 60, 254], 1449);
                step(f, Op::AddV, &[256, 254, 258], 1450);
                step(f, Op::RemapF, &[443, 628, 56, 628, 62, 78, 447], 1451);
                step(f, Op::MakeVector, &[628, 628, 447, 252], 1452);
                step(f, Op::AddV, &[258, 252, 262], 1453);
                step(f, Op::BreakVector, &[247, 451, 452, 453], 1454);
                step(f, Op::BreakTransform, &[64, 245, 44, 246], 1455);
                step(f, Op::BreakVector, &[245, 448, 449, 450], 1456);
                step(f, Op::SubF, &[453, 450, 454], 1457);
                step(f, Op::NegF, &[454, 455], 1458);
                step(f, Op::MaxF, &[455, 628, 457], 1459);
                step(f, Op::MulF, &[457, 64, 461], 1460);
                step(f, Op::AbsF, &[454, 458], 1461);
                step(f, Op::RemapF, &[458, 628, 66, 628, 65, 78, 459], 1462);
                step(f, Op::AddF, &[461, 459, 463], 1463);
                step(f, Op::MakeVector, &[628, 628, 463, 260], 1464);
                step(f, Op::AddV, &[262, 260, 264], 1465);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 264], 1466);
                step(f, Op::BreakTransform, &[65, 247, 45, 248], 1467);
                step(f, Op::UnitV, &[2, 244], 1468);
                step(f, Op::LengthV, &[2, 443], 1469);
                step(f, Op::RemapF, &[443, 628, 56, 628, 58, 78, 445], 1470);
                step(f, Op::ScaleV, &[244, 445, 250], 1471);
                step(f, Op::AddV, &[247, 250, 256], 1472);
                step(f, Op::MakeVector, &[628, 628, 60, 254], 1473);
                step(f, Op::AddV, &[256, 254, 258], 1474);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 258], 1475);
                step(f, Op::BreakTransform, &[65, 247, 45, 248], 1476);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 247], 1477);
                step(f, Op::JumpIfFalse, &[8, 1480], 1478)
            }
            1478 => {
                step(f, Op::DrawSpline, &[2, 64, 67, 629, 385], 1479);
                step(f, Op::Jump, &[1480], 1480)
            }
            1480 => {
                step(f, Op::Spline, &[2, 442, 64, 273, 274], 1481);
                step(f, Op::BreakTransform, &[64, 245, 44, 246], 1482);
                step(f, Op::BreakTransform, &[65, 247, 45, 248], 1483);
                step(f, Op::SlerpQ, &[44, 45, 442, 48], 1484);
                step(f, Op::MulF, &[442, 641, 491], 1485);
                step(f, Op::SinF, &[491, 492], 1486);
                step(f, Op::Copy(ValueType::Float), &[442, 483], 1487);
                step(f, Op::Copy(ValueType::Float), &[628, 484], 1488);
                step(f, Op::DivF, &[483, 78, 485], 1489);
                step(f, Op::ClampF, &[485, 628, 630, 486], 1490);
                step(f, Op::MulF, &[486, 486, 487], 1491);
                step(f, Op::MulF, &[486, 633, 488], 1492);
                step(f, Op::SubF, &[634, 488, 489], 1493);
                step(f, Op::MulF, &[487, 489, 490], 1494);
                step(f, Op::Copy(ValueType::Float), &[490, 484], 1495);
                step(f, Op::Jump, &[1496], 1496)
            }
            1496 => {
                step(f, Op::MulF, &[492, 484, 493], 1497);
                step(f, Op::MulF, &[493, 68, 494], 1498);
                step(f, Op::SlerpQ, &[48, 89, 494, 49], 1499);
                step(f, Op::MakeTransform, &[273, 49, 381, 68], 1500);
                step(f, Op::Copy(ValueType::Transform), &[68, 66], 1501);
                step(f, Op::Jump, &[1502], 1502)
            }
            1502 => {
                step(f, Op::BreakTransform, &[66, 231, 40, 232], 1503);
                step(f, Op::Equals(Elem::Int), &[52, 64, 52], 1504);
                step(f, Op::Select(ValueType::Int), &[52, 65, 64, 53], 1505);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 53, 38], 1506);
                step(f, Op::BreakTransform, &[38, 137, 27, 138], 1507);
                step(f, Op::SubF, &[630, 10, 324], 1508);
                step(f, Op::MulF, &[9, 324, 325], 1509);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 53, 65], 1510);
                step(f, Op::Select(ValueType::Float), &[65, 71, 628, 430], 1511);
                step(f, Op::ArrayAt(Elem::Float), &[2, 52, 319], 1512);
                step(f, Op::ClampF, &[319, 628, 630, 427], 1513);
                step(f, Op::MulF, &[427, 641, 428], 1514);
                step(f, Op::SinF, &[428, 429], 1515);
                step(f, Op::MulF, &[429, 429, 431], 1516);
                step(f, Op::MulF, &[430, 431, 432], 1517);
                step(f, Op::AddF, &[70, 432, 433], 1518);
                step(f, Op::FootAvoidance, &[231, 137, 325, 52, 433, 233], 1519);
                step(f, Op::SubV, &[233, 231, 234], 1520);
                step(f, Op::LengthV, &[234, 434], 1521);
                step(f, Op::AddF, &[434, 432, 435], 1522);
                step(f, Op::DivF, &[434, 435, 436], 1523);
                step(f, Op::ScaleV, &[234, 436, 235], 1524);
                step(f, Op::AddV, &[231, 235, 236], 1525);
                step(f, Op::MakeTransform, &[236, 40, 381, 60], 1526);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 52, 60], 1527);
                1527
            }
            1527 => {
                step(f, Op::GreaterF, &[15, 628, 53], 1528);
                step(f, Op::JumpIfFalse, &[53, 1545], 1529)
            }
            1529 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 52, 61], 1530);
                step(f, Op::BreakTransform, &[61, 237, 41, 238], 1531);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 52, 62], 1532);
                step(f, Op::BreakTransform, &[62, 239, 42, 240], 1533);
                step(f, Op::MulF, &[15, 15, 437], 1534);
                step(f, Op::LerpV, &[237, 239, 437, 241], 1535);
                step(f, Op::SubF, &[630, 15, 438], 1536);
                step(f, Op::MulF, &[15, 438, 439], 1537);
                step(f, Op::MulF, &[109, 633, 440], 1538);
                step(f, Op::MulF, &[439, 440, 441], 1539);
                step(f, Op::MakeVector, &[628, 628, 441, 242], 1540);
                step(f, Op::AddV, &[241, 242, 243], 1541);
                step(f, Op::SlerpQ, &[41, 42, 15, 43], 1542);
                step(f, Op::MakeTransform, &[243, 43, 381, 63], 1543);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 52, 63], 1544);
                step(f, Op::Jump, &[1545], 1545)
            }
            1545 => {
                step(f, Op::ArrayAt(Elem::Float), &[2, 52, 319], 1546);
                step(f, Op::GreaterEqualF, &[319, 630, 51], 1547);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 52, 51], 1548);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 52, 37], 1549);
                step(f, Op::BreakTransform, &[37, 133, 26, 134], 1550);
                step(f, Op::ArrayAt(Elem::Float), &[2, 52, 319], 1551);
                step(f, Op::SubF, &[630, 319, 321], 1552);
                step(f, Op::MulF, &[5, 2, 322], 1553);
                step(f, Op::MulF, &[321, 322, 323], 1554);
                step(f, Op::ScaleV, &[2, 323, 135], 1555);
                step(f, Op::AddV, &[133, 135, 136], 1556);
                step(f, Op::MakeTransform, &[136, 89, 381, 53], 1557);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 52, 53], 1558);
                step(f, Op::Copy(ValueType::Bone), &[0, 17], 1559);
                step(f, Op::Copy(ValueType::Int), &[3, 54], 1560);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 54, 69], 1561);
                step(f, Op::BreakTransform, &[69, 275, 50, 276], 1562);
                step(f, Op::MakeVector, &[628, 628, 43, 285], 1563);
                step(f, Op::AddV, &[275, 285, 286], 1564);
                step(f, Op::GetTransform, &[17, 64, 78, 71], 1565);
                step(f, Op::BreakTransform, &[71, 280, 52, 281], 1566);
                step(f, Op::MakeTransform, &[286, 52, 381, 73], 1567);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 54, 20], 1568);
                step(f, Op::GetTransform, &[20, 64, 78, 72], 1569);
                step(f, Op::BreakTransform, &[72, 282, 53, 283], 1570);
                step(f, Op::SubV, &[282, 280, 284], 1571);
                step(f, Op::AddV, &[286, 284, 287], 1572);
                step(f, Op::FootPivots, &[286, 287, 45, 44, 43, 46, 288, 289, 290], 1573);
                step(f, Op::GetParent, &[17, 18], 1574);
                step(f, Op::GetParent, &[18, 19], 1575);
                step(f, Op::GetTransform, &[19, 64, 79, 70], 1576);
                step(f, Op::BreakTransform, &[70, 277, 51, 278], 1577);
                step(f, Op::SubV, &[275, 277, 279], 1578);
                step(f, Op::DotV, &[279, 384, 495], 1579);
                step(f, Op::RemapF, &[495, 73, 72, 74, 628, 78, 498], 1580);
                step(f, Op::LengthV, &[2, 496], 1581);
                step(f, Op::RemapF, &[496, 628, 82, 628, 630, 78, 497], 1582);
                step(f, Op::MulF, &[498, 497, 499], 1583);
                step(f, Op::QuatFromAxisAngle, &[386, 499, 54], 1584);
                step(f, Op::RotateAroundPoint, &[73, 288, 54, 74], 1585);
                step(f, Op::ArrayAt(Elem::Float), &[2, 54, 500], 1586);
                step(f, Op::Copy(ValueType::Float), &[500, 502], 1587);
                step(f, Op::Copy(ValueType::Float), &[628, 503], 1588);
                step(f, Op::DivF, &[502, 78, 504], 1589);
                step(f, Op::ClampF, &[504, 628, 630, 505], 1590);
                step(f, Op::MulF, &[505, 505, 506], 1591);
                step(f, Op::MulF, &[505, 633, 507], 1592);
                step(f, Op::SubF, &[634, 507, 508], 1593);
                step(f, Op::MulF, &[506, 508, 509], 1594);
                step(f, Op::Copy(ValueType::Float), &[509, 503], 1595);
                step(f, Op::Jump, &[1596], 1596)
            }
            1596 => {
                step(f, Op::SubF, &[630, 500, 501], 1597);
                step(f, Op::Copy(ValueType::Float), &[501, 510], 1598);
                step(f, Op::Copy(ValueType::Float), &[628, 511], 1599);
                step(f, Op::DivF, &[510, 78, 512], 1600);
                step(f, Op::ClampF, &[512, 628, 630, 513], 1601);
                step(f, Op::MulF, &[513, 513, 514], 1602);
                step(f, Op::MulF, &[513, 633, 515], 1603);
                step(f, Op::SubF, &[634, 515, 516], 1604);
                step(f, Op::MulF, &[514, 516, 517], 1605);
                step(f, Op::Copy(ValueType::Float), &[517, 511], 1606);
                step(f, Op::Jump, &[1607], 1607)
            }
            1607 => {
                step(f, Op::MulF, &[503, 511, 518], 1608);
                step(f, Op::LerpF, &[77, 630, 518, 519], 1609);
                step(f, Op::MulF, &[499, 519, 520], 1610);
                step(f, Op::QuatFromAxisAngle, &[386, 520, 55], 1611);
                step(f, Op::SubV, &[289, 288, 291], 1612);
                step(f, Op::RotateVector, &[55, 291, 292], 1613);
                step(f, Op::AddV, &[288, 292, 293], 1614);
                step(f, Op::RemapF, &[495, 75, 73, 76, 628, 78, 521], 1615);
                step(f, Op::MulF, &[521, 497, 522], 1616);
                step(f, Op::QuatFromAxisAngle, &[386, 522, 56], 1617);
                step(f, Op::RotateAroundPoint, &[74, 293, 56, 75], 1618);
                step(f, Op::RemapF, &[495, 79, 80, 628, 81, 78, 523], 1619);
                step(f, Op::MulF, &[523, 497, 524], 1620);
                step(f, Op::QuatFromAxisAngle, &[386, 524, 57], 1621);
                step(f, Op::RotateAroundPoint, &[75, 290, 57, 76], 1622);
                step(f, Op::SubF, &[630, 10, 525], 1623);
                step(f, Op::MulF, &[9, 525, 526], 1624);
                step(f, Op::LimitRotationAroundZ, &[50, 526, 83, 58], 1625);
                step(f, Op::RotateAroundPoint, &[76, 275, 58, 77], 1626);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 54, 77], 1627);
                step(f, Op::JumpIfFalse, &[8, 1709], 1628)
            }
            1628 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 54, 69], 1629);
                step(f, Op::BreakTransform, &[69, 275, 50, 276], 1630);
                step(f, Op::MakeVector, &[628, 628, 43, 285], 1631);
                step(f, Op::AddV, &[275, 285, 286], 1632);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 54, 20], 1633);
                step(f, Op::GetTransform, &[20, 64, 78, 72], 1634);
                step(f, Op::BreakTransform, &[72, 282, 53, 283], 1635);
                step(f, Op::GetTransform, &[17, 64, 78, 71], 1636);
                step(f, Op::BreakTransform, &[71, 280, 52, 281], 1637);
                step(f, Op::SubV, &[282, 280, 284], 1638);
                step(f, Op::AddV, &[286, 284, 287], 1639);
                step(f, Op::FootPivots, &[286, 287, 45, 44, 43, 46, 288, 289, 290], 1640);
                step(f, Op::DrawPoint, &[290, 634, 386], 1641);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 54, 69], 1642);
                step(f, Op::BreakTransform, &[69, 275, 50, 276], 1643);
                step(f, Op::MakeVector, &[628, 628, 43, 285], 1644);
                step(f, Op::AddV, &[275, 285, 286], 1645);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 54, 20], 1646);
                step(f, Op::GetTransform, &[20, 64, 78, 72], 1647);
                step(f, Op::BreakTransform, &[72, 282, 53, 283], 1648);
                step(f, Op::GetTransform, &[17, 64, 78, 71], 1649);
                step(f, Op::BreakTransform, &[71, 280, 52, 281], 1650);
                step(f, Op::SubV, &[282, 280, 284], 1651);
                step(f, Op::AddV, &[286, 284, 287], 1652);
                step(f, Op::FootPivots, &[286, 287, 45, 44, 43, 46, 288, 289, 290], 1653);
                step(f, Op::DrawPoint, &[288, 634, 384], 1654);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 54, 69], 1655);
                step(f, Op::BreakTransform, &[69, 275, 50, 276], 1656);
                step(f, Op::MakeVector, &[628, 628, 43, 285], 1657);
                step(f, Op::AddV, &[275, 285, 286], 1658);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 54, 20], 1659);
                step(f, Op::GetTransform, &[20, 64, 78, 72], 1660);
                step(f, Op::BreakTransform, &[72, 282, 53, 283], 1661);
                step(f, Op::GetTransform, &[17, 64, 78, 71], 1662);
                step(f, Op::BreakTransform, &[71, 280, 52, 281], 1663);
                step(f, Op::SubV, &[282, 280, 284], 1664);
                step(f, Op::AddV, &[286, 284, 287], 1665);
                step(f, Op::FootPivots, &[286, 287, 45, 44, 43, 46, 288, 289, 290], 1666);
                step(f, Op::GetParent, &[17, 18], 1667);
                step(f, Op::GetParent, &[18, 19], 1668);
                step(f, Op::GetTransform, &[19, 64, 79, 70], 1669);
                step(f, Op::BreakTransform, &[70, 277, 51, 278], 1670);
                step(f, Op::SubV, &[275, 277, 279], 1671);
                step(f, Op::DotV, &[279, 384, 495], 1672);
                step(f, Op::RemapF, &[495, 73, 72, 74, 628, 78, 498], 1673);
                step(f, Op::LengthV, &[2, 496], 1674);
                step(f, Op::RemapF, &[496, 628, 82, 628, 630, 78, 497], 1675);
                step(f, Op::MulF, &[498, 497, 499], 1676);
                step(f, Op::ArrayAt(Elem::Float), &[2, 54, 500], 1677);
                step(f, Op::Copy(ValueType::Float), &[500, 502], 1678);
                step(f, Op::Copy(ValueType::Float), &[628, 503], 1679);
                step(f, Op::DivF, &[502, 78, 504], 1680);
                step(f, Op::ClampF, &[504, 628, 630, 505], 1681);
                step(f, Op::MulF, &[505, 505, 506], 1682);
                step(f, Op::MulF, &[505, 633, 507], 1683);
                step(f, Op::SubF, &[634, 507, 508], 1684);
                step(f, Op::MulF, &[506, 508, 509], 1685);
                step(f, Op::Copy(ValueType::Float), &[509, 503], 1686);
                step(f, Op::Jump, &[1687], 1687)
            }
            1687 => {
                step(f, Op::SubF, &[630, 500, 501], 1688);
                step(f, Op::Copy(ValueType::Float), &[501, 510], 1689);
                step(f, Op::Copy(ValueType::Float), &[628, 511], 1690);
                step(f, Op::DivF, &[510, 78, 512], 1691);
                step(f, Op::ClampF, &[512, 628, 630, 513], 1692);
                step(f, Op::MulF, &[513, 513, 514], 1693);
                step(f, Op::MulF, &[513, 633, 515], 1694);
                step(f, Op::SubF, &[634, 515, 516], 1695);
                step(f, Op::MulF, &[514, 516, 517], 1696);
                step(f, Op::Copy(ValueType::Float), &[517, 511], 1697);
                step(f, Op::Jump, &[1698], 1698)
            }
            1698 => {
                step(f, Op::MulF, &[503, 511, 518], 1699);
                step(f, Op::LerpF, &[77, 630, 518, 519], 1700);
                step(f, Op::MulF, &[499, 519, 520], 1701);
                step(f, Op::QuatFromAxisAngle, &[386, 520, 55], 1702);
                step(f, Op::SubV, &[289, 288, 291], 1703);
                step(f, Op::RotateVector, &[55, 291, 292], 1704);
                step(f, Op::AddV, &[288, 292, 293], 1705);
                step(f, Op::DrawPoint, &[293, 634, 383], 1706);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 54, 69], 1707);
                step(f, Op::DrawTransform, &[69, 640, 629], 1708);
                step(f, Op::Jump, &[1709], 1709)
            }
            1709 => {
                step(f, Op::Jump, &[942], 1710)
            }
            1710 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1711);
                step(f, Op::Copy(ValueType::Int), &[64, 5], 1712);
                1712
            }
            1712 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 5, 1, 6, 7, 1767], 1713)
            }
            1713 => {
                step(f, Op::Copy(ValueType::Bone), &[1, 21], 1714);
                step(f, Op::Copy(ValueType::Int), &[6, 55], 1715);
                step(f, Op::GetParent, &[21, 22], 1716);
                step(f, Op::GetParent, &[22, 23], 1717);
                step(f, Op::GetParent, &[23, 24], 1718);
                step(f, Op::GetTransform, &[24, 64, 79, 78], 1719);
                step(f, Op::BreakTransform, &[78, 294, 59, 295], 1720);
                step(f, Op::LengthV, &[1, 528], 1721);
                step(f, Op::ClavicleOffset, &[7, 528, 88, 91, 529], 1722);
                step(f, Op::MakeVector, &[628, 628, 529, 296], 1723);
                step(f, Op::AddV, &[294, 296, 297], 1724);
                step(f, Op::MakeTransform, &[297, 59, 381, 79], 1725);
                step(f, Op::SetTransform, &[24, 79, 64, 78, 630], 1726);
                step(f, Op::GetParent, &[21, 22], 1727);
                step(f, Op::GetParent, &[22, 23], 1728);
                step(f, Op::GetTransform, &[21, 64, 79, 80], 1729);
                step(f, Op::GetTransform, &[23, 64, 79, 81], 1730);
                step(f, Op::BreakTransform, &[81, 298, 61, 299], 1731);
                step(f, Op::Equals(Elem::Int), &[55, 64, 66], 1732);
                step(f, Op::Select(ValueType::Int), &[66, 65, 64, 56], 1733);
                step(f, Op::ArrayAt(Elem::Float), &[0, 56, 527], 1734);
                step(f, Op::ArmSwingRotation, &[527, 1, 0, 89, 636, 642, 630, 88, 86, 87, 636, 636, 630, 530], 1735);
                step(f, Op::QuatFromAxisAngle, &[386, 530, 60], 1736);
                step(f, Op::RotateAroundPoint, &[80, 298, 60, 82], 1737);
                step(f, Op::BreakTransform, &[82, 300, 62, 301], 1738);
                step(f, Op::LengthV, &[1, 528], 1739);
                step(f, Op::RemapF, &[528, 628, 88, 628, 90, 78, 531], 1740);
                step(f, Op::MakeVector, &[628, 628, 531, 302], 1741);
                step(f, Op::AddV, &[300, 302, 303], 1742);
                step(f, Op::MakeTransform, &[303, 62, 381, 83], 1743);
                step(f, Op::Select(ValueType::Vec3), &[66, 387, 386, 305], 1744);
                step(f, Op::Select(ValueType::Vec3), &[66, 384, 388, 306], 1745);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 55, 304], 1746);
                step(f, Op::TwoBoneIK, &[23, 22, 21, 83, 305, 306, 304, 64, 630, 79, 643, 644, 78, 67, 532], 1747);
                step(f, Op::JumpIfFalse, &[8, 1766], 1748)
            }
            1748 => {
                step(f, Op::GetParent, &[21, 22], 1749);
                step(f, Op::GetParent, &[22, 23], 1750);
                step(f, Op::GetTransform, &[23, 64, 79, 81], 1751);
                step(f, Op::BreakTransform, &[81, 298, 61, 299], 1752);
                step(f, Op::GetTransform, &[21, 64, 79, 80], 1753);
                step(f, Op::Equals(Elem::Int), &[55, 64, 66], 1754);
                step(f, Op::Select(ValueType::Int), &[66, 65, 64, 56], 1755);
                step(f, Op::ArrayAt(Elem::Float), &[0, 56, 527], 1756);
                step(f, Op::ArmSwingRotation, &[527, 1, 0, 89, 636, 642, 630, 88, 86, 87, 636, 636, 630, 530], 1757);
                step(f, Op::QuatFromAxisAngle, &[386, 530, 60], 1758);
                step(f, Op::RotateAroundPoint, &[80, 298, 60, 82], 1759);
                step(f, Op::BreakTransform, &[82, 300, 62, 301], 1760);
                step(f, Op::LengthV, &[1, 528], 1761);
                step(f, Op::RemapF, &[528, 628, 88, 628, 90, 78, 531], 1762);
                step(f, Op::MakeVector, &[628, 628, 531, 302], 1763);
                step(f, Op::AddV, &[300, 302, 303], 1764);
                step(f, Op::DrawLine, &[298, 303, 629, 384], 1765);
                step(f, Op::Jump, &[1766], 1766)
            }
            1766 => {
                step(f, Op::Jump, &[1712], 1767)
            }
            1767 => {
                step(f, Op::Copy(ValueType::Float), &[628, 535], 1768);
                step(f, Op::Copy(ValueType::Float), &[637, 536], 1769);
                step(f, Op::Copy(ValueType::Bool), &[79, 68], 1770);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 10], 1771);
                step(f, Op::Copy(ValueType::Int), &[64, 57], 1772);
                step(f, Op::MakeVector, &[628, 628, 48, 309], 1773);
                1773
            }
            1773 => {
                step(f, Op::ForEachNext(Elem::Transform), &[10, 57, 84, 58, 59, 1786], 1774)
            }
            1774 => {
                step(f, Op::BreakTransform, &[84, 307, 63, 308], 1775);
                step(f, Op::AddV, &[307, 309, 310], 1776);
                step(f, Op::SubV, &[307, 309, 311], 1777);
                step(f, Op::SphereTrace, &[310, 311, 47, 69, 312, 313, 537], 1778);
                step(f, Op::BreakVector, &[312, 538, 539, 540], 1779);
                step(f, Op::LessF, &[540, 536, 70], 1780);
                step(f, Op::And, &[69, 70, 71], 1781);
                step(f, Op::JumpIfFalse, &[71, 1785], 1782)
            }
            1782 => {
                step(f, Op::Copy(ValueType::Float), &[540, 536], 1783);
                step(f, Op::Copy(ValueType::Bool), &[78, 68], 1784);
                step(f, Op::Jump, &[1785], 1785)
            }
            1785 => {
                step(f, Op::Jump, &[1773], 1786)
            }
            1786 => {
                step(f, Op::Select(ValueType::Float), &[68, 536, 628, 541], 1787);
                step(f, Op::ClampF, &[541, 51, 52, 542], 1788);
                step(f, Op::Copy(ValueType::Float), &[542, 535], 1789);
                step(f, Op::Jump, &[1790], 1790)
            }
            1790 => {
                step(f, Op::SubF, &[630, 15, 534], 1791);
                step(f, Op::MulF, &[535, 534, 543], 1792);
                step(f, Op::FloatLerp, &[11, 543, 41, 544], 1793);
                step(f, Op::Select(ValueType::Float), &[1, 543, 544, 545], 1794);
                step(f, Op::Copy(ValueType::Float), &[545, 11], 1795);
                step(f, Op::GetTransform, &[37, 64, 78, 89], 1796);
                step(f, Op::BreakTransform, &[89, 326, 70, 327], 1797);
                step(f, Op::PelvisLean, &[1, 93, 98, 99, 559, 560], 1798);
                step(f, Op::LengthV, &[2, 533], 1799);
                step(f, Op::RemapF, &[533, 628, 93, 628, 92, 78, 546], 1800);
                step(f, Op::MulF, &[7, 645, 547], 1801);
                step(f, Op::SinF, &[547, 548], 1802);
                step(f, Op::MulF, &[546, 548, 549], 1803);
                step(f, Op::MulF, &[549, 534, 550], 1804);
                step(f, Op::AddF, &[550, 11, 551], 1805);
                step(f, Op::MakeVector, &[628, 560, 551, 328], 1806);
                step(f, Op::AddV, &[326, 328, 329], 1807);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 64, 85], 1808);
                step(f, Op::BreakTransform, &[85, 314, 64, 315], 1809);
                step(f, Op::BreakVector, &[314, 561, 562, 563], 1810);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 86], 1811);
                step(f, Op::BreakTransform, &[86, 316, 65, 317], 1812);
                step(f, Op::BreakVector, &[316, 564, 565, 566], 1813);
                step(f, Op::SubF, &[563, 566, 567], 1814);
                step(f, Op::PelvisSideLean, &[567, 100, 101, 568], 1815);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 64, 87], 1816);
                step(f, Op::BreakTransform, &[87, 320, 66, 321], 1817);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 65, 88], 1818);
                step(f, Op::BreakTransform, &[88, 322, 67, 323], 1819);
                step(f, Op::SlerpQ, &[66, 67, 629, 68], 1820);
                step(f, Op::EulerFromQuat, &[68, 64, 324], 1821);
                step(f, Op::BreakVector, &[324, 555, 556, 557], 1822);
                step(f, Op::RemapF, &[533, 94, 93, 628, 95, 78, 553], 1823);
                step(f, Op::SubV, &[314, 316, 318], 1824);
                step(f, Op::RotateVector, &[0, 384, 319], 1825);
                step(f, Op::DotV, &[318, 319, 552], 1826);
                step(f, Op::MulF, &[553, 552, 554], 1827);
                step(f, Op::AddF, &[557, 554, 558], 1828);
                step(f, Op::MakeVector, &[559, 568, 558, 325], 1829);
                step(f, Op::QuatFromEuler, &[325, 64, 69], 1830);
                step(f, Op::MakeTransform, &[329, 69, 381, 90], 1831);
                step(f, Op::SetTransform, &[38, 90, 64, 78, 630], 1832);
                step(f, Op::GetTransform, &[39, 65, 78, 91], 1833);
                step(f, Op::BreakTransform, &[91, 330, 74, 331], 1834);
                step(f, Op::LengthV, &[2, 533], 1835);
                step(f, Op::RemapF, &[533, 94, 93, 628, 95, 78, 553], 1836);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 64, 85], 1837);
                step(f, Op::BreakTransform, &[85, 314, 64, 315], 1838);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 86], 1839);
                step(f, Op::BreakTransform, &[86, 316, 65, 317], 1840);
                step(f, Op::SubV, &[314, 316, 318], 1841);
                step(f, Op::RotateVector, &[0, 384, 319], 1842);
                step(f, Op::DotV, &[318, 319, 552], 1843);
                step(f, Op::MulF, &[553, 552, 554], 1844);
                step(f, Op::QuatFromAxisAngle, &[383, 554, 71], 1845);
                step(f, Op::DivF, &[96, 634, 569], 1846);
                step(f, Op::QuatScale, &[71, 569, 72], 1847);
                step(f, Op::MulQ, &[74, 72, 78], 1848);
                step(f, Op::MakeTransform, &[330, 78, 381, 95], 1849);
                step(f, Op::SetTransform, &[40, 95, 65, 78, 630], 1850);
                step(f, Op::GetTransform, &[41, 65, 78, 92], 1851);
                step(f, Op::BreakTransform, &[92, 332, 75, 333], 1852);
                step(f, Op::LengthV, &[2, 533], 1853);
                step(f, Op::RemapF, &[533, 94, 93, 628, 95, 78, 553], 1854);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 64, 85], 1855);
                step(f, Op::BreakTransform, &[85, 314, 64, 315], 1856);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 86], 1857);
                step(f, Op::BreakTransform, &[86, 316, 65, 317], 1858);
                step(f, Op::SubV, &[314, 316, 318], 1859);
                step(f, Op::RotateVector, &[0, 384, 319], 1860);
                step(f, Op::DotV, &[318, 319, 552], 1861);
                step(f, Op::MulF, &[553, 552, 554], 1862);
                step(f, Op::QuatFromAxisAngle, &[383, 554, 71], 1863);
                step(f, Op::DivF, &[96, 634, 569], 1864);
                step(f, Op::QuatScale, &[71, 569, 72], 1865);
                step(f, Op::MulQ, &[75, 72, 79], 1866);
                step(f, Op::MakeTransform, &[332, 79, 381, 96], 1867);
                step(f, Op::SetTransform, &[42, 96, 65, 78, 630], 1868);
                step(f, Op::GetTransform, &[43, 65, 78, 93], 1869);
                step(f, Op::BreakTransform, &[93, 334, 76, 335], 1870);
                step(f, Op::LengthV, &[2, 533], 1871);
                step(f, Op::RemapF, &[533, 94, 93, 628, 95, 78, 553], 1872);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 64, 85], 1873);
                step(f, Op::BreakTransform, &[85, 314, 64, 315], 1874);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 86], 1875);
                step(f, Op::BreakTransform, &[86, 316, 65, 317], 1876);
                step(f, Op::SubV, &[314, 316, 318], 1877);
                step(f, Op::RotateVector, &[0, 384, 319], 1878);
                step(f, Op::DotV, &[318, 319, 552], 1879);
                step(f, Op::MulF, &[553, 552, 554], 1880);
                step(f, Op::QuatFromAxisAngle, &[383, 554, 71], 1881);
                step(f, Op::DivF, &[96, 634, 569], 1882);
                step(f, Op::QuatScale, &[71, 569, 72], 1883);
                step(f, Op::MulQ, &[76, 72, 80], 1884);
                step(f, Op::MakeTransform, &[334, 80, 381, 97], 1885);
                step(f, Op::SetTransform, &[44, 97, 65, 78, 630], 1886);
                step(f, Op::GetTransform, &[45, 65, 78, 94], 1887);
                step(f, Op::BreakTransform, &[94, 336, 77, 337], 1888);
                step(f, Op::LengthV, &[2, 533], 1889);
                step(f, Op::RemapF, &[533, 94, 93, 628, 95, 78, 553], 1890);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 64, 85], 1891);
                step(f, Op::BreakTransform, &[85, 314, 64, 315], 1892);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 86], 1893);
                step(f, Op::BreakTransform, &[86, 316, 65, 317], 1894);
                step(f, Op::SubV, &[314, 316, 318], 1895);
                step(f, Op::RotateVector, &[0, 384, 319], 1896);
                step(f, Op::DotV, &[318, 319, 552], 1897);
                step(f, Op::MulF, &[553, 552, 554], 1898);
                step(f, Op::QuatFromAxisAngle, &[383, 554, 71], 1899);
                step(f, Op::QuatScale, &[71, 97, 73], 1900);
                step(f, Op::MulQ, &[77, 73, 81], 1901);
                step(f, Op::MakeTransform, &[336, 81, 381, 98], 1902);
                step(f, Op::SetTransform, &[46, 98, 65, 78, 630], 1903);
                step(f, Op::Copy(ValueType::Float), &[628, 570], 1904);
                step(f, Op::Copy(ValueType::Float), &[628, 571], 1905);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1906);
                step(f, Op::Copy(ValueType::Int), &[64, 60], 1907);
                1907
            }
            1907 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 60, 25, 61, 62, 1937], 1908)
            }
            1908 => {
                step(f, Op::GetParent, &[25, 26], 1909);
                step(f, Op::GetParent, &[26, 27], 1910);
                step(f, Op::GetTransform, &[27, 64, 79, 99], 1911);
                step(f, Op::BreakTransform, &[99, 338, 82, 339], 1912);
                step(f, Op::BreakVector, &[338, 572, 573, 574], 1913);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 61, 100], 1914);
                step(f, Op::BreakTransform, &[100, 340, 83, 341], 1915);
                step(f, Op::BreakVector, &[340, 575, 576, 577], 1916);
                step(f, Op::ArrayAt(Elem::Float), &[1, 61, 581], 1917);
                step(f, Op::MulF, &[581, 102, 582], 1918);
                step(f, Op::MulF, &[582, 582, 583], 1919);
                step(f, Op::SubF, &[572, 575, 578], 1920);
                step(f, Op::SubF, &[573, 576, 579], 1921);
                step(f, Op::MakeVector, &[578, 579, 628, 342], 1922);
                step(f, Op::DotV, &[342, 342, 580], 1923);
                step(f, Op::SubF, &[583, 580, 584], 1924);
                step(f, Op::SqrtF, &[584, 585], 1925);
                step(f, Op::AddF, &[577, 585, 586], 1926);
                step(f, Op::SubF, &[574, 586, 587], 1927);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 61, 72], 1928);
                step(f, Op::ArrayAt(Elem::Float), &[2, 61, 588], 1929);
                step(f, Op::RemapF, &[588, 629, 630, 628, 630, 78, 589], 1930);
                step(f, Op::RemapF, &[588, 628, 105, 630, 628, 78, 590], 1931);
                step(f, Op::MaxF, &[589, 590, 591], 1932);
                step(f, Op::Select(ValueType::Float), &[72, 630, 591, 592], 1933);
                step(f, Op::MulF, &[587, 592, 593], 1934);
                step(f, Op::MaxF, &[571, 593, 594], 1935);
                step(f, Op::Copy(ValueType::Float), &[594, 571], 1936);
                step(f, Op::Jump, &[1907], 1937)
            }
            1937 => {
                step(f, Op::ClampF, &[571, 628, 103, 595], 1938);
                step(f, Op::Copy(ValueType::Float), &[595, 570], 1939);
                step(f, Op::Jump, &[1940], 1940)
            }
            1940 => {
                step(f, Op::MakeVector, &[12, 628, 628, 343], 1941);
                step(f, Op::MakeVector, &[570, 628, 628, 344], 1942);
                step(f, Op::MakeVector, &[13, 628, 628, 345], 1943);
                step(f, Op::GreaterF, &[570, 12, 73], 1944);
                step(f, Op::Select(ValueType::Float), &[73, 107, 104, 596], 1945);
                step(f, Op::Copy(ValueType::Vec3), &[343, 346], 1946);
                step(f, Op::Copy(ValueType::Vec3), &[344, 347], 1947);
                step(f, Op::Copy(ValueType::Vec3), &[345, 348], 1948);
                step(f, Op::Copy(ValueType::Float), &[596, 597], 1949);
                step(f, Op::Copy(ValueType::Float), &[42, 598], 1950);
                step(f, Op::Copy(ValueType::Vec3), &[380, 349], 1951);
                step(f, Op::SubV, &[347, 348, 350], 1952);
                step(f, Op::DeltaTime, &[599], 1953);
                step(f, Op::DivF, &[598, 599, 600], 1954);
                step(f, Op::ScaleV, &[350, 600, 351], 1955);
                step(f, Op::AddV, &[347, 351, 352], 1956);
                step(f, Op::AddV, &[348, 351, 353], 1957);
                step(f, Op::SubV, &[346, 353, 354], 1958);
                step(f, Op::FloatLerp, &[628, 630, 597, 601], 1959);
                step(f, Op::SubF, &[630, 601, 602], 1960);
                step(f, Op::ScaleV, &[354, 602, 355], 1961);
                step(f, Op::AddV, &[352, 355, 357], 1962);
                step(f, Op::MulF, &[597, 599, 603], 1963);
                step(f, Op::GreaterF, &[603, 628, 74], 1964);
                step(f, Op::DivF, &[601, 603, 604], 1965);
                step(f, Op::Select(ValueType::Float), &[74, 604, 630, 605], 1966);
                step(f, Op::ScaleV, &[350, 605, 356], 1967);
                step(f, Op::SubV, &[357, 356, 358], 1968);
                step(f, Op::Copy(ValueType::Vec3), &[358, 349], 1969);
                step(f, Op::Jump, &[1970], 1970)
            }
            1970 => {
                step(f, Op::BreakVector, &[349, 606, 607, 608], 1971);
                step(f, Op::Select(ValueType::Float), &[1, 570, 606, 609], 1972);
                step(f, Op::Copy(ValueType::Float), &[609, 12], 1973);
                step(f, Op::Copy(ValueType::Float), &[570, 13], 1974);
                step(f, Op::GetTransform, &[47, 64, 79, 101], 1975);
                step(f, Op::BreakTransform, &[101, 359, 84, 360], 1976);
                step(f, Op::MakeVector, &[628, 628, 12, 361], 1977);
                step(f, Op::SubV, &[359, 361, 362], 1978);
                step(f, Op::MakeTransform, &[362, 84, 381, 102], 1979);
                step(f, Op::SetTransform, &[48, 102, 64, 78, 630], 1980);
                step(f, Op::JumpIfFalse, &[8, 1988], 1981)
            }
            1981 => {
                step(f, Op::GetTransform, &[47, 64, 79, 101], 1982);
                step(f, Op::BreakTransform, &[101, 359, 84, 360], 1983);
                step(f, Op::MakeVector, &[628, 628, 12, 361], 1984);
                step(f, Op::SubV, &[359, 361, 362], 1985);
                step(f, Op::MakeTransform, &[362, 84, 381, 102], 1986);
                step(f, Op::DrawTransform, &[102, 646, 629], 1987);
                step(f, Op::Jump, &[1988], 1988)
            }
            1988 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1989);
                step(f, Op::Copy(ValueType::Int), &[64, 8], 1990);
                1990
            }
            1990 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 8, 2, 9, 10, 2042], 1991)
            }
            1991 => {
                step(f, Op::Copy(ValueType::Bone), &[2, 28], 1992);
                step(f, Op::Copy(ValueType::Int), &[9, 63], 1993);
                step(f, Op::GetParent, &[28, 29], 1994);
                step(f, Op::GetParent, &[29, 30], 1995);
                step(f, Op::GetTransform, &[30, 64, 79, 103], 1996);
                step(f, Op::BreakTransform, &[103, 363, 85, 364], 1997);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 63, 104], 1998);
                step(f, Op::BreakTransform, &[104, 365, 86, 366], 1999);
                step(f, Op::SubV, &[365, 363, 367], 2000);
                step(f, Op::LengthV, &[367, 618], 2001);
                step(f, Op::ArrayAt(Elem::Float), &[1, 63, 610], 2002);
                step(f, Op::MulF, &[610, 110, 611], 2003);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 63, 75], 2004);
                step(f, Op::ArrayAt(Elem::Float), &[2, 63, 612], 2005);
                step(f, Op::ClampF, &[612, 628, 630, 613], 2006);
                step(f, Op::MulF, &[613, 641, 614], 2007);
                step(f, Op::SinF, &[614, 615], 2008);
                step(f, Op::MulF, &[615, 111, 616], 2009);
                step(f, Op::Select(ValueType::Float), &[75, 628, 616, 617], 2010);
                step(f, Op::SubF, &[611, 617, 619], 2011);
                step(f, Op::SubF, &[618, 619, 620], 2012);
                step(f, Op::MaxF, &[620, 628, 621], 2013);
                step(f, Op::MulF, &[621, 621, 622], 2014);
                step(f, Op::AddF, &[621, 617, 623], 2015);
                step(f, Op::DivF, &[622, 623, 624], 2016);
                step(f, Op::SubF, &[618, 624, 625], 2017);
                step(f, Op::DivF, &[625, 618, 626], 2018);
                step(f, Op::ScaleV, &[367, 626, 368], 2019);
                step(f, Op::AddV, &[363, 368, 369], 2020);
                step(f, Op::ClampSpatially, &[369, 363, 628, 611, 370], 2021);
                step(f, Op::MakeTransform, &[370, 86, 381, 105], 2022);
                step(f, Op::Equals(Elem::Int), &[63, 64, 76], 2023);
                step(f, Op::Select(ValueType::Vec3), &[76, 387, 386, 375], 2024);
                step(f, Op::Select(ValueType::Vec3), &[76, 384, 388, 376], 2025);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 63, 106], 2026);
                step(f, Op::BreakTransform, &[106, 371, 87, 372], 2027);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 63, 373], 2028);
                step(f, Op::KneeVector, &[87, 0, 373, 112, 113, 374], 2029);
                step(f, Op::TwoBoneIK, &[30, 29, 28, 105, 375, 376, 374, 64, 630, 79, 643, 644, 78, 77, 627], 2030);
                step(f, Op::JumpIfFalse, &[8, 2041], 2031)
            }
            2031 => {
                step(f, Op::GetParent, &[28, 29], 2032);
                step(f, Op::GetTransform, &[29, 64, 79, 107], 2033);
                step(f, Op::BreakTransform, &[107, 377, 88, 378], 2034);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 63, 106], 2035);
                step(f, Op::BreakTransform, &[106, 371, 87, 372], 2036);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 63, 373], 2037);
                step(f, Op::KneeVector, &[87, 0, 373, 112, 113, 374], 2038);
                step(f, Op::AddV, &[377, 374, 379], 2039);
                step(f, Op::DrawLine, &[377, 379, 629, 389], 2040);
                step(f, Op::Jump, &[2041], 2041)
            }
            2041 => {
                step(f, Op::Jump, &[1990], 2042)
            }
            2042 => {
                step(f, Op::End, &[], 2043)
            }
            _ => return,
        } };
    }
}
