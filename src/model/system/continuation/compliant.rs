//! The compliant stop's periodic orbits by shooting through its solver on a stroboscopic section
//! (docs/continuation.md §1): the unknowns are the body's position and velocity at a fixed forcing
//! phase φ_s, chosen in the start orbit's flight where the body is farthest from every stop; the
//! orbit is the motion from there over m forcing periods (flights in closed form, contacts
//! through the law), which must come back to the same state.
//!
//! A section at first contact degenerates as the impact speed falls to zero; this one does not:
//! the compliant force is continuous in the penetration, so the time-mT map is continuous (and,
//! for the Hertz family's F ∝ δ^n with n > 1, differentiable) through a contact that vanishes or
//! appears, and the branch can be followed to grazing and past it.

use std::cell::RefCell;
use std::f64::consts::TAU;
use std::rc::Rc;

use nalgebra::Matrix2;

use crate::model::ForceModel;
use crate::model::system::compliant::plant::Plant;
use crate::model::system::compliant::{CompliantOptions, CompliantStop, ORBIT_RTOL};
use crate::model::system::{CompliantDamping, Orbit, Param, SystemModel};

use super::error::ContinuationError;
use super::journey::{Journey, journey};
use super::problem::{Approach, Monitors, OrbitProblem, model_at};

/// Stops built for recent parameter values: a Jacobian's columns in the unknowns share one.
const CACHED: usize = 4;

/// The smallest step of the multipliers' differences, scaled (at a grazing itself).
const MIN_STEP: f64 = 1e-9;

/// Samples per flight when the section is chosen.
const SECTION_SAMPLES: usize = 256;

/// A compliant orbit of m forcing periods through the section at phase φ_s.
#[derive(Debug, Clone)]
pub(crate) struct CompliantProblem {
    pub base: SystemModel,
    pub keys: Vec<Param>,
    pub law: ForceModel,
    pub damping: CompliantDamping,
    /// The stops of the start orbit's contacts (the branch's signature).
    pub stops: Vec<usize>,
    pub cycles: u32,
    /// Speed scale V (unknown w = v/V), m/s.
    pub speed: f64,
    /// The section's forcing phase φ_s = ωt_s, rad.
    pub section: f64,
    cache: Rc<RefCell<Vec<Cached>>>,
}

/// A stop built at parameter values λ.
type Cached = (Vec<f64>, Rc<CompliantStop>);

impl CompliantProblem {
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        base: SystemModel,
        keys: Vec<Param>,
        law: ForceModel,
        damping: CompliantDamping,
        stops: Vec<usize>,
        cycles: u32,
        speed: f64,
        section: f64,
    ) -> CompliantProblem {
        CompliantProblem {
            base,
            keys,
            law,
            damping,
            stops,
            cycles,
            speed,
            section,
            cache: Rc::default(),
        }
    }

    fn stop_at(&self, lambda: &[f64]) -> Result<Rc<CompliantStop>, ContinuationError> {
        if let Some((_, s)) = self.cache.borrow().iter().find(|(l, _)| l == lambda) {
            return Ok(s.clone());
        }
        let model = model_at(&self.base, &self.keys, lambda)?;
        let stop = Rc::new(built(&model, self.law, self.damping)?);
        let mut cache = self.cache.borrow_mut();
        if cache.len() >= CACHED {
            cache.remove(0);
        }
        cache.push((lambda.to_vec(), stop.clone()));
        Ok(stop)
    }

    /// The length scale of x: V/ω at the base model, m.
    fn length(&self) -> f64 {
        self.speed / self.base.spec.omega()
    }

    /// The section's time at λ, s, and the orbit's duration mT.
    fn times(&self, stop: &CompliantStop) -> (f64, f64) {
        let omega = stop.plant.omega();
        (self.section / omega, f64::from(self.cycles) * TAU / omega)
    }

    /// The motion over one orbit from the scaled state y at the section.
    fn orbit(&self, stop: &CompliantStop, y: &[f64]) -> Result<Journey, ContinuationError> {
        let (t0, duration) = self.times(stop);
        let (x, v) = (y[0] * self.length(), y[1] * self.speed);
        for i in 0..stop.plant.stop_count() {
            if stop.plant.stop(i, t0).gap(x) < 0.0 {
                return Err(ContinuationError::Unsupported(
                    "the compliant orbit's section fell inside a contact".into(),
                ));
            }
        }
        journey(stop, (t0, x, v), t0 + duration, false)
    }

    /// The approaches of an orbit, their phases from the section.
    fn approaches_of(&self, stop: &CompliantStop, path: &Journey) -> Vec<Approach> {
        let (t0, _) = self.times(stop);
        let omega = stop.plant.omega();
        path.clearances
            .iter()
            .map(|c| Approach {
                phase: omega * (c.t - t0),
                stop: c.stop,
                clearance: c.value,
            })
            .collect()
    }

    /// The scaled time-mT map.
    fn map(&self, stop: &CompliantStop, y: &[f64]) -> Result<[f64; 2], ContinuationError> {
        let end = self.orbit(stop, y)?.end;
        Ok([end.0 / self.length(), end.1 / self.speed])
    }

    /// The map's Jacobian by central differences at steps h and h/2, combined by Richardson's
    /// extrapolation (4·D(h/2) − D(h))/3, h = rtol^(1/5)/2π in the scaled unknowns: the step
    /// the compliant `orbit` takes for its multipliers (docs/compliant.md §4). Near grazing the
    /// step is cut to a tenth of the orbit's smallest clearance (over the length scale), so that
    /// the differences are the map's on this side of the grazing, not a chord across it.
    fn jacobian(
        &self,
        stop: &CompliantStop,
        y: &[f64],
        closest: f64,
    ) -> Result<Matrix2<f64>, ContinuationError> {
        let difference = |h: f64| -> Result<Matrix2<f64>, ContinuationError> {
            let mut j = Matrix2::zeros();
            for col in 0..2 {
                let (mut plus, mut minus) = (y.to_vec(), y.to_vec());
                plus[col] += h;
                minus[col] -= h;
                let (a, b) = (self.map(stop, &plus)?, self.map(stop, &minus)?);
                for row in 0..2 {
                    j[(row, col)] = (a[row] - b[row]) / (2.0 * h);
                }
            }
            Ok(j)
        };
        let h = (stop.options.rtol.powf(0.2) / TAU)
            .min(0.1 * closest / self.length())
            .max(MIN_STEP);
        Ok((4.0 * difference(0.5 * h)? - difference(h)?) / 3.0)
    }
}

/// The compliant stop of `model`, integrated to the orbits' tolerance.
fn built(
    model: &SystemModel,
    law: ForceModel,
    damping: CompliantDamping,
) -> Result<CompliantStop, ContinuationError> {
    let options = CompliantOptions {
        rtol: ORBIT_RTOL,
        ..CompliantOptions::default()
    };
    Ok(CompliantStop::new(model, law, damping, options)?)
}

/// The section of a compliant orbit found by the solver (its first contact's time and speed):
/// the forcing phase where, over its flights, the body is farthest from the nearest stop, and the
/// body's (x, v) there.
pub(crate) fn section_of(
    model: &SystemModel,
    law: ForceModel,
    damping: CompliantDamping,
    orbit: &Orbit,
) -> Result<(f64, (f64, f64)), ContinuationError> {
    let stop = built(model, law, damping)?;
    let plant = &stop.plant;
    let first = orbit.points.first().ok_or_else(|| {
        ContinuationError::Unsupported("the compliant orbit has no impact to start from".into())
    })?;
    let duration = f64::from(orbit.period_forcing_cycles) * plant.period();
    let motion = plant.stop(first.stop, first.t);
    let (_, v) = motion.body(0.0, first.v_in);
    let end = first.t + duration;
    let c = stop.contact(first.stop, first.t, v, end, false)?;
    let crate::model::system::compliant::contact::Exit::Free { t, x, v } = c.exit else {
        return Err(ContinuationError::Unsupported(
            "the compliant orbit's first contact does not end".into(),
        ));
    };
    // To just before the orbit's next first contact, which closes it.
    let path = journey(
        &stop,
        (t, x, v),
        end - 1e-6 * plant.period(),
        c.t_end == c.t_start,
    )?;
    let clearance = |t: f64, x: f64| {
        (0..plant.stop_count())
            .map(|i| plant.stop(i, t).gap(x))
            .fold(f64::INFINITY, f64::min)
    };
    let mut best: Option<(f64, f64)> = None;
    for (a, b, flight) in &path.flights {
        for k in 1..SECTION_SAMPLES {
            let t = a + (b - a) * k as f64 / SECTION_SAMPLES as f64;
            let g = clearance(t, flight.at(t).0);
            if best.is_none_or(|(_, bg)| g > bg) {
                best = Some((t, g));
            }
        }
    }
    let (t_s, _) = best.ok_or_else(|| {
        ContinuationError::Unsupported(
            "the compliant orbit has no flight to put a section in".into(),
        )
    })?;
    let flight = path
        .flights
        .iter()
        .find(|(a, b, _)| (*a..=*b).contains(&t_s))
        .map(|f| f.2)
        .ok_or_else(|| ContinuationError::Unsupported("no flight at the section".into()))?;
    let omega = plant.omega();
    // The phase in [0, 2π·m) from the orbit's first contact.
    let turn = (omega * first.t).div_euclid(TAU) * TAU;
    Ok((omega * t_s - turn, flight.at(t_s)))
}

impl OrbitProblem for CompliantProblem {
    fn unknowns(&self) -> usize {
        2
    }

    fn residual(&self, y: &[f64], lambda: &[f64]) -> Result<Vec<f64>, ContinuationError> {
        let stop = self.stop_at(lambda)?;
        let image = self.map(&stop, y)?;
        Ok(vec![image[0] - y[0], image[1] - y[1]])
    }

    fn monitors(&self, y: &[f64], lambda: &[f64]) -> Result<Monitors, ContinuationError> {
        let stop = self.stop_at(lambda)?;
        let path = self.orbit(&stop, y)?;
        let approaches = self.approaches_of(&stop, &path);
        let closest = path
            .clearances
            .iter()
            .map(|c| c.value.abs())
            .fold(f64::INFINITY, f64::min);
        let j = self.jacobian(&stop, y, closest)?;
        let jacobian = [[j[(0, 0)], j[(0, 1)]], [j[(1, 0)], j[(1, 1)]]];
        let min_gap = approaches
            .iter()
            .filter(|a| a.clearance >= 0.0)
            .map(|a| a.clearance)
            .reduce(f64::min);
        Ok(Monitors {
            jacobian,
            partials: vec![jacobian],
            speeds: path.impacts.iter().map(|p| p.v_in).collect(),
            min_gap,
            points: path.impacts,
            approaches: Some(approaches),
        })
    }

    fn fd_step(&self) -> f64 {
        1e-6
    }

    fn tolerance(&self) -> f64 {
        // Tighter (1e-10) and Newton no longer converges within the stiff stop's last few
        // micrometres per second of impact speed before grazing.
        1e-9
    }

    fn scales(&self) -> (f64, f64) {
        (self.speed, self.length())
    }

    fn signature(&self) -> (u32, Vec<usize>) {
        (self.cycles, self.stops.clone())
    }

    fn section(&self) -> Option<f64> {
        Some(self.section)
    }

    fn approaches(
        &self,
        y: &[f64],
        lambda: &[f64],
    ) -> Result<Option<Vec<Approach>>, ContinuationError> {
        let stop = self.stop_at(lambda)?;
        let path = self.orbit(&stop, y)?;
        Ok(Some(self.approaches_of(&stop, &path)))
    }

    fn doubled(
        &self,
        y: &[f64],
        _monitors: &Monitors,
        q: [f64; 2],
    ) -> Result<(Box<dyn OrbitProblem>, Vec<f64>, Vec<f64>), ContinuationError> {
        let mut stops = self.stops.clone();
        stops.extend_from_slice(&self.stops);
        let problem = CompliantProblem {
            stops,
            cycles: 2 * self.cycles,
            ..self.clone()
        };
        Ok((Box::new(problem), y.to_vec(), q.to_vec()))
    }
}
