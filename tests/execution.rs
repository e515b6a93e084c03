//! Execution tests: small graphs compiled from RON and run on the mannequin, checking what
//! the runtime computes against values derived by hand in the comments (never copied from
//! the runtime's own output).
//!
//! Mannequin facts used below, read off `graphs/skeletons/mannequin.ron` (all translations
//! are local; root, pelvis and the spine have identity rotations):
//! - pelvis at (0, 0, 95) under root (0, 0, 0);
//! - spine_01 (0, 0, 12) under pelvis → rest global (0, 0, 107); spine_02 (0, 0, 12) under
//!   spine_01 → (0, 0, 119); spine_03 +13, neck_01 +20, head +13 → head at (0, 0, 165);
//! - thigh_l (9.5, 0, −3) under pelvis → rest global translation (9.5, 0, 92), rest global
//!   rotation = its local rotation (0.0126209, −0.7069941, −0.0126209, 0.7069941);
//! - bones in hierarchy (file) order: root, pelvis, thigh_l, calf_l, foot_l, ball_l,
//!   thigh_r, calf_r, foot_r, ball_r, spine_01, spine_02, spine_03, clavicle_l,
//!   upperarm_l, lowerarm_l, hand_l, clavicle_r, upperarm_r, lowerarm_r, hand_r, neck_01,
//!   head.

use std::path::Path;
use std::sync::Arc;
use strider_core::{
    DebugColor, DebugPrimitive, EmptyWorld, Quat, Skeleton, TraceHit, Transform, Vec3, WorldQuery,
};
use strider_nodes::{Elem, Value};
use strider_vm::{FrameInput, InputPose, Instance, InstantiateError, Program};

// ---------------------------------------------------------------------------------------
// Helpers
// ---------------------------------------------------------------------------------------

fn mannequin() -> Arc<Skeleton> {
    match strider_graph::load_skeleton(Path::new("graphs/skeletons/mannequin.ron")) {
        Ok(s) => s.skeleton,
        Err(d) => panic!("{}", join(&d)),
    }
}

fn join(d: &[strider_graph::Diagnostic]) -> String {
    d.iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join("\n")
}

fn compile(text: &str) -> Arc<Program> {
    match strider_compiler::compile_str(Path::new("tests/graphs/inline.ron"), text) {
        Ok(p) => Arc::new(p),
        Err(d) => panic!("graph does not compile:\n{}", join(&d)),
    }
}

fn compile_file(path: &str) -> Arc<Program> {
    match strider_compiler::compile_file(Path::new(path)) {
        Ok(p) => Arc::new(p),
        Err(d) => panic!("{path} does not compile:\n{}", join(&d)),
    }
}

fn compile_err(text: &str) -> String {
    match strider_compiler::compile_str(Path::new("tests/graphs/inline.ron"), text) {
        Ok(_) => panic!("graph compiled but should not have"),
        Err(d) => join(&d),
    }
}

fn instance(program: &Arc<Program>) -> Instance {
    Instance::new(Arc::clone(program), mannequin()).expect("instantiates on the mannequin")
}

fn frame(dt: f32) -> FrameInput<'static> {
    FrameInput {
        dt,
        ..Default::default()
    }
}

fn run(inst: &mut Instance, dt: f32) {
    inst.run_forward(&frame(dt), &EmptyWorld, false);
}

fn var(inst: &Instance, name: &str) -> Value {
    let id = inst
        .program()
        .variable_id(name)
        .unwrap_or_else(|| panic!("no variable {name}"));
    inst.variable(id)
}

fn f(inst: &Instance, name: &str) -> f32 {
    match var(inst, name) {
        Value::Float(x) => x,
        other => panic!("{name} is {other:?}, not a Float"),
    }
}

fn i(inst: &Instance, name: &str) -> i32 {
    match var(inst, name) {
        Value::Int(x) => x,
        other => panic!("{name} is {other:?}, not an Int"),
    }
}

fn b(inst: &Instance, name: &str) -> bool {
    match var(inst, name) {
        Value::Bool(x) => x,
        other => panic!("{name} is {other:?}, not a Bool"),
    }
}

fn v(inst: &Instance, name: &str) -> Vec3 {
    match var(inst, name) {
        Value::Vec3(x) => x,
        other => panic!("{name} is {other:?}, not a Vec3"),
    }
}

fn t(inst: &Instance, name: &str) -> Transform {
    match var(inst, name) {
        Value::Transform(x) => x,
        other => panic!("{name} is {other:?}, not a Transform"),
    }
}

fn set_f(inst: &mut Instance, name: &str, value: f32) {
    let id = inst.program().variable_id(name).unwrap();
    inst.set_float(id, value);
}

fn set(inst: &mut Instance, name: &str, value: Value) {
    let id = inst.program().variable_id(name).unwrap();
    inst.set_variable(id, &value).unwrap();
}

fn bones(names: &[&str]) -> Value {
    Value::Array(
        Elem::Bone,
        names
            .iter()
            .map(|n| Value::Bone(Some((*n).to_string())))
            .collect(),
    )
}

fn bone(name: &str) -> Value {
    Value::Bone(Some(name.to_string()))
}

fn global(inst: &mut Instance, name: &str) -> Transform {
    let bone = inst.pose().skeleton().find(name).unwrap();
    inst.pose_mut().global(bone)
}

fn local(inst: &Instance, name: &str) -> Transform {
    let bone = inst.pose().skeleton().find(name).unwrap();
    inst.pose().local(bone)
}

#[track_caller]
fn near(actual: f32, expected: f32, tol: f32, what: &str) {
    assert!(
        (actual - expected).abs() <= tol,
        "{what}: got {actual}, expected {expected} (±{tol})"
    );
}

#[track_caller]
fn near_v(actual: Vec3, expected: Vec3, tol: f32, what: &str) {
    assert!(
        (actual - expected).abs().max_element() <= tol,
        "{what}: got {actual}, expected {expected} (±{tol})"
    );
}

/// Same rotation (q and −q are the same rotation).
#[track_caller]
fn near_q(actual: Quat, expected: Quat, tol: f32, what: &str) {
    let d = actual.dot(expected).abs();
    assert!(
        (1.0 - d) <= tol,
        "{what}: got {actual:?}, expected {expected:?} (|dot| = {d})"
    );
}

const TOL: f32 = 1e-3;

/// Rotation of `deg` degrees about +Z, written out by hand: (0, 0, sin(θ/2), cos(θ/2)).
fn rot_z(deg: f64) -> Quat {
    let h = deg.to_radians() / 2.0;
    Quat::from_xyzw(0.0, 0.0, h.sin() as f32, h.cos() as f32)
}

/// thigh_l's rest rotation as written in the skeleton file.
const THIGH_L_REST: Quat = Quat::from_xyzw(0.0126209, -0.7069941, -0.0126209, 0.7069941);

// ---------------------------------------------------------------------------------------
// 1. pelvis_bob
// ---------------------------------------------------------------------------------------

/// Expected pelvis height of pelvis_bob after a frame ending at time `t` (seconds):
/// 95 + A·sin(360°·f·t), computed in f64.
fn bob_z(amplitude: f64, frequency: f64, t: f64) -> f64 {
    95.0 + amplitude * (2.0 * std::f64::consts::PI * frequency * t).sin()
}

#[test]
fn pelvis_bob_at_60_hz_follows_the_sine_of_accumulated_time() {
    let program = compile_file("graphs/pelvis_bob.ron");
    let mut inst = instance(&program);
    let dt = 1.0_f32 / 60.0;
    // The forward event first Sets Time = Time + dt, then SetTransform pulls "target", which
    // reads Time again: pure nodes are pulled per exec step, so frame k (from 0) uses
    // t = (k + 1)·dt.
    //
    //   k    t        360°·t   sin      z = 95 + 5·sin
    //   0    1/60     6°       0.104528 95.522642
    //   9    1/6      60°      0.866025 99.330127
    //   14   1/4      90°      1        100
    //   19   1/3      120°     0.866025 99.330127
    //   29   1/2      180°     0        95
    //   44   3/4      270°     −1       90
    //   59   1        360°     0        95
    //   89   3/2      540°     0        95
    //   104  7/4      630°     −1       90
    let table: [(usize, f32); 9] = [
        (0, 95.522642),
        (9, 99.330127),
        (14, 100.0),
        (19, 99.330127),
        (29, 95.0),
        (44, 90.0),
        (59, 95.0),
        (89, 95.0),
        (104, 90.0),
    ];
    let mut next = 0;
    for k in 0..=104 {
        run(&mut inst, dt);
        let t_expected = (k + 1) as f64 / 60.0;
        // Time accumulates in f32: 105 additions, each off by at most half an ulp (≤ 6e-8).
        near(
            f(&inst, "Time"),
            t_expected as f32,
            1e-5,
            &format!("Time after frame {k}"),
        );
        let z_formula = bob_z(5.0, 1.0, t_expected) as f32;
        let pelvis = global(&mut inst, "pelvis");
        near(
            pelvis.translation.z,
            z_formula,
            TOL,
            &format!("pelvis z, frame {k}"),
        );
        near(pelvis.translation.x, 0.0, 1e-6, "pelvis x");
        near(pelvis.translation.y, 0.0, 1e-6, "pelvis y");
        near_q(pelvis.rotation, Quat::IDENTITY, 1e-6, "pelvis rotation");
        if next < table.len() && table[next].0 == k {
            near(
                pelvis.translation.z,
                table[next].1,
                TOL,
                &format!("table row k={k}"),
            );
            next += 1;
        }
    }
    assert_eq!(next, table.len());
}

#[test]
fn pelvis_bob_at_quarter_second_steps_and_with_tuned_amplitude_and_frequency() {
    let program = compile_file("graphs/pelvis_bob.ron");
    let mut inst = instance(&program);
    // dt = 0.25 s: t = 0.25, 0.5, 0.75, 1.0, 1.25 (exact in f32) → 90°, 180°, 270°, 360°,
    // 450° → z = 100, 95, 90, 95, 100.
    for (k, z) in [100.0, 95.0, 90.0, 95.0, 100.0].into_iter().enumerate() {
        run(&mut inst, 0.25);
        assert_eq!(f(&inst, "Time"), 0.25 * (k + 1) as f32, "Time is exact");
        near(
            global(&mut inst, "pelvis").translation.z,
            z,
            TOL,
            &format!("frame {k}"),
        );
    }

    // Amplitude 10 from the host: t = 1.5 → 540° → sin 0 → 95; t = 1.75 → 630° → −1 → 85;
    // t = 2.0 → 720° → 95; t = 2.25 → 810° = 90° (mod 360) → 105.
    let amplitude = program.variable_id("Amplitude").unwrap();
    inst.set_float(amplitude, 10.0);
    assert_eq!(inst.variable(amplitude), Value::Float(10.0));
    for z in [95.0, 85.0, 95.0, 105.0] {
        run(&mut inst, 0.25);
        near(
            global(&mut inst, "pelvis").translation.z,
            z,
            TOL,
            "amplitude 10",
        );
    }
    assert_eq!(f(&inst, "Time"), 2.25);

    // Frequency 0.5 Hz, Amplitude 10, fresh instance: t = 0.25 → 0.25·0.5·360 = 45° →
    // 95 + 10·0.7071068 = 102.071068; t = 0.5 → 90° → 105; t = 0.75 → 135° → 102.071068;
    // t = 1.0 → 180° → 95.
    let mut inst = instance(&program);
    inst.set_float(amplitude, 10.0);
    inst.set_float(program.variable_id("Frequency").unwrap(), 0.5);
    for z in [102.07107, 105.0, 102.07107, 95.0] {
        run(&mut inst, 0.25);
        near(
            global(&mut inst, "pelvis").translation.z,
            z,
            TOL,
            "frequency 0.5",
        );
    }
}

#[test]
fn pelvis_bob_moves_the_children_with_the_pelvis() {
    let program = compile_file("graphs/pelvis_bob.ron");
    let mut inst = instance(&program);
    // dt = 0.25, first frame: t = 0.25 → offset +5 cm. Every descendant keeps its local
    // transform (propagate: true), so it moves by exactly (0, 0, 5).
    run(&mut inst, 0.25);
    near_v(
        global(&mut inst, "pelvis").translation,
        Vec3::new(0.0, 0.0, 100.0),
        TOL,
        "pelvis",
    );
    near_v(
        global(&mut inst, "spine_01").translation,
        Vec3::new(0.0, 0.0, 112.0),
        TOL,
        "spine_01",
    );
    near_v(
        global(&mut inst, "head").translation,
        Vec3::new(0.0, 0.0, 170.0),
        TOL,
        "head",
    );
    near_v(
        global(&mut inst, "thigh_l").translation,
        Vec3::new(9.5, 0.0, 97.0),
        TOL,
        "thigh_l",
    );
    near_q(
        global(&mut inst, "thigh_l").rotation,
        THIGH_L_REST,
        1e-5,
        "thigh_l rotation kept",
    );
    near_v(
        local(&inst, "spine_01").translation,
        Vec3::new(0.0, 0.0, 12.0),
        1e-6,
        "spine_01 local",
    );

    // Third frame: t = 0.75 → offset −5 cm.
    run(&mut inst, 0.25);
    run(&mut inst, 0.25);
    near_v(
        global(&mut inst, "spine_01").translation,
        Vec3::new(0.0, 0.0, 102.0),
        TOL,
        "spine_01",
    );
    near_v(
        global(&mut inst, "head").translation,
        Vec3::new(0.0, 0.0, 160.0),
        TOL,
        "head",
    );
    near_v(
        global(&mut inst, "thigh_l").translation,
        Vec3::new(9.5, 0.0, 87.0),
        TOL,
        "thigh_l",
    );

    // The feet, far down the chain, move by the same offset as the pelvis: compare against
    // their rest globals (input data, not runtime output).
    let s = mannequin();
    for name in ["foot_l", "foot_r", "hand_l", "hand_r", "ball_r"] {
        let rest = s.rest_global(s.find(name).unwrap()).translation;
        near_v(
            global(&mut inst, name).translation,
            rest + Vec3::new(0.0, 0.0, -5.0),
            TOL,
            name,
        );
    }
}

// ---------------------------------------------------------------------------------------
// 2. Hierarchy
// ---------------------------------------------------------------------------------------

const SET_PELVIS: &str = r#"
Graph(
    version: 1,
    name: "set_pelvis",
    variables: {
        "Propagate": (type: Bool, default: true),
        "Weight":    (type: Float, default: 1.0),
        "Target":    (type: Transform, default: (translation: (10.0, 0.0, 95.0), rotation: euler(0.0, 0.0, 90.0))),
    },
    events: {
        forward: [
            SetTransform(bone: bone("pelvis"), value: var("Target"), space: Global,
                         propagate: var("Propagate"), weight: var("Weight")),
        ],
    },
)
"#;

#[test]
fn set_transform_global_with_propagation_moves_children() {
    let program = compile(SET_PELVIS);
    let mut inst = instance(&program);
    run(&mut inst, 1.0 / 60.0);
    // Pelvis at (10, 0, 95) turned 90° about Z. Rz90 maps (x, y, z) → (−y, x, z).
    let pelvis = global(&mut inst, "pelvis");
    near_v(
        pelvis.translation,
        Vec3::new(10.0, 0.0, 95.0),
        TOL,
        "pelvis",
    );
    near_q(pelvis.rotation, rot_z(90.0), 1e-6, "pelvis rotation");
    // spine_01: pelvis + Rz90·(0, 0, 12) = (10, 0, 107); head likewise (10, 0, 165).
    near_v(
        global(&mut inst, "spine_01").translation,
        Vec3::new(10.0, 0.0, 107.0),
        TOL,
        "spine_01",
    );
    near_v(
        global(&mut inst, "head").translation,
        Vec3::new(10.0, 0.0, 165.0),
        TOL,
        "head",
    );
    // thigh_l: pelvis + Rz90·(9.5, 0, −3) = (10, 0, 95) + (0, 9.5, −3) = (10, 9.5, 92),
    // rotation Rz90 · rest.
    let thigh = global(&mut inst, "thigh_l");
    near_v(
        thigh.translation,
        Vec3::new(10.0, 9.5, 92.0),
        TOL,
        "thigh_l",
    );
    near_q(
        thigh.rotation,
        rot_z(90.0) * THIGH_L_REST,
        1e-5,
        "thigh_l rotation",
    );
    // Locals of the children are untouched.
    near_v(
        local(&inst, "spine_01").translation,
        Vec3::new(0.0, 0.0, 12.0),
        1e-5,
        "spine_01 local",
    );
    near_v(
        local(&inst, "thigh_l").translation,
        Vec3::new(9.5, 0.0, -3.0),
        1e-5,
        "thigh_l local",
    );
}

#[test]
fn set_transform_global_without_propagation_keeps_children_in_place() {
    let program = compile(SET_PELVIS);
    let mut inst = instance(&program);
    set(&mut inst, "Propagate", Value::Bool(false));
    run(&mut inst, 1.0 / 60.0);
    let pelvis = global(&mut inst, "pelvis");
    near_v(
        pelvis.translation,
        Vec3::new(10.0, 0.0, 95.0),
        TOL,
        "pelvis",
    );
    near_q(pelvis.rotation, rot_z(90.0), 1e-6, "pelvis rotation");
    // Children keep their rig-space transforms...
    near_v(
        global(&mut inst, "spine_01").translation,
        Vec3::new(0.0, 0.0, 107.0),
        TOL,
        "spine_01",
    );
    near_q(
        global(&mut inst, "spine_01").rotation,
        Quat::IDENTITY,
        1e-5,
        "spine_01 rotation",
    );
    let thigh = global(&mut inst, "thigh_l");
    near_v(thigh.translation, Vec3::new(9.5, 0.0, 92.0), TOL, "thigh_l");
    near_q(thigh.rotation, THIGH_L_REST, 1e-5, "thigh_l rotation");
    // ...and so do grandchildren (their locals are unchanged).
    near_v(
        global(&mut inst, "head").translation,
        Vec3::new(0.0, 0.0, 165.0),
        TOL,
        "head",
    );
    near_v(
        global(&mut inst, "spine_02").translation,
        Vec3::new(0.0, 0.0, 119.0),
        TOL,
        "spine_02",
    );
    // spine_01's new local: Rz(−90)·((0, 0, 107) − (10, 0, 95)) = Rz(−90)·(−10, 0, 12);
    // Rz(−90) maps (x, y, z) → (y, −x, z) → (0, 10, 12).
    near_v(
        local(&inst, "spine_01").translation,
        Vec3::new(0.0, 10.0, 12.0),
        TOL,
        "spine_01 local",
    );
    near_q(
        local(&inst, "spine_01").rotation,
        rot_z(-90.0),
        1e-5,
        "spine_01 local rotation",
    );
}

#[test]
fn set_transform_weight_blends_from_the_current_transform() {
    let program = compile(SET_PELVIS);
    let mut inst = instance(&program);
    set_f(&mut inst, "Weight", 0.5);
    run(&mut inst, 1.0 / 60.0);
    // Half way from (0, 0, 95), identity to (10, 0, 95), Rz90: (5, 0, 95), Rz45.
    let pelvis = global(&mut inst, "pelvis");
    near_v(pelvis.translation, Vec3::new(5.0, 0.0, 95.0), TOL, "pelvis");
    near_q(pelvis.rotation, rot_z(45.0), 1e-6, "pelvis rotation");
    // thigh_l: (5, 0, 95) + Rz45·(9.5, 0, −3) = (5 + 9.5·cos45°, 9.5·sin45°, 92)
    //        = (11.717514, 6.717514, 92).
    near_v(
        global(&mut inst, "thigh_l").translation,
        Vec3::new(11.717514, 6.717514, 92.0),
        TOL,
        "thigh_l",
    );

    // Weight is clamped to 0..1: 0 and −1 leave the rest pose, 2 acts as 1.
    for (w, x) in [(0.0, 0.0), (-1.0, 0.0), (2.0, 10.0), (1.0, 10.0)] {
        set_f(&mut inst, "Weight", w);
        run(&mut inst, 1.0 / 60.0);
        near_v(
            global(&mut inst, "pelvis").translation,
            Vec3::new(x, 0.0, 95.0),
            TOL,
            &format!("weight {w}"),
        );
    }
}

#[test]
fn set_transform_local_space_composes_with_the_parent() {
    let program = compile(
        r#"
Graph(
    version: 1,
    name: "set_local",
    events: {
        forward: [
            SetTransform(bone: bone("spine_01"),
                         value: (translation: (0.0, 5.0, 12.0), rotation: euler(90.0, 0.0, 0.0)),
                         space: Local),
        ],
    },
)
"#,
    );
    let mut inst = instance(&program);
    run(&mut inst, 1.0 / 60.0);
    // Local (0, 5, 12) under the pelvis at (0, 0, 95): global (0, 5, 107), rotation Rx90.
    let spine = global(&mut inst, "spine_01");
    near_v(
        spine.translation,
        Vec3::new(0.0, 5.0, 107.0),
        TOL,
        "spine_01",
    );
    let h = std::f32::consts::FRAC_PI_4;
    near_q(
        spine.rotation,
        Quat::from_xyzw(h.sin(), 0.0, 0.0, h.cos()),
        1e-6,
        "Rx90",
    );
    // spine_02 (local (0, 0, 12)) follows: Rx90 maps (x, y, z) → (x, −z, y), so
    // (0, 0, 12) → (0, −12, 0) and spine_02 lands at (0, −7, 107).
    near_v(
        global(&mut inst, "spine_02").translation,
        Vec3::new(0.0, -7.0, 107.0),
        TOL,
        "spine_02",
    );
    // The pelvis is not affected.
    near_v(
        global(&mut inst, "pelvis").translation,
        Vec3::new(0.0, 0.0, 95.0),
        1e-6,
        "pelvis",
    );
}

#[test]
fn get_transform_reads_the_current_pose_at_each_step_and_the_rest_pose_when_initial() {
    let program = compile(
        r#"
Graph(
    version: 1,
    name: "get_transform",
    variables: {
        "Before": (type: Transform), "After": (type: Transform), "Initial": (type: Transform),
        "ChildLocal": (type: Transform), "ChildGlobal": (type: Transform),
        "ThighLocalRest": (type: Transform), "NoBone": (type: Transform),
    },
    nodes: {
        "cur":          GetTransform(bone: bone("pelvis")),
        "init":         GetTransform(bone: bone("pelvis"), space: Global, initial: true),
        "child_local":  GetTransform(bone: bone("spine_01"), space: Local),
        "child_global": GetTransform(bone: bone("spine_01"), space: Global),
        "thigh_rest":   GetTransform(bone: bone("thigh_l"), space: Local, initial: true),
        "nothing":      GetTransform(bone: None),
        "lifted":       MakeTransform(translation: (0.0, 0.0, 120.0)),
    },
    events: {
        forward: [
            Set("Before", "cur"),
            SetTransform(bone: bone("pelvis"), value: "lifted"),
            Set("After", "cur"),
            Set("Initial", "init"),
            Set("ChildLocal", "child_local"),
            Set("ChildGlobal", "child_global"),
            Set("ThighLocalRest", "thigh_rest"),
            Set("NoBone", "nothing"),
        ],
    },
)
"#,
    );
    let mut inst = instance(&program);
    for _ in 0..2 {
        // The input pose is the rest pose every frame, so "Before" is 95 each time.
        run(&mut inst, 1.0 / 60.0);
        near_v(
            t(&inst, "Before").translation,
            Vec3::new(0.0, 0.0, 95.0),
            1e-6,
            "Before",
        );
        // The same node pulled by a later step sees the new pose.
        near_v(
            t(&inst, "After").translation,
            Vec3::new(0.0, 0.0, 120.0),
            1e-6,
            "After",
        );
        near_v(
            t(&inst, "Initial").translation,
            Vec3::new(0.0, 0.0, 95.0),
            1e-6,
            "Initial",
        );
        // spine_01 keeps its local (0, 0, 12) and rides to 120 + 12 = 132.
        near_v(
            t(&inst, "ChildLocal").translation,
            Vec3::new(0.0, 0.0, 12.0),
            1e-5,
            "ChildLocal",
        );
        near_v(
            t(&inst, "ChildGlobal").translation,
            Vec3::new(0.0, 0.0, 132.0),
            1e-4,
            "ChildGlobal",
        );
        let thigh = t(&inst, "ThighLocalRest");
        near_v(
            thigh.translation,
            Vec3::new(9.5, 0.0, -3.0),
            1e-6,
            "thigh local rest",
        );
        near_q(
            thigh.rotation,
            THIGH_L_REST,
            1e-6,
            "thigh local rest rotation",
        );
        assert_eq!(
            t(&inst, "NoBone"),
            Transform::IDENTITY,
            "no bone gives the identity"
        );
    }

    // Starting from the previous pose, "Before" reads last frame's 120.
    inst.run_forward(
        &FrameInput {
            dt: 1.0 / 60.0,
            pose: InputPose::Previous,
            ..Default::default()
        },
        &EmptyWorld,
        false,
    );
    near_v(
        t(&inst, "Before").translation,
        Vec3::new(0.0, 0.0, 120.0),
        1e-6,
        "Before (previous)",
    );
    near_v(
        t(&inst, "Initial").translation,
        Vec3::new(0.0, 0.0, 95.0),
        1e-6,
        "Initial (previous)",
    );
}

#[test]
fn get_parent_walks_up_the_hierarchy() {
    let program = compile(
        r#"
Graph(
    version: 1,
    name: "get_parent",
    variables: {
        "P1": (type: Bone), "P2": (type: Bone), "P3": (type: Bone), "P4": (type: Bone),
        "RootHasNone": (type: Bool), "SameAsLiteral": (type: Bool),
    },
    nodes: {
        "p1": GetParent(bone: bone("foot_l")),
        "p2": GetParent(bone: "p1"),
        "p3": GetParent(bone: bone("root")),
        "p4": GetParent(bone: None),
        "root_none": Equals(a: "p3", b: None),
        "same": Equals(a: "p2", b: bone("thigh_l")),
    },
    events: {
        construction: [ Set("P1", "p1"), Set("P2", "p2"), Set("P3", "p3"), Set("P4", "p4"),
                        Set("RootHasNone", "root_none"), Set("SameAsLiteral", "same") ],
    },
)
"#,
    );
    let inst = instance(&program);
    assert_eq!(var(&inst, "P1"), bone("calf_l"));
    assert_eq!(var(&inst, "P2"), bone("thigh_l"));
    assert_eq!(var(&inst, "P3"), Value::Bone(None));
    assert_eq!(var(&inst, "P4"), Value::Bone(None));
    assert!(b(&inst, "RootHasNone"));
    assert!(b(&inst, "SameAsLiteral"));
}

#[test]
fn input_pose_previous_accumulates_and_locals_replace_the_start_pose() {
    let program = compile(
        r#"
Graph(
    version: 1,
    name: "nudge",
    nodes: {
        "cur":   GetTransform(bone: bone("pelvis"), space: Local),
        "parts": BreakTransform(value: "cur"),
        "moved": Add(a: "parts.translation", b: (1.0, 0.0, 0.0)),
        "t":     MakeTransform(translation: "moved", rotation: "parts.rotation"),
    },
    events: { forward: [ SetTransform(bone: bone("pelvis"), value: "t", space: Local) ] },
)
"#,
    );
    let mut inst = instance(&program);
    let previous = FrameInput {
        dt: 0.1,
        pose: InputPose::Previous,
        ..Default::default()
    };
    // Each frame adds 1 cm along X to whatever the pose held: 1, 2, 3.
    for x in [1.0, 2.0, 3.0] {
        inst.run_forward(&previous, &EmptyWorld, false);
        near_v(
            global(&mut inst, "pelvis").translation,
            Vec3::new(x, 0.0, 95.0),
            1e-5,
            "previous",
        );
    }
    // From the rest pose again: 0 + 1.
    run(&mut inst, 0.1);
    near_v(
        global(&mut inst, "pelvis").translation,
        Vec3::new(1.0, 0.0, 95.0),
        1e-5,
        "rest",
    );

    // From given locals: pelvis local (0, 0, 50) → (1, 0, 50); spine_01 follows at 62.
    let s = mannequin();
    let mut locals = s.rest_locals().to_vec();
    locals[s.find("pelvis").unwrap().get()] =
        Transform::from_translation(Vec3::new(0.0, 0.0, 50.0));
    inst.run_forward(
        &FrameInput {
            dt: 0.1,
            pose: InputPose::Locals(&locals),
            ..Default::default()
        },
        &EmptyWorld,
        false,
    );
    near_v(
        global(&mut inst, "pelvis").translation,
        Vec3::new(1.0, 0.0, 50.0),
        1e-5,
        "locals",
    );
    near_v(
        global(&mut inst, "spine_01").translation,
        Vec3::new(1.0, 0.0, 62.0),
        1e-5,
        "locals child",
    );
}

// ---------------------------------------------------------------------------------------
// 3. Control flow
// ---------------------------------------------------------------------------------------

#[test]
fn foreach_for_branch_select_sequence_and_return() {
    let program = compile_file("tests/graphs/control_flow.ron");
    let mut inst = instance(&program);
    for frame_no in 0..3 {
        run(&mut inst, 1.0 / 60.0);
        let at = |what: &str| format!("{what} (frame {frame_no})");
        // ForEach over [1.5, 2.0, 4.25, 8.0]:
        //   Sum = 1.5 + 2 + 4.25 + 8 = 15.75
        //   IndexSum = 0 + 1 + 2 + 3 = 6, CountSeen = 4
        //   Weighted = Σ x·i = 0·1.5 + 1·2 + 2·4.25 + 3·8 = 0 + 2 + 8.5 + 24 = 34.5
        assert_eq!(f(&inst, "Sum"), 15.75, "{}", at("Sum"));
        assert_eq!(i(&inst, "IndexSum"), 6, "{}", at("IndexSum"));
        assert_eq!(i(&inst, "CountSeen"), 4, "{}", at("CountSeen"));
        assert_eq!(f(&inst, "Weighted"), 34.5, "{}", at("Weighted"));
        // ForEach over the literal [0.5, 0.25, 0.125]: 0.875.
        assert_eq!(f(&inst, "LitSum"), 0.875, "{}", at("LitSum"));
        // Branch inside ForEach over [3, −1, 4, −1, 5]: positives 3 + 4 + 5 = 12, two negatives.
        assert_eq!(f(&inst, "PosSum"), 12.0, "{}", at("PosSum"));
        assert_eq!(i(&inst, "NegCount"), 2, "{}", at("NegCount"));
        // For(5): 5 iterations, Σ k² for k = 0..4 = 0 + 1 + 4 + 9 + 16 = 30.
        assert_eq!(i(&inst, "Loops"), 5, "{}", at("Loops"));
        assert_eq!(i(&inst, "Squares"), 30, "{}", at("Squares"));
        // For(3) with d ← 2d + 1, re-reading the variable each iteration: 0 → 1 → 3 → 7.
        assert_eq!(i(&inst, "Doubling"), 7, "{}", at("Doubling"));
        // For(N) with N = 0: the body never runs.
        assert_eq!(i(&inst, "Runs"), 0, "{}", at("Runs"));
        // Nested: Σ o·in = (1 + 2 + 3)·(10 + 20) = 180;
        // Σ (10·oi + ii) = 10·(0 + 1 + 2)·2 + (0 + 1)·3 = 60 + 3 = 63.
        assert_eq!(f(&inst, "Nested"), 180.0, "{}", at("Nested"));
        assert_eq!(i(&inst, "NestedIdx"), 63, "{}", at("NestedIdx"));
        // X = 0 ≤ 2: else branch, Select's if_false.
        assert_eq!(i(&inst, "Path"), 2, "{}", at("Path"));
        assert_eq!(f(&inst, "Sel"), -10.0, "{}", at("Sel"));
        assert_eq!(
            v(&inst, "SelVec"),
            Vec3::new(-1.0, -2.0, -3.0),
            "{}",
            at("SelVec")
        );
        // Sequence: Seq ← 10·Seq + 1, + 2, + 3 with the shared node pulled again by each
        // step: 0 → 1 → 12 → 123.
        assert_eq!(i(&inst, "Seq"), 123, "{}", at("Seq"));
        // No early return: Early = 2.
        assert_eq!(i(&inst, "Early"), 2, "{}", at("Early"));
    }

    // Then side of the Branch and Select.
    set_f(&mut inst, "X", 2.5);
    run(&mut inst, 1.0 / 60.0);
    assert_eq!(i(&inst, "Path"), 1);
    assert_eq!(f(&inst, "Sel"), 10.0);
    assert_eq!(v(&inst, "SelVec"), Vec3::new(1.0, 2.0, 3.0));
    // Exactly 2 is not greater than 2.
    set_f(&mut inst, "X", 2.0);
    run(&mut inst, 1.0 / 60.0);
    assert_eq!(i(&inst, "Path"), 2);

    // For with a count from a variable: 4 → 4 runs; negative → none.
    set(&mut inst, "N", Value::Int(4));
    run(&mut inst, 1.0 / 60.0);
    assert_eq!(i(&inst, "Runs"), 4);
    set(&mut inst, "N", Value::Int(-3));
    run(&mut inst, 1.0 / 60.0);
    assert_eq!(i(&inst, "Runs"), 0);

    // Changing the array changes the loop: [2, 2] → Sum 4, CountSeen 2, Weighted 0·2 + 1·2 = 2.
    set(
        &mut inst,
        "Items",
        Value::Array(Elem::Float, vec![Value::Float(2.0), Value::Float(2.0)]),
    );
    run(&mut inst, 1.0 / 60.0);
    assert_eq!(f(&inst, "Sum"), 4.0);
    assert_eq!(i(&inst, "CountSeen"), 2);
    assert_eq!(f(&inst, "Weighted"), 2.0);
    // An empty array: the body never runs.
    set(&mut inst, "Items", Value::Array(Elem::Float, vec![]));
    run(&mut inst, 1.0 / 60.0);
    assert_eq!(f(&inst, "Sum"), 0.0);
    assert_eq!(i(&inst, "CountSeen"), 0);

    // Early Return from the event: the last Set is skipped, everything before it ran.
    set(&mut inst, "StopEarly", Value::Bool(true));
    run(&mut inst, 1.0 / 60.0);
    assert_eq!(i(&inst, "Early"), 1);
    assert_eq!(i(&inst, "Seq"), 123);
}

#[test]
fn loop_names_exist_only_inside_their_loop() {
    // Used correctly: the element feeds a node pulled inside the body.
    let ok = r#"
Graph(
    version: 1,
    name: "loop_scope",
    variables: { "Items": (type: FloatArray, default: [1.0, 2.0]), "Last": (type: Float) },
    nodes: { "twice": Multiply(a: "e", b: 2.0) },
    events: { forward: [ ForEach(items: var("Items"), element: "e", body: [ Set("Last", "twice") ]) ] },
)
"#;
    let mut inst = instance(&compile(ok));
    run(&mut inst, 0.1);
    // Last iteration: e = 2 → 4.
    assert_eq!(f(&inst, "Last"), 4.0);

    // The same node pulled after the loop is an error.
    let bad = ok.replace(
        r#"body: [ Set("Last", "twice") ]) ]"#,
        r#"body: [ ]), Set("Last", "twice") ]"#,
    );
    assert_ne!(bad, ok);
    let err = compile_err(&bad);
    assert!(err.contains("outside its loop"), "{err}");
}

const LOOP_HEADS: &str = r#"
Graph(
    version: 1,
    name: "loop_heads",
    variables: {
        "Limit":    (type: Int),
        "Runs":     (type: Int),
        "Echo":     (type: Int),
        "Limit2":   (type: Int),
        "Runs2":    (type: Int),
        "UseA":     (type: Bool),
        "A":        (type: FloatArray, default: [1.0, 2.0, 3.0]),
        "B":        (type: FloatArray, default: [100.0]),
        "EchoN":    (type: Int),
        "Sum":      (type: Float),
        "Visits":   (type: Int),
        "Grow":     (type: FloatArray),
        "GrowInit": (type: FloatArray, default: [1.0, 2.0, 3.0]),
        "GrowSum":  (type: Float),
    },
    nodes: {
        "limit_copy":  Add(a: var("Limit"), b: 0),
        "runs_next":   Add(a: var("Runs"), b: 1),
        "runs2_next":  Add(a: var("Runs2"), b: 1),
        "chosen":      Select(condition: var("UseA"), if_true: var("A"), if_false: var("B")),
        "chosen_n":    Count(array: "chosen"),
        "sum_next":    Add(a: var("Sum"), b: "e"),
        "visits_next": Add(a: var("Visits"), b: 1),
        "grow_n":      Count(array: var("Grow")),
        "small":       Less(a: "grow_n", b: 5),
        "grow_next":   Add(a: var("GrowSum"), b: "g"),
    },
    events: {
        forward: [
            // For with its count from a pure node; the body changes the node's source and
            // pulls the node again.
            Set("Limit", 3),
            Set("Runs", 0),
            For(count: "limit_copy", index: "k", body: [
                Set("Limit", 10),
                Set("Echo", "limit_copy"),
                Set("Runs", "runs_next"),
            ]),
            // For with its count from a variable the body changes.
            Set("Limit2", 3),
            Set("Runs2", 0),
            For(count: var("Limit2"), index: "k2", body: [
                Set("Limit2", 10),
                Set("Runs2", "runs2_next"),
            ]),
            // ForEach with its items from a pure node; the body flips the node's condition
            // and pulls it again.
            Set("UseA", true),
            Set("Sum", 0.0),
            Set("Visits", 0),
            ForEach(items: "chosen", element: "e", body: [
                Set("UseA", false),
                Set("EchoN", "chosen_n"),
                Set("Sum", "sum_next"),
                Set("Visits", "visits_next"),
            ]),
            // ForEach over a variable its body appends to.
            Set("Grow", var("GrowInit")),
            Set("GrowSum", 0.0),
            ForEach(items: var("Grow"), element: "g", body: [
                Branch(condition: "small", then: [ Append(array: var("Grow"), value: 10.0) ]),
                Set("GrowSum", "grow_next"),
            ]),
        ],
    },
)
"#;

// docs/format.md, evaluation semantics: "A loop's items (ForEach) or count (For) and a
// Branch's condition are evaluated once, before the loop or branch. ForEach reads its
// array in place: when items is a variable, changes the body makes to it are seen by later
// iterations."

#[test]
fn for_count_from_a_node_is_evaluated_once_before_the_loop() {
    // limit_copy = Limit + 0 = 3 when the loop starts → 3 iterations, although the body sets
    // Limit to 10 and pulls limit_copy again (which then reads 10).
    let mut inst = instance(&compile(LOOP_HEADS));
    run(&mut inst, 0.1);
    assert_eq!(
        i(&inst, "Echo"),
        10,
        "the body's own pull sees the new Limit"
    );
    assert_eq!(
        i(&inst, "Runs"),
        3,
        "For must run the count it had at the start"
    );
}

#[test]
fn for_count_from_a_variable_is_evaluated_once_before_the_loop() {
    // Limit2 = 3 when the loop starts → 3 iterations, although the body sets it to 10.
    let mut inst = instance(&compile(LOOP_HEADS));
    run(&mut inst, 0.1);
    assert_eq!(
        i(&inst, "Runs2"),
        3,
        "For must run the count it had at the start"
    );
}

#[test]
fn foreach_items_from_a_node_are_evaluated_once_before_the_loop() {
    // items = Select(UseA, A, B) = A = [1, 2, 3] when the loop starts. The body flips UseA
    // and pulls "chosen" again (through chosen_n, which then counts B: 1), but the loop must
    // still visit 1, 2, 3: Sum = 6, Visits = 3.
    let mut inst = instance(&compile(LOOP_HEADS));
    run(&mut inst, 0.1);
    assert_eq!(i(&inst, "EchoN"), 1, "the body's own pull sees B");
    assert_eq!(f(&inst, "Sum"), 6.0);
    assert_eq!(i(&inst, "Visits"), 3);
}

#[test]
fn foreach_iterates_over_the_array_as_it_was_when_the_loop_started() {
    // Grow = [1, 2, 3]; while it has fewer than 5 elements the body appends 10. The loop
    // walks its own copy taken at the start, so it visits 1 (→ len 4), 2 (→ len 5) and 3:
    // GrowSum = 6, and the variable keeps the appends: [1, 2, 3, 10, 10].
    let mut inst = instance(&compile(LOOP_HEADS));
    for _ in 0..2 {
        run(&mut inst, 0.1);
        assert_eq!(f(&inst, "GrowSum"), 6.0);
        assert_eq!(
            var(&inst, "Grow"),
            Value::Array(
                Elem::Float,
                [1.0, 2.0, 3.0, 10.0, 10.0].map(Value::Float).to_vec()
            )
        );
    }
}

// ---------------------------------------------------------------------------------------
// 4. Functions
// ---------------------------------------------------------------------------------------

#[test]
fn functions_inputs_outputs_locals_returns_and_call_sites() {
    let program = compile_file("tests/graphs/functions.ron");
    let mut inst = instance(&program);
    for frame_no in 0..3 {
        run(&mut inst, 1.0 / 60.0);
        let at = |what: &str| format!("{what} (frame {frame_no})");
        // Mad(x: 2) with the default k = 3 → 6; Mad(2, 5) → 10; Mad(4 (Int), 0.5) → 2.
        assert_eq!(f(&inst, "R1"), 6.0, "{}", at("R1"));
        assert_eq!(f(&inst, "R2"), 10.0, "{}", at("R2"));
        assert_eq!(f(&inst, "R3"), 2.0, "{}", at("R3"));
        // Outer(3) = Mad(3, 10) + 1 = 31.
        assert_eq!(f(&inst, "Chain"), 31.0, "{}", at("Chain"));
        // Accum: acc starts at 100 on every call and adds x twice: 102 and 104, every frame,
        // and when both call sites are pulled again by one step: 102 + 104 = 206.
        assert_eq!(f(&inst, "A1"), 102.0, "{}", at("A1"));
        assert_eq!(f(&inst, "A2"), 104.0, "{}", at("A2"));
        assert_eq!(f(&inst, "ATwice"), 206.0, "{}", at("ATwice"));
        // Maybe(true) → 42.
        assert_eq!(f(&inst, "Maybe"), 42.0, "{}", at("Maybe"));
        // SumArray([1, 2, 3.5]) = 6.5.
        assert_eq!(f(&inst, "Total"), 6.5, "{}", at("Total"));
        // Guarded(5, skip) returns 7 early and writes nothing; Guarded(6) writes Touched = 6,
        // Calls = 1, returns 8, and never reaches the Set after its Return.
        assert_eq!(f(&inst, "Out1"), 7.0, "{}", at("Out1"));
        assert_eq!(f(&inst, "Out2"), 8.0, "{}", at("Out2"));
        assert_eq!(f(&inst, "Touched"), 6.0, "{}", at("Touched"));
        assert_eq!(i(&inst, "Calls"), 1, "{}", at("Calls"));
        // Gained(1.5) reads Gain at each step: 1.5·2 = 3, then 1.5·4 = 6.
        assert_eq!(f(&inst, "G1"), 3.0, "{}", at("G1"));
        assert_eq!(f(&inst, "G2"), 6.0, "{}", at("G2"));
    }

    // Outputs are reset per call: Maybe(false) falls off its end without a value → 0, not
    // last frame's 42.
    set(&mut inst, "Give", Value::Bool(false));
    run(&mut inst, 1.0 / 60.0);
    assert_eq!(f(&inst, "Maybe"), 0.0);
    set(&mut inst, "Give", Value::Bool(true));
    run(&mut inst, 1.0 / 60.0);
    assert_eq!(f(&inst, "Maybe"), 42.0);

    // The array passed in is the variable's current value: [10, 0.25] → 10.25.
    set(
        &mut inst,
        "Items",
        Value::Array(Elem::Float, vec![Value::Float(10.0), Value::Float(0.25)]),
    );
    run(&mut inst, 1.0 / 60.0);
    assert_eq!(f(&inst, "Total"), 10.25);
}

#[test]
fn function_calls_inside_loops_and_returns_from_inside_a_loop() {
    let program = compile(
        r#"
Graph(
    version: 1,
    name: "fn_loops",
    variables: {
        "Items":   (type: FloatArray, default: [4.0, -2.0, 7.0, -9.0]),
        "Results": (type: FloatArray),
        "FirstNeg": (type: Int),
        "NoNeg":   (type: Int),
        "Positives": (type: FloatArray, default: [1.0, 2.0]),
    },
    functions: {
        // out = 100 + 2x with a local reset at every call.
        "Accum": (
            inputs:  { "x": Float },
            outputs: { "out": Float },
            locals:  { "acc": (type: Float, default: 100.0) },
            nodes:   { "next": Add(a: var("acc"), b: "x") },
            exec:    [ Set("acc", "next"), Set("acc", "next"), Return(out: var("acc")) ],
        ),
        // Index of the first negative value, −1 when there is none: returns from inside
        // the loop.
        "FirstNegative": (
            inputs:  { "values": FloatArray },
            outputs: { "index": Int },
            nodes:   { "neg": Less(a: "v", b: 0.0) },
            exec:    [
                ForEach(items: "values", element: "v", index: "i", body: [
                    Branch(condition: "neg", then: [ Return(index: "i") ]),
                ]),
                Return(index: -1),
            ],
        ),
    },
    nodes: {
        "acc":  Accum(x: "e"),
        "first": FirstNegative(values: var("Items")),
        "none":  FirstNegative(values: var("Positives")),
    },
    events: { forward: [
        Reset(array: var("Results")),
        ForEach(items: var("Items"), element: "e", body: [ Append(array: var("Results"), value: "acc") ]),
        Set("FirstNeg", "first"),
        Set("NoNeg", "none"),
    ] },
)
"#,
    );
    let mut inst = instance(&program);
    for _ in 0..3 {
        run(&mut inst, 0.1);
        // 100 + 2x per element: 108, 96, 114, 82 (the local restarts at 100 every iteration).
        assert_eq!(
            var(&inst, "Results"),
            Value::Array(
                Elem::Float,
                [108.0, 96.0, 114.0, 82.0].map(Value::Float).to_vec()
            )
        );
        // [4, −2, 7, −9]: first negative at index 1; [1, 2]: none → −1. Both call sites
        // start their loop from the beginning on every call.
        assert_eq!(i(&inst, "FirstNeg"), 1);
        assert_eq!(i(&inst, "NoNeg"), -1);
    }
    // Moving the first negative: [−1, 5] → 0.
    set(
        &mut inst,
        "Items",
        Value::Array(Elem::Float, vec![Value::Float(-1.0), Value::Float(5.0)]),
    );
    run(&mut inst, 0.1);
    assert_eq!(i(&inst, "FirstNeg"), 0);
}

const SPRINGS: &str = r#"
Graph(
    version: 1,
    name: "springs",
    variables: {
        "T": (type: Float), "U": (type: Float, default: 100.0),
        "A": (type: Float), "B": (type: Float), "FromT": (type: Float), "FromU": (type: Float),
    },
    functions: {
        "Follow": (
            inputs:  { "target": Float },
            outputs: { "value": Float },
            nodes:   { "s": SpringDamper(target: "target", half_life: 0.5) },
            exec:    [ Return(value: "s") ],
        ),
    },
    nodes: {
        "s":      SpringDamper(target: var("T"), half_life: 0.5),
        "from_t": Follow(target: var("T")),
        "from_u": Follow(target: var("U")),
    },
    events: { forward: [ Set("A", "s"), Set("FromT", "from_t"), Set("FromU", "from_u") ] },
)
"#;

// A critically damped spring with half-life h = 0.5 s starting at rest on 0, after its
// target jumps to 10 and t = 0.5 s pass: x − 10 = −10·(1 + y·t)·e^(−y·t) with
// y = 2·ln2/h = 4·ln2, so y·t = 2·ln2, e^(−2·ln2) = 1/4 and
// x = 10 − 10·(1 + 2·ln2)/4 = 10 − 5.965736 = 4.034264 (nodes.md: "after t = h the remaining
// fraction is (1 + 2·ln2)/4 ≈ 0.597").
const SPRING_AFTER_HALF_LIFE: f32 = 4.034264;

#[test]
fn stateful_nodes_keep_separate_state_per_call_site() {
    let mut inst = instance(&compile(SPRINGS));
    // Frame 1: every spring starts at rest on the first target it sees (T = 0, U = 100).
    run(&mut inst, 0.5);
    assert_eq!(f(&inst, "A"), 0.0);
    assert_eq!(f(&inst, "FromT"), 0.0);
    assert_eq!(f(&inst, "FromU"), 100.0);
    // Frame 2: T jumps to 10. The node at the top level and the call site following T both
    // move to 4.034264; the call site following U (same function, other call site) stays
    // at 100 — it does not share the other call site's spring.
    set_f(&mut inst, "T", 10.0);
    run(&mut inst, 0.5);
    near(
        f(&inst, "A"),
        SPRING_AFTER_HALF_LIFE,
        1e-4,
        "top-level spring",
    );
    near(
        f(&inst, "FromT"),
        SPRING_AFTER_HALF_LIFE,
        1e-4,
        "call site following T",
    );
    assert_eq!(f(&inst, "FromU"), 100.0, "call site following U");
    // Frame-rate independence through the graph: four frames of 0.125 s reach the same value.
    let mut fine = instance(&compile(SPRINGS));
    run(&mut fine, 0.125);
    set_f(&mut fine, "T", 10.0);
    for _ in 0..4 {
        run(&mut fine, 0.125);
    }
    near(
        f(&fine, "A"),
        SPRING_AFTER_HALF_LIFE,
        1e-4,
        "0.5 s in four frames",
    );
    // Rebinding resets the hidden state: the spring starts again at rest on the target.
    inst.rebind(mannequin(), &EmptyWorld).unwrap();
    set_f(&mut inst, "T", 10.0);
    run(&mut inst, 0.5);
    assert_eq!(f(&inst, "A"), 10.0);
}

#[test]
fn a_stateful_node_read_by_two_steps_advances_once_per_frame() {
    // The same spring read by two Sets in one frame. Both must see the frame's value,
    // 4.034264 after the jump; advancing it again for the second read would give the value
    // after 1 s: 10 − 10·(1 + 4·ln2)·e^(−4·ln2) = 10 − 10·3.772589/16 = 7.642132.
    let text = SPRINGS.replace(r#"Set("A", "s"),"#, r#"Set("A", "s"), Set("B", "s"),"#);
    let mut inst = instance(&compile(&text));
    run(&mut inst, 0.5);
    set_f(&mut inst, "T", 10.0);
    run(&mut inst, 0.5);
    near(f(&inst, "A"), SPRING_AFTER_HALF_LIFE, 1e-4, "first read");
    near(
        f(&inst, "B"),
        SPRING_AFTER_HALF_LIFE,
        1e-4,
        "second read in the same frame",
    );
}

#[test]
fn function_errors_are_reported_not_run() {
    // Recursion and a missing required input are compile errors.
    let recursive = r#"
Graph(
    version: 1,
    name: "recursive",
    functions: {
        "Loop": (inputs: { "x": Float }, outputs: { "y": Float },
                 nodes: { "again": Loop(x: "x") }, exec: [ Return(y: "again") ]),
    },
    variables: { "Y": (type: Float) },
    nodes: { "call": Loop(x: 1.0) },
    events: { forward: [ Set("Y", "call") ] },
)
"#;
    let err = compile_err(recursive);
    assert!(err.contains("recursion"), "{err}");

    let missing = r#"
Graph(
    version: 1,
    name: "missing_input",
    functions: {
        "Id": (inputs: { "x": Float }, outputs: { "y": Float }, exec: [ Return(y: "x") ]),
    },
    variables: { "Y": (type: Float) },
    nodes: { "call": Id() },
    events: { forward: [ Set("Y", "call") ] },
)
"#;
    let err = compile_err(missing);
    assert!(err.contains("missing input `x`"), "{err}");
}

// ---------------------------------------------------------------------------------------
// 5. Variables across frames, construction and rebind
// ---------------------------------------------------------------------------------------

const LIFECYCLE: &str = r#"
Graph(
    version: 1,
    name: "lifecycle",
    variables: {
        "Frames":           (type: Int),
        "Gain":             (type: Float, default: 1.0, tunable: (min: 0.0, max: 10.0)),
        "Seen":             (type: Float),
        "Feet":             (type: BoneArray),
        "Hands":            (type: BoneArray),
        "LeftFeet":         (type: BoneArray),
        "BelowThighR":      (type: BoneArray),
        "ConstructionRuns": (type: Int),
        "ConstructionDt":   (type: Float, default: -1.0),
        "Elapsed":          (type: Float),
    },
    nodes: {
        "feet":        FindBones(root: bone("root"), contains: name("foot"), excludes: name("ik")),
        "hands":       FindBones(root: bone("root"), contains: name("HAND")),
        "left_feet":   FindBones(root: bone("root"), contains: name("foot"), excludes: name("_R")),
        "below":       FindBones(root: bone("thigh_r"), contains: name("")),
        "runs_next":   Add(a: var("ConstructionRuns"), b: 1),
        "frames_next": Add(a: var("Frames"), b: 1),
        "dt":          DeltaTime(),
        "elapsed":     Add(a: var("Elapsed"), b: "dt"),
    },
    events: {
        construction: [
            Set("Feet", "feet"),
            Set("Hands", "hands"),
            Set("LeftFeet", "left_feet"),
            Set("BelowThighR", "below"),
            Set("Seen", var("Gain")),
            Set("ConstructionRuns", "runs_next"),
            Set("ConstructionDt", "dt"),
        ],
        forward: [ Set("Frames", "frames_next"), Set("Elapsed", "elapsed") ],
    },
)
"#;

const TRIPOD: &str = r#"
Skeleton(
    version: 1,
    name: "tripod",
    bones: [
        (name: "root", parent: None),
        (name: "body", parent: "root", translation: (0.0, 0.0, 50.0)),
        (name: "leg_a", parent: "body", translation: (10.0, 0.0, 0.0)),
        (name: "Foot_A", parent: "leg_a", translation: (0.0, 0.0, -50.0)),
        (name: "leg_b", parent: "body", translation: (-10.0, 0.0, 0.0)),
        (name: "foot_b", parent: "leg_b", translation: (0.0, 0.0, -50.0)),
        (name: "foot_ik", parent: "root"),
        (name: "hand", parent: "body"),
        (name: "thigh_r", parent: "root"),
        (name: "shin_r", parent: "thigh_r"),
    ],
)
"#;

fn tripod() -> Arc<Skeleton> {
    match strider_graph::load_skeleton_str(Path::new("tripod.ron"), TRIPOD.to_string()) {
        Ok(s) => s.skeleton,
        Err(d) => panic!("{}", join(&d)),
    }
}

#[test]
fn variables_persist_across_frames_and_construction_runs_at_instantiation() {
    let program = compile(LIFECYCLE);
    let mut inst = instance(&program);
    // Construction ran once, with dt = 0, on the mannequin.
    assert_eq!(i(&inst, "ConstructionRuns"), 1);
    assert_eq!(f(&inst, "ConstructionDt"), 0.0);
    assert_eq!(f(&inst, "Seen"), 1.0);
    // Feet and hands in hierarchy order; "ball_*" does not contain "foot"; matching is
    // case-insensitive ("HAND"); excludes "_R" removes foot_r.
    assert_eq!(var(&inst, "Feet"), bones(&["foot_l", "foot_r"]));
    assert_eq!(var(&inst, "Hands"), bones(&["hand_l", "hand_r"]));
    assert_eq!(var(&inst, "LeftFeet"), bones(&["foot_l"]));
    // Descendants of thigh_r, not thigh_r itself.
    assert_eq!(
        var(&inst, "BelowThighR"),
        bones(&["calf_r", "foot_r", "ball_r"])
    );
    assert_eq!(i(&inst, "Frames"), 0);

    // The counter counts frames; Elapsed sums dt = 0.125 exactly.
    for n in 1..=10 {
        run(&mut inst, 0.125);
        assert_eq!(i(&inst, "Frames"), n);
        assert_eq!(f(&inst, "Elapsed"), 0.125 * n as f32);
    }
    // Construction does not run per frame.
    assert_eq!(i(&inst, "ConstructionRuns"), 1);

    // Running construction by hand runs it again without resetting anything.
    inst.run_construction(&EmptyWorld);
    assert_eq!(i(&inst, "ConstructionRuns"), 2);
    assert_eq!(i(&inst, "Frames"), 10);

    // Two instances of one program do not share variables.
    let other = instance(&program);
    assert_eq!(i(&other, "Frames"), 0);
    assert_eq!(i(&other, "ConstructionRuns"), 1);
}

#[test]
fn rebind_reruns_construction_keeps_tunables_and_resets_the_rest() {
    let program = compile(LIFECYCLE);
    let mut inst = instance(&program);
    set_f(&mut inst, "Gain", 3.5);
    for _ in 0..5 {
        run(&mut inst, 0.125);
    }
    assert_eq!(i(&inst, "Frames"), 5);
    assert_eq!(
        f(&inst, "Seen"),
        1.0,
        "construction has not seen the new Gain yet"
    );

    inst.rebind(tripod(), &EmptyWorld)
        .expect("tripod has root and thigh_r");
    // Tunable kept; construction re-ran with it (Seen = Gain = 3.5); non-tunables were reset
    // before it ran (ConstructionRuns 0 + 1 = 1, Frames and Elapsed back to 0).
    assert_eq!(f(&inst, "Gain"), 3.5);
    assert_eq!(f(&inst, "Seen"), 3.5);
    assert_eq!(i(&inst, "ConstructionRuns"), 1);
    assert_eq!(i(&inst, "Frames"), 0);
    assert_eq!(f(&inst, "Elapsed"), 0.0);
    // FindBones ran on the new skeleton: "Foot_A" matches case-insensitively, "foot_ik"
    // is excluded; the hand is "hand"; below thigh_r is shin_r.
    assert_eq!(var(&inst, "Feet"), bones(&["Foot_A", "foot_b"]));
    assert_eq!(var(&inst, "Hands"), bones(&["hand"]));
    assert_eq!(
        var(&inst, "LeftFeet"),
        bones(&["Foot_A", "foot_b", "foot_ik"])
    );
    assert_eq!(var(&inst, "BelowThighR"), bones(&["shin_r"]));
    assert_eq!(inst.pose().len(), 10);
    run(&mut inst, 0.125);
    assert_eq!(i(&inst, "Frames"), 1);

    // And back to the mannequin.
    inst.rebind(mannequin(), &EmptyWorld).unwrap();
    assert_eq!(var(&inst, "Feet"), bones(&["foot_l", "foot_r"]));
    assert_eq!(f(&inst, "Gain"), 3.5);
    assert_eq!(i(&inst, "Frames"), 0);
}

#[test]
fn missing_bones_are_reported_and_a_failed_rebind_changes_nothing() {
    // pelvis_bob names "pelvis", which the tripod lacks.
    let program = compile_file("graphs/pelvis_bob.ron");
    match Instance::new(Arc::clone(&program), tripod()) {
        Err(InstantiateError::MissingBones { missing, .. }) => {
            assert!(missing.iter().all(|m| m.name == "pelvis"), "{missing:?}");
            assert!(!missing.is_empty());
            assert!(
                missing[0].location.contains("tests/graphs")
                    || missing[0].location.contains("pelvis_bob")
            );
        }
        other => panic!("expected MissingBones, got {other:?}"),
    }

    let mut inst = instance(&program);
    run(&mut inst, 0.25);
    assert!(inst.rebind(tripod(), &EmptyWorld).is_err());
    // Unchanged: still on the mannequin, Time kept, next frame continues at t = 0.5.
    assert_eq!(inst.pose().len(), 23);
    assert_eq!(f(&inst, "Time"), 0.25);
    run(&mut inst, 0.25);
    near(
        global(&mut inst, "pelvis").translation.z,
        95.0,
        TOL,
        "t = 0.5 → sin 180° = 0",
    );
}

#[test]
fn set_variable_checks_types_and_bones() {
    let program = compile(LIFECYCLE);
    let mut inst = instance(&program);
    let gain = program.variable_id("Gain").unwrap();
    // An Int is accepted for a Float variable.
    inst.set_variable(gain, &Value::Int(4)).unwrap();
    assert_eq!(inst.variable(gain), Value::Float(4.0));
    // Other mismatches are refused and change nothing.
    assert!(inst.set_variable(gain, &Value::Bool(true)).is_err());
    assert_eq!(inst.variable(gain), Value::Float(4.0));
    let frames = program.variable_id("Frames").unwrap();
    assert!(inst.set_variable(frames, &Value::Float(1.5)).is_err());
    // Bone arrays by name; an unknown bone is refused.
    let feet = program.variable_id("Feet").unwrap();
    inst.set_variable(feet, &bones(&["hand_l", "head"]))
        .unwrap();
    assert_eq!(inst.variable(feet), bones(&["hand_l", "head"]));
    assert!(
        inst.set_variable(feet, &bones(&["hand_l", "tail"]))
            .is_err()
    );
    assert_eq!(inst.variable(feet), bones(&["hand_l", "head"]));
    // set_float ignores non-float variables.
    inst.set_float(frames, 7.0);
    assert_eq!(inst.variable(frames), Value::Int(0));
}

#[test]
fn locals_input_with_missing_entries_keeps_the_previous_values() {
    let program = compile(
        r#"
Graph(
    version: 1,
    name: "passthrough",
    variables: { "Spine": (type: Transform) },
    nodes: { "spine": GetTransform(bone: bone("spine_01")) },
    events: { forward: [ Set("Spine", "spine") ] },
)
"#,
    );
    let mut inst = instance(&program);
    let s = mannequin();
    let mut locals = s.rest_locals().to_vec();
    locals[s.find("pelvis").unwrap().get()] =
        Transform::from_translation(Vec3::new(0.0, 0.0, 50.0));
    let with = |l| FrameInput {
        dt: 0.1,
        pose: InputPose::Locals(l),
        ..Default::default()
    };
    inst.run_forward(&with(&locals), &EmptyWorld, false);
    // spine_01 = pelvis (0, 0, 50) + (0, 0, 12).
    near_v(
        t(&inst, "Spine").translation,
        Vec3::new(0.0, 0.0, 62.0),
        1e-5,
        "full locals",
    );
    // Only the root given: the pelvis keeps last frame's local, (0, 0, 50).
    let root_only = [Transform::from_translation(Vec3::new(5.0, 0.0, 0.0))];
    inst.run_forward(&with(&root_only), &EmptyWorld, false);
    near_v(
        t(&inst, "Spine").translation,
        Vec3::new(5.0, 0.0, 62.0),
        1e-5,
        "root only",
    );
    // Extra entries are ignored.
    let mut extra = s.rest_locals().to_vec();
    extra.push(Transform::from_translation(Vec3::splat(1e6)));
    inst.run_forward(&with(&extra), &EmptyWorld, false);
    near_v(
        t(&inst, "Spine").translation,
        Vec3::new(0.0, 0.0, 107.0),
        1e-5,
        "extra entries",
    );
}

// ---------------------------------------------------------------------------------------
// 6. Determinism
// ---------------------------------------------------------------------------------------

fn pose_bits(inst: &mut Instance) -> Vec<[u32; 10]> {
    inst.pose_mut()
        .globals()
        .iter()
        .map(|g| {
            [
                g.translation.x.to_bits(),
                g.translation.y.to_bits(),
                g.translation.z.to_bits(),
                g.rotation.x.to_bits(),
                g.rotation.y.to_bits(),
                g.rotation.z.to_bits(),
                g.rotation.w.to_bits(),
                g.scale.x.to_bits(),
                g.scale.y.to_bits(),
                g.scale.z.to_bits(),
            ]
        })
        .collect()
}

/// A deterministic, irregular frame time around 1/60 s (8..25 ms), with an occasional
/// hitch of 0.1 s and an occasional 0.
fn varying_dt(k: usize) -> f32 {
    match k % 37 {
        11 => 0.1,
        23 => 0.0,
        _ => 0.008 + 0.017 * (((k * 7919) % 101) as f32 / 100.0),
    }
}

fn assert_deterministic(path: &str, dt: &dyn Fn(usize) -> f32) {
    let program = compile_file(path);
    let mut a = instance(&program);
    let mut b = instance(&program);
    let frames = 200;
    let mut history = Vec::with_capacity(frames);
    for k in 0..frames {
        let input = frame(dt(k));
        a.run_forward(&input, &EmptyWorld, k % 3 == 0);
        b.run_forward(&input, &EmptyWorld, k % 3 == 0);
        let (pa, pb) = (pose_bits(&mut a), pose_bits(&mut b));
        assert_eq!(pa, pb, "{path}: poses differ at frame {k}");
        assert_eq!(
            a.debug_draw().primitives(),
            b.debug_draw().primitives(),
            "{path}: debug draw differs at frame {k}"
        );
        history.push(pa);
    }
    // A third instance run later, with other instances interleaved, replays the same bits:
    // no state is shared between instances or leaks in from elsewhere.
    let mut c = instance(&program);
    let mut noise = instance(&program);
    for (k, expected) in history.iter().enumerate() {
        noise.run_forward(&frame(0.05), &EmptyWorld, true);
        c.run_forward(&frame(dt(k)), &EmptyWorld, k % 3 == 0);
        assert_eq!(
            &pose_bits(&mut c),
            expected,
            "{path}: replay differs at frame {k}"
        );
    }
    // The motion is not trivial: some bone moved away from the rest pose at some frame.
    let rest = {
        let mut r = instance(&program);
        pose_bits(&mut r)
    };
    assert!(history.iter().any(|p| *p != rest), "{path}: nothing moved");
}

#[test]
fn two_instances_are_bit_identical_at_fixed_dt() {
    for path in ["graphs/pelvis_bob.ron", "tests/graphs/wobble.ron"] {
        assert_deterministic(path, &|_| 1.0 / 60.0);
    }
}

#[test]
fn two_instances_are_bit_identical_at_varying_dt() {
    for path in ["graphs/pelvis_bob.ron", "tests/graphs/wobble.ron"] {
        assert_deterministic(path, &varying_dt);
    }
}

#[test]
fn a_cloned_instance_continues_identically() {
    let program = compile_file("tests/graphs/wobble.ron");
    let mut a = instance(&program);
    for k in 0..50 {
        a.run_forward(&frame(varying_dt(k)), &EmptyWorld, false);
    }
    let mut b = a.clone();
    for k in 50..120 {
        a.run_forward(&frame(varying_dt(k)), &EmptyWorld, false);
        b.run_forward(&frame(varying_dt(k)), &EmptyWorld, false);
        assert_eq!(pose_bits(&mut a), pose_bits(&mut b), "frame {k}");
    }
    assert_eq!(var(&a, "Smoothed"), var(&b, "Smoothed"));
}

#[test]
fn feet_finder_draws_the_same_every_run() {
    // feet_finder does not move bones; its debug output must still be identical.
    let program = compile_file("graphs/examples/feet_finder.ron");
    let mut a = instance(&program);
    let mut b = instance(&program);
    for k in 0..50 {
        a.run_forward(&frame(varying_dt(k)), &EmptyWorld, true);
        b.run_forward(&frame(varying_dt(k)), &EmptyWorld, true);
        assert_eq!(a.debug_draw().primitives(), b.debug_draw().primitives());
        assert_eq!(a.debug_draw().primitives().len(), 6);
    }
}

// ---------------------------------------------------------------------------------------
// 7. Hazards
// ---------------------------------------------------------------------------------------

#[test]
fn bad_dt_counts_as_zero() {
    let program = compile(
        r#"
Graph(
    version: 1,
    name: "bad_dt",
    variables: { "Time": (type: Float), "LastDt": (type: Float, default: -1.0), "Speed": (type: Float) },
    nodes: {
        "dt":    DeltaTime(),
        "t":     Add(a: var("Time"), b: "dt"),
        "speed": Divide(a: 10.0, b: "dt"),
        "pos":   MakeVector(z: "speed"),
        "xf":    MakeTransform(translation: "pos"),
    },
    events: { forward: [
        Set("Time", "t"), Set("LastDt", "dt"), Set("Speed", "speed"),
        SetTransform(bone: bone("spine_03"), value: "xf", space: Local),
    ] },
)
"#,
    );
    let mut inst = instance(&program);
    run(&mut inst, 0.25);
    assert_eq!(f(&inst, "Time"), 0.25);
    assert_eq!(f(&inst, "LastDt"), 0.25);
    // 10 / 0.25 = 40.
    assert_eq!(f(&inst, "Speed"), 40.0);
    for bad in [
        f32::NAN,
        -f32::NAN,
        -0.5,
        -0.0,
        f32::INFINITY,
        f32::NEG_INFINITY,
        -f32::MIN_POSITIVE,
    ] {
        run(&mut inst, bad);
        assert_eq!(f(&inst, "Time"), 0.25, "dt {bad} must not advance time");
        assert_eq!(
            f(&inst, "LastDt").to_bits(),
            0.0_f32.to_bits(),
            "DeltaTime for dt {bad}"
        );
        // 10 / 0 → 0, never infinity.
        assert_eq!(f(&inst, "Speed"), 0.0, "speed for dt {bad}");
        assert!(
            inst.pose_mut().globals().iter().all(Transform::is_finite),
            "pose finite for dt {bad}"
        );
    }
    // And a good dt afterwards continues from 0.25.
    run(&mut inst, 0.5);
    assert_eq!(f(&inst, "Time"), 0.75);
}

#[test]
fn non_finite_component_to_world_is_ignored() {
    let program = compile(
        r#"
Graph(
    version: 1,
    name: "world",
    variables: { "World": (type: Transform) },
    nodes: { "w": WorldTransform() },
    events: { forward: [ Set("World", "w") ] },
)
"#,
    );
    let mut inst = instance(&program);
    let placed = Transform::from_translation(Vec3::new(100.0, -20.0, 5.0));
    let input = |w: Transform| FrameInput {
        dt: 1.0 / 60.0,
        component_to_world: w,
        pose: InputPose::Rest,
    };
    inst.run_forward(&input(placed), &EmptyWorld, false);
    assert_eq!(t(&inst, "World"), placed);
    let nan_translation = Transform::from_translation(Vec3::new(f32::NAN, 0.0, 0.0));
    let inf_scale = Transform::new(
        Vec3::ZERO,
        Quat::IDENTITY,
        Vec3::new(1.0, f32::INFINITY, 1.0),
    );
    let nan_rotation = Transform::from_rotation(Quat::from_xyzw(f32::NAN, 0.0, 0.0, 1.0));
    for bad in [nan_translation, inf_scale, nan_rotation] {
        inst.run_forward(&input(bad), &EmptyWorld, false);
        assert_eq!(
            t(&inst, "World"),
            placed,
            "kept the last finite transform instead of {bad:?}"
        );
    }
    // A new finite transform is taken.
    let moved = Transform::from_translation(Vec3::new(1.0, 2.0, 3.0));
    inst.run_forward(&input(moved), &EmptyWorld, false);
    assert_eq!(t(&inst, "World"), moved);
}

const DEGENERATE: &str = r#"
Graph(
    version: 1,
    name: "degenerate",
    variables: {
        "Zero":     (type: Float, default: 0.0),
        "ZeroI":    (type: Int, default: 0),
        "ZeroV":    (type: Vec3),
        "QIn":      (type: Quat),
        "Floats":   (type: FloatArray, default: [1.0, 2.0]),
        "Xforms":   (type: TransformArray, default: [(translation: (1.0, 2.0, 3.0))]),
        "Bones":    (type: BoneArray, default: [bone("pelvis")]),
        "Vecs":     (type: Vec3Array),
        "Index":    (type: Int, default: 5),
        "DivF": (type: Float, default: -1.0), "DivZeroZero": (type: Float, default: -1.0),
        "DivI": (type: Int, default: -1), "DivV": (type: Vec3),
        "UnitV": (type: Vec3, default: (9.0, 9.0, 9.0)), "UnitQ": (type: Quat),
        "AtF": (type: Float, default: -1.0), "AtNeg": (type: Float, default: -1.0),
        "AtT": (type: Transform, default: (translation: (9.0, 9.0, 9.0))),
        "AtB": (type: Bone, default: bone("head")), "AtEmpty": (type: Vec3, default: (9.0, 9.0, 9.0)),
        "AtIn": (type: Float),
        "SqrtNeg": (type: Float, default: -1.0), "ModZero": (type: Float, default: -1.0),
        "Atan00": (type: Float, default: -1.0), "RemapFlat": (type: Float),
        "ClampLen": (type: Vec3, default: (9.0, 9.0, 9.0)), "Between": (type: Quat, default: (1.0, 0.0, 0.0, 0.0)),
        "SetAtOut": (type: FloatArray),
    },
    nodes: {
        "div_f":   Divide(a: 5.0, b: var("Zero")),
        "div_00":  Divide(a: var("Zero"), b: var("Zero")),
        "div_i":   Divide(a: 7, b: var("ZeroI")),
        "div_v":   Divide(a: (1.0, 2.0, 3.0), b: (0.0, 2.0, 0.0)),
        "unit_v":  Unit(value: var("ZeroV")),
        "unit_q":  Unit(value: var("QIn")),
        "at_f":    At(array: var("Floats"), index: var("Index")),
        "at_neg":  At(array: var("Floats"), index: -1),
        "at_t":    At(array: var("Xforms"), index: 1),
        "at_b":    At(array: var("Bones"), index: 1),
        "at_empty": At(array: var("Vecs"), index: 0),
        "at_in":   At(array: var("Floats"), index: 1),
        "sqrt":    Sqrt(value: -4.0),
        "mod":     Modulo(a: 5.0, b: var("Zero")),
        "atan":    Atan2(y: 0.0, x: 0.0),
        "remap":   Remap(value: 3.0, in_min: 2.0, in_max: 2.0, out_min: 7.0, out_max: 9.0),
        "clamp_len": ClampLength(value: var("ZeroV"), min: 5.0, max: 10.0),
        "between": FindQuatBetween(from: var("ZeroV"), to: (0.0, 0.0, 1.0)),
        "pos":     Add(a: "div_v", b: "unit_v"),
        "bad_xf":  MakeTransform(translation: "pos", rotation: "unit_q", scale: (0.0, 0.0, 0.0)),
        "inv":     Inverse(value: "bad_xf"),
    },
    events: {
        forward: [
            Set("DivF", "div_f"), Set("DivZeroZero", "div_00"), Set("DivI", "div_i"), Set("DivV", "div_v"),
            Set("UnitV", "unit_v"), Set("UnitQ", "unit_q"),
            Set("AtF", "at_f"), Set("AtNeg", "at_neg"), Set("AtT", "at_t"), Set("AtB", "at_b"),
            Set("AtEmpty", "at_empty"), Set("AtIn", "at_in"),
            Set("SqrtNeg", "sqrt"), Set("ModZero", "mod"), Set("Atan00", "atan"), Set("RemapFlat", "remap"),
            Set("ClampLen", "clamp_len"), Set("Between", "between"),
            Reset(array: var("SetAtOut")),
            Append(array: var("SetAtOut"), value: 1.0),
            SetAt(array: var("SetAtOut"), index: 3, value: 5.0),
            SetAt(array: var("SetAtOut"), index: -1, value: 5.0),
            SetTransform(bone: bone("spine_01"), value: "bad_xf", space: Global, propagate: false),
            SetTransform(bone: bone("thigh_l"), value: "inv", space: Local),
            SetTransform(bone: None, value: "bad_xf"),
        ],
    },
)
"#;

#[test]
fn degenerate_math_gives_documented_finite_results() {
    let program = compile(DEGENERATE);
    let mut inst = instance(&program);
    // A zero quaternion from the host (a var default must be a unit quaternion).
    set(
        &mut inst,
        "QIn",
        Value::Quat(Quat::from_xyzw(0.0, 0.0, 0.0, 0.0)),
    );
    for _ in 0..3 {
        run(&mut inst, 1.0 / 60.0);
        // Divide by zero → 0 (per component for vectors): 5/0 = 0, 0/0 = 0, 7/0 = 0,
        // (1, 2, 3)/(0, 2, 0) = (0, 1, 0).
        assert_eq!(f(&inst, "DivF"), 0.0);
        assert_eq!(f(&inst, "DivZeroZero"), 0.0);
        assert_eq!(i(&inst, "DivI"), 0);
        assert_eq!(v(&inst, "DivV"), Vec3::new(0.0, 1.0, 0.0));
        // Unit of a zero vector → zero vector; of a zero quaternion → identity.
        assert_eq!(v(&inst, "UnitV"), Vec3::ZERO);
        assert_eq!(var(&inst, "UnitQ"), Value::Quat(Quat::IDENTITY));
        // At out of range (5 of 2, −1, 1 of 1, 0 of 0) → the element type's zero.
        assert_eq!(f(&inst, "AtF"), 0.0);
        assert_eq!(f(&inst, "AtNeg"), 0.0);
        assert_eq!(t(&inst, "AtT"), Transform::IDENTITY);
        assert_eq!(var(&inst, "AtB"), Value::Bone(None));
        assert_eq!(v(&inst, "AtEmpty"), Vec3::ZERO);
        // In range it reads the element: Floats[1] = 2.
        assert_eq!(f(&inst, "AtIn"), 2.0);
        // Sqrt(−4) → 0; Modulo by 0 → 0; Atan2(0, 0) → 0; zero-width Remap → out_min 7.
        assert_eq!(f(&inst, "SqrtNeg"), 0.0);
        assert_eq!(f(&inst, "ModZero"), 0.0);
        assert_eq!(f(&inst, "Atan00"), 0.0);
        assert_eq!(f(&inst, "RemapFlat"), 7.0);
        // A zero vector has no direction: ClampLength keeps it zero; FindQuatBetween → identity.
        assert_eq!(v(&inst, "ClampLen"), Vec3::ZERO);
        near_q(
            match var(&inst, "Between") {
                Value::Quat(q) => q,
                other => panic!("{other:?}"),
            },
            Quat::IDENTITY,
            1e-6,
            "FindQuatBetween from zero",
        );
        // SetAt out of range does nothing: [1].
        assert_eq!(
            var(&inst, "SetAtOut"),
            Value::Array(Elem::Float, vec![Value::Float(1.0)])
        );
        // Zero scale and its inverse written into the pose: still finite.
        assert!(inst.pose_mut().globals().iter().all(Transform::is_finite));
    }
    // Index 1 is in range.
    set(&mut inst, "Index", Value::Int(1));
    run(&mut inst, 1.0 / 60.0);
    assert_eq!(f(&inst, "AtF"), 2.0);
}

#[test]
fn more_documented_fallbacks() {
    let program = compile(
        r#"
Graph(
    version: 1,
    name: "fallbacks",
    variables: {
        "In":      (type: Float),
        "ToIntIn": (type: Int, default: -1),
        "Big":     (type: Int, default: 2147483647),
        "Wrapped": (type: Int), "Neg": (type: Int), "Abs": (type: Int), "Prod": (type: Int),
        "Clamped": (type: Float), "ClampedI": (type: Int),
        "NoAxis":  (type: Quat, default: euler(10.0, 20.0, 30.0)),
    },
    nodes: {
        "to_int":  ToInt(value: var("In")),
        "wrap":    Add(a: var("Big"), b: 1),
        "min_int": Add(a: "wrap", b: 0),
        "neg":     Negate(value: "min_int"),
        "abs":     Abs(value: "min_int"),
        "prod":    Multiply(a: var("Big"), b: 2),
        "clamp":   Clamp(value: 5.0, min: 3.0, max: 1.0),
        "clamp_i": Clamp(value: -5, min: 3, max: 1),
        "no_axis": QuatFromAxisAngle(axis: (0.0, 0.0, 0.0), angle: 45.0),
    },
    events: { forward: [
        Set("ToIntIn", "to_int"), Set("Wrapped", "wrap"), Set("Neg", "neg"), Set("Abs", "abs"),
        Set("Prod", "prod"), Set("Clamped", "clamp"), Set("ClampedI", "clamp_i"), Set("NoAxis", "no_axis"),
    ] },
)
"#,
    );
    let mut inst = instance(&program);
    run(&mut inst, 0.1);
    // Int overflow wraps: i32::MAX + 1 = i32::MIN; −i32::MIN and |i32::MIN| wrap to i32::MIN;
    // i32::MAX · 2 = 2³² − 2 → wraps to −2.
    assert_eq!(i(&inst, "Wrapped"), i32::MIN);
    assert_eq!(i(&inst, "Neg"), i32::MIN);
    assert_eq!(i(&inst, "Abs"), i32::MIN);
    assert_eq!(i(&inst, "Prod"), -2);
    // Clamp with min > max gives max.
    assert_eq!(f(&inst, "Clamped"), 1.0);
    assert_eq!(i(&inst, "ClampedI"), 1);
    // A zero axis gives the identity.
    assert_eq!(var(&inst, "NoAxis"), Value::Quat(Quat::IDENTITY));
    // ToInt: truncates towards zero; NaN → 0; out of range saturates.
    for (x, expected) in [
        (0.0, 0),
        (-2.7, -2),
        (2.7, 2),
        (f32::NAN, 0),
        (1e10, i32::MAX),
        (-1e10, i32::MIN),
        (f32::INFINITY, i32::MAX),
    ] {
        set_f(&mut inst, "In", x);
        run(&mut inst, 0.1);
        assert_eq!(i(&inst, "ToIntIn"), expected, "ToInt({x})");
    }
}

/// Records the radius of the last sphere trace it was asked, and misses.
struct RadiusProbe(std::cell::Cell<f32>);

impl WorldQuery for RadiusProbe {
    fn line_trace(&self, _start: Vec3, _end: Vec3) -> Option<TraceHit> {
        None
    }

    fn sphere_trace(&self, _start: Vec3, _end: Vec3, radius: f32) -> Option<TraceHit> {
        self.0.set(radius);
        None
    }
}

#[test]
fn sphere_trace_with_a_negative_radius_uses_zero() {
    let program = compile(
        r#"
Graph(
    version: 1,
    name: "sphere",
    variables: { "Radius": (type: Float, default: -3.0), "Hit": (type: Bool, default: true) },
    nodes: { "s": SphereTrace(start: (0.0, 0.0, 10.0), end: (0.0, 0.0, -10.0), radius: var("Radius")) },
    events: { forward: [ Set("Hit", "s.hit") ] },
)
"#,
    );
    let mut inst = instance(&program);
    let probe = RadiusProbe(std::cell::Cell::new(f32::NAN));
    inst.run_forward(&frame(0.1), &probe, false);
    assert_eq!(probe.0.get(), 0.0);
    assert!(!b(&inst, "Hit"));
    set_f(&mut inst, "Radius", 4.5);
    inst.run_forward(&frame(0.1), &probe, false);
    assert_eq!(probe.0.get(), 4.5);
}

/// A floor at world z = 0, as a host would answer traces.
struct Floor;

impl WorldQuery for Floor {
    fn line_trace(&self, start: Vec3, end: Vec3) -> Option<TraceHit> {
        if start.z < 0.0 || end.z > 0.0 || start.z == end.z {
            return None;
        }
        let s = start.z / (start.z - end.z);
        let point = start + (end - start) * s;
        Some(TraceHit {
            point,
            normal: Vec3::Z,
            distance: start.distance(point),
        })
    }

    fn sphere_trace(&self, start: Vec3, end: Vec3, _radius: f32) -> Option<TraceHit> {
        self.line_trace(start, end)
    }
}

/// A broken host that answers every trace with NaN.
struct NanWorld;

impl WorldQuery for NanWorld {
    fn line_trace(&self, _start: Vec3, _end: Vec3) -> Option<TraceHit> {
        Some(TraceHit {
            point: Vec3::NAN,
            normal: Vec3::NAN,
            distance: f32::NAN,
        })
    }

    fn sphere_trace(&self, start: Vec3, end: Vec3, _radius: f32) -> Option<TraceHit> {
        self.line_trace(start, end)
    }
}

const TRACE: &str = r#"
Graph(
    version: 1,
    name: "trace",
    variables: { "Hit": (type: Bool), "Point": (type: Vec3), "Normal": (type: Vec3), "Dist": (type: Float) },
    nodes: { "down": LineTrace(start: (10.0, 0.0, 100.0), end: (10.0, 0.0, -100.0)) },
    events: { forward: [
        Set("Hit", "down.hit"), Set("Point", "down.point"), Set("Normal", "down.normal"), Set("Dist", "down.distance"),
        SetTransform(bone: bone("foot_l"), value: "foot", space: Global),
    ] },
)
"#;

#[test]
fn traces_go_through_the_world_transform_and_survive_a_nan_host() {
    let text = TRACE.replace(
        r#""down": LineTrace"#,
        r#""foot": MakeTransform(translation: "down.point"), "down": LineTrace"#,
    );
    let program = compile(&text);
    let mut inst = instance(&program);
    // The character stands at world (100, 50, 30), turned 90° about Z. The rig-space
    // segment (10, 0, ±100) maps to world (100, 50, 30) + Rz90·(10, 0, ±100) =
    // (100, 60, 130) → (100, 60, −70). It meets the floor at world (100, 60, 0) after
    // 130 cm. Back in rig space: Rz(−90)·((100, 60, 0) − (100, 50, 30)) = Rz(−90)·(0, 10, −30)
    // = (10, 0, −30); the normal +Z stays +Z.
    let input = FrameInput {
        dt: 1.0 / 60.0,
        component_to_world: Transform::from_translation_rotation(
            Vec3::new(100.0, 50.0, 30.0),
            rot_z(90.0),
        ),
        pose: InputPose::Rest,
    };
    inst.run_forward(&input, &Floor, false);
    assert!(b(&inst, "Hit"));
    near_v(
        v(&inst, "Point"),
        Vec3::new(10.0, 0.0, -30.0),
        TOL,
        "hit point",
    );
    near_v(v(&inst, "Normal"), Vec3::Z, 1e-5, "hit normal");
    near(f(&inst, "Dist"), 130.0, TOL, "hit distance");
    near_v(
        global(&mut inst, "foot_l").translation,
        Vec3::new(10.0, 0.0, -30.0),
        TOL,
        "foot",
    );

    // No geometry: a miss reports the end point, +Z and the full length (200).
    inst.run_forward(&input, &EmptyWorld, false);
    assert!(!b(&inst, "Hit"));
    near_v(
        v(&inst, "Point"),
        Vec3::new(10.0, 0.0, -100.0),
        TOL,
        "miss point",
    );
    near_v(v(&inst, "Normal"), Vec3::Z, 1e-6, "miss normal");
    near(f(&inst, "Dist"), 200.0, TOL, "miss distance");

    // A host answering NaN: treated as a miss (docs/format.md, runtime fallbacks), so every
    // output and the pose stay finite.
    inst.run_forward(&input, &NanWorld, false);
    assert!(!b(&inst, "Hit"));
    near_v(
        v(&inst, "Point"),
        Vec3::new(10.0, 0.0, -100.0),
        TOL,
        "NaN host point",
    );
    near_v(v(&inst, "Normal"), Vec3::Z, 1e-6, "NaN host normal");
    near(f(&inst, "Dist"), 200.0, TOL, "NaN host distance");
    assert!(inst.pose_mut().globals().iter().all(Transform::is_finite));
}

// ---------------------------------------------------------------------------------------
// 8. Debug draw
// ---------------------------------------------------------------------------------------

#[test]
fn pelvis_bob_draws_its_target_only_when_asked() {
    let program = compile_file("graphs/pelvis_bob.ron");
    let mut inst = instance(&program);
    // Debug on, dt = 0.25: target at (0, 0, 100), drawn with size 15 and the default
    // thickness 0.5.
    inst.run_forward(&frame(0.25), &EmptyWorld, true);
    let prims = inst.debug_draw().primitives().to_vec();
    assert_eq!(prims.len(), 1, "{prims:?}");
    match prims[0] {
        DebugPrimitive::Axes {
            transform,
            size,
            thickness,
        } => {
            near_v(
                transform.translation,
                Vec3::new(0.0, 0.0, 100.0),
                TOL,
                "axes",
            );
            near_q(transform.rotation, Quat::IDENTITY, 1e-6, "axes rotation");
            assert_eq!(size, 15.0);
            assert_eq!(thickness, 0.5);
        }
        other => panic!("expected axes, got {other:?}"),
    }
    // Debug off: nothing recorded, the animation still runs (t = 0.5 → 95).
    inst.run_forward(&frame(0.25), &EmptyWorld, false);
    assert!(inst.debug_draw().primitives().is_empty());
    near(
        global(&mut inst, "pelvis").translation.z,
        95.0,
        TOL,
        "pelvis with debug off",
    );
    // On again: one primitive per frame, not accumulated (t = 0.75 → z 90).
    for z in [90.0, 95.0] {
        inst.run_forward(&frame(0.25), &EmptyWorld, true);
        let prims = inst.debug_draw().primitives();
        assert_eq!(prims.len(), 1);
        let DebugPrimitive::Axes { transform, .. } = prims[0] else {
            panic!("{prims:?}")
        };
        near(transform.translation.z, z, TOL, "axes z");
    }
}

#[test]
fn draw_nodes_record_their_pins_in_order() {
    let program = compile(
        r#"
Graph(
    version: 1,
    name: "draw",
    nodes: {
        "x":     MakeVector(x: "i"),
        "tip":   Add(a: "x", b: (0.0, 0.0, 10.0)),
        "box_t": MakeTransform(translation: (1.0, 2.0, 3.0)),
    },
    events: { forward: [
        For(count: 3, index: "i", body: [ DrawLine(start: "x", end: "tip", thickness: 2.0, color: (0.0, 1.0, 0.0)) ]),
        DrawPoint(position: (5.0, 6.0, 7.0)),
        DrawArrow(start: (0.0, 0.0, 0.0), end: (0.0, 1.0, 0.0)),
        DrawSphere(center: (0.0, 0.0, 50.0), radius: 4.0, color: (0.25, 0.5, 0.75)),
        DrawBox(transform: "box_t", half_extents: (1.0, 2.0, 3.0)),
    ] },
)
"#,
    );
    let mut inst = instance(&program);
    inst.run_forward(&frame(0.1), &EmptyWorld, true);
    let green = DebugColor([0.0, 1.0, 0.0, 1.0]);
    let mut expected: Vec<DebugPrimitive> = (0..3)
        .map(|i| DebugPrimitive::Line {
            start: Vec3::new(i as f32, 0.0, 0.0),
            end: Vec3::new(i as f32, 0.0, 10.0),
            thickness: 2.0,
            color: green,
        })
        .collect();
    expected.push(DebugPrimitive::Point {
        position: Vec3::new(5.0, 6.0, 7.0),
        size: 2.0,                // default
        color: DebugColor::WHITE, // default
    });
    expected.push(DebugPrimitive::Arrow {
        start: Vec3::ZERO,
        end: Vec3::Y,
        thickness: 0.5,                          // default
        color: DebugColor([1.0, 1.0, 0.0, 1.0]), // default yellow
    });
    expected.push(DebugPrimitive::Sphere {
        center: Vec3::new(0.0, 0.0, 50.0),
        radius: 4.0,
        color: DebugColor([0.25, 0.5, 0.75, 1.0]),
    });
    expected.push(DebugPrimitive::Box {
        transform: Transform::from_translation(Vec3::new(1.0, 2.0, 3.0)),
        half_extents: Vec3::new(1.0, 2.0, 3.0),
        color: DebugColor::WHITE,
    });
    assert_eq!(inst.debug_draw().primitives(), expected.as_slice());
    // Same again next frame (the buffer is cleared, not appended to).
    inst.run_forward(&frame(0.1), &EmptyWorld, true);
    assert_eq!(inst.debug_draw().primitives(), expected.as_slice());
    inst.run_forward(&frame(0.1), &EmptyWorld, false);
    assert!(inst.debug_draw().primitives().is_empty());
    // Construction draws nothing that survives into the frame output either.
    let fresh = instance(&program);
    assert!(fresh.debug_draw().primitives().is_empty());
}
