//! Diagnostics: `path:line:col: error: message`, the node and pin concerned, and a hint.

use crate::reader::{LineIndex, Span};
use std::fmt;
use std::path::{Path, PathBuf};

/// Identifies a source file in a [`SourceMap`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub struct FileId(pub u32);

/// A place in a source file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Loc {
    /// The file.
    pub file: FileId,
    /// Byte range in it.
    pub span: Span,
}

struct SourceFile {
    path: PathBuf,
    /// `path` as shown in `path:line:col` (lossy UTF-8), made once: the compiler describes
    /// a location for every node it emits.
    shown: String,
    /// The text and where its lines start.
    lines: LineIndex,
}

/// The text of every file read, so locations can be shown as `path:line:col`.
#[derive(Default)]
pub struct SourceMap {
    files: Vec<SourceFile>,
}

impl fmt::Debug for SourceMap {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_list()
            .entries(self.files.iter().map(|s| &s.path))
            .finish()
    }
}

impl SourceMap {
    /// Adds a file's text.
    pub fn add(&mut self, path: &Path, text: String) -> FileId {
        self.files.push(SourceFile {
            path: path.to_path_buf(),
            shown: path.display().to_string(),
            lines: LineIndex::of(text),
        });
        FileId((self.files.len() - 1) as u32)
    }

    /// A file's path as given.
    #[must_use]
    pub fn path(&self, file: FileId) -> &Path {
        &self.files[file.0 as usize].path
    }

    /// A file's text.
    #[must_use]
    pub fn text(&self, file: FileId) -> &str {
        self.files[file.0 as usize].lines.text()
    }

    /// Every file, in the order read.
    pub fn files(&self) -> impl Iterator<Item = FileId> + '_ {
        (0..self.files.len()).map(|i| FileId(i as u32))
    }

    /// 1-based line and column of a location.
    #[must_use]
    pub fn line_col(&self, loc: Loc) -> (usize, usize) {
        self.files[loc.file.0 as usize]
            .lines
            .line_col(loc.span.start)
    }

    /// `path:line:col` of a location.
    #[must_use]
    pub fn describe(&self, loc: Loc) -> String {
        // Built without `format!`: the compiler describes every node it emits.
        let (line, col) = self.line_col(loc);
        let (mut line_digits, mut col_digits) = (itoa::Buffer::new(), itoa::Buffer::new());
        let (line, col) = (line_digits.format(line), col_digits.format(col));
        let shown = &self.files[loc.file.0 as usize].shown;
        let mut out = String::with_capacity(shown.len() + line.len() + col.len() + 2);
        for part in [shown, ":", line, ":", col] {
            out.push_str(part);
        }
        out
    }
}

/// One problem found in a graph, skeleton or scenario file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Diagnostic {
    /// The file, as given on the command line or in an import.
    pub path: PathBuf,
    /// 1-based line.
    pub line: usize,
    /// 1-based column, in characters.
    pub col: usize,
    /// What is wrong.
    pub message: String,
    /// The node concerned, if any (its id, or its type for an anonymous exec node).
    pub node: Option<String>,
    /// The pin concerned, if any.
    pub pin: Option<String>,
    /// How to fix it.
    pub hint: Option<String>,
}

impl fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}:{}:{}: error: {}",
            self.path.display(),
            self.line,
            self.col,
            self.message
        )?;
        match (&self.node, &self.pin) {
            (Some(n), Some(p)) => write!(f, " [node `{n}`, pin `{p}`]")?,
            (Some(n), None) => write!(f, " [node `{n}`]")?,
            (None, Some(p)) => write!(f, " [pin `{p}`]")?,
            (None, None) => {}
        }
        if let Some(h) = &self.hint {
            write!(f, "\n  hint: {h}")?;
        }
        Ok(())
    }
}

/// Collects diagnostics against a [`SourceMap`], in the order found.
#[derive(Debug, Default)]
pub struct Diagnostics {
    list: Vec<Diagnostic>,
}

/// Builder for one diagnostic; adds node, pin and hint before [`Report::emit`].
#[must_use = "call .emit() to record the diagnostic"]
pub struct Report<'a> {
    sink: &'a mut Diagnostics,
    diagnostic: Diagnostic,
}

impl Report<'_> {
    /// Names the node concerned.
    pub fn node(mut self, node: impl Into<String>) -> Self {
        self.diagnostic.node = Some(node.into());
        self
    }

    /// Names the pin concerned.
    pub fn pin(mut self, pin: impl Into<String>) -> Self {
        self.diagnostic.pin = Some(pin.into());
        self
    }

    /// Says how to fix it.
    pub fn hint(mut self, hint: impl Into<String>) -> Self {
        self.diagnostic.hint = Some(hint.into());
        self
    }

    /// Adds a hint when there is one.
    pub fn maybe_hint(mut self, hint: Option<String>) -> Self {
        if hint.is_some() {
            self.diagnostic.hint = hint;
        }
        self
    }

    /// Records the diagnostic.
    pub fn emit(self) {
        self.sink.list.push(self.diagnostic);
    }
}

impl Diagnostics {
    /// Starts a diagnostic at `loc`.
    pub fn error(
        &mut self,
        sources: &SourceMap,
        loc: Loc,
        message: impl Into<String>,
    ) -> Report<'_> {
        let (line, col) = sources.line_col(loc);
        Report {
            diagnostic: Diagnostic {
                path: sources.path(loc.file).to_path_buf(),
                line,
                col,
                message: message.into(),
                node: None,
                pin: None,
                hint: None,
            },
            sink: self,
        }
    }

    /// Starts a diagnostic about a whole file (line 1, column 1) — for a file that cannot
    /// be read at all.
    pub fn file_error(&mut self, path: &Path, message: impl Into<String>) -> Report<'_> {
        Report {
            diagnostic: Diagnostic {
                path: path.to_path_buf(),
                line: 1,
                col: 1,
                message: message.into(),
                node: None,
                pin: None,
                hint: None,
            },
            sink: self,
        }
    }

    /// Names `node` and `pin` on the diagnostics recorded since the first `since` ones that
    /// do not name any yet (a check that found a bad link inside a pin, say).
    pub fn annotate_since(&mut self, since: usize, node: &str, pin: &str) {
        for d in self.list.iter_mut().skip(since) {
            if d.node.is_none() && d.pin.is_none() {
                d.node = Some(node.to_string());
                d.pin = Some(pin.to_string());
            }
        }
    }

    /// Adds finished diagnostics.
    pub fn extend(&mut self, other: impl IntoIterator<Item = Diagnostic>) {
        self.list.extend(other);
    }

    /// True when nothing was reported.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.list.is_empty()
    }

    /// Number of diagnostics.
    #[must_use]
    pub fn len(&self) -> usize {
        self.list.len()
    }

    /// The diagnostics, in the order found.
    #[must_use]
    pub fn into_vec(self) -> Vec<Diagnostic> {
        self.list
    }

    /// The diagnostics so far.
    #[must_use]
    pub fn as_slice(&self) -> &[Diagnostic] {
        &self.list
    }
}
