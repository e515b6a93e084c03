//! Playback and time travel: play, pause, single step, slow motion, and a timeline over
//! the recorded frames. Scrubbing pauses the simulation and shows the chosen frame in
//! every panel; playing (or stepping) from there continues the simulation from that frame
//! (the recorded frames after it are dropped, see [`crate::Session::resume_from`]); "Live"
//! goes back to the newest frame without rewinding.

use crate::recording::Recorder;
use egui::Ui;

/// Lowest and highest playback speed (simulated seconds per wall second).
pub const SPEED_RANGE: (f32, f32) = (0.1, 2.0);
/// Most simulation frames run for one UI frame (a slow UI frame does not snowball).
pub const MAX_STEPS_PER_UPDATE: u32 = 8;

/// Playback state.
#[derive(Clone, Debug)]
pub struct Playback {
    /// Whether the simulation advances with wall time.
    pub playing: bool,
    /// Simulated seconds per wall second, within [`SPEED_RANGE`].
    pub speed: f32,
    /// The recorded frame shown (index from the oldest kept); `None`: the live frame.
    pub cursor: Option<usize>,
    /// Simulated seconds owed to the simulation.
    pub accumulator: f64,
    /// Run exactly one frame at the next update.
    pub step_once: bool,
    /// Continue the simulation from this recorded frame (index from the oldest kept) at
    /// the next update, before any frame runs.
    pub resume: Option<usize>,
}

impl Default for Playback {
    fn default() -> Self {
        Self {
            playing: true,
            speed: 1.0,
            cursor: None,
            accumulator: 0.0,
            step_once: false,
            resume: None,
        }
    }
}

impl Playback {
    /// How many fixed steps of `step_dt` seconds to run after `wall_dt` wall seconds
    /// (clamped to 0.1 s), at most [`MAX_STEPS_PER_UPDATE`]; keeps the remainder.
    pub fn steps_due(&mut self, wall_dt: f64, step_dt: f64) -> u32 {
        if self.step_once {
            self.step_once = false;
            self.accumulator = 0.0;
            return 1;
        }
        if !self.playing {
            self.accumulator = 0.0;
            return 0;
        }
        self.accumulator += wall_dt.clamp(0.0, 0.1) * f64::from(self.speed);
        let mut n = 0;
        while self.accumulator >= step_dt && n < MAX_STEPS_PER_UPDATE {
            self.accumulator -= step_dt;
            n += 1;
        }
        if n == MAX_STEPS_PER_UPDATE {
            self.accumulator = 0.0;
        }
        n
    }

    /// The recorded frame shown: the cursor, or the newest.
    #[must_use]
    pub fn shown(&self, recorder: &Recorder) -> Option<usize> {
        let newest = recorder.len().checked_sub(1)?;
        Some(self.cursor.map_or(newest, |c| c.min(newest)))
    }

    /// Goes back `seconds` from the frame shown (pauses).
    pub fn scrub_back(&mut self, recorder: &Recorder, seconds: f64) {
        let Some(shown) = self.shown(recorder).and_then(|i| recorder.get(i)) else {
            return;
        };
        self.playing = false;
        self.cursor = recorder.index_at_time(shown.meta.time - seconds);
    }
}

/// Shows the playback controls and the timeline.
pub fn show(ui: &mut Ui, playback: &mut Playback, recorder: &Recorder) {
    ui.horizontal(|ui| {
        let label = if playback.playing {
            "⏸ Pause"
        } else {
            "▶ Play"
        };
        if ui
            .button(label)
            .on_hover_text("Space; from a frame scrubbed back, play on from it")
            .clicked()
        {
            toggle(playback, recorder);
        }
        if ui
            .button("⏭ Step")
            .on_hover_text("run one frame (.); from a frame scrubbed back, the one after it")
            .clicked()
        {
            step(playback, recorder);
        }
        ui.add(
            egui::Slider::new(&mut playback.speed, SPEED_RANGE.0..=SPEED_RANGE.1)
                .logarithmic(true)
                .text("speed")
                .suffix("×"),
        );
        if ui
            .button("Live")
            .on_hover_text("show the newest frame (the simulation is not rewound)")
            .clicked()
        {
            playback.cursor = None;
        }
        let Some(newest) = recorder.len().checked_sub(1) else {
            ui.label("no frames yet");
            return;
        };
        let mut index = playback.shown(recorder).unwrap_or(newest);
        let width = (ui.available_width() - 160.0).max(100.0);
        ui.spacing_mut().slider_width = width;
        let changed = ui
            .add(egui::Slider::new(&mut index, 0..=newest).show_value(false))
            .on_hover_text("recorded frames: drag to travel back in time")
            .changed();
        if changed {
            playback.playing = false;
            playback.cursor = Some(index);
        }
        if let (Some(shown), Some(last)) = (recorder.get(index), recorder.latest()) {
            ui.label(format!(
                "t {:.2} s ({:+.2} s)",
                shown.meta.time,
                shown.meta.time - last.meta.time
            ));
        }
    });
}

/// Play ↔ pause; playing from a recorded frame before the newest continues the
/// simulation from it ([`Playback::resume`]).
pub fn toggle(playback: &mut Playback, recorder: &Recorder) {
    playback.playing = !playback.playing;
    if playback.playing {
        playback.resume = scrubbed(playback, recorder);
    }
}

/// Runs one frame and pauses; from a recorded frame before the newest, the frame after it.
pub fn step(playback: &mut Playback, recorder: &Recorder) {
    playback.playing = false;
    playback.resume = scrubbed(playback, recorder);
    playback.cursor = None;
    playback.step_once = true;
}

/// The frame shown when it is not the newest.
fn scrubbed(playback: &Playback, recorder: &Recorder) -> Option<usize> {
    let shown = playback.cursor?;
    (shown + 1 < recorder.len()).then_some(shown)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fixed_steps_follow_wall_time_and_speed() {
        let mut p = Playback::default();
        let dt = 1.0 / 60.0;
        // 0.05 s of wall time at 1× owes 3 frames of 1/60 s.
        assert_eq!(p.steps_due(0.05 + 1e-9, dt), 3);
        // At 0.1× the same wall time owes 0.3 frames: none yet, then one after ten.
        p.speed = 0.1;
        p.accumulator = 0.0;
        let total: u32 = (0..10).map(|_| p.steps_due(1.0 / 60.0 + 1e-9, dt)).sum();
        assert_eq!(total, 1);
        // Paused: nothing, except a single step when asked.
        p.playing = false;
        assert_eq!(p.steps_due(1.0, dt), 0);
        p.step_once = true;
        assert_eq!(p.steps_due(0.0, dt), 1);
        // A long hitch of wall time is clamped to 0.1 s (6 frames), never more than 8.
        p.playing = true;
        p.speed = 2.0;
        assert!(p.steps_due(5.0, dt) <= MAX_STEPS_PER_UPDATE);
    }
}
