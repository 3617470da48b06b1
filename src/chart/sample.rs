//! Chart data: the solver's dense output sampled at the chart's resolution, in display units,
//! with the true peaks, as a [`Chart`] for any back-end.

use std::borrow::Borrow;

use crate::chart::{Chart, Ink, Series as ChartSeries};
use crate::format::units::{self, Unit};
use crate::model::ForceModel;
use crate::model::impact::{ImpactSolution, Ratios, Sample};

use super::kind::ChartKind;
use super::ticks::{NiceAxis, nice_axis};

/// Dots across the widest plot each chart gets on the screen, and down the tallest: what a solution
/// is sampled for, once, when it arrives (see [`Series::for_charts`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ChartDots {
    /// F(t), whose x axis is the contact time.
    pub time: u32,
    /// F(x) and v(x), whose x axis is the approach.
    pub approach: u32,
    /// F(x), F(t) or v(x), whichever plot is tallest.
    pub high: u32,
}

/// Dots of t and of x between consecutive samples at most, on plots no taller for their width
/// than `REFERENCE_BEND` says. The straight lines joining them stay within a fifth of a dot of
/// the curves on every law (tested against curves sampled 24 times as densely): an impact's
/// curves are smooth between the extrema, which are samples of their own, and bend over tens of
/// dots, so samples a dot apart were mostly spent where a line draws the same dots. Where they bend
/// sharply, at first contact and at an end at x = 0, the trajectory refines the steps itself.
pub const STRIDE: f64 = 3.0;

/// Height over width² of the plots [`STRIDE`] is measured for: the explorer's at 160×48, 48
/// dots high and 98 across (F(x) and v(x); F(t) is wider). A line s dots long bows from the
/// curve by about s²·high/across² dots (the curve's bend in dots grows with the height it is
/// drawn to and falls with the square of the width its time spans), so taller or narrower plots
/// take samples closer, by the square root of how much more they bend.
const REFERENCE_BEND: f64 = 48.0 / (98.0 * 98.0);

/// Closest samples are ever spaced, in dots: a bound on their number on absurdly tall and
/// narrow plots (it binds past 144 times the explorer's bend, such as 40 dots across and 1150
/// high).
const CLOSEST_STRIDE: f64 = 0.25;

/// Fewest and most samples of one solution, whatever the screen.
const SAMPLES: std::ops::RangeInclusive<usize> = 32..=8192;

impl ChartDots {
    /// Until the terminal's size is known: plots 100 braille columns wide and 12 rows high.
    pub const UNKNOWN_SCREEN: ChartDots = ChartDots {
        time: 200,
        approach: 200,
        high: 48,
    };

    /// Dots between consecutive samples at most: [`STRIDE`], or closer on plots that bend their
    /// curves more than `REFERENCE_BEND` (the tallest plot over the narrowest, conservatively).
    pub fn stride(self) -> f64 {
        let across = f64::from(self.time.min(self.approach).max(1));
        let bend = f64::from(self.high) / (across * across);
        (STRIDE * (REFERENCE_BEND / bend).sqrt()).clamp(CLOSEST_STRIDE, STRIDE)
    }

    /// The spacing (Δt, Δx) that puts consecutive samples of `solution` at most
    /// [`ChartDots::stride`] dots apart across every chart: `time` dots over the contact time on
    /// F(t); `approach` dots over x_max on F(x) and v(x) (the axis spans at least the solution's
    /// own x_max). Lines join the samples, so the curves stay connected; the extrema are added
    /// exactly.
    pub fn spacing(self, solution: &ImpactSolution) -> (f64, f64) {
        let s = &solution.summary;
        let stride = self.stride();
        (
            stride * s.t_contact / f64::from(self.time),
            stride * s.x_max / f64::from(self.approach),
        )
    }
}

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
    /// `n` samples of the solution's drawn curves (evenly in t, the true extrema inserted by the
    /// trajectory).
    pub fn sample(model: K, solution: &ImpactSolution, n: usize) -> Series<K> {
        Series::of(model, solution, solution.trajectory.drawn_samples(n))
    }

    /// The solution's drawn curves sampled at most [`ChartDots::stride`] dots apart on the
    /// charts `dots` measures ([`ChartDots::spacing`]): densely in t where the approach moves
    /// fast, no denser than the stride where it is slow — within the cap of 8192 samples, which
    /// can bind at e ≤ 0.01 on the laws whose approach is over in the first hundredth of the
    /// contact (Flores, Hu–Guo, Gonthier, Gharib–Hurmuzlu), where the first steps then span
    /// further, as evenly spaced samples at the cap did.
    pub fn for_charts(model: K, solution: &ImpactSolution, dots: ChartDots) -> Series<K> {
        let (dt, dx) = dots.spacing(solution);
        let samples = solution.trajectory.drawn_samples_within(dt, dx, SAMPLES);
        Series::of(model, solution, samples)
    }

    /// These samples of a similar law's solution moved with it by `r`
    /// ([`ImpactSolution::similar_at`], [`ImpactSolution::ratios_to`]): the sampling is spaced in
    /// the solution's own t_contact and x_max, so the moved solution would be sampled at the
    /// moved times.
    pub fn moved(&self, r: Ratios) -> Series<K>
    where
        K: Copy,
    {
        let (t, x, v, f) = (r.t, r.x, r.v, r.f);
        Series {
            model: self.model,
            samples: (self.samples.iter())
                .map(|s| Sample {
                    t: s.t * t,
                    x: s.x * x,
                    v: s.v * v,
                    f: s.f * f,
                })
                .collect(),
            force_peak_x: (self.force_peak_x.0 * x, self.force_peak_x.1 * f),
            force_peak_t: (self.force_peak_t.0 * t, self.force_peak_t.1 * f),
            deepest: (self.deepest.0 * x, self.deepest.1 * v),
        }
    }

    fn of(model: K, solution: &ImpactSolution, samples: Vec<Sample>) -> Series<K> {
        let s = &solution.summary;
        Series {
            model,
            samples,
            force_peak_x: (solution.trajectory.peak_state().0, s.f_max),
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

/// The smallest (x, y) box holding the origin and every point covered.
#[derive(Debug, Clone, Copy, Default)]
struct Ranges {
    x: (f64, f64),
    y: (f64, f64),
}

impl Ranges {
    /// Widens the box to finite point `(x, y)`: plain comparisons (f64::min's NaN handling costs
    /// more, and there is no NaN here).
    #[inline]
    fn cover(&mut self, (x, y): (f64, f64)) {
        if x < self.x.0 {
            self.x.0 = x;
        } else if x > self.x.1 {
            self.x.1 = x;
        }
        if y < self.y.0 {
            self.y.0 = y;
        } else if y > self.y.1 {
            self.y.1 = y;
        }
    }
}

/// The finite points `point` makes of `samples`, `ranges` widened to them (a loop per chart kind,
/// so that picking the coordinates costs no branch per sample). Samples are all finite but in a
/// failure: the points are made without a test each, and the rare non-finite ones dropped after.
#[inline]
fn finite_points(
    samples: &[Sample],
    ranges: &mut Ranges,
    point: impl Fn(&Sample) -> (f64, f64),
) -> Vec<(f64, f64)> {
    let mut points: Vec<(f64, f64)> = samples.iter().map(point).collect();
    // A copy in registers, not through the reference, for the loop.
    let mut covered = *ranges;
    let mut all_finite = true;
    for &p in &points {
        if finite(&p) {
            covered.cover(p);
        } else {
            all_finite = false;
        }
    }
    *ranges = covered;
    if !all_finite {
        points.retain(finite);
    }
    points
}

/// The chart of `kind` over `series`, with at most the given numbers of axis labels. Non-finite
/// points are dropped (never drawn, never NaN on an axis).
pub fn plot<K: Copy, S: Borrow<Series<K>>>(
    kind: ChartKind,
    series: &[S],
    max_x_labels: usize,
    max_y_labels: usize,
) -> Plot<K> {
    // Curves in SI first, to find the ranges. Axes always include 0: the contact starts at x = 0,
    // t = 0 and F = 0.
    let mut ranges = Ranges::default();
    let raw: Vec<Curve<K>> = series
        .iter()
        .map(Borrow::borrow)
        .map(|s| {
            let points = match kind {
                ChartKind::ForceDisplacement => {
                    finite_points(&s.samples, &mut ranges, |q| (q.x, q.f))
                }
                ChartKind::ForceTime => finite_points(&s.samples, &mut ranges, |q| (q.t, q.f)),
                ChartKind::VelocityDisplacement => {
                    finite_points(&s.samples, &mut ranges, |q| (q.x, q.v))
                }
            };
            let peak = kind.peak(s);
            if finite(&peak) {
                ranges.cover(peak);
            }
            Curve {
                model: s.model,
                points,
                peak,
            }
        })
        .collect();
    let Ranges {
        x: (x_lo, x_hi),
        y: (y_lo, y_hi),
    } = ranges;
    let ((x_name, x_unit), (y_name, y_unit)) = kind.axes();
    let x = nice_axis(x_lo, x_hi, x_unit, max_x_labels);
    let y = nice_axis(y_lo, y_hi, y_unit, max_y_labels);
    let to_display = |(px, py): (f64, f64)| (px / x.scale, py / y.scale);
    let mut curves = raw;
    for c in &mut curves {
        for p in &mut c.points {
            *p = to_display(*p);
        }
        c.peak = to_display(c.peak);
    }
    Plot {
        x_title: format!("{x_name} [{}{}]", x.prefix.symbol, x_unit.symbol),
        y_title: format!("{y_name} [{}{}]", y.prefix.symbol, y_unit.symbol),
        x,
        y,
        curves,
    }
}

/// How one curve of a [`Plot`] is shown: its name, ink and glyph, and whether it is focused.
pub struct Look {
    pub name: String,
    pub ink: Ink,
    pub glyph: char,
    pub focused: bool,
    /// Each sample is a step of a fixed-step method (marked one by one).
    pub steps: bool,
}

impl<K: Copy> Plot<K> {
    /// The chart of this plot titled `title`, each curve shown as `look` says, in drawing order
    /// (the focused curve last, so it lies on top).
    pub fn into_chart(self, title: String, look: impl Fn(K) -> Look) -> Chart {
        let mut series: Vec<ChartSeries> = self
            .curves
            .into_iter()
            .map(|c| {
                let look = look(c.model);
                ChartSeries {
                    name: look.name,
                    ink: look.ink,
                    glyph: look.glyph,
                    runs: vec![c.points],
                    focused: look.focused,
                    peak: Some(c.peak),
                    steps: look.steps,
                }
            })
            .collect();
        series.sort_by_key(|s| s.focused);
        Chart::new(
            title,
            self.x.chart_axis(self.x_title),
            self.y.chart_axis(self.y_title),
            series,
        )
    }
}

#[cfg(test)]
pub(crate) mod tests {
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

    /// How far, in dots, the lines joining `samples` pass from the curve's points `dense` on
    /// the three charts: each point's distance to the nearest line near its time, on F(t),
    /// F(x) and v(x), in dots of each axis (`dot`: t, x, v, F), the largest of all.
    fn chord_error(samples: &[Sample], dense: &[Sample], dot: [f64; 4]) -> f64 {
        let [t, x, v, f] = dot;
        // A sample's point on F(t), F(x) and v(x), in dots.
        let charts = |q: &Sample| [(q.t / t, q.f / f), (q.x / x, q.f / f), (q.x / x, q.v / v)];
        let to_line = |p: (f64, f64), a: (f64, f64), b: (f64, f64)| {
            let (ab, ap) = ((b.0 - a.0, b.1 - a.1), (p.0 - a.0, p.1 - a.1));
            let length = ab.0 * ab.0 + ab.1 * ab.1;
            let s = if length > 0.0 {
                ((ap.0 * ab.0 + ap.1 * ab.1) / length).clamp(0.0, 1.0)
            } else {
                0.0
            };
            (ap.0 - s * ab.0).hypot(ap.1 - s * ab.1)
        };
        let mut worst = 0.0f64;
        let mut first = 0;
        for d in dense {
            while first + 2 < samples.len() && samples[first + 1].t < d.t {
                first += 1;
            }
            // The lines around d's time: from the one before it to a few after (a jump makes
            // several samples share a time).
            let near = &samples[first.saturating_sub(1)..(first + 5).min(samples.len())];
            for (k, p) in charts(d).into_iter().enumerate() {
                let error = near
                    .windows(2)
                    .map(|w| to_line(p, charts(&w[0])[k], charts(&w[1])[k]))
                    .fold(f64::INFINITY, f64::min);
                worst = worst.max(error);
            }
        }
        worst
    }

    /// The explorer's plots at 160×48 in braille (the explorer's layout tests check that its
    /// layout gives these).
    pub(crate) const EXPLORER_160X48: ChartDots = ChartDots {
        time: 214,
        approach: 98,
        high: 48,
    };

    /// On every law of the paper's Fig. 5 (and e = 0.2, x_pl = 0, where the contact is shortest
    /// against x_max; and e = 0.95), on plots as the explorer lays them out at 160×48 and far
    /// taller or narrower ones (a 120×80 terminal's, 58 dots across and 128 high; 40 across and
    /// 200 high): consecutive samples lie within [`ChartDots::stride`] dots of each other on every
    /// chart (t over the time plot, x over the approach plots); the lines joining them pass within
    /// a fifth of a dot of the curves sampled 24 times as densely, on F(t), F(x) and v(x) as high
    /// as the tallest plot (measured at 160×48: 0.03–0.06 on the paper's models, 0.15 at most, on
    /// Tsuji's x^¼ damping at e = 0.2, where the force rises as t^¼); and at 160×48 there are at
    /// most half as many as evenly spaced samples a dot apart would need (the fastest approach,
    /// v₀, everywhere). The tall plots are met within 0.09 dots; at the 160×48 stride they
    /// were missed by up to 0.32 and 0.48 dots.
    #[test]
    fn samples_are_a_stride_apart_and_their_lines_on_the_curves() {
        use crate::model::impact::{SolveOptions, solve_impact};
        use crate::model::scene::tests::fig5_params;
        let explorer = EXPLORER_160X48;
        let screens = [
            explorer,
            ChartDots {
                time: 116,
                approach: 58,
                high: 128,
            },
            ChartDots {
                time: 40,
                approach: 40,
                high: 200,
            },
        ];
        assert_eq!(explorer.stride(), STRIDE);
        let mut damped = fig5_params(0.3);
        damped.restitution = 0.2;
        damped.plastic_indentation = 0.0;
        let mut lively = fig5_params(0.3);
        lively.restitution = 0.95;
        let mut laws = 0;
        for params in [fig5_params(0.3), damped, lively] {
            for model in ForceModel::ALL {
                let Ok(solution) = solve_impact(model, &params, &SolveOptions::default()) else {
                    continue;
                };
                let s = &solution.summary;
                for dots in screens {
                    let samples = Series::for_charts(model, &solution, dots).samples;
                    let n = samples.len();
                    let widest = |f: &dyn Fn(&Sample) -> f64| {
                        samples
                            .windows(2)
                            .map(|w| (f(&w[1]) - f(&w[0])).abs())
                            .fold(0.0, f64::max)
                    };
                    let t_step = widest(&|q| q.t) / s.t_contact * f64::from(dots.time);
                    let x_step = widest(&|q| q.x) / s.x_max * f64::from(dots.approach);
                    let stride = dots.stride();
                    assert!(
                        t_step <= stride + 1e-9,
                        "{model}: {n} samples, {t_step} dots in t"
                    );
                    assert!(
                        x_step <= stride + 1e-9,
                        "{model}: {n} samples, {x_step} dots in x"
                    );
                    let (dt, dx) = dots.spacing(&solution);
                    let dense = solution.trajectory.drawn_samples_within(
                        dt / stride / 8.0,
                        dx / stride / 8.0,
                        2..=1_000_000,
                    );
                    let high = f64::from(dots.high);
                    let dot = [
                        s.t_contact / f64::from(dots.time),
                        s.x_max / f64::from(dots.approach),
                        params.v0 / high,
                        s.f_max / high,
                    ];
                    let error = chord_error(&samples, &dense, dot);
                    assert!(
                        error <= 0.2,
                        "{model} e = {} on {dots:?}: {error} dots",
                        params.restitution
                    );
                    if dots == explorer {
                        let sweep = params.v0 * s.t_contact / s.x_max * f64::from(dots.approach);
                        let even = sweep.ceil().max(f64::from(dots.time)) as usize + 1;
                        let extrema = solution.trajectory.extrema().len();
                        assert!(
                            2 * n <= even + extrema,
                            "{model}: {n} samples, {even} evenly spaced"
                        );
                    }
                }
                laws += 1;
            }
        }
        assert!(laws > 50, "{laws} laws solved");
    }

    #[test]
    fn no_series_still_gives_axes() {
        let none: &[Series] = &[];
        let p = plot(ChartKind::ForceTime, none, 5, 5);
        assert!(p.curves.is_empty());
        assert!(p.x.bounds[1] > p.x.bounds[0] && p.y.bounds[1] > p.y.bounds[0]);
    }
}
