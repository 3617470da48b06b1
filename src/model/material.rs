//! Isotropic linear-elastic material with a yield stress.

use serde::{Deserialize, Serialize};

use super::error::{ModelError, require, require_positive};

/// A homogeneous isotropic material, SI units throughout.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Material {
    pub name: String,
    /// Young's modulus E, Pa.
    pub youngs_modulus: f64,
    /// Poisson's ratio ν (the paper's μ), dimensionless.
    pub poisson_ratio: f64,
    /// Uniaxial yield stress σ_y, Pa.
    pub yield_stress: f64,
    /// Density ρ, kg/m³.
    pub density: f64,
}

impl Material {
    /// Checks E > 0, 0 ≤ ν < 0.5, σ_y > 0, ρ > 0, all finite.
    pub fn validate(&self) -> Result<(), ModelError> {
        require_positive("youngs_modulus", self.youngs_modulus)?;
        require("poisson_ratio", self.poisson_ratio, "in [0, 0.5)", |nu| {
            (0.0..0.5).contains(&nu)
        })?;
        require_positive("yield_stress", self.yield_stress)?;
        require_positive("density", self.density)?;
        Ok(())
    }

    /// Elastic factor ηᵢ = (1 − νᵢ²)/Eᵢ, m²/N (one term of eq 3).
    pub fn elastic_factor(&self) -> f64 {
        (1.0 - self.poisson_ratio * self.poisson_ratio) / self.youngs_modulus
    }

    /// Bar wave speed √(E/ρ), m/s (the conclusion's wave criterion).
    pub fn wave_speed(&self) -> f64 {
        (self.youngs_modulus / self.density).sqrt()
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// The paper's steel (Table 1) with the density of docs/physics.md §2.
    pub fn steel() -> Material {
        Material {
            name: "steel".into(),
            youngs_modulus: 2e11,
            poisson_ratio: 0.3,
            yield_stress: 780e6,
            density: 7800.0,
        }
    }

    /// The paper's aluminium alloy (Table 1) with the density of docs/physics.md §2.
    pub fn aluminium() -> Material {
        Material {
            name: "aluminium-alloy".into(),
            youngs_modulus: 7e10,
            poisson_ratio: 0.33,
            yield_stress: 340e6,
            density: 2700.0,
        }
    }

    #[test]
    fn steel_elastic_factor_matches_table_1() {
        // Table 1: η = η₁ + η₂ = 9.1e-12 m²/N for steel on steel.
        let eta = 2.0 * steel().elastic_factor();
        assert!((eta - 9.1e-12).abs() < 1e-16);
    }

    #[test]
    fn aluminium_elastic_factor_matches_table_1() {
        // Table 1 prints 2.546e-11.
        let eta = 2.0 * aluminium().elastic_factor();
        assert!((eta / 2.546e-11 - 1.0).abs() < 5e-4, "{eta}");
    }

    /// A field name and a way to spoil it.
    type Spoiler = (&'static str, fn(&mut Material));

    #[test]
    fn validation_names_each_bad_field() {
        let cases: [Spoiler; 6] = [
            ("youngs_modulus", |m| m.youngs_modulus = -1.0),
            ("poisson_ratio", |m| m.poisson_ratio = 0.5),
            ("poisson_ratio", |m| m.poisson_ratio = -0.1),
            ("yield_stress", |m| m.yield_stress = 0.0),
            ("density", |m| m.density = f64::NAN),
            ("youngs_modulus", |m| m.youngs_modulus = f64::INFINITY),
        ];
        for (field, spoil) in cases {
            let mut m = steel();
            spoil(&mut m);
            let msg = m.validate().unwrap_err().to_string();
            assert!(msg.starts_with(field), "{msg}");
        }
        assert!(steel().validate().is_ok());
    }
}
