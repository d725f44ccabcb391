//! `KEY = VALUE` settings of the building scene: presets and `--set` share them, as for impacts.

pub use super::motion::MotionSpec;

/// The `motion.file` value that asks for the seeded synthetic record.
pub const SYNTHETIC: &str = "synthetic";
use super::motion::Units;
use super::settings::{SettingValue, choice, count, number, text};
use crate::model::building::{BuildingScenario, ContactModel, SlabReading};
use crate::model::scenario::InputError;

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

pub const BUILDING_KEYS: &[(&str, &str)] = &[
    (
        "contact.model",
        "sears|linear|kelvin|hertz|hertzdamp|jankowski|stereo|none (the --contact flag)",
    ),
    (
        "SIDE.stiffness",
        "storey stiffness k [N/m], > 0 (SIDE is left or right)",
    ),
    ("SIDE.mass", "seismic mass m [kg], > 0"),
    (
        "SIDE.period",
        "natural period [s], > 0: sets the stiffness from the mass",
    ),
    (
        "SIDE.damping_ratio",
        "viscous damping ratio, in [0, 1); default 0.05",
    ),
    (
        "SIDE.velocity",
        "velocity relative to the ground at t = 0 [m/s] (isolated-impact studies)",
    ),
    ("SIDE.height", "storey height [m], > 0"),
    (
        "SIDE.slab_length",
        "roof slab length along the pounding direction [m], > 0",
    ),
    ("SIDE.slab_width", "roof slab width [m], > 0"),
    ("SIDE.slab_thickness", "roof slab thickness [m], > 0"),
    ("SIDE.youngs_modulus", "roof slab Young's modulus [Pa], > 0"),
    ("gap", "at-rest separation [m], >= 0"),
    (
        "contact.stiffness",
        "element stiffness (N/m; N/m^1.5 for hertz, hertzdamp, jankowski), or auto",
    ),
    (
        "contact.restitution",
        "target restitution (kelvin, hertzdamp, jankowski, stereo), in (0, 1]",
    ),
    ("contact.reading", "paper|end: the Sears reading"),
    (
        "contact.zone_length",
        "Sears zone length d [m], or auto (a tenth of the stiffer slab)",
    ),
    (
        "slab.damping",
        "damping ratio of the slabs' axial waves, in [0, 1); 0 = undamped d'Alembert",
    ),
    (
        "impact.merge_gap_s",
        "contacts closer than this form one impact [s], >= 0",
    ),
    (
        "motion.file",
        "the ground motion: a built-in record (elcentro-1940), a file (.AT2 or text), or synthetic; the --motion flag",
    ),
    (
        "motion.units",
        "g|m/s2|cm/s2 for text files (AT2 files are in g)",
    ),
    ("motion.scale", "factor on the record; negative flips it"),
    (
        "motion.duration",
        "use only the first seconds of the record [s], > 0",
    ),
    ("motion.dt", "step of a values-only text file [s], > 0"),
    (
        "motion.pga",
        "synthetic record: peak ground acceleration [g], > 0",
    ),
    (
        "motion.seed",
        "synthetic record: random seed, a whole number",
    ),
    ("motion.length", "synthetic record: length [s], > 0"),
    (
        "solver.steps_per_scale",
        "steps per contact time scale inside contacts, >= 1",
    ),
    ("solver.max_step", "longest step outside contacts [s], > 0"),
    ("solver.max_steps", "step budget, >= 1"),
];

impl BuildingSetup {
    pub fn apply(&mut self, key: &str, value: &SettingValue) -> Result<(), InputError> {
        let sc = &mut self.scenario;
        if let Some((side, field)) = key.split_once('.')
            && (side == "left" || side == "right")
        {
            let b = if side == "left" {
                &mut sc.left
            } else {
                &mut sc.right
            };
            match field {
                "stiffness" => b.stiffness_n_m = number(key, value)?,
                "mass" => b.mass_kg = number(key, value)?,
                "period" => {
                    let t = number(key, value)?;
                    if !(t.is_finite() && t > 0.0) {
                        return Err(InputError::new(
                            key,
                            format!("{t} is not allowed: must be a finite number > 0 s"),
                        ));
                    }
                    b.stiffness_n_m = b.mass_kg * (2.0 * std::f64::consts::PI / t).powi(2);
                }
                "damping_ratio" => b.damping_ratio = number(key, value)?,
                "velocity" => {
                    sc.initial_velocity_m_s[if side == "left" { 0 } else { 1 }] =
                        number(key, value)?
                }
                "height" => b.storey_height_m = number(key, value)?,
                "slab_length" => b.slab.length_m = number(key, value)?,
                "slab_width" => b.slab.width_m = number(key, value)?,
                "slab_thickness" => b.slab.thickness_m = number(key, value)?,
                "youngs_modulus" => b.slab.youngs_modulus_pa = number(key, value)?,
                _ => return Err(unknown(key)),
            }
            return Ok(());
        }
        let auto = |v: &SettingValue| matches!(v, SettingValue::Text(s) if s == "auto");
        let m = &mut self.motion;
        match key {
            "contact.model" => {
                sc.contact = choice(
                    key,
                    value,
                    ContactModel::from_name,
                    "sears|linear|kelvin|hertz|hertzdamp|jankowski|stereo|none",
                )?
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
                sc.reading = choice(
                    key,
                    value,
                    |s| match s {
                        "paper" => Some(SlabReading::Paper),
                        "end" => Some(SlabReading::End),
                        _ => None,
                    },
                    "paper|end",
                )?
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
            "motion.file" => {
                let name = text(key, value)?;
                m.file = (name != SYNTHETIC).then(|| name.to_string());
            }
            "motion.units" => m.units = choice(key, value, Units::from_name, "g|m/s2|cm/s2")?,
            "motion.scale" => {
                let x = number(key, value)?;
                if !x.is_finite() || x == 0.0 {
                    return Err(InputError::new(
                        key,
                        format!("{x} is not allowed: must be a finite, non-zero factor"),
                    ));
                }
                m.scale = x;
            }
            "motion.duration" => m.duration_s = Some(positive(key, value)?),
            "motion.dt" => m.dt_s = Some(positive(key, value)?),
            "motion.pga" => m.synthetic.pga_g = positive(key, value)?,
            "motion.seed" => m.synthetic.seed = count(key, value)? as u64,
            "motion.length" => m.synthetic.duration_s = positive(key, value)?,
            "solver.steps_per_scale" => sc.steps_per_scale = number(key, value)?,
            "solver.max_step" => sc.max_step_s = number(key, value)?,
            "solver.max_steps" => sc.max_steps = count(key, value)?,
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

fn positive(key: &str, value: &SettingValue) -> Result<f64, InputError> {
    let x = number(key, value)?;
    if x.is_finite() && x > 0.0 {
        Ok(x)
    } else {
        Err(InputError::new(
            key,
            format!("{x} is not allowed: must be a finite number > 0"),
        ))
    }
}

fn unknown(key: &str) -> InputError {
    let known: Vec<&str> = BUILDING_KEYS.iter().map(|(k, _)| *k).collect();
    InputError::new(
        key,
        format!(
            "unknown key; known keys: {} (SIDE is left or right)",
            known.join(", ")
        ),
    )
}
