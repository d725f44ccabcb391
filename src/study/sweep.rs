//! One impact setting varied over a range: peak force, contact duration and e against it for each
//! model. The command line's `pounding sweep` and the window's Parameter study run this.

use super::{Cancelled, Control, par_map};
use crate::io::settings::ImpactSetup;
use crate::model::error::InputError;
use crate::model::impact::{ModelKind, Workspace, summary_with};
use crate::model::settings::{IMPACT_SETTINGS, Kind, concrete_keys};
use serde::Serialize;

#[derive(Serialize, Debug, Clone, PartialEq)]
pub struct Point {
    pub model: String,
    pub value: f64,
    pub peak_force_n: Option<f64>,
    pub contact_duration_s: Option<f64>,
    pub restitution: Option<f64>,
    pub contacts: Option<usize>,
    /// Why this point has no result (a solver error), if so.
    pub error: Option<String>,
    /// Why a point that solved has no restitution (the bars never met), if so.
    pub no_restitution: Option<String>,
}

/// The swept values: linear or geometric, ends included.
pub fn values(from: f64, to: f64, count: usize, log: bool) -> Vec<f64> {
    (0..count)
        .map(|i| {
            let f = i as f64 / (count.max(2) - 1) as f64;
            // The ends are the user's own values, exactly: exp(ln x) can land an ulp outside a
            // key's range. Rounding inside is held within the ends for the same reason.
            if i == 0 {
                from
            } else if i + 1 == count {
                to
            } else if log {
                (from.ln() + f * (to.ln() - from.ln()))
                    .exp()
                    .clamp(from.min(to), from.max(to))
            } else {
                (from + f * (to - from)).clamp(from.min(to), from.max(to))
            }
        })
        .collect()
}

/// The numeric impact keys a sweep can vary (both bars spelled out), from the settings table.
pub fn numeric_keys() -> Vec<String> {
    let numeric: Vec<_> = IMPACT_SETTINGS
        .iter()
        .filter(|s| matches!(s.kind, Kind::Number { .. } | Kind::Count { .. }))
        .copied()
        .collect();
    concrete_keys(&numeric)
}

/// What is wrong with a sweep, by the part of it at fault; each front end names that part its
/// own way (a flag, a field).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SweepError {
    #[error("'{0}' is not a numeric impact setting")]
    NotNumeric(String),
    #[error("'{0}' is not a numeric building setting")]
    NotNumericBuilding(String),
    #[error("{0} values is outside 2 to 100000")]
    Count(usize),
    #[error("the ends of the range must be finite numbers")]
    NotFinite,
    #[error("a geometric range needs both ends > 0 (got {from} and {to})")]
    Geometric { from: f64, to: f64 },
    /// One swept value that the setting refuses.
    #[error("{param}={value}: {source}")]
    Value {
        param: String,
        value: f64,
        source: InputError,
    },
}

/// Which part of a sweep an error is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Part {
    Param,
    Count,
    Range,
    Spacing,
    Value,
}

impl SweepError {
    pub fn part(&self) -> Part {
        match self {
            SweepError::NotNumeric(_) | SweepError::NotNumericBuilding(_) => Part::Param,
            SweepError::Count(_) => Part::Count,
            SweepError::NotFinite => Part::Range,
            SweepError::Geometric { .. } => Part::Spacing,
            SweepError::Value { .. } => Part::Value,
        }
    }
}

/// The sweep's range, checked.
pub fn check(param: &str, from: f64, to: f64, count: usize, log: bool) -> Result<(), SweepError> {
    if !numeric_keys().iter().any(|k| k == param) {
        return Err(SweepError::NotNumeric(param.to_string()));
    }
    check_range(from, to, count, log)
}

/// The count and the ends of a sweep's range, checked.
pub(super) fn check_range(from: f64, to: f64, count: usize, log: bool) -> Result<(), SweepError> {
    if !(2..=100_000).contains(&count) {
        return Err(SweepError::Count(count));
    }
    if !from.is_finite() || !to.is_finite() {
        return Err(SweepError::NotFinite);
    }
    if log && (from <= 0.0 || to <= 0.0) {
        return Err(SweepError::Geometric { from, to });
    }
    Ok(())
}

/// The base setup with `param` set to each value, every one validated before any solve so a bad
/// range fails at once and names the value.
pub fn setups(
    base: &ImpactSetup,
    param: &str,
    values: &[f64],
) -> Result<Vec<ImpactSetup>, SweepError> {
    each_value(base, param, values, |s, assignment| {
        s.apply_assignment(assignment)
            .and_then(|()| s.scenario.validate())
    })
}

/// `base` with `param` set to each value by `apply` (which also validates the result); the
/// first value refused names itself.
pub(super) fn each_value<S: Clone>(
    base: &S,
    param: &str,
    values: &[f64],
    apply: impl Fn(&mut S, &str) -> Result<(), InputError>,
) -> Result<Vec<S>, SweepError> {
    values
        .iter()
        .map(|v| {
            let mut s = base.clone();
            apply(&mut s, &format!("{param}={v}"))
                .map(|()| s)
                .map_err(|source| SweepError::Value {
                    param: param.to_string(),
                    value: *v,
                    source,
                })
        })
        .collect()
}

thread_local! {
    /// Each worker thread's Sears workspace, kept from one point to the next.
    static WORKSPACE: std::cell::RefCell<Workspace> = std::cell::RefCell::new(Workspace::default());
}

/// Every (model, value) point solved in parallel; a point whose solve fails carries the error.
pub fn run(
    setups: &[ImpactSetup],
    values: &[f64],
    models: &[ModelKind],
    progress: &Control,
) -> Result<Vec<Point>, Cancelled> {
    let jobs: Vec<(ModelKind, usize)> = models
        .iter()
        .flat_map(|&m| (0..setups.len()).map(move |i| (m, i)))
        .collect();
    par_map(progress, &jobs, |&(model, i)| {
        let value = values[i];
        let name = model.name().to_string();
        // The summary path, through this thread's workspace: no histories, and no allocation
        // once the thread has solved a run as long.
        let outcome =
            WORKSPACE.with(|ws| summary_with(model, &setups[i].scenario, &mut ws.borrow_mut()));
        match outcome {
            // Without an impact the velocities are the ones the bars started with: their ratio
            // is no coefficient of restitution.
            Ok(r) => Point {
                model: name,
                value,
                peak_force_n: r.peak_force_n,
                contact_duration_s: Some(r.contact_duration_s),
                restitution: r.impact.then_some(r.restitution),
                contacts: Some(r.contacts),
                error: None,
                no_restitution: (!r.impact)
                    .then(|| "no impact: the bars never met in the simulated time".to_string()),
            },
            Err(e) => Point {
                model: name,
                value,
                peak_force_n: None,
                contact_duration_s: None,
                restitution: None,
                contacts: None,
                error: Some(e.to_string()),
                no_restitution: None,
            },
        }
    })
}
