//! The synthetic example data of presets/data/ (docs/fitting.md), regenerated here from known laws
//! with stated Gaussian noise and seeds, and compared byte for byte with the files checked in.
//! This test is the command that made them:
//!
//! ```sh no-run
//! HERTZ_TUI_REGENERATE_DATA=1 cargo test --test cli fit_data
//! ```
//!
//! rewrites them (then `git diff presets/data` shows what changed).

use std::fmt::Write as _;
use std::fs;
use std::path::Path;

use hertz_tui::model::impact::{SolveOptions, solve_law};
use hertz_tui::model::presets::Registry;
use hertz_tui::model::scene_fit::{FittedKind, FittedLaw};
use hertz_tui::model::{ForceModel, Scene};

/// SplitMix64 (Steele, Lea & Flood 2014): a small seeded generator, the same on every machine.
struct SplitMix(u64);

impl SplitMix {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in (0, 1).
    fn uniform(&mut self) -> f64 {
        ((self.next() >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }

    /// Standard normal by Box–Muller (one of the pair).
    fn normal(&mut self) -> f64 {
        let (u1, u2) = (self.uniform(), self.uniform());
        (-2.0 * u1.ln()).sqrt() * (2.0 * std::f64::consts::PI * u2).cos()
    }
}

fn scene(name: &str) -> Scene {
    Registry::builtin().unwrap().scene(name).unwrap()
}

/// e of `fit` on `scene` at `v` m/s.
fn e_at(scene: &Scene, fit: &FittedLaw, v: f64) -> f64 {
    let mut s = scene.clone();
    s.impact.v0 = v;
    let q = s.quasistatic().unwrap();
    fit.restitution_at(&s.impact_params(&q)).unwrap()
}

/// An e(v) set: `repeats` drops at each velocity, e = law + N(0, sd²), rounded to 4 decimals.
#[allow(clippy::too_many_arguments)]
fn restitution_set(
    about: &str,
    scene_name: &str,
    fit: &FittedLaw,
    velocities: &[f64],
    repeats: usize,
    sd: f64,
    seed: u64,
) -> String {
    let scene = scene(scene_name);
    let (key, _, unit) = fit.constant();
    let mut out = String::new();
    let _ = writeln!(out, "# SYNTHETIC data, not measurements: {about}");
    let _ = writeln!(
        out,
        "# generated from {} with {key} = {} {unit} on the preset scene {scene_name},",
        fit.kind.id(),
        fit.value
    );
    let _ = writeln!(
        out,
        "# plus Gaussian noise of sd = {sd} on e (SplitMix64 seed {seed}, Box-Muller), {repeats} drops per velocity;"
    );
    let _ = writeln!(
        out,
        "# regenerate: HERTZ_TUI_REGENERATE_DATA=1 cargo test --test cli fit_data"
    );
    out.push_str("v (m/s), e, sd\n");
    let mut rng = SplitMix(seed);
    for &v in velocities {
        let e = e_at(&scene, fit, v);
        for _ in 0..repeats {
            let noisy = (e + sd * rng.normal()).min(1.0);
            let _ = writeln!(out, "{v}, {noisy:.4}, {sd}");
        }
    }
    out
}

/// A force trace over one impact of `model` with its damping `value` on `scene_name` at its v₀:
/// zero before the contact starts at `t0`, F + N(0, sd²) during it, zero after; t in µs, F in N.
fn force_trace(
    scene_name: &str,
    model: ForceModel,
    a: f64,
    t0: f64,
    points: usize,
    sd: f64,
    seed: u64,
) -> String {
    let scene = scene(scene_name);
    let q = scene.quasistatic().unwrap();
    let params = scene.impact_params(&q);
    let fit = FittedLaw::new(FittedKind::Law(model), a);
    let law = fit.law(&params).unwrap().unwrap().1;
    let solution = solve_law(&law, &SolveOptions::default()).unwrap();
    let tc = solution.summary.t_contact;
    let span = t0 + 1.3 * tc;
    let mut out = String::new();
    let _ = writeln!(
        out,
        "# SYNTHETIC trace, not a measurement: one impact of {model} with a = {a} s/m on the preset"
    );
    let _ = writeln!(
        out,
        "# scene {scene_name} (v0 = {} m/s); contact starts at t0 = {} us; Gaussian noise of",
        scene.impact.v0,
        t0 * 1e6
    );
    let _ = writeln!(
        out,
        "# sd = {sd} N on F (SplitMix64 seed {seed}, Box-Muller); regenerate:"
    );
    let _ = writeln!(
        out,
        "# HERTZ_TUI_REGENERATE_DATA=1 cargo test --test cli fit_data"
    );
    out.push_str("t (us), F (N)\n");
    let mut rng = SplitMix(seed);
    for i in 0..points {
        let t = span * i as f64 / (points - 1) as f64;
        let inside = t > t0 && t < t0 + tc;
        let f = if inside {
            solution.trajectory.at(t - t0).f
        } else {
            0.0
        };
        let noisy = f + sd * rng.normal();
        let _ = writeln!(out, "{:.4}, {noisy:.3}", t * 1e6);
    }
    out
}

/// The example files: name and text.
fn examples() -> Vec<(&'static str, String)> {
    let hc = FittedLaw::new(FittedKind::Law(ForceModel::HuntCrossley), 1.2);
    let velocities = [0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0, 1.5];
    // Thornton at the aluminium pair's own yield velocity (its material constant v_y).
    let al = scene("aluminium-sphere-r10-plate");
    let thornton = ForceModel::with_id("thornton");
    let v_y = thornton
        .law(&al.impact_params(&al.quasistatic().unwrap()))
        .unwrap()
        .damping()
        .unwrap()
        .value;
    let th = FittedLaw::new(FittedKind::Law(thornton), v_y);
    vec![
        (
            "steel-hunt-crossley.csv",
            restitution_set(
                "a steel sphere R = 10 mm dropped on a steel plate",
                "steel-sphere-r10-plate",
                &hc,
                &velocities,
                2,
                0.01,
                23,
            ),
        ),
        (
            "aluminium-thornton.csv",
            restitution_set(
                "an aluminium alloy sphere R = 10 mm dropped on an aluminium alloy plate",
                "aluminium-sphere-r10-plate",
                &th,
                &[0.1, 0.2, 0.4, 0.7, 1.0, 1.5, 2.0, 3.0],
                2,
                0.01,
                42,
            ),
        ),
        (
            "steel-force-trace.csv",
            force_trace(
                "steel-sphere-r10-plate",
                ForceModel::HuntCrossley,
                1.2,
                20e-6,
                121,
                20.0,
                7,
            ),
        ),
    ]
}

#[test]
fn fit_data_regenerates_byte_for_byte() {
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("presets/data");
    let regenerate = std::env::var_os("HERTZ_TUI_REGENERATE_DATA").is_some();
    for (name, text) in examples() {
        let path = folder.join(name);
        if regenerate {
            fs::create_dir_all(&folder).unwrap();
            fs::write(&path, &text).unwrap();
        }
        let checked_in = fs::read_to_string(&path).unwrap_or_default();
        assert!(
            checked_in == text,
            "{} differs from what its generator gives; rerun with HERTZ_TUI_REGENERATE_DATA=1 if the change is meant",
            path.display()
        );
    }
}

#[test]
fn the_noise_generator_is_standard_normal() {
    let mut rng = SplitMix(1);
    let n = 20_000;
    let xs: Vec<f64> = (0..n).map(|_| rng.normal()).collect();
    let mean = xs.iter().sum::<f64>() / n as f64;
    let var = xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1) as f64;
    // Standard errors of the mean and variance at n = 20 000: 0.007 and 0.01; 4 of them.
    assert!(mean.abs() < 0.03, "{mean}");
    assert!((var - 1.0).abs() < 0.04, "{var}");
}
