//! The runs `translate` prints (docs/engines.md): Drake SAP's relaxation_time against the closed
//! form of the clamped oscillator, the printed step against its own promise and against a
//! tighter tolerance, and the scripts carrying the numbers they claim. The scripts themselves are
//! run in the engines by `tests/engines`.

use std::f64::consts::PI;

use hertz_tui::model::Scene;
use hertz_tui::model::engine::run::{Claim, StepChoice};
use hertz_tui::model::engine::{self, ENGINES, EngineRun};

use crate::laws_common::preset as scene;

fn with(mut scene: Scene, v0: f64, e: f64) -> Scene {
    scene.impact.v0 = v0;
    scene.impact.restitution = e;
    scene
}

fn scenes() -> Vec<Scene> {
    let fig5 = scene("fig5-steel-sphere-r10-plate");
    vec![
        fig5.clone(),
        with(fig5.clone(), 0.3, 0.3),
        with(fig5, 0.3, 0.95),
        with(scene("aluminium-sphere-r10-plate"), 1.0, 0.7),
        with(scene("steel-sphere-r10-plate"), 0.03, 0.8),
    ]
}

fn run(id: &str, scene: &Scene, tolerance: f64) -> EngineRun {
    engine::translate_run(id, scene, tolerance).unwrap_or_else(|e| panic!("{id}: {e}"))
}

fn stepped(r: &EngineRun) -> Option<&StepChoice> {
    match &r.run.claim {
        Claim::Stepped(c) => Some(c),
        _ => None,
    }
}

/// The clamped linear oscillator in closed form (ω₀ = 1): x = e^{−ζt}·sin(ω_d·t)/ω_d until
/// x + 2ζẋ = 0; e = −ẋ there (as in tests/model/engines.rs).
fn clamped_linear_e(zeta: f64) -> f64 {
    let wd = (1.0 - zeta * zeta).sqrt();
    let t = (2.0 * zeta * wd).atan2(-(1.0 - 2.0 * zeta * zeta)) / wd;
    -(-zeta * t).exp() * ((wd * t).cos() - zeta / wd * (wd * t).sin())
}

#[test]
fn drake_sap_relaxation_time_realises_e_in_closed_form() {
    for s in scenes() {
        let r = run("drake-sap", &s, 0.01);
        let value = |name: &str| {
            r.translation
                .parameters
                .iter()
                .find(|p| p.name == name)
                .map(|p| p.value)
                .unwrap_or_else(|| panic!("no {name}"))
        };
        // Two geometries: K = k/2, τ = τ₁ + τ₂; ζ = τ·ω₀/2 with ω₀ = √(K/m).
        let big_k = value("point_contact_stiffness") / 2.0;
        let tau = 2.0 * value("relaxation_time");
        let m = s.quasistatic().unwrap().reduced_mass;
        let zeta = tau * (big_k / m).sqrt() / 2.0;
        let e = clamped_linear_e(zeta);
        assert!((e - s.impact.restitution).abs() < 1e-8, "SAP e {e}");
        assert!(r.translation.law.contains("τ"));
    }
}

#[test]
fn every_printed_step_keeps_its_promise_and_the_script_prints_it() {
    // Fig. 5, a low e and a low velocity (the other scenes: tests/engines, in the engines).
    for s in scenes().into_iter().step_by(2) {
        for engine in &ENGINES {
            let r = run(engine.id, &s, 0.01);
            let claims =
                std::iter::once(&r.run.claim).chain(r.run.other_claims.iter().map(|(_, c)| c));
            for claim in claims {
                let Claim::Stepped(c) = claim else { continue };
                let e = s.impact.restitution;
                assert!(
                    (c.at_step.e_out / e - 1.0).abs() <= 0.01,
                    "{}: {c:?}",
                    engine.id
                );
                let law = &r.translation.realised;
                assert!(
                    (c.at_step.f_max / law.f_max - 1.0).abs() <= 0.01,
                    "{}",
                    engine.id
                );
                assert!(
                    (c.at_step.t_contact / law.t_contact - 1.0).abs() <= 0.01,
                    "{}",
                    engine.id
                );
                // The step is a resolution of the contact, not a stability bound.
                assert!(c.steps_per_contact >= 10.0, "{}: {c:?}", engine.id);
                if let Some(script) = &r.run.script {
                    let step = engine::shown(c.step);
                    assert!(
                        script.text.contains(&step),
                        "{}: step {step} not in the script",
                        engine.id
                    );
                }
            }
            if engine.id == "chrono" || engine.id == "adams" {
                assert!(
                    r.run.script.is_none() && r.run.checked().starts_with("not run in the engine")
                );
            } else {
                assert!(r.run.checked_in.is_some(), "{}", engine.id);
            }
        }
    }
}

#[test]
fn a_tighter_tolerance_gives_a_finer_step_that_keeps_it() {
    let s = scene("fig5-steel-sphere-r10-plate");
    for id in ["mujoco", "drake-sap", "lammps", "liggghts", "yade"] {
        let loose = run(id, &s, 0.01);
        let tight = run(id, &s, 1e-4);
        let (loose, tight) = (stepped(&loose).unwrap(), stepped(&tight).unwrap());
        assert!(
            tight.step < loose.step,
            "{id}: {} !< {}",
            tight.step,
            loose.step
        );
        assert!(
            (tight.at_step.e_out / 0.6 - 1.0).abs() <= 1e-4,
            "{id}: {tight:?}"
        );
    }
}

/// MuJoCo's step on the Fig. 5 scene at e = 0.9: the old advice, timeconst/10, is a step at which
/// hertz-tui's model of MuJoCo's stepping (checked against MuJoCo 4.0) gains energy; the printed
/// step is far finer and realises 0.9 within 1 %.
#[test]
fn mujoco_s_step_follows_the_contact_time_not_timeconst() {
    let s = with(scene("fig5-steel-sphere-r10-plate"), 0.3, 0.9);
    let r = run("mujoco", &s, 0.01);
    let timeconst = r
        .translation
        .parameters
        .iter()
        .find(|p| p.name == "timeconst")
        .map(|p| p.value)
        .unwrap();
    let c = stepped(&r).unwrap();
    assert!(c.step <= timeconst / 2.0);
    assert!(
        c.step < timeconst / 10.0 / 5.0,
        "{} against timeconst {timeconst}",
        c.step
    );
    let _ = PI;
}

#[test]
fn each_run_says_what_its_claim_rests_on_in_its_json() {
    let sphere = scene("fig5-steel-sphere-r10-plate");
    let cylinders = scene("steel-cylinders-r20-l100");
    let lammps = engine::run::lammps::CHECKED_IN;
    let drake = engine::run::drake::CHECKED_IN;
    for (id, scene, expected) in [
        (
            "lammps",
            &sphere,
            format!("run in {lammps} by hertz-tui's engine checks"),
        ),
        (
            "drake",
            &sphere,
            format!("run in {drake} by hertz-tui's engine checks (continuous and discrete)"),
        ),
        (
            "drake",
            &cylinders,
            format!("scripts are run in {drake} for spheres; not this scene"),
        ),
        (
            "chrono",
            &sphere,
            "not run in the engine: checked against the formulas of its source (named above)"
                .to_string(),
        ),
    ] {
        let r = run(id, scene, 0.01);
        assert_eq!(r.run.checked(), expected, "{id}");
        let json = serde_json::to_value(&r).unwrap();
        assert_eq!(json["run"]["checked"], expected.as_str(), "{id}");
    }
}
