//! Hysteresis loops: each yielding storey's shear against its drift, drawn up to the time the
//! animation shows (so the loops grow as it plays), with the impacts marked where they struck
//! and the lines the law keeps the shear between. The model computed every value; this draws.

use super::building_view::{BuildingDrawing, YIELDED};
use super::export::ShownPlot;
use crate::model::building::BuildingResult;
use eframe::egui::{self, Color32};
use egui_plot::{Line, LineStyle, MarkerShape, Plot, Points};

/// The loop's colour (the impacts' crosses are red, the bounds grey).
const LOOP: Color32 = Color32::from_rgb(80, 150, 230);

/// At most this many storeys a side get a plot: those of the largest ductility demand.
const MOST_STOREYS: usize = 6;

/// The storeys of a side that get a plot, lowest first: all of them, or the [`MOST_STOREYS`]
/// of the largest ductility demand.
pub fn storeys_drawn(r: &BuildingResult, side: usize) -> Vec<usize> {
    let n = r.storey_shear_n[side].len();
    let mut order: Vec<usize> = (0..n).collect();
    let demand = |j: usize| r.ductility_demand[side].get(j).copied().unwrap_or(0.0);
    order.sort_by(|&a, &b| demand(b).total_cmp(&demand(a)));
    order.truncate(MOST_STOREYS);
    order.sort_unstable();
    order
}

/// One storey's loop: its drift [mm] and shear [kN] at every sample.
struct Storey {
    name: String,
    points: Vec<[f64; 2]>,
    /// The law's bounding lines over the run's drift range (none for an elastic law).
    bounds: Option<[Vec<[f64; 2]>; 2]>,
    ductility: f64,
}

fn storey(d: &BuildingDrawing, side: usize, j: usize) -> Storey {
    let r = &d.result;
    let drift = r.storey_drift_m(side, j);
    let points: Vec<[f64; 2]> = drift
        .iter()
        .zip(&r.storey_shear_n[side][j])
        .map(|(u, f)| [u * 1e3, f * 1e-3])
        .collect();
    let sc = &d.setup.scenario;
    let law = [&sc.left, &sc.right][side].storey_law(j);
    let (lo, hi) = drift
        .iter()
        .fold((0.0f64, 0.0f64), |(a, b), &u| (a.min(u), b.max(u)));
    let reach = (hi - lo).max(law.yield_drift_m()) * 0.1;
    let ends = [lo - reach, hi + reach];
    let at_ends: Option<Vec<[f64; 2]>> = ends.iter().map(|&u| law.bounding_shears_n(u)).collect();
    let bounds = at_ends.map(|f| {
        std::array::from_fn(|band| {
            ends.iter()
                .zip(&f)
                .map(|(u, f)| [u * 1e3, f[band] * 1e-3])
                .collect()
        })
    });
    Storey {
        name: format!("{} storey {}", ["left", "right"][side], j + 1),
        points,
        bounds,
        ductility: r.ductility_demand[side].get(j).copied().unwrap_or(0.0),
    }
}

/// The loops of every yielding storey (up to [`MOST_STOREYS`] a side) up to time `t`; what
/// an export of them holds goes into `shown`. Nothing where no storey yields.
pub fn show(ui: &mut egui::Ui, d: &BuildingDrawing, t: f64, shown: &mut ShownPlot) {
    let r = &d.result;
    let sides: Vec<usize> = (0..2)
        .filter(|&s| !r.storey_shear_n[s].is_empty())
        .collect();
    if sides.is_empty() {
        return;
    }
    let lecture = super::lecture::on(ui.ctx());
    let about = "hysteresis loops: storey shear against storey drift up to the time shown; x marks an impact, dashed lines the law's bounds b k u \u{b1} (1 - b) F_y";
    // A projector's panel has no row to spare: the plots' titles say what they are.
    if !lecture {
        ui.label(about).on_hover_text("The area a loop encloses is the energy the storey dissipated. A storey's columns turn orange in the view once its drift has passed F_y / k.");
    }
    let upto = r.time_s.partition_point(|&x| x <= t).max(1);
    let struck: Vec<usize> = r
        .impacts
        .iter()
        .filter(|e| e.start_s <= t)
        .map(|e| r.time_s.partition_point(|&x| x < e.start_s).min(upto - 1))
        .collect();
    let width = super::lecture::line_width(ui);
    // The loops stand side by side: one share of the panel's height for the row, and the
    // width divided between them.
    let count: usize = sides.iter().map(|&s| storeys_drawn(r, s).len()).sum();
    let size = egui::vec2(
        ((ui.available_width() - 8.0 * count as f32) / count as f32).clamp(150.0, 300.0),
        super::fill::height(ui, 170.0, 80.0),
    );
    let mut series = Vec::new();
    ui.horizontal_wrapped(|ui| {
        for s in sides {
            for j in storeys_drawn(r, s) {
                let st = storey(d, s, j);
                let grown = &st.points[..upto.min(st.points.len())];
                ui.vertical(|ui| {
                    // A projector's narrow column takes the lessons' symbol for it.
                    let title = if lecture {
                        format!(
                            "{} loop: mu = {:.2}",
                            st.name.replace(" storey", ""),
                            st.ductility
                        )
                    } else {
                        format!("{}: ductility {:.2}", st.name, st.ductility)
                    };
                    ui.label(title).on_hover_text(about);
                    loop_plot(
                        ui,
                        (s, j),
                        &st,
                        grown,
                        &struck,
                        (width, size),
                        r.yielded_by(s, j, t),
                    );
                });
                series.push((st.name, grown.to_vec()));
            }
        }
    });
    *shown = ShownPlot {
        title: format!("Hysteresis loops to t = {t:.3} s"),
        x_label: "storey drift [mm]".into(),
        y_label: "storey shear [kN]".into(),
        series,
        bounds: None,
    };
}

/// One storey's plot, its bounds fixed over the whole run so the loop grows in place.
fn loop_plot(
    ui: &mut egui::Ui,
    id: (usize, usize),
    st: &Storey,
    grown: &[[f64; 2]],
    struck: &[usize],
    (width, size): (f32, egui::Vec2),
    yielded: bool,
) {
    let (mut lo, mut hi) = ([0.0f64; 2], [0.0f64; 2]);
    for p in &st.points {
        for a in 0..2 {
            lo[a] = lo[a].min(p[a]);
            hi[a] = hi[a].max(p[a]);
        }
    }
    Plot::new(("b-loop", id.0, id.1))
        .width(size.x)
        .height(size.y)
        .x_axis_label("drift [mm]")
        .x_grid_spacer(super::plot_view::sparse_marks)
        .y_grid_spacer(super::plot_view::nice_marks)
        .y_axis_label("shear [kN]")
        .include_x(lo[0] * 1.05)
        .include_x(hi[0] * 1.05)
        .include_y(lo[1] * 1.1)
        .include_y(hi[1] * 1.1)
        .allow_drag(false)
        .allow_scroll(false)
        .show(ui, |p| {
            if let Some(bounds) = &st.bounds {
                for (k, b) in bounds.iter().enumerate() {
                    p.line(
                        Line::new(format!("bound {}", k + 1), b.clone())
                            .style(LineStyle::dashed_loose())
                            .color(Color32::GRAY),
                    );
                }
            }
            p.line(
                Line::new(st.name.as_str(), grown.to_vec())
                    .width(width)
                    .color(LOOP),
            );
            let hits: Vec<[f64; 2]> = struck
                .iter()
                .filter_map(|&i| grown.get(i).copied())
                .collect();
            if !hits.is_empty() {
                p.points(
                    Points::new("impacts", hits)
                        .shape(MarkerShape::Cross)
                        .radius(5.0)
                        .color(Color32::from_rgb(220, 60, 50)),
                );
            }
            if let Some(now) = grown.last() {
                p.points(
                    Points::new("now", vec![*now])
                        .radius(4.0)
                        .color(if yielded { YIELDED } else { Color32::GRAY }),
                );
            }
        });
}
