//! The paper's viscous model F = k·xⁿ + b·xⁿ⁻¹·ẋ (eq 18), b = k·x_pl/(v₀·e). The same law with
//! b = k·A is the Kuwabara–Kono / Brilliantov viscoelastic sphere (docs/physics.md §6.5).

use crate::model::error::ModelError;
use crate::model::exact::{ExactImpact, elastic::elastic};

use super::any::kuwabara_kono_a;
use super::law::{ContactEnd, ForceLaw, Phase, abs_pow_nm1};
use super::table::ContactRule;
use super::{ForceModel, ImpactParams};

/// F = xⁿ⁻¹·(k·x + b·ẋ) (eq 18). Contact ends where F returns to 0, i.e. at ẋ = −k·x/b, leaving a
/// residual indentation; x_pl = 0 makes b = 0, the elastic law. A Kuwabara–Kono row may instead
/// let the force pull until x = 0 (the rule its restitution series assumes).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Proposed {
    params: ImpactParams,
    model: ForceModel,
    b: f64,
    /// b per unit of the row's damping parameter: 1 when it is b, k when it is Kuwabara–Kono's A.
    per_unit: f64,
    /// Contact ends at x = 0 with the force allowed to pull, not where F returns to 0.
    tension_allowed: bool,
}

impl Proposed {
    /// b = k·x_pl/(v₀·e) (eq 18, from F = 0 at x = x_pl, ẋ = −v₀e).
    pub fn new(params: &ImpactParams) -> Self {
        Proposed {
            params: *params,
            model: ForceModel::Proposed,
            b: params.law.k * params.plastic_indentation / (params.v0 * params.restitution),
            per_unit: 1.0,
            tension_allowed: false,
        }
    }

    /// The law with an explicit damping factor b, N·s/mⁿ.
    pub fn with_b(params: &ImpactParams, b: f64) -> Self {
        Proposed {
            params: *params,
            model: ForceModel::Proposed,
            b,
            per_unit: 1.0,
            tension_allowed: false,
        }
    }

    /// The table's law `model` of this form, F = k·(xⁿ + A·xⁿ⁻¹·ẋ): b = k·A (Kuwabara & Kono,
    /// Jpn. J. Appl. Phys. 26, 1987; Brilliantov et al., Phys. Rev. E 53, 1996), A in s.
    pub fn kuwabara_kono(model: ForceModel, params: &ImpactParams, a: f64) -> Self {
        Proposed {
            params: *params,
            model,
            b: params.law.k * a,
            per_unit: params.law.k,
            tension_allowed: false,
        }
    }

    /// The table's builder of the paper's row: b given, or from x_pl and e (eq 18).
    pub fn build(
        _model: ForceModel,
        params: &ImpactParams,
        b: Option<f64>,
    ) -> Result<Self, ModelError> {
        Ok(match b {
            Some(b) => Self::with_b(params, b),
            None => Self::new(params),
        })
    }

    /// The table's builder of the Kuwabara–Kono rows: A given, or from e by the series' first term
    /// at the scene's v₀ (docs/physics.md §6.5); the row's contact rule says whether tension is
    /// allowed.
    pub fn build_kuwabara_kono(
        model: ForceModel,
        params: &ImpactParams,
        a: Option<f64>,
    ) -> Result<Self, ModelError> {
        let a = a.unwrap_or_else(|| kuwabara_kono_a(params));
        Ok(Proposed {
            tension_allowed: model.spec().contact == ContactRule::TensionAllowed,
            ..Self::kuwabara_kono(model, params, a)
        })
    }

    /// The damping factor b, N·s/mⁿ.
    pub fn b(&self) -> f64 {
        self.b
    }
}

impl ForceLaw for Proposed {
    fn model(&self) -> ForceModel {
        self.model
    }

    fn params(&self) -> &ImpactParams {
        &self.params
    }

    /// F = k·xⁿ + b·xⁿ⁻¹·ẋ (eq 18).
    fn phase_force(&self, x: f64, v: f64, _phase: Phase) -> f64 {
        let (k, n) = (self.params.law.k, self.params.law.n);
        abs_pow_nm1(x, n) * (k * x + self.b * v)
    }

    /// b·xⁿ⁻¹·ẋ (eq 18).
    fn dissipative_force(&self, x: f64, v: f64, _phase: Phase) -> f64 {
        self.b * abs_pow_nm1(x, self.params.law.n) * v
    }

    /// (n·k·xⁿ⁻¹ + (n−1)·b·xⁿ⁻²·ẋ, b·xⁿ⁻¹) (eq 18 differentiated). xⁿ⁻² = xⁿ⁻¹/x is singular at
    /// x = 0 for n < 2; |x| is kept above the smallest normal number so the result stays finite.
    fn partials(&self, x: f64, v: f64, _phase: Phase) -> (f64, f64) {
        let (k, n) = (self.params.law.k, self.params.law.n);
        let xnm1 = abs_pow_nm1(x, n);
        let ax = x.abs().max(f64::MIN_POSITIVE);
        let xnm2 = abs_pow_nm1(ax, n) / ax * x.signum();
        (n * k * xnm1 + (n - 1.0) * self.b * xnm2 * v, self.b * xnm1)
    }

    fn contact_end(&self) -> ContactEnd {
        if self.b > 0.0 && !self.tension_allowed {
            ContactEnd::ForceZero
        } else {
            ContactEnd::ApproachZero
        }
    }

    fn may_turn_tensile(&self) -> bool {
        self.b > 0.0 && !self.tension_allowed
    }

    /// Its residual at F = 0 is the plastic indentation x_pl the model is built for (eq 18).
    fn residual_is_permanent(&self) -> bool {
        self.contact_end() == ContactEnd::ForceZero
    }

    /// F/xⁿ⁻¹ = k·x + b·ẋ.
    fn tension(&self, x: f64, v: f64) -> f64 {
        self.params.law.k * x + self.b * v
    }

    /// b·xⁿ⁻¹·ẋ = d(b·xⁿ/n)/dt.
    fn impulse_coefficient(&self) -> f64 {
        self.b / self.params.law.n
    }

    /// b, or A = b/k for the Kuwabara–Kono row.
    fn damping_value(&self) -> Option<f64> {
        Some(self.b / self.per_unit)
    }

    /// Only the elastic limit b = 0 has a closed form.
    fn exact(&self, _rtol: f64) -> Option<ExactImpact> {
        (self.b == 0.0).then(|| elastic(&self.params))
    }
}
