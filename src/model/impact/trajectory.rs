//! The continuous (t, x, v, F) curves of a solved impact, sampled on demand.

use std::sync::OnceLock;

use crate::model::force::{AnyLaw, ForceLaw, Phase};
use crate::model::ode::{DenseOutput, State};

use super::phases::{self, Run, RunOptions};
use super::scale::Scales;
use super::similar::Ratios;
use super::{ImpactSummary, Sample};

/// Both phases' dense outputs, in scaled variables.
#[derive(Debug, Clone, Default)]
struct Curves {
    loading: DenseOutput,
    unloading: DenseOutput,
    /// Scaled time of the phase switch on the dense output.
    t_switch: f64,
    /// The scales of the unloading dense output ([`Run::unloading_scales`]).
    unloading_scales: Scales,
    /// The law as these curves unload: anchored at their own turning point
    /// ([`ForceLaw::unloading_at_turn`]; the law itself unless it is a hysteresis such as
    /// Thornton's). An exact solution's law is anchored at the exact x_max; its curves, integrated,
    /// turn within their tolerance of it, and their forces must follow their own anchor.
    unloading_law: Option<AnyLaw>,
}

/// Where a walk through increasing times stands in each phase's segments (`None`: not yet in it).
#[derive(Debug, Clone, Copy, Default)]
struct Cursor {
    loading: Option<usize>,
    unloading: Option<usize>,
}

impl Curves {
    /// Scaled state and phase at scaled time `tau`, `None` without curves; `cursor` is where the
    /// previous (earlier) time was found.
    fn state_at(&self, tau: f64, scales: &Scales, cursor: &mut Cursor) -> Option<(State, Phase)> {
        if self.loading.is_empty() || self.unloading.is_empty() {
            return None;
        }
        Some(if tau <= self.t_switch {
            let y = self.loading.eval_from(tau, &mut cursor.loading);
            (scales.xv(&y), Phase::Loading)
        } else if tau <= self.unloading.t_end() {
            (
                self.unloading_scales
                    .xv(&self.unloading.eval_from(tau, &mut cursor.unloading)),
                Phase::Unloading,
            )
        } else {
            // An exact solution may end after its curve (a Hunt–Crossley tail where F has decayed
            // below the integrator's resolution and it cut contact off): the bodies coast.
            let t_curve = self.unloading.t_end();
            let end = self.unloading_scales.xv(&self.unloading.eval(t_curve));
            let coast = end[1] * (tau - t_curve);
            (
                State::new((end[0] + coast).max(0.0), end[1]),
                Phase::Unloading,
            )
        })
    }

    fn new(run: Run, law: &AnyLaw, scales: &Scales) -> Self {
        Curves {
            unloading_law: Some(law.unloading_at_turn(run.x_turn(scales))),
            loading: run.loading,
            unloading: run.unloading,
            t_switch: run.t_switch,
            unloading_scales: run.unloading_scales,
        }
    }
}

/// The curves of one impact. Sample it at the resolution the consumer can show.
///
/// Holds both phases' dense outputs (scaled variables) and the force law, so any t in the contact
/// can be evaluated; and the extrema of the summary, so that sampled charts peak where the numbers
/// say (for exact solutions, the exact values). For an exact solution the curves are integrated on
/// first use, so that solves whose curves nobody draws (sweeps, reference values) cost only the
/// exact solution: by DOP853 at tight tolerance when sampled ([`Trajectory::at`],
/// [`Trajectory::samples`]: within 1e-9 of the truth), by DOPRI5 at a chart's when drawn
/// ([`Trajectory::drawn_samples`]: within 2e-5 of the curve's scale, tested).
#[derive(Debug, Clone)]
pub struct Trajectory {
    law: AnyLaw,
    scales: Scales,
    curves: OnceLock<Curves>,
    /// How to integrate the curves when they are first needed (exact solutions).
    pending: Option<RunOptions>,
    /// Exact solutions: how to integrate the curves charts draw, when first drawn — looser than
    /// `pending`, for a tolerance far below a chart's dot rather than the 1e-9 the sampled
    /// trajectory promises. Integrated solutions draw their own curves.
    drawn: Option<RunOptions>,
    drawn_curves: OnceLock<Curves>,
    /// End of contact, s.
    t_end: f64,
    /// The summary's extrema, turned into marks when first asked for: a solve whose curves
    /// nobody samples (a sweep's) pays for neither the forces at them nor their allocation.
    extrema: Extrema,
    /// Extrema in time order: force peak, maximum compression (two samples where the force jumps
    /// there), end of contact.
    marks: OnceLock<Vec<Sample>>,
}

/// What the marks are made of: the summary's extrema and the state (x, ẋ) at the force peak.
#[derive(Debug, Clone, Copy)]
struct Extrema {
    t_f_max: f64,
    f_max: f64,
    peak: (f64, f64),
    t_x_max: f64,
    x_max: f64,
    t_contact: f64,
    x_residual: f64,
    v_out: f64,
}

impl Trajectory {
    /// The curves of an integrated `run`, with the extrema of its `summary`.
    pub(crate) fn integrated(
        law: AnyLaw,
        scales: Scales,
        run: Run,
        summary: &ImpactSummary,
    ) -> Self {
        let mut traj = Self::bare(law, scales, summary, (0.0, 0.0));
        traj.curves = OnceLock::from(Curves::new(run, &law, &scales));
        // From the curves directly: `at` would fall back on the marks, not made yet.
        if let Some((y, _)) = traj.state_at(summary.t_f_max.clamp(0.0, traj.t_end)) {
            traj.extrema.peak = (y[0] * scales.x, y[1] * scales.v);
        }
        traj
    }

    /// The curves of an exact solution `summary`, integrated with `curve` when first sampled
    /// and with `drawn` when first drawn ([`Trajectory::drawn_samples`]); `peak` is the state
    /// (x, ẋ) at the force peak.
    pub(crate) fn deferred(
        law: AnyLaw,
        scales: Scales,
        [curve, drawn]: [RunOptions; 2],
        summary: &ImpactSummary,
        peak: (f64, f64),
    ) -> Self {
        let mut traj = Self::bare(law, scales, summary, peak);
        traj.pending = Some(curve);
        traj.drawn = Some(drawn);
        traj
    }

    /// These curves moved to `law` with `scales`, `r` from this trajectory's scales (a similar
    /// law's impact under other parameters, docs/physics.md §6.9): the dense outputs are in
    /// scaled variables and stay, the scales and the extrema move.
    /// Curves integrated already are kept (equal, to rounding, to integrating them again).
    pub(crate) fn rescaled(&self, law: AnyLaw, scales: Scales, r: &Ratios) -> Self {
        let (x, v, t, f) = (r.x, r.v, r.t, r.f);
        let moved = |lock: &OnceLock<Curves>| {
            lock.get().map_or_else(OnceLock::new, |c| {
                OnceLock::from(Curves {
                    unloading_scales: if c.unloading_scales.shift == 0.0 {
                        scales.without_shift()
                    } else {
                        scales
                    },
                    unloading_law: c.unloading_law.map(|_| law),
                    ..c.clone()
                })
            })
        };
        let e = &self.extrema;
        Trajectory {
            law,
            scales,
            curves: moved(&self.curves),
            pending: self.pending,
            drawn: self.drawn,
            drawn_curves: moved(&self.drawn_curves),
            t_end: self.t_end * t,
            extrema: Extrema {
                t_f_max: e.t_f_max * t,
                f_max: e.f_max * f,
                peak: (e.peak.0 * x, e.peak.1 * v),
                t_x_max: e.t_x_max * t,
                x_max: e.x_max * x,
                t_contact: e.t_contact * t,
                x_residual: e.x_residual * x,
                v_out: e.v_out * v,
            },
            marks: OnceLock::new(),
        }
    }

    fn bare(law: AnyLaw, scales: Scales, summary: &ImpactSummary, peak: (f64, f64)) -> Self {
        Trajectory {
            law,
            scales,
            curves: OnceLock::new(),
            pending: None,
            drawn: None,
            drawn_curves: OnceLock::new(),
            t_end: summary.t_contact,
            extrema: Extrema {
                t_f_max: summary.t_f_max,
                f_max: summary.f_max,
                peak,
                t_x_max: summary.t_x_max,
                x_max: summary.x_max,
                t_contact: summary.t_contact,
                x_residual: summary.x_residual,
                v_out: summary.v_out,
            },
            marks: OnceLock::new(),
        }
    }

    /// The extrema as samples, in time order, made on first use.
    fn marks(&self) -> &[Sample] {
        self.marks.get_or_init(|| self.make_marks())
    }

    fn make_marks(&self) -> Vec<Sample> {
        let law = self.law;
        let summary = &self.extrema;
        let (x_peak, v_peak) = summary.peak;
        let at_rest = |phase| Sample {
            t: summary.t_x_max,
            x: summary.x_max,
            v: 0.0,
            f: law.phase_force(summary.x_max, 0.0, phase),
        };
        let loading_end = at_rest(Phase::Loading);
        let mut marks = Vec::with_capacity(4);
        if summary.t_f_max == summary.t_x_max {
            marks.push(Sample {
                f: summary.f_max,
                ..loading_end
            });
        } else {
            marks.push(Sample {
                t: summary.t_f_max,
                x: x_peak,
                v: v_peak,
                f: summary.f_max,
            });
            marks.push(loading_end);
        }
        if law.switches_at_max_compression() {
            // Unloading starts at or below the peak (dry friction drops, Thornton's branch passes
            // through it, up to rounding): never above the summary's F_max.
            let unloading_start = at_rest(Phase::Unloading);
            marks.push(Sample {
                f: unloading_start.f.min(summary.f_max),
                ..unloading_start
            });
        }
        marks.push(Sample {
            t: summary.t_contact,
            x: summary.x_residual,
            v: -summary.v_out,
            f: law.force(summary.x_residual, -summary.v_out),
        });
        marks.sort_by(|a, b| a.t.total_cmp(&b.t));
        marks
    }

    /// First contact: x = 0, ẋ = v₀.
    fn start(&self) -> Sample {
        let v0 = self.scales.v;
        Sample {
            t: 0.0,
            x: 0.0,
            v: v0,
            f: self.law.force(0.0, v0),
        }
    }

    /// The curves, integrating them first if this trajectory was deferred. A failed integration
    /// leaves them empty, and the trajectory falls back to its extrema.
    fn curves(&self) -> &Curves {
        self.curves
            .get_or_init(|| self.integrate(self.pending.as_ref()))
    }

    /// The curves charts draw: an exact solution's own, looser ones; else [`Trajectory::curves`].
    fn drawn_curves(&self) -> &Curves {
        match &self.drawn {
            Some(drawn) => self
                .drawn_curves
                .get_or_init(|| self.integrate(Some(drawn))),
            None => self.curves(),
        }
    }

    fn integrate(&self, how: Option<&RunOptions>) -> Curves {
        match how {
            Some(ro) => phases::run(&self.law, &self.scales, ro)
                .map(|run| Curves::new(run, &self.law, &self.scales))
                .unwrap_or_default(),
            None => Curves::default(),
        }
    }

    /// Scaled state and phase at time t (s), `None` without curves.
    fn state_at(&self, t: f64) -> Option<(State, Phase)> {
        self.curves()
            .state_at(t / self.scales.t, &self.scales, &mut Cursor::default())
    }

    /// The law these curves are of.
    pub(crate) fn law(&self) -> &AnyLaw {
        &self.law
    }

    /// Duration of contact covered, s.
    pub fn t_end(&self) -> f64 {
        self.t_end
    }

    /// The state and force at time t in [0, t_end] (clamped to it).
    pub fn at(&self, t: f64) -> Sample {
        self.sample_on(self.curves(), t, &mut Cursor::default())
    }

    /// [`Trajectory::at`] on `curves`, from `cursor`'s segments on (times in increasing order).
    fn sample_on(&self, curves: &Curves, t: f64, cursor: &mut Cursor) -> Sample {
        let t = t.clamp(0.0, self.t_end);
        let Some((y, phase)) = curves.state_at(t / self.scales.t, &self.scales, cursor) else {
            return self.between_marks(t);
        };
        let (x, v) = (y[0] * self.scales.x, y[1] * self.scales.v);
        let law = match (phase, &curves.unloading_law) {
            (Phase::Unloading, Some(anchored)) => anchored,
            _ => &self.law,
        };
        let f = if x > 0.0 {
            law.phase_force(x, v, phase)
        } else {
            0.0
        };
        Sample { t, x, v, f }
    }

    /// Without curves: linear between first contact and the extrema.
    fn between_marks(&self, t: f64) -> Sample {
        let mut prev = self.start();
        for mark in self.marks() {
            if mark.t >= t {
                return lerp(&prev, mark, t);
            }
            prev = *mark;
        }
        prev
    }

    /// `n` samples evenly spaced in t over the contact, with the exact extrema
    /// (x_max, F_max, contact end) inserted in time order: each [`Trajectory::at`] its time.
    pub fn samples(&self, n: usize) -> Vec<Sample> {
        self.samples_on(self.curves(), n)
    }

    /// [`Trajectory::samples`] for a chart: an exact solution's curves integrated at a tolerance
    /// far below a dot (`auto::DRAWN_RTOL`) rather than the trajectory's 1e-9;
    /// an integrated solution's own. The extrema inserted are the same exact ones.
    pub fn drawn_samples(&self, n: usize) -> Vec<Sample> {
        self.samples_on(self.drawn_curves(), n)
    }

    fn samples_on(&self, curves: &Curves, n: usize) -> Vec<Sample> {
        let mut out = Vec::with_capacity(n + self.marks().len());
        let mut marks = self.marks().iter().peekable();
        // The times increase: the segments are walked once rather than searched for each.
        let mut cursor = Cursor::default();
        for i in 0..n {
            // The last sample is t_end itself, not a rounded multiple of it.
            let t = if i + 1 == n && n > 1 {
                self.t_end
            } else if n > 1 {
                self.t_end * i as f64 / (n - 1) as f64
            } else {
                0.0
            };
            while let Some(mark) = marks.next_if(|m| m.t < t) {
                out.push(*mark);
            }
            // An even sample that falls exactly on a mark is the mark.
            if marks.peek().is_some_and(|m| m.t == t) {
                continue;
            }
            out.push(self.sample_on(curves, t, &mut cursor));
        }
        out.extend(marks.copied());
        out
    }

    /// Samples of the drawn curves ([`Trajectory::drawn_samples`]) for a chart, from first contact
    /// to the end, consecutive ones at most `dt` apart in time and `dx` in approach, with the
    /// exact extrema inserted in time order; between `count`'s bounds of them (the steps widened
    /// or narrowed to t_end/(count − 1) where `dt` and `dx` ask for more or fewer).
    ///
    /// From a sample of speed |v| the next is as far as both bounds allow: in a step Δt ≤ dt the
    /// approach moves at most (|v| + a·dt)·Δt, a = F_max/m bounding the acceleration (|F| ≤
    /// F_max), so the fast stretches after first contact and before the end are sampled densely
    /// in time and the slow ones around maximum compression no denser than `dt` — where evenly
    /// spaced samples would all be as dense as the fastest stretch needs. Where the force is
    /// steep at an end (it rises slower than x from first contact, or falls so to an end at
    /// x = 0, or jumps there: F = c·ẋ), the steps there are refined geometrically from 1/128 of
    /// these bounds (or the shortest `count` allows, if longer).
    pub fn drawn_samples_within(
        &self,
        dt: f64,
        dx: f64,
        count: std::ops::RangeInclusive<usize>,
    ) -> Vec<Sample> {
        let t_end = self.t_end;
        if !(t_end.is_finite() && t_end > 0.0) {
            return self.drawn_samples(*count.start());
        }
        let curves = self.drawn_curves();
        let intervals = |n: usize| n.max(2) as f64 - 1.0;
        let (shortest, longest) = (
            t_end / intervals(*count.end()),
            dt.min(t_end / intervals(*count.start())),
        );
        let a = self.extrema.f_max.abs() / self.scales.mass;
        let mut out = Vec::with_capacity(*count.start() + self.marks().len());
        let mut marks = self.marks().iter().peekable();
        let mut cursor = Cursor::default();
        let mut t = 0.0;
        // A force that rises slower than x from first contact (a damping term in xⁿ⁻¹·ẋ or
        // x^((n−1)/2)·ẋ, or one that jumps, c·ẋ) bends most there, and so does one that falls so
        // to a contact ending at x = 0: steps start at 1/128 of what the bounds allow and double
        // from there (halve towards the end), so the lines joining the samples hug the curve.
        let fine = (dx / (self.scales.v + a * longest)).min(longest) / 128.0;
        let unloading = curves.unloading_law.as_ref().unwrap_or(&self.law);
        let (x_probe, v_out) = (1e-6 * self.extrema.x_max, self.extrema.v_out);
        let steep_start = slower_than_x(&self.law, x_probe, self.scales.v, Phase::Loading);
        let steep_end = self.extrema.x_residual == 0.0
            && slower_than_x(unloading, x_probe, -v_out, Phase::Unloading);
        let mut grown = if steep_start { fine } else { f64::INFINITY };
        let f_step = FORCE_STEP * self.extrema.f_max.abs() * dx / self.extrema.x_max;
        let breakpoint = self.law.loading_breakpoint();
        loop {
            while let Some(mark) = marks.next_if(|m| m.t < t) {
                out.push(*mark);
            }
            // A sample that falls exactly on a mark is the mark.
            let (x, v, f) = match marks.peek() {
                Some(mark) if mark.t == t => (mark.x, mark.v, mark.f),
                _ => {
                    let sample = self.sample_on(curves, t, &mut cursor);
                    out.push(sample);
                    (sample.x, sample.v, sample.f)
                }
            };
            if t >= t_end {
                break;
            }
            // NaN bounds (a zero x_max) leave the other bound; `max` keeps the count finite.
            let mut step = (dx / (v.abs() + a * longest)).min(longest).min(grown);
            if steep_end {
                step = step.min(((t_end - t) / 2.0).max(fine));
            }
            // Below a loading breakpoint the law's force may bend over a few dots (Adams' STEP
            // ramps its damper in over [0, d]): there a step may move F by FORCE_STEP at most.
            if breakpoint.is_some_and(|x_b| v > 0.0 && x < x_b) {
                let mut probe = Cursor::default();
                while step > shortest
                    && (self.sample_on(curves, (t + step).min(t_end), &mut probe).f - f).abs()
                        > f_step
                {
                    step /= 2.0;
                    probe = Cursor::default();
                }
            }
            let step = step.max(shortest);
            grown = 2.0 * step;
            // A step that does not move t (zero, or below t's ulp for a subnormal t_end) ends the
            // walk rather than looping.
            let next = t + step;
            t = if next > t && next < t_end {
                next
            } else {
                t_end
            };
        }
        out.extend(marks.copied());
        out
    }

    /// The state (x, ẋ) at the force peak: an exact solution's exact one, else its curves'.
    pub fn peak_state(&self) -> (f64, f64) {
        self.extrema.peak
    }

    /// The extrema inserted by [`Trajectory::samples`], in time order.
    pub fn extrema(&self) -> &[Sample] {
        self.marks()
    }
}

/// The most a chart's samples let the force move between two below a law's loading breakpoint,
/// as a fraction of F_max per fraction of x_max that they may move (a chart's dx/x_max, which
/// shrinks on taller plots): half, so that a force ramped in over a few dots of x (Adams' STEP
/// damper, docs/physics.md §6.8) is drawn as closely as one that rises with x.
const FORCE_STEP: f64 = 0.5;

/// Whether |F| grows slower than x near x = 0 (F ∝ xᵖ with p below about 0.85), from its values
/// at `x` and 2`x`: false where F vanishes there or is not finite.
fn slower_than_x(law: &AnyLaw, x: f64, v: f64, phase: Phase) -> bool {
    let near = law.phase_force(x, v, phase).abs();
    let far = law.phase_force(2.0 * x, v, phase).abs();
    far < 1.8 * near
}

/// Linear interpolation between two samples at time t.
fn lerp(a: &Sample, b: &Sample, t: f64) -> Sample {
    let s = if b.t > a.t {
        ((t - a.t) / (b.t - a.t)).clamp(0.0, 1.0)
    } else {
        1.0
    };
    Sample {
        t,
        x: a.x + s * (b.x - a.x),
        v: a.v + s * (b.v - a.v),
        f: a.f + s * (b.f - a.f),
    }
}
