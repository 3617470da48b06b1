//! The forward model of a trace: a law's F(t) or x(t) over one impact, from the project's impact
//! solver ([`solve_law`]) read on its dense output at the sample times, shifted to the contact
//! start t₀ (docs/fitting.md, Traces).

use serde::Serialize;

use crate::model::error::ModelError;
use crate::model::force::{AnyLaw, ForceLaw, ForceModel, ImpactParams, Phase};
use crate::model::impact::{ImpactError, ImpactSolution, SolveOptions, solve_law};
use crate::model::power_law::PowerLaw;

use super::data::TraceQuantity;

/// What a displacement trace reads outside contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Outside {
    /// The approach of the bodies' centres in free flight: x = v₀·(t − t₀) < 0 before contact,
    /// x_res − v_out·(t − t₀ − t_c) after it (a vibrometer or a camera on the impactor).
    #[default]
    FreeFlight,
    /// Zero outside contact (a gauge that reads the indentation only while the bodies touch).
    Zero,
}

/// The parameters of one forward evaluation, SI: the law F = k·xⁿ… (eq 1) with its damping, the
/// impact velocity and the contact start.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TraceParams {
    /// Stiffness k, N/mⁿ (eq 1).
    pub k: f64,
    /// Exponent n (eq 1).
    pub n: f64,
    /// Impact velocity v₀, m/s.
    pub v0: f64,
    /// The law's damping parameter in its table unit; `None` for a law without one.
    pub damping: Option<f64>,
    /// Contact start t₀ on the recording's clock, s.
    pub t0: f64,
}

/// The law's impact for `p` on the scene `base` (mass, contact, e and x_pl kept), solved.
pub fn solve_trace_impact(
    base: &ImpactParams,
    model: ForceModel,
    p: &TraceParams,
    opts: &SolveOptions,
) -> Result<ImpactSolution, ImpactError> {
    solve_law(&law_of(base, model, p)?, opts)
}

/// The force the law of `p` exerts at first touch (x = 0, ẋ = v₀), N: nonzero where it jumps
/// there (Kelvin–Voigt's c·v₀), which a sampled trace can place only between two samples.
pub fn force_at_touch(
    base: &ImpactParams,
    model: ForceModel,
    p: &TraceParams,
) -> Result<f64, ImpactError> {
    Ok(law_of(base, model, p)?.phase_force(0.0, p.v0, Phase::Loading))
}

/// The law of `p` on the scene `base` (mass, contact, e and x_pl kept).
fn law_of(base: &ImpactParams, model: ForceModel, p: &TraceParams) -> Result<AnyLaw, ModelError> {
    let params = ImpactParams {
        law: PowerLaw::new(p.k, p.n)?,
        v0: p.v0,
        ..*base
    };
    match p.damping {
        Some(d) => model.law_with_damping(&params, d),
        None => model.law(&params),
    }
}

/// `quantity` of the solved impact of `p` at each of `times` (s, recording clock), contact
/// starting at `p.t0`: the dense output within contact; outside it zero force, and for displacement the free
/// flight at v₀ before and v_out after, or zero ([`Outside`]).
pub fn sample_trace(
    solution: &ImpactSolution,
    quantity: TraceQuantity,
    outside: Outside,
    p: &TraceParams,
    times: &[f64],
) -> Vec<f64> {
    let traj = &solution.trajectory;
    let s = &solution.summary;
    let t_end = traj.t_end();
    let (t0, v0) = (p.t0, p.v0);
    times
        .iter()
        .map(|&t| {
            let tau = t - t0;
            let inside = (0.0..=t_end).contains(&tau);
            match (quantity, inside, outside) {
                (TraceQuantity::Force, true, _) => traj.at(tau).f,
                (TraceQuantity::Displacement, true, _) => traj.at(tau).x,
                (TraceQuantity::Force, false, _) | (_, false, Outside::Zero) => 0.0,
                (TraceQuantity::Displacement, false, Outside::FreeFlight) => {
                    if tau < 0.0 {
                        v0 * tau
                    } else {
                        s.x_residual - s.v_out * (tau - t_end)
                    }
                }
            }
        })
        .collect()
}

/// The forward model: [`solve_trace_impact`] then [`sample_trace`].
pub fn trace_forward(
    base: &ImpactParams,
    model: ForceModel,
    p: &TraceParams,
    quantity: TraceQuantity,
    outside: Outside,
    times: &[f64],
    opts: &SolveOptions,
) -> Result<Vec<f64>, ImpactError> {
    let solution = solve_trace_impact(base, model, p, opts)?;
    Ok(sample_trace(&solution, quantity, outside, p, times))
}
