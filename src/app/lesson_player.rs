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
    /// When each step was first answered or its task first met [s since 1970, UTC].
    #[serde(default)]
    pub at_s: BTreeMap<usize, u64>,
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
    /// A step with a prediction and a task has moved on to its task (lecture mode shows one
    /// at a time: a projector holds the explanation or the task, not both).
    pub task_opened: bool,
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
            task_opened: false,
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
        self.task_opened = false;
    }

    /// Whether the step's task (and the settings it unlocks) is on screen: always, except in
    /// lecture mode on a step that asks a prediction first, until the class moves on to it.
    pub fn shows_task(&self, lecture: bool) -> bool {
        !lecture || self.current().prediction.is_none() || self.task_opened
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
        let now = || {
            std::time::SystemTime::now()
                .duration_since(std::time::UNIX_EPOCH)
                .map_or(0, |d| d.as_secs())
        };
        if let Some(Ok(j)) = &self.judged {
            p.answered.entry(self.step).or_insert(j.correct);
            p.answers
                .entry(self.step)
                .or_insert_with(|| self.answer.clone());
            p.at_s.entry(self.step).or_insert_with(now);
        }
        if matches!(self.task, Some(Ok(true))) {
            p.met.insert(self.step);
            p.at_s.entry(self.step).or_insert_with(now);
        }
    }
}

/// One row of a class's lesson results: a step's prediction or task, as a teacher collects it.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ResultRow {
    pub lesson: String,
    /// From 1, as the window shows it.
    pub step: usize,
    pub title: String,
    /// `prediction` or `task`.
    pub kind: &'static str,
    /// The student's first answer (the option's text, or the number typed), or `met`.
    pub answer: String,
    /// Whether the first answer was right, or the task met.
    pub right: bool,
    /// When, in UTC (ISO 8601).
    pub time_utc: String,
}

/// Every answered prediction and met task of every lesson in `progress`, in lesson and step
/// order (lessons that cannot be loaded any more are left out).
pub fn results(progress: &Progress, load: impl Fn(&str) -> Option<Lesson>) -> Vec<ResultRow> {
    let mut rows = vec![];
    for (name, p) in &progress.0 {
        let Some(lesson) = load(name) else { continue };
        for (k, step) in lesson.steps.iter().enumerate() {
            let row = |kind, answer, right| ResultRow {
                lesson: name.clone(),
                step: k + 1,
                title: step.title.clone(),
                kind,
                answer,
                right,
                time_utc: p.at_s.get(&k).map_or_else(String::new, |&t| utc(t)),
            };
            if let Some(&right) = p.answered.get(&k) {
                let given = p.answers.get(&k).cloned().unwrap_or_default();
                let answer = match (&step.prediction, given.choice) {
                    (Some(Prediction::Choice { options, .. }), Some(c)) => {
                        options.get(c).cloned().unwrap_or_default()
                    }
                    _ => given.number,
                };
                rows.push(row("prediction", answer, right));
            }
            if step.task.is_some() && p.met.contains(&k) {
                rows.push(row("task", "met".into(), true));
            }
        }
    }
    rows
}

/// The rows as CSV, one a line under a header; text quoted where it holds a comma or a quote.
pub fn results_csv(rows: &[ResultRow]) -> String {
    let q = |t: &str| {
        if t.contains([',', '"', '\n']) {
            format!("\"{}\"", t.replace('"', "\"\""))
        } else {
            t.to_string()
        }
    };
    let mut out = String::from("lesson,step,title,kind,answer,right,time_utc\n");
    for r in rows {
        out.push_str(&format!(
            "{},{},{},{},{},{},{}\n",
            q(&r.lesson),
            r.step,
            q(&r.title),
            r.kind,
            q(&r.answer),
            r.right,
            r.time_utc
        ));
    }
    out
}

/// Seconds since 1970 as an ISO 8601 UTC time (the civil calendar from days since the epoch).
fn utc(t: u64) -> String {
    let (days, secs) = ((t / 86_400) as i64, t % 86_400);
    // Howard Hinnant's days-to-civil algorithm.
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    format!(
        "{y:04}-{m:02}-{d:02}T{:02}:{:02}:{:02}Z",
        secs / 3600,
        secs % 3600 / 60,
        secs % 60
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn utc_times_match_known_dates() {
        assert_eq!(utc(0), "1970-01-01T00:00:00Z");
        assert_eq!(utc(951_782_400), "2000-02-29T00:00:00Z");
        assert_eq!(utc(1_795_810_245), "2026-11-27T20:10:45Z");
    }

    #[test]
    fn lesson_results_list_first_answers_and_met_tasks_as_csv_and_json() {
        let lesson = crate::lesson::builtin("lumped-or-wave").expect("shipped");
        let k = lesson
            .steps
            .iter()
            .position(|s| matches!(s.prediction, Some(Prediction::Choice { .. })))
            .expect("a choice");
        let t = lesson
            .steps
            .iter()
            .position(|s| s.task.is_some())
            .expect("a task");
        let mut progress = Progress::default();
        let p = progress.0.entry("lumped-or-wave".into()).or_default();
        p.answered.insert(k, false);
        p.answers.insert(
            k,
            Answer {
                choice: Some(1),
                number: String::new(),
            },
        );
        p.at_s.insert(k, 0);
        p.met.insert(t);
        let rows = results(&progress, |n| crate::lesson::builtin(n).ok());
        let Some(Prediction::Choice { options, .. }) = &lesson.steps[k].prediction else {
            unreachable!()
        };
        assert_eq!(rows[0].step, k + 1);
        assert_eq!(rows[0].answer, options[1]);
        assert!(!rows[0].right);
        assert_eq!(rows[0].time_utc, "1970-01-01T00:00:00Z");
        assert!(
            rows.iter()
                .any(|r| r.kind == "task" && r.step == t + 1 && r.right)
        );
        let csv = results_csv(&rows);
        assert!(csv.starts_with("lesson,step,title,kind,answer,right,time_utc\n"));
        assert_eq!(csv.lines().count(), rows.len() + 1);
        let json: serde_json::Value =
            serde_json::from_str(&serde_json::to_string(&rows).unwrap()).unwrap();
        assert_eq!(json[0]["lesson"], "lumped-or-wave");
    }

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
