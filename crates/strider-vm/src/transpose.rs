//! A batch's vectors and rotations moved between the lanes' layout (one value after
//! another: `x0 y0 z0 x1 y1 z1 …`) and one array per component (`[x0 x1 …]`, `[y0 y1 …]`,
//! …), which is how the wide ops of [`crate::lanes`] compute on them.
//!
//! Written by hand because the compiler moves such strided data one float at a time: a
//! block of 16 vectors broken into its components took 96 scalar loads and stores. On
//! x86-64 four values at a time go through SSE shuffles instead (SSE2 is part of every
//! x86-64 processor, so the same code serves the batch loop's baseline and AVX2 builds);
//! elsewhere the plain loops below run. Only data moves here, never arithmetic, so every
//! bit (NaN payloads included) arrives as it left.

// Blocks are read and written through SSE loads and stores of four floats.
#![allow(unsafe_code)]

use crate::exec::BATCH;
use glam::{Quat, Vec3};
use strider_core::Transform;

/// Component arrays of a block of vectors: `[x, y, z]`, each one float per lane.
pub(crate) type Vec3Columns = [[f32; BATCH]; 3];

/// Component arrays of a block of rotations: `[x, y, z, w]`, each one float per lane.
pub(crate) type QuatColumns = [[f32; BATCH]; 4];

// Four lanes at a time.
const _: () = assert!(BATCH.is_multiple_of(4));

#[cfg(target_arch = "x86_64")]
mod sse {
    use super::{BATCH, QuatColumns, Vec3Columns};
    use core::arch::x86_64::{
        __m128, _mm_loadu_ps, _mm_movehl_ps, _mm_movelh_ps, _mm_shuffle_ps, _mm_storeu_ps,
        _mm_unpackhi_ps, _mm_unpacklo_ps,
    };

    /// `_MM_SHUFFLE(d, c, b, a)`: lanes `a`, `b` of the first operand, then `c`, `d` of
    /// the second.
    const fn pick(d: i32, c: i32, b: i32, a: i32) -> i32 {
        (d << 6) | (c << 4) | (b << 2) | a
    }

    /// `BATCH` vectors (`3 * BATCH` floats from `from`) into component arrays.
    ///
    /// # Safety
    /// `from` must be valid for reads of `3 * BATCH` floats.
    #[inline(always)]
    pub(super) unsafe fn vec3_columns(from: *const f32) -> Vec3Columns {
        let mut cols = [[0.0; BATCH]; 3];
        for g in 0..BATCH / 4 {
            // SAFETY: floats `12 g .. 12 g + 12` of `3 * BATCH` (the caller's contract);
            // the stores are within the columns' `BATCH` floats.
            unsafe {
                let a = _mm_loadu_ps(from.add(12 * g)); // x0 y0 z0 x1
                let b = _mm_loadu_ps(from.add(12 * g + 4)); // y1 z1 x2 y2
                let c = _mm_loadu_ps(from.add(12 * g + 8)); // z2 x3 y3 z3
                let x2x3 = _mm_shuffle_ps::<{ pick(1, 1, 2, 2) }>(b, c);
                let x = _mm_shuffle_ps::<{ pick(2, 0, 3, 0) }>(a, x2x3);
                let y0y1 = _mm_shuffle_ps::<{ pick(0, 0, 1, 1) }>(a, b);
                let y2y3 = _mm_shuffle_ps::<{ pick(2, 2, 3, 3) }>(b, c);
                let y = _mm_shuffle_ps::<{ pick(2, 0, 2, 0) }>(y0y1, y2y3);
                let z0z1 = _mm_shuffle_ps::<{ pick(1, 1, 2, 2) }>(a, b);
                let z = _mm_shuffle_ps::<{ pick(3, 0, 2, 0) }>(z0z1, c);
                for (col, v) in cols.iter_mut().zip([x, y, z]) {
                    _mm_storeu_ps(col.as_mut_ptr().add(4 * g), v);
                }
            }
        }
        cols
    }

    /// Component arrays into `BATCH` vectors (`3 * BATCH` floats at `to`).
    ///
    /// # Safety
    /// `to` must be valid for writes of `3 * BATCH` floats.
    #[inline(always)]
    pub(super) unsafe fn vec3_rows(cols: &Vec3Columns, to: *mut f32) {
        for g in 0..BATCH / 4 {
            // SAFETY: within the columns' `BATCH` floats, and floats `12 g .. 12 g + 12`
            // of `3 * BATCH` (the caller's contract).
            unsafe {
                let [x, y, z]: [__m128; 3] =
                    std::array::from_fn(|c| _mm_loadu_ps(cols[c].as_ptr().add(4 * g)));
                let x0y0 = _mm_shuffle_ps::<{ pick(0, 0, 0, 0) }>(x, y);
                let z0x1 = _mm_shuffle_ps::<{ pick(1, 1, 0, 0) }>(z, x);
                let a = _mm_shuffle_ps::<{ pick(2, 0, 2, 0) }>(x0y0, z0x1);
                let y1z1 = _mm_shuffle_ps::<{ pick(1, 1, 1, 1) }>(y, z);
                let x2y2 = _mm_shuffle_ps::<{ pick(2, 2, 2, 2) }>(x, y);
                let b = _mm_shuffle_ps::<{ pick(2, 0, 2, 0) }>(y1z1, x2y2);
                let z2x3 = _mm_shuffle_ps::<{ pick(3, 3, 2, 2) }>(z, x);
                let y3z3 = _mm_shuffle_ps::<{ pick(3, 3, 3, 3) }>(y, z);
                let c = _mm_shuffle_ps::<{ pick(2, 0, 2, 0) }>(z2x3, y3z3);
                _mm_storeu_ps(to.add(12 * g), a);
                _mm_storeu_ps(to.add(12 * g + 4), b);
                _mm_storeu_ps(to.add(12 * g + 8), c);
            }
        }
    }

    /// A 4×4 transpose: rows `r` become columns.
    #[inline(always)]
    fn transpose(r: [__m128; 4]) -> [__m128; 4] {
        // SAFETY: SSE is part of every x86-64 processor.
        unsafe {
            let t0 = _mm_unpacklo_ps(r[0], r[1]); // a0 b0 a1 b1
            let t1 = _mm_unpacklo_ps(r[2], r[3]); // c0 d0 c1 d1
            let t2 = _mm_unpackhi_ps(r[0], r[1]); // a2 b2 a3 b3
            let t3 = _mm_unpackhi_ps(r[2], r[3]); // c2 d2 c3 d3
            [
                _mm_movelh_ps(t0, t1),
                _mm_movehl_ps(t1, t0),
                _mm_movelh_ps(t2, t3),
                _mm_movehl_ps(t3, t2),
            ]
        }
    }

    /// `BATCH` rotations (`4 * BATCH` floats from `from`) into component arrays.
    ///
    /// # Safety
    /// `from` must be valid for reads of `4 * BATCH` floats.
    #[inline(always)]
    pub(super) unsafe fn quat_columns(from: *const f32) -> QuatColumns {
        // SAFETY: the rotations lie four floats apart (the caller's contract).
        unsafe { strided_quat_columns(from, 4) }
    }

    /// `BATCH` runs of four floats (from `from`, one every `stride` floats: the rotations
    /// of a block of transforms) into component arrays.
    ///
    /// # Safety
    /// `from` must be valid for reads of four floats every `stride` floats, `BATCH` times.
    #[inline(always)]
    pub(super) unsafe fn strided_quat_columns(from: *const f32, stride: usize) -> QuatColumns {
        let mut cols = [[0.0; BATCH]; 4];
        for g in 0..BATCH / 4 {
            // SAFETY: rotations `4 g .. 4 g + 4` (the caller's contract), and within the
            // columns' `BATCH` floats.
            unsafe {
                let rows = std::array::from_fn(|k| _mm_loadu_ps(from.add(stride * (4 * g + k))));
                for (col, v) in cols.iter_mut().zip(transpose(rows)) {
                    _mm_storeu_ps(col.as_mut_ptr().add(4 * g), v);
                }
            }
        }
        cols
    }

    /// Component arrays into `BATCH` rotations (`4 * BATCH` floats at `to`).
    ///
    /// # Safety
    /// `to` must be valid for writes of `4 * BATCH` floats.
    #[inline(always)]
    pub(super) unsafe fn quat_rows(cols: &QuatColumns, to: *mut f32) {
        for g in 0..BATCH / 4 {
            // SAFETY: within the columns' `BATCH` floats, and floats `16 g .. 16 g + 16` of
            // `4 * BATCH` (the caller's contract).
            unsafe {
                let rows = std::array::from_fn(|c| _mm_loadu_ps(cols[c].as_ptr().add(4 * g)));
                for (k, v) in transpose(rows).into_iter().enumerate() {
                    _mm_storeu_ps(to.add(16 * g + 4 * k), v);
                }
            }
        }
    }
}

/// The component arrays of a block of vectors.
#[inline(always)]
pub(crate) fn vec3_columns(block: &[Vec3; BATCH]) -> Vec3Columns {
    #[cfg(target_arch = "x86_64")]
    {
        // SAFETY: a `Vec3` is three `f32`s (`repr(C)`), so the block is `3 * BATCH` floats.
        unsafe { sse::vec3_columns(block.as_ptr().cast()) }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        plain::vec3_columns(block)
    }
}

/// Writes component arrays `cols` into a block of vectors.
#[inline(always)]
pub(crate) fn vec3_rows(cols: &Vec3Columns, block: &mut [Vec3; BATCH]) {
    #[cfg(target_arch = "x86_64")]
    {
        // SAFETY: as in `vec3_columns`.
        unsafe { sse::vec3_rows(cols, block.as_mut_ptr().cast()) }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        plain::vec3_rows(cols, block)
    }
}

/// The component arrays of a block of rotations.
#[inline(always)]
pub(crate) fn quat_columns(block: &[Quat; BATCH]) -> QuatColumns {
    #[cfg(target_arch = "x86_64")]
    {
        // SAFETY: a `Quat` is four `f32`s, so the block is `4 * BATCH` floats.
        unsafe { sse::quat_columns(block.as_ptr().cast()) }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        plain::quat_columns(block)
    }
}

/// The component arrays of a block of transforms' rotations.
#[inline(always)]
pub(crate) fn rotation_columns(block: &[Transform; BATCH]) -> QuatColumns {
    #[cfg(target_arch = "x86_64")]
    {
        const STRIDE: usize = size_of::<Transform>() / size_of::<f32>();
        let first = &raw const block[0].rotation;
        // SAFETY: each transform's rotation is four floats, `STRIDE` floats after the one
        // before (`block` is an array of transforms).
        unsafe { sse::strided_quat_columns(first.cast(), STRIDE) }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        plain::rotation_columns(block)
    }
}

/// The component arrays of a block of transforms' scales.
#[inline(always)]
pub(crate) fn scale_columns(block: &[Transform; BATCH]) -> Vec3Columns {
    #[cfg(target_arch = "x86_64")]
    {
        const STRIDE: usize = size_of::<Transform>() / size_of::<f32>();
        // A transform's scale follows its rotation's `w` (`Transform` is `repr(C)`, the
        // rotation at byte 16, the scale at 32): the four floats from that `w` on are all
        // values (the padding after the translation and the scale is not read).
        const _: () = assert!(
            std::mem::offset_of!(Transform, rotation) == 16
                && std::mem::offset_of!(Transform, scale) == 32
        );
        let first = (&raw const block[0].scale).cast::<f32>().wrapping_sub(1);
        // SAFETY: each transform's rotation `w` and scale are four floats in a row,
        // `STRIDE` floats after the one before.
        let [_, x, y, z] = unsafe { sse::strided_quat_columns(first, STRIDE) };
        [x, y, z]
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        plain::scale_columns(block)
    }
}

/// Writes component arrays `cols` into a block of rotations.
#[inline(always)]
pub(crate) fn quat_rows(cols: &QuatColumns, block: &mut [Quat; BATCH]) {
    #[cfg(target_arch = "x86_64")]
    {
        // SAFETY: as in `quat_columns`.
        unsafe { sse::quat_rows(cols, block.as_mut_ptr().cast()) }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        plain::quat_rows(cols, block)
    }
}

/// The same moves one float at a time: the other targets' code, and what the tests hold
/// the SSE code to.
#[cfg(any(test, not(target_arch = "x86_64")))]
mod plain {
    use super::{BATCH, QuatColumns, Vec3Columns};
    use glam::{Quat, Vec3};
    use strider_core::Transform;

    pub(super) fn vec3_columns(block: &[Vec3; BATCH]) -> Vec3Columns {
        std::array::from_fn(|c| std::array::from_fn(|m| block[m][c]))
    }

    pub(super) fn vec3_rows(cols: &Vec3Columns, block: &mut [Vec3; BATCH]) {
        for (m, v) in block.iter_mut().enumerate() {
            *v = Vec3::new(cols[0][m], cols[1][m], cols[2][m]);
        }
    }

    pub(super) fn quat_columns(block: &[Quat; BATCH]) -> QuatColumns {
        std::array::from_fn(|c| std::array::from_fn(|m| block[m].to_array()[c]))
    }

    pub(super) fn rotation_columns(block: &[Transform; BATCH]) -> QuatColumns {
        std::array::from_fn(|c| std::array::from_fn(|m| block[m].rotation.to_array()[c]))
    }

    pub(super) fn scale_columns(block: &[Transform; BATCH]) -> Vec3Columns {
        std::array::from_fn(|c| std::array::from_fn(|m| block[m].scale[c]))
    }

    pub(super) fn quat_rows(cols: &QuatColumns, block: &mut [Quat; BATCH]) {
        for (m, q) in block.iter_mut().enumerate() {
            *q = Quat::from_array(std::array::from_fn(|c| cols[c][m]));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Distinct bit patterns for every float of a block: ordinary values, `-0.0`, and
    /// NaNs with their own payloads, so a float moved to the wrong place or changed shows.
    fn pattern(k: usize) -> f32 {
        match k % 5 {
            0 => -0.0,
            1 => f32::from_bits(0x7fc0_0000 | k as u32),
            _ => k as f32 * 1.5 - 20.0,
        }
    }

    fn bits<const C: usize>(cols: &[[f32; BATCH]; C]) -> Vec<u32> {
        cols.iter().flatten().map(|x| x.to_bits()).collect()
    }

    #[test]
    fn vectors_to_columns_and_back_move_every_bit() {
        let block: [Vec3; BATCH] = std::array::from_fn(|m| {
            Vec3::new(pattern(3 * m), pattern(3 * m + 1), pattern(3 * m + 2))
        });
        let cols = vec3_columns(&block);
        let expected: Vec3Columns =
            std::array::from_fn(|c| std::array::from_fn(|m| pattern(3 * m + c)));
        assert_eq!(bits(&cols), bits(&expected));
        assert_eq!(bits(&cols), bits(&plain::vec3_columns(&block)));
        let mut back = [Vec3::ZERO; BATCH];
        vec3_rows(&cols, &mut back);
        let flat = |b: &[Vec3; BATCH]| {
            b.iter()
                .flat_map(|v| v.to_array())
                .map(f32::to_bits)
                .collect::<Vec<_>>()
        };
        assert_eq!(flat(&back), flat(&block));
        let mut plain_back = [Vec3::ZERO; BATCH];
        plain::vec3_rows(&cols, &mut plain_back);
        assert_eq!(flat(&plain_back), flat(&block));
    }

    #[test]
    fn rotations_to_columns_and_back_move_every_bit() {
        let block: [Quat; BATCH] =
            std::array::from_fn(|m| Quat::from_array(std::array::from_fn(|c| pattern(4 * m + c))));
        let cols = quat_columns(&block);
        let expected: QuatColumns =
            std::array::from_fn(|c| std::array::from_fn(|m| pattern(4 * m + c)));
        assert_eq!(bits(&cols), bits(&expected));
        assert_eq!(bits(&cols), bits(&plain::quat_columns(&block)));
        let transforms: [Transform; BATCH] = std::array::from_fn(|m| {
            Transform::new(
                Vec3::splat(pattern(m)),
                block[m],
                Vec3::new(
                    pattern(3 * m + 100),
                    pattern(3 * m + 101),
                    pattern(3 * m + 102),
                ),
            )
        });
        assert_eq!(bits(&rotation_columns(&transforms)), bits(&cols));
        let scales: [Vec3; BATCH] = std::array::from_fn(|m| transforms[m].scale);
        assert_eq!(
            bits(&scale_columns(&transforms)),
            bits(&vec3_columns(&scales))
        );
        assert_eq!(
            bits(&plain::scale_columns(&transforms)),
            bits(&vec3_columns(&scales))
        );
        assert_eq!(bits(&plain::rotation_columns(&transforms)), bits(&cols));
        let mut back = [Quat::IDENTITY; BATCH];
        quat_rows(&cols, &mut back);
        let flat = |b: &[Quat; BATCH]| {
            b.iter()
                .flat_map(|q| q.to_array())
                .map(f32::to_bits)
                .collect::<Vec<_>>()
        };
        assert_eq!(flat(&back), flat(&block));
        let mut plain_back = [Quat::IDENTITY; BATCH];
        plain::quat_rows(&cols, &mut plain_back);
        assert_eq!(flat(&plain_back), flat(&block));
    }
}
