//! One value for any of the five laws, dispatching statically (no boxing in the solver's hot loop).

use super::dry_friction::DryFriction;
use super::elastic::Elastic;
use super::hysteresis::Hysteresis;
use super::law::{ContactEnd, ForceLaw, Phase};
use super::proposed::Proposed;
use super::{ForceModel, ImpactParams};
use crate::model::error::ModelError;
use crate::model::exact::ExactImpact;

/// Any of the paper's five force laws.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum AnyLaw {
    Elastic(Elastic),
    DryFriction(DryFriction),
    Proposed(Proposed),
    Hysteresis(Hysteresis),
}

impl AnyLaw {
    /// The law `model` with parameters from `params`, after validating them.
    pub fn new(model: ForceModel, params: &ImpactParams) -> Result<Self, ModelError> {
        params.validate()?;
        Ok(match model {
            ForceModel::Quasistatic => AnyLaw::Elastic(Elastic::new(params)),
            ForceModel::DryFriction => AnyLaw::DryFriction(DryFriction::new(params)),
            ForceModel::Proposed => AnyLaw::Proposed(Proposed::new(params)),
            ForceModel::HuntCrossley => AnyLaw::Hysteresis(Hysteresis::hunt_crossley(params)),
            ForceModel::LankaraniNikravesh => {
                AnyLaw::Hysteresis(Hysteresis::lankarani_nikravesh(params))
            }
        })
    }
}

macro_rules! dispatch {
    ($self:ident, $law:ident => $body:expr) => {
        match $self {
            AnyLaw::Elastic($law) => $body,
            AnyLaw::DryFriction($law) => $body,
            AnyLaw::Proposed($law) => $body,
            AnyLaw::Hysteresis($law) => $body,
        }
    };
}

impl ForceLaw for AnyLaw {
    fn model(&self) -> ForceModel {
        dispatch!(self, l => l.model())
    }

    fn params(&self) -> &ImpactParams {
        dispatch!(self, l => l.params())
    }

    fn phase_force(&self, x: f64, v: f64, phase: Phase) -> f64 {
        dispatch!(self, l => l.phase_force(x, v, phase))
    }

    fn dissipative_force(&self, x: f64, v: f64, phase: Phase) -> f64 {
        dispatch!(self, l => l.dissipative_force(x, v, phase))
    }

    fn partials(&self, x: f64, v: f64, phase: Phase) -> (f64, f64) {
        dispatch!(self, l => l.partials(x, v, phase))
    }

    fn contact_end(&self) -> ContactEnd {
        dispatch!(self, l => l.contact_end())
    }

    fn switches_at_max_compression(&self) -> bool {
        dispatch!(self, l => l.switches_at_max_compression())
    }

    fn may_turn_tensile(&self) -> bool {
        dispatch!(self, l => l.may_turn_tensile())
    }

    fn tension(&self, x: f64, v: f64) -> f64 {
        dispatch!(self, l => l.tension(x, v))
    }

    fn exact(&self, rtol: f64) -> Option<ExactImpact> {
        dispatch!(self, l => l.exact(rtol))
    }

    fn impulse_coefficient(&self) -> f64 {
        dispatch!(self, l => l.impulse_coefficient())
    }
}
