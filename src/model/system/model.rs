//! A system with everything its solvers need: the spec, the moving mass, e, and the contact pair.
#![warn(missing_docs)]

use crate::model::error::{ModelError, require, require_positive};
use crate::model::quasistatic::PairEstimate;
use crate::model::scene::Scene;

use super::spec::SystemSpec;

/// The system a solver runs: [`SystemSpec`] plus what the scene's bodies give.
#[derive(Debug, Clone, PartialEq)]
pub struct SystemModel {
    /// The `[system]` table.
    pub spec: SystemSpec,
    /// The moving body's mass m (body 1), kg.
    pub mass: f64,
    /// The restitution e of the scene's `[impact]` table, in [0, 1] (0 allowed here: a plastic stop).
    pub restitution: f64,
    /// The scene the model was built from (its bodies give the compliant stop and the Hertz
    /// estimate); `None` for a model built from numbers alone.
    pub scene: Option<Scene>,
    /// The Hertz estimate of body 1 on body 2 (eqs 1–14), evaluated once.
    pub pair: Option<PairEstimate>,
}

impl SystemModel {
    /// A model of numbers alone (no bodies: rigid stop only, no force estimate).
    pub fn new(spec: SystemSpec, mass: f64, restitution: f64) -> Result<SystemModel, ModelError> {
        let model = SystemModel {
            spec,
            mass,
            restitution,
            scene: None,
            pair: None,
        };
        model.validate()?;
        Ok(model)
    }

    /// The model of `scene` (body 1 moves, body 2 is the stop; e from `[impact]`) in `spec`.
    pub fn from_scene(scene: &Scene, spec: &SystemSpec) -> Result<SystemModel, ModelError> {
        let pair = scene.pair()?;
        let model = SystemModel {
            spec: *spec,
            mass: scene.body1.mass(),
            restitution: scene.impact.restitution,
            scene: Some(scene.clone()),
            pair: Some(PairEstimate::new(pair)),
        };
        model.validate()?;
        Ok(model)
    }

    /// Checks the spec, the mass and e; errors name the key.
    pub fn validate(&self) -> Result<(), ModelError> {
        require_positive("body1.mass", self.mass)?;
        require("impact.restitution", self.restitution, "in [0, 1]", |e| {
            (0.0..=1.0).contains(&e)
        })?;
        self.spec.validate_with_mass(self.mass)
    }

    /// The Hertz estimate of the peak force of an impact at relative speed `v` (eqs 5–6), N.
    pub fn peak_force_estimate(&self, v: f64) -> Option<f64> {
        if v <= 0.0 {
            return Some(0.0);
        }
        self.pair.as_ref()?.at(v).ok().map(|q| q.f_max)
    }
}
