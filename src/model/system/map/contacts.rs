//! What a cell's impacts say about its stop beyond the motion: the restitution they realise and
//! how long their contacts last, the two known causes of a rigid/compliant difference
//! (docs/maps.md §2).
#![warn(missing_docs)]

use serde::Serialize;

use crate::model::system::{History, ImpactKind};

/// A cell's impacts as a stop sees them.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct ContactReading {
    /// v_out/v_in of the fastest recorded impact: the e the stop realises where the system's
    /// forces during the contact matter least (a rigid stop's own e exactly).
    pub restitution: Option<f64>,
    /// The longest recorded impact's contact over the forcing period (resting phases left out;
    /// none for a rigid stop).
    pub contact_ratio: Option<f64>,
}

impl ContactReading {
    /// The reading of `history` with forcing period `forcing_period`, s.
    pub fn of(history: &History, forcing_period: f64) -> ContactReading {
        let fastest = history
            .impacts
            .iter()
            .filter(|i| i.kind == ImpactKind::Impact && i.v_in > 0.0)
            .max_by(|a, b| a.v_in.total_cmp(&b.v_in));
        let contact_ratio = history
            .impacts
            .iter()
            .filter(|i| i.kind == ImpactKind::Impact)
            .filter_map(|i| i.contact_time)
            .reduce(f64::max)
            .map(|tc| tc / forcing_period);
        ContactReading {
            restitution: fastest.map(|i| i.v_out / i.v_in),
            contact_ratio,
        }
    }
}
