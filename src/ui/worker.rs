//! The solve of one impact as a background job (on the [`Jobs`](super::jobs::Jobs) queue of the
//! solves), so a slow solve (a stiff method at a tight tolerance) never freezes input. A job queued
//! for a model is superseded by a newer one for the same model.

use std::sync::Arc;
use std::time::Instant;

use crate::model::ForceModel;
use crate::model::calibrate::scene_or_calibrated;
use crate::model::force::AnyLaw;
use crate::model::impact::{ImpactError, ImpactSolution, solve_law};

use super::jobs::Background;
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
    if let Some(value) = job.fitted {
        return job
            .model
            .law_with_damping(&job.params, value)
            .map_err(|e| e.to_string());
    }
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

impl Background for Job {
    /// A newer solve of the same model supersedes a queued one.
    type Slot = ForceModel;
    type Outcome = Outcome;

    fn slot(&self) -> ForceModel {
        self.model
    }

    fn generation(&self) -> u64 {
        self.generation
    }

    /// A solve runs to its end: a stale outcome is dropped by [`Solutions`](super::solutions).
    fn run(&self, _stop: &(dyn Fn() -> bool + Sync)) -> Option<Outcome> {
        Some(solve(self))
    }

    fn panicked(&self, message: &str) -> String {
        format!(
            "the solver panicked on {} ({message}): this is a bug",
            self.model
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::impact::SolveOptions;
    use crate::ui::jobs::supersede;
    use crate::ui::testing::fig5_params;

    fn job(generation: u64, model: ForceModel) -> Job {
        Job {
            generation,
            model,
            params: fig5_params(0.3),
            options: SolveOptions::default(),
            calibrate: false,
            fitted: None,
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
}
