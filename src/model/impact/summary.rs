//! The numbers of an integrated impact, read off the dense output: the true force peak (a root of
//! dF/dt, not a sample near it) and the work ∮F dx (Gauss–Legendre on every step's interpolant).

use crate::model::exact::quadrature::{gauss_legendre_4, gauss_legendre_6};
use crate::model::force::{ContactEnd, ForceLaw, Phase};
use crate::model::numeric::roots::brent_max;
use crate::model::ode::{DenseOutput, Segment, State};

use super::phases::{End, Run};
use super::scale::Scales;
use super::{ImpactSummary, MethodUsed, TensileCutoff};

/// The force peak (T, F) of one phase over [t_lo, t_hi] of its dense output.
///
/// F is first compared at the step points (stored states, no interpolation); the peak — where
/// dF/dt along the dense output vanishes — lies in one of the two steps next to the largest of
/// them, and F is maximised on each of their interpolants (Brent's fmin). The peak is thus the
/// dense output's own, what any chart of it shows, at every tolerance. Phase ends count as
/// candidates too (dry friction peaks at the end of loading, where its force jumps).
fn phase_peak<L: ForceLaw>(
    law: &L,
    sc: &Scales,
    dense: &DenseOutput,
    phase: Phase,
    t_lo: f64,
    t_hi: f64,
) -> (f64, f64) {
    let force = |y: State| law.phase_force(y[0] * sc.x, sc.velocity(&y) * sc.v, phase);
    let segments = dense.segments();
    let mut best = (t_lo, force(dense.eval(t_lo)));
    let end = (t_hi, force(dense.eval(t_hi)));
    if end.1 > best.1 {
        best = end;
    }
    // The interior step point with the largest force.
    let mut top: Option<(usize, f64)> = None;
    for (i, seg) in segments.iter().enumerate() {
        if seg.t_end() < t_hi && seg.t_end() > t_lo {
            let f = force(seg.y_end());
            if top.is_none_or(|(_, g)| f > g) {
                top = Some((i, f));
            }
        }
    }
    let near = match top {
        Some((i, _)) => i..(i + 2).min(segments.len()),
        None => 0..segments.len(),
    };
    for seg in &segments[near] {
        let (ta, tb) = (seg.t_start().max(t_lo), seg.t_end().min(t_hi));
        if tb > ta {
            let peak = segment_peak(|t| force(seg.eval(t)), ta, tb);
            if peak.1 > best.1 {
                best = peak;
            }
        }
    }
    best
}

/// Sub-intervals a step is sampled in before its peak is refined.
const PEAK_SAMPLES: usize = 8;

/// The maximum of `f` on one step [ta, tb]: f is sampled at [`PEAK_SAMPLES`] + 1 points and
/// maximised (Brent's fmin) between the neighbours of the largest. An interpolant need not be
/// unimodal over a whole step (a symplectic Euler step at loose resolution rises, dips and rises
/// again), and an end peak found by a unimodality test would then hide a higher interior one.
fn segment_peak(mut f: impl FnMut(f64) -> f64, ta: f64, tb: f64) -> (f64, f64) {
    let at = |k: usize| ta + (tb - ta) * (k as f64 / PEAK_SAMPLES as f64);
    let (mut k_best, mut f_best) = (0, f(ta));
    for k in 1..=PEAK_SAMPLES {
        let value = f(at(k));
        if value > f_best {
            (k_best, f_best) = (k, value);
        }
    }
    let lo = at(k_best.saturating_sub(1));
    let hi = at((k_best + 1).min(PEAK_SAMPLES));
    let peak = brent_max(&mut f, lo, hi);
    if peak.1 >= f_best {
        peak
    } else {
        (at(k_best), f_best)
    }
}

/// The longest stretch of scaled time (the contact lasts about 3) one four-point Gauss rule
/// integrates at tolerance `rtol`: its error on a power oscillating at twice the contact's
/// frequency is about (2·piece)⁸/4·10⁴, held under rtol (0.16 at 1e-8, one piece a DOP853 step;
/// 0.05 at 1e-12).
fn max_piece(rtol: f64) -> f64 {
    (0.5 * (4e4 * rtol).powf(0.125)).clamp(0.02, 1.0)
}

/// ∫ F_d·ẋ dt over [t_lo, t_hi] of one phase, in units of F_ref·x_e (F_d the dissipative force).
/// Each step's interpolant gets four-point Gauss–Legendre, over pieces of at most
/// [`max_piece`] (a DOP853 step can span a tenth of the contact). Loading steps are integrated
/// in s = √(T − T₀), which turns the xⁿ⁻¹ ∝ (T − T₀)ⁿ⁻¹ behaviour of first contact into a smooth integrand on every step,
/// not only the first (the proposed model's damping is ∝ √x there, and steps a few lengths from
/// first contact still feel it); the first step gets six points. The last step of unloading
/// (separation) gets six points after the substitution T = T₀ + h·u²(3 − 2u). A phase integrated
/// in (X, W) ([`Scales::shift`]) integrates the damping's work by parts.
fn phase_work<L: ForceLaw>(
    law: &L,
    sc: &Scales,
    dense: &DenseOutput,
    phase: Phase,
    (t_lo, t_hi): (f64, f64),
    rtol: f64,
) -> f64 {
    let power = |seg: &Segment, t: f64| {
        let y = sc.xv(&seg.eval(t));
        if sc.shift == 0.0 {
            law.dissipative_force(y[0] * sc.x, y[1] * sc.v, phase) / sc.f * y[1]
        } else {
            // F_d = d(β·xᵖ)/dt, so ∫F_d·ẋ dt = [β·xᵖ·ẋ] + ∫β·xᵖ·F/m dt, and the bracket vanishes
            // over loading (x = 0 at its start, ẋ = 0 at its end) and over an unloading kept in W
            // (ẋ = 0 at its start, x = 0 at its end): γ·Xᵖ·F/F_ref has no xᵖ⁻¹ singularity at
            // first or last contact for the quadrature to miss.
            sc.shift * sc.shift_pow(y[0]) * law.phase_force(y[0] * sc.x, y[1] * sc.v, phase) / sc.f
        }
    };
    let segments = dense.segments();
    let last = segments.len().saturating_sub(1);
    let mut work = 0.0;
    for (i, seg) in segments.iter().enumerate() {
        let (ta, tb) = (seg.t_start().max(t_lo), seg.t_end().min(t_hi));
        if tb <= ta {
            continue;
        }
        let h = tb - ta;
        // A long step (DOP853 covers a contact in ~10) is cut into pieces of at most
        // max_piece(rtol): the power oscillates at twice the contact's frequency, and four points
        // over a whole step left the work 2e-7 off on a linear oscillator whose solution was
        // right to 1e-12.
        let count = (h / max_piece(rtol)).ceil().clamp(1.0, 64.0) as usize;
        let piece = h / count as f64;
        let bounds = (0..count).map(|j| (ta + j as f64 * piece, ta + (j + 1) as f64 * piece));
        if phase == Phase::Loading {
            let integrand = |s: f64| power(seg, t_lo + s * s) * 2.0 * s;
            for (pa, pb) in bounds {
                let (sa, sb) = ((pa - t_lo).max(0.0).sqrt(), (pb - t_lo).max(0.0).sqrt());
                work += if i == 0 {
                    gauss_legendre_6(integrand, sa, sb)
                } else {
                    gauss_legendre_4(integrand, sa, sb)
                };
            }
            continue;
        }
        work += bounds
            .enumerate()
            .map(|(j, (pa, pb))| {
                if i == last && j + 1 == count {
                    // Separation: smooth the end-point behaviour by T = T₀ + h·u²(3 − 2u).
                    let w = pb - pa;
                    gauss_legendre_6(
                        |u| power(seg, pa + w * u * u * (3.0 - 2.0 * u)) * 6.0 * w * u * (1.0 - u),
                        0.0,
                        1.0,
                    )
                } else {
                    gauss_legendre_4(|t| power(seg, t), pa, pb)
                }
            })
            .sum::<f64>();
    }
    work
}

/// ∮F dx over the contact of `run`, in units of ½mv₀²: k·x_end^{n+1}/(n+1) (the elastic part,
/// exact) plus ∮F_d dx by quadrature on the dense output (F_ref·x_e = (n+1)/2·mv₀²).
pub(crate) fn cycle_work<L: ForceLaw>(law: &L, sc: &Scales, run: &Run) -> f64 {
    if law.rate_independent() {
        // Work in, minus what the unloading branch gives back from x_max to the end, exactly.
        let (x_max, x_end) = (run.y_switch[0] * sc.x, run.y_end[0] * sc.x);
        let given_back =
            law.stored_energy(x_max, Phase::Unloading) - law.stored_energy(x_end, Phase::Unloading);
        let work = law.stored_energy(x_max, Phase::Loading) - given_back;
        return work / (0.5 * sc.mass * sc.v * sc.v);
    }
    let dissipative = phase_work(
        law,
        sc,
        &run.loading,
        Phase::Loading,
        (0.0, run.t_switch),
        run.rtol,
    ) + phase_work(
        law,
        &run.unloading_scales,
        &run.unloading,
        Phase::Unloading,
        (run.t_switch, run.t_end),
        run.rtol,
    );
    sc.energy(run.y_end[0], 0.0) + (sc.n + 1.0) * dissipative
}

/// The summary of an integrated impact (SI units); the energy residual compares the lost kinetic
/// energy 1 − V_end² with [`cycle_work`].
pub(crate) fn summarize<L: ForceLaw>(
    law: &L,
    sc: &Scales,
    run: &Run,
    method: MethodUsed,
) -> ImpactSummary {
    let loading_peak = phase_peak(law, sc, &run.loading, Phase::Loading, 0.0, run.t_switch);
    let unloading_peak = phase_peak(
        law,
        &run.unloading_scales,
        &run.unloading,
        Phase::Unloading,
        run.t_switch,
        run.t_end,
    );
    let (t_f, f_max) = if unloading_peak.1 > loading_peak.1 {
        unloading_peak
    } else {
        loading_peak
    };

    let (x_end, v_end) = (run.y_end[0], run.y_end[1]);
    let v_out = (-v_end).max(0.0) * sc.v;
    let x_residual = match run.end {
        End::Approach => 0.0,
        End::Tension => x_end.max(0.0) * sc.x,
    };
    // A cutoff that fires where the approach has already returned to 0 (a creep back along
    // F ≈ 0 that reaches the surface) is the ordinary end of contact.
    let tensile_cutoff = (run.end == End::Tension
        && law.contact_end() == ContactEnd::ApproachZero
        && x_residual > 0.0)
        .then_some(TensileCutoff {
            t: run.t_end * sc.t,
            x: x_residual,
            v: v_end * sc.v,
        });

    let work = cycle_work(law, sc, run);
    let lost = 1.0 - v_end * v_end;
    let e0 = 0.5 * sc.mass * sc.v * sc.v;

    ImpactSummary {
        model: law.model(),
        method,
        x_max: run.y_switch[0] * sc.x,
        t_x_max: run.t_switch * sc.t,
        f_max,
        t_f_max: t_f * sc.t,
        t_contact: run.t_end * sc.t,
        v_out,
        e_out: v_out / sc.v,
        x_residual,
        energy_dissipated: e0 * lost,
        energy_residual: (lost - work).abs(),
        steps: run.stats.steps,
        rejected_steps: run.stats.rejected_steps,
        force_evals: run.force_evals,
        tensile_cutoff,
    }
}
