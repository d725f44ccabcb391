//! The x-t diagram as a PNG for slides and papers: both bars along x (bar 1 to the left of the
//! contact at x = 0, bar 2 to the right), time upward, every pixel coloured by the field with
//! the view's colour map; axes with units, a symmetric colour bar, a title.

use super::plot::{PlotError, write_png};
use crate::model::xt::{XtField, XtGrid};
use plotters::prelude::*;
use std::path::Path;

/// The view's diverging colour map as linear RGB in [0, 1]: compression (s < 0) blue, tension
/// red, stress-free pale grey; |s| = 1 saturates. `shaders/field.wgsl` has the same map for the
/// GPU; this is the one copy on the CPU (the window's legends and the GPU tests read it too).
pub fn diverging_linear(s: f64) -> [f64; 3] {
    let neutral = [0.90, 0.90, 0.88];
    let end = if s < 0.0 {
        [0.10, 0.30, 0.85]
    } else {
        [0.85, 0.15, 0.10]
    };
    let a = s.abs().clamp(0.0, 1.0).powf(0.7);
    [0, 1, 2].map(|i| neutral[i] + (end[i] - neutral[i]) * a)
}

/// [`diverging_linear`] as 8-bit channels.
pub fn diverging(s: f64) -> [u8; 3] {
    diverging_linear(s).map(|c| (c * 255.0).round() as u8)
}

/// A diagram to write.
pub struct XtImage<'a> {
    pub grid: &'a XtGrid,
    pub field: XtField,
    pub title: String,
    /// Pixel size.
    pub size: (u32, u32),
    /// Text and line size relative to the defaults.
    pub scale: f64,
    /// Sears zone lengths d to mark, per bar [m].
    pub zones_m: Option<[f64; 2]>,
}

impl XtImage<'_> {
    /// The field's value at a world point: x < 0 in bar 1 (its x_m = -x), x > 0 in bar 2; time
    /// t; `None` outside the bars. Nearest grid point.
    fn value_at(&self, x: f64, t: f64) -> Option<f64> {
        let g = self.grid;
        let (bar, xm) = if x < 0.0 { (0, -x) } else { (1, x) };
        let b = &g.bars[bar];
        let length = *b.x_m.last()?;
        if xm > length || g.times_s.len() < 2 {
            return None;
        }
        let (t0, t1) = (g.times_s[0], *g.times_s.last()?);
        let nt = g.times_s.len();
        let k = (((t - t0) / (t1 - t0)) * (nt - 1) as f64).round();
        let i = ((xm / length) * (b.x_m.len() - 1) as f64).round();
        if !(0.0..=(nt - 1) as f64).contains(&k) {
            return None;
        }
        Some(b.at(self.field, k as usize, i as usize))
    }

    /// Writes the PNG.
    pub fn write_png(&self, path: &Path) -> Result<(), PlotError> {
        super::plot::register_font();
        if let Some(parent) = path.parent().filter(|p| !p.as_os_str().is_empty()) {
            std::fs::create_dir_all(parent).map_err(|e| PlotError::Write {
                path: path.to_path_buf(),
                message: format!("cannot create its folder: {e}"),
            })?;
        }
        let rgb = self.pixels().map_err(|message| PlotError::Write {
            path: path.to_path_buf(),
            message,
        })?;
        write_png(path, self.size, png::ColorType::Rgb, &rgb).map_err(|e| PlotError::Write {
            path: path.to_path_buf(),
            message: e.to_string(),
        })
    }

    /// The image as 8-bit RGB.
    pub fn pixels(&self) -> Result<Vec<u8>, String> {
        let (w, h) = self.size;
        let mut rgb = vec![255u8; (w * h * 3) as usize];
        let k = self.scale.clamp(0.25, 8.0);
        let px = |v: f64| (v * k).round().max(1.0) as u32;
        let g = self.grid;
        let lengths = [0, 1].map(|b| g.bars[b].x_m.last().copied().unwrap_or(0.0));
        let (t0, t1) = (
            g.times_s.first().copied().unwrap_or(0.0),
            g.times_s.last().copied().unwrap_or(0.0),
        );
        let (x0, x1) = (-lengths[0], lengths[1]);
        let ms = |t: f64| t * 1e3;
        let peak = g.max_abs(self.field).max(f64::MIN_POSITIVE);
        let (unit, factor) = match self.field {
            XtField::Stress => ("MPa", 1e-6),
            XtField::Velocity => ("m/s", 1.0),
        };
        let bar_width = px(140.0);
        // Axes, labels and title by plotters; the field's pixels afterwards, inside the
        // plotting area plotters reports.
        let area_px;
        {
            let root = super::bitmap::Bitmap::with_buffer(&mut rgb, (w, h)).into_drawing_area();
            let (main, _) = root.split_horizontally(w.saturating_sub(bar_width));
            let mut chart = ChartBuilder::on(&main)
                .caption(&self.title, ("sans-serif", px(22.0)))
                .margin(px(14.0))
                .x_label_area_size(px(44.0))
                .y_label_area_size(px(70.0))
                .build_cartesian_2d(x0..x1, ms(t0)..ms(t1))
                .map_err(|e| e.to_string())?;
            chart
                .configure_mesh()
                .disable_mesh()
                .x_desc("position [m] (bar 1 | contact | bar 2)")
                .y_desc("time [ms]")
                .label_style(("sans-serif", px(14.0)))
                .axis_desc_style(("sans-serif", px(16.0)))
                .draw()
                .map_err(|e| e.to_string())?;
            area_px = chart.plotting_area().get_pixel_range();
            root.present().map_err(|e| e.to_string())?;
        }
        let (xr, yr) = area_px;
        let (pw, ph) = ((xr.end - xr.start).max(1), (yr.end - yr.start).max(1));
        for py in yr.clone() {
            // Row py: time upward.
            let t = t1 - (t1 - t0) * (py - yr.start) as f64 / ph as f64;
            for pxl in xr.clone() {
                let x = x0 + (x1 - x0) * (pxl - xr.start) as f64 / pw as f64;
                let colour = match self.value_at(x, t) {
                    Some(v) => diverging(v / peak),
                    None => [255, 255, 255],
                };
                let at = ((py as u32 * w + pxl as u32) * 3) as usize;
                if at + 3 <= rgb.len() {
                    rgb[at..at + 3].copy_from_slice(&colour);
                }
            }
        }
        // The contact (x = 0) and the zones d, as thin dark lines over the field.
        let column = |x: f64| xr.start + ((x - x0) / (x1 - x0) * pw as f64).round() as i32;
        let mut marks = vec![column(0.0)];
        if let Some(d) = self.zones_m {
            marks.extend([column(-d[0]), column(d[1])]);
        }
        for c in marks {
            for py in yr.clone() {
                let at = ((py as u32 * w + c.clamp(0, w as i32 - 1) as u32) * 3) as usize;
                if at + 3 <= rgb.len() {
                    rgb[at..at + 3].copy_from_slice(&[40, 40, 40]);
                }
            }
        }
        // The colour bar: top +peak, bottom -peak.
        let (bx0, bx1) = (w - bar_width + px(14.0), w - bar_width + px(32.0));
        for py in yr.clone() {
            let s = 1.0 - 2.0 * (py - yr.start) as f64 / ph as f64;
            for bx in bx0..bx1.min(w) {
                let at = ((py as u32 * w + bx) * 3) as usize;
                rgb[at..at + 3].copy_from_slice(&diverging(s));
            }
        }
        {
            let root = super::bitmap::Bitmap::with_buffer(&mut rgb, (w, h)).into_drawing_area();
            let style = ("sans-serif", px(13.0)).into_font().color(&BLACK);
            let label = |v: f64| format!("{:+.3}", v * factor);
            let (top, bottom, mid) = (yr.start, yr.end, (yr.start + yr.end) / 2);
            let tx = (bx1 + px(6.0)) as i32;
            let (pos, neg) = match self.field {
                XtField::Stress => ("tension", "compression"),
                XtField::Velocity => ("right", "left"),
            };
            for (y, text) in [
                (top, format!("{} {unit}", label(peak))),
                (top + px(16.0) as i32, pos.to_string()),
                (mid, format!("0 {unit}")),
                (bottom - px(32.0) as i32, neg.to_string()),
                (bottom - px(16.0) as i32, format!("{} {unit}", label(-peak))),
            ] {
                root.draw_text(&text, &style, (tx, y))
                    .map_err(|e| e.to_string())?;
            }
            let name = match self.field {
                XtField::Stress if g.uniform => "stress (uniform: F/A)",
                XtField::Stress => "axial stress",
                XtField::Velocity => "particle velocity",
            };
            root.draw_text(name, &style, (bx0 as i32, top - px(18.0) as i32))
                .map_err(|e| e.to_string())?;
            root.present().map_err(|e| e.to_string())?;
        }
        Ok(rgb)
    }
}
