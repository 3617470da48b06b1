//! What an engine's law cannot do for a scene: every translation puts an elastic contact law with
//! damping into the engine, so a scene that yields, or leaves Hertz's range, gets numbers that
//! are right for the law and wrong for the bodies (docs/engines.md, "Regime warnings").

use serde::Serialize;
use thiserror::Error;

use crate::model::Scene;
use crate::model::error::ModelError;
use crate::model::pressure::Regime;
use crate::model::warnings::{ModelWarning, scene_warnings};

/// Why a translation's law does not describe the scene's bodies.
#[derive(Debug, Clone, PartialEq, Serialize, Error)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum RegimeWarning {
    /// Yield begins below the surface (p₀ ≥ 1.1·σ_y): the engine's elastic law with damping stands
    /// in for a plastic loss it does not model.
    #[error(
        "yield begins: v₀ = {v0:.4} m/s is above the yield velocity {v_yield:.4} m/s (p₀ = 1.1·σ_y; \
         fully plastic from {v_plastic:.4} m/s): the engine's elastic law with damping reproduces the \
         requested e but not the permanent indentation, nor how e changes with v₀"
    )]
    YieldBegins {
        /// Impact velocity, m/s.
        v0: f64,
        /// Yield begins, m/s.
        v_yield: f64,
        /// Fully plastic, m/s.
        v_plastic: f64,
    },
    /// Fully plastic contact (p₀ ≥ 2.8·σ_y): Hertz's law no longer describes the force.
    #[error(
        "fully plastic: v₀ = {v0:.4} m/s is above {v_plastic:.4} m/s (p₀ = 2.8·σ_y): Hertz's elastic \
         law no longer describes the force; these parameters give the requested e with forces \
         and contact time of an elastic contact that does not happen"
    )]
    FullyPlastic {
        /// Impact velocity, m/s.
        v0: f64,
        /// Fully plastic, m/s.
        v_plastic: f64,
    },
    /// The scene leaves a hypothesis of Hertz's theory (large contact, or the line-contact fit).
    #[error("outside Hertz's range: {0}")]
    OutsideHertz(ModelWarning),
}

/// The warnings of `scene` for an engine translation: its yield regime at v₀ and the scene's own
/// warnings on Hertz's hypotheses.
pub fn regime_warnings(scene: &Scene) -> Result<Vec<RegimeWarning>, ModelError> {
    let q = scene.quasistatic()?;
    let v0 = scene.impact.v0;
    let mut out = match q.regime(v0) {
        Regime::Elastic => Vec::new(),
        Regime::YieldBegins => vec![RegimeWarning::YieldBegins {
            v0,
            v_yield: q.onset.v_yield,
            v_plastic: q.onset.v_plastic,
        }],
        Regime::FullyPlastic => vec![RegimeWarning::FullyPlastic {
            v0,
            v_plastic: q.onset.v_plastic,
        }],
    };
    out.extend(
        scene_warnings(&scene.pair()?, &q)
            .into_iter()
            .map(RegimeWarning::OutsideHertz),
    );
    Ok(out)
}
