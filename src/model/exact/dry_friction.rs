//! Dry friction F = k·xⁿ + P·x·sign(ẋ) (eq 15) through its energy identity (docs/physics.md §3).
//!
//! Scaled variables X = x/x_e, V = v/v₀ (x_e the elastic x_max), q = P·x_e²/(m·v₀²):
//! - loading:   V² = 1 − X^{n+1} − q·X², so X_m solves X^{n+1} + q·X² = 1;
//! - unloading: V² = (X_m^{n+1} − X^{n+1}) − q·(X_m² − X²).
//!
//! On unloading F = k·xⁿ − P·x turns tensile below x* = (P/k)^{1/(n−1)} (n > 1): the friction term
//! outgrows the elastic one near x = 0. By the compressive-only rule contact ends there, so
//! v_out² follows from the unloading identity at X* (not at 0), and x* is left as residual
//! approach. Eq 16's e² = 1 − 2P·x_max²/(m·v₀²) is the same identity carried on to x = 0.

use crate::model::force::ImpactParams;

use super::ExactImpact;
use super::elastic::elastic;
use super::gauss_jacobi::singular_at_end;

/// 1 − u^k for u ∈ [0, 1] from `to_one` = 1 − u, without cancellation.
#[derive(Debug, Clone, Copy)]
enum OneMinusPower {
    /// An integer k ≤ 8 (k = 2n + 2: 5 for spheres, 4 for a linear law): the factor
    /// (1 − u)·(1 + u + … + u^{k−1}), with no transcendental function.
    Integer(usize),
    /// Otherwise −expm1(k·ln(1 − to_one)).
    Real(f64),
}

impl OneMinusPower {
    fn new(k: f64) -> Self {
        if k.fract() == 0.0 && (1.0..=8.0).contains(&k) {
            OneMinusPower::Integer(k as usize)
        } else {
            OneMinusPower::Real(k)
        }
    }

    fn at(self, u: f64, to_one: f64) -> f64 {
        match self {
            OneMinusPower::Integer(k) => {
                let mut sum = 1.0;
                for _ in 1..k {
                    sum = sum * u + 1.0;
                }
                to_one * sum
            }
            OneMinusPower::Real(k) => -(k * (-to_one).ln_1p()).exp_m1(),
        }
    }
}

/// Digits of accuracy each Gauss–Jacobi node adds to the times, at the least: measured over n
/// from 1.05 to 1.5 and e from 0.3 to 0.99 (test `node_count_meets_the_tolerance`).
const DIGITS_PER_NODE: f64 = 1.2;

/// Nodes per time integral for a relative accuracy `rtol`, one more than the rate asks.
fn nodes_for(rtol: f64) -> usize {
    let digits = -rtol.clamp(1e-16, 1e-2).log10();
    (digits / DIGITS_PER_NODE).ceil() as usize + 1
}

/// The exact dry-friction impact with friction coefficient `p` (N/m, eq 16/17) and tensile cutoff at
/// `x_cut` (m; 0 where the law stays compressive): x_max from the loading energy equation, v_out from
/// the unloading identity, times by Gauss–Jacobi quadrature of dt = dx/v to `rtol`. P = 0 is elastic.
pub fn dry_friction(params: &ImpactParams, p: f64, x_cut: f64, rtol: f64) -> Option<ExactImpact> {
    with_nodes(params, p, x_cut, nodes_for(rtol))
}

/// [`dry_friction`] with `size` Gauss–Jacobi nodes per time integral.
fn with_nodes(params: &ImpactParams, p: f64, x_cut: f64, size: usize) -> Option<ExactImpact> {
    if p <= 0.0 {
        return Some(elastic(params));
    }
    let (m, v0, law) = (params.mass, params.v0, params.law);
    let n = law.n;
    let x_e = law.max_approach(m, v0);
    let t_ref = x_e / v0;
    let q = p * x_e * x_e / (m * v0 * v0);

    // X^{n+1} + q·X² = 1: increasing and convex in X, so Newton from X = 1 descends monotonically.
    let mut x_m = 1.0_f64;
    for _ in 0..100 {
        let x_n = x_m.powf(n);
        let step = (x_m * x_n + q * x_m * x_m - 1.0) / ((n + 1.0) * x_n + 2.0 * q * x_m);
        x_m -= step;
        if step.abs() <= 2.0 * f64::EPSILON * x_m {
            break;
        }
    }
    let x_star = (x_cut / x_e).min(x_m);

    // V² on each branch at X = X_m·u², from `to_one` = 1 − u: X_m^{n+1}·(1 − u^{2n+2}) ± q·(X_m² − X²).
    let x_m_p = x_m.powf(n + 1.0);
    let power = OneMinusPower::new(2.0 * n + 2.0);
    let elastic_drop = |u: f64, to_one: f64| x_m_p * power.at(u, to_one);
    let friction_drop = |u: f64, to_one: f64| q * x_m * x_m * to_one * (1.0 + u) * (1.0 + u * u);
    let loading_v2 = |u: f64, to_one: f64| elastic_drop(u, to_one) + friction_drop(u, to_one);
    let unloading_v2 = |u: f64, to_one: f64| elastic_drop(u, to_one) - friction_drop(u, to_one);

    let u_star = (x_star / x_m).sqrt();
    let v_out = unloading_v2(u_star, 1.0 - u_star).max(0.0).sqrt();
    // ∫dX/V with X = X_m·u²: 1/V ~ (1 − u)^{−1/2} at maximum compression (u = 1) is absorbed by
    // the Gauss–Jacobi weight, and V²'s X^{n+1} at first contact becomes u^{2n+2} (a polynomial
    // for spheres), which Gauss rules integrate without the algebraic slowdown of X^{n+1} itself.
    let time = |v2: &dyn Fn(f64, f64) -> f64, u_lo: f64| {
        singular_at_end(
            |u, _, to_one| 2.0 * x_m * u / v2(u, to_one).sqrt(),
            u_lo,
            1.0,
            -0.5,
            size,
        )
    };
    let loading = time(&loading_v2, 0.0);
    let unloading = time(&unloading_v2, u_star);
    let x_max = x_e * x_m;
    let t_x_max = t_ref * loading;

    let exact = ExactImpact {
        x_max,
        t_x_max,
        // The force rises with x on loading and drops by 2P·x_max at the switch: the peak is the end
        // of loading.
        f_max: law.force(x_max) + p * x_max,
        t_f_max: t_x_max,
        x_f_max: x_max,
        v_f_max: 0.0,
        t_contact: t_x_max + t_ref * unloading,
        v_out: v0 * v_out,
        x_residual: x_e * x_star,
        tensile_cutoff: x_star > 0.0,
    };
    exact.is_valid().then_some(exact)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::power_law::PowerLaw;

    fn fig4() -> ImpactParams {
        ImpactParams {
            mass: 0.033,
            law: PowerLaw {
                k: 1.465e10,
                n: 1.5,
            },
            v0: 0.03,
            restitution: 0.9,
            plastic_indentation: 0.0,
            contact: crate::model::force::Contact::Unspecified,
        }
    }

    fn rel(a: f64, b: f64) -> f64 {
        (a / b - 1.0).abs()
    }

    #[test]
    fn node_count_meets_the_tolerance() {
        // Against 64 nodes, over n (sphere and cylinder-like) and restitution, with and without
        // the tensile cutoff.
        for n in [1.5, 1.2, 1.05] {
            for e in [0.3, 0.9, 0.99] {
                let mut params = fig4();
                params.law.n = n;
                params.restitution = e;
                let x_e = params.law.max_approach(params.mass, params.v0);
                let p = 0.5 * params.mass * params.v0 * params.v0 * (1.0 - e * e) / (x_e * x_e);
                for x_cut in [0.0, (p / params.law.k).powf(1.0 / (n - 1.0)).min(0.5 * x_e)] {
                    let r = with_nodes(&params, p, x_cut, 64).unwrap();
                    for rtol in [1e-3, 1e-6, 1e-9, 1e-12] {
                        let g = dry_friction(&params, p, x_cut, rtol).unwrap();
                        let err = rel(g.t_contact, r.t_contact).max(rel(g.t_x_max, r.t_x_max));
                        assert!(
                            err <= rtol,
                            "n {n} e {e} cut {x_cut:e} rtol {rtol:e}: {err:e}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn fig4_against_40_digit_reference() {
        // mpmath at 40 digits: P from eq 16 with the elastic x_max, x_max root of the loading energy
        // equation, x* = (P/k)², v_out from the unloading identity at x*, times by adaptive quadrature.
        let params = fig4();
        let x_e = params.law.max_approach(params.mass, params.v0);
        let p = 0.5 * params.mass * params.v0 * params.v0 * (1.0 - 0.81) / (x_e * x_e);
        assert!(rel(p, 1_340_963.585_370_805) < 1e-14);
        let x_cut = (p / params.law.k).powi(2);
        let ex = dry_friction(&params, p, x_cut, 1e-14).unwrap();
        assert!(
            rel(ex.x_max, 1.397_928_938_372_607_5e-6) < 1e-14,
            "{}",
            ex.x_max
        );
        assert!(rel(ex.x_residual, 8.378_354_260_576_239e-9) < 1e-13);
        assert!(
            rel(ex.v_out, 0.027_224_644_856_800_613) < 1e-13,
            "{}",
            ex.v_out
        );
        assert!(rel(ex.f_max, 26.088_500_965_174_086) < 1e-14);
        assert!(
            rel(ex.t_x_max, 6.893_696_307_590_915e-5) < 1e-12,
            "{}",
            ex.t_x_max
        );
        assert!(
            rel(ex.t_contact, 1.437_212_206_712_726e-4) < 1e-12,
            "{}",
            ex.t_contact
        );
        assert!(ex.tensile_cutoff);
    }

    #[test]
    fn without_cutoff_eq_16_holds_exactly() {
        // Carried on to x = 0 the identity is eq 16: e_out² = 1 − 2P·x_max²/(m·v₀²).
        let params = fig4();
        let p = 1.0e6;
        let ex = dry_friction(&params, p, 0.0, 1e-12).unwrap();
        let e2 = 1.0 - 2.0 * p * ex.x_max * ex.x_max / (params.mass * params.v0 * params.v0);
        assert!(rel((ex.v_out / params.v0).powi(2), e2) < 1e-14);
        assert!(!ex.tensile_cutoff);
        assert_eq!(ex.x_residual, 0.0);
    }

    #[test]
    fn linear_spring_with_friction_has_closed_form_times() {
        // n = 1: loading is a harmonic arc of ω₁ = √((k+P)/m), unloading of ω₂ = √((k−P)/m):
        // t_x = (π/2)/ω₁, t_c = t_x + (π/2)/ω₂, and x_max = v₀/ω₁.
        let params = ImpactParams {
            mass: 2.0,
            law: PowerLaw { k: 8e6, n: 1.0 },
            v0: 0.5,
            restitution: 0.8,
            plastic_indentation: 0.0,
            contact: crate::model::force::Contact::Unspecified,
        };
        let p = 2e6;
        let ex = dry_friction(&params, p, 0.0, 1e-14).unwrap();
        let w1 = (10e6f64 / 2.0).sqrt();
        let w2 = (6e6f64 / 2.0).sqrt();
        let half_pi = std::f64::consts::FRAC_PI_2;
        assert!(rel(ex.x_max, 0.5 / w1) < 1e-14);
        assert!(rel(ex.t_x_max, half_pi / w1) < 1e-13, "{}", ex.t_x_max);
        assert!(rel(ex.t_contact, half_pi / w1 + half_pi / w2) < 1e-13);
        assert!(rel(ex.v_out, 0.5 / w1 * w2) < 1e-14);
    }
}
