//! Each result's own error estimate, by step doubling: the same impact with twice the step (half
//! the mesh for FE), and Richardson's estimate |q(h) - q(2h)| / (2^p - 1) with the design order
//! p = 2 of every stepped model here. Wave theory and stereomechanics are exact.

use super::{ImpactResult, ModelKind, SolveError};
use crate::model::control::Control;
use crate::model::scenario::ImpactScenario;
use std::time::Instant;

/// Estimated errors, relative to the values (absolute for the restitution).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ErrorEstimate {
    /// Peak force, relative.
    pub peak_force: f64,
    /// Contact duration, relative.
    pub contact_duration: f64,
    /// Impulse, relative.
    pub impulse: f64,
    /// Absolute error of e.
    pub restitution: f64,
    /// What the estimate compared: "step" or "mesh" doubling, or "exact".
    pub method: &'static str,
    /// Wall time of the extra solve [s].
    pub wall_time_s: f64,
}

/// |a - b| relative to b (absolute where b is 0): how the estimates compare two runs.
pub fn rel(a: f64, b: f64) -> f64 {
    if b == 0.0 {
        (a - b).abs()
    } else {
        ((a - b) / b).abs()
    }
}

/// The estimate for `result`, solved from `scenario` with `model`.
pub fn estimate_error(
    model: ModelKind,
    scenario: &ImpactScenario,
    result: &ImpactResult,
) -> Result<ErrorEstimate, SolveError> {
    estimate_error_with(model, scenario, result, Control::never())
}

/// [`estimate_error`], its solve reporting to `control`.
pub fn estimate_error_with(
    model: ModelKind,
    scenario: &ImpactScenario,
    result: &ImpactResult,
    control: &Control,
) -> Result<ErrorEstimate, SolveError> {
    if matches!(model, ModelKind::Wave | ModelKind::Stereo) || !result.impact {
        return Ok(ErrorEstimate {
            method: "exact",
            ..Default::default()
        });
    }
    let mut coarse = *scenario;
    let method = if model == ModelKind::Fe {
        coarse.fe.segments = (scenario.fe.segments / 2).max(1);
        "mesh"
    } else {
        // Double the step actually used (it may have been refined), and keep it.
        coarse.solver.dt_s = 2.0 * result.stats.dt_s;
        coarse.solver.refine = false;
        "step"
    };
    let start = Instant::now();
    let c = super::solve_with(model, &coarse, control)?;
    let wall_time_s = start.elapsed().as_secs_f64();
    let factor = 1.0 / (2f64.powi(2) - 1.0);
    Ok(ErrorEstimate {
        peak_force: rel(
            result.peak_force_n.unwrap_or(0.0),
            c.peak_force_n.unwrap_or(0.0),
        ) * factor,
        contact_duration: rel(result.contact_duration_s, c.contact_duration_s) * factor,
        impulse: rel(result.impulse_ns, c.impulse_ns) * factor,
        restitution: (result.restitution - c.restitution).abs() * factor,
        method,
        wall_time_s,
    })
}
