//! What the Parameter study's two sweeps (an impact setting, a building setting) share: the
//! range a picked key starts from, the range's fields, Run and Cancel, errors named by field,
//! and the finished sweep's status line.

use super::background::Background;
use crate::model::settings::{Kind, Setting, find};
use crate::study::sweep::{Part, SweepError};
use eframe::egui;
use std::time::Duration;

/// The range a sweep of `key` starts from when it is picked: (from, to, geometric), the span of
/// the key's slider in its settings table (the one place its ranges are written).
pub fn default_range(table: &'static [Setting], key: &str) -> (f64, f64, bool) {
    match find(table, key).map(|s| s.kind) {
        Some(Kind::Number { slider, log, .. } | Kind::List { slider, log, .. }) => {
            (slider.0, slider.1, log)
        }
        Some(Kind::Count { min, max }) => {
            let (lo, hi) = ((min.max(1)) as f64, max.min(1_000_000) as f64);
            (lo, hi, hi / lo > 100.0)
        }
        _ => (0.5, 2.0, false),
    }
}

/// A sweep's error, phrased with the panel's field at fault.
pub fn fielded(e: SweepError) -> String {
    let field = match e.part() {
        Part::Param => "swept setting: ",
        Part::Count => "points: ",
        Part::Range => "from/to: ",
        Part::Spacing => "geometric spacing: ",
        Part::Value => "",
    };
    format!("{field}{e}")
}

/// The typed ends of the range, read; a refusal names the field.
pub fn ends(from: &str, to: &str) -> Result<(f64, f64), String> {
    let number = |name: &str, text: &str| {
        text.trim()
            .parse::<f64>()
            .map_err(|_| format!("{name}: '{}' is not a number", text.trim()))
    };
    Ok((number("from", from)?, number("to", to)?))
}

/// The range's fields: from, to, the number of points and the spacing.
pub fn range_ui(
    ui: &mut egui::Ui,
    from: &mut String,
    to: &mut String,
    count: &mut usize,
    log: &mut bool,
) {
    for (name, text) in [("from", from), ("to", to)] {
        ui.horizontal(|ui| {
            let label = ui.label(name).id;
            ui.add(egui::TextEdit::singleline(text).desired_width(120.0))
                .labelled_by(label)
                .on_hover_text("typed values are checked when the study runs");
        });
    }
    ui.horizontal(|ui| {
        let label = ui.label("points").id;
        ui.add(egui::DragValue::new(count).range(2..=10_000))
            .labelled_by(label)
            .on_hover_text("values swept, ends included (2 to 10000)");
    });
    ui.checkbox(log, "geometric spacing")
        .on_hover_text("equal ratios between values (from and to > 0)");
}

/// What was pressed of Run and Cancel (Cancel only while `busy`).
pub struct Pressed {
    pub run: bool,
    pub cancel: bool,
}

/// Run and Cancel, then the running job's progress (if any) and the status line.
pub fn run_ui<T: Send + 'static>(
    ui: &mut egui::Ui,
    busy: bool,
    job: Option<&Background<T>>,
    status: Option<&(String, bool)>,
) -> Pressed {
    let mut pressed = Pressed {
        run: false,
        cancel: false,
    };
    ui.add_space(6.0);
    ui.horizontal(|ui| {
        pressed.run = ui
            .button("Run")
            .on_hover_text("solve every point on every core")
            .clicked();
        pressed.cancel = ui
            .add_enabled(busy, egui::Button::new("Cancel"))
            .on_hover_text("stop: finished points are dropped")
            .clicked();
    });
    if let Some(job) = job {
        job.progress_ui(ui);
    }
    super::params::status_ui(ui, status);
    pressed
}

/// The status line of a finished sweep of `points` solves, `failed` of them without a result.
pub fn finished_status(
    points: usize,
    failed: usize,
    elapsed: Duration,
    failed_hint: &str,
) -> String {
    format!(
        "{points} solves in {} on {} threads{}",
        super::ms(elapsed.as_secs_f64(), 1),
        rayon::current_num_threads(),
        if failed > 0 {
            format!("; {failed} points without a result ({failed_hint})")
        } else {
            String::new()
        }
    )
}

/// The swept setting's chooser (`keys`, from `table`); picking another resets the range to
/// its slider's span.
#[allow(clippy::too_many_arguments)]
pub fn param_ui(
    ui: &mut egui::Ui,
    id: &str,
    table: &'static [Setting],
    keys: Vec<String>,
    param: &mut String,
    from: &mut String,
    to: &mut String,
    log: &mut bool,
) {
    let label = ui.label("swept setting").id;
    let before = param.clone();
    egui::ComboBox::from_id_salt(id)
        .selected_text(param.as_str())
        .height(400.0)
        .show_ui(ui, |ui| {
            for k in keys {
                ui.selectable_value(param, k.clone(), k);
            }
        })
        .response
        .labelled_by(label);
    if *param != before {
        let (a, b, geometric) = default_range(table, param);
        (*from, *to, *log) = (
            super::params::format_value(a),
            super::params::format_value(b),
            geometric,
        );
    }
}

/// The points without a result (the first 50 listed): `param = value: why`.
pub fn failed_ui(ui: &mut egui::Ui, param: &str, failed: &[(f64, String)]) {
    if failed.is_empty() {
        return;
    }
    ui.collapsing(format!("{} points without a result", failed.len()), |ui| {
        for (value, why) in failed.iter().take(50) {
            ui.label(format!(
                "{param} = {}: {why}",
                super::params::format_value(*value)
            ));
        }
    });
}
