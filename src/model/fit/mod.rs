//! Fitting laws to measured data (placeholder until the fit interface lands).

pub mod trace;
