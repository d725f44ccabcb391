//! The Building pounding scene's solve, in the order the scene shows it: the run streamed while
//! it solves, the run whole, the run without contact (the displacements it is compared with and
//! the gap that avoids pounding), then the error estimate (a second run twice as fine, the
//! slowest of them). Each stage is handed over as it lands, so the run is on screen before the
//! checks that follow it.

use super::building_view::BuildingDrawing;
use super::worker::Stages;
use crate::io::building_settings::BuildingSetup;
use crate::model::building::gaps::{GapAssessment, assess};
use crate::model::building::{
    BuildingErrorEstimate, BuildingResult, BuildingScenario, ContactModel, PUBLISH_EVERY,
    estimate_error_with, solve_streaming, solve_with,
};
use crate::model::control::Control;
use crate::model::error::SolveError;

/// The run without contact and the gap it gives.
pub(super) struct Baseline {
    pub result: BuildingResult,
    pub gaps: GapAssessment,
}

/// One stage of a building job, in the order they come.
pub(super) enum Stage {
    /// The run solved so far (its `solved_to_s` short of the record's end); any number of them.
    Partial(Box<BuildingDrawing>),
    /// The run, whole: the job's first result.
    Run(Box<BuildingDrawing>),
    /// The run without contact.
    Baseline(Box<Baseline>),
    /// The run's error estimate, the job's last (`None` where it could not be worked out: the
    /// run stands without one).
    Estimate(Option<BuildingErrorEstimate>),
}

pub(super) type Output = Result<Stage, JobError>;
pub(super) use super::job_error::JobError;

/// The job: its stages go to `stages`, its last is returned. The drawings (the slabs' waves
/// and their GPU grid) are made here, off the UI thread.
pub(super) fn run_job(setup: BuildingSetup, control: &Control, stages: &Stages<Output>) -> Output {
    let (motion, stats) = super::motion_cache::load(&setup.motion)?;
    // Three parts of the progress bar: the run, the run without contact, the estimate.
    control.stage(0, 3);
    let result = solve_streaming(
        &setup.scenario,
        &motion,
        control,
        PUBLISH_EVERY,
        &mut |so_far| {
            let drawing = BuildingDrawing::with_stats(setup.clone(), motion.clone(), so_far, stats);
            stages.send(Ok(Stage::Partial(Box::new(drawing))));
        },
    )?;
    // The drawing goes to the UI thread, which cannot share it (the slabs' records are not
    // `Sync`): the estimate compares with a copy.
    let run = BuildingDrawing::with_stats(setup.clone(), motion.clone(), result.clone(), stats);
    stages.send(Ok(Stage::Run(Box::new(run))));
    control.stage(1, 3);
    // The baseline's roof displacements are drawn, so it is a run with histories.
    let baseline = solve_with(
        &BuildingScenario {
            contact: ContactModel::None,
            ..setup.scenario.clone()
        },
        &motion,
        control,
    )?;
    stages.send(Ok(Stage::Baseline(Box::new(Baseline {
        gaps: assess(&baseline),
        result: baseline,
    }))));
    control.stage(2, 3);
    match estimate_error_with(&setup.scenario, &motion, &result, control) {
        Err(SolveError::Cancelled) => Err(JobError::Cancelled),
        estimate => Ok(Stage::Estimate(estimate.ok())),
    }
}
