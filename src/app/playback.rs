//! Animation time: an impact lasts about a millisecond, so it is shown in deep slow motion.

use eframe::egui;

pub struct Playback {
    /// Animation time [s of the simulation].
    pub t: f64,
    pub playing: bool,
    /// Simulated seconds per real second.
    pub speed: f64,
    /// End of the scrubber [s].
    pub t_max: f64,
    /// How far the result shown is solved [s], while its run is still solving: playing and
    /// stepping wait there, and the view draws no later (`None`: a finished run).
    pub ready_s: Option<f64>,
}

impl Default for Playback {
    fn default() -> Self {
        Playback {
            t: 0.0,
            playing: true,
            speed: 1e-4,
            t_max: 1e-3,
            ready_s: None,
        }
    }
}

impl Playback {
    /// Advances by a frame of `real_dt` seconds; loops at the end, or waits at the edge of a run
    /// still solving.
    pub fn advance(&mut self, real_dt: f64) {
        if !self.playing {
            return;
        }
        match self.ready_s {
            // Looping back would replay the start while the rest solves: hold for more instead.
            Some(edge) => {
                if self.t < edge {
                    self.t = (self.t + real_dt * self.speed).min(edge);
                }
            }
            None => {
                self.t += real_dt * self.speed;
                if self.t > self.t_max {
                    self.t = 0.0;
                }
            }
        }
    }

    pub fn step(&mut self) {
        self.playing = false;
        let end = self.ready_s.map_or(self.t_max, |e| e.min(self.t_max));
        if self.t < end {
            self.t = (self.t + self.t_max / 500.0).min(end);
        }
    }

    /// The time the view and the plots' cursors show: the animation time, or the edge of a run
    /// still solving where the time set (by a launch, a click or the scrubber) lies beyond it.
    pub fn shown_t(&self) -> f64 {
        self.ready_s.map_or(self.t, |e| self.t.min(e))
    }

    /// Play/pause, step, speed and scrubber; returns whether the user asked for a restart.
    /// Where the transport stands in the top bar ([`hoist`]) the scene's call only asks for
    /// it there.
    pub fn ui(&mut self, ui: &mut egui::Ui) -> bool {
        if hoisted(ui.ctx()) {
            ui.ctx().data_mut(|d| d.insert_temp(wanted_id(), true));
            return false;
        }
        self.controls(ui)
    }

    /// The transport in the top bar, where a scene asked for it last frame; returns whether
    /// the user asked for a restart.
    pub fn bar_ui(&mut self, ui: &mut egui::Ui) -> bool {
        let wanted = ui
            .ctx()
            .data_mut(|d| d.remove_temp::<bool>(wanted_id()))
            .unwrap_or(false);
        wanted && self.controls(ui)
    }

    /// Lecture mode keeps play, restart and the scrubber on one row (the arrow key still
    /// steps; each scene starts at a speed that shows its waves).
    fn controls(&mut self, ui: &mut egui::Ui) -> bool {
        let lecture = super::lecture::on(ui.ctx());
        let mut restart = false;
        // The row's room, measured where it starts: a row nested in another (the top bar) sees
        // its parent's whole width as its own.
        let (start, room) = (ui.cursor().min.x, ui.available_size_before_wrap().x);
        let left = move |ui: &egui::Ui| room - (ui.cursor().min.x - start);
        ui.horizontal_wrapped(|ui| {
            if ui
                .button(if self.playing { "Pause" } else { "Play" })
                .on_hover_text("Play or pause (space)")
                .clicked()
            {
                self.playing = !self.playing;
            }
            if !lecture
                && ui
                    .button("Step")
                    .on_hover_text("One step forward (right arrow)")
                    .clicked()
            {
                self.step();
            }
            if ui
                .button("Restart")
                .on_hover_text("Back to t = 0 with the same parameters (R)")
                .clicked()
            {
                restart = true;
                self.t = 0.0;
            }
            if !lecture {
                self.speed_ui(ui, left(ui));
                ui.end_row();
            }
            let t_max = self.t_max;
            let label = ui.label("t").on_hover_text("Animation time").id;
            // The slider takes the width the row leaves: a fixed width runs off a narrow panel.
            ui.spacing_mut().slider_width = (left(ui) - 150.0).clamp(60.0, 400.0);
            ui.add(
                egui::Slider::new(&mut self.t, 0.0..=t_max)
                    .custom_formatter(|v, _| format!("{:.4} ms", v * 1e3)),
            )
            .labelled_by(label);
        });
        restart
    }

    fn speed_ui(&mut self, ui: &mut egui::Ui, room: f32) {
        let label = ui
            .label("speed")
            .on_hover_text(
                "Simulated time per real second: 1e-4 shows a millisecond impact over 10 s",
            )
            .id;
        ui.spacing_mut().slider_width = (room - 150.0).clamp(40.0, 160.0);
        ui.add(
            egui::Slider::new(&mut self.speed, 1e-7..=10.0)
                .logarithmic(true)
                .custom_formatter(|v, _| format!("{v:.1e} s/s")),
        )
        .labelled_by(label);
    }
}

fn hoisted_id() -> egui::Id {
    egui::Id::unique("transport-in-top-bar")
}

fn wanted_id() -> egui::Id {
    egui::Id::unique("transport-wanted")
}

/// Puts the transport in the top bar (a lesson in lecture mode, where the scene's panel needs
/// every row for its results) or back in the scene.
pub fn hoist(ctx: &egui::Context, on: bool) {
    ctx.data_mut(|d| d.insert_temp(hoisted_id(), on));
}

fn hoisted(ctx: &egui::Context) -> bool {
    ctx.data(|d| d.get_temp(hoisted_id())).unwrap_or(false)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn playing_or_stepping_a_run_still_solving_never_passes_how_far_it_is_solved() {
        let mut p = Playback {
            t: 0.0,
            playing: true,
            speed: 1.0,
            t_max: 8.0,
            ready_s: Some(1.25),
        };
        for _ in 0..100 {
            p.advance(0.1);
            assert!(p.t <= 1.25, "played to {}", p.t);
        }
        // It waits at the edge rather than looping to the start.
        assert_eq!(p.t, 1.25);
        p.step();
        assert_eq!(p.t, 1.25);
        // More solved: it plays on from where it waited.
        p.ready_s = Some(2.0);
        p.playing = true;
        p.advance(0.1);
        assert!((p.t - 1.35).abs() < 1e-12, "{}", p.t);
        // A time set beyond the edge stays set, and is shown at the edge until solved.
        p.t = 3.0;
        assert_eq!(p.shown_t(), 2.0);
        p.advance(0.1);
        assert_eq!(p.t, 3.0);
        // The finished run: the time set is shown, and playing loops at the end.
        p.ready_s = None;
        assert_eq!(p.shown_t(), 3.0);
        p.t = 7.95;
        p.advance(0.1);
        assert_eq!(p.t, 0.0);
    }
}
