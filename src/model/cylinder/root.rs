//! Newton's method safeguarded by bisection, for an increasing function on a bracket.

/// Relative change of the iterate at which the solve stops.
const TOLERANCE: f64 = 1e-14;

/// Newton steps plus bisections allowed; bisection alone halves the bracket, so a few hundred
/// steps reach any f64 resolution from any bracket.
const MAX_ITERATIONS: usize = 400;

/// Solves g(t) = target for t in (lo, hi), given `value_and_slope(t) = (g(t), g'(t))` with g
/// increasing and g(lo) < target < g(hi).
///
/// A Newton step that leaves the current bracket, or meets a slope that is not positive and
/// finite, is replaced by bisection, so the iterate never leaves (lo, hi). Stops when a step
/// changes t by less than 1e-14 relative, or when the bracket has shrunk below that. `None` if
/// g is not finite at an iterate, or neither happens within the iteration budget.
pub(super) fn solve_increasing(
    value_and_slope: impl Fn(f64) -> (f64, f64),
    target: f64,
    mut lo: f64,
    mut hi: f64,
    guess: f64,
) -> Option<f64> {
    let mut t = if guess > lo && guess < hi {
        guess
    } else {
        midpoint(lo, hi)
    };
    for _ in 0..MAX_ITERATIONS {
        let (value, slope) = value_and_slope(t);
        let residual = value - target;
        if !residual.is_finite() {
            return None;
        }
        if residual == 0.0 {
            return Some(t);
        }
        if residual < 0.0 {
            lo = t;
        } else {
            hi = t;
        }
        let newton = t - residual / slope;
        let next = if slope > 0.0 && slope.is_finite() && newton > lo && newton < hi {
            newton
        } else {
            midpoint(lo, hi)
        };
        if (next - t).abs() <= TOLERANCE * next.abs() || hi - lo <= TOLERANCE * hi.abs() {
            return Some(next);
        }
        t = next;
    }
    None
}

/// Midpoint of the bracket; geometric when it spans decades, so tiny roots are reached quickly.
fn midpoint(lo: f64, hi: f64) -> f64 {
    if lo > 0.0 && hi > 4.0 * lo {
        (lo * hi).sqrt()
    } else if lo == 0.0 && hi > 0.0 {
        // Roots may sit many decades below hi: step down by a large factor, not by one half.
        hi * 1e-3
    } else {
        0.5 * (lo + hi)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cube_root_by_newton() {
        let root = solve_increasing(|t| (t * t * t, 3.0 * t * t), 2.0, 0.0, 10.0, 5.0).unwrap();
        assert!((root - 2f64.cbrt()).abs() < 1e-15, "{root}");
    }

    #[test]
    fn flat_and_wrong_slopes_fall_back_to_bisection() {
        // A deliberately wrong slope (negative): only bisection can make progress.
        let root = solve_increasing(|t| (t, -1.0), 0.3, 0.0, 1.0, 0.9).unwrap();
        assert!((root - 0.3).abs() < 1e-14, "{root}");
        // Zero slope everywhere: Newton is undefined.
        let root = solve_increasing(|t| (t.powi(3), 0.0), 1e-6, 0.0, 1.0, 0.5).unwrap();
        assert!((root / 1e-2 - 1.0).abs() < 1e-13, "{root}");
    }

    #[test]
    fn tiny_roots_from_zero_lower_bound() {
        let target = 1e-200;
        let root = solve_increasing(|t| (t, 1.0), target, 0.0, 1.0, 2.0).unwrap();
        assert!((root / target - 1.0).abs() < 1e-14, "{root}");
    }

    #[test]
    fn a_guess_outside_the_bracket_is_ignored() {
        let root = solve_increasing(|t| (t.exp(), t.exp()), 3.0, 0.0, 5.0, -7.0).unwrap();
        assert!((root - 3f64.ln()).abs() < 1e-15, "{root}");
    }

    #[test]
    fn non_finite_values_give_none() {
        assert_eq!(
            solve_increasing(|_| (f64::NAN, 1.0), 1.0, 0.0, 1.0, 0.5),
            None
        );
        assert_eq!(
            solve_increasing(|t| (1.0 / (t - 0.5), 1.0), 1.0, 0.0, 1.0, 0.5),
            None
        );
    }
}
