//! Loading a graph file with its imports.

use crate::diagnostic::{Diagnostic, Diagnostics, FileId, Loc, SourceMap};
use crate::document::Graph;
use crate::parse::Parser;
use crate::reader::{self, Bump};
use std::path::{Path, PathBuf};

/// A graph and the libraries it imports (transitively), parsed, with their sources.
#[derive(Debug)]
pub struct LoadedGraph {
    /// Every file read, for locations.
    pub sources: SourceMap,
    /// The graph named on the command line.
    pub main: Graph,
    /// Imported library files, each once, in the order first imported.
    pub libraries: Vec<Graph>,
}

/// Reads and parses `path` and everything it imports.
///
/// # Errors
/// Every syntax and structure problem found in any of the files, plus missing imports and
/// import cycles, each with `path:line:col`.
pub fn load_graph(path: &Path) -> Result<LoadedGraph, Vec<Diagnostic>> {
    match std::fs::read_to_string(path) {
        Ok(text) => load_graph_str(path, text),
        Err(e) => {
            let mut d = Diagnostics::default();
            d.file_error(path, format!("cannot read the graph file: {e}"))
                .emit();
            Err(d.into_vec())
        }
    }
}

/// Parses graph `text` as if read from `path` (imports resolve relative to `path`'s folder).
///
/// # Errors
/// As [`load_graph`].
pub fn load_graph_str(path: &Path, text: String) -> Result<LoadedGraph, Vec<Diagnostic>> {
    let mut loader = Loader {
        sources: SourceMap::default(),
        diags: Diagnostics::default(),
        loaded: Vec::new(),
        libraries: Vec::new(),
    };
    let main_file = loader.sources.add(path, text);
    let main = loader.parse(main_file);
    loader.loaded.push(canonical(path));
    let mut stack = vec![canonical(path)];
    if let Some(g) = &main {
        loader.imports(g, &mut stack);
    }
    match main {
        Some(main) if loader.diags.is_empty() => Ok(LoadedGraph {
            sources: loader.sources,
            main,
            libraries: loader.libraries,
        }),
        _ => Err(loader.diags.into_vec()),
    }
}

fn canonical(path: &Path) -> PathBuf {
    std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf())
}

struct Loader {
    sources: SourceMap,
    diags: Diagnostics,
    loaded: Vec<PathBuf>,
    libraries: Vec<Graph>,
}

impl Loader {
    fn parse(&mut self, file: FileId) -> Option<Graph> {
        let arena = Bump::new();
        match reader::parse(self.sources.text(file), &arena) {
            Ok(root) => {
                let mut p = Parser {
                    sources: &self.sources,
                    diags: &mut self.diags,
                    file,
                };
                Some(p.graph(&root))
            }
            Err(e) => {
                self.diags
                    .error(
                        &self.sources,
                        Loc { file, span: e.span },
                        format!("RON syntax: {}", e.message),
                    )
                    .emit();
                None
            }
        }
    }

    fn imports(&mut self, graph: &Graph, stack: &mut Vec<PathBuf>) {
        let base = self
            .sources
            .path(graph.file)
            .parent()
            .map(Path::to_path_buf)
            .unwrap_or_default();
        for import in &graph.imports {
            let path = base.join(&import.name);
            let canon = canonical(&path);
            if let Some(pos) = stack.iter().position(|p| *p == canon) {
                let cycle: Vec<String> = stack[pos..]
                    .iter()
                    .chain(std::iter::once(&canon))
                    .map(|p| {
                        p.file_name()
                            .map(|f| f.to_string_lossy().into_owned())
                            .unwrap_or_default()
                    })
                    .collect();
                self.diags
                    .error(
                        &self.sources,
                        import.loc,
                        format!("import cycle: {}", cycle.join(" → ")),
                    )
                    .hint(
                        "a library must not import, directly or indirectly, a file that imports it",
                    )
                    .emit();
                continue;
            }
            if self.loaded.contains(&canon) {
                continue;
            }
            let text = match std::fs::read_to_string(&path) {
                Ok(t) => t,
                Err(e) => {
                    self.diags
                        .error(
                            &self.sources,
                            import.loc,
                            format!("import not found: `{}` ({e})", path.display()),
                        )
                        .hint(
                            "import paths are relative to the folder of the file that imports them",
                        )
                        .emit();
                    continue;
                }
            };
            self.loaded.push(canon.clone());
            let file = self.sources.add(&path, text);
            if let Some(lib) = self.parse(file) {
                for e in &lib.events {
                    self.diags
                        .error(&self.sources, e.loc, "a library file cannot define events")
                        .hint("move the event to the graph that imports this file")
                        .emit();
                }
                for n in &lib.nodes {
                    self.diags
                        .error(
                            &self.sources,
                            n.loc,
                            "a library file cannot define graph-level nodes",
                        )
                        .node(n.label().to_string())
                        .hint("put the node inside one of the library's functions")
                        .emit();
                }
                stack.push(canon);
                self.imports(&lib, stack);
                stack.pop();
                self.libraries.push(lib);
            }
        }
    }
}
