//! The Building pounding scene: two buildings swaying under a ground motion, pounding across
//! the gap; the roof slabs coloured by their stress waves (the wgpu pipeline of the bar view),
//! displacements with and without pounding, the pounding force, and a zoom on any impact.

use super::export::{Exporter, ShownPlot};
use super::params::{Fields, Spec};
use super::playback::Playback;
use super::series::decimate;
use super::worker::Worker;
use crate::io::building_settings::BuildingSetup;
use crate::model::building::{
    BuildingErrorEstimate, BuildingResult, BuildingScenario, ContactModel, SlabReading,
    estimate_error, solve,
};
use crate::model::motion::{G, GroundMotion};
use crate::render::bars::{GpuBar, GpuHistory, Viewport};
use eframe::egui::{self, Color32, Pos2, Stroke};
use egui_plot::{Legend, Line, Plot, PlotBounds, VLine};
use std::sync::Arc;
use std::time::Duration;

type Output = Result<
    (
        GroundMotion,
        BuildingResult,
        BuildingResult,
        Option<BuildingErrorEstimate>,
    ),
    String,
>;

struct Solved {
    setup: BuildingSetup,
    motion: GroundMotion,
    result: BuildingResult,
    baseline: BuildingResult,
    ground_displacement: Vec<f64>,
    estimate: Option<BuildingErrorEstimate>,
    gpu: Arc<GpuHistory>,
    version: u64,
}

pub struct BuildingScene {
    pub setup: BuildingSetup,
    fields: Fields,
    worker: Worker<BuildingSetup, Output>,
    solved: Option<Solved>,
    pub playback: Playback,
    exaggeration: f64,
    zoom: Option<(f64, f64)>,
    pub solve_time: Duration,
    pub latency: Duration,
    pub error: Option<String>,
    motion_path: String,
    version: u64,
    /// The view's rectangle last frame (for a screenshot of the view alone).
    pub view_rect: Option<egui::Rect>,
    shown_displacements: ShownPlot,
    shown_force: ShownPlot,
}

fn run_job(setup: BuildingSetup) -> Output {
    let motion =
        crate::io::motion::load(&setup.motion).map_err(|e| format!("ground motion: {e}"))?;
    let result = solve(&setup.scenario, &motion).map_err(|e| e.to_string())?;
    let baseline = solve(
        &BuildingScenario {
            contact: ContactModel::None,
            ..setup.scenario
        },
        &motion,
    )
    .map_err(|e| e.to_string())?;
    let estimate = estimate_error(&setup.scenario, &motion, &result).ok();
    Ok((motion, result, baseline, estimate))
}

/// Ground displacement by integrating the record twice (trapezoid; no baseline correction).
fn ground_displacement(m: &GroundMotion) -> Vec<f64> {
    let (mut v, mut d) = (0.0, 0.0);
    let mut out = vec![0.0];
    for w in m.accel_m_s2.windows(2) {
        let v1 = v + 0.5 * m.dt_s * (w[0] + w[1]);
        d += 0.5 * m.dt_s * (v + v1);
        v = v1;
        out.push(d);
    }
    out
}

/// The slabs' wave histories from the pounding force: H = F + r H(t - T) on a uniform grid,
/// r = exp(-2 pi zeta) the attenuation per round trip of the slab damping.
fn slab_history(sc: &BuildingScenario, r: &BuildingResult) -> GpuHistory {
    let dt = r.stats.fine_step_s.max(1e-6);
    let end = *r.time_s.last().unwrap_or(&0.0);
    let n = (end / dt).ceil() as usize + 1;
    let mut force = Vec::with_capacity(n);
    let mut k = 0;
    for j in 0..n {
        let t = j as f64 * dt;
        while k + 1 < r.time_s.len() && r.time_s[k + 1] < t {
            k += 1;
        }
        let f = if k + 1 < r.time_s.len() {
            let (t0, t1) = (r.time_s[k], r.time_s[k + 1]);
            let s = if t1 > t0 {
                ((t - t0) / (t1 - t0)).clamp(0.0, 1.0)
            } else {
                0.0
            };
            r.force_n[k] + s * (r.force_n[k + 1] - r.force_n[k])
        } else {
            0.0
        };
        force.push(f);
    }
    let decay = (-2.0 * std::f64::consts::PI * sc.slab_damping).exp();
    let mut samples = Vec::with_capacity(2 * n);
    let mut layout = [(0, 0, 0.0, 0.0); 2];
    for (i, b) in [sc.left, sc.right].iter().enumerate() {
        let lag = (b.slab_round_trip_s() / dt).round().max(1.0) as usize;
        let offset = samples.len();
        for j in 0..n {
            let echo = if j >= lag {
                samples[offset + j - lag] as f64
            } else {
                0.0
            };
            samples.push((force[j] + decay * echo) as f32);
        }
        layout[i] = (offset as u32, n as u32, dt as f32, end as f32);
    }
    GpuHistory { samples, layout }
}

impl BuildingScene {
    pub fn new(ctx: &egui::Context, setup: BuildingSetup) -> Self {
        let waker = ctx.clone();
        let mut s = BuildingScene {
            setup,
            fields: Fields::default(),
            worker: Worker::new(run_job, move || waker.request_repaint()),
            solved: None,
            playback: Playback {
                t: 0.0,
                playing: true,
                speed: 1.0,
                t_max: 8.0,
            },
            exaggeration: 20.0,
            zoom: None,
            solve_time: Duration::ZERO,
            latency: Duration::ZERO,
            error: None,
            motion_path: String::new(),
            version: 0,
            view_rect: None,
            shown_displacements: ShownPlot::default(),
            shown_force: ShownPlot::default(),
        };
        s.request();
        s
    }

    pub fn request(&mut self) {
        self.worker.request(self.setup.clone());
    }

    pub fn busy(&self) -> bool {
        self.worker.busy()
    }

    pub fn poll(&mut self) {
        let Some((done, latency)) = self.worker.poll() else {
            return;
        };
        self.solve_time = done.elapsed;
        self.latency = latency;
        match done.output {
            Ok((motion, result, baseline, estimate)) => {
                self.error = None;
                self.version += 1;
                self.playback.t_max = motion.duration_s();
                self.playback.t = self.playback.t.min(self.playback.t_max);
                let gpu = Arc::new(slab_history(&self.setup.scenario, &result));
                self.solved = Some(Solved {
                    setup: self.setup.clone(),
                    ground_displacement: ground_displacement(&motion),
                    estimate,
                    motion,
                    result,
                    baseline,
                    gpu,
                    version: self.version,
                });
            }
            // The last result stays; the error says why the new one failed.
            Err(e) => self.error = Some(e),
        }
    }

    /// A dropped file becomes the ground motion.
    pub fn take_dropped(&mut self, ctx: &egui::Context) {
        let dropped: Vec<_> = ctx.input(|i| {
            i.raw
                .dropped_files
                .iter()
                .map(|f| f.path().to_path_buf())
                .filter(|p| !p.as_os_str().is_empty())
                .collect()
        });
        if let Some(path) = dropped.first() {
            self.motion_path = path.display().to_string();
            self.setup.motion.file = Some(self.motion_path.clone());
            self.request();
        }
    }

    pub fn params_ui(&mut self, ui: &mut egui::Ui) {
        let before = self.setup.clone();
        let sc = &mut self.setup.scenario;
        let fields = &mut self.fields;
        for (side, b) in [("left", &mut sc.left), ("right", &mut sc.right)] {
            egui::CollapsingHeader::new(format!("{side} building")).default_open(true).show(ui, |ui| {
                fields.row(ui, &format!("{side}.mass"), &Spec { label: "mass", unit: "kg", tooltip: "Seismic mass: with the stiffness it sets the period", min: 1e3, max: 1e7, log: true }, &mut b.mass_kg);
                fields.row(ui, &format!("{side}.stiffness"), &Spec { label: "stiffness", unit: "N/m", tooltip: "Storey stiffness", min: 1e5, max: 1e10, log: true }, &mut b.stiffness_n_m);
                ui.label(format!("period {:.3} s", b.period_s()));
                fields.row(ui, &format!("{side}.damping"), &Spec { label: "damping", unit: "", tooltip: "Viscous damping ratio of the building (5% is the design-code value for concrete)", min: 0.0, max: 0.5, log: false }, &mut b.damping_ratio);
            });
        }
        egui::CollapsingHeader::new("Contact").default_open(true).show(ui, |ui| {
            ui.horizontal_wrapped(|ui| {
                for m in ContactModel::ALL {
                    ui.selectable_value(&mut sc.contact, m, m.name());
                }
            });
            fields.row(ui, "gap", &Spec { label: "gap", unit: "m", tooltip: "At-rest separation of the roofs", min: 0.0, max: 0.2, log: false }, &mut sc.gap_m);
            let mut k = sc.element_stiffness();
            if fields.row(ui, "contact.stiffness", &Spec { label: "stiffness", unit: if sc.contact.is_hertzian() { "N/m^1.5" } else { "N/m" }, tooltip: "Contact element stiffness (the paper: 15 GN/m)", min: 1e6, max: 1e14, log: true }, &mut k) {
                sc.stiffness = Some(k);
            }
            fields.row(ui, "contact.restitution", &Spec { label: "restitution", unit: "", tooltip: "Target restitution of kelvin, hertzdamp, jankowski and stereo", min: 0.05, max: 1.0, log: false }, &mut sc.restitution);
            ui.horizontal(|ui| {
                ui.label("Sears reading");
                ui.selectable_value(&mut sc.reading, SlabReading::Paper, "paper");
                ui.selectable_value(&mut sc.reading, SlabReading::End, "end");
            });
            fields.row(ui, "slab.damping", &Spec { label: "slab damping", unit: "", tooltip: "Damping ratio of the slabs' axial waves; 0 lets them ring through the record", min: 0.0, max: 0.5, log: false }, &mut sc.slab_damping);
            fields.row(ui, "impact.merge_gap_s", &Spec { label: "merge gap", unit: "s", tooltip: "Contacts closer than this count as one impact", min: 0.0, max: 0.5, log: false }, &mut sc.merge_gap_s);
        });
        egui::CollapsingHeader::new("Ground motion")
            .default_open(true)
            .show(ui, |ui| {
                let m = &mut self.setup.motion;
                let built_in = crate::io::motion::BUILT_IN;
                let shown = match &m.file {
                    None => "synthetic (Kanai-Tajimi)".to_string(),
                    Some(f) => built_in
                        .iter()
                        .find(|b| b.name == f)
                        .map_or_else(|| "file".to_string(), |b| b.title.to_string()),
                };
                ui.horizontal(|ui| {
                    let label = ui.label("record").id;
                    egui::ComboBox::from_id_salt("motion-record")
                        .selected_text(shown)
                        .show_ui(ui, |ui| {
                            for b in built_in {
                                if ui
                                    .selectable_label(m.file.as_deref() == Some(b.name), b.title)
                                    .on_hover_text(b.about)
                                    .clicked()
                                {
                                    m.file = Some(b.name.to_string());
                                }
                            }
                            if ui
                                .selectable_label(m.file.is_none(), "synthetic (Kanai-Tajimi)")
                                .on_hover_text("A seeded synthetic record: PGA and seed below")
                                .clicked()
                            {
                                m.file = None;
                            }
                        })
                        .response
                        .labelled_by(label);
                });
                ui.horizontal(|ui| {
                    let label = ui.label("file").id;
                    ui.add(
                        egui::TextEdit::singleline(&mut self.motion_path)
                            .hint_text(".AT2 or text file (or drop one here)")
                            .desired_width(170.0),
                    )
                    .labelled_by(label);
                    if ui.button("Load").clicked() && !self.motion_path.trim().is_empty() {
                        m.file = Some(self.motion_path.trim().to_string());
                    }
                });
                let mut scale = m.scale;
                if fields.row(
                    ui,
                    "motion.scale",
                    &Spec {
                        label: "scale",
                        unit: "x",
                        tooltip: "Factor on the record; negative flips it",
                        min: -5.0,
                        max: 5.0,
                        log: false,
                    },
                    &mut scale,
                ) && scale != 0.0
                {
                    m.scale = scale;
                }
                let mut duration = m.duration_s.unwrap_or(0.0);
                if fields.row(
                    ui,
                    "motion.duration",
                    &Spec {
                        label: "duration",
                        unit: "s",
                        tooltip: "Use only the first seconds of the record (0: all)",
                        min: 0.0,
                        max: 120.0,
                        log: false,
                    },
                    &mut duration,
                ) {
                    m.duration_s = (duration > 0.0).then_some(duration);
                }
                if m.file.is_none() {
                    fields.row(
                        ui,
                        "motion.pga",
                        &Spec {
                            label: "PGA",
                            unit: "g",
                            tooltip: "Peak ground acceleration of the synthetic record",
                            min: 0.01,
                            max: 2.0,
                            log: false,
                        },
                        &mut m.synthetic.pga_g,
                    );
                    let mut seed = m.synthetic.seed as f64;
                    if fields.row(
                        ui,
                        "motion.seed",
                        &Spec {
                            label: "seed",
                            unit: "",
                            tooltip: "Another seed, another record of the same kind",
                            min: 0.0,
                            max: 1e6,
                            log: false,
                        },
                        &mut seed,
                    ) {
                        m.synthetic.seed = seed.round() as u64;
                    }
                }
            });
        if self.setup != before {
            self.request();
        }
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
        if self.solved.is_some() {
            plots.push(("displacements", &self.shown_displacements));
            plots.push(("force", &self.shown_force));
        }
        plots
    }

    pub fn main_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter) {
        if let Some(e) = &self.error {
            ui.colored_label(Color32::from_rgb(220, 60, 50), e);
        }
        let Some(s) = &self.solved else {
            ui.label("solving...");
            return;
        };
        let stats = s.motion.stats();
        ui.label(format!(
            "{}: {:.2} s at {} s, PGA {:.3} g, PGV {:.3} m/s, Arias {:.2} m/s, 5% spectrum peaks at {:.2} s",
            s.motion.name,
            stats.duration_s,
            s.motion.dt_s,
            stats.pga_m_s2 / G,
            stats.pgv_m_s,
            stats.arias_m_s,
            stats.predominant_period_s
        ));
        let (rect, _) = ui.allocate_exact_size(
            egui::vec2(ui.available_width(), 230.0),
            egui::Sense::hover(),
        );
        draw_buildings(ui, rect, s, self.playback.t, self.exaggeration);
        self.view_rect = Some(rect);
        ui.horizontal(|ui| {
            let label = ui
                .label("exaggeration")
                .on_hover_text("The buildings' drift is drawn this many times larger")
                .id;
            ui.add(egui::Slider::new(&mut self.exaggeration, 1.0..=500.0).logarithmic(true))
                .labelled_by(label);
        });
        self.playback.ui(ui);
        let r = &s.result;
        ui.label(format!(
            "{} impacts ({} contacts), max force {:.4e} N, peak displacement left {:.2} mm (without pounding {:.2}), right {:.2} mm ({:.2}); solve {}",
            r.impacts.len(),
            r.contacts.len(),
            r.max_pounding_force_n,
            r.peak_displacement_m[0] * 1e3,
            s.baseline.peak_displacement_m[0] * 1e3,
            r.peak_displacement_m[1] * 1e3,
            s.baseline.peak_displacement_m[1] * 1e3,
            super::ms(self.solve_time.as_secs_f64(), 1)
        ));
        if let Some(e) = &s.estimate {
            ui.label(format!(
                "error estimate (step doubling): max force {:.1e}, peak displacement {:.1e} (relative), impact count {:+} with twice the step",
                e.max_force, e.peak_displacement, e.impact_count_change
            ));
        }
        let t = self.playback.t;
        let h = 170.0;
        let pts =
            |time: &[f64], y: &[f64], scale: f64| -> Vec<[f64; 2]> { decimate(time, y, scale) };
        let disp_lines = vec![
            (
                "left".to_string(),
                pts(&r.time_s, &r.displacement_m[0], 1e3),
            ),
            (
                "right".to_string(),
                pts(&r.time_s, &r.displacement_m[1], 1e3),
            ),
            (
                "left, no pounding".to_string(),
                pts(&s.baseline.time_s, &s.baseline.displacement_m[0], 1e3),
            ),
            (
                "right, no pounding".to_string(),
                pts(&s.baseline.time_s, &s.baseline.displacement_m[1], 1e3),
            ),
        ];
        let disp_plot = Plot::new("b-disp")
            .height(h)
            .legend(Legend::default())
            .x_axis_label("time [s]")
            .y_axis_label("displacement [mm]")
            .show(ui, |p| {
                for (i, (name, line)) in disp_lines.iter().enumerate() {
                    let l = Line::new(name.as_str(), line.clone());
                    p.line(if i >= 2 {
                        l.style(egui_plot::LineStyle::dashed_loose())
                    } else {
                        l
                    });
                }
                p.vline(VLine::new("t", t));
            });
        let b = disp_plot.transform.bounds();
        self.shown_displacements = ShownPlot {
            title: "Roof displacements with and without pounding".into(),
            x_label: "time [s]".into(),
            y_label: "displacement [mm]".into(),
            series: disp_lines,
            bounds: Some((b.min(), b.max())),
        };
        exporter.buttons(ui, &self.shown_displacements, "displacements");
        let zoom = self.zoom.take();
        let force_pts = pts(&r.time_s, &r.force_n, 1e-6);
        let force_plot = Plot::new("b-force")
            .height(h)
            .legend(Legend::default())
            .x_axis_label("time [s]")
            .y_axis_label("pounding force [MN]")
            .show(ui, |p| {
                p.line(Line::new("force", force_pts.clone()).allow_band(false));
                p.vline(VLine::new("t", t));
                if let Some((a, b)) = zoom {
                    p.set_plot_bounds(PlotBounds::from_min_max(
                        [a, -0.05 * r.max_pounding_force_n * 1e-6],
                        [b, 1.1 * r.max_pounding_force_n * 1e-6],
                    ));
                }
            });
        let b = force_plot.transform.bounds();
        self.shown_force = ShownPlot {
            title: format!("Pounding force: {} contact", r.contact.name()),
            x_label: "time [s]".into(),
            y_label: "pounding force [MN]".into(),
            series: vec![("force".into(), force_pts)],
            bounds: Some((b.min(), b.max())),
        };
        exporter.buttons(ui, &self.shown_force, "force");
        ui.label("impacts (click one here or in the force plot to zoom on it):");
        let mut clicked = None;
        // A click in the force plot picks the impact nearest in time.
        if force_plot.response.clicked()
            && let Some(pos) = force_plot.response.interact_pointer_pos()
        {
            let at = force_plot.transform.value_from_position(pos).x;
            clicked = r
                .impacts
                .iter()
                .enumerate()
                .min_by(|a, b| {
                    (a.1.start_s - at)
                        .abs()
                        .total_cmp(&(b.1.start_s - at).abs())
                })
                .map(|(i, _)| i);
        }
        egui::Grid::new("impacts")
            .striped(true)
            .num_columns(6)
            .show(ui, |ui| {
                for h in [
                    "#",
                    "start [s]",
                    "duration [ms]",
                    "peak force [N]",
                    "impulse [N s]",
                    "approach [m/s]",
                    "contacts",
                ] {
                    ui.strong(h);
                }
                ui.end_row();
                for (i, e) in r.impacts.iter().enumerate() {
                    if ui.button(format!("{}", i + 1)).clicked() {
                        clicked = Some(i);
                    }
                    ui.label(format!("{:.4}", e.start_s));
                    ui.label(format!("{:.3}", e.duration_s() * 1e3));
                    ui.label(format!("{:.4e}", e.peak_force_n));
                    ui.label(format!("{:.4e}", e.impulse_ns));
                    ui.label(format!("{:.4}", e.approach_velocity_m_s));
                    ui.label(format!("{}", e.contacts.len()));
                    ui.end_row();
                }
            });
        if let Some(i) = clicked {
            let e = &r.impacts[i];
            let margin = 0.5 * e.duration_s().max(0.002);
            self.zoom = Some((e.start_s - margin, e.end_s + margin));
            self.playback.t = e.start_s;
            self.playback.playing = false;
            self.playback.speed = 1e-3;
        }
        for w in &r.warnings {
            ui.colored_label(Color32::from_rgb(220, 140, 40), format!("warning: {w}"));
        }
    }
}

fn sample(time: &[f64], y: &[f64], t: f64) -> f64 {
    let k = time.partition_point(|&x| x <= t);
    if k == 0 {
        return y.first().copied().unwrap_or(0.0);
    }
    if k >= time.len() {
        return y.last().copied().unwrap_or(0.0);
    }
    let (t0, t1) = (time[k - 1], time[k]);
    let s = if t1 > t0 { (t - t0) / (t1 - t0) } else { 0.0 };
    y[k - 1] + s * (y[k] - y[k - 1])
}

fn draw_buildings(ui: &mut egui::Ui, rect: egui::Rect, s: &Solved, t: f64, exaggeration: f64) {
    let sc = &s.setup.scenario;
    let r = &s.result;
    let (l1, l2) = (sc.left.slab.length_m, sc.right.slab.length_m);
    let height = sc.left.storey_height_m.max(sc.right.storey_height_m);
    // World: metres, the at-rest gap centred at x = 0, the ground at y = 0.
    let gap_world = (sc.gap_m * exaggeration).max(0.05);
    let (left, right) = (-l1 - gap_world - 2.0, l2 + gap_world + 2.0);
    let (bottom, top) = (-1.0f32, (height * 1.6) as f32);
    let aspect = rect.width() / rect.height();
    let span = (right - left) as f32;
    let (bottom, top) = if span / (top - bottom) < aspect {
        (bottom, top)
    } else {
        let h = span / aspect;
        (bottom, bottom + h)
    };
    let xg = sample(
        &(0..s.ground_displacement.len())
            .map(|i| i as f64 * s.motion.dt_s)
            .collect::<Vec<_>>(),
        &s.ground_displacement,
        t,
    );
    let u = [
        sample(&r.time_s, &r.displacement_m[0], t),
        sample(&r.time_s, &r.displacement_m[1], t),
    ];
    let roof = [
        -0.5 * gap_world + u[0] * exaggeration,
        0.5 * gap_world + u[1] * exaggeration,
    ];
    let base = [-0.5 * gap_world, 0.5 * gap_world];
    let slab_t = 0.4f32;
    let mut bars = [GpuBar::default(); 2];
    let force_scale = r.max_pounding_force_n.max(1.0);
    for (i, b) in [sc.left, sc.right].iter().enumerate() {
        let (offset, count, dt, end) = s.gpu.layout[i];
        bars[i] = GpuBar {
            origin_x: (roof[i] + xg) as f32,
            direction: if i == 0 { -1.0 } else { 1.0 },
            body_length: b.slab.length_m as f32,
            zone_length: 0.0,
            wave_speed: b.slab_wave_speed_m_s() as f32,
            round_trip: b.slab_round_trip_s() as f32,
            dt,
            end_time: end,
            offset,
            count,
            inv_area: (1.0 / b.slab.area_m2()) as f32,
            inv_stress_scale: (b.slab.area_m2() / force_scale) as f32,
            y_bottom: height as f32 - slab_t,
            y_top: height as f32,
            world_per_metre: 1.0,
            _pad: 0.0,
        };
    }
    let vp = Viewport {
        rect,
        left,
        right,
        bottom: bottom as f64,
        top: top as f64,
    };
    let world = [vp.left, vp.right, vp.bottom, vp.top];
    vp.paint_bars(
        ui,
        crate::render::bars::uniforms(world, t, bars),
        s.gpu.clone(),
        s.version,
    );
    let to_screen = |x: f64, y: f64| vp.to_screen(x, y);
    let painter = ui.painter_at(rect);
    let text = ui.visuals().text_color();
    let column = Stroke::new(
        3.0,
        if ui.visuals().dark_mode {
            Color32::from_gray(170)
        } else {
            Color32::from_gray(80)
        },
    );
    // Ground, moving with the record (drawn to scale).
    painter.line_segment(
        [to_screen(left, 0.0), to_screen(right, 0.0)],
        Stroke::new(2.0, Color32::from_rgb(140, 110, 70)),
    );
    for k in 0..24 {
        let x = left + (right - left) * k as f64 / 24.0 + xg;
        painter.line_segment(
            [to_screen(x, 0.0), to_screen(x - 0.4, -0.4)],
            Stroke::new(1.0, Color32::from_rgb(140, 110, 70)),
        );
    }
    for i in 0..2 {
        let dir = if i == 0 { -1.0 } else { 1.0 };
        let len = if i == 0 { l1 } else { l2 };
        for frac in [0.05, 0.95] {
            let x0 = base[i] + dir * frac * len + xg;
            let x1 = roof[i] + dir * frac * len + xg;
            painter.line_segment(
                [to_screen(x0, 0.0), to_screen(x1, height - slab_t as f64)],
                column,
            );
        }
        painter.text(
            to_screen(base[i] + dir * 0.5 * len + xg, height + 0.6),
            egui::Align2::CENTER_BOTTOM,
            format!(
                "{} building: {:+.2} mm",
                if i == 0 { "left" } else { "right" },
                u[i] * 1e3
            ),
            egui::FontId::proportional(13.0),
            text,
        );
    }
    let f = sample(&r.time_s, &r.force_n, t);
    if f > 0.0 {
        painter.text(
            to_screen(0.0, height + 1.6),
            egui::Align2::CENTER_BOTTOM,
            format!("pounding: {:.3e} N", f),
            egui::FontId::proportional(14.0),
            Color32::from_rgb(220, 60, 50),
        );
    }
    painter.text(
        Pos2::new(rect.right() - 8.0, rect.top() + 6.0),
        egui::Align2::RIGHT_TOP,
        format!("t = {t:.4} s, drift x{exaggeration:.0}, ground to scale"),
        egui::FontId::proportional(12.0),
        text,
    );
}
