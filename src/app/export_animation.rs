//! File > Export animation: the scene's run rendered offscreen, frame by frame, into a GIF or an
//! APNG on a thread of its own (the renderer the command line uses), with the view, the time
//! range, the frame rate, the duration and the pixel size chosen in the menu.

use super::export::Exporter;
use crate::io::bridge_settings::BridgeSetup;
use crate::io::building_settings::BuildingSetup;
use crate::io::settings::ImpactSetup;
use crate::model::bridge::BridgeResult;
use crate::model::building::BuildingResult;
use crate::model::impact::ImpactResult;
use crate::model::motion::GroundMotion;
use crate::render::animate::{AnimView, ImpactAnimation};
use crate::render::animate_bridge::BridgeAnimation;
use crate::render::animate_buildings::BuildingAnimation;
use crate::render::animate_view::{SceneView, ViewAnimation};
use crate::render::offscreen::Offscreen;
use eframe::egui;
use std::path::PathBuf;

/// The run an animation shows, copied when its export starts.
pub enum AnimationSource {
    Impact {
        setup: Box<ImpactSetup>,
        result: Box<ImpactResult>,
    },
    Buildings {
        setup: Box<BuildingSetup>,
        motion: GroundMotion,
        result: Box<BuildingResult>,
    },
    Bridge {
        setup: Box<BridgeSetup>,
        motion: GroundMotion,
        result: Box<BridgeResult>,
    },
}

/// The menu's choices.
pub struct AnimationSettings {
    pub view: AnimView,
    /// Start and end of the animated time [s]; an end of 0 runs to the end of the run.
    pub start_s: f64,
    pub end_s: f64,
    pub fps: f64,
    pub duration_s: f64,
    pub size: [u32; 2],
    /// APNG (.png) instead of GIF.
    pub apng: bool,
}

impl Default for AnimationSettings {
    fn default() -> Self {
        AnimationSettings {
            view: AnimView::Both,
            start_s: 0.0,
            end_s: 0.0,
            fps: 30.0,
            duration_s: 4.0,
            size: [1280, 720],
            apng: false,
        }
    }
}

impl AnimationSettings {
    /// The menu's controls; `true` when its export button was pressed. `impact` picks the
    /// time unit (ms for an impact, s for buildings) and offers the view.
    pub fn ui(&mut self, ui: &mut egui::Ui, impact: bool, enabled: bool) -> bool {
        if impact {
            ui.horizontal(|ui| {
                ui.label("view");
                for (v, name) in [
                    (AnimView::Bars, "bars"),
                    (AnimView::Xt, "x-t"),
                    (AnimView::Both, "both"),
                ] {
                    ui.radio_value(&mut self.view, v, name);
                }
            });
        }
        let (unit, factor) = if impact { ("ms", 1e3) } else { ("s", 1.0) };
        ui.horizontal(|ui| {
            ui.label("time from");
            let mut from = self.start_s * factor;
            ui.add(
                egui::DragValue::new(&mut from)
                    .range(0.0..=1e6)
                    .suffix(unit),
            );
            ui.label("to");
            let mut to = self.end_s * factor;
            ui.add(egui::DragValue::new(&mut to).range(0.0..=1e6).suffix(unit))
                .on_hover_text("0: to the end of the run");
            self.start_s = from / factor;
            self.end_s = to / factor;
        });
        ui.horizontal(|ui| {
            ui.label("frames per second");
            ui.add(egui::DragValue::new(&mut self.fps).range(1.0..=50.0));
            ui.label("duration");
            ui.add(
                egui::DragValue::new(&mut self.duration_s)
                    .range(0.2..=60.0)
                    .speed(0.1)
                    .suffix(" s"),
            );
        });
        ui.horizontal(|ui| {
            ui.label("size");
            ui.add(
                egui::DragValue::new(&mut self.size[0])
                    .range(160..=3840)
                    .suffix(" px"),
            );
            ui.label("x");
            ui.add(
                egui::DragValue::new(&mut self.size[1])
                    .range(120..=2160)
                    .suffix(" px"),
            );
        });
        ui.checkbox(&mut self.apng, "APNG (.png) instead of GIF");
        ui.add_enabled(enabled, egui::Button::new("Export animation"))
            .on_disabled_hover_text("needs a solved impact, building or bridge run on screen")
            .clicked()
    }

    fn frames(&self) -> usize {
        (self.fps * self.duration_s).round().clamp(2.0, 2000.0) as usize
    }

    /// The time range for a run ending at `end`.
    fn range(&self, end: f64) -> (f64, f64) {
        let to = if self.end_s > 0.0 { self.end_s } else { end };
        (self.start_s.min(to), to)
    }
}

/// An animation's rendering, to run on the export thread.
type RenderJob = Box<dyn FnOnce(&mut Offscreen) -> Result<(), String> + Send>;

/// The rendering of a scene's animation over the menu's time range (`range` of the run's end).
fn view_job<D: SceneView + Send + 'static>(
    mut a: ViewAnimation<D>,
    range: impl Fn(f64) -> (f64, f64),
    path: PathBuf,
    fps: f64,
) -> RenderJob {
    a.t_range = range(a.t_range.1);
    Box::new(move |t| {
        a.write(t, &path, fps, &mut |_| {})
            .map_err(|e| e.to_string())
    })
}

impl Exporter {
    /// Renders `source` as `<prefix>-animation.gif` (or .png) on a thread of its own.
    pub fn export_animation(&self, source: AnimationSource) {
        let s = &self.animation;
        let ext = if s.apng { "png" } else { "gif" };
        let path = PathBuf::from(format!("{}-animation.{ext}", self.prefix));
        let (size, frames, fps) = ((s.size[0], s.size[1]), s.frames(), s.fps);
        let (view, range) = (s.view, |end| s.range(end));
        let job: RenderJob = match source {
            AnimationSource::Impact { setup, result } => {
                let title = format!("{} model: stress waves", setup.model.name());
                let mut a =
                    ImpactAnimation::new(&setup.scenario, &result, title, view, size, frames);
                a.t_range = range(a.t_range.1);
                let path = path.clone();
                Box::new(move |t| {
                    a.write(t, &path, fps, &mut |_| {})
                        .map_err(|e| e.to_string())
                })
            }
            AnimationSource::Buildings {
                setup,
                motion,
                result,
            } => {
                let title = format!("Two buildings: {} contact", result.contact.name());
                let a = BuildingAnimation::new(*setup, motion, *result, title, size, frames);
                view_job(a, range, path.clone(), fps)
            }
            AnimationSource::Bridge {
                setup,
                motion,
                result,
            } => {
                let title = format!("A bridge: {} contact", result.contact.name());
                let a = BridgeAnimation::new(*setup, motion, *result, title, size, frames);
                view_job(a, range, path.clone(), fps)
            }
        };
        self.spawn(move || {
            let mut target = Offscreen::headless(size).map_err(|e| e.to_string())?;
            job(&mut target).map_err(|e| format!("animation: {e}"))?;
            Ok(format!("wrote {} ({frames} frames)", path.display()))
        });
    }
}
