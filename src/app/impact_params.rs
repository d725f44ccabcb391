//! The parameter panel of the bar scenes: every input of the impact core, each row's label,
//! unit, tooltip, slider and accepted range from the settings table, its value read and written
//! through the settings registry.

use super::params::{Fields, Spec};
use crate::io::settings::{IMPACT, ImpactSetup, SettingValue};
use crate::model::bar::EndShape;
use crate::model::contact::LawKind;
use crate::model::impact::ModelKind;
use crate::model::material::MaterialPreset;
use crate::model::scenario::Reading;
use crate::model::settings::{BARS, Setting, impact as setting};
use eframe::egui;

/// A row's group as the lesson lock names it: `bar1.`, `contact.`.
fn group(s: &Setting, owner: usize) -> String {
    format!("{}.", s.group(owner))
}

fn bar_ui(ui: &mut egui::Ui, fields: &mut Fields, setup: &mut ImpactSetup, i: usize) -> bool {
    let bar = setup.bar_mut(i);
    let mut changed = fields.gate(ui, &setting::MATERIAL.key_of(i), |ui| {
        ui.horizontal(|ui| {
            ui.label(setting::MATERIAL.label)
                .on_hover_text("Sets E, nu and rho; the fields below can change them");
            let mut changed = false;
            for m in MaterialPreset::ALL {
                let selected = bar.material == m.material();
                if ui.selectable_label(selected, m.name()).clicked() && !selected {
                    bar.material = m.material();
                    changed = true;
                }
            }
            changed
        })
        .inner
    });
    let row = |fields: &mut Fields, ui: &mut egui::Ui, s: &Setting, setup: &mut ImpactSetup| {
        fields.setting(ui, IMPACT.entry(s), i, setup)
    };
    changed |= row(fields, ui, &setting::LENGTH, setup);
    // A bar given by its area shows the radius of the same area; moving it makes the bar round.
    let radius = IMPACT.entry(&setting::RADIUS);
    let radius_m = setup.bar(i).radius_m();
    changed |= fields.entry_row(ui, radius, i, setup, &Spec::of(radius.setting), radius_m);
    changed |= end_ui(ui, fields, setup, i);
    changed |= row(fields, ui, &setting::ADDED_MASS, setup);
    changed |= row(fields, ui, &setting::VELOCITY, setup);
    changed |= row(fields, ui, &setting::YOUNGS_MODULUS, setup);
    changed |= row(fields, ui, &setting::DENSITY, setup);
    changed
}

/// Flat or rounded, and a rounded end's radius.
fn end_ui(ui: &mut egui::Ui, fields: &mut Fields, setup: &mut ImpactSetup, i: usize) -> bool {
    let end = IMPACT.entry(&setting::END_RADIUS);
    let mut flat = setup.bar(i).end == EndShape::Flat;
    let radius_m = setup.bar(i).radius_m();
    let mut changed = fields.gate(ui, &end.setting.key_of(i), |ui| {
        let clicked = ui
            .checkbox(&mut flat, "flat end")
            .on_hover_text(
                "A flat end has no Hertz curvature; a rounded end's radius sets the Hertz stiffness",
            )
            .changed();
        if clicked {
            let value = match end.setting.word() {
                Some(w) if flat => SettingValue::Text(w.into()),
                _ => SettingValue::Number(radius_m),
            };
            end.set_value(setup, i, &value).expect("a flat end or a number");
        }
        clicked
    });
    if !flat {
        changed |= fields.setting(ui, end, i, setup);
    }
    changed
}

/// The contact's law, stiffness, zone, reading and restitution.
fn contact_ui(ui: &mut egui::Ui, fields: &mut Fields, setup: &mut ImpactSetup) {
    let law = &setting::CONTACT_LAW;
    fields.gate(ui, law.key, |ui| {
        ui.horizontal(|ui| {
            ui.label(law.label).on_hover_text(law.help);
            for l in LawKind::ALL {
                ui.selectable_value(&mut setup.scenario.contact.law, l, l.name());
            }
        });
        false
    });
    let stiffness = IMPACT.entry(&setting::CONTACT_STIFFNESS);
    let mut auto = setup.scenario.contact.stiffness.is_none();
    fields.gate(ui, stiffness.setting.key, |ui| {
        ui.checkbox(&mut auto, "automatic stiffness").on_hover_text(
            "Hertz from the ends and materials; linear from the paper's E A / (L / n)",
        );
        false
    });
    if auto {
        setup.scenario.contact.stiffness = None;
    } else {
        let sc = &setup.scenario;
        let k = sc
            .contact
            .stiffness
            .unwrap_or_else(|| sc.contact_law().map(|l| l.stiffness).unwrap_or(1e10));
        let unit = if sc.contact.law == LawKind::Hertz {
            "N/m^1.5"
        } else {
            "N/m"
        };
        let spec = Spec {
            unit,
            ..Spec::of(stiffness.setting)
        };
        // Unticking "automatic" keeps the stiffness shown, moved or not.
        if !fields.entry_row(ui, stiffness, 0, setup, &spec, k) {
            setup.scenario.contact.stiffness = Some(k);
        }
    }
    fields.setting(ui, IMPACT.entry(&setting::ZONE_SCALE), 0, setup);
    let reading = &setting::SEARS_READING;
    fields.gate(ui, reading.key, |ui| {
        ui.horizontal(|ui| {
            ui.label(reading.label).on_hover_text(reading.help);
            for r in Reading::ALL {
                ui.selectable_value(&mut setup.scenario.reading, r, r.name());
            }
        });
        false
    });
    fields.setting(ui, IMPACT.entry(&setting::RESTITUTION), 0, setup);
}

/// The model (Bar impact only), the step, the span and the FE mesh.
fn solver_ui(ui: &mut egui::Ui, fields: &mut Fields, setup: &mut ImpactSetup, show_model: bool) {
    if show_model {
        fields.gate(ui, setting::MODEL.key, |ui| {
            ui.horizontal_wrapped(|ui| {
                ui.label(setting::MODEL.label);
                for m in ModelKind::ALL {
                    ui.selectable_value(&mut setup.model, m, m.name());
                }
            });
            false
        });
    }
    fields.setting(ui, IMPACT.entry(&setting::DT), 0, setup);
    fields.setting(ui, IMPACT.entry(&setting::WINDOW), 0, setup);
    let segments = IMPACT.entry(&setting::FE_SEGMENTS);
    // The table's span reaches a million segments; the slider keeps to what solves in a frame
    // or two.
    let spec = Spec {
        min: 2.0,
        max: 2000.0,
        log: true,
        ..Spec::of(segments.setting)
    };
    let n = setup.scenario.fe.segments as f64;
    fields.entry_row(ui, segments, 0, setup, &spec, n);
}

/// The whole panel; returns whether anything changed.
pub fn ui(
    ui: &mut egui::Ui,
    fields: &mut Fields,
    setup: &mut ImpactSetup,
    show_model: bool,
) -> bool {
    let before = *setup;
    for (i, title) in ["Bar 1 (left, moving right)", "Bar 2 (right)"]
        .into_iter()
        .enumerate()
    {
        if fields.shows_group(&format!("{}.", BARS[i])) {
            egui::CollapsingHeader::new(title)
                .default_open(true)
                .show(ui, |ui| bar_ui(ui, fields, setup, i));
        }
    }
    let contact_open = fields.shows_group(&group(&setting::CONTACT_LAW, 0))
        || fields.shows_group(&group(&setting::SEARS_READING, 0));
    if contact_open {
        egui::CollapsingHeader::new("Contact")
            .default_open(true)
            .show(ui, |ui| contact_ui(ui, fields, setup));
    }
    let solver_open = fields.shows_group(&group(&setting::DT, 0))
        || fields.shows_group(&group(&setting::FE_SEGMENTS, 0))
        || (show_model && fields.shows_group(setting::MODEL.key));
    if solver_open {
        egui::CollapsingHeader::new("Solver")
            .default_open(fields.lock.is_some())
            .show(ui, |ui| solver_ui(ui, fields, setup, show_model));
    }
    *setup != before
}
