//! Hertz point contact of spheres (and a sphere on a plane, R₂ → ∞): eqs 2 and 8–10.

use std::f64::consts::PI;

use super::pair::ContactPair;
use super::power_law::PowerLaw;
use super::pressure::PressureLaw;

/// Hertz stiffness k = 4/(3η)·√R, N/m^{3/2}, with R the reduced radius (eq 2).
pub fn stiffness(eta: f64, reduced_radius: f64) -> f64 {
    4.0 / (3.0 * eta) * reduced_radius.sqrt()
}

/// The elastic law F = k·x^{3/2} of a point contact (eqs 1–2).
pub fn hertz_law(pair: &ContactPair) -> PowerLaw {
    PowerLaw {
        k: stiffness(pair.elastic_factor(), pair.reduced_radius()),
        n: 1.5,
    }
}

/// Contact radius a = ∛(¾·η·F·R), m (eq 8).
pub fn contact_radius(eta: f64, reduced_radius: f64, f: f64) -> f64 {
    (0.75 * eta * f * reduced_radius).cbrt()
}

/// Approach x = ∛((¾)²·(ηF)²/R), m (eq 10).
pub fn approach(eta: f64, reduced_radius: f64, f: f64) -> f64 {
    (0.5625 * (eta * f).powi(2) / reduced_radius).cbrt()
}

/// Maximum pressure p₀ = 3F/(2πa²) = c·∛(F/(η²R²)) with c = (3/2π)(4/3)^{2/3} = 0.5784…, Pa (eq 9).
pub fn pressure_law(eta: f64, reduced_radius: f64) -> PressureLaw {
    let c = 3.0 / (2.0 * PI) * (4.0f64 / 3.0).powf(2.0 / 3.0);
    PressureLaw {
        coefficient: c * (eta * reduced_radius).powf(-2.0 / 3.0),
        exponent: 1.0 / 3.0,
        mean_to_max: 2.0 / 3.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const ETA: f64 = 9.1e-12;

    #[test]
    fn eq_9_constant_is_0_5784() {
        let p = pressure_law(1.0, 1.0).coefficient;
        assert!((p - 0.5784).abs() < 5e-5, "{p}");
    }

    #[test]
    fn eq_9_is_three_halves_of_mean_pressure() {
        let (r, f) = (0.01, 1710.0);
        let a = contact_radius(ETA, r, f);
        let p0 = pressure_law(ETA, r).pressure(f);
        assert!((p0 / (1.5 * f / (PI * a * a)) - 1.0).abs() < 1e-14);
    }

    #[test]
    fn eq_10_inverts_eq_1_with_eq_2() {
        // approach(F) must be the inverse of F = k·x^{3/2}.
        let r = 0.005;
        let f = 427.0;
        let x = approach(ETA, r, f);
        let k = stiffness(ETA, r);
        assert!((k * x.powf(1.5) / f - 1.0).abs() < 1e-13);
    }

    #[test]
    fn table_1_stiffness_and_contact_radius() {
        assert!((stiffness(ETA, 0.005) / 1.036e10 - 1.0).abs() < 5e-4);
        assert!((stiffness(ETA, 0.01) / 1.465e10 - 1.0).abs() < 5e-4);
        // a(v₀ = 1) for R = 10 mm: 4.886e-4 m at F_max = 1710 N
        assert!((contact_radius(ETA, 0.01, 1710.0) / 4.886e-4 - 1.0).abs() < 5e-4);
    }
}
