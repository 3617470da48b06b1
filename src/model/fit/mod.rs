//! Fitting contact laws to measured restitution e(v) (issue 23; docs/fitting.md, Method;
//! docs/physics.md §9).
//!
//! # API
//! - Data: [`RestitutionData`] of [`RestitutionSample`]s (v in m/s, e, optional sd, the file's
//!   line), checked by [`RestitutionData::new`] ([`FitDataError`] names the line; the CSV reader
//!   `crate::format::fit_csv` adds the file).
//! - What may be fitted: [`Candidate`] (`ConstantE` or `Law(ForceModel)`), the default list
//!   [`candidates`] and [`unfittable`] (the laws left out, with the reason and, for a law that is a
//!   reparametrised copy of another, which one); [`Candidate::params`] gives each
//!   [`ParamSpec`] (one material constant per law: the Hunt–Crossley family's a with χ = a·v,
//!   Kelvin–Voigt's c, Hertz–viscous' γ, Kuwabara–Kono's A, Thornton's v_y, dry friction's P,
//!   Adams' c_max, the proposed model's b).
//! - The forward model: [`Forward`] (built once per candidate and scene) and
//!   [`restitution_model`] (one call), e(v; θ) in SI.
//! - The fit: [`fit_restitution`] (a scene) or [`fit_restitution_params`] (its impact parameters)
//!   → [`FitReport`]: every candidate's [`LawFit`] ranked best first by [`Criterion`] (AICc by
//!   default, or BIC) with Δ and Akaike weights, parameters with Student-t confidence intervals
//!   ([`FittedParam`]), the candidates that failed and why, the groups the data cannot tell apart
//!   and a structured [`Verdict`] (worded by `crate::format::fit_verdict` for the command line
//!   and the explorer).
//!   [`LawFit::predict`] evaluates a fitted law at any v. [`Fitter`] keeps the forward models
//!   (and Kuwabara–Kono's table of e(ψ)) between fits, for refits on edits.
//! - Data too small for a law (fewer points than its parameters, plus one for the noise unless
//!   sd is given) fails that law, listed in [`FitReport::failed`]; every law failing is
//!   [`FitError::NothingFitted`].
//! - The engine: [`lsq::least_squares`] on an [`lsq::LsqProblem`], shared with trace fits.
//! - Traces: [`trace::fit_trace`] fits laws to one force or displacement trace through the same
//!   engine and report (docs/fitting.md, Traces).
//!
//! ```
//! use hertz_tui::model::fit::{Candidate, FitOptions, RestitutionData, fit_restitution, restitution_model};
//! use hertz_tui::model::presets::{DEFAULT_SCENE, Registry};
//! use hertz_tui::model::ForceModel;
//!
//! let scene = Registry::builtin()?.scene(DEFAULT_SCENE)?;
//! let params = scene.impact_params(&scene.quasistatic()?);
//! // Synthetic data from Hunt–Crossley with a = 0.2 s/m, noise-free.
//! let hc = Candidate::Law(ForceModel::HuntCrossley);
//! let pairs: Vec<(f64, f64)> = [0.1, 0.3, 1.0, 3.0]
//!     .iter()
//!     .map(|&v| Ok((v, restitution_model(&params, hc, &[0.2], v)?)))
//!     .collect::<Result<_, hertz_tui::model::fit::FitError>>()?;
//! let data = RestitutionData::from_pairs(&pairs)?;
//! let report = fit_restitution(&scene, &data, &[Candidate::ConstantE, hc], &FitOptions::default())?;
//! assert_eq!(report.fits[0].candidate, hc);
//! assert!((report.fits[0].params[0].value / 0.2 - 1.0).abs() < 1e-6);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
#![warn(missing_docs)]

pub mod candidate;
pub mod criterion;
pub mod data;
pub mod group;
pub mod lsq;
pub mod restitution;
pub mod trace;

use std::collections::HashMap;
use std::sync::{Arc, Mutex};

use rayon::prelude::*;
use serde::Serialize;
use thiserror::Error;

use crate::model::ModelError;
use crate::model::force::ImpactParams;
use crate::model::scene::Scene;

pub use candidate::{CONSTANT_E_ID, Candidate, Unfittable, candidates, identical, unfittable};
pub use criterion::{Criterion, Indistinguishable, Verdict};
pub use data::{FitDataError, RestitutionData, RestitutionSample};
pub use lsq::{LsqError, LsqOptions, LsqProblem, LsqResult, ParamSpec, least_squares};
pub use restitution::{Forward, restitution_model};

use criterion::{RESIDUAL_FLOOR, Scores, judge};
use lsq::Convergence;

/// Why a fit failed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FitError {
    /// The data was refused.
    #[error(transparent)]
    Data(#[from] FitDataError),
    /// The scene was refused.
    #[error(transparent)]
    Model(#[from] ModelError),
    /// The candidate cannot be fitted (a law with no dissipation).
    #[error("{candidate} cannot be fitted: {reason}")]
    Unfittable {
        /// The candidate.
        candidate: Candidate,
        /// Why.
        reason: String,
    },
    /// θ of the wrong length.
    #[error("{candidate} takes {expected} parameter(s), {got} given")]
    Parameters {
        /// The candidate.
        candidate: Candidate,
        /// Its parameter count.
        expected: usize,
        /// What was given.
        got: usize,
    },
    /// An impact solve of the forward model failed.
    #[error("{candidate} at v = {v} m/s with parameter {value:e}: {message}")]
    Solve {
        /// The candidate.
        candidate: Candidate,
        /// The velocity, m/s.
        v: f64,
        /// The parameter value.
        value: f64,
        /// The solver's message.
        message: String,
    },
    /// The least-squares engine failed.
    #[error("{candidate}: {source}")]
    Lsq {
        /// The candidate.
        candidate: Candidate,
        /// Why.
        #[source]
        source: LsqError,
    },
    /// No candidate could be fitted; each one's reason.
    #[error("no law could be fitted: {}", .0.iter().map(|(c, m)| format!("{c}: {m}")).collect::<Vec<_>>().join("; "))]
    NothingFitted(Vec<(Candidate, String)>),
    /// The trace was refused (too few samples for a law's parameters; see [`trace`]).
    #[error(transparent)]
    Trace(#[from] trace::TraceDataError),
    /// No candidates were given.
    #[error("no candidate laws to fit")]
    NoCandidates,
}

/// Options of a restitution fit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitOptions {
    /// The criterion that ranks the laws.
    pub criterion: Criterion,
    /// The least-squares engine's options, the confidence level among them.
    pub lsq: LsqOptions,
    /// Fit the candidates in parallel (rayon).
    pub parallel: bool,
}

impl Default for FitOptions {
    fn default() -> Self {
        FitOptions {
            criterion: Criterion::Aicc,
            lsq: LsqOptions::default(),
            parallel: true,
        }
    }
}

/// One fitted parameter.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FittedParam {
    /// What it is.
    pub spec: ParamSpec,
    /// The best value, SI.
    pub value: f64,
    /// Its standard error (delta method for a log-scale parameter); NaN when not determined.
    pub std_error: f64,
    /// The confidence interval at `level` (multiplicative for a log-scale parameter).
    pub ci: (f64, f64),
    /// The confidence level, e.g. 0.95.
    pub level: f64,
}

/// One candidate fitted to the data.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LawFit {
    /// The candidate.
    pub candidate: Candidate,
    /// Its fitted parameters.
    pub params: Vec<FittedParam>,
    /// Σ(e_model − e)², unweighted.
    pub rss: f64,
    /// Σ((e_model − e)/sd)² when the data gives sd.
    pub chi2: Option<f64>,
    /// e_model(vᵢ) − eᵢ, in the data's order, unweighted.
    pub residuals: Vec<f64>,
    /// Data points.
    pub n_points: usize,
    /// Akaike's criterion.
    pub aic: f64,
    /// AICc (+∞ when N ≤ K + 1).
    pub aicc: f64,
    /// Schwarz's criterion.
    pub bic: f64,
    /// The ranking criterion minus the best's (0 for the best).
    pub delta: f64,
    /// Akaike weight by the ranking criterion.
    pub weight: f64,
    /// Why the engine stopped.
    pub convergence: Convergence,
    /// Engine iterations.
    pub iterations: usize,
    /// Forward-model curve evaluations (each one e at every data velocity).
    pub evaluations: usize,
}

impl LawFit {
    /// The fitted θ.
    pub fn theta(&self) -> Vec<f64> {
        self.params.iter().map(|p| p.value).collect()
    }

    /// e at velocity `v` (m/s) by the fitted law on `scene`: the forward model the fit used.
    pub fn predict(&self, scene: &Scene, v: f64) -> Result<f64, FitError> {
        let params = scene.impact_params(&scene.quasistatic()?);
        self.predict_params(&params, v)
    }

    /// [`LawFit::predict`] on the scene's impact parameters.
    pub fn predict_params(&self, params: &ImpactParams, v: f64) -> Result<f64, FitError> {
        restitution_model(params, self.candidate, &self.theta(), v)
    }

    /// The value of `criterion`.
    pub fn score(&self, criterion: Criterion) -> f64 {
        match criterion {
            Criterion::Aicc => self.aicc,
            Criterion::Bic => self.bic,
        }
    }
}

/// Every candidate's fit, ranked.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FitReport {
    /// The fits, best first by `criterion` (ties: fewer parameters, then the candidates' order).
    pub fits: Vec<LawFit>,
    /// Candidates that could not be fitted, with the reason.
    pub failed: Vec<(Candidate, String)>,
    /// The ranking criterion.
    pub criterion: Criterion,
    /// Groups of fitted laws the data cannot tell apart, best group first.
    pub indistinguishable: Vec<Vec<Candidate>>,
    /// What the ranking says, with its numbers.
    pub verdict: Verdict,
    /// The data was weighted by given standard deviations.
    pub weighted: bool,
}

/// Fits every candidate to `data` on `scene` (k, n, m and the bodies from the scene) and ranks
/// them (see the module documentation).
pub fn fit_restitution(
    scene: &Scene,
    data: &RestitutionData,
    candidates: &[Candidate],
    opts: &FitOptions,
) -> Result<FitReport, FitError> {
    let params = scene.impact_params(&scene.quasistatic()?);
    fit_restitution_params(&params, data, candidates, opts)
}

/// [`fit_restitution`] on the scene's impact parameters.
pub fn fit_restitution_params(
    params: &ImpactParams,
    data: &RestitutionData,
    candidates: &[Candidate],
    opts: &FitOptions,
) -> Result<FitReport, FitError> {
    Fitter::new(params, candidates)?.fit(data, opts)
}

/// The candidates' forward models on one scene, kept between fits: a refit (new data, an edit)
/// reuses their tables of g(ψ) instead of solving them again.
#[derive(Debug, Clone)]
pub struct Fitter {
    params: ImpactParams,
    forwards: Vec<(Candidate, Result<Forward, FitError>)>,
    /// Each candidate's θ from the last fit: the warm start of the next.
    last: Arc<Mutex<HashMap<Candidate, Vec<f64>>>>,
}

impl Fitter {
    /// The forward models of `candidates` on the scene's impact `params`; a candidate that cannot
    /// be modelled is reported as failed by every fit.
    pub fn new(params: &ImpactParams, candidates: &[Candidate]) -> Result<Self, FitError> {
        if candidates.is_empty() {
            return Err(FitError::NoCandidates);
        }
        params.validate()?;
        Ok(Fitter {
            params: *params,
            forwards: candidates
                .iter()
                .map(|&c| (c, Forward::new(params, c)))
                .collect(),
            last: Arc::default(),
        })
    }

    /// Fits every candidate to `data` and ranks them.
    pub fn fit(&self, data: &RestitutionData, opts: &FitOptions) -> Result<FitReport, FitError> {
        // Never stopped, so always `Some`.
        self.fit_until(data, opts, &|| false, &|| {})
            .unwrap_or(Err(FitError::NoCandidates))
    }

    /// [`Fitter::fit`] that gives up (`None`) once `stop` returns true, checked before each
    /// candidate, and calls `done` after each candidate fitted (the explorer's progress).
    pub fn fit_until(
        &self,
        data: &RestitutionData,
        opts: &FitOptions,
        stop: &(dyn Fn() -> bool + Sync),
        done: &(dyn Fn() + Sync),
    ) -> Option<Result<FitReport, FitError>> {
        for p in &data.points {
            if let Err(e) = p.validate() {
                return Some(Err(e.into()));
            }
        }
        let warm = |c: &Candidate| self.last.lock().ok().and_then(|l| l.get(c).cloned());
        let fit = |(c, f): &(Candidate, Result<Forward, FitError>)| {
            if stop() {
                return None;
            }
            let result = f
                .clone()
                .and_then(|f| fit_one_from(&f, data, opts, warm(c).as_deref()));
            if let (Ok(fit), Ok(mut last)) = (&result, self.last.lock()) {
                last.insert(*c, fit.theta());
            }
            done();
            Some((*c, result))
        };
        let results: Option<Vec<(Candidate, Result<LawFit, FitError>)>> = if opts.parallel {
            self.forwards.par_iter().map(fit).collect()
        } else {
            self.forwards.iter().map(fit).collect()
        };
        Some(self.ranked(results?, data, opts))
    }

    /// The report of every candidate's fit or failure, ranked.
    fn ranked(
        &self,
        results: Vec<(Candidate, Result<LawFit, FitError>)>,
        data: &RestitutionData,
        opts: &FitOptions,
    ) -> Result<FitReport, FitError> {
        let mut fits = Vec::new();
        let mut failed = Vec::new();
        for (c, r) in results {
            match r {
                Ok(f) => fits.push(f),
                Err(e) => failed.push((c, e.to_string())),
            }
        }
        if fits.is_empty() {
            return Err(FitError::NothingFitted(failed));
        }
        let order: Vec<Candidate> = self.forwards.iter().map(|(c, _)| *c).collect();
        criterion::rank(&mut fits, opts.criterion, &order);
        let verdict = verdict(self, data, &fits, opts.criterion);
        let indistinguishable = verdict.groups.iter().map(|g| g.members.clone()).collect();
        Ok(FitReport {
            fits,
            failed,
            criterion: opts.criterion,
            indistinguishable,
            verdict,
            weighted: data.weighted(),
        })
    }

    /// The forward model of `candidate`, if it is one of this fitter's.
    pub fn forward(&self, candidate: Candidate) -> Option<&Forward> {
        self.forwards
            .iter()
            .find(|(c, _)| *c == candidate)
            .and_then(|(_, f)| f.as_ref().ok())
    }

    /// The scene's impact parameters.
    pub fn params(&self) -> &ImpactParams {
        &self.params
    }
}

/// Fits one candidate through its forward model.
pub fn fit_one(
    forward: &Forward,
    data: &RestitutionData,
    opts: &FitOptions,
) -> Result<LawFit, FitError> {
    fit_one_from(forward, data, opts, None)
}

/// [`fit_one`] with a warm start `warm` (θ of an earlier fit), used when it fits the data better
/// than the calibrated start.
pub fn fit_one_from(
    forward: &Forward,
    data: &RestitutionData,
    opts: &FitOptions,
    warm: Option<&[f64]>,
) -> Result<LawFit, FitError> {
    let candidate = forward.candidate();
    let specs = candidate.params().map_err(|reason| FitError::Unfittable {
        candidate,
        reason: reason.to_string(),
    })?;
    let n = data.len();
    // Without given sd the noise is estimated from the residuals: it needs a point more.
    let needed = specs.len() + usize::from(!data.weighted());
    if n < needed {
        return Err(FitDataError::TooFewPoints {
            points: n,
            needed,
            law: candidate.id().to_string(),
        }
        .into());
    }
    // Sorted by v so that repeats are solved once; `order` maps back to the data's order.
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| data.points[a].v.total_cmp(&data.points[b].v));
    let vs: Vec<f64> = order.iter().map(|&i| data.points[i].v).collect();
    let es: Vec<f64> = order.iter().map(|&i| data.points[i].e).collect();
    let weighted = data.weighted();
    let inv_sd: Vec<f64> = order
        .iter()
        .map(|&i| data.points[i].sd.map_or(1.0, |sd| 1.0 / sd))
        .collect();
    let residuals = |theta: &[f64]| -> Result<Vec<f64>, String> {
        let model = forward.curve(theta, &vs).map_err(|e| e.to_string())?;
        Ok(model
            .iter()
            .zip(&es)
            .zip(&inv_sd)
            .map(|((m, e), w)| (m - e) * w)
            .collect())
    };
    let mut start = start(forward, &vs, &es)?;
    // A warm start (the previous fit's θ, on a refit) wins if it already fits better.
    if let Some(warm) = warm.filter(|w| w.len() == specs.len()) {
        let rss = |theta: &[f64]| {
            residuals(theta).map_or(f64::INFINITY, |r| r.iter().map(|x| x * x).sum::<f64>())
        };
        if rss(warm) < rss(&start) {
            start = warm.to_vec();
        }
    }
    let problem = LsqProblem {
        params: &specs,
        start,
        residuals: &residuals,
        known_sd: weighted,
    };
    // One parameter: a forward difference steers the steps as well as a central one at half the
    // solves; the covariance still comes from a central one.
    let lsq = LsqOptions {
        difference: lsq::Difference::Forward,
        ..opts.lsq
    };
    let result =
        least_squares(&problem, &lsq).map_err(|source| FitError::Lsq { candidate, source })?;
    // Back to the data's order, unweighted.
    let mut sorted_res = vec![0.0; n];
    for (k, &i) in order.iter().enumerate() {
        sorted_res[i] = result.residuals[k] / inv_sd[k];
    }
    let rss: f64 = sorted_res.iter().map(|r| r * r).sum();
    let floor: f64 = if weighted {
        inv_sd.iter().map(|w| (RESIDUAL_FLOOR * w).powi(2)).sum()
    } else {
        n as f64 * RESIDUAL_FLOOR * RESIDUAL_FLOOR
    };
    let Scores { aic, aicc, bic } = criterion::scores(result.rss, floor, n, specs.len(), weighted);
    let params = specs
        .iter()
        .enumerate()
        .map(|(j, spec)| FittedParam {
            spec: *spec,
            value: result.theta[j],
            std_error: result.std_errors[j],
            ci: result.ci[j],
            level: result.level,
        })
        .collect();
    Ok(LawFit {
        candidate,
        params,
        rss,
        chi2: weighted.then_some(result.rss),
        residuals: sorted_res,
        n_points: n,
        aic,
        aicc,
        bic,
        delta: 0.0,
        weight: f64::NAN,
        convergence: result.convergence,
        iterations: result.iterations,
        evaluations: result.evaluations,
    })
}

/// A start for `forward` from data sorted by v: the calibration at the median velocity to the
/// median e of the middle third of the points.
fn start(forward: &Forward, vs: &[f64], es: &[f64]) -> Result<Vec<f64>, FitError> {
    let n = vs.len();
    let (lo, hi) = (n / 3, (2 * n).div_ceil(3).max(n / 3 + 1).min(n));
    let mut middle: Vec<f64> = es[lo..hi].to_vec();
    middle.sort_by(f64::total_cmp);
    let e = middle[middle.len() / 2];
    let v = vs[n / 2];
    forward.start(v, e)
}

/// Points of the grid over the data's velocity range on which curves are compared.
const GAP_GRID: usize = 48;

/// Groups the ranked fits the data cannot tell apart and says who won (docs/physics.md §9.3): a
/// law joins the group of the best-ranked law still ungrouped when their Δ < 2, or when their
/// curves stay within the noise of each other over the data's velocity range.
fn verdict(
    fitter: &Fitter,
    data: &RestitutionData,
    fits: &[LawFit],
    criterion: Criterion,
) -> Verdict {
    let (v_lo, v_hi) = data.v_range();
    let grid: Vec<f64> = (0..GAP_GRID)
        .map(|i| v_lo * (v_hi / v_lo).powf(i as f64 / (GAP_GRID - 1) as f64))
        .collect();
    let best = &fits[0];
    let noise = if data.weighted() {
        let mean_var = data
            .points
            .iter()
            .map(|p| p.sd.unwrap_or(0.0).powi(2))
            .sum::<f64>()
            / data.len() as f64;
        mean_var.sqrt()
    } else {
        let dof = data.len().saturating_sub(best.params.len()).max(1);
        (best.rss / dof as f64).sqrt()
    }
    .max(10.0 * RESIDUAL_FLOOR);
    let curves: Vec<Option<Vec<f64>>> = fits
        .par_iter()
        .map(|f| {
            fitter
                .forward(f.candidate)
                .and_then(|fw| fw.curve(&f.theta(), &grid).ok())
        })
        .collect();
    let gap = |i: usize, j: usize| -> f64 {
        match (&curves[i], &curves[j]) {
            (Some(a), Some(b)) => a
                .iter()
                .zip(b)
                .map(|(x, y)| (x - y).abs())
                .fold(0.0, f64::max),
            _ => f64::INFINITY,
        }
    };
    judge(fits, criterion, noise, gap, identical, (v_lo, v_hi))
}
