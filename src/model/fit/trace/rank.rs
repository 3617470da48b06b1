//! Telling which ranked trace fits the trace cannot separate, as e(v) fits are grouped
//! (docs/physics.md §9.3); both are ranked by [`criterion::rank`].

use crate::model::fit::criterion::{self, Verdict, judge};
use crate::model::fit::{Candidate, LawFit};
use crate::model::force::ForceModel;
use crate::model::force::table::Family;

use super::data::TraceData;
use super::options::TRACE_FLOOR;

/// Groups the ranked fits the trace cannot tell apart, as e(v) fits are grouped (docs/physics.md
/// §9.3): a law joins the group of the best-ranked law still ungrouped when their Δ < 2 or when
/// their fitted traces differ nowhere on the samples by more than the noise (the best fit's
/// residual standard deviation). `v_range` is the scene's v₀ at both ends: a trace is one impact.
pub(super) fn verdict(
    data: &TraceData,
    fits: &[LawFit],
    criterion: criterion::Criterion,
    v0: f64,
) -> Verdict {
    let best = &fits[0];
    let dof = data.samples.len().saturating_sub(best.params.len()).max(1);
    let peak = data.peak().value.abs();
    let noise = (best.rss / dof as f64)
        .sqrt()
        .max(10.0 * TRACE_FLOOR * peak);
    // Residuals are model minus data at the same samples: their difference is the models'.
    let gap = |i: usize, j: usize| -> f64 {
        fits[i]
            .residuals
            .iter()
            .zip(&fits[j].residuals)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max)
    };
    judge(fits, criterion, noise, gap, identical_on_traces, (v0, v0))
}

/// The laws whose F(t) and x(t) are the same functions as `candidate`'s on any trace (a
/// reparametrised copy): the Hunt–Crossley rows among themselves (with χ fitted, each is
/// F = k·xⁿ·(1 + χ·ẋ/v₀), eq 19, whatever its χ(e)), and the proposed model and Kuwabara–Kono
/// with F ≥ 0 (b = k·A, docs/physics.md §6.5).
fn identical_on_traces(candidate: Candidate) -> Vec<Candidate> {
    let class = |m: ForceModel| -> Option<u8> {
        if m.spec().family == Family::HuntCrossley {
            Some(0)
        } else if m == ForceModel::Proposed || m.name() == "kuwabara-kono" {
            Some(1)
        } else {
            None
        }
    };
    let Some(own) = candidate.model().and_then(class) else {
        return Vec::new();
    };
    ForceModel::ALL
        .into_iter()
        .filter(|&m| Candidate::Law(m) != candidate && class(m) == Some(own))
        .map(Candidate::Law)
        .collect()
}
