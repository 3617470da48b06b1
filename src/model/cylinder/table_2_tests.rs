//! Table 2 of the paper reproduced through `quasistatic::evaluate`.
//!
//! Fit range (see `scene_fit`): 16 forces spaced geometrically over [F_top/10, F_top], relative
//! residuals, F_top = min(F_max, F_y) with F_y the force at p₀ = 1.1·σ_y (eq 12). At v₀ = 1 m/s
//! that is [2104.6, 21046] N for two cylinders (F_top = F_y: the impact is past yield) and
//! [2947.7, 29477] N for a cylinder on a plane (F_top = F_max).

use crate::model::body::{Body, Shape};
use crate::model::material::tests::steel;
use crate::model::pair::ContactPair;
use crate::model::power_law::PowerLaw;
use crate::model::pressure::{PLASTIC_FACTOR, YIELD_FACTOR};
use crate::model::quasistatic::{self, ContactGeometry, Quasistatic};

use super::{PowerFit, fit_power_law};

/// The paper's tolerance for Table 2.
const TABLE_TOLERANCE: f64 = 0.02;

fn cylinder() -> Body {
    Body {
        shape: Shape::Cylinder {
            radius: 0.02,
            length: 0.1,
        },
        material: steel(),
        mass: Some(1.0),
    }
}

fn plane() -> Body {
    Body {
        shape: Shape::Plane,
        material: steel(),
        mass: None,
    }
}

pub(super) fn two_cylinders() -> ContactPair {
    ContactPair::new(cylinder(), cylinder()).unwrap()
}

pub(super) fn cylinder_on_plane() -> ContactPair {
    ContactPair::new(cylinder(), plane()).unwrap()
}

fn rel(a: f64, b: f64) -> f64 {
    (a / b - 1.0).abs()
}

fn assert_close(name: &str, ours: f64, paper: f64, tolerance: f64) {
    assert!(
        rel(ours, paper) < tolerance,
        "{name}: ours {ours:e}, paper {paper:e} ({:+.2} %)",
        100.0 * (ours / paper - 1.0)
    );
}

/// Half-width b and the fit of a line-contact estimate.
fn line(q: &Quasistatic) -> (f64, PowerFit) {
    match q.geometry {
        ContactGeometry::Line { half_width, fit } => (half_width, fit),
        ContactGeometry::Point { .. } => panic!("a cylinder pair gave a point contact"),
    }
}

/// Exponent p of y ∝ v₀^p measured between two velocities.
fn exponent(y1: f64, y2: f64, v1: f64, v2: f64) -> f64 {
    (y2 / y1).ln() / (v2 / v1).ln()
}

/// F at which p₀ of eq 12 reaches `factor`·σ_y, N.
fn force_at_pressure_factor(factor: f64, radius: f64) -> f64 {
    (factor * 780e6).powi(2) * std::f64::consts::PI * 0.1 * 9.1e-12 * radius
}

#[test]
fn two_cylinders_at_one_metre_per_second() {
    let q = quasistatic::evaluate(&two_cylinders(), 1.0).unwrap();
    let (b, fit) = line(&q);
    assert_close("η", q.eta, 9.1e-12, 1e-12);
    assert_close("m", q.reduced_mass, 0.5, 1e-15);
    assert_close("k", q.k, 8.435e9, TABLE_TOLERANCE);
    assert_close("x_max", q.x_max, 1.306e-5, TABLE_TOLERANCE);
    assert_close("b", b, 2.154e-4, TABLE_TOLERANCE);
    assert_close("F_max", q.f_max, 4.004e4, TABLE_TOLERANCE);
    assert_close("p₀", q.p_max, 1183e6, TABLE_TOLERANCE);
    assert_close("v₀y", q.onset.v_yield, 0.539, TABLE_TOLERANCE);
    assert_close("v₀p", q.onset.v_plastic, 3.259, TABLE_TOLERANCE);
    // n comes out as printed (1.090), k 0.5 % low: 8.389e9.
    assert!((q.n - 1.090).abs() < 5e-4, "n = {}", q.n);
    assert!(fit.max_rel_error < 1e-3, "{fit:?}");
}

#[test]
fn two_cylinders_exponents_between_one_and_two_metres_per_second() {
    // Both impacts are past yield, so both use the same fit and the laws are exact powers.
    let pair = two_cylinders();
    let (q1, q2) = (
        quasistatic::evaluate(&pair, 1.0).unwrap(),
        quasistatic::evaluate(&pair, 2.0).unwrap(),
    );
    let (b1, b2) = (line(&q1).0, line(&q2).0);
    let tol = TABLE_TOLERANCE;
    assert_close(
        "x_max exponent",
        exponent(q1.x_max, q2.x_max, 1.0, 2.0),
        0.957,
        tol,
    );
    assert_close("b exponent", exponent(b1, b2, 1.0, 2.0), 0.522, tol);
    assert_close(
        "F_max exponent",
        exponent(q1.f_max, q2.f_max, 1.0, 2.0),
        1.043,
        tol,
    );
    assert_close(
        "p₀ exponent",
        exponent(q1.p_max, q2.p_max, 1.0, 2.0),
        0.522,
        tol,
    );
}

#[test]
fn cylinder_on_plane_at_one_metre_per_second() {
    let q = quasistatic::evaluate(&cylinder_on_plane(), 1.0).unwrap();
    let (b, fit) = line(&q);
    assert_close("η", q.eta, 9.1e-12, 1e-12);
    assert_close("m", q.reduced_mass, 1.0, 1e-15);
    assert_close("k", q.k, 1.91e9, TABLE_TOLERANCE);
    assert_close("x_max", q.x_max, 3.535e-5, TABLE_TOLERANCE);
    // n comes out as printed (1.081), k 0.3 % high: 1.917e9.
    assert!((q.n - 1.081).abs() < 5e-4, "n = {}", q.n);
    assert!(fit.max_rel_error < 1e-3, "{fit:?}");

    // Not reproducible: the column's F_max = 4.779e4 N contradicts its own k = 1.91e9,
    // n = 1.081 and x_max = 3.535e-5 m. Eq 6 gives F_max = k·x_maxⁿ = 2.943e4 N, and any power
    // law has F_max·x_max = (n+1)/2·m·v₀² = 1.0405 J here, while the table's product is
    // 4.779e4 × 3.535e-5 = 1.689 J (1.62 times more). The table's p₀ = 914e6 Pa,
    // v₀y = 0.885 m/s and v₀p = 5.340 m/s follow from F_max = 4.779e4 N by eq 12 with
    // R = 0.02 m, and its b = 2.353e-4 m from the same F_max by eq 11 with R = 0.01 m (the
    // two-cylinder reduced radius, although R₂ → ∞ here). So we check these against the values
    // the table's own k, n and x_max imply, with eqs 11–12 at R = 0.02 m: F_max = 2.943e4 N
    // (ours 2.948e4), b = 2.612e-4 m (ours 2.614e-4), p₀ = 717.5e6 Pa (ours 718.0e6),
    // v₀y = 1.411 m/s (ours 1.409), v₀p = 8.52 m/s (ours 8.51).
    let paper_law = PowerLaw {
        k: 1.91e9,
        n: 1.081,
    };
    let implied_f_max = (paper_law.n + 1.0) / 2.0 * 1.0 / 3.535e-5;
    assert_close("F_max·x_max (paper)", 4.779e4 * 3.535e-5, 1.689, 1e-3);
    assert_close("k·x_maxⁿ (paper)", paper_law.force(3.535e-5), 2.943e4, 1e-3);
    assert!(
        rel(4.779e4, implied_f_max) > 0.6,
        "the table's F_max is inconsistent"
    );
    assert_close("F_max", q.f_max, implied_f_max, TABLE_TOLERANCE);
    let implied_b = super::half_width(9.1e-12, 0.02, 0.1, implied_f_max);
    assert_close("b", b, implied_b, TABLE_TOLERANCE);
    // The table's b is eq 11 at its own F_max with R = 0.01 m:
    assert_close(
        "b (paper)",
        super::half_width(9.1e-12, 0.01, 0.1, 4.779e4),
        2.353e-4,
        1e-3,
    );
    let pressure = super::pressure_law(9.1e-12, 0.02, 0.1);
    assert_close(
        "p₀",
        q.p_max,
        pressure.pressure(implied_f_max),
        TABLE_TOLERANCE,
    );
    assert_close("p₀ (paper)", pressure.pressure(4.779e4), 914e6, 1e-3);
    let implied_v_yield =
        paper_law.velocity_for_force(1.0, force_at_pressure_factor(YIELD_FACTOR, 0.02));
    let implied_v_plastic =
        paper_law.velocity_for_force(1.0, force_at_pressure_factor(PLASTIC_FACTOR, 0.02));
    assert_close("v₀y", q.onset.v_yield, implied_v_yield, TABLE_TOLERANCE);
    assert_close("v₀p", q.onset.v_plastic, implied_v_plastic, TABLE_TOLERANCE);
}

#[test]
fn cylinder_on_plane_exponents_between_half_and_one_metre_per_second() {
    // Both impacts stay below the yield force, so each has its own fit over its own F_max: the
    // measured exponents are those of eq 14 itself, not of a single fitted law.
    let pair = cylinder_on_plane();
    let (q1, q2) = (
        quasistatic::evaluate(&pair, 0.5).unwrap(),
        quasistatic::evaluate(&pair, 1.0).unwrap(),
    );
    let (b1, b2) = (line(&q1).0, line(&q2).0);
    let tol = TABLE_TOLERANCE;
    assert_close(
        "x_max exponent",
        exponent(q1.x_max, q2.x_max, 0.5, 1.0),
        0.961,
        tol,
    );
    assert_close("b exponent", exponent(b1, b2, 0.5, 1.0), 0.519, tol);
    assert_close(
        "F_max exponent",
        exponent(q1.f_max, q2.f_max, 0.5, 1.0),
        1.039,
        tol,
    );
    assert_close(
        "p₀ exponent",
        exponent(q1.p_max, q2.p_max, 0.5, 1.0),
        0.519,
        tol,
    );
}

#[test]
fn the_fit_range_that_reproduces_table_2() {
    // Two cylinders at v₀ = 1 m/s: the range ends at the yield force F_y = 21046 N.
    let q = quasistatic::evaluate(&two_cylinders(), 1.0).unwrap();
    let fit = line(&q).1;
    let yield_force = force_at_pressure_factor(YIELD_FACTOR, 0.01);
    assert_close("F_top", fit.f_max, yield_force, 1e-12);
    assert_close("F_y", yield_force, 21_046.0, 1e-4);
    assert_close("f_min", fit.f_min, 0.1 * fit.f_max, 1e-12);
    // Cylinder on plane at v₀ = 1 m/s: F_max = 29477 N is below F_y = 42092 N, so the range
    // ends at F_max.
    let q = quasistatic::evaluate(&cylinder_on_plane(), 1.0).unwrap();
    let fit = line(&q).1;
    assert_close("F_top", fit.f_max, q.f_max, 1e-5);
    assert_close("f_min", fit.f_min, 0.1 * fit.f_max, 1e-12);
}

#[test]
fn fitting_two_cylinders_up_to_f_max_does_not_reproduce_table_2() {
    // Why the range stops at the yield force: the full elastic range of the two-cylinder impact
    // at v₀ = 1 m/s, [F_max/10, F_max] with F_max = 3.99e4 N, gives k about 6 % high.
    let fit = fit_power_law(&two_cylinders(), 3.99e3, 3.99e4).unwrap();
    assert!(fit.a / 8.435e9 - 1.0 > 0.05, "{fit:?}");
    assert!(fit.n - 1.090 > 0.005, "{fit:?}");
}
