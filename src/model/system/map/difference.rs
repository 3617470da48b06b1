//! The rigid/compliant difference as a map of its own: where the two stops give the same motion.
#![warn(missing_docs)]

use serde::Serialize;

use super::motion::Motion;
use super::run::Cell;

/// Whether two stops agree at a cell.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Agreement {
    /// The same kind of motion, with the same n:m where it has one.
    Same,
    /// Different kinds, or different periods.
    Differs,
    /// One of the two runs failed.
    Unknown,
}

impl Agreement {
    /// The name in every output.
    pub fn name(self) -> &'static str {
        match self {
            Agreement::Same => "same",
            Agreement::Differs => "differs",
            Agreement::Unknown => "unknown",
        }
    }

    /// Whether two motions agree.
    pub fn of(a: Motion, b: Motion) -> Agreement {
        if a == Motion::Failed || b == Motion::Failed {
            Agreement::Unknown
        } else if a == b {
            Agreement::Same
        } else {
            Agreement::Differs
        }
    }
}

/// One cell of the difference map.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DifferenceCell {
    /// Column index.
    pub ix: usize,
    /// Row index.
    pub iy: usize,
    /// x value, SI.
    pub x: f64,
    /// y value, SI.
    pub y: f64,
    /// Agreement of the two motions.
    pub agreement: Agreement,
    /// λ_compliant − λ_rigid, per impact, where both have one.
    pub lyapunov_change: Option<f64>,
}

/// The difference of two maps over the same cells (`rigid` and `compliant` in the same order).
pub fn difference(rigid: &[Cell], compliant: &[Cell]) -> Vec<DifferenceCell> {
    rigid
        .iter()
        .zip(compliant)
        .map(|(r, c)| DifferenceCell {
            ix: r.ix,
            iy: r.iy,
            x: r.x,
            y: r.y,
            agreement: Agreement::of(r.motion, c.motion),
            lyapunov_change: r.lyapunov.zip(c.lyapunov).map(|(a, b)| b - a),
        })
        .collect()
}
