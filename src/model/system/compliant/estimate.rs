//! The Hertz estimate of one impact of a system at its impact velocity (eqs 5–7): what a rigid
//! stop's impacts would load the bodies with, and the contact time the verdict weighs against the
//! forcing period.

use serde::Serialize;

use crate::model::power_law::PowerLaw;

/// The elastic impact of mass m at approach speed v on F = k·xⁿ.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct HertzEstimate {
    /// x_max, m (eq 5).
    pub max_approach: f64,
    /// F_max = k·x_maxⁿ, N (eq 6).
    pub peak_force: f64,
    /// t_c, s (eq 7).
    pub contact_time: f64,
}

/// The Hertz estimate (eqs 5–7) at approach speed `v` > 0; `None` for v ≤ 0 or non-finite
/// results (no impact to estimate).
pub fn hertz_estimate(law: &PowerLaw, mass: f64, v: f64) -> Option<HertzEstimate> {
    if !(v > 0.0 && v.is_finite()) {
        return None;
    }
    let estimate = HertzEstimate {
        max_approach: law.max_approach(mass, v),
        peak_force: law.max_force(mass, v),
        contact_time: law.contact_time(mass, v),
    };
    [
        estimate.max_approach,
        estimate.peak_force,
        estimate.contact_time,
    ]
    .iter()
    .all(|q| q.is_finite() && *q > 0.0)
    .then_some(estimate)
}

/// The speed at which the elastic contact lasts `t_c` (eq 7 inverted: t_c ∝ v^(−(n−1)/(n+1))); for
/// n = 1 every speed gives the same t_c and `None` is returned.
pub fn speed_for_contact_time(law: &PowerLaw, mass: f64, t_c: f64) -> Option<f64> {
    let exponent = (law.n - 1.0) / (law.n + 1.0);
    if exponent <= 0.0 || t_c.is_nan() || t_c <= 0.0 {
        return None;
    }
    // t_c(v) = t_c(1)·v^(−exponent).
    let at_one = law.contact_time(mass, 1.0);
    let v = (at_one / t_c).powf(1.0 / exponent);
    v.is_finite().then_some(v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_1_values_and_the_inverse_of_eq_7() {
        // Table 1 of the paper, R = 10 mm steel sphere on a steel plate at v₀ = 1 m/s.
        let law = PowerLaw::new(1.465_201_465_201_465e10, 1.5).unwrap();
        let m = 0.032_672_563_597_333_846;
        let e = hertz_estimate(&law, m, 1.0).unwrap();
        assert!((e.max_approach / 2.388e-5 - 1.0).abs() < 5e-4);
        assert!((e.peak_force / 1710.0 - 1.0).abs() < 5e-4);
        assert!((e.contact_time / 7.029e-5 - 1.0).abs() < 5e-4);
        let v = speed_for_contact_time(&law, m, e.contact_time).unwrap();
        assert!((v - 1.0).abs() < 1e-12, "{v}");
        assert_eq!(hertz_estimate(&law, m, 0.0), None);
        assert_eq!(hertz_estimate(&law, m, f64::NAN), None);
    }
}
