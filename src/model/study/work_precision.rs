//! Speed against accuracy: every method over a ladder of tolerances or step sizes (issue 5).

use std::time::Duration;

use serde::Serialize;

use crate::model::force::{ForceModel, ImpactParams};
use crate::model::impact::{ImpactError, ImpactSummary, MethodChoice, SolveOptions, solve_impact};
use crate::model::ode::Method;

use super::reference::{SummaryErrors, reference};
use super::stability::{FIXED_STEP_METHODS, fixed_step_options, largest_bounded_step};
use super::timing::median_seconds;

/// The adaptive methods, cheapest per step first.
pub const ADAPTIVE_METHODS: [Method; 3] = [Method::Dopri5, Method::Dop853, Method::Radau5];

/// Tolerances of the adaptive ladder: 1e-2 … 1e-12, one per decade.
pub fn rtol_ladder() -> Vec<f64> {
    (2..=12).map(|p| 10f64.powi(-p)).collect()
}

/// Number of halvings of the fixed-step ladder below the largest stable step.
pub const FIXED_STEP_HALVINGS: u32 = 10;

/// How a rung of the ladder was set.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Setting {
    Rtol(f64),
    Dt(f64),
}

/// One point of the work-precision diagram.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WorkPrecisionRow {
    pub method: Method,
    #[serde(flatten)]
    pub setting: Setting,
    /// Relative errors against the reference; `None` when the solve failed.
    #[serde(flatten)]
    pub errors: Option<SummaryErrors>,
    pub force_evals: Option<usize>,
    /// Median wall time of one solve, s.
    pub seconds_per_solve: Option<f64>,
    /// Why the solve failed, if it did.
    pub failure: Option<String>,
}

/// Timing effort per rung.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Timing {
    pub min_repeats: usize,
    pub min_total: Duration,
}

impl Default for Timing {
    fn default() -> Self {
        Timing {
            min_repeats: 5,
            min_total: Duration::from_millis(2),
        }
    }
}

/// The work-precision data of `model` for every method, against the exact or DOP853 reference.
pub fn work_precision(
    model: ForceModel,
    params: &ImpactParams,
    timing: Timing,
) -> Result<(ImpactSummary, Vec<WorkPrecisionRow>), ImpactError> {
    work_precision_until(model, params, timing, &|| false)
}

/// [`work_precision`] that gives up between rungs once `stop` returns true, with the rungs measured
/// so far: an interactive caller whose request was superseded throws the partial ladder away.
pub fn work_precision_until(
    model: ForceModel,
    params: &ImpactParams,
    timing: Timing,
    stop: &(dyn Fn() -> bool + Sync),
) -> Result<(ImpactSummary, Vec<WorkPrecisionRow>), ImpactError> {
    let reference = reference(model, params)?;
    let mut rows = Vec::new();
    for method in ADAPTIVE_METHODS {
        for rtol in rtol_ladder() {
            if stop() {
                return Ok((reference, rows));
            }
            let opts = SolveOptions {
                method: MethodChoice::Integrator(method),
                rtol,
                atol: None,
                ..SolveOptions::default()
            };
            rows.push(measure(
                model,
                params,
                &reference,
                method,
                Setting::Rtol(rtol),
                &opts,
                timing,
            ));
        }
    }
    for method in FIXED_STEP_METHODS {
        if stop() {
            return Ok((reference, rows));
        }
        let Some(largest) = largest_bounded_step(model, params, &reference, method) else {
            continue;
        };
        for halving in 0..=FIXED_STEP_HALVINGS {
            if stop() {
                return Ok((reference, rows));
            }
            let dt = largest / f64::from(1u32 << halving);
            let opts = fixed_step_options(method, dt);
            rows.push(measure(
                model,
                params,
                &reference,
                method,
                Setting::Dt(dt),
                &opts,
                timing,
            ));
        }
    }
    Ok((reference, rows))
}

fn measure(
    model: ForceModel,
    params: &ImpactParams,
    reference: &ImpactSummary,
    method: Method,
    setting: Setting,
    opts: &SolveOptions,
    timing: Timing,
) -> WorkPrecisionRow {
    match solve_impact(model, params, opts) {
        Ok(solution) => WorkPrecisionRow {
            method,
            setting,
            errors: Some(SummaryErrors::between(&solution.summary, reference)),
            force_evals: Some(solution.summary.force_evals),
            seconds_per_solve: Some(median_seconds(
                || solve_impact(model, params, opts),
                timing.min_repeats,
                timing.min_total,
            )),
            failure: None,
        },
        Err(err) => WorkPrecisionRow {
            method,
            setting,
            errors: None,
            force_evals: None,
            seconds_per_solve: None,
            failure: Some(err.to_string()),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rtol_ladder_spans_ten_decades() {
        let ladder = rtol_ladder();
        assert_eq!(ladder.len(), 11);
        assert_eq!(ladder[0], 1e-2);
        assert!((ladder[10] / 1e-12 - 1.0).abs() < 1e-12);
    }
}
