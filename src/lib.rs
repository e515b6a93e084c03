//! Strider: a runtime for procedural character animation.
//!
//! A rig is described as a *graph* in a RON file: variables, nodes (math, bone reads and
//! writes, traces, IK...) and events (`construction`, run once per instance, and
//! `forward`, run every frame). The compiler checks the graph and turns it into an
//! immutable, shareable [`Program`]; each character gets an [`Instance`] of it bound to a
//! [`Skeleton`], and the host runs one frame at a time, answering world queries through
//! [`WorldQuery`] and reading back the pose.
//!
//! # Conventions
//!
//! Rig space is **+Z up, +Y forward, +X the character's left** (right-handed);
//! lengths are **centimetres**, time **seconds**, and angles facing graph authors
//! **degrees**. Transforms compose parent · child (`global = parent_global * local`);
//! quaternions are stored `(x, y, z, w)`. See [`core`] for the full statement.
//!
//! # Example
//!
//! ```no_run
//! use std::path::Path;
//! use std::sync::Arc;
//! use strider::{EmptyWorld, FrameInput, InputPose, Instance, Transform};
//!
//! fn report(diagnostics: Vec<strider::Diagnostic>) -> String {
//!     diagnostics.iter().map(ToString::to_string).collect::<Vec<_>>().join("\n")
//! }
//!
//! # fn main() -> Result<(), Box<dyn std::error::Error>> {
//! let skeleton = strider::load_skeleton(Path::new("graphs/skeletons/mannequin.ron"))
//!     .map_err(report)?;
//! let program = strider::compile_file(Path::new("graphs/pelvis_bob.ron")).map_err(report)?;
//! let mut instance = Instance::new(Arc::new(program), skeleton.skeleton.clone())?;
//!
//! let input = FrameInput {
//!     dt: 1.0 / 60.0, // seconds
//!     component_to_world: Transform::IDENTITY,
//!     pose: InputPose::Rest,
//! };
//! instance.run_forward(&input, &EmptyWorld, false);
//!
//! let pelvis = skeleton.skeleton.find("pelvis").expect("the mannequin has a pelvis");
//! let z = instance.pose_mut().global(pelvis).translation.z; // rig space, cm
//! println!("pelvis height after one frame: {z} cm");
//! # Ok(())
//! # }
//! ```
//!
//! The same from the command line: `strider run graphs/pelvis_bob.ron --skeleton
//! graphs/skeletons/mannequin.ron --frames 60 --out pose.jsonl`.

pub use strider_compiler as compiler;
pub use strider_core as core;
pub use strider_graph as graph;
pub use strider_host as host;
pub use strider_nodes as nodes;
pub use strider_vm as vm;

pub use strider_compiler::compile_file;
pub use strider_core::{
    EmptyWorld, LineQuery, Skeleton, SphereQuery, TraceHit, Transform, WorldQuery,
};
pub use strider_graph::{Diagnostic, load_skeleton};
pub use strider_vm::{FrameInput, InputPose, Instance, Program};
