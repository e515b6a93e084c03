//! Asking the processor for a batch's member state before the batch reads it.
//!
//! A batch's members each keep their slots and arrays in allocations of their own, reached
//! through a chain of pointers (context, slots, the list of an element type's arrays, the
//! array). The batch copies the slots into its lanes first thing, and reads the arrays'
//! elements member by member later; each member's first read of a line waits for it,
//! behind the loads of the pointers that lead to it. Asking for every member's lines level
//! by level, the pointers of all members first, lets the processor fetch them side by side.

// `_mm_prefetch` is an intrinsic, so `unsafe` to call, though it reads nothing.
#![allow(unsafe_code)]

use crate::exec::Ctx;
use crate::lanes::Copies;

/// Asks for every cache line of `items` to be brought into the first-level data cache,
/// without waiting for it. Reads nothing and changes nothing; a no-op off x86-64.
#[inline(always)]
fn lines<T>(items: &[T]) {
    #[cfg(target_arch = "x86_64")]
    {
        let (p, bytes) = (items.as_ptr().cast::<i8>(), size_of_val(items));
        let mut at = 0;
        while at < bytes {
            // SAFETY: a prefetch reads no memory and faults on no address; SSE, which it
            // needs, is part of x86-64.
            unsafe {
                std::arch::x86_64::_mm_prefetch::<{ std::arch::x86_64::_MM_HINT_T0 }>(
                    p.wrapping_add(at),
                );
            }
            at += 64;
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = items;
}

/// Asks for what a batch on lanes reads of its `members` first: every member's scalar
/// slots that `copies` copies into the lanes and its arrays' headers, then every member's
/// array elements.
#[inline(always)]
pub(crate) fn batch(members: &[Ctx<'_>], copies: &Copies<'_>) {
    for cx in members {
        let s = &*cx.slots;
        lines(&s.bools[..copies.kept.0[0].min(s.bools.len())]);
        lines(&s.ints[..copies.kept.0[1].min(s.ints.len())]);
        lines(&s.floats[..copies.kept.0[2].min(s.floats.len())]);
        lines(&s.vec3s[..copies.kept.0[3].min(s.vec3s.len())]);
        lines(&s.quats[..copies.kept.0[4].min(s.quats.len())]);
        lines(&s.transforms[..copies.kept.0[5].min(s.transforms.len())]);
        lines(&s.bool_arrays);
        lines(&s.int_arrays);
        lines(&s.float_arrays);
        lines(&s.vec3_arrays);
        lines(&s.quat_arrays);
        lines(&s.transform_arrays);
        lines(&s.bone_arrays);
    }
    fn each<T>(arrays: &[Vec<T>]) {
        for array in arrays {
            lines(array);
        }
    }
    for cx in members {
        let s = &*cx.slots;
        each(&s.bool_arrays);
        each(&s.int_arrays);
        each(&s.float_arrays);
        each(&s.vec3_arrays);
        each(&s.quat_arrays);
        each(&s.transform_arrays);
        each(&s.bone_arrays);
    }
}
