//! The running character behind the panels: the graph (document and compiled program), the
//! skeleton, the world, the mover or a scenario, the instance, the recording, and hot reload.
//!
//! The simulation advances in fixed steps of [`SIM_DT`] (1/60 s) whatever the UI's frame
//! rate: the mover takes [`MOVER_SUBSTEPS`] steps of 1/720 s per frame (the host's mover
//! rate, as in scenarios), then the graph runs its `forward` event once with `dt = 1/60`.
//! Slow motion and pause change how many steps run per wall-clock second, never `dt`.
//!
//! Every frame is recorded ([`crate::recording`]); full-state keyframes, taken every
//! [`KEYFRAME_EVERY`] frames and after an overrides file is loaded, and the variable
//! edits noted with their frame, let the simulation continue from any recorded frame
//! ([`Session::resume_from`]).

use crate::recording::{FrameMeta, Recorder};
use crate::{InspectError, InspectOptions};
use std::collections::VecDeque;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::mpsc::{Receiver, channel};
use std::time::{Duration, Instant};
use strider_core::{Transform, Vec3};
use strider_graph::{LoadedGraph, SkeletonFile};
use strider_host::mover::{MoveInput, Mover};
use strider_host::overrides::Overrides;
use strider_host::report::{PlantSpan, Report, ReportRig};
use strider_host::scenario::{Scenario, SimCheckpoint, Simulation};
use strider_host::world::World;
use strider_nodes::Value;
use strider_vm::{FrameInput, InputPose, Instance, Program, VariableId};

/// Simulation rate, frames per second.
pub const SIM_HZ: u32 = 60;
/// Seconds per simulation frame.
pub const SIM_DT: f32 = 1.0 / SIM_HZ as f32;
/// Mover steps per simulation frame (the host's mover runs at 720 Hz).
pub const MOVER_SUBSTEPS: u32 = 12;
/// How many frames the recording keeps: 32 s at 60 Hz.
pub const RECORD_FRAMES: usize = 32 * SIM_HZ as usize;
/// Frames between two regular keyframes (1 s): resuming from a recorded frame re-runs at
/// most this many frames (more only when resuming before the oldest keyframe kept).
pub const KEYFRAME_EVERY: u64 = SIM_HZ as u64;
/// Most keyframes kept: one a second covers the recording (32), the rest are for those
/// taken after an overrides file is loaded. Past it the oldest go, and frames before the
/// oldest kept can be shown but not resumed from.
pub const MAX_KEYFRAMES: usize = 128;
/// How long the watched files must stay quiet before a reload, so that an editor's
/// several writes reload once.
pub const RELOAD_QUIET: Duration = Duration::from_millis(150);

/// What runs while the graph given has never loaded: nothing (the rest pose).
const EMPTY_GRAPH: &str = "Graph(version: 1, name: \"(not loaded)\", events: { forward: [] })";

/// The world used when neither a scenario nor a world file is given: ground, a box, a
/// ramp, stairs, a platform and a patch of uneven ground around the start.
pub const DEMO_WORLD: &str = include_str!("../assets/demo_world.ron");

/// Where the character's input comes from.
#[derive(Clone, Debug)]
pub enum Drive {
    /// The keyboard (or a test) sets [`Session::input`] before each step.
    Keyboard,
    /// A scenario's timeline plays (and starts again at its end).
    Scenario {
        /// The scenario file.
        path: PathBuf,
        /// The scenario.
        scenario: Box<Scenario>,
        /// Its simulation at [`SIM_HZ`].
        sim: Box<Simulation>,
    },
}

/// The live quality report and the foot plants of the recorded frames of the current run.
#[derive(Clone, Debug, Default)]
pub struct Quality {
    /// The report over the recorded frames of the current program (`None` before the
    /// first evaluation or when the skeleton has no contact points).
    pub report: Option<Report>,
    /// Frames the report covers.
    pub frames: usize,
    /// Planted spans found in those frames (world positions in each span).
    pub plants: Vec<PlantSpan>,
    /// Why there is no report, if there is none.
    pub unavailable: Option<String>,
}

/// Where the character's motion stood before a keyframe's frame.
#[derive(Clone, Debug)]
enum KeyDrive {
    /// The keyboard's mover.
    Keyboard(Mover),
    /// The scenario's simulation.
    Scenario(SimCheckpoint),
}

/// The whole state before frame `frame` ran: what resuming from a recorded frame starts
/// from, before running the recorded inputs again up to that frame.
#[derive(Clone, Debug)]
struct Keyframe {
    /// The frame about to run.
    frame: u64,
    /// Simulated seconds before it.
    time: f64,
    /// The instance (variables, pin values, pose, program).
    instance: Instance,
    /// The mover or the scenario's place.
    drive: KeyDrive,
}

/// A file watcher: events from notify, and which files matter.
struct Watch {
    _watcher: notify::RecommendedWatcher,
    events: Receiver<notify::Result<notify::Event>>,
    files: Vec<PathBuf>,
}

/// Everything the inspector runs. See the module docs for the stepping model.
pub struct Session {
    options: InspectOptions,
    loaded: Arc<LoadedGraph>,
    program: Arc<Program>,
    skeleton: SkeletonFile,
    rig: Result<ReportRig, String>,
    instance: Instance,
    world: Arc<World>,
    world_path: Option<PathBuf>,
    mover: Mover,
    drive: Drive,
    /// The input used by the next keyboard-driven steps.
    pub input: MoveInput,
    frame: u64,
    time: f64,
    generation: u32,
    recorder: Recorder,
    problems: Vec<String>,
    status: String,
    /// Whether the graph given ever loaded (else an empty graph runs in its place).
    graph_loaded: bool,
    watch: Option<Watch>,
    dirty_since: Option<Instant>,
    quality: Quality,
    quality_frame: u64,
    /// The report being computed on another thread, if any.
    quality_job: Option<Receiver<Quality>>,
    /// Per node location (`file:line:col`), mean µs per frame over the last half second
    /// (profiling builds only).
    profile_us: Option<std::collections::HashMap<String, f64>>,
    /// Full-state keyframes, oldest first, all of the current program, world and drive.
    keyframes: VecDeque<Keyframe>,
    /// Take a keyframe before the next frame (something other than the input and the
    /// edits noted in `edits` changed the state: replaying them would not get there).
    keyframe_due: bool,
    /// Variable edits ([`Session::set_tunables`]) since the oldest keyframe, each with the
    /// frame that ran after it, oldest first: made again when frames run again.
    edits: VecDeque<(u64, Vec<(VariableId, Value)>)>,
}

fn diagnostics_text(d: &[strider_graph::Diagnostic]) -> Vec<String> {
    d.iter().map(ToString::to_string).collect()
}

fn canonical(path: &Path) -> PathBuf {
    std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf())
}

/// Compiles a graph for inspection: every pin keeps a slot of its own, so the graph view
/// shows each pin's value after a frame (the results are the same bit for bit).
fn compile(
    loaded: &strider_graph::LoadedGraph,
) -> Result<strider_vm::Program, Vec<strider_graph::Diagnostic>> {
    let options = strider_compiler::Options {
        keep_pin_values: true,
    };
    strider_compiler::compile_with(loaded, options)
}

impl Session {
    /// Loads the graph, skeleton, world or scenario and overrides of `options`, creates the
    /// instance and starts watching the files.
    ///
    /// A graph with problems still opens: an empty graph runs in its place (the character
    /// stands in its rest pose), the problems are listed, and the graph loads as soon as
    /// its file is fixed.
    ///
    /// # Errors
    /// [`InspectError::Load`] with every problem (`path:line:col: error: ...`) when the
    /// skeleton, the scenario or world, or the overrides file does not load.
    pub fn open(options: InspectOptions) -> Result<Session, InspectError> {
        let fail = |lines: Vec<String>| InspectError::Load(lines.join("\n"));
        let compiled = strider_graph::load_graph(&options.graph).and_then(|loaded| {
            let program = compile(&loaded)?;
            Ok((loaded, program))
        });
        let (loaded, program, graph_problems) = match compiled {
            Ok((loaded, program)) => (loaded, program, Vec::new()),
            Err(d) => {
                let loaded = strider_graph::load_graph_str(&options.graph, EMPTY_GRAPH.to_string())
                    .map_err(|e| fail(diagnostics_text(&e)))?;
                let program = compile(&loaded).map_err(|e| fail(diagnostics_text(&e)))?;
                (loaded, program, diagnostics_text(&d))
            }
        };
        let skeleton = strider_graph::load_skeleton(&options.skeleton)
            .map_err(|d| fail(diagnostics_text(&d)))?;
        let program = Arc::new(program);
        let mut instance = Instance::new(Arc::clone(&program), Arc::clone(&skeleton.skeleton))
            .map_err(|e| fail(vec![e.to_string()]))?;
        let (world, world_path, drive) = match (&options.scenario, &options.world) {
            (Some(path), _) => {
                let scenario = Scenario::load(path).map_err(|e| fail(vec![e.to_string()]))?;
                let sim = Simulation::new(&scenario, SIM_HZ);
                (
                    sim.world().clone(),
                    None,
                    Drive::Scenario {
                        path: path.clone(),
                        scenario: Box::new(scenario),
                        sim: Box::new(sim),
                    },
                )
            }
            (None, Some(path)) => (
                World::load(path).map_err(|e| fail(vec![e.to_string()]))?,
                Some(path.clone()),
                Drive::Keyboard,
            ),
            (None, None) => (
                World::from_str(DEMO_WORLD).map_err(|e| fail(vec![e.to_string()]))?,
                None,
                Drive::Keyboard,
            ),
        };
        if let Some(path) = &options.overrides {
            Overrides::load(path, &program)
                .map_err(|d| fail(diagnostics_text(&d)))?
                .apply(&mut instance);
            // `construction` runs again with the new tunables (rebind keeps them).
            instance
                .rebind(Arc::clone(&skeleton.skeleton), &world)
                .map_err(|e| fail(vec![e.to_string()]))?;
        }
        let mut mover = Mover::new(Default::default(), Vec3::ZERO, 0.0);
        mover.settle(&world);
        let rig = ReportRig::from_skeleton(&skeleton).map_err(|e| e.to_string());
        let recorder = Recorder::new(RECORD_FRAMES);
        let mut session = Session {
            options,
            loaded: Arc::new(loaded),
            program,
            skeleton,
            rig,
            instance,
            world: Arc::new(world),
            world_path,
            mover,
            drive,
            input: MoveInput::STAND,
            frame: 0,
            time: 0.0,
            generation: 0,
            recorder,
            graph_loaded: graph_problems.is_empty(),
            problems: Vec::new(),
            status: String::new(),
            watch: None,
            dirty_since: None,
            quality: Quality::default(),
            quality_frame: 0,
            quality_job: None,
            profile_us: None,
            keyframes: VecDeque::new(),
            keyframe_due: true,
            edits: VecDeque::new(),
        };
        session.start_profiling();
        session.status = if graph_problems.is_empty() {
            format!("loaded {}", session.options.graph.display())
        } else {
            format!(
                "{} has problems: nothing runs until it is fixed",
                session.options.graph.display()
            )
        };
        session.problems = graph_problems;
        session.watch = session.start_watch();
        Ok(session)
    }

    /// The files whose changes reload the session: the graph, its imports, the skeleton,
    /// and the scenario or world file.
    #[must_use]
    pub fn watched_files(&self) -> Vec<PathBuf> {
        let mut files: Vec<PathBuf> = self
            .loaded
            .sources
            .files()
            .map(|f| canonical(self.loaded.sources.path(f)))
            .collect();
        files.push(canonical(&self.options.skeleton));
        if let Drive::Scenario { path, .. } = &self.drive {
            files.push(canonical(path));
        }
        if let Some(path) = &self.world_path {
            files.push(canonical(path));
        }
        files.sort();
        files.dedup();
        files
    }

    fn start_watch(&self) -> Option<Watch> {
        use notify::Watcher as _;
        let (tx, rx) = channel();
        let mut watcher = notify::recommended_watcher(move |event| {
            let _ = tx.send(event);
        })
        .ok()?;
        let files = self.watched_files();
        let mut dirs: Vec<PathBuf> = files
            .iter()
            .filter_map(|f| f.parent().map(Path::to_path_buf))
            .collect();
        dirs.sort();
        dirs.dedup();
        for dir in dirs {
            // Watching the folder (not the file) also sees editors that save by renaming a
            // new file over the old one.
            let _ = watcher.watch(&dir, notify::RecursiveMode::NonRecursive);
        }
        Some(Watch {
            _watcher: watcher,
            events: rx,
            files,
        })
    }

    /// Looks at file events; once a watched file changed and [`RELOAD_QUIET`] passed
    /// without further change, reloads. Returns true when a reload was attempted.
    pub fn poll_files(&mut self) -> bool {
        let Some(watch) = &self.watch else {
            return false;
        };
        let mut changed = false;
        while let Ok(event) = watch.events.try_recv() {
            let Ok(event) = event else { continue };
            if matches!(event.kind, notify::EventKind::Access(_)) {
                continue;
            }
            if event
                .paths
                .iter()
                .any(|p| watch.files.iter().any(|f| *f == canonical(p) || f == p))
            {
                changed = true;
            }
        }
        if changed {
            self.dirty_since = Some(Instant::now());
        }
        match self.dirty_since {
            Some(at) if at.elapsed() >= RELOAD_QUIET => {
                self.dirty_since = None;
                self.reload();
                true
            }
            _ => false,
        }
    }

    /// Reloads every file now. On success the new program replaces the old one: the
    /// instance is re-created, tunables whose name and type are unchanged keep their values,
    /// `construction` runs with them, and state variables keep theirs (see
    /// `carry_variables`); on failure the problems are listed and the last good program
    /// keeps running. Returns true on success.
    pub fn reload(&mut self) -> bool {
        let mut problems = Vec::new();
        let skeleton = match strider_graph::load_skeleton(&self.options.skeleton) {
            Ok(s) => s,
            Err(d) => {
                problems.extend(diagnostics_text(&d));
                self.skeleton.clone()
            }
        };
        let compiled = strider_graph::load_graph(&self.options.graph).and_then(|loaded| {
            let program = compile(&loaded)?;
            Ok((loaded, program))
        });
        let (loaded, program) = match compiled {
            Ok(ok) => ok,
            Err(d) => {
                problems.extend(diagnostics_text(&d));
                return self.reload_failed(problems);
            }
        };
        let program = Arc::new(program);
        let mut instance = match Instance::new(Arc::clone(&program), Arc::clone(&skeleton.skeleton))
        {
            Ok(i) => i,
            Err(e) => {
                problems.push(e.to_string());
                return self.reload_failed(problems);
            }
        };
        self.reload_drive(&mut problems);
        carry_variables(&self.instance, &mut instance, &skeleton, &self.world);
        let same_program = program.code() == self.program.code()
            && program.operands() == self.program.operands()
            && program.variables() == self.program.variables();
        self.loaded = Arc::new(loaded);
        self.program = program;
        self.rig = ReportRig::from_skeleton(&skeleton).map_err(|e| e.to_string());
        self.skeleton = skeleton;
        self.instance = instance;
        self.start_profiling();
        if !same_program {
            self.generation += 1;
        }
        // The program, the world or the scenario may have changed: the keyframes could not
        // replay the frames before.
        self.forget_keyframes();
        self.graph_loaded = true;
        self.status = format!(
            "reloaded {} at frame {}",
            self.options.graph.display(),
            self.frame
        );
        self.problems = problems;
        self.watch = self.start_watch();
        self.problems.is_empty()
    }

    fn reload_failed(&mut self, problems: Vec<String>) -> bool {
        self.status = if self.graph_loaded {
            format!(
                "reload failed at frame {}: running the last good program",
                self.frame
            )
        } else {
            format!(
                "{} has problems: nothing runs until it is fixed",
                self.options.graph.display()
            )
        };
        self.problems = problems;
        false
    }

    /// Reloads the scenario or world file, keeping the old one on error.
    fn reload_drive(&mut self, problems: &mut Vec<String>) {
        if let Drive::Scenario { path, .. } = &self.drive {
            let path = path.clone();
            match Scenario::load(&path) {
                Ok(s) => self.play_loaded_scenario(path, s),
                Err(e) => problems.push(e.to_string()),
            }
        } else if let Some(path) = &self.world_path {
            match World::load(path) {
                Ok(w) => self.world = Arc::new(w),
                Err(e) => problems.push(e.to_string()),
            }
        }
    }

    /// Plays the scenario at `path` from its start (the character is placed at the
    /// scenario's start).
    ///
    /// # Errors
    /// The scenario's problem, `path:line:col: error: ...`.
    pub fn play_scenario(&mut self, path: &Path) -> Result<(), String> {
        let scenario = Scenario::load(path).map_err(|e| e.to_string())?;
        self.play_loaded_scenario(path.to_path_buf(), scenario);
        self.watch = self.start_watch();
        Ok(())
    }

    fn play_loaded_scenario(&mut self, path: PathBuf, scenario: Scenario) {
        let sim = Simulation::new(&scenario, SIM_HZ);
        self.world = Arc::new(sim.world().clone());
        self.world_path = None;
        self.drive = Drive::Scenario {
            path,
            scenario: Box::new(scenario),
            sim: Box::new(sim),
        };
        self.forget_keyframes();
    }

    /// Drives the character with [`Session::input`] from where it stands now (in the
    /// current world).
    pub fn drive_with_keyboard(&mut self) {
        if let Drive::Scenario { sim, .. } = &self.drive {
            let m = sim.mover();
            self.mover = Mover::new(*m.settings(), m.position(), m.yaw());
            self.mover.settle(&self.world);
        }
        self.drive = Drive::Keyboard;
        self.forget_keyframes();
    }

    /// Runs one simulation frame: moves the character (keyboard input or scenario), runs
    /// the graph with `dt` = [`SIM_DT`] and debug drawing on, and records the frame. A
    /// keyframe is taken first every [`KEYFRAME_EVERY`] frames, and after an overrides
    /// file was loaded or the program, world or drive changed.
    pub fn step(&mut self) {
        if self.keyframe_due || self.frame.is_multiple_of(KEYFRAME_EVERY) {
            self.take_keyframe();
        }
        let Some(meta) = self.simulate() else { return };
        self.recorder.push(meta, &mut self.instance);
        self.frame += 1;
        if self.frame >= self.quality_frame + u64::from(SIM_HZ) / 2 {
            self.update_quality();
        }
    }

    /// Runs frame [`Session::frame`] without recording it: the mover or scenario, then the
    /// graph. `None` when a scenario has no frame at all.
    fn simulate(&mut self) -> Option<FrameMeta> {
        let (dt, to_world, velocity, standing, teleported, move_input) = match &mut self.drive {
            Drive::Keyboard => {
                for _ in 0..MOVER_SUBSTEPS {
                    self.mover.step(
                        &self.input,
                        1.0 / (SIM_HZ * MOVER_SUBSTEPS) as f32,
                        &self.world,
                    );
                }
                (
                    SIM_DT,
                    self.mover.component_to_world(),
                    self.mover.velocity(),
                    self.input.is_standing_still(),
                    false,
                    self.input,
                )
            }
            Drive::Scenario { scenario, sim, .. } => {
                let frame = match sim.next_frame() {
                    Some(f) => f,
                    None => {
                        **sim = Simulation::new(scenario, SIM_HZ);
                        sim.next_frame()?
                    }
                };
                (
                    frame.dt,
                    frame.component_to_world,
                    frame.velocity,
                    frame.standing_still,
                    frame.teleported,
                    MoveInput::STAND,
                )
            }
        };
        let input = FrameInput {
            dt,
            component_to_world: to_world,
            pose: InputPose::Rest,
        };
        self.instance.run_forward(&input, &*self.world, true);
        self.time += f64::from(dt);
        Some(FrameMeta {
            frame: self.frame,
            time: self.time,
            dt,
            generation: self.generation,
            to_world,
            velocity,
            standing_still: standing,
            teleported,
            input: move_input,
        })
    }

    /// Keeps the whole state before the next frame (clones the instance: a few
    /// allocations, about once a second). Drops keyframes that can no longer serve: those
    /// before the oldest recorded frame, and the oldest past [`MAX_KEYFRAMES`]; and the
    /// edits before the oldest keyframe kept.
    fn take_keyframe(&mut self) {
        self.keyframe_due = false;
        let oldest = self.recorder.get(0).map_or(self.frame, |f| f.meta.frame);
        while self.keyframes.len() >= MAX_KEYFRAMES
            || self.keyframes.front().is_some_and(|k| k.frame < oldest)
        {
            self.keyframes.pop_front();
        }
        let drive = match &self.drive {
            Drive::Keyboard => KeyDrive::Keyboard(self.mover.clone()),
            Drive::Scenario { sim, .. } => KeyDrive::Scenario(sim.checkpoint()),
        };
        // Edits before the oldest keyframe can no longer be run again.
        let first = self.keyframes.front().map_or(self.frame, |k| k.frame);
        while self.edits.front().is_some_and(|(f, _)| *f < first) {
            self.edits.pop_front();
        }
        self.keyframes.push_back(Keyframe {
            frame: self.frame,
            time: self.time,
            instance: self.instance.clone(),
            drive,
        });
    }

    /// Forgets every keyframe (the program, world or drive changed) and takes one before
    /// the next frame.
    fn forget_keyframes(&mut self) {
        self.keyframes.clear();
        self.edits.clear();
        self.keyframe_due = true;
    }

    /// Continues the simulation from recorded frame `index` (counted from the oldest kept):
    /// restores the nearest keyframe at or before it, runs the recorded inputs and the
    /// variable edits again up to it (the frames come out bit-identical: the simulation is
    /// deterministic), then forgets the recorded frames and the edits after it (variables
    /// are as they were at that frame). The next [`Session::step`] runs the frame
    /// that follows. Nothing changes on error.
    ///
    /// # Errors
    /// When `index` is not recorded, was recorded by an earlier program, or lies before
    /// the oldest keyframe kept (before a reload, a change of drive or scenario, or past
    /// [`MAX_KEYFRAMES`]).
    pub fn resume_from(&mut self, index: usize) -> Result<(), String> {
        let target = self
            .recorder
            .get(index)
            .map(|f| f.meta)
            .ok_or_else(|| format!("frame {index} is not recorded"))?;
        if target.generation != self.generation {
            return Err(format!(
                "cannot resume from t {:.2} s: it was recorded before the graph changed",
                target.time
            ));
        }
        // The nearest keyframe at or before the frame whose frames since are all still
        // recorded (frame numbers are consecutive in the recording).
        let oldest = self.recorder.get(0).map_or(target.frame, |f| f.meta.frame);
        let key = self
            .keyframes
            .iter()
            .rposition(|k| k.frame <= target.frame)
            .filter(|&k| self.keyframes[k].frame >= oldest)
            .ok_or_else(|| {
                let since = self
                    .keyframes
                    .iter()
                    .find(|k| k.frame >= oldest)
                    .map_or(self.time, |k| k.time);
                format!(
                    "cannot resume from t {:.2} s: the simulation can be resumed from \
                     t {since:.2} s on (the first keyframe still recorded, after the last \
                     reload or change of drive)",
                    target.time
                )
            })?;
        let key = &self.keyframes[key];
        let first = index - (target.frame - key.frame) as usize;
        match (&key.drive, &mut self.drive) {
            (KeyDrive::Keyboard(m), Drive::Keyboard) => self.mover = m.clone(),
            (KeyDrive::Scenario(c), Drive::Scenario { sim, .. }) => sim.restore(c),
            // Keyframes are forgotten when the drive changes.
            _ => return Err("the keyframe's drive is not the current one".to_string()),
        }
        self.instance.clone_from(&key.instance);
        self.frame = key.frame;
        self.time = key.time;
        // Edits noted with the keyframe's frame were made before it was taken: it has them.
        let mut edit = self.edits.partition_point(|(f, _)| *f <= key.frame);
        for i in first..=index {
            while let Some((f, values)) = self.edits.get(edit)
                && *f == self.frame
            {
                let values = values.clone();
                // It was applied the first time; it applies the same way again.
                let _ = self.apply_edit(&values);
                edit += 1;
            }
            if let Some(f) = self.recorder.get(i) {
                self.input = f.meta.input;
            }
            self.simulate();
            self.frame += 1;
        }
        let same = self
            .recorder
            .get(index)
            .is_some_and(|f| f.globals == self.instance.pose_mut().globals());
        self.recorder.truncate(index + 1);
        self.keyframes.retain(|k| k.frame <= target.frame);
        // Edits made after the frame are undone with the frames after it.
        self.edits.retain(|(f, _)| *f <= target.frame);
        self.quality_frame = self.frame;
        self.status = if same {
            format!(
                "resumed from frame {} (t {:.2} s)",
                target.frame, target.time
            )
        } else {
            format!(
                "resumed from frame {} (t {:.2} s), but the replayed pose differs from the \
                 recorded one: the simulation is not deterministic",
                target.frame, target.time
            )
        };
        Ok(())
    }

    fn start_profiling(&mut self) {
        #[cfg(feature = "profile")]
        {
            self.instance.set_profiling(true);
            self.instance.reset_profile();
        }
    }

    /// Mean time per frame of each node or step, µs, keyed by where it is written
    /// (`file:line:col`); `None` without the `profile` feature or before the first half
    /// second.
    #[must_use]
    pub fn profile_us(&self) -> Option<&std::collections::HashMap<String, f64>> {
        self.profile_us.as_ref()
    }

    #[cfg(feature = "profile")]
    fn update_profile(&mut self, frames: u64) {
        let mut map = std::collections::HashMap::new();
        let program = Arc::clone(&self.program);
        for n in self.instance.profile_by_node() {
            if let Some(origin) = n.origin(&program)
                && !origin.location.is_empty()
            {
                *map.entry(origin.location.clone()).or_insert(0.0) +=
                    n.nanos as f64 / 1000.0 / frames.max(1) as f64;
            }
        }
        self.instance.reset_profile();
        self.profile_us = Some(map);
    }

    /// Takes the quality report computed on another thread, if it is ready, and starts the
    /// next one from the recorded frames of the current program (twice a second while the
    /// simulation runs): the report costs milliseconds over 32 s of frames, too much for
    /// one UI frame.
    pub fn update_quality(&mut self) {
        #[cfg(feature = "profile")]
        self.update_profile(self.frame - self.quality_frame);
        self.quality_frame = self.frame;
        if let Some(job) = &self.quality_job {
            match job.try_recv() {
                Ok(q) => {
                    self.quality = q;
                    self.quality_job = None;
                }
                Err(std::sync::mpsc::TryRecvError::Empty) => return,
                Err(std::sync::mpsc::TryRecvError::Disconnected) => self.quality_job = None,
            }
        }
        let rig = match &self.rig {
            Ok(rig) => rig.clone(),
            Err(e) => {
                self.quality = Quality {
                    unavailable: Some(e.clone()),
                    ..Quality::default()
                };
                return;
            }
        };
        let records = self.recorder.frame_records(self.generation);
        if records.len() < 2 {
            return;
        }
        let world = Arc::clone(&self.world);
        let (tx, rx) = channel();
        std::thread::spawn(move || {
            let report = strider_host::report::analyse(&rig, &records, &*world);
            let plants = strider_host::report::plant_spans(&rig, &records, &*world);
            let _ = tx.send(Quality {
                report: Some(report),
                frames: records.len(),
                plants,
                unavailable: None,
            });
        });
        self.quality_job = Some(rx);
    }

    /// Waits until the quality report being computed is in (for tests and tools that
    /// step the session themselves).
    pub fn finish_quality(&mut self) {
        if let Some(job) = self.quality_job.take()
            && let Ok(q) = job.recv()
        {
            self.quality = q;
        }
    }

    /// Sets a variable by id on the live instance (slider edits). Setting a tunable runs
    /// `construction` again with the new value (see [`Session::set_tunables`]).
    ///
    /// # Errors
    /// As [`Instance::set_variable`]; nothing changes then.
    pub fn set_variable(&mut self, id: VariableId, value: &Value) -> Result<(), String> {
        self.set_tunables(&[(id, value.clone())])
    }

    /// Sets variables on the live instance (slider edits), noting the edit with the frame
    /// that runs next (so that resuming from a recorded frame makes it again). When any of
    /// them is tunable,
    /// `construction` runs again on a fresh instance with the new tunables, and every
    /// other variable whose value `construction` now gives differently from what it gave
    /// with the previous tunables takes the new value; the others keep their live values
    /// (the state the frames built). The program does not say which variables
    /// `construction` reads, so this happens on any tunable change; it costs two runs of
    /// `construction`.
    ///
    /// # Errors
    /// The first value that does not fit its variable (wrong type, unknown bone); nothing
    /// changes then.
    pub fn set_tunables(&mut self, values: &[(VariableId, Value)]) -> Result<(), String> {
        self.apply_edit(values)?;
        // Kept to make the same edit when running the frames again (resume_from).
        self.edits.push_back((self.frame, values.to_vec()));
        Ok(())
    }

    /// [`Session::set_tunables`] without noting the edit.
    fn apply_edit(&mut self, values: &[(VariableId, Value)]) -> Result<(), String> {
        let mut next = self.instance.clone();
        for (id, value) in values {
            next.set_variable(*id, value).map_err(|e| e.to_string())?;
        }
        let program = Arc::clone(&self.program);
        let tunable = values
            .iter()
            .any(|(id, _)| program.variable(*id).tunable.is_some());
        if tunable {
            let skeleton = &self.skeleton.skeleton;
            let before = constructed(&program, &self.instance, skeleton, &self.world);
            let after = constructed(&program, &next, skeleton, &self.world);
            if let (Some(before), Some(after)) = (before, after) {
                for (i, v) in program.variables().iter().enumerate() {
                    let id = VariableId(i as u32);
                    if v.tunable.is_none() && after.variable(id) != before.variable(id) {
                        let _ = next.set_variable(id, &after.variable(id));
                    }
                }
            }
        }
        self.instance = next;
        Ok(())
    }

    /// Sets every tunable variable back to its default from the graph file (and runs
    /// `construction` again, as [`Session::set_tunables`]).
    pub fn reset_tunables(&mut self) {
        let defaults: Vec<(VariableId, Value)> = self
            .program
            .variables()
            .iter()
            .enumerate()
            .filter(|(_, v)| v.tunable.is_some())
            .map(|(i, v)| (VariableId(i as u32), v.default.clone()))
            .collect();
        // The defaults are the variables' own: they fit.
        let _ = self.set_tunables(&defaults);
    }

    /// Writes the current tunable values as an overrides file at `path`. Refuses to write
    /// over any file the session reads (the graph, its imports, the skeleton, ...).
    ///
    /// # Errors
    /// A message when `path` is one of those files or cannot be written.
    pub fn export_overrides(&self, path: &Path) -> Result<(), String> {
        let target = canonical(path);
        if self.watched_files().contains(&target) {
            return Err(format!(
                "{} is one of the files the inspector reads; choose another file",
                path.display()
            ));
        }
        std::fs::write(path, Overrides::from_instance(&self.instance).to_ron())
            .map_err(|e| format!("cannot write {}: {e}", path.display()))
    }

    /// Reads an overrides file, applies it to the live instance and re-runs `construction`
    /// (the other variables restart from their defaults).
    ///
    /// # Errors
    /// Every problem, `path:line:col: error: ...`, one per line.
    pub fn load_overrides(&mut self, path: &Path) -> Result<usize, String> {
        let o =
            Overrides::load(path, &self.program).map_err(|d| diagnostics_text(&d).join("\n"))?;
        o.apply(&mut self.instance);
        // `construction` runs again so that what it derives from tunables is current; the
        // other variables start again from their defaults (as after `Instance::rebind`).
        self.instance
            .rebind(Arc::clone(&self.skeleton.skeleton), &*self.world)
            .map_err(|e| e.to_string())?;
        self.start_profiling();
        self.keyframe_due = true;
        Ok(o.entries.len())
    }

    /// The options the session was opened with.
    #[must_use]
    pub fn options(&self) -> &InspectOptions {
        &self.options
    }

    /// The loaded graph document (main file and libraries) of the running program.
    #[must_use]
    pub fn document(&self) -> &Arc<LoadedGraph> {
        &self.loaded
    }

    /// The running program.
    #[must_use]
    pub fn program(&self) -> &Arc<Program> {
        &self.program
    }

    /// The live instance.
    #[must_use]
    pub fn instance(&self) -> &Instance {
        &self.instance
    }

    /// The skeleton file (bones and sole contact points).
    #[must_use]
    pub fn skeleton(&self) -> &SkeletonFile {
        &self.skeleton
    }

    /// The world the character walks in.
    #[must_use]
    pub fn world(&self) -> &World {
        &self.world
    }

    /// Where the input comes from.
    #[must_use]
    pub fn drive(&self) -> &Drive {
        &self.drive
    }

    /// The recording of the last frames.
    #[must_use]
    pub fn recorder(&self) -> &Recorder {
        &self.recorder
    }

    /// Frames run so far.
    #[must_use]
    pub fn frame(&self) -> u64 {
        self.frame
    }

    /// Simulated seconds so far.
    #[must_use]
    pub fn time(&self) -> f64 {
        self.time
    }

    /// Counts reloads that changed the program (recorded frames carry it).
    #[must_use]
    pub fn generation(&self) -> u32 {
        self.generation
    }

    /// Whether the graph given ever loaded; until it does, an empty graph runs in its place.
    #[must_use]
    pub fn graph_loaded(&self) -> bool {
        self.graph_loaded
    }

    /// Problems of the last reload (empty when it succeeded).
    #[must_use]
    pub fn problems(&self) -> &[String] {
        &self.problems
    }

    /// One line about the last load or reload.
    #[must_use]
    pub fn status(&self) -> &str {
        &self.status
    }

    /// The live quality report.
    #[must_use]
    pub fn quality(&self) -> &Quality {
        &self.quality
    }

    /// The component-to-world transform of the last frame (or the mover's, before any).
    #[must_use]
    pub fn component_to_world(&self) -> Transform {
        self.recorder
            .latest()
            .map_or_else(|| self.mover.component_to_world(), |f| f.meta.to_world)
    }
}

/// Carries what survives a reload from `from` (the running instance) to `to` (a fresh
/// instance of the new program): every tunable whose name and type are unchanged; then
/// `construction` runs again with them; then every other variable whose name and type are
/// unchanged keeps its live value, unless the edit changed what `construction` gives it
/// (compared with the old program's `construction` run on the same tunables), in which
/// case the new value stands.
fn carry_variables(from: &Instance, to: &mut Instance, skeleton: &SkeletonFile, world: &World) {
    let old = Arc::clone(from.program());
    let new = Arc::clone(to.program());
    let matching = |v: &strider_vm::VariableInfo| {
        old.variable_id(&v.name)
            .filter(|&j| old.variable(j).ty == v.ty)
    };
    for (i, v) in new.variables().iter().enumerate() {
        if v.tunable.is_some()
            && let Some(j) = matching(v)
        {
            let _ = to.set_variable(VariableId(i as u32), &from.variable(j));
        }
    }
    let _ = to.rebind(Arc::clone(&skeleton.skeleton), world);
    // What the old program's `construction` gave, with the same tunables.
    let old_constructed = constructed(&old, from, from.pose().skeleton(), world);
    for (i, v) in new.variables().iter().enumerate() {
        let id = VariableId(i as u32);
        if v.tunable.is_some() {
            continue;
        }
        let Some(j) = matching(v) else { continue };
        let unchanged = old_constructed
            .as_ref()
            .is_none_or(|fresh| fresh.variable(j) == to.variable(id));
        if unchanged {
            let _ = to.set_variable(id, &from.variable(j));
        }
    }
}

/// A fresh instance of `program` on `skeleton` whose tunables are those of `tunables` (an
/// instance of the same program), after `construction` ran in `world`; `None` when the
/// skeleton lacks bones the program names.
fn constructed(
    program: &Arc<Program>,
    tunables: &Instance,
    skeleton: &Arc<strider_core::Skeleton>,
    world: &World,
) -> Option<Instance> {
    let mut fresh = Instance::new(Arc::clone(program), Arc::clone(skeleton)).ok()?;
    for (j, v) in program.variables().iter().enumerate() {
        if v.tunable.is_some() {
            let id = VariableId(j as u32);
            let _ = fresh.set_variable(id, &tunables.variable(id));
        }
    }
    fresh.rebind(Arc::clone(skeleton), world).ok()?;
    Some(fresh)
}
