//! The rigid stop's periodic orbits by multiple shooting over the closed-form flights
//! (docs/continuation.md §1): the unknowns are each impact's phase ωt_k and the velocity v_k⁺
//! just after it; impact k's flight must meet the next impact's stop at t_{k+1} (the last one at
//! t₀ + mT) with the velocity that Newton's restitution turns into v_{k+1}⁺.
//!
//! Nothing is root-found: the residual is the closed-form flight evaluated at the unknown times,
//! so it stays smooth when an impact's speed reaches zero or a flight's gap minimum reaches the
//! stop (grazing), and the branch can be followed to those points and located there.

use std::f64::consts::TAU;

use crate::model::system::rigid::dynamics::{Dynamics, Law};
use crate::model::system::{ImpactPoint, Param, SystemModel};

use super::error::ContinuationError;
use super::journey;
use super::problem::{
    Mat, Monitors, OrbitProblem, model_at, mul, rescale, varies_restitution, wrap,
};

/// A rigid orbit of fixed impact sequence.
#[derive(Debug, Clone)]
pub(crate) struct RigidProblem {
    pub base: SystemModel,
    pub keys: Vec<Param>,
    /// The stop's e, or None when e follows the model (the continued key is the restitution).
    pub restitution: Option<f64>,
    /// The stop of each impact.
    pub stops: Vec<usize>,
    /// m: forcing periods per orbit.
    pub cycles: u32,
    /// Speed scale V (unknowns w = v⁺/V), m/s.
    pub speed: f64,
}

/// The flights of one orbit, evaluated.
struct Leg {
    t0: f64,
    t1: f64,
    x0: f64,
    v0: f64,
    flight: crate::model::system::rigid::dynamics::Flight,
    next: usize,
}

impl RigidProblem {
    fn dynamics(&self, lambda: &[f64]) -> Result<Dynamics, ContinuationError> {
        let model = model_at(&self.base, &self.keys, lambda)?;
        let e = if varies_restitution(&self.keys) {
            model.restitution
        } else {
            self.restitution.unwrap_or(model.restitution)
        };
        Ok(Dynamics::new(&model, e))
    }

    /// The length scale of the gap equations: V/ω at the base model, m.
    fn length(&self) -> f64 {
        self.speed / self.base.spec.omega()
    }

    fn legs(&self, d: &Dynamics, y: &[f64]) -> Result<Vec<Leg>, ContinuationError> {
        let n = self.stops.len();
        let shift = f64::from(self.cycles) * d.period;
        (0..n)
            .map(|k| {
                let t0 = y[2 * k] / d.omega;
                let v0 = y[2 * k + 1] * self.speed;
                let (t1, next) = if k + 1 < n {
                    (y[2 * k + 2] / d.omega, k + 1)
                } else {
                    (y[0] / d.omega + shift, 0)
                };
                if t1 <= t0 || !t1.is_finite() {
                    return Err(ContinuationError::Unsupported(
                        "the impacts of the orbit fell out of order".into(),
                    ));
                }
                let x0 = d.stop_motion(self.stops[k], t0).0;
                Ok(Leg {
                    t0,
                    t1,
                    x0,
                    v0,
                    flight: d.flight(t0, x0, v0),
                    next,
                })
            })
            .collect()
    }
}

/// ∂(t₁, v₁⁺)/∂(t₀, v₀⁺) of one impact-to-impact step (docs/systems.md §5).
fn step_jacobian(d: &Dynamics, leg: &Leg, from_stop: usize, to_stop: usize) -> Mat {
    let tau = leg.t1 - leg.t0;
    let p = leg.flight.at(tau);
    let phi = leg.flight.transition(tau);
    let (_, s0v, _) = d.stop_motion(from_stop, leg.t0);
    let a0 = d.accel(leg.t0, leg.x0, leg.v0);
    let (u, w) = (s0v - leg.v0, -a0);
    let dy_dt0 = [phi[0][0] * u + phi[0][1] * w, phi[1][0] * u + phi[1][1] * w];
    let dy_dv0 = [phi[0][1], phi[1][1]];
    let (_, s1v, s1a) = d.stop_motion(to_stop, leg.t1);
    let closing = p.v - s1v;
    let a1 = d.accel(leg.t1, leg.x0 + p.dx, p.v);
    let e = d.restitution;
    let mut j = [[0.0; 2]; 2];
    for (col, dy) in [dy_dt0, dy_dv0].iter().enumerate() {
        let dt1 = -dy[0] / closing;
        let dv1 = dy[1] + a1 * dt1;
        j[0][col] = dt1;
        j[1][col] = (1.0 + e) * s1a * dt1 - e * dv1;
    }
    j
}

/// The smallest interior minimum of any stop's gap over (0, τ₁) of a flight, m
/// ([`journey::minima`]: sampled against both its forcing and its free period).
fn interior_min_gap(d: &Dynamics, leg: &Leg) -> Option<f64> {
    let tau1 = leg.t1 - leg.t0;
    let fastest = match d.law {
        Law::Ball { .. } => d.omega,
        Law::Oscillator { omega_d, .. } => d.omega.max(omega_d),
    };
    let mut best: Option<f64> = None;
    for stop in 0..d.stop_count {
        let gap = |tau: f64| leg.flight.gap(stop, &leg.flight.at(tau));
        for tau in journey::minima(|tau| gap(tau).1, (0.0, tau1), fastest) {
            let g = gap(tau).0;
            best = Some(best.map_or(g, |b: f64| b.min(g)));
        }
    }
    best
}

impl OrbitProblem for RigidProblem {
    fn unknowns(&self) -> usize {
        2 * self.stops.len()
    }

    fn residual(&self, y: &[f64], lambda: &[f64]) -> Result<Vec<f64>, ContinuationError> {
        let d = self.dynamics(lambda)?;
        let length = self.length();
        let mut r = Vec::with_capacity(y.len());
        for leg in self.legs(&d, y)? {
            let stop = self.stops[leg.next];
            let p = leg.flight.at(leg.t1 - leg.t0);
            let (g, _) = leg.flight.gap(stop, &p);
            let (_, s1v, _) = d.stop_motion(stop, leg.t1);
            // v⁺ = (1 + e)·ṡ − e·v⁻ (Newton's restitution relative to the stop).
            let v_plus = (1.0 + d.restitution) * s1v - d.restitution * p.v;
            r.push(g / length);
            r.push((y[2 * leg.next + 1] * self.speed - v_plus) / self.speed);
        }
        Ok(r)
    }

    fn monitors(&self, y: &[f64], lambda: &[f64]) -> Result<Monitors, ContinuationError> {
        let d = self.dynamics(lambda)?;
        let legs = self.legs(&d, y)?;
        let n = self.stops.len();
        let mut partials = Vec::with_capacity(n);
        let mut speeds = Vec::with_capacity(n);
        let mut points = Vec::with_capacity(n);
        let mut min_gap: Option<f64> = None;
        let mut jacobian = [[1.0, 0.0], [0.0, 1.0]];
        for (k, leg) in legs.iter().enumerate() {
            let to = self.stops[leg.next];
            let j = rescale(
                &step_jacobian(&d, leg, self.stops[k], to),
                d.omega,
                1.0 / self.speed,
            );
            jacobian = mul(&j, &jacobian);
            partials.push(j);
            let p = leg.flight.at(leg.t1 - leg.t0);
            let (_, gd) = leg.flight.gap(to, &p);
            let v_in = -gd;
            speeds.push(v_in);
            points.push(ImpactPoint {
                t: leg.t1,
                phase: wrap(d.omega * leg.t1),
                x: leg.x0 + p.dx,
                stop: to,
                v_in,
                v_out: d.restitution * v_in,
            });
            if let Some(g) = interior_min_gap(&d, leg) {
                min_gap = Some(min_gap.map_or(g, |b| b.min(g)));
            }
        }
        // The points in the order of the unknowns: impact k is where leg k − 1 lands.
        points.rotate_right(1);
        speeds.rotate_right(1);
        if let Some(first) = points.first_mut() {
            first.t -= f64::from(self.cycles) * d.period;
        }
        Ok(Monitors {
            jacobian,
            partials,
            speeds,
            min_gap,
            points,
            approaches: None,
        })
    }

    fn fd_step(&self) -> f64 {
        1e-7
    }

    fn tolerance(&self) -> f64 {
        1e-12
    }

    fn scales(&self) -> (f64, f64) {
        (self.speed, self.length())
    }

    fn signature(&self) -> (u32, Vec<usize>) {
        (self.cycles, self.stops.clone())
    }

    fn doubled(
        &self,
        y: &[f64],
        monitors: &Monitors,
        q: [f64; 2],
    ) -> Result<(Box<dyn OrbitProblem>, Vec<f64>, Vec<f64>), ContinuationError> {
        let n = self.stops.len();
        let shift = TAU * f64::from(self.cycles);
        let mut stops = self.stops.clone();
        stops.extend_from_slice(&self.stops);
        let mut y2 = y.to_vec();
        for k in 0..n {
            y2.push(y[2 * k] + shift);
            y2.push(y[2 * k + 1]);
        }
        // δ at impact k + 1 is impact k's Jacobian applied to δ at impact k; the second half of
        // the doubled orbit carries J·q = −q onward.
        let mut direction = Vec::with_capacity(4 * n);
        let mut delta = q;
        for k in 0..2 * n {
            direction.push(delta[0]);
            direction.push(delta[1]);
            let j = &monitors.partials[k % n];
            delta = [
                j[0][0] * delta[0] + j[0][1] * delta[1],
                j[1][0] * delta[0] + j[1][1] * delta[1],
            ];
        }
        let problem = RigidProblem {
            stops,
            cycles: 2 * self.cycles,
            ..self.clone()
        };
        Ok((Box::new(problem), y2, direction))
    }
}
