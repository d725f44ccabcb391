//! A printable worksheet: Markdown with each step's text and questions, and the step's figures
//! rendered headless as PNG with the CPU exporters. The teacher's version adds the answers
//! (computed from the model), the explanations and the teacher notes.

use super::solve::{Solved, solve_step};
use super::{Lesson, LessonError, Panel, Prediction, Step};
use crate::export::plot::{LinePlot, Series};
use crate::export::xt::XtImage;
use crate::model::control::Control;
use crate::model::xt::{XtField, XtGrid};
use std::fmt::Write;
use std::path::{Path, PathBuf};

/// What a handout wrote.
#[derive(Debug, Clone, PartialEq)]
pub struct Handout {
    /// The Markdown file.
    pub markdown: PathBuf,
    /// The figures, in order.
    pub figures: Vec<PathBuf>,
}

/// Figure size of the handout's plots [px]: a printed page's width at about 150 dpi.
const SIZE: (u32, u32) = (1000, 560);

fn io_error(dir: &Path, what: String) -> LessonError {
    LessonError {
        file: dir.display().to_string(),
        line: None,
        field: None,
        message: what,
    }
}

/// Writes `DIR/NAME.md` (or `NAME-teacher.md`) and its figures `DIR/NAME-stepN-PANEL.png`.
pub fn write(
    lesson: &Lesson,
    dir: &Path,
    teacher: bool,
    control: &Control,
) -> Result<Handout, LessonError> {
    std::fs::create_dir_all(dir)
        .map_err(|e| io_error(dir, format!("cannot create the folder: {e}")))?;
    let mut md = String::new();
    let _ = writeln!(md, "# {}\n", lesson.title);
    let _ = writeln!(
        md,
        "*{}, about {} minutes.*\n\n## Goals\n",
        lesson.audience, lesson.duration_min
    );
    for g in &lesson.goals {
        let _ = writeln!(md, "- {g}");
    }
    if teacher {
        let _ = writeln!(md, "\n## Teacher notes\n\n{}", lesson.teacher_notes.trim());
    }
    let mut figures = Vec::new();
    for (i, step) in lesson.steps.iter().enumerate() {
        control.stage(i as u32, lesson.steps.len() as u32);
        let solved = solve_step(step, &[], control, &lesson.source)?;
        let _ = writeln!(
            md,
            "\n## Step {}: {}\n\n{}\n",
            i + 1,
            step.title,
            step.text.trim()
        );
        let own = question(&mut md, step);
        for panel in &step.show {
            let name = format!("{}-step{}-{}.png", lesson.name, i + 1, panel.name());
            let path = dir.join(&name);
            if figure(&solved, *panel, &path).map_err(|e| io_error(&path, e))? {
                let _ = writeln!(md, "![{} ({})]({name})\n", step.title, panel.name());
                figures.push(path);
            }
        }
        if teacher && own {
            answer(&mut md, step, &solved, &lesson.source)?;
        }
    }
    let file = if teacher {
        format!("{}-teacher.md", lesson.name)
    } else {
        format!("{}.md", lesson.name)
    };
    let markdown = dir.join(file);
    std::fs::write(&markdown, md).map_err(|e| io_error(&markdown, format!("cannot write: {e}")))?;
    Ok(Handout { markdown, figures })
}

/// The step's question and task, with room to answer; whether there is anything to answer.
fn question(md: &mut String, step: &Step) -> bool {
    if let Some(p) = &step.prediction {
        let _ = writeln!(md, "**Predict first.** {}\n", p.question());
        match p {
            Prediction::Choice { options, .. } => {
                for (k, o) in options.iter().enumerate() {
                    let _ = writeln!(md, "{}. [ ] {o}", k + 1);
                }
                md.push('\n');
            }
            Prediction::Number { unit, .. } => {
                let _ = writeln!(md, "Your answer: ______________ {unit}\n");
            }
        }
    }
    if let Some(t) = &step.task {
        let _ = writeln!(
            md,
            "**Task.** {}\n\n*Hint:* {}\n",
            t.text.trim(),
            t.hint.trim()
        );
    }
    step.prediction.is_some() || step.task.is_some()
}

/// The teacher's answer block: the model's answer, the explanation, the goal.
fn answer(md: &mut String, step: &Step, solved: &Solved, file: &str) -> Result<(), LessonError> {
    let ctx = solved.context();
    if let Some(p) = &step.prediction {
        let expected = p.expected(&ctx).map_err(|e| LessonError {
            file: file.to_string(),
            line: Some(step.line),
            field: Some(format!("step '{}'.prediction", step.title)),
            message: e.to_string(),
        })?;
        let tolerance = match p {
            Prediction::Number { tolerance, .. } => {
                format!(" (accepted within {}%)", tolerance * 100.0)
            }
            Prediction::Choice { .. } => String::new(),
        };
        let _ = writeln!(
            md,
            "> **Answer:** {expected}{tolerance}\n>\n> {}\n",
            p.explanation().trim().replace('\n', "\n> ")
        );
    }
    if let Some(t) = &step.task {
        let _ = writeln!(md, "> **Goal checked:** `{}`\n", t.goal);
        if !t.solution.is_empty() {
            let s: Vec<String> = t
                .solution
                .iter()
                .map(|(k, v, _)| format!("{k}={v}"))
                .collect();
            let _ = writeln!(md, "> **One way:** `{}`\n", s.join(" "));
        }
    }
    Ok(())
}

/// Renders one panel as PNG; `false` for a panel with no printable figure (the animated bars
/// and buildings, the readouts: the text carries them).
fn figure(solved: &Solved, panel: Panel, path: &Path) -> Result<bool, String> {
    let plot = match (solved, panel) {
        (Solved::Impact { runs, .. }, Panel::Force) => LinePlot::new(
            "Contact force",
            "time [ms]",
            "force [kN]",
            runs.iter()
                .map(|(m, r)| series(m.name(), &r.time_s, &r.force_n, 1e3, 1e-3))
                .collect(),
        ),
        (Solved::Impact { runs, .. }, Panel::Approach) => LinePlot::new(
            "Approach of the contact",
            "time [ms]",
            "approach [um]",
            runs.iter()
                .map(|(m, r)| series(m.name(), &r.time_s, &r.approach_m, 1e3, 1e6))
                .collect(),
        ),
        (Solved::Impact { setup, runs }, Panel::Energy) => {
            let (m, r) = &runs[0];
            let h = crate::model::impact::energy::energy_history(&setup.scenario, r, 600);
            LinePlot::new(
                format!("Where the energy goes: {}", m.name()),
                "time [ms]",
                "energy [J]",
                vec![
                    series(
                        "rigid-body kinetic",
                        &h.time_s,
                        &h.rigid_kinetic_j,
                        1e3,
                        1.0,
                    ),
                    series("waves in the bars", &h.time_s, &h.wave_j, 1e3, 1.0),
                    series("in the contact", &h.time_s, &h.contact_j, 1e3, 1.0),
                    series("dissipated", &h.time_s, &h.dissipated_j, 1e3, 1.0),
                ],
            )
        }
        (Solved::Impact { setup, runs }, Panel::Xt) => {
            let (m, r) = &runs[0];
            let sc = &setup.scenario;
            let grid = XtGrid::of(
                r,
                [sc.bar1.area_m2(), sc.bar2.area_m2()],
                [sc.bar1.length_m, sc.bar2.length_m],
                160,
                320,
                r.view_span_s(),
            );
            XtImage {
                grid: &grid,
                field: XtField::Stress,
                title: format!("x-t diagram: {}, stress", m.name()),
                size: SIZE,
                scale: 1.0,
                zones_m: None,
            }
            .write_png(path)
            .map_err(|e| e.to_string())?;
            return Ok(true);
        }
        (Solved::Buildings { result, .. }, Panel::Force) => LinePlot::new(
            "Pounding force",
            "time [s]",
            "force [MN]",
            vec![series(
                "pounding",
                &result.time_s,
                &result.force_n,
                1.0,
                1e-6,
            )],
        ),
        (Solved::Buildings { result, free, .. }, Panel::Displacements) => LinePlot::new(
            "Roof displacements",
            "time [s]",
            "displacement [mm]",
            vec![
                series("left", &result.time_s, &result.displacement_m[0], 1.0, 1e3),
                series("right", &result.time_s, &result.displacement_m[1], 1.0, 1e3),
                series(
                    "left, no contact",
                    &free.time_s,
                    &free.displacement_m[0],
                    1.0,
                    1e3,
                ),
                series(
                    "right, no contact",
                    &free.time_s,
                    &free.displacement_m[1],
                    1.0,
                    1e3,
                ),
            ],
        ),
        (Solved::Buildings { free, .. }, Panel::Gaps) => {
            let closing: Vec<f64> = free.displacement_m[0]
                .iter()
                .zip(&free.displacement_m[1])
                .map(|(l, r)| l - r)
                .collect();
            LinePlot::new(
                "Closing motion without contact (its peak is the gap needed)",
                "time [s]",
                "u_left - u_right [mm]",
                vec![series("closing", &free.time_s, &closing, 1.0, 1e3)],
            )
        }
        _ => return Ok(false),
    };
    LinePlot { size: SIZE, ..plot }
        .write(path)
        .map_err(|e| e.to_string())?;
    Ok(true)
}

fn series(name: &str, t: &[f64], y: &[f64], tx: f64, ty: f64) -> Series {
    // A printed line needs no more than a few thousand points.
    let stride = (t.len() / 4000).max(1);
    Series {
        name: name.to_string(),
        points: t
            .iter()
            .zip(y)
            .step_by(stride)
            .map(|(a, b)| (a * tx, b * ty))
            .collect(),
    }
}
