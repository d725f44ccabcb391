//! What the window asks of whichever scene is on screen, so the frame, the status bar and the
//! File menu handle every scene alike (a new scene implements this and nothing else changes).

use super::bar_scene::BarScene;
use super::building_scene::BuildingScene;
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
    /// The animated view's rectangle last frame.
    fn view_rect(&self) -> Option<egui::Rect>;
    /// The plots on screen last frame, by export name.
    fn shown_plots(&self) -> Vec<(&str, &ShownPlot)>;
    fn params_ui(&mut self, ui: &mut egui::Ui);
    fn main_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter);
}

impl Scene for BarScene {
    fn playback(&mut self) -> &mut Playback {
        &mut self.playback
    }
    fn busy(&self) -> bool {
        BarScene::busy(self)
    }
    fn progress(&self) -> Option<f64> {
        BarScene::progress(self)
    }
    fn cancel(&mut self) {
        BarScene::cancel(self)
    }
    fn timings(&self) -> (Duration, Duration) {
        self.slot.timings()
    }
    fn view_rect(&self) -> Option<egui::Rect> {
        self.view_rect
    }
    fn shown_plots(&self) -> Vec<(&str, &ShownPlot)> {
        BarScene::shown_plots(self)
    }
    fn params_ui(&mut self, ui: &mut egui::Ui) {
        BarScene::params_ui(self, ui)
    }
    fn main_ui(&mut self, ui: &mut egui::Ui, exporter: &Exporter) {
        BarScene::main_ui(self, ui, exporter)
    }
}

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
