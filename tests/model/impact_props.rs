//! Property tests: for random valid scenes (spheres and cylinders, n in [1, 1.5], v₀ from 1e-4 to
//! 10 m/s, e from 0.05 to 1) every model's solve terminates with finite results and an energy
//! residual below its tolerance, or with a typed error — never a panic, a hang or a NaN.

use hertz_tui::model::PowerLaw;
use hertz_tui::model::force::{ForceModel, ImpactParams};
use hertz_tui::model::impact::{
    ImpactError, ImpactSolution, MethodChoice, MethodUsed, SolveOptions, solve_impact,
};
use hertz_tui::model::ode::Method;
use proptest::prelude::*;

/// A scene: a sphere (n = 3/2) or a cylinder-like power law (n in [1, 1.5]); stiffness and mass
/// spanning steel balls to heavy rollers; x_pl from 0 to 1.5 elastic x_max.
fn scene() -> impl Strategy<Value = ImpactParams> {
    (
        prop_oneof![Just(1.5), 1.0..1.5f64],
        8.0..11.0f64,
        -3.0..1.0f64,
        -4.0..1.0f64,
        0.05..=1.0f64,
        prop_oneof![Just(0.0), 0.0..1.5f64],
    )
        .prop_map(|(n, log_k, log_m, log_v0, e, pl)| {
            let law = PowerLaw {
                k: 10f64.powf(log_k),
                n,
            };
            let (mass, v0) = (10f64.powf(log_m), 10f64.powf(log_v0));
            ImpactParams {
                mass,
                law,
                v0,
                restitution: e,
                plastic_indentation: pl * law.max_approach(mass, v0),
                contact: hertz_tui::model::force::Contact::Unspecified,
            }
        })
}

fn any_model() -> impl Strategy<Value = ForceModel> {
    prop::sample::select(ForceModel::ALL.to_vec())
}

pub fn any_method() -> impl Strategy<Value = MethodChoice> {
    prop_oneof![
        3 => Just(MethodChoice::Auto),
        1 => prop::sample::select(Method::ALL.to_vec()).prop_map(MethodChoice::Integrator),
    ]
}

/// The energy residual an adaptive solve must meet (fraction of ½mv₀²): a multiple of rtol — the
/// global error is a problem-dependent multiple of the local tolerance, up to ~300 on scenes
/// whose force all but jumps at first contact (n → 1 with strong damping), so 1000. `None` for
/// fixed-step methods, whose residual is instead required to shrink with the step.
fn energy_tolerance(method: MethodUsed, rtol: f64) -> Option<f64> {
    match method {
        MethodUsed::Exact => Some(0.0),
        // A quadrature on the dense output, an order below the steps: up to ~1.1e3·rtol measured
        // on long DOP853 steps (see a_long_step_residual_is_the_dense_outputs_not_the_solutions).
        MethodUsed::Integrator(Method::Dopri5) => Some(1000.0 * rtol),
        MethodUsed::Integrator(Method::Dop853 | Method::Radau5) => Some(3000.0 * rtol),
        MethodUsed::Integrator(_) => None,
    }
}

/// Whether the default fixed step t_c/1000 resolves the proposed model's damping: its scaled
/// eigenvalue (n+1)/2·x_pl/(e·x_e) times the step stays below 0.05 (other laws' damping is
/// bounded by the elastic frequency).
fn resolved(model: ForceModel, p: &ImpactParams) -> bool {
    if model != ForceModel::Proposed {
        return true;
    }
    let x_e = p.law.max_approach(p.mass, p.v0);
    let lambda = 0.5 * (p.law.n + 1.0) * p.plastic_indentation / (p.restitution * x_e);
    let dt = p.law.contact_time(p.mass, p.v0) / 1000.0 * p.v0 / x_e;
    lambda * dt < 0.05
}

/// Solves `p` with `model` by `method` at rtol = atol = 10^`log_rtol` and [`check`]s the outcome.
pub fn solve_and_check(model: ForceModel, p: &ImpactParams, method: MethodChoice, log_rtol: f64) {
    let opts = SolveOptions {
        method,
        rtol: 10f64.powf(log_rtol),
        atol: Some(10f64.powf(log_rtol)),
        ..SolveOptions::default()
    };
    check(model, p, &opts, solve_impact(model, p, &opts));
}

pub fn check(
    model: ForceModel,
    p: &ImpactParams,
    opts: &SolveOptions,
    result: Result<ImpactSolution, ImpactError>,
) {
    let sol = match result {
        Ok(sol) => sol,
        // A typed failure is a valid outcome; its message must say something.
        Err(e) => {
            assert!(!e.to_string().is_empty());
            return;
        }
    };
    let s = &sol.summary;
    let numbers = [
        s.x_max,
        s.t_x_max,
        s.f_max,
        s.t_f_max,
        s.t_contact,
        s.v_out,
        s.e_out,
        s.x_residual,
        s.energy_dissipated,
        s.energy_residual,
    ];
    assert!(numbers.iter().all(|q| q.is_finite()), "{model}: {s:?}");
    assert!(
        s.x_max > 0.0 && s.f_max > 0.0 && s.t_contact > 0.0,
        "{model}: {s:?}"
    );
    assert!(
        s.t_x_max <= s.t_contact && s.t_f_max <= s.t_contact,
        "{model}: {s:?}"
    );
    assert!(
        s.v_out >= 0.0 && s.x_residual >= 0.0 && s.x_residual <= s.x_max,
        "{model}: {s:?}"
    );
    match energy_tolerance(s.method, opts.rtol) {
        Some(tol) => assert!(
            s.energy_residual <= tol,
            "{model} {}: residual {:e} > {tol:e}",
            s.method,
            s.energy_residual
        ),
        None if resolved(model, p) && s.energy_residual > 1e-6 => {
            // A fixed step: the residual must shrink when the step is cut by 16 (above 1e-6,
            // where the first step's O(h^(n+1)) error and the quadrature no longer blur its
            // trend: symplectic Euler on Gharib–Hurmuzlu went 1.7e-7 → 9.1e-8 only), by 2.25 (an
            // order ≥ 0.3). Four halvings, not one: where a damping term in a fractional power
            // of x stays on to x = 0 (Hertz–viscous and Kuwabara–Kono with tension) the last
            // step's error depends on where it falls against that singularity, so single
            // halvings gain erratically (RK4: 1.53e-6, 1.39e-6, 1.15e-6, 8.6e-8, 7.2e-8 from dt
            // to dt/16). Kuwabara–Kono's xⁿ⁻¹·ẋ with tension is the worst: at n = 1.18 the
            // damping is nearly a step at x = 0 and RK4 gains only 2.1 over dt/16, so it must
            // merely shrink.
            let gain = if model.name() == "kuwabara-kono-tension" {
                1.0
            } else {
                2.25
            };
            let dt = opts.dt.unwrap_or(p.law.contact_time(p.mass, p.v0) / 1000.0);
            let finer = SolveOptions {
                dt: Some(dt / 16.0),
                ..*opts
            };
            if let Ok(finer) = solve_impact(model, p, &finer) {
                assert!(
                    finer.summary.energy_residual < s.energy_residual / gain,
                    "{model} {}: residual {:e} at dt, {:e} at dt/16",
                    s.method,
                    s.energy_residual,
                    finer.summary.energy_residual
                );
            }
        }
        None => {}
    }
    if s.method != MethodUsed::Integrator(Method::Euler) {
        // Every law dissipates or conserves: only explicit Euler may gain energy beyond rounding.
        assert!(
            s.e_out <= 1.0 + 1e-3,
            "{model} {}: e_out {}",
            s.method,
            s.e_out
        );
    }
    if let Some(cut) = s.tensile_cutoff {
        assert!(cut.x > 0.0 && cut.v <= 0.0 && cut.t == s.t_contact);
    }
    // The curves: finite everywhere, starting at first contact, passing through the extrema.
    let samples = sol.trajectory.samples(33);
    assert!(samples.len() >= 33);
    assert!(samples.windows(2).all(|w| w[0].t <= w[1].t));
    assert!(
        samples
            .iter()
            .all(|q| q.t.is_finite() && q.x.is_finite() && q.v.is_finite() && q.f.is_finite())
    );
    assert_eq!(samples[0].t, 0.0);
    assert!((samples[0].v / p.v0 - 1.0).abs() < 1e-9);
    let peak = samples.iter().map(|q| q.f).fold(f64::MIN, f64::max);
    // The peak is located to ~√ε in t, so an even sample may land nearer it by ~1e-14; an exact
    // solution's curves are integrated for the chart at rtol min(rtol, 1e-10), so their samples
    // may pass its closed-form peak by the 100·rtol that promises (6.8e-12 on Kelvin–Voigt with
    // tension; 1.2e-10 on Thornton's strip far above v_y, a 40-step plastic loading).
    let sampled = if s.method == MethodUsed::Exact {
        100.0 * opts.rtol.clamp(1e-14, 1e-10)
    } else {
        1e-12
    };
    assert!(
        (peak - s.f_max).abs() <= sampled * s.f_max,
        "{model}: the chart's peak {peak} is the summary's {}",
        s.f_max
    );
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    #[test]
    fn every_model_terminates_with_finite_results_or_a_typed_error(
        p in scene(),
        model in any_model(),
        method in any_method(),
        log_rtol in -12.0..-4.0f64,
    ) {
        solve_and_check(model, &p, method, log_rtol);
    }

    #[test]
    fn auto_always_succeeds_on_valid_scenes(p in scene(), model in any_model()) {
        // Thornton's law takes its yield velocity from the bodies' yield stress, and the exact
        // contact law its equations from their shapes, which parameters built without a scene
        // lack: both refuse them by design (tests/model/laws_thornton.rs, laws_line_exact.rs).
        prop_assume!(!["thornton", "hertz-line-exact"].contains(&model.name()));
        let opts = SolveOptions::default();
        let result = solve_impact(model, &p, &opts);
        // A law allowed to pull and damped beyond critical never lets go (docs/physics.md §6.4):
        // Kuwabara–Kono's A from a low e by the series' first term can be that far outside the
        // series (its clamped row ends at F = 0 instead and always separates).
        // Kelvin–Voigt and Hertz–viscous with tension stay below critical for every e > 0 and
        // must always separate.
        let overdampable = model.name() == "kuwabara-kono-tension";
        if overdampable && matches!(result, Err(ImpactError::NoSeparation { .. })) {
            return Ok(());
        }
        prop_assert!(result.is_ok(), "{model}: {:?}", result.as_ref().err());
        check(model, &p, &opts, result);
    }
}

#[test]
fn extreme_but_valid_scenes_do_not_break_the_solver() {
    // Corners of the property ranges, and beyond them where inputs are still valid.
    let base = ImpactParams {
        mass: 0.033,
        law: PowerLaw {
            k: 1.465e10,
            n: 1.5,
        },
        v0: 0.3,
        restitution: 0.6,
        plastic_indentation: 2.3e-6,
        contact: hertz_tui::model::force::Contact::Unspecified,
    };
    let scenes = [
        ImpactParams { v0: 1e-6, ..base },
        ImpactParams { v0: 300.0, ..base },
        ImpactParams {
            restitution: 1e-3,
            ..base
        },
        ImpactParams {
            restitution: 1.0,
            ..base
        },
        ImpactParams {
            plastic_indentation: 1e-3,
            ..base
        },
        ImpactParams {
            plastic_indentation: 1e-15,
            ..base
        },
        ImpactParams {
            law: PowerLaw { k: 1e6, n: 1.0 },
            mass: 100.0,
            ..base
        },
        ImpactParams {
            law: PowerLaw { k: 1e12, n: 2.5 },
            ..base
        },
    ];
    for p in scenes {
        for model in ForceModel::ALL {
            for method in [
                MethodChoice::Auto,
                MethodChoice::Integrator(Method::Dopri5),
                MethodChoice::Integrator(Method::Rk4),
            ] {
                let opts = SolveOptions {
                    method,
                    ..SolveOptions::default()
                };
                check(model, &p, &opts, solve_impact(model, &p, &opts));
            }
        }
    }
}

/// A scene proptest found: Kelvin–Voigt with tension on DOP853 at rtol 1.3e-11 takes 17 long
/// steps, and the residual — a quadrature of the dissipated power on the dense output, whose
/// interpolant is an order below the steps — reads 1.05e3·rtol while e_out itself is within
/// 0.1·rtol. The residual's bound on DOP853 (and Radau5) is 3000·rtol for that reason.
#[test]
fn a_long_step_residual_is_the_dense_outputs_not_the_solutions() {
    let p = ImpactParams {
        mass: 1.0,
        law: PowerLaw { k: 1e8, n: 1.5 },
        v0: 1.0,
        restitution: 0.9115671791864951,
        plastic_indentation: 0.0,
        contact: hertz_tui::model::force::Contact::Unspecified,
    };
    let rtol = 10f64.powf(-10.877883245213095);
    let opts = SolveOptions {
        method: MethodChoice::Integrator(Method::Dop853),
        rtol,
        atol: Some(rtol),
        ..SolveOptions::default()
    };
    let model = ForceModel::with_id("kelvin-voigt-tension");
    let s = solve_impact(model, &p, &opts).unwrap().summary;
    assert!(
        (s.e_out / p.restitution - 1.0).abs() < 100.0 * rtol,
        "{s:?}"
    );
    check(model, &p, &opts, solve_impact(model, &p, &opts));
}
