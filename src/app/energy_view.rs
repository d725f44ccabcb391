//! Where the energy is over an impact, as a stacked plot: the bars' rigid-body motion at the
//! bottom, the waves in each bar, the contact, what was dissipated; the total as a line on top.
//! The readouts give the final split; this shows how the run gets there.

use super::export::ShownPlot;
use super::legend::Key;
use crate::model::impact::ImpactResult;
use crate::model::impact::energy::energy_history;
use crate::model::scenario::ImpactScenario;
use eframe::egui::{self, Color32};
use egui_plot::{FilledArea, Line, Plot, VLine};

/// The bands, bottom up: name and colour.
const BANDS: [(&str, Color32); 5] = [
    ("rigid-body motion", Color32::from_rgb(120, 150, 200)),
    ("waves in bar 1", Color32::from_rgb(230, 150, 60)),
    ("waves in bar 2", Color32::from_rgb(200, 100, 40)),
    ("contact", Color32::from_rgb(120, 190, 110)),
    ("dissipated", Color32::from_rgb(170, 120, 180)),
];

/// Draws the energy history of `r` `height` points high with a line at `t_ms`; returns what it
/// shows, for export.
pub fn draw(
    ui: &mut egui::Ui,
    id: &str,
    sc: &ImpactScenario,
    r: &ImpactResult,
    height: f32,
    t_ms: f64,
    title: String,
) -> ShownPlot {
    let h = energy_history(sc, r, 600);
    let t: Vec<f64> = h.time_s.iter().map(|t| t * 1e3).collect();
    let n = t.len();
    // Each bar's waves where the model keeps them; both bars' in the first band otherwise.
    let waves = match &h.wave_by_bar_j {
        Some(w) => [w[0].clone(), w[1].clone()],
        None => [h.wave_j.clone(), vec![0.0; n]],
    };
    let parts: [&[f64]; 5] = [
        &h.rigid_kinetic_j,
        &waves[0],
        &waves[1],
        &h.contact_j,
        &h.dissipated_j,
    ];
    let mut lower = vec![0.0; n];
    let mut bands = Vec::new();
    for (k, part) in parts.iter().enumerate() {
        if part.iter().all(|v| *v == 0.0) {
            continue;
        }
        let upper: Vec<f64> = lower.iter().zip(part.iter()).map(|(a, b)| a + b).collect();
        bands.push((k, lower.clone(), upper.clone()));
        lower = upper;
    }
    let total: Vec<[f64; 2]> = (0..n).map(|k| [t[k], h.total_j(k)]).collect();
    let line_colour = ui.visuals().text_color();
    let width = super::lecture::line_width(ui);
    let band_name = |k: usize| {
        if k == 1 && h.wave_by_bar_j.is_none() {
            "waves (both bars)"
        } else {
            BANDS[k].0
        }
    };
    let mut keys: Vec<Key> = bands
        .iter()
        .map(|(k, _, _)| Key::band(band_name(*k), BANDS[*k].1))
        .collect();
    keys.push(Key::line("total", line_colour, false));
    super::legend::row(ui, &keys);
    let response = Plot::new(id)
        .y_grid_spacer(super::plot_view::nice_marks)
        .height(height)
        .x_axis_label("time [ms]")
        .y_axis_label("energy [J]")
        .show(ui, |p| {
            for (k, lo, hi) in &bands {
                let (name, colour) = (band_name(*k), BANDS[*k].1);
                p.add(
                    FilledArea::new(name, &t, lo, hi)
                        .fill_color(colour.gamma_multiply(0.85))
                        .allow_hover(false),
                );
            }
            p.line(
                Line::new("total", total.clone())
                    .color(line_colour)
                    .width(width),
            );
            p.vline(VLine::new("t", t_ms));
        });
    let b = response.transform.bounds();
    let mut series: Vec<(String, Vec<[f64; 2]>)> = parts
        .iter()
        .enumerate()
        .filter(|(_, p)| p.iter().any(|v| *v != 0.0))
        .map(|(k, p)| {
            (
                BANDS[k].0.to_string(),
                (0..n).map(|i| [t[i], p[i]]).collect(),
            )
        })
        .collect();
    series.push(("total".into(), total));
    ShownPlot {
        title,
        x_label: "time [ms]".into(),
        y_label: "energy [J]".into(),
        series,
        bounds: Some((b.min(), b.max())),
    }
}
