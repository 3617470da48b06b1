//! A resolved scene: two bodies with their materials and the impact conditions, SI units.

use super::body::Body;
use super::error::{ModelError, require, require_positive};
use super::force::ImpactParams;
use super::pair::ContactPair;
use super::quasistatic::{self, Quasistatic};

/// Conditions of the impact (the `[impact]` table of a scene file).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactConditions {
    /// Pre-impact relative velocity v₀, m/s.
    pub v0: f64,
    /// Coefficient of restitution e in (0, 1], used by the dissipative models.
    pub restitution: f64,
    /// Plastic indentation x_pl ≥ 0, m, used by the proposed viscous model (eq 18).
    pub plastic_indentation: f64,
}

impl ImpactConditions {
    /// Checks v₀ > 0, 0 < e ≤ 1, x_pl ≥ 0 (0: no permanent deformation); field names are `impact.…`.
    pub fn validate(&self) -> Result<(), ModelError> {
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
        Ok(())
    }
}

/// A scene with materials resolved and every value in SI units.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    pub name: String,
    pub body1: Body,
    pub body2: Body,
    pub impact: ImpactConditions,
}

impl Scene {
    /// The validated contact pair of the two bodies.
    pub fn pair(&self) -> Result<ContactPair, ModelError> {
        ContactPair::new(self.body1.clone(), self.body2.clone())
    }

    /// The quasistatic estimate (eqs 1–14) at the scene's v₀.
    pub fn quasistatic(&self) -> Result<Quasistatic, ModelError> {
        self.impact.validate()?;
        quasistatic::evaluate(&self.pair()?, self.impact.v0)
    }

    /// Inputs of the impact solver: the quasistatic law F = k·xⁿ, the reduced mass and the impact conditions.
    pub fn impact_params(&self, quasistatic: &Quasistatic) -> ImpactParams {
        ImpactParams {
            mass: quasistatic.reduced_mass,
            law: quasistatic.law(),
            v0: self.impact.v0,
            restitution: self.impact.restitution,
            plastic_indentation: self.impact.plastic_indentation,
        }
    }
}
