//! A straight bridge pounding at its expansion joints: N frames (a girder on bearings on a pier
//! each) between two rigid abutments, longitudinal motion only, one ground motion reaching each
//! support when a travelling wave gets there. Each frame is a two-storey shear building (pier
//! top, girder) on its own ground point; the joints carry the buildings' contact elements; under
//! Sears each girder is a bar whose waves from both ends add to its ends' motion.
//!
//! docs/model.md, "Bridges", gives the model in full.

pub mod estimate;
pub mod girder;
pub mod ground;
pub mod result;
pub mod scenario;
pub mod solve;

pub use estimate::{BridgeErrorEstimate, estimate_error};
pub use result::{BridgeEnergy, BridgeResult, BridgeStats, Unseating};
pub use scenario::{BridgeScenario, Girder, Joint, Member};
pub use solve::{
    solve, solve_stepped, solve_streaming, solve_summary, solve_walked, solve_with, step_s,
};
