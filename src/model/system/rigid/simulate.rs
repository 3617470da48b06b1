//! The event loop of the rigid solver: flights, impacts, chatter and sticking.

use std::f64::consts::TAU;

use crate::model::system::error::SystemError;
use crate::model::system::model::SystemModel;
use crate::model::system::run::{
    EndReason, History, ImpactKind, ImpactRecord, RunOptions, State, Stick, SystemSample,
};

use super::dynamics::Dynamics;
use super::search::{Found, first_impact};

/// A chatter sequence is summed in closed form once what remains of it would last less than this
/// fraction of a forcing period: the constant-acceleration sum 2v/(a(1 − e)) is then exact to
/// about (this fraction)²·ωT of a period (docs/systems.md §4).
pub const CHATTER_WINDOW: f64 = 1e-6;

/// Forcing periods searched at a time along a flight.
const FLIGHT_STRETCH: f64 = 64.0;

/// What the body does next.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Phase {
    /// Flying from this state; the search starts at τ = `free_until` (a stretch known free).
    Flight { state: State, free_until: f64 },
    /// Resting on `stop` since `since`.
    Stuck { stop: usize, since: f64 },
    /// The recorded impacts are complete.
    Done(State),
}

/// The outcome of one impact.
pub(crate) enum AfterImpact {
    Flight(State),
    /// Chatter summed to its accumulation point, or an impact at zero speed: the body rests.
    Rests {
        at: f64,
        chatter: bool,
    },
}

/// Applies Newton's restitution at an impact on `stop` at `t` with velocity `v`: the state after
/// it (on the stop exactly) and the speeds in and out relative to the stop.
pub(crate) fn impact(dynamics: &Dynamics, stop: usize, t: f64, v: f64) -> (State, f64, f64) {
    let (s, sv, _) = dynamics.stop_motion(stop, t);
    let sigma = dynamics.stops[stop].sigma;
    let v_in = (-sigma * (v - sv)).max(0.0);
    let v_out = dynamics.restitution * v_in;
    // Set exactly on the stop: rounding never leaves the body inside it.
    (
        State {
            t,
            x: s,
            v: sv + sigma * v_out,
        },
        v_in,
        v_out,
    )
}

/// What follows an impact leaving the stop at speed `v_out`: a flight, or rest (chatter summed).
pub(crate) fn after_impact(
    dynamics: &Dynamics,
    stop: usize,
    state: State,
    v_out: f64,
) -> AfterImpact {
    let e = dynamics.restitution;
    let tiny = 1e-13 * dynamics.speed_scale;
    if v_out <= tiny {
        return AfterImpact::Rests {
            at: state.t,
            chatter: false,
        };
    }
    // Not even the largest pressing acceleration brings the body back within the window: a
    // flight (skips evaluating the pressing at most impacts).
    let (c0, c1, c2) = dynamics.pressing(stop);
    let most = c0 + c1.hypot(c2);
    if e >= 1.0
        || most <= 0.0
        || 2.0 * v_out / (most * (1.0 - e)) >= CHATTER_WINDOW * dynamics.period
    {
        return AfterImpact::Flight(state);
    }
    let pressing = dynamics.pressing_at(stop, state.t);
    if pressing > 0.0 {
        // Under a constant pressing acceleration a the flights last 2v/a, 2ev/a, …: the
        // impacts accumulate at 2v/(a(1 − e)) (docs/physics.md §8.4).
        let remaining = 2.0 * v_out / (pressing * (1.0 - e));
        if remaining < CHATTER_WINDOW * dynamics.period {
            return AfterImpact::Rests {
                at: state.t + remaining,
                chatter: true,
            };
        }
    }
    AfterImpact::Flight(state)
}

/// Simulates `model` with a rigid stop of restitution `restitution` (see [`super`]).
pub fn simulate(
    model: &SystemModel,
    restitution: f64,
    options: &RunOptions,
) -> Result<History, SystemError> {
    model.validate()?;
    crate::model::error::require("impact.restitution", restitution, "in [0, 1]", |e| {
        (0.0..=1.0).contains(&e)
    })?;
    let dynamics = Dynamics::new(model, restitution);
    let mut run = Run::new(&dynamics, model, options);
    let start = options.initial.unwrap_or_else(|| dynamics.rest_state(0.0));
    let t_max = start.t + options.max_periods * dynamics.period;
    let mut phase = run.start(start)?;
    loop {
        phase = match phase {
            Phase::Done(state) => return Ok(run.finish(EndReason::Recorded, state)),
            Phase::Stuck { stop, since } => match dynamics.release(stop, since) {
                None => {
                    run.stick(stop, since, None, t_max);
                    return Ok(run.finish(
                        EndReason::StuckForever,
                        State {
                            t: since,
                            x: dynamics.stop_motion(stop, since).0,
                            v: dynamics.stop_motion(stop, since).1,
                        },
                    ));
                }
                Some((leave, window)) => {
                    if leave > t_max {
                        run.stick(stop, since, None, t_max);
                        let (x, v, _) = dynamics.stop_motion(stop, t_max);
                        return Ok(run.finish(EndReason::TimeLimit, State { t: t_max, x, v }));
                    }
                    run.stick(stop, since, Some(leave), t_max);
                    let (x, v, _) = dynamics.stop_motion(stop, leave);
                    let free = (0.5 * window.min(dynamics.liftoff_horizon())).min(dynamics.period);
                    Phase::Flight {
                        state: State { t: leave, x, v },
                        free_until: free,
                    }
                }
            },
            Phase::Flight { state, free_until } => {
                let flight = dynamics.flight(state.t, state.x, state.v);
                // A long flight is searched a stretch at a time, so that one search's step budget
                // bounds a stretch, not the run.
                let stretch = (t_max - state.t).min(FLIGHT_STRETCH * dynamics.period);
                match first_impact(&flight, free_until, stretch)? {
                    Found::Nothing => {
                        let end = state.t + stretch;
                        let p = flight.at(stretch);
                        run.samples_of(&flight, end);
                        let next = State {
                            t: end,
                            x: state.x + p.dx,
                            v: p.v,
                        };
                        if end >= t_max {
                            return Ok(run.finish(EndReason::TimeLimit, next));
                        }
                        Phase::Flight {
                            state: next,
                            free_until: 0.0,
                        }
                    }
                    Found::Impact { tau, stop, point } => {
                        let t = state.t + tau;
                        run.samples_of(&flight, t);
                        let (after, v_in, v_out) = impact(&dynamics, stop, t, point.v);
                        run.sample_point(t, state.x + point.dx, point.v);
                        if run.impact(stop, after, v_in, v_out, ImpactKind::Impact)? {
                            return Ok(run.finish(EndReason::Recorded, after));
                        }
                        run.sample_point(t, after.x, after.v);
                        match after_impact(&dynamics, stop, after, v_out) {
                            AfterImpact::Flight(state) => Phase::Flight {
                                state,
                                free_until: 0.0,
                            },
                            AfterImpact::Rests { at, chatter } => {
                                if chatter {
                                    let (x, v, _) = dynamics.stop_motion(stop, at);
                                    let rest = State { t: at, x, v };
                                    if run.impact(stop, rest, 0.0, 0.0, ImpactKind::ChatterEnd)? {
                                        return Ok(run.finish(EndReason::Recorded, rest));
                                    }
                                }
                                Phase::Stuck { stop, since: at }
                            }
                        }
                    }
                }
            }
        };
    }
}

/// The bookkeeping of one run: counts, records, samples.
struct Run<'a> {
    dynamics: &'a Dynamics,
    model: &'a SystemModel,
    options: &'a RunOptions,
    history: History,
    /// Sample spacing, s (∞: none).
    dt: f64,
}

impl<'a> Run<'a> {
    fn new(dynamics: &'a Dynamics, model: &'a SystemModel, options: &'a RunOptions) -> Run<'a> {
        Run {
            dynamics,
            model,
            options,
            history: History {
                dents: Default::default(),
                samples: Vec::new(),
                impacts: Vec::with_capacity(options.recorded_impacts.min(1 << 16)),
                sticks: Vec::new(),
                impacts_total: 0,
                last_impact: None,
                end_state: State {
                    t: 0.0,
                    x: 0.0,
                    v: 0.0,
                },
                end: EndReason::TimeLimit,
            },
            dt: if options.samples_per_period > 0 {
                dynamics.period / options.samples_per_period as f64
            } else {
                f64::INFINITY
            },
        }
    }

    fn recording(&self) -> bool {
        self.history.impacts_total >= self.options.transient_impacts
    }

    /// The first phase from a given state: inside a stop is refused, on a stop it is an impact.
    fn start(&mut self, state: State) -> Result<Phase, SystemError> {
        let d = self.dynamics;
        for stop in 0..d.stop_count {
            let (s, sv, _) = d.stop_motion(stop, state.t);
            let sigma = d.stops[stop].sigma;
            let gap = sigma * (state.x - s);
            let tolerance = 1e-12 * d.length_scale;
            if gap < -tolerance {
                return Err(crate::model::error::ModelError::InvalidParameter {
                    field: "initial state x".into(),
                    requirement: "outside the stops",
                    value: state.x,
                }
                .into());
            }
            if gap <= tolerance {
                let rate = sigma * (state.v - sv);
                let tiny = 1e-13 * d.speed_scale;
                // On the stop and leaving it: a flight from exactly there.
                if rate > tiny {
                    let on = State { x: s, ..state };
                    return Ok(Phase::Flight {
                        state: on,
                        free_until: 0.0,
                    });
                }
                let (after, v_in, v_out) = impact(d, stop, state.t, state.v);
                if rate < -tiny && self.impact(stop, after, v_in, v_out, ImpactKind::Impact)? {
                    return Ok(Phase::Done(after));
                }
                return Ok(match after_impact(d, stop, after, v_out) {
                    AfterImpact::Flight(state) => Phase::Flight {
                        state,
                        free_until: 0.0,
                    },
                    AfterImpact::Rests { at, .. } => Phase::Stuck { stop, since: at },
                });
            }
        }
        Ok(Phase::Flight {
            state,
            free_until: 0.0,
        })
    }

    /// Counts an impact (recording it after the transient); true when the run is complete.
    fn impact(
        &mut self,
        stop: usize,
        after: State,
        v_in: f64,
        v_out: f64,
        kind: ImpactKind,
    ) -> Result<bool, SystemError> {
        let recording = self.recording();
        self.history.impacts_total += 1;
        self.history.last_impact = Some(after.t);
        if self.history.impacts_total > self.options.max_impacts {
            return Err(SystemError::ImpactBudget {
                what: "the simulation".into(),
                budget: self.options.max_impacts,
                time: after.t,
            });
        }
        if recording {
            self.history.impacts.push(ImpactRecord {
                t: after.t,
                phase: (self.dynamics.omega * after.t).rem_euclid(TAU),
                x: after.x,
                stop,
                v_in,
                v_out,
                peak_force: None,
                // The Hertz estimate (eqs 5–6) of the peak force at this impact's speed.
                peak_force_estimate: if v_in > 0.0 {
                    self.model.peak_force_estimate(v_in)
                } else {
                    None
                },
                contact_time: None,
                energy_lost: 0.5 * self.model.mass * (v_in * v_in - v_out * v_out),
                kind,
            });
            return Ok(self.history.impacts.len() >= self.options.recorded_impacts);
        }
        Ok(false)
    }

    fn stick(&mut self, stop: usize, since: f64, until: Option<f64>, t_max: f64) {
        if !self.recording() {
            return;
        }
        self.history.sticks.push(Stick {
            start: since,
            end: until,
            stop,
        });
        if self.dt.is_finite() {
            let end = until.unwrap_or(t_max).min(t_max);
            let mut k = (since / self.dt).ceil();
            while k * self.dt < end {
                let t = k * self.dt;
                let (x, v, _) = self.dynamics.stop_motion(stop, t);
                self.push_sample(t, x, v);
                k += 1.0;
            }
        }
    }

    /// Samples of a flight on the sample grid up to `until`.
    fn samples_of(&mut self, flight: &super::dynamics::Flight, until: f64) {
        if !self.dt.is_finite() || !self.recording() {
            return;
        }
        let mut k = (flight.t0 / self.dt).floor() + 1.0;
        while k * self.dt < until {
            let t = k * self.dt;
            let p = flight.at(t - flight.t0);
            self.push_sample(t, flight.x0 + p.dx, p.v);
            k += 1.0;
        }
    }

    fn sample_point(&mut self, t: f64, x: f64, v: f64) {
        if self.dt.is_finite() && self.recording() {
            self.push_sample(t, x, v);
        }
    }

    fn push_sample(&mut self, t: f64, x: f64, v: f64) {
        let stop = self.dynamics.stop_motion(0, t).0;
        self.history.samples.push(SystemSample { t, x, v, stop });
    }

    fn finish(mut self, end: EndReason, state: State) -> History {
        self.history.end = end;
        self.history.end_state = state;
        self.history
    }
}
