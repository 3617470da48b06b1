//! The linear spring–dashpot (Kelvin–Voigt) contact F = K·x + c·ẋ, docs/physics.md §6.3.

use std::f64::consts::PI;

use crate::model::error::ModelError;
use crate::model::exact::ExactImpact;

use super::law::{ContactEnd, ForceLaw, Phase, signed_pow_n};
use super::table::ContactRule;
use super::{ForceModel, ImpactParams};

/// F = K·x + c·ẋ with K = m·(π/t_c)², t_c the Hertz contact time of the scene (eq 7), so that the
/// undamped linear contact lasts as long as the Hertz one. Two contact-end rules: F ≥ 0 (contact
/// ends where F returns to 0) or tension allowed (contact ends at x = 0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KelvinVoigt {
    params: ImpactParams,
    model: ForceModel,
    stiffness: f64,
    c: f64,
    tension_allowed: bool,
}

/// ζ = −ln e/√(π² + ln²e): the damping ratio whose linear oscillator rebounds with e after half
/// a damped period, docs/physics.md §6.3.
pub fn damping_ratio(e: f64) -> f64 {
    let ln_e = e.ln();
    -ln_e / (PI * PI + ln_e * ln_e).sqrt()
}

impl KelvinVoigt {
    /// The law with dashpot c, N·s/m.
    pub fn new(model: ForceModel, params: &ImpactParams, c: f64, tension_allowed: bool) -> Self {
        KelvinVoigt {
            params: *params,
            model,
            stiffness: Self::stiffness_of(params),
            c,
            tension_allowed,
        }
    }

    /// The table's builder: c given, or from e through ζ; the row's contact rule says whether
    /// tension is allowed.
    pub fn build(
        model: ForceModel,
        params: &ImpactParams,
        c: Option<f64>,
    ) -> Result<Self, ModelError> {
        Ok(Self::new(
            model,
            params,
            c.unwrap_or_else(|| Self::default_c(params)),
            model.spec().contact == ContactRule::TensionAllowed,
        ))
    }

    /// K = m·(π/t_c)², t_c of eq 7 (docs/physics.md §6.3), N/m: k itself for a linear law
    /// (t_c = π√(m/k)), without the rounding of t_c's beta function.
    pub fn stiffness_of(params: &ImpactParams) -> f64 {
        if params.law.n == 1.0 {
            return params.law.k;
        }
        let t_c = params.law.contact_time(params.mass, params.v0);
        params.mass * (PI / t_c).powi(2)
    }

    /// c = 2ζ·√(m·K), ζ from e (docs/physics.md §6.3), N·s/m.
    pub fn default_c(params: &ImpactParams) -> f64 {
        2.0 * damping_ratio(params.restitution) * (params.mass * Self::stiffness_of(params)).sqrt()
    }

    /// The spring K, N/m.
    pub fn stiffness(&self) -> f64 {
        self.stiffness
    }

    /// The dashpot c, N·s/m.
    pub fn c(&self) -> f64 {
        self.c
    }

    /// ζ = c/(2√(m·K)).
    pub fn zeta(&self) -> f64 {
        self.c / (2.0 * (self.params.mass * self.stiffness).sqrt())
    }
}

impl ForceLaw for KelvinVoigt {
    fn model(&self) -> ForceModel {
        self.model
    }

    fn params(&self) -> &ImpactParams {
        &self.params
    }

    /// F = K·x + c·ẋ.
    fn phase_force(&self, x: f64, v: f64, _phase: Phase) -> f64 {
        self.stiffness * x + self.c * v
    }

    /// F − k·xⁿ: the part of F that the scene's Hertz law does not store, which is what the
    /// energy check integrates (the elastic part of the balance is k·xⁿ's, see the trait).
    fn dissipative_force(&self, x: f64, v: f64, phase: Phase) -> f64 {
        self.phase_force(x, v, phase) - self.params.law.k * signed_pow_n(x, self.params.law.n)
    }

    fn partials(&self, _x: f64, _v: f64, _phase: Phase) -> (f64, f64) {
        (self.stiffness, self.c)
    }

    fn contact_end(&self) -> ContactEnd {
        if self.tension_allowed || self.c == 0.0 {
            ContactEnd::ApproachZero
        } else {
            ContactEnd::ForceZero
        }
    }

    fn may_turn_tensile(&self) -> bool {
        !self.tension_allowed && self.c > 0.0
    }

    fn tension(&self, x: f64, v: f64) -> f64 {
        self.stiffness * x + self.c * v
    }

    fn damping_value(&self) -> Option<f64> {
        Some(self.c)
    }

    /// The damped oscillator x = (v₀/ω_d)·e^{−ζω₀t}·sin(ω_d·t) (docs/physics.md §6.3), for ζ < 1.
    fn exact(&self, _rtol: f64) -> Option<ExactImpact> {
        let zeta = self.zeta();
        if !(0.0..1.0).contains(&zeta) {
            return None;
        }
        let v0 = self.params.v0;
        let w0 = (self.stiffness / self.params.mass).sqrt();
        let wd = w0 * (1.0 - zeta * zeta).sqrt();
        let decay = zeta * w0;
        let x_at = |theta: f64| v0 / wd * (-decay * theta / wd).exp() * theta.sin();
        let v_at = |theta: f64| {
            v0 * (-decay * theta / wd).exp() * (theta.cos() - decay / wd * theta.sin())
        };
        // ẋ = 0 at ω_d·t = arccos ζ.
        let theta_x_max = zeta.acos();
        // dF/dt = 0 at tan θ = √(1−ζ²)(1−4ζ²)/(ζ(3−4ζ²)) while ζ < 1/2; beyond, F peaks at the
        // first touch, F = c·v₀.
        let theta_f_max = if zeta < 0.5 {
            ((1.0 - zeta * zeta).sqrt() * (1.0 - 4.0 * zeta * zeta))
                .atan2(zeta * (3.0 - 4.0 * zeta * zeta))
        } else {
            0.0
        };
        // Tension allowed: x = 0 again at θ = π. F ≥ 0: F = 0 at θ = 2·arccos ζ.
        let theta_end = if self.tension_allowed {
            PI
        } else {
            2.0 * theta_x_max
        };
        let (x_f, v_f) = (x_at(theta_f_max), v_at(theta_f_max));
        let x_residual = if self.tension_allowed {
            0.0
        } else {
            x_at(theta_end)
        };
        let ex = ExactImpact {
            x_max: x_at(theta_x_max),
            t_x_max: theta_x_max / wd,
            f_max: self.stiffness * x_f + self.c * v_f,
            t_f_max: theta_f_max / wd,
            x_f_max: x_f,
            v_f_max: v_f,
            t_contact: theta_end / wd,
            v_out: -v_at(theta_end),
            x_residual,
            tensile_cutoff: false,
        };
        ex.is_valid().then_some(ex)
    }
}
