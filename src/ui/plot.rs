//! Chart data: the solver's dense output sampled at the chart's resolution, in display units,
//! with the true peaks, and the dash patterns that keep curves apart without colour.

use crate::model::ForceModel;
use crate::model::impact::{ImpactSolution, Sample};

use super::app::ChartKind;
use super::theme::LinePattern;
use super::ticks::{NiceAxis, nice_axis};
use super::units::{self, Unit};

/// One solution's samples and its exact extrema, under a key that says whose they are (a force
/// model in the explorer; a method or the reference in the stability view).
#[derive(Debug, Clone, PartialEq)]
pub struct Series<K = ForceModel> {
    pub model: K,
    pub samples: Vec<Sample>,
    /// (x, F) at the force peak.
    pub force_peak_x: (f64, f64),
    /// (t, F) at the force peak.
    pub force_peak_t: (f64, f64),
    /// (x, v) at maximum compression (v = 0).
    pub deepest: (f64, f64),
}

impl<K> Series<K> {
    /// `n` samples of the solution (evenly in t, the true extrema inserted by the trajectory).
    pub fn sample(model: K, solution: &ImpactSolution, n: usize) -> Series<K> {
        let s = &solution.summary;
        let at_peak = solution.trajectory.at(s.t_f_max);
        Series {
            model,
            samples: solution.trajectory.samples(n),
            force_peak_x: (at_peak.x, s.f_max),
            force_peak_t: (s.t_f_max, s.f_max),
            deepest: (s.x_max, 0.0),
        }
    }
}

/// A curve in display units.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve<K = ForceModel> {
    pub model: K,
    pub points: Vec<(f64, f64)>,
    /// The extremum this chart marks (F_max or x_max), exact.
    pub peak: (f64, f64),
}

/// Everything a chart draws.
#[derive(Debug, Clone, PartialEq)]
pub struct Plot<K = ForceModel> {
    pub x: NiceAxis,
    pub y: NiceAxis,
    pub x_title: String,
    pub y_title: String,
    pub curves: Vec<Curve<K>>,
}

impl ChartKind {
    /// Title of the chart.
    pub fn title(self) -> &'static str {
        match self {
            ChartKind::ForceDisplacement => "F(x) force–approach",
            ChartKind::ForceTime => "F(t) force–time",
            ChartKind::VelocityDisplacement => "v(x) velocity–approach",
        }
    }

    fn axes(self) -> ((&'static str, Unit), (&'static str, Unit)) {
        match self {
            ChartKind::ForceDisplacement => (("x", units::METRE), ("F", units::NEWTON)),
            ChartKind::ForceTime => (("t", units::SECOND), ("F", units::NEWTON)),
            ChartKind::VelocityDisplacement => {
                (("x", units::METRE), ("v", units::METRE_PER_SECOND))
            }
        }
    }

    fn point(self, s: &Sample) -> (f64, f64) {
        match self {
            ChartKind::ForceDisplacement => (s.x, s.f),
            ChartKind::ForceTime => (s.t, s.f),
            ChartKind::VelocityDisplacement => (s.x, s.v),
        }
    }

    fn peak<K>(self, series: &Series<K>) -> (f64, f64) {
        match self {
            ChartKind::ForceDisplacement => series.force_peak_x,
            ChartKind::ForceTime => series.force_peak_t,
            ChartKind::VelocityDisplacement => series.deepest,
        }
    }
}

fn finite(p: &(f64, f64)) -> bool {
    p.0.is_finite() && p.1.is_finite()
}

/// The chart of `kind` over `series`, with at most the given numbers of axis labels. Non-finite
/// points are dropped (never drawn, never NaN on an axis).
pub fn plot<K: Copy>(
    kind: ChartKind,
    series: &[Series<K>],
    max_x_labels: usize,
    max_y_labels: usize,
) -> Plot<K> {
    // Curves in SI first, to find the ranges.
    let raw: Vec<Curve<K>> = series
        .iter()
        .map(|s| Curve {
            model: s.model,
            points: s
                .samples
                .iter()
                .map(|sample| kind.point(sample))
                .filter(finite)
                .collect(),
            peak: kind.peak(s),
        })
        .collect();
    let all = raw
        .iter()
        .flat_map(|c| c.points.iter().chain(std::iter::once(&c.peak)))
        .filter(|p| finite(p));
    // Axes always include 0: the contact starts at x = 0, t = 0 and F = 0.
    let (mut x_lo, mut x_hi, mut y_lo, mut y_hi) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for &(x, y) in all {
        x_lo = x_lo.min(x);
        x_hi = x_hi.max(x);
        y_lo = y_lo.min(y);
        y_hi = y_hi.max(y);
    }
    let ((x_name, x_unit), (y_name, y_unit)) = kind.axes();
    let x = nice_axis(x_lo, x_hi, x_unit, max_x_labels);
    let y = nice_axis(y_lo, y_hi, y_unit, max_y_labels);
    let to_display = |(px, py): (f64, f64)| (px / x.scale, py / y.scale);
    let curves = raw
        .into_iter()
        .map(|c| Curve {
            model: c.model,
            points: c.points.into_iter().map(to_display).collect(),
            peak: to_display(c.peak),
        })
        .collect();
    Plot {
        x_title: format!("{x_name} [{}{}]", x.prefix.symbol, x_unit.symbol),
        y_title: format!("{y_name} [{}{}]", y.prefix.symbol, y_unit.symbol),
        x,
        y,
        curves,
    }
}

/// A curve cut into the pieces of a line pattern: drawn runs and single dots.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Pieces {
    pub runs: Vec<Vec<(f64, f64)>>,
    pub dots: Vec<(f64, f64)>,
}

/// Largest gap between the points of a rastered run, in plot dots: one dot, so neighbours land in
/// the same or adjacent dots on either axis and the line has no hole, and no thicker than a line.
const RASTER_SPACING: f64 = 1.0;

impl Pieces {
    /// Every point the pattern draws, as one scatter: the runs filled in at most one plot dot
    /// apart, then the single dots. One dataset per curve, rather than one per dash, keeps a chart
    /// to a few canvas layers (ratatui allocates a whole grid per dataset).
    pub fn raster(&self, dots_per_x: f64, dots_per_y: f64) -> Vec<(f64, f64)> {
        let mut points = Vec::new();
        for run in &self.runs {
            points.extend(densify(run, dots_per_x, dots_per_y));
        }
        points.extend_from_slice(&self.dots);
        points
    }
}

/// `run` with points inserted so that neighbours are at most [`RASTER_SPACING`] plot dots apart.
fn densify(run: &[(f64, f64)], dots_per_x: f64, dots_per_y: f64) -> Vec<(f64, f64)> {
    let scaled =
        dots_per_x > 0.0 && dots_per_y > 0.0 && dots_per_x.is_finite() && dots_per_y.is_finite();
    if !scaled {
        return run.to_vec();
    }
    let mut out = Vec::with_capacity(run.len());
    for pair in run.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        let length = ((b.0 - a.0) * dots_per_x).hypot((b.1 - a.1) * dots_per_y);
        // A non-finite length (a point off to infinity) gets no fill: the ends only.
        let steps = if length.is_finite() {
            (length / RASTER_SPACING).ceil().clamp(1.0, 1e5) as usize
        } else {
            1
        };
        out.extend((0..steps).map(|k| {
            let s = k as f64 / steps as f64;
            (a.0 + (b.0 - a.0) * s, a.1 + (b.1 - a.1) * s)
        }));
    }
    out.extend(run.last().copied());
    out
}

/// Cuts `points` by `pattern`, measuring lengths in plot dots: `dots_per_x` and `dots_per_y` are
/// the dots per display unit of each axis.
pub fn dash(
    points: &[(f64, f64)],
    pattern: LinePattern,
    dots_per_x: f64,
    dots_per_y: f64,
) -> Pieces {
    let pieces = pattern.pieces();
    if pieces.is_empty() || !(dots_per_x > 0.0 && dots_per_y > 0.0) {
        return Pieces {
            runs: vec![points.to_vec()],
            dots: Vec::new(),
        };
    }
    let mut out = Pieces::default();
    let mut piece = 0;
    // (drawing?, length left in this state)
    let (mut drawing, mut left) = start_piece(pieces[0], &mut out, points.first().copied());
    let mut run: Vec<(f64, f64)> = Vec::new();
    if drawing {
        run.extend(points.first().copied());
    }
    for pair in points.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        let length = ((b.0 - a.0) * dots_per_x).hypot((b.1 - a.1) * dots_per_y);
        let at = |s: f64| (a.0 + (b.0 - a.0) * s, a.1 + (b.1 - a.1) * s);
        let mut done = 0.0;
        while length - done > 1e-12 {
            let step = left.min(length - done);
            done += step;
            left -= step;
            let here = at(done / length);
            if drawing {
                run.push(here);
            }
            if left <= 1e-12 {
                if drawing {
                    out.runs.push(std::mem::take(&mut run));
                    drawing = false;
                    left = pieces[piece].1;
                } else {
                    piece = (piece + 1) % pieces.len();
                    (drawing, left) = start_piece(pieces[piece], &mut out, Some(here));
                    if drawing {
                        run.push(here);
                    }
                }
            }
        }
    }
    if run.len() >= 2 {
        out.runs.push(run);
    }
    out
}

/// Enters a (drawn, gap) piece at `here`: a dot piece draws its dot at once and starts its gap.
fn start_piece(piece: (f64, f64), out: &mut Pieces, here: Option<(f64, f64)>) -> (bool, f64) {
    let (drawn, gap) = piece;
    if drawn > 0.0 {
        (true, drawn)
    } else {
        out.dots.extend(here);
        (false, gap.max(1.0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample(t: f64, x: f64, v: f64, f: f64) -> Sample {
        Sample { t, x, v, f }
    }

    /// A triangle-ish loop: out to 9 µm at 400 N and back, v from 0.3 to −0.2.
    fn series(model: ForceModel) -> Series {
        Series {
            model,
            samples: vec![
                sample(0.0, 0.0, 0.3, 0.0),
                sample(2e-5, 6e-6, 0.2, 250.0),
                sample(4.4e-5, 9e-6, 0.0, 400.0),
                sample(7e-5, 5e-6, -0.15, 120.0),
                sample(8.5e-5, 2.3e-6, -0.2, 0.0),
                sample(f64::NAN, 1e-6, -0.2, 0.0),
            ],
            force_peak_x: (9.05e-6, 403.3),
            force_peak_t: (4.5e-5, 403.3),
            deepest: (9.1e-6, 0.0),
        }
    }

    #[test]
    fn axes_cover_the_true_peaks_in_engineering_units() {
        let p = plot(
            ChartKind::ForceDisplacement,
            &[series(ForceModel::Proposed)],
            6,
            5,
        );
        assert_eq!(p.x_title, "x [µm]");
        assert_eq!(p.y_title, "F [N]");
        let curve = &p.curves[0];
        assert!((curve.peak.0 - 9.05).abs() < 1e-9 && (curve.peak.1 - 403.3).abs() < 1e-9);
        assert!(p.x.bounds[1] >= 9.05 && p.y.bounds[1] >= 403.3);
        assert_eq!(p.x.bounds[0], 0.0);
        let t = plot(ChartKind::ForceTime, &[series(ForceModel::Proposed)], 6, 5);
        assert_eq!(t.x_title, "t [µs]");
        // The NaN sample is dropped from F(t) (its t is NaN) but kept where finite.
        assert_eq!(t.curves[0].points.len(), 5);
        assert_eq!(p.curves[0].points.len(), 6);
        let v = plot(
            ChartKind::VelocityDisplacement,
            &[series(ForceModel::Proposed)],
            6,
            5,
        );
        assert_eq!(v.y_title, "v [m/s]");
        assert!(v.y.bounds[0] <= -0.2 && v.y.bounds[1] >= 0.3);
    }

    #[test]
    fn no_series_still_gives_axes() {
        let none: &[Series] = &[];
        let p = plot(ChartKind::ForceTime, none, 5, 5);
        assert!(p.curves.is_empty());
        assert!(p.x.bounds[1] > p.x.bounds[0] && p.y.bounds[1] > p.y.bounds[0]);
    }

    fn length(run: &[(f64, f64)]) -> f64 {
        run.windows(2)
            .map(|w| (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1))
            .sum()
    }

    #[test]
    fn dashes_follow_the_pattern_along_the_curve() {
        // A straight line 100 dots long, as two segments.
        let line = [(0.0, 0.0), (40.0, 0.0), (100.0, 0.0)];
        let solid = dash(&line, LinePattern::Solid, 1.0, 1.0);
        assert_eq!(solid.runs, vec![line.to_vec()]);
        let dashed = dash(&line, LinePattern::Dashed, 1.0, 1.0);
        // 5 on, 4 off: runs start every 9 dots: 0, 9, …, 99 → 12 runs (the last one cut short).
        assert_eq!(dashed.runs.len(), 12);
        assert!(
            dashed.runs[..11]
                .iter()
                .all(|r| (length(r) - 5.0).abs() < 1e-9)
        );
        assert_eq!(dashed.runs[1][0], (9.0, 0.0));
        // The run across the joint at x = 40 keeps the corner point.
        assert!(dashed.runs.iter().any(|r| r.contains(&(40.0, 0.0))));
        let dotted = dash(&line, LinePattern::Dotted, 1.0, 1.0);
        assert!(dotted.runs.is_empty());
        assert_eq!(dotted.dots.len(), 34, "a dot every 3 dots over 100");
        assert_eq!(dotted.dots[1], (3.0, 0.0));
        let dash_dot = dash(&line, LinePattern::DashDot, 1.0, 1.0);
        assert!(!dash_dot.runs.is_empty() && !dash_dot.dots.is_empty());
        assert_eq!(dash_dot.dots[0], (10.0, 0.0));
    }

    #[test]
    fn rasters_leave_no_gap_of_a_dot_and_keep_the_single_dots() {
        // A diagonal 10 dots across and 20 up, then a dot.
        let pieces = Pieces {
            runs: vec![vec![(0.0, 0.0), (10.0, 20.0)]],
            dots: vec![(30.0, 0.0)],
        };
        let points = pieces.raster(1.0, 1.0);
        assert_eq!(points.first(), Some(&(0.0, 0.0)));
        assert_eq!(points[points.len() - 2], (10.0, 20.0));
        assert_eq!(points.last(), Some(&(30.0, 0.0)));
        for w in points[..points.len() - 1].windows(2) {
            let gap = (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1);
            assert!(gap <= RASTER_SPACING + 1e-12, "{gap}");
        }
        // The same line over 2 dots per unit needs twice the points.
        let finer = pieces.raster(2.0, 2.0);
        assert!(finer.len() > 2 * points.len() - 10);
        // Without a scale, the points as they are.
        assert_eq!(pieces.raster(0.0, 1.0).len(), 3);
    }

    #[test]
    fn dash_lengths_are_measured_in_dots_not_data_units() {
        // 1 data unit = 10 dots across: a 10-unit line is 100 dots long.
        let line = [(0.0, 0.0), (10.0, 0.0)];
        let dashed = dash(&line, LinePattern::Dashed, 10.0, 1.0);
        assert_eq!(dashed.runs.len(), 12);
        assert!((length(&dashed.runs[0]) - 0.5).abs() < 1e-12);
    }
}
