//! The impact oscillator against closed forms (docs/physics.md §8.2–8.3): the undamped
//! ẍ + x = cos ωt with a rigid stop at x = σ (Budd–Dux form), whose one-impact period-n orbits lie
//! on a closed-form ellipse in (σ, V) and period-double where the closed-form trace of the map
//! reaches −(1 + r²); and the damped oscillator's grazing amplitude A_g = d·√((k−ω²)² + (cω)²).

use std::f64::consts::PI;

use hertz_tui::model::system::{Contact, OrbitOptions, RunOptions, State, find_orbit, simulate};

use crate::systems_common::{angle_diff, guess, oscillator};

/// The one-impact period-n orbit of ẍ + x = cos ωt, stop at σ, restitution r: the impact phase
/// φ = ωt₀ and speed V > 0, from σ(1−ω²) = cos φ + γ·sin φ, V = −2ω·sin φ/((1−ω²)(1−r)),
/// γ = ω(1+r)/(1−r)·cot(nπ/ω) (docs/physics.md §8.2). Both roots φ are returned with V > 0.
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

/// The trace and determinant of the impact map's Jacobian at that orbit, in closed form
/// (implicit differentiation of the flight's solution; docs/physics.md §8.2).
fn budd_dux_jacobian(omega: f64, r: f64, sigma: f64, n: u32, phi: f64, v: f64) -> (f64, f64) {
    let w2 = 1.0 - omega * omega;
    let t = 2.0 * PI * f64::from(n) / omega;
    let (s, c) = t.sin_cos();
    let p0 = phi.cos() / w2;
    let q = -omega * phi.sin() / w2;
    let h = sigma - p0;
    let a = -r * v - q;
    let g_t0 = -q * c + h * s + omega * omega * p0 * s - a * c;
    let dt1_dt0 = -g_t0 / v;
    let dt1_dv0 = r * s / v;
    let v1_t0 = q * s + h * c + omega * omega * p0 * c + a * s;
    let v1_v0 = -r * c;
    let v1_t1 = -h - omega * omega * p0;
    let dv1_dt0 = v1_t0 + v1_t1 * dt1_dt0;
    let dv1_dv0 = v1_v0 + v1_t1 * dt1_dv0;
    (dt1_dt0 + dv1_dv0, dt1_dt0 * dv1_dv0 - dt1_dv0 * dv1_dt0)
}

fn solver_orbit(
    omega: f64,
    r: f64,
    sigma: f64,
    n: u32,
    phi: f64,
    v: f64,
) -> hertz_tui::model::system::Orbit {
    let model = oscillator(1.0, 0.0, 1.0, omega, sigma, None, r);
    find_orbit(
        &model,
        &Contact::rigid(r),
        &guess(n, 1, phi + 1e-3, v * 1.001, 0),
        &OrbitOptions::default(),
    )
    .unwrap()
}

const OMEGA: f64 = 2.2;
const R: f64 = 0.8;

#[test]
fn one_impact_orbits_lie_on_the_closed_form_ellipse() {
    let mut checked = 0;
    for sigma in [0.02, 0.05, 0.1, 0.15, 0.2] {
        for (phi, v) in budd_dux(OMEGA, R, sigma, 1) {
            let o = solver_orbit(OMEGA, R, sigma, 1, phi, v);
            let p = &o.points[0];
            assert!(
                angle_diff(p.phase, phi).abs() < 1e-8,
                "σ={sigma}: φ {} vs {phi}",
                p.phase
            );
            assert!(
                (p.v_in - v).abs() < 1e-8 * v.max(1.0),
                "σ={sigma}: V {} vs {v}",
                p.v_in
            );
            // The ellipse: (σ(1−ω²) − γY)² + Y² = 1 with Y = −V(1−ω²)(1−r)/(2ω).
            let w2 = 1.0 - OMEGA * OMEGA;
            let gamma = OMEGA * (1.0 + R) / (1.0 - R) / (PI / OMEGA).tan();
            let y = -p.v_in * w2 * (1.0 - R) / (2.0 * OMEGA);
            let ellipse = (sigma * w2 - gamma * y).powi(2) + y * y;
            assert!(
                (ellipse - 1.0).abs() < 1e-8,
                "σ={sigma}: on the ellipse to {}",
                ellipse - 1.0
            );
            // An undamped map with one impact: det J = r².
            assert!(
                (o.jacobian_det - R * R).abs() < 1e-9,
                "det {}",
                o.jacobian_det
            );
            let (trace, det) = budd_dux_jacobian(OMEGA, R, sigma, 1, phi, v);
            assert!((det - R * R).abs() < 1e-9, "closed-form det {det}");
            let solver_trace = o.jacobian[0][0] + o.jacobian[1][1];
            assert!(
                (solver_trace - trace).abs() < 1e-7 * trace.abs().max(1.0),
                "{solver_trace} vs {trace}"
            );
            checked += 1;
        }
    }
    assert!(checked >= 4, "only {checked} orbits checked");
}

#[test]
fn period_doubling_where_the_closed_form_puts_it() {
    // The orbit's trace as a function of σ along the branch with the larger V; it crosses
    // −(1 + r²) at σ_PD (bisection on the closed form alone).
    let branch = |sigma: f64| {
        budd_dux(OMEGA, R, sigma, 1)
            .into_iter()
            .max_by(|a, b| a.1.total_cmp(&b.1))
    };
    let excess = |sigma: f64| {
        let (phi, v) = branch(sigma).unwrap();
        budd_dux_jacobian(OMEGA, R, sigma, 1, phi, v).0 + 1.0 + R * R
    };
    let grid: Vec<f64> = (1..150).map(|i| f64::from(i) * 0.002).collect();
    let bracket = grid
        .windows(2)
        .find(|w| {
            branch(w[0]).is_some() && branch(w[1]).is_some() && excess(w[0]) * excess(w[1]) < 0.0
        })
        .expect("the branch period-doubles in σ ∈ (0, 0.3)");
    let (mut lo, mut hi) = (bracket[0], bracket[1]);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if excess(lo) * excess(mid) <= 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let sigma_pd = 0.5 * (lo + hi);
    let (phi, v) = branch(sigma_pd).unwrap();
    let o = solver_orbit(OMEGA, R, sigma_pd, 1, phi, v);
    let trace = o.jacobian[0][0] + o.jacobian[1][1];
    assert!(
        (trace + 1.0 + R * R).abs() < 1e-7,
        "trace {trace} at σ_PD = {sigma_pd}"
    );
    let side = |sigma: f64| {
        let (phi, v) = branch(sigma).unwrap();
        solver_orbit(OMEGA, R, sigma, 1, phi, v).stable
    };
    assert_ne!(
        side(sigma_pd * (1.0 - 1e-6)),
        side(sigma_pd * (1.0 + 1e-6)),
        "stability changes at σ_PD"
    );
}

/// The steady state of ẍ + cẋ + kx = A·cos ωt: x(0), ẋ(0).
fn steady_start(k: f64, c: f64, a: f64, omega: f64) -> State {
    let (re, im) = (k - omega * omega, c * omega);
    let d = re * re + im * im;
    let (p_re, p_im) = (a * re / d, -a * im / d);
    State {
        t: 0.0,
        x: p_re,
        v: -omega * p_im,
    }
}

/// Whether the steady response at amplitude `a` reaches the stop within two periods.
fn impacts(k: f64, c: f64, a: f64, omega: f64, gap: f64) -> bool {
    let model = oscillator(k, c, a, omega, gap, None, 0.8);
    let options = RunOptions {
        transient_impacts: 0,
        recorded_impacts: 1,
        max_periods: 2.0,
        initial: Some(steady_start(k, c, a, omega)),
        ..RunOptions::default()
    };
    !simulate(&model, &Contact::rigid(0.8), &options)
        .unwrap()
        .impacts
        .is_empty()
}

#[test]
fn grazing_amplitude_is_found_to_1e_9() {
    for (k, c, omega, gap) in [
        (1.0f64, 0.1, 1.3, 1.0),
        (4.0, 0.02, 0.7, 0.3),
        (1.0, 0.5, 2.0, 2.0),
    ] {
        let a_g = gap * ((k - omega * omega).powi(2) + (c * omega).powi(2)).sqrt();
        // A penetration of 1e-9·gap, lasting ~1e-4.5 of a period, is not missed …
        assert!(
            impacts(k, c, a_g * (1.0 + 1e-9), omega, gap),
            "missed grazing impact at k={k}"
        );
        // … and a miss by 1e-9·gap is no impact.
        assert!(
            !impacts(k, c, a_g * (1.0 - 1e-9), omega, gap),
            "false impact at k={k}"
        );
    }
}

#[test]
fn damped_orbits_contract_by_liouville_and_match_the_attractor() {
    // ẍ + 2ζẋ + x = cos ωt with a stop: det J = r^{2n}·e^{−2ζ·mT} (the flow contracts phase-space
    // area by e^{−2ζτ}, each impact by r² times a ratio of speeds that cancels around an orbit).
    let (zeta, omega, sigma, r) = (0.05, 2.2, 0.1, 0.8);
    let model = oscillator(1.0, 2.0 * zeta, 1.0, omega, sigma, None, r);
    let contact = Contact::rigid(r);
    let attractor = RunOptions {
        transient_impacts: 2000,
        recorded_impacts: 8,
        ..RunOptions::default()
    };
    let history = simulate(&model, &contact, &attractor).unwrap();
    assert_eq!(
        history.period(2.0 * PI / omega),
        Some((1, 1)),
        "a period-1 attractor"
    );
    let orbit = find_orbit(
        &model,
        &contact,
        &hertz_tui::model::system::OrbitGuess {
            forcing_cycles: 1,
            impacts: 1,
            start: None,
            attractor,
        },
        &OrbitOptions::default(),
    )
    .unwrap();
    let period = 2.0 * PI / omega;
    let expected = r * r * (-2.0 * zeta * period).exp();
    assert!(
        (orbit.jacobian_det - expected).abs() < 1e-10,
        "{} vs {expected}",
        orbit.jacobian_det
    );
    assert!(orbit.stable);
    let last = history.impacts.last().unwrap();
    let p = &orbit.points[0];
    assert!(
        angle_diff(p.phase, last.phase).abs() < 1e-9,
        "{} vs {}",
        p.phase,
        last.phase
    );
    assert!((p.v_in - last.v_in).abs() < 1e-9 * last.v_in);
}

#[test]
fn a_clearance_orbit_hits_both_stops() {
    // Two stops at ±σ: an orbit with one impact on each per forcing period; with damping,
    // det J over the period is r⁴·e^{−2ζ·T}.
    let (zeta, omega, sigma, r) = (0.1, 1.3, 0.5, 0.7);
    let model = oscillator(1.0, 2.0 * zeta, 1.0, omega, sigma, Some(sigma), r);
    let contact = Contact::rigid(r);
    let attractor = RunOptions {
        transient_impacts: 3000,
        recorded_impacts: 8,
        ..RunOptions::default()
    };
    let history = simulate(&model, &contact, &attractor).unwrap();
    assert_eq!(
        history.period(2.0 * PI / omega),
        Some((2, 1)),
        "{:?}",
        &history.impacts[..4]
    );
    let stops: Vec<usize> = history.impacts.iter().map(|i| i.stop).collect();
    assert!(stops.contains(&0) && stops.contains(&1));
    let orbit = find_orbit(
        &model,
        &contact,
        &hertz_tui::model::system::OrbitGuess {
            forcing_cycles: 1,
            impacts: 2,
            start: None,
            attractor,
        },
        &OrbitOptions::default(),
    )
    .unwrap();
    let expected = r.powi(4) * (-2.0 * zeta * 2.0 * PI / omega).exp();
    assert!(
        (orbit.jacobian_det - expected).abs() < 1e-10,
        "{} vs {expected}",
        orbit.jacobian_det
    );
    // The attractor's impacts, one on each stop (this orbit is not the symmetric one: the
    // speeds differ, a symmetry-broken orbit of this clearance).
    for p in &orbit.points {
        let seen = history.impacts.iter().any(|i| {
            i.stop == p.stop
                && angle_diff(i.phase, p.phase).abs() < 1e-9
                && (i.v_in - p.v_in).abs() < 1e-9 * p.v_in
        });
        assert!(seen, "{p:?} is on the attractor");
    }
    assert_ne!(orbit.points[0].stop, orbit.points[1].stop);
}
