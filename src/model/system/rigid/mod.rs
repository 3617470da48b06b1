//! The rigid (instantaneous-impact) solver: closed-form flight, certified impact search,
//! chatter summed to its accumulation point, sticking until the contact force turns tensile,
//! and the impact map with its Jacobian for periodic orbits (docs/systems.md).

pub(crate) mod dynamics;
pub(crate) mod orbit;
pub(crate) mod search;
mod simulate;

pub use orbit::find_orbit;
pub use simulate::{CHATTER_WINDOW, simulate};
