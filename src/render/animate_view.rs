//! Frames of a scene the window draws in one rectangle (two buildings swaying and pounding, a
//! bridge in elevation), for slides: the window's own drawing (egui shapes and the stress waves
//! on the GPU) rendered offscreen through egui's wgpu renderer, with a heading and the colour
//! bar; the drawing carries its own time stamp.

use super::animate::{PixelRect, colour_bar, heading, write_frames};
use super::offscreen::Offscreen;
use crate::export::animation::AnimationError;
use eframe::egui;
use plotters::prelude::*;
use std::path::Path;

/// A run as the window draws it: at time `t`, its displacements `exaggeration` times their size.
pub trait SceneView {
    fn draw(&self, ui: &mut egui::Ui, rect: egui::Rect, t: f64, exaggeration: f64);
    /// The run's end [s].
    fn end_s(&self) -> f64;
    /// The colour bar's label and the labels of its two ends (tension first).
    fn colour_bar(&self) -> (&'static str, [String; 2]);
}

/// The animation of one run.
pub struct ViewAnimation<D> {
    pub title: String,
    pub size: (u32, u32),
    pub frames: usize,
    /// Time of the first and the last frame [s].
    pub t_range: (f64, f64),
    /// Displacements drawn this many times their size (the window's slider).
    pub exaggeration: f64,
    drawing: D,
    ctx: egui::Context,
}

impl<D: SceneView> ViewAnimation<D> {
    /// Over the whole run, displacements exaggerated 20 times (the window's default).
    pub fn of(drawing: D, title: String, size: (u32, u32), frames: usize) -> Self {
        let ctx = egui::Context::default();
        ctx.set_visuals(egui::Visuals::light());
        ViewAnimation {
            title,
            size,
            frames: frames.max(2),
            t_range: (0.0, drawing.end_s()),
            exaggeration: 20.0,
            drawing,
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

    /// The pixel rectangle the scene is drawn in.
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
                self.drawing.draw(ui, rect, t, self.exaggeration)
            })
            .map_err(|e| fail(e.to_string()))?;
        let mut rgb: Vec<u8> = rgba
            .chunks_exact(4)
            .flat_map(|p| [p[0], p[1], p[2]])
            .collect();
        self.overlay(&mut rgb).map_err(fail)?;
        Ok(rgb)
    }

    /// The heading (the drawing carries the time stamp) and the colour bar.
    fn overlay(&self, rgb: &mut [u8]) -> Result<(), String> {
        crate::export::plot::register_font();
        let root = crate::export::bitmap::Bitmap::with_buffer(rgb, self.size).into_drawing_area();
        let px = |v: f64| self.px(v);
        heading(&root, &px, &self.title, "")?;
        let (label, ends) = self.drawing.colour_bar();
        let [_, top, _, h] = self.panel();
        colour_bar(&root, &px, [top, top + h * 3 / 4], label, ends)?;
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
