//! What a bridge step's expressions read: the run's fields as `bridge --json` names them, each
//! joint's and each girder's under its own prefix (`joint2.max_opening_m`, joints from 0 at the
//! left abutment as the window and `--json` count them; `girder1.round_trip_s`, girders from 1
//! as the plots name them), and the same bridge without contact beside it.

use super::context::Context;
use super::expr::Value;
use crate::io::bridge_settings::{BRIDGE, BridgeSetup};
use crate::model::bridge::BridgeResult;
use crate::model::settings::{BRIDGE_SETTINGS, Kind, concrete_keys};

/// The run's fields, and a few a lecturer needs (the largest force at the abutments and
/// between girders, the strongest impact's duration and closing speed).
pub const BRIDGE_FIELDS: &[(&str, &str)] = &[
    (
        "impact_count",
        "impacts at all joints (contacts grouped by merge_gap_s)",
    ),
    ("contact_count", "raw contact intervals"),
    ("max_pounding_force_n", "largest joint force [N]"),
    (
        "joint_count",
        "joints, both abutments' included (spans + 1)",
    ),
    ("joints_with_impacts", "joints where the run pounded"),
    (
        "max_force_at_abutments_n",
        "largest force at the two abutment joints [N]",
    ),
    (
        "max_force_between_girders_n",
        "largest force at a joint between two girders [N] (none for one span)",
    ),
    (
        "strongest_impact",
        "which impact (from 1) had the largest force",
    ),
    ("strongest_impact_joint", "the joint it happened at"),
    (
        "strongest_impact_duration_s",
        "how long the strongest impact lasted [s]",
    ),
    (
        "strongest_impact_approach_velocity_m_s",
        "the closing speed at the strongest impact's onset [m/s]",
    ),
    ("shortest_impact_duration_s", "the briefest impact [s]"),
    ("longest_impact_duration_s", "the longest impact [s]"),
    ("max_opening_m", "largest opening of any joint [m]"),
    ("max_opening_no_pounding_m", "the same without contact [m]"),
    (
        "unseated_count",
        "joints whose opening passed the seat length",
    ),
    ("unseated_count_no_pounding", "the same without contact"),
    (
        "first_unseating_s",
        "when a joint first opened past its seat [s] (none where none did)",
    ),
    ("length_m", "abutment to abutment [m]"),
    (
        "far_abutment_delay_s",
        "how late the motion reaches the far abutment [s] (0: uniform)",
    ),
    ("energy_input_j", "work of the ground on the frames [J]"),
    (
        "energy_differential_input_j",
        "work the supports' different motions do through the joints [J]",
    ),
    (
        "energy_frame_damping_j",
        "energy the frames' damping took [J]",
    ),
    (
        "energy_contact_j",
        "energy the contact elements dissipated [J]",
    ),
    (
        "energy_girder_waves_j",
        "energy carried into the girders' axial waves [J]",
    ),
    ("energy_balance_error", "the ledger's relative residual"),
];

/// Each joint's fields, read as `jointJ.NAME` (J from 0, the left abutment's).
pub const BRIDGE_JOINT_FIELDS: &[(&str, &str)] = &[
    (
        "abutment",
        "whether an abutment is one side of it (true/false)",
    ),
    ("gap_m", "its gap at rest [m]"),
    ("impacts", "impacts there"),
    ("max_force_n", "largest force there [N]"),
    ("max_opening_m", "largest opening [m]"),
    ("max_opening_no_pounding_m", "the same without contact [m]"),
    (
        "required_gap_m",
        "largest closing without contact: the gap that avoids pounding there [m]",
    ),
    (
        "seat_margin_m",
        "the seat length less the largest opening [m]",
    ),
    (
        "unseated",
        "whether it opened past the seat length (true/false)",
    ),
    ("unseated_s", "when it first did [s]"),
];

/// Each girder's (and its frame's) fields, read as `girderI.NAME` (I from 1, the leftmost).
pub const BRIDGE_GIRDER_FIELDS: &[(&str, &str)] = &[
    ("wave_speed_m_s", "axial wave speed sqrt(E/rho~) [m/s]"),
    ("round_trip_s", "a wave's round trip 2 L / c [s]"),
    ("impedance_n_s_m", "impedance A sqrt(E rho~) [N s/m]"),
    ("mass_kg", "its mass with the added mass [kg]"),
    ("period_s", "its frame's first period [s]"),
    (
        "delay_s",
        "how late the motion reaches its frame's ground point, under its midpoint [s]",
    ),
    ("peak_displacement_m", "peak |u| relative to its ground [m]"),
    (
        "peak_displacement_no_pounding_m",
        "the same without contact [m]",
    ),
];

/// The most spans a bridge may have: the joint and girder names run that far.
fn max_spans() -> usize {
    match crate::model::settings::bridge::SPANS.kind {
        Kind::Count { max, .. } => max as usize,
        _ => 1,
    }
}

/// Every name of the bridge scene: its settings, its fields, every joint's and girder's.
pub fn names() -> Vec<String> {
    let own = |list: &[(&str, &str)]| list.iter().map(|(n, _)| n.to_string()).collect::<Vec<_>>();
    let mut names = concrete_keys(BRIDGE_SETTINGS);
    names.extend(own(BRIDGE_FIELDS));
    let n = max_spans();
    for j in 0..=n {
        names.extend(
            BRIDGE_JOINT_FIELDS
                .iter()
                .map(|(f, _)| format!("joint{j}.{f}")),
        );
    }
    for i in 1..=n {
        names.extend(
            BRIDGE_GIRDER_FIELDS
                .iter()
                .map(|(f, _)| format!("girder{i}.{f}")),
        );
    }
    names
}

/// The largest of `xs`, `None` for none.
fn largest(xs: impl Iterator<Item = f64>) -> Option<f64> {
    xs.fold(None, |m: Option<f64>, x| Some(m.map_or(x, |m| m.max(x))))
}

impl Context {
    /// A bridge scene: the run's fields, and where `free` (the same bridge without contact) is
    /// given, the openings, peaks and gaps without pounding.
    pub fn bridge(setup: &BridgeSetup, r: &BridgeResult, free: Option<&BridgeResult>) -> Self {
        let mut ctx = Context::of_scene(super::LessonScene::Bridge);
        for key in concrete_keys(BRIDGE_SETTINGS) {
            if let Some(v) = BRIDGE
                .shown(setup, &key)
                .and_then(super::context::lesson_value)
            {
                ctx.set(key, v);
            }
        }
        ctx.bridge_run(setup, r);
        ctx.bridge_joints(setup, r, free);
        ctx.bridge_girders(setup, r, free);
        ctx
    }

    fn bridge_run(&mut self, setup: &BridgeSetup, r: &BridgeResult) {
        let sc = &setup.scenario;
        self.number("impact_count", r.impacts.len() as f64);
        self.number("contact_count", r.contacts.len() as f64);
        self.number("max_pounding_force_n", r.max_pounding_force_n);
        self.number("joint_count", r.joints.len() as f64);
        let pounded = (0..r.joints.len()).filter(|&j| r.impacts.iter().any(|e| e.level == j));
        self.number("joints_with_impacts", pounded.count() as f64);
        let at = |abutment: bool| {
            largest(
                r.joints
                    .iter()
                    .zip(&r.max_force_by_joint_n)
                    .filter(|(j, _)| (j.kind() == "abutment") == abutment)
                    .map(|(_, f)| *f),
            )
        };
        if let Some(f) = at(true) {
            self.number("max_force_at_abutments_n", f);
        }
        if let Some(f) = at(false) {
            self.number("max_force_between_girders_n", f);
        }
        if let Some((i, e)) = r
            .impacts
            .iter()
            .enumerate()
            .max_by(|a, b| a.1.peak_force_n.total_cmp(&b.1.peak_force_n))
        {
            self.number("strongest_impact", (i + 1) as f64);
            self.number("strongest_impact_joint", e.level as f64);
            self.number("strongest_impact_duration_s", e.duration_s());
            self.number(
                "strongest_impact_approach_velocity_m_s",
                e.approach_velocity_m_s,
            );
        }
        let durations = || r.impacts.iter().map(|e| e.duration_s());
        if let Some(d) = largest(durations().map(|d| -d)) {
            self.number("shortest_impact_duration_s", -d);
        }
        if let Some(d) = largest(durations()) {
            self.number("longest_impact_duration_s", d);
        }
        self.number("unseated_count", r.unseating.len() as f64);
        if let Some(u) = r.unseating.iter().map(|u| u.time_s).reduce(f64::min) {
            self.number("first_unseating_s", u);
        }
        self.number("length_m", sc.length_m());
        self.number("far_abutment_delay_s", sc.delay_s(sc.length_m()));
        let e = &r.energy;
        self.number("energy_input_j", e.input_j);
        self.number("energy_differential_input_j", e.differential_j);
        self.number("energy_frame_damping_j", e.damping_j);
        self.number("energy_contact_j", e.contact_j);
        self.number("energy_girder_waves_j", e.girder_waves_j);
        self.number("energy_balance_error", e.balance_error());
    }

    fn bridge_joints(
        &mut self,
        setup: &BridgeSetup,
        r: &BridgeResult,
        free: Option<&BridgeResult>,
    ) {
        let seat = setup.scenario.seat_length_m;
        if let Some(o) = largest(r.max_opening_m.iter().copied()) {
            self.number("max_opening_m", o);
        }
        for (j, joint) in r.joints.iter().enumerate() {
            let n = |f: &str| format!("joint{j}.{f}");
            self.set(n("abutment"), Value::Bool(joint.kind() == "abutment"));
            self.number(n("gap_m"), joint.gap_m);
            let count = r.impacts.iter().filter(|e| e.level == j).count();
            self.number(n("impacts"), count as f64);
            self.number(n("max_force_n"), r.max_force_by_joint_n[j]);
            self.number(n("max_opening_m"), r.max_opening_m[j]);
            self.number(n("seat_margin_m"), seat - r.max_opening_m[j]);
            let unseated = r.unseating.iter().find(|u| u.joint == j);
            self.set(n("unseated"), Value::Bool(unseated.is_some()));
            if let Some(u) = unseated {
                self.number(n("unseated_s"), u.time_s);
            }
            if let Some(f) = free {
                self.number(n("max_opening_no_pounding_m"), f.max_opening_m[j]);
                self.number(n("required_gap_m"), f.max_closing_m[j].max(0.0));
            }
        }
        if let Some(f) = free {
            if let Some(o) = largest(f.max_opening_m.iter().copied()) {
                self.number("max_opening_no_pounding_m", o);
            }
            self.number("unseated_count_no_pounding", f.unseating.len() as f64);
        }
    }

    fn bridge_girders(
        &mut self,
        setup: &BridgeSetup,
        r: &BridgeResult,
        free: Option<&BridgeResult>,
    ) {
        let sc = &setup.scenario;
        for i in 0..sc.spans {
            let n = |f: &str| format!("girder{}.{f}", i + 1);
            let g = sc.girder(i);
            self.number(n("wave_speed_m_s"), g.wave_speed_m_s());
            self.number(n("round_trip_s"), g.round_trip_s());
            self.number(n("impedance_n_s_m"), g.impedance_n_s_m());
            self.number(n("mass_kg"), g.mass_kg);
            if let Some(t) = sc.frame_modes(i).periods_s().first() {
                self.number(n("period_s"), *t);
            }
            self.number(n("delay_s"), sc.delay_s(sc.frame_position_m(i)));
            self.number(n("peak_displacement_m"), r.peak_girder_displacement_m[i]);
            if let Some(f) = free {
                self.number(
                    n("peak_displacement_no_pounding_m"),
                    f.peak_girder_displacement_m[i],
                );
            }
        }
    }
}
