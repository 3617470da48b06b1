//! A bifurcation diagram: one column of recorded impacts per parameter value.
#![warn(missing_docs)]

use std::f64::consts::PI;
use std::ops::ControlFlow;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc;

use serde::Serialize;

use super::error::SystemError;
use super::model::SystemModel;
use super::param::Param;
use super::run::{EndReason, History, RunOptions, State};
use super::spec::SystemKind;

/// The recorded impacts at one parameter value.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Column {
    /// Index of the value in the diagram's list.
    pub index: usize,
    /// The parameter value.
    pub value: f64,
    /// Approach speed relative to the stop at each recorded impact, m/s (chatter accumulation
    /// points count with their zero speed).
    pub velocities: Vec<f64>,
    /// Forcing phase ωt mod 2π of each recorded impact, rad.
    pub phases: Vec<f64>,
    /// Which stop each recorded impact hit.
    pub stops: Vec<usize>,
    /// The period of the recorded sequence if it repeats: (impacts n, forcing periods m).
    pub period: Option<(u32, u32)>,
    /// Why the run at this value ended (few or no impacts: the body stopped impacting).
    pub end: EndReason,
}

/// A whole diagram.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Diagram {
    /// The varied parameter's dotted path.
    pub key: String,
    /// The columns in the order of the values.
    pub columns: Vec<Column>,
}

/// How a diagram is run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DiagramOptions {
    /// The run at each value; its `initial` (a state of the model passed in, carried to each
    /// value at the same phase and gap) starts each chunk.
    pub run: super::run::RunOptions,
    /// Budget of values × (transient + recorded) impacts for the whole diagram.
    pub max_total_impacts: usize,
    /// Values followed in sequence by one worker (the attractor at one value starts the next);
    /// chunks run in parallel on rayon's pool. 0: chosen from the number of values and threads.
    pub chunk: usize,
}

impl Default for DiagramOptions {
    fn default() -> DiagramOptions {
        DiagramOptions {
            run: super::run::RunOptions::default(),
            max_total_impacts: 50_000_000,
            chunk: 0,
        }
    }
}

/// The engine of [`bifurcation`](super::bifurcation): values split into chunks followed in
/// sequence, chunks on rayon's pool, columns handed to `on_column` in order on this thread.
pub(super) fn run<R>(
    model: &SystemModel,
    param: Param,
    values: &[f64],
    options: &DiagramOptions,
    run: R,
    mut on_column: impl FnMut(&Column) -> ControlFlow<()>,
) -> Result<Diagram, SystemError>
where
    R: Fn(&SystemModel, &RunOptions) -> Result<History, SystemError> + Sync,
{
    if values.is_empty() {
        return Err(SystemError::NoValues);
    }
    let per_value = options.run.transient_impacts + options.run.recorded_impacts;
    let needed = values.len() as u128 * per_value as u128;
    if needed > options.max_total_impacts as u128 {
        return Err(SystemError::DiagramBudget {
            needed,
            values: values.len(),
            per_value,
            budget: options.max_total_impacts,
        });
    }
    // Every value is checked before any work, so that a bad one is reported at once.
    let models = values
        .iter()
        .map(|&v| param.apply(model, v))
        .collect::<Result<Vec<_>, _>>()?;
    let threads = rayon::current_num_threads().max(1);
    let chunk = if options.chunk > 0 {
        options.chunk
    } else {
        values.len().div_ceil(4 * threads).max(1)
    };
    let chunks = values.len().div_ceil(chunk);
    let next = AtomicUsize::new(0);
    let cancelled = AtomicBool::new(false);
    let (sender, receiver) = mpsc::channel::<(usize, Result<Column, SystemError>)>();
    let worker = |sender: mpsc::Sender<(usize, Result<Column, SystemError>)>| {
        loop {
            let c = next.fetch_add(1, Ordering::Relaxed);
            if c >= chunks || cancelled.load(Ordering::Relaxed) {
                break;
            }
            // Each chunk starts from the given state (of `model`), then follows the attractor.
            let mut state: Option<(State, &SystemModel)> = options.run.initial.map(|s| (s, model));
            for i in c * chunk..((c + 1) * chunk).min(values.len()) {
                if cancelled.load(Ordering::Relaxed) {
                    return;
                }
                let m = &models[i];
                let run_options = RunOptions {
                    initial: state.map(|(s, from)| rebase(s, from, m)),
                    ..options.run
                };
                let column = run(m, &run_options).map(|h| {
                    state = Some((h.end_state, m));
                    column_of(i, values[i], &h, m.spec.period())
                });
                let column = column.map_err(|e| match e {
                    SystemError::ImpactBudget { budget, time, .. } => SystemError::ImpactBudget {
                        what: format!("the diagram at {} = {}", param.path(), values[i]),
                        budget,
                        time,
                    },
                    other => other,
                });
                let failed = column.is_err();
                if sender.send((i, column)).is_err() || failed {
                    return;
                }
            }
        }
    };
    let mut columns: Vec<Option<Column>> = vec![None; values.len()];
    let mut emitted = 0;
    let mut outcome = Ok(());
    std::thread::scope(|scope| {
        let worker = &worker;
        let pool_sender = sender.clone();
        scope.spawn(move || {
            rayon::scope(|s| {
                for _ in 0..threads {
                    let sender = pool_sender.clone();
                    s.spawn(move |_| worker(sender));
                }
            });
        });
        drop(sender);
        for (i, column) in receiver.iter() {
            match column {
                Err(e) => {
                    outcome = Err(e);
                    break;
                }
                Ok(column) => columns[i] = Some(column),
            }
            while emitted < columns.len() {
                let Some(column) = &columns[emitted] else {
                    break;
                };
                if on_column(column).is_break() {
                    outcome = Err(SystemError::Cancelled);
                    break;
                }
                emitted += 1;
            }
            if outcome.is_err() {
                break;
            }
        }
        cancelled.store(true, Ordering::Relaxed);
    });
    outcome?;
    Ok(Diagram {
        key: param.path(),
        columns: columns.into_iter().flatten().collect(),
    })
}

/// A state of the run at `from` carried to `to` at the same forcing phase, in the first period
/// (the systems are periodic in t; a small t keeps ωt accurate along a long diagram), with the
/// same gap and relative velocity to the table, or inside the new stops.
pub(super) fn rebase(state: State, from: &SystemModel, to: &SystemModel) -> State {
    let phase = (from.spec.omega() * state.t).rem_euclid(2.0 * PI);
    let t = phase / to.spec.omega();
    match (from.spec.kind, to.spec.kind) {
        (
            SystemKind::BouncingBall {
                amplitude: a_from, ..
            },
            SystemKind::BouncingBall {
                amplitude: a_to, ..
            },
        ) => {
            let (w_from, w_to) = (from.spec.omega(), to.spec.omega());
            let (s, c) = phase.sin_cos();
            let gap = (state.x - a_from * s).max(0.0);
            let rate = state.v - a_from * w_from * c;
            State {
                t,
                x: a_to * s + gap,
                v: a_to * w_to * c + rate,
            }
        }
        (
            _,
            SystemKind::ImpactOscillator {
                gap, second_gap, ..
            },
        ) => {
            let low = -second_gap.unwrap_or(f64::INFINITY);
            let x = state.x.clamp(low, gap);
            let v = if x == gap {
                state.v.min(0.0)
            } else if x == low {
                state.v.max(0.0)
            } else {
                state.v
            };
            State { t, x, v }
        }
        _ => State { t, ..state },
    }
}

/// The column of a run's history.
fn column_of(index: usize, value: f64, history: &History, period: f64) -> Column {
    Column {
        index,
        value,
        velocities: history.impacts.iter().map(|i| i.v_in).collect(),
        phases: history.impacts.iter().map(|i| i.phase).collect(),
        stops: history.impacts.iter().map(|i| i.stop).collect(),
        period: history.period(period),
        end: history.end,
    }
}
