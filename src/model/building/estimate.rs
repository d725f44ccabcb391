//! A building run's own error estimate: the same run with every discretisation parameter
//! refined at once (the contact step and the grid on which onsets are sought and peaks sampled
//! halved, the longest free step halved; the free motion is integrated exactly, so halving its
//! step changes it by round-off only), compared with the run itself.
//!
//! Why it bounds the error: if q* is the converged value and e(h) = q(h) - q*, then
//! |e(h)| <= |q(h) - q(h/2)| + |e(h/2)|. Where the method converges at order p >= 1,
//! |e(h/2)| <= |e(h)| / 2, so |e(h)| <= 2 |q(h) - q(h/2)|: twice the difference is a bound. The
//! contact steps are second order, so the bound is about 1.5 times the actual error.
//!
//! A run twice as coarse would cost a quarter as much, and |q(2h) - q(h)| = (2^p - 1) |e(h)| is
//! a bound under the same assumption; but at the default tolerance the coarse run is not yet in
//! that regime: on the paper's buildings its Hertz-damped max force moved by 1.4e-5 where the
//! run's actual error is 4.9e-5. The refined companion is what bounds the error.

use super::result::ImpactEvent;
use super::{BuildingResult, BuildingScenario};
use crate::model::control::Control;
use crate::model::error::SolveError;
use crate::model::impact::estimate::rel;
use crate::model::motion::GroundMotion;

/// Bounds on the relative errors of a run, and what changed with the refinement.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BuildingErrorEstimate {
    /// Bound on the max pounding force's relative error.
    pub max_force: f64,
    /// The largest over both roofs and every floor.
    pub peak_displacement: f64,
    /// The largest over the impacts' start times, relative to the time; 0 when the companion
    /// run has another count.
    pub impact_time: f64,
    /// This run's impacts minus the companion run's.
    pub impact_count_change: i64,
    /// Wall time of the companion run [s] (where it runs beside the run, as `pounding
    /// buildings` makes it, on a machine it shares with the run).
    pub wall_time_s: f64,
}

/// The same scenario with every discretisation parameter refined `factor`-fold (its step budget
/// kept: a run that would outgrow it is held to a coarser step, with a warning, so a reference
/// made this way must be checked for one).
pub fn refined(sc: &BuildingScenario, factor: f64) -> BuildingScenario {
    BuildingScenario {
        steps_per_scale: Some(sc.steps_per_scale() * factor),
        tolerance: sc.tolerance / (factor * factor),
        max_step_s: sc.max_step_s / factor,
        ..sc.clone()
    }
}

/// The run the estimate compares with: the contact step and the grid on which onsets are sought
/// and peaks sampled halved (every step the tolerance and the steps per contact time scale set,
/// with twice the step budget, so that a run held to its budget's step is refined too). The free
/// motion between contacts is exact whatever the length of its steps, so those keep theirs,
/// unless the grid cannot be halved within them. This is the scenario; the halving is the
/// companion run's ([`companion_run`]).
pub fn companion_scenario(sc: &BuildingScenario, fine_step_s: f64) -> BuildingScenario {
    if sc.max_step_s / (0.5 * fine_step_s) <= super::solve::MAX_FREE_STEP as f64 {
        sc.clone()
    } else {
        BuildingScenario {
            max_step_s: sc.max_step_s / 2.0,
            ..sc.clone()
        }
    }
}

/// The estimate for run `r` of `sc`: twice its difference from the refined run.
pub fn estimate_error(
    sc: &BuildingScenario,
    motion: &GroundMotion,
    r: &BuildingResult,
) -> Result<BuildingErrorEstimate, SolveError> {
    estimate_error_with(sc, motion, r, Control::never())
}

/// [`estimate_error`], its solve reporting to `control`.
pub fn estimate_error_with(
    sc: &BuildingScenario,
    motion: &GroundMotion,
    r: &BuildingResult,
    control: &Control,
) -> Result<BuildingErrorEstimate, SolveError> {
    let start = std::time::Instant::now();
    let fine = companion_run(sc, motion, r.stats.fine_step_s, control)?;
    Ok(estimate_from(r, &fine, start.elapsed().as_secs_f64()))
}

/// The companion run of a run whose fine step is `fine_step_s` ([`companion_scenario`]), keeping only
/// what the estimate compares: the floors' peaks (the drifts' are not followed), the impacts and
/// the forces.
pub fn companion_run(
    sc: &BuildingScenario,
    motion: &GroundMotion,
    fine_step_s: f64,
    control: &Control,
) -> Result<BuildingResult, SolveError> {
    super::solve::solve_summary_refined(
        &companion_scenario(sc, fine_step_s),
        motion,
        control,
        super::Tracked::Floors,
        2,
    )
}

/// The estimate for run `r` from its companion run `fine` (which took `wall_time_s`): twice
/// their difference.
pub fn estimate_from(
    r: &BuildingResult,
    fine: &BuildingResult,
    wall_time_s: f64,
) -> BuildingErrorEstimate {
    let mut e = compare(r, fine);
    e.max_force *= 2.0;
    e.peak_displacement *= 2.0;
    e.impact_time *= 2.0;
    e.wall_time_s = wall_time_s;
    e
}

/// The relative differences between two runs of the same scenario (`reference` the other
/// discretisation).
pub fn compare(r: &BuildingResult, reference: &BuildingResult) -> BuildingErrorEstimate {
    let peak = (0..2)
        .flat_map(|s| {
            r.peak_floor_displacement_m[s]
                .iter()
                .zip(&reference.peak_floor_displacement_m[s])
                .map(|(a, b)| rel(*a, *b))
        })
        .fold(0.0, f64::max);
    let impact_time = impact_time_change(&r.impacts, &reference.impacts);
    BuildingErrorEstimate {
        max_force: rel(r.max_pounding_force_n, reference.max_pounding_force_n),
        peak_displacement: peak,
        impact_time,
        impact_count_change: r.impacts.len() as i64 - reference.impacts.len() as i64,
        wall_time_s: 0.0,
    }
}

/// The largest relative change of the impacts' start times between two runs; 0 when their
/// counts differ (the impacts then do not pair up).
pub fn impact_time_change(a: &[ImpactEvent], b: &[ImpactEvent]) -> f64 {
    if a.len() != b.len() {
        return 0.0;
    }
    a.iter()
        .zip(b)
        .map(|(x, y)| rel(x.start_s, y.start_s))
        .fold(0.0, f64::max)
}
