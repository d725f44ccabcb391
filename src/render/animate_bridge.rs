//! Frames of a bridge pounding at its joints, for slides: the window's own drawing of it in
//! elevation (`app::bridge_view::draw`: frames, joints, seats, the girders' stress waves on the
//! GPU) as a [`ViewAnimation`].

use super::animate_view::{SceneView, ViewAnimation};
use crate::app::bridge_view::{self, BridgeDrawing};
use crate::io::bridge_settings::BridgeSetup;
use crate::model::bridge::BridgeResult;
use crate::model::motion::GroundMotion;
use eframe::egui;

/// The animation of one bridge run.
pub type BridgeAnimation = ViewAnimation<BridgeDrawing>;

impl SceneView for BridgeDrawing {
    fn draw(&self, ui: &mut egui::Ui, rect: egui::Rect, t: f64, exaggeration: f64) {
        bridge_view::draw(ui, rect, self, t, exaggeration)
    }

    fn end_s(&self) -> f64 {
        self.result.duration_s
    }

    /// As the window colours the girders: the largest joint force over the smallest girder
    /// area saturates the map.
    fn colour_bar(&self) -> (&'static str, [String; 2]) {
        let peak = self.stress_scale_pa() * 1e-6;
        (
            "girder stress",
            [format!("{peak:+.3} MPa"), format!("{:+.3} MPa", -peak)],
        )
    }
}

impl BridgeAnimation {
    /// Over the whole run, displacements exaggerated 20 times (the window's default).
    pub fn new(
        setup: BridgeSetup,
        motion: GroundMotion,
        result: BridgeResult,
        title: String,
        size: (u32, u32),
        frames: usize,
    ) -> Self {
        let stats = motion.stats();
        let drawing = BridgeDrawing::with_stats(setup, motion, result, stats);
        Self::of(drawing, title, size, frames)
    }
}
