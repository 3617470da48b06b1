//! Quadrature rules: tanh-sinh for integrands with end-point singularities (contact times), and
//! Gauss–Legendre for smooth integrands on short intervals (work integrals on dense output).

use std::f64::consts::FRAC_PI_2;
use std::sync::OnceLock;

/// Finest tanh-sinh spacing is 1/2^`MAX_LEVEL`.
const MAX_LEVEL: u32 = 6;
/// Nodes per unit of t at the finest level.
const PER_UNIT: usize = 1 << MAX_LEVEL;
/// Truncation of the tanh-sinh sum: at t = 4.5 the node lies 1e-61 of the half-width from the end,
/// far enough for integrands as singular as δ^(−0.9).
const T_MAX: f64 = 4.5;

/// (1 − tanh u, weight) at t = k/64, u = (π/2)·sinh t, weight = (π/2)·cosh t / cosh² u
/// (Takahasi–Mori). The distance to the end is kept separately so nodes 1e-60 from an end
/// still tell the integrand where they are.
fn table() -> &'static [(f64, f64)] {
    static TABLE: OnceLock<Vec<(f64, f64)>> = OnceLock::new();
    TABLE.get_or_init(|| {
        let count = (T_MAX * PER_UNIT as f64) as usize;
        (0..=count)
            .map(|k| {
                let t = k as f64 / PER_UNIT as f64;
                let u = FRAC_PI_2 * t.sinh();
                let dist = 2.0 / (1.0 + (2.0 * u).exp());
                let weight = FRAC_PI_2 * t.cosh() / (u.cosh() * u.cosh());
                (dist, weight)
            })
            .collect()
    })
}

/// ∫ₐᵇ f, where `f(x, x − a, b − x)` receives both end distances exactly, so integrands singular at
/// an end (δ^(−p), p < 1) can evaluate themselves without cancellation. Levels are refined until the
/// change between levels is below √`rtol`/10 (tanh-sinh doubles its correct digits per level), up to
/// spacing 1/64. Returns the last estimate; a non-finite integrand gives a non-finite result.
pub fn tanh_sinh(mut f: impl FnMut(f64, f64, f64) -> f64, a: f64, b: f64, rtol: f64) -> f64 {
    let half = 0.5 * (b - a);
    if half <= 0.0 {
        return 0.0;
    }
    let table = table();
    let mid = a + half;
    // Level 0 starts with the centre node.
    let mut sum = table[0].1 * f(mid, half, half);
    let mut pair = |k: usize| {
        let (dist, weight) = table[k];
        let near = half * dist;
        let far = 2.0 * half - near;
        weight * (f(a + near, near, far) + f(b - near, far, near))
    };
    let target = 0.1 * rtol.max(1e-15).sqrt();
    // Level 0: spacing 1.
    let mut stride = PER_UNIT;
    let mut k = stride;
    while k < table.len() {
        sum += pair(k);
        k += stride;
    }
    let mut estimate = half * sum;
    for level in 1..=MAX_LEVEL {
        stride /= 2;
        let mut k = stride;
        while k < table.len() {
            sum += pair(k);
            k += 2 * stride;
        }
        let h = 1.0 / (1u32 << level) as f64;
        let next = half * h * sum;
        let change = (next - estimate).abs();
        estimate = next;
        if level >= 3 && change <= target * next.abs() {
            break;
        }
        if !next.is_finite() {
            break;
        }
    }
    estimate
}

/// Four-point Gauss–Legendre nodes on [−1, 1] (positive half; the rule is symmetric).
pub const GL4_NODES: [f64; 2] = [0.339_981_043_584_856_3, 0.861_136_311_594_052_6];
/// Weights matching [`GL4_NODES`].
pub const GL4_WEIGHTS: [f64; 2] = [0.652_145_154_862_546_1, 0.347_854_845_137_453_9];

/// ∫ₐᵇ f by four-point Gauss–Legendre: exact for polynomials of degree ≤ 7.
pub fn gauss_legendre_4(mut f: impl FnMut(f64) -> f64, a: f64, b: f64) -> f64 {
    let c = 0.5 * (a + b);
    let r = 0.5 * (b - a);
    let mut sum = 0.0;
    for (x, w) in GL4_NODES.iter().zip(GL4_WEIGHTS) {
        sum += w * (f(c - r * x) + f(c + r * x));
    }
    r * sum
}

/// Six-point Gauss–Legendre nodes on [−1, 1] (positive half; the rule is symmetric).
pub const GL6_NODES: [f64; 3] = [
    0.238_619_186_083_196_9,
    0.661_209_386_466_264_5,
    0.932_469_514_203_152,
];
/// Weights matching [`GL6_NODES`].
pub const GL6_WEIGHTS: [f64; 3] = [
    0.467_913_934_572_691,
    0.360_761_573_048_138_6,
    0.171_324_492_379_170_3,
];

/// ∫ₐᵇ f by six-point Gauss–Legendre: exact for polynomials of degree ≤ 11.
pub fn gauss_legendre_6(mut f: impl FnMut(f64) -> f64, a: f64, b: f64) -> f64 {
    let c = 0.5 * (a + b);
    let r = 0.5 * (b - a);
    let mut sum = 0.0;
    for (x, w) in GL6_NODES.iter().zip(GL6_WEIGHTS) {
        sum += w * (f(c - r * x) + f(c + r * x));
    }
    r * sum
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::numeric::beta::beta;

    #[test]
    fn four_point_gauss_legendre_is_exact_to_degree_seven() {
        let got = gauss_legendre_4(|x| x.powi(7) - 3.0 * x.powi(2), -1.0, 3.0);
        let exact = (3f64.powi(8) - 1.0) / 8.0 - (27.0 + 1.0);
        assert!((got / exact - 1.0).abs() < 1e-14, "{got} vs {exact}");
        let deg8 = gauss_legendre_4(|x| x.powi(8), 0.0, 1.0);
        assert!((deg8 * 9.0 - 1.0).abs() > 1e-6);
    }

    #[test]
    fn gauss_legendre_is_exact_to_degree_eleven() {
        // ∫₀² x¹¹ dx = 2¹²/12; degree 12 is not integrated exactly.
        let exact = 4096.0 / 12.0;
        let got = gauss_legendre_6(|x| x.powi(11), 0.0, 2.0);
        assert!((got / exact - 1.0).abs() < 1e-14, "{got}");
        let deg12 = gauss_legendre_6(|x| x.powi(12), 0.0, 2.0);
        assert!((deg12 / (8192.0 / 13.0) - 1.0).abs() > 1e-8);
    }

    #[test]
    fn tanh_sinh_integrates_end_point_singularities() {
        // ∫₀¹ x^(−0.6)(1 − x)^(−0.5) dx = B(0.4, 0.5): both ends singular.
        let got = tanh_sinh(|_, l, r| l.powf(-0.6) * r.powf(-0.5), 0.0, 1.0, 1e-15);
        let exact = beta(0.4, 0.5);
        assert!((got / exact - 1.0).abs() < 1e-13, "{got} vs {exact}");
    }

    #[test]
    fn tanh_sinh_meets_a_loose_tolerance_with_few_levels() {
        // ∫₀^π sin = 2, to 1e-6 at least.
        let got = tanh_sinh(|x, _, _| x.sin(), 0.0, std::f64::consts::PI, 1e-8);
        assert!((got - 2.0).abs() < 1e-8, "{got}");
    }

    #[test]
    fn empty_interval_integrates_to_zero() {
        assert_eq!(tanh_sinh(|_, _, _| 1.0, 1.0, 1.0, 1e-10), 0.0);
    }
}
