//! The paper's figures in the window: one built-in impact study (Figures 4 to 9, Sections 3.3 to
//! 3.5) run in the background with progress and cancel, its figures drawn and its findings listed.

use super::background::Background;
use super::export::{Exporter, ShownPlot};
use super::plot_view;
use crate::study::{self, Cancelled, Context, Control, StudyOutput};
use eframe::egui;
use std::time::Duration;

struct Done {
    output: StudyOutput,
    shown: Vec<ShownPlot>,
}

pub struct PaperFigures {
    pub choice: &'static str,
    running: Option<Background<Result<StudyOutput, study::StudyError>>>,
    done: Option<Done>,
    status: Option<(String, bool)>,
    ctx: egui::Context,
}

/// The studies the window offers: those of the bars (the buildings have their own scene).
fn offered() -> Vec<&'static study::Study> {
    study::studies()
        .into_iter()
        .filter(|s| !s.buildings)
        .collect()
}

impl PaperFigures {
    pub fn new(ctx: &egui::Context) -> Self {
        PaperFigures {
            choice: "fig6-restitution",
            running: None,
            done: None,
            status: None,
            ctx: ctx.clone(),
        }
    }

    pub fn busy(&self) -> bool {
        self.running.is_some()
    }

    /// Picks a study by name; `false` when there is none of that name.
    pub fn choose(&mut self, name: &str) -> bool {
        match offered().into_iter().find(|s| s.name == name) {
            Some(s) => {
                self.choice = s.name;
                true
            }
            None => false,
        }
    }

    pub fn start(&mut self) {
        self.cancel();
        let Some(s) = study::find(self.choice) else {
            return;
        };
        let run = s.run;
        self.running = Some(Background::spawn(&self.ctx, move |p: &Control| {
            run(&Context::new(p))
        }));
        self.status = None;
    }

    /// The last outcome's message.
    #[cfg(test)]
    pub fn status(&self) -> Option<&str> {
        self.status.as_ref().map(|(m, _)| m.as_str())
    }

    pub fn cancel(&self) {
        if let Some(r) = &self.running {
            r.cancel();
        }
    }

    /// Takes a landed study; returns its wall time.
    pub fn poll(&mut self) -> Option<Duration> {
        let r = self.running.as_ref()?;
        let (outcome, elapsed) = r.try_take(&self.ctx)?;
        let (done, total) = r.counts();
        self.running = None;
        let outcome = match outcome {
            Ok(outcome) => outcome,
            Err(panic) => {
                self.status = Some((super::worker::internal_error(&panic), true));
                return None;
            }
        };
        match outcome {
            Ok(output) => {
                self.status = Some((
                    format!(
                        "{done} solves in {}{}",
                        super::ms(elapsed.as_secs_f64(), 1),
                        output
                            .notes
                            .iter()
                            .map(|n| format!("; {n}"))
                            .collect::<String>()
                    ),
                    false,
                ));
                self.done = Some(Done {
                    shown: vec![ShownPlot::default(); output.figures.len()],
                    output,
                });
                Some(elapsed)
            }
            Err(study::StudyError::Cancelled(Cancelled)) => {
                self.status = Some((format!("cancelled after {done} of {total} solves"), false));
                None
            }
            Err(e) => {
                self.status = Some((e.to_string(), true));
                None
            }
        }
    }

    pub fn shown_plots(&self) -> Vec<(&str, &ShownPlot)> {
        self.done.as_ref().map_or(vec![], |d| {
            d.output
                .figures
                .iter()
                .zip(&d.shown)
                .map(|(f, s)| (f.stem.as_str(), s))
                .collect()
        })
    }

    pub fn params_ui(&mut self, ui: &mut egui::Ui) {
        let label = ui.label("figure").id;
        let before = self.choice;
        egui::ComboBox::from_id_salt("paper-figure")
            .selected_text(self.choice)
            .show_ui(ui, |ui| {
                for s in offered() {
                    ui.selectable_value(&mut self.choice, s.name, s.name)
                        .on_hover_text(format!("{}: {}", s.paper, s.about));
                }
            })
            .response
            .labelled_by(label);
        if let Some(s) = study::find(self.choice) {
            ui.label(format!("{}: {}", s.paper, s.about));
        }
        ui.label(
            "Figures 12 and 13 (the buildings): the Building pounding scene, or `pounding study`.",
        );
        if self.choice != before {
            self.start();
        }
        ui.horizontal(|ui| {
            if ui.button("Run").clicked() {
                self.start();
            }
            if ui
                .add_enabled(self.busy(), egui::Button::new("Cancel"))
                .clicked()
            {
                self.cancel();
            }
        });
        if let Some(r) = &self.running {
            r.progress_ui(ui);
        }
        super::params::status_ui(ui, self.status.as_ref());
    }

    pub fn main_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter) {
        let Some(d) = &mut self.done else {
            ui.label(if self.running.is_some() {
                "solving..."
            } else {
                "press Run"
            });
            return;
        };
        let n = d.output.figures.len().max(1) as f32;
        let h = ((ui.available_height() - 60.0 * n - 120.0) / n).clamp(200.0, 420.0);
        for (k, (fig, shown)) in d.output.figures.iter().zip(&mut d.shown).enumerate() {
            ui.strong(&fig.plot.title);
            *shown = plot_view::draw(ui, ("paper-figure", k), &fig.plot, h, None);
            exporter.buttons(ui, shown, &fig.stem);
            ui.add_space(6.0);
        }
        ui.collapsing("findings", |ui| {
            egui::Grid::new("paper-findings")
                .striped(true)
                .show(ui, |ui| {
                    for f in &d.output.findings {
                        ui.label(&f.what);
                        ui.label(format!("{:.6} {}", f.value, f.unit));
                        ui.end_row();
                    }
                });
        })
        .header_response
        .on_hover_text("docs/paper-reproduction.md checks the paper's claims against these");
    }
}
