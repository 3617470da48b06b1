//! The explorer's system studies (docs/systems.md): a run of every stop with dense samples, and a
//! bifurcation diagram of every stop that reports what it has so far, so that the diagram fills
//! in on the screen as it computes.

use std::ops::ControlFlow;

use crate::model::system::compliant::verdict::{Verdict, verdict_of};
use crate::model::system::{
    self, Column, Contact, DiagramOptions, History, Param, RunOptions, SystemError, SystemModel,
};

/// Runs of a system with each stop.
#[derive(Debug, Clone, PartialEq)]
pub struct SystemStudy {
    pub model: SystemModel,
    pub contacts: Vec<Contact>,
    pub run: RunOptions,
}

/// Each stop's run, or why it failed, and which approach the system needs (with a compliant
/// stop among them).
#[derive(Debug, Clone)]
pub struct SystemRuns {
    pub runs: Vec<(Contact, Result<History, SystemError>)>,
    pub verdict: Option<Result<Verdict, SystemError>>,
}

/// A bifurcation diagram of a system with each stop.
#[derive(Debug, Clone, PartialEq)]
pub struct DiagramStudy {
    pub model: SystemModel,
    pub contacts: Vec<Contact>,
    pub param: Param,
    pub values: Vec<f64>,
    pub options: DiagramOptions,
}

/// One stop's diagram so far: its columns in the order of the values, and why it stopped short.
#[derive(Debug, Clone)]
pub struct Branch {
    pub contact: Contact,
    pub columns: Vec<Column>,
    pub error: Option<SystemError>,
}

/// The diagrams of every stop so far.
#[derive(Debug, Clone)]
pub struct DiagramData {
    pub param: Param,
    /// The values asked for (the columns fill them in order).
    pub values: Vec<f64>,
    pub branches: Vec<Branch>,
    /// Every stop's diagram is done (or failed): no more columns will come.
    pub complete: bool,
}

/// The values of a diagram: `points` evenly from `from` to `to`, both ends exactly.
pub fn values(from: f64, to: f64, points: usize) -> Vec<f64> {
    let n = points.max(2);
    (0..n)
        .map(|i| {
            if i + 1 == n {
                to
            } else {
                from + (to - from) * i as f64 / (n - 1) as f64
            }
        })
        .collect()
}

/// Every stop's run.
pub fn run_system(study: &SystemStudy) -> SystemRuns {
    let runs: Vec<(Contact, Result<History, SystemError>)> = study
        .contacts
        .iter()
        .map(|c| (*c, system::simulate(&study.model, c, &study.run)))
        .collect();
    // The verdict weighs the runs just made (the dense samples do not change the impacts).
    let rigid = runs.iter().find_map(|(c, h)| match (c, h) {
        (Contact::Rigid { restitution }, Ok(h)) if *restitution == study.model.restitution => {
            Some(h)
        }
        _ => None,
    });
    let verdict = runs.iter().find_map(|(c, h)| match c {
        Contact::Compliant { model: law, .. } => Some(
            h.clone()
                .and_then(|h| verdict_of(&study.model, *law, &study.run, &h, rigid)),
        ),
        Contact::Rigid { .. } => None,
    });
    SystemRuns { runs, verdict }
}

/// Partial reports per stop's diagram at most: a report copies the columns so far, so a few
/// dozen keep the copies a small multiple of the diagram.
const REPORTS_PER_DIAGRAM: usize = 16;

/// Every stop's diagram, one after the other, handing `partial` the data so far every few
/// columns; `None` once `stop` says so.
pub fn run_diagram(
    study: &DiagramStudy,
    stop: &(dyn Fn() -> bool + Sync),
    partial: &dyn Fn(DiagramData),
) -> Option<DiagramData> {
    let every = study.values.len().div_ceil(REPORTS_PER_DIAGRAM).max(1);
    let mut data = DiagramData {
        param: study.param,
        values: study.values.clone(),
        branches: Vec::new(),
        complete: false,
    };
    for contact in &study.contacts {
        data.branches.push(Branch {
            contact: *contact,
            columns: Vec::new(),
            error: None,
        });
        let mut columns = Vec::new();
        let result = system::bifurcation(
            &study.model,
            contact,
            study.param,
            &study.values,
            &study.options,
            |column| {
                if stop() {
                    return ControlFlow::Break(());
                }
                columns.push(column.clone());
                if columns.len() % every == 0 && columns.len() < study.values.len() {
                    let mut so_far = data.clone();
                    if let Some(last) = so_far.branches.last_mut() {
                        last.columns = columns.clone();
                    }
                    partial(so_far);
                }
                ControlFlow::Continue(())
            },
        );
        if stop() {
            return None;
        }
        if let Some(last) = data.branches.last_mut() {
            last.columns = columns;
            last.error = result.err();
        }
    }
    data.complete = true;
    Some(data)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::system::{STANDARD_GRAVITY, SystemKind, SystemSpec};
    use std::sync::Mutex;

    fn ball(amplitude: f64) -> SystemModel {
        let spec = SystemSpec {
            kind: SystemKind::BouncingBall {
                amplitude,
                frequency: 20.0,
                gravity: STANDARD_GRAVITY,
            },
        };
        SystemModel::new(spec, 0.033, 0.5).unwrap()
    }

    #[test]
    fn values_include_both_ends_exactly() {
        let v = values(0.9, 3.5, 27);
        assert_eq!(v.len(), 27);
        assert_eq!(v[0], 0.9);
        assert_eq!(v[26], 3.5);
        assert!((v[1] - 1.0).abs() < 1e-12);
    }

    #[test]
    fn a_diagram_reports_growing_prefixes_then_the_whole_which_the_last_prefix_begins() {
        let values: Vec<f64> = (0..32).map(|i| 1.1 + 0.01 * f64::from(i)).collect();
        let study = DiagramStudy {
            model: ball(8e-4),
            contacts: vec![Contact::rigid(0.5)],
            param: Param::System(crate::model::system::SystemKey::Gamma),
            values: values.clone(),
            options: DiagramOptions {
                run: RunOptions {
                    transient_impacts: 100,
                    recorded_impacts: 8,
                    ..RunOptions::default()
                },
                ..DiagramOptions::default()
            },
        };
        let seen = Mutex::new(Vec::new());
        let whole = run_diagram(&study, &|| false, &|d| {
            seen.lock().unwrap().push(d.branches[0].columns.clone())
        })
        .unwrap();
        assert!(whole.complete);
        let columns = &whole.branches[0].columns;
        assert_eq!(columns.len(), values.len(), "{:?}", whole.branches[0].error);
        let seen = seen.into_inner().unwrap();
        // 32 values, a report every 2 columns: 15 before the end.
        assert_eq!(seen.len(), 15);
        for (k, prefix) in seen.iter().enumerate() {
            assert_eq!(prefix.len(), 2 * (k + 1));
            assert_eq!(prefix[..], columns[..prefix.len()]);
        }
        // Stopped: nothing.
        assert!(run_diagram(&study, &|| true, &|_| {}).is_none());
    }
}
