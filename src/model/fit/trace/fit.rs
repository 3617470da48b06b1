//! Fitting laws to one trace through the shared least-squares engine ([`least_squares`]) and
//! ranking them as e(v) fits are ranked (docs/fitting.md, Traces; docs/physics.md §9).

use rayon::prelude::*;

use crate::model::fit::criterion::{self, Scores};
use crate::model::fit::lsq::{LsqProblem, LsqResult, ParamSpec, least_squares};
use crate::model::fit::{Candidate, FitError, FitReport, FittedParam, LawFit};
use crate::model::force::{ForceModel, ImpactParams};
use crate::model::impact::{ImpactSolution, SolveOptions};
use crate::model::scene::Scene;

use super::data::{TraceData, TraceDataError, TraceQuantity};
use super::forward::{TraceParams, force_at_touch, sample_trace, solve_trace_impact};
use super::layout::Layout;
use super::options::{FreeParams, TRACE_FLOOR, TraceFitOptions};
use super::rank::verdict;
use super::start::start;

/// Fits each law of `models` to the trace `data` on `scene` and ranks them by the criterion of
/// `opts.fit`, as [`crate::model::fit::fit_restitution`] ranks e(v) fits.
///
/// Each law's parameters are its damping (the Hunt–Crossley family's a = χ/v₀) and the contact
/// start t₀, plus whichever of k, n, v₀ `opts.free` frees; the others are the scene's. The mass is
/// always the scene's. Reported in SI in the order k, n, v₀, damping, t₀. A law without a damping
/// parameter (elastic Hertz) fits t₀ (and what is freed) alone, so the ranking says whether the
/// trace shows dissipation at all. [`predict_trace`] evaluates a fitted law at any time.
///
/// ```
/// use hertz_tui::model::ForceModel;
/// use hertz_tui::model::fit::trace::{TraceData, TraceFitOptions, TraceParams, TraceQuantity, fit_trace, trace_forward};
/// use hertz_tui::model::presets::{DEFAULT_SCENE, Registry};
///
/// let scene = Registry::builtin()?.scene(DEFAULT_SCENE)?;
/// let base = scene.impact_params(&scene.quasistatic()?);
/// let opts = TraceFitOptions::default();
/// // A noise-free Hunt–Crossley force trace (χ = 0.6 at v₀ = 0.3 m/s: a = 2 s/m) from 5 µs before
/// // contact, sampled every microsecond, contact at t₀ = 12 µs.
/// let truth = TraceParams { k: base.law.k, n: base.law.n, v0: base.v0, damping: Some(0.6), t0: 12e-6 };
/// let times: Vec<f64> = (7..70).map(|i| i as f64 * 1e-6).collect();
/// let forces = trace_forward(&base, ForceModel::HuntCrossley, &truth, TraceQuantity::Force,
///     opts.outside, &times, &opts.solve)?;
/// let data = TraceData::from_pairs(TraceQuantity::Force, times.into_iter().zip(forces))?;
///
/// let report = fit_trace(&scene, &data, &[ForceModel::HuntCrossley, ForceModel::Quasistatic], &opts)?;
/// let best = &report.fits[0];
/// assert_eq!(best.candidate.id(), "hunt-crossley");
/// assert_eq!(best.params[0].spec.key, "a");
/// assert!((best.params[0].value / 2.0 - 1.0).abs() < 1e-6);
/// assert!((best.params[1].value / 12e-6 - 1.0).abs() < 1e-6);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn fit_trace(
    scene: &Scene,
    data: &TraceData,
    models: &[ForceModel],
    opts: &TraceFitOptions,
) -> Result<FitReport, FitError> {
    let base = scene.impact_params(&scene.quasistatic()?);
    fit_trace_params(&base, data, models, opts)
}

/// [`fit_trace`] on the scene's impact parameters.
pub fn fit_trace_params(
    base: &ImpactParams,
    data: &TraceData,
    models: &[ForceModel],
    opts: &TraceFitOptions,
) -> Result<FitReport, FitError> {
    if models.is_empty() {
        return Err(FitError::NoCandidates);
    }
    base.validate()?;
    data.validate()?;
    // Too short for what was asked is the data's fault, said before any law is tried.
    for &model in models {
        let needed = Layout::of(model, opts.free).len() + 1;
        if data.samples.len() < needed {
            return Err(TraceDataError::TooFewForLaw {
                file: data.source.clone().unwrap_or_else(|| "the trace".into()),
                points: data.samples.len(),
                params: needed - 1,
                law: model.name(),
            }
            .into());
        }
    }
    let fit = |&m: &ForceModel| (m, fit_one(base, data, m, opts));
    let results: Vec<(ForceModel, Result<LawFit, FitError>)> = if opts.fit.parallel {
        models.par_iter().map(fit).collect()
    } else {
        models.iter().map(fit).collect()
    };
    let mut fits = Vec::new();
    let mut failed = Vec::new();
    for (m, r) in results {
        match r {
            Ok(f) => fits.push(f),
            Err(e) => failed.push((Candidate::Law(m), e.to_string())),
        }
    }
    if fits.is_empty() {
        return Err(FitError::NothingFitted(failed));
    }
    let criterion = opts.fit.criterion;
    let order: Vec<Candidate> = models.iter().map(|&m| Candidate::Law(m)).collect();
    criterion::rank(&mut fits, criterion, &order);
    let verdict = verdict(data, &fits, opts.fit.criterion, base.v0);
    let indistinguishable = verdict.groups.iter().map(|g| g.members.clone()).collect();
    Ok(FitReport {
        fits,
        failed,
        criterion,
        indistinguishable,
        verdict,
        weighted: false,
    })
}

/// The fitted law's forward parameters on the scene `base`: k, n, v₀ where fitted, else the
/// scene's; the damping in the law's own unit (χ for the Hunt–Crossley family).
pub fn fitted_trace_params(base: &ImpactParams, fit: &LawFit) -> Result<TraceParams, FitError> {
    let model = fit.candidate.model().ok_or_else(|| FitError::Unfittable {
        candidate: fit.candidate,
        reason: "not a contact law: a trace needs a force law".into(),
    })?;
    let get = |key: &str| {
        fit.params
            .iter()
            .find(|p| p.spec.key == key)
            .map(|p| p.value)
    };
    let free = FreeParams {
        k: get("k").is_some(),
        n: get("n").is_some(),
        v0: get("v0").is_some(),
    };
    let layout = Layout::of(model, free);
    Ok(layout.params(base, &fit.theta()))
}

/// The fitted law's `quantity` at `times` (s, the recording's clock): the forward model the fit
/// used, for figures and residual plots.
pub fn predict_trace(
    scene: &Scene,
    fit: &LawFit,
    quantity: TraceQuantity,
    opts: &TraceFitOptions,
    times: &[f64],
) -> Result<Vec<f64>, FitError> {
    let base = scene.impact_params(&scene.quasistatic()?);
    let p = fitted_trace_params(&base, fit)?;
    let model = fit.candidate.model().unwrap_or(ForceModel::Quasistatic);
    let solution = solve(&base, model, &p, &opts.solve, fit.candidate)?;
    Ok(sample_trace(&solution, quantity, opts.outside, &p, times))
}

pub(super) fn solve(
    base: &ImpactParams,
    model: ForceModel,
    p: &TraceParams,
    opts: &SolveOptions,
    candidate: Candidate,
) -> Result<ImpactSolution, FitError> {
    solve_trace_impact(base, model, p, opts).map_err(|e| FitError::Unfittable {
        candidate,
        reason: format!("the impact solve failed: {e}"),
    })
}

/// Fits one law (see [`fit_trace`]).
fn fit_one(
    base: &ImpactParams,
    data: &TraceData,
    model: ForceModel,
    opts: &TraceFitOptions,
) -> Result<LawFit, FitError> {
    let candidate = Candidate::Law(model);
    let layout = Layout::of(model, opts.free);
    if let Some(reason) = layout.unidentifiable(base) {
        return Err(FitError::Unfittable { candidate, reason });
    }
    let times = data.times();
    let values = data.values();
    let (t_first, t_last) = (times[0], times[times.len() - 1]);
    let span = t_last - t_first;
    let t_bounds = (t_first - span, t_last);
    let specs = layout.specs(t_bounds);
    let start = start(base, data, &layout, opts, t_bounds)?;
    // The engine steps t₀ in units of the scene's elastic contact time (eq 7) from its start:
    // its finite-difference step is relative to max(|u|, 1), which on t₀ in seconds would be a
    // microsecond, a tenth of a contact.
    let t_scale = base.law.contact_time(base.mass, base.v0);
    let t_anchor = start[start.len() - 1];
    let last = specs.len() - 1;
    let mut engine_specs = specs.clone();
    engine_specs[last] = ParamSpec::bounded(
        "t₀",
        "t0",
        "1",
        (t_bounds.0 - t_anchor) / t_scale,
        (t_bounds.1 - t_anchor) / t_scale,
    );
    let to_si = |u: &[f64]| -> Vec<f64> {
        let mut theta = u.to_vec();
        theta[last] = t_anchor + u[last] * t_scale;
        theta
    };
    let residuals = |u: &[f64]| -> Result<Vec<f64>, String> {
        let p = layout.params(base, &to_si(u));
        let solution =
            solve_trace_impact(base, model, &p, &opts.solve).map_err(|e| e.to_string())?;
        let modelled = sample_trace(&solution, data.quantity, opts.outside, &p, &times);
        Ok(modelled.iter().zip(&values).map(|(m, y)| m - y).collect())
    };
    let mut engine_start = start.clone();
    engine_start[last] = 0.0;
    let problem = LsqProblem {
        params: &engine_specs,
        start: engine_start,
        residuals: &residuals,
        known_sd: false,
    };
    let result = least_squares(&problem, &opts.fit.lsq)
        .map_err(|source| FitError::Lsq { candidate, source })?;
    let mut fit = law_fit(
        candidate,
        &specs,
        &result,
        data,
        |j, x| {
            if j == last { t_anchor + x * t_scale } else { x }
        },
        t_scale,
        last,
    );
    let p = layout.params(base, &fit.theta());
    if data.quantity == TraceQuantity::Force
        && force_at_touch(base, model, &p).is_ok_and(|f| f.abs() > 0.0)
    {
        quantise_t0(&mut fit.params[last], &times, result.quantile);
    }
    Ok(fit)
}

/// Widens t₀'s interval by the sampling where the force jumps at first touch: the residuals are
/// then a step function of t₀ wherever no sample crosses the jump, so that the linearised
/// interval says nothing of where between its two samples the jump lies. The jump's time is
/// taken as uniform over that spacing Δ, variance Δ²/12 (the quantisation error), added to the
/// linearised variance; the interval is t₀ ± q·se with the engine's quantile q.
fn quantise_t0(t0: &mut FittedParam, times: &[f64], quantile: f64) {
    let i = times
        .partition_point(|&t| t < t0.value)
        .clamp(1, times.len() - 1);
    let spacing = times[i] - times[i - 1];
    let linear = if t0.std_error.is_finite() {
        t0.std_error
    } else {
        0.0
    };
    let se = linear.hypot(spacing / 12f64.sqrt());
    t0.std_error = se;
    t0.ci = (t0.value - quantile * se, t0.value + quantile * se);
}

/// The engine's result as a [`LawFit`] in SI: `to_si(j, x)` maps parameter j's value back.
fn law_fit(
    candidate: Candidate,
    specs: &[ParamSpec],
    result: &LsqResult,
    data: &TraceData,
    to_si: impl Fn(usize, f64) -> f64,
    t_scale: f64,
    t_index: usize,
) -> LawFit {
    let n = data.samples.len();
    let peak = data.peak().value.abs();
    let floor = n as f64 * (TRACE_FLOOR * peak).powi(2);
    let Scores { aic, aicc, bic } = criterion::scores(result.rss, floor, n, specs.len(), false);
    let params = specs
        .iter()
        .enumerate()
        .map(|(j, spec)| FittedParam {
            spec: *spec,
            value: to_si(j, result.theta[j]),
            std_error: if j == t_index {
                result.std_errors[j] * t_scale
            } else {
                result.std_errors[j]
            },
            ci: (to_si(j, result.ci[j].0), to_si(j, result.ci[j].1)),
            level: result.level,
        })
        .collect();
    LawFit {
        candidate,
        params,
        rss: result.rss,
        chi2: None,
        residuals: result.residuals.clone(),
        n_points: n,
        aic,
        aicc,
        bic,
        delta: 0.0,
        weight: f64::NAN,
        convergence: result.convergence,
        iterations: result.iterations,
        evaluations: result.evaluations,
    }
}
