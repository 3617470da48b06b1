//! The bouncing ball's exact impact map against its closed forms (docs/physics.md §8.1):
//! period-n orbits exist from Γ_SN = nπ(1−e)/(1+e), lose stability at
//! Γ_PD = √(Γ_SN² + (2(1+e²)/(1+e)²)²), and the map's Jacobian has det J = e².

use std::f64::consts::PI;

use hertz_tui::model::system::{Contact, OrbitOptions, SystemError, find_orbit};

use crate::systems_common::{angle_diff, ball, guess};

fn gamma_sn(n: f64, e: f64) -> f64 {
    n * PI * (1.0 - e) / (1.0 + e)
}

fn gamma_pd(n: f64, e: f64) -> f64 {
    let b = 2.0 * (1.0 + e * e) / (1.0 + e).powi(2);
    gamma_sn(n, e).hypot(b)
}

/// The period-n orbit at Γ: impact phase φ with Γ·cos φ = Γ_SN (table rising), sin φ of `sign`;
/// the ball leaves at nπ and arrives at −nπ (units g/ω), so v_in = nπ + Γ_SN.
fn closed_form(n: u32, gamma: f64, e: f64, sign: f64) -> (f64, f64) {
    let sn = gamma_sn(f64::from(n), e);
    let phase = sign * (sn / gamma).acos();
    (phase, f64::from(n) * PI + sn)
}

fn orbit(
    n: u32,
    gamma: f64,
    e: f64,
    sign: f64,
) -> Result<hertz_tui::model::system::Orbit, SystemError> {
    let (phase, v_in) = closed_form(n, gamma, e, sign);
    // Start off the orbit, so that Newton has work to do.
    let start = guess(n, 1, phase + 0.02, v_in * 1.01, 0);
    find_orbit(
        &ball(gamma, e),
        &Contact::rigid(e),
        &start,
        &OrbitOptions::default(),
    )
}

#[test]
fn period_n_orbits_sit_where_the_closed_form_puts_them() {
    for (n, e) in [(1, 0.5), (2, 0.5), (3, 0.8), (1, 0.9)] {
        let gamma = 0.5 * (gamma_sn(f64::from(n), e) + gamma_pd(f64::from(n), e));
        let o = orbit(n, gamma, e, 1.0).unwrap();
        let (phase, v_in) = closed_form(n, gamma, e, 1.0);
        let p = &o.points[0];
        assert!(
            angle_diff(p.phase, phase).abs() < 1e-9,
            "n={n} e={e}: {} vs {phase}",
            p.phase
        );
        assert!(
            (p.v_in - v_in).abs() < 1e-9 * v_in,
            "n={n}: v_in {} vs {v_in}",
            p.v_in
        );
        assert!((p.v_out - e * v_in).abs() < 1e-9 * v_in);
        assert!(
            (o.jacobian_det - e * e).abs() < 1e-10,
            "det J = {} vs e² = {}",
            o.jacobian_det,
            e * e
        );
        assert!(
            o.stable,
            "n={n}: between Γ_SN and Γ_PD the orbit is stable: {:?}",
            o.multipliers
        );
        // Its partner born at the saddle-node is a saddle.
        let saddle = orbit(n, gamma, e, -1.0).unwrap();
        assert!(!saddle.stable);
        assert!((saddle.jacobian_det - e * e).abs() < 1e-10);
    }
}

#[test]
fn period_n_orbits_are_born_at_the_saddle_node() {
    for (n, e) in [(1u32, 0.5), (2, 0.3)] {
        let sn = gamma_sn(f64::from(n), e);
        assert!(
            orbit(n, sn * (1.0 + 1e-8), e, 1.0).is_ok(),
            "n={n}: exists just above Γ_SN"
        );
        let below = orbit(n, sn * (1.0 - 1e-8), e, 1.0);
        assert!(
            below.is_err(),
            "n={n}: no orbit just below Γ_SN, got {below:?}"
        );
    }
}

#[test]
fn period_doubling_where_the_exact_map_puts_it() {
    for (n, e) in [(1u32, 0.5), (2, 0.5), (1, 0.8)] {
        let pd = gamma_pd(f64::from(n), e);
        let o = orbit(n, pd, e, 1.0).unwrap();
        let trace = o.jacobian[0][0] + o.jacobian[1][1];
        // A multiplier −1 with det = e²: trace = −(1 + e²).
        assert!(
            (trace + 1.0 + e * e).abs() < 1e-8,
            "n={n} e={e}: trace {trace} at Γ_PD = {pd}"
        );
        assert!(orbit(n, pd * (1.0 - 1e-7), e, 1.0).unwrap().stable);
        let past = orbit(n, pd * (1.0 + 1e-7), e, 1.0).unwrap();
        assert!(!past.stable);
        let lambda = past.multipliers.iter().map(|z| z.re).fold(0.0, f64::min);
        assert!(
            (lambda + 1.0).abs() < 1e-3,
            "the multiplier leaves through −1: {lambda}"
        );
    }
}
