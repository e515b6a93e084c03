//! A batch's array variables side by side ([`ArrayLanes`]): a copy of each member's array,
//! element `i` of member `m` at item `i * BATCH + m`, made the first time the whole batch
//! reads the array, so that later reads of the batch find every member's element in one
//! block.
//!
//! Each member keeps its arrays in allocations of its own, reached through a chain of
//! pointers (context, slots, the element type's list of arrays, the array); an `ArrayAt`
//! of the whole batch follows that chain once per member ([`crate::per_member`]). The
//! per-foot arrays of `graphs/locomotion.ron` hold two elements and are read several
//! times a frame each, so one copy of the batch's elements, made at the first read, takes
//! the chains out of the reads that follow (and out of the steps of loops over the array).
//!
//! The members' own arrays stay the truth, and the copy follows them: a write by the
//! whole batch (`ArraySetAt` on [`crate::per_member`]'s path) writes both; any other write
//! of an array variable (an append, a reset, a copy or a select into it, the bones found
//! by `FindBones`, a member's own write while the batch is split) drops its copy
//! ([`ArrayLanes::forget`]) before the write, and the next read of the whole batch copies
//! it again. Only arrays whose members all have one length are copied (reading an element
//! is then one bounds check for every lane). Copies live for one run of a batch:
//! [`ArrayLanes::begin`] drops them all.
//!
//! Written here rather than taken from a crate: it is a cache over the executor's own
//! slots, whose invalidation follows this instruction set's writes.

// The copies are written through a pointer to their room, as the lanes are (see `lanes`).
#![allow(unsafe_code)]

use crate::exec::{BATCH, Ctx};
use crate::slots::Slots;
use glam::{Quat, Vec3};
use strider_core::Transform;
use strider_nodes::Elem;

/// Elements of each element type one run of a batch may copy (each `BATCH` items):
/// `graphs/locomotion.ron` has nine per-foot arrays of transforms, two elements each (18
/// at most to copy), and fewer elements of the other types. A read that would need more
/// room is done member by member.
pub(crate) const ELEMENTS: usize = 32;

/// What a run knows of one array variable's copy.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
enum State {
    /// No copy (none made yet in this run, or dropped by a write).
    #[default]
    None,
    /// The copy holds every member's elements, `len` of them.
    Copied,
    /// The members' arrays differ in length: read member by member until a write changes
    /// that.
    Apart,
}

/// One array variable's copy: its place in its type's items and its state, for run `run`
/// (a copy of an earlier run is no copy).
#[derive(Clone, Copy, Debug, Default)]
struct Entry {
    /// The run ([`ArrayLanes::begin`]) the other fields are of.
    run: u32,
    state: State,
    /// The first element's place (item `at * BATCH`) of the room this array holds in the
    /// run, and how many elements it has room for (a copy made again after a write reuses
    /// it when the array still fits).
    at: u32,
    room: u32,
    /// Elements in the copy (every member's array length).
    len: u32,
}

/// The copies of one element type's array variables.
pub(crate) struct Column<T> {
    /// `ELEMENTS * BATCH` items once the program has arrays of this type; empty before.
    items: Vec<T>,
    /// Per array variable of this type (the slot index of its arrays).
    entries: Vec<Entry>,
    /// Elements of `items` given to arrays in this run.
    used: u32,
}

impl<T> Default for Column<T> {
    fn default() -> Self {
        Self {
            items: Vec::new(),
            entries: Vec::new(),
            used: 0,
        }
    }
}

impl<T: Copy + Default> Column<T> {
    /// Room for `arrays` array variables: their entries, and the items when there are any.
    fn reserve(&mut self, arrays: usize) {
        if self.entries.len() < arrays {
            self.entries.resize(arrays, Entry::default());
        }
        if arrays > 0 && self.items.len() < ELEMENTS * BATCH {
            self.items.resize(ELEMENTS * BATCH, T::default());
        }
    }

    /// The batch's copy of array variable `array` in run `run`, as member 0's element 0 and
    /// the length of every member's array: made now from the `members`' arrays (`list`
    /// gives a member's arrays of this type) when the run has none yet. `None` when the
    /// members' arrays differ in length or the run's room is used up: the caller reads
    /// member by member. `array` must be an array variable of the program the column was
    /// reserved for.
    #[inline(always)]
    pub(crate) fn copy(
        &mut self,
        run: u32,
        array: usize,
        members: &[Ctx<'_>],
        list: impl Fn(&Slots) -> &[Vec<T>],
    ) -> Option<(*const T, usize)> {
        let entry = self.entries.get_mut(array)?;
        if entry.run != run {
            *entry = Entry {
                run,
                ..Entry::default()
            };
        }
        match entry.state {
            State::Copied => {
                let at = entry.at as usize * BATCH;
                return Some((self.items[at..].as_ptr(), entry.len as usize));
            }
            State::Apart => return None,
            State::None => {}
        }
        // Member 0's length, which every member's must have; each member's array is
        // reached once, its length checked and its elements copied.
        let len = list(&*members.first()?.slots)[array].len();
        if entry.room < len as u32 {
            // New room, at the end of what the run has given out.
            let at = self.used as usize;
            if at + len > self.items.len() / BATCH {
                return None;
            }
            (entry.at, entry.room) = (at as u32, len as u32);
            self.used += len as u32;
        }
        let at = entry.at as usize * BATCH;
        let items = self.items[at..at + len * BATCH].as_mut_ptr();
        for (m, cx) in members.iter().enumerate() {
            let from = &list(&*cx.slots)[array];
            if from.len() != len {
                // What was copied so far is never read: the state says so.
                entry.state = State::Apart;
                return None;
            }
            for (i, &x) in from.iter().enumerate() {
                // SAFETY: `i < len` and `m < members.len() <= BATCH`: within the
                // `len * BATCH` items sliced above.
                unsafe { *items.add(i * BATCH + m) = x };
            }
        }
        (entry.state, entry.len) = (State::Copied, len as u32);
        Some((items, len))
    }

    /// The copy of array variable `array` in run `run` if there is one (as
    /// [`Column::copy`], without making one), to write into.
    #[inline(always)]
    pub(crate) fn copied(&mut self, run: u32, array: usize) -> Option<(*mut T, usize)> {
        let entry = self.entries.get(array)?;
        if entry.run != run || entry.state != State::Copied {
            return None;
        }
        let at = entry.at as usize * BATCH;
        Some((self.items[at..].as_mut_ptr(), entry.len as usize))
    }

    /// Drops the copy of array variable `array` (a write is about to change the members'
    /// arrays).
    #[inline(always)]
    fn forget(&mut self, array: usize) {
        if let Some(entry) = self.entries.get_mut(array) {
            entry.state = State::None;
        }
    }
}

/// The copies of a batch's array variables, one [`Column`] per element type.
#[derive(Default)]
pub(crate) struct ArrayLanes {
    /// The current run: copies of other runs are none. Starts at 1 with the first run.
    pub(crate) run: u32,
    pub(crate) bools: Column<bool>,
    pub(crate) ints: Column<i32>,
    pub(crate) floats: Column<f32>,
    pub(crate) vec3s: Column<Vec3>,
    pub(crate) quats: Column<Quat>,
    pub(crate) transforms: Column<Transform>,
    /// Bone arrays' elements (bone indices, or -1): read by loops over them.
    pub(crate) bones: Column<i32>,
}

/// Runs `$m!(column, arrays)` for each column of [`ArrayLanes`] and the field of
/// [`Slots`] with its element type's array variables.
macro_rules! each_column {
    ($m:ident) => {
        $m!(bools, bool_arrays);
        $m!(ints, int_arrays);
        $m!(floats, float_arrays);
        $m!(vec3s, vec3_arrays);
        $m!(quats, quat_arrays);
        $m!(transforms, transform_arrays);
        $m!(bones, bone_arrays);
    };
}

impl ArrayLanes {
    /// Room for the array variables of a program whose initial slots are `initial`.
    pub(crate) fn reserve(&mut self, initial: &Slots) {
        macro_rules! reserve {
            ($col:ident, $ar:ident) => {
                self.$col.reserve(initial.$ar.len())
            };
        }
        each_column!(reserve);
    }

    /// Starts a run of a batch of the program whose initial slots are `initial`, with no
    /// copies.
    #[inline(always)]
    pub(crate) fn begin(&mut self, initial: &Slots) {
        self.reserve(initial);
        self.run = self.run.wrapping_add(1);
        // When the count comes round, entries of run 1, 2, ... four billion runs ago would
        // pass for the coming runs': they are cleared, and the count starts at 1 again.
        let wrapped = self.run == 0;
        macro_rules! begin {
            ($col:ident, $ar:ident) => {{
                if wrapped {
                    self.$col.entries.fill(Entry::default());
                }
                self.$col.used = 0;
            }};
        }
        each_column!(begin);
        if wrapped {
            self.run = 1;
        }
    }

    /// Drops the copy of array variable `array` of element type `elem`, if it has one.
    #[inline(always)]
    pub(crate) fn forget(&mut self, elem: Elem, array: u32) {
        let array = array as usize;
        match elem {
            Elem::Bool => self.bools.forget(array),
            Elem::Int => self.ints.forget(array),
            Elem::Float => self.floats.forget(array),
            Elem::Vec3 => self.vec3s.forget(array),
            Elem::Quat => self.quats.forget(array),
            Elem::Transform => self.transforms.forget(array),
            Elem::Bone => self.bones.forget(array),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tests::one_bone;
    use strider_core::{DebugDraw, Pose};
    use strider_nodes::{Access, Op, Operand, ValueType};

    /// Runs `f` on a batch of `n` members whose float array 0 is `lens(m)` long (element
    /// `i` of member `m`: `10 m + i`), with a run of copies begun.
    fn with_batch(
        n: usize,
        lens: impl Fn(usize) -> usize,
        f: impl FnOnce(&mut ArrayLanes, &[Ctx<'_>]),
    ) {
        let mut slots: Vec<Slots> = (0..n)
            .map(|m| Slots {
                float_arrays: vec![(0..lens(m)).map(|i| (10 * m + i) as f32).collect()],
                ..Slots::default()
            })
            .collect();
        let mut poses: Vec<Pose> = (0..n).map(|_| Pose::new(one_bone())).collect();
        let mut draws: Vec<DebugDraw> = (0..n).map(|_| DebugDraw::new(false)).collect();
        let cxs: Vec<Ctx<'_>> = slots
            .iter_mut()
            .zip(&mut poses)
            .zip(&mut draws)
            .map(|((s, p), d)| Ctx::for_test(s, &[], p, d, 1.0 / 60.0))
            .collect();
        let mut arrays = ArrayLanes::default();
        arrays.begin(cxs[0].slots);
        f(&mut arrays, &cxs);
    }

    /// Element `i` of member `m` of a copy at `items`.
    fn item(items: *const f32, i: usize, m: usize) -> f32 {
        // SAFETY: the callers' `i` and `m` are within the copy.
        unsafe { *items.add(i * BATCH + m) }
    }

    #[test]
    fn a_copy_holds_every_member_s_elements_side_by_side_until_forgotten() {
        with_batch(
            5,
            |_| 3,
            |arrays, cxs| {
                let run = arrays.run;
                let (items, len) = arrays
                    .floats
                    .copy(run, 0, cxs, |s| &s.float_arrays)
                    .expect("a copy");
                assert_eq!(len, 3);
                for (m, i) in [(0, 0), (4, 2), (2, 1)] {
                    assert_eq!(item(items, i, m), (10 * m + i) as f32);
                }
                // Read again: the same copy, written through.
                let (written, _) = arrays.floats.copied(run, 0).expect("copied");
                assert_eq!(written.cast_const(), items);
                arrays.forget(Elem::Float, 0);
                assert!(arrays.floats.copied(run, 0).is_none(), "forgotten");
                // Made again in the room it had.
                let (again, _) = arrays
                    .floats
                    .copy(run, 0, cxs, |s| &s.float_arrays)
                    .expect("a copy");
                assert_eq!(again, items);
                // A new run has none.
                arrays.begin(cxs[0].slots);
                assert!(arrays.floats.copied(arrays.run, 0).is_none(), "a new run");
            },
        );
    }

    /// The length of the copy a run makes of float array 0 of `n` members whose arrays are
    /// `lens(m)` long, if it makes one (and when it does not, it has none to write into).
    fn copy_len(n: usize, lens: impl Fn(usize) -> usize) -> Option<usize> {
        let mut len = None;
        with_batch(n, lens, |arrays, cxs| {
            let run = arrays.run;
            len = arrays.floats.copy(run, 0, cxs, |s| &s.float_arrays);
            let len = len.map(|(_, len)| len);
            assert_eq!(arrays.floats.copied(run, 0).map(|(_, len)| len), len);
        });
        len.map(|(_, len)| len)
    }

    #[test]
    fn arrays_of_lengths_apart_or_past_the_room_are_not_copied() {
        assert_eq!(copy_len(4, |m| 2 + m % 2), None, "lengths apart");
        assert_eq!(copy_len(3, |_| ELEMENTS + 1), None, "past the room");
        assert_eq!(copy_len(3, |_| ELEMENTS), Some(ELEMENTS), "the whole room");
        assert_eq!(copy_len(2, |_| 0), Some(0), "empty arrays");
    }

    #[test]
    fn the_run_count_coming_round_leaves_no_copy_behind() {
        with_batch(
            2,
            |_| 1,
            |arrays, cxs| {
                arrays.run = u32::MAX - 1;
                arrays.begin(cxs[0].slots);
                let run = arrays.run;
                assert_eq!(run, u32::MAX);
                assert!(
                    arrays
                        .floats
                        .copy(run, 0, cxs, |s| &s.float_arrays)
                        .is_some()
                );
                arrays.begin(cxs[0].slots);
                assert_eq!(arrays.run, 1, "0 is skipped");
                // An entry of run 1 from before would pass; the count cleared them all.
                assert!(arrays.floats.copied(1, 0).is_none());
                assert!(arrays.floats.copied(u32::MAX, 0).is_none());
            },
        );
    }

    /// The executor tells the copies of every write of an array variable by a handler
    /// (`execute!`'s `$forget`): at operand 0 for `ArraySetAt`, `ArrayAdd` and
    /// `ArrayReset`, at operand 1 for a `Copy`, at operand 3 for a `Select` and
    /// `FindBones`. Any other op that writes an array of an
    /// element type that is copied would leave a stale copy.
    #[test]
    fn the_ops_that_write_arrays_are_the_ones_the_executor_tells() {
        for op in crate::tests::every_op() {
            // An op with no layout is never emitted.
            let Some(layout) = op.operands() else {
                continue;
            };
            let written: Vec<usize> = (0..layout.len())
                .filter(|&k| {
                    matches!(
                        layout[k],
                        Operand::Slot(ValueType::Array(_), Access::Write | Access::ReadWrite)
                    )
                })
                .collect();
            let told = match op {
                Op::ArraySetAt(_) | Op::ArrayAdd(_) | Op::ArrayReset(_) => vec![0],
                Op::Copy(ValueType::Array(_)) => vec![1],
                Op::Select(ValueType::Array(_)) | Op::FindBones => vec![3],
                _ => vec![],
            };
            assert_eq!(written, told, "{op:?}");
        }
    }
}
