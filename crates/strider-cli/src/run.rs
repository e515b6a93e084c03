//! `strider run GRAPH --skeleton SKEL`: compile a graph, run it headless for a number of
//! frames, optionally write every frame's pose as JSON lines, and print a summary.

use crate::setup::{apply_assignments, instantiate, load, resolve_assignments, skeleton_label};
use crate::{jsonl, output};
use anyhow::{Context as _, anyhow, bail};
use std::fmt::Write as _;
use std::fs::File;
use std::io::{BufWriter, Write as _};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::Arc;
use std::time::{Duration, Instant};
use strider_core::{EmptyWorld, Transform, WorldQuery};
use strider_graph::SkeletonFile;
use strider_host::scenario::{MAX_HZ, Scenario, Simulation};
use strider_vm::{FrameInput, InputPose, Program};

/// Default frame rate, Hz.
pub(crate) const DEFAULT_HZ: f64 = 60.0;
/// Frames run without --frames or --scenario.
const DEFAULT_FRAMES: u32 = 60;

/// Arguments of `strider run`.
#[derive(Debug, clap::Args)]
#[command(
    about = "Compile a graph, run it headless on a skeleton and summarise the motion",
    long_about = "Compile a graph, run it headless on a skeleton and summarise the motion.\n\n\
        Each frame starts from the skeleton's rest pose, advances time by 1/H seconds and \
        runs the graph's `forward` event with the character at the world origin \
        (component-to-world = identity) in an empty world (every trace misses). With \
        --scenario, the scenario's world answers the traces and its capsule, driven by the \
        scenario's timeline of inputs, places the character (and sets dt) every frame; the \
        run lasts the whole scenario unless --frames is given. Variables \
        given with --set are applied before the first frame; tunable ones before the \
        `construction` event, which is re-run.\n\n\
        With --out, every frame's rig-space (global) bone transforms are written as one \
        JSON object per line, bones in the skeleton's depth-first storage order:\n  \
        {\"frame\":0,\"time\":0.0166…,\"bones\":{\"root\":{\"t\":[x,y,z],\"r\":[x,y,z,w],\"s\":[x,y,z]},…}}\n\
        With --scenario each line also has \
        `\"world\":{\"t\":…,\"r\":…,\"s\":…}`, the component-to-world transform.\n\
        `frame` counts from 0, `time` is seconds at the end of the frame ((frame + 1) / H; \
        with --scenario the scenario's clock, frame / H, hitches included), \
        `t` is in centimetres, `r` a unit quaternion, `s` the scale; NaN and infinities are \
        written `null`.\n\n\
        The summary (stdout) gives the graph, the skeleton, the frame count and rate, the \
        wall-clock cost per frame (informational), the output file and, when the skeleton \
        has a `pelvis` bone, the pelvis height range over the run."
)]
pub(crate) struct RunArgs {
    /// Graph file to compile and run (`Graph( ... )`, RON).
    #[arg(value_name = "GRAPH")]
    pub graph: PathBuf,

    /// Skeleton file to run the graph on (`Skeleton( ... )`, RON).
    #[arg(long, short = 's', value_name = "SKEL")]
    pub skeleton: PathBuf,

    /// Number of frames to run [default: 60, or the whole scenario with --scenario].
    #[arg(long, short = 'n', value_name = "N")]
    pub frames: Option<u32>,

    /// Drive the character through a scenario (`graphs/scenarios/*.ron`): its world
    /// answers the traces and its capsule places the character every frame. --hz must then
    /// be a whole number.
    #[arg(long, value_name = "SCEN")]
    pub scenario: Option<PathBuf>,

    /// Frame rate in Hz (frames per second): each frame advances time by 1/H seconds.
    #[arg(long, value_name = "H", default_value_t = DEFAULT_HZ, value_parser = positive_hz)]
    pub hz: f64,

    /// Set a graph variable before the first frame; repeatable. VALUE by the variable's
    /// type: Float `3.5` (in the variable's unit: cm, degrees, seconds, Hz...), Int `3`,
    /// Bool `true`/`false`, Vec3 `1,2,3` or `(1,2,3)` (cm for positions), Quat `x,y,z,w`
    /// (unit length). Setting a non-tunable variable is allowed, with a warning.
    #[arg(long, value_name = "NAME=VALUE")]
    pub set: Vec<String>,

    /// Set tunable variables from an overrides file (a RON map `{ "Name": value, ... }`, as
    /// the inspector exports) before the first frame; `--set` wins for a variable both give.
    #[arg(long, value_name = "FILE")]
    pub overrides: Option<PathBuf>,

    /// Write every frame's rig-space bone transforms to this file, one JSON object per line
    /// (translations in cm, rotations as quaternions x,y,z,w).
    #[arg(long, short = 'o', value_name = "FILE.jsonl")]
    pub out: Option<PathBuf>,

    /// Turn debug drawing on (the summary counts the primitives the graph drew).
    #[arg(long)]
    pub debug: bool,
}

/// `--hz`: a finite number above zero.
fn positive_hz(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(h) if h.is_finite() && h > 0.0 => Ok(h),
        Ok(_) => Err("the frame rate must be a finite number of Hz above 0".to_string()),
        Err(e) => Err(format!("{e}")),
    }
}

/// Runs `strider run`.
pub(crate) fn run(args: &RunArgs) -> anyhow::Result<ExitCode> {
    let (program, skeleton) = load(&args.graph, &args.skeleton)?;
    let program = Arc::new(program);
    let assignments = resolve_assignments(&program, args.overrides.as_deref(), &args.set)?;

    let mut sim = match &args.scenario {
        Some(path) => {
            let scenario = Scenario::load(path).map_err(|e| anyhow!("{e}"))?;
            if args.hz.fract() != 0.0 || args.hz > f64::from(MAX_HZ) {
                bail!(
                    "--hz {} with --scenario: the frame rate must be a whole number of Hz up to {MAX_HZ}",
                    args.hz
                );
            }
            Some(Simulation::new(&scenario, args.hz as u32))
        }
        None => None,
    };
    let frames = args.frames.unwrap_or_else(|| {
        sim.as_ref().map_or(DEFAULT_FRAMES, |s| {
            s.frame_count().try_into().unwrap_or(u32::MAX)
        })
    });

    let mut instance = instantiate(&program, &skeleton, &args.skeleton)?;
    let world: &dyn WorldQuery = match &sim {
        Some(sim) => sim.world(),
        None => &EmptyWorld,
    };
    apply_assignments(&mut instance, &skeleton, &assignments, world)?;

    let mut writer = match &args.out {
        Some(path) => {
            Some(BufWriter::new(File::create(path).with_context(|| {
                format!("cannot create `{}`", path.display())
            })?))
        }
        None => None,
    };
    let write_error = |path: &Option<PathBuf>| {
        format!(
            "cannot write `{}`",
            path.as_deref().unwrap_or(Path::new("")).display()
        )
    };

    let bones = skeleton.skeleton.names();
    let pelvis = skeleton.skeleton.find("pelvis");
    let mut stats = Stats::default();
    for frame in 0..frames {
        // Without a scenario: the origin, an empty world, a fixed step.
        let (input, time, world): (FrameInput<'_>, f64, &dyn WorldQuery) = match &mut sim {
            Some(sim) => {
                let Some(f) = sim.next_frame() else { break };
                let input = FrameInput {
                    dt: f.dt,
                    component_to_world: f.component_to_world,
                    pose: InputPose::Rest,
                };
                (input, f.time, sim.world())
            }
            None => {
                let input = FrameInput {
                    dt: (1.0 / args.hz) as f32,
                    component_to_world: Transform::IDENTITY,
                    pose: InputPose::Rest,
                };
                (input, f64::from(frame + 1) / args.hz, &EmptyWorld)
            }
        };
        let start = Instant::now();
        instance.run_forward(&input, world, args.debug);
        let primitives = instance.debug_draw().primitives().len();
        let globals = instance.pose_mut().globals();
        stats.busy += start.elapsed();
        stats.primitives += primitives;

        stats.frames += 1;
        let placed = args.scenario.as_ref().map(|_| &input.component_to_world);
        stats.non_finite += match &mut writer {
            Some(w) => jsonl::write_frame(w, u64::from(frame), time, placed, bones, globals)
                .with_context(|| write_error(&args.out))?,
            None => jsonl::count_non_finite(globals),
        };
        if let Some(p) = pelvis {
            stats.pelvis_z(globals[p.get()].translation.z);
        }
    }
    if let Some(w) = &mut writer {
        w.flush().with_context(|| write_error(&args.out))?;
    }

    output::print_stdout(&summary(args, &program, &skeleton, &stats))?;
    Ok(ExitCode::SUCCESS)
}

/// What the summary reports about the run.
#[derive(Debug, Default)]
struct Stats {
    /// Frames run.
    frames: u32,
    /// Wall-clock time in `run_forward` and the global-pose update.
    busy: Duration,
    /// NaN or infinite components over all frames and bones.
    non_finite: usize,
    /// Debug primitives drawn over the run.
    primitives: usize,
    /// Lowest and highest finite pelvis global Z, cm.
    pelvis: Option<(f32, f32)>,
}

impl Stats {
    fn pelvis_z(&mut self, z: f32) {
        if z.is_finite() {
            self.pelvis = Some(match self.pelvis {
                Some((lo, hi)) => (lo.min(z), hi.max(z)),
                None => (z, z),
            });
        }
    }
}

fn summary(args: &RunArgs, program: &Program, skeleton: &SkeletonFile, stats: &Stats) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "graph      {} ({})",
        program.name(),
        args.graph.display()
    );
    let _ = writeln!(
        s,
        "skeleton   {}, {} bones ({})",
        skeleton_label(skeleton, &args.skeleton),
        skeleton.skeleton.len(),
        args.skeleton.display()
    );
    let _ = write!(
        s,
        "frames     {} at {} Hz = {} s simulated",
        stats.frames,
        args.hz,
        f64::from(stats.frames) / args.hz
    );
    if let Some(path) = &args.scenario {
        let _ = write!(s, " in scenario {}", path.display());
    }
    if stats.frames > 0 {
        let per_frame = stats.busy.as_secs_f64() * 1e6 / f64::from(stats.frames);
        let _ = write!(
            s,
            ", {per_frame:.2} µs per frame (wall clock, informational)"
        );
    }
    s.push('\n');
    match &args.out {
        Some(path) => {
            let _ = writeln!(s, "output     {} ({} lines)", path.display(), stats.frames);
        }
        None => s.push_str("output     none (--out FILE.jsonl writes the bone transforms)\n"),
    }
    if args.debug {
        let _ = writeln!(s, "debug draw {} primitives over the run", stats.primitives);
    }
    if let Some(pelvis) = skeleton.skeleton.find("pelvis") {
        let rest = skeleton.skeleton.rest_global(pelvis).translation.z;
        match stats.pelvis {
            Some((lo, hi)) => {
                let _ = writeln!(
                    s,
                    "pelvis z   {lo:.3} .. {hi:.3} cm (range {:.3} cm; rest {rest:.3} cm)",
                    hi - lo
                );
            }
            None if stats.frames == 0 => {
                let _ = writeln!(s, "pelvis z   no frame run (rest {rest:.3} cm)");
            }
            None => {
                let _ = writeln!(s, "pelvis z   never finite (rest {rest:.3} cm)");
            }
        }
    }
    if stats.non_finite > 0 {
        let _ = writeln!(
            s,
            "warning    {} non-finite values (NaN or infinite) in the output pose{}",
            stats.non_finite,
            if args.out.is_some() {
                ", written as null"
            } else {
                ""
            }
        );
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frame_rates_must_be_positive_and_finite() {
        assert_eq!(positive_hz("60"), Ok(60.0));
        assert_eq!(positive_hz("29.97"), Ok(29.97));
        for bad in ["0", "-30", "inf", "NaN", "", "fast"] {
            assert!(positive_hz(bad).is_err(), "{bad}");
        }
    }
}
