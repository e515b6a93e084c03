//! Runs a graph instance through a scenario: each frame the [`Simulation`] moves the capsule,
//! the instance runs its `forward` event from the rest pose with the frame's `dt` and
//! component-to-world transform against the scenario's [`World`], and the output pose is
//! handed to the caller or recorded as [`FrameRecord`]s for the report.
//!
//! The rig only reads where the capsule is; it never moves it.

use crate::report::{FrameRecord, GROUND_SEARCH_ABOVE_CM, Ground};
use crate::scenario::{Scenario, SimFrame, Simulation};
use crate::world::World;
use glam::Vec3;
use strider_vm::{FrameInput, InputPose, Instance};

impl Ground for World {
    /// The first surface below `p` (world space, cm), searching from
    /// [`GROUND_SEARCH_ABOVE_CM`] above it so that a sole sunk into a step still finds the
    /// step's top.
    fn ground_below(&self, p: Vec3) -> Option<f32> {
        self.ground_height(p.x, p.y, p.z + GROUND_SEARCH_ABOVE_CM)
            .map(|(z, _)| z)
    }
}

/// Runs `instance` through `scenario` at `hz` frames per second (see [`Simulation::new`]),
/// calling `each` after every frame with the frame and the instance (its pose holds the
/// output). `debug` asks the graph for debug drawing. Returns the simulation, so the caller
/// can read its world.
pub fn drive(
    instance: &mut Instance,
    scenario: &Scenario,
    hz: u32,
    debug: bool,
    mut each: impl FnMut(&SimFrame, &mut Instance),
) -> Simulation {
    let mut sim = Simulation::new(scenario, hz);
    while let Some(frame) = sim.next_frame() {
        let input = FrameInput {
            dt: frame.dt,
            component_to_world: frame.component_to_world,
            pose: InputPose::Rest,
        };
        instance.run_forward(&input, sim.world(), debug);
        each(&frame, instance);
    }
    sim
}

/// Runs `instance` through `scenario` at `hz` and records every frame's rig-space pose for
/// [`crate::report::analyse`]. `progress` is called after each frame with
/// `(frames done, frames in all)`. Returns the records and the scenario's world.
pub fn record(
    instance: &mut Instance,
    scenario: &Scenario,
    hz: u32,
    mut progress: impl FnMut(usize, usize),
) -> (Vec<FrameRecord>, World) {
    let total = Simulation::new(scenario, hz).frame_count();
    let mut frames = Vec::with_capacity(total);
    let sim = drive(instance, scenario, hz, false, |frame, instance| {
        frames.push(FrameRecord {
            time: frame.time,
            dt: frame.dt,
            component_to_world: frame.component_to_world,
            standing_still: frame.standing_still,
            teleported: frame.teleported,
            globals: instance.pose_mut().globals().to_vec(),
        });
        progress(frames.len(), total);
    });
    (frames, sim.world().clone())
}
