//! `hertz-tui solve`: the quasistatic estimate and one impact solve per force model.

use serde::Serialize;

use super::args::{SceneSelection, SolveArgs};
use super::error::CliError;
use crate::model::impact::{self, ImpactError, ImpactSolution, SolveOptions, TensileCutoff};
use crate::model::presets::Registry;
use crate::model::warnings::{ModelWarning, end_warning, scene_warnings};
use crate::model::{ForceModel, ImpactParams, Quasistatic, Scene};

/// Everything `solve` computed; serialized as the JSON output.
#[derive(Debug, Serialize)]
pub struct SolveReport {
    pub scene: Scene,
    pub quasistatic: Quasistatic,
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
    pub e_out: Option<f64>,
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

impl ImpactRow {
    fn new(
        model: ForceModel,
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
                    e_out: Some(s.e_out),
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
                e_out: None,
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

/// The models to solve: those given, else all five.
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
    let impacts: Vec<ImpactRow> = models_or_all(&args.models)
        .into_iter()
        .map(|model| {
            let result = impact::solve_impact(model, &params, &options);
            ImpactRow::new(model, &options, result.as_ref())
        })
        .collect();
    let warnings = warning_rows(&scene, &quasistatic, &params, &impacts)?;
    Ok(SolveReport {
        scene,
        quasistatic,
        impacts,
        warnings,
    })
}

/// The scene's warnings, then each solved impact's.
fn warning_rows(
    scene: &Scene,
    quasistatic: &Quasistatic,
    params: &ImpactParams,
    impacts: &[ImpactRow],
) -> Result<Vec<WarningRow>, CliError> {
    let mut warnings = scene_warnings(&scene.pair()?, quasistatic);
    for row in impacts {
        if let (Some(v_out), Some(t_contact)) = (row.v_out, row.t_contact) {
            warnings.extend(end_warning(params, row.model, v_out, t_contact));
        }
    }
    Ok(warnings.into_iter().map(WarningRow::from).collect())
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
    impact::solve_impact(model, &scene.impact_params(&quasistatic), &options)
        .map_err(|source| CliError::Impact { model, source })
}
