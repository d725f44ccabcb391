//! `KEY = VALUE` settings of the building scene: [`BUILDINGS`] holds every setting's registry
//! entry; presets and `--set` share them, as for impacts.

pub use super::motion::MotionSpec;

use super::motion_settings::{self, WithMotion};
use super::registry::{Entry, Registry, Target, number, put, uniform, word};
use super::settings::SettingValue;
use crate::model::building::{
    Building, BuildingScenario, ContactModel, DampingModel, Recording, SlabReading,
};
use crate::model::error::InputError;
use crate::model::hysteresis::Hysteresis;
use crate::model::settings::building as setting;
use crate::model::settings::shown;

pub use super::motion_settings::SYNTHETIC;

#[derive(Debug, Clone, PartialEq)]
pub struct BuildingSetup {
    pub scenario: BuildingScenario,
    pub motion: MotionSpec,
}

impl Default for BuildingSetup {
    fn default() -> Self {
        BuildingSetup {
            scenario: BuildingScenario::paper(),
            motion: MotionSpec::default(),
        }
    }
}

impl WithMotion for BuildingSetup {
    fn motion(&self) -> &MotionSpec {
        &self.motion
    }
    fn motion_mut(&mut self) -> &mut MotionSpec {
        &mut self.motion
    }
}

impl BuildingSetup {
    pub fn apply(&mut self, key: &str, value: &SettingValue) -> Result<(), InputError> {
        BUILDINGS.apply(self, key, value)
    }

    pub fn apply_assignment(&mut self, assignment: &str) -> Result<(), InputError> {
        BUILDINGS.apply_assignment(self, assignment, "left.damping_ratio=0.02")
    }

    /// Why `key` (as `--set` spells it) has no effect on this setup, where it has none: the
    /// record's keys that do not apply to the record, and the yielding laws' parameters on
    /// storeys that do not follow that law.
    pub fn unused(&self, key: &str) -> Option<String> {
        if let Some(why) = self.motion.unused(key) {
            return Some(why);
        }
        let (side, rest) = key.split_once('.')?;
        let i = ["left", "right"].iter().position(|s| *s == side)?;
        let law = self.building(i).hysteresis;
        let used = match rest {
            "yield_forces" | "hardening" => law != Hysteresis::Elastic,
            "bouc_wen_n" => law == Hysteresis::BoucWen,
            _ => true,
        };
        (!used).then(|| format!("{side}.hysteresis is {}", law.name()))
    }

    /// Building `i` (0: the left one).
    pub fn building(&self, i: usize) -> &Building {
        [&self.scenario.left, &self.scenario.right][i]
    }

    /// Building `i`, to change.
    pub fn building_mut(&mut self, i: usize) -> &mut Building {
        let sc = &mut self.scenario;
        if i == 0 { &mut sc.left } else { &mut sc.right }
    }
}

fn list(values: &[f64]) -> Option<SettingValue> {
    Some(SettingValue::List(values.to_vec()))
}

/// Scales building `t.owner`'s storey stiffnesses to the period asked for; the storeys must
/// be valid first, or there is no period to scale from.
fn set_period(s: &mut BuildingSetup, t: &Target, v: &SettingValue) -> Result<(), InputError> {
    let period_s = t.checked(v)?;
    let mut check = s.scenario.clone();
    check.contact = ContactModel::None;
    check
        .validate()
        .map_err(|e| InputError::new(t.key, format!("needs valid storeys first: {e}")))?;
    // The period is a way of setting the stiffnesses: a period they cannot reach within their
    // own range is refused as this key, with the periods that would do.
    let building = s.building(t.owner);
    let now = building.period_s();
    let range = setting::STIFFNESSES
        .range()
        .expect("storey stiffnesses have a range");
    let (k_lo, k_hi) = building
        .stiffnesses_n_m
        .iter()
        .fold((f64::INFINITY, 0.0_f64), |(lo, hi), &k| {
            (lo.min(k), hi.max(k))
        });
    // k scales as 1 / T^2: the stiffest storey meets the top of the range at the shortest period.
    let shortest = now * (k_hi / range.max).sqrt();
    let longest = now * (k_lo / range.min).sqrt();
    if !(shortest..=longest).contains(&period_s) {
        return Err(InputError::new(
            t.key,
            format!(
                "{} s is not allowed: with these masses it needs storey stiffnesses outside {range} N/m ({}); periods from about {:.4e} to {:.4e} s keep them inside",
                shown(period_s),
                setting::STIFFNESSES
                    .key
                    .replace("SIDE", ["left", "right"][t.owner]),
                shortest * (1.0 + 1e-4),
                longest * (1.0 - 1e-4)
            ),
        ));
    }
    s.building_mut(t.owner).set_period(period_s);
    Ok(())
}

/// Rayleigh damping between two modes, given as `i,j`.
fn set_rayleigh_modes(
    s: &mut BuildingSetup,
    t: &Target,
    v: &SettingValue,
) -> Result<(), InputError> {
    let m = t.numbers(v)?;
    let whole = |x: f64| x.fract() == 0.0 && (1.0..=100.0).contains(&x);
    if m.len() != 2 || !whole(m[0]) || !whole(m[1]) {
        return Err(InputError::new(
            t.key,
            format!(
                "{} is not allowed: two mode numbers from 1, as i,j",
                v.describe()
            ),
        ));
    }
    s.building_mut(t.owner).damping = DampingModel::Rayleigh {
        modes: [m[0] as usize, m[1] as usize],
    };
    Ok(())
}

type E = Entry<BuildingSetup>;

/// Every setting of the building scene, in the order of the settings table.
pub static BUILDINGS: Registry<BuildingSetup> = Registry {
    placeholders: "SIDE is left or right",
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
            &setting::STOREYS,
            |s, i| number(s.building(i).storeys as f64),
            |s, t, v| put(&mut s.building_mut(t.owner).storeys, t.count(v)),
        ),
        E::new(
            &setting::MASSES,
            |s, i| list(&s.building(i).masses_kg),
            |s, t, v| put(&mut s.building_mut(t.owner).masses_kg, t.numbers(v)),
        ),
        E::new(
            &setting::STIFFNESSES,
            |s, i| list(&s.building(i).stiffnesses_n_m),
            |s, t, v| put(&mut s.building_mut(t.owner).stiffnesses_n_m, t.numbers(v)),
        ),
        E::new(
            &setting::HEIGHTS,
            |s, i| list(&s.building(i).heights_m),
            |s, t, v| put(&mut s.building_mut(t.owner).heights_m, t.numbers(v)),
        ),
        // Sets every storey's value alike; saved and shown as the list.
        E::new(
            &setting::MASS,
            |_, _| None,
            |s, t, v| put(&mut s.building_mut(t.owner).masses_kg, t.numbers(v)),
        )
        .derived(|s, i| uniform(&s.building(i).masses_kg)),
        // Sets every storey's value alike; saved and shown as the list.
        E::new(
            &setting::STIFFNESS,
            |_, _| None,
            |s, t, v| put(&mut s.building_mut(t.owner).stiffnesses_n_m, t.numbers(v)),
        )
        .derived(|s, i| uniform(&s.building(i).stiffnesses_n_m)),
        // Sets every storey's value alike; saved and shown as the list.
        E::new(
            &setting::HEIGHT,
            |_, _| None,
            |s, t, v| put(&mut s.building_mut(t.owner).heights_m, t.numbers(v)),
        )
        .derived(|s, i| uniform(&s.building(i).heights_m)),
        // An action on the stiffnesses, not a value of its own: shown, never saved.
        E::new(&setting::PERIOD, |_, _| None, set_period)
            .derived(|s, i| s.building(i).modes().periods_s().first().copied()),
        E::new(
            &setting::DAMPING_RATIO,
            |s, i| number(s.building(i).damping_ratio),
            |s, t, v| put(&mut s.building_mut(t.owner).damping_ratio, t.number(v)),
        ),
        E::new(
            &setting::DAMPING,
            |s, i| word(s.building(i).damping.name()),
            |s, t, v| {
                let b = s.building_mut(t.owner);
                let modes = match b.damping {
                    DampingModel::Rayleigh { modes } => modes,
                    DampingModel::Modal => [1, 2],
                };
                put(
                    &mut b.damping,
                    t.choice(v, |w| DampingModel::from_name(w, modes)),
                )
            },
        ),
        E::new(
            &setting::RAYLEIGH_MODES,
            |s, i| match s.building(i).damping {
                DampingModel::Rayleigh { modes: [i, j] } => list(&[i as f64, j as f64]),
                DampingModel::Modal => None,
            },
            set_rayleigh_modes,
        ),
        E::new(
            &setting::HYSTERESIS,
            |s, i| word(s.building(i).hysteresis.name()),
            |s, t, v| {
                put(
                    &mut s.building_mut(t.owner).hysteresis,
                    t.choice(v, Hysteresis::from_name),
                )
            },
        ),
        E::new(
            &setting::YIELD_FORCES,
            |s, i| s.building(i).yield_forces_n.as_deref().and_then(list),
            |s, t, v| {
                // `auto` (the default) gives the storeys back their derived yield forces.
                let forces = match v {
                    SettingValue::Text(w) if w == "auto" => Ok(None),
                    SettingValue::Number(_) | SettingValue::List(_) => t.numbers(v).map(Some),
                    other => Err(t.expected(
                        "auto, or a force in newtons (one for every storey, or one each by commas)",
                        other,
                    )),
                };
                put(&mut s.building_mut(t.owner).yield_forces_n, forces)
            },
        ),
        E::new(
            &setting::HARDENING,
            |s, i| number(s.building(i).hardening),
            |s, t, v| put(&mut s.building_mut(t.owner).hardening, t.number(v)),
        ),
        E::new(
            &setting::BOUC_WEN_N,
            |s, i| number(s.building(i).bouc_wen_n),
            |s, t, v| put(&mut s.building_mut(t.owner).bouc_wen_n, t.number(v)),
        ),
        E::new(
            &setting::VELOCITY,
            |s, i| number(s.scenario.initial_velocity_m_s[i]),
            |s, t, v| put(&mut s.scenario.initial_velocity_m_s[t.owner], t.number(v)),
        ),
        E::new(
            &setting::SLAB_LENGTH,
            |s, i| list(&s.building(i).slab_lengths_m),
            |s, t, v| put(&mut s.building_mut(t.owner).slab_lengths_m, t.numbers(v)),
        ),
        E::new(
            &setting::SLAB_WIDTH,
            |s, i| list(&s.building(i).slab_widths_m),
            |s, t, v| put(&mut s.building_mut(t.owner).slab_widths_m, t.numbers(v)),
        ),
        E::new(
            &setting::SLAB_THICKNESS,
            |s, i| list(&s.building(i).slab_thicknesses_m),
            |s, t, v| {
                put(
                    &mut s.building_mut(t.owner).slab_thicknesses_m,
                    t.numbers(v),
                )
            },
        ),
        E::new(
            &setting::SLAB_YOUNGS_MODULUS,
            |s, i| list(&s.building(i).slab_youngs_pa),
            |s, t, v| put(&mut s.building_mut(t.owner).slab_youngs_pa, t.numbers(v)),
        ),
        E::new(
            &setting::GAP,
            |s, _| number(s.scenario.gap_m),
            |s, t, v| put(&mut s.scenario.gap_m, t.number(v)),
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
            &setting::CONTACT_READING,
            |s, _| word(s.scenario.reading.name()),
            |s, t, v| put(&mut s.scenario.reading, t.choice(v, SlabReading::from_name)),
        ),
        E::new(
            &setting::ZONE_LENGTH,
            |s, _| s.scenario.zone_length_m.and_then(number),
            |s, t, v| put(&mut s.scenario.zone_length_m, t.number_or_word(v)),
        ),
        E::new(
            &setting::SLAB_DAMPING,
            |s, _| number(s.scenario.slab_damping),
            |s, t, v| put(&mut s.scenario.slab_damping, t.number(v)),
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
            &setting::MOTION_SETTLE,
            |s, _| number(s.motion.settle_s),
            |s, t, v| put(&mut s.motion.settle_s, t.checked(v)),
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
        E::new(
            &setting::RECORD,
            |s, _| word(s.scenario.recording.name()),
            |s, t, v| put(&mut s.scenario.recording, t.choice(v, Recording::from_name)),
        ),
    ],
};
