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
        let value = match damping {
            _ if !has_damping => None,
            CompliantDamping::PerImpact => None,
            CompliantDamping::Constant(value) => Some(value),
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
        match self.value {
            Some(value) => self.model.law_with_damping(&params, value),
            None => self.model.law(&params),
        }
    }

    /// The damping value the laws use at `v_in` (χ, c, …), SI; `None` for a law without one.
    pub fn damping_at(&self, v_in: f64) -> Option<f64> {
        self.at(v_in).ok().and_then(|l| l.damping_value())
    }
}
