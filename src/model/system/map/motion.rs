//! The kind of motion at one point of a map, decided from the recorded impacts and the largest
//! Lyapunov exponent of the impact map (docs/maps.md §2).
#![warn(missing_docs)]

use std::f64::consts::TAU;

use serde::Serialize;

use crate::model::system::{EndReason, History, ImpactKind, ImpactRecord};

/// What the body does after the transient.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case", tag = "kind")]
pub enum Motion {
    /// At most one impact recorded after the transient within the run's time limit, and none
    /// in the run's last stretch: the body stopped impacting.
    NoImpact,
    /// At most one impact recorded within the run's time limit, yet the body still impacted in
    /// the run's last stretch ([`History::impacting_at_end`]): the transient never ended (or only
    /// just), so the motion is not known (docs/maps.md §2).
    Unsettled,
    /// The body rests on a stop for ever (a rigid stop's chatter ends in a stick that never
    /// releases; a compliant contact is held for [`HELD_PERIODS`](crate::model::system::compliant::HELD_PERIODS)).
    Sticking,
    /// Chatter: resting phases that release again (a rigid stop's accumulation point, a compliant
    /// contact in which the body comes to rest or is held) or impacts in a chatter's tail (after
    /// flights shorter than [`CHATTER_FLIGHT`] of a period); `period` if the sequence repeats.
    Chattering {
        /// n events outside the chatter's tail (a resting phase counts as one) in m forcing
        /// periods.
        period: Option<(u32, u32)>,
    },
    /// n impacts every m forcing periods, isolated impacts only.
    Periodic {
        /// n.
        impacts: u32,
        /// m.
        cycles: u32,
    },
    /// No period found, largest Lyapunov exponent within the tolerance of 0.
    QuasiPeriodic,
    /// No period found, largest Lyapunov exponent above the tolerance.
    Chaotic,
    /// No period found within the recorded impacts, yet the exponent is clearly negative: a
    /// periodic attractor of a longer period, or one the transient has not reached yet.
    LongPeriod,
    /// No period found and no exponent (the impact map could not be iterated).
    Unresolved,
    /// The run failed (its error is kept beside the cell).
    Failed,
}

impl Motion {
    /// The name in every output: `periodic`, `chaotic`, `no-impact`, …
    pub fn name(self) -> &'static str {
        match self {
            Motion::NoImpact => "no-impact",
            Motion::Unsettled => "unsettled",
            Motion::Sticking => "sticking",
            Motion::Chattering { .. } => "chattering",
            Motion::Periodic { .. } => "periodic",
            Motion::QuasiPeriodic => "quasi-periodic",
            Motion::Chaotic => "chaotic",
            Motion::LongPeriod => "long-period",
            Motion::Unresolved => "unresolved",
            Motion::Failed => "failed",
        }
    }

    /// (n, m) where the motion has a period.
    pub fn period(self) -> Option<(u32, u32)> {
        match self {
            Motion::Periodic { impacts, cycles } => Some((impacts, cycles)),
            Motion::Chattering { period } => period,
            _ => None,
        }
    }

    /// The motion named `name` with period `period` (the inverse of [`Motion::name`] and
    /// [`Motion::period`]), for reading a map file back.
    pub fn parse(name: &str, period: Option<(u32, u32)>) -> Option<Motion> {
        Some(match name {
            "no-impact" => Motion::NoImpact,
            "unsettled" => Motion::Unsettled,
            "sticking" => Motion::Sticking,
            "chattering" => Motion::Chattering { period },
            "periodic" => {
                let (impacts, cycles) = period?;
                Motion::Periodic { impacts, cycles }
            }
            "quasi-periodic" => Motion::QuasiPeriodic,
            "chaotic" => Motion::Chaotic,
            "long-period" => Motion::LongPeriod,
            "unresolved" => Motion::Unresolved,
            "failed" => Motion::Failed,
            _ => return None,
        })
    }
}

/// How the recorded impacts are read.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerances {
    /// Two impacts are the same point of the impact map when their speeds differ by at most this
    /// fraction of the largest recorded speed and their phases by at most this fraction of 2π.
    pub period: f64,
    /// |λ| at most this (per impact) reads as zero: quasi-periodic.
    pub lyapunov: f64,
    /// Longest period searched, in impacts (at most half the recorded impacts).
    pub max_period_impacts: usize,
}

impl Default for Tolerances {
    fn default() -> Tolerances {
        Tolerances {
            period: 1e-5,
            lyapunov: 0.01,
            max_period_impacts: 32,
        }
    }
}

/// The smallest n for which every recorded impact matches the one n before (same stop, speed and
/// phase within `tolerance`), with the m forcing periods those n impacts span.
pub fn period_of(
    impacts: &[ImpactRecord],
    forcing_period: f64,
    tolerance: f64,
    max_n: usize,
) -> Option<(u32, u32)> {
    let count = impacts.len();
    let scale = impacts.iter().map(|i| i.v_in).fold(0.0, f64::max);
    let close = |a: &ImpactRecord, b: &ImpactRecord| {
        let dphase = (a.phase - b.phase).rem_euclid(TAU);
        a.stop == b.stop
            && a.kind == b.kind
            && (a.v_in - b.v_in).abs() <= tolerance * scale
            && dphase.min(TAU - dphase) <= tolerance * TAU
    };
    (1..=(count / 2).min(max_n)).find_map(|n| {
        if !(n..count).all(|i| close(&impacts[i], &impacts[i - n])) {
            return None;
        }
        let cycles = ((impacts[count - 1].t - impacts[count - 1 - n].t) / forcing_period).round();
        (cycles >= 1.0).then_some((n as u32, cycles as u32))
    })
}

/// A contact lasting longer than this fraction of a forcing period holds the body: the compliant
/// image of chatter and sticking.
pub const HOLDING_CONTACT: f64 = 0.1;

/// An impact that ends a flight shorter than this fraction of a forcing period is in a chatter's
/// tail (docs/maps.md §2): a rigid stop resolves that tail down to its accumulation point, a
/// compliant one only until a bounce is no longer than a contact, so neither the tail nor its
/// length is compared between the two.
pub const CHATTER_FLIGHT: f64 = 0.02;

/// Whether a recorded event is a resting phase: a rigid chatter summed to its accumulation point,
/// or a compliant contact in which the body came to rest.
fn rests(impact: &ImpactRecord) -> bool {
    impact.kind != ImpactKind::Impact
}

/// The recorded events that are not in a chatter's tail, with whether the history had a tail:
/// every resting phase, and every impact whose flight (from the event before it) lasted at least
/// [`CHATTER_FLIGHT`] of a forcing period. The first recorded impact, whose flight began before
/// the record, is left out.
pub fn skeleton(impacts: &[ImpactRecord], forcing_period: f64) -> (Vec<ImpactRecord>, bool) {
    let mut tail = false;
    let mut kept = Vec::with_capacity(impacts.len());
    for (k, i) in impacts.iter().enumerate() {
        if rests(i) {
            kept.push(*i);
            continue;
        }
        let Some(before) = k.checked_sub(1).map(|b| impacts[b]) else {
            continue;
        };
        if i.t - before.t < CHATTER_FLIGHT * forcing_period {
            tail = true;
        } else {
            kept.push(*i);
        }
    }
    (kept, tail)
}

/// What the history of a run of `max_periods` forcing periods says before any exponent: `Some`
/// when it decides the motion alone (no impact, unsettled, sticking, chatter, a period), `None`
/// when the exponent must decide.
///
/// Out of time with at most one impact recorded, the motion is `unsettled` if the body still
/// impacted in the run's last stretch ([`History::impacting_at_end`]), else `no-impact`: the
/// counts alone cannot tell a transient that never ends from one that ends in free motion.
///
/// Chatter is one definition for both stops (docs/maps.md §2): a resting phase, an impact in a
/// chatter's tail, or a contact holding the body; its period is that of the events outside the
/// tail, a resting phase counting once.
pub fn from_history(
    history: &History,
    forcing_period: f64,
    max_periods: f64,
    tol: &Tolerances,
) -> Option<Motion> {
    let impacts = &history.impacts;
    match history.end {
        EndReason::StuckForever => return Some(Motion::Sticking),
        // Out of time with (almost) nothing recorded. With more, the impacts were only slow to
        // come; what was recorded is read as usual.
        EndReason::TimeLimit if impacts.len() < 2 => {
            return Some(if history.impacting_at_end(max_periods, forcing_period) {
                Motion::Unsettled
            } else {
                Motion::NoImpact
            });
        }
        EndReason::TimeLimit | EndReason::Recorded => {}
    }
    let (kept, tail) = skeleton(impacts, forcing_period);
    let chatters = tail
        || !history.sticks.is_empty()
        || impacts.iter().any(|i| {
            rests(i)
                || i.contact_time
                    .is_some_and(|tc| tc > HOLDING_CONTACT * forcing_period)
        });
    if chatters {
        let period = period_of(&kept, forcing_period, tol.period, tol.max_period_impacts);
        return Some(Motion::Chattering { period });
    }
    period_of(impacts, forcing_period, tol.period, tol.max_period_impacts)
        .map(|(impacts, cycles)| Motion::Periodic { impacts, cycles })
}

/// The motion without a period, from its largest Lyapunov exponent per impact.
pub fn from_exponent(lyapunov: Option<f64>, tol: &Tolerances) -> Motion {
    match lyapunov {
        Some(l) if l > tol.lyapunov => Motion::Chaotic,
        Some(l) if l >= -tol.lyapunov => Motion::QuasiPeriodic,
        Some(_) => Motion::LongPeriod,
        None => Motion::Unresolved,
    }
}
