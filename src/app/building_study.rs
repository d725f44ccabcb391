//! The Parameter study's building sweep: one setting of the Building pounding scene varied over a
//! range (that scene's settings and record the base), with the pounding, the sway and, where
//! storeys yield, their ductility demands and dissipated energy against it. It runs on a thread
//! of its own, shows its progress and can be cancelled.

use super::background::Background;
use super::export::{Exporter, ShownPlot};
use super::params::format_value;
use super::plot_view;
use crate::export::plot::{LinePlot, Series};
use crate::io::building_settings::BuildingSetup;
use crate::model::settings::{BUILDING_SETTINGS, Kind, axis_label, find};
use crate::study::Cancelled;
use crate::study::building_sweep::{self, BuildingPoint};
use crate::study::sweep::{self, SweepError};
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

/// The range a sweep of `key` starts from when it is picked: its slider's span.
fn default_range(key: &str) -> (f64, f64, bool) {
    match find(BUILDING_SETTINGS, key).map(|s| s.kind) {
        Some(Kind::Number { slider, log, .. } | Kind::List { slider, log, .. }) => {
            (slider.0, slider.1, log)
        }
        Some(Kind::Count { min, max }) => {
            let (lo, hi) = (min.max(1) as f64, max.min(1_000_000) as f64);
            (lo, hi, hi / lo > 100.0)
        }
        _ => (0.5, 2.0, false),
    }
}

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
        let (a, b, log) = default_range(&param);
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
        let number = |name: &str, text: &str| {
            text.trim()
                .parse::<f64>()
                .map_err(|_| format!("{name}: '{}' is not a number", text.trim()))
        };
        let (from, to) = (number("from", &self.from)?, number("to", &self.to)?);
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
                    format!(
                        "{} solves in {} on {} threads{}",
                        points.len(),
                        super::ms(elapsed.as_secs_f64(), 1),
                        rayon::current_num_threads(),
                        if failed > 0 {
                            format!("; {failed} points without a result (listed below)")
                        } else {
                            String::new()
                        }
                    ),
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
        let label = ui.label("swept setting").id;
        let before = self.param.clone();
        egui::ComboBox::from_id_salt("building-study-param")
            .selected_text(&self.param)
            .height(400.0)
            .show_ui(ui, |ui| {
                for k in building_sweep::numeric_keys() {
                    ui.selectable_value(&mut self.param, k.clone(), k);
                }
            })
            .response
            .labelled_by(label);
        if self.param != before {
            let (a, b, log) = default_range(&self.param);
            (self.from, self.to, self.log) = (format_value(a), format_value(b), log);
        }
        for (name, text) in [("from", &mut self.from), ("to", &mut self.to)] {
            ui.horizontal(|ui| {
                let label = ui.label(name).id;
                ui.add(egui::TextEdit::singleline(text).desired_width(120.0))
                    .labelled_by(label)
                    .on_hover_text("typed values are checked when the study runs");
            });
        }
        ui.horizontal(|ui| {
            let label = ui.label("points").id;
            ui.add(egui::DragValue::new(&mut self.count).range(2..=10_000))
                .labelled_by(label)
                .on_hover_text("values swept, ends included (2 to 10000)");
        });
        ui.checkbox(&mut self.log, "geometric spacing")
            .on_hover_text("equal ratios between values (from and to > 0)");
        ui.add_space(6.0);
        ui.horizontal(|ui| {
            if ui
                .button("Run")
                .on_hover_text("solve every point on every core")
                .clicked()
            {
                self.start();
            }
            if ui
                .add_enabled(self.busy(), egui::Button::new("Cancel"))
                .on_hover_text("stop: finished points are dropped")
                .clicked()
            {
                self.cancel();
            }
        });
        if let Some(r) = &self.running {
            r.job.progress_ui(ui);
        }
        super::params::status_ui(ui, self.status.as_ref());
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
        let failed: Vec<&BuildingPoint> = f.points.iter().filter(|p| p.error.is_some()).collect();
        if !failed.is_empty() {
            ui.collapsing(format!("{} points without a result", failed.len()), |ui| {
                for p in failed.iter().take(50) {
                    ui.label(format!(
                        "{} = {}: {}",
                        f.param,
                        format_value(p.value),
                        p.error.as_deref().unwrap_or_default()
                    ));
                }
            });
        }
    }
}

/// A sweep's error, phrased with the panel's field at fault.
fn fielded(e: SweepError) -> String {
    let field = match e.part() {
        sweep::Part::Param => "swept setting: ",
        sweep::Part::Count => "points: ",
        sweep::Part::Range => "from/to: ",
        sweep::Part::Spacing => "geometric spacing: ",
        sweep::Part::Value => "",
    };
    format!("{field}{e}")
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
