//! Thornton's elastic–perfectly-plastic sphere (J. Appl. Mech. 64, 1997), and the same
//! construction on a line contact, docs/physics.md §6.6: Hertz up to the limiting pressure, then
//! the Hertz pressure capped at it; elastic unloading with the enlarged radius, down to a residual
//! indentation.

use std::f64::consts::PI;

use crate::model::cylinder::pressure_law;
use crate::model::error::{Domain, ModelError};
use crate::model::exact::ExactImpact;
use crate::model::numeric::roots::brent;

use super::law::{ContactEnd, ForceLaw, Phase, abs_pow_nm1, signed_pow_n};
use super::{Contact, ForceModel, ImpactParams};

mod cap;
mod exact;

pub use cap::{Cap, capped_restitution, thornton_restitution};

/// Thornton's law with its yield velocity v_y (the impact speed at which Hertz contact first
/// reaches the limiting pressure p_y). With x_y = the elastic x_max at v_y and F_y = k·x_yⁿ:
/// loading F = k·xⁿ up to x_y, then the Hertz pressure capped at p_y ([`Cap`]); unloading
/// F = k_u·(x − x_res)ⁿ, the elastic contact of enlarged radius R_p = λ·R that is as wide at
/// F_max as the loaded one: λ = k·x_maxⁿ/F_max and k_u = k·λⁿ⁻¹ (= k·√(R_p/R) for spheres).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Thornton {
    params: ImpactParams,
    model: ForceModel,
    cap: Cap,
    v_yield: f64,
    x_yield: f64,
    f_yield: f64,
    x_max: f64,
    /// F_max, N: the loading force at x_max, where unloading starts.
    f_max: f64,
    k_unload: f64,
    x_residual: f64,
}

/// The smallest v_y/v₀ calibration searches: e ∝ q^{1/4} (spheres) or q^{n/(n+2)} (strips) is
/// then ~10⁻²⁵ or less.
const LOWEST_Q: f64 = 1e-100;

/// The refusal of a contact whose n is not Hertz's (spheres, by hand without a scene).
fn exponent_refused(n: f64) -> ModelError {
    ModelError::OutOfDomain {
        formula: "Thornton (1997) elastic–perfectly-plastic law",
        detail: Domain::NotHertzExponent { n },
    }
}

impl Thornton {
    /// The law with yield velocity `v_yield`, m/s: the circle cap on spheres (n = 3/2), the strip
    /// cap on line contacts (any n of the scene's fit); parameters without a scene are a sphere's.
    pub fn new(model: ForceModel, params: &ImpactParams, v_yield: f64) -> Result<Self, ModelError> {
        let cap = match params.contact {
            Contact::Line { .. } => Cap::Strip,
            Contact::Point(_) | Contact::Unspecified => {
                if params.law.n != 1.5 {
                    return Err(exponent_refused(params.law.n));
                }
                Cap::Circle
            }
        };
        if !(v_yield > 0.0 && v_yield.is_finite()) {
            return Err(ModelError::OutOfDomain {
                formula: "Thornton (1997) elastic–perfectly-plastic law",
                detail: Domain::YieldVelocity { v_yield },
            });
        }
        let (k, n, m, v0) = (params.law.k, params.law.n, params.mass, params.v0);
        let elastic = v_yield >= v0;
        let x_yield = params.law.max_approach(m, v_yield.min(v0));
        let f_yield = k * x_yield.powf(n);
        let x_max = if elastic || x_yield == 0.0 {
            params.law.max_approach(m, v0)
        } else {
            // ½mv₀² = k·x_y^{n+1}/(n+1) + the plastic work from x_y to x_max.
            let unit = f_yield * x_yield;
            let plastic = (0.5 * m * v0 * v0 - k * x_yield.powf(n + 1.0) / (n + 1.0)) / unit;
            x_yield * cap.approach_for_work(plastic, n)
        };
        let law = Thornton {
            params: *params,
            model,
            cap,
            v_yield,
            x_yield: if elastic { x_max } else { x_yield },
            f_yield,
            x_max,
            f_max: f_yield,
            k_unload: k,
            x_residual: 0.0,
        }
        .unloading_from(x_max);
        if !(x_max.is_finite() && law.f_max.is_finite() && (x_max / x_yield).is_finite()) {
            return Err(ModelError::OutOfDomain {
                formula: "Thornton (1997) elastic–perfectly-plastic law",
                detail: Domain::EnergyBeyondF64 {
                    energy: 0.5 * m * v0 * v0,
                },
            });
        }
        Ok(law)
    }

    /// The law unloading from the turning point `x_max`, m: Hertz's if it lies at or below first
    /// yield, else k_u = k·λⁿ⁻¹ with λ = k·x_maxⁿ/F_max and x_res = x_max − (F_max/k_u)^{1/n}.
    fn unloading_from(self, x_max: f64) -> Self {
        let (k, n) = (self.params.law.k, self.params.law.n);
        if x_max <= self.x_yield {
            return Thornton {
                x_max: self.x_yield,
                f_max: self.f_yield,
                k_unload: k,
                x_residual: 0.0,
                ..self
            };
        }
        let f_max = self.f_yield * self.cap.force_ratio(x_max / self.x_yield, n);
        let lambda = (k * x_max.powf(n) / f_max).max(1.0);
        let k_unload = k * lambda.powf(n - 1.0);
        let x_residual = x_max - (f_max / k_unload).powf(1.0 / n);
        Thornton {
            x_max,
            f_max,
            k_unload,
            x_residual: x_residual.max(0.0),
            ..self
        }
    }

    /// The table's builder: v_y given, or from the material ([`Thornton::default_v_yield`]).
    pub fn build(
        model: ForceModel,
        params: &ImpactParams,
        v_yield: Option<f64>,
    ) -> Result<Self, ModelError> {
        let v_yield = match v_yield {
            Some(v_yield) => v_yield,
            None => Self::default_v_yield(params)?,
        };
        Self::new(model, params, v_yield)
    }

    /// Thornton's V_y from the material: the impact speed at which the Hertz pressure p₀ first
    /// reaches p_y. Spheres: x_y = R·(π·p_y/(2E*))² (p₀ = (2E*/π)·√(x/R)) and
    /// ½mV_y² = k·x_y^{5/2}/(5/2) (Thornton 1997; his V_y = 1.56·(p_y⁵/(E*⁴ρ))^{1/2} for a sphere
    /// on a plane). Cylinders: F_y = π·L·η·R·p_y² (eq 12 inverted) on the scene's k·xⁿ. With
    /// p_y = 1.1·σ_y both are the paper's yield-onset speed v₀y, docs/physics.md §6.6.
    pub fn default_v_yield(params: &ImpactParams) -> Result<f64, ModelError> {
        let f_yield = match params.contact {
            Contact::Point(point) => {
                let x_yield =
                    point.radius * (PI * point.yield_pressure / (2.0 * point.modulus)).powi(2);
                params.law.force(x_yield)
            }
            Contact::Line {
                line,
                yield_pressure,
                ..
            } => pressure_law(line.eta(), line.reduced_radius(), line.length())
                .force_at_pressure(yield_pressure),
            Contact::Unspecified => {
                return Err(ModelError::OutOfDomain {
                    formula: "Thornton (1997) elastic–perfectly-plastic law",
                    detail: Domain::YieldNeedsBodies,
                });
            }
        };
        Ok(params.law.velocity_for_force(params.mass, f_yield))
    }

    /// The v_y at which the law's e(V) at `v0` is `e` (calibration, docs/physics.md §6.4):
    /// Thornton's closed form inverted on spheres, [`capped_restitution`] on line contacts;
    /// `None` where even v_y = 10⁻¹⁰⁰·v₀ rebounds above `e`.
    pub fn v_yield_for_restitution(params: &ImpactParams, e: f64) -> Option<f64> {
        let v0 = params.v0;
        if e >= 1.0 {
            return Some(v0);
        }
        brent(|q| Self::restitution_at(params, q) - e, LOWEST_Q, 1.0).map(|q| q * v0)
    }

    /// The lowest restitution calibration can reach: at v_y = 10⁻¹⁰⁰·v₀.
    pub fn lowest_restitution(params: &ImpactParams) -> f64 {
        Self::restitution_at(params, LOWEST_Q)
    }

    /// The restitution the law gives at `params` with yield velocity `v_yield`: Thornton's closed
    /// form on spheres, [`capped_restitution`] on line contacts.
    pub fn restitution_of(params: &ImpactParams, v_yield: f64) -> f64 {
        Self::restitution_at(params, v_yield / params.v0)
    }

    /// [`Thornton::restitution_of`] at q = v_y/v₀.
    fn restitution_at(params: &ImpactParams, q: f64) -> f64 {
        match params.contact {
            Contact::Line { .. } => capped_restitution(Cap::Strip, q, params.law.n),
            _ => thornton_restitution(q),
        }
    }

    /// The yield velocity v_y, m/s.
    pub fn v_yield(&self) -> f64 {
        self.v_yield
    }

    /// The residual indentation after unloading, m.
    pub fn x_residual(&self) -> f64 {
        self.x_residual
    }

    /// How the pressure is capped: a circle (spheres) or a strip (line contacts).
    pub fn cap(&self) -> Cap {
        self.cap
    }

    fn yielded(&self) -> bool {
        self.x_max > self.x_yield
    }
}

impl ForceLaw for Thornton {
    fn model(&self) -> ForceModel {
        self.model
    }

    fn params(&self) -> &ImpactParams {
        &self.params
    }

    /// Loading: k·xⁿ, then the capped pressure's force; unloading: k_u·(x − x_res)ⁿ (Thornton
    /// 1997; docs/physics.md §6.6).
    fn phase_force(&self, x: f64, _v: f64, phase: Phase) -> f64 {
        let law = self.params.law;
        match phase {
            Phase::Loading if x > self.x_yield => {
                self.f_yield * self.cap.force_ratio(x / self.x_yield, law.n)
            }
            Phase::Unloading if self.yielded() => {
                self.k_unload * signed_pow_n(x - self.x_residual, law.n)
            }
            _ => law.k * signed_pow_n(x, law.n),
        }
    }

    /// F − k·xⁿ: what the plastic branch adds to Hertz (the energy check integrates it).
    fn dissipative_force(&self, x: f64, v: f64, phase: Phase) -> f64 {
        self.phase_force(x, v, phase) - self.params.law.k * signed_pow_n(x, self.params.law.n)
    }

    fn partials(&self, x: f64, _v: f64, phase: Phase) -> (f64, f64) {
        let law = self.params.law;
        let dfdx = match phase {
            Phase::Loading if x > self.x_yield => {
                self.f_yield / self.x_yield * self.cap.slope_ratio(x / self.x_yield, law.n)
            }
            Phase::Unloading if self.yielded() => {
                law.n * self.k_unload * abs_pow_nm1(x - self.x_residual, law.n)
            }
            _ => law.n * law.k * abs_pow_nm1(x, law.n),
        };
        (dfdx, 0.0)
    }

    /// Thornton's unloading is fixed by the state at maximum compression: anchored at the turning
    /// point the integration reached, the rebound is as accurate as that point. Anchored at the
    /// energy balance's x_max instead, an error δ in the turning point would move the rebound's
    /// span x_max − x_res by δ itself, amplified by x_max/(x_max − x_res) (10⁴ at e = 0.01).
    fn unloading_at_turn(&self, x_turn: f64) -> Self {
        if self.yielded() {
            self.unloading_from(x_turn)
        } else {
            *self
        }
    }

    /// First yield: the force's curvature jumps there (spheres) or grows as 1/√(x − x_y) (strips).
    fn loading_breakpoint(&self) -> Option<f64> {
        self.yielded().then_some(self.x_yield)
    }

    /// Loading and unloading are each a force of x alone (Thornton 1997).
    fn rate_independent(&self) -> bool {
        true
    }

    /// Loading: Hertz's k·x^{n+1}/(n+1) up to x_y, then + the capped branch's work
    /// ([`Cap`]); unloading: k_u·(x − x_res)^{n+1}/(n+1), what the rebound gives back.
    fn stored_energy(&self, x: f64, phase: Phase) -> f64 {
        let (k, n) = (self.params.law.k, self.params.law.n);
        let hertz = |x: f64| k * x * x * abs_pow_nm1(x, n) / (n + 1.0);
        match phase {
            Phase::Loading if x > self.x_yield => {
                hertz(self.x_yield)
                    + self.f_yield * self.x_yield * self.cap.work_ratio(x / self.x_yield, n)
            }
            Phase::Unloading if self.yielded() => {
                let u = (x - self.x_residual).max(0.0);
                self.k_unload * u * u * abs_pow_nm1(u, n) / (n + 1.0)
            }
            _ => hertz(x),
        }
    }

    fn residual_is_permanent(&self) -> bool {
        self.yielded()
    }

    fn contact_end(&self) -> ContactEnd {
        if self.yielded() {
            ContactEnd::ForceZero
        } else {
            ContactEnd::ApproachZero
        }
    }

    fn switches_at_max_compression(&self) -> bool {
        self.yielded()
    }

    fn may_turn_tensile(&self) -> bool {
        self.yielded()
    }

    /// Unloading: F = 0 where x = x_res.
    fn tension(&self, x: f64, _v: f64) -> f64 {
        x - self.x_residual
    }

    fn damping_value(&self) -> Option<f64> {
        Some(self.v_yield)
    }

    /// Three conservative phases: closed forms on spheres, a quadrature of the capped loading's
    /// time on strips (the `exact` module).
    fn exact(&self, rtol: f64) -> Option<ExactImpact> {
        Some(self.exact_impact(rtol)).filter(ExactImpact::is_valid)
    }
}
