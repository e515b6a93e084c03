//! The demo host: what a game engine would provide around a Strider rig, small enough to
//! read. A world described in RON with line and sphere traces (parry3d), a kinematic
//! capsule moved by input, scenario files (a world plus a timeline of inputs), and the
//! locomotion quality report computed from output poses.
//!
//! World space follows the rig conventions: +Z up, centimetres. The mover's
//! component-to-world transform puts the rig origin at the capsule's bottom (the feet),
//! turned about Z by the character's facing.

pub mod drive;
pub mod mover;
pub mod overrides;
pub mod plots;
pub mod report;
pub mod scenario;
mod sweep;
pub mod world;
