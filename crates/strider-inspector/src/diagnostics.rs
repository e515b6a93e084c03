//! The diagnostics panel: what the last load or reload said, every problem as
//! `path:line:col: error: ...`, and which files are watched.

use crate::session::Session;
use egui::{Color32, RichText, Ui};

/// Shows the status line, the problems of the last reload and the watched files.
pub fn show(ui: &mut Ui, session: &Session) {
    let problems = session.problems();
    if problems.is_empty() {
        ui.label(RichText::new("✔ no problems").color(Color32::from_rgb(120, 220, 120)));
    } else {
        let running = if session.graph_loaded() {
            "the last good program keeps running"
        } else {
            "nothing runs until the graph loads"
        };
        ui.label(
            RichText::new(format!(
                "{} problem{} — {running}",
                problems.len(),
                if problems.len() == 1 { "" } else { "s" }
            ))
            .color(Color32::from_rgb(255, 140, 110)),
        );
        for p in problems {
            ui.label(
                RichText::new(p)
                    .monospace()
                    .color(Color32::from_rgb(255, 180, 160)),
            );
        }
    }
    ui.label(RichText::new(session.status()).weak());
    ui.collapsing("Watched files", |ui| {
        for f in session.watched_files() {
            ui.label(RichText::new(f.display().to_string()).monospace().small());
        }
    });
}
