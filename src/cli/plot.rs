//! `hertz-tui plot`: one chart as the explorer draws it, written to an SVG or PNG figure through
//! the same chart description ([`crate::chart`]) the terminal renders.

use crate::chart::figure::{self, FigureError};
use crate::chart::kind::ChartKind;
use crate::chart::sample::{Look, Series, plot};
use crate::chart::stability as stability_plot;
use crate::chart::sweep::SweepOutput;
use crate::chart::sweep::{self as sweep_plot, SweepSet};
use crate::chart::work_precision::{self as wp_plot, Cost};
use crate::chart::{Chart, Ink, model_glyph};
use crate::model::impact::{SolveOptions, solve_impact};
use crate::model::presets::Registry;
use crate::model::study::runner::{
    self, StabilityData, StudyJob, StudyResult, StudySpec, SweepData,
};
use crate::model::study::stability::critical_step;
use crate::model::study::sweep::default_range;
use crate::model::study::sweep::{SweepSpec, sweep};
use crate::model::system::Param;
use crate::model::{ForceModel, ImpactParams, Scene};

use super::args::{ChartChoice, PlotArgs, QuantityChoice, SceneSelection};
use super::error::CliError;
use super::solve::{load_scene, models_or_all};

/// Tick labels of a figure: as many as read well on a page.
const BUDGET: (usize, usize) = (9, 8);
/// Samples of each curve (the exact extrema are added): smooth at any figure size.
const SAMPLES: usize = 400;

/// Draws the chart the arguments ask for and writes the figure; says what was written.
pub fn run(args: &PlotArgs, registry: &Registry) -> Result<String, CliError> {
    let size = figure::parse_size(&args.size).map_err(usage)?;
    figure::Format::of(&args.out).map_err(usage)?;
    let scenes = args
        .scene
        .iter()
        .map(|name| {
            load_scene(
                &SceneSelection {
                    scene: name.clone(),
                    overrides: args.overrides.clone(),
                },
                registry,
            )
        })
        .collect::<Result<Vec<_>, _>>()?;
    if scenes.len() > 1 && args.chart != ChartChoice::Sweep {
        return Err(CliError::Usage(
            "several --scene go on one chart only with --chart sweep".into(),
        ));
    }
    let charts = match args.chart {
        ChartChoice::Fx => vec![trajectories(
            args,
            &scenes[0],
            ChartKind::ForceDisplacement,
        )?],
        ChartChoice::Ft => vec![trajectories(args, &scenes[0], ChartKind::ForceTime)?],
        ChartChoice::Vx => vec![trajectories(
            args,
            &scenes[0],
            ChartKind::VelocityDisplacement,
        )?],
        ChartChoice::Sweep => vec![sweeps(args, &scenes)?],
        ChartChoice::WorkPrecision => work_precision(args, &scenes[0])?,
        ChartChoice::Stability => stability(args, &scenes[0])?,
        ChartChoice::History
        | ChartChoice::Phase
        | ChartChoice::ImpactMap
        | ChartChoice::Bifurcation => vec![super::plot_system::chart(args, registry, BUDGET)?],
        ChartChoice::Fit | ChartChoice::FitEngines => {
            super::plot_fit::charts(args, &scenes[0], BUDGET)?
        }
    };
    figure::write(&charts, &args.out, size).map_err(usage)?;
    Ok(format!(
        "wrote {} ({}×{} px)\n",
        args.out.display(),
        size.0,
        size.1
    ))
}

fn usage(e: FigureError) -> CliError {
    CliError::Usage(e.to_string())
}

fn options(args: &PlotArgs) -> SolveOptions {
    let defaults = SolveOptions::default();
    SolveOptions {
        method: args.method,
        rtol: args.rtol.unwrap_or(defaults.rtol),
        dt: args.dt.or(defaults.dt),
        ..defaults
    }
}

fn params(scene: &Scene) -> Result<ImpactParams, CliError> {
    let hertz = scene.quasistatic()?;
    Ok(scene.impact_params(&hertz))
}

/// The model studied by work-precision and stability: the first given, else proposed.
fn studied(args: &PlotArgs) -> ForceModel {
    args.models.first().copied().unwrap_or(ForceModel::Proposed)
}

/// F(x), F(t) or v(x) of the models, the first focused; a model that fails is named with its
/// reason on the chart.
fn trajectories(args: &PlotArgs, scene: &Scene, kind: ChartKind) -> Result<Chart, CliError> {
    let params = params(scene)?;
    let models = models_or_all(&args.models);
    let opts = options(args);
    let mut series = Vec::new();
    let mut notes = Vec::new();
    for &model in &models {
        match solve_impact(model, &params, &opts) {
            Ok(solution) => series.push(Series::sample(model, &solution, SAMPLES)),
            Err(e) => notes.push(format!("✗ {}: {e}", model.name())),
        }
    }
    let focused = models[0];
    let title = format!("{} · {}", kind.title(), scene.name);
    let mut chart = plot(kind, &series, BUDGET.0, BUDGET.1).into_chart(title, |m| Look {
        name: m.label().to_string(),
        ink: Ink::Model(m),
        glyph: model_glyph(m),
        focused: m == focused,
        steps: false,
    });
    chart.notes = notes;
    Ok(chart)
}

fn quantity(q: QuantityChoice) -> SweepOutput {
    match q {
        QuantityChoice::P0 => SweepOutput::PeakPressure,
        QuantityChoice::ContactSize => SweepOutput::ContactSize,
        QuantityChoice::XMax => SweepOutput::XMax,
        QuantityChoice::FMax => SweepOutput::FMax,
        QuantityChoice::TC => SweepOutput::TContact,
        QuantityChoice::VOut => SweepOutput::VOut,
        QuantityChoice::EOut => SweepOutput::EOut,
    }
}

/// One sweep per scene on one chart.
fn sweeps(args: &PlotArgs, scenes: &[Scene]) -> Result<Chart, CliError> {
    let output = quantity(args.quantity);
    let Param::Scene(key) = args.param else {
        return Err(CliError::Usage(format!(
            "--chart sweep varies a scene key, not {} (that is --chart bifurcation's)",
            args.param
        )));
    };
    let mut data = Vec::new();
    for scene in scenes {
        let (from, to, log) = match (args.from, args.to) {
            (Some(from), Some(to)) => (from, to, args.log),
            _ => {
                let range = default_range(key, scene).ok_or_else(|| {
                    CliError::Usage(format!("{key} does not apply to {}", scene.name))
                })?;
                (range.from, range.to, range.log)
            }
        };
        let spec = SweepSpec {
            key,
            from,
            to,
            points: args.points as usize,
            log,
            models: if output.per_model() {
                models_or_all(&args.models)
            } else {
                Vec::new()
            },
            options: options(args),
        };
        let rows = sweep(scene, &spec).map_err(|e| CliError::Usage(e.to_string()))?;
        let yield_stress = scene.pair()?.yield_stress();
        data.push((
            scene.body1.material.name.clone(),
            SweepData { spec, rows },
            yield_stress,
        ));
    }
    let several = data.len() > 1;
    let sets: Vec<SweepSet> = data
        .iter()
        .map(|(name, data, yield_stress)| SweepSet {
            name: several.then(|| name.clone()),
            data,
            yield_stress: Some(*yield_stress),
        })
        .collect();
    let focused = args.models.first().copied();
    let mut chart = sweep_plot::chart(&sets, output, focused, BUDGET);
    if let [scene] = scenes {
        chart.title = format!("{} · {}", chart.title, scene.name);
    }
    Ok(chart)
}

fn unexpected(result: &StudyResult) -> CliError {
    CliError::Usage(format!("the study gave {:?} data", result.kind()))
}

/// Runs one study on this thread.
fn study(spec: StudySpec) -> Result<StudyResult, CliError> {
    let job = StudyJob {
        generation: 0,
        spec,
    };
    runner::run(&job, &|| false)
        .map(|outcome| outcome.result)
        .ok_or_else(|| CliError::Usage("the study was stopped".into()))
}

/// Both work-precision charts, against seconds and against force evaluations, with the solve
/// `--method`/`--rtol` ask for marked.
fn work_precision(args: &PlotArgs, scene: &Scene) -> Result<Vec<Chart>, CliError> {
    let model = studied(args);
    let params = params(scene)?;
    let data = match study(StudySpec::WorkPrecision { model, params })? {
        StudyResult::WorkPrecision(Ok(data)) => data,
        StudyResult::WorkPrecision(Err(e)) => return Err(CliError::Usage(e.to_string())),
        other => return Err(unexpected(&other)),
    };
    let current = match study(StudySpec::Current {
        model,
        params,
        options: options(args),
    })? {
        StudyResult::Current(Ok(point)) => Some(point),
        _ => None,
    };
    Ok([Cost::Seconds, Cost::ForceEvals]
        .into_iter()
        .map(|cost| {
            let mut chart = wp_plot::chart(&data, current.as_ref(), cost, BUDGET);
            chart.title = format!("{} · {}", chart.title, model.label());
            chart
        })
        .collect())
}

/// F(x) and v(x) of every fixed-step method at `--dt` (default: the rk4 critical step).
fn stability(args: &PlotArgs, scene: &Scene) -> Result<Vec<Chart>, CliError> {
    let model = studied(args);
    let params = params(scene)?;
    let dt = match args.dt {
        Some(dt) => dt,
        None => critical_step(crate::model::ode::Method::Rk4, &params)
            .ok_or_else(|| CliError::Usage("no critical step for rk4".into()))?,
    };
    let data: std::sync::Arc<StabilityData> = match study(StudySpec::Runs { model, params, dt })? {
        StudyResult::Runs(Ok(data)) => data,
        StudyResult::Runs(Err(e)) => return Err(CliError::Usage(e.to_string())),
        other => return Err(unexpected(&other)),
    };
    Ok([
        ChartKind::ForceDisplacement,
        ChartKind::VelocityDisplacement,
    ]
    .into_iter()
    .map(|kind| stability_plot::chart(&data, kind, 600, BUDGET))
    .collect())
}
