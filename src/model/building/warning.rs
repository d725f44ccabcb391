//! What a reader of a building run must know besides its numbers, as variants (tests match the
//! kind, never a phrase); the message is the `Display`.

use std::fmt;

/// A warning attached to a building run.
#[derive(Debug, Clone, PartialEq)]
pub enum Warning {
    /// The contact's time scale needs a finer grid than the step budget allows; a
    /// coarser grid is used (stable: the contact force is implicit) and the force's rise is not
    /// resolved.
    GridOverBudget {
        /// The contact's time scale [s].
        scale_s: f64,
        /// The step it needs [s].
        wanted_s: f64,
        /// The step used [s].
        used_s: f64,
        /// The step budget.
        max_steps: usize,
    },
    /// The Sears paper reading's validity number exceeds pi/2 at a level.
    PaperReadingUnstable {
        /// The level (index into the run's levels).
        level: usize,
        /// Its validity number.
        a_tau: f64,
    },
    /// Still in contact when the record ended.
    InContactAtEnd {
        /// The end of the record [s].
        end_s: f64,
    },
    /// Stereomechanical exchanges accumulated (floors pressed together, each rebound shorter):
    /// cut at one per level per step, the impacts hold many exchanges.
    StereoChatter {
        /// Impacts of more than ten exchanges.
        impacts: usize,
        /// Their exchanges.
        exchanges: usize,
    },
    /// The energy ledger does not balance (a defect: it balances to round-off by construction).
    CreatedEnergy {
        /// What the ledger misses [J].
        joules: f64,
        /// The same relative to the energy that entered.
        relative: f64,
    },
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Warning::GridOverBudget {
                scale_s,
                wanted_s,
                used_s,
                max_steps,
            } => write!(
                f,
                "the contact's time scale ({scale_s:.3e} s) needs a step of {wanted_s:.3e} s, over the step budget (solver.max_steps = {max_steps}) for this record: using {used_s:.3e} s, which does not resolve the force's rise; raise solver.max_steps or shorten the record for accurate forces"
            ),
            Warning::PaperReadingUnstable { level, a_tau } => write!(
                f,
                "at level {}, the Sears paper reading's validity number a tau = {a_tau:.3} exceeds pi/2: this reading oscillates and creates energy once separation clips the force (docs/model.md); use contact.reading = end or a softer contact",
                level + 1
            ),
            Warning::InContactAtEnd { end_s } => write!(
                f,
                "the buildings were still in contact at the end of the record (t = {} s)",
                crate::model::settings::shown(*end_s)
            ),
            Warning::StereoChatter { impacts, exchanges } => write!(
                f,
                "stereomechanics chattered: {exchanges} instantaneous exchanges in {impacts} impacts, cut at one per level per step; the floors were pressed together, which an instantaneous exchange cannot hold (use a contact element with a force, kelvin say)"
            ),
            Warning::CreatedEnergy { joules, relative } => write!(
                f,
                "the energy ledger does not balance: {joules:.3e} J ({relative:.2e} of the energy that entered) unaccounted for"
            ),
        }
    }
}
