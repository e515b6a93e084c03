//! Layout files: where the user dragged the graph view's nodes, kept next to the graph so
//! that the graph file itself is never rewritten.
//!
//! `graphs/locomotion.ron` has its layout in `graphs/locomotion.layout.ron`, a RON map from
//! body (`"<top>"` for the graph's top level, else the function's name) to a map from node
//! (its id; a node without id is `label#n`, the n-th such node of that label in the body,
//! from 0) to its canvas position `(x, y)`:
//!
//! ```ron
//! {
//!     "<top>": { "t": (0.0, 0.0), "Set Time#0": (300.0, 0.0) },
//!     "Wave": { "cycles": (0.0, 40.0) },
//! }
//! ```
//!
//! A node's position comes from the layout file, else from the graph file's `editor`
//! section, else from the automatic layout.

use egui::{Pos2, pos2};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// The body name of the graph's top level in a layout file.
pub const TOP_LEVEL: &str = "<top>";

/// Node positions per body, canvas units.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Layout {
    /// Body name → node key → position.
    pub bodies: BTreeMap<String, BTreeMap<String, (f32, f32)>>,
}

impl Layout {
    /// The layout file of `graph`: `<graph stem>.layout.ron` next to it.
    #[must_use]
    pub fn path_for(graph: &Path) -> PathBuf {
        let stem = graph
            .file_stem()
            .map_or_else(|| "graph".to_string(), |s| s.to_string_lossy().into_owned());
        graph.with_file_name(format!("{stem}.layout.ron"))
    }

    /// Reads the layout file at `path`; an empty layout when there is none.
    ///
    /// # Errors
    /// `path:line:col: error: ...` when it cannot be read or is not a layout.
    pub fn load(path: &Path) -> Result<Layout, String> {
        match std::fs::read_to_string(path) {
            Ok(text) => Layout::parse(path, &text),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(Layout::default()),
            Err(e) => Err(format!(
                "{}:1:1: error: cannot read the layout file: {e}",
                path.display()
            )),
        }
    }

    /// Parses a layout file's text (`path` names it in errors).
    ///
    /// # Errors
    /// `path:line:col: error: ...` for a syntax error, a value that is not a map of maps
    /// of `(x, y)`, or a coordinate that is not finite.
    pub fn parse(path: &Path, text: &str) -> Result<Layout, String> {
        let bodies: BTreeMap<String, BTreeMap<String, (f32, f32)>> =
            ron::from_str(text).map_err(|e| {
                format!(
                    "{}:{}:{}: error: {} (a layout file maps body names to maps of node \
                     positions, `{{ \"<top>\": {{ \"node\": (x, y) }} }}`)",
                    path.display(),
                    e.span.start.line,
                    e.span.start.col,
                    e.code
                )
            })?;
        for (body, nodes) in &bodies {
            for (node, (x, y)) in nodes {
                if !x.is_finite() || !y.is_finite() {
                    return Err(format!(
                        "{}:1:1: error: the position of `{node}` in `{body}` is not finite",
                        path.display()
                    ));
                }
            }
        }
        Ok(Layout { bodies })
    }

    /// The layout as a layout file's text (bodies and nodes sorted by name).
    #[must_use]
    pub fn to_ron(&self) -> String {
        let mut s = String::from(
            "// Node positions arranged in the Strider inspector (canvas units); the graph \
             file is never rewritten.\n{\n",
        );
        for (body, nodes) in &self.bodies {
            let _ = writeln!(s, "    {body:?}: {{");
            for (node, (x, y)) in nodes {
                let _ = writeln!(s, "        {node:?}: ({x:?}, {y:?}),");
            }
            s.push_str("    },\n");
        }
        s.push_str("}\n");
        s
    }

    /// Writes the layout file at `path`.
    ///
    /// # Errors
    /// When it cannot be written.
    pub fn save(&self, path: &Path) -> Result<(), String> {
        std::fs::write(path, self.to_ron())
            .map_err(|e| format!("cannot write {}: {e}", path.display()))
    }

    /// The position of node `node` of body `body`, if the layout has one.
    #[must_use]
    pub fn position(&self, body: &str, node: &str) -> Option<Pos2> {
        let (x, y) = self.bodies.get(body)?.get(node)?;
        Some(pos2(*x, *y))
    }

    /// Sets the position of node `node` of body `body`.
    pub fn set(&mut self, body: &str, node: &str, at: Pos2) {
        self.bodies
            .entry(body.to_string())
            .or_default()
            .insert(node.to_string(), (at.x, at.y));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_layout_reads_back_what_it_writes_and_reports_bad_files() {
        let mut layout = Layout::default();
        layout.set(TOP_LEVEL, "t", pos2(10.5, -3.0));
        layout.set("Wave", "Return#0", pos2(300.0, 0.25));
        let path = Path::new("bob.layout.ron");
        assert_eq!(Layout::parse(path, &layout.to_ron()), Ok(layout));
        assert_eq!(
            Layout::path_for(Path::new("graphs/locomotion.ron")),
            Path::new("graphs/locomotion.layout.ron")
        );
        // The second line's value is not a position.
        let err = Layout::parse(path, "{\n  \"<top>\": { \"t\": 3 } }").expect_err("bad");
        assert!(err.starts_with("bob.layout.ron:2:"), "{err}");
    }
}
