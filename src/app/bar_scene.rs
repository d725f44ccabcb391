//! The Bar impact scene: one impact through one model, with all its readouts: the bars, their
//! x-t diagram, force, approach and energy against time, and the run's error estimate.

use super::bar_view::{self, Solved};
use super::export::XtExport;
use super::export::{Exporter, ShownPlot};
use super::impact_scene::{
    ImpactCore, ImpactScene, context_of, force_line, plot_height, series, xt_diagram, xt_title,
};
use super::legend::Key;
use super::worker::SolveSlot;
use crate::io::settings::ImpactSetup;
use crate::lesson::Context;
use crate::model::control::Control;
use crate::model::impact::estimate::{ErrorEstimate, estimate_error_with};
use crate::model::impact::{ImpactResult, ModelKind, SolveError, solve_with};
use crate::model::scenario::Reading;
use crate::model::xt::XtField;
use crate::render::bars::XtShown;
use eframe::egui::{self, Color32};
use egui_plot::{Plot, VLine};
use std::time::Duration;

/// The model solved, its result, and the result's error estimate (one more, coarser solve).
type Output = (
    ModelKind,
    Result<ImpactResult, SolveError>,
    Option<ErrorEstimate>,
);

fn run_job(setup: ImpactSetup, control: &Control) -> Output {
    let model = setup.model;
    control.stage(0, 2);
    let result = solve_with(model, &setup.scenario, control);
    control.stage(1, 2);
    let estimate = result
        .as_ref()
        .ok()
        .and_then(|r| estimate_error_with(model, &setup.scenario, r, control).ok());
    (model, result, estimate)
}

pub struct BarScene {
    pub core: ImpactCore,
    pub(super) slot: SolveSlot<ImpactSetup, Output>,
    /// The last good run and its model: drawn while a newer solve runs or after one fails.
    solved: Option<(ModelKind, Solved)>,
    /// Whether `solved` is the newest solve's (a lesson reads no older result).
    fresh: bool,
    estimate: Option<ErrorEstimate>,
    shown_approach: ShownPlot,
}

impl BarScene {
    pub fn new(ctx: &egui::Context, setup: ImpactSetup) -> Self {
        let waker = ctx.clone();
        let mut s = BarScene {
            core: ImpactCore::new(setup, "bar-plots"),
            slot: SolveSlot::new(run_job, move || waker.request_repaint()),
            solved: None,
            fresh: false,
            estimate: None,
            shown_approach: ShownPlot::default(),
        };
        s.request();
        s
    }

    /// Takes a finished solve, if any.
    pub fn poll(&mut self) {
        // A panic's message stays as the error, and the last result on screen.
        let Some((model, result, estimate)) = self.slot.poll() else {
            return;
        };
        if matches!(result, Err(SolveError::Cancelled)) {
            self.slot.error = Some("cancelled: the last result is kept".into());
            return;
        }
        self.estimate = estimate;
        match result {
            Ok(r) => {
                let solved = Solved::new(self.core.setup, r);
                self.core.landed(&solved);
                self.solved = Some((model, solved));
                self.fresh = true;
            }
            // The last result stays on screen; the error says why this one failed.
            Err(e) => {
                self.slot.error = Some(format!("{}: {e}", model.name()));
                self.fresh = false;
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

    pub fn params_ui(&mut self, ui: &mut egui::Ui) {
        if self.core.params_ui(ui, true) {
            self.request();
        }
    }

    /// The plots on screen last frame, by export name.
    pub fn shown_plots(&self) -> Vec<(&str, &ShownPlot)> {
        if self.solved.is_none() {
            return vec![];
        }
        vec![
            ("force", &self.core.shown_force),
            ("approach", &self.shown_approach),
            ("energy", &self.core.shown_energy),
        ]
    }

    pub fn main_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter) {
        if let Some(e) = &self.slot.error {
            ui.colored_label(Color32::from_rgb(220, 60, 50), e);
        }
        if self.solved.is_none() {
            ui.label("solving...");
            return;
        }
        let t = self.core.playback.t;
        let show = self.core.visibility.clone();
        if show.shows("bars") {
            self.bars_ui(ui, t);
        }
        let clicked = if show.shows("xt") {
            self.xt_ui(ui, exporter)
        } else {
            None
        };
        let playback = &mut self.core.playback;
        if let Some(t) = clicked {
            playback.t = t;
            playback.playing = false;
        }
        if (show.shows("bars") || show.shows("xt")) && playback.ui(ui) {
            playback.playing = true;
        }
        self.plots_ui(ui, exporter);
        if let Some((_, solved)) = &self.solved
            && show.shows("readouts")
        {
            readouts_ui(
                ui,
                &solved.result,
                self.slot.solve_time,
                self.estimate.as_ref(),
            );
        }
    }

    /// The animated bars.
    fn bars_ui(&mut self, ui: &mut egui::Ui, t: f64) {
        let Some((_, solved)) = &self.solved else {
            return;
        };
        bar_view::caption(ui, solved, t);
        let (rect, _) = ui.allocate_exact_size(
            egui::vec2(ui.available_width(), super::fill::height(ui, 190.0, 70.0)),
            egui::Sense::hover(),
        );
        bar_view::draw(ui, rect, super::slots::BAR_VIEW, solved, t);
        self.core.view_rect = Some(rect);
    }

    /// The run's x-t diagram and its export buttons; returns a time set by a click in it.
    fn xt_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter) -> Option<f64> {
        let (_, solved) = self.solved.as_ref()?;
        let t = self.core.playback.t;
        let span = solved.span_s();
        self.core.xt.ui(ui);
        let title = xt_title(self.core.setup.model, solved);
        let options = self.core.xt;
        let clicked = xt_diagram(solved, span, &title).show(
            ui,
            super::slots::BAR_XT,
            super::fill::height(ui, 250.0, 80.0),
            t,
            &options,
        );
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
                title,
            },
            "xt",
        );
        clicked
    }

    fn plots_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter) {
        let Some((solved_model, solved)) = &self.solved else {
            return;
        };
        let core = &mut self.core;
        let t_ms = core.playback.t * 1e3;
        let show = core.visibility.clone();
        let model = core.setup.model;
        if show.shows("force") {
            let line = force_line(*solved_model, &solved.result);
            let title = format!("Contact force: {}", model.name());
            core.force_plot_ui(ui, exporter, plot_height(ui), t_ms, vec![line], title);
        }
        if show.shows("approach") {
            self.shown_approach = approach_ui(
                ui,
                &solved.result,
                (plot_height(ui), t_ms),
                model,
                core.plot_link,
            );
            exporter.buttons(ui, &self.shown_approach, "approach");
        }
        // Where the energy goes, once the run of the model chosen has landed.
        if show.shows("energy") && *solved_model == model {
            core.energy_ui(ui, exporter, (model, solved), plot_height(ui), t_ms);
        }
    }

    /// The shown run for File > Export animation, copied only when called.
    pub(super) fn animation_source(
        &self,
    ) -> Option<Box<dyn FnOnce() -> super::export_animation::AnimationSource + '_>> {
        let (_, s) = self.solved.as_ref()?;
        Some(Box::new(move || {
            super::export_animation::AnimationSource::Impact {
                setup: Box::new(s.setup),
                result: Box::new(s.result.clone()),
            }
        }))
    }
}

impl ImpactScene for BarScene {
    fn core(&self) -> &ImpactCore {
        &self.core
    }
    fn core_mut(&mut self) -> &mut ImpactCore {
        &mut self.core
    }
    fn request(&mut self) {
        self.slot.request(self.core.setup);
    }
    fn lesson_context(&self) -> Option<Context> {
        let (model, solved) = self
            .solved
            .as_ref()
            .filter(|_| self.fresh && !self.busy())?;
        context_of(&[(*model, solved)])
    }
}

/// The approach of the bars against time.
fn approach_ui(
    ui: &mut egui::Ui,
    r: &ImpactResult,
    (h, t_ms): (f32, f64),
    model: ModelKind,
    link: egui::Id,
) -> ShownPlot {
    let pts = series(r, &|j| r.approach_m[j] * 1e6);
    let width = super::lecture::line_width(ui);
    let key = Key::line("approach", super::legend::okabe_ito(0), false);
    super::legend::row(ui, std::slice::from_ref(&key));
    let response = Plot::new("approach")
        .y_grid_spacer(super::plot_view::nice_marks)
        .height(h)
        .x_axis_label("time [ms]")
        .y_axis_label("approach [um]")
        .link_axis(link, [true, false])
        .show(ui, |p| {
            p.line(key.plot_line(pts.clone(), width));
            p.vline(VLine::new("t", t_ms).color(egui::Color32::GRAY));
        });
    let b = response.transform.bounds();
    ShownPlot {
        title: format!("Approach: {}", model.name()),
        x_label: "time [ms]".into(),
        y_label: "approach [um]".into(),
        series: vec![("approach".into(), pts)],
        bounds: Some((b.min(), b.max())),
    }
}

fn readouts_ui(
    ui: &mut egui::Ui,
    r: &ImpactResult,
    solve_time: Duration,
    estimate: Option<&ErrorEstimate>,
) {
    use super::readouts::Readout;
    use crate::model::settings::engineering;
    let e = &r.energy;
    // A hall reads what the lesson talks about; the checks on the run are the researcher's.
    let lecture = super::lecture::on(ui.ctx());
    let mut rows = vec![
        Readout::new(
            "peak force",
            r.peak_force_n
                .map_or("none (instantaneous)".into(), |p| engineering(p, "N")),
        ),
        Readout::new("contact duration", engineering(r.contact_duration_s, "s")),
        Readout::new(
            "restitution e",
            format!(
                "{:.4} (first contact {:.4})",
                r.restitution, r.restitution_first_contact
            ),
        ),
        Readout::new("contacts", r.contacts.len().to_string()),
        Readout::new(
            "energy",
            format!(
                "rigid {}, vibration {}, dissipated {} of {}",
                engineering(e.rigid_body_j, "J"),
                engineering(e.vibration_j, "J"),
                engineering(e.dissipated_j, "J"),
                engineering(e.initial_j, "J")
            ),
        ),
    ];
    if !lecture {
        rows.push(Readout::new(
            "energy balance",
            format!("{:+.2e}", e.balance_error),
        ));
    }
    if let Some(d) = &r.sears {
        if !lecture {
            rows.push(Readout::new("Sears reading", d.reading.name()));
        }
        rows.push(Readout::new(
            "validity a tau",
            format!("{:.4} ({})", d.a_tau, d.regime()),
        ));
        if d.reading == Reading::Paper && d.creates_energy {
            rows.push(Readout::alarm("the paper reading created energy here"));
        }
    }
    if !lecture {
        rows.push(Readout::new(
            "solve",
            format!(
                "{} steps of {}, {}",
                r.stats.steps,
                engineering(r.stats.dt_s, "s"),
                super::ms(solve_time.as_secs_f64(), 3)
            ),
        ));
        rows.push(
        Readout::new(
            "error estimate",
            match estimate {
                None => "-".to_string(),
                Some(e) if e.method == "exact" => "exact".to_string(),
                Some(e) => format!(
                    "peak {:.1e}, duration {:.1e}, e {:.1e}",
                    e.peak_force, e.contact_duration, e.restitution
                ),
            },
        )
        .hover("Step doubling: the same impact with twice the step (half the mesh for FE), Richardson's |q(h) - q(2h)| / 3"),
    );
    }
    super::readouts::show(ui, "readouts", &rows);
    for w in &r.warnings {
        super::readouts::warning(ui, "warning", &w.to_string());
    }
}
