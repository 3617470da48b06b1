//! Typed errors of the model layer. Every message names the field or the domain it is about.
#![warn(missing_docs)]

use thiserror::Error;

use crate::format::{Zeros, scientific};

/// Everything the quasistatic model layer can refuse.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ModelError {
    /// A parameter is non-finite or outside its physical range.
    #[error("{field} must be {requirement}, got {value}")]
    InvalidParameter {
        /// The dotted field, e.g. `body1.material.poisson_ratio`.
        field: String,
        /// What the field must be, e.g. `in [0, 0.5)`.
        requirement: &'static str,
        /// The value given.
        value: f64,
    },
    /// A pair of shapes the model has no contact law for: the two shapes' names, body 1's first.
    #[error(
        "{}–{} contact is not supported (supported: sphere–sphere, sphere–plane, cylinder–cylinder, cylinder–plane)",
        .0[0], .0[1]
    )]
    UnsupportedPair([&'static str; 2]),
    /// A formula was asked for a value outside the domain where it holds.
    #[error("{formula}: {detail}")]
    OutOfDomain {
        /// The formula, with its equation number.
        formula: &'static str,
        /// What lies outside its domain, with the numbers.
        detail: Domain,
    },
    /// Inputs valid one by one whose elastic scales x_max (eq 5), x_max/v₀ and F_max (eq 6) are
    /// not all finite and non-zero in double precision: the solver could not scale them.
    #[error(
        "elastic impact scales (eqs 5–7): x_max = {x_max:e} m, x_max/v₀ = {t_ref:e} s, F_max = {f_max:e} N are not all finite and non-zero"
    )]
    ImpactScales {
        /// x_max, m.
        x_max: f64,
        /// x_max/v₀, s.
        t_ref: f64,
        /// F_max, N.
        f_max: f64,
    },
    /// A plastic indentation whose proposed damping b = k·x_pl/(v₀·e) (eq 18) overflows.
    #[error(
        "proposed damping b = k·x_pl/(v₀·e) (eq 18): impact.plastic_indentation = {plastic_indentation:e} m gives b = {damping:e}; use a plastic indentation of the order of x_max = {x_max:e} m"
    )]
    ProposedDamping {
        /// The scene's x_pl, m.
        plastic_indentation: f64,
        /// The damping b it gives, N·s/m^n.
        damping: f64,
        /// The elastic x_max (eq 5), m: the order x_pl should have.
        x_max: f64,
    },
    /// A quantity of the quasistatic estimate (eqs 1–14) left double precision (inputs each valid,
    /// together out of range, e.g. v₀ = 1e200 m/s).
    #[error(
        "quasistatic estimate: {quantity} = {value} is out of double-precision range; check the units of v0, radii, masses and moduli"
    )]
    EstimateOutOfRange {
        /// The first quantity out of range, as the estimate names it (`x_max`, `f_max`, …).
        quantity: &'static str,
        /// Its value: infinite, NaN or not positive.
        value: f64,
    },
    /// A line-contact impact storing more energy than eqs 13–14 hold for: they stop holding at
    /// `force_limit`, where they store `stored`.
    #[error(
        "eqs 13–14 (line contact): the impact energy {} J exceeds the {} J the formulas store up to F = {} N, where they stop holding; lower impact.v0",
        sci(*.energy), sci(*.stored), sci(*.force_limit)
    )]
    LineContactEnergy {
        /// The impact energy ½·m·v₀², J.
        energy: f64,
        /// The energy eqs 13–14 store up to their force limit, J.
        stored: f64,
        /// The force up to which eqs 13–14 hold, N.
        force_limit: f64,
    },
    /// The power-law fit of a cylinder force law did not converge.
    #[error("power-law fit F = a·xⁿ + c failed: {0}")]
    FitFailed(FitFailure),
}

/// What put a formula's input outside its domain, with the numbers ([`ModelError::OutOfDomain`]).
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum Domain {
    /// The line-contact formulas asked of a pair that touches at a point: the two shapes.
    #[error(
        "{}–{} is a point contact; the line-contact formulas need a cylinder on a cylinder or on a plane",
        .0[0], .0[1]
    )]
    PointContact([&'static str; 2]),
    /// A force so small that the approach x(F) underflows.
    #[error("force F = {force:e} N is too small: the approach x underflows to {approach:e} m")]
    ForceTooSmall {
        /// F, N.
        force: f64,
        /// x(F), m.
        approach: f64,
    },
    /// An approach past the largest the line-contact formula gives.
    #[error(
        "approach x = {approach:e} m is beyond x = {x_limit:e} m, the largest approach the formula gives (at F = {f_limit:e} N); use a smaller approach"
    )]
    ApproachBeyondLimit {
        /// x, m.
        approach: f64,
        /// The largest approach, m.
        x_limit: f64,
        /// The force there, N.
        f_limit: f64,
    },
    /// The inversion F(x) found no positive force.
    #[error(
        "the Newton–bisection solve for F at x = {approach:e} m found no positive force (x too small to resolve)"
    )]
    NoForceAt {
        /// x, m.
        approach: f64,
    },
    /// A force at or past the line-contact formula's limit; `bound` says what sets the limit.
    #[error(
        "force F = {force:e} N is at or beyond the limit {limit:e} N ({bound}); the line-contact formula does not hold there — lower the force or the impact velocity, or use longer cylinders"
    )]
    ForceBeyondLimit {
        /// F, N.
        force: f64,
        /// The limit, N.
        limit: f64,
        /// What bounds the formula there.
        bound: &'static str,
    },
    /// An impact that reaches the formula's force limit before the contact yields.
    #[error(
        "an impact at v0 = {v0} m/s reaches the force limit {limit:e} N of the formula before the contact yields; lower impact.v0 or use longer cylinders"
    )]
    LimitBeforeYield {
        /// v₀, m/s.
        v0: f64,
        /// The force limit, N.
        limit: f64,
    },
    /// An impact energy beyond what eqs 13–14 store up to their force limit.
    #[error("the impact energy {energy:e} J exceeds what the formulas store up to F = {limit:e} N")]
    EnergyBeyondLimit {
        /// ½·m·v₀², J.
        energy: f64,
        /// The force limit, N.
        limit: f64,
    },
    /// No peak force stores the impact energy (the root search failed).
    #[error("no peak force stores the impact energy")]
    NoPeakForce,
    /// The fitted exponent of a line contact outside the paper's 1 ≤ n ≤ 1.5.
    #[error(
        "the fit of eq 13/14 over {f_min:.4e}…{f_max:.4e} N gives n = {n:.4}, outside the paper's 1 ≤ n ≤ 1.5: the scene is near the end of the formulas' domain; lower impact.v0 or change the geometry"
    )]
    FitExponent {
        /// Lower end of the fit range, N.
        f_min: f64,
        /// Upper end of the fit range, N.
        f_max: f64,
        /// The fitted n.
        n: f64,
    },
    /// An impact whose F_max is past the force up to which eq 13/14 holds.
    #[error(
        "impact.v0 = {v0} m/s reaches F_max = {f_max:.4e} N, beyond the {limit:.4e} N up to which eq 13/14 holds (half-width b below the cylinder diameter); lower impact.v0"
    )]
    PeakBeyondLimit {
        /// v₀, m/s.
        v0: f64,
        /// F_max, N.
        f_max: f64,
        /// The force limit, N.
        limit: f64,
    },
    /// Thornton's law on a point contact whose exponent is not Hertz's 3/2.
    #[error("on a point contact it is Hertz's sphere (n = 3/2), and these parameters have n = {n}")]
    NotHertzExponent {
        /// The parameters' n.
        n: f64,
    },
    /// A yield velocity that is not finite and positive.
    #[error("v_yield = {v_yield} m/s: the yield velocity must be finite and > 0")]
    YieldVelocity {
        /// v_y, m/s.
        v_yield: f64,
    },
    /// An impact energy past what the law can store in double precision.
    #[error("the impact energy ½·m·v₀² = {energy:e} J is beyond what the law can store in f64")]
    EnergyBeyondF64 {
        /// ½·m·v₀², J.
        energy: f64,
    },
    /// Thornton's law without the bodies its yield velocity comes from.
    #[error(
        "its yield velocity comes from the yield stress and elastic constants of the bodies, and these parameters carry none (built without a scene); give v_y explicitly"
    )]
    YieldNeedsBodies,
    /// The exact contact law without the bodies its equations come from.
    #[error(
        "it needs the bodies (the cylinders' eq 13/14, or a sphere's eq 1), and these parameters carry none (built without a scene)"
    )]
    ExactNeedsBodies,
    /// A model index with no row in the law table.
    #[error("no row for model index {0}")]
    NoLawRow(usize),
    /// A law without a damping parameter asked for one: its id.
    #[error("{0} has no damping parameter")]
    NoDampingParameter(&'static str),
    /// A Hunt–Crossley-family row without a χ(e) rule: its id.
    #[error("{0} is built as a Hunt–Crossley law but has no χ(e)")]
    NoChiRule(&'static str),
    /// Two bodies of infinite mass.
    #[error("both bodies have infinite mass; give one of them a mass")]
    InfiniteMasses,
}

/// Why the power-law fit F = a·xⁿ + c of a line contact (eq 13/14) failed, with its numbers.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum FitFailure {
    /// The force range [f_min, f_max] is narrower than `ratio`·f_min allows.
    #[error(
        "the force range [{f_min:e}, {f_max:e}] N is too narrow; f_max must be at least {ratio}·f_min to determine a, n and c"
    )]
    RangeTooNarrow {
        /// Lower end of the range, N.
        f_min: f64,
        /// Upper end of the range, N.
        f_max: f64,
        /// The smallest f_max/f_min the fit accepts.
        ratio: f64,
    },
    /// The residuals at the log-log starting guess are not finite.
    #[error("the log-log starting guess is not finite")]
    StartNotFinite,
    /// Levenberg–Marquardt did not converge within `iterations`.
    #[error("Levenberg–Marquardt did not converge in {iterations} iterations")]
    NotConverged {
        /// The iteration limit.
        iterations: usize,
    },
    /// The fit converged to a stiffness that is not finite and positive.
    #[error(
        "the fit over [{f_min:e}, {f_max:e}] N gave a = {a:e}, n = {n}, c = {c:e}; the stiffness a must be finite and positive"
    )]
    BadStiffness {
        /// Lower end of the range, N.
        f_min: f64,
        /// Upper end of the range, N.
        f_max: f64,
        /// The fitted a, N/mⁿ.
        a: f64,
        /// The fitted n.
        n: f64,
        /// The fitted c, N.
        c: f64,
    },
    /// The fitted law gives no finite peak force at v₀.
    #[error("the fitted law a = {a:e}, n = {n} gives no finite F_max at v0 = {v0} m/s")]
    NoFiniteMaxForce {
        /// The fitted a, N/mⁿ.
        a: f64,
        /// The fitted n.
        n: f64,
        /// The impact velocity, m/s.
        v0: f64,
    },
    /// No fit range [F/10, F] reproduces its own F as the peak force below `ceiling`.
    #[error(
        "the fit range did not settle at v0 = {v0} m/s: no force F with F_max(fit over [F/10, F]) = F below {ceiling:e} N"
    )]
    RangeUnsettled {
        /// The impact velocity, m/s.
        v0: f64,
        /// The highest force searched, N.
        ceiling: f64,
    },
}

/// `value` in 4 significant digits, scientific, as the messages write it.
fn sci(value: f64) -> String {
    scientific(value, 4, Zeros::Trim)
}

impl ModelError {
    /// Prefixes the field name with its location, e.g. `youngs_modulus` → `body1.material.youngs_modulus`.
    pub fn within(self, prefix: &str) -> Self {
        match self {
            ModelError::InvalidParameter {
                field,
                requirement,
                value,
            } => ModelError::InvalidParameter {
                field: format!("{prefix}.{field}"),
                requirement,
                value,
            },
            other => other,
        }
    }
}

/// Checks that `value` is finite and satisfies `ok`; `requirement` says what `ok` demands.
pub fn require(
    field: &str,
    value: f64,
    requirement: &'static str,
    ok: impl Fn(f64) -> bool,
) -> Result<f64, ModelError> {
    if value.is_finite() && ok(value) {
        Ok(value)
    } else {
        Err(ModelError::InvalidParameter {
            field: field.to_string(),
            requirement,
            value,
        })
    }
}

/// Checks that `value` is finite and strictly positive.
pub fn require_positive(field: &str, value: f64) -> Result<f64, ModelError> {
    require(field, value, "a finite number > 0", |v| v > 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn invalid_parameter_message_names_the_field() {
        let err = require_positive("radius", 0.0).unwrap_err().within("body1");
        assert_eq!(
            err.to_string(),
            "body1.radius must be a finite number > 0, got 0"
        );
    }

    #[test]
    fn nan_and_infinity_are_rejected() {
        assert!(require_positive("mass", f64::NAN).is_err());
        assert!(require_positive("mass", f64::INFINITY).is_err());
        assert_eq!(require_positive("mass", 2.0), Ok(2.0));
    }
}
