//! The numbers of an integrated impact, read off the dense output: the true force peak (a root of
//! dF/dt, not a sample near it) and the work ∮F dx (Gauss–Legendre on every step's interpolant).

use crate::model::exact::quadrature::gauss_legendre_6;
use crate::model::exact::roots::brent;
use crate::model::force::{ContactEnd, ForceLaw, Phase};
use crate::model::ode::{DenseOutput, Segment, State};

use super::phases::{End, Run};
use super::scale::Scales;
use super::{ImpactSummary, MethodUsed, TensileCutoff};

/// The force peak (T, F) of one phase over [t_lo, t_hi] of its dense output.
fn phase_peak<L: ForceLaw>(
    law: &L,
    sc: &Scales,
    dense: &DenseOutput,
    phase: Phase,
    t_lo: f64,
    t_hi: f64,
) -> (f64, f64) {
    let force = |y: State| law.phase_force(y[0] * sc.x, y[1] * sc.v, phase);
    // dF/dt along the flow = ∂F/∂x·ẋ + ∂F/∂ẋ·ẍ with ẍ = −F/m; only its sign matters here.
    let rate = |y: State| {
        let (x, v) = (y[0] * sc.x, y[1] * sc.v);
        let (fx, fv) = law.partials(x, v, phase);
        fx * v - fv * law.phase_force(x, v, phase) / sc.mass
    };
    let mut best = (t_lo, force(dense.eval(t_lo)));
    let end = (t_hi, force(dense.eval(t_hi)));
    if end.1 > best.1 {
        best = end;
    }
    for seg in dense.segments() {
        let (ta, tb) = (seg.t_start().max(t_lo), seg.t_end().min(t_hi));
        if tb <= ta {
            continue;
        }
        let tm = 0.5 * (ta + tb);
        let (ra, rm, rb) = (rate(seg.eval(ta)), rate(seg.eval(tm)), rate(seg.eval(tb)));
        // A maximum is where the rate falls through zero; the midpoint catches a peak between two
        // rising ends only if the rate dips twice, which smooth forces do not do within one step.
        let bracket = if ra > 0.0 && rm <= 0.0 {
            Some((ta, tm))
        } else if rm > 0.0 && rb <= 0.0 {
            Some((tm, tb))
        } else {
            None
        };
        if let Some((a, b)) = bracket
            && let Some(t) = brent(|t| rate(seg.eval(t)), a, b)
        {
            let f = force(seg.eval(t));
            if f > best.1 {
                best = (t, f);
            }
        }
    }
    best
}

/// ∫ F_d·ẋ dt over [t_lo, t_hi] of one phase, in units of F_ref·x_e (F_d the dissipative force).
/// Each step's interpolant gets six-point Gauss–Legendre; the first step of loading (first
/// contact) and the last of unloading (separation) get it after the substitution T = T₀ + h·u²(3 − 2u), which turns the xⁿ ∝ (T − T₀)ⁿ behaviour
/// at first contact and at separation into a smooth integrand.
fn phase_work<L: ForceLaw>(
    law: &L,
    sc: &Scales,
    dense: &DenseOutput,
    phase: Phase,
    (t_lo, t_hi): (f64, f64),
) -> f64 {
    let power = |seg: &Segment, t: f64| {
        let y = seg.eval(t);
        law.dissipative_force(y[0] * sc.x, y[1] * sc.v, phase) / sc.f * y[1]
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
        let graded = match phase {
            Phase::Loading => i == 0,
            Phase::Unloading => i == last,
        };
        work += if graded {
            gauss_legendre_6(
                |u| power(seg, ta + h * u * u * (3.0 - 2.0 * u)) * 6.0 * h * u * (1.0 - u),
                0.0,
                1.0,
            )
        } else {
            gauss_legendre_6(|t| power(seg, t), ta, tb)
        };
    }
    work
}

/// ∮F dx over the contact of `run`, in units of ½mv₀²: k·x_end^{n+1}/(n+1) (the elastic part,
/// exact) plus ∮F_d dx by quadrature on the dense output (F_ref·x_e = (n+1)/2·mv₀²).
pub(crate) fn cycle_work<L: ForceLaw>(law: &L, sc: &Scales, run: &Run) -> f64 {
    let dissipative = phase_work(law, sc, &run.loading, Phase::Loading, (0.0, run.t_switch))
        + phase_work(
            law,
            sc,
            &run.unloading,
            Phase::Unloading,
            (run.t_switch, run.t_end),
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
        sc,
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
    let tensile_cutoff = (run.end == End::Tension && law.contact_end() == ContactEnd::ApproachZero)
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
