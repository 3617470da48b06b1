//! One value for any law of the table, dispatching statically (no boxing in the solver's hot loop),
//! and the damping-parameter API: each law's damping from the scene's e, or an explicit value.

use super::dry_friction::DryFriction;
use super::elastic::Elastic;
use super::hertz_viscous::HertzViscous;
use super::hysteresis::Hysteresis;
use super::kelvin_voigt::KelvinVoigt;
use super::law::{ContactEnd, ForceLaw, Phase};
use super::proposed::Proposed;
use super::table::{ContactRule, DampingParam, Kind};
use super::thornton::Thornton;
use super::{ForceModel, ImpactParams};
use crate::model::error::{ModelError, require};
use crate::model::exact::ExactImpact;

/// Something done with a law of a concrete type (the solver monomorphises on it).
pub trait LawVisitor {
    type Output;
    fn visit<L: ForceLaw>(self, law: &L) -> Self::Output;
}

/// The law files behind the table's [`Kind`]s: adding a law with its own equations adds one line
/// here (and one file, and one row of [`super::table::LAWS`]).
macro_rules! any_law {
    ($($variant:ident($ty:ty)),* $(,)?) => {
        /// Any law of the table.
        #[derive(Debug, Clone, Copy, PartialEq)]
        pub enum AnyLaw {
            $($variant($ty)),*
        }

        impl AnyLaw {
            /// Calls `visitor` with the concrete law.
            pub fn visit<V: LawVisitor>(&self, visitor: V) -> V::Output {
                match self {
                    $(AnyLaw::$variant(law) => visitor.visit(law)),*
                }
            }
        }

        impl ForceLaw for AnyLaw {
            fn model(&self) -> ForceModel {
                match self {
                    $(AnyLaw::$variant(l) => l.model()),*
                }
            }

            fn params(&self) -> &ImpactParams {
                match self {
                    $(AnyLaw::$variant(l) => l.params()),*
                }
            }

            fn phase_force(&self, x: f64, v: f64, phase: Phase) -> f64 {
                match self {
                    $(AnyLaw::$variant(l) => l.phase_force(x, v, phase)),*
                }
            }

            fn dissipative_force(&self, x: f64, v: f64, phase: Phase) -> f64 {
                match self {
                    $(AnyLaw::$variant(l) => l.dissipative_force(x, v, phase)),*
                }
            }

            fn partials(&self, x: f64, v: f64, phase: Phase) -> (f64, f64) {
                match self {
                    $(AnyLaw::$variant(l) => l.partials(x, v, phase)),*
                }
            }

            fn contact_end(&self) -> ContactEnd {
                match self {
                    $(AnyLaw::$variant(l) => l.contact_end()),*
                }
            }

            fn switches_at_max_compression(&self) -> bool {
                match self {
                    $(AnyLaw::$variant(l) => l.switches_at_max_compression()),*
                }
            }

            fn may_turn_tensile(&self) -> bool {
                match self {
                    $(AnyLaw::$variant(l) => l.may_turn_tensile()),*
                }
            }

            fn tension(&self, x: f64, v: f64) -> f64 {
                match self {
                    $(AnyLaw::$variant(l) => l.tension(x, v)),*
                }
            }

            fn exact(&self, rtol: f64) -> Option<ExactImpact> {
                match self {
                    $(AnyLaw::$variant(l) => l.exact(rtol)),*
                }
            }

            fn impulse_coefficient(&self) -> f64 {
                match self {
                    $(AnyLaw::$variant(l) => l.impulse_coefficient()),*
                }
            }

            fn damping_value(&self) -> Option<f64> {
                match self {
                    $(AnyLaw::$variant(l) => l.damping_value()),*
                }
            }

            fn stored_energy(&self, x: f64, phase: Phase) -> f64 {
                match self {
                    $(AnyLaw::$variant(l) => l.stored_energy(x, phase)),*
                }
            }

            fn rate_independent(&self) -> bool {
                match self {
                    $(AnyLaw::$variant(l) => l.rate_independent()),*
                }
            }
        }
    };
}

any_law! {
    Elastic(Elastic),
    DryFriction(DryFriction),
    Proposed(Proposed),
    Hysteresis(Hysteresis),
    HertzViscous(HertzViscous),
    KelvinVoigt(KelvinVoigt),
    Thornton(Thornton),
}

/// C₁ of the Kuwabara–Kono restitution series e = 1 − C₁·ε + C₂·ε² − …, ε = A·(k/m)^{2/5}·v₀^{1/5}:
/// 2·(2/5)·B(3/5, 3/2)·(5/4)^{3/5} = 1.1534489 (docs/physics.md §6.5; published as 1.15344).
pub const KUWABARA_KONO_C1: f64 = 1.153_448_858_095_288;

/// A from e at the scene's v₀ by the series' first term, A = (1 − e)/(C₁·(k/m)^{2/5}·v₀^{1/5})
/// (docs/physics.md §6.5): a material constant, so e then falls as v₀ grows.
pub fn kuwabara_kono_a(params: &ImpactParams) -> f64 {
    let (k, m, v0) = (params.law.k, params.mass, params.v0);
    (1.0 - params.restitution) / (KUWABARA_KONO_C1 * (k / m).powf(0.4) * v0.powf(0.2))
}

/// A law's damping parameter and the value in use.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Damping {
    pub param: DampingParam,
    /// SI, in `param.unit`.
    pub value: f64,
}

impl AnyLaw {
    /// The law `model` with parameters from `params`, its damping from the scene's e by the law's
    /// own rule, after validating them.
    pub fn new(model: ForceModel, params: &ImpactParams) -> Result<Self, ModelError> {
        params.validate()?;
        Self::build(model, params, None)
    }

    /// The law `model` with its damping parameter set to `value` (χ, P, b, γ or c, SI) instead of
    /// the value the scene's e gives. Refused for a law without a damping parameter, and for a
    /// value that is not finite and ≥ 0.
    pub fn with_damping(
        model: ForceModel,
        params: &ImpactParams,
        value: f64,
    ) -> Result<Self, ModelError> {
        params.validate()?;
        let Some(param) = model.spec().damping else {
            return Err(ModelError::OutOfDomain {
                formula: "damping parameter",
                detail: format!("{model} has no damping parameter"),
            });
        };
        require(param.symbol, value, "a finite number ≥ 0", |d| d >= 0.0)?;
        Self::build(model, params, Some(value))
    }

    fn build(
        model: ForceModel,
        params: &ImpactParams,
        damping: Option<f64>,
    ) -> Result<Self, ModelError> {
        let spec = model.spec();
        let tension_allowed = spec.contact == ContactRule::TensionAllowed;
        Ok(match spec.kind {
            Kind::Elastic => AnyLaw::Elastic(Elastic::new(params)),
            Kind::DryFriction => AnyLaw::DryFriction(match damping {
                Some(p) => DryFriction::with_p(params, p),
                None => DryFriction::new(params),
            }),
            Kind::Proposed => AnyLaw::Proposed(match damping {
                Some(b) => Proposed::with_b(params, b),
                None => Proposed::new(params),
            }),
            Kind::HuntCrossley(chi) => AnyLaw::Hysteresis(Hysteresis::with_chi(
                model,
                params,
                damping.unwrap_or_else(|| chi(params.restitution)),
            )),
            Kind::HertzViscous => AnyLaw::HertzViscous(HertzViscous::new(
                model,
                params,
                damping.unwrap_or_else(|| HertzViscous::default_gamma(params)),
                tension_allowed,
            )),
            Kind::KuwabaraKono => AnyLaw::Proposed(Proposed::kuwabara_kono(
                model,
                params,
                damping.unwrap_or_else(|| kuwabara_kono_a(params)),
            )),
            Kind::Thornton => AnyLaw::Thornton(Thornton::new(
                model,
                params,
                match damping {
                    Some(v_yield) => v_yield,
                    None => Thornton::default_v_yield(params)?,
                },
            )?),
            Kind::KelvinVoigt => AnyLaw::KelvinVoigt(KelvinVoigt::new(
                model,
                params,
                damping.unwrap_or_else(|| KelvinVoigt::default_c(params)),
                tension_allowed,
            )),
        })
    }

    /// The damping parameter in use, `None` for a law without one.
    pub fn damping(&self) -> Option<Damping> {
        Some(Damping {
            param: self.model().spec().damping?,
            value: self.damping_value()?,
        })
    }
}
