//! Property tests for the laws that need the bodies (Thornton's, on spheres and cylinders, and
//! the exact line-contact law): random scenes built from the presets with their radius, length,
//! yield stress, mass and v₀ varied, every method and tolerance. Each solve terminates with
//! finite results and a residual below its tolerance, or a typed error; `auto` on Thornton
//! always succeeds, its rebound is the law's own e(q, n) (docs/physics.md §6.6), and calibrated
//! it realises the requested e.

use hertz_tui::model::calibrate::calibrate;
use hertz_tui::model::force::thornton::Thornton;
use hertz_tui::model::force::{ForceModel, ImpactParams};
use hertz_tui::model::impact::{MethodChoice, SolveOptions, solve_impact, solve_law};
use hertz_tui::model::ode::Method;
use hertz_tui::model::presets::Registry;
use hertz_tui::model::{Scene, Shape};
use proptest::prelude::*;

use crate::impact_props::{any_method, check, solve_and_check};

const PRESETS: [&str; 3] = [
    "fig5-steel-sphere-r10-plate",
    "steel-cylinder-r20-l100-plate",
    "steel-cylinders-r20-l100",
];

/// A preset with its sizes scaled by 10^[−1, 1], its yield stress set to 10^[8, 9.5] Pa, its
/// mass scaled by 10^[−1, 1] and v₀ = 10^[−3, 1] m/s; `None` where the scene is out of its
/// formulas' domain (a cylinder's eq 13/14 at that force), which the scene itself reports.
fn scene_params(
    preset: &str,
    size: f64,
    log_sigma: f64,
    mass: f64,
    log_v0: f64,
) -> Option<ImpactParams> {
    let mut scene: Scene = Registry::builtin().ok()?.scene(preset).ok()?;
    for body in [&mut scene.body1, &mut scene.body2] {
        body.shape = match body.shape {
            Shape::Sphere { radius } => Shape::Sphere {
                radius: radius * size,
            },
            Shape::Cylinder { radius, length } => Shape::Cylinder {
                radius: radius * size,
                length: length * size,
            },
            Shape::Plane => Shape::Plane,
        };
        body.material.yield_stress = 10f64.powf(log_sigma);
        body.mass = body.mass.map(|m| m * mass);
    }
    scene.impact.v0 = 10f64.powf(log_v0);
    let quasistatic = scene.quasistatic().ok()?;
    Some(scene.impact_params(&quasistatic))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    #[test]
    fn laws_that_need_the_bodies_terminate_with_finite_results_or_a_typed_error(
        preset in prop::sample::select(PRESETS.to_vec()),
        size in -1.0..1.0f64,
        log_sigma in 8.0..9.5f64,
        mass in -1.0..1.0f64,
        log_v0 in -3.0..1.0f64,
        model in prop::sample::select(vec!["thornton", "hertz-line-exact"]),
        method in any_method(),
        log_rtol in -12.0..-4.0f64,
    ) {
        let p = scene_params(preset, 10f64.powf(size), log_sigma, 10f64.powf(mass), log_v0);
        prop_assume!(p.is_some());
        let p = p.unwrap();
        solve_and_check(ForceModel::with_id(model), &p, method, log_rtol);
    }

    #[test]
    fn thornton_on_auto_is_exact_and_agrees_with_dop853(
        preset in prop::sample::select(PRESETS.to_vec()),
        size in -1.0..1.0f64,
        log_sigma in 8.0..9.5f64,
        mass in -1.0..1.0f64,
        log_v0 in -3.0..1.0f64,
    ) {
        let p = scene_params(preset, 10f64.powf(size), log_sigma, 10f64.powf(mass), log_v0);
        prop_assume!(p.is_some());
        let p = p.unwrap();
        let model = ForceModel::with_id("thornton");
        let opts = SolveOptions::default();
        let solution = solve_impact(model, &p, &opts);
        prop_assert!(solution.is_ok(), "{p:?}: {:?}", solution.as_ref().err());
        let solution = solution.unwrap();
        let s = &solution.summary;
        prop_assert_eq!(s.method.to_string(), "exact");
        // An independent integration at rtol 1e-11: every number within 100·1e-11 of it, plus
        // the exact path's own 100·rtol (the default rtol 1e-8).
        let tight = SolveOptions {
            method: MethodChoice::Integrator(Method::Dop853),
            rtol: 1e-11,
            ..SolveOptions::default()
        };
        let num = solve_impact(model, &p, &tight);
        prop_assert!(num.is_ok(), "{p:?}: {:?}", num.as_ref().err());
        let num = num.unwrap().summary;
        let bound = 100.0 * opts.rtol + 1e-9;
        for (what, a, b) in [
            ("x_max", s.x_max, num.x_max),
            ("f_max", s.f_max, num.f_max),
            ("t_contact", s.t_contact, num.t_contact),
        ] {
            prop_assert!((a / b - 1.0).abs() < bound, "{p:?} {what}: exact {a} vs {b}");
        }
        prop_assert!((s.v_out - num.v_out).abs() < bound * p.v0, "{p:?}: {s:?} {num:?}");
        let expected = Thornton::restitution_of(&p, model.law(&p).unwrap().damping().unwrap().value);
        prop_assert!((s.e_out - expected).abs() < 1e-12, "{p:?}: {} vs {expected}", s.e_out);
        check(model, &p, &opts, Ok(solution));
    }

    #[test]
    fn thornton_calibrates_to_the_requested_e_on_random_bodies(
        preset in prop::sample::select(PRESETS.to_vec()),
        size in -1.0..1.0f64,
        log_sigma in 8.0..9.5f64,
        mass in -1.0..1.0f64,
        log_v0 in -3.0..1.0f64,
        e in 0.01..0.99f64,
    ) {
        let p = scene_params(preset, 10f64.powf(size), log_sigma, 10f64.powf(mass), log_v0);
        prop_assume!(p.is_some());
        let p = ImpactParams { restitution: e, ..p.unwrap() };
        let model = ForceModel::with_id("thornton");
        let c = calibrate(model, &p);
        prop_assert!(c.is_ok(), "{p:?}: {:?}", c.as_ref().err());
        let c = c.unwrap();
        prop_assert!((c.e_out / e - 1.0).abs() < 1e-10, "{p:?}: {} vs {e}", c.e_out);
        // An independent integration of the calibrated law: v_out within 100·rtol·v₀.
        let opts = SolveOptions {
            method: MethodChoice::Integrator(Method::Dop853),
            rtol: 1e-10,
            ..SolveOptions::default()
        };
        let s = solve_law(&c.law, &opts);
        prop_assert!(s.is_ok(), "{p:?}: {:?}", s.as_ref().err());
        let e_out = s.unwrap().summary.e_out;
        prop_assert!((e_out - e).abs() < 1e-8, "{p:?}: DOP853 {e_out} vs {e}");
    }
}
