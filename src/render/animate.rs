//! Frames of an impact's animation for slides: the bar view, the x-t diagram with its moving
//! time line, or both, drawn offscreen by the window's field pipelines; plotters adds the axes,
//! the time stamp and the colour bar with its units (the bundled font, no system fonts).

use super::bars::{BarsLayout, GpuHistory, View, XtShown, uniforms};
use super::offscreen::{FieldPart, Offscreen};
use crate::export::animation::{AnimationError, AnimationWriter};
use crate::model::impact::ImpactResult;
use crate::model::scenario::ImpactScenario;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// Which picture an impact animation shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AnimView {
    Bars,
    Xt,
    Both,
}

/// Tick labels' size on a 720-pixel-high frame: 14 px on a 960x540 slide, legible from the back
/// of a hall.
const TICK: f64 = 19.0;

impl AnimView {
    pub const NAMES: &str = "bars|xt|both";

    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "bars" => Some(AnimView::Bars),
            "xt" => Some(AnimView::Xt),
            "both" => Some(AnimView::Both),
            _ => None,
        }
    }
}

/// The world's height band the bar view shows around the bars (y 0.40 to 0.62).
const BARS_WORLD_Y: (f64, f64) = (0.30, 0.72);
/// The field panels' background (outside the bars): white, as on a slide.
const PAPER: [f64; 3] = [1.0, 1.0, 1.0];

/// A pixel rectangle: left, top, width, height.
pub type PixelRect = [u32; 4];

/// An impact's animation: what it shows, its frames' times and pixel size.
pub struct ImpactAnimation {
    pub title: String,
    pub view: AnimView,
    pub size: (u32, u32),
    pub frames: usize,
    /// Time of the first and the last frame [s].
    pub t_range: (f64, f64),
    layout: BarsLayout,
    history: GpuHistory,
}

impl ImpactAnimation {
    /// The bars of `result` (waves, or a lumped model's uniform-stress picture, as in the window)
    /// over the window's x-t span.
    pub fn new(
        sc: &ImpactScenario,
        result: &ImpactResult,
        title: String,
        view: AnimView,
        size: (u32, u32),
        frames: usize,
    ) -> Self {
        let span = result.view_span_s();
        let (history, layout) = match &result.waves {
            Some(w) => {
                let h = GpuHistory::from_waves(w);
                let l = BarsLayout::new(w, sc.approach_velocity_m_s(), &h);
                (h, l)
            }
            None => {
                let h = GpuHistory::uniform(result, 2000, span);
                let l = BarsLayout::uniform(sc, result, &h);
                (h, l)
            }
        };
        ImpactAnimation {
            title,
            view,
            size,
            frames: frames.max(2),
            t_range: (0.0, span),
            layout,
            history,
        }
    }

    /// Frame `k`'s time [s]: the range's ends at the first and the last frame.
    pub fn time(&self, k: usize) -> f64 {
        let (t0, t1) = self.t_range;
        t0 + (t1 - t0) * k as f64 / (self.frames - 1) as f64
    }

    /// The bars' geometry and colour scale.
    pub fn layout(&self) -> &BarsLayout {
        &self.layout
    }

    fn scale(&self) -> f64 {
        (self.size.1 as f64 / 720.0).clamp(0.3, 8.0)
    }

    fn px(&self, v: f64) -> u32 {
        (v * self.scale()).round().max(1.0) as u32
    }

    /// The pixel rectangles of the bar view and of the x-t diagram (those the view shows).
    pub fn panels(&self) -> (Option<PixelRect>, Option<PixelRect>) {
        let (w, h) = self.size;
        let (left, right, top, bottom) =
            (self.px(100.0), self.px(170.0), self.px(64.0), self.px(60.0));
        let width = w.saturating_sub(left + right).max(8);
        let height = h.saturating_sub(top + bottom).max(8);
        match self.view {
            AnimView::Bars => {
                let bh = (height * 2 / 5).max(8);
                (Some([left, top + (height - bh) / 2, width, bh]), None)
            }
            AnimView::Xt => (None, Some([left, top, width, height])),
            AnimView::Both => {
                let bh = (height / 4).max(8);
                let gap = bottom;
                let xh = height.saturating_sub(bh + gap).max(8);
                (
                    Some([left, top, width, bh]),
                    Some([left, top + bh + gap, width, xh]),
                )
            }
        }
    }

    /// The pixel column of world x in the bar view's rectangle (fractional: 0 at its left edge).
    pub fn bars_column(&self, x_world: f64) -> Option<f64> {
        let [x0, _, w, _] = self.panels().0?;
        let l = &self.layout;
        Some(x0 as f64 + (x_world - l.left) / (l.right - l.left) * w as f64)
    }

    /// Frame `k` as RGB rows, top first.
    pub fn frame(&self, target: &mut Offscreen, k: usize) -> Result<Vec<u8>, AnimationError> {
        let t = self.time(k);
        let fail = |message: String| AnimationError::Frame { index: k, message };
        let (bars_rect, xt_rect) = self.panels();
        let l = &self.layout;
        let xt = l.xt();
        let mut parts = vec![];
        if let Some(rect) = bars_rect {
            parts.push(FieldPart {
                rect,
                view: View::Bars,
                uniforms: uniforms([l.left, l.right, BARS_WORLD_Y.0, BARS_WORLD_Y.1], t, 2),
                bars: &l.bars,
                history: &self.history,
            });
        }
        if let Some(rect) = xt_rect {
            let (t0, t1) = self.t_range;
            parts.push(FieldPart {
                rect,
                view: View::Xt,
                uniforms: xt.xt_uniforms(t0, t1 - t0, XtShown::Stress),
                bars: &xt.bars,
                history: &self.history,
            });
        }
        let rgba = target
            .draw_fields(PAPER, &parts)
            .map_err(|e| fail(e.to_string()))?;
        let mut rgb: Vec<u8> = rgba
            .chunks_exact(4)
            .flat_map(|p| [p[0], p[1], p[2]])
            .collect();
        self.overlay(&mut rgb, t).map_err(fail)?;
        Ok(rgb)
    }

    /// Axes, title, time stamp, time line and colour bar over the fields.
    fn overlay(&self, rgb: &mut [u8], t: f64) -> Result<(), String> {
        crate::export::plot::register_font();
        let root = crate::export::bitmap::Bitmap::with_buffer(rgb, self.size).into_drawing_area();
        let (bars_rect, xt_rect) = self.panels();
        let l = &self.layout;
        let font = |size: f64| ("sans-serif", self.px(size)).into_font().color(&BLACK);
        let err = |e: &dyn std::fmt::Display| e.to_string();
        heading(
            &root,
            &|v| self.px(v),
            &self.title,
            &format!("t = {:.3} ms", t * 1e3),
        )?;
        let x_desc = if l.to_scale {
            "position [m] (bar 1 | contact | bar 2)"
        } else {
            "position / bar length (bar 1 | contact | bar 2)"
        };
        if let Some(rect) = bars_rect {
            let mut chart = self.chart(&root, rect, BARS_WORLD_Y)?;
            chart
                .configure_mesh()
                .disable_mesh()
                .disable_y_axis()
                .x_desc(if xt_rect.is_some() { "" } else { x_desc })
                .x_labels(8)
                .label_style(font(TICK))
                .axis_desc_style(font(TICK + 2.0))
                .draw()
                .map_err(|e| err(&e))?;
            let y = l.bars[0].y_top as f64 + 0.02;
            for (x, name) in [
                (-0.5 * (l.gap - l.left), "bar 1"),
                (0.5 * (l.right + l.gap), "bar 2"),
            ] {
                chart
                    .draw_series(std::iter::once(Text::new(
                        name,
                        (x, y + 0.05),
                        font(17.0).pos(plotters::style::text_anchor::Pos::new(
                            plotters::style::text_anchor::HPos::Center,
                            plotters::style::text_anchor::VPos::Bottom,
                        )),
                    )))
                    .map_err(|e| err(&e))?;
            }
        }
        if let Some(rect) = xt_rect {
            let (t0, t1) = self.t_range;
            let mut chart = self.chart(&root, rect, (t0 * 1e3, t1 * 1e3))?;
            chart
                .configure_mesh()
                .disable_mesh()
                .x_desc(x_desc)
                .y_desc("time [ms]")
                .x_labels(8)
                .label_style(font(TICK))
                .axis_desc_style(font(TICK + 2.0))
                .draw()
                .map_err(|e| err(&e))?;
            // The moving time line: black over a white halo, visible on any colour.
            let tm = t * 1e3;
            let dy = (t1 - t0) * 1e3 / rect[3] as f64;
            for (off, colour, width) in [(0.0, WHITE, 5.0), (0.0, BLACK, 2.0)] {
                chart
                    .draw_series(LineSeries::new(
                        [(l.left, tm + off * dy), (l.right, tm + off * dy)],
                        colour.stroke_width(self.px(width)),
                    ))
                    .map_err(|e| err(&e))?;
            }
        }
        let span = xt_rect.or(bars_rect).ok_or("no panel")?;
        let top = bars_rect.unwrap_or(span)[1];
        let peak = self.layout.stress_scale_pa * 1e-6;
        colour_bar(
            &root,
            &|v| self.px(v),
            [top, span[1] + span[3]],
            "axial stress",
            [format!("{peak:+.3} MPa"), format!("{:+.3} MPa", -peak)],
        )?;
        root.present().map_err(|e| err(&e))
    }

    /// A chart whose plotting area is exactly `rect`, x over the world's [left, right].
    fn chart<'a, 'b>(
        &self,
        root: &'a DrawingArea<crate::export::bitmap::Bitmap<'b>, Shift>,
        rect: PixelRect,
        y: (f64, f64),
    ) -> Result<
        ChartContext<
            'a,
            crate::export::bitmap::Bitmap<'b>,
            Cartesian2d<
                plotters::coord::types::RangedCoordf64,
                plotters::coord::types::RangedCoordf64,
            >,
        >,
        String,
    > {
        let [x, top, w, h] = rect;
        let (left_labels, bottom_labels) = (self.px(96.0), self.px(56.0));
        let (width, height) = self.size;
        ChartBuilder::on(root)
            .margin_left(x.saturating_sub(left_labels))
            .margin_top(top)
            .margin_right(width.saturating_sub(x + w))
            .margin_bottom(height.saturating_sub(top + h + bottom_labels))
            .y_label_area_size(left_labels)
            .x_label_area_size(bottom_labels)
            .build_cartesian_2d(self.layout.left..self.layout.right, y.0..y.1)
            .map_err(|e| e.to_string())
    }

    /// Renders every frame into `path` (GIF, or APNG for .png) at `fps`; `progress` hears each
    /// frame written.
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

/// The title (top left) and the time stamp (top right, large) of a frame.
pub(crate) fn heading(
    root: &DrawingArea<crate::export::bitmap::Bitmap<'_>, Shift>,
    px: &dyn Fn(f64) -> u32,
    title: &str,
    stamp: &str,
) -> Result<(), String> {
    use plotters::style::text_anchor::{HPos, Pos, VPos};
    let font = |size: f64| ("sans-serif", px(size)).into_font().color(&BLACK);
    root.draw_text(title, &font(24.0), (px(16.0) as i32, px(14.0) as i32))
        .map_err(|e| e.to_string())?;
    let width = root.dim_in_pixel().0;
    root.draw_text(
        stamp,
        &font(28.0).pos(Pos::new(HPos::Right, VPos::Top)),
        ((width - px(16.0)) as i32, px(12.0) as i32),
    )
    .map_err(|e| e.to_string())
}

/// The colour bar at the right edge, from `top` to `bottom` (pixels): `ends` label the
/// values that saturate the map (tension at the top, compression at the bottom).
pub(crate) fn colour_bar(
    root: &DrawingArea<crate::export::bitmap::Bitmap<'_>, Shift>,
    px: &dyn Fn(f64) -> u32,
    [top, bottom]: [u32; 2],
    name: &str,
    ends: [String; 2],
) -> Result<(), String> {
    let err = |e: &dyn std::fmt::Display| e.to_string();
    let x0 = (root.dim_in_pixel().0 - px(150.0)) as i32;
    let x1 = x0 + px(22.0) as i32;
    let (top, bottom) = (top as i32 + px(26.0) as i32, bottom as i32);
    let n = (bottom - top).max(1);
    for y in top..bottom {
        let s = 1.0 - 2.0 * (y - top) as f64 / n as f64;
        let [r, g, b] = crate::export::xt::diverging(s);
        root.draw(&Rectangle::new(
            [(x0, y), (x1, y + 1)],
            RGBColor(r, g, b).filled(),
        ))
        .map_err(|e| err(&e))?;
    }
    root.draw(&Rectangle::new(
        [(x0, top), (x1, bottom)],
        BLACK.stroke_width(1),
    ))
    .map_err(|e| err(&e))?;
    let font = ("sans-serif", px(TICK)).into_font().color(&BLACK);
    let tx = x1 + px(6.0) as i32;
    let line = px(17.0) as i32;
    let mid = (top + bottom) / 2;
    let [high, low] = ends;
    for (y, text) in [
        (top, high),
        (top + line, "tension".to_string()),
        (mid - line / 2, "0".to_string()),
        (bottom - 2 * line, "compression".to_string()),
        (bottom - line, low),
    ] {
        root.draw_text(&text, &font, (tx, y)).map_err(|e| err(&e))?;
    }
    root.draw_text(name, &font, (x0, top - px(24.0) as i32))
        .map_err(|e| err(&e))
}

/// Renders `frames` frames with `frame` and writes them; the GIF palette learns from the
/// first, middle and last frames.
pub fn write_frames(
    frames: usize,
    size: (u32, u32),
    path: &Path,
    fps: f64,
    progress: &mut dyn FnMut(usize),
    frame: &mut dyn FnMut(usize) -> Result<Vec<u8>, AnimationError>,
) -> Result<(), AnimationError> {
    crate::export::animation::check_timing(frames, fps)?;
    let samples = if crate::export::animation::AnimationFormat::of_path(path)?
        == crate::export::animation::AnimationFormat::Gif
    {
        let mut samples = [0, frames / 2, frames - 1]
            .iter()
            .map(|&k| frame(k))
            .collect::<Result<Vec<_>, _>>()?;
        samples.push(colour_map_ramp(size));
        samples
    } else {
        vec![]
    };
    let mut writer = AnimationWriter::create(path, size, frames, fps, &samples)?;
    for k in 0..frames {
        writer.push(&frame(k)?)?;
        progress(k + 1);
    }
    writer.finish()
}

/// Every colour of the field's map (and its darker shade in a Sears zone), as a frame-sized
/// sample: taught to the GIF palette beside the frames, it keeps smooth stress gradients from
/// banding even when the sampled frames hold few of them.
fn colour_map_ramp((w, h): (u32, u32)) -> Vec<u8> {
    let n = (w * h) as usize;
    (0..n)
        .flat_map(|i| {
            let s = 2.0 * (i % 512) as f64 / 511.0 - 1.0;
            let dim = if (i / 512) % 2 == 1 { 0.8 } else { 1.0 };
            crate::export::xt::diverging_linear(s).map(|c| (c * dim * 255.0).round() as u8)
        })
        .collect()
}
