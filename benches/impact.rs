//! One impact per model and method: `cargo bench --bench impact`.
//!
//! The scene is the paper's Fig. 5 (steel sphere on a steel plate, v₀ = 0.3 m/s, e = 0.6,
//! x_pl = 2.3 µm). Fixed-step methods run at t_c/200, well inside their stability bounds.

use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use hertz_tui::model::PowerLaw;
use hertz_tui::model::force::{Contact, ForceModel, ImpactParams, PointContact};
use hertz_tui::model::impact::{MethodChoice, SolveOptions, solve_impact};
use hertz_tui::model::ode::Method;

fn fig5() -> ImpactParams {
    ImpactParams {
        mass: 0.033,
        law: PowerLaw {
            k: 1.465e10,
            n: 1.5,
        },
        v0: 0.3,
        restitution: 0.6,
        plastic_indentation: 2.3e-6,
        // Steel on steel (Table 1): what Thornton's yield velocity and the exact contact law need.
        contact: Contact::Point(PointContact {
            yield_pressure: 1.1 * 780e6,
            modulus: 1.0 / 9.1e-12,
            radius: 0.01,
        }),
    }
}

fn choices(t_c: f64) -> Vec<(String, SolveOptions)> {
    let adaptive = |method: Method| SolveOptions {
        method: MethodChoice::Integrator(method),
        rtol: 1e-8,
        atol: None,
        ..SolveOptions::default()
    };
    let fixed = |method: Method| SolveOptions {
        method: MethodChoice::Integrator(method),
        dt: Some(t_c / 200.0),
        ..SolveOptions::default()
    };
    vec![
        ("auto".into(), SolveOptions::default()),
        ("dopri5-1e-8".into(), adaptive(Method::Dopri5)),
        ("dop853-1e-8".into(), adaptive(Method::Dop853)),
        ("radau5-1e-8".into(), adaptive(Method::Radau5)),
        ("rk4-tc/200".into(), fixed(Method::Rk4)),
        ("verlet-tc/200".into(), fixed(Method::Verlet)),
        (
            "symplectic-euler-tc/200".into(),
            fixed(Method::SymplecticEuler),
        ),
        ("euler-tc/200".into(), fixed(Method::Euler)),
    ]
}

fn impacts(c: &mut Criterion) {
    let params = fig5();
    let t_c = params.law.contact_time(params.mass, params.v0);
    let mut group = c.benchmark_group("impact");
    group
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1))
        .sample_size(20);
    for model in ForceModel::ALL {
        for (name, opts) in choices(t_c) {
            group.bench_with_input(BenchmarkId::new(model.name(), &name), &opts, |b, opts| {
                b.iter(|| solve_impact(model, black_box(&params), opts))
            });
        }
    }
    group.finish();
}

fn five_models_auto(c: &mut Criterion) {
    // What the TUI recomputes on every keystroke (without rendering), and 64 samples of each curve.
    let params = fig5();
    let opts = SolveOptions::default();
    c.bench_function("impact/all-five-auto+samples", |b| {
        b.iter(|| {
            for model in ForceModel::ALL {
                let sol = solve_impact(model, black_box(&params), &opts);
                if let Ok(sol) = sol {
                    black_box(sol.trajectory.samples(64));
                }
            }
        })
    });
}

criterion_group!(benches, impacts, five_models_auto);
criterion_main!(benches);
