//! Maximum contact pressure as a power of force, p₀ = c·F^q, and the yield-onset velocities.

use serde::Serialize;

use super::power_law::PowerLaw;

/// p₀(F) = c·F^q: q = 1/3 for point contact (eq 9), 1/2 for line contact (eq 12).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PressureLaw {
    /// c, Pa/N^q.
    pub coefficient: f64,
    /// q.
    pub exponent: f64,
    /// Mean over maximum pressure: 2/3 for a circle (sphere), π/4 for a strip (cylinder).
    pub mean_to_max: f64,
}

impl PressureLaw {
    /// Maximum pressure p₀ at force F, Pa (eq 9 or 12).
    pub fn pressure(&self, f: f64) -> f64 {
        self.coefficient * f.max(0.0).powf(self.exponent)
    }

    /// Force at which the maximum pressure reaches p, N (eq 9 or 12 inverted).
    pub fn force_at_pressure(&self, p: f64) -> f64 {
        (p / self.coefficient).powf(1.0 / self.exponent)
    }
}

/// Velocities at which an elastic impact reaches the yield and full-plasticity pressures.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct YieldOnset {
    /// p₀ = 1.1·σ_y: yield begins (the paper's convention, on the maximum pressure; Tables 1–2), m/s.
    pub v_yield: f64,
    /// p₀ = 2.8·σ_y: full plasticity (the paper's convention), m/s.
    pub v_plastic: f64,
    /// p_mean = 1.1·σ_y: yield begins in the textbook convention on the mean pressure, m/s.
    pub v_yield_mean_pressure: f64,
    /// p_mean = 2.8·σ_y: full plasticity in the textbook convention, m/s.
    pub v_plastic_mean_pressure: f64,
    /// Wave criterion v₀ ≤ 10⁻⁵·√(E/ρ) of the conclusion, for the slower material, m/s.
    pub v_wave_limit: f64,
}

/// Elastic-plastic factor of the yield onset: p = 1.1·σ_y (the paper's §2).
pub const YIELD_FACTOR: f64 = 1.1;
/// Elastic-plastic factor of full plasticity: p = 2.8·σ_y (the paper's §2).
pub const PLASTIC_FACTOR: f64 = 2.8;
/// Wave criterion factor: v₀ ≤ 10⁻⁵·√(E/ρ) (the paper's conclusion).
pub const WAVE_FACTOR: f64 = 1e-5;

impl YieldOnset {
    /// Inverts p₀(F_max(v₀)) for the four pressure levels (Tables 1–2, docs/physics.md §2).
    pub fn new(
        law: &PowerLaw,
        pressure: &PressureLaw,
        mass: f64,
        yield_stress: f64,
        wave_speed: f64,
    ) -> Self {
        let velocity_at =
            |p_max: f64| law.velocity_for_force(mass, pressure.force_at_pressure(p_max));
        YieldOnset {
            v_yield: velocity_at(YIELD_FACTOR * yield_stress),
            v_plastic: velocity_at(PLASTIC_FACTOR * yield_stress),
            v_yield_mean_pressure: velocity_at(YIELD_FACTOR * yield_stress / pressure.mean_to_max),
            v_plastic_mean_pressure: velocity_at(
                PLASTIC_FACTOR * yield_stress / pressure.mean_to_max,
            ),
            v_wave_limit: WAVE_FACTOR * wave_speed,
        }
    }

    /// Where v₀ stands against the paper's yield-onset velocities.
    pub fn regime(&self, v0: f64) -> Regime {
        if v0 < self.v_yield {
            Regime::Elastic
        } else if v0 < self.v_plastic {
            Regime::YieldBegins
        } else {
            Regime::FullyPlastic
        }
    }
}

/// The deformation regime of an impact (the paper's §2 estimate).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Regime {
    /// p₀ < 1.1·σ_y: elastic Hertz holds.
    Elastic,
    /// 1.1·σ_y ≤ p₀ < 2.8·σ_y: plastic zone below the surface, permanent indentation begins.
    YieldBegins,
    /// p₀ ≥ 2.8·σ_y: fully plastic contact; Hertz theory no longer describes the force.
    FullyPlastic,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::sphere;

    #[test]
    fn table_1_steel_yield_velocities() {
        // Table 1: v₀y = 0.032 m/s, v₀p = 0.326 m/s for steel spheres on a steel plate, any radius.
        for (r, m) in [
            (0.005, 0.004_084_070_449_666_731),
            (0.01, 0.032_672_563_597_333_846),
        ] {
            let eta = 9.1e-12;
            let law = PowerLaw {
                k: sphere::stiffness(eta, r),
                n: 1.5,
            };
            let onset = YieldOnset::new(&law, &sphere::pressure_law(eta, r), m, 780e6, 5064.0);
            assert!((onset.v_yield - 0.032).abs() < 0.0005, "{}", onset.v_yield);
            assert!(
                (onset.v_plastic - 0.326).abs() < 0.0005,
                "{}",
                onset.v_plastic
            );
            // The textbook convention on the mean pressure is reached later: (3/2)^{5/2} times.
            let ratio = onset.v_yield_mean_pressure / onset.v_yield;
            assert!((ratio - 1.5f64.powf(2.5)).abs() < 1e-12, "{ratio}");
        }
    }

    #[test]
    fn regime_boundaries() {
        let onset = YieldOnset {
            v_yield: 0.03,
            v_plastic: 0.3,
            v_yield_mean_pressure: 0.08,
            v_plastic_mean_pressure: 0.8,
            v_wave_limit: 0.05,
        };
        assert_eq!(onset.regime(0.01), Regime::Elastic);
        assert_eq!(onset.regime(0.03), Regime::YieldBegins);
        assert_eq!(onset.regime(0.3), Regime::FullyPlastic);
    }
}
