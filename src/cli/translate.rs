//! `hertz-tui translate`: a scene's contact parameters for one simulation engine, calibrated with
//! hertz-tui's own solver, what that engine will really give, and a script that runs as printed
//! (`--script FILE` writes it).

use serde::Serialize;

use crate::format::translation::render_run;
use crate::format::{Zeros, significant};
use crate::model::Scene;
use crate::model::engine::{self, EngineRun};
use crate::model::fit::{FitOptions, RestitutionData, candidates, fit_restitution};
use crate::model::presets::Registry;

use super::args::{TranslateArgs, TranslateFormat};
use super::error::CliError;
use super::fit::{EngineAgainstData, engine_against, read_restitution, render_engines};
use super::layout::columns;
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
    let against = match &args.data {
        Some(path) => Some(against_data(&args.engine, &scene, path)?),
        None => None,
    };
    match (args.format, against) {
        (TranslateFormat::Text, None) => Ok(render_run(&scene.name, &translated)),
        (TranslateFormat::Text, Some((data, row))) => Ok(format!(
            "{}\n{}",
            render_run(&scene.name, &translated),
            render_against(&data, &row)
        )),
        (TranslateFormat::Json, None) => super::json(&translated),
        (TranslateFormat::Json, Some((_, row))) => super::json(&WithData {
            run: &translated,
            data: row,
        }),
    }
}

/// `translate --format json --data`: the translation and the engine against the data.
#[derive(Serialize)]
struct WithData<'a> {
    #[serde(flatten)]
    run: &'a EngineRun,
    data: EngineAgainstData,
}

/// The engine's realised e at the data's velocities, its constants calibrated at the scene's v₀;
/// the noise is the RMS of the given sd, or else the best law's residual sd.
fn against_data(
    id: &str,
    scene: &Scene,
    path: &std::path::Path,
) -> Result<(RestitutionData, EngineAgainstData), CliError> {
    let engine = engine::find(id)?;
    let data = read_restitution(path)?;
    let sds: Vec<f64> = data.points.iter().filter_map(|p| p.sd).collect();
    let noise = if sds.len() == data.len() {
        (sds.iter().map(|s| s * s).sum::<f64>() / sds.len() as f64).sqrt()
    } else {
        fit_restitution(scene, &data, &candidates(), &FitOptions::default())
            .map_err(|e| CliError::Usage(format!("{}: {e}", path.display())))?
            .verdict
            .noise
    };
    let row = engine_against(engine.id, scene, &data, noise);
    Ok((data, row))
}

/// The engine's e beside each measured point, then its verdict.
fn render_against(data: &RestitutionData, row: &EngineAgainstData) -> String {
    let source = data.source.as_deref().unwrap_or("the data");
    let mut out = format!("Against {source}:\n");
    if !row.e.is_empty() {
        let mut rows = vec![
            ["v0 (m/s)", "e measured", "e engine", "difference"]
                .map(String::from)
                .to_vec(),
        ];
        for (p, e) in data.points.iter().zip(&row.e) {
            rows.push(vec![
                significant(p.v, 4, Zeros::Trim),
                significant(p.e, 4, Zeros::Trim),
                significant(*e, 4, Zeros::Keep),
                significant(e - p.e, 4, Zeros::Keep),
            ]);
        }
        out.push_str(&columns(&rows, "  "));
    }
    out.push_str(&render_engines(std::slice::from_ref(row)));
    out
}
