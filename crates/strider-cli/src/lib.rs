//! The `strider` command line.
//!
//! ```text
//! strider check FILE...                       validate graph and skeleton files
//! strider run GRAPH --skeleton SKEL [...]     run a graph headless, optionally dump poses
//! strider report GRAPH --skeleton SKEL --scenario SCEN   measure the motion in a scenario
//! strider bench GRAPH --skeleton SKEL --scenario SCEN   cost per character-frame, crowds
//! strider nodes [--markdown]                  list the built-in nodes
//! strider native GRAPH [--out FILE]           a graph's forward event as Rust source
//! strider inspect [GRAPH] [--scenario SCEN]    the inspector window
//! strider                                     the demo: the inspector on the locomotion
//!                                             graph; without a display, the locomotion
//!                                             report on walk_flat
//! ```
//!
//! The binary itself lives in the root `strider` package (`src/main.rs`), which only calls
//! [`main`]. Exit codes: 0 on success, 1 on any failure (invalid files, I/O errors), 2 for
//! bad command-line arguments (clap's code).

mod alloc_count;
mod bench;
mod check;
mod inspect;
mod jsonl;
mod native;
mod nodes;
mod output;
mod report;
mod run;
mod setup;
mod value;

pub use alloc_count::{CountingAllocator, allocations_on_this_thread};
pub use native::generate as native_source;

use clap::{Parser, Subcommand};
use std::path::PathBuf;
use std::process::ExitCode;

/// The graph `strider` runs without a subcommand, relative to the current directory.
pub(crate) const DEMO_GRAPH: &str = "graphs/locomotion.ron";
/// The skeleton the demo runs on.
pub(crate) const DEMO_SKELETON: &str = "graphs/skeletons/mannequin.ron";
/// The scenario the demo walks through.
const DEMO_SCENARIO: &str = "graphs/scenarios/walk_flat.ron";

#[derive(Debug, Parser)]
#[command(
    name = "strider",
    version,
    about = "Strider: procedural character animation graphs, compiled and run headless",
    long_about = "Strider: procedural character animation graphs, compiled and run headless.\n\n\
        Graphs are RON files (`Graph( ... )`) describing a rig: variables, nodes and events. \
        Skeletons are RON files (`Skeleton( ... )`) listing bones with rest transforms. \
        Rig space is +Z up, +Y forward, +X the character's left; lengths are centimetres, \
        angles degrees, time seconds.\n\n\
        Without a subcommand, opens the inspector on graphs/locomotion.ron and the mannequin \
        in a demo world (`strider inspect`); without a display it says so and runs the \
        headless demo instead: `strider report graphs/locomotion.ron --skeleton \
        graphs/skeletons/mannequin.ron --scenario graphs/scenarios/walk_flat.ron \
        --compare-hz 30,60,144,240`. Paths are relative to the current directory.",
    after_help = "Exit codes: 0 success, 1 failure (invalid files, I/O), 2 bad arguments."
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Debug, Subcommand)]
enum Command {
    Check(check::CheckArgs),
    Run(run::RunArgs),
    Report(report::ReportArgs),
    Nodes(nodes::NodesArgs),
    Native(native::NativeArgs),
    Bench(bench::BenchArgs),
    Inspect(inspect::InspectArgs),
}

/// Parses the command line, runs the command and returns the process exit code.
///
/// Failures are reported on standard error as one `error: ...` line, preceded by any
/// diagnostics (`path:line:col: error: ...`), and give exit code 1; argument errors keep
/// clap's exit code 2. `--help` and `--version` exit with 0.
pub fn main() -> ExitCode {
    run_cli()
}

fn run_cli() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            // Help and version go to stdout with code 0; errors to stderr with code 2.
            let _ = e.print();
            return ExitCode::from(u8::try_from(e.exit_code()).unwrap_or(2));
        }
    };
    let result = match cli.command {
        Some(Command::Check(args)) => check::run(&args),
        Some(Command::Run(args)) => run::run(&args),
        Some(Command::Report(args)) => report::run(&args),
        Some(Command::Nodes(args)) => nodes::run(&args),
        Some(Command::Native(args)) => native::run(&args),
        Some(Command::Bench(args)) => bench::run(&args),
        Some(Command::Inspect(args)) => inspect::run(&args),
        None => demo(),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            // `{:#}` puts the whole context chain on one line.
            output::error_line(&format!("error: {e:#}"));
            ExitCode::FAILURE
        }
    }
}

/// `strider` with no subcommand: the inspector on the locomotion graph in the demo world;
/// without a display (or in a build without the inspector), the headless demo — the
/// locomotion graph walking the `walk_flat` scenario, measured by the quality report —
/// then a hint about the subcommands.
fn demo() -> anyhow::Result<ExitCode> {
    for file in [DEMO_GRAPH, DEMO_SKELETON, DEMO_SCENARIO] {
        if !std::path::Path::new(file).is_file() {
            anyhow::bail!(
                "`{file}` not found in the current directory: run `strider` from the \
                 repository root, or see `strider --help`"
            );
        }
    }
    let inspect = inspect::InspectArgs {
        graph: PathBuf::from(DEMO_GRAPH),
        skeleton: PathBuf::from(DEMO_SKELETON),
        scenario: None,
        world: None,
        overrides: None,
    };
    match inspect::open(&inspect) {
        Ok(()) => return Ok(ExitCode::SUCCESS),
        Err(e) => output::error_line(&format!(
            "note: {e}\nnote: running the headless demo instead\n"
        )),
    }
    let args = report::ReportArgs {
        graph: PathBuf::from(DEMO_GRAPH),
        skeleton: PathBuf::from(DEMO_SKELETON),
        scenario: PathBuf::from(DEMO_SCENARIO),
        hz: 60,
        json: false,
        compare_hz: vec![30, 60, 144, 240],
        plots: None,
        set: Vec::new(),
        overrides: None,
        check: false,
    };
    let code = report::run(&args)?;
    output::print_stdout(
        "\nhint: this was the demo (`strider report graphs/locomotion.ron --skeleton \
         graphs/skeletons/mannequin.ron --scenario graphs/scenarios/walk_flat.ron \
         --compare-hz 30,60,144,240`); other scenarios are in graphs/scenarios/. \
         Subcommands: check, run, report, nodes (see `strider --help`)\n",
    )?;
    Ok(code)
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn the_command_line_definition_is_consistent() {
        Cli::command().debug_assert();
    }

    #[test]
    fn no_subcommand_means_the_demo() {
        let cli = Cli::try_parse_from(["strider"]).unwrap();
        assert!(cli.command.is_none());
    }

    #[test]
    fn bad_arguments_are_clap_errors_with_code_2() {
        let e = Cli::try_parse_from(["strider", "run", "g.ron"]).unwrap_err();
        assert_eq!(e.exit_code(), 2);
        let e = Cli::try_parse_from([
            "strider",
            "run",
            "g.ron",
            "--skeleton",
            "s.ron",
            "--hz",
            "0",
        ])
        .unwrap_err();
        assert_eq!(e.exit_code(), 2);
        let e = Cli::try_parse_from(["strider", "check"]).unwrap_err();
        assert_eq!(e.exit_code(), 2);
    }

    #[test]
    fn run_arguments_parse() {
        let cli = Cli::try_parse_from([
            "strider",
            "run",
            "g.ron",
            "--skeleton",
            "s.ron",
            "--frames",
            "10",
            "--hz",
            "30",
            "--set",
            "Amplitude=3",
            "--set",
            "Offset=(1,2,-3)",
            "--out",
            "o.jsonl",
            "--debug",
        ])
        .unwrap();
        let Some(Command::Run(args)) = cli.command else {
            panic!("not run: {cli:?}");
        };
        assert_eq!(args.frames, Some(10));
        assert_eq!(args.hz, 30.0);
        assert_eq!(args.set, ["Amplitude=3", "Offset=(1,2,-3)"]);
        assert_eq!(args.out, Some(PathBuf::from("o.jsonl")));
        assert!(args.debug);
    }
}
