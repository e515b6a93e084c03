//! The batch loop's two copies of machine code (`strider::vm::batch_code`: the baseline
//! x86-64 one and the AVX2 one) give a crowd bit-identical poses, debug drawing, variables
//! and slots, frame by frame, through scenarios where the characters branch apart.
//!
//! One test in its own binary: `allow_avx2` switches the whole process, so no other test
//! may run batches at the same time.

use std::path::Path;
use std::sync::Arc;
use strider::Instance;
use strider::host::scenario::Scenario;
use strider::vm::{BatchCode, allow_avx2, batch_code};

mod common;

/// Runs `characters` locomotion instances through `scenario` at `hz` (character `k` offset
/// by `5 k` frames), one crowd on each copy of the batch loop, and compares them every frame.
fn both_copies_agree(scenario: &str, hz: u32, characters: usize, frames: usize) {
    let program = Arc::new(
        strider::compile_file(Path::new("graphs/locomotion.ron")).expect("locomotion compiles"),
    );
    let skeleton = strider::load_skeleton(Path::new("graphs/skeletons/mannequin.ron"))
        .expect("skeleton")
        .skeleton;
    let scenario = Scenario::load(scenario).expect("scenario");
    let (sim, track) = common::track(&scenario, hz);
    let make = || -> Vec<Instance> {
        (0..characters)
            .map(|_| Instance::new(Arc::clone(&program), Arc::clone(&skeleton)).unwrap())
            .collect()
    };
    let (mut wide, mut baseline) = (make(), make());
    for f in 0..frames {
        let input = |k: usize| common::input_at(&track, f, 5 * k);
        let debug = f % 3 == 0 || f + 1 == frames;
        allow_avx2(true);
        assert_eq!(batch_code(), BatchCode::Avx2);
        Instance::run_forward_batch(&mut wide, input, sim.world(), debug);
        allow_avx2(false);
        assert_eq!(batch_code(), BatchCode::Baseline);
        Instance::run_forward_batch(&mut baseline, input, sim.world(), debug);
        for (k, (a, b)) in wide.iter().zip(&baseline).enumerate() {
            common::assert_same_frame(&scenario.name, &program, k, f, a, b);
        }
    }
    // The last frame ran with debug: every written slot came back.
    for (k, (a, b)) in wide.iter().zip(&baseline).enumerate() {
        assert!(a.slots().bit_eq(b.slots()), "character {k}'s slots differ");
    }
}

#[test]
fn the_avx2_batch_loop_gives_what_the_baseline_one_gives() {
    allow_avx2(true);
    if batch_code() == BatchCode::Baseline {
        // No AVX2 here (or not x86-64): there is one copy, and the switch cannot add one.
        eprintln!("this processor has no AVX2: only the baseline batch loop exists here");
        return;
    }
    both_copies_agree("graphs/scenarios/strafe_8dir.ron", 60, 19, 120);
    both_copies_agree("graphs/scenarios/stairs_up_down.ron", 144, 17, 120);
    allow_avx2(true);
}
