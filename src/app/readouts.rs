//! Named values beside a result: two pairs a row in a grid, or, in lecture mode, each pair one
//! label that wraps with the panel's width (a grid's rows run off a projector's narrow screen).

use eframe::egui::{self, Color32};

/// One named value.
pub struct Readout {
    name: String,
    value: String,
    hover: Option<&'static str>,
    /// A value that says the run is wrong (no name): drawn red on a row of its own.
    alarm: bool,
}

impl Readout {
    pub fn new(name: &str, value: impl Into<String>) -> Self {
        Readout {
            name: name.to_string(),
            value: value.into(),
            hover: None,
            alarm: false,
        }
    }

    pub fn alarm(text: &str) -> Self {
        Readout {
            alarm: true,
            ..Readout::new("", text)
        }
    }

    pub fn hover(self, text: &'static str) -> Self {
        Readout {
            hover: Some(text),
            ..self
        }
    }
}

const ALARM: Color32 = Color32::from_rgb(220, 60, 50);

pub fn show(ui: &mut egui::Ui, id: &str, rows: &[Readout]) {
    if super::lecture::on(ui.ctx()) {
        ui.horizontal_wrapped(|ui| {
            ui.spacing_mut().item_spacing.x = 24.0;
            for r in rows {
                if r.alarm {
                    ui.colored_label(ALARM, &r.value);
                    continue;
                }
                let label = ui.label(format!("{}: {}", r.name, r.value));
                if let Some(h) = r.hover {
                    label.on_hover_text(h);
                }
            }
        });
        return;
    }
    egui::Grid::new(id)
        .num_columns(4)
        .spacing([18.0, 4.0])
        .show(ui, |ui| {
            let mut in_row = 0;
            for r in rows {
                if r.alarm {
                    if in_row > 0 {
                        ui.end_row();
                    }
                    ui.colored_label(ALARM, &r.value);
                    ui.end_row();
                    in_row = 0;
                    continue;
                }
                let name = ui.label(&r.name);
                if let Some(h) = r.hover {
                    name.on_hover_text(h);
                }
                ui.label(&r.value);
                in_row += 1;
                if in_row == 2 {
                    ui.end_row();
                    in_row = 0;
                }
            }
        });
}

const WARN: Color32 = Color32::from_rgb(220, 140, 40);

/// A warning the model gives about a run, under `whose` name ("warning", a model's). On a
/// projector it keeps its first clause (what went wrong) and holds the rest (the numbers, what
/// to do) for its tooltip.
pub fn warning(ui: &mut egui::Ui, whose: &str, text: &str) {
    if !super::lecture::on(ui.ctx()) {
        ui.colored_label(WARN, format!("{whose}: {text}"));
        return;
    }
    let head = text.split([':', ';']).next().unwrap_or(text);
    ui.colored_label(WARN, format!("{whose}: {head}"))
        .on_hover_text(text);
}
