//! Tests of the report on hand-made recordings. Every expected value is derived by hand in
//! the comments from the synthetic geometry below.

use super::*;
use glam::Quat;
use std::sync::Arc;
use strider_core::{Bone, Skeleton};
use strider_graph::skeleton_file::ContactPoint;

/// A tiny biped with identity rotations everywhere (rig axes = bone axes):
///
/// ```text
/// bone      parent    local            rest global
/// root      —         (0, 0, 0)        (0, 0, 0)
/// pelvis    root      (0, 0, 90)       (0, 0, 90)
/// thigh_l   pelvis    (10, 0, 0)       (10, 0, 90)      hip
/// calf_l    thigh_l   (0, 3, -40)      (10, 3, 50)      knee, 3 cm forward
/// foot_l    calf_l    (0, -3, -40)     (10, 0, 10)      ankle
/// ball_l    foot_l    (0, 15, -10)     (10, 15, 0)
/// thigh_r … ball_r: mirrored (x = −10)
/// head      pelvis    (0, 0, 70)       (0, 0, 160)
/// ```
/// Contacts on each foot: heel (0, −5, −10) and ball (0, 15, −10), so at rest the heel is
/// at (±10, −5, 0) and the ball at (±10, 15, 0): on the ground, 20 cm apart.
/// Rest bone lengths: √(3² + 40²) = 40.112 cm each, reach 80.225 cm; rest hip → foot 80 cm.
fn tiny() -> SkeletonFile {
    let b = |name: &str, parent: Option<&str>, t: (f32, f32, f32)| Bone {
        name: name.into(),
        parent: parent.map(Into::into),
        rest_local: Transform::from_translation(Vec3::new(t.0, t.1, t.2)),
    };
    let bones = vec![
        b("root", None, (0.0, 0.0, 0.0)),
        b("pelvis", Some("root"), (0.0, 0.0, 90.0)),
        b("thigh_l", Some("pelvis"), (10.0, 0.0, 0.0)),
        b("calf_l", Some("thigh_l"), (0.0, 3.0, -40.0)),
        b("foot_l", Some("calf_l"), (0.0, -3.0, -40.0)),
        b("ball_l", Some("foot_l"), (0.0, 15.0, -10.0)),
        b("thigh_r", Some("pelvis"), (-10.0, 0.0, 0.0)),
        b("calf_r", Some("thigh_r"), (0.0, 3.0, -40.0)),
        b("foot_r", Some("calf_r"), (0.0, -3.0, -40.0)),
        b("ball_r", Some("foot_r"), (0.0, 15.0, -10.0)),
        b("head", Some("pelvis"), (0.0, 0.0, 70.0)),
    ];
    let c = |name: &str, bone: &str, o: (f32, f32, f32)| ContactPoint {
        name: name.into(),
        bone: bone.into(),
        offset: Vec3::new(o.0, o.1, o.2),
    };
    SkeletonFile {
        name: "tiny".into(),
        skeleton: Arc::new(Skeleton::new(bones).expect("valid skeleton")),
        contacts: vec![
            c("heel_l", "foot_l", (0.0, -5.0, -10.0)),
            c("ball_l", "foot_l", (0.0, 15.0, -10.0)),
            c("heel_r", "foot_r", (0.0, -5.0, -10.0)),
            c("ball_r", "foot_r", (0.0, 15.0, -10.0)),
        ],
    }
}

struct Fixture {
    file: SkeletonFile,
    rig: ReportRig,
}

impl Fixture {
    fn new() -> Self {
        let file = tiny();
        let rig = ReportRig::from_skeleton(&file).expect("rig");
        Self { file, rig }
    }

    fn bone(&self, name: &str) -> usize {
        self.file.skeleton.find(name).expect("bone").get()
    }

    /// `n` rest-pose frames at `hz`: frame k at time k / hz, dt = 1 / hz, identity
    /// component-to-world, moving (not standing still).
    fn frames(&self, n: usize, hz: u32) -> Vec<FrameRecord> {
        (0..n)
            .map(|k| FrameRecord {
                time: k as f64 / f64::from(hz),
                dt: 1.0 / hz as f32,
                component_to_world: Transform::IDENTITY,
                standing_still: false,
                teleported: false,
                globals: self.file.skeleton.rest_globals().to_vec(),
            })
            .collect()
    }

    /// Moves one bone's global translation (only that bone: globals are independent).
    fn shift(&self, f: &mut FrameRecord, bone: &str, d: Vec3) {
        let i = self.bone(bone);
        f.globals[i].translation += d;
    }

    fn set(&self, f: &mut FrameRecord, bone: &str, t: Transform) {
        let i = self.bone(bone);
        f.globals[i] = t;
    }

    fn rest(&self, bone: &str) -> Transform {
        self.file.skeleton.rest_globals()[self.bone(bone)]
    }
}

fn near(a: f32, b: f32, tol: f32) -> bool {
    (a - b).abs() <= tol
}

const UP: Vec3 = Vec3::new(0.0, 0.0, 10.0);

#[test]
fn rig_finds_legs_sides_and_rest_lengths() {
    let fx = Fixture::new();
    let r = &fx.rig;
    assert_eq!(r.legs.len(), 2);
    assert_eq!(r.legs[0].name, "foot_l");
    assert_eq!(r.legs[0].side, Side::Left);
    assert_eq!(r.legs[1].side, Side::Right);
    assert_eq!(
        (r.legs[0].hip, r.legs[0].knee, r.legs[0].foot),
        (fx.bone("thigh_l"), fx.bone("calf_l"), fx.bone("foot_l"))
    );
    assert_eq!(r.legs[0].contacts.len(), 2);
    // √(3² + 40²) = √1609 = 40.1123
    assert!(near(r.legs[0].upper_length, 1609f32.sqrt(), 1e-4));
    assert!(near(r.legs[0].lower_length, 1609f32.sqrt(), 1e-4));
    assert_eq!(r.pelvis, fx.bone("pelvis"));
    assert_eq!(r.root, 0);
}

#[test]
fn rig_errors_instead_of_panicking() {
    let mut f = tiny();
    f.contacts.clear();
    assert!(matches!(
        ReportRig::from_skeleton(&f),
        Err(ReportError::NoContacts(_))
    ));
    for bone in ["root", "pelvis"] {
        let mut f = tiny();
        f.contacts[0].bone = bone.into();
        assert_eq!(
            ReportRig::from_skeleton(&f),
            Err(ReportError::ChainTooShort { foot: bone.into() })
        );
    }
    let mut f = tiny();
    f.contacts[0].bone = "fot_l".into();
    assert!(matches!(
        ReportRig::from_skeleton(&f),
        Err(ReportError::UnknownContactBone { .. })
    ));
}

#[test]
fn rest_pose_on_the_mannequin_is_clean() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../graphs/skeletons/mannequin.ron"
    );
    let file = strider_graph::load_skeleton(std::path::Path::new(path)).expect("mannequin");
    let rig = ReportRig::from_skeleton(&file).expect("rig");
    let name = |i: usize| rig.bone_names[i].as_str();
    assert_eq!(rig.legs.len(), 2);
    let (l, r) = (&rig.legs[0], &rig.legs[1]);
    assert_eq!(
        (name(l.foot), name(l.knee), name(l.hip), l.side),
        ("foot_l", "calf_l", "thigh_l", Side::Left)
    );
    assert_eq!(
        (name(r.foot), name(r.knee), name(r.hip), r.side),
        ("foot_r", "calf_r", "thigh_r", Side::Right)
    );
    assert_eq!(name(rig.pelvis), "pelvis");
    let frames: Vec<FrameRecord> = (0..30)
        .map(|k| FrameRecord {
            time: f64::from(k) / 60.0,
            dt: 1.0 / 60.0,
            component_to_world: Transform::from_translation(Vec3::new(100.0, -50.0, 0.0)),
            standing_still: true,
            teleported: false,
            globals: file.skeleton.rest_globals().to_vec(),
        })
        .collect();
    let rep = analyse(&rig, &frames, &FlatGround(0.0));
    // The rest pose stands flat: both feet planted for the whole recording, knees 1.5 cm
    // forward (not backward, not at full reach), feet apart.
    assert_eq!(plant_spans(&rig, &frames, &FlatGround(0.0)).len(), 2);
    assert_eq!(rep.crossing_frames, 0);
    assert_eq!(rep.knee_backward_frames, 0);
    assert_eq!(rep.leg_overextension_frames, 0);
    assert_eq!(rep.steps, 0);
    assert!(rep.skate_cm_per_stance_max < 1e-4);
    assert!(rep.penetration_cm_max < 1e-3);
    assert!(rep.pop_cm_per_frame_max < 1e-4);
}

#[test]
fn sliding_stance_skates_by_the_slide() {
    // Left foot planted frames 0..=10 sliding 0.2 cm per frame along x (2.0 cm at frame
    // 10), lifted 10 cm for frames 11..=20, planted again still (x = 2) for 21..=39.
    // The right foot stays planted throughout. Stances: left 2.0, left 0, right 0.
    let fx = Fixture::new();
    let mut frames = fx.frames(40, 60);
    for (k, f) in frames.iter_mut().enumerate() {
        let x = 0.2 * k.min(10) as f32;
        let lift = if (11..=20).contains(&k) {
            UP
        } else {
            Vec3::ZERO
        };
        fx.shift(f, "foot_l", Vec3::new(x, 0.0, 0.0) + lift);
    }
    let spans = plant_spans(&fx.rig, &frames, &FlatGround(0.0));
    let left: Vec<(usize, usize)> = spans
        .iter()
        .filter(|s| s.leg == 0)
        .map(|s| (s.start, s.end))
        .collect();
    assert_eq!(left, [(0, 10), (21, 39)]);
    let rep = analyse(&fx.rig, &frames, &FlatGround(0.0));
    assert!(near(rep.skate_cm_per_stance_max, 2.0, 1e-4), "{rep:?}");
    assert!(
        near(rep.skate_cm_per_stance_mean, 2.0 / 3.0, 1e-4),
        "{rep:?}"
    );
    // The sliding stance is the left foot's first, from frame 0.
    assert_eq!(rep.skate_foot.as_deref(), Some("foot_l"));
    assert_eq!(rep.skate_time_s, Some(frames[0].time));
    assert_eq!(rep.steps, 1);
}

/// The foot's global after pitching it by `deg` about rig X around the world point `pivot`
/// (rest rotation is the identity): translation `p + R (t − p)`, rotation `R`.
fn pitched(rest: Transform, pivot: Vec3, deg: f32) -> Transform {
    let r = Quat::from_rotation_x(deg.to_radians());
    Transform::from_translation_rotation(pivot + r * (rest.translation - pivot), r)
}

#[test]
fn heel_to_ball_roll_is_not_skating() {
    // Left foot: heel strike with the toe up 20°, 10°, 5° about the heel (the ball is then
    // 20·sin θ = 6.8, 3.5, 1.74 cm up: not grounded), flat for frames 3..=7, heel off
    // 5°, 10°, 20° about the ball (the heel 1.74 cm and more up), then lifted.
    // The heel does not move while it is down, nor the ball while it is down: skate 0,
    // although the ankle (foot bone) travels 5 − (5 cos 20° − 10 sin 20°) = 3.72 cm in y.
    let fx = Fixture::new();
    let rest = fx.rest("foot_l");
    let heel = Vec3::new(10.0, -5.0, 0.0);
    let ball = Vec3::new(10.0, 15.0, 0.0);
    let mut frames = fx.frames(16, 60);
    let poses: Vec<Transform> = [20.0, 10.0, 5.0]
        .iter()
        .map(|&d| pitched(rest, heel, d))
        .chain(std::iter::repeat_n(rest, 5))
        .chain([5.0, 10.0, 20.0].iter().map(|&d| pitched(rest, ball, -d)))
        .chain(std::iter::repeat_n(
            Transform::from_translation(rest.translation + UP),
            5,
        ))
        .collect();
    for (f, p) in frames.iter_mut().zip(&poses) {
        fx.set(f, "foot_l", *p);
    }
    let ankle_travel = (poses[0].translation - rest.translation)
        .truncate()
        .length();
    assert!(near(ankle_travel, 3.72, 0.01), "{ankle_travel}");
    let spans = plant_spans(&fx.rig, &frames, &FlatGround(0.0));
    let left = spans.iter().find(|s| s.leg == 0).expect("left stance");
    assert_eq!((left.start, left.end), (0, 10));
    assert!(left.skate_cm < 1e-4, "{left:?}");
    let rep = analyse(&fx.rig, &frames, &FlatGround(0.0));
    assert!(rep.skate_cm_per_stance_max < 1e-4, "{rep:?}");
}

#[test]
fn penetration_is_measured_against_the_ground_in_world_space() {
    // Ground at z = 5 everywhere; the character stands on it (component-to-world lifts
    // it by 5 and yaws it 90°). At frame 3 the left foot is 0.7 cm lower: contacts at
    // z = 4.3, 0.7 below the ground.
    let fx = Fixture::new();
    let mut frames = fx.frames(8, 60);
    for f in &mut frames {
        f.component_to_world = Transform::from_translation_rotation(
            Vec3::new(30.0, 40.0, 5.0),
            Quat::from_rotation_z(90f32.to_radians()),
        );
    }
    fx.shift(&mut frames[3], "foot_l", Vec3::new(0.0, 0.0, -0.7));
    let ground = |_p: Vec3| Some(5.0f32);
    let rep = analyse(&fx.rig, &frames, &ground);
    assert!(near(rep.penetration_cm_max, 0.7, 1e-4), "{rep:?}");
    // No ground at all: nothing is grounded or below.
    let rep = analyse(&fx.rig, &frames, &|_p: Vec3| None::<f32>);
    assert_eq!(rep.penetration_cm_max, 0.0);
    assert_eq!(rep.skate_cm_per_stance_max, 0.0);
}

#[test]
fn idle_float_counts_only_after_a_second_of_standing_still() {
    // 121 frames at 60 Hz (t = 0 … 2 s), standing still throughout.
    let fx = Fixture::new();
    let still = |raised: &dyn Fn(usize) -> bool, still_from: usize| {
        let mut frames = fx.frames(121, 60);
        for (k, f) in frames.iter_mut().enumerate() {
            f.standing_still = k >= still_from;
            if raised(k) {
                fx.shift(f, "foot_l", Vec3::new(0.0, 0.0, 0.8));
            }
        }
        analyse(&fx.rig, &frames, &FlatGround(0.0)).idle_float_cm_max
    };
    // Left foot 0.8 cm up from frame 61 (t = 1.0167 s > 1 s): 0.8.
    assert!(near(still(&|k| k >= 61, 0), 0.8, 1e-4));
    // Up only during frames 0..=60 (t ≤ 1 s, not "more than 1 s"): 0.
    assert_eq!(still(&|k| k <= 60, 0), 0.0);
    // Standing still only from frame 30 (t = 0.5): frames 61..=90 (t ≤ 1.5) are within
    // the first second of stillness: 0; frame 91 (t − 0.5 = 1.0167 s) counts: 0.8.
    assert_eq!(still(&|k| (61..=90).contains(&k), 30), 0.0);
    assert!(near(still(&|k| k == 91, 30), 0.8, 1e-4));
}

#[test]
fn crossed_feet_are_counted_per_frame() {
    // Frames 5..=9: the left foot at rig x = −3, the right at +3 (crossed), with the
    // character yawed 90° in the world (rig space is the facing frame): 5 frames.
    let fx = Fixture::new();
    let mut frames = fx.frames(20, 60);
    for (k, f) in frames.iter_mut().enumerate() {
        f.component_to_world = Transform::from_rotation(Quat::from_rotation_z(1.0));
        if (5..=9).contains(&k) {
            fx.shift(f, "foot_l", Vec3::new(-13.0, 0.0, 0.0));
            fx.shift(f, "foot_r", Vec3::new(13.0, 0.0, 0.0));
        }
    }
    let rep = analyse(&fx.rig, &frames, &FlatGround(0.0));
    assert_eq!(rep.crossing_frames, 5);
}

#[test]
fn backward_knees_are_counted_and_straight_legs_ignored() {
    let fx = Fixture::new();
    let mut frames = fx.frames(10, 60);
    // Frame 4: left knee 3 cm behind the hip → foot line (bend (0, −3, 0), foot forward
    // +Y): backward.
    fx.shift(&mut frames[4], "calf_l", Vec3::new(0.0, -6.0, 0.0));
    // Frame 6: left knee on the line (bend 0 < 0.5 cm): straight, ignored.
    fx.shift(&mut frames[6], "calf_l", Vec3::new(0.0, -3.0, 0.0));
    // Frame 8: right foot turned 180° about Z (it now points −Y) under a knee 3 cm
    // forward (+Y): the knee bends against the foot's current forward: backward.
    let mut foot = fx.rest("foot_r");
    foot.rotation = Quat::from_rotation_z(std::f32::consts::PI);
    fx.set(&mut frames[8], "foot_r", foot);
    // Frame 9: knee 0.4 cm behind the line: straight (|bend| < 0.5), ignored.
    fx.shift(&mut frames[9], "calf_l", Vec3::new(0.0, -3.4, 0.0));
    let rep = analyse(&fx.rig, &frames, &FlatGround(0.0));
    assert_eq!(rep.knee_backward_frames, 2);
}

#[test]
fn planted_legs_at_full_reach_are_counted() {
    // Reach 2·√1609 = 80.2247 cm, threshold 80.1747. Frames 3..=9: left foot 0.2 cm
    // lower (z 9.8, contacts at −0.2: still planted), hip → foot 80.2: at full reach, 7
    // frames. Frames 10..=12: foot lifted 10 cm and hip raised 10.2 cm: also 80.2 apart
    // but not planted, not counted.
    let fx = Fixture::new();
    let mut frames = fx.frames(13, 60);
    for (k, f) in frames.iter_mut().enumerate() {
        if (3..=9).contains(&k) {
            fx.shift(f, "foot_l", Vec3::new(0.0, 0.0, -0.2));
        }
        if k >= 10 {
            fx.shift(f, "foot_l", UP);
            fx.shift(f, "thigh_l", Vec3::new(0.0, 0.0, 10.2));
        }
    }
    let rep = analyse(&fx.rig, &frames, &FlatGround(0.0));
    assert_eq!(rep.leg_overextension_frames, 7);
    assert!(near(rep.penetration_cm_max, 0.2, 1e-4));
}

#[test]
fn pops_are_relative_to_the_root_and_normalised_to_60_hz() {
    // The character walks 2 cm per frame in the world (component-to-world), which moves
    // every bone with the root: no pop. At frame 4 the head jumps 10 cm (rig x) and stays.
    // Frame 6 is a teleport (the world position jumps 500 cm and the head another 30 cm);
    // frame 7 repeats frame 6 with dt = 0 and the head jumps again: both skipped.
    let fx = Fixture::new();
    let run = |hz: u32| {
        let mut frames = fx.frames(8, hz);
        for (k, f) in frames.iter_mut().enumerate() {
            let mut walk = Vec3::new(0.0, 2.0 * k as f32, 0.0);
            if k >= 6 {
                walk.x += 500.0;
            }
            f.component_to_world = Transform::from_translation(walk);
            if k >= 4 {
                fx.shift(f, "head", Vec3::new(10.0, 0.0, 0.0));
            }
            if k >= 6 {
                fx.shift(f, "head", Vec3::new(30.0, 0.0, 0.0));
            }
        }
        frames[6].teleported = true;
        frames[7].dt = 0.0;
        fx.shift(&mut frames[7], "head", Vec3::new(0.0, 0.0, 50.0));
        let rep = analyse(&fx.rig, &frames, &FlatGround(0.0));
        // The worst pop is the head's: at frame 4 (it moves) and at frame 5 (it stops)
        // equally; the first is reported.
        assert_eq!(rep.pop_bone.as_deref(), Some("head"));
        assert_eq!(rep.pop_time_s, Some(frames[4].time));
        rep.pop_cm_per_frame_max
    };
    // 10 cm in a 1/60 s frame: the relative velocity goes 0 → 600 cm/s → 0, a change of
    // 600 cm/s · (1/60)² / (1/60) = 10 cm per 60 Hz frame.
    assert!(near(run(60), 10.0, 1e-3), "{}", run(60));
    // 10 cm in a 1/30 s frame: 300 cm/s · (1/60)² / (1/30) = 2.5.
    assert!(near(run(30), 2.5, 1e-3), "{}", run(30));
}

#[test]
fn smooth_acceleration_scores_the_same_at_every_frame_rate() {
    // The head accelerates along rig x at a = 3600 cm/s² (x = a·t²/2): the second
    // difference of a parabola is exactly a·dt², so the pop is a / 60² = 1 cm per 60 Hz
    // frame at any rate.
    let fx = Fixture::new();
    for hz in [30, 60, 144, 240] {
        let mut frames = fx.frames(20, hz);
        for (k, f) in frames.iter_mut().enumerate() {
            let t = k as f32 / hz as f32;
            fx.shift(f, "head", Vec3::new(0.5 * 3600.0 * t * t, 0.0, 0.0));
        }
        let pop = analyse(&fx.rig, &frames, &FlatGround(0.0)).pop_cm_per_frame_max;
        assert!(near(pop, 1.0, 2e-3), "{hz} Hz: {pop}");
    }
}

#[test]
fn nonfinite_values_are_counted_without_spoiling_the_rest() {
    let fx = Fixture::new();
    let mut frames = fx.frames(10, 60);
    let head = fx.bone("head");
    let foot = fx.bone("foot_l");
    frames[2].globals[head].translation.x = f32::NAN;
    frames[3].globals[foot].rotation.w = f32::NAN;
    frames[5].component_to_world.scale.z = f32::INFINITY;
    // A truncated frame: missing bones are skipped, not indexed.
    frames[7].globals.truncate(3);
    let rep = analyse(&fx.rig, &frames, &FlatGround(0.0));
    assert_eq!(rep.nonfinite_values, 3);
    for v in [
        rep.skate_cm_per_stance_max,
        rep.skate_cm_per_stance_mean,
        rep.penetration_cm_max,
        rep.idle_float_cm_max,
        rep.pop_cm_per_frame_max,
        rep.cadence_steps_per_min,
        rep.mean_step_length_cm,
    ] {
        assert!(v.is_finite(), "{rep:?}");
    }
    assert!(rep.to_json().is_ok());
}

#[test]
fn steps_cadence_and_step_length_on_a_hand_made_walk() {
    // 60 Hz. Right foot: planted 0..=9 (y 0), lifted 10..=19, planted 20..=49 at y = 21,
    // lifted 50..=59, planted from 60 at y = 63. Left foot: planted 0..=29 (y 0), lifted
    // 30..=39, planted from 40 at y = 42. Feet 20 cm apart in x (±10).
    // Plants: L@0, R@0 (initial, not steps), R@20, L@40, R@60: 3 steps.
    // Each step is (20, 21) from the other foot's previous plant: √(400 + 441) = 29 cm.
    // Frames 0..=79 move, 80..=139 stand still: moving time 80/60 s,
    // cadence 3 / (4/3) · 60 = 135 steps/min.
    let fx = Fixture::new();
    let mut frames = fx.frames(140, 60);
    for (k, f) in frames.iter_mut().enumerate() {
        let right = match k {
            0..=9 => Vec3::ZERO,
            10..=19 => Vec3::new(0.0, 10.0, 10.0),
            20..=49 => Vec3::new(0.0, 21.0, 0.0),
            50..=59 => Vec3::new(0.0, 40.0, 10.0),
            _ => Vec3::new(0.0, 63.0, 0.0),
        };
        let left = match k {
            0..=29 => Vec3::ZERO,
            30..=39 => Vec3::new(0.0, 20.0, 10.0),
            _ => Vec3::new(0.0, 42.0, 0.0),
        };
        fx.shift(f, "foot_r", right);
        fx.shift(f, "foot_l", left);
        f.standing_still = k >= 80;
    }
    let rep = analyse(&fx.rig, &frames, &FlatGround(0.0));
    assert_eq!(rep.steps, 3);
    assert!(near(rep.cadence_steps_per_min, 135.0, 0.01), "{rep:?}");
    assert!(near(rep.mean_step_length_cm, 29.0, 1e-3), "{rep:?}");
    // 140 frames from t = 0 to 139/60 s: 60 Hz.
    assert_eq!(rep.frames, 140);
    assert!((rep.duration_s - 139.0 / 60.0).abs() < 1e-9);
    assert!((rep.hz - 60.0).abs() < 1e-6);
}

#[test]
fn framerate_deviation_compares_common_times_only() {
    // 60 Hz and 144 Hz share every 1/12 s. At t = 1/6 (60 Hz frame 10, 144 Hz frame 24)
    // the 144 Hz pelvis is 0.3 cm off. Decoys at times the other run lacks (144 Hz frame
    // 1, 60 Hz frame 3 = 7.2/144) are ignored: 0.3.
    let fx = Fixture::new();
    let mut a = fx.frames(21, 60);
    let mut b = fx.frames(49, 144);
    fx.shift(&mut b[24], "pelvis", Vec3::new(0.3, 0.0, 0.0));
    fx.shift(&mut b[1], "head", Vec3::new(5.0, 0.0, 0.0));
    fx.shift(&mut a[3], "head", Vec3::new(7.0, 0.0, 0.0));
    let d = framerate_deviation(&[(60, &a), (144, &b)]);
    assert!(near(d, 0.3, 1e-5), "{d}");

    // 30/60/144/240 Hz share every 1/6 s. The 240 Hz run is 0.3 cm off at t = 1/6
    // (frame 40); decoys at 240 Hz frame 8 (1/30 s) and 30 Hz frame 1 (1/30 s, not a
    // multiple of 1/6): 0.3.
    let c30 = {
        let mut c = fx.frames(11, 30);
        fx.shift(&mut c[1], "head", Vec3::new(4.0, 0.0, 0.0));
        c
    };
    let mut d240 = fx.frames(81, 240);
    fx.shift(&mut d240[40], "head", Vec3::new(0.0, 0.3, 0.0));
    fx.shift(&mut d240[8], "head", Vec3::new(0.0, 9.0, 0.0));
    let a_clean = fx.frames(21, 60);
    let b_clean = fx.frames(49, 144);
    let d = framerate_deviation(&[(30, &c30), (60, &a_clean), (144, &b_clean), (240, &d240)]);
    assert!(near(d, 0.3, 1e-5), "{d}");

    // Fewer than two runs, or none usable: 0.
    assert_eq!(framerate_deviation(&[(60, &a)]), 0.0);
    assert_eq!(framerate_deviation(&[(0, &a), (60, &a)]), 0.0);
}

#[test]
fn json_has_exactly_the_documented_keys_and_the_table_marks_failures() {
    let fx = Fixture::new();
    let mut frames = fx.frames(40, 60);
    for (k, f) in frames.iter_mut().enumerate() {
        let x = 0.2 * k.min(10) as f32;
        fx.shift(f, "foot_l", Vec3::new(x, 0.0, 0.0));
    }
    let mut rep = analyse(&fx.rig, &frames, &FlatGround(0.0));
    rep.framerate_deviation_cm_max = Some(0.3);
    let json: serde_json::Value = serde_json::from_str(&rep.to_json().expect("json")).unwrap();
    let mut keys: Vec<&str> = json
        .as_object()
        .expect("object")
        .keys()
        .map(String::as_str)
        .collect();
    keys.sort_unstable();
    let mut expected = vec![
        "frames",
        "duration_s",
        "hz",
        "skate_cm_per_stance_max",
        "skate_cm_per_stance_mean",
        "skate_foot",
        "skate_time_s",
        "penetration_cm_max",
        "idle_float_cm_max",
        "crossing_frames",
        "knee_backward_frames",
        "leg_overextension_frames",
        "pop_cm_per_frame_max",
        "pop_bone",
        "pop_time_s",
        "nonfinite_values",
        "steps",
        "cadence_steps_per_min",
        "mean_step_length_cm",
        "framerate_deviation_cm_max",
    ];
    expected.sort_unstable();
    assert_eq!(keys, expected);

    let checks = rep.targets_met();
    let failed: Vec<&str> = checks.iter().filter(|c| !c.met).map(|c| c.metric).collect();
    // The 2 cm slide fails the 0.5 cm skate target, and it is the only failure.
    assert_eq!(failed, ["skate_cm_per_stance_max"]);
    assert!(
        checks
            .iter()
            .any(|c| c.metric == "framerate_deviation_cm_max" && c.met)
    );
    assert!(!rep.all_targets_met());

    let table = rep.table();
    let skate = table
        .lines()
        .find(|l| l.starts_with("skate per stance, max"))
        .expect("skate row");
    assert!(skate.contains("2.000 cm") && skate.contains("≤ 0.5 cm") && skate.ends_with("FAIL"));
    let pops = table.lines().find(|l| l.starts_with("pops")).expect("pops");
    assert!(pops.ends_with("pass"), "{table}");
    // Columns are aligned: every target starts under the header's "target".
    let header = table.lines().nth(1).expect("header");
    let column = header[..header.find("target").expect("target")]
        .chars()
        .count();
    let mut rows = 0;
    for line in table.lines().skip(2) {
        if let Some(i) = line.find('≤') {
            assert_eq!(line[..i].chars().count(), column, "{table}");
            rows += 1;
        }
    }
    // skate, penetration, idle float, crossing, knees, pops, non-finite, frame rate.
    assert_eq!(rows, 8, "{table}");
    println!("{table}");
}

#[test]
fn empty_and_degenerate_recordings_do_not_panic() {
    let fx = Fixture::new();
    let rep = analyse(&fx.rig, &[], &FlatGround(0.0));
    assert_eq!(rep.frames, 0);
    assert_eq!((rep.duration_s, rep.hz), (0.0, 0.0));
    assert_eq!(rep.steps, 0);
    let mut one = fx.frames(1, 60);
    one[0].globals.clear();
    let rep = analyse(&fx.rig, &one, &FlatGround(0.0));
    assert_eq!(rep.frames, 1);
    assert!(!rep.table().is_empty());
}

#[test]
fn flat_ground_searches_from_above_the_point() {
    let g = FlatGround(10.0);
    assert_eq!(g.ground_below(Vec3::new(0.0, 0.0, 12.0)), Some(10.0));
    // 49 cm below the plane: the search starts 50 cm above the point and finds it.
    assert_eq!(g.ground_below(Vec3::new(0.0, 0.0, -39.0)), Some(10.0));
    assert_eq!(g.ground_below(Vec3::new(0.0, 0.0, -41.0)), None);
}

#[test]
fn plots_are_written_as_svg_with_labelled_axes() {
    use crate::plots::write_plots;
    let fx = Fixture::new();
    let mut frames = fx.frames(140, 60);
    for (k, f) in frames.iter_mut().enumerate() {
        let right = match k {
            0..=9 => Vec3::ZERO,
            10..=19 => Vec3::new(0.0, 10.0, 10.0),
            20..=49 => Vec3::new(0.0, 21.0, 0.0),
            50..=59 => Vec3::new(0.0, 40.0, 10.0),
            _ => Vec3::new(0.0, 63.0, 0.0),
        };
        let left = match k {
            0..=29 => Vec3::ZERO,
            30..=39 => Vec3::new(0.0, 20.0, 10.0),
            _ => Vec3::new(0.0, 42.0, 0.0),
        };
        fx.shift(f, "foot_r", right);
        fx.shift(f, "foot_l", left);
        f.component_to_world =
            Transform::from_translation(Vec3::new(0.0, 0.5 * k.min(80) as f32, 0.0));
    }
    frames[50].globals[0].translation.x = f32::NAN;
    let rep = analyse(&fx.rig, &frames, &FlatGround(0.0));
    let dir = std::env::temp_dir().join(format!("strider-report-plots-{}", std::process::id()));
    let paths = write_plots(&dir, &fx.rig, &frames, &FlatGround(0.0), &rep).expect("plots");
    assert_eq!(paths.len(), 3);
    let labels = [
        ["time (s)", "height above ground (cm)", "Foot height"],
        ["world X (cm)", "world Y (cm)", "Plants and root path"],
        ["time (s)", "height (cm)", "Pelvis height"],
    ];
    for (path, labels) in paths.iter().zip(labels) {
        let svg = std::fs::read_to_string(path).expect("read");
        assert!(svg.trim_start().starts_with("<svg"), "{path:?}");
        assert!(svg.trim_end().ends_with("</svg>"), "{path:?}");
        assert!(!svg.contains("NaN"), "{path:?}");
        for l in labels {
            assert!(svg.contains(l), "{path:?} lacks {l}");
        }
    }
    // Also with nothing to plot.
    let empty = dir.join("empty");
    let rep = analyse(&fx.rig, &[], &FlatGround(0.0));
    assert_eq!(
        write_plots(&empty, &fx.rig, &[], &FlatGround(0.0), &rep)
            .expect("empty plots")
            .len(),
        3
    );
    if std::env::var_os("STRIDER_KEEP_PLOTS").is_none() {
        let _ = std::fs::remove_dir_all(&dir);
    }
}
