//! `lesson --check`: every step loaded and solved headless, every expression evaluated.

use super::context::{COMPARE_MODELS, model_prefix};
use super::expr::Expr;
use super::solve::solve_step;
use super::{Context, Lesson, LessonError, LessonScene, Panel, Prediction, Step};
use crate::model::control::Control;
use crate::model::settings::concrete_keys;

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
    let mut steps = Vec::with_capacity(lesson.steps.len());
    let mut seen: Vec<Context> = Vec::with_capacity(lesson.steps.len());
    for i in 0..lesson.steps.len() {
        // Each step is an equal part of the progress a caller shows.
        control.stage(i as u32, n);
        let (report, ctx) = check_step(lesson, i, control)?;
        answer_not_shown_before(lesson, i, &ctx, &seen)?;
        steps.push(report);
        seen.push(ctx);
    }
    Ok(CheckReport {
        lesson: lesson.name.clone(),
        steps,
    })
}

/// The result fields a panel shows as numbers, by scene (a compare scene's table shows each
/// model's): what a later step must not ask while the same value is already on screen.
fn shown_by(scene: LessonScene, panel: Panel) -> &'static [&'static str] {
    match (scene, panel) {
        (LessonScene::Bar, Panel::Readouts) => &[
            "peak_force_n",
            "contact_duration_s",
            "touching_duration_s",
            "restitution",
            "restitution_first_contact",
            "contacts",
            "energy.initial_j",
            "energy.rigid_body_j",
            "energy.vibration_j",
            "energy.dissipated_j",
            "energy_balance_error",
            "a_tau",
            "steps",
            "dt_s",
        ],
        (LessonScene::Compare, Panel::Readouts) => {
            &["peak_force_n", "contact_duration_s", "restitution"]
        }
        (LessonScene::Buildings, Panel::Readouts) => &[
            "impact_count",
            "contact_count",
            "max_pounding_force_n",
            "peak_displacement_left_m",
            "peak_displacement_right_m",
            "peak_displacement_left_no_pounding_m",
            "peak_displacement_right_no_pounding_m",
        ],
        (LessonScene::Buildings, Panel::Impacts) => {
            &["impact_count", "contact_count", "max_pounding_force_n"]
        }
        (LessonScene::Buildings, Panel::Hysteresis) => {
            &["ductility_demand_left", "ductility_demand_right"]
        }
        (LessonScene::Buildings, Panel::Gaps) => &[
            "min_gap_m",
            "abs_gap_m",
            "srss_gap_m",
            "abs_ratio",
            "srss_ratio",
        ],
        (LessonScene::Bridge, panel) => bridge_shown_by(panel),
        _ => &[],
    }
}

/// The bridge's panels: its readouts and tables, and the plots whose axes give a number away
/// (each joint's and girder's fields as `joint.NAME` and `girder.NAME`, whichever joint).
fn bridge_shown_by(panel: Panel) -> &'static [&'static str] {
    const FORCES: &[&str] = &[
        "max_pounding_force_n",
        "max_force_at_abutments_n",
        "max_force_between_girders_n",
        "joint.max_force_n",
        "joints_with_impacts",
    ];
    const SEATS: &[&str] = &[
        "max_opening_m",
        "joint.max_opening_m",
        "joint.seat_margin_m",
        "joint.unseated",
        "joint.unseated_s",
        "unseated_count",
        "first_unseating_s",
    ];
    match panel {
        Panel::Readouts => &[
            "impact_count",
            "contact_count",
            "max_pounding_force_n",
            "girder.peak_displacement_m",
            "girder.peak_displacement_no_pounding_m",
            "energy_girder_waves_j",
        ],
        Panel::Force => FORCES,
        Panel::Openings => SEATS,
        Panel::Displacements => &[
            "girder.peak_displacement_m",
            "girder.peak_displacement_no_pounding_m",
        ],
        Panel::Joints => &[
            "max_pounding_force_n",
            "max_force_at_abutments_n",
            "max_force_between_girders_n",
            "joint.max_force_n",
            "joint.required_gap_m",
            "max_opening_m",
            "joint.max_opening_m",
            "joint.seat_margin_m",
            "joint.unseated",
            "joint.unseated_s",
            "unseated_count",
            "first_unseating_s",
        ],
        Panel::Impacts => &[
            "impact_count",
            "contact_count",
            "joints_with_impacts",
            "joint.impacts",
            "max_pounding_force_n",
            "max_force_at_abutments_n",
            "max_force_between_girders_n",
            "joint.max_force_n",
            "strongest_impact",
            "strongest_impact_joint",
            "strongest_impact_duration_s",
            "strongest_impact_approach_velocity_m_s",
            "shortest_impact_duration_s",
            "longest_impact_duration_s",
        ],
        _ => &[],
    }
}

/// Whether `panel` of a step in `scene` shows the field `name` (a compare model's field under
/// its prefix too; a bridge joint's or girder's as `joint.NAME` or `girder.NAME`).
fn shows(scene: LessonScene, panel: Panel, name: &str) -> bool {
    let fields = shown_by(scene, panel);
    let bare = match name.split_once('.') {
        Some((model, field))
            if scene == LessonScene::Compare
                && COMPARE_MODELS.iter().any(|m| model_prefix(*m) == model) =>
        {
            field.to_string()
        }
        Some((member, field)) if scene == LessonScene::Bridge => {
            let kind = member.trim_end_matches(|c: char| c.is_ascii_digit());
            if kind.len() < member.len() && (kind == "joint" || kind == "girder") {
                format!("{kind}.{field}")
            } else {
                name.to_string()
            }
        }
        _ => name.to_string(),
    };
    fields.contains(&bare.as_str())
}

/// Refuses a prediction whose answer can be read off an earlier step's screen: every result
/// field its expressions read (settings are the step's own inputs) is shown, with the value it
/// has now, by a panel of some earlier step.
fn answer_not_shown_before(
    lesson: &Lesson,
    i: usize,
    ctx: &Context,
    seen: &[Context],
) -> Result<(), LessonError> {
    let step = &lesson.steps[i];
    let Some(p) = &step.prediction else {
        return Ok(());
    };
    let settings = concrete_keys(step.scene.settings().0);
    let mut names: Vec<&str> = match p {
        Prediction::Choice { when, .. } => when.iter().flat_map(|e| e.names()).collect(),
        Prediction::Number { answer, .. } => answer.names(),
    };
    names.retain(|n| !settings.iter().any(|k| k == n));
    names.sort_unstable();
    names.dedup();
    let shown_where = |name: &str| {
        let now = ctx.get(name).ok()?;
        lesson.steps[..i]
            .iter()
            .enumerate()
            .find_map(|(j, earlier)| {
                earlier.show.iter().find_map(|&panel| {
                    (shows(earlier.scene, panel, name)
                        && seen[j].get(name).ok() == Some(now.clone()))
                    .then(|| format!("{name} = {now} (step {}'s {})", j + 1, panel.name()))
                })
            })
    };
    let shown: Vec<String> = names.iter().filter_map(|n| shown_where(n)).collect();
    if names.is_empty() || shown.len() < names.len() {
        return Ok(());
    }
    Err(at(
        lesson,
        i,
        ".prediction",
        format!(
            "its answer can be read off an earlier screen: {}; ask before showing it, or leave that panel out",
            shown.join(", ")
        ),
    ))
}

fn check_step(
    lesson: &Lesson,
    i: usize,
    control: &Control,
) -> Result<(StepReport, Context), LessonError> {
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
    let report = StepReport {
        title: step.title.clone(),
        answer,
        task_met_at_start: before,
        task_met_by_solution: after,
        asserts: step.asserts.len(),
        solve_time_s: start.elapsed().as_secs_f64(),
    };
    Ok((report, ctx))
}
