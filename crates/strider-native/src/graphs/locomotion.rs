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
    fingerprint: 0x9c535687a1bc7087,
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
                step(f, Op::LengthV, &[36, 116], 385);
                step(f, Op::GreaterF, &[116, 27, 10], 386);
                step(f, Op::Copy(ValueType::Bool), &[10, 2], 387);
                step(f, Op::MakeRelative, &[13, 12, 17], 388);
                step(f, Op::Select(ValueType::Transform), &[10, 103, 17, 18], 389);
                step(f, Op::Copy(ValueType::Transform), &[18, 2], 390);
                step(f, Op::InverseT, &[13, 15], 391);
                step(f, Op::MulT, &[12, 15, 16], 392);
                step(f, Op::Copy(ValueType::Transform), &[16, 1], 393);
                step(f, Op::TransformVector, &[2, 0, 39], 394);
                step(f, Op::InverseT, &[12, 14], 395);
                step(f, Op::DeltaTime, &[115], 396);
                step(f, Op::DivF, &[539, 115, 117], 397);
                step(f, Op::ScaleV, &[36, 117, 37], 398);
                step(f, Op::TransformVector, &[14, 37, 38], 399);
                step(f, Op::Select(ValueType::Vec3), &[2, 39, 38, 41], 400);
                step(f, Op::VectorLerp, &[39, 41, 28, 537, 42], 401);
                step(f, Op::Copy(ValueType::Vec3), &[42, 0], 402);
                step(f, Op::TransformVector, &[2, 1, 40], 403);
                step(f, Op::TransformVector, &[2, 0, 39], 404);
                step(f, Op::Select(ValueType::Vec3), &[2, 39, 38, 41], 405);
                step(f, Op::VectorLerp, &[40, 41, 29, 537, 43], 406);
                step(f, Op::Copy(ValueType::Vec3), &[43, 1], 407);
                step(f, Op::LengthV, &[41, 118], 408);
                step(f, Op::Copy(ValueType::Float), &[118, 0], 409);
                step(f, Op::JumpIfFalse, &[2, 424], 410)
            }
            410 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 12], 411);
                step(f, Op::Copy(ValueType::Int), &[64, 17], 412);
                412
            }
            412 => {
                step(f, Op::ForEachNext(Elem::Bone), &[12, 17, 13, 18, 19, 422], 413)
            }
            413 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 18, 20], 414);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 18, 20], 415);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 18, 20], 416);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 18, 20], 417);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 18, 20], 418);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 18, 20], 419);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 18, 20], 420);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 18, 20], 421);
                step(f, Op::Jump, &[412], 422)
            }
            422 => {
                step(f, Op::Copy(ValueType::Float), &[537, 10], 423);
                step(f, Op::Jump, &[424], 424)
            }
            424 => {
                step(f, Op::WorldTransform, &[12], 425);
                step(f, Op::Copy(ValueType::Transform), &[12, 0], 426);
                step(f, Op::Copy(ValueType::Bool), &[74, 0], 427);
                step(f, Op::JumpIfFalse, &[8, 434], 428)
            }
            428 => {
                step(f, Op::GetTransform, &[34, 64, 74, 19], 429);
                step(f, Op::BreakTransform, &[19, 44, 9, 45], 430);
                step(f, Op::ScaleV, &[0, 540, 46], 431);
                step(f, Op::AddV, &[44, 46, 47], 432);
                step(f, Op::DrawArrow, &[44, 47, 538, 338], 433);
                step(f, Op::Jump, &[434], 434)
            }
            434 => {
                step(f, Op::Copy(ValueType::Float), &[537, 119], 435);
                step(f, Op::Copy(ValueType::Float), &[539, 120], 436);
                step(f, Op::Copy(ValueType::Float), &[539, 121], 437);
                step(f, Op::Copy(ValueType::Bool), &[75, 11], 438);
                step(f, Op::Copy(ValueType::Bool), &[75, 12], 439);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 6], 440);
                step(f, Op::Copy(ValueType::Int), &[64, 25], 441);
                step(f, Op::MakeVector, &[537, 537, 45, 52], 442);
                442
            }
            442 => {
                step(f, Op::ForEachNext(Elem::Transform), &[6, 25, 21, 26, 27, 453], 443)
            }
            443 => {
                step(f, Op::BreakTransform, &[21, 48, 10, 49], 444);
                step(f, Op::TransformPoint, &[2, 48, 50], 445);
                step(f, Op::LerpV, &[50, 48, 121, 51], 446);
                step(f, Op::AddV, &[51, 52, 53], 447);
                step(f, Op::SubV, &[51, 52, 54], 448);
                step(f, Op::LineTrace, &[53, 54, 13, 55, 56, 122], 449);
                step(f, Op::JumpIfFalse, &[13, 452], 450)
            }
            450 => {
                step(f, Op::Copy(ValueType::Bool), &[74, 12], 451);
                step(f, Op::Jump, &[452], 452)
            }
            452 => {
                step(f, Op::Jump, &[442], 453)
            }
            453 => {
                step(f, Op::Copy(ValueType::Bool), &[12, 11], 454);
                step(f, Op::Jump, &[455], 455)
            }
            455 => {
                step(f, Op::Or, &[11, 7, 14], 456);
                step(f, Op::NotEquals(Elem::Bool), &[14, 5, 15], 457);
                step(f, Op::JumpIfFalse, &[15, 492], 458)
            }
            458 => {
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 459);
                step(f, Op::JumpIfFalse, &[16, 491], 460)
            }
            460 => {
                step(f, Op::Copy(ValueType::Int), &[1, 24], 461);
                step(f, Op::Copy(ValueType::Int), &[64, 20], 462);
                462
            }
            462 => {
                step(f, Op::ForNext, &[20, 24, 22, 490], 463)
            }
            463 => {
                step(f, Op::AddF, &[119, 120, 123], 464);
                step(f, Op::MulF, &[123, 538, 124], 465);
                step(f, Op::Copy(ValueType::Float), &[124, 125], 466);
                step(f, Op::Copy(ValueType::Bool), &[75, 17], 467);
                step(f, Op::Copy(ValueType::Bool), &[75, 18], 468);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[5, 7], 469);
                step(f, Op::Copy(ValueType::Int), &[64, 28], 470);
                step(f, Op::MakeVector, &[537, 537, 45, 61], 471);
                471
            }
            471 => {
                step(f, Op::ForEachNext(Elem::Transform), &[7, 28, 22, 29, 30, 482], 472)
            }
            472 => {
                step(f, Op::BreakTransform, &[22, 57, 11, 58], 473);
                step(f, Op::TransformPoint, &[2, 57, 59], 474);
                step(f, Op::LerpV, &[59, 57, 125, 60], 475);
                step(f, Op::AddV, &[60, 61, 62], 476);
                step(f, Op::SubV, &[60, 61, 63], 477);
                step(f, Op::LineTrace, &[62, 63, 19, 64, 65, 126], 478);
                step(f, Op::JumpIfFalse, &[19, 481], 479)
            }
            479 => {
                step(f, Op::Copy(ValueType::Bool), &[74, 18], 480);
                step(f, Op::Jump, &[481], 481)
            }
            481 => {
                step(f, Op::Jump, &[471], 482)
            }
            482 => {
                step(f, Op::Copy(ValueType::Bool), &[18, 17], 483);
                step(f, Op::Jump, &[484], 484)
            }
            484 => {
                step(f, Op::Equals(Elem::Bool), &[17, 6, 20], 485);
                step(f, Op::JumpIfFalse, &[20, 488], 486)
            }
            486 => {
                step(f, Op::Copy(ValueType::Float), &[124, 119], 487);
                step(f, Op::Jump, &[489], 488)
            }
            488 => {
                step(f, Op::Copy(ValueType::Float), &[124, 120], 489);
                489
            }
            489 => {
                step(f, Op::Jump, &[462], 490)
            }
            490 => {
                step(f, Op::Jump, &[491], 491)
            }
            491 => {
                step(f, Op::Jump, &[492], 492)
            }
            492 => {
                step(f, Op::Select(ValueType::Float), &[5, 541, 539, 132], 493);
                step(f, Op::NotEquals(Elem::Bool), &[11, 6, 16], 494);
                step(f, Op::AddF, &[119, 120, 123], 495);
                step(f, Op::MulF, &[123, 538, 127], 496);
                step(f, Op::Select(ValueType::Float), &[16, 127, 538, 128], 497);
                step(f, Op::Select(ValueType::Float), &[15, 128, 537, 134], 498);
                step(f, Op::MulF, &[132, 134, 136], 499);
                step(f, Op::DeltaTime, &[130], 500);
                step(f, Op::DivF, &[130, 103, 131], 501);
                step(f, Op::MulF, &[136, 131, 137], 502);
                step(f, Op::AddF, &[12, 137, 138], 503);
                step(f, Op::ClampF, &[138, 537, 539, 139], 504);
                step(f, Op::Select(ValueType::Float), &[14, 541, 539, 133], 505);
                step(f, Op::SubF, &[539, 128, 129], 506);
                step(f, Op::Select(ValueType::Float), &[15, 129, 539, 135], 507);
                step(f, Op::MulF, &[133, 135, 140], 508);
                step(f, Op::MulF, &[140, 131, 141], 509);
                step(f, Op::AddF, &[139, 141, 142], 510);
                step(f, Op::ClampF, &[142, 537, 539, 143], 511);
                step(f, Op::MulF, &[143, 143, 144], 512);
                step(f, Op::MulF, &[143, 542, 145], 513);
                step(f, Op::SubF, &[543, 145, 146], 514);
                step(f, Op::MulF, &[144, 146, 147], 515);
                step(f, Op::AddF, &[13, 147, 148], 516);
                step(f, Op::MulF, &[148, 538, 149], 517);
                step(f, Op::SubF, &[539, 149, 150], 518);
                step(f, Op::MulF, &[150, 150, 151], 519);
                step(f, Op::SubF, &[539, 151, 152], 520);
                step(f, Op::Copy(ValueType::Float), &[152, 14], 521);
                step(f, Op::Copy(ValueType::Float), &[147, 13], 522);
                step(f, Op::Copy(ValueType::Float), &[143, 12], 523);
                step(f, Op::GreaterF, &[13, 537, 21], 524);
                step(f, Op::TransformVector, &[2, 3, 66], 525);
                step(f, Op::Select(ValueType::Vec3), &[21, 66, 0, 67], 526);
                step(f, Op::Copy(ValueType::Vec3), &[67, 3], 527);
                step(f, Op::LerpV, &[0, 3, 13, 68], 528);
                step(f, Op::Select(ValueType::Vec3), &[21, 68, 0, 69], 529);
                step(f, Op::Copy(ValueType::Vec3), &[69, 2], 530);
                step(f, Op::Copy(ValueType::Bool), &[14, 5], 531);
                step(f, Op::Copy(ValueType::Bool), &[11, 6], 532);
                step(f, Op::Copy(ValueType::Bool), &[75, 7], 533);
                step(f, Op::Copy(ValueType::Bool), &[75, 23], 534);
                step(f, Op::Copy(ValueType::Bool), &[74, 24], 535);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 536);
                step(f, Op::Copy(ValueType::Int), &[64, 34], 537);
                537
            }
            537 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 34, 25, 35, 36, 543], 538)
            }
            538 => {
                step(f, Op::Not, &[25, 26], 539);
                step(f, Op::JumpIfFalse, &[26, 542], 540)
            }
            540 => {
                step(f, Op::Copy(ValueType::Bool), &[75, 24], 541);
                step(f, Op::Jump, &[542], 542)
            }
            542 => {
                step(f, Op::Jump, &[537], 543)
            }
            543 => {
                step(f, Op::Copy(ValueType::Bool), &[24, 23], 544);
                step(f, Op::Jump, &[545], 545)
            }
            545 => {
                step(f, Op::Copy(ValueType::Bool), &[75, 27], 546);
                step(f, Op::Copy(ValueType::Bool), &[74, 28], 547);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 548);
                step(f, Op::Copy(ValueType::Int), &[64, 37], 549);
                549
            }
            549 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 37, 15, 38, 39, 564], 550)
            }
            550 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 38, 23], 551);
                step(f, Op::BreakTransform, &[23, 70, 12, 71], 552);
                step(f, Op::BreakVector, &[70, 161, 162, 163], 553);
                step(f, Op::MakeVector, &[161, 162, 537, 74], 554);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 38, 24], 555);
                step(f, Op::BreakTransform, &[24, 72, 13, 73], 556);
                step(f, Op::BreakVector, &[72, 164, 165, 166], 557);
                step(f, Op::MakeVector, &[164, 165, 537, 75], 558);
                step(f, Op::DistanceV, &[74, 75, 167], 559);
                step(f, Op::GreaterF, &[167, 23, 29], 560);
                step(f, Op::JumpIfFalse, &[29, 563], 561)
            }
            561 => {
                step(f, Op::Copy(ValueType::Bool), &[75, 28], 562);
                step(f, Op::Jump, &[563], 563)
            }
            563 => {
                step(f, Op::Jump, &[549], 564)
            }
            564 => {
                step(f, Op::Copy(ValueType::Bool), &[28, 27], 565);
                step(f, Op::Jump, &[566], 566)
            }
            566 => {
                step(f, Op::And, &[23, 27, 30], 567);
                step(f, Op::LengthV, &[2, 153], 568);
                step(f, Op::GreaterF, &[153, 21, 22], 569);
                step(f, Op::GreaterF, &[0, 21, 31], 570);
                step(f, Op::Or, &[22, 31, 32], 571);
                step(f, Op::Not, &[32, 33], 572);
                step(f, Op::And, &[30, 33, 38], 573);
                step(f, Op::DeltaTime, &[190], 574);
                step(f, Op::MulF, &[190, 26, 191], 575);
                step(f, Op::AddF, &[6, 191, 192], 576);
                step(f, Op::GreaterF, &[6, 538, 39], 577);
                step(f, Op::AddF, &[25, 538, 188], 578);
                step(f, Op::Select(ValueType::Float), &[39, 188, 25, 189], 579);
                step(f, Op::MinF, &[192, 189, 193], 580);
                step(f, Op::NotEquals(Elem::Bool), &[33, 4, 34], 581);
                step(f, Op::Not, &[30, 35], 582);
                step(f, Op::And, &[34, 35, 36], 583);
                step(f, Op::SubF, &[7, 21, 174], 584);
                step(f, Op::SubF, &[7, 153, 175], 585);
                step(f, Op::DivF, &[174, 175, 176], 586);
                step(f, Op::ClampF, &[176, 537, 539, 177], 587);
                step(f, Op::MulF, &[3, 177, 179], 588);
                step(f, Op::RemapF, &[153, 21, 22, 537, 539, 74, 168], 589);
                step(f, Op::Select(ValueType::Float), &[33, 24, 539, 169], 590);
                step(f, Op::Select(ValueType::Float), &[30, 168, 169, 170], 591);
                step(f, Op::SubF, &[539, 13, 171], 592);
                step(f, Op::MulF, &[170, 171, 172], 593);
                step(f, Op::LerpF, &[15, 36, 9, 156], 594);
                step(f, Op::RemapF, &[153, 18, 19, 16, 17, 74, 154], 595);
                step(f, Op::LerpF, &[154, 35, 9, 155], 596);
                step(f, Op::MaxF, &[153, 20, 157], 597);
                step(f, Op::DivF, &[155, 157, 158], 598);
                step(f, Op::AddF, &[156, 158, 159], 599);
                step(f, Op::DivF, &[172, 159, 173], 600);
                step(f, Op::SubF, &[539, 177, 178], 601);
                step(f, Op::MulF, &[173, 178, 180], 602);
                step(f, Op::AddF, &[179, 180, 181], 603);
                step(f, Op::MulF, &[181, 542, 182], 604);
                step(f, Op::AddF, &[3, 173, 183], 605);
                step(f, Op::Select(ValueType::Float), &[36, 182, 183, 184], 606);
                step(f, Op::DivF, &[542, 184, 185], 607);
                step(f, Op::GreaterF, &[184, 537, 37], 608);
                step(f, Op::CycleStep, &[6, 185, 537, 37, 186, 187], 609);
                step(f, Op::Select(ValueType::Float), &[38, 193, 186, 194], 610);
                step(f, Op::Copy(ValueType::Float), &[194, 6], 611);
                step(f, Op::Copy(ValueType::Float), &[173, 3], 612);
                step(f, Op::Copy(ValueType::Bool), &[22, 3], 613);
                step(f, Op::Copy(ValueType::Float), &[158, 1], 614);
                step(f, Op::Copy(ValueType::Float), &[159, 2], 615);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 616);
                step(f, Op::Copy(ValueType::Int), &[64, 31], 617);
                617
            }
            617 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 31, 14, 32, 33, 720], 618)
            }
            618 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 32, 208], 619);
                step(f, Op::ToFloat, &[32, 195], 620);
                step(f, Op::MulF, &[195, 538, 196], 621);
                step(f, Op::AddF, &[6, 196, 197], 622);
                step(f, Op::FractF, &[197, 198], 623);
                step(f, Op::SubF, &[208, 198, 210], 624);
                step(f, Op::GreaterF, &[210, 538, 40], 625);
                step(f, Op::SubF, &[539, 208, 222], 626);
                step(f, Op::AddF, &[198, 222, 223], 627);
                step(f, Op::DivF, &[198, 223, 224], 628);
                step(f, Op::LengthV, &[2, 153], 629);
                step(f, Op::GreaterF, &[153, 21, 22], 630);
                step(f, Op::GreaterF, &[0, 21, 31], 631);
                step(f, Op::Or, &[22, 31, 32], 632);
                step(f, Op::Not, &[32, 33], 633);
                step(f, Op::NotEquals(Elem::Bool), &[33, 4, 34], 634);
                step(f, Op::Copy(ValueType::Bool), &[75, 23], 635);
                step(f, Op::Copy(ValueType::Bool), &[74, 24], 636);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 637);
                step(f, Op::Copy(ValueType::Int), &[64, 34], 638);
                638
            }
            638 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 34, 25, 35, 36, 644], 639)
            }
            639 => {
                step(f, Op::Not, &[25, 26], 640);
                step(f, Op::JumpIfFalse, &[26, 643], 641)
            }
            641 => {
                step(f, Op::Copy(ValueType::Bool), &[75, 24], 642);
                step(f, Op::Jump, &[643], 643)
            }
            643 => {
                step(f, Op::Jump, &[638], 644)
            }
            644 => {
                step(f, Op::Copy(ValueType::Bool), &[24, 23], 645);
                step(f, Op::Jump, &[646], 646)
            }
            646 => {
                step(f, Op::Copy(ValueType::Bool), &[75, 27], 647);
                step(f, Op::Copy(ValueType::Bool), &[74, 28], 648);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 649);
                step(f, Op::Copy(ValueType::Int), &[64, 37], 650);
                650
            }
            650 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 37, 15, 38, 39, 665], 651)
            }
            651 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 38, 23], 652);
                step(f, Op::BreakTransform, &[23, 70, 12, 71], 653);
                step(f, Op::BreakVector, &[70, 161, 162, 163], 654);
                step(f, Op::MakeVector, &[161, 162, 537, 74], 655);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 38, 24], 656);
                step(f, Op::BreakTransform, &[24, 72, 13, 73], 657);
                step(f, Op::BreakVector, &[72, 164, 165, 166], 658);
                step(f, Op::MakeVector, &[164, 165, 537, 75], 659);
                step(f, Op::DistanceV, &[74, 75, 167], 660);
                step(f, Op::GreaterF, &[167, 23, 29], 661);
                step(f, Op::JumpIfFalse, &[29, 664], 662)
            }
            662 => {
                step(f, Op::Copy(ValueType::Bool), &[75, 28], 663);
                step(f, Op::Jump, &[664], 664)
            }
            664 => {
                step(f, Op::Jump, &[650], 665)
            }
            665 => {
                step(f, Op::Copy(ValueType::Bool), &[28, 27], 666);
                step(f, Op::Jump, &[667], 667)
            }
            667 => {
                step(f, Op::And, &[23, 27, 30], 668);
                step(f, Op::Not, &[30, 35], 669);
                step(f, Op::And, &[34, 35, 36], 670);
                step(f, Op::SubF, &[7, 21, 174], 671);
                step(f, Op::SubF, &[7, 153, 175], 672);
                step(f, Op::DivF, &[174, 175, 176], 673);
                step(f, Op::ClampF, &[176, 537, 539, 177], 674);
                step(f, Op::MulF, &[5, 177, 200], 675);
                step(f, Op::RemapF, &[153, 21, 22, 537, 539, 74, 168], 676);
                step(f, Op::Select(ValueType::Float), &[33, 24, 539, 169], 677);
                step(f, Op::Select(ValueType::Float), &[30, 168, 169, 170], 678);
                step(f, Op::SubF, &[539, 13, 171], 679);
                step(f, Op::MulF, &[170, 171, 172], 680);
                step(f, Op::LerpF, &[15, 36, 9, 156], 681);
                step(f, Op::DivF, &[172, 156, 199], 682);
                step(f, Op::SubF, &[539, 177, 178], 683);
                step(f, Op::MulF, &[199, 178, 201], 684);
                step(f, Op::AddF, &[200, 201, 202], 685);
                step(f, Op::MulF, &[202, 542, 203], 686);
                step(f, Op::AddF, &[5, 199, 204], 687);
                step(f, Op::Select(ValueType::Float), &[36, 203, 204, 205], 688);
                step(f, Op::DeltaTime, &[190], 689);
                step(f, Op::MulF, &[190, 538, 206], 690);
                step(f, Op::MulF, &[205, 206, 207], 691);
                step(f, Op::MulF, &[224, 207, 225], 692);
                step(f, Op::ArrayAt(Elem::Float), &[2, 32, 209], 693);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 32, 41], 694);
                step(f, Op::RemapF, &[153, 18, 19, 16, 17, 74, 154], 695);
                step(f, Op::LerpF, &[154, 35, 9, 155], 696);
                step(f, Op::MaxF, &[153, 20, 157], 697);
                step(f, Op::DivF, &[155, 157, 158], 698);
                step(f, Op::AddF, &[156, 158, 159], 699);
                step(f, Op::DivF, &[156, 159, 160], 700);
                step(f, Op::SubF, &[160, 4, 211], 701);
                step(f, Op::MaxF, &[211, 537, 212], 702);
                step(f, Op::DivF, &[212, 160, 213], 703);
                step(f, Op::MulF, &[213, 209, 214], 704);
                step(f, Op::SubF, &[539, 9, 215], 705);
                step(f, Op::MulF, &[214, 215, 216], 706);
                step(f, Op::MulF, &[216, 171, 217], 707);
                step(f, Op::MulF, &[217, 101, 218], 708);
                step(f, Op::Select(ValueType::Float), &[41, 537, 218, 219], 709);
                step(f, Op::SubF, &[207, 219, 220], 710);
                step(f, Op::AddF, &[209, 220, 221], 711);
                step(f, Op::Select(ValueType::Float), &[40, 225, 221, 226], 712);
                step(f, Op::MinF, &[226, 542, 227], 713);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 32, 227], 714);
                step(f, Op::ToFloat, &[32, 195], 715);
                step(f, Op::MulF, &[195, 538, 196], 716);
                step(f, Op::AddF, &[6, 196, 197], 717);
                step(f, Op::FractF, &[197, 198], 718);
                step(f, Op::ArraySetAt(Elem::Float), &[0, 32, 198], 719);
                step(f, Op::Jump, &[617], 720)
            }
            720 => {
                step(f, Op::LerpF, &[15, 36, 9, 156], 721);
                step(f, Op::LengthV, &[2, 153], 722);
                step(f, Op::RemapF, &[153, 18, 19, 16, 17, 74, 154], 723);
                step(f, Op::LerpF, &[154, 35, 9, 155], 724);
                step(f, Op::MaxF, &[153, 20, 157], 725);
                step(f, Op::DivF, &[155, 157, 158], 726);
                step(f, Op::AddF, &[156, 158, 159], 727);
                step(f, Op::DivF, &[156, 159, 160], 728);
                step(f, Op::Copy(ValueType::Float), &[160, 4], 729);
                step(f, Op::GreaterF, &[153, 21, 22], 730);
                step(f, Op::GreaterF, &[0, 21, 31], 731);
                step(f, Op::Or, &[22, 31, 32], 732);
                step(f, Op::Not, &[32, 33], 733);
                step(f, Op::Copy(ValueType::Bool), &[33, 4], 734);
                step(f, Op::Copy(ValueType::Float), &[153, 7], 735);
                step(f, Op::Copy(ValueType::Bool), &[75, 23], 736);
                step(f, Op::Copy(ValueType::Bool), &[74, 24], 737);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 738);
                step(f, Op::Copy(ValueType::Int), &[64, 34], 739);
                739
            }
            739 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 34, 25, 35, 36, 745], 740)
            }
            740 => {
                step(f, Op::Not, &[25, 26], 741);
                step(f, Op::JumpIfFalse, &[26, 744], 742)
            }
            742 => {
                step(f, Op::Copy(ValueType::Bool), &[75, 24], 743);
                step(f, Op::Jump, &[744], 744)
            }
            744 => {
                step(f, Op::Jump, &[739], 745)
            }
            745 => {
                step(f, Op::Copy(ValueType::Bool), &[24, 23], 746);
                step(f, Op::Jump, &[747], 747)
            }
            747 => {
                step(f, Op::Copy(ValueType::Bool), &[75, 27], 748);
                step(f, Op::Copy(ValueType::Bool), &[74, 28], 749);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 750);
                step(f, Op::Copy(ValueType::Int), &[64, 37], 751);
                751
            }
            751 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 37, 15, 38, 39, 766], 752)
            }
            752 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 38, 23], 753);
                step(f, Op::BreakTransform, &[23, 70, 12, 71], 754);
                step(f, Op::BreakVector, &[70, 161, 162, 163], 755);
                step(f, Op::MakeVector, &[161, 162, 537, 74], 756);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 38, 24], 757);
                step(f, Op::BreakTransform, &[24, 72, 13, 73], 758);
                step(f, Op::BreakVector, &[72, 164, 165, 166], 759);
                step(f, Op::MakeVector, &[164, 165, 537, 75], 760);
                step(f, Op::DistanceV, &[74, 75, 167], 761);
                step(f, Op::GreaterF, &[167, 23, 29], 762);
                step(f, Op::JumpIfFalse, &[29, 765], 763)
            }
            763 => {
                step(f, Op::Copy(ValueType::Bool), &[75, 28], 764);
                step(f, Op::Jump, &[765], 765)
            }
            765 => {
                step(f, Op::Jump, &[751], 766)
            }
            766 => {
                step(f, Op::Copy(ValueType::Bool), &[28, 27], 767);
                step(f, Op::Jump, &[768], 768)
            }
            768 => {
                step(f, Op::And, &[23, 27, 30], 769);
                step(f, Op::RemapF, &[153, 21, 22, 537, 539, 74, 168], 770);
                step(f, Op::Select(ValueType::Float), &[33, 24, 539, 169], 771);
                step(f, Op::Select(ValueType::Float), &[30, 168, 169, 170], 772);
                step(f, Op::SubF, &[539, 13, 171], 773);
                step(f, Op::MulF, &[170, 171, 172], 774);
                step(f, Op::DivF, &[172, 156, 199], 775);
                step(f, Op::Copy(ValueType::Float), &[199, 5], 776);
                step(f, Op::Select(ValueType::Vec3), &[3, 2, 336, 76], 777);
                step(f, Op::MovementAngleOffset, &[76, 8, 6, 30, 31, 544, 32, 545, 228], 778);
                step(f, Op::Copy(ValueType::Float), &[228, 8], 779);
                step(f, Op::QuatFromAxisAngle, &[339, 8, 14], 780);
                step(f, Op::Copy(ValueType::Quat), &[14, 0], 781);
                step(f, Op::SinF, &[8, 229], 782);
                step(f, Op::AbsF, &[229, 230], 783);
                step(f, Op::RemapF, &[230, 33, 34, 537, 539, 74, 231], 784);
                step(f, Op::Copy(ValueType::Float), &[231, 9], 785);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 786);
                step(f, Op::Copy(ValueType::Int), &[64, 2], 787);
                787
            }
            787 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 2, 0, 3, 4, 1403], 788)
            }
            788 => {
                step(f, Op::Copy(ValueType::Bone), &[0, 16], 789);
                step(f, Op::Copy(ValueType::Int), &[3, 40], 790);
                step(f, Op::GetTransform, &[35, 64, 74, 25], 791);
                step(f, Op::BreakTransform, &[25, 79, 15, 80], 792);
                step(f, Op::BreakVector, &[79, 243, 244, 245], 793);
                step(f, Op::SubF, &[539, 9, 241], 794);
                step(f, Op::MulF, &[8, 241, 242], 795);
                step(f, Op::QuatFromAxisAngle, &[339, 242, 17], 796);
                step(f, Op::GetTransform, &[16, 64, 74, 26], 797);
                step(f, Op::BreakTransform, &[26, 81, 16, 82], 798);
                step(f, Op::SubV, &[81, 79, 83], 799);
                step(f, Op::BreakVector, &[83, 238, 239, 240], 800);
                step(f, Op::MakeVector, &[238, 239, 537, 84], 801);
                step(f, Op::RotateVector, &[17, 84, 85], 802);
                step(f, Op::BreakVector, &[85, 246, 247, 248], 803);
                step(f, Op::MulF, &[37, 9, 249], 804);
                step(f, Op::Equals(Elem::Int), &[40, 64, 42], 805);
                step(f, Op::Select(ValueType::Float), &[42, 539, 541, 258], 806);
                step(f, Op::MulF, &[249, 258, 250], 807);
                step(f, Op::AddF, &[246, 250, 251], 808);
                step(f, Op::AddF, &[243, 251, 252], 809);
                step(f, Op::AddF, &[244, 247, 253], 810);
                step(f, Op::BreakVector, &[81, 254, 255, 256], 811);
                step(f, Op::SubF, &[256, 40, 257], 812);
                step(f, Op::MakeVector, &[252, 253, 257, 86], 813);
                step(f, Op::ArrayAt(Elem::Float), &[2, 40, 232], 814);
                step(f, Op::SubF, &[539, 232, 233], 815);
                step(f, Op::MaxF, &[233, 537, 234], 816);
                step(f, Op::MulF, &[4, 2, 235], 817);
                step(f, Op::MulF, &[234, 235, 236], 818);
                step(f, Op::ScaleV, &[2, 236, 77], 819);
                step(f, Op::AddV, &[86, 77, 87], 820);
                step(f, Op::MulF, &[1, 538, 237], 821);
                step(f, Op::ScaleV, &[2, 237, 78], 822);
                step(f, Op::AddV, &[87, 78, 88], 823);
                step(f, Op::RotateVector, &[0, 340, 89], 824);
                step(f, Op::Copy(ValueType::Vec3), &[88, 96], 825);
                step(f, Op::Copy(ValueType::Vec3), &[89, 97], 826);
                step(f, Op::Copy(ValueType::Float), &[258, 268], 827);
                step(f, Op::Copy(ValueType::Vec3), &[336, 98], 828);
                step(f, Op::Copy(ValueType::Vec3), &[336, 99], 829);
                step(f, Op::Copy(ValueType::Bool), &[75, 43], 830);
                step(f, Op::Copy(ValueType::Float), &[546, 269], 831);
                step(f, Op::Copy(ValueType::Vec3), &[336, 100], 832);
                step(f, Op::Copy(ValueType::Vec3), &[339, 101], 833);
                step(f, Op::Copy(ValueType::Bool), &[75, 44], 834);
                step(f, Op::MulI, &[0, 0, 46], 835);
                step(f, Op::Copy(ValueType::Int), &[46, 45], 836);
                step(f, Op::Copy(ValueType::Int), &[64, 41], 837);
                step(f, Op::SubI, &[0, 65, 49], 838);
                step(f, Op::DivI, &[49, 66, 50], 839);
                step(f, Op::MakeVector, &[537, 537, 45, 106], 840);
                step(f, Op::ScaleV, &[97, 47, 111], 841);
                841
            }
            841 => {
                step(f, Op::ForNext, &[41, 45, 43, 881], 842)
            }
            842 => {
                step(f, Op::ModI, &[43, 0, 47], 843);
                step(f, Op::ToFloat, &[47, 270], 844);
                step(f, Op::MulF, &[270, 46, 272], 845);
                step(f, Op::MulF, &[272, 268, 273], 846);
                step(f, Op::MakeVector, &[273, 537, 537, 102], 847);
                step(f, Op::DivI, &[43, 0, 48], 848);
                step(f, Op::SubI, &[48, 50, 51], 849);
                step(f, Op::ToFloat, &[51, 271], 850);
                step(f, Op::MulF, &[271, 46, 274], 851);
                step(f, Op::ScaleV, &[97, 274, 103], 852);
                step(f, Op::AddV, &[102, 103, 104], 853);
                step(f, Op::AddV, &[96, 104, 105], 854);
                step(f, Op::AddV, &[105, 106, 107], 855);
                step(f, Op::SubV, &[105, 106, 108], 856);
                step(f, Op::SphereTrace, &[107, 108, 44, 45, 109, 110, 275], 857);
                step(f, Op::BreakVector, &[109, 277, 278, 279], 858);
                step(f, Op::AddV, &[107, 111, 112], 859);
                step(f, Op::AddV, &[108, 111, 113], 860);
                step(f, Op::SphereTrace, &[112, 113, 44, 46, 114, 115, 276], 861);
                step(f, Op::BreakVector, &[114, 280, 281, 282], 862);
                step(f, Op::SubF, &[279, 282, 283], 863);
                step(f, Op::AbsF, &[283, 284], 864);
                step(f, Op::Select(ValueType::Float), &[45, 537, 539, 285], 865);
                step(f, Op::AddF, &[284, 285, 290], 866);
                step(f, Op::LengthV, &[104, 286], 867);
                step(f, Op::RemapF, &[286, 537, 547, 537, 539, 74, 287], 868);
                step(f, Op::MinF, &[279, 282, 288], 869);
                step(f, Op::RemapF, &[288, 548, 547, 539, 538, 74, 289], 870);
                step(f, Op::AddF, &[287, 289, 291], 871);
                step(f, Op::AddF, &[290, 291, 292], 872);
                step(f, Op::LessF, &[292, 269, 47], 873);
                step(f, Op::And, &[45, 47, 48], 874);
                step(f, Op::JumpIfFalse, &[48, 880], 875)
            }
            875 => {
                step(f, Op::Copy(ValueType::Float), &[292, 269], 876);
                step(f, Op::Copy(ValueType::Vec3), &[109, 100], 877);
                step(f, Op::Copy(ValueType::Vec3), &[110, 101], 878);
                step(f, Op::Copy(ValueType::Bool), &[74, 44], 879);
                step(f, Op::Jump, &[880], 880)
            }
            880 => {
                step(f, Op::Jump, &[841], 881)
            }
            881 => {
                step(f, Op::JumpIfFalse, &[8, 884], 882)
            }
            882 => {
                step(f, Op::DrawSphere, &[100, 44, 340], 883);
                step(f, Op::Jump, &[884], 884)
            }
            884 => {
                step(f, Op::Copy(ValueType::Vec3), &[100, 98], 885);
                step(f, Op::Copy(ValueType::Vec3), &[101, 99], 886);
                step(f, Op::Copy(ValueType::Bool), &[44, 43], 887);
                step(f, Op::Jump, &[888], 888)
            }
            888 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 40, 27], 889);
                step(f, Op::BreakTransform, &[27, 91, 21, 92], 890);
                step(f, Op::ArrayAt(Elem::Float), &[2, 40, 232], 891);
                step(f, Op::SubF, &[539, 232, 233], 892);
                step(f, Op::MaxF, &[233, 537, 234], 893);
                step(f, Op::MulF, &[4, 2, 235], 894);
                step(f, Op::MulF, &[234, 235, 236], 895);
                step(f, Op::ScaleV, &[2, 236, 77], 896);
                step(f, Op::SubV, &[98, 77, 90], 897);
                step(f, Op::Select(ValueType::Vec3), &[43, 90, 91, 93], 898);
                step(f, Op::VectorLerp, &[91, 93, 38, 537, 94], 899);
                step(f, Op::BreakVector, &[94, 264, 265, 266], 900);
                step(f, Op::ClampF, &[266, 48, 49, 267], 901);
                step(f, Op::MakeVector, &[264, 265, 267, 95], 902);
                step(f, Op::RotationFromNormal, &[99, 262, 263, 19], 903);
                step(f, Op::PerFootRotationFactor, &[8, 79, 80, 259], 904);
                step(f, Op::MulF, &[8, 259, 260], 905);
                step(f, Op::SubF, &[539, 9, 241], 906);
                step(f, Op::MulF, &[260, 241, 261], 907);
                step(f, Op::QuatFromAxisAngle, &[339, 261, 18], 908);
                step(f, Op::MulQ, &[19, 18, 20], 909);
                step(f, Op::Select(ValueType::Quat), &[43, 20, 21, 22], 910);
                step(f, Op::MakeTransform, &[95, 22, 337, 28], 911);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 40, 28], 912);
                step(f, Op::JumpIfFalse, &[43, 915], 913)
            }
            913 => {
                step(f, Op::Copy(ValueType::Bool), &[74, 7], 914);
                step(f, Op::Jump, &[915], 915)
            }
            915 => {
                step(f, Op::Copy(ValueType::Int), &[3, 52], 916);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 52, 31], 917);
                step(f, Op::GreaterF, &[13, 537, 52], 918);
                step(f, Op::InterpolateTransform, &[2, 103, 14, 29], 919);
                step(f, Op::Select(ValueType::Transform), &[52, 29, 2, 30], 920);
                step(f, Op::MakeAbsolute, &[31, 30, 32], 921);
                step(f, Op::BreakTransform, &[32, 116, 23, 117], 922);
                step(f, Op::ClampSpatially, &[116, 336, 537, 52, 118], 923);
                step(f, Op::SubF, &[539, 9, 298], 924);
                step(f, Op::MulF, &[8, 298, 294], 925);
                step(f, Op::LimitRotationAroundZ, &[23, 294, 78, 24], 926);
                step(f, Op::MakeTransform, &[118, 24, 337, 33], 927);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 52, 33], 928);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 52, 49], 929);
                step(f, Op::JumpIfFalse, &[49, 983], 930)
            }
            930 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 52, 35], 931);
                step(f, Op::BreakTransform, &[35, 119, 25, 120], 932);
                step(f, Op::ArrayAt(Elem::Float), &[2, 52, 293], 933);
                step(f, Op::SubF, &[539, 293, 295], 934);
                step(f, Op::MulF, &[4, 2, 296], 935);
                step(f, Op::MulF, &[295, 296, 297], 936);
                step(f, Op::ScaleV, &[2, 297, 121], 937);
                step(f, Op::AddV, &[119, 121, 122], 938);
                step(f, Op::MakeTransform, &[122, 25, 337, 42], 939);
                step(f, Op::Copy(ValueType::Transform), &[42, 43], 940);
                step(f, Op::Copy(ValueType::Transform), &[103, 44], 941);
                step(f, Op::BreakTransform, &[43, 150, 30, 151], 942);
                step(f, Op::MakeVector, &[537, 537, 45, 152], 943);
                step(f, Op::AddV, &[150, 152, 153], 944);
                step(f, Op::SubV, &[150, 152, 154], 945);
                step(f, Op::LineTrace, &[153, 154, 56, 155, 156, 325], 946);
                step(f, Op::RotateVector, &[30, 339, 157], 947);
                step(f, Op::FindQuatBetween, &[157, 156, 31], 948);
                step(f, Op::MulQ, &[31, 30, 32], 949);
                step(f, Op::MulF, &[43, 42, 326], 950);
                step(f, Op::AddF, &[326, 51, 327], 951);
                step(f, Op::NegF, &[327, 328], 952);
                step(f, Op::MakeVector, &[537, 328, 537, 158], 953);
                step(f, Op::RotateVector, &[32, 158, 160], 954);
                step(f, Op::AddV, &[155, 160, 162], 955);
                step(f, Op::AddV, &[162, 152, 164], 956);
                step(f, Op::SubV, &[162, 152, 165], 957);
                step(f, Op::LineTrace, &[164, 165, 57, 168, 169, 330], 958);
                step(f, Op::BreakVector, &[168, 332, 333, 334], 959);
                step(f, Op::BreakVector, &[162, 338, 339, 340], 960);
                step(f, Op::SubF, &[334, 340, 344], 961);
                step(f, Op::Select(ValueType::Float), &[57, 344, 537, 346], 962);
                step(f, Op::AddF, &[47, 51, 329], 963);
                step(f, Op::MakeVector, &[537, 329, 537, 159], 964);
                step(f, Op::RotateVector, &[32, 159, 161], 965);
                step(f, Op::AddV, &[155, 161, 163], 966);
                step(f, Op::AddV, &[163, 152, 166], 967);
                step(f, Op::SubV, &[163, 152, 167], 968);
                step(f, Op::LineTrace, &[166, 167, 58, 170, 171, 331], 969);
                step(f, Op::BreakVector, &[170, 335, 336, 337], 970);
                step(f, Op::BreakVector, &[163, 341, 342, 343], 971);
                step(f, Op::SubF, &[337, 343, 345], 972);
                step(f, Op::Select(ValueType::Float), &[58, 345, 537, 347], 973);
                step(f, Op::MaxF, &[346, 347, 348], 974);
                step(f, Op::ClampF, &[348, 537, 50, 349], 975);
                step(f, Op::MakeVector, &[537, 537, 349, 172], 976);
                step(f, Op::AddV, &[155, 172, 173], 977);
                step(f, Op::MakeTransform, &[173, 32, 337, 45], 978);
                step(f, Op::Select(ValueType::Transform), &[56, 45, 43, 46], 979);
                step(f, Op::Copy(ValueType::Transform), &[46, 44], 980);
                step(f, Op::Jump, &[981], 981)
            }
            981 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 52, 44], 982);
                step(f, Op::Jump, &[1045], 983)
            }
            983 => {
                step(f, Op::ArrayAt(Elem::Transform), &[2, 52, 47], 984);
                step(f, Op::GreaterF, &[13, 537, 52], 985);
                step(f, Op::InterpolateTransform, &[2, 103, 14, 29], 986);
                step(f, Op::Select(ValueType::Transform), &[52, 29, 2, 30], 987);
                step(f, Op::MakeAbsolute, &[47, 30, 48], 988);
                step(f, Op::BreakTransform, &[48, 174, 33, 175], 989);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 52, 35], 990);
                step(f, Op::BreakTransform, &[35, 119, 25, 120], 991);
                step(f, Op::ArrayAt(Elem::Float), &[2, 52, 293], 992);
                step(f, Op::SubF, &[539, 293, 295], 993);
                step(f, Op::MulF, &[4, 2, 296], 994);
                step(f, Op::MulF, &[295, 296, 297], 995);
                step(f, Op::ScaleV, &[2, 297, 121], 996);
                step(f, Op::AddV, &[119, 121, 122], 997);
                step(f, Op::ClampF, &[293, 537, 539, 377], 998);
                step(f, Op::SubF, &[539, 377, 350], 999);
                step(f, Op::MulF, &[66, 350, 351], 1000);
                step(f, Op::VectorLerp, &[174, 122, 351, 537, 176], 1001);
                step(f, Op::MakeTransform, &[176, 25, 337, 49], 1002);
                step(f, Op::Copy(ValueType::Transform), &[49, 50], 1003);
                step(f, Op::Copy(ValueType::Transform), &[103, 51], 1004);
                step(f, Op::BreakTransform, &[50, 177, 34, 178], 1005);
                step(f, Op::MakeVector, &[537, 537, 45, 179], 1006);
                step(f, Op::AddV, &[177, 179, 180], 1007);
                step(f, Op::SubV, &[177, 179, 181], 1008);
                step(f, Op::LineTrace, &[180, 181, 59, 182, 183, 352], 1009);
                step(f, Op::RotateVector, &[34, 339, 184], 1010);
                step(f, Op::FindQuatBetween, &[184, 183, 35], 1011);
                step(f, Op::MulQ, &[35, 34, 36], 1012);
                step(f, Op::MulF, &[43, 42, 353], 1013);
                step(f, Op::AddF, &[353, 51, 354], 1014);
                step(f, Op::NegF, &[354, 355], 1015);
                step(f, Op::MakeVector, &[537, 355, 537, 185], 1016);
                step(f, Op::RotateVector, &[36, 185, 187], 1017);
                step(f, Op::AddV, &[182, 187, 189], 1018);
                step(f, Op::AddV, &[189, 179, 191], 1019);
                step(f, Op::SubV, &[189, 179, 192], 1020);
                step(f, Op::LineTrace, &[191, 192, 60, 195, 196, 357], 1021);
                step(f, Op::BreakVector, &[195, 359, 360, 361], 1022);
                step(f, Op::BreakVector, &[189, 365, 366, 367], 1023);
                step(f, Op::SubF, &[361, 367, 371], 1024);
                step(f, Op::Select(ValueType::Float), &[60, 371, 537, 373], 1025);
                step(f, Op::AddF, &[47, 51, 356], 1026);
                step(f, Op::MakeVector, &[537, 356, 537, 186], 1027);
                step(f, Op::RotateVector, &[36, 186, 188], 1028);
                step(f, Op::AddV, &[182, 188, 190], 1029);
                step(f, Op::AddV, &[190, 179, 193], 1030);
                step(f, Op::SubV, &[190, 179, 194], 1031);
                step(f, Op::LineTrace, &[193, 194, 61, 197, 198, 358], 1032);
                step(f, Op::BreakVector, &[197, 362, 363, 364], 1033);
                step(f, Op::BreakVector, &[190, 368, 369, 370], 1034);
                step(f, Op::SubF, &[364, 370, 372], 1035);
                step(f, Op::Select(ValueType::Float), &[61, 372, 537, 374], 1036);
                step(f, Op::MaxF, &[373, 374, 375], 1037);
                step(f, Op::ClampF, &[375, 537, 50, 376], 1038);
                step(f, Op::MakeVector, &[537, 537, 376, 199], 1039);
                step(f, Op::AddV, &[182, 199, 200], 1040);
                step(f, Op::MakeTransform, &[200, 36, 337, 52], 1041);
                step(f, Op::Select(ValueType::Transform), &[59, 52, 50, 53], 1042);
                step(f, Op::Copy(ValueType::Transform), &[53, 51], 1043);
                step(f, Op::Jump, &[1044], 1044)
            }
            1044 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 52, 51], 1045);
                1045
            }
            1045 => {
                step(f, Op::ArrayAt(Elem::Float), &[2, 52, 293], 1046);
                step(f, Op::GreaterEqualF, &[293, 539, 50], 1047);
                step(f, Op::JumpIfFalse, &[50, 1107], 1048)
            }
            1048 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 52, 49], 1049);
                step(f, Op::JumpIfFalse, &[49, 1051], 1050)
            }
            1050 => {
                step(f, Op::Jump, &[1104], 1051)
            }
            1051 => {
                step(f, Op::ArrayAt(Elem::Transform), &[2, 52, 54], 1052);
                step(f, Op::BreakTransform, &[54, 201, 37, 202], 1053);
                step(f, Op::Equals(Elem::Int), &[52, 64, 51], 1054);
                step(f, Op::Select(ValueType::Int), &[51, 65, 64, 53], 1055);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 53, 36], 1056);
                step(f, Op::BreakTransform, &[36, 123, 26, 124], 1057);
                step(f, Op::SubF, &[539, 9, 298], 1058);
                step(f, Op::MulF, &[8, 298, 299], 1059);
                step(f, Op::FootAvoidance, &[201, 123, 299, 51, 67, 125], 1060);
                step(f, Op::MakeTransform, &[125, 37, 337, 37], 1061);
                step(f, Op::Copy(ValueType::Transform), &[37, 38], 1062);
                step(f, Op::Copy(ValueType::Transform), &[103, 39], 1063);
                step(f, Op::BreakTransform, &[38, 126, 27, 127], 1064);
                step(f, Op::MakeVector, &[537, 537, 45, 128], 1065);
                step(f, Op::AddV, &[126, 128, 129], 1066);
                step(f, Op::SubV, &[126, 128, 130], 1067);
                step(f, Op::LineTrace, &[129, 130, 53, 131, 132, 300], 1068);
                step(f, Op::RotateVector, &[27, 339, 133], 1069);
                step(f, Op::FindQuatBetween, &[133, 132, 28], 1070);
                step(f, Op::MulQ, &[28, 27, 29], 1071);
                step(f, Op::MulF, &[43, 42, 301], 1072);
                step(f, Op::AddF, &[301, 51, 302], 1073);
                step(f, Op::NegF, &[302, 303], 1074);
                step(f, Op::MakeVector, &[537, 303, 537, 134], 1075);
                step(f, Op::RotateVector, &[29, 134, 136], 1076);
                step(f, Op::AddV, &[131, 136, 138], 1077);
                step(f, Op::AddV, &[138, 128, 140], 1078);
                step(f, Op::SubV, &[138, 128, 141], 1079);
                step(f, Op::LineTrace, &[140, 141, 54, 144, 145, 305], 1080);
                step(f, Op::BreakVector, &[144, 307, 308, 309], 1081);
                step(f, Op::BreakVector, &[138, 313, 314, 315], 1082);
                step(f, Op::SubF, &[309, 315, 319], 1083);
                step(f, Op::Select(ValueType::Float), &[54, 319, 537, 321], 1084);
                step(f, Op::AddF, &[47, 51, 304], 1085);
                step(f, Op::MakeVector, &[537, 304, 537, 135], 1086);
                step(f, Op::RotateVector, &[29, 135, 137], 1087);
                step(f, Op::AddV, &[131, 137, 139], 1088);
                step(f, Op::AddV, &[139, 128, 142], 1089);
                step(f, Op::SubV, &[139, 128, 143], 1090);
                step(f, Op::LineTrace, &[142, 143, 55, 146, 147, 306], 1091);
                step(f, Op::BreakVector, &[146, 310, 311, 312], 1092);
                step(f, Op::BreakVector, &[139, 316, 317, 318], 1093);
                step(f, Op::SubF, &[312, 318, 320], 1094);
                step(f, Op::Select(ValueType::Float), &[55, 320, 537, 322], 1095);
                step(f, Op::MaxF, &[321, 322, 323], 1096);
                step(f, Op::ClampF, &[323, 537, 50, 324], 1097);
                step(f, Op::MakeVector, &[537, 537, 324, 148], 1098);
                step(f, Op::AddV, &[131, 148, 149], 1099);
                step(f, Op::MakeTransform, &[149, 29, 337, 40], 1100);
                step(f, Op::Select(ValueType::Transform), &[53, 40, 38, 41], 1101);
                step(f, Op::Copy(ValueType::Transform), &[41, 39], 1102);
                step(f, Op::Jump, &[1103], 1103)
            }
            1103 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 52, 39], 1104);
                1104
            }
            1104 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 52, 34], 1105);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 52, 34], 1106);
                step(f, Op::Jump, &[1281], 1107)
            }
            1107 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 52, 34], 1108);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 52, 54], 1109);
                step(f, Op::ClampF, &[293, 537, 539, 377], 1110);
                step(f, Op::Copy(ValueType::Transform), &[34, 59], 1111);
                step(f, Op::Copy(ValueType::Transform), &[54, 60], 1112);
                step(f, Op::Copy(ValueType::Float), &[377, 392], 1113);
                step(f, Op::Copy(ValueType::Transform), &[103, 61], 1114);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[3, 2], 1115);
                step(f, Op::ArrayReset(Elem::Vec3), &[2], 1116);
                step(f, Op::BreakTransform, &[59, 217, 42, 218], 1117);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 217], 1118);
                step(f, Op::BreakTransform, &[59, 217, 42, 218], 1119);
                step(f, Op::UnitV, &[2, 216], 1120);
                step(f, Op::LengthV, &[2, 393], 1121);
                step(f, Op::RemapF, &[393, 537, 53, 537, 54, 74, 394], 1122);
                step(f, Op::ScaleV, &[216, 394, 221], 1123);
                step(f, Op::SubV, &[217, 221, 227], 1124);
                step(f, Op::MakeVector, &[537, 537, 56, 225], 1125);
                step(f, Op::AddV, &[227, 225, 229], 1126);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 229], 1127);
                step(f, Op::BreakTransform, &[59, 217, 42, 218], 1128);
                step(f, Op::UnitV, &[2, 216], 1129);
                step(f, Op::LengthV, &[2, 393], 1130);
                step(f, Op::RemapF, &[393, 537, 53, 537, 54, 74, 394], 1131);
                step(f, Op::ScaleV, &[216, 394, 221], 1132);
                step(f, Op::SubV, &[217, 221, 227], 1133);
                step(f, Op::MakeVector, &[537, 537, 56, 225], 1134);
                step(f, Op::AddV, &[227, 225, 229], 1135);
                step(f, Op::RemapF, &[393, 537, 53, 537, 58, 74, 396], 1136);
                step(f, Op::MakeVector, &[537, 537, 396, 223], 1137);
                step(f, Op::AddV, &[229, 223, 233], 1138);
                step(f, Op::BreakTransform, &[60, 219, 43, 220], 1139);
                step(f, Op::BreakVector, &[219, 401, 402, 403], 1140);
                step(f, Op::BreakVector, &[217, 398, 399, 400], 1141);
                step(f, Op::SubF, &[403, 400, 404], 1142);
                step(f, Op::MaxF, &[404, 537, 406], 1143);
                step(f, Op::MulF, &[406, 60, 410], 1144);
                step(f, Op::AbsF, &[404, 408], 1145);
                step(f, Op::RemapF, &[408, 537, 63, 537, 62, 74, 409], 1146);
                step(f, Op::AddF, &[410, 409, 412], 1147);
                step(f, Op::MakeVector, &[537, 537, 412, 231], 1148);
                step(f, Op::AddV, &[233, 231, 235], 1149);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 235], 1150);
                step(f, Op::BreakTransform, &[59, 217, 42, 218], 1151);
                step(f, Op::UnitV, &[2, 216], 1152);
                step(f, Op::LengthV, &[2, 393], 1153);
                step(f, Op::RemapF, &[393, 537, 53, 537, 54, 74, 394], 1154);
                step(f, Op::ScaleV, &[216, 394, 221], 1155);
                step(f, Op::SubV, &[217, 221, 227], 1156);
                step(f, Op::MakeVector, &[537, 537, 56, 225], 1157);
                step(f, Op::AddV, &[227, 225, 229], 1158);
                step(f, Op::RemapF, &[393, 537, 53, 537, 58, 74, 396], 1159);
                step(f, Op::MakeVector, &[537, 537, 396, 223], 1160);
                step(f, Op::AddV, &[229, 223, 233], 1161);
                step(f, Op::BreakTransform, &[60, 219, 43, 220], 1162);
                step(f, Op::BreakVector, &[219, 401, 402, 403], 1163);
                step(f, Op::BreakVector, &[217, 398, 399, 400], 1164);
                step(f, Op::SubF, &[403, 400, 404], 1165);
                step(f, Op::MaxF, &[404, 537, 406], 1166);
                step(f, Op::MulF, &[406, 60, 410], 1167);
                step(f, Op::AbsF, &[404, 408], 1168);
                step(f, Op::RemapF, &[408, 537, 63, 537, 62, 74, 409], 1169);
                step(f, Op::AddF, &[410, 409, 412], 1170);
                step(f, Op::MakeVector, &[537, 537, 412, 231], 1171);
                step(f, Op::AddV, &[233, 231, 235], 1172);
                step(f, Op::RemapF, &[393, 537, 53, 537, 55, 74, 395], 1173);
                step(f, Op::ScaleV, &[216, 395, 222], 1174);
                step(f, Op::AddV, &[219, 222, 228], 1175);
                step(f, Op::MakeVector, &[537, 537, 57, 226], 1176);
                step(f, Op::AddV, &[228, 226, 230], 1177);
                step(f, Op::RemapF, &[393, 537, 53, 537, 59, 74, 397], 1178);
                step(f, Op::MakeVector, &[537, 537, 397, 224], 1179);
                step(f, Op::AddV, &[230, 224, 234], 1180);
                step(f, Op::NegF, &[404, 405], 1181);
                step(f, Op::MaxF, &[405, 537, 407], 1182);
                step(f, Op::MulF, &[407, 61, 411], 1183);
                step(f, Op::AddF, &[411, 409, 413], 1184);
                step(f, Op::MakeVector, &[537, 537, 413, 232], 1185);
                step(f, Op::AddV, &[234, 232, 236], 1186);
                step(f, Op::LerpV, &[235, 236, 538, 237], 1187);
                step(f, Op::GetTransform, &[36, 64, 74, 62], 1188);
                step(f, Op::BreakTransform, &[62, 238, 44, 239], 1189);
                step(f, Op::BreakVector, &[238, 423, 424, 425], 1190);
                step(f, Op::SubF, &[539, 9, 417], 1191);
                step(f, Op::MulF, &[64, 417, 418], 1192);
                step(f, Op::MulF, &[8, 418, 419], 1193);
                step(f, Op::QuatFromAxisAngle, &[339, 419, 45], 1194);
                step(f, Op::SubV, &[237, 238, 240], 1195);
                step(f, Op::BreakVector, &[240, 414, 415, 416], 1196);
                step(f, Op::MakeVector, &[414, 415, 537, 241], 1197);
                step(f, Op::RotateVector, &[45, 241, 242], 1198);
                step(f, Op::BreakVector, &[242, 420, 421, 422], 1199);
                step(f, Op::AddF, &[423, 420, 429], 1200);
                step(f, Op::AddF, &[424, 421, 430], 1201);
                step(f, Op::BreakVector, &[237, 426, 427, 428], 1202);
                step(f, Op::MakeVector, &[429, 430, 428, 243], 1203);
                step(f, Op::DistanceV, &[217, 219, 431], 1204);
                step(f, Op::RemapF, &[431, 542, 549, 537, 539, 74, 432], 1205);
                step(f, Op::LerpV, &[237, 243, 432, 244], 1206);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 244], 1207);
                step(f, Op::BreakTransform, &[60, 219, 43, 220], 1208);
                step(f, Op::UnitV, &[2, 216], 1209);
                step(f, Op::LengthV, &[2, 393], 1210);
                step(f, Op::RemapF, &[393, 537, 53, 537, 55, 74, 395], 1211);
                step(f, Op::ScaleV, &[216, 395, 222], 1212);
                step(f, Op::AddV, &[219, 222, 228], 1213);
                step(f, Op::MakeVector, &[537, 537, 57, 226], 1214);
                step(f, Op::AddV, &[228, 226, 230], 1215);
                step(f, Op::RemapF, &[393, 537, 53, 537, 59, 74, 397], 1216);
                step(f, Op::MakeVector, &[537, 537, 397, 224], 1217);
                step(f, Op::AddV, &[230, 224, 234], 1218);
                step(f, Op::BreakVector, &[219, 401, 402, 403], 1219);
                step(f, Op::BreakTransform, &[59, 217, 42, 218], 1220);
                step(f, Op::BreakVector, &[217, 398, 399, 400], 1221);
                step(f, Op::SubF, &[403, 400, 404], 1222);
                step(f, Op::NegF, &[404, 405], 1223);
                step(f, Op::MaxF, &[405, 537, 407], 1224);
                step(f, Op::MulF, &[407, 61, 411], 1225);
                step(f, Op::AbsF, &[404, 408], 1226);
                step(f, Op::RemapF, &[408, 537, 63, 537, 62, 74, 409], 1227);
                step(f, Op::AddF, &[411, 409, 413], 1228);
                step(f, Op::MakeVector, &[537, 537, 413, 232], 1229);
                step(f, Op::AddV, &[234, 232, 236], 1230);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 236], 1231);
                step(f, Op::BreakTransform, &[60, 219, 43, 220], 1232);
                step(f, Op::UnitV, &[2, 216], 1233);
                step(f, Op::LengthV, &[2, 393], 1234);
                step(f, Op::RemapF, &[393, 537, 53, 537, 55, 74, 395], 1235);
                step(f, Op::ScaleV, &[216, 395, 222], 1236);
                step(f, Op::AddV, &[219, 222, 228], 1237);
                step(f, Op::MakeVector, &[537, 537, 57, 226], 1238);
                step(f, Op::AddV, &[228, 226, 230], 1239);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 230], 1240);
                step(f, Op::BreakTransform, &[60, 219, 43, 220], 1241);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 219], 1242);
                step(f, Op::JumpIfFalse, &[8, 1245], 1243)
            }
            1243 => {
                step(f, Op::DrawSpline, &[2, 64, 67, 538, 341], 1244);
                step(f, Op::Jump, &[1245], 1245)
            }
            1245 => {
                step(f, Op::Spline, &[2, 392, 64, 245, 246], 1246);
                step(f, Op::BreakTransform, &[59, 217, 42, 218], 1247);
                step(f, Op::BreakTransform, &[60, 219, 43, 220], 1248);
                step(f, Op::SlerpQ, &[42, 43, 392, 46], 1249);
                step(f, Op::MulF, &[392, 550, 433], 1250);
                step(f, Op::SinF, &[433, 434], 1251);
                step(f, Op::MulF, &[434, 65, 435], 1252);
                step(f, Op::SlerpQ, &[46, 86, 435, 47], 1253);
                step(f, Op::MakeTransform, &[245, 47, 337, 63], 1254);
                step(f, Op::Copy(ValueType::Transform), &[63, 61], 1255);
                step(f, Op::Jump, &[1256], 1256)
            }
            1256 => {
                step(f, Op::BreakTransform, &[61, 203, 38, 204], 1257);
                step(f, Op::Equals(Elem::Int), &[52, 64, 51], 1258);
                step(f, Op::Select(ValueType::Int), &[51, 65, 64, 53], 1259);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 53, 36], 1260);
                step(f, Op::BreakTransform, &[36, 123, 26, 124], 1261);
                step(f, Op::SubF, &[539, 9, 298], 1262);
                step(f, Op::MulF, &[8, 298, 299], 1263);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 53, 62], 1264);
                step(f, Op::Select(ValueType::Float), &[62, 68, 537, 380], 1265);
                step(f, Op::ArrayAt(Elem::Float), &[2, 52, 293], 1266);
                step(f, Op::ClampF, &[293, 537, 539, 377], 1267);
                step(f, Op::MulF, &[377, 550, 378], 1268);
                step(f, Op::SinF, &[378, 379], 1269);
                step(f, Op::MulF, &[379, 379, 381], 1270);
                step(f, Op::MulF, &[380, 381, 382], 1271);
                step(f, Op::AddF, &[67, 382, 383], 1272);
                step(f, Op::FootAvoidance, &[203, 123, 299, 51, 383, 205], 1273);
                step(f, Op::SubV, &[205, 203, 206], 1274);
                step(f, Op::LengthV, &[206, 384], 1275);
                step(f, Op::AddF, &[384, 382, 385], 1276);
                step(f, Op::DivF, &[384, 385, 386], 1277);
                step(f, Op::ScaleV, &[206, 386, 207], 1278);
                step(f, Op::AddV, &[203, 207, 208], 1279);
                step(f, Op::MakeTransform, &[208, 38, 337, 55], 1280);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 52, 55], 1281);
                1281
            }
            1281 => {
                step(f, Op::GreaterF, &[13, 537, 52], 1282);
                step(f, Op::JumpIfFalse, &[52, 1299], 1283)
            }
            1283 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 52, 56], 1284);
                step(f, Op::BreakTransform, &[56, 209, 39, 210], 1285);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 52, 57], 1286);
                step(f, Op::BreakTransform, &[57, 211, 40, 212], 1287);
                step(f, Op::MulF, &[13, 13, 387], 1288);
                step(f, Op::LerpV, &[209, 211, 387, 213], 1289);
                step(f, Op::SubF, &[539, 13, 388], 1290);
                step(f, Op::MulF, &[13, 388, 389], 1291);
                step(f, Op::MulF, &[104, 542, 390], 1292);
                step(f, Op::MulF, &[389, 390, 391], 1293);
                step(f, Op::MakeVector, &[537, 537, 391, 214], 1294);
                step(f, Op::AddV, &[213, 214, 215], 1295);
                step(f, Op::SlerpQ, &[39, 40, 13, 41], 1296);
                step(f, Op::MakeTransform, &[215, 41, 337, 58], 1297);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 52, 58], 1298);
                step(f, Op::Jump, &[1299], 1299)
            }
            1299 => {
                step(f, Op::ArrayAt(Elem::Float), &[2, 52, 293], 1300);
                step(f, Op::GreaterEqualF, &[293, 539, 50], 1301);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 52, 50], 1302);
                step(f, Op::Copy(ValueType::Bone), &[0, 17], 1303);
                step(f, Op::Copy(ValueType::Int), &[3, 54], 1304);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 54, 64], 1305);
                step(f, Op::BreakTransform, &[64, 247, 48, 248], 1306);
                step(f, Op::MakeVector, &[537, 537, 40, 257], 1307);
                step(f, Op::AddV, &[247, 257, 258], 1308);
                step(f, Op::GetTransform, &[17, 64, 74, 66], 1309);
                step(f, Op::BreakTransform, &[66, 252, 50, 253], 1310);
                step(f, Op::MakeTransform, &[258, 50, 337, 68], 1311);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 54, 20], 1312);
                step(f, Op::GetTransform, &[20, 64, 74, 67], 1313);
                step(f, Op::BreakTransform, &[67, 254, 51, 255], 1314);
                step(f, Op::SubV, &[254, 252, 256], 1315);
                step(f, Op::AddV, &[258, 256, 259], 1316);
                step(f, Op::FootPivots, &[258, 259, 42, 41, 40, 43, 260, 261, 262], 1317);
                step(f, Op::GetParent, &[17, 18], 1318);
                step(f, Op::GetParent, &[18, 19], 1319);
                step(f, Op::GetTransform, &[19, 64, 75, 65], 1320);
                step(f, Op::BreakTransform, &[65, 249, 49, 250], 1321);
                step(f, Op::SubV, &[247, 249, 251], 1322);
                step(f, Op::DotV, &[251, 340, 436], 1323);
                step(f, Op::RemapF, &[436, 70, 69, 71, 537, 74, 439], 1324);
                step(f, Op::LengthV, &[2, 437], 1325);
                step(f, Op::RemapF, &[437, 537, 77, 537, 539, 74, 438], 1326);
                step(f, Op::MulF, &[439, 438, 440], 1327);
                step(f, Op::QuatFromAxisAngle, &[342, 440, 52], 1328);
                step(f, Op::RotateAroundPoint, &[68, 260, 52, 69], 1329);
                step(f, Op::SubV, &[261, 260, 263], 1330);
                step(f, Op::RotateVector, &[52, 263, 264], 1331);
                step(f, Op::AddV, &[260, 264, 265], 1332);
                step(f, Op::RemapF, &[436, 72, 70, 73, 537, 74, 441], 1333);
                step(f, Op::MulF, &[441, 438, 442], 1334);
                step(f, Op::QuatFromAxisAngle, &[342, 442, 53], 1335);
                step(f, Op::RotateAroundPoint, &[69, 265, 53, 70], 1336);
                step(f, Op::RemapF, &[436, 74, 75, 537, 76, 74, 443], 1337);
                step(f, Op::MulF, &[443, 438, 444], 1338);
                step(f, Op::QuatFromAxisAngle, &[342, 444, 54], 1339);
                step(f, Op::RotateAroundPoint, &[70, 262, 54, 71], 1340);
                step(f, Op::SubF, &[539, 9, 445], 1341);
                step(f, Op::MulF, &[8, 445, 446], 1342);
                step(f, Op::LimitRotationAroundZ, &[48, 446, 78, 55], 1343);
                step(f, Op::RotateAroundPoint, &[71, 247, 55, 72], 1344);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 54, 72], 1345);
                step(f, Op::JumpIfFalse, &[8, 1402], 1346)
            }
            1346 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 54, 64], 1347);
                step(f, Op::BreakTransform, &[64, 247, 48, 248], 1348);
                step(f, Op::MakeVector, &[537, 537, 40, 257], 1349);
                step(f, Op::AddV, &[247, 257, 258], 1350);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 54, 20], 1351);
                step(f, Op::GetTransform, &[20, 64, 74, 67], 1352);
                step(f, Op::BreakTransform, &[67, 254, 51, 255], 1353);
                step(f, Op::GetTransform, &[17, 64, 74, 66], 1354);
                step(f, Op::BreakTransform, &[66, 252, 50, 253], 1355);
                step(f, Op::SubV, &[254, 252, 256], 1356);
                step(f, Op::AddV, &[258, 256, 259], 1357);
                step(f, Op::FootPivots, &[258, 259, 42, 41, 40, 43, 260, 261, 262], 1358);
                step(f, Op::DrawPoint, &[262, 543, 342], 1359);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 54, 64], 1360);
                step(f, Op::BreakTransform, &[64, 247, 48, 248], 1361);
                step(f, Op::MakeVector, &[537, 537, 40, 257], 1362);
                step(f, Op::AddV, &[247, 257, 258], 1363);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 54, 20], 1364);
                step(f, Op::GetTransform, &[20, 64, 74, 67], 1365);
                step(f, Op::BreakTransform, &[67, 254, 51, 255], 1366);
                step(f, Op::GetTransform, &[17, 64, 74, 66], 1367);
                step(f, Op::BreakTransform, &[66, 252, 50, 253], 1368);
                step(f, Op::SubV, &[254, 252, 256], 1369);
                step(f, Op::AddV, &[258, 256, 259], 1370);
                step(f, Op::FootPivots, &[258, 259, 42, 41, 40, 43, 260, 261, 262], 1371);
                step(f, Op::DrawPoint, &[260, 543, 340], 1372);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 54, 64], 1373);
                step(f, Op::BreakTransform, &[64, 247, 48, 248], 1374);
                step(f, Op::MakeVector, &[537, 537, 40, 257], 1375);
                step(f, Op::AddV, &[247, 257, 258], 1376);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 54, 20], 1377);
                step(f, Op::GetTransform, &[20, 64, 74, 67], 1378);
                step(f, Op::BreakTransform, &[67, 254, 51, 255], 1379);
                step(f, Op::GetTransform, &[17, 64, 74, 66], 1380);
                step(f, Op::BreakTransform, &[66, 252, 50, 253], 1381);
                step(f, Op::SubV, &[254, 252, 256], 1382);
                step(f, Op::AddV, &[258, 256, 259], 1383);
                step(f, Op::FootPivots, &[258, 259, 42, 41, 40, 43, 260, 261, 262], 1384);
                step(f, Op::GetParent, &[17, 18], 1385);
                step(f, Op::GetParent, &[18, 19], 1386);
                step(f, Op::GetTransform, &[19, 64, 75, 65], 1387);
                step(f, Op::BreakTransform, &[65, 249, 49, 250], 1388);
                step(f, Op::SubV, &[247, 249, 251], 1389);
                step(f, Op::DotV, &[251, 340, 436], 1390);
                step(f, Op::RemapF, &[436, 70, 69, 71, 537, 74, 439], 1391);
                step(f, Op::LengthV, &[2, 437], 1392);
                step(f, Op::RemapF, &[437, 537, 77, 537, 539, 74, 438], 1393);
                step(f, Op::MulF, &[439, 438, 440], 1394);
                step(f, Op::QuatFromAxisAngle, &[342, 440, 52], 1395);
                step(f, Op::SubV, &[261, 260, 263], 1396);
                step(f, Op::RotateVector, &[52, 263, 264], 1397);
                step(f, Op::AddV, &[260, 264, 265], 1398);
                step(f, Op::DrawPoint, &[265, 543, 339], 1399);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 54, 64], 1400);
                step(f, Op::DrawTransform, &[64, 549, 538], 1401);
                step(f, Op::Jump, &[1402], 1402)
            }
            1402 => {
                step(f, Op::Jump, &[787], 1403)
            }
            1403 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1404);
                step(f, Op::Copy(ValueType::Int), &[64, 5], 1405);
                1405
            }
            1405 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 5, 1, 6, 7, 1460], 1406)
            }
            1406 => {
                step(f, Op::Copy(ValueType::Bone), &[1, 21], 1407);
                step(f, Op::Copy(ValueType::Int), &[6, 55], 1408);
                step(f, Op::GetParent, &[21, 22], 1409);
                step(f, Op::GetParent, &[22, 23], 1410);
                step(f, Op::GetParent, &[23, 24], 1411);
                step(f, Op::GetTransform, &[24, 64, 75, 73], 1412);
                step(f, Op::BreakTransform, &[73, 266, 56, 267], 1413);
                step(f, Op::LengthV, &[1, 448], 1414);
                step(f, Op::ClavicleOffset, &[6, 448, 83, 86, 449], 1415);
                step(f, Op::MakeVector, &[537, 537, 449, 268], 1416);
                step(f, Op::AddV, &[266, 268, 269], 1417);
                step(f, Op::MakeTransform, &[269, 56, 337, 74], 1418);
                step(f, Op::SetTransform, &[24, 74, 64, 74, 539], 1419);
                step(f, Op::GetParent, &[21, 22], 1420);
                step(f, Op::GetParent, &[22, 23], 1421);
                step(f, Op::GetTransform, &[21, 64, 75, 75], 1422);
                step(f, Op::GetTransform, &[23, 64, 75, 76], 1423);
                step(f, Op::BreakTransform, &[76, 270, 58, 271], 1424);
                step(f, Op::Equals(Elem::Int), &[55, 64, 63], 1425);
                step(f, Op::Select(ValueType::Int), &[63, 65, 64, 56], 1426);
                step(f, Op::ArrayAt(Elem::Float), &[0, 56, 447], 1427);
                step(f, Op::ArmSwingRotation, &[447, 1, 0, 84, 545, 551, 539, 83, 81, 82, 545, 545, 539, 450], 1428);
                step(f, Op::QuatFromAxisAngle, &[342, 450, 57], 1429);
                step(f, Op::RotateAroundPoint, &[75, 270, 57, 77], 1430);
                step(f, Op::BreakTransform, &[77, 272, 59, 273], 1431);
                step(f, Op::LengthV, &[1, 448], 1432);
                step(f, Op::RemapF, &[448, 537, 83, 537, 85, 74, 451], 1433);
                step(f, Op::MakeVector, &[537, 537, 451, 274], 1434);
                step(f, Op::AddV, &[272, 274, 275], 1435);
                step(f, Op::MakeTransform, &[275, 59, 337, 78], 1436);
                step(f, Op::Select(ValueType::Vec3), &[63, 343, 342, 277], 1437);
                step(f, Op::Select(ValueType::Vec3), &[63, 340, 344, 278], 1438);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 55, 276], 1439);
                step(f, Op::TwoBoneIK, &[23, 22, 21, 78, 277, 278, 276, 64, 539, 75, 552, 553, 74, 64, 452], 1440);
                step(f, Op::JumpIfFalse, &[8, 1459], 1441)
            }
            1441 => {
                step(f, Op::GetParent, &[21, 22], 1442);
                step(f, Op::GetParent, &[22, 23], 1443);
                step(f, Op::GetTransform, &[23, 64, 75, 76], 1444);
                step(f, Op::BreakTransform, &[76, 270, 58, 271], 1445);
                step(f, Op::GetTransform, &[21, 64, 75, 75], 1446);
                step(f, Op::Equals(Elem::Int), &[55, 64, 63], 1447);
                step(f, Op::Select(ValueType::Int), &[63, 65, 64, 56], 1448);
                step(f, Op::ArrayAt(Elem::Float), &[0, 56, 447], 1449);
                step(f, Op::ArmSwingRotation, &[447, 1, 0, 84, 545, 551, 539, 83, 81, 82, 545, 545, 539, 450], 1450);
                step(f, Op::QuatFromAxisAngle, &[342, 450, 57], 1451);
                step(f, Op::RotateAroundPoint, &[75, 270, 57, 77], 1452);
                step(f, Op::BreakTransform, &[77, 272, 59, 273], 1453);
                step(f, Op::LengthV, &[1, 448], 1454);
                step(f, Op::RemapF, &[448, 537, 83, 537, 85, 74, 451], 1455);
                step(f, Op::MakeVector, &[537, 537, 451, 274], 1456);
                step(f, Op::AddV, &[272, 274, 275], 1457);
                step(f, Op::DrawLine, &[270, 275, 538, 340], 1458);
                step(f, Op::Jump, &[1459], 1459)
            }
            1459 => {
                step(f, Op::Jump, &[1405], 1460)
            }
            1460 => {
                step(f, Op::Copy(ValueType::Float), &[537, 455], 1461);
                step(f, Op::Copy(ValueType::Float), &[546, 456], 1462);
                step(f, Op::Copy(ValueType::Bool), &[75, 65], 1463);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[3, 8], 1464);
                step(f, Op::Copy(ValueType::Int), &[64, 57], 1465);
                step(f, Op::MakeVector, &[537, 537, 45, 281], 1466);
                1466
            }
            1466 => {
                step(f, Op::ForEachNext(Elem::Transform), &[8, 57, 79, 58, 59, 1479], 1467)
            }
            1467 => {
                step(f, Op::BreakTransform, &[79, 279, 60, 280], 1468);
                step(f, Op::AddV, &[279, 281, 282], 1469);
                step(f, Op::SubV, &[279, 281, 283], 1470);
                step(f, Op::SphereTrace, &[282, 283, 44, 66, 284, 285, 457], 1471);
                step(f, Op::BreakVector, &[284, 458, 459, 460], 1472);
                step(f, Op::LessF, &[460, 456, 67], 1473);
                step(f, Op::And, &[66, 67, 68], 1474);
                step(f, Op::JumpIfFalse, &[68, 1478], 1475)
            }
            1475 => {
                step(f, Op::Copy(ValueType::Float), &[460, 456], 1476);
                step(f, Op::Copy(ValueType::Bool), &[74, 65], 1477);
                step(f, Op::Jump, &[1478], 1478)
            }
            1478 => {
                step(f, Op::Jump, &[1466], 1479)
            }
            1479 => {
                step(f, Op::Select(ValueType::Float), &[65, 456, 537, 461], 1480);
                step(f, Op::ClampF, &[461, 48, 49, 462], 1481);
                step(f, Op::Copy(ValueType::Float), &[462, 455], 1482);
                step(f, Op::Jump, &[1483], 1483)
            }
            1483 => {
                step(f, Op::SubF, &[539, 13, 454], 1484);
                step(f, Op::MulF, &[455, 454, 463], 1485);
                step(f, Op::FloatLerp, &[10, 463, 39, 464], 1486);
                step(f, Op::Select(ValueType::Float), &[1, 463, 464, 465], 1487);
                step(f, Op::Copy(ValueType::Float), &[465, 10], 1488);
                step(f, Op::GetTransform, &[37, 64, 74, 84], 1489);
                step(f, Op::BreakTransform, &[84, 298, 67, 299], 1490);
                step(f, Op::PelvisLean, &[1, 88, 93, 94, 479, 480], 1491);
                step(f, Op::LengthV, &[2, 453], 1492);
                step(f, Op::RemapF, &[453, 537, 88, 537, 87, 74, 466], 1493);
                step(f, Op::MulF, &[6, 554, 467], 1494);
                step(f, Op::SinF, &[467, 468], 1495);
                step(f, Op::MulF, &[466, 468, 469], 1496);
                step(f, Op::MulF, &[469, 454, 470], 1497);
                step(f, Op::AddF, &[470, 10, 471], 1498);
                step(f, Op::MakeVector, &[537, 480, 471, 300], 1499);
                step(f, Op::AddV, &[298, 300, 301], 1500);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 64, 80], 1501);
                step(f, Op::BreakTransform, &[80, 286, 61, 287], 1502);
                step(f, Op::BreakVector, &[286, 481, 482, 483], 1503);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 65, 81], 1504);
                step(f, Op::BreakTransform, &[81, 288, 62, 289], 1505);
                step(f, Op::BreakVector, &[288, 484, 485, 486], 1506);
                step(f, Op::SubF, &[483, 486, 487], 1507);
                step(f, Op::PelvisSideLean, &[487, 95, 96, 488], 1508);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 64, 82], 1509);
                step(f, Op::BreakTransform, &[82, 292, 63, 293], 1510);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 65, 83], 1511);
                step(f, Op::BreakTransform, &[83, 294, 64, 295], 1512);
                step(f, Op::SlerpQ, &[63, 64, 538, 65], 1513);
                step(f, Op::EulerFromQuat, &[65, 64, 296], 1514);
                step(f, Op::BreakVector, &[296, 475, 476, 477], 1515);
                step(f, Op::RemapF, &[453, 89, 88, 537, 90, 74, 473], 1516);
                step(f, Op::SubV, &[286, 288, 290], 1517);
                step(f, Op::RotateVector, &[0, 340, 291], 1518);
                step(f, Op::DotV, &[290, 291, 472], 1519);
                step(f, Op::MulF, &[473, 472, 474], 1520);
                step(f, Op::AddF, &[477, 474, 478], 1521);
                step(f, Op::MakeVector, &[479, 488, 478, 297], 1522);
                step(f, Op::QuatFromEuler, &[297, 64, 66], 1523);
                step(f, Op::MakeTransform, &[301, 66, 337, 85], 1524);
                step(f, Op::SetTransform, &[38, 85, 64, 74, 539], 1525);
                step(f, Op::GetTransform, &[39, 65, 74, 86], 1526);
                step(f, Op::BreakTransform, &[86, 302, 71, 303], 1527);
                step(f, Op::LengthV, &[2, 453], 1528);
                step(f, Op::RemapF, &[453, 89, 88, 537, 90, 74, 473], 1529);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 64, 80], 1530);
                step(f, Op::BreakTransform, &[80, 286, 61, 287], 1531);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 65, 81], 1532);
                step(f, Op::BreakTransform, &[81, 288, 62, 289], 1533);
                step(f, Op::SubV, &[286, 288, 290], 1534);
                step(f, Op::RotateVector, &[0, 340, 291], 1535);
                step(f, Op::DotV, &[290, 291, 472], 1536);
                step(f, Op::MulF, &[473, 472, 474], 1537);
                step(f, Op::QuatFromAxisAngle, &[339, 474, 68], 1538);
                step(f, Op::DivF, &[91, 543, 489], 1539);
                step(f, Op::QuatScale, &[68, 489, 69], 1540);
                step(f, Op::MulQ, &[71, 69, 75], 1541);
                step(f, Op::MakeTransform, &[302, 75, 337, 90], 1542);
                step(f, Op::SetTransform, &[40, 90, 65, 74, 539], 1543);
                step(f, Op::GetTransform, &[41, 65, 74, 87], 1544);
                step(f, Op::BreakTransform, &[87, 304, 72, 305], 1545);
                step(f, Op::LengthV, &[2, 453], 1546);
                step(f, Op::RemapF, &[453, 89, 88, 537, 90, 74, 473], 1547);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 64, 80], 1548);
                step(f, Op::BreakTransform, &[80, 286, 61, 287], 1549);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 65, 81], 1550);
                step(f, Op::BreakTransform, &[81, 288, 62, 289], 1551);
                step(f, Op::SubV, &[286, 288, 290], 1552);
                step(f, Op::RotateVector, &[0, 340, 291], 1553);
                step(f, Op::DotV, &[290, 291, 472], 1554);
                step(f, Op::MulF, &[473, 472, 474], 1555);
                step(f, Op::QuatFromAxisAngle, &[339, 474, 68], 1556);
                step(f, Op::DivF, &[91, 543, 489], 1557);
                step(f, Op::QuatScale, &[68, 489, 69], 1558);
                step(f, Op::MulQ, &[72, 69, 76], 1559);
                step(f, Op::MakeTransform, &[304, 76, 337, 91], 1560);
                step(f, Op::SetTransform, &[42, 91, 65, 74, 539], 1561);
                step(f, Op::GetTransform, &[43, 65, 74, 88], 1562);
                step(f, Op::BreakTransform, &[88, 306, 73, 307], 1563);
                step(f, Op::LengthV, &[2, 453], 1564);
                step(f, Op::RemapF, &[453, 89, 88, 537, 90, 74, 473], 1565);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 64, 80], 1566);
                step(f, Op::BreakTransform, &[80, 286, 61, 287], 1567);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 65, 81], 1568);
                step(f, Op::BreakTransform, &[81, 288, 62, 289], 1569);
                step(f, Op::SubV, &[286, 288, 290], 1570);
                step(f, Op::RotateVector, &[0, 340, 291], 1571);
                step(f, Op::DotV, &[290, 291, 472], 1572);
                step(f, Op::MulF, &[473, 472, 474], 1573);
                step(f, Op::QuatFromAxisAngle, &[339, 474, 68], 1574);
                step(f, Op::DivF, &[91, 543, 489], 1575);
                step(f, Op::QuatScale, &[68, 489, 69], 1576);
                step(f, Op::MulQ, &[73, 69, 77], 1577);
                step(f, Op::MakeTransform, &[306, 77, 337, 92], 1578);
                step(f, Op::SetTransform, &[44, 92, 65, 74, 539], 1579);
                step(f, Op::GetTransform, &[45, 65, 74, 89], 1580);
                step(f, Op::BreakTransform, &[89, 308, 74, 309], 1581);
                step(f, Op::LengthV, &[2, 453], 1582);
                step(f, Op::RemapF, &[453, 89, 88, 537, 90, 74, 473], 1583);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 64, 80], 1584);
                step(f, Op::BreakTransform, &[80, 286, 61, 287], 1585);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 65, 81], 1586);
                step(f, Op::BreakTransform, &[81, 288, 62, 289], 1587);
                step(f, Op::SubV, &[286, 288, 290], 1588);
                step(f, Op::RotateVector, &[0, 340, 291], 1589);
                step(f, Op::DotV, &[290, 291, 472], 1590);
                step(f, Op::MulF, &[473, 472, 474], 1591);
                step(f, Op::QuatFromAxisAngle, &[339, 474, 68], 1592);
                step(f, Op::QuatScale, &[68, 92, 70], 1593);
                step(f, Op::MulQ, &[74, 70, 78], 1594);
                step(f, Op::MakeTransform, &[308, 78, 337, 93], 1595);
                step(f, Op::SetTransform, &[46, 93, 65, 74, 539], 1596);
                step(f, Op::Copy(ValueType::Float), &[537, 490], 1597);
                step(f, Op::Copy(ValueType::Float), &[537, 491], 1598);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1599);
                step(f, Op::Copy(ValueType::Int), &[64, 60], 1600);
                1600
            }
            1600 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 60, 25, 61, 62, 1630], 1601)
            }
            1601 => {
                step(f, Op::GetParent, &[25, 26], 1602);
                step(f, Op::GetParent, &[26, 27], 1603);
                step(f, Op::GetTransform, &[27, 64, 75, 94], 1604);
                step(f, Op::BreakTransform, &[94, 310, 79, 311], 1605);
                step(f, Op::BreakVector, &[310, 492, 493, 494], 1606);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 61, 95], 1607);
                step(f, Op::BreakTransform, &[95, 312, 80, 313], 1608);
                step(f, Op::BreakVector, &[312, 495, 496, 497], 1609);
                step(f, Op::ArrayAt(Elem::Float), &[1, 61, 501], 1610);
                step(f, Op::MulF, &[501, 97, 502], 1611);
                step(f, Op::MulF, &[502, 502, 503], 1612);
                step(f, Op::SubF, &[492, 495, 498], 1613);
                step(f, Op::SubF, &[493, 496, 499], 1614);
                step(f, Op::MakeVector, &[498, 499, 537, 314], 1615);
                step(f, Op::DotV, &[314, 314, 500], 1616);
                step(f, Op::SubF, &[503, 500, 504], 1617);
                step(f, Op::SqrtF, &[504, 505], 1618);
                step(f, Op::AddF, &[497, 505, 506], 1619);
                step(f, Op::SubF, &[494, 506, 507], 1620);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 61, 69], 1621);
                step(f, Op::ArrayAt(Elem::Float), &[2, 61, 508], 1622);
                step(f, Op::RemapF, &[508, 538, 539, 537, 539, 74, 509], 1623);
                step(f, Op::RemapF, &[508, 537, 100, 539, 537, 74, 510], 1624);
                step(f, Op::MaxF, &[509, 510, 511], 1625);
                step(f, Op::Select(ValueType::Float), &[69, 539, 511, 512], 1626);
                step(f, Op::MulF, &[507, 512, 513], 1627);
                step(f, Op::MaxF, &[491, 513, 514], 1628);
                step(f, Op::Copy(ValueType::Float), &[514, 491], 1629);
                step(f, Op::Jump, &[1600], 1630)
            }
            1630 => {
                step(f, Op::ClampF, &[491, 537, 98, 515], 1631);
                step(f, Op::Copy(ValueType::Float), &[515, 490], 1632);
                step(f, Op::Jump, &[1633], 1633)
            }
            1633 => {
                step(f, Op::GreaterF, &[490, 11, 70], 1634);
                step(f, Op::Select(ValueType::Float), &[70, 102, 99, 516], 1635);
                step(f, Op::FloatLerp, &[11, 490, 516, 517], 1636);
                step(f, Op::Select(ValueType::Float), &[1, 490, 517, 518], 1637);
                step(f, Op::Copy(ValueType::Float), &[518, 11], 1638);
                step(f, Op::GetTransform, &[47, 64, 75, 96], 1639);
                step(f, Op::BreakTransform, &[96, 315, 81, 316], 1640);
                step(f, Op::MakeVector, &[537, 537, 11, 317], 1641);
                step(f, Op::SubV, &[315, 317, 318], 1642);
                step(f, Op::MakeTransform, &[318, 81, 337, 97], 1643);
                step(f, Op::SetTransform, &[48, 97, 64, 74, 539], 1644);
                step(f, Op::JumpIfFalse, &[8, 1652], 1645)
            }
            1645 => {
                step(f, Op::GetTransform, &[47, 64, 75, 96], 1646);
                step(f, Op::BreakTransform, &[96, 315, 81, 316], 1647);
                step(f, Op::MakeVector, &[537, 537, 11, 317], 1648);
                step(f, Op::SubV, &[315, 317, 318], 1649);
                step(f, Op::MakeTransform, &[318, 81, 337, 97], 1650);
                step(f, Op::DrawTransform, &[97, 555, 538], 1651);
                step(f, Op::Jump, &[1652], 1652)
            }
            1652 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1653);
                step(f, Op::Copy(ValueType::Int), &[64, 8], 1654);
                1654
            }
            1654 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 8, 2, 9, 10, 1706], 1655)
            }
            1655 => {
                step(f, Op::Copy(ValueType::Bone), &[2, 28], 1656);
                step(f, Op::Copy(ValueType::Int), &[9, 63], 1657);
                step(f, Op::GetParent, &[28, 29], 1658);
                step(f, Op::GetParent, &[29, 30], 1659);
                step(f, Op::GetTransform, &[30, 64, 75, 98], 1660);
                step(f, Op::BreakTransform, &[98, 319, 82, 320], 1661);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 63, 99], 1662);
                step(f, Op::BreakTransform, &[99, 321, 83, 322], 1663);
                step(f, Op::SubV, &[321, 319, 323], 1664);
                step(f, Op::LengthV, &[323, 527], 1665);
                step(f, Op::ArrayAt(Elem::Float), &[1, 63, 519], 1666);
                step(f, Op::MulF, &[519, 105, 520], 1667);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 63, 71], 1668);
                step(f, Op::ArrayAt(Elem::Float), &[2, 63, 521], 1669);
                step(f, Op::ClampF, &[521, 537, 539, 522], 1670);
                step(f, Op::MulF, &[522, 550, 523], 1671);
                step(f, Op::SinF, &[523, 524], 1672);
                step(f, Op::MulF, &[524, 106, 525], 1673);
                step(f, Op::Select(ValueType::Float), &[71, 537, 525, 526], 1674);
                step(f, Op::SubF, &[520, 526, 528], 1675);
                step(f, Op::SubF, &[527, 528, 529], 1676);
                step(f, Op::MaxF, &[529, 537, 530], 1677);
                step(f, Op::MulF, &[530, 530, 531], 1678);
                step(f, Op::AddF, &[530, 526, 532], 1679);
                step(f, Op::DivF, &[531, 532, 533], 1680);
                step(f, Op::SubF, &[527, 533, 534], 1681);
                step(f, Op::DivF, &[534, 527, 535], 1682);
                step(f, Op::ScaleV, &[323, 535, 324], 1683);
                step(f, Op::AddV, &[319, 324, 325], 1684);
                step(f, Op::ClampSpatially, &[325, 319, 537, 520, 326], 1685);
                step(f, Op::MakeTransform, &[326, 83, 337, 100], 1686);
                step(f, Op::Equals(Elem::Int), &[63, 64, 72], 1687);
                step(f, Op::Select(ValueType::Vec3), &[72, 343, 342, 331], 1688);
                step(f, Op::Select(ValueType::Vec3), &[72, 340, 344, 332], 1689);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 63, 101], 1690);
                step(f, Op::BreakTransform, &[101, 327, 84, 328], 1691);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 63, 329], 1692);
                step(f, Op::KneeVector, &[84, 0, 329, 107, 108, 330], 1693);
                step(f, Op::TwoBoneIK, &[30, 29, 28, 100, 331, 332, 330, 64, 539, 75, 552, 553, 74, 73, 536], 1694);
                step(f, Op::JumpIfFalse, &[8, 1705], 1695)
            }
            1695 => {
                step(f, Op::GetParent, &[28, 29], 1696);
                step(f, Op::GetTransform, &[29, 64, 75, 102], 1697);
                step(f, Op::BreakTransform, &[102, 333, 85, 334], 1698);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 63, 101], 1699);
                step(f, Op::BreakTransform, &[101, 327, 84, 328], 1700);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 63, 329], 1701);
                step(f, Op::KneeVector, &[84, 0, 329, 107, 108, 330], 1702);
                step(f, Op::AddV, &[333, 330, 335], 1703);
                step(f, Op::DrawLine, &[333, 335, 538, 345], 1704);
                step(f, Op::Jump, &[1705], 1705)
            }
            1705 => {
                step(f, Op::Jump, &[1654], 1706)
            }
            1706 => {
                step(f, Op::End, &[], 1707)
            }
            _ => return,
        } };
    }
}
