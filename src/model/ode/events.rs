//! Event detection and location on the dense output of an accepted step.
//!
//! Each event function is sampled at the step ends and at a few interior points of the step's
//! interpolant, so that a double crossing inside one step (g dipping below zero and back) is not
//! missed; the first sign change in the event's direction is then bracketed and its root located
//! with Brent's zeroin (`model::numeric::roots`).

use crate::model::numeric::roots::zeroin;

use super::{Direction, Event, Segment, State};

/// Interior sample points per step: the step is split into this many equal sub-intervals.
const SUBDIVISIONS: usize = 4;

/// The earliest event in one step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Hit {
    pub index: usize,
    pub t: f64,
    pub y: State,
}

/// Remembers each event's value at the current step start.
pub(super) struct EventTracker {
    g_prev: Vec<f64>,
}

/// Whether g going from `ga` to `gb` is a crossing in `direction`. A zero at the start never
/// counts (so an event sitting exactly on zero at t₀ does not fire there); reaching zero at the
/// end does.
fn crosses(direction: Direction, ga: f64, gb: f64) -> bool {
    let rising = ga < 0.0 && gb >= 0.0;
    let falling = ga > 0.0 && gb <= 0.0;
    match direction {
        Direction::Rising => rising,
        Direction::Falling => falling,
        Direction::Either => rising || falling,
    }
}

impl EventTracker {
    pub(super) fn new(events: &[Event], t0: f64, y0: &State) -> Self {
        EventTracker {
            g_prev: events.iter().map(|e| (e.g)(t0, y0)).collect(),
        }
    }

    /// Looks for events in [t_a, t_b] of `segment` (t_b is the step end, or `t_max` inside the
    /// step), where the state at t_b is `y_b`. Returns the earliest located event; otherwise
    /// advances the stored values to t_b.
    pub(super) fn check(
        &mut self,
        events: &[Event],
        segment: &Segment,
        t_a: f64,
        t_b: f64,
        y_b: &State,
    ) -> Option<Hit> {
        if events.is_empty() {
            return None;
        }
        let mut best: Option<Hit> = None;
        // Interior sample times and states are shared by all events.
        let mut ts = [0.0; SUBDIVISIONS + 1];
        let mut ys = [State::zeros(); SUBDIVISIONS + 1];
        // Index 0 is the step start, whose g values are remembered in `g_prev`; its state is
        // never needed.
        ts[0] = t_a;
        for k in 1..SUBDIVISIONS {
            ts[k] = t_a + (t_b - t_a) * (k as f64 / SUBDIVISIONS as f64);
            ys[k] = segment.eval(ts[k]);
        }
        ts[SUBDIVISIONS] = t_b;
        ys[SUBDIVISIONS] = *y_b;

        for (index, event) in events.iter().enumerate() {
            let mut ga = self.g_prev[index];
            for k in 1..=SUBDIVISIONS {
                let gb = (event.g)(ts[k], &ys[k]);
                if crosses(event.direction, ga, gb) {
                    // Only an event earlier than the best so far matters.
                    if best.is_some_and(|b| b.t <= ts[k - 1]) {
                        break;
                    }
                    let t = locate(|t| (event.g)(t, &segment.eval(t)), ts[k - 1], ts[k], ga, gb);
                    if best.is_none_or(|b| t < b.t) {
                        let y = if t == t_b { *y_b } else { segment.eval(t) };
                        best = Some(Hit { index, t, y });
                    }
                    break;
                }
                ga = gb;
            }
            // Without a crossing the loop ran to t_b, so ga = g(t_b, y_b): the next step's start.
            // (With one, integration stops and the stale value is never read.)
            self.g_prev[index] = ga;
        }
        best
    }
}

/// The root of g on [a, b] with g(a) = ga, g(b) = gb of opposite signs (or gb = 0), by Brent's
/// zeroin to |bracket| ≤ 4·ε·|t|. Returns the bracket end on the far side of the crossing (where g
/// has already changed sign or is zero), so the returned point is never before the event.
pub(super) fn locate(g: impl FnMut(f64) -> f64, a: f64, b: f64, ga: f64, gb: f64) -> f64 {
    if gb == 0.0 {
        return b;
    }
    let bracket = zeroin(g, a, b, ga, gb);
    if bracket.f_best == 0.0 || bracket.f_best.signum() == gb.signum() {
        bracket.best
    } else {
        bracket.other
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn brent_finds_pi_to_a_few_ulps() {
        let mut n = 0;
        let t = locate(
            |t| {
                n += 1;
                t.sin()
            },
            3.0,
            3.5,
            3.0f64.sin(),
            3.5f64.sin(),
        );
        assert!(
            (t - std::f64::consts::PI).abs() <= 4.0 * f64::EPSILON * 4.0,
            "{t}"
        );
        // Far side: sin is already negative (or zero) at the returned point.
        assert!(t.sin() <= 0.0);
        assert!(n < 20, "{n} evaluations");
    }

    #[test]
    fn brent_returns_the_far_side_in_both_orientations() {
        // Rising crossing of t − 1/3 on [0, 1].
        let t = locate(|t| t - 1.0 / 3.0, 0.0, 1.0, -1.0 / 3.0, 2.0 / 3.0);
        assert!(t - 1.0 / 3.0 >= 0.0 && t - 1.0 / 3.0 < 1e-15);
        // Falling crossing of 1/3 − t.
        let t = locate(|t| 1.0 / 3.0 - t, 0.0, 1.0, 1.0 / 3.0, -2.0 / 3.0);
        assert!(1.0 / 3.0 - t <= 0.0 && t - 1.0 / 3.0 < 1e-15);
    }

    #[test]
    fn crossing_rules() {
        assert!(crosses(Direction::Rising, -1.0, 0.0));
        assert!(!crosses(Direction::Rising, 0.0, 1.0));
        assert!(!crosses(Direction::Rising, 1.0, -1.0));
        assert!(crosses(Direction::Falling, 1.0, -1.0));
        assert!(!crosses(Direction::Falling, 0.0, -1.0));
        assert!(crosses(Direction::Either, 1.0, -1.0));
        assert!(crosses(Direction::Either, -1.0, 1.0));
        assert!(!crosses(Direction::Either, 1.0, 2.0));
    }
}
