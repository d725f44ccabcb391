//! A bridge run's own error estimate: the same run with its step halved (twice the steps per
//! contact time scale and half the longest step), compared with the run itself. As for the
//! buildings (`building::estimate`): where the method converges at order p >= 1, twice the
//! difference bounds the run's error.

use super::{BridgeResult, BridgeScenario};
use crate::model::building::estimate::impact_time_change;
use crate::model::control::Control;
use crate::model::error::SolveError;
use crate::model::impact::estimate::rel;
use crate::model::motion::GroundMotion;

/// Bounds on the relative errors of a run.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BridgeErrorEstimate {
    /// Bound on the max joint force's relative error.
    pub max_force: f64,
    /// The largest over every girder's, pier's and bearing's peak.
    pub peak_displacement: f64,
    /// The largest over the joints' largest openings.
    pub opening: f64,
    /// The largest over the impacts' start times, relative to the time; 0 when the companion
    /// run has another count.
    pub impact_time: f64,
    /// This run's impacts minus the companion run's.
    pub impact_count_change: i64,
    /// Wall time of the companion run [s].
    pub wall_time_s: f64,
}

/// The same scenario with its step refined by `factor`.
pub fn refined(sc: &BridgeScenario, factor: f64) -> BridgeScenario {
    BridgeScenario {
        steps_per_scale: Some(sc.steps_per_scale() * factor),
        max_step_s: sc.max_step_s / factor,
        // The refined run needs the steps the run had room for, times the factor (within the
        // budget's range).
        max_steps: sc
            .max_steps
            .saturating_mul(factor.ceil() as usize)
            .min(100_000_000),
        ..sc.clone()
    }
}

/// The estimate for run `r` of `sc`: twice its difference from the run with half the step.
pub fn estimate_error(
    sc: &BridgeScenario,
    motion: &GroundMotion,
    r: &BridgeResult,
    control: &Control,
) -> Result<BridgeErrorEstimate, SolveError> {
    let start = std::time::Instant::now();
    let fine = super::solve::solve_summary(&refined(sc, 2.0), motion, control)?;
    let mut e = compare(r, &fine);
    e.max_force *= 2.0;
    e.peak_displacement *= 2.0;
    e.opening *= 2.0;
    e.impact_time *= 2.0;
    e.wall_time_s = start.elapsed().as_secs_f64();
    Ok(e)
}

fn largest(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| rel(*x, *y))
        .fold(0.0, f64::max)
}

/// The relative differences between two runs of the same scenario.
pub fn compare(r: &BridgeResult, reference: &BridgeResult) -> BridgeErrorEstimate {
    let peak = largest(
        &r.peak_girder_displacement_m,
        &reference.peak_girder_displacement_m,
    )
    .max(largest(
        &r.peak_pier_displacement_m,
        &reference.peak_pier_displacement_m,
    ))
    .max(largest(
        &r.peak_bearing_displacement_m,
        &reference.peak_bearing_displacement_m,
    ));
    let impact_time = impact_time_change(&r.impacts, &reference.impacts);
    BridgeErrorEstimate {
        max_force: rel(r.max_pounding_force_n, reference.max_pounding_force_n),
        peak_displacement: peak,
        opening: largest(&r.max_opening_m, &reference.max_opening_m),
        impact_time,
        impact_count_change: r.impacts.len() as i64 - reference.impacts.len() as i64,
        wall_time_s: 0.0,
    }
}
