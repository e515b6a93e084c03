//! The native baselines in `crates/strider-native` (code generated ahead of time by
//! `strider native`) are current and behave exactly like the interpreter.

use std::path::Path;
use std::sync::Arc;
use strider::host::scenario::{Scenario, Simulation};
use strider::vm::native::NativeProgram;
use strider::{FrameInput, InputPose, Instance, Program};

/// The shipped graphs with a native baseline: graph file, generated file, its code.
fn baselines() -> [(&'static str, &'static str, &'static NativeProgram); 2] {
    [
        (
            "graphs/locomotion.ron",
            "crates/strider-native/src/graphs/locomotion.rs",
            &strider_native::graphs::locomotion::NATIVE,
        ),
        (
            "graphs/foot_ik.ron",
            "crates/strider-native/src/graphs/foot_ik.rs",
            &strider_native::graphs::foot_ik::NATIVE,
        ),
    ]
}

fn compile(graph: &str) -> Program {
    strider::compile_file(Path::new(graph)).unwrap_or_else(|d| panic!("{graph}: {d:?}"))
}

#[test]
fn generated_files_are_current() {
    for (graph, file, _) in baselines() {
        let program = compile(graph);
        let expected =
            strider_cli::native_source(&program, Path::new(graph), Some(Path::new(file)));
        let actual = std::fs::read_to_string(file).unwrap_or_default();
        assert!(
            actual == expected,
            "{file} is out of date with {graph}; regenerate it:\n  \
             cargo run --release -- native {graph} --out {file}"
        );
    }
}

#[test]
fn find_picks_the_baseline_of_its_program_only() {
    for (graph, _, native) in baselines() {
        let program = compile(graph);
        assert!(native.matches(&program));
        let found = strider_native::find(&program).expect("a baseline");
        assert_eq!(found.name, native.name);
    }
    let other = compile("graphs/pelvis_bob.ron");
    assert!(strider_native::find(&other).is_none());
}

#[test]
fn native_code_of_another_program_is_refused() {
    let program = Arc::new(compile("graphs/pelvis_bob.ron"));
    let skeleton = strider::load_skeleton(Path::new("graphs/skeletons/mannequin.ron"))
        .expect("skeleton")
        .skeleton;
    let mut instance = Instance::new(program, skeleton).expect("instance");
    let before = instance.slots().clone();
    let err = instance
        .run_forward_native(
            &strider_native::graphs::locomotion::NATIVE,
            &FrameInput::default(),
            &strider::EmptyWorld,
            false,
        )
        .expect_err("a mismatch");
    assert!(err.to_string().contains("pelvis_bob"), "{err}");
    assert_eq!(instance.slots(), &before, "nothing ran");
}

/// Runs an interpreted and a native instance side by side through a scenario and asserts
/// that every frame's pose and every slot are bit-identical.
fn same_through(graph: &str, native: &NativeProgram, scenario: &str, hz: u32) {
    let program = Arc::new(compile(graph));
    let skeleton = strider::load_skeleton(Path::new("graphs/skeletons/mannequin.ron"))
        .expect("skeleton")
        .skeleton;
    let mut interpreted = Instance::new(Arc::clone(&program), Arc::clone(&skeleton)).unwrap();
    let mut compiled = Instance::new(program, skeleton).unwrap();
    let scenario = Scenario::load(scenario).expect("scenario");
    let mut sim = Simulation::new(&scenario, hz);
    let mut frames = 0;
    while let Some(frame) = sim.next_frame() {
        let input = FrameInput {
            dt: frame.dt,
            component_to_world: frame.component_to_world,
            pose: InputPose::Rest,
        };
        // Debug drawing on every other frame: the draw handlers are shared too.
        let debug = frames % 2 == 0;
        interpreted.run_forward(&input, sim.world(), debug);
        compiled
            .run_forward_native(native, &input, sim.world(), debug)
            .expect("generated from this program");
        let (a, b) = (interpreted.pose().locals(), compiled.pose().locals());
        assert!(
            a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.bit_eq(y)),
            "{graph} in {}: poses differ at frame {frames}",
            scenario.name
        );
        assert_eq!(
            interpreted.debug_draw().primitives().len(),
            compiled.debug_draw().primitives().len()
        );
        frames += 1;
    }
    assert!(
        interpreted.slots().bit_eq(compiled.slots()),
        "{graph} in {}: slots differ",
        scenario.name
    );
    assert!(frames > 100, "{frames} frames");
}

#[test]
fn locomotion_native_is_bit_identical_walking_and_on_stairs() {
    let native = &strider_native::graphs::locomotion::NATIVE;
    same_through(
        "graphs/locomotion.ron",
        native,
        "graphs/scenarios/start_stop.ron",
        60,
    );
    same_through(
        "graphs/locomotion.ron",
        native,
        "graphs/scenarios/stairs_up_down.ron",
        30,
    );
    same_through(
        "graphs/locomotion.ron",
        native,
        "graphs/scenarios/strafe_8dir.ron",
        144,
    );
}

#[test]
fn foot_ik_native_is_bit_identical() {
    let native = &strider_native::graphs::foot_ik::NATIVE;
    same_through(
        "graphs/foot_ik.ron",
        native,
        "graphs/scenarios/standing_on_stairs.ron",
        60,
    );
    same_through(
        "graphs/foot_ik.ron",
        native,
        "graphs/scenarios/uneven_ground.ron",
        240,
    );
}
