//! Why a background job of a scene ended without its result.

use crate::model::error::SolveError;

/// Why a scene's staged job (buildings, bridge) gave no (or only part of a) result, typed
/// across the thread: the scene words it.
#[derive(Debug, thiserror::Error)]
pub(crate) enum JobError {
    #[error("ground motion: {0}")]
    Motion(#[from] crate::io::motion::MotionError),
    #[error("cancelled: the last result is kept")]
    Cancelled,
    #[error(transparent)]
    Solve(SolveError),
}

impl From<SolveError> for JobError {
    fn from(e: SolveError) -> Self {
        match e {
            SolveError::Cancelled => JobError::Cancelled,
            e => JobError::Solve(e),
        }
    }
}
