//! The recording behind time travel: a ring buffer of the last frames, each with the
//! pose, the placement, every scalar slot of the instance (all pin values and variables)
//! and the debug drawing.
//!
//! Memory is bounded: the ring holds a fixed number of frames, allocated as they first
//! fill and then overwritten in place (`clear` + `extend_from_slice` keep each vector's
//! capacity), so once full, recording a frame allocates nothing. Array slots are not
//! recorded (their size is unbounded): a recorded frame shows arrays as unavailable.

use std::mem::size_of;
use strider_core::{DebugPrimitive, Quat, Transform, Vec3};
use strider_host::report::FrameRecord;
use strider_nodes::{Value, ValueType};
use strider_vm::{Instance, Slots};

/// What is known of a frame besides the instance's memory.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FrameMeta {
    /// Frame number since the session started.
    pub frame: u64,
    /// Simulated time at the end of the frame, seconds.
    pub time: f64,
    /// The frame's `dt`, seconds.
    pub dt: f32,
    /// The program generation that ran it (changes when a reload changes the program).
    pub generation: u32,
    /// Rig (component) space to world, cm.
    pub to_world: Transform,
    /// The capsule's velocity, world, cm/s.
    pub velocity: Vec3,
    /// Whether the input asked to stand still.
    pub standing_still: bool,
    /// Whether the character was teleported before this frame.
    pub teleported: bool,
}

/// A copy of an instance's scalar slots (the arrays of [`Slots`] without the array slots).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SlotImage {
    /// Bool slots.
    pub bools: Vec<bool>,
    /// Int slots.
    pub ints: Vec<i32>,
    /// Float slots.
    pub floats: Vec<f32>,
    /// Vector slots, cm or unitless as the pin says.
    pub vec3s: Vec<Vec3>,
    /// Rotation slots.
    pub quats: Vec<Quat>,
    /// Transform slots.
    pub transforms: Vec<Transform>,
    /// Bone slots: bone index, -1 for none.
    pub bones: Vec<i32>,
}

fn copy<T: Copy>(to: &mut Vec<T>, from: &[T]) {
    to.clear();
    to.extend_from_slice(from);
}

impl SlotImage {
    /// Overwrites the image with `slots` (no allocation once the capacity suffices).
    pub fn copy_from(&mut self, slots: &Slots) {
        copy(&mut self.bools, &slots.bools);
        copy(&mut self.ints, &slots.ints);
        copy(&mut self.floats, &slots.floats);
        copy(&mut self.vec3s, &slots.vec3s);
        copy(&mut self.quats, &slots.quats);
        copy(&mut self.transforms, &slots.transforms);
        copy(&mut self.bones, &slots.bones);
    }

    /// Slot `slot` of type `ty`; `None` for arrays and names (not recorded) and for a slot
    /// out of range. Bones read as `Bone(None)`: the caller names them (see
    /// [`crate::values::format_value`]).
    #[must_use]
    pub fn read(&self, ty: ValueType, slot: u32) -> Option<Value> {
        let s = slot as usize;
        Some(match ty {
            ValueType::Bool => Value::Bool(*self.bools.get(s)?),
            ValueType::Int => Value::Int(*self.ints.get(s)?),
            ValueType::Float => Value::Float(*self.floats.get(s)?),
            ValueType::Vec3 => Value::Vec3(*self.vec3s.get(s)?),
            ValueType::Quat => Value::Quat(*self.quats.get(s)?),
            ValueType::Transform => Value::Transform(*self.transforms.get(s)?),
            ValueType::Bone | ValueType::Name | ValueType::Array(_) => return None,
        })
    }

    /// Bytes the image's values occupy (its capacity may be larger).
    #[must_use]
    pub fn bytes(&self) -> usize {
        self.bools.len() * size_of::<bool>()
            + self.ints.len() * size_of::<i32>()
            + self.floats.len() * size_of::<f32>()
            + self.vec3s.len() * size_of::<Vec3>()
            + self.quats.len() * size_of::<Quat>()
            + self.transforms.len() * size_of::<Transform>()
            + self.bones.len() * size_of::<i32>()
    }
}

/// One recorded frame.
#[derive(Clone, Debug, Default)]
pub struct RecordedFrame {
    /// Time, placement and input of the frame.
    pub meta: FrameMeta,
    /// Rig-space (global) transforms of every bone, skeleton order, cm.
    pub globals: Vec<Transform>,
    /// The instance's scalar slots after the frame.
    pub slots: SlotImage,
    /// The debug primitives the frame drew, rig space.
    pub debug: Vec<DebugPrimitive>,
}

impl RecordedFrame {
    /// Bytes the frame's data occupies.
    #[must_use]
    pub fn bytes(&self) -> usize {
        size_of::<Self>()
            + self.globals.len() * size_of::<Transform>()
            + self.slots.bytes()
            + self.debug.len() * size_of::<DebugPrimitive>()
    }
}

/// The ring of the last recorded frames. Index 0 is the oldest frame kept.
#[derive(Clone, Debug)]
pub struct Recorder {
    frames: Vec<RecordedFrame>,
    capacity: usize,
    /// Where the next frame goes once the ring is full.
    head: usize,
}

impl Recorder {
    /// A recorder keeping the last `capacity` frames (at least 1). Frames of different
    /// programs (before and after a reload) may be kept side by side: each keeps its own
    /// slot layout, and [`FrameMeta::generation`] tells them apart.
    #[must_use]
    pub fn new(capacity: usize) -> Recorder {
        let capacity = capacity.max(1);
        Recorder {
            frames: Vec::with_capacity(capacity),
            capacity,
            head: 0,
        }
    }

    /// Records the frame `instance` just ran.
    pub fn push(&mut self, meta: FrameMeta, instance: &mut Instance) {
        let slot = if self.frames.len() < self.capacity {
            self.frames.push(RecordedFrame::default());
            self.frames.len() - 1
        } else {
            let at = self.head;
            self.head = (self.head + 1) % self.capacity;
            at
        };
        let debug = instance.debug_draw().primitives();
        let f = &mut self.frames[slot];
        f.meta = meta;
        copy(&mut f.debug, debug);
        f.slots.copy_from(instance.slots());
        copy(&mut f.globals, instance.pose_mut().globals());
    }

    /// Frames kept.
    #[must_use]
    pub fn len(&self) -> usize {
        self.frames.len()
    }

    /// Whether nothing is recorded yet.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.frames.is_empty()
    }

    /// Most frames kept.
    #[must_use]
    pub fn capacity(&self) -> usize {
        self.capacity
    }

    /// Frame `i` counted from the oldest kept (0) to the newest (`len() - 1`).
    #[must_use]
    pub fn get(&self, i: usize) -> Option<&RecordedFrame> {
        if i >= self.frames.len() {
            return None;
        }
        let at = if self.frames.len() < self.capacity {
            i
        } else {
            (self.head + i) % self.capacity
        };
        self.frames.get(at)
    }

    /// The newest frame.
    #[must_use]
    pub fn latest(&self) -> Option<&RecordedFrame> {
        self.len().checked_sub(1).and_then(|i| self.get(i))
    }

    /// Frames from oldest to newest.
    pub fn iter(&self) -> impl DoubleEndedIterator<Item = &RecordedFrame> {
        let (newer, older) = self.frames.split_at(self.head.min(self.frames.len()));
        older.iter().chain(newer)
    }

    /// The position of the newest frame whose time is at most `time` (the oldest if all
    /// are later).
    #[must_use]
    pub fn index_at_time(&self, time: f64) -> Option<usize> {
        if self.is_empty() {
            return None;
        }
        let (mut lo, mut hi) = (0, self.len());
        while lo < hi {
            let mid = (lo + hi) / 2;
            if self.get(mid).is_some_and(|f| f.meta.time <= time) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        Some(lo.saturating_sub(1))
    }

    /// The frames of program `generation` as the report's records (allocates: for the
    /// quality panel, a few times a second).
    #[must_use]
    pub fn frame_records(&self, generation: u32) -> Vec<FrameRecord> {
        self.iter()
            .filter(|f| f.meta.generation == generation)
            .map(|f| FrameRecord {
                time: f.meta.time,
                dt: f.meta.dt,
                component_to_world: f.meta.to_world,
                standing_still: f.meta.standing_still,
                teleported: f.meta.teleported,
                globals: f.globals.clone(),
            })
            .collect()
    }

    /// Bytes of the newest frame (0 when empty).
    #[must_use]
    pub fn bytes_per_frame(&self) -> usize {
        self.latest().map_or(0, RecordedFrame::bytes)
    }

    /// Bytes the kept frames occupy (their vectors' lengths, not capacities).
    #[must_use]
    pub fn bytes(&self) -> usize {
        self.frames.iter().map(RecordedFrame::bytes).sum()
    }
}
