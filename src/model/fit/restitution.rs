//! The forward model e(v; θ) of every candidate (docs/physics.md §9.1): the restitution a law
//! realises at impact velocity v with its material constant θ, from the scene's k, n and m.
//!
//! Exact relations where they exist: the Hunt–Crossley family through
//! ln((1 + χ)/(1 − χ·e)) = χ·(1 + e) with χ = a·v (§6.4); Thornton's closed e(V) (§6.6);
//! Hertz–viscous, whose e does not depend on v (§6.2), solved once per θ. Every other law by the
//! project's solver at a tight tolerance (exact where the law has an exact solution: Kelvin–Voigt,
//! dry friction), with Adams' depth d held at the scene's value as a model constant.
#![warn(missing_docs)]

use rayon::prelude::*;

use crate::model::ModelError;
use crate::model::calibrate::{calibrate_with, hunt_crossley_chi, hunt_crossley_restitution};
use crate::model::exact::ExactImpact;
use crate::model::force::adams_impact::AdamsImpact;
use crate::model::force::table::Family;
use crate::model::force::thornton::Thornton;
use crate::model::force::{AnyLaw, ForceLaw, ForceModel, ImpactParams};
use crate::model::impact::{ImpactError, MethodChoice, SolveOptions, solve_law};

use super::FitError;
use super::candidate::Candidate;
use super::group::GroupTable;

/// The solver tolerance of the forward model: its e is within about 1e-10 of the truth, well
/// inside any measurement and below the 1e-9 floor the criteria put on residuals.
pub const SOLVE_RTOL: f64 = 1e-11;

/// The tolerance asked of an exact solution whose exit speed does not depend on it: only its
/// contact times do, which e does not need.
const EXIT_ONLY_RTOL: f64 = 1e-2;

const THORNTON: ForceModel = ForceModel::with_id("thornton");
const ADAMS: ForceModel = ForceModel::with_id("adams-impact");

/// How a candidate's e(v) is computed.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Kind {
    /// e(v) = θ₀.
    Constant,
    /// e = e_HC(a·v), §6.4.
    HuntCrossley,
    /// Thornton's closed e(v_y/v), §6.6.
    Thornton,
    /// e independent of v (§6.2): one solve at the scene's v₀ per θ.
    VelocityFree,
    /// F = k·xⁿ⁻¹·(x + A·ẋ) with A = θ/`per_unit`: e = g(ψ), ψ = A·v/x_e(v), tabulated
    /// ([`GroupTable`]).
    Group {
        /// θ per unit of A: 1 for Kuwabara–Kono's A, k for the proposed model's b.
        per_unit: f64,
    },
    /// The law's exact solution, whose exit speed is a closed form or a root (dry friction's
    /// energy identity, the damped oscillator) whatever the tolerance its times are computed to;
    /// the solver where it has none (Kelvin–Voigt past critical damping).
    Exact,
    /// One solve per v; Adams' depth d fixed at `depth`, m.
    Solver {
        /// Adams IMPACT's d, held at the scene's value.
        depth: Option<f64>,
    },
}

/// The forward model of one candidate on one scene, built once per fit: e at (θ, v). Clones
/// share its table of g(ψ) (Kuwabara–Kono, the proposed model).
#[derive(Debug, Clone, PartialEq)]
pub struct Forward {
    candidate: Candidate,
    params: ImpactParams,
    kind: Kind,
    opts: SolveOptions,
    table: GroupTable,
}

impl Forward {
    /// The forward model of `candidate` on the scene's impact `params` (k, n, m and the bodies;
    /// its v₀ is the reference for velocity-free laws and Adams' depth). Refused for a law with
    /// no damping parameter.
    pub fn new(params: &ImpactParams, candidate: Candidate) -> Result<Self, FitError> {
        params.validate().map_err(FitError::Model)?;
        let kind = match candidate {
            Candidate::ConstantE => Kind::Constant,
            Candidate::Law(model) => {
                if let Err(reason) = candidate.params() {
                    return Err(FitError::Unfittable {
                        candidate,
                        reason: reason.to_string(),
                    });
                }
                if model.spec().family == Family::HuntCrossley {
                    Kind::HuntCrossley
                } else if model == THORNTON {
                    Kind::Thornton
                } else if model.name().starts_with("hertz-viscous") {
                    Kind::VelocityFree
                } else if model == ForceModel::Proposed || model.name().starts_with("kuwabara-kono")
                {
                    Kind::Group {
                        per_unit: if model == ForceModel::Proposed {
                            params.law.k
                        } else {
                            1.0
                        },
                    }
                } else if model == ForceModel::DryFriction
                    || model.name().starts_with("kelvin-voigt")
                {
                    Kind::Exact
                } else if model == ADAMS {
                    Kind::Solver {
                        depth: Some(AdamsImpact::default_depth(params)),
                    }
                } else {
                    Kind::Solver { depth: None }
                }
            }
        };
        Ok(Forward {
            candidate,
            params: *params,
            kind,
            opts: SolveOptions {
                method: MethodChoice::Auto,
                rtol: SOLVE_RTOL,
                ..SolveOptions::default()
            },
            table: GroupTable::default(),
        })
    }

    /// The candidate.
    pub fn candidate(&self) -> Candidate {
        self.candidate
    }

    /// The scene's impact at velocity v.
    fn at(&self, v: f64) -> ImpactParams {
        ImpactParams {
            v0: v,
            ..self.params
        }
    }

    /// The law at velocity `v` with its damping parameter `d` (for the Hunt–Crossley family χ).
    fn law(&self, v: f64, d: f64) -> Result<AnyLaw, FitError> {
        let model = self.candidate.model().ok_or(FitError::Unfittable {
            candidate: self.candidate,
            reason: "constant e has no law".into(),
        })?;
        self.law_of(model, v, d).map_err(FitError::Model)
    }

    /// [`Forward::law`] for the law `model`.
    fn law_of(&self, model: ForceModel, v: f64, d: f64) -> Result<AnyLaw, ModelError> {
        let at = self.at(v);
        match self.kind {
            Kind::Solver { depth: Some(depth) } => {
                at.validate()?;
                Ok(AnyLaw::AdamsImpact(AdamsImpact::new(model, &at, d, depth)))
            }
            _ => model.law_with_damping(&at, d),
        }
    }

    /// e realised at velocity `v` (m/s) with parameters `theta` (SI).
    pub fn e(&self, theta: &[f64], v: f64) -> Result<f64, FitError> {
        let Some(&d) = theta.first() else {
            return Err(FitError::Parameters {
                candidate: self.candidate,
                expected: 1,
                got: 0,
            });
        };
        match self.kind {
            Kind::Constant => Ok(d),
            Kind::HuntCrossley => Ok(hunt_crossley_restitution(d * v)),
            Kind::Thornton => Ok(Thornton::restitution_of(&self.at(v), d)),
            Kind::VelocityFree => self.solve(self.params.v0, d),
            Kind::Group { per_unit } => {
                let psi = d / per_unit * v / self.x_e(v);
                let solve = |psi: f64| self.e_of_group(psi, per_unit).ok();
                match self.table.value(psi, &solve) {
                    Some(e) => Ok(e),
                    None => self.solve(v, d),
                }
            }
            Kind::Exact => {
                let law = self.law(v, d)?;
                match law.exact(EXIT_ONLY_RTOL).filter(ExactImpact::is_valid) {
                    Some(exact) => Ok(exact.v_out / v),
                    None => self.solve(v, d),
                }
            }
            Kind::Solver { .. } => self.solve(v, d),
        }
    }

    /// e at (θ, v) by the solver itself, never from the table or an exact solution's exit speed
    /// alone: the reference they are tested against.
    pub fn e_solved(&self, theta: &[f64], v: f64) -> Result<f64, FitError> {
        match (self.kind, theta.first()) {
            (Kind::Group { .. } | Kind::Exact, Some(&d)) => self.solve(v, d),
            _ => self.e(theta, v),
        }
    }

    /// The elastic x_max at v (eq 5), m.
    fn x_e(&self, v: f64) -> f64 {
        self.params.law.max_approach(self.params.mass, v)
    }

    /// g(ψ) solved at the scene's v₀: A = ψ·x_e(v₀)/v₀.
    fn e_of_group(&self, psi: f64, per_unit: f64) -> Result<f64, FitError> {
        let v0 = self.params.v0;
        let e = self.solve(v0, psi * self.x_e(v0) / v0 * per_unit)?;
        if e > 0.0 {
            Ok(e)
        } else {
            Err(FitError::Solve {
                candidate: self.candidate,
                v: v0,
                value: psi,
                message: "no rebound".into(),
            })
        }
    }

    /// Panels of the g(ψ) table built so far (0 for a law without one).
    pub fn table_panels(&self) -> usize {
        self.table.panels()
    }

    /// e at every velocity of `vs` with `theta`; a velocity repeated in `vs` is solved once, and
    /// a law that needs one solve per velocity solves them in parallel (rayon).
    pub fn curve(&self, theta: &[f64], vs: &[f64]) -> Result<Vec<f64>, FitError> {
        if self.kind == Kind::VelocityFree {
            let e = self.e(theta, self.params.v0)?;
            return Ok(vec![e; vs.len()]);
        }
        let mut distinct: Vec<f64> = vs.to_vec();
        distinct.sort_by(f64::total_cmp);
        distinct.dedup();
        let es: Vec<f64> = if matches!(self.kind, Kind::Solver { .. }) && distinct.len() >= 8 {
            distinct
                .par_iter()
                .map(|&v| self.e(theta, v))
                .collect::<Result<_, _>>()?
        } else {
            distinct
                .iter()
                .map(|&v| self.e(theta, v))
                .collect::<Result<_, _>>()?
        };
        Ok(vs
            .iter()
            .map(|v| {
                let i = distinct.partition_point(|d| d < v);
                es[i]
            })
            .collect())
    }

    /// One impact solve: its e_out; a bilateral law damped beyond critical never separates, a
    /// rebound of 0 (§6.4).
    fn solve(&self, v: f64, d: f64) -> Result<f64, FitError> {
        let law = self.law(v, d)?;
        match solve_law(&law, &self.opts) {
            Ok(s) => Ok(s.summary.e_out),
            Err(ImpactError::NoSeparation { .. }) => Ok(0.0),
            Err(source) => Err(FitError::Solve {
                candidate: self.candidate,
                v,
                value: d,
                message: source.to_string(),
            }),
        }
    }

    /// A starting θ: the constant that makes the law realise `e` at velocity `v` (calibration,
    /// §6.4), or the law's own default at `v` when that fails.
    pub fn start(&self, v: f64, e: f64) -> Result<Vec<f64>, FitError> {
        let Some(model) = self.candidate.model() else {
            return Ok(vec![e]);
        };
        let at = ImpactParams {
            restitution: e,
            ..self.at(v)
        };
        match self.kind {
            Kind::HuntCrossley => {
                // χ(e) inverts e_HC; an e of 1 would start a at 0, outside the log scale.
                let chi = hunt_crossley_chi(e.min(1.0 - 1e-9)).unwrap_or(1.0);
                return Ok(vec![chi / v]);
            }
            Kind::Thornton => {
                if let Some(vy) = Thornton::v_yield_for_restitution(&at, e.min(1.0 - 1e-9)) {
                    return Ok(vec![vy]);
                }
            }
            _ => {
                let calibrated = calibrate_with(model, &at, |d| self.law_of(model, v, d));
                if let Ok(c) = calibrated
                    && c.damping.value > 0.0
                {
                    return Ok(vec![c.damping.value]);
                }
            }
        }
        let default = model
            .law(&at)
            .ok()
            .and_then(|l| l.damping())
            .map(|d| d.value)
            .filter(|d| d.is_finite() && *d > 0.0)
            .unwrap_or(1.0);
        Ok(vec![default])
    }
}

/// The forward model: e of `candidate` at velocity `v` with parameters `theta`, on the scene's
/// impact `params` (public for tests, data generation and figures; a fit builds one [`Forward`]).
pub fn restitution_model(
    params: &ImpactParams,
    candidate: Candidate,
    theta: &[f64],
    v: f64,
) -> Result<f64, FitError> {
    Forward::new(params, candidate)?.e(theta, v)
}
