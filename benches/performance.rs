//! One impact per model (auto, and DOPRI5 at rtol 1e-8, side by side) and a 1000-point v₀ sweep
//! of the paper's five models. The explorer's key-to-frame time is the pty benchmark's.
//!
//! Run with `cargo bench --bench performance` (one group: `cargo bench --bench performance -- sweep`).

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use hertz_tui::model::ForceModel;
use hertz_tui::model::impact::{MethodChoice, SolveOptions, solve_impact};
use hertz_tui::model::ode::Method;
use hertz_tui::model::presets::{DEFAULT_SCENE, Registry};
use hertz_tui::model::scene::Scene;
use hertz_tui::model::scene_file::PAPER_MODELS;
use hertz_tui::model::scene_key::SceneKey;
use hertz_tui::model::study::sweep::{SweepSpec, sweep};

fn default_scene() -> Scene {
    let registry = Registry::load().expect("built-in presets load");
    registry
        .scene(DEFAULT_SCENE)
        .expect("default scene resolves")
}

fn impacts(c: &mut Criterion) {
    let scene = default_scene();
    let qs = scene.quasistatic().expect("default scene is valid");
    let params = scene.impact_params(&qs);
    let auto = SolveOptions::default();
    let dopri5 = SolveOptions {
        method: MethodChoice::Integrator(Method::Dopri5),
        rtol: 1e-8,
        atol: Some(1e-8),
        ..SolveOptions::default()
    };
    for model in ForceModel::ALL {
        c.bench_function(&format!("impact/auto/{model}"), |b| {
            b.iter(|| solve_impact(black_box(model), black_box(&params), &auto))
        });
        c.bench_function(&format!("impact/dopri5-1e-8/{model}"), |b| {
            b.iter(|| solve_impact(black_box(model), black_box(&params), &dopri5))
        });
    }
}

fn sweeps(c: &mut Criterion) {
    let scene = default_scene();
    let spec = SweepSpec {
        key: SceneKey::V0,
        from: 1e-3,
        to: 1.0,
        points: 1000,
        log: true,
        models: PAPER_MODELS.to_vec(),
        options: SolveOptions::default(),
    };
    let mut group = c.benchmark_group("sweep");
    group.sample_size(10);
    group.bench_function("v0/1000-points/paper-models", |b| {
        b.iter(|| sweep(black_box(&scene), &spec))
    });
    group.finish();
}

criterion_group!(benches, impacts, sweeps);
criterion_main!(benches);
