//! "Which approach does my system need?" (issue 25, item 6): the same system run with a rigid and
//! a compliant stop, the contact time set against the forcing period, and the answers compared.
//! Data only; src/format/verdict.rs puts it in words.
//!
//! The paper's introduction names the criterion: the instantaneous model is valid when contacts
//! are short against the system's motion. Short contacts are not enough on their own: a law that
//! does not realise the e it was given for (clamped Kelvin–Voigt) moves the whole answer, so the
//! rigid stop is also run at the compliant law's *realised* e, which separates the two effects.
//!
//! Contact time means the impacts' contacts: a contact in which the body came to rest on the stop
//! (a bouncing ball riding its table) is a resting phase, weighed separately as the fraction of
//! the recorded time the body spends on a stop, beside the rigid stop's sticking phases.

use serde::Serialize;

use crate::model::force::ForceModel;

use super::super::{
    CompliantDamping, EndReason, History, ImpactKind, ImpactRecord, RunOptions, SystemError,
    SystemModel, rigid,
};
use super::{CompliantOptions, CompliantStop, run};

/// Contacts shorter than this fraction of the forcing period, with answers that agree within
/// [`AGREEMENT`], make the instantaneous model valid.
pub const SHORT_CONTACT: f64 = 0.01;
/// Contacts longer than this fraction of the period make it invalid whatever the answers say.
pub const LONG_CONTACT: f64 = 0.05;
/// Relative agreement of the compared answers for a valid instantaneous model.
pub const AGREEMENT: f64 = 0.01;
/// Beyond this relative difference the instantaneous model is invalid.
pub const DISAGREEMENT: f64 = 0.05;

/// The quantity a comparison is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Quantity {
    /// The mean approach speed of the recorded impacts, m/s.
    MeanImpactSpeed,
    /// The mean forcing phase of the recorded impacts, as a fraction of the period (circular mean).
    MeanImpactPhase,
    /// Impacts per forcing period over the recorded part.
    ImpactRate,
}

/// One answer of both stops.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Comparison {
    pub quantity: Quantity,
    /// The rigid stop's answer at the scene's e.
    pub rigid: f64,
    /// The rigid stop's answer at the compliant law's realised e.
    pub rigid_at_realised: f64,
    /// The compliant stop's answer.
    pub compliant: f64,
}

impl Comparison {
    /// (compliant − rigid)/|rigid| (0 when both are 0); for the phase, the difference in
    /// periods wrapped to [−½, ½).
    pub fn relative(&self) -> f64 {
        relative(self.quantity, self.compliant, self.rigid)
    }

    /// The same against the rigid stop at the realised e.
    pub fn relative_at_realised(&self) -> f64 {
        relative(self.quantity, self.compliant, self.rigid_at_realised)
    }
}

fn relative(quantity: Quantity, a: f64, b: f64) -> f64 {
    if quantity == Quantity::MeanImpactPhase {
        (a - b + 0.5).rem_euclid(1.0) - 0.5
    } else if a == b {
        0.0
    } else {
        (a - b) / b.abs().max(f64::MIN_POSITIVE)
    }
}

/// What the comparison says.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Validity {
    /// Short contacts and agreeing answers: the rigid stop is enough.
    Valid,
    /// Between the thresholds: the rigid stop is an approximation worth checking.
    Marginal,
    /// Long contacts or disagreeing answers: the system needs the compliant stop.
    NotValid,
}

/// A run's resting phases: the sticking after chatter of a rigid stop, the contacts in which the
/// body came to rest on a compliant one.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct Resting {
    /// Resting phases in the recorded part.
    pub phases: usize,
    /// The fraction of the recorded time (from the first recorded impact to the run's end) the
    /// body spends resting on a stop.
    pub fraction: f64,
}

impl Resting {
    /// The resting phases of `history`.
    pub fn of(history: &History) -> Resting {
        let Some(first) = history.impacts.first() else {
            // No impact recorded: the body came to rest for good within the transient, or flies.
            return if history.end == EndReason::StuckForever {
                Resting {
                    phases: 1,
                    fraction: 1.0,
                }
            } else {
                Resting::default()
            };
        };
        let end = history.end_state.t;
        let span = end - first.t;
        let on_stop: f64 = history
            .sticks
            .iter()
            .map(|s| s.end.unwrap_or(end).min(end) - s.start)
            .sum();
        Resting {
            phases: history.sticks.len(),
            fraction: if span > 0.0 {
                (on_stop / span).clamp(0.0, 1.0)
            } else {
                1.0
            },
        }
    }
}

/// Why the compliant run recorded no impact proper, when it recorded none.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "kebab-case", tag = "kind")]
pub enum NothingRecorded {
    /// The run reached its time limit (`--max-periods`) before its transient impacts were done,
    /// still impacting in its last stretch ([`History::transient_unfinished`]): the motion never
    /// settled, so nothing was recorded.
    TransientUnfinished {
        /// Impacts made in all.
        impacts: usize,
        /// The transient impacts asked for.
        transient: usize,
        /// Forcing periods run.
        periods: f64,
    },
    /// The body came to rest on the stop for ever.
    RestsForever,
    /// The body stopped impacting, in the transient or after it, or made at most resting
    /// contacts until the time limit.
    NoBounce,
}

impl NothingRecorded {
    /// Why `history`, run with `options`, recorded no impact proper (None if it recorded one).
    pub fn of(history: &History, options: &RunOptions, period: f64) -> Option<NothingRecorded> {
        if impacts(history).next().is_some() {
            return None;
        }
        let start = options.initial.map_or(0.0, |s| s.t);
        Some(match history.end {
            EndReason::StuckForever => NothingRecorded::RestsForever,
            // The map's `unsettled` is the same notion (docs/maps.md §2).
            EndReason::TimeLimit if history.transient_unfinished(options, period) => {
                NothingRecorded::TransientUnfinished {
                    impacts: history.impacts_total,
                    transient: options.transient_impacts,
                    periods: (history.end_state.t - start) / period,
                }
            }
            _ => NothingRecorded::NoBounce,
        })
    }
}

/// The verdict for one system, law and damping.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Verdict {
    pub law: ForceModel,
    /// Forcing period T, s.
    pub period: f64,
    /// The longest recorded impact's contact (resting phases left out), s.
    pub contact_time: f64,
    /// contact_time / T.
    pub contact_ratio: f64,
    /// The scene's e (what the rigid stop uses and the law was given).
    pub asked_restitution: f64,
    /// The compliant law's mean v_out/v_in over the recorded impacts (resting phases left out).
    pub realised_restitution: f64,
    pub comparisons: Vec<Comparison>,
    /// The comparison that decided (largest relative difference).
    pub decisive: usize,
    pub validity: Validity,
    /// Recorded impacts of each run (rigid, compliant), resting phases left out.
    pub impacts: (usize, usize),
    /// The resting phases of the rigid stop at the scene's e.
    pub rigid_resting: Resting,
    /// The resting phases of the compliant stop.
    pub compliant_resting: Resting,
    /// Why the compliant run recorded no impact, when it recorded none.
    pub nothing_recorded: Option<NothingRecorded>,
}

/// Runs `model` rigid (at the scene's e and at the law's realised e) and compliant with `law` and
/// `damping` over `options`, and compares them ([`verdict_of`] with no run given).
pub fn verdict(
    model: &SystemModel,
    law: ForceModel,
    damping: CompliantDamping,
    options: &RunOptions,
) -> Result<Verdict, SystemError> {
    let stop = CompliantStop::new(model, law, damping, CompliantOptions::default())?;
    let compliant = run(&stop, model, options)?.history;
    verdict_of(model, law, options, &compliant, None)
}

/// The verdict from the runs a caller already has: `compliant`, the compliant stop of `law` run
/// with `options`, and, if given, `rigid`, the rigid stop at the scene's e with the same options
/// (run here otherwise). Only the rigid stop at the law's realised e is run here.
pub fn verdict_of(
    model: &SystemModel,
    law: ForceModel,
    options: &RunOptions,
    compliant: &History,
    rigid: Option<&History>,
) -> Result<Verdict, SystemError> {
    let options = &RunOptions {
        samples_per_period: 0,
        ..*options
    };
    let rigid_asked = match rigid {
        Some(h) => h.clone(),
        None => rigid::simulate(model, model.restitution, options)?,
    };
    let realised = mean(
        impacts(compliant)
            .filter(|i| i.v_in > 0.0)
            .map(|i| i.v_out / i.v_in),
    )
    .unwrap_or(model.restitution)
    .clamp(0.0, 1.0);
    let rigid_realised = rigid::simulate(model, realised, options)?;
    let period = model.spec.period();
    let contact_time = impacts(compliant)
        .filter_map(|i| i.contact_time)
        .fold(0.0, f64::max);
    let comparisons: Vec<Comparison> = [
        Quantity::MeanImpactSpeed,
        Quantity::MeanImpactPhase,
        Quantity::ImpactRate,
    ]
    .into_iter()
    .map(|q| Comparison {
        quantity: q,
        rigid: answer(q, &rigid_asked, period),
        rigid_at_realised: answer(q, &rigid_realised, period),
        compliant: answer(q, compliant, period),
    })
    .collect();
    let decisive = comparisons
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.relative().abs().total_cmp(&b.1.relative().abs()))
        .map_or(0, |(i, _)| i);
    let contact_ratio = contact_time / period;
    let worst = comparisons
        .get(decisive)
        .map_or(0.0, |c| c.relative().abs());
    let validity = if contact_ratio > LONG_CONTACT || worst > DISAGREEMENT {
        Validity::NotValid
    } else if contact_ratio > SHORT_CONTACT || worst > AGREEMENT {
        Validity::Marginal
    } else {
        Validity::Valid
    };
    Ok(Verdict {
        law,
        period,
        contact_time,
        contact_ratio,
        asked_restitution: model.restitution,
        realised_restitution: realised,
        comparisons,
        decisive,
        validity,
        impacts: (impacts(&rigid_asked).count(), impacts(compliant).count()),
        rigid_resting: Resting::of(&rigid_asked),
        compliant_resting: Resting::of(compliant),
        nothing_recorded: NothingRecorded::of(compliant, options, period),
    })
}

/// A run's recorded impacts proper: no chatter accumulation points, no resting phases.
fn impacts(history: &History) -> impl Iterator<Item = &ImpactRecord> {
    history
        .impacts
        .iter()
        .filter(|i| i.kind == ImpactKind::Impact)
}

fn mean(values: impl Iterator<Item = f64>) -> Option<f64> {
    let (sum, n) = values.fold((0.0, 0usize), |(s, n), v| (s + v, n + 1));
    (n > 0).then(|| sum / n as f64)
}

/// A run's answer for `quantity`, over its impacts proper.
fn answer(quantity: Quantity, history: &History, period: f64) -> f64 {
    let impacts: Vec<&ImpactRecord> = impacts(history).collect();
    match quantity {
        Quantity::MeanImpactSpeed => mean(impacts.iter().map(|i| i.v_in)).unwrap_or(0.0),
        Quantity::MeanImpactPhase => {
            let (s, c) = impacts.iter().fold((0.0, 0.0), |(s, c), i| {
                (s + i.phase.sin(), c + i.phase.cos())
            });
            if s == 0.0 && c == 0.0 {
                0.0
            } else {
                s.atan2(c).rem_euclid(std::f64::consts::TAU) / std::f64::consts::TAU
            }
        }
        Quantity::ImpactRate => match (impacts.first(), impacts.last()) {
            (Some(a), Some(b)) if b.t > a.t => (impacts.len() - 1) as f64 * period / (b.t - a.t),
            _ => 0.0,
        },
    }
}
