//! The plane a map covers: two keys, each over evenly spaced values, and the fixed partition of its
//! rows into shards (docs/maps.md).
#![warn(missing_docs)]

use serde::Serialize;

use crate::model::system::{Param, SystemError, SystemModel};

/// One axis of a map: `points` values of `param` from `from` to `to`, both ends included.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Axis {
    /// The key varied along the axis.
    #[serde(serialize_with = "serialize_param")]
    pub param: Param,
    /// First value, SI units.
    pub from: f64,
    /// Last value, SI units.
    pub to: f64,
    /// Number of values (≥ 2).
    pub points: usize,
}

fn serialize_param<S: serde::Serializer>(param: &Param, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(&param.path())
}

impl Axis {
    /// The i-th value: `from + (to − from)·i/(points − 1)`, the last one exactly `to`.
    pub fn value(&self, i: usize) -> f64 {
        let n = self.points.max(2);
        if i + 1 >= n {
            self.to
        } else {
            self.from + (self.to - self.from) * i as f64 / (n - 1) as f64
        }
    }
}

/// The grid: rows of constant y, cells along x. The attractor is followed along a row.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Grid {
    /// Along a row (followed from cell to cell).
    pub x: Axis,
    /// Across rows (rows are independent).
    pub y: Axis,
}

impl Grid {
    /// The model at cell (ix, iy): x applied first, then y (so that `system.gamma` on y uses the
    /// frequency set on x).
    pub fn model_at(
        &self,
        model: &SystemModel,
        ix: usize,
        iy: usize,
    ) -> Result<SystemModel, SystemError> {
        let m = self.x.param.apply(model, self.x.value(ix))?;
        self.y.param.apply(&m, self.y.value(iy))
    }

    /// Checks the axes before any work: at least two points each, finite ends, and every value of
    /// each axis accepted by the model (errors name the key).
    pub fn check(&self, model: &SystemModel) -> Result<(), SystemError> {
        if self.x.points < 2 || self.y.points < 2 {
            return Err(SystemError::NoValues);
        }
        if self.x.param == self.y.param {
            return Err(SystemError::KeyNotApplicable {
                key: self.y.param.path(),
                why: "a map needs two different keys on x and y",
            });
        }
        for ix in 0..self.x.points {
            self.model_at(model, ix, 0)?;
        }
        for iy in 0..self.y.points {
            self.model_at(model, 0, iy)?;
        }
        Ok(())
    }
}

/// Shard `index` of `count` (1-based): the rows iy with iy mod count = index − 1. Rows are dealt
/// round-robin so that each shard gets rows from the whole y range (costly regions are shared).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct Shard {
    /// 1..=count.
    pub index: usize,
    /// Number of shards.
    pub count: usize,
}

impl Shard {
    /// The whole map.
    pub const WHOLE: Shard = Shard { index: 1, count: 1 };

    /// A shard, checked: 1 ≤ index ≤ count.
    pub fn new(index: usize, count: usize) -> Option<Shard> {
        (count >= 1 && (1..=count).contains(&index)).then_some(Shard { index, count })
    }

    /// The rows of `rows` this shard computes, in order.
    pub fn rows(self, rows: usize) -> impl Iterator<Item = usize> {
        (self.index - 1..rows).step_by(self.count)
    }

    /// Whether row `iy` is this shard's.
    pub fn owns(self, iy: usize) -> bool {
        iy % self.count == self.index - 1
    }
}
