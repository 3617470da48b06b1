//! Shared pieces of adaptive step control: the error norm, Hairer's PI controller, his starting
//! step heuristic, and the guards every attempted step passes (budget, underflow).

use super::{OdeError, OdeSystem, Options, State, Stats};

/// Hairer's RMS norm of a local error estimate, sc = atol + rtol·max(|y₀|, |y₁|)
/// (Hairer–Nørsett–Wanner I, §II.4, eq. 4.11).
pub(super) fn error_norm(err: &State, y0: &State, y1: &State, atol: f64, rtol: f64) -> f64 {
    let mut sum = 0.0;
    for i in 0..2 {
        let sc = atol + rtol * y0[i].abs().max(y1[i].abs());
        let q = err[i] / sc;
        sum += q * q;
    }
    (sum / 2.0).sqrt()
}

/// Counts one right-hand-side evaluation and returns it.
#[inline]
pub(super) fn rhs(sys: &mut dyn OdeSystem, stats: &mut Stats, t: f64, y: &State) -> State {
    stats.rhs_evals += 1;
    sys.rhs(t, y)
}

pub(super) fn is_finite(y: &State) -> bool {
    y[0].is_finite() && y[1].is_finite()
}

/// Fails once accepted plus rejected steps reach `opts.max_steps` (checked before every attempt,
/// so the loop cannot run forever whatever the step size does).
pub(super) fn check_budget(stats: &Stats, opts: &Options, t: f64) -> Result<(), OdeError> {
    if stats.steps + stats.rejected_steps >= opts.max_steps {
        return Err(OdeError::StepBudgetExhausted {
            t,
            steps: opts.max_steps,
        });
    }
    Ok(())
}

/// Step-size underflow: h < 16·ε·|t|, where t + h would hardly differ from t. The second clause
/// catches h shrinking towards zero at t = 0, where the relative test is void.
pub(super) fn underflows(h: f64, t: f64) -> bool {
    h < 16.0 * f64::EPSILON * t.abs() || h < f64::MIN_POSITIVE
}

/// Why the last attempt was rejected; decides which error an underflow is reported as.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Rejection {
    /// The error estimate exceeded the tolerance.
    Error,
    /// The trial step produced a non-finite value.
    NonFinite,
    /// The Newton iteration of an implicit method did not converge.
    Newton,
}

/// The failure to report when the step size underflows after `last` rejections: if the step was
/// shrinking because the state turned non-finite or Newton failed, that is the real cause.
pub(super) fn underflow_error(last: Option<Rejection>, t: f64, h: f64) -> OdeError {
    match last {
        Some(Rejection::NonFinite) => OdeError::NonFinite { t },
        Some(Rejection::Newton) => OdeError::NewtonFailed { t },
        _ => OdeError::StepSizeUnderflow { t, h },
    }
}

/// Hairer's PI step-size controller of DOPRI5/DOP853 (Hairer–Nørsett–Wanner I, §IV.2 and the codes):
/// h_new = h / clamp(err^expo1 / err_old^β / safety, 1/facmax, 1/facmin).
///
/// The two powers are evaluated as one exponential of logarithms (ln err_old is kept from the
/// previous step): the same numbers as Hairer's formula to rounding, at half the cost of two
/// `powf` calls in the hot loop.
#[derive(Debug, Clone, Copy)]
pub(super) struct PiController {
    beta: f64,
    expo1: f64,
    safety: f64,
    /// 1/facmin: the largest shrink divisor.
    facc1: f64,
    /// 1/facmax: the smallest divisor (largest growth).
    facc2: f64,
    /// ln of the previous accepted error, floored at ln 1e-4 (Hairer's FACOLD).
    ln_facold: f64,
    /// (h, ln err) of the last rejected attempt since the last accepted step.
    last_rejection: Option<(f64, f64)>,
}

/// ln 1e-4: Hairer's floor and initial value of FACOLD.
const LN_FACOLD_MIN: f64 = -9.210_340_371_976_182;

impl PiController {
    /// DOPRI5's defaults: β = 0.04, safety 0.9, facmin 0.2, facmax 10, expo1 = 1/5 − 0.75·β.
    pub(super) fn dopri5() -> Self {
        Self::new(0.2 - 0.04 * 0.75, 0.04, 0.9, 0.2, 10.0)
    }

    /// DOP853's defaults: β = 0 (plain I control), safety 0.9, facmin 0.333, facmax 6,
    /// expo1 = 1/8 − 0.2·β.
    pub(super) fn dop853() -> Self {
        Self::new(1.0 / 8.0, 0.0, 0.9, 0.333, 6.0)
    }

    fn new(expo1: f64, beta: f64, safety: f64, facmin: f64, facmax: f64) -> Self {
        PiController {
            beta,
            expo1,
            safety,
            facc1: 1.0 / facmin,
            facc2: 1.0 / facmax,
            ln_facold: LN_FACOLD_MIN,
            last_rejection: None,
        }
    }

    /// The step after an accepted step with error `err` ≤ 1; `after_reject` forbids growth right
    /// after a rejection (Hairer's REJECT flag).
    pub(super) fn accepted(&mut self, err: f64, h: f64, h_max: f64, after_reject: bool) -> f64 {
        // err = 0 gives ln = −∞, fac = 0, and the clamp to facmax.
        let ln_err = err.ln();
        let fac = (self.expo1 * ln_err - self.beta * self.ln_facold).exp();
        let fac = (fac / self.safety).clamp(self.facc2, self.facc1);
        self.ln_facold = ln_err.max(LN_FACOLD_MIN);
        self.last_rejection = None;
        let mut h_new = (h / fac).min(h_max);
        if after_reject {
            h_new = h_new.min(h);
        }
        h_new
    }

    /// The retry step after a rejected step with error `err` > 1 (no PI memory: Hairer uses the
    /// pure I factor here).
    ///
    /// A second rejection from the same point measures how the error really scales with h,
    /// err ∝ h^q from the two attempts, and retries with that q instead of the method's order: where
    /// the solution is not smooth (a damping force ∝ x^¼ at first or last contact gives q ≈ 2.3
    /// against DOP853's 8), the pure I factor shrinks h by err^(1/8) and needs four or five
    /// rejections to get under the tolerance, where the measured q needs one. The retry aims at
    /// the error the I factor aims at (safety^(1/expo1)), so accepted steps keep their margin.
    pub(super) fn rejected(&mut self, err: f64, h: f64) -> f64 {
        let ln_err = err.ln();
        let mut expo = self.expo1;
        if let Some((h_prev, ln_prev)) = self.last_rejection {
            let q = (ln_prev - ln_err) / (h_prev / h).ln();
            if q.is_finite() && q > 0.0 {
                // Between first order and the method's own (the I factor's exponent).
                expo = 1.0 / q.clamp(1.0, 1.0 / self.expo1);
            }
        }
        self.last_rejection = Some((h, ln_err));
        // The I factor err^expo1/safety aims at the error safety^(1/expo1) (0.43 for DOP853);
        // with the measured exponent the retry aims at the same error, not at a larger one.
        let ln_target = self.safety.ln() / self.expo1;
        let fac11 = (expo * (ln_err - ln_target)).exp();
        h / self.facc1.min(fac11)
    }
}

/// Hairer's starting step heuristic HINIT (Hairer–Nørsett–Wanner I, §II.4): h from the sizes of y₀,
/// f₀ and an estimate of the second derivative, for a method of order `order`. Costs one rhs
/// evaluation.
#[allow(clippy::too_many_arguments)]
pub(super) fn initial_step(
    sys: &mut dyn OdeSystem,
    stats: &mut Stats,
    t0: f64,
    y0: &State,
    f0: &State,
    order: u32,
    opts: &Options,
    h_max: f64,
) -> f64 {
    let mut dnf = 0.0;
    let mut dny = 0.0;
    for i in 0..2 {
        let sk = opts.atol + opts.rtol * y0[i].abs();
        dnf += (f0[i] / sk).powi(2);
        dny += (y0[i] / sk).powi(2);
    }
    let mut h = if dnf <= 1e-10 || dny <= 1e-10 {
        1e-6
    } else {
        (dny / dnf).sqrt() * 0.01
    };
    h = h.min(h_max);
    // One explicit Euler step to estimate the second derivative.
    let y1 = y0 + f0 * h;
    let f1 = rhs(sys, stats, t0 + h, &y1);
    let mut der2 = 0.0;
    for i in 0..2 {
        let sk = opts.atol + opts.rtol * y0[i].abs();
        der2 += ((f1[i] - f0[i]) / sk).powi(2);
    }
    let der2 = der2.sqrt() / h;
    let der12 = der2.abs().max(dnf.sqrt());
    let h1 = if der12 <= 1e-15 {
        (h * 1e-3).max(1e-6)
    } else {
        (0.01 / der12).powf(1.0 / f64::from(order))
    };
    // A non-finite trial (f blows up next to y₀) leaves h1 NaN: fall back to the first guess and
    // let the step control shrink it.
    let h = (100.0 * h).min(h1).min(h_max);
    if h.is_finite() && h > 0.0 {
        h
    } else {
        1e-6_f64.min(h_max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn error_norm_is_the_rms_of_scaled_components() {
        let e = State::new(3e-6, 4e-6);
        let y0 = State::new(1.0, -2.0);
        let y1 = State::new(2.0, -1.0);
        // sc = 1e-6 + 1e-6·(2, 2) = 3e-6 for both components.
        let n = error_norm(&e, &y0, &y1, 1e-6, 1e-6);
        let expected = ((1.0 + (4.0f64 / 3.0).powi(2)) / 2.0).sqrt();
        assert!((n - expected).abs() < 1e-15, "{n} vs {expected}");
    }

    #[test]
    fn pi_controller_respects_its_bounds() {
        let mut c = PiController::dopri5();
        // Error 0: growth capped at facmax = 10.
        assert!((c.accepted(0.0, 1.0, f64::INFINITY, false) - 10.0).abs() < 1e-12);
        // Huge error: shrink capped at facmin = 0.2.
        assert!((c.rejected(1e12, 1.0) - 0.2).abs() < 1e-12);
        c.accepted(0.5, 1.0, f64::INFINITY, true);
        // After a rejection the step may not grow.
        assert!(c.accepted(1e-3, 1.0, f64::INFINITY, true) <= 1.0);
        // h_max caps the proposal.
        assert_eq!(c.accepted(1e-3, 1.0, 0.5, false), 0.5);
    }

    #[test]
    fn pi_controller_follows_hairers_formula() {
        let mut c = PiController::dopri5();
        let h1 = c.accepted(0.5, 1.0, f64::INFINITY, false);
        // First step: facold = 1e-4.
        let fac = 0.5f64.powf(0.17) / 1e-4f64.powf(0.04) / 0.9;
        assert!((h1 - 1.0 / fac).abs() < 1e-14);
        let h2 = c.accepted(0.25, 1.0, f64::INFINITY, false);
        let fac = 0.25f64.powf(0.17) / 0.5f64.powf(0.04) / 0.9;
        assert!((h2 - 1.0 / fac).abs() < 1e-14);
    }

    #[test]
    fn a_second_rejection_retries_with_the_measured_order() {
        let mut c = PiController::dop853();
        // The first rejection knows only the method's order: h·0.9/err^(1/8).
        let h1 = c.rejected(4.0, 1.0);
        assert!((h1 - 0.9 / 4f64.powf(0.125)).abs() < 1e-14);
        // err ∝ h² measured over the two attempts: the retry aims with q = 2 at the error the
        // I factor aims at, 0.9⁸.
        let err2 = 4.0 * h1 * h1;
        let h2 = c.rejected(err2, h1);
        let target = 0.9f64.powi(8);
        assert!((h2 - h1 * (target / err2).sqrt()).abs() < 1e-14, "{h2}");
        assert!((4.0 * h2 * h2 / target - 1.0).abs() < 1e-12);
        // An accepted step forgets the rejections: the next one uses the method's order again.
        c.accepted(0.5, h2, f64::INFINITY, true);
        let h3 = c.rejected(4.0, 1.0);
        assert!((h3 - h1).abs() < 1e-14);
    }

    #[test]
    fn log_floor_is_ln_1e_minus_4() {
        assert!((LN_FACOLD_MIN - 1e-4f64.ln()).abs() < 1e-15);
    }

    #[test]
    fn underflow_threshold() {
        assert!(underflows(1e-20, 1.0));
        assert!(!underflows(1e-14, 1.0));
        assert!(underflows(0.0, 0.0));
        assert!(!underflows(1e-300, 0.0));
    }
}
