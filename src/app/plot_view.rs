//! A [`LinePlot`] (what the studies produce) drawn with egui_plot, and what it shows kept for
//! export. A geometric axis is drawn against log10 of the value, with the values on its ticks.

use super::export::ShownPlot;
use crate::export::plot::LinePlot;
use eframe::egui;
use egui_plot::{Legend, Line, Plot, Points};

/// A tick label: three significant digits.
pub fn tick(x: f64) -> String {
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

/// Draws `plot` `height` points high; plots sharing `link` pan and zoom together in x.
pub fn draw(
    ui: &mut egui::Ui,
    id: impl egui::AsIdSalt,
    plot: &LinePlot,
    height: f32,
    link: Option<egui::Id>,
) -> ShownPlot {
    let x = |v: f64| if plot.log_x { v.log10() } else { v };
    let series: Vec<(String, Vec<[f64; 2]>)> = plot
        .series
        .iter()
        .map(|s| {
            let pts = s
                .points
                .iter()
                .map(|(a, b)| [x(*a), *b])
                .filter(|p| p[0].is_finite() && p[1].is_finite())
                .collect();
            (s.name.clone(), super::series::thin(pts))
        })
        .collect();
    let mut p = Plot::new(id)
        .height(height)
        .legend(Legend::default())
        .y_axis_label(plot.y_label.clone());
    p = if plot.log_x {
        p.x_axis_label(format!("{} (log scale)", plot.x_label))
            .x_axis_formatter(|mark, _| tick(10f64.powf(mark.value)))
    } else {
        p.x_axis_label(plot.x_label.clone())
    };
    if let Some(link) = link {
        p = p.link_axis(link, [true, false]);
    }
    let response = p.show(ui, |p| {
        for (name, pts) in &series {
            // Wave theory's jumps (repeated x): no band aggregation, which would fill them.
            p.line(Line::new(name.as_str(), pts.clone()).allow_band(false));
            if plot.markers {
                p.points(Points::new(name.as_str(), pts.clone()).radius(2.5));
            }
        }
    });
    let b = response.transform.bounds();
    ShownPlot {
        title: plot.title.clone(),
        x_label: if plot.log_x {
            format!("log10 {}", plot.x_label)
        } else {
            plot.x_label.clone()
        },
        y_label: plot.y_label.clone(),
        series,
        bounds: Some((b.min(), b.max())),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_axis_ticks_read_as_three_significant_digits() {
        let shown: Vec<String> = [0.501187, 1.0, 1.258925, 7.943282, 12345.0, 0.0001]
            .map(tick)
            .into();
        assert_eq!(shown, ["0.501", "1", "1.26", "7.94", "1.23e4", "1.00e-4"]);
    }
}
