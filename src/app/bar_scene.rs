//! The Bar impact scene, and the Wave vs lumped scene: the same impact, either through one model
//! with all its readouts, or through the Sears model and its peers overlaid.

use super::bar_view::{self, Solved};
use super::energy_view;
use super::export::XtExport;
use super::export::{Exporter, ShownPlot};
use super::impact_params;
use super::params::Fields;
use super::playback::Playback;
use super::visibility::Visibility;
use super::worker::SolveSlot;
use super::xt_view::{XtDiagram, XtOptions, XtSource};
use crate::io::preset;
use crate::io::settings::ImpactSetup;
use crate::model::control::Control;
use crate::model::impact::estimate::{ErrorEstimate, estimate_error_with};
use crate::model::impact::{ImpactResult, ModelKind, SolveError, solve_with};
use crate::model::scenario::Reading;
use crate::model::xt::XtField;
use crate::render::bars::XtShown;
use eframe::egui::{self, Color32};
use egui_plot::{Legend, Line, Plot, VLine};
use std::time::Duration;

/// Models overlaid by the comparison scene.
pub const COMPARED: [ModelKind; 5] = [
    ModelKind::Sears,
    ModelKind::Wave,
    ModelKind::LumpedHertz,
    ModelKind::LumpedLinear,
    ModelKind::Fe,
];

type Job = (ImpactSetup, bool);
type Output = (
    Vec<(ModelKind, Result<ImpactResult, SolveError>)>,
    Option<ErrorEstimate>,
);

pub struct BarScene {
    pub setup: ImpactSetup,
    pub compare: bool,
    pub fields: Fields,
    pub(super) slot: SolveSlot<Job, Output>,
    solved: Option<Solved>,
    /// Every model's run (the comparison), or the one model's.
    peers: Vec<(ModelKind, Solved)>,
    /// What the x-t diagrams show.
    pub xt: XtOptions,
    /// The model whose energy the comparison plots.
    energy_model: ModelKind,
    estimate: Option<ErrorEstimate>,
    shown: [bool; 5],
    pub playback: Playback,
    /// The view's rectangle last frame (for a screenshot of the view alone).
    pub view_rect: Option<egui::Rect>,
    shown_force: ShownPlot,
    shown_approach: ShownPlot,
    shown_energy: ShownPlot,
    /// The panels drawn (a lesson step's, or all).
    pub visibility: Visibility,
}

fn run_job((setup, compare): Job, control: &Control) -> Output {
    let models: Vec<ModelKind> = if compare {
        COMPARED.to_vec()
    } else {
        vec![setup.model]
    };
    // The single-model scene shows its result's own error estimate (one more, coarser solve).
    let stages = if compare { models.len() } else { 2 } as u32;
    let results: Vec<_> = models
        .into_iter()
        .enumerate()
        .map(|(k, m)| {
            control.stage(k as u32, stages);
            (m, solve_with(m, &setup.scenario, control))
        })
        .collect();
    control.stage(1, stages);
    let estimate = match (&results[..], compare) {
        ([(m, Ok(r))], false) => estimate_error_with(*m, &setup.scenario, r, control).ok(),
        _ => None,
    };
    (results, estimate)
}

impl BarScene {
    pub fn new(ctx: &egui::Context, setup: ImpactSetup, compare: bool) -> Self {
        let waker = ctx.clone();
        let mut s = BarScene {
            visibility: Visibility::default(),
            setup,
            compare,
            fields: Fields::default(),
            slot: SolveSlot::new(run_job, move || waker.request_repaint()),
            solved: None,
            peers: vec![],
            xt: XtOptions::default(),
            energy_model: ModelKind::Sears,
            estimate: None,
            shown: [true; 5],
            playback: Playback::default(),
            view_rect: None,
            shown_force: ShownPlot::default(),
            shown_approach: ShownPlot::default(),
            shown_energy: ShownPlot::default(),
        };
        s.request();
        s
    }

    pub fn request(&mut self) {
        self.slot.request((self.setup, self.compare));
    }

    /// Takes a finished solve, if any.
    pub fn poll(&mut self) {
        // A panic's message stays as the error, and the last result on screen.
        let Some((results, estimate)) = self.slot.poll() else {
            return;
        };
        if results
            .iter()
            .any(|(_, r)| matches!(r, Err(SolveError::Cancelled)))
        {
            self.slot.error = Some("cancelled: the last result is kept".into());
            return;
        }
        self.peers.clear();
        self.estimate = estimate;
        for (model, result) in results {
            match result {
                Ok(r) => {
                    let lead = if self.compare {
                        model == ModelKind::Sears
                    } else {
                        true
                    };
                    let solved = Solved::new(self.setup, r);
                    if lead {
                        self.playback.t_max = solved.span_s();
                        self.playback.t = self.playback.t.min(self.playback.t_max);
                        self.solved = Some(Solved::new(self.setup, solved.result.clone()));
                    }
                    self.peers.push((model, solved));
                }
                // The last result stays on screen; the error says why this one failed.
                Err(e) => self.slot.error = Some(format!("{}: {e}", model.name())),
            }
        }
    }

    pub fn busy(&self) -> bool {
        self.slot.busy()
    }

    /// The running solve's progress, once it has taken longer than a frame.
    pub fn progress(&self) -> Option<f64> {
        self.slot.progress()
    }

    pub fn cancel(&mut self) {
        self.slot.cancel();
    }

    /// Loads a preset by name or file; on error the scene is kept and the error returned.
    pub fn load_preset(&mut self, name_or_path: &str) -> Result<(), String> {
        let setup: ImpactSetup =
            preset::load_for(name_or_path, "impact").map_err(|e| e.to_string())?;
        self.setup = setup;
        self.fields.clear();
        self.playback.t = 0.0;
        self.request();
        Ok(())
    }

    /// What a lesson's expressions read: the settings the results were solved with and every
    /// model's run; `None` while a solve is under way (the results would be stale).
    pub fn lesson_context(&self) -> Option<crate::lesson::Context> {
        if self.busy() || self.peers.is_empty() {
            return None;
        }
        let setup = &self.peers[0].1.setup;
        let runs: Vec<_> = self.peers.iter().map(|(m, s)| (*m, &s.result)).collect();
        Some(crate::lesson::Context::impact(setup, &runs))
    }

    pub fn params_ui(&mut self, ui: &mut egui::Ui) {
        if impact_params::ui(ui, &mut self.fields, &mut self.setup, !self.compare) {
            self.request();
        }
    }

    /// The plots on screen last frame, by export name.
    pub fn shown_plots(&self) -> Vec<(&str, &ShownPlot)> {
        let mut plots = vec![];
        if self.solved.is_some() {
            plots.push(("force", &self.shown_force));
            if !self.compare {
                plots.push(("approach", &self.shown_approach));
            }
            plots.push(("energy", &self.shown_energy));
        }
        plots
    }

    pub fn main_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter) {
        if let Some(e) = &self.slot.error {
            ui.colored_label(Color32::from_rgb(220, 60, 50), e);
        }
        if self.solved.is_none() {
            ui.label("solving...");
            return;
        }
        let t = self.playback.t;
        let show = self.visibility.clone();
        if show.shows("bars") {
            self.bars_ui(ui, t);
        }
        let clicked = if show.shows("xt") {
            self.xt_ui(ui, exporter)
        } else {
            None
        };
        if let Some(t) = clicked {
            self.playback.t = t;
            self.playback.playing = false;
        }
        if (show.shows("bars") || show.shows("xt")) && self.playback.ui(ui) {
            self.playback.playing = true;
        }
        if self.compare && show.shows("force") {
            ui.horizontal(|ui| {
                ui.label("show:");
                for (i, m) in COMPARED.iter().enumerate() {
                    ui.checkbox(&mut self.shown[i], m.name());
                }
            });
        }
        self.plots_ui(ui, exporter);
        if !show.shows("readouts") {
            return;
        }
        if !self.compare
            && let Some(solved) = &self.solved
        {
            readouts_ui(
                ui,
                &solved.result,
                self.slot.solve_time,
                self.estimate.as_ref(),
            );
        } else {
            compare_table(ui, &self.peers);
        }
    }

    /// The animated bars (and in the comparison the lumped blocks below them).
    fn bars_ui(&mut self, ui: &mut egui::Ui, t: f64) {
        let Some(solved) = &self.solved else { return };
        let height = if self.compare { 150.0 } else { 190.0 };
        let (rect, _) = ui.allocate_exact_size(
            egui::vec2(ui.available_width(), height),
            egui::Sense::hover(),
        );
        let slot = if self.compare {
            super::slots::COMPARE_VIEW
        } else {
            super::slots::BAR_VIEW
        };
        bar_view::draw(ui, rect, slot, solved, t);
        self.view_rect = Some(rect);
        if self.compare {
            let lumped = self
                .peers
                .iter()
                .find(|(m, _)| *m == ModelKind::LumpedHertz)
                .map(|(_, s)| &s.result);
            let (rect, _) = ui
                .allocate_exact_size(egui::vec2(ui.available_width(), 70.0), egui::Sense::hover());
            if let Some(r) = lumped {
                draw_lumped(ui, rect, r, t);
            }
        }
    }

    /// The x-t diagrams: the run's (Bar impact), or Sears, wave theory and the lumped Hertz
    /// bodies' uniform stress side by side on the same scales (Wave vs lumped). Returns a time
    /// set by a click in one.
    fn xt_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter) -> Option<f64> {
        let solved = self.solved.as_ref()?;
        let t = self.playback.t;
        let span = solved.span_s();
        self.xt.ui(ui);
        let shown: Vec<(ModelKind, &Solved)> = if self.compare {
            [ModelKind::Sears, ModelKind::Wave, ModelKind::LumpedHertz]
                .iter()
                .filter_map(|m| self.peers.iter().find(|(p, _)| p == m))
                .map(|(m, s)| (*m, s))
                .collect()
        } else {
            vec![(self.setup.model, solved)]
        };
        let mut clicked = None;
        let titles: Vec<String> = shown
            .iter()
            .map(|(m, s)| {
                if s.result.waves.is_some() {
                    format!("{}: space-time", m.name())
                } else {
                    format!("{}: uniform stress F/A", m.name())
                }
            })
            .collect();
        let diagram = |k: usize| {
            let (_, s) = shown[k];
            XtDiagram {
                source: XtSource::Impact {
                    sc: &s.setup.scenario,
                    result: &s.result,
                },
                gpu: &s.gpu,
                t_start: 0.0,
                t_span: span,
                title: &titles[k],
                zones_m: s.zones_m(),
            }
        };
        let options = self.xt;
        if self.compare {
            ui.columns(shown.len().max(1), |cols| {
                for (k, col) in cols.iter_mut().enumerate().take(shown.len()) {
                    let slot = super::slots::COMPARE_XT + k as u64;
                    if let Some(t) = diagram(k).show(col, slot, 230.0, t, &options) {
                        clicked = Some(t);
                    }
                }
            });
        } else if let Some(t) = diagram(0).show(ui, super::slots::BAR_XT, 250.0, t, &options) {
            clicked = Some(t);
        }
        if !self.compare {
            let sc = &solved.setup.scenario;
            exporter.xt_buttons(
                ui,
                &XtExport {
                    result: &solved.result,
                    areas_m2: [sc.bar1.area_m2(), sc.bar2.area_m2()],
                    lengths_m: [sc.bar1.length_m, sc.bar2.length_m],
                    t_end: span,
                    field: match options.field {
                        XtShown::Stress => XtField::Stress,
                        XtShown::Velocity => XtField::Velocity,
                    },
                    zones_m: solved.zones_m(),
                    title: titles[0].clone(),
                },
                "xt",
            );
        }
        clicked
    }

    fn plots_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter) {
        let t_ms = self.playback.t * 1e3;
        let h = ((ui.available_height() - 160.0) / 2.0).clamp(120.0, 260.0);
        let show = self.visibility.clone();
        if show.shows("force") {
            self.force_plot_ui(ui, exporter, h, t_ms);
        }
        if !self.compare
            && show.shows("approach")
            && let Some(s) = &self.solved
        {
            let r = &s.result;
            let pts = series(r, &|j| r.approach_m[j] * 1e6);
            let width = super::lecture::line_width(ui);
            let response = Plot::new("approach")
                .y_grid_spacer(super::plot_view::nice_marks)
                .height(h)
                .legend(Legend::default())
                .x_axis_label("time [ms]")
                .y_axis_label("approach [um]")
                .link_axis(egui::Id::unique("bar-plots"), [true, false])
                .show(ui, |p| {
                    p.line(Line::new("approach", pts.clone()).width(width));
                    p.vline(VLine::new("t", t_ms));
                });
            let b = response.transform.bounds();
            self.shown_approach = ShownPlot {
                title: format!("Approach: {}", self.setup.model.name()),
                x_label: "time [ms]".into(),
                y_label: "approach [um]".into(),
                series: vec![("approach".into(), pts)],
                bounds: Some((b.min(), b.max())),
            };
            exporter.buttons(ui, &self.shown_approach, "approach");
        }
        // Where the energy goes: the run's, or the chosen model's in the comparison.
        if !show.shows("energy") {
            return;
        }
        if self.compare {
            ui.horizontal(|ui| {
                let label = ui.label("energy of").id;
                egui::ComboBox::from_id_salt("energy-model")
                    .selected_text(self.energy_model.name())
                    .show_ui(ui, |ui| {
                        for (m, _) in &self.peers {
                            ui.selectable_value(&mut self.energy_model, *m, m.name());
                        }
                    })
                    .response
                    .labelled_by(label);
            });
        }
        let model = if self.compare {
            self.energy_model
        } else {
            self.setup.model
        };
        if let Some((_, s)) = self.peers.iter().find(|(m, _)| *m == model) {
            self.shown_energy = energy_view::draw(
                ui,
                "energy",
                &s.setup.scenario,
                &s.result,
                h,
                t_ms,
                format!("Energy: {}", model.name()),
            );
            exporter.buttons(ui, &self.shown_energy, "energy");
        }
    }

    /// The contact force: the run's, or every model's shown in the comparison.
    fn force_plot_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter, h: f32, t_ms: f64) {
        let mut force_lines = vec![];
        for (i, (m, s)) in self.peers.iter().enumerate() {
            let r = &s.result;
            let k = COMPARED.iter().position(|c| c == m).unwrap_or(i);
            if !self.compare || self.shown[k] {
                force_lines.push((m.name().to_string(), series(r, &|j| r.force_n[j] * 1e-3)));
            }
        }
        let width = super::lecture::line_width(ui);
        let response = Plot::new("force")
            .y_grid_spacer(super::plot_view::nice_marks)
            .height(h)
            .legend(Legend::default())
            .x_axis_label("time [ms]")
            .y_axis_label("force [kN]")
            .link_axis(egui::Id::unique("bar-plots"), [true, false])
            .show(ui, |p| {
                for (name, pts) in &force_lines {
                    // Wave theory jumps (repeated times): no band aggregation, which would fill them.
                    p.line(
                        Line::new(name.as_str(), pts.clone())
                            .allow_band(false)
                            .width(width),
                    );
                }
                p.vline(VLine::new("t", t_ms));
            });
        let b = response.transform.bounds();
        self.shown_force = ShownPlot {
            title: if self.compare {
                "Contact force by model".into()
            } else {
                format!("Contact force: {}", self.setup.model.name())
            },
            x_label: "time [ms]".into(),
            y_label: "force [kN]".into(),
            series: force_lines,
            bounds: Some((b.min(), b.max())),
        };
        exporter.buttons(ui, &self.shown_force, "force");
    }
}

/// A result's signal against time in ms, decimated for the screen.
fn series(r: &ImpactResult, f: &dyn Fn(usize) -> f64) -> Vec<[f64; 2]> {
    let t: Vec<f64> = r.time_s.iter().map(|t| t * 1e3).collect();
    let y: Vec<f64> = (0..r.time_s.len()).map(f).collect();
    super::series::decimate(&t, &y, 1.0)
}

/// Rigid blocks and a spring: the lumped reading, with the spring's compression exaggerated.
fn draw_lumped(ui: &mut egui::Ui, rect: egui::Rect, r: &ImpactResult, t: f64) {
    let painter = ui.painter_at(rect);
    let text = ui.visuals().text_color();
    let dmax = r.approach_m.iter().cloned().fold(1e-30, f64::max);
    let k = r.time_s.partition_point(|&x| x <= t);
    let d = if k == 0 || k >= r.approach_m.len() {
        0.0
    } else {
        r.approach_m[k - 1].max(0.0)
    };
    let f = if k == 0 || k >= r.force_n.len() {
        0.0
    } else {
        r.force_n[k - 1]
    };
    let squeeze = (d / dmax) as f32;
    let (cx, cy) = (rect.center().x, rect.center().y);
    let spring = 60.0 * (1.0 - 0.6 * squeeze);
    let tint = bar_view::diverging(-(f / r.peak_force_n.unwrap_or(1.0).max(1e-30)) as f32);
    let block = |x0: f32, x1: f32| {
        egui::Rect::from_min_max(egui::pos2(x0, cy - 18.0), egui::pos2(x1, cy + 18.0))
    };
    painter.rect_filled(
        block(cx - spring / 2.0 - 160.0, cx - spring / 2.0),
        2.0,
        tint,
    );
    painter.rect_filled(
        block(cx + spring / 2.0, cx + spring / 2.0 + 220.0),
        2.0,
        tint,
    );
    let mut pts = vec![];
    for i in 0..=12 {
        let x = cx - spring / 2.0 + spring * i as f32 / 12.0;
        let y = if i == 0 || i == 12 {
            cy
        } else if i % 2 == 1 {
            cy - 8.0
        } else {
            cy + 8.0
        };
        pts.push(egui::pos2(x, y));
    }
    painter.add(egui::Shape::line(pts, egui::Stroke::new(2.0, text)));
    painter.text(
        egui::pos2(rect.left() + 8.0, rect.top() + 4.0),
        egui::Align2::LEFT_TOP,
        "lumped Hertz: rigid blocks and a spring (compression exaggerated)",
        egui::FontId::proportional(12.0),
        text,
    );
}

fn readouts_ui(
    ui: &mut egui::Ui,
    r: &ImpactResult,
    solve_time: Duration,
    estimate: Option<&ErrorEstimate>,
) {
    egui::Grid::new("readouts")
        .num_columns(4)
        .spacing([18.0, 4.0])
        .show(ui, |ui| {
            ui.label("peak force");
            ui.label(
                r.peak_force_n
                    .map_or("none (instantaneous)".into(), |p| format!("{:.5e} N", p)),
            );
            ui.label("contact duration");
            ui.label(format!("{:.5} ms", r.contact_duration_s * 1e3));
            ui.end_row();
            ui.label("restitution e");
            ui.label(format!(
                "{:.5} (first contact {:.5})",
                r.restitution, r.restitution_first_contact
            ));
            ui.label("contacts");
            ui.label(format!("{}", r.contacts.len()));
            ui.end_row();
            let e = &r.energy;
            ui.label("energy");
            ui.label(format!(
                "rigid {:.3e} J, vibration {:.3e} J, dissipated {:.3e} J of {:.3e} J",
                e.rigid_body_j, e.vibration_j, e.dissipated_j, e.initial_j
            ));
            ui.label("energy balance");
            ui.label(format!("{:+.2e}", e.balance_error));
            ui.end_row();
            if let Some(d) = &r.sears {
                ui.label("Sears reading");
                ui.label(d.reading.name());
                ui.label("validity a tau");
                let regime = if d.a_tau < (-1f64).exp() {
                    "well behaved"
                } else if d.a_tau < std::f64::consts::FRAC_PI_2 {
                    "overshoot"
                } else {
                    "oscillating"
                };
                ui.label(format!("{:.4} ({regime})", d.a_tau));
                ui.end_row();
                if d.reading == Reading::Paper && d.creates_energy {
                    ui.colored_label(
                        Color32::from_rgb(220, 60, 50),
                        "the paper reading created energy here",
                    );
                    ui.end_row();
                }
            }
            ui.label("solve");
            ui.label(format!(
                "{} steps of {:.3e} s, {}",
                r.stats.steps,
                r.stats.dt_s,
                super::ms(solve_time.as_secs_f64(), 3)
            ));
            ui.label("error estimate").on_hover_text("Step doubling: the same impact with twice the step (half the mesh for FE), Richardson's |q(h) - q(2h)| / 3");
            ui.label(match estimate {
                None => "-".to_string(),
                Some(e) if e.method == "exact" => "exact".to_string(),
                Some(e) => format!("peak {:.1e}, duration {:.1e}, e {:.1e}", e.peak_force, e.contact_duration, e.restitution),
            });
            ui.end_row();
        });
    for w in &r.warnings {
        ui.colored_label(Color32::from_rgb(220, 140, 40), format!("warning: {w}"));
    }
}

fn compare_table(ui: &mut egui::Ui, peers: &[(ModelKind, Solved)]) {
    egui::Grid::new("compare")
        .num_columns(5)
        .striped(true)
        .spacing([18.0, 4.0])
        .show(ui, |ui| {
            let model = crate::model::settings::impact::MODEL.label;
            for h in [model, "peak force [N]", "duration [ms]", "e", "solve"] {
                ui.strong(h);
            }
            ui.end_row();
            for (m, s) in peers {
                let r = &s.result;
                ui.label(m.name());
                ui.label(r.peak_force_n.map_or("-".into(), |p| format!("{p:.4e}")));
                ui.label(format!("{:.4}", r.contact_duration_s * 1e3));
                ui.label(format!("{:.4}", r.restitution));
                ui.label(super::ms(r.stats.wall_time_s, 3));
                ui.end_row();
            }
        });
}

impl BarScene {
    /// The shown run for File > Export animation, copied only when called.
    pub(super) fn animation_source(
        &self,
    ) -> Option<Box<dyn FnOnce() -> super::export_animation::AnimationSource + '_>> {
        let s = self.solved.as_ref()?;
        Some(Box::new(move || {
            super::export_animation::AnimationSource::Impact {
                setup: Box::new(s.setup),
                result: Box::new(s.result.clone()),
            }
        }))
    }
}
