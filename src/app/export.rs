//! Exports from the window: a plot as PNG, SVG or CSV with exactly what it shows (the same
//! series, the visible range), and screenshots. Files are written on a thread of their own, so an
//! export never blocks the window; the outcome comes back as a message.

use crate::export::plot::{LinePlot, Series};
use eframe::egui;
use std::path::PathBuf;
use std::sync::mpsc::{Receiver, Sender, channel};

/// What a plot shows, kept from its last frame.
#[derive(Clone, Default)]
pub struct ShownPlot {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub series: Vec<(String, Vec<[f64; 2]>)>,
    /// Visible x and y ranges.
    pub bounds: Option<([f64; 2], [f64; 2])>,
}

impl ShownPlot {
    fn visible(&self) -> Vec<Series> {
        let (x0, x1) = self
            .bounds
            .map_or((f64::NEG_INFINITY, f64::INFINITY), |(min, max)| {
                (min[0], max[0])
            });
        self.series
            .iter()
            .map(|(name, pts)| Series {
                name: name.clone(),
                points: pts
                    .iter()
                    .filter(|p| p[0] >= x0 && p[0] <= x1)
                    .map(|p| (p[0], p[1]))
                    .collect(),
            })
            .collect()
    }

    fn csv(&self) -> String {
        // One block per series: x, y, with the axis labels (which carry the units) as the header.
        let mut out = String::new();
        for s in self.visible() {
            out += &format!("# {}\n{},{}\n", s.name, self.x_label, self.y_label);
            for (x, y) in s.points {
                out += &format!("{x:.12e},{y:.12e}\n");
            }
        }
        out
    }
}

pub struct Exporter {
    /// Path prefix for exported files (a folder and a name stem).
    pub prefix: String,
    /// Pixel size of PNG exports.
    pub size: [u32; 2],
    /// Text and line scale of plot exports.
    pub scale: f64,
    /// File > Export animation's choices.
    pub animation: super::export_animation::AnimationSettings,
    done_tx: Sender<Result<String, String>>,
    done_rx: Receiver<Result<String, String>>,
}

impl Default for Exporter {
    fn default() -> Self {
        let (done_tx, done_rx) = channel();
        Exporter {
            prefix: "pounding".into(),
            size: [1600, 900],
            scale: 1.0,
            animation: Default::default(),
            done_tx,
            done_rx,
        }
    }
}

impl Exporter {
    pub(super) fn spawn(&self, job: impl FnOnce() -> Result<String, String> + Send + 'static) {
        let tx = self.done_tx.clone();
        std::thread::spawn(move || {
            let _ = tx.send(job());
        });
    }

    /// Writes `plot` as `<prefix>-<name>.<ext>` (png, svg or csv).
    pub fn export(&self, plot: &ShownPlot, name: &str, ext: &str) {
        let path = PathBuf::from(format!("{}-{name}.{ext}", self.prefix));
        let plot = plot.clone();
        let size = (self.size[0], self.size[1]);
        let scale = self.scale;
        let is_csv = ext == "csv";
        self.spawn(move || {
            let shown = path.display().to_string();
            let result = if is_csv {
                std::fs::write(&path, plot.csv())
                    .map_err(|e| format!("could not write {shown}: {e}"))
            } else {
                LinePlot {
                    size,
                    scale,
                    x_range: plot.bounds.map(|(a, b)| (a[0], b[0])),
                    y_range: plot.bounds.map(|(a, b)| (a[1], b[1])),
                    ..LinePlot::new(
                        plot.title.clone(),
                        plot.x_label.clone(),
                        plot.y_label.clone(),
                        plot.visible(),
                    )
                }
                .write(&path)
                .map_err(|e| format!("could not write {e:#}"))
            };
            result.map(|()| format!("wrote {shown}"))
        });
    }

    /// Asks for a screenshot of the window, or of its part `crop` (in points), saved as PNG.
    pub fn screenshot(&self, ctx: &egui::Context, crop: Option<egui::Rect>, name: &str) {
        self.screenshot_to(
            ctx,
            crop,
            PathBuf::from(format!("{}-{name}.png", self.prefix)),
        );
    }

    /// As `screenshot`, to a given path.
    pub fn screenshot_to(&self, ctx: &egui::Context, crop: Option<egui::Rect>, path: PathBuf) {
        let tx = self.done_tx.clone();
        let pixels_per_point = ctx.pixels_per_point();
        ctx.request_screenshot(move |image| {
            std::thread::spawn(move || {
                let _ = tx.send(write_png(&image, crop, pixels_per_point, &path));
            });
        });
    }

    /// The outcome of finished exports, if any.
    pub fn poll(&self) -> Option<Result<String, String>> {
        self.done_rx.try_recv().ok()
    }

    /// Export buttons for one plot.
    pub fn buttons(&self, ui: &mut egui::Ui, plot: &ShownPlot, name: &str) {
        // A class looks at the plot; File > Export every plot writes what a lecturer prepares.
        if super::lecture::on(ui.ctx()) {
            return;
        }
        ui.horizontal(|ui| {
            ui.label(format!("export {name}:")).on_hover_text(format!(
                "writes {}-{name}.png/.svg/.csv with what the plot shows",
                self.prefix
            ));
            for ext in ["png", "svg", "csv"] {
                if ui.small_button(ext).clicked() {
                    self.export(plot, name, ext);
                }
            }
        });
    }
}

/// What an x-t diagram exports: the run and how the window shows it. The grid and the image are
/// made on the export thread, from a copy of the run taken when the button is pressed.
pub struct XtExport<'a> {
    pub result: &'a crate::model::impact::ImpactResult,
    pub areas_m2: [f64; 2],
    pub lengths_m: [f64; 2],
    pub t_end: f64,
    pub field: crate::model::xt::XtField,
    pub zones_m: Option<[f64; 2]>,
    pub title: String,
}

impl Exporter {
    /// `png` and `csv` buttons for an x-t diagram: the image (the same colour map, axes, colour
    /// bar) at the export size and scale, and the grid (200 x 400 points, the command line's
    /// `bar,x_m,t_s,stress_pa,velocity_m_s` rows).
    pub fn xt_buttons(&self, ui: &mut egui::Ui, xt: &XtExport, name: &str) {
        if super::lecture::on(ui.ctx()) {
            return;
        }
        ui.horizontal(|ui| {
            ui.label(format!("export {name}:")).on_hover_text(format!(
                "writes {}-{name}.png (the diagram) or .csv (its grid)",
                self.prefix
            ));
            for ext in ["png", "csv"] {
                if !ui.small_button(ext).clicked() {
                    continue;
                }
                let path = PathBuf::from(format!("{}-{name}.{ext}", self.prefix));
                let result = xt.result.clone();
                let (areas, lengths, t_end, field) =
                    (xt.areas_m2, xt.lengths_m, xt.t_end, xt.field);
                let (zones, title) = (xt.zones_m, xt.title.clone());
                let (size, scale) = ((self.size[0], self.size[1]), self.scale);
                let csv = ext == "csv";
                self.spawn(move || {
                    let shown = path.display().to_string();
                    let grid =
                        crate::model::xt::XtGrid::of(&result, areas, lengths, 200, 400, t_end);
                    let written = if csv {
                        std::fs::File::create(&path)
                            .and_then(|f| {
                                let mut w = std::io::BufWriter::new(f);
                                crate::io::csv::write_xt(&mut w, &grid)
                            })
                            .map_err(|e| format!("could not write {shown}: {e}"))
                    } else {
                        crate::export::xt::XtImage {
                            grid: &grid,
                            field,
                            title,
                            size,
                            scale,
                            zones_m: zones,
                        }
                        .write_png(&path)
                        .map_err(|e| format!("could not write {e}"))
                    };
                    written.map(|()| format!("wrote {shown}"))
                });
            }
        });
    }
}

/// Encodes (a part of) a screenshot as PNG.
fn write_png(
    image: &egui::ColorImage,
    crop: Option<egui::Rect>,
    pixels_per_point: f32,
    path: &std::path::Path,
) -> Result<String, String> {
    let shown = path.display().to_string();
    let [w, h] = image.size;
    let (x0, y0, x1, y1) = match crop {
        Some(r) => (
            ((r.min.x * pixels_per_point) as usize).min(w),
            ((r.min.y * pixels_per_point) as usize).min(h),
            ((r.max.x * pixels_per_point) as usize).min(w),
            ((r.max.y * pixels_per_point) as usize).min(h),
        ),
        None => (0, 0, w, h),
    };
    let (cw, ch) = (x1.saturating_sub(x0), y1.saturating_sub(y0));
    if cw == 0 || ch == 0 {
        return Err(format!("could not write {shown}: empty region"));
    }
    let mut rgba = Vec::with_capacity(cw * ch * 4);
    for y in y0..y1 {
        for px in &image.pixels[y * w + x0..y * w + x1] {
            rgba.extend_from_slice(&px.to_array());
        }
    }
    crate::export::plot::write_png(path, (cw as u32, ch as u32), png::ColorType::Rgba, &rgba)
        .map(|()| format!("wrote {shown}"))
        .map_err(|e| format!("could not write {shown}: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shown() -> ShownPlot {
        ShownPlot {
            title: "t".into(),
            x_label: "time [ms]".into(),
            y_label: "force [kN]".into(),
            series: vec![(
                "a".into(),
                (0..10).map(|i| [i as f64, 2.0 * i as f64]).collect(),
            )],
            bounds: Some(([2.5, -1.0], [6.0, 30.0])),
        }
    }

    #[test]
    fn an_export_holds_the_visible_x_range_only() {
        let v = shown().visible();
        let xs: Vec<f64> = v[0].points.iter().map(|p| p.0).collect();
        assert_eq!(xs, vec![3.0, 4.0, 5.0, 6.0]);
    }

    #[test]
    fn csv_names_quantities_and_units_then_rows_of_the_visible_points() {
        let csv = shown().csv();
        let mut lines = csv.lines();
        assert_eq!(lines.next(), Some("# a"));
        assert_eq!(lines.next(), Some("time [ms],force [kN]"));
        let rows: Vec<_> = lines.collect();
        assert_eq!(rows.len(), 4);
        let first: Vec<f64> = rows[0].split(',').map(|v| v.parse().unwrap()).collect();
        assert_eq!(first, vec![3.0, 6.0]);
    }

    #[test]
    fn a_failed_write_says_which_path() {
        let e = Exporter {
            prefix: "/dev/null/inside-a-file/x".into(),
            ..Default::default()
        };
        e.export(&shown(), "force", "csv");
        let outcome = e
            .done_rx
            .recv_timeout(std::time::Duration::from_secs(10))
            .unwrap();
        let err = outcome.unwrap_err();
        assert!(err.contains("/dev/null/inside-a-file/x-force.csv"), "{err}");
    }
}
