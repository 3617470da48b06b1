//! The five integrated laws of a default sweep (the proposed model, Hertz–viscous and
//! Kuwabara–Kono, each of the last two with both contact-end rules) keep the tolerance promise
//! across v₀ with the events landed by glides (`ode::integrate`): `auto` at rtol 1e-6, 1e-8 and
//! 1e-10 against DOP853 at rtol 1e-13, every reported number within 100·rtol (x_max, F_max, t_c
//! relative, x_residual relative to x_max, v_out relative to v₀), over the Fig. 5 sweep's
//! v₀ = 0.01–1 m/s and beyond, at e = 0.2, 0.6 and 0.95.

use hertz_tui::model::force::{ForceModel, ImpactParams};
use hertz_tui::model::impact::{ImpactSummary, MethodChoice, SolveOptions, solve_impact};
use hertz_tui::model::ode::Method;

use crate::laws_common::{dop853, sphere};

const LAWS: [ForceModel; 5] = [
    ForceModel::Proposed,
    ForceModel::with_id("hertz-viscous"),
    ForceModel::with_id("hertz-viscous-tension"),
    ForceModel::with_id("kuwabara-kono"),
    ForceModel::with_id("kuwabara-kono-tension"),
];

/// The sweep's sphere at `v0` and `e`, with the Fig. 5 scene's plastic indentation scaled to its
/// elastic x_max (the proposed model's damping b = k·x_pl/(v₀·e) then varies with v₀).
fn scene(v0: f64, e: f64) -> ImpactParams {
    let mut p = sphere(v0, e);
    p.plastic_indentation = 0.3 * p.law.max_approach(p.mass, v0);
    p
}

/// The largest error of the five numbers, each on the scale the promise states.
fn error(s: &ImpactSummary, t: &ImpactSummary, v0: f64) -> f64 {
    let rel = |a: f64, b: f64, scale: f64| (a - b).abs() / scale;
    [
        rel(s.x_max, t.x_max, t.x_max),
        rel(s.f_max, t.f_max, t.f_max),
        rel(s.t_contact, t.t_contact, t.t_contact),
        rel(s.x_residual, t.x_residual, t.x_max),
        rel(s.v_out, t.v_out, v0),
    ]
    .into_iter()
    .fold(0.0, f64::max)
}

fn solve(model: ForceModel, p: &ImpactParams, opts: &SolveOptions) -> ImpactSummary {
    solve_impact(model, p, opts)
        .unwrap_or_else(|e| panic!("{model} at v0 {}: {e}", p.v0))
        .summary
}

#[test]
fn integrated_laws_keep_the_promise_across_v0() {
    let mut worst = 0.0f64;
    for model in LAWS {
        for v0 in [0.01, 0.03, 0.1, 0.3, 1.0, 2.0] {
            for e in [0.2, 0.6, 0.95] {
                let p = scene(v0, e);
                let truth = solve(model, &p, &dop853(1e-13));
                // The reference itself, against the other explicit pair at its own tight
                // tolerance: a landing that drifted off the event would show here first.
                let dopri5 = SolveOptions {
                    method: MethodChoice::Integrator(Method::Dopri5),
                    rtol: 1e-11,
                    ..SolveOptions::default()
                };
                let check = error(&solve(model, &p, &dopri5), &truth, v0);
                assert!(check <= 1e-9, "{model} v0 {v0} e {e}: references {check:e}");
                for rtol in [1e-6, 1e-8, 1e-10] {
                    let opts = SolveOptions {
                        rtol,
                        ..SolveOptions::default()
                    };
                    let s = solve(model, &p, &opts);
                    let err = error(&s, &truth, v0);
                    assert!(
                        err <= 100.0 * rtol,
                        "{model} v0 {v0} e {e} rtol {rtol:e}: error {err:e} ({})",
                        s.method
                    );
                    worst = worst.max(err / rtol);
                }
            }
        }
    }
    // The promise is met with room, not by a hair: measured worst 0.0 · rtol.
    eprintln!("worst {worst} rtol");
    assert!(worst > 0.0 && worst <= 100.0, "worst {worst} rtol");
}
