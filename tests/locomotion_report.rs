//! The shipped graphs meet the locomotion quality targets on every shipped scenario, as
//! measured by the host's report (`strider report`) from the output poses and the world:
//! skate ≤ 0.5 cm per stance, penetration ≤ 0.5 cm, idle float ≤ 0.5 cm, no crossing legs,
//! no backward knees, pops ≤ 5 cm per 60 Hz frame, no non-finite values, and a frame-rate
//! deviation ≤ 1 cm across 30/60/144/240 Hz.

use std::path::Path;
use std::sync::Arc;
use strider_host::drive;
use strider_host::report::{Report, ReportRig, analyse, framerate_deviation};
use strider_host::scenario::Scenario;
use strider_host::world::World;
use strider_vm::Instance;

/// The flagship graph.
const LOCOMOTION: &str = "graphs/locomotion.ron";

/// Frame rates the frame-rate deviation compares.
const RATES: [u32; 4] = [30, 60, 144, 240];

/// Runs `graph` through `scenario` at 60 Hz and at every rate of [`RATES`] and returns the
/// report with the frame-rate deviation filled in.
fn measure(graph: &str, scenario: &str) -> Report {
    let program = Arc::new(
        strider_compiler::compile_file(Path::new(graph)).unwrap_or_else(|d| panic!("{d:?}")),
    );
    let skeleton = strider_graph::load_skeleton(Path::new("graphs/skeletons/mannequin.ron"))
        .unwrap_or_else(|d| panic!("{d:?}"));
    let scenario = Scenario::load(format!("graphs/scenarios/{scenario}.ron"))
        .unwrap_or_else(|e| panic!("{e}"));
    let rig = ReportRig::from_skeleton(&skeleton).unwrap();
    let mut runs = Vec::new();
    for hz in RATES {
        let mut instance = Instance::new(Arc::clone(&program), skeleton.skeleton.clone()).unwrap();
        let (frames, _) = drive::record(&mut instance, &scenario, hz, |_, _| {});
        runs.push((hz, frames));
    }
    let world = World::from_desc(&scenario.world);
    let (_, at_60) = runs.iter().find(|(hz, _)| *hz == 60).unwrap();
    let mut report = analyse(&rig, at_60, &world);
    let compared: Vec<(u32, &[_])> = runs.iter().map(|(hz, f)| (*hz, f.as_slice())).collect();
    report.framerate_deviation_cm_max = Some(framerate_deviation(&compared));
    report
}

/// Asserts every target of `graph` on `scenario`.
fn assert_targets(graph: &str, scenario: &str) {
    let report = measure(graph, scenario);
    assert!(report.frames > 0, "{scenario}: no frames");
    assert!(
        report.steps > 0 || scenario.starts_with("standing"),
        "{scenario}: never stepped"
    );
    let mut failures = Vec::new();
    for check in report.targets_met() {
        if !check.met {
            failures.push(format!(
                "{}: {} = {} {}, target ≤ {}",
                scenario, check.metric, check.value, check.unit, check.target
            ));
        }
    }
    assert!(
        failures.is_empty(),
        "{graph} on {scenario}:\n  {}\n{}",
        failures.join("\n  "),
        report.table()
    );
}

/// One test per scenario of the locomotion graph.
macro_rules! scenarios {
    ($($name:ident),* $(,)?) => {
        $(
            #[test]
            fn $name() {
                assert_targets(LOCOMOTION, stringify!($name));
            }
        )*
    };
}

scenarios!(
    walk_flat,
    run_flat,
    start_stop,
    strafe_8dir,
    reverse,
    circle_turn,
    stairs_up_down,
    slope,
    platform_edge,
    uneven_ground,
    teleport,
    hitch,
    void,
);

#[test]
fn standing_on_stairs() {
    assert_targets("graphs/foot_ik.ron", "standing_on_stairs");
}

#[test]
fn every_shipped_scenario_is_measured_here() {
    let source = include_str!("locomotion_report.rs");
    for entry in std::fs::read_dir("graphs/scenarios").unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_stem().unwrap().to_string_lossy().into_owned();
        assert!(
            source.contains(&format!(" {name},")) || source.contains(&format!("fn {name}()")),
            "scenario `{name}` has no test in tests/locomotion_report.rs"
        );
    }
}
