//! The law of each impact: built from the scene's contact at the impact's own incoming velocity
//! for the laws whose damping is defined through v₀ (the Hunt–Crossley family, α = χ/v₀, eqs
//! 19–20; dry friction's P, eqs 16–17; the proposed model's b, eq 18), once at the scene's v₀ for
//! the laws whose damping is a material constant (Kelvin–Voigt's c, Hertz–viscous γ,
//! Kuwabara–Kono's A, Thornton's v_y; docs/physics.md §6).

use crate::model::calibrate::{CalibrationError, calibrate};
use crate::model::error::ModelError;
use crate::model::force::table::Family;
use crate::model::force::{AnyLaw, ForceLaw, ForceModel, ImpactParams};

use super::super::CompliantDamping;

/// Whether `model`'s damping is defined through the impact velocity v₀, so that the law is rebuilt
/// at every impact from that impact's v_in.
pub fn defined_per_impact(model: ForceModel) -> bool {
    model.spec().family == Family::HuntCrossley
        || model == ForceModel::DryFriction
        || model == ForceModel::Proposed
}

/// Where each impact's law comes from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LawSource {
    model: ForceModel,
    /// The scene's contact at its own v₀ and e, with the system's moving mass.
    base: ImpactParams,
    /// The law of every impact, for laws whose damping is a material constant.
    fixed: Option<AnyLaw>,
    /// The damping value per-impact laws are rebuilt with; `None`: the law's own rule from e.
    value: Option<f64>,
    /// A fitted Hunt–Crossley-family constant a = χ/v₀: each impact's law takes χ = a·v_in.
    per_velocity: Option<f64>,
    /// Impact velocities below this build the law at it (a contact slower than the static
    /// settling speed is a settling, not an impact; α = χ/v₀ would grow without bound).
    v_floor: f64,
}

/// Why a stop's law could not be set up.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LawSourceError {
    #[error(transparent)]
    Model(#[from] ModelError),
    #[error(transparent)]
    Calibration(#[from] CalibrationError),
}

impl LawSource {
    /// The source of `model`'s laws for the scene contact `base` (its v₀ the reference velocity of
    /// material constants and of calibration) with `damping`.
    pub fn new(
        model: ForceModel,
        base: ImpactParams,
        damping: CompliantDamping,
        v_floor: f64,
    ) -> Result<Self, LawSourceError> {
        let has_damping = model.spec().damping.is_some();
        let hunt_crossley = model.spec().family == Family::HuntCrossley;
        let per_velocity = match damping {
            CompliantDamping::Fitted(a) if has_damping && hunt_crossley => Some(a),
            _ => None,
        };
        let value = match damping {
            _ if !has_damping => None,
            CompliantDamping::PerImpact => None,
            // χ = a·v₀ at the scene's v₀; each impact's own below.
            CompliantDamping::Fitted(a) if hunt_crossley => Some(a * base.v0),
            CompliantDamping::Constant(value) | CompliantDamping::Fitted(value) => Some(value),
            CompliantDamping::CalibratedTo(e) => {
                let target = ImpactParams {
                    restitution: e,
                    ..base
                };
                Some(calibrate(model, &target)?.damping.value)
            }
        };
        let fixed = if defined_per_impact(model) {
            // Checked once here so that every impact's build can only fail on its velocity.
            model.law(&base)?;
            None
        } else {
            Some(match value {
                Some(value) => model.law_with_damping(&base, value)?,
                None => model.law(&base)?,
            })
        };
        Ok(LawSource {
            model,
            base,
            fixed,
            value,
            per_velocity,
            v_floor,
        })
    }

    pub fn model(&self) -> ForceModel {
        self.model
    }

    /// The scene contact the laws are built from.
    pub fn base(&self) -> &ImpactParams {
        &self.base
    }

    /// The law of an impact at incoming velocity `v_in`, m/s.
    pub fn at(&self, v_in: f64) -> Result<AnyLaw, ModelError> {
        if let Some(law) = self.fixed {
            return Ok(law);
        }
        let params = ImpactParams {
            v0: v_in.max(self.v_floor),
            ..self.base
        };
        match (self.per_velocity, self.value) {
            (Some(a), _) => self.model.law_with_damping(&params, a * params.v0),
            (None, Some(value)) => self.model.law_with_damping(&params, value),
            (None, None) => self.model.law(&params),
        }
    }

    /// The damping value the laws use at `v_in` (χ, c, …), SI; `None` for a law without one.
    pub fn damping_at(&self, v_in: f64) -> Option<f64> {
        self.at(v_in).ok().and_then(|l| l.damping_value())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::scene::tests::fig5_scene;

    /// A fitted Hunt–Crossley a gives χ = a·v_in at every impact (e falls with speed, as the data
    /// said); a fitted constant of another law is held like `Constant`.
    #[test]
    fn a_fitted_constant_follows_each_impacts_speed_where_the_law_says_so() {
        let scene = fig5_scene();
        let base = scene.impact_params(&scene.quasistatic().unwrap());
        let hc = LawSource::new(
            ForceModel::HuntCrossley,
            base,
            CompliantDamping::Fitted(1.5),
            1e-6,
        )
        .unwrap();
        for v in [0.1, 0.3, 2.0] {
            assert!((hc.damping_at(v).unwrap() - 1.5 * v).abs() < 1e-12, "{v}");
        }
        let held = LawSource::new(
            ForceModel::HuntCrossley,
            base,
            CompliantDamping::Constant(0.45),
            1e-6,
        )
        .unwrap();
        assert_eq!(held.damping_at(2.0), Some(0.45), "Constant holds χ itself");
        let kv = ForceModel::with_id("kelvin-voigt");
        let fitted = LawSource::new(kv, base, CompliantDamping::Fitted(40.0), 1e-6).unwrap();
        assert_eq!(fitted.damping_at(0.1), Some(40.0));
        assert_eq!(fitted.damping_at(3.0), Some(40.0));
    }
}
