//! The interface every contact-force law implements, and the rules all of them share.
//!
//! **Compressive-only rule.** A contact force can push the bodies apart but never pull them together.
//! Where a law would turn tensile (F < 0 while x > 0) on unloading, contact ends there: the bodies
//! separate with the velocity they have, and the approach left is reported as residual indentation.
//! The solver reports where this happened (`ImpactSummary::tensile_cutoff`). The proposed model
//! (eq 18) ends at F = 0 by design — that is its own contact-end rule, not a cutoff.

use crate::model::exact::ExactImpact;

use super::{ForceModel, ImpactParams};

/// Which half of the impact a force is evaluated in.
///
/// Dry friction (eq 15) switches sign at ẋ = 0; the solver never integrates across the switch, it
/// evaluates the law with the phase fixed and restarts at the maximum-compression event.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Phase {
    /// ẋ ≥ 0: from first contact to maximum compression.
    Loading,
    /// ẋ ≤ 0: from maximum compression to the end of contact.
    Unloading,
}

impl Phase {
    /// The phase a velocity belongs to (ẋ = 0 counts as loading, the end of which it is).
    pub fn of_velocity(v: f64) -> Phase {
        if v < 0.0 {
            Phase::Unloading
        } else {
            Phase::Loading
        }
    }
}

/// Where a law's contact ends, besides the compressive-only cutoff.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ContactEnd {
    /// When the approach returns to x = 0 (elastic, dry friction, Hunt–Crossley, Lankarani–Nikravesh).
    ApproachZero,
    /// When the force returns to F = 0, leaving a residual indentation (the proposed model, eq 18).
    ForceZero,
}

/// One contact-force law F(x, ẋ) with its parameters resolved from an [`ImpactParams`], SI units.
/// A law is a handful of numbers, copied freely (the solver re-anchors a hysteresis by value).
pub trait ForceLaw: Copy {
    /// Which law this is.
    fn model(&self) -> ForceModel;

    /// The impact the law was built for.
    fn params(&self) -> &ImpactParams;

    /// F during `phase`, N. Powers of x are continued to x < 0 as x·|x|ⁿ⁻¹ so that integrator
    /// stages evaluated just past the end-of-contact event see a smooth right-hand side; every
    /// reported number lies at x ≥ 0.
    fn phase_force(&self, x: f64, v: f64, phase: Phase) -> f64;

    /// The dissipative part F − k·xⁿ during `phase`, N (what ∮F dx measures).
    fn dissipative_force(&self, x: f64, v: f64, phase: Phase) -> f64;

    /// (∂F/∂x, ∂F/∂ẋ) during `phase`: the Jacobian of implicit methods and the rate dF/dt that
    /// locates the force peak.
    fn partials(&self, x: f64, v: f64, phase: Phase) -> (f64, f64);

    /// Where contact ends besides the compressive-only cutoff.
    fn contact_end(&self) -> ContactEnd;

    /// Whether the law switches at ẋ = 0 (dry friction's sign(ẋ)).
    fn switches_at_max_compression(&self) -> bool {
        false
    }

    /// Whether the law can turn tensile on unloading, so that the cutoff (or, for
    /// [`ContactEnd::ForceZero`], the end of contact) must be watched for.
    fn may_turn_tensile(&self) -> bool;

    /// A smooth function with the sign of the unloading force for x > 0 that stays regular as
    /// x → 0 (F divided by a power of x). Contact ends where it falls through zero.
    fn tension(&self, x: f64, v: f64) -> f64;

    /// The value of the law's damping parameter (the one its table row names), SI; `None` for a
    /// law without one.
    fn damping_value(&self) -> Option<f64> {
        None
    }

    /// The exact impact (closed form or quadrature) where one exists; quadratures aim at `rtol`.
    fn exact(&self, rtol: f64) -> Option<ExactImpact>;

    /// β where the dissipative force is p·β·xᵖ⁻¹·ẋ = d(β·xᵖ)/dt (p = [`ForceLaw::impulse_power`]),
    /// so that its impulse is β·xᵖ in closed form (the proposed model, eq 18: β = b/n, p = n;
    /// Hertz–viscous: β = 2γ/(n+1), p = (n+1)/2); 0 for every other law. The solver then
    /// integrates w = ẋ + β·xᵖ/m, whose equation m·ẇ = −k·xⁿ is as smooth as the elastic one,
    /// instead of ẋ, whose xᵖ⁻¹ damping at first contact (√x, x^¼) costs adaptive methods their
    /// order and most of their rejected steps.
    fn impulse_coefficient(&self) -> f64 {
        0.0
    }

    /// The exponent p of the damping impulse β·xᵖ ([`ForceLaw::impulse_coefficient`]): n unless
    /// the law says otherwise.
    fn impulse_power(&self) -> f64 {
        self.params().law.n
    }

    /// The law as it unloads from the turning point x_turn (m) the integration reached: a
    /// rate-independent hysteresis (Thornton's) defines its unloading branch by the state at
    /// maximum compression. The law itself for every other law.
    fn unloading_at_turn(&self, _x_turn: f64) -> Self {
        *self
    }

    /// An approach x, m, past which the loading force is not smooth (Thornton's first yield, where
    /// the capped pressure sets in): adaptive methods stop there and start a fresh step, so that
    /// no step straddles it and fools its error estimate. `None` for smooth laws.
    fn loading_breakpoint(&self) -> Option<f64> {
        None
    }

    /// Whether the indentation left where the force returns to zero is permanent (a plastic dent:
    /// Thornton's once it has yielded, the proposed model's x_pl) rather than recovered by the
    /// material after separation (a viscoelastic law clamped at F ≥ 0).
    fn residual_is_permanent(&self) -> bool {
        false
    }

    /// Whether F depends on x alone within each phase (a rate-independent hysteresis such as
    /// Thornton's), so that ∮F dx over an impact is exact from [`ForceLaw::stored_energy`]: no
    /// quadrature has to resolve the kink where such a law changes branch.
    fn rate_independent(&self) -> bool {
        false
    }

    /// The energy the contact holds at approach x during `phase`, J: what the solver's energy
    /// guard adds to ½mẋ². Hertz's k·x^{n+1}/(n+1) unless the law's conservative part differs.
    fn stored_energy(&self, x: f64, _phase: Phase) -> f64 {
        let law = self.params().law;
        law.k * x * x * abs_pow_nm1(x, law.n) / (law.n + 1.0)
    }

    /// F(x, ẋ), N: zero out of contact (x ≤ 0), else the law with sign(ẋ) deciding the phase.
    fn force(&self, x: f64, v: f64) -> f64 {
        if x > 0.0 {
            self.phase_force(x, v, Phase::of_velocity(v))
        } else {
            0.0
        }
    }
}

/// |x|^(n−1) with the common exponents specialised (n = 3/2 is x·√x, n = 1 is linear), so the hot
/// loop of the integrators avoids `powf` for spheres.
#[inline]
pub fn abs_pow_nm1(x: f64, n: f64) -> f64 {
    if n == 1.5 {
        x.abs().sqrt()
    } else if n == 1.0 {
        1.0
    } else {
        x.abs().powf(n - 1.0)
    }
}

/// xⁿ continued oddly to x < 0 as x·|x|ⁿ⁻¹ (eq 1's power).
#[inline]
pub fn signed_pow_n(x: f64, n: f64) -> f64 {
    x * abs_pow_nm1(x, n)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn specialised_powers_match_powf() {
        for &x in &[1e-12_f64, 3.7e-6, 0.25, 1.0, 7.5] {
            for &n in &[1.0, 1.081, 1.5] {
                let expect = x.powf(n);
                assert!((signed_pow_n(x, n) / expect - 1.0).abs() < 1e-15, "{x} {n}");
                assert!(
                    (signed_pow_n(-x, n) / expect + 1.0).abs() < 1e-15,
                    "odd in x"
                );
            }
        }
        assert_eq!(signed_pow_n(0.0, 1.5), 0.0);
        assert_eq!(abs_pow_nm1(0.0, 1.0), 1.0);
    }

    #[test]
    fn phase_follows_the_sign_of_velocity() {
        assert_eq!(Phase::of_velocity(0.3), Phase::Loading);
        assert_eq!(Phase::of_velocity(0.0), Phase::Loading);
        assert_eq!(Phase::of_velocity(-1e-300), Phase::Unloading);
    }
}
