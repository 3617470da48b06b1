//! The map engine: rows of the grid on rayon's pool, the attractor followed along each row.
#![warn(missing_docs)]

use rayon::prelude::*;
use serde::Serialize;

use crate::model::system::diagram::rebase;
use crate::model::system::{
    CompliantDamping, Contact, EndReason, History, RunOptions, State, SystemError, SystemModel,
    simulate,
};

use super::contacts::ContactReading;
use super::grid::{Grid, Shard};
use super::lyapunov::{self, NoExponent};
use super::motion::{self, Motion, Tolerances};

/// How every cell is run and read.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MapOptions {
    /// Each cell's run: transient and recorded impacts, time and impact budgets. Its `initial`
    /// starts the first cell of every row (None: at rest).
    pub run: RunOptions,
    /// Map steps the largest Lyapunov exponent is averaged over (0: no exponent, so no chaos or
    /// quasi-periodicity is told apart: `unresolved`).
    pub lyapunov_impacts: usize,
    /// How impacts are compared and the exponent read.
    pub tolerances: Tolerances,
    /// Budget of cells × (transient + recorded + exponent) impacts of the part computed.
    pub max_total_impacts: u128,
}

impl Default for MapOptions {
    fn default() -> MapOptions {
        MapOptions {
            run: RunOptions {
                transient_impacts: 300,
                recorded_impacts: 64,
                max_periods: 20_000.0,
                max_impacts: 100_000,
                samples_per_period: 0,
                initial: None,
            },
            lyapunov_impacts: 200,
            tolerances: Tolerances::default(),
            max_total_impacts: 10_000_000_000,
        }
    }
}

/// One point of the map.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Cell {
    /// Column index (along x).
    pub ix: usize,
    /// Row index (along y).
    pub iy: usize,
    /// x value, SI.
    pub x: f64,
    /// y value, SI.
    pub y: f64,
    /// The motion.
    pub motion: Motion,
    /// Largest Lyapunov exponent of the impact map, per impact (where the map of isolated impacts
    /// could be iterated).
    pub lyapunov: Option<f64>,
    /// The restitution the recorded impacts realise and their longest contact (default where the
    /// cell failed).
    pub contacts: ContactReading,
    /// The slowest recorded approach speed, m/s (where an impact was recorded): how close the
    /// motion comes to grazing or chatter.
    pub slowest_impact: Option<f64>,
    /// Why the cell failed (`motion` is then [`Motion::Failed`]).
    pub error: Option<String>,
}

/// A computed part of a map: its rows in order, each row's cells in order of x.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MapRows {
    /// Which rows.
    pub shard: Shard,
    /// The rows' cells, row after row.
    pub cells: Vec<Cell>,
}

/// The map of `model` with `contact` over `grid`, the rows of `shard` only. Rows run in parallel
/// on rayon's pool; each row is followed in sequence from its first cell, so the result does not
/// depend on the number of threads or on the sharding. A cell whose run fails is kept as
/// [`Motion::Failed`] with its error (the next cell then starts from `options.run.initial`).
pub fn map(
    model: &SystemModel,
    contact: &Contact,
    grid: &Grid,
    shard: Shard,
    options: &MapOptions,
) -> Result<MapRows, SystemError> {
    let rows: Vec<usize> = shard.rows(grid.y.points).collect();
    check(model, grid, rows.len(), options)?;
    let cells = rows
        .par_iter()
        .filter_map(|&iy| row(model, contact, grid, iy, options, &|| false))
        .collect::<Vec<_>>()
        .into_iter()
        .flatten()
        .collect();
    Ok(MapRows { shard, cells })
}

/// Checks the grid and the budget of `rows` rows of `grid` before any work.
pub fn check(
    model: &SystemModel,
    grid: &Grid,
    rows: usize,
    options: &MapOptions,
) -> Result<(), SystemError> {
    grid.check(model)?;
    let per_cell =
        options.run.transient_impacts + options.run.recorded_impacts + options.lyapunov_impacts;
    let needed = rows as u128 * grid.x.points as u128 * per_cell as u128;
    if needed > options.max_total_impacts {
        return Err(SystemError::DiagramBudget {
            needed,
            values: rows * grid.x.points,
            per_value: per_cell,
            budget: usize::try_from(options.max_total_impacts).unwrap_or(usize::MAX),
        });
    }
    Ok(())
}

/// Row `iy`, followed from its first cell (started from `options.run.initial`); `None` once
/// `stop` says so, checked before every cell.
pub fn row(
    model: &SystemModel,
    contact: &Contact,
    grid: &Grid,
    iy: usize,
    options: &MapOptions,
    stop: &(dyn Fn() -> bool + Sync),
) -> Option<Vec<Cell>> {
    let mut warm: Option<(State, SystemModel)> = None;
    let mut cells = Vec::with_capacity(grid.x.points);
    for ix in 0..grid.x.points {
        if stop() {
            return None;
        }
        let (x, y) = (grid.x.value(ix), grid.y.value(iy));
        let outcome = grid.model_at(model, ix, iy).and_then(|m| {
            let run = RunOptions {
                initial: match &warm {
                    Some((s, from)) => Some(rebase(*s, from, &m)),
                    None => options.run.initial,
                },
                ..options.run
            };
            let (reading, end) = read(&m, contact, &run, options)?;
            Ok((reading, end, m))
        });
        cells.push(match outcome {
            Ok((reading, end, m)) => {
                warm = Some((end, m));
                Cell {
                    ix,
                    iy,
                    x,
                    y,
                    motion: reading.motion,
                    lyapunov: reading.lyapunov,
                    contacts: reading.contacts,
                    slowest_impact: reading.slowest_impact,
                    error: None,
                }
            }
            Err(e) => {
                warm = None;
                Cell {
                    ix,
                    iy,
                    x,
                    y,
                    motion: Motion::Failed,
                    lyapunov: None,
                    contacts: ContactReading::default(),
                    slowest_impact: None,
                    error: Some(e.to_string()),
                }
            }
        });
    }
    Some(cells)
}

/// The contact at a cell: a rigid stop takes the cell's e (so that `impact.restitution` can be an
/// axis), a compliant stop calibrated to e is calibrated to the cell's e.
pub fn contact_at(contact: &Contact, model: &SystemModel) -> Contact {
    match *contact {
        Contact::Rigid { .. } => Contact::rigid(model.restitution),
        Contact::Compliant {
            model: law,
            damping: CompliantDamping::CalibratedTo(_),
        } => Contact::Compliant {
            model: law,
            damping: CompliantDamping::CalibratedTo(model.restitution),
        },
        other => other,
    }
}

/// The run of a cell with its transient and recorded impacts counted as events outside a
/// chatter's tail (docs/maps.md §2), the same for both stops: a rigid stop resolves a tail of
/// some twenty impacts where a compliant one makes a few, so counted in impacts a rigid run would
/// record a few chatters where a compliant one records many. A run whose record holds a tail is
/// run once more with both counts scaled by its impacts per event.
fn events_counted(
    model: &SystemModel,
    contact: &Contact,
    run: &RunOptions,
) -> Result<History, SystemError> {
    let history = simulate(model, contact, run)?;
    let (kept, tail) = motion::skeleton(&history.impacts, model.spec.period());
    let recorded = history.impacts.len();
    if !tail || history.end != EndReason::Recorded || kept.is_empty() {
        return Ok(history);
    }
    let scale = |n: usize| (n as f64 * recorded as f64 / kept.len() as f64).ceil() as usize;
    let longer = RunOptions {
        transient_impacts: scale(run.transient_impacts),
        // One more: the skeleton leaves out the first recorded impact.
        recorded_impacts: scale(run.recorded_impacts) + 1,
        ..*run
    };
    simulate(model, contact, &longer)
}

/// The motion at one cell, its exponent, what its impacts realise, and the state its run ended in
/// (the next cell's start).
pub fn cell(
    model: &SystemModel,
    contact: &Contact,
    run: &RunOptions,
    options: &MapOptions,
) -> Result<(Motion, Option<f64>, ContactReading, State), SystemError> {
    read(model, contact, run, options).map(|(r, end)| (r.motion, r.lyapunov, r.contacts, end))
}

/// What a cell's run shows.
struct Reading {
    motion: Motion,
    lyapunov: Option<f64>,
    contacts: ContactReading,
    /// The slowest recorded approach speed, m/s.
    slowest_impact: Option<f64>,
}

/// [`cell`] with the slowest recorded approach speed.
fn read(
    model: &SystemModel,
    contact: &Contact,
    run: &RunOptions,
    options: &MapOptions,
) -> Result<(Reading, State), SystemError> {
    let contact = contact_at(contact, model);
    let history = events_counted(model, &contact, run)?;
    let end = history.end_state;
    let contacts = ContactReading::of(&history, model.spec.period());
    let slowest_impact = history.impacts.iter().map(|i| i.v_in).reduce(f64::min);
    let reading = |motion, lyapunov| Reading {
        motion,
        lyapunov,
        contacts,
        slowest_impact,
    };
    let tol = &options.tolerances;
    let decided = motion::from_history(&history, model.spec.period(), run.max_periods, tol);
    let exponent_needed = matches!(decided, None | Some(Motion::Periodic { .. }));
    if !exponent_needed || options.lyapunov_impacts == 0 {
        return Ok((reading(decided.unwrap_or(Motion::Unresolved), None), end));
    }
    let Some(last) = lyapunov::start_of(&history.impacts) else {
        return Ok((reading(decided.unwrap_or(Motion::Unresolved), None), end));
    };
    let speed = history.impacts.iter().map(|i| i.v_in).fold(0.0, f64::max);
    let steps = options.lyapunov_impacts;
    let exponent = match contact {
        Contact::Rigid { restitution } => lyapunov::rigid(model, restitution, last, speed, steps)?,
        Contact::Compliant {
            model: law,
            damping,
        } => lyapunov::compliant(model, law, damping, last, speed, steps)?,
    };
    let (motion, lyapunov) = match (decided, exponent) {
        (Some(periodic), Ok(l)) => (periodic, Some(l)),
        (Some(periodic), Err(_)) => (periodic, None),
        (None, Ok(l)) => (motion::from_exponent(Some(l), tol), Some(l)),
        (None, Err(NoExponent::Chatters)) => (Motion::Chattering { period: None }, None),
        // No next impact within a map step's horizon: the body stopped impacting only if its run
        // says so; a run that still impacted at its end makes flights longer than the horizon
        // (the elastic ball climbing ever higher), so the map could not be iterated.
        (None, Err(NoExponent::NoImpact))
            if history.impacting_at_end(run.max_periods, model.spec.period()) =>
        {
            (Motion::Unresolved, None)
        }
        (None, Err(NoExponent::NoImpact)) => (Motion::NoImpact, None),
        (None, Err(NoExponent::Grazes)) => (Motion::Unresolved, None),
    };
    Ok((reading(motion, lyapunov), end))
}
