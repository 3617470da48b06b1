//! `hertz-tui translate`: a scene's contact parameters for one simulation engine, calibrated with
//! hertz-tui's own solver, what that engine will really give, and a script that runs as printed
//! (`--script FILE` writes it).

use crate::format::translation::render_run;
use crate::model::engine;
use crate::model::presets::Registry;

use super::args::{TranslateArgs, TranslateFormat};
use super::error::CliError;
use super::solve::load_scene;

/// Translates the scene for the engine, writes the script where asked, and renders it.
pub fn run(args: &TranslateArgs, registry: &Registry) -> Result<String, CliError> {
    let scene = load_scene(&args.source, registry)?;
    let translated = engine::translate_run(&args.engine, &scene, args.tolerance)?;
    if let Some(path) = &args.script {
        let script = translated.run.script.as_ref().ok_or_else(|| {
            CliError::Usage(format!(
                "--script: {} has no runnable script for this scene ({})",
                args.engine,
                translated.run.no_script.as_deref().unwrap_or("none")
            ))
        })?;
        std::fs::write(path, &script.text).map_err(|e| {
            CliError::Usage(format!("--script: cannot write {}: {e}", path.display()))
        })?;
    }
    match args.format {
        TranslateFormat::Text => Ok(render_run(&scene.name, &translated)),
        TranslateFormat::Json => super::json(&translated),
    }
}
