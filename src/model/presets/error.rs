//! Why a preset could not be found, read, parsed or saved.

use std::path::PathBuf;

use thiserror::Error;

use crate::model::error::ModelError;
use crate::model::overrides::OverrideError;
use crate::model::scene_file::SceneFileError;

/// Errors of the preset layer. I/O errors are kept as messages so the type stays `Clone + PartialEq`.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum PresetError {
    /// The scene or material file is invalid; the error locates it.
    #[error(transparent)]
    File(#[from] SceneFileError),
    /// A `--set` override is invalid.
    #[error(transparent)]
    Override(#[from] OverrideError),
    /// No scene by that name: the name and the known ones.
    #[error(
        "unknown scene \"{name}\" (scenes: {}; or give the path of a .toml scene file)",
        .known.join(", ")
    )]
    UnknownScene {
        /// The name asked for.
        name: String,
        /// The scenes there are.
        known: Vec<String>,
    },
    /// No material by that name: the name and the known ones.
    #[error("unknown material \"{name}\" (materials: {})", .known.join(", "))]
    UnknownMaterial {
        /// The name asked for.
        name: String,
        /// The materials there are.
        known: Vec<String>,
    },
    /// A file could not be read.
    #[error("cannot read {}: {message}", path.display())]
    Read {
        /// The file.
        path: PathBuf,
        /// The system's reason.
        message: String,
    },
    /// A file could not be written.
    #[error("cannot write {}: {message}", path.display())]
    Write {
        /// The file.
        path: PathBuf,
        /// The system's reason.
        message: String,
    },
    /// A user preset whose file name is not kebab-case, skipped.
    #[error(
        "user preset {} is skipped: its name \"{stem}\" is not kebab-case (rename it to {suggestion}.toml)",
        path.display()
    )]
    NotKebabCase {
        /// The file.
        path: PathBuf,
        /// Its name without `.toml`.
        stem: String,
        /// The kebab-case name to rename it to.
        suggestion: String,
    },
    /// A preset name to save under that is not kebab-case.
    #[error(
        "invalid preset name \"{0}\": use kebab-case (lowercase letters and digits joined by single hyphens)"
    )]
    InvalidName(String),
    /// Neither XDG_CONFIG_HOME nor HOME is set.
    #[error("no folder for user presets: set XDG_CONFIG_HOME or HOME, or save to a path")]
    NoUserDir,
    /// The scene to save does not validate.
    #[error("refusing to save an invalid scene: {0}")]
    InvalidScene(ModelError),
    /// The `[system]` table to save does not validate.
    #[error("refusing to save an invalid [system] table: {0}")]
    InvalidSystem(ModelError),
}
