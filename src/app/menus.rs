//! The top bar (scenes, presets, theme, help), the File menu and what its dialogs bring back.

use super::{PoundingApp, SceneKind, dialog};
use crate::io::preset::{self, EMBEDDED};
use eframe::egui;

impl PoundingApp {
    pub(super) fn top_bar(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            // On a projector the bar holds the lesson's title instead.
            if !(self.lecture && self.lesson.is_some()) {
                ui.strong("Pounding Lab");
            }
            ui.menu_button("File", |ui| self.file_menu(ui))
                .response
                .on_hover_text("Exports: plots, screenshots");
            ui.menu_button("Lessons", |ui| self.lessons_menu(ui))
                .response
                .on_hover_text("Guided lessons: predict, observe, explain");
            ui.menu_button("View", |ui| self.view_menu(ui))
                .response
                .on_hover_text("Lecture mode and the theme");
            // In a lesson shown in lecture mode the step decides the scene and the settings:
            // the bar keeps only the menus, readable at 1280 x 720.
            if self.lecture
                && let Some(lesson) = &self.lesson
            {
                ui.separator();
                ui.strong(&lesson.lesson.title);
                ui.separator();
                let p = self.playback();
                if p.bar_ui(ui) {
                    p.playing = true;
                }
                return;
            }
            ui.separator();
            // A lesson step decides its scene: the ways of replacing it are closed (the lock
            // itself is held in lesson_gate, whatever changes the scene).
            self.scene_tabs(ui);
            ui.separator();
            self.scene_presets(ui);
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

    /// The scene tabs, closed in a lesson.
    fn scene_tabs(&mut self, ui: &mut egui::Ui) {
        for (kind, label, about) in [
            (
                SceneKind::BarImpact,
                "Bar impact",
                "One impact, one model, every readout",
            ),
            (
                SceneKind::WaveVsLumped,
                "Wave vs lumped",
                "Sears, wave theory, lumped and FE models overlaid",
            ),
            (
                SceneKind::Buildings,
                "Building pounding",
                "Two buildings swaying in an earthquake, with and without pounding",
            ),
            (
                SceneKind::Bridge,
                "Bridge pounding",
                "Bridge girders pounding at their joints, stress waves in the deck, seats running out",
            ),
            (
                SceneKind::Study,
                "Parameter study",
                "One setting swept over a range: peak force, duration and e per model",
            ),
        ] {
            if self
                .open_button(ui, egui::Button::selectable(self.scene == kind, label))
                .on_hover_text(about)
                .clicked()
            {
                self.scene = kind;
            }
        }
    }

    /// A button that replaces the scene: enabled unless a lesson step decides the scene.
    fn open_button(&self, ui: &mut egui::Ui, button: egui::Button) -> egui::Response {
        ui.add_enabled(!self.scene_locked(), button)
            .on_disabled_hover_text(
                "A lesson step decides its scene and settings: Leave the lesson to explore",
            )
    }

    /// The shown scene's presets: pick, load, reset.
    fn scene_presets(&mut self, ui: &mut egui::Ui) {
        if self.scene == SceneKind::Buildings {
            let mut load = None;
            if self
                .open_button(ui, egui::Button::new("Paper's buildings"))
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
            if self
                .open_button(ui, egui::Button::new("Load preset"))
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
        } else if self.scene == SceneKind::Bridge {
            self.bridge_preset_ui(ui);
        } else {
            self.preset_ui(ui);
        }
    }

    /// The bridge presets, and loading one into the Bridge pounding scene.
    fn bridge_preset_ui(&mut self, ui: &mut egui::Ui) {
        let label = ui.label("preset").id;
        egui::ComboBox::from_id_salt("bridge-preset")
            .selected_text(&self.bridge_preset)
            .show_ui(ui, |ui| {
                for (name, text) in EMBEDDED
                    .iter()
                    .filter(|(_, t)| preset::scene(t) == "bridge")
                {
                    ui.selectable_value(&mut self.bridge_preset, name.to_string(), *name)
                        .on_hover_text(preset::description(text).unwrap_or_default());
                }
            })
            .response
            .labelled_by(label);
        if self
            .open_button(ui, egui::Button::new("Load preset"))
            .on_hover_text("Replace the bridge by the preset's")
            .clicked()
        {
            match preset::load_for::<crate::io::bridge_settings::BridgeSetup>(
                &self.bridge_preset,
                "bridge",
            ) {
                Ok(s) => {
                    self.bridge.setup = s;
                    self.bridge.reset_fields();
                    self.bridge.request();
                }
                Err(e) => self.message = Some((e.to_string(), true)),
            }
        }
    }

    fn lessons_menu(&mut self, ui: &mut egui::Ui) {
        for name in crate::lesson::builtin_names() {
            let title = crate::lesson::builtin(name)
                .map(|l| l.title)
                .unwrap_or_else(|e| e.to_string());
            let done = self.progress.0.get(name).map(|p| p.step + 1);
            let label = match done {
                Some(k) => format!("{title} (at step {k})"),
                None => title,
            };
            if ui.button(label).on_hover_text(name).clicked() {
                let step = self.resume_step(name);
                self.message = self.open_lesson(name, step).err().map(|e| (e, true));
                ui.close();
            }
        }
        ui.separator();
        ui.horizontal(|ui| {
            let label = ui.label("lesson file").id;
            ui.add(egui::TextEdit::singleline(&mut self.lesson_path).desired_width(160.0))
                .labelled_by(label);
            if ui.button("Open lesson").clicked() {
                let path = self.lesson_path.clone();
                self.message = self.open_lesson(&path, 0).err().map(|e| (e, true));
                ui.close();
            }
        });
        if self.lesson.is_some() && ui.button("Leave the lesson").clicked() {
            self.close_lesson();
            ui.close();
        }
    }

    fn view_menu(&mut self, ui: &mut egui::Ui) {
        let mut lecture = self.lecture;
        if ui
            .checkbox(&mut lecture, "Lecture mode (F5)")
            .on_hover_text(
                "Large and high-contrast for a projector; in a lesson only the step's settings",
            )
            .changed()
        {
            self.set_lecture(ui.ctx(), lecture);
            ui.close();
        }
        let mut teacher = self.teacher;
        if ui
            .checkbox(&mut teacher, "Teacher mode")
            .on_hover_text(
                "A lesson's teacher notes: its goals, the model's limits and the usual \
                 misconceptions (they answer some of the questions: not for a student's screen)",
            )
            .changed()
        {
            self.teacher = teacher;
            ui.close();
        }
        let mut smooth = self.smooth_lines;
        if ui
            .checkbox(&mut smooth, "Smooth lines")
            .on_hover_text(
                "Anti-aliased lines and edges. Off at first on a software renderer (no GPU): \
                 every line then takes a third of the triangles, and a dragged slider shows its \
                 result a frame sooner",
            )
            .changed()
        {
            self.smooth_lines = smooth;
            self.smooth_lines_chosen = true;
            ui.ctx().tessellation_options_mut(|o| o.feathering = smooth);
        }
    }

    fn file_menu(&mut self, ui: &mut egui::Ui) {
        let recorded = matches!(self.scene, SceneKind::Buildings | SceneKind::Bridge);
        let open = !self.scene_locked();
        let why = "A lesson step decides its scene and record: Leave the lesson to open another";
        if !recorded {
            if ui
                .add_enabled(open, egui::Button::new("Open scene..."))
                .on_disabled_hover_text(why)
                .clicked()
            {
                self.dialogs.ask(dialog::Purpose::OpenScene, &self.path);
                ui.close();
            }
            if ui.button("Save scene as...").clicked() {
                self.dialogs.ask(dialog::Purpose::SaveScene, &self.path);
                ui.close();
            }
        } else if ui
            .add_enabled(open, egui::Button::new("Open ground motion..."))
            .on_disabled_hover_text(why)
            .clicked()
        {
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
        ui.menu_button("Export animation", |ui| self.animation_menu(ui));
        if ui
            .button("Export lesson results (CSV, JSON)")
            .on_hover_text(
                "Every lesson's answered predictions (first answer, right or not, when) and met \
                 tasks, for a teacher to collect",
            )
            .clicked()
        {
            self.message = Some(self.export_lesson_results());
            ui.close();
        }
    }

    /// File > Export animation: the shown run (an impact, the buildings or the bridge) as a GIF
    /// or APNG.
    fn animation_menu(&mut self, ui: &mut egui::Ui) {
        let impact = self.scene == SceneKind::BarImpact;
        let has = match self.scene {
            SceneKind::BarImpact => self.bar.animation_source().is_some(),
            SceneKind::Buildings => self.buildings.animation_source().is_some(),
            SceneKind::Bridge => self.bridge.animation_source().is_some(),
            _ => false,
        };
        if self.exporter.animation.ui(ui, impact, has) {
            let source = match self.scene {
                SceneKind::BarImpact => self.bar.animation_source(),
                SceneKind::Bridge => self.bridge.animation_source(),
                _ => self.buildings.animation_source(),
            };
            if let Some(s) = source {
                self.exporter.export_animation(s());
                self.message = Some(("rendering the animation...".into(), false));
            }
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
        let load = self
            .open_button(ui, egui::Button::new("Load preset"))
            .on_hover_text("Replace the scene's parameters by the preset")
            .clicked();
        let reset = self
            .open_button(ui, egui::Button::new("Reset"))
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
        if self.open_button(ui, egui::Button::new("Open")).clicked() {
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
        let text = preset::impact_to_toml(&self.current().core().setup);
        self.message = Some(match std::fs::write(&self.path, text) {
            Ok(()) => (format!("saved {}", self.path), false),
            Err(e) => (format!("could not save {}: {e}", self.path), true),
        });
    }

    /// Acts on a file dialog that has closed.
    pub(super) fn dialog_done(&mut self) {
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
            dialog::Purpose::Motion if self.scene == SceneKind::Bridge => {
                self.bridge.load_motion(shown)
            }
            dialog::Purpose::Motion => self.buildings.load_motion(shown),
        }
    }
}
