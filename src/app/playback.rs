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
}

impl Default for Playback {
    fn default() -> Self {
        Playback {
            t: 0.0,
            playing: true,
            speed: 1e-4,
            t_max: 1e-3,
        }
    }
}

impl Playback {
    /// Advances by a frame of `real_dt` seconds; loops at the end.
    pub fn advance(&mut self, real_dt: f64) {
        if self.playing {
            self.t += real_dt * self.speed;
            if self.t > self.t_max {
                self.t = 0.0;
            }
        }
    }

    pub fn step(&mut self) {
        self.playing = false;
        self.t = (self.t + self.t_max / 500.0).min(self.t_max);
    }

    /// Play/pause, step, speed and scrubber; returns whether the user asked for a restart.
    pub fn ui(&mut self, ui: &mut egui::Ui) -> bool {
        let mut restart = false;
        ui.horizontal_wrapped(|ui| {
            if ui
                .button(if self.playing { "Pause" } else { "Play" })
                .on_hover_text("Play or pause (space)")
                .clicked()
            {
                self.playing = !self.playing;
            }
            if ui
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
            let label = ui
                .label("speed")
                .on_hover_text(
                    "Simulated time per real second: 1e-4 shows a millisecond impact over 10 s",
                )
                .id;
            ui.add(
                egui::Slider::new(&mut self.speed, 1e-7..=10.0)
                    .logarithmic(true)
                    .custom_formatter(|v, _| format!("{v:.1e} s/s")),
            )
            .labelled_by(label);
            let t_max = self.t_max;
            let label = ui.label("t").on_hover_text("Animation time").id;
            ui.add(
                egui::Slider::new(&mut self.t, 0.0..=t_max)
                    .custom_formatter(|v, _| format!("{:.4} ms", v * 1e3)),
            )
            .labelled_by(label);
        });
        restart
    }
}
