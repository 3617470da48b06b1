//! Thornton's impact solved exactly (docs/physics.md §6.6): x_max from the energy balance, the
//! rebound from the unloading branch's stored energy, and the times as the sum of three phases,
//! each a one-dimensional conservative motion: elastic Hertz loading to x_y (an incomplete beta
//! function, eq 7's), the capped loading to x_max, and elastic unloading with k_u (half of
//! eq 7's contact time at the exit speed).

use std::f64::consts::PI;

use crate::model::exact::ExactImpact;
use crate::model::exact::elastic::elastic;
use crate::model::exact::gauss_jacobi::{nodes_for_gap, singular_at_end};
use crate::model::force::law::ForceLaw;
use crate::model::power_law::PowerLaw;

use super::Thornton;
use super::cap::{Cap, strip_dxi_du, strip_u, strip_work_rate};

impl Thornton {
    /// The exact impact, its quadratures (strips only) aimed at `rtol`.
    pub(super) fn exact_impact(&self, rtol: f64) -> ExactImpact {
        let params = self.params();
        if !self.yielded() {
            return elastic(params);
        }
        let (m, v0, law) = (params.mass, params.v0, params.law);
        let f_max = self.f_max;
        let t_elastic = law.loading_time_at(m, v0, self.x_yield);
        let t_plastic = match self.cap {
            Cap::Circle => self.circle_plastic_time(f_max),
            Cap::Strip => self.strip_plastic_time(rtol),
        };
        // Unloading from rest at x_max: the elastic law k_u·(x − x_res)ⁿ, its energy given back.
        // The span from F_max itself: x_max − x_res cancels where the dent is nearly all of x_max.
        let span = (f_max / self.k_unload).powf(1.0 / law.n);
        let unloading = PowerLaw {
            k: self.k_unload,
            n: law.n,
        };
        let v_out = (2.0 * unloading.energy(span) / m).sqrt();
        let t_unloading = 0.5 * unloading.contact_time(m, v_out);
        let t_x_max = t_elastic + t_plastic;
        ExactImpact {
            x_max: self.x_max,
            t_x_max,
            f_max,
            t_f_max: t_x_max,
            x_f_max: self.x_max,
            v_f_max: 0.0,
            t_contact: t_x_max + t_unloading,
            v_out,
            x_residual: self.x_residual,
            tensile_cutoff: false,
        }
    }

    /// The circle's capped loading, F = F_max − k_p·s with s = x_max − x and k_p = (3/2)·F_y/x_y:
    /// ½m·v² = F_max·s − ½k_p·s², so t = ∫₀^{s_y} ds/v = (2/√B)·arcsin(√(B·s_y/A)), A = 2F_max/m,
    /// B = k_p/m (the arcsine written from s = 0, where it has no cancellation).
    fn circle_plastic_time(&self, f_max: f64) -> f64 {
        let m = self.params.mass;
        let k_plastic = 1.5 * self.f_yield / self.x_yield;
        let (a, b) = (2.0 * f_max / m, k_plastic / m);
        let s_yield = self.x_max - self.x_yield;
        2.0 / b.sqrt() * (b * s_yield / a).min(1.0).sqrt().asin()
    }

    /// The strip's capped loading, in u with β = cosh u (ξ = x/x_y = β^{2/n}): t = ∫ (dx/du)/v du
    /// from 0 to u_max, v = √(2·ΔW(u)/m) with ΔW the capped force's work from u to u_max. Panels of
    /// unit width in u (the integrands' singularities lie at u = ±iπ/2); the last one's rule
    /// absorbs v's (u_max − u)^{−1/2}. ΔW at each node is the sum of the later panels' work and a
    /// Gauss–Legendre integral over the rest of its own panel: positive terms, no cancellation.
    fn strip_plastic_time(&self, rtol: f64) -> f64 {
        let (m, n) = (self.params.mass, self.params.law.n);
        let u_max = strip_u(self.x_max / self.x_yield, n);
        let panels = u_max.ceil().max(1.0) as usize;
        let width = u_max / panels as f64;
        let nodes = nodes_for_gap(rtol, 0.25 * PI, width);
        // The last panel's time integrand, its (u_max − u)^{−1/2} divided out, also has a branch
        // point at u = −u_max (ΔW ∝ u_max² − u² near u = 0): as near as a + u_max to its start.
        let last_nodes = nodes_for_gap(rtol, (0.25 * PI).min(u_max + u_max - width), width);
        let work =
            |a: f64, b: f64| singular_at_end(|u, _, _| strip_work_rate(u, n), a, b, 0.0, nodes);
        // tail[i]: the work over panels i.. (over F_y·x_y).
        let mut tail = vec![0.0; panels + 1];
        for i in (0..panels).rev() {
            let a = i as f64 * width;
            tail[i] = tail[i + 1] + work(a, a + width);
        }
        let scale = self.x_yield * (m / (2.0 * self.f_yield * self.x_yield)).sqrt();
        (0..panels)
            .map(|i| {
                let (a, b) = (i as f64 * width, (i + 1) as f64 * width);
                let b = if i + 1 == panels { u_max } else { b };
                let integrand = |u: f64, _: f64, to_b: f64| {
                    let rest = if to_b > 0.0 { work(u, b) } else { 0.0 };
                    scale * strip_dxi_du(u, n) / (rest + tail[i + 1]).sqrt()
                };
                if i + 1 == panels {
                    singular_at_end(integrand, a, b, -0.5, last_nodes)
                } else {
                    singular_at_end(integrand, a, b, 0.0, nodes)
                }
            })
            .sum()
    }
}
