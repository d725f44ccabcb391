//! The ground-motion rows of a scene driven by a record (buildings, bridges): the record (a
//! built-in, a file or a synthetic one), its scale, length and, for a synthetic one, PGA and
//! seed; values through the scene's settings registry.

use super::params::{Fields, Spec};
use crate::io::motion_settings::WithMotion;
use crate::io::registry::Registry;
use crate::model::settings::{Range, building as setting};
use eframe::egui;

pub fn ui<S: WithMotion>(
    ui: &mut egui::Ui,
    fields: &mut Fields,
    setup: &mut S,
    registry: &Registry<S>,
    path: &mut String,
) {
    let m = setup.motion_mut();
    let built_in = crate::io::motion::BUILT_IN;
    let shown = match &m.file {
        None => "synthetic (Kanai-Tajimi)".to_string(),
        Some(f) => built_in
            .iter()
            .find(|b| b.name == f)
            .map_or_else(|| "file".to_string(), |b| b.title.to_string()),
    };
    let file_key = setting::MOTION_FILE.key;
    let file_shown = fields.shows(file_key);
    ui.horizontal(|ui| {
        if !file_shown {
            return;
        }
        let label = ui.label("record").id;
        fields.gate(ui, file_key, |ui| {
            egui::ComboBox::from_id_salt("motion-record")
                .selected_text(shown)
                .show_ui(ui, |ui| {
                    for b in built_in {
                        if ui
                            .selectable_label(m.file.as_deref() == Some(b.name), b.title)
                            .on_hover_text(b.about)
                            .clicked()
                        {
                            m.file = Some(b.name.to_string());
                        }
                    }
                    if ui
                        .selectable_label(m.file.is_none(), "synthetic (Kanai-Tajimi)")
                        .on_hover_text("A seeded synthetic record: PGA and seed below")
                        .clicked()
                    {
                        m.file = None;
                    }
                })
                .response
                .labelled_by(label);
            false
        });
    });
    ui.horizontal(|ui| {
        if !file_shown {
            return;
        }
        let label = ui.label("file").id;
        ui.add(
            egui::TextEdit::singleline(path)
                .hint_text(".AT2 or text file (or drop one here)")
                .desired_width(170.0),
        )
        .labelled_by(label);
        fields.gate(ui, file_key, |ui| {
            if ui.button("Load").clicked() && !path.trim().is_empty() {
                m.file = Some(path.trim().to_string());
            }
            false
        });
    });
    // A factor of 0 is refused by the entry: the record keeps its last factor.
    fields.setting(ui, registry.entry(&setting::MOTION_SCALE), 0, setup);
    if let Some((settle, _)) = registry.lookup(setting::MOTION_SETTLE.key) {
        fields.setting(ui, settle, 0, setup);
    }
    let duration = registry.entry(&setting::MOTION_DURATION);
    // 0 here means the whole record.
    let whole = Spec {
        tooltip: "Use only the first seconds of the record (0: all of it)",
        typed: Range::closed(0.0, 1e6),
        ..Spec::of(duration.setting)
    };
    let mut d = setup.motion().duration_s.unwrap_or(0.0);
    if fields.row(ui, &duration.setting.key_of(0), &whole, &mut d) {
        if d > 0.0 {
            let _ = duration.set_number(setup, 0, d);
        } else {
            setup.motion_mut().duration_s = None;
        }
    }
    if setup.motion().file.is_none() {
        fields.setting(ui, registry.entry(&setting::MOTION_PGA), 0, setup);
        let seed = registry.entry(&setting::MOTION_SEED);
        // The table's span is every seed there is; a slider over it could not pick one.
        let seeds = Spec {
            max: 1e6,
            ..Spec::of(seed.setting)
        };
        let value = setup.motion().synthetic.seed as f64;
        fields.entry_row(ui, seed, 0, setup, &seeds, value);
    }
}
