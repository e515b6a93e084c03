//! A counting global allocator, so `strider bench` can report heap allocations per frame
//! and tests can check that a frame allocates nothing.
//!
//! The `strider` binary installs [`CountingAllocator`] as its global allocator
//! (`src/main.rs`), as does the allocation test (`tests/allocations.rs`). Counting is off
//! except while a counting function runs its closure: `count` counts every allocation and
//! reallocation on every thread (the benchmark's worker threads included);
//! [`allocations_on_this_thread`] only the calling thread's, so a test harness running
//! other tests meanwhile does not disturb it. Off, the cost is one relaxed atomic load per
//! allocation, and no call into the counting code.

// Implementing `GlobalAlloc` is an `unsafe impl`; each method only forwards the caller's
// arguments, unchanged, to mimalloc, whose contract the caller upholds. No
// allocation crate offers a counter that is switched on for a time span across threads
// without also replacing the allocator, so this is written here.
#![allow(unsafe_code)]

use mimalloc::MiMalloc;
use std::alloc::{GlobalAlloc, Layout};
use std::cell::Cell;
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};

/// mimalloc, counting allocations while `strider bench` times frames. Install it as the
/// binary's `#[global_allocator]`.
pub struct CountingAllocator;

/// How many `count` calls run (each counts every thread's allocations).
static COUNTING: AtomicUsize = AtomicUsize::new(0);
static ALLOCATIONS: AtomicU64 = AtomicU64::new(0);
/// How many threads are inside [`allocations_on_this_thread`].
static THREADS_COUNTING: AtomicUsize = AtomicUsize::new(0);
/// How many counting functions run (`count` and [`allocations_on_this_thread`] alike): the
/// one flag an allocation reads while nothing counts.
static WATCHERS: AtomicUsize = AtomicUsize::new(0);

thread_local! {
    // This thread's count while it counts its own allocations. `const` initialisation and no
    // destructor: touching it never allocates.
    static THREAD_ALLOCATIONS: Cell<Option<u64>> = const { Cell::new(None) };
}

/// Counts an allocation while some counting function runs.
#[inline(always)]
fn note_watched() {
    if COUNTING.load(Ordering::Relaxed) > 0 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
    }
    if THREADS_COUNTING.load(Ordering::Relaxed) > 0 {
        // Fails only while the thread is being torn down: nothing to count then.
        let _ = THREAD_ALLOCATIONS.try_with(|c| c.set(c.get().map(|n| n + 1)));
    }
}

/// Every mimalloc block is aligned to at least a machine word, so a request aligned to no
/// more goes to the plain `mi_malloc`/`mi_realloc`, which skip the alignment path that
/// `MiMalloc` always takes (about a third of the cost of a small allocation).
const WORD: usize = std::mem::size_of::<usize>();

/// mimalloc's allocation, not counted.
///
/// # Safety
/// `GlobalAlloc::alloc`'s contract.
#[inline(always)]
unsafe fn allocate(layout: Layout) -> *mut u8 {
    if layout.align() <= WORD {
        // SAFETY: any size is valid for `mi_malloc`; its blocks are word-aligned.
        return unsafe { libmimalloc_sys::mi_malloc(layout.size()) }.cast();
    }
    // SAFETY: forwarded unchanged from the caller, who upholds `alloc`'s contract.
    unsafe { MiMalloc.alloc(layout) }
}

/// mimalloc's reallocation, not counted.
///
/// # Safety
/// `GlobalAlloc::realloc`'s contract, with `ptr` allocated by [`CountingAllocator`].
#[inline(always)]
unsafe fn reallocate(ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
    if layout.align() <= WORD {
        // SAFETY: `ptr` came from mimalloc (either entry point), and its block, like the
        // new one, is word-aligned.
        return unsafe { libmimalloc_sys::mi_realloc(ptr.cast(), new_size) }.cast();
    }
    // SAFETY: as above; `ptr` was allocated by this allocator, i.e. by `MiMalloc`.
    unsafe { MiMalloc.realloc(ptr, layout, new_size) }
}

/// [`allocate`], counted: out of line, so that the path taken while nothing counts is a
/// load, a branch and a jump into mimalloc.
///
/// # Safety
/// As [`allocate`].
#[cold]
#[inline(never)]
unsafe fn allocate_watched(layout: Layout) -> *mut u8 {
    note_watched();
    // SAFETY: as the caller's.
    unsafe { allocate(layout) }
}

/// [`reallocate`], counted (see [`allocate_watched`]).
///
/// # Safety
/// As [`reallocate`].
#[cold]
#[inline(never)]
unsafe fn reallocate_watched(ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
    note_watched();
    // SAFETY: as the caller's.
    unsafe { reallocate(ptr, layout, new_size) }
}

unsafe impl GlobalAlloc for CountingAllocator {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if WATCHERS.load(Ordering::Relaxed) != 0 {
            // SAFETY: forwarded unchanged from the caller, who upholds `alloc`'s contract.
            return unsafe { allocate_watched(layout) };
        }
        // SAFETY: as above.
        unsafe { allocate(layout) }
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        if WATCHERS.load(Ordering::Relaxed) != 0 {
            note_watched();
        }
        // SAFETY: as above.
        unsafe { MiMalloc.alloc_zeroed(layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        if WATCHERS.load(Ordering::Relaxed) != 0 {
            // SAFETY: as above; `ptr` was allocated by this allocator.
            return unsafe { reallocate_watched(ptr, layout, new_size) };
        }
        // SAFETY: as above.
        unsafe { reallocate(ptr, layout, new_size) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: as above.
        unsafe { MiMalloc.dealloc(ptr, layout) }
    }
}

/// Runs `f` and returns its result with the number of heap allocations (and reallocations)
/// made meanwhile on any thread, or `None` for the count when [`CountingAllocator`] is not
/// the global allocator (a library user's binary).
///
/// Never inlined, in every build profile: the bench's timed frames run inside it, so a
/// profiler can collect exactly them by its name (callgrind's
/// `--toggle-collect='strider_cli::alloc_count::count*'`, docs/performance.md).
#[inline(never)]
pub(crate) fn count<T>(f: impl FnOnce() -> T) -> (T, Option<u64>) {
    WATCHERS.fetch_add(1, Ordering::SeqCst);
    COUNTING.fetch_add(1, Ordering::SeqCst);
    // An allocation of our own: counted only if this allocator is the global one.
    let probe = ALLOCATIONS.load(Ordering::SeqCst);
    drop(std::hint::black_box(Box::new(0u8)));
    let before = ALLOCATIONS.load(Ordering::SeqCst);
    let installed = before > probe;
    let out = f();
    COUNTING.fetch_sub(1, Ordering::SeqCst);
    WATCHERS.fetch_sub(1, Ordering::SeqCst);
    let counted = ALLOCATIONS.load(Ordering::SeqCst) - before;
    (out, installed.then_some(counted))
}

/// Runs `f` and returns its result with the number of heap allocations (and reallocations)
/// the calling thread made meanwhile (allocations on other threads are not counted), or
/// `None` for the count when [`CountingAllocator`] is not the global allocator.
pub fn allocations_on_this_thread<T>(f: impl FnOnce() -> T) -> (T, Option<u64>) {
    THREAD_ALLOCATIONS.with(|c| c.set(Some(0)));
    THREADS_COUNTING.fetch_add(1, Ordering::SeqCst);
    WATCHERS.fetch_add(1, Ordering::SeqCst);
    // An allocation of our own: counted only if this allocator is the global one.
    drop(std::hint::black_box(Box::new(0u8)));
    let installed = THREAD_ALLOCATIONS.with(|c| c.replace(Some(0))) == Some(1);
    let out = f();
    WATCHERS.fetch_sub(1, Ordering::SeqCst);
    THREADS_COUNTING.fetch_sub(1, Ordering::SeqCst);
    let counted = THREAD_ALLOCATIONS.with(|c| c.replace(None)).unwrap_or(0);
    (out, installed.then_some(counted))
}
