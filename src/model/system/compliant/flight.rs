//! Flight between contacts of a compliant stop: the rigid solver's closed-form flight and its
//! certified search for the first impact (docs/systems.md §3), so that a compliant stop misses
//! no contact either, and a flight costs one bracketed root of its gap function.

use crate::model::system::SystemError;
use crate::model::system::rigid::dynamics::{Dynamics, Flight as Closed};
use crate::model::system::rigid::search::{Found, first_impact};

/// Forcing periods searched at a time along a flight (one search's step budget bounds a stretch).
const STRETCH: f64 = 64.0;

/// How a flight ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Landing {
    /// The gap to stop `stop` closes at t with the body at (x, v).
    Contact { stop: usize, t: f64, x: f64, v: f64 },
    /// `t_limit` came first.
    TimeLimit { t: f64, x: f64, v: f64 },
}

/// A flight's end, and the closed form to sample it by.
#[derive(Debug, Clone, Copy)]
pub struct Flight {
    pub landing: Landing,
    closed: Closed,
}

impl Flight {
    /// The body's (x, v) at t during the flight.
    pub fn at(&self, t: f64) -> (f64, f64) {
        let p = self.closed.at(t - self.closed.t0);
        (self.closed.x0 + p.dx, p.v)
    }
}

/// The free flight of `dynamics` from (t₀, x₀, v₀) to the first contact or `t_limit`, the search
/// starting `free` seconds in (a stretch known free: a body that touched a stop with no approach
/// speed and is pulled away from it).
pub(crate) fn fly(
    dynamics: &Dynamics,
    (t0, x0, v0): (f64, f64, f64),
    t_limit: f64,
    free: f64,
) -> Result<Flight, SystemError> {
    let (mut t, mut x, mut v) = (t0, x0, v0);
    let mut free = free;
    loop {
        let closed = dynamics.flight(t, x, v);
        let stretch = (t_limit - t).min(STRETCH * dynamics.period);
        match first_impact(&closed, std::mem::take(&mut free).min(stretch), stretch)? {
            Found::Impact { tau, stop, point } => {
                return Ok(Flight {
                    landing: Landing::Contact {
                        stop,
                        t: t + tau,
                        x: x + point.dx,
                        v: point.v,
                    },
                    closed,
                });
            }
            Found::Nothing => {
                let p = closed.at(stretch);
                (t, x, v) = (t + stretch, x + p.dx, p.v);
                if t >= t_limit {
                    return Ok(Flight {
                        landing: Landing::TimeLimit { t, x, v },
                        closed,
                    });
                }
            }
        }
    }
}
