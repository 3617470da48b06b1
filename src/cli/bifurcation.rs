//! `hertz-tui bifurcation`: a brute-force bifurcation diagram of a system over one key, for each
//! stop asked for; CSV is streamed column by column as the model hands them over (in the order
//! of the values, computed on every core), JSON and the table when all are done.

use std::io::Write;
use std::ops::ControlFlow;

use serde::Serialize;

use crate::format::csv;
use crate::model::presets::Registry;
pub use crate::model::study::system::values;
use crate::model::system::{
    self, Column, Contact, Diagram, DiagramOptions, Param, SystemError, SystemModel,
};

use super::args::{BifurcationArgs, Format};
use super::error::CliError;
use super::json;
use super::layout::columns;
use super::system::{contact_label, contacts, failed, load_system, run_options};
use super::units::engineering;

/// The SI unit of a parameter's values.
pub fn param_unit(param: Param) -> &'static str {
    match param {
        Param::System(key) => key.unit(),
        Param::Scene(key) => key.unit(),
    }
}

/// The diagram of one contact, each column handed to `on_column` as it comes.
pub fn diagram(
    model: &SystemModel,
    contact: &Contact,
    args: &BifurcationArgs,
    on_column: impl FnMut(&Column) -> ControlFlow<()>,
) -> Result<Diagram, SystemError> {
    let options = DiagramOptions {
        run: run_options(&args.run, 0),
        max_total_impacts: args.budget,
        chunk: 0,
    };
    let values = values(args.from, args.to, args.points as usize);
    system::bifurcation(model, contact, args.param, &values, &options, on_column)
}

/// The checks clap cannot make: finite bounds.
fn check(args: &BifurcationArgs) -> Result<(), CliError> {
    for (name, v) in [("--from", args.from), ("--to", args.to)] {
        if !v.is_finite() {
            return Err(CliError::Usage(format!(
                "{name} must be a finite number, got {v}"
            )));
        }
    }
    Ok(())
}

/// The CSV header: one row per recorded impact of every column.
fn header(param: Param) -> String {
    format!(
        "contact,{},v_in,phase,stop,period_impacts,period_cycles,end\n",
        csv::field(&param.path())
    )
}

/// The rows of a column (one with empty impact fields when nothing was recorded, so that every
/// value appears).
fn column_rows(out: &mut String, contact: &str, column: &Column) {
    let period = column
        .period
        .map_or_else(|| ",".to_string(), |(n, m)| format!("{n},{m}"));
    let end = serde_json::to_value(column.end)
        .ok()
        .and_then(|v| v.as_str().map(str::to_string))
        .unwrap_or_default();
    if column.velocities.is_empty() {
        out.push_str(&format!("{contact},{:e},,,,{period},{end}\n", column.value));
    }
    for ((v, phase), stop) in column
        .velocities
        .iter()
        .zip(&column.phases)
        .zip(&column.stops)
    {
        out.push_str(&format!(
            "{contact},{:e},{v:e},{phase:e},{stop},{period},{end}\n",
            column.value
        ));
    }
}

/// `--format csv`, streamed: each column written as soon as the model hands it over.
pub fn stream_csv(
    args: &BifurcationArgs,
    registry: &Registry,
    out: &mut dyn Write,
) -> Result<(), CliError> {
    check(args)?;
    let model = load_system(&args.source, registry)?;
    // The header goes with the first column: a diagram refused at once (a key the system lacks,
    // over budget) prints nothing but its error.
    let mut header = Some(header(args.param));
    for contact in contacts(&args.contact, &model)? {
        let label = csv::field(&contact_label(&contact));
        let mut written: Result<(), std::io::Error> = Ok(());
        let mut text = String::new();
        let result = diagram(&model, &contact, args, |column| {
            text.clear();
            text.extend(header.take());
            column_rows(&mut text, &label, column);
            written = out.write_all(text.as_bytes());
            if written.is_ok() {
                ControlFlow::Continue(())
            } else {
                ControlFlow::Break(())
            }
        });
        written?;
        result.map_err(|e| failed(&contact, e))?;
        out.flush()?;
    }
    Ok(())
}

/// One contact's diagram in the JSON document.
#[derive(Debug, Serialize)]
pub struct DiagramRow {
    pub contact: String,
    #[serde(flatten)]
    pub diagram: Diagram,
}

/// The JSON document of `bifurcation`.
#[derive(Debug, Serialize)]
pub struct BifurcationReport {
    pub param: String,
    pub unit: &'static str,
    pub diagrams: Vec<DiagramRow>,
}

/// Every contact's whole diagram.
pub fn report(args: &BifurcationArgs, registry: &Registry) -> Result<BifurcationReport, CliError> {
    check(args)?;
    let model = load_system(&args.source, registry)?;
    let diagrams = contacts(&args.contact, &model)?
        .iter()
        .map(|contact| {
            let diagram = diagram(&model, contact, args, |_| ControlFlow::Continue(()))
                .map_err(|e| failed(contact, e))?;
            Ok(DiagramRow {
                contact: contact_label(contact),
                diagram,
            })
        })
        .collect::<Result<Vec<_>, CliError>>()?;
    Ok(BifurcationReport {
        param: args.param.path(),
        unit: param_unit(args.param),
        diagrams,
    })
}

/// Runs `bifurcation` as JSON or a table (CSV is streamed by [`stream_csv`]).
pub fn run(args: &BifurcationArgs, registry: &Registry) -> Result<String, CliError> {
    if args.format == Format::Csv {
        let mut out = Vec::new();
        stream_csv(args, registry, &mut out)?;
        return String::from_utf8(out).map_err(|e| CliError::Usage(e.to_string()));
    }
    let report = report(args, registry)?;
    if args.format == Format::Json {
        return json(&report);
    }
    Ok(table(&report))
}

/// One row per value: its period, how many distinct impacts and the range of their speeds.
fn table(report: &BifurcationReport) -> String {
    let mut out = String::new();
    for d in &report.diagrams {
        out.push_str(&format!("{} stop over {}\n", d.contact, report.param));
        let mut rows = vec![
            [
                report.param.as_str(),
                "period",
                "impacts",
                "v_in min",
                "v_in max",
            ]
            .map(String::from)
            .to_vec(),
        ];
        for c in &d.diagram.columns {
            let lo = c.velocities.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = c
                .velocities
                .iter()
                .copied()
                .fold(f64::NEG_INFINITY, f64::max);
            let speed = |v: f64| {
                if v.is_finite() {
                    engineering(v, "m/s")
                } else {
                    "—".into()
                }
            };
            rows.push(vec![
                engineering(c.value, report.unit),
                c.period
                    .map_or_else(|| "—".into(), |(n, m)| format!("{n} per {m} T")),
                c.velocities.len().to_string(),
                speed(lo),
                speed(hi),
            ]);
        }
        out.push_str(&columns(&rows, "  "));
    }
    out
}
