//! What continuation refuses or where it stops, in words that name the cause.
#![warn(missing_docs)]

use thiserror::Error;

use crate::model::system::SystemError;

/// Everything the continuation of periodic orbits can refuse.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ContinuationError {
    /// The system's own refusal (a key out of range, an orbit that chatters, …).
    #[error(transparent)]
    System(#[from] SystemError),
    /// A matrix that should be invertible is not (a degenerate branch point).
    #[error("continuation: {0} is singular here (a degenerate point of the branch)")]
    Singular(&'static str),
    /// Newton's corrector did not converge.
    #[error(
        "continuation: the corrector did not converge in {iterations} iterations (last correction {correction:e})"
    )]
    Corrector {
        /// Iterations done.
        iterations: usize,
        /// The last correction, scaled.
        correction: f64,
    },
    /// The parameter range is empty or not finite.
    #[error("continuation: `{key}` range {from} → {to} is empty or not finite")]
    Range {
        /// The key.
        key: String,
        /// Start.
        from: f64,
        /// End.
        to: f64,
    },
    /// The orbit asked for does not fit the continuation (its impacts, its period).
    #[error("continuation: {0}")]
    Unsupported(String),
    /// The special point asked for is not of a kind that can be followed or switched at.
    #[error("continuation: {0}")]
    NoSuchPoint(String),
    /// Stopped on request before the branch ended (a newer request superseded it).
    #[error("continuation: stopped before the branch ended")]
    Stopped,
}
