//! The solved impacts of the current scene, one slot per force model, and the solve requests.
//!
//! A slot remembers the inputs it was solved for, so a request with the same inputs solves nothing.
//! Every request gets a new generation; an outcome of an older generation is stale and dropped.

use std::sync::Arc;
use std::time::Duration;

use crate::chart::sample::{ChartDots, Series};
use crate::model::force::{Damping, LAW_COUNT};
use crate::model::impact::{ImpactSolution, SolveOptions};
use crate::model::{ForceModel, ImpactParams};

/// One impact to solve off the UI thread.
#[derive(Debug, Clone, Copy, PartialEq)]
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
fn sampled(model: ForceModel, solution: &ImpactSolution, dots: ChartDots) -> Arc<Series> {
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
        Some(Job {
            generation: self.last_generation,
            model,
            params,
            options,
            calibrate,
            fitted,
        })
    }

    /// Stores an outcome if it answers the latest request of its model; returns whether it did.
    pub fn accept(&mut self, outcome: Outcome) -> bool {
        let slot = &mut self.slots[index(outcome.model)];
        if outcome.generation != slot.generation || !slot.pending {
            return false;
        }
        slot.pending = false;
        slot.sampled = match &outcome.result {
            Ok(solution) => Some(sampled(outcome.model, solution, self.dots)),
            Err(_) => None,
        };
        slot.shown = Some(outcome.result);
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
        assert_eq!(
            s.request(ForceModel::Proposed, fig5_params(0.3), opts, false),
            None
        );
        assert!(s.accept(failed(&job, "x")));
        assert!(!s.any_pending());
        assert_eq!(
            s.request(ForceModel::Proposed, fig5_params(0.3), opts, false),
            None
        );
        assert!(
            s.request(ForceModel::HuntCrossley, fig5_params(0.3), opts, false)
                .is_some()
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
