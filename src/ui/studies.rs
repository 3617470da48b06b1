//! The bookkeeping of the explorer's studies in flight, like
//! [`Solutions`](super::solutions::Solutions) for impacts: a slot remembers the inputs of its latest
//! request, so asking again with the same inputs computes nothing; every request gets a new
//! generation and an outcome of an older one is stale. The studies themselves run in
//! [`crate::model::study::runner`], on the [`Jobs`](super::jobs::Jobs) queue of the studies: a
//! newer request of a kind supersedes the queued one and stops the running one between rungs or
//! points.

use std::sync::Arc;

use crate::model::study::continuation::ContinuedBranches;
use crate::model::study::fit::FitData;
use crate::model::study::map::MapData;
use crate::model::study::runner::{
    self, CurrentPoint, MeasuredBound, RestitutionData, StabilityData, StudyError, StudyJob,
    StudyKind, StudyOutcome, StudyResult, StudySpec, SweepData, WorkPrecisionData,
};
use crate::model::study::system::{DiagramData, SystemRuns};

use super::jobs::Background;

impl Background for StudyJob {
    /// A newer study of the same kind supersedes the queued and the running one.
    type Slot = StudyKind;
    type Outcome = StudyOutcome;

    fn slot(&self) -> StudyKind {
        self.spec.kind()
    }

    fn generation(&self) -> u64 {
        self.generation
    }

    fn priority(&self) -> u8 {
        self.spec.kind().priority()
    }

    fn run(&self, stop: &(dyn Fn() -> bool + Sync)) -> Option<StudyOutcome> {
        runner::run(self, stop)
    }

    /// A diagram reports its columns so far as it goes.
    fn run_partially(
        &self,
        stop: &(dyn Fn() -> bool + Sync),
        partial: &dyn Fn(StudyOutcome),
    ) -> Option<StudyOutcome> {
        runner::run_partially(self, stop, partial)
    }

    fn panicked(&self, message: &str) -> String {
        format!(
            "a {:?} study panicked ({message}): this is a bug",
            self.spec.kind()
        )
    }
}

#[derive(Debug, Clone, Default)]
struct Slot {
    inputs: Option<StudySpec>,
    generation: u64,
    pending: bool,
    shown: Option<StudyResult>,
}

/// The latest result of every study, with the requests in flight.
#[derive(Debug, Clone, Default)]
pub struct Studies {
    slots: [Slot; StudyKind::ALL.len()],
    last_generation: u64,
}

impl Studies {
    /// A job for `spec` if its inputs differ from those of the last request of its kind.
    pub fn request(&mut self, spec: StudySpec) -> Option<StudyJob> {
        let slot = &mut self.slots[spec.kind().index()];
        if slot.inputs.as_ref() == Some(&spec) {
            return None;
        }
        self.last_generation += 1;
        slot.inputs = Some(spec.clone());
        slot.generation = self.last_generation;
        slot.pending = true;
        Some(StudyJob {
            generation: self.last_generation,
            spec,
        })
    }

    /// Stores an outcome if it answers the latest request of its kind; returns whether it did.
    /// A partial one (a diagram so far) is shown while its study stays pending.
    pub fn accept(&mut self, outcome: StudyOutcome) -> bool {
        let slot = &mut self.slots[outcome.result.kind().index()];
        if outcome.generation != slot.generation || !slot.pending {
            return false;
        }
        slot.pending = outcome.result.is_partial();
        slot.shown = Some(outcome.result);
        true
    }

    /// Cancels the running or queued study of `kind`: the job that stops it (none if nothing of
    /// that kind is pending). Its result so far stays shown; asking for the same inputs again
    /// computes it anew.
    pub fn cancel(&mut self, kind: StudyKind) -> Option<StudyJob> {
        let slot = &mut self.slots[kind.index()];
        if !slot.pending {
            return None;
        }
        self.last_generation += 1;
        slot.inputs = None;
        slot.generation = self.last_generation;
        slot.pending = false;
        Some(StudyJob {
            generation: self.last_generation,
            spec: StudySpec::Stop(kind),
        })
    }

    pub fn is_pending(&self, kind: StudyKind) -> bool {
        self.slots[kind.index()].pending
    }

    /// The latest finished result of a kind (the previous one while a newer request runs).
    pub fn result(&self, kind: StudyKind) -> Option<&StudyResult> {
        self.slots[kind.index()].shown.as_ref()
    }

    pub fn work_precision(&self) -> Option<&Result<Arc<WorkPrecisionData>, StudyError>> {
        match self.result(StudyKind::WorkPrecision) {
            Some(StudyResult::WorkPrecision(r)) => Some(r),
            _ => None,
        }
    }

    pub fn current(&self) -> Option<&Result<CurrentPoint, StudyError>> {
        match self.result(StudyKind::Current) {
            Some(StudyResult::Current(r)) => Some(r),
            _ => None,
        }
    }

    pub fn runs(&self) -> Option<&Result<Arc<StabilityData>, StudyError>> {
        match self.result(StudyKind::Runs) {
            Some(StudyResult::Runs(r)) => Some(r),
            _ => None,
        }
    }

    pub fn bounds(&self) -> Option<&Result<Arc<Vec<MeasuredBound>>, StudyError>> {
        match self.result(StudyKind::Bounds) {
            Some(StudyResult::Bounds(r)) => Some(r),
            _ => None,
        }
    }

    pub fn sweep(&self) -> Option<&Result<Arc<SweepData>, StudyError>> {
        match self.result(StudyKind::Sweep) {
            Some(StudyResult::Sweep(r)) => Some(r),
            _ => None,
        }
    }

    pub fn system(&self) -> Option<&Arc<SystemRuns>> {
        match self.result(StudyKind::System) {
            Some(StudyResult::System(r)) => Some(r),
            _ => None,
        }
    }

    pub fn diagram(&self) -> Option<&Arc<DiagramData>> {
        match self.result(StudyKind::Diagram) {
            Some(StudyResult::Diagram(r)) => Some(r),
            _ => None,
        }
    }

    /// The fit view's fit, or its progress while a slow one runs.
    pub fn fit(&self) -> Option<&Arc<FitData>> {
        match self.result(StudyKind::Fit) {
            Some(StudyResult::Fit(r)) => Some(r),
            _ => None,
        }
    }

    /// The system view's continued branches, or those done so far.
    pub fn continuation(&self) -> Option<&Arc<ContinuedBranches>> {
        match self.result(StudyKind::Continuation) {
            Some(StudyResult::Continuation(r)) => Some(r),
            _ => None,
        }
    }

    /// The map view's maps, or the rows done so far.
    pub fn map(&self) -> Option<&Arc<MapData>> {
        match self.result(StudyKind::Map) {
            Some(StudyResult::Map(r)) => Some(r),
            _ => None,
        }
    }

    pub fn restitution(&self) -> Option<&Result<Arc<RestitutionData>, StudyError>> {
        match self.result(StudyKind::Restitution) {
            Some(StudyResult::Restitution(r)) => Some(r),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::ForceModel;
    use crate::model::study::runner::tests::bounds;
    use crate::model::study::sweep::SweepError;
    use crate::ui::jobs::{Jobs, supersede, take_next};
    use crate::ui::testing::fig5_params;

    /// A failed outcome of `job`, told apart from others by `mark`.
    fn failed(job: &StudyJob, mark: usize) -> StudyOutcome {
        StudyOutcome {
            generation: job.generation,
            result: StudyResult::Bounds(Err(SweepError::TooFewPoints(mark).into())),
        }
    }

    #[test]
    fn same_inputs_compute_nothing_and_stale_outcomes_are_dropped() {
        let mut s = Studies::default();
        let first = s.request(bounds(0.3)).unwrap();
        assert_eq!(s.request(bounds(0.3)), None);
        assert!(s.is_pending(StudyKind::Bounds));
        let second = s.request(bounds(0.4)).unwrap();
        assert!(!s.accept(failed(&first, 0)));
        assert!(s.accept(failed(&second, 1)));
        assert!(!s.is_pending(StudyKind::Bounds));
        assert!(matches!(
            s.bounds(),
            Some(Err(StudyError::Sweep(SweepError::TooFewPoints(1))))
        ));
        // Other kinds are independent.
        assert!(s.runs().is_none());
        assert!(
            s.request(StudySpec::Runs {
                model: ForceModel::Proposed,
                params: fig5_params(0.3),
                dt: 1e-6,
            })
            .is_some()
        );
        assert_eq!(s.request(bounds(0.4)), None, "answered: asks nothing again");
    }

    /// A job of `kind`, one of those the tests queue.
    fn job(generation: u64, kind: StudyKind) -> StudyJob {
        let (model, params) = (ForceModel::Proposed, fig5_params(0.3));
        let spec = match kind {
            StudyKind::WorkPrecision => StudySpec::WorkPrecision { model, params },
            StudyKind::Runs => StudySpec::Runs {
                model,
                params,
                dt: 1e-6,
            },
            StudyKind::Bounds => StudySpec::Bounds { model, params },
            other => panic!("the tests queue no {other:?} study"),
        };
        StudyJob { generation, spec }
    }

    #[test]
    fn a_cancel_stops_the_running_study_keeps_what_it_showed_and_asks_again_on_request() {
        let mut s = Studies::default();
        assert_eq!(s.cancel(StudyKind::Bounds), None, "nothing to cancel");
        let first = s.request(bounds(0.3)).unwrap();
        assert!(s.accept(failed(&first, 0)));
        let second = s.request(bounds(0.4)).unwrap();
        let stop = s.cancel(StudyKind::Bounds).unwrap();
        assert_eq!(stop.spec, StudySpec::Stop(StudyKind::Bounds));
        assert!(
            stop.generation > second.generation,
            "supersedes the running one"
        );
        assert!(!s.is_pending(StudyKind::Bounds));
        assert!(
            !s.accept(failed(&second, 1)),
            "the cancelled one's outcome is dropped"
        );
        assert!(matches!(
            s.bounds(),
            Some(Err(StudyError::Sweep(SweepError::TooFewPoints(0))))
        ));
        assert!(
            runner::run(&stop, &|| false).is_none(),
            "a stop computes nothing"
        );
        assert!(
            s.request(bounds(0.4)).is_some(),
            "the same inputs run again"
        );
    }

    #[test]
    fn newer_studies_replace_queued_ones_and_quick_kinds_go_first() {
        let mut queue = vec![
            job(1, StudyKind::WorkPrecision),
            job(2, StudyKind::Bounds),
            job(3, StudyKind::Runs),
        ];
        supersede(&mut queue, job(4, StudyKind::Runs));
        let kinds: Vec<StudyKind> = queue.iter().map(|j| j.spec.kind()).collect();
        assert_eq!(
            kinds,
            [StudyKind::WorkPrecision, StudyKind::Bounds, StudyKind::Runs]
        );
        assert_eq!(take_next(&mut queue).map(|j| j.generation), Some(4));
        assert_eq!(take_next(&mut queue).map(|j| j.generation), Some(2));
        assert_eq!(take_next(&mut queue).map(|j| j.generation), Some(1));
        assert!(take_next(&mut queue).is_none());
    }

    #[test]
    fn a_study_on_its_queue_reports_and_the_queue_ends_with_its_handle() {
        let (tx, rx) = std::sync::mpsc::channel();
        let queue = Jobs::spawn("test-studies", 1, move |report| tx.send(report).is_ok()).unwrap();
        assert!(queue.submit(job(3, StudyKind::Runs)));
        let outcome = rx.recv().unwrap().unwrap();
        assert_eq!(outcome.generation, 3);
        assert!(matches!(outcome.result, StudyResult::Runs(Ok(_))));
        drop(queue);
        assert!(rx.recv().is_err(), "the thread ended");
    }
}
