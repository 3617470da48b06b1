//! `hertz-tui sweep`: one scene key varied over a range; rows in parameter order.

use serde::Serialize;

use super::args::{Format, SweepArgs};
use super::error::CliError;
use super::json;
use super::layout::columns;
use super::solve::{load_scene, models_or_all};
use super::units::engineering;
use crate::format::{csv, push_shortest_exp};
use crate::model::ForceModel;
use crate::model::Scene;
use crate::model::impact::SolveOptions;
use crate::model::presets::Registry;
use crate::model::study::sweep::{SweepPlan, SweepRow, SweepSpec, check, sweep};
use rayon::prelude::*;
use std::io::Write;

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

/// The messages of a row's failures, `model: message` joined by `; `.
fn failures(row: &SweepRow) -> String {
    let mut messages: Vec<String> = row.error.iter().cloned().collect();
    messages.extend(
        row.impacts
            .iter()
            .filter_map(|i| i.error.as_ref().map(|e| format!("{}: {e}", i.model))),
    );
    messages.join("; ")
}

/// Sweep points solved and formatted per chunk: the rows in flight are bounded by it, not by
/// `--points` (a million-point sweep holds 16 Ki rows, a few MB, at a time).
const CHUNK: usize = 16_384;

/// Formatting buffers per worker thread: enough pieces per chunk for rayon to balance the load.
const BUFFERS_PER_THREAD: usize = 4;

/// `--format csv`, streamed: each chunk of points is solved and formatted in parallel, each worker
/// into its own reused buffer, and the buffers are written in order.
pub fn stream_csv(
    args: &SweepArgs,
    registry: &Registry,
    out: &mut dyn Write,
) -> Result<(), CliError> {
    let (scene, spec, models) = prepare(args, registry)?;
    let values = check(&scene, &spec).map_err(|e| CliError::Usage(e.to_string()))?;
    out.write_all(csv_header(&args.param.path(), &models).as_bytes())?;
    let pieces = BUFFERS_PER_THREAD * rayon::current_num_threads();
    let plan = SweepPlan::new(&scene, &spec);
    let mut buffers = vec![Vec::new(); pieces];
    let piece = CHUNK.div_ceil(pieces);
    for chunk in values.chunks(CHUNK) {
        let used = chunk.len().div_ceil(piece);
        chunk
            .par_chunks(piece)
            .zip(buffers.par_iter_mut())
            .for_each(|(points, buffer)| {
                buffer.clear();
                for &value in points {
                    csv_row(buffer, &plan.point(value), &models);
                }
            });
        for buffer in &buffers[..used] {
            out.write_all(buffer)?;
        }
    }
    Ok(())
}

fn csv_header(param: &str, models: &[ForceModel]) -> String {
    let mut header = vec![
        param.to_string(),
        "p_max".into(),
        "contact_radius".into(),
        "half_width".into(),
        "v_yield".into(),
        "v_plastic".into(),
    ];
    for model in models {
        for field in ["x_max", "f_max", "t_contact", "v_out", "e_out"] {
            header.push(format!("{model}.{field}"));
        }
    }
    header.push("error".into());
    header.join(",") + "\n"
}

/// `value,` in Rust's `{:e}` (shortest round-trip), or just `,` for a missing number.
fn push_number(out: &mut Vec<u8>, value: Option<f64>) {
    if let Some(v) = value {
        push_shortest_exp(out, v);
    }
    out.push(b',');
}

/// One CSV row of `row` appended to `out`.
fn csv_row(out: &mut Vec<u8>, row: &SweepRow, models: &[ForceModel]) {
    let q = row.quasistatic;
    push_number(out, Some(row.value));
    push_number(out, q.map(|q| q.p_max));
    push_number(out, q.and_then(|q| q.contact_radius));
    push_number(out, q.and_then(|q| q.half_width));
    push_number(out, q.map(|q| q.v_yield));
    push_number(out, q.map(|q| q.v_plastic));
    for model in models {
        let point = row.impacts.iter().find(|i| i.model == *model);
        push_number(out, point.and_then(|p| p.x_max));
        push_number(out, point.and_then(|p| p.f_max));
        push_number(out, point.and_then(|p| p.t_contact));
        push_number(out, point.and_then(|p| p.v_out));
        push_number(out, point.and_then(|p| p.e_out));
    }
    let failed = row.error.is_some() || row.impacts.iter().any(|i| i.error.is_some());
    if failed {
        out.extend_from_slice(csv::field(&failures(row)).as_bytes());
    }
    out.push(b'\n');
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
