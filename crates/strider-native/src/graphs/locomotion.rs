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
    fingerprint: 0xecea7510d9a4df9f,
    forward,
};

fn forward(f: &mut Frame<'_>) {
    let mut pc: usize = 377;
    loop {
        // SAFETY: each `step` is an instruction of the program this code was generated
        // from, with its own operands; `NATIVE` runs only on that program (fingerprint).
        pc = unsafe { match pc {
            377 => {
                step(f, Op::Not, &[0, 6], 378);
                step(f, Op::Copy(ValueType::Bool), &[6, 1], 379);
                step(f, Op::WorldTransform, &[12], 380);
                step(f, Op::BreakTransform, &[12, 30, 7, 31], 381);
                step(f, Op::Select(ValueType::Transform), &[0, 0, 12, 13], 382);
                step(f, Op::BreakTransform, &[13, 32, 8, 33], 383);
                step(f, Op::SubV, &[30, 32, 34], 384);
                step(f, Op::LengthV, &[34, 111], 385);
                step(f, Op::GreaterF, &[111, 24, 7], 386);
                step(f, Op::Copy(ValueType::Bool), &[7, 2], 387);
                step(f, Op::MakeRelative, &[13, 12, 17], 388);
                step(f, Op::Select(ValueType::Transform), &[7, 96, 17, 18], 389);
                step(f, Op::Copy(ValueType::Transform), &[18, 2], 390);
                step(f, Op::InverseT, &[13, 15], 391);
                step(f, Op::MulT, &[12, 15, 16], 392);
                step(f, Op::Copy(ValueType::Transform), &[16, 1], 393);
                step(f, Op::TransformVector, &[2, 0, 37], 394);
                step(f, Op::InverseT, &[12, 14], 395);
                step(f, Op::DeltaTime, &[110], 396);
                step(f, Op::DivF, &[489, 110, 112], 397);
                step(f, Op::ScaleV, &[34, 112, 35], 398);
                step(f, Op::TransformVector, &[14, 35, 36], 399);
                step(f, Op::Select(ValueType::Vec3), &[2, 37, 36, 39], 400);
                step(f, Op::VectorLerp, &[37, 39, 25, 487, 40], 401);
                step(f, Op::Copy(ValueType::Vec3), &[40, 0], 402);
                step(f, Op::TransformVector, &[2, 1, 38], 403);
                step(f, Op::TransformVector, &[2, 0, 37], 404);
                step(f, Op::Select(ValueType::Vec3), &[2, 37, 36, 39], 405);
                step(f, Op::VectorLerp, &[38, 39, 26, 487, 41], 406);
                step(f, Op::Copy(ValueType::Vec3), &[41, 1], 407);
                step(f, Op::LengthV, &[39, 113], 408);
                step(f, Op::Copy(ValueType::Float), &[113, 0], 409);
                step(f, Op::JumpIfFalse, &[2, 424], 410)
            }
            410 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 12], 411);
                step(f, Op::Copy(ValueType::Int), &[52, 16], 412);
                412
            }
            412 => {
                step(f, Op::ForEachNext(Elem::Bone), &[12, 16, 13, 17, 18, 422], 413)
            }
            413 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 17, 20], 414);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 17, 20], 415);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 17, 20], 416);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 17, 20], 417);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 17, 20], 418);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 17, 20], 419);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 17, 20], 420);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 17, 20], 421);
                step(f, Op::Jump, &[412], 422)
            }
            422 => {
                step(f, Op::Copy(ValueType::Float), &[487, 10], 423);
                step(f, Op::Jump, &[424], 424)
            }
            424 => {
                step(f, Op::WorldTransform, &[12], 425);
                step(f, Op::Copy(ValueType::Transform), &[12, 0], 426);
                step(f, Op::Copy(ValueType::Bool), &[59, 0], 427);
                step(f, Op::JumpIfFalse, &[5, 434], 428)
            }
            428 => {
                step(f, Op::GetTransform, &[34, 52, 59, 19], 429);
                step(f, Op::BreakTransform, &[19, 42, 9, 43], 430);
                step(f, Op::ScaleV, &[0, 490, 44], 431);
                step(f, Op::AddV, &[42, 44, 45], 432);
                step(f, Op::DrawArrow, &[42, 45, 488, 307], 433);
                step(f, Op::Jump, &[434], 434)
            }
            434 => {
                step(f, Op::Copy(ValueType::Bool), &[60, 9], 435);
                step(f, Op::Copy(ValueType::Bool), &[59, 10], 436);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 437);
                step(f, Op::Copy(ValueType::Int), &[52, 22], 438);
                438
            }
            438 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 22, 11, 23, 24, 444], 439)
            }
            439 => {
                step(f, Op::Not, &[11, 12], 440);
                step(f, Op::JumpIfFalse, &[12, 443], 441)
            }
            441 => {
                step(f, Op::Copy(ValueType::Bool), &[60, 10], 442);
                step(f, Op::Jump, &[443], 443)
            }
            443 => {
                step(f, Op::Jump, &[438], 444)
            }
            444 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 9], 445);
                step(f, Op::Jump, &[446], 446)
            }
            446 => {
                step(f, Op::Copy(ValueType::Bool), &[60, 13], 447);
                step(f, Op::Copy(ValueType::Bool), &[59, 14], 448);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 449);
                step(f, Op::Copy(ValueType::Int), &[52, 25], 450);
                450
            }
            450 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 25, 15, 26, 27, 465], 451)
            }
            451 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 26, 21], 452);
                step(f, Op::BreakTransform, &[21, 46, 10, 47], 453);
                step(f, Op::BreakVector, &[46, 122, 123, 124], 454);
                step(f, Op::MakeVector, &[122, 123, 487, 50], 455);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 26, 22], 456);
                step(f, Op::BreakTransform, &[22, 48, 11, 49], 457);
                step(f, Op::BreakVector, &[48, 125, 126, 127], 458);
                step(f, Op::MakeVector, &[125, 126, 487, 51], 459);
                step(f, Op::DistanceV, &[50, 51, 128], 460);
                step(f, Op::GreaterF, &[128, 20, 15], 461);
                step(f, Op::JumpIfFalse, &[15, 464], 462)
            }
            462 => {
                step(f, Op::Copy(ValueType::Bool), &[60, 14], 463);
                step(f, Op::Jump, &[464], 464)
            }
            464 => {
                step(f, Op::Jump, &[450], 465)
            }
            465 => {
                step(f, Op::Copy(ValueType::Bool), &[14, 13], 466);
                step(f, Op::Jump, &[467], 467)
            }
            467 => {
                step(f, Op::And, &[9, 13, 16], 468);
                step(f, Op::LengthV, &[0, 114], 469);
                step(f, Op::GreaterF, &[114, 18, 8], 470);
                step(f, Op::GreaterF, &[0, 18, 17], 471);
                step(f, Op::Or, &[8, 17, 18], 472);
                step(f, Op::Not, &[18, 19], 473);
                step(f, Op::And, &[16, 19, 24], 474);
                step(f, Op::DeltaTime, &[149], 475);
                step(f, Op::MulF, &[149, 23, 150], 476);
                step(f, Op::AddF, &[6, 150, 151], 477);
                step(f, Op::GreaterF, &[6, 488, 25], 478);
                step(f, Op::AddF, &[22, 488, 147], 479);
                step(f, Op::Select(ValueType::Float), &[25, 147, 22, 148], 480);
                step(f, Op::MinF, &[151, 148, 152], 481);
                step(f, Op::NotEquals(Elem::Bool), &[19, 4, 20], 482);
                step(f, Op::Not, &[16, 21], 483);
                step(f, Op::And, &[20, 21, 22], 484);
                step(f, Op::SubF, &[7, 18, 133], 485);
                step(f, Op::SubF, &[7, 114, 134], 486);
                step(f, Op::DivF, &[133, 134, 135], 487);
                step(f, Op::ClampF, &[135, 487, 489, 136], 488);
                step(f, Op::MulF, &[3, 136, 138], 489);
                step(f, Op::RemapF, &[114, 18, 19, 487, 489, 59, 129], 490);
                step(f, Op::Select(ValueType::Float), &[19, 21, 489, 130], 491);
                step(f, Op::Select(ValueType::Float), &[16, 129, 130, 131], 492);
                step(f, Op::LerpF, &[12, 33, 9, 117], 493);
                step(f, Op::RemapF, &[114, 15, 16, 13, 14, 59, 115], 494);
                step(f, Op::LerpF, &[115, 32, 9, 116], 495);
                step(f, Op::MaxF, &[114, 17, 118], 496);
                step(f, Op::DivF, &[116, 118, 119], 497);
                step(f, Op::AddF, &[117, 119, 120], 498);
                step(f, Op::DivF, &[131, 120, 132], 499);
                step(f, Op::SubF, &[489, 136, 137], 500);
                step(f, Op::MulF, &[132, 137, 139], 501);
                step(f, Op::AddF, &[138, 139, 140], 502);
                step(f, Op::MulF, &[140, 491, 141], 503);
                step(f, Op::AddF, &[3, 132, 142], 504);
                step(f, Op::Select(ValueType::Float), &[22, 141, 142, 143], 505);
                step(f, Op::DivF, &[491, 143, 144], 506);
                step(f, Op::GreaterF, &[143, 487, 23], 507);
                step(f, Op::CycleStep, &[6, 144, 487, 23, 145, 146], 508);
                step(f, Op::Select(ValueType::Float), &[24, 152, 145, 153], 509);
                step(f, Op::Copy(ValueType::Float), &[153, 6], 510);
                step(f, Op::Copy(ValueType::Float), &[132, 3], 511);
                step(f, Op::Copy(ValueType::Bool), &[8, 3], 512);
                step(f, Op::Copy(ValueType::Float), &[119, 1], 513);
                step(f, Op::Copy(ValueType::Float), &[120, 2], 514);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 515);
                step(f, Op::Copy(ValueType::Int), &[52, 19], 516);
                516
            }
            516 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 19, 14, 20, 21, 616], 517)
            }
            517 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 20, 167], 518);
                step(f, Op::ToFloat, &[20, 154], 519);
                step(f, Op::MulF, &[154, 488, 155], 520);
                step(f, Op::AddF, &[6, 155, 156], 521);
                step(f, Op::FractF, &[156, 157], 522);
                step(f, Op::SubF, &[167, 157, 169], 523);
                step(f, Op::GreaterF, &[169, 488, 26], 524);
                step(f, Op::SubF, &[489, 167, 180], 525);
                step(f, Op::AddF, &[157, 180, 181], 526);
                step(f, Op::DivF, &[157, 181, 182], 527);
                step(f, Op::LengthV, &[0, 114], 528);
                step(f, Op::GreaterF, &[114, 18, 8], 529);
                step(f, Op::GreaterF, &[0, 18, 17], 530);
                step(f, Op::Or, &[8, 17, 18], 531);
                step(f, Op::Not, &[18, 19], 532);
                step(f, Op::NotEquals(Elem::Bool), &[19, 4, 20], 533);
                step(f, Op::Copy(ValueType::Bool), &[60, 9], 534);
                step(f, Op::Copy(ValueType::Bool), &[59, 10], 535);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 536);
                step(f, Op::Copy(ValueType::Int), &[52, 22], 537);
                537
            }
            537 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 22, 11, 23, 24, 543], 538)
            }
            538 => {
                step(f, Op::Not, &[11, 12], 539);
                step(f, Op::JumpIfFalse, &[12, 542], 540)
            }
            540 => {
                step(f, Op::Copy(ValueType::Bool), &[60, 10], 541);
                step(f, Op::Jump, &[542], 542)
            }
            542 => {
                step(f, Op::Jump, &[537], 543)
            }
            543 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 9], 544);
                step(f, Op::Jump, &[545], 545)
            }
            545 => {
                step(f, Op::Copy(ValueType::Bool), &[60, 13], 546);
                step(f, Op::Copy(ValueType::Bool), &[59, 14], 547);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 548);
                step(f, Op::Copy(ValueType::Int), &[52, 25], 549);
                549
            }
            549 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 25, 15, 26, 27, 564], 550)
            }
            550 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 26, 21], 551);
                step(f, Op::BreakTransform, &[21, 46, 10, 47], 552);
                step(f, Op::BreakVector, &[46, 122, 123, 124], 553);
                step(f, Op::MakeVector, &[122, 123, 487, 50], 554);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 26, 22], 555);
                step(f, Op::BreakTransform, &[22, 48, 11, 49], 556);
                step(f, Op::BreakVector, &[48, 125, 126, 127], 557);
                step(f, Op::MakeVector, &[125, 126, 487, 51], 558);
                step(f, Op::DistanceV, &[50, 51, 128], 559);
                step(f, Op::GreaterF, &[128, 20, 15], 560);
                step(f, Op::JumpIfFalse, &[15, 563], 561)
            }
            561 => {
                step(f, Op::Copy(ValueType::Bool), &[60, 14], 562);
                step(f, Op::Jump, &[563], 563)
            }
            563 => {
                step(f, Op::Jump, &[549], 564)
            }
            564 => {
                step(f, Op::Copy(ValueType::Bool), &[14, 13], 565);
                step(f, Op::Jump, &[566], 566)
            }
            566 => {
                step(f, Op::And, &[9, 13, 16], 567);
                step(f, Op::Not, &[16, 21], 568);
                step(f, Op::And, &[20, 21, 22], 569);
                step(f, Op::SubF, &[7, 18, 133], 570);
                step(f, Op::SubF, &[7, 114, 134], 571);
                step(f, Op::DivF, &[133, 134, 135], 572);
                step(f, Op::ClampF, &[135, 487, 489, 136], 573);
                step(f, Op::MulF, &[5, 136, 159], 574);
                step(f, Op::RemapF, &[114, 18, 19, 487, 489, 59, 129], 575);
                step(f, Op::Select(ValueType::Float), &[19, 21, 489, 130], 576);
                step(f, Op::Select(ValueType::Float), &[16, 129, 130, 131], 577);
                step(f, Op::LerpF, &[12, 33, 9, 117], 578);
                step(f, Op::DivF, &[131, 117, 158], 579);
                step(f, Op::SubF, &[489, 136, 137], 580);
                step(f, Op::MulF, &[158, 137, 160], 581);
                step(f, Op::AddF, &[159, 160, 161], 582);
                step(f, Op::MulF, &[161, 491, 162], 583);
                step(f, Op::AddF, &[5, 158, 163], 584);
                step(f, Op::Select(ValueType::Float), &[22, 162, 163, 164], 585);
                step(f, Op::DeltaTime, &[149], 586);
                step(f, Op::MulF, &[149, 488, 165], 587);
                step(f, Op::MulF, &[164, 165, 166], 588);
                step(f, Op::MulF, &[182, 166, 183], 589);
                step(f, Op::ArrayAt(Elem::Float), &[2, 20, 168], 590);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 20, 27], 591);
                step(f, Op::RemapF, &[114, 15, 16, 13, 14, 59, 115], 592);
                step(f, Op::LerpF, &[115, 32, 9, 116], 593);
                step(f, Op::MaxF, &[114, 17, 118], 594);
                step(f, Op::DivF, &[116, 118, 119], 595);
                step(f, Op::AddF, &[117, 119, 120], 596);
                step(f, Op::DivF, &[117, 120, 121], 597);
                step(f, Op::SubF, &[121, 4, 170], 598);
                step(f, Op::MaxF, &[170, 487, 171], 599);
                step(f, Op::DivF, &[171, 121, 172], 600);
                step(f, Op::MulF, &[172, 168, 173], 601);
                step(f, Op::SubF, &[489, 9, 174], 602);
                step(f, Op::MulF, &[173, 174, 175], 603);
                step(f, Op::MulF, &[175, 98, 176], 604);
                step(f, Op::Select(ValueType::Float), &[27, 487, 176, 177], 605);
                step(f, Op::SubF, &[166, 177, 178], 606);
                step(f, Op::AddF, &[168, 178, 179], 607);
                step(f, Op::Select(ValueType::Float), &[26, 183, 179, 184], 608);
                step(f, Op::MinF, &[184, 491, 185], 609);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 20, 185], 610);
                step(f, Op::ToFloat, &[20, 154], 611);
                step(f, Op::MulF, &[154, 488, 155], 612);
                step(f, Op::AddF, &[6, 155, 156], 613);
                step(f, Op::FractF, &[156, 157], 614);
                step(f, Op::ArraySetAt(Elem::Float), &[0, 20, 157], 615);
                step(f, Op::Jump, &[516], 616)
            }
            616 => {
                step(f, Op::LerpF, &[12, 33, 9, 117], 617);
                step(f, Op::LengthV, &[0, 114], 618);
                step(f, Op::RemapF, &[114, 15, 16, 13, 14, 59, 115], 619);
                step(f, Op::LerpF, &[115, 32, 9, 116], 620);
                step(f, Op::MaxF, &[114, 17, 118], 621);
                step(f, Op::DivF, &[116, 118, 119], 622);
                step(f, Op::AddF, &[117, 119, 120], 623);
                step(f, Op::DivF, &[117, 120, 121], 624);
                step(f, Op::Copy(ValueType::Float), &[121, 4], 625);
                step(f, Op::GreaterF, &[114, 18, 8], 626);
                step(f, Op::GreaterF, &[0, 18, 17], 627);
                step(f, Op::Or, &[8, 17, 18], 628);
                step(f, Op::Not, &[18, 19], 629);
                step(f, Op::Copy(ValueType::Bool), &[19, 4], 630);
                step(f, Op::Copy(ValueType::Float), &[114, 7], 631);
                step(f, Op::Copy(ValueType::Bool), &[60, 9], 632);
                step(f, Op::Copy(ValueType::Bool), &[59, 10], 633);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 634);
                step(f, Op::Copy(ValueType::Int), &[52, 22], 635);
                635
            }
            635 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 22, 11, 23, 24, 641], 636)
            }
            636 => {
                step(f, Op::Not, &[11, 12], 637);
                step(f, Op::JumpIfFalse, &[12, 640], 638)
            }
            638 => {
                step(f, Op::Copy(ValueType::Bool), &[60, 10], 639);
                step(f, Op::Jump, &[640], 640)
            }
            640 => {
                step(f, Op::Jump, &[635], 641)
            }
            641 => {
                step(f, Op::Copy(ValueType::Bool), &[10, 9], 642);
                step(f, Op::Jump, &[643], 643)
            }
            643 => {
                step(f, Op::Copy(ValueType::Bool), &[60, 13], 644);
                step(f, Op::Copy(ValueType::Bool), &[59, 14], 645);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 646);
                step(f, Op::Copy(ValueType::Int), &[52, 25], 647);
                647
            }
            647 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 25, 15, 26, 27, 662], 648)
            }
            648 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 26, 21], 649);
                step(f, Op::BreakTransform, &[21, 46, 10, 47], 650);
                step(f, Op::BreakVector, &[46, 122, 123, 124], 651);
                step(f, Op::MakeVector, &[122, 123, 487, 50], 652);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 26, 22], 653);
                step(f, Op::BreakTransform, &[22, 48, 11, 49], 654);
                step(f, Op::BreakVector, &[48, 125, 126, 127], 655);
                step(f, Op::MakeVector, &[125, 126, 487, 51], 656);
                step(f, Op::DistanceV, &[50, 51, 128], 657);
                step(f, Op::GreaterF, &[128, 20, 15], 658);
                step(f, Op::JumpIfFalse, &[15, 661], 659)
            }
            659 => {
                step(f, Op::Copy(ValueType::Bool), &[60, 14], 660);
                step(f, Op::Jump, &[661], 661)
            }
            661 => {
                step(f, Op::Jump, &[647], 662)
            }
            662 => {
                step(f, Op::Copy(ValueType::Bool), &[14, 13], 663);
                step(f, Op::Jump, &[664], 664)
            }
            664 => {
                step(f, Op::And, &[9, 13, 16], 665);
                step(f, Op::RemapF, &[114, 18, 19, 487, 489, 59, 129], 666);
                step(f, Op::Select(ValueType::Float), &[19, 21, 489, 130], 667);
                step(f, Op::Select(ValueType::Float), &[16, 129, 130, 131], 668);
                step(f, Op::DivF, &[131, 117, 158], 669);
                step(f, Op::Copy(ValueType::Float), &[158, 5], 670);
                step(f, Op::Select(ValueType::Vec3), &[3, 0, 305, 52], 671);
                step(f, Op::MovementAngleOffset, &[52, 8, 6, 27, 28, 492, 29, 493, 186], 672);
                step(f, Op::Copy(ValueType::Float), &[186, 8], 673);
                step(f, Op::QuatFromAxisAngle, &[308, 8, 12], 674);
                step(f, Op::Copy(ValueType::Quat), &[12, 0], 675);
                step(f, Op::SinF, &[8, 187], 676);
                step(f, Op::AbsF, &[187, 188], 677);
                step(f, Op::RemapF, &[188, 30, 31, 487, 489, 59, 189], 678);
                step(f, Op::Copy(ValueType::Float), &[189, 9], 679);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 680);
                step(f, Op::Copy(ValueType::Int), &[52, 1], 681);
                681
            }
            681 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 1, 0, 2, 3, 1270], 682)
            }
            682 => {
                step(f, Op::Copy(ValueType::Bone), &[0, 16], 683);
                step(f, Op::Copy(ValueType::Int), &[2, 28], 684);
                step(f, Op::GetTransform, &[35, 52, 59, 23], 685);
                step(f, Op::BreakTransform, &[23, 55, 13, 56], 686);
                step(f, Op::BreakVector, &[55, 201, 202, 203], 687);
                step(f, Op::SubF, &[489, 9, 199], 688);
                step(f, Op::MulF, &[8, 199, 200], 689);
                step(f, Op::QuatFromAxisAngle, &[308, 200, 15], 690);
                step(f, Op::GetTransform, &[16, 52, 59, 24], 691);
                step(f, Op::BreakTransform, &[24, 57, 14, 58], 692);
                step(f, Op::SubV, &[57, 55, 59], 693);
                step(f, Op::BreakVector, &[59, 196, 197, 198], 694);
                step(f, Op::MakeVector, &[196, 197, 487, 60], 695);
                step(f, Op::RotateVector, &[15, 60, 61], 696);
                step(f, Op::BreakVector, &[61, 204, 205, 206], 697);
                step(f, Op::MulF, &[34, 9, 207], 698);
                step(f, Op::Equals(Elem::Int), &[28, 52, 28], 699);
                step(f, Op::Select(ValueType::Float), &[28, 489, 494, 216], 700);
                step(f, Op::MulF, &[207, 216, 208], 701);
                step(f, Op::AddF, &[204, 208, 209], 702);
                step(f, Op::AddF, &[201, 209, 210], 703);
                step(f, Op::AddF, &[202, 205, 211], 704);
                step(f, Op::BreakVector, &[57, 212, 213, 214], 705);
                step(f, Op::SubF, &[214, 37, 215], 706);
                step(f, Op::MakeVector, &[210, 211, 215, 62], 707);
                step(f, Op::ArrayAt(Elem::Float), &[2, 28, 190], 708);
                step(f, Op::SubF, &[489, 190, 191], 709);
                step(f, Op::MaxF, &[191, 487, 192], 710);
                step(f, Op::MulF, &[4, 2, 193], 711);
                step(f, Op::MulF, &[192, 193, 194], 712);
                step(f, Op::ScaleV, &[0, 194, 53], 713);
                step(f, Op::AddV, &[62, 53, 63], 714);
                step(f, Op::MulF, &[1, 488, 195], 715);
                step(f, Op::ScaleV, &[0, 195, 54], 716);
                step(f, Op::AddV, &[63, 54, 64], 717);
                step(f, Op::RotateVector, &[0, 309, 65], 718);
                step(f, Op::Copy(ValueType::Vec3), &[64, 72], 719);
                step(f, Op::Copy(ValueType::Vec3), &[65, 73], 720);
                step(f, Op::Copy(ValueType::Float), &[216, 226], 721);
                step(f, Op::Copy(ValueType::Vec3), &[305, 74], 722);
                step(f, Op::Copy(ValueType::Vec3), &[305, 75], 723);
                step(f, Op::Copy(ValueType::Bool), &[60, 29], 724);
                step(f, Op::Copy(ValueType::Float), &[495, 227], 725);
                step(f, Op::Copy(ValueType::Vec3), &[305, 76], 726);
                step(f, Op::Copy(ValueType::Vec3), &[308, 77], 727);
                step(f, Op::Copy(ValueType::Bool), &[60, 30], 728);
                step(f, Op::MulI, &[0, 0, 34], 729);
                step(f, Op::Copy(ValueType::Int), &[34, 33], 730);
                step(f, Op::Copy(ValueType::Int), &[52, 29], 731);
                step(f, Op::SubI, &[0, 53, 37], 732);
                step(f, Op::DivI, &[37, 54, 38], 733);
                step(f, Op::MakeVector, &[487, 487, 42, 82], 734);
                step(f, Op::ScaleV, &[73, 44, 87], 735);
                735
            }
            735 => {
                step(f, Op::ForNext, &[29, 33, 31, 775], 736)
            }
            736 => {
                step(f, Op::ModI, &[31, 0, 35], 737);
                step(f, Op::ToFloat, &[35, 228], 738);
                step(f, Op::MulF, &[228, 43, 230], 739);
                step(f, Op::MulF, &[230, 226, 231], 740);
                step(f, Op::MakeVector, &[231, 487, 487, 78], 741);
                step(f, Op::DivI, &[31, 0, 36], 742);
                step(f, Op::SubI, &[36, 38, 39], 743);
                step(f, Op::ToFloat, &[39, 229], 744);
                step(f, Op::MulF, &[229, 43, 232], 745);
                step(f, Op::ScaleV, &[73, 232, 79], 746);
                step(f, Op::AddV, &[78, 79, 80], 747);
                step(f, Op::AddV, &[72, 80, 81], 748);
                step(f, Op::AddV, &[81, 82, 83], 749);
                step(f, Op::SubV, &[81, 82, 84], 750);
                step(f, Op::SphereTrace, &[83, 84, 41, 31, 85, 86, 233], 751);
                step(f, Op::BreakVector, &[85, 235, 236, 237], 752);
                step(f, Op::AddV, &[83, 87, 88], 753);
                step(f, Op::AddV, &[84, 87, 89], 754);
                step(f, Op::SphereTrace, &[88, 89, 41, 32, 90, 91, 234], 755);
                step(f, Op::BreakVector, &[90, 238, 239, 240], 756);
                step(f, Op::SubF, &[237, 240, 241], 757);
                step(f, Op::AbsF, &[241, 242], 758);
                step(f, Op::Select(ValueType::Float), &[31, 487, 489, 243], 759);
                step(f, Op::AddF, &[242, 243, 248], 760);
                step(f, Op::LengthV, &[80, 244], 761);
                step(f, Op::RemapF, &[244, 487, 496, 487, 489, 59, 245], 762);
                step(f, Op::MinF, &[237, 240, 246], 763);
                step(f, Op::RemapF, &[246, 497, 496, 489, 488, 59, 247], 764);
                step(f, Op::AddF, &[245, 247, 249], 765);
                step(f, Op::AddF, &[248, 249, 250], 766);
                step(f, Op::LessF, &[250, 227, 33], 767);
                step(f, Op::And, &[31, 33, 34], 768);
                step(f, Op::JumpIfFalse, &[34, 774], 769)
            }
            769 => {
                step(f, Op::Copy(ValueType::Float), &[250, 227], 770);
                step(f, Op::Copy(ValueType::Vec3), &[85, 76], 771);
                step(f, Op::Copy(ValueType::Vec3), &[86, 77], 772);
                step(f, Op::Copy(ValueType::Bool), &[59, 30], 773);
                step(f, Op::Jump, &[774], 774)
            }
            774 => {
                step(f, Op::Jump, &[735], 775)
            }
            775 => {
                step(f, Op::JumpIfFalse, &[5, 778], 776)
            }
            776 => {
                step(f, Op::DrawSphere, &[76, 41, 309], 777);
                step(f, Op::Jump, &[778], 778)
            }
            778 => {
                step(f, Op::Copy(ValueType::Vec3), &[76, 74], 779);
                step(f, Op::Copy(ValueType::Vec3), &[77, 75], 780);
                step(f, Op::Copy(ValueType::Bool), &[30, 29], 781);
                step(f, Op::Jump, &[782], 782)
            }
            782 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 28, 25], 783);
                step(f, Op::BreakTransform, &[25, 67, 19, 68], 784);
                step(f, Op::ArrayAt(Elem::Float), &[2, 28, 190], 785);
                step(f, Op::SubF, &[489, 190, 191], 786);
                step(f, Op::MaxF, &[191, 487, 192], 787);
                step(f, Op::MulF, &[4, 2, 193], 788);
                step(f, Op::MulF, &[192, 193, 194], 789);
                step(f, Op::ScaleV, &[0, 194, 53], 790);
                step(f, Op::SubV, &[74, 53, 66], 791);
                step(f, Op::Select(ValueType::Vec3), &[29, 66, 67, 69], 792);
                step(f, Op::VectorLerp, &[67, 69, 35, 487, 70], 793);
                step(f, Op::BreakVector, &[70, 222, 223, 224], 794);
                step(f, Op::ClampF, &[224, 45, 46, 225], 795);
                step(f, Op::MakeVector, &[222, 223, 225, 71], 796);
                step(f, Op::RotationFromNormal, &[75, 220, 221, 17], 797);
                step(f, Op::PerFootRotationFactor, &[8, 76, 77, 217], 798);
                step(f, Op::MulF, &[8, 217, 218], 799);
                step(f, Op::SubF, &[489, 9, 199], 800);
                step(f, Op::MulF, &[218, 199, 219], 801);
                step(f, Op::QuatFromAxisAngle, &[308, 219, 16], 802);
                step(f, Op::MulQ, &[17, 16, 18], 803);
                step(f, Op::Select(ValueType::Quat), &[29, 18, 19, 20], 804);
                step(f, Op::MakeTransform, &[71, 20, 306, 26], 805);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 28, 26], 806);
                step(f, Op::Copy(ValueType::Int), &[2, 40], 807);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 40, 27], 808);
                step(f, Op::MakeAbsolute, &[27, 2, 28], 809);
                step(f, Op::BreakTransform, &[28, 92, 21, 93], 810);
                step(f, Op::ClampSpatially, &[92, 305, 487, 49, 94], 811);
                step(f, Op::SubF, &[489, 9, 256], 812);
                step(f, Op::MulF, &[8, 256, 252], 813);
                step(f, Op::LimitRotationAroundZ, &[21, 252, 75, 22], 814);
                step(f, Op::MakeTransform, &[94, 22, 306, 29], 815);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 40, 29], 816);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 40, 35], 817);
                step(f, Op::JumpIfFalse, &[35, 871], 818)
            }
            818 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 40, 31], 819);
                step(f, Op::BreakTransform, &[31, 95, 23, 96], 820);
                step(f, Op::ArrayAt(Elem::Float), &[2, 40, 251], 821);
                step(f, Op::SubF, &[489, 251, 253], 822);
                step(f, Op::MulF, &[4, 2, 254], 823);
                step(f, Op::MulF, &[253, 254, 255], 824);
                step(f, Op::ScaleV, &[0, 255, 97], 825);
                step(f, Op::AddV, &[95, 97, 98], 826);
                step(f, Op::MakeTransform, &[98, 23, 306, 38], 827);
                step(f, Op::Copy(ValueType::Transform), &[38, 39], 828);
                step(f, Op::Copy(ValueType::Transform), &[96, 40], 829);
                step(f, Op::BreakTransform, &[39, 126, 28, 127], 830);
                step(f, Op::MakeVector, &[487, 487, 42, 128], 831);
                step(f, Op::AddV, &[126, 128, 129], 832);
                step(f, Op::SubV, &[126, 128, 130], 833);
                step(f, Op::LineTrace, &[129, 130, 41, 131, 132, 283], 834);
                step(f, Op::RotateVector, &[28, 308, 133], 835);
                step(f, Op::FindQuatBetween, &[133, 132, 29], 836);
                step(f, Op::MulQ, &[29, 28, 30], 837);
                step(f, Op::MulF, &[40, 39, 284], 838);
                step(f, Op::AddF, &[284, 48, 285], 839);
                step(f, Op::NegF, &[285, 286], 840);
                step(f, Op::MakeVector, &[487, 286, 487, 134], 841);
                step(f, Op::RotateVector, &[30, 134, 136], 842);
                step(f, Op::AddV, &[131, 136, 138], 843);
                step(f, Op::AddV, &[138, 128, 140], 844);
                step(f, Op::SubV, &[138, 128, 141], 845);
                step(f, Op::LineTrace, &[140, 141, 42, 144, 145, 288], 846);
                step(f, Op::BreakVector, &[144, 290, 291, 292], 847);
                step(f, Op::BreakVector, &[138, 296, 297, 298], 848);
                step(f, Op::SubF, &[292, 298, 302], 849);
                step(f, Op::Select(ValueType::Float), &[42, 302, 487, 304], 850);
                step(f, Op::AddF, &[44, 48, 287], 851);
                step(f, Op::MakeVector, &[487, 287, 487, 135], 852);
                step(f, Op::RotateVector, &[30, 135, 137], 853);
                step(f, Op::AddV, &[131, 137, 139], 854);
                step(f, Op::AddV, &[139, 128, 142], 855);
                step(f, Op::SubV, &[139, 128, 143], 856);
                step(f, Op::LineTrace, &[142, 143, 43, 146, 147, 289], 857);
                step(f, Op::BreakVector, &[146, 293, 294, 295], 858);
                step(f, Op::BreakVector, &[139, 299, 300, 301], 859);
                step(f, Op::SubF, &[295, 301, 303], 860);
                step(f, Op::Select(ValueType::Float), &[43, 303, 487, 305], 861);
                step(f, Op::MaxF, &[304, 305, 306], 862);
                step(f, Op::ClampF, &[306, 487, 47, 307], 863);
                step(f, Op::MakeVector, &[487, 487, 307, 148], 864);
                step(f, Op::AddV, &[131, 148, 149], 865);
                step(f, Op::MakeTransform, &[149, 30, 306, 41], 866);
                step(f, Op::Select(ValueType::Transform), &[41, 41, 39, 42], 867);
                step(f, Op::Copy(ValueType::Transform), &[42, 40], 868);
                step(f, Op::Jump, &[869], 869)
            }
            869 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 40, 40], 870);
                step(f, Op::Jump, &[930], 871)
            }
            871 => {
                step(f, Op::ArrayAt(Elem::Transform), &[2, 40, 43], 872);
                step(f, Op::MakeAbsolute, &[43, 2, 44], 873);
                step(f, Op::BreakTransform, &[44, 150, 31, 151], 874);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 40, 31], 875);
                step(f, Op::BreakTransform, &[31, 95, 23, 96], 876);
                step(f, Op::ArrayAt(Elem::Float), &[2, 40, 251], 877);
                step(f, Op::SubF, &[489, 251, 253], 878);
                step(f, Op::MulF, &[4, 2, 254], 879);
                step(f, Op::MulF, &[253, 254, 255], 880);
                step(f, Op::ScaleV, &[0, 255, 97], 881);
                step(f, Op::AddV, &[95, 97, 98], 882);
                step(f, Op::ClampF, &[251, 487, 489, 335], 883);
                step(f, Op::SubF, &[489, 335, 308], 884);
                step(f, Op::MulF, &[63, 308, 309], 885);
                step(f, Op::VectorLerp, &[150, 98, 309, 487, 152], 886);
                step(f, Op::MakeTransform, &[152, 23, 306, 45], 887);
                step(f, Op::Copy(ValueType::Transform), &[45, 46], 888);
                step(f, Op::Copy(ValueType::Transform), &[96, 47], 889);
                step(f, Op::BreakTransform, &[46, 153, 32, 154], 890);
                step(f, Op::MakeVector, &[487, 487, 42, 155], 891);
                step(f, Op::AddV, &[153, 155, 156], 892);
                step(f, Op::SubV, &[153, 155, 157], 893);
                step(f, Op::LineTrace, &[156, 157, 44, 158, 159, 310], 894);
                step(f, Op::RotateVector, &[32, 308, 160], 895);
                step(f, Op::FindQuatBetween, &[160, 159, 33], 896);
                step(f, Op::MulQ, &[33, 32, 34], 897);
                step(f, Op::MulF, &[40, 39, 311], 898);
                step(f, Op::AddF, &[311, 48, 312], 899);
                step(f, Op::NegF, &[312, 313], 900);
                step(f, Op::MakeVector, &[487, 313, 487, 161], 901);
                step(f, Op::RotateVector, &[34, 161, 163], 902);
                step(f, Op::AddV, &[158, 163, 165], 903);
                step(f, Op::AddV, &[165, 155, 167], 904);
                step(f, Op::SubV, &[165, 155, 168], 905);
                step(f, Op::LineTrace, &[167, 168, 45, 171, 172, 315], 906);
                step(f, Op::BreakVector, &[171, 317, 318, 319], 907);
                step(f, Op::BreakVector, &[165, 323, 324, 325], 908);
                step(f, Op::SubF, &[319, 325, 329], 909);
                step(f, Op::Select(ValueType::Float), &[45, 329, 487, 331], 910);
                step(f, Op::AddF, &[44, 48, 314], 911);
                step(f, Op::MakeVector, &[487, 314, 487, 162], 912);
                step(f, Op::RotateVector, &[34, 162, 164], 913);
                step(f, Op::AddV, &[158, 164, 166], 914);
                step(f, Op::AddV, &[166, 155, 169], 915);
                step(f, Op::SubV, &[166, 155, 170], 916);
                step(f, Op::LineTrace, &[169, 170, 46, 173, 174, 316], 917);
                step(f, Op::BreakVector, &[173, 320, 321, 322], 918);
                step(f, Op::BreakVector, &[166, 326, 327, 328], 919);
                step(f, Op::SubF, &[322, 328, 330], 920);
                step(f, Op::Select(ValueType::Float), &[46, 330, 487, 332], 921);
                step(f, Op::MaxF, &[331, 332, 333], 922);
                step(f, Op::ClampF, &[333, 487, 47, 334], 923);
                step(f, Op::MakeVector, &[487, 487, 334, 175], 924);
                step(f, Op::AddV, &[158, 175, 176], 925);
                step(f, Op::MakeTransform, &[176, 34, 306, 48], 926);
                step(f, Op::Select(ValueType::Transform), &[44, 48, 46, 49], 927);
                step(f, Op::Copy(ValueType::Transform), &[49, 47], 928);
                step(f, Op::Jump, &[929], 929)
            }
            929 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 40, 47], 930);
                930
            }
            930 => {
                step(f, Op::ArrayAt(Elem::Float), &[2, 40, 251], 931);
                step(f, Op::GreaterEqualF, &[251, 489, 36], 932);
                step(f, Op::JumpIfFalse, &[36, 992], 933)
            }
            933 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 40, 35], 934);
                step(f, Op::JumpIfFalse, &[35, 936], 935)
            }
            935 => {
                step(f, Op::Jump, &[989], 936)
            }
            936 => {
                step(f, Op::ArrayAt(Elem::Transform), &[2, 40, 50], 937);
                step(f, Op::BreakTransform, &[50, 177, 35, 178], 938);
                step(f, Op::Equals(Elem::Int), &[40, 52, 37], 939);
                step(f, Op::Select(ValueType::Int), &[37, 53, 52, 41], 940);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 41, 32], 941);
                step(f, Op::BreakTransform, &[32, 99, 24, 100], 942);
                step(f, Op::SubF, &[489, 9, 256], 943);
                step(f, Op::MulF, &[8, 256, 257], 944);
                step(f, Op::FootAvoidance, &[177, 99, 257, 37, 64, 101], 945);
                step(f, Op::MakeTransform, &[101, 35, 306, 33], 946);
                step(f, Op::Copy(ValueType::Transform), &[33, 34], 947);
                step(f, Op::Copy(ValueType::Transform), &[96, 35], 948);
                step(f, Op::BreakTransform, &[34, 102, 25, 103], 949);
                step(f, Op::MakeVector, &[487, 487, 42, 104], 950);
                step(f, Op::AddV, &[102, 104, 105], 951);
                step(f, Op::SubV, &[102, 104, 106], 952);
                step(f, Op::LineTrace, &[105, 106, 38, 107, 108, 258], 953);
                step(f, Op::RotateVector, &[25, 308, 109], 954);
                step(f, Op::FindQuatBetween, &[109, 108, 26], 955);
                step(f, Op::MulQ, &[26, 25, 27], 956);
                step(f, Op::MulF, &[40, 39, 259], 957);
                step(f, Op::AddF, &[259, 48, 260], 958);
                step(f, Op::NegF, &[260, 261], 959);
                step(f, Op::MakeVector, &[487, 261, 487, 110], 960);
                step(f, Op::RotateVector, &[27, 110, 112], 961);
                step(f, Op::AddV, &[107, 112, 114], 962);
                step(f, Op::AddV, &[114, 104, 116], 963);
                step(f, Op::SubV, &[114, 104, 117], 964);
                step(f, Op::LineTrace, &[116, 117, 39, 120, 121, 263], 965);
                step(f, Op::BreakVector, &[120, 265, 266, 267], 966);
                step(f, Op::BreakVector, &[114, 271, 272, 273], 967);
                step(f, Op::SubF, &[267, 273, 277], 968);
                step(f, Op::Select(ValueType::Float), &[39, 277, 487, 279], 969);
                step(f, Op::AddF, &[44, 48, 262], 970);
                step(f, Op::MakeVector, &[487, 262, 487, 111], 971);
                step(f, Op::RotateVector, &[27, 111, 113], 972);
                step(f, Op::AddV, &[107, 113, 115], 973);
                step(f, Op::AddV, &[115, 104, 118], 974);
                step(f, Op::SubV, &[115, 104, 119], 975);
                step(f, Op::LineTrace, &[118, 119, 40, 122, 123, 264], 976);
                step(f, Op::BreakVector, &[122, 268, 269, 270], 977);
                step(f, Op::BreakVector, &[115, 274, 275, 276], 978);
                step(f, Op::SubF, &[270, 276, 278], 979);
                step(f, Op::Select(ValueType::Float), &[40, 278, 487, 280], 980);
                step(f, Op::MaxF, &[279, 280, 281], 981);
                step(f, Op::ClampF, &[281, 487, 47, 282], 982);
                step(f, Op::MakeVector, &[487, 487, 282, 124], 983);
                step(f, Op::AddV, &[107, 124, 125], 984);
                step(f, Op::MakeTransform, &[125, 27, 306, 36], 985);
                step(f, Op::Select(ValueType::Transform), &[38, 36, 34, 37], 986);
                step(f, Op::Copy(ValueType::Transform), &[37, 35], 987);
                step(f, Op::Jump, &[988], 988)
            }
            988 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 40, 35], 989);
                989
            }
            989 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 40, 30], 990);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 40, 30], 991);
                step(f, Op::Jump, &[1166], 992)
            }
            992 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 40, 30], 993);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 40, 50], 994);
                step(f, Op::ClampF, &[251, 487, 489, 335], 995);
                step(f, Op::Copy(ValueType::Transform), &[30, 52], 996);
                step(f, Op::Copy(ValueType::Transform), &[50, 53], 997);
                step(f, Op::Copy(ValueType::Float), &[335, 345], 998);
                step(f, Op::Copy(ValueType::Transform), &[96, 54], 999);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[3, 2], 1000);
                step(f, Op::ArrayReset(Elem::Vec3), &[2], 1001);
                step(f, Op::BreakTransform, &[52, 186, 37, 187], 1002);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 186], 1003);
                step(f, Op::BreakTransform, &[52, 186, 37, 187], 1004);
                step(f, Op::UnitV, &[0, 185], 1005);
                step(f, Op::LengthV, &[0, 346], 1006);
                step(f, Op::RemapF, &[346, 487, 50, 487, 51, 59, 347], 1007);
                step(f, Op::ScaleV, &[185, 347, 190], 1008);
                step(f, Op::SubV, &[186, 190, 196], 1009);
                step(f, Op::MakeVector, &[487, 487, 53, 194], 1010);
                step(f, Op::AddV, &[196, 194, 198], 1011);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 198], 1012);
                step(f, Op::BreakTransform, &[52, 186, 37, 187], 1013);
                step(f, Op::UnitV, &[0, 185], 1014);
                step(f, Op::LengthV, &[0, 346], 1015);
                step(f, Op::RemapF, &[346, 487, 50, 487, 51, 59, 347], 1016);
                step(f, Op::ScaleV, &[185, 347, 190], 1017);
                step(f, Op::SubV, &[186, 190, 196], 1018);
                step(f, Op::MakeVector, &[487, 487, 53, 194], 1019);
                step(f, Op::AddV, &[196, 194, 198], 1020);
                step(f, Op::RemapF, &[346, 487, 50, 487, 55, 59, 349], 1021);
                step(f, Op::MakeVector, &[487, 487, 349, 192], 1022);
                step(f, Op::AddV, &[198, 192, 202], 1023);
                step(f, Op::BreakTransform, &[53, 188, 38, 189], 1024);
                step(f, Op::BreakVector, &[188, 354, 355, 356], 1025);
                step(f, Op::BreakVector, &[186, 351, 352, 353], 1026);
                step(f, Op::SubF, &[356, 353, 357], 1027);
                step(f, Op::MaxF, &[357, 487, 359], 1028);
                step(f, Op::MulF, &[359, 57, 363], 1029);
                step(f, Op::AbsF, &[357, 361], 1030);
                step(f, Op::RemapF, &[361, 487, 60, 487, 59, 59, 362], 1031);
                step(f, Op::AddF, &[363, 362, 365], 1032);
                step(f, Op::MakeVector, &[487, 487, 365, 200], 1033);
                step(f, Op::AddV, &[202, 200, 204], 1034);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 204], 1035);
                step(f, Op::BreakTransform, &[52, 186, 37, 187], 1036);
                step(f, Op::UnitV, &[0, 185], 1037);
                step(f, Op::LengthV, &[0, 346], 1038);
                step(f, Op::RemapF, &[346, 487, 50, 487, 51, 59, 347], 1039);
                step(f, Op::ScaleV, &[185, 347, 190], 1040);
                step(f, Op::SubV, &[186, 190, 196], 1041);
                step(f, Op::MakeVector, &[487, 487, 53, 194], 1042);
                step(f, Op::AddV, &[196, 194, 198], 1043);
                step(f, Op::RemapF, &[346, 487, 50, 487, 55, 59, 349], 1044);
                step(f, Op::MakeVector, &[487, 487, 349, 192], 1045);
                step(f, Op::AddV, &[198, 192, 202], 1046);
                step(f, Op::BreakTransform, &[53, 188, 38, 189], 1047);
                step(f, Op::BreakVector, &[188, 354, 355, 356], 1048);
                step(f, Op::BreakVector, &[186, 351, 352, 353], 1049);
                step(f, Op::SubF, &[356, 353, 357], 1050);
                step(f, Op::MaxF, &[357, 487, 359], 1051);
                step(f, Op::MulF, &[359, 57, 363], 1052);
                step(f, Op::AbsF, &[357, 361], 1053);
                step(f, Op::RemapF, &[361, 487, 60, 487, 59, 59, 362], 1054);
                step(f, Op::AddF, &[363, 362, 365], 1055);
                step(f, Op::MakeVector, &[487, 487, 365, 200], 1056);
                step(f, Op::AddV, &[202, 200, 204], 1057);
                step(f, Op::RemapF, &[346, 487, 50, 487, 52, 59, 348], 1058);
                step(f, Op::ScaleV, &[185, 348, 191], 1059);
                step(f, Op::AddV, &[188, 191, 197], 1060);
                step(f, Op::MakeVector, &[487, 487, 54, 195], 1061);
                step(f, Op::AddV, &[197, 195, 199], 1062);
                step(f, Op::RemapF, &[346, 487, 50, 487, 56, 59, 350], 1063);
                step(f, Op::MakeVector, &[487, 487, 350, 193], 1064);
                step(f, Op::AddV, &[199, 193, 203], 1065);
                step(f, Op::NegF, &[357, 358], 1066);
                step(f, Op::MaxF, &[358, 487, 360], 1067);
                step(f, Op::MulF, &[360, 58, 364], 1068);
                step(f, Op::AddF, &[364, 362, 366], 1069);
                step(f, Op::MakeVector, &[487, 487, 366, 201], 1070);
                step(f, Op::AddV, &[203, 201, 205], 1071);
                step(f, Op::LerpV, &[204, 205, 488, 206], 1072);
                step(f, Op::GetTransform, &[36, 52, 59, 55], 1073);
                step(f, Op::BreakTransform, &[55, 207, 39, 208], 1074);
                step(f, Op::BreakVector, &[207, 376, 377, 378], 1075);
                step(f, Op::SubF, &[489, 9, 370], 1076);
                step(f, Op::MulF, &[61, 370, 371], 1077);
                step(f, Op::MulF, &[8, 371, 372], 1078);
                step(f, Op::QuatFromAxisAngle, &[308, 372, 40], 1079);
                step(f, Op::SubV, &[206, 207, 209], 1080);
                step(f, Op::BreakVector, &[209, 367, 368, 369], 1081);
                step(f, Op::MakeVector, &[367, 368, 487, 210], 1082);
                step(f, Op::RotateVector, &[40, 210, 211], 1083);
                step(f, Op::BreakVector, &[211, 373, 374, 375], 1084);
                step(f, Op::AddF, &[376, 373, 382], 1085);
                step(f, Op::AddF, &[377, 374, 383], 1086);
                step(f, Op::BreakVector, &[206, 379, 380, 381], 1087);
                step(f, Op::MakeVector, &[382, 383, 381, 212], 1088);
                step(f, Op::DistanceV, &[186, 188, 384], 1089);
                step(f, Op::RemapF, &[384, 491, 498, 487, 489, 59, 385], 1090);
                step(f, Op::LerpV, &[206, 212, 385, 213], 1091);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 213], 1092);
                step(f, Op::BreakTransform, &[53, 188, 38, 189], 1093);
                step(f, Op::UnitV, &[0, 185], 1094);
                step(f, Op::LengthV, &[0, 346], 1095);
                step(f, Op::RemapF, &[346, 487, 50, 487, 52, 59, 348], 1096);
                step(f, Op::ScaleV, &[185, 348, 191], 1097);
                step(f, Op::AddV, &[188, 191, 197], 1098);
                step(f, Op::MakeVector, &[487, 487, 54, 195], 1099);
                step(f, Op::AddV, &[197, 195, 199], 1100);
                step(f, Op::RemapF, &[346, 487, 50, 487, 56, 59, 350], 1101);
                step(f, Op::MakeVector, &[487, 487, 350, 193], 1102);
                step(f, Op::AddV, &[199, 193, 203], 1103);
                step(f, Op::BreakVector, &[188, 354, 355, 356], 1104);
                step(f, Op::BreakTransform, &[52, 186, 37, 187], 1105);
                step(f, Op::BreakVector, &[186, 351, 352, 353], 1106);
                step(f, Op::SubF, &[356, 353, 357], 1107);
                step(f, Op::NegF, &[357, 358], 1108);
                step(f, Op::MaxF, &[358, 487, 360], 1109);
                step(f, Op::MulF, &[360, 58, 364], 1110);
                step(f, Op::AbsF, &[357, 361], 1111);
                step(f, Op::RemapF, &[361, 487, 60, 487, 59, 59, 362], 1112);
                step(f, Op::AddF, &[364, 362, 366], 1113);
                step(f, Op::MakeVector, &[487, 487, 366, 201], 1114);
                step(f, Op::AddV, &[203, 201, 205], 1115);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 205], 1116);
                step(f, Op::BreakTransform, &[53, 188, 38, 189], 1117);
                step(f, Op::UnitV, &[0, 185], 1118);
                step(f, Op::LengthV, &[0, 346], 1119);
                step(f, Op::RemapF, &[346, 487, 50, 487, 52, 59, 348], 1120);
                step(f, Op::ScaleV, &[185, 348, 191], 1121);
                step(f, Op::AddV, &[188, 191, 197], 1122);
                step(f, Op::MakeVector, &[487, 487, 54, 195], 1123);
                step(f, Op::AddV, &[197, 195, 199], 1124);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 199], 1125);
                step(f, Op::BreakTransform, &[53, 188, 38, 189], 1126);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 188], 1127);
                step(f, Op::JumpIfFalse, &[5, 1130], 1128)
            }
            1128 => {
                step(f, Op::DrawSpline, &[2, 52, 55, 488, 310], 1129);
                step(f, Op::Jump, &[1130], 1130)
            }
            1130 => {
                step(f, Op::Spline, &[2, 345, 52, 214, 215], 1131);
                step(f, Op::BreakTransform, &[52, 186, 37, 187], 1132);
                step(f, Op::BreakTransform, &[53, 188, 38, 189], 1133);
                step(f, Op::SlerpQ, &[37, 38, 345, 41], 1134);
                step(f, Op::MulF, &[345, 499, 386], 1135);
                step(f, Op::SinF, &[386, 387], 1136);
                step(f, Op::MulF, &[387, 62, 388], 1137);
                step(f, Op::SlerpQ, &[41, 81, 388, 42], 1138);
                step(f, Op::MakeTransform, &[214, 42, 306, 56], 1139);
                step(f, Op::Copy(ValueType::Transform), &[56, 54], 1140);
                step(f, Op::Jump, &[1141], 1141)
            }
            1141 => {
                step(f, Op::BreakTransform, &[54, 179, 36, 180], 1142);
                step(f, Op::Equals(Elem::Int), &[40, 52, 37], 1143);
                step(f, Op::Select(ValueType::Int), &[37, 53, 52, 41], 1144);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 41, 32], 1145);
                step(f, Op::BreakTransform, &[32, 99, 24, 100], 1146);
                step(f, Op::SubF, &[489, 9, 256], 1147);
                step(f, Op::MulF, &[8, 256, 257], 1148);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 41, 47], 1149);
                step(f, Op::Select(ValueType::Float), &[47, 65, 487, 338], 1150);
                step(f, Op::ArrayAt(Elem::Float), &[2, 40, 251], 1151);
                step(f, Op::ClampF, &[251, 487, 489, 335], 1152);
                step(f, Op::MulF, &[335, 499, 336], 1153);
                step(f, Op::SinF, &[336, 337], 1154);
                step(f, Op::MulF, &[337, 337, 339], 1155);
                step(f, Op::MulF, &[338, 339, 340], 1156);
                step(f, Op::AddF, &[64, 340, 341], 1157);
                step(f, Op::FootAvoidance, &[179, 99, 257, 37, 341, 181], 1158);
                step(f, Op::SubV, &[181, 179, 182], 1159);
                step(f, Op::LengthV, &[182, 342], 1160);
                step(f, Op::AddF, &[342, 340, 343], 1161);
                step(f, Op::DivF, &[342, 343, 344], 1162);
                step(f, Op::ScaleV, &[182, 344, 183], 1163);
                step(f, Op::AddV, &[179, 183, 184], 1164);
                step(f, Op::MakeTransform, &[184, 36, 306, 51], 1165);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 40, 51], 1166);
                1166
            }
            1166 => {
                step(f, Op::ArrayAt(Elem::Float), &[2, 40, 251], 1167);
                step(f, Op::GreaterEqualF, &[251, 489, 36], 1168);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 40, 36], 1169);
                step(f, Op::Copy(ValueType::Bone), &[0, 17], 1170);
                step(f, Op::Copy(ValueType::Int), &[2, 42], 1171);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 42, 57], 1172);
                step(f, Op::BreakTransform, &[57, 216, 43, 217], 1173);
                step(f, Op::MakeVector, &[487, 487, 37, 226], 1174);
                step(f, Op::AddV, &[216, 226, 227], 1175);
                step(f, Op::GetTransform, &[17, 52, 59, 59], 1176);
                step(f, Op::BreakTransform, &[59, 221, 45, 222], 1177);
                step(f, Op::MakeTransform, &[227, 45, 306, 61], 1178);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 42, 20], 1179);
                step(f, Op::GetTransform, &[20, 52, 59, 60], 1180);
                step(f, Op::BreakTransform, &[60, 223, 46, 224], 1181);
                step(f, Op::SubV, &[223, 221, 225], 1182);
                step(f, Op::AddV, &[227, 225, 228], 1183);
                step(f, Op::FootPivots, &[227, 228, 39, 38, 37, 40, 229, 230, 231], 1184);
                step(f, Op::GetParent, &[17, 18], 1185);
                step(f, Op::GetParent, &[18, 19], 1186);
                step(f, Op::GetTransform, &[19, 52, 60, 58], 1187);
                step(f, Op::BreakTransform, &[58, 218, 44, 219], 1188);
                step(f, Op::SubV, &[216, 218, 220], 1189);
                step(f, Op::DotV, &[220, 309, 389], 1190);
                step(f, Op::RemapF, &[389, 67, 66, 68, 487, 59, 392], 1191);
                step(f, Op::LengthV, &[0, 390], 1192);
                step(f, Op::RemapF, &[390, 487, 74, 487, 489, 59, 391], 1193);
                step(f, Op::MulF, &[392, 391, 393], 1194);
                step(f, Op::QuatFromAxisAngle, &[311, 393, 47], 1195);
                step(f, Op::RotateAroundPoint, &[61, 229, 47, 62], 1196);
                step(f, Op::SubV, &[230, 229, 232], 1197);
                step(f, Op::RotateVector, &[47, 232, 233], 1198);
                step(f, Op::AddV, &[229, 233, 234], 1199);
                step(f, Op::RemapF, &[389, 69, 67, 70, 487, 59, 394], 1200);
                step(f, Op::MulF, &[394, 391, 395], 1201);
                step(f, Op::QuatFromAxisAngle, &[311, 395, 48], 1202);
                step(f, Op::RotateAroundPoint, &[62, 234, 48, 63], 1203);
                step(f, Op::RemapF, &[389, 71, 72, 487, 73, 59, 396], 1204);
                step(f, Op::MulF, &[396, 391, 397], 1205);
                step(f, Op::QuatFromAxisAngle, &[311, 397, 49], 1206);
                step(f, Op::RotateAroundPoint, &[63, 231, 49, 64], 1207);
                step(f, Op::SubF, &[489, 9, 398], 1208);
                step(f, Op::MulF, &[8, 398, 399], 1209);
                step(f, Op::LimitRotationAroundZ, &[43, 399, 75, 50], 1210);
                step(f, Op::RotateAroundPoint, &[64, 216, 50, 65], 1211);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 42, 65], 1212);
                step(f, Op::JumpIfFalse, &[5, 1269], 1213)
            }
            1213 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 42, 57], 1214);
                step(f, Op::BreakTransform, &[57, 216, 43, 217], 1215);
                step(f, Op::MakeVector, &[487, 487, 37, 226], 1216);
                step(f, Op::AddV, &[216, 226, 227], 1217);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 42, 20], 1218);
                step(f, Op::GetTransform, &[20, 52, 59, 60], 1219);
                step(f, Op::BreakTransform, &[60, 223, 46, 224], 1220);
                step(f, Op::GetTransform, &[17, 52, 59, 59], 1221);
                step(f, Op::BreakTransform, &[59, 221, 45, 222], 1222);
                step(f, Op::SubV, &[223, 221, 225], 1223);
                step(f, Op::AddV, &[227, 225, 228], 1224);
                step(f, Op::FootPivots, &[227, 228, 39, 38, 37, 40, 229, 230, 231], 1225);
                step(f, Op::DrawPoint, &[231, 500, 311], 1226);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 42, 57], 1227);
                step(f, Op::BreakTransform, &[57, 216, 43, 217], 1228);
                step(f, Op::MakeVector, &[487, 487, 37, 226], 1229);
                step(f, Op::AddV, &[216, 226, 227], 1230);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 42, 20], 1231);
                step(f, Op::GetTransform, &[20, 52, 59, 60], 1232);
                step(f, Op::BreakTransform, &[60, 223, 46, 224], 1233);
                step(f, Op::GetTransform, &[17, 52, 59, 59], 1234);
                step(f, Op::BreakTransform, &[59, 221, 45, 222], 1235);
                step(f, Op::SubV, &[223, 221, 225], 1236);
                step(f, Op::AddV, &[227, 225, 228], 1237);
                step(f, Op::FootPivots, &[227, 228, 39, 38, 37, 40, 229, 230, 231], 1238);
                step(f, Op::DrawPoint, &[229, 500, 309], 1239);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 42, 57], 1240);
                step(f, Op::BreakTransform, &[57, 216, 43, 217], 1241);
                step(f, Op::MakeVector, &[487, 487, 37, 226], 1242);
                step(f, Op::AddV, &[216, 226, 227], 1243);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 42, 20], 1244);
                step(f, Op::GetTransform, &[20, 52, 59, 60], 1245);
                step(f, Op::BreakTransform, &[60, 223, 46, 224], 1246);
                step(f, Op::GetTransform, &[17, 52, 59, 59], 1247);
                step(f, Op::BreakTransform, &[59, 221, 45, 222], 1248);
                step(f, Op::SubV, &[223, 221, 225], 1249);
                step(f, Op::AddV, &[227, 225, 228], 1250);
                step(f, Op::FootPivots, &[227, 228, 39, 38, 37, 40, 229, 230, 231], 1251);
                step(f, Op::GetParent, &[17, 18], 1252);
                step(f, Op::GetParent, &[18, 19], 1253);
                step(f, Op::GetTransform, &[19, 52, 60, 58], 1254);
                step(f, Op::BreakTransform, &[58, 218, 44, 219], 1255);
                step(f, Op::SubV, &[216, 218, 220], 1256);
                step(f, Op::DotV, &[220, 309, 389], 1257);
                step(f, Op::RemapF, &[389, 67, 66, 68, 487, 59, 392], 1258);
                step(f, Op::LengthV, &[0, 390], 1259);
                step(f, Op::RemapF, &[390, 487, 74, 487, 489, 59, 391], 1260);
                step(f, Op::MulF, &[392, 391, 393], 1261);
                step(f, Op::QuatFromAxisAngle, &[311, 393, 47], 1262);
                step(f, Op::SubV, &[230, 229, 232], 1263);
                step(f, Op::RotateVector, &[47, 232, 233], 1264);
                step(f, Op::AddV, &[229, 233, 234], 1265);
                step(f, Op::DrawPoint, &[234, 500, 308], 1266);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 42, 57], 1267);
                step(f, Op::DrawTransform, &[57, 498, 488], 1268);
                step(f, Op::Jump, &[1269], 1269)
            }
            1269 => {
                step(f, Op::Jump, &[681], 1270)
            }
            1270 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1271);
                step(f, Op::Copy(ValueType::Int), &[52, 4], 1272);
                1272
            }
            1272 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 4, 1, 5, 6, 1327], 1273)
            }
            1273 => {
                step(f, Op::Copy(ValueType::Bone), &[1, 21], 1274);
                step(f, Op::Copy(ValueType::Int), &[5, 43], 1275);
                step(f, Op::GetParent, &[21, 22], 1276);
                step(f, Op::GetParent, &[22, 23], 1277);
                step(f, Op::GetParent, &[23, 24], 1278);
                step(f, Op::GetTransform, &[24, 52, 60, 66], 1279);
                step(f, Op::BreakTransform, &[66, 235, 51, 236], 1280);
                step(f, Op::LengthV, &[1, 401], 1281);
                step(f, Op::ClavicleOffset, &[6, 401, 80, 83, 402], 1282);
                step(f, Op::MakeVector, &[487, 487, 402, 237], 1283);
                step(f, Op::AddV, &[235, 237, 238], 1284);
                step(f, Op::MakeTransform, &[238, 51, 306, 67], 1285);
                step(f, Op::SetTransform, &[24, 67, 52, 59, 489], 1286);
                step(f, Op::GetParent, &[21, 22], 1287);
                step(f, Op::GetParent, &[22, 23], 1288);
                step(f, Op::GetTransform, &[21, 52, 60, 68], 1289);
                step(f, Op::GetTransform, &[23, 52, 60, 69], 1290);
                step(f, Op::BreakTransform, &[69, 239, 53, 240], 1291);
                step(f, Op::Equals(Elem::Int), &[43, 52, 48], 1292);
                step(f, Op::Select(ValueType::Int), &[48, 53, 52, 44], 1293);
                step(f, Op::ArrayAt(Elem::Float), &[0, 44, 400], 1294);
                step(f, Op::ArmSwingRotation, &[400, 1, 0, 81, 493, 501, 489, 80, 78, 79, 493, 493, 489, 403], 1295);
                step(f, Op::QuatFromAxisAngle, &[311, 403, 52], 1296);
                step(f, Op::RotateAroundPoint, &[68, 239, 52, 70], 1297);
                step(f, Op::BreakTransform, &[70, 241, 54, 242], 1298);
                step(f, Op::LengthV, &[1, 401], 1299);
                step(f, Op::RemapF, &[401, 487, 80, 487, 82, 59, 404], 1300);
                step(f, Op::MakeVector, &[487, 487, 404, 243], 1301);
                step(f, Op::AddV, &[241, 243, 244], 1302);
                step(f, Op::MakeTransform, &[244, 54, 306, 71], 1303);
                step(f, Op::Select(ValueType::Vec3), &[48, 312, 311, 246], 1304);
                step(f, Op::Select(ValueType::Vec3), &[48, 309, 313, 247], 1305);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 43, 245], 1306);
                step(f, Op::TwoBoneIK, &[23, 22, 21, 71, 246, 247, 245, 52, 489, 60, 502, 503, 59, 49, 405], 1307);
                step(f, Op::JumpIfFalse, &[5, 1326], 1308)
            }
            1308 => {
                step(f, Op::GetParent, &[21, 22], 1309);
                step(f, Op::GetParent, &[22, 23], 1310);
                step(f, Op::GetTransform, &[23, 52, 60, 69], 1311);
                step(f, Op::BreakTransform, &[69, 239, 53, 240], 1312);
                step(f, Op::GetTransform, &[21, 52, 60, 68], 1313);
                step(f, Op::Equals(Elem::Int), &[43, 52, 48], 1314);
                step(f, Op::Select(ValueType::Int), &[48, 53, 52, 44], 1315);
                step(f, Op::ArrayAt(Elem::Float), &[0, 44, 400], 1316);
                step(f, Op::ArmSwingRotation, &[400, 1, 0, 81, 493, 501, 489, 80, 78, 79, 493, 493, 489, 403], 1317);
                step(f, Op::QuatFromAxisAngle, &[311, 403, 52], 1318);
                step(f, Op::RotateAroundPoint, &[68, 239, 52, 70], 1319);
                step(f, Op::BreakTransform, &[70, 241, 54, 242], 1320);
                step(f, Op::LengthV, &[1, 401], 1321);
                step(f, Op::RemapF, &[401, 487, 80, 487, 82, 59, 404], 1322);
                step(f, Op::MakeVector, &[487, 487, 404, 243], 1323);
                step(f, Op::AddV, &[241, 243, 244], 1324);
                step(f, Op::DrawLine, &[239, 244, 488, 309], 1325);
                step(f, Op::Jump, &[1326], 1326)
            }
            1326 => {
                step(f, Op::Jump, &[1272], 1327)
            }
            1327 => {
                step(f, Op::Copy(ValueType::Float), &[487, 407], 1328);
                step(f, Op::Copy(ValueType::Float), &[495, 408], 1329);
                step(f, Op::Copy(ValueType::Bool), &[60, 50], 1330);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[3, 6], 1331);
                step(f, Op::Copy(ValueType::Int), &[52, 45], 1332);
                step(f, Op::MakeVector, &[487, 487, 42, 250], 1333);
                1333
            }
            1333 => {
                step(f, Op::ForEachNext(Elem::Transform), &[6, 45, 72, 46, 47, 1346], 1334)
            }
            1334 => {
                step(f, Op::BreakTransform, &[72, 248, 55, 249], 1335);
                step(f, Op::AddV, &[248, 250, 251], 1336);
                step(f, Op::SubV, &[248, 250, 252], 1337);
                step(f, Op::SphereTrace, &[251, 252, 41, 51, 253, 254, 409], 1338);
                step(f, Op::BreakVector, &[253, 410, 411, 412], 1339);
                step(f, Op::LessF, &[412, 408, 52], 1340);
                step(f, Op::And, &[51, 52, 53], 1341);
                step(f, Op::JumpIfFalse, &[53, 1345], 1342)
            }
            1342 => {
                step(f, Op::Copy(ValueType::Float), &[412, 408], 1343);
                step(f, Op::Copy(ValueType::Bool), &[59, 50], 1344);
                step(f, Op::Jump, &[1345], 1345)
            }
            1345 => {
                step(f, Op::Jump, &[1333], 1346)
            }
            1346 => {
                step(f, Op::Select(ValueType::Float), &[50, 408, 487, 413], 1347);
                step(f, Op::ClampF, &[413, 45, 46, 414], 1348);
                step(f, Op::Copy(ValueType::Float), &[414, 407], 1349);
                step(f, Op::Jump, &[1350], 1350)
            }
            1350 => {
                step(f, Op::FloatLerp, &[10, 407, 36, 415], 1351);
                step(f, Op::Select(ValueType::Float), &[1, 407, 415, 416], 1352);
                step(f, Op::Copy(ValueType::Float), &[416, 10], 1353);
                step(f, Op::GetTransform, &[37, 52, 59, 77], 1354);
                step(f, Op::BreakTransform, &[77, 267, 62, 268], 1355);
                step(f, Op::PelvisLean, &[1, 85, 90, 91, 429, 430], 1356);
                step(f, Op::LengthV, &[0, 406], 1357);
                step(f, Op::RemapF, &[406, 487, 85, 487, 84, 59, 417], 1358);
                step(f, Op::MulF, &[6, 504, 418], 1359);
                step(f, Op::SinF, &[418, 419], 1360);
                step(f, Op::MulF, &[417, 419, 420], 1361);
                step(f, Op::AddF, &[420, 10, 421], 1362);
                step(f, Op::MakeVector, &[487, 430, 421, 269], 1363);
                step(f, Op::AddV, &[267, 269, 270], 1364);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 52, 73], 1365);
                step(f, Op::BreakTransform, &[73, 255, 56, 256], 1366);
                step(f, Op::BreakVector, &[255, 431, 432, 433], 1367);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 53, 74], 1368);
                step(f, Op::BreakTransform, &[74, 257, 57, 258], 1369);
                step(f, Op::BreakVector, &[257, 434, 435, 436], 1370);
                step(f, Op::SubF, &[433, 436, 437], 1371);
                step(f, Op::PelvisSideLean, &[437, 92, 93, 438], 1372);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 52, 75], 1373);
                step(f, Op::BreakTransform, &[75, 261, 58, 262], 1374);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 53, 76], 1375);
                step(f, Op::BreakTransform, &[76, 263, 59, 264], 1376);
                step(f, Op::SlerpQ, &[58, 59, 488, 60], 1377);
                step(f, Op::EulerFromQuat, &[60, 52, 265], 1378);
                step(f, Op::BreakVector, &[265, 425, 426, 427], 1379);
                step(f, Op::RemapF, &[406, 86, 85, 487, 87, 59, 423], 1380);
                step(f, Op::SubV, &[255, 257, 259], 1381);
                step(f, Op::RotateVector, &[0, 309, 260], 1382);
                step(f, Op::DotV, &[259, 260, 422], 1383);
                step(f, Op::MulF, &[423, 422, 424], 1384);
                step(f, Op::AddF, &[427, 424, 428], 1385);
                step(f, Op::MakeVector, &[429, 438, 428, 266], 1386);
                step(f, Op::QuatFromEuler, &[266, 52, 61], 1387);
                step(f, Op::MakeTransform, &[270, 61, 306, 78], 1388);
                step(f, Op::SetTransform, &[38, 78, 52, 59, 489], 1389);
                step(f, Op::GetTransform, &[39, 53, 59, 79], 1390);
                step(f, Op::BreakTransform, &[79, 271, 66, 272], 1391);
                step(f, Op::LengthV, &[0, 406], 1392);
                step(f, Op::RemapF, &[406, 86, 85, 487, 87, 59, 423], 1393);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 52, 73], 1394);
                step(f, Op::BreakTransform, &[73, 255, 56, 256], 1395);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 53, 74], 1396);
                step(f, Op::BreakTransform, &[74, 257, 57, 258], 1397);
                step(f, Op::SubV, &[255, 257, 259], 1398);
                step(f, Op::RotateVector, &[0, 309, 260], 1399);
                step(f, Op::DotV, &[259, 260, 422], 1400);
                step(f, Op::MulF, &[423, 422, 424], 1401);
                step(f, Op::QuatFromAxisAngle, &[308, 424, 63], 1402);
                step(f, Op::DivF, &[88, 500, 439], 1403);
                step(f, Op::QuatScale, &[63, 439, 64], 1404);
                step(f, Op::MulQ, &[66, 64, 70], 1405);
                step(f, Op::MakeTransform, &[271, 70, 306, 83], 1406);
                step(f, Op::SetTransform, &[40, 83, 53, 59, 489], 1407);
                step(f, Op::GetTransform, &[41, 53, 59, 80], 1408);
                step(f, Op::BreakTransform, &[80, 273, 67, 274], 1409);
                step(f, Op::LengthV, &[0, 406], 1410);
                step(f, Op::RemapF, &[406, 86, 85, 487, 87, 59, 423], 1411);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 52, 73], 1412);
                step(f, Op::BreakTransform, &[73, 255, 56, 256], 1413);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 53, 74], 1414);
                step(f, Op::BreakTransform, &[74, 257, 57, 258], 1415);
                step(f, Op::SubV, &[255, 257, 259], 1416);
                step(f, Op::RotateVector, &[0, 309, 260], 1417);
                step(f, Op::DotV, &[259, 260, 422], 1418);
                step(f, Op::MulF, &[423, 422, 424], 1419);
                step(f, Op::QuatFromAxisAngle, &[308, 424, 63], 1420);
                step(f, Op::DivF, &[88, 500, 439], 1421);
                step(f, Op::QuatScale, &[63, 439, 64], 1422);
                step(f, Op::MulQ, &[67, 64, 71], 1423);
                step(f, Op::MakeTransform, &[273, 71, 306, 84], 1424);
                step(f, Op::SetTransform, &[42, 84, 53, 59, 489], 1425);
                step(f, Op::GetTransform, &[43, 53, 59, 81], 1426);
                step(f, Op::BreakTransform, &[81, 275, 68, 276], 1427);
                step(f, Op::LengthV, &[0, 406], 1428);
                step(f, Op::RemapF, &[406, 86, 85, 487, 87, 59, 423], 1429);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 52, 73], 1430);
                step(f, Op::BreakTransform, &[73, 255, 56, 256], 1431);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 53, 74], 1432);
                step(f, Op::BreakTransform, &[74, 257, 57, 258], 1433);
                step(f, Op::SubV, &[255, 257, 259], 1434);
                step(f, Op::RotateVector, &[0, 309, 260], 1435);
                step(f, Op::DotV, &[259, 260, 422], 1436);
                step(f, Op::MulF, &[423, 422, 424], 1437);
                step(f, Op::QuatFromAxisAngle, &[308, 424, 63], 1438);
                step(f, Op::DivF, &[88, 500, 439], 1439);
                step(f, Op::QuatScale, &[63, 439, 64], 1440);
                step(f, Op::MulQ, &[68, 64, 72], 1441);
                step(f, Op::MakeTransform, &[275, 72, 306, 85], 1442);
                step(f, Op::SetTransform, &[44, 85, 53, 59, 489], 1443);
                step(f, Op::GetTransform, &[45, 53, 59, 82], 1444);
                step(f, Op::BreakTransform, &[82, 277, 69, 278], 1445);
                step(f, Op::LengthV, &[0, 406], 1446);
                step(f, Op::RemapF, &[406, 86, 85, 487, 87, 59, 423], 1447);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 52, 73], 1448);
                step(f, Op::BreakTransform, &[73, 255, 56, 256], 1449);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 53, 74], 1450);
                step(f, Op::BreakTransform, &[74, 257, 57, 258], 1451);
                step(f, Op::SubV, &[255, 257, 259], 1452);
                step(f, Op::RotateVector, &[0, 309, 260], 1453);
                step(f, Op::DotV, &[259, 260, 422], 1454);
                step(f, Op::MulF, &[423, 422, 424], 1455);
                step(f, Op::QuatFromAxisAngle, &[308, 424, 63], 1456);
                step(f, Op::QuatScale, &[63, 89, 65], 1457);
                step(f, Op::MulQ, &[69, 65, 73], 1458);
                step(f, Op::MakeTransform, &[277, 73, 306, 86], 1459);
                step(f, Op::SetTransform, &[46, 86, 53, 59, 489], 1460);
                step(f, Op::Copy(ValueType::Float), &[487, 440], 1461);
                step(f, Op::Copy(ValueType::Float), &[487, 441], 1462);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1463);
                step(f, Op::Copy(ValueType::Int), &[52, 48], 1464);
                1464
            }
            1464 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 48, 25, 49, 50, 1494], 1465)
            }
            1465 => {
                step(f, Op::GetParent, &[25, 26], 1466);
                step(f, Op::GetParent, &[26, 27], 1467);
                step(f, Op::GetTransform, &[27, 52, 60, 87], 1468);
                step(f, Op::BreakTransform, &[87, 279, 74, 280], 1469);
                step(f, Op::BreakVector, &[279, 442, 443, 444], 1470);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 49, 88], 1471);
                step(f, Op::BreakTransform, &[88, 281, 75, 282], 1472);
                step(f, Op::BreakVector, &[281, 445, 446, 447], 1473);
                step(f, Op::ArrayAt(Elem::Float), &[1, 49, 451], 1474);
                step(f, Op::MulF, &[451, 94, 452], 1475);
                step(f, Op::MulF, &[452, 452, 453], 1476);
                step(f, Op::SubF, &[442, 445, 448], 1477);
                step(f, Op::SubF, &[443, 446, 449], 1478);
                step(f, Op::MakeVector, &[448, 449, 487, 283], 1479);
                step(f, Op::DotV, &[283, 283, 450], 1480);
                step(f, Op::SubF, &[453, 450, 454], 1481);
                step(f, Op::SqrtF, &[454, 455], 1482);
                step(f, Op::AddF, &[447, 455, 456], 1483);
                step(f, Op::SubF, &[444, 456, 457], 1484);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 49, 54], 1485);
                step(f, Op::ArrayAt(Elem::Float), &[2, 49, 458], 1486);
                step(f, Op::RemapF, &[458, 488, 489, 487, 489, 59, 459], 1487);
                step(f, Op::RemapF, &[458, 487, 97, 489, 487, 59, 460], 1488);
                step(f, Op::MaxF, &[459, 460, 461], 1489);
                step(f, Op::Select(ValueType::Float), &[54, 489, 461, 462], 1490);
                step(f, Op::MulF, &[457, 462, 463], 1491);
                step(f, Op::MaxF, &[441, 463, 464], 1492);
                step(f, Op::Copy(ValueType::Float), &[464, 441], 1493);
                step(f, Op::Jump, &[1464], 1494)
            }
            1494 => {
                step(f, Op::ClampF, &[441, 487, 95, 465], 1495);
                step(f, Op::Copy(ValueType::Float), &[465, 440], 1496);
                step(f, Op::Jump, &[1497], 1497)
            }
            1497 => {
                step(f, Op::GreaterF, &[440, 11, 55], 1498);
                step(f, Op::Select(ValueType::Float), &[55, 99, 96, 466], 1499);
                step(f, Op::FloatLerp, &[11, 440, 466, 467], 1500);
                step(f, Op::Select(ValueType::Float), &[1, 440, 467, 468], 1501);
                step(f, Op::Copy(ValueType::Float), &[468, 11], 1502);
                step(f, Op::GetTransform, &[47, 52, 60, 89], 1503);
                step(f, Op::BreakTransform, &[89, 284, 76, 285], 1504);
                step(f, Op::MakeVector, &[487, 487, 11, 286], 1505);
                step(f, Op::SubV, &[284, 286, 287], 1506);
                step(f, Op::MakeTransform, &[287, 76, 306, 90], 1507);
                step(f, Op::SetTransform, &[48, 90, 52, 59, 489], 1508);
                step(f, Op::JumpIfFalse, &[5, 1516], 1509)
            }
            1509 => {
                step(f, Op::GetTransform, &[47, 52, 60, 89], 1510);
                step(f, Op::BreakTransform, &[89, 284, 76, 285], 1511);
                step(f, Op::MakeVector, &[487, 487, 11, 286], 1512);
                step(f, Op::SubV, &[284, 286, 287], 1513);
                step(f, Op::MakeTransform, &[287, 76, 306, 90], 1514);
                step(f, Op::DrawTransform, &[90, 505, 488], 1515);
                step(f, Op::Jump, &[1516], 1516)
            }
            1516 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1517);
                step(f, Op::Copy(ValueType::Int), &[52, 7], 1518);
                1518
            }
            1518 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 7, 2, 8, 9, 1570], 1519)
            }
            1519 => {
                step(f, Op::Copy(ValueType::Bone), &[2, 28], 1520);
                step(f, Op::Copy(ValueType::Int), &[8, 51], 1521);
                step(f, Op::GetParent, &[28, 29], 1522);
                step(f, Op::GetParent, &[29, 30], 1523);
                step(f, Op::GetTransform, &[30, 52, 60, 91], 1524);
                step(f, Op::BreakTransform, &[91, 288, 77, 289], 1525);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 51, 92], 1526);
                step(f, Op::BreakTransform, &[92, 290, 78, 291], 1527);
                step(f, Op::SubV, &[290, 288, 292], 1528);
                step(f, Op::LengthV, &[292, 477], 1529);
                step(f, Op::ArrayAt(Elem::Float), &[1, 51, 469], 1530);
                step(f, Op::MulF, &[469, 100, 470], 1531);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 51, 56], 1532);
                step(f, Op::ArrayAt(Elem::Float), &[2, 51, 471], 1533);
                step(f, Op::ClampF, &[471, 487, 489, 472], 1534);
                step(f, Op::MulF, &[472, 499, 473], 1535);
                step(f, Op::SinF, &[473, 474], 1536);
                step(f, Op::MulF, &[474, 101, 475], 1537);
                step(f, Op::Select(ValueType::Float), &[56, 487, 475, 476], 1538);
                step(f, Op::SubF, &[470, 476, 478], 1539);
                step(f, Op::SubF, &[477, 478, 479], 1540);
                step(f, Op::MaxF, &[479, 487, 480], 1541);
                step(f, Op::MulF, &[480, 480, 481], 1542);
                step(f, Op::AddF, &[480, 476, 482], 1543);
                step(f, Op::DivF, &[481, 482, 483], 1544);
                step(f, Op::SubF, &[477, 483, 484], 1545);
                step(f, Op::DivF, &[484, 477, 485], 1546);
                step(f, Op::ScaleV, &[292, 485, 293], 1547);
                step(f, Op::AddV, &[288, 293, 294], 1548);
                step(f, Op::ClampSpatially, &[294, 288, 487, 470, 295], 1549);
                step(f, Op::MakeTransform, &[295, 78, 306, 93], 1550);
                step(f, Op::Equals(Elem::Int), &[51, 52, 57], 1551);
                step(f, Op::Select(ValueType::Vec3), &[57, 312, 311, 300], 1552);
                step(f, Op::Select(ValueType::Vec3), &[57, 309, 313, 301], 1553);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 51, 94], 1554);
                step(f, Op::BreakTransform, &[94, 296, 79, 297], 1555);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 51, 298], 1556);
                step(f, Op::KneeVector, &[79, 0, 298, 102, 103, 299], 1557);
                step(f, Op::TwoBoneIK, &[30, 29, 28, 93, 300, 301, 299, 52, 489, 60, 502, 503, 59, 58, 486], 1558);
                step(f, Op::JumpIfFalse, &[5, 1569], 1559)
            }
            1559 => {
                step(f, Op::GetParent, &[28, 29], 1560);
                step(f, Op::GetTransform, &[29, 52, 60, 95], 1561);
                step(f, Op::BreakTransform, &[95, 302, 80, 303], 1562);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 51, 94], 1563);
                step(f, Op::BreakTransform, &[94, 296, 79, 297], 1564);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 51, 298], 1565);
                step(f, Op::KneeVector, &[79, 0, 298, 102, 103, 299], 1566);
                step(f, Op::AddV, &[302, 299, 304], 1567);
                step(f, Op::DrawLine, &[302, 304, 488, 314], 1568);
                step(f, Op::Jump, &[1569], 1569)
            }
            1569 => {
                step(f, Op::Jump, &[1518], 1570)
            }
            1570 => {
                step(f, Op::End, &[], 1571)
            }
            _ => return,
        } };
    }
}
