//! What a simulation is asked for ([`RunOptions`]) and what it returns ([`History`]).
#![warn(missing_docs)]

use serde::Serialize;

/// Budgets and outputs of one run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunOptions {
    /// Impacts simulated before recording starts (the transient).
    pub transient_impacts: usize,
    /// Impacts recorded after the transient; the run ends when they are reached.
    pub recorded_impacts: usize,
    /// Forcing periods after which the run ends anyway (a system that stops impacting).
    pub max_periods: f64,
    /// Budget of impacts per run, chatter included: beyond it the run is refused
    /// ([`SystemError::ImpactBudget`](super::SystemError::ImpactBudget)), never left hanging.
    pub max_impacts: usize,
    /// Dense samples per forcing period for drawing, over the recorded part (0: none).
    pub samples_per_period: usize,
    /// Where the run starts; `None`: at rest at t = 0 (the ball on the table, the body at x = 0).
    pub initial: Option<State>,
}

impl Default for RunOptions {
    fn default() -> RunOptions {
        RunOptions {
            transient_impacts: 500,
            recorded_impacts: 200,
            max_periods: 10_000.0,
            max_impacts: 1_000_000,
            samples_per_period: 0,
            initial: None,
        }
    }
}

/// The body's state: time, position and velocity (in the frame for base forcing).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct State {
    /// t, s.
    pub t: f64,
    /// x, m: the ball's height (table at rest level 0), or the oscillator's displacement.
    pub x: f64,
    /// ẋ, m/s.
    pub v: f64,
}

/// One dense-output sample for drawing.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SystemSample {
    /// t, s.
    pub t: f64,
    /// x, m.
    pub x: f64,
    /// ẋ, m/s.
    pub v: f64,
    /// The position of the (first) stop at t, m: the table's height, or the gap.
    pub stop: f64,
}

/// Which stop: 0 the table or the stop at x = gap, 1 the stop at x = −second_gap.
pub type StopIndex = usize;

/// How a recorded impact came about.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum ImpactKind {
    /// An isolated impact.
    Impact,
    /// The accumulation point of a chatter sequence (infinitely many impacts in finite time,
    /// summed in closed form): the body sticks to the stop from here (docs/systems.md §4).
    ChatterEnd,
    /// A compliant contact in which the body came to rest on the stop instead of bouncing off
    /// it (docs/compliant.md §3): its time on the stop is a [`Stick`], not a contact time.
    Rest,
}

/// One impact.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ImpactRecord {
    /// Time of the impact (for a compliant stop, of first contact), s.
    pub t: f64,
    /// Forcing phase ωt mod 2π, rad.
    pub phase: f64,
    /// The body's position at the impact, m.
    pub x: f64,
    /// Which stop.
    pub stop: StopIndex,
    /// Approach speed relative to the stop (≥ 0), m/s.
    pub v_in: f64,
    /// Separation speed relative to the stop (≥ 0), m/s.
    pub v_out: f64,
    /// Peak contact force, N (compliant stop).
    pub peak_force: Option<f64>,
    /// The Hertz estimate of the peak force at v_in (eqs 5–6), N, where the scene has bodies.
    pub peak_force_estimate: Option<f64>,
    /// Contact duration, s (compliant stop).
    pub contact_time: Option<f64>,
    /// Kinetic energy lost in the stop's frame, ½·m·(v_in² − v_out²), J.
    pub energy_lost: f64,
    /// Isolated impact or chatter accumulation point.
    pub kind: ImpactKind,
}

/// An interval during which the body rides on a stop (after chatter, or an impact at zero speed;
/// for a compliant stop, a contact in which the body came to rest).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Stick {
    /// Start, s.
    pub start: f64,
    /// End, s: where the contact force would turn tensile (None: still stuck when the run ended).
    pub end: Option<f64>,
    /// Which stop.
    pub stop: StopIndex,
}

/// The permanent (plastic) indentations a compliant stop's recorded contacts left — Thornton's
/// law once yielded, the proposed model — which the stop does not carry from one contact to the
/// next: every contact starts from an undeformed stop (docs/compliant.md §1 says why).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct Dents {
    /// Recorded contacts that left one.
    pub contacts: usize,
    /// Their sum, m: the dent a stop carrying them would have after the recorded contacts.
    pub total: f64,
    /// The largest, m.
    pub largest: f64,
}

/// Why a run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum EndReason {
    /// All recorded impacts were reached.
    Recorded,
    /// `max_periods` was reached first.
    TimeLimit,
    /// The body sticks to a stop for ever (the contact force never turns tensile: Γ ≤ 1 …).
    StuckForever,
}

/// What a run returns.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct History {
    /// Dense samples over the recorded part (empty unless asked for).
    pub samples: Vec<SystemSample>,
    /// The recorded impacts (after the transient), chatter accumulation points included.
    pub impacts: Vec<ImpactRecord>,
    /// Sticking phases in the recorded part.
    pub sticks: Vec<Stick>,
    /// Impacts counted in all (transient and chatter included; a chatter sequence counts the
    /// impacts simulated before its accumulation point was summed).
    pub impacts_total: usize,
    /// The time of the last impact, transient and chatter included (for a compliant stop, the
    /// start of the last contact), s; None if there was none. Whether the body still impacts
    /// when the time limit ends the run ([`History::impacting_at_end`]).
    pub last_impact: Option<f64>,
    /// The state at the end (to continue from, e.g. the next value of a diagram).
    pub end_state: State,
    /// Why it ended.
    pub end: EndReason,
    /// The permanent dents of the recorded contacts, not carried (compliant stop; none for the
    /// rigid one).
    pub dents: Dents,
}

/// A run that reaches its time limit still impacts at its end when its last impact came within
/// this fraction of the run from the end (docs/maps.md §2): since its last impact a body that
/// still impacts has made one unfinished flight, one that stopped impacting has moved freely for
/// the rest of the run.
pub const IMPACTING_AT_END: f64 = 0.1;

impl History {
    /// Whether the body still impacted when the run ended: a run that recorded all its impacts
    /// ended on one; one that reached its time limit still impacts if its last impact (transient
    /// included) came within [`IMPACTING_AT_END`] of its `max_periods` forcing periods of
    /// `forcing_period` s from its end (docs/maps.md §2); one stuck for ever does not.
    pub fn impacting_at_end(&self, max_periods: f64, forcing_period: f64) -> bool {
        match self.end {
            EndReason::Recorded => true,
            EndReason::StuckForever => false,
            EndReason::TimeLimit => self.last_impact.is_some_and(|t| {
                self.end_state.t - t <= IMPACTING_AT_END * max_periods * forcing_period
            }),
        }
    }

    /// Whether the run reached its time limit before its `transient` impacts were done while
    /// still impacting ([`History::impacting_at_end`]): the transient never ended, so nothing
    /// was recorded. The map's `unsettled` and the compliant verdict's "the transient never
    /// ended" are this (docs/maps.md §2).
    pub fn transient_unfinished(&self, options: &RunOptions, forcing_period: f64) -> bool {
        self.end == EndReason::TimeLimit
            && self.impacts_total < options.transient_impacts
            && self.impacting_at_end(options.max_periods, forcing_period)
    }

    /// The period of the recorded impacts if they repeat: (impacts n, forcing periods m), the
    /// smallest n ≤ 128 for which every impact matches the one n before (same stop, speed within
    /// 1e-6 of the largest, phase within 1e-6 rad). `forcing_period` in s.
    pub fn period(&self, forcing_period: f64) -> Option<(u32, u32)> {
        let impacts = &self.impacts;
        let count = impacts.len();
        let scale = impacts.iter().map(|i| i.v_in).fold(0.0, f64::max);
        let close = |a: &ImpactRecord, b: &ImpactRecord| {
            let dphase = (a.phase - b.phase).rem_euclid(std::f64::consts::TAU);
            a.stop == b.stop
                && (a.v_in - b.v_in).abs() <= 1e-6 * scale
                && dphase.min(std::f64::consts::TAU - dphase) <= 1e-6
        };
        (1..=(count / 2).min(128)).find_map(|n| {
            if !(n..count).all(|i| close(&impacts[i], &impacts[i - n])) {
                return None;
            }
            let cycles =
                ((impacts[count - 1].t - impacts[count - 1 - n].t) / forcing_period).round();
            (cycles >= 1.0).then_some((n as u32, cycles as u32))
        })
    }
}
