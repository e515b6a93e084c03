//! A counting global allocator, so `strider bench` can report heap allocations per frame.
//!
//! The `strider` binary installs [`CountingAllocator`] as its global allocator
//! (`src/main.rs`). Counting is off except while `count` runs its closure; it then counts
//! every allocation and reallocation on every thread (the benchmark's worker threads
//! included). Off, the cost is one relaxed atomic load per allocation.

// Implementing `GlobalAlloc` is an `unsafe impl`; each method only forwards the caller's
// arguments, unchanged, to the system allocator, whose contract the caller upholds. No
// allocation crate offers a counter that is switched on for a time span across threads
// without also replacing the allocator, so this is written here.
#![allow(unsafe_code)]

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

/// The system allocator, counting allocations while `strider bench` times frames. Install
/// it as the binary's `#[global_allocator]`.
pub struct CountingAllocator;

static COUNTING: AtomicBool = AtomicBool::new(false);
static ALLOCATIONS: AtomicU64 = AtomicU64::new(0);
/// Set by any allocation that went through [`CountingAllocator`]: whether it is installed.
static SEEN: AtomicBool = AtomicBool::new(false);

#[inline]
fn note() {
    SEEN.store(true, Ordering::Relaxed);
    if COUNTING.load(Ordering::Relaxed) {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
    }
}

unsafe impl GlobalAlloc for CountingAllocator {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        note();
        // SAFETY: forwarded unchanged from the caller, who upholds `alloc`'s contract.
        unsafe { System.alloc(layout) }
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        note();
        // SAFETY: as above.
        unsafe { System.alloc_zeroed(layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        note();
        // SAFETY: as above; `ptr` was allocated by this allocator, i.e. by `System`.
        unsafe { System.realloc(ptr, layout, new_size) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: as above.
        unsafe { System.dealloc(ptr, layout) }
    }
}

/// Runs `f` and returns its result with the number of heap allocations (and reallocations)
/// made meanwhile on any thread, or `None` for the count when [`CountingAllocator`] is not
/// the global allocator (a library user's binary).
pub(crate) fn count<T>(f: impl FnOnce() -> T) -> (T, Option<u64>) {
    // Make sure at least one allocation has gone through the global allocator.
    drop(std::hint::black_box(Box::new(0u8)));
    let before = ALLOCATIONS.load(Ordering::SeqCst);
    COUNTING.store(true, Ordering::SeqCst);
    let out = f();
    COUNTING.store(false, Ordering::SeqCst);
    let counted = ALLOCATIONS.load(Ordering::SeqCst) - before;
    (out, SEEN.load(Ordering::SeqCst).then_some(counted))
}
