//! Plots of pins and variables over the recorded frames, several at once, with a line
//! at the frame shown (time travel moves it).

use crate::recording::Recorder;
use egui::Ui;
use egui_plot::{Legend, Line, Plot, PlotPoints, VLine};
use strider_nodes::{Value, ValueType};

/// One plotted value: a slot of the program that recorded it.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// Shown in the legend (`node.pin`, a variable name; `.x`/`.y`/`.z` for components).
    pub label: String,
    /// The slot's type.
    pub ty: ValueType,
    /// The slot.
    pub slot: u32,
    /// For vectors, the component (0 x, 1 y, 2 z).
    pub component: Option<usize>,
    /// The program generation whose slot layout `slot` belongs to.
    pub generation: u32,
}

impl Series {
    /// The series' value in a recorded slot image, as a number (bools 0 or 1).
    #[must_use]
    pub fn value(&self, slots: &crate::recording::SlotImage) -> Option<f64> {
        Some(match slots.read(self.ty, self.slot, &[])? {
            Value::Float(x) => f64::from(x),
            Value::Int(i) => f64::from(i),
            Value::Bool(b) => f64::from(u8::from(b)),
            Value::Vec3(v) => f64::from(v.to_array()[self.component.unwrap_or(0).min(2)]),
            _ => return None,
        })
    }
}

/// The plotted series.
#[derive(Clone, Debug, Default)]
pub struct PlotsState {
    /// Series shown, in the order added.
    pub series: Vec<Series>,
}

impl PlotsState {
    /// Adds a slot to plot (a vector adds its three components); ignores one already there.
    pub fn add(&mut self, label: &str, ty: ValueType, slot: u32, generation: u32) {
        let parts: Vec<(String, Option<usize>)> = if ty == ValueType::Vec3 {
            ["x", "y", "z"]
                .iter()
                .enumerate()
                .map(|(i, c)| (format!("{label}.{c}"), Some(i)))
                .collect()
        } else {
            vec![(label.to_string(), None)]
        };
        for (label, component) in parts {
            let s = Series {
                label,
                ty,
                slot,
                component,
                generation,
            };
            if !self.series.contains(&s) {
                self.series.push(s);
            }
        }
    }

    /// The points of series `s` over the recorded frames of its program: (time s, value).
    #[must_use]
    pub fn points(s: &Series, recorder: &Recorder) -> Vec<[f64; 2]> {
        recorder
            .iter()
            .filter(|f| f.meta.generation == s.generation)
            .filter_map(|f| s.value(&f.slots).map(|v| [f.meta.time, v]))
            .collect()
    }
}

/// Shows the plots; `cursor_time` is the time of the frame shown.
pub fn show(ui: &mut Ui, state: &mut PlotsState, recorder: &Recorder, cursor_time: Option<f64>) {
    if state.series.is_empty() {
        ui.label("Add a pin (node panel) or a variable (variables panel) with its “plot” button.");
        return;
    }
    let mut remove = None;
    ui.horizontal_wrapped(|ui| {
        for (i, s) in state.series.iter().enumerate() {
            if ui.small_button(format!("✕ {}", s.label)).clicked() {
                remove = Some(i);
            }
        }
        if ui.small_button("clear").clicked() {
            remove = Some(usize::MAX);
        }
    });
    match remove {
        Some(usize::MAX) => state.series.clear(),
        Some(i) => {
            state.series.remove(i);
        }
        None => {}
    }
    let lines: Vec<(String, Vec<[f64; 2]>)> = state
        .series
        .iter()
        .map(|s| (s.label.clone(), PlotsState::points(s, recorder)))
        .collect();
    Plot::new("strider-plots")
        .legend(Legend::default())
        .height(ui.available_height().max(80.0))
        .show(ui, |plot| {
            for (label, points) in lines {
                plot.line(Line::new(label, PlotPoints::from(points)));
            }
            if let Some(t) = cursor_time {
                plot.vline(VLine::new("shown frame", t));
            }
        });
}
