//! Locomotion unit kernels: the math of the procedural locomotion rig
//! (`spec/locomotion.md`, after the seed's Control Rig units) and of standing foot IK
//! (`spec/foot-ik-and-als.md`), one plain function per node, plus the damping family the
//! rig smooths its state with.
//!
//! # Conventions
//!
//! Rig space is the character's component space: **+Z up, +Y forward, +X the character's
//! left** (right-handed), lengths in **centimetres**, time in **seconds**, every angle on a
//! pin in **degrees**. A positive angle about an axis follows the right-hand rule, so a
//! positive yaw (about +Z) turns forward towards the character's **right**:
//! `Rz(θ)·(0,1,0) = (−sin θ, cos θ, 0)`; `Rz(+45°)` maps +Y to (−0.707, 0.707, 0).
//!
//! Every tunable of the rig is a parameter. Each parameter's doc gives, in parentheses, the
//! seed's value that the node table uses as the default.
//!
//! # Degenerate input
//!
//! No kernel panics, allocates or returns a non-finite value. Each documents its fallback;
//! the general rules are: a non-finite *state* input (the current value of something being
//! smoothed) is replaced by the target; a non-finite target or direction keeps the current
//! state; a non-finite tunable counts as 0 unless stated otherwise; a result that would
//! overflow `f32` falls back as documented.

use glam::{Quat, Vec3};
use strider_core::EulerOrder;
use strider_core::euler::quat_from_euler;

use super::{clamp_f, clamp_length, div_f, fract, quat_scale, remap, slerp, unit_q, unit_v};

// ---------------------------------------------------------------------------------------
// Small private helpers.
// ---------------------------------------------------------------------------------------

/// `value` if finite, else `fallback`.
#[inline]
fn finite_or(value: f32, fallback: f32) -> f32 {
    if value.is_finite() { value } else { fallback }
}

/// `value` if every component is finite, else `fallback`.
#[inline]
fn finite_v_or(value: Vec3, fallback: Vec3) -> Vec3 {
    if value.is_finite() { value } else { fallback }
}

/// `value > 0`; false for NaN.
#[inline]
fn positive(value: f32) -> bool {
    value > 0.0
}

/// `value` clamped to [0, 1]; NaN → 0.
#[inline]
fn clamp01(value: f32) -> f32 {
    if value.is_nan() {
        0.0
    } else {
        value.clamp(0.0, 1.0)
    }
}

/// A finite angle in degrees wrapped to (−180, 180]. `%` on floats is exact (IEEE fmod),
/// and the ±360 corrections are exact too (Sterbenz), so even huge angles wrap correctly.
#[inline]
fn wrap_deg(degrees: f32) -> f32 {
    let r = degrees % 360.0;
    if r > 180.0 {
        r - 360.0
    } else if r <= -180.0 {
        r + 360.0
    } else {
        r
    }
}

/// The frame-rate independent blend weight `1 − e^(−rate·dt)` (in 0..=1) for a decay
/// `rate` in 1/s over `dt` seconds, computed as `−expm1(−rate·dt)` for precision at small
/// steps. A rate or dt that is not positive (or NaN) gives 0 (no motion); an infinite
/// product gives 1.
#[inline]
#[must_use]
pub fn exp_alpha(rate: f32, dt: f32) -> f32 {
    if !positive(rate) || !positive(dt) {
        return 0.0;
    }
    let x = rate * dt;
    if x.is_infinite() {
        1.0
    } else {
        clamp01(-(-x).exp_m1())
    }
}

/// Unreal's blend weight `clamp(dt·speed, 0, 1)` (NaN → 0).
#[inline]
fn unreal_alpha(speed: f32, dt: f32) -> f32 {
    clamp01(dt * speed)
}

/// The yaw of a unit-ish quaternion's twist about +Z in the swing-twist split
/// `q = swing · twist` (twist applied first, about +Z; swing about a horizontal axis).
/// Returns `(swing, yaw_deg)`. When the twist is undefined (q is a 180° turn about a
/// horizontal axis, so q.z = q.w = 0) the twist is taken as the identity (yaw 0).
fn swing_twist_z(q: Quat) -> (Quat, f32) {
    let twist = Quat::from_xyzw(0.0, 0.0, q.z, q.w);
    let len = twist.length();
    if len.is_nan() || len <= 1e-6 {
        return (q, 0.0);
    }
    let twist = twist / len;
    let swing = unit_q(q * twist.conjugate());
    let yaw = wrap_deg((2.0 * twist.z.atan2(twist.w)).to_degrees());
    (swing, yaw)
}

/// The folded movement yaw of a velocity (degrees about +Z), or `None` when its XY part
/// is zero or not finite. `yaw = atan2(−v.x, v.y)` is the Z angle of the rotation from
/// (0,1,0) to the velocity's XY direction; beyond ±`fold_threshold_deg` it is folded by
/// 180° (backward diagonals use the forward diagonal's foot orientation).
fn folded_movement_yaw(velocity: Vec3, fold_threshold_deg: f32) -> Option<f32> {
    let (x, y) = (velocity.x, velocity.y);
    if !(x.is_finite() && y.is_finite()) || (x == 0.0 && y == 0.0) {
        return None;
    }
    let yaw = (-x).atan2(y).to_degrees();
    Some(if yaw > fold_threshold_deg {
        yaw - 180.0
    } else if yaw < -fold_threshold_deg {
        yaw + 180.0
    } else {
        yaw
    })
}

// ---------------------------------------------------------------------------------------
// Movement direction.
// ---------------------------------------------------------------------------------------

/// **GetMovementAngleOffset**: the new MovementAngleOffset, in **degrees about rig +Z**
/// (a yaw; positive turns forward towards the character's right), in (−180, 180].
///
/// - `velocity`: rig-space velocity, cm/s. Only its XY direction matters.
/// - `current_offset_deg`: last frame's offset, degrees about +Z.
/// - `master_cycle`: MasterCyclePercent, in cycles [0, 1).
/// - `dt`: frame time, seconds.
/// - `speed` (6): normal blend rate `k`, 1/s.
/// - `jump_speed` (0.2): blend rate, 1/s, used for a large jump outside the step start
///   (nearly frozen: keeps the legs from crossing on sudden reversals).
/// - `jump_threshold_deg` (90): a target further than this (shortest angle) from the
///   current offset is a jump.
/// - `fold_threshold_deg` (110): raw yaws beyond ±this are folded by 180°.
/// - `step_start_gate` (0.4): the start of each step is `fract(2·master_cycle) < gate`.
///
/// ```text
/// yaw    = atan2(−v.x, v.y)        Z angle of the rotation from (0,1,0) to v.xy
/// target = yaw − 180 if yaw > fold;  yaw + 180 if yaw < −fold;  else yaw
/// d      = wrap(target − current)  shortest difference, (−180, 180]
/// k      = jump_speed if |d| > jump_threshold and fract(2·M) ≥ gate, else speed
/// new    = wrap(current + d·(1 − e^(−k·dt)))
/// ```
///
/// The blend is exactly frame-rate independent (the seed's `clamp(k·dt, 0, 1)` is not).
///
/// Fallbacks: a zero or non-finite velocity XY keeps the current offset (the offset
/// freezes when the character stops); a non-finite current offset counts as 0; `dt` or a
/// rate that is not positive (or NaN) means no change; a non-finite `master_cycle` (or
/// gate) counts as *outside* the step start, so a jump blends at `jump_speed`.
#[must_use]
pub fn get_movement_angle_offset(
    velocity: Vec3,
    current_offset_deg: f32,
    master_cycle: f32,
    dt: f32,
    speed: f32,
    jump_speed: f32,
    jump_threshold_deg: f32,
    fold_threshold_deg: f32,
    step_start_gate: f32,
) -> f32 {
    let current = wrap_deg(finite_or(current_offset_deg, 0.0));
    let Some(target) = folded_movement_yaw(velocity, fold_threshold_deg) else {
        return current;
    };
    let d = wrap_deg(target - current);
    // Written as "< gate" so that NaN fails it: NaN is not the start of a step.
    let in_step_start = fract(2.0 * master_cycle) < step_start_gate;
    let rate = if d.abs() > jump_threshold_deg && !in_step_start {
        jump_speed
    } else {
        speed
    };
    wrap_deg(current + d * exp_alpha(rate, dt))
}

/// **CalculatePerFootRotationFactor**: how much of the movement angle offset a foot takes
/// (dimensionless): `positive_factor` when `yaw_deg > 0`, else `negative_factor`.
///
/// - `yaw_deg`: the movement angle offset, degrees about +Z.
/// - `positive_factor` (0.5): factor for a positive yaw (moving towards the right).
/// - `negative_factor` (0.9): factor for zero or negative yaw.
///
/// The seed gives both feet the same rule. A NaN yaw is not > 0 and gets
/// `negative_factor`; a non-finite factor counts as 0.
#[must_use]
pub fn per_foot_rotation_factor(yaw_deg: f32, positive_factor: f32, negative_factor: f32) -> f32 {
    let factor = if yaw_deg > 0.0 {
        positive_factor
    } else {
        negative_factor
    };
    finite_or(factor, 0.0)
}

/// **LimitRotationAroundZ**: `rotation` with its yaw (twist about rig +Z) clamped to
/// `center_yaw_deg ± limit_deg`, its tilt (swing) kept.
///
/// - `rotation`: a rig-space rotation (normalised here; zero or non-finite → identity).
/// - `center_yaw_deg` (the movement angle offset): degrees about +Z.
/// - `limit_deg` (25): half-width of the allowed yaw range, degrees (negative or NaN → 0).
///
/// Swing-twist split: `rotation = swing · twist`, where `twist` = the normalised
/// `(0, 0, q.z, q.w)` is a pure rotation about +Z (the yaw), applied first, and `swing`
/// rotates about a horizontal axis (its z component is exactly 0). The yaw is measured
/// from the center along the shortest way and clamped, and the result is
/// `swing · Rz(center + clamped)`. Because the swing is kept in rig space, the rotated
/// +Z axis (a foot's sole normal, say) is unchanged: a foot on a slope stays on the
/// slope. For a rotation without tilt the twist yaw is its Euler Z angle; with tilt it
/// differs slightly from the Euler Z angle (which mixes in pitch and roll).
///
/// Fallbacks: a 180° tilt has no defined twist; its yaw counts as 0. A non-finite center
/// returns the normalised rotation unchanged.
#[must_use]
pub fn limit_rotation_around_z(rotation: Quat, center_yaw_deg: f32, limit_deg: f32) -> Quat {
    let q = unit_q(rotation);
    if !center_yaw_deg.is_finite() {
        return q;
    }
    let limit = if limit_deg.is_nan() {
        0.0
    } else {
        limit_deg.max(0.0)
    };
    let (swing, yaw) = swing_twist_z(q);
    let offset = wrap_deg(yaw - center_yaw_deg);
    let clamped = clamp_f(offset, -limit, limit);
    if clamped == offset {
        return q;
    }
    let new_yaw = wrap_deg(center_yaw_deg + clamped);
    unit_q(swing * Quat::from_rotation_z(new_yaw.to_radians()))
}

// ---------------------------------------------------------------------------------------
// Feet.
// ---------------------------------------------------------------------------------------

/// **FootAvoidance**: the foot target `ideal` moved sideways (relative to the movement
/// direction) so the left foot stays at least `margin` to the left of the other foot and
/// the right foot at least `margin` to its right. Rig space, cm; z is kept.
///
/// - `ideal`: the foot's ideal target location, cm.
/// - `other_foot`: the opposite foot's saved platform location, cm.
/// - `movement_offset_deg`: the movement angle offset, degrees about +Z.
/// - `is_left`: true for the left foot.
/// - `margin` (15): the minimum sideways gap between the feet, cm.
///
/// ```text
/// Mv   = Rz(offset)·(0,1,0) = (−sin θ, cos θ, 0)     movement direction
/// Side = Rz(90°)·Mv         = (−cos θ, −sin θ, 0)    the character's RIGHT of Mv
/// o    = other·Side
/// left:  lateral = min(ideal·Side, o − margin)
/// right: lateral = max(ideal·Side, o + margin)
/// out  = Side·lateral + Mv·(ideal·Mv),  out.z = ideal.z
/// ```
///
/// Fallbacks: a non-finite `ideal` gives the rig origin (0,0,0); a non-finite
/// `other_foot` leaves `ideal` unchanged (nothing to avoid); a non-finite offset counts
/// as 0, a non-finite margin as 0.
#[must_use]
pub fn foot_avoidance(
    ideal: Vec3,
    other_foot: Vec3,
    movement_offset_deg: f32,
    is_left: bool,
    margin: f32,
) -> Vec3 {
    if !ideal.is_finite() {
        return Vec3::ZERO;
    }
    if !other_foot.is_finite() {
        return ideal;
    }
    let theta = finite_or(movement_offset_deg, 0.0).to_radians();
    let margin = finite_or(margin, 0.0);
    let mv = Vec3::new(-theta.sin(), theta.cos(), 0.0);
    // Which way does Side point? Rz(90°) maps (x, y) to (−y, x), so
    // Side = (−cos θ, −sin θ, 0); at θ = 0 that is (−1, 0, 0) = −X, the character's RIGHT
    // (+X is left). In general Side = Z × Mv, the right-hand side of the movement
    // direction (Mv × Z would be its left).
    // So s(p) = p·Side measures "how far to the right". The left foot must be at least
    // `margin` further LEFT (smaller s) than the other foot: s_left ≤ o − margin, i.e.
    // s_left = min(s_ideal, o − margin). The right foot must be at least `margin` further
    // RIGHT: s_right ≥ o + margin, i.e. max(s_ideal, o + margin). This is exactly the
    // spec's (and the seed's) min/max; with a left-pointing Side the same min/max would
    // push the feet into each other instead.
    let side = Vec3::new(-theta.cos(), -theta.sin(), 0.0);
    let o = other_foot.dot(side);
    let s = ideal.dot(side);
    let lateral = if is_left {
        s.min(o - margin)
    } else {
        s.max(o + margin)
    };
    let planar = side * lateral + mv * ideal.dot(mv);
    let out = Vec3::new(planar.x, planar.y, ideal.z);
    finite_v_or(out, ideal)
}

/// **CalculateKneeVector**: the knee pole direction for the leg IK, rig space:
/// `slerp(platform_rotation, movement_rotation, blend) · (default_knee · scale)`.
///
/// - `platform_rotation`: the foot platform's rotation (rig space).
/// - `movement_rotation`: the movement angle offset as a yaw quaternion (MAO).
/// - `default_knee`: the leg's knee vector from the initial pose, cm
///   (`calf − midpoint(thigh, foot)`), rig space.
/// - `blend` (0.25): how far from the platform rotation towards MAO, clamped to [0, 1]
///   (knees follow the movement direction a little).
/// - `scale` (20): dimensionless multiplier on `default_knee` (the spec's "·20"; the seed's
///   IK takes the pole as a direction, so only the direction matters there).
///
/// Rotations are normalised (zero or non-finite → identity); the slerp takes the short
/// way. A zero or non-finite `default_knee`, or a non-finite `scale`, gives the zero
/// vector (no pole preference); a NaN `blend` counts as 0.
#[must_use]
pub fn knee_vector(
    platform_rotation: Quat,
    movement_rotation: Quat,
    default_knee: Vec3,
    blend: f32,
    scale: f32,
) -> Vec3 {
    let knee = finite_v_or(default_knee, Vec3::ZERO) * finite_or(scale, 0.0);
    if knee == Vec3::ZERO || !knee.is_finite() {
        return Vec3::ZERO;
    }
    let rotation = slerp(
        unit_q(platform_rotation),
        unit_q(movement_rotation),
        clamp01(blend),
    );
    finite_v_or(rotation * knee, Vec3::ZERO)
}

/// **SetFootTransforms** pivots: the ball, toe-tip and heel points the foot rolls about,
/// rig space, cm. Returns `(ball_pivot, tip, heel)`.
///
/// - `foot`: the foot (ankle) bone's rig-space location, cm.
/// - `ball`: the ball bone's rig-space location, cm.
/// - `tip_length` (5.8): distance from the ball pivot forward to the tip pivot, cm.
/// - `ball_drop` (2.5): how far below the ball bone the ball pivot is, cm.
/// - `heel_drop` (9): how far below the ankle the heel pivot is, cm.
/// - `heel_back` (0.8): how far behind the ankle the heel pivot is, as a fraction of
///   `tip_length` (dimensionless; 0.8 × 5.8 = 4.64 cm).
///
/// ```text
/// fwd        = tip_length · unit((ball − foot).xy, 0)
/// ball_pivot = (ball.x, ball.y, ball.z − ball_drop)
/// tip        = ball_pivot + fwd
/// heel       = (foot.x, foot.y, foot.z − heel_drop) − heel_back · fwd
/// ```
///
/// The tip is offset from the *ball pivot* (on the sole), as the seed's graph does
/// ("Ball的世界坐标" there is the ball pivot point), so tip and ball pivot are level.
///
/// Fallbacks: a ball straight above or below the ankle (zero XY offset) has no forward
/// direction: `fwd` = 0, the tip sits on the ball pivot and the heel straight below the
/// ankle. A non-finite `ball` is replaced by `foot` and vice versa (both non-finite →
/// the origin); non-finite tunables count as 0; an overflowing output falls back to the
/// bone it hangs from.
#[must_use]
pub fn foot_pivots(
    foot: Vec3,
    ball: Vec3,
    tip_length: f32,
    ball_drop: f32,
    heel_drop: f32,
    heel_back: f32,
) -> (Vec3, Vec3, Vec3) {
    let foot_ok = finite_v_or(foot, finite_v_or(ball, Vec3::ZERO));
    let ball = finite_v_or(ball, foot_ok);
    let foot = foot_ok;
    let along = ball - foot;
    let fwd = unit_v(Vec3::new(along.x, along.y, 0.0)) * finite_or(tip_length, 0.0);
    let fwd = finite_v_or(fwd, Vec3::ZERO);
    let ball_pivot = finite_v_or(
        Vec3::new(ball.x, ball.y, ball.z - finite_or(ball_drop, 0.0)),
        ball,
    );
    let tip = finite_v_or(ball_pivot + fwd, ball_pivot);
    let heel = finite_v_or(
        Vec3::new(foot.x, foot.y, foot.z - finite_or(heel_drop, 0.0))
            - fwd * finite_or(heel_back, 0.0),
        foot,
    );
    (ball_pivot, tip, heel)
}

// ---------------------------------------------------------------------------------------
// Cycle.
// ---------------------------------------------------------------------------------------

/// **CycleStep**: advances the master cycle and gives one foot's cycle. Returns
/// `(new_master, per_foot)`, both in cycles [0, 1).
///
/// - `master`: MasterCyclePercent, cycles.
/// - `dt`: frame time, seconds.
/// - `cycle_length`: CycleLength, seconds per full cycle (two steps).
/// - `foot_offset`: this foot's phase offset, cycles (0 for the left foot, 0.5 for the right).
/// - `moving`: whether the character is moving; when false the cycle does not advance (no
///   stepping in place).
///
/// ```text
/// new_master = fract(master + dt / cycle_length)   (moving; else fract(master))
/// per_foot   = fract(new_master + foot_offset)
/// ```
///
/// Fallbacks: `cycle_length` ≤ 0 or non-finite, or `dt` < 0 or non-finite: no advance. A
/// non-finite `master` restarts at 0; a non-finite `foot_offset` counts as 0.
#[must_use]
pub fn cycle_step(
    master: f32,
    dt: f32,
    cycle_length: f32,
    foot_offset: f32,
    moving: bool,
) -> (f32, f32) {
    let master = fract(finite_or(master, 0.0));
    let advance = if moving && cycle_length > 0.0 && dt >= 0.0 {
        finite_or(dt / cycle_length, 0.0)
    } else {
        0.0
    };
    let new_master = finite_or(fract(master + advance), master);
    let per_foot = finite_or(fract(new_master + finite_or(foot_offset, 0.0)), new_master);
    (new_master, per_foot)
}

/// **CalculateCycle**: the cycle length and the swing share of it. Returns
/// `(cycle_length, swing_percent)`: seconds per full cycle, and the fraction [0, 1] of the
/// cycle a foot spends swinging.
///
/// - `speed`: the character's speed |v|, cm/s (its absolute value is used).
/// - `swing_time` (0.5): SwingTime, seconds.
/// - `stride` (70): MaxFootStrideLength, cm (the graph may feed
///   `remap(|v|, 200..300 → 65..45)` instead).
/// - `min_speed` (100): the speed floor, cm/s, so that slow walking still cycles.
///
/// ```text
/// cycle_length  = swing_time + stride / max(|speed|, min_speed)
/// swing_percent = swing_time / cycle_length
/// ```
///
/// Fallbacks: a non-finite speed counts as 0. If the divisor `max(|speed|, min_speed)` is
/// not positive, or the result is not finite or not positive, the result is `(0, 0)`:
/// "no cycle" ([`cycle_step`] does not advance for a cycle length ≤ 0). The swing share
/// is clamped to [0, 1].
#[must_use]
pub fn cycle_length(speed: f32, swing_time: f32, stride: f32, min_speed: f32) -> (f32, f32) {
    let divisor = finite_or(speed, 0.0).abs().max(min_speed);
    if !positive(divisor) {
        return (0.0, 0.0);
    }
    let length = swing_time + stride / divisor;
    if !(length.is_finite() && length > 0.0) {
        return (0.0, 0.0);
    }
    (length, clamp01(finite_or(div_f(swing_time, length), 0.0)))
}

// ---------------------------------------------------------------------------------------
// Arms and body.
// ---------------------------------------------------------------------------------------

/// **GetArmMotionEffectorRotationAmount**: the arm swing pitch, in **degrees about rig +X**
/// (positive swings a hanging hand forward: `Rx(+θ)·(0,0,−1) = (0, sin θ, −cos θ)`).
///
/// - `per_foot_cycle`: the cycle of the foot paired with this hand, cycles [0, 1).
/// - `velocity`: rig-space velocity (the slower-smoothed copy), cm/s.
/// - `movement_rotation`: the movement angle offset as a yaw quaternion (MAO).
/// - `phase_offset` (0.15): phase lead of the swing, cycles.
/// - `direction_scale` (0.4): how much of MAO the swing direction takes (`quat_scale`).
/// - `direction_min` (−0.5), `direction_max` (1.0): clamp of the direction factor
///   (backwards: smaller, reversed swing, so never same-arm-same-leg).
/// - `speed_max` (300): speed at which the swing and the base reach their maxima, cm/s.
/// - `swing_max_deg` (50): swing amplitude at `speed_max`, degrees.
/// - `base_max_deg` (15): forward offset of the swing axis at `speed_max`, degrees.
/// - `lateral_scale` (0.4): weight of the forward velocity component in the lateral
///   factor, s/cm (it multiplies the raw velocity in cm/s, as in the seed).
/// - `lateral_min` (0.4), `lateral_max` (1.0): clamp of the lateral factor.
///
/// ```text
/// phase     = sin(2π · fract(per_foot_cycle + phase_offset))
/// direction = clamp(v̂ · (quat_scale(MAO, direction_scale)·(0,1,0)), direction_min, direction_max)
/// amplitude = remap(|v|, 0..speed_max → 0..swing_max_deg)
/// lateral   = clamp(|v · (0, lateral_scale, 0)|, lateral_min, lateral_max)
/// base      = remap(|v|, 0..speed_max → 0..base_max_deg)
/// pitch     = phase · direction · amplitude · lateral + base
/// ```
///
/// Remaps are clamped. Note that `lateral` uses the velocity in cm/s, not v̂: with the
/// defaults it is 1 once |v.y| ≥ 2.5 cm/s and drops to 0.4 only for (nearly) pure
/// sideways motion. (With v̂ it would be the constant 0.4.)
///
/// Fallbacks: zero velocity gives 0 (v̂ = 0, base 0). Any non-finite input, parameter or
/// result gives 0 (the arm hangs at rest).
#[must_use]
pub fn arm_swing_pitch(
    per_foot_cycle: f32,
    velocity: Vec3,
    movement_rotation: Quat,
    phase_offset: f32,
    direction_scale: f32,
    direction_min: f32,
    direction_max: f32,
    speed_max: f32,
    swing_max_deg: f32,
    base_max_deg: f32,
    lateral_scale: f32,
    lateral_min: f32,
    lateral_max: f32,
) -> f32 {
    if !velocity.is_finite() {
        return 0.0;
    }
    let speed = velocity.length();
    let phase = (core::f32::consts::TAU * fract(per_foot_cycle + phase_offset)).sin();
    let swing_forward = quat_scale(movement_rotation, direction_scale) * Vec3::Y;
    let direction = clamp_f(
        unit_v(velocity).dot(swing_forward),
        direction_min,
        direction_max,
    );
    let amplitude = remap(speed, 0.0, speed_max, 0.0, swing_max_deg, true);
    let lateral = clamp_f(
        velocity.dot(Vec3::new(0.0, lateral_scale, 0.0)).abs(),
        lateral_min,
        lateral_max,
    );
    let base = remap(speed, 0.0, speed_max, 0.0, base_max_deg, true);
    finite_or(phase * direction * amplitude * lateral + base, 0.0)
}

/// **GetClavicleOffset**: the clavicle's vertical bob, cm along rig +Z:
/// `sin(4π·(master_cycle − 0.25)) · remap(|speed|, 0..speed_max → 0..amplitude_max)`
/// (two bobs per cycle, one per step; the −0.25 puts the left shoulder down as the left
/// foot lands).
///
/// - `master_cycle`: MasterCyclePercent, cycles.
/// - `speed`: the character's speed |v|, cm/s (its absolute value is used).
/// - `speed_max` (300): speed at which the bob reaches full amplitude, cm/s.
/// - `amplitude_max` (1.5): bob amplitude at `speed_max`, cm.
///
/// The remap is clamped. Any non-finite input or result gives 0.
#[must_use]
pub fn clavicle_offset(master_cycle: f32, speed: f32, speed_max: f32, amplitude_max: f32) -> f32 {
    let wave = (2.0 * core::f32::consts::TAU * (master_cycle - 0.25)).sin();
    let amplitude = remap(speed.abs(), 0.0, speed_max, 0.0, amplitude_max, true);
    finite_or(wave * amplitude, 0.0)
}

/// **PelvisLean**: forward lean of the pelvis with speed. Returns
/// `(pitch_deg, forward_shift_cm)`: a pitch in **degrees about rig +X** (negative leans
/// forward: `Rx(−15°)` tips the up axis towards +Y) and a shift in **cm along rig +Y**.
///
/// - `velocity`: rig-space velocity (the slower-smoothed copy), cm/s.
/// - `speed_max` (300): speed of full lean, cm/s.
/// - `pitch_max_deg` (−15): pitch at `speed_max` moving straight forward, degrees.
/// - `shift_max` (10): forward shift at `speed_max` moving straight forward, cm.
///
/// ```text
/// f     = v̂ · (0,1,0)                     (3D unit velocity)
/// pitch = remap(|v|, 0..speed_max → 0..pitch_max_deg) · f
/// shift = remap(|v|, 0..speed_max → 0..shift_max) · f
/// ```
///
/// Moving backwards leans back; sideways does not lean. Zero velocity gives (0, 0); any
/// non-finite input or result gives 0 for that output.
#[must_use]
pub fn pelvis_lean(
    velocity: Vec3,
    speed_max: f32,
    pitch_max_deg: f32,
    shift_max: f32,
) -> (f32, f32) {
    if !velocity.is_finite() {
        return (0.0, 0.0);
    }
    let speed = velocity.length();
    let f = unit_v(velocity).y;
    let pitch = remap(speed, 0.0, speed_max, 0.0, pitch_max_deg, true) * f;
    let shift = remap(speed, 0.0, speed_max, 0.0, shift_max, true) * f;
    (finite_or(pitch, 0.0), finite_or(shift, 0.0))
}

/// **PelvisSideLean**: the pelvis roll from the feet's height difference, in **degrees
/// about rig +Y** (positive tips the up axis towards +X, the character's left:
/// `Ry(θ)·(0,0,1) = (sin θ, 0, cos θ)`):
/// `remap(height_difference, −range..range → −roll_max_deg..roll_max_deg)`, clamped.
///
/// - `height_difference`: the feet's height difference, cm, in whichever order the graph
///   chooses (e.g. left z − right z).
/// - `range` (60): the difference of full roll, cm (its absolute value is used).
/// - `roll_max_deg` (15): the roll at ±`range`, degrees (the seed's write-up says 7; a
///   negative value flips the direction).
///
/// A zero or non-finite `range`, or any non-finite input, gives 0.
#[must_use]
pub fn pelvis_side_lean(height_difference: f32, range: f32, roll_max_deg: f32) -> f32 {
    let r = range.abs();
    if !positive(r) || !r.is_finite() {
        return 0.0;
    }
    finite_or(
        remap(height_difference, -r, r, -roll_max_deg, roll_max_deg, true),
        0.0,
    )
}

// ---------------------------------------------------------------------------------------
// Standing foot IK (seed 003).
// ---------------------------------------------------------------------------------------

/// Standing foot IK: the foot's vertical offset from its downward trace, cm along rig +Z.
/// A hit gives `half_height − hit_distance` (negative: the ground is below the capsule's
/// foot level, the foot goes down); a miss gives 0 (foot left unchanged).
///
/// - `hit`: whether the trace hit.
/// - `hit_distance`: distance from the trace start (capsule centre height) to the hit, cm.
/// - `half_height`: the capsule's half-height, cm.
///
/// A non-finite input or result gives 0 (as a miss).
#[must_use]
pub fn foot_offset_from_trace(hit: bool, hit_distance: f32, half_height: f32) -> f32 {
    if hit {
        finite_or(half_height - hit_distance, 0.0)
    } else {
        0.0
    }
}

/// Standing foot IK: the foot's tilt from the ground normal `normal` (rig space, any
/// length), as the seed computes it. Returns `(pitch_deg, roll_deg)`, degrees:
///
/// ```text
/// pitch = −atan2(n.x, n.z)
/// roll  =  atan2(n.y, n.z)
/// ```
///
/// The names are the seed's (Unreal, where X is forward). In Strider's axes (X left, Y
/// forward) `pitch` measures the ground's tilt towards ±X, i.e. it is a rotation about the
/// forward **+Y** axis (a sideways tilt), and `roll` the tilt towards ±Y, a rotation about
/// **+X**. Both carry the seed's sign, which is the *negative* of the right-hand rule in
/// Strider: the rotation that aligns the sole with the ground is `Ry(−pitch)·Rx(−roll)`,
/// see [`rotation_from_normal_quat`]. Yaw is untouched (the foot keeps facing forward).
///
/// A zero or non-finite normal gives (0, 0).
#[must_use]
pub fn rotation_from_normal(normal: Vec3) -> (f32, f32) {
    if !normal.is_finite() || normal == Vec3::ZERO {
        return (0.0, 0.0);
    }
    let pitch = -normal.x.atan2(normal.z).to_degrees();
    let roll = normal.y.atan2(normal.z).to_degrees();
    (finite_or(pitch, 0.0), finite_or(roll, 0.0))
}

/// Standing foot IK: the foot tilt of [`rotation_from_normal`] as a rig-space rotation,
/// `Ry(−pitch) · Rx(−roll)` — the Strider Euler triple `(x, y, z) = (−roll, −pitch, 0)`
/// in the default XYZ order.
///
/// It maps +Z onto the normal exactly when the ground tilts along one axis only, and to
/// within second order of the slope otherwise (for a 3° by 2° slope the error is under
/// 0.01°). A zero or non-finite normal gives the identity.
#[must_use]
pub fn rotation_from_normal_quat(normal: Vec3) -> Quat {
    let (pitch, roll) = rotation_from_normal(normal);
    unit_q(quat_from_euler(
        Vec3::new(-roll, -pitch, 0.0),
        EulerOrder::XYZ,
    ))
}

// ---------------------------------------------------------------------------------------
// Damping.
// ---------------------------------------------------------------------------------------

/// Unreal's **FInterpTo**: moves `current` towards `target` by
/// `(target − current) · clamp(dt·speed, 0, 1)`; returns `target` when `speed` ≤ 0 or when
/// the two are within 1e-4 (squared distance < 1e-8, Unreal's `SMALL_NUMBER`).
///
/// - `current`, `target`: the value (any unit).
/// - `dt`: frame time, seconds.
/// - `speed`: blend rate, 1/s (the seed uses 20; ALS 10–30).
///
/// This is **not** frame-rate independent: two steps of dt/2 move
/// `1 − (1 − k·dt/2)²` of the way instead of `k·dt`, and any dt ≥ 1/speed jumps to the
/// target. Prefer [`lerp_exponential`]; this exists to reproduce seeds that use it.
///
/// Fallbacks: a NaN speed counts as ≤ 0 (snap); NaN or negative `dt` means no motion; a
/// non-finite `current` gives the target (0 if that is not finite either); a non-finite
/// `target` keeps `current`.
#[must_use]
pub fn finterp_to(current: f32, target: f32, dt: f32, speed: f32) -> f32 {
    if !target.is_finite() {
        return finite_or(current, 0.0);
    }
    if !current.is_finite() || !positive(speed) {
        return target;
    }
    let dist = target - current;
    if dist * dist < 1e-8 {
        return target;
    }
    let alpha = unreal_alpha(speed, dt);
    if alpha >= 1.0 {
        return target;
    }
    finite_or(current + dist * alpha, target)
}

/// Unreal's **VInterpTo**: [`finterp_to`] for vectors (cm or any unit), snapping to the
/// target when the squared distance is below 1e-4 (Unreal's `KINDA_SMALL_NUMBER`). Not
/// frame-rate independent. Same fallbacks as [`finterp_to`], per vector (a vector with any
/// non-finite component counts as non-finite).
#[must_use]
pub fn vinterp_to(current: Vec3, target: Vec3, dt: f32, speed: f32) -> Vec3 {
    if !target.is_finite() {
        return finite_v_or(current, Vec3::ZERO);
    }
    if !current.is_finite() || !positive(speed) {
        return target;
    }
    let dist = target - current;
    if dist.length_squared() < 1e-4 {
        return target;
    }
    let alpha = unreal_alpha(speed, dt);
    if alpha >= 1.0 {
        return target;
    }
    finite_v_or(current + dist * alpha, target)
}

/// Unreal's **QInterpTo**: shortest-path slerp from `current` towards `target` by
/// `clamp(dt·speed, 0, 1)`; `target` when `speed` ≤ 0 or the two are equal within 1e-4 per
/// component (either sign). Not frame-rate independent.
///
/// Rotations are normalised (zero → identity). A non-finite `current` gives the target; a
/// non-finite `target` keeps `current`; NaN speed snaps; NaN or negative `dt` means no motion.
#[must_use]
pub fn qinterp_to(current: Quat, target: Quat, dt: f32, speed: f32) -> Quat {
    if !target.is_finite() {
        return unit_q(current);
    }
    let target = unit_q(target);
    if !current.is_finite() || !positive(speed) {
        return target;
    }
    let current = unit_q(current);
    if max_abs_diff(current, target) <= 1e-4 || max_abs_diff(current, -target) <= 1e-4 {
        return target;
    }
    let alpha = unreal_alpha(speed, dt);
    if alpha >= 1.0 {
        return target;
    }
    slerp(current, target, alpha)
}

/// Largest absolute component difference of two quaternions (Unreal's `FQuat::Equals`).
#[inline]
fn max_abs_diff(a: Quat, b: Quat) -> f32 {
    (a.x - b.x)
        .abs()
        .max((a.y - b.y).abs())
        .max((a.z - b.z).abs())
        .max((a.w - b.w).abs())
}

/// **Exponential lerp** (the frame-rate independent VectorLerp), scalar:
/// `current + (target − current) · (1 − e^(−speed·dt))`.
///
/// - `current`, `target`: the value (any unit).
/// - `dt`: frame time, seconds.
/// - `speed`: decay rate `k`, 1/s: the remaining distance shrinks by `e^(−k)` per second,
///   (it halves every `ln 2 / k` s).
///
/// Exactly frame-rate independent: n steps of dt/n multiply the remaining distance by
/// `(e^(−k·dt/n))^n = e^(−k·dt)`, the same as one step of dt.
///
/// Note the rate convention: `speed` ≤ 0 means **no motion** (unlike Unreal's FInterpTo,
/// where 0 snaps). Fallbacks: NaN speed or dt, or dt ≤ 0: no motion; infinite `speed·dt`
/// reaches the target; a non-finite `current` gives the target (0 if that is not finite
/// either); a non-finite `target` keeps `current`.
#[must_use]
pub fn lerp_exponential(current: f32, target: f32, dt: f32, speed: f32) -> f32 {
    lerp_by_weight(current, target, exp_alpha(speed, dt))
}

/// [`lerp_exponential`] with its weight `alpha = exp_alpha(speed, dt)` already computed
/// (a crowd whose characters share `speed` and `dt` computes it once).
#[inline]
#[must_use]
pub fn lerp_by_weight(current: f32, target: f32, alpha: f32) -> f32 {
    // Every case computed, then chosen (no early return), so that a loop of these over a
    // crowd's lanes vectorises: a non-finite target keeps `current` (0 if that is not
    // finite either); a non-finite current, or a weight of 1 or more, gives `target`;
    // otherwise the lerp, or `target` should the lerp overflow.
    let lerped = finite_or(current + (target - current) * alpha, target);
    let moved = if alpha >= 1.0 || !current.is_finite() {
        target
    } else {
        lerped
    };
    if target.is_finite() {
        moved
    } else {
        finite_or(current, 0.0)
    }
}

/// [`lerp_exponential`] for vectors (cm or any unit), same weight `1 − e^(−speed·dt)` and
/// same fallbacks per vector. Exactly frame-rate independent.
#[must_use]
pub fn lerp_exponential_v(current: Vec3, target: Vec3, dt: f32, speed: f32) -> Vec3 {
    lerp_by_weight_v(current, target, exp_alpha(speed, dt))
}

/// [`lerp_exponential_v`] with its weight `alpha = exp_alpha(speed, dt)` already computed
/// (a crowd whose characters share `speed` and `dt` computes it once).
#[inline]
#[must_use]
pub fn lerp_by_weight_v(current: Vec3, target: Vec3, alpha: f32) -> Vec3 {
    if !target.is_finite() {
        return finite_v_or(current, Vec3::ZERO);
    }
    if !current.is_finite() || alpha >= 1.0 {
        return target;
    }
    finite_v_or(current + (target - current) * alpha, target)
}

/// [`lerp_exponential`] for rotations: shortest-path slerp by `1 − e^(−speed·dt)`.
/// Exactly frame-rate independent (repeated slerps towards a fixed target stay on one
/// great arc and shrink the remaining angle by `e^(−speed·dt)`). Rotations are normalised
/// (zero → identity); same fallbacks as [`lerp_exponential`].
#[must_use]
pub fn lerp_exponential_q(current: Quat, target: Quat, dt: f32, speed: f32) -> Quat {
    slerp_by_weight(current, target, exp_alpha(speed, dt))
}

/// [`lerp_exponential_q`] with its weight `alpha = exp_alpha(speed, dt)` already computed.
#[inline]
#[must_use]
pub fn slerp_by_weight(current: Quat, target: Quat, alpha: f32) -> Quat {
    if !target.is_finite() {
        return unit_q(current);
    }
    let target = unit_q(target);
    if !current.is_finite() {
        return target;
    }
    if alpha >= 1.0 {
        return target;
    }
    slerp(unit_q(current), target, alpha)
}

/// Exponential lerp with a speed limit (the seed's first VectorLerp, combined): the step
/// `(target − current) · (1 − e^(−speed·dt))` with its length clamped to
/// `max_per_second · dt`.
///
/// - `current`, `target`: the vector (cm or any unit).
/// - `dt`: frame time, seconds.
/// - `speed`: decay rate, 1/s.
/// - `max_per_second`: the largest distance covered per second (cm/s); infinite = no
///   limit, 0 (or negative, or NaN) = frozen.
///
/// Frame-rate independent while the limit is inactive (exponential) and while it is
/// active for the whole interval (constant speed); only the switch between the two
/// depends slightly on the step. Same fallbacks as [`lerp_exponential_v`].
#[must_use]
pub fn lerp_max_step(
    current: Vec3,
    target: Vec3,
    dt: f32,
    speed: f32,
    max_per_second: f32,
) -> Vec3 {
    if !target.is_finite() {
        return finite_v_or(current, Vec3::ZERO);
    }
    if !current.is_finite() {
        return target;
    }
    let alpha = exp_alpha(speed, dt);
    let max_step = if max_per_second > 0.0 && dt > 0.0 {
        max_per_second * dt
    } else {
        0.0
    };
    let full = target - current;
    let step = if alpha >= 1.0 { full } else { full * alpha };
    let step = if step.length() > max_step {
        clamp_length(step, 0.0, max_step)
    } else if alpha >= 1.0 {
        return target;
    } else {
        step
    };
    finite_v_or(current + step, current)
}

/// Holden's critically damped spring decay constant `y = (4·ln 2 / half_life) / 2`.
#[inline]
fn spring_y(half_life: f32) -> f32 {
    2.0 * core::f32::consts::LN_2 / half_life
}

// Critically damped spring ("spring-it-on", Daniel Holden), derived:
//
// x'' = −k·(x − g) − c·x' with critical damping c² = 4k. Write c = 2y, k = y²: the
// characteristic polynomial (r + y)² has the double root −y, so
//     x(t) = g + (A + B·t)·e^(−y·t).
// At t = 0: A = x0 − g =: j0, and x'(0) = B − y·A = v0, so B = v0 + y·j0 =: j1. Then
//     x(t) = g + (j0 + j1·t)·e^(−y·t)
//     v(t) = e^(−y·t)·(j1 − y·(j0 + j1·t)) = e^(−y·t)·(v0 − y·j1·t).
// This is the exact solution of an autonomous ODE, so stepping t1 then t2 equals one step
// of t1 + t2 for any split: the update is exact for any dt (up to rounding).
// Holden parameterises by a half-life h: damping c = 4·ln2 / h, so y = c/2 = 2·ln2 / h and
// the envelope e^(−y·t) = 2^(−2t/h) halves every h/2. From rest (v0 = 0),
// x − g = j0·(1 + y·t)·e^(−y·t); (1 + u)·e^(−u) falls monotonically from 1 to 0 for u > 0,
// so the spring approaches the target without overshoot; after t = h the remaining
// fraction is (1 + 2·ln2)/4 ≈ 0.597.

/// **Critically damped spring**, scalar: moves `value` with `velocity` towards `target`
/// for `dt` seconds, exactly (closed form, any dt). Returns `(value, velocity)`.
///
/// - `value`, `target`: the value (any unit); `velocity`: its rate, unit/s.
/// - `half_life`: stiffness as Holden's half-life, seconds (decay `y = 2·ln 2 / half_life`).
/// - `dt`: time step, seconds.
///
/// ```text
/// j0 = value − target;  j1 = velocity + j0·y;  e = e^(−y·dt)
/// value'    = target + e·(j0 + j1·dt)
/// velocity' = e·(velocity − j1·y·dt)
/// ```
///
/// From rest it approaches the target without overshoot. Fallbacks: `dt` ≤ 0 or NaN: no
/// change; `half_life` ≤ 0 or NaN: snap to `(target, 0)`; a non-finite `value` snaps to
/// `(target, 0)`; a non-finite `velocity` counts as 0; a non-finite `target` counts as the
/// current value (the spring brakes to a stop); a non-finite result gives `(target, 0)`.
#[must_use]
pub fn spring_damper(
    value: f32,
    velocity: f32,
    target: f32,
    half_life: f32,
    dt: f32,
) -> (f32, f32) {
    let target = if target.is_finite() {
        target
    } else {
        finite_or(value, 0.0)
    };
    if !value.is_finite() || !positive(half_life) {
        return (target, 0.0);
    }
    let velocity = finite_or(velocity, 0.0);
    if !positive(dt) {
        return (value, velocity);
    }
    let y = spring_y(half_life);
    let j0 = value - target;
    let j1 = velocity + j0 * y;
    let e = (-y * dt).exp();
    let new_value = target + e * (j0 + j1 * dt);
    let new_velocity = e * (velocity - j1 * y * dt);
    if new_value.is_finite() && new_velocity.is_finite() {
        (new_value, new_velocity)
    } else {
        (target, 0.0)
    }
}

/// [`spring_damper`] for vectors (cm and cm/s, or any unit): the same exact critically
/// damped spring per component, one decay `y` for all. Returns `(value, velocity)`. Same
/// fallbacks per vector.
#[must_use]
pub fn spring_damper_v(
    value: Vec3,
    velocity: Vec3,
    target: Vec3,
    half_life: f32,
    dt: f32,
) -> (Vec3, Vec3) {
    let target = if target.is_finite() {
        target
    } else {
        finite_v_or(value, Vec3::ZERO)
    };
    if !value.is_finite() || !positive(half_life) {
        return (target, Vec3::ZERO);
    }
    let velocity = finite_v_or(velocity, Vec3::ZERO);
    if !positive(dt) {
        return (value, velocity);
    }
    let y = spring_y(half_life);
    let j0 = value - target;
    let j1 = velocity + j0 * y;
    let e = (-y * dt).exp();
    let new_value = target + (j0 + j1 * dt) * e;
    let new_velocity = (velocity - j1 * (y * dt)) * e;
    if new_value.is_finite() && new_velocity.is_finite() {
        (new_value, new_velocity)
    } else {
        (target, Vec3::ZERO)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f32::consts::{FRAC_1_SQRT_2, LN_2};

    fn near(a: f32, b: f32, tol: f32) -> bool {
        (a - b).abs() <= tol
    }

    #[track_caller]
    fn assert_near(a: f32, b: f32, tol: f32) {
        assert!(near(a, b, tol), "{a} != {b} (tolerance {tol})");
    }

    #[track_caller]
    fn assert_vnear(a: Vec3, b: Vec3, tol: f32) {
        assert!((a - b).length() <= tol, "{a} != {b} (tolerance {tol})");
    }

    #[track_caller]
    fn assert_qnear(a: Quat, b: Quat, tol: f32) {
        assert!(a.dot(b).abs() >= 1.0 - tol, "{a} != {b}");
    }

    fn rz(deg: f32) -> Quat {
        Quat::from_rotation_z(deg.to_radians())
    }

    /// The twist yaw of a rotation, for checks.
    fn yaw_of(q: Quat) -> f32 {
        swing_twist_z(q).1
    }

    // --- GetMovementAngleOffset -------------------------------------------------------

    /// The seed's defaults, with a huge dt so the blend reaches the target (1 − e^(−6e6)
    /// is exactly 1 in f32): returns the folded target yaw.
    fn target_of(v: Vec3) -> f32 {
        get_movement_angle_offset(v, 0.0, 0.0, 1e6, 6.0, 0.2, 90.0, 110.0, 0.4)
    }

    #[test]
    fn movement_yaw_by_hand() {
        // Straight forward: the rotation from +Y to +Y is the identity, yaw 0.
        assert_near(target_of(Vec3::new(0.0, 100.0, 0.0)), 0.0, 1e-4);
        // (−100, 100): Rz(+45°) maps +Y to (−sin45, cos45) = (−0.707, 0.707), so yaw 45.
        assert_near(target_of(Vec3::new(-100.0, 100.0, 0.0)), 45.0, 1e-4);
        // (100, 100): forward-left, Rz(−45°): yaw −45.
        assert_near(target_of(Vec3::new(100.0, 100.0, 0.0)), -45.0, 1e-4);
        // (−100, 0): straight right, Rz(+90°)·Y = (−1, 0): yaw 90 (not folded, 90 < 110).
        // The step from 0 is exactly 90: not > 90, so no jump.
        assert_near(target_of(Vec3::new(-100.0, 0.0, 0.0)), 90.0, 1e-4);
        // (0, −100): yaw 180 > 110, folded to 180 − 180 = 0.
        assert_near(target_of(Vec3::new(0.0, -100.0, 0.0)), 0.0, 1e-4);
        // (−100, −100): backward-right, yaw 135 > 110, folded to −45.
        assert_near(target_of(Vec3::new(-100.0, -100.0, 0.0)), -45.0, 1e-4);
        // (100, −100): backward-left, yaw −135 < −110, folded to 45.
        assert_near(target_of(Vec3::new(100.0, -100.0, 0.0)), 45.0, 1e-4);
        // The z component is ignored: only the XY direction counts.
        assert_near(target_of(Vec3::new(-100.0, 100.0, 500.0)), 45.0, 1e-4);
    }

    #[test]
    fn movement_fold_threshold_parameter() {
        // (−100, −20): yaw = atan2(100, −20) = 180 − atan(100/20) = 180 − 78.690 = 101.310.
        // The step from 0 is 101.3 > 90, so start inside the step start (M = 0) to use the
        // normal speed.
        let v = Vec3::new(-100.0, -20.0, 0.0);
        let at = |fold: f32| get_movement_angle_offset(v, 0.0, 0.0, 1e6, 6.0, 0.2, 90.0, fold, 0.4);
        // Fold 110: 101.31 is not folded.
        assert_near(at(110.0), 101.309_93, 1e-3);
        // Fold 100 (the seed's first version): 101.31 − 180 = −78.690.
        assert_near(at(100.0), -78.690_07, 1e-3);
    }

    #[test]
    fn movement_blend_speed_and_dt() {
        let v = Vec3::new(-100.0, 100.0, 0.0); // target 45
        // speed 6, dt 1/60: weight 1 − e^(−0.1) = 0.095163, so 45·0.095163 = 4.28232.
        let one = get_movement_angle_offset(v, 0.0, 0.0, 1.0 / 60.0, 6.0, 0.2, 90.0, 110.0, 0.4);
        assert_near(one, 4.282_32, 1e-3);
        // dt = 1 s: weight 1 − e^(−6) = 0.997521, 45·0.997521 = 44.88845.
        let second = get_movement_angle_offset(v, 0.0, 0.0, 1.0, 6.0, 0.2, 90.0, 110.0, 0.4);
        assert_near(second, 44.888_45, 1e-3);
        // Speed parameter: ln 2 per second halves the distance in 1 s: 22.5.
        let half = get_movement_angle_offset(v, 0.0, 0.0, 1.0, LN_2, 0.2, 90.0, 110.0, 0.4);
        assert_near(half, 22.5, 1e-3);
        // Speed 0: no motion. dt 0: no motion.
        assert_eq!(
            get_movement_angle_offset(v, 10.0, 0.0, 1.0, 0.0, 0.2, 90.0, 110.0, 0.4),
            10.0
        );
        assert_eq!(
            get_movement_angle_offset(v, 10.0, 0.0, 0.0, 6.0, 0.2, 90.0, 110.0, 0.4),
            10.0
        );
        // Frame-rate independent: 60 steps of 1/60 s equal one step of 1 s.
        let mut x = 0.0;
        for _ in 0..60 {
            x = get_movement_angle_offset(v, x, 0.0, 1.0 / 60.0, 6.0, 0.2, 90.0, 110.0, 0.4);
        }
        assert_near(x, second, 1e-3);
    }

    #[test]
    fn movement_jump_gate_and_parameters() {
        // Target −101.31 (velocity (100, −20): yaw = atan2(−100, −20) = −101.31, not
        // folded). From 0 the jump is 101.31 > 90.
        let v = Vec3::new(100.0, -20.0, 0.0);
        let f = |m: f32, jump_speed: f32, threshold: f32, gate: f32| {
            get_movement_angle_offset(v, 0.0, m, 1.0, 6.0, jump_speed, threshold, 110.0, gate)
        };
        // M = 0.3: fract(0.6) = 0.6 ≥ 0.4, not the step start: jump speed 0.2,
        // weight 1 − e^(−0.2) = 0.181269, −101.30993·0.181269 = −18.36432.
        assert_near(f(0.3, 0.2, 90.0, 0.4), -18.364_32, 1e-3);
        // jump_speed parameter: 0 freezes.
        assert_eq!(f(0.3, 0.0, 90.0, 0.4), 0.0);
        // M = 0.1: fract(0.2) = 0.2 < 0.4, the step start: normal speed 6,
        // −101.30993·0.997521 = −101.05878.
        assert_near(f(0.1, 0.2, 90.0, 0.4), -101.058_78, 1e-3);
        // M = 0.8: fract(1.6) = 0.6, not the start (the gate repeats twice per cycle).
        assert_near(f(0.8, 0.2, 90.0, 0.4), -18.364_32, 1e-3);
        // jump_threshold parameter: 120 makes 101° an ordinary change.
        assert_near(f(0.3, 0.2, 120.0, 0.4), -101.058_78, 1e-3);
        // step_start_gate parameter: 0.7 makes fract(0.6) = 0.6 the step start.
        assert_near(f(0.3, 0.2, 90.0, 0.7), -101.058_78, 1e-3);
        // NaN master cycle: not the step start, so the jump is slow.
        assert_near(f(f32::NAN, 0.2, 90.0, 0.4), -18.364_32, 1e-3);
    }

    #[test]
    fn movement_wraps_the_shortest_way() {
        // Without folding (fold 180), current 170 and target −170 (velocity
        // Rz(−170°)·Y = (sin170, cos170) = (0.17365, −0.98481)) are 20° apart across
        // ±180, not 340°. Half way (speed ln2, dt 1) is 180.
        let v = Vec3::new(0.173_648, -0.984_808, 0.0);
        let out = get_movement_angle_offset(v, 170.0, 0.0, 1.0, LN_2, 0.2, 90.0, 180.0, 0.4);
        assert_near(wrap_deg(out - 180.0), 0.0, 1e-2);
        // And a current offset outside (−180, 180] is wrapped first: 530 = 170.
        let out = get_movement_angle_offset(v, 530.0, 0.0, 1.0, LN_2, 0.2, 90.0, 180.0, 0.4);
        assert_near(wrap_deg(out - 180.0), 0.0, 1e-2);
        // The jump test uses the shortest difference too: 20° is not a jump even at M = 0.3.
        let out = get_movement_angle_offset(v, 170.0, 0.3, 1.0, LN_2, 0.0, 90.0, 180.0, 0.4);
        assert_near(wrap_deg(out - 180.0), 0.0, 1e-2);
    }

    #[test]
    fn movement_degenerate_inputs() {
        // Zero velocity: the offset freezes.
        let f = |v: Vec3, cur: f32, dt: f32| {
            get_movement_angle_offset(v, cur, 0.0, dt, 6.0, 0.2, 90.0, 110.0, 0.4)
        };
        assert_eq!(f(Vec3::ZERO, 30.0, 1.0), 30.0);
        // Vertical-only velocity has no XY direction: freeze.
        assert_eq!(f(Vec3::new(0.0, 0.0, -500.0), 30.0, 1.0), 30.0);
        // NaN or infinite velocity: freeze.
        assert_eq!(f(Vec3::new(f32::NAN, 1.0, 0.0), 30.0, 1.0), 30.0);
        assert_eq!(f(Vec3::new(f32::INFINITY, 1.0, 0.0), 30.0, 1.0), 30.0);
        // NaN current: counts as 0, then blends towards the target 45 (dt 1 s: 44.888).
        assert_near(f(Vec3::new(-1.0, 1.0, 0.0), f32::NAN, 1.0), 44.888_45, 1e-3);
        // NaN dt: no change.
        assert_eq!(f(Vec3::new(-1.0, 1.0, 0.0), 30.0, f32::NAN), 30.0);
        // Antiparallel to +Y: yaw ±180, folded to 0 either way.
        assert_near(f(Vec3::new(-0.0, -1.0, 0.0), 0.0, 1e6), 0.0, 1e-4);
    }

    // --- CalculatePerFootRotationFactor ----------------------------------------------

    #[test]
    fn per_foot_rotation_factor_cases() {
        assert_eq!(per_foot_rotation_factor(10.0, 0.5, 0.9), 0.5);
        assert_eq!(per_foot_rotation_factor(-10.0, 0.5, 0.9), 0.9);
        // 0 is not > 0.
        assert_eq!(per_foot_rotation_factor(0.0, 0.5, 0.9), 0.9);
        // Parameters.
        assert_eq!(per_foot_rotation_factor(10.0, 0.2, 0.7), 0.2);
        assert_eq!(per_foot_rotation_factor(-10.0, 0.2, 0.7), 0.7);
        // NaN yaw: not > 0. NaN factor: 0.
        assert_eq!(per_foot_rotation_factor(f32::NAN, 0.5, 0.9), 0.9);
        assert_eq!(per_foot_rotation_factor(1.0, f32::NAN, 0.9), 0.0);
    }

    // --- LimitRotationAroundZ --------------------------------------------------------

    #[test]
    fn limit_rotation_pure_yaw() {
        // 40° is 15° beyond the ±25° window around 0: clamped to 25.
        assert_qnear(limit_rotation_around_z(rz(40.0), 0.0, 25.0), rz(25.0), 1e-6);
        assert_qnear(
            limit_rotation_around_z(rz(-40.0), 0.0, 25.0),
            rz(-25.0),
            1e-6,
        );
        // Inside the window: unchanged.
        assert_eq!(limit_rotation_around_z(rz(10.0), 0.0, 25.0), rz(10.0));
        // Center parameter: window 30 ± 25 = [5, 55]; yaw 0 → 5, yaw 70 → 55.
        assert_qnear(limit_rotation_around_z(rz(0.0), 30.0, 25.0), rz(5.0), 1e-6);
        assert_qnear(
            limit_rotation_around_z(rz(70.0), 30.0, 25.0),
            rz(55.0),
            1e-6,
        );
        // Limit parameter: 10 → [−10, 10]; 0 → exactly the center.
        assert_qnear(limit_rotation_around_z(rz(40.0), 0.0, 10.0), rz(10.0), 1e-6);
        assert_qnear(limit_rotation_around_z(rz(40.0), 20.0, 0.0), rz(20.0), 1e-6);
        // Negative or NaN limit counts as 0.
        assert_qnear(
            limit_rotation_around_z(rz(40.0), 20.0, -5.0),
            rz(20.0),
            1e-6,
        );
        assert_qnear(
            limit_rotation_around_z(rz(40.0), 20.0, f32::NAN),
            rz(20.0),
            1e-6,
        );
    }

    #[test]
    fn limit_rotation_wraps_around() {
        // Center 170, yaw −170: offset wrap(−340) = +20, inside ±25: unchanged.
        let q = rz(-170.0);
        assert_qnear(limit_rotation_around_z(q, 170.0, 25.0), q, 1e-6);
        // Center 170, yaw −150: offset +40, clamped to +25 → 195 = −165.
        assert_qnear(
            limit_rotation_around_z(rz(-150.0), 170.0, 25.0),
            rz(-165.0),
            1e-6,
        );
    }

    #[test]
    fn limit_rotation_keeps_the_swing() {
        // q = swing · twist with a 20° tilt about X after a 40° yaw.
        let swing = Quat::from_rotation_x(20f32.to_radians());
        let q = swing * rz(40.0);
        assert_near(yaw_of(q), 40.0, 1e-3);
        let out = limit_rotation_around_z(q, 0.0, 25.0);
        // The result is swing · Rz(25°): same tilt, yaw 25.
        assert_qnear(out, swing * rz(25.0), 1e-6);
        assert_near(yaw_of(out), 25.0, 1e-3);
        // The rotated up axis (a sole normal) is unchanged.
        assert_vnear(out * Vec3::Z, q * Vec3::Z, 1e-5);
    }

    #[test]
    fn limit_rotation_degenerate() {
        // NaN or zero rotation: identity, which is inside the window around 0.
        let nan = Quat::from_xyzw(f32::NAN, 0.0, 0.0, 1.0);
        assert_eq!(limit_rotation_around_z(nan, 0.0, 25.0), Quat::IDENTITY);
        let zero = Quat::from_xyzw(0.0, 0.0, 0.0, 0.0);
        assert_eq!(limit_rotation_around_z(zero, 0.0, 25.0), Quat::IDENTITY);
        // ... and moved into the window around 50 (yaw 0 → 25).
        assert_qnear(limit_rotation_around_z(zero, 50.0, 25.0), rz(25.0), 1e-6);
        // 180° about X: no twist defined, yaw 0; clamped into [25, 75] → 25, tilt kept.
        let flip = Quat::from_xyzw(1.0, 0.0, 0.0, 0.0);
        let out = limit_rotation_around_z(flip, 50.0, 25.0);
        assert!(out.is_finite());
        assert_vnear(out * Vec3::Z, -Vec3::Z, 1e-5);
        // NaN center: unchanged.
        assert_qnear(
            limit_rotation_around_z(rz(40.0), f32::NAN, 25.0),
            rz(40.0),
            1e-6,
        );
    }

    // --- FootAvoidance ---------------------------------------------------------------

    #[test]
    fn avoidance_side_points_right() {
        // Offset 0: Mv = +Y and Side = Rz(90°)·Y = (−1, 0, 0), the character's right.
        // Right foot at x = −10: o = 10. A left foot crossed to x = 0: s = 0,
        // min(0, 10 − 15) = −5, Side·(−5) = (5, 0, 0): pushed to x = 5, 15 cm left of the
        // right foot. Forward part 10 and z 3 kept.
        let out = foot_avoidance(
            Vec3::new(0.0, 10.0, 3.0),
            Vec3::new(-10.0, 0.0, 0.0),
            0.0,
            true,
            15.0,
        );
        assert_vnear(out, Vec3::new(5.0, 10.0, 3.0), 1e-5);
        // A left foot already far left (x = 20, s = −20 < −5): unchanged.
        let ideal = Vec3::new(20.0, 0.0, 1.0);
        let out = foot_avoidance(ideal, Vec3::new(-10.0, 0.0, 0.0), 0.0, true, 15.0);
        assert_vnear(out, ideal, 1e-5);
    }

    #[test]
    fn avoidance_right_foot() {
        // Left foot at x = 0: o = 0. A right foot crossed to x = 2 (s = −2):
        // max(−2, 0 + 15) = 15, Side·15 = (−15, 0, 0).
        let out = foot_avoidance(Vec3::new(2.0, -5.0, 1.0), Vec3::ZERO, 0.0, false, 15.0);
        assert_vnear(out, Vec3::new(-15.0, -5.0, 1.0), 1e-5);
    }

    #[test]
    fn avoidance_rotated_and_margin() {
        // Offset 90: Mv = Rz(90°)·Y = (−1, 0, 0) (moving right), Side = Rz(90°)·Mv =
        // (0, −1, 0): behind, which is the right of someone facing −X.
        // Right foot at (−30, 5): o = −5. Left ideal (−30, 0): s = 0,
        // min(0, −5 − 15) = −20 → Side·(−20) = (0, 20, 0); forward part
        // Mv·(ideal·Mv) = (−1,0,0)·30 = (−30, 0, 0). Result (−30, 20, 0).
        let out = foot_avoidance(
            Vec3::new(-30.0, 0.0, 0.0),
            Vec3::new(-30.0, 5.0, 0.0),
            90.0,
            true,
            15.0,
        );
        assert_vnear(out, Vec3::new(-30.0, 20.0, 0.0), 1e-4);
        // Margin parameter 0: the crossed left foot at x = 0 vs right at x = −10:
        // min(0, 10) = 0, unchanged.
        let ideal = Vec3::new(0.0, 10.0, 3.0);
        let out = foot_avoidance(ideal, Vec3::new(-10.0, 0.0, 0.0), 0.0, true, 0.0);
        assert_vnear(out, ideal, 1e-5);
        // Margin 30: min(0, 10 − 30) = −20 → x = 20.
        let out = foot_avoidance(ideal, Vec3::new(-10.0, 0.0, 0.0), 0.0, true, 30.0);
        assert_vnear(out, Vec3::new(20.0, 10.0, 3.0), 1e-5);
    }

    #[test]
    fn avoidance_keeps_left_left_of_right_in_every_direction() {
        for i in 0..24 {
            let offset = -180.0 + 15.0 * i as f32;
            // Both ideals at the same crossed point: each foot must end on its own side.
            let ideal = Vec3::new(3.0, 4.0, 0.0);
            let right = foot_avoidance(ideal, Vec3::new(-8.0, 1.0, 0.0), offset, false, 15.0);
            let left = foot_avoidance(ideal, right, offset, true, 15.0);
            // The character's left of the movement direction is Mv × Z.
            let theta = offset.to_radians();
            let mv = Vec3::new(-theta.sin(), theta.cos(), 0.0);
            let left_dir = mv.cross(Vec3::Z);
            assert!(
                (left - right).dot(left_dir) >= 15.0 - 1e-3,
                "offset {offset}: left {left}, right {right}"
            );
        }
    }

    #[test]
    fn avoidance_degenerate() {
        let ideal = Vec3::new(1.0, 2.0, 3.0);
        assert_eq!(
            foot_avoidance(Vec3::splat(f32::NAN), Vec3::ZERO, 0.0, true, 15.0),
            Vec3::ZERO
        );
        assert_eq!(
            foot_avoidance(ideal, Vec3::splat(f32::NAN), 0.0, true, 15.0),
            ideal
        );
        // NaN offset counts as 0, NaN margin as 0.
        assert_eq!(
            foot_avoidance(ideal, Vec3::new(-10.0, 0.0, 0.0), f32::NAN, true, 15.0),
            foot_avoidance(ideal, Vec3::new(-10.0, 0.0, 0.0), 0.0, true, 15.0)
        );
        assert_vnear(
            foot_avoidance(ideal, Vec3::new(-10.0, 0.0, 0.0), 0.0, true, f32::NAN),
            ideal,
            1e-5,
        );
    }

    // --- CalculateKneeVector ---------------------------------------------------------

    #[test]
    fn knee_vector_by_hand() {
        // Platform identity, MAO Rz(90°), blend 0.25: slerp gives Rz(22.5°). The default
        // knee (0, 5, 0)·20 = (0, 100, 0) turns to (−100·sin22.5, 100·cos22.5, 0) =
        // (−38.2683, 92.3880, 0).
        let k = knee_vector(
            Quat::IDENTITY,
            rz(90.0),
            Vec3::new(0.0, 5.0, 0.0),
            0.25,
            20.0,
        );
        assert_vnear(k, Vec3::new(-38.268_3, 92.388, 0.0), 1e-3);
        // Blend parameter: 0 → platform only, 1 → MAO only ((−100, 0, 0)).
        let k0 = knee_vector(Quat::IDENTITY, rz(90.0), Vec3::Y * 5.0, 0.0, 20.0);
        assert_vnear(k0, Vec3::new(0.0, 100.0, 0.0), 1e-3);
        let k1 = knee_vector(Quat::IDENTITY, rz(90.0), Vec3::Y * 5.0, 1.0, 20.0);
        assert_vnear(k1, Vec3::new(-100.0, 0.0, 0.0), 1e-3);
        // Out-of-range blend is clamped (2 → 1).
        let k2 = knee_vector(Quat::IDENTITY, rz(90.0), Vec3::Y * 5.0, 2.0, 20.0);
        assert_vnear(k2, k1, 1e-4);
        // Scale parameter: 1 keeps the default length.
        let k3 = knee_vector(Quat::IDENTITY, Quat::IDENTITY, Vec3::Y * 5.0, 0.25, 1.0);
        assert_vnear(k3, Vec3::new(0.0, 5.0, 0.0), 1e-5);
    }

    #[test]
    fn knee_vector_degenerate() {
        assert_eq!(
            knee_vector(Quat::IDENTITY, rz(90.0), Vec3::ZERO, 0.25, 20.0),
            Vec3::ZERO
        );
        assert_eq!(
            knee_vector(Quat::IDENTITY, rz(90.0), Vec3::splat(f32::NAN), 0.25, 20.0),
            Vec3::ZERO
        );
        assert_eq!(
            knee_vector(Quat::IDENTITY, rz(90.0), Vec3::Y, 0.25, f32::NAN),
            Vec3::ZERO
        );
        // NaN blend counts as 0 (platform rotation).
        let k = knee_vector(Quat::IDENTITY, rz(90.0), Vec3::Y, f32::NAN, 20.0);
        assert_vnear(k, Vec3::new(0.0, 20.0, 0.0), 1e-4);
        // Antiparallel rotations (identity vs 180° about Z): finite, length kept.
        let k = knee_vector(Quat::IDENTITY, rz(180.0), Vec3::Y, 0.5, 20.0);
        assert!(k.is_finite());
        assert_near(k.length(), 20.0, 1e-3);
        // A zero quaternion counts as identity.
        let zero = Quat::from_xyzw(0.0, 0.0, 0.0, 0.0);
        assert_vnear(
            knee_vector(zero, zero, Vec3::Y, 0.25, 20.0),
            Vec3::new(0.0, 20.0, 0.0),
            1e-4,
        );
    }

    // --- ArmMotion -------------------------------------------------------------------

    /// The seed's parameters.
    fn arm(cycle: f32, v: Vec3, mao: Quat) -> f32 {
        arm_swing_pitch(
            cycle, v, mao, 0.15, 0.4, -0.5, 1.0, 300.0, 50.0, 15.0, 0.4, 0.4, 1.0,
        )
    }

    #[test]
    fn arm_swing_by_hand() {
        let fwd = Vec3::new(0.0, 300.0, 0.0);
        // Cycle 0.1: sin(2π·fract(0.25)) = 1. v̂·Y = 1 → direction 1; amplitude
        // remap(300) = 50; lateral |300·0.4| = 120 → 1; base 15. 1·1·50·1 + 15 = 65.
        assert_near(arm(0.1, fwd, Quat::IDENTITY), 65.0, 1e-3);
        // Cycle 0.6: sin(2π·0.75) = −1: −50 + 15 = −35.
        assert_near(arm(0.6, fwd, Quat::IDENTITY), -35.0, 1e-3);
        // Cycle 0.85: sin(2π·fract(1.0)) = sin 0 = 0: base only, 15.
        assert_near(arm(0.85, fwd, Quat::IDENTITY), 15.0, 1e-3);
        // Backwards at half speed: direction −1 clamped to −0.5; amplitude 25; lateral
        // |−150·0.4| = 60 → 1; base 7.5. 1·(−0.5)·25·1 + 7.5 = −5.
        assert_near(
            arm(0.1, Vec3::new(0.0, -150.0, 0.0), Quat::IDENTITY),
            -5.0,
            1e-3,
        );
        // Sideways right (v = (−300, 0, 0)) with MAO Rz(90°): quat_scale(MAO, 0.4) = Rz(36°)
        // maps Y to (−sin36, cos36) = (−0.587785, 0.809017); v̂ = (−1, 0, 0), so
        // direction 0.587785; lateral |0| → 0.4. 0.587785·50·0.4 + 15 = 26.75571.
        let side = Vec3::new(-300.0, 0.0, 0.0);
        assert_near(arm(0.1, side, rz(90.0)), 26.755_71, 1e-3);
    }

    #[test]
    fn arm_swing_each_parameter() {
        let fwd = Vec3::new(0.0, 300.0, 0.0);
        let back = Vec3::new(0.0, -150.0, 0.0);
        let side = Vec3::new(-300.0, 0.0, 0.0);
        let id = Quat::IDENTITY;
        let run = |c: f32, v: Vec3, q: Quat, p: [f32; 10]| {
            arm_swing_pitch(
                c, v, q, p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], p[8], p[9],
            )
        };
        let d = [0.15, 0.4, -0.5, 1.0, 300.0, 50.0, 15.0, 0.4, 0.4, 1.0];
        let with = |i: usize, value: f32| {
            let mut p = d;
            p[i] = value;
            p
        };
        // phase_offset 0.35: sin(2π·0.45) = sin(162°) = 0.309017: 50·0.309017 + 15 = 30.45085.
        assert_near(run(0.1, fwd, id, with(0, 0.35)), 30.450_85, 1e-3);
        // direction_scale 1: Rz(90°)·Y = (−1, 0, 0) = v̂: direction 1: 50·0.4 + 15 = 35.
        assert_near(run(0.1, side, rz(90.0), with(1, 1.0)), 35.0, 1e-3);
        // direction_min −1: backwards −1·25 + 7.5 = −17.5.
        assert_near(run(0.1, back, id, with(2, -1.0)), -17.5, 1e-3);
        // direction_max 0.5: forward 0.5·50 + 15 = 40.
        assert_near(run(0.1, fwd, id, with(3, 0.5)), 40.0, 1e-3);
        // speed_max 600: at 300 half: amplitude 25, base 7.5 → 32.5.
        assert_near(run(0.1, fwd, id, with(4, 600.0)), 32.5, 1e-3);
        // swing_max 30: 30 + 15 = 45.
        assert_near(run(0.1, fwd, id, with(5, 30.0)), 45.0, 1e-3);
        // base_max 0: 50.
        assert_near(run(0.1, fwd, id, with(6, 0.0)), 50.0, 1e-3);
        // lateral_scale 0.001: |300·0.001| = 0.3 → clamped to 0.4: 20 + 15 = 35.
        assert_near(run(0.1, fwd, id, with(7, 0.001)), 35.0, 1e-3);
        // lateral_min 0.2 sideways: 0.587785·50·0.2 + 15 = 20.87785.
        assert_near(run(0.1, side, rz(90.0), with(8, 0.2)), 20.877_85, 1e-3);
        // lateral_max 0.5 forward: 25 + 15 = 40.
        assert_near(run(0.1, fwd, id, with(9, 0.5)), 40.0, 1e-3);
    }

    #[test]
    fn arm_swing_degenerate() {
        assert_eq!(arm(0.1, Vec3::ZERO, Quat::IDENTITY), 0.0);
        assert_eq!(arm(0.1, Vec3::splat(f32::NAN), Quat::IDENTITY), 0.0);
        assert_eq!(arm(f32::NAN, Vec3::Y * 300.0, Quat::IDENTITY), 0.0);
        // A NaN MAO counts as identity (quat_scale of a NaN rotation is the identity).
        let nan = Quat::from_xyzw(f32::NAN, 0.0, 0.0, 1.0);
        assert_near(arm(0.1, Vec3::Y * 300.0, nan), 65.0, 1e-3);
    }

    // --- GetClavicleOffset -----------------------------------------------------------

    #[test]
    fn clavicle_offset_by_hand() {
        // M = 0.375: sin(4π·0.125) = sin(π/2) = 1; remap(300) = 1.5.
        assert_near(clavicle_offset(0.375, 300.0, 300.0, 1.5), 1.5, 1e-5);
        // M = 0: sin(−π) = 0.
        assert_near(clavicle_offset(0.0, 300.0, 300.0, 1.5), 0.0, 1e-5);
        // M = 0.125: sin(−π/2) = −1; speed 150 → 0.75: −0.75.
        assert_near(clavicle_offset(0.125, 150.0, 300.0, 1.5), -0.75, 1e-5);
        // speed_max 600: 300 is half: 0.75. amplitude_max 3: 3. Negative speed: |speed|.
        assert_near(clavicle_offset(0.375, 300.0, 600.0, 1.5), 0.75, 1e-5);
        assert_near(clavicle_offset(0.375, 300.0, 300.0, 3.0), 3.0, 1e-5);
        assert_near(clavicle_offset(0.375, -300.0, 300.0, 1.5), 1.5, 1e-5);
        // Faster than speed_max: clamped.
        assert_near(clavicle_offset(0.375, 900.0, 300.0, 1.5), 1.5, 1e-5);
        // Standing still: 0. NaN: 0.
        assert_eq!(clavicle_offset(0.375, 0.0, 300.0, 1.5), 0.0);
        assert_eq!(clavicle_offset(f32::NAN, 300.0, 300.0, 1.5), 0.0);
        assert_eq!(clavicle_offset(0.375, f32::NAN, 300.0, 1.5), 0.0);
    }

    // --- PelvisLean / PelvisSideLean -------------------------------------------------

    #[test]
    fn pelvis_lean_by_hand() {
        // Straight forward at 300: v̂·Y = 1: (−15, 10).
        let (p, s) = pelvis_lean(Vec3::new(0.0, 300.0, 0.0), 300.0, -15.0, 10.0);
        assert_near(p, -15.0, 1e-4);
        assert_near(s, 10.0, 1e-4);
        // Backwards at 150: remaps −7.5 and 5, times −1: (7.5, −5).
        let (p, s) = pelvis_lean(Vec3::new(0.0, -150.0, 0.0), 300.0, -15.0, 10.0);
        assert_near(p, 7.5, 1e-4);
        assert_near(s, -5.0, 1e-4);
        // Sideways: v̂·Y = 0: no lean.
        let (p, s) = pelvis_lean(Vec3::new(300.0, 0.0, 0.0), 300.0, -15.0, 10.0);
        assert_near(p, 0.0, 1e-6);
        assert_near(s, 0.0, 1e-6);
        // Diagonal at |v| = 300: v̂·Y = 0.707107: (−10.6066, 7.07107).
        let v = Vec3::new(-300.0 * FRAC_1_SQRT_2, 300.0 * FRAC_1_SQRT_2, 0.0);
        let (p, s) = pelvis_lean(v, 300.0, -15.0, 10.0);
        assert_near(p, -10.606_6, 1e-3);
        assert_near(s, 7.071_07, 1e-3);
        // Parameters: speed_max 600 → half; pitch_max −5; shift_max 20.
        let fwd = Vec3::new(0.0, 300.0, 0.0);
        assert_near(pelvis_lean(fwd, 600.0, -15.0, 10.0).0, -7.5, 1e-4);
        assert_near(pelvis_lean(fwd, 600.0, -15.0, 10.0).1, 5.0, 1e-4);
        assert_near(pelvis_lean(fwd, 300.0, -5.0, 10.0).0, -5.0, 1e-4);
        assert_near(pelvis_lean(fwd, 300.0, -15.0, 20.0).1, 20.0, 1e-4);
        // Degenerate.
        assert_eq!(pelvis_lean(Vec3::ZERO, 300.0, -15.0, 10.0), (0.0, 0.0));
        assert_eq!(
            pelvis_lean(Vec3::splat(f32::NAN), 300.0, -15.0, 10.0),
            (0.0, 0.0)
        );
        assert_eq!(pelvis_lean(fwd, f32::NAN, -15.0, 10.0), (0.0, 0.0));
    }

    #[test]
    fn pelvis_side_lean_by_hand() {
        // remap(30, −60..60 → −15..15): 30 is 3/4 of the way: −15 + 30·0.75 = 7.5.
        assert_near(pelvis_side_lean(30.0, 60.0, 15.0), 7.5, 1e-5);
        assert_near(pelvis_side_lean(-60.0, 60.0, 15.0), -15.0, 1e-5);
        assert_near(pelvis_side_lean(0.0, 60.0, 15.0), 0.0, 1e-5);
        // Clamped beyond the range.
        assert_near(pelvis_side_lean(100.0, 60.0, 15.0), 15.0, 1e-5);
        // range 120: 30 → 3.75. roll_max 7: 30 → 3.5.
        assert_near(pelvis_side_lean(30.0, 120.0, 15.0), 3.75, 1e-5);
        assert_near(pelvis_side_lean(30.0, 60.0, 7.0), 3.5, 1e-5);
        // Degenerate: zero range, NaN.
        assert_eq!(pelvis_side_lean(30.0, 0.0, 15.0), 0.0);
        assert_eq!(pelvis_side_lean(f32::NAN, 60.0, 15.0), 0.0);
        assert_eq!(pelvis_side_lean(30.0, f32::NAN, 15.0), 0.0);
    }

    // --- SetFootTransforms pivots ----------------------------------------------------

    #[test]
    fn foot_pivots_by_hand() {
        // Ankle 13.5 above the sole, ball 13 cm ahead and 3.5 up: fwd = 5.8·(0,1,0).
        // ball pivot = (0, 13, 3.5 − 2.5) = (0, 13, 1); tip = (0, 18.8, 1);
        // heel = (0, 0, 13.5 − 9) − 0.8·(0, 5.8, 0) = (0, −4.64, 4.5).
        let foot = Vec3::new(0.0, 0.0, 13.5);
        let ball = Vec3::new(0.0, 13.0, 3.5);
        let (b, t, h) = foot_pivots(foot, ball, 5.8, 2.5, 9.0, 0.8);
        assert_vnear(b, Vec3::new(0.0, 13.0, 1.0), 1e-5);
        assert_vnear(t, Vec3::new(0.0, 18.8, 1.0), 1e-5);
        assert_vnear(h, Vec3::new(0.0, -4.64, 4.5), 1e-5);
        // A turned foot: (ball − foot).xy = (−3, 4), unit (−0.6, 0.8), fwd (−3.48, 4.64).
        let (b, t, h) = foot_pivots(
            Vec3::new(0.0, 0.0, 13.5),
            Vec3::new(-3.0, 4.0, 3.5),
            5.8,
            2.5,
            9.0,
            0.8,
        );
        assert_vnear(b, Vec3::new(-3.0, 4.0, 1.0), 1e-5);
        assert_vnear(t, Vec3::new(-6.48, 8.64, 1.0), 1e-5);
        assert_vnear(h, Vec3::new(2.784, -3.712, 4.5), 1e-5);
    }

    #[test]
    fn foot_pivots_each_parameter() {
        let foot = Vec3::new(0.0, 0.0, 13.5);
        let ball = Vec3::new(0.0, 13.0, 3.5);
        // tip_length 10: tip (0, 23, 1), heel (0, −8, 4.5).
        let (_, t, h) = foot_pivots(foot, ball, 10.0, 2.5, 9.0, 0.8);
        assert_vnear(t, Vec3::new(0.0, 23.0, 1.0), 1e-5);
        assert_vnear(h, Vec3::new(0.0, -8.0, 4.5), 1e-5);
        // ball_drop 0: ball pivot and tip at the ball's height 3.5.
        let (b, t, _) = foot_pivots(foot, ball, 5.8, 0.0, 9.0, 0.8);
        assert_vnear(b, ball, 1e-5);
        assert_near(t.z, 3.5, 1e-5);
        // heel_drop 13.5: heel on the sole (z 0).
        let (_, _, h) = foot_pivots(foot, ball, 5.8, 2.5, 13.5, 0.8);
        assert_near(h.z, 0.0, 1e-5);
        // heel_back 0: heel straight below the ankle.
        let (_, _, h) = foot_pivots(foot, ball, 5.8, 2.5, 9.0, 0.0);
        assert_vnear(h, Vec3::new(0.0, 0.0, 4.5), 1e-5);
    }

    #[test]
    fn foot_pivots_degenerate() {
        // Ball straight below the ankle: no forward direction, no NaN.
        let foot = Vec3::new(1.0, 2.0, 13.5);
        let ball = Vec3::new(1.0, 2.0, 3.5);
        let (b, t, h) = foot_pivots(foot, ball, 5.8, 2.5, 9.0, 0.8);
        assert_vnear(b, Vec3::new(1.0, 2.0, 1.0), 1e-6);
        assert_eq!(t, b);
        assert_vnear(h, Vec3::new(1.0, 2.0, 4.5), 1e-6);
        // Coincident bones: same.
        let (_, t, h) = foot_pivots(foot, foot, 5.8, 2.5, 9.0, 0.8);
        assert!(t.is_finite() && h.is_finite());
        // NaN ball: replaced by the foot.
        let (b, t, h) = foot_pivots(foot, Vec3::splat(f32::NAN), 5.8, 2.5, 9.0, 0.8);
        assert_vnear(b, Vec3::new(1.0, 2.0, 11.0), 1e-5);
        assert_eq!(t, b);
        assert_vnear(h, Vec3::new(1.0, 2.0, 4.5), 1e-5);
        // NaN tunables count as 0.
        let (b, t, h) = foot_pivots(foot, ball, f32::NAN, f32::NAN, f32::NAN, f32::NAN);
        assert_eq!((b, t, h), (ball, ball, foot));
    }

    // --- Cycle -----------------------------------------------------------------------

    #[test]
    fn cycle_step_by_hand() {
        // 0.9 + 0.25/1 = 1.15 → 0.15; the right foot (offset 0.5): 0.65.
        let (m, f) = cycle_step(0.9, 0.25, 1.0, 0.5, true);
        assert_near(m, 0.15, 1e-6);
        assert_near(f, 0.65, 1e-6);
        // dt = 1 s with L = 0.8: 0.9 + 1.25 = 2.15 → 0.15.
        let (m, _) = cycle_step(0.9, 1.0, 0.8, 0.0, true);
        assert_near(m, 0.15, 1e-5);
        // Not moving: no advance; the foot still follows the master: fract(1.4) = 0.4.
        let (m, f) = cycle_step(0.9, 0.25, 1.0, 0.5, false);
        assert_near(m, 0.9, 1e-6);
        assert_near(f, 0.4, 1e-6);
        // dt 0: no advance.
        assert_near(cycle_step(0.3, 0.0, 1.0, 0.0, true).0, 0.3, 1e-7);
    }

    #[test]
    fn cycle_step_degenerate() {
        // L ≤ 0 or NaN: no advance.
        assert_near(cycle_step(0.3, 0.1, 0.0, 0.0, true).0, 0.3, 1e-7);
        assert_near(cycle_step(0.3, 0.1, -1.0, 0.0, true).0, 0.3, 1e-7);
        assert_near(cycle_step(0.3, 0.1, f32::NAN, 0.0, true).0, 0.3, 1e-7);
        // dt NaN, negative or infinite: no advance.
        assert_near(cycle_step(0.3, f32::NAN, 1.0, 0.0, true).0, 0.3, 1e-7);
        assert_near(cycle_step(0.3, -0.1, 1.0, 0.0, true).0, 0.3, 1e-7);
        assert_near(cycle_step(0.3, f32::INFINITY, 1.0, 0.0, true).0, 0.3, 1e-7);
        // NaN master restarts at 0; NaN foot offset counts as 0.
        let (m, f) = cycle_step(f32::NAN, 0.25, 1.0, f32::NAN, true);
        assert_near(m, 0.25, 1e-7);
        assert_near(f, 0.25, 1e-7);
        // A master outside [0, 1) is wrapped: 1.3 → 0.3.
        assert_near(cycle_step(1.3, 0.0, 1.0, 0.0, true).0, 0.3, 1e-6);
    }

    #[test]
    fn cycle_length_by_hand() {
        // 200 cm/s: L = 0.5 + 70/200 = 0.85, swing share 0.5/0.85 = 0.588235.
        let (l, s) = cycle_length(200.0, 0.5, 70.0, 100.0);
        assert_near(l, 0.85, 1e-6);
        assert_near(s, 0.588_235, 1e-5);
        // 50 cm/s is below the floor 100: L = 0.5 + 0.7 = 1.2, share 0.416667.
        let (l, s) = cycle_length(50.0, 0.5, 70.0, 100.0);
        assert_near(l, 1.2, 1e-6);
        assert_near(s, 0.416_667, 1e-5);
        // Standing still: same as the floor. Negative speed: |speed|.
        assert_eq!(
            cycle_length(0.0, 0.5, 70.0, 100.0),
            cycle_length(50.0, 0.5, 70.0, 100.0)
        );
        assert_eq!(
            cycle_length(-200.0, 0.5, 70.0, 100.0),
            cycle_length(200.0, 0.5, 70.0, 100.0)
        );
        // Parameters: swing_time 0.3 → 0.65 and 0.461538; stride 100 → 1.0 and 0.5;
        // min_speed 200 with speed 50 → 0.85.
        let (l, s) = cycle_length(200.0, 0.3, 70.0, 100.0);
        assert_near(l, 0.65, 1e-6);
        assert_near(s, 0.461_538, 1e-5);
        let (l, s) = cycle_length(200.0, 0.5, 100.0, 100.0);
        assert_near(l, 1.0, 1e-6);
        assert_near(s, 0.5, 1e-6);
        assert_near(cycle_length(50.0, 0.5, 70.0, 200.0).0, 0.85, 1e-6);
    }

    #[test]
    fn cycle_length_degenerate() {
        // NaN speed counts as 0 → the floor.
        assert_near(cycle_length(f32::NAN, 0.5, 70.0, 100.0).0, 1.2, 1e-6);
        // No floor and no speed: no cycle.
        assert_eq!(cycle_length(0.0, 0.5, 70.0, 0.0), (0.0, 0.0));
        // NaN tunables: no cycle.
        assert_eq!(cycle_length(200.0, f32::NAN, 70.0, 100.0), (0.0, 0.0));
        assert_eq!(cycle_length(200.0, 0.5, f32::NAN, 100.0), (0.0, 0.0));
        // Negative length: no cycle.
        assert_eq!(cycle_length(200.0, -1.0, 70.0, 100.0), (0.0, 0.0));
    }

    // --- Standing foot IK ------------------------------------------------------------

    #[test]
    fn foot_offset_from_trace_cases() {
        // Half-height 90, hit at 95: the ground is 5 cm lower: −5. Hit at 80: +10.
        assert_eq!(foot_offset_from_trace(true, 95.0, 90.0), -5.0);
        assert_eq!(foot_offset_from_trace(true, 80.0, 90.0), 10.0);
        // Miss: 0, whatever the distance.
        assert_eq!(foot_offset_from_trace(false, 80.0, 90.0), 0.0);
        // NaN: 0.
        assert_eq!(foot_offset_from_trace(true, f32::NAN, 90.0), 0.0);
        assert_eq!(foot_offset_from_trace(true, 80.0, f32::INFINITY), 0.0);
    }

    #[test]
    fn rotation_from_normal_by_hand() {
        // Flat ground: no tilt.
        let (p, r) = rotation_from_normal(Vec3::Z);
        assert_eq!((p, r), (0.0, 0.0));
        // Normal (sin30, 0, cos30) = (0.5, 0, 0.866): pitch = −atan2(0.5, 0.866) = −30.
        let n = Vec3::new(0.5, 0.0, 3f32.sqrt() / 2.0);
        let (p, r) = rotation_from_normal(n);
        assert_near(p, -30.0, 1e-4);
        assert_near(r, 0.0, 1e-6);
        // The quaternion Ry(−pitch) = Ry(30°) maps +Z to (sin30, 0, cos30) = n exactly.
        assert_vnear(rotation_from_normal_quat(n) * Vec3::Z, n, 1e-5);
        // Normal (0, sin20, cos20): roll = atan2(sin20, cos20) = 20. Rx(−20°) maps +Z to
        // (0, sin20, cos20) = n exactly.
        let n = Vec3::new(0.0, 20f32.to_radians().sin(), 20f32.to_radians().cos());
        let (p, r) = rotation_from_normal(n);
        assert_near(p, 0.0, 1e-6);
        assert_near(r, 20.0, 1e-4);
        assert_vnear(rotation_from_normal_quat(n) * Vec3::Z, n, 1e-5);
        // Length does not matter.
        assert_eq!(rotation_from_normal(n * 7.0), rotation_from_normal(n));
    }

    #[test]
    fn rotation_from_normal_small_slope_matches_normal() {
        // A 3° by 2° slope: tan3° = 0.052408, tan2° = 0.034921.
        let n = Vec3::new(0.052_408, 0.034_921, 1.0).normalize();
        let (p, r) = rotation_from_normal(n);
        assert_near(p, -3.0, 1e-3);
        assert_near(r, 2.0, 1e-3);
        let up = rotation_from_normal_quat(n) * Vec3::Z;
        let error_deg = up.angle_between(n).to_degrees();
        assert!(error_deg < 0.01, "{error_deg}");
        // Signs: for every small slope the rotated up axis leans the same way as n.
        for &(x, y) in &[
            (0.05, 0.0),
            (-0.05, 0.0),
            (0.0, 0.05),
            (0.0, -0.05),
            (0.03, -0.04),
        ] {
            let n = Vec3::new(x, y, 1.0).normalize();
            let up = rotation_from_normal_quat(n) * Vec3::Z;
            assert!(up.angle_between(n).to_degrees() < 0.01, "{n} vs {up}");
        }
    }

    #[test]
    fn rotation_from_normal_degenerate() {
        assert_eq!(rotation_from_normal(Vec3::ZERO), (0.0, 0.0));
        assert_eq!(rotation_from_normal(Vec3::splat(f32::NAN)), (0.0, 0.0));
        assert_eq!(rotation_from_normal_quat(Vec3::ZERO), Quat::IDENTITY);
        assert_eq!(
            rotation_from_normal_quat(Vec3::new(f32::NAN, 0.0, 1.0)),
            Quat::IDENTITY
        );
    }

    // --- Damping ---------------------------------------------------------------------

    #[test]
    fn finterp_to_by_hand() {
        // dt·speed = 0.1·5 = 0.5: half way.
        assert_eq!(finterp_to(0.0, 10.0, 0.1, 5.0), 5.0);
        // dt = 1 s: clamp(5) = 1: the target.
        assert_eq!(finterp_to(0.0, 10.0, 1.0, 5.0), 10.0);
        // speed 0 (or negative, or NaN): snap to the target (Unreal).
        assert_eq!(finterp_to(0.0, 10.0, 0.1, 0.0), 10.0);
        assert_eq!(finterp_to(0.0, 10.0, 0.1, f32::NAN), 10.0);
        // dt 0: no motion.
        assert_eq!(finterp_to(0.0, 10.0, 0.0, 5.0), 0.0);
        // Within 1e-4: snap.
        assert_eq!(finterp_to(0.0, 5e-5, 0.001, 1.0), 5e-5);
        // NaN current: target; NaN target: current.
        assert_eq!(finterp_to(f32::NAN, 10.0, 0.1, 5.0), 10.0);
        assert_eq!(finterp_to(3.0, f32::NAN, 0.1, 5.0), 3.0);
        // Not frame-rate independent: two steps of 0.05 s move 2.5 then 1.875, 4.375 in
        // all, one step of 0.1 s moves 5.
        let two = finterp_to(finterp_to(0.0, 10.0, 0.05, 5.0), 10.0, 0.05, 5.0);
        assert_near(two, 4.375, 1e-5);
    }

    #[test]
    fn vinterp_and_qinterp_by_hand() {
        let t = Vec3::new(10.0, 0.0, 0.0);
        assert_vnear(
            vinterp_to(Vec3::ZERO, t, 0.1, 5.0),
            Vec3::new(5.0, 0.0, 0.0),
            1e-6,
        );
        assert_eq!(vinterp_to(Vec3::ZERO, t, 0.1, 0.0), t);
        assert_eq!(vinterp_to(Vec3::ZERO, t, 0.0, 5.0), Vec3::ZERO);
        // Squared distance 1e-6·... < 1e-4: snap.
        let close = Vec3::new(0.005, 0.0, 0.0);
        assert_eq!(vinterp_to(Vec3::ZERO, close, 0.001, 1.0), close);
        assert_eq!(vinterp_to(Vec3::splat(f32::NAN), t, 0.1, 5.0), t);
        assert_eq!(vinterp_to(t, Vec3::splat(f32::NAN), 0.1, 5.0), t);
        // Identity towards Rz(90°) half way: Rz(45°).
        assert_qnear(
            qinterp_to(Quat::IDENTITY, rz(90.0), 0.1, 5.0),
            rz(45.0),
            1e-6,
        );
        assert_qnear(
            qinterp_to(Quat::IDENTITY, rz(90.0), 1.0, 5.0),
            rz(90.0),
            1e-6,
        );
        assert_qnear(
            qinterp_to(Quat::IDENTITY, rz(90.0), 0.1, 0.0),
            rz(90.0),
            1e-6,
        );
        assert_qnear(
            qinterp_to(Quat::IDENTITY, rz(90.0), 0.0, 5.0),
            Quat::IDENTITY,
            1e-6,
        );
        // The short way: from identity towards −Rz(90°) (the same rotation) still 45°.
        assert_qnear(
            qinterp_to(Quat::IDENTITY, -rz(90.0), 0.1, 5.0),
            rz(45.0),
            1e-6,
        );
        let nan = Quat::from_xyzw(f32::NAN, 0.0, 0.0, 1.0);
        assert_qnear(qinterp_to(nan, rz(90.0), 0.1, 5.0), rz(90.0), 1e-6);
        assert_qnear(qinterp_to(rz(30.0), nan, 0.1, 5.0), rz(30.0), 1e-6);
    }

    #[test]
    fn lerp_exponential_by_hand() {
        // Speed ln 2, dt 1 s: half way.
        assert_near(lerp_exponential(0.0, 100.0, 1.0, LN_2), 50.0, 1e-4);
        // Speed 0, dt 0, NaN dt, NaN speed: no motion.
        assert_eq!(lerp_exponential(3.0, 100.0, 1.0, 0.0), 3.0);
        assert_eq!(lerp_exponential(3.0, 100.0, 0.0, 6.0), 3.0);
        assert_eq!(lerp_exponential(3.0, 100.0, f32::NAN, 6.0), 3.0);
        assert_eq!(lerp_exponential(3.0, 100.0, 1.0, f32::NAN), 3.0);
        // Infinite speed: the target.
        assert_eq!(lerp_exponential(3.0, 100.0, 0.1, f32::INFINITY), 100.0);
        // NaN current: target; NaN target: current.
        assert_eq!(lerp_exponential(f32::NAN, 100.0, 0.1, 6.0), 100.0);
        assert_eq!(lerp_exponential(3.0, f32::NAN, 0.1, 6.0), 3.0);
        // Both non-finite: 0. A step that overflows (−MAX − MAX = −∞): the target.
        assert_eq!(lerp_exponential(f32::NAN, f32::INFINITY, 0.1, 6.0), 0.0);
        assert_eq!(lerp_by_weight(f32::MAX, -f32::MAX, 0.5), -f32::MAX);
        // A weight of 1 or more is the target exactly; NaN weight: the target (no lerp).
        assert_eq!(lerp_by_weight(3.0, 100.0, 1.5), 100.0);
        assert_eq!(lerp_by_weight(3.0, 100.0, f32::NAN), 100.0);
    }

    #[test]
    fn lerp_exponential_is_frame_rate_independent() {
        // k = 2/s from 0 towards 1 for 1 s. Exponential: 1 − e^(−2) = 0.864665 however the
        // second is split.
        let k = 2.0;
        let one = lerp_exponential(0.0, 1.0, 1.0, k);
        let mut at60 = 0.0;
        for _ in 0..60 {
            at60 = lerp_exponential(at60, 1.0, 1.0 / 60.0, k);
        }
        let mut at30 = 0.0;
        for _ in 0..30 {
            at30 = lerp_exponential(at30, 1.0, 1.0 / 30.0, k);
        }
        assert_near(one, 0.864_665, 1e-5);
        assert_near(at60, one, 1e-4);
        assert_near(at30, one, 1e-4);

        // The seed's final VectorLerp, x + (t − x)·clamp(k·dt, 0, 1), computed inline:
        // 60 fps: 1 − (1 − 2/60)^60 = 1 − (29/30)^60 = 1 − 0.130799 = 0.869201;
        // 30 fps: 1 − (14/15)^30 = 0.873787; one 1 s step: clamp(2) = 1, the target.
        let seed = |x: f32, t: f32, dt: f32| x + (t - x) * (k * dt).clamp(0.0, 1.0);
        let mut s60 = 0.0;
        for _ in 0..60 {
            s60 = seed(s60, 1.0, 1.0 / 60.0);
        }
        let mut s30 = 0.0;
        for _ in 0..30 {
            s30 = seed(s30, 1.0, 1.0 / 30.0);
        }
        let s1 = seed(0.0, 1.0, 1.0);
        assert_near(s60, 0.869_201, 1e-4);
        assert_near(s30, 0.873_787, 1e-4);
        assert_eq!(s1, 1.0);
        // The seed's form differs measurably: 0.0046 between 30 and 60 fps (a 100 cm
        // move lands 0.46 cm apart), 0.131 between 60 fps and a 1 s hitch.
        assert!(s30 - s60 > 0.004, "{}", s30 - s60);
        assert!(s1 - s60 > 0.13);
    }

    #[test]
    fn lerp_exponential_vectors_and_rotations() {
        let t = Vec3::new(100.0, -50.0, 20.0);
        assert_vnear(lerp_exponential_v(Vec3::ZERO, t, 1.0, LN_2), t * 0.5, 1e-3);
        let one = lerp_exponential_v(Vec3::ZERO, t, 1.0, 6.0);
        let mut x = Vec3::ZERO;
        for _ in 0..60 {
            x = lerp_exponential_v(x, t, 1.0 / 60.0, 6.0);
        }
        assert_vnear(x, one, 1e-3);
        assert_eq!(lerp_exponential_v(Vec3::ONE, t, 0.0, 6.0), Vec3::ONE);
        assert_eq!(lerp_exponential_v(Vec3::splat(f32::NAN), t, 0.1, 6.0), t);
        assert_eq!(
            lerp_exponential_v(Vec3::ONE, Vec3::splat(f32::NAN), 0.1, 6.0),
            Vec3::ONE
        );

        // Rotations: identity towards Rz(90°) at ln2/s for 1 s: Rz(45°).
        assert_qnear(
            lerp_exponential_q(Quat::IDENTITY, rz(90.0), 1.0, LN_2),
            rz(45.0),
            1e-6,
        );
        let one = lerp_exponential_q(Quat::IDENTITY, rz(120.0), 1.0, 2.0);
        let mut q = Quat::IDENTITY;
        for _ in 0..60 {
            q = lerp_exponential_q(q, rz(120.0), 1.0 / 60.0, 2.0);
        }
        // 120·(1 − e^(−2)) = 103.7598°.
        assert_near(yaw_of(one), 103.759_8, 1e-2);
        assert_qnear(q, one, 1e-6);
        assert_qnear(
            lerp_exponential_q(Quat::IDENTITY, rz(90.0), 0.0, 6.0),
            Quat::IDENTITY,
            1e-7,
        );
        let nan = Quat::from_xyzw(f32::NAN, 0.0, 0.0, 1.0);
        assert_qnear(lerp_exponential_q(nan, rz(90.0), 0.1, 6.0), rz(90.0), 1e-6);
        assert_qnear(lerp_exponential_q(rz(30.0), nan, 0.1, 6.0), rz(30.0), 1e-6);
    }

    #[test]
    fn lerp_max_step_by_hand() {
        let t = Vec3::new(100.0, 0.0, 0.0);
        // Weight 0.5 (ln2/s, 1 s): step 50; limit 20 cm/s·1 s = 20.
        assert_vnear(
            lerp_max_step(Vec3::ZERO, t, 1.0, LN_2, 20.0),
            Vec3::new(20.0, 0.0, 0.0),
            1e-4,
        );
        // Limit 100: step 50 unclamped.
        assert_vnear(
            lerp_max_step(Vec3::ZERO, t, 1.0, LN_2, 100.0),
            Vec3::new(50.0, 0.0, 0.0),
            1e-3,
        );
        // No limit: the target at infinite speed.
        assert_eq!(
            lerp_max_step(Vec3::ZERO, t, 1.0, f32::INFINITY, f32::INFINITY),
            t
        );
        // Limit 0, negative or NaN: frozen. dt 0: frozen.
        assert_eq!(lerp_max_step(Vec3::ZERO, t, 1.0, LN_2, 0.0), Vec3::ZERO);
        assert_eq!(lerp_max_step(Vec3::ZERO, t, 1.0, LN_2, -5.0), Vec3::ZERO);
        assert_eq!(
            lerp_max_step(Vec3::ZERO, t, 1.0, LN_2, f32::NAN),
            Vec3::ZERO
        );
        assert_eq!(lerp_max_step(Vec3::ZERO, t, 0.0, LN_2, 20.0), Vec3::ZERO);
        // While the limit holds the motion is constant-speed, frame-rate independent:
        // 60 steps of 1/60 s at 20 cm/s cover 20 cm, like one 1 s step.
        let mut x = Vec3::ZERO;
        for _ in 0..60 {
            x = lerp_max_step(x, t, 1.0 / 60.0, 6.0, 20.0);
        }
        assert_vnear(x, Vec3::new(20.0, 0.0, 0.0), 1e-3);
        assert_eq!(lerp_max_step(Vec3::splat(f32::NAN), t, 0.1, 6.0, 20.0), t);
    }

    #[test]
    fn spring_by_hand() {
        // From rest at 0 towards 1, half-life 0.5 s, one step of 0.5 s:
        // y = 2·ln2/0.5 = 2.772589, y·dt = 1.386294, e = 0.25; j0 = −1, j1 = −2.772589.
        // x = 1 + 0.25·(−1 − 1.386294) = 0.403426; v = 0.25·(0 + 2.772589·1.386294)
        // = 0.960906.
        let (x, v) = spring_damper(0.0, 0.0, 1.0, 0.5, 0.5);
        assert_near(x, 0.403_426, 1e-5);
        assert_near(v, 0.960_906, 1e-5);
        // Vector version, per component.
        let (xv, vv) = spring_damper_v(Vec3::ZERO, Vec3::ZERO, Vec3::new(1.0, -2.0, 0.0), 0.5, 0.5);
        assert_vnear(xv, Vec3::new(0.403_426, -0.806_852, 0.0), 1e-5);
        assert_vnear(vv, Vec3::new(0.960_906, -1.921_812, 0.0), 1e-5);
        // half_life parameter: longer half-life, slower: 1 s gives y = 1.386294, y·dt =
        // 0.693147, e = 0.5: x = 1 + 0.5·(−1 − 0.693147) = 0.153426.
        assert_near(spring_damper(0.0, 0.0, 1.0, 1.0, 0.5).0, 0.153_426, 1e-5);
    }

    #[test]
    fn spring_is_exact_for_any_dt() {
        // With an initial velocity too: one step of 0.5 s equals 50 steps of 0.01 s.
        let (x1, v1) = spring_damper(2.0, -3.0, 10.0, 0.3, 0.5);
        let (mut x, mut v) = (2.0, -3.0);
        for _ in 0..50 {
            (x, v) = spring_damper(x, v, 10.0, 0.3, 0.01);
        }
        assert_near(x, x1, 1e-4);
        assert_near(v, v1, 1e-4);
        let (xv1, vv1) = spring_damper_v(Vec3::ONE, Vec3::X * 5.0, Vec3::Y * 4.0, 0.3, 0.5);
        let (mut xv, mut vv) = (Vec3::ONE, Vec3::X * 5.0);
        for _ in 0..50 {
            (xv, vv) = spring_damper_v(xv, vv, Vec3::Y * 4.0, 0.3, 0.01);
        }
        assert_vnear(xv, xv1, 1e-4);
        assert_vnear(vv, vv1, 1e-4);
        // dt = 1 s from rest: 1 − (1 + 2.772589)·e^(−2.772589) = 1 − 3.772589·0.0625
        // = 0.764213.
        assert_near(spring_damper(0.0, 0.0, 1.0, 0.5, 1.0).0, 0.764_213, 1e-5);
    }

    #[test]
    fn spring_converges_without_overshoot() {
        let (mut x, mut v) = (0.0f32, 0.0f32);
        let mut last = x;
        for _ in 0..600 {
            (x, v) = spring_damper(x, v, 10.0, 0.2, 1.0 / 60.0);
            assert!(x >= last - 1e-6 && x <= 10.0 + 1e-5, "{x} after {last}");
            last = x;
        }
        // After 10 s (50 half-lives) it has arrived and stopped.
        assert_near(x, 10.0, 1e-4);
        assert_near(v, 0.0, 1e-4);
    }

    #[test]
    fn spring_degenerate() {
        // dt 0 or NaN: unchanged.
        assert_eq!(spring_damper(1.0, 2.0, 5.0, 0.5, 0.0), (1.0, 2.0));
        assert_eq!(spring_damper(1.0, 2.0, 5.0, 0.5, f32::NAN), (1.0, 2.0));
        // half_life 0 or NaN: snap.
        assert_eq!(spring_damper(1.0, 2.0, 5.0, 0.0, 0.1), (5.0, 0.0));
        assert_eq!(spring_damper(1.0, 2.0, 5.0, f32::NAN, 0.1), (5.0, 0.0));
        // NaN value: snap. NaN velocity: 0. NaN target: brake at the current value.
        assert_eq!(spring_damper(f32::NAN, 2.0, 5.0, 0.5, 0.1), (5.0, 0.0));
        assert_eq!(
            spring_damper(1.0, f32::NAN, 5.0, 0.5, 0.1),
            spring_damper(1.0, 0.0, 5.0, 0.5, 0.1)
        );
        let (x, v) = spring_damper(1.0, 0.0, f32::NAN, 0.5, 0.1);
        assert_eq!((x, v), (1.0, 0.0));
        // Huge dt: settled.
        let (x, v) = spring_damper(1.0, 2.0, 5.0, 0.5, 1e30);
        assert_eq!((x, v), (5.0, 0.0));
        let (xv, vv) = spring_damper_v(Vec3::splat(f32::NAN), Vec3::ZERO, Vec3::ONE, 0.5, 0.1);
        assert_eq!((xv, vv), (Vec3::ONE, Vec3::ZERO));
    }

    // --- Robustness sweep --------------------------------------------------------------

    #[test]
    fn no_kernel_returns_non_finite_values() {
        let specials = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            1e-30,
            1e30,
            -1e30,
            f32::MAX,
            f32::MIN,
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
        ];
        let vectors = [
            Vec3::ZERO,
            Vec3::new(-100.0, 100.0, 3.0),
            Vec3::new(0.0, -1.0, 0.0),
            Vec3::splat(f32::NAN),
            Vec3::new(f32::INFINITY, 0.0, 0.0),
            Vec3::splat(f32::MAX),
            Vec3::new(f32::MIN, f32::MAX, 1e30),
        ];
        let quats = [
            Quat::IDENTITY,
            rz(170.0),
            Quat::from_xyzw(1.0, 0.0, 0.0, 0.0),
            Quat::from_xyzw(0.0, 0.0, 0.0, 0.0),
            Quat::from_xyzw(f32::NAN, 0.0, 0.0, 1.0),
            Quat::from_xyzw(f32::INFINITY, 0.0, 0.0, 1.0),
        ];
        let ok = |x: f32| assert!(x.is_finite(), "{x}");
        let okv = |x: Vec3| assert!(x.is_finite(), "{x}");
        let okq = |x: Quat| assert!(x.is_finite() && (x.length() - 1.0).abs() < 1e-3, "{x}");
        // Each scalar argument in turn takes every special value; the others stay sane.
        for &s in &specials {
            for i in 0..8 {
                let mut a = [10.0, 0.3, 1.0 / 60.0, 6.0, 0.2, 90.0, 110.0, 0.4];
                a[i] = s;
                for &v in &vectors {
                    ok(get_movement_angle_offset(
                        v, a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7],
                    ));
                }
            }
            ok(per_foot_rotation_factor(s, 0.5, 0.9));
            ok(per_foot_rotation_factor(1.0, s, s));
            for &q in &quats {
                okq(limit_rotation_around_z(q, s, 25.0));
                okq(limit_rotation_around_z(q, 10.0, s));
                okq(qinterp_to(q, rz(20.0), s, 5.0));
                okq(qinterp_to(q, rz(20.0), 0.1, s));
                okq(lerp_exponential_q(q, rz(20.0), s, 5.0));
                okq(lerp_exponential_q(rz(20.0), q, 0.1, s));
                okv(knee_vector(q, q, Vec3::Y, s, 20.0));
                okv(knee_vector(q, rz(30.0), Vec3::Y, 0.25, s));
                okq(rotation_from_normal_quat(Vec3::new(s, 0.1, 1.0)));
            }
            for &v in &vectors {
                for &w in &vectors {
                    okv(foot_avoidance(v, w, s, true, 15.0));
                    okv(foot_avoidance(v, w, 10.0, false, s));
                    let (b, t, h) = foot_pivots(v, w, s, 2.5, 9.0, 0.8);
                    okv(b);
                    okv(t);
                    okv(h);
                    let (b, t, h) = foot_pivots(v, w, 5.8, s, s, s);
                    okv(b);
                    okv(t);
                    okv(h);
                    okv(vinterp_to(v, w, s, 5.0));
                    okv(vinterp_to(v, w, 0.1, s));
                    okv(lerp_exponential_v(v, w, s, 5.0));
                    okv(lerp_exponential_v(v, w, 0.1, s));
                    okv(lerp_max_step(v, w, s, 5.0, 20.0));
                    okv(lerp_max_step(v, w, 0.1, s, s));
                    let (x, y) = spring_damper_v(v, w, v, s, 0.1);
                    okv(x);
                    okv(y);
                    let (x, y) = spring_damper_v(v, w, w, 0.5, s);
                    okv(x);
                    okv(y);
                }
                for p in 0..13 {
                    let mut a = [
                        0.1, 0.15, 0.4, -0.5, 1.0, 300.0, 50.0, 15.0, 0.4, 0.4, 1.0, 0.0, 0.0,
                    ];
                    a[p] = s;
                    ok(arm_swing_pitch(
                        a[0],
                        v,
                        rz(30.0),
                        a[1],
                        a[2],
                        a[3],
                        a[4],
                        a[5],
                        a[6],
                        a[7],
                        a[8],
                        a[9],
                        a[10],
                    ));
                }
                let (p, f) = pelvis_lean(v, s, -15.0, 10.0);
                ok(p);
                ok(f);
                let (p, r) = rotation_from_normal(v);
                ok(p);
                ok(r);
            }
            for &t in &specials {
                ok(clavicle_offset(s, t, 300.0, 1.5));
                ok(clavicle_offset(0.3, 300.0, s, t));
                ok(pelvis_side_lean(s, t, 15.0));
                ok(pelvis_side_lean(30.0, s, t));
                let (m, f) = cycle_step(s, t, 1.0, 0.5, true);
                ok(m);
                ok(f);
                assert!((0.0..1.0).contains(&m) && (0.0..1.0).contains(&f));
                let (m, f) = cycle_step(0.3, 0.1, s, t, true);
                ok(m);
                ok(f);
                let (l, p) = cycle_length(s, t, 70.0, 100.0);
                ok(l);
                ok(p);
                let (l, p) = cycle_length(200.0, 0.5, s, t);
                ok(l);
                ok(p);
                ok(foot_offset_from_trace(true, s, t));
                ok(finterp_to(s, t, 0.1, 5.0));
                ok(finterp_to(1.0, 2.0, s, t));
                ok(lerp_exponential(s, t, 0.1, 5.0));
                ok(lerp_exponential(1.0, 2.0, s, t));
                let (x, v) = spring_damper(s, t, 1.0, 0.5, 0.1);
                ok(x);
                ok(v);
                let (x, v) = spring_damper(1.0, 0.0, s, t, 0.1);
                ok(x);
                ok(v);
                let (x, v) = spring_damper(1.0, 0.0, 2.0, s, t);
                ok(x);
                ok(v);
            }
        }
    }
}
