//! The Bridge pounding scene's parameter panel: the bridge (spans, seat, damping), the girders,
//! piers and bearings (one value for every span or one each), the joints' gaps, the contact, the
//! ground motion with its apparent velocity (a log slider that ends in "uniform"), and the
//! solver; rows from the settings table, values through the settings registry.

use super::building_params::{compact, expand};
use super::params::{Fields, Spec};
use crate::io::bridge_settings::{BRIDGE, BridgeSetup};
use crate::io::settings::SettingValue;
use crate::model::building::ContactModel;
use crate::model::settings::{Setting, bridge as setting};
use eframe::egui;

fn row(ui: &mut egui::Ui, fields: &mut Fields, s: &Setting, setup: &mut BridgeSetup) {
    fields.setting(ui, BRIDGE.entry(s), 0, setup);
}

/// A list of one value for every member, or one each (`n` of them, named `member` and counted
/// from `first`): one row, with a button to give each its own, or a row each.
fn list_ui(
    ui: &mut egui::Ui,
    fields: &mut Fields,
    s: &'static Setting,
    list: &mut Vec<f64>,
    (n, member, first): (usize, &str, usize),
) {
    let spec = Spec::of(s);
    if list.len() != n && list.len() > 1 {
        // A list made for another count of spans: one value for all until given each.
        list.truncate(1);
    }
    if !fields.shows(s.key) {
        return;
    }
    if list.len() == 1 || n == 1 {
        let mut v = list[0];
        if fields.row(ui, s.key, &spec, &mut v) {
            list[0] = v;
        }
        if n > 1
            && fields.gate(ui, s.key, |ui| {
                ui.small_button(format!("per {member} ({})", s.label))
                    .on_hover_text(format!("Give each {member} its own value"))
                    .clicked()
            })
        {
            expand(list, n);
        }
    } else {
        egui::CollapsingHeader::new(format!("{} per {member}", s.label))
            .id_salt(s.key)
            .default_open(true)
            .show(ui, |ui| {
                for (k, v) in list.iter_mut().enumerate() {
                    ui.horizontal(|ui| {
                        ui.label(format!("{:2}", k + first));
                        fields.row(ui, &format!("{}.{k}", s.key), &spec, v);
                    });
                }
            });
        compact(list);
    }
}

/// The settings of each group whose keys start the list (a lesson in lecture mode leaves out a
/// group with nothing unlocked).
const BRIDGE_KEYS: [&str; 3] = [
    setting::SPANS.key,
    setting::SEAT_LENGTH.key,
    setting::DAMPING_RATIO.key,
];
const MEMBER_KEYS: [&str; 9] = [
    setting::SPAN_LENGTH.key,
    setting::SPAN_AREA.key,
    setting::SPAN_YOUNGS_MODULUS.key,
    setting::SPAN_DENSITY.key,
    setting::SPAN_ADDED_MASS.key,
    setting::SPAN_VELOCITY.key,
    setting::PIER_MASS.key,
    setting::PIER_STIFFNESS.key,
    setting::BEARING_STIFFNESS.key,
];
const JOINT_KEYS: [&str; 6] = [
    setting::JOINT_GAPS.key,
    setting::CONTACT_MODEL.key,
    setting::CONTACT_STIFFNESS.key,
    setting::RESTITUTION.key,
    setting::GIRDER_DAMPING.key,
    setting::MERGE_GAP.key,
];
const SOLVER_KEYS: [&str; 3] = [
    setting::TOLERANCE.key,
    setting::MAX_STEP.key,
    setting::MAX_STEPS.key,
];

pub fn ui(ui: &mut egui::Ui, fields: &mut Fields, setup: &mut BridgeSetup, path: &mut String) {
    if fields.shows_any(&BRIDGE_KEYS) {
        egui::CollapsingHeader::new("Bridge")
            .default_open(true)
            .show(ui, |ui| {
                row(ui, fields, &setting::SPANS, setup);
                row(ui, fields, &setting::SEAT_LENGTH, setup);
                row(ui, fields, &setting::DAMPING_RATIO, setup);
            });
    }
    if fields.shows_any(&MEMBER_KEYS) {
        egui::CollapsingHeader::new("Girders, piers and bearings")
            .default_open(true)
            .show(ui, |ui| spans_ui(ui, fields, setup));
    }
    if fields.shows_any(&JOINT_KEYS) {
        egui::CollapsingHeader::new("Joints and contact")
            .default_open(true)
            .show(ui, |ui| contact_ui(ui, fields, setup));
    }
    if fields.shows(setting::APPARENT_VELOCITY.key) || fields.shows_group("motion.") {
        egui::CollapsingHeader::new("Ground motion")
            .default_open(true)
            .show(ui, |ui| {
                apparent_velocity_ui(ui, fields, setup);
                super::motion_params::ui(ui, fields, setup, &BRIDGE, path);
            });
    }
    if fields.shows_any(&SOLVER_KEYS) {
        egui::CollapsingHeader::new("Solver")
            .default_open(false)
            .show(ui, |ui| {
                row(ui, fields, &setting::TOLERANCE, setup);
                row(ui, fields, &setting::MAX_STEP, setup);
                row(ui, fields, &setting::MAX_STEPS, setup);
            });
    }
}

fn spans_ui(ui: &mut egui::Ui, fields: &mut Fields, setup: &mut BridgeSetup) {
    let sc = &mut setup.scenario;
    let n = sc.spans;
    for (s, list) in [
        (&setting::SPAN_LENGTH, &mut sc.span_length_m),
        (&setting::SPAN_AREA, &mut sc.span_area_m2),
        (&setting::SPAN_YOUNGS_MODULUS, &mut sc.span_youngs_pa),
        (&setting::SPAN_DENSITY, &mut sc.span_density_kg_m3),
        (&setting::SPAN_ADDED_MASS, &mut sc.span_added_mass_kg),
        (&setting::SPAN_VELOCITY, &mut sc.span_velocity_m_s),
        (&setting::PIER_MASS, &mut sc.pier_mass_kg),
        (&setting::PIER_STIFFNESS, &mut sc.pier_stiffness_n_m),
        (&setting::BEARING_STIFFNESS, &mut sc.bearing_stiffness_n_m),
    ] {
        list_ui(ui, fields, s, list, (n, "span", 1));
    }
    let periods: Vec<String> = (0..n)
        .map(|i| format!("{:.2}", sc.frame_modes(i).periods_s()[0]))
        .collect();
    // Beside the frames' own settings only: a lecture's step that opens a girder's length alone
    // leaves the piers' periods out.
    if fields.shows_any(&MEMBER_KEYS[6..]) {
        ui.label(format!("frames' first periods: {} s", periods.join(", ")));
    }
}

fn contact_ui(ui: &mut egui::Ui, fields: &mut Fields, setup: &mut BridgeSetup) {
    let n = setup.scenario.spans + 1;
    list_ui(
        ui,
        fields,
        &setting::JOINT_GAPS,
        &mut setup.scenario.joint_gaps_m,
        (n, "joint", 0),
    );
    // A lesson's lock greys the choice as it greys the sliders (lesson_gate holds it).
    ui.horizontal_wrapped(|ui| {
        fields.gate(ui, setting::CONTACT_MODEL.key, |ui| {
            for m in ContactModel::ALL {
                ui.selectable_value(&mut setup.scenario.contact, m, m.name());
            }
            false
        });
    });
    let stiffness = BRIDGE.entry(&setting::CONTACT_STIFFNESS);
    // Automatic until moved: the row shows the stiffness of the first girder joint (or the
    // abutment's, for one span), which the run works out per joint.
    let sc = &setup.scenario;
    let joints = sc.joints();
    let shown = joints.get(1).filter(|_| n > 2).or(joints.first());
    let k = sc
        .stiffness
        .or_else(|| shown.map(|j| sc.joint_stiffness(j)))
        .unwrap_or(1e9);
    let spec = Spec {
        unit: if sc.contact.is_hertzian() {
            "N/m^1.5"
        } else {
            "N/m"
        },
        ..Spec::of(stiffness.setting)
    };
    fields.entry_row(ui, stiffness, 0, setup, &spec, k);
    if setup.scenario.stiffness.is_some()
        && fields.gate(ui, stiffness.setting.key, |ui| {
            ui.small_button("auto stiffness")
                .on_hover_text("E A / (L / 10) of the girders at each joint, in series")
                .clicked()
        })
    {
        setup.scenario.stiffness = None;
    }
    row(ui, fields, &setting::RESTITUTION, setup);
    row(ui, fields, &setting::GIRDER_DAMPING, setup);
    row(ui, fields, &setting::MERGE_GAP, setup);
}

/// Where the slider's top notch, "uniform", begins (log10 of m/s).
const UNIFORM_FROM: f64 = 5.1;

/// The apparent velocity on a log slider from 50 m/s to 100 km/s that ends in "uniform", and a
/// field to type any value or `uniform`.
fn apparent_velocity_ui(ui: &mut egui::Ui, fields: &mut Fields, setup: &mut BridgeSetup) {
    let s = &setting::APPARENT_VELOCITY;
    fields.gate(ui, s.key, |ui| {
        let mut changed = false;
        ui.horizontal(|ui| {
            let label = ui.label(s.label).on_hover_text(s.help).id;
            let v = &mut setup.scenario.apparent_velocity_m_s;
            let mut pos = v.map_or(UNIFORM_FROM + 0.1, |v| v.log10().clamp(50f64.log10(), 5.0));
            let slider = egui::Slider::new(&mut pos, 50f64.log10()..=UNIFORM_FROM + 0.1)
                .show_value(false)
                .clamping(egui::SliderClamping::Always);
            if ui
                .add(slider)
                .labelled_by(label)
                .on_hover_text(s.help)
                .changed()
            {
                *v = (pos < UNIFORM_FROM).then(|| round3(10f64.powf(pos.min(5.0))));
                changed = true;
            }
            ui.label(v.map_or("uniform".to_string(), |v| format!("{v} m/s")));
        });
        ui.horizontal(|ui| typed_velocity_ui(ui, setup));
        changed
    });
}

/// The apparent velocity typed exactly: a number in its range, or `uniform`; anything else is
/// refused with the range, and the value stays.
fn typed_velocity_ui(ui: &mut egui::Ui, setup: &mut BridgeSetup) {
    let s = &setting::APPARENT_VELOCITY;
    let (id, refused) = (
        egui::Id::unique("apparent-velocity-field"),
        egui::Id::unique("apparent-velocity-refused"),
    );
    let current = setup
        .scenario
        .apparent_velocity_m_s
        .map_or("uniform".into(), |v| format!("{v}"));
    let mut text = ui.data_mut(|d| d.get_temp::<String>(id)).unwrap_or(current);
    let label = ui.label("exact").id;
    let response = ui
        .add(egui::TextEdit::singleline(&mut text).desired_width(80.0))
        .labelled_by(label)
        .on_hover_text("m/s, or uniform");
    if response.lost_focus() {
        let value = match text.trim().parse::<f64>() {
            Ok(x) => SettingValue::Number(x),
            Err(_) => SettingValue::Text(text.trim().to_string()),
        };
        let mut tried = setup.clone();
        match BRIDGE.apply(&mut tried, s.key, &value) {
            Ok(()) => {
                *setup = tried;
                ui.data_mut(|d| d.remove::<String>(refused));
            }
            Err(e) => {
                let msg = format!("'{}' refused: {e}", text.trim());
                ui.data_mut(|d| d.insert_temp(refused, msg));
            }
        }
        ui.data_mut(|d| d.remove::<String>(id));
    } else if response.has_focus() {
        ui.data_mut(|d| d.insert_temp(id, text));
    }
    ui.label("m/s");
    if let Some(msg) = ui.data_mut(|d| d.get_temp::<String>(refused)) {
        ui.colored_label(egui::Color32::from_rgb(220, 60, 50), msg);
    }
}

/// Three significant digits: a slider's value reads as a round number.
fn round3(v: f64) -> f64 {
    let p = 10f64.powf(v.log10().floor() - 2.0);
    (v / p).round() * p
}
