//! Thornton's elastic–perfectly-plastic sphere (J. Appl. Mech. 64, 1997), docs/physics.md §6.6:
//! Hertz up to the limiting pressure, then linear loading; Hertzian unloading with the enlarged
//! radius, down to a residual indentation.

use super::law::{ContactEnd, ForceLaw, Phase, abs_pow_nm1, signed_pow_n};
use super::{Contact, ForceModel, ImpactParams};
use crate::model::error::ModelError;
use crate::model::exact::ExactImpact;
use crate::model::numeric::roots::brent;

/// Thornton's law with its yield velocity v_y (the impact speed at which Hertz contact first
/// reaches the limiting pressure p_y). With x_y = the elastic x_max at v_y and F_y = k·x_yⁿ:
/// loading F = k·xⁿ up to x_y, then F = F_y + k_p·(x − x_y) with k_p = n·k·x_yⁿ⁻¹ (= π·p_y·R for
/// spheres); unloading F = k_u·(x − x_res)ⁿ with k_u = k·√(R_p/R),
/// R_p/R = (k/F_max)·((2F_max + F_y)/(3k·√x_y))^{3/2}, passing through (x_max, F_max).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Thornton {
    params: ImpactParams,
    model: ForceModel,
    v_yield: f64,
    x_yield: f64,
    f_yield: f64,
    k_plastic: f64,
    x_max: f64,
    k_unload: f64,
    x_residual: f64,
}

/// Thornton's e(V) above the yield velocity, q = V_y/V ∈ (0, 1]:
/// e = √(6√3/5)·√(1 − q²/6)·[q/(q + 2√(6/5 − q²/5))]^{1/4}; 1 at and below V_y.
pub fn thornton_restitution(q: f64) -> f64 {
    if q >= 1.0 {
        return 1.0;
    }
    let root = (6.0 / 5.0 - q * q / 5.0).sqrt();
    (6.0 * 3f64.sqrt() / 5.0).sqrt()
        * (1.0 - q * q / 6.0).sqrt()
        * (q / (q + 2.0 * root)).powf(0.25)
}

/// The refusal of a line contact, naming the cylinder body (docs/physics.md §6.6).
fn line_contact_refused(bodies: &str) -> ModelError {
    ModelError::OutOfDomain {
        formula: "Thornton (1997) elastic–perfectly-plastic law",
        detail: format!(
            "{bodies}: the law's limiting pressure and enlarged unloading radius are Hertz's \
             sphere geometry, and no line-contact counterpart is derived here; use a viscous law \
             (proposed, hertz-viscous) for cylinders"
        ),
    }
}

impl Thornton {
    /// The law with yield velocity `v_yield`, m/s. Spheres only (n = 3/2): the enlarged unloading
    /// radius is Hertz's sphere geometry; a line contact is refused naming its cylinder.
    pub fn new(model: ForceModel, params: &ImpactParams, v_yield: f64) -> Result<Self, ModelError> {
        if let Contact::Line { bodies, .. } = params.contact {
            return Err(line_contact_refused(bodies));
        }
        if params.law.n != 1.5 {
            return Err(ModelError::OutOfDomain {
                formula: "Thornton (1997) elastic–perfectly-plastic law",
                detail: format!(
                    "it is for spheres (n = 3/2), this contact has n = {}",
                    params.law.n
                ),
            });
        }
        let (k, n, m, v0) = (params.law.k, params.law.n, params.mass, params.v0);
        let x_yield = params.law.max_approach(m, v_yield.min(v0));
        let f_yield = k * x_yield.powf(n);
        let k_plastic = n * k * x_yield.powf(n - 1.0);
        // ½mv₀² = k·x_y^{n+1}/(n+1) + F_y·d + ½k_p·d², d = x_max − x_y.
        let rest = 0.5 * m * v0 * v0 - k * x_yield.powf(n + 1.0) / (n + 1.0);
        let d = if rest > 0.0 && k_plastic > 0.0 {
            2.0 * rest / (f_yield + (f_yield * f_yield + 2.0 * k_plastic * rest).sqrt())
        } else {
            0.0
        };
        let x_max = if v_yield >= v0 {
            params.law.max_approach(m, v0)
        } else {
            x_yield + d
        };
        let f_max = if v_yield >= v0 {
            params.law.force(x_max)
        } else {
            f_yield + k_plastic * d
        };
        let ratio = if v_yield >= v0 || x_yield == 0.0 {
            1.0
        } else {
            (k / f_max) * ((2.0 * f_max + f_yield) / (3.0 * k * x_yield.sqrt())).powf(1.5)
        };
        let k_unload = k * ratio.sqrt();
        let x_residual = x_max - (f_max / k_unload).powf(1.0 / n);
        Ok(Thornton {
            params: *params,
            model,
            v_yield,
            x_yield: if v_yield >= v0 { x_max } else { x_yield },
            f_yield,
            k_plastic,
            x_max,
            k_unload,
            x_residual: x_residual.max(0.0),
        })
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
    /// reaches p_y, i.e. x_y = R·(π·p_y/(2E*))² (p₀ = (2E*/π)·√(x/R)) and ½mV_y² = k·x_y^{5/2}/(5/2)
    /// (Thornton 1997; his V_y = 1.56·(p_y⁵/(E*⁴ρ))^{1/2} for a sphere on a plane), docs/physics.md
    /// §6.6. With p_y = 1.1·σ_y it is the paper's yield-onset speed v₀y.
    pub fn default_v_yield(params: &ImpactParams) -> Result<f64, ModelError> {
        let point = match params.contact {
            Contact::Point(point) => point,
            Contact::Line { bodies, .. } => return Err(line_contact_refused(bodies)),
            Contact::Unspecified => {
                return Err(ModelError::OutOfDomain {
                    formula: "Thornton (1997) elastic–perfectly-plastic law",
                    detail: "its yield velocity comes from the yield stress and elastic constants \
                             of the bodies, and these parameters carry none (built without a \
                             scene); give v_y explicitly"
                        .into(),
                });
            }
        };
        let x_yield = point.radius
            * (std::f64::consts::PI * point.yield_pressure / (2.0 * point.modulus)).powi(2);
        Ok(params
            .law
            .velocity_for_force(params.mass, params.law.force(x_yield)))
    }

    /// The v_y at which Thornton's e(V) at `v0` is `e` (calibration, docs/physics.md §6.4).
    pub fn v_yield_for_restitution(e: f64, v0: f64) -> f64 {
        if e >= 1.0 {
            return v0;
        }
        brent(|q| thornton_restitution(q) - e, 1e-12, 1.0).unwrap_or(1.0) * v0
    }

    /// The yield velocity v_y, m/s.
    pub fn v_yield(&self) -> f64 {
        self.v_yield
    }

    /// The residual indentation after unloading, m.
    pub fn x_residual(&self) -> f64 {
        self.x_residual
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

    /// Loading: k·xⁿ, then F_y + k_p·(x − x_y); unloading: k_u·(x − x_res)ⁿ (Thornton 1997).
    fn phase_force(&self, x: f64, _v: f64, phase: Phase) -> f64 {
        let law = self.params.law;
        match phase {
            Phase::Loading if x > self.x_yield => {
                self.f_yield + self.k_plastic * (x - self.x_yield)
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
            Phase::Loading if x > self.x_yield => self.k_plastic,
            Phase::Unloading if self.yielded() => {
                law.n * self.k_unload * abs_pow_nm1(x - self.x_residual, law.n)
            }
            _ => law.n * law.k * abs_pow_nm1(x, law.n),
        };
        (dfdx, 0.0)
    }

    /// Loading and unloading are each a force of x alone (Thornton 1997).
    fn rate_independent(&self) -> bool {
        true
    }

    /// Loading: Hertz's k·x^{n+1}/(n+1) up to x_y, then + F_y·d + ½k_p·d² (d = x − x_y);
    /// unloading: k_u·(x − x_res)^{n+1}/(n+1), what the rebound gives back.
    fn stored_energy(&self, x: f64, phase: Phase) -> f64 {
        let (k, n) = (self.params.law.k, self.params.law.n);
        let hertz = |x: f64| k * x * x * abs_pow_nm1(x, n) / (n + 1.0);
        match phase {
            Phase::Loading if x > self.x_yield => {
                let d = x - self.x_yield;
                hertz(self.x_yield) + self.f_yield * d + 0.5 * self.k_plastic * d * d
            }
            Phase::Unloading if self.yielded() => {
                let u = (x - self.x_residual).max(0.0);
                self.k_unload * u * u * abs_pow_nm1(u, n) / (n + 1.0)
            }
            _ => hertz(x),
        }
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

    /// No closed form for the times: the solver integrates it; e(V) is the test oracle.
    fn exact(&self, _rtol: f64) -> Option<ExactImpact> {
        None
    }
}
