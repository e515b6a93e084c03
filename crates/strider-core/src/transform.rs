//! [`Transform`]: translation, rotation and scale, composed parent · child.

use core::ops::{Add, Sub};
use glam::{Affine3A, Mat3A, Quat, Vec3, Vec3A, Vec4};

/// A rigid transform with scale: maps a point `p` to `translation + rotation · (scale ⊙ p)`.
///
/// Translation is in centimetres, in the parent space of whatever the transform positions
/// (the parent bone for a local transform, rig space for a global one).
///
/// Composition (`a * b`) applies `b` first, then `a`, so a global transform is
/// `parent_global * local`. With non-uniform scale this composition is the usual
/// approximation used by animation runtimes: scales multiply component-wise and never
/// shear.
///
/// Laid out in declaration order (`repr(C)`): translation in bytes 0–11, rotation in 16–31,
/// scale in 32–43, so each part lies within one of the three 16-byte words a transform is
/// copied in. Left to reorder, the compiler puts the scale across two of those words, and
/// reading a scale just after its transform was stored (a node reading what the node before
/// it wrote) then waits for the store to reach the cache instead of being forwarded from it.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C)]
pub struct Transform {
    /// Translation in centimetres.
    pub translation: Vec3,
    /// Rotation, a unit quaternion.
    pub rotation: Quat,
    /// Scale per axis of the transformed frame (1 = unscaled).
    pub scale: Vec3,
}

impl Default for Transform {
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl Transform {
    /// The identity: no translation, no rotation, unit scale.
    pub const IDENTITY: Self = Self {
        translation: Vec3::ZERO,
        rotation: Quat::IDENTITY,
        scale: Vec3::ONE,
    };

    /// A transform from its three parts.
    #[must_use]
    pub const fn new(translation: Vec3, rotation: Quat, scale: Vec3) -> Self {
        Self {
            translation,
            rotation,
            scale,
        }
    }

    /// A pure translation (centimetres).
    #[must_use]
    pub const fn from_translation(translation: Vec3) -> Self {
        Self {
            translation,
            rotation: Quat::IDENTITY,
            scale: Vec3::ONE,
        }
    }

    /// A pure rotation.
    #[must_use]
    pub const fn from_rotation(rotation: Quat) -> Self {
        Self {
            translation: Vec3::ZERO,
            rotation,
            scale: Vec3::ONE,
        }
    }

    /// A translation and a rotation with unit scale.
    #[must_use]
    pub const fn from_translation_rotation(translation: Vec3, rotation: Quat) -> Self {
        Self {
            translation,
            rotation,
            scale: Vec3::ONE,
        }
    }

    /// Applies the transform to a point: `t + r · (s ⊙ p)`.
    #[must_use]
    #[inline]
    pub fn transform_point(&self, point: Vec3) -> Vec3 {
        self.translation + self.rotation * (self.scale * point)
    }

    /// Applies rotation and scale to a direction (no translation): `r · (s ⊙ v)`.
    #[must_use]
    #[inline]
    pub fn transform_vector(&self, vector: Vec3) -> Vec3 {
        self.rotation * (self.scale * vector)
    }

    /// The same map as [`Transform::transform_point`] and [`Transform::transform_vector`],
    /// as a matrix: its columns are the rotated, scaled axes `r · (s_i e_i)`. For code that
    /// maps many points through one transform (a matrix product is cheaper than a rotation
    /// by a quaternion). Exact in real arithmetic for any rotation, unit or not (the
    /// rotation of a vector is linear in it); the rounding differs from the quaternion's.
    #[must_use]
    pub fn to_affine(&self) -> Affine3A {
        let axis = |e: Vec3, s: f32| self.rotation * (e * s);
        Affine3A {
            matrix3: Mat3A::from_cols(
                axis(Vec3::X, self.scale.x).into(),
                axis(Vec3::Y, self.scale.y).into(),
                axis(Vec3::Z, self.scale.z).into(),
            ),
            translation: self.translation.into(),
        }
    }

    /// The inverse transform: `self.inverse() * self` is the identity for uniform scale.
    ///
    /// A zero scale component has no inverse; it maps to a zero inverse scale on that
    /// axis instead of infinity, so a collapsed bone never produces NaN.
    #[must_use]
    #[inline]
    pub fn inverse(&self) -> Self {
        let inv_scale = Vec3::from(reciprocal_or_zero(self.scale));
        let inv_rotation = self.rotation.inverse();
        let translation = inv_scale * (inv_rotation * -self.translation);
        Self {
            translation,
            rotation: inv_rotation,
            scale: inv_scale,
        }
    }

    /// `self` expressed relative to `parent` (RigVM's "Make Relative", Unreal's
    /// `GetRelativeTransform`): the local transform `l` with `parent * l == self`, for any
    /// non-zero scale, uniform or not. Rotation `p.r⁻¹ · r` (normalised, as a product in
    /// [`Mul`](core::ops::Mul) is), scale `s / p.s`, translation `(p.r⁻¹ · (t − p.t)) / p.s`;
    /// a zero parent scale component divides by nothing and gives 0 on that axis, as in
    /// [`Transform::inverse`]. For uniform scale this is `parent.inverse() * self`, with one
    /// rotation of a vector fewer.
    #[must_use]
    #[inline]
    pub fn relative_to(&self, parent: &Self) -> Self {
        let inv_scale = reciprocal_or_zero(parent.scale);
        let inv_rotation = parent.rotation.inverse();
        let offset = Vec3A::from(self.translation) - Vec3A::from(parent.translation);
        Self {
            translation: (inv_scale * (inv_rotation * offset)).into(),
            rotation: (inv_rotation * self.rotation).normalize(),
            scale: (inv_scale * Vec3A::from(self.scale)).into(),
        }
    }

    /// The bit patterns of every component: translation, rotation (x, y, z, w), scale.
    #[must_use]
    pub fn to_bits(&self) -> [u32; 10] {
        let (t, r, s) = (self.translation, self.rotation, self.scale);
        [t.x, t.y, t.z, r.x, r.y, r.z, r.w, s.x, s.y, s.z].map(f32::to_bits)
    }

    /// Bit-for-bit equality (unlike `==`, NaN equals an identical NaN and `0.0` differs from
    /// `-0.0`): what determinism checks compare.
    #[must_use]
    pub fn bit_eq(&self, other: &Transform) -> bool {
        self.to_bits() == other.to_bits()
    }

    /// True when every component is finite (no NaN or infinity).
    #[must_use]
    #[inline]
    pub fn is_finite(&self) -> bool {
        all_finite([Vec3A::from(self.translation), Vec3A::from(self.scale)])
            && all_finite([Vec4::from(self.rotation)])
    }

    /// Linear interpolation of translation and scale, shortest-path slerp of rotation;
    /// `alpha` 0 gives `self`, 1 gives `other`.
    #[must_use]
    pub fn interpolate(&self, other: &Self, alpha: f32) -> Self {
        Self {
            translation: self.translation.lerp(other.translation, alpha),
            rotation: self.rotation.slerp(other.rotation, alpha).normalize(),
            scale: self.scale.lerp(other.scale, alpha),
        }
    }
}

impl core::ops::Mul for Transform {
    type Output = Transform;

    /// Parent · child: applies `rhs` first, then `self`.
    #[inline]
    fn mul(self, rhs: Transform) -> Transform {
        Transform {
            translation: self.transform_point(rhs.translation),
            rotation: (self.rotation * rhs.rotation).normalize(),
            scale: self.scale * rhs.scale,
        }
    }
}

/// `1 / x` per axis, or 0 where `x` is 0 (a collapsed axis stays collapsed instead of
/// exploding), for the three axes at once.
#[inline]
fn reciprocal_or_zero(scale: Vec3) -> Vec3A {
    let scale = Vec3A::from(scale);
    Vec3A::select(scale.cmpeq(Vec3A::ZERO), Vec3A::ZERO, Vec3A::ONE / scale)
}

/// Whether every component of `values` is finite (no NaN, no infinity). `x − x` is 0 for
/// every finite `x` and NaN otherwise, so the sum of the differences is zero exactly when
/// all are: one vector comparison for all of them instead of a branch per component (for
/// the checks on hot paths: a transform, a trace's ends and its hit).
#[must_use]
#[inline]
pub fn all_finite<V, const N: usize>(values: [V; N]) -> bool
where
    V: Copy + Default + PartialEq + Add<Output = V> + Sub<Output = V>,
{
    // `Default` is the zero vector (glam's vectors, and `f32`).
    #[allow(clippy::eq_op)]
    let sum = values.iter().fold(V::default(), |sum, &v| sum + (v - v));
    sum == V::default()
}

impl Transform {
    /// A copy of a transform stored a moment ago (an argument, a bone's global just set),
    /// its vectors read with [`load_vec3`], as they were stored.
    #[must_use]
    #[inline(always)]
    pub fn load_stored(&self) -> Transform {
        Transform::new(
            load_vec3(&self.translation).into(),
            self.rotation,
            load_vec3(&self.scale).into(),
        )
    }
}

/// `v` in a SIMD register, read as one 8-byte load of `x, y` and one 4-byte load of `z`:
/// for a `Vec3` stored a moment ago, such as a query's argument or its answer.
///
/// That is how a `Vec3` computed in a SIMD register is stored (`movlps` and `movss`), so
/// each load takes its bytes from one store still in flight and the processor forwards it;
/// a load straddling two recent stores waits until both reach the cache. Left to itself
/// the compiler may read `x` alone and `y, z` together, or 16 bytes at once when more
/// bytes follow `v`, straddling the stores (a world's sphere trace did: 3 to 5 % of a
/// locomotion frame's time, see docs/performance.md). Written by hand because no crate
/// pins the width of a load; the compiler may not widen the inline `movsd`.
#[must_use]
#[inline(always)]
#[allow(unsafe_code)]
pub fn load_vec3(v: &Vec3) -> Vec3A {
    #[cfg(target_arch = "x86_64")]
    {
        use core::arch::x86_64::{__m128, _mm_load_ss, _mm_movelh_ps};
        let xy: __m128;
        // SAFETY: `Vec3` is `#[repr(C)]` x, y, z: its first 8 bytes are x and y, read by
        // one unaligned `movsd` (written out, so that the compiler does not widen it into a
        // 16-byte load when more bytes follow `v`); `v.z` is a valid `f32`; SSE2 is part
        // of x86_64.
        unsafe {
            core::arch::asm!(
                "movsd {xy}, qword ptr [{p}]",
                xy = out(xmm_reg) xy,
                p = in(reg) core::ptr::from_ref(v),
                options(pure, readonly, nostack, preserves_flags),
            );
            Vec3A::from(_mm_movelh_ps(xy, _mm_load_ss(&v.z)))
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    Vec3A::from(*v)
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f32::consts::FRAC_PI_2;

    fn assert_vec_near(a: Vec3, b: Vec3) {
        assert!(
            (a - b).length() < 1e-4,
            "{a} != {b} (difference {})",
            (a - b).length()
        );
    }

    #[test]
    fn composition_applies_the_child_first() {
        // Parent: 90° about Z then move 10 along X. Child: 5 along X.
        let parent = Transform::from_translation_rotation(
            Vec3::new(10.0, 0.0, 0.0),
            Quat::from_rotation_z(FRAC_PI_2),
        );
        let child = Transform::from_translation(Vec3::new(5.0, 0.0, 0.0));
        let global = parent * child;
        // The child's offset (5,0,0) is rotated to (0,5,0) and then moved by (10,0,0).
        assert_vec_near(global.translation, Vec3::new(10.0, 5.0, 0.0));
        assert_vec_near(global.transform_point(Vec3::X), Vec3::new(10.0, 6.0, 0.0));
    }

    #[test]
    fn scale_applies_before_rotation() {
        let t = Transform::new(
            Vec3::ZERO,
            Quat::from_rotation_z(FRAC_PI_2),
            Vec3::new(2.0, 1.0, 1.0),
        );
        // (1,0,0) scaled to (2,0,0), then rotated 90° about Z to (0,2,0).
        assert_vec_near(t.transform_point(Vec3::X), Vec3::new(0.0, 2.0, 0.0));
    }

    #[test]
    fn the_matrix_maps_as_the_transform_does() {
        // Unit and non-unit rotations, non-uniform and negative scales: the matrix's map
        // agrees with the quaternion's to rounding.
        let rotations = [
            Quat::IDENTITY,
            Quat::from_rotation_z(0.8),
            Quat::from_rotation_x(0.7) * Quat::from_rotation_y(-2.1),
            Quat::from_xyzw(0.3, -0.2, 0.5, 0.9), // length 1.1
            Quat::from_xyzw(0.0, 0.0, 0.0, 0.0),
        ];
        let scales = [Vec3::ONE, Vec3::new(2.0, 0.5, -1.0), Vec3::ZERO];
        let p = Vec3::new(13.0, -4.5, 7.25);
        for rotation in rotations {
            for scale in scales {
                let t = Transform::new(Vec3::new(100.0, -20.0, 3.0), rotation, scale);
                let m = t.to_affine();
                assert_vec_near(m.transform_point3(p), t.transform_point(p));
                assert_vec_near(m.transform_vector3(p), t.transform_vector(p));
            }
        }
        // By hand: 90° about Z takes +X to +Y; scale 2 along X first.
        let t = Transform::new(
            Vec3::new(1.0, 0.0, 0.0),
            Quat::from_rotation_z(FRAC_PI_2),
            Vec3::new(2.0, 1.0, 1.0),
        );
        assert_vec_near(
            t.to_affine().transform_point3(Vec3::X),
            Vec3::new(1.0, 2.0, 0.0),
        );
    }

    #[test]
    fn inverse_undoes_the_transform() {
        let t = Transform::new(
            Vec3::new(3.0, -4.0, 12.0),
            Quat::from_rotation_x(0.7) * Quat::from_rotation_z(-1.1),
            Vec3::splat(2.0),
        );
        let p = Vec3::new(1.0, 2.0, 3.0);
        assert_vec_near(t.inverse().transform_point(t.transform_point(p)), p);
        let id = t.inverse() * t;
        assert_vec_near(id.translation, Vec3::ZERO);
        assert_vec_near(id.scale, Vec3::ONE);
    }

    #[test]
    fn a_loaded_vector_holds_its_three_components_bit_for_bit() {
        let nan = f32::from_bits(0x7fc0_1234);
        for v in [
            Vec3::new(1.5, -2.25, 1e30),
            Vec3::new(-0.0, 0.0, f32::MIN_POSITIVE / 4.0),
            Vec3::new(nan, f32::INFINITY, f32::NEG_INFINITY),
        ] {
            let a = load_vec3(&v);
            assert_eq!(
                a.to_array().map(f32::to_bits),
                v.to_array().map(f32::to_bits),
                "{v:?}"
            );
        }
        // From inside an array (unaligned to 8 and 16 bytes), each element itself.
        let vs = [Vec3::X, Vec3::Y, Vec3::Z, Vec3::new(4.0, 5.0, 6.0)];
        for v in &vs {
            assert_eq!(Vec3::from(load_vec3(v)), *v);
        }
    }

    #[test]
    fn a_stored_transform_loads_bit_for_bit() {
        let t = Transform::new(
            Vec3::new(-0.0, f32::from_bits(0x7fc0_0042), 3.5),
            Quat::from_xyzw(0.1, -0.2, 0.3, 0.9),
            Vec3::new(f32::MIN_POSITIVE / 8.0, 0.0, -2.0),
        );
        assert!(t.load_stored().bit_eq(&t));
    }

    #[test]
    fn finite_means_every_component_finite() {
        let t = Transform::new(
            Vec3::new(1.0, -2.0, 3e38),
            Quat::from_xyzw(0.0, -0.0, 1e-42, 1.0),
            Vec3::new(-1.0, 0.0, 2.0),
        );
        assert!(t.is_finite());
        for k in 0..10 {
            for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
                let mut c = t.to_bits().map(f32::from_bits);
                c[k] = bad;
                let broken = Transform::new(
                    Vec3::new(c[0], c[1], c[2]),
                    Quat::from_xyzw(c[3], c[4], c[5], c[6]),
                    Vec3::new(c[7], c[8], c[9]),
                );
                assert!(!broken.is_finite(), "component {k} = {bad}");
            }
        }
    }

    #[test]
    fn bit_equality_is_stricter_than_equality() {
        let a = Transform::from_translation(Vec3::new(0.0, 1.0, 2.0));
        let mut b = a;
        b.translation.x = -0.0;
        assert_eq!(a, b);
        assert!(!a.bit_eq(&b), "0.0 and -0.0 differ in their bits");
        let mut nan = a;
        nan.scale.y = f32::NAN;
        assert_ne!(nan, nan);
        assert!(nan.bit_eq(&nan));
        assert_eq!(a.to_bits()[1], 1.0f32.to_bits());
    }

    #[test]
    fn zero_scale_inverts_without_nan() {
        let t = Transform::new(Vec3::X, Quat::IDENTITY, Vec3::new(0.0, 1.0, 1.0));
        assert!(t.inverse().is_finite());
    }

    #[test]
    fn relative_to_recovers_the_local_transform() {
        let parent = Transform::from_translation_rotation(
            Vec3::new(0.0, 0.0, 95.0),
            Quat::from_rotation_y(-FRAC_PI_2),
        );
        let local = Transform::from_translation(Vec3::new(-40.0, 0.0, 0.0));
        let global = parent * local;
        // -40 along the parent's X, which points up (+Z) after -90° about Y: 95 - 40 = 55.
        assert_vec_near(global.translation, Vec3::new(0.0, 0.0, 55.0));
        let back = global.relative_to(&parent);
        assert_vec_near(back.translation, local.translation);
    }

    #[test]
    fn relative_to_inverts_a_parent_with_non_uniform_scale() {
        // Parent at (10, 0, 0), turned 90° about Z (X → Y), stretched 2× along its own X.
        // A child 2 cm along the parent's X sits at (10, 0, 0) + Rz(90°)·(2·2, 0, 0) =
        // (10, 4, 0); its scale (1, 3, 1) becomes (2, 3, 1). Back from the globals: (2, 0, 0)
        // and (1, 3, 1). (`parent.inverse() * global` gives (4, 5, 0) here: the inverse of a
        // non-uniformly scaled rotation is not a transform of this form.)
        let parent = Transform::new(
            Vec3::new(10.0, 0.0, 0.0),
            Quat::from_rotation_z(FRAC_PI_2),
            Vec3::new(2.0, 1.0, 1.0),
        );
        let global = Transform::new(
            Vec3::new(10.0, 4.0, 0.0),
            Quat::from_rotation_z(FRAC_PI_2) * Quat::from_rotation_x(0.5),
            Vec3::new(2.0, 3.0, 1.0),
        );
        let local = global.relative_to(&parent);
        assert_vec_near(local.translation, Vec3::new(2.0, 0.0, 0.0));
        assert_vec_near(local.scale, Vec3::new(1.0, 3.0, 1.0));
        assert!(local.rotation.angle_between(Quat::from_rotation_x(0.5)) < 1e-6);
        // And the parent carries it back onto the global.
        let again = parent * local;
        assert_vec_near(again.translation, global.translation);
        assert_vec_near(again.scale, global.scale);
    }

    #[test]
    fn relative_to_a_collapsed_parent_axis_stays_finite() {
        let parent = Transform::new(Vec3::ZERO, Quat::IDENTITY, Vec3::new(0.0, 2.0, 1.0));
        let global = Transform::new(Vec3::new(3.0, 4.0, 5.0), Quat::IDENTITY, Vec3::ONE);
        let local = global.relative_to(&parent);
        assert!(local.is_finite());
        assert_vec_near(local.translation, Vec3::new(0.0, 2.0, 5.0));
        assert_vec_near(local.scale, Vec3::new(0.0, 0.5, 1.0));
    }
}
