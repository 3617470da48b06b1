//! From the accuracy a caller asks for to the tolerances an integrator is given.
//!
//! An adaptive integrator bounds its local error per step, not the error of the numbers an impact
//! reports; how the two relate depends on the method. Measured on random scenes of every law
//! (sphere and cylinder, v₀ 0.01–2 m/s, e 0.2–0.99, with and without x_pl; errors of x_max,
//! F_max, t_c and x_residual relative to their scale, v_out relative to v₀, against DOP853 at
//! rtol 1e-14), with rtol = atol = p in the scaled variables and the end of contact landed on:
//!
//! - DOPRI5: worst error 0.3·p at p = 1e-3, 10·p at 1e-9, 60·p at 1e-12;
//! - DOP853: 0.02·p at 1e-3, up to 10·p at 1e-9…1e-12;
//! - Radau5: ≈ 0.3·p′ with its internal p′ = 0.1·p^{2/3} (Hairer's RADAU5 mapping), floored by
//!   its p > 10·ε at p′ ≈ 2e-11.
//!
//! So DOPRI5 runs at rtol/10, DOP853 at rtol, Radau5 at the p whose p′ is 3·rtol: each keeps every
//! reported number within 100·rtol with a margin of at least 1.5 (tests/model/tolerance_promise.rs).

use crate::model::ode::Method;

/// DOPRI5 is given rtol/10.
const DOPRI5_FACTOR: f64 = 0.1;

/// Radau5's internal tolerance p′ = 0.1·p^{2/3} is set to this multiple of rtol.
const RADAU5_INTERNAL_FACTOR: f64 = 3.0;

/// The smallest p Radau5 accepts with a margin (it refuses p ≤ 10·ε): p′ ≈ 4.6e-11.
const RADAU5_FLOOR: f64 = 1e-14;

/// (rtol, atol) to hand `method` so that the impact's numbers are within 100·`rtol` of the truth.
/// `atol` is the caller's absolute tolerance in the solver's scaled variables, or `None` for the
/// same value as rtol (the scaled variables are of order 1 throughout an impact); it is mapped by
/// the same factor as rtol.
pub(crate) fn integrator_tolerances(method: Method, rtol: f64, atol: Option<f64>) -> (f64, f64) {
    let given = match method {
        Method::Dopri5 => rtol * DOPRI5_FACTOR,
        // p with 0.1·p^{2/3} = 3·rtol.
        Method::Radau5 => (10.0 * RADAU5_INTERNAL_FACTOR * rtol)
            .powf(1.5)
            .max(RADAU5_FLOOR),
        _ => rtol,
    };
    let atol = atol.map_or(given, |a| a * given / rtol);
    (given, atol)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn radau5_is_never_asked_below_its_floor_and_tightens_monotonically() {
        let mut last = f64::INFINITY;
        for k in 3..=14 {
            let (p, a) = integrator_tolerances(Method::Radau5, 10f64.powi(-k), None);
            assert!(p >= RADAU5_FLOOR);
            assert!(p <= last, "1e-{k}");
            assert_eq!(a, p);
            last = p;
        }
        // 0.1·p^{2/3} = 3e-8 at rtol 1e-8.
        let (p, _) = integrator_tolerances(Method::Radau5, 1e-8, None);
        assert!((0.1 * p.powf(2.0 / 3.0) / 3e-8 - 1.0).abs() < 1e-12);
    }

    #[test]
    fn a_given_atol_scales_with_rtol() {
        let (r, a) = integrator_tolerances(Method::Dopri5, 1e-6, Some(1e-9));
        assert!((r - 1e-7).abs() < 1e-22 && (a - 1e-10).abs() < 1e-25);
        assert_eq!(
            integrator_tolerances(Method::Dop853, 1e-6, None),
            (1e-6, 1e-6)
        );
    }
}
