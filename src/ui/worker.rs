//! The solve of one impact as a background job (on the [`Jobs`](super::jobs::Jobs) queue of the
//! solves), so a slow solve (a stiff method at a tight tolerance) never freezes input. A job queued
//! for a model is superseded by a newer one for the same model.

use std::sync::Arc;
use std::time::Instant;

use crate::model::ForceModel;
use crate::model::calibrate::scene_or_calibrated;
use crate::model::force::AnyLaw;
use crate::model::impact::{ImpactError, ImpactSolution, solve_law};

use super::action::Action;
use super::app::App;
use super::jobs::Background;
use super::solutions::{Job, Outcome, sampled};
use super::update::update;
use crate::chart::sample::Series;

/// Solves one job on the calling thread, and samples its curves for the job's charts (so that
/// the UI thread only draws them).
pub fn solve(job: &Job) -> Outcome {
    let start = Instant::now();
    let (result, damping, moved) = match law_of(job) {
        Ok(law) => {
            let (result, moved) = solve_job(job, &law);
            (result, law.damping(), moved)
        }
        Err(message) => (Err(message), None, None),
    };
    let elapsed = start.elapsed();
    let sampled = match (result.as_ref(), moved) {
        (Ok(_), Some(series)) => Some((job.dots, series)),
        (Ok(solution), None) => Some((job.dots, sampled(job.model, solution, job.dots))),
        (Err(_), _) => None,
    };
    Outcome {
        generation: job.generation,
        model: job.model,
        result,
        damping,
        elapsed,
        sampled,
    }
}

/// Solves every job `app` has queued, on the calling thread, and reports each to it, until the
/// reports queue none: what the solver threads do, for tests and benchmarks.
pub fn settle(app: &mut App) {
    loop {
        let jobs = app.take_jobs();
        if jobs.is_empty() {
            return;
        }
        for job in jobs {
            update(app, Action::Solved(Ok(solve(&job))));
        }
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

/// The job's law solved, or its previous solution moved to it where the law is similar, with
/// the previous curves moved too when they were sampled for the job's charts.
fn solve_job(
    job: &Job,
    law: &AnyLaw,
) -> (Result<Arc<ImpactSolution>, String>, Option<Arc<Series>>) {
    if let Some(previous) = &job.previous
        && let Some(moved) = previous.solution.similar_at(law)
    {
        let ratios = previous.solution.ratios_to(&moved);
        let series = (previous.sampled.as_ref()).map(|s| Arc::new(s.moved(ratios)));
        return (Ok(Arc::new(moved)), series);
    }
    let solved = solve_law(law, &job.options)
        .map(Arc::new)
        .map_err(|e: ImpactError| e.to_string());
    (solved, None)
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
    use crate::model::impact::{SolveOptions, solve_impact};
    use crate::ui::jobs::supersede;
    use crate::ui::solutions::Previous;
    use crate::ui::testing::fig5_params;

    fn job(generation: u64, model: ForceModel) -> Job {
        Job {
            generation,
            model,
            params: fig5_params(0.3),
            options: SolveOptions::default(),
            calibrate: false,
            fitted: None,
            dots: crate::chart::sample::ChartDots::UNKNOWN_SCREEN,
            previous: None,
        }
    }

    /// A job with the last solution of a similar law gives the numbers of a solve (to 1e-12)
    /// by moving it; for a law that is not similar the solver solves.
    #[test]
    fn a_similar_laws_last_solution_is_moved_to_the_new_parameters() {
        for model in [
            ForceModel::HuntCrossley,
            ForceModel::with_id("hertz-viscous"),
        ] {
            let solved = solve(&job(1, model));
            let previous = Some(Previous {
                solution: solved.result.clone().unwrap(),
                sampled: solved.sampled.clone().map(|(_, s)| s),
            });
            let nudged = Job {
                params: fig5_params(0.05),
                previous,
                ..job(2, model)
            };
            let moved = solve(&nudged).result.unwrap();
            let direct = solve(&Job {
                previous: None,
                ..nudged.clone()
            })
            .result
            .unwrap();
            for (a, b) in [
                (moved.summary.x_max, direct.summary.x_max),
                (moved.summary.f_max, direct.summary.f_max),
                (moved.summary.t_contact, direct.summary.t_contact),
                (moved.summary.v_out, direct.summary.v_out),
            ] {
                assert!((a - b).abs() <= 1e-12 * b.abs(), "{model:?}: {a} vs {b}");
            }
            assert_eq!(moved.summary.steps, direct.summary.steps);
            // Its curves moved with it: the samples of a solve there, to 1e-7 of each scale.
            let moved_curves = solve(&nudged).sampled.unwrap().1;
            let direct_curves = sampled(model, &direct, nudged.dots);
            assert_eq!(moved_curves.samples.len(), direct_curves.samples.len());
            let s = &direct.summary;
            for (a, b) in moved_curves.samples.iter().zip(&direct_curves.samples) {
                let off = [
                    (a.t - b.t) / s.t_contact,
                    (a.x - b.x) / s.x_max,
                    (a.v - b.v) / 0.05,
                    (a.f - b.f) / s.f_max,
                ];
                assert!(off.iter().all(|d| d.abs() < 1e-7), "{model:?}: {a:?} {b:?}");
            }
        }
        // The proposed model's damping holds x_pl/x_e, which moves with v₀: solved afresh.
        let proposed = ForceModel::Proposed;
        let previous = solve(&job(1, proposed))
            .result
            .ok()
            .map(|solution| Previous {
                solution,
                sampled: None,
            });
        let nudged = Job {
            params: fig5_params(0.05),
            previous,
            ..job(2, proposed)
        };
        let solved = solve(&nudged).result.unwrap();
        let direct = solve_impact(proposed, &fig5_params(0.05), &SolveOptions::default()).unwrap();
        assert_eq!(solved.summary, direct.summary);
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
