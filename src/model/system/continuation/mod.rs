//! Continuation of periodic orbits of a vibro-impact system (issue 24; docs/continuation.md).
//!
//! A periodic orbit of fixed impacts (n impacts on given stops in m forcing periods) is a zero of
//! a residual in scaled unknowns: for the rigid stop, multiple shooting over the closed-form
//! flights (each impact's phase and the velocity after it); for the compliant stop, shooting
//! through its solver on the impact map at first contact. Pseudo-arclength continuation follows
//! that zero in one scene key ([`continue_orbit`]), with the orbit's Floquet multipliers at
//! every point, and locates by their test functions:
//! - folds, det(J − I) = 0 (a multiplier +1);
//! - period doublings, det(J + I) = 0 (a multiplier −1); [`switch_at_period_doubling`] follows
//!   the doubled branch born there;
//! - grazing: an impact speed reaching zero, or the minimum of a gap over a flight reaching the
//!   stop (a new low-speed impact appearing).
//!
//! [`continue_special`] follows a located point in a second key: a two-parameter curve of folds,
//! period doublings or grazings.

mod branch;
mod compliant;
mod engine;
mod error;
mod problem;
mod rigid;
mod run;
mod trace;

pub use branch::{Branch, BranchEnd, BranchPoint, ContinuationOptions, SpecialKind, SpecialPoint};
pub use error::ContinuationError;
pub use run::{
    continue_orbit, continue_orbit_until, continue_special, switch_at_period_doubling,
    switch_at_period_doubling_until,
};
