//! `strider native GRAPH [--out FILE]`: a graph's forward event as Rust source, compiled
//! ahead of time (the native baseline of `strider bench`).

use crate::check::guard;
use crate::output;
use anyhow::{Context as _, bail};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Arguments of `strider native`.
#[derive(Debug, clap::Args)]
#[command(
    about = "Generate Rust source for a graph's forward event (the native baseline)",
    long_about = "Generate Rust source for a graph's forward event: the compiled program's \
        instructions as straight-line calls of the same node handlers the interpreter runs, \
        with constant operands, and branches and loops as a match over basic blocks. The \
        output is bit-identical to the interpreter; `strider bench` runs it beside the \
        interpreter to report `native_ratio`. The shipped graphs' code lives in \
        crates/strider-native (see docs/performance.md):\n  \
        strider native graphs/locomotion.ron --out crates/strider-native/src/graphs/locomotion.rs"
)]
pub(crate) struct NativeArgs {
    /// The graph file (`Graph( ... )`).
    pub graph: PathBuf,
    /// Write the source here instead of to standard output.
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
}

/// Runs `strider native`.
pub(crate) fn run(args: &NativeArgs) -> anyhow::Result<ExitCode> {
    let program = match guard(&args.graph, || strider_compiler::compile_file(&args.graph)) {
        Ok(p) => p,
        Err(d) => {
            output::print_diagnostics(&d);
            bail!(
                "{} in {}",
                output::problems(d.len().max(1)),
                args.graph.display()
            );
        }
    };
    let source = generate(&program, &args.graph, args.out.as_deref());
    match &args.out {
        Some(path) => std::fs::write(path, source)
            .with_context(|| format!("cannot write {}", path.display()))?,
        None => output::print_stdout(&source)?,
    }
    Ok(ExitCode::SUCCESS)
}

/// The Rust source `strider native` writes for `program`, compiled from `graph`: the
/// generated code ([`strider_vm::native::generate`]) under a header saying how to regenerate
/// it (into `out` when given).
#[must_use]
pub fn generate(program: &strider_vm::Program, graph: &Path, out: Option<&Path>) -> String {
    let graph = graph.display().to_string().replace('\\', "/");
    let command = match out {
        Some(out) => format!(
            "native {graph} --out {}",
            out.display().to_string().replace('\\', "/")
        ),
        None => format!("native {graph}"),
    };
    let header = format!(
        "The forward event of `{graph}`, compiled ahead of time: the native baseline that\n\
         `strider bench` measures the interpreter against (see docs/performance.md).\n\n\
         Generated from the graph; do not edit. Regenerate after changing the graph or the\n\
         compiler with:\n\n```text\ncargo run --release -- {command}\n```\n"
    );
    strider_vm::native::generate(program, program.name(), &header)
}
