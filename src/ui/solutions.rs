//! The solved impacts of the current scene, one slot per force model, and the solve requests.
//!
//! A slot remembers the inputs it was solved for, so a request with the same inputs solves nothing.
//! Every request gets a new generation; an outcome of an older generation is stale and dropped.

use std::sync::Arc;
use std::time::Duration;

use crate::chart::sample::{ChartDots, Series};
use crate::model::force::{Damping, LAW_COUNT};
use crate::model::impact::{ImpactSolution, SolveOptions};
use crate::model::recommend::Outcome as Realised;
use crate::model::{ForceModel, ImpactParams};

/// One impact to solve off the UI thread.
#[derive(Debug, Clone)]
pub struct Job {
    pub generation: u64,
    pub model: ForceModel,
    pub params: ImpactParams,
    pub options: SolveOptions,
    /// Calibrate the law's damping so that it realises the scene's e (docs/physics.md §6.4).
    pub calibrate: bool,
    /// The damping value at v₀ of the scene's `[fit]` law when this model is it: solved with it,
    /// never calibrated (docs/fitting.md).
    pub fitted: Option<f64>,
    /// The charts' widths when it was asked for: the solver samples the curves for them too,
    /// off the UI thread.
    pub dots: ChartDots,
    /// The model's last solution when it was solved with the same options and damping rule: a
    /// similar law's is moved to the new parameters instead of solving them (docs/physics.md
    /// §6.9), as a nudge of v₀ does for 17 of the 21 laws.
    pub previous: Option<Previous>,
}

/// A model's last solution, and its curves as sampled for the job's charts.
#[derive(Debug, Clone)]
pub struct Previous {
    pub solution: Arc<ImpactSolution>,
    pub sampled: Option<Arc<Series>>,
}

/// What a solve produced; errors are kept as the solver's message.
pub type SolveResult = Result<Arc<ImpactSolution>, String>;

/// A finished job.
#[derive(Debug, Clone)]
pub struct Outcome {
    pub generation: u64,
    pub model: ForceModel,
    pub result: SolveResult,
    /// The damping parameter of the law solved (calibrated when the job asked), `None` for a law
    /// without one or a law that could not be built.
    pub damping: Option<Damping>,
    pub elapsed: Duration,
    /// The solution's curves sampled for the job's charts (`None` for a failed solve).
    pub sampled: Option<(ChartDots, Arc<Series>)>,
}

#[derive(Debug, Clone, Default)]
struct Slot {
    /// Inputs of the latest request.
    inputs: Option<(ImpactParams, SolveOptions, bool, Option<f64>)>,
    /// Generation of the latest request.
    generation: u64,
    /// Whether the latest request is still running.
    pending: bool,
    /// The latest finished result (of the latest request once it is no longer pending).
    shown: Option<SolveResult>,
    /// The inputs `shown` was solved with.
    shown_inputs: Option<(ImpactParams, SolveOptions, bool, Option<f64>)>,
    /// The damping its law used.
    damping: Option<Damping>,
    /// Its curves sampled once, for every chart and frame until the next solve.
    sampled: Option<Arc<Series>>,
}

/// Results per model (one slot per row of the law table), with the bookkeeping of requests in flight.
#[derive(Debug, Clone)]
pub struct Solutions {
    slots: [Slot; LAW_COUNT],
    last_generation: u64,
    /// The charts' widths the curves are sampled for.
    dots: ChartDots,
}

impl Default for Solutions {
    fn default() -> Self {
        Solutions {
            slots: std::array::from_fn(|_| Slot::default()),
            last_generation: 0,
            dots: ChartDots::UNKNOWN_SCREEN,
        }
    }
}

/// `solution`'s curves sampled for charts `dots` wide.
pub fn sampled(model: ForceModel, solution: &ImpactSolution, dots: ChartDots) -> Arc<Series> {
    Arc::new(Series::for_charts(model, solution, dots))
}

fn index(model: ForceModel) -> usize {
    model.index()
}

impl Solutions {
    /// A job for `model` (calibrated or not) if its inputs differ from those of its last request, else `None`.
    pub fn request(
        &mut self,
        model: ForceModel,
        params: ImpactParams,
        options: SolveOptions,
        calibrate: bool,
    ) -> Option<Job> {
        self.request_fitted(model, params, options, calibrate, None)
    }

    /// [`Solutions::request`] for a scene that carries a fitted law: `fitted` is its damping at
    /// v₀ when `model` is that law.
    pub fn request_fitted(
        &mut self,
        model: ForceModel,
        params: ImpactParams,
        options: SolveOptions,
        calibrate: bool,
        fitted: Option<f64>,
    ) -> Option<Job> {
        let slot = &mut self.slots[index(model)];
        if slot.inputs == Some((params, options, calibrate, fitted)) {
            return None;
        }
        self.last_generation += 1;
        slot.inputs = Some((params, options, calibrate, fitted));
        slot.generation = self.last_generation;
        slot.pending = true;
        // Only the row's own damping rule moves with the parameters, and a step in seconds would not.
        let previous = match (&slot.shown, &slot.shown_inputs) {
            (Some(Ok(solution)), Some((_, shown_options, false, None)))
                if *shown_options == options
                    && !calibrate
                    && fitted.is_none()
                    && options.dt.is_none() =>
            {
                Some(Previous {
                    solution: Arc::clone(solution),
                    sampled: slot.sampled.clone(),
                })
            }
            _ => None,
        };
        Some(Job {
            generation: self.last_generation,
            model,
            params,
            options,
            calibrate,
            fitted,
            dots: self.dots,
            previous,
        })
    }

    /// Stores an outcome if it answers the latest request of its model; returns whether it did.
    pub fn accept(&mut self, outcome: Outcome) -> bool {
        let slot = &mut self.slots[index(outcome.model)];
        if outcome.generation != slot.generation || !slot.pending {
            return false;
        }
        slot.pending = false;
        slot.sampled = match (&outcome.result, outcome.sampled) {
            // Sampled by the solver for the charts as they still are.
            (Ok(_), Some((dots, series))) if dots == self.dots => Some(series),
            (Ok(solution), _) => Some(sampled(outcome.model, solution, self.dots)),
            (Err(_), _) => None,
        };
        slot.shown = Some(outcome.result);
        slot.shown_inputs = slot.inputs;
        slot.damping = outcome.damping;
        true
    }

    /// Samples the curves for charts `dots` wide from now on, the shown solutions' again if that
    /// changes their resolution.
    pub fn set_chart_dots(&mut self, dots: ChartDots) {
        if dots == self.dots {
            return;
        }
        self.dots = dots;
        for (slot, model) in self.slots.iter_mut().zip(ForceModel::ALL) {
            if let Some(Ok(solution)) = &slot.shown {
                slot.sampled = Some(sampled(model, solution, dots));
            }
        }
    }

    /// The damping parameter of the law of `model`'s latest finished result.
    pub fn damping(&self, model: ForceModel) -> Option<Damping> {
        self.slots[index(model)].damping
    }

    /// The latest finished result of `model` (the previous one while a new solve runs).
    pub fn result(&self, model: ForceModel) -> Option<&SolveResult> {
        self.slots[index(model)].shown.as_ref()
    }

    /// The solution of `model`, if its latest finished solve succeeded.
    pub fn solution(&self, model: ForceModel) -> Option<&ImpactSolution> {
        match self.result(model) {
            Some(Ok(solution)) => Some(solution),
            _ => None,
        }
    }

    /// The curves of `model`'s solution, sampled when it arrived.
    pub fn samples(&self, model: ForceModel) -> Option<&Series> {
        self.slots[index(model)].sampled.as_deref()
    }

    /// `model` solved on `params` with the default options, uncalibrated, as the recommendation
    /// solves it: the latest finished solve where it is that one (`None` otherwise).
    pub fn default_outcome(&self, model: ForceModel, params: &ImpactParams) -> Option<Realised> {
        let slot = &self.slots[index(model)];
        if slot.pending || slot.inputs != Some((*params, SolveOptions::default(), false, None)) {
            return None;
        }
        match &slot.shown {
            Some(Ok(solution)) => Some(Realised::of(model, &solution.summary)),
            _ => None,
        }
    }

    pub fn is_pending(&self, model: ForceModel) -> bool {
        self.slots[index(model)].pending
    }

    pub fn any_pending(&self) -> bool {
        self.slots.iter().any(|s| s.pending)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ui::testing::fig5_params;

    fn failed(job: &Job, message: &str) -> Outcome {
        Outcome {
            generation: job.generation,
            model: job.model,
            result: Err(message.into()),
            damping: None,
            elapsed: Duration::ZERO,
            sampled: None,
        }
    }

    fn message(s: &Solutions) -> Option<&str> {
        match s.result(ForceModel::Proposed) {
            Some(Err(m)) => Some(m),
            _ => None,
        }
    }

    #[test]
    fn same_inputs_solve_nothing() {
        let mut s = Solutions::default();
        let opts = SolveOptions::default();
        let job = s
            .request(ForceModel::Proposed, fig5_params(0.3), opts, false)
            .unwrap();
        assert!(s.is_pending(ForceModel::Proposed));
        assert!(
            s.request(ForceModel::Proposed, fig5_params(0.3), opts, false)
                .is_none()
        );
        assert!(s.accept(failed(&job, "x")));
        assert!(!s.any_pending());
        assert!(
            s.request(ForceModel::Proposed, fig5_params(0.3), opts, false)
                .is_none()
        );
        assert!(
            s.request(ForceModel::HuntCrossley, fig5_params(0.3), opts, false)
                .is_some()
        );
    }

    /// A new request carries the model's last solution when it was solved with the same options
    /// and the row's own damping (the solver moves a similar law's, docs/physics.md §6.9);
    /// calibration, other options or a step in seconds leave it out.
    #[test]
    fn the_last_solution_goes_with_a_request_it_can_be_moved_to() {
        use crate::model::impact::solve_impact;
        let mut s = Solutions::default();
        let opts = SolveOptions::default();
        let model = ForceModel::HuntCrossley;
        let job = s.request(model, fig5_params(0.3), opts, false).unwrap();
        assert!(job.previous.is_none());
        let solution = Arc::new(solve_impact(model, &fig5_params(0.3), &opts).unwrap());
        assert!(s.accept(Outcome {
            result: Ok(Arc::clone(&solution)),
            ..failed(&job, "")
        }));
        let next = s.request(model, fig5_params(0.05), opts, false).unwrap();
        let previous = next.previous.unwrap();
        assert!(Arc::ptr_eq(&previous.solution, &solution));
        assert!(previous.sampled.is_some());
        assert!(
            s.request(model, fig5_params(0.06), opts, true)
                .unwrap()
                .previous
                .is_none()
        );
        let tighter = SolveOptions {
            rtol: 1e-10,
            ..opts
        };
        assert!(
            s.request(model, fig5_params(0.07), tighter, false)
                .unwrap()
                .previous
                .is_none()
        );
        let fixed = SolveOptions {
            dt: Some(1e-7),
            ..opts
        };
        assert!(
            s.request(model, fig5_params(0.08), fixed, false)
                .unwrap()
                .previous
                .is_none()
        );
    }

    /// A solution is sampled for the charts' resolution when it arrives, and again when the
    /// resolution changes; a failed one has no samples either way.
    #[test]
    fn curves_are_sampled_again_for_a_new_resolution() {
        use crate::model::impact::solve_impact;
        let mut s = Solutions::default();
        let opts = SolveOptions::default();
        let params = fig5_params(0.3);
        let job = s
            .request(ForceModel::HuntCrossley, params, opts, false)
            .unwrap();
        let solution = Arc::new(solve_impact(ForceModel::HuntCrossley, &params, &opts).unwrap());
        assert!(s.accept(Outcome {
            result: Ok(Arc::clone(&solution)),
            damping: None,
            ..failed(&job, "")
        }));
        let failing = s
            .request(ForceModel::Proposed, params, opts, false)
            .unwrap();
        assert!(s.accept(failed(&failing, "no")));
        let count = |s: &Solutions| s.samples(ForceModel::HuntCrossley).unwrap().samples.len();
        let expected = |dots: ChartDots| {
            Series::for_charts(ForceModel::HuntCrossley, &solution, dots)
                .samples
                .len()
        };
        assert_eq!(count(&s), expected(ChartDots::UNKNOWN_SCREEN));
        let wide = ChartDots {
            time: 700,
            approach: 400,
            high: 48,
        };
        s.set_chart_dots(wide);
        assert!(expected(wide) > expected(ChartDots::UNKNOWN_SCREEN));
        assert_eq!(count(&s), expected(wide));
        assert!(s.samples(ForceModel::Proposed).is_none());

        // The solver's samples are kept where they are for the charts as they are, else sampled
        // again (the screen was resized while it solved).
        let ten = Arc::new(Series::sample(ForceModel::HuntCrossley, &solution, 10));
        for (v0, dots, samples) in [
            (0.4, wide, ten.samples.len()),
            (0.5, ChartDots::UNKNOWN_SCREEN, expected(wide)),
        ] {
            let job = s
                .request(ForceModel::HuntCrossley, fig5_params(v0), opts, false)
                .unwrap();
            assert!(s.accept(Outcome {
                result: Ok(Arc::clone(&solution)),
                sampled: Some((dots, Arc::clone(&ten))),
                ..failed(&job, "")
            }));
            assert_eq!(count(&s), samples);
        }
    }

    #[test]
    fn stale_outcomes_are_dropped_and_the_old_result_stays_meanwhile() {
        let mut s = Solutions::default();
        let opts = SolveOptions::default();
        let first = s
            .request(ForceModel::Proposed, fig5_params(0.3), opts, false)
            .unwrap();
        assert!(s.accept(failed(&first, "first")));
        let second = s
            .request(ForceModel::Proposed, fig5_params(0.4), opts, false)
            .unwrap();
        let third = s
            .request(ForceModel::Proposed, fig5_params(0.5), opts, false)
            .unwrap();
        assert!(second.generation < third.generation);
        // While the new request runs, the previous result is what is shown.
        assert_eq!(message(&s), Some("first"));
        assert!(!s.accept(failed(&second, "second")), "stale");
        assert!(s.is_pending(ForceModel::Proposed));
        assert!(s.accept(failed(&third, "third")));
        assert_eq!(message(&s), Some("third"));
        assert!(!s.accept(failed(&third, "again")), "answered already");
    }
}
