//! Exact solutions of the impact ODE where mathematics allows (docs/physics.md §3).
//!
//! Elastic Hertz in closed form; the Hunt–Crossley family through its separable energy integral and
//! Lambert W; dry friction through its energy identity. Contact times come from Gauss–Jacobi
//! quadrature of dt = dx/v (or dt = m·dv/F), whose weights absorb the integrands' singularities at
//! the ends of contact (tanh-sinh where the damping nearly stops the bodies).

pub mod dry_friction;
pub mod elastic;
pub mod gauss_jacobi;
pub mod hysteresis;
pub mod quadrature;
pub mod special;

use serde::Serialize;

/// The numbers of an exactly solved impact, SI units.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ExactImpact {
    /// Maximum approach, m.
    pub x_max: f64,
    /// Time of maximum approach (ẋ = 0), s.
    pub t_x_max: f64,
    /// Peak force, N.
    pub f_max: f64,
    /// Time of the peak force, s.
    pub t_f_max: f64,
    /// Approach at the peak force, m.
    pub x_f_max: f64,
    /// Velocity ẋ at the peak force, m/s.
    pub v_f_max: f64,
    /// Duration of contact, s.
    pub t_contact: f64,
    /// Exit speed |ẋ| when contact ends, m/s.
    pub v_out: f64,
    /// Approach left when contact ends, m.
    pub x_residual: f64,
    /// Contact ended by the compressive-only rule (at `x_residual`, with speed `v_out`).
    pub tensile_cutoff: bool,
}

impl ExactImpact {
    /// Every number finite, and all but the peak velocity non-negative: what a caller may rely on
    /// before reporting it.
    pub fn is_valid(&self) -> bool {
        self.v_f_max.is_finite()
            && [
                self.x_max,
                self.t_x_max,
                self.f_max,
                self.t_f_max,
                self.x_f_max,
                self.t_contact,
                self.v_out,
                self.x_residual,
            ]
            .iter()
            .all(|q| q.is_finite() && *q >= 0.0)
    }
}
