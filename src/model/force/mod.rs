//! The five contact-force laws of the paper (eqs 1, 15–20) behind one interface.

use std::fmt;
use std::str::FromStr;

use serde::Serialize;

use super::error::{ModelError, require, require_positive};
use super::power_law::PowerLaw;

pub mod any;
pub mod dry_friction;
pub mod elastic;
pub mod hysteresis;
pub mod law;
pub mod proposed;

pub use any::AnyLaw;
pub use law::{ContactEnd, ForceLaw, Phase};

/// Inputs every force law draws its parameters from (the scene plus the quasistatic law).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ImpactParams {
    /// Reduced mass m, kg (eq 4).
    pub mass: f64,
    /// Elastic law F = k·xⁿ (eq 1).
    pub law: PowerLaw,
    /// Pre-impact velocity v₀ > 0, m/s.
    pub v0: f64,
    /// Coefficient of restitution e in (0, 1].
    pub restitution: f64,
    /// Plastic indentation x_pl ≥ 0, m (eq 18); 0 makes the proposed model elastic.
    pub plastic_indentation: f64,
}

impl ImpactParams {
    /// Checks m > 0, a valid power law (k > 0, n ≥ 1), v₀ > 0, 0 < e ≤ 1, x_pl ≥ 0, all finite, and
    /// that the elastic scales x_max, x_max/v₀ and F_max are finite and non-zero (they scale the
    /// solver; t_c is x_max/v₀ times a constant of n).
    pub fn validate(&self) -> Result<(), ModelError> {
        require_positive("mass", self.mass)?;
        PowerLaw::new(self.law.k, self.law.n)?;
        require_positive("impact.v0", self.v0)?;
        require("impact.restitution", self.restitution, "in (0, 1]", |e| {
            e > 0.0 && e <= 1.0
        })?;
        require(
            "impact.plastic_indentation",
            self.plastic_indentation,
            "a finite number ≥ 0",
            |x| x >= 0.0,
        )?;
        let x_max = self.law.max_approach(self.mass, self.v0);
        let t_ref = x_max / self.v0;
        let f_max = self.law.force(x_max);
        if [x_max, t_ref, f_max]
            .iter()
            .any(|q| !(q.is_finite() && q.is_normal()))
        {
            return Err(ModelError::OutOfDomain {
                formula: "elastic impact scales (eqs 5–7)",
                detail: format!(
                    "x_max = {x_max:e} m, x_max/v₀ = {t_ref:e} s, F_max = {f_max:e} N are not all finite and non-zero"
                ),
            });
        }
        let damping = self.law.k * self.plastic_indentation / (self.v0 * self.restitution);
        if !damping.is_finite() {
            return Err(ModelError::OutOfDomain {
                formula: "proposed damping b = k·x_pl/(v₀·e) (eq 18)",
                detail: format!(
                    "impact.plastic_indentation = {:e} m gives b = {damping:e}; use a plastic indentation of the order of x_max = {x_max:e} m",
                    self.plastic_indentation
                ),
            });
        }
        Ok(())
    }
}

/// Which force law.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum ForceModel {
    /// Elastic Hertz F = k·xⁿ (eq 1).
    Quasistatic,
    /// F = k·xⁿ + P·x·sign(ẋ) (eqs 15–17).
    DryFriction,
    /// The paper's viscous model F = k·xⁿ + b·xⁿ⁻¹·ẋ (eq 18).
    Proposed,
    /// F = k·xⁿ·(1 + (3/2)·a·ẋ), a = (1 − e)/v₀ (eq 19).
    HuntCrossley,
    /// F = k·xⁿ·(1 + 3(1 − e²)/4·ẋ/v₀) (eq 20).
    LankaraniNikravesh,
}

impl ForceModel {
    pub const ALL: [ForceModel; 5] = [
        ForceModel::Quasistatic,
        ForceModel::DryFriction,
        ForceModel::Proposed,
        ForceModel::HuntCrossley,
        ForceModel::LankaraniNikravesh,
    ];

    /// The kebab-case name used on the command line and in JSON.
    pub fn name(self) -> &'static str {
        match self {
            ForceModel::Quasistatic => "quasistatic",
            ForceModel::DryFriction => "dry-friction",
            ForceModel::Proposed => "proposed",
            ForceModel::HuntCrossley => "hunt-crossley",
            ForceModel::LankaraniNikravesh => "lankarani-nikravesh",
        }
    }

    /// The law of this model for `params` (validated).
    pub fn law(self, params: &ImpactParams) -> Result<AnyLaw, ModelError> {
        AnyLaw::new(self, params)
    }

    /// A human label with the paper's equation number.
    pub fn label(self) -> &'static str {
        match self {
            ForceModel::Quasistatic => "Hertz, elastic (eq 1)",
            ForceModel::DryFriction => "dry friction (eq 15)",
            ForceModel::Proposed => "proposed viscous (eq 18)",
            ForceModel::HuntCrossley => "Hunt–Crossley (eq 19)",
            ForceModel::LankaraniNikravesh => "Lankarani–Nikravesh (eq 20)",
        }
    }
}

impl fmt::Display for ForceModel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for ForceModel {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        ForceModel::ALL
            .into_iter()
            .find(|m| m.name() == s)
            .ok_or_else(|| {
                let names: Vec<_> = ForceModel::ALL.iter().map(|m| m.name()).collect();
                format!(
                    "unknown model '{s}' (expected one of: {})",
                    names.join(", ")
                )
            })
    }
}

#[cfg(test)]
mod tests;
