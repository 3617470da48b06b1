//! `hertz-tui solve`: the quasistatic estimate and one impact solve per force model.

use serde::Serialize;

use crate::format::recommendation;
use crate::model::force::Damping;
use crate::model::impact::{self, ImpactError, ImpactSolution, SolveOptions, TensileCutoff};
use crate::model::presets::Registry;
use crate::model::recommend::recommend;
use crate::model::scene_fit::{FittedLaw, scene_law};
use crate::model::warnings::{ModelWarning, impact_warnings, scene_warnings};
use crate::model::{ForceModel, ImpactParams, Quasistatic, Scene};

use super::args::{SceneSelection, SolveArgs};
use super::error::CliError;

/// Everything `solve` computed; serialized as the JSON output.
#[derive(Debug, Serialize)]
pub struct SolveReport {
    pub scene: Scene,
    pub quasistatic: Quasistatic,
    /// The simplest law the scene needs, the others that fit, and why in one line.
    pub recommendation: RecommendationRow,
    pub impacts: Vec<ImpactRow>,
    /// Results to read with care: the scene outside Hertz's hypotheses, an ill-conditioned number.
    pub warnings: Vec<WarningRow>,
}

/// One [`ModelWarning`], with its text.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WarningRow {
    pub message: String,
    #[serde(flatten)]
    pub warning: ModelWarning,
}

impl From<ModelWarning> for WarningRow {
    fn from(warning: ModelWarning) -> Self {
        WarningRow {
            message: warning.to_string(),
            warning,
        }
    }
}

/// The model layer's recommendation as JSON reports it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RecommendationRow {
    pub model: ForceModel,
    pub fits: Vec<ForceModel>,
    pub why: String,
}

/// One force model's impact, or the reason it failed (`error`); numbers are SI.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ImpactRow {
    pub model: ForceModel,
    /// The path actually used (`exact`, `dopri5`, …), or the one requested if the solve failed.
    pub method: String,
    pub x_max: Option<f64>,
    pub f_max: Option<f64>,
    pub t_contact: Option<f64>,
    pub v_out: Option<f64>,
    /// The scene's restitution e, which the law's damping was set from (or calibrated to).
    pub e_requested: f64,
    /// The realised restitution v_out/v₀.
    pub e_out: Option<f64>,
    /// The law's damping parameter as used (`None` for elastic Hertz).
    pub damping: Option<DampingUsed>,
    /// Whether the damping was calibrated so that e_out = e_requested (`--calibrate`).
    pub calibrated: bool,
    /// Whether the law is the scene's `[fit]` law, solved with its fitted constant at v₀.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub fitted: bool,
    /// Why `--calibrate` could not calibrate this law (the row then uses the scene's damping).
    pub calibration_error: Option<String>,
    pub x_residual: Option<f64>,
    pub energy_dissipated: Option<f64>,
    pub energy_residual: Option<f64>,
    pub steps: Option<usize>,
    pub rejected_steps: Option<usize>,
    pub force_evals: Option<usize>,
    /// Time of maximum compression and of the force peak, s.
    pub t_x_max: Option<f64>,
    pub t_f_max: Option<f64>,
    /// Where the compressive-only rule ended contact, if it fired.
    pub tensile_cutoff: Option<TensileCutoff>,
    pub error: Option<String>,
}

/// A damping parameter with its name and unit, as JSON reports it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DampingUsed {
    /// Its key, e.g. `chi`, `gamma`, `p`, `b`, `c`.
    pub parameter: &'static str,
    pub symbol: &'static str,
    pub value: f64,
    /// SI unit; `1` for a pure number.
    pub unit: &'static str,
}

impl From<Damping> for DampingUsed {
    fn from(d: Damping) -> Self {
        DampingUsed {
            parameter: d.param.key,
            symbol: d.param.symbol,
            value: d.value,
            unit: d.param.unit,
        }
    }
}

impl ImpactRow {
    fn new(
        model: ForceModel,
        params: &ImpactParams,
        requested: &SolveOptions,
        calibrate: bool,
        fit: Option<&FittedLaw>,
        warnings: &mut Vec<WarningRow>,
    ) -> Self {
        let (law, calibration, fitted) = match scene_law(model, params, calibrate, fit) {
            Ok(found) => found,
            Err(e) => return Self::from_result(model, params.restitution, requested, Err(&e)),
        };
        let result = impact::solve_law(&law, requested);
        if let Ok(solution) = &result {
            warnings.extend(
                impact_warnings(params, &solution.summary)
                    .into_iter()
                    .map(WarningRow::from),
            );
        }
        let mut row = Self::from_result(model, params.restitution, requested, result.as_ref());
        row.damping = law.damping().map(DampingUsed::from);
        row.fitted = fitted;
        match calibration {
            Ok(done) => row.calibrated = done,
            Err(why) => row.calibration_error = Some(why.to_string()),
        }
        row
    }

    fn from_result(
        model: ForceModel,
        e_requested: f64,
        requested: &SolveOptions,
        result: Result<&ImpactSolution, &ImpactError>,
    ) -> Self {
        match result {
            Ok(solution) => {
                let s = &solution.summary;
                ImpactRow {
                    model,
                    method: s.method.to_string(),
                    x_max: Some(s.x_max),
                    f_max: Some(s.f_max),
                    t_contact: Some(s.t_contact),
                    v_out: Some(s.v_out),
                    e_requested,
                    e_out: Some(s.e_out),
                    damping: None,
                    calibrated: false,
                    fitted: false,
                    calibration_error: None,
                    x_residual: Some(s.x_residual),
                    energy_dissipated: Some(s.energy_dissipated),
                    energy_residual: Some(s.energy_residual),
                    steps: Some(s.steps),
                    rejected_steps: Some(s.rejected_steps),
                    force_evals: Some(s.force_evals),
                    t_x_max: Some(s.t_x_max),
                    t_f_max: Some(s.t_f_max),
                    tensile_cutoff: s.tensile_cutoff,
                    error: None,
                }
            }
            Err(e) => ImpactRow {
                model,
                method: requested.method.to_string(),
                x_max: None,
                f_max: None,
                t_contact: None,
                v_out: None,
                e_requested,
                e_out: None,
                damping: None,
                calibrated: false,
                fitted: false,
                calibration_error: None,
                x_residual: None,
                energy_dissipated: None,
                energy_residual: None,
                steps: None,
                rejected_steps: None,
                force_evals: None,
                t_x_max: None,
                t_f_max: None,
                tensile_cutoff: None,
                error: Some(e.to_string()),
            },
        }
    }
}

/// The solver options the arguments ask for.
pub fn solve_options(args: &SolveArgs) -> SolveOptions {
    let defaults = SolveOptions::default();
    SolveOptions {
        method: args.method,
        rtol: args.rtol.unwrap_or(defaults.rtol),
        atol: args.atol.or(defaults.atol),
        dt: args.dt.or(defaults.dt),
        ..defaults
    }
}

/// The scene the arguments name, with their overrides applied.
pub fn load_scene(source: &SceneSelection, registry: &Registry) -> Result<Scene, CliError> {
    Ok(registry.scene_with(&source.scene, &source.overrides)?)
}

/// The models to solve: those given, else every law of the table.
pub fn models_or_all(given: &[ForceModel]) -> Vec<ForceModel> {
    if given.is_empty() {
        ForceModel::ALL.to_vec()
    } else {
        given.to_vec()
    }
}

/// Solves the scene for every requested model; a failing model becomes a row with `error` set.
pub fn report(args: &SolveArgs, registry: &Registry) -> Result<SolveReport, CliError> {
    let scene = load_scene(&args.source, registry)?;
    let quasistatic = scene.quasistatic()?;
    let params = scene.impact_params(&quasistatic);
    let options = solve_options(args);
    let mut warnings: Vec<WarningRow> = scene_warnings(&scene.pair()?, &quasistatic)
        .into_iter()
        .map(WarningRow::from)
        .collect();
    let impacts = models_or_all(&args.models)
        .into_iter()
        .map(|model| {
            ImpactRow::new(
                model,
                &params,
                &options,
                args.calibrate,
                scene.fit.as_ref(),
                &mut warnings,
            )
        })
        .collect();
    let advice = recommend(&scene, &quasistatic);
    Ok(SolveReport {
        recommendation: RecommendationRow {
            model: advice.model,
            why: recommendation::why(&advice, &scene),
            fits: advice.fits,
        },
        scene,
        quasistatic,
        impacts,
        warnings,
    })
}

/// The one model's solution that `--format csv` prints.
pub fn trajectory(args: &SolveArgs, registry: &Registry) -> Result<ImpactSolution, CliError> {
    let model = match args.models.as_slice() {
        [model] => *model,
        _ => {
            return Err(CliError::Usage(
                "--format csv prints one trajectory: give exactly one --model (e.g. --model hunt-crossley)".into(),
            ));
        }
    };
    let scene = load_scene(&args.source, registry)?;
    let quasistatic = scene.quasistatic()?;
    let options = solve_options(args);
    let params = scene.impact_params(&quasistatic);
    let (law, calibration, _) = scene_law(model, &params, args.calibrate, scene.fit.as_ref())
        .map_err(|source| CliError::Impact { model, source })?;
    if let Err(why) = calibration {
        return Err(CliError::Usage(format!("--calibrate: {why}")));
    }
    impact::solve_law(&law, &options).map_err(|source| CliError::Impact { model, source })
}
