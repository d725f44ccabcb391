//! Frames of two buildings swaying and pounding, for slides: the window's own drawing of them
//! (`app::building_view::draw`) as a [`ViewAnimation`].

use super::animate_view::{SceneView, ViewAnimation};
use crate::app::building_view::{self, BuildingDrawing};
use crate::io::building_settings::BuildingSetup;
use crate::model::building::BuildingResult;
use crate::model::motion::GroundMotion;
use eframe::egui;

/// The animation of one building run.
pub type BuildingAnimation = ViewAnimation<BuildingDrawing>;

impl SceneView for BuildingDrawing {
    fn draw(&self, ui: &mut egui::Ui, rect: egui::Rect, t: f64, exaggeration: f64) {
        building_view::draw(ui, rect, self, t, exaggeration)
    }

    fn end_s(&self) -> f64 {
        self.result.time_s.last().copied().unwrap_or(0.0)
    }

    /// The slabs' colour saturates at the run's peak pounding force over the slab's area.
    fn colour_bar(&self) -> (&'static str, [String; 2]) {
        let sc = &self.setup.scenario;
        let areas: Vec<f64> = [&sc.left, &sc.right]
            .iter()
            .flat_map(|b| (0..b.storeys).map(|j| b.slab(j).area_m2()))
            .collect();
        let (lo, hi) = areas
            .iter()
            .fold((f64::INFINITY, 0.0f64), |(a, b), &v| (a.min(v), b.max(v)));
        let force = self.result.max_pounding_force_n.max(1.0);
        let ends = if hi > 0.0 && (hi - lo) <= 1e-9 * hi {
            let peak = force / hi * 1e-6;
            [format!("{peak:+.3} MPa"), format!("{:+.3} MPa", -peak)]
        } else {
            ["+ peak F / A".to_string(), "- peak F / A".to_string()]
        };
        ("slab stress", ends)
    }
}

impl BuildingAnimation {
    /// Over the whole run, drift exaggerated 20 times (the window's default).
    pub fn new(
        setup: BuildingSetup,
        motion: GroundMotion,
        result: BuildingResult,
        title: String,
        size: (u32, u32),
        frames: usize,
    ) -> Self {
        Self::of(
            BuildingDrawing::new(setup, motion, result),
            title,
            size,
            frames,
        )
    }
}
