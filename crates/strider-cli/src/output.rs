//! Writing to the terminal without panicking: `println!` panics when stdout is a closed
//! pipe (`strider nodes | head`), these helpers do not.

use std::io::{self, Write};
use strider_graph::Diagnostic;

/// Writes `text` to standard output as is. A closed pipe is not an error (the reader has
/// seen enough); any other failure (disk full behind a redirect) is.
pub(crate) fn print_stdout(text: &str) -> anyhow::Result<()> {
    let mut out = io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == io::ErrorKind::BrokenPipe => Ok(()),
        Err(e) => Err(anyhow::Error::new(e).context("cannot write to standard output")),
    }
}

/// Writes one line to standard error, ignoring failures (there is nowhere left to report
/// them).
pub(crate) fn error_line(line: &str) {
    let _ = writeln!(io::stderr().lock(), "{line}");
}

/// Prints every diagnostic on standard error, in order.
pub(crate) fn print_diagnostics(diagnostics: &[Diagnostic]) {
    let mut err = io::stderr().lock();
    for d in diagnostics {
        let _ = writeln!(err, "{d}");
    }
}

/// `1 problem` / `3 problems`.
pub(crate) fn problems(n: usize) -> String {
    if n == 1 {
        "1 problem".to_string()
    } else {
        format!("{n} problems")
    }
}
