//! Asking the processor for a batch's member state before the batch reads it.
//!
//! A batch's members each keep their arrays in allocations of their own, reached through a
//! chain of pointers (context, slots, the list of an element type's arrays, the array),
//! and the batch reads their elements member by member; each member's first read of a
//! line waits for it, behind the loads of the pointers that lead to it. Asking for every
//! member's lines level by level, the lists of all members first, lets the processor fetch
//! them side by side.

// `_mm_prefetch` is an intrinsic, so `unsafe` to call, though it reads nothing.
#![allow(unsafe_code)]

use crate::exec::Ctx;

/// Asks for the cache line at `p` to be brought into the first-level data cache, without
/// waiting for it. Reads nothing and changes nothing; a no-op off x86-64.
#[inline(always)]
fn line(p: *const i8) {
    // SAFETY: a prefetch reads no memory and faults on no address; SSE, which it needs, is
    // part of x86-64.
    #[cfg(target_arch = "x86_64")]
    unsafe {
        std::arch::x86_64::_mm_prefetch::<{ std::arch::x86_64::_MM_HINT_T0 }>(p);
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = p;
}

/// Asks for the first and the last cache line of `items`: all of them when they span two
/// or fewer (a character's arrays hold a few items, one per foot or limb); the processor
/// fetches a longer one's middle by itself once it reads it in order.
#[inline(always)]
fn ends<T>(items: &[T]) {
    let p = items.as_ptr().cast::<i8>();
    line(p);
    line(p.wrapping_add(size_of_val(items).saturating_sub(1)));
}

/// Calls `$f` on each element type's list of arrays of slots `$s`.
macro_rules! each_list {
    ($s:expr, $f:ident) => {{
        let s = $s;
        $f(&s.bool_arrays);
        $f(&s.int_arrays);
        $f(&s.float_arrays);
        $f(&s.vec3_arrays);
        $f(&s.quat_arrays);
        $f(&s.transform_arrays);
        $f(&s.bone_arrays);
    }};
}

/// Asks for what a batch reads of its `members` through pointers: first the lists of every
/// member's arrays, then every member's array elements.
#[inline(always)]
pub(crate) fn batch(members: &[Ctx<'_>]) {
    fn arrays<T>(list: &[Vec<T>]) {
        for array in list {
            ends(array);
        }
    }
    for cx in members {
        each_list!(&*cx.slots, ends);
    }
    for cx in members {
        each_list!(&*cx.slots, arrays);
    }
}
