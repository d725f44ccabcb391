//! One impact setting varied over a range: peak force, contact duration and e against it for each
//! model. The command line's `pounding sweep` and the window's Parameter study run this.

use super::{Cancelled, Progress, par_map};
use crate::io::settings::{IMPACT_KEYS, ImpactSetup};
use crate::model::impact::{ModelKind, solve};
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
}

/// The swept values: linear or geometric, ends included.
pub fn values(from: f64, to: f64, count: usize, log: bool) -> Vec<f64> {
    (0..count)
        .map(|i| {
            let f = i as f64 / (count.max(2) - 1) as f64;
            if log {
                (from.ln() + f * (to.ln() - from.ln())).exp()
            } else {
                from + f * (to - from)
            }
        })
        .collect()
}

/// The numeric impact keys a sweep can vary (both bars spelled out).
pub fn numeric_keys() -> Vec<String> {
    const WORDS: [&str; 5] = ["model", "material", "law", "reading", "refine"];
    IMPACT_KEYS
        .iter()
        .filter(|(k, _)| !WORDS.iter().any(|w| k.ends_with(w)))
        .flat_map(|(k, _)| match k.strip_prefix("barN.") {
            Some(rest) => vec![format!("bar1.{rest}"), format!("bar2.{rest}")],
            None => vec![k.to_string()],
        })
        .collect()
}

/// The range, checked; errors name the flag (or field) at fault.
pub fn check(param: &str, from: f64, to: f64, count: usize, log: bool) -> Result<(), String> {
    if !numeric_keys().iter().any(|k| k == param) {
        return Err(format!(
            "--param: '{param}' is not a numeric impact setting; see `pounding sweep --list-keys`"
        ));
    }
    if !(2..=100_000).contains(&count) {
        return Err(format!("--count: {count} is outside 2 to 100000"));
    }
    if !from.is_finite() || !to.is_finite() {
        return Err("--from/--to: values must be finite numbers".into());
    }
    if log && (from <= 0.0 || to <= 0.0) {
        return Err(format!(
            "--log: --from and --to must be > 0 (got {from} and {to})"
        ));
    }
    Ok(())
}

/// The base setup with `param` set to each value, every one validated before any solve so a bad
/// range fails at once and names the value.
pub fn setups(base: &ImpactSetup, param: &str, values: &[f64]) -> Result<Vec<ImpactSetup>, String> {
    values
        .iter()
        .map(|v| {
            let mut s = *base;
            s.apply_assignment(&format!("{param}={v}"))
                .and_then(|()| s.scenario.validate())
                .map(|()| s)
                .map_err(|e| format!("--param {param}={v}: {e}"))
        })
        .collect()
}

/// Every (model, value) point solved in parallel; a point whose solve fails carries the error.
pub fn run(
    setups: &[ImpactSetup],
    values: &[f64],
    models: &[ModelKind],
    progress: &Progress,
) -> Result<Vec<Point>, Cancelled> {
    let jobs: Vec<(ModelKind, usize)> = models
        .iter()
        .flat_map(|&m| (0..setups.len()).map(move |i| (m, i)))
        .collect();
    par_map(progress, &jobs, |&(model, i)| {
        let value = values[i];
        let name = model.name().to_string();
        match solve(model, &setups[i].scenario) {
            Ok(r) => Point {
                model: name,
                value,
                peak_force_n: r.peak_force_n,
                contact_duration_s: Some(r.contact_duration_s),
                restitution: Some(r.restitution),
                contacts: Some(r.contacts.len()),
                error: None,
            },
            Err(e) => Point {
                model: name,
                value,
                peak_force_n: None,
                contact_duration_s: None,
                restitution: None,
                contacts: None,
                error: Some(e.to_string()),
            },
        }
    })
}
