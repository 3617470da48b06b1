//! `hertz-tui translate`: a scene's contact parameters for one simulation engine, calibrated with
//! hertz-tui's own solver, and what that engine will really give.

use crate::format::translation::render;
use crate::model::engine;
use crate::model::presets::Registry;

use super::args::{TranslateArgs, TranslateFormat};
use super::error::CliError;
use super::solve::load_scene;

/// Translates the scene for the engine and renders it.
pub fn run(args: &TranslateArgs, registry: &Registry) -> Result<String, CliError> {
    let scene = load_scene(&args.source, registry)?;
    let translation = engine::translate(&args.engine, &scene)?;
    match args.format {
        TranslateFormat::Text => Ok(render(&scene.name, &translation)),
        TranslateFormat::Json => super::json(&translation),
    }
}
