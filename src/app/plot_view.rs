//! A [`LinePlot`] (what the studies produce) drawn with egui_plot, and what it shows kept for
//! export. A geometric axis is drawn against log10 of the value, with the values on its ticks.

use super::export::ShownPlot;
use super::legend::Key;
use crate::export::plot::LinePlot;
use crate::export::plot::{log_axis_pays, tick_label};
use eframe::egui;
use egui_plot::{GridInput, GridMark, Plot, Points};

/// Grid marks of a log10 axis: every decade (labelled first), 2 and 5 times it, then the other
/// digits, so a decade a few hundred points wide reads 1, 2, 5, 10 and a wider one each digit.
fn log_marks(input: GridInput) -> Vec<GridMark> {
    let (lo, hi) = input.bounds;
    if !(lo.is_finite() && hi.is_finite()) || hi - lo > 400.0 {
        return Vec::new();
    }
    let mut marks = Vec::new();
    for decade in (lo.floor() as i64)..=(hi.ceil() as i64) {
        for digit in 1..10 {
            let value = decade as f64 + f64::from(digit).log10();
            let step_size = match digit {
                1 => 1.0,
                2 | 5 => 0.3,
                _ => 0.1,
            };
            if (lo..=hi).contains(&value) {
                marks.push(GridMark { value, step_size });
            }
        }
    }
    marks
}

/// Grid marks of a linear axis: labelled steps of 1, 2 or 5 times a power of ten, at least 32
/// points apart (egui_plot's own spacer labels only powers of ten, so a short plot of e between
/// 0.5 and 1 read "1" alone), with five unlabelled lines between.
pub(super) fn nice_marks(input: GridInput) -> Vec<GridMark> {
    marks_apart(input, 32.0)
}

/// [`nice_marks`] with labelled marks at least 64 points apart: a narrow plot's axis, whose
/// labels egui_plot leaves out closer than 40.
pub(super) fn sparse_marks(input: GridInput) -> Vec<GridMark> {
    marks_apart(input, 64.0)
}

/// Marks at round values, the labelled ones at least `points` apart.
fn marks_apart(input: GridInput, points: f64) -> Vec<GridMark> {
    let (lo, hi) = input.bounds;
    // base_step_size is the value of 8 points.
    let wanted = points / 8.0 * input.base_step_size;
    if !(lo.is_finite() && hi.is_finite() && wanted.is_finite() && wanted > 0.0) {
        return Vec::new();
    }
    let major = nice_step(wanted);
    let minor = major / 5.0;
    let (first, last) = ((lo / minor).ceil(), (hi / minor).floor());
    if last - first >= 10_000.0 || last < first {
        return Vec::new();
    }
    (first as i64..=last as i64)
        .map(|k| GridMark {
            value: k as f64 * minor,
            step_size: if k % 5 == 0 { major } else { minor },
        })
        .collect()
}

/// The smallest step of 1, 2 or 5 times a power of ten that is at least `wanted` (> 0).
pub(super) fn nice_step(wanted: f64) -> f64 {
    let decade = 10f64.powf(wanted.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * decade)
        .find(|&step| step >= wanted * (1.0 - 1e-12))
        .unwrap_or(10.0 * decade)
}

/// Round times for an axis over [start, start + span]: multiples of a 1-2-5 step, about
/// `count` of them.
pub(super) fn round_ticks(start: f64, span: f64, count: usize) -> Vec<f64> {
    if !(start.is_finite() && span.is_finite() && span > 0.0) {
        return vec![];
    }
    let step = nice_step(span / count.max(1) as f64);
    let first = (start / step - 1e-9).ceil() as i64;
    let last = ((start + span) / step + 1e-9).floor() as i64;
    (first..=last).map(|k| k as f64 * step).collect()
}

/// Draws `plot` `height` points high; plots sharing `link` pan and zoom together in x.
pub fn draw(
    ui: &mut egui::Ui,
    id: impl egui::AsIdSalt,
    plot: &LinePlot,
    height: f32,
    link: Option<egui::Id>,
) -> ShownPlot {
    let points = || plot.series.iter().flat_map(|s| s.points.iter());
    let log_x = log_axis_pays(plot.log_x, points().map(|p| p.0));
    let log_y = log_axis_pays(plot.log_y, points().map(|p| p.1));
    let axis = |log: bool| move |v: f64| if log { v.log10() } else { v };
    let (x, y) = (axis(log_x), axis(log_y));
    let series: Vec<(String, Vec<[f64; 2]>)> = plot
        .series
        .iter()
        .map(|s| {
            let pts = s
                .points
                .iter()
                .map(|(a, b)| [x(*a), y(*b)])
                .filter(|p| p[0].is_finite() && p[1].is_finite())
                .collect();
            (s.name.clone(), super::series::thin(pts))
        })
        .collect();
    let label = |text: &str, log: bool| {
        if log {
            format!("{text} (log scale)")
        } else {
            text.to_string()
        }
    };
    let width = super::lecture::line_width(ui);
    // A model's series in its palette colour, any other in the palette's order; the legend a
    // row above the data.
    let keys: Vec<Key> = series
        .iter()
        .enumerate()
        .map(|(k, (name, _))| Key::of_series(name, k))
        .collect();
    super::legend::row(ui, &keys);
    let mut p = Plot::new(id)
        .height(height)
        .x_axis_label(label(&plot.x_label, log_x))
        .y_axis_label(label(&plot.y_label, log_y));
    if log_x {
        p = p
            .x_grid_spacer(log_marks)
            .x_axis_formatter(|mark, _| tick_label(10f64.powf(mark.value)));
    }
    if log_y {
        p = p
            .y_grid_spacer(log_marks)
            .y_axis_formatter(|mark, _| tick_label(10f64.powf(mark.value)));
    } else {
        p = p.y_grid_spacer(nice_marks);
    }
    if let Some(link) = link {
        p = p.link_axis(link, [true, false]);
    }
    let response = p.show(ui, |p| {
        for (key, (name, pts)) in keys.iter().zip(&series) {
            // Wave theory's jumps (repeated x): no band aggregation, which would fill them.
            p.line(key.plot_line(pts.clone(), width).allow_band(false));
            if plot.markers {
                p.points(
                    Points::new(name.as_str(), pts.clone())
                        .radius(2.5)
                        .color(key.colour),
                );
            }
        }
    });
    let b = response.transform.bounds();
    ShownPlot {
        title: plot.title.clone(),
        x_label: if log_x {
            format!("log10 {}", plot.x_label)
        } else {
            plot.x_label.clone()
        },
        y_label: if log_y {
            format!("log10 {}", plot.y_label)
        } else {
            plot.y_label.clone()
        },
        series,
        bounds: Some((b.min(), b.max())),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn time_axes_are_marked_at_round_numbers() {
        // A 1.585 ms span read 0.317, 0.633, ... at fifths: now 0, 0.5, 1, 1.5 ms.
        let t = round_ticks(0.0, 1.585e-3, 5);
        assert_eq!(t.len(), 4);
        for (k, x) in t.iter().enumerate() {
            assert!((x - k as f64 * 0.5e-3).abs() < 1e-15, "{x}");
        }
        let t = round_ticks(2.6, 0.05, 5);
        assert!(t.iter().all(|x| (2.6..=2.65).contains(x)) && t.len() >= 5);
        assert_eq!(nice_step(0.3), 0.5);
        assert_eq!(nice_step(2.0), 2.0);
        assert_eq!(nice_step(7e-4), 1e-3);
    }

    #[test]
    fn log_axis_ticks_read_as_three_significant_digits() {
        let shown: Vec<String> = [0.501187, 1.0, 1.258925, 7.943282, 12345.0, 0.0001]
            .map(tick_label)
            .into();
        assert_eq!(shown, ["0.501", "1", "1.26", "7.94", "1.23e4", "1.00e-4"]);
    }

    #[test]
    fn a_range_under_a_decade_gets_a_linear_axis() {
        // Restitution between 0.5 and 1 on a log axis showed one tick label ("1").
        assert!(!log_axis_pays(true, [0.5, 0.7, 1.0].into_iter()));
        assert!(log_axis_pays(true, [0.05, 1.0].into_iter()));
        assert!(!log_axis_pays(false, [0.05, 1.0].into_iter()));
    }

    #[test]
    fn a_log_axis_marks_every_decade_and_labels_two_and_five_between() {
        let marks = log_marks(GridInput {
            bounds: (-1.05, 0.35),
            base_step_size: 0.01,
        });
        let labelled: Vec<String> = marks
            .iter()
            .filter(|m| m.step_size >= 0.3)
            .map(|m| tick_label(10f64.powf(m.value)))
            .collect();
        assert_eq!(labelled, ["0.1", "0.2", "0.5", "1", "2"]);
        assert_eq!(marks.len(), 9 + 3);
    }

    #[test]
    fn a_linear_axis_labels_one_two_five_steps_at_least_32_points_apart() {
        // 0.5 to 1 over 160 points: 8 points are 0.025, so labels every 0.1 (32 points).
        let marks = nice_marks(GridInput {
            bounds: (0.5, 1.0),
            base_step_size: 0.025,
        });
        let labelled: Vec<f64> = marks
            .iter()
            .filter(|m| m.step_size > 0.05)
            .map(|m| (m.value * 1e9).round() / 1e9)
            .collect();
        assert_eq!(labelled, [0.5, 0.6, 0.7, 0.8, 0.9, 1.0]);
        assert!(
            marks
                .iter()
                .all(|m| (m.step_size - 0.1).abs() < 1e-12 || (m.step_size - 0.02).abs() < 1e-12)
        );
    }
}
