//! The capped Hertz pressure of Thornton's law: a circle on spheres, a strip on cylinders
//! (docs/physics.md §6.6), and the restitution each gives.

use std::f64::consts::PI;

use crate::model::exact::gauss_jacobi::singular_at_end;
use crate::model::numeric::roots::brent;

/// Where the capped pressure acts: a circle of radius a (spheres, Thornton 1997) or a strip of
/// half-width b (cylinders, the same construction in two dimensions), docs/physics.md §6.6.
/// Both follow Hertz's kinematics, a² = R·x or b² ∝ k·xⁿ, so with β = a/a_y or b/b_y the
/// loaded contact is β times as wide as at first yield.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Cap {
    /// F = F_y·(3β² − 1)/2, β² = x/x_y: Thornton's F = F_y + π·p_y·R·(x − x_y).
    Circle,
    /// F = (2F_y/π)·(β²·arcsin(1/β) + √(β² − 1)), β = (x/x_y)^{n/2}: the strip's Hertz pressure
    /// p₀·√(1 − s²/b²) capped at p_y and integrated across it (Johnson 1985, eq 4.45).
    Strip,
}

impl Cap {
    /// The plastic branch's force over F_y at ξ = x/x_y ≥ 1 for exponent n.
    pub(crate) fn force_ratio(self, xi: f64, n: f64) -> f64 {
        match self {
            Cap::Circle => 0.5 * (3.0 * xi - 1.0),
            Cap::Strip => {
                let beta = xi.powf(0.5 * n);
                2.0 / PI * (beta * beta * beta.recip().asin() + (beta * beta - 1.0).max(0.0).sqrt())
            }
        }
    }

    /// d(F/F_y)/dξ: 3/2, or (2/π)·n·β²·arcsin(1/β)/ξ (= n at ξ = 1: the loading is C¹ at yield).
    pub(crate) fn slope_ratio(self, xi: f64, n: f64) -> f64 {
        match self {
            Cap::Circle => 1.5,
            Cap::Strip => {
                let beta2 = xi.powf(n);
                2.0 / PI * n * beta2 * beta2.sqrt().recip().asin() / xi
            }
        }
    }

    /// ∫₁^ξ (F/F_y) dξ′, the plastic branch's work over F_y·x_y. The strip's integrand, in u with
    /// β = cosh u, is (2/π)·(cosh²u·(π/2 − gd u) + sinh u)·(2/n)·cosh^{2/n−1}u·sinh u: analytic,
    /// its nearest singularities at u = ±iπ/2, so 10 Gauss–Legendre nodes a unit panel reach
    /// rounding.
    pub(crate) fn work_ratio(self, xi: f64, n: f64) -> f64 {
        match self {
            Cap::Circle => {
                let d = xi - 1.0;
                d + 0.75 * d * d
            }
            Cap::Strip => {
                let top = strip_u(xi, n);
                if !top.is_finite() {
                    return f64::INFINITY;
                }
                let integrand = |u: f64, _: f64, _: f64| strip_work_rate(u, n);
                let panels = top.ceil().max(1.0);
                let width = top / panels;
                (0..panels as usize)
                    .map(|i| {
                        let a = i as f64 * width;
                        singular_at_end(integrand, a, a + width, 0.0, 10)
                    })
                    .sum()
            }
        }
    }

    /// ξ_max ≥ 1 where the plastic work reaches `work` (over F_y·x_y).
    pub(crate) fn approach_for_work(self, work: f64, n: f64) -> f64 {
        if work <= 0.0 || work.is_nan() {
            return 1.0;
        }
        if work == f64::INFINITY {
            return f64::INFINITY;
        }
        match self {
            // d + ¾d² = w.
            Cap::Circle => 1.0 + 2.0 * work / (1.0 + (1.0 + 3.0 * work).sqrt()),
            Cap::Strip => {
                // g(β) ≥ (π/2)·β (equal at β = 1, and g′ = 2β·arcsin(1/β) ≥ π/2), so F/F_y ≥ ξ^{n/2}
                // and the work reaches w by ξ = (1 + (n/2 + 1)·w)^{1/(n/2+1)}.
                let p = 0.5 * n + 1.0;
                let high = (1.0 + p * work).powf(p.recip());
                brent(|xi| self.work_ratio(xi, n) - work, 1.0, high).unwrap_or(high)
            }
        }
    }
}

/// u = arccosh β with β = ξ^{n/2}: the strip's variable, in which its work and times are analytic.
pub(crate) fn strip_u(xi: f64, n: f64) -> f64 {
    xi.powf(0.5 * n).max(1.0).acosh()
}

/// dξ/du = (2/n)·cosh^{2/n−1}u·sinh u, ξ = cosh^{2/n}u.
pub(crate) fn strip_dxi_du(u: f64, n: f64) -> f64 {
    let exponent = 2.0 / n;
    exponent * u.cosh().powf(exponent - 1.0) * u.sinh()
}

/// d(work over F_y·x_y)/du on the strip: (F/F_y)·dξ/du with F/F_y = (2/π)·(β²·arcsin(1/β) +
/// √(β² − 1)), β = cosh u, arcsin(1/β) = π/2 − gd u written as arctan(1/sinh u) (no
/// cancellation where it is ~2e^{−u}).
pub(crate) fn strip_work_rate(u: f64, n: f64) -> f64 {
    let (c, s) = (u.cosh(), u.sinh());
    2.0 / PI * (c * (c * s.recip().atan()) + s) * strip_dxi_du(u, n)
}

/// Thornton's e(V) above the yield velocity, q = V_y/V ∈ (0, 1]:
/// e = √(6√3/5)·√(1 − q²/6)·[q/(q + 2√(6/5 − q²/5))]^{1/4}; 1 at and below V_y.
pub fn thornton_restitution(q: f64) -> f64 {
    if q >= 1.0 {
        return 1.0;
    }
    let root = (6.0 / 5.0 - q * q / 5.0).sqrt();
    (6.0 * 3f64.sqrt() / 5.0).sqrt()
        * (1.0 - q * q / 6.0).sqrt()
        * (q / (q + 2.0 * root)).powf(0.25)
}

/// The restitution of Thornton's construction at q = V_y/V for a contact F = k·xⁿ capped as
/// `cap` (docs/physics.md §6.6): it depends on q and n alone. In units x_y = F_y = 1, the impact
/// energy is 1/((n + 1)·q²); ξ_max from the work, λ = ξ_maxⁿ/F_max, and the rebound returns
/// F_max·(ξ_max − ξ_res)/(n + 1) with ξ_max − ξ_res = (F_max/λⁿ⁻¹)^{1/n}. For the circle and
/// n = 3/2 it is [`thornton_restitution`]; for the strip it is the oracle and the calibration's.
pub fn capped_restitution(cap: Cap, q: f64, n: f64) -> f64 {
    if q >= 1.0 {
        return 1.0;
    }
    let energy = 1.0 / ((n + 1.0) * q * q);
    let xi_max = cap.approach_for_work(energy - 1.0 / (n + 1.0), n);
    let f_max = cap.force_ratio(xi_max, n);
    let lambda = xi_max.powf(n) / f_max;
    let span = (f_max / lambda.powf(n - 1.0)).powf(1.0 / n);
    (f_max * span / (n + 1.0) / energy).sqrt()
}
