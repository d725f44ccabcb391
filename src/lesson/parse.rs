//! Reading a lesson file: strict (a field the format does not know is an error), every error
//! with its line and field.

use super::context::{COMPARE_MODELS, Vocabulary, model_prefix};
use super::expr::Expr;
use super::solve::SceneSetup;
use super::{Lesson, LessonError, LessonScene, Panel, Prediction, Step, Task};
use crate::model::impact::ModelKind;
use crate::model::settings::concrete_keys;
use toml::de::{DeTable, DeValue};

type Spanned<T> = toml::Spanned<T>;

/// The text and where errors point.
struct Doc<'a> {
    source: &'a str,
    /// Where each line break is, so a line number is a binary search (a lesson of many steps
    /// or long lists asks for one at every field).
    breaks: Vec<usize>,
}

impl<'a> Doc<'a> {
    fn new(text: &str, source: &'a str) -> Self {
        Doc {
            source,
            breaks: text
                .bytes()
                .enumerate()
                .filter(|&(_, b)| b == b'\n')
                .map(|(i, _)| i)
                .collect(),
        }
    }

    /// The line (from 1) of a byte offset.
    fn line(&self, offset: usize) -> usize {
        self.breaks.partition_point(|&b| b < offset) + 1
    }

    fn error(&self, line: Option<usize>, field: &str, message: impl Into<String>) -> LessonError {
        LessonError {
            file: self.source.to_string(),
            line,
            field: (!field.is_empty()).then(|| field.to_string()),
            message: message.into(),
        }
    }
}

/// One table's fields, taken one by one; what is left over is an unknown field.
struct Fields<'t, 'i> {
    path: String,
    line: usize,
    entries: Vec<(&'t str, &'t Spanned<DeValue<'i>>, usize)>,
}

impl<'t, 'i> Fields<'t, 'i> {
    /// The table's fields; a field not in `allowed` is refused first, so a typo is reported
    /// as itself rather than as the field it should have been, missing.
    fn new(
        doc: &Doc,
        table: &'t DeTable<'i>,
        path: &str,
        line: usize,
        allowed: &[&str],
    ) -> Result<Self, LessonError> {
        let f = Fields {
            path: path.to_string(),
            line,
            entries: table
                .iter()
                .map(|(k, v)| (k.get_ref().as_ref(), v, doc.line(k.span().start)))
                .collect(),
        };
        f.refuse_unknown(doc, allowed)?;
        Ok(f)
    }

    fn refuse_unknown(&self, doc: &Doc, allowed: &[&str]) -> Result<(), LessonError> {
        match self.entries.iter().find(|(k, _, _)| !allowed.contains(k)) {
            None => Ok(()),
            Some((k, _, line)) => Err(doc.error(
                Some(*line),
                &self.field(k),
                format!("unknown field; allowed here: {}", allowed.join(", ")),
            )),
        }
    }

    fn field(&self, key: &str) -> String {
        if self.path.is_empty() {
            key.to_string()
        } else {
            format!("{}.{key}", self.path)
        }
    }

    fn take(&mut self, key: &str) -> Option<(&'t DeValue<'i>, usize)> {
        let i = self.entries.iter().position(|(k, _, _)| *k == key)?;
        let (_, v, line) = self.entries.remove(i);
        Some((v.get_ref(), line))
    }

    fn string(&mut self, doc: &Doc, key: &str) -> Result<Option<(String, usize)>, LessonError> {
        match self.take(key) {
            None => Ok(None),
            Some((DeValue::String(s), line)) => Ok(Some((s.to_string(), line))),
            Some((_, line)) => Err(doc.error(Some(line), &self.field(key), "expected a string")),
        }
    }

    fn required(&mut self, doc: &Doc, key: &str) -> Result<(String, usize), LessonError> {
        self.string(doc, key)?.ok_or_else(|| {
            doc.error(
                Some(self.line),
                &self.field(key),
                "missing (a string is required here)",
            )
        })
    }

    fn strings(&mut self, doc: &Doc, key: &str) -> Result<Vec<(String, usize)>, LessonError> {
        match self.take(key) {
            None => Ok(Vec::new()),
            Some((DeValue::Array(items), line)) => items
                .iter()
                .map(|item| match item.get_ref() {
                    DeValue::String(s) => Ok((s.to_string(), doc.line(item.span().start))),
                    _ => Err(doc.error(
                        Some(doc.line(item.span().start)),
                        &self.field(key),
                        "expected a list of strings",
                    )),
                })
                .collect::<Result<Vec<_>, _>>()
                .map_err(|e| LessonError {
                    line: e.line.or(Some(line)),
                    ..e
                }),
            Some((_, line)) => Err(doc.error(
                Some(line),
                &self.field(key),
                "expected a list of strings, [\"...\", \"...\"]",
            )),
        }
    }

    fn number(&mut self, doc: &Doc, key: &str) -> Result<Option<(f64, usize)>, LessonError> {
        let parsed = match self.take(key) {
            None => return Ok(None),
            Some((DeValue::Integer(i), line)) => (i.as_str().replace('_', "").parse::<f64>(), line),
            Some((DeValue::Float(x), line)) => (x.as_str().replace('_', "").parse::<f64>(), line),
            Some((_, line)) => {
                return Err(doc.error(Some(line), &self.field(key), "expected a number"));
            }
        };
        match parsed {
            (Ok(x), line) if x.is_finite() => Ok(Some((x, line))),
            (_, line) => Err(doc.error(Some(line), &self.field(key), "expected a finite number")),
        }
    }

    fn table(
        &mut self,
        doc: &Doc,
        key: &str,
    ) -> Result<Option<(&'t DeTable<'i>, usize)>, LessonError> {
        match self.take(key) {
            None => Ok(None),
            Some((DeValue::Table(t), line)) => Ok(Some((t, line))),
            Some((_, line)) => Err(doc.error(
                Some(line),
                &self.field(key),
                format!("expected a table, [{}]", self.field(key)),
            )),
        }
    }

    /// Refuses whatever was not taken: a typo must not be silently ignored.
    fn finish(self, doc: &Doc, allowed: &[&str]) -> Result<(), LessonError> {
        match self.entries.first() {
            None => Ok(()),
            Some((k, _, line)) => Err(doc.error(
                Some(*line),
                &self.field(k),
                format!("unknown field; allowed here: {}", allowed.join(", ")),
            )),
        }
    }
}

const TOP: &[&str] = &[
    "title",
    "audience",
    "duration_min",
    "goals",
    "teacher_notes",
    "step",
];
const STEP: &[&str] = &[
    "title",
    "text",
    "scene",
    "preset",
    "set",
    "show",
    "models",
    "unlock",
    "asserts",
    "prediction",
    "task",
];
const CHOICE: &[&str] = &[
    "kind",
    "question",
    "options",
    "when",
    "answer",
    "explanation",
];
const NUMBER: &[&str] = &[
    "kind",
    "question",
    "unit",
    "answer",
    "tolerance",
    "explanation",
];
const TASK: &[&str] = &["goal", "text", "hint", "solution"];

pub(super) fn parse(text: &str, name: &str, source: &str) -> Result<Lesson, LessonError> {
    let doc = Doc::new(text, source);
    let root = DeTable::parse(text).map_err(|e| {
        doc.error(
            e.span().map(|s| doc.line(s.start)),
            "",
            e.message().to_string(),
        )
    })?;
    let mut top = Fields::new(&doc, root.get_ref(), "", 1, TOP)?;
    let (title, _) = top.required(&doc, "title")?;
    let (audience, _) = top.required(&doc, "audience")?;
    let duration_min = match top.number(&doc, "duration_min")? {
        Some((x, _)) if x.fract() == 0.0 && (1.0..=600.0).contains(&x) => x as u32,
        Some((x, line)) => {
            return Err(doc.error(
                Some(line),
                "duration_min",
                format!("{x} is not allowed: a whole number of minutes from 1 to 600"),
            ));
        }
        None => return Err(doc.error(Some(1), "duration_min", "missing (minutes)")),
    };
    let goals: Vec<String> = top
        .strings(&doc, "goals")?
        .into_iter()
        .map(|(s, _)| s)
        .collect();
    if goals.is_empty() {
        return Err(doc.error(Some(1), "goals", "missing: at least one learning goal"));
    }
    let (teacher_notes, _) = top.required(&doc, "teacher_notes")?;
    let steps = match top.take("step") {
        Some((DeValue::Array(items), _)) if !items.is_empty() => items
            .iter()
            .enumerate()
            .map(|(i, item)| match item.get_ref() {
                DeValue::Table(t) => step(&doc, t, i + 1, doc.line(item.span().start)),
                _ => Err(doc.error(
                    Some(doc.line(item.span().start)),
                    &format!("step[{}]", i + 1),
                    "expected a [[step]] table",
                )),
            })
            .collect::<Result<Vec<_>, _>>()?,
        Some((_, line)) => {
            return Err(doc.error(Some(line), "step", "expected [[step]] tables"));
        }
        None => return Err(doc.error(None, "step", "missing: at least one [[step]]")),
    };
    top.finish(&doc, TOP)?;
    Ok(Lesson {
        name: name.to_string(),
        source: source.to_string(),
        title,
        audience,
        duration_min,
        goals,
        teacher_notes,
        steps,
    })
}

/// `key=value` overrides, each checked against the scene's settings.
fn assignments(
    doc: &Doc,
    field: &str,
    items: Vec<(String, usize)>,
) -> Result<Vec<(String, String, usize)>, LessonError> {
    items
        .into_iter()
        .map(|(s, line)| match s.split_once('=') {
            Some((k, v)) if !k.trim().is_empty() => {
                Ok((k.trim().to_string(), v.trim().to_string(), line))
            }
            _ => Err(doc.error(
                Some(line),
                field,
                format!("'{s}': expected KEY=VALUE, e.g. bar2.length=4"),
            )),
        })
        .collect()
}

fn expression(
    doc: &Doc,
    text: &str,
    line: usize,
    field: &str,
    vocabulary: &Vocabulary,
) -> Result<Expr, LessonError> {
    // A hostile expression can be megabytes long: the error quotes its start.
    let quoted = if text.chars().count() > 200 {
        format!(
            "{}... ({} characters)",
            text.chars().take(200).collect::<String>(),
            text.chars().count()
        )
    } else {
        text.to_string()
    };
    let expr =
        Expr::parse(text).map_err(|e| doc.error(Some(line), field, format!("'{quoted}': {e}")))?;
    expr.check(vocabulary)
        .map_err(|e| doc.error(Some(line), field, format!("'{quoted}': {e}")))?;
    Ok(expr)
}

fn step(doc: &Doc, table: &DeTable, index: usize, line: usize) -> Result<Step, LessonError> {
    let path = format!("step[{index}]");
    let mut f = Fields::new(doc, table, &path, line, STEP)?;
    let (title, _) = f.required(doc, "title")?;
    let (text, _) = f.required(doc, "text")?;
    let (scene_name, scene_line) = f.required(doc, "scene")?;
    let scene = LessonScene::from_name(&scene_name).ok_or_else(|| {
        doc.error(
            Some(scene_line),
            &f.field("scene"),
            format!(
                "unknown scene '{scene_name}': allowed {}",
                LessonScene::ALL.map(LessonScene::name).join("|")
            ),
        )
    })?;
    let vocabulary = Vocabulary::for_scene(scene);
    let preset = f.string(doc, "preset")?;
    let set = assignments(doc, &f.field("set"), f.strings(doc, "set")?)?;
    // Loading the scene here checks the preset and every override, with the override's line.
    let setup = SceneSetup::load(scene, preset.as_ref().map(|(p, _)| p.as_str()), &[])
        .map_err(|m| doc.error(preset.as_ref().map(|(_, l)| *l), &f.field("preset"), m))?;
    overrides_apply(doc, &f.field("set"), setup.clone(), &set)?;
    let show = panels(doc, f.strings(doc, "show")?, scene, &path)?;
    if show.is_empty() {
        return Err(doc.error(
            Some(line),
            &f.field("show"),
            "missing: the panels this step shows",
        ));
    }
    let models = models(doc, f.strings(doc, "models")?, scene, &path, line)?;
    let unlock = unlocked(doc, f.strings(doc, "unlock")?, scene, &path)?;
    let asserts = f
        .strings(doc, "asserts")?
        .into_iter()
        .map(|(s, l)| expression(doc, &s, l, &format!("{path}.asserts"), &vocabulary))
        .collect::<Result<Vec<_>, _>>()?;
    let prediction = match f.table(doc, "prediction")? {
        Some((t, l)) => Some(prediction(
            doc,
            t,
            &format!("{path}.prediction"),
            l,
            &vocabulary,
        )?),
        None => None,
    };
    let task = match f.table(doc, "task")? {
        Some((t, l)) => {
            let task = task(doc, t, &format!("{path}.task"), l, &vocabulary)?;
            overrides_apply(doc, &format!("{path}.task.solution"), setup, &task.solution)?;
            for (k, _, l) in &task.solution {
                if !unlock.contains(k) {
                    return Err(doc.error(
                        Some(*l),
                        &format!("{path}.task.solution"),
                        format!("'{k}' is locked in this step: a solution may change only unlocked settings"),
                    ));
                }
            }
            Some(task)
        }
        None => None,
    };
    f.finish(doc, STEP)?;
    let step = Step {
        title,
        text,
        line,
        scene,
        preset: preset.map(|(p, _)| p),
        set,
        show,
        models,
        unlock,
        prediction,
        task,
        asserts,
    };
    reads_only_its_models(doc, &step, &path)?;
    Ok(step)
}

/// The models a compare step solves: those it names (Sears among them: the scene's bars and
/// x-t diagrams are its run), or every model the scene compares.
fn models(
    doc: &Doc,
    items: Vec<(String, usize)>,
    scene: LessonScene,
    path: &str,
    line: usize,
) -> Result<Vec<ModelKind>, LessonError> {
    let field = format!("{path}.models");
    if scene != LessonScene::Compare {
        return match items.first() {
            Some((_, l)) => {
                Err(doc.error(Some(*l), &field, "only a compare step names its models"))
            }
            None => Ok(vec![]),
        };
    }
    if items.is_empty() {
        return Ok(COMPARE_MODELS.to_vec());
    }
    let allowed: Vec<&str> = COMPARE_MODELS.iter().map(|m| m.name()).collect();
    let mut out = Vec::new();
    for (name, l) in items {
        let Some(m) = COMPARE_MODELS.iter().find(|m| m.name() == name) else {
            return Err(doc.error(
                Some(l),
                &field,
                format!("unknown model '{name}': allowed {}", allowed.join("|")),
            ));
        };
        if out.contains(m) {
            return Err(doc.error(Some(l), &field, format!("'{name}' is named twice")));
        }
        out.push(*m);
    }
    if !out.contains(&ModelKind::Sears) {
        return Err(doc.error(
            Some(line),
            &field,
            "a compare step solves sears: its bars and x-t diagrams are Sears' run",
        ));
    }
    Ok(out)
}

/// Refuses an expression that reads a model the compare step leaves out.
fn reads_only_its_models(doc: &Doc, step: &Step, path: &str) -> Result<(), LessonError> {
    if step.scene != LessonScene::Compare {
        return Ok(());
    }
    let mut exprs: Vec<&Expr> = step.asserts.iter().collect();
    match &step.prediction {
        Some(Prediction::Choice { when, .. }) => exprs.extend(when),
        Some(Prediction::Number { answer, .. }) => exprs.push(answer),
        None => {}
    }
    if let Some(t) = &step.task {
        exprs.push(&t.goal);
    }
    for name in exprs.iter().flat_map(|e| e.names()) {
        let Some((prefix, _)) = name.split_once('.') else {
            continue;
        };
        let left_out = COMPARE_MODELS
            .iter()
            .find(|m| model_prefix(**m) == prefix && !step.models.contains(m));
        if let Some(m) = left_out {
            return Err(doc.error(
                Some(step.line),
                &format!("{path}.models"),
                format!(
                    "'{name}' reads {}, which the step's models leave out: name it in models",
                    m.name()
                ),
            ));
        }
    }
    Ok(())
}

/// The panels a step shows, each one its scene has.
fn panels(
    doc: &Doc,
    items: Vec<(String, usize)>,
    scene: LessonScene,
    path: &str,
) -> Result<Vec<Panel>, LessonError> {
    items
        .into_iter()
        .map(|(name, l)| match Panel::from_name(&name) {
            Some(p) if p.in_scene(scene) => Ok(p),
            _ => {
                let allowed: Vec<&str> = Panel::ALL
                    .iter()
                    .filter(|p| p.in_scene(scene))
                    .map(|p| p.name())
                    .collect();
                Err(doc.error(
                    Some(l),
                    &format!("{path}.show"),
                    format!(
                        "unknown panel '{name}' in the {} scene: allowed {}",
                        scene.name(),
                        allowed.join("|")
                    ),
                ))
            }
        })
        .collect()
}

/// The settings a step unlocks, each a key of its scene's table.
fn unlocked(
    doc: &Doc,
    items: Vec<(String, usize)>,
    scene: LessonScene,
    path: &str,
) -> Result<Vec<String>, LessonError> {
    let (table, command) = scene.settings();
    let keys = concrete_keys(table);
    items
        .into_iter()
        .map(|(k, l)| {
            if keys.contains(&k) {
                Ok(k)
            } else {
                Err(doc.error(
                    Some(l),
                    &format!("{path}.unlock"),
                    format!(
                        "'{k}' is not a setting of the {} scene (see `pounding {command} --list-keys`)",
                        scene.name()
                    ),
                ))
            }
        })
        .collect()
}

fn overrides_apply(
    doc: &Doc,
    field: &str,
    mut setup: SceneSetup,
    set: &[(String, String, usize)],
) -> Result<(), LessonError> {
    for (k, v, l) in set {
        setup
            .apply(k, v)
            .map_err(|e| doc.error(Some(*l), field, format!("{}: {}", e.field, e.message)))?;
    }
    Ok(())
}

fn prediction(
    doc: &Doc,
    table: &DeTable,
    path: &str,
    line: usize,
    vocabulary: &Vocabulary,
) -> Result<Prediction, LessonError> {
    let either: Vec<&str> = CHOICE.iter().chain(NUMBER).copied().collect();
    let mut f = Fields::new(doc, table, path, line, &either)?;
    let (kind, kind_line) = f.required(doc, "kind")?;
    let (question, _) = f.required(doc, "question")?;
    let (explanation, _) = f.required(doc, "explanation")?;
    let p = match kind.as_str() {
        "choice" => {
            let options: Vec<String> = f
                .strings(doc, "options")?
                .into_iter()
                .map(|(s, _)| s)
                .collect();
            if options.len() < 2 {
                return Err(doc.error(
                    Some(line),
                    &f.field("options"),
                    "give at least two options",
                ));
            }
            let answer = match f.number(doc, "answer")? {
                Some((x, _)) if x.fract() == 0.0 && x >= 1.0 && x <= options.len() as f64 => {
                    x as usize - 1
                }
                Some((x, l)) => {
                    return Err(doc.error(
                        Some(l),
                        &f.field("answer"),
                        format!(
                            "{x} is not allowed: the right option's number, 1 to {}",
                            options.len()
                        ),
                    ));
                }
                None => {
                    return Err(doc.error(
                        Some(line),
                        &f.field("answer"),
                        "missing: the right option's number, from 1",
                    ));
                }
            };
            let when = f.strings(doc, "when")?;
            if when.len() != options.len() {
                return Err(doc.error(
                    Some(when.first().map_or(line, |(_, l)| *l)),
                    &f.field("when"),
                    format!(
                        "give one condition per option: {} options, {} conditions",
                        options.len(),
                        when.len()
                    ),
                ));
            }
            let when = when
                .into_iter()
                .map(|(w, l)| expression(doc, &w, l, &f.field("when"), vocabulary))
                .collect::<Result<Vec<_>, _>>()?;
            f.finish(doc, CHOICE)?;
            Prediction::Choice {
                question,
                options,
                when,
                answer,
                explanation,
            }
        }
        "number" => {
            let (unit, _) = f.required(doc, "unit")?;
            let (a, al) = f.required(doc, "answer")?;
            let answer = expression(doc, &a, al, &f.field("answer"), vocabulary)?;
            let tolerance = match f.number(doc, "tolerance")? {
                Some((x, _)) if x > 0.0 && x < 1.0 => x,
                Some((x, l)) => {
                    return Err(doc.error(
                        Some(l),
                        &f.field("tolerance"),
                        format!(
                            "{x} is not allowed: a relative tolerance in (0, 1), e.g. 0.1 for 10%"
                        ),
                    ));
                }
                None => {
                    return Err(doc.error(
                        Some(line),
                        &f.field("tolerance"),
                        "missing: the relative tolerance, e.g. 0.1",
                    ));
                }
            };
            f.finish(doc, NUMBER)?;
            Prediction::Number {
                question,
                unit,
                answer,
                tolerance,
                explanation,
            }
        }
        other => {
            return Err(doc.error(
                Some(kind_line),
                &f.field("kind"),
                format!("unknown kind '{other}': allowed choice|number"),
            ));
        }
    };
    Ok(p)
}

fn task(
    doc: &Doc,
    table: &DeTable,
    path: &str,
    line: usize,
    vocabulary: &Vocabulary,
) -> Result<Task, LessonError> {
    let mut f = Fields::new(doc, table, path, line, TASK)?;
    let (g, gl) = f.required(doc, "goal")?;
    let goal = expression(doc, &g, gl, &f.field("goal"), vocabulary)?;
    let (text, _) = f.required(doc, "text")?;
    let (hint, _) = f.required(doc, "hint")?;
    let solution = assignments(doc, &f.field("solution"), f.strings(doc, "solution")?)?;
    f.finish(doc, TASK)?;
    Ok(Task {
        goal,
        text,
        hint,
        solution,
    })
}
