//! Line contact of parallel cylinders and of a cylinder on a plane (eqs 11–14), and its fitted law.

mod approach;
mod exact_impact;
mod fit;
mod root;
mod scene;

#[cfg(test)]
mod property_tests;
#[cfg(test)]
mod table_2_tests;

use std::f64::consts::PI;

use serde::Serialize;

use super::error::ModelError;
use super::pair::ContactPair;
use super::pressure::PressureLaw;

pub use approach::LineContact;
pub use exact_impact::{LineImpact, line_contact_impact};
pub use fit::{FIT_SAMPLES, MIN_RANGE_RATIO, fit_power_law};
pub use scene::{FIT_RANGE_LOWER_FRACTION, scene_fit};

/// Half-width of the contact strip b = √((4/π)·η·(F/L)·R), m (eq 11).
pub fn half_width(eta: f64, reduced_radius: f64, length: f64, f: f64) -> f64 {
    (4.0 / PI * eta * f / length * reduced_radius).sqrt()
}

/// Maximum pressure p₀ = 2F/(πbL) = √(F/(π·L·η·R)), Pa (eq 12).
pub fn pressure_law(eta: f64, reduced_radius: f64, length: f64) -> PressureLaw {
    PressureLaw {
        coefficient: (1.0 / (PI * length * eta * reduced_radius)).sqrt(),
        exponent: 0.5,
        mean_to_max: PI / 4.0,
    }
}

/// The fitted law F = a·xⁿ + c (the paper's "pwrfit") over a force range.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PowerFit {
    /// a, N/mⁿ: the k used downstream.
    pub a: f64,
    /// Exponent n, dimensionless.
    pub n: f64,
    /// c, N.
    pub c: f64,
    /// Largest |F_fit − F|/F over the fitted samples.
    pub max_rel_error: f64,
    /// Lower end of the fitted force range, N.
    pub f_min: f64,
    /// Upper end of the fitted force range, N.
    pub f_max: f64,
}

/// Approach x(F) of a line contact, m: eq 13 for two cylinders, eq 14 for a cylinder on a plane.
///
/// Domain 0 < F < [`LineContact::force_limit`]: for eq 13, b (eq 11) below both diameters 2Rᵢ
/// (both logarithms positive) and x still increasing in F; for eq 14, F < L³/(R·η), where
/// dx/dF = (η/L)·ln(L³/(F·R·η)) vanishes. Outside: `InvalidParameter` (F not finite and positive),
/// `OutOfDomain` (F too large, or a point contact).
pub fn approach(pair: &ContactPair, f: f64) -> Result<f64, ModelError> {
    LineContact::of(pair)?.approach(f)
}

/// Force at approach x, N: eq 13/14 inverted by Newton's method safeguarded by bisection
/// (converged to 1e-14 relative).
///
/// Domain 0 < x < x(F_limit), the largest approach of the increasing branch (see [`approach`]).
/// Outside: `InvalidParameter` (x not finite and positive) or `OutOfDomain`.
pub fn force_at_approach(pair: &ContactPair, x: f64) -> Result<f64, ModelError> {
    LineContact::of(pair)?.force_at(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eq_12_is_twice_the_mean_pressure_over_pi_over_four() {
        // p₀ = 2F/(πbL) with b from eq 11 equals the closed form √(F/(π·L·η·R)).
        let (eta, r, l, f) = (9.1e-12, 0.01, 0.1, 4.004e4);
        let b = half_width(eta, r, l, f);
        let p0 = pressure_law(eta, r, l).pressure(f);
        assert!((p0 / (2.0 * f / (PI * b * l)) - 1.0).abs() < 1e-14);
        // Table 2, two cylinders at v₀ = 1 m/s: b = 2.154e-4 m, p₀ = 1183e6 Pa at F_max.
        assert!((b / 2.154e-4 - 1.0).abs() < 5e-4, "{b}");
        assert!((p0 / 1183e6 - 1.0).abs() < 5e-4, "{p0}");
    }
}
