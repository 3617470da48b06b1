//! Bracketed root finding and maximisation (Brent's methods) for scalar functions: event times,
//! energy-integral roots, force peaks.

/// The final bracket of [`zeroin`]: `best` is the iterate with the smallest |f|, `other` lies on the
/// opposite side of the root (they coincide in the limit).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bracket {
    pub best: f64,
    pub f_best: f64,
    pub other: f64,
}

/// Brent's zeroin (Brent 1973, "Algorithms for minimization without derivatives", ch. 4): inverse
/// quadratic interpolation guarded by bisection, on [a, b] with f(a) = fa and f(b) = fb of opposite
/// signs, to a bracket of ≤ 4·ε·|root|. Stops early if f turns NaN (`f_best` is then NaN).
pub fn zeroin(mut f: impl FnMut(f64) -> f64, a: f64, b: f64, fa: f64, fb: f64) -> Bracket {
    let (mut a, mut fa, mut b, mut fb) = (a, fa, b, fb);
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    // Brent's method converges in well under 100 iterations for any f64 bracket; the cap only
    // guarantees termination if f misbehaves.
    for _ in 0..200 {
        if fb.signum() == fc.signum() {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        let tol = 2.0 * f64::EPSILON * b.abs() + f64::MIN_POSITIVE;
        let m = 0.5 * (c - b);
        if m.abs() <= tol || fb == 0.0 {
            break;
        }
        if e.abs() >= tol && fa.abs() > fb.abs() {
            // Inverse quadratic interpolation, or secant when only two points are distinct.
            let s = fb / fa;
            let (mut p, mut q) = if a == c {
                (2.0 * m * s, 1.0 - s)
            } else {
                let q = fa / fc;
                let r = fb / fc;
                (
                    s * (2.0 * m * q * (q - r) - (b - a) * (r - 1.0)),
                    (q - 1.0) * (r - 1.0) * (s - 1.0),
                )
            };
            if p > 0.0 {
                q = -q;
            } else {
                p = -p;
            }
            if 2.0 * p < (3.0 * m * q - (tol * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = m;
            }
        } else {
            d = m;
            e = m;
        }
        a = b;
        fa = fb;
        b += if d.abs() > tol { d } else { tol.copysign(m) };
        fb = f(b);
        if fb.is_nan() {
            break;
        }
    }
    Bracket {
        best: b,
        f_best: fb,
        other: c,
    }
}

/// A root of `f` in [a, b] where f(a) and f(b) differ in sign (or one is zero), by [`zeroin`].
/// Returns `None` if the ends do not bracket a root or `f` is non-finite on the way.
pub fn brent(mut f: impl FnMut(f64) -> f64, a: f64, b: f64) -> Option<f64> {
    let (fa, fb) = (f(a), f(b));
    if !(fa.is_finite() && fb.is_finite()) {
        return None;
    }
    if fa == 0.0 {
        return Some(a);
    }
    if fb == 0.0 {
        return Some(b);
    }
    if fa.signum() == fb.signum() {
        return None;
    }
    let bracket = zeroin(f, a, b, fa, fb);
    bracket.f_best.is_finite().then_some(bracket.best)
}

/// The maximum of `f` on [a, b], assumed unimodal there, by golden-section search with parabolic
/// steps (Brent's `fmin`), to a bracket of ~√ε relative width: f itself is then exact to ~ε.
/// Returns (argmax, max); an end of the interval if f is monotone.
pub fn brent_max(mut f: impl FnMut(f64) -> f64, a: f64, b: f64) -> (f64, f64) {
    const GOLDEN: f64 = 0.381_966_011_250_105_1;
    let (mut a, mut b) = (a.min(b), a.max(b));
    // A peak at an end (a monotone f, the common case of force peaks next to a phase boundary)
    // is where golden sections converge slowest. For unimodal f, f(b − δ) < f(b) puts the peak in
    // [b − δ, b]; with δ the search's own resolution the end is as exact as the search would be.
    // (Equality proves nothing — f may be flat there, or δ below f's resolution — so it searches.)
    // The golden point, the search's first probe, must not lie higher: a guard for interpolants
    // that are not quite unimodal at loose tolerances.
    let delta = 2.0 * f64::EPSILON.sqrt() * a.abs().max(b.abs()).max(b - a);
    if b - a > 4.0 * delta {
        let (fa, fb) = (f(a), f(b));
        let f_golden = f(a + GOLDEN * (b - a));
        if f_golden <= fb && f(b - delta) < fb {
            return (b, fb);
        }
        if f_golden <= fa && f(a + delta) < fa {
            return (a, fa);
        }
    }
    let mut x = a + GOLDEN * (b - a);
    let (mut w, mut v) = (x, x);
    let mut fx = -f(x);
    let (mut fw, mut fv) = (fx, fx);
    let (mut d, mut e) = (0.0_f64, 0.0_f64);
    for _ in 0..100 {
        let m = 0.5 * (a + b);
        let tol = f64::EPSILON.sqrt() * x.abs() + 1e-300;
        if (x - m).abs() <= 2.0 * tol - 0.5 * (b - a) {
            break;
        }
        let mut golden = true;
        if e.abs() > tol {
            // Parabola through (v, fv), (w, fw), (x, fx).
            let r = (x - w) * (fx - fv);
            let q = (x - v) * (fx - fw);
            let mut p = (x - v) * q - (x - w) * r;
            let mut q = 2.0 * (q - r);
            if q > 0.0 {
                p = -p;
            } else {
                q = -q;
            }
            if p.abs() < (0.5 * q * e).abs() && p > q * (a - x) && p < q * (b - x) {
                e = d;
                d = p / q;
                let u = x + d;
                if u - a < 2.0 * tol || b - u < 2.0 * tol {
                    d = tol.copysign(m - x);
                }
                golden = false;
            }
        }
        if golden {
            e = if x < m { b - x } else { a - x };
            d = GOLDEN * e;
        }
        let u = if d.abs() >= tol {
            x + d
        } else {
            x + tol.copysign(d)
        };
        let fu = -f(u);
        if fu <= fx {
            if u < x {
                b = x;
            } else {
                a = x;
            }
            (v, fv, w, fw, x, fx) = (w, fw, x, fx, u, fu);
        } else {
            if u < x {
                a = u;
            } else {
                b = u;
            }
            if fu <= fw || w == x {
                (v, fv, w, fw) = (w, fw, u, fu);
            } else if fu <= fv || v == x || v == w {
                (v, fv) = (u, fu);
            }
        }
    }
    // The ends, for a monotone f.
    let (fa, fb) = (f(a), f(b));
    if fa > -fx && fa >= fb {
        (a, fa)
    } else if fb > -fx {
        (b, fb)
    } else {
        (x, -fx)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_roots_to_machine_precision() {
        let r = brent(|x| x * x - 2.0, 0.0, 3.0).unwrap();
        assert!((r - 2f64.sqrt()).abs() < 4e-16);
        let r = brent(|x| x.cos() - x, 0.0, 1.0).unwrap();
        assert!((r.cos() - r).abs() < 1e-15);
    }

    #[test]
    fn maximises_a_smooth_peak() {
        // sin peaks at π/2; the value is exact to ε even though the argument is only to √ε.
        let (t, f) = brent_max(f64::sin, 0.3, 2.9);
        assert!((t - std::f64::consts::FRAC_PI_2).abs() < 1e-7, "{t}");
        assert!((f - 1.0).abs() < 1e-15);
        // A monotone function peaks at an end.
        assert_eq!(brent_max(|x| x, 0.0, 1.0), (1.0, 1.0));
    }

    #[test]
    fn a_peak_at_an_end_costs_a_few_evaluations_and_an_inner_one_is_still_searched() {
        let mut calls = 0;
        let (t, f) = brent_max(
            |x| {
                calls += 1;
                1.0 - (x - 2.0).powi(2)
            },
            0.0,
            1.0,
        );
        assert_eq!((t, f), (1.0, 0.0));
        assert!(calls <= 5, "{calls} evaluations");
        // A peak 1e-3 inside the right end: the end test fails and the search finds it.
        let (t, f) = brent_max(|x| 1.0 - (x - 0.999).powi(2), 0.0, 1.0);
        assert!((t - 0.999).abs() < 1e-7, "{t}");
        assert!((f - 1.0).abs() < 1e-15);
    }

    #[test]
    fn refuses_a_non_bracket() {
        assert_eq!(brent(|x| x * x + 1.0, -1.0, 1.0), None);
        assert_eq!(brent(|_| f64::NAN, -1.0, 1.0), None);
    }

    #[test]
    fn returns_an_end_that_is_a_root() {
        assert_eq!(brent(|x| x - 1.0, 1.0, 2.0), Some(1.0));
    }
}
