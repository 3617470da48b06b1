//! The solver's dimensionless variables X = x/x_e, V = v/v₀, T = t·v₀/x_e, with x_e the elastic
//! x_max (eq 5), so that rtol/atol mean the same thing for every scene.

use crate::model::force::law::signed_pow_n;
use crate::model::force::{ForceLaw, ImpactParams};
use crate::model::ode::State;

/// Reference scales of one impact, SI units.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct Scales {
    /// x_e: the elastic x_max (eq 5), m.
    pub x: f64,
    /// v₀, m/s.
    pub v: f64,
    /// x_e/v₀, s: in these units the elastic contact lasts 2·B(1/(n+1), ½)/(n+1) ≈ 3.2.
    pub t: f64,
    /// k·x_eⁿ: the elastic F_max (eq 6), N.
    pub f: f64,
    /// x_e/(m·v₀²), 1/N: dV/dT = −accel·F.
    pub accel: f64,
    /// The elastic contact time in units of `t` (eq 7, docs/physics.md §3).
    pub t_contact: f64,
    /// Reduced mass m, kg.
    pub mass: f64,
    /// Exponent n.
    pub n: f64,
    /// γ of the solver's second variable W = V + γ·Xᵖ (the scaled w = ẋ + β·xᵖ/m of
    /// [`ForceLaw::impulse_coefficient`]); 0 when it is V itself.
    pub shift: f64,
    /// p of W = V + γ·Xᵖ ([`ForceLaw::impulse_power`]).
    pub shift_power: f64,
}

impl Scales {
    /// Scales of validated `params`.
    pub fn new(params: &ImpactParams) -> Self {
        let (m, v0, law) = (params.mass, params.v0, params.law);
        let x = law.max_approach(m, v0);
        let t = x / v0;
        Scales {
            x,
            v: v0,
            t,
            f: law.force(x),
            accel: x / (m * v0 * v0),
            t_contact: elastic_contact_time(law.n),
            mass: m,
            n: law.n,
            shift: 0.0,
            shift_power: law.n,
        }
    }

    /// Scales of `law`'s validated parameters, with its closed-form damping impulse taken into
    /// the second variable: γ = β·x_eᵖ/(m·v₀).
    pub fn of_law<L: ForceLaw>(law: &L) -> Self {
        let mut sc = Scales::new(law.params());
        let beta = law.impulse_coefficient();
        if beta == 0.0 {
            return sc;
        }
        // β·(x_e·X)ᵖ/(m·v₀) = β·x_eᵖ/(m·v₀)·Xᵖ, and x_eⁿ = F_ref/k.
        let p = law.impulse_power();
        let x_e_p = if p == sc.n {
            sc.f / law.params().law.k
        } else {
            sc.x.powf(p)
        };
        sc.shift = beta * x_e_p / (sc.mass * sc.v);
        sc.shift_power = p;
        sc
    }

    /// These scales with W = V (for methods that read the second variable as ẋ).
    pub fn without_shift(&self) -> Self {
        Scales {
            shift: 0.0,
            ..*self
        }
    }

    /// The scaled velocity V of a solver state (X, W).
    #[inline]
    pub fn velocity(&self, y: &State) -> f64 {
        if self.shift == 0.0 {
            y[1]
        } else {
            y[1] - self.shift * self.shift_pow(y[0])
        }
    }

    /// (X, V) of a solver state (X, W).
    #[inline]
    pub fn xv(&self, y: &State) -> State {
        State::new(y[0], self.velocity(y))
    }

    /// The solver state (X, W) of (X, V).
    #[inline]
    pub fn xw(&self, x: f64, v: f64) -> State {
        State::new(x, v + self.shift * self.shift_pow(x))
    }

    /// Xᵖ of the shift W = V + γ·Xᵖ, continued oddly to X < 0 (as the laws' powers are).
    #[inline]
    pub fn shift_pow(&self, x: f64) -> f64 {
        let p = self.shift_power;
        if p == self.n {
            signed_pow_n(x, p)
        } else if p == 1.25 {
            // Hertz–viscous on a sphere: x^{(n+1)/2} with n = 3/2, two square roots.
            x * x.abs().sqrt().sqrt()
        } else {
            x * x.abs().powf(p - 1.0)
        }
    }

    /// Mechanical energy ½mv² + k·x^{n+1}/(n+1) over ½mv₀², in scaled variables: V² + |X|^{n+1}
    /// (the elastic part uses x_e's definition, k·x_e^{n+1}/(n+1) = ½mv₀²).
    pub fn energy(&self, x: f64, v: f64) -> f64 {
        v * v + x * x * crate::model::force::law::abs_pow_nm1(x, self.n)
    }
}

/// The elastic contact time in units of x_e/v₀: 2·B(1/(n+1), ½)/(n+1) (eq 7, docs/physics.md §3),
/// with the sphere's (4/5)·B(2/5, ½) and the linear spring's π spelled out (no ln Γ per solve).
fn elastic_contact_time(n: f64) -> f64 {
    if n == 1.5 {
        2.943_275_184_324_704_7
    } else if n == 1.0 {
        std::f64::consts::PI
    } else {
        let a = 1.0 / (n + 1.0);
        2.0 * a * crate::model::numeric::beta::beta(a, 0.5)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::numeric::beta::beta;

    #[test]
    fn spelled_out_contact_times_are_the_beta_values() {
        // The constants are exact to the last digit (mpmath: (4/5)·B(2/5, ½) = 2.94327518432470470);
        // the beta through ln Γ, agrees to ~1e-14.
        assert!((elastic_contact_time(1.5) / (0.8 * beta(0.4, 0.5)) - 1.0).abs() < 1e-14);
        assert!((elastic_contact_time(1.0) / beta(0.5, 0.5) - 1.0).abs() < 1e-14);
        let a = 1.0 / 2.2;
        assert_eq!(elastic_contact_time(1.2), 2.0 * a * beta(a, 0.5));
    }
}
