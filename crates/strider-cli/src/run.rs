//! `strider run GRAPH --skeleton SKEL`: compile a graph, run it headless for a number of
//! frames, optionally write every frame's pose as JSON lines, and print a summary.

use crate::check::guard;
use crate::{jsonl, output, value};
use anyhow::{Context as _, anyhow, bail};
use std::fmt::Write as _;
use std::fs::File;
use std::io::{BufWriter, Write as _};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::Arc;
use std::time::{Duration, Instant};
use strider_core::{EmptyWorld, Transform};
use strider_graph::{Diagnostic, SkeletonFile};
use strider_nodes::Value;
use strider_vm::{FrameInput, InputPose, Instance, InstantiateError, Program, VariableId};

/// Default frame rate, Hz.
pub(crate) const DEFAULT_HZ: f64 = 60.0;

/// Arguments of `strider run`.
#[derive(Debug, clap::Args)]
#[command(
    about = "Compile a graph, run it headless on a skeleton and summarise the motion",
    long_about = "Compile a graph, run it headless on a skeleton and summarise the motion.\n\n\
        Each frame starts from the skeleton's rest pose, advances time by 1/H seconds and \
        runs the graph's `forward` event with the character at the world origin \
        (component-to-world = identity) in an empty world (every trace misses). Variables \
        given with --set are applied before the first frame; tunable ones before the \
        `construction` event, which is re-run.\n\n\
        With --out, every frame's rig-space (global) bone transforms are written as one \
        JSON object per line, bones in the skeleton's depth-first storage order:\n  \
        {\"frame\":0,\"time\":0.0166…,\"bones\":{\"root\":{\"t\":[x,y,z],\"r\":[x,y,z,w],\"s\":[x,y,z]},…}}\n\
        `frame` counts from 0, `time` is seconds at the end of the frame ((frame + 1) / H), \
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

    /// Number of frames to run.
    #[arg(long, short = 'n', value_name = "N", default_value_t = 60)]
    pub frames: u32,

    /// Frame rate in Hz (frames per second): each frame advances time by 1/H seconds.
    #[arg(long, value_name = "H", default_value_t = DEFAULT_HZ, value_parser = positive_hz)]
    pub hz: f64,

    /// Set a graph variable before the first frame; repeatable. VALUE by the variable's
    /// type: Float `3.5` (in the variable's unit: cm, degrees, seconds, Hz...), Int `3`,
    /// Bool `true`/`false`, Vec3 `1,2,3` or `(1,2,3)` (cm for positions), Quat `x,y,z,w`
    /// (unit length). Setting a non-tunable variable is allowed, with a warning.
    #[arg(long, value_name = "NAME=VALUE")]
    pub set: Vec<String>,

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
    let assignments = parse_assignments(&program, &args.set)?;

    let mut instance = match Instance::new(Arc::clone(&program), skeleton.skeleton.clone()) {
        Ok(instance) => instance,
        Err(InstantiateError::MissingBones { mut missing, .. }) => {
            // A pure node emitted in front of several exec steps reports the same reference
            // once per step: show each reference once.
            let mut seen = std::collections::HashSet::new();
            missing.retain(|m| seen.insert((m.name.clone(), m.location.clone())));
            let mut names: Vec<String> = missing.iter().map(|m| m.name.clone()).collect();
            names.sort_unstable();
            names.dedup();
            let label = skeleton_label(&skeleton, &args.skeleton);
            // Re-labelled with the skeleton's own name: the VM only knows it as "skeleton".
            let e = InstantiateError::MissingBones {
                skeleton: label.clone(),
                missing,
            };
            output::error_line(&e.to_string());
            bail!(
                "graph `{}` names {} that skeleton `{label}` ({}) lacks: {}",
                program.name(),
                if names.len() == 1 {
                    "a bone".to_string()
                } else {
                    format!("{} bones", names.len())
                },
                args.skeleton.display(),
                names.join(", ")
            );
        }
    };
    apply_assignments(&mut instance, &skeleton, &assignments)?;

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
    let input = FrameInput {
        dt: (1.0 / args.hz) as f32,
        component_to_world: Transform::IDENTITY,
        pose: InputPose::Rest,
    };
    let mut stats = Stats::default();
    for frame in 0..args.frames {
        let start = Instant::now();
        instance.run_forward(&input, &EmptyWorld, args.debug);
        let primitives = instance.debug_draw().primitives().len();
        let globals = instance.pose_mut().globals();
        stats.busy += start.elapsed();
        stats.primitives += primitives;

        let time = f64::from(frame + 1) / args.hz;
        stats.non_finite += match &mut writer {
            Some(w) => jsonl::write_frame(w, u64::from(frame), time, bones, globals)
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

/// Loads the skeleton and compiles the graph, reporting the diagnostics of both.
fn load(graph: &Path, skeleton: &Path) -> anyhow::Result<(Program, SkeletonFile)> {
    let skel = guard(skeleton, || strider_graph::load_skeleton(skeleton));
    let program = guard(graph, || strider_compiler::compile_file(graph));
    let mut failures = Vec::new();
    let mut report = |path: &Path, d: &[Diagnostic]| {
        output::print_diagnostics(d);
        failures.push(format!(
            "{} in {}",
            output::problems(d.len().max(1)),
            path.display()
        ));
    };
    match (program, skel) {
        (Ok(p), Ok(s)) => Ok((p, s)),
        (p, s) => {
            if let Err(d) = &p {
                report(graph, d);
            }
            if let Err(d) = &s {
                report(skeleton, d);
            }
            Err(anyhow!("{}", failures.join(", ")))
        }
    }
}

fn skeleton_label(skeleton: &SkeletonFile, path: &Path) -> String {
    if skeleton.name.is_empty() {
        path.display().to_string()
    } else {
        skeleton.name.clone()
    }
}

/// One `--set`, resolved against the program.
#[derive(Debug)]
struct Assignment {
    id: VariableId,
    value: Value,
    tunable: bool,
}

/// Resolves and parses every `--set` before anything runs.
fn parse_assignments(program: &Program, sets: &[String]) -> anyhow::Result<Vec<Assignment>> {
    let mut out = Vec::with_capacity(sets.len());
    for text in sets {
        let (name, raw) = value::split_assignment(text)?;
        let id = program
            .variable_id(name)
            .ok_or_else(|| anyhow!("{}", unknown_variable(program, name)))?;
        let info = program.variable(id);
        let value = value::parse_value(info.ty, raw)
            .with_context(|| format!("`--set {text}`: `{name}` is a {}", info.ty))?;
        if let Some((min, max)) = info.tunable {
            let x = match value {
                Value::Float(x) => Some(x),
                Value::Int(i) => Some(i as f32),
                _ => None,
            };
            if let Some(x) = x
                && (min.is_some_and(|m| x < m) || max.is_some_and(|m| x > m))
            {
                output::error_line(&format!(
                    "warning: `{name}` = {raw} is outside its tunable range {}; setting it anyway",
                    range(min, max)
                ));
            }
        } else {
            output::error_line(&format!(
                "warning: `{name}` is not a tunable variable of graph `{}`; setting it anyway \
                 (after the construction event)",
                program.name()
            ));
        }
        out.push(Assignment {
            id,
            value,
            tunable: info.tunable.is_some(),
        });
    }
    Ok(out)
}

/// `unknown variable ...`, with a suggestion and the graph's tunable variables.
fn unknown_variable(program: &Program, name: &str) -> String {
    let mut msg = format!("unknown variable `{name}` in graph `{}`", program.name());
    if let Some(s) =
        strider_graph::suggest(name, program.variables().iter().map(|v| v.name.as_str()))
    {
        let _ = write!(msg, " (did you mean `{s}`?)");
    }
    let tunables: Vec<String> = program
        .variables()
        .iter()
        .filter_map(|v| {
            v.tunable
                .map(|(min, max)| format!("{} ({}, {})", v.name, v.ty, range(min, max)))
        })
        .collect();
    if tunables.is_empty() {
        msg.push_str("; the graph has no tunable variables");
    } else {
        let _ = write!(msg, "; tunable variables: {}", tunables.join(", "));
    }
    msg
}

/// `0..20`, `..4`, `0..`, `any value`.
fn range(min: Option<f32>, max: Option<f32>) -> String {
    match (min, max) {
        (None, None) => "any value".to_string(),
        (min, max) => format!(
            "{}..{}",
            min.map(|m| m.to_string()).unwrap_or_default(),
            max.map(|m| m.to_string()).unwrap_or_default()
        ),
    }
}

/// Sets the variables: tunables first, then `construction` re-runs so that what it derives
/// from them is current (`rebind` keeps tunables and resets the rest), then the others.
fn apply_assignments(
    instance: &mut Instance,
    skeleton: &SkeletonFile,
    assignments: &[Assignment],
) -> anyhow::Result<()> {
    let set = |instance: &mut Instance, a: &Assignment| {
        instance
            .set_variable(a.id, &a.value)
            .map_err(|e| anyhow!("--set: {e}"))
    };
    let mut any_tunable = false;
    for a in assignments.iter().filter(|a| a.tunable) {
        set(instance, a)?;
        any_tunable = true;
    }
    if any_tunable {
        instance
            .rebind(skeleton.skeleton.clone(), &EmptyWorld)
            .map_err(|e| anyhow!("{e}"))?;
    }
    for a in assignments.iter().filter(|a| !a.tunable) {
        set(instance, a)?;
    }
    Ok(())
}

/// What the summary reports about the run.
#[derive(Debug, Default)]
struct Stats {
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
        args.frames,
        args.hz,
        f64::from(args.frames) / args.hz
    );
    if args.frames > 0 {
        let per_frame = stats.busy.as_secs_f64() * 1e6 / f64::from(args.frames);
        let _ = write!(
            s,
            ", {per_frame:.2} µs per frame (wall clock, informational)"
        );
    }
    s.push('\n');
    match &args.out {
        Some(path) => {
            let _ = writeln!(s, "output     {} ({} lines)", path.display(), args.frames);
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
            None if args.frames == 0 => {
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

    fn repo_file(path: &str) -> PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../..")
            .join(path)
    }

    #[test]
    fn tunables_set_before_construction_and_state_after() {
        let (program, skeleton) = load(
            &repo_file("graphs/examples/feet_finder.ron"),
            &repo_file("graphs/skeletons/mannequin.ron"),
        )
        .unwrap();
        let program = Arc::new(program);
        let mut instance = Instance::new(Arc::clone(&program), skeleton.skeleton.clone()).unwrap();
        let sets = ["AnkleHeight=0".to_string()];
        let assignments = parse_assignments(&program, &sets).unwrap();
        apply_assignments(&mut instance, &skeleton, &assignments).unwrap();
        let id = program.variable_id("AnkleHeight").unwrap();
        assert_eq!(instance.variable(id), Value::Float(0.0));
        // Construction ran again with the new ankle height: the soles are the ankles.
        let soles = program.variable_id("LockedFootLocationArray").unwrap();
        let Value::Array(_, soles) = instance.variable(soles) else {
            panic!()
        };
        let foot_l = skeleton.skeleton.find("foot_l").unwrap();
        let Value::Transform(sole) = &soles[0] else {
            panic!()
        };
        let ankle = skeleton.skeleton.rest_global(foot_l).translation;
        assert!((sole.translation - ankle).length() < 1e-4, "{sole:?}");

        assert!(parse_assignments(&program, &["Nope=1".to_string()]).is_err());
        assert!(parse_assignments(&program, &["AnkleHeight=x".to_string()]).is_err());
        assert!(parse_assignments(&program, &["FootArray=1".to_string()]).is_err());
    }

    #[test]
    fn ranges_read_naturally() {
        assert_eq!(range(Some(0.0), Some(20.0)), "0..20");
        assert_eq!(range(None, Some(4.5)), "..4.5");
        assert_eq!(range(Some(1.0), None), "1..");
        assert_eq!(range(None, None), "any value");
    }
}
