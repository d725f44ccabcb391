//! `KEY = VALUE` settings of the building scene: presets and `--set` share them, as for impacts.

pub use super::motion::MotionSpec;

/// The `motion.file` value that asks for the seeded synthetic record.
pub const SYNTHETIC: &str = "synthetic";
use super::motion::Units;
use super::settings::{SettingValue, choice, count, number, numbers, text};
use crate::model::building::{BuildingScenario, ContactModel, DampingModel, SlabReading};
use crate::model::error::InputError;
use crate::model::settings::BUILDING_SETTINGS;

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

impl BuildingSetup {
    pub fn apply(&mut self, key: &str, value: &SettingValue) -> Result<(), InputError> {
        if let Some((side, field)) = key.split_once('.')
            && (side == "left" || side == "right")
        {
            return self.apply_side(side == "left", field, key, value);
        }
        if key.starts_with("motion.") {
            return self.apply_motion(key, value);
        }
        let sc = &mut self.scenario;
        let auto = |v: &SettingValue| matches!(v, SettingValue::Text(s) if s == "auto");
        match key {
            "contact.model" => {
                sc.contact = choice(BUILDING_SETTINGS, key, value, ContactModel::from_name)?
            }
            "gap" => sc.gap_m = number(key, value)?,
            "contact.stiffness" => {
                sc.stiffness = if auto(value) {
                    None
                } else {
                    Some(number(key, value)?)
                }
            }
            "contact.restitution" => sc.restitution = number(key, value)?,
            "contact.reading" => {
                sc.reading = choice(BUILDING_SETTINGS, key, value, |s| match s {
                    "paper" => Some(SlabReading::Paper),
                    "end" => Some(SlabReading::End),
                    _ => None,
                })?
            }
            "contact.zone_length" => {
                sc.zone_length_m = if auto(value) {
                    None
                } else {
                    Some(number(key, value)?)
                }
            }
            "slab.damping" => sc.slab_damping = number(key, value)?,
            "impact.merge_gap_s" => sc.merge_gap_s = number(key, value)?,
            "solver.tolerance" => sc.tolerance = number(key, value)?,
            "solver.steps_per_scale" => {
                sc.steps_per_scale = if auto(value) {
                    None
                } else {
                    Some(number(key, value)?)
                }
            }
            "solver.max_step" => sc.max_step_s = number(key, value)?,
            "solver.max_steps" => sc.max_steps = count(key, value)?,
            _ => return Err(unknown(key)),
        }
        Ok(())
    }

    /// A key of one building (`left.` or `right.`).
    fn apply_side(
        &mut self,
        left: bool,
        field: &str,
        key: &str,
        value: &SettingValue,
    ) -> Result<(), InputError> {
        let sc = &mut self.scenario;
        let b = if left { &mut sc.left } else { &mut sc.right };
        match field {
            "storeys" => b.storeys = count(key, value)?,
            "masses" | "mass" => b.masses_kg = numbers(key, value)?,
            "stiffnesses" | "stiffness" => b.stiffnesses_n_m = numbers(key, value)?,
            "heights" | "height" => b.heights_m = numbers(key, value)?,
            "period" => {
                let t = checked(key, value)?;
                let mut check = sc.clone();
                check.contact = crate::model::building::ContactModel::None;
                check
                    .validate()
                    .map_err(|e| InputError::new(key, format!("needs valid storeys first: {e}")))?;
                let b = if left { &mut sc.left } else { &mut sc.right };
                b.set_period(t);
            }
            "damping_ratio" => b.damping_ratio = number(key, value)?,
            "damping" => {
                let modes = match b.damping {
                    DampingModel::Rayleigh { modes } => modes,
                    DampingModel::Modal => [1, 2],
                };
                b.damping = choice(BUILDING_SETTINGS, key, value, |s| match s {
                    "modal" => Some(DampingModel::Modal),
                    "rayleigh" => Some(DampingModel::Rayleigh { modes }),
                    _ => None,
                })?
            }
            "rayleigh_modes" => {
                let m = numbers(key, value)?;
                let whole = |x: f64| x.fract() == 0.0 && (1.0..=100.0).contains(&x);
                if m.len() != 2 || !whole(m[0]) || !whole(m[1]) {
                    return Err(InputError::new(
                        key,
                        format!(
                            "{} is not allowed: two mode numbers from 1, as i,j",
                            value.describe()
                        ),
                    ));
                }
                b.damping = DampingModel::Rayleigh {
                    modes: [m[0] as usize, m[1] as usize],
                };
            }
            "velocity" => sc.initial_velocity_m_s[if left { 0 } else { 1 }] = number(key, value)?,
            "slab_length" => b.slab_lengths_m = numbers(key, value)?,
            "slab_width" => b.slab_widths_m = numbers(key, value)?,
            "slab_thickness" => b.slab_thicknesses_m = numbers(key, value)?,
            "youngs_modulus" => b.slab_youngs_pa = numbers(key, value)?,
            _ => return Err(unknown(key)),
        }
        Ok(())
    }

    /// A key of the ground motion (`motion.`).
    fn apply_motion(&mut self, key: &str, value: &SettingValue) -> Result<(), InputError> {
        let m = &mut self.motion;
        match key {
            "motion.file" => {
                let name = text(key, value)?;
                m.set_source(name).map_err(|e| InputError::new(key, e))?;
            }
            "motion.units" => m.units = choice(BUILDING_SETTINGS, key, value, Units::from_name)?,
            "motion.scale" => {
                let x = checked(key, value)?;
                if x == 0.0 {
                    return Err(InputError::new(
                        key,
                        "0 is not allowed: a factor in [-100, 100] other than 0 (negative flips the record)",
                    ));
                }
                m.scale = x;
            }
            "motion.duration" => m.duration_s = Some(checked(key, value)?),
            "motion.dt" => m.dt_s = Some(checked(key, value)?),
            "motion.pga" => m.synthetic.pga_g = checked(key, value)?,
            "motion.seed" => {
                let x = checked(key, value)?;
                if x.fract() != 0.0 || x < 0.0 {
                    return Err(InputError::new(
                        key,
                        format!(
                            "{} is not a whole number; the seed is a whole number >= 0",
                            crate::model::settings::shown(x)
                        ),
                    ));
                }
                m.synthetic.seed = x as u64;
            }
            "motion.length" => m.synthetic.duration_s = checked(key, value)?,
            _ => return Err(unknown(key)),
        }
        Ok(())
    }

    pub fn apply_assignment(&mut self, assignment: &str) -> Result<(), InputError> {
        let (key, value) = assignment.split_once('=').ok_or_else(|| {
            InputError::new(
                assignment,
                "expected KEY=VALUE (for example left.damping_ratio=0.02)",
            )
        })?;
        self.apply(key.trim(), &SettingValue::from_cli(value))
    }
}

/// A number checked at once against its row of the settings table (the ground motion's settings
/// are read before any run validates them).
fn checked(key: &str, value: &SettingValue) -> Result<f64, InputError> {
    let x = number(key, value)?;
    crate::model::settings::check(crate::model::settings::BUILDING_SETTINGS, key, x)?;
    Ok(x)
}

fn unknown(key: &str) -> InputError {
    let known: Vec<&str> = crate::model::settings::BUILDING_SETTINGS
        .iter()
        .map(|s| s.key)
        .collect();
    InputError::new(
        key,
        format!(
            "unknown key; known keys: {} (SIDE is left or right)",
            known.join(", ")
        ),
    )
}
