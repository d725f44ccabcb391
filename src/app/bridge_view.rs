//! The bridge in elevation: the abutments and the piers on their own ground points (each moving
//! with the ground where the travelling wave has got to), the piers swaying and the bearings
//! shearing with the drift exaggerated, the girders coloured by their stress waves on the GPU
//! (the bar view's pipeline: a girder holds the waves from both its ends), and at every joint
//! its gap, a red mark while it carries force and the seat it rests on, turning red as the
//! joint's margin runs out.
//!
//! Every displacement is drawn exaggerated by the same factor, gaps and seats with it, so a
//! joint closes on screen when it closes in the run and a girder's end leaves its seat when the
//! joint opens further than the seat length.

use crate::io::bridge_settings::BridgeSetup;
use crate::model::bridge::ground::Ground;
use crate::model::bridge::{BridgeResult, Member};
use crate::model::motion::{GroundMotion, MotionStats};
use crate::model::xt::interpolate;
use crate::render::bars::{GpuBar, GpuHistory, View, Viewport, uniforms};
use eframe::egui::{self, Color32, Pos2, Stroke};
use std::sync::Arc;

/// A solve ready to draw: the run, its corrected ground, and the girders' waves on the GPU.
pub struct BridgeDrawing {
    pub setup: BridgeSetup,
    pub motion: GroundMotion,
    pub result: BridgeResult,
    pub ground: Ground,
    pub gpu: Arc<GpuHistory>,
    /// The record's summary (a response spectrum among it: worked out here, off the UI thread).
    pub motion_stats: MotionStats,
}

impl BridgeDrawing {
    /// The drawing of a run, with the record's summary worked out once per job (a job draws a
    /// run many times as it solves).
    pub fn with_stats(
        setup: BridgeSetup,
        motion: GroundMotion,
        result: BridgeResult,
        motion_stats: MotionStats,
    ) -> Self {
        let gpu = Arc::new(GpuHistory::from_pairs(&result.girder_waves));
        BridgeDrawing {
            ground: Ground::new(&motion),
            motion_stats,
            setup,
            motion,
            result,
            gpu,
        }
    }

    /// The ground's displacement at `x_m` along the bridge at `t` [m].
    pub fn ground_at(&self, x_m: f64, t: f64) -> f64 {
        self.ground
            .at(t, self.setup.scenario.delay_s(x_m))
            .displacement
    }

    /// How much of joint `j`'s seat is used at `t`: its opening over the seat length (1 or
    /// more: unseated).
    pub fn seat_use(&self, j: usize, t: f64) -> f64 {
        let r = &self.result;
        interpolate(&r.time_s, &r.joint_opening_m[j], t) / self.setup.scenario.seat_length_m
    }

    /// The stress that saturates the girders' colour [Pa]: the largest joint force over the
    /// smallest girder area.
    pub fn stress_scale_pa(&self) -> f64 {
        (self.result.max_pounding_force_n / self.smallest_area_m2()).max(1.0)
    }

    /// The smallest girder cross-section [m^2]: a force over it is the largest stress it makes.
    pub fn smallest_area_m2(&self) -> f64 {
        let sc = &self.setup.scenario;
        (0..sc.spans)
            .map(|i| sc.girder(i).area_m2)
            .fold(f64::INFINITY, f64::min)
    }

    /// Girder i as a bar the GPU colours by the waves from both its ends (kind 2), its left end
    /// at world x `origin_x`, drawn from `y` = (bottom, top), one world unit a metre; the
    /// stress and the velocity that saturate the colour map.
    pub fn girder_bar(
        &self,
        i: usize,
        origin_x: f64,
        y: (f64, f64),
        (stress_scale_pa, velocity_scale_m_s): (f64, f64),
    ) -> GpuBar {
        let w = &self.result.girder_waves[i][0];
        let (offset, count, _, _) = self.gpu.layout[i];
        GpuBar {
            origin_x: origin_x as f32,
            direction: 1.0,
            inv_stress_scale: (1.0 / stress_scale_pa) as f32,
            y_bottom: y.0 as f32,
            y_top: y.1 as f32,
            world_per_metre: 1.0,
            kind: 2,
            aux_offset: offset + count,
            ..GpuBar::of_waves(w, self.gpu.layout[i], velocity_scale_m_s)
        }
    }
}

/// A seat with more than half its length to spare.
const SEAT_GREY: Color32 = Color32::from_gray(150);

/// The colour of a seat: grey while less than half of it is used, through orange to red as
/// the opening reaches the seat length, red once the girder has left it.
pub fn seat_colour(used: f64, unseated: bool) -> Color32 {
    if unseated || used >= 1.0 {
        return Color32::from_rgb(225, 40, 40);
    }
    if used < 0.5 {
        return SEAT_GREY;
    }
    let grey = [150.0, 150.0, 150.0];
    let (orange, red) = ([240.0, 160.0, 40.0], [225.0, 40.0, 40.0]);
    let mix = |a: [f64; 3], b: [f64; 3], s: f64| {
        Color32::from_rgb(
            (a[0] + (b[0] - a[0]) * s) as u8,
            (a[1] + (b[1] - a[1]) * s) as u8,
            (a[2] + (b[2] - a[2]) * s) as u8,
        )
    };
    if used < 0.75 {
        mix(grey, orange, (used - 0.5) / 0.25)
    } else {
        mix(orange, red, (used - 0.75) / 0.25)
    }
}

/// Heights in the drawing [world units, the ground at 0]: not to scale, chosen to read.
const PIER_TOP: f64 = 7.0;
const GIRDER_BOTTOM: f64 = 7.8;
const GIRDER_TOP: f64 = 10.0;
const SEAT_DEPTH: f64 = 0.5;
const ABUTMENT_WIDTH: f64 = 5.0;

/// One frame of the view: where every member is drawn at time t.
struct Frame<'a> {
    d: &'a BridgeDrawing,
    vp: Viewport,
    t: f64,
    ex: f64,
    /// Each girder's left end at rest in the drawing: its position plus the gaps left of it,
    /// exaggerated.
    rest: Vec<f64>,
    /// The right abutment's face at rest.
    right_face: f64,
}

impl<'a> Frame<'a> {
    fn new(rect: egui::Rect, d: &'a BridgeDrawing, t: f64, ex: f64) -> Self {
        let sc = &d.setup.scenario;
        let gaps: Vec<f64> = d.result.joints.iter().map(|j| j.gap_m).collect();
        let rest: Vec<f64> = (0..sc.spans)
            .map(|i| sc.girder_start_m(i) + ex * gaps[..=i].iter().sum::<f64>())
            .collect();
        let right_face = sc.length_m() + ex * gaps.iter().sum::<f64>();
        let margin = 0.03 * right_face + ex * 0.2;
        let vp = Viewport {
            rect,
            left: -ABUTMENT_WIDTH - margin,
            right: right_face + ABUTMENT_WIDTH + margin,
            bottom: -1.5,
            top: GIRDER_TOP + 3.2,
        };
        Frame {
            d,
            vp,
            t,
            ex,
            rest,
            right_face,
        }
    }

    fn at(&self, y: &[f64]) -> f64 {
        interpolate(&self.d.result.time_s, y, self.t)
    }

    fn to_screen(&self, x: f64, y: f64) -> Pos2 {
        self.vp.to_screen(x, y)
    }

    /// Girder i's left end in the drawing: at rest, moved by its absolute displacement.
    fn girder_left(&self, i: usize) -> f64 {
        self.rest[i] + self.ex * self.at(&self.d.result.girder_absolute_m[i])
    }

    /// The faces of the abutments in the drawing (the left one's right face, the right one's
    /// left face), moved with their ground.
    fn abutment_faces(&self) -> [f64; 2] {
        let sc = &self.d.setup.scenario;
        [
            self.ex * self.d.ground_at(0.0, self.t),
            self.right_face + self.ex * self.d.ground_at(sc.length_m(), self.t),
        ]
    }

    /// A member's end at a joint, in the drawing.
    fn member_end(&self, member: Member, on_left: bool) -> f64 {
        match member {
            Member::Abutment => self.abutment_faces()[if on_left { 0 } else { 1 }],
            Member::Girder(i) => {
                let l = self.d.setup.scenario.girder(i).length_m;
                self.girder_left(i) + if on_left { l } else { 0.0 }
            }
        }
    }

    /// The ground line, with hatching under each support moving with its own ground.
    fn ground(&self, painter: &egui::Painter) {
        let brown = Color32::from_rgb(140, 110, 70);
        painter.line_segment(
            [
                self.to_screen(self.vp.left, 0.0),
                self.to_screen(self.vp.right, 0.0),
            ],
            Stroke::new(2.0, brown),
        );
        let sc = &self.d.setup.scenario;
        let n = 48;
        for k in 0..=n {
            let x0 = sc.length_m() * k as f64 / n as f64;
            let x = x0
                + self.ex * self.d.ground_at(x0, self.t)
                + (self.right_face - sc.length_m()) * k as f64 / n as f64;
            painter.line_segment(
                [self.to_screen(x, 0.0), self.to_screen(x - 0.8, -0.8)],
                Stroke::new(1.0, brown),
            );
        }
    }

    fn abutments(&self, painter: &egui::Painter, fill: Color32) {
        let [left, right] = self.abutment_faces();
        for (a, b) in [
            (left - ABUTMENT_WIDTH, left),
            (right, right + ABUTMENT_WIDTH),
        ] {
            painter.rect_filled(
                egui::Rect::from_two_pos(self.to_screen(a, 0.0), self.to_screen(b, GIRDER_TOP)),
                1.0,
                fill,
            );
        }
    }

    /// Each pier from its ground point to its top, and the bearing up to its girder.
    fn piers(&self, painter: &egui::Painter, column: Stroke) {
        let (sc, r) = (&self.d.setup.scenario, &self.d.result);
        for i in 0..sc.spans {
            let mid = 0.5 * sc.girder(i).length_m;
            let base =
                self.rest[i] + mid + self.ex * self.d.ground_at(sc.frame_position_m(i), self.t);
            let top = base + self.ex * self.at(&r.pier_displacement_m[i]);
            let girder = self.girder_left(i) + mid;
            painter.line_segment(
                [self.to_screen(base, 0.0), self.to_screen(top, PIER_TOP)],
                Stroke::new(column.width * 2.5, column.color),
            );
            painter.rect_filled(
                egui::Rect::from_center_size(self.to_screen(top, PIER_TOP), egui::vec2(18.0, 5.0)),
                1.0,
                column.color,
            );
            painter.line_segment(
                [
                    self.to_screen(top, PIER_TOP),
                    self.to_screen(girder, GIRDER_BOTTOM),
                ],
                Stroke::new(2.0, Color32::from_rgb(90, 140, 200)),
            );
        }
    }

    /// The girders as bars the GPU colours by their waves (Sears; none for rigid girders),
    /// the largest joint force over the smallest area saturating the map.
    fn girder_bars(&self) -> Vec<GpuBar> {
        let d = self.d;
        let scale = d.stress_scale_pa();
        (0..d.result.girder_waves.len())
            .map(|i| {
                d.girder_bar(
                    i,
                    self.girder_left(i),
                    (GIRDER_BOTTOM, GIRDER_TOP),
                    (scale, 1.0),
                )
            })
            .collect()
    }

    fn plain_girders(&self, painter: &egui::Painter, fill: Color32) {
        let sc = &self.d.setup.scenario;
        for i in 0..sc.spans {
            let x = self.girder_left(i);
            painter.rect_filled(
                egui::Rect::from_two_pos(
                    self.to_screen(x, GIRDER_BOTTOM),
                    self.to_screen(x + sc.girder(i).length_m, GIRDER_TOP),
                ),
                0.0,
                fill,
            );
        }
    }

    /// Each joint's seat, a ledge of the gap and the seat length below the member that holds
    /// it (an abutment, else the girder on the joint's left), coloured by how much of it the
    /// opening uses; and a mark at the joint, red while it carries force.
    fn joints(&self, painter: &egui::Painter) {
        let r = &self.d.result;
        let seat = self.d.setup.scenario.seat_length_m;
        for (j, joint) in r.joints.iter().enumerate() {
            let ledge = self.ex * (joint.gap_m + seat);
            let (a, b) = match joint.right {
                Member::Abutment => {
                    let face = self.member_end(Member::Abutment, false);
                    (face - ledge, face)
                }
                _ => {
                    let end = self.member_end(joint.left, true);
                    (end, end + ledge)
                }
            };
            let unseated = r
                .unseating
                .iter()
                .any(|u| u.joint == j && u.time_s <= self.t);
            let colour = seat_colour(self.d.seat_use(j, self.t), unseated);
            painter.rect_filled(
                egui::Rect::from_two_pos(
                    self.to_screen(a, GIRDER_BOTTOM - SEAT_DEPTH),
                    self.to_screen(b, GIRDER_BOTTOM),
                ),
                1.0,
                colour,
            );
            let force = self.at(&r.joint_force_n[j]);
            let x = 0.5 * (self.member_end(joint.left, true) + self.member_end(joint.right, false));
            let mark = if force > 0.0 {
                Color32::from_rgb(220, 60, 50)
            } else {
                Color32::from_rgb(240, 180, 60)
            };
            painter.circle_filled(
                self.to_screen(x, 0.5 * (GIRDER_BOTTOM + GIRDER_TOP)),
                4.0,
                mark,
            );
            painter.text(
                self.to_screen(x, GIRDER_TOP + 0.3),
                egui::Align2::CENTER_BOTTOM,
                format!("{j}"),
                super::lecture::font(painter.ctx(), 11.0),
                colour,
            );
        }
    }

    /// The time and scale, the joint pounding hardest now, and the seat closest to running out.
    fn captions(&self, painter: &egui::Painter, text: Color32) {
        let (r, rect) = (&self.d.result, self.vp.rect);
        painter.text(
            Pos2::new(rect.right() - 8.0, rect.top() + 6.0),
            egui::Align2::RIGHT_TOP,
            format!(
                "t = {:.4} s, displacements and gaps x{:.0}, heights not to scale",
                self.t, self.ex
            ),
            super::lecture::font(painter.ctx(), 12.0),
            text,
        );
        let pounding = (0..r.joints.len())
            .map(|j| (j, self.at(&r.joint_force_n[j])))
            .filter(|(_, f)| *f > 0.0)
            .max_by(|a, b| a.1.total_cmp(&b.1));
        if let Some((j, f)) = pounding {
            painter.text(
                Pos2::new(rect.left() + 8.0, rect.top() + 6.0),
                egui::Align2::LEFT_TOP,
                format!("pounding at joint {j}: {:.3e} N", f),
                super::lecture::font(painter.ctx(), 14.0),
                Color32::from_rgb(220, 60, 50),
            );
        }
        let seat = self.d.setup.scenario.seat_length_m;
        let unseated: Vec<String> = r
            .unseating
            .iter()
            .filter(|u| u.time_s <= self.t)
            .map(|u| format!("joint {} at {:.2} s", u.joint, u.time_s))
            .collect();
        let (line, colour) = if unseated.is_empty() {
            let (j, used) = (0..r.joints.len())
                .map(|j| (j, self.d.seat_use(j, self.t)))
                .max_by(|a, b| a.1.total_cmp(&b.1))
                .unwrap_or((0, 0.0));
            // A seat with room to spare reads in the text colour, not grey.
            let colour = if used < 0.5 {
                text
            } else {
                seat_colour(used, false)
            };
            (
                format!(
                    "seats: joint {j} uses the most now, {:.1} of {:.0} mm",
                    used.max(0.0) * seat * 1e3,
                    seat * 1e3
                ),
                colour,
            )
        } else {
            (
                format!("unseated: {}", unseated.join(", ")),
                seat_colour(1.0, true),
            )
        };
        painter.text(
            Pos2::new(rect.left() + 8.0, rect.bottom() - 6.0),
            egui::Align2::LEFT_BOTTOM,
            line,
            super::lecture::font(painter.ctx(), 12.0),
            colour,
        );
    }
}

pub fn draw(ui: &mut egui::Ui, rect: egui::Rect, d: &BridgeDrawing, t: f64, exaggeration: f64) {
    let frame = Frame::new(rect, d, t, exaggeration);
    let painter = ui.painter_at(rect);
    let dark = ui.visuals().dark_mode;
    let text = ui.visuals().text_color();
    let (concrete, column) = if dark {
        (
            Color32::from_gray(120),
            Stroke::new(2.0, Color32::from_gray(170)),
        )
    } else {
        (
            Color32::from_gray(150),
            Stroke::new(2.0, Color32::from_gray(80)),
        )
    };
    frame.ground(&painter);
    frame.abutments(&painter, concrete);
    frame.piers(&painter, column);
    let bars = frame.girder_bars();
    if bars.is_empty() {
        frame.plain_girders(&painter, concrete);
    } else {
        let vp = &frame.vp;
        let count = bars.len() as u32;
        vp.paint(
            ui,
            super::slots::BRIDGE_VIEW,
            View::Bars,
            uniforms([vp.left, vp.right, vp.bottom, vp.top], t, count),
            bars,
            d.gpu.clone(),
        );
    }
    frame.joints(&painter);
    frame.captions(&painter, text);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_seat_turns_from_grey_through_orange_to_red_as_its_margin_runs_out() {
        let grey = seat_colour(0.2, false);
        assert_eq!(grey, seat_colour(0.49, false));
        let orange = seat_colour(0.75, false);
        assert!(
            orange.r() > orange.b() && orange.g() > orange.b(),
            "{orange:?}"
        );
        let red = seat_colour(1.0, false);
        assert!(red.r() > 200 && red.g() < 60, "{red:?}");
        assert_eq!(seat_colour(0.1, true), red);
    }
}
