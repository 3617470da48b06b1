//! Solves impacts off the UI thread, so a slow solve (a stiff method at a tight tolerance) never
//! freezes input. Jobs queued for a model are superseded by newer ones for the same model.

use std::any::Any;
use std::panic::{self, AssertUnwindSafe};
use std::sync::Arc;
use std::sync::mpsc::{self, Receiver, Sender};
use std::thread;
use std::time::Instant;

use crate::model::calibrate::scene_or_calibrated;
use crate::model::force::AnyLaw;
use crate::model::impact::{ImpactError, ImpactSolution, solve_law};

use super::solutions::{Job, Outcome};

/// Solves one job on the calling thread.
pub fn solve(job: &Job) -> Outcome {
    let start = Instant::now();
    let (result, damping) = match law_of(job) {
        Ok(law) => (solve_job(job, &law), law.damping()),
        Err(message) => (Err(message), None),
    };
    Outcome {
        generation: job.generation,
        model: job.model,
        result,
        damping,
        elapsed: start.elapsed(),
    }
}

/// The job's law (calibrated when asked; a law that cannot be, says why).
fn law_of(job: &Job) -> Result<AnyLaw, String> {
    let (law, calibration) =
        scene_or_calibrated(job.model, &job.params, job.calibrate).map_err(|e| e.to_string())?;
    match calibration {
        Ok(_) => Ok(law),
        Err(why) => Err(format!("not calibrated: {why}")),
    }
}

/// The job's law solved.
fn solve_job(job: &Job, law: &AnyLaw) -> Result<Arc<ImpactSolution>, String> {
    solve_law(law, &job.options)
        .map(Arc::new)
        .map_err(|e: ImpactError| e.to_string())
}

/// A report of the worker: an outcome, or the message of a solver panic (a bug; the worker stops).
pub type Report = Result<Outcome, String>;

/// Handle of the background solver thread; dropping it ends the thread after the current solve.
pub struct Worker {
    jobs: Sender<Job>,
}

impl Worker {
    /// Starts the thread; `deliver` receives every report and returns false once nobody listens.
    pub fn spawn(deliver: impl Fn(Report) -> bool + Send + 'static) -> std::io::Result<Worker> {
        let (jobs, queue) = mpsc::channel();
        thread::Builder::new()
            .name("hertz-solver".into())
            .spawn(move || serve(&queue, deliver))?;
        Ok(Worker { jobs })
    }

    /// Queues a job; returns false if the worker has stopped.
    pub fn submit(&self, job: Job) -> bool {
        self.jobs.send(job).is_ok()
    }
}

fn serve(incoming: &Receiver<Job>, deliver: impl Fn(Report) -> bool) {
    let mut queue: Vec<Job> = Vec::new();
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
        let job = queue.remove(0);
        let report = panic::catch_unwind(AssertUnwindSafe(|| solve(&job))).map_err(|payload| {
            format!(
                "the solver panicked on {} ({}): this is a bug",
                job.model,
                panic_message(payload.as_ref())
            )
        });
        let stop = report.is_err();
        if !deliver(report) || stop {
            return;
        }
    }
}

/// Adds `job` to the queue, dropping a queued job of the same model (it is stale).
pub fn supersede(queue: &mut Vec<Job>, job: Job) {
    queue.retain(|queued| queued.model != job.model);
    queue.push(job);
}

pub(super) fn panic_message(payload: &(dyn Any + Send)) -> String {
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
    use crate::model::ForceModel;
    use crate::model::impact::SolveOptions;
    use crate::ui::testing::fig5_params;

    fn job(generation: u64, model: ForceModel) -> Job {
        Job {
            generation,
            model,
            params: fig5_params(0.3),
            options: SolveOptions::default(),
            calibrate: false,
        }
    }

    #[test]
    fn newer_jobs_replace_queued_ones_of_the_same_model() {
        let mut queue = vec![
            job(1, ForceModel::Proposed),
            job(2, ForceModel::HuntCrossley),
        ];
        supersede(&mut queue, job(3, ForceModel::Proposed));
        let generations: Vec<u64> = queue.iter().map(|j| j.generation).collect();
        assert_eq!(generations, [2, 3]);
    }

    #[test]
    fn panic_payloads_become_messages() {
        assert_eq!(panic_message(&"boom"), "boom");
        assert_eq!(panic_message(&String::from("bang")), "bang");
        assert_eq!(panic_message(&42), "no message");
    }
}
