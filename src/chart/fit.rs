//! The fit's charts as plain descriptions (docs/fitting.md): measured e against v₀ with its
//! error bars and every fitted law's curve in the law's own style, the residuals, and the
//! engines' realised e(v₀) against the same data.

use crate::chart::ticks::{self, NiceAxis, log_axis, nice_axis};
use crate::chart::{Chart, Hue, Ink, Mark, Rule, Series, model_glyph};
use crate::format::units::{DIMENSIONLESS, METRE_PER_SECOND};
use crate::model::ForceModel;
use crate::model::fit::{Candidate, LawFit, RestitutionData};

/// The glyph of a measured point.
pub const DATA_GLYPH: char = 'O';
/// The glyph of Newton's constant e, which is no law of the table.
pub const CONSTANT_E_GLYPH: char = 'E';

/// The residuals panel shows the laws within this Δ of the best (Burnham & Anderson's "much less
/// supported" bound), at most [`MAX_RESIDUALS`] of them: the others' misfit would set its scale.
pub const RESIDUALS_WITHIN: f64 = 10.0;
pub const MAX_RESIDUALS: usize = 5;

/// One measured point: v₀ (m/s), e and its standard deviation where known.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Point {
    pub v: f64,
    pub e: f64,
    pub sd: Option<f64>,
}

/// The measured points as the charts take them.
pub fn points(data: &RestitutionData) -> Vec<Point> {
    data.points
        .iter()
        .map(|p| Point {
            v: p.v,
            e: p.e,
            sd: p.sd,
        })
        .collect()
}

/// A curve e(v₀) or r(v₀) of one fitted law (or engine), and how it is drawn.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    pub name: String,
    pub ink: Ink,
    pub glyph: char,
    /// (v₀ in m/s, value), in order of v₀.
    pub points: Vec<(f64, f64)>,
    /// The best-ranked law: drawn last and bold.
    pub focused: bool,
}

impl Curve {
    /// A fitted candidate in its style: a law's own, or constant e's.
    pub fn of(candidate: Candidate, points: Vec<(f64, f64)>) -> Curve {
        match candidate {
            Candidate::ConstantE => Curve::constant_e(points),
            Candidate::Law(m) => Curve::law(m, points),
        }
    }

    /// A law of the table in its own hue, pattern and glyph.
    pub fn law(model: ForceModel, points: Vec<(f64, f64)>) -> Curve {
        Curve {
            name: model.name().to_string(),
            ink: Ink::Model(model),
            glyph: model_glyph(model),
            points,
            focused: false,
        }
    }

    /// Newton's constant e, in the foreground's colour.
    pub fn constant_e(points: Vec<(f64, f64)>) -> Curve {
        Curve {
            name: "constant-e".to_string(),
            ink: Ink::Plain(Hue::Foreground),
            glyph: CONSTANT_E_GLYPH,
            points,
            focused: false,
        }
    }
}

/// The v₀ axis over the data's span with a margin of a fifth of a decade each side (log when
/// the data spans more than a factor of 3).
pub fn velocity_axis(data: &[Point], max_labels: usize) -> NiceAxis {
    let (lo, hi) = span(data.iter().map(|p| p.v));
    if hi > 3.0 * lo {
        log_axis(lo / 1.6, hi * 1.6, METRE_PER_SECOND, max_labels)
    } else {
        let pad = 0.1 * (hi - lo).max(0.1 * hi);
        nice_axis((lo - pad).max(0.0), hi + pad, METRE_PER_SECOND, max_labels)
    }
}

/// The v₀ values a curve is sampled at: `n` over the velocity axis's range.
pub fn sample_velocities(axis: &NiceAxis, n: usize) -> Vec<f64> {
    let n = n.max(2);
    let [a, b] = axis.bounds;
    (0..n)
        .map(|i| {
            let d = a + (b - a) * i as f64 / (n - 1) as f64;
            let v = if axis.log { 10f64.powf(d) } else { d };
            v * axis.scale
        })
        .filter(|v| *v > 0.0)
        .collect()
}

/// The finite values' span, (∞, −∞) without any.
fn span(values: impl Iterator<Item = f64>) -> (f64, f64) {
    ticks::span(values).unwrap_or((f64::INFINITY, f64::NEG_INFINITY))
}

/// The data as a series of error bars (one run per point with a standard deviation) and a
/// mark at each point.
fn data_layer(data: &[Point], x: &NiceAxis, y: &NiceAxis) -> (Option<Series>, Vec<Mark>) {
    let bars: Vec<Vec<(f64, f64)>> = data
        .iter()
        .filter_map(|p| {
            let sd = p.sd?;
            let at = x.to_display(p.v);
            Some(vec![
                (at, y.to_display(p.e - sd)),
                (at, y.to_display(p.e + sd)),
            ])
        })
        .collect();
    let marks = data
        .iter()
        .map(|p| Mark {
            at: (x.to_display(p.v), y.to_display(p.e)),
            ink: Ink::Foreground,
            glyph: DATA_GLYPH,
            label: None,
        })
        .collect();
    let series = (!bars.is_empty()).then(|| Series {
        name: "data ± sd".to_string(),
        ink: Ink::Foreground,
        glyph: '|',
        runs: bars,
        focused: false,
        peak: None,
        steps: false,
    });
    (series, marks)
}

fn curve_series(curves: &[Curve], x: &NiceAxis, y: &NiceAxis) -> Vec<Series> {
    let mut series: Vec<Series> = curves
        .iter()
        .map(|c| Series {
            name: c.name.clone(),
            ink: c.ink,
            glyph: c.glyph,
            runs: vec![
                c.points
                    .iter()
                    .filter(|p| p.0.is_finite() && p.1.is_finite())
                    .map(|&(v, e)| (x.to_display(v), y.to_display(e)))
                    .collect(),
            ],
            focused: c.focused,
            peak: None,
            steps: false,
        })
        .collect();
    series.sort_by_key(|s| s.focused);
    series
}

/// Measured e against v₀ with error bars, and each curve; `title` says what the curves are.
pub fn restitution_chart(
    title: String,
    data: &[Point],
    curves: &[Curve],
    (max_x, max_y): (usize, usize),
) -> Chart {
    let x = velocity_axis(data, max_x);
    let in_view = |v: f64| {
        let d = x.to_display(v);
        d >= x.bounds[0] && d <= x.bounds[1]
    };
    let (lo, hi) = span(
        data.iter()
            .flat_map(|p| [p.e - p.sd.unwrap_or(0.0), p.e + p.sd.unwrap_or(0.0)])
            .chain(
                curves
                    .iter()
                    .flat_map(|c| c.points.iter().filter(|p| in_view(p.0)).map(|p| p.1)),
            ),
    );
    let pad = 0.05 * (hi - lo).max(0.02);
    let y = nice_axis(
        (lo - pad).max(0.0),
        (hi + pad).min(1.05),
        DIMENSIONLESS,
        max_y.min(8),
    );
    let (bars, marks) = data_layer(data, &x, &y);
    let mut series: Vec<Series> = bars.into_iter().collect();
    series.extend(curve_series(curves, &x, &y));
    let unit = format!("{}{}", x.prefix.symbol, METRE_PER_SECOND.symbol);
    Chart {
        title,
        x: x.chart_axis(format!("v₀ [{unit}]")),
        y: y.chart_axis("e".to_string()),
        series,
        marks,
        rules: Vec::new(),
        notes: Vec::new(),
        readout: None,
    }
}

/// The residuals of the ranked `fits` (best first, and focused) at the measured `data`, in order
/// of v₀: the best's, and the others' within Δ ≤ [`RESIDUALS_WITHIN`] of it, at most
/// [`MAX_RESIDUALS`] in all.
pub fn residual_curves(data: &[Point], fits: &[LawFit]) -> Vec<Curve> {
    let mut residuals = Vec::new();
    for (i, fit) in fits.iter().enumerate() {
        if i > 0 && (fit.delta > RESIDUALS_WITHIN || residuals.len() >= MAX_RESIDUALS) {
            continue;
        }
        let mut at: Vec<(f64, f64)> = data
            .iter()
            .zip(&fit.residuals)
            .map(|(p, r)| (p.v, *r))
            .collect();
        at.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut r = Curve::of(fit.candidate, at);
        r.focused = i == 0;
        residuals.push(r);
    }
    residuals
}

/// Residuals e_law − e_measured at each measured v₀, one line per law through its points, a rule
/// at 0 and, with standard deviations, error bars around 0.
pub fn residual_chart(
    data: &[Point],
    residuals: &[Curve],
    (max_x, max_y): (usize, usize),
) -> Chart {
    let x = velocity_axis(data, max_x);
    let (lo, hi) = span(
        residuals
            .iter()
            .flat_map(|c| c.points.iter().map(|p| p.1))
            .chain(data.iter().filter_map(|p| p.sd).flat_map(|s| [-s, s])),
    );
    let reach = lo.abs().max(hi.abs()).max(1e-6) * 1.1;
    let y = nice_axis(-reach, reach, DIMENSIONLESS, max_y.min(7));
    let unit = format!("{}{}", x.prefix.symbol, METRE_PER_SECOND.symbol);
    let mut series = Vec::new();
    let bars: Vec<Vec<(f64, f64)>> = data
        .iter()
        .filter_map(|p| {
            let sd = p.sd?;
            let at = x.to_display(p.v);
            Some(vec![(at, y.to_display(-sd)), (at, y.to_display(sd))])
        })
        .collect();
    if !bars.is_empty() {
        series.push(Series {
            name: "± sd".to_string(),
            ink: Ink::Foreground,
            glyph: '|',
            runs: bars,
            focused: false,
            peak: None,
            steps: false,
        });
    }
    series.extend(curve_series(residuals, &x, &y));
    Chart {
        rules: vec![Rule {
            at: 0.0,
            horizontal: true,
            ink: Ink::Foreground,
            label: "0".to_string(),
        }],
        ..Chart::new(
            "residuals e law − e measured".to_string(),
            x.chart_axis(format!("v₀ [{unit}]")),
            y.chart_axis("residual".to_string()),
            series,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn data() -> Vec<Point> {
        [(0.1, 0.9, 0.01), (0.5, 0.8, 0.02), (1.0, 0.7, 0.01)]
            .map(|(v, e, sd)| Point { v, e, sd: Some(sd) })
            .to_vec()
    }

    /// Read back through the axes: a point's mark sits where its tick labels say.
    #[test]
    fn marks_and_bars_read_back_through_the_ticks() {
        let chart = restitution_chart("t".into(), &data(), &[], (8, 8));
        assert!(chart.x.log, "a decade of data is drawn on a log axis");
        let m = &chart.marks[1];
        let v = 10f64.powf(m.at.0);
        assert!((v - 0.5).abs() < 1e-12, "{v}");
        assert!((m.at.1 - 0.8).abs() < 1e-12);
        let bars = &chart.series[0];
        assert_eq!(bars.runs.len(), 3);
        assert!((bars.runs[1][1].1 - 0.82).abs() < 1e-12);
        for p in data() {
            assert!(chart.y.fraction(p.e - 0.02) >= 0.0 && chart.y.fraction(p.e + 0.02) <= 1.0);
        }
    }

    #[test]
    fn every_curve_is_drawn_in_its_laws_style_and_residuals_straddle_zero() {
        let hc = ForceModel::HuntCrossley;
        let c = Curve::law(hc, vec![(0.1, 0.9), (1.0, 0.7)]);
        let chart = restitution_chart("t".into(), &data(), &[c], (8, 8));
        let s = chart
            .series
            .iter()
            .find(|s| s.name == "hunt-crossley")
            .unwrap();
        assert_eq!((s.ink, s.glyph), (Ink::Model(hc), model_glyph(hc)));
        let r = Curve::law(hc, vec![(0.1, -0.01), (1.0, 0.03)]);
        let res = residual_chart(&data(), &[r], (8, 8));
        assert!(res.y.range[0] < -0.03 && res.y.range[1] > 0.03);
        assert_eq!(res.rules[0].at, 0.0);
    }
}
