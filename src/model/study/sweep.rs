//! Parameter sweeps: one scene key varied over a range, every point solved (the paper's Fig. 2, and more).

use rayon::prelude::*;
use serde::Serialize;
use thiserror::Error;

use crate::model::force::ForceModel;
use crate::model::force::ImpactParams;
use crate::model::impact::{
    ImpactError, ImpactSummary, SimilarImpact, SolveOptions, solve_impact, solve_law,
};
use crate::model::quasistatic::ContactGeometry;
use crate::model::scene::{Scene, SceneBodies};
use crate::model::scene_fit::{FittedLaw, fitted_law_for};
use crate::model::scene_key::{BodyField, BodyIndex, SceneKey, SceneKeyError};

/// What to sweep and how.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepSpec {
    pub key: SceneKey,
    pub from: f64,
    pub to: f64,
    pub points: usize,
    /// Geometric spacing instead of linear.
    pub log: bool,
    pub models: Vec<ForceModel>,
    pub options: SolveOptions,
}

/// A sweep that cannot start.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SweepError {
    #[error("--points must be at least 2, got {0}")]
    TooFewPoints(usize),
    #[error("sweep bounds must be finite, got {from} … {to}")]
    NonFiniteBounds { from: f64, to: f64 },
    #[error("a logarithmic sweep needs bounds of one sign, non-zero; got {from} … {to}")]
    LogBounds { from: f64, to: f64 },
    #[error(transparent)]
    Key(#[from] SceneKeyError),
}

/// The quasistatic numbers of one sweep point.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct QuasistaticPoint {
    pub p_max: f64,
    /// Radius of the contact circle (spheres), m.
    pub contact_radius: Option<f64>,
    /// Half-width of the contact strip (cylinders), m.
    pub half_width: Option<f64>,
    pub v_yield: f64,
    pub v_plastic: f64,
}

/// One model's numbers at one sweep point; `error` set when the solve failed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ImpactPoint {
    pub model: ForceModel,
    pub x_max: Option<f64>,
    pub f_max: Option<f64>,
    pub t_contact: Option<f64>,
    pub v_out: Option<f64>,
    pub e_out: Option<f64>,
    pub error: Option<String>,
}

/// One row of a sweep.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SweepRow {
    /// The swept parameter's value, SI.
    pub value: f64,
    /// `None` with `error` set when the scene is invalid at this value.
    pub quasistatic: Option<QuasistaticPoint>,
    pub impacts: Vec<ImpactPoint>,
    pub error: Option<String>,
}

/// The parameter values of the sweep, in order.
pub fn sweep_values(spec: &SweepSpec) -> Result<Vec<f64>, SweepError> {
    let (from, to, n) = (spec.from, spec.to, spec.points);
    if n < 2 {
        return Err(SweepError::TooFewPoints(n));
    }
    if !from.is_finite() || !to.is_finite() {
        return Err(SweepError::NonFiniteBounds { from, to });
    }
    if spec.log && (from * to <= 0.0) {
        return Err(SweepError::LogBounds { from, to });
    }
    let last = (n - 1) as f64;
    Ok((0..n)
        .map(|i| {
            let s = i as f64 / last;
            if spec.log {
                from * (to / from).powf(s)
            } else {
                from + (to - from) * s
            }
        })
        .collect())
}

/// Solves every point of the sweep in parallel; rows come out in parameter order.
pub fn sweep(base: &Scene, spec: &SweepSpec) -> Result<Vec<SweepRow>, SweepError> {
    sweep_until(base, spec, &|| false).map(Option::unwrap_or_default)
}

/// [`sweep`] that gives up once `stop` returns true (checked before each point): `None` then, as an
/// interactive caller whose request was superseded wants no partial sweep.
pub fn sweep_until(
    base: &Scene,
    spec: &SweepSpec,
    stop: &(dyn Fn() -> bool + Sync),
) -> Result<Option<Vec<SweepRow>>, SweepError> {
    // Fail early on a key that does not apply to this scene's shapes.
    let values = check(base, spec)?;
    let plan = SweepPlan::new(base, spec);
    Ok(values
        .into_par_iter()
        .map(|value| (!stop()).then(|| plan.point(value)))
        .collect())
}

/// Checks that the sweep can start: its values are valid and its key applies to `base`'s shapes.
pub fn check(base: &Scene, spec: &SweepSpec) -> Result<Vec<f64>, SweepError> {
    let values = sweep_values(spec)?;
    spec.key.set(&mut base.clone(), values[0])?;
    Ok(values)
}

/// A sweep ready to be solved point by point. When its key is an impact condition (v₀, e, x_pl)
/// the bodies are evaluated once for every point: the numbers are the same as re-evaluating the
/// scene at each point, which a sweep of a body's key does. The similar laws are solved once, on
/// the base scene, and scaled to every point with its n and e (docs/physics.md §6.9).
pub struct SweepPlan<'a> {
    base: &'a Scene,
    spec: &'a SweepSpec,
    /// The base scene's bodies, when the key leaves them unchanged.
    bodies: Option<SceneBodies>,
    /// Per model of the spec, its impact on the base scene when the law is similar (not for a
    /// fitted scene, whose e follows the point).
    similar: Vec<Option<SimilarImpact>>,
}

impl<'a> SweepPlan<'a> {
    pub fn new(base: &'a Scene, spec: &'a SweepSpec) -> Self {
        let mut impact = base.impact;
        let bodies = spec
            .key
            .impact_condition(&mut impact)
            .map(|_| SceneBodies::of(base));
        let params = base
            .quasistatic()
            .ok()
            .filter(|_| base.fit.is_none())
            .map(|qs| base.impact_params(&qs));
        let similar = spec
            .models
            .iter()
            .map(|&model| {
                let params = params.as_ref()?;
                SimilarImpact::solve(model, params, &spec.options)?.ok()
            })
            .collect();
        SweepPlan {
            base,
            spec,
            bodies,
            similar,
        }
    }

    /// One point of the sweep: the scene with the key set to `value`, its quasistatic numbers and
    /// every model's impact (or the error that stopped them).
    pub fn point(&self, value: f64) -> SweepRow {
        let invalid = |error: String| SweepRow {
            value,
            quasistatic: None,
            impacts: Vec::new(),
            error: Some(error),
        };
        let mut impact = self.base.impact;
        let estimate = match (&self.bodies, self.spec.key.impact_condition(&mut impact)) {
            (Some(bodies), Some(condition)) => {
                *condition = value;
                bodies.quasistatic(&impact)
            }
            _ => {
                let mut scene = self.base.clone();
                if let Err(e) = self.spec.key.set(&mut scene, value) {
                    return invalid(e.to_string());
                }
                impact = scene.impact;
                scene.quasistatic()
            }
        };
        let qs = match estimate {
            Ok(qs) => qs,
            Err(e) => return invalid(e.to_string()),
        };
        let mut params = impact.params(&qs);
        // A fitted scene's e follows the swept scene as the data says (docs/fitting.md).
        if let Some(fit) = &self.base.fit {
            if self.spec.key == SceneKey::Restitution {
                return invalid("impact.restitution is set by the scene's [fit]".into());
            }
            match fit.restitution_at(&params) {
                Ok(e) => params.restitution = e,
                Err(e) => return invalid(format!("[fit] {}: {e}", fit.kind)),
            }
        }
        let (contact_radius, half_width) = match qs.geometry {
            ContactGeometry::Point { contact_radius } => (Some(contact_radius), None),
            ContactGeometry::Line { half_width, .. } => (None, Some(half_width)),
        };
        let impacts = self
            .spec
            .models
            .iter()
            .zip(&self.similar)
            .map(|(&model, similar)| {
                let solved = match similar.as_ref().and_then(|s| s.at(&params)) {
                    Some(scaled) => scaled,
                    None => solve(model, &params, self.base.fit.as_ref(), &self.spec.options),
                };
                impact_point(model, solved)
            })
            .collect();
        SweepRow {
            value,
            quasistatic: Some(QuasistaticPoint {
                p_max: qs.p_max,
                contact_radius,
                half_width,
                v_yield: qs.onset.v_yield,
                v_plastic: qs.onset.v_plastic,
            }),
            impacts,
            error: None,
        }
    }
}

/// `model`'s impact under `params` (the fitted law with its constant where `fit` is its).
fn solve(
    model: ForceModel,
    params: &ImpactParams,
    fit: Option<&FittedLaw>,
    options: &SolveOptions,
) -> Result<ImpactSummary, ImpactError> {
    let solved = match fitted_law_for(fit, model, params) {
        Ok(Some(law)) => solve_law(&law, options),
        Ok(None) => solve_impact(model, params, options),
        Err(e) => Err(e.into()),
    };
    solved.map(|solution| solution.summary)
}

/// The row entry of `model`'s impact, or of the error that stopped it.
fn impact_point(model: ForceModel, solved: Result<ImpactSummary, ImpactError>) -> ImpactPoint {
    match solved {
        Ok(s) => ImpactPoint {
            model,
            x_max: Some(s.x_max),
            f_max: Some(s.f_max),
            t_contact: Some(s.t_contact),
            v_out: Some(s.v_out),
            e_out: Some(s.e_out),
            error: None,
        },
        Err(e) => ImpactPoint {
            model,
            x_max: None,
            f_max: None,
            t_contact: None,
            v_out: None,
            e_out: None,
            error: Some(e.to_string()),
        },
    }
}

/// The swept interval and its spacing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SweepRange {
    pub from: f64,
    pub to: f64,
    pub log: bool,
}

/// The key's value in `scene`, with a derived mass as its value (`None`: the key does not apply).
pub fn value_of(key: SceneKey, scene: &Scene) -> Option<f64> {
    let value = match key {
        SceneKey::Body(index, BodyField::Mass) => Some(match index {
            BodyIndex::One => scene.body1.mass(),
            BodyIndex::Two => scene.body2.mass(),
        }),
        _ => key.get(scene),
    }?;
    // A plane's mass is infinite: there is nothing to sweep.
    value.is_finite().then_some(value)
}

/// The keys a sweep of `scene` can vary, in [`SceneKey::all`] order.
pub fn sweepable_keys(scene: &Scene) -> Vec<SceneKey> {
    SceneKey::all()
        .into_iter()
        .filter(|&k| value_of(k, scene).is_some())
        .collect()
}

/// A range around the scene's value: v₀/100 … 10·v₀ on a log scale for v₀, a decade either side
/// for sizes, masses and moduli, the whole admissible interval for e and ν, 0 … 2·x_pl for x_pl.
pub fn default_range(key: SceneKey, scene: &Scene) -> Option<SweepRange> {
    let value = value_of(key, scene)?;
    let range = |from, to, log| SweepRange { from, to, log };
    Some(match key {
        SceneKey::V0 => range(value / 100.0, value * 10.0, true),
        SceneKey::Restitution => range(0.05, 1.0, false),
        SceneKey::PlasticIndentation if value > 0.0 => range(0.0, 2.0 * value, false),
        SceneKey::PlasticIndentation => range(0.0, 1e-5, false),
        SceneKey::Body(_, BodyField::PoissonRatio) => range(0.0, 0.49, false),
        SceneKey::Body(..) => range(value / 10.0, value * 10.0, true),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec(from: f64, to: f64, points: usize, log: bool) -> SweepSpec {
        SweepSpec {
            key: SceneKey::V0,
            from,
            to,
            points,
            log,
            models: Vec::new(),
            options: SolveOptions::default(),
        }
    }

    #[test]
    fn linear_and_log_spacing_hit_both_ends() {
        let lin = sweep_values(&spec(0.1, 0.5, 5, false)).unwrap();
        assert_eq!(lin.len(), 5);
        assert!((lin[2] - 0.3).abs() < 1e-15);
        assert_eq!(lin[4], 0.5);
        let log = sweep_values(&spec(1e-3, 1e1, 5, true)).unwrap();
        assert!((log[1] / 1e-2 - 1.0).abs() < 1e-12);
        assert!((log[4] / 10.0 - 1.0).abs() < 1e-12);
    }

    /// On a scene with a fitted Hunt–Crossley a, a v₀ sweep's e falls as the fit says: the fitted
    /// law's e_out is e_HC(a·v₀) at every point, and the scene's e follows (the proposed model
    /// sets its damping from it); sweeping e itself is refused point by point.
    #[test]
    fn a_fitted_scene_sweeps_v0_with_e_from_its_fit() {
        use crate::model::calibrate::hunt_crossley_restitution;
        use crate::model::fit::Candidate;
        let mut scene = crate::model::scene::tests::fig5_scene();
        scene.fit = Some(FittedLaw::new(
            Candidate::Law(ForceModel::HuntCrossley),
            2.0,
        ));
        let mut spec = spec(0.1, 1.0, 3, true);
        spec.models = vec![ForceModel::HuntCrossley];
        let rows = sweep(&scene, &spec).unwrap();
        for row in &rows {
            let e = rows_e(row);
            assert!(
                (e - hunt_crossley_restitution(2.0 * row.value)).abs() < 1e-6,
                "{}",
                row.value
            );
        }
        assert!(rows_e(&rows[0]) > rows_e(&rows[2]));
        let mut by_e = spec.clone();
        by_e.key = SceneKey::Restitution;
        by_e.from = 0.3;
        by_e.to = 0.9;
        by_e.log = false;
        let rows = sweep(&scene, &by_e).unwrap();
        assert!(
            rows.iter()
                .all(|r| r.error.as_deref()
                    == Some("impact.restitution is set by the scene's [fit]"))
        );
    }

    fn rows_e(row: &SweepRow) -> f64 {
        row.impacts[0].e_out.unwrap()
    }

    #[test]
    fn a_stopped_sweep_gives_nothing_and_an_unstopped_one_every_row() {
        let scene = crate::model::scene::tests::fig5_scene();
        let mut spec = spec(0.01, 1.0, 4, true);
        spec.models = vec![ForceModel::Quasistatic];
        assert_eq!(sweep_until(&scene, &spec, &|| true), Ok(None));
        let rows = sweep_until(&scene, &spec, &|| false).unwrap().unwrap();
        assert_eq!(rows.len(), 4);
        assert!(
            rows.iter()
                .all(|r| r.impacts.len() == 1 && r.error.is_none())
        );
    }

    #[test]
    fn impact_keys_reuse_the_bodies_with_the_numbers_of_a_scene_evaluated_afresh() {
        use crate::model::body::Shape;
        let sphere = crate::model::scene::tests::fig5_scene();
        let mut cylinder = sphere.clone();
        cylinder.body1.shape = Shape::Cylinder {
            radius: 0.02,
            length: 0.1,
        };
        cylinder.body1.mass = Some(1.0);
        // Each with invalid values: v₀ ≤ 0, e > 1, x_pl < 0, and a cylinder beyond eq 13/14 at 1e6 m/s.
        let cases = [
            (&sphere, SceneKey::V0, vec![-0.1, 1e-3, 0.3, 2.0]),
            (&sphere, SceneKey::Restitution, vec![0.05, 0.6, 1.0, 1.5]),
            (
                &sphere,
                SceneKey::PlasticIndentation,
                vec![-1e-6, 0.0, 2.3e-6],
            ),
            (&cylinder, SceneKey::V0, vec![1e-3, 1.0, 1e6]),
            (&cylinder, SceneKey::Restitution, vec![0.3, 1.2]),
        ];
        for (scene, key, values) in cases {
            let mut spec = spec(0.1, 1.0, 2, false);
            spec.key = key;
            spec.models = vec![ForceModel::Quasistatic, ForceModel::HuntCrossley];
            let plan = SweepPlan::new(scene, &spec);
            assert!(plan.bodies.is_some(), "{key:?}");
            let afresh = SweepPlan {
                bodies: None,
                ..SweepPlan::new(scene, &spec)
            };
            let mut failures = 0;
            for value in values {
                let row = plan.point(value);
                assert_eq!(row, afresh.point(value), "{key:?} = {value}");
                failures += usize::from(row.error.is_some());
            }
            assert_eq!(failures, 1, "{key:?}: one invalid value each");
        }
    }

    /// A v₀ sweep over three decades (and one over the sphere's radius) with every law: the
    /// similar laws, scaled from one solve on the base scene, equal direct solves at each point
    /// to 1e-12 relative (their solver's own error is 1e-8), so the scaling adds nothing to it;
    /// and the plan scales exactly the laws the table calls similar.
    #[test]
    fn a_sweep_scales_the_similar_laws_to_the_numbers_of_direct_solves() {
        let scene = crate::model::scene::tests::fig5_scene();
        let mut v0 = spec(0.001, 3.0, 40, true);
        v0.models = ForceModel::ALL.to_vec();
        let mut radius = v0.clone();
        radius.key = SceneKey::Body(BodyIndex::One, BodyField::Radius);
        (radius.from, radius.to, radius.points) = (1e-3, 0.1, 15);
        for spec in [v0, radius] {
            let plan = SweepPlan::new(&scene, &spec);
            let scaled: Vec<_> = (spec.models.iter().zip(&plan.similar))
                .filter_map(|(m, s)| s.as_ref().map(|_| *m))
                .collect();
            let similar: Vec<_> = (spec.models.iter().copied())
                .filter(|m| m.spec().similar)
                .collect();
            assert_eq!(scaled, similar);
            assert!(scaled.len() >= 5, "{scaled:?}");
            for value in sweep_values(&spec).unwrap() {
                let row = plan.point(value);
                let mut at = scene.clone();
                spec.key.set(&mut at, value).unwrap();
                let params = at.impact_params(&at.quasistatic().unwrap());
                for point in &row.impacts {
                    let direct = solve_impact(point.model, &params, &spec.options)
                        .unwrap()
                        .summary;
                    for (got, want) in [
                        (point.x_max, direct.x_max),
                        (point.f_max, direct.f_max),
                        (point.t_contact, direct.t_contact),
                        (point.v_out, direct.v_out),
                        (point.e_out, direct.e_out),
                    ] {
                        let got = got.unwrap();
                        assert!(
                            (got - want).abs() <= 1e-12 * want.abs(),
                            "{:?} = {value}: {} {got} against {want}",
                            spec.key,
                            point.model.name()
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn bad_specs_are_refused() {
        assert_eq!(
            sweep_values(&spec(0.1, 0.5, 1, false)),
            Err(SweepError::TooFewPoints(1))
        );
        assert!(matches!(
            sweep_values(&spec(0.0, 1.0, 5, true)),
            Err(SweepError::LogBounds { .. })
        ));
        assert!(matches!(
            sweep_values(&spec(f64::NAN, 1.0, 5, false)),
            Err(SweepError::NonFiniteBounds { .. })
        ));
    }
}
