//! The trace CSV at the edge: a force or displacement trace over one impact, `t, F` or `t, x`, with
//! units in the header (`t (ms), F (N)`, `t [us], x [um]`; none means SI) read by
//! [`crate::format::units`], into the model's [`TraceData`] in SI. `#` starts a comment and
//! blank lines are skipped (`#` starts a comment anywhere); other columns (the `v` of `solve --format csv`) are ignored. Every
//! error names the file and, where there is one, the line (docs/fitting.md, Traces).

use std::path::Path;

use thiserror::Error;

use crate::format::units::{self, METRE, NEWTON, SECOND, Unit};
use crate::model::fit::trace::{TraceData, TraceDataError, TraceQuantity, TraceSample};

/// A trace file that could not be read, with the file and the line (0: the file as a whole), as
/// [`crate::format::fit_csv::FitCsvError`] says it: `file:line: message`.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("{file}{}: {message}", if *.line > 0 { format!(":{}", .line) } else { String::new() })]
pub struct TraceCsvError {
    /// The file as the user named it.
    pub file: String,
    /// The 1-based line, 0 for the whole file.
    pub line: usize,
    /// What is wrong.
    pub message: String,
}

impl TraceCsvError {
    /// The model's refusal of the samples with the file named (its "line N: " said as file:N).
    pub fn of_data(file: &str, error: &TraceDataError) -> Self {
        let line = error.line();
        let message = error.to_string();
        let message = message
            .strip_prefix(&format!("line {line}: "))
            .map_or(message.clone(), str::to_string);
        TraceCsvError {
            file: file.to_string(),
            line,
            message,
        }
    }
}

/// A header column this reader knows: which, where, and its unit's size in SI.
#[derive(Debug, Clone, Copy)]
struct Column {
    index: usize,
    si_per_unit: f64,
}

/// The names a column may go by (case ignored).
const TIME_NAMES: [&str; 2] = ["t", "time"];
const FORCE_NAMES: [&str; 2] = ["f", "force"];
const DISPLACEMENT_NAMES: [&str; 6] =
    ["x", "displacement", "approach", "indentation", "delta", "δ"];

/// A header cell split into its name and unit: `t (ms)`, `t [us]`, `t`.
fn name_and_unit(cell: &str) -> (String, Option<&str>) {
    let cell = cell.trim();
    for (open, close) in [('(', ')'), ('[', ']')] {
        if let Some(start) = cell.find(open)
            && let Some(unit) = cell[start + open.len_utf8()..].strip_suffix(close)
        {
            return (cell[..start].trim().to_lowercase(), Some(unit.trim()));
        }
    }
    (cell.to_lowercase(), None)
}

/// The lines that carry data or the header: (1-based line number, text before any `#`
/// comment), blank lines left out.
fn content_lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    text.lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.find('#').map_or(l, |c| &l[..c]).trim()))
        .filter(|(_, l)| !l.is_empty())
}

/// The columns of a header: time, force, displacement, each if present with its unit (an
/// unknown unit is an error naming the column).
type HeaderColumns = [Option<Column>; 3];

fn header_columns(header: &str) -> Result<HeaderColumns, String> {
    let mut found: HeaderColumns = [None; 3];
    let kinds: [(&[&str], Unit); 3] = [
        (&TIME_NAMES, SECOND),
        (&FORCE_NAMES, NEWTON),
        (&DISPLACEMENT_NAMES, METRE),
    ];
    for (index, cell) in header.split(',').enumerate() {
        let (name, unit_text) = name_and_unit(cell);
        let Some(kind) = kinds
            .iter()
            .position(|(names, _)| names.contains(&name.as_str()))
        else {
            continue;
        };
        if found[kind].is_some() {
            return Err(format!("column '{}' appears twice", cell.trim()));
        }
        let si_per_unit = match unit_text {
            None | Some("") => 1.0,
            Some(u) => units::parse(&format!("1 {u}"), kinds[kind].1)
                .map_err(|e| format!("column '{}': {e}", cell.trim()))?,
        };
        found[kind] = Some(Column { index, si_per_unit });
    }
    Ok(found)
}

/// Whether `text` (a whole file) starts, after comments, with a trace header: a time column and
/// a force or displacement column. What `fit --data` asks to tell a trace from e(v) data.
pub fn is_trace(text: &str) -> bool {
    content_lines(text).next().is_some_and(|(_, header)| {
        header_columns(header).is_ok_and(|[t, f, x]| t.is_some() && (f.is_some() || x.is_some()))
    })
}

/// Reads a trace; a header with both F and x gives the force trace (see [`parse_trace_csv_as`]).
pub fn parse_trace_csv(text: &str, file: &str) -> Result<TraceData, TraceCsvError> {
    parse(text, file, None)
}

/// Reads the `quantity` column of a trace (of a file with both F and x columns, say).
pub fn parse_trace_csv_as(
    text: &str,
    file: &str,
    quantity: TraceQuantity,
) -> Result<TraceData, TraceCsvError> {
    parse(text, file, Some(quantity))
}

fn parse(
    text: &str,
    file: &str,
    wanted: Option<TraceQuantity>,
) -> Result<TraceData, TraceCsvError> {
    let syntax = |line: usize, message: String| TraceCsvError {
        file: file.to_string(),
        line,
        message,
    };
    let mut lines = content_lines(text);
    let Some((header_line, header)) = lines.next() else {
        return Err(syntax(
            0,
            "no header: expected a line like `t (ms), F (N)` or `t (us), x (um)`".into(),
        ));
    };
    let [time, force, displacement] = header_columns(header).map_err(|m| syntax(header_line, m))?;
    let Some(time) = time else {
        return Err(syntax(
            header_line,
            format!("no time column in `{header}`: name one t or time, e.g. `t (ms)`"),
        ));
    };
    let (quantity, value) = match (wanted, force, displacement) {
        (Some(TraceQuantity::Force) | None, Some(f), _) => (TraceQuantity::Force, f),
        (Some(TraceQuantity::Displacement) | None, _, Some(x)) => (TraceQuantity::Displacement, x),
        (Some(q), _, _) => {
            return Err(syntax(
                header_line,
                format!(
                    "no {} column in `{header}`: name one {}",
                    match q {
                        TraceQuantity::Force => "force",
                        TraceQuantity::Displacement => "displacement",
                    },
                    match q {
                        TraceQuantity::Force => "F (force), e.g. `F (N)`",
                        TraceQuantity::Displacement => "x (displacement), e.g. `x (um)`",
                    }
                ),
            ));
        }
        (None, None, None) => {
            return Err(syntax(
                header_line,
                format!(
                    "no force or displacement column in `{header}`: name one F (force) or x (displacement), e.g. `F (N)`"
                ),
            ));
        }
    };
    let columns = header.split(',').count();
    let mut samples = Vec::new();
    for (line, row) in lines {
        let fields: Vec<&str> = row.split(',').map(str::trim).collect();
        if fields.len() != columns {
            return Err(syntax(
                line,
                format!("{} fields where the header has {columns}", fields.len()),
            ));
        }
        let read = |col: Column, name: &str| -> Result<f64, TraceCsvError> {
            let cell = fields[col.index];
            cell.parse::<f64>()
                .map(|v| v * col.si_per_unit)
                .map_err(|_| syntax(line, format!("{name} '{cell}' is not a number")))
        };
        samples.push(TraceSample {
            t: read(time, "t")?,
            value: read(value, quantity.symbol())?,
            line,
        });
    }
    TraceData::new(quantity, samples, Some(file.to_string()))
        .map_err(|e| TraceCsvError::of_data(file, &e))
}

/// Reads a trace from the file at `path` ([`parse_trace_csv`]).
pub fn read_trace_csv(path: &Path) -> Result<TraceData, TraceCsvError> {
    let file = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| TraceCsvError {
        file: file.clone(),
        line: 0,
        message: e.to_string(),
    })?;
    parse_trace_csv(&text, &file)
}

#[cfg(test)]
mod tests {
    use super::*;

    const FORCE: &str =
        "# synthetic\nt (ms), F (kN)\n0, 0\n0.01, 0.2  # rising\n0.02, 0.4\n0.03, 0\n";

    #[test]
    fn units_in_the_header_convert_to_si() {
        let trace = parse_trace_csv(FORCE, "f.csv").unwrap();
        assert_eq!(trace.quantity, TraceQuantity::Force);
        assert_eq!(trace.samples.len(), 4);
        let s = trace.samples[2];
        assert!((s.t - 2e-5).abs() < 1e-18 && (s.value - 400.0).abs() < 1e-9);
        assert_eq!(s.line, 5);
        let x = parse_trace_csv("t [us], x [um]\n0,-1\n1,2\n2,3\n", "x.csv").unwrap();
        assert_eq!(x.quantity, TraceQuantity::Displacement);
        assert!((x.samples[1].t - 1e-6).abs() < 1e-20 && (x.samples[1].value - 2e-6).abs() < 1e-20);
        // The solver's own CSV (SI, no units) reads as a force trace, or as x when asked.
        let solved = "t,x,v,F\n0,0,0.3,0\n1e-5,2e-6,0.2,50\n2e-5,1e-6,-0.2,20\n";
        assert_eq!(
            parse_trace_csv(solved, "s.csv").unwrap().quantity,
            TraceQuantity::Force
        );
        let as_x = parse_trace_csv_as(solved, "s.csv", TraceQuantity::Displacement).unwrap();
        assert_eq!(as_x.values(), [0.0, 2e-6, 1e-6]);
        assert!(is_trace(FORCE) && is_trace(solved));
        assert!(!is_trace("v (m/s), e\n0.3, 0.8\n"));
    }

    #[test]
    fn errors_name_file_and_line() {
        let err = |text: &str| parse_trace_csv(text, "d.csv").unwrap_err().to_string();
        assert_eq!(
            err("time (s), v\n0,1\n"),
            "d.csv:1: no force or displacement column in `time (s), v`: name one F (force) or x (displacement), e.g. `F (N)`"
        );
        assert!(err("F (N)\n1\n").starts_with("d.csv:1: no time column"));
        assert!(
            err("t (fortnights), F\n")
                .starts_with("d.csv:1: column 't (fortnights)': unknown unit")
        );
        assert_eq!(
            err("t,F\n0,0\n1,2,3\n"),
            "d.csv:3: 3 fields where the header has 2"
        );
        assert_eq!(err("t,F\n0,0\n1,abc\n"), "d.csv:3: F 'abc' is not a number");
        assert_eq!(
            err("t,F\n0,0\n1,NaN\n2,1\n"),
            "d.csv:3: F is NaN, not a finite number"
        );
        assert!(
            err("t,F\n0,0\n# gap\n2,1\n1,1\n").starts_with("d.csv:5: t = 1e0 s does not increase")
        );
        assert!(err("t,F\n0,0\n1,0\n2,-0.1\n").starts_with("d.csv: no contact in the trace"));
        assert!(err("").starts_with("d.csv: no header"));
        assert!(
            parse_trace_csv_as("t,F\n0,0\n1,1\n2,0\n", "d.csv", TraceQuantity::Displacement)
                .unwrap_err()
                .to_string()
                .starts_with("d.csv:1: no displacement column")
        );
    }
}
