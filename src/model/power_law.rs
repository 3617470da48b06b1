//! The elastic power law F = k·xⁿ (eq 1) and the exact impact it produces (docs/physics.md §3).

use super::error::{ModelError, require, require_positive};
use super::numeric::beta::{beta, beta_reg};

/// F = k·xⁿ with k > 0 and n ≥ 1 (n = 3/2 for spheres, 1 ≤ n ≤ 1.5 for cylinders).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct PowerLaw {
    /// Stiffness k, N/mⁿ.
    pub k: f64,
    /// Exponent n.
    pub n: f64,
}

impl PowerLaw {
    pub fn new(k: f64, n: f64) -> Result<Self, ModelError> {
        require_positive("k", k)?;
        require("n", n, "a finite number ≥ 1", |n| n >= 1.0)?;
        Ok(PowerLaw { k, n })
    }

    /// Hertz contact force F = k·xⁿ, N (eq 1); zero out of contact.
    pub fn force(&self, x: f64) -> f64 {
        if x > 0.0 {
            self.k * x.powf(self.n)
        } else {
            0.0
        }
    }

    /// Approach at which the force is `f`: x = (F/k)^{1/n}, m (eq 1 inverted).
    pub fn approach_at_force(&self, f: f64) -> f64 {
        (f / self.k).powf(1.0 / self.n)
    }

    /// Elastic energy stored at approach x: k·x^{n+1}/(n+1), J (integral of eq 1).
    pub fn energy(&self, x: f64) -> f64 {
        if x > 0.0 {
            self.k * x.powf(self.n + 1.0) / (self.n + 1.0)
        } else {
            0.0
        }
    }

    /// Tangent stiffness dF/dx = n·k·x^{n−1}, N/m.
    pub fn tangent_stiffness(&self, x: f64) -> f64 {
        self.n * self.k * x.max(0.0).powf(self.n - 1.0)
    }

    /// Maximum approach x_max = ((n+1)·m·v₀²/(2k))^{1/(n+1)}, m (eq 5; general n: docs/physics.md §3).
    pub fn max_approach(&self, mass: f64, v0: f64) -> f64 {
        ((self.n + 1.0) * mass * v0 * v0 / (2.0 * self.k)).powf(1.0 / (self.n + 1.0))
    }

    /// Maximum force F_max = k·x_maxⁿ, N (eq 6).
    pub fn max_force(&self, mass: f64, v0: f64) -> f64 {
        self.force(self.max_approach(mass, v0))
    }

    /// Pre-impact velocity whose elastic impact reaches the force `f`, m/s (eqs 5–6 inverted).
    pub fn velocity_for_force(&self, mass: f64, f: f64) -> f64 {
        (2.0 * self.energy(self.approach_at_force(f)) / mass).sqrt()
    }

    /// Contact time t_c = (2·x_max/v₀)·B(1/(n+1), 1/2)/(n+1), s (eq 7; general n: docs/physics.md §3).
    pub fn contact_time(&self, mass: f64, v0: f64) -> f64 {
        let a = 1.0 / (self.n + 1.0);
        2.0 * self.max_approach(mass, v0) / v0 * a * beta(a, 0.5)
    }

    /// Time to reach approach x on loading, s: (x_max/v₀)·B(u; 1/(n+1), 1/2)/(n+1), u = (x/x_max)^{n+1}
    /// (docs/physics.md §3). Clamped to the quarter period for x ≥ x_max.
    pub fn loading_time_at(&self, mass: f64, v0: f64, x: f64) -> f64 {
        let x_max = self.max_approach(mass, v0);
        let a = 1.0 / (self.n + 1.0);
        let u = (x.max(0.0) / x_max).min(1.0).powf(self.n + 1.0);
        x_max / v0 * a * beta(a, 0.5) * beta_reg(a, 0.5, u)
    }

    /// Elastic velocity at approach x: v = v₀·√(1 − (x/x_max)^{n+1}), m/s (energy integral of eq 4).
    pub fn loading_velocity_at(&self, mass: f64, v0: f64, x: f64) -> f64 {
        let x_max = self.max_approach(mass, v0);
        let s = (x.max(0.0) / x_max).min(1.0);
        v0 * (1.0 - s.powf(self.n + 1.0)).max(0.0).sqrt()
    }

    /// Angular frequency of small oscillations at approach x: ω = √(n·k·x^{n−1}/m), rad/s
    /// (docs/physics.md §4); at x_max it bounds explicit step sizes.
    pub fn angular_frequency(&self, mass: f64, x: f64) -> f64 {
        (self.tangent_stiffness(x) / mass).sqrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const M: f64 = 0.032_672_563_597_333_846; // steel sphere R = 10 mm, ρ = 7800
    const K: f64 = 1.465_201_465_201_465e10; // 4/(3·9.1e-12)·√0.01

    fn hertz() -> PowerLaw {
        PowerLaw::new(K, 1.5).unwrap()
    }

    #[test]
    fn eq_7_constant_is_the_exact_beta_value() {
        // (4/5)·B(2/5, 1/2) = 2.943275… (docs/physics.md §2); t_c = that × (5m/4k)^{2/5} v₀^{-1/5}.
        let law = hertz();
        let v0: f64 = 0.7;
        let scale = (5.0 * M / (4.0 * K)).powf(0.4) * v0.powf(-0.2);
        let c = law.contact_time(M, v0) / scale;
        assert!((c - 2.943_275).abs() < 1e-6, "{c}");
        assert!((c - 0.8 * beta(0.4, 0.5)).abs() < 1e-13);
    }

    #[test]
    fn table_1_middle_column_coefficients() {
        // Table 1, R = 10 mm steel sphere on steel plate, at v₀ = 1 m/s.
        let law = hertz();
        assert!((law.max_approach(M, 1.0) / 2.388e-5 - 1.0).abs() < 5e-4);
        assert!((law.max_force(M, 1.0) / 1710.0 - 1.0).abs() < 5e-4);
        assert!((law.contact_time(M, 1.0) / 7.029e-5 - 1.0).abs() < 5e-4);
    }

    #[test]
    fn eq_5_equals_general_formula_at_n_three_halves() {
        let law = hertz();
        let v0 = 0.3;
        let eq5 = (5.0 * M * v0 * v0 / (4.0 * K)).powf(0.4);
        assert!((law.max_approach(M, v0) / eq5 - 1.0).abs() < 1e-14);
        let eq6 = K.powf(0.4) * (5.0 * M * v0 * v0 / 4.0).powf(0.6);
        assert!((law.max_force(M, v0) / eq6 - 1.0).abs() < 1e-14);
    }

    #[test]
    fn linear_law_gives_half_period_of_harmonic_oscillator() {
        // n = 1: a linear spring, contact lasts π·√(m/k) regardless of v₀.
        let law = PowerLaw::new(1e6, 1.0).unwrap();
        let t = law.contact_time(2.0, 0.37);
        let exact = std::f64::consts::PI * (2.0f64 / 1e6).sqrt();
        assert!((t / exact - 1.0).abs() < 1e-13, "{t} vs {exact}");
        // and the loading time to x_max is a quarter period
        let x_max = law.max_approach(2.0, 0.37);
        assert!((law.loading_time_at(2.0, 0.37, x_max) / (exact / 2.0) - 1.0).abs() < 1e-13);
    }

    #[test]
    fn loading_time_is_consistent_with_velocity() {
        // dt/dx = 1/v: check by a central difference at mid-approach.
        let law = hertz();
        let (v0, x) = (0.3, 4e-6);
        let h = 1e-10;
        let dtdx =
            (law.loading_time_at(M, v0, x + h) - law.loading_time_at(M, v0, x - h)) / (2.0 * h);
        let v = law.loading_velocity_at(M, v0, x);
        assert!((dtdx * v - 1.0).abs() < 1e-6, "{}", dtdx * v);
    }

    #[test]
    fn velocity_for_force_inverts_max_force() {
        let law = PowerLaw::new(8.4e9, 1.09).unwrap();
        let f = law.max_force(0.5, 0.42);
        assert!((law.velocity_for_force(0.5, f) / 0.42 - 1.0).abs() < 1e-13);
    }

    #[test]
    fn invalid_laws_are_refused() {
        assert!(PowerLaw::new(-1.0, 1.5).is_err());
        assert!(PowerLaw::new(1.0, 0.5).is_err());
        assert!(PowerLaw::new(1.0, f64::NAN).is_err());
    }
}
