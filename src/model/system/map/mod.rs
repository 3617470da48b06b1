//! Two-parameter maps of a system's motion (issue 24; docs/maps.md).
//!
//! [`map`] runs the system at every cell of a [`Grid`] of two scene keys and tells its motion
//! ([`Motion`]): n:m periodic from the recorded impacts, quasi-periodic or chaotic from the
//! largest Lyapunov exponent of the impact map ([`lyapunov`]: the exact Jacobian for the rigid
//! stop, two trajectories for the compliant one), chattering, sticking, no impact, unsettled.
//! Rows run in parallel on rayon's pool; along a row the attractor of one cell starts the next,
//! so that the result is fixed by the grid alone: independent of the number of threads and of
//! the [`Shard`] the rows are dealt into. [`difference`] compares the rigid and compliant maps
//! cell by cell.

mod contacts;
mod difference;
mod grid;
pub mod lyapunov;
mod motion;
mod run;
mod start;

pub use contacts::ContactReading;
pub use difference::{Agreement, Cause, DifferenceCell, difference};
pub use grid::{Axis, Grid, Shard};
pub use motion::{
    CHATTER_FLIGHT, HOLDING_CONTACT, Motion, Tolerances, from_exponent, from_history, period_of,
    skeleton,
};
pub use run::{Cell, MapOptions, MapRows, cell, check, contact_at, map, row};
pub use start::period_one;
