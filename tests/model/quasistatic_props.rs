//! Property tests of the quasistatic model over wide parameter ranges: finite positive results,
//! the v₀ scaling laws of Table 1, and errors (never panics) for invalid input.

use std::collections::BTreeMap;

use hertz_tui::model::overrides::Override;
use hertz_tui::model::presets::Registry;
use hertz_tui::model::quasistatic::ContactGeometry;
use hertz_tui::model::scene_file::parse_scene;
use hertz_tui::model::{Body, ImpactConditions, Material, ModelError, Quasistatic, Scene, Shape};
use proptest::prelude::*;

/// A valid scene file whose lines the tests replace.
const SMALL_SCENE: &str = "name = \"p\"
[body1]
shape = \"sphere\"
radius = 0.01
material = \"steel\"
[body2]
shape = \"plane\"
material = \"steel\"
[impact]
v0 = 0.3
restitution = 0.6
plastic_indentation = 0.0
";

/// A log-uniform number in [lo, hi]: wide ranges are sampled evenly per decade.
fn log_uniform(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo.ln()..=hi.ln()).prop_map(f64::exp)
}

fn material() -> impl Strategy<Value = Material> {
    (
        log_uniform(1e8, 1e12),
        0.0..0.4999,
        log_uniform(1e6, 1e10),
        log_uniform(100.0, 25_000.0),
    )
        .prop_map(|(e, nu, sy, rho)| Material {
            name: "random".into(),
            youngs_modulus: e,
            poisson_ratio: nu,
            yield_stress: sy,
            density: rho,
        })
}

/// Sphere–sphere or sphere–plane, radii 0.1 mm … 1 m, masses from density or given.
fn sphere_scene() -> impl Strategy<Value = Scene> {
    (
        log_uniform(1e-4, 1.0),
        prop::option::of(log_uniform(1e-4, 1.0)),
        material(),
        material(),
        prop::option::of(log_uniform(1e-6, 1e3)),
        log_uniform(1e-4, 10.0),
    )
        .prop_map(|(r1, r2, m1, m2, mass, v0)| Scene {
            name: "random spheres".into(),
            body1: Body {
                shape: Shape::Sphere { radius: r1 },
                material: m1,
                mass,
            },
            body2: Body {
                shape: r2.map_or(Shape::Plane, |radius| Shape::Sphere { radius }),
                material: m2,
                mass: None,
            },
            impact: ImpactConditions {
                v0,
                restitution: 0.6,
                plastic_indentation: 0.0,
            },
            assumed: Default::default(),
            fit: None,
        })
}

fn assert_finite_positive(q: &Quasistatic) {
    let mut values = vec![
        ("eta", q.eta),
        ("k", q.k),
        ("n", q.n),
        ("reduced_mass", q.reduced_mass),
        ("x_max", q.x_max),
        ("f_max", q.f_max),
        ("t_contact", q.t_contact),
        ("p_max", q.p_max),
        ("v_yield", q.onset.v_yield),
        ("v_plastic", q.onset.v_plastic),
        ("v_yield_mean_pressure", q.onset.v_yield_mean_pressure),
        ("v_plastic_mean_pressure", q.onset.v_plastic_mean_pressure),
        ("v_wave_limit", q.onset.v_wave_limit),
    ];
    match q.geometry {
        ContactGeometry::Point { contact_radius } => {
            values.push(("contact_radius", contact_radius))
        }
        ContactGeometry::Line { half_width, fit } => {
            values.push(("half_width", half_width));
            values.push(("fit.a", fit.a));
            values.push(("fit.n", fit.n));
        }
    }
    for (name, value) in values {
        assert!(value.is_finite() && value > 0.0, "{name} = {value}");
    }
}

fn with_v0(scene: &Scene, v0: f64) -> Scene {
    let mut s = scene.clone();
    s.impact.v0 = v0;
    s
}

/// |a/b − 1| ≤ tol.
fn close(a: f64, b: f64, tol: f64) -> bool {
    (a / b - 1.0).abs() <= tol
}

proptest! {
    #[test]
    fn sphere_results_are_finite_and_positive(scene in sphere_scene()) {
        let q = scene.quasistatic().expect("a valid sphere scene evaluates");
        assert_finite_positive(&q);
        prop_assert_eq!(q.n, 1.5);
        // The yield and plasticity velocities are ordered, and the paper's convention (maximum
        // pressure) is reached before the textbook one (mean pressure).
        prop_assert!(q.onset.v_yield < q.onset.v_plastic);
        prop_assert!(q.onset.v_yield < q.onset.v_yield_mean_pressure);
    }

    /// Table 1's laws: x_max ∝ v₀^{4/5}, F_max ∝ v₀^{6/5}, t ∝ v₀^{−1/5}, a and p₀ ∝ v₀^{2/5};
    /// k and the yield velocities do not depend on v₀.
    #[test]
    fn sphere_scaling_laws_in_v0(scene in sphere_scene(), factor in log_uniform(1e-2, 1e2)) {
        let q1 = scene.quasistatic().unwrap();
        let q2 = with_v0(&scene, scene.impact.v0 * factor).quasistatic().unwrap();
        let tol = 1e-9;
        prop_assert!(close(q2.x_max / q1.x_max, factor.powf(0.8), tol));
        prop_assert!(close(q2.f_max / q1.f_max, factor.powf(1.2), tol));
        prop_assert!(close(q2.t_contact / q1.t_contact, factor.powf(-0.2), tol));
        prop_assert!(close(q2.p_max / q1.p_max, factor.powf(0.4), tol));
        let (ContactGeometry::Point { contact_radius: a1 }, ContactGeometry::Point { contact_radius: a2 }) =
            (q1.geometry, q2.geometry) else { panic!("spheres have point contact") };
        prop_assert!(close(a2 / a1, factor.powf(0.4), tol));
        prop_assert_eq!(q1.k, q2.k);
        prop_assert!(close(q1.onset.v_yield, q2.onset.v_yield, tol));
        prop_assert!(close(q1.onset.v_plastic, q2.onset.v_plastic, tol));
    }

    /// Eq 5 and eq 6 hold exactly: energy ½mv₀² = k·x_max^{5/2}/(5/2), F_max = k·x_max^{3/2}.
    #[test]
    fn sphere_energy_balance(scene in sphere_scene()) {
        let q = scene.quasistatic().unwrap();
        let kinetic = 0.5 * q.reduced_mass * scene.impact.v0.powi(2);
        let elastic = q.k * q.x_max.powf(2.5) / 2.5;
        prop_assert!(close(elastic, kinetic, 1e-12));
        prop_assert!(close(q.f_max, q.k * q.x_max.powf(1.5), 1e-12));
    }

    /// A bad value in any field is an error that names the field, never a panic or a NaN.
    #[test]
    fn invalid_inputs_are_errors_naming_the_field(
        scene in sphere_scene(),
        field in 0usize..9,
        bad in prop::sample::select(vec![f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 0.0, -1.0, -1e-300]),
    ) {
        let mut s = scene;
        let name = match field {
            0 => { s.body1.shape = Shape::Sphere { radius: bad }; "body1.radius" }
            1 => { s.body1.material.youngs_modulus = bad; "body1.material.youngs_modulus" }
            2 => { s.body2.material.yield_stress = bad; "body2.material.yield_stress" }
            3 => { s.body1.material.density = bad; "body1.material.density" }
            4 => { s.body1.mass = Some(bad); "body1.mass" }
            5 => { s.impact.v0 = bad; "impact.v0" }
            6 => { s.impact.restitution = bad; "impact.restitution" }
            7 => {
                // ν must lie in [0, 0.5): shift the bad value out of range from above too.
                s.body2.material.poisson_ratio = if bad == 0.0 { 0.5 } else { bad };
                "body2.material.poisson_ratio"
            }
            _ => {
                s.impact.plastic_indentation = if bad == 0.0 { f64::NAN } else { bad };
                "impact.plastic_indentation"
            }
        };
        let err = s.quasistatic().and_then(|_| s.validate()).expect_err("invalid input is refused");
        prop_assert!(err.to_string().starts_with(name), "{} does not start with {}", err, name);
    }

    /// Whatever a scene file holds, parsing returns a scene or an error; it never panics.
    #[test]
    fn arbitrary_values_in_a_scene_file_never_panic(
        key in prop::sample::select(vec!["radius", "v0", "restitution", "material", "shape", "plastic_indentation"]),
        value in prop_oneof![
            any::<f64>().prop_map(|x| format!("{x:e}")),
            any::<i64>().prop_map(|i| i.to_string()),
            "[a-z ]{0,8}".prop_map(|s| format!("\"{s}\"")),
            Just("nan".to_string()),
            Just("-inf".to_string()),
            Just("[1, 2]".to_string()),
            Just("{ x = 1 }".to_string()),
            "[^\n]{0,12}",
        ],
    ) {
        let text = SMALL_SCENE;
        let line = text.lines().find(|l| l.starts_with(&format!("{key} ="))).unwrap();
        let text = text.replacen(line, &format!("{key} = {value}"), 1);
        let registry = Registry::builtin().unwrap();
        match parse_scene("p.toml", &text, registry.material_catalog()) {
            // Whatever parsed also validated: the quasistatic model gives finite numbers, or
            // refuses an overflow by its domain.
            Ok(scene) => match scene.quasistatic() {
                Ok(q) => assert_finite_positive(&q),
                Err(e) => prop_assert!(
                    matches!(e, ModelError::OutOfDomain { .. } | ModelError::EstimateOutOfRange { .. }),
                    "{e}"
                ),
            },
            // A refusal is located in the file.
            Err(e) => prop_assert!(e.to_string().starts_with("p.toml"), "{e}"),
        }
    }

    /// Arbitrary `--set` arguments are parsed or refused with a message, never a panic.
    #[test]
    fn arbitrary_overrides_never_panic(arg in "[a-z0-9_.=\"{} -]{0,30}") {
        let registry = Registry::builtin().unwrap();
        if let Ok(o) = arg.parse::<Override>()
            && let Ok(scene) = registry.scene_with("steel-sphere-r10-plate", &[o])
        {
            prop_assert!(scene.validate().is_ok());
        }
    }

    /// Random text is refused with a located error or parsed, never a panic.
    #[test]
    fn arbitrary_text_never_panics(text in "\\PC{0,200}") {
        if let Err(e) = parse_scene("p.toml", &text, &BTreeMap::new()) {
            prop_assert!(e.to_string().starts_with("p.toml"), "{e}");
        }
    }
}

/// Two parallel cylinders or a cylinder on a plane, radii 1 mm … 0.5 m, lengths 1 cm … 1 m.
fn cylinder_scene() -> impl Strategy<Value = Scene> {
    (
        log_uniform(1e-3, 0.5),
        prop::option::of(log_uniform(1e-3, 0.5)),
        log_uniform(1e-2, 1.0),
        material(),
        log_uniform(1e-3, 10.0),
    )
        .prop_map(|(r1, r2, length, m, v0)| Scene {
            name: "random cylinders".into(),
            body1: Body {
                shape: Shape::Cylinder { radius: r1, length },
                material: m.clone(),
                mass: None,
            },
            body2: Body {
                shape: r2.map_or(Shape::Plane, |radius| Shape::Cylinder { radius, length }),
                material: m,
                mass: None,
            },
            impact: ImpactConditions {
                v0,
                restitution: 0.6,
                plastic_indentation: 0.0,
            },
            assumed: Default::default(),
            fit: None,
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Cylinders: the fitted law gives finite positive results with 1 ≤ n ≤ 1.5 (the paper's
    /// range), or the scene is refused with an error stating the domain of eq 13/14.
    #[test]
    fn cylinder_results_are_finite_and_positive(scene in cylinder_scene()) {
        match scene.quasistatic() {
            Ok(q) => {
                assert_finite_positive(&q);
                prop_assert!((1.0..=1.5).contains(&q.n), "n = {}", q.n);
            }
            Err(e) => prop_assert!(
                matches!(e, ModelError::OutOfDomain { .. } | ModelError::FitFailed(_)),
                "not a domain error: {}", e
            ),
        }
    }
}

/// Steel cylinders of everyday size always evaluate: the domain errors above are for extremes only.
#[test]
fn moderate_steel_cylinders_always_evaluate() {
    let steel = Registry::builtin().unwrap().material("steel").unwrap();
    for radius in [0.005, 0.02, 0.1] {
        for length in [0.05, 0.2] {
            for v0 in [0.01, 0.1, 1.0] {
                for on_plane in [false, true] {
                    let cylinder = Body {
                        shape: Shape::Cylinder { radius, length },
                        material: steel.clone(),
                        mass: None,
                    };
                    let other = if on_plane {
                        Body {
                            shape: Shape::Plane,
                            ..cylinder.clone()
                        }
                    } else {
                        cylinder.clone()
                    };
                    let scene = Scene {
                        name: "cylinders".into(),
                        body1: cylinder,
                        body2: other,
                        impact: ImpactConditions {
                            v0,
                            restitution: 0.6,
                            plastic_indentation: 0.0,
                        },
                        assumed: Default::default(),
                        fit: None,
                    };
                    let q = scene.quasistatic().unwrap_or_else(|e| {
                        panic!("R = {radius}, L = {length}, v0 = {v0}, plane {on_plane}: {e}")
                    });
                    assert_finite_positive(&q);
                    assert!((1.0..=1.5).contains(&q.n), "n = {}", q.n);
                }
            }
        }
    }
}

/// A radius so small that the contact radius underflows to 0 is refused, naming it (found by
/// `arbitrary_values_in_a_scene_file_never_panic`: radius = 1.106750042135791e-107).
#[test]
fn a_contact_radius_that_underflows_is_refused() {
    let line = SMALL_SCENE
        .lines()
        .find(|l| l.starts_with("radius ="))
        .unwrap();
    let text = SMALL_SCENE.replacen(line, "radius = 1.106750042135791e-107", 1);
    let registry = Registry::builtin().unwrap();
    let scene = parse_scene("p.toml", &text, registry.material_catalog()).unwrap();
    match scene.quasistatic() {
        Err(ModelError::EstimateOutOfRange { quantity, value }) => {
            assert_eq!((quantity, value), ("contact_radius", 0.0))
        }
        other => panic!("expected the contact radius refused, got {other:?}"),
    }
}
