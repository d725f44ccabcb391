//! The Parameter study scene: one impact setting swept over a range on top of the Bar impact
//! scene's settings, with peak force, contact duration and e against it for each chosen model;
//! or one building setting on top of the Building pounding scene's (`building_study`).
//! The sweep runs on a thread of its own (its solves on every core), shows its progress and can be
//! cancelled; the window keeps drawing throughout.

use super::background::Background;
use super::export::{Exporter, ShownPlot};
use super::paper_figures::PaperFigures;
use super::playback::Playback;
use super::plot_view;
use super::sweep_panel::{self, fielded};
use crate::export::plot::{LinePlot, Series};
use crate::io::settings::ImpactSetup;
use crate::model::impact::ModelKind;
use crate::model::settings::{IMPACT_SETTINGS, axis_label};
use crate::study::Cancelled;
use crate::study::sweep::{self, Point};
use eframe::egui;
use std::time::Duration;

/// The sweep's plots by export name.
const PLOT_NAMES: [&str; 3] = ["peak-force", "duration", "restitution"];

/// Models offered, and the ones ticked at start.
const MODELS: [ModelKind; 7] = ModelKind::ALL;
const TICKED: [ModelKind; 3] = [ModelKind::Sears, ModelKind::Wave, ModelKind::LumpedHertz];

/// A validated sweep: the setups, their values and the models.
type Job = (Vec<ImpactSetup>, Vec<f64>, Vec<ModelKind>);

/// A plotted quantity: title, axis label, and how to read it from a point.
type Quantity = (&'static str, &'static str, fn(&Point) -> Option<f64>);

struct Running {
    job: Background<Result<Vec<Point>, Cancelled>>,
    param: String,
    log: bool,
}

/// The last finished sweep.
struct Finished {
    param: String,
    log: bool,
    points: Vec<Point>,
}

/// What the scene shows: a sweep of one setting, or one of the paper's figures.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Mode {
    Sweep,
    Buildings,
    Paper,
}

pub struct StudyScene {
    pub playback: Playback,
    mode: Mode,
    paper: PaperFigures,
    /// The settings every point starts from (the Bar impact scene's, kept current by the app).
    pub base: ImpactSetup,
    param: String,
    from: String,
    to: String,
    count: usize,
    log: bool,
    models: [bool; 7],
    running: Option<Running>,
    finished: Option<Finished>,
    status: Option<(String, bool)>,
    /// The last study's wall time: it is also the time from Run to its result.
    pub solve_time: Duration,
    shown: [ShownPlot; 3],
    /// The sweep of a building setting.
    pub buildings: super::building_study::BuildingStudy,
    ctx: egui::Context,
}

impl StudyScene {
    pub fn new(ctx: &egui::Context, base: ImpactSetup) -> Self {
        let param = crate::model::settings::impact::LENGTH
            .key_of(1)
            .into_owned();
        let mut s = StudyScene {
            playback: Playback {
                playing: false,
                ..Playback::default()
            },
            base,
            param: param.clone(),
            from: "0.5".into(),
            to: "10".into(),
            count: 50,
            log: false,
            models: MODELS.map(|m| TICKED.contains(&m)),
            mode: Mode::Sweep,
            paper: PaperFigures::new(ctx),
            running: None,
            finished: None,
            status: None,
            solve_time: Duration::ZERO,
            shown: Default::default(),
            buildings: super::building_study::BuildingStudy::new(ctx, Default::default()),
            ctx: ctx.clone(),
        };
        s.start();
        s
    }

    /// The study's inputs as `key=value` lines, as typed (what the window keeps between sessions).
    pub fn state(&self) -> String {
        let models: Vec<&str> = MODELS
            .iter()
            .zip(self.models)
            .filter(|(_, on)| *on)
            .map(|(m, _)| m.name())
            .collect();
        let b = &self.buildings;
        format!(
            "mode={}\npaper={}\nparam={}\nfrom={}\nto={}\ncount={}\nlog={}\nmodels={}\nbuilding_param={}\nbuilding_from={}\nbuilding_to={}\nbuilding_count={}\nbuilding_log={}\n",
            match self.mode {
                Mode::Paper => "paper",
                Mode::Buildings => "buildings",
                Mode::Sweep => "sweep",
            },
            self.paper.choice,
            self.param,
            self.from.trim(),
            self.to.trim(),
            self.count,
            self.log,
            models.join(","),
            b.param,
            b.from.trim(),
            b.to.trim(),
            b.count,
            b.log,
        )
    }

    /// Restores inputs saved by [`StudyScene::state`] and reruns; what cannot be read is named
    /// and left at its current value.
    pub fn restore(&mut self, text: &str) -> Result<(), String> {
        let mut bad = vec![];
        for line in text.lines().filter(|l| !l.trim().is_empty()) {
            let (k, v) = line.split_once('=').unwrap_or((line, ""));
            let ok = match k {
                "mode" => match v {
                    "paper" => {
                        self.mode = Mode::Paper;
                        true
                    }
                    "sweep" => {
                        self.mode = Mode::Sweep;
                        true
                    }
                    "buildings" => {
                        self.mode = Mode::Buildings;
                        true
                    }
                    _ => false,
                },
                "building_param"
                    if crate::study::building_sweep::numeric_keys()
                        .iter()
                        .any(|n| n == v) =>
                {
                    self.buildings.param = v.into();
                    true
                }
                "building_from" => {
                    self.buildings.from = v.into();
                    true
                }
                "building_to" => {
                    self.buildings.to = v.into();
                    true
                }
                "building_count" => v
                    .parse()
                    .ok()
                    .filter(|c| (2..=10_000).contains(c))
                    .map(|c| self.buildings.count = c)
                    .is_some(),
                "building_log" => v.parse().map(|b| self.buildings.log = b).is_ok(),
                "paper" => self.paper.choose(v),
                "param" if sweep::numeric_keys().iter().any(|n| n == v) => {
                    self.param = v.into();
                    true
                }
                "from" => {
                    self.from = v.into();
                    true
                }
                "to" => {
                    self.to = v.into();
                    true
                }
                "count" => v
                    .parse()
                    .ok()
                    .filter(|c| (2..=10_000).contains(c))
                    .map(|c| self.count = c)
                    .is_some(),
                "log" => v.parse().map(|b| self.log = b).is_ok(),
                "models" => {
                    let names: Vec<&str> = v.split(',').collect();
                    let known = names.iter().all(|n| ModelKind::from_name(n).is_some());
                    if known {
                        self.models = MODELS.map(|m| names.contains(&m.name()));
                    }
                    known
                }
                _ => false,
            };
            if !ok {
                bad.push(line.to_string());
            }
        }
        self.start();
        if self.mode == Mode::Paper {
            self.paper.start();
        }
        if bad.is_empty() {
            Ok(())
        } else {
            Err(format!(
                "the last session's parameter study: could not read {}",
                bad.join("; ")
            ))
        }
    }

    pub fn busy(&self) -> bool {
        self.running.is_some() || self.paper.busy() || self.buildings.busy()
    }

    /// Validates the inputs and starts the sweep on a thread; a refusal names the field.
    pub fn start(&mut self) {
        self.cancel();
        match self.prepare() {
            Ok((setups, values, models)) => {
                self.running = Some(Running {
                    job: Background::spawn(&self.ctx, move |p| {
                        sweep::run(&setups, &values, &models, p)
                    }),
                    param: self.param.clone(),
                    log: self.log,
                });
                self.status = None;
            }
            Err(e) => self.status = Some((e, true)),
        }
    }

    fn prepare(&self) -> Result<Job, String> {
        let (from, to) = sweep_panel::ends(&self.from, &self.to)?;
        sweep::check(&self.param, from, to, self.count, self.log).map_err(fielded)?;
        let models: Vec<ModelKind> = MODELS
            .iter()
            .zip(self.models)
            .filter(|(_, on)| *on)
            .map(|(m, _)| *m)
            .collect();
        if models.is_empty() {
            return Err("models: tick at least one".into());
        }
        let values = sweep::values(from, to, self.count, self.log);
        let setups = sweep::setups(&self.base, &self.param, &values).map_err(fielded)?;
        Ok((setups, values, models))
    }

    /// Takes a finished sweep or paper figure, if one arrived.
    pub fn poll(&mut self) {
        if let Some(t) = self.paper.poll() {
            self.solve_time = t;
        }
        if self.buildings.busy() {
            self.buildings.poll();
            if !self.buildings.busy() {
                self.solve_time = self.buildings.solve_time;
            }
        }
        let Some(r) = &self.running else { return };
        let Some((outcome, elapsed)) = r.job.try_take(&self.ctx) else {
            return;
        };
        let outcome = match outcome {
            Ok(outcome) => outcome,
            Err(panic) => {
                self.status = Some((super::worker::internal_error(&panic), true));
                self.running = None;
                return;
            }
        };
        match outcome {
            Ok(points) => {
                let failed = points.iter().filter(|p| p.error.is_some()).count();
                self.status = Some((
                    sweep_panel::finished_status(
                        points.len(),
                        failed,
                        elapsed,
                        "hover a plot's point",
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
            Err(Cancelled) => {
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
        self.buildings.cancel();
    }

    pub fn shown_plots(&self) -> Vec<(&str, &ShownPlot)> {
        if self.mode == Mode::Paper {
            return self.paper.shown_plots();
        }
        if self.mode == Mode::Buildings {
            return self.buildings.shown_plots();
        }
        if self.finished.is_none() {
            return vec![];
        }
        PLOT_NAMES.into_iter().zip(&self.shown).collect()
    }

    pub fn params_ui(&mut self, ui: &mut egui::Ui) {
        ui.heading("Parameter study");
        ui.horizontal(|ui| {
            let before = self.mode;
            ui.selectable_value(&mut self.mode, Mode::Sweep, "Sweep a setting");
            ui.selectable_value(&mut self.mode, Mode::Buildings, "Sweep a building setting");
            ui.selectable_value(&mut self.mode, Mode::Paper, "The paper's figures");
            if self.mode != before && !self.paper.busy() && self.paper.shown_plots().is_empty() {
                self.paper.start();
            }
            if self.mode != before
                && self.mode == Mode::Buildings
                && !self.buildings.busy()
                && self.buildings.shown_plots().is_empty()
            {
                self.buildings.start();
            }
        });
        if self.mode == Mode::Paper {
            self.paper.params_ui(ui);
            return;
        }
        if self.mode == Mode::Buildings {
            self.buildings.params_ui(ui);
            return;
        }
        ui.label(
            "Sweeps one setting of the Bar impact scene (its preset and values are the base).",
        );
        ui.add_space(4.0);
        sweep_panel::param_ui(
            ui,
            "study-param",
            IMPACT_SETTINGS,
            sweep::numeric_keys(),
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
        ui.add_space(4.0);
        ui.label("models");
        for (m, on) in MODELS.iter().zip(self.models.iter_mut()) {
            ui.checkbox(on, m.name());
        }
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
        if self.mode == Mode::Paper {
            self.paper.main_ui(ui, exporter);
            return;
        }
        if self.mode == Mode::Buildings {
            self.buildings.main_ui(ui, exporter);
            return;
        }
        let Some(f) = &self.finished else {
            ui.label(if self.busy() {
                "solving..."
            } else {
                "press Run"
            });
            return;
        };
        let quantities: [Quantity; 3] = [
            ("Peak contact force", "peak force [kN]", |p| {
                p.peak_force_n.map(|f| f * 1e-3)
            }),
            ("Contact duration", "contact duration [ms]", |p| {
                p.contact_duration_s.map(|d| d * 1e3)
            }),
            ("Coefficient of restitution", "e", |p| p.restitution),
        ];
        let h = ((ui.available_height() - 120.0) / 3.0).clamp(140.0, 300.0);
        let models: Vec<&str> = MODELS
            .iter()
            .map(|m| m.name())
            .filter(|m| f.points.iter().any(|p| p.model == *m))
            .collect();
        for (k, (title, y_label, get)) in quantities.iter().enumerate() {
            let series = models
                .iter()
                .map(|m| Series {
                    name: m.to_string(),
                    points: f
                        .points
                        .iter()
                        .filter(|p| p.model == *m)
                        .filter_map(|p| get(p).map(|y| (p.value, y)))
                        .collect(),
                })
                .collect();
            let plot = LinePlot {
                log_x: f.log,
                markers: f.points.len() / models.len().max(1) <= 40,
                ..LinePlot::new(
                    format!("{title} against {}", f.param),
                    axis_label(IMPACT_SETTINGS, &f.param),
                    *y_label,
                    series,
                )
            };
            let link = Some(egui::Id::unique("study-plots"));
            self.shown[k] = plot_view::draw(ui, ("study", k), &plot, h, link);
            exporter.buttons(ui, &self.shown[k], PLOT_NAMES[k]);
        }
        let failed: Vec<(f64, String)> = f
            .points
            .iter()
            .filter(|p| p.error.is_some())
            .map(|p| {
                (
                    p.value,
                    format!("{}: {}", p.model, p.error.as_deref().unwrap_or_default()),
                )
            })
            .collect();
        sweep_panel::failed_ui(ui, &f.param, &failed);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Instant;

    fn wait(s: &mut StudyScene) {
        let start = Instant::now();
        while s.busy() {
            s.poll();
            assert!(
                start.elapsed() < Duration::from_secs(60),
                "the study never ended"
            );
            std::thread::sleep(Duration::from_millis(5));
        }
    }

    #[test]
    fn a_sweep_lands_with_every_point_then_a_long_one_can_be_cancelled() {
        let mut s = StudyScene::new(&egui::Context::default(), ImpactSetup::default());
        wait(&mut s);
        assert_eq!(s.finished.as_ref().map(|f| f.points.len()), Some(150));
        // A sweep far too long to finish first: FE with fine meshes.
        s.models = MODELS.map(|m| m == ModelKind::Fe);
        s.count = 10_000;
        s.start();
        assert!(s.busy());
        s.cancel();
        wait(&mut s);
        let (msg, is_error) = s.status.clone().unwrap();
        assert!(msg.starts_with("cancelled after") && !is_error, "{msg}");
        assert_eq!(s.finished.as_ref().map(|f| f.points.len()), Some(150));
    }

    #[test]
    fn the_inputs_come_back_as_typed_and_unreadable_lines_are_named() {
        let mut s = StudyScene::new(&egui::Context::default(), ImpactSetup::default());
        s.param = "bar1.velocity".into();
        (s.from, s.to, s.count, s.log) = ("0.01".into(), "1e2".into(), 7, true);
        s.models = MODELS.map(|m| m == ModelKind::Wave);
        let saved = s.state();
        let mut back = StudyScene::new(&egui::Context::default(), ImpactSetup::default());
        back.restore(&saved).unwrap();
        assert_eq!(back.state(), saved);
        wait(&mut back);
        assert_eq!(back.finished.as_ref().map(|f| f.points.len()), Some(7));
        let err = back
            .restore("count=0\nmodels=sears,nope\nlog=true")
            .unwrap_err();
        assert!(err.contains("count=0") && err.contains("nope"), "{err}");
        assert_eq!(back.count, 7);
    }

    #[test]
    fn a_paper_figure_runs_in_the_background_and_offers_its_plots_for_export() {
        let mut s = StudyScene::new(&egui::Context::default(), ImpactSetup::default());
        s.restore("mode=paper\npaper=fig5-models").unwrap();
        wait(&mut s);
        let names: Vec<&str> = s.shown_plots().iter().map(|(n, _)| *n).collect();
        assert_eq!(
            names,
            ["fig5-models-0.1m", "fig5-models-1m", "fig5-models-10m"]
        );
        assert!(s.paper.status().is_some_and(|m| m.starts_with("9 solves")));
        let err = s.restore("paper=fig12-displacements").unwrap_err();
        assert!(err.contains("fig12-displacements"), "{err}");
    }

    #[test]
    fn bad_inputs_are_refused_naming_the_field_and_kept_as_typed() {
        let mut s = StudyScene::new(&egui::Context::default(), ImpactSetup::default());
        wait(&mut s);
        s.from = "abc".into();
        s.start();
        assert!(!s.busy());
        let (msg, is_error) = s.status.clone().unwrap();
        assert!(is_error && msg.starts_with("from:"), "{msg}");
        assert_eq!(s.from, "abc");
        s.from = "-1".into();
        s.start();
        let (msg, _) = s.status.clone().unwrap();
        assert!(msg.contains("bar2.length") && msg.contains("-1"), "{msg}");
        s.from = "0.5".into();
        s.models = [false; 7];
        s.start();
        assert!(s.status.clone().unwrap().0.starts_with("models:"));
    }

    #[test]
    fn the_plots_name_the_swept_setting_by_label_and_unit_and_restitution_reads_linearly() {
        let ctx = egui::Context::default();
        let mut s = StudyScene::new(&ctx, ImpactSetup::default());
        wait(&mut s);
        let exporter = Exporter::default();
        let mut out = ctx.run_ui(egui::RawInput::default(), |ui| s.main_ui(ui, &exporter));
        out.textures_delta.clear();
        for shown in &s.shown {
            assert_eq!(shown.x_label, "bar 2 length [m]");
        }
        // e spans less than a decade: a linear axis, its values as they are.
        assert_eq!(s.shown[2].y_label, "e");
    }
}
