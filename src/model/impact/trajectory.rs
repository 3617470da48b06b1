//! The continuous (t, x, v, F) curves of a solved impact, sampled on demand.

use std::sync::OnceLock;

use crate::model::force::{AnyLaw, ForceLaw, Phase};
use crate::model::ode::{DenseOutput, State};

use super::phases::{self, Run, RunOptions};
use super::scale::Scales;
use super::{ImpactSummary, Sample};

/// Both phases' dense outputs, in scaled variables.
#[derive(Debug, Clone, Default)]
struct Curves {
    loading: DenseOutput,
    unloading: DenseOutput,
    /// Scaled time of the phase switch on the dense output.
    t_switch: f64,
    /// The law as these curves unload: anchored at their own turning point
    /// ([`ForceLaw::unloading_at_turn`]; the law itself unless it is a hysteresis such as
    /// Thornton's). An exact solution's law is anchored at the exact x_max; its curves, integrated,
    /// turn within their tolerance of it, and their forces must follow their own anchor.
    unloading_law: Option<AnyLaw>,
}

impl Curves {
    fn new(run: Run, law: &AnyLaw, scales: &Scales) -> Self {
        Curves {
            unloading_law: Some(law.unloading_at_turn(run.x_turn(scales))),
            loading: run.loading,
            unloading: run.unloading,
            t_switch: run.t_switch,
        }
    }
}

/// The curves of one impact. Sample it at the resolution the consumer can show.
///
/// Holds both phases' dense outputs (scaled variables) and the force law, so any t in the contact
/// can be evaluated; and the extrema of the summary, so that sampled charts peak where the numbers
/// say (for exact solutions, the exact values). For an exact solution the curves are integrated by
/// DOP853 at tight tolerance on first use, so that solves whose curves nobody draws (sweeps,
/// reference values) cost only the exact solution.
#[derive(Debug, Clone)]
pub struct Trajectory {
    law: AnyLaw,
    scales: Scales,
    curves: OnceLock<Curves>,
    /// How to integrate the curves when they are first needed (exact solutions).
    pending: Option<RunOptions>,
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

    /// The curves of an exact solution `summary`, integrated with `curve` when first sampled;
    /// `peak` is the state (x, ẋ) at the force peak.
    pub(crate) fn deferred(
        law: AnyLaw,
        scales: Scales,
        curve: RunOptions,
        summary: &ImpactSummary,
        peak: (f64, f64),
    ) -> Self {
        let mut traj = Self::bare(law, scales, summary, peak);
        traj.pending = Some(curve);
        traj
    }

    fn bare(law: AnyLaw, scales: Scales, summary: &ImpactSummary, peak: (f64, f64)) -> Self {
        Trajectory {
            law,
            scales,
            curves: OnceLock::new(),
            pending: None,
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
        self.curves.get_or_init(|| match &self.pending {
            Some(ro) => phases::run(&self.law, &self.scales, ro)
                .map(|run| Curves::new(run, &self.law, &self.scales))
                .unwrap_or_default(),
            None => Curves::default(),
        })
    }

    /// Scaled state and phase at time t (s), `None` without curves.
    fn state_at(&self, t: f64) -> Option<(State, Phase)> {
        let curves = self.curves();
        if curves.loading.is_empty() || curves.unloading.is_empty() {
            return None;
        }
        let tau = t / self.scales.t;
        let xv = |y: State| self.scales.xv(&y);
        Some(if tau <= curves.t_switch {
            (xv(curves.loading.eval(tau)), Phase::Loading)
        } else if tau <= curves.unloading.t_end() {
            // Unloading is integrated in (X, V) itself (see `phases::Run`).
            (curves.unloading.eval(tau), Phase::Unloading)
        } else {
            // An exact solution may end after its curve (a Hunt–Crossley tail where F has decayed
            // below the integrator's resolution and it cut contact off): the bodies coast.
            let t_curve = curves.unloading.t_end();
            let end = curves.unloading.eval(t_curve);
            let coast = end[1] * (tau - t_curve);
            (
                State::new((end[0] + coast).max(0.0), end[1]),
                Phase::Unloading,
            )
        })
    }

    /// Approach velocity at first contact, m/s.
    pub fn v0(&self) -> f64 {
        self.scales.v
    }

    /// Duration of contact covered, s.
    pub fn t_end(&self) -> f64 {
        self.t_end
    }

    /// The state and force at time t in [0, t_end] (clamped to it).
    pub fn at(&self, t: f64) -> Sample {
        let t = t.clamp(0.0, self.t_end);
        let Some((y, phase)) = self.state_at(t) else {
            return self.between_marks(t);
        };
        let (x, v) = (y[0] * self.scales.x, y[1] * self.scales.v);
        let law = match (phase, &self.curves().unloading_law) {
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
    /// (x_max, F_max, contact end) inserted in time order.
    pub fn samples(&self, n: usize) -> Vec<Sample> {
        let mut out = Vec::with_capacity(n + self.marks().len());
        let mut marks = self.marks().iter().peekable();
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
            out.push(self.at(t));
        }
        out.extend(marks.copied());
        out
    }

    /// The extrema inserted by [`Trajectory::samples`], in time order.
    pub fn extrema(&self) -> &[Sample] {
        self.marks()
    }
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
