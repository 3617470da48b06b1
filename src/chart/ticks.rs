//! Chart axes in engineering units with round ticks.
//!
//! ratatui spreads axis labels evenly over the bounds, so the bounds are chosen as whole multiples
//! of a round step (1, 2, 2.5 or 5 × 10ᵏ) and every label then sits exactly on its value. A log
//! axis plots log₁₀ of the display value, its bounds on whole decades and its labels at decades.

use crate::format::units::{self, Prefix, Unit};
use crate::format::{self, Zeros};

/// The longest plain tick label: a longer one (5000000000000001830474) is scientific (5e21).
const PLAIN_LABEL: usize = 6;

/// The prefix of an axis reaching `magnitude` (SI): the engineering one, or none beyond f … T,
/// whose labels are then scientific in the bare unit (`F [N]`, `1e100`) rather than `[TN]`.
fn axis_prefix(magnitude: f64, unit: Unit) -> Prefix {
    let prefix = units::engineering_prefix(magnitude, unit);
    let in_prefix = magnitude.abs() / (prefix.factor * unit.si_per_unit);
    if prefix != units::NONE && !(1.0 - 1e-9..1000.0).contains(&in_prefix) {
        units::NONE
    } else {
        prefix
    }
}

/// An axis ready for a chart: bounds and labels in display units, and the unit's prefix.
#[derive(Debug, Clone, PartialEq)]
pub struct NiceAxis {
    /// Bounds in display units (SI value / prefix factor / unit size).
    pub bounds: [f64; 2],
    pub labels: Vec<String>,
    pub prefix: Prefix,
    /// SI value of one display unit: divide SI values by it to plot them.
    pub scale: f64,
    /// Plotted as log₁₀ of the display value.
    pub log: bool,
}

impl NiceAxis {
    /// This axis for a [`Chart`](crate::chart::Chart): its labels at their values (evenly over
    /// the bounds, linear or in log₁₀).
    pub fn chart_axis(&self, title: String) -> crate::chart::Axis {
        let [lo, hi] = self.bounds;
        let intervals = self.labels.len().saturating_sub(1).max(1) as f64;
        crate::chart::Axis {
            title,
            range: self.bounds,
            log: self.log,
            ticks: self
                .labels
                .iter()
                .enumerate()
                .map(|(i, label)| crate::chart::Tick {
                    at: lo + (hi - lo) * i as f64 / intervals,
                    label: label.clone(),
                })
                .collect(),
        }
    }

    /// Where an SI value goes on this axis (non-finite where a log axis has no place for it).
    pub fn to_display(&self, value_si: f64) -> f64 {
        let value = value_si / self.scale;
        if self.log { value.log10() } else { value }
    }
}

/// The smallest and largest finite values of `values` (`None` without any): what an axis spans.
pub fn span(values: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    values
        .filter(|v| v.is_finite())
        .fold(None, |acc, v| match acc {
            None => Some((v, v)),
            Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
        })
}

/// `symbol [unit]` in `axis`'s prefix, or the bare symbol of a dimensionless quantity.
pub fn axis_title(symbol: &str, axis: &NiceAxis, unit: Unit) -> String {
    let text = format!("{}{}", axis.prefix.symbol, unit.symbol);
    if text.is_empty() {
        symbol.to_string()
    } else {
        format!("{symbol} [{text}]")
    }
}

/// A log axis covering [lo, hi] (SI, both > 0) with at most `max_labels` labels (at least 2): the
/// bounds are log₁₀ of display values. A range of whole decades (v₀/100 … 10·v₀) is the axis
/// itself, labelled every decade or few from `lo`; any other range is widened to whole decades of
/// the unit and labelled at them.
pub fn log_axis(lo: f64, hi: f64, unit: Unit, max_labels: usize) -> NiceAxis {
    let (lo, hi) = if lo > 0.0 && hi >= lo && hi.is_finite() {
        (lo, hi)
    } else {
        (1.0, 10.0)
    };
    let prefix = axis_prefix(hi, unit);
    let scale = prefix.factor * unit.si_per_unit;
    let max_intervals = (max_labels.max(2) - 1) as f64;
    let decades = (hi / lo).log10();
    let whole = decades.round();
    if whole >= 1.0 && (decades - whole).abs() < 1e-9 {
        let per_label = (whole / max_intervals).ceil();
        if whole % per_label == 0.0 {
            let first = (lo / scale).log10();
            let intervals = (whole / per_label) as usize;
            let labels = (0..=intervals)
                .map(|i| units::sig(lo / scale * 10f64.powf(i as f64 * per_label), 3))
                .collect();
            return NiceAxis {
                bounds: [first, first + whole],
                labels,
                prefix,
                scale,
                log: true,
            };
        }
    }
    let first = ((lo / scale).log10() + 1e-9).floor();
    let mut last = ((hi / scale).log10() - 1e-9).ceil();
    if last <= first {
        last = first + 1.0;
    }
    let decades_per_label = ((last - first) / max_intervals).ceil().max(1.0);
    let intervals = ((last - first) / decades_per_label).ceil();
    let last = first + intervals * decades_per_label;
    let labels = (0..=intervals as usize)
        .map(|i| units::sig(10f64.powf(first + i as f64 * decades_per_label), 3))
        .collect();
    NiceAxis {
        bounds: [first, last],
        labels,
        prefix,
        scale,
        log: true,
    }
}

const MANTISSAS: [f64; 4] = [1.0, 2.0, 2.5, 5.0];

/// An axis covering [lo, hi] (SI) with at most `max_labels` labels (at least 2).
pub fn nice_axis(lo: f64, hi: f64, unit: Unit, max_labels: usize) -> NiceAxis {
    let (lo, hi) = if lo.is_finite() && hi.is_finite() && lo <= hi {
        (lo, hi)
    } else {
        (0.0, 0.0)
    };
    let prefix = axis_prefix(lo.abs().max(hi.abs()), unit);
    let scale = prefix.factor * unit.si_per_unit;
    let (mut a, mut b) = (lo / scale, hi / scale);
    if b - a <= f64::EPSILON * a.abs().max(b.abs()).max(1e-300) {
        // A flat range: open it around the value (or 0..1 for zero).
        let half = if a == 0.0 { 0.5 } else { a.abs() * 0.5 };
        a -= half;
        b += half;
        if lo >= 0.0 {
            a = a.max(0.0);
        }
    }
    let max_intervals = max_labels.max(2) - 1;
    let step = nice_step(a, b, max_intervals);
    let first = (a / step + 1e-12).floor();
    let last = (b / step - 1e-12).ceil();
    let count = (last - first) as usize;
    let decimals = decimals_of(step);
    let values: Vec<f64> = (0..=count)
        .map(|i| {
            let value = (first + i as f64) * step;
            if value.abs() < step * 1e-9 {
                0.0
            } else {
                value
            }
        })
        .collect();
    let mut wrong = false;
    // A label read back off its tick must be the tick's value (to a millionth of a step): not so
    // on a step far below 1e-12, printed with no decimals.
    let mut labels: Vec<String> = values
        .iter()
        .map(|&value| {
            let label = format!("{value:.decimals$}");
            wrong |= label
                .parse::<f64>()
                .is_ok_and(|shown| (shown - value).abs() > step * 1e-6);
            wrong |= label.chars().count() > PLAIN_LABEL;
            label
        })
        .collect();
    if wrong {
        // Scientific by the shared formatter, with the digits that tell the ticks apart.
        let largest = values.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let digits = (largest.log10().floor() - step.log10().floor()).max(0.0) as usize
            + if decimals_of(step / 10f64.powf(step.log10().floor())) > 0 {
                2
            } else {
                1
            };
        labels = values
            .iter()
            .map(|&v| format::scientific(v, digits, Zeros::Trim))
            .collect();
    }
    NiceAxis {
        bounds: [first * step, last * step],
        labels,
        prefix,
        scale,
        log: false,
    }
}

/// The round step whose outward-rounded ticks cover [a, b] in at most `max_intervals` with the
/// least wasted range (then the most ticks); two intervals at least when the range crosses zero,
/// since zero is always a tick.
fn nice_step(a: f64, b: f64, max_intervals: usize) -> f64 {
    let max_intervals = if a < 0.0 && b > 0.0 {
        max_intervals.max(2)
    } else {
        max_intervals
    };
    let raw = (b - a) / max_intervals as f64;
    let first_exponent = raw.log10().floor() as i32;
    let mut best: Option<(f64, f64)> = None;
    // Steps from the raw step up to 100× it: a step of 10× the raw step always fits.
    for exponent in first_exponent..first_exponent + 3 {
        for mantissa in MANTISSAS {
            let step = mantissa * 10f64.powi(exponent);
            let count = intervals(a, b, step);
            if step < raw * (1.0 - 1e-12) || count > max_intervals as f64 {
                continue;
            }
            let covered = count * step;
            // Strictly less range wins; on a tie the smaller step (more ticks) found first stays.
            if best.is_none_or(|(_, c)| covered < c * (1.0 - 1e-9)) {
                best = Some((step, covered));
            }
        }
    }
    best.map_or(10f64.powi(first_exponent + 3), |(step, _)| step)
}

fn intervals(a: f64, b: f64, step: f64) -> f64 {
    (b / step - 1e-12).ceil() - (a / step + 1e-12).floor()
}

/// Decimals needed to print multiples of `step` exactly (2.5 → 1, 0.25 → 2, 20 → 0).
fn decimals_of(step: f64) -> usize {
    (0..12)
        .find(|&d| {
            let scaled = step * 10f64.powi(d);
            (scaled - scaled.round()).abs() < 1e-6 * scaled.max(1.0)
        })
        .unwrap_or(12) as usize
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::format::units::{METRE, METRE_PER_SECOND, NEWTON, PASCAL, SECOND};

    fn values(axis: &NiceAxis) -> Vec<f64> {
        axis.labels.iter().map(|l| l.parse().unwrap()).collect()
    }

    /// Labels are evenly spaced over the bounds, so they must be the arithmetic sequence.
    fn assert_labels_on_ticks(axis: &NiceAxis) {
        let v = values(axis);
        let n = v.len() - 1;
        for (i, value) in v.iter().enumerate() {
            let expected = axis.bounds[0] + (axis.bounds[1] - axis.bounds[0]) * i as f64 / n as f64;
            assert!((value - expected).abs() < 1e-9 * axis.bounds[1].abs().max(1.0));
        }
    }

    #[test]
    fn micrometres_for_fig5_displacements() {
        let axis = nice_axis(0.0, 9.112e-6, METRE, 6);
        assert_eq!(axis.prefix.symbol, "µ");
        assert_eq!(axis.labels, ["0", "2", "4", "6", "8", "10"]);
        assert_eq!(axis.bounds, [0.0, 10.0]);
        assert!(axis.bounds[1] * axis.scale >= 9.112e-6);
        assert_labels_on_ticks(&axis);
    }

    #[test]
    fn velocities_span_zero() {
        let axis = nice_axis(-0.2134, 0.3, METRE_PER_SECOND, 8);
        assert_eq!(axis.prefix.symbol, "");
        assert_eq!(
            axis.labels,
            ["-0.3", "-0.2", "-0.1", "0.0", "0.1", "0.2", "0.3"]
        );
        assert_labels_on_ticks(&axis);
        assert!(values(&axis).contains(&0.0));
        assert!(axis.bounds[0] * axis.scale <= -0.2134 && axis.bounds[1] * axis.scale >= 0.3);
    }

    #[test]
    fn label_budget_is_respected() {
        for max in 2..10 {
            for (lo, hi, unit) in [
                (0.0, 403.3, NEWTON),
                (0.0, 8.92e-5, SECOND),
                (-0.21, 0.3, METRE_PER_SECOND),
                (0.0, 4.0e4, NEWTON),
                (1.0, 1.0, NEWTON),
            ] {
                let axis = nice_axis(lo, hi, unit, max);
                // A range across zero needs three labels at least: zero is a tick.
                let budget = if lo < 0.0 && hi > 0.0 {
                    max.max(3)
                } else {
                    max
                };
                assert!(
                    axis.labels.len() <= budget && axis.labels.len() >= 2,
                    "{axis:?}"
                );
                assert!(
                    axis.bounds[0] * axis.scale <= lo + 1e-15,
                    "{lo} {hi} {max}: {axis:?}"
                );
                assert!(axis.bounds[1] * axis.scale >= hi - 1e-15);
                assert_labels_on_ticks(&axis);
            }
        }
    }

    #[test]
    fn steps_of_two_and_a_half_print_their_decimal() {
        let axis = nice_axis(0.0, 0.1, NEWTON, 5);
        assert_eq!(axis.prefix.symbol, "m");
        assert_eq!(axis.labels, ["0", "25", "50", "75", "100"]);
        let axis = nice_axis(0.0, 7.4, NEWTON, 4);
        assert_eq!(axis.labels, ["0.0", "2.5", "5.0", "7.5"]);
    }

    #[test]
    fn the_least_wasted_range_wins() {
        // 403 N with three intervals: 0–500 by 250 rather than 0–600 by 200.
        let axis = nice_axis(0.0, 403.3, NEWTON, 4);
        assert_eq!(axis.labels, ["0", "250", "500"]);
        let axis = nice_axis(0.0, 403.3, NEWTON, 6);
        assert_eq!(axis.labels, ["0", "100", "200", "300", "400", "500"]);
    }

    #[test]
    fn log_axes_span_whole_decades_of_the_display_unit() {
        // A v₀ sweep from 3 mm/s to 3 m/s: three whole decades, the axis itself.
        let axis = log_axis(0.003, 3.0, METRE_PER_SECOND, 8);
        assert!((axis.bounds[0] - 0.003f64.log10()).abs() < 1e-12);
        assert!((axis.bounds[1] - 3f64.log10()).abs() < 1e-12);
        assert_eq!(axis.labels, ["0.003", "0.03", "0.3", "3"]);
        assert_eq!(
            log_axis(0.003, 3.0, METRE_PER_SECOND, 2).labels,
            ["0.003", "3"]
        );
        // Otherwise widened to whole decades, labels at each.
        let axis = log_axis(0.002, 3.0, METRE_PER_SECOND, 8);
        assert_eq!(axis.bounds, [-3.0, 1.0]);
        assert_eq!(axis.labels, ["0.001", "0.01", "0.1", "1", "10"]);
        assert!((axis.to_display(0.3) - 0.3f64.log10()).abs() < 1e-12);
        assert!(axis.to_display(0.0).is_infinite() && axis.to_display(-1.0).is_nan());
        // With few labels, several decades per label, still on whole decades.
        let axis = log_axis(2e-6, 9e-2, METRE, 3);
        assert_eq!(axis.prefix.symbol, "m");
        assert_eq!(axis.bounds, [-3.0, 3.0]);
        assert_eq!(axis.labels, ["0.001", "1", "1000"]);
        // Whole decades are not widened; degenerate input still gives an axis.
        assert_eq!(log_axis(1e9, 1e11, PASCAL, 5).bounds, [0.0, 2.0]);
        assert_eq!(log_axis(1e9, 1e11, PASCAL, 5).labels, ["1", "10", "100"]);
        let flat = log_axis(5.0, 5.0, NEWTON, 5);
        assert!(flat.bounds[1] > flat.bounds[0]);
        let bad = log_axis(-1.0, f64::NAN, NEWTON, 5);
        assert!(bad.bounds[1] > bad.bounds[0]);
    }

    #[test]
    fn extreme_ranges_label_in_scientific_notation_in_the_bare_unit() {
        for (hi, unit) in [
            (1e100, NEWTON),
            (5.3e21, NEWTON),
            (3.2e-30, METRE),
            (7e15, METRE_PER_SECOND),
        ] {
            for max in 2..10 {
                let axis = nice_axis(0.0, hi, unit, max);
                assert_eq!(axis.prefix.symbol, "", "{hi}: {axis:?}");
                assert!(
                    axis.labels.iter().all(|l| l.chars().count() <= 8),
                    "{hi}: {axis:?}"
                );
                assert!(axis.labels.iter().any(|l| l.contains('e')), "{axis:?}");
                assert_labels_on_ticks(&axis);
                assert!(axis.bounds[1] * axis.scale >= hi * (1.0 - 1e-12));
            }
        }
        let axis = nice_axis(0.0, 1e100, NEWTON, 6);
        assert_eq!(axis.labels, ["0", "2e99", "4e99", "6e99", "8e99", "1e100"]);
        let axis = log_axis(1e90, 1e100, NEWTON, 6);
        assert_eq!(axis.prefix.symbol, "");
        assert!(
            axis.labels.iter().all(|l| l.chars().count() <= 6),
            "{axis:?}"
        );
    }

    #[test]
    fn degenerate_ranges_still_give_an_axis() {
        let axis = nice_axis(0.0, 0.0, NEWTON, 5);
        assert!(axis.bounds[1] > axis.bounds[0]);
        let axis = nice_axis(f64::NAN, 1.0, NEWTON, 5);
        assert!(axis.bounds[1] > axis.bounds[0]);
    }
}
