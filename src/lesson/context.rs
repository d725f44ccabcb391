//! The names a lesson's expressions may read, and their values for one solved scene.
//!
//! Names are the settings keys exactly as `--set` spells them (`bar1.length`, `gap`), the result
//! fields as `--json` names them (`restitution`, `contact_duration_s`, `impact_count`), and a few
//! derived numbers a lecturer needs (`c1`, `a_tau`, `vibration_fraction`, `min_gap_m`). In the
//! compare scene every compared model's fields are also there with the model as a prefix, a
//! dash written as `_`: `wave.restitution`, `lumped_hertz.contact_duration_s`. The bridge
//! scene's names are [`super::bridge_context`]'s.

use super::LessonScene;
use super::expr::{ExprError, Value};
use crate::io::building_settings::{BUILDINGS, BuildingSetup};
use crate::io::registry::uniform;
use crate::io::settings::{IMPACT, ImpactSetup, SettingValue};
use crate::model::building::BuildingResult;
use crate::model::building::gaps::{GapAssessment, assess};
use crate::model::impact::{ImpactResult, ModelKind};
use crate::model::settings::{BUILDING_SETTINGS, IMPACT_SETTINGS, Kind, Setting, concrete_keys};
use std::collections::{BTreeMap, BTreeSet};

/// The models the compare scene solves (its lead, the setup's model, is one of them).
pub const COMPARE_MODELS: [ModelKind; 5] = [
    ModelKind::Sears,
    ModelKind::Wave,
    ModelKind::LumpedHertz,
    ModelKind::LumpedLinear,
    ModelKind::Fe,
];

/// One model run's fields, as `--json` names them (and a few derived: `a_tau`, the energy
/// fractions).
pub const IMPACT_FIELDS: &[(&str, &str)] = &[
    ("impact", "whether the bars met (true/false)"),
    ("peak_force_n", "largest contact force [N]"),
    (
        "contact_duration_s",
        "how long the first contact's force stays above 1e-6 of its peak [s]",
    ),
    (
        "touching_duration_s",
        "how long the bars touch in the first contact [s]",
    ),
    (
        "restitution",
        "effective e = (V2 - V1)/(v1 - v2) at the end of the run",
    ),
    (
        "restitution_first_contact",
        "e after the first contact alone",
    ),
    ("impulse_ns", "total impulse [N s]"),
    ("contacts", "number of contact intervals"),
    ("recontact_s", "start of a second contact [s]"),
    (
        "velocity_after_1_m_s",
        "bar 1's rigid-body velocity after [m/s]",
    ),
    (
        "velocity_after_2_m_s",
        "bar 2's rigid-body velocity after [m/s]",
    ),
    ("energy.initial_j", "kinetic energy before [J]"),
    ("energy.rigid_body_j", "rigid-body kinetic energy after [J]"),
    ("energy.vibration_j", "energy left in the bars' waves [J]"),
    (
        "energy.dissipated_j",
        "energy a damped contact dissipated [J]",
    ),
    ("energy.contact_j", "energy still in the contact [J]"),
    (
        "energy_balance_error",
        "(final - initial) / relative kinetic energy; > 0 created",
    ),
    (
        "vibration_fraction",
        "energy.vibration_j / energy.initial_j",
    ),
    (
        "rigid_body_fraction",
        "energy.rigid_body_j / energy.initial_j",
    ),
    ("a_tau", "Sears' validity number a tau (Sears only)"),
    (
        "sears.creates_energy",
        "whether the run created energy (Sears only)",
    ),
    (
        "sears.tangent_stiffness_n_m",
        "contact tangent stiffness at the peak (Sears only) [N/m]",
    ),
    ("steps", "solver steps"),
    ("dt_s", "the step used [s]"),
    ("simulated_until_s", "end of the simulated span [s]"),
];

/// Numbers of the impact setup itself (the same for every model).
pub const IMPACT_DERIVED: &[(&str, &str)] = &[
    ("c1", "bar 1's wave speed sqrt(E/rho~) [m/s]"),
    ("c2", "bar 2's wave speed [m/s]"),
    ("z1", "bar 1's impedance rho~ A c [N s/m]"),
    ("z2", "bar 2's impedance [N s/m]"),
    ("m1", "bar 1's mass with its added mass [kg]"),
    ("m2", "bar 2's mass [kg]"),
    ("v_rel", "approach velocity v1 - v2 [m/s]"),
    (
        "wave_force_n",
        "wave theory's force Z1 Z2/(Z1 + Z2) (v1 - v2) [N]",
    ),
    ("round_trip_1_s", "2 L1 / c1 [s]"),
    ("round_trip_2_s", "2 L2 / c2 [s]"),
    (
        "zone_length_1_m",
        "Sears zone d of bar 1 after the scale [m]",
    ),
    ("zone_length_2_m", "Sears zone d of bar 2 [m]"),
    (
        "contact_stiffness",
        "the contact law's k as used (auto resolved) [N/m^1.5 or N/m]",
    ),
];

/// A building run's fields, as `--json` names them, and the gap assessment's (from the same
/// pair without contact).
pub const BUILDING_FIELDS: &[(&str, &str)] = &[
    ("impact_count", "impacts (contacts grouped by merge_gap_s)"),
    ("contact_count", "raw contact intervals"),
    ("max_pounding_force_n", "largest pounding force [N]"),
    (
        "strongest_impact",
        "which impact (from 1) had the largest force",
    ),
    ("peak_displacement_left_m", "left roof's peak |u| [m]"),
    ("peak_displacement_right_m", "right roof's peak |u| [m]"),
    (
        "peak_displacement_left_no_pounding_m",
        "the same without contact [m]",
    ),
    (
        "peak_displacement_right_no_pounding_m",
        "the same without contact [m]",
    ),
    (
        "ductility_demand_left",
        "left building's largest storey ductility demand (peak drift / yield drift)",
    ),
    (
        "ductility_demand_right",
        "right building's largest storey ductility demand",
    ),
    (
        "ductility_demand_left_no_pounding",
        "the same without contact",
    ),
    (
        "ductility_demand_right_no_pounding",
        "the same without contact",
    ),
    (
        "residual_drift_left_m",
        "left building's largest storey drift left at the end, in size [m]",
    ),
    (
        "residual_drift_right_m",
        "right building's largest storey drift left at the end, in size [m]",
    ),
    (
        "residual_drift_left_no_pounding_m",
        "the same without contact [m]",
    ),
    (
        "residual_drift_right_no_pounding_m",
        "the same without contact [m]",
    ),
    (
        "energy_hysteretic_j",
        "energy the yielding storeys dissipated [J]",
    ),
    ("period_left_s", "left building's first period [s]"),
    ("period_right_s", "right building's first period [s]"),
    ("energy_input_j", "work of the ground on the buildings [J]"),
    (
        "energy_building_damping_j",
        "energy the buildings' damping took [J]",
    ),
    (
        "energy_to_contact_j",
        "energy the contact took and kept [J]",
    ),
    ("energy_balance_error", "the ledger's relative residual"),
    (
        "min_gap_m",
        "smallest gap that avoids all contact (run without contact) [m]",
    ),
    ("abs_gap_m", "ABS rule: |u_left|max + |u_right|max [m]"),
    (
        "srss_gap_m",
        "SRSS rule: sqrt(|u_left|max^2 + |u_right|max^2) [m]",
    ),
    ("abs_ratio", "ABS / minimum gap (above 1: safe)"),
    (
        "srss_ratio",
        "SRSS / minimum gap (below 1: they still touch)",
    ),
];

/// The prefix a model's fields carry in the compare scene: its name with `_` for `-`.
pub fn model_prefix(model: ModelKind) -> String {
    model.name().replace('-', "_")
}

/// The names one scene's expressions may use.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Vocabulary {
    names: BTreeSet<String>,
}

impl Vocabulary {
    /// Every name of a scene: settings keys, result fields, derived numbers.
    pub fn for_scene(scene: LessonScene) -> Self {
        let mut names = BTreeSet::new();
        let own = |list: &[(&str, &str)]| list.iter().map(|(n, _)| n.to_string()).collect();
        match scene {
            LessonScene::Bar | LessonScene::Compare => {
                names.extend(concrete_keys(IMPACT_SETTINGS));
                names.extend::<Vec<String>>(own(IMPACT_FIELDS));
                names.extend::<Vec<String>>(own(IMPACT_DERIVED));
                if scene == LessonScene::Compare {
                    for m in COMPARE_MODELS {
                        let p = model_prefix(m);
                        names.extend(IMPACT_FIELDS.iter().map(|(n, _)| format!("{p}.{n}")));
                    }
                }
            }
            LessonScene::Buildings => {
                names.extend(concrete_keys(BUILDING_SETTINGS));
                names.extend::<Vec<String>>(own(BUILDING_FIELDS));
            }
            LessonScene::Bridge => names.extend(super::bridge_context::names()),
        }
        Vocabulary { names }
    }

    pub fn knows(&self, name: &str) -> bool {
        self.names.contains(name)
    }

    /// Every name, sorted.
    pub fn names(&self) -> impl Iterator<Item = &str> {
        self.names.iter().map(String::as_str)
    }

    /// A hint for an unknown name: the closest known names sharing its first part.
    pub fn hint(&self, name: &str) -> String {
        let head = name.split('.').next().unwrap_or(name);
        let close: Vec<&str> = self
            .names()
            .filter(|n| n.starts_with(head) || name.starts_with(n.split('.').next().unwrap_or(n)))
            .take(8)
            .collect();
        if close.is_empty() {
            " (see docs/lessons.md for the names a scene knows)".into()
        } else {
            format!("; did you mean one of: {}", close.join(", "))
        }
    }
}

/// The values of one solved scene, by name.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Context {
    vocabulary: Vocabulary,
    values: BTreeMap<String, Value>,
    /// Why a compared model gave no values, by its prefix (`fe.`): a name under it says so.
    failures: BTreeMap<String, String>,
}

impl Context {
    /// No names at all (constant expressions).
    pub fn empty() -> Self {
        Context::default()
    }

    /// No values yet, the names of `scene`.
    pub(super) fn of_scene(scene: LessonScene) -> Self {
        Context {
            vocabulary: Vocabulary::for_scene(scene),
            ..Context::default()
        }
    }

    /// The value of `name`: unknown names and names without a value in this run are errors.
    pub fn get(&self, name: &str) -> Result<Value, ExprError> {
        if let Some(v) = self.values.get(name) {
            return Ok(v.clone());
        }
        if self.vocabulary.knows(name) {
            let why = self
                .failures
                .iter()
                .find(|(prefix, _)| name.starts_with(prefix.as_str()))
                .map_or_else(
                    || "this model, setting or run does not give it".into(),
                    |(prefix, reason)| {
                        format!("{} did not solve: {reason}", prefix.trim_end_matches('.'))
                    },
                );
            Err(ExprError::Unavailable {
                name: name.to_string(),
                why,
            })
        } else {
            Err(ExprError::UnknownName {
                name: name.to_string(),
                hint: self.vocabulary.hint(name),
            })
        }
    }

    /// The values by name (for a readout of what a step's expressions can see).
    pub fn values(&self) -> impl Iterator<Item = (&str, &Value)> {
        self.values.iter().map(|(k, v)| (k.as_str(), v))
    }

    /// The same values, with the compared models that failed and why: a name of theirs then
    /// says the reason rather than only that it has no value.
    pub fn with_failures(mut self, failed: &[(ModelKind, String)]) -> Self {
        for (m, why) in failed {
            self.failures
                .insert(format!("{}.", model_prefix(*m)), why.clone());
        }
        self
    }

    pub(super) fn set(&mut self, name: impl Into<String>, v: Value) {
        self.values.insert(name.into(), v);
    }

    pub(super) fn number(&mut self, name: impl Into<String>, x: f64) {
        if x.is_finite() {
            self.set(name, Value::Number(x));
        }
    }

    /// An impact scene: the lead model's fields unprefixed (the run whose model is the setup's,
    /// else the first run), every run's also as `MODEL.field`. Bar scene: give the one run;
    /// compare scene: every compared model's that solved.
    pub fn impact(setup: &ImpactSetup, runs: &[(ModelKind, &ImpactResult)]) -> Self {
        // The compare scene's names: a bar step's expressions were checked against the
        // narrower bar vocabulary when the lesson loaded.
        let mut ctx = Context::of_scene(LessonScene::Compare);
        for key in concrete_keys(IMPACT_SETTINGS) {
            if let Some(v) = impact_setting(setup, &key) {
                ctx.set(key, v);
            }
        }
        ctx.impact_derived(setup);
        let lead = runs
            .iter()
            .find(|(m, _)| *m == setup.model)
            .or_else(|| runs.first());
        if let Some((_, r)) = lead {
            ctx.result_fields("", r);
        }
        for (m, r) in runs {
            ctx.result_fields(&format!("{}.", model_prefix(*m)), r);
        }
        ctx
    }

    fn impact_derived(&mut self, setup: &ImpactSetup) {
        let sc = &setup.scenario;
        let (b1, b2) = (&sc.bar1, &sc.bar2);
        for (i, b) in [(1, b1), (2, b2)] {
            self.number(format!("c{i}"), b.wave_speed_m_s());
            self.number(format!("z{i}"), b.impedance_n_s_m());
            self.number(format!("m{i}"), b.mass_kg());
            self.number(format!("round_trip_{i}_s"), b.round_trip_s());
        }
        self.number("v_rel", sc.approach_velocity_m_s());
        self.number("wave_force_n", sc.wave_force_n());
        let [d1, d2] = sc.zone_lengths_m();
        self.number("zone_length_1_m", d1);
        self.number("zone_length_2_m", d2);
        if let Ok(law) = sc.contact_law() {
            self.number("contact_stiffness", law.stiffness);
        }
    }

    fn result_fields(&mut self, prefix: &str, r: &ImpactResult) {
        let n = |s: &str| format!("{prefix}{s}");
        self.set(n("impact"), Value::Bool(r.impact));
        if let Some(p) = r.peak_force_n {
            self.number(n("peak_force_n"), p);
        }
        self.number(n("contact_duration_s"), r.contact_duration_s);
        self.number(n("touching_duration_s"), r.touching_duration_s);
        self.number(n("restitution"), r.restitution);
        self.number(n("restitution_first_contact"), r.restitution_first_contact);
        self.number(n("impulse_ns"), r.impulse_ns);
        self.number(n("contacts"), r.contacts.len() as f64);
        if let Some(t) = r.recontact_s() {
            self.number(n("recontact_s"), t);
        }
        self.number(n("velocity_after_1_m_s"), r.velocities_after_m_s[0]);
        self.number(n("velocity_after_2_m_s"), r.velocities_after_m_s[1]);
        let e = &r.energy;
        self.number(n("energy.initial_j"), e.initial_j);
        self.number(n("energy.rigid_body_j"), e.rigid_body_j);
        self.number(n("energy.vibration_j"), e.vibration_j);
        self.number(n("energy.dissipated_j"), e.dissipated_j);
        self.number(n("energy.contact_j"), e.contact_j);
        self.number(n("energy_balance_error"), e.balance_error);
        if e.initial_j > 0.0 {
            self.number(n("vibration_fraction"), e.vibration_j / e.initial_j);
            self.number(n("rigid_body_fraction"), e.rigid_body_j / e.initial_j);
        }
        if let Some(s) = &r.sears {
            self.number(n("a_tau"), s.a_tau);
            self.set(n("sears.creates_energy"), Value::Bool(s.creates_energy));
            self.number(n("sears.tangent_stiffness_n_m"), s.tangent_stiffness_n_m);
        }
        self.number(n("steps"), r.stats.steps as f64);
        self.number(n("dt_s"), r.stats.dt_s);
        self.number(n("simulated_until_s"), r.end_s);
    }

    /// A building scene: the run's fields, and where `free` (the same pair without contact) is
    /// given, the no-pounding peaks and the gap assessment.
    pub fn buildings(
        setup: &BuildingSetup,
        result: &BuildingResult,
        free: Option<&BuildingResult>,
    ) -> Self {
        let mut ctx = Context::of_scene(LessonScene::Buildings);
        for key in concrete_keys(BUILDING_SETTINGS) {
            if let Some(v) = building_setting(setup, &key) {
                ctx.set(key, v);
            }
        }
        let r = result;
        ctx.number("impact_count", r.impacts.len() as f64);
        ctx.number("contact_count", r.contacts.len() as f64);
        ctx.number("max_pounding_force_n", r.max_pounding_force_n);
        if let Some((i, _)) = r
            .impacts
            .iter()
            .enumerate()
            .max_by(|a, b| a.1.peak_force_n.total_cmp(&b.1.peak_force_n))
        {
            ctx.number("strongest_impact", (i + 1) as f64);
        }
        ctx.number("peak_displacement_left_m", r.peak_displacement_m[0]);
        ctx.number("peak_displacement_right_m", r.peak_displacement_m[1]);
        for (side, modes) in ["left", "right"].iter().zip(&r.modes) {
            if let Some(t) = modes.periods_s().first() {
                ctx.number(format!("period_{side}_s"), *t);
            }
        }
        ctx.yielding(r, "");
        ctx.number("energy_hysteretic_j", r.energy.hysteretic_j);
        ctx.number("energy_input_j", r.energy.input_j);
        ctx.number("energy_building_damping_j", r.energy.building_damping_j);
        ctx.number("energy_to_contact_j", r.energy.contact_j);
        ctx.number("energy_balance_error", r.energy.balance_error());
        if let Some(f) = free {
            ctx.number(
                "peak_displacement_left_no_pounding_m",
                f.peak_displacement_m[0],
            );
            ctx.number(
                "peak_displacement_right_no_pounding_m",
                f.peak_displacement_m[1],
            );
            ctx.gaps(&assess(f));
            ctx.yielding(f, "_no_pounding");
        }
        ctx
    }

    /// Each building's largest storey ductility demand and residual drift, names ending in
    /// `suffix` (the run without contact's: `_no_pounding`).
    fn yielding(&mut self, r: &BuildingResult, suffix: &str) {
        for (side, name) in ["left", "right"].iter().enumerate() {
            let largest = |v: &[f64]| v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            self.number(
                format!("ductility_demand_{name}{suffix}"),
                largest(&r.ductility_demand[side]),
            );
            self.number(
                format!("residual_drift_{name}{suffix}_m"),
                largest(&r.residual_drift_m[side]),
            );
        }
    }

    fn gaps(&mut self, g: &GapAssessment) {
        self.number("min_gap_m", g.min_gap_m);
        self.number("abs_gap_m", g.abs_m);
        self.number("srss_gap_m", g.srss_m);
        if g.min_gap_m > 0.0 {
            self.number("abs_ratio", g.abs_ratio);
            self.number("srss_ratio", g.srss_ratio);
        }
    }
}

/// The value of one impact setting as the setup holds it (`None` where it has no number or
/// word: an automatic stiffness, a list whose storeys differ).
pub fn impact_setting(setup: &ImpactSetup, key: &str) -> Option<Value> {
    IMPACT.shown(setup, key).and_then(lesson_value)
}

/// The value of one building setting as the setup holds it.
pub fn building_setting(setup: &BuildingSetup, key: &str) -> Option<Value> {
    BUILDINGS.shown(setup, key).and_then(lesson_value)
}

/// A setting's value as an expression reads it: a per-storey list as the one value all its
/// storeys share; no other list has a value (Rayleigh damping's two modes).
pub(super) fn lesson_value((setting, value): (&Setting, SettingValue)) -> Option<Value> {
    match value {
        SettingValue::Number(x) => Some(Value::Number(x)),
        SettingValue::Bool(b) => Some(Value::Bool(b)),
        SettingValue::Text(t) => Some(Value::Text(t)),
        SettingValue::List(xs) => match setting.kind {
            Kind::List { .. } => uniform(&xs).map(Value::Number),
            _ => None,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lesson::expr::Expr;

    #[test]
    fn a_compared_model_that_failed_says_why_its_names_have_no_value() {
        let setup = ImpactSetup::default();
        let run = crate::model::impact::solve(ModelKind::Wave, &setup.scenario).unwrap();
        let reason = "work budget exceeded: fe.segments = 100000 per bar needs more";
        let ctx = Context::impact(&setup, &[(ModelKind::Wave, &run)])
            .with_failures(&[(ModelKind::Fe, reason.to_string())]);
        let e = Expr::parse("fe.peak_force_n > 0")
            .unwrap()
            .eval(&ctx)
            .unwrap_err()
            .to_string();
        assert!(e.contains("fe did not solve") && e.contains(reason), "{e}");
        // A model that solved reads as before; one that was not compared says only that.
        assert!(
            Expr::parse("wave.peak_force_n > 0")
                .unwrap()
                .truth(&ctx)
                .unwrap()
        );
        let e = Expr::parse("lumped_linear.contact_duration_s > 0")
            .unwrap()
            .eval(&ctx)
            .unwrap_err()
            .to_string();
        assert!(e.contains("does not give it"), "{e}");
    }
}
