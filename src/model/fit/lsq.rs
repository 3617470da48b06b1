//! The least-squares engine every fit goes through (docs/fitting.md, Method; docs/physics.md §9):
//! Levenberg–Marquardt on parameters transformed to unconstrained space (log for a positive
//! parameter), a finite-difference Jacobian, the covariance s²·(JᵀJ)⁻¹ (or (JᵀJ)⁻¹ when the
//! residuals are already divided by known standard deviations) and Student-t confidence
//! intervals.
//!
//! The problem is a residual function r(θ) of the parameters in their own (SI) units; the engine
//! never sees what they mean. Restitution fits (`super::fit_restitution`) and trace fits
//! (`super::trace`) both build an [`LsqProblem`] and call [`least_squares`]:
//!
//! ```
//! use hertz_tui::model::fit::lsq::{LsqOptions, LsqProblem, ParamSpec, least_squares};
//!
//! // y = A·exp(−t/τ) through five exact points, A = 2, τ = 0.5 s, from a poor start.
//! let t: [f64; 5] = [0.0, 0.25, 0.5, 1.0, 2.0];
//! let y: Vec<f64> = t.iter().map(|t| 2.0 * (-t / 0.5).exp()).collect();
//! let residuals = |p: &[f64]| -> Result<Vec<f64>, String> {
//!     Ok(t.iter().zip(&y).map(|(t, y)| p[0] * (-t / p[1]).exp() - y).collect())
//! };
//! let params = [
//!     ParamSpec::positive("A", "a", "1"),
//!     ParamSpec::positive("τ", "tau", "s"),
//! ];
//! let problem = LsqProblem { params: &params, start: vec![1.0, 2.0], residuals: &residuals, known_sd: false };
//! let fit = least_squares(&problem, &LsqOptions::default())?;
//! assert!((fit.theta[0] / 2.0 - 1.0).abs() < 1e-9 && (fit.theta[1] / 0.5 - 1.0).abs() < 1e-9);
//! # Ok::<(), hertz_tui::model::fit::lsq::LsqError>(())
//! ```
#![warn(missing_docs)]

use nalgebra::{DMatrix, DVector};
use serde::Serialize;
use statrs::distribution::{ContinuousCDF, Normal, StudentsT};
use thiserror::Error;

/// One parameter of a fit: what it is called and where it may lie.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ParamSpec {
    /// Its symbol, e.g. `a` or `v_y`.
    pub symbol: &'static str,
    /// The key it is reported under in JSON and scene files, e.g. `a`.
    pub key: &'static str,
    /// SI unit; `1` for a pure number.
    pub unit: &'static str,
    /// Fitted as ln θ (θ > 0), so that a step can never leave the positive axis and the
    /// confidence interval is multiplicative.
    pub log_scale: bool,
    /// The lowest value allowed (exclusive for a log-scale parameter, whose bound is 0).
    pub lower: f64,
    /// The highest value allowed.
    pub upper: f64,
}

impl ParamSpec {
    /// A parameter in (0, ∞), fitted on a log scale.
    pub const fn positive(symbol: &'static str, key: &'static str, unit: &'static str) -> Self {
        ParamSpec {
            symbol,
            key,
            unit,
            log_scale: true,
            lower: 0.0,
            upper: f64::INFINITY,
        }
    }

    /// A parameter in [lower, upper], fitted as it is.
    pub const fn bounded(
        symbol: &'static str,
        key: &'static str,
        unit: &'static str,
        lower: f64,
        upper: f64,
    ) -> Self {
        ParamSpec {
            symbol,
            key,
            unit,
            log_scale: false,
            lower,
            upper,
        }
    }

    /// θ → u, the unconstrained coordinate the engine steps in.
    pub fn to_free(&self, theta: f64) -> f64 {
        if self.log_scale { theta.ln() } else { theta }
    }

    /// u → θ.
    pub fn from_free(&self, u: f64) -> f64 {
        if self.log_scale { u.exp() } else { u }
    }

    /// u clamped to the bounds (in u).
    fn clamp_free(&self, u: f64) -> f64 {
        let (lo, hi) = if self.log_scale {
            (
                if self.lower > 0.0 {
                    self.lower.ln()
                } else {
                    f64::NEG_INFINITY
                },
                self.upper.ln(),
            )
        } else {
            (self.lower, self.upper)
        };
        u.clamp(lo, hi)
    }
}

/// The residuals r(θ) of a problem, or why they cannot be evaluated at θ.
pub type ResidualFn<'a> = dyn Fn(&[f64]) -> Result<Vec<f64>, String> + Sync + 'a;

/// A least-squares problem: minimise Σ rᵢ(θ)².
pub struct LsqProblem<'a> {
    /// The parameters, in the order of θ.
    pub params: &'a [ParamSpec],
    /// The starting θ, in the parameters' units (inside their bounds).
    pub start: Vec<f64>,
    /// The residuals at θ: model minus data, divided by the data's standard deviations when
    /// `known_sd`. An `Err` (a solve that failed at this θ) rejects the step that led there; at
    /// the start it fails the fit.
    pub residuals: &'a ResidualFn<'a>,
    /// The residuals are already divided by known standard deviations: the covariance is
    /// (JᵀJ)⁻¹ and the intervals use the normal quantile; otherwise s² = RSS/(N − p) scales it
    /// and the intervals use Student's t with N − p degrees of freedom.
    pub known_sd: bool,
}

/// How the Jacobian is estimated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Difference {
    /// (r(u + h·eⱼ) − r(u))/h: p residual evaluations per Jacobian.
    Forward,
    /// (r(u + h·eⱼ) − r(u − h·eⱼ))/(2h): 2p evaluations, second-order accurate.
    Central,
}

/// Tolerances and limits of [`least_squares`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LsqOptions {
    /// Iterations (accepted or rejected steps) before giving up.
    pub max_iterations: usize,
    /// Converged when every step component |δuⱼ| ≤ xtol·(|uⱼ| + xtol).
    pub xtol: f64,
    /// Converged when |Jᵀr|∞ ≤ gtol·(RSS + tiny), the gradient relative to the misfit.
    pub gtol: f64,
    /// Converged when an accepted step lowers RSS by less than ftol relative, or a rejected one
    /// was predicted to lower it by less.
    pub ftol: f64,
    /// Jacobian estimate of the iterations, where it only steers the steps.
    pub difference: Difference,
    /// Jacobian estimate at the minimum, which the covariance is computed from.
    pub final_difference: Difference,
    /// Finite-difference step in u (u = ln θ on log scale, so relative there).
    pub step: f64,
    /// Confidence level of the intervals, e.g. 0.95.
    pub level: f64,
}

impl Default for LsqOptions {
    fn default() -> Self {
        LsqOptions {
            max_iterations: 200,
            xtol: 1e-10,
            gtol: 1e-14,
            ftol: 1e-12,
            difference: Difference::Central,
            final_difference: Difference::Central,
            step: 1e-6,
            level: 0.95,
        }
    }
}

/// Why the engine stopped.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Convergence {
    /// The step fell below xtol.
    Step,
    /// The gradient fell below gtol.
    Gradient,
    /// RSS stopped falling (ftol).
    Residual,
    /// The residuals are zero to rounding.
    ZeroResidual,
    /// `max_iterations` ran out: the result is the best point found, not a converged one.
    IterationLimit,
}

/// The result of [`least_squares`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LsqResult {
    /// The best θ, in the parameters' units.
    pub theta: Vec<f64>,
    /// The residuals at θ.
    pub residuals: Vec<f64>,
    /// Σ rᵢ² at θ.
    pub rss: f64,
    /// Degrees of freedom N − p.
    pub dof: usize,
    /// Covariance of θ (in θ's units, by the delta method through the transform), row-major
    /// p × p; `None` when JᵀJ is singular (a parameter the data does not determine).
    pub covariance: Option<Vec<f64>>,
    /// Standard error of each θⱼ (√ of the covariance's diagonal); NaN where `covariance` is None.
    pub std_errors: Vec<f64>,
    /// The confidence interval of each θⱼ at `level`: θ ± q·se for a linear parameter, and
    /// θ·exp(±q·se(ln θ)) for a log-scale one (always positive), q the t (or normal) quantile.
    pub ci: Vec<(f64, f64)>,
    /// The confidence level of `ci`.
    pub level: f64,
    /// The quantile q the intervals use.
    pub quantile: f64,
    /// Iterations taken.
    pub iterations: usize,
    /// Residual-function evaluations taken.
    pub evaluations: usize,
    /// Why it stopped.
    pub convergence: Convergence,
}

/// Why a least-squares fit failed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum LsqError {
    /// Fewer residuals than parameters.
    #[error("{points} data points cannot determine {params} parameters")]
    TooFewPoints {
        /// Residuals.
        points: usize,
        /// Parameters.
        params: usize,
    },
    /// The start lies outside a parameter's bounds or is not finite.
    #[error("start {symbol} = {value} is outside [{lower}, {upper}]")]
    BadStart {
        /// The parameter.
        symbol: &'static str,
        /// The value given.
        value: f64,
        /// Its lower bound.
        lower: f64,
        /// Its upper bound.
        upper: f64,
    },
    /// The residual function failed or returned a non-finite value at the start.
    #[error("the model cannot be evaluated at the start: {0}")]
    AtStart(String),
    /// The residual function returned a vector of another length than at the start.
    #[error("the residual function returned {got} values, {expected} expected")]
    Length {
        /// What it returned.
        got: usize,
        /// What it returned at the start.
        expected: usize,
    },
}

/// Evaluates the residuals in u, counting, and checking them finite.
struct Counted<'a, 'b> {
    problem: &'a LsqProblem<'b>,
    evaluations: usize,
    len: usize,
}

impl Counted<'_, '_> {
    fn theta(&self, u: &[f64]) -> Vec<f64> {
        self.problem
            .params
            .iter()
            .zip(u)
            .map(|(p, &u)| p.from_free(u))
            .collect()
    }

    fn eval(&mut self, u: &[f64]) -> Result<DVector<f64>, String> {
        self.evaluations += 1;
        let r = (self.problem.residuals)(&self.theta(u))?;
        if self.len != usize::MAX && r.len() != self.len {
            return Err(LsqError::Length {
                got: r.len(),
                expected: self.len,
            }
            .to_string());
        }
        if let Some(i) = r.iter().position(|x| !x.is_finite()) {
            return Err(format!("residual {i} is {}", r[i]));
        }
        Ok(DVector::from_vec(r))
    }

    /// The Jacobian ∂r/∂u at u (r0 = r(u)); a failed evaluation (a bound, a solve) takes the
    /// one-sided difference on the other side.
    fn jacobian(
        &mut self,
        u: &[f64],
        r0: &DVector<f64>,
        opts: &LsqOptions,
        difference: Difference,
    ) -> Result<DMatrix<f64>, String> {
        let (n, p) = (r0.len(), u.len());
        let mut jac = DMatrix::zeros(n, p);
        for j in 0..p {
            let h = opts.step * u[j].abs().max(1.0);
            let mut up = u.to_vec();
            up[j] += h;
            let mut down = u.to_vec();
            down[j] -= h;
            let plus = self.eval(&up);
            let column = match (difference, plus) {
                (Difference::Central, Ok(rp)) => match self.eval(&down) {
                    Ok(rm) => (rp - rm) / (2.0 * h),
                    Err(_) => (rp - r0) / h,
                },
                (Difference::Forward, Ok(rp)) => (rp - r0) / h,
                (_, Err(_)) => (r0 - self.eval(&down)?) / h,
            };
            jac.set_column(j, &column);
        }
        Ok(jac)
    }
}

/// Minimises Σ rᵢ(θ)² by Levenberg–Marquardt (Marquardt's diagonal scaling, λ ×10 on a rejected
/// step and ÷10 on an accepted one; Nocedal & Wright, Numerical Optimization, 2nd ed., §10.3) in
/// the free coordinates u, and returns θ with its covariance and confidence intervals.
pub fn least_squares(problem: &LsqProblem, opts: &LsqOptions) -> Result<LsqResult, LsqError> {
    let p = problem.params.len();
    for (spec, &value) in problem.params.iter().zip(&problem.start) {
        let inside = value.is_finite()
            && value <= spec.upper
            && if spec.log_scale {
                value > 0.0 && value >= spec.lower
            } else {
                value >= spec.lower
            };
        if !inside {
            return Err(LsqError::BadStart {
                symbol: spec.symbol,
                value,
                lower: spec.lower,
                upper: spec.upper,
            });
        }
    }
    let mut counted = Counted {
        problem,
        evaluations: 0,
        len: usize::MAX,
    };
    let mut u: Vec<f64> = problem
        .params
        .iter()
        .zip(&problem.start)
        .map(|(s, &t)| s.to_free(t))
        .collect();
    let mut r = counted.eval(&u).map_err(LsqError::AtStart)?;
    counted.len = r.len();
    let n = r.len();
    if n < p {
        return Err(LsqError::TooFewPoints {
            points: n,
            params: p,
        });
    }
    let mut rss = r.norm_squared();
    let mut lambda = 1e-3;
    let mut iterations = 0;
    let mut jac = counted
        .jacobian(&u, &r, opts, opts.difference)
        .map_err(LsqError::AtStart)?;
    let convergence = loop {
        if rss <= f64::MIN_POSITIVE {
            break Convergence::ZeroResidual;
        }
        let jtr = jac.transpose() * &r;
        if jtr.amax() <= opts.gtol * rss {
            break Convergence::Gradient;
        }
        if iterations >= opts.max_iterations {
            break Convergence::IterationLimit;
        }
        iterations += 1;
        let jtj = jac.transpose() * &jac;
        let mut a = jtj.clone();
        for j in 0..p {
            // Marquardt's scaling, with a floor so a parameter the data ignores still moves.
            a[(j, j)] += lambda * jtj[(j, j)].max(1e-30 * jtj.diagonal().amax().max(1e-300));
        }
        let Some(step) = a.lu().solve(&(-&jtr)) else {
            lambda *= 10.0;
            continue;
        };
        let trial: Vec<f64> = problem
            .params
            .iter()
            .zip(&u)
            .zip(step.iter())
            .map(|((s, &u), &d)| s.clamp_free(u + d))
            .collect();
        let small_step = trial
            .iter()
            .zip(&u)
            .all(|(t, u)| (t - u).abs() <= opts.xtol * (u.abs() + opts.xtol));
        match counted.eval(&trial) {
            Ok(rt) => {
                let rss_t = rt.norm_squared();
                if rss_t < rss {
                    let relative = (rss - rss_t) / rss;
                    u = trial;
                    r = rt;
                    rss = rss_t;
                    lambda = (lambda / 10.0).max(1e-12);
                    if small_step {
                        break Convergence::Step;
                    }
                    if relative < opts.ftol {
                        break Convergence::Residual;
                    }
                    jac = counted
                        .jacobian(&u, &r, opts, opts.difference)
                        .map_err(LsqError::AtStart)?;
                    continue;
                }
                if small_step {
                    break Convergence::Step;
                }
                // The linear model promised next to nothing: what is left is the residual
                // function's own rounding (a solver's tolerance), not a minimum to approach.
                let predicted = -(2.0 * step.dot(&jtr) + step.dot(&(&jtj * &step)));
                if predicted <= opts.ftol * rss {
                    break Convergence::Residual;
                }
                lambda *= 10.0;
            }
            Err(_) => lambda *= 10.0,
        }
        if lambda > 1e16 {
            // No step in any direction lowers RSS: a minimum to rounding.
            break Convergence::Step;
        }
    };
    let theta = counted.theta(&u);
    // The covariance at the final point, from a fresh Jacobian there.
    let jac = counted
        .jacobian(&u, &r, opts, opts.final_difference)
        .unwrap_or(jac);
    let dof = n - p;
    let quantile = quantile(opts.level, if problem.known_sd { None } else { Some(dof) });
    let scale = if problem.known_sd {
        1.0
    } else if dof > 0 {
        rss / dof as f64
    } else {
        f64::NAN
    };
    let cov_u = (jac.transpose() * &jac)
        .try_inverse()
        .filter(|c| c.iter().all(|x| x.is_finite()))
        .map(|c| c * scale);
    // dθ/du: θ on a log scale, 1 otherwise.
    let slope: Vec<f64> = problem
        .params
        .iter()
        .zip(&theta)
        .map(|(s, &t)| if s.log_scale { t } else { 1.0 })
        .collect();
    let covariance = cov_u.as_ref().map(|c| {
        let mut out = vec![0.0; p * p];
        for i in 0..p {
            for j in 0..p {
                out[i * p + j] = c[(i, j)] * slope[i] * slope[j];
            }
        }
        out
    });
    let se_u: Vec<f64> = (0..p)
        .map(|j| {
            cov_u
                .as_ref()
                .map_or(f64::NAN, |c| c[(j, j)].max(0.0).sqrt())
        })
        .collect();
    let std_errors = (0..p).map(|j| se_u[j] * slope[j]).collect();
    let ci = problem
        .params
        .iter()
        .zip(&u)
        .zip(&se_u)
        .map(|((s, &u), &se)| {
            let (lo, hi) = (u - quantile * se, u + quantile * se);
            (s.from_free(lo), s.from_free(hi))
        })
        .collect();
    Ok(LsqResult {
        theta,
        residuals: r.iter().copied().collect(),
        rss,
        dof,
        covariance,
        std_errors,
        ci,
        level: opts.level,
        quantile,
        iterations,
        evaluations: counted.evaluations,
        convergence,
    })
}

/// The two-sided quantile of `level`: Student's t with `dof` degrees of freedom, or the normal
/// with `None` (known standard deviations). NaN for dof = 0.
pub fn quantile(level: f64, dof: Option<usize>) -> f64 {
    let p = 0.5 + 0.5 * level;
    match dof {
        None => Normal::standard().inverse_cdf(p),
        Some(0) => f64::NAN,
        Some(dof) => StudentsT::new(0.0, 1.0, dof as f64)
            .map(|t| t.inverse_cdf(p))
            .unwrap_or(f64::NAN),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quantiles_match_the_tables() {
        // t_{0.975} with 10 and 1 degrees of freedom, z_{0.975} (Abramowitz & Stegun, Table 26.10).
        assert!((quantile(0.95, Some(10)) - 2.228_138_852).abs() < 1e-8);
        assert!((quantile(0.95, Some(1)) - 12.706_204_736).abs() < 1e-6);
        assert!((quantile(0.95, None) - 1.959_963_985).abs() < 1e-8);
        assert!(quantile(0.95, Some(0)).is_nan());
    }

    #[test]
    fn a_straight_line_gets_the_textbook_intervals() {
        // y = c₀ + c₁·x with noise: LM must land on the normal equations' solution, and the
        // standard errors are s·√((XᵀX)⁻¹) exactly (the model is linear).
        let x = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0];
        let y = [1.1, 2.9, 5.2, 6.8, 9.1, 11.0];
        let residuals = |p: &[f64]| -> Result<Vec<f64>, String> {
            Ok(x.iter().zip(&y).map(|(x, y)| p[0] + p[1] * x - y).collect())
        };
        let params = [
            ParamSpec::bounded("c0", "c0", "1", -1e9, 1e9),
            ParamSpec::bounded("c1", "c1", "1", -1e9, 1e9),
        ];
        let problem = LsqProblem {
            params: &params,
            start: vec![0.0, 0.0],
            residuals: &residuals,
            known_sd: false,
        };
        let fit = least_squares(&problem, &LsqOptions::default()).unwrap();
        let n = x.len() as f64;
        let (sx, sy) = (x.iter().sum::<f64>(), y.iter().sum::<f64>());
        let sxx = x.iter().map(|x| x * x).sum::<f64>();
        let sxy = x.iter().zip(&y).map(|(x, y)| x * y).sum::<f64>();
        let det = n * sxx - sx * sx;
        let c1 = (n * sxy - sx * sy) / det;
        let c0 = (sy - c1 * sx) / n;
        assert!((fit.theta[0] - c0).abs() < 1e-9 && (fit.theta[1] - c1).abs() < 1e-9);
        let s2 = fit.rss / 4.0;
        assert!((fit.std_errors[1] - (s2 * n / det).sqrt()).abs() < 1e-7);
        assert!((fit.std_errors[0] - (s2 * sxx / det).sqrt()).abs() < 1e-7);
        let q = quantile(0.95, Some(4));
        assert!((fit.ci[1].1 - (c1 + q * fit.std_errors[1])).abs() < 1e-7);
    }

    #[test]
    fn bad_starts_and_too_few_points_are_refused() {
        let residuals = |p: &[f64]| -> Result<Vec<f64>, String> { Ok(vec![p[0] - 1.0]) };
        let params = [
            ParamSpec::positive("a", "a", "1"),
            ParamSpec::positive("b", "b", "1"),
        ];
        let problem = LsqProblem {
            params: &params,
            start: vec![1.0, 1.0],
            residuals: &residuals,
            known_sd: false,
        };
        let err = least_squares(&problem, &LsqOptions::default()).unwrap_err();
        assert_eq!(
            err,
            LsqError::TooFewPoints {
                points: 1,
                params: 2
            }
        );
        let problem = LsqProblem {
            start: vec![-1.0, 1.0],
            ..problem
        };
        assert!(matches!(
            least_squares(&problem, &LsqOptions::default()),
            Err(LsqError::BadStart { symbol: "a", .. })
        ));
    }
}
