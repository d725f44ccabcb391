//! The space-time (x-t) diagram in the window: both bars along x on the bar view's layout, time
//! upward, every pixel coloured on the GPU (`shaders/xt.wgsl`) from the same history as the bar
//! view. Overlays: the time axis, the animation time as a line, the contact and Sears' zones,
//! optionally the characteristics x = x0 +/- c t, and a colour bar. A click or a drag sets the
//! time; hovering reads x, t, stress and velocity.

use crate::model::field::BarWaves;
use crate::model::impact::ImpactResult;
use crate::model::scenario::ImpactScenario;
use crate::render::bars::{BarsLayout, GpuHistory, HistoryEntry, View, Viewport, XtShown};
use eframe::egui::{self, Color32, Pos2, Rect, Stroke};
use std::sync::Arc;

/// What the diagram shows besides the field.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct XtOptions {
    pub field: XtShown,
    pub characteristics: bool,
}

impl Default for XtOptions {
    fn default() -> Self {
        XtOptions {
            field: XtShown::Stress,
            characteristics: false,
        }
    }
}

impl XtOptions {
    /// The field toggle and the characteristics checkbox.
    pub fn ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            ui.label("x-t diagram:");
            ui.selectable_value(&mut self.field, XtShown::Stress, "stress")
                .on_hover_text("Axial stress: compression blue, tension red");
            ui.selectable_value(&mut self.field, XtShown::Velocity, "velocity")
                .on_hover_text("Particle velocity: to the left blue, to the right red");
            ui.checkbox(&mut self.characteristics, "characteristics")
                .on_hover_text("The lines x = x0 +/- c t along which fronts travel");
        });
    }
}

/// What a diagram shows.
pub enum XtSource<'a> {
    /// An impact of two bars: their waves, or a lumped model's bodies.
    Impact {
        sc: &'a ImpactScenario,
        result: &'a ImpactResult,
    },
    /// Two slabs meeting at a building level, from their waves; `approach_m_s` sets the
    /// colour scale (the wave-theory stress at that closing speed).
    Slabs {
        waves: [&'a BarWaves; 2],
        approach_m_s: f64,
        /// Where the two slabs lie in the diagram's history.
        entries: [HistoryEntry; 2],
    },
}

/// One diagram to draw.
pub struct XtDiagram<'a> {
    pub source: XtSource<'a>,
    /// The history on the GPU: the waves, or the lumped models' force and impulse.
    pub gpu: &'a Arc<GpuHistory>,
    /// Time axis [s].
    pub t_start: f64,
    pub t_span: f64,
    pub title: &'a str,
    /// Sears zone lengths d to mark [m].
    pub zones_m: Option<[f64; 2]>,
}

/// Margins for the time axis labels and the colour bar [points].
pub(super) const LEFT: f32 = 52.0;
pub(super) const RIGHT: f32 = 96.0;
pub(super) const BOTTOM: f32 = 16.0;
pub(super) const TOP: f32 = 18.0;

/// One drawing of the diagram: the viewport of its plot area (x in world metres, y from 0 at
/// the start of the span to 1 at its end) and the bars laid out in it.
struct Frame<'a> {
    vp: Viewport,
    layout: &'a BarsLayout,
    t_start: f64,
    t_span: f64,
}

impl Frame<'_> {
    /// The diagram's y (0 to 1) at time t.
    fn y_of(&self, t: f64) -> f64 {
        ((t - self.t_start) / self.t_span).clamp(0.0, 1.0)
    }

    /// The time at screen height y.
    fn t_of(&self, y: f32) -> f64 {
        let plot = self.vp.rect;
        self.t_start + self.t_span * ((plot.bottom() - y) / plot.height()).clamp(0.0, 1.0) as f64
    }

    /// World x of a point at distance d along bar i.
    fn world(&self, i: usize, d: f64) -> f64 {
        let b = &self.layout.bars[i];
        b.origin_x as f64 + b.direction as f64 * d * self.layout.world_per_metre[i]
    }
}

impl XtDiagram<'_> {
    /// The waves drawn, where the source has them.
    fn waves(&self) -> Option<[&BarWaves; 2]> {
        match &self.source {
            XtSource::Impact { result, .. } => result.waves.as_ref().map(|w| [&w[0], &w[1]]),
            XtSource::Slabs { waves, .. } => Some(*waves),
        }
    }

    fn layout(&self) -> BarsLayout {
        match &self.source {
            XtSource::Impact { sc, result } => match &result.waves {
                Some(w) => BarsLayout::new(w, sc.approach_velocity_m_s(), self.gpu),
                None => BarsLayout::uniform(sc, result, self.gpu),
            },
            XtSource::Slabs {
                waves,
                approach_m_s,
                entries,
            } => BarsLayout::at_entries(*waves, *approach_m_s, *entries),
        }
        .xt()
    }

    /// The field at a point of bar `i` (distance from its impacting end), from the CPU model.
    fn read(&self, i: usize, d: f64, t: f64) -> (f64, f64) {
        if let Some(w) = self.waves() {
            return (w[i].stress_pa(d, t), w[i].velocity_m_s(d, t));
        }
        let XtSource::Impact { sc, result: r } = &self.source else {
            return (0.0, 0.0);
        };
        let area = [sc.bar1.area_m2(), sc.bar2.area_m2()][i];
        let f = crate::model::xt::interpolate(&r.time_s, &r.force_n, t);
        (-f / area, r.rigid_velocities_at(t)[i])
    }

    /// Draws the diagram `height` points high; returns a time set by a click or a drag.
    pub fn show(
        &self,
        ui: &mut egui::Ui,
        slot: u64,
        height: f32,
        t_now: f64,
        options: &XtOptions,
    ) -> Option<f64> {
        let (rect, response) = ui.allocate_exact_size(
            egui::vec2(ui.available_width(), height),
            egui::Sense::click_and_drag(),
        );
        // Named for screen readers (and for tests that click in it).
        response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, "x-t diagram"));
        let layout = self.layout();
        let plot = Rect::from_min_max(
            Pos2::new(rect.left() + LEFT, rect.top() + TOP),
            Pos2::new(rect.right() - RIGHT, rect.bottom() - BOTTOM),
        );
        let frame = Frame {
            vp: Viewport {
                rect: plot,
                left: layout.left,
                right: layout.right,
                bottom: 0.0,
                top: 1.0,
            },
            layout: &layout,
            t_start: self.t_start,
            t_span: self.t_span,
        };
        frame.vp.paint(
            ui,
            slot,
            View::Xt,
            layout.xt_uniforms(self.t_start, self.t_span, options.field),
            layout.bars.to_vec(),
            self.gpu.clone(),
        );
        let painter = ui.painter_at(rect);
        let text = ui.visuals().text_color();
        self.time_axis(&painter, &frame, rect, text);
        self.distance_axis(&painter, &frame, text);
        self.faces_and_zones(&painter, &frame, text);
        if options.characteristics {
            self.characteristic_lines(&painter, &frame);
        }
        // The animation time, where it falls in the diagram.
        if (self.t_start..=self.t_start + self.t_span).contains(&t_now) {
            let y = frame.vp.to_screen(layout.left, frame.y_of(t_now)).y;
            painter.line_segment(
                [Pos2::new(plot.left(), y), Pos2::new(plot.right(), y)],
                Stroke::new(1.5, Color32::from_rgb(240, 200, 80)),
            );
        }
        self.colour_bar(&painter, rect, plot, &layout, options.field, text);
        self.hover_readout(&response, &frame);
        let pointer = response.interact_pointer_pos();
        if (response.clicked() || response.dragged())
            && let Some(p) = pointer.filter(|p| plot.contains(*p))
        {
            return Some(frame.t_of(p.y));
        }
        None
    }

    /// The title and the time axis, in ms at round values.
    fn time_axis(&self, painter: &egui::Painter, frame: &Frame, rect: Rect, text: Color32) {
        let plot = frame.vp.rect;
        let font = super::lecture::font(painter.ctx(), 11.0);
        painter.text(
            Pos2::new(plot.left(), rect.top() + 2.0),
            egui::Align2::LEFT_TOP,
            self.title,
            font.clone(),
            text,
        );
        for t in super::plot_view::round_ticks(self.t_start, self.t_span, 5) {
            let p = frame.vp.to_screen(frame.layout.left, frame.y_of(t));
            painter.text(
                Pos2::new(plot.left() - 4.0, p.y),
                egui::Align2::RIGHT_CENTER,
                crate::export::plot::tick_label(t * 1e3),
                font.clone(),
                text,
            );
        }
        painter.text(
            Pos2::new(rect.left() + 2.0, plot.center().y),
            egui::Align2::LEFT_CENTER,
            "t [ms]",
            font,
            text,
        );
    }

    /// Each bar's distance from the contact in metres at round values, below the diagram, so a
    /// front's speed reads off as a slope.
    fn distance_axis(&self, painter: &egui::Painter, frame: &Frame, text: Color32) {
        let plot = frame.vp.rect;
        let font = super::lecture::font(painter.ctx(), 11.0);
        let lengths: [f64; 2] = match self.waves() {
            Some(w) => [w[0].length_m(), w[1].length_m()],
            None => {
                let b = &frame.layout.bars;
                [0, 1].map(|i| f64::from(b[i].body_length + b[i].zone_length))
            }
        };
        for (i, &length) in lengths.iter().enumerate() {
            for d in super::plot_view::round_ticks(0.0, length, 3) {
                let x = frame.vp.to_screen(frame.world(i, d), 0.0).x;
                painter.line_segment(
                    [
                        Pos2::new(x, plot.bottom()),
                        Pos2::new(x, plot.bottom() + 3.0),
                    ],
                    Stroke::new(1.0, text),
                );
                // One 0 between the two contact faces, not two side by side.
                if d == 0.0 && i == 1 {
                    continue;
                }
                let label = if d == 0.0 {
                    "0".to_string()
                } else {
                    crate::export::plot::tick_label(d)
                };
                painter.text(
                    Pos2::new(x, plot.bottom() + 3.0),
                    egui::Align2::CENTER_TOP,
                    label,
                    font.clone(),
                    text,
                );
            }
        }
        painter.text(
            Pos2::new(plot.right(), plot.bottom() + 3.0),
            egui::Align2::LEFT_TOP,
            " m",
            font,
            text,
        );
    }

    /// The contact faces, and each zone's inner edge where the reading has one.
    fn faces_and_zones(&self, painter: &egui::Painter, frame: &Frame, text: Color32) {
        let vp = &frame.vp;
        let dark = Stroke::new(1.0, Color32::from_gray(40));
        for i in 0..2 {
            let x = frame.world(i, 0.0);
            painter.line_segment([vp.to_screen(x, 0.0), vp.to_screen(x, 1.0)], dark);
            if let Some(d) = self.zones_m {
                let length = self.waves().map_or(0.0, |w| w[i].length_m());
                if d[i] < length {
                    let x = frame.world(i, d[i]);
                    painter.line_segment(
                        [vp.to_screen(x, 0.0), vp.to_screen(x, 1.0)],
                        Stroke::new(1.0, Color32::from_gray(90)),
                    );
                    painter.text(
                        vp.to_screen(x, 1.0),
                        egui::Align2::CENTER_BOTTOM,
                        "d",
                        super::lecture::font(painter.ctx(), 11.0),
                        text,
                    );
                }
            }
        }
    }

    /// The wave fronts' paths x = +-c t from each change of the force, with their reflections.
    fn characteristic_lines(&self, painter: &egui::Painter, frame: &Frame) {
        let Some(w) = self.waves() else {
            return;
        };
        for (i, bar) in w.iter().enumerate() {
            for line in characteristics(bar, self.t_start, self.t_span) {
                let pts: Vec<Pos2> = line
                    .iter()
                    .map(|&(d, t)| frame.vp.to_screen(frame.world(i, d), frame.y_of(t)))
                    .collect();
                painter.add(egui::Shape::line(
                    pts,
                    Stroke::new(1.0, Color32::from_black_alpha(110)),
                ));
            }
        }
    }

    /// Hover: the field under the pointer, read from the model.
    fn hover_readout(&self, response: &egui::Response, frame: &Frame) {
        let (plot, layout) = (frame.vp.rect, frame.layout);
        let Some(pos) = response.hover_pos().filter(|p| plot.contains(*p)) else {
            return;
        };
        let x = layout.left
            + (layout.right - layout.left) * ((pos.x - plot.left()) / plot.width()) as f64;
        let t = frame.t_of(pos.y);
        let i = if x < 0.0 { 0 } else { 1 };
        let b = &layout.bars[i];
        let d = (x - b.origin_x as f64) * b.direction as f64 / layout.world_per_metre[i];
        let length = (b.body_length + b.zone_length) as f64;
        if (0.0..=length).contains(&d) {
            let (stress, velocity) = self.read(i, d, t);
            response.clone().on_hover_text_at_pointer(format!(
                "bar {}: x = {:.4} m from the contact, t = {:.4} ms\nstress {}, velocity {:+.4} m/s",
                i + 1,
                d,
                t * 1e3,
                crate::model::settings::engineering(stress, "Pa"),
                velocity
            ));
        }
    }

    fn colour_bar(
        &self,
        painter: &egui::Painter,
        rect: Rect,
        plot: Rect,
        layout: &BarsLayout,
        field: XtShown,
        text: Color32,
    ) {
        let scale = match field {
            XtShown::Stress => layout.stress_scale_pa,
            XtShown::Velocity => 1.0 / layout.bars[0].inv_velocity_scale as f64,
        };
        colour_bar(painter, rect, plot, field, scale, text);
    }
}

/// The colour map beside a diagram in `rect` plotting in `plot`, labelled with the value that
/// saturates it (`scale`: a stress in Pa or a velocity in m/s, as `field` says).
pub(super) fn colour_bar(
    painter: &egui::Painter,
    rect: Rect,
    plot: Rect,
    field: XtShown,
    scale: f64,
    text: Color32,
) {
    let bar = Rect::from_min_max(
        Pos2::new(rect.right() - RIGHT + 10.0, plot.top()),
        Pos2::new(rect.right() - RIGHT + 22.0, plot.bottom()),
    );
    let n = 48;
    for k in 0..n {
        let s = 1.0 - 2.0 * (k as f32 + 0.5) / n as f32;
        let cell = Rect::from_min_size(
            Pos2::new(bar.left(), bar.top() + bar.height() * k as f32 / n as f32),
            egui::vec2(bar.width(), bar.height() / n as f32 + 0.5),
        );
        painter.rect_filled(cell, 0.0, super::bar_view::diverging(s));
    }
    let (scale, unit, pos, neg) = match field {
        XtShown::Stress => (scale * 1e-6, "MPa", "tension", "compression"),
        XtShown::Velocity => (scale, "m/s", "right", "left"),
    };
    let font = super::lecture::font(painter.ctx(), 11.0);
    let x = bar.right() + 4.0;
    for (y, label) in [
        (bar.top(), format!("+{scale:.3} {unit}")),
        (bar.top() + 13.0, pos.to_string()),
        (bar.center().y, format!("0 {unit}")),
        (bar.bottom() - 13.0, neg.to_string()),
        (bar.bottom(), format!("-{scale:.3} {unit}")),
    ] {
        painter.text(
            Pos2::new(x, y),
            egui::Align2::LEFT_CENTER,
            label,
            font.clone(),
            text,
        );
    }
}

/// Characteristics of one bar over [t0, t0 + span]: from its contact face at every eighth of a
/// round trip, out at c to the free end, reflected back, and so on; each a polyline of
/// (distance from the impacting end, time). A zig-zag started a round trip later runs on the
/// same path, so starts from t0 - T on cover the whole family.
pub fn characteristics(w: &BarWaves, t0: f64, span: f64) -> Vec<Vec<(f64, f64)>> {
    let (c, l) = (w.wave_speed_m_s, w.length_m());
    let trip = 2.0 * l / c;
    if !(trip > 0.0 && span > 0.0) {
        return vec![];
    }
    let step = trip / 8.0;
    let t_end = t0 + span;
    let mut lines = vec![];
    let mut start = t0 - trip;
    while start < t_end && lines.len() < 400 {
        // Corner points of the zig-zag, then clipped to [t0, t_end].
        let mut corners = vec![(0.0, start)];
        let (mut t, mut at_far) = (start, false);
        while t < t_end {
            t += l / c;
            at_far = !at_far;
            corners.push((if at_far { l } else { 0.0 }, t));
        }
        let mut pts = vec![];
        for pair in corners.windows(2) {
            let ((d0, s0), (d1, s1)) = (pair[0], pair[1]);
            let (a, b) = (s0.max(t0), s1.min(t_end));
            if b <= a {
                continue;
            }
            let at = |t: f64| d0 + (d1 - d0) * (t - s0) / (s1 - s0);
            if pts.is_empty() {
                pts.push((at(a), a));
            }
            pts.push((at(b), b));
        }
        if pts.len() >= 2 {
            lines.push(pts);
        }
        start += step;
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::field::History;

    #[test]
    fn characteristics_run_at_the_wave_speed_between_the_ends_within_the_window() {
        let w = BarWaves {
            body_length_m: 2.0,
            zone_length_m: 0.0,
            wave_speed_m_s: 5000.0,
            area_m2: 1e-3,
            impedance_n_s_m: 1e5,
            initial_velocity_m_s: 0.0,
            push_direction: 1.0,
            history: History::Uniform {
                dt_s: 1e-6,
                values: vec![0.0],
            },
            end_s: 0.0,
            decay_per_s: 0.0,
        };
        let (t0, span) = (3e-4, 2e-3);
        let lines = characteristics(&w, t0, span);
        // Eight starts per round trip (0.8 ms) over the window and the round trip before it.
        assert!(lines.len() >= 8 * 3, "{} lines", lines.len());
        for line in &lines {
            for pair in line.windows(2) {
                let ((d0, s0), (d1, s1)) = (pair[0], pair[1]);
                assert!(s1 > s0 && s0 >= t0 - 1e-15 && s1 <= t0 + span + 1e-15);
                assert!((0.0..=2.0).contains(&d0) && (0.0..=2.0).contains(&d1));
                assert!(
                    ((d1 - d0).abs() - 5000.0 * (s1 - s0)).abs() < 1e-9,
                    "slope 1/c"
                );
            }
        }
    }
}
