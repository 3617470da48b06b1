//! Unit tests of the five force laws against their equations.

use super::dry_friction::{DryFriction, EQ17_CONSTANT};
use super::*;

/// Fig. 5 of the paper: n = 1.5, m = 0.033 kg, k = 1.465e10, v₀ = 0.3 m/s, x_pl = 2.3 µm, e = 0.6;
/// steel on steel (η = 9.1e-12 m²/N, σ_y = 780 MPa, Table 1), R = 10 mm.
fn fig5() -> ImpactParams {
    ImpactParams {
        mass: 0.033,
        law: PowerLaw {
            k: 1.465e10,
            n: 1.5,
        },
        v0: 0.3,
        restitution: 0.6,
        plastic_indentation: 2.3e-6,
        contact: Contact::Point(PointContact {
            yield_pressure: 1.1 * 780e6,
            modulus: 1.0 / 9.1e-12,
            radius: 0.01,
        }),
    }
}

fn rel(a: f64, b: f64) -> f64 {
    (a / b - 1.0).abs()
}

#[test]
fn eq17_constant_is_exact() {
    // ½·(4/5)^{4/5} = 0.418255821036509… (docs/physics.md §2; the paper prints 0.418).
    assert!(rel(EQ17_CONSTANT, 0.5 * 0.8f64.powf(0.8)) < 2e-16);
    assert!((EQ17_CONSTANT - 0.418).abs() < 3e-4);
}

#[test]
fn eq16_and_eq17_agree_for_spheres() {
    // Eq 17 is eq 16 with eq 5's x_max substituted: identical at n = 3/2.
    for &(v0, e) in &[(0.03, 0.9), (0.3, 0.6), (7.0, 0.05)] {
        let p = ImpactParams {
            v0,
            restitution: e,
            ..fig5()
        };
        let (p16, p17) = (DryFriction::eq16(&p), DryFriction::eq17(&p));
        assert!(rel(p16, p17) < 1e-14, "{v0} {e}: {p16} vs {p17}");
    }
}

#[test]
fn dry_friction_uses_eq16_for_cylinders() {
    let p = ImpactParams {
        law: PowerLaw {
            k: 1.91e9,
            n: 1.081,
        },
        mass: 1.0,
        ..fig5()
    };
    let law = DryFriction::new(&p);
    assert_eq!(law.p(), DryFriction::eq16(&p));
    // x* = (P/k)^{1/(n−1)}, with 1/(n − 1) = 12.3: tiny, but watched for.
    let x_cut = (law.p() / p.law.k).powf(1.0 / 0.081);
    assert!(rel(law.tensile_approach(), x_cut) < 1e-13);
    assert!(x_cut < 1e-6 * p.law.max_approach(p.mass, p.v0));
    // Nearer n = 1 it vanishes below the watched range.
    let near_linear = ImpactParams {
        law: PowerLaw { k: 1.91e9, n: 1.01 },
        ..p
    };
    assert!(!DryFriction::new(&near_linear).may_turn_tensile());
}

#[test]
fn dry_friction_force_switches_with_the_phase() {
    let p = fig5();
    let law = DryFriction::new(&p);
    let x = 4e-6;
    let elastic = p.law.force(x);
    assert!(
        rel(
            law.phase_force(x, 0.1, Phase::Loading),
            elastic + law.p() * x
        ) < 1e-15
    );
    assert!(
        rel(
            law.phase_force(x, 0.1, Phase::Unloading),
            elastic - law.p() * x
        ) < 1e-15
    );
    assert_eq!(
        law.force(x, -0.1),
        law.phase_force(x, -0.1, Phase::Unloading)
    );
    // Tensile below x* = (P/k)²: the tension indicator changes sign there.
    let x_cut = law.tensile_approach();
    assert!(rel(x_cut, (law.p() / p.law.k).powi(2)) < 1e-14);
    assert!(law.tension(1.01 * x_cut, -0.1) > 0.0);
    assert!(law.tension(0.99 * x_cut, -0.1) < 0.0);
    assert!(law.phase_force(0.99 * x_cut, -0.1, Phase::Unloading) < 0.0);
}

#[test]
fn hunt_crossley_and_lankarani_nikravesh_alphas() {
    let p = fig5();
    let hc = hysteresis::Hysteresis::hunt_crossley(&p);
    let ln = hysteresis::Hysteresis::lankarani_nikravesh(&p);
    // eq 19: (3/2)·(1 − e)/v₀ = 2 s/m; eq 20: 3(1 − e²)/(4v₀) = 1.6 s/m.
    assert!(rel(hc.alpha(), 2.0) < 1e-15);
    assert!(rel(ln.alpha(), 1.6) < 1e-15);
    let (x, v) = (5e-6, -0.2);
    assert!(rel(hc.phase_force(x, v, Phase::Unloading), p.law.force(x) * 0.6) < 1e-15);
    assert!(rel(ln.force(x, v), p.law.force(x) * (1.0 - 0.32)) < 1e-15);
    assert!(
        rel(
            hc.dissipative_force(x, v, Phase::Unloading),
            p.law.force(x) * -0.4
        ) < 1e-15
    );
}

#[test]
fn proposed_force_vanishes_at_the_papers_exit_point() {
    // b = k·x_pl/(v₀e) makes F = 0 at x = x_pl, ẋ = −v₀e (eq 18).
    let p = fig5();
    let law = proposed::Proposed::new(&p);
    assert!(rel(law.b(), 1.465e10 * 2.3e-6 / 0.18) < 1e-15);
    let f = law.force(2.3e-6, -0.18);
    assert!(f.abs() < 1e-12 * p.law.force(2.3e-6), "{f}");
    assert_eq!(law.contact_end(), ContactEnd::ForceZero);
}

#[test]
fn proposed_without_plastic_indentation_is_elastic() {
    let p = ImpactParams {
        plastic_indentation: 0.0,
        ..fig5()
    };
    let law = proposed::Proposed::new(&p);
    assert_eq!(law.b(), 0.0);
    assert_eq!(law.contact_end(), ContactEnd::ApproachZero);
    assert!(!law.may_turn_tensile());
    assert_eq!(law.force(3e-6, 0.2), p.law.force(3e-6));
    let ex = law.exact(1e-12).expect("elastic closed form");
    assert!(rel(ex.x_max, p.law.max_approach(p.mass, p.v0)) < 1e-15);
}

#[test]
fn partials_match_finite_differences() {
    let p = fig5();
    let (x, v) = (6e-6, 0.13);
    for model in ForceModel::ALL {
        let law = model.law(&p).unwrap();
        for phase in [Phase::Loading, Phase::Unloading] {
            let (fx, fv) = law.partials(x, v, phase);
            let (hx, hv) = (1e-6 * x, 1e-6 * v);
            let dfx = (law.phase_force(x + hx, v, phase) - law.phase_force(x - hx, v, phase))
                / (2.0 * hx);
            let dfv = (law.phase_force(x, v + hv, phase) - law.phase_force(x, v - hv, phase))
                / (2.0 * hv);
            assert!(rel(fx, dfx) < 1e-8, "{model} ∂F/∂x: {fx} vs {dfx}");
            if fv == 0.0 {
                assert!(dfv.abs() < 1e-6 * law.phase_force(x, v, phase).abs() / v);
            } else {
                assert!(rel(fv, dfv) < 1e-8, "{model} ∂F/∂v: {fv} vs {dfv}");
            }
        }
    }
}

#[test]
fn every_law_is_zero_out_of_contact_and_splits_into_elastic_plus_dissipative() {
    let p = fig5();
    for model in ForceModel::ALL {
        let law = model.law(&p).unwrap();
        assert_eq!(law.force(0.0, 0.3), 0.0, "{model}");
        assert_eq!(law.force(-1e-7, -0.3), 0.0, "{model}");
        let (x, v) = (3e-6, -0.1);
        let split = p.law.force(x) + law.dissipative_force(x, v, Phase::Unloading);
        assert!(
            rel(law.phase_force(x, v, Phase::Unloading), split) < 1e-14,
            "{model}"
        );
        assert!(law.phase_force(-1e-9, -0.1, Phase::Unloading).is_finite());
    }
}

#[test]
fn invalid_parameters_are_refused_with_the_field_named() {
    // Each bad input, the field the error must name and the value it must carry.
    let bad = [
        (
            ImpactParams {
                mass: 0.0,
                ..fig5()
            },
            "mass",
            0.0,
        ),
        (ImpactParams { v0: -1.0, ..fig5() }, "impact.v0", -1.0),
        (
            ImpactParams {
                restitution: 0.0,
                ..fig5()
            },
            "impact.restitution",
            0.0,
        ),
        (
            ImpactParams {
                restitution: 1.5,
                ..fig5()
            },
            "impact.restitution",
            1.5,
        ),
        (
            ImpactParams {
                plastic_indentation: f64::NAN,
                ..fig5()
            },
            "impact.plastic_indentation",
            f64::NAN,
        ),
        (
            ImpactParams {
                law: PowerLaw { k: 1e10, n: 0.5 },
                ..fig5()
            },
            "n",
            0.5,
        ),
    ];
    for (p, want_field, want_value) in bad {
        let err = ForceModel::HuntCrossley.law(&p).unwrap_err();
        let ModelError::InvalidParameter { field, value, .. } = &err else {
            panic!("{want_field}: not an invalid parameter: {err}");
        };
        assert_eq!(field, want_field, "{err}");
        assert!(
            value.to_bits() == want_value.to_bits(),
            "{want_field}: carries {value}, not {want_value}"
        );
        assert!(err.to_string().starts_with(want_field), "{err}");
    }
    // Valid one by one, together they overflow the elastic scales: refused naming them.
    let overflow = ImpactParams {
        mass: 1e300,
        v0: 1e300,
        ..fig5()
    };
    let err = ForceModel::HuntCrossley.law(&overflow).unwrap_err();
    assert!(
        matches!(err, ModelError::ImpactScales { x_max, .. } if x_max == f64::INFINITY),
        "{err:?}"
    );
    assert!(
        err.to_string()
            .starts_with("elastic impact scales (eqs 5–7): x_max = inf m"),
        "{err}"
    );
    assert!(ForceModel::Proposed.law(&fig5()).is_ok());
}

#[test]
fn an_infinite_proposed_damping_is_refused_naming_the_plastic_indentation() {
    let mut p = fig5();
    p.plastic_indentation = 1e300;
    let err = p.validate().unwrap_err();
    let ModelError::ProposedDamping {
        plastic_indentation,
        damping,
        x_max,
    } = err
    else {
        panic!("{err:?}");
    };
    assert_eq!(plastic_indentation, 1e300);
    assert!(damping.is_infinite());
    // Table 1's x_max for the fixture's m = 0.033 kg, a little over the scene's 32.67 g.
    assert!((x_max / 9.15e-6 - 1.0).abs() < 0.01, "{x_max}");
    let msg = err.to_string();
    assert!(
        msg.starts_with(
            "proposed damping b = k·x_pl/(v₀·e) (eq 18): impact.plastic_indentation = 1e300 m"
        ),
        "{msg}"
    );
}

#[test]
fn the_law_table_has_unique_ids_and_the_paper_five_keep_theirs() {
    let mut ids: Vec<&str> = LAWS.iter().map(|l| l.id).collect();
    ids.sort_unstable();
    ids.dedup();
    assert_eq!(ids.len(), LAW_COUNT, "ids are unique");
    for (model, id) in [
        (ForceModel::Quasistatic, "quasistatic"),
        (ForceModel::DryFriction, "dry-friction"),
        (ForceModel::Proposed, "proposed"),
        (ForceModel::HuntCrossley, "hunt-crossley"),
        (ForceModel::LankaraniNikravesh, "lankarani-nikravesh"),
    ] {
        assert_eq!(model.name(), id);
        assert_eq!(id.parse::<ForceModel>(), Ok(model));
    }
    for (i, model) in ForceModel::ALL.iter().enumerate() {
        assert_eq!(model.index(), i);
        assert_eq!(
            serde_json::to_string(model).unwrap(),
            format!("\"{model}\"")
        );
    }
    let err = "hertz".parse::<ForceModel>().unwrap_err();
    assert_eq!(err, UnknownModel("hertz".into()));
    let message = err.to_string();
    assert!(
        message.starts_with("unknown model 'hertz' (expected one of: quasistatic, ")
            && message.contains("kelvin-voigt")
            && message.contains("gharib-hurmuzlu"),
        "{message}"
    );
}

#[test]
fn every_hunt_crossley_chi_damps_more_as_e_falls_and_vanishes_at_e_1() {
    // A χ(e) must be 0 at e = 1 and grow as e falls; read as a power of e, Zhiying–Qishao's
    // e^{2(1−e)} would fall back to 0 as e → 0 (docs/physics.md §6.1).
    for spec in LAWS {
        let Some(chi) = spec.chi else {
            assert_ne!(spec.family, Family::HuntCrossley, "{} has no χ(e)", spec.id);
            continue;
        };
        assert_eq!(spec.family, Family::HuntCrossley, "{}", spec.id);
        assert_eq!(chi(1.0), 0.0, "{}", spec.id);
        let mut last = 0.0;
        for i in (1..100).rev() {
            let value = chi(f64::from(i) / 100.0);
            assert!(value > last, "{} at e = {}", spec.id, f64::from(i) / 100.0);
            last = value;
        }
    }
}
