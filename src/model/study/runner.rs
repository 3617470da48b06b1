//! The study runner: what a study asks ([`StudySpec`]), what it gives ([`StudyResult`]) and [`run`],
//! which computes one and gives up (returns `None`) as soon as its `stop` says it was superseded.
//! The explorer's study views and `hertz-tui plot` both run studies through it.

use std::sync::Arc;

use crate::model::impact::{
    ImpactError, ImpactSolution, ImpactSummary, MethodUsed, SolveOptions, solve_impact,
};
use crate::model::restitution::{
    REQUESTED, RestitutionRow, realised_curve, requested_grid, table, velocity_curve, velocity_grid,
};
use crate::model::scene::Scene;
use crate::model::study::continuation::{ContinuationStudy, ContinuedBranches, run_continuation};
use crate::model::study::fit::{FitData, FitStudy, run_fit};
use crate::model::study::map::{MapData, MapStudy, run_map};
use crate::model::study::reference::{SummaryErrors, reference, reference_solution};
use crate::model::study::stability::{
    StabilityRun, StepBound, critical_step, peak_angular_frequency, runs_at_step,
    step_bounds_until, step_ratio,
};
use crate::model::study::sweep::{SweepError, SweepRow, SweepSpec, sweep_until};
use crate::model::study::system::{
    DiagramData, DiagramStudy, SystemRuns, SystemStudy, run_diagram, run_system,
};
use crate::model::study::timing::median_seconds;
use crate::model::study::work_precision::{Timing, WorkPrecisionRow, work_precision_until};
use crate::model::{ForceModel, ImpactParams};

/// What a study computes, with all its inputs.
#[derive(Debug, Clone, PartialEq)]
pub enum StudySpec {
    /// Every method over its ladder, for one model.
    WorkPrecision {
        model: ForceModel,
        params: ImpactParams,
    },
    /// The explorer's own solve of one model, placed on the work-precision chart.
    Current {
        model: ForceModel,
        params: ImpactParams,
        options: SolveOptions,
    },
    /// Every fixed-step method at one step, over the reference.
    Runs {
        model: ForceModel,
        params: ImpactParams,
        dt: f64,
    },
    /// The measured largest bounded step of every fixed-step method.
    Bounds {
        model: ForceModel,
        params: ImpactParams,
    },
    /// Boxed: a scene and a sweep are large beside the other studies' inputs.
    Sweep {
        scene: Box<Scene>,
        spec: Box<SweepSpec>,
    },
    /// Realised against requested e, and e against v₀, for the checked models.
    Restitution {
        models: Vec<ForceModel>,
        params: ImpactParams,
    },
    /// A system run with each stop (boxed: a system model holds its scene).
    System(Box<SystemStudy>),
    /// A system's bifurcation diagram with each stop, reported as it fills in.
    Diagram(Box<DiagramStudy>),
    /// Every candidate law fitted to measured restitution, with its progress while slow.
    Fit(Box<FitStudy>),
    /// A system's periodic orbit continued over the diagram's range, reported stop by stop.
    Continuation(Box<ContinuationStudy>),
    /// A two-parameter map of a system's motion with each stop, reported row by row.
    Map(Box<MapStudy>),
    /// Stops the running study of a kind and computes nothing (a cancel: its result so far stays
    /// shown).
    Stop(StudyKind),
}

/// The kinds of study, one slot each.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum StudyKind {
    WorkPrecision,
    Current,
    Runs,
    Bounds,
    Sweep,
    Restitution,
    System,
    Diagram,
    Fit,
    Continuation,
    Map,
}

impl StudyKind {
    pub const ALL: [StudyKind; 11] = [
        StudyKind::WorkPrecision,
        StudyKind::Current,
        StudyKind::Runs,
        StudyKind::Bounds,
        StudyKind::Sweep,
        StudyKind::Restitution,
        StudyKind::System,
        StudyKind::Diagram,
        StudyKind::Fit,
        StudyKind::Continuation,
        StudyKind::Map,
    ];

    pub fn index(self) -> usize {
        StudyKind::ALL
            .iter()
            .position(|&k| k == self)
            .unwrap_or_default()
    }

    /// Quick studies run first, so that a step change answers while a ladder is measured.
    pub fn priority(self) -> u8 {
        match self {
            StudyKind::Current | StudyKind::Runs | StudyKind::System => 0,
            StudyKind::Sweep | StudyKind::Restitution | StudyKind::Fit => 1,
            StudyKind::Bounds | StudyKind::Diagram | StudyKind::Continuation | StudyKind::Map => 2,
            StudyKind::WorkPrecision => 3,
        }
    }
}

impl StudySpec {
    pub fn kind(&self) -> StudyKind {
        match self {
            StudySpec::WorkPrecision { .. } => StudyKind::WorkPrecision,
            StudySpec::Current { .. } => StudyKind::Current,
            StudySpec::Runs { .. } => StudyKind::Runs,
            StudySpec::Bounds { .. } => StudyKind::Bounds,
            StudySpec::Sweep { .. } => StudyKind::Sweep,
            StudySpec::Restitution { .. } => StudyKind::Restitution,
            StudySpec::System(_) => StudyKind::System,
            StudySpec::Diagram(_) => StudyKind::Diagram,
            StudySpec::Fit(_) => StudyKind::Fit,
            StudySpec::Continuation(_) => StudyKind::Continuation,
            StudySpec::Map(_) => StudyKind::Map,
            StudySpec::Stop(kind) => *kind,
        }
    }
}

/// One study to compute off the UI thread.
#[derive(Debug, Clone, PartialEq)]
pub struct StudyJob {
    pub generation: u64,
    pub spec: StudySpec,
}

/// The work-precision ladder of one model.
#[derive(Debug, Clone, PartialEq)]
pub struct WorkPrecisionData {
    pub model: ForceModel,
    pub reference: ImpactSummary,
    pub rows: Vec<WorkPrecisionRow>,
}

/// The explorer's solve measured like a rung of the ladder.
#[derive(Debug, Clone, PartialEq)]
pub struct CurrentPoint {
    /// The explorer's settings (method choice, rtol, step).
    pub options: SolveOptions,
    /// The path the solve took (what `auto` chose).
    pub method: MethodUsed,
    pub errors: SummaryErrors,
    pub force_evals: usize,
    pub seconds_per_solve: f64,
}

/// One fixed-step method at the chosen step.
#[derive(Debug, Clone)]
pub struct MethodRun {
    pub run: StabilityRun,
    /// Theoretical critical step bound/ω_max, s (`None`: no stable step in theory).
    pub critical_dt: Option<f64>,
}

/// The fixed-step methods at one step over the reference.
#[derive(Debug, Clone)]
pub struct StabilityData {
    pub model: ForceModel,
    pub dt: f64,
    /// ω at the elastic maximum compression, rad/s: the stiffest point of the impact.
    pub omega_max: f64,
    /// h·ω_max of the chosen step.
    pub step_ratio: f64,
    pub reference: Arc<ImpactSolution>,
    pub runs: Vec<MethodRun>,
}

/// A measured largest bounded step, with h·ω_max to compare with the theory's bound.
#[derive(Debug, Clone, PartialEq)]
pub struct MeasuredBound {
    pub bound: StepBound,
    pub step_ratio: Option<f64>,
}

/// A finished sweep and what it swept.
#[derive(Debug, Clone)]
pub struct SweepData {
    pub spec: SweepSpec,
    pub rows: Vec<SweepRow>,
}

/// The restitution view's curves and table, per model in the order asked.
#[derive(Debug, Clone, PartialEq)]
pub struct RestitutionData {
    /// The scene's v₀, m/s, the middle of the velocity curves.
    pub v0: f64,
    /// (model, [(e requested, e realised)]).
    pub realised: Vec<(ForceModel, Vec<(f64, f64)>)>,
    /// (model, [(v₀, e realised)]) with the scene's damping coefficient held.
    pub velocity: Vec<(ForceModel, Vec<(f64, f64)>)>,
    /// The realised e for requested 0.1, 0.3, 0.5, 0.7, 0.9.
    pub table: Vec<RestitutionRow>,
}

/// Points of each restitution curve.
const RESTITUTION_POINTS: usize = 25;

/// Why a study failed: the solve or the sweep's own error, kept typed for the edges to word.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StudyError {
    #[error(transparent)]
    Impact(#[from] ImpactError),
    #[error(transparent)]
    Sweep(#[from] SweepError),
}

/// What a study produced.
#[derive(Debug, Clone)]
pub enum StudyResult {
    WorkPrecision(Result<Arc<WorkPrecisionData>, StudyError>),
    Current(Result<CurrentPoint, StudyError>),
    Runs(Result<Arc<StabilityData>, StudyError>),
    Bounds(Result<Arc<Vec<MeasuredBound>>, StudyError>),
    Sweep(Result<Arc<SweepData>, StudyError>),
    Restitution(Result<Arc<RestitutionData>, StudyError>),
    /// Each stop's run (each with its own error).
    System(Arc<SystemRuns>),
    /// Each stop's diagram so far (see [`DiagramData::complete`]).
    Diagram(Arc<DiagramData>),
    /// The fit, or its progress (see [`FitData::complete`]).
    Fit(Arc<FitData>),
    /// Each stop's continued branch so far (see [`ContinuedBranches::complete`]).
    Continuation(Arc<ContinuedBranches>),
    /// Each stop's map so far (see [`MapData::complete`]).
    Map(Arc<MapData>),
}

impl StudyResult {
    pub fn kind(&self) -> StudyKind {
        match self {
            StudyResult::WorkPrecision(_) => StudyKind::WorkPrecision,
            StudyResult::Current(_) => StudyKind::Current,
            StudyResult::Runs(_) => StudyKind::Runs,
            StudyResult::Bounds(_) => StudyKind::Bounds,
            StudyResult::Sweep(_) => StudyKind::Sweep,
            StudyResult::Restitution(_) => StudyKind::Restitution,
            StudyResult::System(_) => StudyKind::System,
            StudyResult::Diagram(_) => StudyKind::Diagram,
            StudyResult::Fit(_) => StudyKind::Fit,
            StudyResult::Continuation(_) => StudyKind::Continuation,
            StudyResult::Map(_) => StudyKind::Map,
        }
    }

    /// A report of a study still running (a diagram filling in): more will come.
    pub fn is_partial(&self) -> bool {
        match self {
            StudyResult::Diagram(d) => !d.complete,
            StudyResult::Fit(f) => !f.complete(),
            StudyResult::Continuation(c) => !c.complete,
            StudyResult::Map(m) => !m.complete,
            _ => false,
        }
    }
}

/// A finished study.
#[derive(Debug, Clone)]
pub struct StudyOutcome {
    pub generation: u64,
    pub result: StudyResult,
}

/// Timing effort of a work-precision rung in the explorer: a few repeats keep the tab quick.
pub const TIMING: Timing = Timing {
    min_repeats: 3,
    min_total: std::time::Duration::from_millis(1),
};

/// [`run`], handing `partial` what a study that fills in (a diagram) has so far.
pub fn run_partially(
    job: &StudyJob,
    stop: &(dyn Fn() -> bool + Sync),
    partial: &dyn Fn(StudyOutcome),
) -> Option<StudyOutcome> {
    let generation = job.generation;
    let outcome = |result| StudyOutcome { generation, result };
    match &job.spec {
        StudySpec::Fit(study) => {
            let data = run_fit(study, stop, &|d| {
                partial(outcome(StudyResult::Fit(Arc::new(d))))
            })?;
            (!stop()).then(|| outcome(StudyResult::Fit(Arc::new(data))))
        }
        StudySpec::Continuation(study) => {
            let data = run_continuation(study, stop, &|d| {
                partial(outcome(StudyResult::Continuation(Arc::new(d))))
            })?;
            (!stop()).then(|| outcome(StudyResult::Continuation(Arc::new(data))))
        }
        StudySpec::Diagram(study) => {
            let data = run_diagram(study, stop, &|d| {
                partial(outcome(StudyResult::Diagram(Arc::new(d))))
            })?;
            (!stop()).then(|| outcome(StudyResult::Diagram(Arc::new(data))))
        }
        StudySpec::Map(study) => {
            let data = run_map(study, stop, &|d| {
                partial(outcome(StudyResult::Map(Arc::new(d))))
            })?;
            (!stop()).then(|| outcome(StudyResult::Map(Arc::new(data))))
        }
        _ => run(job, stop),
    }
}

/// Computes `job` on the calling thread; `None` when `stop` returned true on the way.
pub fn run(job: &StudyJob, stop: &(dyn Fn() -> bool + Sync)) -> Option<StudyOutcome> {
    let result = match &job.spec {
        StudySpec::WorkPrecision { model, params } => {
            let data =
                work_precision_until(*model, params, TIMING, stop).map(|(reference, rows)| {
                    Arc::new(WorkPrecisionData {
                        model: *model,
                        reference,
                        rows,
                    })
                });
            StudyResult::WorkPrecision(data.map_err(StudyError::from))
        }
        StudySpec::Current {
            model,
            params,
            options,
        } => StudyResult::Current(current_point(*model, params, options).map_err(StudyError::from)),
        StudySpec::Runs { model, params, dt } => {
            StudyResult::Runs(stability(*model, params, *dt).map_err(StudyError::from))
        }
        StudySpec::Bounds { model, params } => StudyResult::Bounds(
            reference(*model, params)
                .map(|r| {
                    let bounds = step_bounds_until(*model, params, &r, stop);
                    Arc::new(
                        bounds
                            .into_iter()
                            .map(|bound| MeasuredBound {
                                step_ratio: bound.measured_dt.map(|dt| step_ratio(dt, params)),
                                bound,
                            })
                            .collect(),
                    )
                })
                .map_err(StudyError::from),
        ),
        StudySpec::Sweep { scene, spec } => match sweep_until(scene, spec, stop) {
            Ok(Some(rows)) => StudyResult::Sweep(Ok(Arc::new(SweepData {
                spec: SweepSpec::clone(spec),
                rows,
            }))),
            Ok(None) => return None,
            Err(e) => StudyResult::Sweep(Err(e.into())),
        },
        StudySpec::Restitution { models, params } => match restitution_data(models, params, stop) {
            Some(data) => StudyResult::Restitution(Ok(Arc::new(data))),
            None => return None,
        },
        StudySpec::System(study) => StudyResult::System(Arc::new(run_system(study))),
        StudySpec::Diagram(_)
        | StudySpec::Fit(_)
        | StudySpec::Continuation(_)
        | StudySpec::Map(_) => {
            return run_partially(job, stop, &|_| {});
        }
        StudySpec::Stop(_) => return None,
    };
    // A study cut short is incomplete: nobody wants it.
    (!stop()).then_some(StudyOutcome {
        generation: job.generation,
        result,
    })
}

/// The restitution curves and table of `models`, `None` once `stop` says so.
fn restitution_data(
    models: &[ForceModel],
    params: &ImpactParams,
    stop: &(dyn Fn() -> bool + Sync),
) -> Option<RestitutionData> {
    let opts = SolveOptions::default();
    let requested = requested_grid(RESTITUTION_POINTS);
    let velocities = velocity_grid(params.v0, RESTITUTION_POINTS);
    let mut data = RestitutionData {
        v0: params.v0,
        realised: Vec::new(),
        velocity: Vec::new(),
        table: Vec::new(),
    };
    for &model in models {
        if stop() {
            return None;
        }
        data.realised
            .push((model, realised_curve(model, params, &requested, &opts)));
        data.velocity
            .push((model, velocity_curve(model, params, &velocities, &opts)));
    }
    data.table = table(models, params, &REQUESTED, &opts);
    Some(data)
}

fn current_point(
    model: ForceModel,
    params: &ImpactParams,
    options: &SolveOptions,
) -> Result<CurrentPoint, ImpactError> {
    let reference = reference(model, params)?;
    let solution = solve_impact(model, params, options)?;
    Ok(CurrentPoint {
        options: *options,
        method: solution.summary.method,
        errors: SummaryErrors::between(&solution.summary, &reference),
        force_evals: solution.summary.force_evals,
        seconds_per_solve: median_seconds(
            || solve_impact(model, params, options),
            TIMING.min_repeats,
            TIMING.min_total,
        ),
    })
}

fn stability(
    model: ForceModel,
    params: &ImpactParams,
    dt: f64,
) -> Result<Arc<StabilityData>, ImpactError> {
    let reference = reference_solution(model, params)?;
    let runs = runs_at_step(model, params, &reference.summary, dt)
        .into_iter()
        .map(|run| MethodRun {
            critical_dt: critical_step(run.method, params),
            run,
        })
        .collect();
    Ok(Arc::new(StabilityData {
        model,
        dt,
        omega_max: peak_angular_frequency(params),
        step_ratio: step_ratio(dt, params),
        reference: Arc::new(reference),
        runs,
    }))
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::model::scene::tests::fig5_params;

    /// The bounds study of the Fig. 5 scene's proposed model at `v0`.
    pub(crate) fn bounds(v0: f64) -> StudySpec {
        StudySpec::Bounds {
            model: ForceModel::Proposed,
            params: fig5_params(v0),
        }
    }

    #[test]
    fn a_stopped_study_reports_nothing() {
        let job = StudyJob {
            generation: 1,
            spec: bounds(0.3),
        };
        assert!(run(&job, &|| true).is_none());
    }

    #[test]
    fn runs_at_the_rk4_critical_step_judge_every_fixed_step_method() {
        let p = fig5_params(0.3);
        let dt = critical_step(crate::model::ode::Method::Rk4, &p).unwrap();
        let job = StudyJob {
            generation: 7,
            spec: StudySpec::Runs {
                model: ForceModel::Proposed,
                params: p,
                dt,
            },
        };
        let outcome = run(&job, &|| false).unwrap();
        assert_eq!(outcome.generation, 7);
        let StudyResult::Runs(Ok(data)) = outcome.result else {
            panic!("runs failed: {:?}", outcome.result);
        };
        assert_eq!(data.runs.len(), 4);
        assert!((data.step_ratio - 8f64.sqrt()).abs() < 1e-9);
        assert!(data.runs.iter().all(|r| r.run.dt == dt));
        assert_eq!(data.runs[0].critical_dt, None, "explicit Euler has none");
        assert_eq!(data.runs[3].critical_dt, Some(dt));
    }
}
