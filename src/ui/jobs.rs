//! The explorer's background work: one queue type, one thread per queue, for any kind of job (the
//! solves and the studies each have a queue of their own, so that a work-precision ladder never
//! delays a solve). A job belongs to a slot (a model, a kind of study); a newer job of the same
//! slot supersedes a queued one, and the running one may stop early: it polls whether
//! [`Jobs::submit`] has recorded a newer generation for its slot since.

use std::any::Any;
use std::collections::HashMap;
use std::hash::Hash;
use std::panic::{self, AssertUnwindSafe};
use std::sync::mpsc::{self, Receiver, Sender};
use std::sync::{Arc, Mutex, PoisonError};
use std::thread;

/// Work the queue runs off the UI thread.
pub trait Background: Send + 'static {
    /// What a newer job replaces: the older job of the same slot.
    type Slot: Copy + Eq + Hash + Send + Sync + 'static;
    type Outcome: Send + 'static;

    fn slot(&self) -> Self::Slot;
    /// The request's number: a later request has a larger one.
    fn generation(&self) -> u64;
    /// Queued jobs run lowest first, the oldest first among equals.
    fn priority(&self) -> u8 {
        0
    }
    /// Runs the job; `None` when `stop` said it was superseded on the way (its successor reports).
    fn run(&self, stop: &(dyn Fn() -> bool + Sync)) -> Option<Self::Outcome>;
    /// [`Background::run`] for a job whose result grows (a bifurcation diagram column by column):
    /// it may hand outcomes so far to `partial`, each reported like the final one, so that the
    /// screen fills in as it computes. Most jobs have nothing to show before they end.
    fn run_partially(
        &self,
        stop: &(dyn Fn() -> bool + Sync),
        _partial: &dyn Fn(Self::Outcome),
    ) -> Option<Self::Outcome> {
        self.run(stop)
    }
    /// The report of a panic while running it, from the panic's message.
    fn panicked(&self, message: &str) -> String;
}

/// A report of a queue: an outcome, or the message of a panic (a bug; the queue's thread stops).
pub type Report<T> = Result<T, String>;

/// The generation of the latest request of every slot.
type Latest<S> = Arc<Mutex<HashMap<S, u64>>>;

/// Handle of a queue's thread; dropping it ends the thread after the current job.
pub struct Jobs<J: Background> {
    jobs: Sender<J>,
    latest: Latest<J::Slot>,
}

impl<J: Background> Jobs<J> {
    /// Starts the thread `name`; `deliver` receives every report and returns false once nobody
    /// listens.
    pub fn spawn(
        name: &str,
        deliver: impl Fn(Report<J::Outcome>) -> bool + Send + 'static,
    ) -> std::io::Result<Jobs<J>> {
        let (jobs, queue) = mpsc::channel();
        let latest: Latest<J::Slot> = Arc::default();
        let seen = Arc::clone(&latest);
        thread::Builder::new()
            .name(name.into())
            .spawn(move || serve(&queue, &seen, deliver))?;
        Ok(Jobs { jobs, latest })
    }

    /// Queues a job and marks older jobs of its slot as superseded; false if the thread stopped.
    pub fn submit(&self, job: J) -> bool {
        record(&self.latest, job.slot(), job.generation());
        self.jobs.send(job).is_ok()
    }
}

fn record<S: Eq + Hash>(latest: &Mutex<HashMap<S, u64>>, slot: S, generation: u64) {
    // A panic never happens while the map is held, so a poisoned lock still holds a whole map.
    let mut map = latest.lock().unwrap_or_else(PoisonError::into_inner);
    map.insert(slot, generation);
}

fn is_superseded<S: Eq + Hash>(latest: &Mutex<HashMap<S, u64>>, slot: S, generation: u64) -> bool {
    let map = latest.lock().unwrap_or_else(PoisonError::into_inner);
    map.get(&slot).is_some_and(|&newest| newest != generation)
}

fn serve<J: Background>(
    incoming: &Receiver<J>,
    latest: &Latest<J::Slot>,
    deliver: impl Fn(Report<J::Outcome>) -> bool,
) {
    let mut queue: Vec<J> = Vec::new();
    loop {
        if queue.is_empty() {
            match incoming.recv() {
                Ok(job) => queue.push(job),
                Err(_) => return,
            }
        }
        for job in incoming.try_iter() {
            supersede(&mut queue, job);
        }
        let Some(job) = take_next(&mut queue) else {
            continue;
        };
        let (slot, generation) = (job.slot(), job.generation());
        let stop = || is_superseded(latest, slot, generation);
        let partial = |outcome| {
            deliver(Ok(outcome));
        };
        let report = panic::catch_unwind(AssertUnwindSafe(|| job.run_partially(&stop, &partial)))
            .map_err(|payload| job.panicked(&panic_message(payload.as_ref())));
        let stop_thread = report.is_err();
        let delivered = match report {
            Ok(Some(outcome)) => deliver(Ok(outcome)),
            // Superseded on the way: its successor reports instead.
            Ok(None) => true,
            Err(message) => deliver(Err(message)),
        };
        if !delivered || stop_thread {
            return;
        }
    }
}

/// Adds `job` to the queue, dropping a queued job of the same slot (it is stale).
pub fn supersede<J: Background>(queue: &mut Vec<J>, job: J) {
    let slot = job.slot();
    queue.retain(|queued| queued.slot() != slot);
    queue.push(job);
}

/// The queued job of the lowest priority, the oldest first among equals.
pub fn take_next<J: Background>(queue: &mut Vec<J>) -> Option<J> {
    let i = queue
        .iter()
        .enumerate()
        .min_by_key(|(i, j)| (j.priority(), *i))
        .map(|(i, _)| i)?;
    Some(queue.remove(i))
}

fn panic_message(payload: &(dyn Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        (*s).to_string()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "no message".into()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A job of slot `slot` that counts its checks of `stop` and reports its generation; slot 9
    /// panics.
    #[derive(Debug)]
    struct Probe {
        slot: u8,
        generation: u64,
        priority: u8,
    }

    impl Background for Probe {
        type Slot = u8;
        type Outcome = u64;

        fn slot(&self) -> u8 {
            self.slot
        }

        fn generation(&self) -> u64 {
            self.generation
        }

        fn priority(&self) -> u8 {
            self.priority
        }

        fn run(&self, stop: &(dyn Fn() -> bool + Sync)) -> Option<u64> {
            assert!(self.slot != 9, "probe {}", self.generation);
            (!stop()).then_some(self.generation)
        }

        /// Slot 7 reports two outcomes so far (100 and 101 times its generation) before its end.
        fn run_partially(
            &self,
            stop: &(dyn Fn() -> bool + Sync),
            partial: &dyn Fn(u64),
        ) -> Option<u64> {
            if self.slot == 7 {
                partial(100 * self.generation);
                partial(101 * self.generation);
            }
            self.run(stop)
        }

        fn panicked(&self, message: &str) -> String {
            format!("slot {} panicked ({message})", self.slot)
        }
    }

    fn probe(generation: u64, slot: u8, priority: u8) -> Probe {
        Probe {
            slot,
            generation,
            priority,
        }
    }

    fn generations(queue: &[Probe]) -> Vec<u64> {
        queue.iter().map(|j| j.generation).collect()
    }

    #[test]
    fn newer_jobs_replace_queued_ones_of_their_slot_and_low_priorities_go_first() {
        let mut queue = vec![probe(1, 0, 2), probe(2, 1, 1), probe(3, 2, 0)];
        supersede(&mut queue, probe(4, 2, 0));
        assert_eq!(generations(&queue), [1, 2, 4]);
        supersede(&mut queue, probe(5, 3, 1));
        assert_eq!(take_next(&mut queue).map(|j| j.generation), Some(4));
        assert_eq!(take_next(&mut queue).map(|j| j.generation), Some(2));
        assert_eq!(take_next(&mut queue).map(|j| j.generation), Some(5));
        assert_eq!(take_next(&mut queue).map(|j| j.generation), Some(1));
        assert!(take_next(&mut queue).is_none());
    }

    #[test]
    fn a_superseded_job_stops_and_only_the_latest_reports() {
        // Served on this thread: job 1 runs although generation 2 was already asked for, as when
        // a newer request arrives mid-job; it stops at its first check and reports nothing. Job 3
        // of another slot is not stopped by it.
        let (jobs, incoming) = mpsc::channel();
        let latest: Latest<u8> = Arc::default();
        record(&latest, 0, 2);
        jobs.send(probe(1, 0, 0)).unwrap();
        jobs.send(probe(3, 1, 0)).unwrap();
        drop(jobs);
        let reports = Mutex::new(Vec::new());
        serve(&incoming, &latest, |r| {
            reports.lock().unwrap().push(r);
            true
        });
        assert_eq!(*reports.lock().unwrap(), [Ok(3)]);

        // Through the thread: the latest request reports, and dropping the handle ends it.
        let (tx, rx) = mpsc::channel();
        let queue = Jobs::spawn("test-jobs", move |report| tx.send(report).is_ok()).unwrap();
        assert!(queue.submit(probe(4, 0, 0)));
        assert_eq!(rx.recv().unwrap(), Ok(4));
        drop(queue);
        assert!(rx.recv().is_err(), "the thread ended");
    }

    #[test]
    fn a_job_reports_what_it_has_so_far_then_its_end_in_order() {
        let (tx, rx) = mpsc::channel();
        let queue = Jobs::spawn("test-jobs", move |report| tx.send(report).is_ok()).unwrap();
        assert!(queue.submit(probe(2, 7, 0)));
        assert!(queue.submit(probe(3, 1, 0)));
        let reports: Vec<Report<u64>> = (0..4).map(|_| rx.recv().unwrap()).collect();
        assert_eq!(reports, [Ok(200), Ok(202), Ok(2), Ok(3)]);
    }

    #[test]
    fn a_panic_is_reported_and_stops_the_thread() {
        let (tx, rx) = mpsc::channel();
        let queue = Jobs::spawn("test-jobs", move |report| tx.send(report).is_ok()).unwrap();
        assert!(queue.submit(probe(1, 9, 0)));
        assert_eq!(rx.recv().unwrap(), Err("slot 9 panicked (probe 1)".into()));
        assert!(rx.recv().is_err(), "the thread ended");
    }

    #[test]
    fn panic_payloads_become_messages() {
        assert_eq!(panic_message(&"boom"), "boom");
        assert_eq!(panic_message(&String::from("bang")), "bang");
        assert_eq!(panic_message(&42), "no message");
    }
}
