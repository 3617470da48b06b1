//! Information criteria, Akaike weights and "can the data tell these laws apart?"
//! (docs/physics.md §9.3; Burnham & Anderson, Model Selection and Multimodel Inference, 2nd ed.,
//! 2002, §2.4–2.9, §6.4).
//!
//! With Gaussian errors of unknown σ the maximised log-likelihood gives −2·ln L = N·ln(RSS/N) +
//! const, and σ counts as a parameter (K = p + 1); with known standard deviations −2·ln L = χ² +
//! const and K = p. AIC = −2·ln L + 2K, AICc = AIC + 2K(K + 1)/(N − K − 1) (Hurvich & Tsai,
//! Biometrika 76, 1989), BIC = −2·ln L + K·ln N (Schwarz, Ann. Stat. 6, 1978). The constants cancel
//! in the differences Δ that rank laws.
#![warn(missing_docs)]

use serde::Serialize;

use super::candidate::Candidate;

/// The criterion that ranks the laws.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Criterion {
    /// AIC with the small-sample correction (the default: it tends to AIC for N ≫ K).
    #[default]
    Aicc,
    /// The Bayesian (Schwarz) criterion, which penalises parameters by ln N.
    Bic,
}

impl Criterion {
    /// Its name in tables: `AICc` or `BIC`.
    pub fn name(self) -> &'static str {
        match self {
            Criterion::Aicc => "AICc",
            Criterion::Bic => "BIC",
        }
    }
}

impl std::str::FromStr for Criterion {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s.to_ascii_lowercase().as_str() {
            "aicc" => Ok(Criterion::Aicc),
            "bic" => Ok(Criterion::Bic),
            _ => Err(format!(
                "unknown criterion '{s}' (expected one of: aicc, bic)"
            )),
        }
    }
}

/// Residuals below this (in e) are the forward model's own accuracy, not a better fit: the misfit
/// a criterion sees is floored at it, so two laws that both fit noise-free data tie instead of
/// ranking by their rounding.
pub const RESIDUAL_FLOOR: f64 = 1e-9;

/// A Δ below this says the data cannot tell two laws apart (Burnham & Anderson 2002, §2.6:
/// Δ ≤ 2 is "substantial support" for both).
pub const DELTA_TIE: f64 = 2.0;

/// AIC, AICc and BIC of one fit.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Scores {
    /// Akaike's criterion.
    pub aic: f64,
    /// AIC corrected for small samples; +∞ when N ≤ K + 1.
    pub aicc: f64,
    /// Schwarz's criterion.
    pub bic: f64,
}

impl Scores {
    /// The value of `criterion`.
    pub fn get(&self, criterion: Criterion) -> f64 {
        match criterion {
            Criterion::Aicc => self.aicc,
            Criterion::Bic => self.bic,
        }
    }
}

/// The scores of a fit with `params` parameters to `n` points: from RSS when the standard
/// deviations are unknown (`floor_rss` = N·[`RESIDUAL_FLOOR`]²), from χ² when they are known
/// (`floor_rss` = Σ([`RESIDUAL_FLOOR`]/sdᵢ)²).
pub fn scores(rss: f64, floor_rss: f64, n: usize, params: usize, known_sd: bool) -> Scores {
    let misfit = rss.max(floor_rss);
    let nf = n as f64;
    let (m2ll, k) = if known_sd {
        (misfit, params)
    } else {
        (nf * (misfit / nf).ln(), params + 1)
    };
    let kf = k as f64;
    let aic = m2ll + 2.0 * kf;
    let aicc = if n > k + 1 {
        aic + 2.0 * kf * (kf + 1.0) / (nf - kf - 1.0)
    } else {
        f64::INFINITY
    };
    Scores {
        aic,
        aicc,
        bic: m2ll + kf * nf.ln(),
    }
}

/// Akaike weights exp(−Δᵢ/2)/Σⱼ exp(−Δⱼ/2) of criterion values (Burnham & Anderson 2002, §2.9);
/// an infinite value weighs 0.
pub fn weights(values: &[f64]) -> Vec<f64> {
    let best = values.iter().copied().fold(f64::INFINITY, f64::min);
    let raw: Vec<f64> = values
        .iter()
        .map(|v| {
            if v.is_finite() {
                (-(v - best) / 2.0).exp()
            } else {
                0.0
            }
        })
        .collect();
    let sum: f64 = raw.iter().sum();
    raw.iter()
        .map(|w| if sum > 0.0 { w / sum } else { f64::NAN })
        .collect()
}

/// Sorts `fits` best first by `criterion` (ties: fewer parameters, then their place in `order`,
/// the order asked) and fills Δ and the Akaike weights.
pub(crate) fn rank(fits: &mut [super::LawFit], criterion: Criterion, order: &[Candidate]) {
    let position = |c: Candidate| order.iter().position(|&o| o == c).unwrap_or(usize::MAX);
    fits.sort_by(|a, b| {
        a.score(criterion)
            .total_cmp(&b.score(criterion))
            .then(a.params.len().cmp(&b.params.len()))
            .then(position(a.candidate).cmp(&position(b.candidate)))
    });
    let values: Vec<f64> = fits.iter().map(|f| f.score(criterion)).collect();
    let w = weights(&values);
    for (f, w) in fits.iter_mut().zip(w) {
        f.delta = f.score(criterion) - values[0];
        f.weight = w;
    }
}

/// Laws the data cannot tell apart from the best-ranked law of the group, and the numbers that
/// say so.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Indistinguishable {
    /// The group, best first.
    pub members: Vec<Candidate>,
    /// The largest Δcriterion from the group's first member.
    pub max_delta: f64,
    /// The largest |e₁(v) − eⱼ(v)| between the first member's curve and any other's over the data's
    /// velocity range.
    pub max_gap: f64,
    /// The noise the gap is compared with: the RMS of the given sd, or the best fit's residual
    /// standard deviation s = √(RSS/(N − p)).
    pub noise: f64,
    /// Members that are the same e(v) as the first on any data (reparametrisations), named so.
    pub identical: Vec<Candidate>,
}

/// Why one law ranks above the next: the structured verdict the report words.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Verdict {
    /// The best law by the criterion.
    pub best: Candidate,
    /// The criterion.
    pub criterion: Criterion,
    /// Its Akaike weight.
    pub best_weight: f64,
    /// The runner-up not in the best's group, and its Δ.
    pub runner_up: Option<(Candidate, f64)>,
    /// The velocity range of the data, m/s.
    pub v_range: (f64, f64),
    /// The noise level the comparisons used (see [`Indistinguishable::noise`]).
    pub noise: f64,
    /// The groups of laws the data cannot tell apart (the best's first, when it has company).
    pub groups: Vec<Indistinguishable>,
}

/// The verdict on fits ranked best first (docs/physics.md §9.3): a law joins the group of the
/// best-ranked law still ungrouped when their Δ < 2, or when `gap(i, j)` — the largest difference
/// of their fitted curves over the data — stays below `noise`; `same` names the laws identical
/// to a group's first, `v_range` the velocities the data covers.
pub(crate) fn judge(
    fits: &[super::LawFit],
    criterion: Criterion,
    noise: f64,
    gap: impl Fn(usize, usize) -> f64,
    same: fn(Candidate) -> Vec<Candidate>,
    v_range: (f64, f64),
) -> Verdict {
    let best = &fits[0];
    let mut grouped = vec![false; fits.len()];
    let mut groups = Vec::new();
    for i in 0..fits.len() {
        if grouped[i] {
            continue;
        }
        grouped[i] = true;
        let mut members = vec![fits[i].candidate];
        let (mut max_delta, mut max_gap) = (0.0f64, 0.0f64);
        for j in i + 1..fits.len() {
            if grouped[j] {
                continue;
            }
            let delta = fits[j].score(criterion) - fits[i].score(criterion);
            let g = gap(i, j);
            if delta < DELTA_TIE || g < noise {
                grouped[j] = true;
                members.push(fits[j].candidate);
                max_delta = max_delta.max(delta);
                max_gap = max_gap.max(g);
            }
        }
        if members.len() > 1 {
            let identical = same(members[0]);
            groups.push(Indistinguishable {
                identical: members[1..]
                    .iter()
                    .copied()
                    .filter(|c| identical.contains(c))
                    .collect(),
                members,
                max_delta,
                max_gap,
                noise,
            });
        }
    }
    let best_group: Vec<Candidate> = groups
        .first()
        .filter(|g| g.members[0] == best.candidate)
        .map(|g| g.members.clone())
        .unwrap_or_else(|| vec![best.candidate]);
    let runner_up = fits
        .iter()
        .find(|f| !best_group.contains(&f.candidate))
        .map(|f| (f.candidate, f.delta));
    Verdict {
        best: best.candidate,
        criterion,
        best_weight: best.weight,
        runner_up,
        v_range,
        noise,
        groups,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scores_follow_their_definitions() {
        // N = 10, p = 1, unknown σ: K = 2, −2lnL = 10·ln(0.1/10).
        let s = scores(0.1, 0.0, 10, 1, false);
        let m2ll = 10.0 * (0.01f64).ln();
        assert!((s.aic - (m2ll + 4.0)).abs() < 1e-12);
        assert!((s.aicc - (m2ll + 4.0 + 12.0 / 7.0)).abs() < 1e-12);
        assert!((s.bic - (m2ll + 2.0 * 10f64.ln())).abs() < 1e-12);
        // Known sd: K = p, −2lnL = χ².
        let k = scores(12.0, 0.0, 10, 1, true);
        assert!((k.aic - 14.0).abs() < 1e-12);
        // The floor: a perfect fit scores as one at the floor.
        assert_eq!(
            scores(0.0, 1e-18, 10, 1, false),
            scores(1e-18, 0.0, 10, 1, false)
        );
        assert_eq!(scores(1.0, 0.0, 3, 1, false).aicc, f64::INFINITY);
    }

    #[test]
    fn weights_sum_to_one_and_favour_the_lowest() {
        let w = weights(&[10.0, 12.0, f64::INFINITY]);
        assert!((w.iter().sum::<f64>() - 1.0).abs() < 1e-15);
        assert!((w[0] / w[1] - 1f64.exp()).abs() < 1e-12);
        assert_eq!(w[2], 0.0);
    }
}
