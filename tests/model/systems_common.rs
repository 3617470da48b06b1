//! Builders shared by the systems tests: systems in the units of their closed forms.

use std::f64::consts::TAU;

use hertz_tui::model::Scene;
use hertz_tui::model::presets::Registry;
use hertz_tui::model::system::{
    Damping, Forcing, GuessStart, OrbitGuess, RunOptions, SystemKind, SystemModel, SystemSpec,
};

/// The `bouncing-ball` preset's scene and system: a steel sphere R = 10 mm on a steel table
/// shaken at 20 Hz.
pub fn bouncing_ball_preset() -> (Scene, SystemSpec) {
    let registry = Registry::builtin().unwrap();
    let scene = registry.scene("bouncing-ball").unwrap();
    let spec = registry
        .scene_system("bouncing-ball", &[])
        .unwrap()
        .unwrap();
    (scene, spec)
}

/// A bouncing ball with g = 1 and ω = 1 rad/s, so that Γ = A and speeds are in units of g/ω.
pub fn ball(gamma: f64, e: f64) -> SystemModel {
    let spec = SystemSpec {
        kind: SystemKind::BouncingBall {
            amplitude: gamma,
            frequency: 1.0 / TAU,
            gravity: 1.0,
        },
    };
    SystemModel::new(spec, 1.0, e).unwrap()
}

/// ẍ + 2ζω₀ẋ + ω₀²x = f·cos(ωt) with m = 1 kg: stiffness ω₀², damping coefficient c, force f,
/// a stop at x = gap (and at −second).
pub fn oscillator(
    k: f64,
    c: f64,
    f: f64,
    omega: f64,
    gap: f64,
    second: Option<f64>,
    e: f64,
) -> SystemModel {
    let spec = SystemSpec {
        kind: SystemKind::ImpactOscillator {
            stiffness: k,
            damping: Damping::Coefficient(c),
            forcing: Forcing::Force { amplitude: f },
            frequency: omega / TAU,
            gap,
            second_gap: second,
        },
    };
    SystemModel::new(spec, 1.0, e).unwrap()
}

/// An orbit guess from a first impact.
pub fn guess(cycles: u32, impacts: u32, phase: f64, v_in: f64, stop: usize) -> OrbitGuess {
    OrbitGuess {
        forcing_cycles: cycles,
        impacts,
        start: Some(GuessStart { phase, v_in, stop }),
        attractor: RunOptions::default(),
    }
}

/// The angle difference a − b wrapped into (−π, π].
pub fn angle_diff(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(TAU);
    if d > TAU / 2.0 { d - TAU } else { d }
}
