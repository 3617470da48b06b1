//! Realised against requested restitution, per law (docs/physics.md §6.4): each law's damping is
//! set from the requested e by its own rule, and the impact says what e it really gives.
#![warn(missing_docs)]

use serde::Serialize;

use super::error::ModelError;
use super::force::table::Family;
use super::force::{AnyLaw, ForceModel, ImpactParams};
use super::impact::{ImpactError, SolveOptions, solve_impact, solve_law};

/// The requested values of the restitution table.
pub const REQUESTED: [f64; 5] = [0.1, 0.3, 0.5, 0.7, 0.9];

/// One requested e and what the law gives for it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RestitutionPoint {
    /// The requested e the law's damping was set from.
    pub e_requested: f64,
    /// v_out/v₀, `None` when the solve failed.
    pub e_out: Option<f64>,
    /// Why the solve failed, `None` when it did not (JSON writes its message).
    #[serde(serialize_with = "as_message")]
    pub error: Option<ImpactError>,
}

/// An error as its message, for JSON.
fn as_message<S: serde::Serializer>(
    error: &Option<ImpactError>,
    serializer: S,
) -> Result<S::Ok, S::Error> {
    match error {
        Some(e) => serializer.collect_str(e),
        None => serializer.serialize_none(),
    }
}

/// One law's realised e over the requested values.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RestitutionRow {
    /// The law.
    pub model: ForceModel,
    /// One point per requested e, in the order asked.
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
///
/// Hunt–Crossley's rule χ = 3(1 − e)/2 (eq 19) realises, by its exact unloading relation
/// ([`hunt_crossley_restitution`](crate::model::calibrate::hunt_crossley_restitution),
/// docs/physics.md §6.4), 0.581 where 0.3 is asked; the solved table agrees:
///
/// ```
/// use hertz_tui::model::ForceModel;
/// use hertz_tui::model::calibrate::hunt_crossley_restitution;
/// use hertz_tui::model::impact::SolveOptions;
/// use hertz_tui::model::presets::{DEFAULT_SCENE, Registry};
/// use hertz_tui::model::restitution::{REQUESTED, table};
///
/// let scene = Registry::builtin()?.scene(DEFAULT_SCENE)?;
/// let params = scene.impact_params(&scene.quasistatic()?);
/// let models = [ForceModel::Quasistatic, ForceModel::HuntCrossley];
/// let rows = table(&models, &params, &REQUESTED, &SolveOptions::default());
///
/// // Elastic Hertz ignores the request: e_out = 1 throughout.
/// assert!(rows[0].points.iter().all(|p| (p.e_out.unwrap() - 1.0).abs() < 1e-9));
/// for point in &rows[1].points {
///     let exact = hunt_crossley_restitution(1.5 * (1.0 - point.e_requested));
///     assert!((point.e_out.unwrap() - exact).abs() < 1e-6, "{point:?}");
/// }
/// assert_eq!(rows[1].points[1].e_requested, 0.3);
/// assert!((rows[1].points[1].e_out.unwrap() - 0.581).abs() < 1e-3);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
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
                        error: Some(err),
                    },
                })
                .collect(),
        })
        .collect()
}

/// Requested values of the realised-against-requested curve: 0.02 to 0.98.
pub fn requested_grid(points: usize) -> Vec<f64> {
    let n = points.max(2);
    (0..n)
        .map(|i| 0.02 + 0.96 * i as f64 / (n - 1) as f64)
        .collect()
}

/// Impact velocities from v₀/100 to 100·v₀, evenly spaced in log v₀.
pub fn velocity_grid(v0: f64, points: usize) -> Vec<f64> {
    let n = points.max(2);
    (0..n)
        .map(|i| v0 * 10f64.powf(-2.0 + 4.0 * i as f64 / (n - 1) as f64))
        .collect()
}

/// `model` at impact velocity `v0` with the damping coefficient of the scene `params` held
/// fixed, as a material constant would be: the same P, b, γ, c or A, and for the Hunt–Crossley
/// family the same α = χ/v₀ (so χ grows with v₀). Stiffness rules (Kelvin–Voigt's K) follow v₀.
pub fn fixed_coefficient_law(
    model: ForceModel,
    params: &ImpactParams,
    v0: f64,
) -> Result<AnyLaw, ModelError> {
    let at_v0 = ImpactParams { v0, ..*params };
    match model.law(params)?.damping() {
        None => model.law(&at_v0),
        Some(d) => {
            let value = if model.spec().family == Family::HuntCrossley {
                d.value * v0 / params.v0
            } else {
                d.value
            };
            model.law_with_damping(&at_v0, value)
        }
    }
}

/// (e requested, e realised) of `model` over `requested`; failed solves are left out.
pub fn realised_curve(
    model: ForceModel,
    params: &ImpactParams,
    requested: &[f64],
    opts: &SolveOptions,
) -> Vec<(f64, f64)> {
    requested
        .iter()
        .filter_map(|&e| realised(model, params, e, opts).ok().map(|out| (e, out)))
        .collect()
}

/// (v₀, e realised) of `model` with its scene coefficient fixed over `velocities`; failed
/// solves are left out.
pub fn velocity_curve(
    model: ForceModel,
    params: &ImpactParams,
    velocities: &[f64],
    opts: &SolveOptions,
) -> Vec<(f64, f64)> {
    velocities
        .iter()
        .filter_map(|&v0| {
            let law = fixed_coefficient_law(model, params, v0).ok()?;
            let e = solve_law(&law, opts).ok()?.summary.e_out;
            Some((v0, e))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::calibrate::hunt_crossley_restitution;
    use crate::model::scene::tests::fig5_scene;

    /// The Fig. 5 scene's impact (v₀ = 0.3 m/s, e = 0.6).
    fn fig5() -> ImpactParams {
        let scene = fig5_scene();
        scene.impact_params(&scene.quasistatic().unwrap())
    }

    #[test]
    fn a_fixed_hunt_crossley_alpha_loses_more_at_higher_speed() {
        // χ = α·v₀ with α fixed: e(v₀) = e_out(χ) by the exact relation, falling with v₀.
        let p = fig5();
        let alpha = 1.5 * 0.4 / 0.3;
        let vs = velocity_grid(p.v0, 5);
        let curve = velocity_curve(ForceModel::HuntCrossley, &p, &vs, &SolveOptions::default());
        assert_eq!(curve.len(), 5);
        for &(v0, e) in &curve {
            assert!(
                (e - hunt_crossley_restitution(alpha * v0)).abs() < 1e-12,
                "{v0}"
            );
        }
        assert!(curve.windows(2).all(|w| w[0].1 > w[1].1));
        // At the scene's own v₀ the law is the scene's.
        let at_scene = fixed_coefficient_law(ForceModel::DryFriction, &p, p.v0).unwrap();
        assert_eq!(at_scene, ForceModel::DryFriction.law(&p).unwrap());
    }

    #[test]
    fn grids_span_what_they_say() {
        let e = requested_grid(25);
        assert_eq!((e[0], e[24]), (0.02, 0.98));
        let v = velocity_grid(0.3, 9);
        assert!((v[0] / 0.003 - 1.0).abs() < 1e-12 && (v[8] / 30.0 - 1.0).abs() < 1e-12);
        assert!((v[4] / 0.3 - 1.0).abs() < 1e-12);
    }

    #[test]
    fn the_bilateral_kelvin_voigt_curve_is_the_identity() {
        let kv = ForceModel::with_id("kelvin-voigt-tension");
        let grid = requested_grid(7);
        let curve = realised_curve(kv, &fig5(), &grid, &SolveOptions::default());
        assert_eq!(curve.len(), 7);
        assert!(curve.iter().all(|(e, out)| (e - out).abs() < 1e-12));
    }
}
