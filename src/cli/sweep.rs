//! `hertz-tui sweep`: one scene key varied over a range; rows in parameter order.

use serde::Serialize;

use super::args::{Format, SweepArgs};
use super::error::CliError;
use super::json;
use super::layout::columns;
use super::solve::{load_scene, models_or_all};
use super::units::engineering;
use crate::format::csv;
use crate::model::ForceModel;
use crate::model::impact::SolveOptions;
use crate::model::presets::Registry;
use crate::model::study::sweep::{SweepRow, SweepSpec, sweep};

/// The JSON document of a sweep.
#[derive(Debug, Serialize)]
pub struct SweepReport<'a> {
    /// The swept key's dotted path.
    pub param: String,
    /// Its SI unit.
    pub unit: &'static str,
    pub rows: &'a [SweepRow],
}

/// Runs the sweep the arguments ask for and renders it.
pub fn run(args: &SweepArgs, registry: &Registry) -> Result<String, CliError> {
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
    let rows = sweep(&scene, &spec).map_err(|e| CliError::Usage(e.to_string()))?;
    let param = args.param.path();
    match args.format {
        Format::Csv => Ok(csv(&param, &models, &rows)),
        Format::Json => json(&SweepReport {
            param,
            unit: args.param.unit(),
            rows: &rows,
        }),
        Format::Table => Ok(table(&param, args.param.unit(), &models, &rows)),
    }
}

fn number(value: Option<f64>) -> String {
    value.map_or_else(String::new, |v| format!("{v:e}"))
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

fn csv(param: &str, models: &[ForceModel], rows: &[SweepRow]) -> String {
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
    let mut out = header.join(",") + "\n";
    for row in rows {
        let q = row.quasistatic;
        let mut fields = vec![
            format!("{:e}", row.value),
            number(q.map(|q| q.p_max)),
            number(q.and_then(|q| q.contact_radius)),
            number(q.and_then(|q| q.half_width)),
            number(q.map(|q| q.v_yield)),
            number(q.map(|q| q.v_plastic)),
        ];
        for model in models {
            let point = row.impacts.iter().find(|i| i.model == *model);
            fields.push(number(point.and_then(|p| p.x_max)));
            fields.push(number(point.and_then(|p| p.f_max)));
            fields.push(number(point.and_then(|p| p.t_contact)));
            fields.push(number(point.and_then(|p| p.v_out)));
            fields.push(number(point.and_then(|p| p.e_out)));
        }
        fields.push(csv::field(&failures(row)));
        out.push_str(&fields.join(","));
        out.push('\n');
    }
    out
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
