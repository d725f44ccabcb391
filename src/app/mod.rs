//! The explorer window: an eframe app with a wgpu view. Scenes share the physics core with the
//! command line; each one solves off the UI thread and draws only what it shows.

mod background;
mod bar_scene;
mod bar_view;
mod building_params;
mod building_scene;
mod building_view;
mod dialog;
mod export;
mod impact_params;
mod paper_figures;
mod params;
mod playback;
mod plot_view;
mod scene;
mod series;
mod study_scene;
pub mod worker;

use crate::io::preset::{self, EMBEDDED};
use crate::io::settings::ImpactSetup;
use bar_scene::BarScene;
use building_scene::BuildingScene;
use eframe::egui::{self, Color32};
use scene::Scene;
use std::time::Instant;

/// Storage keys; the suffix is the format's version, so an older save is never misread.
const IMPACT_KEY: &str = "impact-scene-v1";
const COMPARE_KEY: &str = "compare-scene-v1";
const UI_KEY: &str = "ui-v1";
const BUILDINGS_KEY: &str = "buildings-scene-v1";
const STUDY_KEY: &str = "study-scene-v1";

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SceneKind {
    BarImpact,
    WaveVsLumped,
    Buildings,
    Study,
}

impl SceneKind {
    fn name(self) -> &'static str {
        match self {
            SceneKind::BarImpact => "bar",
            SceneKind::WaveVsLumped => "compare",
            SceneKind::Buildings => "buildings",
            SceneKind::Study => "study",
        }
    }
    pub fn from_name(s: &str) -> Option<Self> {
        [
            SceneKind::BarImpact,
            SceneKind::WaveVsLumped,
            SceneKind::Buildings,
            SceneKind::Study,
        ]
        .into_iter()
        .find(|k| k.name() == s)
    }
}

/// How the window starts (from `pounding window` or the defaults).
#[derive(Debug, Clone, Default)]
pub struct Launch {
    pub scene: Option<SceneKind>,
    pub preset: Option<String>,
    /// Close after this many frames (smoke tests, screenshots).
    pub exit_after_frames: Option<u64>,
    /// Start paused at this animation time [s].
    pub time_s: Option<f64>,
    /// Save a screenshot here before closing (with `exit_after_frames`).
    pub screenshot: Option<std::path::PathBuf>,
}

/// Set by snapshot tests: wall-clock timings (which differ run to run) print as "-".
pub static HIDE_TIMINGS: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// A duration in seconds shown in milliseconds with `decimals`.
fn ms(seconds: f64, decimals: usize) -> String {
    if HIDE_TIMINGS.load(std::sync::atomic::Ordering::Relaxed) {
        "- ms".into()
    } else {
        format!("{:.*} ms", decimals, seconds * 1e3)
    }
}

pub struct PoundingApp {
    scene: SceneKind,
    bar: BarScene,
    compare: BarScene,
    buildings: BuildingScene,
    study: study_scene::StudyScene,
    dark: bool,
    help: bool,
    preset_choice: String,
    building_preset: String,
    path: String,
    message: Option<(String, bool)>,
    exporter: export::Exporter,
    dialogs: dialog::Dialogs,
    /// A launch screenshot has been asked for and not yet written.
    screenshot_pending: bool,
    ui_ms: f64,
    frames: u64,
    launch: Launch,
}

fn restore(
    storage: Option<&dyn eframe::Storage>,
    key: &str,
    errors: &mut Vec<String>,
) -> ImpactSetup {
    let mut setup =
        preset::load_for::<ImpactSetup>(preset::DEFAULT_PRESET, "impact").unwrap_or_default();
    if let Some(text) = storage.and_then(|s| s.get_string(key)) {
        let mut restored = setup;
        match preset::apply_text(&mut restored, &text, "the last session's scene") {
            Ok(()) => setup = restored,
            Err(e) => errors.push(format!("{e} (the default scene is used)")),
        }
    }
    setup
}

impl PoundingApp {
    pub fn new(cc: &eframe::CreationContext<'_>, launch: Launch) -> Self {
        let mut errors = vec![];
        match cc.wgpu_render_state.as_ref() {
            Some(rs) => crate::render::bars::install(rs),
            None => errors.push("no wgpu renderer: the stress view is not drawn".into()),
        }
        let storage = cc.storage;
        let fresh = launch.preset.is_some();
        let mut bar_setup = if fresh {
            ImpactSetup::default()
        } else {
            restore(storage, IMPACT_KEY, &mut errors)
        };
        let compare_setup = if fresh {
            ImpactSetup::default()
        } else {
            restore(storage, COMPARE_KEY, &mut errors)
        };
        let ui_state = storage
            .and_then(|s| s.get_string(UI_KEY))
            .unwrap_or_default();
        let dark = !ui_state.contains("light");
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
        if let Some(p) = launch
            .preset
            .as_deref()
            .filter(|_| building_launch.is_none())
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
        let ctx = &cc.egui_ctx;
        ctx.set_theme(if dark {
            egui::Theme::Dark
        } else {
            egui::Theme::Light
        });
        let mut bar = BarScene::new(ctx, bar_setup, false);
        let mut compare = BarScene::new(
            ctx,
            if launch.preset.is_some() {
                bar_setup
            } else {
                compare_setup
            },
            true,
        );
        let mut buildings = BuildingScene::new(ctx, building_setup);
        if let Some(t) = launch.time_s {
            for p in [
                &mut bar.playback,
                &mut compare.playback,
                &mut buildings.playback,
            ] {
                p.playing = false;
                p.t = t;
            }
        }
        let mut study = study_scene::StudyScene::new(ctx, bar.setup);
        if let Some(text) = storage
            .and_then(|s| s.get_string(STUDY_KEY))
            .filter(|_| !fresh)
            && let Err(e) = study.restore(&text)
        {
            errors.push(e);
        }
        PoundingApp {
            scene,
            bar,
            compare,
            buildings,
            study,
            dark,
            help: false,
            preset_choice: launch
                .preset
                .clone()
                .filter(|p| EMBEDDED.iter().any(|(n, _)| n == p))
                .unwrap_or_else(|| preset::DEFAULT_PRESET.into()),
            building_preset: building_launch
                .filter(|p| EMBEDDED.iter().any(|(n, _)| n == p))
                .unwrap_or("paper-buildings")
                .to_string(),
            path: "scene.toml".into(),
            message: (!errors.is_empty()).then(|| (errors.join("; "), true)),
            exporter: export::Exporter::default(),
            dialogs: dialog::Dialogs::default(),
            screenshot_pending: false,
            ui_ms: 0.0,
            frames: 0,
            launch,
        }
    }

    /// The bar scene on screen (the building scene when that is shown falls back to the bar
    /// scene for preset actions, which it does not take).
    fn current(&mut self) -> &mut BarScene {
        match self.scene {
            SceneKind::WaveVsLumped => &mut self.compare,
            _ => &mut self.bar,
        }
    }

    /// A solve is under way in some scene.
    pub fn is_solving(&self) -> bool {
        self.bar.busy() || self.compare.busy() || self.buildings.busy() || self.study.busy()
    }

    /// The scene on screen.
    fn shown(&self) -> &dyn Scene {
        match self.scene {
            SceneKind::BarImpact => &self.bar,
            SceneKind::WaveVsLumped => &self.compare,
            SceneKind::Buildings => &self.buildings,
            SceneKind::Study => &self.study,
        }
    }

    /// The scene on screen, and the exporter its plots' buttons use.
    fn shown_mut(&mut self) -> (&mut dyn Scene, &export::Exporter) {
        let scene: &mut dyn Scene = match self.scene {
            SceneKind::BarImpact => &mut self.bar,
            SceneKind::WaveVsLumped => &mut self.compare,
            SceneKind::Buildings => &mut self.buildings,
            SceneKind::Study => &mut self.study,
        };
        (scene, &self.exporter)
    }

    fn playback(&mut self) -> &mut playback::Playback {
        self.shown_mut().0.playback()
    }

    fn top_bar(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            ui.strong("Pounding Lab");
            ui.menu_button("File", |ui| self.file_menu(ui))
                .response
                .on_hover_text("Exports: plots, screenshots");
            ui.separator();
            ui.selectable_value(&mut self.scene, SceneKind::BarImpact, "Bar impact")
                .on_hover_text("One impact, one model, every readout");
            ui.selectable_value(&mut self.scene, SceneKind::WaveVsLumped, "Wave vs lumped")
                .on_hover_text("Sears, wave theory, lumped and FE models overlaid");
            ui.selectable_value(&mut self.scene, SceneKind::Buildings, "Building pounding")
                .on_hover_text("Two buildings swaying in an earthquake, with and without pounding");
            ui.selectable_value(&mut self.scene, SceneKind::Study, "Parameter study")
                .on_hover_text(
                    "One setting swept over a range: peak force, duration and e per model",
                );
            ui.separator();
            if self.scene == SceneKind::Buildings {
                let mut load = None;
                if ui
                    .button("Paper's buildings")
                    .on_hover_text(
                        "The paper's Section 4 as published: Table 1 on 8 s of El Centro 1940",
                    )
                    .clicked()
                {
                    load = Some("paper-buildings".to_string());
                }
                let label = ui.label("preset").id;
                egui::ComboBox::from_id_salt("building-preset")
                    .selected_text(&self.building_preset)
                    .show_ui(ui, |ui| {
                        for (name, text) in EMBEDDED
                            .iter()
                            .filter(|(_, t)| preset::scene(t) == "buildings")
                        {
                            ui.selectable_value(&mut self.building_preset, name.to_string(), *name)
                                .on_hover_text(preset::description(text).unwrap_or_default());
                        }
                    })
                    .response
                    .labelled_by(label);
                if ui
                    .button("Load preset")
                    .on_hover_text("Replace the buildings by the preset's")
                    .clicked()
                {
                    load = Some(self.building_preset.clone());
                }
                if let Some(name) = load {
                    match preset::load_for::<crate::io::building_settings::BuildingSetup>(
                        &name,
                        "buildings",
                    ) {
                        Ok(s) => {
                            self.buildings.setup = s;
                            self.buildings.reset_fields();
                            self.buildings.request();
                        }
                        Err(e) => self.message = Some((e.to_string(), true)),
                    }
                }
            } else {
                self.preset_ui(ui);
            }
            ui.separator();
            if ui
                .button(if self.dark { "Light" } else { "Dark" })
                .on_hover_text("Switch theme")
                .clicked()
            {
                self.dark = !self.dark;
                ui.ctx().set_theme(if self.dark {
                    egui::Theme::Dark
                } else {
                    egui::Theme::Light
                });
            }
            ui.separator();
            if ui
                .button("Help")
                .on_hover_text("Keyboard and what you see (F1)")
                .clicked()
            {
                self.help = !self.help;
            }
        });
    }

    fn file_menu(&mut self, ui: &mut egui::Ui) {
        if self.scene != SceneKind::Buildings {
            if ui.button("Open scene...").clicked() {
                self.dialogs.ask(dialog::Purpose::OpenScene, &self.path);
                ui.close();
            }
            if ui.button("Save scene as...").clicked() {
                self.dialogs.ask(dialog::Purpose::SaveScene, &self.path);
                ui.close();
            }
        } else if ui.button("Open ground motion...").clicked() {
            self.dialogs.ask(dialog::Purpose::Motion, "");
            ui.close();
        }
        if ui.button("Choose export folder...").clicked() {
            self.dialogs
                .ask(dialog::Purpose::ExportFolder, &self.exporter.prefix);
            ui.close();
        }
        ui.separator();
        let e = &mut self.exporter;
        ui.horizontal(|ui| {
            let label = ui
                .label("export to")
                .on_hover_text("Folder and name stem: files are <this>-<plot>.<ext>")
                .id;
            ui.add(egui::TextEdit::singleline(&mut e.prefix).desired_width(180.0))
                .labelled_by(label);
        });
        ui.horizontal(|ui| {
            let label = ui.label("PNG size (width x height)").id;
            ui.add(
                egui::DragValue::new(&mut e.size[0])
                    .range(200..=8000)
                    .suffix(" px"),
            )
            .labelled_by(label);
            ui.label("x");
            ui.add(
                egui::DragValue::new(&mut e.size[1])
                    .range(150..=8000)
                    .suffix(" px"),
            )
            .labelled_by(label);
        });
        ui.horizontal(|ui| {
            let label = ui.label("text and line scale").id;
            ui.add(
                egui::DragValue::new(&mut e.scale)
                    .range(0.5..=4.0)
                    .speed(0.05),
            )
            .labelled_by(label);
        })
        .response
        .on_hover_text("2 draws text and lines twice as large (e.g. a 3200 x 1800 PNG for print)");
        ui.separator();
        let plots = self.shown().shown_plots();
        if ui
            .add_enabled(
                !plots.is_empty(),
                egui::Button::new("Export every plot (PNG, SVG, CSV)"),
            )
            .clicked()
        {
            for (name, plot) in plots {
                for ext in ["png", "svg", "csv"] {
                    self.exporter.export(plot, name, ext);
                }
            }
            ui.close();
        }
        if ui.button("Screenshot of the window").clicked() {
            self.exporter.screenshot(ui.ctx(), None, "window");
            ui.close();
        }
        let view = self.shown().view_rect();
        if ui
            .add_enabled(view.is_some(), egui::Button::new("Screenshot of the view"))
            .clicked()
        {
            self.exporter.screenshot(ui.ctx(), view, "view");
            ui.close();
        }
    }

    fn preset_ui(&mut self, ui: &mut egui::Ui) {
        let label = ui.label("preset").id;
        egui::ComboBox::from_id_salt("preset")
            .selected_text(&self.preset_choice)
            .show_ui(ui, |ui| {
                for (name, text) in EMBEDDED
                    .iter()
                    .filter(|(_, t)| preset::scene(t) == "impact")
                {
                    ui.selectable_value(&mut self.preset_choice, name.to_string(), *name)
                        .on_hover_text(preset::description(text).unwrap_or_default());
                }
            })
            .response
            .labelled_by(label);
        // Both buttons load the chosen preset (Reset reads as undoing edits); both are drawn
        // every frame, so neither is skipped when the other is clicked.
        let load = ui
            .button("Load preset")
            .on_hover_text("Replace the scene's parameters by the preset")
            .clicked();
        let reset = ui
            .button("Reset")
            .on_hover_text("Back to the preset's values")
            .clicked();
        if load || reset {
            let name = self.preset_choice.clone();
            self.message = self.current().load_preset(&name).err().map(|e| (e, true));
        }
        ui.separator();
        let label = ui.label("scene file").id;
        ui.add(egui::TextEdit::singleline(&mut self.path).desired_width(140.0))
            .labelled_by(label)
            .on_hover_text("A TOML scene file");
        if ui.button("Open").clicked() {
            self.open_scene();
        }
        if ui.button("Save").clicked() {
            self.save_scene();
        }
    }

    fn open_scene(&mut self) {
        let path = self.path.clone();
        self.message = Some(match self.current().load_preset(&path) {
            Ok(()) => (format!("loaded {path}"), false),
            Err(e) => (e, true),
        });
    }

    fn save_scene(&mut self) {
        let text = preset::impact_to_toml(&self.current().setup);
        self.message = Some(match std::fs::write(&self.path, text) {
            Ok(()) => (format!("saved {}", self.path), false),
            Err(e) => (format!("could not save {}: {e}", self.path), true),
        });
    }

    /// Acts on a file dialog that has closed.
    fn dialog_done(&mut self) {
        let Some((purpose, chosen)) = self.dialogs.poll() else {
            return;
        };
        let Some(path) = chosen else {
            self.message = Some((dialog::NOTHING_CHOSEN.into(), false));
            return;
        };
        let shown = path.display().to_string();
        match purpose {
            dialog::Purpose::OpenScene => {
                self.path = shown;
                self.open_scene();
            }
            dialog::Purpose::SaveScene => {
                self.path = shown;
                self.save_scene();
            }
            dialog::Purpose::ExportFolder => {
                self.exporter.prefix = path.join("pounding").display().to_string();
                self.message = Some((format!("exports go to {shown}"), false));
            }
            dialog::Purpose::Motion => self.buildings.load_motion(shown),
        }
    }

    fn keys(&mut self, ctx: &egui::Context) {
        if ctx.memory(|m| m.focused().is_some()) {
            return;
        }
        let (space, right, restart, help) = ctx.input(|i| {
            (
                i.key_pressed(egui::Key::Space),
                i.key_pressed(egui::Key::ArrowRight),
                i.key_pressed(egui::Key::R),
                i.key_pressed(egui::Key::F1),
            )
        });
        let playback = self.playback();
        if space {
            playback.playing = !playback.playing;
        }
        if right {
            playback.step();
        }
        if restart {
            playback.t = 0.0;
            playback.playing = true;
        }
        if help {
            self.help = !self.help;
        }
    }
}

impl eframe::App for PoundingApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        let start = Instant::now();
        let ctx = ui.ctx().clone();
        self.keys(&ctx);
        let dt = ctx.input(|i| i.stable_dt) as f64;
        for s in [&mut self.bar, &mut self.compare] {
            s.poll();
        }
        self.buildings.poll();
        // The study starts from the Bar impact scene's settings; only the shown study can Run.
        if self.scene == SceneKind::Study {
            self.study.base = self.bar.setup;
        }
        self.study.poll();
        if self.scene == SceneKind::Buildings {
            self.buildings.take_dropped(&ctx);
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
        self.playback().advance(dt.min(0.1));
        egui::Panel::top("top").show(ui, |ui| self.top_bar(ui));
        egui::Panel::bottom("status").show(ui, |ui| {
            ui.horizontal(|ui| {
                let (solve, latency) = self.shown().timings();
                let busy = self.shown().busy();
                ui.label(format!(
                    "UI {} | solve {} | change to result {}{}",
                    ms(self.ui_ms * 1e-3, 2),
                    ms(solve.as_secs_f64(), 3),
                    ms(latency.as_secs_f64(), 1),
                    if busy { " | solving..." } else { "" }
                ));
                if let Some(done) = self.shown().progress() {
                    ui.add(
                        egui::ProgressBar::new(done as f32)
                            .desired_width(160.0)
                            .show_percentage(),
                    );
                    if ui
                        .button("Cancel")
                        .on_hover_text("Stop this solve; the last result stays")
                        .clicked()
                    {
                        self.shown_mut().0.cancel();
                    }
                }
                if let Some((m, is_error)) = &self.message {
                    ui.separator();
                    let colour = if *is_error {
                        Color32::from_rgb(220, 60, 50)
                    } else {
                        ui.visuals().text_color()
                    };
                    ui.colored_label(colour, m);
                }
            });
        });
        egui::Panel::left("params")
            .resizable(true)
            .default_size(380.0)
            .show(ui, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| self.shown_mut().0.params_ui(ui));
            });
        egui::CentralPanel::default().show(ui, |ui| {
            let (scene, exporter) = self.shown_mut();
            egui::ScrollArea::vertical().show(ui, |ui| scene.main_ui(ui, exporter));
        });
        if self.help {
            let mut open = true;
            egui::Window::new("Help").open(&mut open).show(&ctx, |ui| {
                ui.label("Space: play / pause    Right arrow: one step    R: restart    F1: this help");
                ui.label("The bars are coloured by axial stress: blue compression, red tension, grey stress-free.");
                ui.label("Fronts leave the contact, reflect at the free ends as tension and come back.");
                ui.label("Vertical marks show Sears' compression zones d; arrows the bars' rigid-body velocities.");
                ui.label("Typed values outside a field's range are refused and the range is shown.");
            });
            self.help = open;
        }
        let busy = self.is_solving();
        // A launch that closes after N frames keeps frames coming even on a still scene.
        if self.playback().playing || busy || self.launch.exit_after_frames.is_some() {
            ctx.request_repaint();
        }
        self.frames += 1;
        if self
            .launch
            .exit_after_frames
            .is_some_and(|n| self.frames >= n)
        {
            // A requested screenshot arrives a frame later and is written off-thread: close
            // only once it is on disk.
            if let Some(path) = self.launch.screenshot.take() {
                self.exporter.screenshot_to(&ctx, None, path);
                self.screenshot_pending = true;
            }
            if self.screenshot_pending {
                ctx.request_repaint();
            } else {
                ctx.send_viewport_cmd(egui::ViewportCommand::Close);
            }
        }
        self.ui_ms = start.elapsed().as_secs_f64() * 1e3;
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        storage.set_string(IMPACT_KEY, preset::impact_to_toml(&self.bar.setup));
        storage.set_string(COMPARE_KEY, preset::impact_to_toml(&self.compare.setup));
        storage.set_string(STUDY_KEY, self.study.state());
        storage.set_string(
            BUILDINGS_KEY,
            preset::buildings_to_toml(&self.buildings.setup),
        );
        storage.set_string(
            UI_KEY,
            format!(
                "{};scene={}",
                if self.dark { "dark" } else { "light" },
                self.scene.name()
            ),
        );
    }
}

/// Opens the window.
pub fn run(launch: Launch) -> Result<(), eframe::Error> {
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
