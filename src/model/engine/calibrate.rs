//! Damping that realises a requested restitution: the Hunt–Crossley relation in closed form, the
//! engines' restitution maps, and a bracketed root on hertz-tui's own solve for the rest.

use std::f64::consts::PI;

use crate::model::numeric::roots::brent;

use super::error::EngineError;

/// The χ = α·v₀ of F = k·xⁿ·(1 + α·ẋ) whose realised restitution is `e`: the root of
/// ln((1 + χ)/(1 − χ·e)) = χ·(1 + e), the exit condition of the family's separable energy integral
/// (docs/physics.md §7; Carvalho & Martins, Mech. Mach. Theory 2019). Independent of n, k, m, v₀.
pub fn hunt_crossley_chi(e: f64) -> f64 {
    if e >= 1.0 {
        return 0.0;
    }
    let g = |chi: f64| (chi).ln_1p() - (-chi * e).ln_1p() - chi * (1.0 + e);
    // g ≈ −(1 − e²)χ²/2 + (1 + e³)χ³/3 near 0 and → +∞ as χ → 1/e: a quarter of the small-χ
    // root 3(1 − e²)/(2(1 + e³)) lies where g < 0 for every e in (0, 1).
    let lo = 0.375 * (1.0 - e * e) / (1.0 + e * e * e);
    let hi = (1.0 - f64::EPSILON) / e;
    // Below e ≈ 0.03 the root lies within (1 + χ)·e^{−χ(1+e)} < ε of the pole 1/e: g(hi) < 0 and
    // the largest representable χ below the pole is the root to double precision.
    if g(hi) <= 0.0 {
        return hi;
    }
    brent(g, lo, hi).unwrap_or(f64::NAN)
}

/// β = ln e/√(ln² e + π²) (≤ 0): the restitution map of Tsuji et al. (Powder Technol. 1992) that
/// Chrono, LIGGGHTS, LAMMPS and Yade share (docs/physics.md §7).
pub fn beta(e: f64) -> f64 {
    let l = e.ln();
    l / (l * l + PI * PI).sqrt()
}

/// How close an end of the damping range must come to the target to be taken as is.
const END_TOLERANCE: f64 = 1e-10;

/// The parameter θ in [lo, hi] at which `e_of(θ)` equals `target`, by Brent's method on the
/// realised restitution (monotone in θ). Unreachable targets name the range the engine spans.
pub fn solve_for_restitution(
    engine: &'static str,
    target: f64,
    lo: f64,
    hi: f64,
    e_of: impl Fn(f64) -> Result<f64, EngineError>,
) -> Result<f64, EngineError> {
    // An end that realises the target to the solver's accuracy is the answer (e = 1 with no
    // damping comes out 1 − 1e-12 from the integrator); `hi` first, the cheap end.
    let e_hi = e_of(hi)?;
    if (e_hi - target).abs() <= END_TOLERANCE {
        return Ok(hi);
    }
    let e_lo = e_of(lo)?;
    if (e_lo - target).abs() <= END_TOLERANCE {
        return Ok(lo);
    }
    let (e_min, e_max) = (e_lo.min(e_hi), e_lo.max(e_hi));
    if !(e_min..=e_max).contains(&target) {
        return Err(EngineError::Unreachable {
            engine,
            requested: target,
            reason: format!(
                "over its damping range the engine's law realises e in [{e_min:.6}, {e_max:.6}]"
            ),
        });
    }
    brent(|theta| e_of(theta).map_or(f64::NAN, |e| e - target), lo, hi)
        .ok_or(EngineError::NonFinite)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The relation changes sign within 1e-7 relative of the root (near e = 1 it is flat to
    /// O(χ³), so rounding allows no closer), and its two limits.
    #[test]
    fn chi_satisfies_the_exit_relation_and_its_limits() {
        for &e in &[0.05, 0.2, 0.5, 0.6, 0.9, 0.999] {
            let chi = hunt_crossley_chi(e);
            let g = |c: f64| c.ln_1p() - (-c * e).ln_1p() - c * (1.0 + e);
            // Near e → 0 the root sits within 1e-8 of the pole 1/e: probe halfway to it there.
            let above = (chi * (1.0 + 1e-7)).min(0.5 * (chi + 1.0 / e));
            assert!(g(chi * (1.0 - 1e-7)) < 0.0 && g(above) > 0.0, "e = {e}");
        }
        // e → 1: χ ≈ 3(1 − e)/2; e = 0.6 → 0.97487 (engine notes, Carvalho & Martins).
        assert!((hunt_crossley_chi(0.9999) / (1.5e-4) - 1.0).abs() < 1e-3);
        assert!((hunt_crossley_chi(0.6) - 0.97487).abs() < 1e-5);
        assert_eq!(hunt_crossley_chi(1.0), 0.0);
    }

    #[test]
    fn beta_map_end_points() {
        assert_eq!(beta(1.0), 0.0);
        assert!((beta(1e-300) + 1.0).abs() < 2e-5);
        assert!((beta(0.5) - 0.5_f64.ln() / (0.5_f64.ln().powi(2) + PI * PI).sqrt()).abs() < 1e-16);
    }
}
