//! Newton's starts for a periodic orbit when no first impact is given (docs/systems.md §5): the
//! isolated impacts of the run past the transient — the detected cycle's first — then starts the
//! solver adds (a grid of phases and speeds for the rigid stop, the rigid orbit for the compliant
//! one). When none converges, the error says why: what the run did and what Newton met.

use std::f64::consts::{PI, TAU};

use super::error::SystemError;
use super::model::SystemModel;
use super::orbit::{GuessStart, Orbit, OrbitGuess};
use super::run::{EndReason, History, ImpactKind, ImpactRecord, RunOptions};
use super::spec::SystemKind;

/// Starts taken from the run at most (the detected cycle's impacts first).
const RUN_STARTS: usize = 12;
/// A flight shorter than this fraction of the period is part of a chatter sequence: its impacts
/// are not isolated.
const CHATTER_FLIGHT: f64 = 1e-3;
/// Two starts closer than this (phase in rad, speed relative) are one.
const SAME_START: f64 = 1e-3;

/// Newton iterations allowed from one start: a start that has not converged by then is left
/// for the next.
pub(crate) const SEED_ITERATIONS: usize = 25;

/// Where the starts `extra` gives go: before the run's (the rigid orbit, close to the compliant
/// one) or after them (a grid).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Extra {
    First,
    Last,
}

/// The orbit `guess` asks for (no start given), from the first start from which `solve`
/// converges to a stable orbit, else the first from which it converges at all: the run's isolated
/// impacts and `extra`'s starts. `guess.forcing_cycles` or `guess.impacts` of 0 asks for the
/// period the run settles on (1 and 1 if it has none). `solve` gets the guess with its start and
/// numbers set; `extra` the guess with its numbers set and the run's starts.
pub(crate) fn search(
    model: &SystemModel,
    guess: &OrbitGuess,
    run: impl Fn(&RunOptions) -> Result<History, SystemError>,
    solve: impl Fn(&OrbitGuess) -> Result<Orbit, SystemError>,
    (extra, place): (
        impl FnOnce(&OrbitGuess, &[GuessStart]) -> Vec<GuessStart>,
        Extra,
    ),
) -> Result<Orbit, SystemError> {
    let history = run(&guess.attractor)?;
    let period = model.spec.period();
    let detected = history.period(period);
    // A detected cycle that chatters or rests has no isolated impacts to iterate: not asked for.
    let iterable = detected.filter(|&(n, _)| {
        history.impacts[history.impacts.len().saturating_sub(n as usize)..]
            .iter()
            .all(|i| i.kind == ImpactKind::Impact && i.v_out > 0.0)
    });
    let guess = &resolved(guess, iterable);
    let from_run = run_starts(&history, period);
    let extra = extra(guess, &from_run);
    let starts: Vec<GuessStart> = match place {
        Extra::First => extra.into_iter().chain(from_run.iter().copied()).collect(),
        Extra::Last => from_run.iter().copied().chain(extra).collect(),
    };
    let mut tried: Vec<GuessStart> = Vec::new();
    let mut last_error = None;
    // A stable orbit is what a run settles on, and where a saddle-node pair coexists it is the
    // one looked for; an unstable one is returned only if no start finds a stable one.
    let mut unstable: Option<Orbit> = None;
    for start in starts {
        if tried.iter().any(|s| same(s, &start)) {
            continue;
        }
        tried.push(start);
        let with_start = OrbitGuess {
            start: Some(start),
            ..*guess
        };
        match solve(&with_start) {
            Ok(orbit) if orbit.stable => return Ok(orbit),
            Ok(orbit) => {
                unstable.get_or_insert(orbit);
            }
            Err(e) => last_error = Some(e),
        }
    }
    if let Some(orbit) = unstable {
        return Ok(orbit);
    }
    Err(SystemError::OrbitNotFound {
        cycles: guess.forcing_cycles,
        impacts: guess.impacts,
        why: reason(
            model,
            guess,
            &history,
            detected,
            from_run.len(),
            tried.len(),
            last_error,
        ),
    })
}

/// `guess` with its numbers set: 0 asks for the run's detected period, else (1, 1).
fn resolved(guess: &OrbitGuess, detected: Option<(u32, u32)>) -> OrbitGuess {
    if guess.forcing_cycles > 0 && guess.impacts > 0 {
        return *guess;
    }
    let (n, m) = detected.unwrap_or((1, 1));
    OrbitGuess {
        forcing_cycles: if guess.forcing_cycles > 0 {
            guess.forcing_cycles
        } else {
            m
        },
        impacts: if guess.impacts > 0 { guess.impacts } else { n },
        ..*guess
    }
}

fn same(a: &GuessStart, b: &GuessStart) -> bool {
    let d = (a.phase - b.phase).rem_euclid(TAU);
    a.stop == b.stop
        && d.min(TAU - d) <= SAME_START
        && (a.v_in - b.v_in).abs() <= SAME_START * a.v_in.abs().max(b.v_in.abs())
}

/// The run's isolated impacts (no chatter, no resting, a rebound), the detected cycle's first
/// and then from the last backwards.
fn run_starts(history: &History, period: f64) -> Vec<GuessStart> {
    let impacts = &history.impacts;
    let isolated = |i: usize| {
        let r = &impacts[i];
        let flight_after = impacts.get(i + 1).map(|n| n.t - r.t);
        r.kind == ImpactKind::Impact
            && r.v_out > 0.0
            && r.v_in > 0.0
            && flight_after.is_none_or(|f| f > CHATTER_FLIGHT * period)
            && impacts
                .get(i + 1)
                .is_none_or(|n| n.kind == ImpactKind::Impact)
            && (i == 0 || r.t - impacts[i - 1].t > CHATTER_FLIGHT * period)
    };
    let start = |r: &ImpactRecord| GuessStart {
        phase: r.phase,
        v_in: r.v_in,
        stop: r.stop,
    };
    let cycle = history.period(period).map_or(0, |(n, _)| n as usize);
    let mut order: Vec<usize> = (impacts.len().saturating_sub(cycle)..impacts.len()).collect();
    order.extend((0..impacts.len().saturating_sub(cycle)).rev());
    let mut starts: Vec<GuessStart> = Vec::new();
    for i in order.into_iter().filter(|&i| isolated(i)) {
        let s = start(&impacts[i]);
        if !starts.iter().any(|t| same(t, &s)) {
            starts.push(s);
        }
        if starts.len() == RUN_STARTS {
            break;
        }
    }
    starts
}

/// A grid of starts on every stop: 16 phases, and speeds of half, once and twice `speed`.
pub(crate) fn grid(model: &SystemModel, speed: f64) -> Vec<GuessStart> {
    let mut starts = Vec::new();
    for factor in [1.0, 0.5, 2.0] {
        for k in 0..16 {
            for stop in 0..model.spec.stops() {
                starts.push(GuessStart {
                    phase: TAU * k as f64 / 16.0,
                    v_in: factor * speed,
                    stop,
                });
            }
        }
    }
    starts
}

/// A speed of the system's impacts for an orbit of `cycles` forcing periods, m/s: for the ball the
/// approach speed of a flight of that many periods under gravity, gmT/(1 + e) (docs/physics.md
/// §8.1); for the oscillator the amplitude of its forced response's velocity, ω|P| with
/// P = f/(ω₀² − ω² + 2iζω₀ω) (docs/systems.md §2).
pub(crate) fn speed_scale(model: &SystemModel, cycles: u32) -> f64 {
    let period = model.spec.period();
    match model.spec.kind {
        SystemKind::BouncingBall { gravity, .. } => {
            gravity * f64::from(cycles.max(1)) * period / (1.0 + model.restitution)
        }
        SystemKind::ImpactOscillator { .. } => model.spec.oscillator(model.mass).map_or(0.0, |o| {
            let re = o.omega0 * o.omega0 - o.omega * o.omega;
            let im = 2.0 * o.zeta * o.omega0 * o.omega;
            o.omega * o.forcing / re.hypot(im)
        }),
    }
}

/// Why no orbit was found, in words with the numbers that say it.
fn reason(
    model: &SystemModel,
    guess: &OrbitGuess,
    history: &History,
    detected: Option<(u32, u32)>,
    from_run: usize,
    tried: usize,
    last_error: Option<SystemError>,
) -> String {
    let chatters = history
        .impacts
        .iter()
        .filter(|i| i.kind != ImpactKind::Impact)
        .count();
    let run = match (history.end, from_run) {
        (EndReason::StuckForever, 0) => {
            "the run from rest comes to rest on the stop for good".to_string()
        }
        (_, 0) if history.impacts.is_empty() => "the run from rest records no impacts".into(),
        (_, 0) => format!(
            "the run from rest only chatters and sticks ({chatters} chatter ends or resting \
             phases, no isolated impacts)"
        ),
        (_, n) => format!("{n} isolated impacts of the run"),
    };
    let mut why = format!("{run}; Newton started from {tried} points and converged from none");
    if let Some(e) = last_error {
        why.push_str(&format!(" (the last: {e})"));
    }
    match detected {
        Some((n, m)) if (n, m) != (guess.impacts, guess.forcing_cycles) => {
            why.push_str(&format!(
                "; the run settles on an orbit of {n} impact{} in {m} forcing period{}{}",
                if n == 1 { "" } else { "s" },
                if m == 1 { "" } else { "s" },
                if chatters > 0 {
                    " that chatters or sticks"
                } else {
                    ": ask for that one"
                }
            ));
        }
        _ => {}
    }
    // The ball's one-impact orbits of m periods exist only from Γ_SN = mπ(1−e)/(1+e)
    // (docs/physics.md §8.1).
    if let (
        SystemKind::BouncingBall {
            amplitude, gravity, ..
        },
        1,
    ) = (model.spec.kind, guess.impacts)
    {
        let e = model.restitution;
        let omega = model.spec.omega();
        let gamma = amplitude * omega * omega / gravity;
        let m = guess.forcing_cycles;
        let sn = f64::from(m) * PI * (1.0 - e) / (1.0 + e);
        if gamma < sn {
            let pi = if m == 1 {
                "π".to_string()
            } else {
                format!("{m}π")
            };
            why.push_str(&format!(
                "; a ball's orbit of one impact in {m} forcing period{} exists only from \
                 Γ = {pi}(1−e)/(1+e) = {sn:.4}, and Γ = {gamma:.4} here",
                if m == 1 { "" } else { "s" }
            ));
        }
    }
    why
}
