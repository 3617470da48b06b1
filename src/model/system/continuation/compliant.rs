//! The compliant stop's periodic orbits by shooting through its solver (docs/continuation.md §1):
//! the unknowns are the first contact's phase ωt and approach speed; one orbit is n applications
//! of the compliant impact map (a contact integrated through the law, then the closed-form flight
//! to the next first contact), which must return after m forcing periods.

use std::cell::RefCell;
use std::f64::consts::TAU;
use std::rc::Rc;

use crate::model::ForceModel;
use crate::model::system::compliant::orbit::{MapPoint, map_jacobian_extrapolated, map_n};
use crate::model::system::compliant::{CompliantOptions, CompliantStop, ORBIT_RTOL};
use crate::model::system::{CompliantDamping, Param, SystemModel};

use super::error::ContinuationError;
use super::problem::{Monitors, OrbitProblem, model_at, rescale};

/// Stops built for recent parameter values: a Jacobian's columns in the unknowns share one.
const CACHED: usize = 4;

/// A compliant orbit of n impacts on `stop` in m forcing periods.
#[derive(Debug, Clone)]
pub(crate) struct CompliantProblem {
    pub base: SystemModel,
    pub keys: Vec<Param>,
    pub law: ForceModel,
    pub damping: CompliantDamping,
    /// The stop of the first contact.
    pub stop: usize,
    pub impacts: u32,
    pub cycles: u32,
    /// Speed scale V (unknown w = v_in/V), m/s.
    pub speed: f64,
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
        stop: usize,
        impacts: u32,
        cycles: u32,
        speed: f64,
    ) -> CompliantProblem {
        CompliantProblem {
            base,
            keys,
            law,
            damping,
            stop,
            impacts,
            cycles,
            speed,
            cache: Rc::default(),
        }
    }

    fn stop_at(&self, lambda: &[f64]) -> Result<Rc<CompliantStop>, ContinuationError> {
        if let Some((_, s)) = self.cache.borrow().iter().find(|(l, _)| l == lambda) {
            return Ok(s.clone());
        }
        let model = model_at(&self.base, &self.keys, lambda)?;
        let options = CompliantOptions {
            rtol: ORBIT_RTOL,
            ..CompliantOptions::default()
        };
        let stop = Rc::new(CompliantStop::new(&model, self.law, self.damping, options)?);
        let mut cache = self.cache.borrow_mut();
        if cache.len() >= CACHED {
            cache.remove(0);
        }
        cache.push((lambda.to_vec(), stop.clone()));
        Ok(stop)
    }

    fn point(&self, stop: &CompliantStop, y: &[f64]) -> MapPoint {
        MapPoint {
            t: y[0] / stop.plant.omega(),
            v_in: y[1] * self.speed,
            stop: self.stop,
        }
    }
}

impl OrbitProblem for CompliantProblem {
    fn unknowns(&self) -> usize {
        2
    }

    fn residual(&self, y: &[f64], lambda: &[f64]) -> Result<Vec<f64>, ContinuationError> {
        let stop = self.stop_at(lambda)?;
        let p = self.point(&stop, y);
        if p.v_in <= 0.0 {
            return Err(ContinuationError::Unsupported(
                "the compliant orbit's impact speed reached zero (grazing)".into(),
            ));
        }
        let (q, _) = map_n(&stop, p, self.impacts)?;
        if q.stop != p.stop {
            return Err(ContinuationError::Unsupported(
                "the compliant orbit ends on the other stop".into(),
            ));
        }
        let omega = stop.plant.omega();
        Ok(vec![
            omega * (q.t - p.t) - TAU * f64::from(self.cycles),
            (q.v_in - p.v_in) / self.speed,
        ])
    }

    fn monitors(&self, y: &[f64], lambda: &[f64]) -> Result<Monitors, ContinuationError> {
        let stop = self.stop_at(lambda)?;
        let p = self.point(&stop, y);
        let (_, steps) = map_n(&stop, p, self.impacts)?;
        // The multipliers and test functions as `orbit` gives them (Richardson-extrapolated).
        let j = map_jacobian_extrapolated(&stop, p, self.impacts)?;
        let jacobian = rescale(
            &[[j[(0, 0)], j[(0, 1)]], [j[(1, 0)], j[(1, 1)]]],
            stop.plant.omega(),
            1.0 / self.speed,
        );
        Ok(Monitors {
            jacobian,
            partials: vec![jacobian],
            speeds: steps.iter().map(|s| s.point.v_in).collect(),
            // The flights' gap minima are the rigid problem's concern: a compliant branch ends
            // where its impact speed does.
            min_gap: None,
            points: steps.iter().map(|s| s.point).collect(),
        })
    }

    fn fd_step(&self) -> f64 {
        1e-6
    }

    fn tolerance(&self) -> f64 {
        1e-9
    }

    fn scales(&self) -> (f64, f64) {
        (self.speed, self.speed / self.base.spec.omega())
    }

    fn signature(&self) -> (u32, Vec<usize>) {
        (self.cycles, vec![self.stop; self.impacts as usize])
    }

    fn doubled(
        &self,
        y: &[f64],
        _monitors: &Monitors,
        q: [f64; 2],
    ) -> Result<(Box<dyn OrbitProblem>, Vec<f64>, Vec<f64>), ContinuationError> {
        let problem = CompliantProblem {
            impacts: 2 * self.impacts,
            cycles: 2 * self.cycles,
            ..self.clone()
        };
        Ok((Box::new(problem), y.to_vec(), q.to_vec()))
    }
}
