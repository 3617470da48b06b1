//! Shared by the fit tests: the scene, a seeded Gaussian generator and synthetic e(v) data.

use hertz_tui::model::ImpactParams;
use hertz_tui::model::fit::{Candidate, Forward, RestitutionData, RestitutionSample};
use hertz_tui::model::presets::{DEFAULT_SCENE, Registry};

/// The default scene (the paper's Fig. 5 steel sphere on a steel plate): k, n and m of every fit.
pub fn params() -> ImpactParams {
    let scene = Registry::builtin().unwrap().scene(DEFAULT_SCENE).unwrap();
    scene.impact_params(&scene.quasistatic().unwrap())
}

/// SplitMix64 (Steele, Lea & Flood, OOPSLA 2014) with Box–Muller normals: seeded and
/// dependency-free, so every draw of a statistical test is reproducible.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Rng(seed)
    }

    pub fn uniform(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }

    pub fn gauss(&mut self) -> f64 {
        let (u, v) = (self.uniform().max(1e-300), self.uniform());
        (-2.0 * u.ln()).sqrt() * (2.0 * std::f64::consts::PI * v).cos()
    }
}

/// `n` velocities from `lo` to `hi`, evenly in log v.
pub fn velocities(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| lo * (hi / lo).powf(i as f64 / (n - 1) as f64))
        .collect()
}

/// The true parameter of a law for the tests: the one that realises `e` at the scene's v₀
/// (calibration, the fits' own start rule), so that every law damps alike at v₀.
pub fn truth(forward: &Forward, params: &ImpactParams, e: f64) -> Vec<f64> {
    forward.start(params.v0, e).unwrap()
}

/// e(v) of `forward` at `theta` plus Gaussian noise of sd `noise` (clamped into (0, 1]), with
/// the sd given when `give_sd`.
pub fn synthetic(
    forward: &Forward,
    theta: &[f64],
    vs: &[f64],
    noise: f64,
    give_sd: bool,
    rng: &mut Rng,
) -> RestitutionData {
    let clean = forward.curve(theta, vs).unwrap();
    let points = vs
        .iter()
        .zip(clean)
        .enumerate()
        .map(|(i, (&v, e))| RestitutionSample {
            v,
            e: (e + noise * rng.gauss()).clamp(1e-6, 1.0),
            sd: give_sd.then_some(noise),
            line: i + 2,
        })
        .collect();
    RestitutionData::new(points).unwrap()
}

/// The candidates a recovery test fits: the defaults plus `truth` if it is not among them.
pub fn with(truth: Candidate) -> Vec<Candidate> {
    let mut all = hertz_tui::model::fit::candidates();
    if !all.contains(&truth) {
        all.push(truth);
    }
    all
}
