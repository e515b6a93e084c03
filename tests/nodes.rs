//! Every built-in node used from RON: a one-node graph per case, run for one frame, its
//! output read back through a variable. Expected values are worked out by hand in the
//! comments. A last test checks that every node of the table appears here or in a shipped
//! example graph.

use std::path::Path;
use std::sync::Arc;
use strider_core::{EmptyWorld, Quat, TraceHit, Transform, Vec3, WorldQuery};
use strider_nodes::{Value, ValueType};
use strider_vm::{FrameInput, Instance};

/// A flat floor at world z = 0 (normal +Z) for trace nodes.
struct Floor;

impl WorldQuery for Floor {
    fn line_trace(&self, start: Vec3, end: Vec3) -> Option<TraceHit> {
        if (start.z >= 0.0) == (end.z >= 0.0) {
            return None;
        }
        let t = start.z / (start.z - end.z);
        let point = start.lerp(end, t);
        Some(TraceHit {
            point,
            normal: Vec3::Z,
            distance: start.distance(point),
        })
    }

    fn sphere_trace(&self, start: Vec3, end: Vec3, radius: f32) -> Option<TraceHit> {
        // The centre stops `radius` above the floor; the contact is right below it.
        let lifted = Vec3::new(0.0, 0.0, radius);
        let hit = self.line_trace(start - lifted, end - lifted)?;
        Some(TraceHit {
            point: hit.point,
            normal: Vec3::Z,
            distance: hit.distance,
        })
    }
}

fn skeleton() -> Arc<strider_core::Skeleton> {
    strider_graph::load_skeleton(Path::new("graphs/skeletons/mannequin.ron"))
        .unwrap()
        .skeleton
}

/// Runs `node` (RON, e.g. `Add(a: 1.0, b: 2.0)`) once and returns output `pin` as type `ty`.
fn eval_with(
    node: &str,
    pin: &str,
    ty: ValueType,
    dt: f32,
    world: &dyn WorldQuery,
    to_world: Transform,
) -> Value {
    let link = if pin.is_empty() {
        "n".to_string()
    } else {
        format!("n.{pin}")
    };
    let text = format!(
        "Graph(version: 1, name: \"t\", variables: {{ \"Out\": (type: {ty}) }}, nodes: {{ \"n\": {node} }}, events: {{ forward: [ Set(\"Out\", \"{link}\") ] }})"
    );
    let program =
        strider_compiler::compile_str(Path::new("node_test.ron"), &text).unwrap_or_else(|d| {
            panic!(
                "{node}: {}",
                d.iter()
                    .map(ToString::to_string)
                    .collect::<Vec<_>>()
                    .join("\n")
            )
        });
    let program = Arc::new(program);
    let mut instance = Instance::new(program.clone(), skeleton()).unwrap();
    instance.run_forward(
        &FrameInput {
            dt,
            component_to_world: to_world,
            ..Default::default()
        },
        world,
        false,
    );
    instance.variable(program.variable_id("Out").unwrap())
}

fn eval(node: &str, pin: &str, ty: ValueType) -> Value {
    eval_with(node, pin, ty, 1.0 / 60.0, &EmptyWorld, Transform::IDENTITY)
}

fn float(node: &str) -> f32 {
    match eval(node, "", ValueType::Float) {
        Value::Float(x) => x,
        v => panic!("{v:?}"),
    }
}

fn int(node: &str) -> i32 {
    match eval(node, "", ValueType::Int) {
        Value::Int(x) => x,
        v => panic!("{v:?}"),
    }
}

fn boolean(node: &str) -> bool {
    match eval(node, "", ValueType::Bool) {
        Value::Bool(x) => x,
        v => panic!("{v:?}"),
    }
}

fn vec3(node: &str, pin: &str) -> Vec3 {
    match eval(node, pin, ValueType::Vec3) {
        Value::Vec3(x) => x,
        v => panic!("{v:?}"),
    }
}

fn quat(node: &str) -> Quat {
    match eval(node, "", ValueType::Quat) {
        Value::Quat(x) => x,
        v => panic!("{v:?}"),
    }
}

fn transform(node: &str) -> Transform {
    match eval(node, "", ValueType::Transform) {
        Value::Transform(x) => x,
        v => panic!("{v:?}"),
    }
}

fn close(a: f32, b: f32) {
    assert!((a - b).abs() < 1e-4, "{a} != {b}");
}

fn close_v(a: Vec3, b: Vec3) {
    assert!((a - b).length() < 1e-4, "{a} != {b}");
}

fn same_rotation(a: Quat, b: Quat) {
    assert!(a.dot(b).abs() > 1.0 - 1e-6, "{a} != {b}");
}

#[test]
fn arithmetic() {
    close(float("Add(a: 1.5, b: 2.25)"), 3.75);
    assert_eq!(int("Add(a: 2, b: 3)"), 5);
    // Int literal on a Float pin: 1 + 0.5.
    close(float("Add(a: 1, b: 0.5)"), 1.5);
    close_v(
        vec3("Add(a: (1.0, 2.0, 3.0), b: (1.0, 1.0, 1.0))", ""),
        Vec3::new(2.0, 3.0, 4.0),
    );
    close(float("Subtract(a: 1.0, b: 3.0)"), -2.0);
    assert_eq!(int("Multiply(a: 6, b: 7)"), 42);
    close_v(
        vec3("Multiply(a: (1.0, 2.0, 3.0), b: (2.0, 2.0, -1.0))", ""),
        Vec3::new(2.0, 4.0, -3.0),
    );
    close(float("Divide(a: 1.0, b: 4.0)"), 0.25);
    close(float("Divide(a: 1.0, b: 0.0)"), 0.0);
    assert_eq!(int("Divide(a: 7, b: 2)"), 3);
    close(float("Modulo(a: -30.0, b: 360.0)"), 330.0);
    assert_eq!(int("Modulo(a: -1, b: 3)"), 2);
    close(float("Min(a: 2.0, b: -1.0)"), -1.0);
    close(float("Max(a: 2.0, b: -1.0)"), 2.0);
    close(float("Abs(value: -2.5)"), 2.5);
    close(float("Negate(value: 2.5)"), -2.5);
    close(float("Clamp(value: 50.0, min: -30.0, max: 40.0)"), 40.0);
    close_v(
        vec3(
            "Clamp(value: (5.0, -5.0, 0.5), min: (0.0, 0.0, 0.0), max: (1.0, 1.0, 1.0))",
            "",
        ),
        Vec3::new(1.0, 0.0, 0.5),
    );
    close(float("Sin(value: 30.0)"), 0.5);
    close(float("Cos(value: 60.0)"), 0.5);
    close(float("Tan(value: 45.0)"), 1.0);
    close(float("Atan2(y: 1.0, x: -1.0)"), 135.0);
    close(float("Sqrt(value: 2.25)"), 1.5);
    close(float("Pow(base: 2.0, exponent: 10.0)"), 1024.0);
    close(float("Fract(value: 2.75)"), 0.75);
    close(float("Floor(value: -1.5)"), -2.0);
    close(float("Ceil(value: -1.5)"), -1.0);
    close(float("Round(value: 2.5)"), 3.0);
    assert_eq!(int("ToInt(value: -2.7)"), -2);
    close(float("ToFloat(value: 7)"), 7.0);
    close(float("Lerp(a: 10.0, b: 20.0, alpha: 0.25)"), 12.5);
    close_v(
        vec3(
            "Lerp(a: (0.0, 0.0, 0.0), b: (4.0, 8.0, 0.0), alpha: 0.5)",
            "",
        ),
        Vec3::new(2.0, 4.0, 0.0),
    );
    // The seed's stride remap: 250 cm/s in 200..300 → 65..45 is 55.
    close(
        float("Remap(value: 250.0, in_min: 200.0, in_max: 300.0, out_min: 65.0, out_max: 45.0)"),
        55.0,
    );
    close(
        float(
            "Remap(value: 400.0, in_min: 0.0, in_max: 200.0, out_min: 0.0, out_max: 1.0, clamp: false)",
        ),
        2.0,
    );
}

#[test]
fn logic_and_comparisons() {
    assert!(boolean("And(a: true, b: true)"));
    assert!(!boolean("And(a: true, b: false)"));
    assert!(boolean("Or(a: false, b: true)"));
    assert!(boolean("Xor(a: false, b: true)"));
    assert!(!boolean("Not(value: true)"));
    assert!(boolean("Equals(a: 0, b: 0)"));
    assert!(boolean("NotEquals(a: 1.0, b: 2.0)"));
    assert!(boolean("Less(a: 1.0, b: 2.0)"));
    assert!(boolean("LessEqual(a: 2, b: 2)"));
    assert!(!boolean("Greater(a: 1.0, b: 2.0)"));
    assert!(boolean("GreaterEqual(a: 3, b: 2)"));
    close_v(
        vec3(
            "Select(condition: false, if_true: (1.0, 0.0, 0.0), if_false: (-1.0, 0.0, 0.0))",
            "",
        ),
        Vec3::new(-1.0, 0.0, 0.0),
    );
}

#[test]
fn vectors() {
    close_v(
        vec3("Scale(value: (1.0, 2.0, 3.0), factor: -2.0)", ""),
        Vec3::new(-2.0, -4.0, -6.0),
    );
    close(float("Length(value: (3.0, 4.0, 12.0))"), 13.0);
    close(
        float("Distance(a: (1.0, 1.0, 1.0), b: (4.0, 5.0, 1.0))"),
        5.0,
    );
    close_v(
        vec3("Unit(value: (0.0, 3.0, 4.0))", ""),
        Vec3::new(0.0, 0.6, 0.8),
    );
    close_v(vec3("Unit(value: (0.0, 0.0, 0.0))", ""), Vec3::ZERO);
    close(float("Dot(a: (1.0, 2.0, 3.0), b: (4.0, -5.0, 6.0))"), 12.0);
    // X × Y = Z (right-handed).
    close_v(
        vec3("Cross(a: (1.0, 0.0, 0.0), b: (0.0, 1.0, 0.0))", ""),
        Vec3::Z,
    );
    close_v(
        vec3("MakeVector(x: 1.0, z: 3.0)", ""),
        Vec3::new(1.0, 0.0, 3.0),
    );
    close(
        match eval("BreakVector(value: (1.0, 2.0, 3.0))", "y", ValueType::Float) {
            Value::Float(x) => x,
            v => panic!("{v:?}"),
        },
        2.0,
    );
    // A 200 cm step clamped to 50 cm keeps its direction.
    close_v(
        vec3("ClampLength(value: (0.0, 120.0, 160.0), max: 50.0)", ""),
        Vec3::new(0.0, 30.0, 40.0),
    );
    // A foot 150 cm ahead of the pelvis pulled into the 100 cm sphere.
    close_v(
        vec3(
            "ClampSpatially(point: (0.0, 150.0, 90.0), center: (0.0, 0.0, 90.0), max_radius: 100.0)",
            "",
        ),
        Vec3::new(0.0, 100.0, 90.0),
    );
}

#[test]
fn rotations() {
    let h = std::f32::consts::FRAC_1_SQRT_2;
    // 90° about +Z.
    same_rotation(
        quat("QuatFromAxisAngle(axis: (0.0, 0.0, 1.0), angle: 90.0)"),
        Quat::from_xyzw(0.0, 0.0, h, h),
    );
    // Euler XYZ (90, 0, 90) = Rz(90)·Rx(90) = (0.5, 0.5, 0.5, 0.5), derived in strider-core.
    same_rotation(
        quat("QuatFromEuler(euler: (90.0, 0.0, 90.0))"),
        Quat::from_xyzw(0.5, 0.5, 0.5, 0.5),
    );
    // ZYX applies Z first: Rx(90)·Rz(90) = (0.5, -0.5, 0.5, 0.5).
    same_rotation(
        quat("QuatFromEuler(euler: (90.0, 0.0, 90.0), order: ZYX)"),
        Quat::from_xyzw(0.5, -0.5, 0.5, 0.5),
    );
    close_v(
        vec3("EulerFromQuat(value: (0.5, 0.5, 0.5, 0.5))", ""),
        Vec3::new(90.0, 0.0, 90.0),
    );
    // (Rz90)·(Rz90) = Rz180 = (0, 0, 1, 0).
    same_rotation(
        quat("Multiply(a: euler(0.0, 0.0, 90.0), b: euler(0.0, 0.0, 90.0))"),
        Quat::from_xyzw(0.0, 0.0, 1.0, 0.0),
    );
    same_rotation(
        quat("Inverse(value: euler(0.0, 0.0, 90.0))"),
        Quat::from_xyzw(0.0, 0.0, -h, h),
    );
    same_rotation(
        quat("Unit(value: (0.0, 0.0, 0.7071068, 0.7071068))"),
        Quat::from_xyzw(0.0, 0.0, h, h),
    );
    // Halfway between 0° and 90° about Z is 45°.
    same_rotation(
        quat("Slerp(b: euler(0.0, 0.0, 90.0), alpha: 0.5)"),
        Quat::from_rotation_z(45f32.to_radians()),
    );
    // Rz90 maps +Y to -X.
    close_v(
        vec3(
            "RotateVector(rotation: euler(0.0, 0.0, 90.0), vector: (0.0, 1.0, 0.0))",
            "",
        ),
        -Vec3::X,
    );
    // Two thirds of a 30° twist, negated: -20°.
    same_rotation(
        quat("QuatScale(rotation: euler(0.0, 0.0, 30.0), scale: -0.6666667)"),
        Quat::from_rotation_z(-20f32.to_radians()),
    );
    // +Y to +Z is +90° about X.
    same_rotation(
        quat("FindQuatBetween(from: (0.0, 1.0, 0.0), to: (0.0, 0.0, 5.0))"),
        Quat::from_rotation_x(90f32.to_radians()),
    );
}

#[test]
fn transforms() {
    let t = transform(
        "MakeTransform(translation: (1.0, 2.0, 3.0), rotation: euler(0.0, 0.0, 90.0), scale: (2.0, 2.0, 2.0))",
    );
    close_v(t.translation, Vec3::new(1.0, 2.0, 3.0));
    close_v(t.scale, Vec3::splat(2.0));
    close_v(
        vec3(
            "BreakTransform(value: (translation: (4.0, 5.0, 6.0)))",
            "translation",
        ),
        Vec3::new(4.0, 5.0, 6.0),
    );
    // Parent at z = 95 rotated 90° about Z; child 10 along its X → rig (0, 10, 95).
    let c = transform(
        "Multiply(a: (translation: (0.0, 0.0, 95.0), rotation: euler(0.0, 0.0, 90.0)), b: (translation: (10.0, 0.0, 0.0)))",
    );
    close_v(c.translation, Vec3::new(0.0, 10.0, 95.0));
    let r = transform(
        "MakeRelative(global: (translation: (0.0, 10.0, 95.0)), parent: (translation: (0.0, 0.0, 95.0), rotation: euler(0.0, 0.0, 90.0)))",
    );
    close_v(r.translation, Vec3::new(10.0, 0.0, 0.0));
    // A parent stretched 2× along its own X and turned 90° about Z: the child at rig
    // (0, 20, 95) is 20 cm along the parent's X, stretched, so 10 cm before the stretch;
    // its scale (2, 3, 1) is (1, 3, 1) of the parent's. MakeAbsolute takes it back.
    let parent =
        "(translation: (0.0, 0.0, 95.0), rotation: euler(0.0, 0.0, 90.0), scale: (2.0, 1.0, 1.0))";
    let r = transform(&format!(
        "MakeRelative(global: (translation: (0.0, 20.0, 95.0), rotation: euler(0.0, 0.0, 90.0), scale: (2.0, 3.0, 1.0)), parent: {parent})"
    ));
    close_v(r.translation, Vec3::new(10.0, 0.0, 0.0));
    close_v(r.scale, Vec3::new(1.0, 3.0, 1.0));
    assert!(r.rotation.angle_between(Quat::IDENTITY) < 1e-5);
    let back = transform(&format!(
        "MakeAbsolute(local: (translation: (10.0, 0.0, 0.0), scale: (1.0, 3.0, 1.0)), parent: {parent})"
    ));
    close_v(back.translation, Vec3::new(0.0, 20.0, 95.0));
    close_v(back.scale, Vec3::new(2.0, 3.0, 1.0));
    let a = transform(
        "MakeAbsolute(local: (translation: (10.0, 0.0, 0.0)), parent: (translation: (0.0, 0.0, 95.0), rotation: euler(0.0, 0.0, 90.0)))",
    );
    close_v(a.translation, Vec3::new(0.0, 10.0, 95.0));
    close_v(
        transform("Inverse(value: (translation: (1.0, 2.0, 3.0)))").translation,
        Vec3::new(-1.0, -2.0, -3.0),
    );
    close_v(
        vec3(
            "TransformPoint(transform: (translation: (0.0, 0.0, 5.0), rotation: euler(0.0, 0.0, 90.0)), point: (0.0, 1.0, 0.0))",
            "",
        ),
        Vec3::new(-1.0, 0.0, 5.0),
    );
    close_v(
        vec3(
            "TransformVector(transform: (translation: (0.0, 0.0, 5.0), rotation: euler(0.0, 0.0, 90.0)), vector: (0.0, 1.0, 0.0))",
            "",
        ),
        -Vec3::X,
    );
    // Heel roll: a foot at (0, 10, 13.5) pitched 90° about +X around the heel (0, 0, 13.5):
    // offset (0, 10, 0) turns to (0, 0, 10).
    let rolled = transform(
        "RotateAroundPoint(transform: (translation: (0.0, 10.0, 13.5)), pivot: (0.0, 0.0, 13.5), rotation: euler(90.0, 0.0, 0.0))",
    );
    close_v(rolled.translation, Vec3::new(0.0, 0.0, 23.5));
    let i = transform(
        "InterpolateTransform(a: (translation: (0.0, 0.0, 0.0)), b: (translation: (10.0, 0.0, 0.0), rotation: euler(0.0, 0.0, 90.0)), alpha: 0.5)",
    );
    close_v(i.translation, Vec3::new(5.0, 0.0, 0.0));
    same_rotation(i.rotation, Quat::from_rotation_z(45f32.to_radians()));
    // Aim the Y axis of a transform at (0, 0, 10) from (0, 0, 0): +Y to +Z.
    let aimed = transform(
        "AimMath(transform: (translation: (0.0, 0.0, 0.0)), target: (0.0, 0.0, 10.0), mode: Location)",
    );
    close_v(aimed.rotation * Vec3::Y, Vec3::Z);
    // Align up with a 45° slope normal towards -X: the up axis follows the normal.
    let n = Vec3::new(-1.0, 0.0, 1.0).normalize();
    let aligned = transform(
        "AlignToNormal(transform: (translation: (0.0, 0.0, 0.0)), normal: (-1.0, 0.0, 1.0))",
    );
    close_v(aligned.rotation * Vec3::Z, n);
}

#[test]
fn splines() {
    // Three points: the B-spline is the quadratic Bézier (1−u)²p0 + 2u(1−u)p1 + u²p2.
    // At u = 0.5: 0.25·(0,0,0) + 0.5·(0,10,20) + 0.25·(0,20,0) = (0, 10, 10); the tangent
    // 2(1−u)(p1 − p0) + 2u(p2 − p1) = p2 − p0 = (0, 20, 0).
    let pts = "[(0.0, 0.0, 0.0), (0.0, 10.0, 20.0), (0.0, 20.0, 0.0)]";
    close_v(
        vec3(&format!("BSpline(points: {pts}, u: 0.5)"), "position"),
        Vec3::new(0.0, 10.0, 10.0),
    );
    close_v(
        vec3(&format!("BSpline(points: {pts}, u: 0.5)"), "tangent"),
        Vec3::new(0.0, 20.0, 0.0),
    );
    // Catmull-Rom passes through the middle point at u = 1/2.
    close_v(
        vec3(
            &format!("BSpline(points: {pts}, u: 0.5, mode: CatmullRom)"),
            "position",
        ),
        Vec3::new(0.0, 10.0, 20.0),
    );
    // u is clamped: past the end is the last point.
    close_v(
        vec3(&format!("BSpline(points: {pts}, u: 3.0)"), "position"),
        Vec3::new(0.0, 20.0, 0.0),
    );

    let text = format!(
        "Graph(version: 1, name: \"s\", events: {{ forward: [ DrawSpline(points: {pts}, segments: 4) ] }})"
    );
    let program = Arc::new(strider_compiler::compile_str(Path::new("s.ron"), &text).unwrap());
    let mut i = Instance::new(program, skeleton()).unwrap();
    i.run_forward(&FrameInput::default(), &EmptyWorld, true);
    let prims = i.debug_draw().primitives();
    assert_eq!(prims.len(), 4);
    // The second piece runs from u = 0.25 to u = 0.5: B(0.25) = 0.5625·p0 + 0.375·p1 + 0.0625·p2
    // = (0, 5, 7.5).
    let strider_core::DebugPrimitive::Line { start, end, .. } = prims[1] else {
        panic!()
    };
    close_v(start, Vec3::new(0.0, 5.0, 7.5));
    close_v(end, Vec3::new(0.0, 10.0, 10.0));
}

fn float_pin(node: &str, pin: &str) -> f32 {
    match eval(node, pin, ValueType::Float) {
        Value::Float(x) => x,
        v => panic!("{v:?}"),
    }
}

#[test]
fn smoothing() {
    // eval runs one frame of dt = 1/60 s. At speed 6/s the gap shrinks by
    // 1 − e^(−6/60) = 1 − e^(−0.1) = 0.0951626.
    let a = 1.0 - (-0.1f32).exp();
    close_v(
        vec3(
            "VectorLerp(current: (0.0, 0.0, 0.0), target: (100.0, 0.0, 0.0), speed: 6.0)",
            "",
        ),
        Vec3::new(100.0 * a, 0.0, 0.0),
    );
    // Max-step variant: at most 60 cm/s · 1/60 s = 1 cm this frame.
    close_v(
        vec3(
            "VectorLerp(current: (0.0, 0.0, 0.0), target: (100.0, 0.0, 0.0), speed: 6.0, max_per_second: 60.0)",
            "",
        ),
        Vec3::new(1.0, 0.0, 0.0),
    );
    close(
        float("FloatLerp(current: 0.0, target: 10.0, speed: 6.0)"),
        10.0 * a,
    );
    // 90° × 0.0951626 = 8.5646° about Z.
    same_rotation(
        quat("QuatLerp(current: euler(0.0, 0.0, 0.0), target: euler(0.0, 0.0, 90.0), speed: 6.0)"),
        Quat::from_rotation_z((90.0 * a).to_radians()),
    );
    // FInterpTo: step (10 − 0)·clamp(10/60, 0, 1) = 1.6667.
    close(
        float("FInterpTo(current: 0.0, target: 10.0, speed: 10.0)"),
        10.0 / 6.0,
    );
    close_v(
        vec3(
            "FInterpTo(current: (0.0, 0.0, 0.0), target: (0.0, 6.0, 0.0), speed: 10.0)",
            "",
        ),
        Vec3::new(0.0, 1.0, 0.0),
    );
    same_rotation(
        quat(
            "FInterpTo(current: euler(0.0, 0.0, 0.0), target: euler(0.0, 0.0, 60.0), speed: 10.0)",
        ),
        Quat::from_rotation_z(10f32.to_radians()),
    );
    // A spring starts at rest on the first target it sees.
    close(float("SpringDamper(target: 5.0, half_life: 0.2)"), 5.0);
    close_v(
        vec3("SpringDamper(target: (1.0, 2.0, 3.0))", "value"),
        Vec3::new(1.0, 2.0, 3.0),
    );
}

#[test]
fn locomotion_units() {
    let a = 1.0 - (-0.1f32).exp();
    // Velocity (−100, 100): Rz(+45°) maps +Y to (−0.707, 0.707), so the yaw is 45°; from 0
    // at speed 6 for 1/60 s: 45 × 0.0951626 = 4.2823.
    close(
        float(
            "GetMovementAngleOffset(velocity: (-100.0, 100.0, 0.0), current: 0.0, master_cycle: 0.0)",
        ),
        45.0 * a,
    );
    // Straight back is yaw 180, folded to 0: the legs step backwards.
    close(
        float(
            "GetMovementAngleOffset(velocity: (0.0, -100.0, 0.0), current: 0.0, master_cycle: 0.0)",
        ),
        0.0,
    );
    // Standing still keeps the offset.
    close(
        float(
            "GetMovementAngleOffset(velocity: (0.0, 0.0, 0.0), current: 30.0, master_cycle: 0.0)",
        ),
        30.0,
    );
    close(float("CalculatePerFootRotationFactor(yaw: 10.0)"), 0.5);
    close(float("CalculatePerFootRotationFactor(yaw: -10.0)"), 0.9);
    same_rotation(
        quat("LimitRotationAroundZ(rotation: euler(0.0, 0.0, 60.0), limit: 25.0)"),
        Quat::from_rotation_z(25f32.to_radians()),
    );
    // Moving forward: Side = Rz(90°)·Y = −X (the character's right). The right foot at
    // x = −10 has side coordinate 10; the left foot wants x = −5 (side 5) but must stay at
    // side ≤ 10 − 15 = −5, i.e. x = 5, 15 cm left of the right foot. Forward (10) is kept.
    close_v(
        vec3(
            "FootAvoidance(ideal: (-5.0, 10.0, 2.0), other_foot: (-10.0, 0.0, 0.0), is_left: true)",
            "",
        ),
        Vec3::new(5.0, 10.0, 2.0),
    );
    // The right foot mirrored: it must stay at side ≥ o + 15.
    close_v(
        vec3(
            "FootAvoidance(ideal: (5.0, 10.0, 0.0), other_foot: (10.0, 0.0, 0.0), is_left: false)",
            "",
        ),
        Vec3::new(-5.0, 10.0, 0.0),
    );
    // Knee (0, 2, 0)·20 = (0, 40, 0), turned by slerp(identity, Rz(90°), 0.25) = Rz(22.5°):
    // (−40·sin 22.5°, 40·cos 22.5°, 0) = (−15.307, 36.955, 0).
    close_v(
        vec3(
            "CalculateKneeVector(platform_rotation: euler(0.0, 0.0, 0.0), movement_rotation: euler(0.0, 0.0, 90.0), default_knee: (0.0, 2.0, 0.0))",
            "",
        ),
        Vec3::new(-15.307337, 36.95518, 0.0),
    );
    // Running forward at 300 cm/s, cycle 0.1: sin(360°·fract(0.1 + 0.15)) = 1; direction
    // factor 1; full swing 50; lateral clamp(|300·0.4|, 0.4, 1) = 1; plus base 15 = 65°.
    close(
        float(
            "ArmSwingRotation(per_foot_cycle: 0.1, velocity: (0.0, 300.0, 0.0), movement_rotation: euler(0.0, 0.0, 0.0))",
        ),
        65.0,
    );
    close(
        float(
            "ArmSwingRotation(per_foot_cycle: 0.1, velocity: (0.0, 0.0, 0.0), movement_rotation: euler(0.0, 0.0, 0.0))",
        ),
        0.0,
    );
    // sin(720°·(0.375 − 0.25)) = sin 90° = 1, at full speed: 1.5 cm.
    close(
        float("ClavicleOffset(master_cycle: 0.375, speed: 300.0)"),
        1.5,
    );
    // Half speed forward: pitch −7.5°, shift 5 cm.
    close(
        float_pin("PelvisLean(velocity: (0.0, 150.0, 0.0))", "pitch"),
        -7.5,
    );
    close(
        float_pin("PelvisLean(velocity: (0.0, 150.0, 0.0))", "shift"),
        5.0,
    );
    // Backwards leans back.
    close(
        float_pin("PelvisLean(velocity: (0.0, -150.0, 0.0))", "pitch"),
        7.5,
    );
    close(float("PelvisSideLean(height_difference: 30.0)"), 7.5);
    // Ankle (0, 0, 13.5), ball (0, 14, 3): fwd = (0, 5.8, 0); ball pivot (0, 14, 0.5);
    // tip (0, 19.8, 0.5); heel (0, 0, 4.5) − 0.8·fwd = (0, −4.64, 4.5).
    let pivots = "FootPivots(foot: (0.0, 0.0, 13.5), ball: (0.0, 14.0, 3.0))";
    close_v(vec3(pivots, "ball_pivot"), Vec3::new(0.0, 14.0, 0.5));
    close_v(vec3(pivots, "tip"), Vec3::new(0.0, 19.8, 0.5));
    close_v(vec3(pivots, "heel"), Vec3::new(0.0, -4.64, 4.5));
    // fract(0.9 + (1/60)/1.0) = 0.916667; the second foot half a cycle on: 0.416667.
    let cycle = "CycleStep(master: 0.9, cycle_length: 1.0, foot_offset: 0.5)";
    close(float_pin(cycle, "next"), 0.9 + 1.0 / 60.0);
    close(float_pin(cycle, "per_foot"), 0.9 + 1.0 / 60.0 - 0.5);
    // Not moving: no stepping in place.
    close(
        float_pin(
            "CycleStep(master: 0.9, cycle_length: 1.0, moving: false)",
            "next",
        ),
        0.9,
    );
    close(
        float("FootOffsetFromTrace(hit: true, distance: 80.0, half_height: 90.0)"),
        10.0,
    );
    close(
        float("FootOffsetFromTrace(hit: false, distance: 80.0, half_height: 90.0)"),
        0.0,
    );
    // A 10° slope rising towards −Y: n = (0, sin 10°, cos 10°): roll = atan2(n.y, n.z) = 10°.
    let (sn, cs) = 10f32.to_radians().sin_cos();
    let node = format!(
        "RotationFromNormal(normal: ({:?}, {:?}, {:?}))",
        0.0f32, sn, cs
    );
    close(float_pin(&node, "roll"), 10.0);
    close(float_pin(&node, "pitch").abs(), 0.0);
    let r = match eval(&node, "rotation", ValueType::Quat) {
        Value::Quat(q) => q,
        v => panic!("{v:?}"),
    };
    close_v(r * Vec3::Z, Vec3::new(0.0, sn, cs));
}

#[test]
fn two_bone_ik_on_the_mannequins_left_leg() {
    // Lift the left foot 20 cm straight up; the knee must bend forward (+Y, the pole) with
    // both bone lengths kept. Expected knee from the law of cosines on the rest lengths:
    // along the hip→target line a = (l1² − l2² + d²)/(2d), forward h = √(l1² − a²).
    let text = "Graph(version: 1, name: \"ik\", \
        variables: { \"Knee\": (type: Vec3), \"Foot\": (type: Vec3), \"Reached\": (type: Bool) }, \
        nodes: { \
            \"rest\": GetTransform(bone: bone(\"foot_l\"), initial: true), \
            \"parts\": BreakTransform(value: \"rest\"), \
            \"up\": Add(a: \"parts.translation\", b: (0.0, 0.0, 20.0)), \
            \"target\": MakeTransform(translation: \"up\", rotation: \"parts.rotation\"), \
            \"knee\": GetTransform(bone: bone(\"calf_l\")), \"knee_p\": BreakTransform(value: \"knee\"), \
            \"foot\": GetTransform(bone: bone(\"foot_l\")), \"foot_p\": BreakTransform(value: \"foot\"), \
        }, \
        events: { forward: [ \
            TwoBoneIK(id: \"ik\", bone_a: bone(\"thigh_l\"), bone_b: bone(\"calf_l\"), effector: bone(\"foot_l\"), \
                      target: \"target\", primary_axis: (-1.0, 0.0, 0.0), secondary_axis: (0.0, 1.0, 0.0), pole: (0.0, 1.0, 0.0)), \
            Set(\"Knee\", \"knee_p.translation\"), Set(\"Foot\", \"foot_p.translation\"), Set(\"Reached\", \"ik.reached\"), \
        ] })";
    let program = Arc::new(
        strider_compiler::compile_str(Path::new("ik.ron"), text)
            .unwrap_or_else(|d| panic!("{d:?}")),
    );
    let s = skeleton();
    let mut i = Instance::new(program.clone(), s.clone()).unwrap();
    i.run_forward(&FrameInput::default(), &EmptyWorld, false);
    let get = |n: &str| i.variable(program.variable_id(n).unwrap());
    let p = |n: &str| s.rest_global(s.find(n).unwrap()).translation;
    let (hip, knee0, ankle0) = (p("thigh_l"), p("calf_l"), p("foot_l"));
    let (l1, l2) = (hip.distance(knee0), knee0.distance(ankle0));
    let target = ankle0 + Vec3::new(0.0, 0.0, 20.0);
    let d = hip.distance(target);
    let down = (target - hip) / d;
    let a = (l1 * l1 - l2 * l2 + d * d) / (2.0 * d);
    let h = (l1 * l1 - a * a).sqrt();
    // Forward, made perpendicular to the hip→target line.
    let forward = (Vec3::Y - down * Vec3::Y.dot(down)).normalize();
    let expected_knee = hip + down * a + forward * h;
    assert_eq!(get("Reached"), Value::Bool(true));
    let Value::Vec3(foot) = get("Foot") else {
        panic!()
    };
    let Value::Vec3(knee) = get("Knee") else {
        panic!()
    };
    close_v(foot, target);
    assert!(
        (knee - expected_knee).length() < 1e-3,
        "{knee} vs {expected_knee}"
    );
    assert!((knee.distance(hip) - l1).abs() < 1e-3 && (knee.distance(foot) - l2).abs() < 1e-3);
}

#[test]
fn hierarchy_and_host() {
    // The mannequin's pelvis rests at z = 95 (skeleton file).
    close_v(
        transform("GetTransform(bone: bone(\"pelvis\"), initial: true)").translation,
        Vec3::new(0.0, 0.0, 95.0),
    );
    close_v(
        transform("GetTransform(bone: bone(\"pelvis\"), space: Local)").translation,
        Vec3::new(0.0, 0.0, 95.0),
    );
    assert_eq!(transform("GetTransform(bone: None)"), Transform::IDENTITY);
    close(float("DeltaTime()"), 1.0 / 60.0);
    let to_world = Transform::from_translation(Vec3::new(100.0, 0.0, 0.0));
    let w = eval_with(
        "WorldTransform()",
        "",
        ValueType::Transform,
        0.1,
        &EmptyWorld,
        to_world,
    );
    assert_eq!(w, Value::Transform(to_world));
}

#[test]
fn traces() {
    // The rig stands 20 cm above a world floor at z = 0: rig z = -20 is the floor.
    let to_world = Transform::from_translation(Vec3::new(0.0, 0.0, 20.0));
    let hit = |pin: &str, ty| {
        eval_with(
            "LineTrace(start: (0.0, 0.0, 50.0), end: (0.0, 0.0, -50.0))",
            pin,
            ty,
            0.1,
            &Floor,
            to_world,
        )
    };
    assert_eq!(hit("hit", ValueType::Bool), Value::Bool(true));
    assert_eq!(
        hit("point", ValueType::Vec3),
        Value::Vec3(Vec3::new(0.0, 0.0, -20.0))
    );
    assert_eq!(hit("normal", ValueType::Vec3), Value::Vec3(Vec3::Z));
    assert_eq!(hit("distance", ValueType::Float), Value::Float(70.0));
    // A sphere of radius 5 stops with its centre 5 cm above the floor: it travelled 65 cm.
    let s = eval_with(
        "SphereTrace(start: (0.0, 0.0, 50.0), end: (0.0, 0.0, -50.0), radius: 5.0)",
        "distance",
        ValueType::Float,
        0.1,
        &Floor,
        to_world,
    );
    assert_eq!(s, Value::Float(65.0));
    // Missing: hit false, point = end, distance = full length.
    let miss = |pin: &str, ty| {
        eval_with(
            "LineTrace(start: (0.0, 0.0, 50.0), end: (0.0, 0.0, 10.0))",
            pin,
            ty,
            0.1,
            &Floor,
            to_world,
        )
    };
    assert_eq!(miss("hit", ValueType::Bool), Value::Bool(false));
    assert_eq!(
        miss("point", ValueType::Vec3),
        Value::Vec3(Vec3::new(0.0, 0.0, 10.0))
    );
    assert_eq!(miss("distance", ValueType::Float), Value::Float(40.0));
}

#[test]
fn malformed_quaternion_literals_are_reported_as_such() {
    let text = "Graph(version: 1, name: \"t\", variables: { \"Out\": (type: Quat) }, nodes: { \"n\": Unit(value: (0.0, 0.0, 0.0, 2.0)) }, events: { forward: [ Set(\"Out\", \"n\") ] })";
    let errors = strider_compiler::compile_str(Path::new("q.ron"), text).unwrap_err();
    assert_eq!(errors.len(), 1);
    assert_eq!(
        errors[0].message,
        "invalid value for pin `value` of Unit: quaternion (x, y, z, w) has length 2, not 1; write a unit quaternion or euler(x, y, z) in degrees"
    );
}

#[test]
fn arrays() {
    let run = |steps: &str| -> Vec<Value> {
        let text = format!(
            "Graph(version: 1, name: \"t\", variables: {{ \"A\": (type: FloatArray, default: [1.0, 2.0, 3.0]), \"N\": (type: Int), \"X\": (type: Float) }}, \
             nodes: {{ \"count\": Count(array: var(\"A\")), \"at\": At(array: var(\"A\"), index: 1) }}, events: {{ forward: [ {steps} ] }})"
        );
        let program = Arc::new(
            strider_compiler::compile_str(Path::new("a.ron"), &text)
                .unwrap_or_else(|d| panic!("{d:?}")),
        );
        let mut i = Instance::new(program.clone(), skeleton()).unwrap();
        i.run_forward(&FrameInput::default(), &EmptyWorld, false);
        ["A", "N", "X"]
            .iter()
            .map(|v| i.variable(program.variable_id(v).unwrap()))
            .collect()
    };
    let f = |xs: &[f32]| {
        Value::Array(
            strider_nodes::Elem::Float,
            xs.iter().map(|&x| Value::Float(x)).collect(),
        )
    };
    // SetAt overwrites element 1; Count is 3; At reads the new value.
    let out = run(
        "SetAt(array: var(\"A\"), index: 1, value: 9.0), Set(\"N\", \"count\"), Set(\"X\", \"at\")",
    );
    assert_eq!(
        out,
        vec![f(&[1.0, 9.0, 3.0]), Value::Int(3), Value::Float(9.0)]
    );
    // Out of range: SetAt does nothing, At gives 0.
    let out = run(
        "SetAt(array: var(\"A\"), index: 7, value: 9.0), Reset(array: var(\"A\")), Set(\"X\", \"at\")",
    );
    assert_eq!(out, vec![f(&[]), Value::Int(0), Value::Float(0.0)]);
    let out = run("Append(array: var(\"A\"), value: 4), Set(\"N\", \"count\")");
    assert_eq!(
        out,
        vec![f(&[1.0, 2.0, 3.0, 4.0]), Value::Int(4), Value::Float(0.0)]
    );
}

#[test]
fn debug_drawing() {
    let text = "Graph(version: 1, name: \"d\", events: { forward: [ \
        DrawArrow(start: (0.0, 0.0, 0.0), end: (0.0, 10.0, 0.0)), \
        DrawSphere(center: (1.0, 2.0, 3.0), radius: 4.0, color: (1.0, 0.0, 0.0)), \
        DrawBox(transform: (translation: (0.0, 0.0, 1.0)), half_extents: (1.0, 2.0, 3.0)) ] })";
    let program = Arc::new(strider_compiler::compile_str(Path::new("d.ron"), text).unwrap());
    let mut i = Instance::new(program, skeleton()).unwrap();
    i.run_forward(&FrameInput::default(), &EmptyWorld, true);
    use strider_core::{DebugColor, DebugPrimitive as P};
    assert_eq!(
        i.debug_draw().primitives(),
        &[
            P::Arrow {
                start: Vec3::ZERO,
                end: Vec3::new(0.0, 10.0, 0.0),
                thickness: 0.5,
                color: DebugColor([1.0, 1.0, 0.0, 1.0])
            },
            P::Sphere {
                center: Vec3::new(1.0, 2.0, 3.0),
                radius: 4.0,
                color: DebugColor::RED
            },
            P::Box {
                transform: Transform::from_translation(Vec3::Z),
                half_extents: Vec3::new(1.0, 2.0, 3.0),
                color: DebugColor::WHITE
            },
        ]
    );
    i.run_forward(&FrameInput::default(), &EmptyWorld, false);
    assert!(i.debug_draw().primitives().is_empty());
}

#[test]
fn every_node_is_exercised_somewhere() {
    let mut corpus = std::fs::read_to_string("tests/nodes.rs").unwrap();
    for dir in ["graphs", "graphs/examples", "tests"] {
        for e in std::fs::read_dir(dir).unwrap().flatten() {
            let p = e.path();
            if p.extension().is_some_and(|x| x == "ron" || x == "rs") {
                corpus.push_str(&std::fs::read_to_string(&p).unwrap());
            }
        }
    }
    let missing: Vec<&str> = strider_nodes::registry()
        .nodes()
        .iter()
        .map(|n| n.name)
        .filter(|name| !corpus.contains(&format!("{name}(")))
        .collect();
    assert!(
        missing.is_empty(),
        "nodes never used from RON in tests or graphs: {missing:?}"
    );
}

#[test]
fn every_public_kernel_has_a_benchmark() {
    // benches/kernels.rs times every kernel of strider_nodes::kernels (docs/performance.md).
    let bench = std::fs::read_to_string("benches/kernels.rs").expect("benches/kernels.rs");
    let mut missing = Vec::new();
    // The kernels' sources, and those of their submodules (`two_bone_ik/lanes.rs`).
    let mut sources = Vec::new();
    let mut dirs = vec![std::path::PathBuf::from("crates/strider-nodes/src/kernels")];
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(&dir).expect("kernels dir") {
            let path = entry.expect("entry").path();
            if path.is_dir() {
                dirs.push(path);
            } else {
                sources.push(path);
            }
        }
    }
    for path in sources {
        let text = std::fs::read_to_string(&path).expect("kernel source");
        for line in text.lines() {
            let Some(rest) = line.strip_prefix("pub fn ") else {
                continue;
            };
            let name: String = rest
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            let used = bench.match_indices(name.as_str()).any(|(i, _)| {
                let before = bench[..i].chars().next_back();
                let after = bench[i + name.len()..].chars().next();
                let word = |c: Option<char>| c.is_some_and(|c| c.is_alphanumeric() || c == '_');
                !word(before) && !word(after)
            });
            if !used {
                missing.push(format!("{} ({})", name, path.display()));
            }
        }
    }
    assert!(
        missing.is_empty(),
        "kernels without a benchmark: {missing:?}"
    );
}
