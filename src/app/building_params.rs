//! The Building pounding scene's parameter panel: each building's storeys (count and per-storey
//! mass, stiffness and height), damping and slabs, the contact, and the ground motion.

use super::params::{Fields, Spec};
use crate::io::building_settings::BuildingSetup;
use crate::model::building::{Building, ContactModel, DampingModel, SlabReading};
use crate::model::settings::{BUILDING_SETTINGS, Range};
use eframe::egui;

fn spec(key: &str) -> Spec<'static> {
    Spec::of(BUILDING_SETTINGS, key)
}

/// The most storeys the panel offers (the command line takes up to 100).
const MAX_STOREYS_SHOWN: usize = 20;

/// A per-storey list with one value for every storey made explicit, so one storey can change.
fn expand(list: &mut Vec<f64>, n: usize) {
    if list.len() != n {
        let v = list.first().copied().unwrap_or(1.0);
        *list = vec![v; n];
    }
}

/// A list that holds one value, or the same value N times, back to one value.
fn compact(list: &mut Vec<f64>) {
    if list.len() > 1 && list.iter().all(|x| *x == list[0]) {
        list.truncate(1);
    }
}

fn building_ui(ui: &mut egui::Ui, fields: &mut Fields, side: &str, b: &mut Building) {
    ui.horizontal(|ui| {
        let label = ui
            .label("storeys")
            .on_hover_text("Number of storeys: a floor (lumped mass) above each")
            .id;
        let mut n = b.storeys;
        if ui
            .add(egui::DragValue::new(&mut n).range(1..=MAX_STOREYS_SHOWN))
            .labelled_by(label)
            .changed()
        {
            for list in [
                &mut b.masses_kg,
                &mut b.stiffnesses_n_m,
                &mut b.heights_m,
                &mut b.slab_lengths_m,
                &mut b.slab_widths_m,
                &mut b.slab_thicknesses_m,
                &mut b.slab_youngs_pa,
            ] {
                if list.len() > 1 {
                    let last = *list.last().expect("not empty");
                    list.resize(n, last);
                }
            }
            b.storeys = n;
        }
        let periods = b.modes().periods_s();
        let shown: Vec<String> = periods.iter().take(3).map(|t| format!("{t:.3}")).collect();
        ui.label(format!(
            "periods {} s{}",
            shown.join(", "),
            if periods.len() > 3 { ", ..." } else { "" }
        ));
    });
    let n = b.storeys;
    for (key, list) in [
        ("masses", &mut b.masses_kg),
        ("stiffnesses", &mut b.stiffnesses_n_m),
        ("heights", &mut b.heights_m),
    ] {
        let each = spec(&format!("SIDE.{key}"));
        if list.len() == 1 || n == 1 {
            let single = match key {
                "masses" => "SIDE.mass",
                "stiffnesses" => "SIDE.stiffness",
                _ => "SIDE.height",
            };
            let mut v = list[0];
            if fields.row(ui, &format!("{side}.{key}"), &spec(single), &mut v) {
                list[0] = v;
            }
            if n > 1
                && ui
                    .small_button(format!("per storey ({key})"))
                    .on_hover_text("Give each storey its own value")
                    .clicked()
            {
                expand(list, n);
            }
        } else {
            egui::CollapsingHeader::new(format!("{key} per storey"))
                .id_salt(format!("{side}-{key}"))
                .default_open(true)
                .show(ui, |ui| {
                    for (j, v) in list.iter_mut().enumerate().rev() {
                        ui.horizontal(|ui| {
                            ui.label(format!("{:2}", j + 1));
                            fields.row(ui, &format!("{side}.{key}.{j}"), &each, v);
                        });
                    }
                });
            compact(list);
        }
    }
    fields.row(
        ui,
        &format!("{side}.damping_ratio"),
        &spec("SIDE.damping_ratio"),
        &mut b.damping_ratio,
    );
    if n > 1 {
        ui.horizontal(|ui| {
            ui.label("damping model").on_hover_text(
                "modal: the ratio in every mode; rayleigh: C = a M + b K with the ratio in modes 1 and 2",
            );
            ui.selectable_value(&mut b.damping, DampingModel::Modal, "modal");
            ui.selectable_value(
                &mut b.damping,
                DampingModel::Rayleigh { modes: [1, 2] },
                "rayleigh",
            );
        });
    }
}

pub fn ui(ui: &mut egui::Ui, fields: &mut Fields, setup: &mut BuildingSetup, path: &mut String) {
    let sc = &mut setup.scenario;
    for (side, b) in [("left", &mut sc.left), ("right", &mut sc.right)] {
        egui::CollapsingHeader::new(format!("{side} building"))
            .default_open(true)
            .show(ui, |ui| building_ui(ui, fields, side, b));
    }
    egui::CollapsingHeader::new("Contact")
        .default_open(true)
        .show(ui, |ui| contact_ui(ui, fields, setup));
    egui::CollapsingHeader::new("Ground motion")
        .default_open(true)
        .show(ui, |ui| motion_ui(ui, fields, setup, path));
}

fn contact_ui(ui: &mut egui::Ui, fields: &mut Fields, setup: &mut BuildingSetup) {
    let sc = &mut setup.scenario;
    ui.horizontal_wrapped(|ui| {
        for m in ContactModel::ALL {
            ui.selectable_value(&mut sc.contact, m, m.name());
        }
    });
    // The question is which gap avoids pounding: it lives between 0 and a few centimetres, so
    // the slider is logarithmic from 0.1 mm (typed values go up to the validated maximum).
    fields.row(ui, "gap", &spec("gap"), &mut sc.gap_m);
    let mut k = sc.element_stiffness();
    let stiffness = Spec {
        unit: if sc.contact.is_hertzian() {
            "N/m^1.5"
        } else {
            "N/m"
        },
        ..spec("contact.stiffness")
    };
    if fields.row(ui, "contact.stiffness", &stiffness, &mut k) {
        sc.stiffness = Some(k);
    }
    fields.row(
        ui,
        "contact.restitution",
        &spec("contact.restitution"),
        &mut sc.restitution,
    );
    ui.horizontal(|ui| {
        ui.label("Sears reading");
        ui.selectable_value(&mut sc.reading, SlabReading::Paper, "paper");
        ui.selectable_value(&mut sc.reading, SlabReading::End, "end");
    });
    fields.row(
        ui,
        "slab.damping",
        &spec("slab.damping"),
        &mut sc.slab_damping,
    );
    fields.row(
        ui,
        "impact.merge_gap_s",
        &spec("impact.merge_gap_s"),
        &mut sc.merge_gap_s,
    );
    fields.row(
        ui,
        "solver.tolerance",
        &spec("solver.tolerance"),
        &mut sc.tolerance,
    );
}

fn motion_ui(ui: &mut egui::Ui, fields: &mut Fields, setup: &mut BuildingSetup, path: &mut String) {
    let m = &mut setup.motion;
    let built_in = crate::io::motion::BUILT_IN;
    let shown = match &m.file {
        None => "synthetic (Kanai-Tajimi)".to_string(),
        Some(f) => built_in
            .iter()
            .find(|b| b.name == f)
            .map_or_else(|| "file".to_string(), |b| b.title.to_string()),
    };
    ui.horizontal(|ui| {
        let label = ui.label("record").id;
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
    });
    ui.horizontal(|ui| {
        let label = ui.label("file").id;
        ui.add(
            egui::TextEdit::singleline(path)
                .hint_text(".AT2 or text file (or drop one here)")
                .desired_width(170.0),
        )
        .labelled_by(label);
        if ui.button("Load").clicked() && !path.trim().is_empty() {
            m.file = Some(path.trim().to_string());
        }
    });
    let mut scale = m.scale;
    if fields.row(ui, "motion.scale", &spec("motion.scale"), &mut scale) && scale != 0.0 {
        m.scale = scale;
    }
    let mut duration = m.duration_s.unwrap_or(0.0);
    // 0 here means the whole record.
    let whole = Spec {
        tooltip: "Use only the first seconds of the record (0: all of it)",
        typed: Range::closed(0.0, 1e6),
        ..spec("motion.duration")
    };
    if fields.row(ui, "motion.duration", &whole, &mut duration) {
        m.duration_s = (duration > 0.0).then_some(duration);
    }
    if m.file.is_none() {
        fields.row(
            ui,
            "motion.pga",
            &spec("motion.pga"),
            &mut m.synthetic.pga_g,
        );
        let mut seed = m.synthetic.seed as f64;
        let seeds = Spec {
            max: 1e6,
            ..spec("motion.seed")
        };
        if fields.row(ui, "motion.seed", &seeds, &mut seed) {
            m.synthetic.seed = seed.round() as u64;
        }
    }
}
