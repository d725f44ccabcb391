//! The parameter panel of the bar scenes: every input of the impact core, each row's label,
//! unit, tooltip, slider and accepted range from the settings table.

use super::params::{Fields, Spec};
use crate::io::settings::ImpactSetup;
use crate::model::bar::{Bar, EndShape, Section};
use crate::model::contact::LawKind;
use crate::model::impact::ModelKind;
use crate::model::material::MaterialPreset;
use crate::model::scenario::{ImpactScenario, Reading};
use crate::model::settings::IMPACT_SETTINGS;
use eframe::egui;

fn spec(key: &str) -> Spec<'static> {
    Spec::of(IMPACT_SETTINGS, key)
}

fn bar_ui(ui: &mut egui::Ui, fields: &mut Fields, id: &str, bar: &mut Bar) -> bool {
    let mut changed = fields.gate(ui, &format!("{id}.material"), |ui| {
        ui.horizontal(|ui| {
            ui.label("material")
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
    let row = |fields: &mut Fields, ui: &mut egui::Ui, key: &str, v: &mut f64| {
        fields.row(ui, &format!("{id}.{key}"), &spec(&format!("barN.{key}")), v)
    };
    changed |= row(fields, ui, "length", &mut bar.length_m);
    let mut radius = bar.radius_m();
    if row(fields, ui, "radius", &mut radius) {
        bar.section = Section::Circular { radius_m: radius };
        changed = true;
    }
    let mut flat = bar.end == EndShape::Flat;
    let radius_m = bar.radius_m();
    changed |= fields.gate(ui, &format!("{id}.end_radius"), |ui| {
        let clicked = ui
            .checkbox(&mut flat, "flat end")
            .on_hover_text(
                "A flat end has no Hertz curvature; a rounded end's radius sets the Hertz stiffness",
            )
            .changed();
        if clicked {
            bar.end = if flat {
                EndShape::Flat
            } else {
                EndShape::Rounded { radius_m }
            };
        }
        clicked
    });
    if let EndShape::Rounded { radius_m } = bar.end {
        let mut r = radius_m;
        if row(fields, ui, "end_radius", &mut r) {
            bar.end = EndShape::Rounded { radius_m: r };
            changed = true;
        }
    }
    changed |= row(fields, ui, "added_mass", &mut bar.added_mass_kg);
    changed |= row(fields, ui, "velocity", &mut bar.velocity_m_s);
    changed |= row(
        fields,
        ui,
        "youngs_modulus",
        &mut bar.material.youngs_modulus_pa,
    );
    changed |= row(fields, ui, "density", &mut bar.material.density_kg_m3);
    changed
}

/// The contact's law, stiffness, zone, reading and restitution.
fn contact_ui(ui: &mut egui::Ui, fields: &mut Fields, sc: &mut ImpactScenario) {
    fields.gate(ui, "contact.law", |ui| {
        ui.horizontal(|ui| {
            ui.label("law").on_hover_text(
                "Hertz F = k delta^1.5 for rounded ends, linear F = kL delta for flat ones",
            );
            ui.selectable_value(&mut sc.contact.law, LawKind::Hertz, "hertz");
            ui.selectable_value(&mut sc.contact.law, LawKind::Linear, "linear");
        });
        false
    });
    let mut auto = sc.contact.stiffness.is_none();
    fields.gate(ui, "contact.stiffness", |ui| {
        ui.checkbox(&mut auto, "automatic stiffness").on_hover_text(
            "Hertz from the ends and materials; linear from the paper's E A / (L / n)",
        );
        false
    });
    if auto {
        sc.contact.stiffness = None;
    } else {
        let mut k = sc
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
            ..spec("contact.stiffness")
        };
        fields.row(ui, "contact.stiffness", &spec, &mut k);
        sc.contact.stiffness = Some(k);
    }
    fields.row(
        ui,
        "contact.zone_scale",
        &spec("contact.zone_scale"),
        &mut sc.contact.zone_scale,
    );
    fields.gate(ui, "sears.reading", |ui| {
        ui.horizontal(|ui| {
            ui.label("Sears reading").on_hover_text(
                "paper: delayed planes (not energy-consistent); collocated: a massless zone spring; end: the law at the bar ends (d -> 0)",
            );
            for r in Reading::ALL {
                ui.selectable_value(&mut sc.reading, r, r.name());
            }
        });
        false
    });
    fields.row(
        ui,
        "contact.restitution",
        &spec("contact.restitution"),
        &mut sc.contact.restitution,
    );
}

/// The whole panel; returns whether anything changed.
pub fn ui(
    ui: &mut egui::Ui,
    fields: &mut Fields,
    setup: &mut ImpactSetup,
    show_model: bool,
) -> bool {
    let before = *setup;
    let sc = &mut setup.scenario;
    if fields.shows_group("bar1.") {
        egui::CollapsingHeader::new("Bar 1 (left, moving right)")
            .default_open(true)
            .show(ui, |ui| bar_ui(ui, fields, "bar1", &mut sc.bar1));
    }
    if fields.shows_group("bar2.") {
        egui::CollapsingHeader::new("Bar 2 (right)")
            .default_open(true)
            .show(ui, |ui| bar_ui(ui, fields, "bar2", &mut sc.bar2));
    }
    let contact_open = fields.shows_group("contact.") || fields.shows_group("sears.");
    if contact_open {
        egui::CollapsingHeader::new("Contact")
            .default_open(true)
            .show(ui, |ui| contact_ui(ui, fields, sc));
    }
    let solver_open = fields.shows_group("solver.")
        || fields.shows_group("fe.")
        || (show_model && fields.shows_group("model"));
    if solver_open {
        egui::CollapsingHeader::new("Solver")
            .default_open(fields.lock.is_some())
            .show(ui, |ui| {
                if show_model {
                    fields.gate(ui, "model", |ui| {
                        ui.horizontal_wrapped(|ui| {
                            ui.label("model");
                            for m in ModelKind::ALL {
                                ui.selectable_value(&mut setup.model, m, m.name());
                            }
                        });
                        false
                    });
                }
                let sc = &mut setup.scenario;
                fields.row(ui, "solver.dt", &spec("solver.dt"), &mut sc.solver.dt_s);
                fields.row(
                    ui,
                    "solver.window",
                    &spec("solver.window"),
                    &mut sc.solver.window_s,
                );
                let mut seg = sc.fe.segments as f64;
                let segments = Spec {
                    min: 2.0,
                    max: 2000.0,
                    log: true,
                    ..spec("fe.segments")
                };
                if fields.row(ui, "fe.segments", &segments, &mut seg) {
                    sc.fe.segments = seg.round() as usize;
                }
            });
    }
    *setup != before
}
