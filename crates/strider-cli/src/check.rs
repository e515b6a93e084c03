//! `strider check FILE...`: load and validate graph and skeleton files.

use crate::output;
use std::panic::{self, AssertUnwindSafe};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use strider_graph::Diagnostic;

/// Arguments of `strider check`.
#[derive(Debug, clap::Args)]
#[command(
    about = "Validate graph and skeleton files and print every problem found",
    long_about = "Validate graph and skeleton files and print every problem found.\n\n\
        A file whose text (after comments and whitespace) starts with `Skeleton` is read as \
        a skeleton: bone names, parents, rest transforms and contact points are checked. \
        Any other file is read as a graph, with its imports, and fully compiled (names, \
        types, cycles, exec chains); bone names are only checked against a skeleton by \
        `strider run`.\n\n\
        Valid files print `ok: PATH` on stdout. Problems are printed on stderr as \
        `path:line:col: error: message`, followed by `error: N problems in PATH`. The exit \
        code is 0 when every file is valid, 1 otherwise."
)]
pub(crate) struct CheckArgs {
    /// Graph (`Graph( ... )`) or skeleton (`Skeleton( ... )`) RON files to check; all are
    /// checked even when one fails.
    #[arg(required = true, value_name = "FILE")]
    pub files: Vec<PathBuf>,
}

/// What a file holds, judged by its first word.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum FileKind {
    /// `Graph( ... )` (or anything that is not a skeleton: the graph loader reports it).
    Graph,
    /// `Skeleton( ... )`.
    Skeleton,
}

/// Runs `strider check`.
pub(crate) fn run(args: &CheckArgs) -> anyhow::Result<ExitCode> {
    let mut all_ok = true;
    for path in &args.files {
        match check_file(path) {
            Ok(_) => output::print_stdout(&format!("ok: {}\n", path.display()))?,
            Err(diagnostics) => {
                all_ok = false;
                output::print_diagnostics(&diagnostics);
                output::error_line(&format!(
                    "error: {} in {}",
                    output::problems(diagnostics.len().max(1)),
                    path.display()
                ));
            }
        }
    }
    Ok(if all_ok {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    })
}

/// Loads and validates one file, whatever it contains: a missing file, a directory or
/// binary data give a diagnostic, never a panic.
pub(crate) fn check_file(path: &Path) -> Result<FileKind, Vec<Diagnostic>> {
    let text = read_text(path)?;
    let kind = sniff(&text);
    guard(path, || match kind {
        FileKind::Skeleton => strider_graph::load_skeleton_str(path, text).map(|_| ()),
        FileKind::Graph => strider_graph::load_graph_str(path, text)
            .and_then(|graph| strider_compiler::compile(&graph))
            .map(|_| ()),
    })?;
    Ok(kind)
}

/// Runs a loader, turning a panic in it (a bug) into a diagnostic so that one bad file
/// does not stop the others from being checked.
pub(crate) fn guard<T>(
    path: &Path,
    f: impl FnOnce() -> Result<T, Vec<Diagnostic>>,
) -> Result<T, Vec<Diagnostic>> {
    match panic::catch_unwind(AssertUnwindSafe(f)) {
        Ok(result) => result,
        Err(payload) => {
            let what = payload
                .downcast_ref::<&str>()
                .map(|s| (*s).to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            Err(vec![file_diagnostic(
                path,
                1,
                1,
                format!(
                    "internal error: the loader crashed on this file ({what}); please report it"
                ),
            )])
        }
    }
}

/// Reads a file as UTF-8 text, or explains why it cannot.
pub(crate) fn read_text(path: &Path) -> Result<String, Vec<Diagnostic>> {
    let bytes = std::fs::read(path).map_err(|e| {
        vec![file_diagnostic(
            path,
            1,
            1,
            format!("cannot read the file: {e}"),
        )]
    })?;
    String::from_utf8(bytes).map_err(|e| {
        let bytes = e.as_bytes();
        let at = e.utf8_error().valid_up_to();
        let before = &bytes[..at];
        let line = before.iter().filter(|&&b| b == b'\n').count() + 1;
        let line_start = before
            .iter()
            .rposition(|&b| b == b'\n')
            .map_or(0, |i| i + 1);
        // The prefix is valid UTF-8 by definition of `valid_up_to`.
        let col = std::str::from_utf8(&before[line_start..]).map_or(1, |s| s.chars().count() + 1);
        vec![file_diagnostic(
            path,
            line,
            col,
            format!("not a text file: invalid UTF-8 at byte {at}"),
        )]
    })
}

fn file_diagnostic(path: &Path, line: usize, col: usize, message: String) -> Diagnostic {
    Diagnostic {
        path: path.to_path_buf(),
        line,
        col,
        message,
        node: None,
        pin: None,
        hint: None,
    }
}

/// `Skeleton` when the first word after whitespace and comments (`// ...`, nested
/// `/* ... */`, a byte-order mark) is `Skeleton`; `Graph` otherwise.
pub(crate) fn sniff(text: &str) -> FileKind {
    let mut rest = text.trim_start_matches('\u{feff}');
    loop {
        rest = rest.trim_start();
        if let Some(after) = rest.strip_prefix("//") {
            rest = after.find('\n').map_or("", |i| &after[i + 1..]);
        } else if rest.starts_with("/*") {
            rest = skip_block_comment(rest);
        } else {
            break;
        }
    }
    match rest.strip_prefix("Skeleton") {
        Some(after) if !after.starts_with(|c: char| c.is_alphanumeric() || c == '_') => {
            FileKind::Skeleton
        }
        _ => FileKind::Graph,
    }
}

/// `text` starts with `/*`: what follows the matching `*/` (comments nest, as in RON), or
/// nothing when it is never closed.
fn skip_block_comment(text: &str) -> &str {
    let mut depth = 0usize;
    let mut i = 0;
    let b = text.as_bytes();
    while i + 1 < b.len() {
        match (b[i], b[i + 1]) {
            (b'/', b'*') => {
                depth += 1;
                i += 2;
            }
            (b'*', b'/') => {
                depth -= 1;
                i += 2;
                if depth == 0 {
                    // `i` follows an ASCII byte, so it is a char boundary.
                    return &text[i..];
                }
            }
            _ => i += 1,
        }
    }
    ""
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sniffs_skeletons_after_comments() {
        assert_eq!(sniff("Skeleton(version: 1)"), FileKind::Skeleton);
        assert_eq!(
            sniff("\u{feff}// a comment\n  /* block /* nested */ still */\n\tSkeleton ("),
            FileKind::Skeleton
        );
        assert_eq!(sniff("// Skeleton\nGraph(version: 1)"), FileKind::Graph);
        assert_eq!(sniff("SkeletonX("), FileKind::Graph);
        assert_eq!(sniff(""), FileKind::Graph);
        assert_eq!(sniff("/* never closed Skeleton"), FileKind::Graph);
        assert_eq!(sniff("//"), FileKind::Graph);
        assert_eq!(sniff("/*/"), FileKind::Graph);
        assert_eq!(sniff("/* é */Skeleton()"), FileKind::Skeleton);
    }

    #[test]
    fn unreadable_inputs_are_diagnostics() {
        let dir = std::env::temp_dir().join(format!("strider-check-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();

        // A directory.
        let d = check_file(&dir).unwrap_err();
        assert_eq!(d.len(), 1);
        assert!(d[0].message.starts_with("cannot read the file"), "{}", d[0]);

        // A missing file.
        let d = check_file(&dir.join("missing.ron")).unwrap_err();
        assert!(d[0].message.starts_with("cannot read the file"), "{}", d[0]);

        // Binary garbage: located at the first bad byte.
        let bin = dir.join("garbage.ron");
        std::fs::write(&bin, b"Graph(\n  ab\xff\xfe\x00").unwrap();
        let d = check_file(&bin).unwrap_err();
        assert_eq!((d[0].line, d[0].col), (2, 5), "{}", d[0]);

        // Text that is neither a graph nor a skeleton.
        let junk = dir.join("junk.ron");
        for text in [
            "",
            "(",
            "Skeleton(",
            "Graph(",
            "Skeleton(bones: [(name: 1)])",
            "]]]",
        ] {
            std::fs::write(&junk, text).unwrap();
            assert!(check_file(&junk).is_err(), "{text:?} accepted");
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
