//! The law a scene carries from a fit to measured restitution (its `[fit]` table, docs/fitting.md):
//! the law and its material constant, from which every solve builds the law at the scene's v₀, and
//! the restitution e that law realises there, which the scene's `[impact] restitution` then holds
//! so that every other law is set (or calibrated) to the same e.
#![warn(missing_docs)]

use super::calibrate::{CalibrationError, scene_or_calibrated};
use super::error::{ModelError, require_positive};
use super::fit::{Candidate, FitError, restitution_model};
use super::force::table::Family;
use super::force::{AnyLaw, ForceModel, ImpactParams};
use super::impact::ImpactError;

/// What a scene's `[fit]` may name: Newton's constant e or a law with a material constant
/// ([`Candidate`]); its `law = "…"` is the candidate's id.
pub type FittedKind = Candidate;

/// The key, symbol and SI unit of `candidate`'s material constant (`e`; `a` = χ/v₀ in s/m for the
/// Hunt–Crossley family; the law's damping parameter otherwise); `None` for a law without one.
pub fn constant_of(candidate: Candidate) -> Option<(&'static str, &'static str, &'static str)> {
    let specs = candidate.params().ok()?;
    let spec = specs.first()?;
    Some((spec.key, spec.symbol, spec.unit))
}

/// The candidate with id `id` when it has a material constant a scene can carry.
pub fn fitted_kind(id: &str) -> Option<Candidate> {
    Candidate::from_id(id).filter(|c| constant_of(*c).is_some())
}

/// The ids [`fitted_kind`] accepts, for messages.
pub fn fitted_ids() -> Vec<&'static str> {
    std::iter::once(Candidate::ConstantE)
        .chain(ForceModel::ALL.into_iter().map(Candidate::Law))
        .filter(|c| constant_of(*c).is_some())
        .map(Candidate::id)
        .collect()
}

/// A fitted law as a scene carries it.
#[derive(Debug, Clone, PartialEq)]
pub struct FittedLaw {
    /// The law (or constant e).
    pub kind: Candidate,
    /// Its material constant in the SI unit of [`FittedLaw::constant`].
    pub value: f64,
    /// The data file it was fitted to, as given (for the reader; never read back).
    pub source: Option<String>,
    /// How it was chosen, in words (criterion, weight, date), for the reader.
    pub note: Option<String>,
}

impl FittedLaw {
    /// A fitted law without provenance.
    pub fn new(kind: Candidate, value: f64) -> Self {
        FittedLaw {
            kind,
            value,
            source: None,
            note: None,
        }
    }

    /// The key, symbol and SI unit of its constant (`a`, `a`, `s/m` for Hunt–Crossley).
    pub fn constant(&self) -> (&'static str, &'static str, &'static str) {
        constant_of(self.kind).unwrap_or(("", "", ""))
    }

    /// The dotted field of the constant, e.g. `fit.a`.
    pub fn field(&self) -> String {
        format!("fit.{}", self.constant().0)
    }

    /// Checks the constant: e in (0, 1] for constant e, a finite number ≥ 0 otherwise.
    pub fn validate(&self) -> Result<(), ModelError> {
        let field = self.field();
        let ok = match self.kind {
            Candidate::ConstantE => self.value > 0.0 && self.value <= 1.0,
            Candidate::Law(_) => self.value.is_finite() && self.value >= 0.0,
        };
        if ok {
            return Ok(());
        }
        Err(ModelError::InvalidParameter {
            field,
            requirement: match self.kind {
                Candidate::ConstantE => "in (0, 1]",
                Candidate::Law(_) => "a finite number ≥ 0",
            },
            value: self.value,
        })
    }

    /// The law's damping value at impact velocity `v0` (χ = a·v₀ for the Hunt–Crossley family,
    /// the constant itself otherwise); `None` for constant e.
    pub fn damping_at(&self, v0: f64) -> Option<f64> {
        match self.kind {
            Candidate::ConstantE => None,
            Candidate::Law(model) if model.spec().family == Family::HuntCrossley => {
                Some(self.value * v0)
            }
            Candidate::Law(_) => Some(self.value),
        }
    }

    /// The fitted law for the impact `params` (at their v₀): `None` for constant e, which is no
    /// force law (every law is then set from e as usual).
    pub fn law(&self, params: &ImpactParams) -> Result<Option<(ForceModel, AnyLaw)>, ModelError> {
        self.validate()?;
        match (self.kind, self.damping_at(params.v0)) {
            (Candidate::Law(model), Some(d)) => {
                Ok(Some((model, model.law_with_damping(params, d)?)))
            }
            _ => Ok(None),
        }
    }

    /// The restitution the fitted law realises at `params.v0`: the fit's own forward model
    /// ([`restitution_model`]: exact relations where they exist, docs/physics.md §9.1).
    pub fn restitution_at(&self, params: &ImpactParams) -> Result<f64, FitError> {
        self.validate()?;
        require_positive("impact.v0", params.v0)?;
        restitution_model(params, self.kind, &[self.value], params.v0)
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
        Some(fit) if fit.kind == Candidate::Law(model) => Ok(fit.law(params)?.map(|(_, l)| l)),
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
    use crate::model::impact::{SolveOptions, solve_law};
    use crate::model::scene::tests::fig5_scene;

    fn fig5_at(v0: f64) -> ImpactParams {
        let mut scene = fig5_scene();
        scene.impact.v0 = v0;
        scene.impact_params(&scene.quasistatic().unwrap())
    }

    #[test]
    fn a_fitted_hunt_crossley_constant_gives_its_exact_e_and_the_solver_agrees() {
        let fit = FittedLaw::new(Candidate::Law(ForceModel::HuntCrossley), 2.0);
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
    fn every_fittable_law_solved_with_its_constant_realises_the_fits_e() {
        // The law a solve builds from the constant and the fit's forward model agree at v₀.
        let p = fig5_at(0.3);
        for model in ForceModel::ALL {
            let candidate = Candidate::Law(model);
            let Some((_, _, _)) = constant_of(candidate) else {
                continue;
            };
            let Some(d) = model.law(&p).unwrap().damping() else {
                continue;
            };
            let value = if model.spec().family == Family::HuntCrossley {
                d.value / p.v0
            } else {
                d.value
            };
            let fit = FittedLaw::new(candidate, value);
            let e = fit.restitution_at(&p).unwrap();
            let law = fit.law(&p).unwrap().unwrap().1;
            let solved = solve_law(&law, &SolveOptions::default())
                .unwrap()
                .summary
                .e_out;
            assert!(
                (solved - e).abs() < 1e-6,
                "{model}: solved {solved}, fit {e}"
            );
        }
    }

    #[test]
    fn ids_and_constants_are_those_of_the_table_and_bad_values_name_the_field() {
        assert_eq!(fitted_kind("constant-e"), Some(Candidate::ConstantE));
        assert_eq!(fitted_kind("quasistatic"), None, "no damping");
        assert_eq!(fitted_kind("no-such"), None);
        let hc = fitted_kind("lankarani-nikravesh").unwrap();
        assert_eq!(constant_of(hc), Some(("a", "a", "s/m")));
        let thornton = fitted_kind("thornton").unwrap();
        assert_eq!(constant_of(thornton).unwrap().0, "v_yield");
        assert!(fitted_ids().contains(&"kelvin-voigt") && !fitted_ids().contains(&"quasistatic"));
        let bad = FittedLaw::new(Candidate::ConstantE, 1.5).validate();
        assert!(
            bad.unwrap_err()
                .to_string()
                .starts_with("fit.e must be in (0, 1]")
        );
        let bad = FittedLaw::new(hc, f64::NAN).validate().unwrap_err();
        assert!(bad.to_string().contains("fit.a"), "{bad}");
    }
}
