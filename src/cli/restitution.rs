//! `hertz-tui restitution`: the realised e of each law for requested e = 0.1, 0.3, 0.5, 0.7, 0.9.

use crate::format::csv::field;
use crate::format::{Zeros, significant};
use crate::model::impact::SolveOptions;
use crate::model::presets::Registry;
use crate::model::restitution::{REQUESTED, RestitutionRow, table};

use super::args::{Format, RestitutionArgs};
use super::error::CliError;
use super::layout::columns;
use super::solve::{load_scene, models_or_all};

/// The table of realised e for the scene the arguments name, in the format asked for.
pub fn run(args: &RestitutionArgs, registry: &Registry) -> Result<String, CliError> {
    let scene = load_scene(&args.source, registry)?;
    let quasistatic = scene.quasistatic()?;
    let params = scene.impact_params(&quasistatic);
    let rows = table(
        &models_or_all(&args.models),
        &params,
        &REQUESTED,
        &SolveOptions::default(),
    );
    match args.format {
        Format::Table => Ok(render_table(&rows)),
        Format::Json => super::json(&rows),
        Format::Csv => Ok(render_csv(&rows)),
    }
}

fn render_table(rows: &[RestitutionRow]) -> String {
    let mut lines = vec![
        std::iter::once("model".to_string())
            .chain(REQUESTED.iter().map(|e| format!("e = {e}")))
            .collect::<Vec<_>>(),
    ];
    let mut failures = String::new();
    for row in rows {
        let mut line = vec![row.model.to_string()];
        for p in &row.points {
            line.push(
                p.e_out
                    .map_or_else(|| "failed".to_string(), |e| significant(e, 4, Zeros::Keep)),
            );
            if let Some(err) = &p.error {
                failures.push_str(&format!(
                    "  {} at e = {}: {err}\n",
                    row.model, p.e_requested
                ));
            }
        }
        lines.push(line);
    }
    let mut out = format!(
        "Realised restitution e_out for the requested e (each law's damping from e by its own rule)\n{}",
        columns(&lines, "  ")
    );
    if !failures.is_empty() {
        out.push_str("Failures:\n");
        out.push_str(&failures);
    }
    out
}

fn render_csv(rows: &[RestitutionRow]) -> String {
    let mut out = String::from("model,e_requested,e_out,error\n");
    for row in rows {
        for p in &row.points {
            out.push_str(&format!(
                "{},{},{},{}\n",
                row.model,
                p.e_requested,
                p.e_out.map_or(String::new(), |e| e.to_string()),
                field(
                    &p.error
                        .as_ref()
                        .map(ToString::to_string)
                        .unwrap_or_default()
                )
            ));
        }
    }
    out
}
