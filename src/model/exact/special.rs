//! The function G(y) = y − ln(1 + y) of the Hunt–Crossley energy integral (docs/physics.md §3) and its
//! inversion on the unloading branch, both accurate near y = 0 where the direct forms cancel.

use lambert_w::lambert_w0;

/// G(y) = y − ln(1 + y) for y > −1, to a few ulp everywhere (docs/physics.md §3, the C of the
/// energy integral). Below |y| = 0.1 the difference cancels, so the series Σₖ₌₂ (−y)ᵏ/k is summed.
pub fn y_minus_log1p(y: f64) -> f64 {
    if y.abs() < 0.1 {
        // y²·Σⱼ (−y)ʲ/(j + 2), Horner, 18 terms: the last is below 1e-17 of the first.
        let mut sum = 0.0;
        for j in (0..18).rev() {
            sum = sum * -y + 1.0 / (j + 2) as f64;
        }
        y * y * sum
    } else {
        y - y.ln_1p()
    }
}

/// The unloading root of G(−s) = c, c ≥ 0, as (s, w) with s ∈ [0, 1) and w = 1 − s both to full
/// relative precision: s = α·v_out and w = 1 + α·ẋ at the exit (docs/physics.md §3). In Lambert-W form
/// s = 1 + W₀(−e^{−(1+c)}). Near the branch point (c → 0, i.e. e → 1) that form loses half its
/// digits, so the guess there comes from the branch-point series W₀ = −1 + p − p²/3 + 11p³/72 −
/// 43p⁴/540 + 769p⁵/17280, p = √(2(1 − e^{−c})), and Newton on G(−s) = c polishes it. For c > 1
/// the small w is solved for directly from ln w − w = −1 − c, since s rounds towards 1.
pub fn unloading_root(c: f64) -> (f64, f64) {
    if c <= 0.0 {
        return (0.0, 1.0);
    }
    if c > 1.0 {
        // w = e^{w − 1 − c} < e^{−2}: Newton on ln w − w + 1 + c = 0 from the fixed-point guess.
        let floor = (-1.0 - c).exp();
        if floor == 0.0 {
            // e^{−1−c} underflows (c > 744): w is below the smallest double.
            return (1.0, 0.0);
        }
        let mut w = (-lambert_w0(-floor)).max(floor);
        for _ in 0..50 {
            let step = (w.ln() - w + 1.0 + c) * w / (1.0 - w);
            w -= step;
            if step.abs() <= 2.0 * f64::EPSILON * w {
                break;
            }
        }
        return (1.0 - w, w);
    }
    let mut s = if c < 0.01 {
        let p = (-2.0 * (-c).exp_m1()).sqrt();
        p * (1.0 + p * (-1.0 / 3.0 + p * (11.0 / 72.0 + p * (-43.0 / 540.0 + p * 769.0 / 17280.0))))
    } else {
        1.0 + lambert_w0(-(-(1.0 + c)).exp())
    };
    // Bracket for the safeguard: G(−s) rises monotonically from 0 at s = 0 to ∞ at s = 1.
    let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
    for _ in 0..60 {
        if !(s > lo && s < hi) {
            s = 0.5 * (lo + hi);
        }
        let residual = y_minus_log1p(-s) - c;
        if residual > 0.0 {
            hi = s;
        } else {
            lo = s;
        }
        // d/ds G(−s) = s/(1 − s).
        let step = residual * (1.0 - s) / s;
        s -= step;
        if step.abs() <= 2.0 * f64::EPSILON * s {
            break;
        }
    }
    let s = s.clamp(0.0, 1.0);
    (s, 1.0 - s)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn series_and_direct_forms_join_smoothly() {
        // At |y| = 0.1 both forms are accurate; they must agree to ~1e-15.
        for &y in &[0.1, -0.1] {
            let below = {
                let mut sum = 0.0;
                for j in (0..18).rev() {
                    sum = sum * -y + 1.0 / (j + 2) as f64;
                }
                y * y * sum
            };
            let direct = y - f64::ln_1p(y);
            assert!((below / direct - 1.0).abs() < 1e-14, "{y}");
        }
    }

    #[test]
    fn small_argument_matches_leading_terms() {
        // G(y) = y²/2 − y³/3 + y⁴/4 − …; at y = 1e-6 three terms leave 4e-19 relative.
        let y: f64 = 1e-6;
        let expect = y * y / 2.0 - y.powi(3) / 3.0 + y.powi(4) / 4.0;
        assert!((y_minus_log1p(y) / expect - 1.0).abs() < 1e-15);
    }

    #[test]
    fn unloading_root_inverts_g() {
        for &c in &[1e-20, 1e-12, 1e-6, 0.009, 0.011, 0.3, 2.0, 5.0] {
            let (s, w) = unloading_root(c);
            assert!(s > 0.0 && s < 1.0, "{c}: {s}");
            assert!((w - (1.0 - s)).abs() <= f64::EPSILON);
            let back = y_minus_log1p(-s);
            assert!((back / c - 1.0).abs() < 1e-14, "{c}: {back}");
        }
        assert_eq!(unloading_root(0.0), (0.0, 1.0));
    }

    #[test]
    fn unloading_root_far_from_the_branch_point() {
        // Large c: w = 1 − s = e^{w − 1 − c} is tiny and is returned to full precision.
        for &c in &[1.5, 30.0, 700.0] {
            let (s, w) = unloading_root(c);
            assert!(((w.ln() - w + 1.0 + c) / c).abs() < 1e-15, "{c}: {w}");
            assert!((s - (1.0 - w)).abs() <= f64::EPSILON);
        }
        // Beyond the range of doubles w is 0 and s exactly 1, not NaN.
        assert_eq!(unloading_root(800.0), (1.0, 0.0));
    }

    #[test]
    fn unloading_root_near_branch_point_follows_the_series() {
        // Loading from y = a: c = G(a), and s = a − (2/3)a² + (4/9)a³ + O(a⁴) (series inversion of
        // s²/2 + s³/3 + … = a²/2 − a³/3 + …), so e_out = s/a = 1 − 2a/3 + 4a²/9 + O(a³).
        for &a in &[1e-9, 1e-6, 1e-4] {
            let (s, _) = unloading_root(y_minus_log1p(a));
            let expect = 1.0 - 2.0 * a / 3.0 + 4.0 * a * a / 9.0;
            assert!(((s / a) / expect - 1.0).abs() < 1e-12 + a * a * a, "{a}");
        }
    }
}
