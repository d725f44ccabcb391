//! A solver thread for a scene: the UI posts the latest inputs and keeps drawing the last result;
//! the thread always works on the newest request (older ones are dropped), so a dragged slider
//! never queues up solves and the UI thread never waits.

use std::sync::mpsc::{Receiver, Sender, channel};
use std::time::{Duration, Instant};

/// A finished job: the request's number, its output and how long the solve took.
pub struct Done<O> {
    pub id: u64,
    pub output: O,
    pub elapsed: Duration,
}

pub struct Worker<I, O> {
    to_worker: Sender<(u64, I)>,
    from_worker: Receiver<Done<O>>,
    next_id: u64,
    pending: Option<(u64, Instant)>,
}

impl<I: Send + 'static, O: Send + 'static> Worker<I, O> {
    /// Starts the thread; `wake` is called after each job (to request a repaint).
    pub fn new(job: impl Fn(I) -> O + Send + 'static, wake: impl Fn() + Send + 'static) -> Self {
        let (to_worker, inbox) = channel::<(u64, I)>();
        let (outbox, from_worker) = channel::<Done<O>>();
        std::thread::Builder::new()
            .name("pounding-solver".into())
            .spawn(move || {
                while let Ok(mut request) = inbox.recv() {
                    // Skip to the newest request.
                    while let Ok(newer) = inbox.try_recv() {
                        request = newer;
                    }
                    let start = Instant::now();
                    let output = job(request.1);
                    if outbox
                        .send(Done {
                            id: request.0,
                            output,
                            elapsed: start.elapsed(),
                        })
                        .is_err()
                    {
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

    pub fn request(&mut self, input: I) {
        self.next_id += 1;
        self.pending = Some((self.next_id, Instant::now()));
        // A send only fails once the thread is gone, and then there is nothing left to do.
        let _ = self.to_worker.send((self.next_id, input));
    }

    /// The newest finished job, if one arrived, with the time from its request to now.
    pub fn poll(&mut self) -> Option<(Done<O>, Duration)> {
        let mut newest = None;
        while let Ok(done) = self.from_worker.try_recv() {
            newest = Some(done);
        }
        let done = newest?;
        let latency = match self.pending {
            Some((id, at)) if id == done.id => {
                self.pending = None;
                at.elapsed()
            }
            Some((_, at)) => at.elapsed(),
            None => Duration::ZERO,
        };
        Some((done, latency))
    }

    pub fn busy(&self) -> bool {
        self.pending.is_some()
    }
}
