//! The Wave vs lumped scene: the same impact through the Sears model and its peers overlaid,
//! the Sears bars above a lumped pair of blocks, the x-t diagrams side by side on one scale.

use super::bar_view::{self, Solved};
use super::export::{Exporter, ShownPlot};
use super::impact_scene::{
    ImpactCore, ImpactScene, context_of, force_line, plot_height, xt_diagram, xt_title,
};
use super::worker::SolveSlot;
use crate::io::settings::ImpactSetup;
use crate::lesson::Context;
use crate::model::control::Control;
use crate::model::impact::{ImpactResult, ModelKind, SolveError, solve_with};
use eframe::egui::{self, Color32};

/// Models overlaid by the comparison scene.
pub const COMPARED: [ModelKind; 5] = [
    ModelKind::Sears,
    ModelKind::Wave,
    ModelKind::LumpedHertz,
    ModelKind::LumpedLinear,
    ModelKind::Fe,
];

/// The run drawn as bars, whose span the animation and the x-t diagrams take.
const LEAD: ModelKind = ModelKind::Sears;

/// Whose x-t diagrams stand side by side: waves with a contact law, without one, and none.
const XT_SHOWN: [ModelKind; 3] = [ModelKind::Sears, ModelKind::Wave, ModelKind::LumpedHertz];

type Output = Vec<(ModelKind, Result<ImpactResult, SolveError>)>;

/// One solve: the setup and the models to run it through.
type Job = (ImpactSetup, Vec<ModelKind>);

fn run_job((setup, models): Job, control: &Control) -> Output {
    let stages = models.len() as u32;
    models
        .iter()
        .enumerate()
        .map(|(k, &m)| {
            control.stage(k as u32, stages);
            (m, solve_with(m, &setup.scenario, control))
        })
        .collect()
}

pub struct CompareScene {
    pub core: ImpactCore,
    pub(super) slot: SolveSlot<Job, Output>,
    /// The models solved: those of [`COMPARED`] a lesson step names, or all of them.
    models: Vec<ModelKind>,
    /// The last solve whose lead ran: every model that solved, the lead among them.
    runs: Vec<(ModelKind, Solved)>,
    /// Whether `runs` are the newest solve's (a lesson reads no older result).
    fresh: bool,
    /// The models of that solve that failed, and why (a lesson's readout of theirs says so).
    failed: Vec<(ModelKind, String)>,
    /// The model whose energy is plotted.
    energy_model: ModelKind,
    /// Which of [`COMPARED`] the force plot shows.
    shown: [bool; 5],
}

impl CompareScene {
    pub fn new(ctx: &egui::Context, setup: ImpactSetup) -> Self {
        let waker = ctx.clone();
        let mut s = CompareScene {
            core: ImpactCore::new(setup, "compare-plots"),
            slot: SolveSlot::new(run_job, move || waker.request_repaint()),
            models: COMPARED.to_vec(),
            runs: vec![],
            fresh: false,
            failed: vec![],
            energy_model: LEAD,
            shown: [true; 5],
        };
        s.request();
        s
    }

    /// Solves only `models` (a lesson step's), or, given none, every model compared.
    pub fn set_models(&mut self, models: &[ModelKind]) {
        let models = if models.is_empty() {
            COMPARED.to_vec()
        } else {
            models.to_vec()
        };
        if models != self.models {
            self.models = models;
            self.runs.clear();
            self.request();
        }
    }

    /// The lead's run.
    fn lead(&self) -> Option<&Solved> {
        self.run(LEAD)
    }

    fn run(&self, model: ModelKind) -> Option<&Solved> {
        self.runs.iter().find(|(m, _)| *m == model).map(|(_, s)| s)
    }

    /// Takes a finished solve, if any. Models that failed are named in the error; without the
    /// lead's run the last result stays whole.
    pub fn poll(&mut self) {
        // A panic's message stays as the error, and the last result on screen.
        let Some(results) = self.slot.poll() else {
            return;
        };
        if results
            .iter()
            .any(|(_, r)| matches!(r, Err(SolveError::Cancelled)))
        {
            self.slot.error = Some("cancelled: the last result is kept".into());
            return;
        }
        let mut runs = vec![];
        let mut failed = vec![];
        for (model, result) in results {
            match result {
                Ok(r) => runs.push((model, Solved::new(self.core.setup, r))),
                Err(e) => {
                    // A compared model the setup does not suit (lumped Hertz on a flat end)
                    // is left out and said quietly; only a failed run is an error.
                    if !matches!(e, SolveError::Input(_)) || model == LEAD {
                        self.slot.error = Some(format!("{}: {e}", model.name()));
                    }
                    failed.push((model, e.to_string()));
                }
            }
        }
        self.fresh = match runs.iter().find(|(m, _)| *m == LEAD) {
            Some((_, lead)) => {
                self.core.landed(lead);
                true
            }
            None => false,
        };
        if self.fresh {
            self.runs = runs;
            self.failed = failed;
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
        if self.core.params_ui(ui, false) {
            self.request();
        }
    }

    /// The plots on screen last frame, by export name.
    pub fn shown_plots(&self) -> Vec<(&str, &ShownPlot)> {
        if self.lead().is_none() {
            return vec![];
        }
        vec![
            ("force", &self.core.shown_force),
            ("energy", &self.core.shown_energy),
        ]
    }

    pub fn main_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter) {
        if let Some(e) = &self.slot.error {
            ui.colored_label(Color32::from_rgb(220, 60, 50), e);
        }
        for (m, why) in &self.failed {
            if !matches!(self.slot.error.as_deref(), Some(e) if e.starts_with(m.name())) {
                ui.weak(format!("{} is left out here: {why}", m.name()));
            }
        }
        if self.lead().is_none() {
            ui.label("solving...");
            return;
        }
        let t = self.core.playback.t;
        let show = self.core.visibility.clone();
        if show.shows("bars") {
            self.bars_ui(ui, t);
        }
        let clicked = if show.shows("xt") {
            self.xt_ui(ui)
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
        // A lecture's step names its models; the plot's legend says which line is which.
        if show.shows("force") && !super::lecture::on(ui.ctx()) {
            ui.horizontal(|ui| {
                ui.label("show:");
                for (i, m) in COMPARED.iter().enumerate() {
                    ui.checkbox(&mut self.shown[i], m.name());
                }
            });
        }
        self.plots_ui(ui, exporter);
        if show.shows("readouts") {
            compare_table(ui, &self.runs);
        }
    }

    /// The Sears bars, and below them the lumped blocks.
    fn bars_ui(&mut self, ui: &mut egui::Ui, t: f64) {
        let Some(lead) = self.lead() else { return };
        bar_view::caption(ui, lead, t);
        let (rect, _) = ui.allocate_exact_size(
            egui::vec2(ui.available_width(), super::fill::height(ui, 150.0, 50.0)),
            egui::Sense::hover(),
        );
        bar_view::draw(ui, rect, super::slots::COMPARE_VIEW, lead, t);
        let strip = if super::lecture::on(ui.ctx()) {
            40.0
        } else {
            70.0
        };
        let (lumped_rect, _) = ui.allocate_exact_size(
            egui::vec2(ui.available_width(), strip),
            egui::Sense::hover(),
        );
        if let Some(lumped) = self.run(ModelKind::LumpedHertz) {
            draw_lumped(ui, lumped_rect, &lumped.result, t);
        }
        self.core.view_rect = Some(rect);
    }

    /// Sears, wave theory and the lumped Hertz bodies' uniform stress side by side on the same
    /// scales. Returns a time set by a click in one.
    fn xt_ui(&mut self, ui: &mut egui::Ui) -> Option<f64> {
        let span = self.lead()?.span_s();
        let t = self.core.playback.t;
        self.core.xt.ui(ui);
        let shown: Vec<(ModelKind, &Solved)> = XT_SHOWN
            .iter()
            .filter_map(|&m| self.run(m).map(|s| (m, s)))
            .collect();
        let titles: Vec<String> = shown.iter().map(|(m, s)| xt_title(*m, s)).collect();
        let options = self.core.xt;
        let mut clicked = None;
        let h = super::fill::height(ui, 230.0, 80.0);
        ui.columns(shown.len().max(1), |cols| {
            for (k, col) in cols.iter_mut().enumerate().take(shown.len()) {
                let slot = super::slots::COMPARE_XT + k as u64;
                let diagram = xt_diagram(shown[k].1, span, &titles[k]);
                if let Some(t) = diagram.show(col, slot, h, t, &options) {
                    clicked = Some(t);
                }
            }
        });
        clicked
    }

    fn plots_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter) {
        let t_ms = self.core.playback.t * 1e3;
        let show = self.core.visibility.clone();
        if show.shows("force") {
            let lines = self
                .runs
                .iter()
                .enumerate()
                .filter(|(i, (m, _))| {
                    self.shown[COMPARED.iter().position(|c| c == m).unwrap_or(*i)]
                })
                .map(|(_, (m, s))| force_line(*m, &s.result))
                .collect();
            let title = "Contact force by model".to_string();
            self.core
                .force_plot_ui(ui, exporter, plot_height(ui), t_ms, lines, title);
        }
        // Where the energy goes: the chosen model's.
        if !show.shows("energy") {
            return;
        }
        ui.horizontal(|ui| {
            let label = ui.label("energy of").id;
            egui::ComboBox::from_id_salt("energy-model")
                .selected_text(self.energy_model.name())
                .show_ui(ui, |ui| {
                    for (m, _) in &self.runs {
                        ui.selectable_value(&mut self.energy_model, *m, m.name());
                    }
                })
                .response
                .labelled_by(label);
        });
        let model = self.energy_model;
        if let Some((_, s)) = self.runs.iter().find(|(m, _)| *m == model) {
            self.core
                .energy_ui(ui, exporter, (model, s), plot_height(ui), t_ms);
        }
    }
}

impl ImpactScene for CompareScene {
    fn core(&self) -> &ImpactCore {
        &self.core
    }
    fn core_mut(&mut self) -> &mut ImpactCore {
        &mut self.core
    }
    fn request(&mut self) {
        self.slot.request((self.core.setup, self.models.clone()));
    }
    fn lesson_context(&self) -> Option<Context> {
        if !self.fresh || self.busy() {
            return None;
        }
        let runs: Vec<_> = self.runs.iter().map(|(m, s)| (*m, s)).collect();
        context_of(&runs).map(|ctx| ctx.with_failures(&self.failed))
    }
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
        "lumped Hertz: rigid blocks, a spring",
        super::lecture::font(painter.ctx(), 12.0),
        text,
    );
}

fn compare_table(ui: &mut egui::Ui, peers: &[(ModelKind, Solved)]) {
    use crate::model::settings::engineering;
    // What each solve cost is the researcher's column, not the class's.
    let costs = !super::lecture::on(ui.ctx());
    egui::Grid::new("compare")
        .num_columns(if costs { 5 } else { 4 })
        .striped(true)
        .spacing([18.0, if costs { 4.0 } else { 0.0 }])
        .show(ui, |ui| {
            let model = crate::model::settings::impact::MODEL.label;
            for h in [model, "peak force", "duration", "e"] {
                ui.strong(h);
            }
            if costs {
                ui.strong("solve");
            }
            ui.end_row();
            for (m, s) in peers {
                let r = &s.result;
                ui.label(m.name());
                ui.label(r.peak_force_n.map_or("-".into(), |p| engineering(p, "N")));
                ui.label(engineering(r.contact_duration_s, "s"));
                ui.label(format!("{:.4}", r.restitution));
                if costs {
                    ui.label(super::ms(r.stats.wall_time_s, 3));
                }
                ui.end_row();
            }
        });
    // Each model's own warnings (an FE mesh too coarse for a stiff contact, say): a number in
    // the table is read with what its model says about it.
    for (m, s) in peers {
        for w in &s.result.warnings {
            super::readouts::warning(ui, m.name(), &w.to_string());
        }
    }
}
