//! The lesson player's state: which lesson and step, the student's answer to the step's
//! prediction, whether its task has been met, and each lesson's progress (kept between
//! sessions). What a step loads and what shows is decided here; the panel draws it
//! (`lesson_panel`), and the window applies it to its scenes.

use crate::lesson::{Judgement, Lesson, Prediction, Step};
use std::collections::{BTreeMap, BTreeSet};

/// Storage key of the progress (the suffix is the format's version).
pub const PROGRESS_KEY: &str = "lesson-progress-v1";

/// What a student has done in one lesson.
#[derive(Debug, Clone, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct LessonProgress {
    /// The step last on screen (from 0).
    pub step: usize,
    /// Steps whose prediction was answered, and whether the first answer was right.
    pub answered: BTreeMap<usize, bool>,
    /// Steps whose task was met.
    pub met: BTreeSet<usize>,
    /// The furthest step reached (going back does not undo what was done).
    #[serde(default)]
    pub furthest: usize,
    /// Each answered step's first answer, given back when the student returns to it.
    #[serde(default)]
    pub answers: BTreeMap<usize, Answer>,
}

impl LessonProgress {
    /// Steps done: answered where they ask, met where they set a task, seen otherwise.
    pub fn done(&self, lesson: &Lesson) -> usize {
        let reached = self.furthest.max(self.step);
        lesson
            .steps
            .iter()
            .enumerate()
            .filter(|(k, s)| {
                let answered = s.prediction.is_none() || self.answered.contains_key(k);
                let met = s.task.is_none() || self.met.contains(k);
                answered && met && *k <= reached
            })
            .count()
    }

    /// The lesson's score: (predictions right at the first try, predictions), (tasks met,
    /// tasks).
    pub fn score(&self, lesson: &Lesson) -> ((usize, usize), (usize, usize)) {
        let predictions = lesson
            .steps
            .iter()
            .filter(|s| s.prediction.is_some())
            .count();
        let tasks = lesson.steps.iter().filter(|s| s.task.is_some()).count();
        let right = self.answered.values().filter(|&&r| r).count();
        ((right, predictions), (self.met.len(), tasks))
    }
}

/// Every lesson's progress, by lesson name.
#[derive(Debug, Clone, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Progress(pub BTreeMap<String, LessonProgress>);

impl Progress {
    /// Progress as stored; what cannot be read starts afresh (an error says so).
    pub fn from_stored(text: Option<String>) -> (Self, Option<String>) {
        match text {
            None => (Progress::default(), None),
            Some(t) => match serde_json::from_str(&t) {
                Ok(p) => (p, None),
                Err(e) => (
                    Progress::default(),
                    Some(format!(
                        "lesson progress could not be read ({e}): starting afresh"
                    )),
                ),
            },
        }
    }

    pub fn to_stored(&self) -> String {
        serde_json::to_string(self).unwrap_or_default()
    }
}

/// What the student has typed or picked for the step's prediction.
#[derive(Debug, Clone, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Answer {
    pub choice: Option<usize>,
    pub number: String,
}

/// A lesson being played.
pub struct LessonPlayer {
    pub lesson: Lesson,
    pub step: usize,
    pub answer: Answer,
    /// The judged prediction (or why it could not be judged).
    pub judged: Option<Result<Judgement, String>>,
    /// The student asked for the task's hint.
    pub hint_shown: bool,
    /// The task's state on the latest result: met, not met, or an error evaluating it.
    pub task: Option<Result<bool, String>>,
    /// The step's scene could not be loaded.
    pub load_error: Option<String>,
    /// The scene has been loaded for this step and a solve requested.
    pub loaded: bool,
    /// The student's answer is waiting for the result to be judged against.
    pub judging: bool,
}

impl LessonPlayer {
    pub fn new(lesson: Lesson, step: usize) -> Self {
        let step = step.min(lesson.steps.len().saturating_sub(1));
        LessonPlayer {
            lesson,
            step,
            answer: Answer::default(),
            judged: None,
            hint_shown: false,
            task: None,
            load_error: None,
            loaded: false,
            judging: false,
        }
    }

    pub fn current(&self) -> &Step {
        &self.lesson.steps[self.step]
    }

    /// Goes to step `k` (clamped), fresh: nothing answered, the scene to be loaded.
    pub fn go_to(&mut self, k: usize) {
        self.step = k.min(self.lesson.steps.len().saturating_sub(1));
        self.reset_step();
    }

    /// Gives back the answer this step was first given (kept in `progress`), judged again
    /// once the step's result lands: going back does not forget what the student said.
    pub fn restore_answer(&mut self, progress: &Progress) {
        let given = progress
            .0
            .get(&self.lesson.name)
            .and_then(|p| p.answers.get(&self.step));
        if let Some(a) = given
            && self.current().prediction.is_some()
        {
            self.answer = a.clone();
            self.judging = true;
        }
    }

    /// The step as it was when first shown.
    pub fn reset_step(&mut self) {
        self.answer = Answer::default();
        self.judged = None;
        self.hint_shown = false;
        self.task = None;
        self.load_error = None;
        self.loaded = false;
        self.judging = false;
    }

    /// Whether the result views wait for the student's prediction.
    pub fn waiting_for_prediction(&self) -> bool {
        self.current().prediction.is_some() && self.judged.is_none()
    }

    /// The panels to show now: none while a prediction waits, else the step's.
    pub fn panels(&self) -> Vec<&'static str> {
        if self.waiting_for_prediction() {
            vec![]
        } else {
            self.current().show.iter().map(|p| p.name()).collect()
        }
    }

    /// Whether the student's answer can be judged (a choice picked, or a number typed).
    pub fn answer_given(&self) -> Result<(), String> {
        match &self.current().prediction {
            None => Ok(()),
            Some(Prediction::Choice { .. }) => self
                .answer
                .choice
                .map(|_| ())
                .ok_or_else(|| "pick one of the options".to_string()),
            Some(Prediction::Number { unit, .. }) => {
                let t = self.answer.number.trim();
                match t.parse::<f64>() {
                    Ok(x) if x.is_finite() => Ok(()),
                    _ if t.is_empty() && unit.is_empty() => Err("type a number".to_string()),
                    _ if t.is_empty() => Err(format!("type a number (in {unit})")),
                    _ if unit.is_empty() => Err(format!("'{t}' is not a number: type one")),
                    _ => Err(format!("'{t}' is not a number: type one, in {unit}")),
                }
            }
        }
    }

    /// Judges the answer given against the result's context.
    pub fn judge(&mut self, ctx: &crate::lesson::Context) {
        let Some(p) = &self.current().prediction else {
            return;
        };
        let judged = match p {
            Prediction::Choice { .. } => self
                .answer
                .choice
                .ok_or_else(|| "no option picked".to_string())
                .and_then(|c| p.judge_choice(c, ctx).map_err(|e| e.to_string())),
            Prediction::Number { .. } => self
                .answer
                .number
                .trim()
                .parse::<f64>()
                .map_err(|e| e.to_string())
                .and_then(|x| p.judge_number(x, ctx).map_err(|e| e.to_string())),
        };
        self.judged = Some(judged);
        self.judging = false;
    }

    /// Evaluates the task on the latest result; true when it has just been met.
    pub fn evaluate_task(&mut self, ctx: &crate::lesson::Context) -> bool {
        let Some(task) = &self.current().task else {
            return false;
        };
        let was_met = matches!(self.task, Some(Ok(true)));
        let now = task.goal.truth(ctx).map_err(|e| e.to_string());
        let met = matches!(now, Ok(true));
        // Once met, the step stays met: the student found the setting, and may go on exploring.
        if !was_met {
            self.task = Some(now);
        }
        met && !was_met
    }

    /// Records this step's state in the lesson's progress; a step's first answer stands.
    pub fn record(&self, progress: &mut Progress) {
        let p = progress.0.entry(self.lesson.name.clone()).or_default();
        p.step = self.step;
        p.furthest = p.furthest.max(self.step);
        if let Some(Ok(j)) = &self.judged {
            p.answered.entry(self.step).or_insert(j.correct);
            p.answers
                .entry(self.step)
                .or_insert_with(|| self.answer.clone());
        }
        if matches!(self.task, Some(Ok(true))) {
            p.met.insert(self.step);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn progress_survives_its_stored_form_and_a_bad_store_starts_afresh() {
        let mut p = Progress::default();
        let e = p.0.entry("lumped-or-wave".into()).or_default();
        e.step = 3;
        e.answered.insert(1, true);
        e.met.insert(2);
        let (back, err) = Progress::from_stored(Some(p.to_stored()));
        assert_eq!(back, p);
        assert!(err.is_none());
        let (fresh, err) = Progress::from_stored(Some("{not json".into()));
        assert_eq!(fresh, Progress::default());
        assert!(err.is_some());
    }

    #[test]
    fn result_views_wait_for_a_prediction_and_show_only_the_steps_panels_after() {
        let lesson = crate::lesson::builtin("lumped-or-wave").expect("shipped");
        let k = lesson
            .steps
            .iter()
            .position(|s| s.prediction.is_some())
            .expect("a step with a prediction");
        let mut player = LessonPlayer::new(lesson, k);
        assert!(player.waiting_for_prediction());
        assert!(player.panels().is_empty());
        assert!(player.answer_given().is_err());
        player.judged = Some(Err("judged".into()));
        let shown: Vec<&str> = player.current().show.iter().map(|p| p.name()).collect();
        assert_eq!(player.panels(), shown);
    }
}
