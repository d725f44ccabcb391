//! The errors the model ends with: bad input (by the key at fault and its allowed range) and a
//! solve that could not finish. Both the bar impacts and the buildings use them, so they live
//! apart from either.

use super::control::Cancelled;

/// Bad input: which field, what it was, what is allowed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{field}: {message}")]
pub struct InputError {
    /// The key at fault (`bar2.length`).
    pub field: String,
    /// What is wrong, with the allowed range.
    pub message: String,
}

impl InputError {
    /// An error naming `field`.
    pub fn new(field: impl Into<String>, message: impl Into<String>) -> Self {
        InputError {
            field: field.into(),
            message: message.into(),
        }
    }
}

/// Errors a solve can end with.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SolveError {
    /// An input refused, by name.
    #[error(transparent)]
    Input(#[from] InputError),
    #[error(
        "step budget exceeded: the run needs more than solver.max_steps = {max_steps} steps (dt = {dt_s:e} s, reached t = {reached_s:e} s); raise solver.max_steps, coarsen solver.dt or shorten solver.window"
    )]
    /// The run needs more steps than `solver.max_steps`.
    Budget {
        /// The budget.
        max_steps: usize,
        /// The step [s].
        dt_s: f64,
        /// How far the run got [s].
        reached_s: f64,
    },
    /// A run on one fixed step (a bridge) that needs more steps than its budget, with what
    /// set the step and the keys that change it.
    #[error(
        "step budget exceeded: the run needs {needed} steps of {dt_s:.3e} s, more than solver.max_steps = {max_steps}; {why}"
    )]
    StepBudget {
        /// The budget.
        max_steps: usize,
        /// The steps the run needs.
        needed: usize,
        /// The step [s].
        dt_s: f64,
        /// What set the step, and what to change.
        why: String,
    },
    /// An FE run whose mesh and steps would take longer than its work budget.
    #[error(
        "work budget exceeded: fe.segments = {segments} per bar needs about {node_steps:.2e} node updates, more than {max:.0e}; lower fe.segments or shorten solver.window"
    )]
    FeWork {
        /// Segments per bar.
        segments: usize,
        /// Node updates the run would take.
        node_steps: f64,
        /// The budget.
        max: f64,
    },
    /// A run whose histories would outgrow the memory budget.
    #[error(
        "memory budget exceeded at t = {at_s:.4} s: the histories would take more than {bytes:.1e} bytes; shorten the record (motion.duration), raise solver.max_step or lower solver.max_steps"
    )]
    Memory {
        /// How far the run got [s].
        at_s: f64,
        /// The budget [bytes].
        bytes: f64,
    },
    /// A run whose numbers grew without bound; no result is given.
    #[error("the run diverged at t = {at_s:.4} s: {why}")]
    Diverged {
        /// When the run stopped [s].
        at_s: f64,
        /// What grew, and what to change (fitted to the element and command that failed).
        why: String,
    },
    /// Stopped through its [`Control`](super::control::Control) (a newer request in the window, or Cancel).
    #[error("cancelled")]
    Cancelled,
}

impl From<Cancelled> for SolveError {
    fn from(_: Cancelled) -> Self {
        SolveError::Cancelled
    }
}
