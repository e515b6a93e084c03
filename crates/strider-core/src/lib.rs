//! Core types of Strider: conventions, transforms, Euler angles, skeletons and poses.
//!
//! # Conventions
//!
//! Everything in Strider follows these conventions; every other crate refers back here.
//!
//! - **Rig space** is the character's component space: **+Z up, +Y forward, +X the
//!   character's left**. It is a right-handed frame (X × Y = Z).
//! - **Units** are **centimetres** for lengths and **seconds** for time.
//! - **Angles** facing graph authors (pins, tunables, file literals) are **degrees**.
//!   Rust APIs that take radians say so in their name (`..._radians`).
//! - A [`Transform`] is translation + rotation (unit quaternion) + scale and maps a point
//!   `p` to `t + r · (s ⊙ p)`.
//! - **Composition is parent · child**: `a * b` applies `b` first, then `a`, as glam's
//!   matrices and quaternions do. A bone's global transform is
//!   `global(parent) * local(bone)`, and "rotate the foot by the platform rotation" is
//!   `platform.rotation * foot.rotation`.
//! - **Quaternions** are stored `(x, y, z, w)`, as glam stores them.
//! - **Euler angles** are `(x, y, z)` in degrees, rotations about the X, Y and Z axes. The
//!   default order [`EulerOrder::XYZ`] applies the X rotation first, then Y, then Z, about
//!   the fixed rig axes: `q = Rz · Ry · Rx`. See [`euler`].
//! - The **world** is the host's space; the host gives each frame the component-to-world
//!   transform, and the rig never moves the character.

pub mod euler;
pub mod host;
pub mod pose;
pub mod skeleton;
pub mod transform;

pub use euler::EulerOrder;
pub use glam::{Quat, Vec3};
pub use host::{
    DebugColor, DebugDraw, DebugPrimitive, EmptyWorld, HitColumns, LineQuery, SphereQuery,
    TRACE_COLUMNS, TraceColumns, TraceHit, WorldQuery,
};
pub use pose::Pose;
pub use skeleton::{Bone, BoneIndex, Skeleton, SkeletonError};
pub use transform::{Transform, all_finite, load_vec3};
