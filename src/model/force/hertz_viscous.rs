//! Hertz with linear viscous damping, F = k·xⁿ + γ·x^{(n−1)/2}·ẋ (Tsuji, Tanaka & Ishida 1992; the
//! law of Chrono's SMC Hertz model, LIGGGHTS and LAMMPS), docs/physics.md §6.2.

use crate::model::error::ModelError;
use crate::model::exact::ExactImpact;

use super::law::{ContactEnd, ForceLaw, Phase, abs_pow_nm1, signed_pow_n};
use super::table::ContactRule;
use super::{ForceModel, ImpactParams};

/// F = k·xⁿ + γ·x^{(n−1)/2}·ẋ (x^{1/4} for spheres). Its damping ratio γ/(2√(n·m·k)) is the same at
/// every approach, so its realised e depends on γ but not on v₀. Two contact-end rules: F ≥ 0
/// (contact ends where F returns to 0) or tension allowed (contact ends at x = 0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzViscous {
    params: ImpactParams,
    model: ForceModel,
    gamma: f64,
    tension_allowed: bool,
}

impl HertzViscous {
    /// The law with damping γ, N·s/m^{(n+1)/2}.
    pub fn new(
        model: ForceModel,
        params: &ImpactParams,
        gamma: f64,
        tension_allowed: bool,
    ) -> Self {
        HertzViscous {
            params: *params,
            model,
            gamma,
            tension_allowed,
        }
    }

    /// The table's builder: γ given, or from e by the β-map; the row's contact rule says whether
    /// tension is allowed.
    pub fn build(
        model: ForceModel,
        params: &ImpactParams,
        gamma: Option<f64>,
    ) -> Result<Self, ModelError> {
        Ok(Self::new(
            model,
            params,
            gamma.unwrap_or_else(|| Self::default_gamma(params)),
            model.spec().contact == ContactRule::TensionAllowed,
        ))
    }

    /// γ = −2√(5/6)·β·√(n·m·k), β = ln e/√(ln²e + π²): Tsuji's map as Chrono writes it
    /// (gn = −2√(5/6)·β·√(Sn·m), Sn = 2E*√(R·x) = (3/2)·k·√x for spheres), docs/physics.md §6.2.
    pub fn default_gamma(params: &ImpactParams) -> f64 {
        let ln_e = params.restitution.ln();
        let beta = ln_e / (ln_e * ln_e + std::f64::consts::PI.powi(2)).sqrt();
        -2.0 * (5.0f64 / 6.0).sqrt() * beta * (params.law.n * params.mass * params.law.k).sqrt()
    }

    /// The damping coefficient γ, N·s/m^{(n+1)/2}.
    pub fn gamma(&self) -> f64 {
        self.gamma
    }

    /// x^{(n−1)/2} for x ≥ 0 (|x| beyond).
    fn damping_power(&self, x: f64) -> f64 {
        abs_pow_nm1(x, self.params.law.n).sqrt()
    }
}

impl ForceLaw for HertzViscous {
    fn model(&self) -> ForceModel {
        self.model
    }

    fn params(&self) -> &ImpactParams {
        &self.params
    }

    /// F = k·xⁿ + γ·x^{(n−1)/2}·ẋ (Tsuji et al. 1992).
    fn phase_force(&self, x: f64, v: f64, _phase: Phase) -> f64 {
        let law = self.params.law;
        law.k * signed_pow_n(x, law.n) + self.gamma * self.damping_power(x) * v
    }

    /// γ·x^{(n−1)/2}·ẋ.
    fn dissipative_force(&self, x: f64, v: f64, _phase: Phase) -> f64 {
        self.gamma * self.damping_power(x) * v
    }

    /// (n·k·xⁿ⁻¹ + ((n−1)/2)·γ·x^{(n−3)/2}·ẋ, γ·x^{(n−1)/2}); |x| is kept above the smallest normal
    /// number so that the singular x^{(n−3)/2} stays finite at x = 0.
    fn partials(&self, x: f64, v: f64, _phase: Phase) -> (f64, f64) {
        let (k, n) = (self.params.law.k, self.params.law.n);
        let ax = x.abs().max(f64::MIN_POSITIVE);
        let q = self.damping_power(ax);
        (
            n * k * abs_pow_nm1(x, n) + 0.5 * (n - 1.0) * self.gamma * q / ax * x.signum() * v,
            self.gamma * self.damping_power(x),
        )
    }

    fn contact_end(&self) -> ContactEnd {
        if self.tension_allowed || self.gamma == 0.0 {
            ContactEnd::ApproachZero
        } else {
            ContactEnd::ForceZero
        }
    }

    fn may_turn_tensile(&self) -> bool {
        !self.tension_allowed && self.gamma > 0.0
    }

    /// F/x^{(n−1)/2} = k·x^{(n+1)/2} + γ·ẋ.
    fn tension(&self, x: f64, v: f64) -> f64 {
        self.params.law.k * x * self.damping_power(x) + self.gamma * v
    }

    /// γ·x^{(n−1)/2}·ẋ = d(β·xᵖ)/dt with p = (n+1)/2, β = γ/p.
    fn impulse_coefficient(&self) -> f64 {
        self.gamma / self.impulse_power()
    }

    fn impulse_power(&self) -> f64 {
        0.5 * (self.params.law.n + 1.0)
    }

    fn damping_value(&self) -> Option<f64> {
        Some(self.gamma)
    }

    /// No closed form: the adaptive solver integrates it.
    fn exact(&self, _rtol: f64) -> Option<ExactImpact> {
        None
    }
}
