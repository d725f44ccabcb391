//! A solver thread for a scene: the UI posts the latest inputs and keeps drawing the last result.
//! Each request carries a [`Control`]; a newer request (or Cancel) cancels the running solve,
//! whose loops look at it every few thousand steps, so the thread always moves on to the newest
//! inputs at once and a dragged slider never queues up solves. A panic in a solve is caught and
//! reported as that request's outcome; the thread lives on.
//!
//! A job may hand the UI outputs before its last through its [`Stages`] (a run solved so far, a
//! first result before the checks that refine it): the UI takes them in the order sent, and a
//! newer request drops whatever of the older one's is still on its way.

use crate::model::control::Control;
use std::collections::VecDeque;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::Arc;
use std::sync::mpsc::{Receiver, Sender, channel};
use std::time::{Duration, Instant};

/// One output of a job: the request's number, the output (or the message of the panic that
/// ended the job), how long the job had run, and whether it is the job's last.
pub struct Done<O> {
    pub id: u64,
    pub output: Result<O, String>,
    pub elapsed: Duration,
    /// The job returned (or panicked) with this: its request is done.
    pub last: bool,
}

type Request<I> = (u64, I, Arc<Control>);

/// The longest a change waits for the run under way (a longer run is cancelled, and shows
/// its progress in the parts it streams).
pub const HOLD_AT_MOST: Duration = Duration::from_secs(1);

/// A solve that lands within this shows no progress bar.
pub const PROGRESS_AFTER: Duration = Duration::from_millis(50);

/// What a scene shows when its solve panicked: the panic's message, and that the last result is
/// kept.
pub fn internal_error(panic: &str) -> String {
    format!("the solver stopped on an internal error ({panic}); the last result is kept")
}

/// A job's line to the UI for the outputs it has before its last, so a scene can show a long
/// job's first answers while the rest is worked out.
pub struct Stages<'a, O> {
    id: u64,
    start: Instant,
    outbox: &'a Sender<Done<O>>,
    wake: &'a dyn Fn(),
}

impl<O> Stages<'_, O> {
    /// Hands `output` to the UI (and wakes it): it lands after those sent before it and before
    /// the job's last.
    pub fn send(&self, output: O) {
        let done = Done {
            id: self.id,
            output: Ok(output),
            elapsed: self.start.elapsed(),
            last: false,
        };
        // A send only fails once the UI is gone, and then nobody is waiting for it.
        if self.outbox.send(done).is_ok() {
            (self.wake)();
        }
    }
}

pub struct Worker<I, O> {
    to_worker: Sender<Request<I>>,
    from_worker: Receiver<Done<O>>,
    next_id: u64,
    /// The newest request: its number, when it was made and its control.
    pending: Option<(u64, Instant, Arc<Control>)>,
    /// The newest request's outputs received and not yet polled, in the order sent.
    landed: VecDeque<Done<O>>,
}

/// The text of a caught panic.
pub fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        s.to_string()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "a panic without a message".into()
    }
}

impl<I: Send + 'static, O: Send + 'static> Worker<I, O> {
    /// Starts the thread for a job of one output; `wake` is called after each job (to request a
    /// repaint).
    pub fn new(
        job: impl Fn(I, &Control) -> O + Send + 'static,
        wake: impl Fn() + Send + 'static,
    ) -> Self {
        Self::staged(move |input, control, _| job(input, control), wake)
    }

    /// Starts the thread for a job that may hand out outputs before its last; `wake` is called
    /// after each output.
    pub fn staged(
        job: impl Fn(I, &Control, &Stages<O>) -> O + Send + 'static,
        wake: impl Fn() + Send + 'static,
    ) -> Self {
        let (to_worker, inbox) = channel::<Request<I>>();
        let (outbox, from_worker) = channel::<Done<O>>();
        std::thread::Builder::new()
            .name("pounding-solver".into())
            .spawn(move || {
                while let Ok(mut request) = inbox.recv() {
                    // Skip to the newest request.
                    while let Ok(newer) = inbox.try_recv() {
                        request = newer;
                    }
                    let (id, input, control) = request;
                    let start = Instant::now();
                    let stages = Stages {
                        id,
                        start,
                        outbox: &outbox,
                        wake: &wake,
                    };
                    let output = catch_unwind(AssertUnwindSafe(|| job(input, &control, &stages)))
                        .map_err(|p| panic_message(p.as_ref()));
                    let done = Done {
                        id,
                        output,
                        elapsed: start.elapsed(),
                        last: true,
                    };
                    if outbox.send(done).is_err() {
                        break;
                    }
                    wake();
                }
            })
            .expect("the solver thread starts");
        Worker {
            to_worker,
            from_worker,
            next_id: 0,
            pending: None,
            landed: VecDeque::new(),
        }
    }

    /// Posts new inputs; the solve under way, if any, is cancelled and what it has not yet
    /// delivered is dropped.
    pub fn request(&mut self, input: I) {
        self.request_at(input, Instant::now());
    }

    /// As `request`, for a change made at `at` (its latency is counted from then).
    pub fn request_at(&mut self, input: I, at: Instant) {
        self.cancel();
        self.landed.clear();
        self.next_id += 1;
        let control = Arc::new(Control::new());
        self.pending = Some((self.next_id, at, control.clone()));
        // A send only fails once the thread is gone, and then there is nothing left to do.
        let _ = self.to_worker.send((self.next_id, input, control));
    }

    /// Asks the job under way to wait before its later stages until it is cancelled
    /// ([`Control::pause_after_first`]).
    pub fn pause_after_first(&self) {
        if let Some((_, _, control)) = &self.pending {
            control.pause_after_first();
        }
    }

    /// Lets the job under way go on to its later stages ([`Control::resume`]).
    pub fn resume(&self) {
        if let Some((_, _, control)) = &self.pending {
            control.resume();
        }
    }

    /// Asks the solve under way to stop; its outcome (a cancellation) still arrives.
    pub fn cancel(&self) {
        if let Some((_, _, control)) = &self.pending {
            control.cancel();
        }
    }

    /// The newest request's next output, in the order its job gave them, with the time from
    /// its request to now; after its last, the request is done. Outputs of older (cancelled)
    /// requests are dropped.
    pub fn poll(&mut self) -> Option<(Done<O>, Duration)> {
        let newest = self.pending.as_ref().map(|p| p.0);
        while let Ok(done) = self.from_worker.try_recv() {
            if newest == Some(done.id) {
                self.landed.push_back(done);
            }
        }
        let done = self.landed.pop_front()?;
        let (_, at, _) = self.pending.as_ref()?;
        let since = at.elapsed();
        if done.last {
            self.pending = None;
        }
        Some((done, since))
    }

    pub fn busy(&self) -> bool {
        self.pending.is_some()
    }

    /// How far the solve under way has got (0 to 1), once it has run longer than `after`
    /// (a solve that lands within a frame shows no progress bar).
    pub fn progress(&self, after: Duration) -> Option<f64> {
        let (_, at, control) = self.pending.as_ref()?;
        (at.elapsed() >= after).then(|| control.fraction())
    }
}

/// One output of a scene's newest request as the scene takes it.
pub struct Landed<O> {
    pub output: O,
    /// The job's last output: the request is done.
    pub last: bool,
    /// From the job's start to this output.
    pub job_time: Duration,
    /// From the change that asked for it to the frame that took it.
    pub since_request: Duration,
}

/// A scene's solve core: its worker, the timings of its last landed solve, and the error the
/// scene shows while the last good result stays on screen. Every scene that solves in the
/// background keeps one, so requesting, cancelling, progress, timings and a caught panic are
/// handled once.
pub struct SolveSlot<I, O> {
    worker: Worker<I, O>,
    /// How long the last landed solve took.
    pub solve_time: Duration,
    /// From the change that asked for the last landed solve to its landing.
    pub latency: Duration,
    /// Why the newest request gave no (or only part of a) result; `None` after a good one.
    pub error: Option<String>,
    /// Runs landed so far (the ones the timings measure).
    pub runs: u64,
    /// A change held back while the run under way finishes, and when it was made.
    queued: Option<(I, Instant)>,
    /// When the solve under way was sent, and whether its run has landed.
    sent: Option<(Instant, bool)>,
    /// Whether an output of the solve under way has been taken (then its checks may go).
    taken: bool,
    /// Whether a job's later stages wait for a frame that shows its first output (a staged
    /// job's; a job of one output, whose stages are all before it, never waits).
    checks_wait: bool,
    /// How long the last landed run took.
    last_run: Option<Duration>,
    /// The longest a change waits for the run under way ([`HOLD_AT_MOST`]).
    pub hold_at_most: Duration,
}

impl<I: Send + 'static, O: Send + 'static> SolveSlot<I, O> {
    /// Starts the solver thread for a job of one output; `wake` is called after each job.
    pub fn new(
        job: impl Fn(I, &Control) -> O + Send + 'static,
        wake: impl Fn() + Send + 'static,
    ) -> Self {
        Self::of(Worker::new(job, wake), false)
    }

    /// Starts the solver thread for a job that hands out outputs before its last (taken with
    /// [`SolveSlot::poll_stage`]); `wake` is called after each output.
    pub fn staged(
        job: impl Fn(I, &Control, &Stages<O>) -> O + Send + 'static,
        wake: impl Fn() + Send + 'static,
    ) -> Self {
        Self::of(Worker::staged(job, wake), true)
    }

    fn of(worker: Worker<I, O>, checks_wait: bool) -> Self {
        SolveSlot {
            worker,
            solve_time: Duration::ZERO,
            latency: Duration::ZERO,
            error: None,
            runs: 0,
            queued: None,
            sent: None,
            taken: false,
            checks_wait,
            last_run: None,
            hold_at_most: HOLD_AT_MOST,
        }
    }

    /// Posts new inputs. The solve under way is cancelled, unless its run is due within twice
    /// the time the last run took (at most `hold_at_most`; not at all before any run has
    /// landed): then the new inputs wait for that run and go when it lands, cancelling only
    /// the later stages. A dragged slider asks for a solve every frame; cancelling each one
    /// shows nothing until the drag stops once a solve takes longer than a frame, where holding
    /// shows every run, each at most one solve behind the hand.
    pub fn request(&mut self, input: I) {
        let now = Instant::now();
        match self.sent {
            Some((at, false)) if self.worker.busy() && now - at < self.hold() => {
                self.queued = Some((input, now));
                // Its checks after the run would be cancelled when the change goes: they wait
                // instead, leaving the machine to the frames until then.
                self.worker.pause_after_first();
            }
            _ => self.send(input, now),
        }
    }

    /// How long a change may wait for the run under way. Nothing is held before a first run
    /// has landed: with nothing on screen to keep live, the newest inputs go at once (and what
    /// a window opens with never depends on which of its first requests finished first).
    fn hold(&self) -> Duration {
        self.last_run
            .map_or(Duration::ZERO, |d| (2 * d).min(self.hold_at_most))
    }

    fn send(&mut self, input: I, changed: Instant) {
        self.queued = None;
        self.sent = Some((Instant::now(), false));
        self.taken = false;
        self.worker.request_at(input, changed);
        // Its checks after its run wait for a frame that shows the run and makes no newer
        // change (`flush`): while a slider is dragged they would only be cancelled, on the
        // cores the frames need.
        if self.checks_wait {
            self.worker.pause_after_first();
        }
    }

    /// Sends a held change once the run it waits for has landed, its job is done, or the wait
    /// is over; and lets a job whose run has landed go on to its checks where no newer change
    /// came. The window calls it once a frame, after the frame's own changes: a change made in
    /// the frame its run landed replaces the one held for that run and goes at once (a change
    /// released before it would only be held behind the one just sent, a frame later for every
    /// change of a drag).
    pub fn flush(&mut self) {
        self.release();
        // Its output is on screen and no newer change came with this frame: its checks go.
        if self.taken && self.queued.is_none() {
            self.worker.resume();
        }
    }

    fn release(&mut self) {
        let waited = self.sent.is_none_or(|(at, run_landed)| {
            run_landed || !self.worker.busy() || at.elapsed() >= self.hold()
        });
        if waited && let Some((input, changed)) = self.queued.take() {
            self.send(input, changed);
        }
    }

    /// Asks the solve under way to stop; a held change is dropped.
    pub fn cancel(&mut self) {
        self.queued = None;
        self.worker.cancel();
    }

    pub fn busy(&self) -> bool {
        self.worker.busy() || self.queued.is_some()
    }

    /// The running solve's progress, once it has taken longer than a frame.
    pub fn progress(&self) -> Option<f64> {
        self.worker.progress(PROGRESS_AFTER)
    }

    /// The last landed solve's time and its change-to-result latency.
    pub fn timings(&self) -> (Duration, Duration) {
        (self.solve_time, self.latency)
    }

    /// Records a landed run's timings: how long its job took to it, and how long from the
    /// change that asked for it. A change held for this run goes at the next poll.
    pub fn record_run(&mut self, job_time: Duration, since_request: Duration) {
        self.solve_time = job_time;
        self.latency = since_request;
        self.runs += 1;
        self.last_run = Some(job_time);
        if let Some((_, run_landed)) = &mut self.sent {
            *run_landed = true;
        }
    }

    /// The newest request's output once it lands, its timings recorded and the error cleared.
    /// A solve that panicked gives `None` and leaves the panic's message as the error.
    pub fn poll(&mut self) -> Option<O> {
        let (done, latency) = self.worker.poll()?;
        self.taken = true;
        self.record_run(done.elapsed, latency);
        self.take(done.output)
    }

    /// The newest request's next output, in the order its job gave them, the error cleared;
    /// the scene records which of them its timings measure. A job that panicked gives `None`
    /// and leaves the panic's message as the error (and the request done).
    pub fn poll_stage(&mut self) -> Option<Landed<O>> {
        // A held change goes at `flush`, after the outputs it waited for have been taken.
        let (done, since_request) = self.worker.poll()?;
        self.taken = true;
        let (last, job_time) = (done.last, done.elapsed);
        self.take(done.output).map(|output| Landed {
            output,
            last,
            job_time,
            since_request,
        })
    }

    fn take(&mut self, output: Result<O, String>) -> Option<O> {
        match output {
            Ok(out) => {
                self.error = None;
                Some(out)
            }
            Err(panic) => {
                self.error = Some(internal_error(&panic));
                None
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn wait<O: Send + 'static>(w: &mut Worker<u64, O>) -> Done<O> {
        let start = Instant::now();
        loop {
            if let Some((done, _)) = w.poll() {
                return done;
            }
            assert!(start.elapsed() < Duration::from_secs(30), "no outcome");
            std::thread::sleep(Duration::from_millis(2));
        }
    }

    /// A job that runs until cancelled (or `n` checks), reporting progress.
    fn long(n: u64, control: &Control) -> Result<u64, &'static str> {
        for k in 0..n {
            if control.report(k as f64 / n as f64).is_err() {
                return Err("cancelled");
            }
            std::thread::sleep(Duration::from_millis(1));
        }
        Ok(n)
    }

    #[test]
    fn a_newer_request_interrupts_a_long_solve_and_only_its_outcome_lands() {
        let mut w = Worker::new(long, || {});
        w.request(1_000_000);
        // Wait for the solve to report progress, however slowly its thread is scheduled (a fixed
        // sleep would fail on a loaded machine).
        let waiting = Instant::now();
        while !w.progress(Duration::ZERO).is_some_and(|f| f > 0.0) {
            assert!(waiting.elapsed() < Duration::from_secs(60), "no progress");
            std::thread::sleep(Duration::from_millis(1));
        }
        let start = Instant::now();
        w.request(3);
        let done = wait(&mut w);
        assert_eq!(done.output, Ok(Ok(3)));
        // A million milliseconds would have been the alternative.
        assert!(start.elapsed() < Duration::from_secs(5));
        assert!(!w.busy());
    }

    #[test]
    fn cancel_stops_the_solve_and_says_so() {
        let mut w = Worker::new(long, || {});
        w.request(1_000_000);
        std::thread::sleep(Duration::from_millis(10));
        w.cancel();
        assert_eq!(wait(&mut w).output, Ok(Err("cancelled")));
    }

    /// Polls the slot until the newest request lands (or its panic is taken).
    fn land<O: Send + 'static>(slot: &mut SolveSlot<u64, O>) -> Option<O> {
        let start = Instant::now();
        while slot.busy() {
            if let Some(out) = slot.poll() {
                return Some(out);
            }
            slot.flush();
            assert!(start.elapsed() < Duration::from_secs(60), "no outcome");
            std::thread::sleep(Duration::from_millis(1));
        }
        None
    }

    #[test]
    fn a_solve_slot_keeps_a_panics_message_as_its_error_and_clears_it_on_the_next_result() {
        let mut slot = SolveSlot::new(
            |n: u64, _: &Control| {
                assert!(n != 13, "unlucky input");
                n * 2
            },
            || {},
        );
        slot.request(13);
        assert_eq!(land(&mut slot), None);
        let error = slot.error.clone().expect("the panic is the error");
        assert!(error.contains("unlucky input"), "{error}");
        slot.request(4);
        assert_eq!(land(&mut slot), Some(8));
        assert_eq!(slot.error, None);
        let (solve, latency) = slot.timings();
        assert!(latency >= solve, "the latency includes the solve");
    }

    /// Every output of the newest request, in the order taken, with whether it was the last,
    /// until the request is done; the error the slot is left with.
    fn drain<O: Send + 'static>(slot: &mut SolveSlot<u64, O>) -> Vec<(O, bool)> {
        let start = Instant::now();
        let mut taken = vec![];
        while slot.busy() {
            if let Some(l) = slot.poll_stage() {
                taken.push((l.output, l.last));
            } else {
                slot.flush();
                assert!(start.elapsed() < Duration::from_secs(60), "no outcome");
                std::thread::sleep(Duration::from_millis(1));
            }
        }
        taken
    }

    #[test]
    fn a_staged_jobs_outputs_land_in_the_order_sent_and_its_last_ends_the_request() {
        let mut slot = SolveSlot::staged(
            |n: u64, _: &Control, stages: &Stages<u64>| {
                for k in 1..n {
                    stages.send(k);
                }
                n
            },
            || {},
        );
        slot.request(5);
        let taken = drain(&mut slot);
        assert_eq!(
            taken,
            [(1, false), (2, false), (3, false), (4, false), (5, true)]
        );
        assert_eq!(slot.error, None);
    }

    #[test]
    fn a_newer_request_drops_what_the_older_one_had_not_delivered() {
        let (sent, all_sent) = channel::<u64>();
        // Request 1 hands out two stages, says so, and holds until cancelled, then tries one more
        // stage and its last; request 2 runs straight through.
        let mut slot = SolveSlot::staged(
            move |n: u64, control: &Control, stages: &Stages<u64>| {
                stages.send(10 * n + 1);
                stages.send(10 * n + 2);
                sent.send(n).expect("the test listens");
                if n == 1 {
                    while !control.cancelled() {
                        std::thread::yield_now();
                    }
                    stages.send(10 * n + 3);
                }
                10 * n + 9
            },
            || {},
        );
        // A change that does not wait for the run under way.
        slot.hold_at_most = Duration::ZERO;
        slot.request(1);
        // Request 1's two stages are on their way: the first taken, the second received with
        // it and left waiting.
        let said = all_sent.recv_timeout(Duration::from_secs(60));
        assert_eq!(said, Ok(1));
        let first = slot.poll_stage().map(|l| (l.output, l.last));
        assert_eq!(first, Some((11, false)));
        slot.request(2);
        assert_eq!(drain(&mut slot), [(21, false), (22, false), (29, true)]);
    }

    /// A job whose first output is its run (recorded as the scenes record theirs), and which
    /// then holds until cancelled (`n == 1`) or finishes.
    fn run_then_checks(n: u64, control: &Control, stages: &Stages<u64>) -> u64 {
        if n == 0 {
            // A first run that takes its time: the holds after it are twice as long.
            std::thread::sleep(WARM_UP);
        }
        if n != 3 {
            stages.send(10 * n + 1);
        }
        if n == 1 || n == 3 {
            while !control.cancelled() {
                std::thread::yield_now();
            }
            stages.send(10 * n + 3);
        }
        10 * n + 9
    }

    const WARM_UP: Duration = Duration::from_millis(600);

    /// A slot whose first run (request 0) has landed and taken `WARM_UP`.
    fn warmed_up(hold_at_most: Duration) -> SolveSlot<u64, u64> {
        let mut slot = SolveSlot::staged(run_then_checks, || {});
        slot.hold_at_most = hold_at_most;
        slot.request(0);
        assert_eq!(drain_runs(&mut slot), [1, 9]);
        slot
    }

    /// As `drain`, each output taken as the scenes take theirs: a job's first is its run.
    fn drain_runs(slot: &mut SolveSlot<u64, u64>) -> Vec<u64> {
        let start = Instant::now();
        let mut taken = vec![];
        while slot.busy() {
            if let Some(l) = slot.poll_stage() {
                if l.output % 10 == 1 {
                    slot.record_run(l.job_time, l.since_request);
                }
                taken.push(l.output);
            } else {
                slot.flush();
                assert!(start.elapsed() < Duration::from_secs(60), "no outcome");
                std::thread::sleep(Duration::from_millis(1));
            }
        }
        taken
    }

    #[test]
    fn a_change_made_while_a_run_is_due_waits_for_that_run_then_cancels_only_its_checks() {
        // The wait runs out after twice the first run, over a second: the run under way
        // decides long before.
        let mut slot = warmed_up(Duration::from_secs(3600));
        slot.request(1);
        slot.request(2);
        assert!(slot.busy());
        // Request 1's run lands and is shown; its checks are cancelled for request 2, which
        // runs through.
        assert_eq!(drain_runs(&mut slot), [11, 21, 29]);
        assert_eq!(slot.runs, 3);
    }

    #[test]
    fn a_change_made_in_the_frame_its_run_lands_replaces_the_held_one_and_goes_at_once() {
        // Runs that take their time (request 1's a fifth of a second), so that a change made
        // right after one is sent waits for it.
        let mut slot = SolveSlot::staged(
            |n: u64, control: &Control, stages: &Stages<u64>| {
                std::thread::sleep(Duration::from_millis(if n == 0 { 600 } else { 200 }));
                stages.send(10 * n + 1);
                while n == 1 && !control.cancelled() {
                    std::thread::yield_now();
                }
                10 * n + 9
            },
            || {},
        );
        slot.hold_at_most = Duration::from_secs(3600);
        slot.request(0);
        assert_eq!(drain_runs(&mut slot), [1, 9]);
        slot.request(1);
        // A drag's next change, made while run 1 is due: held.
        slot.request(2);
        // The frame run 1 lands in, taken as a scene takes it (everything landed, until
        // nothing more has)...
        let start = Instant::now();
        let mut taken = vec![];
        while taken.is_empty() {
            while let Some(l) = slot.poll_stage() {
                slot.record_run(l.job_time, l.since_request);
                taken.push(l.output);
            }
            assert!(start.elapsed() < Duration::from_secs(60), "no run");
            std::thread::sleep(Duration::from_millis(1));
        }
        assert_eq!(taken, [11]);
        // ...makes its own change before the frame ends: it goes at once, in place of the one
        // held (which would only wait behind it).
        slot.request(4);
        assert_eq!(drain_runs(&mut slot), [41, 49]);
        assert_eq!(slot.runs, 3);
    }

    #[test]
    fn a_job_of_one_output_never_waits_for_a_frame_before_its_later_stages() {
        // The bar scenes' jobs: a solve and its estimate, one output at the end.
        let mut slot = SolveSlot::new(
            |n: u64, control: &Control| {
                control.stage(1, 2);
                n + 1
            },
            || {},
        );
        slot.request(7);
        let start = Instant::now();
        let out = loop {
            if let Some(out) = slot.poll() {
                break out;
            }
            // No frame ends here (no flush): nothing may wait for one.
            assert!(
                start.elapsed() < Duration::from_secs(1),
                "it waited for a frame"
            );
            std::thread::sleep(Duration::from_millis(1));
        };
        assert_eq!(out, 8);
    }

    #[test]
    fn a_jobs_checks_wait_for_a_frame_that_shows_its_run_and_makes_no_newer_change() {
        let (told, checks) = channel::<u64>();
        let mut slot = SolveSlot::staged(
            move |n: u64, control: &Control, stages: &Stages<u64>| {
                stages.send(10 * n + 1);
                control.stage(1, 2);
                told.send(n).expect("the test listens");
                10 * n + 9
            },
            || {},
        );
        slot.request(5);
        let start = Instant::now();
        while slot.poll_stage().is_none() {
            assert!(start.elapsed() < Duration::from_secs(60), "no run");
            std::thread::sleep(Duration::from_millis(1));
        }
        // The run is taken; no frame has ended yet: the checks wait.
        std::thread::sleep(Duration::from_millis(200));
        assert!(
            checks.try_recv().is_err(),
            "the checks went before the frame ended"
        );
        // The frame ends without a newer change: they go.
        slot.flush();
        assert_eq!(checks.recv_timeout(Duration::from_secs(2)), Ok(5));
        assert_eq!(drain_runs(&mut slot), [59]);
    }

    #[test]
    fn a_job_whose_run_a_change_waits_for_does_no_checks_before_that_change_goes() {
        let (told, checks) = channel::<(u64, bool)>();
        let (go, gate) = channel::<()>();
        let gate = std::sync::Mutex::new(gate);
        // After its run a job starts its checks as the scenes' do (a later stage), and says
        // whether it was cancelled by then: the checks of a run a change waited for would
        // only be thrown away. Request 1 gives its run once the change is held.
        let mut slot = SolveSlot::staged(
            move |n: u64, control: &Control, stages: &Stages<u64>| {
                if n == 0 {
                    std::thread::sleep(WARM_UP);
                }
                if n == 1 {
                    let gate = gate.lock().expect("one job at a time");
                    gate.recv_timeout(Duration::from_secs(60))
                        .expect("the test says go");
                }
                stages.send(10 * n + 1);
                control.stage(1, 2);
                told.send((n, control.cancelled()))
                    .expect("the test listens");
                10 * n + 9
            },
            || {},
        );
        slot.hold_at_most = Duration::from_secs(3600);
        slot.request(0);
        assert_eq!(drain_runs(&mut slot), [1, 9]);
        slot.request(1);
        slot.request(2);
        go.send(()).expect("request 1 waits");
        assert_eq!(drain_runs(&mut slot), [11, 21, 29]);
        let told: Vec<(u64, bool)> = checks.try_iter().collect();
        // Request 0 ran its checks (nothing waited for it), request 1 only once cancelled by
        // request 2, which ran them.
        assert_eq!(told, [(0, false), (1, true), (2, false)]);
    }

    #[test]
    fn a_change_waits_no_longer_than_its_hold_for_a_run_that_does_not_come() {
        let hold = Duration::from_millis(50);
        let mut slot = warmed_up(hold);
        let start = Instant::now();
        // Request 3 gives no run until cancelled.
        slot.request(3);
        slot.request(2);
        assert_eq!(drain_runs(&mut slot), [21, 29]);
        assert!(start.elapsed() >= hold, "{:?}", start.elapsed());
    }

    #[test]
    fn cancel_drops_a_held_change() {
        let mut slot = warmed_up(Duration::from_secs(3600));
        slot.request(1);
        slot.request(2);
        slot.cancel();
        // Request 1 was cancelled with its run not yet taken or after it; request 2 never went.
        let taken = drain_runs(&mut slot);
        assert!(taken.iter().all(|o| o / 10 == 1), "{taken:?}");
    }

    #[test]
    fn before_a_first_run_has_landed_a_change_goes_at_once() {
        let mut slot = SolveSlot::staged(run_then_checks, || {});
        slot.hold_at_most = Duration::from_secs(3600);
        // Request 3 never gives a run: held behind it, request 2 would wait an hour.
        slot.request(3);
        slot.request(2);
        assert_eq!(drain_runs(&mut slot), [21, 29]);
    }

    #[test]
    fn a_panic_after_a_stage_is_the_requests_error_and_the_next_request_stages_again() {
        let mut slot = SolveSlot::staged(
            |n: u64, _: &Control, stages: &Stages<u64>| {
                stages.send(n);
                assert!(n != 13, "unlucky input");
                n * 2
            },
            || {},
        );
        slot.request(13);
        assert_eq!(drain(&mut slot), [(13, false)]);
        let error = slot.error.clone().expect("the panic is the error");
        assert!(error.contains("unlucky input"), "{error}");
        slot.request(4);
        assert_eq!(drain(&mut slot), [(4, false), (8, true)]);
        assert_eq!(slot.error, None);
    }

    #[test]
    fn a_panicking_solve_is_reported_and_the_thread_lives_on() {
        let mut w = Worker::new(
            |n: u64, _: &Control| {
                assert!(n != 13, "unlucky input");
                n * 2
            },
            || {},
        );
        w.request(13);
        let msg = wait(&mut w).output.unwrap_err();
        assert!(msg.contains("unlucky input"), "{msg}");
        w.request(4);
        assert_eq!(wait(&mut w).output, Ok(8));
    }
}
