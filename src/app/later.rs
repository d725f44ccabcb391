//! A stage of a scene's solve that lands after its run (the run without contact, the error
//! estimate): what is shown until it does, and when each landed.

use std::time::Duration;

/// A stage that comes after the run: on its way, landed, or not coming (its request ended
/// without it; the error line says why).
pub(crate) enum Later<T> {
    Pending,
    Ready(T),
    Missing,
}

impl<T> Later<T> {
    pub(crate) fn ready(&self) -> Option<&T> {
        match self {
            Later::Ready(t) => Some(t),
            _ => None,
        }
    }

    /// The request ended: a stage still pending is not coming.
    pub(crate) fn ended(&mut self) {
        if matches!(self, Later::Pending) {
            *self = Later::Missing;
        }
    }

    /// What a readout shows in place of the stage's value.
    pub(crate) fn absent(&self) -> &'static str {
        match self {
            Later::Missing => "not solved",
            _ => "pending",
        }
    }
}

/// When a request's later stages landed, from its change.
#[derive(Default)]
pub(crate) struct StageTimes {
    pub(crate) baseline: Option<Duration>,
    pub(crate) estimate: Option<Duration>,
}

impl StageTimes {
    /// The status bar's note on them (the change to result being the time to the run);
    /// `busy`: the request still solves (else a stage not landed is not coming).
    pub(crate) fn describe(&self, busy: bool) -> String {
        let missing = if busy { "pending" } else { "not solved" };
        let at =
            |t: Option<Duration>| t.map_or(missing.into(), |t| crate::app::ms(t.as_secs_f64(), 1));
        format!(
            "Change to result: from the change to its run on screen. After the change, the run without pounding landed in {}, the error estimate in {}",
            at(self.baseline),
            at(self.estimate)
        )
    }
}

/// What the status bar says while a run on screen waits for its later stages.
pub(crate) fn pending_note<A, B>(baseline: &Later<A>, estimate: &Later<B>) -> &'static str {
    match (baseline, estimate) {
        (Later::Pending, _) => "run shown; no-pounding run and error estimate pending",
        (_, Later::Pending) => "run shown; error estimate pending",
        _ => "solving...",
    }
}
