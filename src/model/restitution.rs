//! Realised against requested restitution, per law (docs/physics.md §6.4): each law's damping is
//! set from the requested e by its own rule, and the impact says what e it really gives.

use serde::Serialize;

use super::force::{ForceModel, ImpactParams};
use super::impact::{ImpactError, SolveOptions, solve_impact};

/// The requested values of the restitution table.
pub const REQUESTED: [f64; 5] = [0.1, 0.3, 0.5, 0.7, 0.9];

/// One requested e and what the law gives for it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RestitutionPoint {
    pub e_requested: f64,
    /// v_out/v₀, `None` when the solve failed.
    pub e_out: Option<f64>,
    pub error: Option<String>,
}

/// One law's realised e over the requested values.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RestitutionRow {
    pub model: ForceModel,
    pub points: Vec<RestitutionPoint>,
}

/// The e_out of `model` on the scene `params` with its restitution set to `e`.
pub fn realised(
    model: ForceModel,
    params: &ImpactParams,
    e: f64,
    opts: &SolveOptions,
) -> Result<f64, ImpactError> {
    let params = ImpactParams {
        restitution: e,
        ..*params
    };
    Ok(solve_impact(model, &params, opts)?.summary.e_out)
}

/// The realised e of every model in `models` for every requested value.
pub fn table(
    models: &[ForceModel],
    params: &ImpactParams,
    requested: &[f64],
    opts: &SolveOptions,
) -> Vec<RestitutionRow> {
    models
        .iter()
        .map(|&model| RestitutionRow {
            model,
            points: requested
                .iter()
                .map(|&e| match realised(model, params, e, opts) {
                    Ok(e_out) => RestitutionPoint {
                        e_requested: e,
                        e_out: Some(e_out),
                        error: None,
                    },
                    Err(err) => RestitutionPoint {
                        e_requested: e,
                        e_out: None,
                        error: Some(err.to_string()),
                    },
                })
                .collect(),
        })
        .collect()
}
