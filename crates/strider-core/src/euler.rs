//! Euler angles in degrees, stated once for all of Strider.
//!
//! An Euler triple is `(x, y, z)` in **degrees**: rotations about the X, Y and Z axes of
//! rig space. The order says which rotation is applied first, about the fixed (extrinsic)
//! axes:
//!
//! | order | applied | quaternion |
//! |---|---|---|
//! | [`EulerOrder::XYZ`] (default) | X, then Y, then Z | `Rz · Ry · Rx` |
//! | [`EulerOrder::ZYX`] | Z, then Y, then X | `Rx · Ry · Rz` |
//!
//! With Z up, Y forward and X left, the default order reads as Unreal's rotator:
//! roll (X) first, then pitch (Y), then yaw (Z).

use glam::{EulerRot, Quat, Vec3};

/// The order in which Euler rotations are applied (extrinsic, about the rig axes).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum EulerOrder {
    /// X first, then Y, then Z: `q = Rz · Ry · Rx`.
    #[default]
    XYZ,
    /// Z first, then Y, then X: `q = Rx · Ry · Rz`.
    ZYX,
}

impl EulerOrder {
    /// Every order, for tables and tests.
    pub const ALL: [EulerOrder; 2] = [EulerOrder::XYZ, EulerOrder::ZYX];

    /// The order's name as written in graph files.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            EulerOrder::XYZ => "XYZ",
            EulerOrder::ZYX => "ZYX",
        }
    }
}

/// The rotation for Euler angles `degrees = (x, y, z)` applied in `order`.
#[must_use]
pub fn quat_from_euler(degrees: Vec3, order: EulerOrder) -> Quat {
    let r = degrees * (core::f32::consts::PI / 180.0);
    match order {
        // glam's intrinsic ZYX (z, then y', then x'') equals extrinsic X, Y, Z.
        EulerOrder::XYZ => Quat::from_euler(EulerRot::ZYX, r.z, r.y, r.x),
        EulerOrder::ZYX => Quat::from_euler(EulerRot::XYZ, r.x, r.y, r.z),
    }
}

/// Euler angles `(x, y, z)` in degrees for `rotation` in `order`.
///
/// The middle rotation is in [-90°, 90°], the others in (-180°, 180°]. At the singularity
/// (middle angle ±90°) the split between the outer two is glam's choice; the returned
/// triple always converts back to the same rotation.
#[must_use]
pub fn euler_from_quat(rotation: Quat, order: EulerOrder) -> Vec3 {
    let q = rotation.normalize();
    let to_deg = 180.0 / core::f32::consts::PI;
    match order {
        EulerOrder::XYZ => {
            let (z, y, x) = q.to_euler(EulerRot::ZYX);
            Vec3::new(x, y, z) * to_deg
        }
        EulerOrder::ZYX => {
            let (x, y, z) = q.to_euler(EulerRot::XYZ);
            Vec3::new(x, y, z) * to_deg
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn assert_vec_near(a: Vec3, b: Vec3, tol: f32) {
        assert!((a - b).length() < tol, "{a} != {b}");
    }

    #[test]
    fn single_axis_rotations_follow_the_right_hand_rule() {
        // 90° about Z turns forward (+Y) towards the character's right (-X).
        let q = quat_from_euler(Vec3::new(0.0, 0.0, 90.0), EulerOrder::XYZ);
        assert_vec_near(q * Vec3::Y, Vec3::new(-1.0, 0.0, 0.0), 1e-5);
        // 90° about X turns forward (+Y) up (+Z).
        let q = quat_from_euler(Vec3::new(90.0, 0.0, 0.0), EulerOrder::XYZ);
        assert_vec_near(q * Vec3::Y, Vec3::Z, 1e-5);
        // 90° about Y turns up (+Z) towards +X.
        let q = quat_from_euler(Vec3::new(0.0, 90.0, 0.0), EulerOrder::XYZ);
        assert_vec_near(q * Vec3::Z, Vec3::X, 1e-5);
    }

    #[test]
    fn xyz_applies_x_first() {
        // X 90° maps +Y to +Z; then Z 90° leaves +Z alone. So +Y ends at +Z.
        let q = quat_from_euler(Vec3::new(90.0, 0.0, 90.0), EulerOrder::XYZ);
        assert_vec_near(q * Vec3::Y, Vec3::Z, 1e-5);
        // ZYX applies Z first: +Y → -X, then X 90° leaves -X alone.
        let q = quat_from_euler(Vec3::new(90.0, 0.0, 90.0), EulerOrder::ZYX);
        assert_vec_near(q * Vec3::Y, -Vec3::X, 1e-5);
    }

    #[test]
    fn a_hand_computed_quaternion() {
        // Rz(90°)·Rx(90°): Rx = (sin45, 0, 0, cos45), Rz = (0, 0, sin45, cos45).
        // Product (w1w2 - v1·v2, w1 v2 + w2 v1 + v1 × v2) = (0.5, 0.5, 0.5, 0.5).
        let q = quat_from_euler(Vec3::new(90.0, 0.0, 90.0), EulerOrder::XYZ);
        let expected = Quat::from_xyzw(0.5, 0.5, 0.5, 0.5);
        assert!(q.dot(expected).abs() > 1.0 - 1e-6, "{q}");
    }

    #[test]
    fn round_trips_away_from_the_singularity() {
        for order in EulerOrder::ALL {
            for &(x, y, z) in &[
                (10.0, 20.0, 30.0),
                (-170.0, 45.0, 120.0),
                (0.0, -80.0, -5.0),
            ] {
                let e = Vec3::new(x, y, z);
                let back = euler_from_quat(quat_from_euler(e, order), order);
                assert_vec_near(back, e, 1e-3);
            }
        }
    }
}
