//! Periodic orbits of the impact map: what Newton is asked for and what it finds.
#![warn(missing_docs)]

use nalgebra::Complex;
use serde::Serialize;

use super::run::{RunOptions, StopIndex};

/// A point of the impact map: the state just before an impact.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ImpactPoint {
    /// Time of the impact, s.
    pub t: f64,
    /// Forcing phase ωt mod 2π, rad.
    pub phase: f64,
    /// Position at the impact (on the stop), m.
    pub x: f64,
    /// Which stop.
    pub stop: StopIndex,
    /// Approach speed relative to the stop, m/s.
    pub v_in: f64,
    /// Separation speed relative to the stop, m/s.
    pub v_out: f64,
}

/// Where Newton starts, and which orbit it looks for.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OrbitGuess {
    /// m: forcing periods per orbit period.
    pub forcing_cycles: u32,
    /// n: impacts per orbit period.
    pub impacts: u32,
    /// The first impact (phase in rad, approach speed in m/s, stop); `None`: take it from the
    /// attractor reached by simulating `attractor` from rest.
    pub start: Option<GuessStart>,
    /// The run that finds the attractor when `start` is `None`.
    pub attractor: RunOptions,
}

/// A guessed first impact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GuessStart {
    /// Forcing phase ωt of the impact, rad.
    pub phase: f64,
    /// Approach speed relative to the stop, m/s (> 0).
    pub v_in: f64,
    /// Which stop.
    pub stop: StopIndex,
}

/// Newton's settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OrbitOptions {
    /// Converged when the correction is below this, relative to the period and to the velocity.
    pub tolerance: f64,
    /// Newton iterations at most.
    pub max_iterations: usize,
    /// Impact budget of every map evaluation (chatter counts).
    pub max_impacts: usize,
}

impl Default for OrbitOptions {
    fn default() -> OrbitOptions {
        OrbitOptions {
            tolerance: 1e-12,
            max_iterations: 50,
            max_impacts: 100_000,
        }
    }
}

/// A periodic orbit of the impact map.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Orbit {
    /// m: forcing periods per orbit period.
    pub period_forcing_cycles: u32,
    /// n: impacts per orbit period.
    pub impacts_per_period: u32,
    /// The n impacts of one period, in order.
    pub points: Vec<ImpactPoint>,
    /// Floquet multipliers: eigenvalues of the Jacobian of the n-fold impact map (phase, velocity).
    #[serde(serialize_with = "serialize_complex")]
    pub multipliers: Vec<Complex<f64>>,
    /// That Jacobian, in the variables (time of the first impact, s; velocity after it, m/s).
    pub jacobian: [[f64; 2]; 2],
    /// Its determinant (e^{2n}·e^{−2ζω₀·mT} for a rigid stop: docs/physics.md §8).
    pub jacobian_det: f64,
    /// All multipliers inside the unit circle.
    pub stable: bool,
    /// Newton iterations taken.
    pub iterations: usize,
}

/// Multipliers as `[re, im]` pairs (JSON has no complex numbers); branches share it.
pub(crate) fn serialize_complex<S: serde::Serializer>(
    values: &[Complex<f64>],
    serializer: S,
) -> Result<S::Ok, S::Error> {
    use serde::ser::SerializeSeq;
    let mut seq = serializer.serialize_seq(Some(values.len()))?;
    for z in values {
        seq.serialize_element(&[z.re, z.im])?;
    }
    seq.end()
}
