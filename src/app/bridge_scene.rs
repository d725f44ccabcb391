//! The Bridge pounding scene: girders on piers pounding at their joints under a ground motion
//! that may travel along the bridge; the bridge in elevation, the joints' forces, their openings
//! against the seat, the girders' displacements with and without pounding, the impact list, the
//! whole deck's space-time diagram around a picked impact, and per joint its gap, the gap it
//! needs and its seat margin. The state and the solves live here; the panel in
//! `bridge_params`, the drawing in `bridge_view` and `bridge_xt`.

use super::bridge_job::{Output, Stage, run_job};
use super::bridge_view::{self, BridgeDrawing};
use super::bridge_xt::DeckXt;
use super::export::{Exporter, ShownPlot};
use super::later::{Later, StageTimes, pending_note};
use super::legend::Key;
use super::params::Fields;
use super::playback::Playback;
use super::series::plot_lines;
use super::visibility::{Lock, Visibility};
use super::worker::{Landed, SolveSlot};
use crate::io::bridge_settings::BridgeSetup;
use crate::model::bridge::{BridgeErrorEstimate, BridgeResult};
use crate::model::motion::G;
use crate::render::bars::XtShown;
use eframe::egui::{self, Color32};
use egui_plot::{HLine, Plot, PlotBounds, VLine};

/// One request's run (whole, or as far as it has solved) and its later stages as they land.
type Shown =
    crate::app::later::Shown<BridgeDrawing, Box<BridgeResult>, Option<BridgeErrorEstimate>>;

pub struct BridgeScene {
    pub setup: BridgeSetup,
    fields: Fields,
    pub(super) slot: SolveSlot<BridgeSetup, Output>,
    shown: Shown,
    times: StageTimes,
    pub playback: Playback,
    exaggeration: f64,
    zoom: Option<(f64, f64)>,
    /// The joint the force plot and the impact list show (`None`: all).
    joint: Option<usize>,
    /// The impact the deck's diagram is drawn around (`None`: the strongest).
    selected: Option<usize>,
    /// The page of the impact list lecture mode shows.
    impact_page: usize,
    xt_field: XtShown,
    motion_path: String,
    /// The view's rectangle last frame (for a screenshot of the view alone).
    pub view_rect: Option<egui::Rect>,
    shown_forces: ShownPlot,
    shown_openings: ShownPlot,
    shown_girders: ShownPlot,
    /// The panels drawn (a lesson step's, or all).
    pub visibility: Visibility,
}

impl BridgeScene {
    pub fn new(ctx: &egui::Context, setup: BridgeSetup) -> Self {
        let waker = ctx.clone();
        let mut s = BridgeScene {
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
            joint: None,
            selected: None,
            impact_page: 0,
            xt_field: XtShown::Stress,
            motion_path: String::new(),
            view_rect: None,
            shown_forces: ShownPlot::default(),
            shown_openings: ShownPlot::default(),
            shown_girders: ShownPlot::default(),
            visibility: Visibility::default(),
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

    pub fn progress(&self) -> Option<f64> {
        self.slot.progress()
    }

    pub fn cancel(&mut self) {
        self.slot.cancel();
    }

    /// Which settings a lesson step leaves open.
    pub fn set_lock(&mut self, lock: Option<Lock>) {
        self.fields.lock = lock;
    }

    /// What a lesson's expressions read: the run and the run without contact, both whole and
    /// the newest request's; `None` until they are.
    pub fn lesson_context(&self) -> Option<crate::lesson::Context> {
        let s = self
            .shown
            .solved
            .as_ref()
            .filter(|s| s.whole && s.current)?;
        Some(crate::lesson::Context::bridge(
            &s.drawing.setup,
            &s.drawing.result,
            Some(s.baseline.ready()?),
        ))
    }

    /// Forgets typed text (after a preset replaces the values).
    pub fn reset_fields(&mut self) {
        self.fields.clear();
        self.joint = None;
    }

    /// Loads a ground-motion file (a path typed, dropped or chosen in a dialog).
    pub fn load_motion(&mut self, path: String) {
        self.motion_path = path;
        self.setup.motion.file = Some(self.motion_path.trim().to_string());
        self.request();
    }

    /// Takes the stages that landed, in order.
    pub fn poll(&mut self) {
        while let Some(landed) = self.slot.poll_stage() {
            self.land(landed);
        }
        if !self.busy() {
            self.ended();
        }
    }

    /// The newest request is done: a run it left unfinished gives way to the last whole one,
    /// and a stage it never delivered is not coming.
    fn ended(&mut self) {
        self.shown.ended();
        self.hold_playback();
    }

    /// Playback waits at the edge of a run still solving.
    fn hold_playback(&mut self) {
        self.playback.ready_s = self.shown.edge(|d| d.result.solved_to_s);
    }

    fn land(&mut self, landed: Landed<Output>) {
        match landed.output {
            Ok(Stage::Partial(drawing)) => self.show_run(drawing, false),
            Ok(Stage::Run(drawing)) => {
                self.slot.record_run(landed.job_time, landed.since_request);
                self.show_run(drawing, true);
            }
            Ok(Stage::Baseline(b)) => {
                self.times.baseline = Some(landed.since_request);
                if let Some(s) = self.shown.newest_whole() {
                    s.baseline = Later::Ready(b);
                }
            }
            Ok(Stage::Estimate(e)) => {
                self.times.estimate = Some(landed.since_request);
                if let Some(s) = self.shown.newest_whole() {
                    s.estimate = Later::Ready(e);
                }
            }
            Err(e) => self.slot.error = Some(e.to_string()),
        }
    }

    /// Shows the newest request's run, whole or so far; its later stages are on their way.
    fn show_run(&mut self, drawing: Box<BridgeDrawing>, whole: bool) {
        if !self.shown.current() {
            // A new run has its own impacts: the diagram goes back to the strongest.
            self.selected = None;
        }
        self.playback.t_max = drawing.result.duration_s;
        self.playback.t = self.playback.t.min(self.playback.t_max);
        if self.joint.is_some_and(|j| j >= drawing.result.joints.len()) {
            self.joint = None;
        }
        self.shown.show(drawing, whole);
        self.hold_playback();
    }

    /// What the status bar says while the newest request solves.
    pub fn solving_note(&self) -> String {
        match self.shown.solved.as_ref().filter(|s| s.current) {
            None => "solving...".into(),
            Some(s) if !s.whole => format!(
                "solving: {:.1} s of {:.1} s",
                s.drawing.result.solved_to_s, self.playback.t_max
            ),
            Some(s) => pending_note(&s.baseline, &s.estimate).into(),
        }
    }

    /// When the later stages of the newest request landed, from its change.
    pub fn later_stages(&self) -> String {
        self.times.describe(self.busy())
    }

    pub fn params_ui(&mut self, ui: &mut egui::Ui) {
        let before = self.setup.clone();
        super::bridge_params::ui(ui, &mut self.fields, &mut self.setup, &mut self.motion_path);
        if self.setup != before {
            self.request();
        }
    }

    /// The plots on screen last frame, by export name.
    pub fn shown_plots(&self) -> Vec<(&str, &ShownPlot)> {
        if self.shown.solved.is_none() {
            return vec![];
        }
        [
            ("force", "joint-forces", &self.shown_forces),
            ("openings", "joint-openings", &self.shown_openings),
            ("displacements", "girder-displacements", &self.shown_girders),
        ]
        .into_iter()
        .filter(|(panel, _, _)| self.visibility.shows(panel))
        .map(|(_, name, plot)| (name, plot))
        .collect()
    }

    pub fn main_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter) {
        if let Some(e) = &self.slot.error {
            ui.colored_label(Color32::from_rgb(220, 60, 50), e);
        }
        let Some(s) = &self.shown.solved else {
            ui.label("solving...");
            return;
        };
        let d = &s.drawing;
        let stats = d.motion_stats;
        let travel = d
            .setup
            .scenario
            .apparent_velocity_m_s
            .map_or("every support at once".to_string(), |v| {
                format!("travelling along the bridge at {v} m/s")
            });
        if super::lecture::on(ui.ctx()) {
            // A hall needs the record, how strong it is and whether it travels.
            let record = d.motion.short_name();
            let travel = d
                .setup
                .scenario
                .apparent_velocity_m_s
                .map_or("uniform".to_string(), |v| format!("travelling at {v} m/s"));
            ui.label(format!(
                "{record}, PGA {:.2} g, {travel}",
                stats.pga_m_s2 / G
            ));
        } else {
            ui.label(format!(
                "{}: {:.2} s at {} s, PGA {:.3} g, PGV {:.3} m/s; {travel}",
                d.motion.name,
                stats.duration_s,
                d.motion.dt_s,
                stats.pga_m_s2 / G,
                stats.pgv_m_s,
            ));
        }
        let show = self.visibility.clone();
        if show.shows("bridge") {
            self.elevation_ui(ui);
        }
        if show.shows("readouts") {
            self.readouts_ui(ui);
        }
        let seats = show.shows("joints") || show.shows("openings");
        if show.shows("joints") {
            self.joints_table_ui(ui);
        }
        self.plots_ui(ui, exporter);
        if show.shows("impacts") {
            self.impacts_ui(ui);
        }
        if show.shows("xt") {
            self.deck_xt_ui(ui);
        }
        let Some(s) = &self.shown.solved else { return };
        let r = &s.drawing.result;
        // The unseating warnings come first, one per unseated joint: they say what the seats'
        // panels show, and wait with them in a lesson step that asks about the seats.
        let shown = if seats { 0 } else { r.unseating.len() };
        for w in &r.warnings[shown.min(r.warnings.len())..] {
            super::readouts::warning(ui, "warning", &w.to_string());
        }
    }

    fn elevation_ui(&mut self, ui: &mut egui::Ui) {
        let Some(s) = &self.shown.solved else { return };
        let (rect, _) = ui.allocate_exact_size(
            egui::vec2(ui.available_width(), super::fill::height(ui, 260.0, 60.0)),
            egui::Sense::hover(),
        );
        bridge_view::draw(
            ui,
            rect,
            &s.drawing,
            self.playback.shown_t(),
            self.exaggeration,
        );
        self.view_rect = Some(rect);
        // On a projector the view's caption gives the scale; the slider would take a row.
        if super::lecture::on(ui.ctx()) {
            self.playback.ui(ui);
            return;
        }
        ui.horizontal(|ui| {
            let label = ui
                .label("exaggeration")
                .on_hover_text("Displacements, gaps and seats are drawn this many times larger")
                .id;
            ui.add(egui::Slider::new(&mut self.exaggeration, 1.0..=200.0).logarithmic(true))
                .labelled_by(label);
        });
        self.playback.ui(ui);
    }

    /// Impacts, the largest force, the girders' peaks beside those without pounding, the
    /// energy into the girders' waves, and the error bound.
    fn readouts_ui(&self, ui: &mut egui::Ui) {
        let Some(s) = &self.shown.solved else { return };
        let r = &s.drawing.result;
        if !s.whole {
            ui.label(format!(
                "solving: {:.1} s of {:.1} s; so far:",
                r.solved_to_s, r.duration_s
            ));
        }
        let mm = |v: &[f64]| {
            v.iter()
                .map(|x| format!("{:.1}", x * 1e3))
                .collect::<Vec<_>>()
                .join(" / ")
        };
        let without = s
            .baseline
            .ready()
            .map_or(s.baseline.absent().to_string(), |b| {
                mm(&b.peak_girder_displacement_m)
            });
        let run = format!(
            "{} impacts ({} contacts), max force {}; girder peaks {} mm (without pounding {}); {} into the girders' waves",
            r.impacts.len(),
            r.contacts.len(),
            crate::model::settings::engineering(r.max_pounding_force_n, "N"),
            mm(&r.peak_girder_displacement_m),
            without,
            crate::model::settings::engineering(r.energy.girder_waves_j, "J"),
        );
        // What the run cost and its error bound are the researcher's, not a class's.
        if super::lecture::on(ui.ctx()) {
            ui.label(run);
            return;
        }
        ui.label(format!(
            "{run}; solve {} ({} steps, {:.1}% in contact)",
            super::ms(self.slot.solve_time.as_secs_f64(), 1),
            r.stats.steps,
            100.0 * r.stats.contact_steps as f64 / r.stats.steps.max(1) as f64,
        ));
        match &s.estimate {
            Later::Ready(Some(e)) => {
                ui.label(format!(
                    "error bound (against a twice finer run): max force {:.1e}, peaks {:.1e}, openings {:.1e}, impact times {:.1e} (relative), impact count {:+}",
                    e.max_force, e.peak_displacement, e.opening, e.impact_time, e.impact_count_change
                ));
            }
            Later::Ready(None) => {}
            later => {
                ui.label(format!(
                    "error bound (against a twice finer run): {}",
                    later.absent()
                ));
            }
        }
    }

    /// Per joint: its kind and place, its gap and the gap it needs (from the run without
    /// contact), its largest force and opening, and its seat's margin. A projector's narrow
    /// panel keeps the force, the opening (coloured by the seat's margin) and whether the
    /// girder fell.
    fn joints_table_ui(&self, ui: &mut egui::Ui) {
        let Some(s) = &self.shown.solved else { return };
        let (r, sc) = (&s.drawing.result, &s.drawing.setup.scenario);
        let seat = sc.seat_length_m;
        let full = !super::lecture::on(ui.ctx());
        let headers: &[&str] = if full {
            &[
                "joint",
                "between",
                "at [m]",
                "gap [mm]",
                "gap needed [mm]",
                "max force [MN]",
                "max opening [mm]",
                "seat margin [mm]",
                "unseated",
            ]
        } else {
            &["joint", "force [MN]", "opening", "unseated"]
        };
        egui::Grid::new("bridge-joints")
            .striped(true)
            .num_columns(headers.len())
            .show(ui, |ui| {
                for h in headers {
                    ui.strong(*h);
                }
                ui.end_row();
                for (j, joint) in r.joints.iter().enumerate() {
                    ui.label(format!("{j}"));
                    if full {
                        ui.label(joint.kind());
                        ui.label(format!("{:.1}", joint.position_m + 0.0));
                    }
                    if full {
                        ui.label(format!("{:.1}", joint.gap_m * 1e3));
                        let needed = s.baseline.ready().map_or(s.baseline.absent().into(), |b| {
                            let g = b.max_closing_m[j].max(0.0);
                            let verdict = if g <= joint.gap_m { "" } else { " (pounds)" };
                            format!("{:.1}{verdict}", g * 1e3)
                        });
                        ui.label(needed);
                    }
                    ui.label(format!("{:.2}", r.max_force_by_joint_n[j] * 1e-6));
                    let opening = r.max_opening_m[j].max(0.0);
                    let margin = seat - opening;
                    let colour = bridge_view::seat_colour(1.0 - margin / seat, margin < 0.0);
                    if full {
                        ui.label(format!("{:.1}", opening * 1e3));
                        ui.colored_label(colour, format!("{:.1}", margin * 1e3));
                    } else {
                        ui.colored_label(colour, format!("{:.1} mm", opening * 1e3));
                    }
                    let when = r.unseating.iter().find(|u| u.joint == j);
                    ui.label(when.map_or("no".into(), |u| format!("at {:.2} s", u.time_s)));
                    ui.end_row();
                }
            });
    }

    fn plots_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter) {
        let Some(s) = &self.shown.solved else { return };
        let count = s.drawing.result.joints.len();
        let t = self.playback.shown_t();
        let show = self.visibility.clone();
        // The joints the force and opening plots and the impact list show: one, or all.
        let picks = ["force", "openings", "impacts"]
            .iter()
            .any(|p| show.shows(p));
        // A lecture shows every joint: the choice would take a row of the projector's screen.
        if picks && !super::lecture::on(ui.ctx()) {
            self.joint_choice_ui(ui);
        }
        let choice = self.joint.filter(|_| !super::lecture::on(ui.ctx()));
        let joints: Vec<usize> = (0..count)
            .filter(|&j| choice.is_none_or(|k| k == j))
            .collect();
        if show.shows("force") {
            self.force_plot_ui(ui, exporter, &joints, t);
        }
        if show.shows("openings") {
            self.openings_plot_ui(ui, exporter, &joints, t);
        }
        if show.shows("displacements") {
            self.girders_plot_ui(ui, exporter, t);
        }
    }

    /// Which joint the force and opening plots and the impact list show.
    fn joint_choice_ui(&mut self, ui: &mut egui::Ui) {
        let Some(s) = &self.shown.solved else { return };
        let r = &s.drawing.result;
        ui.horizontal(|ui| {
            let label = ui
                .label("joint")
                .on_hover_text("The joint the force plot and the impact list show")
                .id;
            let shown = self.joint.map_or("all joints".to_string(), |j| {
                format!("{j} ({})", r.joints[j].kind())
            });
            egui::ComboBox::from_id_salt("bridge-joint")
                .selected_text(shown)
                .show_ui(ui, |ui| {
                    ui.selectable_value(&mut self.joint, None, "all joints");
                    for (j, joint) in r.joints.iter().enumerate() {
                        ui.selectable_value(
                            &mut self.joint,
                            Some(j),
                            format!("{j} ({})", joint.kind()),
                        );
                    }
                })
                .response
                .labelled_by(label);
        });
    }

    fn force_plot_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter, joints: &[usize], t: f64) {
        let Some(s) = &self.shown.solved else { return };
        let r = &s.drawing.result;
        let width = super::lecture::line_width(ui);
        let named = |j: usize| format!("joint {j}");
        let zoom = self.zoom.take();
        // A zoom onto an impact is drawn at the samples it shows from its first frame.
        let shown = zoom.or(x_range(&self.shown_forces));
        let px = ui.available_width();
        let lines = joints
            .iter()
            .map(|&j| (named(j), &r.time_s[..], &r.joint_force_n[j][..]))
            .collect();
        let (forces, drawn) = plot_lines(lines, 1e-6, shown, px);
        let top = r.max_pounding_force_n.max(1.0) * 1e-6;
        let keys: Vec<Key> = joints
            .iter()
            .map(|&j| Key::line(named(j), super::legend::okabe_ito(j), false))
            .collect();
        super::legend::row(ui, &keys);
        let h = super::fill::height(ui, 160.0, 70.0);
        let force_plot = Plot::new("bridge-force")
            .height(h)
            .x_axis_label("time [s]")
            .y_axis_label(if super::lecture::on(ui.ctx()) {
                "force [MN]"
            } else {
                "joint force [MN]"
            })
            .show(ui, |p| {
                for (key, pts) in keys.iter().zip(drawn) {
                    p.line(key.plot_line(pts, width));
                }
                p.vline(VLine::new("t", t).color(Color32::GRAY));
                if let Some((a, b)) = zoom {
                    p.set_plot_bounds(PlotBounds::from_min_max([a, -0.05 * top], [b, 1.1 * top]));
                }
            });
        let b = force_plot.transform.bounds();
        self.shown_forces = ShownPlot {
            title: format!("Joint forces: {} contact", r.contact.name()),
            x_label: "time [s]".into(),
            y_label: "joint force [MN]".into(),
            series: forces,
            bounds: Some((b.min(), b.max())),
        };
        exporter.buttons(ui, &self.shown_forces, "joint-forces");
        if force_plot.response.clicked()
            && let Some(pos) = force_plot.response.interact_pointer_pos()
        {
            let at = force_plot.transform.value_from_position(pos).x;
            let near = (0..r.impacts.len())
                .filter(|&i| self.joint.is_none_or(|j| r.impacts[i].level == j))
                .min_by(|&a, &b| {
                    (r.impacts[a].start_s - at)
                        .abs()
                        .total_cmp(&(r.impacts[b].start_s - at).abs())
                });
            if let Some(i) = near {
                self.pick(i);
            }
        }
    }

    fn openings_plot_ui(
        &mut self,
        ui: &mut egui::Ui,
        exporter: &Exporter,
        joints: &[usize],
        t: f64,
    ) {
        let Some(s) = &self.shown.solved else { return };
        let (r, seat) = (&s.drawing.result, s.drawing.setup.scenario.seat_length_m);
        let width = super::lecture::line_width(ui);
        let (shown, px) = (x_range(&self.shown_openings), ui.available_width());
        let lines = joints
            .iter()
            .map(|&j| {
                (
                    format!("joint {j}"),
                    &r.time_s[..],
                    &r.joint_opening_m[j][..],
                )
            })
            .collect();
        let (openings, drawn) = plot_lines(lines, 1e3, shown, px);
        let seat_colour = Color32::from_rgb(225, 40, 40);
        let mut keys: Vec<Key> = joints
            .iter()
            .map(|&j| Key::line(format!("joint {j}"), super::legend::okabe_ito(j), false))
            .collect();
        keys.push(Key::line("seat length", seat_colour, true));
        super::legend::row(ui, &keys);
        let h = super::fill::height(ui, 160.0, 70.0);
        let plot = Plot::new("bridge-openings")
            .height(h)
            .x_axis_label("time [s]")
            .y_axis_label(if super::lecture::on(ui.ctx()) {
                "opening [mm]"
            } else {
                "joint opening [mm]"
            })
            .show(ui, |p| {
                for (key, pts) in keys.iter().zip(drawn) {
                    p.line(key.plot_line(pts, width));
                }
                p.hline(
                    HLine::new("seat length", seat * 1e3)
                        .color(seat_colour)
                        .style(egui_plot::LineStyle::dashed_loose()),
                );
                p.vline(VLine::new("t", t).color(Color32::GRAY));
            });
        let b = plot.transform.bounds();
        let mut series = openings;
        series.push((
            "seat length".into(),
            vec![[0.0, seat * 1e3], [r.duration_s, seat * 1e3]],
        ));
        self.shown_openings = ShownPlot {
            title: "Joint openings against the seat length".into(),
            x_label: "time [s]".into(),
            y_label: "joint opening [mm]".into(),
            series,
            bounds: Some((b.min(), b.max())),
        };
        exporter.buttons(ui, &self.shown_openings, "joint-openings");
    }

    fn girders_plot_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter, t: f64) {
        let Some(s) = &self.shown.solved else { return };
        let r = &s.drawing.result;
        let width = super::lecture::line_width(ui);
        let (shown, px) = (x_range(&self.shown_girders), ui.available_width());
        let spans = r.girder_displacement_m.len();
        let mut sources: Vec<(String, &[f64], &[f64])> = (0..spans)
            .map(|i| {
                let y = &r.girder_displacement_m[i];
                (format!("girder {}", i + 1), &r.time_s[..], &y[..])
            })
            .collect();
        // The run without pounding, dashed, once it has landed.
        if let Some(b) = s.baseline.ready() {
            for i in 0..spans {
                let y = &b.girder_displacement_m[i];
                sources.push((format!("girder {}, no pounding", i + 1), &b.time_s, y));
            }
        }
        let (lines, drawn) = plot_lines(sources, 1e3, shown, px);
        // Each girder keeps its colour; its run without pounding is dashed.
        let keys: Vec<Key> = lines
            .iter()
            .enumerate()
            .map(|(k, (name, _))| Key::line(name, super::legend::okabe_ito(k % spans), k >= spans))
            .collect();
        super::legend::row(ui, &keys);
        let h = super::fill::height(ui, 160.0, 70.0);
        let plot = Plot::new("bridge-girders")
            .height(h)
            .x_axis_label("time [s]")
            .y_axis_label(if super::lecture::on(ui.ctx()) {
                "girder [mm]"
            } else {
                "girder displacement [mm]"
            })
            .show(ui, |p| {
                for (key, pts) in keys.iter().zip(drawn) {
                    p.line(key.plot_line(pts, width));
                }
                p.vline(VLine::new("t", t).color(Color32::GRAY));
            });
        let b = plot.transform.bounds();
        self.shown_girders = ShownPlot {
            title: "Girder displacements relative to their ground, with and without pounding"
                .into(),
            x_label: "time [s]".into(),
            y_label: "girder displacement [mm]".into(),
            series: lines,
            bounds: Some((b.min(), b.max())),
        };
        exporter.buttons(ui, &self.shown_girders, "girder-displacements");
    }

    /// Picks impact i: the force plot zooms on it, the animation waits at its start in slow
    /// motion, and the deck's diagram is drawn around it.
    fn pick(&mut self, i: usize) {
        let Some(s) = &self.shown.solved else { return };
        let e = &s.drawing.result.impacts[i];
        self.selected = Some(i);
        let margin = 0.5 * e.duration_s().max(0.002);
        self.zoom = Some((e.start_s - margin, e.end_s + margin));
        self.playback.t = e.start_s;
        self.playback.playing = false;
        self.playback.speed = 1e-2;
    }

    fn impacts_ui(&mut self, ui: &mut egui::Ui) {
        let Some(s) = &self.shown.solved else { return };
        let r = &s.drawing.result;
        let choice = self.joint.filter(|_| !super::lecture::on(ui.ctx()));
        let shown: Vec<usize> = (0..r.impacts.len())
            .filter(|&i| choice.is_none_or(|j| j == r.impacts[i].level))
            .collect();
        let clicked = super::impact_list::ui(
            ui,
            &r.impacts,
            &shown,
            super::impact_list::Place::Joint,
            &mut self.impact_page,
        );
        if let Some(i) = clicked {
            self.pick(i);
        }
    }

    /// The run on screen for File > Export animation, once whole (a run still solving would
    /// animate beyond what it has solved).
    pub(super) fn animation_source(
        &self,
    ) -> Option<Box<dyn FnOnce() -> super::export_animation::AnimationSource + '_>> {
        let d = &self.shown.solved.as_ref().filter(|s| s.whole)?.drawing;
        Some(Box::new(move || {
            super::export_animation::AnimationSource::Bridge {
                setup: Box::new(d.setup.clone()),
                motion: d.motion.clone(),
                result: Box::new(d.result.clone()),
            }
        }))
    }

    /// The whole deck's x-t diagram around the picked impact (the strongest until one is).
    fn deck_xt_ui(&mut self, ui: &mut egui::Ui) {
        let Some(s) = &self.shown.solved else { return };
        if !s.whole {
            ui.label("the deck's space-time diagram: once the run is solved");
            return;
        }
        let r = &s.drawing.result;
        if r.girder_waves.is_empty() {
            ui.label(format!(
                "the deck's space-time diagram: with the Sears element (under {} the girders are rigid and carry no waves)",
                r.contact.name()
            ));
            return;
        }
        let strongest = (0..r.impacts.len()).max_by(|&a, &b| {
            r.impacts[a]
                .peak_force_n
                .total_cmp(&r.impacts[b].peak_force_n)
        });
        let Some(i) = self.selected.filter(|&i| i < r.impacts.len()).or(strongest) else {
            ui.label("the deck's space-time diagram: no impact in this run");
            return;
        };
        let e = &r.impacts[i];
        let sc = &s.drawing.setup.scenario;
        let trip = (0..sc.spans)
            .map(|k| sc.girder(k).round_trip_s())
            .fold(0.0, f64::max);
        let margin = (0.5 * e.duration_s()).max(trip);
        let (t_start, t_end) = ((e.start_s - margin).max(0.0), e.end_s + 2.0 * margin);
        ui.horizontal_wrapped(|ui| {
            ui.label("deck x-t diagram:");
            ui.selectable_value(&mut self.xt_field, XtShown::Stress, "stress")
                .on_hover_text("Axial stress: compression blue, tension red");
            ui.selectable_value(&mut self.xt_field, XtShown::Velocity, "velocity")
                .on_hover_text("The waves' particle velocity: to the left blue, to the right red");
        });
        let title = format!(
            "the deck over impact {} at joint {} ({:.4} s, {:.3e} N): space-time",
            i + 1,
            e.level,
            e.start_s,
            e.peak_force_n
        );
        let area = s.drawing.smallest_area_m2();
        let clicked = DeckXt {
            d: &s.drawing,
            t_start,
            t_span: t_end - t_start,
            title: &title,
            stress_scale_pa: (e.peak_force_n / area).max(1.0),
            velocity_scale_m_s: e.approach_velocity_m_s.abs().max(1e-3),
        }
        .show(
            ui,
            super::fill::height(ui, 280.0, 100.0),
            self.playback.shown_t(),
            self.xt_field,
        );
        if let Some(t) = clicked {
            self.playback.t = t;
            self.playback.playing = false;
        }
    }
}

#[cfg(test)]
#[path = "bridge_scene_tests.rs"]
mod tests;

/// The x range a plot showed last frame.
fn x_range(plot: &ShownPlot) -> Option<(f64, f64)> {
    plot.bounds.map(|(min, max)| (min[0], max[0]))
}
