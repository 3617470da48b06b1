//! hertz-tui: a terminal explorer of impact contact forces.
//!
//! `model` holds the physics and numerics (no UI); `ui` renders it; `cli` exposes it headless;
//! `format` is the text both print (numbers with SI prefixes, the trajectory CSV).

pub mod cli;
pub mod format;
pub mod model;
pub mod ui;
