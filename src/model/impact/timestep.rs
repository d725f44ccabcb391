//! The contact's own time scale, and the step a run uses.

use super::{KeptBecause, Warning};
use crate::model::contact::{ContactLaw, LawKind};
use crate::model::scenario::ImpactScenario;

/// Time scales of a contact between bodies of effective mass `m_eff` and (for elastic bars)
/// effective impedance `z_eff` (infinite for rigid bodies), at approach velocity `w`.
#[derive(Debug, Clone, Copy)]
pub struct TimeScale {
    /// The shortest time over which the force changes appreciably [s].
    pub resolve_s: f64,
    /// Contact duration of the lumped-mass limit [s].
    pub lumped_duration_s: f64,
}

/// The time scales of a contact law between effective mass `m_eff` and impedance `z_eff` approaching at `w`.
pub fn contact_time_scale(law: &ContactLaw, w: f64, m_eff: f64, z_eff: f64) -> TimeScale {
    let k = law.stiffness;
    let (f_lumped, lumped_duration_s) = match law.kind {
        LawKind::Hertz => {
            let dmax = (5.0 * m_eff * w * w / (4.0 * k)).powf(0.4);
            (k * dmax.powf(1.5), 2.9432 * dmax / w)
        }
        LawKind::Linear => (
            w * (k * m_eff).sqrt(),
            std::f64::consts::PI * (m_eff / k).sqrt(),
        ),
    };
    let f_est = f_lumped.min(z_eff * w);
    // Rise time of a wave-limited force: Z_eff / k_t (infinite for rigid bodies).
    let rise = z_eff / law.tangent_at_force(f_est);
    TimeScale {
        resolve_s: rise.min(lumped_duration_s / (2.0 * std::f64::consts::PI)),
        lumped_duration_s,
    }
}

/// The step a run uses: the user's, or a refined one where the user's is coarser than the
/// contact's time scale and the refined run fits the step budget.
pub(crate) struct StepChoice {
    pub dt_s: f64,
    pub refined_from_s: Option<f64>,
    pub warning: Option<Warning>,
}

pub(crate) fn choose_step(
    sc: &ImpactScenario,
    scale: TimeScale,
    expected_span_s: f64,
) -> StepChoice {
    let dt = sc.solver.dt_s;
    let resolve = scale.resolve_s;
    // At least two steps per time scale (one step per time scale left energy errors of 6e-3 on
    // a short bar ringing through its contact; two, 2e-4); a refined run gets four.
    if !(resolve.is_finite() && resolve > 0.0) || dt <= 0.5 * resolve {
        return StepChoice {
            dt_s: dt,
            refined_from_s: None,
            warning: None,
        };
    }
    let factor = (4.0 * dt / resolve).ceil();
    let refined = dt / factor;
    let span = if sc.solver.window_s > 0.0 {
        sc.solver.window_s
    } else {
        expected_span_s
    };
    let steps = span / refined;
    if sc.solver.refine && steps <= sc.solver.max_steps as f64 {
        StepChoice {
            dt_s: refined,
            refined_from_s: Some(dt),
            warning: Some(Warning::StepRefined {
                dt_s: dt,
                scale_s: resolve,
                refined_s: refined,
            }),
        }
    } else {
        let because = if sc.solver.refine {
            KeptBecause::Budget {
                refined_s: refined,
                steps,
                max_steps: sc.solver.max_steps,
            }
        } else {
            KeptBecause::RefineOff
        };
        StepChoice {
            dt_s: dt,
            refined_from_s: None,
            warning: Some(Warning::StepKept {
                dt_s: dt,
                scale_s: resolve,
                because,
            }),
        }
    }
}
