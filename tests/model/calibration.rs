//! Calibration (docs/physics.md §6.4): every law with a damping parameter hits the requested e to
//! 1e-10 relative on scenes spread over masses, stiffnesses, exponents and speeds, confirmed by an
//! independent DOP853 solve; the Hunt–Crossley family's e_out depends on χ alone.

use hertz_tui::model::PowerLaw;
use hertz_tui::model::calibrate::{
    CalibrationError, calibrate, hunt_crossley_chi, hunt_crossley_restitution,
};
use hertz_tui::model::force::{Contact, ForceModel, ImpactParams};
use hertz_tui::model::impact::{MethodChoice, SolveOptions, solve_law};
use hertz_tui::model::ode::Method;

/// Scenes from a fixed linear congruential sequence: reproducible, and no two alike.
fn scenes(count: usize) -> Vec<ImpactParams> {
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut uniform = move || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..count)
        .map(|i| {
            let n = if i % 2 == 0 {
                1.5
            } else {
                1.0 + 0.2 * uniform()
            };
            ImpactParams {
                mass: 10f64.powf(-3.0 + 3.0 * uniform()),
                law: PowerLaw {
                    k: 10f64.powf(8.0 + 3.0 * uniform()),
                    n,
                },
                v0: 10f64.powf(-2.0 + 2.5 * uniform()),
                restitution: 0.05 + 0.9 * uniform(),
                plastic_indentation: 0.0,
                contact: Contact::Unspecified,
            }
        })
        .collect()
}

fn rel(a: f64, b: f64) -> f64 {
    (a / b - 1.0).abs()
}

#[test]
fn every_law_with_damping_hits_the_requested_e_to_1e_10() {
    let check = SolveOptions {
        method: MethodChoice::Integrator(Method::Dop853),
        rtol: 1e-12,
        atol: Some(1e-14),
        ..SolveOptions::default()
    };
    for p in scenes(6) {
        for model in ForceModel::ALL {
            if model.spec().damping.is_none() {
                assert_eq!(
                    calibrate(model, &p),
                    Err(CalibrationError::NoDamping(model))
                );
                continue;
            }
            let c = match calibrate(model, &p) {
                Ok(c) => c,
                Err(refused) => {
                    // Thornton's law without a scene is a sphere's; another n is refused.
                    assert!(
                        model.name() == "thornton" && p.law.n != 1.5,
                        "{model} {p:?}: {refused}"
                    );
                    assert!(refused.to_string().contains("n = 3/2"), "{refused}");
                    continue;
                }
            };
            let e = p.restitution;
            assert!(rel(c.e_out, e) < 1e-10, "{model} {p:?}: {} vs {e}", c.e_out);
            // An independent integration of the calibrated law agrees to its own accuracy.
            let again = solve_law(&c.law, &check).unwrap().summary.e_out;
            assert!(rel(again, e) < 1e-8, "{model} {p:?}: DOP853 {again} vs {e}");
        }
    }
}

#[test]
fn hunt_crossley_restitution_depends_on_chi_alone() {
    // One χ per e, at every n, k, m and v₀: the exact solution (Lambert W) and DOP853 both
    // realise the requested e.
    let dop853 = SolveOptions {
        method: MethodChoice::Integrator(Method::Dop853),
        rtol: 1e-12,
        atol: Some(1e-14),
        ..SolveOptions::default()
    };
    for e in [0.05, 0.3, 0.6, 0.95] {
        let chi = hunt_crossley_chi(e).unwrap();
        assert!(rel(hunt_crossley_restitution(chi), e) < 1e-13, "{e}");
        for p in scenes(6) {
            let law = ForceModel::HuntCrossley.law_with_damping(&p, chi).unwrap();
            let exact = solve_law(&law, &SolveOptions::default()).unwrap().summary;
            assert!(rel(exact.e_out, e) < 1e-12, "{e} {p:?}: {}", exact.e_out);
            let num = solve_law(&law, &dop853).unwrap().summary;
            assert!(rel(num.e_out, e) < 1e-8, "{e} {p:?}: {}", num.e_out);
        }
    }
}

#[test]
fn every_hunt_crossley_row_calibrates_to_the_same_chi() {
    // The family shares one relation e_out(χ): calibrated, all rows coincide; uncalibrated, each
    // row's χ(e) is its published formula and realises the e that relation gives.
    let p = scenes(1)[0];
    let target = hunt_crossley_chi(p.restitution).unwrap();
    for model in ForceModel::ALL {
        let Some(chi_of) = model.spec().chi else {
            continue;
        };
        let c = calibrate(model, &p).unwrap();
        assert_eq!(c.damping.value, target, "{model}");
        let law = model.law(&p).unwrap();
        let chi = law.damping().unwrap().value;
        assert!(rel(chi, chi_of(p.restitution)) < 1e-15, "{model}");
        let s = solve_law(&law, &SolveOptions::default()).unwrap().summary;
        assert!(
            rel(s.e_out, hunt_crossley_restitution(chi)) < 1e-12,
            "{model}"
        );
    }
}
