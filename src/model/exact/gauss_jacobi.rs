//! Gauss–Jacobi rules for integrands with an algebraic end-point singularity, and Gauss–Legendre
//! rules of any size, by the Golub–Welsch eigenvalue method (Golub & Welsch 1969, Math. Comp. 23,
//! 221–230): the nodes are the eigenvalues of the symmetric tridiagonal Jacobi matrix of the
//! weight's three-term recurrence, the weights μ₀ times the squared first components of its
//! eigenvectors. Rules are built once per (exponent, size) and cached per thread.
//!
//! The exact impacts integrate dt = dx/v or dt = m·dv/F, which behave like δ^α (α = −1/2 or
//! −n/(n+1)) at a turning point δ → 0 and are smooth elsewhere: with the weight (1 − x)^α absorbed
//! into the rule, the rest is smooth and converges geometrically in the number of nodes.

use std::cell::RefCell;
use std::rc::Rc;

use nalgebra::{DMatrix, SymmetricEigen};

/// One rule on [−1, 1] for the weight (1 − x)^α: nodes as distances to both ends (exact, so an
/// integrand can evaluate itself near the singular end without cancellation), and weights with
/// the singular factor divided back out, so that Σ wᵢ·f(xᵢ) ≈ ∫ f for f ~ (1 − x)^α·smooth.
#[derive(Debug)]
struct Rule {
    /// (1 + xᵢ, 1 − xᵢ, wᵢ·(1 − xᵢ)^{−α}).
    points: Vec<(f64, f64, f64)>,
}

impl Rule {
    /// Golub–Welsch for the Jacobi weight (1 − x)^α·(1 + x)^0, α > −1, with `size` nodes.
    fn new(alpha: f64, size: usize) -> Self {
        let beta = 0.0;
        let ab = alpha + beta;
        let mut jacobi = DMatrix::<f64>::zeros(size, size);
        for k in 0..size {
            let kf = k as f64;
            let s = 2.0 * kf + ab;
            // Diagonal: (β² − α²)/((2k+α+β)(2k+α+β+2)); k = 0 as its limit (β − α)/(α + β + 2).
            jacobi[(k, k)] = if k == 0 {
                (beta - alpha) / (ab + 2.0)
            } else {
                (beta * beta - alpha * alpha) / (s * (s + 2.0))
            };
            if k + 1 < size {
                let j = kf + 1.0;
                let s = 2.0 * j + ab;
                let b =
                    4.0 * j * (j + alpha) * (j + beta) * (j + ab) / (s * s * (s + 1.0) * (s - 1.0));
                jacobi[(k, k + 1)] = b.sqrt();
                jacobi[(k + 1, k)] = b.sqrt();
            }
        }
        // μ₀ = ∫(1 − x)^α dx over [−1, 1] = 2^{α+1}/(α + 1).
        let mu0 = 2f64.powf(alpha + 1.0) / (alpha + 1.0);
        let eigen = SymmetricEigen::new(jacobi);
        let mut points: Vec<(f64, f64, f64)> = (0..size)
            .map(|i| {
                let x = eigen.eigenvalues[i];
                let v0 = eigen.eigenvectors[(0, i)];
                let w = mu0 * v0 * v0;
                // The node nearest 1 lies ~1/size² from it: 1 − x keeps ~14 digits.
                let (left, right) = (1.0 + x, 1.0 - x);
                (left, right, w * right.powf(-alpha))
            })
            .collect();
        points.sort_by(|a, b| a.0.total_cmp(&b.0));
        Rule { points }
    }
}

/// Nodes per rule for a relative accuracy `rtol` when the integrand's smooth part (what is left
/// once the rule's weight is divided out) is analytic up to a singularity `gap` beyond one end of
/// an interval of `length`: the error of an N-node Gauss rule falls like ρ^{−2N}, ρ = z + √(z² − 1)
/// the Bernstein ellipse through z = 1 + 2·gap/length (Trefethen, *Approximation Theory and
/// Approximation Practice*, ch. 19), plus one node of margin for the constant. At least 3, at
/// most 40.
pub fn nodes_for_gap(rtol: f64, gap: f64, length: f64) -> usize {
    let z = 1.0 + 2.0 * gap / length;
    let nodes = (rtol.clamp(1e-16, 1e-2).ln() / (-2.0 * (z + (z * z - 1.0).sqrt()).ln())).ceil();
    if nodes.is_finite() {
        (nodes as usize + 1).clamp(3, 40)
    } else {
        40
    }
}

thread_local! {
    static RULES: RefCell<Vec<(u64, usize, Rc<Rule>)>> = const { RefCell::new(Vec::new()) };
}

/// The cached rule for (α, size).
fn rule(alpha: f64, size: usize) -> Rc<Rule> {
    RULES.with(|cell| {
        let mut rules = cell.borrow_mut();
        if let Some((_, _, r)) = rules
            .iter()
            .find(|(a, s, _)| *a == alpha.to_bits() && *s == size)
        {
            return Rc::clone(r);
        }
        let r = Rc::new(Rule::new(alpha, size));
        rules.push((alpha.to_bits(), size, Rc::clone(&r)));
        r
    })
}

/// ∫ₐᵇ f for f ~ (b − x)^α·smooth near b (α > −1; α = 0 is Gauss–Legendre), with `size` nodes.
/// `f(x, x − a, b − x)` receives both end distances, as for [`super::quadrature::tanh_sinh`].
pub fn singular_at_end(
    mut f: impl FnMut(f64, f64, f64) -> f64,
    a: f64,
    b: f64,
    alpha: f64,
    size: usize,
) -> f64 {
    let half = 0.5 * (b - a);
    if half <= 0.0 {
        return 0.0;
    }
    let rule = rule(alpha, size);
    let mut sum = 0.0;
    for &(left, right, w) in &rule.points {
        let (from_a, to_b) = (half * left, half * right);
        sum += w * f(a + from_a, from_a, to_b);
    }
    // The weights carry (1 − x)^{−α} on [−1, 1]; on [a, b] that is ((b − x)/half)^{−α}.
    half * sum
}

/// ∫ₐᵇ f for f ~ (x − a)^α·smooth near a: [`singular_at_end`] reflected.
pub fn singular_at_start(
    mut f: impl FnMut(f64, f64, f64) -> f64,
    a: f64,
    b: f64,
    alpha: f64,
    size: usize,
) -> f64 {
    singular_at_end(
        |_, from_a, to_b| f(b - from_a, to_b, from_a),
        a,
        b,
        alpha,
        size,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn legendre_rule_is_exact_for_polynomials_of_degree_2n_minus_1() {
        // ∫₋₁¹ x^10 = 2/11 with 6 nodes (degree ≤ 11).
        let got = singular_at_end(|x, _, _| x.powi(10), -1.0, 1.0, 0.0, 6);
        assert!((got - 2.0 / 11.0).abs() < 1e-15, "{got}");
    }

    #[test]
    fn jacobi_rule_absorbs_the_end_singularity() {
        // ∫₀¹ (1 − x)^{−0.6}·e^x dx = e·γ(0.4, 1)·... checked against the series
        // Σₖ e·(−1)^k/(k!·(k + 0.4)) = ∫₀¹ u^{−0.6} e^{1−u} du.
        let mut series = 0.0;
        let mut term = 1.0;
        for k in 0..40 {
            if k > 0 {
                term *= -1.0 / k as f64;
            }
            series += term / (k as f64 + 0.4);
        }
        let expected = std::f64::consts::E * series;
        let got = singular_at_end(|x, _, to_b| to_b.powf(-0.6) * x.exp(), 0.0, 1.0, -0.6, 12);
        assert!((got / expected - 1.0).abs() < 1e-14, "{got} vs {expected}");
        // The same singularity at the start.
        let got = singular_at_start(
            |x, from_a, _| from_a.powf(-0.6) * (1.0 - x).exp(),
            0.0,
            1.0,
            -0.6,
            12,
        );
        assert!((got / expected - 1.0).abs() < 1e-14, "{got} vs {expected}");
    }

    #[test]
    fn the_rule_is_cached() {
        let a = rule(-0.5, 10);
        let b = rule(-0.5, 10);
        assert!(Rc::ptr_eq(&a, &b));
        assert_eq!(a.points.len(), 10);
    }
}
