//! What the crowd tests share: a scenario's input track, and comparing two instances that
//! must have run alike.

use strider::host::scenario::{Scenario, Simulation};
use strider::vm::VariableId;
use strider::{FrameInput, InputPose, Instance, Program, Transform};

/// `scenario` run through its simulation at `hz`: every frame's time step and
/// component-to-world transform, and the simulation (whose world the characters trace).
pub fn track(scenario: &Scenario, hz: u32) -> (Simulation, Vec<(f32, Transform)>) {
    let mut sim = Simulation::new(scenario, hz);
    let mut track = Vec::new();
    while let Some(frame) = sim.next_frame() {
        track.push((frame.dt, frame.component_to_world));
    }
    (sim, track)
}

/// Frame `f`'s input of a character `offset` frames into `track` (wrapping round): its time
/// step and component-to-world transform, the rest pose as the input pose.
pub fn input_at(track: &[(f32, Transform)], f: usize, offset: usize) -> FrameInput<'static> {
    let (dt, component_to_world) = track[(f + offset) % track.len()];
    FrameInput {
        dt,
        component_to_world,
        pose: InputPose::Rest,
    }
}

/// Asserts that `a` and `b`, character `k` of two crowds of `program` in `what`, hold
/// bit-identical poses, the same debug drawing and the same graph variables after frame
/// `f`.
pub fn assert_same_frame(
    what: &str,
    program: &Program,
    k: usize,
    f: usize,
    a: &Instance,
    b: &Instance,
) {
    let (pa, pb) = (a.pose().locals(), b.pose().locals());
    assert!(
        pa.len() == pb.len() && pa.iter().zip(pb).all(|(x, y)| x.bit_eq(y)),
        "{what}: character {k}'s pose differs at frame {f}"
    );
    assert_eq!(
        a.debug_draw().primitives(),
        b.debug_draw().primitives(),
        "{what}: character {k}'s drawing differs at frame {f}"
    );
    for (v, info) in program.variables().iter().enumerate() {
        let id = VariableId(v as u32);
        // Debug text compares floats by value and sign (bit for bit but a NaN's payload).
        assert_eq!(
            format!("{:?}", a.variable(id)),
            format!("{:?}", b.variable(id)),
            "{what}: character {k}'s {} differs at frame {f}",
            info.name
        );
    }
}
