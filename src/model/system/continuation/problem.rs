//! What a periodic-orbit problem gives the continuation: its residual in scaled unknowns, and the
//! monitors along it (the impact map's Jacobian, the impact speeds, the flights' gap minima).

use std::f64::consts::TAU;

use nalgebra::Complex;

use crate::model::scene_key::SceneKey;
use crate::model::system::{ImpactPoint, Param, SystemModel};

use super::error::ContinuationError;

/// A 2×2 matrix.
pub(crate) type Mat = [[f64; 2]; 2];

/// What the continuation watches at a point of a branch.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Monitors {
    /// The n-fold impact map's Jacobian in scaled variables (phase ωt, speed over the speed scale):
    /// similar to the map's own, so the same multipliers.
    pub jacobian: Mat,
    /// Each impact's Jacobian in the same variables, in the orbit's order.
    pub partials: Vec<Mat>,
    /// The approach speed of each impact relative to its stop, m/s (negative: the orbit would
    /// pass through the stop there — a virtual orbit).
    pub speeds: Vec<f64>,
    /// The smallest interior minimum of a gap over the flights, m (None: no interior minimum).
    pub min_gap: Option<f64>,
    /// The orbit's impacts.
    pub points: Vec<ImpactPoint>,
    /// A compliant orbit's approaches to the stops (its contacts and its flights' gap minima),
    /// whose clearances locate its grazing; None for the rigid stop, whose grazing is watched
    /// through `speeds` and `min_gap`.
    pub approaches: Option<Vec<Approach>>,
}

/// One approach of a compliant orbit to a stop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Approach {
    /// Its forcing phase from the orbit's section, rad in [0, 2π·m].
    pub phase: f64,
    /// Which stop.
    pub stop: usize,
    /// The smallest gap, m; in a contact −its largest approach δ_max.
    pub clearance: f64,
}

impl Monitors {
    /// The smallest approach speed and its impact.
    pub fn min_speed(&self) -> (usize, f64) {
        self.speeds
            .iter()
            .copied()
            .enumerate()
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap_or((0, f64::INFINITY))
    }

    /// tr J and det J.
    pub fn trace_det(&self) -> (f64, f64) {
        let j = &self.jacobian;
        (j[0][0] + j[1][1], j[0][0] * j[1][1] - j[0][1] * j[1][0])
    }

    /// The eigenvalues of J (Floquet multipliers), the larger in modulus first.
    pub fn multipliers(&self) -> [Complex<f64>; 2] {
        let (trace, det) = self.trace_det();
        let half = 0.5 * trace;
        let disc = half * half - det;
        if disc >= 0.0 {
            let root = disc.sqrt();
            let big = half + root.copysign(half);
            let small = if big != 0.0 { det / big } else { half - root };
            [Complex::new(big, 0.0), Complex::new(small, 0.0)]
        } else {
            let im = (-disc).sqrt();
            [Complex::new(half, im), Complex::new(half, -im)]
        }
    }
}

/// A periodic orbit of fixed impact sequence as zeros of a residual in scaled unknowns y at
/// parameter values λ (one per continued key).
pub(crate) trait OrbitProblem {
    /// The number of unknowns (and of equations) at fixed parameters.
    fn unknowns(&self) -> usize;
    /// The scaled residual.
    fn residual(&self, y: &[f64], lambda: &[f64]) -> Result<Vec<f64>, ContinuationError>;
    /// The monitors at a point.
    fn monitors(&self, y: &[f64], lambda: &[f64]) -> Result<Monitors, ContinuationError>;
    /// Central-difference step, scaled.
    fn fd_step(&self) -> f64;
    /// Newton's tolerance, scaled.
    fn tolerance(&self) -> f64;
    /// The speed and length scales, m/s and m.
    fn scales(&self) -> (f64, f64);
    /// Forcing periods and the stops of the orbit's impacts.
    fn signature(&self) -> (u32, Vec<usize>);
    /// A compliant orbit's approaches to the stops alone (without the Jacobian's cost); None for
    /// a problem that has none.
    fn approaches(
        &self,
        _y: &[f64],
        _lambda: &[f64],
    ) -> Result<Option<Vec<Approach>>, ContinuationError> {
        Ok(None)
    }
    /// The forcing phase of a stroboscopic section, rad (None: sectioned at the impacts).
    fn section(&self) -> Option<f64> {
        None
    }
    /// The problem of the orbit run twice (2m forcing periods), its unknowns at the same orbit, and
    /// the direction of the doubled branch there from the critical eigenvector `q` (scaled) of J.
    #[allow(clippy::type_complexity)]
    fn doubled(
        &self,
        y: &[f64],
        monitors: &Monitors,
        q: [f64; 2],
    ) -> Result<(Box<dyn OrbitProblem>, Vec<f64>, Vec<f64>), ContinuationError>;
}

/// `base` with `keys` set to `values`, in order.
pub(crate) fn model_at(
    base: &SystemModel,
    keys: &[Param],
    values: &[f64],
) -> Result<SystemModel, ContinuationError> {
    let mut model = base.clone();
    for (key, value) in keys.iter().zip(values) {
        model = key.apply(&model, *value)?;
    }
    Ok(model)
}

/// Whether varying `keys` varies the restitution (a rigid stop's e then follows the model).
pub(crate) fn varies_restitution(keys: &[Param]) -> bool {
    keys.contains(&Param::Scene(SceneKey::Restitution))
}

/// The phase ωt wrapped into [0, 2π).
pub(crate) fn wrap(phase: f64) -> f64 {
    phase.rem_euclid(TAU)
}

/// a·b for 2×2 matrices.
pub(crate) fn mul(a: &Mat, b: &Mat) -> Mat {
    let mut out = [[0.0; 2]; 2];
    for (i, row) in out.iter_mut().enumerate() {
        for (j, cell) in row.iter_mut().enumerate() {
            *cell = a[i][0] * b[0][j] + a[i][1] * b[1][j];
        }
    }
    out
}

/// S·J·S⁻¹ with S = diag(sx, sy): a Jacobian in (t, v) as one in (sx·t, sy·v).
pub(crate) fn rescale(j: &Mat, sx: f64, sy: f64) -> Mat {
    [[j[0][0], j[0][1] * sx / sy], [j[1][0] * sy / sx, j[1][1]]]
}
