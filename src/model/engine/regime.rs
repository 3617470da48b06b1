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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::presets::Registry;

    fn steel_at(v0: f64) -> Scene {
        let mut scene = Registry::builtin()
            .and_then(|r| r.scene("steel-sphere-r10-plate"))
            .expect("preset");
        scene.impact.v0 = v0;
        scene
    }

    /// The paper's Table 1 for steel R = 10 mm: yield begins near 0.03 m/s, full plasticity near
    /// 0.33 m/s; Fig. 5's 0.3 m/s lies between.
    #[test]
    fn warns_from_yield_onset_and_says_fully_plastic_above_it() {
        assert_eq!(regime_warnings(&steel_at(0.01)), Ok(Vec::new()));
        let yielding = regime_warnings(&steel_at(0.3)).unwrap();
        let [
            RegimeWarning::YieldBegins {
                v_yield, v_plastic, ..
            },
        ] = yielding[..]
        else {
            panic!("{yielding:?}");
        };
        assert!(v_yield < 0.3 && 0.3 < v_plastic, "{v_yield} {v_plastic}");
        assert!(yielding[0].to_string().starts_with("yield begins"));
        let plastic = regime_warnings(&steel_at(1.0)).unwrap();
        assert!(
            matches!(plastic[0], RegimeWarning::FullyPlastic { .. }),
            "{plastic:?}"
        );
        // A far faster impact also leaves Hertz's small-contact range.
        let extreme = regime_warnings(&steel_at(300.0)).unwrap();
        assert!(
            extreme
                .iter()
                .any(|w| matches!(w, RegimeWarning::OutsideHertz(_))),
            "{extreme:?}"
        );
    }
}
