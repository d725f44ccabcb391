//! `KEY = VALUE` settings of the building scene: presets and `--set` share them, as for impacts.

pub use super::motion::MotionSpec;

/// The `motion.file` value that asks for the seeded synthetic record.
pub const SYNTHETIC: &str = "synthetic";
use super::motion::Units;
use super::settings::{SettingValue, choice, count, number, numbers, text};
use crate::model::building::{BuildingScenario, ContactModel, DampingModel, SlabReading};
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
        "SIDE.storeys",
        "number of storeys N, in [1, 100] (SIDE is left or right)",
    ),
    (
        "SIDE.masses",
        "floor masses [kg], > 0: one value for every floor, or N separated by commas",
    ),
    (
        "SIDE.stiffnesses",
        "storey shear stiffnesses [N/m], > 0: one value, or N",
    ),
    ("SIDE.heights", "storey heights [m], > 0: one value, or N"),
    ("SIDE.mass", "every floor's mass [kg], > 0"),
    ("SIDE.stiffness", "every storey's stiffness [N/m], > 0"),
    ("SIDE.height", "every storey's height [m], > 0"),
    (
        "SIDE.period",
        "fundamental period [s], > 0: scales every storey's stiffness to it",
    ),
    (
        "SIDE.damping_ratio",
        "viscous damping ratio, in [0, 1); default 0.05",
    ),
    (
        "SIDE.damping",
        "modal|rayleigh: the ratio in every mode, or Rayleigh damping on two modes",
    ),
    (
        "SIDE.rayleigh_modes",
        "the two modes (1-based) Rayleigh damping gets the ratio in; default 1,2",
    ),
    (
        "SIDE.velocity",
        "velocity of every floor relative to the ground at t = 0 [m/s] (isolated-impact studies)",
    ),
    (
        "SIDE.slab_length",
        "floor slab length along the pounding direction [m], > 0: one value, or N",
    ),
    (
        "SIDE.slab_width",
        "floor slab width [m], > 0: one value, or N",
    ),
    (
        "SIDE.slab_thickness",
        "floor slab thickness [m], > 0: one value, or N",
    ),
    (
        "SIDE.youngs_modulus",
        "floor slab Young's modulus [Pa], > 0: one value, or N",
    ),
    (
        "gap",
        "at-rest separation, the same at every level [m], >= 0",
    ),
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
        "Sears zone length d [m], or auto (a tenth of the stiffer building's slab)",
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
        "solver.tolerance",
        "accuracy target of the contact steps (relative), in (0, 0.1]; default 1e-4",
    ),
    (
        "solver.steps_per_scale",
        "steps per contact time scale inside contacts, >= 1, or auto (from the tolerance)",
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
                "storeys" => b.storeys = count(key, value)?,
                "masses" | "mass" => b.masses_kg = numbers(key, value)?,
                "stiffnesses" | "stiffness" => b.stiffnesses_n_m = numbers(key, value)?,
                "heights" | "height" => b.heights_m = numbers(key, value)?,
                "period" => {
                    let t = number(key, value)?;
                    if !(t.is_finite() && t > 0.0) {
                        return Err(InputError::new(
                            key,
                            format!("{t} is not allowed: must be a finite number > 0 s"),
                        ));
                    }
                    let mut check = sc.clone();
                    check.contact = crate::model::building::ContactModel::None;
                    check.validate().map_err(|e| {
                        InputError::new(key, format!("needs valid storeys first: {e}"))
                    })?;
                    let b = if side == "left" {
                        &mut sc.left
                    } else {
                        &mut sc.right
                    };
                    b.set_period(t);
                }
                "damping_ratio" => b.damping_ratio = number(key, value)?,
                "damping" => {
                    let modes = match b.damping {
                        DampingModel::Rayleigh { modes } => modes,
                        DampingModel::Modal => [1, 2],
                    };
                    b.damping = choice(
                        key,
                        value,
                        |s| match s {
                            "modal" => Some(DampingModel::Modal),
                            "rayleigh" => Some(DampingModel::Rayleigh { modes }),
                            _ => None,
                        },
                        "modal|rayleigh",
                    )?
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
                "velocity" => {
                    sc.initial_velocity_m_s[if side == "left" { 0 } else { 1 }] =
                        number(key, value)?
                }
                "slab_length" => b.slab_lengths_m = numbers(key, value)?,
                "slab_width" => b.slab_widths_m = numbers(key, value)?,
                "slab_thickness" => b.slab_thicknesses_m = numbers(key, value)?,
                "youngs_modulus" => b.slab_youngs_pa = numbers(key, value)?,
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
