//! Fixtures of the model tests: the built-in scenes, their impact parameters at any v₀ and e, the
//! Fig. 5 sphere at any v₀ and e, and a tight DOP853 solve.

use hertz_tui::model::PowerLaw;
use hertz_tui::model::Scene;
use hertz_tui::model::force::{Contact, ForceModel, ImpactParams, PointContact};
use hertz_tui::model::impact::{MethodChoice, SolveOptions, solve_law};
use hertz_tui::model::ode::Method;
use hertz_tui::model::presets::Registry;

/// Fig. 5's steel sphere (R = 10 mm) on a steel plate as the laws that need the bodies see it:
/// p_y = 1.1·σ_y with σ_y = 780 MPa, E* = 1/η with η = 9.1e-12 m²/N (Table 1).
pub fn fig5_contact() -> Contact {
    Contact::Point(PointContact {
        yield_pressure: 1.1 * 780e6,
        modulus: 1.0 / 9.1e-12,
        radius: 0.01,
    })
}

/// Fig. 5's steel sphere on a plate (m = 0.033 kg, k = 1.465e10 N/m^1.5) at `v0` and `restitution`.
pub fn sphere(v0: f64, restitution: f64) -> ImpactParams {
    ImpactParams {
        mass: 0.033,
        law: PowerLaw {
            k: 1.465e10,
            n: 1.5,
        },
        v0,
        restitution,
        plastic_indentation: 0.0,
        contact: fig5_contact(),
    }
}

/// DOP853 at `rtol` (atol a hundredth of it): the independent integration of these tests.
pub fn dop853(rtol: f64) -> SolveOptions {
    SolveOptions {
        method: MethodChoice::Integrator(Method::Dop853),
        rtol,
        atol: Some(rtol * 1e-2),
        ..SolveOptions::default()
    }
}

/// The realised e of `model` with its damping parameter set to `damping`, by DOP853 at `rtol`.
pub fn e_out_with(model: ForceModel, p: &ImpactParams, damping: f64, rtol: f64) -> f64 {
    let law = model.law_with_damping(p, damping).unwrap();
    solve_law(&law, &dop853(rtol)).unwrap().summary.e_out
}

/// A built-in scene by name.
pub fn preset(name: &str) -> Scene {
    Registry::builtin()
        .and_then(|r| r.scene(name))
        .unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// `scene`'s impact parameters at `v0` and restitution `e` (a cylinder's fit is redone for v₀).
pub fn params_at(scene: &Scene, v0: f64, e: f64) -> ImpactParams {
    let mut scene = scene.clone();
    scene.impact.v0 = v0;
    scene.impact.restitution = e;
    scene.impact_params(&scene.quasistatic().unwrap())
}
