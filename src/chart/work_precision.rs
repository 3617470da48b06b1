//! Work-precision data as chart lines: log₁₀ error (the worst of the four headline numbers)
//! against log₁₀ seconds per solve or log₁₀ force evaluations, one line per method in ladder
//! order; failed rungs are listed, not drawn.

use crate::chart::ticks::nice_axis;
use crate::chart::{Chart, Ink, Mark, Series, method_glyph};
use crate::format::units::{self, sig};
use crate::model::ode::Method;
use crate::model::study::runner::{CurrentPoint, WorkPrecisionData};
use crate::model::study::work_precision::{Setting, WorkPrecisionRow};

/// The glyph of the explorer's own solve on the work-precision charts.
pub const CURRENT_GLYPH: char = '█';

/// Errors below this are drawn at it: a solve can match its reference to the last bit, and
/// log₁₀ 0 has no place on a chart.
pub const ERROR_FLOOR: f64 = 1e-16;

/// What the cost axis measures.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Cost {
    Seconds,
    ForceEvals,
}

impl Cost {
    /// The other chart, for `c` where only one fits.
    pub fn other(self) -> Cost {
        match self {
            Cost::Seconds => Cost::ForceEvals,
            Cost::ForceEvals => Cost::Seconds,
        }
    }

    pub fn title(self) -> &'static str {
        match self {
            Cost::Seconds => "log₁₀ s per solve",
            Cost::ForceEvals => "log₁₀ force evaluations",
        }
    }
}

/// One method's rungs as (log₁₀ cost, log₁₀ error).
#[derive(Debug, Clone, PartialEq)]
pub struct MethodLine {
    pub method: Method,
    pub points: Vec<(f64, f64)>,
}

fn log_error(worst: f64) -> f64 {
    worst.max(ERROR_FLOOR).log10()
}

fn point(cost: Cost, seconds: Option<f64>, evals: Option<usize>, worst: f64) -> Option<(f64, f64)> {
    let c = match cost {
        Cost::Seconds => seconds?,
        Cost::ForceEvals => evals? as f64,
    };
    let p = (c.log10(), log_error(worst));
    (p.0.is_finite() && p.1.is_finite()).then_some(p)
}

fn rung_point(row: &WorkPrecisionRow, cost: Cost) -> Option<(f64, f64)> {
    let errors = row.errors?;
    point(cost, row.seconds_per_solve, row.force_evals, errors.worst())
}

/// The methods' lines, in the order the ladder measured them (methods without a drawable rung
/// are left out).
pub fn lines(data: &WorkPrecisionData, cost: Cost) -> Vec<MethodLine> {
    let mut lines: Vec<MethodLine> = Vec::new();
    for row in &data.rows {
        let Some(p) = rung_point(row, cost) else {
            continue;
        };
        match lines.iter_mut().find(|l| l.method == row.method) {
            Some(line) => line.points.push(p),
            None => lines.push(MethodLine {
                method: row.method,
                points: vec![p],
            }),
        }
    }
    lines
}

/// The explorer's solve on the same axes.
pub fn current(point_of: &CurrentPoint, cost: Cost) -> Option<(f64, f64)> {
    point(
        cost,
        Some(point_of.seconds_per_solve),
        Some(point_of.force_evals),
        point_of.errors.worst(),
    )
}

/// The work-precision chart against `cost`, with at most `max_x` × `max_y` tick labels: one line
/// per method and the explorer's solve as a block.
pub fn chart(
    data: &WorkPrecisionData,
    current: Option<&CurrentPoint>,
    cost: Cost,
    (max_x, max_y): (usize, usize),
) -> Chart {
    let lines = lines(data, cost);
    let mark = current.and_then(|p| self::current(p, cost));
    let all = lines
        .iter()
        .flat_map(|l| l.points.iter().copied())
        .chain(mark);
    let (mut x_lo, mut x_hi, mut y_lo, mut y_hi) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for (x, y) in all {
        x_lo = x_lo.min(x);
        x_hi = x_hi.max(x);
        y_lo = y_lo.min(y);
        y_hi = y_hi.max(y);
    }
    // Three labels at least: log axes cross zero freely, and two labels over a range across zero
    // would need a step wider than the range.
    let x = nice_axis(x_lo, x_hi, units::DIMENSIONLESS, max_x.max(3));
    let y = nice_axis(y_lo, y_hi, units::DIMENSIONLESS, max_y.max(3));
    Chart {
        title: format!("log₁₀ error against {}", cost.title()),
        x: x.chart_axis(cost.title().to_string()),
        y: y.chart_axis("log₁₀ error".to_string()),
        series: lines
            .into_iter()
            .map(|l| Series {
                name: l.method.to_string(),
                ink: Ink::Method(l.method),
                glyph: method_glyph(l.method),
                steps: true,
                runs: vec![l.points],
                focused: false,
                peak: None,
            })
            .collect(),
        marks: mark
            .map(|at| Mark {
                at,
                ink: Ink::Foreground,
                glyph: CURRENT_GLYPH,
                label: None,
            })
            .into_iter()
            .collect(),
        rules: Vec::new(),
        notes: Vec::new(),
        readout: None,
    }
}

/// A rung's setting as the lists print it: `rtol 1e-4`, `h 1.2 µs`.
pub fn setting(setting: Setting) -> String {
    match setting {
        Setting::Rtol(rtol) => format!("rtol {}", sig(rtol, 2)),
        Setting::Dt(dt) => format!("h {}", units::engineering(dt, units::SECOND, 3)),
    }
}

/// The rungs that failed, as `method setting: reason`.
pub fn failures(data: &WorkPrecisionData) -> Vec<String> {
    data.rows
        .iter()
        .filter_map(|row| {
            let reason = row.failure.as_ref()?;
            Some(format!("{} {}: {reason}", row.method, setting(row.setting)))
        })
        .collect()
}

/// The fixed-step methods the ladder has no rung of: no bounded step was found for them.
pub fn unmeasured(data: &WorkPrecisionData, fixed: &[Method]) -> Vec<Method> {
    fixed
        .iter()
        .copied()
        .filter(|m| !data.rows.iter().any(|r| r.method == *m))
        .collect()
}

/// Whether some drawn error lies below [`ERROR_FLOOR`].
pub fn any_floored(data: &WorkPrecisionData) -> bool {
    data.rows
        .iter()
        .filter_map(|r| r.errors)
        .any(|e| e.worst() < ERROR_FLOOR)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::ForceModel;
    use crate::model::impact::{ImpactSummary, MethodUsed};
    use crate::model::study::reference::SummaryErrors;

    fn errors(worst: f64) -> SummaryErrors {
        SummaryErrors {
            error_x_max: worst / 10.0,
            error_f_max: worst,
            error_t_contact: 0.0,
            error_v_out: worst / 2.0,
        }
    }

    fn row(method: Method, setting: Setting, worst: Option<f64>, evals: usize) -> WorkPrecisionRow {
        WorkPrecisionRow {
            method,
            setting,
            errors: worst.map(errors),
            force_evals: worst.map(|_| evals),
            seconds_per_solve: worst.map(|_| evals as f64 * 1e-8),
            failure: worst.is_none().then(|| "step size too small".to_string()),
        }
    }

    fn data() -> WorkPrecisionData {
        let summary = ImpactSummary {
            model: ForceModel::Proposed,
            method: MethodUsed::Integrator(Method::Dop853),
            x_max: 1.0,
            t_x_max: 1.0,
            f_max: 1.0,
            t_f_max: 1.0,
            t_contact: 1.0,
            v_out: 1.0,
            e_out: 1.0,
            x_residual: 0.0,
            energy_dissipated: 0.0,
            energy_residual: 0.0,
            steps: 1,
            rejected_steps: 0,
            force_evals: 1,
            tensile_cutoff: None,
        };
        WorkPrecisionData {
            model: ForceModel::Proposed,
            reference: summary,
            rows: vec![
                row(Method::Dopri5, Setting::Rtol(1e-2), None, 0),
                row(Method::Dopri5, Setting::Rtol(1e-3), Some(1e-3), 100),
                row(Method::Dopri5, Setting::Rtol(1e-4), Some(1e-5), 1000),
                row(Method::Rk4, Setting::Dt(1e-6), Some(0.0), 10),
            ],
        }
    }

    #[test]
    fn lines_take_the_worst_error_and_skip_failed_rungs() {
        let d = data();
        let by_evals = lines(&d, Cost::ForceEvals);
        assert_eq!(by_evals.len(), 2);
        assert_eq!(by_evals[0].method, Method::Dopri5);
        assert_eq!(by_evals[0].points, [(2.0, -3.0), (3.0, -5.0)]);
        // An exact match is drawn at the floor, never at −∞.
        assert_eq!(by_evals[1].points, [(1.0, -16.0)]);
        assert!(any_floored(&d));
        let by_time = lines(&d, Cost::Seconds);
        assert!((by_time[0].points[0].0 - (-6.0)).abs() < 1e-12);
        assert_eq!(failures(&d), ["dopri5 rtol 0.01: step size too small"]);
        assert_eq!(
            unmeasured(&d, &[Method::Euler, Method::Rk4]),
            [Method::Euler]
        );
    }

    #[test]
    fn settings_print_in_engineering_units() {
        assert_eq!(setting(Setting::Rtol(1e-8)), "rtol 1e-8");
        assert_eq!(setting(Setting::Dt(1.25e-6)), "h 1.25 µs");
    }
}
