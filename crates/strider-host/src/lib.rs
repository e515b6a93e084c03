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

/// Reproducible numbers in [−1, 1) from `seed` (a linear congruential generator), for the
/// unit tests' random sweeps and traces.
#[cfg(test)]
fn signed(mut seed: u32) -> impl FnMut() -> f32 {
    move || {
        seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
        (seed >> 8) as f32 / (1u32 << 24) as f32 * 2.0 - 1.0
    }
}
