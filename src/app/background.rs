//! A study run on a thread of its own: its progress is read each frame, it can be cancelled, and
//! its outcome is taken once it lands (the window is repainted when it does). A panic in the
//! study is caught and lands as its outcome, so the scene never waits for ever.

use crate::study::Control;
use eframe::egui;
use std::sync::Arc;
use std::sync::mpsc::{Receiver, channel};
use std::time::{Duration, Instant};

pub struct Background<T> {
    progress: Arc<Control>,
    rx: Receiver<Result<T, String>>,
    started: Instant,
}

impl<T: Send + 'static> Background<T> {
    pub fn spawn(ctx: &egui::Context, work: impl FnOnce(&Control) -> T + Send + 'static) -> Self {
        let progress = Arc::new(Control::new());
        let (tx, rx) = channel();
        let (p, ctx) = (progress.clone(), ctx.clone());
        std::thread::Builder::new()
            .name("pounding-study".into())
            .spawn(move || {
                let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| work(&p)))
                    .map_err(|e| super::worker::panic_message(e.as_ref()));
                let _ = tx.send(outcome);
                ctx.request_repaint();
            })
            .expect("the study thread starts");
        Background {
            progress,
            rx,
            started: Instant::now(),
        }
    }

    /// The outcome (or the message of the panic that ended the study) and the wall time, once
    /// landed; until then asks for a repaint soon so the progress bar moves.
    pub fn try_take(&self, ctx: &egui::Context) -> Option<(Result<T, String>, Duration)> {
        match self.rx.try_recv() {
            Ok(out) => Some((out, self.started.elapsed())),
            Err(_) => {
                ctx.request_repaint_after(Duration::from_millis(50));
                None
            }
        }
    }

    /// Solves done and planned.
    pub fn counts(&self) -> (usize, usize) {
        (self.progress.done(), self.progress.total())
    }

    pub fn cancel(&self) {
        self.progress.cancel();
    }

    pub fn progress_ui(&self, ui: &mut egui::Ui) {
        let (done, total) = self.counts();
        ui.add(
            egui::ProgressBar::new(done as f32 / total.max(1) as f32)
                .text(format!("{done} / {total} solves")),
        );
    }
}
