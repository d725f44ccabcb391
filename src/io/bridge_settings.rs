//! `KEY = VALUE` settings of the bridge scene: [`BRIDGE`] holds every setting's registry entry;
//! presets and `--set` share them.

use super::motion::MotionSpec;
use super::motion_settings::{self, WithMotion};
use super::registry::{Entry, Registry, number, put, word};
use super::settings::SettingValue;
use crate::model::bridge::BridgeScenario;
use crate::model::building::ContactModel;
use crate::model::error::InputError;
use crate::model::settings::bridge as setting;

#[derive(Debug, Clone, PartialEq, Default)]
pub struct BridgeSetup {
    pub scenario: BridgeScenario,
    pub motion: MotionSpec,
}

impl BridgeSetup {
    /// Why `key` (as `--set` spells it) has no effect on this setup, where it has none.
    pub fn unused(&self, key: &str) -> Option<String> {
        self.motion.unused(key)
    }
}

impl WithMotion for BridgeSetup {
    fn motion(&self) -> &MotionSpec {
        &self.motion
    }
    fn motion_mut(&mut self) -> &mut MotionSpec {
        &mut self.motion
    }
}

impl BridgeSetup {
    pub fn apply(&mut self, key: &str, value: &SettingValue) -> Result<(), InputError> {
        BRIDGE.apply(self, key, value)
    }

    pub fn apply_assignment(&mut self, assignment: &str) -> Result<(), InputError> {
        BRIDGE.apply_assignment(self, assignment, "motion.apparent_velocity=500")
    }
}

fn list(values: &[f64]) -> Option<SettingValue> {
    Some(SettingValue::List(values.to_vec()))
}

type E = Entry<BridgeSetup>;

/// Every setting of the bridge scene, in the order of the settings table.
pub static BRIDGE: Registry<BridgeSetup> = Registry {
    placeholders: "lists take one value for every span, or one each",
    entries: &[
        E::new(
            &setting::CONTACT_MODEL,
            |s, _| word(s.scenario.contact.name()),
            |s, t, v| {
                put(
                    &mut s.scenario.contact,
                    t.choice(v, ContactModel::from_name),
                )
            },
        ),
        E::new(
            &setting::SPANS,
            |s, _| number(s.scenario.spans as f64),
            |s, t, v| put(&mut s.scenario.spans, t.count(v)),
        ),
        E::new(
            &setting::SPAN_LENGTH,
            |s, _| list(&s.scenario.span_length_m),
            |s, t, v| put(&mut s.scenario.span_length_m, t.numbers(v)),
        ),
        E::new(
            &setting::SPAN_AREA,
            |s, _| list(&s.scenario.span_area_m2),
            |s, t, v| put(&mut s.scenario.span_area_m2, t.numbers(v)),
        ),
        E::new(
            &setting::SPAN_YOUNGS_MODULUS,
            |s, _| list(&s.scenario.span_youngs_pa),
            |s, t, v| put(&mut s.scenario.span_youngs_pa, t.numbers(v)),
        ),
        E::new(
            &setting::SPAN_DENSITY,
            |s, _| list(&s.scenario.span_density_kg_m3),
            |s, t, v| put(&mut s.scenario.span_density_kg_m3, t.numbers(v)),
        ),
        E::new(
            &setting::SPAN_ADDED_MASS,
            |s, _| list(&s.scenario.span_added_mass_kg),
            |s, t, v| put(&mut s.scenario.span_added_mass_kg, t.numbers(v)),
        ),
        E::new(
            &setting::SPAN_VELOCITY,
            |s, _| list(&s.scenario.span_velocity_m_s),
            |s, t, v| put(&mut s.scenario.span_velocity_m_s, t.numbers(v)),
        ),
        E::new(
            &setting::PIER_MASS,
            |s, _| list(&s.scenario.pier_mass_kg),
            |s, t, v| put(&mut s.scenario.pier_mass_kg, t.numbers(v)),
        ),
        E::new(
            &setting::PIER_STIFFNESS,
            |s, _| list(&s.scenario.pier_stiffness_n_m),
            |s, t, v| put(&mut s.scenario.pier_stiffness_n_m, t.numbers(v)),
        ),
        E::new(
            &setting::BEARING_STIFFNESS,
            |s, _| list(&s.scenario.bearing_stiffness_n_m),
            |s, t, v| put(&mut s.scenario.bearing_stiffness_n_m, t.numbers(v)),
        ),
        E::new(
            &setting::DAMPING_RATIO,
            |s, _| number(s.scenario.damping_ratio),
            |s, t, v| put(&mut s.scenario.damping_ratio, t.number(v)),
        ),
        E::new(
            &setting::JOINT_GAPS,
            |s, _| list(&s.scenario.joint_gaps_m),
            |s, t, v| put(&mut s.scenario.joint_gaps_m, t.numbers(v)),
        ),
        E::new(
            &setting::SEAT_LENGTH,
            |s, _| number(s.scenario.seat_length_m),
            |s, t, v| put(&mut s.scenario.seat_length_m, t.number(v)),
        ),
        E::new(
            &setting::CONTACT_STIFFNESS,
            |s, _| s.scenario.stiffness.and_then(number),
            |s, t, v| put(&mut s.scenario.stiffness, t.number_or_word(v)),
        ),
        E::new(
            &setting::RESTITUTION,
            |s, _| number(s.scenario.restitution),
            |s, t, v| put(&mut s.scenario.restitution, t.number(v)),
        ),
        E::new(
            &setting::GIRDER_DAMPING,
            |s, _| number(s.scenario.girder_damping),
            |s, t, v| put(&mut s.scenario.girder_damping, t.number(v)),
        ),
        E::new(
            &setting::MERGE_GAP,
            |s, _| number(s.scenario.merge_gap_s),
            |s, t, v| put(&mut s.scenario.merge_gap_s, t.number(v)),
        ),
        motion_settings::file_entry(),
        motion_settings::units_entry(),
        motion_settings::scale_entry(),
        motion_settings::duration_entry(),
        motion_settings::dt_entry(),
        motion_settings::pga_entry(),
        motion_settings::seed_entry(),
        motion_settings::length_entry(),
        E::new(
            &setting::APPARENT_VELOCITY,
            |s, _| s.scenario.apparent_velocity_m_s.and_then(number),
            |s, t, v| put(&mut s.scenario.apparent_velocity_m_s, t.number_or_word(v)),
        ),
        E::new(
            &setting::TOLERANCE,
            |s, _| number(s.scenario.tolerance),
            |s, t, v| put(&mut s.scenario.tolerance, t.number(v)),
        ),
        E::new(
            &setting::STEPS_PER_SCALE,
            |s, _| s.scenario.steps_per_scale.and_then(number),
            |s, t, v| put(&mut s.scenario.steps_per_scale, t.number_or_word(v)),
        ),
        E::new(
            &setting::MAX_STEP,
            |s, _| number(s.scenario.max_step_s),
            |s, t, v| put(&mut s.scenario.max_step_s, t.number(v)),
        ),
        E::new(
            &setting::MAX_STEPS,
            |s, _| number(s.scenario.max_steps as f64),
            |s, t, v| put(&mut s.scenario.max_steps, t.count(v)),
        ),
    ],
};
