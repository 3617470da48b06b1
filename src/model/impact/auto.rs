//! `MethodChoice::Auto`: per model the cheapest path that meets rtol.
//!
//! 1. The exact solution where one exists (elastic; Hunt–Crossley and Lankarani–Nikravesh by the
//!    energy integral; dry friction by its energy identity; the proposed model at x_pl = 0). Its
//!    numbers are reported with no integration at all; the curves come from DOP853 at tight
//!    tolerance (a few hundred force evaluations) when the trajectory is first sampled.
//! 2. Otherwise DOPRI5 at the requested tolerance.
//! 3. Radau5 when the scene is stiff: a priori, when the damping eigenvalue would hold DOPRI5 to
//!    hundreds of stability-limited steps; a posteriori, when DOPRI5 fails or rejects many steps.

use crate::model::exact::ExactImpact;
use crate::model::force::{AnyLaw, ForceLaw, Phase};
use crate::model::ode::{Method, OdeError, Stats};

use super::phases::{self, Run, RunOptions};
use super::scale::Scales;
use super::summary::summarize;
use super::{
    ImpactError, ImpactSolution, ImpactSummary, MethodUsed, SolveOptions, TensileCutoff, Trajectory,
};

/// DOPRI5's stability region reaches about −3.3 on the real axis; a damping eigenvalue λ (scaled)
/// then forces ≈ λ·t_c/3.3 ≈ λ steps over the contact. Beyond this, Radau5 is cheaper.
const STIFF_EIGENVALUE: f64 = 300.0;

/// Steps DOPRI5 may spend before auto concludes the scene is stiff and switches to Radau5.
const DOPRI5_BUDGET: usize = 20_000;

/// Tolerance of the curves drawn for exact solutions: tight enough to look exact on any chart,
/// cheap with an 8th-order method.
const CURVE_RTOL: f64 = 1e-10;

pub(super) fn solve<L: ForceLaw>(
    law: &L,
    any: AnyLaw,
    sc: &Scales,
    opts: &SolveOptions,
) -> Result<ImpactSolution, ImpactError> {
    // Quadratures of the exact solutions aim two digits below the requested tolerance.
    let quad_rtol = (opts.rtol * 1e-2).max(1e-15);
    if let Some(exact) = law.exact(quad_rtol).filter(ExactImpact::is_valid) {
        let rtol = opts.rtol.clamp(1e-14, CURVE_RTOL);
        let curve = RunOptions {
            method: Method::Dop853,
            rtol,
            atol: rtol,
            dt: None,
            max_steps: opts.max_steps,
        };
        let summary = exact_summary(law, sc, &exact);
        let peak = (exact.x_f_max, exact.v_f_max);
        let trajectory = Trajectory::deferred(any, *sc, curve, &summary, peak);
        return Ok(ImpactSolution {
            summary,
            trajectory,
        });
    }

    let mut spent = Stats::default();
    let mut spent_evals = 0;
    if damping_eigenvalue(law, sc) <= STIFF_EIGENVALUE {
        let ro = RunOptions {
            method: Method::Dopri5,
            rtol: opts.rtol,
            atol: opts.atol,
            dt: None,
            max_steps: opts.max_steps.min(DOPRI5_BUDGET),
        };
        match phases::run(law, sc, &ro) {
            Ok(run) if !looks_stiff(&run.stats) => {
                return Ok(finish(law, any, sc, run, Method::Dopri5));
            }
            Ok(run) => {
                spent = run.stats;
                spent_evals = run.force_evals;
            }
            Err(ImpactError::Integration {
                source: OdeError::StepBudgetExhausted { steps, .. },
                ..
            }) => spent.steps = steps,
            // An underflow does not say how many steps it took; its work goes uncounted.
            Err(ImpactError::Integration {
                source: OdeError::StepSizeUnderflow { .. },
                ..
            }) => {}
            Err(other) => return Err(other),
        }
    }
    let ro = RunOptions {
        method: Method::Radau5,
        rtol: opts.rtol.max(1e-13),
        atol: opts.atol,
        dt: None,
        max_steps: opts
            .max_steps
            .saturating_sub(spent.steps + spent.rejected_steps)
            .max(1),
    };
    let mut run = phases::run(law, sc, &ro)?;
    // The counters report all work of the solve, including an abandoned DOPRI5 attempt.
    run.stats += spent;
    run.force_evals += spent_evals;
    Ok(finish(law, any, sc, run, Method::Radau5))
}

fn finish<L: ForceLaw>(
    law: &L,
    any: AnyLaw,
    sc: &Scales,
    run: Run,
    method: Method,
) -> ImpactSolution {
    let summary = summarize(law, sc, &run, MethodUsed::Integrator(method));
    let trajectory = Trajectory::integrated(any, *sc, run, &summary);
    ImpactSolution {
        summary,
        trajectory,
    }
}

/// |∂(dV/dT)/∂V| at the elastic x_max: the damping eigenvalue of the scaled system (for the
/// proposed model (n+1)/2·x_pl/(e·x_e)); the elastic part contributes an O(1) frequency only.
fn damping_eigenvalue<L: ForceLaw>(law: &L, sc: &Scales) -> f64 {
    let (_, fv) = law.partials(sc.x, 0.0, Phase::Loading);
    sc.accel * sc.v * fv.abs()
}

/// Many rejections are the step-size controller's symptom of stiffness (Hairer–Wanner II §IV.2).
fn looks_stiff(stats: &Stats) -> bool {
    stats.rejected_steps > 20 && 3 * stats.rejected_steps > stats.steps
}

/// The exact numbers. No step was taken and no force evaluated, and the exit speed comes from
/// the energy balance itself, so its residual is zero by construction (the integrators' residuals
/// are what it measures).
fn exact_summary<L: ForceLaw>(law: &L, sc: &Scales, exact: &ExactImpact) -> ImpactSummary {
    let e_out = exact.v_out / sc.v;
    ImpactSummary {
        model: law.model(),
        method: MethodUsed::Exact,
        x_max: exact.x_max,
        t_x_max: exact.t_x_max,
        f_max: exact.f_max,
        t_f_max: exact.t_f_max,
        t_contact: exact.t_contact,
        v_out: exact.v_out,
        e_out,
        x_residual: exact.x_residual,
        energy_dissipated: 0.5 * sc.mass * (sc.v * sc.v - exact.v_out * exact.v_out),
        energy_residual: 0.0,
        steps: 0,
        rejected_steps: 0,
        force_evals: 0,
        tensile_cutoff: exact.tensile_cutoff.then_some(TensileCutoff {
            t: exact.t_contact,
            x: exact.x_residual,
            v: -exact.v_out,
        }),
    }
}
