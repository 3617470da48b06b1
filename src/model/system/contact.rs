//! How the stop acts: instantaneously (rigid, restitution e) or through a contact law (compliant).
#![warn(missing_docs)]

use crate::model::ForceModel;

/// The kind of contact between the body and its stop(s). Every entry point dispatches on it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Contact {
    /// Instantaneous impact: the relative velocity jumps from −v to e·v (Newton's restitution).
    Rigid {
        /// e in [0, 1].
        restitution: f64,
    },
    /// A contact force F(x, ẋ) of the law table through the impact (the compliant solver).
    Compliant {
        /// The law.
        model: ForceModel,
        /// How the law's damping is set at each impact.
        damping: CompliantDamping,
    },
}

/// How a compliant law's damping parameter is set, impact by impact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CompliantDamping {
    /// From that impact's own incoming velocity, for the laws defined that way (Hunt–Crossley's
    /// α = 3(1 − e)/(2v₀), eq 19).
    PerImpact,
    /// A constant the law has as a material constant (its own unit).
    Constant(f64),
    /// Calibrated once so that the law realises this restitution.
    CalibratedTo(f64),
    /// A material constant fitted to measured restitution (a scene's `[fit]`, docs/fitting.md):
    /// for the Hunt–Crossley family a = χ/v₀ in s/m, so that χ = a·v_in at each impact; for the
    /// other laws their damping constant itself, as [`CompliantDamping::Constant`].
    Fitted(f64),
}

impl Contact {
    /// A rigid stop with the model's restitution.
    pub fn rigid(restitution: f64) -> Contact {
        Contact::Rigid { restitution }
    }

    /// Short name: `rigid` or `compliant`.
    pub fn name(&self) -> &'static str {
        match self {
            Contact::Rigid { .. } => "rigid",
            Contact::Compliant { .. } => "compliant",
        }
    }
}
