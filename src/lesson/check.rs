//! `lesson --check`: every step loaded and solved headless, every expression evaluated.

use super::expr::Expr;
use super::solve::solve_step;
use super::{Context, Lesson, LessonError, Prediction, Step};
use crate::model::control::Control;

/// What one step gave.
#[derive(Debug, Clone, PartialEq)]
pub struct StepReport {
    pub title: String,
    /// The prediction's right answer as shown (`None` without a prediction).
    pub answer: Option<String>,
    /// Whether the task's goal held as the step loads (`None` without a task).
    pub task_met_at_start: Option<bool>,
    /// Whether it held after the task's solution (`None` without a solution).
    pub task_met_by_solution: Option<bool>,
    /// How many statements (`asserts`) held.
    pub asserts: usize,
    /// Wall time of the step's solves [s].
    pub solve_time_s: f64,
}

/// What `--check` found: one report per step.
#[derive(Debug, Clone, PartialEq)]
pub struct CheckReport {
    pub lesson: String,
    pub steps: Vec<StepReport>,
}

fn at(lesson: &Lesson, step: usize, part: &str, message: String) -> LessonError {
    LessonError {
        file: lesson.source.clone(),
        line: Some(lesson.steps[step].line),
        field: Some(format!("step[{}]{part}", step + 1)),
        message,
    }
}

fn truth(
    lesson: &Lesson,
    i: usize,
    part: &str,
    e: &Expr,
    ctx: &Context,
) -> Result<bool, LessonError> {
    e.truth(ctx)
        .map_err(|err| at(lesson, i, part, format!("'{e}': {err}")))
}

/// Loads and solves every step, evaluates every expression, and checks that each statement
/// holds, each choice's answer key is confirmed by the model, each number answer is a number,
/// and each task's solution meets a goal not met before it.
pub fn check(lesson: &Lesson, control: &Control) -> Result<CheckReport, LessonError> {
    let n = lesson.steps.len() as u32;
    let steps = (0..lesson.steps.len())
        .map(|i| {
            // Each step is an equal part of the progress a caller shows.
            control.stage(i as u32, n);
            check_step(lesson, i, control)
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(CheckReport {
        lesson: lesson.name.clone(),
        steps,
    })
}

fn check_step(lesson: &Lesson, i: usize, control: &Control) -> Result<StepReport, LessonError> {
    let step: &Step = &lesson.steps[i];
    let start = std::time::Instant::now();
    let solved = solve_step(step, &[], control, &lesson.source)?;
    let ctx = solved.context();
    for e in &step.asserts {
        if !truth(lesson, i, ".asserts", e, &ctx)? {
            return Err(at(
                lesson,
                i,
                ".asserts",
                format!("'{e}' is false for this step's run"),
            ));
        }
    }
    let answer = match &step.prediction {
        None => None,
        Some(p) => {
            if let Prediction::Choice {
                answer, options, ..
            } = p
            {
                let picked = p
                    .model_choice(&ctx)
                    .map_err(|e| at(lesson, i, ".prediction.when", e.to_string()))?;
                if picked != Some(*answer) {
                    return Err(at(
                        lesson,
                        i,
                        ".prediction.answer",
                        format!(
                            "the answer key is option {}, but the model picks option {} ('{}')",
                            answer + 1,
                            picked.map_or(0, |k| k + 1),
                            picked.map_or("", |k| options[k].as_str())
                        ),
                    ));
                }
            }
            Some(
                p.expected(&ctx)
                    .map_err(|e| at(lesson, i, ".prediction.answer", e.to_string()))?,
            )
        }
    };
    let (mut before, mut after) = (None, None);
    if let Some(task) = &step.task {
        let met = truth(lesson, i, ".task.goal", &task.goal, &ctx)?;
        before = Some(met);
        if !task.solution.is_empty() {
            if met {
                return Err(at(
                    lesson,
                    i,
                    ".task.goal",
                    format!("'{}' is already met before the solution", task.goal),
                ));
            }
            let solved = solve_step(step, &task.solution, control, &lesson.source)?;
            let met = truth(lesson, i, ".task.goal", &task.goal, &solved.context())?;
            if !met {
                return Err(at(
                    lesson,
                    i,
                    ".task.solution",
                    format!("the solution does not meet '{}'", task.goal),
                ));
            }
            after = Some(met);
        }
    }
    Ok(StepReport {
        title: step.title.clone(),
        answer,
        task_met_at_start: before,
        task_met_by_solution: after,
        asserts: step.asserts.len(),
        solve_time_s: start.elapsed().as_secs_f64(),
    })
}
