//! Ways translating a scene for an engine fails. Each names the engine or the quantity.

use thiserror::Error;

use crate::model::error::ModelError;
use crate::model::ode::OdeError;

#[derive(Debug, Clone, PartialEq, Error)]
pub enum EngineError {
    #[error(transparent)]
    Model(#[from] ModelError),
    #[error("integrating the engine's contact law failed: {0}")]
    Integration(OdeError),
    #[error("the engine's contact did not end within {t_limit:.3e} s")]
    NoSeparation { t_limit: f64 },
    #[error("the engine's impact gave a non-finite number")]
    NonFinite,
    #[error("{engine}: restitution {requested} cannot be reached: {reason}")]
    Unreachable {
        engine: &'static str,
        requested: f64,
        reason: String,
    },
    #[error("{engine} takes point contact (spheres); this scene is a {pair} contact")]
    NeedsPointContact { engine: &'static str, pair: String },
    #[error("unknown engine '{0}' (expected one of: {1})")]
    UnknownEngine(String, String),
}
