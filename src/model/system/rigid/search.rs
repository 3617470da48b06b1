//! The certified search for the first impact of a flight (docs/systems.md §3).
//!
//! With |g''| ≤ M over the flight, from a point where g > 0:
//! - g(t+τ) ≥ g + g'τ − Mτ²/2, so no root lies before τ_l = (g' + √(g'² + 2Mg))/M: the step is
//!   safe (conservative advancement);
//! - if g' < 0 and D = g'² − 2Mg > 0, then g(t+τ) ≤ g + g'τ + Mτ²/2 is ≤ 0 at
//!   τ_u = (−g' − √D)/M, and g' ≤ g' + Mτ < 0 on [0, τ_u]: exactly one root, in [τ_l, τ_u],
//!   found by Newton kept inside that bracket.
//!
//! A grazing approach (g' → 0 as g → 0) never brackets and is stepped past; a gap within the
//! evaluation's rounding while closing counts as a contact at zero speed.

use crate::model::system::error::SystemError;

use super::dynamics::{Flight, Point};

/// Steps of one flight's search before it gives up with an error (never hangs).
const MAX_STEPS: usize = 200_000;

/// What a flight meets first.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Found {
    /// The gap to `stop` closes at τ.
    Impact { tau: f64, stop: usize, point: Point },
    /// Nothing before τ = horizon.
    Nothing,
}

/// The first impact of `flight` in (τ_start, horizon], τ_start ≥ 0 a point known to be free.
pub(crate) fn first_impact(
    flight: &Flight,
    tau_start: f64,
    horizon: f64,
) -> Result<Found, SystemError> {
    let mut tau = tau_start;
    for _ in 0..MAX_STEPS {
        let point = flight.at(tau);
        let mut safe = f64::INFINITY;
        let mut bracket: Option<(usize, f64, f64)> = None;
        for stop in 0..flight.stop_count {
            let (g, gd) = flight.gap(stop, &point);
            let m = flight.bounds[stop];
            if gd <= 0.0 && g <= point.noise && (tau > tau_start || g < 0.0) {
                return Ok(Found::Impact { tau, stop, point });
            }
            let g = g.max(0.0);
            let step = if m > 0.0 {
                (gd + (gd * gd + 2.0 * m * g).sqrt()) / m
            } else if gd < 0.0 {
                g / -gd
            } else {
                f64::INFINITY
            };
            if gd < 0.0 {
                let d = gd * gd - 2.0 * m * g;
                if d > 0.0 {
                    let upper = if m > 0.0 {
                        (-gd - d.sqrt()) / m
                    } else {
                        g / -gd
                    };
                    let earliest = bracket.is_none_or(|(_, _, u)| tau + upper < u);
                    if earliest {
                        bracket = Some((stop, tau + step, tau + upper));
                    }
                }
            }
            safe = safe.min(step);
        }
        if let Some((stop, lo, hi)) = bracket {
            // The bracketed root is first if every other stop is certainly free up to it.
            let others_free = (0..flight.stop_count).all(|k| {
                k == stop || {
                    let (g, gd) = flight.gap(k, &point);
                    let m = flight.bounds[k];
                    let step = (gd + (gd * gd + 2.0 * m * g.max(0.0)).sqrt()) / m;
                    tau + step >= hi
                }
            });
            if others_free {
                if lo > horizon {
                    return Ok(Found::Nothing);
                }
                let tau = root_in(flight, stop, lo, hi);
                if tau > horizon {
                    return Ok(Found::Nothing);
                }
                let point = flight.at(tau);
                return Ok(Found::Impact { tau, stop, point });
            }
        }
        let next = tau + safe;
        if next > horizon {
            return Ok(Found::Nothing);
        }
        if next == tau {
            // The safe step is below the resolution of t: the gap is at rounding level.
            let stop = (0..flight.stop_count)
                .min_by(|&a, &b| flight.gap(a, &point).0.total_cmp(&flight.gap(b, &point).0))
                .unwrap_or(0);
            return Ok(Found::Impact { tau, stop, point });
        }
        tau = next;
    }
    let point = flight.at(tau);
    Err(SystemError::SearchBudget {
        steps: MAX_STEPS,
        from: flight.t0,
        gap: flight.gap(0, &point).0,
    })
}

/// The unique root of the gap to `stop` in [lo, hi] (g ≥ 0 at lo, ≤ 0 at hi, g' < 0 between):
/// Newton, falling back to bisection when a step leaves the bracket.
fn root_in(flight: &Flight, stop: usize, mut lo: f64, mut hi: f64) -> f64 {
    let mut tau = lo;
    for _ in 0..100 {
        let (g, gd) = flight.gap(stop, &flight.at(tau));
        if g == 0.0 {
            return tau;
        }
        if g > 0.0 {
            lo = tau;
        } else {
            hi = tau;
        }
        let newton = tau - g / gd;
        let next = if gd < 0.0 && newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        let resolution = 2.0 * f64::EPSILON * (flight.t0.abs() + next.abs());
        if (next - tau).abs() <= resolution || hi - lo <= resolution {
            return next;
        }
        tau = next;
    }
    tau
}
