//! Thornton's elastic–perfectly-plastic sphere (docs/physics.md §6.6) against his closed-form
//! restitution e(V), integrated at tight tolerance; e = 1 below the yield velocity.

use hertz_tui::model::force::thornton::thornton_restitution;
use hertz_tui::model::force::{ForceModel, ImpactParams};
use hertz_tui::model::impact::{SolveOptions, solve_law};

use crate::laws_common::{e_out_with, sphere};

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
fn the_default_yield_velocity_realises_the_requested_e() {
    for e in [0.2, 0.6, 0.95] {
        let p = sphere(0.3, e);
        let law = THORNTON.law(&p).unwrap();
        let v_yield = law.damping().unwrap().value;
        assert!(v_yield < p.v0);
        assert!((e_out(&p, v_yield) / e - 1.0).abs() < 1e-8, "{e}");
    }
}
