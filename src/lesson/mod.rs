//! Guided lessons: TOML files of ordered steps, each a scene to load, the panels to show, the
//! settings to unlock, a prediction to make before the result shows and a task to meet on the
//! live result. The format is documented in `docs/lessons.md`.
//!
//! - [`load`] reads a shipped lesson by name or a file by path, checking every name an
//!   expression reads against its scene ([`Vocabulary`]) and every override against the
//!   settings, so a typo is an error naming its line, never a silent false;
//! - [`Context`] holds what a solved scene gives an expression; the window builds one from what
//!   it holds, [`check`] from its own headless solves;
//! - [`handout`] writes a printable worksheet.

pub mod bridge_context;
pub mod check;
pub mod context;
pub mod expr;
pub mod handout;
mod parse;
pub mod solve;

pub use check::{CheckReport, StepReport, check};
pub use context::{Context, Vocabulary};
pub use expr::{Expr, ExprError, Value};
pub use solve::{SceneSetup, Solved, solve_step};

use crate::model::settings::{BRIDGE_SETTINGS, BUILDING_SETTINGS, IMPACT_SETTINGS, Setting};

/// Lessons shipped with Pounding Lab, compiled in (name = file stem).
pub const EMBEDDED: &[(&str, &str)] = &[
    (
        "lumped-or-wave",
        include_str!("../../assets/lessons/lumped-or-wave.toml"),
    ),
    (
        "reading-xt",
        include_str!("../../assets/lessons/reading-xt.toml"),
    ),
    (
        "where-the-energy-goes",
        include_str!("../../assets/lessons/where-the-energy-goes.toml"),
    ),
    (
        "soft-and-stiff-contact",
        include_str!("../../assets/lessons/soft-and-stiff-contact.toml"),
    ),
    (
        "buildings-that-pound",
        include_str!("../../assets/lessons/buildings-that-pound.toml"),
    ),
    (
        "storeys-that-yield",
        include_str!("../../assets/lessons/storeys-that-yield.toml"),
    ),
    (
        "waves-in-a-bridge",
        include_str!("../../assets/lessons/waves-in-a-bridge.toml"),
    ),
];

/// A lesson: what it is for, and its steps in order.
#[derive(Debug, Clone, PartialEq)]
pub struct Lesson {
    /// The file stem (or the file's path for a user's file).
    pub name: String,
    /// Where it was read from, for error messages.
    pub source: String,
    pub title: String,
    pub audience: String,
    pub duration_min: u32,
    pub goals: Vec<String>,
    /// The model's limits and the usual misconceptions (the teacher's version only).
    pub teacher_notes: String,
    pub steps: Vec<Step>,
}

/// Which scene a step loads.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LessonScene {
    /// One impact through one model.
    Bar,
    /// The same impact through the compared models ([`context::COMPARE_MODELS`]).
    Compare,
    /// Two buildings in an earthquake.
    Buildings,
    /// A bridge's girders pounding at their joints in an earthquake.
    Bridge,
}

impl LessonScene {
    pub const ALL: [LessonScene; 4] = [
        LessonScene::Bar,
        LessonScene::Compare,
        LessonScene::Buildings,
        LessonScene::Bridge,
    ];

    pub fn name(self) -> &'static str {
        match self {
            LessonScene::Bar => "bar",
            LessonScene::Compare => "compare",
            LessonScene::Buildings => "buildings",
            LessonScene::Bridge => "bridge",
        }
    }

    /// The settings its steps may set and unlock, and the command whose `--list-keys` lists
    /// them.
    pub fn settings(self) -> (&'static [Setting], &'static str) {
        match self {
            LessonScene::Bar | LessonScene::Compare => (IMPACT_SETTINGS, "impact"),
            LessonScene::Buildings => (BUILDING_SETTINGS, "buildings"),
            LessonScene::Bridge => (BRIDGE_SETTINGS, "bridge"),
        }
    }

    pub fn from_name(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|k| k.name() == s)
    }

    /// The preset a step of this scene loads when it names none.
    pub fn default_preset(self) -> &'static str {
        match self {
            LessonScene::Bar | LessonScene::Compare => crate::io::preset::DEFAULT_PRESET,
            LessonScene::Buildings => "paper-buildings",
            LessonScene::Bridge => "bridge-3-span",
        }
    }
}

/// A panel or plot a step shows (the others are hidden).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Panel {
    /// The animated bars (in compare: the Sears bars and the lumped blocks).
    Bars,
    /// The swaying buildings.
    Buildings,
    /// Force against time.
    Force,
    /// The contact's approach against time.
    Approach,
    /// The buildings' roof displacements against time.
    Displacements,
    /// The numbers: peak force, duration, e, a tau, ...
    Readouts,
    /// The space-time diagram of the waves.
    Xt,
    /// Where the energy went.
    Energy,
    /// The buildings' impacts listed.
    Impacts,
    /// The gap assessment against ABS and SRSS.
    Gaps,
    /// The yielding storeys' hysteresis loops.
    Hysteresis,
    /// The bridge in elevation: frames swaying, joints closing, girders on their seats.
    Bridge,
    /// The bridge's joint openings against the seat length.
    Openings,
    /// The bridge's joints tabled: gap, gap needed, largest force and opening, seat margin.
    Joints,
}

impl Panel {
    pub const ALL: [Panel; 14] = [
        Panel::Bars,
        Panel::Buildings,
        Panel::Force,
        Panel::Approach,
        Panel::Displacements,
        Panel::Readouts,
        Panel::Xt,
        Panel::Energy,
        Panel::Impacts,
        Panel::Gaps,
        Panel::Hysteresis,
        Panel::Bridge,
        Panel::Openings,
        Panel::Joints,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Panel::Bars => "bars",
            Panel::Buildings => "buildings",
            Panel::Force => "force",
            Panel::Approach => "approach",
            Panel::Displacements => "displacements",
            Panel::Readouts => "readouts",
            Panel::Xt => "xt",
            Panel::Energy => "energy",
            Panel::Impacts => "impacts",
            Panel::Gaps => "gaps",
            Panel::Hysteresis => "hysteresis",
            Panel::Bridge => "bridge",
            Panel::Openings => "openings",
            Panel::Joints => "joints",
        }
    }

    pub fn from_name(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|p| p.name() == s)
    }

    /// Whether a scene has this panel.
    pub fn in_scene(self, scene: LessonScene) -> bool {
        use LessonScene::{Bar, Bridge, Buildings, Compare};
        match self {
            Panel::Force | Panel::Readouts => true,
            Panel::Energy => scene != Bridge,
            Panel::Bars | Panel::Approach => matches!(scene, Bar | Compare),
            Panel::Xt => scene != Buildings,
            Panel::Displacements | Panel::Impacts => matches!(scene, Buildings | Bridge),
            Panel::Buildings | Panel::Gaps | Panel::Hysteresis => scene == Buildings,
            Panel::Bridge | Panel::Openings | Panel::Joints => scene == Bridge,
        }
    }
}

/// One step: a short text, the scene to load, what shows, what may change, and optionally a
/// prediction and a task.
#[derive(Debug, Clone, PartialEq)]
pub struct Step {
    pub title: String,
    pub text: String,
    /// The line of the step's `[[step]]` header.
    pub line: usize,
    pub scene: LessonScene,
    /// A preset name or path; `None` for the scene's default.
    pub preset: Option<String>,
    /// `--set` overrides: (key, value, line).
    pub set: Vec<(String, String, usize)>,
    pub show: Vec<Panel>,
    /// The models a compare step solves and shows (Sears, whose bars the scene draws, among
    /// them); empty in the other scenes.
    pub models: Vec<crate::model::impact::ModelKind>,
    /// The settings keys the student may change (the rest stay locked).
    pub unlock: Vec<String>,
    pub prediction: Option<Prediction>,
    pub task: Option<Task>,
    /// Statements the step's text and explanation make, each checked on the solved step.
    pub asserts: Vec<Expr>,
}

/// A question the student answers before the result views appear.
#[derive(Debug, Clone, PartialEq)]
pub enum Prediction {
    /// Pick one option. Each option has a condition over the result (`when`, one per option);
    /// the right option is the one whose condition holds on the run, so the model computes the
    /// answer. `answer` (from 0; the file counts from 1) is the author's key, which `--check`
    /// compares with the model's pick.
    Choice {
        question: String,
        options: Vec<String>,
        when: Vec<Expr>,
        answer: usize,
        explanation: String,
    },
    /// A number: right when within `tolerance` (relative: |x - answer| <= tolerance |answer|)
    /// of `answer`, an expression over the result.
    Number {
        question: String,
        unit: String,
        answer: Expr,
        tolerance: f64,
        explanation: String,
    },
}

/// How a student's answer fared.
#[derive(Debug, Clone, PartialEq)]
pub struct Judgement {
    pub correct: bool,
    /// The right answer as shown: the option's text, or the number with its unit.
    pub expected: String,
}

impl Prediction {
    pub fn question(&self) -> &str {
        match self {
            Prediction::Choice { question, .. } | Prediction::Number { question, .. } => question,
        }
    }

    pub fn explanation(&self) -> &str {
        match self {
            Prediction::Choice { explanation, .. } | Prediction::Number { explanation, .. } => {
                explanation
            }
        }
    }

    /// The option (from 0) the model picks: the one whose `when` holds. An error unless exactly
    /// one holds; for a number prediction, `None`.
    pub fn model_choice(&self, ctx: &Context) -> Result<Option<usize>, ExprError> {
        let Prediction::Choice { when, .. } = self else {
            return Ok(None);
        };
        let mut holding = Vec::new();
        for (k, e) in when.iter().enumerate() {
            if e.truth(ctx)? {
                holding.push(k);
            }
        }
        match holding.as_slice() {
            [k] => Ok(Some(*k)),
            _ => Err(ExprError::Type(format!(
                "exactly one option's condition must hold, but {} do (options {:?}, from 1)",
                holding.len(),
                holding.iter().map(|k| k + 1).collect::<Vec<_>>()
            ))),
        }
    }

    /// The right answer as shown, computed from the run.
    pub fn expected(&self, ctx: &Context) -> Result<String, ExprError> {
        match self {
            Prediction::Choice { options, .. } => {
                let k = self.model_choice(ctx)?.unwrap_or_default();
                Ok(options[k].clone())
            }
            Prediction::Number { answer, unit, .. } => {
                let x = answer.number(ctx)?;
                Ok(format!("{} {unit}", significant(x, 3))
                    .trim_end()
                    .to_string())
            }
        }
    }

    /// Judges a choice (its index, from 0) against the model's pick.
    pub fn judge_choice(&self, chosen: usize, ctx: &Context) -> Result<Judgement, ExprError> {
        match self.model_choice(ctx)? {
            Some(k) => Ok(Judgement {
                correct: chosen == k,
                expected: self.expected(ctx)?,
            }),
            None => Err(ExprError::Type(
                "this prediction wants a number, not a choice".into(),
            )),
        }
    }

    /// Judges a number against the run's answer and the tolerance.
    pub fn judge_number(&self, x: f64, ctx: &Context) -> Result<Judgement, ExprError> {
        match self {
            Prediction::Number {
                answer, tolerance, ..
            } => Ok(Judgement {
                correct: x.is_finite() && expr::within(x, answer.number(ctx)?, *tolerance),
                expected: self.expected(ctx)?,
            }),
            Prediction::Choice { .. } => Err(ExprError::Type(
                "this prediction wants a choice, not a number".into(),
            )),
        }
    }
}

/// A number to `digits` significant figures, plain or in exponent form.
pub fn significant(x: f64, digits: usize) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    if x.fract() == 0.0 && x.abs() < 1e5 {
        return format!("{x}");
    }
    let magnitude = x.abs().log10().floor() as i32;
    if (-3..5).contains(&magnitude) {
        let decimals = (digits as i32 - 1 - magnitude).max(0) as usize;
        format!("{x:.decimals$}")
    } else {
        format!("{x:.prec$e}", prec = digits.saturating_sub(1))
    }
}

/// A goal on the live result: met the moment a setting change makes `goal` true.
#[derive(Debug, Clone, PartialEq)]
pub struct Task {
    pub goal: Expr,
    pub text: String,
    pub hint: String,
    /// Overrides that meet the goal (a scripted slider change): `--check` asserts the goal is
    /// not met before them and is met after. (key, value, line).
    pub solution: Vec<(String, String, usize)>,
}

/// A lesson that could not be read or checked: where, which field, why.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{file}{}{}: {message}", crate::io::file::at_line(*.line), .field.as_ref().map(|k| format!(", {k}")).unwrap_or_default())]
pub struct LessonError {
    /// The file, or `lesson NAME` for a shipped one.
    pub file: String,
    pub line: Option<usize>,
    /// The field: `step[2].task.goal`, `title`, ...
    pub field: Option<String>,
    pub message: String,
}

/// The shipped lessons' names.
pub fn builtin_names() -> Vec<&'static str> {
    EMBEDDED.iter().map(|(n, _)| *n).collect()
}

/// A shipped lesson by name.
pub fn builtin(name: &str) -> Result<Lesson, LessonError> {
    let (n, text) = EMBEDDED
        .iter()
        .find(|(n, _)| *n == name)
        .ok_or_else(|| LessonError {
            file: name.to_string(),
            line: None,
            field: None,
            message: format!(
                "no such lesson; shipped lessons: {}",
                builtin_names().join(", ")
            ),
        })?;
    parse::parse(text, n, &format!("lesson {n}"))
}

/// A lesson from text (`source` names it in errors).
pub fn parse_text(text: &str, name: &str, source: &str) -> Result<Lesson, LessonError> {
    parse::parse(text, name, source)
}

/// A shipped lesson by name, or a file by path (a path wins where both exist, unless it is a
/// folder of a shipped lesson's name). A file is read as records and presets are: devices,
/// pipes and folders refused, its size bounded, a byte that is not UTF-8 named by line.
pub fn load(name_or_path: &str) -> Result<Lesson, LessonError> {
    use crate::io::file::FileError;
    let path = std::path::Path::new(name_or_path);
    let shipped = EMBEDDED.iter().any(|(n, _)| *n == name_or_path);
    if path.exists() && !(shipped && path.is_dir()) {
        let text = crate::io::file::read_text(path).map_err(|e| LessonError {
            file: name_or_path.to_string(),
            // A byte that is not UTF-8 is placed by line and byte in the message itself.
            line: None,
            field: None,
            message: match e {
                FileError::NotRegular => format!(
                    "not a regular file (a folder, device or pipe); give a lesson file, or a shipped lesson's name ({})",
                    builtin_names().join(", ")
                ),
                _ => e.to_string(),
            },
        })?;
        let stem = path
            .file_stem()
            .map_or_else(|| name_or_path.to_string(), |s| s.to_string_lossy().into());
        return parse::parse(&text, &stem, name_or_path);
    }
    builtin(name_or_path)
}
