//! `KEY = VALUE` settings of an impact: [`IMPACT`], the registry entry of every setting, is the
//! one place where a setting meets the scenario. Presets (TOML) and `--set KEY=VALUE` overrides
//! both go through [`ImpactSetup::apply`], so they accept exactly the same keys with exactly the
//! same checks.

use super::registry::{Entry, Registry, number, put, word};
use crate::model::bar::{Bar, EndShape, Section};
use crate::model::contact::LawKind;
use crate::model::error::InputError;
use crate::model::impact::ModelKind;
use crate::model::material::MaterialPreset;
use crate::model::scenario::{ImpactScenario, Reading};
use crate::model::settings::impact as setting;

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

impl ImpactSetup {
    /// Sets one key. Unknown keys and ill-typed values are errors naming the key; range checks
    /// happen in [`ImpactScenario::validate`] so that they see the final combination.
    pub fn apply(&mut self, key: &str, value: &SettingValue) -> Result<(), InputError> {
        IMPACT.apply(self, key, value)
    }

    /// Applies `KEY=VALUE` text from the command line.
    pub fn apply_assignment(&mut self, assignment: &str) -> Result<(), InputError> {
        IMPACT.apply_assignment(self, assignment, "bar1.length=2")
    }

    /// Bar `i` (0: bar1, the left one).
    pub fn bar(&self, i: usize) -> &Bar {
        [&self.scenario.bar1, &self.scenario.bar2][i]
    }

    /// Bar `i`, to change.
    pub fn bar_mut(&mut self, i: usize) -> &mut Bar {
        let sc = &mut self.scenario;
        if i == 0 { &mut sc.bar1 } else { &mut sc.bar2 }
    }
}

type E = Entry<ImpactSetup>;

/// Every setting of an impact, in the order of the settings table.
pub static IMPACT: Registry<ImpactSetup> = Registry {
    placeholders: "barN is bar1 or bar2",
    entries: &[
        E::new(
            &setting::MODEL,
            |s, _| word(s.model.name()),
            |s, t, v| put(&mut s.model, t.choice(v, ModelKind::from_name)),
        ),
        // A material is not kept: it sets E, nu and rho, which are saved and shown instead.
        E::new(
            &setting::MATERIAL,
            |_, _| None,
            |s, t, v| {
                let material = t.choice(v, MaterialPreset::from_name)?.material();
                s.bar_mut(t.owner).material = material;
                Ok(())
            },
        ),
        E::new(
            &setting::YOUNGS_MODULUS,
            |s, i| number(s.bar(i).material.youngs_modulus_pa),
            |s, t, v| {
                put(
                    &mut s.bar_mut(t.owner).material.youngs_modulus_pa,
                    t.number(v),
                )
            },
        ),
        E::new(
            &setting::POISSON_RATIO,
            |s, i| number(s.bar(i).material.poisson_ratio),
            |s, t, v| put(&mut s.bar_mut(t.owner).material.poisson_ratio, t.number(v)),
        ),
        E::new(
            &setting::DENSITY,
            |s, i| number(s.bar(i).material.density_kg_m3),
            |s, t, v| put(&mut s.bar_mut(t.owner).material.density_kg_m3, t.number(v)),
        ),
        E::new(
            &setting::LENGTH,
            |s, i| number(s.bar(i).length_m),
            |s, t, v| put(&mut s.bar_mut(t.owner).length_m, t.number(v)),
        ),
        E::new(
            &setting::RADIUS,
            |s, i| match s.bar(i).section {
                Section::Circular { radius_m } => number(radius_m),
                Section::Area { .. } => None,
            },
            |s, t, v| {
                let radius_m = t.number(v)?;
                s.bar_mut(t.owner).section = Section::Circular { radius_m };
                Ok(())
            },
        ),
        E::new(
            &setting::AREA,
            |s, i| match s.bar(i).section {
                Section::Area { area_m2 } => number(area_m2),
                Section::Circular { .. } => None,
            },
            |s, t, v| {
                let area_m2 = t.number(v)?;
                s.bar_mut(t.owner).section = Section::Area { area_m2 };
                Ok(())
            },
        )
        .derived(|s, i| Some(s.bar(i).area_m2())),
        E::new(
            &setting::ADDED_MASS,
            |s, i| number(s.bar(i).added_mass_kg),
            |s, t, v| put(&mut s.bar_mut(t.owner).added_mass_kg, t.number(v)),
        ),
        E::new(
            &setting::VELOCITY,
            |s, i| number(s.bar(i).velocity_m_s),
            |s, t, v| put(&mut s.bar_mut(t.owner).velocity_m_s, t.number(v)),
        ),
        E::new(
            &setting::END_RADIUS,
            |s, i| match s.bar(i).end {
                EndShape::Rounded { radius_m } => number(radius_m),
                EndShape::Flat => setting::END_RADIUS.word().and_then(word),
            },
            |s, t, v| {
                let end = match v {
                    SettingValue::Number(r) => EndShape::Rounded { radius_m: *r },
                    SettingValue::Text(w) if Some(w.as_str()) == t.setting.word() => EndShape::Flat,
                    other => return Err(t.expected("a radius in m or flat", other)),
                };
                s.bar_mut(t.owner).end = end;
                Ok(())
            },
        ),
        E::new(
            &setting::CONTACT_LAW,
            |s, _| word(s.scenario.contact.law.name()),
            |s, t, v| put(&mut s.scenario.contact.law, t.choice(v, LawKind::from_name)),
        ),
        E::new(
            &setting::CONTACT_STIFFNESS,
            |s, _| s.scenario.contact.stiffness.and_then(number),
            |s, t, v| put(&mut s.scenario.contact.stiffness, t.number_or_word(v)),
        ),
        E::new(
            &setting::ZONE_SCALE,
            |s, _| number(s.scenario.contact.zone_scale),
            |s, t, v| put(&mut s.scenario.contact.zone_scale, t.number(v)),
        ),
        E::new(
            &setting::ZONE_LENGTH,
            |s, _| s.scenario.contact.zone_length_m.and_then(number),
            |s, t, v| put(&mut s.scenario.contact.zone_length_m, t.number_or_word(v)),
        ),
        E::new(
            &setting::DIVISIONS,
            |s, _| number(s.scenario.contact.divisions),
            |s, t, v| put(&mut s.scenario.contact.divisions, t.number(v)),
        ),
        E::new(
            &setting::RESTITUTION,
            |s, _| number(s.scenario.contact.restitution),
            |s, t, v| put(&mut s.scenario.contact.restitution, t.number(v)),
        ),
        E::new(
            &setting::SEARS_READING,
            |s, _| word(s.scenario.reading.name()),
            |s, t, v| put(&mut s.scenario.reading, t.choice(v, Reading::from_name)),
        ),
        E::new(
            &setting::DT,
            |s, _| number(s.scenario.solver.dt_s),
            |s, t, v| put(&mut s.scenario.solver.dt_s, t.number(v)),
        ),
        E::new(
            &setting::WINDOW,
            |s, _| number(s.scenario.solver.window_s),
            |s, t, v| put(&mut s.scenario.solver.window_s, t.number(v)),
        ),
        E::new(
            &setting::MAX_STEPS,
            |s, _| number(s.scenario.solver.max_steps as f64),
            |s, t, v| put(&mut s.scenario.solver.max_steps, t.count(v)),
        ),
        E::new(
            &setting::REFINE,
            |s, _| Some(SettingValue::Bool(s.scenario.solver.refine)),
            |s, t, v| put(&mut s.scenario.solver.refine, t.boolean(v)),
        ),
        E::new(
            &setting::FE_SEGMENTS,
            |s, _| number(s.scenario.fe.segments as f64),
            |s, t, v| put(&mut s.scenario.fe.segments, t.count(v)),
        ),
        E::new(
            &setting::FE_COURANT,
            |s, _| number(s.scenario.fe.courant),
            |s, t, v| put(&mut s.scenario.fe.courant, t.number(v)),
        ),
    ],
};
