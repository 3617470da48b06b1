//! The continuous (t, x, v, F) curves of a solved impact, sampled on demand.

use super::Sample;

/// The curves of one impact. Sample it at the resolution the consumer can show.
#[derive(Debug, Clone)]
pub struct Trajectory {
    // impact helper: phases' dense outputs and the force law used to evaluate F
}

impl Trajectory {
    /// Duration of contact covered, s.
    pub fn t_end(&self) -> f64 {
        todo!("impact helper")
    }

    /// The state and force at time t in [0, t_end].
    pub fn at(&self, t: f64) -> Sample {
        let _ = t;
        todo!("impact helper")
    }

    /// `n` samples evenly spaced in t over the contact, with the exact extrema
    /// (x_max, F_max, contact end) inserted in time order.
    pub fn samples(&self, n: usize) -> Vec<Sample> {
        let _ = n;
        todo!("impact helper")
    }
}
