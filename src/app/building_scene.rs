//! The Building pounding scene: two buildings of any number of storeys swaying under a ground
//! motion and pounding across the gap at every level they share; displacements with and
//! without pounding, the pounding force (all levels or one), the impact list with a zoom on any
//! impact, and the gap that avoids pounding against the code rules. The state and the solves
//! live here; the panel in `building_params`, the drawing in `building_view`.

use super::building_job::{Baseline, Output, run_job};
use super::building_view;
use super::export::{Exporter, ShownPlot};
use super::legend::Key;
use super::params::Fields;
use super::playback::Playback;
use super::series::decimate;
use super::visibility::Visibility;
use super::worker::SolveSlot;
use super::xt_view::{XtDiagram, XtOptions, XtSource};
use crate::io::building_settings::BuildingSetup;
use crate::model::motion::G;
use eframe::egui::{self, Color32};
use egui_plot::{Plot, PlotBounds, VLine};

#[path = "building_stages.rs"]
mod stages;
use stages::{Later, Shown, StageTimes};

pub struct BuildingScene {
    pub setup: BuildingSetup,
    fields: Fields,
    pub(super) slot: SolveSlot<BuildingSetup, Output>,
    shown: Shown,
    times: StageTimes,
    pub playback: Playback,
    exaggeration: f64,
    zoom: Option<(f64, f64)>,
    /// The level the force plot and the impact list show (`None`: all).
    level: Option<usize>,
    motion_path: String,
    /// The view's rectangle last frame (for a screenshot of the view alone).
    pub view_rect: Option<egui::Rect>,
    shown_displacements: ShownPlot,
    shown_force: ShownPlot,
    shown_loops: ShownPlot,
    /// The impact whose slabs the x-t diagram shows (`None`: the strongest).
    selected: Option<usize>,
    /// The page of the impact list lecture mode shows.
    impact_page: usize,
    /// What the x-t diagram shows.
    xt: XtOptions,
    /// The panels drawn (a lesson step's, or all).
    pub visibility: Visibility,
}

impl BuildingScene {
    pub fn new(ctx: &egui::Context, setup: BuildingSetup) -> Self {
        let waker = ctx.clone();
        let mut s = BuildingScene {
            visibility: Visibility::default(),
            setup,
            fields: Fields::default(),
            slot: SolveSlot::staged(run_job, move || waker.request_repaint()),
            shown: Shown::default(),
            times: StageTimes::default(),
            playback: Playback {
                t: 0.0,
                playing: true,
                speed: 1.0,
                t_max: 8.0,
                ready_s: None,
            },
            exaggeration: 20.0,
            zoom: None,
            level: None,
            selected: None,
            impact_page: 0,
            xt: XtOptions::default(),
            motion_path: String::new(),
            view_rect: None,
            shown_displacements: ShownPlot::default(),
            shown_force: ShownPlot::default(),
            shown_loops: ShownPlot::default(),
        };
        s.request();
        s
    }

    pub fn request(&mut self) {
        self.slot.request(self.setup.clone());
        self.times = StageTimes::default();
        self.shown.superseded();
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

    /// A dropped file becomes the ground motion.
    pub fn take_dropped(&mut self, ctx: &egui::Context) {
        if let Some(path) = dropped_path(ctx) {
            self.load_motion(path);
        }
    }

    /// Which settings a lesson step leaves open.
    pub fn set_lock(&mut self, lock: Option<super::visibility::Lock>) {
        self.fields.lock = lock;
    }

    pub fn params_ui(&mut self, ui: &mut egui::Ui) {
        let before = self.setup.clone();
        super::building_params::ui(ui, &mut self.fields, &mut self.setup, &mut self.motion_path);
        if self.setup != before {
            self.request();
        }
    }

    /// Forgets typed text (after a preset replaces the values).
    pub fn reset_fields(&mut self) {
        self.fields.clear();
        self.level = None;
    }

    /// Loads a ground-motion file (a path typed, dropped or chosen in a dialog).
    pub fn load_motion(&mut self, path: String) {
        self.motion_path = path;
        self.setup.motion.file = Some(self.motion_path.trim().to_string());
        self.request();
    }

    /// The plots on screen last frame, by export name.
    pub fn shown_plots(&self) -> Vec<(&str, &ShownPlot)> {
        let mut plots = vec![];
        if self.shown.solved.is_some() {
            plots.push(("displacements", &self.shown_displacements));
            plots.push(("force", &self.shown_force));
            if !self.shown_loops.series.is_empty() {
                plots.push(("hysteresis", &self.shown_loops));
            }
        }
        plots
    }

    pub fn main_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter) {
        if let Some(e) = &self.slot.error {
            ui.colored_label(Color32::from_rgb(220, 60, 50), e);
        }
        let Some(s) = &self.shown.solved else {
            ui.label("solving...");
            return;
        };
        let stats = s.drawing.motion_stats;
        let d = &s.drawing;
        let show = self.visibility.clone();
        if super::lecture::on(ui.ctx()) {
            // A hall needs the record and how strong it is (in the view's caption where the
            // view shows); the rest is the researcher's.
            if !show.shows("buildings") {
                ui.label(lecture_record(d));
            }
        } else {
            ui.label(format!(
            "{}: {:.2} s at {} s, PGA {:.3} g, PGV {:.3} m/s, Arias {:.2} m/s, 5% spectrum peaks at {:.2} s",
            d.motion.name,
            stats.duration_s,
            d.motion.dt_s,
            stats.pga_m_s2 / G,
            stats.pgv_m_s,
            stats.arias_m_s,
            stats.predominant_period_s
        ));
        }
        if show.shows("buildings") {
            self.sway_ui(ui);
        }
        let Some(s) = &self.shown.solved else { return };
        if show.shows("readouts") {
            self.readouts_ui(ui);
        }
        if show.shows("gaps") {
            let d = &s.drawing;
            gap_ui(
                ui,
                &s.baseline,
                d.setup.scenario.gap_m,
                d.result.levels.len(),
            );
        }
        self.plots_ui(ui, exporter);
        if show.shows("xt") {
            self.slabs_xt_ui(ui);
        }
        for w in &self
            .shown
            .solved
            .as_ref()
            .expect("shown")
            .drawing
            .result
            .warnings
        {
            super::readouts::warning(ui, "warning", &w.to_string());
        }
    }

    /// The run's impacts, force and peaks beside those without pounding, and its error bound;
    /// a run still solving says how far it has got.
    fn readouts_ui(&self, ui: &mut egui::Ui) {
        let Some(s) = &self.shown.solved else { return };
        let r = &s.drawing.result;
        let without = |side: usize| {
            s.baseline.ready().map_or(s.baseline.absent().into(), |b| {
                format!("{:.2}", b.result.peak_displacement_m[side] * 1e3)
            })
        };
        let lecture = super::lecture::on(ui.ctx());
        let (so_far, solve) = if s.whole && lecture {
            // What a run costs and its error bound are the researcher's, not the class's.
            (String::new(), String::new())
        } else if s.whole {
            (
                String::new(),
                format!(
                    "; solve {}",
                    super::ms(self.slot.solve_time.as_secs_f64(), 1)
                ),
            )
        } else {
            (
                format!(
                    "solving: {:.1} s of {:.1} s; so far ",
                    r.solved_to_s, self.playback.t_max
                ),
                String::new(),
            )
        };
        ui.label(format!(
            "{so_far}{} impacts ({} contacts), max force {}, peak roof displacement left {:.2} mm (without pounding {}), right {:.2} mm ({}){solve}",
            r.impacts.len(),
            r.contacts.len(),
            crate::model::settings::engineering(r.max_pounding_force_n, "N"),
            r.peak_displacement_m[0] * 1e3,
            without(0),
            r.peak_displacement_m[1] * 1e3,
            without(1),
        ));
        if lecture {
            return;
        }
        match &s.estimate {
            Later::Ready(Some(e)) => {
                ui.label(format!(
                    "error bound (against a twice finer run): max force {:.1e}, peak displacement {:.1e}, impact times {:.1e} (relative), impact count {:+}",
                    e.max_force, e.peak_displacement, e.impact_time, e.impact_count_change
                )).on_hover_text("Twice the difference from the same run with every discretisation parameter halved: a bound on the error wherever the steps converge at order 1 or more");
            }
            // Where the finer run failed, the run stands without a bound, as it always has.
            Later::Ready(None) => {}
            later => {
                ui.label(format!(
                    "error bound (against a twice finer run): {}",
                    later.absent()
                ))
                .on_hover_text("The twice finer run follows the run and the run without pounding");
            }
        }
    }

    /// The two buildings swaying, with the drift's exaggeration and the playback controls.
    fn sway_ui(&mut self, ui: &mut egui::Ui) {
        let Some(s) = &self.shown.solved else { return };
        let d = &s.drawing;
        let tall = d
            .setup
            .scenario
            .left
            .storeys
            .max(d.setup.scenario.right.storeys);
        let lecture = super::lecture::on(ui.ctx());
        if lecture {
            let record = lecture_record(d);
            building_view::caption(ui, &record, d, self.playback.shown_t(), self.exaggeration);
        }
        let (rect, _) = ui.allocate_exact_size(
            egui::vec2(
                ui.available_width(),
                super::fill::height(ui, (200.0 + 25.0 * tall as f32).min(420.0), 90.0),
            ),
            egui::Sense::hover(),
        );
        building_view::draw(ui, rect, d, self.playback.shown_t(), self.exaggeration);
        self.view_rect = Some(rect);
        // On a projector the caption gives the scale; the slider would take a row.
        if lecture {
            self.playback.ui(ui);
            return;
        }
        ui.horizontal(|ui| {
            let label = ui
                .label("exaggeration")
                .on_hover_text("The buildings' drift is drawn this many times larger")
                .id;
            ui.add(egui::Slider::new(&mut self.exaggeration, 1.0..=500.0).logarithmic(true))
                .labelled_by(label);
        });
        self.playback.ui(ui);
    }

    /// The x-t diagram of the two slabs at the level of the selected impact (the strongest
    /// until one is picked), over that impact and a little either side.
    fn slabs_xt_ui(&mut self, ui: &mut egui::Ui) {
        let Some(s) = &self.shown.solved else { return };
        if !s.whole {
            ui.label("the slabs' space-time diagram: once the run is solved");
            return;
        }
        let r = &s.drawing.result;
        let strongest = (0..r.impacts.len()).max_by(|&a, &b| {
            r.impacts[a]
                .peak_force_n
                .total_cmp(&r.impacts[b].peak_force_n)
        });
        let Some(i) = self.selected.filter(|&i| i < r.impacts.len()).or(strongest) else {
            return;
        };
        let e = &r.impacts[i];
        let Some([Some(left), Some(right)]) = r.slab_waves().get(e.level) else {
            ui.label(format!(
                "impact {}: a floor meets a column at this level, so there is no pair of slabs to draw",
                i + 1
            ));
            return;
        };
        let Some(entries) = s.drawing.slab_entries(e.level) else {
            return;
        };
        // The slabs' histories on the GPU are the drawing's.
        let (waves, gpu) = ([left, right], s.drawing.gpu());
        // A slab round trip either side at least: the waves arriving and ringing on.
        let trip = waves[0].round_trip_s().max(waves[1].round_trip_s());
        let margin = (0.5 * e.duration_s()).max(trip);
        let (t_start, t_end) = ((e.start_s - margin).max(0.0), e.end_s + margin);
        self.xt.ui(ui);
        let title = format!(
            "slabs at level {} over impact {} ({:.4} s, {:.3e} N): space-time",
            e.level + 1,
            i + 1,
            e.start_s,
            e.peak_force_n
        );
        let clicked = XtDiagram {
            source: XtSource::Slabs {
                waves,
                approach_m_s: e.approach_velocity_m_s,
                entries,
            },
            gpu,
            t_start,
            t_span: t_end - t_start,
            title: &title,
            zones_m: None,
        }
        .show(
            ui,
            super::slots::BUILDING_XT,
            260.0,
            self.playback.shown_t(),
            &self.xt,
        );
        if let Some(t) = clicked {
            self.playback.t = t;
            self.playback.playing = false;
        }
    }

    /// Roof displacements with and without pounding.
    fn displacements_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter) {
        let Some(s) = &self.shown.solved else { return };
        let r = &s.drawing.result;
        let t = self.playback.shown_t();
        // Until the run without pounding lands its lines are named for why, and hold only the
        // point every run starts from (at rest): the plot lists no line without a point.
        let (base, note) = match s.baseline.ready() {
            Some(b) => (Some(&b.result), String::new()),
            None => (None, format!(" ({})", s.baseline.absent())),
        };
        let without = |side: usize| {
            base.map_or(vec![[0.0, 0.0]], |b| {
                decimate(&b.time_s, &b.displacement_m[side], 1e3)
            })
        };
        let disp_lines = vec![
            (
                "left".to_string(),
                decimate(&r.time_s, &r.displacement_m[0], 1e3),
            ),
            (
                "right".to_string(),
                decimate(&r.time_s, &r.displacement_m[1], 1e3),
            ),
            (format!("left, no pounding{note}"), without(0)),
            (format!("right, no pounding{note}"), without(1)),
        ];
        let width = super::lecture::line_width(ui);
        // Each building keeps its colour; its run without pounding is dashed.
        let keys: Vec<Key> = disp_lines
            .iter()
            .enumerate()
            .map(|(i, (name, _))| Key::line(name, super::legend::okabe_ito(i % 2), i >= 2))
            .collect();
        super::legend::row(ui, &keys);
        let h = super::fill::height(ui, 170.0, 80.0);
        let disp_plot = Plot::new("b-disp")
            .y_grid_spacer(super::plot_view::nice_marks)
            .height(h)
            .x_axis_label("time [s]")
            // A projector's short plot takes a short axis label.
            .y_axis_label(if super::lecture::on(ui.ctx()) {
                "roof [mm]"
            } else {
                "roof displacement [mm]"
            })
            .show(ui, |p| {
                for (key, (_, line)) in keys.iter().zip(&disp_lines) {
                    p.line(key.plot_line(line.clone(), width));
                }
                p.vline(VLine::new("t", t).color(egui::Color32::GRAY));
            });
        let b = disp_plot.transform.bounds();
        self.shown_displacements = ShownPlot {
            title: "Roof displacements with and without pounding".into(),
            x_label: "time [s]".into(),
            y_label: "roof displacement [mm]".into(),
            series: disp_lines,
            bounds: Some((b.min(), b.max())),
        };
        exporter.buttons(ui, &self.shown_displacements, "displacements");
    }

    /// The pounding force at every level or the one picked; the time of a click in it.
    fn force_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter, h: f32, t: f64) -> Option<f64> {
        let s = self.shown.solved.as_ref()?;
        let r = &s.drawing.result;
        let zoom = self.zoom.take();
        let (force, name) = match self.level {
            Some(l) => (&r.level_force_n[l], format!("level {}", l + 1)),
            None => (&r.force_n, "force".to_string()),
        };
        let force_pts = decimate(&r.time_s, force, 1e-6);
        let top = force.iter().cloned().fold(0.0, f64::max).max(1.0);
        let width = super::lecture::line_width(ui);
        let key = Key::line(&name, super::legend::okabe_ito(2), false);
        super::legend::row(ui, std::slice::from_ref(&key));
        let force_plot = Plot::new("b-force")
            .y_grid_spacer(super::plot_view::nice_marks)
            .height(h)
            .x_axis_label("time [s]")
            .y_axis_label(if super::lecture::on(ui.ctx()) {
                "force [MN]"
            } else {
                "pounding force [MN]"
            })
            .show(ui, |p| {
                p.line(key.plot_line(force_pts.clone(), width).allow_band(false));
                p.vline(VLine::new("t", t).color(egui::Color32::GRAY));
                if let Some((a, b)) = zoom {
                    p.set_plot_bounds(PlotBounds::from_min_max(
                        [a, -0.05 * top * 1e-6],
                        [b, 1.1 * top * 1e-6],
                    ));
                }
            });
        let b = force_plot.transform.bounds();
        self.shown_force = ShownPlot {
            title: format!(
                "Pounding force: {} contact{}",
                r.contact.name(),
                self.level
                    .map_or(String::new(), |l| format!(", level {}", l + 1))
            ),
            x_label: "time [s]".into(),
            y_label: "pounding force [MN]".into(),
            series: vec![(name, force_pts)],
            bounds: Some((b.min(), b.max())),
        };
        exporter.buttons(ui, &self.shown_force, "force");
        if force_plot.response.clicked() {
            let pos = force_plot.response.interact_pointer_pos()?;
            return Some(force_plot.transform.value_from_position(pos).x);
        }
        None
    }

    /// The level the force plot and the impact list show, where there is more than one.
    fn level_ui(&mut self, ui: &mut egui::Ui) {
        let Some(s) = &self.shown.solved else { return };
        let r = &s.drawing.result;
        if r.levels.len() > 1 {
            ui.horizontal(|ui| {
                let label = ui
                    .label("level")
                    .on_hover_text("The level the force plot and the impact list show")
                    .id;
                let shown = self.level.map_or("all levels".to_string(), |l| {
                    format!("{} ({:.2} m)", l + 1, r.levels[l].elevation_m)
                });
                egui::ComboBox::from_id_salt("b-level")
                    .selected_text(shown)
                    .show_ui(ui, |ui| {
                        ui.selectable_value(&mut self.level, None, "all levels");
                        for (i, l) in r.levels.iter().enumerate() {
                            ui.selectable_value(
                                &mut self.level,
                                Some(i),
                                format!("{} ({:.2} m, {})", i + 1, l.elevation_m, l.kind.name()),
                            );
                        }
                    })
                    .response
                    .labelled_by(label);
            });
        }
    }

    fn plots_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter) {
        let t = self.playback.shown_t();
        let show = self.visibility.clone();
        if show.shows("displacements") {
            self.displacements_ui(ui, exporter);
        }
        if show.shows("hysteresis")
            && let Some(s) = &self.shown.solved
        {
            super::hysteresis_view::show(ui, &s.drawing, t, &mut self.shown_loops);
            if !self.shown_loops.series.is_empty() {
                exporter.buttons(ui, &self.shown_loops, "hysteresis");
            }
        }
        if !show.shows("force") && !show.shows("impacts") {
            return;
        }
        self.level_ui(ui);
        let at = if show.shows("force") {
            self.force_ui(ui, exporter, super::fill::height(ui, 170.0, 80.0), t)
        } else {
            None
        };
        let Some(s) = &self.shown.solved else { return };
        let r = &s.drawing.result;
        let shown: Vec<usize> = (0..r.impacts.len())
            .filter(|&i| self.level.is_none_or(|l| r.impacts[i].level == l))
            .collect();
        // A click in the force plot picks the impact nearest in time.
        let mut clicked = at.and_then(|at| {
            shown.iter().copied().min_by(|&a, &b| {
                (r.impacts[a].start_s - at)
                    .abs()
                    .total_cmp(&(r.impacts[b].start_s - at).abs())
            })
        });
        if show.shows("impacts") {
            let picked = super::impact_list::ui(
                ui,
                &r.impacts,
                &shown,
                super::impact_list::Place::Level,
                &mut self.impact_page,
            );
            clicked = clicked.or(picked);
        }
        if let Some(i) = clicked {
            self.selected = Some(i);
            let e = &r.impacts[i];
            let margin = 0.5 * e.duration_s().max(0.002);
            self.zoom = Some((e.start_s - margin, e.end_s + margin));
            self.playback.t = e.start_s;
            self.playback.playing = false;
            self.playback.speed = 1e-3;
        }
    }
}

/// The record and its peak acceleration, as a lecture shows them.
fn lecture_record(d: &building_view::BuildingDrawing) -> String {
    let record = d.motion.short_name();
    format!("{record}, PGA {:.2} g", d.motion_stats.pga_m_s2 / G)
}

/// The first file dropped on the window this frame, if any.
pub(super) fn dropped_path(ctx: &egui::Context) -> Option<String> {
    ctx.input(|i| {
        i.raw
            .dropped_files
            .iter()
            .map(|f| f.path().to_path_buf())
            .find(|p| !p.as_os_str().is_empty())
            .map(|p| p.display().to_string())
    })
}

/// The gap that avoids pounding for this record, against the code rules.
fn gap_ui(ui: &mut egui::Ui, baseline: &Later<Box<Baseline>>, gap_m: f64, levels: usize) {
    ui.horizontal_wrapped(|ui| {
        ui.strong("gap that avoids pounding:")
            .on_hover_text("From the run without contact: the largest closing motion at any level over the record. ABS and SRSS combine the two buildings' peak displacements at each level, as design codes do");
        let Some(g) = baseline.ready().map(|b| &b.gaps) else {
            ui.label(baseline.absent());
            return;
        };
        if g.min_gap_m > 0.0 {
            ui.label(format!(
                "{:.2} mm{} (now {:.2} mm: {}); ABS {:.2} mm ({:.2}x), SRSS {:.2} mm ({:.2}x)",
                g.min_gap_m * 1e3,
                match (g.level, levels > 1) {
                    (Some(l), true) => format!(" at level {}", l + 1),
                    _ => String::new(),
                },
                gap_m * 1e3,
                if gap_m >= g.min_gap_m {
                    "no pounding"
                } else {
                    "they pound"
                },
                g.abs_m * 1e3,
                g.abs_ratio,
                g.srss_m * 1e3,
                g.srss_ratio
            ));
        } else {
            ui.label("the buildings never close on each other in this record");
        }
    });
}

impl BuildingScene {
    /// The shown run for File > Export animation, copied only when called.
    pub(super) fn animation_source(
        &self,
    ) -> Option<Box<dyn FnOnce() -> super::export_animation::AnimationSource + '_>> {
        // A run still solving would animate beyond what it has solved.
        let d = &self.shown.solved.as_ref().filter(|s| s.whole)?.drawing;
        Some(Box::new(move || {
            super::export_animation::AnimationSource::Buildings {
                setup: Box::new(d.setup.clone()),
                motion: d.motion.clone(),
                result: Box::new(d.result.clone()),
            }
        }))
    }
}

#[cfg(test)]
#[path = "building_scene_tests.rs"]
mod tests;
