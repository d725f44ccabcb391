//! A printable worksheet: each step's text and questions, and the step's figures rendered
//! headless as PNG with the CPU exporters, written as Markdown and as one self-contained HTML
//! page (figures inlined) that prints from any browser. The student's copy keeps the figures of
//! a step that asks a question until after all the questions, under "Results", so no result
//! sits under its own question; the teacher's copy adds the answers (computed from the model),
//! the explanations and the teacher notes, with each figure in its step.

use super::solve::{Solved, solve_step};
use super::{Lesson, LessonError, Panel, Prediction, Step};
use crate::export::plot::{LinePlot, Series};
use crate::export::xt::XtImage;
use crate::io::bridge_settings::BridgeSetup;
use crate::model::bridge::BridgeResult;
use crate::model::building::BuildingResult;
use crate::model::control::Control;
use crate::model::xt::{XtField, XtGrid};
use std::fmt::Write;
use std::path::{Path, PathBuf};

/// What a handout wrote.
#[derive(Debug, Clone, PartialEq)]
pub struct Handout {
    /// The Markdown file.
    pub markdown: PathBuf,
    /// The self-contained HTML page.
    pub html: PathBuf,
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

/// One piece of a worksheet, as both formats write it.
#[derive(Debug, Clone, PartialEq)]
enum Block {
    /// A heading of `level` (1: the title).
    Heading(u8, String),
    /// A paragraph, with a bold lead (`Predict first.`) if any.
    Para { lead: Option<String>, text: String },
    /// Options to tick.
    Options(Vec<String>),
    /// A line to write an answer on, with its unit.
    AnswerLine(String),
    /// A figure: its file name and caption.
    Figure { file: String, caption: String },
    /// What the teacher's copy says under a question: answer, explanation, goal.
    Solution(Vec<String>),
    /// A list of items.
    List(Vec<String>),
}

/// Writes the student's copy (`DIR/NAME.md`, `DIR/NAME.html`), and with `teacher` the
/// teacher's copy too (`NAME-teacher.md`, `NAME-teacher.html`): both from one solve of every
/// step, sharing the figures `DIR/NAME-stepN-PANEL.png`. Returns the last copy written.
pub fn write(
    lesson: &Lesson,
    dir: &Path,
    teacher: bool,
    control: &Control,
) -> Result<Handout, LessonError> {
    std::fs::create_dir_all(dir)
        .map_err(|e| io_error(dir, format!("cannot create the folder: {e}")))?;
    let steps = render_steps(lesson, dir, teacher, control)?;
    let figures: Vec<PathBuf> = steps
        .iter()
        .flat_map(|s| s.figures.iter().map(|(f, _)| dir.join(f)))
        .collect();
    let mut last = save(lesson, dir, &student_copy(lesson, &steps), &lesson.name)?;
    if teacher {
        let name = format!("{}-teacher", lesson.name);
        last = save(lesson, dir, &teacher_copy(lesson, &steps), &name)?;
    }
    Ok(Handout { figures, ..last })
}

/// One step, solved: its text and question, its figures (file, caption), the figures it shares
/// with an earlier step (said, not drawn twice), and the teacher's solution.
struct StepBlocks {
    text: Vec<Block>,
    figures: Vec<(String, String)>,
    same_as: Vec<String>,
    asks: bool,
    solution: Vec<Block>,
}

fn render_steps(
    lesson: &Lesson,
    dir: &Path,
    teacher: bool,
    control: &Control,
) -> Result<Vec<StepBlocks>, LessonError> {
    let mut out: Vec<StepBlocks> = Vec::new();
    let mut drawn: Vec<(Vec<u8>, String)> = Vec::new();
    for (i, step) in lesson.steps.iter().enumerate() {
        control.stage(i as u32, lesson.steps.len() as u32);
        let solved = solve_step(step, &[], control, &lesson.source)?;
        let mut text = vec![
            Block::Heading(2, format!("Step {}: {}", i + 1, step.title)),
            Block::Para {
                lead: None,
                text: step.text.trim().to_string(),
            },
        ];
        let asks = question(&mut text, step);
        let (mut figures, mut same_as) = (vec![], vec![]);
        for panel in &step.show {
            let name = format!("{}-step{}-{}.png", lesson.name, i + 1, panel.name());
            let path = dir.join(&name);
            if !figure(&solved, *panel, &path).map_err(|e| io_error(&path, e))? {
                continue;
            }
            let bytes = std::fs::read(&path).map_err(|e| io_error(&path, e.to_string()))?;
            let caption = format!("Step {}, {}", i + 1, panel.name());
            match drawn.iter().find(|(b, _)| *b == bytes) {
                Some((_, earlier)) => {
                    let _ = std::fs::remove_file(&path);
                    same_as.push(format!("{caption}: the same figure as {earlier}."));
                }
                None => {
                    drawn.push((bytes, caption.clone()));
                    figures.push((name, caption));
                }
            }
        }
        let mut solution = vec![];
        if teacher && asks {
            solution.push(answer(step, &solved, &lesson.source)?);
        }
        out.push(StepBlocks {
            text,
            figures,
            same_as,
            asks,
            solution,
        });
    }
    Ok(out)
}

fn head(lesson: &Lesson) -> Vec<Block> {
    vec![
        Block::Heading(1, lesson.title.clone()),
        Block::Para {
            lead: None,
            text: format!(
                "{}, about {} minutes.",
                lesson.audience, lesson.duration_min
            ),
        },
        Block::Heading(2, "Goals".into()),
        Block::List(lesson.goals.clone()),
    ]
}

fn figure_blocks(s: &StepBlocks) -> Vec<Block> {
    let mut out: Vec<Block> = s
        .figures
        .iter()
        .map(|(file, caption)| Block::Figure {
            file: file.clone(),
            caption: caption.clone(),
        })
        .collect();
    out.extend(s.same_as.iter().map(|t| Block::Para {
        lead: None,
        text: t.clone(),
    }));
    out
}

/// The student's copy: questions first; a questioning step's figures wait under "Results".
fn student_copy(lesson: &Lesson, steps: &[StepBlocks]) -> Vec<Block> {
    let mut doc = head(lesson);
    let mut results = vec![];
    for s in steps {
        doc.extend(s.text.iter().cloned());
        if s.asks {
            results.extend(figure_blocks(s));
        } else {
            doc.extend(figure_blocks(s));
        }
    }
    if !results.is_empty() {
        doc.push(Block::Heading(
            2,
            "Results, to look at after answering".into(),
        ));
        doc.extend(results);
    }
    doc
}

/// The teacher's copy: the notes, then each step with its figures and its solution.
fn teacher_copy(lesson: &Lesson, steps: &[StepBlocks]) -> Vec<Block> {
    let mut doc = head(lesson);
    doc.push(Block::Heading(2, "Teacher notes".into()));
    doc.push(Block::Para {
        lead: None,
        text: lesson.teacher_notes.trim().to_string(),
    });
    for s in steps {
        doc.extend(s.text.iter().cloned());
        doc.extend(figure_blocks(s));
        doc.extend(s.solution.iter().cloned());
    }
    doc
}

/// Writes `NAME.md` and `NAME.html` (figures inlined) of `doc`.
fn save(lesson: &Lesson, dir: &Path, doc: &[Block], name: &str) -> Result<Handout, LessonError> {
    let markdown = dir.join(format!("{name}.md"));
    std::fs::write(&markdown, to_markdown(doc))
        .map_err(|e| io_error(&markdown, format!("cannot write: {e}")))?;
    let html = dir.join(format!("{name}.html"));
    std::fs::write(&html, to_html(&lesson.title, doc, dir)?)
        .map_err(|e| io_error(&html, format!("cannot write: {e}")))?;
    Ok(Handout {
        markdown,
        html,
        figures: vec![],
    })
}

fn to_markdown(doc: &[Block]) -> String {
    let mut md = String::new();
    for b in doc {
        match b {
            Block::Heading(level, t) => {
                let _ = writeln!(md, "{} {t}\n", "#".repeat(usize::from(*level)));
            }
            Block::Para {
                lead: Some(l),
                text,
            } => {
                let _ = writeln!(md, "**{l}** {text}\n");
            }
            Block::Para { lead: None, text } => {
                let _ = writeln!(md, "{text}\n");
            }
            Block::Options(options) => {
                for (k, o) in options.iter().enumerate() {
                    let _ = writeln!(md, "{}. [ ] {o}", k + 1);
                }
                md.push('\n');
            }
            Block::AnswerLine(unit) => {
                let _ = writeln!(md, "Your answer: ______________ {unit}\n");
            }
            Block::Figure { file, caption } => {
                let _ = writeln!(md, "![{caption}]({file})\n");
            }
            Block::Solution(lines) => {
                let quoted: Vec<String> = lines
                    .iter()
                    .map(|l| format!("> {}", l.replace('\n', "\n> ")))
                    .collect();
                let _ = writeln!(md, "{}\n", quoted.join("\n>\n"));
            }
            Block::List(items) => {
                for i in items {
                    let _ = writeln!(md, "- {i}");
                }
                md.push('\n');
            }
        }
    }
    md
}

/// Text as HTML: the characters XML reserves escaped.
fn escape(t: &str) -> String {
    t.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
        .replace('\'', "&#39;")
}

/// Text with `**bold**` and `` `code` `` spans, as HTML.
fn inline(t: &str) -> String {
    let mut out = String::new();
    for (k, part) in escape(t).split("**").enumerate() {
        let part: String = part
            .split('`')
            .enumerate()
            .map(|(j, p)| {
                if j % 2 == 1 {
                    format!("<code>{p}</code>")
                } else {
                    p.to_string()
                }
            })
            .collect();
        if k % 2 == 1 {
            let _ = write!(out, "<strong>{part}</strong>");
        } else {
            out.push_str(&part);
        }
    }
    out
}

/// A text's paragraphs (blank lines apart) as `<p>`s; single line breaks flow together.
fn paragraphs(lead: Option<&str>, text: &str) -> String {
    let mut out = String::new();
    for (k, p) in text.split("\n\n").enumerate() {
        let flowed = p.split('\n').map(str::trim).collect::<Vec<_>>().join(" ");
        let lead = match (k, lead) {
            (0, Some(l)) => format!("<strong>{}</strong> ", escape(l)),
            _ => String::new(),
        };
        let _ = writeln!(out, "<p>{lead}{}</p>", inline(&flowed));
    }
    out
}

/// A style that reads on screen and prints on A4 or Letter (figures kept whole on a page).
const STYLE: &str = "body{font-family:sans-serif;max-width:46em;margin:2em auto;line-height:1.45;color:#111}\
h1{font-size:1.7em}h2{font-size:1.25em;margin-top:1.6em;border-bottom:1px solid #999}\
figure{margin:1em 0;break-inside:avoid}figure img{width:100%;height:auto;border:1px solid #ccc}\
figcaption{font-size:.9em;color:#444}.line{border-bottom:1px solid #000;display:inline-block;width:12em}\
blockquote{border-left:4px solid #0072b2;margin:1em 0;padding:.2em 1em;background:#f3f7fb}\
ol.options{list-style:none;padding-left:0}ol.options li::before{content:'\\2610  '}\
@media print{body{margin:0;max-width:none}h2{break-after:avoid}}";

/// A self-contained page: the figures as data URIs, so one file is the whole handout.
fn to_html(title: &str, doc: &[Block], dir: &Path) -> Result<String, LessonError> {
    let mut h = String::new();
    let _ = writeln!(
        h,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n<title>{}</title>\n<style>{STYLE}</style>\n</head>\n<body>",
        escape(title)
    );
    for b in doc {
        match b {
            Block::Heading(level, t) => {
                let _ = writeln!(h, "<h{level}>{}</h{level}>", escape(t));
            }
            Block::Para { lead, text } => h.push_str(&paragraphs(lead.as_deref(), text)),
            Block::Options(options) => {
                h.push_str("<ol class=\"options\">\n");
                for o in options {
                    let _ = writeln!(h, "<li>{}</li>", inline(o));
                }
                h.push_str("</ol>\n");
            }
            Block::AnswerLine(unit) => {
                let _ = writeln!(
                    h,
                    "<p>Your answer: <span class=\"line\"></span> {}</p>",
                    escape(unit)
                );
            }
            Block::Figure { file, caption } => {
                let path = dir.join(file);
                let bytes = std::fs::read(&path).map_err(|e| io_error(&path, e.to_string()))?;
                let _ = writeln!(
                    h,
                    "<figure><img src=\"data:image/png;base64,{}\" alt=\"{}\" title=\"{}\"/><figcaption>{}</figcaption></figure>",
                    base64(&bytes),
                    escape(caption),
                    escape(file),
                    escape(caption)
                );
            }
            Block::Solution(lines) => {
                h.push_str("<blockquote>\n");
                for l in lines {
                    h.push_str(&paragraphs(None, l));
                }
                h.push_str("</blockquote>\n");
            }
            Block::List(items) => {
                h.push_str("<ul>\n");
                for i in items {
                    let _ = writeln!(h, "<li>{}</li>", inline(i));
                }
                h.push_str("</ul>\n");
            }
        }
    }
    h.push_str("</body>\n</html>\n");
    Ok(h)
}

/// Standard base64 (RFC 4648, padded): how a figure travels inside the page.
fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            chunk.get(1).copied().unwrap_or(0),
            chunk.get(2).copied().unwrap_or(0),
        ];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(ALPHABET[((n >> (18 - 6 * k)) & 63) as usize] as char);
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// The step's question and task, with room to answer; whether there is anything to answer.
fn question(doc: &mut Vec<Block>, step: &Step) -> bool {
    if let Some(p) = &step.prediction {
        doc.push(Block::Para {
            lead: Some("Predict first.".into()),
            text: p.question().trim().to_string(),
        });
        match p {
            Prediction::Choice { options, .. } => doc.push(Block::Options(options.clone())),
            Prediction::Number { unit, .. } => doc.push(Block::AnswerLine(unit.clone())),
        }
    }
    if let Some(t) = &step.task {
        doc.push(Block::Para {
            lead: Some("Task.".into()),
            text: t.text.trim().to_string(),
        });
        doc.push(Block::Para {
            lead: Some("Hint:".into()),
            text: t.hint.trim().to_string(),
        });
    }
    step.prediction.is_some() || step.task.is_some()
}

/// The teacher's solution to a step: the model's answer, the explanation, the goal.
fn answer(step: &Step, solved: &Solved, file: &str) -> Result<Block, LessonError> {
    let ctx = solved.context();
    let mut lines = vec![];
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
        lines.push(format!("**Answer:** {expected}{tolerance}"));
        lines.push(p.explanation().trim().to_string());
    }
    if let Some(t) = &step.task {
        lines.push(format!("**Goal checked:** `{}`", t.goal));
        if !t.solution.is_empty() {
            let s: Vec<String> = t
                .solution
                .iter()
                .map(|(k, v, _)| format!("{k}={v}"))
                .collect();
            lines.push(format!("**One way:** `{}`", s.join(" ")));
        }
    }
    Ok(Block::Solution(lines))
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
        (Solved::Buildings { result, free, .. }, _) => match buildings_plot(result, free, panel) {
            Some(plot) => plot,
            None => return Ok(false),
        },
        (
            Solved::Bridge {
                setup,
                result,
                free,
            },
            _,
        ) => match bridge_plot(setup, result, free, panel) {
            Some(plot) => plot,
            None => return Ok(false),
        },
        _ => return Ok(false),
    };
    LinePlot { size: SIZE, ..plot }
        .write(path)
        .map_err(|e| e.to_string())?;
    Ok(true)
}

/// A buildings step's plot of `panel`; `None` for a panel with no printable figure.
fn buildings_plot(
    result: &BuildingResult,
    free: &BuildingResult,
    panel: Panel,
) -> Option<LinePlot> {
    let plot = match panel {
        Panel::Force => LinePlot::new(
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
        Panel::Displacements => LinePlot::new(
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
        Panel::Gaps => {
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
        _ => return None,
    };
    Some(plot)
}

/// A bridge step's plot of `panel` (for the impact list, the strongest impact's force); `None`
/// for a panel with no printable figure (the animated bridge and the deck's x-t diagram, the
/// readouts and the joints' table: the text carries them).
fn bridge_plot(
    setup: &BridgeSetup,
    result: &BridgeResult,
    free: &BridgeResult,
    panel: Panel,
) -> Option<LinePlot> {
    use crate::export::bridge_plots as plots;
    match panel {
        Panel::Force => Some(plots::joint_forces(
            result,
            format!("Joint forces: {} contact", result.contact.name()),
        )),
        Panel::Openings => Some(plots::joint_openings(result, setup.scenario.seat_length_m)),
        Panel::Displacements => Some(plots::girder_displacements(result, free)),
        Panel::Impacts => plots::strongest_impact(result),
        _ => None,
    }
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_matches_the_standards_examples() {
        // RFC 4648, section 10.
        for (plain, coded) in [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(base64(plain.as_bytes()), coded, "{plain}");
        }
    }

    #[test]
    fn html_text_is_escaped_and_bold_and_code_spans_kept() {
        assert_eq!(inline("a < b & **c**"), "a &lt; b &amp; <strong>c</strong>");
        assert_eq!(inline("`k=1`"), "<code>k=1</code>");
    }
}
