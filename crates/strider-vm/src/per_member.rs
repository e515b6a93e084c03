//! The ops that read or write each member's own arrays or pose, run for a whole batch with
//! their operands fetched once ([`run_per_member`]).
//!
//! While a batch is at one instruction, the executor's handlers run member by member: each
//! member's run fetches the instruction's operands again and works out where its slots
//! are, one slot after another. For an op with half a dozen operands that is most of the
//! work (an `ArrayAt` of a transform then a `BreakTransform` took about 64 machine
//! instructions per member). The ops here find every operand's block of lanes
//! ([`crate::lanes`]) once, then visit the members, each with its own arrays and pose: the
//! same element functions as the handlers ([`array_get`], [`array_set`],
//! [`bone_transform`]), on the same values, in the same order, so the results are the
//! handlers', bit for bit.

// Slots are read and written through the lanes' base pointers, as in `lanes`.
#![allow(unsafe_code)]

use crate::exec::{BATCH, Bases, Ctx, array_get, array_set, bone_transform};
use glam::{Quat, Vec3};
use strider_core::Transform;
use strider_nodes::{Elem, Op};

/// Item 0 (member 0's) of the block of [`BATCH`] lanes of slot `slot` of the array at
/// `base`; member `m`'s item is `m` on.
#[inline(always)]
fn lane0_of<T>(base: *mut T, slot: u32) -> *mut T {
    base.wrapping_add(slot as usize * BATCH)
}

/// Runs `op` (operands `o`) for every member of the batch whose member 0's lane is `lane0`,
/// member by member in order, when it is one of the ops that read an element of a member's
/// array (`ArrayAt` of a scalar element type, alone or followed by `BreakTransform`), write
/// one (`ArraySetAt`), or read a bone's transform (`GetTransform`, alone or followed by
/// `BreakTransform`); returns true. Returns false, doing nothing, for every other op.
///
/// # Safety
/// As [`crate::lanes::run_wide`]: `op` and `o` an instruction of a program built by
/// [`ProgramBuilder::finish`](crate::ProgramBuilder::finish) (with its operand window),
/// `lane0` the bases of lanes loaded for that program's slots, and `members` the batch
/// (at most [`BATCH`]), each with that program's slots.
#[inline(never)]
pub(crate) unsafe fn run_per_member(
    op: Op,
    o: &[u32],
    lane0: Bases,
    members: &mut [Ctx<'_>],
) -> bool {
    // Member 0's item of slot operand `$k` of scalar array `$a`.
    macro_rules! lane {
        ($a:ident, $k:expr) => {
            lane0_of(lane0.$a, o[$k])
        };
    }
    // `BreakTransform` of member `$m`'s transform `$x` into `$parts` (the blocks of its
    // translation, rotation and scale), in the handler's order.
    macro_rules! break_transform {
        ($m:expr, $x:expr, $parts:expr) => {{
            let (x, (tr, rot, sc)): (Transform, _) = ($x, $parts);
            // SAFETY: slots of the program's lanes (the caller's contract), `$m < BATCH`.
            unsafe {
                *tr.add($m) = x.translation;
                *rot.add($m) = x.rotation;
                *sc.add($m) = x.scale;
            }
        }};
    }
    // `ArrayAt` (operands: array, index, element) of element type `$sc` (arrays `$ar`,
    // default `$zero`), then `$then` for each member `$m`.
    macro_rules! array_at {
        ($sc:ident, $ar:ident, $zero:expr, |$m:ident| $then:expr) => {{
            let (array, index, out) = (o[0] as usize, lane!(ints, 1), lane!($sc, 2));
            for ($m, cx) in members.iter().enumerate() {
                // SAFETY: as above; the index is read before the element is written (they
                // may share a slot).
                unsafe { *out.add($m) = array_get(&cx.slots.$ar[array], *index.add($m), &$zero) };
                $then;
            }
        }};
        ($sc:ident, $ar:ident, $zero:expr) => {
            array_at!($sc, $ar, $zero, |_m| {})
        };
    }
    // `ArraySetAt` (operands: array, index, element).
    macro_rules! array_set_at {
        ($sc:ident, $ar:ident) => {{
            let (array, index, value) = (o[0] as usize, lane!(ints, 1), lane!($sc, 2));
            for (m, cx) in members.iter_mut().enumerate() {
                // SAFETY: as above.
                let (i, value) = unsafe { (*index.add(m), *value.add(m)) };
                array_set(&mut cx.slots.$ar[array], i, value);
            }
        }};
    }
    // `GetTransform` (operands `$b`..: bone, space, initial, result), then `$then` for each
    // member `$m`.
    macro_rules! get_transform {
        ($b:expr, |$m:ident| $then:expr) => {{
            let (bone, space, initial, out) = (
                o[$b] as usize,
                lane!(ints, $b + 1),
                lane!(bools, $b + 2),
                lane!(transforms, $b + 3),
            );
            for ($m, cx) in members.iter_mut().enumerate() {
                // SAFETY: as above.
                let (space, initial) = unsafe { (*space.add($m), *initial.add($m)) };
                let x = bone_transform(cx.pose, cx.slots.bones[bone], space, initial);
                // SAFETY: as above.
                unsafe { *out.add($m) = x };
                $then;
            }
        }};
    }
    // A fused read then `BreakTransform` (operands from `$b`: the transform to break, then
    // the blocks of its parts): `$read!(…, |m| …)`, each member's transform broken from
    // its slot after the read has written its result (the two may share a slot, as the
    // compiler lays them out, or not).
    macro_rules! then_break {
        ($read:ident!($($args:tt)*), $b:expr) => {{
            let (t, parts) = (
                lane!(transforms, $b),
                (lane!(vec3s, $b + 1), lane!(quats, $b + 2), lane!(vec3s, $b + 3)),
            );
            // SAFETY: as above.
            $read!($($args)* |m| break_transform!(m, unsafe { *t.add(m) }, parts))
        }};
    }
    match op {
        Op::ArrayAt(e) => match e {
            Elem::Bool => array_at!(bools, bool_arrays, false),
            Elem::Int => array_at!(ints, int_arrays, 0),
            Elem::Float => array_at!(floats, float_arrays, 0.0),
            Elem::Vec3 => array_at!(vec3s, vec3_arrays, Vec3::ZERO),
            Elem::Quat => array_at!(quats, quat_arrays, Quat::IDENTITY),
            Elem::Transform => array_at!(transforms, transform_arrays, Transform::IDENTITY),
            // Bone slots are not in the lanes.
            Elem::Bone => return false,
        },
        Op::ArrayAtBreakTransform => then_break!(
            array_at!(transforms, transform_arrays, Transform::IDENTITY,),
            3
        ),
        Op::ArraySetAt(e) => match e {
            Elem::Bool => array_set_at!(bools, bool_arrays),
            Elem::Int => array_set_at!(ints, int_arrays),
            Elem::Float => array_set_at!(floats, float_arrays),
            Elem::Vec3 => array_set_at!(vec3s, vec3_arrays),
            Elem::Quat => array_set_at!(quats, quat_arrays),
            Elem::Transform => array_set_at!(transforms, transform_arrays),
            Elem::Bone => return false,
        },
        Op::GetTransform => get_transform!(0, |_m| {}),
        Op::GetTransformBreakTransform => then_break!(get_transform!(0,), 4),
        _ => return false,
    }
    true
}
