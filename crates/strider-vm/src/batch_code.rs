//! Which machine code the batch loop runs: the baseline x86-64 copy (SSE2, what every
//! x86-64 processor runs) or a second copy compiled for AVX2, chosen at run time.
//!
//! The batch loop ([`crate::exec`]'s `run_group` on lanes, with the wide ops and the copies
//! into and out of the lanes inlined into it) is compiled twice on x86-64. Its wide ops are
//! loops over a batch's 16 lanes; with AVX2 the compiler does them 8 floats at a time
//! instead of 4, with three-operand instructions (about 8 % fewer machine instructions per
//! locomotion frame, docs/performance.md). The choice is made once per batch, from what the
//! processor reports (cached by the standard library) and this module's switch.
//!
//! Both copies compute **bit for bit the same results**: AVX2 adds wider registers, not new
//! arithmetic. Fused multiply-add (`fma`, which rounds once where a multiply and an add
//! round twice) is not enabled, and Rust never fuses a multiply and an add on its own; glam
//! chooses its own code paths when it is compiled (for the build's target), not per
//! function. So a crowd gives the same poses on a processor with AVX2 and one without:
//! `tests/batch_code.rs` checks the AVX2 copy against the baseline frame by frame, and
//! `tests/batch.rs` checks batches against each character run alone.
//!
//! Kernels the loop calls without inlining (the two-bone IK, the pose's global transforms,
//! the world's traces) run the baseline code either way.

use std::sync::atomic::{AtomicBool, Ordering};

/// The machine code batches run on ([`batch_code`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BatchCode {
    /// The baseline copy: SSE2 on x86-64, the build's target elsewhere.
    Baseline,
    /// The copy compiled for AVX2 (x86-64 processors that have it).
    Avx2,
}

impl BatchCode {
    /// Its name as the CLI prints it: `baseline` or `avx2`.
    pub fn name(self) -> &'static str {
        match self {
            BatchCode::Baseline => "baseline",
            BatchCode::Avx2 => "avx2",
        }
    }
}

/// Whether batches may run the AVX2 copy (the default); see [`allow_avx2`].
static AVX2_ALLOWED: AtomicBool = AtomicBool::new(true);

/// Lets batches run the AVX2 copy of the batch loop where the processor has AVX2 (`true`,
/// the default), or keeps every batch on the baseline copy (`false`). For the whole
/// process, from the next batch on; results are the same either way, so this is for
/// measuring the difference (`strider bench --baseline-code`) and for tests.
pub fn allow_avx2(allow: bool) {
    AVX2_ALLOWED.store(allow, Ordering::Relaxed);
}

/// The machine code the next batch runs on: [`BatchCode::Avx2`] when the processor has
/// AVX2 and [`allow_avx2`] has not turned it off, else [`BatchCode::Baseline`].
pub fn batch_code() -> BatchCode {
    #[cfg(target_arch = "x86_64")]
    if AVX2_ALLOWED.load(Ordering::Relaxed) && std::arch::is_x86_feature_detected!("avx2") {
        return BatchCode::Avx2;
    }
    BatchCode::Baseline
}
