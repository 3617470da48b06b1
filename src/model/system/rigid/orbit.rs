//! The rigid impact map, its Jacobian in closed form, and periodic orbits by Newton on it
//! (docs/systems.md §5).

use std::f64::consts::TAU;

use nalgebra::Complex;

use crate::model::system::error::SystemError;
use crate::model::system::model::SystemModel;
use crate::model::system::orbit::{GuessStart, ImpactPoint, Orbit, OrbitGuess, OrbitOptions};
use crate::model::system::run::State;
use crate::model::system::seed;

use super::dynamics::Dynamics;
use super::search::{Found, first_impact};
use super::simulate::{AfterImpact, after_impact, impact, simulate};

type Mat = [[f64; 2]; 2];

fn mul(a: &Mat, b: &Mat) -> Mat {
    let mut out = [[0.0; 2]; 2];
    for (i, row) in out.iter_mut().enumerate() {
        for (j, cell) in row.iter_mut().enumerate() {
            *cell = a[i][0] * b[0][j] + a[i][1] * b[1][j];
        }
    }
    out
}

/// One step of the impact map from just after an impact on `stop` at (t0, v0): the next
/// impact's point, the state after it, and ∂(t1, v1⁺)/∂(t0, v0⁺).
pub(crate) struct Step {
    pub point: ImpactPoint,
    pub after: State,
    pub jacobian: Mat,
}

/// The map from the state just after an impact on `stop` to the state just after the next one.
pub(crate) fn map_step(
    d: &Dynamics,
    stop: usize,
    start: State,
    horizon: f64,
) -> Result<Step, SystemError> {
    let flight = d.flight(start.t, start.x, start.v);
    let (tau, next, point) = match first_impact(&flight, 0.0, horizon)? {
        Found::Impact { tau, stop, point } => (tau, stop, point),
        Found::Nothing => {
            return Err(SystemError::OrbitDegenerate(
                "no impact within the horizon from the guess",
            ));
        }
    };
    let t1 = start.t + tau;
    let x1 = start.x + point.dx;
    let v1 = point.v;
    let (after, v_in, v_out) = impact(d, next, t1, v1);
    if let AfterImpact::Rests { .. } = after_impact(d, next, after, v_out) {
        return Err(SystemError::OrbitDegenerate(
            "the orbit chatters or sticks: it has no isolated impacts to iterate",
        ));
    }
    // dy(t1)/dt0 = Φ·(ṡ0 − v0, −a0) (the start lies on the stop), dy(t1)/dv0 = Φ·(0, 1).
    let phi = flight.transition(tau);
    let (_, s0v, _) = d.stop_motion(stop, start.t);
    let a0 = d.accel(start.t, start.x, start.v);
    let (u, w) = (s0v - start.v, -a0);
    let dy_dt0 = [phi[0][0] * u + phi[0][1] * w, phi[1][0] * u + phi[1][1] * w];
    let dy_dv0 = [phi[0][1], phi[1][1]];
    let (_, s1v, s1a) = d.stop_motion(next, t1);
    let closing = v1 - s1v;
    let a1 = d.accel(t1, x1, v1);
    let e = d.restitution;
    let mut jacobian = [[0.0; 2]; 2];
    for (col, dy) in [dy_dt0, dy_dv0].iter().enumerate() {
        // g(t1) = 0 ⇒ dt1 = −dx/(v1 − ṡ1); v1⁺ = (1 + e)·ṡ1 − e·v1⁻.
        let dt1 = -dy[0] / closing;
        let dv1 = dy[1] + a1 * dt1;
        jacobian[0][col] = dt1;
        jacobian[1][col] = (1.0 + e) * s1a * dt1 - e * dv1;
    }
    Ok(Step {
        point: ImpactPoint {
            t: t1,
            phase: (d.omega * t1).rem_euclid(TAU),
            x: after.x,
            stop: next,
            v_in,
            v_out,
        },
        after,
        jacobian,
    })
}

/// A periodic orbit of the rigid impact map (see [`super`]).
pub fn find_orbit(
    model: &SystemModel,
    restitution: f64,
    guess: &OrbitGuess,
    options: &OrbitOptions,
) -> Result<Orbit, SystemError> {
    model.validate()?;
    let d = Dynamics::new(model, restitution);
    let cycles = guess.forcing_cycles.max(1);
    let impacts = guess.impacts.max(1) as usize;
    let period = f64::from(cycles) * d.period;
    let (stop, mut t0, mut v0) = match guess.start {
        Some(start) => {
            let t = start.phase.rem_euclid(TAU) / d.omega;
            let (_, sv, _) = d.stop_motion(start.stop, t);
            let v = sv + d.stops[start.stop].sigma * restitution * start.v_in;
            (start.stop, t, v)
        }
        None => {
            // Starts from the run past the transient, then a grid of phases and speeds.
            let seeded = OrbitOptions {
                max_iterations: options.max_iterations.min(seed::SEED_ITERATIONS),
                ..*options
            };
            return seed::search(
                model,
                guess,
                |run| simulate(model, restitution, run),
                |guess| find_orbit(model, restitution, guess, &seeded),
                (
                    |guess: &OrbitGuess, from_run: &[GuessStart]| {
                        let speed = from_run.first().map_or_else(
                            || seed::speed_scale(model, guess.forcing_cycles),
                            |s| s.v_in,
                        );
                        seed::grid(model, speed)
                    },
                    seed::Extra::Last,
                ),
            );
        }
    };
    let horizon = 2.0 * period + 4.0 * d.period;
    let mut residual = f64::INFINITY;
    for iteration in 1..=options.max_iterations {
        let mut state = State {
            t: t0,
            x: d.stop_motion(stop, t0).0,
            v: v0,
        };
        let mut jacobian = [[1.0, 0.0], [0.0, 1.0]];
        let mut points = Vec::with_capacity(impacts);
        let mut at = stop;
        for _ in 0..impacts {
            let step = map_step(&d, at, state, horizon)?;
            jacobian = mul(&step.jacobian, &jacobian);
            at = step.point.stop;
            state = step.after;
            points.push(step.point);
        }
        if at != stop {
            return Err(SystemError::OrbitDegenerate(
                "the guess ends on the other stop: ask for another number of impacts",
            ));
        }
        let r = [state.t - t0 - period, state.v - v0];
        // Newton on (t0, v0): (J − I)·Δ = −r.
        let a = [
            [jacobian[0][0] - 1.0, jacobian[0][1]],
            [jacobian[1][0], jacobian[1][1] - 1.0],
        ];
        let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
        let speed = v0.abs().max(points[0].v_in).max(1e-300);
        if !det.is_finite() || det == 0.0 {
            return Err(SystemError::OrbitDegenerate(
                "the impact map's Jacobian has a multiplier 1 here (a saddle-node)",
            ));
        }
        let dt = -(a[1][1] * r[0] - a[0][1] * r[1]) / det;
        let dv = -(-a[1][0] * r[0] + a[0][0] * r[1]) / det;
        residual = (dt.abs() / d.period).max(dv.abs() / speed);
        let converged = residual <= options.tolerance
            || (r[0].abs() <= 4.0 * f64::EPSILON * period.max(t0.abs())
                && r[1].abs() <= 4.0 * f64::EPSILON * speed);
        if converged {
            let trace = jacobian[0][0] + jacobian[1][1];
            let jdet = jacobian[0][0] * jacobian[1][1] - jacobian[0][1] * jacobian[1][0];
            let multipliers = eigenvalues(trace, jdet);
            return Ok(Orbit {
                period_forcing_cycles: cycles,
                impacts_per_period: impacts as u32,
                stable: multipliers.iter().all(|z| z.norm() < 1.0),
                points,
                multipliers,
                jacobian,
                jacobian_det: jdet,
                iterations: iteration,
            });
        }
        t0 += dt;
        v0 += dv;
        // Keep t0 in the first period: the map is periodic in t.
        let shift = (t0 / d.period).floor() * d.period;
        t0 -= shift;
    }
    Err(SystemError::OrbitNotConverged {
        iterations: options.max_iterations,
        residual,
    })
}

/// The eigenvalues of a 2×2 matrix from its trace and determinant.
fn eigenvalues(trace: f64, det: f64) -> Vec<Complex<f64>> {
    let half = 0.5 * trace;
    let disc = half * half - det;
    if disc >= 0.0 {
        let root = disc.sqrt();
        // The larger in magnitude first, the other from det/λ to avoid cancellation.
        let big = half + root.copysign(half);
        let small = if big != 0.0 { det / big } else { half - root };
        vec![Complex::new(big, 0.0), Complex::new(small, 0.0)]
    } else {
        let im = (-disc).sqrt();
        vec![Complex::new(half, im), Complex::new(half, -im)]
    }
}
