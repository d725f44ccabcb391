//! A scene's solve that lands in stages: the run (streamed while it solves, then whole) and the
//! stages that land after it (the run without contact, the error estimate): what is shown until
//! each does, and when each landed.

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

/// One request's run, whole or as far as it has solved, and its later stages as they land.
pub(crate) struct Solved<D, B, E> {
    pub(crate) drawing: Box<D>,
    /// Whether the run is whole (else it is the part solved so far).
    pub(crate) whole: bool,
    pub(crate) baseline: Later<B>,
    pub(crate) estimate: Later<E>,
    /// Whether it is the newest request's (false once a newer one is made).
    pub(crate) current: bool,
}

/// What a scene whose solve lands in stages shows: one request's run, and while that shows only
/// the part solved so far, the last whole run, to come back if the request stops short. A
/// later stage joins only the whole run of its own request, so nothing shown mixes two.
pub(crate) struct Shown<D, B, E> {
    pub(crate) solved: Option<Solved<D, B, E>>,
    kept: Option<Solved<D, B, E>>,
}

impl<D, B, E> Default for Shown<D, B, E> {
    fn default() -> Self {
        Shown {
            solved: None,
            kept: None,
        }
    }
}

impl<D, B, E> Shown<D, B, E> {
    /// Whether the run on screen is the newest request's.
    pub(crate) fn current(&self) -> bool {
        self.solved.as_ref().is_some_and(|s| s.current)
    }

    /// A newer request is made: what is shown is no longer its.
    pub(crate) fn superseded(&mut self) {
        if let Some(s) = &mut self.solved {
            s.current = false;
        }
    }

    /// Shows the newest request's run, whole or so far; its later stages are on their way.
    pub(crate) fn show(&mut self, drawing: Box<D>, whole: bool) {
        let before = self.solved.replace(Solved {
            drawing,
            whole,
            baseline: Later::Pending,
            estimate: Later::Pending,
            current: true,
        });
        if whole {
            self.kept = None;
        } else if let Some(b) = before.filter(|b| b.whole) {
            self.kept = Some(b);
        }
    }

    /// The newest request's whole run, for a later stage to join.
    pub(crate) fn newest_whole(&mut self) -> Option<&mut Solved<D, B, E>> {
        self.solved.as_mut().filter(|s| s.current && s.whole)
    }

    /// The newest request is done: a run it left unfinished gives way to the last whole one,
    /// and a stage it never delivered is not coming.
    pub(crate) fn ended(&mut self) {
        if self.solved.as_ref().is_some_and(|s| !s.whole) {
            self.solved = self.kept.take();
        }
        if let Some(s) = &mut self.solved {
            s.baseline.ended();
            s.estimate.ended();
        }
    }

    /// Where the part on screen ends (`solved_to` of its drawing): playback waits there.
    pub(crate) fn edge(&self, solved_to: impl Fn(&D) -> f64) -> Option<f64> {
        self.solved
            .as_ref()
            .filter(|s| !s.whole)
            .map(|s| solved_to(&s.drawing))
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
