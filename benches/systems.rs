//! The bouncing-ball bifurcation diagram of issue 25's performance item, rigid and compliant:
//! e = 0.5, Γ from 0.9 to 3.5 in 1000 values, 500 transient and 200 recorded impacts per value
//! (7·10⁵ impacts), on rayon's pool (both cores), through `system::bifurcation` — the steel sphere
//! R = 10 mm of the `bouncing-ball` preset, at the forcing frequency where the elastic contact at
//! the period-1 orbit's impact speed gT/(1+e) lasts 1 % of the period (eq 7). The compliant stop is
//! Hunt–Crossley with the exact χ (its realised e is e at every impact).
//!
//! Beside each diagram it measures the per-impact floor: for the rigid stop one root of the
//! flight's gap function (the cost of evaluating the gap, times the evaluations one root takes);
//! for the compliant stop, the contact's force evaluations (their count per contact, from the
//! run's own counters, times the cost of one).
//!
//! Run with `cargo bench --bench systems` (`-- --values N` for a smaller diagram); its peer is
//! `python3 benches/scipy/bouncing_ball.py` (docs/performance.md, "Vibro-impact diagrams").

use std::hint::black_box;
use std::ops::ControlFlow;
use std::time::Instant;

use hertz_tui::model::ForceModel;
use hertz_tui::model::force::{ForceLaw, Phase};
use hertz_tui::model::presets::Registry;
use hertz_tui::model::system::compliant::{CompliantOptions, simulate_detailed};
use hertz_tui::model::system::{
    CompliantDamping, Contact, DiagramOptions, Param, RunOptions, SystemKey, SystemKind,
    SystemModel, SystemSpec, bifurcation,
};

mod machine;
use machine::{cpu_seconds, load_average};

const E: f64 = 0.5;
const CONTACT_RATIO: f64 = 0.01;

/// The preset's ball and table at Γ = 2, its frequency set for t_c/T = 1 % at gT/(1+e).
fn model() -> SystemModel {
    let registry = Registry::load().expect("built-in presets load");
    let mut scene = registry.scene("bouncing-ball").expect("preset resolves");
    scene.impact.restitution = E;
    let gravity = 9.81;
    let probe = SystemModel::from_scene(
        &scene,
        &SystemSpec {
            kind: SystemKind::BouncingBall {
                amplitude: 1e-3,
                frequency: 20.0,
                gravity,
            },
        },
    )
    .expect("preset model");
    let law = scene.quasistatic().expect("valid scene").law();
    let c1 = law.contact_time(probe.mass, 1.0);
    // t_c/T = c1·(g/((1+e)f))^(−1/5)·f  ⇒  f = (ratio/c1·(g/(1+e))^(1/5))^(5/6).
    let frequency = (CONTACT_RATIO / c1 * (gravity / (1.0 + E)).powf(0.2)).powf(5.0 / 6.0);
    let omega = 2.0 * std::f64::consts::PI * frequency;
    SystemModel::from_scene(
        &scene,
        &SystemSpec {
            kind: SystemKind::BouncingBall {
                amplitude: 2.0 * gravity / (omega * omega),
                frequency,
                gravity,
            },
        },
    )
    .expect("bench model")
}

fn diagram(model: &SystemModel, contact: &Contact, values: &[f64]) -> (f64, f64, usize) {
    let options = DiagramOptions {
        run: RunOptions {
            transient_impacts: 500,
            recorded_impacts: 200,
            ..RunOptions::default()
        },
        ..DiagramOptions::default()
    };
    let start = Instant::now();
    let cpu = cpu_seconds();
    let mut impacts = 0;
    let d = bifurcation(
        model,
        contact,
        Param::System(SystemKey::Gamma),
        values,
        &options,
        |_| ControlFlow::Continue(()),
    )
    .expect("diagram runs");
    let seconds = start.elapsed().as_secs_f64();
    let cpu = cpu_seconds() - cpu;
    // Impacts simulated: 700 a value, fewer where the ball came to rest (then at most the
    // transient and what was recorded).
    for c in &d.columns {
        impacts += if c.velocities.len() == 200 {
            700
        } else {
            500 + c.velocities.len()
        };
    }
    (seconds, cpu, impacts)
}

/// Nanoseconds per call of `f`, best of 5 batches.
fn per_call(mut f: impl FnMut(u64) -> f64) -> f64 {
    let n = 2_000_000;
    (0..5)
        .map(|_| {
            let start = Instant::now();
            let mut acc = 0.0;
            for i in 0..n {
                acc += f(i);
            }
            black_box(acc);
            start.elapsed().as_secs_f64() * 1e9 / n as f64
        })
        .fold(f64::INFINITY, f64::min)
}

fn main() {
    let mut values_n = 1000;
    let args: Vec<String> = std::env::args().collect();
    if let Some(i) = args.iter().position(|a| a == "--values") {
        values_n = args.get(i + 1).and_then(|v| v.parse().ok()).unwrap_or(1000);
    }
    let model = model();
    let values: Vec<f64> = (0..values_n)
        .map(|i| 0.9 + 2.6 * i as f64 / (values_n - 1).max(1) as f64)
        .collect();
    println!(
        "bouncing-ball diagram: f = {:.3} Hz, e = {E}, Γ 0.9–3.5 in {values_n} values, 500 + 200 impacts each, {} threads",
        model.spec.frequency(),
        rayon::current_num_threads()
    );
    println!("load average before: {}", load_average());

    let rigid = Contact::rigid(E);
    let (s, cpu, total) = diagram(&model, &rigid, &values);
    println!(
        "rigid:          {s:8.3} s wall, {cpu:8.2} s CPU, {total} impacts, {:.3} µs CPU per impact",
        1e6 * cpu / total as f64
    );

    let hc = Contact::Compliant {
        model: ForceModel::HuntCrossley,
        damping: CompliantDamping::CalibratedTo(E),
    };
    let (s, cpu, total) = diagram(&model, &hc, &values);
    println!(
        "hunt-crossley:  {s:8.3} s wall, {cpu:8.2} s CPU, {total} impacts, {:.3} µs CPU per impact",
        1e6 * cpu / total as f64
    );

    // Floors. The contact's: force evaluations per contact (the run's counters) × one evaluation.
    let run = simulate_detailed(
        &model,
        ForceModel::HuntCrossley,
        CompliantDamping::CalibratedTo(E),
        &RunOptions {
            transient_impacts: 100,
            recorded_impacts: 200,
            ..RunOptions::default()
        },
        CompliantOptions::default(),
    )
    .expect("run");
    let contacts = run.details.len().max(1) as f64;
    let evals = run.details.iter().map(|d| d.force_evals).sum::<usize>() as f64 / contacts;
    let steps = run.details.iter().map(|d| d.steps).sum::<usize>() as f64 / contacts;
    let law = hertz_tui::model::system::compliant::CompliantStop::new(
        &model,
        ForceModel::HuntCrossley,
        CompliantDamping::CalibratedTo(E),
        CompliantOptions::default(),
    )
    .expect("stop")
    .source
    .at(0.2)
    .expect("law");
    let force_ns = per_call(|i| {
        let x = 1e-7 * (1.0 + (i & 1023) as f64 * 1e-3);
        law.phase_force(black_box(x), black_box(0.1), Phase::Loading)
    });
    println!(
        "compliant floor: {evals:.0} force evaluations ({steps:.1} steps) per contact × {force_ns:.1} ns = {:.2} µs per impact",
        evals * force_ns * 1e-3
    );
    // The flight's: the gap y − A·sin(ωt) of a ballistic flight, evaluated once per iteration of
    // a bracketed root (Brent: about 10 evaluations to 1e-15 of the period).
    let (a, w) = (1e-4, 2.0 * std::f64::consts::PI * model.spec.frequency());
    let gap_ns = per_call(|i| {
        let t = 1e-3 * (i & 1023) as f64;
        black_box(0.1 + 0.5 * t - 4.9 * t * t) - a * (w * black_box(t)).sin()
    });
    println!(
        "rigid floor: one root of the flight's gap ≈ 10 evaluations × {gap_ns:.1} ns = {:.2} µs per impact",
        10.0 * gap_ns * 1e-3
    );
    println!("load average after: {}", load_average());
}
