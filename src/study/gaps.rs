//! The gap that avoids pounding, record by record: each record's run without contact, solved in
//! parallel, and its gaps against the code rules (see `model::building::gaps`).

use super::{Cancelled, Control, par_map};
use crate::model::building::gaps::{GapAssessment, assess};
use crate::model::building::{BuildingScenario, ContactModel, Tracked, solve_summary_tracking};
use crate::model::error::SolveError;
use crate::model::motion::{G, GroundMotion};

/// One record's gaps.
#[derive(Debug, Clone)]
pub struct RecordGaps {
    pub record: String,
    pub duration_s: f64,
    pub pga_g: f64,
    pub gaps: GapAssessment,
}

/// Every record's gaps for the buildings of `scenario` (its contact element is not used: the
/// runs are without contact); a record whose run fails carries the error.
pub fn record_gaps(
    scenario: &BuildingScenario,
    motions: &[GroundMotion],
    progress: &Control,
) -> Result<Vec<Result<RecordGaps, SolveError>>, Cancelled> {
    let free = BuildingScenario {
        contact: ContactModel::None,
        ..scenario.clone()
    };
    par_map(progress, motions, |m| {
        // Only the closings and the floors at the levels count here.
        let r = solve_summary_tracking(&free, m, Control::never(), Tracked::Levels)?;
        Ok(RecordGaps {
            record: m.name.clone(),
            duration_s: m.duration_s(),
            pga_g: m.accel_m_s2.iter().fold(0.0f64, |a, x| a.max(x.abs())) / G,
            gaps: assess(&r),
        })
    })
}
