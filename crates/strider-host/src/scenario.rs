//! Scenario files: a world, a start, optional mover settings and a timeline of inputs, run
//! at a chosen frame rate by [`Simulation`].
//!
//! # File format (`graphs/scenarios/*.ron`)
//!
//! ```ron
//! // walk_flat: stand 1 s, then walk straight along +Y at 150 cm/s.
//! (
//!     world: (shapes: [Ground(height: 0.0)]),
//!     start: (position: (0.0, 0.0, 0.0), yaw: 0.0),
//!     mover: (acceleration: 1000.0),            // optional; any field left out keeps its default
//!     timeline: [
//!         Stand(seconds: 1.0),
//!         Move(seconds: 6.0, heading: 0.0, speed: 150.0),
//!         Move(seconds: 2.0, direction: (1.0, 0.0), speed: 150.0, facing: Look(yaw: 0.0)),
//!         Arc(seconds: 4.0, speed: 150.0, heading: 0.0, radius: 300.0),
//!         Teleport(position: (500.0, 0.0, 0.0), yaw: 90.0),
//!         Hitch(seconds: 1.0),
//!         ZeroDt(frames: 3),
//!     ],
//! )
//! ```
//!
//! World space: +Z up, centimetres, seconds; yaw and headings in degrees, 0 = +Y, positive
//! counter-clockwise seen from above (90° = −X). Segments:
//!
//! - `Stand(seconds)`: ask to stand still (the mover brakes to a stop).
//! - `Move(seconds, direction: (x, y) | heading: deg, speed: cm/s, facing)`: move along a
//!   world XY direction (its length, clamped to 1, scales the speed) or a heading; exactly
//!   one of `direction` and `heading`. `facing` is `Velocity` (default: turn towards the
//!   velocity) or `Look(yaw: deg)` (face a fixed yaw: strafing).
//! - `Arc(seconds, speed, heading, turn_rate: deg/s | radius: cm, facing)`: the move
//!   direction starts at `heading` and turns at `turn_rate` (positive counter-clockwise),
//!   or at `speed / radius` (a circle of that radius; positive radius turns
//!   counter-clockwise); exactly one of `turn_rate` and `radius`.
//! - `Teleport(position, yaw)`: put the capsule bottom at `position` facing `yaw`, at once.
//! - `Hitch(seconds)`: the previous input continues for `seconds`, but the frames inside
//!   are not produced: one frame jumps over the whole span (a long `dt`).
//! - `ZeroDt(frames)`: `frames` extra frames with `dt = 0` repeating the current time.
//!
//! # Timing
//!
//! The mover always advances with a fixed internal step of `1/720` s ([`MOVER_RATE_HZ`];
//! 720 is divisible by 30, 60, 144 and 240) and each segment lasts
//! `round(seconds · 720)` steps, so its path is the same whatever the output frame rate.
//! Frames sample that path: frame tick `k` at `hz` sits at time `k / hz` and shows the mover
//! after `floor(k · 720 / hz)` steps. Ticks strictly inside a hitch are skipped (the first
//! tick at or after the hitch's end is the hitch frame, whose `dt` covers the gap);
//! zero-dt frames repeat the tick before them. The first frame is tick 0 with a nominal
//! `dt = 1 / hz`. A teleport takes effect at its step; the first frame at or after it is
//! flagged [`SimFrame::teleported`]. The mover is put on the floor ([`Mover::settle`]) at
//! the start and after each teleport, so those frames already stand on the ground.

use std::path::{Path, PathBuf};

use glam::{Vec2, Vec3};
use serde::Deserialize;
use serde::de::{self, Deserializer};
use strider_core::Transform;

use crate::mover::{Facing, MoveInput, Mover, MoverSettings, heading_vector};
use crate::world::{
    CheckedElement, World, WorldDesc, describe_ron_error, deserialize_checked_seq, ron_options,
};

/// Rate of the mover's fixed internal step, Hz.
pub const MOVER_RATE_HZ: u32 = 720;

/// Longest accepted scenario, seconds.
pub const MAX_SCENARIO_SECONDS: f64 = 3600.0;

/// Largest accepted output frame rate, Hz ([`Simulation::new`] clamps to 1..=this).
pub const MAX_HZ: u32 = 10_000;

/// Where the character starts. World space, centimetres; yaw in degrees.
#[derive(Clone, Copy, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Start {
    /// Capsule bottom (the soles), world, cm.
    pub position: (f32, f32, f32),
    /// Facing yaw, degrees (0 = +Y, counter-clockwise positive). Default 0.
    #[serde(default)]
    pub yaw: f32,
}

/// How the character turns during a segment (RON: `Velocity` or `Look(yaw: 0.0)`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum FacingDesc {
    /// Turn towards the velocity.
    #[default]
    Velocity,
    /// Face a fixed world yaw, degrees.
    Look {
        /// Yaw, degrees (0 = +Y, counter-clockwise positive).
        yaw: f32,
    },
}

impl FacingDesc {
    /// The mover's [`Facing`].
    #[must_use]
    pub fn to_facing(self) -> Facing {
        match self {
            FacingDesc::Velocity => Facing::Velocity,
            FacingDesc::Look { yaw } => Facing::Look(yaw),
        }
    }
}

/// One segment of a scenario's timeline (see the module docs). Seconds, cm, cm/s, degrees.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum Segment {
    /// Stand still for `seconds`.
    Stand {
        /// Duration, s.
        seconds: f32,
    },
    /// Move in a fixed direction for `seconds`.
    Move {
        /// Duration, s.
        seconds: f32,
        /// World XY direction (length clamped to 1 scales the speed); or use `heading`.
        #[serde(default)]
        direction: Option<(f32, f32)>,
        /// Direction as a yaw, degrees (0 = +Y, counter-clockwise positive); or use
        /// `direction`.
        #[serde(default)]
        heading: Option<f32>,
        /// Speed, cm/s.
        speed: f32,
        /// How the character turns. Default `Velocity`.
        #[serde(default)]
        facing: FacingDesc,
    },
    /// Move with a turning direction for `seconds` (walking an arc or circle).
    Arc {
        /// Duration, s.
        seconds: f32,
        /// Speed, cm/s.
        speed: f32,
        /// Direction at the start of the segment, degrees.
        heading: f32,
        /// Rate the direction turns, degrees/s, positive counter-clockwise; or use `radius`.
        #[serde(default)]
        turn_rate: Option<f32>,
        /// Radius of the circle walked, cm; positive turns counter-clockwise. Or use
        /// `turn_rate`.
        #[serde(default)]
        radius: Option<f32>,
        /// How the character turns. Default `Velocity`.
        #[serde(default)]
        facing: FacingDesc,
    },
    /// Move the character at once.
    Teleport {
        /// New capsule bottom, world, cm.
        position: (f32, f32, f32),
        /// New yaw, degrees. Default 0.
        #[serde(default)]
        yaw: f32,
    },
    /// One frame spanning `seconds`; the previous input continues meanwhile.
    Hitch {
        /// Duration, s.
        seconds: f32,
    },
    /// Extra frames with `dt = 0`.
    ZeroDt {
        /// Number of frames (at most 10 000).
        frames: u32,
    },
}

impl Segment {
    /// The variant's name as written in RON.
    #[must_use]
    pub fn kind(&self) -> &'static str {
        match self {
            Segment::Stand { .. } => "Stand",
            Segment::Move { .. } => "Move",
            Segment::Arc { .. } => "Arc",
            Segment::Teleport { .. } => "Teleport",
            Segment::Hitch { .. } => "Hitch",
            Segment::ZeroDt { .. } => "ZeroDt",
        }
    }

    /// Duration, seconds (0 for `Teleport` and `ZeroDt`).
    #[must_use]
    pub fn seconds(&self) -> f32 {
        match self {
            Segment::Stand { seconds }
            | Segment::Move { seconds, .. }
            | Segment::Arc { seconds, .. }
            | Segment::Hitch { seconds } => *seconds,
            Segment::Teleport { .. } | Segment::ZeroDt { .. } => 0.0,
        }
    }

    /// Duration in fixed mover steps: `round(seconds · 720)`.
    #[must_use]
    pub fn steps(&self) -> u64 {
        (f64::from(self.seconds()) * f64::from(MOVER_RATE_HZ)).round() as u64
    }

    /// Checks the values; the message says what is wrong and how to fix it.
    pub fn validate(&self) -> Result<(), String> {
        let seconds = self.seconds();
        if !(seconds.is_finite() && seconds >= 0.0 && f64::from(seconds) <= MAX_SCENARIO_SECONDS) {
            return Err(format!(
                "`seconds` must be between 0 and {MAX_SCENARIO_SECONDS}"
            ));
        }
        let speed_ok = |speed: f32| {
            if speed.is_finite() && speed >= 0.0 {
                Ok(())
            } else {
                Err("`speed` must be 0 or more (cm/s)".to_string())
            }
        };
        let facing_ok = |facing: &FacingDesc| match facing {
            FacingDesc::Look { yaw } if !yaw.is_finite() => {
                Err("`facing: Look(yaw: ...)` needs a finite yaw in degrees".to_string())
            }
            _ => Ok(()),
        };
        match self {
            Segment::Stand { .. } | Segment::Hitch { .. } => Ok(()),
            Segment::Move {
                direction,
                heading,
                speed,
                facing,
                ..
            } => {
                speed_ok(*speed)?;
                facing_ok(facing)?;
                match (direction, heading) {
                    (Some(_), Some(_)) => Err(
                        "give either `direction: (x, y)` or `heading: degrees`, not both".into(),
                    ),
                    (None, None) => Err(
                        "add `direction: (x, y)` (world XY) or `heading: degrees` (0 = +Y)".into(),
                    ),
                    (Some((x, y)), None) if !(x.is_finite() && y.is_finite()) => {
                        Err("`direction` must be finite numbers".into())
                    }
                    (None, Some(h)) if !h.is_finite() => {
                        Err("`heading` must be a finite number of degrees".into())
                    }
                    _ => Ok(()),
                }
            }
            Segment::Arc {
                speed,
                heading,
                turn_rate,
                radius,
                facing,
                ..
            } => {
                speed_ok(*speed)?;
                facing_ok(facing)?;
                if !heading.is_finite() {
                    return Err("`heading` must be a finite number of degrees".into());
                }
                match (turn_rate, radius) {
                    (Some(_), Some(_)) => {
                        Err("give either `turn_rate` (deg/s) or `radius` (cm), not both".into())
                    }
                    (None, None) => {
                        Err("add `turn_rate: degrees per second` or `radius: centimetres`".into())
                    }
                    (Some(rate), None) if !rate.is_finite() => {
                        Err("`turn_rate` must be a finite number of degrees per second".into())
                    }
                    (None, Some(r)) if !(r.is_finite() && *r != 0.0) => {
                        Err("`radius` must be a finite, non-zero number of centimetres \
                         (negative turns clockwise)"
                            .into())
                    }
                    _ => Ok(()),
                }
            }
            Segment::Teleport { position, yaw } => {
                if [position.0, position.1, position.2, *yaw]
                    .iter()
                    .all(|v| v.is_finite())
                {
                    Ok(())
                } else {
                    Err("`position` and `yaw` must be finite numbers".into())
                }
            }
            Segment::ZeroDt { frames } => {
                if *frames <= 10_000 {
                    Ok(())
                } else {
                    Err("`frames` must be at most 10000".into())
                }
            }
        }
    }
}

/// The file as written (private: the public [`Scenario`] has the defaults filled in).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ScenarioFile {
    world: WorldDesc,
    start: Start,
    #[serde(default, deserialize_with = "deserialize_checked_mover")]
    mover: Option<MoverSettings>,
    #[serde(deserialize_with = "deserialize_checked_seq")]
    timeline: Vec<Segment>,
}

fn deserialize_checked_mover<'de, D: Deserializer<'de>>(
    deserializer: D,
) -> Result<Option<MoverSettings>, D::Error> {
    let settings = Option::<MoverSettings>::deserialize(deserializer)?;
    if let Some(s) = &settings {
        s.validate().map_err(de::Error::custom)?;
    }
    Ok(settings)
}

impl CheckedElement for Segment {
    const NOUN: &'static str = "segment";
    fn kind(&self) -> &'static str {
        Segment::kind(self)
    }
    fn validate(&self) -> Result<(), String> {
        Segment::validate(self)
    }
}

/// An error reading a scenario.
#[derive(Debug, thiserror::Error)]
pub enum ScenarioError {
    /// The file could not be read.
    #[error("{}: cannot read the scenario file: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The I/O error.
        #[source]
        source: std::io::Error,
    },
    /// The text is not a valid scenario (syntax, unknown or missing field, bad value).
    #[error("{origin}:{line}:{col}: error: {message}\n  hint: {help}")]
    Parse {
        /// The file name (or the origin given to [`Scenario::parse`]).
        origin: String,
        /// Line, from 1.
        line: usize,
        /// Column, from 1.
        col: usize,
        /// What is wrong.
        message: String,
        /// How to fix it.
        help: String,
    },
    /// The scenario as a whole is invalid (for instance too long, or its world cannot be
    /// built).
    #[error("{origin}: error: {message}\n  hint: {help}")]
    Invalid {
        /// The file name.
        origin: String,
        /// What is wrong.
        message: String,
        /// How to fix it.
        help: String,
    },
}

/// A scenario: a world, a start, mover settings (defaults with the file's overrides) and a
/// timeline.
#[derive(Clone, Debug, PartialEq)]
pub struct Scenario {
    /// The file stem (`walk_flat`), or the origin given to [`Scenario::parse`].
    pub name: String,
    /// The world.
    pub world: WorldDesc,
    /// Where the character starts.
    pub start: Start,
    /// Mover settings: [`MoverSettings::default`] with the file's overrides.
    pub mover: MoverSettings,
    /// The segments, in order.
    pub timeline: Vec<Segment>,
}

impl Scenario {
    /// Reads a scenario file. Errors name `file:line:col` and say how to fix the problem.
    pub fn load(path: impl AsRef<Path>) -> Result<Scenario, ScenarioError> {
        let path = path.as_ref();
        let text = std::fs::read_to_string(path).map_err(|source| ScenarioError::Io {
            path: path.to_path_buf(),
            source,
        })?;
        let mut scenario = Self::parse(&text, &path.display().to_string())?;
        if let Some(stem) = path.file_stem() {
            scenario.name = stem.to_string_lossy().into_owned();
        }
        Ok(scenario)
    }

    /// Parses scenario text; `origin` names it in error messages (and becomes the name).
    pub fn parse(text: &str, origin: &str) -> Result<Scenario, ScenarioError> {
        let file: ScenarioFile = ron_options().from_str(text).map_err(|e| {
            let (message, help) = describe_ron_error(&e.code);
            ScenarioError::Parse {
                origin: origin.to_string(),
                line: e.span.start.line,
                col: e.span.start.col,
                message,
                help,
            }
        })?;
        let start_ok = [
            file.start.position.0,
            file.start.position.1,
            file.start.position.2,
            file.start.yaw,
        ]
        .iter()
        .all(|v| v.is_finite());
        if !start_ok {
            return Err(ScenarioError::Invalid {
                origin: origin.to_string(),
                message: "`start` has a non-finite value".into(),
                help: "write `start: (position: (x, y, z), yaw: degrees)` with numbers".into(),
            });
        }
        let scenario = Scenario {
            name: origin.to_string(),
            world: file.world,
            start: file.start,
            mover: file.mover.unwrap_or_default(),
            timeline: file.timeline,
        };
        if scenario.duration() > MAX_SCENARIO_SECONDS {
            return Err(ScenarioError::Invalid {
                origin: origin.to_string(),
                message: format!(
                    "the timeline lasts {:.1} s, more than {MAX_SCENARIO_SECONDS} s",
                    scenario.duration()
                ),
                help: "shorten the segments or split the scenario".into(),
            });
        }
        World::try_from_desc(&scenario.world).map_err(|e| ScenarioError::Invalid {
            origin: origin.to_string(),
            message: e.to_string(),
            help: "fix the shape in `world`".into(),
        })?;
        Ok(scenario)
    }

    /// Total simulated time, seconds (sum of the segments' step counts / 720).
    #[must_use]
    pub fn duration(&self) -> f64 {
        self.total_steps() as f64 / f64::from(MOVER_RATE_HZ)
    }

    /// Total number of fixed mover steps.
    #[must_use]
    pub fn total_steps(&self) -> u64 {
        self.timeline.iter().map(Segment::steps).sum()
    }
}

/// One output frame of a [`Simulation`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SimFrame {
    /// Output frame number, from 0 (counts hitch and zero-dt frames once each).
    pub index: u32,
    /// Simulated time of the frame, seconds (the tick's `k / hz`).
    pub time: f64,
    /// Seconds since the previous frame (`1 / hz` for the first frame, 0 for zero-dt
    /// frames, the whole gap for a hitch frame).
    pub dt: f32,
    /// Rig (component) space to world: capsule bottom, rotated by the yaw about +Z.
    pub component_to_world: Transform,
    /// The mover's velocity, world, cm/s (z = 0 while grounded).
    pub velocity: Vec3,
    /// Whether the input at this frame asks to stand still.
    pub standing_still: bool,
    /// Whether a teleport happened since the previous frame (the first frame counts a
    /// teleport at time 0).
    pub teleported: bool,
}

/// Where an input comes from during a timeline span.
#[derive(Clone, Copy, Debug)]
enum InputSource {
    Fixed(MoveInput),
    Arc {
        speed: f32,
        heading: f32,
        rate_deg_per_s: f32,
        facing: Facing,
    },
}

impl InputSource {
    /// The input `elapsed` steps into the span.
    fn at(&self, elapsed: u64) -> MoveInput {
        match *self {
            InputSource::Fixed(input) => input,
            InputSource::Arc {
                speed,
                heading,
                rate_deg_per_s,
                facing,
            } => {
                let t = elapsed as f64 / f64::from(MOVER_RATE_HZ);
                let h = (f64::from(heading) + f64::from(rate_deg_per_s) * t).rem_euclid(360.0);
                MoveInput {
                    direction: heading_vector(h as f32),
                    speed,
                    facing,
                }
            }
        }
    }
}

#[derive(Clone, Copy, Debug)]
struct Span {
    start: u64,
    steps: u64,
    source: InputSource,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Slot {
    Tick(u64),
    ZeroDt,
}

/// The state a [`Simulation`] changes as it runs (the mover and where the timeline is),
/// without the scenario's fixed parts (world, timeline, schedule): a few dozen bytes, to
/// go back to with [`Simulation::restore`].
#[derive(Clone, Debug)]
pub struct SimCheckpoint {
    mover: Mover,
    next: usize,
    steps_done: u64,
    next_teleport: usize,
    last_tick: u64,
}

/// Runs a scenario at a frame rate, frame by frame (see the module docs for the timing).
#[derive(Clone, Debug)]
pub struct Simulation {
    world: World,
    mover: Mover,
    hz: u32,
    spans: Vec<Span>,
    teleports: Vec<(u64, Vec3, f32)>,
    schedule: Vec<Slot>,
    next: usize,
    steps_done: u64,
    next_teleport: usize,
    last_tick: u64,
    total_steps: u64,
}

impl Simulation {
    /// Prepares `scenario` at `hz` frames per second (clamped to 1..=10 000). The world is
    /// built from the scenario's description (already checked when the scenario was read).
    #[must_use]
    pub fn new(scenario: &Scenario, hz: u32) -> Simulation {
        let hz = hz.clamp(1, MAX_HZ);
        let world = World::from_desc(&scenario.world);
        let start = Vec3::new(
            scenario.start.position.0,
            scenario.start.position.1,
            scenario.start.position.2,
        );
        let mut mover = Mover::new(scenario.mover, start, scenario.start.yaw);
        mover.settle(&world);

        let mut spans: Vec<Span> = Vec::new();
        let mut teleports = Vec::new();
        let mut hitches: Vec<(u64, u64)> = Vec::new();
        let mut zero_dt: Vec<(u64, u32)> = Vec::new();
        let mut step = 0u64;
        for segment in &scenario.timeline {
            let steps = segment.steps();
            let source = match *segment {
                Segment::Stand { .. } => Some(InputSource::Fixed(MoveInput::STAND)),
                Segment::Move {
                    direction,
                    heading,
                    speed,
                    facing,
                    ..
                } => {
                    let direction = match (direction, heading) {
                        (Some((x, y)), _) => Vec2::new(x, y),
                        (None, Some(h)) => heading_vector(h),
                        (None, None) => Vec2::ZERO,
                    };
                    Some(InputSource::Fixed(MoveInput {
                        direction,
                        speed,
                        facing: facing.to_facing(),
                    }))
                }
                Segment::Arc {
                    speed,
                    heading,
                    turn_rate,
                    radius,
                    facing,
                    ..
                } => {
                    let rate = match (turn_rate, radius) {
                        (Some(rate), _) => rate,
                        (None, Some(r)) if r != 0.0 => (speed / r).to_degrees(),
                        _ => 0.0,
                    };
                    Some(InputSource::Arc {
                        speed,
                        heading,
                        rate_deg_per_s: rate,
                        facing: facing.to_facing(),
                    })
                }
                Segment::Hitch { .. } => {
                    hitches.push((step, step + steps));
                    let held = spans
                        .last()
                        .map_or(MoveInput::STAND, |s| s.source.at(s.steps));
                    Some(InputSource::Fixed(held))
                }
                Segment::Teleport { position, yaw } => {
                    teleports.push((step, Vec3::new(position.0, position.1, position.2), yaw));
                    None
                }
                Segment::ZeroDt { frames } => {
                    zero_dt.push((step, frames));
                    None
                }
            };
            if let Some(source) = source
                && steps > 0
            {
                spans.push(Span {
                    start: step,
                    steps,
                    source,
                });
            }
            step += steps;
        }
        let total_steps = step;

        // The frame schedule: every tick, minus those strictly inside a hitch, plus zero-dt
        // frames after the last tick at or before their time.
        let rate = u64::from(MOVER_RATE_HZ);
        let hz64 = u64::from(hz);
        let last_tick = total_steps * hz64 / rate;
        let mut schedule = Vec::new();
        let mut zi = 0;
        let mut hi = 0;
        for k in 0..=last_tick {
            let at = k * rate;
            while zi < zero_dt.len() && zero_dt[zi].0 * hz64 < at {
                schedule.extend(std::iter::repeat_n(Slot::ZeroDt, zero_dt[zi].1 as usize));
                zi += 1;
            }
            while hi < hitches.len() && hitches[hi].1 * hz64 <= at {
                hi += 1;
            }
            if hi < hitches.len() && hitches[hi].0 * hz64 < at && at < hitches[hi].1 * hz64 {
                continue;
            }
            schedule.push(Slot::Tick(k));
        }
        for &(_, frames) in &zero_dt[zi..] {
            schedule.extend(std::iter::repeat_n(Slot::ZeroDt, frames as usize));
        }

        Simulation {
            world,
            mover,
            hz,
            spans,
            teleports,
            schedule,
            next: 0,
            steps_done: 0,
            next_teleport: 0,
            last_tick: 0,
            total_steps,
        }
    }

    /// The world the character moves in.
    #[must_use]
    pub fn world(&self) -> &World {
        &self.world
    }

    /// The mover, as of the last frame returned.
    #[must_use]
    pub fn mover(&self) -> &Mover {
        &self.mover
    }

    /// Output frame rate, Hz (after clamping).
    #[must_use]
    pub fn hz(&self) -> u32 {
        self.hz
    }

    /// Total number of frames [`Simulation::next_frame`] returns.
    #[must_use]
    pub fn frame_count(&self) -> usize {
        self.schedule.len()
    }

    /// Simulated time of the last frame, seconds.
    #[must_use]
    pub fn duration(&self) -> f64 {
        (self.total_steps * u64::from(self.hz) / u64::from(MOVER_RATE_HZ)) as f64
            / f64::from(self.hz)
    }

    /// The input the timeline gives for mover step `step` (the last span's final input
    /// past the end, standing still for an empty timeline).
    #[must_use]
    pub fn input_at_step(&self, step: u64) -> MoveInput {
        let index = self.spans.partition_point(|s| s.start <= step);
        match index.checked_sub(1).map(|i| &self.spans[i]) {
            Some(span) => span.source.at((step - span.start).min(span.steps)),
            None => MoveInput::STAND,
        }
    }

    /// Where the simulation is now (see [`Simulation::restore`]).
    #[must_use]
    pub fn checkpoint(&self) -> SimCheckpoint {
        SimCheckpoint {
            mover: self.mover.clone(),
            next: self.next,
            steps_done: self.steps_done,
            next_teleport: self.next_teleport,
            last_tick: self.last_tick,
        }
    }

    /// Goes back (or forward) to `checkpoint`, taken from this simulation or another of the
    /// same scenario and rate: the frames that follow are the ones that followed it.
    pub fn restore(&mut self, checkpoint: &SimCheckpoint) {
        self.mover = checkpoint.mover.clone();
        self.next = checkpoint.next.min(self.schedule.len());
        self.steps_done = checkpoint.steps_done;
        self.next_teleport = checkpoint.next_teleport.min(self.teleports.len());
        self.last_tick = checkpoint.last_tick;
    }

    /// Advances to the next frame, or `None` after the last.
    pub fn next_frame(&mut self) -> Option<SimFrame> {
        let slot = *self.schedule.get(self.next)?;
        let index = self.next as u32;
        self.next += 1;
        let hz = f64::from(self.hz);
        let (dt, teleported) = match slot {
            Slot::ZeroDt => (0.0, false),
            Slot::Tick(k) => {
                let dt = if index == 0 {
                    1.0 / hz
                } else {
                    (k - self.last_tick) as f64 / hz
                };
                self.last_tick = k;
                let target = k * u64::from(MOVER_RATE_HZ) / u64::from(self.hz);
                (dt as f32, self.advance_to(target))
            }
        };
        Some(SimFrame {
            index,
            time: self.last_tick as f64 / hz,
            dt,
            component_to_world: self.mover.component_to_world(),
            velocity: self.mover.velocity(),
            standing_still: self.input_at_step(self.steps_done).is_standing_still(),
            teleported,
        })
    }

    /// Runs fixed mover steps until `target` steps are done; true if a teleport happened.
    fn advance_to(&mut self, target: u64) -> bool {
        let dt = 1.0 / MOVER_RATE_HZ as f32;
        let mut teleported = false;
        loop {
            while let Some(&(at, position, yaw)) = self.teleports.get(self.next_teleport)
                && at <= self.steps_done
            {
                self.mover.teleport(position, yaw);
                self.mover.settle(&self.world);
                self.next_teleport += 1;
                teleported = true;
            }
            if self.steps_done >= target {
                return teleported;
            }
            let input = self.input_at_step(self.steps_done);
            self.mover.step(&input, dt, &self.world);
            self.steps_done += 1;
        }
    }
}
