//! `strider inspect [GRAPH] [--skeleton SKEL] [--scenario SCEN | --world WORLD]`: the
//! inspector window (crate `strider-inspector`, cargo feature `inspector`, on by default).

use std::path::PathBuf;
use std::process::ExitCode;

/// Arguments of `strider inspect`.
#[derive(Debug, clap::Args)]
#[command(
    about = "Open the inspector: watch a graph run, drive the character, tune it live",
    long_about = "Open the inspector window on a graph: a 3D view of the character in a world, \
        the graph with live pin values, every tunable variable, plots, the quality report's \
        figures, time travel over the last 30 s, and hot reload of the files. Without \
        --scenario or --world the character stands in a demo world and the keyboard drives \
        it (WASD, Shift to run, F to switch facing). The graph file is only read; export \
        tuned values as an overrides file from the variables panel. See docs/inspector.md.\n\n\
        Needs a display; without one it says so and names the headless commands."
)]
pub(crate) struct InspectArgs {
    /// Graph file (`Graph( ... )`, RON).
    #[arg(value_name = "GRAPH", default_value = crate::DEMO_GRAPH)]
    pub graph: PathBuf,

    /// Skeleton file (`Skeleton( ... )`, RON).
    #[arg(long, short = 's', value_name = "SKEL", default_value = crate::DEMO_SKELETON)]
    pub skeleton: PathBuf,

    /// Play this scenario (its world and timeline of inputs).
    #[arg(long, value_name = "SCEN", conflicts_with = "world")]
    pub scenario: Option<PathBuf>,

    /// Walk this world (`(shapes: [...])`, RON) with the keyboard.
    #[arg(long, value_name = "WORLD")]
    pub world: Option<PathBuf>,

    /// Apply the tunable values of this overrides file after loading.
    #[arg(long, value_name = "FILE")]
    pub overrides: Option<PathBuf>,
}

/// Runs `strider inspect`.
pub(crate) fn run(args: &InspectArgs) -> anyhow::Result<ExitCode> {
    open(args)?;
    Ok(ExitCode::SUCCESS)
}

/// Opens the window and returns when it is closed.
#[cfg(feature = "inspector")]
pub(crate) fn open(args: &InspectArgs) -> Result<(), strider_inspector::InspectError> {
    strider_inspector::run(strider_inspector::InspectOptions {
        graph: args.graph.clone(),
        skeleton: args.skeleton.clone(),
        scenario: args.scenario.clone(),
        world: args.world.clone(),
        overrides: args.overrides.clone(),
    })
}

/// Without the `inspector` feature there is no window to open.
#[cfg(not(feature = "inspector"))]
pub(crate) fn open(_: &InspectArgs) -> anyhow::Result<()> {
    anyhow::bail!(
        "this build of strider has no inspector (it was built without the `inspector` \
         feature); headless, use `strider run` or `strider report`"
    )
}
