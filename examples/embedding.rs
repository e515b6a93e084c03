//! Embedding Strider in a host engine: compile a graph once, run one instance per
//! character every frame against the host's world, read back the pose.
//!
//! Run it with `cargo run --example embedding`; `docs/embedding.md`
//! explains each step.

use std::error::Error;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use strider::core::{DebugPrimitive, TraceHit, Transform, Vec3, WorldQuery};
use strider::graph::Diagnostic;
use strider::nodes::Value;
use strider::vm::{FrameInput, InputPose, Instance, InstantiateError, Program};

/// The host's world: flat ground at world height `height` (cm). A real host would ask its
/// physics engine instead.
struct FlatGround {
    height: f32,
}

impl WorldQuery for FlatGround {
    /// First hit of the segment `start → end` (world space, cm) going down through the
    /// ground plane.
    fn line_trace(&self, start: Vec3, end: Vec3) -> Option<TraceHit> {
        let above_start = start.z - self.height;
        let above_end = end.z - self.height;
        if above_start < 0.0 || above_end > 0.0 || above_start == above_end {
            return None;
        }
        let t = above_start / (above_start - above_end);
        Some(TraceHit {
            point: start.lerp(end, t),
            normal: Vec3::Z,
            distance: start.distance(end) * t,
        })
    }

    /// A sphere swept down onto the ground touches it when its centre is `radius` above.
    fn sphere_trace(&self, start: Vec3, end: Vec3, radius: f32) -> Option<TraceHit> {
        let lifted = FlatGround {
            height: self.height + radius,
        };
        lifted.line_trace(start, end).map(|hit| TraceHit {
            point: hit.point - Vec3::Z * radius,
            ..hit
        })
    }
}

/// Diagnostics, one per line, as `path:line:col: error: message` with hints.
fn report(diagnostics: Vec<Diagnostic>) -> String {
    diagnostics
        .iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join("\n")
}

/// `(x, y, z)` with one decimal.
fn cm(v: Vec3) -> String {
    format!("({:.1}, {:.1}, {:.1})", v.x, v.y, v.z)
}

/// A file of this repository, wherever the example is run from.
fn repo_file(relative: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(relative)
}

fn main() -> Result<(), Box<dyn Error>> {
    // Load and compile once. The program is immutable and `Send + Sync`: share it.
    let skeleton_file = strider::graph::load_skeleton(&repo_file("graphs/skeletons/mannequin.ron"))
        .map_err(report)?;
    let skeleton = Arc::clone(&skeleton_file.skeleton);
    let program: Arc<Program> = Arc::new(
        strider::compiler::compile_file(&repo_file("graphs/pelvis_bob.ron")).map_err(report)?,
    );

    // Resolve names to ids once, outside the frame loop.
    let amplitude = program
        .variable_id("Amplitude")
        .ok_or("pelvis_bob declares `Amplitude`")?;
    let pelvis = skeleton
        .find("pelvis")
        .ok_or("the mannequin has a pelvis")?;
    for v in program.variables().iter().filter(|v| v.tunable.is_some()) {
        println!("tunable {} ({}), default {}", v.name, v.ty, v.default);
    }

    // One instance per character; creating it runs the `construction` event.
    let mut walker = Instance::new(Arc::clone(&program), Arc::clone(&skeleton))?;
    let mut runner = Instance::new(Arc::clone(&program), Arc::clone(&skeleton))?;
    runner.set_float(amplitude, 10.0); // per character, no allocation

    let world = FlatGround { height: 0.0 };
    let runner_placement = Transform::from_translation(Vec3::new(100.0, 0.0, 0.0));
    for frame in 0..60 {
        let last = frame == 59;
        let input = FrameInput {
            dt: 1.0 / 60.0,
            component_to_world: Transform::IDENTITY,
            pose: InputPose::Rest,
        };
        walker.run_forward(&input, &world, last); // debug drawing on the last frame only
        let input = FrameInput {
            component_to_world: runner_placement,
            ..input
        };
        runner.run_forward(&input, &world, false);
        if (frame + 1) % 15 == 0 {
            let a = walker.pose_mut().global(pelvis).translation.z;
            let b = runner.pose_mut().global(pelvis).translation.z;
            println!(
                "frame {:2}: pelvis height {a:6.2} cm (walker), {b:6.2} cm (runner)",
                frame + 1
            );
        }
    }

    // The whole output pose, rig space, in the skeleton's storage order.
    let globals = walker.pose_mut().globals();
    for (name, global) in skeleton.names().iter().zip(globals) {
        if name == "pelvis" || name == "head" {
            println!("{name} at {} cm", cm(global.translation));
        }
    }

    // Debug primitives drawn by the last frame (rig space).
    for primitive in walker.debug_draw().primitives() {
        if let DebugPrimitive::Axes {
            transform, size, ..
        } = primitive
        {
            println!(
                "debug axes at {} cm, {size} cm long",
                cm(transform.translation)
            );
        }
    }

    // A crowd: many characters of one program, run together through each instruction
    // (up to 16 at a time, picked by the path their last frame took) with the same results
    // as one by one. For threads, hand each thread a large chunk of the crowd.
    let mut crowd = (0..64)
        .map(|_| Instance::new(Arc::clone(&program), Arc::clone(&skeleton)))
        .collect::<Result<Vec<_>, _>>()?;
    for _ in 0..45 {
        Instance::run_forward_batch(
            &mut crowd,
            // Character `k`'s input: placed two metres apart along world X.
            |k| FrameInput {
                dt: 1.0 / 60.0,
                component_to_world: Transform::from_translation(Vec3::new(
                    200.0 * k as f32,
                    0.0,
                    0.0,
                )),
                pose: InputPose::Rest,
            },
            &world,
            false,
        );
    }
    // The bob does not depend on placement: every character is where the walker was at
    // frame 45.
    let heights: Vec<f32> = crowd
        .iter_mut()
        .map(|c| c.pose_mut().global(pelvis).translation.z)
        .collect();
    println!(
        "crowd of {}: pelvis heights {:6.2} to {:6.2} cm after 45 frames",
        crowd.len(),
        heights.iter().copied().fold(f32::INFINITY, f32::min),
        heights.iter().copied().fold(f32::NEG_INFINITY, f32::max),
    );

    // Setting a variable with the wrong type is refused.
    if let Err(e) = walker.set_variable(amplitude, &Value::Bool(true)) {
        println!("set_variable refused: {e}");
    }

    probe_the_ground(&skeleton, &world)?;
    refuse_a_skeleton_without_a_pelvis(&program)
}

/// Traces go through the host's `WorldQuery` in world space: this graph measures how far
/// the left ankle is above the ground, with the character standing on a 5 cm step.
fn probe_the_ground(
    skeleton: &Arc<strider::core::Skeleton>,
    world: &FlatGround,
) -> Result<(), Box<dyn Error>> {
    let source = r#"
        Graph(
            version: 1,
            name: "ground_probe",
            variables: { "Distance": (type: Float) },
            nodes: {
                "ankle": GetTransform(bone: bone("foot_l")),
                "parts": BreakTransform(value: "ankle"),
                "below": Add(a: "parts.translation", b: (0.0, 0.0, -100.0)),
                "trace": LineTrace(start: "parts.translation", end: "below"),
            },
            events: { forward: [ Set("Distance", "trace.distance") ] },
        )
    "#;
    let program =
        strider::compiler::compile_str(Path::new("ground_probe.ron"), source).map_err(report)?;
    let program = Arc::new(program);
    let distance = program.variable_id("Distance").ok_or("declared above")?;
    let mut probe = Instance::new(Arc::clone(&program), Arc::clone(skeleton))?;
    let input = FrameInput {
        dt: 1.0 / 60.0,
        component_to_world: Transform::from_translation(Vec3::new(0.0, 0.0, 5.0)),
        pose: InputPose::Rest,
    };
    probe.run_forward(&input, world, false);
    if let Value::Float(d) = probe.variable(distance) {
        println!("left ankle above the ground: {d:.2} cm");
    }
    Ok(())
}

/// Bones named by the graph are resolved when an instance is created; a skeleton that
/// lacks one is refused with the graph location of every reference.
fn refuse_a_skeleton_without_a_pelvis(program: &Arc<Program>) -> Result<(), Box<dyn Error>> {
    let tiny = strider::graph::load_skeleton_str(
        Path::new("tiny.ron"),
        r#"Skeleton(version: 1, name: "tiny", bones: [ (name: "root", parent: None) ])"#.into(),
    )
    .map_err(report)?;
    match Instance::new(Arc::clone(program), tiny.skeleton) {
        Ok(_) => Err("pelvis_bob should need a pelvis".into()),
        Err(InstantiateError::MissingBones { missing, .. }) => {
            if let Some(m) = missing.first() {
                println!(
                    "refused: missing bone `{}`, named at {}",
                    m.name, m.location
                );
            }
            Ok(())
        }
    }
}
