//! Continuation of the impact oscillator against closed forms (docs/physics.md §8.2–8.5): the
//! Budd–Dux period doubling of ẍ + x = cos ωt with a rigid stop, found by continuation in the gap;
//! the damped oscillator's grazing point and its curve over the forcing frequency on
//! A_g(ω) = d·√((k−ω²)² + (cω)²); det J = r²·e^{−cT} along the branch.

use std::f64::consts::{PI, TAU};

use hertz_tui::model::system::continuation::{
    BranchEnd, ContinuationOptions, SpecialKind, continue_orbit, continue_special,
};
use hertz_tui::model::system::{Contact, OrbitGuess, Param, RunOptions, State, SystemKey};

use crate::systems_common::{guess, oscillator};

/// The one-impact period-n orbit of ẍ + x = cos ωt, stop at σ, restitution r (Budd–Dux form,
/// docs/physics.md §8.2): both roots (φ, V) with V > 0.
fn budd_dux(omega: f64, r: f64, sigma: f64, n: u32) -> Vec<(f64, f64)> {
    let w2 = 1.0 - omega * omega;
    let gamma = omega * (1.0 + r) / (1.0 - r) / (f64::from(n) * PI / omega).tan();
    let amp = gamma.hypot(1.0);
    let beta = gamma.atan2(1.0);
    let c = sigma * w2 / amp;
    if c.abs() > 1.0 {
        return vec![];
    }
    [beta + c.acos(), beta - c.acos()]
        .into_iter()
        .map(|phi| (phi, -2.0 * omega * phi.sin() / (w2 * (1.0 - r))))
        .filter(|&(_, v)| v > 0.0)
        .collect()
}

/// The trace of the impact map's Jacobian at that orbit in closed form (docs/physics.md §8.2).
fn budd_dux_trace(omega: f64, r: f64, sigma: f64, phi: f64, v: f64) -> f64 {
    let w2 = 1.0 - omega * omega;
    let (s, c) = (TAU / omega).sin_cos();
    let p0 = phi.cos() / w2;
    let q = -omega * phi.sin() / w2;
    let h = sigma - p0;
    let a = -r * v - q;
    let dt1_dt0 = -(-q * c + h * s + omega * omega * p0 * s - a * c) / v;
    let dt1_dv0 = r * s / v;
    let v1_t1 = -h - omega * omega * p0;
    dt1_dt0 + (-r * c + v1_t1 * dt1_dv0)
}

const OMEGA: f64 = 2.2;
const R: f64 = 0.8;

#[test]
fn budd_dux_period_doubling_by_continuation_in_the_gap() {
    let branch = |sigma: f64| {
        budd_dux(OMEGA, R, sigma, 1)
            .into_iter()
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap()
    };
    // σ_PD from the closed form alone: tr J = −(1 + r²), by bisection.
    let excess = |sigma: f64| {
        let (phi, v) = branch(sigma);
        budd_dux_trace(OMEGA, R, sigma, phi, v) + 1.0 + R * R
    };
    let grid: Vec<f64> = (1..150).map(|i| f64::from(i) * 0.002).collect();
    let w = grid
        .windows(2)
        .find(|w| excess(w[0]) * excess(w[1]) < 0.0)
        .expect("a closed-form period doubling in σ ∈ (0, 0.3)");
    let (mut lo, mut hi) = (w[0], w[1]);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if excess(lo) * excess(mid) <= 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let sigma_pd = 0.5 * (lo + hi);
    // Continue from a gap a quarter below it.
    let start = 0.75 * sigma_pd;
    let (phi, v) = branch(start);
    let model = oscillator(1.0, 0.0, 1.0, OMEGA, start, None, R);
    let b = continue_orbit(
        &model,
        &Contact::rigid(R),
        Param::System(SystemKey::Gap),
        (start, 1.5 * sigma_pd),
        &guess(1, 1, phi + 1e-3, v * 1.001, 0),
        &ContinuationOptions::default(),
    )
    .unwrap();
    let pd: Vec<_> = b.special(SpecialKind::PeriodDoubling).collect();
    assert!(!pd.is_empty(), "{:?} {:?}", b.specials, b.end);
    let at = pd[0].point.values[0];
    eprintln!(
        "Budd–Dux σ_PD {sigma_pd}: continuation {at} ({:.2e})",
        at - sigma_pd
    );
    assert!((at - sigma_pd).abs() < 1e-8, "{at} vs {sigma_pd}");
    // Undamped, one impact: det J = r² at every point (but a grazing end's, where J is singular).
    for p in b.points.iter().filter(|p| p.min_speed > 1e-6) {
        assert!((p.jacobian_det - R * R).abs() < 1e-9, "{}", p.jacobian_det);
    }
}

/// A_g(ω) = d·√((k − ω²)² + (cω)²) (docs/physics.md §8.3), m = 1.
fn grazing_amplitude(k: f64, c: f64, omega: f64, d: f64) -> f64 {
    d * ((k - omega * omega).powi(2) + (c * omega).powi(2)).sqrt()
}

#[test]
fn damped_grazing_point_and_curve_over_frequency() {
    let (k, c, d) = (1.0, 0.1, 0.1);
    let model = oscillator(k, c, 1.0, OMEGA, d, None, R);
    let attractor = OrbitGuess {
        forcing_cycles: 1,
        impacts: 1,
        start: None,
        attractor: RunOptions {
            transient_impacts: 2000,
            recorded_impacts: 8,
            ..RunOptions::default()
        },
    };
    let key = Param::System(SystemKey::ForcingAmplitude);
    let a_g = grazing_amplitude(k, c, OMEGA, d);
    let options = ContinuationOptions::default();
    let b = continue_orbit(
        &model,
        &Contact::rigid(R),
        key,
        (1.0, 0.2),
        &attractor,
        &options,
    )
    .unwrap();
    assert_eq!(b.end, BranchEnd::Grazing, "{:?}", b.specials);
    let graze = b.special(SpecialKind::GrazingImpact).next().unwrap();
    let at = graze.point.values[0];
    eprintln!("grazing A_g {a_g}: continuation {at} ({:.2e})", at - a_g);
    assert!((at - a_g).abs() < 1e-8 * a_g, "{at} vs {a_g}");
    // Liouville (docs/physics.md §8.5): det J = r²·e^{−c·T} with m = 1.
    let period = TAU / OMEGA;
    for p in b.points.iter().filter(|p| p.min_speed > 1e-3) {
        let expected = R * R * (-c * period).exp();
        assert!(
            (p.jacobian_det - expected).abs() < 1e-8,
            "{} vs {expected}",
            p.jacobian_det
        );
    }
    // The grazing curve in (A, f): every point on A_g(ω).
    let f = OMEGA / TAU;
    let curve = continue_special(
        &model,
        &Contact::rigid(R),
        key,
        Param::System(SystemKey::Frequency),
        (0.8 * f, 1.2 * f),
        &b,
        graze,
        &options,
    )
    .unwrap();
    assert!(curve.points.len() > 10, "{} points", curve.points.len());
    let mut worst = 0.0f64;
    for p in &curve.points {
        let (a, freq) = (p.values[0], p.values[1]);
        let expected = grazing_amplitude(k, c, TAU * freq, d);
        worst = worst.max((a - expected).abs() / expected);
    }
    let span = (
        curve.points.first().unwrap().values[1] / f,
        curve.points.last().unwrap().values[1] / f,
    );
    eprintln!(
        "grazing curve: {} points over f/f₀ {span:?}, worst relative error {worst:.2e}",
        curve.points.len()
    );
    assert!(worst < 1e-8, "{worst}");
    assert!(span.0 < 0.81 && span.1 > 1.19, "{span:?}");
}

#[test]
fn a_new_impact_on_the_other_stop_is_located_where_the_swing_grazes_it() {
    // One impact per period on the upper stop; as the force grows the swing reaches the lower
    // stop at −second: the flight's gap minimum to it falls to zero there.
    let (k, c, d, second) = (1.0, 0.1, 0.1, 1.0);
    let model = oscillator(k, c, 0.6, OMEGA, d, Some(second), R);
    let attractor = OrbitGuess {
        forcing_cycles: 1,
        impacts: 1,
        start: None,
        attractor: RunOptions {
            transient_impacts: 2000,
            recorded_impacts: 8,
            ..RunOptions::default()
        },
    };
    let key = Param::System(SystemKey::ForcingAmplitude);
    let b = continue_orbit(
        &model,
        &Contact::rigid(R),
        key,
        (0.6, 3.0),
        &attractor,
        &ContinuationOptions::default(),
    )
    .unwrap();
    let graze = b
        .special(SpecialKind::GrazingFlight)
        .next()
        .expect("a grazing in flight");
    let f_g = graze.point.values[0];
    assert_eq!(b.end, BranchEnd::Grazing);
    assert!(
        graze.point.min_gap.unwrap().abs() < 1e-12,
        "{:?}",
        graze.point.min_gap
    );
    // Independently, the solver's certified impact search run from the orbit's impact for one
    // period: no impact on the lower stop just below f_g, one just above it.
    let p = &graze.point.points[0];
    let lower_hits = |f: f64| {
        let m = oscillator(k, c, f, OMEGA, d, Some(second), R);
        let start = State {
            t: p.t,
            x: d,
            v: -R * p.v_in,
        };
        let options = RunOptions {
            transient_impacts: 0,
            recorded_impacts: 2,
            max_periods: 1.0,
            initial: Some(start),
            ..RunOptions::default()
        };
        hertz_tui::model::system::simulate(&m, &Contact::rigid(R), &options)
            .unwrap()
            .impacts
            .iter()
            .any(|i| i.stop == 1)
    };
    assert!(
        !lower_hits(f_g * (1.0 - 1e-9)),
        "an impact below f_g = {f_g}"
    );
    assert!(
        lower_hits(f_g * (1.0 + 1e-9)),
        "no impact above f_g = {f_g}"
    );
}
