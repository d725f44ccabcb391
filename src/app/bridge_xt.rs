//! The space-time diagram of the whole deck: every girder along the bridge (x), time upward,
//! each pixel coloured on the GPU from the girders' waves from both their ends (the x-t
//! pipeline, `shaders/xt.wgsl`). The joints are the vertical lines: a front leaves a joint as
//! it pounds, crosses its girder at c, reflects at the far end or passes into the next
//! pounding. A click or a drag sets the time; hovering reads the stress and velocity.

use super::bridge_view::BridgeDrawing;
use crate::render::bars::{GpuBar, View, Viewport, XtShown, uniforms};
use eframe::egui::{self, Color32, Pos2, Rect, Stroke};

use super::xt_view::{BOTTOM, LEFT, RIGHT, TOP, colour_bar};

/// One diagram over [t_start, t_start + t_span].
pub struct DeckXt<'a> {
    pub d: &'a BridgeDrawing,
    pub t_start: f64,
    pub t_span: f64,
    pub title: &'a str,
    /// The stress and the velocity that saturate the colour map.
    pub stress_scale_pa: f64,
    pub velocity_scale_m_s: f64,
}

impl DeckXt<'_> {
    /// World x of girder i's left end: its place on the deck, a sliver apart from the next so
    /// the joints show.
    fn girder_x(&self, i: usize) -> f64 {
        let sc = &self.d.setup.scenario;
        sc.girder_start_m(i) + i as f64 * 0.004 * sc.length_m()
    }

    fn bars(&self) -> Vec<GpuBar> {
        let scales = (self.stress_scale_pa, self.velocity_scale_m_s);
        (0..self.d.result.girder_waves.len())
            .map(|i| self.d.girder_bar(i, self.girder_x(i), (0.0, 1.0), scales))
            .collect()
    }

    /// Draws the diagram `height` points high; returns a time set by a click or a drag.
    pub fn show(&self, ui: &mut egui::Ui, height: f32, t_now: f64, field: XtShown) -> Option<f64> {
        let (rect, response) = ui.allocate_exact_size(
            egui::vec2(ui.available_width(), height),
            egui::Sense::click_and_drag(),
        );
        response
            .widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, "deck x-t diagram"));
        let sc = &self.d.setup.scenario;
        let right = self.girder_x(sc.spans - 1) + sc.girder(sc.spans - 1).length_m;
        let pad = 0.01 * right;
        let plot = Rect::from_min_max(
            Pos2::new(rect.left() + LEFT, rect.top() + TOP),
            Pos2::new(rect.right() - RIGHT, rect.bottom() - BOTTOM),
        );
        let vp = Viewport {
            rect: plot,
            left: -pad,
            right: right + pad,
            bottom: 0.0,
            top: 1.0,
        };
        let bars = self.bars();
        let count = bars.len() as u32;
        let u = crate::render::bars::GpuUniforms {
            field: field as u32,
            t_start: self.t_start as f32,
            t_span: self.t_span as f32,
            ..uniforms([vp.left, vp.right, 0.0, 1.0], self.t_start, count)
        };
        vp.paint(
            ui,
            super::slots::BRIDGE_XT,
            View::Xt,
            u,
            bars,
            self.d.gpu.clone(),
        );
        let painter = ui.painter_at(rect);
        let text = ui.visuals().text_color();
        let y_of = |t: f64| ((t - self.t_start) / self.t_span).clamp(0.0, 1.0);
        self.axes(&painter, &vp, rect, text, &y_of);
        if (self.t_start..=self.t_start + self.t_span).contains(&t_now) {
            let y = vp.to_screen(0.0, y_of(t_now)).y;
            painter.line_segment(
                [Pos2::new(plot.left(), y), Pos2::new(plot.right(), y)],
                Stroke::new(1.5, Color32::from_rgb(240, 200, 80)),
            );
        }
        let scale = match field {
            XtShown::Stress => self.stress_scale_pa,
            XtShown::Velocity => self.velocity_scale_m_s,
        };
        colour_bar(&painter, rect, plot, field, scale, text);
        let t_of = |y: f32| {
            self.t_start
                + self.t_span * ((plot.bottom() - y) / plot.height()).clamp(0.0, 1.0) as f64
        };
        if let Some(pos) = response.hover_pos().filter(|p| plot.contains(*p)) {
            let x = vp.left + (vp.right - vp.left) * ((pos.x - plot.left()) / plot.width()) as f64;
            let t = t_of(pos.y);
            let r = &self.d.result;
            if let Some(i) = (0..sc.spans)
                .find(|&i| (0.0..=sc.girder(i).length_m).contains(&(x - self.girder_x(i))))
            {
                let along = x - self.girder_x(i);
                response.clone().on_hover_text_at_pointer(format!(
                    "girder {}: {:.2} m from its left end, t = {:.4} s\nstress {:+.4e} Pa, wave velocity {:+.4} m/s",
                    i + 1,
                    along,
                    t,
                    r.girder_stress_pa(i, along, t),
                    r.girder_wave_velocity_m_s(i, along, t),
                ));
            }
        }
        if (response.clicked() || response.dragged())
            && let Some(p) = response
                .interact_pointer_pos()
                .filter(|p| plot.contains(*p))
        {
            return Some(t_of(p.y));
        }
        None
    }

    /// The title, the time axis (seconds of the run, at round values), the girders and the joints.
    fn axes(
        &self,
        painter: &egui::Painter,
        vp: &Viewport,
        rect: Rect,
        text: Color32,
        y_of: &dyn Fn(f64) -> f64,
    ) {
        let plot = vp.rect;
        let font = super::lecture::font(painter.ctx(), 11.0);
        painter.text(
            Pos2::new(plot.left(), rect.top() + 2.0),
            egui::Align2::LEFT_TOP,
            self.title,
            font.clone(),
            text,
        );
        for t in super::plot_view::round_ticks(self.t_start, self.t_span, 5) {
            let p = vp.to_screen(0.0, y_of(t));
            painter.text(
                Pos2::new(plot.left() - 4.0, p.y),
                egui::Align2::RIGHT_CENTER,
                format!("{:.3}", t),
                font.clone(),
                text,
            );
        }
        painter.text(
            Pos2::new(rect.left() + 2.0, plot.center().y),
            egui::Align2::LEFT_CENTER,
            "t [s]",
            font.clone(),
            text,
        );
        let sc = &self.d.setup.scenario;
        let line = Stroke::new(1.0, Color32::from_gray(40));
        for i in 0..sc.spans {
            let a = self.girder_x(i);
            let b = a + sc.girder(i).length_m;
            for x in [a, b] {
                painter.line_segment([vp.to_screen(x, 0.0), vp.to_screen(x, 1.0)], line);
            }
            painter.text(
                vp.to_screen(0.5 * (a + b), 0.0) + egui::vec2(0.0, 2.0),
                egui::Align2::CENTER_TOP,
                format!("girder {}", i + 1),
                font.clone(),
                text,
            );
        }
        // The joints' numbers under the axis, between the girders' names.
        for j in 0..=sc.spans {
            let x = if j == 0 {
                0.0
            } else {
                self.girder_x(j - 1) + sc.girder(j - 1).length_m
            };
            painter.text(
                vp.to_screen(x, 0.0) + egui::vec2(0.0, 2.0),
                egui::Align2::CENTER_TOP,
                format!("{j}"),
                font.clone(),
                Color32::from_rgb(240, 180, 60),
            );
        }
    }
}
