//! The restitution data file: a CSV of impact velocity and measured e, optionally a standard
//! deviation per point, units in the header (docs/fitting.md).
//!
//! ```text
//! # steel ball on a steel plate, synthetic
//! v (m/s), e, sd
//! 0.10, 0.912, 0.01
//! 0.10, 0.905, 0.01   # a repeat at the same velocity
//! 0.50, 0.842, 0.01
//! ```
//!
//! The header names the columns in any order: `v` (also `v0`, `velocity`) with an optional unit
//! in parentheses or brackets (`v [mm/s]`, `v (km/h)`; m/s when none), `e` (also `restitution`,
//! `cor`; `%` allowed), and optionally `sd` (also `std`, `sigma`), in e's unit unless it gives
//! its own. `#` starts a comment; blank lines are skipped. Every error names the file and line.

use std::path::Path;

use thiserror::Error;

use crate::model::fit::{FitDataError, RestitutionData, RestitutionSample};

use super::units::{DIMENSIONLESS, METRE_PER_SECOND, Unit, parse};

/// A data file that could not be read, with the file and the line (0: the file as a whole).
#[derive(Debug, Clone, PartialEq, Error)]
#[error("{file}{}: {message}", if *.line > 0 { format!(":{}", .line) } else { String::new() })]
pub struct FitCsvError {
    /// The file as the user named it.
    pub file: String,
    /// The 1-based line, 0 for the whole file.
    pub line: usize,
    /// What is wrong.
    pub message: String,
}

/// The columns a restitution file may have.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Column {
    V,
    E,
    Sd,
}

impl Column {
    fn of(name: &str) -> Option<Column> {
        match name.to_ascii_lowercase().as_str() {
            "v" | "v0" | "v_0" | "v₀" | "velocity" | "impact velocity" => Some(Column::V),
            "e" | "restitution" | "cor" => Some(Column::E),
            "sd" | "std" | "sigma" | "σ" | "e_sd" => Some(Column::Sd),
            _ => None,
        }
    }

    fn unit(self) -> Unit {
        match self {
            Column::V => METRE_PER_SECOND,
            Column::E | Column::Sd => DIMENSIONLESS,
        }
    }
}

/// A header cell `name (unit)` or `name [unit]`: the name and the unit text, if any.
fn split_header(cell: &str) -> (&str, Option<&str>) {
    let cell = cell.trim();
    for (open, close) in [('(', ')'), ('[', ']')] {
        if let Some(i) = cell.find(open)
            && cell.ends_with(close)
        {
            return (
                cell[..i].trim(),
                Some(cell[i + open.len_utf8()..cell.len() - close.len_utf8()].trim()),
            );
        }
    }
    (cell, None)
}

/// SI value of one `unit_text` of the column's quantity (`mm/s` → 1e-3).
fn unit_factor(column: Column, unit_text: &str) -> Result<f64, String> {
    if column != Column::V && matches!(unit_text, "" | "1" | "-") {
        return Ok(1.0);
    }
    parse(&format!("1 {unit_text}"), column.unit())
}

/// The text of a line before its comment.
fn strip_comment(line: &str) -> &str {
    line.find('#').map_or(line, |i| &line[..i]).trim()
}

/// Parses restitution data from `text`; `file` names it in errors and becomes the data's source.
pub fn parse_restitution_csv(text: &str, file: &str) -> Result<RestitutionData, FitCsvError> {
    let err = |line: usize, message: String| FitCsvError {
        file: file.to_string(),
        line,
        message,
    };
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, strip_comment(l)))
        .filter(|(_, l)| !l.is_empty());
    let Some((header_line, header)) = lines.next() else {
        return Err(err(
            0,
            "no header: expected a line like `v (m/s), e, sd`".into(),
        ));
    };
    let mut columns: Vec<(Column, f64)> = Vec::new();
    for cell in header.split(',') {
        let (name, unit) = split_header(cell);
        let column = Column::of(name).ok_or_else(|| {
            err(
                header_line,
                format!("unknown column '{name}' (expected v, e and optionally sd)"),
            )
        })?;
        if columns.iter().any(|(c, _)| *c == column) {
            return Err(err(header_line, format!("column '{name}' given twice")));
        }
        let factor = match unit {
            Some(u) => unit_factor(column, u)
                .map_err(|m| err(header_line, format!("unit of '{name}': {m}")))?,
            None => 1.0,
        };
        columns.push((column, factor));
    }
    for (needed, what) in [(Column::V, "v (impact velocity)"), (Column::E, "e")] {
        if !columns.iter().any(|(c, _)| *c == needed) {
            return Err(err(header_line, format!("missing column {what}")));
        }
    }
    let e_factor = columns
        .iter()
        .find(|(c, _)| *c == Column::E)
        .map_or(1.0, |(_, f)| *f);
    // sd without its own unit is in e's.
    let sd_has_unit = header
        .split(',')
        .map(split_header)
        .any(|(n, u)| Column::of(n) == Some(Column::Sd) && u.is_some());
    let mut points = Vec::new();
    for (line, text) in lines {
        let cells: Vec<&str> = text.split(',').map(str::trim).collect();
        if cells.len() != columns.len() {
            return Err(err(
                line,
                format!(
                    "{} field(s), the header has {} ({})",
                    cells.len(),
                    columns.len(),
                    header
                ),
            ));
        }
        let mut sample = RestitutionSample {
            v: f64::NAN,
            e: f64::NAN,
            sd: None,
            line,
        };
        for (&(column, factor), cell) in columns.iter().zip(&cells) {
            if column == Column::Sd && cell.is_empty() {
                continue;
            }
            let name = match column {
                Column::V => "v",
                Column::E => "e",
                Column::Sd => "sd",
            };
            let value: f64 = cell
                .parse()
                .map_err(|_| err(line, format!("{name}: '{cell}' is not a number")))?;
            let factor = if column == Column::Sd && !sd_has_unit {
                e_factor
            } else {
                factor
            };
            match column {
                Column::V => sample.v = value * factor,
                Column::E => sample.e = value * factor,
                Column::Sd => sample.sd = Some(value * factor),
            }
        }
        points.push(sample);
    }
    RestitutionData::new(points)
        .map(|d| d.with_source(file))
        .map_err(|e| data_error(file, e))
}

/// A data error with the file named.
pub fn data_error(file: &str, error: FitDataError) -> FitCsvError {
    let line = error.line();
    let message = error.to_string();
    // The model's message starts with "line N: "; the file error says it as file:N.
    let message = message
        .strip_prefix(&format!("line {line}: "))
        .map_or(message.clone(), str::to_string);
    FitCsvError {
        file: file.to_string(),
        line,
        message,
    }
}

/// Reads restitution data from the file at `path`.
pub fn read_restitution_csv(path: &Path) -> Result<RestitutionData, FitCsvError> {
    let file = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| FitCsvError {
        file: file.clone(),
        line: 0,
        message: e.to_string(),
    })?;
    parse_restitution_csv(&text, &file)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_in_the_header_convert_to_si() {
        let text = "# synthetic\n\nv [mm/s], e (%), sd\n100, 90, 1  # a comment\n200, 85, 1\n";
        let d = parse_restitution_csv(text, "d.csv").unwrap();
        assert_eq!(d.len(), 2);
        assert!((d.points[0].v - 0.1).abs() < 1e-15);
        assert!((d.points[0].e - 0.9).abs() < 1e-15);
        assert!((d.points[0].sd.unwrap() - 0.01).abs() < 1e-15);
        assert_eq!(d.points[0].line, 4);
        assert_eq!(d.source.as_deref(), Some("d.csv"));
        let d = parse_restitution_csv("e, v (km/h)\n0.5, 3.6\n", "x").unwrap();
        assert!((d.points[0].v - 1.0).abs() < 1e-12 && d.points[0].sd.is_none());
    }

    #[test]
    fn bad_files_name_file_and_line() {
        let cases = [
            ("", "f.csv: no header"),
            ("v, sd\n1, 0.1\n", "f.csv:1: missing column e"),
            ("v, e, colour\n", "f.csv:1: unknown column 'colour'"),
            ("v (furlong/s), e\n", "f.csv:1: unit of 'v'"),
            ("v, e\n1, 0.5\n2\n", "f.csv:3: 1 field(s), the header has 2"),
            ("v, e\n# c\n1, abc\n", "f.csv:3: e: 'abc' is not a number"),
            ("v, e\n1, 0.5\n-1, 0.5\n", "f.csv:3: impact velocity v = -1"),
            ("v, e\n1, 1.5\n", "f.csv:2: restitution e = 1.5"),
            ("v, e\n1, NaN\n", "f.csv:2: e = NaN is not a finite number"),
            (
                "v, e, sd\n1, 0.5, 0.1\n2, 0.4,\n",
                "f.csv:3: no sd, while line 2",
            ),
            ("v, e\n", "f.csv: no data points"),
        ];
        for (text, message) in cases {
            let e = parse_restitution_csv(text, "f.csv")
                .unwrap_err()
                .to_string();
            assert!(e.starts_with(message), "{text:?}: {e}");
        }
    }
}
