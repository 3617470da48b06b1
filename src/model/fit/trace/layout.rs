//! The parameters of one law's trace fit, in θ order, and θ as the forward model's inputs.

use crate::model::PowerLaw;
use crate::model::fit::Candidate;
use crate::model::fit::lsq::ParamSpec;
use crate::model::force::table::Family;
use crate::model::force::{AnyLaw, ForceModel, ImpactParams};

use super::forward::TraceParams;
use super::options::FreeParams;

/// The stiffness k of F = k·xⁿ (eq 1), on a log scale.
const K: ParamSpec = ParamSpec::positive("k", "k", "N/m^n");
/// The exponent n of eq 1: at least 1 (a law that stiffens with x), at most 4.
const N: ParamSpec = ParamSpec::bounded("n", "n", "1", 1.0, 4.0);
/// The impact velocity, on a log scale.
const V0: ParamSpec = ParamSpec::positive("v₀", "v0", "m/s");

/// The parameters of one law's trace fit, in θ order: k, n, v₀ where freed, the damping where
/// the law has one, t₀ last.
#[derive(Debug, Clone, Copy)]
pub(super) struct Layout {
    pub(super) model: ForceModel,
    pub(super) free: FreeParams,
    /// The damping as fitted: the table's parameter, except the Hunt–Crossley family's
    /// a = χ/v₀ (s/m), the material constant of e(v) fits and of a scene's `[fit]` table.
    pub(super) damping: Option<ParamSpec>,
}

impl Layout {
    pub(super) fn of(model: ForceModel, free: FreeParams) -> Self {
        Layout {
            model,
            free,
            damping: Candidate::Law(model)
                .params()
                .ok()
                .and_then(|p| p.first().copied()),
        }
    }

    fn hunt_crossley(&self) -> bool {
        self.model.spec().family == Family::HuntCrossley
    }

    /// The specs in SI, t₀ within `t_bounds`.
    pub(super) fn specs(&self, t_bounds: (f64, f64)) -> Vec<ParamSpec> {
        let mut specs = Vec::with_capacity(5);
        for (on, spec) in [(self.free.k, K), (self.free.n, N), (self.free.v0, V0)] {
            if on {
                specs.push(spec);
            }
        }
        specs.extend(self.damping);
        specs.push(ParamSpec::bounded("t₀", "t0", "s", t_bounds.0, t_bounds.1));
        specs
    }

    /// Why these free parameters cannot all be determined by any trace of this law, if so:
    /// Kelvin–Voigt's F = K·x + c·ẋ sees k and n only through its one spring K = m·(π/t_c)²
    /// (docs/physics.md §6.3), so that freeing both leaves a line of (k, n) with the same trace.
    ///
    /// A law that fixes k or n by its bodies (Thornton's on a point contact is Hertz's sphere,
    /// n = 3/2, docs/physics.md §6.6) refuses them freed: it is built here with each freed one
    /// moved by a millionth, and its refusal is the reason.
    pub(super) fn unidentifiable(&self, base: &ImpactParams) -> Option<String> {
        let linear = matches!(
            self.model.law(base),
            Ok(AnyLaw::KelvinVoigt(_) | AnyLaw::KelvinVoigtTension(_))
        );
        if linear && self.free.k && self.free.n {
            return Some(
                "its force K·x + c·ẋ depends on k and n only through K = m·(π/t_c)²: free k or n, not both"
                    .to_string(),
            );
        }
        for (on, key, moved) in [
            (
                self.free.k,
                "k",
                PowerLaw {
                    k: base.law.k * (1.0 + 1e-6),
                    ..base.law
                },
            ),
            (
                self.free.n,
                "n",
                PowerLaw {
                    n: base.law.n * (1.0 + 1e-6),
                    ..base.law
                },
            ),
        ] {
            if let (true, Err(e)) = (
                on,
                self.model.law(&ImpactParams {
                    law: moved,
                    ..*base
                }),
            ) {
                return Some(format!("{key} cannot be freed: {e}"));
            }
        }
        None
    }

    pub(super) fn len(&self) -> usize {
        self.free.count() + usize::from(self.damping.is_some()) + 1
    }

    /// θ (SI, in [`Layout::specs`] order) on the scene `base` as the forward model's parameters.
    pub(super) fn params(&self, base: &ImpactParams, theta: &[f64]) -> TraceParams {
        let mut it = theta.iter().copied();
        let mut take = |on: bool, default: f64| {
            if on {
                it.next().unwrap_or(default)
            } else {
                default
            }
        };
        let k = take(self.free.k, base.law.k);
        let n = take(self.free.n, base.law.n);
        let v0 = take(self.free.v0, base.v0);
        let damping = self.damping.map(|_| {
            let d = take(true, 0.0);
            if self.hunt_crossley() { d * v0 } else { d }
        });
        let t0 = take(true, 0.0);
        TraceParams {
            k,
            n,
            v0,
            damping,
            t0,
        }
    }
}
