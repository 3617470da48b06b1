//! The compliant stop: every contact integrated through a law of the law table with the project's
//! own integrators (src/model/ode), contact turn and end located as events at the method's full
//! order (docs/systems.md, "Compliant stops").
//!
//! - Flights are the rigid solver's closed forms with its certified search for the first impact
//!   (docs/systems.md §3): no contact is missed, and a flight costs one bracketed root.
//! - Each impact's law comes from the scene's bodies (Hertz k, n; eqs 1–9) with its damping set
//!   by [`CompliantDamping`]: from the impact's own incoming velocity for the laws defined that
//!   way (the Hunt–Crossley family's α = χ/v₀, eqs 19–20), from a material constant, or
//!   calibrated to e ([`damping::LawSource`]).
//! - Each impact records its contact time, peak force and energy balance
//!   ([`contact::EnergyAudit`]); [`simulate_detailed`] returns them all.
//! - The impact map is taken at first contact (time, approach speed); periodic orbits are found by
//!   Newton on it with a central-difference Jacobian, whose eigenvalues are the Floquet
//!   multipliers ([`orbit`]).
//! - [`verdict`] compares the rigid and compliant answers for one system (item 6 of issue 25).

pub mod contact;
pub mod damping;
pub mod estimate;
pub mod flight;
pub mod orbit;
pub mod plant;
pub mod plant_of;
pub mod verdict;

use std::f64::consts::TAU;

use serde::Serialize;

use crate::model::force::{ForceModel, ImpactParams};
use crate::model::ode::Method;
use crate::model::power_law::PowerLaw;

use super::{
    CompliantDamping, Dents, EndReason, History, ImpactKind, ImpactRecord, RunOptions, State,
    Stick, SystemError, SystemModel, SystemSample,
};
use contact::{ContactResult, ContactSettings, EnergyAudit, Exit, integrate_contact};
use damping::LawSource;
use flight::{Landing, fly};
use plant::Plant;
use plant_of::SystemPlant;

use super::rigid::dynamics::Dynamics;

/// A contact still held after this many forcing periods is taken to be permanent: the body rests
/// on the stop for ever (the run ends with [`EndReason::StuckForever`]).
pub const HELD_PERIODS: f64 = 4.0;

/// Integrator settings of a compliant run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CompliantOptions {
    /// DOP853 (default) or DOPRI5.
    pub method: Method,
    /// Relative tolerance of the contacts, in their scaled variables (the single-impact solver's
    /// default, 1e-8; orbits take [`ORBIT_RTOL`]).
    pub rtol: f64,
    /// Accepted plus rejected steps allowed per contact.
    pub max_steps_per_contact: usize,
}

impl Default for CompliantOptions {
    fn default() -> Self {
        CompliantOptions {
            method: Method::Dop853,
            rtol: 1e-8,
            max_steps_per_contact: 1_000_000,
        }
    }
}

/// A system with a compliant stop, ready to run: the law source, the elastic law of the bodies
/// and the plant.
#[derive(Debug, Clone)]
pub struct CompliantStop {
    pub plant: SystemPlant,
    pub source: LawSource,
    /// The Hertz law F = k·xⁿ of the scene's bodies (eq 1).
    pub elastic: PowerLaw,
    pub options: CompliantOptions,
    /// The flights' closed forms (the rigid solver's).
    dynamics: Dynamics,
}

impl CompliantStop {
    /// The compliant stop of `model` with law `law` and its damping set by `damping`.
    pub fn new(
        model: &SystemModel,
        law: ForceModel,
        damping: CompliantDamping,
        options: CompliantOptions,
    ) -> Result<Self, SystemError> {
        let scene = model
            .scene
            .as_ref()
            .ok_or(SystemError::CompliantNeedsBodies)?;
        let quasistatic = scene.quasistatic()?;
        let base = ImpactParams {
            mass: model.mass,
            restitution: model.restitution,
            ..scene.impact_params(&quasistatic)
        };
        let plant = SystemPlant::of(model);
        let elastic = base.law;
        let source = LawSource::new(law, base, damping, static_speed(&plant, &elastic))
            .map_err(|e| SystemError::Compliant(e.to_string()))?;
        Ok(CompliantStop {
            plant,
            source,
            elastic,
            options,
            dynamics: Dynamics::new(model, model.restitution),
        })
    }

    fn settings(&self, keep_dense: bool) -> ContactSettings {
        ContactSettings {
            method: self.options.method,
            rtol: self.options.rtol,
            max_steps: self.options.max_steps_per_contact,
            keep_dense,
        }
    }

    /// The contact beginning at (t, x, v) on stop `stop`, the body arriving with approach speed
    /// v_in = side·(ṡ − v) (0 if it only touches).
    pub fn contact(
        &self,
        stop: usize,
        t: f64,
        v: f64,
        t_limit: f64,
        keep_dense: bool,
    ) -> Result<ContactResult, SystemError> {
        let motion = self.plant.stop(stop, t);
        let v_in = motion.approach(motion.s, v).1.max(0.0);
        let law = self
            .source
            .at(v_in)
            .map_err(|e| SystemError::Compliant(e.to_string()))?;
        integrate_contact(
            &self.plant,
            &law,
            self.elastic,
            stop,
            t,
            v_in,
            t_limit,
            &self.settings(keep_dense),
        )
        .map_err(|e| SystemError::Compliant(e.to_string()))
    }

    /// The free flight from (t, x, v) to the next contact or `t_limit`.
    pub fn flight(
        &self,
        from: (f64, f64, f64),
        t_limit: f64,
    ) -> Result<flight::Flight, SystemError> {
        fly(&self.dynamics, from, t_limit, 0.0)
    }

    /// [`CompliantStop::flight`] after a contact that ended as it began (a touch with no approach
    /// speed, the body pulled away): the first millionth of a period is known free.
    pub(crate) fn flight_after_touch(
        &self,
        from: (f64, f64, f64),
        t_limit: f64,
    ) -> Result<flight::Flight, SystemError> {
        fly(&self.dynamics, from, t_limit, 1e-6 * self.dynamics.period)
    }
}

/// The speed whose elastic x_max (eq 5) is the static deflection under the plant's accelerations:
/// below it a contact is a settling rather than an impact.
fn static_speed(plant: &SystemPlant, elastic: &PowerLaw) -> f64 {
    let m = plant.mass();
    let x_static = (m * plant.accel_scale() / elastic.k).powf(1.0 / elastic.n);
    (2.0 * elastic.energy(x_static) / m).sqrt()
}

/// One compliant impact's details beyond [`ImpactRecord`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ContactDetail {
    /// The energy balance of the contact in the stop's frame.
    pub energy: EnergyAudit,
    /// The largest approach δ, m.
    pub max_approach: f64,
    /// The approach left where the law let go (F = 0 at δ > 0), m.
    pub residual: f64,
    /// Time of the peak force, s.
    pub t_peak: f64,
    /// The law's damping value used at this impact (χ, c, …, SI).
    pub damping: Option<f64>,
    /// Force evaluations and integrator steps of the contact (its cost).
    pub force_evals: usize,
    pub steps: usize,
}

/// A compliant run: the [`History`] every solver returns, plus each recorded contact's details.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CompliantHistory {
    pub history: History,
    pub details: Vec<ContactDetail>,
}

/// [`simulate_detailed`] without the details: the compliant arm of `system::simulate`.
pub fn simulate(
    model: &SystemModel,
    law: ForceModel,
    damping: CompliantDamping,
    options: &RunOptions,
) -> Result<History, SystemError> {
    let stop = CompliantStop::new(model, law, damping, CompliantOptions::default())?;
    Ok(run(&stop, model, options)?.history)
}

/// Simulates `model` with a compliant stop of law `law`, recording each contact's details.
pub fn simulate_detailed(
    model: &SystemModel,
    law: ForceModel,
    damping: CompliantDamping,
    options: &RunOptions,
    compliant: CompliantOptions,
) -> Result<CompliantHistory, SystemError> {
    let stop = CompliantStop::new(model, law, damping, compliant)?;
    run(&stop, model, options)
}

/// A periodic orbit of the compliant impact map and its Floquet multipliers: the compliant arm of
/// `system::find_orbit` ([`orbit::find_orbit`]).
pub fn find_orbit(
    model: &SystemModel,
    law: ForceModel,
    damping: CompliantDamping,
    guess: &super::OrbitGuess,
    options: &super::OrbitOptions,
) -> Result<super::Orbit, SystemError> {
    let compliant = CompliantOptions {
        rtol: ORBIT_RTOL,
        ..CompliantOptions::default()
    };
    let stop = CompliantStop::new(model, law, damping, compliant)?;
    orbit::find_orbit(&stop, model, guess, options)
}

/// The tolerance orbits are integrated to: the Jacobian's central differences divide the map's
/// error by their relative step, 1e-6.
pub const ORBIT_RTOL: f64 = 1e-12;

/// Samples of (t, x, v, stop) at the grid times k·T/samples_per_period inside [a, b).
struct Sampler {
    dt: f64,
    next: f64,
    samples: Vec<SystemSample>,
}

impl Sampler {
    fn new(samples_per_period: usize, period: f64, t0: f64) -> Option<Sampler> {
        (samples_per_period > 0).then(|| {
            let dt = period / samples_per_period as f64;
            Sampler {
                dt,
                next: (t0 / dt).ceil() * dt,
                samples: Vec::new(),
            }
        })
    }

    /// Samples up to (not including) `b` from `at(t) -> (x, v)`.
    fn fill(&mut self, plant: &SystemPlant, b: f64, mut at: impl FnMut(f64) -> (f64, f64)) {
        while self.next < b {
            let t = self.next;
            let (x, v) = at(t);
            self.samples.push(SystemSample {
                t,
                x,
                v,
                stop: plant.stop(0, t).s,
            });
            self.next += self.dt;
        }
    }
}

/// The run loop: flight, contact, flight … until the recorded impacts, the time limit or a
/// contact that never ends.
pub fn run(
    stop: &CompliantStop,
    model: &SystemModel,
    options: &RunOptions,
) -> Result<CompliantHistory, SystemError> {
    let plant = &stop.plant;
    let period = plant.period();
    let omega = plant.omega();
    // At rest at t = 0 as the rigid stop starts (the ball on the table and moving with it, the
    // body at x = 0): the two stops' runs from rest begin in the same state (docs/maps.md §2).
    let start = options
        .initial
        .unwrap_or_else(|| stop.dynamics.rest_state(0.0));
    let t_limit = start.t + options.max_periods * period;
    let mut state = (start.t, start.x, start.v);
    let mut impacts = Vec::with_capacity(options.recorded_impacts);
    let mut details = Vec::with_capacity(options.recorded_impacts);
    let mut sticks = Vec::new();
    let mut dents = Dents::default();
    let mut total = 0usize;
    let mut last_impact = None;
    let mut sampler: Option<Sampler> = None;
    let mut touched = false;
    let end = loop {
        let recording = total >= options.transient_impacts;
        if recording && sampler.is_none() {
            sampler = Sampler::new(options.samples_per_period, period, state.0);
        }
        if impacts.len() >= options.recorded_impacts {
            break EndReason::Recorded;
        }
        let keep = sampler.is_some();
        let flight = if std::mem::take(&mut touched) {
            stop.flight_after_touch(state, t_limit)?
        } else {
            stop.flight(state, t_limit)?
        };
        if let Some(s) = sampler.as_mut() {
            let b = match flight.landing {
                Landing::Contact { t, .. } | Landing::TimeLimit { t, .. } => t,
            };
            s.fill(plant, b, |t| flight.at(t));
        }
        let (i, t, x, v) = match flight.landing {
            Landing::TimeLimit { t, x, v } => {
                state = (t, x, v);
                break EndReason::TimeLimit;
            }
            Landing::Contact { stop: i, t, x, v } => (i, t, x, v),
        };
        total += 1;
        last_impact = Some(t);
        if total > options.max_impacts {
            return Err(SystemError::ImpactBudget {
                what: "the simulation".into(),
                budget: options.max_impacts,
                time: t,
            });
        }
        let held_limit = (t + HELD_PERIODS * period).min(t_limit);
        let c = stop.contact(i, t, v, held_limit, keep)?;
        if let Some(s) = sampler.as_mut() {
            let b = match c.exit {
                Exit::Free { t, .. } | Exit::Held { t, .. } => t,
            };
            for piece in &c.pieces {
                let sc = piece.scale;
                let end = sc.time(piece.dense.t_end()).min(b);
                s.fill(plant, end, |t| {
                    let y = piece.dense.eval((t - sc.t0) / sc.t);
                    sc.body(plant, (t - sc.t0) / sc.t, &y)
                });
            }
        }
        if total > options.transient_impacts {
            impacts.push(record(model, omega, x, &c));
            if c.permanent {
                dents.contacts += 1;
                dents.total += c.residual;
                dents.largest = dents.largest.max(c.residual);
            }
            if let (true, Exit::Free { .. }) = (c.is_rest(), c.exit) {
                sticks.push(Stick {
                    start: c.t_start,
                    end: Some(c.t_end),
                    stop: i,
                });
            }
            details.push(ContactDetail {
                energy: c.energy,
                max_approach: c.max_approach,
                residual: c.residual,
                t_peak: c.t_peak,
                damping: stop.source.damping_at(c.v_in),
                force_evals: c.force_evals,
                steps: c.steps,
            });
        }
        match c.exit {
            Exit::Free { t, x, v } => {
                touched = c.t_end == c.t_start;
                state = (t, x, v);
            }
            Exit::Held { t, x, v } => {
                state = (t, x, v);
                if total > options.transient_impacts {
                    sticks.push(Stick {
                        start: c.t_start,
                        end: None,
                        stop: i,
                    });
                }
                break if t >= t_limit {
                    EndReason::TimeLimit
                } else {
                    EndReason::StuckForever
                };
            }
        }
    };
    Ok(CompliantHistory {
        history: History {
            samples: sampler.map(|s| s.samples).unwrap_or_default(),
            impacts,
            sticks,
            impacts_total: total,
            last_impact,
            end_state: State {
                t: state.0,
                x: state.1,
                v: state.2,
            },
            end,
            dents,
        },
        details,
    })
}

/// The [`ImpactRecord`] of a contact that began with the body at x.
fn record(model: &SystemModel, omega: f64, x: f64, c: &ContactResult) -> ImpactRecord {
    ImpactRecord {
        t: c.t_start,
        phase: (omega * c.t_start).rem_euclid(TAU),
        x,
        stop: c.stop,
        v_in: c.v_in,
        v_out: c.v_out.max(0.0),
        peak_force: Some(c.peak_force),
        peak_force_estimate: model.peak_force_estimate(c.v_in),
        contact_time: Some(c.contact_time()),
        energy_lost: c.energy.incoming - c.energy.outgoing,
        kind: if c.is_rest() {
            ImpactKind::Rest
        } else {
            ImpactKind::Impact
        },
    }
}
