//! `strider report GRAPH --skeleton SKEL --scenario SCEN`: run a graph through a scenario in
//! its world and measure the motion from the output poses (foot skate, penetration, idle
//! float, crossing legs, backward knees, pops, non-finite values, steps, and frame-rate
//! deviation across several rates), as a table or one JSON object, with optional plots.

use crate::output;
use crate::setup::{Assignment, apply_assignments, instantiate, load, resolve_assignments};
use anyhow::{Context as _, anyhow, bail};
use indicatif::{ProgressBar, ProgressStyle};
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::Arc;
use strider_graph::SkeletonFile;
use strider_host::report::{FrameRecord, ReportRig, analyse, framerate_deviation};
use strider_host::scenario::{Scenario, Simulation};
use strider_host::world::World;
use strider_host::{drive, plots};
use strider_vm::Program;

/// Arguments of `strider report`.
#[derive(Debug, clap::Args)]
#[command(
    about = "Run a graph through a scenario and report foot skate, penetration, pops and more",
    long_about = "Run a graph through a scenario and report the quality of the motion.\n\n\
        The scenario (graphs/scenarios/*.ron) gives a world and a timeline of inputs; a \
        kinematic capsule follows the inputs and places the character, and the graph runs \
        every frame from the rest pose. The report is computed from the output poses and the \
        world only, never from the graph's variables: foot skate per stance, penetration \
        and idle float of the sole contact points (from the skeleton file's `contacts`), \
        crossing legs, backward knees, over-extended legs, pops, non-finite values, steps, \
        cadence and step length. The definitions are in docs/report.md.\n\n\
        With --compare-hz the scenario also runs at each listed rate and the report adds \
        the largest distance between the same bone's world position at the same time \
        stamps across the rates. With --check the exit code is 1 when a target is missed."
)]
pub(crate) struct ReportArgs {
    /// Graph file to run (`Graph( ... )`, RON).
    #[arg(value_name = "GRAPH")]
    pub graph: PathBuf,

    /// Skeleton file (`Skeleton( ... )`, RON) with sole contact points.
    #[arg(long, short = 's', value_name = "SKEL")]
    pub skeleton: PathBuf,

    /// Scenario file (`Scenario( ... )`, RON): a world and a timeline of inputs.
    #[arg(long, value_name = "SCEN")]
    pub scenario: PathBuf,

    /// Frame rate in Hz (whole frames per second).
    #[arg(long, value_name = "H", default_value_t = 60, value_parser = clap::value_parser!(u32).range(1..=10_000))]
    pub hz: u32,

    /// Print one JSON object instead of the table.
    #[arg(long)]
    pub json: bool,

    /// Also run at these rates (Hz, comma separated, e.g. 30,60,144,240) and report the
    /// largest frame-rate deviation of any bone at the time stamps the rates share.
    #[arg(long, value_name = "HZ,HZ,...", value_delimiter = ',', value_parser = clap::value_parser!(u32).range(1..=10_000))]
    pub compare_hz: Vec<u32>,

    /// Write plots (SVG) into this directory: foot heights with planted spans, a top-down
    /// map of foot plants and the path, pelvis height.
    #[arg(long, value_name = "DIR")]
    pub plots: Option<PathBuf>,

    /// Set a graph variable before the first frame; repeatable (as in `strider run`).
    #[arg(long, value_name = "NAME=VALUE")]
    pub set: Vec<String>,

    /// Set tunable variables from an overrides file (a RON map `{ "Name": value, ... }`, as
    /// the inspector exports) before the first frame; `--set` wins for a variable both give.
    #[arg(long, value_name = "FILE")]
    pub overrides: Option<PathBuf>,

    /// Exit with code 1 when any target is missed.
    #[arg(long)]
    pub check: bool,
}

/// Runs `strider report`.
pub(crate) fn run(args: &ReportArgs) -> anyhow::Result<ExitCode> {
    let (program, skeleton) = load(&args.graph, &args.skeleton)?;
    let program = Arc::new(program);
    let assignments = resolve_assignments(&program, args.overrides.as_deref(), &args.set)?;
    let scenario = Scenario::load(&args.scenario).map_err(|e| anyhow!("{e}"))?;
    let rig = ReportRig::from_skeleton(&skeleton).map_err(|e| {
        anyhow!(
            "{}: cannot measure this skeleton: {e}",
            args.skeleton.display()
        )
    })?;

    // Every rate to run: the main one first, then the comparisons it does not repeat.
    let mut rates = vec![args.hz];
    for &hz in &args.compare_hz {
        if !rates.contains(&hz) {
            rates.push(hz);
        }
    }
    let total: usize = rates
        .iter()
        .map(|&hz| Simulation::new(&scenario, hz).frame_count())
        .sum();
    let bar = ProgressBar::new(total as u64);
    bar.set_style(
        ProgressStyle::with_template("{msg:>12} [{bar:40}] {pos}/{len} frames ({eta})")
            .unwrap_or_else(|_| ProgressStyle::default_bar())
            .progress_chars("=> "),
    );

    let mut runs: Vec<(u32, Vec<FrameRecord>)> = Vec::with_capacity(rates.len());
    let mut world = None;
    for &hz in &rates {
        bar.set_message(format!("{hz} Hz"));
        let (frames, w) = record(&program, &skeleton, args, &assignments, &scenario, hz, &bar)?;
        runs.push((hz, frames));
        world.get_or_insert(w);
    }
    bar.finish_and_clear();
    let world = world.ok_or_else(|| anyhow!("no frame rate to run"))?;

    let main = &runs[0].1;
    let mut report = analyse(&rig, main, &world);
    if !args.compare_hz.is_empty() {
        let compared: Vec<(u32, &[FrameRecord])> = runs
            .iter()
            .filter(|(hz, _)| args.compare_hz.contains(hz))
            .map(|(hz, frames)| (*hz, frames.as_slice()))
            .collect();
        report.framerate_deviation_cm_max = Some(framerate_deviation(&compared));
    }

    let mut written = Vec::new();
    if let Some(dir) = &args.plots {
        std::fs::create_dir_all(dir)
            .with_context(|| format!("cannot create the plot directory `{}`", dir.display()))?;
        written =
            plots::write_plots(dir, &rig, main, &world, &report).map_err(|e| anyhow!("{e}"))?;
    }

    if args.json {
        let mut value = serde_json::to_value(&report)?;
        if let Some(object) = value.as_object_mut() {
            object.insert("graph".into(), program.name().into());
            object.insert("scenario".into(), scenario.name.clone().into());
            object.insert("targets_met".into(), report.all_targets_met().into());
        }
        output::print_stdout(&format!("{value}\n"))?;
    } else {
        let mut text = format!(
            "graph     {} ({})\nscenario  {} ({}), {:.2} s at {} Hz\n\n",
            program.name(),
            args.graph.display(),
            scenario.name,
            args.scenario.display(),
            report.duration_s,
            args.hz
        );
        text.push_str(&report.table());
        for path in &written {
            text.push_str(&format!("plot      {}\n", path.display()));
        }
        output::print_stdout(&text)?;
    }
    if args.check && !report.all_targets_met() {
        let missed: Vec<&str> = report
            .targets_met()
            .iter()
            .filter(|t| !t.met)
            .map(|t| t.metric)
            .collect();
        bail!("targets missed: {}", missed.join(", "));
    }
    Ok(ExitCode::SUCCESS)
}

/// One run of the scenario at `hz` on a fresh instance.
fn record(
    program: &Arc<Program>,
    skeleton: &SkeletonFile,
    args: &ReportArgs,
    assignments: &[Assignment],
    scenario: &Scenario,
    hz: u32,
    bar: &ProgressBar,
) -> anyhow::Result<(Vec<FrameRecord>, World)> {
    let mut instance = instantiate(program, skeleton, &args.skeleton)?;
    let world = World::from_desc(&scenario.world);
    apply_assignments(&mut instance, skeleton, assignments, &world)?;
    Ok(drive::record(&mut instance, scenario, hz, |_, _| {
        bar.inc(1)
    }))
}
