//! `hertz-tui sweep`: one scene key varied over a range; rows in parameter order.

use std::io::Write;

use serde::Serialize;

use crate::format::sweep_csv::{QuasistaticColumns, csv_header, csv_row, failures};
use crate::model::ForceModel;
use crate::model::Scene;
use crate::model::impact::SolveOptions;
use crate::model::presets::Registry;
use crate::model::study::sweep::{SweepPlan, SweepRow, SweepSpec, check, sweep};

use super::args::{Format, SweepArgs};
use super::error::CliError;
use super::in_order::write_in_order;
use super::json;
use super::layout::columns;
use super::solve::{load_scene, models_or_all};
use super::units::engineering;

/// The JSON document of a sweep.
#[derive(Debug, Serialize)]
pub struct SweepReport<'a> {
    /// The swept key's dotted path.
    pub param: String,
    /// Its SI unit.
    pub unit: &'static str,
    pub rows: &'a [SweepRow],
}

/// The scene, the sweep and its models the arguments ask for.
fn prepare(
    args: &SweepArgs,
    registry: &Registry,
) -> Result<(Scene, SweepSpec, Vec<ForceModel>), CliError> {
    let scene = load_scene(&args.source, registry)?;
    let defaults = SolveOptions::default();
    let models = models_or_all(&args.models);
    let spec = SweepSpec {
        key: args.param,
        from: args.from,
        to: args.to,
        points: args.points as usize,
        log: args.log,
        models: models.clone(),
        options: SolveOptions {
            method: args.method,
            rtol: args.rtol.unwrap_or(defaults.rtol),
            ..defaults
        },
    };
    Ok((scene, spec, models))
}

/// Runs the sweep the arguments ask for and renders it (CSV is streamed by [`stream_csv`]).
pub fn run(args: &SweepArgs, registry: &Registry) -> Result<String, CliError> {
    let table_or_json = |args: &SweepArgs| {
        let (scene, spec, models) = prepare(args, registry)?;
        let rows = sweep(&scene, &spec).map_err(|e| CliError::Usage(e.to_string()))?;
        Ok::<_, CliError>((rows, models))
    };
    let param = args.param.path();
    match args.format {
        Format::Csv => {
            let mut out = Vec::new();
            stream_csv(args, registry, &mut out)?;
            String::from_utf8(out).map_err(|e| CliError::Usage(e.to_string()))
        }
        Format::Json => {
            let (rows, _) = table_or_json(args)?;
            json(&SweepReport {
                param,
                unit: args.param.unit(),
                rows: &rows,
            })
        }
        Format::Table => {
            let (rows, models) = table_or_json(args)?;
            Ok(table(&param, args.param.unit(), &models, &rows))
        }
    }
}

/// Sweep points solved and formatted per piece of output: small enough that the pieces in flight
/// stay a few MB even with every law (a million-point sweep never holds its rows), large enough
/// that handing a piece out costs nothing against solving it.
const PIECE: usize = 512;

/// `--format csv`, streamed: pieces of points are solved and formatted on every core, each into a
/// reused buffer, and written in order (`write_in_order`).
pub fn stream_csv(
    args: &SweepArgs,
    registry: &Registry,
    out: &mut dyn Write,
) -> Result<(), CliError> {
    let (scene, spec, models) = prepare(args, registry)?;
    let values = check(&scene, &spec).map_err(|e| CliError::Usage(e.to_string()))?;
    out.write_all(csv_header(&args.param.path(), &models).as_bytes())?;
    let plan = SweepPlan::new(&scene, &spec);
    let pieces: Vec<&[f64]> = values.chunks(PIECE).collect();
    write_in_order(pieces.len(), out, |index, buffer| {
        let mut quasistatic = QuasistaticColumns::default();
        for &value in pieces[index] {
            csv_row(buffer, &plan.point(value), &models, &mut quasistatic);
        }
    })?;
    Ok(())
}

fn table(param: &str, unit: &str, models: &[ForceModel], rows: &[SweepRow]) -> String {
    let mut header = vec![param.to_string(), "p_max".into()];
    for model in models {
        header.push(format!("{model} F_max"));
        header.push("e_out".into());
    }
    header.push(String::new());
    let mut table = vec![header];
    let show = |v: Option<f64>, unit: &str| v.map_or_else(|| "—".into(), |v| engineering(v, unit));
    for row in rows {
        let mut cells = vec![
            engineering(row.value, unit),
            show(row.quasistatic.map(|q| q.p_max), "Pa"),
        ];
        for model in models {
            let point = row.impacts.iter().find(|i| i.model == *model);
            cells.push(show(point.and_then(|p| p.f_max), "N"));
            cells.push(
                point
                    .and_then(|p| p.e_out)
                    .map_or_else(|| "—".into(), |e| format!("{e:.4}")),
            );
        }
        cells.push(failures(row));
        table.push(cells);
    }
    columns(&table, "")
}
