//! The explorer's continuation study (docs/continuation.md §8): the periodic orbit the system
//! settles on at the scene's value of the diagram's key, continued both ways to the ends of the
//! diagram's range with every stop, reported stop by stop so that the rigid branch shows while the
//! compliant one is computed, and stopped between steps once a newer request supersedes it.
//! Where a branch has a period doubling, the study switches onto the doubled branch born there
//! and continues it over the same range (docs/continuation.md §3, §8).

use crate::model::system::continuation::{
    Branch, ContinuationError, ContinuationOptions, SpecialKind, continue_orbit_until,
    switch_at_period_doubling_until,
};
use crate::model::system::{Contact, OrbitGuess, Param, SystemModel};

/// Continue the orbit of `model` in `param` over `range` with each stop.
#[derive(Debug, Clone, PartialEq)]
pub struct ContinuationStudy {
    pub model: SystemModel,
    pub contacts: Vec<Contact>,
    pub param: Param,
    /// The diagram's range, SI, in either order.
    pub range: (f64, f64),
    /// Which orbit (`forcing_cycles`/`impacts` 0: the one the attractor run settles on).
    pub guess: OrbitGuess,
    pub options: ContinuationOptions,
}

/// One stop's branch: the halves from the scene's value towards each end of the range (a half
/// is absent when the value is on that end), or why it could not start; and the doubled branch
/// born at each half's first period doubling, or why the switch onto it failed.
#[derive(Debug, Clone)]
pub struct ContinuedBranch {
    pub contact: Contact,
    pub halves: Result<Vec<Branch>, ContinuationError>,
    pub doubled: Vec<Result<Branch, ContinuationError>>,
}

/// Every stop's branch so far.
#[derive(Debug, Clone)]
pub struct ContinuedBranches {
    pub param: Param,
    /// Where the branches start (the scene's value, within the range), SI.
    pub start: f64,
    pub branches: Vec<ContinuedBranch>,
    /// Every stop's branch is done (or failed).
    pub complete: bool,
}

/// Where the branch starts: the scene's value of the key, clamped to the range (the run there
/// is the attractor whose period is continued).
pub fn start_value(study: &ContinuationStudy) -> Result<f64, ContinuationError> {
    let (lo, hi) = (
        study.range.0.min(study.range.1),
        study.range.0.max(study.range.1),
    );
    Ok(study.param.get(&study.model)?.clamp(lo, hi))
}

/// Every stop's branch and doubled branches, handing `partial` the branches so far after each
/// stop's branch and after its doubled ones but the last stop's; `None` once `stop` says so.
pub fn run_continuation(
    study: &ContinuationStudy,
    stop: &(dyn Fn() -> bool + Sync),
    partial: &dyn Fn(ContinuedBranches),
) -> Option<ContinuedBranches> {
    let start = start_value(study);
    let mut data = ContinuedBranches {
        param: study.param,
        start: *start.as_ref().unwrap_or(&study.range.0),
        branches: Vec::new(),
        complete: false,
    };
    for (i, contact) in study.contacts.iter().enumerate() {
        let halves = start.clone().and_then(|from| {
            let mut halves = Vec::new();
            for to in [study.range.0, study.range.1] {
                if to == from {
                    continue;
                }
                halves.push(continue_orbit_until(
                    &study.model,
                    contact,
                    study.param,
                    (from, to),
                    &study.guess,
                    &study.options,
                    stop,
                )?);
            }
            Ok(halves)
        });
        if stop() || matches!(halves, Err(ContinuationError::Stopped)) {
            return None;
        }
        let doubling: Vec<Branch> = halves
            .as_ref()
            .map(|h| {
                h.iter()
                    .filter(|b| b.special(SpecialKind::PeriodDoubling).next().is_some())
                    .cloned()
                    .collect()
            })
            .unwrap_or_default();
        data.branches.push(ContinuedBranch {
            contact: *contact,
            halves,
            doubled: Vec::new(),
        });
        if doubling.is_empty() && i + 1 == study.contacts.len() {
            break;
        }
        partial(data.clone());
        for half in &doubling {
            let Some(pd) = half.special(SpecialKind::PeriodDoubling).next() else {
                continue;
            };
            let doubled = switch_at_period_doubling_until(
                &study.model,
                contact,
                study.param,
                study.range,
                half,
                pd,
                &study.options,
                stop,
            );
            if stop() || matches!(doubled, Err(ContinuationError::Stopped)) {
                return None;
            }
            if let Some(last) = data.branches.last_mut() {
                last.doubled.push(doubled);
            }
        }
        if !doubling.is_empty() && i + 1 < study.contacts.len() {
            partial(data.clone());
        }
    }
    data.complete = true;
    Some(data)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::system::continuation::SpecialKind;
    use crate::model::system::{RunOptions, STANDARD_GRAVITY, SystemKey, SystemKind, SystemSpec};
    use std::sync::Mutex;

    fn study(gamma_range: (f64, f64)) -> ContinuationStudy {
        let spec = SystemSpec {
            kind: SystemKind::BouncingBall {
                amplitude: 8e-4,
                frequency: 20.0,
                gravity: STANDARD_GRAVITY,
            },
        };
        let model = SystemModel::new(spec, 0.033, 0.5).unwrap();
        ContinuationStudy {
            model,
            contacts: vec![Contact::rigid(0.5), Contact::rigid(0.5)],
            param: Param::System(SystemKey::Gamma),
            range: gamma_range,
            guess: OrbitGuess {
                forcing_cycles: 0,
                impacts: 0,
                start: None,
                attractor: RunOptions {
                    transient_impacts: 200,
                    recorded_impacts: 20,
                    ..RunOptions::default()
                },
            },
            options: ContinuationOptions::default(),
        }
    }

    /// Γ_PD of the ball's period-1 orbit at e = 0.5 (docs/continuation.md §5; its closed form
    /// is tested to 1e-8 in tests/model).
    const GAMMA_PD: f64 = 1.5268237;

    #[test]
    fn both_halves_meet_at_the_scene_value_and_the_upper_one_finds_the_period_doubling() {
        let s = study((1.2, 2.0));
        let start = start_value(&s).unwrap();
        let reports = Mutex::new(0);
        let data = run_continuation(&s, &|| false, &|d| {
            assert!(!d.complete);
            *reports.lock().unwrap() += 1;
        })
        .unwrap();
        assert!(data.complete);
        assert_eq!(
            *reports.lock().unwrap(),
            3,
            "a report after each stop's branch and the first stop's doubled branch"
        );
        let halves = data.branches[0].halves.as_ref().unwrap();
        assert_eq!(halves.len(), 2);
        for half in halves {
            assert!((half.points[0].values[0] - start).abs() < 1e-12);
        }
        let pd: Vec<f64> = halves
            .iter()
            .flat_map(|h| h.special(SpecialKind::PeriodDoubling))
            .map(|s| s.point.values[0])
            .collect();
        assert_eq!(pd.len(), 1, "{pd:?}");
        assert!((pd[0] - GAMMA_PD).abs() < 1e-6, "{}", pd[0]);
        // Switched onto the doubled branch there, continued to the range's end, with its own
        // doubling (docs/continuation.md §5: Γ = 1.6671307).
        let doubled = &data.branches[0].doubled;
        assert_eq!(doubled.len(), 1);
        let d = doubled[0].as_ref().unwrap();
        assert_eq!((d.cycles, d.stops.len()), (2, 2));
        assert!((d.points[0].values[0] - GAMMA_PD).abs() < 1e-6);
        let last = d.points.last().unwrap().values[0];
        assert!((last - 2.0).abs() < 1e-9, "ends on the range's end: {last}");
        let pd2: Vec<f64> = d
            .special(SpecialKind::PeriodDoubling)
            .map(|s| s.point.values[0])
            .collect();
        assert_eq!(pd2.len(), 1, "{pd2:?}");
        assert!((pd2[0] - 1.6671307).abs() < 1e-6, "{}", pd2[0]);
        // Stopped: nothing.
        assert!(run_continuation(&s, &|| true, &|_| {}).is_none());
    }

    #[test]
    fn a_stop_while_switching_onto_the_doubled_branch_gives_nothing() {
        let s = study((1.2, 2.0));
        // The branches are done after the first report; stop the switch that follows it.
        let reported = std::sync::atomic::AtomicBool::new(false);
        let stop = || reported.load(std::sync::atomic::Ordering::SeqCst);
        let data = run_continuation(&s, &stop, &|_| {
            reported.store(true, std::sync::atomic::Ordering::SeqCst);
        });
        assert!(data.is_none());
    }
}
