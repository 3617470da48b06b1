//! Line contact of parallel cylinders and of a cylinder on a plane: eqs 11–14 and the power-law fit.

use std::f64::consts::PI;

use serde::Serialize;

use super::error::ModelError;
use super::pair::ContactPair;
use super::pressure::PressureLaw;

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
pub fn approach(_pair: &ContactPair, _f: f64) -> Result<f64, ModelError> {
    todo!("cylinder helper: eq 13/14 with domain checks")
}

/// Force at approach x, N: eq 13/14 inverted by a bracketed Newton solve.
pub fn force_at_approach(_pair: &ContactPair, _x: f64) -> Result<f64, ModelError> {
    todo!("cylinder helper: bracketed Newton")
}

/// Fits F = a·xⁿ + c to eq 13/14 sampled over [f_min, f_max] (Levenberg–Marquardt, nalgebra).
pub fn fit_power_law(
    _pair: &ContactPair,
    _f_min: f64,
    _f_max: f64,
) -> Result<PowerFit, ModelError> {
    todo!("cylinder helper: LM fit")
}

/// The fit over the force range an impact at v₀ reaches (Table 2).
pub fn scene_fit(_pair: &ContactPair, _v0: f64) -> Result<PowerFit, ModelError> {
    todo!("cylinder helper: fit range of the scene")
}
