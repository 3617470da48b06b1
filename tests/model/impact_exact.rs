//! The impact solver against exact solutions (docs/physics.md §3): adaptive methods at tight
//! tolerance to 1e-9 relative, `auto` reporting the exact numbers, and the convergence order of
//! every fixed-step method.

use hertz_tui::model::PowerLaw;
use hertz_tui::model::exact::ExactImpact;
use hertz_tui::model::force::{ForceLaw, ForceModel, ImpactParams};
use hertz_tui::model::impact::{
    ImpactSummary, MethodChoice, MethodUsed, SolveOptions, solve_impact,
};
use hertz_tui::model::ode::Method;

/// Fig. 5 of the paper (sphere): n = 1.5, m = 0.033 kg, k = 1.465e10 N/m^1.5, v₀ = 0.3 m/s.
fn sphere(restitution: f64) -> ImpactParams {
    ImpactParams {
        mass: 0.033,
        law: PowerLaw {
            k: 1.465e10,
            n: 1.5,
        },
        v0: 0.3,
        restitution,
        plastic_indentation: 2.3e-6,
        contact: hertz_tui::model::force::Contact::Unspecified,
    }
}

/// Table 2's steel cylinder on a plate: n = 1.081, k = 1.91e9 N/m^n, m = 1 kg, at 0.5 m/s.
pub(crate) fn cylinder(restitution: f64) -> ImpactParams {
    ImpactParams {
        mass: 1.0,
        law: PowerLaw {
            k: 1.91e9,
            n: 1.081,
        },
        v0: 0.5,
        restitution,
        plastic_indentation: 1e-6,
        contact: hertz_tui::model::force::Contact::Unspecified,
    }
}

fn rel(a: f64, b: f64) -> f64 {
    if b == 0.0 {
        a.abs()
    } else {
        (a / b - 1.0).abs()
    }
}

fn exact(model: ForceModel, params: &ImpactParams) -> ExactImpact {
    model.law(params).unwrap().exact(1e-15).unwrap()
}

fn solve(model: ForceModel, params: &ImpactParams, method: MethodChoice) -> ImpactSummary {
    let opts = SolveOptions {
        method,
        rtol: 1e-12,
        atol: Some(1e-14),
        ..SolveOptions::default()
    };
    solve_impact(model, params, &opts).unwrap().summary
}

/// Every headline number of `got` within `tol` (relative) of the exact impact.
fn assert_matches(got: &ImpactSummary, ex: &ExactImpact, tol: f64, what: &str) {
    let pairs = [
        ("x_max", got.x_max, ex.x_max),
        ("t_x_max", got.t_x_max, ex.t_x_max),
        ("f_max", got.f_max, ex.f_max),
        ("t_contact", got.t_contact, ex.t_contact),
        ("v_out", got.v_out, ex.v_out),
    ];
    for (name, a, b) in pairs {
        assert!(
            rel(a, b) < tol,
            "{what}: {name} = {a:e}, exact {b:e} ({:.2e})",
            rel(a, b)
        );
    }
    // The residual approach is ~1e-8 of x_max for dry friction: compare on the scale of x_max.
    assert!(
        (got.x_residual - ex.x_residual).abs() < tol * ex.x_max,
        "{what}: x_residual {:e} vs {:e}",
        got.x_residual,
        ex.x_residual
    );
    assert_eq!(
        got.tensile_cutoff.is_some(),
        ex.tensile_cutoff,
        "{what}: cutoff"
    );
}

#[test]
fn adaptive_methods_match_every_exact_solution_to_1e9() {
    // Elastic (x_max, F_max, t_c), HC and LN (x_max, v_out), dry friction (x_max, e_out), and all
    // the other numbers too, for spheres and cylinders, at two restitutions.
    let models = [
        ForceModel::Quasistatic,
        ForceModel::HuntCrossley,
        ForceModel::LankaraniNikravesh,
        ForceModel::DryFriction,
    ];
    for params in [sphere(0.6), sphere(0.9), cylinder(0.3), cylinder(0.8)] {
        for model in models {
            let ex = exact(model, &params);
            for method in [Method::Dopri5, Method::Dop853] {
                let got = solve(model, &params, MethodChoice::Integrator(method));
                let what = format!(
                    "{model} {method} n = {} e = {}",
                    params.law.n, params.restitution
                );
                assert_matches(&got, &ex, 1e-9, &what);
                assert!(rel(got.e_out, ex.v_out / params.v0) < 1e-9, "{what}: e_out");
                assert!(
                    got.energy_residual < 1e-9,
                    "{what}: {}",
                    got.energy_residual
                );
            }
        }
    }
}

#[test]
fn elastic_impact_matches_eqs_5_to_7() {
    let params = sphere(1.0);
    let (m, v0, law) = (params.mass, params.v0, params.law);
    let got = solve(
        ForceModel::Quasistatic,
        &params,
        MethodChoice::Integrator(Method::Dop853),
    );
    // eq 5, eq 6, eq 7 with its exact constant (4/5)·B(2/5, 1/2); and the realized e_out = 1.
    let x_max = (5.0 * m * v0 * v0 / (4.0 * law.k)).powf(0.4);
    let f_max = law.k.powf(0.4) * (5.0 * m * v0 * v0 / 4.0).powf(0.6);
    let t_c = 2.943_275_184_324_704_7 * (5.0 * m / (4.0 * law.k)).powf(0.4) * v0.powf(-0.2);
    assert!(rel(got.x_max, x_max) < 1e-9);
    assert!(rel(got.f_max, f_max) < 1e-9);
    assert!(rel(got.t_contact, t_c) < 1e-9);
    assert!(rel(got.e_out, 1.0) < 1e-9);
    assert!(
        rel(got.t_f_max, 0.5 * t_c) < 1e-9,
        "the peak is at half time"
    );
    assert_eq!(got.x_residual, 0.0);
    assert!(got.energy_dissipated.abs() < 1e-9 * 0.5 * m * v0 * v0);
}

#[test]
fn auto_reports_the_exact_solution_where_one_exists() {
    for params in [sphere(0.6), cylinder(0.3)] {
        for model in [
            ForceModel::Quasistatic,
            ForceModel::HuntCrossley,
            ForceModel::LankaraniNikravesh,
            ForceModel::DryFriction,
        ] {
            let opts = SolveOptions {
                rtol: 1e-12,
                atol: Some(1e-14),
                ..SolveOptions::default()
            };
            let sol = solve_impact(model, &params, &opts).unwrap();
            let got = &sol.summary;
            assert_eq!(got.method, MethodUsed::Exact, "{model}");
            let ex = exact(model, &params);
            // The quadratures of `auto` aim at 1e-14 here (rtol/100): the same numbers.
            assert_matches(got, &ex, 1e-12, &format!("auto {model}"));
            // No integration was needed for the numbers.
            assert_eq!(
                (got.steps, got.force_evals, got.energy_residual),
                (0, 0, 0.0)
            );
            // The curves, integrated when first sampled, pass through the exact extrema.
            let traj = &sol.trajectory;
            let at_x_max = traj.at(ex.t_x_max);
            assert!(rel(at_x_max.x, ex.x_max) < 1e-9, "{model}: {}", at_x_max.x);
            assert!(at_x_max.v.abs() < 1e-9 * params.v0);
            let at_peak = traj.at(ex.t_f_max);
            assert!(rel(at_peak.f, ex.f_max) < 1e-9, "{model}: {}", at_peak.f);
            let end = traj.at(ex.t_contact);
            assert!(rel(-end.v, ex.v_out) < 1e-9, "{model}: {}", end.v);
        }
        // The proposed model has no closed form: the adaptive integrator (DOP853 at rtol 1e-12,
        // DOPRI5 at 1e-6, the cheaper one for each).
        let proposed = solve(ForceModel::Proposed, &params, MethodChoice::Auto);
        assert_eq!(proposed.method, MethodUsed::Integrator(Method::Dop853));
        let loose = SolveOptions {
            rtol: 1e-6,
            ..SolveOptions::default()
        };
        let proposed = solve_impact(ForceModel::Proposed, &params, &loose).unwrap();
        assert_eq!(
            proposed.summary.method,
            MethodUsed::Integrator(Method::Dopri5)
        );
    }
}

#[test]
fn proposed_model_without_plastic_indentation_is_the_exact_elastic_impact() {
    let params = ImpactParams {
        plastic_indentation: 0.0,
        ..sphere(0.6)
    };
    let got = solve(ForceModel::Proposed, &params, MethodChoice::Auto);
    assert_eq!(got.method, MethodUsed::Exact);
    let ex = exact(ForceModel::Quasistatic, &params);
    assert_matches(&got, &ex, 1e-14, "proposed, x_pl = 0");
    // And integrated, it ends at x = 0 with v_out = v₀.
    let dopri = solve(
        ForceModel::Proposed,
        &params,
        MethodChoice::Integrator(Method::Dopri5),
    );
    assert_matches(&dopri, &ex, 1e-9, "proposed dopri5, x_pl = 0");
}

/// Velocity at t = t_c/4 from the trajectory, relative error against the exact elastic velocity
/// there (t(x) by the incomplete beta function, docs/physics.md §3, inverted by bisection).
fn velocity_error_at_quarter_time(method: Method, params: &ImpactParams, steps: f64) -> f64 {
    let (m, v0, law) = (params.mass, params.v0, params.law);
    let t_c = law.contact_time(m, v0);
    let opts = SolveOptions {
        method: MethodChoice::Integrator(method),
        dt: Some(t_c / steps),
        ..SolveOptions::default()
    };
    let sol = solve_impact(ForceModel::Quasistatic, params, &opts).unwrap();
    let t = 0.25 * t_c;
    let (mut lo, mut hi) = (0.0, law.max_approach(m, v0));
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if law.loading_time_at(m, v0, mid) < t {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let v_exact = law.loading_velocity_at(m, v0, 0.5 * (lo + hi));
    rel(sol.trajectory.at(t).v, v_exact)
}

/// Error ratios when the step halves, at t_c/200 → t_c/400 → t_c/800 (t_c/4 stays on a step point).
fn order_ratios(method: Method, params: &ImpactParams) -> Vec<f64> {
    let errors: Vec<f64> = [200.0, 400.0, 800.0]
        .iter()
        .map(|&k| velocity_error_at_quarter_time(method, params, k))
        .collect();
    errors.windows(2).map(|w| w[0] / w[1]).collect()
}

#[test]
fn fixed_step_methods_converge_at_their_order() {
    // Error ratio 2^p when dt halves. F ∝ x^n makes the solution only C^(n+1) at first contact
    // (v = v₀ − c·t^(n+1)): the first step's quadrature of t^n errs by O(h^(n+1)), so the observed
    // order is min(p, n + 1). RK4 thus shows 2^2.5 = 5.66 on a sphere, 2^2.25 = 4.76 at n = 1.25,
    // and its full 2^4 = 16 on a linear spring; the others are below the limit.
    let linear = ImpactParams {
        law: PowerLaw {
            k: 1.465e10,
            n: 1.0,
        },
        ..sphere(1.0)
    };
    let mid = ImpactParams {
        law: PowerLaw {
            k: 1.465e10,
            n: 1.25,
        },
        ..sphere(1.0)
    };
    let cases = [
        (Method::Euler, sphere(1.0), 2.0),
        (Method::SymplecticEuler, sphere(1.0), 2.0),
        (Method::Verlet, sphere(1.0), 4.0),
        (Method::Rk4, sphere(1.0), 2f64.powf(2.5)),
        (Method::Rk4, mid, 2f64.powf(2.25)),
        (Method::Rk4, linear, 16.0),
        (Method::Euler, linear, 2.0),
        (Method::Verlet, linear, 4.0),
    ];
    for (method, params, expect) in cases {
        for ratio in order_ratios(method, &params) {
            assert!(
                (ratio / expect - 1.0).abs() < 0.08,
                "{method} n = {}: ratio {ratio:.3}, expected {expect:.3}",
                params.law.n
            );
        }
    }
}

#[test]
fn fixed_step_event_location_keeps_the_contact_time_at_the_method_order() {
    // The end of contact is located on the step's Hermite interpolant, not at the step after it:
    // the contact time then converges too (RK4 at order n + 1 = 2.5 on a sphere) instead of
    // stalling at O(dt).
    let params = sphere(1.0);
    let t_c = params.law.contact_time(params.mass, params.v0);
    let err = |k: f64| {
        let opts = SolveOptions {
            method: MethodChoice::Integrator(Method::Rk4),
            dt: Some(t_c / k),
            ..SolveOptions::default()
        };
        rel(
            solve_impact(ForceModel::Quasistatic, &params, &opts)
                .unwrap()
                .summary
                .t_contact,
            t_c,
        )
    };
    let (e1, e2) = (err(301.0), err(602.0));
    assert!(e2 < 1e-8, "{e2}");
    assert!(e1 / e2 > 4.0, "ratio {}", e1 / e2);
}
