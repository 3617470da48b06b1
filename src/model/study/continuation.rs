//! The explorer's continuation study (docs/continuation.md §8): the periodic orbit the system
//! settles on at the scene's value of the diagram's key, continued both ways to the ends of the
//! diagram's range with every stop, reported stop by stop so that the rigid branch shows while the
//! compliant one is computed, and stopped between steps once a newer request supersedes it.

use crate::model::system::continuation::{
    Branch, ContinuationError, ContinuationOptions, continue_orbit_until,
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
/// is absent when the value is on that end), or why it could not start.
#[derive(Debug, Clone)]
pub struct ContinuedBranch {
    pub contact: Contact,
    pub halves: Result<Vec<Branch>, ContinuationError>,
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

/// Every stop's branch, handing `partial` the branches so far after each stop but the last;
/// `None` once `stop` says so.
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
        data.branches.push(ContinuedBranch {
            contact: *contact,
            halves,
        });
        if i + 1 < study.contacts.len() {
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
            1,
            "one report before the last stop"
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
        // Stopped: nothing.
        assert!(run_continuation(&s, &|| true, &|_| {}).is_none());
    }
}
