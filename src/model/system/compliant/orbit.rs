//! Periodic orbits of the compliant impact map and their Floquet multipliers.
//!
//! The map is taken at first contact: the state there is (t, v_in) on a stop's surface (x = s(t)),
//! so it is two-dimensional like the rigid map. One application is a contact from that state and
//! the flight to the next first contact. An orbit of m forcing periods and n impacts is a zero of
//! (t_n − t₀ − m·T, v_n − v₀), found by Newton; the Jacobian ∂(t_n, v_n)/∂(t₀, v₀) is taken by
//! central differences of integrations at a tight tolerance, and its eigenvalues are the Floquet
//! multipliers (a fixed point of a Poincaré map is stable when they lie inside the unit circle).

use std::f64::consts::TAU;

use nalgebra::{Complex, Matrix2, Vector2};

use crate::model::numeric::roots::brent;

use super::super::{
    GuessStart, ImpactPoint, Orbit, OrbitGuess, OrbitOptions, SystemError, rigid, seed,
};
use super::contact::Exit;
use super::flight::Landing;
use super::plant::Plant;
use super::{CompliantStop, HELD_PERIODS};

/// Relative step of the central differences: the map is integrated to ~1e-12, so its differences
/// are good to ~1e-12/1e-6 = 1e-6 while the truncation error, ~(1e-6)², is far below.
const FD_STEP: f64 = 1e-6;

/// Newton's corrections cannot be resolved below the integration's own accuracy.
const TOLERANCE_FLOOR: f64 = 1e-10;

/// A first contact: time, approach speed and stop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MapPoint {
    pub t: f64,
    pub v_in: f64,
    pub stop: usize,
}

/// One map step's outcome: the next first contact and what happened on the way.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MapStep {
    pub next: MapPoint,
    /// The impact just integrated, as an orbit point.
    pub point: ImpactPoint,
    pub contact_time: f64,
    pub peak_force: f64,
}

/// Applies the map once from `p`.
pub fn map_step(stop: &CompliantStop, p: MapPoint) -> Result<MapStep, SystemError> {
    let plant = &stop.plant;
    let period = plant.period();
    let motion = plant.stop(p.stop, p.t);
    let (x, v) = motion.body(0.0, p.v_in);
    let limit = p.t + HELD_PERIODS * period;
    let c = stop.contact(p.stop, p.t, v, limit, false)?;
    let Exit::Free { t, x: xe, v: ve } = c.exit else {
        return Err(SystemError::OrbitDegenerate(
            "the body comes to rest on the stop (a contact that does not end)",
        ));
    };
    let flight = stop.flight((t, xe, ve), t + 64.0 * period)?;
    let Landing::Contact {
        stop: next_stop,
        t: tn,
        v: vn,
        ..
    } = flight.landing
    else {
        return Err(SystemError::OrbitDegenerate(
            "no further impact within 64 forcing periods",
        ));
    };
    let next_motion = plant.stop(next_stop, tn);
    let v_next = next_motion.approach(next_motion.s, vn).1.max(0.0);
    Ok(MapStep {
        next: MapPoint {
            t: tn,
            v_in: v_next,
            stop: next_stop,
        },
        point: ImpactPoint {
            t: p.t,
            phase: (plant.omega() * p.t).rem_euclid(TAU),
            x,
            stop: p.stop,
            v_in: p.v_in,
            v_out: c.v_out.max(0.0),
        },
        contact_time: c.contact_time(),
        peak_force: c.peak_force,
    })
}

/// The n-fold map from `p`: the point reached and the n impacts on the way.
pub fn map_n(
    stop: &CompliantStop,
    p: MapPoint,
    n: u32,
) -> Result<(MapPoint, Vec<MapStep>), SystemError> {
    let mut q = p;
    let mut steps = Vec::with_capacity(n as usize);
    for _ in 0..n {
        let s = map_step(stop, q)?;
        q = s.next;
        steps.push(s);
    }
    Ok((q, steps))
}

/// The Jacobian ∂(t_n, v_n)/∂(t₀, v₀) of the n-fold map at `p` by central differences.
pub fn map_jacobian(
    stop: &CompliantStop,
    p: MapPoint,
    n: u32,
) -> Result<Matrix2<f64>, SystemError> {
    map_jacobian_step(stop, p, n, FD_STEP)
}

/// Central differences of the n-fold map at `p` with relative step `step`.
fn map_jacobian_step(
    stop: &CompliantStop,
    p: MapPoint,
    n: u32,
    step: f64,
) -> Result<Matrix2<f64>, SystemError> {
    let ht = step * stop.plant.period();
    let hv = step * p.v_in.abs().max(f64::MIN_POSITIVE);
    let image = |t: f64, v: f64| -> Result<Vector2<f64>, SystemError> {
        let (q, _) = map_n(stop, MapPoint { t, v_in: v, ..p }, n)?;
        if q.stop != p.stop {
            return Err(SystemError::OrbitDegenerate(
                "a neighbouring orbit hits the other stop (a grazing orbit)",
            ));
        }
        Ok(Vector2::new(q.t, q.v_in))
    };
    let dt = (image(p.t + ht, p.v_in)? - image(p.t - ht, p.v_in)?) / (2.0 * ht);
    let dv = (image(p.t, p.v_in + hv)? - image(p.t, p.v_in - hv)?) / (2.0 * hv);
    Ok(Matrix2::from_columns(&[dt, dv]))
}

/// The Jacobian of the n-fold map at `p` for the multipliers: central differences at steps h and
/// h/2 combined by Richardson's extrapolation, (4·D(h/2) − D(h))/3, whose truncation error is
/// O(h⁴) instead of O(h²). The step is relative (of the period for t, of v_in for v) and set by
/// the contacts' tolerance: h = rtol^(1/5)/2π (6e-4 at the orbits' 1e-12; a phase step of
/// rtol^(1/5)) balances the truncation (2πh)⁴ against the integration's noise rtol/(2πh), so J is
/// good to about rtol^(4/5), 2e-10 at 1e-12 (docs/compliant.md §4).
pub fn map_jacobian_extrapolated(
    stop: &CompliantStop,
    p: MapPoint,
    n: u32,
) -> Result<Matrix2<f64>, SystemError> {
    let step = stop.options.rtol.powf(0.2) / TAU;
    let coarse = map_jacobian_step(stop, p, n, step)?;
    let fine = map_jacobian_step(stop, p, n, 0.5 * step)?;
    Ok((4.0 * fine - coarse) / 3.0)
}

/// The eigenvalues of a 2×2 matrix.
pub fn eigenvalues(j: &Matrix2<f64>) -> [Complex<f64>; 2] {
    let half_trace = 0.5 * j.trace();
    let disc = half_trace * half_trace - j.determinant();
    if disc >= 0.0 {
        let r = disc.sqrt();
        // The larger-magnitude root first, the other from the product to keep its digits.
        let big = half_trace + r.copysign(half_trace);
        let small = if big != 0.0 {
            j.determinant() / big
        } else {
            0.0
        };
        [Complex::new(big, 0.0), Complex::new(small, 0.0)]
    } else {
        let r = (-disc).sqrt();
        [Complex::new(half_trace, r), Complex::new(half_trace, -r)]
    }
}

/// A periodic orbit of the compliant map by Newton from `guess` (its `start`, or an impact of the
/// attractor `guess.attractor` reaches).
pub fn find_orbit(
    stop: &CompliantStop,
    model: &super::super::SystemModel,
    guess: &OrbitGuess,
    options: &OrbitOptions,
) -> Result<Orbit, SystemError> {
    let plant = &stop.plant;
    // 0 asks for the period the run settles on (without a start; with one, 1).
    let (m, n) = (guess.forcing_cycles.max(1), guess.impacts.max(1));
    let p = match guess.start {
        Some(s) => MapPoint {
            t: s.phase / plant.omega(),
            v_in: s.v_in,
            stop: s.stop,
        },
        None => {
            // The rigid stop's orbit first (the compliant one's limit as t_c/T falls;
            // docs/compliant.md §5), then the run's isolated impacts.
            let seeded = OrbitOptions {
                max_iterations: options.max_iterations.min(seed::SEED_ITERATIONS),
                ..*options
            };
            return seed::search(
                model,
                guess,
                |run| Ok(super::run(stop, model, run)?.history),
                |guess| find_orbit(stop, model, guess, &seeded),
                (
                    |guess: &OrbitGuess, _: &[GuessStart]| {
                        rigid::find_orbit(model, model.restitution, guess, options).map_or_else(
                            |_| Vec::new(),
                            |o| {
                                o.points
                                    .iter()
                                    .map(|p| GuessStart {
                                        phase: p.phase,
                                        v_in: p.v_in,
                                        stop: p.stop,
                                    })
                                    .collect()
                            },
                        )
                    },
                    seed::Extra::First,
                ),
            );
        }
    };
    let tol = options.tolerance.max(TOLERANCE_FLOOR);
    let (p, iterations) = newton(stop, p, m, n, tol, options.max_iterations)?;
    orbit_at(stop, p, m, n, iterations)
}

/// Newton on (t_n − t₀ − m·T, v_n − v₀) from `p`, to a correction below `tol` (relative to the
/// period and to the speed), with steps damped to a quarter period and half the speed. Returns
/// the converged point and the iterations taken.
pub fn newton(
    stop: &CompliantStop,
    mut p: MapPoint,
    m: u32,
    n: u32,
    tol: f64,
    max_iterations: usize,
) -> Result<(MapPoint, usize), SystemError> {
    let period = stop.plant.period();
    let target = m as f64 * period;
    let mut residual = f64::INFINITY;
    for iteration in 1..=max_iterations {
        let (q, _) = map_n(stop, p, n)?;
        let r = Vector2::new(q.t - p.t - target, q.v_in - p.v_in);
        let j = map_jacobian(stop, p, n)?;
        let newton = j - Matrix2::identity();
        let Some(step) = newton.try_inverse().map(|inv| -(inv * r)) else {
            return Err(SystemError::OrbitDegenerate(
                "the map's Jacobian has a multiplier at 1 (a fold)",
            ));
        };
        let scale = (step[0].abs() / (0.25 * period))
            .max(step[1].abs() / (0.5 * p.v_in.max(f64::MIN_POSITIVE)))
            .max(1.0);
        let step = step / scale;
        residual = (step[0] / period).abs().max((step[1] / p.v_in).abs());
        p.t += step[0];
        p.v_in += step[1];
        if p.v_in.is_nan() || p.v_in <= 0.0 {
            return Err(SystemError::OrbitDegenerate(
                "Newton drove the impact speed to zero (grazing or sticking)",
            ));
        }
        if residual <= tol {
            return Ok((p, iteration));
        }
    }
    Err(SystemError::OrbitNotConverged {
        iterations: max_iterations,
        residual,
    })
}

/// Where, between `lo` and `hi`, a period-m, n-impact orbit loses stability by period doubling: the
/// root in the parameter of 1 + tr J + det J (the characteristic polynomial of the map's Jacobian
/// at −1), by Brent's method, the orbit followed from each value to the next by Newton starting
/// at `guess`. `build` makes the stop at a parameter value. `None` without a sign change there.
pub fn period_doubling(
    build: impl Fn(f64) -> Result<CompliantStop, SystemError>,
    guess: MapPoint,
    (m, n): (u32, u32),
    (lo, hi): (f64, f64),
) -> Result<Option<f64>, SystemError> {
    let mut p = guess;
    let mut failure = None;
    let mut at = |value: f64| -> f64 {
        let result = build(value).and_then(|stop| {
            let (q, _) = newton(&stop, p, m, n, 1e-11, 40)?;
            p = q;
            let j = map_jacobian_extrapolated(&stop, q, n)?;
            Ok(1.0 + j.trace() + j.determinant())
        });
        match result {
            Ok(f) => f,
            Err(e) => {
                failure.get_or_insert(e);
                f64::NAN
            }
        }
    };
    let root = brent(&mut at, lo, hi);
    match failure {
        Some(e) => Err(e),
        None => Ok(root),
    }
}

/// The orbit through the converged point `p`: its impacts and multipliers.
fn orbit_at(
    stop: &CompliantStop,
    p: MapPoint,
    m: u32,
    n: u32,
    iterations: usize,
) -> Result<Orbit, SystemError> {
    let (_, steps) = map_n(stop, p, n)?;
    let j = map_jacobian_extrapolated(stop, p, n)?;
    let multipliers = eigenvalues(&j);
    Ok(Orbit {
        period_forcing_cycles: m,
        impacts_per_period: n,
        points: steps.iter().map(|s| s.point).collect(),
        multipliers: multipliers.to_vec(),
        // In (time of first contact, approach speed): similar to the rigid map's (time, speed
        // after), so the same multipliers.
        jacobian: [[j[(0, 0)], j[(0, 1)]], [j[(1, 0)], j[(1, 1)]]],
        jacobian_det: j.determinant(),
        stable: multipliers.iter().all(|z| z.norm() < 1.0),
        iterations,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eigenvalues_of_real_and_complex_pairs() {
        let j = Matrix2::new(2.0, 0.0, 0.0, -0.5);
        let [a, b] = eigenvalues(&j);
        assert_eq!((a.re, b.re), (2.0, -0.5));
        let r = Matrix2::new(0.0, -0.25, 1.0, 0.0); // λ² = −0.25
        let [a, b] = eigenvalues(&r);
        assert!((a.im - 0.5).abs() < 1e-15 && (b.im + 0.5).abs() < 1e-15 && a.re == 0.0);
    }
}
