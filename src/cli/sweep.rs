//! `hertz-tui sweep`: one scene key varied over a range; rows in parameter order.

use std::io::Write;

use serde::Serialize;

use crate::format::{csv, push_shortest_exp};
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

/// The text of the last number written in a column: copied, not formatted again, while the column
/// repeats (a sweep of v₀ on a sphere keeps v_yield and v_plastic, of e or x_pl every quasistatic
/// column).
#[derive(Default)]
struct Repeated {
    bits: Option<u64>,
    text: Vec<u8>,
}

impl Repeated {
    /// [`push_number`], from the last text when `value` is the last number.
    fn push(&mut self, out: &mut Vec<u8>, value: Option<f64>) {
        if let Some(v) = value {
            if self.bits != Some(v.to_bits()) {
                self.text.clear();
                push_shortest_exp(&mut self.text, v);
                self.bits = Some(v.to_bits());
            }
            out.extend_from_slice(&self.text);
        }
        out.push(b',');
    }
}

/// The quasistatic columns, p_max … v_plastic, each remembering its last number.
#[derive(Default)]
struct QuasistaticColumns([Repeated; 5]);

/// One CSV row of `row` appended to `out`.
fn csv_row(
    out: &mut Vec<u8>,
    row: &SweepRow,
    models: &[ForceModel],
    quasistatic: &mut QuasistaticColumns,
) {
    let q = row.quasistatic;
    push_number(out, Some(row.value));
    let [p_max, contact_radius, half_width, v_yield, v_plastic] = &mut quasistatic.0;
    p_max.push(out, q.map(|q| q.p_max));
    contact_radius.push(out, q.and_then(|q| q.contact_radius));
    half_width.push(out, q.and_then(|q| q.half_width));
    v_yield.push(out, q.map(|q| q.v_yield));
    v_plastic.push(out, q.map(|q| q.v_plastic));
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::study::sweep::QuasistaticPoint;

    fn row(value: f64, quasistatic: Option<QuasistaticPoint>) -> SweepRow {
        SweepRow {
            value,
            quasistatic,
            impacts: Vec::new(),
            error: quasistatic.is_none().then(|| "invalid".into()),
        }
    }

    #[test]
    fn repeated_columns_are_written_as_if_formatted_afresh() {
        let q = |p_max: f64, v_yield: f64| QuasistaticPoint {
            p_max,
            contact_radius: Some(7.7e-5),
            half_width: None,
            v_yield,
            v_plastic: 0.326,
        };
        // v_yield repeats, changes, disappears with an invalid point, and comes back.
        let rows = [
            row(0.01, Some(q(5.4e8, 0.0316))),
            row(0.02, Some(q(6.1e8, 0.0316))),
            row(0.03, Some(q(6.6e8, 0.0451))),
            row(0.04, None),
            row(0.05, Some(q(7.3e8, 0.0451))),
        ];
        let mut out = Vec::new();
        let mut columns = QuasistaticColumns::default();
        for row in &rows {
            csv_row(&mut out, row, &[], &mut columns);
        }
        assert_eq!(
            String::from_utf8(out).unwrap(),
            "1e-2,5.4e8,7.7e-5,,3.16e-2,3.26e-1,\n\
             2e-2,6.1e8,7.7e-5,,3.16e-2,3.26e-1,\n\
             3e-2,6.6e8,7.7e-5,,4.51e-2,3.26e-1,\n\
             4e-2,,,,,,invalid\n\
             5e-2,7.3e8,7.7e-5,,4.51e-2,3.26e-1,\n"
        );
    }
}
