//! The entry points: a branch in one key from an orbit found by Newton, the switch onto the
//! doubled branch at a period doubling, and the curve of a special point in a second key.

use nalgebra::DVector;

use crate::model::system::{Contact, OrbitGuess, OrbitOptions, Param, SystemModel, find_orbit};

use super::branch::{Branch, ContinuationOptions, SpecialKind, SpecialPoint};
use super::compliant::CompliantProblem;
use super::engine::{correct, jacobian, tangent};
use super::error::ContinuationError;
use super::problem::{OrbitProblem, model_at, varies_restitution};
use super::rigid::RigidProblem;
use super::trace::{Augmented, Trace, never, test_value};

/// A fold or period-doubling curve ends where an impact speed falls below this fraction of the
/// speed scale: it is running into a grazing point, where J ~ 1/v has no finite limit.
const GRAZED: f64 = 1e-6;

/// A parameter's scale: its range's extent, or its size when that is larger.
fn scale_of(from: f64, to: f64) -> f64 {
    from.abs()
        .max(to.abs())
        .max((to - from).abs())
        .max(f64::MIN_POSITIVE)
}

fn check_range(key: Param, (from, to): (f64, f64)) -> Result<(), ContinuationError> {
    if from.is_finite() && to.is_finite() && from != to {
        Ok(())
    } else {
        Err(ContinuationError::Range {
            key: key.path(),
            from,
            to,
        })
    }
}

/// The orbit problem of `contact` for orbits of `stops` in `cycles` forcing periods.
fn problem(
    model: &SystemModel,
    contact: &Contact,
    keys: Vec<Param>,
    (cycles, stops): (u32, Vec<usize>),
    speed: f64,
) -> Box<dyn OrbitProblem> {
    match *contact {
        Contact::Rigid { restitution } => Box::new(RigidProblem {
            base: model.clone(),
            restitution: (!varies_restitution(&keys)).then_some(restitution),
            keys,
            stops,
            cycles,
            speed,
        }),
        Contact::Compliant {
            model: law,
            damping,
        } => Box::new(CompliantProblem::new(
            model.clone(),
            keys,
            law,
            damping,
            stops.first().copied().unwrap_or(0),
            stops.len() as u32,
            cycles,
            speed,
        )),
    }
}

/// The branch of periodic orbits of `model` with `contact` in `param` from `range.0` towards
/// `range.1`, starting from the orbit Newton finds from `guess` at `range.0` (docs/continuation.md).
pub fn continue_orbit(
    model: &SystemModel,
    contact: &Contact,
    param: Param,
    range: (f64, f64),
    guess: &OrbitGuess,
    options: &ContinuationOptions,
) -> Result<Branch, ContinuationError> {
    continue_orbit_until(model, contact, param, range, guess, options, &never)
}

/// [`continue_orbit`] that polls `stop` before every step and ends with
/// [`ContinuationError::Stopped`] once it says so (the explorer's job, superseded by an edit).
pub fn continue_orbit_until(
    model: &SystemModel,
    contact: &Contact,
    param: Param,
    range: (f64, f64),
    guess: &OrbitGuess,
    options: &ContinuationOptions,
    stop: &(dyn Fn() -> bool + Sync),
) -> Result<Branch, ContinuationError> {
    check_range(param, range)?;
    let keys = vec![param];
    let at_start = model_at(model, &keys, &[range.0])?;
    let contact = match contact {
        Contact::Rigid { .. } if varies_restitution(&keys) => Contact::rigid(at_start.restitution),
        c => *c,
    };
    let orbit = find_orbit(&at_start, &contact, guess, &OrbitOptions::default())?;
    let speed = orbit
        .points
        .iter()
        .map(|p| p.v_in)
        .fold(f64::MIN_POSITIVE, f64::max);
    let omega = at_start.spec.omega();
    let stops: Vec<usize> = orbit.points.iter().map(|p| p.stop).collect();
    let p = problem(
        model,
        &contact,
        keys,
        (orbit.period_forcing_cycles, stops),
        speed,
    );
    let scale = scale_of(range.0, range.1);
    // Unknowns at the found orbit: the rigid problem's (ωt_k, v_k⁺/V) for each impact, the
    // compliant one's (ωt, v_in/V) of the first contact.
    let first = orbit.points[0].t;
    let turn = (omega * first).div_euclid(std::f64::consts::TAU) * std::f64::consts::TAU;
    let mut y = Vec::new();
    match contact {
        Contact::Rigid { restitution } => {
            let d = crate::model::system::rigid::dynamics::Dynamics::new(&at_start, restitution);
            for point in &orbit.points {
                let (_, sv, _) = d.stop_motion(point.stop, point.t);
                let v_plus = sv + d.stops[point.stop].sigma * point.v_out;
                y.push(omega * point.t - turn);
                y.push(v_plus / speed);
            }
        }
        Contact::Compliant { .. } => {
            y.push(omega * first - turn);
            y.push(orbit.points[0].v_in / speed);
        }
    }
    let mut z = DVector::from_vec(y);
    z = z.push(range.0 / scale);
    let eq = Augmented {
        problem: p.as_ref(),
        scales: vec![scale],
        test: None,
    };
    let mut toward = DVector::zeros(z.len());
    toward[z.len() - 1] = (range.1 - range.0).signum();
    let t0 = tangent(&jacobian(&eq, &z)?, &toward)?;
    trace_branch(&eq, z, t0, range, options, (false, stop), &contact, param)
}

#[allow(clippy::too_many_arguments)]
fn trace_branch(
    eq: &Augmented,
    z: DVector<f64>,
    t0: DVector<f64>,
    range: (f64, f64),
    options: &ContinuationOptions,
    (skip_first, stop): (bool, &(dyn Fn() -> bool + Sync)),
    contact: &Contact,
    key: Param,
) -> Result<Branch, ContinuationError> {
    let scale = eq.scales[0];
    let lo = range.0.min(range.1) / scale;
    let hi = range.0.max(range.1) / scale;
    let trace = Trace {
        eq,
        options: *options,
        watch: SpecialKind::ALL.to_vec(),
        bounds: (lo, hi),
        min_speed: None,
        stop,
    };
    let traced = trace.run(z, t0, skip_first)?;
    let (cycles, stops) = eq.problem.signature();
    Ok(Branch {
        keys: vec![key.path()],
        contact: contact.name().to_string(),
        cycles,
        stops,
        follows: None,
        points: traced.points,
        specials: traced.specials,
        end: traced.end,
        speed: eq.problem.scales().0,
        scales: eq.scales.clone(),
    })
}

/// The branch of doubled orbits (2m forcing periods) born at the period doubling `special` of
/// `branch`, followed in the same key over `range`: started from the doubling point plus a step
/// along the critical eigenvector (the multiplier −1's), corrected onto the new branch.
pub fn switch_at_period_doubling(
    model: &SystemModel,
    contact: &Contact,
    param: Param,
    range: (f64, f64),
    branch: &Branch,
    special: &SpecialPoint,
    options: &ContinuationOptions,
) -> Result<Branch, ContinuationError> {
    switch_at_period_doubling_until(
        model, contact, param, range, branch, special, options, &never,
    )
}

/// [`switch_at_period_doubling`] that polls `stop` before every step and ends with
/// [`ContinuationError::Stopped`] once it says so (the explorer's job, superseded by an edit).
#[allow(clippy::too_many_arguments)]
pub fn switch_at_period_doubling_until(
    model: &SystemModel,
    contact: &Contact,
    param: Param,
    range: (f64, f64),
    branch: &Branch,
    special: &SpecialPoint,
    options: &ContinuationOptions,
    stop: &(dyn Fn() -> bool + Sync),
) -> Result<Branch, ContinuationError> {
    if special.kind != SpecialKind::PeriodDoubling {
        return Err(ContinuationError::NoSuchPoint(format!(
            "branch switching needs a period doubling, not a {}",
            special.kind.label()
        )));
    }
    check_range(param, range)?;
    let keys = vec![param];
    let p = problem(
        model,
        contact,
        keys.clone(),
        (branch.cycles, branch.stops.clone()),
        branch.speed,
    );
    let z = &special.point.z;
    let n = p.unknowns();
    let (y, mu) = (&z[..n], z[n]);
    let lambda: Vec<f64> = vec![mu * branch.scales[0]];
    let monitors = p.monitors(y, &lambda)?;
    // (J + I)·q = 0 from whichever row of J + I is larger.
    let j = monitors.jacobian;
    let rows = [[j[0][0] + 1.0, j[0][1]], [j[1][0], j[1][1] + 1.0]];
    let row = if rows[0][0].hypot(rows[0][1]) >= rows[1][0].hypot(rows[1][1]) {
        rows[0]
    } else {
        rows[1]
    };
    let norm = row[0].hypot(row[1]);
    let q = [row[1] / norm, -row[0] / norm];
    let (doubled, y2, direction) = p.doubled(y, &monitors, q)?;
    let mut z0 = DVector::from_vec(y2);
    z0 = z0.push(mu);
    let mut t = DVector::from_vec(direction);
    t = t.push(0.0);
    let t = t.normalize();
    let eq = Augmented {
        problem: doubled.as_ref(),
        scales: branch.scales.clone(),
        test: None,
    };
    let step = options.initial_step;
    let (z1, _) = correct(&eq, &(&z0 + &t * step), &t, 12)?;
    let chord = (&z1 - &z0).normalize();
    let t1 = tangent(&jacobian(&eq, &z1)?, &chord)?;
    let mut branch = trace_branch(&eq, z1, t1, range, options, (false, stop), contact, param)?;
    // The doubling point itself starts the new branch.
    let trace = Trace {
        eq: &eq,
        options: *options,
        watch: vec![],
        bounds: (f64::NEG_INFINITY, f64::INFINITY),
        min_speed: None,
        stop: &never,
    };
    let m0 = eq.monitors(&z0)?;
    let first = trace.point(&z0, &m0, 0.0);
    for point in &mut branch.points {
        point.arclength += step;
    }
    for s in &mut branch.specials {
        s.after += 1;
        s.point.arclength += step;
    }
    branch.points.insert(0, first);
    Ok(branch)
}

/// The curve of the special point `special` of `branch` (a fold, period doubling or grazing) in
/// `param` and `second`, followed both ways from the second key's value in `model` until the second
/// key leaves `range2`. Its points' `values` are (first key, second key).
#[allow(clippy::too_many_arguments)]
pub fn continue_special(
    model: &SystemModel,
    contact: &Contact,
    param: Param,
    second: Param,
    range2: (f64, f64),
    branch: &Branch,
    special: &SpecialPoint,
    options: &ContinuationOptions,
) -> Result<Branch, ContinuationError> {
    check_range(second, range2)?;
    let keys = vec![param, second];
    let p = problem(
        model,
        contact,
        keys,
        (branch.cycles, branch.stops.clone()),
        branch.speed,
    );
    let n = p.unknowns();
    let z = &special.point.z;
    let here = second.get(model)?;
    let scale2 = scale_of(range2.0, range2.1).max(here.abs());
    let mut z0 = DVector::from_column_slice(&z[..=n]);
    z0 = z0.push(here / scale2);
    let scales = vec![branch.scales[0], scale2];
    let lambda = vec![z[n] * scales[0], here];
    let index = match special.kind {
        SpecialKind::GrazingImpact => p.monitors(&z[..n], &lambda)?.min_speed().0,
        _ => 0,
    };
    let eq = Augmented {
        problem: p.as_ref(),
        scales,
        test: Some((special.kind, index)),
    };
    test_value(special.kind, &eq.monitors(&z0)?, p.scales(), Some(index)).ok_or_else(|| {
        ContinuationError::NoSuchPoint(format!("no {} test function here", special.kind.label()))
    })?;
    let lo = range2.0.min(range2.1) / scale2;
    let hi = range2.0.max(range2.1) / scale2;
    let (watch, min_speed): (Vec<SpecialKind>, _) = match special.kind {
        SpecialKind::Fold | SpecialKind::PeriodDoubling => (
            vec![SpecialKind::GrazingImpact, SpecialKind::GrazingFlight],
            Some(GRAZED),
        ),
        _ => (vec![], None),
    };
    let jac = jacobian(&eq, &z0)?;
    let mut halves = Vec::new();
    for sign in [-1.0, 1.0] {
        let mut toward = DVector::zeros(z0.len());
        toward[z0.len() - 1] = sign;
        let t0 = tangent(&jac, &toward)?;
        let trace = Trace {
            eq: &eq,
            options: *options,
            watch: watch.clone(),
            bounds: (lo, hi),
            min_speed,
            stop: &never,
        };
        halves.push(trace.run(z0.clone(), t0, false)?);
    }
    let forward = halves.pop().expect("two halves");
    let backward = halves.pop().expect("two halves");
    // The backward half without its start (the forward half's), nor a range end on the start.
    let start = z0.as_slice().to_vec();
    let mut points: Vec<_> = backward
        .points
        .into_iter()
        .rev()
        .filter(|p| p.z.iter().zip(&start).any(|(a, b)| (a - b).abs() > 1e-12))
        .collect();
    for point in &mut points {
        point.arclength = -point.arclength;
    }
    let offset = points.len();
    points.extend(forward.points);
    let mut specials: Vec<_> = backward
        .specials
        .into_iter()
        .map(|mut s| {
            s.point.arclength = -s.point.arclength;
            s.after = offset.saturating_sub(s.after + 1);
            s
        })
        .collect();
    specials.extend(forward.specials.into_iter().map(|mut s| {
        s.after += offset;
        s
    }));
    let (cycles, stops) = p.signature();
    Ok(Branch {
        keys: vec![param.path(), second.path()],
        contact: contact.name().to_string(),
        cycles,
        stops,
        follows: Some(special.kind),
        points,
        specials,
        end: forward.end,
        speed: branch.speed,
        scales: eq.scales.clone(),
    })
}
