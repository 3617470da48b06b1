//! Ways translating a scene for an engine fails. Each names the engine or the quantity.

use thiserror::Error;

use crate::model::error::ModelError;
use crate::model::impact::ImpactError;

/// Why a scene could not be translated for an engine.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum EngineError {
    /// The scene is invalid; the error names the field.
    #[error(transparent)]
    Model(#[from] ModelError),
    /// Solving the engine's law (a law of the table) failed.
    #[error("solving the engine's contact law failed: {0}")]
    Solve(#[from] ImpactError),
    /// No value of the engine's parameter realises the requested restitution.
    #[error("{engine}: restitution {requested} cannot be reached: {reason}")]
    Unreachable {
        /// The engine's id.
        engine: &'static str,
        /// The requested restitution.
        requested: f64,
        /// What stops it.
        reason: String,
    },
    /// The engine's law is for point contact and the scene is a line contact.
    #[error("{engine} takes point contact (spheres); this scene is a {pair} contact")]
    NeedsPointContact {
        /// The engine's id.
        engine: &'static str,
        /// The scene's pair, e.g. `cylinder–plane`.
        pair: String,
    },
    /// No engine has this id: the id given and the known ids.
    #[error("unknown engine '{0}' (expected one of: {1})")]
    UnknownEngine(String, String),
}
