//! Opens the inspector for manual runs:
//!
//! ```sh
//! cargo run -p strider-inspector --release --example inspect -- \
//!     [GRAPH] [--skeleton SKEL] [--scenario SCEN | --world WORLD] [--overrides FILE]
//! ```
//!
//! Without arguments: `graphs/locomotion.ron` on the mannequin in the demo world (from the
//! repository root: the current folder when it holds `graphs/`, else found from this
//! crate's folder).

use std::path::PathBuf;
use std::process::ExitCode;
use strider_inspector::{InspectOptions, run};

fn main() -> ExitCode {
    // Relative paths from the repository root when run from there (shorter messages).
    let root = if PathBuf::from("graphs/locomotion.ron").exists() {
        PathBuf::new()
    } else {
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
    };
    let mut options = InspectOptions {
        graph: root.join("graphs/locomotion.ron"),
        skeleton: root.join("graphs/skeletons/mannequin.ron"),
        scenario: None,
        world: None,
        overrides: None,
    };
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        let mut value = |name: &str| match args.next() {
            Some(v) => Ok(PathBuf::from(v)),
            None => Err(format!("{name} needs a file")),
        };
        let result = match arg.as_str() {
            "--skeleton" => value("--skeleton").map(|v| options.skeleton = v),
            "--scenario" => value("--scenario").map(|v| options.scenario = Some(v)),
            "--world" => value("--world").map(|v| options.world = Some(v)),
            "--overrides" => value("--overrides").map(|v| options.overrides = Some(v)),
            other if !other.starts_with('-') => {
                options.graph = PathBuf::from(other);
                Ok(())
            }
            other => Err(format!("unknown option `{other}`")),
        };
        if let Err(e) = result {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    }
    match run(options) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("{e}");
            ExitCode::FAILURE
        }
    }
}
