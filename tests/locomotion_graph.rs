//! The flagship graph, `graphs/locomotion.ron`, on its own: it compiles and instantiates,
//! refuses a skeleton without feet, does not step while standing, and stays sane under
//! dt = 0, a one-second hitch, a teleport and a world where every trace misses.
//!
//! A self-contained harness: a flat-ground world answering traces against the plane z = 0
//! analytically, and component-to-world paths. The quality targets (skate, penetration,
//! pops, frame-rate deviation...) are measured by the host's report on the shipped
//! scenarios in `tests/locomotion_report.rs`.

use std::path::Path;
use std::sync::Arc;
use strider_core::{EmptyWorld, Quat, Skeleton, TraceHit, Transform, Vec3, WorldQuery};
use strider_vm::{FrameInput, InputPose, Instance, InstantiateError, Program};

// ---------------------------------------------------------------------------------------
// World and paths
// ---------------------------------------------------------------------------------------

/// The plane z = 0, solid below.
struct Flat;

impl WorldQuery for Flat {
    fn line_trace(&self, start: Vec3, end: Vec3) -> Option<TraceHit> {
        if start.z < 0.0 || end.z > 0.0 || start.z == end.z {
            return None;
        }
        let t = start.z / (start.z - end.z);
        let p = start + (end - start) * t;
        Some(TraceHit {
            point: Vec3::new(p.x, p.y, 0.0),
            normal: Vec3::Z,
            distance: (end - start).length() * t,
        })
    }

    fn sphere_trace(&self, start: Vec3, end: Vec3, radius: f32) -> Option<TraceHit> {
        let r = radius.max(0.0);
        if start.z < r {
            // Starts overlapping the ground: a hit where it starts.
            return Some(TraceHit {
                point: Vec3::new(start.x, start.y, 0.0),
                normal: Vec3::Z,
                distance: 0.0,
            });
        }
        if end.z > r || start.z == end.z {
            return None;
        }
        let t = (start.z - r) / (start.z - end.z);
        let c = start + (end - start) * t;
        Some(TraceHit {
            point: Vec3::new(c.x, c.y, 0.0),
            normal: Vec3::Z,
            distance: (end - start).length() * t,
        })
    }
}

/// A capsule path: component-to-world at time t (seconds).
type PathFn = Box<dyn Fn(f64) -> Transform>;

/// Piecewise-linear world velocity (x, y) through keys `(time, vx, vy)`, integrated exactly,
/// with a fixed facing yaw (degrees, + turns right).
fn linear_path(keys: Vec<(f64, f64, f64)>, yaw_deg: f64) -> PathFn {
    Box::new(move |t: f64| {
        let (mut x, mut y) = (0.0f64, 0.0f64);
        for w in keys.windows(2) {
            let (ta, vxa, vya) = w[0];
            let (tb, vxb, vyb) = w[1];
            if t <= ta {
                break;
            }
            let tau = t.min(tb) - ta;
            let len = tb - ta;
            x += vxa * tau + (vxb - vxa) * tau * tau / (2.0 * len);
            y += vya * tau + (vyb - vya) * tau * tau / (2.0 * len);
        }
        if let Some(&(tl, vx, vy)) = keys.last()
            && t > tl
        {
            x += vx * (t - tl);
            y += vy * (t - tl);
        }
        Transform::from_translation_rotation(
            Vec3::new(x as f32, y as f32, 0.0),
            Quat::from_rotation_z((yaw_deg as f32).to_radians()),
        )
    })
}

fn walk_path() -> PathFn {
    // Accelerate to 150 cm/s along +Y over 0.5 s, walk 4 s, stop over 0.5 s, stand 2 s.
    linear_path(
        vec![
            (0.0, 0.0, 0.0),
            (0.5, 0.0, 150.0),
            (4.5, 0.0, 150.0),
            (5.0, 0.0, 0.0),
            (7.0, 0.0, 0.0),
        ],
        0.0,
    )
}

// ---------------------------------------------------------------------------------------
// Running the graph
// ---------------------------------------------------------------------------------------

struct Rig {
    program: Arc<Program>,
    skeleton: Arc<Skeleton>,
}

fn rig() -> Rig {
    let program = match strider_compiler::compile_file(Path::new("graphs/locomotion.ron")) {
        Ok(p) => Arc::new(p),
        Err(d) => panic!(
            "{}",
            d.iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join("\n")
        ),
    };
    let file = strider_graph::load_skeleton(Path::new("graphs/skeletons/mannequin.ron")).unwrap();
    Rig {
        program,
        skeleton: file.skeleton,
    }
}

struct Frame {
    time: f64,
    rig: Vec<Transform>, // bone globals, rig space
}

fn simulate(rig: &Rig, path: &PathFn, hz: u32, seconds: f64, world: &dyn WorldQuery) -> Vec<Frame> {
    let mut instance = Instance::new(rig.program.clone(), rig.skeleton.clone()).unwrap();
    let dt = 1.0 / hz as f32;
    let frames = (seconds * f64::from(hz)).round() as usize;
    let mut out = Vec::with_capacity(frames);
    for n in 0..frames {
        let time = (n + 1) as f64 / f64::from(hz);
        let root = path(time);
        instance.run_forward(
            &FrameInput {
                dt,
                component_to_world: root,
                pose: InputPose::Rest,
            },
            world,
            false,
        );
        let rig_pose = instance.pose_mut().globals().to_vec();
        out.push(Frame {
            time,
            rig: rig_pose,
        });
    }
    out
}

#[test]
fn the_graph_compiles_without_diagnostics_and_instantiates() {
    let rig = rig();
    let instance = Instance::new(rig.program.clone(), rig.skeleton.clone());
    assert!(instance.is_ok());
}

#[test]
fn a_skeleton_without_feet_is_refused_naming_the_missing_bones() {
    let text = std::fs::read_to_string("graphs/skeletons/mannequin.ron").unwrap();
    // Rename the feet (and their contacts' bone): no `foot_l` / `foot_r` any more.
    let text = text
        .replace("\"foot_l\"", "\"ankle_l\"")
        .replace("\"foot_r\"", "\"ankle_r\"");
    let file = strider_graph::load_skeleton_str(Path::new("footless.ron"), text).unwrap();
    let rig = rig();
    match Instance::new(rig.program.clone(), file.skeleton) {
        Err(InstantiateError::MissingBones { missing, .. }) => {
            let names: Vec<_> = missing.iter().map(|m| m.name.as_str()).collect();
            assert!(
                names.contains(&"foot_l") && names.contains(&"foot_r"),
                "{names:?}"
            );
        }
        Ok(_) => panic!("a skeleton without feet was accepted"),
    }
}

fn bone(rig: &Rig, name: &str) -> usize {
    rig.skeleton.find(name).unwrap().get()
}

#[test]
fn standing_still_does_not_step() {
    let rig = rig();
    let path = linear_path(vec![(0.0, 0.0, 0.0), (3.0, 0.0, 0.0)], 0.0);
    let frames = simulate(&rig, &path, 60, 3.0, &Flat);
    let foot = bone(&rig, "foot_l");
    let first = frames[0].rig[foot].translation;
    for f in &frames {
        assert!(
            (f.rig[foot].translation - first).length() < 0.5,
            "the foot moved at {}",
            f.time
        );
    }
}

#[test]
fn zero_dt_and_a_one_second_hitch_stay_finite() {
    let rig = rig();
    let mut instance = Instance::new(rig.program.clone(), rig.skeleton.clone()).unwrap();
    let path = walk_path();
    let mut t = 0.0;
    for (n, dt) in [1.0f32 / 60.0; 60]
        .into_iter()
        .chain([0.0, 0.0, 1.0, 0.0, 1.0 / 60.0, 1.0])
        .enumerate()
    {
        t += f64::from(dt) + if dt == 0.0 { 0.01 } else { 0.0 }; // the capsule moves even at dt = 0
        instance.run_forward(
            &FrameInput {
                dt,
                component_to_world: path(t),
                pose: InputPose::Rest,
            },
            &Flat,
            true,
        );
        let pose = instance.pose_mut().globals().to_vec();
        assert!(
            pose.iter().all(Transform::is_finite),
            "frame {n} (dt {dt}) is not finite"
        );
        // Legs are never longer than the rest leg (within the IK clamp).
        let (thigh, foot) = (bone(&rig, "thigh_l"), bone(&rig, "foot_l"));
        let leg = (pose[foot].translation - pose[thigh].translation).length();
        assert!(leg < 79.0, "frame {n}: leg {leg} cm");
    }
}

#[test]
fn a_teleport_resets_the_feet_instead_of_stretching_the_legs() {
    let rig = rig();
    let mut instance = Instance::new(rig.program.clone(), rig.skeleton.clone()).unwrap();
    let path = walk_path();
    let dt = 1.0 / 60.0;
    for n in 0..240 {
        let mut root = path(f64::from(n + 1) * f64::from(dt));
        if n >= 120 {
            root.translation += Vec3::new(5000.0, -3000.0, 0.0); // 58 m away
        }
        instance.run_forward(
            &FrameInput {
                dt,
                component_to_world: root,
                pose: InputPose::Rest,
            },
            &Flat,
            false,
        );
        let pose = instance.pose_mut().globals().to_vec();
        for (thigh, foot) in [("thigh_l", "foot_l"), ("thigh_r", "foot_r")] {
            let leg =
                (pose[bone(&rig, foot)].translation - pose[bone(&rig, thigh)].translation).length();
            assert!(leg < 79.0, "frame {n}: {foot} {leg} cm from its hip");
            let ankle = root.transform_point(pose[bone(&rig, foot)].translation);
            assert!(
                ankle.z > -1.0 && ankle.z < 60.0,
                "frame {n}: {foot} at z {}",
                ankle.z
            );
        }
    }
}

#[test]
fn walking_into_a_void_keeps_the_legs_sane() {
    let rig = rig();
    let frames = simulate(&rig, &walk_path(), 60, 7.0, &EmptyWorld);
    for f in &frames {
        assert!(
            f.rig.iter().all(|t| t.is_finite()),
            "non-finite at {} s",
            f.time
        );
        for foot in ["foot_l", "foot_r"] {
            let z = f.rig[bone(&rig, foot)].translation.z;
            assert!(
                (-1.0..60.0).contains(&z),
                "{foot} at rig z {z} at {} s",
                f.time
            );
        }
    }
}
