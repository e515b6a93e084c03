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
    fingerprint: 0xbf518c88e72542e1,
    forward,
};

fn forward(f: &mut Frame<'_>) {
    let mut pc: usize = 377;
    loop {
        // SAFETY: each `step` is an instruction of the program this code was generated
        // from, with its own operands; `NATIVE` runs only on that program (fingerprint).
        pc = unsafe { match pc {
            377 => {
                step(f, Op::WorldTransform, &[12], 378);
                step(f, Op::BreakTransform, &[12, 30, 7, 31], 379);
                step(f, Op::Select(ValueType::Transform), &[0, 0, 12, 13], 380);
                step(f, Op::BreakTransform, &[13, 32, 8, 33], 381);
                step(f, Op::SubV, &[30, 32, 34], 382);
                step(f, Op::LengthV, &[34, 110], 383);
                step(f, Op::GreaterF, &[110, 23, 4], 384);
                step(f, Op::Copy(ValueType::Bool), &[4, 1], 385);
                step(f, Op::MakeRelative, &[13, 12, 17], 386);
                step(f, Op::Select(ValueType::Transform), &[4, 96, 17, 18], 387);
                step(f, Op::Copy(ValueType::Transform), &[18, 2], 388);
                step(f, Op::InverseT, &[13, 15], 389);
                step(f, Op::MulT, &[12, 15, 16], 390);
                step(f, Op::Copy(ValueType::Transform), &[16, 1], 391);
                step(f, Op::TransformVector, &[2, 0, 37], 392);
                step(f, Op::InverseT, &[12, 14], 393);
                step(f, Op::DeltaTime, &[109], 394);
                step(f, Op::DivF, &[471, 109, 111], 395);
                step(f, Op::ScaleV, &[34, 111, 35], 396);
                step(f, Op::TransformVector, &[14, 35, 36], 397);
                step(f, Op::Select(ValueType::Vec3), &[1, 37, 36, 39], 398);
                step(f, Op::VectorLerp, &[37, 39, 24, 469, 40], 399);
                step(f, Op::Copy(ValueType::Vec3), &[40, 0], 400);
                step(f, Op::TransformVector, &[2, 1, 38], 401);
                step(f, Op::TransformVector, &[2, 0, 37], 402);
                step(f, Op::Select(ValueType::Vec3), &[1, 37, 36, 39], 403);
                step(f, Op::VectorLerp, &[38, 39, 25, 469, 41], 404);
                step(f, Op::Copy(ValueType::Vec3), &[41, 1], 405);
                step(f, Op::LengthV, &[39, 112], 406);
                step(f, Op::Copy(ValueType::Float), &[112, 0], 407);
                step(f, Op::JumpIfFalse, &[1, 422], 408)
            }
            408 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 12], 409);
                step(f, Op::Copy(ValueType::Int), &[52, 16], 410);
                410
            }
            410 => {
                step(f, Op::ForEachNext(Elem::Bone), &[12, 16, 13, 17, 18, 420], 411)
            }
            411 => {
                step(f, Op::ArrayAt(Elem::Transform), &[5, 17, 20], 412);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 17, 20], 413);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 17, 20], 414);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 17, 20], 415);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 17, 20], 416);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 17, 20], 417);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 17, 20], 418);
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 17, 20], 419);
                step(f, Op::Jump, &[410], 420)
            }
            420 => {
                step(f, Op::Copy(ValueType::Float), &[469, 9], 421);
                step(f, Op::Jump, &[422], 422)
            }
            422 => {
                step(f, Op::WorldTransform, &[12], 423);
                step(f, Op::Copy(ValueType::Transform), &[12, 0], 424);
                step(f, Op::Copy(ValueType::Bool), &[53, 0], 425);
                step(f, Op::JumpIfFalse, &[3, 432], 426)
            }
            426 => {
                step(f, Op::GetTransform, &[34, 52, 53, 19], 427);
                step(f, Op::BreakTransform, &[19, 42, 9, 43], 428);
                step(f, Op::ScaleV, &[0, 472, 44], 429);
                step(f, Op::AddV, &[42, 44, 45], 430);
                step(f, Op::DrawArrow, &[42, 45, 470, 307], 431);
                step(f, Op::Jump, &[432], 432)
            }
            432 => {
                step(f, Op::Copy(ValueType::Bool), &[54, 6], 433);
                step(f, Op::Copy(ValueType::Bool), &[53, 7], 434);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 435);
                step(f, Op::Copy(ValueType::Int), &[52, 22], 436);
                436
            }
            436 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 22, 8, 23, 24, 442], 437)
            }
            437 => {
                step(f, Op::Not, &[8, 9], 438);
                step(f, Op::JumpIfFalse, &[9, 441], 439)
            }
            439 => {
                step(f, Op::Copy(ValueType::Bool), &[54, 7], 440);
                step(f, Op::Jump, &[441], 441)
            }
            441 => {
                step(f, Op::Jump, &[436], 442)
            }
            442 => {
                step(f, Op::Copy(ValueType::Bool), &[7, 6], 443);
                step(f, Op::Jump, &[444], 444)
            }
            444 => {
                step(f, Op::Copy(ValueType::Bool), &[54, 10], 445);
                step(f, Op::Copy(ValueType::Bool), &[53, 11], 446);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 447);
                step(f, Op::Copy(ValueType::Int), &[52, 25], 448);
                448
            }
            448 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 25, 15, 26, 27, 463], 449)
            }
            449 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 26, 21], 450);
                step(f, Op::BreakTransform, &[21, 46, 10, 47], 451);
                step(f, Op::BreakVector, &[46, 121, 122, 123], 452);
                step(f, Op::MakeVector, &[121, 122, 469, 50], 453);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 26, 22], 454);
                step(f, Op::BreakTransform, &[22, 48, 11, 49], 455);
                step(f, Op::BreakVector, &[48, 124, 125, 126], 456);
                step(f, Op::MakeVector, &[124, 125, 469, 51], 457);
                step(f, Op::DistanceV, &[50, 51, 127], 458);
                step(f, Op::GreaterF, &[127, 19, 12], 459);
                step(f, Op::JumpIfFalse, &[12, 462], 460)
            }
            460 => {
                step(f, Op::Copy(ValueType::Bool), &[54, 11], 461);
                step(f, Op::Jump, &[462], 462)
            }
            462 => {
                step(f, Op::Jump, &[448], 463)
            }
            463 => {
                step(f, Op::Copy(ValueType::Bool), &[11, 10], 464);
                step(f, Op::Jump, &[465], 465)
            }
            465 => {
                step(f, Op::And, &[6, 10, 13], 466);
                step(f, Op::LengthV, &[0, 113], 467);
                step(f, Op::GreaterF, &[113, 17, 5], 468);
                step(f, Op::GreaterF, &[0, 17, 14], 469);
                step(f, Op::Or, &[5, 14, 15], 470);
                step(f, Op::Not, &[15, 16], 471);
                step(f, Op::And, &[13, 16, 18], 472);
                step(f, Op::DeltaTime, &[138], 473);
                step(f, Op::MulF, &[138, 22, 139], 474);
                step(f, Op::AddF, &[6, 139, 140], 475);
                step(f, Op::GreaterF, &[6, 470, 19], 476);
                step(f, Op::AddF, &[21, 470, 136], 477);
                step(f, Op::Select(ValueType::Float), &[19, 136, 21, 137], 478);
                step(f, Op::MinF, &[140, 137, 141], 479);
                step(f, Op::RemapF, &[113, 17, 18, 469, 471, 53, 128], 480);
                step(f, Op::Select(ValueType::Float), &[16, 20, 471, 129], 481);
                step(f, Op::Select(ValueType::Float), &[13, 128, 129, 130], 482);
                step(f, Op::LerpF, &[11, 32, 8, 116], 483);
                step(f, Op::RemapF, &[113, 14, 15, 12, 13, 53, 114], 484);
                step(f, Op::LerpF, &[114, 31, 8, 115], 485);
                step(f, Op::MaxF, &[113, 16, 117], 486);
                step(f, Op::DivF, &[115, 117, 118], 487);
                step(f, Op::AddF, &[116, 118, 119], 488);
                step(f, Op::DivF, &[130, 119, 131], 489);
                step(f, Op::AddF, &[3, 131, 132], 490);
                step(f, Op::DivF, &[473, 132, 133], 491);
                step(f, Op::GreaterF, &[132, 469, 17], 492);
                step(f, Op::CycleStep, &[6, 133, 469, 17, 134, 135], 493);
                step(f, Op::Select(ValueType::Float), &[18, 141, 134, 142], 494);
                step(f, Op::Copy(ValueType::Float), &[142, 6], 495);
                step(f, Op::Copy(ValueType::Float), &[131, 3], 496);
                step(f, Op::Copy(ValueType::Bool), &[5, 2], 497);
                step(f, Op::Copy(ValueType::Float), &[118, 1], 498);
                step(f, Op::Copy(ValueType::Float), &[119, 2], 499);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 13], 500);
                step(f, Op::Copy(ValueType::Int), &[52, 19], 501);
                501
            }
            501 => {
                step(f, Op::ForEachNext(Elem::Bone), &[13, 19, 14, 20, 21, 588], 502)
            }
            502 => {
                step(f, Op::ArrayAt(Elem::Float), &[0, 20, 151], 503);
                step(f, Op::ToFloat, &[20, 143], 504);
                step(f, Op::MulF, &[143, 470, 144], 505);
                step(f, Op::AddF, &[6, 144, 145], 506);
                step(f, Op::FractF, &[145, 146], 507);
                step(f, Op::SubF, &[151, 146, 153], 508);
                step(f, Op::GreaterF, &[153, 470, 20], 509);
                step(f, Op::SubF, &[471, 151, 164], 510);
                step(f, Op::AddF, &[146, 164, 165], 511);
                step(f, Op::DivF, &[146, 165, 166], 512);
                step(f, Op::Copy(ValueType::Bool), &[54, 6], 513);
                step(f, Op::Copy(ValueType::Bool), &[53, 7], 514);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 515);
                step(f, Op::Copy(ValueType::Int), &[52, 22], 516);
                516
            }
            516 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 22, 8, 23, 24, 522], 517)
            }
            517 => {
                step(f, Op::Not, &[8, 9], 518);
                step(f, Op::JumpIfFalse, &[9, 521], 519)
            }
            519 => {
                step(f, Op::Copy(ValueType::Bool), &[54, 7], 520);
                step(f, Op::Jump, &[521], 521)
            }
            521 => {
                step(f, Op::Jump, &[516], 522)
            }
            522 => {
                step(f, Op::Copy(ValueType::Bool), &[7, 6], 523);
                step(f, Op::Jump, &[524], 524)
            }
            524 => {
                step(f, Op::Copy(ValueType::Bool), &[54, 10], 525);
                step(f, Op::Copy(ValueType::Bool), &[53, 11], 526);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 527);
                step(f, Op::Copy(ValueType::Int), &[52, 25], 528);
                528
            }
            528 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 25, 15, 26, 27, 543], 529)
            }
            529 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 26, 21], 530);
                step(f, Op::BreakTransform, &[21, 46, 10, 47], 531);
                step(f, Op::BreakVector, &[46, 121, 122, 123], 532);
                step(f, Op::MakeVector, &[121, 122, 469, 50], 533);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 26, 22], 534);
                step(f, Op::BreakTransform, &[22, 48, 11, 49], 535);
                step(f, Op::BreakVector, &[48, 124, 125, 126], 536);
                step(f, Op::MakeVector, &[124, 125, 469, 51], 537);
                step(f, Op::DistanceV, &[50, 51, 127], 538);
                step(f, Op::GreaterF, &[127, 19, 12], 539);
                step(f, Op::JumpIfFalse, &[12, 542], 540)
            }
            540 => {
                step(f, Op::Copy(ValueType::Bool), &[54, 11], 541);
                step(f, Op::Jump, &[542], 542)
            }
            542 => {
                step(f, Op::Jump, &[528], 543)
            }
            543 => {
                step(f, Op::Copy(ValueType::Bool), &[11, 10], 544);
                step(f, Op::Jump, &[545], 545)
            }
            545 => {
                step(f, Op::And, &[6, 10, 13], 546);
                step(f, Op::LengthV, &[0, 113], 547);
                step(f, Op::RemapF, &[113, 17, 18, 469, 471, 53, 128], 548);
                step(f, Op::GreaterF, &[113, 17, 5], 549);
                step(f, Op::GreaterF, &[0, 17, 14], 550);
                step(f, Op::Or, &[5, 14, 15], 551);
                step(f, Op::Not, &[15, 16], 552);
                step(f, Op::Select(ValueType::Float), &[16, 20, 471, 129], 553);
                step(f, Op::Select(ValueType::Float), &[13, 128, 129, 130], 554);
                step(f, Op::LerpF, &[11, 32, 8, 116], 555);
                step(f, Op::DivF, &[130, 116, 147], 556);
                step(f, Op::AddF, &[5, 147, 148], 557);
                step(f, Op::DeltaTime, &[138], 558);
                step(f, Op::MulF, &[138, 470, 149], 559);
                step(f, Op::MulF, &[148, 149, 150], 560);
                step(f, Op::MulF, &[166, 150, 167], 561);
                step(f, Op::ArrayAt(Elem::Float), &[2, 20, 152], 562);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 20, 21], 563);
                step(f, Op::RemapF, &[113, 14, 15, 12, 13, 53, 114], 564);
                step(f, Op::LerpF, &[114, 31, 8, 115], 565);
                step(f, Op::MaxF, &[113, 16, 117], 566);
                step(f, Op::DivF, &[115, 117, 118], 567);
                step(f, Op::AddF, &[116, 118, 119], 568);
                step(f, Op::DivF, &[116, 119, 120], 569);
                step(f, Op::SubF, &[120, 4, 154], 570);
                step(f, Op::MaxF, &[154, 469, 155], 571);
                step(f, Op::DivF, &[155, 120, 156], 572);
                step(f, Op::MulF, &[156, 152, 157], 573);
                step(f, Op::SubF, &[471, 8, 158], 574);
                step(f, Op::MulF, &[157, 158, 159], 575);
                step(f, Op::MulF, &[159, 97, 160], 576);
                step(f, Op::Select(ValueType::Float), &[21, 469, 160, 161], 577);
                step(f, Op::SubF, &[150, 161, 162], 578);
                step(f, Op::AddF, &[152, 162, 163], 579);
                step(f, Op::Select(ValueType::Float), &[20, 167, 163, 168], 580);
                step(f, Op::MinF, &[168, 473, 169], 581);
                step(f, Op::ArraySetAt(Elem::Float), &[2, 20, 169], 582);
                step(f, Op::ToFloat, &[20, 143], 583);
                step(f, Op::MulF, &[143, 470, 144], 584);
                step(f, Op::AddF, &[6, 144, 145], 585);
                step(f, Op::FractF, &[145, 146], 586);
                step(f, Op::ArraySetAt(Elem::Float), &[0, 20, 146], 587);
                step(f, Op::Jump, &[501], 588)
            }
            588 => {
                step(f, Op::LerpF, &[11, 32, 8, 116], 589);
                step(f, Op::LengthV, &[0, 113], 590);
                step(f, Op::RemapF, &[113, 14, 15, 12, 13, 53, 114], 591);
                step(f, Op::LerpF, &[114, 31, 8, 115], 592);
                step(f, Op::MaxF, &[113, 16, 117], 593);
                step(f, Op::DivF, &[115, 117, 118], 594);
                step(f, Op::AddF, &[116, 118, 119], 595);
                step(f, Op::DivF, &[116, 119, 120], 596);
                step(f, Op::Copy(ValueType::Float), &[120, 4], 597);
                step(f, Op::Copy(ValueType::Bool), &[54, 6], 598);
                step(f, Op::Copy(ValueType::Bool), &[53, 7], 599);
                step(f, Op::Copy(ValueType::Array(Elem::Bool)), &[0, 1], 600);
                step(f, Op::Copy(ValueType::Int), &[52, 22], 601);
                601
            }
            601 => {
                step(f, Op::ForEachNext(Elem::Bool), &[1, 22, 8, 23, 24, 607], 602)
            }
            602 => {
                step(f, Op::Not, &[8, 9], 603);
                step(f, Op::JumpIfFalse, &[9, 606], 604)
            }
            604 => {
                step(f, Op::Copy(ValueType::Bool), &[54, 7], 605);
                step(f, Op::Jump, &[606], 606)
            }
            606 => {
                step(f, Op::Jump, &[601], 607)
            }
            607 => {
                step(f, Op::Copy(ValueType::Bool), &[7, 6], 608);
                step(f, Op::Jump, &[609], 609)
            }
            609 => {
                step(f, Op::Copy(ValueType::Bool), &[54, 10], 610);
                step(f, Op::Copy(ValueType::Bool), &[53, 11], 611);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 14], 612);
                step(f, Op::Copy(ValueType::Int), &[52, 25], 613);
                613
            }
            613 => {
                step(f, Op::ForEachNext(Elem::Bone), &[14, 25, 15, 26, 27, 628], 614)
            }
            614 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 26, 21], 615);
                step(f, Op::BreakTransform, &[21, 46, 10, 47], 616);
                step(f, Op::BreakVector, &[46, 121, 122, 123], 617);
                step(f, Op::MakeVector, &[121, 122, 469, 50], 618);
                step(f, Op::ArrayAt(Elem::Transform), &[5, 26, 22], 619);
                step(f, Op::BreakTransform, &[22, 48, 11, 49], 620);
                step(f, Op::BreakVector, &[48, 124, 125, 126], 621);
                step(f, Op::MakeVector, &[124, 125, 469, 51], 622);
                step(f, Op::DistanceV, &[50, 51, 127], 623);
                step(f, Op::GreaterF, &[127, 19, 12], 624);
                step(f, Op::JumpIfFalse, &[12, 627], 625)
            }
            625 => {
                step(f, Op::Copy(ValueType::Bool), &[54, 11], 626);
                step(f, Op::Jump, &[627], 627)
            }
            627 => {
                step(f, Op::Jump, &[613], 628)
            }
            628 => {
                step(f, Op::Copy(ValueType::Bool), &[11, 10], 629);
                step(f, Op::Jump, &[630], 630)
            }
            630 => {
                step(f, Op::And, &[6, 10, 13], 631);
                step(f, Op::RemapF, &[113, 17, 18, 469, 471, 53, 128], 632);
                step(f, Op::GreaterF, &[113, 17, 5], 633);
                step(f, Op::GreaterF, &[0, 17, 14], 634);
                step(f, Op::Or, &[5, 14, 15], 635);
                step(f, Op::Not, &[15, 16], 636);
                step(f, Op::Select(ValueType::Float), &[16, 20, 471, 129], 637);
                step(f, Op::Select(ValueType::Float), &[13, 128, 129, 130], 638);
                step(f, Op::DivF, &[130, 116, 147], 639);
                step(f, Op::Copy(ValueType::Float), &[147, 5], 640);
                step(f, Op::Select(ValueType::Vec3), &[2, 0, 305, 52], 641);
                step(f, Op::MovementAngleOffset, &[52, 7, 6, 26, 27, 474, 28, 475, 170], 642);
                step(f, Op::Copy(ValueType::Float), &[170, 7], 643);
                step(f, Op::QuatFromAxisAngle, &[308, 7, 12], 644);
                step(f, Op::Copy(ValueType::Quat), &[12, 0], 645);
                step(f, Op::SinF, &[7, 171], 646);
                step(f, Op::AbsF, &[171, 172], 647);
                step(f, Op::RemapF, &[172, 29, 30, 469, 471, 53, 173], 648);
                step(f, Op::Copy(ValueType::Float), &[173, 8], 649);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 4], 650);
                step(f, Op::Copy(ValueType::Int), &[52, 1], 651);
                651
            }
            651 => {
                step(f, Op::ForEachNext(Elem::Bone), &[4, 1, 0, 2, 3, 1240], 652)
            }
            652 => {
                step(f, Op::Copy(ValueType::Bone), &[0, 16], 653);
                step(f, Op::Copy(ValueType::Int), &[2, 28], 654);
                step(f, Op::GetTransform, &[35, 52, 53, 23], 655);
                step(f, Op::BreakTransform, &[23, 55, 13, 56], 656);
                step(f, Op::BreakVector, &[55, 185, 186, 187], 657);
                step(f, Op::SubF, &[471, 8, 183], 658);
                step(f, Op::MulF, &[7, 183, 184], 659);
                step(f, Op::QuatFromAxisAngle, &[308, 184, 15], 660);
                step(f, Op::GetTransform, &[16, 52, 53, 24], 661);
                step(f, Op::BreakTransform, &[24, 57, 14, 58], 662);
                step(f, Op::SubV, &[57, 55, 59], 663);
                step(f, Op::BreakVector, &[59, 180, 181, 182], 664);
                step(f, Op::MakeVector, &[180, 181, 469, 60], 665);
                step(f, Op::RotateVector, &[15, 60, 61], 666);
                step(f, Op::BreakVector, &[61, 188, 189, 190], 667);
                step(f, Op::MulF, &[33, 8, 191], 668);
                step(f, Op::Equals(Elem::Int), &[28, 52, 22], 669);
                step(f, Op::Select(ValueType::Float), &[22, 471, 476, 200], 670);
                step(f, Op::MulF, &[191, 200, 192], 671);
                step(f, Op::AddF, &[188, 192, 193], 672);
                step(f, Op::AddF, &[185, 193, 194], 673);
                step(f, Op::AddF, &[186, 189, 195], 674);
                step(f, Op::BreakVector, &[57, 196, 197, 198], 675);
                step(f, Op::SubF, &[198, 36, 199], 676);
                step(f, Op::MakeVector, &[194, 195, 199, 62], 677);
                step(f, Op::ArrayAt(Elem::Float), &[2, 28, 174], 678);
                step(f, Op::SubF, &[471, 174, 175], 679);
                step(f, Op::MaxF, &[175, 469, 176], 680);
                step(f, Op::MulF, &[4, 2, 177], 681);
                step(f, Op::MulF, &[176, 177, 178], 682);
                step(f, Op::ScaleV, &[0, 178, 53], 683);
                step(f, Op::AddV, &[62, 53, 63], 684);
                step(f, Op::MulF, &[1, 470, 179], 685);
                step(f, Op::ScaleV, &[0, 179, 54], 686);
                step(f, Op::AddV, &[63, 54, 64], 687);
                step(f, Op::RotateVector, &[0, 309, 65], 688);
                step(f, Op::Copy(ValueType::Vec3), &[64, 72], 689);
                step(f, Op::Copy(ValueType::Vec3), &[65, 73], 690);
                step(f, Op::Copy(ValueType::Float), &[200, 210], 691);
                step(f, Op::Copy(ValueType::Vec3), &[305, 74], 692);
                step(f, Op::Copy(ValueType::Vec3), &[305, 75], 693);
                step(f, Op::Copy(ValueType::Bool), &[54, 23], 694);
                step(f, Op::Copy(ValueType::Float), &[477, 211], 695);
                step(f, Op::Copy(ValueType::Vec3), &[305, 76], 696);
                step(f, Op::Copy(ValueType::Vec3), &[308, 77], 697);
                step(f, Op::Copy(ValueType::Bool), &[54, 24], 698);
                step(f, Op::MulI, &[0, 0, 34], 699);
                step(f, Op::Copy(ValueType::Int), &[34, 33], 700);
                step(f, Op::Copy(ValueType::Int), &[52, 29], 701);
                step(f, Op::SubI, &[0, 53, 37], 702);
                step(f, Op::DivI, &[37, 54, 38], 703);
                step(f, Op::MakeVector, &[469, 469, 41, 82], 704);
                step(f, Op::ScaleV, &[73, 43, 87], 705);
                705
            }
            705 => {
                step(f, Op::ForNext, &[29, 33, 31, 745], 706)
            }
            706 => {
                step(f, Op::ModI, &[31, 0, 35], 707);
                step(f, Op::ToFloat, &[35, 212], 708);
                step(f, Op::MulF, &[212, 42, 214], 709);
                step(f, Op::MulF, &[214, 210, 215], 710);
                step(f, Op::MakeVector, &[215, 469, 469, 78], 711);
                step(f, Op::DivI, &[31, 0, 36], 712);
                step(f, Op::SubI, &[36, 38, 39], 713);
                step(f, Op::ToFloat, &[39, 213], 714);
                step(f, Op::MulF, &[213, 42, 216], 715);
                step(f, Op::ScaleV, &[73, 216, 79], 716);
                step(f, Op::AddV, &[78, 79, 80], 717);
                step(f, Op::AddV, &[72, 80, 81], 718);
                step(f, Op::AddV, &[81, 82, 83], 719);
                step(f, Op::SubV, &[81, 82, 84], 720);
                step(f, Op::SphereTrace, &[83, 84, 40, 25, 85, 86, 217], 721);
                step(f, Op::BreakVector, &[85, 219, 220, 221], 722);
                step(f, Op::AddV, &[83, 87, 88], 723);
                step(f, Op::AddV, &[84, 87, 89], 724);
                step(f, Op::SphereTrace, &[88, 89, 40, 26, 90, 91, 218], 725);
                step(f, Op::BreakVector, &[90, 222, 223, 224], 726);
                step(f, Op::SubF, &[221, 224, 225], 727);
                step(f, Op::AbsF, &[225, 226], 728);
                step(f, Op::Select(ValueType::Float), &[25, 469, 471, 227], 729);
                step(f, Op::AddF, &[226, 227, 232], 730);
                step(f, Op::LengthV, &[80, 228], 731);
                step(f, Op::RemapF, &[228, 469, 478, 469, 471, 53, 229], 732);
                step(f, Op::MinF, &[221, 224, 230], 733);
                step(f, Op::RemapF, &[230, 479, 478, 471, 470, 53, 231], 734);
                step(f, Op::AddF, &[229, 231, 233], 735);
                step(f, Op::AddF, &[232, 233, 234], 736);
                step(f, Op::LessF, &[234, 211, 27], 737);
                step(f, Op::And, &[25, 27, 28], 738);
                step(f, Op::JumpIfFalse, &[28, 744], 739)
            }
            739 => {
                step(f, Op::Copy(ValueType::Float), &[234, 211], 740);
                step(f, Op::Copy(ValueType::Vec3), &[85, 76], 741);
                step(f, Op::Copy(ValueType::Vec3), &[86, 77], 742);
                step(f, Op::Copy(ValueType::Bool), &[53, 24], 743);
                step(f, Op::Jump, &[744], 744)
            }
            744 => {
                step(f, Op::Jump, &[705], 745)
            }
            745 => {
                step(f, Op::JumpIfFalse, &[3, 748], 746)
            }
            746 => {
                step(f, Op::DrawSphere, &[76, 40, 309], 747);
                step(f, Op::Jump, &[748], 748)
            }
            748 => {
                step(f, Op::Copy(ValueType::Vec3), &[76, 74], 749);
                step(f, Op::Copy(ValueType::Vec3), &[77, 75], 750);
                step(f, Op::Copy(ValueType::Bool), &[24, 23], 751);
                step(f, Op::Jump, &[752], 752)
            }
            752 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 28, 25], 753);
                step(f, Op::BreakTransform, &[25, 67, 19, 68], 754);
                step(f, Op::ArrayAt(Elem::Float), &[2, 28, 174], 755);
                step(f, Op::SubF, &[471, 174, 175], 756);
                step(f, Op::MaxF, &[175, 469, 176], 757);
                step(f, Op::MulF, &[4, 2, 177], 758);
                step(f, Op::MulF, &[176, 177, 178], 759);
                step(f, Op::ScaleV, &[0, 178, 53], 760);
                step(f, Op::SubV, &[74, 53, 66], 761);
                step(f, Op::Select(ValueType::Vec3), &[23, 66, 67, 69], 762);
                step(f, Op::VectorLerp, &[67, 69, 34, 469, 70], 763);
                step(f, Op::BreakVector, &[70, 206, 207, 208], 764);
                step(f, Op::ClampF, &[208, 44, 45, 209], 765);
                step(f, Op::MakeVector, &[206, 207, 209, 71], 766);
                step(f, Op::RotationFromNormal, &[75, 204, 205, 17], 767);
                step(f, Op::PerFootRotationFactor, &[7, 75, 76, 201], 768);
                step(f, Op::MulF, &[7, 201, 202], 769);
                step(f, Op::SubF, &[471, 8, 183], 770);
                step(f, Op::MulF, &[202, 183, 203], 771);
                step(f, Op::QuatFromAxisAngle, &[308, 203, 16], 772);
                step(f, Op::MulQ, &[17, 16, 18], 773);
                step(f, Op::Select(ValueType::Quat), &[23, 18, 19, 20], 774);
                step(f, Op::MakeTransform, &[71, 20, 306, 26], 775);
                step(f, Op::ArraySetAt(Elem::Transform), &[1, 28, 26], 776);
                step(f, Op::Copy(ValueType::Int), &[2, 40], 777);
                step(f, Op::ArrayAt(Elem::Transform), &[0, 40, 27], 778);
                step(f, Op::MakeAbsolute, &[27, 2, 28], 779);
                step(f, Op::BreakTransform, &[28, 92, 21, 93], 780);
                step(f, Op::ClampSpatially, &[92, 305, 469, 48, 94], 781);
                step(f, Op::SubF, &[471, 8, 240], 782);
                step(f, Op::MulF, &[7, 240, 236], 783);
                step(f, Op::LimitRotationAroundZ, &[21, 236, 74, 22], 784);
                step(f, Op::MakeTransform, &[94, 22, 306, 29], 785);
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 40, 29], 786);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 40, 29], 787);
                step(f, Op::JumpIfFalse, &[29, 841], 788)
            }
            788 => {
                step(f, Op::ArrayAt(Elem::Transform), &[1, 40, 31], 789);
                step(f, Op::BreakTransform, &[31, 95, 23, 96], 790);
                step(f, Op::ArrayAt(Elem::Float), &[2, 40, 235], 791);
                step(f, Op::SubF, &[471, 235, 237], 792);
                step(f, Op::MulF, &[4, 2, 238], 793);
                step(f, Op::MulF, &[237, 238, 239], 794);
                step(f, Op::ScaleV, &[0, 239, 97], 795);
                step(f, Op::AddV, &[95, 97, 98], 796);
                step(f, Op::MakeTransform, &[98, 23, 306, 38], 797);
                step(f, Op::Copy(ValueType::Transform), &[38, 39], 798);
                step(f, Op::Copy(ValueType::Transform), &[96, 40], 799);
                step(f, Op::BreakTransform, &[39, 126, 28, 127], 800);
                step(f, Op::MakeVector, &[469, 469, 41, 128], 801);
                step(f, Op::AddV, &[126, 128, 129], 802);
                step(f, Op::SubV, &[126, 128, 130], 803);
                step(f, Op::LineTrace, &[129, 130, 35, 131, 132, 267], 804);
                step(f, Op::RotateVector, &[28, 308, 133], 805);
                step(f, Op::FindQuatBetween, &[133, 132, 29], 806);
                step(f, Op::MulQ, &[29, 28, 30], 807);
                step(f, Op::MulF, &[39, 38, 268], 808);
                step(f, Op::AddF, &[268, 47, 269], 809);
                step(f, Op::NegF, &[269, 270], 810);
                step(f, Op::MakeVector, &[469, 270, 469, 134], 811);
                step(f, Op::RotateVector, &[30, 134, 136], 812);
                step(f, Op::AddV, &[131, 136, 138], 813);
                step(f, Op::AddV, &[138, 128, 140], 814);
                step(f, Op::SubV, &[138, 128, 141], 815);
                step(f, Op::LineTrace, &[140, 141, 36, 144, 145, 272], 816);
                step(f, Op::BreakVector, &[144, 274, 275, 276], 817);
                step(f, Op::BreakVector, &[138, 280, 281, 282], 818);
                step(f, Op::SubF, &[276, 282, 286], 819);
                step(f, Op::Select(ValueType::Float), &[36, 286, 469, 288], 820);
                step(f, Op::AddF, &[43, 47, 271], 821);
                step(f, Op::MakeVector, &[469, 271, 469, 135], 822);
                step(f, Op::RotateVector, &[30, 135, 137], 823);
                step(f, Op::AddV, &[131, 137, 139], 824);
                step(f, Op::AddV, &[139, 128, 142], 825);
                step(f, Op::SubV, &[139, 128, 143], 826);
                step(f, Op::LineTrace, &[142, 143, 37, 146, 147, 273], 827);
                step(f, Op::BreakVector, &[146, 277, 278, 279], 828);
                step(f, Op::BreakVector, &[139, 283, 284, 285], 829);
                step(f, Op::SubF, &[279, 285, 287], 830);
                step(f, Op::Select(ValueType::Float), &[37, 287, 469, 289], 831);
                step(f, Op::MaxF, &[288, 289, 290], 832);
                step(f, Op::ClampF, &[290, 469, 46, 291], 833);
                step(f, Op::MakeVector, &[469, 469, 291, 148], 834);
                step(f, Op::AddV, &[131, 148, 149], 835);
                step(f, Op::MakeTransform, &[149, 30, 306, 41], 836);
                step(f, Op::Select(ValueType::Transform), &[35, 41, 39, 42], 837);
                step(f, Op::Copy(ValueType::Transform), &[42, 40], 838);
                step(f, Op::Jump, &[839], 839)
            }
            839 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 40, 40], 840);
                step(f, Op::Jump, &[900], 841)
            }
            841 => {
                step(f, Op::ArrayAt(Elem::Transform), &[2, 40, 43], 842);
                step(f, Op::MakeAbsolute, &[43, 2, 44], 843);
                step(f, Op::BreakTransform, &[44, 150, 31, 151], 844);
                step(f, Op::ArrayAt(Elem::Transform), &[1, 40, 31], 845);
                step(f, Op::BreakTransform, &[31, 95, 23, 96], 846);
                step(f, Op::ArrayAt(Elem::Float), &[2, 40, 235], 847);
                step(f, Op::SubF, &[471, 235, 237], 848);
                step(f, Op::MulF, &[4, 2, 238], 849);
                step(f, Op::MulF, &[237, 238, 239], 850);
                step(f, Op::ScaleV, &[0, 239, 97], 851);
                step(f, Op::AddV, &[95, 97, 98], 852);
                step(f, Op::ClampF, &[235, 469, 471, 319], 853);
                step(f, Op::SubF, &[471, 319, 292], 854);
                step(f, Op::MulF, &[62, 292, 293], 855);
                step(f, Op::VectorLerp, &[150, 98, 293, 469, 152], 856);
                step(f, Op::MakeTransform, &[152, 23, 306, 45], 857);
                step(f, Op::Copy(ValueType::Transform), &[45, 46], 858);
                step(f, Op::Copy(ValueType::Transform), &[96, 47], 859);
                step(f, Op::BreakTransform, &[46, 153, 32, 154], 860);
                step(f, Op::MakeVector, &[469, 469, 41, 155], 861);
                step(f, Op::AddV, &[153, 155, 156], 862);
                step(f, Op::SubV, &[153, 155, 157], 863);
                step(f, Op::LineTrace, &[156, 157, 38, 158, 159, 294], 864);
                step(f, Op::RotateVector, &[32, 308, 160], 865);
                step(f, Op::FindQuatBetween, &[160, 159, 33], 866);
                step(f, Op::MulQ, &[33, 32, 34], 867);
                step(f, Op::MulF, &[39, 38, 295], 868);
                step(f, Op::AddF, &[295, 47, 296], 869);
                step(f, Op::NegF, &[296, 297], 870);
                step(f, Op::MakeVector, &[469, 297, 469, 161], 871);
                step(f, Op::RotateVector, &[34, 161, 163], 872);
                step(f, Op::AddV, &[158, 163, 165], 873);
                step(f, Op::AddV, &[165, 155, 167], 874);
                step(f, Op::SubV, &[165, 155, 168], 875);
                step(f, Op::LineTrace, &[167, 168, 39, 171, 172, 299], 876);
                step(f, Op::BreakVector, &[171, 301, 302, 303], 877);
                step(f, Op::BreakVector, &[165, 307, 308, 309], 878);
                step(f, Op::SubF, &[303, 309, 313], 879);
                step(f, Op::Select(ValueType::Float), &[39, 313, 469, 315], 880);
                step(f, Op::AddF, &[43, 47, 298], 881);
                step(f, Op::MakeVector, &[469, 298, 469, 162], 882);
                step(f, Op::RotateVector, &[34, 162, 164], 883);
                step(f, Op::AddV, &[158, 164, 166], 884);
                step(f, Op::AddV, &[166, 155, 169], 885);
                step(f, Op::SubV, &[166, 155, 170], 886);
                step(f, Op::LineTrace, &[169, 170, 40, 173, 174, 300], 887);
                step(f, Op::BreakVector, &[173, 304, 305, 306], 888);
                step(f, Op::BreakVector, &[166, 310, 311, 312], 889);
                step(f, Op::SubF, &[306, 312, 314], 890);
                step(f, Op::Select(ValueType::Float), &[40, 314, 469, 316], 891);
                step(f, Op::MaxF, &[315, 316, 317], 892);
                step(f, Op::ClampF, &[317, 469, 46, 318], 893);
                step(f, Op::MakeVector, &[469, 469, 318, 175], 894);
                step(f, Op::AddV, &[158, 175, 176], 895);
                step(f, Op::MakeTransform, &[176, 34, 306, 48], 896);
                step(f, Op::Select(ValueType::Transform), &[38, 48, 46, 49], 897);
                step(f, Op::Copy(ValueType::Transform), &[49, 47], 898);
                step(f, Op::Jump, &[899], 899)
            }
            899 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[2, 40, 47], 900);
                900
            }
            900 => {
                step(f, Op::ArrayAt(Elem::Float), &[2, 40, 235], 901);
                step(f, Op::GreaterEqualF, &[235, 471, 30], 902);
                step(f, Op::JumpIfFalse, &[30, 962], 903)
            }
            903 => {
                step(f, Op::ArrayAt(Elem::Bool), &[0, 40, 29], 904);
                step(f, Op::JumpIfFalse, &[29, 906], 905)
            }
            905 => {
                step(f, Op::Jump, &[959], 906)
            }
            906 => {
                step(f, Op::ArrayAt(Elem::Transform), &[2, 40, 50], 907);
                step(f, Op::BreakTransform, &[50, 177, 35, 178], 908);
                step(f, Op::Equals(Elem::Int), &[40, 52, 31], 909);
                step(f, Op::Select(ValueType::Int), &[31, 53, 52, 41], 910);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 41, 32], 911);
                step(f, Op::BreakTransform, &[32, 99, 24, 100], 912);
                step(f, Op::SubF, &[471, 8, 240], 913);
                step(f, Op::MulF, &[7, 240, 241], 914);
                step(f, Op::FootAvoidance, &[177, 99, 241, 31, 63, 101], 915);
                step(f, Op::MakeTransform, &[101, 35, 306, 33], 916);
                step(f, Op::Copy(ValueType::Transform), &[33, 34], 917);
                step(f, Op::Copy(ValueType::Transform), &[96, 35], 918);
                step(f, Op::BreakTransform, &[34, 102, 25, 103], 919);
                step(f, Op::MakeVector, &[469, 469, 41, 104], 920);
                step(f, Op::AddV, &[102, 104, 105], 921);
                step(f, Op::SubV, &[102, 104, 106], 922);
                step(f, Op::LineTrace, &[105, 106, 32, 107, 108, 242], 923);
                step(f, Op::RotateVector, &[25, 308, 109], 924);
                step(f, Op::FindQuatBetween, &[109, 108, 26], 925);
                step(f, Op::MulQ, &[26, 25, 27], 926);
                step(f, Op::MulF, &[39, 38, 243], 927);
                step(f, Op::AddF, &[243, 47, 244], 928);
                step(f, Op::NegF, &[244, 245], 929);
                step(f, Op::MakeVector, &[469, 245, 469, 110], 930);
                step(f, Op::RotateVector, &[27, 110, 112], 931);
                step(f, Op::AddV, &[107, 112, 114], 932);
                step(f, Op::AddV, &[114, 104, 116], 933);
                step(f, Op::SubV, &[114, 104, 117], 934);
                step(f, Op::LineTrace, &[116, 117, 33, 120, 121, 247], 935);
                step(f, Op::BreakVector, &[120, 249, 250, 251], 936);
                step(f, Op::BreakVector, &[114, 255, 256, 257], 937);
                step(f, Op::SubF, &[251, 257, 261], 938);
                step(f, Op::Select(ValueType::Float), &[33, 261, 469, 263], 939);
                step(f, Op::AddF, &[43, 47, 246], 940);
                step(f, Op::MakeVector, &[469, 246, 469, 111], 941);
                step(f, Op::RotateVector, &[27, 111, 113], 942);
                step(f, Op::AddV, &[107, 113, 115], 943);
                step(f, Op::AddV, &[115, 104, 118], 944);
                step(f, Op::SubV, &[115, 104, 119], 945);
                step(f, Op::LineTrace, &[118, 119, 34, 122, 123, 248], 946);
                step(f, Op::BreakVector, &[122, 252, 253, 254], 947);
                step(f, Op::BreakVector, &[115, 258, 259, 260], 948);
                step(f, Op::SubF, &[254, 260, 262], 949);
                step(f, Op::Select(ValueType::Float), &[34, 262, 469, 264], 950);
                step(f, Op::MaxF, &[263, 264, 265], 951);
                step(f, Op::ClampF, &[265, 469, 46, 266], 952);
                step(f, Op::MakeVector, &[469, 469, 266, 124], 953);
                step(f, Op::AddV, &[107, 124, 125], 954);
                step(f, Op::MakeTransform, &[125, 27, 306, 36], 955);
                step(f, Op::Select(ValueType::Transform), &[32, 36, 34, 37], 956);
                step(f, Op::Copy(ValueType::Transform), &[37, 35], 957);
                step(f, Op::Jump, &[958], 958)
            }
            958 => {
                step(f, Op::ArraySetAt(Elem::Transform), &[0, 40, 35], 959);
                959
            }
            959 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 40, 30], 960);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 40, 30], 961);
                step(f, Op::Jump, &[1136], 962)
            }
            962 => {
                step(f, Op::ArrayAt(Elem::Transform), &[0, 40, 30], 963);
                step(f, Op::ArrayAt(Elem::Transform), &[2, 40, 50], 964);
                step(f, Op::ClampF, &[235, 469, 471, 319], 965);
                step(f, Op::Copy(ValueType::Transform), &[30, 52], 966);
                step(f, Op::Copy(ValueType::Transform), &[50, 53], 967);
                step(f, Op::Copy(ValueType::Float), &[319, 329], 968);
                step(f, Op::Copy(ValueType::Transform), &[96, 54], 969);
                step(f, Op::Copy(ValueType::Array(Elem::Vec3)), &[3, 2], 970);
                step(f, Op::ArrayReset(Elem::Vec3), &[2], 971);
                step(f, Op::BreakTransform, &[52, 186, 37, 187], 972);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 186], 973);
                step(f, Op::BreakTransform, &[52, 186, 37, 187], 974);
                step(f, Op::UnitV, &[0, 185], 975);
                step(f, Op::LengthV, &[0, 330], 976);
                step(f, Op::RemapF, &[330, 469, 49, 469, 50, 53, 331], 977);
                step(f, Op::ScaleV, &[185, 331, 190], 978);
                step(f, Op::SubV, &[186, 190, 196], 979);
                step(f, Op::MakeVector, &[469, 469, 52, 194], 980);
                step(f, Op::AddV, &[196, 194, 198], 981);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 198], 982);
                step(f, Op::BreakTransform, &[52, 186, 37, 187], 983);
                step(f, Op::UnitV, &[0, 185], 984);
                step(f, Op::LengthV, &[0, 330], 985);
                step(f, Op::RemapF, &[330, 469, 49, 469, 50, 53, 331], 986);
                step(f, Op::ScaleV, &[185, 331, 190], 987);
                step(f, Op::SubV, &[186, 190, 196], 988);
                step(f, Op::MakeVector, &[469, 469, 52, 194], 989);
                step(f, Op::AddV, &[196, 194, 198], 990);
                step(f, Op::RemapF, &[330, 469, 49, 469, 54, 53, 333], 991);
                step(f, Op::MakeVector, &[469, 469, 333, 192], 992);
                step(f, Op::AddV, &[198, 192, 202], 993);
                step(f, Op::BreakTransform, &[53, 188, 38, 189], 994);
                step(f, Op::BreakVector, &[188, 338, 339, 340], 995);
                step(f, Op::BreakVector, &[186, 335, 336, 337], 996);
                step(f, Op::SubF, &[340, 337, 341], 997);
                step(f, Op::MaxF, &[341, 469, 343], 998);
                step(f, Op::MulF, &[343, 56, 347], 999);
                step(f, Op::AbsF, &[341, 345], 1000);
                step(f, Op::RemapF, &[345, 469, 59, 469, 58, 53, 346], 1001);
                step(f, Op::AddF, &[347, 346, 349], 1002);
                step(f, Op::MakeVector, &[469, 469, 349, 200], 1003);
                step(f, Op::AddV, &[202, 200, 204], 1004);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 204], 1005);
                step(f, Op::BreakTransform, &[52, 186, 37, 187], 1006);
                step(f, Op::UnitV, &[0, 185], 1007);
                step(f, Op::LengthV, &[0, 330], 1008);
                step(f, Op::RemapF, &[330, 469, 49, 469, 50, 53, 331], 1009);
                step(f, Op::ScaleV, &[185, 331, 190], 1010);
                step(f, Op::SubV, &[186, 190, 196], 1011);
                step(f, Op::MakeVector, &[469, 469, 52, 194], 1012);
                step(f, Op::AddV, &[196, 194, 198], 1013);
                step(f, Op::RemapF, &[330, 469, 49, 469, 54, 53, 333], 1014);
                step(f, Op::MakeVector, &[469, 469, 333, 192], 1015);
                step(f, Op::AddV, &[198, 192, 202], 1016);
                step(f, Op::BreakTransform, &[53, 188, 38, 189], 1017);
                step(f, Op::BreakVector, &[188, 338, 339, 340], 1018);
                step(f, Op::BreakVector, &[186, 335, 336, 337], 1019);
                step(f, Op::SubF, &[340, 337, 341], 1020);
                step(f, Op::MaxF, &[341, 469, 343], 1021);
                step(f, Op::MulF, &[343, 56, 347], 1022);
                step(f, Op::AbsF, &[341, 345], 1023);
                step(f, Op::RemapF, &[345, 469, 59, 469, 58, 53, 346], 1024);
                step(f, Op::AddF, &[347, 346, 349], 1025);
                step(f, Op::MakeVector, &[469, 469, 349, 200], 1026);
                step(f, Op::AddV, &[202, 200, 204], 1027);
                step(f, Op::RemapF, &[330, 469, 49, 469, 51, 53, 332], 1028);
                step(f, Op::ScaleV, &[185, 332, 191], 1029);
                step(f, Op::AddV, &[188, 191, 197], 1030);
                step(f, Op::MakeVector, &[469, 469, 53, 195], 1031);
                step(f, Op::AddV, &[197, 195, 199], 1032);
                step(f, Op::RemapF, &[330, 469, 49, 469, 55, 53, 334], 1033);
                step(f, Op::MakeVector, &[469, 469, 334, 193], 1034);
                step(f, Op::AddV, &[199, 193, 203], 1035);
                step(f, Op::NegF, &[341, 342], 1036);
                step(f, Op::MaxF, &[342, 469, 344], 1037);
                step(f, Op::MulF, &[344, 57, 348], 1038);
                step(f, Op::AddF, &[348, 346, 350], 1039);
                step(f, Op::MakeVector, &[469, 469, 350, 201], 1040);
                step(f, Op::AddV, &[203, 201, 205], 1041);
                step(f, Op::LerpV, &[204, 205, 470, 206], 1042);
                step(f, Op::GetTransform, &[36, 52, 53, 55], 1043);
                step(f, Op::BreakTransform, &[55, 207, 39, 208], 1044);
                step(f, Op::BreakVector, &[207, 360, 361, 362], 1045);
                step(f, Op::SubF, &[471, 8, 354], 1046);
                step(f, Op::MulF, &[60, 354, 355], 1047);
                step(f, Op::MulF, &[7, 355, 356], 1048);
                step(f, Op::QuatFromAxisAngle, &[308, 356, 40], 1049);
                step(f, Op::SubV, &[206, 207, 209], 1050);
                step(f, Op::BreakVector, &[209, 351, 352, 353], 1051);
                step(f, Op::MakeVector, &[351, 352, 469, 210], 1052);
                step(f, Op::RotateVector, &[40, 210, 211], 1053);
                step(f, Op::BreakVector, &[211, 357, 358, 359], 1054);
                step(f, Op::AddF, &[360, 357, 366], 1055);
                step(f, Op::AddF, &[361, 358, 367], 1056);
                step(f, Op::BreakVector, &[206, 363, 364, 365], 1057);
                step(f, Op::MakeVector, &[366, 367, 365, 212], 1058);
                step(f, Op::DistanceV, &[186, 188, 368], 1059);
                step(f, Op::RemapF, &[368, 473, 480, 469, 471, 53, 369], 1060);
                step(f, Op::LerpV, &[206, 212, 369, 213], 1061);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 213], 1062);
                step(f, Op::BreakTransform, &[53, 188, 38, 189], 1063);
                step(f, Op::UnitV, &[0, 185], 1064);
                step(f, Op::LengthV, &[0, 330], 1065);
                step(f, Op::RemapF, &[330, 469, 49, 469, 51, 53, 332], 1066);
                step(f, Op::ScaleV, &[185, 332, 191], 1067);
                step(f, Op::AddV, &[188, 191, 197], 1068);
                step(f, Op::MakeVector, &[469, 469, 53, 195], 1069);
                step(f, Op::AddV, &[197, 195, 199], 1070);
                step(f, Op::RemapF, &[330, 469, 49, 469, 55, 53, 334], 1071);
                step(f, Op::MakeVector, &[469, 469, 334, 193], 1072);
                step(f, Op::AddV, &[199, 193, 203], 1073);
                step(f, Op::BreakVector, &[188, 338, 339, 340], 1074);
                step(f, Op::BreakTransform, &[52, 186, 37, 187], 1075);
                step(f, Op::BreakVector, &[186, 335, 336, 337], 1076);
                step(f, Op::SubF, &[340, 337, 341], 1077);
                step(f, Op::NegF, &[341, 342], 1078);
                step(f, Op::MaxF, &[342, 469, 344], 1079);
                step(f, Op::MulF, &[344, 57, 348], 1080);
                step(f, Op::AbsF, &[341, 345], 1081);
                step(f, Op::RemapF, &[345, 469, 59, 469, 58, 53, 346], 1082);
                step(f, Op::AddF, &[348, 346, 350], 1083);
                step(f, Op::MakeVector, &[469, 469, 350, 201], 1084);
                step(f, Op::AddV, &[203, 201, 205], 1085);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 205], 1086);
                step(f, Op::BreakTransform, &[53, 188, 38, 189], 1087);
                step(f, Op::UnitV, &[0, 185], 1088);
                step(f, Op::LengthV, &[0, 330], 1089);
                step(f, Op::RemapF, &[330, 469, 49, 469, 51, 53, 332], 1090);
                step(f, Op::ScaleV, &[185, 332, 191], 1091);
                step(f, Op::AddV, &[188, 191, 197], 1092);
                step(f, Op::MakeVector, &[469, 469, 53, 195], 1093);
                step(f, Op::AddV, &[197, 195, 199], 1094);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 199], 1095);
                step(f, Op::BreakTransform, &[53, 188, 38, 189], 1096);
                step(f, Op::ArrayAdd(Elem::Vec3), &[2, 188], 1097);
                step(f, Op::JumpIfFalse, &[3, 1100], 1098)
            }
            1098 => {
                step(f, Op::DrawSpline, &[2, 52, 55, 470, 310], 1099);
                step(f, Op::Jump, &[1100], 1100)
            }
            1100 => {
                step(f, Op::Spline, &[2, 329, 52, 214, 215], 1101);
                step(f, Op::BreakTransform, &[52, 186, 37, 187], 1102);
                step(f, Op::BreakTransform, &[53, 188, 38, 189], 1103);
                step(f, Op::SlerpQ, &[37, 38, 329, 41], 1104);
                step(f, Op::MulF, &[329, 481, 370], 1105);
                step(f, Op::SinF, &[370, 371], 1106);
                step(f, Op::MulF, &[371, 61, 372], 1107);
                step(f, Op::SlerpQ, &[41, 81, 372, 42], 1108);
                step(f, Op::MakeTransform, &[214, 42, 306, 56], 1109);
                step(f, Op::Copy(ValueType::Transform), &[56, 54], 1110);
                step(f, Op::Jump, &[1111], 1111)
            }
            1111 => {
                step(f, Op::BreakTransform, &[54, 179, 36, 180], 1112);
                step(f, Op::Equals(Elem::Int), &[40, 52, 31], 1113);
                step(f, Op::Select(ValueType::Int), &[31, 53, 52, 41], 1114);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 41, 32], 1115);
                step(f, Op::BreakTransform, &[32, 99, 24, 100], 1116);
                step(f, Op::SubF, &[471, 8, 240], 1117);
                step(f, Op::MulF, &[7, 240, 241], 1118);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 41, 41], 1119);
                step(f, Op::Select(ValueType::Float), &[41, 64, 469, 322], 1120);
                step(f, Op::ArrayAt(Elem::Float), &[2, 40, 235], 1121);
                step(f, Op::ClampF, &[235, 469, 471, 319], 1122);
                step(f, Op::MulF, &[319, 481, 320], 1123);
                step(f, Op::SinF, &[320, 321], 1124);
                step(f, Op::MulF, &[321, 321, 323], 1125);
                step(f, Op::MulF, &[322, 323, 324], 1126);
                step(f, Op::AddF, &[63, 324, 325], 1127);
                step(f, Op::FootAvoidance, &[179, 99, 241, 31, 325, 181], 1128);
                step(f, Op::SubV, &[181, 179, 182], 1129);
                step(f, Op::LengthV, &[182, 326], 1130);
                step(f, Op::AddF, &[326, 324, 327], 1131);
                step(f, Op::DivF, &[326, 327, 328], 1132);
                step(f, Op::ScaleV, &[182, 328, 183], 1133);
                step(f, Op::AddV, &[179, 183, 184], 1134);
                step(f, Op::MakeTransform, &[184, 36, 306, 51], 1135);
                step(f, Op::ArraySetAt(Elem::Transform), &[3, 40, 51], 1136);
                1136
            }
            1136 => {
                step(f, Op::ArrayAt(Elem::Float), &[2, 40, 235], 1137);
                step(f, Op::GreaterEqualF, &[235, 471, 30], 1138);
                step(f, Op::ArraySetAt(Elem::Bool), &[0, 40, 30], 1139);
                step(f, Op::Copy(ValueType::Bone), &[0, 17], 1140);
                step(f, Op::Copy(ValueType::Int), &[2, 42], 1141);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 42, 57], 1142);
                step(f, Op::BreakTransform, &[57, 216, 43, 217], 1143);
                step(f, Op::MakeVector, &[469, 469, 36, 226], 1144);
                step(f, Op::AddV, &[216, 226, 227], 1145);
                step(f, Op::GetTransform, &[17, 52, 53, 59], 1146);
                step(f, Op::BreakTransform, &[59, 221, 45, 222], 1147);
                step(f, Op::MakeTransform, &[227, 45, 306, 61], 1148);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 42, 20], 1149);
                step(f, Op::GetTransform, &[20, 52, 53, 60], 1150);
                step(f, Op::BreakTransform, &[60, 223, 46, 224], 1151);
                step(f, Op::SubV, &[223, 221, 225], 1152);
                step(f, Op::AddV, &[227, 225, 228], 1153);
                step(f, Op::FootPivots, &[227, 228, 38, 37, 36, 39, 229, 230, 231], 1154);
                step(f, Op::GetParent, &[17, 18], 1155);
                step(f, Op::GetParent, &[18, 19], 1156);
                step(f, Op::GetTransform, &[19, 52, 54, 58], 1157);
                step(f, Op::BreakTransform, &[58, 218, 44, 219], 1158);
                step(f, Op::SubV, &[216, 218, 220], 1159);
                step(f, Op::DotV, &[220, 309, 373], 1160);
                step(f, Op::RemapF, &[373, 66, 65, 67, 469, 53, 376], 1161);
                step(f, Op::LengthV, &[0, 374], 1162);
                step(f, Op::RemapF, &[374, 469, 73, 469, 471, 53, 375], 1163);
                step(f, Op::MulF, &[376, 375, 377], 1164);
                step(f, Op::QuatFromAxisAngle, &[311, 377, 47], 1165);
                step(f, Op::RotateAroundPoint, &[61, 229, 47, 62], 1166);
                step(f, Op::SubV, &[230, 229, 232], 1167);
                step(f, Op::RotateVector, &[47, 232, 233], 1168);
                step(f, Op::AddV, &[229, 233, 234], 1169);
                step(f, Op::RemapF, &[373, 68, 66, 69, 469, 53, 378], 1170);
                step(f, Op::MulF, &[378, 375, 379], 1171);
                step(f, Op::QuatFromAxisAngle, &[311, 379, 48], 1172);
                step(f, Op::RotateAroundPoint, &[62, 234, 48, 63], 1173);
                step(f, Op::RemapF, &[373, 70, 71, 469, 72, 53, 380], 1174);
                step(f, Op::MulF, &[380, 375, 381], 1175);
                step(f, Op::QuatFromAxisAngle, &[311, 381, 49], 1176);
                step(f, Op::RotateAroundPoint, &[63, 231, 49, 64], 1177);
                step(f, Op::SubF, &[471, 8, 382], 1178);
                step(f, Op::MulF, &[7, 382, 383], 1179);
                step(f, Op::LimitRotationAroundZ, &[43, 383, 74, 50], 1180);
                step(f, Op::RotateAroundPoint, &[64, 216, 50, 65], 1181);
                step(f, Op::ArraySetAt(Elem::Transform), &[4, 42, 65], 1182);
                step(f, Op::JumpIfFalse, &[3, 1239], 1183)
            }
            1183 => {
                step(f, Op::ArrayAt(Elem::Transform), &[3, 42, 57], 1184);
                step(f, Op::BreakTransform, &[57, 216, 43, 217], 1185);
                step(f, Op::MakeVector, &[469, 469, 36, 226], 1186);
                step(f, Op::AddV, &[216, 226, 227], 1187);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 42, 20], 1188);
                step(f, Op::GetTransform, &[20, 52, 53, 60], 1189);
                step(f, Op::BreakTransform, &[60, 223, 46, 224], 1190);
                step(f, Op::GetTransform, &[17, 52, 53, 59], 1191);
                step(f, Op::BreakTransform, &[59, 221, 45, 222], 1192);
                step(f, Op::SubV, &[223, 221, 225], 1193);
                step(f, Op::AddV, &[227, 225, 228], 1194);
                step(f, Op::FootPivots, &[227, 228, 38, 37, 36, 39, 229, 230, 231], 1195);
                step(f, Op::DrawPoint, &[231, 482, 311], 1196);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 42, 57], 1197);
                step(f, Op::BreakTransform, &[57, 216, 43, 217], 1198);
                step(f, Op::MakeVector, &[469, 469, 36, 226], 1199);
                step(f, Op::AddV, &[216, 226, 227], 1200);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 42, 20], 1201);
                step(f, Op::GetTransform, &[20, 52, 53, 60], 1202);
                step(f, Op::BreakTransform, &[60, 223, 46, 224], 1203);
                step(f, Op::GetTransform, &[17, 52, 53, 59], 1204);
                step(f, Op::BreakTransform, &[59, 221, 45, 222], 1205);
                step(f, Op::SubV, &[223, 221, 225], 1206);
                step(f, Op::AddV, &[227, 225, 228], 1207);
                step(f, Op::FootPivots, &[227, 228, 38, 37, 36, 39, 229, 230, 231], 1208);
                step(f, Op::DrawPoint, &[229, 482, 309], 1209);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 42, 57], 1210);
                step(f, Op::BreakTransform, &[57, 216, 43, 217], 1211);
                step(f, Op::MakeVector, &[469, 469, 36, 226], 1212);
                step(f, Op::AddV, &[216, 226, 227], 1213);
                step(f, Op::ArrayAt(Elem::Bone), &[2, 42, 20], 1214);
                step(f, Op::GetTransform, &[20, 52, 53, 60], 1215);
                step(f, Op::BreakTransform, &[60, 223, 46, 224], 1216);
                step(f, Op::GetTransform, &[17, 52, 53, 59], 1217);
                step(f, Op::BreakTransform, &[59, 221, 45, 222], 1218);
                step(f, Op::SubV, &[223, 221, 225], 1219);
                step(f, Op::AddV, &[227, 225, 228], 1220);
                step(f, Op::FootPivots, &[227, 228, 38, 37, 36, 39, 229, 230, 231], 1221);
                step(f, Op::GetParent, &[17, 18], 1222);
                step(f, Op::GetParent, &[18, 19], 1223);
                step(f, Op::GetTransform, &[19, 52, 54, 58], 1224);
                step(f, Op::BreakTransform, &[58, 218, 44, 219], 1225);
                step(f, Op::SubV, &[216, 218, 220], 1226);
                step(f, Op::DotV, &[220, 309, 373], 1227);
                step(f, Op::RemapF, &[373, 66, 65, 67, 469, 53, 376], 1228);
                step(f, Op::LengthV, &[0, 374], 1229);
                step(f, Op::RemapF, &[374, 469, 73, 469, 471, 53, 375], 1230);
                step(f, Op::MulF, &[376, 375, 377], 1231);
                step(f, Op::QuatFromAxisAngle, &[311, 377, 47], 1232);
                step(f, Op::SubV, &[230, 229, 232], 1233);
                step(f, Op::RotateVector, &[47, 232, 233], 1234);
                step(f, Op::AddV, &[229, 233, 234], 1235);
                step(f, Op::DrawPoint, &[234, 482, 308], 1236);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 42, 57], 1237);
                step(f, Op::DrawTransform, &[57, 480, 470], 1238);
                step(f, Op::Jump, &[1239], 1239)
            }
            1239 => {
                step(f, Op::Jump, &[651], 1240)
            }
            1240 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[1, 5], 1241);
                step(f, Op::Copy(ValueType::Int), &[52, 4], 1242);
                1242
            }
            1242 => {
                step(f, Op::ForEachNext(Elem::Bone), &[5, 4, 1, 5, 6, 1297], 1243)
            }
            1243 => {
                step(f, Op::Copy(ValueType::Bone), &[1, 21], 1244);
                step(f, Op::Copy(ValueType::Int), &[5, 43], 1245);
                step(f, Op::GetParent, &[21, 22], 1246);
                step(f, Op::GetParent, &[22, 23], 1247);
                step(f, Op::GetParent, &[23, 24], 1248);
                step(f, Op::GetTransform, &[24, 52, 54, 66], 1249);
                step(f, Op::BreakTransform, &[66, 235, 51, 236], 1250);
                step(f, Op::LengthV, &[1, 385], 1251);
                step(f, Op::ClavicleOffset, &[6, 385, 79, 82, 386], 1252);
                step(f, Op::MakeVector, &[469, 469, 386, 237], 1253);
                step(f, Op::AddV, &[235, 237, 238], 1254);
                step(f, Op::MakeTransform, &[238, 51, 306, 67], 1255);
                step(f, Op::SetTransform, &[24, 67, 52, 53, 471], 1256);
                step(f, Op::GetParent, &[21, 22], 1257);
                step(f, Op::GetParent, &[22, 23], 1258);
                step(f, Op::GetTransform, &[21, 52, 54, 68], 1259);
                step(f, Op::GetTransform, &[23, 52, 54, 69], 1260);
                step(f, Op::BreakTransform, &[69, 239, 53, 240], 1261);
                step(f, Op::Equals(Elem::Int), &[43, 52, 42], 1262);
                step(f, Op::Select(ValueType::Int), &[42, 53, 52, 44], 1263);
                step(f, Op::ArrayAt(Elem::Float), &[0, 44, 384], 1264);
                step(f, Op::ArmSwingRotation, &[384, 1, 0, 80, 475, 483, 471, 79, 77, 78, 475, 475, 471, 387], 1265);
                step(f, Op::QuatFromAxisAngle, &[311, 387, 52], 1266);
                step(f, Op::RotateAroundPoint, &[68, 239, 52, 70], 1267);
                step(f, Op::BreakTransform, &[70, 241, 54, 242], 1268);
                step(f, Op::LengthV, &[1, 385], 1269);
                step(f, Op::RemapF, &[385, 469, 79, 469, 81, 53, 388], 1270);
                step(f, Op::MakeVector, &[469, 469, 388, 243], 1271);
                step(f, Op::AddV, &[241, 243, 244], 1272);
                step(f, Op::MakeTransform, &[244, 54, 306, 71], 1273);
                step(f, Op::Select(ValueType::Vec3), &[42, 312, 311, 246], 1274);
                step(f, Op::Select(ValueType::Vec3), &[42, 309, 313, 247], 1275);
                step(f, Op::ArrayAt(Elem::Vec3), &[1, 43, 245], 1276);
                step(f, Op::TwoBoneIK, &[23, 22, 21, 71, 246, 247, 245, 52, 471, 54, 484, 485, 53, 43, 389], 1277);
                step(f, Op::JumpIfFalse, &[3, 1296], 1278)
            }
            1278 => {
                step(f, Op::GetParent, &[21, 22], 1279);
                step(f, Op::GetParent, &[22, 23], 1280);
                step(f, Op::GetTransform, &[23, 52, 54, 69], 1281);
                step(f, Op::BreakTransform, &[69, 239, 53, 240], 1282);
                step(f, Op::GetTransform, &[21, 52, 54, 68], 1283);
                step(f, Op::Equals(Elem::Int), &[43, 52, 42], 1284);
                step(f, Op::Select(ValueType::Int), &[42, 53, 52, 44], 1285);
                step(f, Op::ArrayAt(Elem::Float), &[0, 44, 384], 1286);
                step(f, Op::ArmSwingRotation, &[384, 1, 0, 80, 475, 483, 471, 79, 77, 78, 475, 475, 471, 387], 1287);
                step(f, Op::QuatFromAxisAngle, &[311, 387, 52], 1288);
                step(f, Op::RotateAroundPoint, &[68, 239, 52, 70], 1289);
                step(f, Op::BreakTransform, &[70, 241, 54, 242], 1290);
                step(f, Op::LengthV, &[1, 385], 1291);
                step(f, Op::RemapF, &[385, 469, 79, 469, 81, 53, 388], 1292);
                step(f, Op::MakeVector, &[469, 469, 388, 243], 1293);
                step(f, Op::AddV, &[241, 243, 244], 1294);
                step(f, Op::DrawLine, &[239, 244, 470, 309], 1295);
                step(f, Op::Jump, &[1296], 1296)
            }
            1296 => {
                step(f, Op::Jump, &[1242], 1297)
            }
            1297 => {
                step(f, Op::Copy(ValueType::Float), &[469, 391], 1298);
                step(f, Op::Copy(ValueType::Float), &[477, 392], 1299);
                step(f, Op::Copy(ValueType::Bool), &[54, 44], 1300);
                step(f, Op::Copy(ValueType::Array(Elem::Transform)), &[3, 6], 1301);
                step(f, Op::Copy(ValueType::Int), &[52, 45], 1302);
                step(f, Op::MakeVector, &[469, 469, 41, 250], 1303);
                1303
            }
            1303 => {
                step(f, Op::ForEachNext(Elem::Transform), &[6, 45, 72, 46, 47, 1316], 1304)
            }
            1304 => {
                step(f, Op::BreakTransform, &[72, 248, 55, 249], 1305);
                step(f, Op::AddV, &[248, 250, 251], 1306);
                step(f, Op::SubV, &[248, 250, 252], 1307);
                step(f, Op::SphereTrace, &[251, 252, 40, 45, 253, 254, 393], 1308);
                step(f, Op::BreakVector, &[253, 394, 395, 396], 1309);
                step(f, Op::LessF, &[396, 392, 46], 1310);
                step(f, Op::And, &[45, 46, 47], 1311);
                step(f, Op::JumpIfFalse, &[47, 1315], 1312)
            }
            1312 => {
                step(f, Op::Copy(ValueType::Float), &[396, 392], 1313);
                step(f, Op::Copy(ValueType::Bool), &[53, 44], 1314);
                step(f, Op::Jump, &[1315], 1315)
            }
            1315 => {
                step(f, Op::Jump, &[1303], 1316)
            }
            1316 => {
                step(f, Op::Select(ValueType::Float), &[44, 392, 469, 397], 1317);
                step(f, Op::ClampF, &[397, 44, 45, 398], 1318);
                step(f, Op::Copy(ValueType::Float), &[398, 391], 1319);
                step(f, Op::Jump, &[1320], 1320)
            }
            1320 => {
                step(f, Op::FloatLerp, &[9, 391, 35, 399], 1321);
                step(f, Op::Copy(ValueType::Float), &[399, 9], 1322);
                step(f, Op::GetTransform, &[37, 52, 53, 77], 1323);
                step(f, Op::BreakTransform, &[77, 267, 62, 268], 1324);
                step(f, Op::PelvisLean, &[1, 84, 89, 90, 412, 413], 1325);
                step(f, Op::LengthV, &[0, 390], 1326);
                step(f, Op::RemapF, &[390, 469, 84, 469, 83, 53, 400], 1327);
                step(f, Op::MulF, &[6, 486, 401], 1328);
                step(f, Op::SinF, &[401, 402], 1329);
                step(f, Op::MulF, &[400, 402, 403], 1330);
                step(f, Op::AddF, &[403, 9, 404], 1331);
                step(f, Op::MakeVector, &[469, 413, 404, 269], 1332);
                step(f, Op::AddV, &[267, 269, 270], 1333);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 52, 73], 1334);
                step(f, Op::BreakTransform, &[73, 255, 56, 256], 1335);
                step(f, Op::BreakVector, &[255, 414, 415, 416], 1336);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 53, 74], 1337);
                step(f, Op::BreakTransform, &[74, 257, 57, 258], 1338);
                step(f, Op::BreakVector, &[257, 417, 418, 419], 1339);
                step(f, Op::SubF, &[416, 419, 420], 1340);
                step(f, Op::PelvisSideLean, &[420, 91, 92, 421], 1341);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 52, 75], 1342);
                step(f, Op::BreakTransform, &[75, 261, 58, 262], 1343);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 53, 76], 1344);
                step(f, Op::BreakTransform, &[76, 263, 59, 264], 1345);
                step(f, Op::SlerpQ, &[58, 59, 470, 60], 1346);
                step(f, Op::EulerFromQuat, &[60, 52, 265], 1347);
                step(f, Op::BreakVector, &[265, 408, 409, 410], 1348);
                step(f, Op::RemapF, &[390, 85, 84, 469, 86, 53, 406], 1349);
                step(f, Op::SubV, &[255, 257, 259], 1350);
                step(f, Op::RotateVector, &[0, 309, 260], 1351);
                step(f, Op::DotV, &[259, 260, 405], 1352);
                step(f, Op::MulF, &[406, 405, 407], 1353);
                step(f, Op::AddF, &[410, 407, 411], 1354);
                step(f, Op::MakeVector, &[412, 421, 411, 266], 1355);
                step(f, Op::QuatFromEuler, &[266, 52, 61], 1356);
                step(f, Op::MakeTransform, &[270, 61, 306, 78], 1357);
                step(f, Op::SetTransform, &[38, 78, 52, 53, 471], 1358);
                step(f, Op::GetTransform, &[39, 53, 53, 79], 1359);
                step(f, Op::BreakTransform, &[79, 271, 66, 272], 1360);
                step(f, Op::LengthV, &[0, 390], 1361);
                step(f, Op::RemapF, &[390, 85, 84, 469, 86, 53, 406], 1362);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 52, 73], 1363);
                step(f, Op::BreakTransform, &[73, 255, 56, 256], 1364);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 53, 74], 1365);
                step(f, Op::BreakTransform, &[74, 257, 57, 258], 1366);
                step(f, Op::SubV, &[255, 257, 259], 1367);
                step(f, Op::RotateVector, &[0, 309, 260], 1368);
                step(f, Op::DotV, &[259, 260, 405], 1369);
                step(f, Op::MulF, &[406, 405, 407], 1370);
                step(f, Op::QuatFromAxisAngle, &[308, 407, 63], 1371);
                step(f, Op::DivF, &[87, 482, 422], 1372);
                step(f, Op::QuatScale, &[63, 422, 64], 1373);
                step(f, Op::MulQ, &[66, 64, 70], 1374);
                step(f, Op::MakeTransform, &[271, 70, 306, 83], 1375);
                step(f, Op::SetTransform, &[40, 83, 53, 53, 471], 1376);
                step(f, Op::GetTransform, &[41, 53, 53, 80], 1377);
                step(f, Op::BreakTransform, &[80, 273, 67, 274], 1378);
                step(f, Op::LengthV, &[0, 390], 1379);
                step(f, Op::RemapF, &[390, 85, 84, 469, 86, 53, 406], 1380);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 52, 73], 1381);
                step(f, Op::BreakTransform, &[73, 255, 56, 256], 1382);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 53, 74], 1383);
                step(f, Op::BreakTransform, &[74, 257, 57, 258], 1384);
                step(f, Op::SubV, &[255, 257, 259], 1385);
                step(f, Op::RotateVector, &[0, 309, 260], 1386);
                step(f, Op::DotV, &[259, 260, 405], 1387);
                step(f, Op::MulF, &[406, 405, 407], 1388);
                step(f, Op::QuatFromAxisAngle, &[308, 407, 63], 1389);
                step(f, Op::DivF, &[87, 482, 422], 1390);
                step(f, Op::QuatScale, &[63, 422, 64], 1391);
                step(f, Op::MulQ, &[67, 64, 71], 1392);
                step(f, Op::MakeTransform, &[273, 71, 306, 84], 1393);
                step(f, Op::SetTransform, &[42, 84, 53, 53, 471], 1394);
                step(f, Op::GetTransform, &[43, 53, 53, 81], 1395);
                step(f, Op::BreakTransform, &[81, 275, 68, 276], 1396);
                step(f, Op::LengthV, &[0, 390], 1397);
                step(f, Op::RemapF, &[390, 85, 84, 469, 86, 53, 406], 1398);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 52, 73], 1399);
                step(f, Op::BreakTransform, &[73, 255, 56, 256], 1400);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 53, 74], 1401);
                step(f, Op::BreakTransform, &[74, 257, 57, 258], 1402);
                step(f, Op::SubV, &[255, 257, 259], 1403);
                step(f, Op::RotateVector, &[0, 309, 260], 1404);
                step(f, Op::DotV, &[259, 260, 405], 1405);
                step(f, Op::MulF, &[406, 405, 407], 1406);
                step(f, Op::QuatFromAxisAngle, &[308, 407, 63], 1407);
                step(f, Op::DivF, &[87, 482, 422], 1408);
                step(f, Op::QuatScale, &[63, 422, 64], 1409);
                step(f, Op::MulQ, &[68, 64, 72], 1410);
                step(f, Op::MakeTransform, &[275, 72, 306, 85], 1411);
                step(f, Op::SetTransform, &[44, 85, 53, 53, 471], 1412);
                step(f, Op::GetTransform, &[45, 53, 53, 82], 1413);
                step(f, Op::BreakTransform, &[82, 277, 69, 278], 1414);
                step(f, Op::LengthV, &[0, 390], 1415);
                step(f, Op::RemapF, &[390, 85, 84, 469, 86, 53, 406], 1416);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 52, 73], 1417);
                step(f, Op::BreakTransform, &[73, 255, 56, 256], 1418);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 53, 74], 1419);
                step(f, Op::BreakTransform, &[74, 257, 57, 258], 1420);
                step(f, Op::SubV, &[255, 257, 259], 1421);
                step(f, Op::RotateVector, &[0, 309, 260], 1422);
                step(f, Op::DotV, &[259, 260, 405], 1423);
                step(f, Op::MulF, &[406, 405, 407], 1424);
                step(f, Op::QuatFromAxisAngle, &[308, 407, 63], 1425);
                step(f, Op::QuatScale, &[63, 88, 65], 1426);
                step(f, Op::MulQ, &[69, 65, 73], 1427);
                step(f, Op::MakeTransform, &[277, 73, 306, 86], 1428);
                step(f, Op::SetTransform, &[46, 86, 53, 53, 471], 1429);
                step(f, Op::Copy(ValueType::Float), &[469, 423], 1430);
                step(f, Op::Copy(ValueType::Float), &[469, 424], 1431);
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 15], 1432);
                step(f, Op::Copy(ValueType::Int), &[52, 48], 1433);
                1433
            }
            1433 => {
                step(f, Op::ForEachNext(Elem::Bone), &[15, 48, 25, 49, 50, 1463], 1434)
            }
            1434 => {
                step(f, Op::GetParent, &[25, 26], 1435);
                step(f, Op::GetParent, &[26, 27], 1436);
                step(f, Op::GetTransform, &[27, 52, 54, 87], 1437);
                step(f, Op::BreakTransform, &[87, 279, 74, 280], 1438);
                step(f, Op::BreakVector, &[279, 425, 426, 427], 1439);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 49, 88], 1440);
                step(f, Op::BreakTransform, &[88, 281, 75, 282], 1441);
                step(f, Op::BreakVector, &[281, 428, 429, 430], 1442);
                step(f, Op::ArrayAt(Elem::Float), &[1, 49, 434], 1443);
                step(f, Op::MulF, &[434, 93, 435], 1444);
                step(f, Op::MulF, &[435, 435, 436], 1445);
                step(f, Op::SubF, &[425, 428, 431], 1446);
                step(f, Op::SubF, &[426, 429, 432], 1447);
                step(f, Op::MakeVector, &[431, 432, 469, 283], 1448);
                step(f, Op::DotV, &[283, 283, 433], 1449);
                step(f, Op::SubF, &[436, 433, 437], 1450);
                step(f, Op::SqrtF, &[437, 438], 1451);
                step(f, Op::AddF, &[430, 438, 439], 1452);
                step(f, Op::SubF, &[427, 439, 440], 1453);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 49, 48], 1454);
                step(f, Op::ArrayAt(Elem::Float), &[2, 49, 441], 1455);
                step(f, Op::RemapF, &[441, 470, 471, 469, 471, 53, 442], 1456);
                step(f, Op::RemapF, &[441, 469, 96, 471, 469, 53, 443], 1457);
                step(f, Op::MaxF, &[442, 443, 444], 1458);
                step(f, Op::Select(ValueType::Float), &[48, 471, 444, 445], 1459);
                step(f, Op::MulF, &[440, 445, 446], 1460);
                step(f, Op::MaxF, &[424, 446, 447], 1461);
                step(f, Op::Copy(ValueType::Float), &[447, 424], 1462);
                step(f, Op::Jump, &[1433], 1463)
            }
            1463 => {
                step(f, Op::ClampF, &[424, 469, 94, 448], 1464);
                step(f, Op::Copy(ValueType::Float), &[448, 423], 1465);
                step(f, Op::Jump, &[1466], 1466)
            }
            1466 => {
                step(f, Op::GreaterF, &[423, 10, 49], 1467);
                step(f, Op::Select(ValueType::Float), &[49, 98, 95, 449], 1468);
                step(f, Op::FloatLerp, &[10, 423, 449, 450], 1469);
                step(f, Op::Copy(ValueType::Float), &[450, 10], 1470);
                step(f, Op::GetTransform, &[47, 52, 54, 89], 1471);
                step(f, Op::BreakTransform, &[89, 284, 76, 285], 1472);
                step(f, Op::MakeVector, &[469, 469, 10, 286], 1473);
                step(f, Op::SubV, &[284, 286, 287], 1474);
                step(f, Op::MakeTransform, &[287, 76, 306, 90], 1475);
                step(f, Op::SetTransform, &[48, 90, 52, 53, 471], 1476);
                step(f, Op::JumpIfFalse, &[3, 1484], 1477)
            }
            1477 => {
                step(f, Op::GetTransform, &[47, 52, 54, 89], 1478);
                step(f, Op::BreakTransform, &[89, 284, 76, 285], 1479);
                step(f, Op::MakeVector, &[469, 469, 10, 286], 1480);
                step(f, Op::SubV, &[284, 286, 287], 1481);
                step(f, Op::MakeTransform, &[287, 76, 306, 90], 1482);
                step(f, Op::DrawTransform, &[90, 487, 470], 1483);
                step(f, Op::Jump, &[1484], 1484)
            }
            1484 => {
                step(f, Op::Copy(ValueType::Array(Elem::Bone)), &[0, 6], 1485);
                step(f, Op::Copy(ValueType::Int), &[52, 7], 1486);
                1486
            }
            1486 => {
                step(f, Op::ForEachNext(Elem::Bone), &[6, 7, 2, 8, 9, 1538], 1487)
            }
            1487 => {
                step(f, Op::Copy(ValueType::Bone), &[2, 28], 1488);
                step(f, Op::Copy(ValueType::Int), &[8, 51], 1489);
                step(f, Op::GetParent, &[28, 29], 1490);
                step(f, Op::GetParent, &[29, 30], 1491);
                step(f, Op::GetTransform, &[30, 52, 54, 91], 1492);
                step(f, Op::BreakTransform, &[91, 288, 77, 289], 1493);
                step(f, Op::ArrayAt(Elem::Transform), &[4, 51, 92], 1494);
                step(f, Op::BreakTransform, &[92, 290, 78, 291], 1495);
                step(f, Op::SubV, &[290, 288, 292], 1496);
                step(f, Op::LengthV, &[292, 459], 1497);
                step(f, Op::ArrayAt(Elem::Float), &[1, 51, 451], 1498);
                step(f, Op::MulF, &[451, 99, 452], 1499);
                step(f, Op::ArrayAt(Elem::Bool), &[0, 51, 50], 1500);
                step(f, Op::ArrayAt(Elem::Float), &[2, 51, 453], 1501);
                step(f, Op::ClampF, &[453, 469, 471, 454], 1502);
                step(f, Op::MulF, &[454, 481, 455], 1503);
                step(f, Op::SinF, &[455, 456], 1504);
                step(f, Op::MulF, &[456, 100, 457], 1505);
                step(f, Op::Select(ValueType::Float), &[50, 469, 457, 458], 1506);
                step(f, Op::SubF, &[452, 458, 460], 1507);
                step(f, Op::SubF, &[459, 460, 461], 1508);
                step(f, Op::MaxF, &[461, 469, 462], 1509);
                step(f, Op::MulF, &[462, 462, 463], 1510);
                step(f, Op::AddF, &[462, 458, 464], 1511);
                step(f, Op::DivF, &[463, 464, 465], 1512);
                step(f, Op::SubF, &[459, 465, 466], 1513);
                step(f, Op::DivF, &[466, 459, 467], 1514);
                step(f, Op::ScaleV, &[292, 467, 293], 1515);
                step(f, Op::AddV, &[288, 293, 294], 1516);
                step(f, Op::ClampSpatially, &[294, 288, 469, 452, 295], 1517);
                step(f, Op::MakeTransform, &[295, 78, 306, 93], 1518);
                step(f, Op::Equals(Elem::Int), &[51, 52, 51], 1519);
                step(f, Op::Select(ValueType::Vec3), &[51, 312, 311, 300], 1520);
                step(f, Op::Select(ValueType::Vec3), &[51, 309, 313, 301], 1521);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 51, 94], 1522);
                step(f, Op::BreakTransform, &[94, 296, 79, 297], 1523);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 51, 298], 1524);
                step(f, Op::KneeVector, &[79, 0, 298, 101, 102, 299], 1525);
                step(f, Op::TwoBoneIK, &[30, 29, 28, 93, 300, 301, 299, 52, 471, 54, 484, 485, 53, 52, 468], 1526);
                step(f, Op::JumpIfFalse, &[3, 1537], 1527)
            }
            1527 => {
                step(f, Op::GetParent, &[28, 29], 1528);
                step(f, Op::GetTransform, &[29, 52, 54, 95], 1529);
                step(f, Op::BreakTransform, &[95, 302, 80, 303], 1530);
                step(f, Op::ArrayAt(Elem::Transform), &[3, 51, 94], 1531);
                step(f, Op::BreakTransform, &[94, 296, 79, 297], 1532);
                step(f, Op::ArrayAt(Elem::Vec3), &[0, 51, 298], 1533);
                step(f, Op::KneeVector, &[79, 0, 298, 101, 102, 299], 1534);
                step(f, Op::AddV, &[302, 299, 304], 1535);
                step(f, Op::DrawLine, &[302, 304, 470, 314], 1536);
                step(f, Op::Jump, &[1537], 1537)
            }
            1537 => {
                step(f, Op::Jump, &[1486], 1538)
            }
            1538 => {
                step(f, Op::End, &[], 1539)
            }
            _ => return,
        } };
    }
}
