//! The explorer's background work: one queue type, served by threads of its own, for any kind of
//! job (the solves and the studies each have a queue of their own, so that a work-precision
//! ladder never delays a solve; the solves are served by two threads, so that an edit's laws are
//! solved on both cores). A job belongs to a slot (a model, a kind of study); a newer job of the
//! same slot supersedes a queued one, and the running one may stop early: it polls whether
//! [`Jobs::submit`] has recorded a newer generation for its slot since. A queue may also say when
//! it falls idle (nothing queued, nothing running) after its reports, so that a listener can wait
//! for a whole batch with one wake-up rather than one per report. A listener must be ready for
//! a batch's reports before it queues it: a thread woken by the queuing may take the queuing
//! thread's core at once (on two cores it usually does), which then runs again only once the
//! batch is done.

use std::any::Any;
use std::collections::HashMap;
use std::hash::Hash;
use std::panic::{self, AssertUnwindSafe};
use std::sync::{Arc, Condvar, Mutex, MutexGuard, PoisonError};
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

/// A report of a queue: an outcome, or the message of a panic (a bug; the queue's threads stop).
pub type Report<T> = Result<T, String>;

/// What the handle and the queue's threads share.
struct Shared<J: Background> {
    state: Mutex<State<J>>,
    /// Signalled when a job is queued or the queue closes.
    changed: Condvar,
}

struct State<J: Background> {
    /// Jobs not yet started.
    queue: Vec<J>,
    /// Jobs started and not yet reported.
    running: usize,
    /// The generation of the latest request of every slot.
    latest: HashMap<J::Slot, u64>,
    /// False once the handle is dropped, nobody listens or a job panicked: the threads end.
    open: bool,
}

impl<J: Background> Shared<J> {
    fn new() -> Self {
        Shared {
            state: Mutex::new(State {
                queue: Vec::new(),
                running: 0,
                latest: HashMap::new(),
                open: true,
            }),
            changed: Condvar::new(),
        }
    }

    /// A panic never happens while the state is held, so a poisoned lock still holds a whole one.
    fn lock(&self) -> MutexGuard<'_, State<J>> {
        self.state.lock().unwrap_or_else(PoisonError::into_inner)
    }

    /// The next job to run, waiting for one; `None` once the queue is closed.
    fn next(&self) -> Option<J> {
        let mut state = self.lock();
        loop {
            if !state.open {
                return None;
            }
            if let Some(job) = take_next(&mut state.queue) {
                state.running += 1;
                return Some(job);
            }
            state = self
                .changed
                .wait(state)
                .unwrap_or_else(PoisonError::into_inner);
        }
    }

    fn is_superseded(&self, slot: J::Slot, generation: u64) -> bool {
        let state = self.lock();
        state
            .latest
            .get(&slot)
            .is_some_and(|&newest| newest != generation)
    }

    /// A started job has reported (or ended without a report): whether the queue is now idle.
    fn finished(&self) -> bool {
        let mut state = self.lock();
        state.running = state.running.saturating_sub(1);
        state.queue.is_empty() && state.running == 0
    }

    fn close(&self) {
        self.lock().open = false;
        self.changed.notify_all();
    }
}

/// Handle of a queue's threads; dropping it ends them after their current jobs.
pub struct Jobs<J: Background> {
    shared: Arc<Shared<J>>,
}

impl<J: Background> Jobs<J> {
    /// Starts `threads` threads named `name` on one queue; `deliver` receives every report (from
    /// any of them) and returns false once nobody listens.
    pub fn spawn(
        name: &str,
        threads: usize,
        deliver: impl Fn(Report<J::Outcome>) -> bool + Send + Sync + 'static,
    ) -> std::io::Result<Jobs<J>> {
        Jobs::spawn_with_idle(name, threads, deliver, || {})
    }

    /// [`Jobs::spawn`], and `idle` is called whenever the queue falls idle: every job submitted
    /// so far has been delivered (or superseded), none is queued or running.
    pub fn spawn_with_idle(
        name: &str,
        threads: usize,
        deliver: impl Fn(Report<J::Outcome>) -> bool + Send + Sync + 'static,
        idle: impl Fn() + Send + Sync + 'static,
    ) -> std::io::Result<Jobs<J>> {
        let shared = Arc::new(Shared::new());
        let deliver = Arc::new(deliver);
        let idle = Arc::new(idle);
        for _ in 0..threads.max(1) {
            let (ours, deliver, idle) =
                (Arc::clone(&shared), Arc::clone(&deliver), Arc::clone(&idle));
            let started = thread::Builder::new()
                .name(name.into())
                .spawn(move || serve(&ours, deliver.as_ref(), idle.as_ref()));
            if let Err(e) = started {
                shared.close();
                return Err(e);
            }
        }
        Ok(Jobs { shared })
    }

    /// Queues a job and marks older jobs of its slot as superseded; false if the threads stopped.
    pub fn submit(&self, job: J) -> bool {
        self.submit_all([job])
    }

    /// [`Jobs::submit`] for every job of `jobs`, queued together: one lock and one wake-up of
    /// the threads for an edit's laws, not one each (a wake-up is a system call, and a thread
    /// woken by the first job would contend for the lock with the queuing of the rest).
    pub fn submit_all(&self, jobs: impl IntoIterator<Item = J>) -> bool {
        let mut state = self.shared.lock();
        if !state.open {
            return false;
        }
        let mut queued = 0;
        for job in jobs {
            state.latest.insert(job.slot(), job.generation());
            supersede(&mut state.queue, job);
            queued += 1;
        }
        drop(state);
        match queued {
            0 => {}
            1 => self.shared.changed.notify_one(),
            _ => self.shared.changed.notify_all(),
        }
        true
    }
}

impl<J: Background> Drop for Jobs<J> {
    fn drop(&mut self) {
        self.shared.close();
    }
}

/// Runs the queue's jobs until it closes; closes it when a job panics or nobody listens. A job's
/// report is delivered before the job counts as finished, so when `idle` is called every report
/// of the jobs before it has been delivered, by whichever thread.
fn serve<J: Background>(
    shared: &Shared<J>,
    deliver: &dyn Fn(Report<J::Outcome>) -> bool,
    idle: &dyn Fn(),
) {
    while let Some(job) = shared.next() {
        let (slot, generation) = (job.slot(), job.generation());
        let stop = || shared.is_superseded(slot, generation);
        let partial = |outcome| {
            deliver(Ok(outcome));
        };
        let report = panic::catch_unwind(AssertUnwindSafe(|| job.run_partially(&stop, &partial)))
            .map_err(|payload| job.panicked(&panic_message(payload.as_ref())));
        let panicked = report.is_err();
        let delivered = match report {
            Ok(Some(outcome)) => deliver(Ok(outcome)),
            // Superseded on the way: its successor reports instead.
            Ok(None) => true,
            Err(message) => deliver(Err(message)),
        };
        if !delivered || panicked {
            shared.close();
            return;
        }
        if shared.finished() {
            idle();
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
    use std::sync::mpsc;

    /// Lets the probes of slot 8 end.
    static GO: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

    /// A job of slot `slot` that counts its checks of `stop` and reports its generation; slot 9
    /// panics, slot 8 waits for [`GO`].
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
            while self.slot == 8 && !GO.load(std::sync::atomic::Ordering::SeqCst) {
                thread::yield_now();
            }
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
        // of another slot is not stopped by it; its report, answered "nobody listens", ends it.
        let shared = Shared::new();
        {
            let mut state = shared.lock();
            state.latest.insert(0, 2);
            state.queue.extend([probe(1, 0, 0), probe(3, 1, 0)]);
        }
        let reports = Mutex::new(Vec::new());
        serve(
            &shared,
            &|r| {
                reports.lock().unwrap().push(r);
                false
            },
            &|| {},
        );
        assert_eq!(*reports.lock().unwrap(), [Ok(3)]);
        assert!(!shared.lock().open, "closed: nobody listens");

        // Through the threads: the latest request reports, and dropping the handle ends them.
        let (tx, rx) = mpsc::channel();
        let queue = Jobs::spawn("test-jobs", 2, move |report| tx.send(report).is_ok()).unwrap();
        assert!(queue.submit(probe(4, 0, 0)));
        assert_eq!(rx.recv().unwrap(), Ok(4));
        drop(queue);
        assert!(rx.recv().is_err(), "the threads ended");
    }

    #[test]
    fn idle_is_said_once_the_last_queued_job_has_reported() {
        // Served on this thread: three jobs queued at once report one by one, and the queue says
        // it is idle once, after the third (the listener's one wake-up for the batch).
        let shared = Shared::new();
        shared
            .lock()
            .queue
            .extend([probe(1, 0, 0), probe(2, 1, 0), probe(3, 2, 0)]);
        let heard = Mutex::new(Vec::new());
        serve(
            &shared,
            &|r| {
                heard.lock().unwrap().push(format!("{r:?}"));
                true
            },
            &|| {
                heard.lock().unwrap().push("idle".into());
                shared.close();
            },
        );
        assert_eq!(*heard.lock().unwrap(), ["Ok(1)", "Ok(2)", "Ok(3)", "idle"]);
        assert_eq!(shared.lock().running, 0);
    }

    #[test]
    fn two_threads_serve_one_queue() {
        // Slot 8 blocks until told to go on: with two threads, the other jobs are served meanwhile.
        let (tx, rx) = mpsc::channel();
        let queue = Jobs::spawn("test-jobs", 2, move |report| tx.send(report).is_ok()).unwrap();
        assert!(queue.submit(probe(1, 8, 0)));
        assert!(queue.submit(probe(2, 1, 0)));
        assert!(queue.submit(probe(3, 2, 0)));
        assert_eq!(rx.recv().unwrap(), Ok(2));
        assert_eq!(rx.recv().unwrap(), Ok(3));
        GO.store(true, std::sync::atomic::Ordering::SeqCst);
        assert_eq!(rx.recv().unwrap(), Ok(1));
    }

    #[test]
    fn a_batch_is_queued_whole_so_its_own_stale_jobs_never_run() {
        // Generation 1 and 2 of slot 0 in one batch: no thread can take 1 before 2 replaces it.
        let (tx, rx) = mpsc::channel();
        let queue = Jobs::spawn("test-jobs", 2, move |report| tx.send(report).is_ok()).unwrap();
        assert!(queue.submit_all([probe(1, 0, 0), probe(2, 0, 0), probe(3, 1, 0)]));
        let mut reports: Vec<Report<u64>> = (0..2).map(|_| rx.recv().unwrap()).collect();
        reports.sort();
        assert_eq!(reports, [Ok(2), Ok(3)]);
        assert!(queue.submit_all([]), "an empty batch queues nothing");
        drop(queue);
        assert!(rx.recv().is_err(), "nothing more was reported");
    }

    #[test]
    fn a_job_reports_what_it_has_so_far_then_its_end_in_order() {
        let (tx, rx) = mpsc::channel();
        let queue = Jobs::spawn("test-jobs", 1, move |report| tx.send(report).is_ok()).unwrap();
        assert!(queue.submit(probe(2, 7, 0)));
        assert!(queue.submit(probe(3, 1, 0)));
        let reports: Vec<Report<u64>> = (0..4).map(|_| rx.recv().unwrap()).collect();
        assert_eq!(reports, [Ok(200), Ok(202), Ok(2), Ok(3)]);
    }

    #[test]
    fn a_panic_is_reported_and_stops_the_thread() {
        let (tx, rx) = mpsc::channel();
        let queue = Jobs::spawn("test-jobs", 1, move |report| tx.send(report).is_ok()).unwrap();
        assert!(queue.submit(probe(1, 9, 0)));
        assert_eq!(rx.recv().unwrap(), Err("slot 9 panicked (probe 1)".into()));
        assert!(rx.recv().is_err(), "the threads ended");
    }

    #[test]
    fn panic_payloads_become_messages() {
        assert_eq!(panic_message(&"boom"), "boom");
        assert_eq!(panic_message(&String::from("bang")), "bang");
        assert_eq!(panic_message(&42), "no message");
    }
}
