//! Graph files as text: reading RON with spans, the editable document types, loading a
//! graph with its imports, loading skeleton files, and the diagnostics every later phase
//! reports through.
//!
//! The document types here are the *editable* form of a graph (what a person wrote, with
//! where they wrote it). `strider-compiler` turns them into the immutable runtime
//! [`Program`](../strider_vm/struct.Program.html).

pub mod diagnostic;
pub mod document;
pub mod load;
mod parse;
pub mod reader;
pub mod skeleton_file;

pub use diagnostic::{Diagnostic, Diagnostics, FileId, Loc, SourceMap};
pub use document::*;
pub use load::{LoadedGraph, load_graph, load_graph_str};
pub use skeleton_file::{SkeletonFile, load_skeleton, load_skeleton_str};

/// The newest graph and skeleton file format version this build reads.
pub const FORMAT_VERSION: u32 = 1;

/// The name among `candidates` closest to `name`, for "did you mean" hints.
#[must_use]
pub fn suggest<'a>(name: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<String> {
    let mut best: Option<(f64, &str)> = None;
    for c in candidates {
        let score = strsim::jaro_winkler(&name.to_lowercase(), &c.to_lowercase());
        if score > 0.8 && best.is_none_or(|(s, _)| score > s) {
            best = Some((score, c));
        }
    }
    best.map(|(_, c)| c.to_string())
}
