//! The most accurate answer the crate can give for an impact: the yardstick of every error measurement.

use crate::model::force::{ForceModel, ImpactParams};
use crate::model::impact::{
    ImpactError, ImpactSolution, ImpactSummary, MethodChoice, MethodUsed, SolveOptions,
    solve_impact,
};
use crate::model::ode::Method;

/// Tolerance of the DOP853 reference where no exact solution exists (issue 5).
pub const REFERENCE_RTOL: f64 = 1e-13;

/// The exact solution where one exists, else DOP853 at rtol 1e-13.
pub fn reference(model: ForceModel, params: &ImpactParams) -> Result<ImpactSummary, ImpactError> {
    reference_solution(model, params).map(|solution| solution.summary)
}

/// [`reference()`] with its curves, for drawing other solves over it (the exact solution's curves come
/// from a tight-tolerance integrator, see [`MethodUsed::Exact`]).
pub fn reference_solution(
    model: ForceModel,
    params: &ImpactParams,
) -> Result<ImpactSolution, ImpactError> {
    let tight = SolveOptions {
        method: MethodChoice::Auto,
        rtol: REFERENCE_RTOL,
        atol: Some(REFERENCE_RTOL * 1e-2),
        ..SolveOptions::default()
    };
    let auto = solve_impact(model, params, &tight)?;
    if auto.summary.method == MethodUsed::Exact
        || auto.summary.method == MethodUsed::Integrator(Method::Dop853)
    {
        return Ok(auto);
    }
    let dop853 = SolveOptions {
        method: MethodChoice::Integrator(Method::Dop853),
        ..tight
    };
    solve_impact(model, params, &dop853)
}

/// Relative errors of the four headline numbers against a reference.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SummaryErrors {
    pub error_x_max: f64,
    pub error_f_max: f64,
    pub error_t_contact: f64,
    pub error_v_out: f64,
}

impl SummaryErrors {
    /// |q − q_ref|/|q_ref| for x_max, F_max, t_c and v_out.
    pub fn between(summary: &ImpactSummary, reference: &ImpactSummary) -> Self {
        let rel = |a: f64, b: f64| (a - b).abs() / b.abs().max(f64::MIN_POSITIVE);
        SummaryErrors {
            error_x_max: rel(summary.x_max, reference.x_max),
            error_f_max: rel(summary.f_max, reference.f_max),
            error_t_contact: rel(summary.t_contact, reference.t_contact),
            error_v_out: rel(summary.v_out, reference.v_out),
        }
    }

    /// The largest of the four: the error a work-precision chart plots.
    pub fn worst(&self) -> f64 {
        self.error_x_max
            .max(self.error_f_max)
            .max(self.error_t_contact)
            .max(self.error_v_out)
    }
}
