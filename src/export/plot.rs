//! A line plot written as SVG or PNG (chosen by the file's extension), with plotters. Text goes
//! through ab_glyph with a bundled font, so no system font configuration is needed.

use plotters::prelude::*;
use std::path::Path;
use std::sync::Once;

/// One series: its legend name and points.
#[derive(Clone, Debug)]
pub struct Series {
    pub name: String,
    pub points: Vec<(f64, f64)>,
}

#[derive(Clone, Debug)]
pub struct LinePlot {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub log_x: bool,
    pub log_y: bool,
    pub series: Vec<Series>,
    /// Pixel size.
    pub size: (u32, u32),
    /// A dot at each point (for a few points, like a ladder's rungs).
    pub markers: bool,
    /// Text and line size relative to the defaults (2 for print at twice the density).
    pub scale: f64,
    /// Axis ranges (what a window shows); `None` fits the data.
    pub x_range: Option<(f64, f64)>,
    pub y_range: Option<(f64, f64)>,
}

/// A plot that could not be written.
#[derive(Debug, thiserror::Error)]
pub enum PlotError {
    #[error("{}: the plot's extension must be .svg or .png", .0.display())]
    Extension(std::path::PathBuf),
    #[error("{}: {message}", path.display())]
    Write {
        path: std::path::PathBuf,
        message: String,
    },
}

/// Why drawing or encoding failed, before the path is attached.
#[derive(Debug, thiserror::Error)]
enum Failure {
    #[error("{0}")]
    Draw(String),
    #[error(transparent)]
    Encode(#[from] png::EncodingError),
}

/// plotters' errors are generic over the backend: their text is what a user can act on.
fn draw_failed(e: impl std::fmt::Display) -> Failure {
    Failure::Draw(e.to_string())
}

static FONT: Once = Once::new();

pub(crate) fn register_font() {
    FONT.call_once(|| {
        // The font egui ships (Ubuntu Light, Ubuntu Font Licence), registered for plotters.
        let _ = plotters::style::register_font(
            "sans-serif",
            FontStyle::Normal,
            epaint_default_fonts::UBUNTU_LIGHT,
        );
    });
}

const PALETTE: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(23, 190, 207),
];

/// An RGB image `k` times smaller, each pixel the mean of its k x k block.
fn downsample(rgb: &[u8], (w, h): (u32, u32), k: u32) -> Vec<u8> {
    if k == 1 {
        return rgb.to_vec();
    }
    let (ow, oh) = (w / k, h / k);
    let mut out = vec![0u8; (ow * oh * 3) as usize];
    for y in 0..oh {
        for x in 0..ow {
            for c in 0..3 {
                let mut sum = 0u32;
                for dy in 0..k {
                    for dx in 0..k {
                        let i = (((y * k + dy) * w + x * k + dx) * 3 + c) as usize;
                        sum += u32::from(rgb[i]);
                    }
                }
                out[((y * ow + x) * 3 + c) as usize] = ((sum + k * k / 2) / (k * k)) as u8;
            }
        }
    }
    out
}

/// A tick label: three significant digits, exponent form outside [1e-3, 1e4).
pub fn tick_label(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return "0".into();
    }
    if !(1e-3..1e4).contains(&x.abs()) {
        return format!("{x:.2e}");
    }
    let decimals = (2 - x.abs().log10().floor() as i32).max(0) as usize;
    let text = format!("{x:.decimals$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}

/// Whether values asked for on a logarithmic axis get one: only where they span a decade or more
/// (over less, a log axis has one or two labelled ticks and reads worse than a linear one).
pub fn log_axis_pays(log: bool, values: impl Iterator<Item = f64>) -> bool {
    if !log {
        return false;
    }
    let (lo, hi) = values
        .filter(|v| v.is_finite() && *v > 0.0)
        .fold((f64::INFINITY, 0.0f64), |(a, b), v| (a.min(v), b.max(v)));
    lo.is_finite() && hi >= 10.0 * lo
}

impl LinePlot {
    /// A linear-axes plot of 1000 x 600 pixels at scale 1, fitted to its data.
    pub fn new(
        title: impl Into<String>,
        x_label: impl Into<String>,
        y_label: impl Into<String>,
        series: Vec<Series>,
    ) -> Self {
        LinePlot {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            log_x: false,
            log_y: false,
            series,
            size: (1000, 600),
            markers: false,
            scale: 1.0,
            x_range: None,
            y_range: None,
        }
    }

    /// Writes the plot; the extension picks the format (`.svg` or `.png`).
    pub fn write(&self, path: &Path) -> Result<(), PlotError> {
        register_font();
        let ext = super::extension(path);
        match ext.as_str() {
            "svg" | "png" => {}
            _ => return Err(PlotError::Extension(path.to_path_buf())),
        }
        // A plot asked for in a folder that does not exist yet gets the folder.
        if let Some(parent) = path.parent().filter(|p| !p.as_os_str().is_empty()) {
            std::fs::create_dir_all(parent).map_err(|e| PlotError::Write {
                path: path.to_path_buf(),
                message: format!("cannot create its folder: {e}"),
            })?;
        }
        match ext.as_str() {
            "svg" => self.draw(SVGBackend::new(path, self.size).into_drawing_area()),
            _ => self.write_png(path),
        }
        .map_err(|e| PlotError::Write {
            path: path.to_path_buf(),
            message: e.to_string(),
        })
    }

    /// PNG through a pixel buffer and the png crate (plotters' own encoder brings a second
    /// image crate along).
    ///
    /// Drawn at twice the size and averaged down (where that fits in a few tens of megabytes):
    /// plotters' bitmap draws lines and glyph positions without anti-aliasing, so a curve is
    /// jagged and a glyph's advance rounds to whole pixels ("tim e") at the size asked for.
    fn write_png(&self, path: &Path) -> Result<(), Failure> {
        let (w, h) = self.size;
        let k = if u64::from(w) * u64::from(h) <= 4_000_000 && self.scale <= 4.0 {
            2
        } else {
            1
        };
        let big = LinePlot {
            size: (w * k, h * k),
            scale: self.scale * f64::from(k),
            ..self.clone()
        };
        let mut rgb = vec![255u8; (w * k * h * k * 3) as usize];
        big.draw(super::bitmap::Bitmap::with_buffer(&mut rgb, big.size).into_drawing_area())?;
        let rgb = downsample(&rgb, (w * k, h * k), k);
        write_png(path, (w, h), png::ColorType::Rgb, &rgb)?;
        Ok(())
    }

    fn range(&self, log: bool, pick: impl Fn(&(f64, f64)) -> f64) -> (f64, f64) {
        let values = self
            .series
            .iter()
            .flat_map(|s| s.points.iter().map(&pick))
            .filter(|v| v.is_finite() && (!log || *v > 0.0));
        let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
        if !lo.is_finite() {
            return if log { (1e-12, 1.0) } else { (0.0, 1.0) };
        }
        if log {
            // From a power of ten: the axis's ticks run upwards from one (1, 2, ..., 9 times
            // it), and a first decade without one would have no labels.
            (10f64.powf((lo / 1.5).log10().floor()), hi * 1.5)
        } else {
            let pad = 0.05 * (hi - lo).max(hi.abs().max(1e-300) * 1e-9);
            (lo - pad, hi + pad)
        }
    }

    fn draw<DB: DrawingBackend>(
        &self,
        area: DrawingArea<DB, plotters::coord::Shift>,
    ) -> Result<(), Failure>
    where
        DB::ErrorType: 'static,
    {
        area.fill(&WHITE).map_err(draw_failed)?;
        let points = || self.series.iter().flat_map(|s| s.points.iter());
        let log_x = log_axis_pays(self.log_x, points().map(|p| p.0));
        let log_y = log_axis_pays(self.log_y, points().map(|p| p.1));
        let (x0, x1) = self.x_range.unwrap_or_else(|| self.range(log_x, |p| p.0));
        let (y0, y1) = self.y_range.unwrap_or_else(|| self.range(log_y, |p| p.1));
        let k = self.scale.clamp(0.25, 8.0);
        let px = |v: f64| (v * k).round().max(1.0) as u32;
        let mut builder = ChartBuilder::on(&area);
        builder
            .caption(&self.title, ("sans-serif", px(22.0)))
            .margin(px(14.0))
            .x_label_area_size(px(44.0))
            .y_label_area_size(px(70.0));
        macro_rules! finish {
            ($chart:expr) => {{
                let mut chart = $chart;
                let tick = |log: bool| {
                    move |v: &f64| {
                        if log {
                            tick_label(*v)
                        } else {
                            format!("{}", (v * 1e6).round() / 1e6)
                        }
                    }
                };
                chart
                    .configure_mesh()
                    .x_desc(self.x_label.as_str())
                    .y_desc(self.y_label.as_str())
                    .x_label_formatter(&tick(log_x))
                    .y_label_formatter(&tick(log_y))
                    .label_style(("sans-serif", px(14.0)))
                    .axis_desc_style(("sans-serif", px(16.0)))
                    .draw()
                    .map_err(draw_failed)?;
                for (i, s) in self.series.iter().enumerate() {
                    // A model's curve keeps its colour in every figure.
                    let colour = super::palette::style_of(&s.name)
                        .map_or(PALETTE[i % PALETTE.len()], |st| {
                            RGBColor(st.rgb[0], st.rgb[1], st.rgb[2])
                        });
                    let pts: Vec<(f64, f64)> = s
                        .points
                        .iter()
                        .copied()
                        .filter(|(x, y)| {
                            x.is_finite()
                                && y.is_finite()
                                && (!log_x || *x > 0.0)
                                && (!log_y || *y > 0.0)
                        })
                        .collect();
                    chart
                        .draw_series(LineSeries::new(pts.clone(), colour.stroke_width(px(2.0))))
                        .map_err(draw_failed)?
                        .label(s.name.as_str())
                        .legend(move |(x, y)| {
                            PathElement::new(
                                vec![(x, y), (x + px(18.0) as i32, y)],
                                colour.stroke_width(px(2.0)),
                            )
                        });
                    if self.markers {
                        chart
                            .draw_series(
                                pts.iter()
                                    .map(|&p| Circle::new(p, px(3.0), colour.filled())),
                            )
                            .map_err(draw_failed)?;
                    }
                }
                chart
                    .configure_series_labels()
                    .background_style(WHITE.mix(0.85))
                    .border_style(BLACK)
                    .legend_area_size(px(30.0))
                    .label_font(("sans-serif", px(14.0)))
                    .draw()
                    .map_err(draw_failed)?;
            }};
        }
        match (log_x, log_y) {
            (true, true) => finish!(
                builder
                    .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())
                    .map_err(draw_failed)?
            ),
            (true, false) => finish!(
                builder
                    .build_cartesian_2d((x0..x1).log_scale(), y0..y1)
                    .map_err(draw_failed)?
            ),
            (false, true) => finish!(
                builder
                    .build_cartesian_2d(x0..x1, (y0..y1).log_scale())
                    .map_err(draw_failed)?
            ),
            (false, false) => finish!(
                builder
                    .build_cartesian_2d(x0..x1, y0..y1)
                    .map_err(draw_failed)?
            ),
        }
        area.present().map_err(draw_failed)?;
        Ok(())
    }
}

/// Encodes 8-bit pixels (`color` says how many channels) as a PNG file.
pub fn write_png(
    path: &Path,
    (width, height): (u32, u32),
    color: png::ColorType,
    pixels: &[u8],
) -> Result<(), png::EncodingError> {
    let file = std::io::BufWriter::new(std::fs::File::create(path)?);
    let mut encoder = png::Encoder::new(file, width, height);
    encoder.set_color(color);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.write_header()?.write_image_data(pixels)
}
