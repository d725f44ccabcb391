//! The explorer window: an eframe app with a wgpu view. Scenes share the physics core with the
//! command line; each one solves off the UI thread and draws only what it shows.

mod background;
mod bar_scene;
mod bar_view;
mod bridge_job;
mod bridge_params;
mod bridge_scene;
pub(crate) mod bridge_view;
mod bridge_xt;
mod building_job;
mod building_params;
mod building_scene;
mod building_study;
pub(crate) mod building_view;
mod compare_scene;
mod dialog;
mod drag;
mod energy_view;
mod export;
mod export_animation;
mod fill;
mod hysteresis_view;
mod impact_list;
mod impact_params;
mod impact_scene;
mod job_error;
mod later;
mod launch;
mod lecture;
mod legend;
mod lesson_gate;
mod lesson_panel;
pub mod lesson_player;
mod menus;
mod motion_cache;
mod motion_params;
mod paper_figures;
mod params;
mod persistence;
mod playback;
mod plot_view;
mod readouts;
mod scene;
mod series;
mod slots;
mod status;
mod study_scene;
mod sweep_panel;
mod visibility;
pub mod worker;
mod xt_view;

use crate::io::bridge_settings::BridgeSetup;
use crate::io::building_settings::BuildingSetup;
use crate::io::preset::{self, EMBEDDED};
use crate::io::settings::ImpactSetup;
use bar_scene::BarScene;
use bridge_scene::BridgeScene;
use building_scene::BuildingScene;
use compare_scene::CompareScene;
use eframe::egui;
use impact_scene::ImpactScene;
use scene::Scene;

pub use drag::DragSpec;
pub use launch::{HIDE_TIMINGS, Launch, SceneKind};
pub use lecture::ZOOM as LECTURE_ZOOM;
pub use lesson_panel::reflow;
pub use lesson_player::LessonPlayer;
use persistence::{BRIDGE_KEY, BUILDINGS_KEY, COMPARE_KEY, IMPACT_KEY, STUDY_KEY, UI_KEY, restore};
use status::ms;
use std::time::Instant;

pub struct PoundingApp {
    scene: SceneKind,
    bar: BarScene,
    compare: CompareScene,
    buildings: BuildingScene,
    bridge: BridgeScene,
    study: study_scene::StudyScene,
    dark: bool,
    help: bool,
    preset_choice: String,
    building_preset: String,
    bridge_preset: String,
    path: String,
    message: Option<(String, bool)>,
    exporter: export::Exporter,
    dialogs: dialog::Dialogs,
    /// A launch screenshot has been asked for and not yet written.
    screenshot_pending: bool,
    ui_ms: f64,
    frames: u64,
    launch: Launch,
    /// The lesson being played, and every lesson's progress.
    lesson: Option<lesson_player::LessonPlayer>,
    /// The lesson step's scene as the last frame left it: what its lock holds to.
    lesson_held: Option<lesson_gate::Held>,
    progress: lesson_player::Progress,
    /// Lecture mode: large, high-contrast, only what the step needs.
    lecture: bool,
    /// Teacher mode: a lesson's teacher notes (goals, the model's limits, the answers' traps)
    /// are shown; a student never sees them otherwise.
    teacher: bool,
    /// Lines anti-aliased (egui's feathering), and whether the user chose it (saved) rather
    /// than the adapter (off on a software renderer, where every line then costs a third of
    /// the triangles: a dragged slider's result shows in 40 ms there instead of 55).
    smooth_lines: bool,
    smooth_lines_chosen: bool,
    /// A lesson file's path typed in the Lessons menu.
    lesson_path: String,
    /// `--drag`: a setting moved every frame, and how soon its runs landed.
    drag: Option<drag::Drag>,
}

impl PoundingApp {
    pub fn new(cc: &eframe::CreationContext<'_>, launch: Launch) -> Self {
        let mut errors = vec![];
        let software = install_renderer(cc, &mut errors);
        let storage = cc.storage;
        let fresh = launch.preset.is_some();
        let Start {
            bar: bar_setup,
            compare: compare_setup,
            buildings: building_setup,
            bridge: bridge_setup,
            scene,
            dark,
            smooth_lines,
            building_launch,
        } = start(storage, &launch, &mut errors);
        let ctx = &cc.egui_ctx;
        let smooth_lines_chosen = smooth_lines.is_some();
        let smooth_lines = smooth_lines.unwrap_or(!(software && launch.plain_lines_on_software));
        ctx.tessellation_options_mut(|o| o.feathering = smooth_lines);
        ctx.set_theme(if dark {
            egui::Theme::Dark
        } else {
            egui::Theme::Light
        });
        let mut bar = BarScene::new(ctx, bar_setup);
        let mut compare = CompareScene::new(
            ctx,
            if launch.preset.is_some() {
                bar_setup
            } else {
                compare_setup
            },
        );
        let mut buildings = BuildingScene::new(ctx, building_setup);
        let mut bridge = BridgeScene::new(ctx, bridge_setup);
        if let Some(t) = launch.time_s {
            // A launch time holds every scene's animation there, paused.
            for p in [
                &mut bar.core.playback,
                &mut compare.core.playback,
                &mut buildings.playback,
                &mut bridge.playback,
            ] {
                p.playing = false;
                p.t = t;
            }
        }
        let (preset_choice, building_preset, bridge_preset) =
            launch_presets(&launch, building_launch);
        let mut study = study_scene::StudyScene::new(ctx, bar.core.setup);
        if let Some(text) = storage
            .and_then(|s| s.get_string(STUDY_KEY))
            .filter(|_| !fresh)
            && let Err(e) = study.restore(&text)
        {
            errors.push(e);
        }
        let (progress, progress_error) = lesson_player::Progress::from_stored(
            storage.and_then(|s| s.get_string(lesson_player::PROGRESS_KEY)),
        );
        errors.extend(progress_error);
        lecture::apply(ctx, launch.lecture, dark);
        let mut app = PoundingApp {
            scene,
            bar,
            compare,
            buildings,
            bridge,
            study,
            dark,
            help: false,
            preset_choice,
            building_preset,
            bridge_preset,
            path: "scene.toml".into(),
            message: (!errors.is_empty()).then(|| (errors.join("; "), true)),
            exporter: export::Exporter::default(),
            dialogs: dialog::Dialogs::default(),
            screenshot_pending: false,
            ui_ms: 0.0,
            frames: 0,
            lesson: None,
            lesson_held: None,
            progress,
            lecture: launch.lecture,
            teacher: launch.teacher,
            smooth_lines,
            smooth_lines_chosen,
            lesson_path: "lesson.toml".into(),
            drag: launch.drag.clone().map(drag::Drag::new),
            launch,
        };
        app.open_launch_lesson();
        app
    }

    /// Opens the lesson the launch asks for: `--step K` counts from 1; without it the lesson
    /// resumes where it was left.
    fn open_launch_lesson(&mut self) {
        let Some(name) = self.launch.lesson.clone() else {
            return;
        };
        let step = match self.launch.lesson_step {
            Some(k) => k.saturating_sub(1),
            None => self.resume_step(&name),
        };
        if let Err(e) = self.open_lesson(&name, step) {
            self.message = Some((e, true));
        }
    }

    /// The step a lesson was left at (from 0).
    fn resume_step(&self, name: &str) -> usize {
        let stem = std::path::Path::new(name)
            .file_stem()
            .map_or(name.to_string(), |s| s.to_string_lossy().into_owned());
        self.progress.0.get(&stem).map_or(0, |p| p.step)
    }

    /// Lecture mode on or off.
    pub fn set_lecture(&mut self, ctx: &egui::Context, on: bool) {
        self.lecture = on;
        lecture::apply(ctx, on, self.dark);
    }

    /// The bar scene on screen (the building scene when that is shown falls back to the bar
    /// scene for preset actions, which it does not take).
    fn current(&mut self) -> &mut dyn ImpactScene {
        match self.scene {
            SceneKind::WaveVsLumped => &mut self.compare,
            _ => &mut self.bar,
        }
    }

    /// The animation time of the scene on screen [s].
    pub fn animation_time(&self) -> f64 {
        match self.scene {
            SceneKind::BarImpact => self.bar.core.playback.t,
            SceneKind::WaveVsLumped => self.compare.core.playback.t,
            SceneKind::Buildings => self.buildings.playback.t,
            SceneKind::Bridge => self.bridge.playback.t,
            SceneKind::Study => self.study.playback.t,
        }
    }

    /// The scene on screen.
    pub fn scene_kind(&self) -> SceneKind {
        self.scene
    }

    /// Whether lecture mode is on.
    pub fn lecture(&self) -> bool {
        self.lecture
    }

    /// Whether teacher mode is on (View > Teacher mode, `--teacher`).
    pub fn teacher(&self) -> bool {
        self.teacher
    }

    /// Turns teacher mode on or off.
    pub fn set_teacher(&mut self, on: bool) {
        self.teacher = on;
    }

    /// A solve is under way in some scene.
    pub fn is_solving(&self) -> bool {
        self.bar.busy()
            || self.compare.busy()
            || self.buildings.busy()
            || self.bridge.busy()
            || self.study.busy()
    }

    /// The scene on screen.
    fn shown(&self) -> &dyn Scene {
        match self.scene {
            SceneKind::BarImpact => &self.bar,
            SceneKind::WaveVsLumped => &self.compare,
            SceneKind::Buildings => &self.buildings,
            SceneKind::Bridge => &self.bridge,
            SceneKind::Study => &self.study,
        }
    }

    /// The scene on screen, and the exporter its plots' buttons use.
    fn shown_mut(&mut self) -> (&mut dyn Scene, &export::Exporter) {
        let scene: &mut dyn Scene = match self.scene {
            SceneKind::BarImpact => &mut self.bar,
            SceneKind::WaveVsLumped => &mut self.compare,
            SceneKind::Buildings => &mut self.buildings,
            SceneKind::Bridge => &mut self.bridge,
            SceneKind::Study => &mut self.study,
        };
        (scene, &self.exporter)
    }

    /// A panel's frame. In the window the panels are not filled: the frame's clear, in their
    /// colour, is their background. A software rasterizer clears at memory speed but shades a
    /// painted rectangle pixel by pixel: on Mesa's llvmpipe with 2 cores, filling the whole
    /// window took 45-55 ms, a third of each frame.
    pub(super) fn panel_frame(&self, frame: egui::Frame) -> egui::Frame {
        if self.launch.background_by_clear {
            frame.fill(egui::Color32::TRANSPARENT)
        } else {
            frame
        }
    }

    /// `--drag`: this frame's change to the scene on screen, and what landed since the last.
    fn drag_frame(&mut self) {
        let Some(drag) = self.drag.as_mut() else {
            return;
        };
        match self.scene {
            SceneKind::Buildings => {
                let s = &mut self.buildings;
                if drag.step(&s.slot, &mut s.setup, BuildingSetup::apply_assignment) {
                    s.request();
                }
            }
            SceneKind::Bridge => {
                let s = &mut self.bridge;
                if drag.step(&s.slot, &mut s.setup, BridgeSetup::apply_assignment) {
                    s.request();
                }
            }
            _ => {
                drag.refused =
                    Some("only the buildings and bridge scenes (--scene) take a drag".into())
            }
        }
    }

    fn playback(&mut self) -> &mut playback::Playback {
        self.shown_mut().0.playback()
    }
}

impl PoundingApp {
    /// What arrived since the last frame: finished solves, a dragged setting, dropped files,
    /// dialogs' answers and exports' outcomes.
    fn take_arrivals(&mut self, ctx: &egui::Context) {
        self.bar.poll();
        self.compare.poll();
        self.buildings.poll();
        self.bridge.poll();
        // The study starts from the Bar impact and Building pounding scenes' settings; only the
        // shown study can Run.
        if self.scene == SceneKind::Study {
            self.study.base = self.bar.core.setup;
            // A building sweep starts from the Building pounding scene's settings.
            if self.study.buildings.base != self.buildings.setup {
                self.study.buildings.base.clone_from(&self.buildings.setup);
            }
        }
        self.study.poll();
        self.drag_frame();
        if self.scene_locked() {
            if building_scene::dropped_path(ctx).is_some() {
                self.message = Some((
                    "A lesson step decides its record: leave the lesson to open a dropped file"
                        .into(),
                    true,
                ));
            }
        } else if self.scene == SceneKind::Buildings {
            self.buildings.take_dropped(ctx);
        } else if self.scene == SceneKind::Bridge
            && let Some(path) = building_scene::dropped_path(ctx)
        {
            self.bridge.load_motion(path);
        }
        self.dialog_done();
        if self.dialogs.is_open() {
            ctx.request_repaint_after(std::time::Duration::from_millis(100));
        }
        if let Some(outcome) = self.exporter.poll() {
            if self.screenshot_pending {
                self.screenshot_pending = false;
                match &outcome {
                    Ok(m) => eprintln!("{m}"),
                    Err(e) => eprintln!("error: --screenshot: {e}"),
                }
            }
            self.message = Some(match outcome {
                Ok(m) => (m, false),
                Err(e) => (e, true),
            });
        }
    }

    /// The top bar, the status bar, the settings (under a lesson's panel) and the scene, or the
    /// prediction the scene waits for.
    fn panels(&mut self, ui: &mut egui::Ui) {
        playback::hoist(ui.ctx(), self.lecture && self.lesson.is_some());
        let side = self.panel_frame(egui::Frame::side_top_panel(ui.style()));
        egui::Panel::top("top")
            .frame(side)
            .show(ui, |ui| self.top_bar(ui));
        self.status_bar(ui);
        // A projector's lesson panel holds the step's text in lines a hall can read, and
        // leaves the results more than half the screen.
        let screen = ui.ctx().content_rect().width();
        let (width, widest) = if self.lecture {
            (0.42 * screen, 0.5 * screen)
        } else {
            (380.0, f32::INFINITY)
        };
        egui::Panel::left("params")
            .frame(side)
            .resizable(true)
            .default_size(width)
            .max_size(widest)
            .show(ui, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| {
                    if self.lesson.is_some() {
                        self.lesson_ui(ui);
                        ui.separator();
                    }
                    if self.lesson_shows_settings() {
                        self.shown_mut().0.params_ui(ui);
                    }
                });
            });
        let hidden = self.lesson_hides_results();
        let central = self.panel_frame(egui::Frame::central_panel(ui.style()));
        egui::CentralPanel::default().frame(central).show(ui, |ui| {
            if hidden {
                egui::ScrollArea::vertical().show(ui, |ui| self.prediction_waiting_ui(ui));
                return;
            }
            // A few points short of the panel: a view that fills it exactly would still show a
            // scroll bar for the rounding of its last row.
            fill::begin(ui.ctx(), ui.available_height() - 6.0);
            let (scene, exporter) = self.shown_mut();
            let shown = egui::ScrollArea::vertical().show(ui, |ui| scene.main_ui(ui, exporter));
            fill::end(ui.ctx(), shown.content_size.y);
        });
    }

    fn help_window(&mut self, ctx: &egui::Context) {
        let mut open = true;
        egui::Window::new("Help").open(&mut open).show(ctx, |ui| {
            ui.label("Space: play / pause    Right arrow: one step    R: restart    F1: this help");
            ui.label("The bars are coloured by axial stress: blue compression, red tension, grey stress-free.");
            ui.label("Fronts leave the contact, reflect at the free ends as tension and come back.");
            ui.label("Vertical marks show Sears' compression zones d; arrows the bars' rigid-body velocities.");
            ui.label("Typed values outside a field's range are refused and the range is shown.");
        });
        self.help = open;
    }

    /// Asks for the next frame while anything moves, and closes a launch that asked to end
    /// after N frames (once its screenshot is written).
    fn frame_end(&mut self, ctx: &egui::Context) {
        let busy = self.is_solving();
        // A launch that closes after N frames keeps frames coming even on a still scene.
        if self.playback().playing || busy || self.launch.exit_after_frames.is_some() {
            ctx.request_repaint();
        }
        self.frames += 1;
        if self
            .launch
            .exit_after_frames
            .is_none_or(|n| self.frames < n)
        {
            return;
        }
        // A requested screenshot arrives a frame later and is written off-thread: close only
        // once it is on disk.
        if let Some(path) = self.launch.screenshot.take() {
            self.exporter.screenshot_to(ctx, None, path);
            self.screenshot_pending = true;
        }
        if self.screenshot_pending {
            ctx.request_repaint();
        } else {
            if let Some(d) = self.drag.take() {
                eprintln!("{}", d.report());
            }
            ctx.send_viewport_cmd(egui::ViewportCommand::Close);
        }
    }
}

impl eframe::App for PoundingApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        let start = Instant::now();
        let ctx = ui.ctx().clone();
        self.keys(&ctx);
        self.lesson_keys(&ctx);
        let dt = ctx.input(|i| i.stable_dt) as f64;
        self.take_arrivals(&ctx);
        if self.lecture && !lecture::holds(&ctx) {
            lecture::apply(&ctx, true, self.dark);
        }
        self.lesson_frame();
        if self.lesson_held.is_none() {
            self.hold_lesson_scene();
        }
        self.playback().advance(dt.min(0.1));
        self.panels(ui);
        if self.help {
            self.help_window(&ctx);
        }
        self.frame_end(&ctx);
        self.enforce_lesson_lock();
        // A change held for a run goes now, unless this frame's own change replaced it.
        self.bar.slot.flush();
        self.compare.slot.flush();
        self.buildings.slot.flush();
        self.bridge.slot.flush();
        let ui_time = start.elapsed();
        self.ui_ms = ui_time.as_secs_f64() * 1e3;
        if let Some(d) = &mut self.drag {
            d.ui_time(ui_time);
        }
    }

    /// The panels' colour: where they leave the background to the clear (see
    /// [`PoundingApp::panel_frame`]) it is theirs, and where they are filled it is hidden.
    fn clear_color(&self, visuals: &egui::Visuals) -> [f32; 4] {
        visuals.panel_fill.to_normalized_gamma_f32()
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        // A measurement's drag is not the user's work: what they saved stays.
        if self.launch.drag.is_some() {
            return;
        }
        persistence::save(self, storage);
    }
}

/// Opens the window.
/// Installs the stress views' pipelines on the window's renderer; whether that renderer is a
/// software one (where lines start without anti-aliasing).
fn install_renderer(cc: &eframe::CreationContext<'_>, errors: &mut Vec<String>) -> bool {
    match cc.wgpu_render_state.as_ref() {
        Some(rs) => {
            if let Err(e) = crate::render::bars::install(rs) {
                errors.push(e);
            }
            rs.adapter.get_info().device_type == eframe::egui_wgpu::wgpu::DeviceType::Cpu
        }
        None => {
            errors.push("no wgpu renderer: the stress view is not drawn".into());
            false
        }
    }
}

/// The preset each scene's top bar names at launch: the launch's own where it is a shipped one
/// of that scene, else the scene's default.
fn launch_presets(launch: &Launch, building: Option<String>) -> (String, String, String) {
    let shipped = |p: &String| EMBEDDED.iter().any(|(n, _)| n == p);
    let impact = launch
        .preset
        .clone()
        .filter(shipped)
        .unwrap_or_else(|| preset::DEFAULT_PRESET.into());
    let building = building
        .filter(shipped)
        .unwrap_or_else(|| "paper-buildings".into());
    let bridge = launch
        .preset
        .clone()
        .filter(|p| {
            EMBEDDED
                .iter()
                .any(|(n, t)| n == p && preset::scene(t) == "bridge")
        })
        .unwrap_or_else(|| "bridge-3-span".into());
    (impact, building, bridge)
}

pub fn run(mut launch: Launch) -> Result<(), eframe::Error> {
    launch.background_by_clear = true;
    launch.plain_lines_on_software = true;
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_inner_size([1320.0, 900.0])
            .with_title("Pounding Lab"),
        ..Default::default()
    };
    eframe::run_native(
        "Pounding Lab",
        options,
        Box::new(move |cc| Ok(Box::new(PoundingApp::new(cc, launch)))),
    )
}

/// What a launch starts from: the last session's scenes (unless a preset was given), the
/// launch's preset in the scene it is written for, the theme and the scene shown.
struct Start {
    bar: ImpactSetup,
    compare: ImpactSetup,
    buildings: crate::io::building_settings::BuildingSetup,
    bridge: crate::io::bridge_settings::BridgeSetup,
    scene: SceneKind,
    dark: bool,
    /// Lines anti-aliased or not, where the user chose.
    smooth_lines: Option<bool>,
    /// The launch preset, where it is a buildings preset.
    building_launch: Option<String>,
}

fn start(
    storage: Option<&dyn eframe::Storage>,
    launch: &Launch,
    errors: &mut Vec<String>,
) -> Start {
    let fresh = launch.preset.is_some();
    let mut bar_setup = if fresh {
        ImpactSetup::default()
    } else {
        restore(storage, IMPACT_KEY, errors)
    };
    let compare_setup = if fresh {
        ImpactSetup::default()
    } else {
        restore(storage, COMPARE_KEY, errors)
    };
    let ui_state = storage
        .and_then(|s| s.get_string(UI_KEY))
        .unwrap_or_default();
    let dark = !ui_state.contains("light");
    let smooth_lines = ui_state
        .split(';')
        .find_map(|p| p.strip_prefix("smooth="))
        .and_then(|v| match v {
            "on" => Some(true),
            "off" => Some(false),
            _ => None,
        });
    let mut scene = ui_state
        .split(';')
        .find_map(|p| p.strip_prefix("scene="))
        .and_then(SceneKind::from_name)
        .unwrap_or(SceneKind::BarImpact);
    if let Some(s) = launch.scene {
        scene = s;
    }
    // A launch preset goes to the scene it is written for.
    let building_launch = launch
        .preset
        .as_deref()
        .filter(|p| preset::find(p).is_ok_and(|(text, _)| preset::scene(&text) == "buildings"));
    let bridge_launch = launch
        .preset
        .as_deref()
        .filter(|p| preset::find(p).is_ok_and(|(text, _)| preset::scene(&text) == "bridge"));
    if let Some(p) = launch
        .preset
        .as_deref()
        .filter(|_| building_launch.is_none() && bridge_launch.is_none())
    {
        match preset::load_for::<ImpactSetup>(p, "impact") {
            Ok(s) => bar_setup = s,
            Err(e) => errors.push(e.to_string()),
        }
    }
    let mut building_setup: crate::io::building_settings::BuildingSetup =
        preset::load_for("paper-buildings", "buildings").unwrap_or_default();
    if let Some(p) = building_launch {
        match preset::load_for(p, "buildings") {
            Ok(s) => building_setup = s,
            Err(e) => errors.push(e.to_string()),
        }
        if launch.scene.is_none() {
            scene = SceneKind::Buildings;
        }
    } else if let Some(text) = storage.and_then(|s| s.get_string(BUILDINGS_KEY)) {
        let mut restored = building_setup.clone();
        match preset::apply_text(&mut restored, &text, "the last session's building scene") {
            Ok(()) => building_setup = restored,
            Err(e) => errors.push(format!("{e} (the paper's buildings are used)")),
        }
    }
    let mut bridge_setup = crate::io::bridge_settings::BridgeSetup::default();
    if let Some(p) = bridge_launch {
        match preset::load_for(p, "bridge") {
            Ok(s) => bridge_setup = s,
            Err(e) => errors.push(e.to_string()),
        }
        if launch.scene.is_none() {
            scene = SceneKind::Bridge;
        }
    } else {
        match preset::load_for("bridge-3-span", "bridge") {
            Ok(s) => bridge_setup = s,
            Err(e) => errors.push(e.to_string()),
        }
        if let Some(text) = storage.and_then(|s| s.get_string(BRIDGE_KEY)) {
            let mut restored = bridge_setup.clone();
            match preset::apply_text(&mut restored, &text, "the last session's bridge scene") {
                Ok(()) => bridge_setup = restored,
                Err(e) => errors.push(format!("{e} (the bridge-3-span preset is used)")),
            }
        }
    }
    Start {
        bar: bar_setup,
        compare: compare_setup,
        buildings: building_setup,
        bridge: bridge_setup,
        scene,
        dark,
        smooth_lines,
        building_launch: building_launch.map(str::to_string),
    }
}
