//! A stretch of a compliant motion in time, from a state in flight to a given time: the flights
//! in closed form and the contacts through the law (the compliant solver's own steps), with every
//! approach of the body to a stop recorded as a signed clearance (docs/continuation.md §3): a
//! contact's −δ_max, or a flight's gap minimum. Both tend to zero at a grazing contact, from
//! either side, so the clearance of one approach is continuous through grazing.

use std::f64::consts::TAU;
use std::mem::take;

use crate::model::system::ImpactPoint;
use crate::model::system::compliant::CompliantStop;
use crate::model::system::compliant::contact::Exit;
use crate::model::system::compliant::flight::{Flight, Landing};
use crate::model::system::compliant::plant::Plant;
use crate::model::system::compliant::plant_of::SystemPlant;

use super::error::ContinuationError;

/// Samples of a flight per forcing period and per free period, for its gap minima.
const SAMPLES_PER_PERIOD: f64 = 64.0;

/// One approach of the body to a stop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Clearance {
    /// When, s: a flight's gap minimum, or a contact's middle.
    pub t: f64,
    /// Which stop.
    pub stop: usize,
    /// The smallest gap, m; negative in a contact: −the contact's largest approach δ_max.
    pub value: f64,
}

/// What a stretch of motion went through.
#[derive(Debug, Clone)]
pub(crate) struct Journey {
    /// (x, v) at the stretch's end.
    pub end: (f64, f64),
    /// The contacts, in time order, as orbit points (time and approach speed at first contact).
    pub impacts: Vec<ImpactPoint>,
    /// Every approach to a stop, in time order.
    pub clearances: Vec<Clearance>,
    /// The flights: start, end and closed form.
    pub flights: Vec<(f64, f64, Flight)>,
}

/// The motion from (t, x, v) in flight to `t_end` (`after_touch`: the state is a touch's end,
/// the first instant known free). A contact still on at `t_end` is refused: the stretch must end
/// in flight.
pub(crate) fn journey(
    stop: &CompliantStop,
    from: (f64, f64, f64),
    t_end: f64,
    after_touch: bool,
) -> Result<Journey, ContinuationError> {
    let plant = &stop.plant;
    let omega = plant.omega();
    let mut state = from;
    let mut touched = after_touch;
    let mut impacts = Vec::new();
    let mut clearances = Vec::new();
    let mut flights = Vec::new();
    loop {
        let flight = if take(&mut touched) {
            stop.flight_after_touch(state, t_end)?
        } else {
            stop.flight(state, t_end)?
        };
        let landing = match flight.landing {
            Landing::Contact { t, .. } => t,
            Landing::TimeLimit { .. } => t_end,
        };
        gap_minima(plant, &flight, (state.0, landing), &mut clearances);
        flights.push((state.0, landing, flight));
        let Landing::Contact { stop: i, t, x, v } = flight.landing else {
            return Ok(Journey {
                end: flight.at(t_end),
                impacts,
                clearances,
                flights,
            });
        };
        let c = stop.contact(i, t, v, t_end, false)?;
        let Exit::Free {
            t: te,
            x: xe,
            v: ve,
        } = c.exit
        else {
            return Err(ContinuationError::Unsupported(
                "a compliant contact is still on at the orbit's section (the body rests on the \
                 stop, or a contact has moved onto the section's phase)"
                    .into(),
            ));
        };
        impacts.push(ImpactPoint {
            t,
            phase: (omega * t).rem_euclid(TAU),
            x,
            stop: i,
            v_in: c.v_in,
            v_out: c.v_out.max(0.0),
        });
        clearances.push(Clearance {
            t: 0.5 * (c.t_start + c.t_end),
            stop: i,
            value: -c.max_approach,
        });
        touched = c.t_end == c.t_start;
        state = (te, xe, ve);
    }
}

/// The interior minima over (a, b) of a function whose rate is `rate`: sampled against the
/// fastest motion `fastest` (rad/s), a minimum where the rate turns from negative to
/// non-negative, refined by bisection on the rate. The rigid and compliant flights share it.
pub(super) fn minima(rate: impl Fn(f64) -> f64, (a, b): (f64, f64), fastest: f64) -> Vec<f64> {
    let samples = (SAMPLES_PER_PERIOD * (b - a) * fastest / TAU)
        .ceil()
        .clamp(SAMPLES_PER_PERIOD, 1e5) as usize;
    let mut found = Vec::new();
    let mut prev = (a, rate(a));
    for k in 1..samples {
        let t = a + (b - a) * k as f64 / samples as f64;
        let here = (t, rate(t));
        if prev.1 < 0.0 && here.1 >= 0.0 {
            let (mut lo, mut hi) = (prev.0, here.0);
            for _ in 0..80 {
                let mid = 0.5 * (lo + hi);
                if rate(mid) < 0.0 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            found.push(0.5 * (lo + hi));
        }
        prev = here;
    }
    found
}

/// The fastest motion a flight has: the forcing's, or the oscillator's free one, rad/s.
fn fastest(plant: &SystemPlant) -> f64 {
    match *plant {
        SystemPlant::Ball { omega, .. } => omega,
        SystemPlant::Oscillator { omega, omega0, .. } => omega.max(omega0),
    }
}

/// The interior minima of every stop's gap over the flight's (a, b), appended to `out`.
fn gap_minima(plant: &SystemPlant, flight: &Flight, (a, b): (f64, f64), out: &mut Vec<Clearance>) {
    if b <= a {
        return;
    }
    let mut found = Vec::new();
    for i in 0..plant.stop_count() {
        // g and g' of stop i at t.
        let gap = |t: f64| {
            let (x, v) = flight.at(t);
            let s = plant.stop(i, t);
            (s.gap(x), s.side * (v - s.sd))
        };
        for t in minima(|t| gap(t).1, (a, b), fastest(plant)) {
            found.push(Clearance {
                t,
                stop: i,
                value: gap(t).0,
            });
        }
    }
    found.sort_by(|p, q| p.t.total_cmp(&q.t));
    out.extend(found);
}
