//! Performance budget of issue 5: one impact per model (auto, and DOPRI5 at rtol 1e-8),
//! a 1000-point v₀ sweep, and one full edit cycle of the explorer.
//!
//! Run with `cargo bench --bench performance` (one group: `cargo bench --bench performance -- edit`).

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
use hertz_tui::ui::MarkerStyle;
use hertz_tui::ui::action::Action;
use hertz_tui::ui::app::App;
use hertz_tui::ui::field::Nudge;
use hertz_tui::ui::render::draw;
use hertz_tui::ui::style::Theme;
use hertz_tui::ui::update::update;
use hertz_tui::ui::worker;
use ratatui::Terminal;
use ratatui::backend::TestBackend;

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

/// Solves every queued job on this thread, as the worker would: the edit cycle measures the work.
fn solve_queued(app: &mut App) -> usize {
    let jobs = app.take_jobs();
    let solved = jobs.len();
    for job in jobs {
        update(app, Action::Solved(Ok(worker::solve(&job))));
    }
    solved
}

/// The explorer on the default scene at 160×48 with the paper's five models checked (and no other),
/// their first solves done.
fn paper_models_app() -> App {
    let registry = Registry::builtin().expect("built-in presets load");
    let scene = registry
        .scene(DEFAULT_SCENE)
        .expect("default scene resolves");
    let mut app = App::new(scene, registry, MarkerStyle::Braille, Theme { color: true });
    // As the runtime does before its first frame: the curves are sampled for this screen's charts.
    update(&mut app, Action::Resize(160, 48));
    for model in ForceModel::ALL {
        if app.is_checked(model) != PAPER_MODELS.contains(&model) {
            app.focused = model;
            update(&mut app, Action::ToggleModel);
        }
    }
    app.focused = ForceModel::Proposed;
    solve_queued(&mut app);
    app
}

/// One full edit cycle of the explorer: v₀ nudged (by →/← on the v₀ field, alternately, so every
/// edit changes the inputs), the paper's five models recomputed, and every pane rendered and
/// written to a 160×48 TestBackend through ratatui's `Terminal` (as the running explorer
/// writes to the terminal), all on this thread.
fn edit_cycle(c: &mut Criterion) {
    let mut app = paper_models_app();
    let mut terminal = Terminal::new(TestBackend::new(160, 48)).expect("a test backend");
    let mut up = true;
    c.bench_function("edit/cycle/paper-models/160x48", |b| {
        b.iter(|| {
            let direction = if up { Nudge::Up } else { Nudge::Down };
            up = !up;
            update(&mut app, Action::Nudge(direction));
            let solved = solve_queued(&mut app);
            assert_eq!(
                solved,
                PAPER_MODELS.len(),
                "every checked model is recomputed"
            );
            terminal
                .draw(|frame| draw(frame, black_box(&app)))
                .expect("drawing into a test backend");
        })
    });
}

/// The two halves of the edit cycle apart: the recompute alone, and the drawing alone.
fn edit_parts(c: &mut Criterion) {
    let mut app = paper_models_app();
    let mut up = true;
    c.bench_function("edit/recompute/paper-models", |b| {
        b.iter(|| {
            let direction = if up { Nudge::Up } else { Nudge::Down };
            up = !up;
            update(&mut app, Action::Nudge(direction));
            solve_queued(&mut app)
        })
    });
    let mut terminal = Terminal::new(TestBackend::new(160, 48)).expect("a test backend");
    c.bench_function("edit/render/160x48", |b| {
        b.iter(|| {
            terminal
                .draw(|frame| draw(frame, black_box(&app)))
                .expect("drawing into a test backend");
        })
    });
}

criterion_group!(benches, impacts, sweeps, edit_cycle, edit_parts);
criterion_main!(benches);
