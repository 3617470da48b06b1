//! `hertz-tui bench`: work-precision rows, or the stability table with `--stability`.

use serde::Serialize;

use crate::format::csv;
use crate::model::impact::ImpactSummary;
use crate::model::ode::Method;
use crate::model::presets::Registry;
use crate::model::study::reference::reference;
use crate::model::study::stability::{
    STEP_TOLERANCE, StepBound, peak_angular_frequency, stability_bound, step_bounds,
};
use crate::model::study::work_precision::{Setting, Timing, WorkPrecisionRow, work_precision};

use super::args::{BenchArgs, Format};
use super::error::CliError;
use super::json;
use super::layout::columns;
use super::solve::load_scene;
use super::units::{engineering, scientific};

/// One rung of the work-precision ladder as printed: `rtol` or `dt` is set, errors are relative.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BenchRow {
    pub method: Method,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rtol: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dt: Option<f64>,
    pub error_x_max: Option<f64>,
    pub error_f_max: Option<f64>,
    pub error_t_contact: Option<f64>,
    pub error_v_out: Option<f64>,
    pub force_evals: Option<usize>,
    pub seconds_per_solve: Option<f64>,
    /// Why the solve failed at this rung (e.g. the step is beyond the stable range).
    pub error: Option<String>,
}

impl From<&WorkPrecisionRow> for BenchRow {
    fn from(row: &WorkPrecisionRow) -> Self {
        let (rtol, dt) = match row.setting {
            Setting::Rtol(rtol) => (Some(rtol), None),
            Setting::Dt(dt) => (None, Some(dt)),
        };
        BenchRow {
            method: row.method,
            rtol,
            dt,
            error_x_max: row.errors.map(|e| e.error_x_max),
            error_f_max: row.errors.map(|e| e.error_f_max),
            error_t_contact: row.errors.map(|e| e.error_t_contact),
            error_v_out: row.errors.map(|e| e.error_v_out),
            force_evals: row.force_evals,
            seconds_per_solve: row.seconds_per_solve,
            error: row.failure.clone(),
        }
    }
}

/// One fixed-step method's stability: theory next to measurement.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StabilityRow {
    pub method: Method,
    /// Largest stable h·ω of the linear theory (none for explicit Euler).
    pub bound_h_omega: Option<f64>,
    /// bound/ω_max, s.
    pub theoretical_dt: Option<f64>,
    /// Worst relative error of x_max, F_max, t_c and v_out at theoretical_dt (null: infinite,
    /// the solve failed there).
    pub error_at_theoretical_dt: Option<f64>,
    /// Largest step keeping those four errors within `tolerance`, measured, s.
    pub measured_dt: Option<f64>,
    /// measured_dt·ω_max.
    pub measured_h_omega: Option<f64>,
    /// The tolerance of measured_dt.
    pub tolerance: f64,
    /// ω_max = √(n·k·x_maxⁿ⁻¹/m), rad/s.
    pub omega_max: f64,
}

impl From<&StepBound> for StabilityRow {
    fn from(b: &StepBound) -> Self {
        StabilityRow {
            method: b.method,
            bound_h_omega: stability_bound(b.method),
            theoretical_dt: b.theoretical_dt,
            error_at_theoretical_dt: b.error_at_theoretical.filter(|e| e.is_finite()),
            measured_dt: b.measured_dt,
            measured_h_omega: b.measured_dt.map(|dt| dt * b.omega_max),
            tolerance: b.tolerance,
            omega_max: b.omega_max,
        }
    }
}

/// Runs the benchmark the arguments ask for and renders it.
pub fn run(args: &BenchArgs, registry: &Registry) -> Result<String, CliError> {
    let scene = load_scene(&args.source, registry)?;
    let quasistatic = scene.quasistatic()?;
    let params = scene.impact_params(&quasistatic);
    let impact_error = |source| CliError::Impact {
        model: args.model,
        source,
    };
    if args.stability {
        let reference = reference(args.model, &params).map_err(impact_error)?;
        let rows: Vec<StabilityRow> = step_bounds(args.model, &params, &reference)
            .iter()
            .map(StabilityRow::from)
            .collect();
        return match args.format {
            Format::Table => Ok(stability_table(
                &rows,
                &reference,
                peak_angular_frequency(&params),
            )),
            Format::Json => json(&rows),
            Format::Csv => Ok(stability_csv(&rows)),
        };
    }
    let (reference, rows) =
        work_precision(args.model, &params, Timing::default()).map_err(impact_error)?;
    let rows: Vec<BenchRow> = rows.iter().map(BenchRow::from).collect();
    match args.format {
        Format::Table => Ok(work_precision_table(&rows, &reference)),
        Format::Json => json(&rows),
        Format::Csv => Ok(work_precision_csv(&rows)),
    }
}

fn cell(value: Option<f64>, format: impl Fn(f64) -> String) -> String {
    value.map_or_else(|| "—".to_string(), format)
}

fn csv_cell<T: ToString>(value: Option<T>) -> String {
    value.map_or_else(String::new, |v| v.to_string())
}

fn reference_line(reference: &ImpactSummary) -> String {
    format!(
        "Reference: {} ({}), x_max {}, F_max {}, t_c {}, v_out {}\n\n",
        reference.model,
        reference.method,
        engineering(reference.x_max, "m"),
        engineering(reference.f_max, "N"),
        engineering(reference.t_contact, "s"),
        engineering(reference.v_out, "m/s"),
    )
}

fn work_precision_table(rows: &[BenchRow], reference: &ImpactSummary) -> String {
    let mut table = vec![
        [
            "method",
            "setting",
            "err x_max",
            "err F_max",
            "err t_c",
            "err v_out",
            "F evals",
            "time/solve",
            "",
        ]
        .map(String::from)
        .to_vec(),
    ];
    for r in rows {
        let setting = match (r.rtol, r.dt) {
            (Some(rtol), _) => format!("rtol {rtol:.0e}"),
            (_, Some(dt)) => format!("dt {}", engineering(dt, "s")),
            _ => String::new(),
        };
        let err = |e: Option<f64>| cell(e, |e| format!("{e:.2e}"));
        table.push(vec![
            r.method.to_string(),
            setting,
            err(r.error_x_max),
            err(r.error_f_max),
            err(r.error_t_contact),
            err(r.error_v_out),
            cell(r.force_evals.map(|n| n as f64), |n| format!("{n}")),
            cell(r.seconds_per_solve, |s| engineering(s, "s")),
            r.error.clone().unwrap_or_default(),
        ]);
    }
    reference_line(reference) + &columns(&table, "")
}

fn work_precision_csv(rows: &[BenchRow]) -> String {
    let mut out = String::from(
        "method,rtol,dt,error_x_max,error_f_max,error_t_contact,error_v_out,force_evals,seconds_per_solve,error\n",
    );
    for r in rows {
        let fields = [
            r.method.to_string(),
            csv_cell(r.rtol),
            csv_cell(r.dt),
            csv_cell(r.error_x_max),
            csv_cell(r.error_f_max),
            csv_cell(r.error_t_contact),
            csv_cell(r.error_v_out),
            csv_cell(r.force_evals),
            csv_cell(r.seconds_per_solve),
            csv::field(r.error.as_deref().unwrap_or("")),
        ];
        out.push_str(&fields.join(","));
        out.push('\n');
    }
    out
}

fn stability_table(rows: &[StabilityRow], reference: &ImpactSummary, omega: f64) -> String {
    let mut table = vec![
        [
            "method",
            "bound h·ω",
            "theoretical dt",
            "error there",
            "measured dt",
            "measured h·ω",
        ]
        .map(String::from)
        .to_vec(),
    ];
    for r in rows {
        table.push(vec![
            r.method.to_string(),
            r.bound_h_omega
                .map_or_else(|| "none (gains energy)".into(), |b| format!("{b:.3}")),
            cell(r.theoretical_dt, |dt| engineering(dt, "s")),
            match (r.theoretical_dt, r.error_at_theoretical_dt) {
                (None, _) => "—".into(),
                (Some(_), None) => "fails".into(),
                (Some(_), Some(e)) => format!("{:.2} %", 100.0 * e),
            },
            cell(r.measured_dt, |dt| engineering(dt, "s")),
            cell(r.measured_h_omega, |h| format!("{h:.3}")),
        ]);
    }
    let header = format!(
        "{}ω_max = √(n·k·x_maxⁿ⁻¹/m) = {} at the elastic x_max; \"error there\" is the worst relative error of\nx_max, F_max, t_c and v_out at the theoretical step; \"measured\" is the largest step keeping all four within\n{} % (every scanned step below it does too).\n\n",
        reference_line(reference),
        scientific(omega, "rad/s"),
        100.0 * rows.first().map_or(STEP_TOLERANCE, |r| r.tolerance),
    );
    header + &columns(&table, "")
}

fn stability_csv(rows: &[StabilityRow]) -> String {
    let mut out = String::from(
        "method,bound_h_omega,theoretical_dt,error_at_theoretical_dt,measured_dt,measured_h_omega,tolerance,omega_max\n",
    );
    for r in rows {
        let fields = [
            r.method.to_string(),
            csv_cell(r.bound_h_omega),
            csv_cell(r.theoretical_dt),
            csv_cell(r.error_at_theoretical_dt),
            csv_cell(r.measured_dt),
            csv_cell(r.measured_h_omega),
            r.tolerance.to_string(),
            r.omega_max.to_string(),
        ];
        out.push_str(&fields.join(","));
        out.push('\n');
    }
    out
}
