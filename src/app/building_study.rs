//! The Parameter study's building sweep: one setting of the Building pounding scene varied over a
//! range (that scene's settings and record the base), with the pounding, the sway and, where
//! storeys yield, their ductility demands and dissipated energy against it. It runs on a thread
//! of its own, shows its progress and can be cancelled.

use super::background::Background;
use super::export::{Exporter, ShownPlot};
use super::params::format_value;
use super::plot_view;
use super::sweep_panel::{self, default_range, fielded};
use crate::export::plot::{LinePlot, Series};
use crate::io::building_settings::BuildingSetup;
use crate::model::settings::{BUILDING_SETTINGS, axis_label};
use crate::study::Cancelled;
use crate::study::building_sweep::{self, BuildingPoint};
use crate::study::sweep;
use eframe::egui;
use std::time::Duration;

/// The plots by export name.
pub const PLOT_NAMES: [&str; 3] = ["building-force", "building-sway", "building-ductility"];

/// A plotted quantity: its name and how to read it from a point.
type Line = (&'static str, fn(&BuildingPoint) -> Option<f64>);

/// What each plot shows: title, axis label, lines.
const PLOTS: [(&str, &str, &[Line]); 3] = [
    (
        "Max pounding force",
        "max pounding force [kN]",
        &[("max force", |p| p.max_pounding_force_n.map(|f| f * 1e-3))],
    ),
    (
        "Peak roof displacements",
        "peak roof displacement [mm]",
        &[
            ("left", |p| p.peak_displacement_left_m.map(|u| u * 1e3)),
            ("right", |p| p.peak_displacement_right_m.map(|u| u * 1e3)),
        ],
    ),
    (
        "Largest storey ductility demand",
        "peak drift / yield drift",
        &[
            ("left", |p| p.max_ductility_left),
            ("right", |p| p.max_ductility_right),
        ],
    ),
];

struct Running {
    job: Background<Result<Vec<BuildingPoint>, Cancelled>>,
    param: String,
    log: bool,
}

struct Finished {
    param: String,
    log: bool,
    points: Vec<BuildingPoint>,
}

pub struct BuildingStudy {
    /// The settings every point starts from (the Building pounding scene's, kept current).
    pub base: BuildingSetup,
    pub param: String,
    pub from: String,
    pub to: String,
    pub count: usize,
    pub log: bool,
    running: Option<Running>,
    finished: Option<Finished>,
    pub status: Option<(String, bool)>,
    pub solve_time: Duration,
    shown: [ShownPlot; 3],
    ctx: egui::Context,
}

impl BuildingStudy {
    pub fn new(ctx: &egui::Context, base: BuildingSetup) -> Self {
        let param = crate::model::settings::building::YIELD_FORCES
            .key_of(0)
            .into_owned();
        let (a, b, log) = default_range(BUILDING_SETTINGS, &param);
        BuildingStudy {
            base,
            param,
            from: format_value(a),
            to: format_value(b),
            count: 12,
            log,
            running: None,
            finished: None,
            status: None,
            solve_time: Duration::ZERO,
            shown: Default::default(),
            ctx: ctx.clone(),
        }
    }

    pub fn busy(&self) -> bool {
        self.running.is_some()
    }

    /// Validates the inputs and starts the sweep on a thread; a refusal names the field.
    pub fn start(&mut self) {
        self.cancel();
        match self.prepare() {
            Ok((setups, values)) => {
                self.running = Some(Running {
                    job: Background::spawn(&self.ctx, move |p| {
                        building_sweep::run(&setups, &values, p)
                    }),
                    param: self.param.clone(),
                    log: self.log,
                });
                self.status = None;
            }
            Err(e) => self.status = Some((e, true)),
        }
    }

    fn prepare(&self) -> Result<(Vec<BuildingSetup>, Vec<f64>), String> {
        let (from, to) = sweep_panel::ends(&self.from, &self.to)?;
        building_sweep::check(&self.param, from, to, self.count, self.log).map_err(fielded)?;
        let values = sweep::values(from, to, self.count, self.log);
        let setups = building_sweep::setups(&self.base, &self.param, &values).map_err(fielded)?;
        Ok((setups, values))
    }

    /// Takes a finished sweep, if one arrived.
    pub fn poll(&mut self) {
        let Some(r) = &self.running else { return };
        let Some((outcome, elapsed)) = r.job.try_take(&self.ctx) else {
            return;
        };
        match outcome {
            Err(panic) => self.status = Some((super::worker::internal_error(&panic), true)),
            Ok(Ok(points)) => {
                let failed = points.iter().filter(|p| p.error.is_some()).count();
                self.status = Some((
                    sweep_panel::finished_status(points.len(), failed, elapsed, "listed below"),
                    false,
                ));
                self.finished = Some(Finished {
                    param: r.param.clone(),
                    log: r.log,
                    points,
                });
                self.solve_time = elapsed;
            }
            Ok(Err(Cancelled)) => {
                let (done, total) = r.job.counts();
                self.status = Some((format!("cancelled after {done} of {total} solves"), false));
            }
        }
        self.running = None;
    }

    pub fn cancel(&mut self) {
        if let Some(r) = &self.running {
            r.job.cancel();
        }
    }

    pub fn shown_plots(&self) -> Vec<(&str, &ShownPlot)> {
        if self.finished.is_none() {
            return vec![];
        }
        PLOT_NAMES.into_iter().zip(&self.shown).collect()
    }

    /// The swept setting, its range and Run; `running` draws the progress.
    pub fn params_ui(&mut self, ui: &mut egui::Ui) {
        ui.label("Sweeps one setting of the Building pounding scene (its settings and record are the base), with its contact element.");
        ui.add_space(4.0);
        sweep_panel::param_ui(
            ui,
            "building-study-param",
            BUILDING_SETTINGS,
            building_sweep::numeric_keys(),
            &mut self.param,
            &mut self.from,
            &mut self.to,
            &mut self.log,
        );
        sweep_panel::range_ui(
            ui,
            &mut self.from,
            &mut self.to,
            &mut self.count,
            &mut self.log,
        );
        let job = self.running.as_ref().map(|r| &r.job);
        let pressed = sweep_panel::run_ui(ui, self.busy(), job, self.status.as_ref());
        if pressed.run {
            self.start();
        }
        if pressed.cancel {
            self.cancel();
        }
    }

    pub fn main_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter) {
        let Some(f) = &self.finished else {
            ui.label(if self.busy() {
                "solving..."
            } else {
                "press Run"
            });
            return;
        };
        let h = ((ui.available_height() - 120.0) / 3.0).clamp(140.0, 300.0);
        for (k, (title, y_label, lines)) in PLOTS.iter().enumerate() {
            let series = lines
                .iter()
                .map(|(name, get)| Series {
                    name: name.to_string(),
                    points: f
                        .points
                        .iter()
                        .filter_map(|p| get(p).map(|y| (p.value, y)))
                        .collect(),
                })
                .collect();
            let plot = LinePlot {
                log_x: f.log,
                markers: f.points.len() <= 40,
                ..LinePlot::new(
                    format!("{title} against {}", f.param),
                    axis_label(BUILDING_SETTINGS, &f.param),
                    *y_label,
                    series,
                )
            };
            let link = Some(egui::Id::unique("building-study-plots"));
            self.shown[k] = plot_view::draw(ui, ("building-study", k), &plot, h, link);
            exporter.buttons(ui, &self.shown[k], PLOT_NAMES[k]);
        }
        let failed: Vec<(f64, String)> = f
            .points
            .iter()
            .filter(|p| p.error.is_some())
            .map(|p| (p.value, p.error.as_deref().unwrap_or_default().to_string()))
            .collect();
        sweep_panel::failed_ui(ui, &f.param, &failed);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Instant;

    #[test]
    fn a_building_sweep_of_the_yield_force_lands_with_every_point_and_weaker_storeys_yield_more() {
        let ctx = egui::Context::default();
        let mut base: BuildingSetup =
            crate::io::preset::load_for("paper-buildings-yielding", "buildings").unwrap();
        base.apply_assignment("contact.model=linear").unwrap();
        base.apply_assignment("motion.duration=4").unwrap();
        base.apply_assignment("motion.settle_s=0").unwrap();
        let mut s = BuildingStudy::new(&ctx, base);
        (s.from, s.to, s.count, s.log) = ("1e5".into(), "4e5".into(), 3, true);
        s.start();
        let start = Instant::now();
        while s.busy() {
            s.poll();
            assert!(start.elapsed() < Duration::from_secs(120), "never ended");
            std::thread::sleep(Duration::from_millis(5));
        }
        let f = s.finished.as_ref().expect("a finished sweep");
        assert_eq!(f.points.len(), 3);
        assert!(f.points.iter().all(|p| p.error.is_none()));
        let mu: Vec<f64> = f
            .points
            .iter()
            .map(|p| p.max_ductility_left.unwrap())
            .collect();
        // The weaker the storey, the further past its yield drift it is driven.
        assert!(mu[0] > mu[1] && mu[1] > mu[2], "{mu:?}");
        assert!(mu[0] > 1.0);
        // A refused range names its field.
        s.from = "abc".into();
        s.start();
        assert!(
            s.status
                .as_ref()
                .is_some_and(|(m, e)| *e && m.starts_with("from"))
        );
    }
}
