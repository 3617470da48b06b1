//! The paper's "pwrfit": F = a·xⁿ + c fitted to eq 13/14 by Levenberg–Marquardt (nalgebra).

use nalgebra::{Matrix3, Vector3};

use super::super::error::{FitFailure, ModelError, require_positive};
use super::super::pair::ContactPair;
use super::PowerFit;
use super::approach::LineContact;

/// Number of force samples. The residual is smooth and nearly linear in the parameters, so a few
/// more samples than parameters pin it down; more only cost time on every keystroke.
pub const FIT_SAMPLES: usize = 16;

/// The range must span at least this factor, or a, n and c are not separately determined.
pub const MIN_RANGE_RATIO: f64 = 1.5;

/// Levenberg–Marquardt iterations allowed; from the log-log start a handful suffice.
const MAX_ITERATIONS: usize = 100;

/// Largest parameter change (the parameters are scaled to order one) at which the fit stops:
/// n is then known far better than its five printed digits.
const STEP_TOLERANCE: f64 = 1e-10;

/// Fits F = a·xⁿ + c to eq 13/14 at [`FIT_SAMPLES`] forces spaced geometrically over
/// [f_min, f_max], N, minimising the relative residuals (F_fit − F)/F.
///
/// Needs 0 < f_min, f_max ≥ 1.5·f_min and f_max inside the domain of eq 13/14
/// ([`LineContact::force_limit`]). The start is a log-log linear regression (c = 0), refined by
/// Levenberg–Marquardt on (ln a, n, c) scaled to order one.
pub fn fit_power_law(pair: &ContactPair, f_min: f64, f_max: f64) -> Result<PowerFit, ModelError> {
    fit_line_contact(&LineContact::of(pair)?, f_min, f_max)
}

/// [`fit_power_law`] for a line contact already extracted from its pair.
pub(super) fn fit_line_contact(
    contact: &LineContact,
    f_min: f64,
    f_max: f64,
) -> Result<PowerFit, ModelError> {
    require_positive("fit range f_min", f_min)?;
    require_positive("fit range f_max", f_max)?;
    if f_max < MIN_RANGE_RATIO * f_min {
        return Err(ModelError::FitFailed(FitFailure::RangeTooNarrow {
            f_min,
            f_max,
            ratio: MIN_RANGE_RATIO,
        }));
    }
    let limit = contact.force_limit();
    if f_max >= limit {
        return Err(contact.force_out_of_domain(f_max, limit));
    }
    let samples = Samples::new(contact, f_min, f_max);
    let params = levenberg_marquardt(&samples)?;
    samples.power_fit(params, f_min, f_max)
}

/// Geometric force samples and their approaches, scaled by the top of the range.
struct Samples {
    /// F_ref/Fᵢ: turns absolute residuals into relative ones.
    weight: [f64; FIT_SAMPLES],
    /// sᵢ = ln(xᵢ/x_ref).
    log_x: [f64; FIT_SAMPLES],
    /// F_ref = f_max, N.
    f_ref: f64,
    /// x_ref = x(f_max), m.
    x_ref: f64,
}

/// Scaled parameters p = (ln A, n, γ) of F = F_ref·(A·(x/x_ref)ⁿ + γ).
type Params = Vector3<f64>;

impl Samples {
    fn new(contact: &LineContact, f_min: f64, f_max: f64) -> Self {
        let x_ref = contact.approach_unchecked(f_max);
        let ratio = (f_max / f_min).powf(1.0 / (FIT_SAMPLES - 1) as f64);
        let mut weight = [0.0; FIT_SAMPLES];
        let mut log_x = [0.0; FIT_SAMPLES];
        let mut f = f_min;
        for i in 0..FIT_SAMPLES {
            // The last sample is exactly f_max, whatever the rounding of the ratio.
            let force = if i + 1 == FIT_SAMPLES { f_max } else { f };
            weight[i] = f_max / force;
            log_x[i] = (contact.approach_unchecked(force) / x_ref).ln();
            f *= ratio;
        }
        Samples {
            weight,
            log_x,
            f_ref: f_max,
            x_ref,
        }
    }

    /// Relative residual of sample i: F_fit/F − 1.
    fn residual(&self, p: &Params, i: usize) -> f64 {
        self.weight[i] * ((p[0] + p[1] * self.log_x[i]).exp() + p[2]) - 1.0
    }

    /// Sum of squared relative residuals.
    fn cost(&self, p: &Params) -> f64 {
        let (ln_a, n, gamma) = (p[0], p[1], p[2]);
        let mut sum = 0.0;
        for (w, s) in self.weight.iter().zip(&self.log_x) {
            let r = w * ((ln_a + n * s).exp() + gamma) - 1.0;
            sum += r * r;
        }
        sum
    }

    /// Gauss–Newton normal equations JᵀJ and Jᵀr at p. Accumulated in scalars: this loop runs on
    /// every keystroke, and generic matrix code is slow in unoptimised builds.
    fn normal_equations(&self, p: &Params) -> (Matrix3<f64>, Vector3<f64>) {
        let (ln_a, n, gamma) = (p[0], p[1], p[2]);
        let mut sums = [0.0; 9];
        for (&w, &s) in self.weight.iter().zip(&self.log_x) {
            // Jacobian row (∂r/∂ln A, ∂r/∂n, ∂r/∂γ) = (m, m·s, w) with m = w·A·(x/x_ref)ⁿ.
            let m = w * (ln_a + n * s).exp();
            let (j0, j1, j2) = (m, m * s, w);
            let r = m + w * gamma - 1.0;
            let terms = [
                j0 * j0,
                j0 * j1,
                j0 * j2,
                j1 * j1,
                j1 * j2,
                j2 * j2,
                j0 * r,
                j1 * r,
                j2 * r,
            ];
            for (sum, term) in sums.iter_mut().zip(terms) {
                *sum += term;
            }
        }
        let [a00, a01, a02, a11, a12, a22, g0, g1, g2] = sums;
        (
            Matrix3::new(a00, a01, a02, a01, a11, a12, a02, a12, a22),
            Vector3::new(g0, g1, g2),
        )
    }

    /// Log-log linear regression ln(F/F_ref) = ln A + n·s with γ = 0: the starting point.
    fn log_log_start(&self) -> Params {
        let count = FIT_SAMPLES as f64;
        let (mut sx, mut sy, mut sxx, mut sxy) = (0.0, 0.0, 0.0, 0.0);
        for i in 0..FIT_SAMPLES {
            let (x, y) = (self.log_x[i], -self.weight[i].ln());
            sx += x;
            sy += y;
            sxx += x * x;
            sxy += x * y;
        }
        let n = (count * sxy - sx * sy) / (count * sxx - sx * sx);
        Params::new((sy - n * sx) / count, n, 0.0)
    }

    /// Unscales p into a, n, c and measures the worst relative error over the samples.
    fn power_fit(&self, p: Params, f_min: f64, f_max: f64) -> Result<PowerFit, ModelError> {
        let n = p[1];
        let a = self.f_ref * p[0].exp() / self.x_ref.powf(n);
        let c = self.f_ref * p[2];
        let max_rel_error = (0..FIT_SAMPLES)
            .map(|i| self.residual(&p, i).abs())
            .fold(0.0, f64::max);
        let fit = PowerFit {
            a,
            n,
            c,
            max_rel_error,
            f_min,
            f_max,
        };
        if [a, n, c, max_rel_error].iter().all(|v| v.is_finite()) && a > 0.0 {
            Ok(fit)
        } else {
            Err(ModelError::FitFailed(FitFailure::BadStiffness {
                f_min,
                f_max,
                a,
                n,
                c,
            }))
        }
    }
}

/// Minimises the relative residuals from the log-log start; Marquardt's diagonal scaling.
fn levenberg_marquardt(samples: &Samples) -> Result<Params, ModelError> {
    let mut p = samples.log_log_start();
    let mut cost = samples.cost(&p);
    if !cost.is_finite() {
        return Err(ModelError::FitFailed(FitFailure::StartNotFinite));
    }
    let mut lambda = 1e-3;
    for _ in 0..MAX_ITERATIONS {
        let (jtj, jtr) = samples.normal_equations(&p);
        let mut step = None;
        while lambda < 1e16 {
            let mut damped = jtj;
            for k in 0..3 {
                damped[(k, k)] *= 1.0 + lambda;
            }
            // A 3×3 inverse is closed-form in nalgebra: cheaper than a factorisation here.
            if let Some(delta) = damped.try_inverse().map(|inverse| -(inverse * jtr)) {
                let trial = p + delta;
                let trial_cost = samples.cost(&trial);
                if trial_cost.is_finite() && trial_cost <= cost {
                    step = Some(delta);
                    p = trial;
                    cost = trial_cost;
                    lambda = (lambda * 0.1).max(1e-12);
                    break;
                }
            }
            lambda *= 10.0;
        }
        match step {
            // No damping finds a lower cost: p is a minimum to working precision.
            None => return Ok(p),
            Some(delta) if delta.amax() < STEP_TOLERANCE => return Ok(p),
            Some(_) => {}
        }
    }
    Err(ModelError::FitFailed(FitFailure::NotConverged {
        iterations: MAX_ITERATIONS,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn on_plane() -> LineContact {
        LineContact::OnPlane {
            eta: 9.1e-12,
            radius: 0.02,
            length: 0.1,
        }
    }

    fn equal_cylinders() -> LineContact {
        LineContact::TwoCylinders {
            eta1: 4.55e-12,
            radius1: 0.02,
            eta2: 4.55e-12,
            radius2: 0.02,
            length: 0.1,
        }
    }

    #[test]
    fn the_fit_reproduces_the_curve_it_was_fitted_to() {
        for contact in [on_plane(), equal_cylinders()] {
            let fit = fit_line_contact(&contact, 3e3, 3e4).unwrap();
            assert!(fit.max_rel_error < 2e-3, "{fit:?}");
            // Check max_rel_error independently at the two ends and at a point between samples.
            for f in [3e3, 1.234e4, 3e4] {
                let x = contact.approach(f).unwrap();
                let err = ((fit.a * x.powf(fit.n) + fit.c) / f - 1.0).abs();
                assert!(err <= fit.max_rel_error * 1.5 + 1e-12, "{err} at {f}");
            }
            assert_eq!((fit.f_min, fit.f_max), (3e3, 3e4));
        }
    }

    #[test]
    fn the_exponent_lies_between_the_local_exponents_at_the_ends() {
        // The local exponent d ln F/d ln x = x/(F·dx/dF) grows with F; a fit over a range must
        // land between its values at the two ends. Eq 14: local n = 1 + 1/ln(L³/(F·R·η)).
        let contact = on_plane();
        let local = |f: f64| contact.approach_unchecked(f) / (f * contact.slope_unchecked(f));
        let fit = fit_line_contact(&contact, 1e2, 1e6).unwrap();
        assert!(local(1e2) < fit.n && fit.n < local(1e6), "{}", fit.n);
        let a_a = 1e-3 / (0.02 * 9.1e-12);
        assert!((local(1e6) - (1.0 + 1.0 / (a_a / 1e6f64).ln())).abs() < 1e-12);
    }

    #[test]
    fn an_exact_power_law_is_recovered_exactly() {
        // If x(F) were exactly (F/k)^{1/n}, the fit must return k, n and c = 0. Use the samples
        // machinery on synthetic data to check the optimiser itself.
        let (k, n): (f64, f64) = (8.435e9, 1.09);
        let (f_min, f_max): (f64, f64) = (4e3, 4e4);
        let x_ref = (f_max / k).powf(1.0 / n);
        let ratio = (f_max / f_min).powf(1.0 / (FIT_SAMPLES - 1) as f64);
        let mut samples = Samples {
            weight: [0.0; FIT_SAMPLES],
            log_x: [0.0; FIT_SAMPLES],
            f_ref: f_max,
            x_ref,
        };
        for i in 0..FIT_SAMPLES {
            let f = f_min * ratio.powi(i as i32);
            samples.weight[i] = f_max / f;
            samples.log_x[i] = ((f / k).powf(1.0 / n) / x_ref).ln();
        }
        let fit = samples
            .power_fit(levenberg_marquardt(&samples).unwrap(), f_min, f_max)
            .unwrap();
        assert!((fit.a / k - 1.0).abs() < 1e-9, "{fit:?}");
        assert!((fit.n - n).abs() < 1e-11, "{fit:?}");
        assert!(fit.c.abs() < 1e-7 * f_max, "{fit:?}");
        assert!(fit.max_rel_error < 1e-12, "{fit:?}");
    }

    #[test]
    fn the_offset_c_is_found_when_the_data_have_one() {
        // F = k·xⁿ + c₀ exactly: the third parameter must come out as c₀.
        let (k, n, c0) = (1.9e9, 1.2, 150.0);
        let (f_min, f_max): (f64, f64) = (1e3, 1e5);
        let x_of = |f: f64| ((f - c0) / k).powf(1.0 / n);
        let x_ref = x_of(f_max);
        let ratio = (f_max / f_min).powf(1.0 / (FIT_SAMPLES - 1) as f64);
        let mut samples = Samples {
            weight: [0.0; FIT_SAMPLES],
            log_x: [0.0; FIT_SAMPLES],
            f_ref: f_max,
            x_ref,
        };
        for i in 0..FIT_SAMPLES {
            let f = f_min * ratio.powi(i as i32);
            samples.weight[i] = f_max / f;
            samples.log_x[i] = (x_of(f) / x_ref).ln();
        }
        let fit = samples
            .power_fit(levenberg_marquardt(&samples).unwrap(), f_min, f_max)
            .unwrap();
        assert!((fit.c / c0 - 1.0).abs() < 1e-6, "{fit:?}");
        assert!((fit.n - n).abs() < 1e-9, "{fit:?}");
    }

    #[test]
    fn bad_ranges_are_refused_by_name() {
        let contact = on_plane();
        let msg = fit_line_contact(&contact, 0.0, 1e3)
            .unwrap_err()
            .to_string();
        assert!(msg.starts_with("fit range f_min must be"), "{msg}");
        let msg = fit_line_contact(&contact, 1e3, f64::NAN)
            .unwrap_err()
            .to_string();
        assert!(msg.starts_with("fit range f_max must be"), "{msg}");
        let err = fit_line_contact(&contact, 1e3, 1.2e3).unwrap_err();
        assert_eq!(
            err,
            ModelError::FitFailed(FitFailure::RangeTooNarrow {
                f_min: 1e3,
                f_max: 1.2e3,
                ratio: MIN_RANGE_RATIO
            })
        );
        assert_eq!(
            err.to_string(),
            "power-law fit F = a·xⁿ + c failed: the force range [1e3, 1.2e3] N is too narrow; f_max \
             must be at least 1.5·f_min to determine a, n and c"
        );
        let msg = fit_line_contact(&contact, 1e3, 1e12)
            .unwrap_err()
            .to_string();
        assert!(
            msg.starts_with("eq 14 (cylinder on a plane): force F = 1e12 N"),
            "{msg}"
        );
    }

    #[test]
    fn a_range_reaching_the_domain_edge_still_fits() {
        // Near F = L³/(Rη) the local exponent diverges; the fit must stay finite or say why.
        let contact = on_plane();
        let limit = contact.force_limit();
        match fit_line_contact(&contact, 0.1 * limit, 0.999 * limit) {
            Ok(fit) => assert!(fit.a > 0.0 && fit.n.is_finite() && fit.n > 1.0, "{fit:?}"),
            Err(err) => assert!(matches!(err, ModelError::FitFailed(_)), "{err}"),
        }
    }
}
