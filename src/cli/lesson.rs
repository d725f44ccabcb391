//! `pounding lesson`: list the shipped lessons, check a lesson file, write a worksheet.

use clap::Args;
use pounding::lesson::{self, Lesson};
use std::io::Write;
use std::path::PathBuf;

#[derive(Args, Debug, Default)]
pub struct LessonArgs {
    /// A shipped lesson's name (see --list) or a lesson file
    #[arg(value_name = "NAME-or-FILE")]
    pub lesson: Option<String>,
    /// List the shipped lessons, and exit
    #[arg(long)]
    pub list: bool,
    /// Load every step's scene, solve it, and evaluate every prediction, task and statement
    /// (a shipped name or a file); errors name the file, line and field
    #[arg(long, value_name = "NAME-or-FILE", conflicts_with_all = ["list", "handout"])]
    pub check: Option<String>,
    /// Write a printable worksheet into DIR: Markdown and the steps' figures as PNG
    #[arg(long, value_name = "DIR")]
    pub handout: Option<PathBuf>,
    /// With --handout: the teacher's copy too, with the answers, explanations and notes
    #[arg(long, requires = "handout")]
    pub teacher: bool,
    /// Show no progress bar on standard error (it shows only on a terminal)
    #[arg(long)]
    pub quiet: bool,
}

pub fn run(args: &LessonArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    if args.list {
        return list(out);
    }
    if let Some(name) = &args.check {
        return check(name, args.quiet, out);
    }
    let Some(name) = &args.lesson else {
        anyhow::bail!(
            "name a lesson (NAME or FILE), or give --list or --check; shipped lessons: {}",
            lesson::builtin_names().join(", ")
        );
    };
    let lesson = lesson::load(name)?;
    match &args.handout {
        Some(dir) => handout(&lesson, dir, args.teacher, args.quiet, out),
        None => outline(&lesson, out),
    }
}

fn list(out: &mut dyn Write) -> anyhow::Result<()> {
    for name in lesson::builtin_names() {
        let l = lesson::builtin(name)?;
        writeln!(
            out,
            "{name:24} {} ({} steps, about {} min; {})",
            l.title,
            l.steps.len(),
            l.duration_min,
            l.audience
        )?;
    }
    Ok(())
}

fn check(name: &str, quiet: bool, out: &mut dyn Write) -> anyhow::Result<()> {
    let lesson = lesson::load(name)?;
    let report = super::with_control("lesson --check", quiet, |c| lesson::check(&lesson, c))?;
    writeln!(out, "{}: {}", lesson.source, lesson.title)?;
    for (i, s) in report.steps.iter().enumerate() {
        let mut parts = Vec::new();
        if let Some(a) = &s.answer {
            parts.push(format!("answer {a}"));
        }
        match (s.task_met_at_start, s.task_met_by_solution) {
            (Some(_), Some(true)) => parts.push("task met by its solution".into()),
            (Some(met), None) => {
                parts.push(format!("task {}", if met { "met" } else { "not yet met" }))
            }
            _ => {}
        }
        if s.asserts > 0 {
            parts.push(format!("{} statement(s) hold", s.asserts));
        }
        writeln!(
            out,
            "  step {}: {}: ok ({:.2} s){}{}",
            i + 1,
            s.title,
            s.solve_time_s,
            if parts.is_empty() { "" } else { "; " },
            parts.join("; ")
        )?;
    }
    writeln!(out, "ok: {} steps checked", report.steps.len())?;
    Ok(())
}

fn outline(lesson: &Lesson, out: &mut dyn Write) -> anyhow::Result<()> {
    writeln!(
        out,
        "{} ({}, about {} min)",
        lesson.title, lesson.audience, lesson.duration_min
    )?;
    for g in &lesson.goals {
        writeln!(out, "  goal: {g}")?;
    }
    for (i, s) in lesson.steps.iter().enumerate() {
        writeln!(
            out,
            "  step {}: {} [{} scene]",
            i + 1,
            s.title,
            s.scene.name()
        )?;
    }
    writeln!(
        out,
        "(`pounding lesson {} --handout DIR` writes the worksheet)",
        lesson.name
    )?;
    Ok(())
}

fn handout(
    lesson: &Lesson,
    dir: &std::path::Path,
    teacher: bool,
    quiet: bool,
    out: &mut dyn Write,
) -> anyhow::Result<()> {
    let start = std::time::Instant::now();
    let h = super::with_control("lesson --handout", quiet, |c| {
        lesson::handout::write(lesson, dir, teacher, c)
    })?;
    let copies = if teacher {
        format!(
            "the student's copy ({name}.md, {name}.html) and the teacher's ({})",
            h.html.display(),
            name = lesson.name
        )
    } else {
        format!("{} and {}", h.markdown.display(), h.html.display())
    };
    writeln!(
        out,
        "wrote {copies} with {} figure(s) in {:.2} s",
        h.figures.len(),
        start.elapsed().as_secs_f64()
    )?;
    Ok(())
}
