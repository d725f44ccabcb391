//! A run with its checks, as `pounding buildings` reports it: the run, its error estimate and
//! the same buildings without contact. The estimate's companion run needs only the run's fine
//! step, which is planned before the run, and the run without contact needs nothing of it: both
//! go on a second thread while the run solves, so on two cores the whole takes about as long as
//! the companion (twice the run's contact steps) instead of the three one after another.

use super::estimate::{companion_run, estimate_from};
use super::{BuildingErrorEstimate, BuildingResult, BuildingScenario, ContactModel};
use crate::model::control::Control;
use crate::model::error::SolveError;
use crate::model::motion::GroundMotion;

/// A run, its error estimate (none where the companion run failed) and the run without contact.
#[derive(Debug, Clone)]
pub struct Checked {
    /// The run, with its histories.
    pub result: BuildingResult,
    /// Its error estimate.
    pub estimate: Option<BuildingErrorEstimate>,
    /// The same buildings without contact, with their histories.
    pub baseline: BuildingResult,
}

/// Runs `sc` with its checks side by side, each bit for bit what it is alone. `control` sees the
/// run as the first half of the job and the checks left when it ends as the second; cancelling
/// it stops all three.
pub fn solve_checked(
    sc: &BuildingScenario,
    motion: &GroundMotion,
    control: &Control,
) -> Result<Checked, SolveError> {
    let fine_step_s = super::solve::planned_step_s(sc, motion)?;
    let checks = Control::new();
    let without_contact = BuildingScenario {
        contact: ContactModel::None,
        ..sc.clone()
    };
    let (checks, without_contact) = (&checks, &without_contact);
    std::thread::scope(|scope| {
        let (done, ended) = std::sync::mpsc::channel::<()>();
        let side = scope.spawn(move || {
            let start = std::time::Instant::now();
            checks.stage(0, 2);
            let fine = companion_run(sc, motion, fine_step_s, checks);
            let wall = start.elapsed().as_secs_f64();
            checks.stage(1, 2);
            let baseline = super::solve_with(without_contact, motion, checks);
            let _ = done.send(());
            (fine, wall, baseline)
        });
        control.stage(0, 2);
        let result = super::solve_with(sc, motion, control);
        if result.is_err() {
            checks.cancel();
        } else {
            control.stage(1, 2);
            // Passes the checks' progress on, and a cancel back, until they end.
            while let Err(std::sync::mpsc::RecvTimeoutError::Timeout) =
                ended.recv_timeout(std::time::Duration::from_millis(10))
            {
                if control.report(checks.fraction()).is_err() {
                    checks.cancel();
                }
            }
        }
        let (fine, wall, baseline) = match side.join() {
            Ok(v) => v,
            Err(panic) => std::panic::resume_unwind(panic),
        };
        let result = result?;
        if control.cancelled() {
            return Err(SolveError::Cancelled);
        }
        // The plan is the run's own: a companion refined from another step would not be the
        // estimate's (never seen; made again after the run rather than trusted).
        let estimate = if result.stats.fine_step_s == fine_step_s {
            fine.ok().map(|f| estimate_from(&result, &f, wall))
        } else {
            super::estimate_error_with(sc, motion, &result, control).ok()
        };
        Ok(Checked {
            estimate,
            baseline: baseline?,
            result,
        })
    })
}
