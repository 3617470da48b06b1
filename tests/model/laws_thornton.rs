//! Thornton's elastic–perfectly-plastic sphere (docs/physics.md §6.6) against his closed-form
//! restitution e(V), integrated at tight tolerance; e = 1 below the yield velocity, which comes
//! from the material's yield stress and is the paper's v₀y.

use std::f64::consts::PI;

use hertz_tui::model::force::thornton::{Thornton, thornton_restitution};
use hertz_tui::model::force::{Contact, ForceModel, ImpactParams};
use hertz_tui::model::impact::{SolveOptions, solve_impact, solve_law};
use hertz_tui::model::pressure::YIELD_FACTOR;
use hertz_tui::model::{Scene, Shape};

use crate::laws_common::{dop853, e_out_with, preset, sphere};

const THORNTON: ForceModel = ForceModel::with_id("thornton");

fn e_out(p: &ImpactParams, v_yield: f64) -> f64 {
    e_out_with(THORNTON, p, v_yield, 1e-12)
}

#[test]
fn restitution_follows_thorntons_closed_form_above_yield() {
    let v_yield = 0.0316;
    for v0 in [0.04, 0.1, 0.3, 1.0, 10.0] {
        let e = e_out(&sphere(v0, 0.6), v_yield);
        let closed = thornton_restitution(v_yield / v0);
        assert!((e / closed - 1.0).abs() < 1e-8, "v₀ {v0}: {e} vs {closed}");
    }
}

#[test]
fn below_the_yield_velocity_the_impact_is_elastic() {
    for v0 in [0.001, 0.01, 0.03] {
        let law = THORNTON.law_with_damping(&sphere(v0, 0.6), 0.0316).unwrap();
        let s = solve_law(&law, &SolveOptions::default()).unwrap().summary;
        assert!((s.e_out - 1.0).abs() < 1e-7, "{v0}: {}", s.e_out);
        assert_eq!(s.x_residual, 0.0);
    }
    assert_eq!(thornton_restitution(1.0), 1.0);
    assert_eq!(thornton_restitution(2.0), 1.0);
}

#[test]
fn above_it_a_dent_stays_and_e_tends_to_1_185_q_to_the_quarter() {
    let p = sphere(0.3, 0.6);
    let law = THORNTON.law_with_damping(&p, 0.0316).unwrap();
    let s = solve_law(&law, &SolveOptions::default()).unwrap().summary;
    assert!(
        s.x_residual > 0.1 * s.x_max && s.x_residual < s.x_max,
        "{s:?}"
    );
    // e ≈ (6√3/5)^{1/2}·(1/(2√(6/5)))^{1/4}·q^{1/4} = 1.185·q^{1/4} as q → 0.
    let q: f64 = 1e-8;
    assert!((thornton_restitution(q) / (1.185 * q.powf(0.25)) - 1.0).abs() < 1e-3);
}

#[test]
fn the_yield_velocity_inverted_from_e_realises_it() {
    // What calibration uses: v_y from Thornton's e(V) at the scene's v₀.
    for e in [0.2, 0.6, 0.95] {
        let p = sphere(0.3, e);
        let v_yield = Thornton::v_yield_for_restitution(&p, e).unwrap();
        assert!(v_yield < p.v0);
        assert!((e_out(&p, v_yield) / e - 1.0).abs() < 1e-8, "{e}");
    }
}

/// `scene` at `v0`, its own e kept.
fn params_at(scene: &Scene, v0: f64) -> ImpactParams {
    crate::laws_common::params_at(scene, v0, scene.impact.restitution)
}

#[test]
fn the_yield_velocity_comes_from_the_material_and_is_the_papers_v_y() {
    for name in ["fig5-steel-sphere-r10-plate", "steel-sphere-r5-plate"] {
        let scene = preset(name);
        let q = scene.quasistatic().unwrap();
        let p = scene.impact_params(&q);
        let v_yield = THORNTON.law(&p).unwrap().damping().unwrap().value;
        // p_y = 1.1·σ_y on the maximum pressure: Thornton's V_y is the paper's yield onset v₀y.
        assert!(
            (v_yield / q.onset.v_yield - 1.0).abs() < 1e-12,
            "{name}: {v_yield} vs {:?}",
            q.onset
        );
        // And Thornton's closed form for a sphere on a rigid-massed plate, m = (4/3)πR³ρ:
        // V_y = (π²/√40)·(p_y⁵/(E*⁴ρ))^{1/2} (= 1.56·… as he prints it).
        let Shape::Sphere { radius } = scene.body1.shape else {
            panic!("{name}: body1 is the sphere");
        };
        let rho = scene.body1.material.density;
        assert!((p.mass / (4.0 / 3.0 * PI * radius.powi(3) * rho) - 1.0).abs() < 1e-12);
        let sigma_y = scene
            .body1
            .material
            .yield_stress
            .min(scene.body2.material.yield_stress);
        let p_y = YIELD_FACTOR * sigma_y;
        let e_star = 1.0
            / ((1.0 - scene.body1.material.poisson_ratio.powi(2))
                / scene.body1.material.youngs_modulus
                + (1.0 - scene.body2.material.poisson_ratio.powi(2))
                    / scene.body2.material.youngs_modulus);
        let thornton = PI * PI / 40f64.sqrt() * (p_y.powi(5) / (e_star.powi(4) * rho)).sqrt();
        assert!(
            (v_yield / thornton - 1.0).abs() < 1e-12,
            "{name}: {v_yield} vs {thornton}"
        );
    }
}

#[test]
fn restitution_from_the_material_follows_the_closed_form_over_two_decades_of_v_over_v_y() {
    // V/V_y ∈ [1, 100] on the Fig. 5 sphere, the law built from the scene alone (its e unused),
    // integrated by DOP853 at rtol 1e-12 against Thornton's e(V) to 1e-8.
    let scene = preset("fig5-steel-sphere-r10-plate");
    let p = params_at(&scene, 0.3);
    let v_yield = THORNTON.law(&p).unwrap().damping().unwrap().value;
    for ratio in [1.0, 1.001, 1.5, 3.0, 10.0, 30.0, 100.0] {
        let p = params_at(&scene, ratio * v_yield);
        let s = solve_impact(THORNTON, &p, &dop853(1e-12)).unwrap().summary;
        let closed = thornton_restitution(1.0 / ratio);
        assert!(
            (s.e_out / closed - 1.0).abs() < 1e-8,
            "V/V_y {ratio}: {} vs {closed}",
            s.e_out
        );
        // The energy balance of the integrated plastic cycle closes.
        assert!(s.energy_residual.abs() < 1e-8, "V/V_y {ratio}: {s:?}");
    }
    // The scene's e does not enter: the material decides.
    let other_e = ImpactParams {
        restitution: 0.2,
        ..params_at(&scene, 10.0 * v_yield)
    };
    let s = solve_impact(THORNTON, &other_e, &dop853(1e-12))
        .unwrap()
        .summary;
    assert!((s.e_out / thornton_restitution(0.1) - 1.0).abs() < 1e-8);
}

#[test]
fn sceneless_parameters_are_refused_by_name() {
    let sceneless = ImpactParams {
        contact: Contact::Unspecified,
        ..sphere(0.3, 0.6)
    };
    let err = THORNTON.law(&sceneless).unwrap_err().to_string();
    assert!(
        err.contains("yield stress") && err.contains("v_y explicitly"),
        "{err}"
    );
    // Given v_y, hand-built parameters are a sphere's: another n is refused by name.
    let other_n = ImpactParams {
        law: hertz_tui::model::PowerLaw {
            n: 1.2,
            ..sceneless.law
        },
        ..sceneless
    };
    let err = THORNTON
        .law_with_damping(&other_n, 0.03)
        .unwrap_err()
        .to_string();
    assert!(err.contains("n = 3/2") && err.contains("n = 1.2"), "{err}");
}
