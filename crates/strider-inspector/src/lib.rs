//! The Strider inspector: watch a graph run, drive the character, tune it live and travel
//! back in time. A library of egui panels plus a thin eframe app ([`run`]).
//!
//! Conventions are the rig's: world and rig space are +Z up, +Y forward, +X the
//! character's left; centimetres, seconds, degrees. The 3D view draws +X on the left of
//! the screen when the camera looks along +Y (from behind the character), so the
//! character's left is on screen left.
//!
//! The simulation runs at a fixed 1/60 s step ([`session`]); the panels only read it,
//! except the controls that change input, tunables, playback and files:
//!
//! - [`session`]: graph, skeleton, world, mover or scenario, instance, hot reload;
//! - [`recording`]: the ring buffer of the last frames behind time travel;
//! - [`viewport`]: the 3D view (world, skeleton, debug drawing, foot plants);
//! - [`graph_view`]: the graph and its functions as node views (egui-snarl) with live
//!   pin values and per-node times; [`layout`]: where the user dragged its nodes;
//! - [`timeline`], [`variables`], [`plots`], [`quality`], [`diagnostics`]: the other panels;
//! - [`app`]: the eframe app that lays them out and steps the session.

pub mod app;
pub mod diagnostics;
pub mod graph_view;
pub mod layout;
pub mod plots;
pub mod quality;
pub mod recording;
pub mod session;
pub mod timeline;
pub mod values;
pub mod variables;
pub mod viewport;

use std::path::PathBuf;

pub use app::InspectorApp;
pub use session::Session;

/// What to open.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InspectOptions {
    /// The graph file (`Graph( ... )`, RON).
    pub graph: PathBuf,
    /// The skeleton file (`Skeleton( ... )`, RON).
    pub skeleton: PathBuf,
    /// A scenario to play (its world and timeline); the keyboard drives the character when
    /// `None`.
    pub scenario: Option<PathBuf>,
    /// A world file to walk in (ignored with a scenario); the built-in demo world when
    /// both are `None`.
    pub world: Option<PathBuf>,
    /// An overrides file (tunable values, RON map) applied after loading.
    pub overrides: Option<PathBuf>,
}

/// Why the inspector could not run.
#[derive(Debug, thiserror::Error)]
pub enum InspectError {
    /// No display to open a window on (no `DISPLAY` / `WAYLAND_DISPLAY`, or the window
    /// system refused the window).
    #[error(
        "the inspector needs a display, and {0}.\nHeadless, use `strider run GRAPH --skeleton \
         SKEL [--scenario SCEN]` to run a graph (pose dump with --out) or `strider report \
         GRAPH --skeleton SKEL --scenario SCEN` to measure it."
    )]
    NoDisplay(String),
    /// The skeleton, scenario, world or overrides file could not be loaded: every problem,
    /// one per line (`path:line:col: error: ...`). A graph with problems still opens (see
    /// [`Session::open`]).
    #[error("{0}")]
    Load(String),
}

/// Opens the inspector window on `options` and returns when it is closed.
///
/// # Errors
/// [`InspectError::NoDisplay`] without a display (the message names the headless
/// commands), [`InspectError::Load`] when the skeleton, scenario, world or overrides file
/// does not load.
pub fn run(options: InspectOptions) -> Result<(), InspectError> {
    let has_display = ["DISPLAY", "WAYLAND_DISPLAY"]
        .iter()
        .any(|v| std::env::var_os(v).is_some_and(|s| !s.is_empty()));
    if !has_display {
        return Err(InspectError::NoDisplay(
            "neither DISPLAY nor WAYLAND_DISPLAY is set".to_string(),
        ));
    }
    let session = Session::open(options)?;
    let native = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title(format!("Strider inspector — {}", session.program().name()))
            .with_inner_size([1600.0, 950.0]),
        ..Default::default()
    };
    let mut session = Some(session);
    eframe::run_native(
        "Strider inspector",
        native,
        Box::new(move |cc| {
            let session = session
                .take()
                .ok_or("the inspector app was created twice")?;
            Ok(Box::new(InspectorApp::new(&cc.egui_ctx, session)))
        }),
    )
    .map_err(|e| InspectError::NoDisplay(format!("the window could not be opened ({e})")))
}
