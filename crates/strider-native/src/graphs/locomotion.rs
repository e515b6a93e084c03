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
    fingerprint: 0x916b28a1cb13a7da,
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
                step(f, Op::LengthV, &[36, 119], 461);
                step(f, Op::GreaterF, &[119, 29, 10], 462);
                step(f, Op::Copy(ValueType::Bool), &[10, 2], 463);
                step(f, Op::MakeRelative, &[13, 12, 17], 464);
                step(f, Op::Select(ValueType::Transform), &[10, 108, 17, 18], 465);
                step(f, Op::Copy(ValueType::Transform), &[18, 2], 466);
                step(f, Op::InverseT, &[13, 15], 467);
                step(f, Op::MulT, &[12, 15, 16], 468);
                step(f, Op::Copy(ValueType::Transform), &[16, 1], 469);
                step(f, Op::TransformVector, &[2, 0, 39], 470);
                step(f, Op::InverseT, &[12, 14], 471);
                step(f, Op::DeltaTime, &[118], 472);
                step(f, Op::DivF, &[598, 118, 120], 473);
                step(f, Op::ScaleV, &[36, 120, 37], 474);
                step(f, Op::TransformVector, &[14, 37, 38], 475);
                step(f, Op::Select(ValueType::Vec3), &[2, 39, 38, 41], 476);
                step(f, Op::VectorLerp, &[39, 41, 30, 596, 42], 477);
                step(f, Op::Copy(ValueType::Vec3), &[42, 0], 478);
                step(f, Op::TransformVector, &[2, 1, 40], 479);
                step(f, Op::TransformVector, &[2, 0, 39], 480);
                step(f, Op::Select(ValueType::Vec3), &[2, 39, 38, 41], 481);
                step(f, Op::VectorLerp, &[40, 41, 31, 596, 43], 482);
                step(f, Op::Copy(ValueType::Vec3), &[43, 1], 483);
                step(f, Op::LengthV, &[41, 121], 484);
                step(f, Op::Copy(ValueType::Float), &[121, 0], 485);
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
                step(f, Op::Copy(ValueType::Float), &[596, 11], 503);
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
                step(f, Op::ScaleV, &[0, 599, 46], 511);
                step(f, Op::AddV, &[44, 46, 47], 512);
                step(f, Op::DrawArrow, &[44, 47, 597, 382], 513);
                step(f, Op::Jump, &[514], 514)
            }
            514 => {
                step(f, Op::Copy(ValueType::Float), &[596, 122], 515);
                step(f, Op::Copy(ValueType::Float), &[598, 123], 516);
                step(f, Op::Copy(ValueType::Float), &[598, 124], 517);
                step(f, Op::Copy(ValueType::Bool), &[79, 11], 518);
                step(f, Op::Copy(ValueType::Bool), &[79, 12], 519);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[7, 8], 520);
                step(f, Op::Copy(ValueType::Int), &[64, 25], 521);
                step(f, Op::MakeVector, &[596, 596, 48, 52], 522);
                522
            }
            522 => {
                step(f, Op::ForEachNext(Elem::Transform), &[8, 25, 21, 26, 27, 533], 523)
            }
            523 => {
                step(f, Op::BreakTransform, &[21, 48, 10, 49], 524);
                step(f, Op::TransformPoint, &[2, 48, 50], 525);
                step(f, Op::LerpV, &[50, 48, 124, 51], 526);
                step(f, Op::AddV, &[51, 52, 53], 527);
                step(f, Op::SubV, &[51, 52, 54], 528);
                step(f, Op::LineTrace, &[53, 54, 13, 55, 56, 125], 529);
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
                step(f, Op::AddF, &[122, 123, 126], 544);
                step(f, Op::MulF, &[126, 597, 127], 545);
                step(f, Op::Copy(ValueType::Float), &[127, 128], 546);
                step(f, Op::Copy(ValueType::Bool), &[79, 17], 547);
                step(f, Op::Copy(ValueType::Bool), &[79, 18], 548);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[7, 9], 549);
                step(f, Op::Copy(ValueType::Int), &[64, 28], 550);
                step(f, Op::MakeVector, &[596, 596, 48, 61], 551);
                551
            }
            551 => {
                step(f, Op::ForEachNext(Elem::Transform), &[9, 28, 22, 29, 30, 562], 552)
            }
            552 => {
                step(f, Op::BreakTransform, &[22, 57, 11, 58], 553);
                step(f, Op::TransformPoint, &[2, 57, 59], 554);
                step(f, Op::LerpV, &[59, 57, 128, 60], 555);
                step(f, Op::AddV, &[60, 61, 62], 556);
                step(f, Op::SubV, &[60, 61, 63], 557);
                step(f, Op::LineTrace, &[62, 63, 19, 64, 65, 129], 558);
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
                step(f, Op::Copy(ValueType::Float), &[127, 122], 567);
                step(f, Op::Jump, &[569], 568)
            }
            568 => {
                step(f, Op::Copy(ValueType::Float), &[127, 123], 569);
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
                step(f, Op::Select(ValueType::Float), &[5, 600, 598, 135], 573);
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 574);
                step(f, Op::AddF, &[122, 123, 126], 575);
                step(f, Op::MulF, &[126, 597, 130], 576);
                step(f, Op::Select(ValueType::Float), &[16, 130, 597, 131], 577);
                step(f, Op::Select(ValueType::Float), &[15, 131, 596, 137], 578);
                step(f, Op::MulF, &[135, 137, 139], 579);
                step(f, Op::DeltaTime, &[133], 580);
                step(f, Op::DivF, &[133, 106, 134], 581);
                step(f, Op::MulF, &[139, 134, 140], 582);
                step(f, Op::AddF, &[14, 140, 141], 583);
                step(f, Op::ClampF, &[141, 596, 598, 142], 584);
                step(f, Op::Select(ValueType::Float), &[14, 600, 598, 136], 585);
                step(f, Op::SubF, &[598, 131, 132], 586);
                step(f, Op::Select(ValueType::Float), &[15, 132, 598, 138], 587);
                step(f, Op::MulF, &[136, 138, 143], 588);
                step(f, Op::MulF, &[143, 134, 144], 589);
                step(f, Op::AddF, &[142, 144, 145], 590);
                step(f, Op::ClampF, &[145, 596, 598, 146], 591);
                step(f, Op::MulF, &[146, 146, 147], 592);
                step(f, Op::MulF, &[146, 601, 148], 593);
                step(f, Op::SubF, &[602, 148, 149], 594);
                step(f, Op::MulF, &[147, 149, 150], 595);
                step(f, Op::AddF, &[15, 150, 151], 596);
                step(f, Op::MulF, &[151, 597, 152], 597);
                step(f, Op::SubF, &[598, 152, 153], 598);
                step(f, Op::MulF, &[153, 153, 154], 599);
                step(f, Op::SubF, &[598, 154, 155], 600);
                step(f, Op::Copy(ValueType::Float), &[155, 16], 601);
                step(f, Op::Copy(ValueType::Float), &[150, 15], 602);
                step(f, Op::Copy(ValueType::Float), &[146, 14], 603);
                step(f, Op::GreaterF, &[15, 596, 21], 604);
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
                step(f, Op::BreakVector, &[70, 164, 165, 166], 633);
                step(f, Op::MakeVector, &[164, 165, 596, 74], 634);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 38, 24], 635);
                step(f, Op::BreakTransform, &[24, 72, 13, 73], 636);
                step(f, Op::BreakVector, &[72, 167, 168, 169], 637);
                step(f, Op::MakeVector, &[167, 168, 596, 75], 638);
                step(f, Op::DistanceV, &[74, 75, 170], 639);
                step(f, Op::GreaterF, &[170, 25, 29], 640);
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
                step(f, Op::LengthV, &[2, 156], 648);
                step(f, Op::GreaterF, &[156, 23, 22], 649);
                step(f, Op::GreaterF, &[0, 23, 31], 650);
                step(f, Op::Or, &[22, 31, 32], 651);
                step(f, Op::Not, &[32, 33], 652);
                step(f, Op::And, &[30, 33, 38], 653);
                step(f, Op::DeltaTime, &[195], 654);
                step(f, Op::MulF, &[195, 28, 196], 655);
                step(f, Op::AddF, &[7, 196, 197], 656);
                step(f, Op::GreaterF, &[7, 597, 39], 657);
                step(f, Op::AddF, &[27, 597, 193], 658);
                step(f, Op::Select(ValueType::Float), &[39, 193, 27, 194], 659);
                step(f, Op::MinF, &[197, 194, 198], 660);
                step(f, Op::NotEquals(Elem::Bool), &[33, 4, 34], 661);
                step(f, Op::Not, &[30, 35], 662);
                step(f, Op::And, &[34, 35, 36], 663);
                step(f, Op::SubF, &[8, 23, 179], 664);
                step(f, Op::SubF, &[8, 156, 180], 665);
                step(f, Op::DivF, &[179, 180, 181], 666);
                step(f, Op::ClampF, &[181, 596, 598, 182], 667);
                step(f, Op::MulF, &[3, 182, 184], 668);
                step(f, Op::RemapF, &[156, 23, 24, 596, 598, 78, 171], 669);
                step(f, Op::MaxF, &[171, 4, 172], 670);
                step(f, Op::Select(ValueType::Float), &[23, 598, 172, 173], 671);
                step(f, Op::Select(ValueType::Float), &[33, 26, 173, 174], 672);
                step(f, Op::Select(ValueType::Float), &[30, 171, 174, 175], 673);
                step(f, Op::SubF, &[598, 15, 176], 674);
                step(f, Op::MulF, &[175, 176, 177], 675);
                step(f, Op::LerpF, &[17, 38, 10, 159], 676);
                step(f, Op::RemapF, &[156, 20, 21, 18, 19, 78, 157], 677);
                step(f, Op::LerpF, &[157, 37, 10, 158], 678);
                step(f, Op::MaxF, &[156, 22, 160], 679);
                step(f, Op::DivF, &[158, 160, 161], 680);
                step(f, Op::AddF, &[159, 161, 162], 681);
                step(f, Op::DivF, &[177, 162, 178], 682);
                step(f, Op::SubF, &[598, 182, 183], 683);
                step(f, Op::MulF, &[178, 183, 185], 684);
                step(f, Op::AddF, &[184, 185, 186], 685);
                step(f, Op::MulF, &[186, 601, 187], 686);
                step(f, Op::AddF, &[3, 178, 188], 687);
                step(f, Op::Select(ValueType::Float), &[36, 187, 188, 189], 688);
                step(f, Op::DivF, &[601, 189, 190], 689);
                step(f, Op::GreaterF, &[189, 596, 37], 690);
                step(f, Op::CycleStep, &[7, 190, 596, 37, 191, 192], 691);
                step(f, Op::Select(ValueType::Float), &[38, 198, 191, 199], 692);
                step(f, Op::Copy(ValueType::Float), &[199, 7], 693);
                step(f, Op::Copy(ValueType::Float), &[178, 3], 694);
                step(f, Op::Copy(ValueType::Bool), &[22, 3], 695);
                step(f, Op::Copy(ValueType::Float), &[161, 1], 696);
                step(f, Op::Copy(ValueType::Float), &[162, 2], 697);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 698);
                step(f, Op::Copy(ValueType::Int), &[64, 31], 699);
                699
            }
            699 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 31, 14, 32, 33, 873], 700)
            }
            700 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 32, 213], 701);
                step(f, Op::ToFloat, &[32, 200], 702);
                step(f, Op::MulF, &[200, 597, 201], 703);
                step(f, Op::AddF, &[7, 201, 202], 704);
                step(f, Op::FractF, &[202, 203], 705);
                step(f, Op::SubF, &[213, 203, 215], 706);
                step(f, Op::GreaterF, &[215, 597, 40], 707);
                step(f, Op::ArrayAt(Elem::Float), &[2, 32, 214], 708);
                step(f, Op::Select(ValueType::Float), &[40, 596, 214, 242], 709);
                step(f, Op::ArraySetAt(Elem::Float), &[3, 32, 242], 710);
                step(f, Op::ArrayAt(Elem::Float), &[0, 32, 213], 711);
                step(f, Op::ToFloat, &[32, 200], 712);
                step(f, Op::MulF, &[200, 597, 201], 713);
                step(f, Op::AddF, &[7, 201, 202], 714);
                step(f, Op::FractF, &[202, 203], 715);
                step(f, Op::SubF, &[213, 203, 215], 716);
                step(f, Op::GreaterF, &[215, 597, 40], 717);
                step(f, Op::SubF, &[598, 213, 236], 718);
                step(f, Op::AddF, &[203, 236, 237], 719);
                step(f, Op::DivF, &[203, 237, 238], 720);
                step(f, Op::LengthV, &[2, 156], 721);
                step(f, Op::GreaterF, &[156, 23, 22], 722);
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
                step(f, Op::BreakVector, &[70, 164, 165, 166], 746);
                step(f, Op::MakeVector, &[164, 165, 596, 74], 747);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 38, 24], 748);
                step(f, Op::BreakTransform, &[24, 72, 13, 73], 749);
                step(f, Op::BreakVector, &[72, 167, 168, 169], 750);
                step(f, Op::MakeVector, &[167, 168, 596, 75], 751);
                step(f, Op::DistanceV, &[74, 75, 170], 752);
                step(f, Op::GreaterF, &[170, 25, 29], 753);
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
                step(f, Op::SubF, &[8, 23, 179], 763);
                step(f, Op::SubF, &[8, 156, 180], 764);
                step(f, Op::DivF, &[179, 180, 181], 765);
                step(f, Op::ClampF, &[181, 596, 598, 182], 766);
                step(f, Op::MulF, &[6, 182, 205], 767);
                step(f, Op::RemapF, &[156, 23, 24, 596, 598, 78, 171], 768);
                step(f, Op::MaxF, &[171, 4, 172], 769);
                step(f, Op::Select(ValueType::Float), &[23, 598, 172, 173], 770);
                step(f, Op::Select(ValueType::Float), &[33, 26, 173, 174], 771);
                step(f, Op::Select(ValueType::Float), &[30, 171, 174, 175], 772);
                step(f, Op::SubF, &[598, 15, 176], 773);
                step(f, Op::MulF, &[175, 176, 177], 774);
                step(f, Op::LerpF, &[17, 38, 10, 159], 775);
                step(f, Op::DivF, &[177, 159, 204], 776);
                step(f, Op::SubF, &[598, 182, 183], 777);
                step(f, Op::MulF, &[204, 183, 206], 778);
                step(f, Op::AddF, &[205, 206, 207], 779);
                step(f, Op::MulF, &[207, 601, 208], 780);
                step(f, Op::AddF, &[6, 204, 209], 781);
                step(f, Op::Select(ValueType::Float), &[36, 208, 209, 210], 782);
                step(f, Op::DeltaTime, &[195], 783);
                step(f, Op::MulF, &[195, 597, 211], 784);
                step(f, Op::MulF, &[210, 211, 212], 785);
                step(f, Op::MulF, &[238, 212, 239], 786);
                step(f, Op::ArrayAt(Elem::Float), &[2, 32, 214], 787);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 32, 41], 788);
                step(f, Op::RemapF, &[156, 20, 21, 18, 19, 78, 157], 789);
                step(f, Op::LerpF, &[157, 37, 10, 158], 790);
                step(f, Op::MaxF, &[156, 22, 160], 791);
                step(f, Op::DivF, &[158, 160, 161], 792);
                step(f, Op::AddF, &[159, 161, 162], 793);
                step(f, Op::DivF, &[159, 162, 163], 794);
                step(f, Op::SubF, &[163, 5, 216], 795);
                step(f, Op::MaxF, &[216, 596, 217], 796);
                step(f, Op::DivF, &[217, 163, 218], 797);
                step(f, Op::SubF, &[598, 10, 220], 798);
                step(f, Op::MulF, &[218, 220, 227], 799);
                step(f, Op::MulF, &[227, 176, 228], 800);
                step(f, Op::MulF, &[228, 104, 229], 801);
                step(f, Op::DivF, &[42, 195, 225], 802);
                step(f, Op::SubF, &[597, 225, 226], 803);
                step(f, Op::MulF, &[229, 226, 230], 804);
                step(f, Op::SubF, &[598, 230, 231], 805);
                step(f, Op::MulF, &[212, 231, 232], 806);
                step(f, Op::Select(ValueType::Float), &[41, 212, 232, 233], 807);
                step(f, Op::MulF, &[218, 214, 219], 808);
                step(f, Op::MulF, &[219, 220, 221], 809);
                step(f, Op::MulF, &[221, 176, 222], 810);
                step(f, Op::MulF, &[222, 104, 223], 811);
                step(f, Op::Select(ValueType::Float), &[41, 596, 223, 224], 812);
                step(f, Op::SubF, &[233, 224, 234], 813);
                step(f, Op::AddF, &[214, 234, 235], 814);
                step(f, Op::Select(ValueType::Float), &[40, 239, 235, 240], 815);
                step(f, Op::MinF, &[240, 601, 241], 816);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 32, 241], 817);
                step(f, Op::ArrayAt(Elem::Float), &[0, 32, 213], 818);
                step(f, Op::ToFloat, &[32, 200], 819);
                step(f, Op::MulF, &[200, 597, 201], 820);
                step(f, Op::AddF, &[7, 201, 202], 821);
                step(f, Op::FractF, &[202, 203], 822);
                step(f, Op::SubF, &[213, 203, 215], 823);
                step(f, Op::GreaterF, &[215, 597, 40], 824);
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
                step(f, Op::BreakVector, &[70, 164, 165, 166], 845);
                step(f, Op::MakeVector, &[164, 165, 596, 74], 846);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 38, 24], 847);
                step(f, Op::BreakTransform, &[24, 72, 13, 73], 848);
                step(f, Op::BreakVector, &[72, 167, 168, 169], 849);
                step(f, Op::MakeVector, &[167, 168, 596, 75], 850);
                step(f, Op::DistanceV, &[74, 75, 170], 851);
                step(f, Op::GreaterF, &[170, 25, 29], 852);
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
                step(f, Op::LengthV, &[2, 156], 860);
                step(f, Op::RemapF, &[156, 23, 24, 596, 598, 78, 171], 861);
                step(f, Op::GreaterF, &[156, 23, 22], 862);
                step(f, Op::GreaterF, &[0, 23, 31], 863);
                step(f, Op::Or, &[22, 31, 32], 864);
                step(f, Op::Not, &[32, 33], 865);
                step(f, Op::MaxF, &[171, 4, 172], 866);
                step(f, Op::Select(ValueType::Float), &[23, 598, 172, 173], 867);
                step(f, Op::Select(ValueType::Float), &[33, 26, 173, 174], 868);
                step(f, Op::Select(ValueType::Float), &[30, 171, 174, 175], 869);
                step(f, Op::Copy(ValueType::Float), &[175, 4], 870);
                step(f, Op::Jump, &[871], 871)
            }
            871 => {
                step(f, Op::ArraySetAt(Elem::Float), &[0, 32, 203], 872);
                step(f, Op::Jump, &[699], 873)
            }
            873 => {
                step(f, Op::LerpF, &[17, 38, 10, 159], 874);
                step(f, Op::LengthV, &[2, 156], 875);
                step(f, Op::RemapF, &[156, 20, 21, 18, 19, 78, 157], 876);
                step(f, Op::LerpF, &[157, 37, 10, 158], 877);
                step(f, Op::MaxF, &[156, 22, 160], 878);
                step(f, Op::DivF, &[158, 160, 161], 879);
                step(f, Op::AddF, &[159, 161, 162], 880);
                step(f, Op::DivF, &[159, 162, 163], 881);
                step(f, Op::Copy(ValueType::Float), &[163, 5], 882);
                step(f, Op::GreaterF, &[156, 23, 22], 883);
                step(f, Op::GreaterF, &[0, 23, 31], 884);
                step(f, Op::Or, &[22, 31, 32], 885);
                step(f, Op::Not, &[32, 33], 886);
                step(f, Op::Copy(ValueType::Bool), &[33, 4], 887);
                step(f, Op::Copy(ValueType::Float), &[156, 8], 888);
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
                step(f, Op::BreakVector, &[70, 164, 165, 166], 908);
                step(f, Op::MakeVector, &[164, 165, 596, 74], 909);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 38, 24], 910);
                step(f, Op::BreakTransform, &[24, 72, 13, 73], 911);
                step(f, Op::BreakVector, &[72, 167, 168, 169], 912);
                step(f, Op::MakeVector, &[167, 168, 596, 75], 913);
                step(f, Op::DistanceV, &[74, 75, 170], 914);
                step(f, Op::GreaterF, &[170, 25, 29], 915);
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
                step(f, Op::RemapF, &[156, 23, 24, 596, 598, 78, 171], 923);
                step(f, Op::MaxF, &[171, 4, 172], 924);
                step(f, Op::Select(ValueType::Float), &[23, 598, 172, 173], 925);
                step(f, Op::Select(ValueType::Float), &[33, 26, 173, 174], 926);
                step(f, Op::Select(ValueType::Float), &[30, 171, 174, 175], 927);
                step(f, Op::SubF, &[598, 15, 176], 928);
                step(f, Op::MulF, &[175, 176, 177], 929);
                step(f, Op::DivF, &[177, 159, 204], 930);
                step(f, Op::Copy(ValueType::Float), &[204, 6], 931);
                step(f, Op::Select(ValueType::Vec3), &[3, 2, 380, 76], 932);
                step(f, Op::MovementAngleOffset, &[76, 9, 7, 32, 33, 603, 34, 604, 243], 933);
                step(f, Op::Copy(ValueType::Float), &[243, 9], 934);
                step(f, Op::QuatFromAxisAngle, &[383, 9, 14], 935);
                step(f, Op::Copy(ValueType::Quat), &[14, 0], 936);
                step(f, Op::SinF, &[9, 244], 937);
                step(f, Op::AbsF, &[244, 245], 938);
                step(f, Op::RemapF, &[245, 35, 36, 596, 598, 78, 246], 939);
                step(f, Op::Copy(ValueType::Float), &[246, 10], 940);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 941);
                step(f, Op::Copy(ValueType::Int), &[64, 2], 942);
                942
            }
            942 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 2, 0, 3, 4, 1648], 943)
            }
            943 => {
                step(f, Op::Copy(ValueType::Bone), &[0, 16], 944);
                step(f, Op::Copy(ValueType::Int), &[3, 40], 945);
                step(f, Op::GetTransform, &[35, 64, 78, 25], 946);
                step(f, Op::BreakTransform, &[25, 79, 15, 80], 947);
                step(f, Op::BreakVector, &[79, 258, 259, 260], 948);
                step(f, Op::SubF, &[598, 10, 256], 949);
                step(f, Op::MulF, &[9, 256, 257], 950);
                step(f, Op::QuatFromAxisAngle, &[383, 257, 17], 951);
                step(f, Op::GetTransform, &[16, 64, 78, 26], 952);
                step(f, Op::BreakTransform, &[26, 81, 16, 82], 953);
                step(f, Op::SubV, &[81, 79, 83], 954);
                step(f, Op::BreakVector, &[83, 253, 254, 255], 955);
                step(f, Op::MakeVector, &[253, 254, 596, 84], 956);
                step(f, Op::RotateVector, &[17, 84, 85], 957);
                step(f, Op::BreakVector, &[85, 261, 262, 263], 958);
                step(f, Op::MulF, &[39, 10, 264], 959);
                step(f, Op::Equals(Elem::Int), &[40, 64, 42], 960);
                step(f, Op::Select(ValueType::Float), &[42, 598, 600, 273], 961);
                step(f, Op::MulF, &[264, 273, 265], 962);
                step(f, Op::AddF, &[261, 265, 266], 963);
                step(f, Op::AddF, &[258, 266, 267], 964);
                step(f, Op::AddF, &[259, 262, 268], 965);
                step(f, Op::BreakVector, &[81, 269, 270, 271], 966);
                step(f, Op::SubF, &[271, 43, 272], 967);
                step(f, Op::MakeVector, &[267, 268, 272, 86], 968);
                step(f, Op::ArrayAt(Elem::Float), &[2, 40, 247], 969);
                step(f, Op::SubF, &[598, 247, 248], 970);
                step(f, Op::MaxF, &[248, 596, 249], 971);
                step(f, Op::MulF, &[5, 2, 250], 972);
                step(f, Op::MulF, &[249, 250, 251], 973);
                step(f, Op::ScaleV, &[2, 251, 77], 974);
                step(f, Op::AddV, &[86, 77, 87], 975);
                step(f, Op::MulF, &[1, 597, 252], 976);
                step(f, Op::ScaleV, &[2, 252, 78], 977);
                step(f, Op::AddV, &[87, 78, 88], 978);
                step(f, Op::RotateVector, &[0, 384, 89], 979);
                step(f, Op::Copy(ValueType::Vec3), &[88, 110], 980);
                step(f, Op::Copy(ValueType::Vec3), &[89, 111], 981);
                step(f, Op::Copy(ValueType::Float), &[273, 292], 982);
                step(f, Op::Copy(ValueType::Vec3), &[380, 112], 983);
                step(f, Op::Copy(ValueType::Vec3), &[380, 113], 984);
                step(f, Op::Copy(ValueType::Bool), &[79, 44], 985);
                step(f, Op::Copy(ValueType::Float), &[605, 293], 986);
                step(f, Op::Copy(ValueType::Vec3), &[380, 114], 987);
                step(f, Op::Copy(ValueType::Vec3), &[383, 115], 988);
                step(f, Op::Copy(ValueType::Bool), &[79, 45], 989);
                step(f, Op::MulI, &[0, 0, 46], 990);
                step(f, Op::Copy(ValueType::Int), &[46, 45], 991);
                step(f, Op::Copy(ValueType::Int), &[64, 41], 992);
                step(f, Op::SubI, &[0, 65, 49], 993);
                step(f, Op::DivI, &[49, 66, 50], 994);
                step(f, Op::MakeVector, &[596, 596, 48, 120], 995);
                step(f, Op::ScaleV, &[111, 50, 125], 996);
                996
            }
            996 => {
                step(f, Op::ForNext, &[41, 45, 43, 1036], 997)
            }
            997 => {
                step(f, Op::ModI, &[43, 0, 47], 998);
                step(f, Op::ToFloat, &[47, 294], 999);
                step(f, Op::MulF, &[294, 49, 296], 1000);
                step(f, Op::MulF, &[296, 292, 297], 1001);
                step(f, Op::MakeVector, &[297, 596, 596, 116], 1002);
                step(f, Op::DivI, &[43, 0, 48], 1003);
                step(f, Op::SubI, &[48, 50, 51], 1004);
                step(f, Op::ToFloat, &[51, 295], 1005);
                step(f, Op::MulF, &[295, 49, 298], 1006);
                step(f, Op::ScaleV, &[111, 298, 117], 1007);
                step(f, Op::AddV, &[116, 117, 118], 1008);
                step(f, Op::AddV, &[110, 118, 119], 1009);
                step(f, Op::AddV, &[119, 120, 121], 1010);
                step(f, Op::SubV, &[119, 120, 122], 1011);
                step(f, Op::SphereTrace, &[121, 122, 47, 46, 123, 124, 299], 1012);
                step(f, Op::BreakVector, &[123, 301, 302, 303], 1013);
                step(f, Op::AddV, &[121, 125, 126], 1014);
                step(f, Op::AddV, &[122, 125, 127], 1015);
                step(f, Op::SphereTrace, &[126, 127, 47, 47, 128, 129, 300], 1016);
                step(f, Op::BreakVector, &[128, 304, 305, 306], 1017);
                step(f, Op::SubF, &[303, 306, 307], 1018);
                step(f, Op::AbsF, &[307, 308], 1019);
                step(f, Op::Select(ValueType::Float), &[46, 596, 598, 309], 1020);
                step(f, Op::AddF, &[308, 309, 314], 1021);
                step(f, Op::LengthV, &[118, 310], 1022);
                step(f, Op::RemapF, &[310, 596, 606, 596, 598, 78, 311], 1023);
                step(f, Op::MinF, &[303, 306, 312], 1024);
                step(f, Op::RemapF, &[312, 607, 606, 598, 597, 78, 313], 1025);
                step(f, Op::AddF, &[311, 313, 315], 1026);
                step(f, Op::AddF, &[314, 315, 316], 1027);
                step(f, Op::LessF, &[316, 293, 48], 1028);
                step(f, Op::And, &[46, 48, 49], 1029);
                step(f, Op::JumpIfFalse, &[49, 1035], 1030)
            }
            1030 => {
                step(f, Op::Copy(ValueType::Float), &[316, 293], 1031);
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
                step(f, Op::ArrayAt(Elem::Float), &[2, 40, 247], 1046);
                step(f, Op::SubF, &[598, 247, 248], 1047);
                step(f, Op::MaxF, &[248, 596, 249], 1048);
                step(f, Op::MulF, &[5, 2, 250], 1049);
                step(f, Op::MulF, &[249, 250, 251], 1050);
                step(f, Op::ScaleV, &[2, 251, 77], 1051);
                step(f, Op::SubV, &[112, 77, 90], 1052);
                step(f, Op::Select(ValueType::Vec3), &[44, 90, 91, 93], 1053);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 40, 28], 1054);
                step(f, Op::BreakTransform, &[28, 94, 23, 95], 1055);
                step(f, Op::Copy(ValueType::Vec3), &[91, 96], 1056);
                step(f, Op::Copy(ValueType::Vec3), &[93, 97], 1057);
                step(f, Op::Copy(ValueType::Vec3), &[94, 98], 1058);
                step(f, Op::Copy(ValueType::Float), &[40, 279], 1059);
                step(f, Op::Copy(ValueType::Float), &[42, 280], 1060);
                step(f, Op::Copy(ValueType::Vec3), &[380, 99], 1061);
                step(f, Op::SubV, &[97, 98, 100], 1062);
                step(f, Op::DeltaTime, &[281], 1063);
                step(f, Op::DivF, &[280, 281, 282], 1064);
                step(f, Op::ScaleV, &[100, 282, 101], 1065);
                step(f, Op::AddV, &[97, 101, 102], 1066);
                step(f, Op::AddV, &[98, 101, 103], 1067);
                step(f, Op::SubV, &[96, 103, 104], 1068);
                step(f, Op::FloatLerp, &[596, 598, 279, 283], 1069);
                step(f, Op::SubF, &[598, 283, 284], 1070);
                step(f, Op::ScaleV, &[104, 284, 105], 1071);
                step(f, Op::AddV, &[102, 105, 107], 1072);
                step(f, Op::MulF, &[279, 281, 285], 1073);
                step(f, Op::GreaterF, &[285, 596, 43], 1074);
                step(f, Op::DivF, &[283, 285, 286], 1075);
                step(f, Op::Select(ValueType::Float), &[43, 286, 598, 287], 1076);
                step(f, Op::ScaleV, &[100, 287, 106], 1077);
                step(f, Op::SubV, &[107, 106, 108], 1078);
                step(f, Op::Copy(ValueType::Vec3), &[108, 99], 1079);
                step(f, Op::Jump, &[1080], 1080)
            }
            1080 => {
                step(f, Op::BreakVector, &[99, 288, 289, 290], 1081);
                step(f, Op::ClampF, &[290, 51, 52, 291], 1082);
                step(f, Op::MakeVector, &[288, 289, 291, 109], 1083);
                step(f, Op::RotationFromNormal, &[113, 277, 278, 19], 1084);
                step(f, Op::PerFootRotationFactor, &[9, 82, 83, 274], 1085);
                step(f, Op::MulF, &[9, 274, 275], 1086);
                step(f, Op::SubF, &[598, 10, 256], 1087);
                step(f, Op::MulF, &[275, 256, 276], 1088);
                step(f, Op::QuatFromAxisAngle, &[383, 276, 18], 1089);
                step(f, Op::MulQ, &[19, 18, 20], 1090);
                step(f, Op::Select(ValueType::Quat), &[44, 20, 21, 22], 1091);
                step(f, Op::MakeTransform, &[109, 22, 381, 30], 1092);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 40, 30], 1093);
                step(f, Op::ArrayAt(Elem::Float), &[2, 40, 247], 1094);
                step(f, Op::SubF, &[598, 247, 248], 1095);
                step(f, Op::MaxF, &[248, 596, 249], 1096);
                step(f, Op::MulF, &[5, 2, 250], 1097);
                step(f, Op::MulF, &[249, 250, 251], 1098);
                step(f, Op::ScaleV, &[2, 251, 77], 1099);
                step(f, Op::SubV, &[112, 77, 90], 1100);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 40, 27], 1101);
                step(f, Op::BreakTransform, &[27, 91, 21, 92], 1102);
                step(f, Op::Select(ValueType::Vec3), &[44, 90, 91, 93], 1103);
                step(f, Op::MakeTransform, &[93, 88, 381, 29], 1104);
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
                step(f, Op::GreaterF, &[15, 596, 53], 1111);
                step(f, Op::InterpolateTransform, &[2, 108, 16, 31], 1112);
                step(f, Op::Select(ValueType::Transform), &[53, 31, 2, 32], 1113);
                step(f, Op::MakeAbsolute, &[33, 32, 34], 1114);
                step(f, Op::BreakTransform, &[34, 130, 24, 131], 1115);
                step(f, Op::ClampSpatially, &[130, 380, 596, 55, 132], 1116);
                step(f, Op::SubF, &[598, 10, 322], 1117);
                step(f, Op::MulF, &[9, 322, 318], 1118);
                step(f, Op::LimitRotationAroundZ, &[24, 318, 81, 25], 1119);
                step(f, Op::MakeTransform, &[132, 25, 381, 35], 1120);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 52, 35], 1121);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 52, 50], 1122);
                step(f, Op::JumpIfFalse, &[50, 1176], 1123)
            }
            1123 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 52, 37], 1124);
                step(f, Op::BreakTransform, &[37, 133, 26, 134], 1125);
                step(f, Op::ArrayAt(Elem::Float), &[2, 52, 317], 1126);
                step(f, Op::SubF, &[598, 317, 319], 1127);
                step(f, Op::MulF, &[5, 2, 320], 1128);
                step(f, Op::MulF, &[319, 320, 321], 1129);
                step(f, Op::ScaleV, &[2, 321, 135], 1130);
                step(f, Op::AddV, &[133, 135, 136], 1131);
                step(f, Op::MakeTransform, &[136, 26, 381, 44], 1132);
                step(f, Op::Copy(ValueType::Transform), &[44, 45], 1133);
                step(f, Op::Copy(ValueType::Transform), &[108, 46], 1134);
                step(f, Op::BreakTransform, &[45, 164, 31, 165], 1135);
                step(f, Op::MakeVector, &[596, 596, 48, 166], 1136);
                step(f, Op::AddV, &[164, 166, 167], 1137);
                step(f, Op::SubV, &[164, 166, 168], 1138);
                step(f, Op::LineTrace, &[167, 168, 57, 169, 170, 349], 1139);
                step(f, Op::RotateVector, &[31, 383, 171], 1140);
                step(f, Op::FindQuatBetween, &[171, 170, 32], 1141);
                step(f, Op::MulQ, &[32, 31, 33], 1142);
                step(f, Op::MulF, &[46, 45, 350], 1143);
                step(f, Op::AddF, &[350, 54, 351], 1144);
                step(f, Op::NegF, &[351, 352], 1145);
                step(f, Op::MakeVector, &[596, 352, 596, 172], 1146);
                step(f, Op::RotateVector, &[33, 172, 174], 1147);
                step(f, Op::AddV, &[169, 174, 176], 1148);
                step(f, Op::AddV, &[176, 166, 178], 1149);
                step(f, Op::SubV, &[176, 166, 179], 1150);
                step(f, Op::LineTrace, &[178, 179, 58, 182, 183, 354], 1151);
                step(f, Op::BreakVector, &[182, 356, 357, 358], 1152);
                step(f, Op::BreakVector, &[176, 362, 363, 364], 1153);
                step(f, Op::SubF, &[358, 364, 368], 1154);
                step(f, Op::Select(ValueType::Float), &[58, 368, 596, 370], 1155);
                step(f, Op::AddF, &[50, 54, 353], 1156);
                step(f, Op::MakeVector, &[596, 353, 596, 173], 1157);
                step(f, Op::RotateVector, &[33, 173, 175], 1158);
                step(f, Op::AddV, &[169, 175, 177], 1159);
                step(f, Op::AddV, &[177, 166, 180], 1160);
                step(f, Op::SubV, &[177, 166, 181], 1161);
                step(f, Op::LineTrace, &[180, 181, 59, 184, 185, 355], 1162);
                step(f, Op::BreakVector, &[184, 359, 360, 361], 1163);
                step(f, Op::BreakVector, &[177, 365, 366, 367], 1164);
                step(f, Op::SubF, &[361, 367, 369], 1165);
                step(f, Op::Select(ValueType::Float), &[59, 369, 596, 371], 1166);
                step(f, Op::MaxF, &[370, 371, 372], 1167);
                step(f, Op::ClampF, &[372, 596, 53, 373], 1168);
                step(f, Op::MakeVector, &[596, 596, 373, 186], 1169);
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
                step(f, Op::GreaterF, &[15, 596, 53], 1178);
                step(f, Op::InterpolateTransform, &[2, 108, 16, 31], 1179);
                step(f, Op::Select(ValueType::Transform), &[53, 31, 2, 32], 1180);
                step(f, Op::MakeAbsolute, &[49, 32, 50], 1181);
                step(f, Op::BreakTransform, &[50, 188, 34, 189], 1182);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 52, 37], 1183);
                step(f, Op::BreakTransform, &[37, 133, 26, 134], 1184);
                step(f, Op::ArrayAt(Elem::Float), &[2, 52, 317], 1185);
                step(f, Op::SubF, &[598, 317, 319], 1186);
                step(f, Op::MulF, &[5, 2, 320], 1187);
                step(f, Op::MulF, &[319, 320, 321], 1188);
                step(f, Op::ScaleV, &[2, 321, 135], 1189);
                step(f, Op::AddV, &[133, 135, 136], 1190);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 52, 51], 1191);
                step(f, Op::MakeAbsolute, &[51, 32, 52], 1192);
                step(f, Op::BreakTransform, &[52, 190, 35, 191], 1193);
                step(f, Op::ArrayAt(Elem::Float), &[3, 52, 374], 1194);
                step(f, Op::SubF, &[317, 374, 375], 1195);
                step(f, Op::DeltaTime, &[390], 1196);
                step(f, Op::DivF, &[42, 390, 376], 1197);
                step(f, Op::MulF, &[375, 376, 377], 1198);
                step(f, Op::AddF, &[374, 377, 378], 1199);
                step(f, Op::ClampF, &[378, 596, 598, 380], 1200);
                step(f, Op::AddF, &[317, 377, 379], 1201);
                step(f, Op::ClampF, &[379, 596, 598, 381], 1202);
                step(f, Op::AddF, &[380, 381, 382], 1203);
                step(f, Op::MulF, &[382, 597, 383], 1204);
                step(f, Op::SubF, &[598, 383, 384], 1205);
                step(f, Op::GreaterF, &[375, 596, 60], 1206);
                step(f, Op::SubF, &[381, 380, 385], 1207);
                step(f, Op::DivF, &[385, 375, 386], 1208);
                step(f, Op::Select(ValueType::Float), &[60, 386, 598, 387], 1209);
                step(f, Op::MulF, &[384, 387, 388], 1210);
                step(f, Op::MulF, &[69, 388, 389], 1211);
                step(f, Op::Copy(ValueType::Vec3), &[188, 192], 1212);
                step(f, Op::Copy(ValueType::Vec3), &[136, 193], 1213);
                step(f, Op::Copy(ValueType::Vec3), &[190, 194], 1214);
                step(f, Op::Copy(ValueType::Float), &[389, 391], 1215);
                step(f, Op::Copy(ValueType::Float), &[42, 392], 1216);
                step(f, Op::Copy(ValueType::Vec3), &[380, 195], 1217);
                step(f, Op::SubV, &[193, 194, 196], 1218);
                step(f, Op::DeltaTime, &[393], 1219);
                step(f, Op::DivF, &[392, 393, 394], 1220);
                step(f, Op::ScaleV, &[196, 394, 197], 1221);
                step(f, Op::AddV, &[193, 197, 198], 1222);
                step(f, Op::AddV, &[194, 197, 199], 1223);
                step(f, Op::SubV, &[192, 199, 200], 1224);
                step(f, Op::FloatLerp, &[596, 598, 391, 395], 1225);
                step(f, Op::SubF, &[598, 395, 396], 1226);
                step(f, Op::ScaleV, &[200, 396, 201], 1227);
                step(f, Op::AddV, &[198, 201, 203], 1228);
                step(f, Op::MulF, &[391, 393, 397], 1229);
                step(f, Op::GreaterF, &[397, 596, 61], 1230);
                step(f, Op::DivF, &[395, 397, 398], 1231);
                step(f, Op::Select(ValueType::Float), &[61, 398, 598, 399], 1232);
                step(f, Op::ScaleV, &[196, 399, 202], 1233);
                step(f, Op::SubV, &[203, 202, 204], 1234);
                step(f, Op::Copy(ValueType::Vec3), &[204, 195], 1235);
                step(f, Op::Jump, &[1236], 1236)
            }
            1236 => {
                step(f, Op::MakeTransform, &[195, 26, 381, 54], 1237);
                step(f, Op::Copy(ValueType::Transform), &[54, 55], 1238);
                step(f, Op::Copy(ValueType::Transform), &[108, 56], 1239);
                step(f, Op::BreakTransform, &[55, 205, 36, 206], 1240);
                step(f, Op::MakeVector, &[596, 596, 48, 207], 1241);
                step(f, Op::AddV, &[205, 207, 208], 1242);
                step(f, Op::SubV, &[205, 207, 209], 1243);
                step(f, Op::LineTrace, &[208, 209, 62, 210, 211, 400], 1244);
                step(f, Op::RotateVector, &[36, 383, 212], 1245);
                step(f, Op::FindQuatBetween, &[212, 211, 37], 1246);
                step(f, Op::MulQ, &[37, 36, 38], 1247);
                step(f, Op::MulF, &[46, 45, 401], 1248);
                step(f, Op::AddF, &[401, 54, 402], 1249);
                step(f, Op::NegF, &[402, 403], 1250);
                step(f, Op::MakeVector, &[596, 403, 596, 213], 1251);
                step(f, Op::RotateVector, &[38, 213, 215], 1252);
                step(f, Op::AddV, &[210, 215, 217], 1253);
                step(f, Op::AddV, &[217, 207, 219], 1254);
                step(f, Op::SubV, &[217, 207, 220], 1255);
                step(f, Op::LineTrace, &[219, 220, 63, 223, 224, 405], 1256);
                step(f, Op::BreakVector, &[223, 407, 408, 409], 1257);
                step(f, Op::BreakVector, &[217, 413, 414, 415], 1258);
                step(f, Op::SubF, &[409, 415, 419], 1259);
                step(f, Op::Select(ValueType::Float), &[63, 419, 596, 421], 1260);
                step(f, Op::AddF, &[50, 54, 404], 1261);
                step(f, Op::MakeVector, &[596, 404, 596, 214], 1262);
                step(f, Op::RotateVector, &[38, 214, 216], 1263);
                step(f, Op::AddV, &[210, 216, 218], 1264);
                step(f, Op::AddV, &[218, 207, 221], 1265);
                step(f, Op::SubV, &[218, 207, 222], 1266);
                step(f, Op::LineTrace, &[221, 222, 64, 225, 226, 406], 1267);
                step(f, Op::BreakVector, &[225, 410, 411, 412], 1268);
                step(f, Op::BreakVector, &[218, 416, 417, 418], 1269);
                step(f, Op::SubF, &[412, 418, 420], 1270);
                step(f, Op::Select(ValueType::Float), &[64, 420, 596, 422], 1271);
                step(f, Op::MaxF, &[421, 422, 423], 1272);
                step(f, Op::ClampF, &[423, 596, 53, 424], 1273);
                step(f, Op::MakeVector, &[596, 596, 424, 227], 1274);
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
                step(f, Op::ArrayAt(Elem::Float), &[2, 52, 317], 1281);
                step(f, Op::GreaterEqualF, &[317, 598, 51], 1282);
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
                step(f, Op::SubF, &[598, 10, 322], 1293);
                step(f, Op::MulF, &[9, 322, 323], 1294);
                step(f, Op::FootAvoidance, &[229, 137, 323, 52, 70, 139], 1295);
                step(f, Op::MakeTransform, &[139, 39, 381, 39], 1296);
                step(f, Op::Copy(ValueType::Transform), &[39, 40], 1297);
                step(f, Op::Copy(ValueType::Transform), &[108, 41], 1298);
                step(f, Op::BreakTransform, &[40, 140, 28, 141], 1299);
                step(f, Op::MakeVector, &[596, 596, 48, 142], 1300);
                step(f, Op::AddV, &[140, 142, 143], 1301);
                step(f, Op::SubV, &[140, 142, 144], 1302);
                step(f, Op::LineTrace, &[143, 144, 54, 145, 146, 324], 1303);
                step(f, Op::RotateVector, &[28, 383, 147], 1304);
                step(f, Op::FindQuatBetween, &[147, 146, 29], 1305);
                step(f, Op::MulQ, &[29, 28, 30], 1306);
                step(f, Op::MulF, &[46, 45, 325], 1307);
                step(f, Op::AddF, &[325, 54, 326], 1308);
                step(f, Op::NegF, &[326, 327], 1309);
                step(f, Op::MakeVector, &[596, 327, 596, 148], 1310);
                step(f, Op::RotateVector, &[30, 148, 150], 1311);
                step(f, Op::AddV, &[145, 150, 152], 1312);
                step(f, Op::AddV, &[152, 142, 154], 1313);
                step(f, Op::SubV, &[152, 142, 155], 1314);
                step(f, Op::LineTrace, &[154, 155, 55, 158, 159, 329], 1315);
                step(f, Op::BreakVector, &[158, 331, 332, 333], 1316);
                step(f, Op::BreakVector, &[152, 337, 338, 339], 1317);
                step(f, Op::SubF, &[333, 339, 343], 1318);
                step(f, Op::Select(ValueType::Float), &[55, 343, 596, 345], 1319);
                step(f, Op::AddF, &[50, 54, 328], 1320);
                step(f, Op::MakeVector, &[596, 328, 596, 149], 1321);
                step(f, Op::RotateVector, &[30, 149, 151], 1322);
                step(f, Op::AddV, &[145, 151, 153], 1323);
                step(f, Op::AddV, &[153, 142, 156], 1324);
                step(f, Op::SubV, &[153, 142, 157], 1325);
                step(f, Op::LineTrace, &[156, 157, 56, 160, 161, 330], 1326);
                step(f, Op::BreakVector, &[160, 334, 335, 336], 1327);
                step(f, Op::BreakVector, &[153, 340, 341, 342], 1328);
                step(f, Op::SubF, &[336, 342, 344], 1329);
                step(f, Op::Select(ValueType::Float), &[56, 344, 596, 346], 1330);
                step(f, Op::MaxF, &[345, 346, 347], 1331);
                step(f, Op::ClampF, &[347, 596, 53, 348], 1332);
                step(f, Op::MakeVector, &[596, 596, 348, 162], 1333);
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
                step(f, Op::Jump, &[1516], 1342)
            }
            1342 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 52, 36], 1343);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 52, 59], 1344);
                step(f, Op::ClampF, &[317, 596, 598, 425], 1345);
                step(f, Op::Copy(ValueType::Transform), &[36, 64], 1346);
                step(f, Op::Copy(ValueType::Transform), &[59, 65], 1347);
                step(f, Op::Copy(ValueType::Float), &[425, 440], 1348);
                step(f, Op::Copy(ValueType::Transform), &[108, 66], 1349);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[3, 2], 1350);
                step(f, Op::ArrayReset(Elem::Vec3), &[2], 1351);
                step(f, Op::BreakTransform, &[64, 245, 44, 246], 1352);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 245], 1353);
                step(f, Op::BreakTransform, &[64, 245, 44, 246], 1354);
                step(f, Op::UnitV, &[2, 244], 1355);
                step(f, Op::LengthV, &[2, 441], 1356);
                step(f, Op::RemapF, &[441, 596, 56, 596, 57, 78, 442], 1357);
                step(f, Op::ScaleV, &[244, 442, 249], 1358);
                step(f, Op::SubV, &[245, 249, 255], 1359);
                step(f, Op::MakeVector, &[596, 596, 59, 253], 1360);
                step(f, Op::AddV, &[255, 253, 257], 1361);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 257], 1362);
                step(f, Op::BreakTransform, &[64, 245, 44, 246], 1363);
                step(f, Op::UnitV, &[2, 244], 1364);
                step(f, Op::LengthV, &[2, 441], 1365);
                step(f, Op::RemapF, &[441, 596, 56, 596, 57, 78, 442], 1366);
                step(f, Op::ScaleV, &[244, 442, 249], 1367);
                step(f, Op::SubV, &[245, 249, 255], 1368);
                step(f, Op::MakeVector, &[596, 596, 59, 253], 1369);
                step(f, Op::AddV, &[255, 253, 257], 1370);
                step(f, Op::RemapF, &[441, 596, 56, 596, 61, 78, 444], 1371);
                step(f, Op::MakeVector, &[596, 596, 444, 251], 1372);
                step(f, Op::AddV, &[257, 251, 261], 1373);
                step(f, Op::BreakTransform, &[65, 247, 45, 248], 1374);
                step(f, Op::BreakVector, &[247, 449, 450, 451], 1375);
                step(f, Op::BreakVector, &[245, 446, 447, 448], 1376);
                step(f, Op::SubF, &[451, 448, 452], 1377);
                step(f, Op::MaxF, &[452, 596, 454], 1378);
                step(f, Op::MulF, &[454, 63, 458], 1379);
                step(f, Op::AbsF, &[452, 456], 1380);
                step(f, Op::RemapF, &[456, 596, 66, 596, 65, 78, 457], 1381);
                step(f, Op::AddF, &[458, 457, 460], 1382);
                step(f, Op::MakeVector, &[596, 596, 460, 259], 1383);
                step(f, Op::AddV, &[261, 259, 263], 1384);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 263], 1385);
                step(f, Op::BreakTransform, &[64, 245, 44, 246], 1386);
                step(f, Op::UnitV, &[2, 244], 1387);
                step(f, Op::LengthV, &[2, 441], 1388);
                step(f, Op::RemapF, &[441, 596, 56, 596, 57, 78, 442], 1389);
                step(f, Op::ScaleV, &[244, 442, 249], 1390);
                step(f, Op::SubV, &[245, 249, 255], 1391);
                step(f, Op::MakeVector, &[596, 596, 59, 253], 1392);
                step(f, Op::AddV, &[255, 253, 257], 1393);
                step(f, Op::RemapF, &[441, 596, 56, 596, 61, 78, 444], 1394);
                step(f, Op::MakeVector, &[596, 596, 444, 251], 1395);
                step(f, Op::AddV, &[257, 251, 261], 1396);
                step(f, Op::BreakTransform, &[65, 247, 45, 248], 1397);
                step(f, Op::BreakVector, &[247, 449, 450, 451], 1398);
                step(f, Op::BreakVector, &[245, 446, 447, 448], 1399);
                step(f, Op::SubF, &[451, 448, 452], 1400);
                step(f, Op::MaxF, &[452, 596, 454], 1401);
                step(f, Op::MulF, &[454, 63, 458], 1402);
                step(f, Op::AbsF, &[452, 456], 1403);
                step(f, Op::RemapF, &[456, 596, 66, 596, 65, 78, 457], 1404);
                step(f, Op::AddF, &[458, 457, 460], 1405);
                step(f, Op::MakeVector, &[596, 596, 460, 259], 1406);
                step(f, Op::AddV, &[261, 259, 263], 1407);
                step(f, Op::RemapF, &[441, 596, 56, 596, 58, 78, 443], 1408);
                step(f, Op::ScaleV, &[244, 443, 250], 1409);
                step(f, Op::AddV, &[247, 250, 256], 1410);
                step(f, Op::MakeVector, &[596, 596, 60, 254], 1411);
                step(f, Op::AddV, &[256, 254, 258], 1412);
                step(f, Op::RemapF, &[441, 596, 56, 596, 62, 78, 445], 1413);
                step(f, Op::MakeVector, &[596, 596, 445, 252], 1414);
                step(f, Op::AddV, &[258, 252, 262], 1415);
                step(f, Op::NegF, &[452, 453], 1416);
                step(f, Op::MaxF, &[453, 596, 455], 1417);
                step(f, Op::MulF, &[455, 64, 459], 1418);
                step(f, Op::AddF, &[459, 457, 461], 1419);
                step(f, Op::MakeVector, &[596, 596, 461, 260], 1420);
                step(f, Op::AddV, &[262, 260, 264], 1421);
                step(f, Op::LerpV, &[263, 264, 597, 265], 1422);
                step(f, Op::GetTransform, &[36, 64, 78, 67], 1423);
                step(f, Op::BreakTransform, &[67, 266, 46, 267], 1424);
                step(f, Op::BreakVector, &[266, 471, 472, 473], 1425);
                step(f, Op::SubF, &[598, 10, 465], 1426);
                step(f, Op::MulF, &[67, 465, 466], 1427);
                step(f, Op::MulF, &[9, 466, 467], 1428);
                step(f, Op::QuatFromAxisAngle, &[383, 467, 47], 1429);
                step(f, Op::SubV, &[265, 266, 268], 1430);
                step(f, Op::BreakVector, &[268, 462, 463, 464], 1431);
                step(f, Op::MakeVector, &[462, 463, 596, 269], 1432);
                step(f, Op::RotateVector, &[47, 269, 270], 1433);
                step(f, Op::BreakVector, &[270, 468, 469, 470], 1434);
                step(f, Op::AddF, &[471, 468, 477], 1435);
                step(f, Op::AddF, &[472, 469, 478], 1436);
                step(f, Op::BreakVector, &[265, 474, 475, 476], 1437);
                step(f, Op::MakeVector, &[477, 478, 476, 271], 1438);
                step(f, Op::DistanceV, &[245, 247, 479], 1439);
                step(f, Op::RemapF, &[479, 601, 608, 596, 598, 78, 480], 1440);
                step(f, Op::LerpV, &[265, 271, 480, 272], 1441);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 272], 1442);
                step(f, Op::BreakTransform, &[65, 247, 45, 248], 1443);
                step(f, Op::UnitV, &[2, 244], 1444);
                step(f, Op::LengthV, &[2, 441], 1445);
                step(f, Op::RemapF, &[441, 596, 56, 596, 58, 78, 443], 1446);
                step(f, Op::ScaleV, &[244, 443, 250], 1447);
                step(f, Op::AddV, &[247, 250, 256], 1448);
                step(f, Op::MakeVector, &[596, 596, 60, 254], 1449);
                step(f, Op::AddV, &[256, 254, 258], 1450);
                step(f, Op::RemapF, &[441, 596, 56, 596, 62, 78, 445], 1451);
                step(f, Op::MakeVector, &[596, 596, 445, 252], 1452);
                step(f, Op::AddV, &[258, 252, 262], 1453);
                step(f, Op::BreakVector, &[247, 449, 450, 451], 1454);
                step(f, Op::BreakTransform, &[64, 245, 44, 246], 1455);
                step(f, Op::BreakVector, &[245, 446, 447, 448], 1456);
                step(f, Op::SubF, &[451, 448, 452], 1457);
                step(f, Op::NegF, &[452, 453], 1458);
                step(f, Op::MaxF, &[453, 596, 455], 1459);
                step(f, Op::MulF, &[455, 64, 459], 1460);
                step(f, Op::AbsF, &[452, 456], 1461);
                step(f, Op::RemapF, &[456, 596, 66, 596, 65, 78, 457], 1462);
                step(f, Op::AddF, &[459, 457, 461], 1463);
                step(f, Op::MakeVector, &[596, 596, 461, 260], 1464);
                step(f, Op::AddV, &[262, 260, 264], 1465);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 264], 1466);
                step(f, Op::BreakTransform, &[65, 247, 45, 248], 1467);
                step(f, Op::UnitV, &[2, 244], 1468);
                step(f, Op::LengthV, &[2, 441], 1469);
                step(f, Op::RemapF, &[441, 596, 56, 596, 58, 78, 443], 1470);
                step(f, Op::ScaleV, &[244, 443, 250], 1471);
                step(f, Op::AddV, &[247, 250, 256], 1472);
                step(f, Op::MakeVector, &[596, 596, 60, 254], 1473);
                step(f, Op::AddV, &[256, 254, 258], 1474);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 258], 1475);
                step(f, Op::BreakTransform, &[65, 247, 45, 248], 1476);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 247], 1477);
                step(f, Op::JumpIfFalse, &[8, 1480], 1478)
            }
            1478 => {
                step(f, Op::DrawSpline, &[2, 64, 67, 597, 385], 1479);
                step(f, Op::Jump, &[1480], 1480)
            }
            1480 => {
                step(f, Op::Spline, &[2, 440, 64, 273, 274], 1481);
                step(f, Op::BreakTransform, &[64, 245, 44, 246], 1482);
                step(f, Op::BreakTransform, &[65, 247, 45, 248], 1483);
                step(f, Op::SlerpQ, &[44, 45, 440, 48], 1484);
                step(f, Op::MulF, &[440, 609, 481], 1485);
                step(f, Op::SinF, &[481, 482], 1486);
                step(f, Op::MulF, &[482, 68, 483], 1487);
                step(f, Op::SlerpQ, &[48, 88, 483, 49], 1488);
                step(f, Op::MakeTransform, &[273, 49, 381, 68], 1489);
                step(f, Op::Copy(ValueType::Transform), &[68, 66], 1490);
                step(f, Op::Jump, &[1491], 1491)
            }
            1491 => {
                step(f, Op::BreakTransform, &[66, 231, 40, 232], 1492);
                step(f, Op::Equals(Elem::Int), &[52, 64, 52], 1493);
                step(f, Op::Select(ValueType::Int), &[52, 65, 64, 53], 1494);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 53, 38], 1495);
                step(f, Op::BreakTransform, &[38, 137, 27, 138], 1496);
                step(f, Op::SubF, &[598, 10, 322], 1497);
                step(f, Op::MulF, &[9, 322, 323], 1498);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 53, 65], 1499);
                step(f, Op::Select(ValueType::Float), &[65, 71, 596, 428], 1500);
                step(f, Op::ArrayAt(Elem::Float), &[2, 52, 317], 1501);
                step(f, Op::ClampF, &[317, 596, 598, 425], 1502);
                step(f, Op::MulF, &[425, 609, 426], 1503);
                step(f, Op::SinF, &[426, 427], 1504);
                step(f, Op::MulF, &[427, 427, 429], 1505);
                step(f, Op::MulF, &[428, 429, 430], 1506);
                step(f, Op::AddF, &[70, 430, 431], 1507);
                step(f, Op::FootAvoidance, &[231, 137, 323, 52, 431, 233], 1508);
                step(f, Op::SubV, &[233, 231, 234], 1509);
                step(f, Op::LengthV, &[234, 432], 1510);
                step(f, Op::AddF, &[432, 430, 433], 1511);
                step(f, Op::DivF, &[432, 433, 434], 1512);
                step(f, Op::ScaleV, &[234, 434, 235], 1513);
                step(f, Op::AddV, &[231, 235, 236], 1514);
                step(f, Op::MakeTransform, &[236, 40, 381, 60], 1515);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 52, 60], 1516);
                1516
            }
            1516 => {
                step(f, Op::GreaterF, &[15, 596, 53], 1517);
                step(f, Op::JumpIfFalse, &[53, 1534], 1518)
            }
            1518 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 52, 61], 1519);
                step(f, Op::BreakTransform, &[61, 237, 41, 238], 1520);
                step(f, Op::ArrayAt(Elem::Transform), &[7, 52, 62], 1521);
                step(f, Op::BreakTransform, &[62, 239, 42, 240], 1522);
                step(f, Op::MulF, &[15, 15, 435], 1523);
                step(f, Op::LerpV, &[237, 239, 435, 241], 1524);
                step(f, Op::SubF, &[598, 15, 436], 1525);
                step(f, Op::MulF, &[15, 436, 437], 1526);
                step(f, Op::MulF, &[107, 601, 438], 1527);
                step(f, Op::MulF, &[437, 438, 439], 1528);
                step(f, Op::MakeVector, &[596, 596, 439, 242], 1529);
                step(f, Op::AddV, &[241, 242, 243], 1530);
                step(f, Op::SlerpQ, &[41, 42, 15, 43], 1531);
                step(f, Op::MakeTransform, &[243, 43, 381, 63], 1532);
                step(f, Op::ArraySetAt(Elem::Transform), &[5, 52, 63], 1533);
                step(f, Op::Jump, &[1534], 1534)
            }
            1534 => {
                step(f, Op::ArrayAt(Elem::Float), &[2, 52, 317], 1535);
                step(f, Op::GreaterEqualF, &[317, 598, 51], 1536);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 52, 51], 1537);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 52, 37], 1538);
                step(f, Op::BreakTransform, &[37, 133, 26, 134], 1539);
                step(f, Op::ArrayAt(Elem::Float), &[2, 52, 317], 1540);
                step(f, Op::SubF, &[598, 317, 319], 1541);
                step(f, Op::MulF, &[5, 2, 320], 1542);
                step(f, Op::MulF, &[319, 320, 321], 1543);
                step(f, Op::ScaleV, &[2, 321, 135], 1544);
                step(f, Op::AddV, &[133, 135, 136], 1545);
                step(f, Op::MakeTransform, &[136, 88, 381, 53], 1546);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 52, 53], 1547);
                step(f, Op::Copy(ValueType::Bone), &[0, 17], 1548);
                step(f, Op::Copy(ValueType::Int), &[3, 54], 1549);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 54, 69], 1550);
                step(f, Op::BreakTransform, &[69, 275, 50, 276], 1551);
                step(f, Op::MakeVector, &[596, 596, 43, 285], 1552);
                step(f, Op::AddV, &[275, 285, 286], 1553);
                step(f, Op::GetTransform, &[17, 64, 78, 71], 1554);
                step(f, Op::BreakTransform, &[71, 280, 52, 281], 1555);
                step(f, Op::MakeTransform, &[286, 52, 381, 73], 1556);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 54, 20], 1557);
                step(f, Op::GetTransform, &[20, 64, 78, 72], 1558);
                step(f, Op::BreakTransform, &[72, 282, 53, 283], 1559);
                step(f, Op::SubV, &[282, 280, 284], 1560);
                step(f, Op::AddV, &[286, 284, 287], 1561);
                step(f, Op::FootPivots, &[286, 287, 45, 44, 43, 46, 288, 289, 290], 1562);
                step(f, Op::GetParent, &[17, 18], 1563);
                step(f, Op::GetParent, &[18, 19], 1564);
                step(f, Op::GetTransform, &[19, 64, 79, 70], 1565);
                step(f, Op::BreakTransform, &[70, 277, 51, 278], 1566);
                step(f, Op::SubV, &[275, 277, 279], 1567);
                step(f, Op::DotV, &[279, 384, 484], 1568);
                step(f, Op::RemapF, &[484, 73, 72, 74, 596, 78, 487], 1569);
                step(f, Op::LengthV, &[2, 485], 1570);
                step(f, Op::RemapF, &[485, 596, 80, 596, 598, 78, 486], 1571);
                step(f, Op::MulF, &[487, 486, 488], 1572);
                step(f, Op::QuatFromAxisAngle, &[386, 488, 54], 1573);
                step(f, Op::RotateAroundPoint, &[73, 288, 54, 74], 1574);
                step(f, Op::SubV, &[289, 288, 291], 1575);
                step(f, Op::RotateVector, &[54, 291, 292], 1576);
                step(f, Op::AddV, &[288, 292, 293], 1577);
                step(f, Op::RemapF, &[484, 75, 73, 76, 596, 78, 489], 1578);
                step(f, Op::MulF, &[489, 486, 490], 1579);
                step(f, Op::QuatFromAxisAngle, &[386, 490, 55], 1580);
                step(f, Op::RotateAroundPoint, &[74, 293, 55, 75], 1581);
                step(f, Op::RemapF, &[484, 77, 78, 596, 79, 78, 491], 1582);
                step(f, Op::MulF, &[491, 486, 492], 1583);
                step(f, Op::QuatFromAxisAngle, &[386, 492, 56], 1584);
                step(f, Op::RotateAroundPoint, &[75, 290, 56, 76], 1585);
                step(f, Op::SubF, &[598, 10, 493], 1586);
                step(f, Op::MulF, &[9, 493, 494], 1587);
                step(f, Op::LimitRotationAroundZ, &[50, 494, 81, 57], 1588);
                step(f, Op::RotateAroundPoint, &[76, 275, 57, 77], 1589);
                step(f, Op::ArraySetAt(Elem::Transform), &[6, 54, 77], 1590);
                step(f, Op::JumpIfFalse, &[8, 1647], 1591)
            }
            1591 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 54, 69], 1592);
                step(f, Op::BreakTransform, &[69, 275, 50, 276], 1593);
                step(f, Op::MakeVector, &[596, 596, 43, 285], 1594);
                step(f, Op::AddV, &[275, 285, 286], 1595);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 54, 20], 1596);
                step(f, Op::GetTransform, &[20, 64, 78, 72], 1597);
                step(f, Op::BreakTransform, &[72, 282, 53, 283], 1598);
                step(f, Op::GetTransform, &[17, 64, 78, 71], 1599);
                step(f, Op::BreakTransform, &[71, 280, 52, 281], 1600);
                step(f, Op::SubV, &[282, 280, 284], 1601);
                step(f, Op::AddV, &[286, 284, 287], 1602);
                step(f, Op::FootPivots, &[286, 287, 45, 44, 43, 46, 288, 289, 290], 1603);
                step(f, Op::DrawPoint, &[290, 602, 386], 1604);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 54, 69], 1605);
                step(f, Op::BreakTransform, &[69, 275, 50, 276], 1606);
                step(f, Op::MakeVector, &[596, 596, 43, 285], 1607);
                step(f, Op::AddV, &[275, 285, 286], 1608);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 54, 20], 1609);
                step(f, Op::GetTransform, &[20, 64, 78, 72], 1610);
                step(f, Op::BreakTransform, &[72, 282, 53, 283], 1611);
                step(f, Op::GetTransform, &[17, 64, 78, 71], 1612);
                step(f, Op::BreakTransform, &[71, 280, 52, 281], 1613);
                step(f, Op::SubV, &[282, 280, 284], 1614);
                step(f, Op::AddV, &[286, 284, 287], 1615);
                step(f, Op::FootPivots, &[286, 287, 45, 44, 43, 46, 288, 289, 290], 1616);
                step(f, Op::DrawPoint, &[288, 602, 384], 1617);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 54, 69], 1618);
                step(f, Op::BreakTransform, &[69, 275, 50, 276], 1619);
                step(f, Op::MakeVector, &[596, 596, 43, 285], 1620);
                step(f, Op::AddV, &[275, 285, 286], 1621);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 54, 20], 1622);
                step(f, Op::GetTransform, &[20, 64, 78, 72], 1623);
                step(f, Op::BreakTransform, &[72, 282, 53, 283], 1624);
                step(f, Op::GetTransform, &[17, 64, 78, 71], 1625);
                step(f, Op::BreakTransform, &[71, 280, 52, 281], 1626);
                step(f, Op::SubV, &[282, 280, 284], 1627);
                step(f, Op::AddV, &[286, 284, 287], 1628);
                step(f, Op::FootPivots, &[286, 287, 45, 44, 43, 46, 288, 289, 290], 1629);
                step(f, Op::GetParent, &[17, 18], 1630);
                step(f, Op::GetParent, &[18, 19], 1631);
                step(f, Op::GetTransform, &[19, 64, 79, 70], 1632);
                step(f, Op::BreakTransform, &[70, 277, 51, 278], 1633);
                step(f, Op::SubV, &[275, 277, 279], 1634);
                step(f, Op::DotV, &[279, 384, 484], 1635);
                step(f, Op::RemapF, &[484, 73, 72, 74, 596, 78, 487], 1636);
                step(f, Op::LengthV, &[2, 485], 1637);
                step(f, Op::RemapF, &[485, 596, 80, 596, 598, 78, 486], 1638);
                step(f, Op::MulF, &[487, 486, 488], 1639);
                step(f, Op::QuatFromAxisAngle, &[386, 488, 54], 1640);
                step(f, Op::SubV, &[289, 288, 291], 1641);
                step(f, Op::RotateVector, &[54, 291, 292], 1642);
                step(f, Op::AddV, &[288, 292, 293], 1643);
                step(f, Op::DrawPoint, &[293, 602, 383], 1644);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 54, 69], 1645);
                step(f, Op::DrawTransform, &[69, 608, 597], 1646);
                step(f, Op::Jump, &[1647], 1647)
            }
            1647 => {
                step(f, Op::Jump, &[942], 1648)
            }
            1648 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1649);
                step(f, Op::Copy(ValueType::Int), &[64, 5], 1650);
                1650
            }
            1650 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 5, 1, 6, 7, 1705], 1651)
            }
            1651 => {
                step(f, Op::Copy(ValueType::Bone), &[1, 21], 1652);
                step(f, Op::Copy(ValueType::Int), &[6, 55], 1653);
                step(f, Op::GetParent, &[21, 22], 1654);
                step(f, Op::GetParent, &[22, 23], 1655);
                step(f, Op::GetParent, &[23, 24], 1656);
                step(f, Op::GetTransform, &[24, 64, 79, 78], 1657);
                step(f, Op::BreakTransform, &[78, 294, 58, 295], 1658);
                step(f, Op::LengthV, &[1, 496], 1659);
                step(f, Op::ClavicleOffset, &[7, 496, 86, 89, 497], 1660);
                step(f, Op::MakeVector, &[596, 596, 497, 296], 1661);
                step(f, Op::AddV, &[294, 296, 297], 1662);
                step(f, Op::MakeTransform, &[297, 58, 381, 79], 1663);
                step(f, Op::SetTransform, &[24, 79, 64, 78, 598], 1664);
                step(f, Op::GetParent, &[21, 22], 1665);
                step(f, Op::GetParent, &[22, 23], 1666);
                step(f, Op::GetTransform, &[21, 64, 79, 80], 1667);
                step(f, Op::GetTransform, &[23, 64, 79, 81], 1668);
                step(f, Op::BreakTransform, &[81, 298, 60, 299], 1669);
                step(f, Op::Equals(Elem::Int), &[55, 64, 66], 1670);
                step(f, Op::Select(ValueType::Int), &[66, 65, 64, 56], 1671);
                step(f, Op::ArrayAt(Elem::Float), &[0, 56, 495], 1672);
                step(f, Op::ArmSwingRotation, &[495, 1, 0, 87, 604, 610, 598, 86, 84, 85, 604, 604, 598, 498], 1673);
                step(f, Op::QuatFromAxisAngle, &[386, 498, 59], 1674);
                step(f, Op::RotateAroundPoint, &[80, 298, 59, 82], 1675);
                step(f, Op::BreakTransform, &[82, 300, 61, 301], 1676);
                step(f, Op::LengthV, &[1, 496], 1677);
                step(f, Op::RemapF, &[496, 596, 86, 596, 88, 78, 499], 1678);
                step(f, Op::MakeVector, &[596, 596, 499, 302], 1679);
                step(f, Op::AddV, &[300, 302, 303], 1680);
                step(f, Op::MakeTransform, &[303, 61, 381, 83], 1681);
                step(f, Op::Select(ValueType::Vec3), &[66, 387, 386, 305], 1682);
                step(f, Op::Select(ValueType::Vec3), &[66, 384, 388, 306], 1683);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 55, 304], 1684);
                step(f, Op::TwoBoneIK, &[23, 22, 21, 83, 305, 306, 304, 64, 598, 79, 611, 612, 78, 67, 500], 1685);
                step(f, Op::JumpIfFalse, &[8, 1704], 1686)
            }
            1686 => {
                step(f, Op::GetParent, &[21, 22], 1687);
                step(f, Op::GetParent, &[22, 23], 1688);
                step(f, Op::GetTransform, &[23, 64, 79, 81], 1689);
                step(f, Op::BreakTransform, &[81, 298, 60, 299], 1690);
                step(f, Op::GetTransform, &[21, 64, 79, 80], 1691);
                step(f, Op::Equals(Elem::Int), &[55, 64, 66], 1692);
                step(f, Op::Select(ValueType::Int), &[66, 65, 64, 56], 1693);
                step(f, Op::ArrayAt(Elem::Float), &[0, 56, 495], 1694);
                step(f, Op::ArmSwingRotation, &[495, 1, 0, 87, 604, 610, 598, 86, 84, 85, 604, 604, 598, 498], 1695);
                step(f, Op::QuatFromAxisAngle, &[386, 498, 59], 1696);
                step(f, Op::RotateAroundPoint, &[80, 298, 59, 82], 1697);
                step(f, Op::BreakTransform, &[82, 300, 61, 301], 1698);
                step(f, Op::LengthV, &[1, 496], 1699);
                step(f, Op::RemapF, &[496, 596, 86, 596, 88, 78, 499], 1700);
                step(f, Op::MakeVector, &[596, 596, 499, 302], 1701);
                step(f, Op::AddV, &[300, 302, 303], 1702);
                step(f, Op::DrawLine, &[298, 303, 597, 384], 1703);
                step(f, Op::Jump, &[1704], 1704)
            }
            1704 => {
                step(f, Op::Jump, &[1650], 1705)
            }
            1705 => {
                step(f, Op::Copy(ValueType::Float), &[596, 503], 1706);
                step(f, Op::Copy(ValueType::Float), &[605, 504], 1707);
                step(f, Op::Copy(ValueType::Bool), &[79, 68], 1708);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 10], 1709);
                step(f, Op::Copy(ValueType::Int), &[64, 57], 1710);
                step(f, Op::MakeVector, &[596, 596, 48, 309], 1711);
                1711
            }
            1711 => {
                step(f, Op::ForEachNext(Elem::Transform), &[10, 57, 84, 58, 59, 1724], 1712)
            }
            1712 => {
                step(f, Op::BreakTransform, &[84, 307, 62, 308], 1713);
                step(f, Op::AddV, &[307, 309, 310], 1714);
                step(f, Op::SubV, &[307, 309, 311], 1715);
                step(f, Op::SphereTrace, &[310, 311, 47, 69, 312, 313, 505], 1716);
                step(f, Op::BreakVector, &[312, 506, 507, 508], 1717);
                step(f, Op::LessF, &[508, 504, 70], 1718);
                step(f, Op::And, &[69, 70, 71], 1719);
                step(f, Op::JumpIfFalse, &[71, 1723], 1720)
            }
            1720 => {
                step(f, Op::Copy(ValueType::Float), &[508, 504], 1721);
                step(f, Op::Copy(ValueType::Bool), &[78, 68], 1722);
                step(f, Op::Jump, &[1723], 1723)
            }
            1723 => {
                step(f, Op::Jump, &[1711], 1724)
            }
            1724 => {
                step(f, Op::Select(ValueType::Float), &[68, 504, 596, 509], 1725);
                step(f, Op::ClampF, &[509, 51, 52, 510], 1726);
                step(f, Op::Copy(ValueType::Float), &[510, 503], 1727);
                step(f, Op::Jump, &[1728], 1728)
            }
            1728 => {
                step(f, Op::SubF, &[598, 15, 502], 1729);
                step(f, Op::MulF, &[503, 502, 511], 1730);
                step(f, Op::FloatLerp, &[11, 511, 41, 512], 1731);
                step(f, Op::Select(ValueType::Float), &[1, 511, 512, 513], 1732);
                step(f, Op::Copy(ValueType::Float), &[513, 11], 1733);
                step(f, Op::GetTransform, &[37, 64, 78, 89], 1734);
                step(f, Op::BreakTransform, &[89, 326, 69, 327], 1735);
                step(f, Op::PelvisLean, &[1, 91, 96, 97, 527, 528], 1736);
                step(f, Op::LengthV, &[2, 501], 1737);
                step(f, Op::RemapF, &[501, 596, 91, 596, 90, 78, 514], 1738);
                step(f, Op::MulF, &[7, 613, 515], 1739);
                step(f, Op::SinF, &[515, 516], 1740);
                step(f, Op::MulF, &[514, 516, 517], 1741);
                step(f, Op::MulF, &[517, 502, 518], 1742);
                step(f, Op::AddF, &[518, 11, 519], 1743);
                step(f, Op::MakeVector, &[596, 528, 519, 328], 1744);
                step(f, Op::AddV, &[326, 328, 329], 1745);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 64, 85], 1746);
                step(f, Op::BreakTransform, &[85, 314, 63, 315], 1747);
                step(f, Op::BreakVector, &[314, 529, 530, 531], 1748);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 86], 1749);
                step(f, Op::BreakTransform, &[86, 316, 64, 317], 1750);
                step(f, Op::BreakVector, &[316, 532, 533, 534], 1751);
                step(f, Op::SubF, &[531, 534, 535], 1752);
                step(f, Op::PelvisSideLean, &[535, 98, 99, 536], 1753);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 64, 87], 1754);
                step(f, Op::BreakTransform, &[87, 320, 65, 321], 1755);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 65, 88], 1756);
                step(f, Op::BreakTransform, &[88, 322, 66, 323], 1757);
                step(f, Op::SlerpQ, &[65, 66, 597, 67], 1758);
                step(f, Op::EulerFromQuat, &[67, 64, 324], 1759);
                step(f, Op::BreakVector, &[324, 523, 524, 525], 1760);
                step(f, Op::RemapF, &[501, 92, 91, 596, 93, 78, 521], 1761);
                step(f, Op::SubV, &[314, 316, 318], 1762);
                step(f, Op::RotateVector, &[0, 384, 319], 1763);
                step(f, Op::DotV, &[318, 319, 520], 1764);
                step(f, Op::MulF, &[521, 520, 522], 1765);
                step(f, Op::AddF, &[525, 522, 526], 1766);
                step(f, Op::MakeVector, &[527, 536, 526, 325], 1767);
                step(f, Op::QuatFromEuler, &[325, 64, 68], 1768);
                step(f, Op::MakeTransform, &[329, 68, 381, 90], 1769);
                step(f, Op::SetTransform, &[38, 90, 64, 78, 598], 1770);
                step(f, Op::GetTransform, &[39, 65, 78, 91], 1771);
                step(f, Op::BreakTransform, &[91, 330, 73, 331], 1772);
                step(f, Op::LengthV, &[2, 501], 1773);
                step(f, Op::RemapF, &[501, 92, 91, 596, 93, 78, 521], 1774);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 64, 85], 1775);
                step(f, Op::BreakTransform, &[85, 314, 63, 315], 1776);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 86], 1777);
                step(f, Op::BreakTransform, &[86, 316, 64, 317], 1778);
                step(f, Op::SubV, &[314, 316, 318], 1779);
                step(f, Op::RotateVector, &[0, 384, 319], 1780);
                step(f, Op::DotV, &[318, 319, 520], 1781);
                step(f, Op::MulF, &[521, 520, 522], 1782);
                step(f, Op::QuatFromAxisAngle, &[383, 522, 70], 1783);
                step(f, Op::DivF, &[94, 602, 537], 1784);
                step(f, Op::QuatScale, &[70, 537, 71], 1785);
                step(f, Op::MulQ, &[73, 71, 77], 1786);
                step(f, Op::MakeTransform, &[330, 77, 381, 95], 1787);
                step(f, Op::SetTransform, &[40, 95, 65, 78, 598], 1788);
                step(f, Op::GetTransform, &[41, 65, 78, 92], 1789);
                step(f, Op::BreakTransform, &[92, 332, 74, 333], 1790);
                step(f, Op::LengthV, &[2, 501], 1791);
                step(f, Op::RemapF, &[501, 92, 91, 596, 93, 78, 521], 1792);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 64, 85], 1793);
                step(f, Op::BreakTransform, &[85, 314, 63, 315], 1794);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 86], 1795);
                step(f, Op::BreakTransform, &[86, 316, 64, 317], 1796);
                step(f, Op::SubV, &[314, 316, 318], 1797);
                step(f, Op::RotateVector, &[0, 384, 319], 1798);
                step(f, Op::DotV, &[318, 319, 520], 1799);
                step(f, Op::MulF, &[521, 520, 522], 1800);
                step(f, Op::QuatFromAxisAngle, &[383, 522, 70], 1801);
                step(f, Op::DivF, &[94, 602, 537], 1802);
                step(f, Op::QuatScale, &[70, 537, 71], 1803);
                step(f, Op::MulQ, &[74, 71, 78], 1804);
                step(f, Op::MakeTransform, &[332, 78, 381, 96], 1805);
                step(f, Op::SetTransform, &[42, 96, 65, 78, 598], 1806);
                step(f, Op::GetTransform, &[43, 65, 78, 93], 1807);
                step(f, Op::BreakTransform, &[93, 334, 75, 335], 1808);
                step(f, Op::LengthV, &[2, 501], 1809);
                step(f, Op::RemapF, &[501, 92, 91, 596, 93, 78, 521], 1810);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 64, 85], 1811);
                step(f, Op::BreakTransform, &[85, 314, 63, 315], 1812);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 86], 1813);
                step(f, Op::BreakTransform, &[86, 316, 64, 317], 1814);
                step(f, Op::SubV, &[314, 316, 318], 1815);
                step(f, Op::RotateVector, &[0, 384, 319], 1816);
                step(f, Op::DotV, &[318, 319, 520], 1817);
                step(f, Op::MulF, &[521, 520, 522], 1818);
                step(f, Op::QuatFromAxisAngle, &[383, 522, 70], 1819);
                step(f, Op::DivF, &[94, 602, 537], 1820);
                step(f, Op::QuatScale, &[70, 537, 71], 1821);
                step(f, Op::MulQ, &[75, 71, 79], 1822);
                step(f, Op::MakeTransform, &[334, 79, 381, 97], 1823);
                step(f, Op::SetTransform, &[44, 97, 65, 78, 598], 1824);
                step(f, Op::GetTransform, &[45, 65, 78, 94], 1825);
                step(f, Op::BreakTransform, &[94, 336, 76, 337], 1826);
                step(f, Op::LengthV, &[2, 501], 1827);
                step(f, Op::RemapF, &[501, 92, 91, 596, 93, 78, 521], 1828);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 64, 85], 1829);
                step(f, Op::BreakTransform, &[85, 314, 63, 315], 1830);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 65, 86], 1831);
                step(f, Op::BreakTransform, &[86, 316, 64, 317], 1832);
                step(f, Op::SubV, &[314, 316, 318], 1833);
                step(f, Op::RotateVector, &[0, 384, 319], 1834);
                step(f, Op::DotV, &[318, 319, 520], 1835);
                step(f, Op::MulF, &[521, 520, 522], 1836);
                step(f, Op::QuatFromAxisAngle, &[383, 522, 70], 1837);
                step(f, Op::QuatScale, &[70, 95, 72], 1838);
                step(f, Op::MulQ, &[76, 72, 80], 1839);
                step(f, Op::MakeTransform, &[336, 80, 381, 98], 1840);
                step(f, Op::SetTransform, &[46, 98, 65, 78, 598], 1841);
                step(f, Op::Copy(ValueType::Float), &[596, 538], 1842);
                step(f, Op::Copy(ValueType::Float), &[596, 539], 1843);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1844);
                step(f, Op::Copy(ValueType::Int), &[64, 60], 1845);
                1845
            }
            1845 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 60, 25, 61, 62, 1875], 1846)
            }
            1846 => {
                step(f, Op::GetParent, &[25, 26], 1847);
                step(f, Op::GetParent, &[26, 27], 1848);
                step(f, Op::GetTransform, &[27, 64, 79, 99], 1849);
                step(f, Op::BreakTransform, &[99, 338, 81, 339], 1850);
                step(f, Op::BreakVector, &[338, 540, 541, 542], 1851);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 61, 100], 1852);
                step(f, Op::BreakTransform, &[100, 340, 82, 341], 1853);
                step(f, Op::BreakVector, &[340, 543, 544, 545], 1854);
                step(f, Op::ArrayAt(Elem::Float), &[1, 61, 549], 1855);
                step(f, Op::MulF, &[549, 100, 550], 1856);
                step(f, Op::MulF, &[550, 550, 551], 1857);
                step(f, Op::SubF, &[540, 543, 546], 1858);
                step(f, Op::SubF, &[541, 544, 547], 1859);
                step(f, Op::MakeVector, &[546, 547, 596, 342], 1860);
                step(f, Op::DotV, &[342, 342, 548], 1861);
                step(f, Op::SubF, &[551, 548, 552], 1862);
                step(f, Op::SqrtF, &[552, 553], 1863);
                step(f, Op::AddF, &[545, 553, 554], 1864);
                step(f, Op::SubF, &[542, 554, 555], 1865);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 61, 72], 1866);
                step(f, Op::ArrayAt(Elem::Float), &[2, 61, 556], 1867);
                step(f, Op::RemapF, &[556, 597, 598, 596, 598, 78, 557], 1868);
                step(f, Op::RemapF, &[556, 596, 103, 598, 596, 78, 558], 1869);
                step(f, Op::MaxF, &[557, 558, 559], 1870);
                step(f, Op::Select(ValueType::Float), &[72, 598, 559, 560], 1871);
                step(f, Op::MulF, &[555, 560, 561], 1872);
                step(f, Op::MaxF, &[539, 561, 562], 1873);
                step(f, Op::Copy(ValueType::Float), &[562, 539], 1874);
                step(f, Op::Jump, &[1845], 1875)
            }
            1875 => {
                step(f, Op::ClampF, &[539, 596, 101, 563], 1876);
                step(f, Op::Copy(ValueType::Float), &[563, 538], 1877);
                step(f, Op::Jump, &[1878], 1878)
            }
            1878 => {
                step(f, Op::MakeVector, &[12, 596, 596, 343], 1879);
                step(f, Op::MakeVector, &[538, 596, 596, 344], 1880);
                step(f, Op::MakeVector, &[13, 596, 596, 345], 1881);
                step(f, Op::GreaterF, &[538, 12, 73], 1882);
                step(f, Op::Select(ValueType::Float), &[73, 105, 102, 564], 1883);
                step(f, Op::Copy(ValueType::Vec3), &[343, 346], 1884);
                step(f, Op::Copy(ValueType::Vec3), &[344, 347], 1885);
                step(f, Op::Copy(ValueType::Vec3), &[345, 348], 1886);
                step(f, Op::Copy(ValueType::Float), &[564, 565], 1887);
                step(f, Op::Copy(ValueType::Float), &[42, 566], 1888);
                step(f, Op::Copy(ValueType::Vec3), &[380, 349], 1889);
                step(f, Op::SubV, &[347, 348, 350], 1890);
                step(f, Op::DeltaTime, &[567], 1891);
                step(f, Op::DivF, &[566, 567, 568], 1892);
                step(f, Op::ScaleV, &[350, 568, 351], 1893);
                step(f, Op::AddV, &[347, 351, 352], 1894);
                step(f, Op::AddV, &[348, 351, 353], 1895);
                step(f, Op::SubV, &[346, 353, 354], 1896);
                step(f, Op::FloatLerp, &[596, 598, 565, 569], 1897);
                step(f, Op::SubF, &[598, 569, 570], 1898);
                step(f, Op::ScaleV, &[354, 570, 355], 1899);
                step(f, Op::AddV, &[352, 355, 357], 1900);
                step(f, Op::MulF, &[565, 567, 571], 1901);
                step(f, Op::GreaterF, &[571, 596, 74], 1902);
                step(f, Op::DivF, &[569, 571, 572], 1903);
                step(f, Op::Select(ValueType::Float), &[74, 572, 598, 573], 1904);
                step(f, Op::ScaleV, &[350, 573, 356], 1905);
                step(f, Op::SubV, &[357, 356, 358], 1906);
                step(f, Op::Copy(ValueType::Vec3), &[358, 349], 1907);
                step(f, Op::Jump, &[1908], 1908)
            }
            1908 => {
                step(f, Op::BreakVector, &[349, 574, 575, 576], 1909);
                step(f, Op::Select(ValueType::Float), &[1, 538, 574, 577], 1910);
                step(f, Op::Copy(ValueType::Float), &[577, 12], 1911);
                step(f, Op::Copy(ValueType::Float), &[538, 13], 1912);
                step(f, Op::GetTransform, &[47, 64, 79, 101], 1913);
                step(f, Op::BreakTransform, &[101, 359, 83, 360], 1914);
                step(f, Op::MakeVector, &[596, 596, 12, 361], 1915);
                step(f, Op::SubV, &[359, 361, 362], 1916);
                step(f, Op::MakeTransform, &[362, 83, 381, 102], 1917);
                step(f, Op::SetTransform, &[48, 102, 64, 78, 598], 1918);
                step(f, Op::JumpIfFalse, &[8, 1926], 1919)
            }
            1919 => {
                step(f, Op::GetTransform, &[47, 64, 79, 101], 1920);
                step(f, Op::BreakTransform, &[101, 359, 83, 360], 1921);
                step(f, Op::MakeVector, &[596, 596, 12, 361], 1922);
                step(f, Op::SubV, &[359, 361, 362], 1923);
                step(f, Op::MakeTransform, &[362, 83, 381, 102], 1924);
                step(f, Op::DrawTransform, &[102, 614, 597], 1925);
                step(f, Op::Jump, &[1926], 1926)
            }
            1926 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1927);
                step(f, Op::Copy(ValueType::Int), &[64, 8], 1928);
                1928
            }
            1928 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 8, 2, 9, 10, 1980], 1929)
            }
            1929 => {
                step(f, Op::Copy(ValueType::Bone), &[2, 28], 1930);
                step(f, Op::Copy(ValueType::Int), &[9, 63], 1931);
                step(f, Op::GetParent, &[28, 29], 1932);
                step(f, Op::GetParent, &[29, 30], 1933);
                step(f, Op::GetTransform, &[30, 64, 79, 103], 1934);
                step(f, Op::BreakTransform, &[103, 363, 84, 364], 1935);
                step(f, Op::ArrayAt(Elem::Transform), &[6, 63, 104], 1936);
                step(f, Op::BreakTransform, &[104, 365, 85, 366], 1937);
                step(f, Op::SubV, &[365, 363, 367], 1938);
                step(f, Op::LengthV, &[367, 586], 1939);
                step(f, Op::ArrayAt(Elem::Float), &[1, 63, 578], 1940);
                step(f, Op::MulF, &[578, 108, 579], 1941);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 63, 75], 1942);
                step(f, Op::ArrayAt(Elem::Float), &[2, 63, 580], 1943);
                step(f, Op::ClampF, &[580, 596, 598, 581], 1944);
                step(f, Op::MulF, &[581, 609, 582], 1945);
                step(f, Op::SinF, &[582, 583], 1946);
                step(f, Op::MulF, &[583, 109, 584], 1947);
                step(f, Op::Select(ValueType::Float), &[75, 596, 584, 585], 1948);
                step(f, Op::SubF, &[579, 585, 587], 1949);
                step(f, Op::SubF, &[586, 587, 588], 1950);
                step(f, Op::MaxF, &[588, 596, 589], 1951);
                step(f, Op::MulF, &[589, 589, 590], 1952);
                step(f, Op::AddF, &[589, 585, 591], 1953);
                step(f, Op::DivF, &[590, 591, 592], 1954);
                step(f, Op::SubF, &[586, 592, 593], 1955);
                step(f, Op::DivF, &[593, 586, 594], 1956);
                step(f, Op::ScaleV, &[367, 594, 368], 1957);
                step(f, Op::AddV, &[363, 368, 369], 1958);
                step(f, Op::ClampSpatially, &[369, 363, 596, 579, 370], 1959);
                step(f, Op::MakeTransform, &[370, 85, 381, 105], 1960);
                step(f, Op::Equals(Elem::Int), &[63, 64, 76], 1961);
                step(f, Op::Select(ValueType::Vec3), &[76, 387, 386, 375], 1962);
                step(f, Op::Select(ValueType::Vec3), &[76, 384, 388, 376], 1963);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 63, 106], 1964);
                step(f, Op::BreakTransform, &[106, 371, 86, 372], 1965);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 63, 373], 1966);
                step(f, Op::KneeVector, &[86, 0, 373, 110, 111, 374], 1967);
                step(f, Op::TwoBoneIK, &[30, 29, 28, 105, 375, 376, 374, 64, 598, 79, 611, 612, 78, 77, 595], 1968);
                step(f, Op::JumpIfFalse, &[8, 1979], 1969)
            }
            1969 => {
                step(f, Op::GetParent, &[28, 29], 1970);
                step(f, Op::GetTransform, &[29, 64, 79, 107], 1971);
                step(f, Op::BreakTransform, &[107, 377, 87, 378], 1972);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 63, 106], 1973);
                step(f, Op::BreakTransform, &[106, 371, 86, 372], 1974);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 63, 373], 1975);
                step(f, Op::KneeVector, &[86, 0, 373, 110, 111, 374], 1976);
                step(f, Op::AddV, &[377, 374, 379], 1977);
                step(f, Op::DrawLine, &[377, 379, 597, 389], 1978);
                step(f, Op::Jump, &[1979], 1979)
            }
            1979 => {
                step(f, Op::Jump, &[1928], 1980)
            }
            1980 => {
                step(f, Op::End, &[], 1981)
            }
            _ => return,
        } };
    }
}
