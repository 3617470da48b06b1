//! Dry friction F = k·xⁿ + P·x·sign(ẋ) (eq 15), P from eq 17 (spheres) or eq 16 (general n).

use crate::model::error::ModelError;
use crate::model::exact::{ExactImpact, dry_friction::dry_friction};

use super::law::{ContactEnd, ForceLaw, Phase, abs_pow_nm1, signed_pow_n};
use super::{ForceModel, ImpactParams};

/// ½·(4/5)^{4/5} = 0.418256…, the constant eq 17 rounds to 0.418 (docs/physics.md §2).
pub const EQ17_CONSTANT: f64 = 0.418_255_821_036_509_3;

/// Tensile cutoffs closer to x = 0 than this fraction of the elastic x_max are not watched for: the
/// energy they would change is below (n−1)/2·(1e-9)² of the impact energy, far below any tolerance,
/// and an event that close to x = 0 cannot be told apart from it.
const NEGLIGIBLE_CUTOFF: f64 = 1e-9;

/// F = k·xⁿ + P·x·sign(ẋ) (eq 15). The solver evaluates it with the phase fixed (sign +1 on
/// loading, −1 on unloading) and never across ẋ = 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DryFriction {
    params: ImpactParams,
    p: f64,
    x_cut: f64,
}

impl DryFriction {
    /// P by eq 17 when n = 3/2, else by eq 16 with the elastic x_max; x* = (P/k)^{1/(n−1)}.
    pub fn new(params: &ImpactParams) -> Self {
        let p = if params.law.n == 1.5 {
            Self::eq17(params)
        } else {
            Self::eq16(params)
        };
        Self::with_p(params, p)
    }

    /// The table's builder: P given, or from e by eq 16/17.
    pub fn build(
        _model: ForceModel,
        params: &ImpactParams,
        p: Option<f64>,
    ) -> Result<Self, ModelError> {
        Ok(match p {
            Some(p) => Self::with_p(params, p),
            None => Self::new(params),
        })
    }

    /// The law with an explicit friction coefficient P, N/m; x* = (P/k)^{1/(n−1)}.
    pub fn with_p(params: &ImpactParams, p: f64) -> Self {
        let (k, n) = (params.law.k, params.law.n);
        let x_e = params.law.max_approach(params.mass, params.v0);
        let x_cut = if n > 1.0 && p > 0.0 {
            (p / k).powf(1.0 / (n - 1.0))
        } else {
            0.0
        };
        let x_cut = if x_cut > NEGLIGIBLE_CUTOFF * x_e {
            x_cut
        } else {
            0.0
        };
        DryFriction {
            params: *params,
            p,
            x_cut,
        }
    }

    /// P = ½·m·v₀²·(1 − e²)/x_max² with the elastic x_max (eq 16), N/m.
    pub fn eq16(params: &ImpactParams) -> f64 {
        let x_e = params.law.max_approach(params.mass, params.v0);
        let e = params.restitution;
        0.5 * params.mass * params.v0 * params.v0 * (1.0 - e * e) / (x_e * x_e)
    }

    /// P = ½·(4/5)^{4/5}·(1 − e²)·(m·k⁴·v₀²)^{1/5} (eq 17, spheres, exact constant), N/m.
    pub fn eq17(params: &ImpactParams) -> f64 {
        let e = params.restitution;
        let (m, k, v0) = (params.mass, params.law.k, params.v0);
        // (m·k⁴·v₀²)^{1/5} as m^{1/5}·k^{4/5}·v₀^{2/5}: k⁴ alone would overflow for stiff contacts.
        EQ17_CONSTANT * (1.0 - e * e) * m.powf(0.2) * k.powf(0.8) * v0.powf(0.4)
    }

    /// The friction coefficient P, N/m.
    pub fn p(&self) -> f64 {
        self.p
    }

    /// Where the unloading force k·xⁿ − P·x turns tensile, m (0: not within reach).
    pub fn tensile_approach(&self) -> f64 {
        self.x_cut
    }

    fn sign(phase: Phase) -> f64 {
        match phase {
            Phase::Loading => 1.0,
            Phase::Unloading => -1.0,
        }
    }
}

impl ForceLaw for DryFriction {
    fn model(&self) -> ForceModel {
        ForceModel::DryFriction
    }

    fn params(&self) -> &ImpactParams {
        &self.params
    }

    /// F = k·xⁿ ± P·x (eq 15 with sign(ẋ) fixed by the phase).
    fn phase_force(&self, x: f64, _v: f64, phase: Phase) -> f64 {
        let law = self.params.law;
        law.k * signed_pow_n(x, law.n) + Self::sign(phase) * self.p * x
    }

    /// ±P·x (eq 15).
    fn dissipative_force(&self, x: f64, _v: f64, phase: Phase) -> f64 {
        Self::sign(phase) * self.p * x
    }

    /// (n·k·xⁿ⁻¹ ± P, 0) (eq 15 differentiated within a phase).
    fn partials(&self, x: f64, _v: f64, phase: Phase) -> (f64, f64) {
        let law = self.params.law;
        (
            law.n * law.k * abs_pow_nm1(x, law.n) + Self::sign(phase) * self.p,
            0.0,
        )
    }

    fn contact_end(&self) -> ContactEnd {
        ContactEnd::ApproachZero
    }

    fn switches_at_max_compression(&self) -> bool {
        self.p > 0.0
    }

    fn may_turn_tensile(&self) -> bool {
        self.x_cut > 0.0
    }

    /// (x − x*)/x*: the sign of the unloading F/x = k·xⁿ⁻¹ − P, which vanishes at x* in closed
    /// form. Linear in x, so a step that carries x through x* and on below 0 cannot hide the
    /// crossing (F/x, continued as k·|x|ⁿ⁻¹ − P, turns positive again below −x*: a dip too
    /// narrow for an event search to see at e ≥ 0.985).
    fn tension(&self, x: f64, _v: f64) -> f64 {
        (x - self.x_cut) / self.x_cut
    }

    fn damping_value(&self) -> Option<f64> {
        Some(self.p)
    }

    fn exact(&self, rtol: f64) -> Option<ExactImpact> {
        dry_friction(&self.params, self.p, self.x_cut, rtol)
    }
}
