//! `KEY = VALUE` settings: the one place where named keys meet the scenario. Presets (TOML) and
//! `--set KEY=VALUE` overrides both go through [`ImpactSetup::apply`], so they accept exactly the
//! same keys with exactly the same checks.

use crate::model::bar::{EndShape, Section};
use crate::model::contact::LawKind;
use crate::model::error::InputError;
use crate::model::impact::ModelKind;
use crate::model::material::MaterialPreset;
use crate::model::scenario::{ImpactScenario, Reading};
use crate::model::settings::{self, IMPACT_SETTINGS, Setting};

/// A value as typed by a user: TOML gives it typed, the command line as text.
#[derive(Debug, Clone, PartialEq)]
pub enum SettingValue {
    Number(f64),
    Text(String),
    Bool(bool),
    /// Numbers separated by commas on the command line, a TOML array in a preset.
    List(Vec<f64>),
}

impl SettingValue {
    /// Reads command-line text: a number where it parses as one, a boolean for true/false.
    pub fn from_cli(text: &str) -> Self {
        let t = text.trim();
        match t {
            "true" => SettingValue::Bool(true),
            "false" => SettingValue::Bool(false),
            _ => match t.parse::<f64>() {
                Ok(x) => SettingValue::Number(x),
                Err(_) if t.contains(',') => {
                    let parts: Result<Vec<f64>, _> =
                        t.split(',').map(|p| p.trim().parse::<f64>()).collect();
                    parts.map_or_else(|_| SettingValue::Text(t.to_string()), SettingValue::List)
                }
                Err(_) => SettingValue::Text(t.to_string()),
            },
        }
    }

    pub(crate) fn describe(&self) -> String {
        match self {
            SettingValue::Number(x) => x.to_string(),
            SettingValue::Text(s) => format!("'{s}'"),
            SettingValue::Bool(b) => b.to_string(),
            SettingValue::List(v) => v
                .iter()
                .map(|x| x.to_string())
                .collect::<Vec<_>>()
                .join(","),
        }
    }
}

/// A scenario and the model to run it with.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactSetup {
    pub scenario: ImpactScenario,
    pub model: ModelKind,
}

impl Default for ImpactSetup {
    fn default() -> Self {
        ImpactSetup {
            scenario: ImpactScenario::default(),
            model: ModelKind::Sears,
        }
    }
}

pub(crate) fn number(key: &str, v: &SettingValue) -> Result<f64, InputError> {
    match v {
        SettingValue::Number(x) => Ok(*x),
        other => Err(InputError::new(
            key,
            format!("expected a number, got {}", other.describe()),
        )),
    }
}

/// One number or a list of them.
pub(crate) fn numbers(key: &str, v: &SettingValue) -> Result<Vec<f64>, InputError> {
    match v {
        SettingValue::Number(x) => Ok(vec![*x]),
        SettingValue::List(xs) if !xs.is_empty() => Ok(xs.clone()),
        other => Err(InputError::new(
            key,
            format!(
                "expected a number or numbers separated by commas, got {}",
                other.describe()
            ),
        )),
    }
}

pub(crate) fn text<'a>(key: &str, v: &'a SettingValue) -> Result<&'a str, InputError> {
    match v {
        SettingValue::Text(s) => Ok(s),
        other => Err(InputError::new(
            key,
            format!("expected a word, got {}", other.describe()),
        )),
    }
}

pub(crate) fn count(key: &str, v: &SettingValue) -> Result<usize, InputError> {
    let x = number(key, v)?;
    if x.is_finite() && x >= 0.0 && x.fract() == 0.0 && x <= 1e15 {
        Ok(x as usize)
    } else {
        Err(InputError::new(
            key,
            format!(
                "expected a whole number >= 0, got {}",
                crate::model::settings::shown(x)
            ),
        ))
    }
}

pub(crate) fn choice<T: Copy>(
    table: &'static [Setting],
    key: &str,
    v: &SettingValue,
    parse: impl Fn(&str) -> Option<T>,
) -> Result<T, InputError> {
    let s = text(key, v)?;
    parse(s).ok_or_else(|| {
        // The accepted values are the key's row of the settings table, as `--list-keys` shows.
        let allowed = settings::find(table, key)
            .and_then(|row| row.choices())
            .map_or_else(String::new, |options| options.join("|"));
        InputError::new(key, format!("unknown value '{s}': allowed {allowed}"))
    })
}

impl ImpactSetup {
    /// Sets one key. Unknown keys and ill-typed values are errors naming the key; range checks
    /// happen in [`ImpactScenario::validate`] so that they see the final combination.
    pub fn apply(&mut self, key: &str, value: &SettingValue) -> Result<(), InputError> {
        let sc = &mut self.scenario;
        if key == "model" {
            self.model = choice(IMPACT_SETTINGS, key, value, ModelKind::from_name)?;
            return Ok(());
        }
        if let Some((bar_name, field)) = key.split_once('.')
            && (bar_name == "bar1" || bar_name == "bar2")
        {
            let bar = if bar_name == "bar1" {
                &mut sc.bar1
            } else {
                &mut sc.bar2
            };
            match field {
                "material" => {
                    bar.material = choice(IMPACT_SETTINGS, key, value, |s| {
                        MaterialPreset::from_name(s).map(|m| m.material())
                    })?
                }
                "youngs_modulus" => bar.material.youngs_modulus_pa = number(key, value)?,
                "poisson_ratio" => bar.material.poisson_ratio = number(key, value)?,
                "density" => bar.material.density_kg_m3 = number(key, value)?,
                "length" => bar.length_m = number(key, value)?,
                "radius" => {
                    bar.section = Section::Circular {
                        radius_m: number(key, value)?,
                    }
                }
                "area" => {
                    bar.section = Section::Area {
                        area_m2: number(key, value)?,
                    }
                }
                "added_mass" => bar.added_mass_kg = number(key, value)?,
                "velocity" => bar.velocity_m_s = number(key, value)?,
                "end_radius" => {
                    bar.end = match value {
                        SettingValue::Text(s) if s == "flat" => EndShape::Flat,
                        SettingValue::Number(r) => EndShape::Rounded { radius_m: *r },
                        other => {
                            return Err(InputError::new(
                                key,
                                format!("expected a radius in m or flat, got {}", other.describe()),
                            ));
                        }
                    }
                }
                _ => return Err(unknown(key)),
            }
            return Ok(());
        }
        match key {
            "contact.law" => {
                sc.contact.law = choice(IMPACT_SETTINGS, key, value, |s| {
                    [LawKind::Hertz, LawKind::Linear]
                        .into_iter()
                        .find(|l| l.name() == s)
                })?
            }
            "contact.stiffness" => {
                sc.contact.stiffness = match value {
                    SettingValue::Text(s) if s == "auto" => None,
                    other => Some(number(key, other)?),
                }
            }
            "contact.zone_scale" => sc.contact.zone_scale = number(key, value)?,
            "contact.zone_length" => {
                sc.contact.zone_length_m = match value {
                    SettingValue::Text(s) if s == "auto" => None,
                    other => Some(number(key, other)?),
                }
            }
            "contact.divisions" => sc.contact.divisions = number(key, value)?,
            "contact.restitution" => sc.contact.restitution = number(key, value)?,
            "sears.reading" => {
                sc.reading = choice(IMPACT_SETTINGS, key, value, Reading::from_name)?
            }
            "solver.dt" => sc.solver.dt_s = number(key, value)?,
            "solver.window" => sc.solver.window_s = number(key, value)?,
            "solver.max_steps" => sc.solver.max_steps = count(key, value)?,
            "solver.refine" => {
                sc.solver.refine = match value {
                    SettingValue::Bool(b) => *b,
                    other => {
                        return Err(InputError::new(
                            key,
                            format!("expected true or false, got {}", other.describe()),
                        ));
                    }
                }
            }
            "fe.segments" => sc.fe.segments = count(key, value)?,
            "fe.courant" => sc.fe.courant = number(key, value)?,
            _ => return Err(unknown(key)),
        }
        Ok(())
    }

    /// Applies `KEY=VALUE` text from the command line.
    pub fn apply_assignment(&mut self, assignment: &str) -> Result<(), InputError> {
        let (key, value) = assignment.split_once('=').ok_or_else(|| {
            InputError::new(assignment, "expected KEY=VALUE (for example bar1.length=2)")
        })?;
        self.apply(key.trim(), &SettingValue::from_cli(value))
    }
}

fn unknown(key: &str) -> InputError {
    let known: Vec<&str> = crate::model::settings::IMPACT_SETTINGS
        .iter()
        .map(|s| s.key)
        .collect();
    InputError::new(
        key,
        format!(
            "unknown key; known keys: {} (barN is bar1 or bar2)",
            known.join(", ")
        ),
    )
}
