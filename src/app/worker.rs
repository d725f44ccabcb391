//! A solver thread for a scene: the UI posts the latest inputs and keeps drawing the last result.
//! Each request carries a [`Control`]; a newer request (or Cancel) cancels the running solve,
//! whose loops look at it every few thousand steps, so the thread always moves on to the newest
//! inputs at once and a dragged slider never queues up solves. A panic in a solve is caught and
//! reported as that request's outcome; the thread lives on.

use crate::model::control::Control;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::Arc;
use std::sync::mpsc::{Receiver, Sender, channel};
use std::time::{Duration, Instant};

/// A finished job: the request's number, its output (or the message of the panic that ended
/// it) and how long the solve took.
pub struct Done<O> {
    pub id: u64,
    pub output: Result<O, String>,
    pub elapsed: Duration,
}

type Request<I> = (u64, I, Arc<Control>);

/// A solve that lands within this shows no progress bar.
pub const PROGRESS_AFTER: Duration = Duration::from_millis(50);

/// What a scene shows when its solve panicked: the panic's message, and that the last result is
/// kept.
pub fn internal_error(panic: &str) -> String {
    format!("the solver stopped on an internal error ({panic}); the last result is kept")
}

pub struct Worker<I, O> {
    to_worker: Sender<Request<I>>,
    from_worker: Receiver<Done<O>>,
    next_id: u64,
    /// The newest request: its number, when it was made and its control.
    pending: Option<(u64, Instant, Arc<Control>)>,
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
    /// Starts the thread; `wake` is called after each job (to request a repaint).
    pub fn new(
        job: impl Fn(I, &Control) -> O + Send + 'static,
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
                    let output = catch_unwind(AssertUnwindSafe(|| job(input, &control)))
                        .map_err(|p| panic_message(p.as_ref()));
                    let done = Done {
                        id,
                        output,
                        elapsed: start.elapsed(),
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
        }
    }

    /// Posts new inputs; the solve under way, if any, is cancelled.
    pub fn request(&mut self, input: I) {
        self.cancel();
        self.next_id += 1;
        let control = Arc::new(Control::new());
        self.pending = Some((self.next_id, Instant::now(), control.clone()));
        // A send only fails once the thread is gone, and then there is nothing left to do.
        let _ = self.to_worker.send((self.next_id, input, control));
    }

    /// Asks the solve under way to stop; its outcome (a cancellation) still arrives.
    pub fn cancel(&self) {
        if let Some((_, _, control)) = &self.pending {
            control.cancel();
        }
    }

    /// The newest request's outcome, if it arrived, with the time from its request to now.
    /// Outcomes of older (cancelled) requests are dropped.
    pub fn poll(&mut self) -> Option<(Done<O>, Duration)> {
        let mut newest = None;
        while let Ok(done) = self.from_worker.try_recv() {
            if self.pending.as_ref().is_some_and(|p| p.0 == done.id) {
                newest = Some(done);
            }
        }
        let done = newest?;
        let (_, at, _) = self.pending.take()?;
        Some((done, at.elapsed()))
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
}

impl<I: Send + 'static, O: Send + 'static> SolveSlot<I, O> {
    /// Starts the solver thread; `wake` is called after each job.
    pub fn new(
        job: impl Fn(I, &Control) -> O + Send + 'static,
        wake: impl Fn() + Send + 'static,
    ) -> Self {
        SolveSlot {
            worker: Worker::new(job, wake),
            solve_time: Duration::ZERO,
            latency: Duration::ZERO,
            error: None,
        }
    }

    /// Posts new inputs; the solve under way, if any, is cancelled.
    pub fn request(&mut self, input: I) {
        self.worker.request(input);
    }

    /// Asks the solve under way to stop.
    pub fn cancel(&self) {
        self.worker.cancel();
    }

    pub fn busy(&self) -> bool {
        self.worker.busy()
    }

    /// The running solve's progress, once it has taken longer than a frame.
    pub fn progress(&self) -> Option<f64> {
        self.worker.progress(PROGRESS_AFTER)
    }

    /// The last landed solve's time and its change-to-result latency.
    pub fn timings(&self) -> (Duration, Duration) {
        (self.solve_time, self.latency)
    }

    /// The newest request's output once it lands, its timings recorded and the error cleared.
    /// A solve that panicked gives `None` and leaves the panic's message as the error.
    pub fn poll(&mut self) -> Option<O> {
        let (done, latency) = self.worker.poll()?;
        self.solve_time = done.elapsed;
        self.latency = latency;
        match done.output {
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
