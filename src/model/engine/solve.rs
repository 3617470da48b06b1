//! An engine's law solved and calibrated as a law of hertz-tui's table: the same solver
//! ([`solve_law`]) and calibration ([`calibrate_with`]) as every other law (docs/physics.md §7).

use std::ops::RangeInclusive;

use serde::Serialize;

use crate::model::calibrate::calibrate_with;
use crate::model::error::ModelError;
use crate::model::force::{AnyLaw, ForceLaw, ForceModel, ImpactParams};
use crate::model::impact::{SolveOptions, solve_law};
use crate::model::power_law::PowerLaw;

use super::error::EngineError;
use super::{EngineScene, VelocityPoint};

/// What an engine's law gives for one impact, SI units.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct EngineImpact {
    /// Realised restitution v_out/v₀.
    pub e_out: f64,
    /// Peak force, N.
    pub f_max: f64,
    /// Duration of contact, s.
    pub t_contact: f64,
    /// Maximum approach, m.
    pub x_max: f64,
    /// Approach left when contact ends (> 0 where the F ≥ 0 rule ended it), m.
    pub x_residual: f64,
    /// Largest stable step of an explicit integrator, s: h·ω_max < 2 (symplectic Euler, velocity
    /// Verlet) with ω_max = √(max ∂F/∂x / m) at x_max; damping ignored.
    pub dt_stable: f64,
}

/// Tolerance of the engine solves: the promise of [`SolveOptions::rtol`] keeps every number
/// within 1e-10, far below the 1e-8 the translations claim.
const RTOL: f64 = 1e-12;

/// Solves the impact of an engine's law (any row of the law table) with hertz-tui's solver.
pub fn solve(law: &AnyLaw) -> Result<EngineImpact, EngineError> {
    let opts = SolveOptions {
        rtol: RTOL,
        ..SolveOptions::default()
    };
    let s = solve_law(law, &opts)?.summary;
    let p = law.params();
    Ok(EngineImpact {
        e_out: s.e_out,
        f_max: s.f_max,
        t_contact: s.t_contact,
        x_max: s.x_max,
        x_residual: s.x_residual,
        dt_stable: 2.0 / (p.law.tangent_stiffness(s.x_max) / p.mass).sqrt(),
    })
}

/// What the engine's law gives: at the scene's v₀, and its restitution at the scene's
/// [`velocities`](EngineScene::velocities) ([`VELOCITY_FACTORS`](super::VELOCITY_FACTORS)·v₀ by default) with the engine's
/// constants unchanged; `law_at(v₀)` builds the law for an impact at v₀.
pub fn realise(
    scene: &EngineScene,
    law_at: impl Fn(f64) -> Result<AnyLaw, EngineError>,
) -> Result<(EngineImpact, Vec<VelocityPoint>), EngineError> {
    let at_v0 = solve(&law_at(scene.v0)?)?;
    let e_of_v = scene
        .velocities
        .iter()
        .map(|&v0| solve(&law_at(v0)?).map(|r| VelocityPoint { v0, e_out: r.e_out }))
        .collect::<Result<_, _>>()?;
    Ok((at_v0, e_of_v))
}

/// The Hunt–Crossley law (the `hunt-crossley` row) on `elastic` with damping χ for an impact at
/// `v0`: Drake's and Simbody's laws as hertz-tui solves them.
pub fn hunt_crossley(
    scene: &EngineScene,
    elastic: PowerLaw,
    v0: f64,
    chi: f64,
) -> Result<AnyLaw, ModelError> {
    ForceModel::HuntCrossley.law_with_damping(&scene.params(elastic, v0), chi)
}

/// The χ ≥ 0 with which [`hunt_crossley`] on `elastic` realises the scene's e at v₀.
pub fn hunt_crossley_chi(
    engine: &'static str,
    scene: &EngineScene,
    elastic: PowerLaw,
) -> Result<f64, EngineError> {
    calibrated_damping(
        engine,
        ForceModel::HuntCrossley,
        scene,
        elastic,
        0.0..=f64::INFINITY,
        |chi| hunt_crossley(scene, elastic, scene.v0, chi),
    )
}

impl EngineScene {
    /// The impact parameters of the engine's law: the scene's reduced mass and e, the engine's
    /// elastic law, impact velocity `v0`, no plastic indentation (no engine here models one).
    pub fn params(&self, elastic: PowerLaw, v0: f64) -> ImpactParams {
        ImpactParams {
            mass: self.mass,
            law: elastic,
            v0,
            restitution: self.restitution,
            plastic_indentation: 0.0,
            contact: crate::model::force::Contact::Unspecified,
        }
    }
}

/// The damping parameter of `model`'s row that realises the scene's e with `elastic` at v₀, by
/// hertz-tui's calibration ([`calibrate_with`], the law built by `law_with`), within what the
/// engine can express: `range`. Otherwise [`EngineError::Unreachable`] with the e the engine's law
/// realises over that range.
pub fn calibrated_damping(
    engine: &'static str,
    model: ForceModel,
    scene: &EngineScene,
    elastic: PowerLaw,
    range: RangeInclusive<f64>,
    law_with: impl Fn(f64) -> Result<AnyLaw, ModelError>,
) -> Result<f64, EngineError> {
    let params = scene.params(elastic, scene.v0);
    if let Ok(c) = calibrate_with(model, &params, &law_with)
        && range.contains(&c.damping.value)
    {
        return Ok(c.damping.value);
    }
    let e_at = |d: f64| solve(&law_with(d)?).map(|r| r.e_out);
    let (e_lo, e_hi) = (e_at(*range.start())?, e_at(*range.end())?);
    Err(EngineError::Unreachable {
        engine,
        requested: scene.restitution,
        reason: format!(
            "over its damping range the engine's law realises e in [{:.6}, {:.6}]",
            e_lo.min(e_hi),
            e_lo.max(e_hi)
        ),
    })
}
