//! Where a trace fit starts: the damping calibrated to a few restitutions, t₀ aligning the rise.

use crate::model::fit::{Candidate, FitError, Forward};
use crate::model::force::ImpactParams;

use super::data::{TraceData, TraceQuantity};
use super::fit::solve;
use super::forward::{TraceParams, sample_trace};
use super::layout::Layout;
use super::options::TraceFitOptions;

/// Restitutions whose calibrated damping the fit starts from, the best of them (after aligning
/// t₀) kept: a trace's e is not known before the fit.
const START_E: [f64; 4] = [0.2, 0.5, 0.8, 0.95];

/// A start in SI ([`Layout::specs`] order): k, n, v₀ the scene's; the damping calibrated to one
/// of [`START_E`] at v₀ (fit-core's [`Forward::start`]); t₀ aligning the model's rise through
/// half its peak with the data's; of these, the one with the least squared misfit.
pub(super) fn start(
    base: &ImpactParams,
    data: &TraceData,
    layout: &Layout,
    opts: &TraceFitOptions,
    t_bounds: (f64, f64),
) -> Result<Vec<f64>, FitError> {
    let candidate = Candidate::Law(layout.model);
    let dampings: Vec<Option<f64>> = match layout.damping {
        None => vec![None],
        Some(_) => {
            let forward = Forward::new(base, candidate)?;
            START_E
                .iter()
                .filter_map(|&e| forward.start(base.v0, e).ok()?.first().copied())
                .filter(|d| d.is_finite() && *d > 0.0)
                .map(Some)
                .collect()
        }
    };
    let times = data.times();
    let values = data.values();
    let t_data = half_rise(&times, &values);
    let mut best: Option<(f64, Vec<f64>)> = None;
    let mut last_error = None;
    for d in dampings {
        let mut theta: Vec<f64> = Vec::with_capacity(layout.len());
        if layout.free.k {
            theta.push(base.law.k);
        }
        if layout.free.n {
            theta.push(base.law.n);
        }
        if layout.free.v0 {
            theta.push(base.v0);
        }
        theta.extend(d);
        theta.push(0.0);
        let p = layout.params(base, &theta);
        let solution = match solve(base, layout.model, &p, &opts.solve, candidate) {
            Ok(s) => s,
            Err(e) => {
                last_error = Some(e);
                continue;
            }
        };
        let curve = solution.trajectory.samples(512);
        let (ts, ys): (Vec<f64>, Vec<f64>) = curve
            .iter()
            .map(|s| {
                (
                    s.t,
                    match data.quantity {
                        TraceQuantity::Force => s.f,
                        TraceQuantity::Displacement => s.x,
                    },
                )
            })
            .unzip();
        let t0 = (t_data - half_rise(&ts, &ys)).clamp(t_bounds.0, t_bounds.1);
        let last = theta.len() - 1;
        theta[last] = t0;
        let p = TraceParams { t0, ..p };
        let modelled = sample_trace(&solution, data.quantity, opts.outside, &p, &times);
        let rss: f64 = modelled
            .iter()
            .zip(&values)
            .map(|(m, y)| (m - y).powi(2))
            .sum();
        if best.as_ref().is_none_or(|(b, _)| rss < *b) {
            best = Some((rss, theta));
        }
    }
    match (best, last_error) {
        (Some((_, theta)), _) => Ok(theta),
        (None, Some(e)) => Err(e),
        (None, None) => Err(FitError::Unfittable {
            candidate,
            reason: "no damping to start from".into(),
        }),
    }
}

/// When `ys` first rises through half its peak, linearly between samples.
fn half_rise(ts: &[f64], ys: &[f64]) -> f64 {
    let peak = ys.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let half = 0.5 * peak;
    match ys.iter().position(|&y| y >= half) {
        Some(0) | None => ts.first().copied().unwrap_or(0.0),
        Some(i) => {
            let (t0, t1, y0, y1) = (ts[i - 1], ts[i], ys[i - 1], ys[i]);
            t0 + (t1 - t0) * (half - y0) / (y1 - y0)
        }
    }
}
