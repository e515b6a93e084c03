//! The quality panel: the locomotion report's metrics (docs/report.md) for the recorded
//! frames of the current run, recomputed twice a second, each against its target.

use crate::session::Session;
use egui::{Color32, RichText, Ui};

/// Shows the live report.
pub fn show(ui: &mut Ui, session: &Session) {
    let q = session.quality();
    let Some(report) = &q.report else {
        ui.label(q.unavailable.as_deref().unwrap_or("measuring…"));
        return;
    };
    ui.label(format!(
        "last {:.1} s ({} frames) of the current program",
        report.duration_s, q.frames
    ));
    egui::Grid::new("quality").striped(true).show(ui, |ui| {
        for t in report.targets_met() {
            ui.label(t.metric.replace('_', " "));
            ui.label(format!("{:.3} {}", t.value, t.unit));
            ui.label(format!("≤ {} {}", t.target, t.unit));
            let (text, color) = if t.met {
                ("pass", Color32::from_rgb(120, 220, 120))
            } else {
                ("FAIL", Color32::from_rgb(255, 120, 100))
            };
            ui.label(RichText::new(text).color(color).strong());
            ui.end_row();
        }
        ui.label("steps");
        ui.label(report.steps.to_string());
        ui.end_row();
        ui.label("mean step length");
        ui.label(format!("{:.1} cm", report.mean_step_length_cm));
        ui.end_row();
    });
}
