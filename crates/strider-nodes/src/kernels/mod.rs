//! Node kernels: the math of each node as a plain function of its inputs, with the
//! fallback for degenerate input written down. No VM, no allocation (except where a
//! kernel fills a caller-owned buffer).

pub mod locomotion;
pub mod parts;
pub mod spline;
pub mod two_bone_ik;

use glam::{Quat, Vec3, Vec4};
use strider_core::{BoneIndex, Skeleton, Transform};

const DEG: f32 = core::f32::consts::PI / 180.0;

/// `a / b`, or 0 when `b` is 0.
#[must_use]
#[inline]
pub fn div_f(a: f32, b: f32) -> f32 {
    if b == 0.0 { 0.0 } else { a / b }
}

/// `a / b` truncating, or 0 when `b` is 0 (and wrapping for `MIN / -1`).
#[must_use]
#[inline]
pub fn div_i(a: i32, b: i32) -> i32 {
    if b == 0 { 0 } else { a.wrapping_div(b) }
}

/// Component-wise `a / b`, 0 where a component of `b` is 0.
#[must_use]
#[inline]
pub fn div_v(a: Vec3, b: Vec3) -> Vec3 {
    Vec3::new(div_f(a.x, b.x), div_f(a.y, b.y), div_f(a.z, b.z))
}

/// Floored remainder `a − b·floor(a/b)`: the sign of `b`; 0 when `b` is 0.
#[must_use]
#[inline]
pub fn mod_f(a: f32, b: f32) -> f32 {
    if b == 0.0 {
        0.0
    } else {
        a - b * (a / b).floor()
    }
}

/// Floored integer remainder with the sign of `b`; 0 when `b` is 0.
#[must_use]
#[inline]
pub fn mod_i(a: i32, b: i32) -> i32 {
    if b == 0 {
        0
    } else {
        let r = a.wrapping_rem(b);
        if r != 0 && ((r < 0) != (b < 0)) {
            r + b
        } else {
            r
        }
    }
}

/// `value − floor(value)`, in [0, 1). Guarded so rounding never returns exactly 1.
#[must_use]
#[inline]
pub fn fract(value: f32) -> f32 {
    let f = value - value.floor();
    if f >= 1.0 { 0.0 } else { f }
}

/// `value` in `[min, max]`; `max` when the bounds are crossed.
#[must_use]
#[inline]
pub fn clamp_f(value: f32, min: f32, max: f32) -> f32 {
    value.max(min).min(max)
}

/// Linear remap of `value` from `[in_min, in_max]` to `[out_min, out_max]`, optionally
/// clamped to the output range. A zero-width input range gives `out_min`.
#[must_use]
#[inline]
pub fn remap(value: f32, in_min: f32, in_max: f32, out_min: f32, out_max: f32, clamp: bool) -> f32 {
    let width = in_max - in_min;
    if width == 0.0 {
        return out_min;
    }
    let t = (value - in_min) / width;
    let t = if clamp { t.clamp(0.0, 1.0) } else { t };
    out_min + (out_max - out_min) * t
}

/// Smooth Hermite step of `value` over `[min, max]`: with `t = clamp((value − min) /
/// (max − min), 0, 1)`, returns `t²·(3 − 2t)` — 0 at and below `min`, 1 at and above
/// `max`, with zero slope at both ends (GLSL's `smoothstep`). `min > max` runs the ramp
/// backwards; a zero-width range gives 0 (as [`remap`] gives its output start), and so
/// does a NaN anywhere (`t` is clamped as [`clamp_f`] clamps). Unitless.
#[must_use]
#[inline]
pub fn smooth_step(value: f32, min: f32, max: f32) -> f32 {
    let width = max - min;
    if width == 0.0 {
        return 0.0;
    }
    let t = clamp_f((value - min) / width, 0.0, 1.0);
    (t * t) * (3.0 - t * 2.0)
}

/// Sine of degrees.
#[must_use]
#[inline]
pub fn sin_deg(degrees: f32) -> f32 {
    (degrees * DEG).sin()
}

/// Cosine of degrees.
#[must_use]
#[inline]
pub fn cos_deg(degrees: f32) -> f32 {
    (degrees * DEG).cos()
}

/// Tangent of degrees.
#[must_use]
#[inline]
pub fn tan_deg(degrees: f32) -> f32 {
    (degrees * DEG).tan()
}

/// `atan2(y, x)` in degrees, (−180, 180]; 0 for `(0, 0)`.
#[must_use]
#[inline]
pub fn atan2_deg(y: f32, x: f32) -> f32 {
    y.atan2(x) / DEG
}

/// Square root, 0 for negative input.
#[must_use]
#[inline]
pub fn sqrt(value: f32) -> f32 {
    if value > 0.0 { value.sqrt() } else { 0.0 }
}

/// Float → int truncating; NaN → 0, saturating out of range (Rust's `as`).
#[must_use]
#[inline]
pub fn to_int(value: f32) -> i32 {
    value as i32
}

/// `value / |value|`, or zero when the length is zero or not finite.
#[must_use]
#[inline]
pub fn unit_v(value: Vec3) -> Vec3 {
    value.normalize_or_zero()
}

/// Normalised quaternion, identity when its length is zero or not finite.
#[must_use]
#[inline]
pub fn unit_q(value: Quat) -> Quat {
    // What `parts::unit_parts` computes (glam's vector dot product sums the squares as
    // `(x² + z²) + (y² + w²)` too), with one vector division for the four quotients.
    let v = Vec4::from(value);
    let len = v.length();
    if len > 0.0 && len.is_finite() {
        Quat::from_vec4(v / len)
    } else {
        Quat::IDENTITY
    }
}

/// `rotation · vector`: `vector` (any unit) rotated by the unit `rotation`, as glam's
/// `Quat * Vec3` computes it (a rotation of length `l` also scales by `l²`).
#[must_use]
#[inline]
pub fn rotate_vector(rotation: Quat, vector: Vec3) -> Vec3 {
    Vec3::from_array(parts::rotate_parts(rotation.to_array(), vector.to_array()))
}

/// Rotation of `degrees` about `axis`; identity for a zero axis.
#[must_use]
#[inline]
pub fn quat_from_axis_angle(axis: Vec3, degrees: f32) -> Quat {
    match axis.try_normalize() {
        Some(a) => Quat::from_axis_angle(a, degrees * DEG),
        None => Quat::IDENTITY,
    }
}

/// The Euler order for an `order` pin value (0 = XYZ, 1 = ZYX; others fall back to XYZ).
#[must_use]
#[inline]
pub fn euler_order(order: i32) -> strider_core::EulerOrder {
    if order == 1 {
        strider_core::EulerOrder::ZYX
    } else {
        strider_core::EulerOrder::XYZ
    }
}

/// Shortest-path slerp, normalised.
#[must_use]
#[inline]
pub fn slerp(a: Quat, b: Quat, alpha: f32) -> Quat {
    unit_q(a.slerp(b, alpha))
}

/// Blends `current` towards `target` by `weight` clamped to [0, 1]: lerp translation and
/// scale, slerp rotation. Weight 1 returns `target` exactly.
#[must_use]
#[inline]
pub fn blend_transform(current: Transform, target: Transform, weight: f32) -> Transform {
    let w = weight.clamp(0.0, 1.0);
    if w >= 1.0 {
        target
    } else if w <= 0.0 || w.is_nan() {
        current
    } else {
        current.interpolate(&target, w)
    }
}

/// Fills `out` with the descendants of `root` (not `root` itself), in hierarchy order, whose
/// names contain `contains` and not `excludes`, case-insensitively. An empty `excludes`
/// excludes nothing. Bones are written as indices.
pub fn find_bones(
    skeleton: &Skeleton,
    root: BoneIndex,
    contains: &str,
    excludes: &str,
    out: &mut Vec<i32>,
) {
    out.clear();
    let contains = contains.to_lowercase();
    let excludes = excludes.to_lowercase();
    for i in root.get() + 1..skeleton.subtree_end(root) {
        let name = skeleton.name(BoneIndex(i as u32)).to_lowercase();
        if name.contains(&contains) && (excludes.is_empty() || !name.contains(&excludes)) {
            out.push(i as i32);
        }
    }
}

/// `transform` rotated by `rotation` about `pivot` (rig space): the translation moves to
/// `R·(t − p) + p`, the rotation becomes `R · r` (applied after the transform's own
/// rotation, parent · child), the scale is kept.
#[must_use]
pub fn rotate_around_point(transform: Transform, pivot: Vec3, rotation: Quat) -> Transform {
    let r = parts::unit_parts(rotation.to_array());
    let arm = (transform.translation - pivot).to_array();
    let turned = parts::mul_parts(r, transform.rotation.to_array());
    Transform {
        translation: Vec3::from_array(parts::rotate_parts(r, arm)) + pivot,
        rotation: Quat::from_array(parts::unit_parts(turned)),
        scale: transform.scale,
    }
}

/// The rotation `rotation` with its angle multiplied by `scale` about the same axis, along
/// the shortest path (`quat_scale(q, 0.5)` is half of `q`; negative scales reverse it).
#[must_use]
pub fn quat_scale(rotation: Quat, scale: f32) -> Quat {
    let mut q = unit_q(rotation);
    if q.w < 0.0 {
        q = -q;
    }
    let (axis, angle) = q.to_axis_angle();
    if !angle.is_finite() || !scale.is_finite() || angle == 0.0 {
        return Quat::IDENTITY;
    }
    unit_q(Quat::from_axis_angle(axis, angle * scale))
}

/// The shortest rotation taking direction `from` to direction `to`. A zero (or non-finite)
/// vector gives the identity. Opposite directions give 180° about an axis perpendicular
/// to `from`: `from × X` when that is not tiny, else `from × Y`.
#[must_use]
pub fn find_quat_between(from: Vec3, to: Vec3) -> Quat {
    let (Some(a), Some(b)) = (from.try_normalize(), to.try_normalize()) else {
        return Quat::IDENTITY;
    };
    let d = a.dot(b);
    if d < -0.999_999 {
        let axis = a
            .cross(Vec3::X)
            .try_normalize()
            .unwrap_or_else(|| a.cross(Vec3::Y).normalize());
        return Quat::from_axis_angle(axis, core::f32::consts::PI);
    }
    unit_q(Quat::from_xyzw(
        a.y * b.z - a.z * b.y,
        a.z * b.x - a.x * b.z,
        a.x * b.y - a.y * b.x,
        1.0 + d,
    ))
}

/// `vector` with its length limited to `[min, max]` (cm). A zero vector has no direction
/// and stays zero. `min > max` gives length `max`.
#[must_use]
pub fn clamp_length(vector: Vec3, min: f32, max: f32) -> Vec3 {
    let len = vector.length();
    if len == 0.0 || !len.is_finite() {
        return if len.is_finite() { vector } else { Vec3::ZERO };
    }
    let clamped = len.max(min).min(max).max(0.0);
    vector * (clamped / len)
}

/// `point` kept inside the shell between `min_radius` and `max_radius` around `center`
/// (cm): too far is pulled in along the line to the centre, too close pushed out. A point
/// exactly at the centre has no direction to be pushed along and is returned unchanged.
#[must_use]
pub fn clamp_spatially(point: Vec3, center: Vec3, min_radius: f32, max_radius: f32) -> Vec3 {
    let offset = point - center;
    if offset == Vec3::ZERO {
        return point;
    }
    center + clamp_length(offset, min_radius.max(0.0), max_radius.max(0.0))
}

/// Rotates `transform` so that its local `axis` points along `direction` (rig space), by
/// the shortest rotation, blended by `weight` (0 = unchanged, 1 = aligned; clamped).
/// A zero axis or direction leaves the transform unchanged.
#[must_use]
pub fn aim(transform: Transform, axis: Vec3, direction: Vec3, weight: f32) -> Transform {
    let current = transform.rotation * axis;
    let full = find_quat_between(current, direction);
    let w = if weight.is_nan() {
        0.0
    } else {
        weight.clamp(0.0, 1.0)
    };
    let delta = Quat::IDENTITY.slerp(full, w);
    Transform {
        rotation: unit_q(delta * transform.rotation),
        ..transform
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn division_by_zero_is_zero() {
        assert_eq!(div_f(3.0, 0.0), 0.0);
        assert_eq!(div_i(3, 0), 0);
        assert_eq!(div_i(i32::MIN, -1), i32::MIN);
        assert_eq!(
            div_v(Vec3::new(1.0, 2.0, 3.0), Vec3::new(2.0, 0.0, -1.0)),
            Vec3::new(0.5, 0.0, -3.0)
        );
    }

    #[test]
    fn floored_modulo_takes_the_divisor_sign() {
        assert_eq!(mod_f(-1.0, 360.0), 359.0);
        assert_eq!(mod_f(370.0, 360.0), 10.0);
        assert_eq!(mod_i(-7, 3), 2);
        assert_eq!(mod_i(7, -3), -2);
        assert_eq!(mod_i(7, 0), 0);
    }

    #[test]
    fn fract_stays_below_one() {
        assert_eq!(fract(1.25), 0.25);
        assert_eq!(fract(-0.25), 0.75);
        assert!(fract(-1e-9) < 1.0);
    }

    #[test]
    fn smooth_step_by_hand() {
        // t²(3 − 2t): t = 1/4 → 1/16 · 5/2 = 5/32; t = 3/4 → 9/16 · 3/2 = 27/32 (exact).
        assert_eq!(smooth_step(0.25, 0.0, 1.0), 0.156_25);
        assert_eq!(smooth_step(0.5, 0.0, 1.0), 0.5);
        assert_eq!(smooth_step(30.0, 20.0, 60.0), 0.156_25);
        assert_eq!(smooth_step(50.0, 20.0, 60.0), 0.843_75);
        // Clamped outside the range; backwards when min > max.
        assert_eq!(smooth_step(-5.0, 20.0, 60.0), 0.0);
        assert_eq!(smooth_step(75.0, 20.0, 60.0), 1.0);
        assert_eq!(smooth_step(30.0, 60.0, 20.0), 0.843_75);
        // Zero slope at both ends: a step of 1e-3 of the range moves it by about 3e-6.
        assert!(smooth_step(20.04, 20.0, 60.0) < 4e-6);
        assert!(1.0 - smooth_step(59.96, 20.0, 60.0) < 4e-6);
        // A zero-width range gives 0, and so does a NaN.
        assert_eq!(smooth_step(5.0, 1.0, 1.0), 0.0);
        assert_eq!(smooth_step(f32::NAN, 0.0, 1.0), 0.0);
        assert_eq!(smooth_step(0.5, f32::NAN, 1.0), 0.0);
    }

    #[test]
    fn remap_by_hand() {
        // 250 in 0..500 is halfway: halfway between 0 and 20 is 10.
        assert_eq!(remap(250.0, 0.0, 500.0, 0.0, 20.0, true), 10.0);
        assert_eq!(remap(1000.0, 0.0, 500.0, 0.0, 20.0, true), 20.0);
        assert_eq!(remap(1000.0, 0.0, 500.0, 0.0, 20.0, false), 40.0);
        // Reversed output range (200..300 → 65..45): 250 gives 55.
        assert_eq!(remap(250.0, 200.0, 300.0, 65.0, 45.0, true), 55.0);
        assert_eq!(remap(5.0, 1.0, 1.0, 7.0, 9.0, true), 7.0);
    }

    #[test]
    fn degree_trigonometry() {
        assert!((sin_deg(30.0) - 0.5).abs() < 1e-6);
        assert!((cos_deg(60.0) - 0.5).abs() < 1e-6);
        assert!((tan_deg(45.0) - 1.0).abs() < 1e-6);
        assert!((atan2_deg(1.0, 1.0) - 45.0).abs() < 1e-5);
        assert_eq!(atan2_deg(0.0, 0.0), 0.0);
    }

    #[test]
    fn degenerate_vectors_and_rotations() {
        assert_eq!(unit_v(Vec3::ZERO), Vec3::ZERO);
        assert_eq!(unit_v(Vec3::new(f32::NAN, 0.0, 0.0)), Vec3::ZERO);
        assert_eq!(unit_v(Vec3::new(0.0, 3.0, 4.0)), Vec3::new(0.0, 0.6, 0.8));
        assert_eq!(unit_q(Quat::from_xyzw(0.0, 0.0, 0.0, 0.0)), Quat::IDENTITY);
        assert_eq!(quat_from_axis_angle(Vec3::ZERO, 90.0), Quat::IDENTITY);
        let q = quat_from_axis_angle(Vec3::new(0.0, 0.0, 2.0), 90.0);
        assert!((q * Vec3::Y - Vec3::new(-1.0, 0.0, 0.0)).length() < 1e-6);
        assert_eq!(sqrt(-4.0), 0.0);
        assert_eq!(to_int(f32::NAN), 0);
        assert_eq!(to_int(-2.7), -2);
    }

    fn near(a: Vec3, b: Vec3) -> bool {
        (a - b).length() < 1e-5
    }

    #[test]
    fn rotate_around_point_by_hand() {
        // A foot at (0, 10, 0) rotated 90° about Z around the pivot (0, 5, 0): the offset
        // (0, 5, 0) turns to (-5, 0, 0), so the foot lands at (-5, 5, 0).
        let foot = Transform::new(Vec3::new(0.0, 10.0, 0.0), Quat::IDENTITY, Vec3::splat(2.0));
        let r = Quat::from_rotation_z(core::f32::consts::FRAC_PI_2);
        let out = rotate_around_point(foot, Vec3::new(0.0, 5.0, 0.0), r);
        assert!(near(out.translation, Vec3::new(-5.0, 5.0, 0.0)));
        assert!(out.rotation.dot(r).abs() > 1.0 - 1e-6);
        assert_eq!(out.scale, Vec3::splat(2.0));
        // Rotating about the point itself only turns it.
        let out = rotate_around_point(foot, foot.translation, r);
        assert!(near(out.translation, foot.translation));
        // A zero quaternion counts as no rotation.
        let out = rotate_around_point(foot, Vec3::ZERO, Quat::from_xyzw(0.0, 0.0, 0.0, 0.0));
        assert_eq!(out.translation, foot.translation);
    }

    #[test]
    fn quat_scale_scales_the_angle() {
        let q = Quat::from_rotation_z(1.0);
        let half = quat_scale(q, 0.5);
        assert!(half.dot(Quat::from_rotation_z(0.5)).abs() > 1.0 - 1e-6);
        let back = quat_scale(q, -2.0);
        assert!(back.dot(Quat::from_rotation_z(-2.0)).abs() > 1.0 - 1e-6);
        // The long way round (w < 0) is scaled along the short way: 300° is -60°.
        let long = Quat::from_rotation_z(300f32.to_radians());
        let s = quat_scale(long, 0.5);
        assert!(s.dot(Quat::from_rotation_z(-30f32.to_radians())).abs() > 1.0 - 1e-5);
        assert_eq!(quat_scale(Quat::IDENTITY, 3.0), Quat::IDENTITY);
        assert_eq!(quat_scale(q, f32::NAN), Quat::IDENTITY);
    }

    #[test]
    fn find_quat_between_cases() {
        let q = find_quat_between(Vec3::Y, Vec3::new(-1.0, 0.0, 0.0));
        // +Y to -X is +90° about Z.
        assert!(
            q.dot(Quat::from_rotation_z(core::f32::consts::FRAC_PI_2))
                .abs()
                > 1.0 - 1e-6
        );
        assert!(near(q * Vec3::Y, -Vec3::X));
        // Lengths do not matter.
        assert!(near(
            find_quat_between(Vec3::Y * 5.0, Vec3::Z * 0.1) * Vec3::Y,
            Vec3::Z
        ));
        // Antiparallel: 180° about an axis perpendicular to `from`.
        for from in [
            Vec3::X,
            Vec3::Y,
            Vec3::Z,
            Vec3::new(1.0, 2.0, 3.0).normalize(),
        ] {
            let q = find_quat_between(from, -from);
            assert!(near(q * from, -from), "{from}");
        }
        assert_eq!(find_quat_between(Vec3::ZERO, Vec3::X), Quat::IDENTITY);
        assert_eq!(
            find_quat_between(Vec3::X, Vec3::new(f32::NAN, 0.0, 0.0)),
            Quat::IDENTITY
        );
    }

    #[test]
    fn clamps() {
        assert!(near(
            clamp_length(Vec3::new(0.0, 30.0, 40.0), 0.0, 10.0),
            Vec3::new(0.0, 6.0, 8.0)
        ));
        assert!(near(
            clamp_length(Vec3::new(0.0, 3.0, 4.0), 10.0, 20.0),
            Vec3::new(0.0, 6.0, 8.0)
        ));
        assert_eq!(clamp_length(Vec3::ZERO, 5.0, 10.0), Vec3::ZERO);
        assert_eq!(
            clamp_length(Vec3::new(f32::INFINITY, 0.0, 0.0), 0.0, 1.0),
            Vec3::ZERO
        );
        // A foot 150 cm from the body centre is pulled back to the 100 cm sphere.
        let c = Vec3::new(0.0, 0.0, 90.0);
        let p = clamp_spatially(Vec3::new(0.0, 150.0, 90.0), c, 0.0, 100.0);
        assert!(near(p, Vec3::new(0.0, 100.0, 90.0)));
        // Inside the shell: unchanged. Too close: pushed out to the inner radius.
        assert_eq!(
            clamp_spatially(Vec3::new(0.0, 50.0, 90.0), c, 10.0, 100.0),
            Vec3::new(0.0, 50.0, 90.0)
        );
        assert!(near(
            clamp_spatially(Vec3::new(0.0, 0.0, 95.0), c, 10.0, 100.0),
            Vec3::new(0.0, 0.0, 100.0)
        ));
        assert_eq!(clamp_spatially(c, c, 10.0, 100.0), c);
    }

    #[test]
    fn aim_aligns_an_axis_with_weight() {
        // Align the local up axis with a 30° slope normal (tilted towards +Y).
        let n = Vec3::new(0.0, -0.5, 3f32.sqrt() / 2.0);
        let t = Transform::from_translation(Vec3::new(1.0, 2.0, 3.0));
        let out = aim(t, Vec3::Z, n, 1.0);
        assert!(near(out.rotation * Vec3::Z, n));
        assert_eq!(out.translation, t.translation);
        // Half weight: half the angle (15°).
        let half = aim(t, Vec3::Z, n, 0.5);
        let angle = (half.rotation * Vec3::Z)
            .angle_between(Vec3::Z)
            .to_degrees();
        assert!((angle - 15.0).abs() < 1e-3, "{angle}");
        assert_eq!(aim(t, Vec3::Z, n, 0.0).rotation, Quat::IDENTITY);
        assert_eq!(aim(t, Vec3::ZERO, n, 1.0).rotation, Quat::IDENTITY);
    }

    #[test]
    fn blend_weights() {
        let a = Transform::from_translation(Vec3::ZERO);
        let b = Transform::from_translation(Vec3::new(10.0, 0.0, 0.0));
        assert_eq!(blend_transform(a, b, 1.0), b);
        assert_eq!(blend_transform(a, b, 0.0), a);
        assert_eq!(blend_transform(a, b, f32::NAN), a);
        assert_eq!(
            blend_transform(a, b, 0.25).translation,
            Vec3::new(2.5, 0.0, 0.0)
        );
    }
}
