//! The elastic Hertz impact F = k·xⁿ in closed form (eqs 5–7; docs/physics.md §3).

use crate::model::force::ImpactParams;

use super::ExactImpact;

/// Elastic impact: x_max (eq 5), F_max (eq 6), t_c (eq 7 / incomplete-beta form), exit speed v₀.
/// Loading and unloading are mirror images, so both peaks fall at t_c/2.
pub fn elastic(params: &ImpactParams) -> ExactImpact {
    let (m, v0, law) = (params.mass, params.v0, params.law);
    let t_contact = law.contact_time(m, v0);
    let x_max = law.max_approach(m, v0);
    ExactImpact {
        x_max,
        t_x_max: 0.5 * t_contact,
        f_max: law.max_force(m, v0),
        t_f_max: 0.5 * t_contact,
        x_f_max: x_max,
        v_f_max: 0.0,
        t_contact,
        v_out: v0,
        x_residual: 0.0,
        tensile_cutoff: false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::power_law::PowerLaw;

    #[test]
    fn half_period_of_a_linear_spring() {
        // n = 1: t_c = π√(m/k) whatever v₀; x_max = v₀√(m/k).
        let params = ImpactParams {
            mass: 2.0,
            law: PowerLaw { k: 8e6, n: 1.0 },
            v0: 0.5,
            restitution: 1.0,
            plastic_indentation: 0.0,
            contact: crate::model::force::Contact::Unspecified,
        };
        let ex = elastic(&params);
        let w = (8e6f64 / 2.0).sqrt();
        assert!((ex.t_contact * w / std::f64::consts::PI - 1.0).abs() < 1e-14);
        assert!((ex.x_max * w / 0.5 - 1.0).abs() < 1e-14);
        assert_eq!(ex.v_out, 0.5);
        assert!(ex.is_valid());
    }
}
