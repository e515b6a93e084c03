//! The recording behind time travel: a ring buffer of the last frames, each with the
//! pose, the placement, the input, every slot of the instance (all pin values and
//! variables, arrays included) and the debug drawing.
//!
//! Memory is bounded: the ring holds a fixed number of frames, allocated as they first
//! fill and then overwritten in place (`clear` + `extend_from_slice` keep each vector's
//! capacity), so once full, recording a frame allocates nothing while the arrays keep
//! their sizes. The items of array slots are recorded within a fixed budget of
//! [`ARRAY_BUDGET`] bytes per frame: arrays are copied in slot order (per element type)
//! while the budget lasts; an array that does not fit is recorded as unavailable (its
//! length only), and smaller ones after it may still fit.

use std::mem::size_of;
use strider_core::{DebugPrimitive, Quat, Transform, Vec3};
use strider_host::mover::MoveInput;
use strider_host::report::FrameRecord;
use strider_nodes::{Elem, Value, ValueType};
use strider_vm::{Instance, Slots};

/// Bytes of array items one recorded frame may hold (8 KiB: 2,048 floats or 170
/// transforms); with [`crate::session::RECORD_FRAMES`] frames, 15.7 MB at most.
pub const ARRAY_BUDGET: usize = 8 * 1024;

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
    /// The keyboard input the mover followed during the frame ([`MoveInput::STAND`] while
    /// a scenario plays: it gives its own); kept to run the frame again when resuming
    /// from the past.
    pub input: MoveInput,
}

/// Where one array slot's items are in an [`ArrayImage`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ArraySpan {
    /// Index of the first item in [`ArrayImage::items`].
    pub start: u32,
    /// Items the array had.
    pub len: u32,
    /// Whether its items are recorded (false when they did not fit the frame's budget).
    pub kept: bool,
}

/// A copy of the array slots of one element type: their items one after another.
#[derive(Clone, Debug, PartialEq)]
pub struct ArrayImage<T> {
    /// The items of every kept array, in slot order.
    pub items: Vec<T>,
    /// Per array slot, where its items are.
    pub spans: Vec<ArraySpan>,
}

impl<T> Default for ArrayImage<T> {
    fn default() -> Self {
        Self {
            items: Vec::new(),
            spans: Vec::new(),
        }
    }
}

impl<T: Copy> ArrayImage<T> {
    /// Overwrites the image with `arrays`, taking each array's bytes from `budget` while it
    /// lasts. The items' capacity grows only to what the kept items need.
    fn copy_from(&mut self, arrays: &[Vec<T>], budget: &mut usize) {
        self.items.clear();
        self.spans.clear();
        for a in arrays {
            let bytes = std::mem::size_of_val(a.as_slice());
            let kept = bytes <= *budget;
            self.spans.push(ArraySpan {
                start: self.items.len() as u32,
                len: a.len() as u32,
                kept,
            });
            if kept {
                *budget -= bytes;
                self.items.reserve_exact(a.len());
                self.items.extend_from_slice(a);
            }
        }
    }

    /// The items of array slot `slot`, `None` when out of range or not kept.
    #[must_use]
    pub fn get(&self, slot: u32) -> Option<&[T]> {
        let span = self.spans.get(slot as usize).filter(|s| s.kept)?;
        self.items
            .get(span.start as usize..(span.start + span.len) as usize)
    }

    /// Bytes of the items and spans recorded.
    fn bytes(&self) -> usize {
        self.items.len() * size_of::<T>() + self.spans.len() * size_of::<ArraySpan>()
    }

    /// Bytes of the items' allocation.
    fn capacity_bytes(&self) -> usize {
        self.items.capacity() * size_of::<T>()
    }
}

/// A copy of an instance's slots (the arrays of [`Slots`]; array items within
/// [`ARRAY_BUDGET`]; names are not recorded).
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
    /// Bool array slots.
    pub bool_arrays: ArrayImage<bool>,
    /// Int array slots.
    pub int_arrays: ArrayImage<i32>,
    /// Float array slots.
    pub float_arrays: ArrayImage<f32>,
    /// Vector array slots.
    pub vec3_arrays: ArrayImage<Vec3>,
    /// Rotation array slots.
    pub quat_arrays: ArrayImage<Quat>,
    /// Transform array slots.
    pub transform_arrays: ArrayImage<Transform>,
    /// Bone array slots: bone indices, -1 for none.
    pub bone_arrays: ArrayImage<i32>,
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
        let mut budget = ARRAY_BUDGET;
        self.bool_arrays.copy_from(&slots.bool_arrays, &mut budget);
        self.int_arrays.copy_from(&slots.int_arrays, &mut budget);
        self.float_arrays
            .copy_from(&slots.float_arrays, &mut budget);
        self.vec3_arrays.copy_from(&slots.vec3_arrays, &mut budget);
        self.quat_arrays.copy_from(&slots.quat_arrays, &mut budget);
        self.transform_arrays
            .copy_from(&slots.transform_arrays, &mut budget);
        self.bone_arrays.copy_from(&slots.bone_arrays, &mut budget);
        if self.array_capacity_bytes() > ARRAY_BUDGET {
            // The mix of element types changed: give back what the kept items do not use,
            // so that the arrays' memory stays within the budget.
            self.bool_arrays.items.shrink_to_fit();
            self.int_arrays.items.shrink_to_fit();
            self.float_arrays.items.shrink_to_fit();
            self.vec3_arrays.items.shrink_to_fit();
            self.quat_arrays.items.shrink_to_fit();
            self.transform_arrays.items.shrink_to_fit();
            self.bone_arrays.items.shrink_to_fit();
        }
    }

    /// Bytes allocated for array items (at most [`ARRAY_BUDGET`] after each copy).
    #[must_use]
    pub fn array_capacity_bytes(&self) -> usize {
        self.bool_arrays.capacity_bytes()
            + self.int_arrays.capacity_bytes()
            + self.float_arrays.capacity_bytes()
            + self.vec3_arrays.capacity_bytes()
            + self.quat_arrays.capacity_bytes()
            + self.transform_arrays.capacity_bytes()
            + self.bone_arrays.capacity_bytes()
    }

    /// Slot `slot` of type `ty`; bones (and bone array items) are named from `bone_names`
    /// (the skeleton's names, storage order; `Bone(None)` for -1 or an index past them).
    /// `None` for names (not recorded), for arrays over the frame's budget and for a slot
    /// out of range. Allocates for arrays: for the panels, not the frame loop.
    #[must_use]
    pub fn read(&self, ty: ValueType, slot: u32, bone_names: &[String]) -> Option<Value> {
        let s = slot as usize;
        let bone = |b: i32| {
            Value::Bone(
                usize::try_from(b)
                    .ok()
                    .and_then(|i| bone_names.get(i).cloned()),
            )
        };
        fn items<T: Copy>(
            image: &ArrayImage<T>,
            slot: u32,
            f: impl Fn(T) -> Value,
        ) -> Option<Vec<Value>> {
            Some(image.get(slot)?.iter().map(|&x| f(x)).collect())
        }
        Some(match ty {
            ValueType::Bool => Value::Bool(*self.bools.get(s)?),
            ValueType::Int => Value::Int(*self.ints.get(s)?),
            ValueType::Float => Value::Float(*self.floats.get(s)?),
            ValueType::Vec3 => Value::Vec3(*self.vec3s.get(s)?),
            ValueType::Quat => Value::Quat(*self.quats.get(s)?),
            ValueType::Transform => Value::Transform(*self.transforms.get(s)?),
            ValueType::Bone => bone(*self.bones.get(s)?),
            ValueType::Name => return None,
            ValueType::Array(e) => Value::Array(
                e,
                match e {
                    Elem::Bool => items(&self.bool_arrays, slot, Value::Bool)?,
                    Elem::Int => items(&self.int_arrays, slot, Value::Int)?,
                    Elem::Float => items(&self.float_arrays, slot, Value::Float)?,
                    Elem::Vec3 => items(&self.vec3_arrays, slot, Value::Vec3)?,
                    Elem::Quat => items(&self.quat_arrays, slot, Value::Quat)?,
                    Elem::Transform => items(&self.transform_arrays, slot, Value::Transform)?,
                    Elem::Bone => items(&self.bone_arrays, slot, bone)?,
                },
            ),
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
            + self.bool_arrays.bytes()
            + self.int_arrays.bytes()
            + self.float_arrays.bytes()
            + self.vec3_arrays.bytes()
            + self.quat_arrays.bytes()
            + self.transform_arrays.bytes()
            + self.bone_arrays.bytes()
    }
}

/// One recorded frame.
#[derive(Clone, Debug, Default)]
pub struct RecordedFrame {
    /// Time, placement and input of the frame.
    pub meta: FrameMeta,
    /// Rig-space (global) transforms of every bone, skeleton order, cm.
    pub globals: Vec<Transform>,
    /// The instance's slots after the frame.
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

    /// Forgets every frame after the first `len` (counted from the oldest kept): the
    /// recorded future, when the simulation resumes from an earlier frame. The frames
    /// dropped are freed; the next ones are allocated as the ring fills again.
    pub fn truncate(&mut self, len: usize) {
        if len >= self.frames.len() {
            return;
        }
        self.frames.rotate_left(self.head);
        self.head = 0;
        self.frames.truncate(len);
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arrays_over_the_budget_are_not_recorded_and_their_memory_stays_within_it() {
        let float_array =
            |image: &SlotImage, slot| image.read(ValueType::Array(Elem::Float), slot, &[]);
        let mut slots = Slots {
            // 3,000 floats (12,000 bytes) do not fit in 8 KiB; the arrays after them do.
            float_arrays: vec![vec![1.0; 3000], vec![2.0, 3.0]],
            vec3_arrays: vec![vec![Vec3::X; 10]],
            bone_arrays: vec![vec![1, -1]],
            ..Slots::default()
        };
        let mut image = SlotImage::default();
        image.copy_from(&slots);
        assert_eq!(float_array(&image, 0), None);
        assert_eq!(
            float_array(&image, 1),
            Some(Value::Array(
                Elem::Float,
                vec![Value::Float(2.0), Value::Float(3.0)]
            ))
        );
        assert!(matches!(
            image.read(ValueType::Array(Elem::Vec3), 0, &[]),
            Some(Value::Array(Elem::Vec3, items)) if items == vec![Value::Vec3(Vec3::X); 10]
        ));
        let names = ["pelvis".to_string(), "foot_l".to_string()];
        assert_eq!(
            image.read(ValueType::Array(Elem::Bone), 0, &names),
            Some(Value::Array(
                Elem::Bone,
                vec![Value::Bone(Some("foot_l".to_string())), Value::Bone(None)]
            ))
        );
        assert!(image.array_capacity_bytes() <= ARRAY_BUDGET);
        // Shrunk to 1,000 floats (4,000 bytes), the first array fits.
        slots.float_arrays[0] = vec![1.0; 1000];
        image.copy_from(&slots);
        assert!(matches!(
            float_array(&image, 0),
            Some(Value::Array(_, items)) if items.len() == 1000
        ));
        // Another mix: 170 transforms (8,160 bytes) alone. The floats' memory is given back.
        slots = Slots {
            transform_arrays: vec![vec![Transform::IDENTITY; 170]],
            ..Slots::default()
        };
        image.copy_from(&slots);
        assert!(image.transform_arrays.get(0).is_some());
        assert!(image.array_capacity_bytes() <= ARRAY_BUDGET);
    }
}
