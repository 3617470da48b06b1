//! Errors of the headless commands: user errors exit with status 2 and a message, never a backtrace.

use std::io;

use thiserror::Error;

use crate::model::ForceModel;
use crate::model::ModelError;
use crate::model::engine::EngineError;
use crate::model::impact::ImpactError;
use crate::model::presets::PresetError;
use crate::model::system::SystemError;

#[derive(Debug, Error)]
pub enum CliError {
    #[error(transparent)]
    Preset(#[from] PresetError),
    /// The scene is valid but the model cannot evaluate it (e.g. a domain error of eq 13/14).
    #[error("{0}")]
    Model(#[from] ModelError),
    #[error("{0}")]
    Usage(String),
    #[error("{model} impact failed: {source}")]
    Impact {
        model: ForceModel,
        #[source]
        source: ImpactError,
    },
    #[error("{0}")]
    Engine(#[from] EngineError),
    /// A system's run, orbit or diagram refused, with the stop it was for.
    #[error("{contact} stop: {source}")]
    System {
        contact: String,
        #[source]
        source: Box<SystemError>,
    },
    #[error("cannot write the output: {0}")]
    Output(#[from] io::Error),
}

impl CliError {
    /// Exit status: 2 for anything the user can fix (scene, arguments), 1 for output failures.
    pub fn exit_code(&self) -> u8 {
        match self {
            CliError::Output(_) => 1,
            _ => 2,
        }
    }

    /// A closed pipe (`hertz-tui solve … | head`) is not an error worth reporting.
    pub fn is_broken_pipe(&self) -> bool {
        matches!(self, CliError::Output(e) if e.kind() == io::ErrorKind::BrokenPipe)
    }
}
