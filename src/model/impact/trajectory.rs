//! The continuous (t, x, v, F) curves of a solved impact, sampled on demand.

use crate::model::force::{AnyLaw, ForceLaw, Phase};
use crate::model::ode::{DenseOutput, State};

use super::phases::Run;
use super::scale::Scales;
use super::{ImpactSummary, Sample};

/// The curves of one impact. Sample it at the resolution the consumer can show.
///
/// Holds both phases' dense outputs (scaled variables) and the force law, so any t in the contact
/// can be evaluated; and the extrema of the summary, so that sampled charts peak where the
/// numbers say (for exact solutions, the exact values).
#[derive(Debug, Clone)]
pub struct Trajectory {
    law: AnyLaw,
    scales: Scales,
    loading: DenseOutput,
    unloading: DenseOutput,
    /// Scaled time of the phase switch on the dense output.
    t_switch: f64,
    /// End of contact, s.
    t_end: f64,
    /// Extrema in time order: force peak, maximum compression (two samples where the force
    /// jumps there), end of contact.
    marks: Vec<Sample>,
}

impl Trajectory {
    /// The curves of `run` with the extrema of `summary` (which may come from an exact solution).
    pub(crate) fn new(law: AnyLaw, scales: Scales, run: Run, summary: &ImpactSummary) -> Self {
        let mut traj = Trajectory {
            law,
            scales,
            loading: run.loading,
            unloading: run.unloading,
            t_switch: run.t_switch,
            t_end: summary.t_contact,
            marks: Vec::with_capacity(4),
        };
        let at_rest = |phase| Sample {
            t: summary.t_x_max,
            x: summary.x_max,
            v: 0.0,
            f: law.phase_force(summary.x_max, 0.0, phase),
        };
        let peak = Sample {
            f: summary.f_max,
            ..traj.at(summary.t_f_max)
        };
        let loading_end = at_rest(Phase::Loading);
        if summary.t_f_max != summary.t_x_max {
            traj.marks.push(peak);
            traj.marks.push(loading_end);
        } else {
            traj.marks.push(Sample {
                f: summary.f_max,
                ..loading_end
            });
        }
        if law.switches_at_max_compression() {
            traj.marks.push(at_rest(Phase::Unloading));
        }
        traj.marks.push(Sample {
            t: summary.t_contact,
            x: summary.x_residual,
            v: -summary.v_out,
            f: law.force(summary.x_residual, -summary.v_out),
        });
        traj.marks.sort_by(|a, b| a.t.total_cmp(&b.t));
        traj
    }

    /// Duration of contact covered, s.
    pub fn t_end(&self) -> f64 {
        self.t_end
    }

    /// The state and force at time t in [0, t_end] (clamped to it).
    pub fn at(&self, t: f64) -> Sample {
        let sc = &self.scales;
        let t = t.clamp(0.0, self.t_end);
        let tau = t / sc.t;
        let (y, phase) = if tau <= self.t_switch {
            (self.loading.eval(tau), Phase::Loading)
        } else if tau <= self.unloading.t_end() {
            (self.unloading.eval(tau), Phase::Unloading)
        } else {
            // An exact solution may end after its curve (a Hunt–Crossley tail where F has decayed
            // below the integrator's resolution and it cut contact off): the bodies coast.
            let end = self.unloading.eval(self.unloading.t_end());
            let coast = end[1] * (tau - self.unloading.t_end());
            (
                State::new((end[0] + coast).max(0.0), end[1]),
                Phase::Unloading,
            )
        };
        let (x, v) = (y[0] * sc.x, y[1] * sc.v);
        let f = if x > 0.0 {
            self.law.phase_force(x, v, phase)
        } else {
            0.0
        };
        Sample { t, x, v, f }
    }

    /// `n` samples evenly spaced in t over the contact, with the exact extrema
    /// (x_max, F_max, contact end) inserted in time order.
    pub fn samples(&self, n: usize) -> Vec<Sample> {
        let mut out = Vec::with_capacity(n + self.marks.len());
        let mut marks = self.marks.iter().peekable();
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
        &self.marks
    }
}
