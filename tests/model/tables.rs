//! Tables 1 and 2 of the paper, reproduced from the built-in scenes through the preset registry.
//!
//! The table scenes hit at v₀ = 1 m/s, so every v₀-dependent output equals the coefficient the
//! table prints in front of its power of v₀.

use hertz_tui::model::cylinder::{self, PowerFit};
use hertz_tui::model::quasistatic::ContactGeometry;
use hertz_tui::model::{PowerLaw, Quasistatic, Scene};

use crate::laws_common::preset as scene;

fn evaluate(name: &str) -> (Scene, Quasistatic) {
    let scene = scene(name);
    let q = scene
        .quasistatic()
        .unwrap_or_else(|e| panic!("{name}: {e}"));
    (scene, q)
}

/// The value and the unit of the last digit of a number as printed, e.g. "1.036e10" → (1.036e10, 1e7).
fn printed(text: &str) -> (f64, f64) {
    let (mantissa, exponent) = text.split_once('e').unwrap_or((text, "0"));
    let exponent: i32 = exponent.parse().unwrap();
    let decimals = mantissa.split_once('.').map_or(0, |(_, d)| d.len()) as i32;
    (text.parse().unwrap(), 10f64.powi(exponent - decimals))
}

/// `value` rounds to `text`: within half a unit of its last printed digit.
fn assert_rounds_to(what: &str, value: f64, text: &str) {
    let (p, unit) = printed(text);
    assert!(
        (value - p).abs() <= 0.5 * unit * (1.0 + 1e-9),
        "{what}: {value:e} does not round to the printed {text}"
    );
}

/// `value` truncates to `text`: the paper cut the digits off instead of rounding them.
fn assert_truncates_to(what: &str, value: f64, text: &str) {
    let (p, unit) = printed(text);
    assert!(
        value >= p && value < p + unit,
        "{what}: {value:e} does not truncate to the printed {text}"
    );
    assert!(
        (value - p).abs() > 0.5 * unit,
        "{what}: {value:e} rounds to {text}; use assert_rounds_to"
    );
}

/// `value` is within `rel` of the printed number (Table 2, whose fit range the paper does not state).
fn assert_within(what: &str, value: f64, text: &str, rel: f64) {
    let (p, _) = printed(text);
    assert!(
        (value / p - 1.0).abs() <= rel,
        "{what}: {value:e} is not within {} % of the printed {text}",
        rel * 100.0
    );
}

fn contact_radius(q: &Quasistatic) -> f64 {
    match q.geometry {
        ContactGeometry::Point { contact_radius } => contact_radius,
        ContactGeometry::Line { .. } => panic!("a sphere scene has a point contact"),
    }
}

/// One column of Table 1, as printed.
struct Table1Column {
    scene: &'static str,
    radius: f64,
    mass: &'static str,
    youngs_modulus: f64,
    poisson_ratio: f64,
    eta: &'static str,
    k: &'static str,
    x_max: &'static str,
    a: &'static str,
    f_max: &'static str,
    t: &'static str,
    p0: &'static str,
    yield_stress: f64,
    v0y: &'static str,
    v0p: &'static str,
}

const TABLE_1: [Table1Column; 3] = [
    Table1Column {
        scene: "steel-sphere-r5-plate",
        radius: 0.005,
        mass: "0.004",
        youngs_modulus: 2e11,
        poisson_ratio: 0.3,
        eta: "9.1e-12",
        k: "1.036e10",
        x_max: "1.194e-5",
        a: "2.443e-4",
        f_max: "427",
        t: "3.515e-5",
        p0: "3419e6",
        yield_stress: 780e6,
        v0y: "0.032",
        v0p: "0.326",
    },
    Table1Column {
        scene: "steel-sphere-r10-plate",
        radius: 0.01,
        mass: "0.033",
        youngs_modulus: 2e11,
        poisson_ratio: 0.3,
        eta: "9.1e-12",
        k: "1.465e10",
        x_max: "2.388e-5",
        a: "4.886e-4",
        f_max: "1710",
        t: "7.029e-5",
        p0: "3419e6",
        yield_stress: 780e6,
        v0y: "0.032",
        v0p: "0.326",
    },
    Table1Column {
        scene: "aluminium-sphere-r10-plate",
        radius: 0.01,
        mass: "0.011",
        youngs_modulus: 7e10,
        poisson_ratio: 0.33,
        eta: "2.546e-11",
        k: "5.237e9",
        x_max: "2.358e-5",
        a: "4.889e-4",
        f_max: "600",
        t: "6.940e-5",
        p0: "1213e6",
        yield_stress: 340e6,
        v0y: "0.053",
        v0p: "0.545",
    },
];

/// Table 1's inputs are the scenes' inputs: radius, material and the printed (rounded) masses.
#[test]
fn table_1_inputs() {
    for col in &TABLE_1 {
        let (scene, q) = evaluate(col.scene);
        assert_eq!(scene.body1.shape.radius(), col.radius, "{}", col.scene);
        assert!(scene.body2.shape.radius().is_infinite());
        for body in [&scene.body1, &scene.body2] {
            assert_eq!(body.material.youngs_modulus, col.youngs_modulus);
            assert_eq!(body.material.poisson_ratio, col.poisson_ratio);
            assert_eq!(body.material.yield_stress, col.yield_stress);
        }
        assert_eq!(scene.impact.v0, 1.0);
        assert_rounds_to("mass", q.reduced_mass, col.mass);
    }
}

/// Every coefficient of Table 1 that the paper rounded correctly, to its printed digits.
#[test]
fn table_1_coefficients_to_the_printed_digits() {
    for col in &TABLE_1 {
        let (_, q) = evaluate(col.scene);
        let what = |field: &str| format!("{} {field}", col.scene);
        assert_eq!(q.n, 1.5);
        assert_rounds_to(&what("η"), q.eta, col.eta);
        assert_rounds_to(&what("k"), q.k, col.k);
        assert_rounds_to(&what("x_max"), q.x_max, col.x_max);
        assert_rounds_to(&what("t"), q.t_contact, col.t);
        assert_rounds_to(&what("v0y"), q.onset.v_yield, col.v0y);
        match col.scene {
            // F_max 427.52 N and a 488.70 µm: the paper truncates where it should round up.
            "steel-sphere-r5-plate" => {
                assert_truncates_to(&what("F_max"), q.f_max, col.f_max);
                assert_rounds_to(&what("a"), contact_radius(&q), col.a);
            }
            "steel-sphere-r10-plate" => {
                assert_rounds_to(&what("F_max"), q.f_max, col.f_max);
                assert_truncates_to(&what("a"), contact_radius(&q), col.a);
            }
            _ => {
                assert_rounds_to(&what("F_max"), q.f_max, col.f_max);
                assert_rounds_to(&what("a"), contact_radius(&q), "4.856e-4");
            }
        }
        if col.scene == "aluminium-sphere-r10-plate" {
            // Eq 9 with the table's own η = 2.546e-11 and F_max = 599.6 N gives p₀ = 1214.2e6 Pa,
            // one unit above the printed 1213e6; v₀p = (2.8·σ_y/c)^{5/2} then gives 0.5444. From
            // its own 1213e6 the paper gets 0.5457 and prints it truncated, 0.545. We assert the
            // exact values and bound the paper's slips.
            assert_rounds_to(&what("p0"), q.p_max, "1214e6");
            assert_within(&what("p0 vs paper"), q.p_max, col.p0, 1.1e-3);
            assert_rounds_to(&what("v0p"), q.onset.v_plastic, "0.544");
            assert_within(&what("v0p vs paper"), q.onset.v_plastic, col.v0p, 1.2e-3);
            let paper_c: f64 = 1213e6;
            let v0p_from_paper_p0 = (2.8 * 340e6 / paper_c).powf(2.5);
            assert_truncates_to(&what("v0p from the paper's p0"), v0p_from_paper_p0, col.v0p);
        } else {
            assert_rounds_to(&what("p0"), q.p_max, col.p0);
            assert_rounds_to(&what("v0p"), q.onset.v_plastic, col.v0p);
        }
    }
}

/// The aluminium column prints a = 4.889e-4 m, 0.7 % above eq 8 with the column's own η, F_max
/// and R (4.856e-4 m): a slip of the paper, pinned here so it is not mistaken for ours.
#[test]
fn table_1_aluminium_contact_radius_is_a_misprint() {
    let (_, q) = evaluate("aluminium-sphere-r10-plate");
    let eq8 = (0.75 * 2.546e-11 * q.f_max * 0.01).cbrt();
    assert!((contact_radius(&q) / eq8 - 1.0).abs() < 1e-3);
    let off = 4.889e-4 / contact_radius(&q) - 1.0;
    assert!((0.006..0.008).contains(&off), "{off}");
}

/// Tolerance of Table 2: the paper fits F = a·xⁿ + c over a force range it does not state
/// (docs/physics.md §2). `model::cylinder::scene_fit` fits over [F_top/10, F_top], F_top = min(F_max,
/// the force where p₀ reaches 1.1·σ_y), which reproduces the table to 2 %.
const TABLE_2_TOLERANCE: f64 = 0.02;

fn line_contact(name: &str, q: &Quasistatic) -> (f64, PowerFit) {
    match q.geometry {
        ContactGeometry::Line { half_width, fit } => (half_width, fit),
        ContactGeometry::Point { .. } => panic!("{name}: a cylinder scene has a line contact"),
    }
}

/// The exponents of v₀ follow from n: x_max ∝ v₀^{2/(n+1)}, F_max ∝ v₀^{2n/(n+1)}, and b, p₀ ∝
/// F_max^{1/2} ∝ v₀^{n/(n+1)}.
fn assert_exponents(name: &str, n: f64, x_max: &str, f_max: &str, b_and_p0: &str) {
    let tol = TABLE_2_TOLERANCE;
    assert_within(
        &format!("{name} x_max exponent"),
        2.0 / (n + 1.0),
        x_max,
        tol,
    );
    if !f_max.is_empty() {
        assert_within(
            &format!("{name} F_max exponent"),
            2.0 * n / (n + 1.0),
            f_max,
            tol,
        );
    }
    assert_within(
        &format!("{name} b, p0 exponent"),
        n / (n + 1.0),
        b_and_p0,
        tol,
    );
}

/// Table 2, two steel cylinders (1 kg each): every number to 2 %.
#[test]
fn table_2_two_cylinders_to_two_percent() {
    let name = "steel-cylinders-r20-l100";
    let (_, q) = evaluate(name);
    let tol = TABLE_2_TOLERANCE;
    let (b, fit) = line_contact(name, &q);
    assert_eq!(q.reduced_mass, 0.5);
    assert_rounds_to("η", q.eta, "9.1e-12");
    assert_eq!(
        (fit.a, fit.n),
        (q.k, q.n),
        "the fitted law is the law used downstream"
    );
    assert_within("k", q.k, "8.435e9", tol);
    assert_within("n", q.n, "1.090", tol);
    assert_within("x_max", q.x_max, "1.306e-5", tol);
    assert_within("b", b, "2.154e-4", tol);
    assert_within("F_max", q.f_max, "4.004e4", tol);
    assert_within("p0", q.p_max, "1183e6", tol);
    assert_within("v0y", q.onset.v_yield, "0.539", tol);
    assert_within("v0p", q.onset.v_plastic, "3.259", tol);
    assert_exponents(name, q.n, "0.957", "1.043", "0.522");
}

/// Table 2, steel cylinder on a steel plate (1 kg): k, n, x_max and the exponents to 2 %.
///
/// The column's F_max = 4.779e4 N contradicts its own k, n and x_max: any power law gives
/// F_max·x_max = (n+1)/2·m·v₀² = 1.04 J, the table's product is 1.69 J. Its b, p₀, v₀y and v₀p
/// follow from that F_max, so we check them against the values the table's own k, n and x_max
/// imply through eqs 11–12 (R = 0.02 m), and pin the inconsistency.
#[test]
fn table_2_cylinder_on_plane_to_two_percent() {
    let name = "steel-cylinder-r20-l100-plate";
    let (_, q) = evaluate(name);
    let tol = TABLE_2_TOLERANCE;
    let (b, _) = line_contact(name, &q);
    assert_eq!(q.reduced_mass, 1.0);
    assert_rounds_to("η", q.eta, "9.1e-12");
    assert_within("k", q.k, "1.91e9", tol);
    assert_within("n", q.n, "1.081", tol);
    assert_within("x_max", q.x_max, "3.535e-5", tol);
    assert_exponents(name, q.n, "0.961", "1.039", "0.519");

    let paper = PowerLaw {
        k: 1.91e9,
        n: 1.081,
    };
    let (mass, v0, x_max): (f64, f64, f64) = (1.0, 1.0, 3.535e-5);
    let energy_product = (paper.n + 1.0) / 2.0 * mass * v0 * v0;
    assert!(
        (4.779e4 * x_max / energy_product - 1.62).abs() < 0.01,
        "the table's F_max is 1.62× too large"
    );
    let implied_f_max = energy_product / x_max;
    assert_within(
        "F_max (implied)",
        q.f_max,
        &format!("{implied_f_max:e}"),
        tol,
    );
    let (eta, radius, length) = (9.1e-12, 0.02, 0.1);
    let implied_b = cylinder::half_width(eta, radius, length, implied_f_max);
    assert_within("b (implied)", b, &format!("{implied_b:e}"), tol);
    let pressure = cylinder::pressure_law(eta, radius, length);
    let implied_p0 = pressure.pressure(implied_f_max);
    assert_within("p0 (implied)", q.p_max, &format!("{implied_p0:e}"), tol);
    let onset =
        |factor: f64| paper.velocity_for_force(mass, pressure.force_at_pressure(factor * 780e6));
    assert_within(
        "v0y (implied)",
        q.onset.v_yield,
        &format!("{:e}", onset(1.1)),
        tol,
    );
    assert_within(
        "v0p (implied)",
        q.onset.v_plastic,
        &format!("{:e}", onset(2.8)),
        tol,
    );
    // The printed p₀, v₀y and v₀p are what eq 12 gives at the printed F_max.
    assert_within("p0 (paper)", pressure.pressure(4.779e4), "914e6", 1e-3);
}

/// The printed-digit checker itself must be able to fail.
#[test]
fn printed_digit_helpers_reject_near_misses() {
    assert_eq!(printed("1.036e10"), (1.036e10, 1e7));
    assert_eq!(printed("0.032"), (0.032, 1e-3));
    assert_eq!(printed("427"), (427.0, 1.0));
    let rounds = |v: f64, t: &str| std::panic::catch_unwind(|| assert_rounds_to("x", v, t)).is_ok();
    assert!(rounds(1.0364e10, "1.036e10"));
    assert!(!rounds(1.0366e10, "1.036e10"));
    assert!(!rounds(427.52, "427"));
    let truncates =
        |v: f64, t: &str| std::panic::catch_unwind(|| assert_truncates_to("x", v, t)).is_ok();
    assert!(truncates(427.52, "427"));
    assert!(!truncates(427.2, "427"));
    assert!(!truncates(428.1, "427"));
    let within =
        |v: f64, t: &str| std::panic::catch_unwind(|| assert_within("x", v, t, 0.02)).is_ok();
    assert!(within(1.019, "1.0"));
    assert!(!within(1.021, "1.0"));
}
