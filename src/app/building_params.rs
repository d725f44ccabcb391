//! The Building pounding scene's parameter panel: each building's storeys (count and per-storey
//! mass, stiffness and height), damping and slabs, the contact, and the ground motion; rows
//! from the settings table, values through the settings registry.

use super::params::{Fields, Spec};
use crate::io::building_settings::{BUILDINGS, BuildingSetup};
use crate::model::building::{Building, ContactModel, DampingModel, SlabReading};
use crate::model::hysteresis::Hysteresis;
use crate::model::settings::{SIDES, Setting, building as setting};
use eframe::egui;

/// The row of a building setting of one side (0: left) or of the pair, through the registry.
fn row(
    ui: &mut egui::Ui,
    fields: &mut Fields,
    s: &Setting,
    owner: usize,
    setup: &mut BuildingSetup,
) {
    fields.setting(ui, BUILDINGS.entry(s), owner, setup);
}

/// The most storeys a building may have: the panel offers what the command line and a preset
/// take, since egui's field clamps the value it shows (a smaller limit would open a taller
/// preset cut short, its per-storey lists with it).
const MAX_STOREYS: usize = match setting::STOREYS.kind {
    crate::model::settings::Kind::Count { max, .. } => max as usize,
    _ => 1,
};

/// A per-storey list with one value for every storey made explicit, so one storey can change.
pub(super) fn expand(list: &mut Vec<f64>, n: usize) {
    if list.len() != n {
        let v = list.first().copied().unwrap_or(1.0);
        *list = vec![v; n];
    }
}

/// A list that holds one value, or the same value N times, back to one value.
pub(super) fn compact(list: &mut Vec<f64>) {
    if list.len() > 1 && list.iter().all(|x| *x == list[0]) {
        list.truncate(1);
    }
}

fn building_ui(ui: &mut egui::Ui, fields: &mut Fields, setup: &mut BuildingSetup, side: usize) {
    let b = setup.building_mut(side);
    let storeys_shown = fields.shows(&setting::STOREYS.key_of(side));
    ui.horizontal(|ui| {
        if !storeys_shown {
            return;
        }
        let label = ui
            .label(setting::STOREYS.label)
            .on_hover_text("Number of storeys: a floor (lumped mass) above each")
            .id;
        let mut n = b.storeys;
        // A lesson's lock greys every choice as it greys the sliders (lesson_gate holds it).
        let key = setting::STOREYS.key_of(side);
        if fields.gate(ui, &key, |ui| {
            ui.add(egui::DragValue::new(&mut n).range(1..=MAX_STOREYS))
                .labelled_by(label)
                .changed()
        }) {
            b.set_storeys(n);
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
    storey_lists_ui(ui, fields, b, side);
    row(ui, fields, &setting::DAMPING_RATIO, side, setup);
    yielding_ui(ui, fields, side, setup);
    let b = setup.building_mut(side);
    if n > 1 && fields.shows(&setting::DAMPING.key_of(side)) {
        ui.horizontal(|ui| {
            ui.label(setting::DAMPING.label).on_hover_text(
                "modal: the ratio in every mode; rayleigh: C = a M + b K with the ratio in modes 1 and 2",
            );
            fields.gate(ui, &setting::DAMPING.key_of(side), |ui| {
                for d in DampingModel::ALL {
                    ui.selectable_value(&mut b.damping, d, d.name());
                }
                false
            });
        });
    }
}

/// The storeys' law and, where they yield, the yield force (every storey alike; per storey from
/// the command line or a preset), the hardening and Bouc-Wen's exponent.
fn yielding_ui(ui: &mut egui::Ui, fields: &mut Fields, side: usize, setup: &mut BuildingSetup) {
    let b = setup.building_mut(side);
    let law_shown = fields.shows(&setting::HYSTERESIS.key_of(side));
    ui.horizontal(|ui| {
        if !law_shown {
            return;
        }
        ui.label(setting::HYSTERESIS.label)
            .on_hover_text(setting::HYSTERESIS.help);
        fields.gate(ui, &setting::HYSTERESIS.key_of(side), |ui| {
            for h in Hysteresis::ALL {
                ui.selectable_value(&mut b.hysteresis, h, h.name());
            }
            false
        });
    });
    if !b.yields() {
        return;
    }
    let bouc_wen = b.hysteresis == Hysteresis::BoucWen;
    let fy = b.yield_force(0);
    let spec = Spec::of(&setting::YIELD_FORCES);
    fields.entry_row(
        ui,
        BUILDINGS.entry(&setting::YIELD_FORCES),
        side,
        setup,
        &spec,
        fy,
    );
    row(ui, fields, &setting::HARDENING, side, setup);
    if bouc_wen {
        row(ui, fields, &setting::BOUC_WEN_N, side, setup);
    }
}

/// Masses, stiffnesses and heights: one row for every storey, or a row each.
fn storey_lists_ui(ui: &mut egui::Ui, fields: &mut Fields, b: &mut Building, side: usize) {
    let n = b.storeys;
    // Each list, and the one-value setting that stands for all its storeys.
    for (each, one, list) in [
        (&setting::MASSES, &setting::MASS, &mut b.masses_kg),
        (
            &setting::STIFFNESSES,
            &setting::STIFFNESS,
            &mut b.stiffnesses_n_m,
        ),
        (&setting::HEIGHTS, &setting::HEIGHT, &mut b.heights_m),
    ] {
        let key = each.key_of(side);
        let name = each.name();
        if list.len() == 1 || n == 1 {
            let mut v = list[0];
            if fields.row(ui, &key, &Spec::of(one), &mut v) {
                list[0] = v;
            }
            if n > 1
                && ui
                    .small_button(format!("per storey ({name})"))
                    .on_hover_text("Give each storey its own value")
                    .clicked()
            {
                expand(list, n);
            }
        } else {
            let spec = Spec::of(each);
            egui::CollapsingHeader::new(format!("{name} per storey"))
                .id_salt(format!("{}-{name}", SIDES[side]))
                .default_open(true)
                .show(ui, |ui| {
                    for (j, v) in list.iter_mut().enumerate().rev() {
                        ui.horizontal(|ui| {
                            ui.label(format!("{:2}", j + 1));
                            fields.row(ui, &format!("{key}.{j}"), &spec, v);
                        });
                    }
                });
            compact(list);
        }
    }
}

pub fn ui(ui: &mut egui::Ui, fields: &mut Fields, setup: &mut BuildingSetup, path: &mut String) {
    for (side, name) in SIDES.iter().enumerate() {
        if !fields.shows_group(&format!("{}.", crate::model::settings::SIDES[side])) {
            continue;
        }
        egui::CollapsingHeader::new(format!("{name} building"))
            .default_open(true)
            .show(ui, |ui| building_ui(ui, fields, setup, side));
    }
    if fields.shows_any(&[
        setting::CONTACT_MODEL.key,
        setting::GAP.key,
        setting::CONTACT_STIFFNESS.key,
        setting::RESTITUTION.key,
        setting::CONTACT_READING.key,
        setting::SLAB_DAMPING.key,
        setting::MERGE_GAP.key,
        setting::TOLERANCE.key,
    ]) {
        egui::CollapsingHeader::new("Contact")
            .default_open(true)
            .show(ui, |ui| contact_ui(ui, fields, setup));
    }
    if fields.shows_group("motion.") {
        egui::CollapsingHeader::new("Ground motion")
            .default_open(true)
            .show(ui, |ui| {
                super::motion_params::ui(ui, fields, setup, &BUILDINGS, path)
            });
    }
}

fn contact_ui(ui: &mut egui::Ui, fields: &mut Fields, setup: &mut BuildingSetup) {
    ui.horizontal_wrapped(|ui| {
        fields.gate(ui, setting::CONTACT_MODEL.key, |ui| {
            for m in ContactModel::ALL {
                ui.selectable_value(&mut setup.scenario.contact, m, m.name());
            }
            false
        });
    });
    // The question is which gap avoids pounding: it lives between 0 and a few centimetres, so
    // the slider is logarithmic from 0.1 mm (typed values go up to the validated maximum).
    row(ui, fields, &setting::GAP, 0, setup);
    let stiffness = BUILDINGS.entry(&setting::CONTACT_STIFFNESS);
    // Automatic until moved: the row shows the stiffness the run will use.
    let k = setup.scenario.element_stiffness();
    let spec = Spec {
        unit: if setup.scenario.contact.is_hertzian() {
            "N/m^1.5"
        } else {
            "N/m"
        },
        ..Spec::of(stiffness.setting)
    };
    fields.entry_row(ui, stiffness, 0, setup, &spec, k);
    row(ui, fields, &setting::RESTITUTION, 0, setup);
    ui.horizontal(|ui| {
        if !fields.shows(setting::CONTACT_READING.key) {
            return;
        }
        ui.label(setting::CONTACT_READING.label);
        fields.gate(ui, setting::CONTACT_READING.key, |ui| {
            for r in SlabReading::ALL {
                ui.selectable_value(&mut setup.scenario.reading, r, r.name());
            }
            false
        });
    });
    row(ui, fields, &setting::SLAB_DAMPING, 0, setup);
    row(ui, fields, &setting::MERGE_GAP, 0, setup);
    row(ui, fields, &setting::TOLERANCE, 0, setup);
}
