//! Two-bone IK: RigVM's "Basic IK" (Unreal Control Rig) on a [`Pose`].
//!
//! Bones A (root of the chain, e.g. `thigh_l`), B (middle, `calf_l`) and the effector
//! (`foot_l`). Everything is in rig space (+Z up, +Y forward, +X the character's left),
//! lengths in centimetres. Bone lengths are measured on the *current* global positions of A,
//! B and the effector, so a chain that an earlier node stretched stays stretched.
//!
//! # Algorithm
//!
//! 1. **Chain direction** `dir`: from A towards the target. A target at A itself keeps the
//!    chain's current direction (A → effector, else A → B).
//! 2. **Bend side** `side`: the unit vector perpendicular to `dir`, in the bend plane, on the
//!    pole's side. It is the pole (a direction, or for [`Pole::Location`] the vector from A to
//!    the location) with its component along `dir` removed. When that is degenerate (pole
//!    zero, not finite or parallel to the chain) the fallbacks are, in order: B's current
//!    offset from the chain line, bone A's current secondary axis in rig space, and finally
//!    any vector perpendicular to `dir`.
//! 3. **Stretch** (optional, see [`stretch_scale`]) scales both lengths by one factor.
//! 4. **Law of cosines**: with `l1 = |AB|`, `l2 = |BC|` and the target distance `d` clamped to
//!    `[|l1 − l2|, l1 + l2]`, B lands at `A + dir·x + side·h` with
//!    `x = (d² + l1² − l2²) / (2d)` and `h = √(l1² − x²) ≥ 0`, and the effector at
//!    `A + dir·d`. `h ≥ 0` means the middle joint is always on the pole side of the A → target
//!    line: the chain never bends backwards. A target beyond reach straightens the chain
//!    towards it.
//! 5. **Rotations**: for A, the minimal rotation taking A's primary axis (in rig space) onto
//!    `B − A`, followed by a twist about that direction that turns A's secondary axis onto the
//!    bend plane's pole side of the bone, `normal × (B − A)/|B − A|` with
//!    `normal = dir × side`. The same for B with `C − B`. Both bones share one bend plane, so
//!    the secondary axes turn with the plane continuously (a thigh folded back past 90° has
//!    its secondary axis pointing back, as a rigid bone would). Swing and twist together
//!    take the bone's local (primary, secondary) frame onto (bone direction, pole side), so
//!    when both axes are usable that rotation is built from the two frames in one step,
//!    without trigonometry, as the quaternion in the current rotation's hemisphere. Scale is never touched
//!    (rotation only); a zero-length bone keeps its current rotation.
//! 6. **Weight** blends from the current pose: rotations by shortest-path slerp, and each
//!    child offset (expressed in its parent bone's rotation) linearly, so a stretched bone
//!    grows with the weight too.
//!
//! Degenerate input never panics and never writes NaN: invalid bone indices, repeated
//! bones, a non-finite target or non-finite current globals leave the pose unchanged; a chain
//! whose two bones both have zero length is left unchanged.

use super::{find_quat_between, slerp, unit_q};
use glam::{Mat3A, Quat, Vec3, Vec3A};
use strider_core::{BoneIndex, Pose, Transform};

mod lanes;
pub use lanes::{ChainInput, ChainLanes, ChainSolution, LANES_MATCH_GLAM};

/// Lengths (cm) at or below this are treated as zero: a bone this short has no direction.
const LEN_EPS: f32 = 1e-4;

/// A pole counts as parallel to the chain when its perpendicular part is shorter than this
/// fraction of its length (the sine of the angle between them, ~0.006°).
const PARALLEL_EPS: f32 = 1e-4;

/// Distance (cm) under which the effector counts as having reached the target.
const REACH_TOLERANCE: f32 = 1e-3;

/// Pole given as a rig-space direction or a rig-space point: where the middle joint (knee,
/// elbow) should point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Pole {
    /// A direction in rig space (any length; only its part perpendicular to the chain
    /// matters), e.g. `(0, 1, 0)` for "knee forward".
    Direction(Vec3),
    /// A point in rig space (cm); the pole direction is the vector from bone A's position to
    /// this point.
    Location(Vec3),
}

/// Settings of one solve (all rig space, cm).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TwoBoneIk {
    /// Axis of bone A's (and B's) local frame that points along the chain towards the child,
    /// e.g. `(−1, 0, 0)` for the mannequin's left leg, `(1, 0, 0)` for the right. Need not be
    /// unit length. A zero or non-finite axis falls back to each bone's actual local direction
    /// towards its child.
    pub primary_axis: Vec3,
    /// Axis of bone A's (and B's) local frame that should point towards the pole, e.g.
    /// `(0, 1, 0)` for the left leg (knee forward), `(0, −1, 0)` for the right. Its component
    /// along `primary_axis` is ignored; an axis parallel to `primary_axis` (or zero) disables
    /// the twist, leaving the minimal (swing) rotation.
    pub secondary_axis: Vec3,
    /// Where the middle joint points.
    pub pole: Pole,
    /// Blend from the current pose (0) to the solved pose (1); clamped to [0, 1], NaN is 0.
    pub weight: f32,
    /// Soft stretch `(start ratio, max ratio)`, see [`stretch_scale`]; `None` keeps the bone
    /// lengths.
    pub stretch: Option<(f32, f32)>,
    /// Also set the effector's global rotation to the target's rotation (blended by
    /// `weight`). When false the effector keeps its rotation relative to bone B.
    pub set_effector_rotation: bool,
}

/// What a solve did, for tests and debug drawing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IkReport {
    /// The effector is within 1e-3 cm of the target position after the solve (before
    /// weighting).
    pub reached: bool,
    /// Distance (cm) from the solved effector position (before weighting) to the target
    /// position; for a solve that could not run, from the current effector. Infinite when
    /// it cannot be measured (invalid bones, non-finite target).
    pub distance_to_target: f32,
}

impl IkReport {
    /// The report for `effector` (rig space, cm) against `target`.
    fn measure(effector: Vec3A, target: Vec3A) -> Self {
        let d = effector.distance(target);
        let d = if d.is_finite() { d } else { f32::INFINITY };
        Self {
            reached: d <= REACH_TOLERANCE,
            distance_to_target: d,
        }
    }

    /// The report of a solve that could not even measure.
    const UNMEASURED: Self = Self {
        reached: false,
        distance_to_target: f32::INFINITY,
    };
}

impl TwoBoneIk {
    /// Solves and writes A, B (and effector) global transforms into `pose`.
    ///
    /// `a`, `b` and `effector` are the chain's bones (normally parent → child → grandchild);
    /// `target` is the effector's goal in rig space (cm). Writes A's global rotation, B's
    /// global position and rotation, and the effector's global position (and rotation when
    /// [`set_effector_rotation`](Self::set_effector_rotation) is set), each with
    /// `propagate_to_children`, so bones below them follow. Scales are kept. B and the
    /// effector go to the solved positions: when `primary_axis` runs along the bones (as it
    /// should) that is exactly where the new rotations (and the stretch) carry them; when it
    /// does not, the positions win, as in Unreal, so the effector still reaches the target.
    ///
    /// Invalid bone indices, repeated bones, a non-finite target or non-finite current
    /// globals leave the pose unchanged. With weight 0 the solve is still computed for the
    /// report but nothing is written.
    pub fn solve(
        &self,
        pose: &mut Pose,
        a: BoneIndex,
        b: BoneIndex,
        effector: BoneIndex,
        target: Transform,
    ) -> IkReport {
        let axes = BoneAxes::new(self.primary_axis, self.secondary_axis);
        self.solve_with_axes(&axes, pose, a, b, effector, target)
    }

    /// [`TwoBoneIk::solve`] with the bone axes prepared beforehand: `axes` stands for
    /// [`primary_axis`](Self::primary_axis) and [`secondary_axis`](Self::secondary_axis)
    /// (which this call does not read). With `axes` =
    /// `BoneAxes::new(self.primary_axis, self.secondary_axis)` the result is `solve`'s, bit
    /// for bit; solves that share their axes (a crowd's legs) can prepare them once.
    pub fn solve_with_axes(
        &self,
        axes: &BoneAxes,
        pose: &mut Pose,
        a: BoneIndex,
        b: BoneIndex,
        effector: BoneIndex,
        target: Transform,
    ) -> IkReport {
        let n = pose.len();
        if a.get() >= n
            || b.get() >= n
            || effector.get() >= n
            || a == b
            || b == effector
            || a == effector
        {
            return IkReport::UNMEASURED;
        }
        let ga = pose.global(a);
        let gb = pose.global(b);
        let ge = pose.global(effector);
        // In SIMD registers throughout (the same operations, lane by lane, as on three
        // floats): a `Vec3` assembled into a register through memory waits on the stores.
        let goal = Vec3A::from(target.translation);
        if !target.is_finite() {
            return IkReport::UNMEASURED;
        }
        if !(ga.is_finite() && gb.is_finite() && ge.is_finite()) {
            return IkReport::measure(ge.translation.into(), goal);
        }
        let (root, mid, end) = (
            Vec3A::from(ga.translation),
            Vec3A::from(gb.translation),
            Vec3A::from(ge.translation),
        );
        let Some(dir) = chain_direction(root, mid, end, goal) else {
            return IkReport::measure(end, goal);
        };
        let pole = match self.pole {
            Pole::Direction(v) => v.into(),
            Pole::Location(p) => Vec3A::from(p) - root,
        };
        let side = bend_side(dir, [pole, mid - root, ga.rotation * axes.secondary]);
        let Some((new_mid, new_end)) = place_joints(root, mid, end, goal, dir, side, self.stretch)
        else {
            return IkReport::measure(end, goal);
        };
        let report = IkReport::measure(new_end, goal);

        let w = if self.weight.is_nan() {
            0.0
        } else {
            self.weight.clamp(0.0, 1.0)
        };
        if w <= 0.0 {
            return report;
        }

        let normal = dir.cross(side);
        let qa_solved = bone_rotation(ga.rotation, axes, mid - root, new_mid - root, normal);
        let qb_solved = bone_rotation(gb.rotation, axes, end - mid, new_end - new_mid, normal);
        let (qa, qb, mid_w, end_w) = if w >= 1.0 {
            (qa_solved, qb_solved, new_mid, new_end)
        } else {
            // Each child offset in its parent bone's rotation frame, blended linearly (it
            // only changes length when stretching), then carried by the blended rotation.
            let qa = slerp(ga.rotation, qa_solved, w);
            let off_a = (ga.rotation.inverse() * (mid - root))
                .lerp(qa_solved.inverse() * (new_mid - root), w);
            let mid_w = root + qa * off_a;
            let qb = slerp(gb.rotation, qb_solved, w);
            let off_b = (gb.rotation.inverse() * (end - mid))
                .lerp(qb_solved.inverse() * (new_end - new_mid), w);
            (qa, qb, mid_w, mid_w + qb * off_b)
        };
        let qe = if self.set_effector_rotation {
            let goal_rotation = unit_q(target.rotation);
            if w >= 1.0 {
                goal_rotation
            } else {
                slerp(ge.rotation, goal_rotation, w)
            }
        } else {
            unit_q(qb * (gb.rotation.inverse() * ge.rotation))
        };

        pose.set_chain_globals(
            [a, b, effector],
            [
                Transform { rotation: qa, ..ga },
                Transform::new(mid_w.into(), qb, gb.scale),
                Transform::new(end_w.into(), qe, ge.scale),
            ],
        );
        report
    }
}

/// Pure math part, usable without a pose: given the three joint positions, the target
/// position, the pole direction (already resolved to a direction perpendicular-ish to the
/// chain) returns the new mid-joint and effector positions.
///
/// All rig space, cm. `pole_dir` need not be unit length or exactly perpendicular: its
/// component along the root → target line is removed. When it is zero, non-finite or
/// parallel to that line, the mid joint's current offset from the line is used, and if that
/// is degenerate too, an arbitrary perpendicular. `stretch` is `(start ratio, max ratio)` as
/// in [`stretch_scale`]. Non-finite input, or two zero-length bones, return `(mid, end)`
/// unchanged.
#[must_use]
pub fn solve_positions(
    root: Vec3,
    mid: Vec3,
    end: Vec3,
    target: Vec3,
    pole_dir: Vec3,
    stretch: Option<(f32, f32)>,
) -> (Vec3, Vec3) {
    if !(root.is_finite() && mid.is_finite() && end.is_finite() && target.is_finite()) {
        return (mid, end);
    }
    let [root_a, mid_a, end_a, target_a] = [root, mid, end, target].map(Vec3A::from);
    let Some(dir) = chain_direction(root_a, mid_a, end_a, target_a) else {
        return (mid, end);
    };
    let side = bend_side(
        dir,
        [
            pole_dir.into(),
            mid_a - root_a,
            dir.any_orthonormal_vector(),
        ],
    );
    place_joints(root_a, mid_a, end_a, target_a, dir, side, stretch)
        .map_or((mid, end), |(m, e)| (m.into(), e.into()))
}

/// The factor (≥ 1) by which soft stretch scales both bone lengths, for a target at
/// `reach_ratio` = target distance / (|AB| + |BC|).
///
/// With `stretch = Some((start, max))` the curve is the linear ramp of Unreal's two-bone
/// solver (`AnimationCore::SolveTwoBoneIK`):
///
/// `scale = 1 + (max − 1) · clamp((reach_ratio − start) / (max − start), 0, 1)`
///
/// It is 1 up to `start`, grows linearly (continuous, monotonic non-decreasing in the target
/// distance) and reaches `max` at `reach_ratio = max`, staying there beyond: bones never
/// grow more than `max` times. For `start ≤ 1` the stretched chain always reaches targets up
/// to `max · (|AB| + |BC|)`, because `scale ≥ reach_ratio` on the whole ramp. A negative
/// `start` counts as 0. No stretch (factor 1) for `None`, non-finite values, `max ≤ 1` or
/// `max − start ≤ 1e-6`.
#[must_use]
pub fn stretch_scale(stretch: Option<(f32, f32)>, reach_ratio: f32) -> f32 {
    let Some((start, max)) = stretch else {
        return 1.0;
    };
    if !(start.is_finite() && max.is_finite()) || reach_ratio.is_nan() {
        return 1.0;
    }
    let start = start.max(0.0);
    let range = max - start;
    if max <= 1.0 || range <= 1e-6 {
        return 1.0;
    }
    let t = ((reach_ratio - start) / range).clamp(0.0, 1.0);
    1.0 + (max - 1.0) * t
}

/// Unit vector along `v`, or `None` when `v` is shorter than [`LEN_EPS`] or not finite.
/// A vector whose squared length overflows is divided by its largest component first.
fn direction(v: Vec3A) -> Option<Vec3A> {
    let len_sq = v.length_squared();
    if len_sq.is_finite() {
        return (len_sq > LEN_EPS * LEN_EPS).then(|| v / len_sq.sqrt());
    }
    let m = v.abs().max_element();
    if !(m > 0.0 && m.is_finite()) {
        return None;
    }
    let u = v / m;
    let len = u.length();
    if m * len > LEN_EPS {
        Some(u / len)
    } else {
        None
    }
}

/// Whether [`direction`] of `v` is `Some`, without computing it when `v`'s squared length
/// does not overflow.
#[inline]
fn has_direction(v: Vec3A) -> bool {
    let len_sq = v.length_squared();
    if len_sq.is_finite() {
        len_sq > LEN_EPS * LEN_EPS
    } else {
        direction(v).is_some()
    }
}

/// Direction from `root` to `target`, or the chain's current direction (root → end, else
/// root → mid) when the target sits on the root. `None` when all three coincide.
fn chain_direction(root: Vec3A, mid: Vec3A, end: Vec3A, target: Vec3A) -> Option<Vec3A> {
    direction(target - root)
        .or_else(|| direction(end - root))
        .or_else(|| direction(mid - root))
}

/// The part of `v` perpendicular to the unit `dir`, normalised; `None` when `v` is zero,
/// non-finite or within [`PARALLEL_EPS`] of parallel to `dir`.
fn perpendicular(v: Vec3A, dir: Vec3A) -> Option<Vec3A> {
    // Not finite (or overflowing when squared) and zero both fail here.
    let len_sq = v.length_squared();
    if !(len_sq > 0.0 && len_sq.is_finite()) {
        return None;
    }
    let p = v - dir * v.dot(dir);
    if p.length_squared() > PARALLEL_EPS * PARALLEL_EPS * len_sq {
        // A second projection: for a `v` nearly parallel to `dir` the first one cancels
        // most of `v` and leaves a rounding error along `dir` that would tilt the plane.
        (p - dir * p.dot(dir)).try_normalize()
    } else {
        None
    }
}

/// The first candidate with a usable part perpendicular to the unit `dir` (normalised), or
/// an arbitrary perpendicular.
fn bend_side(dir: Vec3A, candidates: [Vec3A; 3]) -> Vec3A {
    candidates
        .into_iter()
        .find_map(|c| perpendicular(c, dir))
        .unwrap_or_else(|| dir.any_orthonormal_vector())
}

/// Law of cosines in the plane of the unit `dir` and the unit `side` (perpendicular to it).
/// `None` when both bones have zero length or the lengths are not finite.
fn place_joints(
    root: Vec3A,
    mid: Vec3A,
    end: Vec3A,
    target: Vec3A,
    dir: Vec3A,
    side: Vec3A,
    stretch: Option<(f32, f32)>,
) -> Option<(Vec3A, Vec3A)> {
    let l1 = mid.distance(root);
    let l2 = end.distance(mid);
    let total = l1 + l2;
    if !(total > LEN_EPS && total.is_finite()) {
        return None;
    }
    let wanted = target.distance(root);
    let k = stretch_scale(stretch, wanted / total);
    // An absurd max ratio could overflow the lengths: no stretch then.
    let k = if (total * k).is_finite() { k } else { 1.0 };
    let (l1, l2) = (l1 * k, l2 * k);
    let d = wanted.max((l1 - l2).abs()).min(l1 + l2);

    // The triangle in f64: near a straight chain h is ill-conditioned in f32.
    let (l1d, l2d, dd) = (f64::from(l1), f64::from(l2), f64::from(d));
    let x = if d >= l1 + l2 {
        // Fully extended (or clamped there): straight, exactly.
        l1d
    } else if dd <= 1e-9 {
        // Equal bones folded onto the root: the mid joint stands straight out to the side
        // (the limit of the general case as d → 0).
        0.0
    } else if d <= (l1 - l2).abs() {
        // Fully folded: the longer bone along the line, the shorter one back along it.
        if l1 >= l2 { l1d } else { -l1d }
    } else {
        (dd * dd + l1d * l1d - l2d * l2d) / (2.0 * dd)
    };
    let x = x.max(-l1d).min(l1d);
    let h = (l1d * l1d - x * x).max(0.0).sqrt();

    let new_mid = root + dir * (x as f32) + side * (h as f32);
    let new_end = if d == wanted { target } else { root + dir * d };
    Some((new_mid, new_end))
}

/// A solve's local bone axes (see [`TwoBoneIk::primary_axis`] and
/// [`TwoBoneIk::secondary_axis`], in the bones' local frames), normalised once for both
/// bones of a solve, or for every solve with the same axes
/// ([`TwoBoneIk::solve_with_axes`]).
#[derive(Clone, Copy, Debug)]
pub struct BoneAxes {
    /// The secondary axis as given (made perpendicular to each bone's own direction when
    /// the primary axis is unusable).
    secondary: Vec3A,
    /// The unit primary axis; `None` when zero or not finite (each bone then uses its own
    /// direction towards its child).
    primary: Option<Vec3A>,
    /// The secondary axis made perpendicular to `primary` and normalised, when both are
    /// usable.
    local_secondary: Option<Vec3A>,
    /// With both axes usable, the transpose (inverse) of the local frame (primary,
    /// secondary, primary × secondary): shared by both bones' rotations.
    local_inverse: Option<Mat3A>,
}

impl BoneAxes {
    /// The axes of a solve with these [`TwoBoneIk::primary_axis`] and
    /// [`TwoBoneIk::secondary_axis`] (any length; zero, non-finite or parallel axes fall back
    /// as those fields' docs say).
    #[must_use]
    pub fn new(primary: Vec3, secondary: Vec3) -> Self {
        let (primary, secondary) = (Vec3A::from(primary), Vec3A::from(secondary));
        let primary = direction(primary);
        let local_secondary = primary.and_then(|p| perpendicular(secondary, p));
        let local_inverse = primary
            .zip(local_secondary)
            .map(|(p, s)| Mat3A::from_cols(p, s, p.cross(s)).transpose());
        Self {
            secondary,
            primary,
            local_secondary,
            local_inverse,
        }
    }
}

/// New global rotation of one bone: `current` swung so the local primary axis points along
/// `new_offset`, then twisted about it so the local secondary axis points to the bend
/// plane's pole side, `normal × dir`. A zero-length bone keeps `current`.
///
/// With both local axes usable that rotation is the one taking the local frame
/// (primary, secondary, primary × secondary) onto (dir, normal × dir, their cross
/// product), built from the two frames at once; of its two quaternions the one in
/// `current`'s hemisphere is returned. Otherwise the swing and the twist are applied in
/// turn.
fn bone_rotation(
    current: Quat,
    axes: &BoneAxes,
    old_offset: Vec3A,
    new_offset: Vec3A,
    normal: Vec3A,
) -> Quat {
    // The bone's current direction is needed only without a usable primary axis; with one,
    // only whether it has a direction (no square root and division for nothing).
    let Some(dir) = direction(new_offset).filter(|_| has_direction(old_offset)) else {
        return current;
    };
    if let Some(local_inverse) = axes.local_inverse
        && let Some(want) = perpendicular(normal.cross(dir), dir)
    {
        // Both frames are orthonormal, so is their product, and glam reads a unit rotation
        // off it (to rounding): no second normalisation.
        let solved = Mat3A::from_cols(dir, want, dir.cross(want));
        let q = Quat::from_mat3a(&(solved * local_inverse));
        return if q.dot(current) < 0.0 { -q } else { q };
    }
    let (primary, local_secondary) = match axes.primary {
        Some(p) => (p, axes.local_secondary),
        None => {
            // `Some`: `has_direction(old_offset)` held.
            let old_dir = direction(old_offset).unwrap_or(dir);
            let p = current.inverse() * old_dir;
            (p, perpendicular(axes.secondary, p))
        }
    };
    let swung = unit_q(find_quat_between((current * primary).into(), dir.into()) * current);

    let Some(local_secondary) = local_secondary else {
        return swung;
    };
    let Some(have) = perpendicular(swung * local_secondary, dir) else {
        return swung;
    };
    let Some(want) = normal.cross(dir).try_normalize() else {
        return swung;
    };
    unit_q(twist_between(have, want, dir) * swung)
}

/// The rotation about the unit `axis` that turns the unit `from` onto the unit `to` (both
/// perpendicular to `axis`), without trigonometry. With `c = from·to` and
/// `s = (from × to)·axis` (cosine and sine of the angle θ), the half-angle quaternion
/// `(axis·sin θ/2, cos θ/2)` is proportional to `(axis·s, 1 + c)` and to `(axis·(1 − c), s)`;
/// the first is used up to 90° and the second beyond, where `1 + c` would lose its digits
/// to cancellation (and vanish at 180°).
fn twist_between(from: Vec3A, to: Vec3A, axis: Vec3A) -> Quat {
    let c = from.dot(to);
    let s = from.cross(to).dot(axis);
    let (v, w) = if c >= 0.0 { (s, 1.0 + c) } else { (1.0 - c, s) };
    unit_q(Quat::from_xyzw(axis.x * v, axis.y * v, axis.z * v, w))
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f32::consts::{FRAC_PI_2, PI};
    use std::sync::Arc;
    use strider_core::{Bone, Skeleton};

    /// [`perpendicular`] on `Vec3`s.
    fn perp(v: Vec3, dir: Vec3) -> Option<Vec3> {
        perpendicular(v.into(), dir.into()).map(Vec3::from)
    }

    // ---------------------------------------------------------------------------------------
    // Fixtures.
    //
    // A leg with the mannequin's left-leg convention: bone local −X points to the child, local
    // +Y to the bend side (forward). The thigh sits at (0, 0, 90) with global rotation
    // Ry(−90°), which maps local −X → rig −Z (down), +Y → +Y (forward), +Z → −X. Calf and
    // foot have identity local rotations, so in the rest pose the leg is straight down:
    // thigh (0,0,90), calf (0,0,90 − l1), foot (0,0,90 − l1 − l2). `ball` is a child of the
    // foot 10 cm in front of it, to check that children follow.
    // ---------------------------------------------------------------------------------------

    struct Leg {
        pose: Pose,
        pelvis: BoneIndex,
        thigh: BoneIndex,
        calf: BoneIndex,
        foot: BoneIndex,
        ball: BoneIndex,
    }

    fn bone(name: &str, parent: Option<&str>, t: Transform) -> Bone {
        Bone {
            name: name.into(),
            parent: parent.map(Into::into),
            rest_local: t,
        }
    }

    fn thigh_rest() -> Quat {
        Quat::from_rotation_y(-FRAC_PI_2)
    }

    /// A leg under a `pelvis` bone placed at `pelvis` (rig space); the thigh's global is
    /// always (0,0,90) with rotation Ry(−90°) and scale `thigh_scale`.
    fn leg_under(pelvis: Transform, l1: f32, l2: f32, thigh_scale: Vec3) -> Leg {
        let thigh_global = Transform::new(Vec3::new(0.0, 0.0, 90.0), thigh_rest(), thigh_scale);
        let s = Arc::new(
            Skeleton::new(vec![
                bone("pelvis", None, pelvis),
                bone("thigh_l", Some("pelvis"), thigh_global.relative_to(&pelvis)),
                bone(
                    "calf_l",
                    Some("thigh_l"),
                    Transform::from_translation(Vec3::new(-l1, 0.0, 0.0)),
                ),
                bone(
                    "foot_l",
                    Some("calf_l"),
                    Transform::from_translation(Vec3::new(-l2, 0.0, 0.0)),
                ),
                bone(
                    "ball_l",
                    Some("foot_l"),
                    Transform::from_translation(Vec3::new(0.0, 10.0, 0.0)),
                ),
            ])
            .unwrap(),
        );
        Leg {
            pelvis: s.find("pelvis").unwrap(),
            thigh: s.find("thigh_l").unwrap(),
            calf: s.find("calf_l").unwrap(),
            foot: s.find("foot_l").unwrap(),
            ball: s.find("ball_l").unwrap(),
            pose: Pose::new(s),
        }
    }

    fn leg(l1: f32, l2: f32) -> Leg {
        leg_under(Transform::IDENTITY, l1, l2, Vec3::ONE)
    }

    /// Left-leg settings: primary −X, secondary +Y, knee pole forward, full weight.
    fn left_leg_ik() -> TwoBoneIk {
        TwoBoneIk {
            primary_axis: Vec3::new(-1.0, 0.0, 0.0),
            secondary_axis: Vec3::Y,
            pole: Pole::Direction(Vec3::Y),
            weight: 1.0,
            stretch: None,
            set_effector_rotation: false,
        }
    }

    fn at(z: f32) -> Transform {
        Transform::from_translation(Vec3::new(0.0, 0.0, z))
    }

    impl Leg {
        fn solve(&mut self, ik: &TwoBoneIk, target: Transform) -> IkReport {
            ik.solve(&mut self.pose, self.thigh, self.calf, self.foot, target)
        }
        fn pos(&mut self, b: BoneIndex) -> Vec3 {
            self.pose.global(b).translation
        }
        fn rot(&mut self, b: BoneIndex) -> Quat {
            self.pose.global(b).rotation
        }
        fn snapshot(&mut self) -> Vec<Transform> {
            self.pose.globals().to_vec()
        }
    }

    #[track_caller]
    fn assert_near(a: Vec3, b: Vec3, tol: f32) {
        assert!(
            (a - b).length() <= tol,
            "{a} != {b} (off by {})",
            (a - b).length()
        );
    }

    #[track_caller]
    fn assert_same_rotation(a: Quat, b: Quat) {
        let dot = a.dot(b).abs();
        assert!(dot >= 1.0 - 1e-5, "{a} != {b} (|dot| = {dot})");
    }

    /// A knee bent by the law of cosines, 40/40 leg, target 60 cm below the hip: the knee is
    /// d/2 = 30 cm down the line and √(40² − 30²) = √700 = 26.4575 cm off it; the thigh is
    /// turned about +X (left) by α = acos(30/40) = 41.4096°.
    const H_60: f32 = 26.457_513;
    fn alpha_60() -> f32 {
        0.75f32.acos()
    }

    // ---------------------------------------------------------------------------------------
    // Validity (ozz: JobValidity).
    // ---------------------------------------------------------------------------------------

    #[test]
    fn twist_between_matches_the_axis_angle_rotation() {
        // Rotations about Z by hand: from +X to the unit vector at θ is a rotation by θ.
        for deg in [
            -179.0f32, -120.0, -90.0, -30.0, -1.0, 0.0, 0.5, 45.0, 90.0, 135.0, 179.9,
        ] {
            let t = deg.to_radians();
            let to = Vec3::new(t.cos(), t.sin(), 0.0);
            let q = twist_between(Vec3A::X, to.into(), Vec3A::Z);
            let want = Quat::from_axis_angle(Vec3::Z, t);
            assert!(q.dot(want).abs() > 1.0 - 1e-6, "{deg}: {q:?} vs {want:?}");
            assert!((q * Vec3::X).distance(to) < 1e-5, "{deg}");
        }
        // A half turn about the given axis, not an arbitrary one.
        let q = twist_between(Vec3A::X, -Vec3A::X, Vec3A::Z);
        assert!((q * Vec3::Y).distance(-Vec3::Y) < 1e-6);
        assert!((q * Vec3::Z).distance(Vec3::Z) < 1e-6);
    }

    #[test]
    fn invalid_input_leaves_the_pose_unchanged() {
        let mut l = leg(40.0, 40.0);
        let before = l.snapshot();
        let ik = left_leg_ik();
        let (t, c, f) = (l.thigh, l.calf, l.foot);
        let out_of_range = BoneIndex(99);
        for (a, b, e) in [
            (out_of_range, c, f),
            (t, out_of_range, f),
            (t, c, out_of_range),
            (t, t, f),
            (t, c, c),
            (f, c, f),
        ] {
            let r = ik.solve(&mut l.pose, a, b, e, at(30.0));
            assert_eq!(r, IkReport::UNMEASURED);
            assert_eq!(l.snapshot(), before);
        }
        // NaN or infinity anywhere in the target.
        let nan = f32::NAN;
        for target in [
            Transform::from_translation(Vec3::new(nan, 0.0, 30.0)),
            Transform::from_translation(Vec3::new(0.0, f32::INFINITY, 30.0)),
            Transform::from_translation_rotation(
                Vec3::new(0.0, 0.0, 30.0),
                Quat::from_xyzw(nan, 0.0, 0.0, 1.0),
            ),
        ] {
            let r = l.solve(&ik, target);
            assert!(!r.reached);
            assert_eq!(r.distance_to_target, f32::INFINITY);
            assert_eq!(l.snapshot(), before);
        }
        // NaN weight counts as 0: the report is computed (60 cm below the hip is
        // reachable), nothing is written.
        let r = l.solve(&TwoBoneIk { weight: nan, ..ik }, at(30.0));
        assert!(r.reached);
        assert_eq!(l.snapshot(), before);
    }

    #[test]
    fn degenerate_settings_fall_back() {
        // A NaN pole falls back to the mid offset (zero: straight leg) and then to the
        // thigh's secondary axis (+Y): the same knee as a forward pole. A NaN stretch is no
        // stretch; a zero primary axis is the bone's own direction (local −X).
        let expected_knee = Vec3::new(0.0, H_60, 60.0);
        for ik in [
            TwoBoneIk {
                pole: Pole::Direction(Vec3::splat(f32::NAN)),
                ..left_leg_ik()
            },
            TwoBoneIk {
                stretch: Some((f32::NAN, 1.2)),
                ..left_leg_ik()
            },
            TwoBoneIk {
                primary_axis: Vec3::ZERO,
                ..left_leg_ik()
            },
            TwoBoneIk {
                primary_axis: Vec3::new(-7.0, 0.0, 0.0), // not unit: normalised
                ..left_leg_ik()
            },
        ] {
            let mut l = leg(40.0, 40.0);
            let r = l.solve(&ik, at(30.0));
            assert!(r.reached, "{ik:?}");
            assert_near(l.pos(l.calf), expected_knee, 1e-3);
            assert_same_rotation(
                l.rot(l.thigh),
                Quat::from_rotation_x(alpha_60()) * thigh_rest(),
            );
        }
    }

    #[test]
    fn parent_transform_does_not_matter() {
        // ozz: StartJointCorrection. The solve works in rig space, so the same thigh global
        // under a translated, rotated, uniformly scaled or mirrored-by-rotation parent gives
        // the same result: knee (0, 26.4575, 60), foot at the target.
        for pelvis in [
            Transform::IDENTITY,
            Transform::from_translation(Vec3::new(0.0, 0.0, 95.0)),
            Transform::from_translation_rotation(
                Vec3::new(5.0, -3.0, 100.0),
                Quat::from_rotation_x(PI / 3.0),
            ),
            Transform::new(Vec3::ZERO, Quat::from_rotation_z(PI), Vec3::splat(2.0)),
        ] {
            let mut l = leg_under(pelvis, 40.0, 40.0, Vec3::ONE);
            assert_near(l.pos(l.foot), Vec3::new(0.0, 0.0, 10.0), 1e-3);
            let r = l.solve(&left_leg_ik(), at(30.0));
            assert!(r.reached);
            assert_near(l.pos(l.calf), Vec3::new(0.0, H_60, 60.0), 1e-3);
            assert_near(l.pos(l.foot), Vec3::new(0.0, 0.0, 30.0), 1e-3);
            assert_eq!(l.pose.global(l.pelvis), pelvis);
        }
    }

    // ---------------------------------------------------------------------------------------
    // Pole (ozz: Pole).
    // ---------------------------------------------------------------------------------------

    #[test]
    fn pole_forward_bends_the_knee_forward() {
        // 40/40 leg, target 60 cm below the hip (0,0,30): knee at (0, 26.4575, 60).
        let mut l = leg(40.0, 40.0);
        let r = l.solve(&left_leg_ik(), at(30.0));
        assert!(r.reached);
        assert!(r.distance_to_target < 1e-4);
        assert_near(l.pos(l.thigh), Vec3::new(0.0, 0.0, 90.0), 1e-6);
        assert_near(l.pos(l.calf), Vec3::new(0.0, H_60, 60.0), 1e-3);
        assert_near(l.pos(l.foot), Vec3::new(0.0, 0.0, 30.0), 1e-3);
        // Thigh: Rx(α)·Ry(−90°): local −X → (0, sin α, −cos α) = (0, 0.6614, −0.75) and
        // local +Y → (0, cos α, sin α) = (0, 0.75, 0.6614), forward and up, ⟂ the thigh.
        // Calf: Rx(−α)·Ry(−90°): −X → (0, −0.6614, −0.75), +Y → (0, 0.75, −0.6614).
        let alpha = alpha_60();
        let thigh = l.rot(l.thigh);
        let calf = l.rot(l.calf);
        assert_same_rotation(thigh, Quat::from_rotation_x(alpha) * thigh_rest());
        assert_same_rotation(calf, Quat::from_rotation_x(-alpha) * thigh_rest());
        assert_near(thigh * Vec3::Y, Vec3::new(0.0, 0.75, 0.661_437_8), 1e-5);
        assert_near(calf * Vec3::Y, Vec3::new(0.0, 0.75, -0.661_437_8), 1e-5);
        // The foot kept its local rotation (identity relative to the calf), and the ball
        // followed it: 10 cm along the foot's local +Y.
        assert_same_rotation(l.rot(l.foot), calf);
        let ball = l.pos(l.foot) + calf * Vec3::new(0.0, 10.0, 0.0);
        assert_near(l.pos(l.ball), ball, 1e-3);
    }

    #[test]
    fn pole_directions_and_locations() {
        let h = H_60;
        let alpha = alpha_60();
        // (pole, expected knee, expected thigh rotation)
        let cases = [
            // Backward: the forward solution turned 180° about the vertical, Rz(180°).
            (
                Pole::Direction(Vec3::new(0.0, -1.0, 0.0)),
                Vec3::new(0.0, -h, 60.0),
                Quat::from_rotation_z(PI) * Quat::from_rotation_x(alpha) * thigh_rest(),
            ),
            // Left (+X): the forward solution turned −90° about Z (Y → X).
            (
                Pole::Direction(Vec3::new(3.0, 0.0, 0.0)),
                Vec3::new(h, 0.0, 60.0),
                Quat::from_rotation_z(-FRAC_PI_2) * Quat::from_rotation_x(alpha) * thigh_rest(),
            ),
            // A pole with a component along the chain: only its forward part counts.
            (
                Pole::Direction(Vec3::new(0.0, 1.0, -5.0)),
                Vec3::new(0.0, h, 60.0),
                Quat::from_rotation_x(alpha) * thigh_rest(),
            ),
            // Location in front of the knee: (0, 100, 60) − hip (0, 0, 90) = (0, 100, −30),
            // whose part ⟂ the vertical chain is forward.
            (
                Pole::Location(Vec3::new(0.0, 100.0, 60.0)),
                Vec3::new(0.0, h, 60.0),
                Quat::from_rotation_x(alpha) * thigh_rest(),
            ),
            // Location behind, on the ground: (0, −50, 0) − (0, 0, 90) → backward.
            (
                Pole::Location(Vec3::new(0.0, -50.0, 0.0)),
                Vec3::new(0.0, -h, 60.0),
                Quat::from_rotation_z(PI) * Quat::from_rotation_x(alpha) * thigh_rest(),
            ),
        ];
        for (pole, knee, thigh) in cases {
            let mut l = leg(40.0, 40.0);
            let ik = TwoBoneIk {
                pole,
                ..left_leg_ik()
            };
            assert!(l.solve(&ik, at(30.0)).reached);
            assert_near(l.pos(l.calf), knee, 1e-3);
            assert_near(l.pos(l.foot), Vec3::new(0.0, 0.0, 30.0), 1e-3);
            // The secondary axis (+Y) of the thigh follows the pole: with a backward pole the
            // whole leg is turned 180° about the vertical, its +Y pointing back.
            assert_same_rotation(l.rot(l.thigh), thigh);
        }
    }

    #[test]
    fn unequal_bones_by_hand() {
        // 30/50 leg, target 60 cm below the hip: x = (60² + 30² − 50²)/(2·60) = 2000/120
        // = 16.6667 down the line, h = √(30² − 16.6667²) = √622.22 = 24.9444 forward.
        let mut l = leg(30.0, 50.0);
        assert!(l.solve(&left_leg_ik(), at(30.0)).reached);
        let knee = l.pos(l.calf);
        assert_near(knee, Vec3::new(0.0, 24.944_39, 73.333_33), 1e-3);
        assert!((knee.distance(Vec3::new(0.0, 0.0, 90.0)) - 30.0).abs() < 1e-3);
        assert!((knee.distance(Vec3::new(0.0, 0.0, 30.0)) - 50.0).abs() < 1e-3);

        // Target only 30 cm below the hip (min reach 50 − 30 = 20): x = (900 + 900 − 2500)
        // / 60 = −11.6667, the knee goes *above* the hip, h = √(900 − 136.11) = 27.6385.
        // It is still on the pole (forward) side: the chain folds, never bends backwards.
        let mut l = leg(30.0, 50.0);
        assert!(l.solve(&left_leg_ik(), at(60.0)).reached);
        assert_near(l.pos(l.calf), Vec3::new(0.0, 27.638_54, 101.666_67), 1e-3);
        assert_near(l.pos(l.foot), Vec3::new(0.0, 0.0, 60.0), 1e-3);
        // The thigh turned more than 90° about +X: it points forward and up,
        // u_A = (0, 27.6385, 11.6667)/30 = (0, 0.9213, 0.3889), so its +Y (in the bend plane,
        // ⟂ the thigh, turning with it) points back and up: X × u_A = (0, −0.3889, 0.9213).
        assert_near(
            l.rot(l.thigh) * Vec3::Y,
            Vec3::new(0.0, -0.388_889, 0.921_285),
            1e-4,
        );
    }

    // ---------------------------------------------------------------------------------------
    // Secondary axis / twist (ozz: Twist, MidAxis).
    // ---------------------------------------------------------------------------------------

    #[test]
    fn secondary_axis_sets_the_twist() {
        let alpha = alpha_60();
        let u_thigh = Vec3::new(0.0, 0.661_437_8, -0.75);
        let side_thigh = Vec3::new(0.0, 0.75, 0.661_437_8); // X × u_thigh
        for (secondary, check) in [
            // Local +Z to the pole side: a 90° twist about the thigh puts +Y on +X (left):
            // q·Y = q·Z × q·X = side × (−u) = (1, 0, 0).
            (Vec3::Z, Vec3::X),
            // Local −Y to the pole side: twisted 180°, +Y points back and down.
            (Vec3::new(0.0, -1.0, 0.0), -side_thigh),
            // Not perpendicular to the primary axis: only its part ⟂ −X (+Y) counts.
            (Vec3::new(0.5, 1.0, 0.0), side_thigh),
        ] {
            let mut l = leg(40.0, 40.0);
            let ik = TwoBoneIk {
                secondary_axis: secondary,
                ..left_leg_ik()
            };
            assert!(l.solve(&ik, at(30.0)).reached);
            // Positions do not depend on the twist.
            assert_near(l.pos(l.calf), Vec3::new(0.0, H_60, 60.0), 1e-3);
            let thigh = l.rot(l.thigh);
            assert_near(thigh * Vec3::new(-1.0, 0.0, 0.0), u_thigh, 1e-5);
            assert_near(thigh * Vec3::Y, check, 1e-5);
            let projected = (secondary - Vec3::X * secondary.x).normalize();
            assert_near(thigh * projected, side_thigh, 1e-5);
        }
        // A secondary axis along the primary axis (or zero) disables the twist: only the
        // minimal swing from −Z to u_thigh, Rx(α), which here equals the twisted answer.
        for secondary in [Vec3::X, Vec3::ZERO] {
            let mut l = leg(40.0, 40.0);
            let ik = TwoBoneIk {
                secondary_axis: secondary,
                ..left_leg_ik()
            };
            assert!(l.solve(&ik, at(30.0)).reached);
            assert_same_rotation(l.rot(l.thigh), Quat::from_rotation_x(alpha) * thigh_rest());
        }
    }

    #[test]
    fn right_leg_axes() {
        // The mannequin's right leg: +X to the child, −Y forward. Thigh global rotation
        // Rz(180°)·Ry(90°): Ry(90°) takes X → −Z (down) and keeps Y; Rz(180°) keeps −Z and
        // takes Y → −Y, so local −Y points forward. Same target and pole as the left leg:
        // the same knee, and local −Y takes the place of the left leg's +Y.
        let thigh_rot = Quat::from_rotation_z(PI) * Quat::from_rotation_y(FRAC_PI_2);
        assert_near(thigh_rot * Vec3::X, Vec3::new(0.0, 0.0, -1.0), 1e-6);
        assert_near(thigh_rot * Vec3::new(0.0, -1.0, 0.0), Vec3::Y, 1e-6);
        let s = Arc::new(
            Skeleton::new(vec![
                bone(
                    "thigh_r",
                    None,
                    Transform::from_translation_rotation(Vec3::new(0.0, 0.0, 90.0), thigh_rot),
                ),
                bone(
                    "calf_r",
                    Some("thigh_r"),
                    Transform::from_translation(Vec3::new(40.0, 0.0, 0.0)),
                ),
                bone(
                    "foot_r",
                    Some("calf_r"),
                    Transform::from_translation(Vec3::new(40.0, 0.0, 0.0)),
                ),
            ])
            .unwrap(),
        );
        let mut pose = Pose::new(s);
        let ik = TwoBoneIk {
            primary_axis: Vec3::X,
            secondary_axis: Vec3::new(0.0, -1.0, 0.0),
            ..left_leg_ik()
        };
        let r = ik.solve(
            &mut pose,
            BoneIndex(0),
            BoneIndex(1),
            BoneIndex(2),
            at(30.0),
        );
        assert!(r.reached);
        assert_near(
            pose.global(BoneIndex(1)).translation,
            Vec3::new(0.0, H_60, 60.0),
            1e-3,
        );
        let thigh = pose.global(BoneIndex(0)).rotation;
        assert_near(
            thigh * Vec3::new(0.0, -1.0, 0.0),
            Vec3::new(0.0, 0.75, 0.661_437_8),
            1e-5,
        );
    }

    #[test]
    fn mannequin_legs() {
        // Both legs as in graphs/skeletons/mannequin.ron (rest: knees 1.5 cm forward, ankles
        // at z = 13.5). Lift each foot 20 cm straight up with the knee pole forward and the
        // file's axes: the knee bends further forward, the lengths hold, the thigh's
        // secondary axis points forward-ish (+Y), the foot keeps its target rotation.
        let q = Quat::from_xyzw;
        let t = |x, y, z, r| Transform::from_translation_rotation(Vec3::new(x, y, z), r);
        let s = Arc::new(
            Skeleton::new(vec![
                bone("root", None, Transform::IDENTITY),
                bone("pelvis", Some("root"), t(0.0, 0.0, 95.0, Quat::IDENTITY)),
                bone(
                    "thigh_l",
                    Some("pelvis"),
                    t(
                        9.5,
                        0.0,
                        -3.0,
                        q(0.012_620_9, -0.706_994_1, -0.012_620_9, 0.706_994_1),
                    ),
                ),
                bone(
                    "calf_l",
                    Some("thigh_l"),
                    t(-42.0268, 0.0, 0.0, q(0.0, 0.0, 0.038_376_5, 0.999_263_4)),
                ),
                bone(
                    "foot_l",
                    Some("calf_l"),
                    t(-36.5308, 0.0, 0.0, q(0.0, 0.0, -0.465_486_3, 0.885_055_1)),
                ),
                bone(
                    "thigh_r",
                    Some("pelvis"),
                    t(
                        -9.5,
                        0.0,
                        -3.0,
                        q(-0.706_994_1, -0.012_620_9, 0.706_994_1, 0.012_620_9),
                    ),
                ),
                bone(
                    "calf_r",
                    Some("thigh_r"),
                    t(42.0268, 0.0, 0.0, q(0.0, 0.0, 0.038_376_5, 0.999_263_4)),
                ),
                bone(
                    "foot_r",
                    Some("calf_r"),
                    t(36.5308, 0.0, 0.0, q(0.0, 0.0, -0.465_486_3, 0.885_055_1)),
                ),
            ])
            .unwrap(),
        );
        for (side, primary, secondary) in [
            ("l", Vec3::new(-1.0, 0.0, 0.0), Vec3::Y),
            ("r", Vec3::X, Vec3::new(0.0, -1.0, 0.0)),
        ] {
            let mut pose = Pose::new(s.clone());
            let [a, b, c] =
                ["thigh_", "calf_", "foot_"].map(|n| s.find(&format!("{n}{side}")).unwrap());
            let (root, mid, end) = (
                pose.global(a).translation,
                pose.global(b).translation,
                pose.global(c).translation,
            );
            assert!(
                (end.z - 13.5).abs() < 0.01 && (mid.y - 1.5).abs() < 0.01,
                "{side}"
            );
            // Rest: the thigh's secondary axis already points forward.
            assert!((pose.global(a).rotation * secondary).y > 0.99, "{side}");
            let foot_rotation = pose.global(c).rotation;
            let ik = TwoBoneIk {
                primary_axis: primary,
                secondary_axis: secondary,
                pole: Pole::Direction(Vec3::Y),
                weight: 1.0,
                stretch: None,
                set_effector_rotation: true,
            };
            let goal = end + Vec3::new(0.0, 0.0, 20.0);
            let r = ik.solve(
                &mut pose,
                a,
                b,
                c,
                Transform::from_translation_rotation(goal, foot_rotation),
            );
            assert!(r.reached, "{side}");
            let (knee, foot) = (pose.global(b).translation, pose.global(c).translation);
            assert!(
                (knee.distance(root) - mid.distance(root)).abs() < 1e-3,
                "{side}"
            );
            assert!(
                (foot.distance(knee) - end.distance(mid)).abs() < 1e-3,
                "{side}"
            );
            assert_near(foot, goal, 1e-3);
            assert!(knee.y > mid.y + 5.0, "{side}: knee {knee}");
            assert!((pose.global(a).rotation * secondary).y > 0.5, "{side}");
            assert!((pose.global(b).rotation * secondary).y > 0.5, "{side}");
            assert_same_rotation(pose.global(c).rotation, foot_rotation);
        }
    }

    // ---------------------------------------------------------------------------------------
    // Weight (ozz: Weight).
    // ---------------------------------------------------------------------------------------

    #[test]
    fn weight_blends_from_the_current_pose() {
        let ik = left_leg_ik();
        // Weight 1 and above (clamped): the full solve.
        for weight in [1.0, 1.1] {
            let mut l = leg(40.0, 40.0);
            assert!(l.solve(&TwoBoneIk { weight, ..ik }, at(30.0)).reached);
            assert_near(l.pos(l.calf), Vec3::new(0.0, H_60, 60.0), 1e-3);
        }
        // Weight 0 and below (clamped): untouched, though the report says reachable.
        for weight in [0.0, -0.1] {
            let mut l = leg(40.0, 40.0);
            let before = l.snapshot();
            assert!(l.solve(&TwoBoneIk { weight, ..ik }, at(30.0)).reached);
            assert_eq!(l.snapshot(), before);
        }
        // Weight 0.5: each rotation goes halfway. Thigh Rx(α/2)·Ry(−90°) with
        // sin(α/2) = √((1 − 0.75)/2) = 0.353553, cos(α/2) = √0.875 = 0.935414: knee at
        // (0, 40·0.353553, 90 − 40·0.935414) = (0, 14.1421, 52.5834). Calf Rx(−α/2)·Ry(−90°):
        // foot at 52.5834 − 37.4166 = 15.1669 straight below the hip: not at the target.
        let mut l = leg(40.0, 40.0);
        let r = l.solve(&TwoBoneIk { weight: 0.5, ..ik }, at(30.0));
        assert!(r.reached, "the report is about the full solve");
        assert_near(l.pos(l.calf), Vec3::new(0.0, 14.142_136, 52.583_4), 1e-3);
        assert_near(l.pos(l.foot), Vec3::new(0.0, 0.0, 15.166_9), 1e-3);
        assert_same_rotation(
            l.rot(l.thigh),
            Quat::from_rotation_x(alpha_60() / 2.0) * thigh_rest(),
        );
    }

    #[test]
    fn effector_rotation() {
        let goal = Quat::from_rotation_z(0.4) * Quat::from_rotation_x(0.3);
        let target = Transform::from_translation_rotation(Vec3::new(0.0, 0.0, 30.0), goal);
        let ik = TwoBoneIk {
            set_effector_rotation: true,
            ..left_leg_ik()
        };
        let mut l = leg(40.0, 40.0);
        assert!(l.solve(&ik, target).reached);
        assert_same_rotation(l.rot(l.foot), goal);
        // The ball follows the foot's new rotation.
        let ball = l.pos(l.foot) + goal * Vec3::new(0.0, 10.0, 0.0);
        assert_near(l.pos(l.ball), ball, 1e-3);
        // Half weight: halfway between the rest rotation Ry(−90°) and the goal.
        let mut l = leg(40.0, 40.0);
        l.solve(&TwoBoneIk { weight: 0.5, ..ik }, target);
        assert!(l.rot(l.foot).dot(thigh_rest().slerp(goal, 0.5)).abs() > 1.0 - 1e-4);
    }

    // ---------------------------------------------------------------------------------------
    // Soft stretch (ozz: Soften).
    // ---------------------------------------------------------------------------------------

    #[test]
    fn stretch_curve_by_hand() {
        // (start 0.75, max 1.25): scale = 1 + 0.25·clamp((r − 0.75)/0.5, 0, 1).
        let s = Some((0.75, 1.25));
        assert_eq!(stretch_scale(s, 0.5), 1.0);
        assert_eq!(stretch_scale(s, 0.75), 1.0);
        assert_eq!(stretch_scale(s, 1.0), 1.125);
        assert_eq!(stretch_scale(s, 1.25), 1.25);
        assert_eq!(stretch_scale(s, 9.0), 1.25);
        assert_eq!(stretch_scale(s, f32::INFINITY), 1.25);
        // Disabled: None, max ≤ 1, max ≤ start, non-finite.
        for off in [
            None,
            Some((0.75, 1.0)),
            Some((0.5, 0.9)),
            Some((1.3, 1.2)),
            Some((1.2, 1.2)),
            Some((f32::NAN, 1.2)),
            Some((0.8, f32::INFINITY)),
        ] {
            assert_eq!(stretch_scale(off, 1.1), 1.0, "{off:?}");
        }
        assert_eq!(stretch_scale(s, f32::NAN), 1.0);
        // Monotonic and bounded, and ≥ the reach ratio on the ramp (start ≤ 1): reachable.
        let mut last = 0.0;
        for i in 0..=400 {
            let r = i as f32 * 0.005;
            let k = stretch_scale(s, r);
            assert!(k >= last && (1.0..=1.25).contains(&k));
            if r <= 1.25 {
                assert!(k >= r - 1e-6);
            }
            last = k;
        }
    }

    #[test]
    fn stretch_on_the_leg() {
        let ik = TwoBoneIk {
            stretch: Some((0.75, 1.25)),
            ..left_leg_ik()
        };
        // r = 60/80 = 0.75: no stretch yet, the plain solve.
        let mut l = leg(40.0, 40.0);
        assert!(l.solve(&ik, at(30.0)).reached);
        assert_near(l.pos(l.calf), Vec3::new(0.0, H_60, 60.0), 1e-3);

        // r = 80/80 = 1: scale 1.125, bones 45/45, x = 40, h = √(45² − 40²) = √425
        // = 20.6155: the knee stays bent a little where the unstretched leg is straight.
        let mut l = leg(40.0, 40.0);
        assert!(l.solve(&ik, at(10.0)).reached);
        assert_near(l.pos(l.calf), Vec3::new(0.0, 20.615_53, 50.0), 1e-3);
        assert_near(l.pos(l.foot), Vec3::new(0.0, 0.0, 10.0), 1e-3);
        let calf_local = l.pose.local(l.calf);
        assert!((calf_local.translation.length() - 45.0).abs() < 1e-3);
        assert_eq!(calf_local.scale, Vec3::ONE);

        // r = 100/80 = 1.25: scale 1.25, bones 50/50, straight and reached. (Exactly at full
        // extension the knee's side offset h = √(l1² − x²) turns an f32 rounding δ of the
        // lengths into ≈ √(l·δ) — δ ≈ 1e-5 cm gives up to ~0.02 cm — hence 0.05 here.)
        let mut l = leg(40.0, 40.0);
        assert!(l.solve(&ik, at(-10.0)).reached);
        assert_near(l.pos(l.calf), Vec3::new(0.0, 0.0, 40.0), 0.05);
        assert!((l.pos(l.calf).distance(Vec3::new(0.0, 0.0, 90.0)) - 50.0).abs() < 1e-3);
        assert_near(l.pos(l.foot), Vec3::new(0.0, 0.0, -10.0), 1e-3);

        // r = 120/80 = 1.5: capped at 1.25, reach 100: 20 cm short.
        let mut l = leg(40.0, 40.0);
        let r = l.solve(&ik, at(-30.0));
        assert!(!r.reached);
        assert!((r.distance_to_target - 20.0).abs() < 1e-3);
        assert_near(l.pos(l.foot), Vec3::new(0.0, 0.0, -10.0), 1e-3);

        // Weight 0.5 at r = 1.25: rotations unchanged (straight already), lengths halfway:
        // 45/45, foot at 90 − 90 = 0.
        let mut l = leg(40.0, 40.0);
        l.solve(&TwoBoneIk { weight: 0.5, ..ik }, at(-10.0));
        assert_near(l.pos(l.calf), Vec3::new(0.0, 0.0, 45.0), 0.05);
        assert_near(l.pos(l.foot), Vec3::new(0.0, 0.0, 0.0), 0.05);

        // Without stretch the same target is out of reach.
        let mut l = leg(40.0, 40.0);
        let r = l.solve(&left_leg_ik(), at(-10.0));
        assert!(!r.reached);
        assert!((r.distance_to_target - 20.0).abs() < 1e-3);
    }

    // ---------------------------------------------------------------------------------------
    // Degenerate cases.
    // ---------------------------------------------------------------------------------------

    #[test]
    fn zero_length_bones() {
        // ozz: ZeroLengthBoneChain. Target (0, 30, 50): offset from the hip (0, 30, −40),
        // |·| = 50, direction (0, 0.6, −0.8).
        let target = Transform::from_translation(Vec3::new(0.0, 30.0, 50.0));
        let turned = Quat::from_rotation_x(0.6f32.atan2(0.8)) * thigh_rest(); // 36.87°

        // Zero-length thigh: the thigh keeps its rotation; the calf (40) aims at the target:
        // foot at hip + 40·(0, 0.6, −0.8) = (0, 24, 58), 10 cm short.
        let mut l = leg(0.0, 40.0);
        let r = l.solve(&left_leg_ik(), target);
        assert!(!r.reached);
        assert!((r.distance_to_target - 10.0).abs() < 1e-3);
        assert_same_rotation(l.rot(l.thigh), thigh_rest());
        assert_near(l.pos(l.calf), Vec3::new(0.0, 0.0, 90.0), 1e-4);
        assert_near(l.pos(l.foot), Vec3::new(0.0, 24.0, 58.0), 1e-3);
        // Calf secondary (+Y) → the pole side ⟂ the calf: (0, 0.8, 0.6).
        assert_same_rotation(l.rot(l.calf), turned);

        // Zero-length calf: the thigh aims, the calf keeps its global rotation.
        let mut l = leg(40.0, 0.0);
        let r = l.solve(&left_leg_ik(), target);
        assert!((r.distance_to_target - 10.0).abs() < 1e-3);
        assert_same_rotation(l.rot(l.thigh), turned);
        assert_same_rotation(l.rot(l.calf), thigh_rest());
        assert_near(l.pos(l.calf), Vec3::new(0.0, 24.0, 58.0), 1e-3);
        assert_near(l.pos(l.foot), Vec3::new(0.0, 24.0, 58.0), 1e-3);

        // Both zero: nothing to solve, pose unchanged, distance from the hip (50).
        let mut l = leg(0.0, 0.0);
        let before = l.snapshot();
        let r = l.solve(&left_leg_ik(), target);
        assert!(!r.reached);
        assert!((r.distance_to_target - 50.0).abs() < 1e-4);
        assert_eq!(l.snapshot(), before);
        assert_eq!(
            solve_positions(Vec3::ZERO, Vec3::ZERO, Vec3::ZERO, Vec3::X, Vec3::Y, None),
            (Vec3::ZERO, Vec3::ZERO)
        );
    }

    #[test]
    fn target_aligned_with_the_chain() {
        // ozz: PoleTargetAlignment / AlignedJointsAndTarget. Straight leg, target straight
        // below, pole parallel to the chain (or zero, or a location on the chain line): the
        // mid offset is zero too, so the thigh's secondary axis (+Y, forward) decides.
        for pole in [
            Pole::Direction(Vec3::new(0.0, 0.0, -1.0)),
            Pole::Direction(Vec3::new(0.0, 0.0, 3.0)),
            Pole::Direction(Vec3::ZERO),
            Pole::Location(Vec3::ZERO),
            Pole::Location(Vec3::new(0.0, 0.0, 90.0)),
        ] {
            let mut l = leg(40.0, 40.0);
            let ik = TwoBoneIk {
                pole,
                ..left_leg_ik()
            };
            assert!(l.solve(&ik, at(30.0)).reached, "{pole:?}");
            assert_near(l.pos(l.calf), Vec3::new(0.0, H_60, 60.0), 1e-3);
        }
        // A knee already bent backwards keeps bending backwards when the pole is parallel:
        // first bend it back (knee (0, −26.4575, 60)), then target 70 cm below the hip:
        // x = 35, h = √(1600 − 1225) = √375 = 19.3649, still behind.
        let mut l = leg(40.0, 40.0);
        let back = TwoBoneIk {
            pole: Pole::Direction(Vec3::new(0.0, -1.0, 0.0)),
            ..left_leg_ik()
        };
        l.solve(&back, at(30.0));
        let parallel = TwoBoneIk {
            pole: Pole::Direction(Vec3::new(0.0, 0.0, -1.0)),
            ..left_leg_ik()
        };
        assert!(l.solve(&parallel, at(20.0)).reached);
        assert_near(l.pos(l.calf), Vec3::new(0.0, -19.364_917, 55.0), 1e-3);

        // The pure solver, straight chain, target on its line and pole along it: some
        // perpendicular is picked; lengths hold and the target is reached.
        let (m, e) = solve_positions(
            Vec3::ZERO,
            Vec3::new(0.0, 0.0, -40.0),
            Vec3::new(0.0, 0.0, -80.0),
            Vec3::new(0.0, 0.0, -60.0),
            Vec3::new(0.0, 0.0, -1.0),
            None,
        );
        assert!((m.length() - 40.0).abs() < 1e-3 && (e.distance(m) - 40.0).abs() < 1e-3);
        assert!(((m.x * m.x + m.y * m.y).sqrt() - H_60).abs() < 1e-3);
        assert_near(e, Vec3::new(0.0, 0.0, -60.0), 1e-3);
    }

    #[test]
    fn unreachable_target_straightens_the_chain() {
        // Straight below, 100 cm from the hip: leg straight down, foot 20 cm short.
        let mut l = leg(40.0, 40.0);
        let r = l.solve(&left_leg_ik(), at(-10.0));
        assert!(!r.reached);
        assert!((r.distance_to_target - 20.0).abs() < 1e-3);
        assert_near(l.pos(l.calf), Vec3::new(0.0, 0.0, 50.0), 1e-3);
        assert_near(l.pos(l.foot), Vec3::new(0.0, 0.0, 10.0), 1e-3);
        assert_same_rotation(l.rot(l.thigh), thigh_rest());

        // Kicked forward, 100 cm in front of the hip with the knee pole up: knee (0, 40, 90),
        // foot (0, 80, 90); the thigh's −X → +Y (forward), +Y → +Z (up).
        let mut l = leg(40.0, 40.0);
        let ik = TwoBoneIk {
            pole: Pole::Direction(Vec3::Z),
            ..left_leg_ik()
        };
        let r = l.solve(
            &ik,
            Transform::from_translation(Vec3::new(0.0, 100.0, 90.0)),
        );
        assert!((r.distance_to_target - 20.0).abs() < 1e-3);
        assert_near(l.pos(l.calf), Vec3::new(0.0, 40.0, 90.0), 1e-3);
        assert_near(l.pos(l.foot), Vec3::new(0.0, 80.0, 90.0), 1e-3);
        let thigh = l.rot(l.thigh);
        assert_near(thigh * Vec3::new(-1.0, 0.0, 0.0), Vec3::Y, 1e-5);
        assert_near(thigh * Vec3::Y, Vec3::Z, 1e-5);

        // Far away (1e30 cm): still a straight chain towards it, no NaN.
        let mut l = leg(40.0, 40.0);
        let far = Transform::from_translation(Vec3::new(1e30, 1e30, 1e30));
        let r = l.solve(&left_leg_ik(), far);
        assert!(!r.reached);
        assert!(l.snapshot().iter().all(Transform::is_finite));
        let dir = Vec3::ONE.normalize();
        assert_near(l.pos(l.foot), Vec3::new(0.0, 0.0, 90.0) + dir * 80.0, 1e-3);
    }

    #[test]
    fn target_at_the_root() {
        // ozz: ZeroLengthStartTarget. 40/40 leg, target on the hip: the chain keeps its
        // direction (down) and folds completely, d = |40 − 40| = 0: knee straight out on the
        // pole side (0, 40, 90), foot back on the hip: reached. Thigh Rx(90°)·Ry(−90°)
        // (−X → +Y), calf Rx(−90°)·Ry(−90°) (−X → −Y).
        let mut l = leg(40.0, 40.0);
        let r = l.solve(&left_leg_ik(), at(90.0));
        assert!(r.reached);
        assert_near(l.pos(l.calf), Vec3::new(0.0, 40.0, 90.0), 1e-3);
        assert_near(l.pos(l.foot), Vec3::new(0.0, 0.0, 90.0), 1e-3);
        assert_same_rotation(
            l.rot(l.thigh),
            Quat::from_rotation_x(FRAC_PI_2) * thigh_rest(),
        );
        assert_same_rotation(
            l.rot(l.calf),
            Quat::from_rotation_x(-FRAC_PI_2) * thigh_rest(),
        );

        // 30/50 leg: the closest the foot gets is |30 − 50| = 20 along the current direction
        // (down): x = (400 + 900 − 2500)/40 = −30, h = 0: the thigh points straight up
        // (knee (0, 0, 120)), the calf comes back down to (0, 0, 70).
        let mut l = leg(30.0, 50.0);
        let r = l.solve(&left_leg_ik(), at(90.0));
        assert!(!r.reached);
        assert!((r.distance_to_target - 20.0).abs() < 1e-3);
        assert_near(l.pos(l.calf), Vec3::new(0.0, 0.0, 120.0), 1e-3);
        assert_near(l.pos(l.foot), Vec3::new(0.0, 0.0, 70.0), 1e-3);
        // Thigh turned 180° about +X: +Y → −Y. Calf unchanged.
        assert_same_rotation(l.rot(l.thigh), Quat::from_rotation_x(PI) * thigh_rest());
        assert_same_rotation(l.rot(l.calf), thigh_rest());
        assert!(l.snapshot().iter().all(Transform::is_finite));
    }

    #[test]
    fn scale_is_ignored() {
        // ozz: ZeroScale. A zero-scaled thigh collapses calf and foot onto the hip: both
        // bones have zero length, the pose is left as it is, no NaN.
        let mut l = leg_under(Transform::IDENTITY, 40.0, 40.0, Vec3::ZERO);
        let before = l.snapshot();
        let r = l.solve(&left_leg_ik(), at(30.0));
        assert!(!r.reached && (r.distance_to_target - 60.0).abs() < 1e-4);
        assert_eq!(l.snapshot(), before);

        // Scale across the bone (local Y, Z; one of them zero) does not change the lengths
        // (along local X): the usual answer, and the scales are kept.
        for scale in [Vec3::new(1.0, 3.0, 0.5), Vec3::new(1.0, 0.0, 1.0)] {
            let mut l = leg_under(Transform::IDENTITY, 40.0, 40.0, scale);
            assert!(l.solve(&left_leg_ik(), at(30.0)).reached, "{scale}");
            assert_near(l.pos(l.calf), Vec3::new(0.0, H_60, 60.0), 1e-3);
            assert_same_rotation(
                l.rot(l.thigh),
                Quat::from_rotation_x(alpha_60()) * thigh_rest(),
            );
            assert_eq!(l.pose.global(l.thigh).scale, scale);
            assert!(l.snapshot().iter().all(Transform::is_finite));
        }

        // Scale along the bone makes it longer: thigh scale (2, 1, 1) is inherited by the
        // calf, so both bones measure 80. Target 100 below: x = 50, h = √(6400 − 2500)
        // = 62.45 forward.
        let mut l = leg_under(Transform::IDENTITY, 40.0, 40.0, Vec3::new(2.0, 1.0, 1.0));
        assert!(l.solve(&left_leg_ik(), at(-10.0)).reached);
        assert_near(l.pos(l.calf), Vec3::new(0.0, 62.449_98, 40.0), 1e-3);
        assert_eq!(l.pose.global(l.thigh).scale, Vec3::new(2.0, 1.0, 1.0));
    }

    // ---------------------------------------------------------------------------------------
    // Properties over random chains.
    // ---------------------------------------------------------------------------------------

    /// xorshift64: small, deterministic, no dependencies.
    struct Rng(u64);

    impl Rng {
        fn next(&mut self) -> u64 {
            let mut x = self.0;
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            self.0 = x;
            x
        }
        /// Uniform in [0, 1).
        fn unit_f(&mut self) -> f32 {
            (self.next() >> 40) as f32 / (1u64 << 24) as f32
        }
        fn range(&mut self, lo: f32, hi: f32) -> f32 {
            lo + (hi - lo) * self.unit_f()
        }
        fn chance(&mut self, p: f32) -> bool {
            self.unit_f() < p
        }
        fn dir(&mut self) -> Vec3 {
            loop {
                let v = Vec3::new(
                    self.range(-1.0, 1.0),
                    self.range(-1.0, 1.0),
                    self.range(-1.0, 1.0),
                );
                let l = v.length();
                if l > 0.1 && l <= 1.0 {
                    return v / l;
                }
            }
        }
        fn quat(&mut self) -> Quat {
            Quat::from_axis_angle(self.dir(), self.range(-PI, PI))
        }
    }

    /// A pelvis at `pelvis`, a bone `a` under it at a random offset, and `b`, `c` placed
    /// `l1` and `l2` along `primary` from their parents, each turned at random, and a `toe`
    /// under `c`.
    fn random_leg(
        rng: &mut Rng,
        pelvis: Transform,
        primary: Vec3,
        (l1, l2): (f32, f32),
    ) -> Arc<Skeleton> {
        let turned =
            |rng: &mut Rng, offset: Vec3| Transform::from_translation_rotation(offset, rng.quat());
        let a = {
            let offset = rng.dir() * 10.0;
            turned(rng, offset)
        };
        let b = turned(rng, primary * l1);
        let c = turned(rng, primary * l2);
        let toe = Transform::from_translation(rng.dir() * 10.0);
        Arc::new(
            Skeleton::new(vec![
                bone("pelvis", None, pelvis),
                bone("a", Some("pelvis"), a),
                bone("b", Some("a"), b),
                bone("c", Some("b"), c),
                bone("toe", Some("c"), toe),
            ])
            .unwrap(),
        )
    }

    #[test]
    fn random_solve_positions() {
        let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
        for i in 0..3000 {
            let root = Vec3::new(
                rng.range(-100.0, 100.0),
                rng.range(-100.0, 100.0),
                rng.range(0.0, 150.0),
            );
            let l1 = rng.range(1.0, 80.0);
            let l2 = rng.range(1.0, 80.0);
            let mid = root + rng.dir() * l1;
            let end = mid + rng.dir() * l2;
            let (lo, hi) = ((l1 - l2).abs(), l1 + l2);
            let eps = 0.01 * hi;
            let d = if rng.chance(0.8) {
                rng.range(lo + eps, hi - eps)
            } else {
                rng.range(0.0, 2.0 * hi)
            };
            let target = root + rng.dir() * d;
            // Direction and distance as rounded in f32, as the solver sees them.
            let (dir, d) = ((target - root).normalize_or_zero(), target.distance(root));
            let pole = rng.dir() * rng.range(0.1, 100.0);
            let (m, e) = solve_positions(root, mid, end, target, pole, None);
            let ctx = format!("case {i}: l1 {l1} l2 {l2} d {d}");
            assert!(m.is_finite() && e.is_finite(), "{ctx}");
            assert!((m.distance(root) - l1).abs() < 1e-3, "{ctx}");
            assert!((e.distance(m) - l2).abs() < 1e-3, "{ctx}");
            if d >= lo + eps && d <= hi - eps {
                assert!(e.distance(target) < 1e-3, "{ctx}");
            }
            if d > 1e-2 {
                // The effector is on the root → target line, at the clamped distance.
                assert_near(e, root + dir * d.max(lo).min(hi), 1e-3);
                // The mid joint is in the plane of the chain and the pole, on the pole side.
                if let Some(side) = perp(pole, dir) {
                    let normal = dir.cross(side);
                    assert!((m - root).dot(normal).abs() < 1e-3, "{ctx}");
                    assert!((m - root).dot(side) >= -1e-3, "{ctx}");
                }
            }
            // With stretch: finite, never longer than max, and reached whenever the target is
            // within the stretched chain's reach [k·|l1 − l2|, k·(l1 + l2)] (for start ≤ 1
            // that covers everything from the plain minimum reach up to max·(l1 + l2), as
            // long as k·|l1 − l2| stays below the target).
            let (start, max) = (rng.range(0.5, 1.0), rng.range(1.0, 1.5));
            let (m, e) = solve_positions(root, mid, end, target, pole, Some((start, max)));
            assert!(m.is_finite() && e.is_finite(), "{ctx}");
            let k = m.distance(root) / l1;
            assert!((1.0 - 1e-4..=max + 1e-4).contains(&k), "{ctx}: k {k}");
            assert!(
                (k - stretch_scale(Some((start, max)), d / hi)).abs() < 1e-4,
                "{ctx}"
            );
            assert!((e.distance(m) / l2 - k).abs() < 1e-3, "{ctx}");
            if d >= k * lo + eps && d <= k * hi - eps {
                assert!(e.distance(target) < 1e-3, "{ctx}");
            }
            if d <= max * hi - eps && d >= max * lo + eps {
                assert!(e.distance(target) < 1e-3, "{ctx}");
            }
        }
    }

    #[test]
    fn random_chains_on_a_pose() {
        let mut rng = Rng(0xD1B5_4A32_D192_ED03);
        for i in 0..3000 {
            // A random pelvis (uniform scale), a thigh under it, calf and foot placed along
            // a random primary axis, random local rotations everywhere.
            let primary = rng.dir();
            let secondary = if rng.chance(0.8) {
                primary.any_orthonormal_vector()
            } else {
                let s = rng.dir();
                if perp(s, primary).is_some() {
                    s
                } else {
                    primary.any_orthonormal_vector()
                }
            };
            let secondary = if rng.chance(0.5) {
                Quat::from_axis_angle(primary, rng.range(-PI, PI)) * secondary
            } else {
                secondary
            };
            let scale = rng.range(0.5, 2.0);
            let pelvis = Transform::new(
                Vec3::new(
                    rng.range(-50.0, 50.0),
                    rng.range(-50.0, 50.0),
                    rng.range(80.0, 120.0),
                ),
                rng.quat(),
                Vec3::splat(scale),
            );
            let (l1, l2) = (rng.range(1.0, 60.0), rng.range(1.0, 60.0));
            let s = random_leg(&mut rng, pelvis, primary, (l1, l2));
            let (a, b, c) = (BoneIndex(1), BoneIndex(2), BoneIndex(3));
            let mut pose = Pose::new(s);
            let before = pose.globals().to_vec();
            let (root, mid, end) = (
                before[1].translation,
                before[2].translation,
                before[3].translation,
            );
            let (l1, l2) = (mid.distance(root), end.distance(mid));
            let (lo, hi) = ((l1 - l2).abs(), l1 + l2);
            let eps = 0.01 * hi;
            let in_range = rng.chance(0.7);
            let d = if in_range {
                rng.range(lo + eps, hi - eps)
            } else if rng.chance(0.5) {
                rng.range(hi, 3.0 * hi)
            } else {
                rng.range(0.0, 3.0 * hi)
            };
            let goal = root + rng.dir() * d;
            let target = Transform::from_translation_rotation(goal, rng.quat());
            // Direction and distance as rounded in f32, as the solver sees them.
            let (dir, d) = ((goal - root).normalize(), goal.distance(root));
            let pole_vec = match i % 10 {
                0 => dir * rng.range(-5.0, 5.0), // parallel to the chain
                1 => Vec3::ZERO,
                _ => rng.dir() * rng.range(0.1, 100.0),
            };
            // The pole as the solver sees it (a location minus the root, rounded).
            let (pole, pole_vec) = if rng.chance(0.5) {
                (Pole::Direction(pole_vec), pole_vec)
            } else {
                (Pole::Location(root + pole_vec), (root + pole_vec) - root)
            };
            let weight = match i % 5 {
                0 => 0.0,
                1 => rng.unit_f(),
                _ => 1.0,
            };
            let stretch = rng
                .chance(0.3)
                .then(|| (rng.range(0.5, 1.0), rng.range(1.0, 1.5)));
            let ik = TwoBoneIk {
                primary_axis: primary,
                secondary_axis: secondary,
                pole,
                weight,
                stretch,
                set_effector_rotation: rng.chance(0.5),
            };
            let ctx = format!("case {i}: {ik:?} l1 {l1} l2 {l2} d {d}");

            let report = ik.solve(&mut pose, a, b, c, target);
            let after = pose.globals().to_vec();
            assert!(after.iter().all(Transform::is_finite), "{ctx}");
            assert!(report.distance_to_target.is_finite(), "{ctx}");
            if weight == 0.0 {
                assert_eq!(after, before, "{ctx}");
                continue;
            }
            let (m, e) = (after[2].translation, after[3].translation);
            assert_eq!(after[1].translation, root, "{ctx}");
            if stretch.is_none() {
                assert!((m.distance(root) - l1).abs() < 1e-3, "{ctx}");
                assert!((e.distance(m) - l2).abs() < 1e-3, "{ctx}");
            }
            // The toe follows the effector rigidly.
            let toe_local = before[3].inverse().transform_point(before[4].translation);
            assert_near(
                after[4].translation,
                after[3].transform_point(toe_local),
                1e-3,
            );
            if weight < 1.0 {
                continue;
            }
            assert!(
                (report.distance_to_target - e.distance(goal)).abs() < 1e-3,
                "{ctx}"
            );
            // Reached whenever the target is inside the (stretched) chain's reach.
            let k = stretch_scale(stretch, d / hi);
            if in_range && d >= k * lo + eps && d <= k * hi - eps {
                assert!(report.reached, "{ctx}");
                assert!(e.distance(goal) < 1e-3, "{ctx}");
            }
            if ik.set_effector_rotation {
                assert!(
                    after[3].rotation.dot(target.rotation).abs() >= 1.0 - 1e-5,
                    "{ctx}"
                );
            } else {
                // The effector kept its rotation relative to B.
                let rel_before = before[2].rotation.inverse() * before[3].rotation;
                let rel_after = after[2].rotation.inverse() * after[3].rotation;
                assert!(rel_before.dot(rel_after).abs() >= 1.0 - 1e-5, "{ctx}");
            }
            // The solved rotations are unit (the frames' rotation is read off an orthonormal
            // matrix, not normalised again).
            for r in [after[1].rotation, after[2].rotation] {
                assert!(
                    (r.length() - 1.0).abs() < 1e-5,
                    "{ctx}: |r| = {}",
                    r.length()
                );
            }
            // Primary axes along the bones.
            let ua = (m - root).normalize();
            let ub = (e - m).normalize();
            assert!((after[1].rotation * primary).dot(ua) >= 1.0 - 1e-4, "{ctx}");
            assert!((after[2].rotation * primary).dot(ub) >= 1.0 - 1e-4, "{ctx}");
            // Plane and pole side, for a pole that is not parallel to the chain.
            let Some(side) = perp(pole_vec, dir) else {
                continue;
            };
            let normal = dir.cross(side);
            assert!((m - root).dot(normal).abs() < 1e-3, "{ctx}");
            assert!((m - root).dot(side) >= -1e-3, "{ctx}");
            // Secondary axes (their part ⟂ primary) lie in the bend plane, ⟂ their bone, on
            // the pole side of it: normal × bone direction.
            let sec = (secondary - primary * secondary.dot(primary)).normalize();
            let sec_a = after[1].rotation * sec;
            let sec_b = after[2].rotation * sec;
            assert!(sec_a.dot(normal.cross(ua)) >= 1.0 - 1e-3, "{ctx}");
            assert!(sec_b.dot(normal.cross(ub)) >= 1.0 - 1e-3, "{ctx}");
            // So A's secondary axis points to the pole side whenever the thigh goes towards
            // the target (sec_a·side = cos of the angle between A and the chain line).
            if ua.dot(dir) >= 0.0 {
                assert!(sec_a.dot(side) >= -1e-3, "{ctx}");
            }
        }
    }

    #[test]
    fn garbage_settings_never_panic_or_write_nan() {
        // Settings and targets drawn from a palette of awkward values: zeros, signed zeros,
        // tiny, huge, infinite, NaN. The pose must stay finite; a non-finite target must
        // leave it unchanged.
        const PALETTE: [f32; 14] = [
            0.0,
            -0.0,
            1e-30,
            1e-6,
            1.0,
            -1.0,
            0.5,
            40.0,
            -90.0,
            1e20,
            1e38,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
        ];
        let mut rng = Rng(0xA076_1D64_78BD_642F);
        let pick = |rng: &mut Rng| {
            if rng.chance(0.5) {
                PALETTE[(rng.next() % PALETTE.len() as u64) as usize]
            } else {
                rng.range(-100.0, 100.0)
            }
        };
        for i in 0..2000 {
            let v = |rng: &mut Rng| Vec3::new(pick(rng), pick(rng), pick(rng));
            let ik = TwoBoneIk {
                primary_axis: if i % 3 == 0 {
                    Vec3::new(-1.0, 0.0, 0.0)
                } else {
                    v(&mut rng)
                },
                secondary_axis: v(&mut rng),
                pole: if rng.chance(0.5) {
                    Pole::Direction(v(&mut rng))
                } else {
                    Pole::Location(v(&mut rng))
                },
                weight: pick(&mut rng),
                stretch: rng.chance(0.5).then(|| (pick(&mut rng), pick(&mut rng))),
                set_effector_rotation: rng.chance(0.5),
            };
            let target = Transform::new(
                v(&mut rng),
                Quat::from_xyzw(
                    pick(&mut rng),
                    pick(&mut rng),
                    pick(&mut rng),
                    pick(&mut rng),
                ),
                Vec3::ONE,
            );
            let (l1, l2) = (
                PALETTE[i % 9].abs().min(60.0),
                PALETTE[(i / 9) % 9].abs().min(60.0),
            );
            let mut l = leg(l1, l2);
            let before = l.snapshot();
            let report = l.solve(&ik, target);
            let after = l.snapshot();
            assert!(
                after.iter().all(Transform::is_finite),
                "case {i}: {ik:?} {target:?}"
            );
            assert!(!report.distance_to_target.is_nan(), "case {i}");
            if !target.is_finite() {
                assert_eq!(after, before, "case {i}");
            }
            let (m, e) = solve_positions(
                Vec3::new(0.0, 0.0, 90.0),
                Vec3::new(0.0, 0.0, 90.0 - l1),
                Vec3::new(0.0, 0.0, 90.0 - l1 - l2),
                target.translation,
                v(&mut rng),
                ik.stretch,
            );
            assert!(m.is_finite() && e.is_finite(), "case {i}");
        }
    }

    /// Every chain's answer from the lanes ([`ChainLanes`]) is the one-chain solve's, bit
    /// for bit: the pose after writing the lanes' globals and locals (only the globals for
    /// a chain given a parent that is not finite), and the report. Batches of 16
    /// chains under random poses share their axes; some chains have weights below 1, poles
    /// parallel to the chain or zero, targets on bone A, zero-length bones, non-finite
    /// globals or a non-finite target (position or scale), which the lanes must leave to
    /// the one-chain solve. It fails if the lanes solve fewer chains than 95 % of the
    /// ordinary ones (a lane path that gives up on everything would pass the comparison
    /// alone). Where glam computes otherwise ([`LANES_MATCH_GLAM`]) there is nothing to
    /// compare.
    #[test]
    #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
    fn lanes_solve_the_common_case_as_one_chain_does() {
        const N: usize = 16;
        let mut rng = Rng(0x2545_F491_4F6C_DD1D);
        let (mut solved, mut ordinary) = (0, 0);
        for batch in 0..200 {
            let primary = rng.dir();
            let secondary = Quat::from_axis_angle(primary, rng.range(-PI, PI))
                * primary.any_orthonormal_vector();
            let axes = BoneAxes::new(primary, secondary);
            let mut poses = Vec::new();
            let mut inputs = Vec::new();
            let mut live = [true; N];
            for (m, alive) in live.iter_mut().enumerate() {
                let case = (batch * N + m) % 23;
                let (l1, l2) = match case {
                    0 => (0.0, 0.0),
                    1 => (rng.range(1.0, 60.0), 0.0),
                    _ => (rng.range(1.0, 60.0), rng.range(1.0, 60.0)),
                };
                let pelvis = Transform::new(
                    Vec3::new(rng.range(-50.0, 50.0), 0.0, rng.range(80.0, 120.0)),
                    rng.quat(),
                    Vec3::splat(rng.range(0.5, 2.0)),
                );
                let s = random_leg(&mut rng, pelvis, primary, (l1, l2));
                let mut pose = Pose::new(s);
                if case == 11 {
                    // Bone B's rotation not a number: its global and the effector's too.
                    let nan = Quat::from_xyzw(f32::NAN, 0.0, 0.0, 1.0);
                    pose.set_local(
                        BoneIndex(2),
                        Transform::from_translation_rotation(primary * l1, nan),
                    );
                }
                let g = pose.globals().to_vec();
                let root = g[1].translation;
                let reach =
                    g[2].translation.distance(root) + g[3].translation.distance(g[2].translation);
                let goal = match case {
                    2 => root,
                    3 => Vec3::new(f32::NAN, 0.0, 0.0),
                    _ => root + rng.dir() * rng.range(0.0, 1.5 * reach.max(1.0)),
                };
                let pole_vec = match case {
                    4 => (goal - root) * 2.0,
                    5 => Vec3::ZERO,
                    _ => rng.dir() * rng.range(0.1, 100.0),
                };
                let pole = if rng.chance(0.5) {
                    Pole::Direction(pole_vec)
                } else {
                    Pole::Location(root + pole_vec)
                };
                let ik = TwoBoneIk {
                    primary_axis: primary,
                    secondary_axis: secondary,
                    pole,
                    weight: match case {
                        6 => 0.0,
                        7 => 0.5,
                        8 => f32::NAN,
                        9 => 3.0,
                        _ => 1.0,
                    },
                    stretch: rng
                        .chance(0.3)
                        .then(|| (rng.range(0.5, 1.0), rng.range(1.0, 1.5))),
                    set_effector_rotation: rng.chance(0.5),
                };
                *alive = case != 10;
                inputs.push(ChainInput {
                    ik,
                    globals: [g[1], g[2], g[3]],
                    target: Transform::new(
                        goal,
                        rng.quat(),
                        Vec3::splat(if case == 12 { f32::NAN } else { 1.0 }),
                    ),
                    // Case 13: a parent the chain's locals cannot be computed against
                    // (the lanes leave them to `set_chain_globals`).
                    parent: Some(if case == 13 {
                        Transform::from_translation(Vec3::NAN)
                    } else {
                        g[0]
                    }),
                });
                poses.push(pose);
            }
            let mut lanes = ChainLanes::<N>::default();
            for (m, x) in inputs.iter().enumerate() {
                if live[m] {
                    lanes.set(m, x);
                }
            }
            lanes.solve(&axes);
            lanes.relate();
            let bones = [BoneIndex(1), BoneIndex(2), BoneIndex(3)];
            for (m, pose) in poses.into_iter().enumerate() {
                let case = (batch * N + m) % 23;
                ordinary += usize::from(case >= 13 || case == 9);
                let x = inputs[m];
                let Some(answer) = lanes.solution(m) else {
                    continue;
                };
                solved += 1;
                let ctx = format!("batch {batch} chain {m}: {x:?}");
                assert!(live[m] && x.ik.weight >= 1.0, "{ctx}");
                let mut one = pose.clone();
                let report =
                    x.ik.solve_with_axes(&axes, &mut one, bones[0], bones[1], bones[2], x.target);
                let mut by_lanes = pose;
                if case == 13 {
                    assert!(answer.locals.is_none(), "{ctx}");
                    by_lanes.set_chain_globals(bones, answer.globals);
                } else {
                    let locals = answer.locals.expect("a finite parent");
                    assert!(by_lanes.set_chain_with_locals(bones, answer.globals, locals));
                }
                let bits = |p: &mut Pose| {
                    p.globals()
                        .iter()
                        .map(Transform::to_bits)
                        .collect::<Vec<_>>()
                };
                assert_eq!(bits(&mut by_lanes), bits(&mut one), "{ctx}");
                let locals = |p: &Pose| {
                    p.locals()
                        .iter()
                        .map(Transform::to_bits)
                        .collect::<Vec<_>>()
                };
                assert_eq!(locals(&by_lanes), locals(&one), "{ctx}");
                assert_eq!(answer.report.reached, report.reached, "{ctx}");
                assert_eq!(
                    answer.report.distance_to_target.to_bits(),
                    report.distance_to_target.to_bits(),
                    "{ctx}"
                );
            }
        }
        // Cases 13 and up (and 9, whose weight counts as 1) are ordinary chains.
        assert!(
            solved * 100 >= ordinary * 95,
            "the lanes solved {solved} chains, {ordinary} ordinary ones"
        );
    }
}
