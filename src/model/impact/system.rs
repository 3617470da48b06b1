//! m·ẍ = −F(x, ẋ) as a first-order system in scaled variables, with the energy guard.
//!
//! The state is (X, W) with W = V + γ·Xᵖ ([`Scales::shift`]): for the proposed model (p = n) and
//! Hertz–viscous (p = (n+1)/2) the damping impulse is taken into W, whose rate is then the elastic
//! force alone; for every other law γ = 0 and W = V.

use nalgebra::Matrix2;

use crate::model::force::law::{abs_pow_nm1, signed_pow_n};
use crate::model::force::{ForceLaw, Phase};
use crate::model::ode::{OdeSystem, State};

use super::scale::Scales;

/// Mechanical energy may grow to this multiple of ½mv₀² before the solve is stopped. Every law here
/// conserves or dissipates energy, so growth is the integrator's doing; 50 % leaves room to report
/// moderate growth honestly (e.g. explicit Euler's e_out > 1) and stops a blow-up early.
pub const ENERGY_LIMIT: f64 = 1.5;

/// dX/dT = V, dV/dT = −(x_e/(m·v₀²))·F(x_e·X, v₀·V) in one phase of the impact; with γ ≠ 0,
/// dX/dT = W − γ·Xᵖ, dW/dT = −(x_e/(m·v₀²))·k·xⁿ (the damping's rate p·γ·Xᵖ⁻¹·V cancels it exactly).
pub(crate) struct ImpactSystem<'a, L> {
    pub law: &'a L,
    pub phase: Phase,
    pub scales: Scales,
    /// Force evaluations so far (rhs calls, including those made for finite-difference Jacobians).
    pub force_evals: usize,
    /// Set when the energy guard stopped the integration: the growth as a fraction of ½mv₀².
    pub growth: Option<f64>,
    /// X_off: the state's first component is X − X_off (shift = 0 only), so that the step control
    /// weighs errors against the span travelled rather than against x itself.
    pub x_offset: f64,
}

impl<'a, L: ForceLaw> ImpactSystem<'a, L> {
    pub fn new(law: &'a L, phase: Phase, scales: Scales) -> Self {
        ImpactSystem {
            law,
            phase,
            scales,
            force_evals: 0,
            growth: None,
            x_offset: 0.0,
        }
    }
}

impl<L: ForceLaw> OdeSystem for ImpactSystem<'_, L> {
    #[inline]
    fn rhs(&mut self, _t: f64, y: &State) -> State {
        self.force_evals += 1;
        let sc = &self.scales;
        if sc.shift == 0.0 {
            let f = self
                .law
                .phase_force((y[0] + self.x_offset) * sc.x, y[1] * sc.v, self.phase);
            State::new(y[1], -sc.accel * f)
        } else {
            // k·xⁿ/F_ref = Xⁿ, and accel·F_ref = (n+1)/2.
            let xn = signed_pow_n(y[0], sc.n);
            let xp = if sc.shift_power == sc.n {
                xn
            } else {
                sc.shift_pow(y[0])
            };
            State::new(y[1] - sc.shift * xp, -sc.accel * sc.f * xn)
        }
    }

    /// [[0, 1], [−accel·x_e·∂F/∂x, −accel·v₀·∂F/∂ẋ]] from the law's partials, taken at
    /// X ≥ 10⁻³: the proposed model's ∂F/∂x ∝ xⁿ⁻² is unbounded at first contact, and a Newton
    /// matrix built from it there stalls Radau5; the Jacobian only steers Newton, so a bounded
    /// stand-in costs nothing in accuracy.
    fn jacobian(&mut self, _t: f64, y: &State) -> Matrix2<f64> {
        let sc = &self.scales;
        let x = (y[0] + self.x_offset).max(1e-3);
        if sc.shift == 0.0 {
            let (fx, fv) = self.law.partials(x * sc.x, y[1] * sc.v, self.phase);
            Matrix2::new(0.0, 1.0, -sc.accel * sc.x * fx, -sc.accel * sc.v * fv)
        } else {
            let dxn = sc.n * abs_pow_nm1(x, sc.n);
            let dxp = sc.shift_power * sc.shift_pow(x) / x;
            Matrix2::new(-sc.shift * dxp, 1.0, -sc.accel * sc.f * dxn, 0.0)
        }
    }

    fn check(&mut self, _t: f64, y: &State) -> Result<(), String> {
        // ½mẋ² plus what the law stores, over ½mv₀²: Hertz's k·x^{n+1}/(n+1) for most laws.
        let sc = &self.scales;
        let v = sc.velocity(y);
        let stored = self
            .law
            .stored_energy((y[0] + self.x_offset) * sc.x, self.phase);
        let energy = v * v + stored / (0.5 * sc.mass * sc.v * sc.v);
        if energy > ENERGY_LIMIT {
            self.growth = Some(energy - 1.0);
            Err(format!(
                "mechanical energy grew by {:.1} % of the impact energy",
                100.0 * (energy - 1.0)
            ))
        } else {
            Ok(())
        }
    }
}
