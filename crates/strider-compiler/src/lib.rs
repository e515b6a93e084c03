//! The compiler: checks a loaded graph document and turns it into an immutable
//! [`Program`].
//!
//! Two passes. The checker resolves every name (nodes, pins, variables, functions, loop
//! names), picks each node's overload from its input types, finds data-flow cycles and
//! recursion (petgraph), validates exec lists, and reports **all** problems as
//! diagnostics. Only a graph without errors reaches `codegen`, which lays out typed slots
//! and emits a flat instruction list: pure nodes are emitted in front of the first exec
//! step that needs them and kept while what they read is unchanged (at most once per
//! loop iteration; `reads` says what each reads), function calls are inlined with their
//! own slots per call site, and control flow becomes jumps.

mod check;
mod codegen;
mod literal;
mod reads;

use std::path::Path;
use strider_graph::{Diagnostic, LoadedGraph};
use strider_vm::Program;

/// How to compile a graph.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Options {
    /// Give every node output, function input and local of every call site a slot of its
    /// own, which still holds its value after a run: for tools that show pin values (the
    /// inspector). Off (the default), values that never outlive a run share slots
    /// ([`strider_vm::ProgramBuilder::finish_sharing_slots`]): a smaller instance and a
    /// faster frame for crowds, with the same results bit for bit.
    pub keep_pin_values: bool,
}

/// Checks and compiles a loaded graph with the default [`Options`].
///
/// # Errors
/// Every problem found, each with `path:line:col`, the node and pin concerned and a hint.
pub fn compile(graph: &LoadedGraph) -> Result<Program, Vec<Diagnostic>> {
    compile_with(graph, Options::default())
}

/// Checks and compiles a loaded graph.
///
/// # Errors
/// As [`compile`].
pub fn compile_with(graph: &LoadedGraph, options: Options) -> Result<Program, Vec<Diagnostic>> {
    let checked = check::check(graph)?;
    Ok(codegen::generate(graph, &checked, options))
}

/// Loads `path` with its imports, checks and compiles it.
///
/// # Errors
/// As [`strider_graph::load_graph`] and [`compile`].
pub fn compile_file(path: &Path) -> Result<Program, Vec<Diagnostic>> {
    compile(&strider_graph::load_graph(path)?)
}

/// Compiles graph text as if read from `path` (imports resolve relative to it).
///
/// # Errors
/// As [`compile_file`].
pub fn compile_str(path: &Path, text: &str) -> Result<Program, Vec<Diagnostic>> {
    compile(&strider_graph::load_graph_str(path, text.to_string())?)
}
