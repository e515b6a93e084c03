//! Every example graph under `graphs/examples/` passes `strider check`, runs through
//! `strider run` on the mannequin for 60 frames at 60 Hz with finite output, and shows the
//! behaviour its header comment describes. Expected values are worked out by hand in the
//! comments, from the mannequin's rest pose (`graphs/skeletons/mannequin.ron`): pelvis at
//! (0, 0, 95), ankles at (±9.5, 0, 13.5), balls at (±9.5, 14, 3), upper arms at (±17.5, 0, 145),
//! hands at (±55.081, 6.470, 107.419), clavicles at (±3, 2, 146).
//!
//! The run starts every frame from the rest pose in an empty world (every trace misses);
//! frame n (from 0) ends at time (n + 1)/60 s. A graph that accumulates time in a variable
//! before using it sees t = (n + 1)/60 at frame n.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};

use strider_core::{Quat, TraceHit, Vec3, WorldQuery};
use strider_vm::{FrameInput, Instance};

const FRAMES: usize = 60;
const SKELETON: &str = "graphs/skeletons/mannequin.ron";

/// Examples that have a behaviour test below. A new example needs one too.
const EXAMPLES: &[&str] = &[
    "arm_swing",
    "feet_finder",
    "foot_avoidance",
    "foot_roll",
    "knee_vector",
    "movement_angle",
    "pelvis_lean",
    "smoothing",
    "standing_foot_ik",
];

/// One bone of one frame, rig space: translation (cm) and rotation (x, y, z, w).
#[derive(Clone, Copy, Debug)]
struct BoneT {
    t: [f64; 3],
    r: [f64; 4],
}

type Frame = HashMap<String, BoneT>;

fn strider() -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_strider"));
    command.current_dir(env!("CARGO_MANIFEST_DIR"));
    command
}

fn example_files() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("graphs/examples");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "ron"))
        .collect();
    files.sort();
    files
}

fn assert_success(what: &str, output: &std::process::Output) {
    assert!(
        output.status.success(),
        "{what} failed ({}):\n{}{}",
        output.status,
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    );
}

/// Panics on a `null` (how the CLI writes NaN and infinities) or a non-finite number.
fn assert_finite(value: &serde_json::Value, at: &str) {
    match value {
        serde_json::Value::Null => panic!("{at}: null (a NaN or infinite value)"),
        serde_json::Value::Number(n) => {
            let x = n.as_f64().unwrap_or(f64::NAN);
            assert!(x.is_finite(), "{at}: {x}");
        }
        serde_json::Value::Array(items) => {
            for (i, item) in items.iter().enumerate() {
                assert_finite(item, &format!("{at}[{i}]"));
            }
        }
        serde_json::Value::Object(map) => {
            for (key, item) in map {
                assert_finite(item, &format!("{at}.{key}"));
            }
        }
        serde_json::Value::Bool(_) | serde_json::Value::String(_) => {}
    }
}

fn numbers<const N: usize>(value: &serde_json::Value) -> [f64; N] {
    let items = value.as_array().unwrap();
    assert_eq!(items.len(), N);
    std::array::from_fn(|i| items[i].as_f64().unwrap())
}

/// `strider check` then `strider run ... --frames 60 --out <temp>`, both must exit 0; the
/// JSONL must have 60 lines of finite numbers. Returns the frames.
fn run_example(name: &str) -> Vec<Frame> {
    static RUNS: AtomicUsize = AtomicUsize::new(0);
    let file = format!("graphs/examples/{name}.ron");

    let check = strider().args(["check", &file]).output().unwrap();
    assert_success(&format!("strider check {file}"), &check);

    let out = std::env::temp_dir().join(format!(
        "strider-examples-run-{}-{}-{name}.jsonl",
        std::process::id(),
        RUNS.fetch_add(1, Ordering::Relaxed)
    ));
    let run = strider()
        .args([
            "run",
            &file,
            "--skeleton",
            SKELETON,
            "--frames",
            "60",
            "--out",
        ])
        .arg(&out)
        .output()
        .unwrap();
    assert_success(&format!("strider run {file}"), &run);
    let text = std::fs::read_to_string(&out).unwrap();
    let _ = std::fs::remove_file(&out);

    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), FRAMES, "{file}: frames written");
    lines
        .iter()
        .enumerate()
        .map(|(n, line)| {
            let json: serde_json::Value = serde_json::from_str(line).unwrap();
            assert_finite(&json, &format!("{file} frame {n}"));
            assert_eq!(json["frame"].as_u64(), Some(n as u64), "{file}");
            json["bones"]
                .as_object()
                .unwrap()
                .iter()
                .map(|(bone, v)| {
                    (
                        bone.clone(),
                        BoneT {
                            t: numbers(&v["t"]),
                            r: numbers(&v["r"]),
                        },
                    )
                })
                .collect()
        })
        .collect()
}

fn t(frame: &Frame, bone: &str) -> [f64; 3] {
    frame[bone].t
}

fn r(frame: &Frame, bone: &str) -> [f64; 4] {
    frame[bone].r
}

/// Angle of a rotation, degrees, 0..180.
fn angle_deg(q: [f64; 4]) -> f64 {
    2.0 * q[3].abs().min(1.0).acos().to_degrees()
}

/// Yaw of a rotation about +Z only, degrees.
fn yaw_deg(q: [f64; 4]) -> f64 {
    2.0 * q[2].atan2(q[3]).to_degrees()
}

fn close(actual: f64, expected: f64, tolerance: f64, what: &str) {
    assert!(
        (actual - expected).abs() <= tolerance,
        "{what}: {actual} vs {expected} (± {tolerance})"
    );
}

fn close3(actual: [f64; 3], expected: [f64; 3], tolerance: f64, what: &str) {
    for i in 0..3 {
        close(actual[i], expected[i], tolerance, &format!("{what}[{i}]"));
    }
}

#[test]
fn every_example_checks_runs_and_stays_finite() {
    let files = example_files();
    let mut names = Vec::new();
    for file in &files {
        let name = file.file_stem().unwrap().to_str().unwrap().to_string();
        run_example(&name);
        names.push(name);
    }
    for name in &names {
        assert!(
            EXAMPLES.contains(&name.as_str()),
            "graphs/examples/{name}.ron has no behaviour test in tests/examples_run.rs: add one \
             and list it in EXAMPLES"
        );
    }
    for name in EXAMPLES {
        assert!(
            names.iter().any(|n| n == name),
            "graphs/examples/{name}.ron is missing"
        );
    }
}

#[test]
fn feet_finder_only_draws() {
    // It finds bones and draws; the pose stays the rest pose.
    for (n, f) in run_example("feet_finder").iter().enumerate() {
        close3(
            t(f, "pelvis"),
            [0.0, 0.0, 95.0],
            1e-3,
            &format!("frame {n} pelvis"),
        );
        close3(
            t(f, "foot_l"),
            [9.5, 0.0, 13.5],
            1e-3,
            &format!("frame {n} foot_l"),
        );
    }
}

#[test]
fn foot_roll_rolls_over_heel_ball_and_tip() {
    let frames = run_example("foot_roll");
    // Pivots (FootPivots with ball_drop 3, heel_drop 13.5, heel_back 0.5, tip_length 5.8):
    // heel (9.5, −2.9, 0), ball (9.5, 14, 0), tip (9.5, 19.8, 0). At 1 Hz frames 9, 29, 49
    // (t = 1/6, 1/2, 5/6 s) are the middles of the three thirds, where sin(180°·s) = 1 and
    // the pitch is at its peak. Rotating the ankle about the pivot by θ about +X:
    // z = dy·sin θ + dz·cos θ with (dy, dz) = ankle − pivot.
    let rolled_z = |dy: f64, dz: f64, deg: f64| {
        let a = deg.to_radians();
        dy * a.sin() + dz * a.cos()
    };
    let heel = rolled_z(2.9, 13.5, 30.0); // toes up about the heel: 13.141
    let ball = rolled_z(-14.0, 13.5, -25.0); // heel up about the ball: 18.152
    let tip = rolled_z(-19.8, 13.5, -40.0); // on the toe tip: 23.069
    // The float time after 10, 30 or 50 frames is within 1e-6 s of the exact value, where
    // the bump is flat (sin near 90°), so f32 rounding (~1e-5 cm) is all that is left.
    close(
        t(&frames[9], "foot_l")[2],
        heel,
        0.01,
        "foot_l z on the heel",
    );
    close(
        t(&frames[29], "foot_l")[2],
        ball,
        0.01,
        "foot_l z on the ball",
    );
    close(
        t(&frames[49], "foot_l")[2],
        tip,
        0.01,
        "foot_l z on the tip",
    );
    // Between the thirds the foot is flat at its rest place (t = 1/3 s: frame 19).
    close3(
        t(&frames[19], "foot_l"),
        [9.5, 0.0, 13.5],
        0.01,
        "foot_l flat",
    );
    // The right foot never moves.
    for f in &frames {
        close3(t(f, "foot_r"), [-9.5, 0.0, 13.5], 1e-3, "foot_r");
    }
}

#[test]
fn movement_angle_follows_the_velocity_folds_and_waits_on_a_jump() {
    let frames = run_example("movement_angle");
    let yaw = |n: usize| yaw_deg(r(&frames[n], "pelvis"));
    // Heading 45°·floor(t / 0.25 s): forward until frame 13 (t = 14/60 s < 0.25).
    for n in 0..=13 {
        close(yaw(n), 0.0, 1e-3, &format!("frame {n} yaw, moving forward"));
    }
    // Forward-right from frame 14 (t = 0.25 s; frame 15 if the float sum of 15 × 1/60
    // falls short). At frame 27 the offset has blended 14 (or 13) frames towards 45° at
    // speed 6/s: 45·(1 − e^(−6·14/60)) = 33.90° (32.74° after 13 frames).
    let y27 = yaw(27);
    assert!((32.5..=34.2).contains(&y27), "frame 27 yaw {y27}");
    // Frames 44..58 move back-right (135°), which folds to −45°: a jump of ~124° from the
    // ~79° reached while moving right, with fract(2·cycle) ≥ 0.4 all along (cycle 0.75..1),
    // so it blends at jump_speed 0.2/s: 15 frames cover 1 − e^(−0.2·15/60) = 4.9% of the
    // jump, under 7°. Without the fold it would head for 135°, without the gate for −45°.
    let (y43, y58) = (yaw(43), yaw(58));
    assert!(y43 > 70.0, "frame 43 yaw {y43}");
    assert!(
        (y58 - y43).abs() < 7.0 && y58 > 45.0,
        "frame 43 yaw {y43}, frame 58 yaw {y58}"
    );
}

#[test]
fn foot_avoidance_keeps_the_left_foot_left_of_the_right() {
    let frames = run_example("foot_avoidance");
    // At 0.5 Hz the first 60 frames are the left foot's step. Its ideal target goes up to
    // Cross = 25 cm inwards, x = 9.5 − 25 = −15.5: 6 cm past the right foot (x = −9.5).
    // FootAvoidance keeps it Margin = 15 cm left of the right foot: x ≥ 5.5. Two-bone IK
    // reaches each target to 1e-3 cm.
    for (n, f) in frames.iter().enumerate() {
        let gap = t(f, "foot_l")[0] - t(f, "foot_r")[0];
        assert!(gap >= 15.0 - 0.01, "frame {n}: feet {gap} cm apart");
        close3(
            t(f, "foot_r"),
            [-9.5, 0.0, 13.5],
            0.01,
            &format!("frame {n} foot_r"),
        );
    }
    // Mid-step (frame 29, t = 0.5 s, sin 90° = 1): clamped sideways, lifted by Lift = 8 cm.
    close3(
        t(&frames[29], "foot_l"),
        [5.5, 0.0, 21.5],
        0.01,
        "foot_l mid-step",
    );
}

#[test]
fn arm_swing_swings_the_arms_in_opposite_phase_and_bobs_the_clavicles() {
    let frames = run_example("arm_swing");
    // A hand's angle about its upper arm in the YZ plane, from straight down towards +Y
    // (the pitch about +X that ArmSwingRotation gives; a clavicle bob moves both points).
    let angle = |f: &Frame, side: &str| {
        let h = t(f, &format!("hand_{side}"));
        let u = t(f, &format!("upperarm_{side}"));
        (h[1] - u[1]).atan2(u[2] - h[2]).to_degrees()
    };
    // At 200 cm/s straight ahead: pitch = sin(360°·fract(phase + 0.15))·(200/300·50)
    // + 200/300·15 = 33.33°·sin(..) + 10°, and the two hands' phases are half a cycle apart.
    // So pitch_l + pitch_r = 20° at every frame, and pitch_l − pitch_r = 66.67°·sin(..).
    let sums: Vec<f64> = frames
        .iter()
        .map(|f| angle(f, "l") + angle(f, "r"))
        .collect();
    let diffs: Vec<f64> = frames
        .iter()
        .map(|f| angle(f, "l") - angle(f, "r"))
        .collect();
    for (n, sum) in sums.iter().enumerate() {
        close(*sum, sums[0], 0.05, &format!("frame {n}: opposite swings"));
    }
    // 60 frames cover a 0.85 s cycle: the sampled extremes (one frame is 7.1° of phase) are
    // at least 66.67°·cos(3.6°) = 66.54°.
    let max = diffs.iter().cloned().fold(f64::MIN, f64::max);
    let min = diffs.iter().cloned().fold(f64::MAX, f64::min);
    assert!(
        (66.5..=66.7).contains(&max),
        "largest swing difference {max}"
    );
    assert!(
        (-66.7..=-66.5).contains(&min),
        "smallest swing difference {min}"
    );
    // Clavicles: 146 + sin(720°·(cycle − 0.25))·(200/300·1.5) = 146 ± 1 cm, twice a cycle.
    let z: Vec<f64> = frames.iter().map(|f| t(f, "clavicle_l")[2]).collect();
    let top = z.iter().cloned().fold(f64::MIN, f64::max);
    let bottom = z.iter().cloned().fold(f64::MAX, f64::min);
    assert!((146.98..=147.001).contains(&top), "clavicle top {top}");
    assert!(
        (144.999..=145.02).contains(&bottom),
        "clavicle bottom {bottom}"
    );
}

#[test]
fn pelvis_lean_leans_with_speed() {
    let frames = run_example("pelvis_lean");
    // v = (0, 300·sin(180°·t), 0): moving forward at every frame before frame 59 (t = 1 s).
    for (n, f) in frames.iter().enumerate().take(59) {
        let tilt = angle_deg(r(f, "pelvis"));
        assert!(tilt > 0.5, "frame {n}: pelvis tilt {tilt}° while moving");
    }
    // Frame 29 (t = 0.5 s) is full speed, 300 cm/s: PelvisLean pitches −15° about X and
    // shifts 10 cm forward; the fake feet difference 20·sin(720°·0.5·0.5) is 0: no roll.
    let f = &frames[29];
    close3(t(f, "pelvis"), [0.0, 10.0, 95.0], 0.01, "pelvis shifted");
    let half = (-7.5f64).to_radians();
    let q = r(f, "pelvis");
    for (i, e) in [half.sin(), 0.0, 0.0, half.cos()].iter().enumerate() {
        close(q[i], *e, 1e-3, &format!("pelvis rotation[{i}], Rx(−15°)"));
    }
    // Stopped at frame 59: no lean.
    assert!(angle_deg(r(&frames[59], "pelvis")) < 0.01);
    close3(
        t(&frames[59], "pelvis"),
        [0.0, 0.0, 95.0],
        0.01,
        "pelvis at rest",
    );
}

#[test]
fn smoothing_exponential_vs_finterp_and_a_spring_without_overshoot() {
    let frames = run_example("smoothing");
    // The hands' target jumps to Reach = (0, 30, 20) cm at frame 0 and back at t = 0.5 s.
    // After frame 23 (24 frames of 1/60 s at speed 6/s) VectorLerp has covered
    // 1 − e^(−6·24/60) = 0.909282 of the gap and FInterpTo 1 − (1 − 6/60)^24 = 0.920234.
    let (rest_y, rest_z) = (6.470_471, 107.418_59);
    let f = &frames[23];
    close(
        t(f, "hand_l")[1] - rest_y,
        30.0 * 0.909_282,
        0.01,
        "VectorLerp follower y",
    );
    close(
        t(f, "hand_l")[2] - rest_z,
        20.0 * 0.909_282,
        0.01,
        "VectorLerp follower z",
    );
    close(
        t(f, "hand_r")[1] - rest_y,
        30.0 * 0.920_234,
        0.01,
        "FInterpTo follower y",
    );
    close(
        t(f, "hand_r")[2] - rest_z,
        20.0 * 0.920_234,
        0.01,
        "FInterpTo follower z",
    );
    // The pelvis target is 95 until t = 0.5 s (frame 29), then 95 − 15 = 80. The spring
    // starts at rest on its first target, so nothing moves before; after, it falls without
    // overshoot: z = 80 + 15·(1 + y·s)·e^(−y·s), y = 2·ln 2 / 0.15 s. At frame 59, s = 31/60
    // s after the switch: 80.731 (80.830 if the switch fell a frame later, s = 30/60).
    for f in &frames[..29] {
        close(t(f, "pelvis")[2], 95.0, 1e-4, "pelvis before the crouch");
    }
    for pair in frames[29..].windows(2) {
        let (a, b) = (t(&pair[0], "pelvis")[2], t(&pair[1], "pelvis")[2]);
        assert!(b <= a + 1e-4 && b >= 80.0 - 1e-3, "pelvis {a} → {b}");
    }
    let z = t(&frames[59], "pelvis")[2];
    assert!((80.7..=80.85).contains(&z), "pelvis z at frame 59: {z}");
}

#[test]
fn knee_vector_turns_the_knees_with_the_movement_yaw() {
    let frames = run_example("knee_vector");
    // Frame 29 (t = 0.5 s at 0.5 Hz): movement yaw 60·sin(90°) = 60°; the pole is
    // slerp(identity, Rz(60°), 0.25)·(knee·20) = Rz(15°)·(0, 30, 0): 15° right of forward.
    // Hip (±9.5, 0, 72) and ankle (±9.5, 0, 13.5) are on one vertical line, so the IK bends
    // the knee straight towards the pole: the knee's offset from the hip–ankle midpoint
    // points at yaw 15°, i.e. atan2(−x, y) = 15°.
    let f = &frames[29];
    for side in ["l", "r"] {
        let [hip, knee, ankle] = ["thigh", "calf", "foot"].map(|b| t(f, &format!("{b}_{side}")));
        let k: Vec<f64> = (0..3)
            .map(|i| knee[i] - (hip[i] + ankle[i]) / 2.0)
            .collect();
        close(
            (-k[0]).atan2(k[1]).to_degrees(),
            15.0,
            0.1,
            &format!("knee_{side} yaw"),
        );
    }
    // The crouch: pelvis 20 cm down, feet kept where they stand.
    for f in &frames {
        close3(t(f, "pelvis"), [0.0, 0.0, 75.0], 1e-3, "pelvis crouched");
        close3(t(f, "foot_l"), [9.5, 0.0, 13.5], 0.01, "foot_l planted");
        close3(t(f, "foot_r"), [-9.5, 0.0, 13.5], 0.01, "foot_r planted");
    }
}

#[test]
fn standing_foot_ik_leaves_the_pose_alone_without_ground() {
    // Every trace misses: offsets 0, no tilt, the pose stays the rest pose.
    for (n, f) in run_example("standing_foot_ik").iter().enumerate() {
        close3(
            t(f, "pelvis"),
            [0.0, 0.0, 95.0],
            1e-3,
            &format!("frame {n} pelvis"),
        );
        close3(
            t(f, "foot_l"),
            [9.5, 0.0, 13.5],
            1e-3,
            &format!("frame {n} foot_l"),
        );
        close3(
            t(f, "foot_r"),
            [-9.5, 0.0, 13.5],
            1e-3,
            &format!("frame {n} foot_r"),
        );
        assert!(angle_deg(r(f, "pelvis")) < 0.01);
    }
}

/// Ground for the standing foot IK: a step 8 cm high on the left (x > 0), tilted by
/// `slope` degrees about +X (rising forward), and a floor 6 cm low on the right (x < 0).
struct Steps {
    slope: f32,
}

impl Steps {
    fn ground(&self, x: f32) -> (f32, Vec3) {
        if x > 0.0 {
            let a = self.slope.to_radians();
            (8.0, Vec3::new(0.0, -a.sin(), a.cos()))
        } else {
            (-6.0, Vec3::Z)
        }
    }
}

impl WorldQuery for Steps {
    fn line_trace(&self, start: Vec3, end: Vec3) -> Option<TraceHit> {
        // Straight-down traces only (all this graph makes); the tilt is in the normal alone.
        let (z, normal) = self.ground(start.x);
        if !(start.z >= z && end.z <= z) {
            return None;
        }
        let point = Vec3::new(start.x, start.y, z);
        Some(TraceHit {
            point,
            normal,
            distance: start.z - z,
        })
    }

    fn sphere_trace(&self, _: Vec3, _: Vec3, _: f32) -> Option<TraceHit> {
        None
    }
}

#[test]
fn standing_foot_ik_on_uneven_ground() {
    // Not through the CLI (its world is empty): the library with a host world.
    let skeleton = strider_graph::load_skeleton(Path::new(SKELETON)).unwrap();
    let s = skeleton.skeleton.clone();
    let program = strider_compiler::compile_file(Path::new("graphs/examples/standing_foot_ik.ron"))
        .unwrap_or_else(|d| {
            panic!(
                "{}",
                d.iter()
                    .map(ToString::to_string)
                    .collect::<Vec<_>>()
                    .join("\n")
            )
        });
    let mut instance = Instance::new(Arc::new(program), s.clone()).unwrap();
    let world = Steps { slope: 10.0 };
    for _ in 0..60 {
        let input = FrameInput {
            dt: 1.0 / 60.0,
            ..Default::default()
        };
        instance.run_forward(&input, &world, false);
    }
    let globals = instance.pose_mut().globals().to_vec();
    let at = |name: &str| globals[s.find(name).unwrap().get()];
    // Offsets, half height 90 from z = 90: left 90 − (90 − 8) = 8, right 90 − 96 = −6. The
    // pelvis drops by the smaller, −6 (FInterpTo at 20/s: (1 − 1/3)^60 of the way left, and
    // it snaps within 1e-4), and each foot lands on its own ground.
    assert!((at("pelvis").translation - Vec3::new(0.0, 0.0, 89.0)).length() < 1e-3);
    assert!((at("foot_l").translation - Vec3::new(9.5, 0.0, 21.5)).length() < 0.01);
    assert!((at("foot_r").translation - Vec3::new(-9.5, 0.0, 7.5)).length() < 0.01);
    // The left foot is tilted onto the slope: its rotation relative to rest takes +Z onto
    // the normal; the right one is not tilted.
    let tilt = |name: &str| {
        let i = s.find(name).unwrap();
        at(name).rotation * s.rest_global(i).rotation.inverse()
    };
    let normal = world.ground(1.0).1;
    assert!(
        (tilt("foot_l") * Vec3::Z - normal).length() < 1e-3,
        "{}",
        tilt("foot_l") * Vec3::Z
    );
    assert!(tilt("foot_r").angle_between(Quat::IDENTITY).to_degrees() < 0.01);
}
