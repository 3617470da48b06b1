//! The Hunt–Crossley family F = k·xⁿ·(1 + α·ẋ) (eqs 19–20) through its separable energy integral
//! (docs/physics.md §3).
//!
//! Scaled variables: X = x/x_e, V = v/v₀ with x_e the elastic x_max, a = α·v₀, G(y) = y − ln(1 + y).
//! Then m·v·dv/(1 + αv) = −k·xⁿ dx integrates to G(a·V) = C − (a²/2)·X^{n+1}, C = G(a), and
//! m·ẍ = −F becomes dV/dT = −((n+1)/2)·Xⁿ(1 + aV) with T = t·v₀/x_e.
//!
//! **The compressive-only rule never fires here.** u = 1 + αv obeys du/dt = −(αk/m)·xⁿ·u, so u
//! decays but cannot cross zero while x > 0: the line 1 + αv = 0 is invariant and an exact trajectory
//! starting at u = 1 + a > 0 exits at x = 0 with α·v_out = 1 + W₀(−e^{−(1+C)}) < 1. Only an
//! integrator's error can carry the state across it (the solver then ends contact there and says so).

use crate::model::force::ImpactParams;

use super::gauss_jacobi::{nodes_for_gap, singular_at_end, singular_at_start};
use super::quadrature::tanh_sinh;
use super::special::{unloading_root, y_minus_log1p};
use super::{ExactImpact, elastic::elastic};

/// Below this exit value of w = 1 + αẋ the unloading time is integrated in x rather than in V:
/// the force has then decayed by the factor w before the bodies reach x = 0, and they coast the
/// rest of the way at an almost constant speed, all of which dt = m·dv/F crowds into the last
/// ulps of V. The Hunt–Crossley and Lankarani–Nikravesh laws of the paper keep w > 0.3.
const STRONG_DAMPING: f64 = 0.1;

/// The scaled energy integral of one Hunt–Crossley-family impact.
#[derive(Debug, Clone, Copy)]
struct Integral {
    n: f64,
    /// a = α·v₀.
    a: f64,
    /// C = G(a).
    c: f64,
    /// s = a·V_out, the unloading root of G(−s) = C.
    s: f64,
    /// w = 1 − s = 1 + a·V at the exit, kept separately: it is tiny for strong damping.
    w: f64,
    /// 2/a², so that X^{n+1} = (2/a²)·D.
    scale: f64,
    /// −n/(n+1), the exponent of X^{n+1} in 1/Xⁿ.
    exponent: f64,
}

impl Integral {
    /// D(V) = C − G(aV) on loading, V ∈ [0, 1], from δ = 1 − V without cancellation:
    /// with z = aδ/(1 + aV), D = G(z) + aV·z (both terms ≥ 0).
    fn d_loading(&self, v: f64, delta: f64) -> f64 {
        let z = self.a * delta / (1.0 + self.a * v);
        y_minus_log1p(z) + self.a * v * z
    }

    /// (D(V), 1 + aV) on unloading, V ∈ [−V_out, 0], δ = V + V_out. Near the exit (δ ≤ V_out/2),
    /// with z = aδ/w: D = s·z − G(z) = ln(1 + z) − w·z (the first form for s < ½, the second for
    /// s ≥ ½, whichever does not cancel) and 1 + aV = w + aδ, so both keep their relative accuracy
    /// as δ → 0 even when w is tiny. Elsewhere D = C − G(aV) directly (G(aV) ≤ G(−s/2) stays well
    /// below C there).
    fn d_unloading(&self, v: f64, delta: f64) -> (f64, f64) {
        let v_out = self.s / self.a;
        if delta <= 0.5 * v_out {
            let z = self.a * delta / self.w;
            let d = if self.s < 0.5 {
                self.s * z - y_minus_log1p(z)
            } else {
                z.ln_1p() - self.w * z
            };
            (d, self.w + self.a * delta)
        } else {
            (self.c - y_minus_log1p(self.a * v), 1.0 + self.a * v)
        }
    }

    /// The unloading time ∫ dX/|V| from X = 0 to X_m, with V(X) the unloading root of
    /// G(aV) = (a²/2)·(X_m^{n+1} − X^{n+1}) (the difference formed from d = X_m − X without
    /// cancellation). Regular at X = 0 and an inverse square root at X_m: tanh-sinh handles both.
    fn unloading_time_in_x(&self, rtol: f64) -> f64 {
        let p = self.n + 1.0;
        let x_m = (2.0 * self.c / (self.a * self.a)).powf(1.0 / p);
        let half_a2 = 0.5 * self.a * self.a;
        tanh_sinh(
            |_, _, d| {
                let drop = -x_m.powf(p) * (p * (-d / x_m).ln_1p()).exp_m1();
                let (s, _) = unloading_root(half_a2 * drop);
                self.a / s
            },
            0.0,
            x_m,
            rtol,
        )
    }

    /// |dT/dV| = 2/((n+1)·f), f = F/(k·x_eⁿ) = Xⁿ·(1 + aV) the scaled force (eqs 19–20): the
    /// integrand of the contact time in V. Its power 1/Xⁿ is taken as
    /// exp(−(n/(n+1))·ln X^{n+1}): a logarithm and an exponential cost half a `powf`, the dearest
    /// step of a quadrature node, and lose no digit that matters (the exponent's rounding,
    /// ≤ 1e-15 of a logarithm below 40, is the result's relative error).
    fn dt_dv(&self, d: f64, u: f64) -> f64 {
        2.0 / (self.n + 1.0) * (self.exponent * (self.scale * d).ln()).exp() / u
    }

    /// The loading velocity V* of the force peak, the root of h(V) = (n+1)·D(V) − n·a·V. h falls
    /// from (n+1)·C at V = 0 to −n·a at V = 1 and is concave (D'' = −a²/(1 + aV)²), so Newton
    /// started right of the root stays right of it and descends monotonically onto it. The start,
    /// min(1, (n+1)·C/(n·a)), is Newton's step from V = 0, which a concave h sends past the root.
    fn peak_velocity(&self) -> Option<f64> {
        let (n, a) = (self.n, self.a);
        let h = |v: f64| (n + 1.0) * self.d_loading(v, 1.0 - v) - n * a * v;
        let mut v = ((n + 1.0) * self.c / (n * a)).min(1.0);
        for _ in 0..100 {
            let slope = -(n + 1.0) * a * a * v / (1.0 + a * v) - n * a;
            let step = -h(v) / slope;
            // Rounding ends the descent: a step that would climb, or one below the last ulps.
            if step >= 0.0 || -step <= 4.0 * f64::EPSILON * v {
                break;
            }
            v += step;
        }
        (v.is_finite() && (0.0..=1.0).contains(&v)).then_some(v)
    }
}

/// The exact impact of F = k·xⁿ(1 + α·ẋ) (eqs 19–20): x_max and v_out in closed form (docs/physics.md
/// §3), the force peak at the root of (n+1)·D(V) = n·a·V, times by Gauss–Jacobi quadrature of
/// dt = m·dv/F to `rtol` (tanh-sinh in x when the damping nearly stops the bodies). α = 0 is the
/// elastic impact. `None` if a number comes out non-finite.
pub fn hysteresis(params: &ImpactParams, alpha: f64, rtol: f64) -> Option<ExactImpact> {
    hysteresis_with(
        params,
        alpha,
        rtol,
        alpha * params.v0 <= GAUSS_JACOBI_MAX_DAMPING,
    )
}

/// Above this a = α·v₀ the times go to tanh-sinh: 1 + aV vanishes at V = −1/a, so close to the
/// loading interval [0, 1] that a Gauss rule's geometric convergence slows (ρ² < 10 beyond
/// a ≈ 5). The paper's laws have a ≤ 1.5 (Hunt–Crossley) and ≤ 0.75 (Lankarani–Nikravesh).
const GAUSS_JACOBI_MAX_DAMPING: f64 = 4.0;

/// [`hysteresis`] by Gauss–Jacobi rules when `gauss`, else by tanh-sinh. Each rule gets the nodes
/// its integrand needs for `rtol` ([`nodes_for_gap`]): its smooth part is analytic up to the
/// nearest of V = 1 (first contact), V = −V_out (the exit, where D = 0) and V = −1/a (where
/// 1 + aV = 0), less those the rule's weight absorbs.
pub(crate) fn hysteresis_with(
    params: &ImpactParams,
    alpha: f64,
    rtol: f64,
    gauss: bool,
) -> Option<ExactImpact> {
    let a = alpha * params.v0;
    if a <= 0.0 {
        return Some(elastic(params));
    }
    let (m, v0, law) = (params.mass, params.v0, params.law);
    let n = law.n;
    let x_e = law.max_approach(m, v0);
    let t_ref = x_e / v0;
    // k·x_eⁿ from the elastic energy balance k·x_e^{n+1}/(n+1) = m·v₀²/2 (eq 5), without a power.
    let f_ref = 0.5 * (n + 1.0) * m * v0 * v0 / x_e;
    let c = y_minus_log1p(a);
    let (s, w) = unloading_root(c);
    let hc = Integral {
        n,
        a,
        c,
        s,
        w,
        scale: 2.0 / (a * a),
        exponent: -n / (n + 1.0),
    };
    let v_out = s / a;

    // Peak force: dF/dV = 0 ⇔ h(V) = (n+1)·D(V) − n·a·V = 0, a unique root on loading.
    let v_peak = hc.peak_velocity()?;
    let d_peak = hc.d_loading(v_peak, 1.0 - v_peak);
    // X at the peak; Xⁿ = X^{n+1}/X.
    let x_peak = (hc.scale * d_peak).powf(1.0 / (n + 1.0));

    // Times, in T: [V*, 1] (start to peak), [0, V*] (peak to x_max), [−V_out, 0] (unloading).
    // dt/dV ~ δ^{−n/(n+1)} at first contact and at the exit, smooth elsewhere.
    let singular = -n / (n + 1.0);
    let loading_rate = |v: f64, top: f64| hc.dt_dv(hc.d_loading(v, top), 1.0 + a * v);
    let unloading_rate = |v: f64, from_exit: f64| {
        let (d, u) = hc.d_unloading(v, from_exit);
        hc.dt_dv(d, u)
    };
    let (to_peak, peak_to_x_max) = if gauss {
        (
            singular_at_end(
                |v, _, top| loading_rate(v, top),
                v_peak,
                1.0,
                singular,
                nodes_for_gap(rtol, v_peak + v_out, 1.0 - v_peak),
            ),
            singular_at_end(
                |v, _, _| loading_rate(v, 1.0 - v),
                0.0,
                v_peak,
                0.0,
                nodes_for_gap(rtol, (1.0 - v_peak).min(v_out), v_peak),
            ),
        )
    } else {
        (
            tanh_sinh(|v, _, top| loading_rate(v, top), v_peak, 1.0, rtol),
            tanh_sinh(|v, _, _| loading_rate(v, 1.0 - v), 0.0, v_peak, rtol),
        )
    };
    let unloading = if w < STRONG_DAMPING {
        hc.unloading_time_in_x(rtol)
    } else if gauss {
        singular_at_start(
            |v, from_exit, _| unloading_rate(v, from_exit),
            -v_out,
            0.0,
            singular,
            nodes_for_gap(rtol, (w / a).min(1.0), v_out),
        )
    } else {
        tanh_sinh(
            |v, from_exit, _| unloading_rate(v, from_exit),
            -v_out,
            0.0,
            rtol,
        )
    };

    let exact = ExactImpact {
        x_max: x_e * (2.0 * c / (a * a)).powf(1.0 / (n + 1.0)),
        t_x_max: t_ref * (to_peak + peak_to_x_max),
        f_max: f_ref * (hc.scale * d_peak / x_peak) * (1.0 + a * v_peak),
        t_f_max: t_ref * to_peak,
        x_f_max: x_e * x_peak,
        v_f_max: v0 * v_peak,
        t_contact: t_ref * (to_peak + peak_to_x_max + unloading),
        v_out: v0 * v_out,
        x_residual: 0.0,
        tensile_cutoff: false,
    };
    exact.is_valid().then_some(exact)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::power_law::PowerLaw;

    fn fig5(mass: f64) -> ImpactParams {
        ImpactParams {
            mass,
            law: PowerLaw {
                k: 1.465e10,
                n: 1.5,
            },
            v0: 0.3,
            restitution: 0.6,
            plastic_indentation: 2.3e-6,
            contact: crate::model::force::Contact::Unspecified,
        }
    }

    fn rel(a: f64, b: f64) -> f64 {
        (a / b - 1.0).abs()
    }

    #[test]
    fn node_count_meets_the_tolerance() {
        // Gauss–Jacobi with the nodes nodes_for_gap gives against tanh-sinh at 1e-15 (itself checked
        // against mpmath above), over damping from e = 0.02 to 0.999 and n from 1 to 3/2.
        // Measured: ≥ 1.1 digits per node (the slowest, e = 0.1: 8e-10 at 8 nodes, 4e-14 at 12).
        for &(n, e) in &[
            (1.5, 0.6),
            (1.5, 0.02),
            (1.5, 0.1),
            (1.5, 0.95),
            (1.1, 0.3),
            (1.0, 0.5),
            (1.45, 0.999),
        ] {
            let p = ImpactParams {
                law: PowerLaw { k: 1.465e10, n },
                restitution: e,
                ..fig5(0.033)
            };
            // a = 1.5·(1 − e), and a = 4, the largest damping given to Gauss–Jacobi.
            for a in [1.5 * (1.0 - e), GAUSS_JACOBI_MAX_DAMPING] {
                let alpha = a / p.v0;
                let r = hysteresis_with(&p, alpha, 1e-15, false).unwrap();
                for rtol in [1e-3, 1e-6, 1e-9, 1e-12, 1e-15] {
                    let g = hysteresis(&p, alpha, rtol).unwrap();
                    let err = rel(g.t_contact, r.t_contact)
                        .max(rel(g.t_f_max, r.t_f_max))
                        .max(rel(g.t_x_max, r.t_x_max));
                    assert!(err <= rtol.max(2e-15), "n {n} a {a} rtol {rtol:e}: {err:e}");
                }
            }
        }
    }

    #[test]
    fn hunt_crossley_fig5_against_40_digit_reference() {
        // mpmath at 40 digits: x_max by eq (docs/physics.md §3), v_out by Lambert W, times and peak by
        // adaptive quadrature / root finding of the same integrals.
        let p = fig5(0.033);
        let alpha = 1.5 * (1.0 - 0.6) / 0.3;
        let ex = hysteresis(&p, alpha, 1e-14).unwrap();
        assert!(
            rel(ex.x_max, 8.035_169_159_662_6e-6) < 1e-14,
            "{}",
            ex.x_max
        );
        assert!(
            rel(ex.v_out, 0.213_585_053_873_359_86) < 1e-14,
            "{}",
            ex.v_out
        );
        assert!(
            rel(ex.f_max, 366.898_766_799_700_87) < 1e-13,
            "{}",
            ex.f_max
        );
        assert!(rel(ex.t_f_max, 3.271_923_371_073_43e-5) < 1e-12);
        assert!(rel(ex.t_x_max, 4.154_061_059_738_278e-5) < 1e-12);
        assert!(
            rel(ex.t_contact, 9.388_273_932_839_247e-5) < 1e-12,
            "{}",
            ex.t_contact
        );
    }

    #[test]
    fn lankarani_nikravesh_fig5_against_40_digit_reference() {
        let p = fig5(0.033);
        let alpha = 3.0 * (1.0 - 0.36) / (4.0 * 0.3);
        let ex = hysteresis(&p, alpha, 1e-14).unwrap();
        assert!(rel(ex.x_max, 8.216_001_471_350_663e-6) < 1e-14);
        assert!(rel(ex.v_out, 0.226_844_604_197_834_3) < 1e-14);
        assert!(rel(ex.f_max, 368.793_189_135_817_8) < 1e-13);
        assert!(rel(ex.t_contact, 9.300_112_290_198_327e-5) < 1e-12);
    }

    #[test]
    fn hunt_crossley_restitution_to_1e12_for_every_e() {
        // e_out = (1 + W₀(−e^{−(1+C)}))/a, a = (3/2)(1 − e), from mpmath at 90 digits with the
        // doubles' e; near e = 1 the branch point would cost the Lambert-W form half its digits.
        let p = fig5(0.033);
        for &(e, e_out) in &[
            (0.05, 0.501_447_028_551_835_2),
            (0.3, 0.581_288_041_808_573_7),
            (0.9, 0.909_015_741_349_202_3),
            (0.99, 0.990_098_912_841_307_9),
            (0.999_999, 0.999_999_000_001_000),
            (0.999_999_999_999, 0.999_999_999_999_000_1),
        ] {
            let params = ImpactParams {
                restitution: e,
                ..p
            };
            let alpha = 1.5 * (1.0 - e) / p.v0;
            let ex = hysteresis(&params, alpha, 1e-12).unwrap();
            assert!(
                rel(ex.v_out / p.v0, e_out) < 1e-12,
                "e = {e}: {}",
                ex.v_out / p.v0
            );
        }
    }

    #[test]
    fn vanishing_damping_tends_to_elastic() {
        // a = 1.5e-12: every number within ~a of the elastic one, and e_out = 1 − 2a/3.
        let p = fig5(0.033);
        let alpha = 1.5e-12 / p.v0;
        let ex = hysteresis(&p, alpha, 1e-14).unwrap();
        let el = elastic(&p);
        assert!(rel(ex.x_max, el.x_max) < 1e-11);
        assert!(rel(ex.f_max, el.f_max) < 1e-11);
        assert!(rel(ex.t_contact, el.t_contact) < 1e-11);
        assert!(rel(ex.v_out / p.v0, 1.0 - 1e-12) < 1e-15);
    }

    #[test]
    fn exit_stays_below_the_invariant_line_for_strong_damping() {
        // Even a = 20 (far beyond HC's 1.5): α·v_out < 1, so F never turns tensile; reference
        // values from mpmath (Lambert W; quadrature split at 1e-30…1e-5 of V_out from the exit,
        // where 1 + αv falls to w = 1.6e-8).
        let p = fig5(0.033);
        for &(a, v_out, t_c) in &[
            (5.0, 0.059_094_073_584_155_67, 1.338_733_437_020_365e-4),
            (20.0, 0.014_999_999_761_149_343, 2.576_715_520_594_233e-4),
        ] {
            let ex = hysteresis(&p, a / p.v0, 1e-14).unwrap();
            assert!(rel(ex.v_out, v_out) < 1e-14, "{a}: {}", ex.v_out);
            assert!(rel(ex.t_contact, t_c) < 1e-9, "{a}: {}", ex.t_contact);
            assert!(a * ex.v_out / p.v0 < 1.0);
            assert!(!ex.tensile_cutoff);
        }
    }
}
