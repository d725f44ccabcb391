//! One building setting varied over a range: the pounding, the sway and, where storeys yield,
//! the ductility demand and the energy the storeys dissipated against it. The command line's
//! `pounding sweep --buildings` and the window's Parameter study run this.

use super::sweep::{SweepError, check_range, each_value};
use super::{Cancelled, Control, par_map};
use crate::io::building_settings::BuildingSetup;
use crate::model::building::solve_summary;
use crate::model::settings::{BUILDING_SETTINGS, Kind, Setting, concrete_keys};
use serde::Serialize;

/// One swept value's run (`None` where it failed, with the error).
#[derive(Serialize, Debug, Clone, PartialEq, Default)]
pub struct BuildingPoint {
    pub value: f64,
    pub impact_count: Option<usize>,
    pub max_pounding_force_n: Option<f64>,
    pub peak_displacement_left_m: Option<f64>,
    pub peak_displacement_right_m: Option<f64>,
    /// The largest over the side's storeys.
    pub max_ductility_left: Option<f64>,
    pub max_ductility_right: Option<f64>,
    /// Summed over both buildings' storeys.
    pub hysteretic_energy_j: Option<f64>,
    /// The largest |residual drift| over both buildings' storeys.
    pub max_residual_drift_m: Option<f64>,
    pub error: Option<String>,
}

/// The numeric building keys a sweep can vary (both sides spelled out; a per-storey list takes
/// the swept value for every storey), from the settings table.
pub fn numeric_keys() -> Vec<String> {
    concrete_keys(&numeric_settings())
}

/// The settings a sweep can vary: those that take a number (or one for every storey).
pub fn numeric_settings() -> Vec<Setting> {
    BUILDING_SETTINGS
        .iter()
        .filter(|s| {
            matches!(
                s.kind,
                Kind::Number { .. } | Kind::List { .. } | Kind::Count { .. }
            )
        })
        .copied()
        .collect()
}

/// The sweep's parameter and range, checked.
pub fn check(param: &str, from: f64, to: f64, count: usize, log: bool) -> Result<(), SweepError> {
    if !numeric_keys().iter().any(|k| k == param) {
        return Err(SweepError::NotNumericBuilding(param.to_string()));
    }
    check_range(from, to, count, log)
}

/// The base setup with `param` set to each value, every one validated before any solve.
pub fn setups(
    base: &BuildingSetup,
    param: &str,
    values: &[f64],
) -> Result<Vec<BuildingSetup>, SweepError> {
    each_value(base, param, values, |s, assignment| {
        s.apply_assignment(assignment)
            .and_then(|()| s.scenario.validate())
    })
}

/// Every point solved in parallel (each its own record, read or generated once per point: a
/// swept motion key changes it); a point whose solve fails carries the error.
pub fn run(
    setups: &[BuildingSetup],
    values: &[f64],
    progress: &Control,
) -> Result<Vec<BuildingPoint>, Cancelled> {
    let jobs: Vec<usize> = (0..setups.len()).collect();
    par_map(progress, &jobs, |&i| point(&setups[i], values[i]))
}

fn point(setup: &BuildingSetup, value: f64) -> BuildingPoint {
    let solved = crate::io::motion::load(&setup.motion)
        .map_err(|e| e.to_string())
        .and_then(|m| solve_summary(&setup.scenario, &m).map_err(|e| e.to_string()));
    let r = match solved {
        Ok(r) => r,
        Err(e) => {
            return BuildingPoint {
                value,
                error: Some(e),
                ..Default::default()
            };
        }
    };
    let largest = |v: &[f64]| v.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    BuildingPoint {
        value,
        impact_count: Some(r.impacts.len()),
        max_pounding_force_n: Some(r.max_pounding_force_n),
        peak_displacement_left_m: Some(r.peak_displacement_m[0]),
        peak_displacement_right_m: Some(r.peak_displacement_m[1]),
        max_ductility_left: Some(largest(&r.ductility_demand[0])),
        max_ductility_right: Some(largest(&r.ductility_demand[1])),
        hysteretic_energy_j: Some(r.hysteretic_energy_j.iter().flatten().sum()),
        max_residual_drift_m: Some(
            largest(&r.residual_drift_m[0]).max(largest(&r.residual_drift_m[1])),
        ),
        error: None,
    }
}
