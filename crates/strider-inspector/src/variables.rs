//! The variables panel: every tunable variable with a slider (the file's range) or a field,
//! reset to the file's default, export and import of overrides files; and every other
//! variable's value, read-only (as of the frame shown).

use crate::session::Session;
use crate::values::{ValueSource, format_value};
use egui::Ui;
use std::path::PathBuf;
use strider_nodes::{Value, ValueType};
use strider_vm::VariableId;

/// State of the variables panel.
#[derive(Clone, Debug, Default)]
pub struct VariablesState {
    /// Where "Export" writes and "Load" reads an overrides file.
    pub overrides_path: String,
    /// The last export/load outcome: (ok, message).
    pub message: Option<(bool, String)>,
    /// Only variables whose name contains this (case-insensitive).
    pub filter: String,
}

impl VariablesState {
    /// The default overrides path for a graph: `<graph stem>.overrides.ron` next to it.
    #[must_use]
    pub fn default_path(graph: &std::path::Path) -> String {
        let stem = graph
            .file_stem()
            .map_or_else(|| "graph".to_string(), |s| s.to_string_lossy().into_owned());
        graph
            .with_file_name(format!("{stem}.overrides.ron"))
            .display()
            .to_string()
    }
}

fn range_f(
    bounds: (Option<f32>, Option<f32>),
    value: f32,
) -> Option<std::ops::RangeInclusive<f32>> {
    match bounds {
        (Some(lo), Some(hi)) if lo <= hi => Some(lo.min(value)..=hi.max(value)),
        _ => None,
    }
}

/// Shows the panel; returns a variable to plot: (name, type, slot).
pub fn show(
    ui: &mut Ui,
    state: &mut VariablesState,
    session: &mut Session,
    shown: Option<usize>,
) -> Option<(String, ValueType, u32)> {
    let mut plot = None;
    ui.horizontal(|ui| {
        ui.label("filter");
        ui.text_edit_singleline(&mut state.filter);
    });
    let program = std::sync::Arc::clone(session.program());
    let filter = state.filter.to_lowercase();
    let visible = |name: &str| filter.is_empty() || name.to_lowercase().contains(&filter);
    let mut changes: Vec<(VariableId, Value)> = Vec::new();
    egui::Grid::new("tunables")
        .num_columns(3)
        .striped(true)
        .show(ui, |ui| {
            for (i, v) in program.variables().iter().enumerate() {
                let Some(bounds) = v.tunable else { continue };
                if !visible(&v.name) {
                    continue;
                }
                let id = VariableId(i as u32);
                let current = session.instance().variable(id);
                ui.label(&v.name).on_hover_text(format!(
                    "{} at {}; range {}..{}",
                    v.ty,
                    v.location,
                    bounds.0.map_or("".into(), |x| x.to_string()),
                    bounds.1.map_or("".into(), |x| x.to_string())
                ));
                match current {
                    Value::Float(mut x) => {
                        let changed = match range_f(bounds, x) {
                            Some(r) => ui.add(egui::Slider::new(&mut x, r)).changed(),
                            None => ui.add(egui::DragValue::new(&mut x).speed(0.1)).changed(),
                        };
                        if changed {
                            changes.push((id, Value::Float(x)));
                        }
                    }
                    Value::Int(mut n) => {
                        let changed = match range_f(bounds, n as f32) {
                            Some(r) => ui
                                .add(egui::Slider::new(
                                    &mut n,
                                    (*r.start() as i32)..=(*r.end() as i32),
                                ))
                                .changed(),
                            None => ui.add(egui::DragValue::new(&mut n)).changed(),
                        };
                        if changed {
                            changes.push((id, Value::Int(n)));
                        }
                    }
                    Value::Bool(mut b) => {
                        if ui.checkbox(&mut b, "").changed() {
                            changes.push((id, Value::Bool(b)));
                        }
                    }
                    Value::Vec3(mut p) => {
                        let mut changed = false;
                        ui.horizontal(|ui| {
                            for c in [&mut p.x, &mut p.y, &mut p.z] {
                                changed |= ui.add(egui::DragValue::new(c).speed(0.1)).changed();
                            }
                        });
                        if changed {
                            changes.push((id, Value::Vec3(p)));
                        }
                    }
                    other => {
                        ui.label(format_value(&other));
                    }
                }
                ui.horizontal(|ui| {
                    let is_default = session.instance().variable(id) == v.default;
                    if ui
                        .add_enabled(!is_default, egui::Button::new("↺").small())
                        .on_hover_text(format!("reset to {}", format_value(&v.default)))
                        .clicked()
                    {
                        changes.push((id, v.default.clone()));
                    }
                    if crate::graph_view::plottable(v.ty) && ui.small_button("plot").clicked() {
                        plot = Some((v.name.clone(), v.ty, v.slot));
                    }
                });
                ui.end_row();
            }
        });
    for (id, value) in changes {
        if let Err(e) = session.set_variable(id, &value) {
            state.message = Some((false, e));
        }
    }
    ui.horizontal(|ui| {
        if ui.button("Reset all").clicked() {
            session.reset_tunables();
        }
    });
    ui.separator();
    ui.label("Overrides file (the graph file is never rewritten):");
    if state.overrides_path.is_empty() {
        state.overrides_path = VariablesState::default_path(&session.options().graph);
    }
    ui.text_edit_singleline(&mut state.overrides_path);
    ui.horizontal(|ui| {
        let path = PathBuf::from(&state.overrides_path);
        if ui.button("Export").clicked() {
            state.message = Some(match session.export_overrides(&path) {
                Ok(()) => (true, format!("wrote {}", path.display())),
                Err(e) => (false, e),
            });
        }
        if ui.button("Load").clicked() {
            state.message = Some(match session.load_overrides(&path) {
                Ok(n) => (true, format!("applied {n} values from {}", path.display())),
                Err(e) => (false, e),
            });
        }
    });
    if let Some((ok, m)) = &state.message {
        let color = if *ok {
            egui::Color32::from_rgb(120, 220, 120)
        } else {
            egui::Color32::from_rgb(255, 140, 110)
        };
        ui.label(egui::RichText::new(m).color(color));
    }
    let values = ValueSource::of(session, shown);
    ui.collapsing("All variables (frame shown)", |ui| {
        egui::Grid::new("all-variables")
            .striped(true)
            .show(ui, |ui| {
                for v in program.variables() {
                    if !visible(&v.name) {
                        continue;
                    }
                    ui.label(&v.name);
                    let text = values
                        .read(v.ty, v.slot)
                        .map_or_else(|| "— (not recorded)".to_string(), |x| format_value(&x));
                    ui.label(text);
                    if crate::graph_view::plottable(v.ty) && ui.small_button("plot").clicked() {
                        plot = Some((v.name.clone(), v.ty, v.slot));
                    }
                    ui.end_row();
                }
            });
    });
    plot
}
