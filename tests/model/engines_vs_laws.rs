//! The engine translations against hertz-tui's own law table: each engine's law is one of
//! hertz-tui's laws, so its printed input, turned into that law's damping by the row's own rule
//! (not by the engine module's map back from the calibrated damping), must realise the
//! restitution the translation promises. Two implementations of Tsuji's β-map and of the
//! Hunt–Crossley damping have to agree.

use hertz_tui::model::engine::{self, Translation};
use hertz_tui::model::force::ForceModel;
use hertz_tui::model::impact::{MethodChoice, SolveOptions, solve_impact, solve_law};
use hertz_tui::model::ode::Method;
use hertz_tui::model::presets::Registry;
use hertz_tui::model::{ImpactParams, Scene};

fn scene(name: &str, v0: f64, e: f64) -> Scene {
    let mut scene = Registry::builtin()
        .and_then(|r| r.scene(name))
        .unwrap_or_else(|e| panic!("{name}: {e}"));
    scene.impact.v0 = v0;
    scene.impact.restitution = e;
    scene
}

fn params(scene: &Scene) -> ImpactParams {
    let q = scene.quasistatic().expect("a valid scene");
    scene.impact_params(&q)
}

fn tight() -> SolveOptions {
    SolveOptions {
        method: MethodChoice::Integrator(Method::Dop853),
        rtol: 1e-12,
        ..SolveOptions::default()
    }
}

fn first_parameter(t: &Translation) -> f64 {
    t.parameters
        .first()
        .unwrap_or_else(|| panic!("{}: no parameter", t.engine))
        .value
}

/// The scenes: Fig. 5 and the Fig. 4 sphere, at three restitutions each.
fn cases() -> Vec<Scene> {
    let mut out = Vec::new();
    for (name, v0) in [
        ("fig5-steel-sphere-r10-plate", 0.3),
        ("fig4-steel-sphere-r10-plate", 0.05),
    ] {
        for e in [0.3, 0.6, 0.9] {
            out.push(scene(name, v0, e));
        }
    }
    out
}

#[test]
fn clamped_tsuji_engines_realise_the_request_through_hertz_viscous() {
    // Chrono, LIGGGHTS and Yade take a restitution input e_in that their β-map turns into γ; the
    // force is clamped at F ≥ 0. hertz-tui's `hertz-viscous` row is that law with that rule, so
    // giving it e_in must realise the requested e. Chrono prints e_in for its float storage, the
    // others to 10 digits: 1e-8 covers both.
    let law = ForceModel::with_id("hertz-viscous");
    for id in ["chrono", "liggghts", "yade"] {
        for s in cases() {
            let t = engine::translate(id, &s).unwrap_or_else(|e| panic!("{id}: {e}"));
            let e_in = first_parameter(&t);
            assert!(
                e_in < s.impact.restitution,
                "{id}: the clamp needs a lower input"
            );
            let mut p = params(&s);
            p.restitution = e_in;
            let e_out = solve_impact(law, &p, &tight()).unwrap().summary.e_out;
            assert!(
                (e_out - s.impact.restitution).abs() < 1e-8,
                "{id} e = {}: hertz-viscous with e_in = {e_in} realises {e_out}",
                s.impact.restitution
            );
        }
    }
}

#[test]
fn lammps_coeff_restitution_is_hertz_viscous_with_tension() {
    let law = ForceModel::with_id("hertz-viscous-tension");
    for s in cases() {
        let t = engine::translate("lammps", &s).unwrap();
        let e_in = first_parameter(&t);
        assert_eq!(
            e_in, s.impact.restitution,
            "the β-map is exact with tension"
        );
        let e_out = solve_impact(law, &params(&s), &tight())
            .unwrap()
            .summary
            .e_out;
        assert!((e_out - e_in).abs() < 1e-8, "{e_in} → {e_out}");
    }
}

#[test]
fn simbody_dissipation_is_the_hunt_crossley_chi_that_realises_e() {
    // Simbody: f = k·x^{3/2}·(1 + 1.5·c·ẋ), so χ = 1.5·c·v₀ in hertz-tui's Hunt–Crossley row.
    for s in cases() {
        let t = engine::translate("simbody", &s).unwrap();
        let c = t
            .parameters
            .iter()
            .find(|p| p.name == "dissipation")
            .expect("simbody prints its dissipation")
            .value;
        let p = params(&s);
        let chi = 1.5 * c * p.v0;
        let law = ForceModel::HuntCrossley.law_with_damping(&p, chi).unwrap();
        let e_out = solve_law(&law, &tight()).unwrap().summary.e_out;
        assert!(
            (e_out - s.impact.restitution).abs() < 1e-8,
            "e = {}: χ = {chi} realises {e_out}",
            s.impact.restitution
        );
    }
}
