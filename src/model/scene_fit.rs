//! The law a scene carries from a fit to measured restitution (its `[fit]` table, docs/fitting.md):
//! the law and its material constant, from which every solve builds the law at the scene's v₀, and
//! the restitution e that law realises there, which the scene's `[impact] restitution` then holds
//! so that every other law is set (or calibrated) to the same e.
#![warn(missing_docs)]

use super::calibrate::{CalibrationError, hunt_crossley_restitution, scene_or_calibrated};
use super::error::{ModelError, require_positive};
use super::force::table::Family;
use super::force::{AnyLaw, ForceModel, ImpactParams};
use super::impact::{ImpactError, MethodChoice, SolveOptions, solve_law};

/// The relative tolerance of the solve that gives a solved law's e at v₀: two digits below the
/// 1e-6 to which a fit recovers its constant.
const SOLVE_RTOL: f64 = 1e-10;

/// What was fitted: Newton's constant e, or a law of the table with its material constant.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FittedKind {
    /// A constant coefficient of restitution, whatever v₀ (`law = "constant-e"`).
    ConstantE,
    /// A law of the table.
    Law(ForceModel),
}

impl FittedKind {
    /// The id of `law = "…"` in a scene file: `constant-e` or the law's id.
    pub fn id(self) -> &'static str {
        match self {
            FittedKind::ConstantE => CONSTANT_E,
            FittedKind::Law(model) => model.name(),
        }
    }

    /// The kind with id `id`, or `None` for an unknown id or a law without a damping parameter
    /// (elastic Hertz rebounds at e = 1 whatever is fitted).
    pub fn from_id(id: &str) -> Option<FittedKind> {
        if id == CONSTANT_E {
            return Some(FittedKind::ConstantE);
        }
        let model: ForceModel = id.parse().ok()?;
        model.spec().damping.map(|_| FittedKind::Law(model))
    }

    /// The ids [`FittedKind::from_id`] accepts, for messages.
    pub fn ids() -> Vec<&'static str> {
        std::iter::once(CONSTANT_E)
            .chain(
                ForceModel::ALL
                    .into_iter()
                    .filter(|m| m.spec().damping.is_some())
                    .map(ForceModel::name),
            )
            .collect()
    }

    /// The key of the material constant in `[fit]`, its symbol and SI unit: `e` for constant e;
    /// `a` = χ/v₀ in s/m for the Hunt–Crossley family (χ = a·v₀, docs/physics.md §6.4); the
    /// law's own damping parameter for the others (c, γ, A, v_y, …), which is a material constant.
    pub fn constant(self) -> (&'static str, &'static str, &'static str) {
        match self {
            FittedKind::ConstantE => ("e", "e", "1"),
            FittedKind::Law(model) if model.spec().family == Family::HuntCrossley => {
                ("a", "a", "s/m")
            }
            FittedKind::Law(model) => match model.spec().damping {
                Some(d) => (d.key, d.symbol, d.unit),
                None => ("", "", ""),
            },
        }
    }
}

/// The id of Newton's constant e in `[fit] law`.
pub const CONSTANT_E: &str = "constant-e";

/// A fitted law as a scene carries it.
#[derive(Debug, Clone, PartialEq)]
pub struct FittedLaw {
    /// The law.
    pub kind: FittedKind,
    /// Its material constant in the SI unit of [`FittedKind::constant`].
    pub value: f64,
    /// The data file it was fitted to, as given (for the reader; never read back).
    pub source: Option<String>,
    /// How it was chosen, in words (criterion, weight, date), for the reader.
    pub note: Option<String>,
}

impl FittedLaw {
    /// A fitted law without provenance.
    pub fn new(kind: FittedKind, value: f64) -> Self {
        FittedLaw {
            kind,
            value,
            source: None,
            note: None,
        }
    }

    /// The dotted field of the constant, e.g. `fit.a`.
    pub fn field(&self) -> String {
        format!("fit.{}", self.kind.constant().0)
    }

    /// Checks the constant: e in (0, 1] for constant e, a finite number ≥ 0 otherwise.
    pub fn validate(&self) -> Result<(), ModelError> {
        let field = self.field();
        let ok = match self.kind {
            FittedKind::ConstantE => self.value > 0.0 && self.value <= 1.0,
            FittedKind::Law(_) => self.value.is_finite() && self.value >= 0.0,
        };
        if ok {
            return Ok(());
        }
        Err(ModelError::InvalidParameter {
            field,
            requirement: match self.kind {
                FittedKind::ConstantE => "in (0, 1]",
                FittedKind::Law(_) => "a finite number ≥ 0",
            },
            value: self.value,
        })
    }

    /// The law's damping value at impact velocity `v0` (χ = a·v₀ for the Hunt–Crossley family,
    /// the constant itself otherwise); `None` for constant e.
    pub fn damping_at(&self, v0: f64) -> Option<f64> {
        match self.kind {
            FittedKind::ConstantE => None,
            FittedKind::Law(model) if model.spec().family == Family::HuntCrossley => {
                Some(self.value * v0)
            }
            FittedKind::Law(_) => Some(self.value),
        }
    }

    /// The fitted law for the impact `params` (at their v₀): `None` for constant e, which is no
    /// force law (every law is then set from e as usual).
    pub fn law(&self, params: &ImpactParams) -> Result<Option<(ForceModel, AnyLaw)>, ModelError> {
        self.validate()?;
        match (self.kind, self.damping_at(params.v0)) {
            (FittedKind::Law(model), Some(d)) => {
                Ok(Some((model, model.law_with_damping(params, d)?)))
            }
            _ => Ok(None),
        }
    }

    /// The restitution the fitted law realises at `params.v0`: the constant e; the exact relation
    /// ln((1 + χ)/(1 − χ·e)) = χ·(1 + e) with χ = a·v₀ for the Hunt–Crossley family
    /// (docs/physics.md §6.4); an impact solve at rtol 1e-10 for the others.
    pub fn restitution_at(&self, params: &ImpactParams) -> Result<f64, ImpactError> {
        self.validate()?;
        require_positive("impact.v0", params.v0)?;
        match self.kind {
            FittedKind::ConstantE => Ok(self.value),
            FittedKind::Law(model) if model.spec().family == Family::HuntCrossley => {
                Ok(hunt_crossley_restitution(self.value * params.v0))
            }
            FittedKind::Law(_) => {
                let Some((_, law)) = self.law(params)? else {
                    return Ok(params.restitution);
                };
                let options = SolveOptions {
                    method: MethodChoice::Auto,
                    rtol: SOLVE_RTOL,
                    ..SolveOptions::default()
                };
                Ok(solve_law(&law, &options)?.summary.e_out)
            }
        }
    }
}

/// The law to solve for `model` on a scene that carries `fit`: the fitted law built from its
/// constant at `params.v0` when `model` is the fitted one, else `None` (the caller sets it from e,
/// or calibrates it, as for any scene).
pub fn fitted_law_for(
    fit: Option<&FittedLaw>,
    model: ForceModel,
    params: &ImpactParams,
) -> Result<Option<AnyLaw>, ModelError> {
    match fit {
        Some(fit) if fit.kind == FittedKind::Law(model) => Ok(fit.law(params)?.map(|(_, l)| l)),
        _ => Ok(None),
    }
}

/// The law to solve for `model`: the scene's `[fit]` law with its fitted constant (never
/// calibrated: the constant is what the data says), else the scene's or the calibrated one;
/// with whether it is the fitted law.
#[allow(clippy::type_complexity)]
pub fn scene_law(
    model: ForceModel,
    params: &ImpactParams,
    calibrate: bool,
    fit: Option<&FittedLaw>,
) -> Result<(AnyLaw, Result<bool, CalibrationError>, bool), ImpactError> {
    if let Some(law) = fitted_law_for(fit, model, params)? {
        return Ok((law, Ok(false), true));
    }
    let (law, calibration) = scene_or_calibrated(model, params, calibrate)?;
    Ok((law, calibration, false))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::impact::solve_impact;
    use crate::model::scene::tests::fig5_scene;

    fn fig5_at(v0: f64) -> ImpactParams {
        let mut scene = fig5_scene();
        scene.impact.v0 = v0;
        scene.impact_params(&scene.quasistatic().unwrap())
    }

    #[test]
    fn a_fitted_hunt_crossley_constant_gives_its_exact_e_and_the_solver_agrees() {
        let fit = FittedLaw::new(FittedKind::Law(ForceModel::HuntCrossley), 2.0);
        let mut last = 1.0;
        for v0 in [0.1, 0.3, 1.0] {
            let p = fig5_at(v0);
            let e = fit.restitution_at(&p).unwrap();
            let law = fitted_law_for(Some(&fit), ForceModel::HuntCrossley, &p)
                .unwrap()
                .unwrap();
            let solved = solve_law(&law, &SolveOptions::default()).unwrap();
            assert!((solved.summary.e_out - e).abs() < 1e-6, "{v0}: {e}");
            assert!(e < last, "e falls with v0");
            last = e;
        }
        // Another law is not the fitted one.
        assert!(
            fitted_law_for(Some(&fit), ForceModel::Proposed, &fig5_at(0.3))
                .unwrap()
                .is_none()
        );
    }

    #[test]
    fn a_solved_law_realises_its_constant_and_calibrating_to_that_e_gives_it_back() {
        let kv = ForceModel::with_id("kelvin-voigt");
        let p = fig5_at(0.3);
        let c = kv.law(&p).unwrap().damping().unwrap().value;
        let fit = FittedLaw::new(FittedKind::Law(kv), c);
        let e = fit.restitution_at(&p).unwrap();
        let own = solve_impact(kv, &p, &SolveOptions::default()).unwrap();
        assert!((own.summary.e_out - e).abs() < 1e-6);
    }

    #[test]
    fn ids_and_constants_are_those_of_the_table_and_bad_values_name_the_field() {
        assert_eq!(
            FittedKind::from_id("constant-e"),
            Some(FittedKind::ConstantE)
        );
        assert_eq!(FittedKind::from_id("quasistatic"), None, "no damping");
        assert_eq!(FittedKind::from_id("no-such"), None);
        let hc = FittedKind::from_id("lankarani-nikravesh").unwrap();
        assert_eq!(hc.constant(), ("a", "a", "s/m"));
        let thornton = FittedKind::from_id("thornton").unwrap();
        assert_eq!(thornton.constant().0, "v_yield");
        let bad = FittedLaw::new(FittedKind::ConstantE, 1.5).validate();
        assert!(
            bad.unwrap_err()
                .to_string()
                .starts_with("fit.e must be in (0, 1]")
        );
        let bad = FittedLaw::new(hc, f64::NAN).validate().unwrap_err();
        assert!(bad.to_string().contains("fit.a"), "{bad}");
    }
}
