//! The eframe app: lays the panels out, reads the keyboard, and steps the session at the
//! fixed simulation rate.
//!
//! Keys (when no text field has focus): W A S D move relative to the camera, Shift runs,
//! F switches between facing the motion and strafing (the mouse over the 3D view sets the
//! look direction), Space plays or pauses, `.` runs one frame, `,` goes one frame back.

use crate::graph_view::GraphViewState;
use crate::plots::PlotsState;
use crate::session::{Drive, SIM_DT, Session};
use crate::timeline::Playback;
use crate::values::ValueSource;
use crate::variables::VariablesState;
use crate::viewport::{Scene, ViewportState};
use egui::{Color32, Key, RichText, Ui};
use glam::Vec2;
use strider_host::mover::{Facing, MoveInput};
use strider_host::world::direction_yaw;

/// Walking speed under the keyboard, cm/s.
pub const WALK_SPEED: f32 = 150.0;
/// Running speed (Shift), cm/s.
pub const RUN_SPEED: f32 = 400.0;

/// How the keyboard-driven character turns.
#[derive(Clone, Debug, Default)]
pub struct Controls {
    /// Strafe: face [`Controls::look_yaw`] (set by the mouse) instead of the motion.
    pub strafe: bool,
    /// The yaw faced while strafing, degrees.
    pub look_yaw: f32,
    /// The scenario file the "Play scenario" button loads.
    pub scenario_path: String,
    /// The last message of the drive controls.
    pub message: Option<String>,
}

/// The inspector: the session and every panel's state.
pub struct InspectorApp {
    /// The running character.
    pub session: Session,
    /// Play, pause, speed, scrub position.
    pub playback: Playback,
    /// The 3D view's camera and toggles.
    pub viewport: ViewportState,
    /// The graph view.
    pub graph: GraphViewState,
    /// The variables panel.
    pub variables: VariablesState,
    /// The plots.
    pub plots: PlotsState,
    /// Keyboard driving.
    pub controls: Controls,
    feet: Vec<usize>,
    /// CPU time of the previous UI frame (simulation steps, panels, tessellation), ms, as
    /// eframe measures it; `None` headless.
    ui_ms: Option<f32>,
    /// Time of the previous [`InspectorApp::frame_ui`] (simulation steps and panels), ms.
    panels_ms: f32,
}

impl InspectorApp {
    /// The app around `session` (dark theme).
    #[must_use]
    pub fn new(ctx: &egui::Context, session: Session) -> Self {
        ctx.set_visuals(egui::Visuals::dark());
        let feet = session
            .skeleton()
            .contacts
            .iter()
            .filter_map(|c| {
                session
                    .skeleton()
                    .skeleton
                    .find(&c.bone)
                    .map(|b| b.0 as usize)
            })
            .fold(Vec::new(), |mut v, b| {
                if !v.contains(&b) {
                    v.push(b);
                }
                v
            });
        let scenario_path = match session.drive() {
            Drive::Scenario { path, .. } => path.display().to_string(),
            Drive::Keyboard => session
                .options()
                .graph
                .parent()
                .map(|p| p.join("scenarios/walk_flat.ron").display().to_string())
                .unwrap_or_default(),
        };
        let mut app = Self {
            session,
            playback: Playback::default(),
            viewport: ViewportState::default(),
            graph: GraphViewState::default(),
            variables: VariablesState::default(),
            plots: PlotsState::default(),
            controls: Controls {
                scenario_path,
                ..Controls::default()
            },
            feet,
            ui_ms: None,
            panels_ms: 0.0,
        };
        let graph = app.session.options().graph.clone();
        app.graph.load_layout(&graph);
        // One frame so that every panel has something to show.
        app.session.step();
        app
    }

    /// Runs `frames` simulation frames now (returns to the live frame).
    pub fn advance(&mut self, frames: u32) {
        self.playback.cursor = None;
        for _ in 0..frames {
            self.session.step();
        }
    }

    /// Continues the simulation from the recorded frame the playback asks for, if any;
    /// when it cannot, says why in the top bar and goes on from the newest frame.
    fn resume(&mut self) {
        if let Some(i) = self.playback.resume.take() {
            self.controls.message = self.session.resume_from(i).err();
            self.playback.cursor = None;
        }
    }

    /// The keyboard's move input (camera-relative), or `None` when the keyboard is busy
    /// with a text field.
    fn keyboard_input(&mut self, ctx: &egui::Context) -> Option<MoveInput> {
        if ctx.egui_wants_keyboard_input() {
            return None;
        }
        let (w, a, s, d, shift) = ctx.input(|i| {
            (
                i.key_down(Key::W),
                i.key_down(Key::A),
                i.key_down(Key::S),
                i.key_down(Key::D),
                i.modifiers.shift,
            )
        });
        let yaw = self.viewport.yaw.to_radians();
        let forward = Vec2::new(-yaw.sin(), yaw.cos());
        // Screen right is up × forward: (−cos ψ, −sin ψ).
        let right = Vec2::new(-yaw.cos(), -yaw.sin());
        let mut dir = Vec2::ZERO;
        if w {
            dir += forward;
        }
        if s {
            dir -= forward;
        }
        if d {
            dir += right;
        }
        if a {
            dir -= right;
        }
        let facing = if self.controls.strafe {
            if let Some(p) = self.viewport.pointer_ground {
                let at = self.session.component_to_world().translation;
                let to = Vec2::new(p.x - at.x, p.y - at.y);
                if to.length() > 10.0 {
                    self.controls.look_yaw = direction_yaw(to.x, to.y);
                }
            }
            Facing::Look(self.controls.look_yaw)
        } else {
            Facing::Velocity
        };
        Some(MoveInput {
            direction: dir.normalize_or_zero(),
            speed: if shift { RUN_SPEED } else { WALK_SPEED },
            facing,
        })
    }

    fn shortcuts(&mut self, ctx: &egui::Context) {
        if ctx.egui_wants_keyboard_input() {
            return;
        }
        let (space, period, comma, f) = ctx.input(|i| {
            (
                i.key_pressed(Key::Space),
                i.key_pressed(Key::Period),
                i.key_pressed(Key::Comma),
                i.key_pressed(Key::F),
            )
        });
        if space {
            crate::timeline::toggle(&mut self.playback, self.session.recorder());
        }
        if period {
            crate::timeline::step(&mut self.playback, self.session.recorder());
        }
        if comma {
            let recorder = self.session.recorder();
            if let Some(i) = self.playback.shown(recorder) {
                self.playback.playing = false;
                self.playback.cursor = Some(i.saturating_sub(1));
            }
        }
        if f {
            self.controls.strafe = !self.controls.strafe;
            self.controls.look_yaw = self
                .session
                .component_to_world()
                .rotation
                .to_euler(glam::EulerRot::ZYX)
                .0
                .to_degrees();
        }
    }

    /// One UI frame: input, simulation steps due, panels.
    pub fn frame_ui(&mut self, ui: &mut Ui) {
        let ctx = ui.ctx().clone();
        self.session.poll_files();
        self.shortcuts(&ctx);
        if matches!(self.session.drive(), Drive::Keyboard) {
            if let Some(input) = self.keyboard_input(&ctx) {
                self.session.input = input;
            } else {
                self.session.input = MoveInput::STAND;
            }
        }
        self.resume();
        let wall_dt = f64::from(ctx.input(|i| i.stable_dt));
        let steps = self.playback.steps_due(wall_dt, f64::from(SIM_DT));
        if steps > 0 {
            self.playback.cursor = None;
            for _ in 0..steps {
                self.session.step();
            }
        }

        egui::Panel::top("strider-top").show(ui, |ui| self.top_bar(ui));
        egui::Panel::bottom("strider-timeline")
            .resizable(true)
            .default_size(230.0)
            .show(ui, |ui| {
                crate::timeline::show(ui, &mut self.playback, self.session.recorder());
                let shown = self.playback.shown(self.session.recorder());
                let time = shown
                    .and_then(|i| self.session.recorder().get(i))
                    .map(|f| f.meta.time);
                crate::plots::show(ui, &mut self.plots, self.session.recorder(), time);
            });
        let shown = self.playback.shown(self.session.recorder());
        egui::Panel::left("strider-left")
            .resizable(true)
            .default_size(380.0)
            .show(ui, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| {
                    let problems = !self.session.problems().is_empty();
                    egui::CollapsingHeader::new("Diagnostics")
                        .default_open(true)
                        .open(problems.then_some(true))
                        .show(ui, |ui| crate::diagnostics::show(ui, &self.session));
                    egui::CollapsingHeader::new("Quality")
                        .default_open(true)
                        .show(ui, |ui| crate::quality::show(ui, &self.session));
                    egui::CollapsingHeader::new("Variables")
                        .default_open(true)
                        .show(ui, |ui| {
                            if let Some((label, ty, slot)) = crate::variables::show(
                                ui,
                                &mut self.variables,
                                &mut self.session,
                                shown,
                            ) {
                                let generation = self.session.generation();
                                self.plots.add(&label, ty, slot, generation);
                            }
                        });
                });
            });
        let loaded = std::sync::Arc::clone(self.session.document());
        let program = std::sync::Arc::clone(self.session.program());
        self.graph
            .sync(&loaded, &program, self.session.generation());
        egui::Panel::right("strider-node")
            .resizable(true)
            .default_size(340.0)
            .show(ui, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| {
                    let values = ValueSource::of(&self.session, shown);
                    if let Some((label, ty, slot)) = self.graph.show_selected(ui, &program, &values)
                    {
                        let generation = self.session.generation();
                        self.plots.add(&label, ty, slot, generation);
                    }
                });
            });
        egui::CentralPanel::default().show(ui, |ui| {
            egui::Panel::bottom("strider-graph")
                .resizable(true)
                .default_size(ui.available_height() * 0.5)
                .show(ui, |ui| {
                    let values = ValueSource::of(&self.session, shown);
                    self.graph
                        .show(ui, &program, &loaded, &values, self.session.profile_us());
                });
            let recorder = self.session.recorder();
            if let Some(frame) = shown.and_then(|i| recorder.get(i)) {
                let scene = Scene {
                    frame,
                    recorder,
                    world: self.session.world(),
                    skeleton: self.session.skeleton(),
                    feet: &self.feet,
                    plants: &self.session.quality().plants,
                };
                crate::viewport::show(ui, &mut self.viewport, &scene);
            }
        });
    }

    fn top_bar(&mut self, ui: &mut Ui) {
        ui.horizontal(|ui| {
            ui.strong(self.session.program().name());
            ui.label(format!(
                "frame {}  t {:.2} s",
                self.session.frame(),
                self.session.time()
            ));
            if let Some(ms) = self.ui_ms {
                ui.label(
                    RichText::new(format!(
                        "UI {ms:.1} ms (sim + panels {:.1} ms)",
                        self.panels_ms
                    ))
                    .weak(),
                )
                .on_hover_text(
                    "CPU time of the last UI frame, and of its simulation steps and panel \
                     layout (the rest is tessellation and painting)",
                );
            }
            ui.separator();
            let keyboard = matches!(self.session.drive(), Drive::Keyboard);
            if ui.selectable_label(keyboard, "⌨ Keyboard").clicked() && !keyboard {
                self.session.drive_with_keyboard();
            }
            ui.add(
                egui::TextEdit::singleline(&mut self.controls.scenario_path).desired_width(220.0),
            );
            if ui.button("▶ Play scenario").clicked() {
                let path = std::path::PathBuf::from(&self.controls.scenario_path);
                self.controls.message = self.session.play_scenario(&path).err();
                self.playback.playing = true;
            }
            ui.separator();
            let mode = if self.controls.strafe {
                "strafe (mouse aims)"
            } else {
                "face motion"
            };
            if ui.button(format!("F: {mode}")).clicked() {
                self.controls.strafe = !self.controls.strafe;
            }
            ui.checkbox(&mut self.viewport.follow, "follow");
            ui.checkbox(&mut self.viewport.show_debug, "debug draw");
            ui.checkbox(&mut self.viewport.show_feet, "feet");
            let problems = self.session.problems().len();
            if problems > 0 {
                let running = if self.session.graph_loaded() {
                    "running the last good program"
                } else {
                    "nothing runs until the graph loads"
                };
                ui.label(
                    RichText::new(format!("⚠ {problems} problem(s): {running}"))
                        .color(Color32::from_rgb(255, 140, 110)),
                );
            }
        });
        ui.horizontal(|ui| {
            ui.label(
                RichText::new(
                    "WASD move (camera relative) · Shift run · F face/strafe · Space pause · . step · , back · \
                     drag orbit · right-drag pan · wheel zoom",
                )
                .weak(),
            );
            if let Some(m) = &self.controls.message {
                ui.label(RichText::new(m).color(Color32::from_rgb(255, 140, 110)));
            }
        });
    }
}

impl eframe::App for InspectorApp {
    fn ui(&mut self, ui: &mut Ui, frame: &mut eframe::Frame) {
        self.ui_ms = frame.info().cpu_usage.map(|s| s * 1000.0);
        let start = std::time::Instant::now();
        self.frame_ui(ui);
        self.panels_ms = start.elapsed().as_secs_f32() * 1000.0;
        ui.ctx().request_repaint();
    }

    /// Writes the graph view's layout file if nodes were moved since it was last saved.
    fn on_exit(&mut self, _gl: Option<&eframe::glow::Context>) {
        if self.graph.layout_dirty
            && let Err(e) = self.graph.save_layout()
        {
            eprintln!("strider inspector: the layout was not saved: {e}");
        }
    }
}
