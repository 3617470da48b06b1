//! Fitting contact laws to a force or displacement trace over one impact (issue 23, item 2;
//! docs/fitting.md, Traces).
//!
//! # API
//! - Data: [`TraceData`] of [`TraceSample`]s (t in s; F in N or the approach x in m; the file's
//!   line), checked by [`TraceData::new`] ([`TraceDataError`] names the line; the CSV reader
//!   `crate::format::trace_csv` adds the file).
//! - The forward model: [`trace_forward`] ([`solve_trace_impact`] then [`sample_trace`]): a law's
//!   F(t) or x(t) from the impact solver's dense output with [`TraceParams`] k, n, v₀, the
//!   damping and the contact start t₀.
//! - The fit: [`fit_trace`] (a scene) or [`fit_trace_params`] → the same [`FitReport`](crate::model::fit::FitReport) as e(v)
//!   fits, every law ranked by AICc or BIC; [`TraceFitOptions::free`] frees k, n, v₀ besides the
//!   damping and t₀. [`predict_trace`] evaluates a fitted law at any times.
#![warn(missing_docs)]

mod data;
mod fit;
mod forward;
mod layout;
mod options;
mod rank;
mod start;

pub use data::{TraceData, TraceDataError, TraceQuantity, TraceSample};
pub use fit::{fit_trace, fit_trace_params, fitted_trace_params, predict_trace};
pub use forward::{
    Outside, TraceParams, force_at_touch, sample_trace, solve_trace_impact, trace_forward,
};
pub use options::{FreeParams, TRACE_FLOOR, TraceFitOptions};
