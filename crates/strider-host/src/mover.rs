//! A kinematic character capsule driven by input, moving through a [`World`].
//!
//! # Spaces and units
//!
//! World space, +Z up, centimetres, seconds; yaw in degrees about +Z: yaw 0 faces world
//! +Y, positive yaw turns counter-clockwise seen from above (`Rz(+90°)` maps +Y to −X, so
//! yaw 90° faces −X). The mover's position is the **bottom centre of the capsule** (the
//! soles), which is the origin of rig space: [`Mover::component_to_world`] is a translation
//! to that point and a rotation of `yaw` about +Z, so rig +Y (forward) maps to
//! [`yaw_direction`]`(yaw) = (−sin yaw, cos yaw, 0)` and rig +X (the character's left by
//! the rig convention) to `(cos yaw, sin yaw, 0)`; rig +Z stays world +Z.
//!
//! The rig never moves the capsule: the host moves it from input, and hands the rig the
//! resulting transform every frame.
//!
//! # How a step works
//!
//! [`Mover::step`] splits `dt` into equal sub-steps of at most
//! [`MoverSettings::max_substep`]. Each sub-step:
//!
//! 1. moves the horizontal velocity towards `direction · speed` by at most
//!    `acceleration · dt` (or `braking · dt` when the input asks to stand still; both
//!    scaled by `air_control` while airborne);
//! 2. turns the yaw towards the velocity ([`Facing::Velocity`], while the input asks to
//!    move and the mover is faster than 1 cm/s; braking to a stop keeps the yaw) or the
//!    look yaw ([`Facing::Look`]) by at most `turn_rate · dt`;
//! 3. sweeps a capsule whose bottom is lifted by `max_step_height` along the move
//!    (collide and slide, parry3d shape casts): walls stop and redirect it, anything lower
//!    than a step passes under it;
//! 4. probes the floor with a sphere of `floor_probe_radius` swept down from
//!    `max_step_height` above the feet. When walking, a walkable floor found between
//!    `max_step_height` above and `ground_snap_distance` below the feet becomes the new
//!    feet height (stepping up stairs, staying glued to ramps and steps going down; a
//!    sphere rolls over a step's edge, so the height changes over a few centimetres rather
//!    than at once). On a plane the floor height is the exact surface height under the
//!    capsule axis (a line trace); over an edge it is the bottom of the resting sphere.
//!    A floor is walkable when its slope is at most `max_slope`, or when the probe rests on
//!    the edge of a walkable top (a stair nose, a platform edge). No floor in range: the
//!    mover falls with `gravity` (capped at `max_fall_speed`) until the probe finds one.
//!
//! While walking the reported velocity has z = 0 (the horizontal ground speed, as game
//! engines keep it); while falling z is the fall speed.
//!
//! The step is deterministic: the same settings, start, inputs and `dt` sequence give a
//! bit-identical path. A `dt` of 0 changes nothing; a `dt` of 1 s (a hitch) is
//! sub-stepped; `dt` is clamped to [0, 60] s and NaN counts as 0.

use glam::{Quat, Vec2, Vec3};
use parry3d::shape::{Ball, Capsule};
use serde::Deserialize;
use strider_core::{Transform, WorldQuery};

use crate::world::{World, direction_yaw, yaw_direction};

/// Distance kept between the capsule and walls, centimetres.
const SKIN: f32 = 0.05;
/// Collide-and-slide iterations per sub-step.
const SLIDE_ITERATIONS: usize = 4;
/// Largest `dt` one call accepts, seconds.
const MAX_DT: f32 = 60.0;
/// Largest accepted input speed, cm/s.
const MAX_INPUT_SPEED: f32 = 100_000.0;
/// Below this horizontal speed (cm/s), [`Facing::Velocity`] keeps the current yaw.
const FACING_MIN_SPEED: f32 = 1.0;

/// Tunables of the mover. Lengths in centimetres, times in seconds, speeds in cm/s,
/// accelerations in cm/s², angles in degrees. In a scenario file any field left out keeps
/// its default.
#[derive(Clone, Copy, Debug, PartialEq, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct MoverSettings {
    /// Capsule radius, cm. Default 34 (the UE mannequin's).
    pub radius: f32,
    /// Capsule half height including the hemispheres, cm: the capsule is `2 · half_height`
    /// tall. Default 88.
    pub half_height: f32,
    /// Largest change of horizontal velocity per second while moving, cm/s². Default 1200.
    pub acceleration: f32,
    /// Largest change of horizontal velocity per second when the input asks to stand
    /// still, cm/s². Default 1600.
    pub braking: f32,
    /// Fraction of `acceleration` / `braking` available while airborne, 0..=1. Default 0.05.
    pub air_control: f32,
    /// Largest yaw change per second, degrees/s. Default 540.
    pub turn_rate: f32,
    /// Highest step walked up (and lowest obstacle that blocks), cm. Default 45.
    pub max_step_height: f32,
    /// Steepest walkable slope, degrees. Default 45.
    pub max_slope: f32,
    /// Downward acceleration while airborne, cm/s². Default 980.
    pub gravity: f32,
    /// Largest fall speed, cm/s. Default 4000.
    pub max_fall_speed: f32,
    /// How far below the feet a floor is still followed while walking (larger drops are
    /// fallen), cm. Default 45.
    pub ground_snap_distance: f32,
    /// Radius of the floor probe sphere (at most `radius`), cm. Default 20.
    pub floor_probe_radius: f32,
    /// Longest internal sub-step, seconds. Default 1/60.
    pub max_substep: f32,
}

impl Default for MoverSettings {
    fn default() -> Self {
        Self {
            radius: 34.0,
            half_height: 88.0,
            acceleration: 1200.0,
            braking: 1600.0,
            air_control: 0.05,
            turn_rate: 540.0,
            max_step_height: 45.0,
            max_slope: 45.0,
            gravity: 980.0,
            max_fall_speed: 4000.0,
            ground_snap_distance: 45.0,
            floor_probe_radius: 20.0,
            max_substep: 1.0 / 60.0,
        }
    }
}

impl MoverSettings {
    /// Checks every field (finite and in range); the message names the field and the range.
    pub fn validate(&self) -> Result<(), String> {
        let checks: [(&str, f32, f32, f32); 13] = [
            ("radius", self.radius, 0.1, 1000.0),
            ("half_height", self.half_height, 0.1, 1000.0),
            ("acceleration", self.acceleration, 0.0, 1.0e7),
            ("braking", self.braking, 0.0, 1.0e7),
            ("air_control", self.air_control, 0.0, 1.0),
            ("turn_rate", self.turn_rate, 0.0, 1.0e6),
            ("max_step_height", self.max_step_height, 0.0, 1000.0),
            ("max_slope", self.max_slope, 0.0, 89.0),
            ("gravity", self.gravity, 0.0, 1.0e6),
            ("max_fall_speed", self.max_fall_speed, 0.0, 1.0e6),
            (
                "ground_snap_distance",
                self.ground_snap_distance,
                0.0,
                1000.0,
            ),
            ("floor_probe_radius", self.floor_probe_radius, 0.1, 1000.0),
            ("max_substep", self.max_substep, 1.0e-4, 1.0),
        ];
        for (name, value, min, max) in checks {
            if !(value.is_finite() && value >= min && value <= max) {
                return Err(format!(
                    "mover setting `{name}` is {value}; it must be between {min} and {max}"
                ));
            }
        }
        if self.half_height < self.radius {
            return Err(format!(
                "mover setting `half_height` ({}) must be at least `radius` ({})",
                self.half_height, self.radius
            ));
        }
        Ok(())
    }

    /// A copy where every invalid field is replaced by its default (and the probe radius
    /// and half height made consistent with the radius).
    #[must_use]
    pub fn sanitized(&self) -> Self {
        let d = Self::default();
        let pick = |v: f32, min: f32, max: f32, default: f32| {
            if v.is_finite() && v >= min && v <= max {
                v
            } else {
                default
            }
        };
        let radius = pick(self.radius, 0.1, 1000.0, d.radius);
        let half_height = pick(self.half_height, 0.1, 1000.0, d.half_height).max(radius);
        Self {
            radius,
            half_height,
            acceleration: pick(self.acceleration, 0.0, 1.0e7, d.acceleration),
            braking: pick(self.braking, 0.0, 1.0e7, d.braking),
            air_control: pick(self.air_control, 0.0, 1.0, d.air_control),
            turn_rate: pick(self.turn_rate, 0.0, 1.0e6, d.turn_rate),
            max_step_height: pick(self.max_step_height, 0.0, 1000.0, d.max_step_height),
            max_slope: pick(self.max_slope, 0.0, 89.0, d.max_slope),
            gravity: pick(self.gravity, 0.0, 1.0e6, d.gravity),
            max_fall_speed: pick(self.max_fall_speed, 0.0, 1.0e6, d.max_fall_speed),
            ground_snap_distance: pick(
                self.ground_snap_distance,
                0.0,
                1000.0,
                d.ground_snap_distance,
            ),
            floor_probe_radius: pick(self.floor_probe_radius, 0.1, 1000.0, d.floor_probe_radius)
                .min(radius),
            max_substep: pick(self.max_substep, 1.0e-4, 1.0, d.max_substep),
        }
    }
}

/// Which way the character turns while it moves.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Facing {
    /// Turn towards the horizontal velocity at the turn rate (keep the yaw when slower
    /// than 1 cm/s or when the input asks to stand still).
    Velocity,
    /// Turn towards a fixed world yaw, degrees (0 = +Y, counter-clockwise positive), at the
    /// turn rate; used for strafing.
    Look(f32),
}

/// What the player asks for during one step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MoveInput {
    /// Desired move direction in world XY. Its length (clamped to 0..=1) scales `speed`;
    /// zero means stand still. Non-finite values count as zero.
    pub direction: Vec2,
    /// Speed at full stick, cm/s (negative or non-finite counts as 0).
    pub speed: f32,
    /// How the character turns.
    pub facing: Facing,
}

impl MoveInput {
    /// Stand still, facing along the velocity (that is, keep the current yaw).
    pub const STAND: Self = Self {
        direction: Vec2::ZERO,
        speed: 0.0,
        facing: Facing::Velocity,
    };

    /// The desired horizontal velocity, world XY, cm/s (sanitised: finite, stick length at
    /// most 1).
    #[must_use]
    pub fn desired_velocity(&self) -> Vec2 {
        let mut dir = if self.direction.is_finite() {
            self.direction
        } else {
            Vec2::ZERO
        };
        if dir.length_squared() > 1.0 {
            dir = dir.normalize_or_zero();
        }
        let speed = if self.speed.is_finite() {
            self.speed.clamp(0.0, MAX_INPUT_SPEED)
        } else {
            0.0
        };
        dir * speed
    }

    /// True when the input asks to stand still (zero direction or zero speed).
    #[must_use]
    pub fn is_standing_still(&self) -> bool {
        self.desired_velocity() == Vec2::ZERO
    }
}

impl Default for MoveInput {
    /// [`MoveInput::STAND`].
    fn default() -> Self {
        Self::STAND
    }
}

/// What the floor probe found.
#[derive(Clone, Copy, Debug)]
enum Floor {
    /// Nothing in range.
    None,
    /// A floor the character can stand on, at this feet height.
    Walkable { height: f32, normal: Vec3 },
    /// A surface too steep to stand on; the sphere rests on it with its bottom at `height`.
    Steep { height: f32, normal: Vec3 },
}

/// A kinematic character capsule. See the module docs for how it moves.
#[derive(Clone, Debug)]
pub struct Mover {
    settings: MoverSettings,
    /// Bottom centre of the capsule (the soles), world, cm.
    position: Vec3,
    /// Degrees, wrapped to (−180, 180].
    yaw: f32,
    /// World cm/s.
    velocity: Vec3,
    grounded: bool,
    ground_normal: Vec3,
}

/// Wraps an angle in degrees to (−180, 180].
fn wrap_degrees(a: f32) -> f32 {
    let mut r = a.rem_euclid(360.0);
    if r > 180.0 {
        r -= 360.0;
    }
    r
}

impl Mover {
    /// A mover whose capsule bottom is at `position` (world, cm) facing `yaw_deg`, at rest
    /// and airborne until the first step (or [`Mover::settle`]) finds the floor. Invalid settings fields are
    /// replaced by their defaults ([`MoverSettings::sanitized`]); a non-finite position
    /// becomes the origin and a non-finite yaw 0.
    #[must_use]
    pub fn new(settings: MoverSettings, position: Vec3, yaw_deg: f32) -> Self {
        let mut mover = Self {
            settings: settings.sanitized(),
            position: Vec3::ZERO,
            yaw: 0.0,
            velocity: Vec3::ZERO,
            grounded: false,
            ground_normal: Vec3::Z,
        };
        mover.teleport(position, yaw_deg);
        mover
    }

    /// Moves the capsule bottom to `position` (world, cm) facing `yaw_deg` at once, at rest
    /// and airborne until the next step (or [`Mover::settle`]) finds the floor. Non-finite values are ignored
    /// (the current position / yaw is kept).
    pub fn teleport(&mut self, position: Vec3, yaw_deg: f32) {
        if position.is_finite() {
            self.position = position;
        }
        if yaw_deg.is_finite() {
            self.yaw = wrap_degrees(yaw_deg);
        }
        self.velocity = Vec3::ZERO;
        self.grounded = false;
        self.ground_normal = Vec3::Z;
    }

    /// Puts the capsule on the floor without time passing: a walkable floor between
    /// `max_step_height` above and `ground_snap_distance` below the feet becomes the feet
    /// height and the mover is grounded. Otherwise nothing changes. Used after spawning
    /// and teleporting, so the first frame already stands on the ground.
    pub fn settle(&mut self, world: &World) {
        let s = self.settings;
        if let Floor::Walkable { height, normal } =
            self.find_floor(world, s.max_step_height, s.ground_snap_distance)
        {
            self.position.z = height;
            self.velocity.z = 0.0;
            self.grounded = true;
            self.ground_normal = normal;
        }
    }

    /// The settings in use (after sanitising).
    #[must_use]
    pub fn settings(&self) -> &MoverSettings {
        &self.settings
    }

    /// Bottom centre of the capsule (the rig origin, the soles), world, cm.
    #[must_use]
    pub fn position(&self) -> Vec3 {
        self.position
    }

    /// Facing yaw, degrees in (−180, 180] (0 = +Y, counter-clockwise positive).
    #[must_use]
    pub fn yaw(&self) -> f32 {
        self.yaw
    }

    /// Velocity, world, cm/s. z is 0 while grounded (horizontal ground speed).
    #[must_use]
    pub fn velocity(&self) -> Vec3 {
        self.velocity
    }

    /// Whether the capsule stands on a walkable floor.
    #[must_use]
    pub fn is_grounded(&self) -> bool {
        self.grounded
    }

    /// Normal of the floor under the capsule (unit, world); +Z while airborne.
    #[must_use]
    pub fn ground_normal(&self) -> Vec3 {
        self.ground_normal
    }

    /// Rig (component) space to world: a translation to the capsule bottom and a rotation
    /// of `yaw` about +Z, unit scale. Rig +Y (forward) maps to the facing direction.
    #[must_use]
    pub fn component_to_world(&self) -> Transform {
        Transform::from_translation_rotation(
            self.position,
            Quat::from_rotation_z(self.yaw.to_radians()),
        )
    }

    /// Advances the mover by `dt` seconds with `input`, sub-stepping so no internal step is
    /// longer than [`MoverSettings::max_substep`]. `dt` is clamped to [0, 60] s (NaN is 0).
    pub fn step(&mut self, input: &MoveInput, dt: f32, world: &World) {
        let dt = if dt.is_finite() {
            dt.clamp(0.0, MAX_DT)
        } else {
            0.0
        };
        if dt <= 0.0 {
            return;
        }
        let count = (dt / self.settings.max_substep).ceil().max(1.0);
        let h = dt / count;
        for _ in 0..count as u32 {
            self.substep(input, h, world);
        }
    }

    fn substep(&mut self, input: &MoveInput, h: f32, world: &World) {
        let s = self.settings;
        // 1. Horizontal velocity.
        let desired = input.desired_velocity();
        let mut rate = if desired == Vec2::ZERO {
            s.braking
        } else {
            s.acceleration
        };
        if !self.grounded {
            rate *= s.air_control;
        }
        let current = self.velocity.truncate();
        let change = desired - current;
        let max_change = rate * h;
        let horizontal = if change.length() <= max_change {
            desired
        } else {
            current + change.normalize_or_zero() * max_change
        };

        // 2. Facing.
        let target = match input.facing {
            Facing::Velocity => (desired != Vec2::ZERO && horizontal.length() > FACING_MIN_SPEED)
                .then(|| direction_yaw(horizontal.x, horizontal.y)),
            Facing::Look(yaw) => yaw.is_finite().then_some(yaw),
        };
        if let Some(target) = target {
            let diff = wrap_degrees(target - self.yaw);
            let max_turn = s.turn_rate * h;
            self.yaw = if diff.abs() <= max_turn {
                wrap_degrees(target)
            } else {
                wrap_degrees(self.yaw + max_turn * diff.signum())
            };
        }

        // 3. Move the lifted capsule.
        let was_grounded = self.grounded;
        let vz = if was_grounded {
            0.0
        } else {
            (self.velocity.z - s.gravity * h).max(-s.max_fall_speed)
        };
        self.velocity = horizontal.extend(vz);
        let old_z = self.position.z;
        self.slide(self.velocity * h, world);

        // 4. Floor.
        let floor = if was_grounded {
            self.find_floor(world, s.max_step_height, s.ground_snap_distance)
        } else {
            let fallen = (old_z - self.position.z).max(0.0);
            self.find_floor(world, s.max_step_height + fallen, 0.01)
        };
        match floor {
            Floor::Walkable { height, normal } => {
                self.position.z = height;
                self.velocity.z = 0.0;
                self.grounded = true;
                self.ground_normal = normal;
            }
            Floor::Steep { height, normal } => {
                if height > self.position.z {
                    self.position.z = height;
                }
                let into = self.velocity.dot(normal);
                if into < 0.0 {
                    self.velocity -= normal * into;
                }
                self.grounded = false;
                self.ground_normal = Vec3::Z;
            }
            Floor::None => {
                self.grounded = false;
                self.ground_normal = Vec3::Z;
            }
        }
        if !self.position.is_finite() || !self.velocity.is_finite() {
            // Cannot happen with finite inputs; never hand out NaN if it does.
            self.position = Vec3::new(
                finite_or(self.position.x, 0.0),
                finite_or(self.position.y, 0.0),
                finite_or(self.position.z, old_z),
            );
            self.velocity = Vec3::ZERO;
        }
    }

    /// Collide and slide: sweeps the capsule (bottom lifted by the step height) by `delta`,
    /// sliding along what it hits. Grounded, only the horizontal part of hit normals is
    /// used, so walls never push the character up or down.
    fn slide(&mut self, delta: Vec3, world: &World) {
        let s = self.settings;
        let height = 2.0 * s.half_height;
        let step = s.max_step_height.min(height - 2.0 * s.radius).max(0.0);
        let half_segment = ((height - step) * 0.5 - s.radius).max(0.0);
        let center_offset = Vec3::Z * (step + s.radius + half_segment);
        let capsule = Capsule::new_z(half_segment, s.radius);
        let mut remaining = delta;
        for _ in 0..SLIDE_ITERATIONS {
            let length = remaining.length();
            if length <= 1e-6 {
                break;
            }
            let Some(hit) = world.sweep(
                &capsule,
                self.position + center_offset,
                remaining,
                SKIN,
                false,
            ) else {
                self.position += remaining;
                break;
            };
            let dir = remaining / length;
            let travel = hit.distance.min(length);
            self.position += dir * travel;
            remaining -= dir * travel;
            let center = self.position + center_offset;
            let (mut normal, gap) =
                refine_normal(world, center, half_segment, s.radius, hit.normal);
            if self.grounded {
                normal = Vec3::new(normal.x, normal.y, 0.0).normalize_or_zero();
                if normal == Vec3::ZERO {
                    break;
                }
            }
            // Stand off a face by twice the skin, so the next sweep along it starts outside
            // the cast's target distance and is not stopped by GJK's noise.
            if let Some(gap) = gap
                && gap < 2.0 * SKIN
                && normal.z.abs() < 0.5
            {
                self.position += normal * (2.0 * SKIN - gap.max(-1.0));
            }
            let into = remaining.dot(normal);
            if into < 0.0 {
                remaining -= normal * into;
            }
            let into_v = self.velocity.dot(normal);
            if into_v < 0.0 {
                self.velocity -= normal * into_v;
            }
        }
    }

    /// Sweeps the probe sphere down from `up` above the feet to `down` below them.
    fn find_floor(&self, world: &World, up: f32, down: f32) -> Floor {
        let s = self.settings;
        let r = s.floor_probe_radius;
        let start = self.position + Vec3::Z * (up + r);
        let Some(hit) = world.sweep(&Ball::new(r), start, Vec3::NEG_Z * (up + down), 0.0, true)
        else {
            return Floor::None;
        };
        let center = start - Vec3::Z * hit.distance;
        let sphere_height = center.z - r;
        let n = hit.normal;
        let min_normal_z = s.max_slope.to_radians().cos() - 1e-4;
        if n.z >= min_normal_z {
            let ray_start = Vec3::new(self.position.x, self.position.y, center.z);
            let height = match world.line_trace(ray_start, ray_start - Vec3::Z * (2.0 * r + 10.0)) {
                Some(ray) if ray.normal.z >= min_normal_z && ray.point.z <= sphere_height => {
                    floor_height(sphere_height, ray.point.z, ray.normal, n, r)
                }
                _ => sphere_height,
            };
            return Floor::Walkable { height, normal: n };
        }
        // Steep contact: an edge of a walkable top (stair nose, platform edge) or a steep
        // slope. Look just beyond the contact, away from the axis.
        let contact = center - n * r;
        let away = (contact - self.position).truncate();
        if away.length() > 1e-3 {
            let probe = contact.truncate() + away.normalize() * 0.5;
            let top = Vec3::new(probe.x, probe.y, contact.z + 1.0);
            if let Some(ray) = world.line_trace(top, top - Vec3::Z * 2.5)
                && ray.normal.z >= min_normal_z
            {
                return Floor::Walkable {
                    height: sphere_height,
                    normal: ray.normal,
                };
            }
        }
        Floor::Steep {
            height: sphere_height,
            normal: n,
        }
    }
}

/// How far the resting probe sphere may float above the surface under the axis before the
/// floor follows the sphere instead of the surface, centimetres ([`floor_height`]).
const FLOAT_BLEND: f32 = 2.0;

/// The feet height from the probe sphere's resting height `sphere` (its bottom, on the
/// axis) and the surface height `ray` under the axis (normal `ray_normal`); `contact` is
/// the sphere's contact normal and `r` its radius.
///
/// A sphere resting on a plane tilted by θ floats `r · (1/cos θ − 1)` above the surface
/// under its axis (the `expected` float); over a valley of uneven ground it floats a
/// little more; over an edge (a stair nose, a platform edge) it floats a lot, and there
/// the sphere is right (the character perches, or rolls over the edge smoothly). With
/// `excess` the float beyond the plane's, the feet sit on the surface while
/// `excess ≤ FLOAT_BLEND`, follow the sphere once `excess ≥ 2 · FLOAT_BLEND`, and blend
/// linearly between, so the height is continuous along the path.
fn floor_height(sphere: f32, ray: f32, ray_normal: Vec3, contact: Vec3, r: f32) -> f32 {
    let float = sphere - ray;
    let expected = if ray_normal.dot(contact) > 2f32.to_radians().cos() {
        r * (1.0 / contact.z - 1.0)
    } else {
        0.0
    };
    let excess = (float - expected).max(0.0);
    let lift = if excess <= FLOAT_BLEND {
        0.0
    } else if excess < 2.0 * FLOAT_BLEND {
        2.0 * (excess - FLOAT_BLEND)
    } else {
        excess
    };
    (ray + lift).min(sphere)
}

/// Shape-cast normals of flat contacts (a capsule's side against a box face) are only as
/// good as GJK's convergence, a few degrees off. A ray from the capsule axis along the
/// normal finds the face itself and its exact normal; edge and corner contacts (no face
/// within 30° of the cast normal) keep the cast normal. Also returns the gap between the
/// capsule and that face, centimetres, when a face was found.
fn refine_normal(
    world: &World,
    center: Vec3,
    half_segment: f32,
    radius: f32,
    cast: Vec3,
) -> (Vec3, Option<f32>) {
    let reach = radius + SKIN + 2.0;
    let mut best: Option<(f32, Vec3, Vec3)> = None;
    for origin in [
        center - Vec3::Z * half_segment,
        center,
        center + Vec3::Z * half_segment,
    ] {
        if let Some(hit) = world.line_trace(origin, origin - cast * reach)
            && hit.distance > 0.0
            && hit.normal.dot(cast) > 30f32.to_radians().cos()
            && best.is_none_or(|(d, _, _)| hit.distance < d)
        {
            best = Some((hit.distance, hit.normal, origin));
        }
    }
    let Some((_, normal, origin)) = best else {
        return (cast, None);
    };
    let gap = world
        .line_trace(origin, origin - normal * reach)
        .filter(|h| h.normal.dot(normal) > 0.999)
        .map(|h| h.distance - radius);
    (normal, gap)
}

fn finite_or(v: f32, fallback: f32) -> f32 {
    if v.is_finite() { v } else { fallback }
}

/// The world XY unit direction of a yaw in degrees (0 = +Y, counter-clockwise positive).
#[must_use]
pub fn heading_vector(yaw_deg: f32) -> Vec2 {
    yaw_direction(yaw_deg).truncate()
}
