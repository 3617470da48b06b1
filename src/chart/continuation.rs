//! The charts of continuation (docs/continuation.md): a branch of periodic orbits, stable parts
//! as lines and unstable parts dotted, special points marked and labelled, over the brute-force
//! diagram when there is one; and a two-parameter curve of special points, one line per stop.
//!
//! The builders take plain data in SI units ([`BranchCurve`]), like [`super::system`]'s. A doubled
//! branch (born at a period doubling) has a look of its own: its stable stretches dashed and
//! [`DOUBLED_GLYPH`], so that it reads apart from the branch it was born on in the same ink.

use crate::chart::system::{Approach, Branch, DiagramAxes};
use crate::chart::ticks::{axis_title, nice_axis, span};
use crate::chart::{Chart, Ink, Mark, Series};

/// Dots of an unstable stretch across the x axis: dense enough to read as a dotted line.
const DOTS: f64 = 240.0;

/// Dashes of a doubled branch's stable stretch across the plot (a figure's; a terminal asks for
/// fewer, [`BranchCurve::dashes`]).
pub const DASHES: usize = 60;

/// The glyph of a doubled branch: none of the laws' glyphs, nor the rigid stop's.
pub const DOUBLED_GLYPH: char = 'D';

/// One stop's branch: per impact of the orbit, the runs of (parameter, v_in) of one stability,
/// and the special points (parameter, v_in, label).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct BranchCurve {
    /// What tells it from the stop's other branches in the legend (`period-2`), if anything.
    pub label: String,
    /// Born at a period doubling: drawn in the doubled branch's look (stable stretches dashed,
    /// [`DOUBLED_GLYPH`]).
    pub doubled: bool,
    /// Dashes of its stable stretches across the plot when doubled (0: [`DASHES`]).
    pub dashes: usize,
    /// (stable, points) in the order of the arclength.
    pub runs: Vec<(bool, Vec<(f64, f64)>)>,
    pub specials: Vec<(f64, f64, String)>,
}

impl BranchCurve {
    /// Splits the points (parameter, value, stable) of one impact's curve into runs of one
    /// stability; a run ends on the first point of the next so that the line is unbroken.
    pub fn push_impact(&mut self, points: &[(f64, f64, bool)]) {
        let mut run: Vec<(f64, f64)> = Vec::new();
        let mut stable = points.first().is_some_and(|p| p.2);
        for &(x, y, s) in points {
            if s != stable && !run.is_empty() {
                run.push((x, y));
                self.runs.push((stable, std::mem::take(&mut run)));
                stable = s;
            }
            run.push((x, y));
        }
        if !run.is_empty() {
            self.runs.push((stable, run));
        }
    }
}

/// The points of a run as dots every `step` along x (a dotted line in every renderer).
fn dotted(run: &[(f64, f64)], step: f64) -> Vec<Vec<(f64, f64)>> {
    let mut dots = Vec::new();
    for pair in run.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        let length = (b.0 - a.0).abs();
        let count = (length / step).ceil().max(1.0) as usize;
        for i in 0..count {
            let f = i as f64 / count as f64;
            dots.push(vec![(a.0 + f * (b.0 - a.0), a.1 + f * (b.1 - a.1))]);
        }
    }
    if let Some(&last) = run.last() {
        dots.push(vec![last]);
    }
    dots
}

/// The points of a run as dashes, each a run of its own: two thirds of every `period` of its
/// length drawn, the length measured in fractions of the axes' spans `scale` (so that a steep
/// stretch is dashed like a flat one).
fn dashed(run: &[(f64, f64)], period: f64, scale: (f64, f64)) -> Vec<Vec<(f64, f64)>> {
    let on = period * 2.0 / 3.0;
    let mut dashes = Vec::new();
    let mut dash: Vec<(f64, f64)> = run.first().copied().into_iter().collect();
    // Drawing a dash or leaving a gap, and the length left of it.
    let (mut drawing, mut left) = (true, on);
    for pair in run.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        let length = ((b.0 - a.0) / scale.0).hypot((b.1 - a.1) / scale.1);
        if !(length.is_finite() && length > 0.0) {
            continue;
        }
        let mut done = 0.0;
        loop {
            let rest = length - done;
            if left > rest {
                left -= rest;
                if drawing {
                    dash.push(b);
                }
                break;
            }
            done += left;
            let f = done / length;
            let p = (a.0 + f * (b.0 - a.0), a.1 + f * (b.1 - a.1));
            dash.push(p);
            if drawing {
                dashes.push(std::mem::take(&mut dash));
            }
            drawing = !drawing;
            left = if drawing { on } else { period - on };
        }
    }
    if drawing && dash.len() > 1 {
        dashes.push(dash);
    }
    dashes
}

fn series(
    name: String,
    ink: Ink,
    glyph: char,
    runs: Vec<Vec<(f64, f64)>>,
    focused: bool,
) -> Series {
    Series {
        name,
        ink,
        glyph,
        runs,
        focused,
        peak: None,
        steps: false,
    }
}

/// The branches of `curves` (v_in against the key of `axes`) over the brute-force `diagram`.
pub fn branch(
    curves: &[(Approach, &BranchCurve)],
    diagram: &[(Approach, &Branch)],
    axes: &DiagramAxes,
    (max_x, max_y): (usize, usize),
) -> Chart {
    let xs = curves
        .iter()
        .flat_map(|(_, c)| c.runs.iter().flat_map(|r| r.1.iter().map(|p| p.0)))
        .chain(
            diagram
                .iter()
                .flat_map(|(_, b)| b.columns.iter().map(|c| c.0)),
        );
    let ys = curves
        .iter()
        .flat_map(|(_, c)| c.runs.iter().flat_map(|r| r.1.iter().map(|p| p.1)))
        .chain(
            diagram
                .iter()
                .flat_map(|(_, b)| b.columns.iter().flat_map(|c| c.1.iter().copied())),
        );
    let (x0, x1) = axes.range.or_else(|| span(xs)).unwrap_or((0.0, 1.0));
    let (y0, y1) = span(ys).unwrap_or((0.0, 1.0));
    let kx = nice_axis(x0, x1, axes.key_unit, max_x);
    let py = nice_axis(y0.min(0.0), y1.max(0.0), axes.quantity_unit, max_y);
    let at = |p: (f64, f64)| (kx.to_display(p.0), py.to_display(p.1));
    let step = (kx.bounds[1] - kx.bounds[0]).abs() / DOTS;
    let mut all = Vec::new();
    for (approach, b) in diagram {
        let (name, ink, _) = approach.look();
        let points = b
            .columns
            .iter()
            .flat_map(|(k, ps)| ps.iter().map(move |&p| (*k, p)))
            .filter(|p| p.0.is_finite() && p.1.is_finite())
            .map(|p| vec![at(p)])
            .collect();
        all.push(series(format!("{name} diagram"), ink, '.', points, false));
    }
    let mut marks = Vec::new();
    let scale = (
        (kx.bounds[1] - kx.bounds[0]).abs(),
        (py.bounds[1] - py.bounds[0]).abs(),
    );
    for (approach, c) in curves {
        let (name, ink, glyph) = approach.look();
        let glyph = if c.doubled { DOUBLED_GLYPH } else { glyph };
        let name = if c.label.is_empty() {
            name
        } else {
            format!("{name} {}", c.label)
        };
        let focused = *approach == Approach::Rigid;
        let stable_runs = c
            .runs
            .iter()
            .filter(|r| r.0)
            .map(|r| r.1.iter().map(|&p| at(p)).collect::<Vec<_>>());
        let stable: Vec<_> = if c.doubled {
            let dashes = if c.dashes == 0 { DASHES } else { c.dashes };
            let period = 1.0 / dashes as f64;
            stable_runs
                .flat_map(|r| dashed(&r, period, scale))
                .collect()
        } else {
            stable_runs.collect()
        };
        let unstable: Vec<_> = c
            .runs
            .iter()
            .filter(|r| !r.0)
            .flat_map(|r| dotted(&r.1.iter().map(|&p| at(p)).collect::<Vec<_>>(), step))
            .collect();
        if !stable.is_empty() {
            all.push(series(
                format!("{name} stable"),
                ink,
                glyph,
                stable,
                focused,
            ));
        }
        if !unstable.is_empty() {
            all.push(series(
                format!("{name} unstable"),
                ink,
                ':',
                unstable,
                false,
            ));
        }
        for (x, y, label) in &c.specials {
            marks.push(Mark {
                at: at((*x, *y)),
                ink,
                glyph: '×',
                label: Some(label.clone()),
            });
        }
    }
    all.sort_by_key(|s| s.focused);
    Chart {
        title: format!("periodic orbits over {}", axes.key),
        x: kx.chart_axis(axis_title(&axes.key, &kx, axes.key_unit)),
        y: py.chart_axis(axis_title(&axes.quantity, &py, axes.quantity_unit)),
        series: all,
        marks,
        rules: Vec::new(),
        notes: Vec::new(),
        readout: None,
    }
}

/// Two-parameter curves of one kind of special point: `first` (the continued key, y) against
/// `second` (x), a line per stop.
pub fn curves(
    curves: &[(Approach, &[(f64, f64)])],
    kind: &str,
    (first, second): (&DiagramAxes, &DiagramAxes),
    (max_x, max_y): (usize, usize),
) -> Chart {
    let (x0, x1) =
        span(curves.iter().flat_map(|(_, c)| c.iter().map(|p| p.1))).unwrap_or((0.0, 1.0));
    let (y0, y1) =
        span(curves.iter().flat_map(|(_, c)| c.iter().map(|p| p.0))).unwrap_or((0.0, 1.0));
    let kx = nice_axis(x0, x1, second.key_unit, max_x);
    let ky = nice_axis(y0, y1, first.key_unit, max_y);
    let mut all: Vec<Series> = curves
        .iter()
        .map(|(approach, c)| {
            let (name, ink, glyph) = approach.look();
            let run = c
                .iter()
                .filter(|p| p.0.is_finite() && p.1.is_finite())
                .map(|&(y, x)| (kx.to_display(x), ky.to_display(y)))
                .collect();
            series(name, ink, glyph, vec![run], *approach == Approach::Rigid)
        })
        .collect();
    all.sort_by_key(|s| s.focused);
    Chart::new(
        format!("{kind} curve in ({}, {})", second.key, first.key),
        kx.chart_axis(axis_title(&second.key, &kx, second.key_unit)),
        ky.chart_axis(axis_title(&first.key, &ky, first.key_unit)),
        all,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::format::units;

    #[test]
    fn runs_split_at_a_change_of_stability_and_share_the_point() {
        let mut c = BranchCurve::default();
        c.push_impact(&[
            (1.0, 1.0, true),
            (2.0, 2.0, true),
            (3.0, 3.0, false),
            (4.0, 4.0, false),
        ]);
        assert_eq!(
            c.runs,
            vec![
                (true, vec![(1.0, 1.0), (2.0, 2.0), (3.0, 3.0)]),
                (false, vec![(3.0, 3.0), (4.0, 4.0)]),
            ]
        );
    }

    #[test]
    fn a_dashed_run_draws_two_thirds_of_each_period_along_its_length() {
        // A diagonal across both axes (length √2 in their fractions), then a step back along x.
        let run = [(0.0, 0.0), (2.0, 10.0), (1.0, 10.0)];
        let dashes = dashed(&run, 0.1, (2.0, 10.0));
        let length = |d: &Vec<(f64, f64)>| {
            d.windows(2)
                .map(|w| ((w[1].0 - w[0].0) / 2.0).hypot((w[1].1 - w[0].1) / 10.0))
                .sum::<f64>()
        };
        let total = 2f64.sqrt() + 0.5;
        assert_eq!(dashes.len(), (total / 0.1).ceil() as usize, "{dashes:?}");
        for d in &dashes[..dashes.len() - 1] {
            assert!((length(d) - 0.1 * 2.0 / 3.0).abs() < 1e-12, "{d:?}");
        }
        assert_eq!(dashes[0][0], (0.0, 0.0));
        // The dash across the corner keeps the corner.
        assert!(dashes.iter().any(|d| d.contains(&(2.0, 10.0))));
        let drawn: f64 = dashes.iter().map(length).sum();
        assert!(
            (drawn / total - 2.0 / 3.0).abs() < 0.05,
            "{drawn} of {total}"
        );
    }

    #[test]
    fn a_branch_places_its_points_and_marks_at_their_values() {
        let mut c = BranchCurve::default();
        c.push_impact(&[(1.0, 0.5, true), (2.0, 0.7, false), (3.0, 0.9, false)]);
        c.specials.push((1.5, 0.6, "PD".into()));
        let axes = DiagramAxes {
            key: "Γ".into(),
            key_unit: units::DIMENSIONLESS,
            quantity: "v_in".into(),
            quantity_unit: units::METRE_PER_SECOND,
            range: None,
        };
        let chart = branch(&[(Approach::Rigid, &c)], &[], &axes, (6, 6));
        let stable = chart
            .series
            .iter()
            .find(|s| s.name == "rigid stable")
            .unwrap();
        assert_eq!(stable.runs, vec![vec![(1.0, 0.5), (2.0, 0.7)]]);
        let unstable = chart
            .series
            .iter()
            .find(|s| s.name == "rigid unstable")
            .unwrap();
        assert!(unstable.runs.len() > 50, "dotted: {}", unstable.runs.len());
        assert_eq!(unstable.runs.first().unwrap(), &vec![(2.0, 0.7)]);
        assert_eq!(unstable.runs.last().unwrap(), &vec![(3.0, 0.9)]);
        assert_eq!(chart.marks[0].at, (1.5, 0.6));
    }
}
