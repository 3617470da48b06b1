//! The explorer's map study (docs/maps.md §6): a two-parameter map of a system's motion with each
//! stop, its rows reported as they complete so that the map fills in on the screen, and stopped
//! between cells when superseded or cancelled.

use std::sync::mpsc;

use rayon::prelude::*;

use crate::model::system::map::{
    self, Cell, DifferenceCell, Grid, MapOptions, difference, period_one,
};
use crate::model::system::{Contact, SystemError, SystemModel};

/// Where each row's first cell starts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Start {
    /// At rest on the stop, as `hertz-tui map` does.
    #[default]
    Rest,
    /// On the rigid stop's period-1 orbit of the row's first cell (at rest where it has none).
    PeriodOne,
}

/// A map of a system with each stop.
#[derive(Debug, Clone, PartialEq)]
pub struct MapStudy {
    pub model: SystemModel,
    pub contacts: Vec<Contact>,
    pub grid: Grid,
    pub options: MapOptions,
    pub start: Start,
}

/// One stop's map so far: its rows by index (`None`: not done yet), and why it could not run.
#[derive(Debug, Clone)]
pub struct MapLayer {
    pub contact: Contact,
    pub rows: Vec<Option<Vec<Cell>>>,
    pub error: Option<SystemError>,
}

impl MapLayer {
    /// The cell at (ix, iy), once its row is done.
    pub fn cell(&self, ix: usize, iy: usize) -> Option<&Cell> {
        self.rows.get(iy)?.as_ref()?.get(ix)
    }

    /// Every cell done, row by row.
    pub fn cells(&self) -> impl Iterator<Item = &Cell> {
        self.rows.iter().flatten().flatten()
    }

    /// Rows done.
    pub fn rows_done(&self) -> usize {
        self.rows.iter().filter(|r| r.is_some()).count()
    }
}

/// Every stop's map so far.
#[derive(Debug, Clone)]
pub struct MapData {
    pub grid: Grid,
    pub start: Start,
    pub layers: Vec<MapLayer>,
    /// Rows that were to start on the period-1 orbit but started at rest (it was not found).
    pub rows_from_rest: usize,
    /// Every stop's map is done (or failed): no more rows will come.
    pub complete: bool,
}

impl MapData {
    /// The rigid/compliant difference over the rows both have done (first two layers).
    pub fn difference(&self) -> Option<Vec<DifferenceCell>> {
        let [a, b, ..] = &self.layers[..] else {
            return None;
        };
        let both: Vec<(Vec<Cell>, Vec<Cell>)> = a
            .rows
            .iter()
            .zip(&b.rows)
            .filter_map(|(r, c)| Some((r.clone()?, c.clone()?)))
            .collect();
        Some(both.iter().flat_map(|(r, c)| difference(r, c)).collect())
    }

    /// Rows done over rows asked, all layers together.
    pub fn progress(&self) -> (usize, usize) {
        let done = self.layers.iter().map(MapLayer::rows_done).sum();
        (done, self.layers.len() * self.grid.y.points)
    }
}

/// Partial reports per layer at most: each copies the map so far.
const REPORTS_PER_LAYER: usize = 32;

/// Every stop's map, one after the other (its rows in parallel on rayon's pool), handing
/// `partial` the data so far as rows complete; `None` once `stop` says so.
pub fn run_map(
    study: &MapStudy,
    stop: &(dyn Fn() -> bool + Sync),
    partial: &dyn Fn(MapData),
) -> Option<MapData> {
    let ny = study.grid.y.points;
    let mut data = MapData {
        grid: study.grid,
        start: study.start,
        layers: Vec::new(),
        rows_from_rest: 0,
        complete: false,
    };
    let starts: Vec<MapOptions> = (0..ny)
        .map(|iy| row_options(study, iy, &mut data.rows_from_rest))
        .collect();
    let every = ny.div_ceil(REPORTS_PER_LAYER).max(1);
    for contact in &study.contacts {
        if stop() {
            return None;
        }
        let error = map::check(&study.model, &study.grid, ny, &study.options).err();
        data.layers.push(MapLayer {
            contact: *contact,
            rows: vec![None; ny],
            error: error.clone(),
        });
        if error.is_some() {
            continue;
        }
        let (tx, rx) = mpsc::channel();
        std::thread::scope(|scope| {
            // Rows run on rayon's pool from a thread of their own; this one reports them.
            scope.spawn(|| {
                (0..ny).into_par_iter().for_each_with(tx, |tx, iy| {
                    let row = map::row(&study.model, contact, &study.grid, iy, &starts[iy], stop);
                    if let Some(cells) = row {
                        let _ = tx.send((iy, cells));
                    }
                });
            });
            let mut done = 0;
            for (iy, cells) in rx {
                done += 1;
                if let Some(layer) = data.layers.last_mut() {
                    layer.rows[iy] = Some(cells);
                }
                if done % every == 0 && done < ny && !stop() {
                    partial(data.clone());
                }
            }
        });
        if stop() {
            return None;
        }
    }
    data.complete = true;
    Some(data)
}

/// The options of row `iy`: its start on the period-1 orbit when asked and found (counted in
/// `from_rest` when not found).
fn row_options(study: &MapStudy, iy: usize, from_rest: &mut usize) -> MapOptions {
    let options = study.options;
    if study.start == Start::Rest {
        return options;
    }
    let first = study
        .grid
        .model_at(&study.model, 0, iy)
        .and_then(|m| period_one(&m, m.restitution, &options.run));
    match first {
        Ok(state) => MapOptions {
            run: crate::model::system::RunOptions {
                initial: Some(state),
                ..options.run
            },
            ..options
        },
        Err(_) => {
            *from_rest += 1;
            options
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::system::map::{Axis, Shard};
    use crate::model::system::{Param, STANDARD_GRAVITY, SystemKey, SystemKind, SystemSpec};
    use std::sync::Mutex;
    use std::sync::atomic::{AtomicUsize, Ordering};

    fn study() -> MapStudy {
        let spec = SystemSpec {
            kind: SystemKind::BouncingBall {
                amplitude: 8e-4,
                frequency: 20.0,
                gravity: STANDARD_GRAVITY,
            },
        };
        let axis = |key, from, to, points| Axis {
            param: Param::System(key),
            from,
            to,
            points,
        };
        let mut options = MapOptions::default();
        options.run.transient_impacts = 60;
        options.run.recorded_impacts = 16;
        options.lyapunov_impacts = 20;
        MapStudy {
            model: SystemModel::new(spec, 0.033, 0.5).unwrap(),
            contacts: vec![Contact::rigid(0.5)],
            grid: Grid {
                x: axis(SystemKey::Frequency, 15.0, 25.0, 6),
                y: axis(SystemKey::Amplitude, 5e-4, 1e-3, 8),
            },
            options,
            start: Start::Rest,
        }
    }

    #[test]
    fn rows_reported_as_they_come_are_those_of_the_whole_map() {
        let s = study();
        let seen = Mutex::new(Vec::new());
        let whole = run_map(&s, &|| false, &|d| seen.lock().unwrap().push(d)).unwrap();
        assert!(whole.complete);
        let reference = map::map(&s.model, &s.contacts[0], &s.grid, Shard::WHOLE, &s.options)
            .unwrap()
            .cells;
        let cells: Vec<Cell> = whole.layers[0].cells().cloned().collect();
        assert_eq!(cells, reference, "the study's map is the command's");
        let seen = seen.into_inner().unwrap();
        assert_eq!(seen.len(), 7, "a report a row but the last");
        for (k, d) in seen.iter().enumerate() {
            assert_eq!(d.layers[0].rows_done(), k + 1);
            for (iy, row) in d.layers[0].rows.iter().enumerate() {
                if let Some(row) = row {
                    assert_eq!(Some(row), whole.layers[0].rows[iy].as_ref());
                }
            }
        }
    }

    #[test]
    fn a_stop_between_cells_ends_it_with_nothing() {
        let s = study();
        let asked = AtomicUsize::new(0);
        // Stopped after a few cells: no more than one more cell a thread is run, nothing reported.
        let stop = || asked.fetch_add(1, Ordering::SeqCst) > 5;
        assert!(run_map(&s, &stop, &|_| panic!("no report once stopped")).is_none());
        assert!(run_map(&s, &|| true, &|_| {}).is_none());
    }
}
