//! The view of two buildings: N-storey frames swaying with the record (drift exaggerated, the
//! ground to scale), every floor slab drawn, the slabs that meet at a level coloured by their
//! stress waves on the GPU (the bar view's pipeline, from the model's slab histories), and the
//! contact points marked.

use super::lecture;
use crate::io::building_settings::BuildingSetup;
use crate::model::building::{Attachment, BuildingResult, Level};
use crate::model::field::BarWaves;
use crate::model::motion::{GroundMotion, MotionStats};
use crate::model::xt::interpolate;
use crate::render::bars::{GpuBar, GpuHistory, HistoryEntry, View, Viewport, uniforms};
use eframe::egui::{self, Color32, Pos2, Stroke};
use std::sync::Arc;

/// A solve ready to draw: the run, its record's ground displacement and the slabs' waves on the
/// GPU grid (one bar per slab that meets another at a level).
pub struct BuildingDrawing {
    pub setup: BuildingSetup,
    pub motion: GroundMotion,
    pub result: BuildingResult,
    /// The record's summary (a response spectrum among it: worked out here, off the UI thread).
    pub motion_stats: MotionStats,
    ground_displacement: Vec<f64>,
    /// (level, side) of each bar in `gpu`.
    bars: Vec<(usize, usize)>,
    gpu: Arc<GpuHistory>,
}

impl BuildingDrawing {
    /// The history on the GPU of every slab with waves.
    pub fn gpu(&self) -> &Arc<GpuHistory> {
        &self.gpu
    }

    /// Where the two slabs of `level` lie in [`BuildingDrawing::gpu`] (`None` unless both
    /// have waves).
    pub fn slab_entries(&self, level: usize) -> Option<[HistoryEntry; 2]> {
        let entry = |side| {
            let i = self.bars.iter().position(|&b| b == (level, side))?;
            Some(self.gpu.layout[i])
        };
        Some([entry(0)?, entry(1)?])
    }

    pub fn new(setup: BuildingSetup, motion: GroundMotion, result: BuildingResult) -> Self {
        let stats = motion.stats();
        Self::with_stats(setup, motion, result, stats)
    }

    /// As `new`, with the record's summary already worked out (a job that draws a run many
    /// times as it solves works it out once).
    pub fn with_stats(
        setup: BuildingSetup,
        motion: GroundMotion,
        result: BuildingResult,
        motion_stats: MotionStats,
    ) -> Self {
        let mut bars = vec![];
        let mut waves: Vec<&BarWaves> = vec![];
        for (l, level) in result.slab_waves().iter().enumerate() {
            for (s, w) in level.iter().enumerate() {
                if let Some(w) = w {
                    bars.push((l, s));
                    waves.push(w);
                }
            }
        }
        let gpu = Arc::new(GpuHistory::from_bars(waves));
        BuildingDrawing {
            ground_displacement: motion.displacement_m(),
            motion_stats,
            setup,
            motion,
            result,
            bars,
            gpu,
        }
    }
}

/// The columns of a storey that has yielded.
pub const YIELDED: Color32 = Color32::from_rgb(230, 120, 30);

/// A point of a building at floor weights: its displacement at t.
fn attached(floors: &[Vec<f64>], time: &[f64], a: &Attachment, t: f64) -> f64 {
    a.weights()
        .iter()
        .map(|(f, w)| w * interpolate(time, &floors[*f], t))
        .sum()
}

/// Where and when one frame of the view is drawn: the viewport over the world (metres, the
/// at-rest gap centred at x = 0, the ground at y = 0), the ground's displacement, each
/// building's inner face and outward direction, the slab thickness drawn.
struct Scene<'a> {
    d: &'a BuildingDrawing,
    vp: Viewport,
    t: f64,
    exaggeration: f64,
    /// The ground's displacement at t [m].
    xg: f64,
    inner: [f64; 2],
    dir: [f64; 2],
    slab_t: f64,
    /// The longest slab of each building [m].
    lengths: [f64; 2],
}

impl<'a> Scene<'a> {
    fn new(rect: egui::Rect, d: &'a BuildingDrawing, t: f64, exaggeration: f64) -> Self {
        let sc = &d.setup.scenario;
        let buildings = [&sc.left, &sc.right];
        let lengths = buildings.map(|b| {
            (0..b.storeys)
                .map(|j| b.slab(j).length_m)
                .fold(0.0, f64::max)
        });
        let height = buildings
            .iter()
            .map(|b| b.total_height_m())
            .fold(0.0, f64::max);
        let gap_world = (sc.gap_m * exaggeration).max(0.05);
        let (left, right) = (-lengths[0] - gap_world - 2.0, lengths[1] + gap_world + 2.0);
        let (bottom, top) = (-1.0f64, height * 1.25 + 1.0);
        let aspect = (rect.width() / rect.height()) as f64;
        let (left, right, top) = if (right - left) / (top - bottom) < aspect {
            // Widen to fill the view.
            let w = (top - bottom) * aspect;
            let mid = 0.5 * (left + right);
            (mid - 0.5 * w, mid + 0.5 * w, top)
        } else {
            (left, right, bottom + (right - left) / aspect)
        };
        let xg = interpolate(
            &(0..d.ground_displacement.len())
                .map(|i| i as f64 * d.motion.dt_s)
                .collect::<Vec<_>>(),
            &d.ground_displacement,
            t,
        );
        Scene {
            d,
            vp: Viewport {
                rect,
                left,
                right,
                bottom,
                top,
            },
            t,
            exaggeration,
            xg,
            inner: [-0.5 * gap_world, 0.5 * gap_world],
            dir: [-1.0, 1.0],
            slab_t: (height * 0.02).clamp(0.15, 0.5),
            lengths,
        }
    }

    fn to_screen(&self, x: f64, y: f64) -> Pos2 {
        self.vp.to_screen(x, y)
    }

    /// Floor f of side s: its displacement relative to the ground at t [m].
    fn floor_u(&self, s: usize, f: usize) -> f64 {
        let r = &self.d.result;
        interpolate(&r.time_s, &r.floor_displacement_m[s][f], self.t)
    }

    /// The slabs that meet at a level, as bars for the GPU to colour by their waves.
    fn slab_bars(&self) -> Vec<GpuBar> {
        let (d, r) = (self.d, &self.d.result);
        let sc = &d.setup.scenario;
        let buildings = [&sc.left, &sc.right];
        let force_scale = r.max_pounding_force_n.max(1.0);
        d.bars
            .iter()
            .enumerate()
            .map(|(i, &(level, s))| {
                let lv: &Level = &r.levels[level];
                let a = if s == 0 { lv.left } else { lv.right };
                let f = a.floor().expect("a slab is a floor's");
                let b = buildings[s];
                let slab = b.slab(f);
                let w = r.slab_waves()[level][s].as_ref().expect("drawn");
                let z = b.elevations_m()[f];
                GpuBar {
                    origin_x: (self.inner[s] + self.floor_u(s, f) * self.exaggeration + self.xg)
                        as f32,
                    direction: self.dir[s] as f32,
                    inv_stress_scale: (slab.area_m2() / force_scale) as f32,
                    y_bottom: (z - self.slab_t) as f32,
                    y_top: z as f32,
                    world_per_metre: 1.0,
                    ..GpuBar::of_waves(w, d.gpu.layout[i], 1.0)
                }
            })
            .collect()
    }

    /// The ground line and its hatching, moving with the record (to scale).
    fn ground(&self, painter: &egui::Painter) {
        let (left, right) = (self.vp.left, self.vp.right);
        let brown = Color32::from_rgb(140, 110, 70);
        painter.line_segment(
            [self.to_screen(left, 0.0), self.to_screen(right, 0.0)],
            Stroke::new(2.0, brown),
        );
        for k in 0..24 {
            let x = left + (right - left) * k as f64 / 24.0 + self.xg;
            painter.line_segment(
                [self.to_screen(x, 0.0), self.to_screen(x - 0.4, -0.4)],
                Stroke::new(1.0, brown),
            );
        }
    }

    /// One building's columns and the slabs the GPU does not colour, and its caption.
    fn building(
        &self,
        painter: &egui::Painter,
        s: usize,
        column: Stroke,
        plain: Color32,
        text: Color32,
    ) {
        let (d, r) = (self.d, &self.d.result);
        let sc = &d.setup.scenario;
        let b = [&sc.left, &sc.right][s];
        let (inner, dir) = (self.inner[s], self.dir[s]);
        let zs = b.elevations_m();
        let mut below_u = 0.0;
        let mut below_z = 0.0;
        for (f, &z) in zs.iter().enumerate() {
            let u = self.floor_u(s, f) * self.exaggeration + self.xg;
            let len = b.slab(f).length_m;
            // Columns from the floor below (the ground, moving with the record, for the first).
            let (base_u, base_z) = if f == 0 {
                (self.xg, 0.0)
            } else {
                (below_u, below_z)
            };
            // A storey that has yielded by now keeps its columns tinted: its drift went past
            // F_y / k, and what is left of it after the record is the residual drift.
            let stroke = if r.yielded_by(s, f, self.t) {
                Stroke::new(column.width + 1.0, YIELDED)
            } else {
                column
            };
            for frac in [0.05, 0.95] {
                let x = inner + dir * frac * len;
                painter.line_segment(
                    [
                        self.to_screen(x + base_u, base_z),
                        self.to_screen(x + u, z - self.slab_t),
                    ],
                    stroke,
                );
            }
            let coloured = d.bars.iter().any(|&(level, side)| {
                side == s && [r.levels[level].left, r.levels[level].right][s].floor() == Some(f)
            });
            if !coloured {
                let (a, c) = (
                    self.to_screen(inner + u, z - self.slab_t),
                    self.to_screen(inner + dir * len + u, z),
                );
                painter.rect_filled(egui::Rect::from_two_pos(a, c), 1.0, plain);
            }
            below_u = u;
            below_z = z;
        }
        if lecture::on(painter.ctx()) {
            return;
        }
        painter.text(
            self.to_screen(
                inner + dir * 0.5 * self.lengths[s] + self.xg,
                b.total_height_m() + 0.4,
            ),
            egui::Align2::CENTER_BOTTOM,
            self.roof_label(s),
            lecture::font(painter.ctx(), 13.0),
            text,
        );
    }

    /// Building `s`, its storeys and its roof's displacement now.
    fn roof_label(&self, s: usize) -> String {
        let sc = &self.d.setup.scenario;
        let b = [&sc.left, &sc.right][s];
        format!(
            "{} building, {} storey{}: roof {:+.2} mm",
            if s == 0 { "left" } else { "right" },
            b.storeys,
            if b.storeys == 1 { "" } else { "s" },
            roof_u(self.d, s, self.t) * 1e3
        )
    }

    /// A mark at each level on each side, red while it carries force.
    fn contact_points(&self, painter: &egui::Painter) {
        let r = &self.d.result;
        for (l, level) in r.levels.iter().enumerate() {
            let force = interpolate(&r.time_s, &r.level_force_n[l], self.t);
            let colour = if force > 0.0 {
                Color32::from_rgb(220, 60, 50)
            } else {
                Color32::from_rgb(240, 180, 60)
            };
            for (s, a) in [(0, &level.left), (1, &level.right)] {
                let u = attached(&r.floor_displacement_m[s], &r.time_s, a, self.t)
                    * self.exaggeration
                    + self.xg;
                let p = self.to_screen(self.inner[s] + u, level.elevation_m - 0.5 * self.slab_t);
                painter.circle_filled(p, 4.0, colour);
            }
        }
    }

    /// The pounding force while there is one, and the time and scales.
    fn captions(&self, painter: &egui::Painter, text: Color32) {
        if lecture::on(painter.ctx()) {
            return;
        }
        let (r, rect) = (&self.d.result, self.vp.rect);
        let f = interpolate(&r.time_s, &r.force_n, self.t);
        if f > 0.0 {
            painter.text(
                Pos2::new(rect.left() + 8.0, rect.top() + 6.0),
                egui::Align2::LEFT_TOP,
                format!("pounding: {:.3e} N", f),
                lecture::font(painter.ctx(), 14.0),
                Color32::from_rgb(220, 60, 50),
            );
        }
        painter.text(
            Pos2::new(rect.right() - 8.0, rect.top() + 6.0),
            egui::Align2::RIGHT_TOP,
            format!(
                "t = {:.4} s, drift x{:.0}, ground to scale",
                self.t, self.exaggeration
            ),
            lecture::font(painter.ctx(), 12.0),
            text,
        );
        let yielded = yielded(self.d, self.t);
        if r.storey_shear_n.iter().any(|s| !s.is_empty()) {
            painter.text(
                Pos2::new(rect.right() - 8.0, rect.top() + 22.0),
                egui::Align2::RIGHT_TOP,
                format!("storeys yielded so far: {yielded} (orange columns)"),
                lecture::font(painter.ctx(), 12.0),
                YIELDED,
            );
        }
    }
}

/// Building `s`'s roof displacement at time `t` [m].
fn roof_u(d: &BuildingDrawing, s: usize, t: f64) -> f64 {
    let r = &d.result;
    let roof = &r.floor_displacement_m[s];
    interpolate(&r.time_s, &roof[roof.len() - 1], t)
}

/// How many storeys have yielded by time `t`.
fn yielded(d: &BuildingDrawing, t: f64) -> usize {
    let r = &d.result;
    (0..2)
        .map(|s| {
            (0..r.first_yield_s[s].len())
                .filter(|&j| r.yielded_by(s, j, t))
                .count()
        })
        .sum()
}

/// What the view's captions say, as a row of labels above it in lecture mode, where a hall's
/// font size would run labels painted over the buildings into each other.
pub fn caption(ui: &mut egui::Ui, record: &str, d: &BuildingDrawing, t: f64, exaggeration: f64) {
    let r = &d.result;
    ui.horizontal_wrapped(|ui| {
        ui.spacing_mut().item_spacing.x = 24.0;
        ui.label(record);
        ui.label(format!("t = {t:.3} s, drift x{exaggeration:.0}"));
        for s in 0..2 {
            let roof = roof_u(d, s, t) * 1e3;
            ui.label(format!("{} roof {roof:+.2} mm", ["left", "right"][s]));
        }
        let f = interpolate(&r.time_s, &r.force_n, t);
        if f > 0.0 {
            ui.colored_label(
                Color32::from_rgb(220, 60, 50),
                format!("pounding: {}", crate::model::settings::engineering(f, "N")),
            );
        }
        if r.storey_shear_n.iter().any(|s| !s.is_empty()) {
            ui.colored_label(
                YIELDED,
                format!("storeys yielded so far: {} (orange)", yielded(d, t)),
            );
        }
    });
}

pub fn draw(ui: &mut egui::Ui, rect: egui::Rect, d: &BuildingDrawing, t: f64, exaggeration: f64) {
    let scene = Scene::new(rect, d, t, exaggeration);
    let gpu_bars = scene.slab_bars();
    let painter = ui.painter_at(rect);
    let dark = ui.visuals().dark_mode;
    let text = ui.visuals().text_color();
    let column = Stroke::new(
        2.5,
        if dark {
            Color32::from_gray(170)
        } else {
            Color32::from_gray(80)
        },
    );
    let plain = if dark {
        Color32::from_gray(150)
    } else {
        Color32::from_gray(110)
    };
    scene.ground(&painter);
    for s in 0..2 {
        scene.building(&painter, s, column, plain, text);
    }
    if !gpu_bars.is_empty() {
        let vp = &scene.vp;
        let world = [vp.left, vp.right, vp.bottom, vp.top];
        let count = gpu_bars.len() as u32;
        vp.paint(
            ui,
            super::slots::BUILDING_VIEW,
            View::Bars,
            uniforms(world, t, count),
            gpu_bars,
            d.gpu.clone(),
        );
    }
    scene.contact_points(&painter);
    scene.captions(&painter, text);
}
