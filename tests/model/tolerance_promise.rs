//! `SolveOptions::rtol` is a promise: on every adaptive method and `auto`, x_max, F_max, t_c
//! (relative), x_residual (relative to x_max) and v_out (relative to v₀) within 100·rtol of the
//! truth, for rtol from 1e-3 to 1e-12, on seeded random scenes of every law.
//!
//! The truth is the exact solution where one exists (quadrature at 1e-15), else DOP853 at rtol
//! 1e-14 (itself within ~1e-13 by this very promise's measurements). Scenes whose end of contact
//! the model flags as ill-conditioned (`warnings::impact_warnings`) are left out here and tested
//! for the flag instead.

use hertz_tui::model::force::ForceLaw;
use hertz_tui::model::impact::{ImpactSummary, MethodChoice, SolveOptions, solve_impact};
use hertz_tui::model::ode::Method;
use hertz_tui::model::warnings::{ModelWarning, impact_warnings};
use hertz_tui::model::{ForceModel, ImpactParams, PowerLaw};

use crate::impact_paper::fig5;

const MODELS: [ForceModel; 4] = [
    ForceModel::DryFriction,
    ForceModel::Proposed,
    ForceModel::HuntCrossley,
    ForceModel::LankaraniNikravesh,
];

const CHOICES: [MethodChoice; 4] = [
    MethodChoice::Auto,
    MethodChoice::Integrator(Method::Dopri5),
    MethodChoice::Integrator(Method::Dop853),
    MethodChoice::Integrator(Method::Radau5),
];

/// SplitMix64: a seeded, dependency-free stream of uniform numbers in [0, 1).
struct Uniform(u64);

impl Uniform {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }

    fn between(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
}

/// A sphere (n = 3/2) or a cylinder-like law (1 < n < 3/2): steel-like stiffness and masses,
/// v₀ 0.01–2 m/s, e 0.2–0.99, x_pl 0 or up to half the elastic x_max.
fn scene(u: &mut Uniform) -> ImpactParams {
    let n = if u.next() < 0.6 {
        1.5
    } else {
        u.between(1.05, 1.45)
    };
    let law = PowerLaw {
        k: 10f64.powf(u.between(8.0, 10.5)),
        n,
    };
    let (mass, v0) = (
        10f64.powf(u.between(-3.0, 0.0)),
        10f64.powf(u.between(-2.0, 0.3)),
    );
    let x_e = law.max_approach(mass, v0);
    let plastic = if u.next() < 0.3 {
        0.0
    } else {
        u.between(0.02, 0.5) * x_e
    };
    ImpactParams {
        mass,
        law,
        v0,
        restitution: u.between(0.2, 0.99),
        plastic_indentation: plastic,
        contact: hertz_tui::model::force::Contact::Unspecified,
    }
}

fn truth(model: ForceModel, p: &ImpactParams) -> ImpactSummary {
    let tight = SolveOptions {
        method: MethodChoice::Integrator(Method::Dop853),
        rtol: 1e-14,
        ..SolveOptions::default()
    };
    let mut s = solve_impact(model, p, &tight).unwrap().summary;
    if let Some(exact) = model.law(p).unwrap().exact(1e-15).filter(|e| e.is_valid()) {
        s.x_max = exact.x_max;
        s.f_max = exact.f_max;
        s.t_contact = exact.t_contact;
        s.v_out = exact.v_out;
        s.x_residual = exact.x_residual;
    }
    s
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

#[test]
fn every_reported_number_is_within_100_rtol_on_random_scenes() {
    let mut u = Uniform(0x5eed_2026);
    let mut checked = 0;
    for _ in 0..6 {
        let p = scene(&mut u);
        for model in MODELS {
            let t = truth(model, &p);
            if !impact_warnings(&p, &t).is_empty() {
                continue;
            }
            for choice in CHOICES {
                for k in 3..=12 {
                    let rtol = 10f64.powi(-k);
                    let opts = SolveOptions {
                        method: choice,
                        rtol,
                        ..SolveOptions::default()
                    };
                    let s = solve_impact(model, &p, &opts).unwrap().summary;
                    let e = error(&s, &t, p.v0);
                    assert!(
                        e <= 100.0 * rtol,
                        "{model} {choice} rtol {rtol:e}: error {e:e} ({}) on {p:?}",
                        s.method
                    );
                    checked += 1;
                }
            }
        }
    }
    // Most scenes are well-conditioned: the skip must not empty the test.
    assert!(
        checked >= 6 * 4 * 4 * 10 * 3 / 4,
        "{checked} solves checked"
    );
}

#[test]
fn radau5_does_not_lose_accuracy_as_rtol_tightens() {
    let p = fig5(0.033);
    let t = truth(ForceModel::Proposed, &p);
    let mut last = f64::INFINITY;
    for k in [8, 10, 12] {
        let opts = SolveOptions {
            method: MethodChoice::Integrator(Method::Radau5),
            rtol: 10f64.powi(-k),
            ..SolveOptions::default()
        };
        let s = solve_impact(ForceModel::Proposed, &p, &opts)
            .unwrap()
            .summary;
        let e = error(&s, &t, p.v0);
        assert!(e < last, "rtol 1e-{k}: {e:e} after {last:e}");
        last = e;
    }
}

#[test]
fn a_grazing_end_of_the_proposed_model_is_flagged() {
    // e = 0.05 with x_pl = x_e/2: the bodies creep apart along F ≈ 0 (e_out ≈ 0.01).
    let fig5 = fig5(0.033);
    let x_e = fig5.law.max_approach(fig5.mass, fig5.v0);
    let p = ImpactParams {
        restitution: 0.05,
        plastic_indentation: 0.5 * x_e,
        ..fig5
    };
    let s = truth(ForceModel::Proposed, &p);
    let warnings = impact_warnings(&p, &s);
    assert!(
        matches!(warnings.as_slice(), [ModelWarning::IllConditionedEnd { condition, .. }] if *condition > 10.0),
        "{warnings:?} (e_out {})",
        s.e_out
    );
    // The Fig. 5 scene is well-conditioned.
    assert!(impact_warnings(&fig5, &truth(ForceModel::Proposed, &fig5)).is_empty());
}

#[test]
fn exit_velocity_improves_with_every_tighter_rtol_on_every_explicit_method() {
    // The end of contact is landed on with the step's full order, so v_out no longer depends on
    // where the last step happened to straddle x = 0 (it was off by 2.9e-7 at rtol 1e-10 and not
    // monotone in rtol). From rtol 1e-6 down, every two decades improve it; at 1e-4 a lucky
    // cancellation can beat 1e-6 (measured: DOPRI5 8.5e-8 at 1e-4, 1.4e-7 at 1e-6).
    let p = fig5(0.033);
    for model in [ForceModel::HuntCrossley, ForceModel::LankaraniNikravesh] {
        let t = truth(model, &p);
        for method in [Method::Dopri5, Method::Dop853] {
            let mut last = f64::INFINITY;
            for k in [6, 8, 10, 12] {
                let opts = SolveOptions {
                    method: MethodChoice::Integrator(method),
                    rtol: 10f64.powi(-k),
                    ..SolveOptions::default()
                };
                let s = solve_impact(model, &p, &opts).unwrap().summary;
                let e = (s.v_out - t.v_out).abs() / p.v0;
                assert!(
                    e <= 100.0 * opts.rtol && (e < last || e < 1e-14),
                    "{model} {method} rtol 1e-{k}: {e:e} after {last:e}"
                );
                last = e;
            }
        }
    }
}

/// Hertz–viscous close to e = 1, 1 − e from 1e-5 to 4e-4 (the rows LAMMPS, LIGGGHTS, Chrono and
/// Yade translate to): its damping γ·x^{(n−1)/2}·ẋ is tiny, and its slope singular at x = 0.
/// Integrating ẋ itself, the error estimate met x^{1/4} at first contact and DOP853 missed on
/// 632 of these 3000 solves, by up to 515·rtol at rtol 1e-10 and 2920·rtol at 1e-12; with
/// w = ẋ + β·xᵖ/m ([`ForceLaw::impulse_coefficient`]) none misses, the worst below 50·rtol on every
/// adaptive method. The truth (DOP853 at 1e-14) agrees with an independent integration (SciPy's
/// DOP853 at 1e-13 on w) to 3.5e-12 on 60 of these scenes. On 500 seeded scenes of both rows,
/// every reported number within 100·rtol at rtol 1e-8, 1e-10 and 1e-12.
#[test]
fn hertz_viscous_keeps_the_promise_close_to_e_1() {
    let rows = [
        ForceModel::with_id("hertz-viscous"),
        ForceModel::with_id("hertz-viscous-tension"),
    ];
    let mut u = Uniform(0x0e1a_5710);
    let mut failures = Vec::new();
    let mut checked = 0;
    for _ in 0..500 {
        let mut p = scene(&mut u);
        p.restitution = 1.0 - 10f64.powf(u.between(-5.0, 4e-4f64.log10()));
        p.plastic_indentation = 0.0;
        for model in rows {
            let t = truth(model, &p);
            if !impact_warnings(&p, &t).is_empty() {
                continue;
            }
            for rtol in [1e-8, 1e-10, 1e-12] {
                let opts = SolveOptions {
                    rtol,
                    ..SolveOptions::default()
                };
                let s = solve_impact(model, &p, &opts).unwrap().summary;
                let e = error(&s, &t, p.v0);
                if e > 100.0 * rtol {
                    failures.push(format!(
                        "{model} rtol {rtol:e}: error {:.0}·rtol on {p:?}",
                        e / rtol
                    ));
                }
                checked += 1;
            }
        }
    }
    assert!(checked >= 2 * 3 * 450, "{checked} solves checked");
    assert!(
        failures.is_empty(),
        "{} of {checked}:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
