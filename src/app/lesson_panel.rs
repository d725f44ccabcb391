//! The lesson panel and how a lesson step drives the window: the step's scene, preset and
//! overrides loaded, its panels shown (none until its prediction is answered), its settings
//! unlocked, its prediction judged and its task checked on every new result.

use super::impact_scene::ImpactScene;
use super::lesson_gate::{scene_of, step_opens};
use super::lesson_player::{LessonPlayer, Progress};
use super::visibility::{Lock, Visibility};
use super::{PoundingApp, SceneKind};
use crate::lesson::solve::SceneSetup;
use crate::lesson::{self, Context, LessonScene, Prediction};
use eframe::egui::{self, Color32, RichText};

const GOOD: Color32 = Color32::from_rgb(20, 140, 60);
const BAD: Color32 = Color32::from_rgb(200, 50, 40);

impl PoundingApp {
    /// Opens a lesson (shipped name or file) at step `step` (from 0).
    pub fn open_lesson(&mut self, name_or_path: &str, step: usize) -> Result<(), String> {
        let lesson = lesson::load(name_or_path).map_err(|e| e.to_string())?;
        if lesson.steps.is_empty() {
            return Err(format!("{name_or_path}: the lesson has no steps"));
        }
        self.lesson = Some(LessonPlayer::new(lesson, step));
        Ok(())
    }

    /// Leaves the lesson: every panel and setting back.
    pub fn close_lesson(&mut self) {
        self.lesson = None;
        self.lesson_held = None;
        self.apply_visibility();
    }

    /// Writes `<export prefix>-lesson-results.csv` and `.json`; the message to show, and
    /// whether it is an error.
    pub fn export_lesson_results(&mut self) -> (String, bool) {
        if let Some(p) = &self.lesson {
            p.record(&mut self.progress);
        }
        let rows = super::lesson_player::results(&self.progress, |n| lesson::load(n).ok());
        let stem = format!("{}-lesson-results", self.exporter.prefix);
        let json = serde_json::to_string_pretty(&rows).unwrap_or_default();
        let written = std::fs::write(
            format!("{stem}.csv"),
            super::lesson_player::results_csv(&rows),
        )
        .and_then(|_| std::fs::write(format!("{stem}.json"), json));
        match written {
            Ok(()) => (
                format!("wrote {stem}.csv and {stem}.json ({} rows)", rows.len()),
                false,
            ),
            Err(e) => (
                format!("lesson results: cannot write {stem}.csv: {e}"),
                true,
            ),
        }
    }

    /// The lesson on screen, if any.
    pub fn lesson_player(&self) -> Option<&LessonPlayer> {
        self.lesson.as_ref()
    }

    /// Turns to step `k` of the lesson (clamped).
    pub fn lesson_go_to(&mut self, k: usize) {
        if let Some(p) = &mut self.lesson {
            p.record(&mut self.progress);
            p.go_to(k);
            p.restore_answer(&self.progress);
        }
    }

    /// Sets one key of the step's scene as a slider would (a scripted change; the tests use it).
    pub fn lesson_set(&mut self, key: &str, value: &str) -> Result<(), String> {
        let Some(p) = &self.lesson else {
            return Err("no lesson is open".into());
        };
        if !step_opens(p, key) {
            return Err(format!("{key}: locked in this step"));
        }
        let v = crate::io::settings::SettingValue::from_cli(value);
        let r = match p.current().scene {
            LessonScene::Bar => self
                .bar
                .core
                .setup
                .apply(key, &v)
                .map(|_| self.bar.request()),
            LessonScene::Compare => self
                .compare
                .core
                .setup
                .apply(key, &v)
                .map(|_| self.compare.request()),
            LessonScene::Buildings => self
                .buildings
                .setup
                .apply(key, &v)
                .map(|_| self.buildings.request()),
            LessonScene::Bridge => self
                .bridge
                .setup
                .apply(key, &v)
                .map(|_| self.bridge.request()),
        };
        r.map_err(|e| format!("{}: {}", e.field, e.message))
    }

    /// Gives the answer to the step's prediction (as the panel's widgets would).
    pub fn lesson_answer(&mut self, choice: Option<usize>, number: Option<&str>) {
        if let Some(p) = &mut self.lesson {
            p.answer.choice = choice.or(p.answer.choice);
            if let Some(n) = number {
                p.answer.number = n.to_string();
            }
            if p.answer_given().is_ok() {
                p.judging = true;
            }
        }
    }

    /// Once a frame: loads the step's scene when it changed, applies what shows and what is
    /// unlocked, judges a waiting answer and checks the task on the latest result.
    pub(super) fn lesson_frame(&mut self) {
        let Some(p) = &mut self.lesson else { return };
        if !p.loaded {
            p.loaded = true;
            let step = p.current().clone();
            // The lock holds to the step's scene as loaded, not to the one before it.
            self.lesson_held = None;
            match SceneSetup::load(step.scene, step.preset.as_deref(), &step.set) {
                Ok(setup) => {
                    // The top bar names the preset the step loaded, not the last one picked.
                    if let Some(name) = &step.preset {
                        match step.scene {
                            LessonScene::Buildings => self.building_preset.clone_from(name),
                            LessonScene::Bridge => self.bridge_preset.clone_from(name),
                            _ => self.preset_choice.clone_from(name),
                        }
                    }
                    self.load_scene(scene_of(step.scene), setup)
                }
                Err(e) => {
                    if let Some(p) = &mut self.lesson {
                        p.load_error = Some(e);
                    }
                }
            }
        }
        self.apply_visibility();
        let ctx = self.lesson_context();
        let Some(p) = &mut self.lesson else { return };
        if let Some(ctx) = ctx {
            if p.judging {
                p.judge(&ctx);
            }
            p.evaluate_task(&ctx);
            p.record(&mut self.progress);
        }
    }

    fn load_scene(&mut self, scene: SceneKind, setup: SceneSetup) {
        self.scene = scene;
        match setup {
            SceneSetup::Impact(s) => {
                let target: &mut dyn ImpactScene = if scene == SceneKind::WaveVsLumped {
                    &mut self.compare
                } else {
                    &mut self.bar
                };
                let core = target.core_mut();
                core.setup = s;
                core.fields.clear();
                target.request();
            }
            SceneSetup::Buildings(s) => {
                self.buildings.setup = s;
                self.buildings.reset_fields();
                self.buildings.request();
            }
            SceneSetup::Bridge(s) => {
                self.bridge.setup = s;
                self.bridge.reset_fields();
                self.bridge.request();
            }
        }
        // A launch time (`--time`) holds the animation there, paused, in every step.
        let (t0, playing) = self.launch.time_s.map_or((0.0, true), |t| (t, false));
        let playback = self.playback();
        playback.t = t0;
        playback.playing = playing;
    }

    /// The scenes show the step's panels and unlock its settings; without a lesson, all.
    fn apply_visibility(&mut self) {
        let (visibility, lock) = match &self.lesson {
            Some(p) => (
                Visibility::only(p.panels()),
                Some(Lock::unlocking(&p.current().unlock, self.lecture)),
            ),
            None => (Visibility::default(), None),
        };
        for core in [&mut self.bar.core, &mut self.compare.core] {
            core.visibility = visibility.clone();
            core.fields.lock = lock.clone();
        }
        self.buildings.visibility = visibility.clone();
        self.buildings.set_lock(lock.clone());
        self.bridge.visibility = visibility;
        self.bridge.set_lock(lock);
        let models = self
            .lesson
            .as_ref()
            .map_or(vec![], |p| p.current().models.clone());
        self.compare.set_models(&models);
    }

    /// The expressions' context from the step's scene, once its solve has landed.
    fn lesson_context(&self) -> Option<Context> {
        let p = self.lesson.as_ref()?;
        match p.current().scene {
            LessonScene::Bar => self.bar.lesson_context(),
            LessonScene::Compare => self.compare.lesson_context(),
            LessonScene::Buildings => self.buildings.lesson_context(),
            LessonScene::Bridge => self.bridge.lesson_context(),
        }
    }

    /// Whether the settings panel shows: not while a lecture's step holds its task back.
    pub(super) fn lesson_shows_settings(&self) -> bool {
        self.lesson
            .as_ref()
            .is_none_or(|p| p.shows_task(self.lecture))
    }

    /// Whether the result views wait for the student's prediction.
    pub fn lesson_hides_results(&self) -> bool {
        self.lesson
            .as_ref()
            .is_some_and(|p| p.waiting_for_prediction())
    }

    /// PgDn and PgUp turn the steps.
    pub(super) fn lesson_keys(&mut self, ctx: &egui::Context) {
        let Some(p) = &self.lesson else { return };
        let (next, back) = ctx.input(|i| {
            (
                i.key_pressed(egui::Key::PageDown),
                i.key_pressed(egui::Key::PageUp),
            )
        });
        let k = p.step;
        if next {
            self.lesson_go_to(k + 1);
        } else if back && k > 0 {
            self.lesson_go_to(k - 1);
        }
    }

    /// The central panel while the step's prediction waits: the question and its answer widgets.
    pub(super) fn prediction_waiting_ui(&mut self, ui: &mut egui::Ui) {
        let Some(p) = &mut self.lesson else { return };
        let Some(pred) = p.current().prediction.clone() else {
            return;
        };
        ui.add_space(16.0);
        ui.label(RichText::new("Before the results: predict").heading());
        ui.add_space(8.0);
        prediction_ui(ui, p, &pred);
        ui.add_space(12.0);
        ui.label(RichText::new("The results appear once you have answered.").italics());
    }

    /// The lesson panel: the step's text, its prediction and task, and the way through.
    pub(super) fn lesson_ui(&mut self, ui: &mut egui::Ui) {
        let teacher = self.teacher;
        let progress = &self.progress;
        let Some(p) = &mut self.lesson else { return };
        let way = way_ui(ui, p, progress);
        ui.separator();
        step_ui(ui, p);
        // The notes answer some of the questions: only a teacher's screen shows them.
        if teacher {
            ui.separator();
            teacher_notes_ui(ui, &p.lesson);
        }
        match way {
            Way::Stay => {}
            Way::Leave => self.close_lesson(),
            Way::Reset => {
                // As it began: the answer cleared too (Back and Next give a step's answer back).
                if let Some(p) = &mut self.lesson {
                    p.record(&mut self.progress);
                    p.reset_step();
                }
            }
            Way::Turn(k) => self.lesson_go_to(k),
        }
    }
}

/// Where the student asked to go from the lesson panel.
enum Way {
    Stay,
    Leave,
    Reset,
    Turn(usize),
}

/// The lesson's title and Leave, where the student is and their score, and Back, Reset step
/// and Next.
fn way_ui(ui: &mut egui::Ui, p: &LessonPlayer, progress: &Progress) -> Way {
    let mut way = Way::Stay;
    let n = p.lesson.steps.len();
    // A projector has the lesson's title in the top bar and where the class is between the
    // buttons, on one row; the score and the progress bar are each student's own.
    let lecture = super::lecture::on(ui.ctx());
    let leave = |ui: &mut egui::Ui, way: &mut Way| {
        if ui
            .small_button("Leave")
            .on_hover_text("Close the lesson: every panel and setting back")
            .clicked()
        {
            *way = Way::Leave;
        }
    };
    if !lecture {
        ui.horizontal_wrapped(|ui| {
            ui.heading(&p.lesson.title);
            leave(ui, &mut way);
        });
        progress_ui(ui, p, progress);
    }
    ui.horizontal_wrapped(|ui| {
        if ui
            .add_enabled(p.step > 0, egui::Button::new("< Back"))
            .on_hover_text("PgUp")
            .clicked()
        {
            way = Way::Turn(p.step - 1);
        }
        if lecture {
            ui.label(format!("step {} of {n}", p.step + 1));
        }
        if ui
            .add_enabled(p.step + 1 < n, egui::Button::new("Next >"))
            .on_hover_text("PgDn")
            .clicked()
        {
            way = Way::Turn(p.step + 1);
        }
        if ui
            .button(if lecture { "Reset" } else { "Reset step" })
            .on_hover_text("The step's settings as it began, the answer cleared")
            .clicked()
        {
            way = Way::Reset;
        }
        if lecture {
            leave(ui, &mut way);
        }
    });
    way
}

/// Where the student is, how many steps they have done and their score.
fn progress_ui(ui: &mut egui::Ui, p: &LessonPlayer, progress: &Progress) {
    let n = p.lesson.steps.len();
    let own = progress.0.get(&p.lesson.name);
    let done = own.map_or(0, |pr| pr.done(&p.lesson));
    let where_ = format!("step {} of {n} ({done} done)", p.step + 1);
    if done == 0 {
        // An empty bar draws its rounded end over the text.
        ui.label(where_);
    } else {
        ui.add(egui::ProgressBar::new(done as f32 / n as f32).text(where_));
    }
    let ((right, asked), (met, tasks)) = own
        .map(|pr| pr.score(&p.lesson))
        .unwrap_or(((0, 0), (0, 0)));
    if asked + tasks > 0 {
        ui.label(format!(
            "score: {right} of {asked} predictions right at the first try, {met} of {tasks} tasks met"
        ));
    }
}

/// The step's title and text, its answered prediction and its task.
fn step_ui(ui: &mut egui::Ui, p: &mut LessonPlayer) {
    let step = p.current().clone();
    ui.label(RichText::new(&step.title).heading());
    if p.judged.is_some() && super::lecture::on(ui.ctx()) {
        // The explanation takes the text's and the question's place on a projector; they
        // stay a click away.
        egui::CollapsingHeader::new("The step and its question")
            .id_salt(("step-text", p.step))
            .default_open(false)
            .show(ui, |ui| {
                ui.label(reflow(&step.text));
                if let Some(pred) = &step.prediction {
                    ui.label(RichText::new(reflow(pred.question())).strong());
                }
            });
    } else {
        ui.label(reflow(&step.text));
    }
    if let Some(e) = &p.load_error {
        ui.colored_label(BAD, format!("this step could not be loaded: {e}"));
    }
    // While the prediction waits it stands in the middle of the window, where the results
    // will appear; once answered, its verdict stays here beside them.
    let lecture = super::lecture::on(ui.ctx());
    let Some(task) = &step.task else {
        if let Some(pred) = &step.prediction
            && p.judged.is_some()
        {
            ui.separator();
            prediction_ui(ui, p, pred);
        }
        return;
    };
    if let Some(pred) = &step.prediction
        && p.judged.is_some()
    {
        ui.separator();
        if p.shows_task(lecture) && lecture {
            egui::CollapsingHeader::new("The prediction")
                .id_salt(("prediction", p.step))
                .default_open(false)
                .show(ui, |ui| prediction_ui(ui, p, pred));
        } else {
            prediction_ui(ui, p, pred);
        }
        if !p.shows_task(lecture) && ui.button("On to the task >").clicked() {
            p.task_opened = true;
        }
    }
    if !p.shows_task(lecture) {
        return;
    }
    ui.separator();
    ui.label(RichText::new(format!("Task: {}", reflow(&task.text))).strong());
    ui.horizontal_wrapped(|ui| {
        match &p.task {
            Some(Ok(true)) => {
                ui.colored_label(GOOD, "met");
            }
            Some(Ok(false)) | None if lecture => {
                ui.label("not yet met");
            }
            Some(Ok(false)) | None => {
                ui.label("not yet met: change the unlocked settings below");
            }
            Some(Err(e)) => {
                ui.colored_label(BAD, format!("the task cannot be checked: {e}"));
            }
        }
        if !p.hint_shown && ui.small_button("Hint").clicked() {
            p.hint_shown = true;
        }
    });
    if p.hint_shown {
        ui.label(RichText::new(format!("Hint: {}", task.hint)).italics());
    }
}

/// The lesson's audience, duration, goals and teacher notes.
fn teacher_notes_ui(ui: &mut egui::Ui, lesson: &crate::lesson::Lesson) {
    egui::CollapsingHeader::new("Teacher notes")
        .id_salt("teacher-notes")
        .default_open(true)
        .show(ui, |ui| {
            ui.label(format!(
                "{} ({} min). Goals:",
                lesson.audience, lesson.duration_min
            ));
            for g in &lesson.goals {
                ui.label(format!("- {g}"));
            }
            ui.label(reflow(&lesson.teacher_notes));
        });
}

/// A lesson's text as written in its file, re-flowed: single line breaks become spaces, a blank
/// line starts a new paragraph, and list items (`- `) keep their own lines.
pub fn reflow(text: &str) -> String {
    let mut out = String::new();
    for paragraph in text.trim().split("\n\n") {
        if !out.is_empty() {
            out.push_str("\n\n");
        }
        let mut first = true;
        for line in paragraph.lines().map(str::trim).filter(|l| !l.is_empty()) {
            if !first {
                out.push(if line.starts_with("- ") { '\n' } else { ' ' });
            }
            out.push_str(line);
            first = false;
        }
    }
    out
}

/// The question, its options or number field, and after the answer its verdict and explanation.
fn prediction_ui(ui: &mut egui::Ui, p: &mut LessonPlayer, pred: &Prediction) {
    let answered = p.judged.is_some();
    // On a projector the verdict names the answer: the question (under the step's text) and
    // the options would only push the explanation off the screen.
    if answered && super::lecture::on(ui.ctx()) {
        judged_ui(ui, p, pred);
        return;
    }
    ui.label(RichText::new(reflow(pred.question())).strong());
    ui.add_enabled_ui(!answered, |ui| match pred {
        Prediction::Choice { options, .. } => {
            for (i, o) in options.iter().enumerate() {
                ui.radio_value(&mut p.answer.choice, Some(i), o);
            }
        }
        Prediction::Number { unit, .. } => {
            ui.horizontal(|ui| {
                let label = ui.label("your answer").id;
                ui.add(egui::TextEdit::singleline(&mut p.answer.number).desired_width(90.0))
                    .labelled_by(label);
                ui.label(unit);
            });
        }
    });
    match &p.judged {
        None => {
            let given = p.answer_given();
            let button = ui
                .add_enabled(given.is_ok() && !p.judging, egui::Button::new("Answer"))
                .on_hover_text("The results appear once you have answered");
            if button.clicked() {
                p.judging = true;
            }
            if p.judging {
                ui.label("solving...");
            } else if let Err(why) = given {
                ui.label(RichText::new(why).italics());
            }
        }
        Some(_) => judged_ui(ui, p, pred),
    }
}

/// The verdict on an answer and the step's explanation.
fn judged_ui(ui: &mut egui::Ui, p: &LessonPlayer, pred: &Prediction) {
    match &p.judged {
        None => {}
        Some(Ok(j)) => {
            if j.correct {
                ui.colored_label(GOOD, format!("Right: {}", j.expected));
            } else {
                ui.colored_label(BAD, format!("Not quite: the model gives {}", j.expected));
            }
            ui.label(reflow(pred.explanation()));
        }
        Some(Err(e)) => {
            ui.colored_label(BAD, format!("the answer cannot be judged: {e}"));
            ui.label(reflow(pred.explanation()));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::reflow;

    #[test]
    fn lesson_text_reflows_into_paragraphs_and_keeps_list_items_apart() {
        let text =
            "Two rods\nmeet at 1 m/s.\n\nMisconceptions:\n- e is a constant\n- longer is heavier\n";
        assert_eq!(
            reflow(text),
            "Two rods meet at 1 m/s.\n\nMisconceptions:\n- e is a constant\n- longer is heavier"
        );
    }
}
