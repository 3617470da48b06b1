//! Dry friction's compressive-only cutoff at high restitution: the unloading force k·xⁿ − P·x turns
//! tensile at x* = (P/k)^{1/(n−1)}, a few nm above x = 0 when e ≥ 0.985. Every adaptive method must
//! end contact there (located as an event on x − x*), not coast on to x = 0.

use hertz_tui::model::force::ForceLaw;
use hertz_tui::model::impact::{MethodChoice, SolveOptions, solve_impact};
use hertz_tui::model::ode::Method;
use hertz_tui::model::{ForceModel, ImpactParams, PowerLaw};

/// The Fig. 4 scene (steel sphere R = 10 mm on a steel plate, v₀ = 0.03 m/s) at restitution e.
fn fig4(restitution: f64) -> ImpactParams {
    ImpactParams {
        mass: 0.032_672_563_597_333_85,
        law: PowerLaw {
            k: 14_652_014_652.014_652,
            n: 1.5,
        },
        v0: 0.03,
        restitution,
        plastic_indentation: 0.0,
        contact: hertz_tui::model::force::Contact::Unspecified,
    }
}

#[test]
fn the_cutoff_is_found_at_high_restitution_on_every_adaptive_method() {
    for e in [0.985, 0.99, 0.995] {
        let p = fig4(e);
        let exact = ForceModel::DryFriction
            .law(&p)
            .unwrap()
            .exact(1e-15)
            .unwrap();
        assert!(exact.tensile_cutoff && exact.x_residual > 0.0, "e = {e}");
        for method in [Method::Dopri5, Method::Dop853, Method::Radau5] {
            for rtol in [1e-5, 1e-8, 1e-12] {
                let opts = SolveOptions {
                    method: MethodChoice::Integrator(method),
                    rtol,
                    ..SolveOptions::default()
                };
                let s = solve_impact(ForceModel::DryFriction, &p, &opts)
                    .unwrap()
                    .summary;
                let cut = s.tensile_cutoff.unwrap_or_else(|| {
                    panic!(
                        "e = {e}, {method} rtol {rtol:e}: no cutoff, x_residual {}",
                        s.x_residual
                    )
                });
                assert_eq!(cut.x, s.x_residual);
                let x_error = (s.x_residual - exact.x_residual).abs() / exact.x_max;
                let t_error = (s.t_contact / exact.t_contact - 1.0).abs();
                assert!(
                    x_error <= 100.0 * rtol && t_error <= 100.0 * rtol,
                    "e = {e}, {method} rtol {rtol:e}: x_residual off by {x_error:e}, t_c by {t_error:e}"
                );
            }
        }
    }
}
