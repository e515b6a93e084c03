//! Rotation math on plain `f32` components, in one fixed order of operations.
//!
//! glam's `Quat` is a SIMD register holding one rotation: its products shuffle lanes
//! within that one value, which is fast for one rotation at a time but leaves nothing for
//! a compiler to vectorise when the same product runs for a crowd's 16 characters at once.
//! The functions here do the same arithmetic on separate components (`[x, y, z, w]`,
//! `[x, y, z]`), so that a loop of them over components laid out one array per component
//! vectorises across characters, and the one-character kernels call them too, so both
//! give the same bits.
//!
//! The order of operations is glam's (0.33, SSE2, without FMA): on x86-64 builds without
//! `fma` the results equal glam's `Quat::length`, `Quat / f32`, `Quat::normalize`,
//! `Quat * Quat` and `Quat * Vec3` bit for bit; elsewhere they may differ from glam in the
//! last bit, never between the one-character and the crowd paths (a crowd's op that
//! computes with these where its one-character handler calls glam does so only where they
//! agree). No fused multiply-add is used (Rust never fuses on its own), so the results are
//! the same on every target.

/// `[x, y, z, w]` normalised, or the identity when its length is zero or not finite
/// (a rotation, unitless). The length sums the squares as `(x² + z²) + (y² + w²)`.
#[must_use]
#[inline(always)]
pub fn unit_parts(q: [f32; 4]) -> [f32; 4] {
    let [x, y, z, w] = q;
    let len = ((x * x + z * z) + (y * y + w * w)).sqrt();
    if len > 0.0 && len.is_finite() {
        [x / len, y / len, z / len, w / len]
    } else {
        [0.0, 0.0, 0.0, 1.0]
    }
}

/// `[x, y, z, w]` divided by its length, as glam's `Quat::normalize` computes it: without
/// [`unit_parts`]' fallback, so a zero or non-finite rotation gives NaNs (or zeros), as
/// glam's does. The length sums the squares as `(x² + z²) + (y² + w²)`.
#[must_use]
#[inline(always)]
pub fn normalize_parts(q: [f32; 4]) -> [f32; 4] {
    let [x, y, z, w] = q;
    let len = ((x * x + z * z) + (y * y + w * w)).sqrt();
    [x / len, y / len, z / len, w / len]
}

/// The product `a · b` of two rotations `[x, y, z, w]` (`b` applied first). Of any
/// number type with these operations: `f32`, or one per chain of a batch (the two-bone
/// IK's lanes), in the same order.
#[must_use]
#[inline(always)]
pub fn mul_parts<T>(a: [T; 4], b: [T; 4]) -> [T; 4]
where
    T: Copy + core::ops::Add<Output = T> + core::ops::Mul<Output = T> + core::ops::Neg<Output = T>,
{
    let [lx, ly, lz, lw] = a;
    let [rx, ry, rz, rw] = b;
    [
        (lx * rw + lw * rx) + (-(lz * ry) + ly * rz),
        (-(lx * rz) + lw * ry) + (lz * rx + ly * rw),
        (lx * ry + lw * rz) + (lz * rw + -(ly * rx)),
        (-(lx * rx) + lw * rw) + (-(lz * rz) + -(ly * ry)),
    ]
}

/// `v` rotated by the unit rotation `q` = `[x, y, z, w]`, as
/// `v·(w² − |b|²) + b·(2 b·v) + (b × v)·2w` with `b` = `[x, y, z]` (any unit of `v`).
#[must_use]
#[inline(always)]
pub fn rotate_parts(q: [f32; 4], v: [f32; 3]) -> [f32; 3] {
    let [x, y, z, w] = q;
    let [vx, vy, vz] = v;
    let k = w * w - ((x * x + y * y) + z * z);
    let d = ((vx * x + vy * y) + vz * z) * 2.0;
    let w2 = w * 2.0;
    let cross = [y * vz - vy * z, z * vx - vz * x, x * vy - vx * y];
    [
        (vx * k + x * d) + cross[0] * w2,
        (vy * k + y * d) + cross[1] * w2,
        (vz * k + z * d) + cross[2] * w2,
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{Quat, Vec3};

    /// Rotations and vectors of every sort: axes, odd angles, tiny and huge components.
    fn samples() -> (Vec<[f32; 4]>, Vec<[f32; 3]>) {
        let mut qs = vec![
            [0.0, 0.0, 0.0, 1.0],
            [1.0, 0.0, 0.0, 0.0],
            [0.3, -1.2, 2.0, 0.5],
            [1e-20, 0.0, -3e-21, 1e-20],
        ];
        let mut vs = vec![[0.0, 0.0, 0.0], [1e-30, -3.0, 7.5], [123.456, -0.001, 1e6]];
        for i in 0..40 {
            let t = i as f32 * 0.731;
            let axis = Vec3::new(t.sin(), (t * 1.7).cos(), 0.3 - t.cos()).normalize();
            qs.push(Quat::from_axis_angle(axis, t * 2.9 - 40.0).to_array());
            vs.push([t.cos() * 90.0, t * -13.0, (t * 0.37).sin() * 4.0]);
        }
        (qs, vs)
    }

    #[test]
    fn rotation_by_hand() {
        // 90° about Z takes X to Y; composing two of them is 180°, which takes X to −X.
        let h = core::f32::consts::FRAC_1_SQRT_2;
        let z90 = [0.0, 0.0, h, h];
        let y = rotate_parts(z90, [1.0, 0.0, 0.0]);
        assert!((y[0]).abs() < 1e-6 && (y[1] - 1.0).abs() < 1e-6 && y[2].abs() < 1e-6);
        let z180 = mul_parts(z90, z90);
        let back = rotate_parts(z180, [1.0, 0.0, 0.0]);
        assert!((back[0] + 1.0).abs() < 1e-6 && back[1].abs() < 1e-6);
        // (0, 0, 3, 4) has length 5.
        assert_eq!(unit_parts([0.0, 0.0, 3.0, 4.0]), [0.0, 0.0, 0.6, 0.8]);
        // Zero, infinite and NaN rotations normalise to the identity.
        for q in [
            [0.0; 4],
            [f32::INFINITY, 0.0, 0.0, 1.0],
            [f32::NAN, 0.0, 0.0, 1.0],
        ] {
            assert_eq!(unit_parts(q), [0.0, 0.0, 0.0, 1.0]);
        }
    }

    /// On x86-64 without FMA (the build the tests run in) these are glam's own results, bit
    /// for bit; elsewhere within a few units in the last place of them.
    #[test]
    fn the_same_as_glam() {
        let exact = cfg!(all(target_arch = "x86_64", not(target_feature = "fma")));
        let close = |a: f32, b: f32| {
            if exact {
                a.to_bits() == b.to_bits()
            } else {
                (a - b).abs() <= 1e-5 * a.abs().max(b.abs()).max(1.0)
            }
        };
        let (qs, vs) = samples();
        for &a in &qs {
            let ga = Quat::from_array(a);
            let len = ga.length();
            if len > 0.0 && len.is_finite() {
                for (m, g) in unit_parts(a).iter().zip((ga / len).to_array()) {
                    assert!(close(*m, g), "unit {a:?}");
                }
            }
            for (m, g) in normalize_parts(a).iter().zip(ga.normalize().to_array()) {
                assert!(
                    close(*m, g) || (m.is_nan() && g.is_nan()),
                    "normalize {a:?}"
                );
            }
            for &b in &qs {
                let ours = mul_parts(a, b);
                let theirs = (ga * Quat::from_array(b)).to_array();
                for (m, g) in ours.iter().zip(theirs) {
                    assert!(close(*m, g), "{a:?} * {b:?}: {ours:?} against {theirs:?}");
                }
            }
            for &v in &vs {
                let ours = rotate_parts(a, v);
                let theirs = (ga * Vec3::from_array(v)).to_array();
                for (m, g) in ours.iter().zip(theirs) {
                    assert!(close(*m, g), "{a:?} * {v:?}: {ours:?} against {theirs:?}");
                }
            }
        }
    }
}
