//! The status bar (timings, progress and Cancel, the last message) and the keyboard.

use super::{HIDE_TIMINGS, PoundingApp};
use eframe::egui::{self, Color32};

/// A duration in seconds shown in milliseconds with `decimals`.
pub fn ms(seconds: f64, decimals: usize) -> String {
    if HIDE_TIMINGS.load(std::sync::atomic::Ordering::Relaxed) {
        "- ms".into()
    } else {
        format!("{:.*} ms", decimals, seconds * 1e3)
    }
}

impl PoundingApp {
    pub(super) fn status_bar(&mut self, ui: &mut egui::Ui) {
        // A class has no use for timings: lecture mode keeps the bar for progress and messages.
        let timings = !self.lecture;
        if !timings && self.message.is_none() && self.shown().progress().is_none() {
            return;
        }
        let frame = self.panel_frame(egui::Frame::side_top_panel(ui.style()));
        egui::Panel::bottom("status").frame(frame).show(ui, |ui| {
            ui.horizontal(|ui| {
                if timings {
                    self.timings_ui(ui);
                }
                self.progress_ui(ui);
                if let Some((m, is_error)) = &self.message {
                    ui.separator();
                    let colour = if *is_error {
                        Color32::from_rgb(220, 60, 50)
                    } else {
                        ui.visuals().text_color()
                    };
                    ui.colored_label(colour, m);
                }
            });
        });
    }

    fn timings_ui(&mut self, ui: &mut egui::Ui) {
        let (solve, latency) = self.shown().timings();
        let solving = if self.shown().busy() {
            format!(" | {}", self.shown().solving_note())
        } else {
            String::new()
        };
        let timings = ui.label(format!(
            "UI {} | solve {} | change to result {}{solving}",
            ms(self.ui_ms * 1e-3, 2),
            ms(solve.as_secs_f64(), 3),
            ms(latency.as_secs_f64(), 1),
        ));
        if let Some(later) = self.shown().later_stages() {
            timings.on_hover_text(later);
        }
    }

    fn progress_ui(&mut self, ui: &mut egui::Ui) {
        if let Some(done) = self.shown().progress() {
            ui.add(
                egui::ProgressBar::new(done as f32)
                    .desired_width(160.0)
                    .show_percentage(),
            );
            if ui
                .button("Cancel")
                .on_hover_text("Stop this solve; the last result stays")
                .clicked()
            {
                self.shown_mut().0.cancel();
            }
        }
    }

    pub(super) fn keys(&mut self, ctx: &egui::Context) {
        if ctx.memory(|m| m.focused().is_some()) {
            return;
        }
        let (space, right, restart, help, lecture) = ctx.input(|i| {
            (
                i.key_pressed(egui::Key::Space),
                i.key_pressed(egui::Key::ArrowRight),
                i.key_pressed(egui::Key::R),
                i.key_pressed(egui::Key::F1),
                i.key_pressed(egui::Key::F5),
            )
        });
        if lecture {
            self.set_lecture(ctx, !self.lecture);
        }
        let playback = self.playback();
        if space {
            playback.playing = !playback.playing;
        }
        if right {
            playback.step();
        }
        if restart {
            playback.t = 0.0;
            playback.playing = true;
        }
        if help {
            self.help = !self.help;
        }
    }
}
