//! A run with its checks, as `pounding buildings` reports it: the run, its error estimate and
//! the same buildings without contact. The estimate's companion run needs only the run's fine
//! step, which is planned before the run, and the run without contact needs nothing of it: both
//! go on a second thread while the run solves, so on two cores the whole takes about as long as
//! the companion (twice the run's contact steps) instead of the three one after another.

use super::estimate::{companion_run, estimate_from};
use super::{BuildingErrorEstimate, BuildingResult, BuildingScenario, ContactModel};
use crate::model::control::{Control, spawn_told};
use crate::model::error::SolveError;
use crate::model::motion::GroundMotion;

/// A run, its error estimate (none where the companion run failed) and the run without contact.
#[derive(Debug, Clone)]
pub struct Checked {
    /// The run, with its histories (none from [`solve_checked_summary`]).
    pub result: BuildingResult,
    /// Its error estimate.
    pub estimate: Option<BuildingErrorEstimate>,
    /// The same buildings without contact, with their histories (as the run's). A comparison:
    /// it does not search for each level's largest closing (its `max_closing_m` is empty; a gap
    /// assessment needs a run of its own, as [`super::solve()`] makes it).
    pub baseline: BuildingResult,
}

/// Runs `sc` with its checks side by side, each bit for bit what it is alone (the run without
/// contact every peak and history, less the search for its largest closings). `control` sees the
/// run as the first half of the job and the checks left when it ends as the second; cancelling
/// it stops all three.
pub fn solve_checked(
    sc: &BuildingScenario,
    motion: &GroundMotion,
    control: &Control,
) -> Result<Checked, SolveError> {
    solve_checked_with(sc, motion, control, &Control::new())
}

/// [`solve_checked`] for a report that reads only the runs' summaries (their impacts, peaks,
/// forces, energy and warnings): the run and the run without contact keep no histories, and
/// every number in them is bit for bit the full runs' (recording reads the state, never moves
/// it). `pounding buildings --json` without a plot, a CSV or an animation needs no more.
pub fn solve_checked_summary(
    sc: &BuildingScenario,
    motion: &GroundMotion,
    control: &Control,
) -> Result<Checked, SolveError> {
    checked_keeping(sc, motion, control, &Control::new(), false)
}

/// [`solve_checked`], the checks (the companion, then the run without contact) reporting to
/// `checks`: cancelled wherever the run ends without a result, or `control` is cancelled.
pub fn solve_checked_with(
    sc: &BuildingScenario,
    motion: &GroundMotion,
    control: &Control,
    checks: &Control,
) -> Result<Checked, SolveError> {
    checked_keeping(sc, motion, control, checks, true)
}

/// The run and its checks, the run and the run without contact with their histories where
/// `histories` asks for them.
fn checked_keeping(
    sc: &BuildingScenario,
    motion: &GroundMotion,
    control: &Control,
    checks: &Control,
    histories: bool,
) -> Result<Checked, SolveError> {
    let run = |sc: &BuildingScenario, control: &Control| {
        if histories {
            super::solve_with(sc, motion, control)
        } else {
            super::solve::solve_summary_with(sc, motion, control)
        }
    };
    let fine_step_s = super::solve::planned_step_s(sc, motion)?;
    let without_contact = BuildingScenario {
        contact: ContactModel::None,
        ..sc.clone()
    };
    let without_contact = &without_contact;
    std::thread::scope(|scope| {
        let side = spawn_told(scope, move || {
            let start = std::time::Instant::now();
            checks.stage(0, 2);
            let fine = companion_run(sc, motion, fine_step_s, checks);
            let wall = start.elapsed().as_secs_f64();
            checks.stage(1, 2);
            let baseline =
                super::solve::solve_comparison(without_contact, motion, checks, histories);
            (fine, wall, baseline)
        });
        // Whatever ends the run without a result (an error, a cancel, a panic) stops the
        // checks too, rather than waiting for them to finish.
        let stop_checks = CancelOnDrop(checks);
        control.stage(0, 2);
        let result = run(sc, control)?;
        control.stage(1, 2);
        // Passes the checks' progress on, and a cancel back, until they end.
        let checked = side.wait_looking(std::time::Duration::from_millis(10), || {
            if control.report(checks.fraction()).is_err() {
                checks.cancel();
            }
        });
        std::mem::forget(stop_checks);
        let (fine, wall, baseline) = match checked {
            Ok(v) => v,
            Err(panic) => std::panic::resume_unwind(panic),
        };
        if control.cancelled() {
            return Err(SolveError::Cancelled);
        }
        // The companion was refined from the run's own plan (the same pure function of the
        // scenario and the record), so it is the estimate's.
        debug_assert_eq!(
            result.stats.fine_step_s.to_bits(),
            fine_step_s.to_bits(),
            "the run's step is the planned one"
        );
        Ok(Checked {
            estimate: fine.ok().map(|f| estimate_from(&result, &f, wall)),
            baseline: baseline?,
            result,
        })
    })
}

/// Cancels a control when dropped (unless forgotten).
struct CancelOnDrop<'a>(&'a Control);

impl Drop for CancelOnDrop<'_> {
    fn drop(&mut self) {
        self.0.cancel();
    }
}
