//! e as a function of one dimensionless group, tabulated once and reused (docs/physics.md §9.1).
//!
//! For F = k·xⁿ⁻¹·(x + A·ẋ) (Kuwabara–Kono, and the proposed model with A = b/k) the impact in
//! X = x/x_e, T = t·v/x_e (x_e the elastic x_max, eq 5) reads X'' = −((n+1)/2)·Xⁿ⁻¹·(X + ψ·X'),
//! ψ = A·v/x_e(v): e depends on v and A through ψ alone, for the scene's n. So the solver is asked
//! for g(ψ) on Chebyshev–Lobatto nodes of panels fixed in ln ψ, each panel built the first time a
//! fit needs it and kept for the whole fit (and every later evaluation of the same forward model),
//! and e is the panel's barycentric interpolant. A panel whose nodes do not all solve to a rebound
//! (a bilateral law damped past critical never separates) is not built: its ψ go to the solver.
#![warn(missing_docs)]

use std::collections::HashMap;
use std::sync::{Arc, Mutex};

/// Width of a panel in ln ψ: a factor e^{1/2} ≈ 1.65 in ψ.
const PANEL_WIDTH: f64 = 0.5;

/// Chebyshev–Lobatto nodes per panel (degree 16): measured against direct solves the interpolant
/// is within 2e-11 of them (measured 1.6e-11, tests/model/fit_forward.rs), the solver's own accuracy.
const NODES: usize = 17;

/// A panel: g at its nodes, or `None` when some node did not solve to a rebound.
type Panel = Option<[f64; NODES]>;

/// The table of g(ψ), shared by clones of the forward model and across threads.
#[derive(Debug, Clone, Default)]
pub struct GroupTable {
    panels: Arc<Mutex<HashMap<i64, Panel>>>,
}

impl PartialEq for GroupTable {
    /// Tables are caches: two forward models are equal whatever they have cached.
    fn eq(&self, _other: &Self) -> bool {
        true
    }
}

/// The node j of a panel on [a, b] in ln ψ: x_j = cos(jπ/(N−1)) mapped.
fn node(a: f64, j: usize) -> f64 {
    let x = (std::f64::consts::PI * j as f64 / (NODES - 1) as f64).cos();
    a + 0.5 * PANEL_WIDTH * (1.0 - x)
}

impl GroupTable {
    /// g(ψ) from the table, building its panel by `solve` (g at a ψ, `None` when it does not
    /// rebound) if needed; `None` when the panel cannot be built (the caller solves directly).
    pub fn value(&self, psi: f64, solve: &dyn Fn(f64) -> Option<f64>) -> Option<f64> {
        if !(psi.is_finite() && psi > 0.0) {
            return None;
        }
        let u = psi.ln();
        let index = (u / PANEL_WIDTH).floor();
        if !index.is_finite() || index.abs() > 1e6 {
            return None;
        }
        let key = index as i64;
        let a = index * PANEL_WIDTH;
        let cached = self.panels.lock().ok()?.get(&key).copied();
        let panel = match cached {
            Some(p) => p,
            None => {
                let mut values = [0.0; NODES];
                let mut ok = true;
                for (j, v) in values.iter_mut().enumerate() {
                    match solve(node(a, j).exp()) {
                        Some(g) if g > 0.0 && g.is_finite() => *v = g,
                        _ => {
                            ok = false;
                            break;
                        }
                    }
                }
                let p = ok.then_some(values);
                self.panels.lock().ok()?.insert(key, p);
                p
            }
        };
        panel.map(|values| barycentric(a, &values, u))
    }

    /// Panels built so far (for the benchmark's and tests' accounting).
    pub fn panels(&self) -> usize {
        self.panels.lock().map_or(0, |p| p.len())
    }
}

/// The barycentric interpolant through Chebyshev–Lobatto nodes (weights (−1)ʲ, halved at the
/// ends; Berrut & Trefethen, SIAM Rev. 46, 2004, eq 5.2) at u.
fn barycentric(a: f64, values: &[f64; NODES], u: f64) -> f64 {
    let (mut num, mut den) = (0.0, 0.0);
    for (j, &g) in values.iter().enumerate() {
        let d = u - node(a, j);
        if d == 0.0 {
            return g;
        }
        let mut w = if j % 2 == 0 { 1.0 } else { -1.0 };
        if j == 0 || j == NODES - 1 {
            w *= 0.5;
        }
        let t = w / d;
        num += t * g;
        den += t;
    }
    num / den
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_smooth_function_is_interpolated_to_rounding() {
        // g(ψ) = 1/(1 + ψ) over ten decades: the panels resolve it to 1e-13.
        let table = GroupTable::default();
        let g = |psi: f64| Some(1.0 / (1.0 + psi));
        for i in 0..200 {
            let psi = 10f64.powf(-5.0 + 10.0 * i as f64 / 199.0);
            let got = table.value(psi, &g).unwrap();
            assert!((got - g(psi).unwrap()).abs() < 1e-13, "{psi}: {got}");
        }
        // A panel that does not solve is refused, not interpolated.
        let table = GroupTable::default();
        assert_eq!(table.value(2.0, &|p| (p < 2.2).then_some(0.5)), None);
        assert_eq!(table.value(-1.0, &g), None);
    }
}
