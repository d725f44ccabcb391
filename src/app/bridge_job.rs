//! The Bridge pounding scene's solve, in the order the scene shows it: the run (streamed while
//! it solves), then the run without contact (the gaps each joint needs, the displacements
//! compared), then the error estimate (the run with half the step, the slowest). Each stage is
//! handed over as it lands, so the run is on screen before the checks that follow it.

use super::bridge_view::BridgeDrawing;
use super::worker::Stages;
use crate::io::bridge_settings::BridgeSetup;
use crate::model::bridge::{
    BridgeErrorEstimate, BridgeResult, BridgeScenario, estimate_error, solve_streaming, solve_with,
};
use crate::model::building::ContactModel;
use crate::model::control::Control;
use crate::model::error::SolveError;

/// One stage of a bridge job, in the order they come.
pub(super) enum Stage {
    /// The run solved so far (its `solved_to_s` short of its end); any number of them.
    Partial(Box<BridgeDrawing>),
    /// The run, whole.
    Run(Box<BridgeDrawing>),
    /// The run without contact.
    Baseline(Box<BridgeResult>),
    /// The run's error estimate, the job's last (`None` where it could not be worked out).
    Estimate(Option<BridgeErrorEstimate>),
}

/// How much wall time passes between two parts of a run shown while it solves. Each part is a
/// drawing (the girders' waves put on their grid): a run that lands within a quarter second
/// (bridge-3-span) is shown whole, without slowing it down to show it half done.
const PUBLISH_EVERY: std::time::Duration = std::time::Duration::from_millis(250);

pub(super) type Output = Result<Stage, JobError>;
use super::job_error::JobError;

/// The job: its stages go to `stages`, its last is returned. The drawing (the girders' waves
/// on their GPU grid) is made here, off the UI thread.
pub(super) fn run_job(setup: BridgeSetup, control: &Control, stages: &Stages<Output>) -> Output {
    let (motion, stats) = super::motion_cache::load(&setup.motion)?;
    control.stage(0, 3);
    let result = solve_streaming(
        &setup.scenario,
        &motion,
        control,
        PUBLISH_EVERY,
        &mut |so_far| {
            let drawing = BridgeDrawing::with_stats(setup.clone(), motion.clone(), so_far, stats);
            stages.send(Ok(Stage::Partial(Box::new(drawing))));
        },
    )?;
    let run = BridgeDrawing::with_stats(setup.clone(), motion.clone(), result.clone(), stats);
    stages.send(Ok(Stage::Run(Box::new(run))));
    control.stage(1, 3);
    let free = BridgeScenario {
        contact: ContactModel::None,
        ..setup.scenario.clone()
    };
    let baseline = solve_with(&free, &motion, control)?;
    stages.send(Ok(Stage::Baseline(Box::new(baseline))));
    control.stage(2, 3);
    match estimate_error(&setup.scenario, &motion, &result, control) {
        Err(SolveError::Cancelled) => Err(JobError::Cancelled),
        estimate => Ok(Stage::Estimate(estimate.ok())),
    }
}
