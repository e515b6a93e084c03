//! Node kernels, called directly (no VM): one group per kernel family of
//! `strider_nodes::kernels` — scalar/vector math, hierarchy searches, transforms (rotate
//! around point, aim), quaternion ops, splines, two-bone IK and the locomotion units,
//! smoothing. Every public kernel has an entry (a test in `tests/nodes.rs` keeps it so).
//!
//! Inputs are realistic rig values (cm, degrees, a 60 Hz frame) passed through
//! `black_box`, so nothing is constant-folded. Times are per call.
//!
//! Run: `cargo bench --bench kernels` (see docs/performance.md; add `-- --quick` for a
//! short run).

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::path::Path;
use std::sync::Arc;
use strider::core::{Pose, Quat, Skeleton, Transform, Vec3};
use strider::nodes::kernels::{self as k, locomotion as loco, parts, spline, two_bone_ik};

/// One 60 Hz frame, seconds.
const DT: f32 = 1.0 / 60.0;

fn mannequin() -> Arc<Skeleton> {
    strider::graph::load_skeleton(Path::new("graphs/skeletons/mannequin.ron"))
        .expect("graphs/skeletons/mannequin.ron loads")
        .skeleton
}

/// Scalar and vector math kernels with fallbacks (division, trigonometry in degrees,
/// remap, smooth step, clamps).
fn math(c: &mut Criterion) {
    let mut g = c.benchmark_group("math");
    let (a, b) = (black_box(37.5_f32), black_box(-12.25_f32));
    let v = black_box(Vec3::new(12.0, -30.0, 4.5));
    g.bench_function("div_f", |x| x.iter(|| k::div_f(black_box(a), black_box(b))));
    g.bench_function("sin_deg", |x| x.iter(|| k::sin_deg(black_box(a))));
    g.bench_function("atan2_deg", |x| {
        x.iter(|| k::atan2_deg(black_box(a), black_box(b)))
    });
    g.bench_function("remap", |x| {
        x.iter(|| k::remap(black_box(a), 0.0, 100.0, -1.0, 1.0, true))
    });
    g.bench_function("smooth_step", |x| {
        x.iter(|| k::smooth_step(black_box(a), 20.0, 60.0))
    });
    g.bench_function("unit_v", |x| x.iter(|| k::unit_v(black_box(v))));
    g.bench_function("clamp_length", |x| {
        x.iter(|| k::clamp_length(black_box(v), 5.0, 20.0))
    });
    g.bench_function("clamp_spatially", |x| {
        x.iter(|| k::clamp_spatially(black_box(v), Vec3::ZERO, 5.0, 20.0))
    });
    let (i, j) = (black_box(37_i32), black_box(-5_i32));
    g.bench_function("div_i", |x| x.iter(|| k::div_i(black_box(i), black_box(j))));
    g.bench_function("div_v", |x| {
        x.iter(|| k::div_v(black_box(v), black_box(Vec3::new(2.0, 0.0, -4.0))))
    });
    g.bench_function("mod_f", |x| x.iter(|| k::mod_f(black_box(a), black_box(b))));
    g.bench_function("mod_i", |x| x.iter(|| k::mod_i(black_box(i), black_box(j))));
    g.bench_function("fract", |x| x.iter(|| k::fract(black_box(b))));
    g.bench_function("clamp_f", |x| {
        x.iter(|| k::clamp_f(black_box(a), black_box(b), 20.0))
    });
    g.bench_function("cos_deg", |x| x.iter(|| k::cos_deg(black_box(a))));
    g.bench_function("tan_deg", |x| x.iter(|| k::tan_deg(black_box(a))));
    g.bench_function("sqrt", |x| x.iter(|| k::sqrt(black_box(a))));
    g.bench_function("to_int", |x| x.iter(|| k::to_int(black_box(b))));
    g.bench_function("euler_order", |x| x.iter(|| k::euler_order(black_box(1))));
    g.finish();
}

/// Hierarchy kernels: bone searches by name under a root.
fn hierarchy(c: &mut Criterion) {
    let mut g = c.benchmark_group("hierarchy");
    let skeleton = mannequin();
    let mut out = Vec::with_capacity(skeleton.len());
    g.bench_function("find_bones", |x| {
        x.iter(|| {
            k::find_bones(
                black_box(&skeleton),
                strider::core::BoneIndex(0),
                black_box("foot"),
                black_box("ik"),
                &mut out,
            );
            out.len()
        })
    });
    g.finish();
}

/// Transform kernels: rotate around a pivot, aim an axis, blend.
fn transforms(c: &mut Criterion) {
    let mut g = c.benchmark_group("transform");
    let foot = black_box(Transform::new(
        Vec3::new(9.5, 2.0, 8.0),
        Quat::from_rotation_z(0.3),
        Vec3::ONE,
    ));
    let pivot = black_box(Vec3::new(9.5, 15.0, 0.0));
    let roll = black_box(Quat::from_rotation_x(0.2));
    g.bench_function("rotate_around_point", |x| {
        x.iter(|| k::rotate_around_point(black_box(foot), black_box(pivot), black_box(roll)))
    });
    g.bench_function("aim", |x| {
        x.iter(|| {
            k::aim(
                black_box(foot),
                Vec3::Y,
                black_box(Vec3::new(0.2, 1.0, -0.1)),
                0.8,
            )
        })
    });
    let target = black_box(Transform::from_translation(Vec3::new(9.5, 4.0, 6.0)));
    g.bench_function("blend_transform", |x| {
        x.iter(|| k::blend_transform(black_box(foot), black_box(target), 0.5))
    });
    g.finish();
}

/// Quaternion kernels.
fn quats(c: &mut Criterion) {
    let mut g = c.benchmark_group("quat");
    let (qa, qb) = (
        black_box(Quat::from_rotation_z(0.4)),
        black_box(Quat::from_rotation_x(-0.7)),
    );
    let axis = black_box(Vec3::new(0.0, 0.6, 0.8));
    g.bench_function("quat_from_axis_angle", |x| {
        x.iter(|| k::quat_from_axis_angle(black_box(axis), black_box(35.0)))
    });
    g.bench_function("slerp", |x| {
        x.iter(|| k::slerp(black_box(qa), black_box(qb), 0.3))
    });
    g.bench_function("quat_scale", |x| {
        x.iter(|| k::quat_scale(black_box(qa), 0.5))
    });
    g.bench_function("find_quat_between", |x| {
        x.iter(|| k::find_quat_between(black_box(Vec3::Z), black_box(axis)))
    });
    g.bench_function("unit_q_mul", |x| {
        x.iter(|| k::unit_q(black_box(qa) * black_box(qb)))
    });
    g.bench_function("rotate_vector", |x| {
        x.iter(|| k::rotate_vector(black_box(qa), black_box(axis)))
    });
    // The same math on plain components (what the crowd path runs lane by lane).
    let (pa, pb, pv) = (qa.to_array(), qb.to_array(), axis.to_array());
    g.bench_function("unit_parts", |x| {
        x.iter(|| parts::unit_parts(black_box(pa)))
    });
    g.bench_function("normalize_parts", |x| {
        x.iter(|| parts::normalize_parts(black_box(pa)))
    });
    g.bench_function("mul_parts", |x| {
        x.iter(|| parts::mul_parts(black_box(pa), black_box(pb)))
    });
    g.bench_function("rotate_parts", |x| {
        x.iter(|| parts::rotate_parts(black_box(pa), black_box(pv)))
    });
    g.finish();
}

/// Spline evaluation over 6 control points (a foot's swing arc).
fn splines(c: &mut Criterion) {
    let mut g = c.benchmark_group("spline");
    let points: Vec<Vec3> = (0..6)
        .map(|i| {
            let t = i as f32 / 5.0;
            Vec3::new(
                9.5,
                -20.0 + 40.0 * t,
                12.0 * (t * std::f32::consts::PI).sin(),
            )
        })
        .collect();
    let points = black_box(points);
    for (name, mode) in [
        ("bspline", spline::SplineMode::BSpline),
        ("catmull_rom", spline::SplineMode::CatmullRom),
    ] {
        g.bench_function(name, |x| {
            x.iter(|| spline::evaluate(&points, black_box(0.37), mode))
        });
    }
    g.finish();
}

/// Two-bone IK: the pure position solve, and the full solve writing a mannequin leg.
fn ik(c: &mut Criterion) {
    let mut g = c.benchmark_group("two_bone_ik");
    let (hip, knee, ankle) = (
        Vec3::new(9.5, 0.0, 92.0),
        Vec3::new(9.5, 1.0, 50.0),
        Vec3::new(9.5, 0.0, 13.5),
    );
    let goal = black_box(Vec3::new(9.5, 10.0, 20.0));
    g.bench_function("stretch_scale", |x| {
        x.iter(|| two_bone_ik::stretch_scale(black_box(Some((0.9, 1.1))), black_box(0.97)))
    });
    g.bench_function("solve_positions", |x| {
        x.iter(|| {
            two_bone_ik::solve_positions(
                black_box(hip),
                black_box(knee),
                black_box(ankle),
                black_box(goal),
                Vec3::Y,
                None,
            )
        })
    });
    let skeleton = mannequin();
    let bone = |n: &str| skeleton.find(n).expect("mannequin bone");
    let (thigh, calf, foot) = (bone("thigh_l"), bone("calf_l"), bone("foot_l"));
    let mut pose = Pose::new(Arc::clone(&skeleton));
    let ik = two_bone_ik::TwoBoneIk {
        primary_axis: Vec3::NEG_X,
        secondary_axis: Vec3::Y,
        pole: two_bone_ik::Pole::Location(Vec3::new(9.5, 60.0, 50.0)),
        weight: 1.0,
        stretch: None,
        set_effector_rotation: false,
    };
    let target = Transform::from_translation(Vec3::new(9.5, 10.0, 20.0));
    // From the rest pose every time, so each iteration solves the same problem; the reset
    // is included in the time (it is part of every frame too).
    g.bench_function("solve_on_mannequin_leg", |x| {
        x.iter(|| {
            pose.reset_to_rest();
            ik.solve(&mut pose, thigh, calf, foot, black_box(target))
        })
    });
    g.finish();
}

/// The locomotion units of `kernels::locomotion`.
fn locomotion(c: &mut Criterion) {
    let mut g = c.benchmark_group("locomotion");
    g.bench_function("clavicle_offset", |x| {
        x.iter(|| loco::clavicle_offset(black_box(0.3), black_box(150.0), 400.0, 2.0))
    });
    g.bench_function("cycle_length", |x| {
        x.iter(|| loco::cycle_length(black_box(150.0), 0.25, 60.0, 100.0))
    });
    g.bench_function("foot_offset_from_trace", |x| {
        x.iter(|| loco::foot_offset_from_trace(black_box(true), black_box(47.0), 50.0))
    });
    g.bench_function("pelvis_side_lean", |x| {
        x.iter(|| loco::pelvis_side_lean(black_box(6.0), 20.0, 8.0))
    });
    g.bench_function("per_foot_rotation_factor", |x| {
        x.iter(|| loco::per_foot_rotation_factor(black_box(-40.0), 0.5, 0.8))
    });
    g.bench_function("rotation_from_normal", |x| {
        x.iter(|| loco::rotation_from_normal(black_box(Vec3::new(0.1, -0.2, 0.97))))
    });
    let velocity = black_box(Vec3::new(20.0, 180.0, 0.0));
    let facing = black_box(Quat::from_rotation_z(0.3));
    g.bench_function("movement_angle_offset", |x| {
        x.iter(|| {
            loco::get_movement_angle_offset(
                black_box(velocity),
                black_box(10.0),
                black_box(0.4),
                DT,
                6.0,
                12.0,
                135.0,
                100.0,
                0.1,
            )
        })
    });
    g.bench_function("foot_avoidance", |x| {
        x.iter(|| {
            loco::foot_avoidance(
                black_box(Vec3::new(4.0, 20.0, 0.0)),
                black_box(Vec3::new(-3.0, -10.0, 0.0)),
                black_box(15.0),
                true,
                12.0,
            )
        })
    });
    g.bench_function("knee_vector", |x| {
        x.iter(|| loco::knee_vector(black_box(facing), black_box(facing), Vec3::Y, 0.5, 1.0))
    });
    g.bench_function("foot_pivots", |x| {
        x.iter(|| {
            loco::foot_pivots(
                black_box(Vec3::new(9.5, 0.0, 13.5)),
                black_box(Vec3::new(9.5, 15.0, 3.0)),
                8.0,
                3.0,
                10.0,
                6.0,
            )
        })
    });
    g.bench_function("cycle_step", |x| {
        x.iter(|| loco::cycle_step(black_box(0.37), DT, 1.1, 0.5, true))
    });
    g.bench_function("arm_swing_pitch", |x| {
        x.iter(|| {
            loco::arm_swing_pitch(
                black_box(0.37),
                black_box(velocity),
                black_box(facing),
                0.25,
                1.0,
                -1.0,
                1.0,
                400.0,
                35.0,
                10.0,
                0.5,
                -1.0,
                1.0,
            )
        })
    });
    g.bench_function("pelvis_lean", |x| {
        x.iter(|| loco::pelvis_lean(black_box(velocity), 400.0, 8.0, 5.0))
    });
    g.bench_function("limit_rotation_around_z", |x| {
        x.iter(|| loco::limit_rotation_around_z(black_box(facing), 0.0, 30.0))
    });
    g.bench_function("rotation_from_normal_quat", |x| {
        x.iter(|| loco::rotation_from_normal_quat(black_box(Vec3::new(0.1, 0.2, 0.97))))
    });
    g.finish();
}

/// Frame-rate-independent smoothing: exponential lerps, interp-to, springs.
fn smoothing(c: &mut Criterion) {
    let mut g = c.benchmark_group("smoothing");
    let (cur, tgt) = (
        black_box(Vec3::new(9.5, 2.0, 8.0)),
        black_box(Vec3::new(9.5, 6.0, 3.0)),
    );
    let (qa, qb) = (
        black_box(Quat::from_rotation_z(0.4)),
        black_box(Quat::from_rotation_x(-0.7)),
    );
    g.bench_function("lerp_exponential", |x| {
        x.iter(|| loco::lerp_exponential(black_box(3.0), black_box(8.0), DT, 10.0))
    });
    g.bench_function("lerp_exponential_v", |x| {
        x.iter(|| loco::lerp_exponential_v(black_box(cur), black_box(tgt), DT, 10.0))
    });
    g.bench_function("lerp_exponential_q", |x| {
        x.iter(|| loco::lerp_exponential_q(black_box(qa), black_box(qb), DT, 10.0))
    });
    g.bench_function("exp_alpha", |x| {
        x.iter(|| loco::exp_alpha(black_box(10.0), black_box(DT)))
    });
    g.bench_function("lerp_by_weight", |x| {
        x.iter(|| loco::lerp_by_weight(black_box(3.0), black_box(8.0), black_box(0.15)))
    });
    g.bench_function("lerp_by_weight_v", |x| {
        x.iter(|| loco::lerp_by_weight_v(black_box(cur), black_box(tgt), black_box(0.15)))
    });
    g.bench_function("slerp_by_weight", |x| {
        x.iter(|| loco::slerp_by_weight(black_box(qa), black_box(qb), black_box(0.15)))
    });
    g.bench_function("lerp_max_step", |x| {
        x.iter(|| loco::lerp_max_step(black_box(cur), black_box(tgt), DT, 10.0, 50.0))
    });
    g.bench_function("vinterp_to", |x| {
        x.iter(|| loco::vinterp_to(black_box(cur), black_box(tgt), DT, 10.0))
    });
    g.bench_function("qinterp_to", |x| {
        x.iter(|| loco::qinterp_to(black_box(qa), black_box(qb), DT, 10.0))
    });
    g.bench_function("finterp_to", |x| {
        x.iter(|| loco::finterp_to(black_box(3.0), black_box(8.0), DT, 10.0))
    });
    g.bench_function("spring_damper", |x| {
        x.iter(|| loco::spring_damper(black_box(3.0), 0.0, black_box(8.0), 0.1, DT))
    });
    g.bench_function("spring_damper_v", |x| {
        x.iter(|| loco::spring_damper_v(black_box(cur), Vec3::ZERO, black_box(tgt), 0.1, DT))
    });
    g.finish();
}

criterion_group!(
    benches, math, hierarchy, transforms, quats, splines, ik, locomotion, smoothing
);
criterion_main!(benches);
