//! Computes studies off the UI thread, on a thread of their own so that a work-precision ladder
//! never delays the explorer's solves. A newer request of a kind supersedes the queued one, and
//! stops the running one between rungs or points: the running study polls the latest generation
//! that [`StudyWorker::submit`] recorded for its kind.

use std::panic::{self, AssertUnwindSafe};
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::mpsc::{self, Receiver, Sender};
use std::thread;

use super::worker::panic_message;
use crate::model::study::runner::{StudyJob, StudyKind, StudyOutcome, run};

/// A report of the study worker: an outcome, or the message of a panic (a bug; the worker stops).
pub type StudyReport = Result<StudyOutcome, String>;

/// The generation of the latest request of every kind.
type Latest = Arc<[AtomicU64; StudyKind::ALL.len()]>;

/// Handle of the study thread; dropping it ends the thread after the current study.
pub struct StudyWorker {
    jobs: Sender<StudyJob>,
    latest: Latest,
}

impl StudyWorker {
    /// Starts the thread; `deliver` receives every report and returns false once nobody listens.
    pub fn spawn(
        deliver: impl Fn(StudyReport) -> bool + Send + 'static,
    ) -> std::io::Result<StudyWorker> {
        let (jobs, queue) = mpsc::channel();
        let latest: Latest = Arc::new(Default::default());
        let seen = Arc::clone(&latest);
        thread::Builder::new()
            .name("hertz-studies".into())
            .spawn(move || serve(&queue, &seen, deliver))?;
        Ok(StudyWorker { jobs, latest })
    }

    /// Queues a job and marks older jobs of its kind as superseded; false if the worker stopped.
    pub fn submit(&self, job: StudyJob) -> bool {
        self.latest[job.spec.kind().index()].store(job.generation, Ordering::Release);
        self.jobs.send(job).is_ok()
    }
}

fn serve(incoming: &Receiver<StudyJob>, latest: &Latest, deliver: impl Fn(StudyReport) -> bool) {
    let mut queue: Vec<StudyJob> = Vec::new();
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
        let kind = job.spec.kind();
        let stop = || latest[kind.index()].load(Ordering::Acquire) != job.generation;
        let report = panic::catch_unwind(AssertUnwindSafe(|| run(&job, &stop))).map_err(|p| {
            format!(
                "a {kind:?} study panicked ({}): this is a bug",
                panic_message(p.as_ref())
            )
        });
        let stop_worker = report.is_err();
        let delivered = match report {
            Ok(Some(outcome)) => deliver(Ok(outcome)),
            // Superseded on the way: its successor reports instead.
            Ok(None) => true,
            Err(message) => deliver(Err(message)),
        };
        if !delivered || stop_worker {
            return;
        }
    }
}

/// Adds `job` to the queue, dropping a queued job of the same kind (it is stale).
pub fn supersede(queue: &mut Vec<StudyJob>, job: StudyJob) {
    let kind = job.spec.kind();
    queue.retain(|queued| queued.spec.kind() != kind);
    queue.push(job);
}

/// The queued job of the quickest kind, the oldest first among equals.
fn take_next(queue: &mut Vec<StudyJob>) -> Option<StudyJob> {
    let i = queue
        .iter()
        .enumerate()
        .min_by_key(|(i, j)| (j.spec.kind().priority(), *i))
        .map(|(i, _)| i)?;
    Some(queue.remove(i))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::ForceModel;
    use crate::model::study::runner::StudySpec;
    use crate::ui::testing::fig5_params;

    fn kinds(queue: &[StudyJob]) -> Vec<StudyKind> {
        queue.iter().map(|j| j.spec.kind()).collect()
    }

    fn job(generation: u64, kind: StudyKind) -> StudyJob {
        let model = ForceModel::Proposed;
        let params = fig5_params(0.3);
        let spec = match kind {
            StudyKind::WorkPrecision => StudySpec::WorkPrecision { model, params },
            StudyKind::Bounds => StudySpec::Bounds { model, params },
            StudyKind::Runs => StudySpec::Runs {
                model,
                params,
                dt: 1e-6,
            },
            StudyKind::Current | StudyKind::Sweep => StudySpec::Current {
                model,
                params,
                options: Default::default(),
            },
            StudyKind::Restitution => StudySpec::Restitution {
                models: vec![model],
                params,
            },
        };
        StudyJob { generation, spec }
    }

    #[test]
    fn newer_jobs_replace_queued_ones_and_quick_kinds_go_first() {
        let mut queue = vec![
            job(1, StudyKind::WorkPrecision),
            job(2, StudyKind::Bounds),
            job(3, StudyKind::Runs),
        ];
        supersede(&mut queue, job(4, StudyKind::Runs));
        assert_eq!(
            kinds(&queue),
            [StudyKind::WorkPrecision, StudyKind::Bounds, StudyKind::Runs]
        );
        assert_eq!(take_next(&mut queue).map(|j| j.generation), Some(4));
        assert_eq!(take_next(&mut queue).map(|j| j.generation), Some(2));
        assert_eq!(take_next(&mut queue).map(|j| j.generation), Some(1));
        assert!(take_next(&mut queue).is_none());
    }

    #[test]
    fn a_superseded_study_stops_and_only_the_latest_reports() {
        // Served on this thread: job 1 runs although generation 2 was already asked for, as when
        // a newer request arrives mid-study; it stops at its first check and reports nothing.
        let (jobs, incoming) = mpsc::channel();
        let latest: Latest = Arc::new(Default::default());
        latest[StudyKind::Bounds.index()].store(2, Ordering::Release);
        jobs.send(job(1, StudyKind::Bounds)).unwrap();
        drop(jobs);
        let reports = std::sync::Mutex::new(Vec::new());
        serve(&incoming, &latest, |r| {
            reports.lock().unwrap().push(r);
            true
        });
        assert!(reports.lock().unwrap().is_empty());

        // Through the thread: the latest request reports, and dropping the handle ends it.
        let (tx, rx) = mpsc::channel();
        let worker = StudyWorker::spawn(move |report| tx.send(report).is_ok()).unwrap();
        assert!(worker.submit(job(3, StudyKind::Runs)));
        assert_eq!(rx.recv().unwrap().unwrap().generation, 3);
        drop(worker);
        assert!(rx.recv().is_err(), "the thread ended");
    }
}
