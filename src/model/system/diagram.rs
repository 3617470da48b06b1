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
    let range = |c: usize| c * chunk..((c + 1) * chunk).min(values.len());
    let name = |i: usize, e: SystemError| match e {
        SystemError::ImpactBudget { budget, time, .. } => SystemError::ImpactBudget {
            what: format!("the diagram at {} = {}", param.path(), values[i]),
            budget,
            time,
        },
        other => other,
    };
    // One value run from `state` (of the model it came from), its column and end state.
    let one = |i: usize, state: Option<(State, &SystemModel)>| {
        let m = &models[i];
        let run_options = RunOptions {
            initial: state.map(|(s, from)| rebase(s, from, m)),
            ..options.run
        };
        run(m, &run_options)
            .map(|h| (column_of(i, values[i], &h, m.spec.period()), h.end_state))
            .map_err(|e| name(i, e))
    };
    let next = AtomicUsize::new(0);
    let cancelled = AtomicBool::new(false);
    // A chunk found to have started on another attractor than the one followed into it is
    // redone on the calling thread; its speculative run stops.
    let dropped: Vec<AtomicBool> = (0..chunks).map(|_| AtomicBool::new(false)).collect();
    let (sender, receiver) = mpsc::channel::<Speculative>();
    let worker = |sender: mpsc::Sender<Speculative>| {
        loop {
            let c = next.fetch_add(1, Ordering::Relaxed);
            if c >= chunks || cancelled.load(Ordering::Relaxed) {
                break;
            }
            // Each chunk starts cold from the given state (of `model`), then follows the
            // attractor; the caller checks its start against the previous chunk's end.
            let mut state: Option<(State, &SystemModel)> = options.run.initial.map(|s| (s, model));
            for i in range(c) {
                if cancelled.load(Ordering::Relaxed) || dropped[c].load(Ordering::Relaxed) {
                    break;
                }
                let result = one(i, state);
                if let Ok((_, end)) = &result {
                    state = Some((*end, &models[i]));
                }
                let failed = result.is_err();
                if sender.send((i, result)).is_err() {
                    return;
                }
                if failed {
                    break;
                }
            }
        }
    };
    let mut speculative: Vec<Option<Result<(Column, State), SystemError>>> =
        (0..values.len()).map(|_| None).collect();
    let mut columns: Vec<Option<Column>> = vec![None; values.len()];
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
        // Emission in the order of the values: chunk `current`, from value `emitted`; `follow`
        // is the state the sequence reached at the end of the previous chunk.
        let mut current = 0;
        let mut emitted = 0;
        let mut verified = false;
        let mut follow: Option<(State, &SystemModel)> = None;
        let mut emit = |i: usize,
                        column: Column,
                        columns: &mut Vec<Option<Column>>|
         -> Result<(), SystemError> {
            let stop = on_column(&column).is_break();
            columns[i] = Some(column);
            if stop {
                Err(SystemError::Cancelled)
            } else {
                Ok(())
            }
        };
        'receive: for (i, result) in receiver.iter() {
            speculative[i] = Some(result);
            while current < chunks {
                let r = range(current);
                if !verified {
                    // Chunk 0 starts where a sequence starts; any other is checked: its first
                    // value run from where the previous chunk ended must reach the attractor
                    // its cold start reached.
                    let Some(cold) = speculative[r.start].take() else {
                        break;
                    };
                    if current == 0 {
                        speculative[r.start] = Some(cold);
                        verified = true;
                        continue;
                    }
                    let warm = one(r.start, follow);
                    let same = match (&warm, &cold) {
                        (Ok((w, _)), Ok((c, _))) => w.same_attractor(c),
                        _ => false,
                    };
                    if same {
                        // The warm column is the sequence's; the rest follow the cold chain on
                        // the same attractor.
                        speculative[r.start] = Some(warm);
                        verified = true;
                        continue;
                    }
                    dropped[current].store(true, Ordering::Relaxed);
                    // Redo the chunk in sequence from the warm start.
                    let mut warm = Some(warm);
                    for j in r.clone() {
                        match warm.take().unwrap_or_else(|| one(j, follow)) {
                            Ok((column, end)) => {
                                follow = Some((end, &models[j]));
                                if let Err(e) = emit(j, column, &mut columns) {
                                    outcome = Err(e);
                                    break 'receive;
                                }
                            }
                            Err(e) => {
                                outcome = Err(e);
                                break 'receive;
                            }
                        }
                    }
                    for k in r.clone() {
                        speculative[k] = None;
                    }
                    current += 1;
                    emitted = range(current.min(chunks - 1)).start;
                    verified = false;
                    continue;
                }
                emitted = emitted.max(r.start);
                while emitted < r.end {
                    match speculative[emitted].take() {
                        None => break,
                        Some(Err(e)) => {
                            outcome = Err(e);
                            break 'receive;
                        }
                        Some(Ok((column, end))) => {
                            follow = Some((end, &models[emitted]));
                            if let Err(e) = emit(emitted, column, &mut columns) {
                                outcome = Err(e);
                                break 'receive;
                            }
                            emitted += 1;
                        }
                    }
                }
                if emitted < r.end {
                    break;
                }
                current += 1;
                verified = false;
            }
            if current >= chunks {
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

/// A speculative column from the pool: its index, and the column with the run's end state.
type Speculative = (usize, Result<(Column, State), SystemError>);

impl Column {
    /// Whether `other` is on the same attractor: the same end and period and, over one period,
    /// the same stops and impact speeds (sorted, within 1e-6 of the largest, the tolerance of
    /// [`History::period`]); without a period (chaos, or a long transient), the same number of
    /// impacts and a range of impact speeds within 5 % of the largest — a chaotic attractor is
    /// told by the band it fills.
    pub fn same_attractor(&self, other: &Column) -> bool {
        if self.end != other.end
            || self.period != other.period
            || self.velocities.len() != other.velocities.len()
        {
            return false;
        }
        let scale = self
            .velocities
            .iter()
            .chain(&other.velocities)
            .fold(0.0_f64, |m, v| m.max(v.abs()));
        match self.period {
            Some((n, _)) => {
                let cycle = |c: &Column| {
                    let from = c.velocities.len().saturating_sub(n as usize);
                    let mut v: Vec<(usize, f64)> = c.stops[from..]
                        .iter()
                        .copied()
                        .zip(c.velocities[from..].iter().copied())
                        .collect();
                    v.sort_by(|a, b| a.0.cmp(&b.0).then(a.1.total_cmp(&b.1)));
                    v
                };
                cycle(self)
                    .iter()
                    .zip(&cycle(other))
                    .all(|(a, b)| a.0 == b.0 && (a.1 - b.1).abs() <= 1e-6 * scale)
            }
            None => {
                let band = |c: &Column| {
                    c.velocities
                        .iter()
                        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                            (lo.min(*v), hi.max(*v))
                        })
                };
                let (a, b) = (band(self), band(other));
                self.velocities.is_empty()
                    || ((a.0 - b.0).abs() <= 0.05 * scale && (a.1 - b.1).abs() <= 0.05 * scale)
            }
        }
    }
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
