//! The parameter panel of the bar scenes: every input of the impact core, with units, log
//! sliders where a range spans decades, and a tooltip saying what each does physically.

use super::params::{Fields, Spec};
use crate::io::settings::ImpactSetup;
use crate::model::bar::{Bar, EndShape, Section};
use crate::model::contact::LawKind;
use crate::model::impact::ModelKind;
use crate::model::material::MaterialPreset;
use crate::model::scenario::Reading;
use eframe::egui;

fn bar_ui(ui: &mut egui::Ui, fields: &mut Fields, id: &str, bar: &mut Bar) -> bool {
    let mut changed = false;
    ui.horizontal(|ui| {
        ui.label("material")
            .on_hover_text("Sets E, nu and rho; the fields below can change them");
        for m in MaterialPreset::ALL {
            let selected = bar.material == m.material();
            if ui.selectable_label(selected, m.name()).clicked() && !selected {
                bar.material = m.material();
                changed = true;
            }
        }
    });
    let mut row = |ui: &mut egui::Ui, key: &str, spec: Spec, v: &mut f64| {
        fields.row(ui, &format!("{id}.{key}"), &spec, v)
    };
    changed |= row(
        ui,
        "length",
        Spec {
            label: "length",
            unit: "m",
            tooltip: "Bar length L: the round trip 2L/c sets when reflections return to the contact",
            min: 0.005,
            max: 100.0,
            log: true,
        },
        &mut bar.length_m,
    );
    let mut radius = bar.radius_m();
    if row(
        ui,
        "radius",
        Spec {
            label: "radius",
            unit: "m",
            tooltip: "Rod radius: sets the area (mass, impedance Z = A sqrt(E rho)) and Sears' zone length d",
            min: 0.002,
            max: 2.0,
            log: true,
        },
        &mut radius,
    ) {
        bar.section = Section::Circular { radius_m: radius };
        changed = true;
    }
    let mut flat = bar.end == EndShape::Flat;
    ui.horizontal(|ui| {
        if ui.checkbox(&mut flat, "flat end").on_hover_text("A flat end has no Hertz curvature; a rounded end's radius sets the Hertz stiffness").changed() {
            bar.end = if flat { EndShape::Flat } else { EndShape::Rounded { radius_m: bar.radius_m() } };
            changed = true;
        }
    });
    if let EndShape::Rounded { radius_m } = bar.end {
        let mut r = radius_m;
        if row(
            ui,
            "end_radius",
            Spec {
                label: "end radius",
                unit: "m",
                tooltip: "Radius of the rounded end: a larger dome is a stiffer Hertz contact",
                min: 0.002,
                max: 10.0,
                log: true,
            },
            &mut r,
        ) {
            bar.end = EndShape::Rounded { radius_m: r };
            changed = true;
        }
    }
    changed |= row(
        ui,
        "added_mass",
        Spec {
            label: "added mass",
            unit: "kg",
            tooltip: "Mass spread over the bar: slows the waves and shifts the impact towards lumped behaviour",
            min: 0.0,
            max: 1e5,
            log: true,
        },
        &mut bar.added_mass_kg,
    );
    changed |= row(
        ui,
        "velocity",
        Spec {
            label: "velocity",
            unit: "m/s",
            tooltip: "Rigid-body velocity before impact, positive to the right",
            min: -100.0,
            max: 100.0,
            log: false,
        },
        &mut bar.velocity_m_s,
    );
    let mut e = bar.material.youngs_modulus_pa;
    if row(
        ui,
        "youngs",
        Spec {
            label: "E",
            unit: "Pa",
            tooltip: "Young's modulus: stiffer bars carry faster waves and a stiffer Hertz contact",
            min: 1e8,
            max: 1e12,
            log: true,
        },
        &mut e,
    ) {
        bar.material.youngs_modulus_pa = e;
        changed = true;
    }
    let mut rho = bar.material.density_kg_m3;
    if row(
        ui,
        "density",
        Spec {
            label: "density",
            unit: "kg/m^3",
            tooltip: "Mass density: with E it sets the wave speed c = sqrt(E / rho)",
            min: 100.0,
            max: 30000.0,
            log: true,
        },
        &mut rho,
    ) {
        bar.material.density_kg_m3 = rho;
        changed = true;
    }
    changed
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
    egui::CollapsingHeader::new("Bar 1 (left, moving right)")
        .default_open(true)
        .show(ui, |ui| bar_ui(ui, fields, "bar1", &mut sc.bar1));
    egui::CollapsingHeader::new("Bar 2 (right)")
        .default_open(true)
        .show(ui, |ui| bar_ui(ui, fields, "bar2", &mut sc.bar2));
    egui::CollapsingHeader::new("Contact").default_open(true).show(ui, |ui| {
        ui.horizontal(|ui| {
            ui.label("law").on_hover_text("Hertz F = k delta^1.5 for rounded ends, linear F = kL delta for flat ones");
            ui.selectable_value(&mut sc.contact.law, LawKind::Hertz, "hertz");
            ui.selectable_value(&mut sc.contact.law, LawKind::Linear, "linear");
        });
        let mut auto = sc.contact.stiffness.is_none();
        ui.checkbox(&mut auto, "automatic stiffness").on_hover_text("Hertz from the ends and materials; linear from the paper's E A / (L / n)");
        if auto {
            sc.contact.stiffness = None;
        } else {
            let mut k = sc.contact.stiffness.unwrap_or_else(|| sc.contact_law().map(|l| l.stiffness).unwrap_or(1e10));
            let unit = if sc.contact.law == LawKind::Hertz { "N/m^1.5" } else { "N/m" };
            fields.row(ui, "contact.stiffness", &Spec { label: "stiffness", unit, tooltip: "Contact stiffness: stiffer contact means a shorter, more wave-like impact", min: 1e4, max: 1e16, log: true }, &mut k);
            sc.contact.stiffness = Some(k);
        }
        fields.row(ui, "contact.zone_scale", &Spec { label: "zone scale", unit: "x d", tooltip: "Multiplier on Sears' compression-zone length d (the paper varies it from 0.01 to 10)", min: 1e-4, max: 10.0, log: true }, &mut sc.contact.zone_scale);
        ui.horizontal(|ui| {
            ui.label("Sears reading").on_hover_text("paper: delayed planes (not energy-consistent); collocated: a massless zone spring; end: the law at the bar ends (d -> 0)");
            for r in Reading::ALL {
                ui.selectable_value(&mut sc.reading, r, r.name());
            }
        });
        fields.row(ui, "contact.restitution", &Spec { label: "restitution", unit: "", tooltip: "Target e of the Kelvin-Voigt and stereomechanics models", min: 0.0, max: 1.0, log: false }, &mut sc.contact.restitution);
    });
    egui::CollapsingHeader::new("Solver")
        .default_open(false)
        .show(ui, |ui| {
            if show_model {
                ui.horizontal_wrapped(|ui| {
                    ui.label("model");
                    for m in ModelKind::ALL {
                        ui.selectable_value(&mut setup.model, m, m.name());
                    }
                });
            }
            let sc = &mut setup.scenario;
            fields.row(
                ui,
                "solver.dt",
                &Spec {
                    label: "step",
                    unit: "s",
                    tooltip: "Time step; refined automatically where the contact is faster",
                    min: 1e-10,
                    max: 1e-4,
                    log: true,
                },
                &mut sc.solver.dt_s,
            );
            fields.row(
                ui,
                "solver.window",
                &Spec {
                    label: "window",
                    unit: "s",
                    tooltip: "Simulated span; 0 runs until the bars separate for good",
                    min: 0.0,
                    max: 0.1,
                    log: false,
                },
                &mut sc.solver.window_s,
            );
            let mut seg = sc.fe.segments as f64;
            if fields.row(
                ui,
                "fe.segments",
                &Spec {
                    label: "FE segments",
                    unit: "per bar",
                    tooltip: "Elements per bar of the finite-element model",
                    min: 2.0,
                    max: 2000.0,
                    log: true,
                },
                &mut seg,
            ) {
                sc.fe.segments = seg.round() as usize;
            }
        });
    *setup != before
}
