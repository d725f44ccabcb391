//! Frames of two buildings swaying and pounding, for slides: the window's own drawing of them
//! (`app::building_view::draw`, egui shapes and the slabs' stress waves on the GPU) rendered
//! offscreen through egui's wgpu renderer, with a heading, a time stamp and the colour bar.

use super::animate::{PixelRect, colour_bar, heading, write_frames};
use super::offscreen::Offscreen;
use crate::app::building_view::{self, BuildingDrawing};
use crate::export::animation::AnimationError;
use crate::io::building_settings::BuildingSetup;
use crate::model::building::BuildingResult;
use crate::model::motion::GroundMotion;
use eframe::egui;
use plotters::prelude::*;
use std::path::Path;

/// The animation of one building run.
pub struct BuildingAnimation {
    pub title: String,
    pub size: (u32, u32),
    pub frames: usize,
    /// Time of the first and the last frame [s].
    pub t_range: (f64, f64),
    /// Drift drawn this many times its size (the window's slider).
    pub exaggeration: f64,
    drawing: BuildingDrawing,
    ctx: egui::Context,
}

impl BuildingAnimation {
    /// Over the whole run, drift exaggerated 20 times (the window's default).
    pub fn new(
        setup: BuildingSetup,
        motion: GroundMotion,
        result: BuildingResult,
        title: String,
        size: (u32, u32),
        frames: usize,
    ) -> Self {
        let end = result.time_s.last().copied().unwrap_or(0.0);
        let ctx = egui::Context::default();
        ctx.set_visuals(egui::Visuals::light());
        BuildingAnimation {
            title,
            size,
            frames: frames.max(2),
            t_range: (0.0, end),
            exaggeration: 20.0,
            drawing: BuildingDrawing::new(setup, motion, result),
            ctx,
        }
    }

    pub fn time(&self, k: usize) -> f64 {
        let (t0, t1) = self.t_range;
        t0 + (t1 - t0) * k as f64 / (self.frames - 1) as f64
    }

    fn px(&self, v: f64) -> u32 {
        (v * (self.size.1 as f64 / 720.0).clamp(0.3, 8.0))
            .round()
            .max(1.0) as u32
    }

    /// The pixel rectangle the buildings are drawn in.
    pub fn panel(&self) -> PixelRect {
        let (w, h) = self.size;
        let (top, right) = (self.px(56.0), self.px(170.0));
        [0, top, w.saturating_sub(right), h.saturating_sub(top)]
    }

    /// Frame `k` as RGB rows, top first.
    pub fn frame(&self, target: &mut Offscreen, k: usize) -> Result<Vec<u8>, AnimationError> {
        let t = self.time(k);
        let fail = |message: String| AnimationError::Frame { index: k, message };
        // Text as large on a 720-pixel-high frame as in a window at 150 %.
        let ppp = 1.5 * self.size.1 as f32 / 720.0;
        let [x, y, w, h] = self.panel().map(|v| v as f32 / ppp);
        let rect = egui::Rect::from_min_size(egui::pos2(x, y), egui::vec2(w, h));
        let rgba = target
            .draw_egui(&self.ctx, [1.0; 3], ppp, |ui| {
                building_view::draw(ui, rect, &self.drawing, t, self.exaggeration)
            })
            .map_err(|e| fail(e.to_string()))?;
        let mut rgb: Vec<u8> = rgba
            .chunks_exact(4)
            .flat_map(|p| [p[0], p[1], p[2]])
            .collect();
        self.overlay(&mut rgb, t).map_err(fail)?;
        Ok(rgb)
    }

    fn overlay(&self, rgb: &mut [u8], t: f64) -> Result<(), String> {
        crate::export::plot::register_font();
        let root = crate::export::bitmap::Bitmap::with_buffer(rgb, self.size).into_drawing_area();
        let px = |v: f64| self.px(v);
        // The buildings' own drawing carries the time stamp: the heading only the title.
        let _ = t;
        heading(&root, &px, &self.title, "")?;
        // The slabs' colour saturates at the run's peak pounding force over the slab's area.
        let sc = &self.drawing.setup.scenario;
        let areas: Vec<f64> = [&sc.left, &sc.right]
            .iter()
            .flat_map(|b| (0..b.storeys).map(|j| b.slab(j).area_m2()))
            .collect();
        let (lo, hi) = areas
            .iter()
            .fold((f64::INFINITY, 0.0f64), |(a, b), &v| (a.min(v), b.max(v)));
        let force = self.drawing.result.max_pounding_force_n.max(1.0);
        let ends = if hi > 0.0 && (hi - lo) <= 1e-9 * hi {
            let peak = force / hi * 1e-6;
            [format!("{peak:+.3} MPa"), format!("{:+.3} MPa", -peak)]
        } else {
            ["+ peak F / A".to_string(), "- peak F / A".to_string()]
        };
        let [_, top, _, h] = self.panel();
        colour_bar(&root, &px, [top, top + h * 3 / 4], "slab stress", ends)?;
        root.present().map_err(|e| e.to_string())
    }

    /// Renders every frame into `path` (GIF, or APNG for .png) at `fps`.
    pub fn write(
        &self,
        target: &mut Offscreen,
        path: &Path,
        fps: f64,
        progress: &mut dyn FnMut(usize),
    ) -> Result<(), AnimationError> {
        write_frames(self.frames, self.size, path, fps, progress, &mut |k| {
            self.frame(target, k)
        })
    }
}
