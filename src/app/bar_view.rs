//! The view of two bars: the wgpu stress-wave quads (render::bars) plus egui overlays: the Sears
//! compression zones, velocity arrows, the colour legend.

use crate::io::settings::ImpactSetup;
use crate::model::impact::ImpactResult;
use crate::model::scenario::Reading;
use crate::render::bars::{BarsLayout, GpuHistory, View, Viewport};
use eframe::egui::{self, Color32, Pos2, Rect, Stroke};
use std::sync::Arc;

/// A solve ready to draw: the result and its history on the GPU grid.
pub struct Solved {
    pub setup: ImpactSetup,
    pub result: ImpactResult,
    pub gpu: Arc<GpuHistory>,
}

impl Solved {
    pub fn new(setup: ImpactSetup, result: ImpactResult) -> Self {
        // The waves, or for a lumped model its force and impulse (its uniform-stress picture).
        let gpu = Arc::new(match result.waves.as_ref() {
            Some(w) => GpuHistory::from_waves(w),
            None => GpuHistory::uniform(&result, 2000, result.view_span_s()),
        });
        Solved { setup, result, gpu }
    }

    /// Rigid-body velocities at time t, as the model integrated its impulse.
    pub fn velocities_at(&self, t: f64) -> [f64; 2] {
        self.result.rigid_velocities_at(t)
    }

    /// The time span worth animating: the impact and a round trip of the waves after it.
    pub fn span_s(&self) -> f64 {
        self.result.view_span_s()
    }

    /// The zones d to mark: the Sears model's, in the readings that have them.
    pub fn zones_m(&self) -> Option<[f64; 2]> {
        self.result
            .sears
            .filter(|s| s.reading != Reading::End)
            .map(|s| s.zone_lengths_m)
    }
}

/// The bars' velocities and lengths and the animation time, as a row of labels above the view
/// (they wrap with the width, where labels painted over short bars would run into each other).
pub fn caption(ui: &mut egui::Ui, solved: &Solved, t: f64) {
    let v = solved.velocities_at(t);
    let lengths = solved
        .result
        .waves
        .as_ref()
        .map(|w| [w[0].length_m(), w[1].length_m()]);
    ui.horizontal_wrapped(|ui| {
        ui.spacing_mut().item_spacing.x = 24.0;
        // A step's text gives the lengths: on a projector the row keeps to one line.
        let lengths = lengths.filter(|_| !super::lecture::on(ui.ctx()));
        for i in 0..2 {
            let length = lengths.map_or(String::new(), |l| format!(", L = {} m", l[i]));
            ui.label(format!("bar {}: {:.3} m/s{length}", i + 1, v[i]));
        }
        ui.label(format!("t = {:.4} ms", t * 1e3));
    });
}

/// Draws the bars at animation time `t` into `rect`; `lumped` adds a pair of rigid blocks and a
/// spring below (the lumped-mass reading of the same impact), given its approach history.
pub fn draw(ui: &mut egui::Ui, rect: Rect, slot: u64, solved: &Solved, t: f64) {
    let setup = &solved.setup;
    let r = &solved.result;
    let Some(waves) = r.waves.as_ref() else {
        ui.painter().text(
            rect.center(),
            egui::Align2::CENTER_CENTER,
            "no wave field for this model",
            super::lecture::font(ui.ctx(), 16.0),
            ui.visuals().text_color(),
        );
        return;
    };
    let lengths = [waves[0].length_m(), waves[1].length_m()];
    let layout = BarsLayout::new(waves, setup.scenario.approach_velocity_m_s(), &solved.gpu);
    let (gap, wpm, to_scale) = (layout.gap, layout.world_per_metre, layout.to_scale);
    let extent = [lengths[0] * wpm[0], lengths[1] * wpm[1]];
    let vp = Viewport {
        rect,
        left: layout.left,
        right: layout.right,
        bottom: layout.bottom,
        top: layout.top,
    };
    vp.paint(
        ui,
        slot,
        View::Bars,
        layout.uniforms(t),
        layout.bars.to_vec(),
        solved.gpu.clone(),
    );
    let to_screen = |x: f64, y: f32| vp.to_screen(x, y as f64);
    let painter = ui.painter_at(rect);
    let text = ui.visuals().text_color();
    let font = super::lecture::font(painter.ctx(), 13.0);
    // The Sears compression zones.
    if setup.model == crate::model::impact::ModelKind::Sears
        && setup.scenario.reading != Reading::End
        && let Some(d) = r.sears.map(|s| s.zone_lengths_m)
    {
        for i in 0..2 {
            // A zone longer than its bar (outside the model: the run warns) is marked at the
            // far end, where it runs off the bar.
            let (at, mark) = if d[i] < lengths[i] {
                (d[i], "d")
            } else {
                (lengths[i], "d > L")
            };
            let dir = if i == 0 { -1.0 } else { 1.0 };
            let x = dir * (gap + at * wpm[i]);
            let (a, b) = (to_screen(x, 0.36), to_screen(x, 0.66));
            painter.line_segment([a, b], Stroke::new(1.5, text));
            painter.text(
                to_screen(x, 0.67),
                egui::Align2::CENTER_BOTTOM,
                mark,
                font.clone(),
                text,
            );
        }
    }
    // Velocity arrows, scaled by the larger initial speed.
    let v = solved.velocities_at(t);
    let v_ref = r.initial_velocities_m_s[0]
        .abs()
        .max(r.initial_velocities_m_s[1].abs())
        .max(1e-12);
    for i in 0..2 {
        let dir = if i == 0 { -1.0 } else { 1.0 };
        let centre = dir * (gap + 0.5 * extent[i]);
        let half = 0.35 * extent[i] * (v[i] / v_ref).clamp(-1.0, 1.0);
        let (a, b) = (
            to_screen(centre - half, 0.78),
            to_screen(centre + half, 0.78),
        );
        let colour = if ui.visuals().dark_mode {
            Color32::from_rgb(240, 200, 80)
        } else {
            Color32::from_rgb(160, 100, 0)
        };
        if (b.x - a.x).abs() > 2.0 {
            painter.arrow(a, b - a, Stroke::new(2.5, colour));
        }
    }
    if !to_scale {
        painter.text(
            to_screen(0.0, 0.30),
            egui::Align2::CENTER_TOP,
            "lengths not to scale",
            font.clone(),
            text,
        );
    }
    stress_legend(&painter, rect, layout.stress_scale_pa, text);
}

/// The colour map's legend in the lower left corner, with the stress it spans.
fn stress_legend(painter: &egui::Painter, rect: Rect, stress_scale_pa: f64, text: Color32) {
    let legend = Rect::from_min_size(
        Pos2::new(rect.left() + 12.0, rect.bottom() - 28.0),
        egui::vec2(160.0, 10.0),
    );
    for k in 0..32 {
        let s = -1.0 + 2.0 * (k as f32 + 0.5) / 32.0;
        let cell = Rect::from_min_size(
            Pos2::new(
                legend.left() + legend.width() * k as f32 / 32.0,
                legend.top(),
            ),
            egui::vec2(legend.width() / 32.0 + 0.5, legend.height()),
        );
        painter.rect_filled(cell, 0.0, diverging(s));
    }
    painter.text(
        Pos2::new(legend.left(), legend.bottom() + 2.0),
        egui::Align2::LEFT_TOP,
        format!(
            "compression  {}  tension",
            crate::model::settings::engineering(stress_scale_pa, "Pa")
        ),
        super::lecture::font(painter.ctx(), 11.0),
        text,
    );
}

/// The shader's colour map, for the legend.
pub fn diverging(s: f32) -> Color32 {
    let [r, g, b] = crate::render::bars::diverging(s).map(|c| (c * 255.0) as u8);
    Color32::from_rgb(r, g, b)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::impact::{ModelKind, solve};

    /// The arrows are drawn from `velocities_at`: a stereomechanical impact passes its whole
    /// impulse at t = 0 (its force samples are zeros), so the arrows must show the rebound at
    /// once, and conserve momentum.
    #[test]
    fn velocity_arrows_rebound_after_a_stereomechanics_impact() {
        let setup = ImpactSetup {
            model: ModelKind::Stereo,
            ..ImpactSetup::default()
        };
        let r = solve(ModelKind::Stereo, &setup.scenario).expect("stereo solves");
        let [m1, m2] = r.masses_kg;
        let [v1, v2] = r.initial_velocities_m_s;
        let e = setup.scenario.contact.restitution;
        let solved = Solved::new(setup, r);
        assert_eq!(solved.velocities_at(-1e-6), [v1, v2]);
        let [u1, u2] = solved.velocities_at(1e-6);
        // Newton's law of restitution and momentum, from the inputs alone.
        assert!(((u2 - u1) - e * (v1 - v2)).abs() < 1e-12 * (v1 - v2).abs());
        let p = m1 * v1 + m2 * v2;
        assert!((m1 * u1 + m2 * u2 - p).abs() < 1e-12 * p.abs().max(1.0));
        assert!(u2 > v2, "bar 2 is pushed on");
    }
}
