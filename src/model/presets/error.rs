//! Why a preset could not be found, read, parsed or saved.

use std::path::PathBuf;

use thiserror::Error;

use crate::model::error::ModelError;
use crate::model::overrides::OverrideError;
use crate::model::scene_file::SceneFileError;

/// Errors of the preset layer. I/O errors are kept as messages so the type stays `Clone + PartialEq`.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum PresetError {
    #[error(transparent)]
    File(#[from] SceneFileError),
    #[error(transparent)]
    Override(#[from] OverrideError),
    #[error(
        "unknown scene \"{name}\" (scenes: {}; or give the path of a .toml scene file)",
        .known.join(", ")
    )]
    UnknownScene { name: String, known: Vec<String> },
    #[error("unknown material \"{name}\" (materials: {})", .known.join(", "))]
    UnknownMaterial { name: String, known: Vec<String> },
    #[error("cannot read {}: {message}", path.display())]
    Read { path: PathBuf, message: String },
    #[error("cannot write {}: {message}", path.display())]
    Write { path: PathBuf, message: String },
    #[error(
        "user preset {} is skipped: its name \"{stem}\" is not kebab-case (rename it to {suggestion}.toml)",
        path.display()
    )]
    NotKebabCase {
        path: PathBuf,
        stem: String,
        suggestion: String,
    },
    #[error(
        "invalid preset name \"{0}\": use kebab-case (lowercase letters and digits joined by single hyphens)"
    )]
    InvalidName(String),
    #[error("no folder for user presets: set XDG_CONFIG_HOME or HOME, or save to a path")]
    NoUserDir,
    #[error("refusing to save an invalid scene: {0}")]
    InvalidScene(ModelError),
}
