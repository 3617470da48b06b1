//! Flight between contacts of a compliant stop, integrated with the project's integrators: the
//! body's free motion until its gap to a stop falls through zero, located as an event at full
//! order (src/model/ode).
//!
//! Every step's interpolant is sampled at its ends and three interior points for each stop's gap
//! (the event tracker of src/model/ode), with steps no longer than [`STEPS_PER_PERIOD`]⁻¹ of the
//! forcing period; a step that ends inside a stop without a located crossing (a flight that starts
//! on the surface and turns straight back in) aborts the flight and is reported as a contact
//! starting at once, so the body never passes into a stop unseen at a step end.

use crate::model::ode::{
    self, DenseOutput, Direction, Event, Method, OdeError, OdeSystem, State, Stop,
};

use super::plant::Plant;

/// Flight steps per forcing period at most.
pub const STEPS_PER_PERIOD: f64 = 32.0;

/// The surface's slack in units of the flight's scale a·T²: far above the rounding of a landed
/// event (~1e-16 of the positions), far below any contact's indentation.
const SLACK: f64 = 1e-12;

/// How a flight ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Landing {
    /// The gap to stop `stop` fell through zero at t with the body at (x, v).
    Contact { stop: usize, t: f64, x: f64, v: f64 },
    /// `t_limit` came first.
    TimeLimit { t: f64, x: f64, v: f64 },
}

/// A flight's end and, if asked, its dense output in (x, v).
#[derive(Debug, Clone)]
pub struct Flight {
    pub landing: Landing,
    pub dense: Option<DenseOutput>,
    /// Right-hand-side evaluations.
    pub evals: usize,
}

struct FreeOde<'a, P> {
    plant: &'a P,
    /// The stop found inside at a step end.
    inside: Option<usize>,
    /// Gaps above −this count as on the surface: an event landed on by Newton's method lies on
    /// either side of it by rounding.
    slack: f64,
}

impl<P: Plant> OdeSystem for FreeOde<'_, P> {
    #[inline]
    fn rhs(&mut self, t: f64, y: &State) -> State {
        State::new(y[1], self.plant.free_accel(t, y[0], y[1]))
    }

    fn check(&mut self, t: f64, y: &State) -> Result<(), String> {
        for i in 0..self.plant.stop_count() {
            if self.plant.stop(i, t).gap(y[0]) < -self.slack {
                self.inside = Some(i);
                return Err(format!("inside stop {i}"));
            }
        }
        Ok(())
    }
}

/// Integrates the free motion from (t₀, x₀, v₀) until a gap falls through zero or `t_limit`.
pub fn fly<P: Plant>(
    plant: &P,
    method: Method,
    rtol: f64,
    (t0, x0, v0): (f64, f64, f64),
    t_limit: f64,
    keep_dense: bool,
) -> Result<Flight, OdeError> {
    let period = plant.period();
    let n = plant.stop_count();
    let gaps: Vec<_> = (0..n)
        .map(|i| move |t: f64, y: &State| plant.stop(i, t).gap(y[0]))
        .collect();
    let events: Vec<Event> = gaps
        .iter()
        .map(|g| Event {
            g: g as &dyn Fn(f64, &State) -> f64,
            direction: Direction::Falling,
        })
        .collect();
    let mut sys = FreeOde {
        plant,
        inside: None,
        slack: SLACK * plant.accel_scale() * period * period,
    };
    // Position and velocity are weighed against the scale the flight covers.
    let opts = ode::Options {
        rtol,
        atol: rtol * plant.accel_scale() * period * period,
        dt: None,
        h_initial: None,
        h_max: period / STEPS_PER_PERIOD,
        t_max: t_limit,
        max_steps: usize::MAX,
    };
    match ode::integrate(method, &mut sys, t0, State::new(x0, v0), &events, &opts) {
        Ok(run) => {
            let landing = match run.stop {
                Stop::Event { index } => Landing::Contact {
                    stop: index,
                    t: run.t,
                    x: run.y[0],
                    v: run.y[1],
                },
                Stop::TimeLimit => Landing::TimeLimit {
                    t: run.t,
                    x: run.y[0],
                    v: run.y[1],
                },
            };
            Ok(Flight {
                landing,
                evals: run.stats.rhs_evals,
                dense: keep_dense.then_some(run.dense),
            })
        }
        Err(OdeError::Aborted { .. }) if sys.inside.is_some() => {
            // Started on a surface and went straight back in: the contact begins at t₀.
            let stop = sys.inside.unwrap_or(0);
            Ok(Flight {
                landing: Landing::Contact {
                    stop,
                    t: t0,
                    x: x0,
                    v: v0,
                },
                evals: 0,
                dense: None,
            })
        }
        Err(e) => Err(e),
    }
}
