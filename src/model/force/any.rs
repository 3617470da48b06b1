//! One value for any law of the table, dispatching statically (no boxing in the solver's hot loop),
//! and the damping-parameter API: each law's damping from the scene's e, or an explicit value.
//!
//! `law_table!` is invoked once, in `table.rs`: that invocation is at the same time the table
//! [`super::LAWS`] and the generator of [`AnyLaw`], one variant per row.

use super::law::ForceLaw;
pub use super::table::AnyLaw;
use super::table::DampingParam;
use super::{ForceModel, ImpactParams};
use crate::model::error::{Domain, ModelError, require};
use crate::model::numeric::beta::beta;

/// Something done with a law of a concrete type (the solver monomorphises on it).
pub trait LawVisitor {
    type Output;
    fn visit<L: ForceLaw>(self, law: &L) -> Self::Output;
}

/// The law table: rows `Variant = file::Type::builder, LawSpec { … };`, `file` a module of
/// `force`. Each row becomes an entry of `LAWS` and a variant `AnyLaw::Variant(file::Type)`. The
/// builder, `fn(ForceModel, &ImpactParams, Option<f64>) -> Result<Type, ModelError>`, makes the law
/// from a scene, with its damping given or, for `None`, from the law's own rule.
macro_rules! law_table {
    ($($(#[$doc:meta])* $variant:ident = $file:ident::$ty:ident::$build:ident, $spec:expr;)*) => {
        /// Every law, in table order: what `--model`, scene files, sweeps and the explorer list.
        pub const LAWS: &[$crate::model::force::table::LawSpec] = &[$($spec),*];

        /// Any law of the table: one variant per row, holding the law type of its file.
        #[derive(Debug, Clone, Copy, PartialEq)]
        pub enum AnyLaw {
            $($(#[$doc])* $variant($crate::model::force::$file::$ty)),*
        }

        impl AnyLaw {
            /// The law of `model`'s row from `params`, by the row's builder.
            pub(super) fn build_row(
                model: $crate::model::force::ForceModel,
                params: &$crate::model::force::ImpactParams,
                damping: Option<f64>,
            ) -> Result<Self, $crate::model::error::ModelError> {
                /// Row indices, in declaration order.
                enum Row {
                    $($variant),*
                }
                $(
                    if model.index() == Row::$variant as usize {
                        return Ok(AnyLaw::$variant(
                            $crate::model::force::$file::$ty::$build(model, params, damping)?,
                        ));
                    }
                )*
                Err($crate::model::error::ModelError::OutOfDomain {
                    formula: "law table",
                    detail: $crate::model::error::Domain::NoLawRow(model.index()),
                })
            }

            /// Calls `visitor` with the concrete law.
            pub fn visit<V: $crate::model::force::any::LawVisitor>(&self, visitor: V) -> V::Output {
                match self {
                    $(AnyLaw::$variant(law) => visitor.visit(law)),*
                }
            }
        }

        impl $crate::model::force::law::ForceLaw for AnyLaw {
            fn model(&self) -> $crate::model::force::ForceModel {
                match self {
                    $(AnyLaw::$variant(l) => l.model()),*
                }
            }

            fn params(&self) -> &$crate::model::force::ImpactParams {
                match self {
                    $(AnyLaw::$variant(l) => l.params()),*
                }
            }

            fn phase_force(&self, x: f64, v: f64, phase: $crate::model::force::law::Phase) -> f64 {
                match self {
                    $(AnyLaw::$variant(l) => l.phase_force(x, v, phase)),*
                }
            }

            fn dissipative_force(&self, x: f64, v: f64, phase: $crate::model::force::law::Phase) -> f64 {
                match self {
                    $(AnyLaw::$variant(l) => l.dissipative_force(x, v, phase)),*
                }
            }

            fn partials(&self, x: f64, v: f64, phase: $crate::model::force::law::Phase) -> (f64, f64) {
                match self {
                    $(AnyLaw::$variant(l) => l.partials(x, v, phase)),*
                }
            }

            fn contact_end(&self) -> $crate::model::force::law::ContactEnd {
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

            fn exact(&self, rtol: f64) -> Option<$crate::model::exact::ExactImpact> {
                match self {
                    $(AnyLaw::$variant(l) => l.exact(rtol)),*
                }
            }

            fn impulse_coefficient(&self) -> f64 {
                match self {
                    $(AnyLaw::$variant(l) => l.impulse_coefficient()),*
                }
            }

            fn impulse_power(&self) -> f64 {
                match self {
                    $(AnyLaw::$variant(l) => l.impulse_power()),*
                }
            }

            fn damping_value(&self) -> Option<f64> {
                match self {
                    $(AnyLaw::$variant(l) => l.damping_value()),*
                }
            }

            fn stored_energy(&self, x: f64, phase: $crate::model::force::law::Phase) -> f64 {
                match self {
                    $(AnyLaw::$variant(l) => l.stored_energy(x, phase)),*
                }
            }

            fn rate_independent(&self) -> bool {
                match self {
                    $(AnyLaw::$variant(l) => l.rate_independent()),*
                }
            }

            fn residual_is_permanent(&self) -> bool {
                match self {
                    $(AnyLaw::$variant(l) => l.residual_is_permanent()),*
                }
            }

            fn unloading_at_turn(&self, x_turn: f64) -> Self {
                match self {
                    $(AnyLaw::$variant(l) => AnyLaw::$variant(l.unloading_at_turn(x_turn))),*
                }
            }

            fn loading_breakpoint(&self) -> Option<f64> {
                match self {
                    $(AnyLaw::$variant(l) => l.loading_breakpoint()),*
                }
            }
        }
    };
}

pub(super) use law_table;

/// C₁ of the Kuwabara–Kono restitution series e = 1 − C₁·ε + C₂·ε² − …, ε = A·(k/m)^{2/5}·v₀^{1/5}:
/// 2·(2/5)·B(3/5, 3/2)·(5/4)^{3/5} = 1.1534489 (docs/physics.md §6.5; published as 1.15344).
pub const KUWABARA_KONO_C1: f64 = 1.153_448_858_095_288;

/// A from e at the scene's v₀ by the series' first term, A = (1 − e)·x_e/(v₀·B(n/(n+1), 3/2))
/// with x_e the elastic x_max (docs/physics.md §6.5): A·v₀/x_e is the dimensionless damping for
/// any n, and for spheres this is A = (1 − e)/(C₁·(k/m)^{2/5}·v₀^{1/5}). A material constant, so
/// e then falls as v₀ grows.
pub fn kuwabara_kono_a(params: &ImpactParams) -> f64 {
    let (m, v0, n) = (params.mass, params.v0, params.law.n);
    let x_e = params.law.max_approach(m, v0);
    (1.0 - params.restitution) * x_e / (v0 * beta(n / (n + 1.0), 1.5))
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
        Self::build_row(model, params, None)
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
                detail: Domain::NoDampingParameter(model.name()),
            });
        };
        require(param.symbol, value, "a finite number ≥ 0", |d| d >= 0.0)?;
        Self::build_row(model, params, Some(value))
    }

    /// The damping parameter in use, `None` for a law without one.
    pub fn damping(&self) -> Option<Damping> {
        Some(Damping {
            param: self.model().spec().damping?,
            value: self.damping_value()?,
        })
    }
}
