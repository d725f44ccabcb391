//! What the window asks of whichever scene is on screen, so the frame, the status bar and the
//! File menu handle every scene alike (a new scene implements this and nothing else changes).

use super::bar_scene::BarScene;
use super::bridge_scene::BridgeScene;
use super::building_scene::BuildingScene;
use super::compare_scene::CompareScene;
use super::export::{Exporter, ShownPlot};
use super::playback::Playback;
use super::study_scene::StudyScene;
use eframe::egui;
use std::time::Duration;

pub trait Scene {
    fn playback(&mut self) -> &mut Playback;
    /// A solve is under way.
    fn busy(&self) -> bool;
    /// How far a solve that has taken longer than a frame has got (0 to 1).
    fn progress(&self) -> Option<f64>;
    /// Stops the solve under way; the last result stays.
    fn cancel(&mut self);
    /// The last solve's own time, and the time from the change to its result.
    fn timings(&self) -> (Duration, Duration);
    /// What the status bar says while a solve is under way.
    fn solving_note(&self) -> String {
        "solving...".into()
    }
    /// What the change-to-result time leaves out (a scene whose solve lands in stages), for
    /// its tooltip.
    fn later_stages(&self) -> Option<String> {
        None
    }
    /// The animated view's rectangle last frame.
    fn view_rect(&self) -> Option<egui::Rect>;
    /// The plots on screen last frame, by export name.
    fn shown_plots(&self) -> Vec<(&str, &ShownPlot)>;
    fn params_ui(&mut self, ui: &mut egui::Ui);
    fn main_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter);
}

/// The Scene of an impact scene: its core's playback and view, its own slot and panels.
macro_rules! impact_scene {
    ($scene:ty) => {
        impl Scene for $scene {
            fn playback(&mut self) -> &mut Playback {
                &mut self.core.playback
            }
            fn busy(&self) -> bool {
                <$scene>::busy(self)
            }
            fn progress(&self) -> Option<f64> {
                <$scene>::progress(self)
            }
            fn cancel(&mut self) {
                <$scene>::cancel(self)
            }
            fn timings(&self) -> (Duration, Duration) {
                self.slot.timings()
            }
            fn view_rect(&self) -> Option<egui::Rect> {
                self.core.view_rect
            }
            fn shown_plots(&self) -> Vec<(&str, &ShownPlot)> {
                <$scene>::shown_plots(self)
            }
            fn params_ui(&mut self, ui: &mut egui::Ui) {
                <$scene>::params_ui(self, ui)
            }
            fn main_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter) {
                <$scene>::main_ui(self, ui, exporter)
            }
        }
    };
}

impact_scene!(BarScene);
impact_scene!(CompareScene);

impl Scene for BuildingScene {
    fn playback(&mut self) -> &mut Playback {
        &mut self.playback
    }
    fn busy(&self) -> bool {
        BuildingScene::busy(self)
    }
    fn progress(&self) -> Option<f64> {
        BuildingScene::progress(self)
    }
    fn cancel(&mut self) {
        BuildingScene::cancel(self)
    }
    fn timings(&self) -> (Duration, Duration) {
        self.slot.timings()
    }
    fn solving_note(&self) -> String {
        BuildingScene::solving_note(self)
    }
    fn later_stages(&self) -> Option<String> {
        Some(BuildingScene::later_stages(self))
    }
    fn view_rect(&self) -> Option<egui::Rect> {
        self.view_rect
    }
    fn shown_plots(&self) -> Vec<(&str, &ShownPlot)> {
        BuildingScene::shown_plots(self)
    }
    fn params_ui(&mut self, ui: &mut egui::Ui) {
        BuildingScene::params_ui(self, ui)
    }
    fn main_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter) {
        BuildingScene::main_ui(self, ui, exporter)
    }
}

impl Scene for BridgeScene {
    fn playback(&mut self) -> &mut Playback {
        &mut self.playback
    }
    fn busy(&self) -> bool {
        BridgeScene::busy(self)
    }
    fn progress(&self) -> Option<f64> {
        BridgeScene::progress(self)
    }
    fn cancel(&mut self) {
        BridgeScene::cancel(self)
    }
    fn timings(&self) -> (Duration, Duration) {
        self.slot.timings()
    }
    fn solving_note(&self) -> String {
        BridgeScene::solving_note(self)
    }
    fn later_stages(&self) -> Option<String> {
        Some(BridgeScene::later_stages(self))
    }
    fn view_rect(&self) -> Option<egui::Rect> {
        self.view_rect
    }
    fn shown_plots(&self) -> Vec<(&str, &ShownPlot)> {
        BridgeScene::shown_plots(self)
    }
    fn params_ui(&mut self, ui: &mut egui::Ui) {
        BridgeScene::params_ui(self, ui)
    }
    fn main_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter) {
        BridgeScene::main_ui(self, ui, exporter)
    }
}

impl Scene for StudyScene {
    fn playback(&mut self) -> &mut Playback {
        &mut self.playback
    }
    fn busy(&self) -> bool {
        StudyScene::busy(self)
    }
    fn progress(&self) -> Option<f64> {
        // The study shows its own progress bar and Cancel in its panel.
        None
    }
    fn cancel(&mut self) {
        StudyScene::cancel(self)
    }
    fn timings(&self) -> (Duration, Duration) {
        (self.solve_time, self.solve_time)
    }
    fn view_rect(&self) -> Option<egui::Rect> {
        None
    }
    fn shown_plots(&self) -> Vec<(&str, &ShownPlot)> {
        StudyScene::shown_plots(self)
    }
    fn params_ui(&mut self, ui: &mut egui::Ui) {
        StudyScene::params_ui(self, ui)
    }
    fn main_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter) {
        StudyScene::main_ui(self, ui, exporter)
    }
}
