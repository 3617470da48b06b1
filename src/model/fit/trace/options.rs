//! What a trace fit frees and how it solves (docs/fitting.md, Traces).

use std::str::FromStr;

use serde::Serialize;

use crate::model::fit::FitOptions;
use crate::model::impact::SolveOptions;

use super::forward::Outside;

/// Which of k, n and v₀ a trace fit frees besides the law's damping and t₀ (fitted always):
/// the rest are the scene's (its Hertz estimate's k and n, eqs 1–4, and its v₀).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize)]
pub struct FreeParams {
    /// Fit the stiffness k of F = k·xⁿ (eq 1).
    pub k: bool,
    /// Fit the exponent n (eq 1).
    pub n: bool,
    /// Fit the impact velocity v₀.
    pub v0: bool,
}

impl FreeParams {
    /// The keys `--free` takes.
    pub const KEYS: [&'static str; 3] = ["k", "n", "v0"];

    /// How many are freed.
    pub fn count(self) -> usize {
        usize::from(self.k) + usize::from(self.n) + usize::from(self.v0)
    }
}

impl FromStr for FreeParams {
    type Err = String;

    /// A comma-separated list of `k`, `n`, `v0` (`none` or nothing for none).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let mut free = FreeParams::default();
        for key in s.split(',').map(str::trim).filter(|k| !k.is_empty()) {
            match key {
                "k" => free.k = true,
                "n" => free.n = true,
                "v0" | "v₀" => free.v0 = true,
                "none" => {}
                _ => {
                    return Err(format!(
                        "unknown parameter '{key}' to free (expected a list of: {}; the damping and t0 are always fitted)",
                        Self::KEYS.join(", ")
                    ));
                }
            }
        }
        Ok(free)
    }
}

/// Options of a trace fit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TraceFitOptions {
    /// What is fitted besides the damping and t₀.
    pub free: FreeParams,
    /// What a displacement trace reads outside contact.
    pub outside: Outside,
    /// The impact solves of the forward model: `auto` at rtol 1e-10 by default, whose 100·rtol
    /// promise (see [`SolveOptions`]) keeps the model 1e-8 of the peak from the truth.
    pub solve: SolveOptions,
    /// Criterion, engine options and parallelism, as for e(v) fits.
    pub fit: FitOptions,
}

impl Default for TraceFitOptions {
    fn default() -> Self {
        TraceFitOptions {
            free: FreeParams::default(),
            outside: Outside::default(),
            solve: SolveOptions {
                rtol: 1e-10,
                ..SolveOptions::default()
            },
            fit: FitOptions::default(),
        }
    }
}

/// Residuals below this fraction of the trace's peak are the forward model's own accuracy (the
/// solver's 100·rtol at rtol 1e-10), not a better fit: the misfit the criteria see is floored at
/// it, so laws that both fit a noise-free trace tie rather than rank by rounding.
pub const TRACE_FLOOR: f64 = 1e-8;
