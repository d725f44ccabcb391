//! The Building pounding scene's parameter panel: each building's storeys (count and per-storey
//! mass, stiffness and height), damping and slabs, the contact, and the ground motion.

use super::params::{Fields, Spec};
use crate::io::building_settings::BuildingSetup;
use crate::model::building::{Building, ContactModel, DampingModel, SlabReading};
use eframe::egui;

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
    for (key, unit, tooltip, min, max, list) in [
        (
            "masses",
            "kg",
            "Floor mass: with the stiffnesses it sets the periods",
            1e2,
            1e8,
            &mut b.masses_kg,
        ),
        (
            "stiffnesses",
            "N/m",
            "Storey shear stiffness",
            1e4,
            1e11,
            &mut b.stiffnesses_n_m,
        ),
        (
            "heights",
            "m",
            "Storey height: the floors' elevations decide where the buildings meet",
            0.5,
            10.0,
            &mut b.heights_m,
        ),
    ] {
        let spec = |label: &'static str| Spec {
            label,
            unit,
            tooltip,
            min,
            max,
            log: key != "heights",
        };
        if list.len() == 1 || n == 1 {
            let label = match key {
                "masses" => "mass",
                "stiffnesses" => "stiffness",
                _ => "height",
            };
            let mut v = list[0];
            if fields.row(ui, &format!("{side}.{key}"), &spec(label), &mut v) {
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
                        let label: &'static str = match key {
                            "masses" => "floor mass",
                            "stiffnesses" => "storey stiffness",
                            _ => "storey height",
                        };
                        ui.horizontal(|ui| {
                            ui.label(format!("{:2}", j + 1));
                            fields.row(ui, &format!("{side}.{key}.{j}"), &spec(label), v);
                        });
                    }
                });
            compact(list);
        }
    }
    fields.row(
        ui,
        &format!("{side}.damping_ratio"),
        &Spec {
            label: "damping",
            unit: "",
            tooltip: "Viscous damping ratio (5% is the design-code value for concrete)",
            min: 0.0,
            max: 0.5,
            log: false,
        },
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
    let mut gap = sc.gap_m;
    if fields.row_typed(
        ui,
        "gap",
        &Spec {
            label: "gap",
            unit: "m",
            tooltip: "At-rest separation, the same at every level; the slider spans 0.1 mm to 0.5 m, type 0 for touching buildings",
            min: 1e-4,
            max: 0.5,
            log: true,
        },
        (0.0, 1e3),
        &mut gap,
    ) {
        sc.gap_m = gap;
    }
    let mut k = sc.element_stiffness();
    if fields.row(
        ui,
        "contact.stiffness",
        &Spec {
            label: "stiffness",
            unit: if sc.contact.is_hertzian() {
                "N/m^1.5"
            } else {
                "N/m"
            },
            tooltip: "Contact element stiffness (the paper: 15 GN/m)",
            min: 1e6,
            max: 1e14,
            log: true,
        },
        &mut k,
    ) {
        sc.stiffness = Some(k);
    }
    fields.row(
        ui,
        "contact.restitution",
        &Spec {
            label: "restitution",
            unit: "",
            tooltip: "Target restitution of kelvin, hertzdamp, jankowski and stereo",
            min: 0.05,
            max: 1.0,
            log: false,
        },
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
        &Spec {
            label: "slab damping",
            unit: "",
            tooltip: "Damping ratio of the slabs' axial waves; 0 lets them ring through the record",
            min: 0.0,
            max: 0.5,
            log: false,
        },
        &mut sc.slab_damping,
    );
    fields.row(
        ui,
        "impact.merge_gap_s",
        &Spec {
            label: "merge gap",
            unit: "s",
            tooltip: "Contacts at one level closer than this count as one impact",
            min: 0.0,
            max: 0.5,
            log: false,
        },
        &mut sc.merge_gap_s,
    );
    fields.row(
        ui,
        "solver.tolerance",
        &Spec {
            label: "tolerance",
            unit: "",
            tooltip: "Accuracy target of the contact steps (the motion between contacts is exact); the run's own error estimate is shown with the results",
            min: 1e-6,
            max: 1e-2,
            log: true,
        },
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
    if fields.row(
        ui,
        "motion.scale",
        &Spec {
            label: "scale",
            unit: "x",
            tooltip: "Factor on the record; negative flips it",
            min: -5.0,
            max: 5.0,
            log: false,
        },
        &mut scale,
    ) && scale != 0.0
    {
        m.scale = scale;
    }
    let mut duration = m.duration_s.unwrap_or(0.0);
    if fields.row(
        ui,
        "motion.duration",
        &Spec {
            label: "duration",
            unit: "s",
            tooltip: "Use only the first seconds of the record (0: all)",
            min: 0.0,
            max: 120.0,
            log: false,
        },
        &mut duration,
    ) {
        m.duration_s = (duration > 0.0).then_some(duration);
    }
    if m.file.is_none() {
        fields.row(
            ui,
            "motion.pga",
            &Spec {
                label: "PGA",
                unit: "g",
                tooltip: "Peak ground acceleration of the synthetic record",
                min: 0.01,
                max: 2.0,
                log: false,
            },
            &mut m.synthetic.pga_g,
        );
        let mut seed = m.synthetic.seed as f64;
        if fields.row(
            ui,
            "motion.seed",
            &Spec {
                label: "seed",
                unit: "",
                tooltip: "Another seed, another record of the same kind",
                min: 0.0,
                max: 1e6,
                log: false,
            },
            &mut seed,
        ) {
            m.synthetic.seed = seed.round() as u64;
        }
    }
}
