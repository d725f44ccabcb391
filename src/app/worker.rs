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
