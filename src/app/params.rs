//! Parameter rows: a slider that keeps the value in its valid range, and a field to type an
//! exact value; a typed value outside the range is refused and the allowed range is shown.

use eframe::egui;
use std::collections::HashMap;

/// What a row edits.
pub struct Spec<'a> {
    pub label: &'a str,
    pub unit: &'a str,
    pub tooltip: &'a str,
    pub min: f64,
    pub max: f64,
    pub log: bool,
}

/// Text being typed per field, and the last refusal.
#[derive(Default)]
pub struct Fields {
    text: HashMap<String, String>,
    refused: HashMap<String, String>,
}

impl Fields {
    /// Shows one row; returns whether the value changed.
    pub fn row(&mut self, ui: &mut egui::Ui, id: &str, spec: &Spec, value: &mut f64) -> bool {
        self.row_typed(ui, id, spec, (spec.min, spec.max), value)
    }

    /// A row whose typed values may go beyond the slider's range, to `typed`.
    pub fn row_typed(
        &mut self,
        ui: &mut egui::Ui,
        id: &str,
        spec: &Spec,
        typed: (f64, f64),
        value: &mut f64,
    ) -> bool {
        let mut changed = false;
        ui.horizontal(|ui| {
            // The label names the slider and the field for screen readers too.
            let label = ui.label(spec.label).on_hover_text(spec.tooltip).id;
            let mut v = value.clamp(spec.min, spec.max);
            let slider = egui::Slider::new(&mut v, spec.min..=spec.max)
                .logarithmic(spec.log)
                .show_value(false)
                .clamping(egui::SliderClamping::Always);
            if ui
                .add(slider)
                .labelled_by(label)
                .on_hover_text(spec.tooltip)
                .changed()
            {
                *value = v;
                changed = true;
                self.text.remove(id);
                self.refused.remove(id);
            }
            let shown = self
                .text
                .entry(id.to_string())
                .or_insert_with(|| format_value(*value));
            if !ui.memory(|m| m.has_focus(egui::Id::unique(("field", id))))
                && !changed
                && shown.parse::<f64>().ok() != Some(*value)
            {
                *shown = format_value(*value);
            }
            let response = ui
                .add(
                    egui::TextEdit::singleline(shown)
                        .id(egui::Id::unique(("field", id)))
                        .desired_width(80.0),
                )
                .labelled_by(label);
            let commit = response.lost_focus()
                || (response.has_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter)));
            if commit {
                match shown.trim().parse::<f64>() {
                    Ok(x) if x.is_finite() && x >= typed.0 && x <= typed.1 => {
                        if x != *value {
                            *value = x;
                            changed = true;
                        }
                        self.refused.remove(id);
                    }
                    _ => {
                        self.refused.insert(
                            id.to_string(),
                            format!(
                                "'{}' refused: allowed {} to {} {}",
                                shown.trim(),
                                format_value(typed.0),
                                format_value(typed.1),
                                spec.unit
                            ),
                        );
                        *shown = format_value(*value);
                    }
                }
            }
            ui.label(spec.unit);
            if let Some(msg) = self.refused.get(id) {
                ui.colored_label(egui::Color32::from_rgb(220, 60, 50), msg);
            }
        });
        changed
    }

    /// Forgets typed text (after a preset replaces the values).
    pub fn clear(&mut self) {
        self.text.clear();
        self.refused.clear();
    }
}

pub fn format_value(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else if (1e-3..1e4).contains(&x.abs()) {
        format!("{}", (x * 1e6).round() / 1e6)
    } else {
        format!("{x:.4e}")
    }
}

/// A scene's last outcome: a message, in red when it is an error.
pub fn status_ui(ui: &mut egui::Ui, status: Option<&(String, bool)>) {
    if let Some((message, is_error)) = status {
        let colour = if *is_error {
            egui::Color32::from_rgb(220, 60, 50)
        } else {
            ui.visuals().text_color()
        };
        ui.colored_label(colour, message);
    }
}
