//! Fitting a law to a force or displacement trace over one impact (docs/fitting.md, Traces).
#![warn(missing_docs)]

mod data;
mod forward;

pub use data::{TraceData, TraceDataError, TraceQuantity, TraceSample};
pub use forward::{Outside, TraceParams, sample_trace, solve_trace_impact, trace_forward};
