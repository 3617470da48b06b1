//! Studies over many solves: speed against accuracy, stability of fixed-step methods, parameter sweeps.

pub mod continuation;
pub mod fit;
pub mod map;
pub mod reference;
pub mod runner;
pub mod stability;
pub mod sweep;
pub mod system;
pub mod timing;
pub mod work_precision;
