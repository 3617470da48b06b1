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
    /// A translation lacks a parameter its script needs (a defect of the engine's file).
    #[error("{engine}: the translation has no parameter '{name}'")]
    MissingParameter {
        /// The engine's id.
        engine: &'static str,
        /// The parameter's name.
        name: String,
    },
    /// Stepping the engine's law gave a non-finite number.
    #[error("stepping the engine's law gave a non-finite number")]
    SteppingNonFinite,
    /// The stepped impact had not ended by the step limit.
    #[error("the stepped impact did not end within {t_limit:.3e} s")]
    SteppingNoSeparation {
        /// The time stepped, s.
        t_limit: f64,
    },
    /// No step on the ladder t_c/10 … t_c/50000 keeps the engine's stepping within the tolerance.
    #[error(
        "no step down to t_c/50000 keeps e, F_max and the contact time within {tolerance} of the continuous law"
    )]
    NoStep {
        /// The relative tolerance asked.
        tolerance: f64,
    },
    /// The step tolerance is not a fraction in (0, 1).
    #[error("--tolerance must lie strictly between 0 and 1; got {0}")]
    Tolerance(f64),
    /// No engine has this id: the id given and the known ids.
    #[error("unknown engine '{0}' (expected one of: {1})")]
    UnknownEngine(String, String),
}
