//! The Hunt–Crossley family F = k·xⁿ·(1 + α·ẋ), α = χ(e)/v₀: Hunt–Crossley (eq 19),
//! Lankarani–Nikravesh (eq 20) and the χ(e) rows of the law table (docs/physics.md §6.1).

use crate::model::error::{Domain, ModelError, require_positive};
use crate::model::exact::{ExactImpact, hysteresis::hysteresis};

use super::law::{ContactEnd, ForceLaw, Phase, abs_pow_nm1, signed_pow_n};
use super::{ForceModel, ImpactParams};

/// F = k·xⁿ·(1 + α·ẋ) with α from the restitution e and v₀.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hysteresis {
    params: ImpactParams,
    model: ForceModel,
    alpha: f64,
}

impl Hysteresis {
    /// Hunt–Crossley: α = (3/2)·a, a = (1 − e)/v₀ (eq 19).
    pub fn hunt_crossley(params: &ImpactParams) -> Self {
        Hysteresis {
            params: *params,
            model: ForceModel::HuntCrossley,
            alpha: 1.5 * (1.0 - params.restitution) / params.v0,
        }
    }

    /// Hunt–Crossley with a = (1 − e)/v_c calibrated at another impact velocity v_c (the paper fits
    /// e = 1 − a·v₀ over a range of velocities, so a is a material constant): α = (3/2)·a (eq 19).
    pub fn hunt_crossley_calibrated(
        params: &ImpactParams,
        v_calibration: f64,
    ) -> Result<Self, ModelError> {
        require_positive("v_calibration", v_calibration)?;
        Ok(Hysteresis {
            params: *params,
            model: ForceModel::HuntCrossley,
            alpha: 1.5 * (1.0 - params.restitution) / v_calibration,
        })
    }

    /// The law `model` of the family with α = χ/v₀ (docs/physics.md §6.1).
    pub fn with_chi(model: ForceModel, params: &ImpactParams, chi: f64) -> Self {
        Hysteresis {
            params: *params,
            model,
            alpha: chi / params.v0,
        }
    }

    /// The table's builder: χ given, or from e by the row's χ(e).
    pub fn build(
        model: ForceModel,
        params: &ImpactParams,
        chi: Option<f64>,
    ) -> Result<Self, ModelError> {
        let chi = match (chi, model.spec().chi) {
            (Some(chi), _) => chi,
            (None, Some(rule)) => rule(params.restitution),
            (None, None) => {
                return Err(ModelError::OutOfDomain {
                    formula: "law table",
                    detail: Domain::NoChiRule(model.name()),
                });
            }
        };
        Ok(Self::with_chi(model, params, chi))
    }

    /// Lankarani–Nikravesh: α = 3(1 − e²)/(4·v₀) (eq 20).
    pub fn lankarani_nikravesh(params: &ImpactParams) -> Self {
        let e = params.restitution;
        Hysteresis {
            params: *params,
            model: ForceModel::LankaraniNikravesh,
            alpha: 3.0 * (1.0 - e * e) / (4.0 * params.v0),
        }
    }

    /// The damping factor α, s/m.
    pub fn alpha(&self) -> f64 {
        self.alpha
    }

    /// χ = α·v₀, dimensionless.
    pub fn chi(&self) -> f64 {
        self.alpha * self.params.v0
    }
}

impl ForceLaw for Hysteresis {
    fn model(&self) -> ForceModel {
        self.model
    }

    fn params(&self) -> &ImpactParams {
        &self.params
    }

    /// F = k·xⁿ·(1 + α·ẋ) (eqs 19–20).
    fn phase_force(&self, x: f64, v: f64, _phase: Phase) -> f64 {
        self.params.law.k * signed_pow_n(x, self.params.law.n) * (1.0 + self.alpha * v)
    }

    /// k·xⁿ·α·ẋ (eqs 19–20).
    fn dissipative_force(&self, x: f64, v: f64, _phase: Phase) -> f64 {
        self.params.law.k * signed_pow_n(x, self.params.law.n) * self.alpha * v
    }

    /// (n·k·xⁿ⁻¹·(1 + αẋ), k·xⁿ·α) (eqs 19–20 differentiated).
    fn partials(&self, x: f64, v: f64, _phase: Phase) -> (f64, f64) {
        let (k, n) = (self.params.law.k, self.params.law.n);
        let xnm1 = abs_pow_nm1(x, n);
        (
            n * k * xnm1 * (1.0 + self.alpha * v),
            k * x * xnm1 * self.alpha,
        )
    }

    fn contact_end(&self) -> ContactEnd {
        ContactEnd::ApproachZero
    }

    /// In exact arithmetic never (1 + αẋ = 0 is invariant, see `exact::hysteresis`); watched for
    /// because an integrator's error can cross it.
    fn may_turn_tensile(&self) -> bool {
        self.alpha > 0.0
    }

    /// F/(k·xⁿ) = 1 + α·ẋ.
    fn tension(&self, _x: f64, v: f64) -> f64 {
        1.0 + self.alpha * v
    }

    fn damping_value(&self) -> Option<f64> {
        Some(self.chi())
    }

    fn exact(&self, rtol: f64) -> Option<ExactImpact> {
        hysteresis(&self.params, self.alpha, rtol)
    }
}
