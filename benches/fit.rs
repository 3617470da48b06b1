//! Issue 23's performance item: a 200-point e(v) data set fitted by every candidate law in under a
//! second. The data: Kuwabara–Kono (A fixed, a law that needs the solver) on the default scene's
//! steel sphere, v from 0.05 to 3 m/s evenly in log v, Gaussian noise of sd 0.005 (seeded).
//! Reports the wall time of `fit_restitution` on rayon's pool, each law's fit (iterations,
//! curve evaluations, its own wall time fitted alone) and the forward model's cost per e(v)
//! evaluation.
//!
//! Run with `cargo bench --bench fit` (`-- --repeat N` to repeat the whole fit N times).

use std::hint::black_box;
use std::time::Instant;

use hertz_tui::model::fit::{
    Candidate, FitOptions, Forward, RestitutionData, RestitutionSample, candidates,
    fit_restitution, fit_restitution_params,
};
use hertz_tui::model::presets::{DEFAULT_SCENE, Registry};

mod machine;
use machine::load_average;

const POINTS: usize = 200;
const NOISE: f64 = 0.005;
const KK_A: f64 = 2e-6;

/// SplitMix64 and Box–Muller: seeded Gaussian noise without a dependency.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }

    fn gauss(&mut self) -> f64 {
        let (u, v) = (self.next().max(1e-300), self.next());
        (-2.0 * u.ln()).sqrt() * (2.0 * std::f64::consts::PI * v).cos()
    }
}

fn main() {
    let repeat: usize = std::env::args()
        .skip_while(|a| a != "--repeat")
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(3);
    let scene = Registry::builtin()
        .expect("presets")
        .scene(DEFAULT_SCENE)
        .expect("default scene");
    let params = scene.impact_params(&scene.quasistatic().expect("valid scene"));
    let kk = Candidate::from_id("kuwabara-kono").expect("a law");
    let truth = Forward::new(&params, kk).expect("forward");
    let mut rng = Rng(23);
    let vs: Vec<f64> = (0..POINTS)
        .map(|i| 0.05 * (3.0f64 / 0.05).powf(i as f64 / (POINTS - 1) as f64))
        .collect();
    let points = vs
        .iter()
        .enumerate()
        .map(|(i, &v)| RestitutionSample {
            v,
            e: (truth.e(&[KK_A], v).expect("solves") + NOISE * rng.gauss()).min(1.0),
            sd: None,
            line: i + 2,
        })
        .collect();
    let data = RestitutionData::new(points).expect("valid data");
    let all = candidates();
    println!(
        "fit: {POINTS} points, {} candidate laws, load {}",
        all.len(),
        load_average()
    );
    let opts = FitOptions::default();
    let mut best = f64::INFINITY;
    let mut report = None;
    for _ in 0..repeat {
        let t = Instant::now();
        let r = fit_restitution(&scene, &data, &all, &opts).expect("fits");
        best = best.min(t.elapsed().as_secs_f64());
        report = Some(r);
    }
    let report = report.expect("at least one run");
    println!(
        "every law, rayon: {:.3} s wall (best of {repeat}; target < 1 s)",
        best
    );
    println!(
        "{:<22} {:>10} {:>6} {:>6} {:>10} {:>12}",
        "law", "Δ", "iter", "evals", "alone s", "e(v) µs"
    );
    let serial = FitOptions {
        parallel: false,
        ..opts
    };
    for fit in &report.fits {
        let t = Instant::now();
        let _ = fit_restitution_params(&params, &data, &[fit.candidate], &serial);
        let alone = t.elapsed().as_secs_f64();
        let forward = Forward::new(&params, fit.candidate).expect("forward");
        let theta = fit.theta();
        let t = Instant::now();
        let mut n = 0;
        while t.elapsed().as_secs_f64() < 0.05 {
            black_box(forward.curve(&theta, &vs).ok());
            n += 1;
        }
        let per = t.elapsed().as_secs_f64() / (n * POINTS) as f64;
        println!(
            "{:<22} {:>10.2} {:>6} {:>6} {:>10.4} {:>12.2}",
            fit.candidate.id(),
            fit.delta,
            fit.iterations,
            fit.evaluations,
            alone,
            per * 1e6
        );
    }
    for (c, why) in &report.failed {
        println!("{c}: failed: {why}");
    }
}
