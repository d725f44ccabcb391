//! What the two impact scenes (Bar impact, Wave vs lumped) share, by composition: the setup and
//! its parameter rows, the playback, the panels shown, the x-t options, and the force and
//! energy plots as drawn last frame. Each scene keeps its own solve slot and its result once.

use super::bar_view::Solved;
use super::energy_view;
use super::export::{Exporter, ShownPlot};
use super::impact_params;
use super::legend::Key;
use super::params::Fields;
use super::playback::Playback;
use super::visibility::Visibility;
use super::xt_view::{XtDiagram, XtOptions, XtSource};
use crate::io::preset;
use crate::io::settings::ImpactSetup;
use crate::lesson::Context;
use crate::model::impact::{ImpactResult, ModelKind};
use eframe::egui;
use egui_plot::{Plot, VLine};

pub struct ImpactCore {
    pub setup: ImpactSetup,
    pub fields: Fields,
    /// What the x-t diagrams show.
    pub xt: XtOptions,
    pub playback: Playback,
    /// The view's rectangle last frame (for a screenshot of the view alone).
    pub view_rect: Option<egui::Rect>,
    /// The panels drawn (a lesson step's, or all).
    pub visibility: Visibility,
    pub(super) shown_force: ShownPlot,
    /// The scene's plots pan and zoom together in time, and only they: the scenes' own links.
    pub(super) plot_link: egui::Id,
    pub(super) shown_energy: ShownPlot,
}

impl ImpactCore {
    pub fn new(setup: ImpactSetup, plot_link: &'static str) -> Self {
        ImpactCore {
            plot_link: egui::Id::unique(plot_link),
            setup,
            fields: Fields::default(),
            xt: XtOptions::default(),
            playback: Playback::default(),
            view_rect: None,
            visibility: Visibility::default(),
            shown_force: ShownPlot::default(),
            shown_energy: ShownPlot::default(),
        }
    }

    /// A new lead result landed: the animation spans it.
    pub(super) fn landed(&mut self, lead: &Solved) {
        self.playback.t_max = lead.span_s();
        self.playback.t = self.playback.t.min(self.playback.t_max);
    }

    /// The parameter panel; returns whether anything changed.
    pub(super) fn params_ui(&mut self, ui: &mut egui::Ui, show_model: bool) -> bool {
        impact_params::ui(ui, &mut self.fields, &mut self.setup, show_model)
    }

    /// The contact force against time of each line, with the animation time marked.
    pub(super) fn force_plot_ui(
        &mut self,
        ui: &mut egui::Ui,
        exporter: &Exporter,
        h: f32,
        t_ms: f64,
        lines: Vec<(String, Vec<[f64; 2]>)>,
        title: String,
    ) {
        let width = super::lecture::line_width(ui);
        let keys: Vec<Key> = lines
            .iter()
            .enumerate()
            .map(|(k, (name, _))| Key::of_series(name, k))
            .collect();
        super::legend::row(ui, &keys);
        let response = Plot::new("force")
            .y_grid_spacer(super::plot_view::nice_marks)
            .height(h)
            .x_axis_label("time [ms]")
            .y_axis_label("force [kN]")
            .link_axis(self.plot_link, [true, false])
            .show(ui, |p| {
                // Sears on top: the curves that lie on it (FE, a stiff contact's wave theory)
                // are dashed beneath it.
                let mut order: Vec<(&Key, &Vec<[f64; 2]>)> =
                    keys.iter().zip(lines.iter().map(|(_, pts)| pts)).collect();
                order.sort_by_key(|(key, _)| key.name == "sears");
                for (key, pts) in order {
                    // Wave theory jumps (repeated times): no band aggregation, which would fill them.
                    p.line(key.plot_line(pts.clone(), width).allow_band(false));
                }
                // The time line in grey: no model's colour.
                p.vline(VLine::new("t", t_ms).color(egui::Color32::GRAY));
            });
        let b = response.transform.bounds();
        self.shown_force = ShownPlot {
            title,
            x_label: "time [ms]".into(),
            y_label: "force [kN]".into(),
            series: lines,
            bounds: Some((b.min(), b.max())),
        };
        exporter.buttons(ui, &self.shown_force, "force");
    }

    /// Where one run's energy goes over time.
    pub(super) fn energy_ui(
        &mut self,
        ui: &mut egui::Ui,
        exporter: &Exporter,
        run: (ModelKind, &Solved),
        h: f32,
        t_ms: f64,
    ) {
        let (model, s) = run;
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

/// What the window's menus and the lesson player ask of either impact scene.
pub trait ImpactScene {
    fn core(&self) -> &ImpactCore;
    fn core_mut(&mut self) -> &mut ImpactCore;
    /// Solves the current setup in the background.
    fn request(&mut self);
    /// What a lesson's expressions read: the settings the newest results were solved with and
    /// their runs; `None` while a solve is under way or when the newest one failed.
    fn lesson_context(&self) -> Option<Context>;

    /// Loads a preset by name or file; on error the scene is kept and the error returned.
    fn load_preset(&mut self, name_or_path: &str) -> Result<(), String> {
        let setup: ImpactSetup =
            preset::load_for(name_or_path, "impact").map_err(|e| e.to_string())?;
        let core = self.core_mut();
        core.setup = setup;
        core.fields.clear();
        core.playback.t = 0.0;
        self.request();
        Ok(())
    }
}

/// The lesson context of `runs`, all solved from the first's setup.
pub(super) fn context_of(runs: &[(ModelKind, &Solved)]) -> Option<Context> {
    let (_, first) = runs.first()?;
    let results: Vec<_> = runs.iter().map(|(m, s)| (*m, &s.result)).collect();
    Some(Context::impact(&first.setup, &results))
}

/// The height of one of the stacked plots: its share of a lecture's panel, or half of what is
/// left below it in the window.
pub(super) fn plot_height(ui: &egui::Ui) -> f32 {
    if super::lecture::on(ui.ctx()) {
        super::fill::height(ui, 200.0, 80.0)
    } else {
        ((ui.available_height() - 160.0) / 2.0).clamp(120.0, 260.0)
    }
}

/// A run's x-t diagram title: its waves, or for a lumped model its uniform stress.
pub(super) fn xt_title(model: ModelKind, s: &Solved) -> String {
    if s.result.waves.is_some() {
        format!("{}: space-time", model.name())
    } else {
        format!("{}: uniform stress F/A", model.name())
    }
}

/// A run's x-t diagram over `span_s` from the start.
pub(super) fn xt_diagram<'a>(s: &'a Solved, span_s: f64, title: &'a str) -> XtDiagram<'a> {
    XtDiagram {
        source: XtSource::Impact {
            sc: &s.setup.scenario,
            result: &s.result,
        },
        gpu: &s.gpu,
        t_start: 0.0,
        t_span: span_s,
        title,
        zones_m: s.zones_m(),
    }
}

/// A result's signal against time in ms, decimated for the screen.
pub(super) fn series(r: &ImpactResult, f: &dyn Fn(usize) -> f64) -> Vec<[f64; 2]> {
    let t: Vec<f64> = r.time_s.iter().map(|t| t * 1e3).collect();
    let y: Vec<f64> = (0..r.time_s.len()).map(f).collect();
    super::series::decimate(&t, &y, 1.0)
}

/// A run's contact force in kN against time in ms.
pub(super) fn force_line(model: ModelKind, r: &ImpactResult) -> (String, Vec<[f64; 2]>) {
    (
        model.name().to_string(),
        series(r, &|j| r.force_n[j] * 1e-3),
    )
}
