//! The explorer's fit study (docs/fitting.md, The explorer's fit view): every candidate law fitted
//! to measured restitution on the scene's bodies, with each fitted law's e(v₀) along the chart's
//! velocities. It gives up as soon as a newer edit supersedes it and reports how many laws are
//! done while a slow fit runs.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc::RecvTimeoutError;
use std::time::{Duration, Instant};

use crate::model::ImpactParams;
use crate::model::fit::{
    Candidate, FitError, FitOptions, FitReport, Fitter, LawFit, RestitutionData,
};

/// A fit of `candidates` to `data` on the scene's impact parameters.
#[derive(Debug, Clone, PartialEq)]
pub struct FitStudy {
    pub params: ImpactParams,
    pub data: RestitutionData,
    pub candidates: Vec<Candidate>,
    /// Where each fitted law's e(v₀) is drawn, m/s.
    pub velocities: Vec<f64>,
}

/// A fitted law's e(v₀) at the study's velocities (a velocity its forward model failed at is
/// left out).
#[derive(Debug, Clone, PartialEq)]
pub struct FitCurve {
    pub candidate: Candidate,
    pub points: Vec<(f64, f64)>,
}

/// The fit so far: while it runs, how many candidates are done; at the end, the report and
/// the curves.
#[derive(Debug, Clone, PartialEq)]
pub struct FitData {
    /// The data fitted (a newer file's fit may still be running).
    pub data: RestitutionData,
    /// (candidates fitted, candidates in all).
    pub progress: (usize, usize),
    /// `None` while the fit runs.
    pub report: Option<Result<FitReport, FitError>>,
    /// Each fitted law's curve, in the report's order.
    pub curves: Vec<FitCurve>,
}

impl FitData {
    /// Every candidate fitted and ranked (or the fit failed): nothing more will come.
    pub fn complete(&self) -> bool {
        self.report.is_some()
    }
}

/// A fit that has run this long reports its progress; a quicker one shows only its result, so
/// that an edit answered at once does not flash a progress note.
const QUIET: Duration = Duration::from_millis(300);

/// How often a running fit looks at its progress.
const POLL: Duration = Duration::from_millis(50);

/// Runs `study`, handing `partial` the progress of a slow fit; `None` once `stop` says so.
pub fn run_fit(
    study: &FitStudy,
    stop: &(dyn Fn() -> bool + Sync),
    partial: &dyn Fn(FitData),
) -> Option<FitData> {
    let total = study.candidates.len();
    let fitter = match Fitter::new(&study.params, &study.candidates) {
        Ok(fitter) => fitter,
        Err(e) => return Some(failed(study, e)),
    };
    let done = AtomicUsize::new(0);
    let count = || {
        done.fetch_add(1, Ordering::Relaxed);
    };
    // The laws are fitted on a thread of their own (in parallel there), so that this one can
    // report how many are done: `partial` need not be shared between threads.
    let (fitter, count) = (&fitter, &count);
    let report = std::thread::scope(|scope| {
        let (tx, rx) = std::sync::mpsc::channel();
        let fitting = scope.spawn(move || {
            let report = fitter.fit_until(&study.data, &FitOptions::default(), stop, count);
            // The receiver waits until this is sent or the thread ends.
            let _ = tx.send(report);
        });
        let started = Instant::now();
        let mut shown = 0;
        loop {
            match rx.recv_timeout(POLL) {
                Ok(report) => return Ok(report),
                Err(RecvTimeoutError::Timeout) => {}
                // The thread ended without a report: it panicked.
                Err(RecvTimeoutError::Disconnected) => return fitting.join().map(|()| None),
            }
            let n = done.load(Ordering::Relaxed);
            if started.elapsed() >= QUIET && n != shown && n < total && !stop() {
                shown = n;
                partial(FitData {
                    data: study.data.clone(),
                    progress: (n, total),
                    report: None,
                    curves: Vec::new(),
                });
            }
        }
    });
    // A panic in a forward model is a bug: the queue reports it as one.
    let report = match report {
        Ok(report) => report?,
        Err(payload) => std::panic::resume_unwind(payload),
    };
    let report = match report {
        Ok(report) => report,
        Err(e) => return Some(failed(study, e)),
    };
    let mut curves = Vec::with_capacity(report.fits.len());
    for fit in &report.fits {
        if stop() {
            return None;
        }
        curves.push(curve(fitter, fit, &study.velocities));
    }
    Some(FitData {
        data: study.data.clone(),
        progress: (total, total),
        report: Some(Ok(report)),
        curves,
    })
}

fn failed(study: &FitStudy, e: FitError) -> FitData {
    let total = study.candidates.len();
    FitData {
        data: study.data.clone(),
        progress: (total, total),
        report: Some(Err(e)),
        curves: Vec::new(),
    }
}

/// `fit`'s e(v₀) at `vs` through the forward model the fit used; point by point where the
/// whole curve fails, so that one velocity beyond a law's range does not hide the rest.
fn curve(fitter: &Fitter, fit: &LawFit, vs: &[f64]) -> FitCurve {
    let theta = fit.theta();
    let points = match fitter.forward(fit.candidate) {
        Some(forward) => match forward.curve(&theta, vs) {
            Ok(es) => vs.iter().copied().zip(es).collect(),
            Err(_) => vs
                .iter()
                .filter_map(|&v| forward.e(&theta, v).ok().map(|e| (v, e)))
                .collect(),
        },
        None => Vec::new(),
    };
    FitCurve {
        candidate: fit.candidate,
        points: points
            .into_iter()
            .filter(|(_, e): &(f64, f64)| e.is_finite())
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::ForceModel;
    use crate::model::fit::restitution_model;
    use crate::model::presets::{DEFAULT_SCENE, Registry};

    fn study(candidates: Vec<Candidate>) -> FitStudy {
        let scene = Registry::builtin().unwrap().scene(DEFAULT_SCENE).unwrap();
        let params = scene.impact_params(&scene.quasistatic().unwrap());
        let hc = Candidate::Law(ForceModel::HuntCrossley);
        let pairs: Vec<(f64, f64)> = [0.1, 0.2, 0.5, 1.0, 2.0]
            .iter()
            .map(|&v| (v, restitution_model(&params, hc, &[0.3], v).unwrap()))
            .collect();
        FitStudy {
            params,
            data: RestitutionData::from_pairs(&pairs).unwrap(),
            candidates,
            velocities: vec![0.05, 0.5, 3.0],
        }
    }

    /// The curve of the law that made the data goes through it: e at 0.5 m/s is the datum.
    #[test]
    fn the_generating_law_ranks_first_and_its_curve_reads_the_data() {
        let hc = Candidate::Law(ForceModel::HuntCrossley);
        let s = study(vec![Candidate::ConstantE, hc]);
        let data = run_fit(&s, &|| false, &|_| {}).unwrap();
        let report = data.report.unwrap().unwrap();
        assert_eq!(report.fits[0].candidate, hc);
        assert_eq!(data.progress, (2, 2));
        let first = &data.curves[0];
        assert_eq!(first.candidate, hc);
        let at = first.points.iter().find(|p| p.0 == 0.5).unwrap().1;
        assert!((at - s.data.points[2].e).abs() < 1e-6, "{at}");
        assert_eq!(data.curves.len(), report.fits.len());
    }

    #[test]
    fn a_superseded_fit_reports_nothing() {
        let s = study(vec![Candidate::ConstantE]);
        assert!(run_fit(&s, &|| true, &|_| {}).is_none());
    }

    /// A newer edit stops a fit between two laws: told to stop after its first check, a fit of
    /// every candidate fits one law and reports nothing.
    #[test]
    fn a_fit_superseded_after_its_first_law_fits_no_other() {
        use crate::model::fit::candidates;
        let s = study(candidates());
        let fitter = Fitter::new(&s.params, &s.candidates).unwrap();
        let checks = AtomicUsize::new(0);
        let done = AtomicUsize::new(0);
        let stop = || checks.fetch_add(1, Ordering::Relaxed) >= 1;
        let count = || {
            done.fetch_add(1, Ordering::Relaxed);
        };
        let opts = FitOptions {
            parallel: false,
            ..FitOptions::default()
        };
        assert!(fitter.fit_until(&s.data, &opts, &stop, &count).is_none());
        assert_eq!(done.load(Ordering::Relaxed), 1, "of {}", s.candidates.len());
        // Not stopped, every candidate is done once.
        done.store(0, Ordering::Relaxed);
        let report = fitter
            .fit_until(&s.data, &opts, &|| false, &count)
            .unwrap()
            .unwrap();
        assert_eq!(done.load(Ordering::Relaxed), s.candidates.len());
        assert_eq!(report.fits.len() + report.failed.len(), s.candidates.len());
    }

    #[test]
    fn no_candidates_is_an_error_not_a_panic() {
        let s = study(Vec::new());
        let data = run_fit(&s, &|| false, &|_| {}).unwrap();
        assert!(matches!(data.report, Some(Err(FitError::NoCandidates))));
    }
}
