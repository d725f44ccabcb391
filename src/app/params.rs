//! Parameter rows: a slider over a setting's usual range, and a field to type an exact value
//! anywhere in its validated range; a typed value outside it is refused and the range shown.
//! Label, unit, help, both ranges and the scale come from the settings table (`model::settings`).

use super::visibility::Lock;
use crate::io::registry::Entry;
use crate::model::settings::{Kind, Range, Setting};
use eframe::egui;
use std::collections::HashMap;

/// What a row edits.
#[derive(Clone, Copy)]
pub struct Spec<'a> {
    pub label: &'a str,
    pub unit: &'a str,
    pub tooltip: &'a str,
    /// The slider's span.
    pub min: f64,
    pub max: f64,
    pub log: bool,
    /// What a typed value may be.
    pub typed: Range,
}

impl Spec<'static> {
    /// The row of a setting of the table.
    pub fn of(s: &'static Setting) -> Self {
        let (range, slider, log) = match s.kind {
            Kind::Number {
                range, slider, log, ..
            }
            | Kind::List { range, slider, log } => (range, slider, log),
            Kind::Count { min, max } => (
                Range::closed(min as f64, max as f64),
                (min as f64, max as f64),
                false,
            ),
            _ => panic!("{} is not a number", s.key),
        };
        Spec {
            label: s.label,
            unit: s.unit,
            tooltip: s.help,
            min: slider.0,
            max: slider.1,
            log,
            typed: range,
        }
    }
}

/// Text being typed per field, the last refusal, and which rows a lesson step leaves open.
#[derive(Default)]
pub struct Fields {
    text: HashMap<String, String>,
    refused: HashMap<String, String>,
    /// `None`: every row may change.
    pub lock: Option<Lock>,
}

impl Fields {
    /// Draws `add` (the widgets of setting `key`) enabled, greyed out when a lesson step locks
    /// the key, or not at all when locked rows are hidden; returns what `add` returned (false
    /// when it was not drawn or could not change).
    pub fn gate(
        &self,
        ui: &mut egui::Ui,
        key: &str,
        add: impl FnOnce(&mut egui::Ui) -> bool,
    ) -> bool {
        if !self.shows(key) {
            return false;
        }
        if self.lock.as_ref().is_none_or(|l| l.opens(key)) {
            add(ui)
        } else {
            ui.add_enabled_ui(false, add);
            false
        }
    }

    /// Whether the row of `key` is drawn at all (a locked row is left out in lecture mode).
    pub fn shows(&self, key: &str) -> bool {
        self.lock
            .as_ref()
            .is_none_or(|l| !l.hide_locked || l.opens(key))
    }

    /// Whether any of `keys` is drawn: a group with none of them is left out whole.
    pub fn shows_any(&self, keys: &[&str]) -> bool {
        keys.iter().any(|k| self.shows(k))
    }

    /// Whether a group of rows whose keys start with `prefix` has anything to show.
    pub fn shows_group(&self, prefix: &str) -> bool {
        self.lock
            .as_ref()
            .is_none_or(|l| !l.hide_locked || !l.closes_all(prefix))
    }

    /// Shows one row; returns whether the value changed.
    pub fn row(&mut self, ui: &mut egui::Ui, id: &str, spec: &Spec, value: &mut f64) -> bool {
        if !self.shows(id) {
            return false;
        }
        let open = self.lock.as_ref().is_none_or(|l| l.opens(id));
        let changed = ui
            .add_enabled_ui(open, |ui| self.row_widgets(ui, id, spec, value))
            .inner;
        changed && open
    }

    fn row_widgets(&mut self, ui: &mut egui::Ui, id: &str, spec: &Spec, value: &mut f64) -> bool {
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
                        // Wide enough for a value like 1.0000e11 in the panel's font.
                        .desired_width(6.4 * ui.style().text_styles[&egui::TextStyle::Body].size),
                )
                .labelled_by(label);
            let commit = response.lost_focus()
                || (response.has_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter)));
            if commit {
                match shown.trim().parse::<f64>() {
                    Ok(x) if spec.typed.contains(x) => {
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
                                "'{}' refused: allowed {} {}",
                                shown.trim(),
                                spec.typed,
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

    /// The row of a setting for `owner` (0: bar1 or left), read and written through its
    /// registry entry; returns whether the setup changed.
    pub fn setting<S>(
        &mut self,
        ui: &mut egui::Ui,
        entry: &Entry<S>,
        owner: usize,
        setup: &mut S,
    ) -> bool {
        let value = entry.number(setup, owner).unwrap_or_default();
        self.entry_row(ui, entry, owner, setup, &Spec::of(entry.setting), value)
    }

    /// The row of a setting showing `value` with `spec`, for a row that shows what the setup
    /// works out (a stiffness picked automatically) or spans other than the table's; a change
    /// is written through the entry, and a value the entry refuses leaves the setup as it was.
    pub fn entry_row<S>(
        &mut self,
        ui: &mut egui::Ui,
        entry: &Entry<S>,
        owner: usize,
        setup: &mut S,
        spec: &Spec,
        mut value: f64,
    ) -> bool {
        let id = entry.setting.key_of(owner);
        self.row(ui, &id, spec, &mut value) && entry.set_number(setup, owner, value).is_ok()
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::settings::building::GAP;

    /// The relative change one pixel of a `width`-pixel slider makes at `value`.
    fn one_pixel(spec: &Spec, value: f64, width: f64) -> f64 {
        if spec.log {
            (spec.max / spec.min).powf(1.0 / width) - 1.0
        } else {
            (spec.max - spec.min) / width / value
        }
    }

    #[test]
    fn the_gap_slider_resolves_millimetres_and_typing_reaches_the_validated_maximum() {
        // The question is which gap avoids pounding: the smallest drag from the paper's 1 mm
        // must not jump to centimetres (a linear 0-0.5 m slider moved it by 5 mm a pixel).
        let spec = Spec::of(&GAP);
        let step = one_pixel(&spec, 1e-3, 100.0);
        assert!(
            step < 0.1,
            "one pixel moves the gap by {:.0}%",
            step * 100.0
        );
        assert!(spec.min <= 1e-4 && spec.max >= 0.1);
        assert!(spec.typed.contains(0.0) && spec.typed.contains(1e3));
    }
}
