//! Scenario files and the simulation's frame schedule.

use std::path::PathBuf;

use glam::Vec3;
use strider_host::scenario::{
    MOVER_RATE_HZ, Scenario, ScenarioError, Segment, SimFrame, Simulation,
};

fn scenarios_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../graphs/scenarios")
}

fn shipped() -> Vec<(PathBuf, Scenario)> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(scenarios_dir())
        .expect("graphs/scenarios")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "ron"))
        .collect();
    files.sort();
    files
        .into_iter()
        .map(|p| {
            let s = Scenario::load(&p).unwrap_or_else(|e| panic!("{e}"));
            (p, s)
        })
        .collect()
}

fn load(name: &str) -> Scenario {
    Scenario::load(scenarios_dir().join(format!("{name}.ron"))).unwrap_or_else(|e| panic!("{e}"))
}

fn run(scenario: &Scenario, hz: u32) -> Vec<SimFrame> {
    let mut sim = Simulation::new(scenario, hz);
    let count = sim.frame_count();
    let frames: Vec<SimFrame> = std::iter::from_fn(|| sim.next_frame()).collect();
    assert_eq!(frames.len(), count);
    frames
}

fn parse(text: &str) -> Result<Scenario, ScenarioError> {
    Scenario::parse(text, "test.ron")
}

#[test]
fn every_shipped_scenario_loads_and_runs() {
    let all = shipped();
    let names: Vec<&str> = all.iter().map(|(_, s)| s.name.as_str()).collect();
    for expected in [
        "walk_flat",
        "run_flat",
        "start_stop",
        "strafe_8dir",
        "reverse",
        "circle_turn",
        "stairs_up_down",
        "slope",
        "platform_edge",
        "uneven_ground",
        "standing_on_stairs",
        "teleport",
        "hitch",
        "void",
    ] {
        assert!(names.contains(&expected), "missing {expected}: {names:?}");
    }
    for (path, scenario) in &all {
        let text = std::fs::read_to_string(path).unwrap();
        assert!(
            text.starts_with("//"),
            "{}: needs a comment header",
            path.display()
        );
        let d = scenario.duration();
        assert!((6.0..=15.0).contains(&d), "{}: {d} s", scenario.name);
        assert_eq!(
            scenario.timeline.first(),
            Some(&Segment::Stand { seconds: 1.0 }),
            "{}: starts with a 1 s stand",
            scenario.name
        );
        let frames = run(scenario, 60);
        for f in &frames {
            assert!(
                f.component_to_world.is_finite() && f.velocity.is_finite() && f.dt.is_finite(),
                "{} frame {}",
                scenario.name,
                f.index
            );
        }
        // The first second is standing still on the start.
        assert!(
            frames[..60].iter().all(|f| f.standing_still),
            "{}",
            scenario.name
        );
        assert!(frames[30].velocity.length() < 1e-3, "{}", scenario.name);
    }
}

fn z_at(frames: &[SimFrame], time: f64) -> Vec3 {
    frames
        .iter()
        .rev()
        .find(|f| f.time <= time + 1e-9)
        .unwrap()
        .component_to_world
        .translation
}

#[test]
fn shipped_scenarios_do_what_their_headers_say() {
    let f = run(&load("stairs_up_down"), 60);
    let top = f
        .iter()
        .map(|f| f.component_to_world.translation.z)
        .fold(f32::MIN, f32::max);
    assert!((top - 120.0).abs() < 0.01, "{top}");
    let end = f.last().unwrap().component_to_world.translation;
    assert!(end.z.abs() < 1e-3 && end.y > 780.0, "{end}");

    let f = run(&load("slope"), 60);
    let top = f
        .iter()
        .map(|f| f.component_to_world.translation.z)
        .fold(f32::MIN, f32::max);
    assert!((top - 109.19).abs() < 0.05, "{top}");
    assert!(f.last().unwrap().component_to_world.translation.y > 950.0);

    // On ramps and rolling ground the capsule bottom is on the surface under its axis.
    for name in ["slope", "uneven_ground"] {
        let s = load(name);
        let mut sim = Simulation::new(&s, 60);
        while let Some(frame) = sim.next_frame() {
            let p = frame.component_to_world.translation;
            let (ground, _) = sim.world().ground_height(p.x, p.y, p.z + 50.0).unwrap();
            assert!(
                (p.z - ground).abs() < 0.05,
                "{name} t = {}: {p} vs {ground}",
                frame.time
            );
        }
    }

    let f = run(&load("void"), 60);
    let end = f.last().unwrap().component_to_world.translation;
    assert!(end.z < -500.0, "{end}");

    let f = run(&load("platform_edge"), 60);
    let on_edge = z_at(&f, 2.0);
    assert!(
        on_edge.z > 15.0 && on_edge.z <= 20.0,
        "perched on the edge: {on_edge}"
    );
    let end = f.last().unwrap().component_to_world.translation;
    assert!(end.z.abs() < 1e-3 && end.y > 700.0, "stepped off: {end}");

    let f = run(&load("standing_on_stairs"), 60);
    assert!(f.iter().all(|f| f.standing_still));
    let p = f.last().unwrap().component_to_world.translation;
    assert!(
        p.z > 10.0 && p.z <= 15.0 && (p.x - 3.0).abs() < 1e-3 && (p.y - 300.0).abs() < 1e-3,
        "{p}"
    );
    // Teleported to the mirrored stance, facing −Y.
    let forward = f
        .last()
        .unwrap()
        .component_to_world
        .transform_vector(Vec3::Y);
    assert!((forward - Vec3::NEG_Y).length() < 1e-4, "{forward}");

    let f = run(&load("circle_turn"), 60);
    let end = f.last().unwrap().component_to_world.translation;
    assert!(end.truncate().length() < 60.0, "back near the start: {end}");

    let f = run(&load("strafe_8dir"), 60);
    for frame in &f {
        let forward = frame.component_to_world.transform_vector(Vec3::Y);
        assert!((forward - Vec3::Y).length() < 1e-4, "always looking at +Y");
    }

    let f = run(&load("teleport"), 60);
    let flagged: Vec<&SimFrame> = f.iter().filter(|f| f.teleported).collect();
    assert_eq!(flagged.len(), 1);
    assert!((flagged[0].time - 4.0).abs() < 1e-9);
    assert_eq!(
        flagged[0].component_to_world.translation,
        Vec3::new(500.0, 440.0, 0.0)
    );

    let f = run(&load("hitch"), 60);
    assert_eq!(f.iter().filter(|f| f.dt == 0.0).count(), 5);
    let long: Vec<&SimFrame> = f.iter().filter(|f| f.dt > 0.5).collect();
    assert_eq!(long.len(), 1);
    assert!((long[0].dt - 1.0).abs() < 1e-6 && (long[0].time - 5.0).abs() < 1e-9);
    // The character kept walking through the hitch: 1 s at 150 cm/s.
    let before = z_at(&f, 4.0);
    assert!((long[0].component_to_world.translation.y - before.y - 150.0).abs() < 1e-2);
}

#[test]
fn frame_times_and_counts() {
    let s = parse(
        "(world: (shapes: [Ground(height: 0.0)]), start: (position: (0.0, 0.0, 0.0)), \
          timeline: [Stand(seconds: 1.0), Move(seconds: 1.0, heading: 0.0, speed: 100.0)])",
    )
    .unwrap();
    assert_eq!(s.total_steps(), 2 * u64::from(MOVER_RATE_HZ));
    for hz in [30u32, 60, 144, 240] {
        let sim = Simulation::new(&s, hz);
        assert_eq!(sim.frame_count(), 2 * hz as usize + 1, "{hz} Hz");
        assert_eq!(sim.duration(), 2.0);
        let frames = run(&s, hz);
        for (k, f) in frames.iter().enumerate() {
            assert_eq!(f.index as usize, k);
            assert_eq!(f.time, k as f64 / f64::from(hz));
            assert_eq!(f.dt, (1.0 / f64::from(hz)) as f32);
            assert!(!f.teleported);
            assert_eq!(f.standing_still, k < hz as usize, "{hz} Hz frame {k}");
        }
    }
    // A rate that does not divide 720 still samples the same path (floor(k · 720 / hz)).
    let frames = run(&s, 50);
    assert_eq!(frames.len(), 101);
    assert_eq!(frames[100].time, 2.0);
}

#[test]
fn hitch_and_zero_dt_frames() {
    let s = parse(
        "(world: (shapes: [Ground(height: 0.0)]), start: (position: (0.0, 0.0, 0.0)), \
          timeline: [Stand(seconds: 1.0), ZeroDt(frames: 3), Hitch(seconds: 1.0), Stand(seconds: 1.0)])",
    )
    .unwrap();
    let frames = run(&s, 60);
    // Ticks 0..=180, minus the 59 inside the hitch, plus 3 zero-dt frames.
    assert_eq!(frames.len(), 181 - 59 + 3);
    for f in &frames[61..64] {
        assert_eq!((f.dt, f.time), (0.0, 1.0));
    }
    assert_eq!(frames[64].time, 2.0);
    assert_eq!(frames[64].dt, 1.0);
    assert_eq!(frames[65].time, 2.0 + 1.0 / 60.0);
    let times: Vec<f64> = frames.iter().map(|f| f.time).collect();
    assert!(times.windows(2).all(|w| w[1] >= w[0]));
}

#[test]
fn the_path_is_identical_at_30_60_144_240_hz() {
    use std::collections::BTreeMap;
    // Key every frame by its mover step (time · 720, exact for these rates) and compare the
    // frames of different rates that share a step.
    let by_step = |frames: &[SimFrame]| -> BTreeMap<u64, SimFrame> {
        frames
            .iter()
            .filter(|f| f.dt != 0.0)
            .map(|f| ((f.time * f64::from(MOVER_RATE_HZ)).round() as u64, *f))
            .collect()
    };
    for name in ["circle_turn", "stairs_up_down", "hitch"] {
        let s = load(name);
        let rates = [30u32, 60, 144, 240];
        let runs: Vec<BTreeMap<u64, SimFrame>> =
            rates.iter().map(|&hz| by_step(&run(&s, hz))).collect();
        for i in 0..rates.len() {
            for j in i + 1..rates.len() {
                let mut shared = 0;
                for (step, a) in &runs[i] {
                    if let Some(b) = runs[j].get(step) {
                        shared += 1;
                        assert_eq!(a.time, b.time);
                        assert_eq!(
                            a.component_to_world, b.component_to_world,
                            "{name}: {} Hz vs {} Hz at t = {}",
                            rates[i], rates[j], a.time
                        );
                        assert_eq!(a.velocity, b.velocity);
                        assert_eq!(a.standing_still, b.standing_still);
                    }
                }
                assert!(
                    shared as f64 >= s.duration() * 5.0,
                    "{name}: {shared} shared frames"
                );
            }
        }
    }
}

#[test]
fn broken_scenarios_report_file_line_and_column() {
    // An unknown segment on line 4.
    let text = "(\n    world: (shapes: [Ground(height: 0.0)]),\n    start: (position: (0.0, 0.0, 0.0)),\n    timeline: [Stand(seconds: 1.0), Jump(seconds: 1.0)],\n)\n";
    let err = parse(text).unwrap_err();
    let message = err.to_string();
    assert!(
        matches!(err, ScenarioError::Parse { line: 4, .. }),
        "{message}"
    );
    assert!(message.starts_with("test.ron:4:"), "{message}");
    assert!(
        message.contains("Jump") && message.contains("hint:"),
        "{message}"
    );

    // A Move with neither direction nor heading, on line 5.
    let text = "(\n    world: (shapes: []),\n    start: (position: (0.0, 0.0, 0.0)),\n    timeline: [\n        Move(seconds: 1.0, speed: 150.0),\n    ],\n)\n";
    let message = parse(text).unwrap_err().to_string();
    assert!(message.starts_with("test.ron:5:"), "{message}");
    assert!(message.contains("heading"), "{message}");

    // A missing field.
    let message = parse("(world: (shapes: []), timeline: [])")
        .unwrap_err()
        .to_string();
    assert!(
        message.contains("start") && message.contains("test.ron:1:"),
        "{message}"
    );

    // A bad mover override and a bad shape inside the world.
    let message = parse(
        "(world: (shapes: []), start: (position: (0.0, 0.0, 0.0)), mover: (radius: -1.0), timeline: [])",
    )
    .unwrap_err()
    .to_string();
    assert!(message.contains("radius"), "{message}");
    let message = parse(
        "(world: (shapes: [\nStairs(start: (0.0, 0.0, 0.0), width: 100.0, steps: 0, rise: 15.0, run: 30.0)]),\n start: (position: (0.0, 0.0, 0.0)), timeline: [])",
    )
    .unwrap_err()
    .to_string();
    assert!(
        message.starts_with("test.ron:2:") && message.contains("steps"),
        "{message}"
    );

    // Syntax error.
    let message = parse("(world: (shapes: [)").unwrap_err().to_string();
    assert!(message.starts_with("test.ron:1:"), "{message}");

    // A file that does not exist names itself.
    let err = Scenario::load("/nonexistent/scenario.ron").unwrap_err();
    assert!(err.to_string().contains("/nonexistent/scenario.ron"));
}

#[test]
fn mover_overrides_keep_other_defaults() {
    let s = parse(
        "(world: (shapes: []), start: (position: (0.0, 0.0, 0.0), yaw: 45.0), \
          mover: (acceleration: 500.0), timeline: [Stand(seconds: 0.5)])",
    )
    .unwrap();
    assert_eq!(s.mover.acceleration, 500.0);
    assert_eq!(s.mover.radius, 34.0);
    let sim = Simulation::new(&s, 0);
    assert_eq!(sim.hz(), 1);
    assert_eq!(sim.frame_count(), 1);
}

#[test]
fn a_checkpoint_replays_the_frames_that_followed_it() {
    // The teleport scenario: restoring must also put back which teleports are done.
    let scenario = load("teleport");
    let all = run(&scenario, 60);
    let mut sim = Simulation::new(&scenario, 60);
    let at = all.len() / 2;
    for _ in 0..at {
        sim.next_frame();
    }
    let checkpoint = sim.checkpoint();
    let rest: Vec<SimFrame> = std::iter::from_fn(|| sim.next_frame()).collect();
    assert_eq!(rest, all[at..]);
    // Back to the middle, in the same simulation and in a fresh one.
    sim.restore(&checkpoint);
    let again: Vec<SimFrame> = std::iter::from_fn(|| sim.next_frame()).collect();
    assert_eq!(again, all[at..]);
    let mut fresh = Simulation::new(&scenario, 60);
    fresh.restore(&checkpoint);
    assert_eq!(fresh.next_frame(), Some(all[at]));
}
