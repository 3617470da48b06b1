//! hertz-tui: a terminal explorer of impact contact forces.
//!
//! `model` holds the physics and numerics (no UI); `ui` renders it; `cli` exposes it headless.

pub mod cli;
pub mod model;
pub mod ui;
