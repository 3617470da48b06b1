//! Where fixed-step methods fail: theoretical critical steps and verdicts of a step size on an impact.

use serde::Serialize;

use crate::model::force::{ForceModel, ImpactParams};
use crate::model::impact::{
    ImpactError, ImpactSolution, ImpactSummary, MethodChoice, SolveOptions, solve_impact,
};
use crate::model::ode::{Method, OdeError};
use crate::model::study::reference::SummaryErrors;

/// The fixed-step methods, in order of increasing order.
pub const FIXED_STEP_METHODS: [Method; 4] = [
    Method::Euler,
    Method::SymplecticEuler,
    Method::Verlet,
    Method::Rk4,
];

/// Energy error (fraction of the impact energy) below which a solve counts as stable.
pub const STABLE_DRIFT: f64 = 0.01;

/// Energy error beyond which a solve counts as diverged when the largest stable step is measured.
pub const DIVERGED_DRIFT: f64 = 0.5;

/// Largest stable h·ω on the undamped oscillator ẍ = −ω²x (docs/physics.md §4; Hairer–Wanner II §IV.2):
/// none for explicit Euler (it gains energy at every step), 2 for symplectic Euler and Verlet,
/// 2√2 for RK4 (its stability region meets the imaginary axis at ±2√2 i).
pub fn stability_bound(method: Method) -> Option<f64> {
    match method {
        Method::SymplecticEuler | Method::Verlet => Some(2.0),
        Method::Rk4 => Some(2.0 * std::f64::consts::SQRT_2),
        Method::Euler | Method::Dopri5 | Method::Dop853 | Method::Radau5 => None,
    }
}

/// ω at the elastic maximum compression, √(n·k·x_maxⁿ⁻¹/m), rad/s: the stiffest point of the impact (docs/physics.md §4).
pub fn peak_angular_frequency(params: &ImpactParams) -> f64 {
    let x_max = params.law.max_approach(params.mass, params.v0);
    params.law.angular_frequency(params.mass, x_max)
}

/// Theoretical critical step h = bound/ω_max, s; `None` where the method has no stable step (Euler) or is adaptive.
pub fn critical_step(method: Method, params: &ImpactParams) -> Option<f64> {
    stability_bound(method).map(|bound| bound / peak_angular_frequency(params))
}

/// What a step size does to an impact.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "verdict", rename_all = "kebab-case")]
pub enum Verdict {
    /// Energy error below [`STABLE_DRIFT`] of the impact energy.
    Stable { drift: f64 },
    /// The solve finished but its exit energy is off by `drift` (fraction of ½mv₀²; positive = gained).
    EnergyDrift { drift: f64 },
    /// The method blew up (energy growth, non-finite state) at time t.
    Diverged { t: f64, reason: String },
    /// The solve failed otherwise (step budget, no separation).
    Failed { reason: String },
}

impl Verdict {
    /// Judges a fixed-step solve against the reference exit energy.
    pub fn judge(result: &Result<ImpactSolution, ImpactError>, reference: &ImpactSummary) -> Self {
        match result {
            Ok(solution) => {
                let drift = solution.summary.e_out.powi(2) - reference.e_out.powi(2);
                if drift.abs() < STABLE_DRIFT {
                    Verdict::Stable { drift }
                } else {
                    Verdict::EnergyDrift { drift }
                }
            }
            Err(ImpactError::EnergyGrowth { t, .. }) => Verdict::Diverged {
                t: *t,
                reason: "energy growth".into(),
            },
            Err(ImpactError::Integration {
                source: OdeError::NonFinite { t },
                ..
            }) => Verdict::Diverged {
                t: *t,
                reason: "non-finite state".into(),
            },
            Err(other) => Verdict::Failed {
                reason: other.to_string(),
            },
        }
    }

    /// Stable or drifting by less than [`DIVERGED_DRIFT`]: not blown up.
    pub fn is_bounded(&self) -> bool {
        match self {
            Verdict::Stable { .. } => true,
            Verdict::EnergyDrift { drift } => drift.abs() < DIVERGED_DRIFT,
            Verdict::Diverged { .. } | Verdict::Failed { .. } => false,
        }
    }
}

/// One fixed-step method run at a chosen step.
#[derive(Debug, Clone)]
pub struct StabilityRun {
    pub method: Method,
    pub dt: f64,
    pub verdict: Verdict,
    /// The solve, for drawing over the reference; `None` when it failed.
    pub solution: Option<ImpactSolution>,
}

/// Solver options of a fixed-step `method` at step `dt`, the rest default.
pub(super) fn fixed_step_options(method: Method, dt: f64) -> SolveOptions {
    SolveOptions {
        method: MethodChoice::Integrator(method),
        dt: Some(dt),
        ..SolveOptions::default()
    }
}

fn solve_fixed(
    model: ForceModel,
    params: &ImpactParams,
    method: Method,
    dt: f64,
) -> Result<ImpactSolution, ImpactError> {
    solve_impact(model, params, &fixed_step_options(method, dt))
}

/// Every fixed-step method at step `dt` on `model`, judged against `reference`.
pub fn runs_at_step(
    model: ForceModel,
    params: &ImpactParams,
    reference: &ImpactSummary,
    dt: f64,
) -> Vec<StabilityRun> {
    FIXED_STEP_METHODS
        .iter()
        .map(|&method| {
            if dt >= reference.t_contact {
                return StabilityRun {
                    method,
                    dt,
                    verdict: Verdict::Failed {
                        reason: format!(
                            "the step is not shorter than the contact (t_c = {:.4e} s): one step cannot resolve the impact",
                            reference.t_contact
                        ),
                    },
                    solution: None,
                };
            }
            let result = solve_fixed(model, params, method, dt);
            StabilityRun {
                method,
                dt,
                verdict: Verdict::judge(&result, reference),
                solution: result.ok(),
            }
        })
        .collect()
}

/// Measured largest step at which `method` stays bounded on this impact, s: where the
/// work-precision ladder of fixed-step methods starts (see [`largest_accurate_step`] for the
/// figure a user can act on).
///
/// Scans dt upward geometrically (2^{1/8} per point) from 1/32 of ω_max⁻¹ until the first unbounded
/// verdict, then bisects between the last bounded and the first unbounded step. A single impact lasts
/// only a few steps near the bound, so the measured step may differ from the linear theory of
/// [`critical_step`] — that difference is what the stability view shows. The scan stops at the
/// reference contact time: a longer step jumps over the whole impact, which can look bounded
/// without describing anything.
pub fn largest_bounded_step(
    model: ForceModel,
    params: &ImpactParams,
    reference: &ImpactSummary,
    method: Method,
) -> Option<f64> {
    let omega = peak_angular_frequency(params);
    let bounded =
        |dt: f64| Verdict::judge(&solve_fixed(model, params, method, dt), reference).is_bounded();
    scan_up(1.0 / (32.0 * omega), reference.t_contact, 20, bounded)
}

/// The accuracy the measured step of [`StepBound`] keeps: the worst relative error of x_max, F_max,
/// t_c and v_out against the reference.
pub const STEP_TOLERANCE: f64 = 0.01;

/// The worst relative error of x_max, F_max, t_c and v_out of `method` at step `dt` against
/// `reference`; infinite where the solve fails.
pub fn step_error(
    model: ForceModel,
    params: &ImpactParams,
    reference: &ImpactSummary,
    method: Method,
    dt: f64,
) -> f64 {
    if dt >= reference.t_contact {
        return f64::INFINITY;
    }
    match solve_fixed(model, params, method, dt) {
        Ok(solution) => {
            let worst = SummaryErrors::between(&solution.summary, reference).worst();
            if worst.is_nan() { f64::INFINITY } else { worst }
        }
        Err(_) => f64::INFINITY,
    }
}

/// Measured largest step at which `method` keeps every headline number of this impact within
/// `tolerance` of the reference, s; `None` if even ω_max⁻¹/1024 does not.
///
/// Scans dt upward geometrically (2^{1/8} per point) from ω_max⁻¹/1024 (where explicit Euler's
/// O(h·ω) error is still a fraction of a percent) and stops at the first step
/// that misses the tolerance (or reaches the contact time), then bisects between it and the last
/// step that met it. Every scanned step below the answer meets the tolerance, so errors that dip
/// back under it at larger steps (a lucky cancellation, a step that skips the impact) cannot
/// raise the figure.
pub fn largest_accurate_step(
    model: ForceModel,
    params: &ImpactParams,
    reference: &ImpactSummary,
    method: Method,
    tolerance: f64,
) -> Option<f64> {
    let omega = peak_angular_frequency(params);
    let accurate = |dt: f64| step_error(model, params, reference, method, dt) <= tolerance;
    // Within one scan factor: bisection to 0.1 % of the step.
    scan_up(1.0 / (1024.0 * omega), reference.t_contact, 7, accurate)
}

/// The largest step passing `ok`, scanning up from `start` by 2^{1/8} until the first step that
/// fails (the last passing one if the scan reaches `limit`), then bisecting `bisections` times
/// between the last pass and that failure; `None` if `start` fails.
fn scan_up(start: f64, limit: f64, bisections: usize, ok: impl Fn(f64) -> bool) -> Option<f64> {
    if !ok(start) {
        return None;
    }
    let growth = 2f64.powf(0.125);
    let (mut lo, mut hi) = (start, start * growth);
    while ok(hi) {
        lo = hi;
        hi *= growth;
        if hi >= limit {
            return Some(lo);
        }
    }
    for _ in 0..bisections {
        let mid = (lo * hi).sqrt();
        if ok(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(lo)
}

/// Theory next to measurement for one fixed-step method.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct StepBound {
    pub method: Method,
    /// Theoretical critical step bound/ω_max, s (`None`: no stable step in theory).
    pub theoretical_dt: Option<f64>,
    /// The worst relative error of x_max, F_max, t_c and v_out at `theoretical_dt` (infinite
    /// where the solve fails there).
    pub error_at_theoretical: Option<f64>,
    /// Measured largest step keeping those four errors within `tolerance`
    /// ([`largest_accurate_step`]), s.
    pub measured_dt: Option<f64>,
    /// The tolerance of `measured_dt`: [`STEP_TOLERANCE`].
    pub tolerance: f64,
    /// ω_max, rad/s.
    pub omega_max: f64,
}

/// The table of `hertz-tui bench --stability`.
pub fn step_bounds(
    model: ForceModel,
    params: &ImpactParams,
    reference: &ImpactSummary,
) -> Vec<StepBound> {
    step_bounds_until(model, params, reference, &|| false)
}

/// [`step_bounds`] that gives up between methods once `stop` returns true, with the methods measured
/// so far (an interactive caller whose request was superseded throws them away).
pub fn step_bounds_until(
    model: ForceModel,
    params: &ImpactParams,
    reference: &ImpactSummary,
    stop: &(dyn Fn() -> bool + Sync),
) -> Vec<StepBound> {
    let omega_max = peak_angular_frequency(params);
    FIXED_STEP_METHODS
        .iter()
        .take_while(|_| !stop())
        .map(|&method| {
            let theoretical_dt = critical_step(method, params);
            StepBound {
                method,
                theoretical_dt,
                error_at_theoretical: theoretical_dt
                    .map(|dt| step_error(model, params, reference, method, dt)),
                measured_dt: largest_accurate_step(
                    model,
                    params,
                    reference,
                    method,
                    STEP_TOLERANCE,
                ),
                tolerance: STEP_TOLERANCE,
                omega_max,
            }
        })
        .collect()
}

/// h·ω_max: a step measured against the stiffest point of the impact, the number the bounds of
/// [`stability_bound`] are stated in.
pub fn step_ratio(dt: f64, params: &ImpactParams) -> f64 {
    dt * peak_angular_frequency(params)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::power_law::PowerLaw;

    #[test]
    fn measured_steps_stay_below_the_contact_time_and_longer_steps_are_refused() {
        let scene = crate::model::scene::tests::fig5_scene();
        let params = scene.impact_params(&scene.quasistatic().unwrap());
        let model = ForceModel::HuntCrossley;
        let reference = super::super::reference::reference(model, &params).unwrap();
        for bound in step_bounds(model, &params, &reference) {
            let measured = bound
                .measured_dt
                .expect("every method is accurate at small steps");
            assert!(
                measured < reference.t_contact,
                "{}: {measured} s vs t_c {} s",
                bound.method,
                reference.t_contact
            );
        }
        for run in runs_at_step(model, &params, &reference, 1.0) {
            assert!(
                matches!(run.verdict, Verdict::Failed { .. }),
                "{:?}",
                run.verdict
            );
            assert!(run.solution.is_none());
        }
    }

    #[test]
    fn the_measured_step_keeps_every_number_within_the_tolerance_at_and_below_it() {
        let scene = crate::model::scene::tests::fig5_scene();
        let params = scene.impact_params(&scene.quasistatic().unwrap());
        for model in [ForceModel::HuntCrossley, ForceModel::Proposed] {
            let reference = super::super::reference::reference(model, &params).unwrap();
            for bound in step_bounds(model, &params, &reference) {
                let dt = bound.measured_dt.expect("accurate at ω_max⁻¹/1024");
                for fraction in [1.0, 0.8, 0.5, 0.25] {
                    let e = step_error(model, &params, &reference, bound.method, fraction * dt);
                    assert!(
                        e <= STEP_TOLERANCE,
                        "{model} {} at {fraction}·dt: {e}",
                        bound.method
                    );
                }
                // Just above it the tolerance is missed: the figure is the edge, not a cap.
                let e = step_error(model, &params, &reference, bound.method, 1.01 * dt);
                assert!(e > STEP_TOLERANCE, "{model} {} above dt: {e}", bound.method);
                if let (Some(theory), Some(error)) =
                    (bound.theoretical_dt, bound.error_at_theoretical)
                {
                    assert_eq!(
                        error,
                        step_error(model, &params, &reference, bound.method, theory)
                    );
                }
            }
        }
    }

    #[test]
    fn bounds_follow_the_linear_theory() {
        assert_eq!(stability_bound(Method::Euler), None);
        assert_eq!(stability_bound(Method::Verlet), Some(2.0));
        let rk4 = stability_bound(Method::Rk4).unwrap();
        assert!((rk4 - 8f64.sqrt()).abs() < 1e-15);
    }

    #[test]
    fn critical_step_uses_the_stiffness_at_x_max() {
        // Linear spring: ω is √(k/m) at every x, so the critical step of Verlet is 2·√(m/k).
        let params = ImpactParams {
            mass: 2.0,
            law: PowerLaw { k: 8e6, n: 1.0 },
            v0: 0.5,
            restitution: 1.0,
            plastic_indentation: 0.0,
            contact: crate::model::force::Contact::Unspecified,
        };
        let dt = critical_step(Method::Verlet, &params).unwrap();
        assert!((dt - 2.0 * (2.0f64 / 8e6).sqrt()).abs() < 1e-15);
        // At its own critical step, a method sits exactly on its bound.
        assert!((step_ratio(dt, &params) - 2.0).abs() < 1e-12);
        let rk4 = critical_step(Method::Rk4, &params).unwrap();
        assert!((step_ratio(rk4, &params) - 8f64.sqrt()).abs() < 1e-12);
    }
}
