//! A solve's line to whoever waits for it: a request to stop, and how far it has got. The
//! window's solver threads hand one to each solve, cancel it when a newer request arrives, and
//! read its progress while drawing; the command line and the tests use [`Control::never`].
//!
//! One solve reports the fraction of its steps done ([`Control::report`]); a job of many solves
//! (a study, a sweep, an accuracy ladder) counts the solves it plans and finishes
//! ([`Control::plan`], [`Control::tick`]). Both are read from the same control, and one cancel
//! stops either.

use std::sync::atomic::{AtomicBool, AtomicU32, AtomicUsize, Ordering};

/// How many steps a solver loop may take between two looks at its [`Control`].
pub const CHECK_EVERY: usize = 4096;

/// The longest a paused job waits before a later stage, unless told otherwise: longer than a
/// window holds a change for a run (a second), so the change always decides first.
pub const PAUSE_LIMIT_MS: u32 = 3000;

/// A job on a scoped thread that says when it ends (with its result or its panic), so that the
/// thread waiting for it can look at something else at a steady pace and still answer the
/// moment it ends, not at its next look.
pub struct Told<'scope, T> {
    job: std::thread::ScopedJoinHandle<'scope, T>,
    ended: std::sync::mpsc::Receiver<()>,
}

/// Starts `work` on `scope` as a [`Told`] job.
pub fn spawn_told<'scope, 'env, T: Send + 'scope>(
    scope: &'scope std::thread::Scope<'scope, 'env>,
    work: impl FnOnce() -> T + Send + 'scope,
) -> Told<'scope, T> {
    let (done, ended) = std::sync::mpsc::channel::<()>();
    let job = scope.spawn(move || {
        let out = work();
        // A panic drops `done` instead, which ends the wait as well.
        let _ = done.send(());
        out
    });
    Told { job, ended }
}

impl<T> Told<'_, T> {
    /// Calls `look` every `every` until the job ends, then joins it.
    pub fn wait_looking(
        self,
        every: std::time::Duration,
        mut look: impl FnMut(),
    ) -> std::thread::Result<T> {
        while let Err(std::sync::mpsc::RecvTimeoutError::Timeout) = self.ended.recv_timeout(every) {
            look();
        }
        self.job.join()
    }
}

/// A cancel flag and the fraction done, shared between a solve and its caller.
#[derive(Debug, Default)]
pub struct Control {
    cancel: AtomicBool,
    /// The fraction done, in millionths.
    done_ppm: AtomicU32,
    /// A job of several solves: this solve is part `stage` of `stages`.
    stage: AtomicU32,
    stages: AtomicU32,
    /// How many times the solve has looked (reported), and the look at which to stop by itself
    /// (0: never).
    looks: AtomicU32,
    stop_at_look: AtomicU32,
    /// A job of many solves: how many it planned and how many are done.
    jobs_total: AtomicUsize,
    jobs_done: AtomicUsize,
    /// Whether the job's later stages wait for a cancel before they start (its first result is
    /// all that is wanted of it), and for at most how many milliseconds.
    pause_after_first: AtomicBool,
    pause_limit_ms: AtomicU32,
}

static NEVER: Control = Control::new();

/// A solve stopped through its [`Control`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[error("cancelled")]
pub struct Cancelled;

impl Control {
    /// Not cancelled, nothing done.
    pub const fn new() -> Self {
        Control {
            cancel: AtomicBool::new(false),
            done_ppm: AtomicU32::new(0),
            stage: AtomicU32::new(0),
            stages: AtomicU32::new(1),
            looks: AtomicU32::new(0),
            stop_at_look: AtomicU32::new(0),
            jobs_total: AtomicUsize::new(0),
            jobs_done: AtomicUsize::new(0),
            pause_after_first: AtomicBool::new(false),
            pause_limit_ms: AtomicU32::new(PAUSE_LIMIT_MS),
        }
    }

    /// One that asks for a stop at the solve's `look`-th look (from 1): a cancel at a point of the
    /// work fixed in advance, so a test of cancelling does not hang on how fast a machine is or
    /// how its threads are scheduled.
    pub fn stopping_at_look(look: u32) -> Self {
        let c = Control::new();
        c.stop_at_look.store(look, Ordering::Relaxed);
        c
    }

    /// One that nobody cancels or reads.
    pub fn never() -> &'static Control {
        &NEVER
    }

    /// Asks the solve to stop at its next look.
    pub fn cancel(&self) {
        self.cancel.store(true, Ordering::Relaxed);
    }

    /// Whether a stop was asked for.
    pub fn cancelled(&self) -> bool {
        self.cancel.load(Ordering::Relaxed)
    }

    /// The solves that follow are part `stage` (from 0) of `stages` equal parts of one job:
    /// their fractions map into that part of the whole. A later part (`stage` above 0) of a
    /// job asked to [pause after its first](Control::pause_after_first) waits here.
    pub fn stage(&self, stage: u32, stages: u32) {
        if !std::ptr::eq(self, &NEVER) {
            self.stages.store(stages.max(1), Ordering::Relaxed);
            self.stage
                .store(stage.min(stages.max(1) - 1), Ordering::Relaxed);
            if stage > 0 {
                self.wait_if_paused();
            }
        }
    }

    /// Asks a job of stages to wait before each later stage until it is cancelled (at most
    /// a few seconds): the window asks it of a job whose first result a newer change waits
    /// for, whose checks that change will cancel. Waiting, they leave the machine to the
    /// drawing instead of doing work that is thrown away.
    pub fn pause_after_first(&self) {
        if !std::ptr::eq(self, &NEVER) {
            self.pause_after_first.store(true, Ordering::Relaxed);
        }
    }

    /// Lets a job paused (or about to pause) before its later stages go on.
    pub fn resume(&self) {
        self.pause_after_first.store(false, Ordering::Relaxed);
    }

    /// The longest a paused stage waits before it goes on anyway [ms].
    pub fn set_pause_limit_ms(&self, ms: u32) {
        self.pause_limit_ms.store(ms, Ordering::Relaxed);
    }

    /// Waits, if paused, until resumed, cancelled or the limit runs out.
    fn wait_if_paused(&self) {
        if !self.pause_after_first.load(Ordering::Relaxed) {
            return;
        }
        let start = std::time::Instant::now();
        let limit = std::time::Duration::from_millis(u64::from(
            self.pause_limit_ms.load(Ordering::Relaxed),
        ));
        while self.pause_after_first.load(Ordering::Relaxed)
            && !self.cancelled()
            && start.elapsed() < limit
        {
            std::thread::sleep(std::time::Duration::from_millis(1));
        }
    }

    /// Records the fraction done (0 to 1) and says whether to go on.
    pub fn report(&self, fraction: f64) -> Result<(), Cancelled> {
        if !std::ptr::eq(self, &NEVER) {
            let stages = f64::from(self.stages.load(Ordering::Relaxed));
            let stage = f64::from(self.stage.load(Ordering::Relaxed));
            let whole = (stage + fraction.clamp(0.0, 1.0)) / stages;
            let ppm = (whole * 1e6) as u32;
            self.done_ppm.store(ppm, Ordering::Relaxed);
            let look = self.looks.fetch_add(1, Ordering::Relaxed) + 1;
            if look == self.stop_at_look.load(Ordering::Relaxed) {
                self.cancel();
            }
        }
        if self.cancelled() {
            Err(Cancelled)
        } else {
            Ok(())
        }
    }

    /// How many times the solve has looked at this control.
    pub fn looks(&self) -> u32 {
        self.looks.load(Ordering::Relaxed)
    }

    /// The fraction done last reported.
    pub fn fraction(&self) -> f64 {
        f64::from(self.done_ppm.load(Ordering::Relaxed)) * 1e-6
    }

    /// Announces `n` more solves of a job of many.
    pub fn plan(&self, n: usize) {
        if !std::ptr::eq(self, &NEVER) {
            self.jobs_total.fetch_add(n, Ordering::Relaxed);
        }
    }

    /// One planned solve is done.
    pub fn tick(&self) {
        if !std::ptr::eq(self, &NEVER) {
            self.jobs_done.fetch_add(1, Ordering::Relaxed);
        }
    }

    /// Solves done.
    pub fn done(&self) -> usize {
        self.jobs_done.load(Ordering::Relaxed)
    }

    /// Solves planned.
    pub fn total(&self) -> usize {
        self.jobs_total.load(Ordering::Relaxed)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cancelled_control_stops_the_next_report_and_keeps_its_progress() {
        let c = Control::new();
        assert_eq!(c.report(0.25), Ok(()));
        assert!((c.fraction() - 0.25).abs() < 1e-6);
        c.cancel();
        assert_eq!(c.report(0.5), Err(Cancelled));
        assert!((c.fraction() - 0.5).abs() < 1e-6);
        assert_eq!(Control::never().report(0.7), Ok(()));
        let c = Control::new();
        c.stage(1, 4);
        c.report(0.5).unwrap();
        assert!((c.fraction() - 0.375).abs() < 1e-6);
        assert_eq!(Control::never().fraction(), 0.0);
    }

    #[test]
    fn a_job_of_many_solves_counts_what_it_planned_and_finished() {
        let c = Control::new();
        c.plan(3);
        c.plan(2);
        c.tick();
        c.tick();
        assert_eq!((c.done(), c.total()), (2, 5));
        // The shared control nobody reads keeps no count.
        Control::never().plan(7);
        Control::never().tick();
        assert_eq!((Control::never().done(), Control::never().total()), (0, 0));
    }

    #[test]
    fn a_paused_job_waits_before_its_later_stages_until_it_is_cancelled() {
        use std::sync::Arc;
        let c = Arc::new(Control::new());
        // Unpaused, and paused in its first stage: nothing waits.
        c.stage(1, 3);
        c.pause_after_first();
        c.stage(0, 3);
        assert_eq!(c.report(0.5), Ok(()));
        // A limit no scheduling reaches: the wait below ends by the cancel alone.
        c.set_pause_limit_ms(600_000);
        let said = Arc::new(AtomicBool::new(false));
        let canceller = {
            let (c, said) = (c.clone(), said.clone());
            std::thread::spawn(move || {
                said.store(true, Ordering::SeqCst);
                c.cancel();
            })
        };
        c.stage(1, 3);
        assert!(
            said.load(Ordering::SeqCst),
            "the stage went on before the cancel"
        );
        assert_eq!(c.report(0.0), Err(Cancelled));
        canceller.join().unwrap();
        // With a limit, a pause nobody cancels ends by itself.
        let c = Control::new();
        c.pause_after_first();
        c.set_pause_limit_ms(5);
        c.stage(2, 3);
        assert_eq!(c.report(0.0), Ok(()));
    }
}
