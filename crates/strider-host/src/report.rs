//! The locomotion quality report, computed from output poses and the world only.
//!
//! The report never looks at a graph's internal state (IK targets, phase variables, ...):
//! it sees what a player would see, the bones' rig-space global transforms of each frame,
//! where the host put the character ([`FrameRecord::component_to_world`]) and the ground
//! under the feet ([`Ground`]). That makes it usable on any rig, and comparable between
//! rigs.
//!
//! Spaces and units follow the workspace conventions: world +Z up, centimetres, seconds.
//! Rig (component) space is +Y forward, +X the character's left, and a bone's world
//! transform is `component_to_world · global` ([`Transform`] composes parent · child).
//!
//! # Definitions
//!
//! A *contact point* is a sole point from the skeleton file (a bone and an offset in that
//! bone's local frame); its world position is `component_to_world · global(bone) · offset`.
//! Its *height* is its world z minus [`Ground::ground_below`] at its position.
//!
//! - **Grounded contact**: `|height| ≤ 1.5 cm` ([`GROUNDED_TOLERANCE_CM`]).
//! - **Planted foot**: the foot's lowest contact (smallest height) is grounded for at
//!   least 3 consecutive frames ([`MIN_PLANTED_FRAMES`]); the maximal run of such frames is
//!   a *planted span* (stance). A frame flagged [`FrameRecord::teleported`] starts a new
//!   run. Frames whose values are missing or not finite are not grounded.
//! - **Skate** of a stance: for each contact point of the foot, each maximal run of frames
//!   inside the span during which *that contact* stays grounded, the largest horizontal
//!   (world XY) distance of the contact from where it was at the run's first frame; the
//!   stance's skate is the largest of these over the foot's contacts. A heel-to-ball roll
//!   is not skating: the heel is measured while the heel is down, the ball while the ball
//!   is down, and a pivot point does not move. The only cost of a pure roll is the small
//!   horizontal creep of a point while it is still inside the 1.5 cm band: for a point
//!   15 cm from the pivot, at most `15 · (1 − cos(asin(1.5 / 15))) ≈ 0.075 cm`. A foot
//!   yawing about its ball while flat does count: its heel is grounded and slides.
//!   `skate_cm_per_stance_max` / `_mean` are the maximum / mean over all stances
//!   (0 when there is none).
//! - **Penetration**: the largest `ground − contact z` over frames and contacts, 0 if no
//!   contact ever goes below the ground.
//! - **Idle float**: the largest height of a foot's lowest contact above the ground over
//!   frames where [`FrameRecord::standing_still`] has been true for more than 1 s
//!   ([`IDLE_SETTLE_S`], measured with [`FrameRecord::time`] from the first frame of the
//!   still run) — the feet had time to settle. Never negative.
//! - **Crossing frames**: frames where a left foot is to the right of a right foot in the
//!   character's facing frame: the smallest rig-space x of the left foot bones is less
//!   than the largest rig-space x of the right foot bones (rig space *is* the facing frame:
//!   `component_to_world`'s rotation maps it to the world).
//! - **Backward knees**: for each leg, `bend = knee − (closest point to the knee on the
//!   infinite line hip → foot)` in rig space. The foot's forward is the rig +Y direction
//!   at rest carried by the foot's current rotation:
//!   `rotation(foot) · rest_rotation(foot)⁻¹ · (0, 1, 0)` (3D, not flattened, so a lifted
//!   leg is judged against a lifted foot). The knee is backward when
//!   `bend · forward < −0.1 · |bend|` (it points more than ≈ 96° away from the foot's
//!   forward, [`KNEE_BACKWARD_COS`]); legs with `|bend| < 0.5 cm` are straight and ignored
//!   ([`STRAIGHT_LEG_BEND_CM`]). A frame counts once however many knees are backward.
//! - **Leg over-extension frames**: frames where a planted leg is at or past full reach,
//!   `|hip − foot| ≥ rest |hip − knee| + rest |knee − foot| − 0.05 cm`
//!   ([`REACH_MARGIN_CM`]). The IK target is graph state the report does not see; a leg at
//!   full reach is the pose-only sign that the IK could not reach it and the foot misses
//!   its target. A frame counts once however many legs are over-extended.
//! - **Pops**: the largest per-frame jump of any bone's world position relative to the
//!   root bone (bone 0) — a *jump* being a change of motion, not motion itself: a planted
//!   foot under a body running at 400 cm/s moves 6.7 cm per 60 Hz frame relative to the
//!   root without popping. With `u(t) = ((p_b − p_root)(t) − (p_b − p_root)(t−1)) / dt(t)`
//!   the bone's velocity relative to the root, the pop at `t` is
//!   `|u(t) − u(t−1)| · (1/60)² / mean(dt(t), dt(t−1))`, in cm per 60 Hz frame: a bone
//!   that jumps J cm in one 60 Hz frame and stays scores J, smooth motion with relative
//!   acceleration a scores `a / 60²` at every frame rate. Triples of frames containing a
//!   `dt ≤ 0` (or not finite) frame, a frame flagged `teleported` (other than the first of
//!   the three) or a non-finite value are skipped.
//! - **Non-finite values**: the number of NaN or infinite components (translation 3,
//!   rotation 4, scale 3 per transform) in all globals and all component-to-world
//!   transforms.
//! - **Steps**: every planted span start is a plant; the first plant of each foot (the
//!   initial stance) is not a step, every later one is. `cadence_steps_per_min` is
//!   `steps / moving time · 60`, where the moving time is the sum of `dt` over frames that
//!   are not standing still (0 when there is no moving time).
//! - **Step length**: for each step, the horizontal (world XY) distance from the foot
//!   bone's position at the step's first planted frame to the foot bone's position at the
//!   first planted frame of the most recent earlier plant of another foot (for a biped,
//!   the other foot). That is step length, not stride, and being a plain XY distance it
//!   includes the step width. `mean_step_length_cm` is the mean over steps that have such
//!   an earlier plant (0 when none).
//! - `duration_s` is the last frame's time minus the first's; `hz` is
//!   `(frames − 1) / duration_s` (0 when the duration is not positive).
//!
//! Frames with fewer globals than the skeleton has bones are malformed: they count for
//! `frames`, `duration_s`, `hz`, `nonfinite_values` and moving time, and are skipped by the
//! geometric metrics (a malformed frame is not grounded).

use glam::{Vec2, Vec3};
use serde::Serialize;
use std::collections::HashMap;
use std::fmt::Write as _;
use strider_core::{BoneIndex, Transform};
use strider_graph::SkeletonFile;

#[cfg(test)]
mod tests;

/// A contact point is grounded while `|height above ground| ≤` this, cm.
pub const GROUNDED_TOLERANCE_CM: f32 = 1.5;
/// A foot is planted after its lowest contact has been grounded this many consecutive
/// frames.
pub const MIN_PLANTED_FRAMES: usize = 3;
/// Idle float is measured once the character has stood still for more than this, s.
pub const IDLE_SETTLE_S: f64 = 1.0;
/// A leg whose knee is closer than this to the hip → foot line is straight, cm.
pub const STRAIGHT_LEG_BEND_CM: f32 = 0.5;
/// A knee is backward when the cosine between its bend and the foot's forward is below
/// this (≈ 96°).
pub const KNEE_BACKWARD_COS: f32 = -0.1;
/// A leg is at full reach when hip → foot is within this of the rest bone lengths' sum, cm.
pub const REACH_MARGIN_CM: f32 = 0.05;
/// Pops are normalised to a frame at this rate, Hz.
pub const REFERENCE_HZ: f32 = 60.0;
/// How far above a point [`Ground::ground_below`] starts searching, cm ([`FlatGround`]
/// follows it; the host's world does the same with a downward trace).
pub const GROUND_SEARCH_ABOVE_CM: f32 = 50.0;

/// Which side of the character a foot is on (rest-pose rig-space x: > 0 is left).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum Side {
    /// The character's left (+X in rig space).
    Left,
    /// The character's right (−X in rig space).
    Right,
}

/// A sole contact point of a foot: an offset in the foot bone's local frame, cm.
#[derive(Clone, Debug, PartialEq)]
pub struct FootContact {
    /// Its name in the skeleton file (`heel_l`).
    pub name: String,
    /// Offset in the foot bone's local frame, cm.
    pub offset: Vec3,
}

/// One leg: the foot bone (the bone carrying contact points), its parent (the knee) and
/// grandparent (the hip), with rest measurements. Bone indices are skeleton storage
/// order, as [`FrameRecord::globals`].
#[derive(Clone, Debug, PartialEq)]
pub struct Leg {
    /// The foot bone's name.
    pub name: String,
    /// Left if the foot's rest rig-space x is > 0.
    pub side: Side,
    /// The hip (thigh) bone: the foot's grandparent.
    pub hip: usize,
    /// The knee (calf) bone: the foot's parent.
    pub knee: usize,
    /// The foot bone.
    pub foot: usize,
    /// The foot's sole contact points (at least one).
    pub contacts: Vec<FootContact>,
    /// Rest distance hip → knee, cm.
    pub upper_length: f32,
    /// Rest distance knee → foot, cm.
    pub lower_length: f32,
    /// Rig +Y expressed in the foot bone's rest frame (unit): the foot's forward is
    /// `rotation(foot) · forward_local`.
    pub forward_local: Vec3,
}

/// What the report needs to know about a skeleton: bone count, root, pelvis and legs.
#[derive(Clone, Debug, PartialEq)]
pub struct ReportRig {
    /// Bone names in storage order.
    pub bone_names: Vec<String>,
    /// The root bone (bone 0); pops are measured relative to it.
    pub root: usize,
    /// The bone plotted as the pelvis: the bone called `pelvis`, else the first hip's
    /// parent, else the root.
    pub pelvis: usize,
    /// The legs, in the order their feet first appear in the skeleton file's contacts.
    pub legs: Vec<Leg>,
}

/// Why a skeleton cannot be reported on.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ReportError {
    /// The skeleton file lists no contact points, so there are no feet.
    #[error(
        "skeleton `{0}` lists no sole contact points; the report finds the feet through `contacts`"
    )]
    NoContacts(String),
    /// A contact point names a bone the skeleton does not have.
    #[error("contact point `{contact}` is on unknown bone `{bone}`")]
    UnknownContactBone {
        /// The contact's name.
        contact: String,
        /// The missing bone.
        bone: String,
    },
    /// A foot bone lacks a parent (knee) or grandparent (hip).
    #[error("foot bone `{foot}` needs a parent (knee) and a grandparent (hip) to form a leg")]
    ChainTooShort {
        /// The foot bone's name.
        foot: String,
    },
}

impl ReportRig {
    /// Finds the legs of a skeleton: the feet are the bones carrying contact points, each
    /// leg is foot → parent (knee) → grandparent (hip); the root is bone 0.
    ///
    /// # Errors
    /// No contact points, a contact on an unknown bone, or a foot without a grandparent.
    pub fn from_skeleton(file: &SkeletonFile) -> Result<Self, ReportError> {
        let skel = &file.skeleton;
        if file.contacts.is_empty() {
            return Err(ReportError::NoContacts(file.name.clone()));
        }
        let rest = skel.rest_globals();
        let mut legs: Vec<Leg> = Vec::new();
        for c in &file.contacts {
            let foot = skel
                .find(&c.bone)
                .ok_or_else(|| ReportError::UnknownContactBone {
                    contact: c.name.clone(),
                    bone: c.bone.clone(),
                })?;
            let contact = FootContact {
                name: c.name.clone(),
                offset: c.offset,
            };
            if let Some(leg) = legs.iter_mut().find(|l| l.foot == foot.get()) {
                leg.contacts.push(contact);
                continue;
            }
            let too_short = || ReportError::ChainTooShort {
                foot: c.bone.clone(),
            };
            let knee = skel.parent(foot).ok_or_else(too_short)?;
            let hip = skel.parent(knee).ok_or_else(too_short)?;
            let (f, k, h) = (foot.get(), knee.get(), hip.get());
            let forward = rest[f].rotation.inverse() * Vec3::Y;
            legs.push(Leg {
                name: c.bone.clone(),
                side: if rest[f].translation.x > 0.0 {
                    Side::Left
                } else {
                    Side::Right
                },
                hip: h,
                knee: k,
                foot: f,
                contacts: vec![contact],
                upper_length: (rest[k].translation - rest[h].translation).length(),
                lower_length: (rest[f].translation - rest[k].translation).length(),
                forward_local: forward.try_normalize().unwrap_or(Vec3::Y),
            });
        }
        let pelvis = skel
            .find("pelvis")
            .or_else(|| {
                let hip = legs.first()?.hip;
                skel.parent(BoneIndex(u32::try_from(hip).ok()?))
            })
            .map_or(0, BoneIndex::get);
        Ok(Self {
            bone_names: skel.names().to_vec(),
            root: 0,
            pelvis,
            legs,
        })
    }

    /// Number of globals a [`FrameRecord`] must hold to be analysed: the skeleton's bone
    /// count (or more, if the public fields were edited to name a bone beyond it).
    #[must_use]
    pub fn bone_count(&self) -> usize {
        let highest = self
            .legs
            .iter()
            .flat_map(|l| [l.hip, l.knee, l.foot])
            .chain([self.root, self.pelvis])
            .max()
            .unwrap_or(0);
        self.bone_names.len().max(highest.saturating_add(1))
    }
}

/// One recorded output frame.
#[derive(Clone, Debug, PartialEq)]
pub struct FrameRecord {
    /// Time of the frame, s (frame `k` of a run at `hz` is at `k / hz`).
    pub time: f64,
    /// Seconds since the previous frame (the `DeltaTime` the graph saw).
    pub dt: f32,
    /// Rig (component) space → world, cm.
    pub component_to_world: Transform,
    /// The host's "no movement input and no velocity" flag for this frame.
    pub standing_still: bool,
    /// The host moved the character discontinuously this frame (respawn, teleport):
    /// pops are not measured into it and planted spans break at it.
    pub teleported: bool,
    /// Rig-space global transform of every bone, skeleton storage order, cm.
    pub globals: Vec<Transform>,
}

impl FrameRecord {
    /// World position of `bone` (cm), `None` if the frame has no such bone.
    #[must_use]
    pub fn world_position(&self, bone: usize) -> Option<Vec3> {
        self.globals
            .get(bone)
            .map(|g| self.component_to_world.transform_point(g.translation))
    }
}

/// The world's ground, as the report sees it.
pub trait Ground {
    /// World height (z, cm) of the first surface below the world point `p`, searching
    /// downward from a little above it ([`GROUND_SEARCH_ABOVE_CM`]) so a contact slightly
    /// below the surface still finds it; `None` when there is nothing below.
    fn ground_below(&self, p: Vec3) -> Option<f32>;
}

/// An infinite horizontal ground plane at this world height, cm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FlatGround(pub f32);

impl Ground for FlatGround {
    /// The plane's height, or `None` for a point more than [`GROUND_SEARCH_ABOVE_CM`]
    /// below it (the search starts above the point, as a trace would).
    fn ground_below(&self, p: Vec3) -> Option<f32> {
        (self.0 <= p.z + GROUND_SEARCH_ABOVE_CM).then_some(self.0)
    }
}

impl<F: Fn(Vec3) -> Option<f32>> Ground for F {
    fn ground_below(&self, p: Vec3) -> Option<f32> {
        self(p)
    }
}

/// The report: one number per metric. Lengths in cm, times in s; see the
/// [module docs](self) for the exact definitions.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Report {
    /// Number of frames analysed.
    pub frames: usize,
    /// Last frame's time minus the first's, s.
    pub duration_s: f64,
    /// Mean frame rate, `(frames − 1) / duration_s`, Hz.
    pub hz: f64,
    /// Largest skate of a stance, cm.
    pub skate_cm_per_stance_max: f32,
    /// Mean skate over stances, cm.
    pub skate_cm_per_stance_mean: f32,
    /// The foot of the stance with the largest skate (`None` without stances).
    pub skate_foot: Option<String>,
    /// When that stance starts, s (`None` without stances).
    pub skate_time_s: Option<f64>,
    /// Deepest contact below the ground, cm.
    pub penetration_cm_max: f32,
    /// Highest lowest-contact above the ground after standing still > 1 s, cm.
    pub idle_float_cm_max: f32,
    /// Frames with a left foot to the right of a right foot.
    pub crossing_frames: usize,
    /// Frames with a knee bent against its foot's forward.
    pub knee_backward_frames: usize,
    /// Frames with a planted leg at or past full reach.
    pub leg_overextension_frames: usize,
    /// Largest bone jump relative to the root, cm per 60 Hz frame.
    pub pop_cm_per_frame_max: f32,
    /// The bone of the largest pop (`None` when nothing was measured).
    pub pop_bone: Option<String>,
    /// The time of the frame of the largest pop, s (`None` when nothing was measured).
    pub pop_time_s: Option<f64>,
    /// NaN or infinite components in globals and component-to-world transforms.
    pub nonfinite_values: usize,
    /// Planted-span starts after each foot's first.
    pub steps: usize,
    /// Steps per minute of moving (not standing still) time.
    pub cadence_steps_per_min: f32,
    /// Mean horizontal distance from a step's plant to the previous plant of another
    /// foot, cm.
    pub mean_step_length_cm: f32,
    /// Largest distance between a bone's world positions at the same time in runs at
    /// different frame rates, cm ([`framerate_deviation`]); `None` until the caller fills
    /// it.
    pub framerate_deviation_cm_max: Option<f32>,
}

/// One metric checked against its target (all targets are upper bounds).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TargetCheck {
    /// The metric's key in the report's JSON.
    pub metric: &'static str,
    /// Its value.
    pub value: f64,
    /// The largest acceptable value.
    pub target: f64,
    /// Unit of value and target.
    pub unit: &'static str,
    /// `value ≤ target` (false for NaN).
    pub met: bool,
}

/// Target: largest skate of a stance, cm.
pub const TARGET_SKATE_CM: f64 = 0.5;
/// Target: deepest penetration, cm.
pub const TARGET_PENETRATION_CM: f64 = 0.5;
/// Target: idle float, cm.
pub const TARGET_IDLE_FLOAT_CM: f64 = 0.5;
/// Target: largest pop, cm per 60 Hz frame.
pub const TARGET_POP_CM: f64 = 5.0;
/// Target: frame-rate deviation, cm.
pub const TARGET_FRAMERATE_DEVIATION_CM: f64 = 1.0;

impl Report {
    /// Every metric that has a target, with its value and whether it is met. The
    /// frame-rate deviation is included only once measured.
    #[must_use]
    pub fn targets_met(&self) -> Vec<TargetCheck> {
        let check = |metric, value: f64, target, unit| TargetCheck {
            metric,
            value,
            target,
            unit,
            met: value <= target,
        };
        let mut v = vec![
            check(
                "skate_cm_per_stance_max",
                f64::from(self.skate_cm_per_stance_max),
                TARGET_SKATE_CM,
                "cm",
            ),
            check(
                "penetration_cm_max",
                f64::from(self.penetration_cm_max),
                TARGET_PENETRATION_CM,
                "cm",
            ),
            check(
                "idle_float_cm_max",
                f64::from(self.idle_float_cm_max),
                TARGET_IDLE_FLOAT_CM,
                "cm",
            ),
            check(
                "crossing_frames",
                self.crossing_frames as f64,
                0.0,
                "frames",
            ),
            check(
                "knee_backward_frames",
                self.knee_backward_frames as f64,
                0.0,
                "frames",
            ),
            check(
                "pop_cm_per_frame_max",
                f64::from(self.pop_cm_per_frame_max),
                TARGET_POP_CM,
                "cm/frame@60Hz",
            ),
            check("nonfinite_values", self.nonfinite_values as f64, 0.0, ""),
        ];
        if let Some(d) = self.framerate_deviation_cm_max {
            v.push(check(
                "framerate_deviation_cm_max",
                f64::from(d),
                TARGET_FRAMERATE_DEVIATION_CM,
                "cm",
            ));
        }
        v
    }

    /// True when every target in [`Report::targets_met`] is met.
    #[must_use]
    pub fn all_targets_met(&self) -> bool {
        self.targets_met().iter().all(|c| c.met)
    }

    /// The report as pretty-printed JSON, keys as the field names. Non-finite numbers
    /// become `null`.
    ///
    /// # Errors
    /// Only if serde_json fails to serialise plain numbers (it does not in practice).
    pub fn to_json(&self) -> Result<String, serde_json::Error> {
        serde_json::to_string_pretty(self)
    }

    /// An aligned, human-readable table: metric, value with unit, target and PASS/FAIL.
    #[must_use]
    pub fn table(&self) -> String {
        struct Row {
            name: &'static str,
            value: String,
            target: String,
            result: &'static str,
        }
        let verdict = |met: bool| if met { "pass" } else { "FAIL" };
        let mut rows = Vec::new();
        let mut push = |name, value: String, target: Option<(f64, &str)>, value_f: f64| {
            let (target, result) = match target {
                Some((t, unit)) => (
                    format!("≤ {t} {unit}").trim_end().to_string(),
                    verdict(value_f <= t),
                ),
                None => (String::from("—"), ""),
            };
            rows.push(Row {
                name,
                value,
                target,
                result,
            });
        };
        let cm = |v: f32| format!("{v:.3} cm");
        push(
            "skate per stance, max",
            cm(self.skate_cm_per_stance_max),
            Some((TARGET_SKATE_CM, "cm")),
            f64::from(self.skate_cm_per_stance_max),
        );
        if let (Some(foot), Some(time)) = (&self.skate_foot, self.skate_time_s) {
            push(
                "  largest at",
                format!("{foot}, stance from {time:.2} s"),
                None,
                0.0,
            );
        }
        push(
            "skate per stance, mean",
            cm(self.skate_cm_per_stance_mean),
            None,
            0.0,
        );
        push(
            "ground penetration, max",
            cm(self.penetration_cm_max),
            Some((TARGET_PENETRATION_CM, "cm")),
            f64::from(self.penetration_cm_max),
        );
        push(
            "idle float, max",
            cm(self.idle_float_cm_max),
            Some((TARGET_IDLE_FLOAT_CM, "cm")),
            f64::from(self.idle_float_cm_max),
        );
        push(
            "crossed feet",
            format!("{} frames", self.crossing_frames),
            Some((0.0, "frames")),
            self.crossing_frames as f64,
        );
        push(
            "backward knees",
            format!("{} frames", self.knee_backward_frames),
            Some((0.0, "frames")),
            self.knee_backward_frames as f64,
        );
        push(
            "planted leg at full reach",
            format!("{} frames", self.leg_overextension_frames),
            None,
            0.0,
        );
        push(
            "pops, max",
            format!("{:.3} cm/60 Hz frame", self.pop_cm_per_frame_max),
            Some((TARGET_POP_CM, "cm/60 Hz frame")),
            f64::from(self.pop_cm_per_frame_max),
        );
        if let (Some(bone), Some(time)) = (&self.pop_bone, self.pop_time_s) {
            push("  largest at", format!("{bone}, {time:.2} s"), None, 0.0);
        }
        push(
            "non-finite values",
            format!("{}", self.nonfinite_values),
            Some((0.0, "")),
            self.nonfinite_values as f64,
        );
        match self.framerate_deviation_cm_max {
            Some(d) => push(
                "frame-rate deviation, max",
                cm(d),
                Some((TARGET_FRAMERATE_DEVIATION_CM, "cm")),
                f64::from(d),
            ),
            None => push(
                "frame-rate deviation, max",
                String::from("not measured"),
                None,
                0.0,
            ),
        }
        push("steps", format!("{}", self.steps), None, 0.0);
        push(
            "cadence",
            format!("{:.1} steps/min", self.cadence_steps_per_min),
            None,
            0.0,
        );
        push(
            "mean step length",
            format!("{:.2} cm", self.mean_step_length_cm),
            None,
            0.0,
        );

        let w0 = rows
            .iter()
            .map(|r| r.name.chars().count())
            .max()
            .unwrap_or(0);
        let w1 = rows
            .iter()
            .map(|r| r.value.chars().count())
            .max()
            .unwrap_or(0);
        let w2 = rows
            .iter()
            .map(|r| r.target.chars().count())
            .max()
            .unwrap_or(0)
            .max("target".len());
        let mut out = format!(
            "locomotion report: {} frames, {:.3} s, {:.1} Hz\n",
            self.frames, self.duration_s, self.hz
        );
        let _ = writeln!(
            out,
            "{:<w0$}  {:>w1$}  {:<w2$}  result",
            "metric", "value", "target"
        );
        for r in &rows {
            let line = format!(
                "{:<w0$}  {:>w1$}  {:<w2$}  {}",
                r.name, r.value, r.target, r.result
            );
            let _ = writeln!(out, "{}", line.trim_end());
        }
        out
    }
}

/// A planted span (stance) of one leg.
#[derive(Clone, Debug, PartialEq)]
pub struct PlantSpan {
    /// Index into [`ReportRig::legs`].
    pub leg: usize,
    /// First planted frame (index into the frames).
    pub start: usize,
    /// Last planted frame, inclusive.
    pub end: usize,
    /// The stance's skate, cm (see the module docs).
    pub skate_cm: f32,
    /// World XY of the foot bone at the first planted frame, cm.
    pub position: Vec2,
}

/// One contact point in one frame.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ContactSample {
    /// World position, cm.
    pub world: Vec3,
    /// Height above the ground below it, cm; `None` without ground or finite values.
    pub height: Option<f32>,
}

/// One leg in one frame.
#[derive(Clone, Debug)]
pub(crate) struct LegSample {
    /// Foot bone's world position, cm.
    pub foot_world: Vec3,
    pub contacts: Vec<ContactSample>,
    /// Smallest contact height, cm.
    pub lowest: Option<f32>,
}

/// Per-frame world samples of every leg; `None` for a malformed frame.
pub(crate) struct Samples {
    pub frames: Vec<Option<Vec<LegSample>>>,
}

fn grounded(h: Option<f32>) -> bool {
    h.is_some_and(|h| h.abs() <= GROUNDED_TOLERANCE_CM)
}

fn height_above(ground: &dyn Ground, p: Vec3) -> Option<f32> {
    if !p.is_finite() {
        return None;
    }
    let g = ground.ground_below(p)?;
    let h = p.z - g;
    h.is_finite().then_some(h)
}

impl Samples {
    pub fn new(rig: &ReportRig, frames: &[FrameRecord], ground: &dyn Ground) -> Self {
        let bone_count = rig.bone_count();
        let frames = frames
            .iter()
            .map(|f| {
                if f.globals.len() < bone_count {
                    return None;
                }
                let c2w = f.component_to_world;
                Some(
                    rig.legs
                        .iter()
                        .map(|leg| {
                            let g = f.globals[leg.foot];
                            let contacts: Vec<ContactSample> = leg
                                .contacts
                                .iter()
                                .map(|c| {
                                    let world = c2w.transform_point(g.transform_point(c.offset));
                                    ContactSample {
                                        world,
                                        height: height_above(ground, world),
                                    }
                                })
                                .collect();
                            let lowest = contacts
                                .iter()
                                .filter_map(|c| c.height)
                                .min_by(f32::total_cmp);
                            LegSample {
                                foot_world: c2w.transform_point(g.translation),
                                contacts,
                                lowest,
                            }
                        })
                        .collect(),
                )
            })
            .collect();
        Self { frames }
    }

    fn leg(&self, t: usize, leg: usize) -> Option<&LegSample> {
        self.frames.get(t)?.as_ref()?.get(leg)
    }

    /// Planted spans of every leg, in order of leg then start frame.
    pub fn spans(&self, rig: &ReportRig, records: &[FrameRecord]) -> Vec<PlantSpan> {
        let mut spans = Vec::new();
        let n = self.frames.len();
        for leg in 0..rig.legs.len() {
            let mut run_start: Option<usize> = None;
            for t in 0..n {
                let down = grounded(self.leg(t, leg).and_then(|l| l.lowest));
                let teleported = records.get(t).is_some_and(|r| r.teleported);
                if let Some(s) = run_start
                    && (!down || teleported)
                {
                    if t - s >= MIN_PLANTED_FRAMES {
                        spans.push(self.span(leg, s, t - 1));
                    }
                    run_start = None;
                }
                if down && run_start.is_none() {
                    run_start = Some(t);
                }
            }
            if let Some(s) = run_start
                && n - s >= MIN_PLANTED_FRAMES
            {
                spans.push(self.span(leg, s, n - 1));
            }
        }
        spans
    }

    fn span(&self, leg: usize, start: usize, end: usize) -> PlantSpan {
        let mut skate = 0.0f32;
        let n_contacts = self.leg(start, leg).map_or(0, |l| l.contacts.len());
        for c in 0..n_contacts {
            let mut anchor: Option<Vec2> = None;
            for t in start..=end {
                let Some(sample) = self.leg(t, leg).and_then(|l| l.contacts.get(c)) else {
                    anchor = None;
                    continue;
                };
                if !grounded(sample.height) {
                    anchor = None;
                    continue;
                }
                let xy = sample.world.truncate();
                match anchor {
                    None => anchor = Some(xy),
                    Some(a) => skate = skate.max(xy.distance(a)),
                }
            }
        }
        let position = self
            .leg(start, leg)
            .map_or(Vec2::ZERO, |l| l.foot_world.truncate());
        PlantSpan {
            leg,
            start,
            end,
            skate_cm: skate,
            position,
        }
    }
}

/// The planted spans (stances) of every leg, ordered by leg then start frame; see the
/// module docs for the definition.
#[must_use]
pub fn plant_spans(rig: &ReportRig, frames: &[FrameRecord], ground: &dyn Ground) -> Vec<PlantSpan> {
    Samples::new(rig, frames, ground).spans(rig, frames)
}

fn count_nonfinite(t: &Transform) -> usize {
    let comps = t
        .translation
        .to_array()
        .into_iter()
        .chain(t.rotation.to_array())
        .chain(t.scale.to_array());
    comps.filter(|v| !v.is_finite()).count()
}

fn frame_finite(f: &FrameRecord) -> bool {
    f.component_to_world.is_finite() && f.globals.iter().all(Transform::is_finite)
}

/// Analyses a recording. `frames` are in time order; `ground` answers for the world the
/// recording was made in. Never panics: missing or non-finite values are skipped (and
/// counted in `nonfinite_values`). See the [module docs](self) for the definitions.
#[must_use]
pub fn analyse(rig: &ReportRig, frames: &[FrameRecord], ground: &dyn Ground) -> Report {
    let samples = Samples::new(rig, frames, ground);
    let spans = samples.spans(rig, frames);
    let bone_count = rig.bone_count();

    let (duration_s, hz) = match (frames.first(), frames.last()) {
        (Some(a), Some(b)) if (b.time - a.time).is_finite() && b.time > a.time => {
            let d = b.time - a.time;
            (d, (frames.len() - 1) as f64 / d)
        }
        _ => (0.0, 0.0),
    };

    let skate_max = spans.iter().map(|s| s.skate_cm).fold(0.0f32, f32::max);
    // The first stance with the largest skate.
    let worst = spans.iter().fold(None::<&PlantSpan>, |w, s| match w {
        Some(w) if w.skate_cm >= s.skate_cm => Some(w),
        _ => Some(s),
    });
    let skate_mean = if spans.is_empty() {
        0.0
    } else {
        spans.iter().map(|s| s.skate_cm).sum::<f32>() / spans.len() as f32
    };

    let mut penetration = 0.0f32;
    for legs in samples.frames.iter().flatten() {
        for c in legs.iter().flat_map(|l| &l.contacts) {
            if let Some(h) = c.height {
                penetration = penetration.max(-h);
            }
        }
    }

    let mut idle_float = 0.0f32;
    let mut still_since: Option<f64> = None;
    for (f, legs) in frames.iter().zip(&samples.frames) {
        if !f.standing_still {
            still_since = None;
            continue;
        }
        let since = *still_since.get_or_insert(f.time);
        if f.time - since > IDLE_SETTLE_S
            && let Some(legs) = legs
        {
            for h in legs.iter().filter_map(|l| l.lowest) {
                idle_float = idle_float.max(h);
            }
        }
    }

    let mut planted = vec![vec![false; frames.len()]; rig.legs.len()];
    for s in &spans {
        planted[s.leg][s.start..=s.end].fill(true);
    }

    let mut crossing = 0;
    let mut knee_backward = 0;
    let mut overextended = 0;
    for (t, f) in frames.iter().enumerate() {
        if f.globals.len() < bone_count {
            continue;
        }
        let g = &f.globals;
        let x_of = |side| {
            rig.legs
                .iter()
                .filter(move |l| l.side == side)
                .map(|l| g[l.foot].translation.x)
                .filter(|x| x.is_finite())
        };
        let left_min = x_of(Side::Left).reduce(f32::min);
        let right_max = x_of(Side::Right).reduce(f32::max);
        if let (Some(l), Some(r)) = (left_min, right_max)
            && l < r
        {
            crossing += 1;
        }

        let mut backward = false;
        let mut over = false;
        for (i, leg) in rig.legs.iter().enumerate() {
            let hip = g[leg.hip].translation;
            let knee = g[leg.knee].translation;
            let foot = g[leg.foot];
            let line = foot.translation - hip;
            if let Some(dir) = line.try_normalize() {
                let closest = hip + dir * (knee - hip).dot(dir);
                let bend = knee - closest;
                let len = bend.length();
                let forward = foot.rotation * leg.forward_local;
                if len >= STRAIGHT_LEG_BEND_CM
                    && forward.is_finite()
                    && bend.dot(forward) < KNEE_BACKWARD_COS * len * forward.length()
                {
                    backward = true;
                }
            }
            if planted[i][t]
                && line.length() >= leg.upper_length + leg.lower_length - REACH_MARGIN_CM
            {
                over = true;
            }
        }
        knee_backward += usize::from(backward);
        overextended += usize::from(over);
    }

    let mut pop = 0.0f32;
    let mut pop_at: Option<(usize, usize)> = None;
    let usable = |t: usize| {
        let f = &frames[t];
        f.dt > 0.0 && f.dt.is_finite() && !f.teleported && samples.frames[t].is_some()
    };
    for t in 2..frames.len() {
        let (f0, f1, f2) = (&frames[t - 2], &frames[t - 1], &frames[t]);
        if !usable(t - 1)
            || !usable(t)
            || samples.frames[t - 2].is_none()
            || !frame_finite(f0)
            || !frame_finite(f1)
            || !frame_finite(f2)
        {
            continue;
        }
        // Change of the bone's velocity relative to the root, cm/s, times the square of a
        // 60 Hz frame over the mean frame time: rate independent for smooth motion.
        let scale = (1.0 / REFERENCE_HZ) * (1.0 / REFERENCE_HZ) / (0.5 * (f1.dt + f2.dt));
        let root = |f: &FrameRecord| f.world_position(rig.root).unwrap_or(Vec3::ZERO);
        let (r0, r1, r2) = (root(f0), root(f1), root(f2));
        for b in 0..bone_count {
            if let (Some(p0), Some(p1), Some(p2)) = (
                f0.world_position(b),
                f1.world_position(b),
                f2.world_position(b),
            ) {
                let before = ((p1 - r1) - (p0 - r0)) / f1.dt;
                let after = ((p2 - r2) - (p1 - r1)) / f2.dt;
                let jump = (after - before).length() * scale;
                if jump.is_finite() && (pop_at.is_none() || jump > pop) {
                    pop = jump;
                    pop_at = Some((b, t));
                }
            }
        }
    }

    let nonfinite: usize = frames
        .iter()
        .map(|f| {
            count_nonfinite(&f.component_to_world)
                + f.globals.iter().map(count_nonfinite).sum::<usize>()
        })
        .sum();

    // Plants in time order (by start frame, then leg).
    let mut plants: Vec<&PlantSpan> = spans.iter().collect();
    plants.sort_by_key(|s| (s.start, s.leg));
    let mut seen = vec![false; rig.legs.len()];
    let mut steps = 0usize;
    let mut lengths = Vec::new();
    for (i, p) in plants.iter().enumerate() {
        if !seen[p.leg] {
            seen[p.leg] = true;
            continue;
        }
        steps += 1;
        let previous_other = plants[..i]
            .iter()
            .rev()
            .find(|q| q.leg != p.leg && q.start < p.start);
        if let Some(q) = previous_other {
            let d = p.position.distance(q.position);
            if d.is_finite() {
                lengths.push(d);
            }
        }
    }
    let moving_time: f64 = frames
        .iter()
        .filter(|f| !f.standing_still && f.dt.is_finite() && f.dt > 0.0)
        .map(|f| f64::from(f.dt))
        .sum();
    let cadence = if moving_time > 0.0 {
        (steps as f64 / moving_time * 60.0) as f32
    } else {
        0.0
    };
    let mean_step = if lengths.is_empty() {
        0.0
    } else {
        lengths.iter().sum::<f32>() / lengths.len() as f32
    };

    Report {
        frames: frames.len(),
        duration_s,
        hz,
        skate_cm_per_stance_max: skate_max,
        skate_cm_per_stance_mean: skate_mean,
        skate_foot: worst.and_then(|w| rig.legs.get(w.leg).map(|l| l.name.clone())),
        skate_time_s: worst.and_then(|w| frames.get(w.start).map(|f| f.time)),
        penetration_cm_max: penetration,
        idle_float_cm_max: idle_float,
        crossing_frames: crossing,
        knee_backward_frames: knee_backward,
        leg_overextension_frames: overextended,
        pop_cm_per_frame_max: pop,
        pop_bone: pop_at.and_then(|(b, _)| rig.bone_names.get(b).cloned()),
        pop_time_s: pop_at.map(|(_, t)| frames[t].time),
        nonfinite_values: nonfinite,
        steps,
        cadence_steps_per_min: cadence,
        mean_step_length_cm: mean_step,
        framerate_deviation_cm_max: None,
    }
}

fn gcd(a: u64, b: u64) -> u64 {
    if b == 0 { a } else { gcd(b, a % b) }
}

/// The largest distance (cm) between the same bone's world positions at the same time
/// in runs of the same scenario at different frame rates.
///
/// Each run is `(hz, frames)`; a frame's integer index is `round(time · hz)` (frame `k`
/// at `hz` is at time `k / hz`), so common times are found exactly: with `g` the GCD of
/// the rates, time `m / g` is frame `m · hz / g` of every run (for 30/60/144/240 Hz,
/// `g` = 6: every 1/6 s). At each common time present in every run, every pair of runs is
/// compared bone by bone (up to the smaller bone count). Runs at 0 Hz, frames whose time
/// is not within 0.001 frame of an integer index and non-finite positions are skipped;
/// fewer than two runs, or no common time, give 0.
#[must_use]
pub fn framerate_deviation(runs: &[(u32, &[FrameRecord])]) -> f32 {
    let runs: Vec<(u64, &[FrameRecord])> = runs
        .iter()
        .filter(|(hz, _)| *hz > 0)
        .map(|&(hz, f)| (u64::from(hz), f))
        .collect();
    if runs.len() < 2 {
        return 0.0;
    }
    let g = runs.iter().fold(0, |g, &(hz, _)| gcd(g, hz));
    let index: Vec<HashMap<i64, usize>> = runs
        .iter()
        .map(|&(hz, frames)| {
            frames
                .iter()
                .enumerate()
                .filter_map(|(i, f)| {
                    let k = f.time * hz as f64;
                    let kr = k.round();
                    (k.is_finite() && (k - kr).abs() <= 1e-3).then_some((kr as i64, i))
                })
                .collect()
        })
        .collect();
    let (hz0, _) = runs[0];
    let step0 = (hz0 / g) as i64;
    let mut worst = 0.0f32;
    let mut at: Vec<&FrameRecord> = Vec::with_capacity(runs.len());
    for &k0 in index[0].keys() {
        if k0.rem_euclid(step0) != 0 {
            continue;
        }
        let m = k0 / step0;
        at.clear();
        for (j, &(hz, frames)) in runs.iter().enumerate() {
            let k = m.checked_mul((hz / g) as i64);
            if let Some(&i) = k.and_then(|k| index[j].get(&k)) {
                at.push(&frames[i]);
            }
        }
        if at.len() != runs.len() {
            continue;
        }
        for a in 0..at.len() {
            for b in a + 1..at.len() {
                let n = at[a].globals.len().min(at[b].globals.len());
                for bone in 0..n {
                    if let (Some(p), Some(q)) =
                        (at[a].world_position(bone), at[b].world_position(bone))
                    {
                        let d = p.distance(q);
                        if d.is_finite() {
                            worst = worst.max(d);
                        }
                    }
                }
            }
        }
    }
    worst
}
