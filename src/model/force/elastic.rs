//! Elastic Hertz contact, F = k·xⁿ (eq 1): no dissipation.

use crate::model::error::ModelError;
use crate::model::exact::{ExactImpact, elastic::elastic};

use super::law::{ContactEnd, ForceLaw, Phase, abs_pow_nm1, signed_pow_n};
use super::{ForceModel, ImpactParams};

/// F = k·xⁿ (eq 1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Elastic {
    params: ImpactParams,
}

impl Elastic {
    /// The elastic law of validated `params`.
    pub fn new(params: &ImpactParams) -> Self {
        Elastic { params: *params }
    }

    /// The table's builder: no damping parameter to set.
    pub fn build(
        _model: ForceModel,
        params: &ImpactParams,
        _damping: Option<f64>,
    ) -> Result<Self, ModelError> {
        Ok(Self::new(params))
    }
}

impl ForceLaw for Elastic {
    fn model(&self) -> ForceModel {
        ForceModel::Quasistatic
    }

    fn params(&self) -> &ImpactParams {
        &self.params
    }

    /// F = k·xⁿ (eq 1).
    fn phase_force(&self, x: f64, _v: f64, _phase: Phase) -> f64 {
        self.params.law.k * signed_pow_n(x, self.params.law.n)
    }

    fn dissipative_force(&self, _x: f64, _v: f64, _phase: Phase) -> f64 {
        0.0
    }

    /// ∂F/∂x = n·k·xⁿ⁻¹ (eq 1 differentiated).
    fn partials(&self, x: f64, _v: f64, _phase: Phase) -> (f64, f64) {
        let law = self.params.law;
        (law.n * law.k * abs_pow_nm1(x, law.n), 0.0)
    }

    fn contact_end(&self) -> ContactEnd {
        ContactEnd::ApproachZero
    }

    fn may_turn_tensile(&self) -> bool {
        false
    }

    fn tension(&self, _x: f64, _v: f64) -> f64 {
        1.0
    }

    fn exact(&self, _rtol: f64) -> Option<ExactImpact> {
        Some(elastic(&self.params))
    }
}
