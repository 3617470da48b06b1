//! `MethodChoice::Auto`: per model the cheapest path that meets rtol.
//!
//! 1. The exact solution where one exists (elastic; Hunt–Crossley and Lankarani–Nikravesh by the
//!    energy integral; dry friction by its energy identity; the proposed model at x_pl = 0). Its
//!    numbers are reported with no integration at all; the curves come from DOP853 at tight
//!    tolerance (a few hundred force evaluations) when the trajectory is first sampled, and by
//!    DOPRI5 at a chart's (far fewer) when first drawn.
//! 2. Otherwise the cheaper explicit method for the requested tolerance ([`explicit_method`]):
//!    DOPRI5 down to rtol 1e-7, DOP853 below.
//! 3. Radau5 when stiffness shows: the explicit method exhausting a budget far above what any non-stiff impact
//!    needs (stability-limited steps), or its step size underflowing.
//!
//! No a-priori stiffness test: the proposed model's damping eigenvalue (n+1)/2·x_pl/(e·x_e) can
//! be 10⁴ without DOPRI5 needing more steps than at 10 (measured: 108 steps at rtol 1e-8 over
//! that whole range), because its contact ends at F = 0, i.e. as soon as the fast mode has
//! relaxed — there is no slow phase after it for the fast mode to make stiff.

use crate::model::exact::ExactImpact;
use crate::model::force::{AnyLaw, ForceLaw};
use crate::model::ode::{Method, OdeError};

use super::phases::{self, End, KnownEnds, RunOptions};
use super::scale::Scales;
use super::tolerance::integrator_tolerances;
use super::{
    ImpactError, ImpactSolution, ImpactSummary, MethodUsed, SolveOptions, TensileCutoff,
    Trajectory, integrated_solution,
};

/// Below this rtol DOP853 costs fewer force evaluations than DOPRI5 for the same promise (both
/// within 100·rtol, DOPRI5 run at rtol/10). Measured, mean over 10 random proposed-model scenes
/// (force evaluations, DOPRI5 vs DOP853): rtol 1e-3 113 vs 197, 1e-6 192 vs 245, 1e-8 358 vs 295,
/// 1e-10 810 vs 457, 1e-12 1943 vs 684.
const DOP853_BELOW_RTOL: f64 = 1e-7;

/// The explicit method `auto` integrates with at `rtol`.
pub(crate) fn explicit_method(rtol: f64) -> Method {
    if rtol < DOP853_BELOW_RTOL {
        Method::Dop853
    } else {
        Method::Dopri5
    }
}

/// Steps the explicit method may spend before auto concludes the scene is stiff and switches to Radau5: non-stiff
/// impacts take 50–400 steps from rtol 1e-6 to 1e-12 (a few thousand at rtol 1e-14).
const EXPLICIT_BUDGET: usize = 5_000;

/// Tolerance of an exact solution's sampled trajectory (`Trajectory::at`, `samples`: the CSV
/// export, the data cursor): within 1e-9 of the exact curves, cheap with an 8th-order method.
const CURVE_RTOL: f64 = 1e-10;

/// Tolerance of the curves charts draw for an exact solution (`Trajectory::drawn_samples`), by
/// DOPRI5: within 1.4e-5 of the curve's scale (measured on every law, e = 0.01–0.99, the worst
/// Gharib–Hurmuzlu at e = 0.8), a seventieth of a dot on a chart 1000 dots wide — no chart can
/// show the difference from CURVE_RTOL's. At this
/// tolerance DOPRI5 takes fewer force evaluations than DOP853 and its segments are cheaper to
/// evaluate (measured on the paper's exact models: 0.20 M instructions for their curves, against
/// 0.23 M by DOP853 at the same rtol, whose error was 1e-5, and 0.44 M at CURVE_RTOL). The phases
/// run to the exact turn and end ([`KnownEnds`]) instead of locating them as events, whose
/// landings (each step retaken until the event's time is found to rounding) were half of that:
/// 0.095 M, the error unchanged.
const DRAWN_RTOL: f64 = 1e-6;

pub(super) fn solve<L: ForceLaw>(
    law: &L,
    any: AnyLaw,
    sc: &Scales,
    opts: &SolveOptions,
) -> Result<ImpactSolution, ImpactError> {
    // Quadratures of the exact solutions aim at the requested tolerance: their node counts keep
    // the times within it (exact::hysteresis and exact::dry_friction test that), far inside the
    // 100·rtol promise.
    let quad_rtol = opts.rtol.max(1e-15);
    if let Some(exact) = law.exact(quad_rtol).filter(ExactImpact::is_valid) {
        let summary = exact_summary(law, sc, &exact);
        let curve = |method: Method, rtol: f64| RunOptions {
            method,
            rtol,
            atol: rtol,
            dt: None,
            max_steps: opts.max_steps,
            known: None,
        };
        // The drawn curves run to the exact turn and end rather than finding them again.
        let known = KnownEnds {
            t_turn: summary.t_x_max / sc.t,
            t_end: summary.t_contact / sc.t,
            end: if summary.x_residual > 0.0 {
                End::Tension
            } else {
                End::Approach
            },
            find_turn: false,
        };
        // Unless the phases leave nothing to integrate (a contact that ends as it turns): then
        // the events say so as they did.
        let known = (known.t_turn > 0.0 && known.t_turn < known.t_end).then_some(known);
        let curves = [
            // The sampled curves too unload to the exact end: a heavily damped unloading creeps
            // out along F ≈ 0 (Gonthier at e = 0.01), where the compressive-only rule's event
            // would fire on the integrator's error and end the curves early.
            RunOptions {
                known: known.map(|known| KnownEnds {
                    find_turn: true,
                    ..known
                }),
                ..curve(Method::Dop853, opts.rtol.clamp(1e-14, CURVE_RTOL))
            },
            RunOptions {
                known,
                ..curve(Method::Dopri5, DRAWN_RTOL)
            },
        ];
        let peak = (exact.x_f_max, exact.v_f_max);
        let trajectory = Trajectory::deferred(any, *sc, curves, &summary, peak);
        return Ok(ImpactSolution {
            summary,
            trajectory,
        });
    }

    let explicit = explicit_method(opts.rtol);
    let (rtol, atol) = integrator_tolerances(explicit, opts.rtol, opts.atol);
    let first = RunOptions {
        method: explicit,
        rtol,
        atol,
        dt: None,
        max_steps: opts.max_steps.min(EXPLICIT_BUDGET),
        known: None,
    };
    let spent = match phases::run(law, sc, &first) {
        Ok(run) => return Ok(integrated_solution(law, any, sc, run, explicit)),
        // Stability-limited steps ran out of DOPRI5's budget (not the caller's): stiff.
        Err(ImpactError::Integration {
            source: OdeError::StepBudgetExhausted { steps, .. },
            ..
        }) if first.max_steps < opts.max_steps => steps,
        // An underflow does not say how many steps it took; they go uncounted.
        Err(ImpactError::Integration {
            source: OdeError::StepSizeUnderflow { .. },
            ..
        }) => 0,
        Err(other) => return Err(other),
    };
    let (rtol, atol) = integrator_tolerances(Method::Radau5, opts.rtol, opts.atol);
    let radau5 = RunOptions {
        method: Method::Radau5,
        rtol,
        atol,
        dt: None,
        max_steps: opts.max_steps.saturating_sub(spent).max(1),
        known: None,
    };
    let mut run = phases::run(law, sc, &radau5)?;
    // The counters report all work of the solve, including the abandoned explicit attempt (whose
    // force evaluations went unrecorded with its error: six per DOPRI5 step, twelve per DOP853).
    let per_step = if explicit == Method::Dop853 { 12 } else { 6 };
    run.stats.steps += spent;
    run.force_evals += per_step * spent;
    Ok(integrated_solution(law, any, sc, run, Method::Radau5))
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::force::elastic::Elastic;
    use crate::model::force::{ContactEnd, ForceModel, ImpactParams, Phase};
    use crate::model::numeric::roots::brent;
    use crate::model::power_law::PowerLaw;

    /// A genuinely stiff test law: F = k·x + c·(ẋ + v_s), a heavily overdamped spring that, after
    /// a fast transient (rate c·v₀/(k·x_e) = 1e5 in scaled time), creeps out of contact at the slow
    /// speed v_s over ~10 scaled time units — 3e5 stability-limited DOPRI5 steps.
    #[derive(Debug, Clone, Copy)]
    struct Creep {
        params: ImpactParams,
        c: f64,
        vs: f64,
    }

    impl ForceLaw for Creep {
        fn model(&self) -> ForceModel {
            ForceModel::Proposed
        }
        fn params(&self) -> &ImpactParams {
            &self.params
        }
        fn phase_force(&self, x: f64, v: f64, _: Phase) -> f64 {
            self.params.law.k * x + self.c * (v + self.vs)
        }
        fn dissipative_force(&self, _: f64, v: f64, _: Phase) -> f64 {
            self.c * (v + self.vs)
        }
        fn partials(&self, _: f64, _: f64, _: Phase) -> (f64, f64) {
            (self.params.law.k, self.c)
        }
        fn contact_end(&self) -> ContactEnd {
            ContactEnd::ApproachZero
        }
        fn may_turn_tensile(&self) -> bool {
            false
        }
        fn tension(&self, _: f64, _: f64) -> f64 {
            1.0
        }
        fn exact(&self, _: f64) -> Option<ExactImpact> {
            None
        }
    }

    #[test]
    fn stiffness_sends_auto_to_radau5_which_matches_the_closed_form() {
        let params = ImpactParams {
            mass: 1.0,
            law: PowerLaw { k: 1e6, n: 1.0 },
            v0: 1.0,
            restitution: 1.0,
            plastic_indentation: 0.0,
            contact: crate::model::force::Contact::Unspecified,
        };
        let sc = Scales::new(&params);
        // Scaled: X'' + ĉ·X' + X = −ĉ·v̂_s with ĉ = c·v₀/(k·x_e), v̂_s = v_s/v₀.
        let (c_hat, vs_hat) = (1e5, 1e-6);
        let law = Creep {
            params,
            c: c_hat * params.law.k * sc.x / params.v0,
            vs: vs_hat * params.v0,
        };
        let any = AnyLaw::Elastic(Elastic::new(&params));
        let sol = solve(&law, any, &sc, &SolveOptions::default()).unwrap();
        assert_eq!(sol.summary.method, MethodUsed::Integrator(Method::Radau5));
        assert!(
            sol.summary.steps > EXPLICIT_BUDGET,
            "the abandoned attempt is counted"
        );

        // Closed form of the linear ODE in each phase: X = X_p + A·e^{r₁T} + B·e^{r₂T}.
        let disc = (c_hat * c_hat - 4.0).sqrt();
        let (r1, r2) = (0.5 * (-c_hat + disc), 0.5 * (-c_hat - disc));
        let x_p = -c_hat * vs_hat;
        // (A, B) from X(0) = x0, X'(0) = v0.
        let coeffs = |x0: f64, v0: f64| {
            let b = (v0 - r1 * (x0 - x_p)) / (r2 - r1);
            (x0 - x_p - b, b)
        };
        let (a1, b1) = coeffs(0.0, 1.0);
        let v1 = |t: f64| a1 * r1 * (r1 * t).exp() + b1 * r2 * (r2 * t).exp();
        let t1 = brent(v1, 0.0, 1.0).unwrap();
        let x1 = x_p + a1 * (r1 * t1).exp() + b1 * (r2 * t1).exp();
        let (a2, b2) = coeffs(x1, 0.0);
        let x2 = |t: f64| x_p + a2 * (r1 * t).exp() + b2 * (r2 * t).exp();
        let t2 = t1 + brent(x2, 0.0, 100.0).unwrap();
        let s = &sol.summary;
        assert!(
            (s.x_max / (x1 * sc.x) - 1.0).abs() < 1e-6,
            "{} vs {}",
            s.x_max,
            x1 * sc.x
        );
        assert!((s.t_contact / (t2 * sc.t) - 1.0).abs() < 1e-6);
    }
}
