//! The ops that read or write each member's own arrays or pose, run for a whole batch with
//! their operands fetched once ([`run_per_member`]).
//!
//! While a batch is at one instruction, the executor's handlers run member by member: each
//! member's run fetches the instruction's operands again and works out where its slots
//! are, one slot after another. For an op with half a dozen operands that is most of the
//! work. The ops here find every operand's block of lanes ([`crate::lanes`]) once, then
//! visit the members, each with its own arrays and pose: the same element functions as
//! the handlers ([`array_get`], [`array_set`], [`bone_transform`], [`parent_of`]), on the
//! same values, in the same order for each member, so the results are the handlers', bit
//! for bit. A read fused with a `BreakTransform` (of its result, as the compiler fuses
//! them) runs for every member first, then the break for the whole batch
//! ([`break_transforms`]): a member's break reads only its own lane, which no other
//! member's read writes, and the reads read none of the break's outputs. A for-each loop's
//! step moves the whole batch at once when its members agree ([`for_each_next`]).
//!
//! Two kinds of op go further, with one piece of work for the whole batch: the traces ask
//! the world once for every member ([`sphere_traces`], [`line_traces`]), and the two-bone
//! IK solves the members' chains together on lanes of its own ([`two_bone_iks`]). The
//! traces take the members' ends to world space and the world's hits back to rig space
//! for every lane at once, one array per coordinate, and ask the world in that layout
//! ([`batch_traces`], [`hits_in_rig_space`], on x86-64: [`COLUMNS_MATCH_GLAM`]), with
//! glam's operations in glam's order. Their answers too are the handlers', bit for bit. A
//! read of the rest pose that every member makes of the same bone of one skeleton is made
//! once ([`shared_rest`]).
//!
//! They run only on lanes (slot `k` of member `m` at item `k * BATCH + m`), with the whole
//! batch at the instruction; anywhere else the handlers do the work.

// Slots are read and written through the lanes' base pointers, as in `lanes`.
#![allow(unsafe_code)]

use crate::array_lanes::ArrayLanes;
use crate::exec::{
    BATCH, Bases, Ctx, array_get, array_set, axes_key, bone, bone_transform, parent_of, read_hit,
    trace_ends, trace_miss, trace_outputs,
};
use crate::lanes::{Uniform, block, break_transforms};
use glam::{Quat, Vec3};
use std::sync::Arc;
use strider_core::{HitColumns, TRACE_COLUMNS, TraceColumns, Transform, WorldQuery};
use strider_nodes::kernels::two_bone_ik::{
    BoneAxes, ChainInput, ChainLanes, LANES_MATCH_GLAM, Pole, TwoBoneIk,
};
use strider_nodes::{Elem, Op};

/// Member 0's item of the block of [`BATCH`] lanes of slot `slot` of the array at `base`;
/// member `m`'s is `m` items on.
#[inline(always)]
fn item0<T>(base: *mut T, slot: u32) -> *mut T {
    block(base, slot).cast()
}

/// Runs `op` (operands `o`) for each of the batch's `members` in order, on the lanes whose
/// member 0 items start at `lane0`, when it is one of the ops that read an element of a
/// member's array (`ArrayAt` of any element type but bones, alone or followed by
/// `BreakTransform`), write one (`ArraySetAt`, the same types), read a bone's transform
/// (`GetTransform`, alone or followed by `BreakTransform`) or find a bone's parent
/// (`GetParent`, bone slots to bone slots); returns true. A fused
/// `BreakTransform` runs after every member's read, on all the lanes at once. Returns
/// false, doing nothing, for every other op.
///
/// # Safety
/// `op` and `o` must be an instruction of a program built by
/// [`ProgramBuilder::finish`](crate::ProgramBuilder::finish) (with its operand window);
/// `lane0` the bases of [`crate::lanes::Lanes`] (stride [`BATCH`]) loaded from `members`
/// for that program's slots, and `arrays` their copies of array variables (each copy
/// holds what the members' arrays hold); `members` the batch (at most [`BATCH`]), each
/// with that program's slots.
#[inline(never)]
pub(crate) unsafe fn run_per_member(
    op: Op,
    o: &[u32],
    lane0: &Bases,
    arrays: &mut ArrayLanes,
    members: &mut [Ctx<'_>],
) -> bool {
    // Taken by reference: a copy of the six pointers, made for every call, cost more than
    // the few the op reads.
    let lane0 = *lane0;
    debug_assert!(members.len() <= BATCH, "a batch has at most BATCH members");
    // Member 0's item of slot operand `$k` of scalar array `$a`.
    macro_rules! lane {
        ($a:ident, $k:expr) => {
            item0(lane0.$a, o[$k])
        };
    }
    // Runs `$m!(lanes, arrays, default)` for scalar element type `$e` (the lane array of its
    // slots, the slots' field of its array variables, its default); bones, whose slots are
    // not in the lanes, are left to the handlers.
    macro_rules! scalar_elem {
        ($e:expr, $m:ident) => {
            match $e {
                Elem::Bool => $m!(bools, bool_arrays, false),
                Elem::Int => $m!(ints, int_arrays, 0),
                Elem::Float => $m!(floats, float_arrays, 0.0),
                Elem::Vec3 => $m!(vec3s, vec3_arrays, Vec3::ZERO),
                Elem::Quat => $m!(quats, quat_arrays, Quat::IDENTITY),
                Elem::Transform => $m!(transforms, transform_arrays, Transform::IDENTITY),
                Elem::Bone => return false,
            }
        };
    }
    // `ArrayAt` (operands: array, index, element) of element type `$sc` (arrays `$ar`,
    // default `$zero`): from the batch's copy of the array, made at its first read
    // ([`crate::array_lanes`]), or member by member when it has none.
    macro_rules! array_at {
        ($sc:ident, $ar:ident, $zero:expr) => {{
            let (array, index, out) = (o[0] as usize, lane!(ints, 1), lane!($sc, 2));
            let run = arrays.run;
            match arrays.$sc.copy(run, array, members, |s| s.$ar.as_slice()) {
                Some((items, len)) => {
                    // SAFETY: as above; a block is `BATCH` items.
                    let indices = unsafe { &*index.cast::<[i32; BATCH]>() };
                    let first = indices[0] as u32 as usize;
                    if members.len() == BATCH && first < len && Uniform::uniform(indices) {
                        // One element for the whole batch (a loop's counter): its block
                        // of the copy is laid out as a slot's block.
                        // SAFETY: the copy holds `len` elements of `BATCH` items each,
                        // in memory of its own (not the lanes'): the two blocks are apart.
                        unsafe {
                            std::ptr::copy_nonoverlapping(items.add(first * BATCH), out, BATCH);
                        }
                    } else {
                        let zero = $zero;
                        for m in 0..members.len() {
                            // SAFETY: as above; `i < len` is checked (a negative index is
                            // a large unsigned one). The index is read before the
                            // element is written (they may share a slot).
                            unsafe {
                                let i = *index.add(m) as u32 as usize;
                                let from = if i < len {
                                    items.add(i * BATCH + m)
                                } else {
                                    &zero
                                };
                                *out.add(m) = *from;
                            }
                        }
                    }
                }
                None => {
                    for (m, cx) in members.iter().enumerate() {
                        // SAFETY: as above; every member has the program's array
                        // variables (its slots are the program's initial ones), and operand
                        // 0 names one of them (`ProgramBuilder::finish` checks every array
                        // operand). The index is read before the element is written.
                        unsafe {
                            let array = cx.slots.$ar.get_unchecked(array);
                            *out.add(m) = array_get(array, *index.add(m), &$zero);
                        }
                    }
                }
            }
        }};
    }
    // `ArraySetAt` (operands: array, index, element); the default is not needed. The
    // batch's copy of the array, if it has one, is written too.
    macro_rules! array_set_at {
        ($sc:ident, $ar:ident, $zero:expr) => {{
            let (array, index, value) = (o[0] as usize, lane!(ints, 1), lane!($sc, 2));
            for (m, cx) in members.iter_mut().enumerate() {
                // SAFETY: as above; the array as in `array_at!`.
                unsafe {
                    let (i, value) = (*index.add(m), *value.add(m));
                    array_set(cx.slots.$ar.get_unchecked_mut(array), i, value);
                }
            }
            if let Some((items, len)) = arrays.$sc.copied(arrays.run, array) {
                for m in 0..members.len() {
                    // SAFETY: as in `array_at!`; each member's array has `len` elements, so
                    // the copy changes where the member's array did.
                    unsafe {
                        let i = *index.add(m) as u32 as usize;
                        if i < len {
                            *items.add(i * BATCH + m) = *value.add(m);
                        }
                    }
                }
            }
        }};
    }
    // `GetTransform` (operands: bone, space, initial, result).
    macro_rules! get_transform {
        () => {{
            let (bone, space, initial, out) = (
                o[0] as usize,
                lane!(ints, 1),
                lane!(bools, 2),
                lane!(transforms, 3),
            );
            // Member `m`'s read, its space and pose given.
            let read = |m: usize, cx: &mut Ctx<'_>, space: i32, initial: bool| {
                let x = bone_transform(cx.pose, cx.slots.bones[bone], space, initial);
                // SAFETY: as above.
                unsafe { *out.add(m) = x };
            };
            // SAFETY: as above; a block is `BATCH` items, and nothing writes these two
            // blocks while the views are held (the reads write the result's block and the
            // poses only).
            let (spaces, initials) = unsafe {
                (
                    &*space.cast::<[i32; BATCH]>(),
                    &*initial.cast::<[bool; BATCH]>(),
                )
            };
            if members.len() == BATCH && Uniform::uniform(spaces) && Uniform::uniform(initials) {
                // One space and pose for the batch (as constants give): the choice is made
                // once, each loop reads one of the four.
                let (space, initial) = (spaces[0], initials[0]);
                // A loop for each choice, its space and pose constants in it.
                macro_rules! read_each {
                    ($space:expr, $initial:expr) => {
                        for (m, cx) in members.iter_mut().enumerate() {
                            read(m, cx, $space, $initial);
                        }
                    };
                }
                let rest = if initial {
                    shared_rest(members, bone, space)
                } else {
                    None
                };
                match (space == 0, initial) {
                    // Every member reads the same transform of the rest pose: read once.
                    // SAFETY: as above; a block is `BATCH` items.
                    _ if let Some(x) = rest => unsafe {
                        *out.cast::<[Transform; BATCH]>() = [x; BATCH];
                    },
                    (true, false) => read_each!(0, false),
                    (false, false) => read_each!(space, false),
                    (true, true) => read_each!(0, true),
                    (false, true) => read_each!(space, true),
                }
            } else {
                for (m, cx) in members.iter_mut().enumerate() {
                    read(m, cx, spaces[m], initials[m]);
                }
            }
        }};
    }
    match op {
        Op::ArrayAt(e) => scalar_elem!(e, array_at),
        // The fused reads, then their breaks for the whole batch: a member's break reads
        // only its own lane of the transform, and the reads read none of the parts' slots
        // (they are of other types), so the order across members does not matter.
        Op::ArrayAtBreakTransform => {
            array_at!(transforms, transform_arrays, Transform::IDENTITY);
            // SAFETY: the caller's contract; the break's operands start at operand 3.
            unsafe { break_transforms(&o[3..], lane0) };
        }
        Op::ArraySetAt(e) => scalar_elem!(e, array_set_at),
        Op::GetTransform => get_transform!(),
        Op::GetTransformBreakTransform => {
            get_transform!();
            // SAFETY: as above; the break's operands start at operand 4.
            unsafe { break_transforms(&o[4..], lane0) };
        }
        Op::GetParent => {
            // Operands: bone, parent (bone slots, each member's own).
            let (child, parent) = (o[0] as usize, o[1] as usize);
            for cx in members.iter_mut() {
                cx.slots.bones[parent] = parent_of(cx.pose, cx.slots.bones[child]);
            }
        }
        _ => return false,
    }
    true
}

/// The transform every one of `members` reads of the bone in bone slot `bone`, in the
/// rest pose, in `space` (0 global, else local), as [`bone_transform`] reads it: `None`
/// unless they all hold the same bone (or all none) of one skeleton (the same `Arc`), each
/// then reading the same transform.
#[inline(always)]
fn shared_rest(members: &mut [Ctx<'_>], bone: usize, space: i32) -> Option<Transform> {
    let (first, others) = members.split_first_mut()?;
    let (b, skeleton) = (first.slots.bones[bone], first.pose.skeleton());
    let shared = others
        .iter()
        .all(|cx| cx.slots.bones[bone] == b && Arc::ptr_eq(cx.pose.skeleton(), skeleton));
    #[cfg(test)]
    tests::RESTS_SHARED.with(|n| n.set(n.get() + usize::from(shared)));
    shared.then(|| bone_transform(first.pose, b, space, true))
}

/// `ForEachNext(elem)` (operands: array, counter; element, index, count; the loop's end)
/// for a whole batch whose members all step on together or all leave the loop together:
/// `Some(true)` when every member's counter is within its array (each member's element,
/// index, count and counter are written as the handler writes them), `Some(false)` when
/// every member's is outside it (nothing is written: the batch jumps to the loop's end),
/// and `None`, with nothing written, when the members part ways (the handler runs each).
/// A bone array's element goes to the member's own bone slot, as in the handler. The
/// lengths and elements come from the batch's copy of the array (`arrays`, made at its
/// first read, [`crate::array_lanes`]) when it has one, else from each member's array.
///
/// # Safety
/// As [`run_per_member`], with `o` a `ForEachNext(elem)`'s operands.
#[inline(never)]
pub(crate) unsafe fn for_each_next(
    elem: Elem,
    o: &[u32],
    lane0: &Bases,
    arrays: &mut ArrayLanes,
    members: &mut [Ctx<'_>],
) -> Option<bool> {
    let lane0 = *lane0;
    let array = o[0] as usize;
    let (counter, index, count) = (
        item0(lane0.ints, o[1]),
        item0(lane0.ints, o[3]),
        item0(lane0.ints, o[4]),
    );
    // Whether every member steps on (true) or every member leaves (false); `None` if they
    // part ways. Each member's array length is its own.
    macro_rules! agree {
        ($ar:ident) => {{
            let mut on = 0usize;
            for (m, cx) in members.iter().enumerate() {
                // SAFETY: as in `run_per_member`: operand 0 names one of the program's
                // array variables, which every member has; `m < BATCH`.
                let (len, at) =
                    unsafe { (cx.slots.$ar.get_unchecked(array).len(), *counter.add(m)) };
                on += usize::from(at >= 0 && (at as usize) < len);
            }
            match on {
                0 => return Some(false),
                n if n == members.len() => {}
                _ => return None,
            }
        }};
    }
    // Every member steps on: its counter read, then its element, index, count and counter
    // written, in the handler's order; from the batch's copy of the array (column `$col`)
    // when it has one.
    macro_rules! step {
        ($col:ident, $ar:ident, |$m:ident, $cx:ident, $x:ident| $write:expr) => {{
            let run = arrays.run;
            if let Some((items, len)) = arrays.$col.copy(run, array, members, |s| s.$ar.as_slice())
            {
                // SAFETY: as below; `m < BATCH`.
                let within = |m: usize| unsafe { (*counter.add(m) as u32 as usize) < len };
                match (0..members.len()).filter(|&m| within(m)).count() {
                    0 => return Some(false),
                    n if n == members.len() => {}
                    _ => return None,
                }
                for ($m, $cx) in members.iter_mut().enumerate() {
                    // SAFETY: as below; the counter is within the copy's `len` elements
                    // (checked above).
                    unsafe {
                        let at = *counter.add($m);
                        let $x = *items.add(at as usize * BATCH + $m);
                        $write;
                        *index.add($m) = at;
                        *count.add($m) = len as i32;
                        *counter.add($m) = at + 1;
                    }
                }
                return Some(true);
            }
            agree!($ar);
            for ($m, $cx) in members.iter_mut().enumerate() {
                // SAFETY: as above; the counter is within the array (checked above), and
                // `$write` indexes anything else it writes with a check.
                unsafe {
                    let at = *counter.add($m);
                    let items = $cx.slots.$ar.get_unchecked(array);
                    let (len, $x) = (items.len() as i32, *items.get_unchecked(at as usize));
                    $write;
                    *index.add($m) = at;
                    *count.add($m) = len;
                    *counter.add($m) = at + 1;
                }
            }
        }};
    }
    // The element into its lane of operand 2's block of scalar array `$sc`.
    macro_rules! into_lane {
        ($sc:ident, $ar:ident) => {{
            let element = item0(lane0.$sc, o[2]);
            step!($sc, $ar, |m, _cx, x| *element.add(m) = x)
        }};
    }
    match elem {
        Elem::Bool => into_lane!(bools, bool_arrays),
        Elem::Int => into_lane!(ints, int_arrays),
        Elem::Float => into_lane!(floats, float_arrays),
        Elem::Vec3 => into_lane!(vec3s, vec3_arrays),
        Elem::Quat => into_lane!(quats, quat_arrays),
        Elem::Transform => into_lane!(transforms, transform_arrays),
        Elem::Bone => {
            // Bone slots are indexed with a check, as in the handler.
            let element = o[2] as usize;
            step!(bones, bone_arrays, |m, cx, x| cx.slots.bones[element] = x)
        }
    }
    Some(true)
}

/// `LineTrace` (operands: start, end; hit, point, normal, distance) for a whole batch
/// with one question to the world
/// ([`WorldQuery::line_traces_in_columns`](strider_core::WorldQuery::line_traces_in_columns)),
/// as [`sphere_traces`] for sphere traces.
///
/// # Safety
/// As [`run_per_member`], with `o` a `LineTrace`'s operands.
#[inline(always)]
pub(crate) unsafe fn line_traces(
    o: &[u32],
    lane0: Bases,
    world: Option<&dyn WorldQuery>,
    frames: &mut FrameColumns,
    members: &[Ctx<'_>],
) -> bool {
    // SAFETY: the caller's contract; a line trace's outputs start at operand 2.
    unsafe {
        batch_traces(o, 2, lane0, world, frames, members, |w, traces, n, hits| {
            w.line_traces_in_columns(traces, n, hits);
        })
    }
}

/// `SphereTrace` (operands: start, end, radius; hit, point, normal, distance) for a whole
/// batch with one question to the world
/// ([`WorldQuery::sphere_traces_in_columns`](strider_core::WorldQuery::sphere_traces_in_columns)),
/// which answers each member's trace as its own `sphere_trace` would: every member's slots
/// end as the handler leaves them. `world` is the world every member traces
/// ([`shared_world`]); `None`, when they do not all trace the same one, returns false and
/// does nothing (each then asks its own, through the handler). Inlined into the batch
/// loop, so that it runs on the loop's machine code (`crate::batch_code`).
///
/// # Safety
/// As [`run_per_member`], with `o` a `SphereTrace`'s operands.
#[inline(always)]
pub(crate) unsafe fn sphere_traces(
    o: &[u32],
    lane0: Bases,
    world: Option<&dyn WorldQuery>,
    frames: &mut FrameColumns,
    members: &[Ctx<'_>],
) -> bool {
    let radius = item0(lane0.floats, o[2]);
    // SAFETY: the caller's contract; a sphere trace's outputs start at operand 3, and its
    // radius (operand 2) is a slot of the program's lanes, read below for `m < BATCH`.
    unsafe {
        batch_traces(o, 3, lane0, world, frames, members, |w, traces, n, hits| {
            // Each radius made 0 where it is below 0 or NaN, as `trace_query` makes it;
            // every lane, as the ends.
            for m in 0..BATCH {
                traces.radius[m] = (*radius.add(m)).max(0.0);
            }
            w.sphere_traces_in_columns(traces, n, hits);
        })
    }
}

/// `TwoBoneIK` (operands: bones A, B and effector; target; primary and secondary axis;
/// pole, pole kind; weight; stretch on, start, max; effector rotation; reached, distance)
/// for a whole batch whose members share their local axes: the chains the IK solves
/// without a fallback are solved together on lanes
/// ([`ChainLanes`], through [`solve_chains`]), the others one by one as the handler solves
/// them. Either way each member's pose and slots end as the handler leaves them, bit for
/// bit. Returns false, doing nothing, when the members' axes differ or cannot be solved on
/// lanes, or on a build where the lanes' arithmetic is not glam's
/// ([`LANES_MATCH_GLAM`]): the handler then solves each member. Out of the batch loop, as
/// [`run_per_member`]; the lanes' arithmetic runs on the loop's machine code all the same
/// ([`solve_chains`]).
///
/// # Safety
/// As [`run_per_member`], with `o` a `TwoBoneIK`'s operands.
#[inline(never)]
pub(crate) unsafe fn two_bone_iks(o: &[u32], lane0: &Bases, members: &mut [Ctx<'_>]) -> bool {
    let lane0 = *lane0;
    let (primary, secondary) = (item0(lane0.vec3s, o[4]), item0(lane0.vec3s, o[5]));
    // SAFETY: slots of the program's lanes (the caller's contract), `m < BATCH`.
    let (p0, s0) = unsafe { (*primary, *secondary) };
    let key = axes_key(p0, s0);
    let shared = (1..members.len()).all(|m| {
        // SAFETY: as above.
        let (p, s) = unsafe { (*primary.add(m), *secondary.add(m)) };
        axes_key(p, s) == key
    });
    if !(shared && LANES_MATCH_GLAM) {
        return false;
    }
    let axes = BoneAxes::new(p0, s0);
    if !ChainLanes::<BATCH>::solves_with(&axes) {
        return false;
    }
    CHAIN_LANES.with(|cell| {
        // The thread's lanes, taken for this batch and given back after it (made on the
        // thread's first IK).
        let mut lanes = cell.take().unwrap_or_default();
        lanes.unset_all();
        // SAFETY: the caller's contract.
        unsafe { solve_batch(o, lane0, members, (p0, s0), &axes, &mut lanes) };
        cell.set(Some(lanes));
    });
    true
}

thread_local! {
    /// Each thread's chain lanes, reused by every batch's IK (a `ChainLanes` is a few
    /// kilobytes, which filling anew for each IK costs more than the lanes it fills).
    static CHAIN_LANES: std::cell::Cell<Option<Box<ChainLanes<BATCH>>>> =
        const { std::cell::Cell::new(None) };
}

/// Makes the calling thread's chain lanes, as its first batch's IK would (they are kept
/// after that); nothing when it has them.
pub(crate) fn reserve_chain_lanes() {
    CHAIN_LANES.with(|cell| {
        let lanes = cell.take().unwrap_or_default();
        cell.set(Some(lanes));
    });
}

/// [`two_bone_iks`]' chains read, solved on `lanes` and written back, once the members'
/// `axes` (from `(p0, s0)`) are known to be shared and solvable on lanes.
///
/// # Safety
/// As [`two_bone_iks`].
#[inline(always)]
unsafe fn solve_batch(
    o: &[u32],
    lane0: Bases,
    members: &mut [Ctx<'_>],
    (p0, s0): (Vec3, Vec3),
    axes: &BoneAxes,
    lanes: &mut ChainLanes<BATCH>,
) {
    let mut chains = [None; BATCH];
    for (m, cx) in members.iter_mut().enumerate() {
        // Written out: `array::map` leaves a call behind here.
        let bone_of = |k: u32| bone(cx.pose, cx.slots.bones[k as usize]);
        let (Some(a), Some(b), Some(c)) = (bone_of(o[0]), bone_of(o[1]), bone_of(o[2])) else {
            continue;
        };
        chains[m] = Some([a, b, c]);
        // Repeated bones are the one-chain solve's to turn down.
        if a != b && b != c && a != c {
            let globals = [cx.pose.global(a), cx.pose.global(b), cx.pose.global(c)];
            let parent = cx.pose.skeleton().parent(a).map(|p| cx.pose.global(p));
            // SAFETY: as above.
            let input = unsafe { chain_input(o, lane0, m, (p0, s0), globals, parent) };
            lanes.set(m, &input);
        }
    }
    solve_chains(lanes, axes);
    let (reached, distance) = (item0(lane0.bools, o[13]), item0(lane0.floats, o[14]));
    for (m, cx) in members.iter_mut().enumerate() {
        let report = match (chains[m], lanes.solution(m)) {
            (Some(bones), Some(answer)) => {
                #[cfg(test)]
                tests::SOLVED_ON_LANES.with(|solved| solved.set(solved.get() + 1));
                let limb = answer.locals.is_some_and(|locals| {
                    cx.pose.set_chain_with_locals(bones, answer.globals, locals)
                });
                if !limb {
                    cx.pose.set_chain_globals(bones, answer.globals);
                }
                Some(answer.report)
            }
            (Some([a, b, c]), None) => {
                // SAFETY: as above; only earlier members' items have been written.
                let x =
                    unsafe { chain_input(o, lane0, m, (p0, s0), [Transform::IDENTITY; 3], None) };
                Some(x.ik.solve_with_axes(axes, cx.pose, a, b, c, x.target))
            }
            (None, _) => None,
        };
        let (hit, miss) = report.map_or((false, f32::INFINITY), |r| {
            (r.reached, r.distance_to_target)
        });
        // SAFETY: as above. Each member's items are its own, and a member's outputs are
        // written after its inputs were read (again, for a chain solved alone).
        unsafe {
            *reached.add(m) = hit;
            *distance.add(m) = miss;
        }
    }
}

/// Member `m`'s `TwoBoneIK` settings and target (operands as in [`two_bone_iks`]) read off
/// the lanes, with the batch's `axes` (primary, secondary), the chain's current `globals`
/// and bone A's parent's.
///
/// # Safety
/// As [`run_per_member`], with `o` a `TwoBoneIK`'s operands and `m < BATCH`.
#[inline(always)]
unsafe fn chain_input(
    o: &[u32],
    lane0: Bases,
    m: usize,
    (primary_axis, secondary_axis): (Vec3, Vec3),
    globals: [Transform; 3],
    parent: Option<Transform>,
) -> ChainInput {
    // SAFETY: the caller's contract: slots of the program's lanes, `m < BATCH`.
    unsafe {
        let pole = *item0(lane0.vec3s, o[6]).add(m);
        ChainInput {
            ik: TwoBoneIk {
                primary_axis,
                secondary_axis,
                pole: if *item0(lane0.ints, o[7]).add(m) == 1 {
                    Pole::Location(pole)
                } else {
                    Pole::Direction(pole)
                },
                weight: *item0(lane0.floats, o[8]).add(m),
                stretch: (*item0(lane0.bools, o[9]).add(m)).then_some((
                    *item0(lane0.floats, o[10]).add(m),
                    *item0(lane0.floats, o[11]).add(m),
                )),
                set_effector_rotation: *item0(lane0.bools, o[12]).add(m),
            },
            globals,
            target: *item0(lane0.transforms, o[3]).add(m),
            parent,
        }
    }
}

/// [`ChainLanes::solve`] and [`ChainLanes::relate`] on the machine code the batch loop
/// runs (`crate::batch_code`): the lanes' loops eight floats at a time with AVX2. Kept out
/// of the batch loop, whose code is large enough already, and each in a function of its
/// own: compiled as one, the compiler leaves part of their loops one float at a time.
#[inline(never)]
fn solve_chains(lanes: &mut ChainLanes<BATCH>, axes: &BoneAxes) {
    #[cfg(target_arch = "x86_64")]
    if crate::batch_code::batch_code() == crate::batch_code::BatchCode::Avx2 {
        /// `lanes.solve(axes)` compiled for AVX2.
        #[target_feature(enable = "avx2")]
        #[inline(never)]
        fn solve_avx2(lanes: &mut ChainLanes<BATCH>, axes: &BoneAxes) {
            lanes.solve(axes);
        }
        /// `lanes.relate()` compiled for AVX2.
        #[target_feature(enable = "avx2")]
        #[inline(never)]
        fn relate_avx2(lanes: &mut ChainLanes<BATCH>) {
            lanes.relate();
        }
        // SAFETY: the processor has AVX2 (`batch_code` checked it).
        unsafe {
            solve_avx2(lanes, axes);
            relate_avx2(lanes);
        }
        return;
    }
    /// `lanes.solve(axes)` on the baseline machine code.
    #[inline(never)]
    fn solve(lanes: &mut ChainLanes<BATCH>, axes: &BoneAxes) {
        lanes.solve(axes);
    }
    solve(lanes, axes);
    lanes.relate();
}

/// The world every one of `members` traces, `None` when they do not all trace the same
/// one (or there are none): found once for a batch, rather than at each of its traces. The
/// same world is the same object and type: two worlds of no size may share an address.
pub(crate) fn shared_world<'w>(members: &[Ctx<'w>]) -> Option<&'w dyn WorldQuery> {
    let world = members.first()?.world;
    members
        .iter()
        .all(|cx| std::ptr::eq(cx.world, world))
        .then_some(world)
}

/// A trace instruction (operands: start, end, then from `outs` on: hit, point, normal,
/// distance) for the whole batch: every member's ends taken to world space, laid out in
/// columns, and asked of the world at once by `ask` (which first writes what else the
/// trace asks, a sphere's radii), and each answer mapped back to the member's slots as the
/// handler maps it.
/// Returns false, doing nothing, when there is no `world` the members share
/// ([`shared_world`]). `world` must be `shared_world(members)`, and `frames` new or filled
/// from these `members`, for the answers to be the handler's.
///
/// # Safety
/// As [`run_per_member`], with `o` a trace's operands, its outputs from `outs` on.
#[inline(always)]
unsafe fn batch_traces(
    o: &[u32],
    outs: usize,
    lane0: Bases,
    world: Option<&dyn WorldQuery>,
    frames: &mut FrameColumns,
    members: &[Ctx<'_>],
    ask: impl Fn(&dyn WorldQuery, &mut TraceColumns, usize, &mut HitColumns),
) -> bool {
    // One question to the world for the batch (its members share it in a crowd's
    // batch; else each asks its own, as the handler does).
    let Some(world) = world else {
        return false;
    };
    let (start, end) = (item0(lane0.vec3s, o[0]), item0(lane0.vec3s, o[1]));
    let n = members.len();
    let frames = frames.of(members);
    let mut traces = TraceColumns::default();
    if COLUMNS_MATCH_GLAM {
        // Every lane, those past the members too (whose traces the world does not
        // answer): a loop of fixed length computes several lanes per instruction.
        for m in 0..BATCH {
            // SAFETY: slots of the program's lanes (the caller's contract), `m < BATCH`.
            let (s, e) = unsafe { (*start.add(m), *end.add(m)) };
            let (s, e) = (
                point_through(&frames.to_world, m, s),
                point_through(&frames.to_world, m, e),
            );
            for c in 0..3 {
                (traces.start[c][m], traces.end[c][m]) = (s[c], e[c]);
            }
        }
    } else {
        for (m, cx) in members.iter().enumerate() {
            // SAFETY: as above.
            let (s, e) = unsafe { (*start.add(m), *end.add(m)) };
            traces.set_line(m, trace_ends(&cx.to_world_matrix, s, e));
        }
    }
    let mut answers = HitColumns::default();
    ask(world, &mut traces, n, &mut answers);
    let (hit, point, normal, distance) = (
        item0(lane0.bools, o[outs]),
        item0(lane0.vec3s, o[outs + 1]),
        item0(lane0.vec3s, o[outs + 2]),
        item0(lane0.floats, o[outs + 3]),
    );
    if !COLUMNS_MATCH_GLAM {
        for (m, cx) in members.iter().enumerate() {
            // SAFETY: as above. A member's outputs, which may share its inputs' slots, are
            // written after its ends are read, and other members' items lie apart.
            let (s, e) = unsafe { (*start.add(m), *end.add(m)) };
            let outs = trace_outputs(read_hit(&answers.get(m)), s, e, &cx.from_world_matrix);
            // SAFETY: as above.
            unsafe { (*hit.add(m), *point.add(m), *normal.add(m), *distance.add(m)) = outs };
        }
        return true;
    }
    let found = hits_in_rig_space(&answers, &frames.from_world);
    for m in 0..n {
        // SAFETY: as above; the ends are read (for a miss) before the member's outputs,
        // which may share their slots, are written.
        unsafe {
            let outs = match found.hit[m] {
                true => (
                    true,
                    Vec3::new(found.point[0][m], found.point[1][m], found.point[2][m]),
                    Vec3::new(found.normal[0][m], found.normal[1][m], found.normal[2][m]),
                    found.distance[m],
                ),
                false => trace_miss(*start.add(m), *end.add(m)),
            };
            (*hit.add(m), *point.add(m), *normal.add(m), *distance.add(m)) = outs;
        }
    }
    true
}

/// Whether the columns compute with glam's operations in glam's order, so that their
/// results are the handler's bit for bit: the ends taken to world space in
/// [`batch_traces`] ([`trace_ends`]) and the hits mapped back in [`hits_in_rig_space`]
/// ([`trace_outputs`]). It holds for glam's SSE2 code, whose products and sums are rounded
/// one at a time, as the columns' are. Elsewhere each member takes its own ends and maps
/// its own answer.
const COLUMNS_MATCH_GLAM: bool = cfg!(target_arch = "x86_64");

// A batch's traces go to the world as one set of columns, lane for lane.
const _: () = assert!(TRACE_COLUMNS == BATCH);

/// Each member's `to_world_matrix` and `from_world_matrix`, one array per entry (the x, y
/// and z axes and the translation, x, y and z of each): read off a batch's members at its
/// first trace, for all of its traces ([`batch_traces`], [`hits_in_rig_space`]).
pub(crate) struct FrameColumns {
    /// Whether the entries hold the batch's matrices.
    filled: bool,
    /// The matrices from rig space to world space.
    to_world: [[f32; BATCH]; 12],
    /// The matrices from world space to rig space.
    from_world: [[f32; BATCH]; 12],
}

impl FrameColumns {
    /// None read yet.
    pub(crate) const fn new() -> Self {
        Self {
            filled: false,
            to_world: [[0.0; BATCH]; 12],
            from_world: [[0.0; BATCH]; 12],
        }
    }

    /// The matrices of `members` (the batch these columns are for), read on the first call.
    #[inline(always)]
    fn of(&mut self, members: &[Ctx<'_>]) -> &Self {
        if !self.filled {
            for (m, cx) in members.iter().enumerate() {
                put_matrix(&mut self.to_world, m, &cx.to_world_matrix);
                put_matrix(&mut self.from_world, m, &cx.from_world_matrix);
            }
            self.filled = true;
        }
        self
    }
}

/// Point `p` through lane `m`'s matrix of `entries` ([`put_matrix`]) as
/// `Affine3A::transform_point3` takes it, bit for bit where [`COLUMNS_MATCH_GLAM`]: x axis
/// times x, plus y axis times y, plus z axis times z, plus the translation, each product
/// and sum rounded in turn (the ends to world space, the hits back).
#[inline(always)]
fn point_through(entries: &[[f32; BATCH]; 12], m: usize, p: Vec3) -> [f32; 3] {
    let t = entries;
    std::array::from_fn(|c| ((t[c][m] * p.x + t[3 + c][m] * p.y) + t[6 + c][m] * p.z) + t[9 + c][m])
}

/// Writes matrix `a` into lane `m` of `entries` (x, y and z axes, then the translation).
#[inline(always)]
fn put_matrix(entries: &mut [[f32; BATCH]; 12], m: usize, a: &glam::Affine3A) {
    let columns = [
        a.matrix3.x_axis,
        a.matrix3.y_axis,
        a.matrix3.z_axis,
        a.translation,
    ];
    for (c, v) in columns.into_iter().enumerate() {
        for (k, x) in v.to_array().into_iter().enumerate() {
            entries[3 * c + k][m] = x;
        }
    }
}

/// The world's answers to a batch's traces, in rig space, one array per component.
struct FoundColumns {
    /// Whether the member's trace hit (an answer with every component finite).
    hit: [bool; BATCH],
    /// Point and unit normal, rig space (for a hit).
    point: [[f32; BATCH]; 3],
    normal: [[f32; BATCH]; 3],
    /// Distance travelled to the hit, as the world gave it.
    distance: [f32; BATCH],
}

/// The `answers` (world space) mapped to rig space by the members' matrices `from_world`
/// ([`FrameColumns`]) as [`trace_outputs`] maps a hit, every member at once: the point
/// through the matrix, the normal through its 3×3 part and normalised (zero when it has
/// no length), each product and sum in glam's order (`Mat3A * Vec3A`: x axis times x, plus
/// y axis times y, plus z axis times z; a length the square root of `(x² + y²) + z²`,
/// normalised by its reciprocal). A hit with a component that is not finite is a miss, as
/// [`read_hit`] reads it. Lanes past the batch's members mean nothing.
#[inline(always)]
fn hits_in_rig_space(answers: &HitColumns, from_world: &[[f32; BATCH]; 12]) -> FoundColumns {
    let (p, v, d) = (&answers.point, &answers.normal, &answers.distance);
    let f = from_world;
    let mut found = FoundColumns {
        hit: [false; BATCH],
        point: [[0.0; BATCH]; 3],
        normal: [[0.0; BATCH]; 3],
        distance: *d,
    };
    for k in 0..BATCH {
        let (x, y, z) = (p[0][k], p[1][k], p[2][k]);
        let (nx, ny, nz) = (v[0][k], v[1][k], v[2][k]);
        let finite = [x, y, z, nx, ny, nz, d[k]]
            .iter()
            .fold(true, |ok, c| ok & c.is_finite());
        found.hit[k] = answers.hit[k] & finite;
        [found.point[0][k], found.point[1][k], found.point[2][k]] =
            point_through(f, k, Vec3::new(x, y, z));
        let a = (f[0][k] * nx + f[3][k] * ny) + f[6][k] * nz;
        let b = (f[1][k] * nx + f[4][k] * ny) + f[7][k] * nz;
        let c = (f[2][k] * nx + f[5][k] * ny) + f[8][k] * nz;
        let rcp = 1.0 / ((a * a + b * b) + c * c).sqrt();
        let unit = rcp.is_finite() & (rcp > 0.0);
        let normal = [a * rcp, b * rcp, c * rcp].map(|x| if unit { x } else { 0.0 });
        [found.normal[0][k], found.normal[1][k], found.normal[2][k]] = normal;
    }
    found
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exec::step;
    use crate::lanes::{Copies, Lanes};
    use crate::slots::{ScalarLens, Slots};
    use std::sync::Arc;
    use strider_core::{
        Bone, BoneIndex, DebugDraw, LineQuery, Pose, Skeleton, SphereQuery, TraceHit,
    };
    use strider_nodes::{MAX_OPERANDS, ValueType};

    /// How many scalar slots of each type, and arrays of each element type, a member has.
    const SLOTS: usize = 8;

    thread_local! {
        /// How many chains `two_bone_iks` took from the lanes, so that a test can check
        /// that the lanes solved some.
        pub(super) static SOLVED_ON_LANES: std::cell::Cell<usize> =
            const { std::cell::Cell::new(0) };
        /// How many reads of the rest pose `shared_rest` found alike for the whole batch.
        pub(super) static RESTS_SHARED: std::cell::Cell<usize> =
            const { std::cell::Cell::new(0) };
    }

    /// A three-bone chain whose rest pose is turned, moved and scaled at every bone.
    fn chain() -> Arc<Skeleton> {
        chain_at_rest(|k| {
            Transform::new(
                Vec3::new(k, 2.0 * k, -k),
                Quat::from_rotation_z(0.3 * k),
                Vec3::splat(1.0 + 0.1 * k),
            )
        })
    }

    /// A three-bone chain, root, mid and tip, whose bone `k` (from 1) rests at `rest(k)`
    /// relative to its parent.
    fn chain_at_rest(rest: impl Fn(f32) -> Transform) -> Arc<Skeleton> {
        let bone = |name: &str, parent: Option<&str>, k: f32| Bone {
            name: name.to_string(),
            parent: parent.map(str::to_string),
            rest_local: rest(k),
        };
        Arc::new(
            Skeleton::new(vec![
                bone("root", None, 1.0),
                bone("mid", Some("root"), 2.0),
                bone("tip", Some("mid"), 3.0),
            ])
            .expect("valid skeleton"),
        )
    }

    /// Member `m`'s slots: bone slots that name each bone, none (-1) and one past the
    /// skeleton; indices in range, negative, one past the end and extreme; arrays of
    /// lengths 0 to 3 that differ from member to member.
    fn member_slots(m: usize) -> Slots {
        let x = |i: usize| (m * 7 + i * 3) as f32 * 0.25 - 2.0;
        let v = |i: usize| Vec3::new(x(i), x(i + 1), -x(i + 2));
        let q = |i: usize| Quat::from_rotation_x(x(i)) * Quat::from_rotation_y(0.5);
        let t = |i: usize| Transform::new(v(i), q(i), Vec3::splat(1.0 + i as f32));
        const INDICES: [i32; 8] = [0, 1, -1, 2, 3, i32::MIN, i32::MAX, 0];
        fn arrays<T>(m: usize, item: impl Fn(usize) -> T) -> Vec<Vec<T>> {
            (0..SLOTS)
                .map(|a| (0..(a + m) % 4).map(&item).collect())
                .collect()
        }
        Slots {
            bools: (0..SLOTS).map(|i| (m + i).is_multiple_of(3)).collect(),
            ints: (0..SLOTS)
                .map(|i| INDICES[(m + i) % INDICES.len()])
                .collect(),
            floats: (0..SLOTS).map(x).collect(),
            vec3s: (0..SLOTS).map(v).collect(),
            quats: (0..SLOTS).map(q).collect(),
            transforms: (0..SLOTS).map(|i| t(i + 10)).collect(),
            bones: (0..SLOTS).map(|i| [0, 1, 2, -1, 3][(m + i) % 5]).collect(),
            bool_arrays: arrays(m, |i| i % 2 == 1),
            int_arrays: arrays(m, |i| 10 * i as i32 + m as i32),
            float_arrays: arrays(m, x),
            vec3_arrays: arrays(m, v),
            quat_arrays: arrays(m, q),
            transform_arrays: arrays(m, t),
            ..Slots::default()
        }
    }

    /// Member `m`'s pose: moved from rest at one bone or another, so that some globals are
    /// stale when the op reads them.
    fn member_pose(m: usize) -> Pose {
        let mut pose = Pose::new(chain());
        let moved = Transform::new(Vec3::splat(m as f32), Quat::from_rotation_y(0.2), Vec3::ONE);
        pose.set_local(BoneIndex((m % 3) as u32), moved);
        pose
    }

    /// Runs `f` with contexts over `slots` and `poses`.
    fn with_contexts(slots: &mut [Slots], poses: &mut [Pose], f: impl FnOnce(&mut [Ctx<'_>])) {
        let mut draws: Vec<DebugDraw> = slots.iter().map(|_| DebugDraw::new(false)).collect();
        let mut cxs: Vec<Ctx<'_>> = slots
            .iter_mut()
            .zip(poses.iter_mut())
            .zip(&mut draws)
            .map(|((s, p), d)| Ctx::for_test(s, &[], p, d, 1.0 / 60.0))
            .collect();
        f(&mut cxs);
    }

    /// What `op` leaves in `n` members' slots and poses: run for the batch at once
    /// (`batch`) or by the handler on each member alone; `None` when the batch path does
    /// not take the op.
    fn run(op: Op, o: &[u32], n: usize, batch: bool) -> Option<(Vec<Slots>, Vec<Pose>)> {
        // SAFETY: the operands are slots below `SLOTS` of the lanes, and arrays and bone
        // slots below `SLOTS` of every member.
        let batched = |lane0: Bases, cxs: &mut [Ctx<'_>]| unsafe {
            run_per_member(op, o, &lane0, &mut no_copies(cxs), cxs)
        };
        let slots = (0..n).map(member_slots).collect();
        run_members(op, o, slots, batch.then_some(&batched))
    }

    /// A run's copies of the arrays of batch `cxs`, none made yet (the first read of an
    /// array makes its copy).
    fn no_copies(cxs: &[Ctx<'_>]) -> ArrayLanes {
        let mut arrays = ArrayLanes::default();
        arrays.begin(&*cxs[0].slots);
        arrays
    }

    /// A batch path under test: given the lanes loaded from the members, and the members,
    /// whether it took the op.
    type BatchRun<'f> = dyn Fn(Bases, &mut [Ctx<'_>]) -> bool + 'f;

    /// What `op` leaves in the members' `slots` and their poses: run for the batch at
    /// once by `batched` (given the lanes loaded from the members, and the members) or,
    /// without it, by the handler on each member alone; `None` when `batched` does not
    /// take the op. The operands must be slots below `SLOTS`.
    fn run_members(
        op: Op,
        o: &[u32],
        mut slots: Vec<Slots>,
        batched: Option<&BatchRun<'_>>,
    ) -> Option<(Vec<Slots>, Vec<Pose>)> {
        let mut poses: Vec<Pose> = (0..slots.len()).map(member_pose).collect();
        let mut ran = true;
        with_contexts(&mut slots, &mut poses, |cxs| match batched {
            Some(batched) => {
                let lens = ScalarLens([SLOTS; 6]);
                let mut lanes = Lanes::default();
                lanes.load(Copies::all(&lens), cxs);
                ran = batched(lanes.bases(), cxs);
                lanes.store(Copies::all(&lens), cxs);
            }
            None => {
                for cx in cxs.iter_mut() {
                    // SAFETY: the operands are slots below `SLOTS` of every member.
                    unsafe { step(op, o, cx, 1) };
                }
            }
        });
        ran.then_some((slots, poses))
    }

    /// Asserts that two runs left every member's slots and pose the same, bit for bit.
    fn same_members(a: &mut (Vec<Slots>, Vec<Pose>), b: &mut (Vec<Slots>, Vec<Pose>), what: &str) {
        let n = a.0.len();
        assert_eq!(n, b.0.len(), "{what}");
        for m in 0..n {
            assert!(
                a.0[m].bit_eq(&b.0[m]),
                "{what}: member {m} of {n}: slots differ"
            );
            assert!(
                same_pose(&mut a.1[m], &mut b.1[m]),
                "{what}: member {m} of {n}: poses differ"
            );
        }
    }

    /// Every local and global of two poses, bit for bit.
    fn same_pose(a: &mut Pose, b: &mut Pose) -> bool {
        (0..a.len() as u32).map(BoneIndex).all(|bone| {
            a.local(bone).to_bits() == b.local(bone).to_bits()
                && a.global(bone).to_bits() == b.global(bone).to_bits()
        })
    }

    /// `operands` laid out with its window.
    fn window(operands: &[u32]) -> Vec<u32> {
        let mut o = operands.to_vec();
        o.resize(o.len() + MAX_OPERANDS, 0);
        o
    }

    #[test]
    fn every_batched_op_leaves_each_member_what_its_handler_leaves() {
        // Every element type but bones, whose slots are not in the lanes.
        let scalar_elems = Elem::ALL.into_iter().filter(|&e| e != Elem::Bone);
        // Operand lists: distinct slots, and outputs sharing an input's slot as slot sharing
        // may lay them out (the element in the index's slot for ints; the broken transform
        // the read's result, as the compiler emits a fused pair, or another slot).
        let mut cases: Vec<(Op, Vec<u32>)> = Vec::new();
        for e in scalar_elems {
            for array in [1, 3, 6] {
                cases.push((Op::ArrayAt(e), vec![array, 2, 4]));
                cases.push((Op::ArraySetAt(e), vec![array, 2, 4]));
                cases.push((Op::ArraySetAt(e), vec![array, 3, 3]));
            }
            cases.push((Op::ArrayAt(e), vec![5, 1, 1]));
        }
        for array in [1, 2, 3, 6] {
            cases.push((Op::ArrayAtBreakTransform, vec![array, 2, 4, 4, 1, 1, 2]));
            cases.push((Op::ArrayAtBreakTransform, vec![array, 2, 4, 5, 1, 1, 2]));
            // Translation and scale into one slot: the scale, written last, stays.
            cases.push((Op::ArrayAtBreakTransform, vec![array, 2, 4, 4, 1, 1, 1]));
        }
        for bone in 0..5 {
            cases.push((Op::GetTransform, vec![bone, 2, 3, 4]));
            cases.push((
                Op::GetTransformBreakTransform,
                vec![bone, 2, 3, 4, 4, 1, 1, 2],
            ));
            cases.push((
                Op::GetTransformBreakTransform,
                vec![bone, 1, 2, 6, 5, 3, 3, 4],
            ));
            cases.push((
                Op::GetTransformBreakTransform,
                vec![bone, 2, 3, 4, 4, 1, 1, 1],
            ));
        }
        // A bone's parent into another bone slot, and into its own (every member's bones
        // name a root, a child, a grandchild, no bone and one past the skeleton's end).
        for bone in 0..5 {
            cases.push((Op::GetParent, vec![bone, (bone + 1) % 5]));
            cases.push((Op::GetParent, vec![bone, bone]));
        }
        for (op, operands) in cases {
            // As many operands as the op has.
            let layout = op.operands().expect("a layout");
            assert_eq!(layout.len(), operands.len(), "{op:?}");
            let o = window(&operands);
            for n in [BATCH, 5, 1] {
                let mut batched =
                    run(op, &o, n, true).unwrap_or_else(|| panic!("{op:?} is batched"));
                let mut alone = run(op, &o, n, false).expect("the handler");
                same_members(&mut batched, &mut alone, &format!("{op:?} {operands:?}"));
                let batched = batched.0;
                // The batch did something: some member's slots changed (a test that
                // compares two runs that do nothing would pass).
                if matches!(op, Op::ArrayAt(_) | Op::GetTransform | Op::GetParent) {
                    let before: Vec<Slots> = (0..n).map(member_slots).collect();
                    let changed = batched.iter().zip(&before).any(|(a, b)| !a.bit_eq(b));
                    assert!(changed || n == 1, "{op:?} {operands:?}: nothing changed");
                }
            }
        }
    }

    #[test]
    fn a_batch_reading_in_one_space_reads_each_member_s_own_bone() {
        // Every member reads in the same space, of the pose or the rest pose (the choice a
        // batch makes once); each reads its own bone slot of its own pose.
        for (space, initial) in [(0, false), (1, false), (0, true), (7, true)] {
            let slots = || {
                (0..BATCH)
                    .map(|m| {
                        let mut s = member_slots(m);
                        (s.ints[2], s.bools[3]) = (space, initial);
                        s
                    })
                    .collect::<Vec<_>>()
            };
            for op in [Op::GetTransform, Op::GetTransformBreakTransform] {
                let operands = match op {
                    Op::GetTransform => vec![1, 2, 3, 4],
                    _ => vec![1, 2, 3, 4, 4, 1, 1, 2],
                };
                let o = window(&operands);
                // SAFETY: as in `run`.
                let batched = |lane0: Bases, cxs: &mut [Ctx<'_>]| unsafe {
                    run_per_member(op, &o, &lane0, &mut no_copies(cxs), cxs)
                };
                let mut batch = run_members(op, &o, slots(), Some(&batched)).expect("batched");
                let mut alone = run_members(op, &o, slots(), None).expect("the handler");
                let what = format!("{op:?} in space {space}, initial {initial}");
                same_members(&mut batch, &mut alone, &what);
                // The members read apart: bones and poses of their own.
                let read: Vec<_> = batch.0.iter().map(|s| s.transforms[4].to_bits()).collect();
                assert!(read.iter().any(|r| *r != read[0]), "{what}: all alike");
            }
        }
    }

    #[test]
    fn a_batch_reading_one_bone_of_its_skeleton_s_rest_pose_reads_it_once() {
        // Members of one skeleton (one `Arc`) that read the same bone slot value of the rest
        // pose, in one space, all read one transform, read once. Where one member reads
        // another bone, or has a skeleton of its own (with another rest pose), each reads
        // its own. Either way every member's slots end as its handler leaves them; the
        // poses are moved away from the rest pose, so that a read of the pose would differ.
        let shared = chain();
        let own = chain_at_rest(|k| {
            Transform::new(Vec3::new(k + 4.0, 0.0, 0.0), Quat::IDENTITY, Vec3::ONE)
        });
        // `chain`'s root at rest, by hand: at (1, 2, −1), turned 0.3 rad about z, scaled 1.1.
        let root = Transform::new(
            Vec3::new(1.0, 2.0, -1.0),
            Quat::from_rotation_z(0.3),
            Vec3::splat(1.1),
        );
        let operands = window(&[1, 2, 3, 4]);
        for apart in [None, Some("another bone"), Some("another skeleton")] {
            for (space, bone) in [0, 7]
                .into_iter()
                .flat_map(|s| [0, 1, 2, -1, 3].map(|b| (s, b)))
            {
                let member = |m: usize| {
                    let mut slots = member_slots(m);
                    (slots.ints[2], slots.bools[3], slots.bones[1]) = (space, true, bone);
                    let skeleton = match (apart, m) {
                        (Some("another bone"), 7) => {
                            slots.bones[1] = (bone + 2) % 3;
                            &shared
                        }
                        (Some("another skeleton"), 7) => &own,
                        _ => &shared,
                    };
                    let mut pose = Pose::new(skeleton.clone());
                    let moved =
                        Transform::new(Vec3::splat(m as f32 + 1.0), Quat::IDENTITY, Vec3::ONE);
                    pose.set_local(BoneIndex(0), moved);
                    (slots, pose)
                };
                let mut results = Vec::new();
                for batched in [true, false] {
                    let (mut slots, mut poses): (Vec<Slots>, Vec<Pose>) =
                        (0..BATCH).map(member).unzip();
                    RESTS_SHARED.with(|n| n.set(0));
                    with_contexts(&mut slots, &mut poses, |cxs| {
                        if batched {
                            let lens = ScalarLens([SLOTS; 6]);
                            let mut lanes = Lanes::default();
                            lanes.load(Copies::all(&lens), cxs);
                            // SAFETY: the operands are slots below `SLOTS` of the lanes.
                            let ran = unsafe {
                                run_per_member(
                                    Op::GetTransform,
                                    &operands,
                                    &lanes.bases(),
                                    &mut no_copies(cxs),
                                    cxs,
                                )
                            };
                            assert!(ran);
                            lanes.store(Copies::all(&lens), cxs);
                        } else {
                            for cx in cxs.iter_mut() {
                                // SAFETY: as above.
                                unsafe { step(Op::GetTransform, &operands, cx, 1) };
                            }
                        }
                    });
                    let once = RESTS_SHARED.with(std::cell::Cell::get);
                    assert_eq!(once, usize::from(batched && apart.is_none()), "{apart:?}");
                    results.push(slots);
                }
                let what = format!("{apart:?}, space {space}, bone {bone}");
                for (m, (batch, alone)) in results[0].iter().zip(&results[1]).enumerate() {
                    assert!(batch.bit_eq(alone), "{what}: member {m}");
                }
                let read = |m: usize| results[0][m].transforms[4].to_bits();
                if apart.is_none() && bone == 0 {
                    // The root, in either space, is its rest local.
                    assert!((0..BATCH).all(|m| read(m) == root.to_bits()), "{what}");
                }
                if apart.is_some() && (0..3).contains(&bone) {
                    assert_ne!(read(7), read(0), "{what}: member 7 reads its own");
                }
            }
        }
    }

    /// A world of the plane z = 0 that counts the batches it is asked: a sphere that
    /// starts below it (by its radius) hits at the start, with a normal that depends on
    /// where (zero right of x = 6), and one that ends above it misses. A hit left of
    /// x = −1 has a NaN normal (which the trace reads as a miss), and is counted. A line
    /// trace is a sphere trace of radius 0.
    #[derive(Default)]
    struct Plane {
        batches: std::cell::Cell<usize>,
        /// How many hits it gave with a NaN normal.
        nans: std::cell::Cell<usize>,
    }

    impl strider_core::WorldQuery for Plane {
        fn line_trace(&self, start: Vec3, end: Vec3) -> Option<strider_core::TraceHit> {
            self.sphere_trace(start, end, 0.0)
        }

        fn sphere_trace(
            &self,
            start: Vec3,
            end: Vec3,
            radius: f32,
        ) -> Option<strider_core::TraceHit> {
            let (from, to) = (start.z - radius, end.z - radius);
            if from < 0.0 {
                return Some(strider_core::TraceHit {
                    point: start - Vec3::Z * radius,
                    normal: if start.x > 6.0 {
                        // No direction: the trace's normal is then zero.
                        Vec3::ZERO
                    } else if start.x < -1.0 {
                        self.nans.set(self.nans.get() + 1);
                        Vec3::NAN
                    } else {
                        // Not of unit length, and tilted by where the trace starts.
                        Vec3::new(0.1 * start.y, 0.3, 1.0)
                    },
                    distance: 0.0,
                });
            }
            if to >= 0.0 {
                return None;
            }
            let t = from / (from - to);
            Some(strider_core::TraceHit {
                point: start.lerp(end, t) - Vec3::Z * radius,
                normal: if start.x < -1.0 {
                    self.nans.set(self.nans.get() + 1);
                    Vec3::NAN
                } else {
                    Vec3::new(0.1, 0.0, 1.0)
                },
                distance: start.distance(end) * t,
            })
        }

        fn sphere_traces(
            &self,
            queries: &[SphereQuery],
            hits: &mut [Option<strider_core::TraceHit>],
        ) {
            self.batches.set(self.batches.get() + 1);
            for (q, hit) in queries.iter().zip(hits) {
                *hit = self.sphere_trace(q.start, q.end, q.radius);
            }
        }

        fn line_traces(&self, queries: &[LineQuery], hits: &mut [Option<strider_core::TraceHit>]) {
            self.batches.set(self.batches.get() + 1);
            for (q, hit) in queries.iter().zip(hits) {
                *hit = self.line_trace(q.start, q.end);
            }
        }
    }

    /// What trace `op` (`LineTrace` or `SphereTrace`) with operands `o` leaves in `n`
    /// members' slots, each member placed in the world by a transform of its own, all
    /// asking `worlds[m % len]`: run for the batch at once (`None` when the batch path
    /// leaves it to the handler) or by the handler on each member alone.
    fn trace(op: Op, o: &[u32], n: usize, batch: bool, worlds: &[&Plane]) -> Option<Vec<Slots>> {
        let mut slots: Vec<Slots> = (0..n).map(member_slots).collect();
        let mut poses: Vec<Pose> = (0..n).map(member_pose).collect();
        let mut draws: Vec<DebugDraw> = slots.iter().map(|_| DebugDraw::new(false)).collect();
        let mut cxs: Vec<Ctx<'_>> = (slots.iter_mut().zip(poses.iter_mut()).zip(&mut draws))
            .enumerate()
            .map(|(m, ((s, p), d))| {
                let mut cx = Ctx::for_test(s, &[], p, d, 1.0 / 60.0);
                // Scaled unevenly and turned about a tilted axis: every entry of the
                // matrices counts.
                let to_world = glam::Affine3A::from_scale_rotation_translation(
                    Vec3::new(1.0, 1.5, 0.8),
                    Quat::from_axis_angle(Vec3::new(0.3, -0.5, 1.0).normalize(), 0.4 * m as f32),
                    Vec3::new(m as f32, -2.0, 1.5 - 0.25 * m as f32),
                );
                (cx.to_world_matrix, cx.from_world_matrix) = (to_world, to_world.inverse());
                cx.world = worlds[m % worlds.len()];
                cx
            })
            .collect();
        if batch {
            let lens = ScalarLens([SLOTS; 6]);
            let mut lanes = Lanes::default();
            lanes.load(Copies::all(&lens), &cxs);
            // SAFETY: the operands are slots below `SLOTS` of the lanes loaded above.
            let ran = unsafe {
                match op {
                    Op::LineTrace => line_traces(
                        o,
                        lanes.bases(),
                        shared_world(&cxs),
                        &mut FrameColumns::new(),
                        &cxs,
                    ),
                    _ => sphere_traces(
                        o,
                        lanes.bases(),
                        shared_world(&cxs),
                        &mut FrameColumns::new(),
                        &cxs,
                    ),
                }
            };
            lanes.store(Copies::all(&lens), &mut cxs);
            if !ran {
                return None;
            }
        } else {
            for cx in &mut cxs {
                // SAFETY: as above.
                unsafe { step(op, o, cx, 1) };
            }
        }
        drop(cxs);
        Some(slots)
    }

    /// Numbers spread over many magnitudes and signs, with zero, tiny, huge, infinite and
    /// NaN among them: xorshift32 from `seed`, each draw a special value one time in 16.
    fn spread(mut seed: u32) -> impl FnMut() -> f32 {
        move || {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            let special = [0.0, -0.0, 1e-30, -1e30, f32::INFINITY, f32::NAN, 1.0];
            match seed % 16 {
                0 => special[(seed >> 4) as usize % special.len()],
                k => ((seed >> 8) as f32 / 65536.0 - 128.0) * 10f32.powi(k as i32 % 7 - 3),
            }
        }
    }

    /// A matrix drawn from `next` ([`spread`]): a turn about an axis, a scale within ±5 on
    /// each axis and a translation.
    fn spread_matrix(next: &mut impl FnMut() -> f32) -> glam::Affine3A {
        let axis = Vec3::new(next(), next(), next()).normalize_or(Vec3::Z);
        let rotation = Quat::from_axis_angle(axis, next().rem_euclid(6.0));
        let scale = Vec3::new(next(), next(), next()).clamp(Vec3::splat(-5.0), Vec3::splat(5.0));
        let at = Vec3::new(next(), next(), next());
        glam::Affine3A::from_scale_rotation_translation(scale, rotation, at)
    }

    #[test]
    fn hits_are_mapped_to_rig_space_by_columns_as_each_alone() {
        // Thousands of answers and matrices, spread over magnitudes, with zero, tiny, huge,
        // infinite and NaN components: the columns' hits are the handler's, bit for bit.
        let mut next = spread(0x2545_f491);
        for round in 0..400 {
            let mut columns = [[0.0; BATCH]; 12];
            let mut matrices = [glam::Affine3A::IDENTITY; BATCH];
            let mut answers = [None; BATCH];
            for m in 0..BATCH {
                matrices[m] = spread_matrix(&mut next);
                put_matrix(&mut columns, m, &matrices[m]);
                if (round + m) % 5 != 0 {
                    // A normal without direction now and then.
                    let normal = if (round + m) % 7 == 0 {
                        Vec3::ZERO
                    } else {
                        Vec3::new(next(), next(), next())
                    };
                    answers[m] = Some(TraceHit {
                        point: Vec3::new(next(), next(), next()),
                        normal,
                        distance: next(),
                    });
                }
            }
            let mut given = HitColumns::default();
            for (m, answer) in answers.iter().enumerate() {
                given.set(m, *answer);
            }
            let found = hits_in_rig_space(&given, &columns);
            for m in 0..BATCH {
                let (start, end) = (Vec3::ONE, Vec3::ZERO);
                let alone = trace_outputs(read_hit(&answers[m]), start, end, &matrices[m]);
                assert_eq!(found.hit[m], alone.0, "round {round}, member {m}");
                if alone.0 {
                    let point = Vec3::from_array(std::array::from_fn(|c| found.point[c][m]));
                    let normal = Vec3::from_array(std::array::from_fn(|c| found.normal[c][m]));
                    assert_eq!(
                        (
                            point.to_array().map(f32::to_bits),
                            normal.to_array().map(f32::to_bits)
                        ),
                        (
                            alone.1.to_array().map(f32::to_bits),
                            alone.2.to_array().map(f32::to_bits)
                        ),
                        "round {round}, member {m}: {answers:?}"
                    );
                    assert_eq!(found.distance[m].to_bits(), alone.3.to_bits());
                }
            }
        }
    }

    #[test]
    fn ends_are_taken_to_world_space_by_columns_as_each_alone() {
        // Thousands of ends and matrices, spread over magnitudes, with zero, tiny, huge,
        // infinite and NaN components: each end through the columns is glam's
        // `transform_point3` of it, bit for bit (NaN for NaN).
        let mut next = spread(0x9e37_79b9);
        let bits = |v: [f32; 3]| v.map(|x| if x.is_nan() { u32::MAX } else { x.to_bits() });
        let mut differing_lanes = 0;
        for round in 0..400 {
            let mut columns = [[0.0; BATCH]; 12];
            let mut matrices = [glam::Affine3A::IDENTITY; BATCH];
            for (m, matrix) in matrices.iter_mut().enumerate() {
                *matrix = spread_matrix(&mut next);
                put_matrix(&mut columns, m, matrix);
            }
            for (m, matrix) in matrices.iter().enumerate() {
                let p = Vec3::new(next(), next(), next());
                let columns = point_through(&columns, m, p);
                let alone = matrix.transform_point3(p).to_array();
                assert_eq!(bits(columns), bits(alone), "round {round}, member {m}: {p}");
                differing_lanes += usize::from(m > 0 && matrices[m] != matrices[m - 1]);
            }
        }
        assert!(
            differing_lanes > 5000,
            "{differing_lanes}: each lane its own matrix"
        );
    }

    #[test]
    fn a_batch_asks_its_world_once_for_every_trace() {
        // Operands: start, end, a sphere's radius, then hit, point, normal, distance; in
        // slots of their own, and with the outputs in the inputs' slots (as slot sharing
        // may lay them out).
        let cases = [
            (Op::SphereTrace, vec![1, 2, 0, 4, 5, 6, 7]),
            (Op::SphereTrace, vec![1, 2, 0, 3, 1, 2, 0]),
            (Op::LineTrace, vec![1, 2, 4, 5, 6, 7]),
            (Op::LineTrace, vec![1, 2, 3, 1, 2, 0]),
        ];
        for (op, operands) in cases {
            let o = window(&operands);
            let hit_slot = operands[operands.len() - 4] as usize;
            for n in [BATCH, 5, 1] {
                let world = Plane::default();
                let batched = trace(op, &o, n, true, &[&world]).expect("the batch path takes it");
                assert_eq!(world.batches.get(), 1, "{op:?} {operands:?}, {n} members");
                assert!(n < BATCH || world.nans.get() > 0, "{op:?}: no NaN normal");
                let alone = trace(op, &o, n, false, &[&Plane::default()]).expect("the handler");
                for m in 0..n {
                    assert!(
                        batched[m].bit_eq(&alone[m]),
                        "{op:?} {operands:?}: member {m} of {n}: slots differ"
                    );
                }
                let hits = alone.iter().filter(|s| s.bools[hit_slot]).count();
                assert!(
                    n < BATCH || (0 < hits && hits < n),
                    "{op:?}: {hits} hits of {n}"
                );
                // Some hit has no direction to its normal, and some a normal turned and
                // normalised.
                let normal_slot = operands[operands.len() - 2] as usize;
                let normals = alone.iter().filter(|s| s.bools[hit_slot]);
                let normals: Vec<Vec3> = normals.map(|s| s.vec3s[normal_slot]).collect();
                assert!(
                    n < BATCH
                        || (normals.contains(&Vec3::ZERO)
                            && normals.iter().any(|v| v.is_normalized() && v.x != 0.0)),
                    "{op:?}: normals {normals:?}"
                );
            }
            // Members in different worlds: each asks its own, through the handler.
            let (a, b) = (Plane::default(), Plane::default());
            assert!(trace(op, &o, BATCH, true, &[&a, &b]).is_none());
        }
    }

    #[test]
    fn a_batch_solves_its_two_bone_iks_as_each_member_alone() {
        // Operands: bones A, B and effector; target; primary and secondary axis; pole, pole
        // kind; weight; stretch on, start, max; effector rotation; reached, distance.
        let o = window(&[0, 1, 2, 0, 6, 7, 1, 0, 6, 1, 2, 3, 2, 4, 7]);
        // What `TwoBoneIK` leaves in `n` members' slots and poses, for the batch at once
        // or by the handler on each alone; `None` when the batch path does not take it.
        // Most members have a chain and full weight, so that the lanes solve them; some
        // have a repeated bone, no effector, a weight of 0.5 or NaN (the one-chain solve's
        // cases), bones that are not a limb (written one by one), or their own axes
        // (`shared` false: the member's index in them). Stretch starts at 0.8 of the
        // chain's reach, for the members that stretch.
        let run = |n: usize, batch: bool, shared: bool, shift: usize| {
            let slots = (0..n)
                .map(|m| {
                    let mut s = member_slots(m + shift);
                    let chain = match (m + shift) % 6 {
                        3 => [0, 0, 2],
                        4 => [0, 1, -1],
                        5 => [0, 2, 1],
                        _ => [0, 1, 2],
                    };
                    s.bones[..3].copy_from_slice(&chain);
                    let tilt = if shared { 0.0 } else { m as f32 };
                    s.vec3s[6] = Vec3::new(1.0, 2.0, -1.0 - tilt);
                    s.vec3s[7] = Vec3::Z;
                    s.floats[6] = [1.0, 1.0, 0.5, 1.0, f32::NAN, 1.0, 2.0][(m + shift) % 7];
                    (s.floats[2], s.floats[3]) = (0.8, 1.3);
                    s
                })
                .collect();
            // SAFETY: the operands are slots below `SLOTS` of the lanes, and bone slots
            // below `SLOTS` of every member.
            let batched =
                |lane0: Bases, cxs: &mut [Ctx<'_>]| unsafe { two_bone_iks(&o, &lane0, cxs) };
            run_members(Op::TwoBoneIK, &o, slots, batch.then_some(&batched))
        };
        // Largest first, on one thread: the smaller batches run on the thread's chain lanes
        // with the larger one's numbers left in them. Their members' cases are shifted: lane
        // 0, which the full batch solved, is not set again in the batch of 7 (its member 0
        // has a repeated bone), so a chain left marked from before would be caught; the
        // other lanes are set again with other numbers.
        for (n, shift) in [(BATCH, 0), (7, 3), (1, 1)] {
            SOLVED_ON_LANES.with(|solved| solved.set(0));
            let mut batched = run(n, true, true, shift).expect("the batch path takes it");
            let on_lanes = SOLVED_ON_LANES.with(std::cell::Cell::get);
            assert!(
                on_lanes > 0 || !LANES_MATCH_GLAM,
                "{n} members: none on lanes"
            );
            let mut alone = run(n, false, true, shift).expect("the handler");
            same_members(&mut batched, &mut alone, "TwoBoneIK");
            let alone = alone.0;
            // The chains were solved (reached or not: a distance to the target), and the
            // repeated bone and the missing effector were not.
            for (m, s) in alone.iter().enumerate() {
                assert_eq!(
                    s.floats[7].is_finite(),
                    !matches!((m + shift) % 6, 3 | 4),
                    "member {m}"
                );
            }
        }
        // Members with axes of their own: each is solved by the handler.
        assert!(run(BATCH, true, false, 0).is_none());
    }

    #[test]
    fn a_batch_steps_through_for_each_as_each_member_alone() {
        // Operands: array 1, counter int 2; element 4 (of the element's type), index int 5,
        // count int 6; the loop's end at instruction 99.
        let o = window(&[1, 2, 4, 5, 6, 99]);
        // Every member's array 1 of each type `len(m)` long, and its counter `at(m)`.
        let members = |n: usize, len: &dyn Fn(usize) -> usize, at: &dyn Fn(usize) -> i32| {
            (0..n)
                .map(|m| {
                    let mut s = member_slots(m + 1);
                    let l = len(m);
                    // Distinct items, so that a wrong index reads a wrong value.
                    let x = |i: usize| (m * 4 + i) as f32 * 0.5;
                    // `member_slots` has no bone arrays.
                    s.bone_arrays = vec![Vec::new(); SLOTS];
                    s.bone_arrays[1] = (0..l).map(|i| (10 * m + i) as i32).collect();
                    s.bool_arrays[1] = (0..l).map(|i| (i + m) % 2 == 1).collect();
                    s.int_arrays[1] = (0..l).map(|i| (100 * m + i) as i32).collect();
                    s.float_arrays[1] = (0..l).map(x).collect();
                    s.vec3_arrays[1] = (0..l).map(|i| Vec3::splat(x(i))).collect();
                    s.quat_arrays[1] = (0..l).map(|i| Quat::from_rotation_z(x(i))).collect();
                    s.transform_arrays[1] = (0..l)
                        .map(|i| Transform::from_translation(Vec3::splat(x(i))))
                        .collect();
                    s.ints[2] = at(m);
                    s
                })
                .collect::<Vec<Slots>>()
        };
        // (what every member does, lengths, counters): all step on, all leave (at the
        // end, before the start, far past it, or an empty array), or they part ways.
        type Case<'a> = (
            Option<bool>,
            &'a dyn Fn(usize) -> usize,
            &'a dyn Fn(usize) -> i32,
        );
        let cases: [Case<'_>; 6] = [
            (Some(true), &|_| 3, &|m| (m % 3) as i32),
            (Some(true), &|m| 1 + m % 4, &|_| 0),
            (Some(false), &|_| 3, &|m| [3, -1, i32::MAX, i32::MIN][m % 4]),
            (Some(false), &|_| 0, &|_| 0),
            (None, &|m| m % 3, &|_| 0),
            (None, &|_| 2, &|m| (m % 3) as i32),
        ];
        for e in Elem::ALL {
            let op = Op::ForEachNext(e);
            for ((k, (expected, len, at)), n) in cases
                .iter()
                .enumerate()
                .flat_map(|case| [(case, BATCH), (case, 5)])
            {
                let what = format!("{op:?} case {k}, {n} members");
                // The handler on each member alone: where each goes next.
                let mut alone = members(n, len, at);
                let mut alone_poses: Vec<Pose> = (0..n).map(member_pose).collect();
                let mut next = Vec::new();
                with_contexts(&mut alone, &mut alone_poses, |cxs| {
                    for cx in cxs.iter_mut() {
                        // SAFETY: the operands are slots below `SLOTS` of every member.
                        next.push(unsafe { step(op, &o, cx, 1) });
                    }
                });
                let steps = next.iter().filter(|&&pc| pc == 1).count();
                let agreed = match steps {
                    0 => Some(false),
                    s if s == n => Some(true),
                    _ => None,
                };
                assert_eq!(agreed, *expected, "{what}: the case itself");
                // The batch.
                let taken = std::cell::Cell::new(None);
                let batched = |lane0: Bases, cxs: &mut [Ctx<'_>]| {
                    // SAFETY: as in `run`.
                    taken.set(unsafe { for_each_next(e, &o, &lane0, &mut no_copies(cxs), cxs) });
                    true
                };
                let before = members(n, len, at);
                let (after, _) = run_members(op, &o, members(n, len, at), Some(&batched))
                    .expect("the batch path ran");
                assert_eq!(taken.get(), *expected, "{what}");
                for m in 0..n {
                    if *expected == Some(true) {
                        assert!(after[m].bit_eq(&alone[m]), "{what}: member {m} differs");
                        assert!(!after[m].bit_eq(&before[m]), "{what}: member {m} unchanged");
                    } else {
                        // Nothing written: the handlers run each member (or the batch
                        // leaves the loop, where the handler writes nothing either).
                        assert!(after[m].bit_eq(&before[m]), "{what}: member {m} written");
                    }
                }
            }
        }
    }

    #[test]
    fn other_ops_are_left_to_the_handlers() {
        for op in [
            Op::ArrayAt(Elem::Bone),
            Op::ArraySetAt(Elem::Bone),
            Op::AddF,
            Op::SetTransform,
            Op::LineTrace,
            Op::Copy(ValueType::Float),
            Op::ForEachNext(Elem::Float),
        ] {
            let o = window(&[1, 2, 3, 4, 5]);
            assert!(
                run(op, &o, BATCH, true).is_none(),
                "{op:?} is not batched here"
            );
        }
    }
}
