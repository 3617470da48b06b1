//! Where methods fail, on purpose: linear stability of the fixed-step methods on ẍ = −ω²x
//! against theory, stiffness, a discontinuous right-hand side, and failures returned as errors.

use std::f64::consts::{FRAC_PI_4, PI, SQRT_2};

use hertz_tui::model::ode::{
    Direction, Event, Method, OdeError, OdeSystem, Options, State, Stop, integrate,
};

use crate::ode_common::{Friction, Harmonic, adaptive, fixed};

/// All states of a fixed-step run: the start of the first segment and every step end.
fn trajectory(method: Method, sys: &mut dyn OdeSystem, y0: State, dt: f64, n: usize) -> Vec<State> {
    let opts = fixed(dt, dt * n as f64);
    let r = integrate(method, sys, 0.0, y0, &[], &opts).expect("integration");
    let mut ys = vec![y0];
    ys.extend(r.dense.segments().iter().map(|s| s.y_end()));
    ys
}

/// The one-step map M of a fixed-step method on a linear system, column by column.
fn one_step_matrix(method: Method, sys: &mut dyn OdeSystem, dt: f64) -> [[f64; 2]; 2] {
    let c0 = trajectory(method, sys, State::new(1.0, 0.0), dt, 1)[1];
    let c1 = trajectory(method, sys, State::new(0.0, 1.0), dt, 1)[1];
    [[c0[0], c1[0]], [c0[1], c1[1]]]
}

/// Largest h in [lo, hi] with amplification ≤ 1, by bisection on `grows`.
fn bisect(lo: f64, hi: f64, mut grows: impl FnMut(f64) -> bool) -> f64 {
    let (mut lo, mut hi) = (lo, hi);
    assert!(
        !grows(lo) && grows(hi),
        "bracket [{lo}, {hi}] does not straddle the limit"
    );
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if grows(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    lo
}

/// Explicit Euler multiplies x² + v² by exactly 1 + (hω)² per step: it gains energy at every
/// step size, however small (no stable step exists for an undamped oscillator).
#[test]
fn explicit_euler_gains_energy_at_every_step_size() {
    let mut osc = Harmonic { omega: 1.0 };
    for h in [1e-3, 0.1, 1.0, 2.5] {
        let ys = trajectory(Method::Euler, &mut osc, State::new(1.0, 0.0), h, 50);
        for w in ys.windows(2) {
            let ratio = osc.energy(&w[1]) / osc.energy(&w[0]);
            assert!(ratio > 1.0, "h = {h}: energy did not grow");
            assert!(
                (ratio - (1.0 + h * h)).abs() <= 1e-13 * ratio,
                "h = {h}: ratio {ratio} vs 1 + h² = {}",
                1.0 + h * h
            );
        }
    }
}

/// Symplectic Euler and velocity Verlet map (x, v) by a matrix with det M = 1 and
/// tr M = 2 − (hω)² (both measured from one step): the eigenvalues lie on the unit circle for
/// hω ≤ 2 and one leaves it for hω > 2. The measured critical hω is 2 to 1e-12.
#[test]
fn symplectic_methods_have_the_step_limit_two_over_omega() {
    let omega = 3.0;
    let mut osc = Harmonic { omega };
    for method in [Method::SymplecticEuler, Method::Verlet] {
        for hw in [0.1, 1.0, 1.9, 2.0, 2.1, 3.0] {
            let m = one_step_matrix(method, &mut osc, hw / omega);
            let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
            let tr = m[0][0] + m[1][1];
            assert!((det - 1.0).abs() < 1e-13, "{method} hω = {hw}: det = {det}");
            assert!(
                (tr - (2.0 - hw * hw)).abs() < 1e-13,
                "{method} hω = {hw}: tr = {tr}"
            );
        }
        // Spectral radius from the measured matrix; > 1 + 1e-9 means unstable.
        let critical = bisect(1.0, 3.0, |hw| {
            let m = one_step_matrix(method, &mut osc, hw / omega);
            let tr = m[0][0] + m[1][1];
            let disc = tr * tr - 4.0;
            disc > 0.0 && (tr.abs() + disc.sqrt()) / 2.0 > 1.0 + 1e-9
        });
        assert!(
            (critical - 2.0).abs() < 1e-12,
            "{method}: critical hω = {critical}"
        );
    }
}

/// End to end over 10⁴ steps: at hω = 1.9 each method conserves its modified energy exactly
/// (symplectic Euler: x² − h·x·v + v²; Verlet: (1 − h²/4)·x² + v², ω = 1), so the energy stays
/// bounded; at hω = 2.1 it grows by |λ|² per step with |λ| = ((h² − 2) + √((h² − 2)² − 4))/2.
#[test]
fn symplectic_methods_bounded_below_and_divergent_above_the_limit() {
    let mut osc = Harmonic { omega: 1.0 };
    let y0 = State::new(1.0, 0.5);
    let h = 1.9;
    type Invariant = fn(f64, &State) -> f64;
    let invariants: [(Method, Invariant); 2] = [
        (Method::SymplecticEuler, |h, y| {
            y[0] * y[0] - h * y[0] * y[1] + y[1] * y[1]
        }),
        (Method::Verlet, |h, y| {
            (1.0 - h * h / 4.0) * y[0] * y[0] + y[1] * y[1]
        }),
    ];
    for (method, q) in invariants {
        let ys = trajectory(method, &mut osc, y0, h, 10_000);
        let q0 = q(h, &y0);
        let drift = ys
            .iter()
            .map(|y| (q(h, y) / q0 - 1.0).abs())
            .fold(0.0, f64::max);
        // Round-off only: ~N·ε·κ with κ = (1 + h/2)/(1 − h/2) ≈ 39 the conditioning of the
        // invariant (measured ≈ 3e-10), against growth by orders of magnitude above the limit.
        assert!(
            drift < 1e-8,
            "{method}: modified energy drifted by {drift:.2e}"
        );
        let e_max = ys.iter().map(|y| osc.energy(y)).fold(0.0, f64::max);
        assert!(e_max < 100.0 * osc.energy(&y0), "{method}: energy {e_max}");

        let h = 2.1;
        let ys = trajectory(method, &mut osc, y0, h, 200);
        let a = h * h - 2.0;
        let lambda = (a + (a * a - 4.0).sqrt()) / 2.0;
        let n = ys.len() - 1;
        let growth = (osc.energy(&ys[n]) / osc.energy(&ys[n - 1])).sqrt();
        assert!(
            (growth - lambda).abs() < 1e-9 * lambda,
            "{method}: growth {growth} vs |λ| = {lambda}"
        );
    }
}

/// RK4 on ẍ = −ω²x multiplies |y| by |R(ihω)| per step, R(z) = 1 + z + z²/2 + z³/6 + z⁴/24,
/// |R(iy)|² = 1 − y⁶/72 + y⁸/576: stable (slightly dissipative) up to hω = 2√2 ≈ 2.828, the
/// extent of RK4's stability region on the imaginary axis. The often quoted 2.785 is its extent
/// on the negative real axis (root of x³ − 4x² + 12x − 24): that is the limit for pure damping
/// ẋ = v, v̇ = −λv, measured here too. An undamped contact oscillator sits on the imaginary axis.
#[test]
fn rk4_stability_limits_on_the_imaginary_and_real_axes() {
    let mut osc = Harmonic { omega: 1.0 };
    let amplification = |osc: &mut Harmonic, h: f64| {
        let y1 = trajectory(Method::Rk4, osc, State::new(0.6, 0.8), h, 1)[1];
        y1.norm()
    };
    for h in [0.5, 1.0, 2.0, 2.8, 2.9, 3.2] {
        let measured = amplification(&mut osc, h).powi(2);
        let theory = 1.0 - h.powi(6) / 72.0 + h.powi(8) / 576.0;
        assert!(
            (measured - theory).abs() < 1e-13,
            "h = {h}: {measured} vs {theory}"
        );
    }
    let critical = bisect(2.0, 3.5, |h| amplification(&mut osc, h) > 1.0 + 1e-14);
    assert!(
        (critical - 2.0 * SQRT_2).abs() < 1e-9,
        "imaginary-axis limit {critical}"
    );

    // Energy over 2000 steps just below and above the limit.
    let y0 = State::new(1.0, 0.0);
    let below = trajectory(Method::Rk4, &mut osc, y0, 2.8, 2000);
    let above = trajectory(Method::Rk4, &mut osc, y0, 2.86, 2000);
    assert!(osc.energy(below.last().expect("states")) < osc.energy(&y0));
    assert!(osc.energy(above.last().expect("states")) > 10.0 * osc.energy(&y0));

    struct Damping;
    impl OdeSystem for Damping {
        fn rhs(&mut self, _t: f64, y: &State) -> State {
            State::new(y[1], -y[1])
        }
    }
    let real_limit = bisect(2.0, 3.5, |h| {
        let y1 = trajectory(Method::Rk4, &mut Damping, State::new(0.0, 1.0), h, 1)[1];
        y1[1].abs() > 1.0 + 1e-14
    });
    // Newton on x³ − 4x² + 12x − 24 = 0 for the theoretical value.
    let mut x = 2.8_f64;
    for _ in 0..50 {
        x -= (x * x * x - 4.0 * x * x + 12.0 * x - 24.0) / (3.0 * x * x - 8.0 * x + 12.0);
    }
    assert!(
        (real_limit - x).abs() < 1e-9,
        "real-axis limit {real_limit} vs {x}"
    );
    assert!((x - 2.785_293_563_4).abs() < 1e-9);
}

/// Overdamped ẍ = −x − c·ẋ with c = 10⁴: eigenvalues ≈ −10⁻⁴ and −10⁴. Radau5 (L-stable)
/// follows the slow mode in a few dozen steps; DOPRI5 is held to h ≲ 3.3/c by stability and
/// needs thousands, though the solution is smooth.
#[test]
fn radau5_handles_stiffness_that_throttles_dopri5() {
    struct Overdamped {
        c: f64,
    }
    impl OdeSystem for Overdamped {
        fn rhs(&mut self, _t: f64, y: &State) -> State {
            State::new(y[1], -y[0] - self.c * y[1])
        }
    }
    let c = 1e4;
    let disc = (c * c - 4.0f64).sqrt();
    let (l1, l2) = ((-c + disc) / 2.0, (-c - disc) / 2.0);
    let (a, b) = (l2 / (l2 - l1), -l1 / (l2 - l1));
    let t_end = 2.0;
    let exact = State::new(
        a * (l1 * t_end).exp() + b * (l2 * t_end).exp(),
        a * l1 * (l1 * t_end).exp() + b * l2 * (l2 * t_end).exp(),
    );
    let opts = adaptive(1e-8, 1e-12, t_end);
    let y0 = State::new(1.0, 0.0);
    let radau =
        integrate(Method::Radau5, &mut Overdamped { c }, 0.0, y0, &[], &opts).expect("radau5");
    let dopri =
        integrate(Method::Dopri5, &mut Overdamped { c }, 0.0, y0, &[], &opts).expect("dopri5");
    assert!(
        (radau.y[0] - exact[0]).abs() < 1e-7,
        "radau5 x = {}",
        radau.y[0]
    );
    assert!(
        (dopri.y[0] - exact[0]).abs() < 1e-7,
        "dopri5 x = {}",
        dopri.y[0]
    );
    eprintln!("radau5 {:?}, dopri5 {:?}", radau.stats, dopri.stats);
    assert!(
        radau.stats.steps < 100,
        "radau5 steps {}",
        radau.stats.steps
    );
    assert!(
        dopri.stats.steps > 5000,
        "dopri5 steps {}",
        dopri.stats.steps
    );
    assert!(radau.stats.jacobian_evals >= 1);
}

fn v_of(_t: f64, y: &State) -> f64 {
    y[1]
}

/// ẍ = −sign(ẋ)·c − x from x = 0, ẋ = 1. Loading (ẋ > 0) gives x = −c + c·cos t + sin t, so
/// ẋ = 0 at t₁ = atan(1/c) with x₁ = √(1 + c²) − c. With c = 1, |x₁| < c: friction holds the
/// spring and the mass sticks. Integrated straight through the switch, DOPRI5 at tight tolerance
/// chatters across ẋ = 0 and burns its whole step budget within 10⁻³ of t₁ (step-size
/// underflow is the other way this ends); split at the ẋ = 0 event, phase 1 lands on the closed
/// form and the stick condition |x₁| ≤ c can be read off.
#[test]
fn sticking_dry_friction_defeats_a_plain_adaptive_step_but_not_event_splitting() {
    let c = 1.0;
    let opts = Options {
        max_steps: 20_000,
        ..adaptive(1e-10, 1e-10, 5.0)
    };
    let y0 = State::new(0.0, 1.0);
    match integrate(
        Method::Dopri5,
        &mut Friction { c, branch: None },
        0.0,
        y0,
        &[],
        &opts,
    ) {
        Err(
            e @ (OdeError::StepBudgetExhausted { t, .. } | OdeError::StepSizeUnderflow { t, .. }),
        ) => {
            eprintln!("straight through: {e}");
            assert!((t - FRAC_PI_4).abs() < 1e-3, "stuck at t = {t}")
        }
        other => panic!("expected a failure at the switch, got {other:?}"),
    }

    let events = [Event {
        g: &v_of,
        direction: Direction::Falling,
    }];
    // Even tighter than the failing run: splitting has no trouble with it.
    let phase1 = integrate(
        Method::Dopri5,
        &mut Friction {
            c,
            branch: Some(1.0),
        },
        0.0,
        y0,
        &events,
        &Options {
            rtol: 1e-12,
            atol: 1e-12,
            ..opts
        },
    )
    .expect("loading phase");
    assert_eq!(phase1.stop, Stop::Event { index: 0 });
    assert!((phase1.t - FRAC_PI_4).abs() < 1e-11, "t₁ = {}", phase1.t);
    assert!(
        (phase1.y[0] - (SQRT_2 - 1.0)).abs() < 1e-11,
        "x₁ = {}",
        phase1.y[0]
    );
    assert!(phase1.stats.steps < 100);
    assert!(
        phase1.y[0].abs() <= c,
        "the spring force cannot overcome friction: sticks"
    );
}

/// With c = 0.1 the mass slips back: unloading (ẋ < 0) from x₁ follows
/// x = c + (x₁ − c)·cos(t − t₁) to the next ẋ = 0 at t₁ + π, x₂ = 2c − x₁. Split at the
/// events, both phases hit the closed forms to 10⁻¹⁰. Straight through, the transversal switch
/// costs a burst of rejected steps at the kink and the accuracy there; it does not collapse.
#[test]
fn slipping_dry_friction_split_at_the_events_matches_the_closed_form() {
    let c: f64 = 0.1;
    let opts = adaptive(1e-12, 1e-12, 10.0);
    let y0 = State::new(0.0, 1.0);
    let x1 = (1.0 + c * c).sqrt() - c;
    let t1 = (1.0 / c).atan();
    let falling = [Event {
        g: &v_of,
        direction: Direction::Falling,
    }];
    let rising = [Event {
        g: &v_of,
        direction: Direction::Rising,
    }];
    let p1 = integrate(
        Method::Dopri5,
        &mut Friction {
            c,
            branch: Some(1.0),
        },
        0.0,
        y0,
        &falling,
        &opts,
    )
    .expect("loading");
    assert!((p1.t - t1).abs() < 1e-10 && (p1.y[0] - x1).abs() < 1e-10);
    let p2 = integrate(
        Method::Dopri5,
        &mut Friction {
            c,
            branch: Some(-1.0),
        },
        p1.t,
        p1.y,
        &rising,
        &opts,
    )
    .expect("unloading");
    assert!((p2.t - (t1 + PI)).abs() < 1e-10, "t₂ = {}", p2.t);
    assert!((p2.y[0] - (2.0 * c - x1)).abs() < 1e-10, "x₂ = {}", p2.y[0]);

    // Straight through to t₁ + π with the sign evaluated from the state.
    let straight = integrate(
        Method::Dopri5,
        &mut Friction { c, branch: None },
        0.0,
        y0,
        &[],
        &Options {
            t_max: t1 + PI,
            ..opts
        },
    )
    .expect("straight through");
    let split_rejections = p1.stats.rejected_steps + p2.stats.rejected_steps;
    eprintln!(
        "straight: {:?}, error {:.2e}; split: {:?} + {:?}",
        straight.stats,
        (straight.y[0] - (2.0 * c - x1)).abs(),
        p1.stats,
        p2.stats
    );
    assert!(
        straight.stats.rejected_steps >= split_rejections + 10,
        "straight-through rejections {} vs split {split_rejections}",
        straight.stats.rejected_steps
    );
}

/// Failures are results: each comes back as its typed error, none panics or hangs.
#[test]
fn budget_exhaustion_is_an_error() {
    let mut osc = Harmonic { omega: 1.0 };
    let y0 = State::new(1.0, 0.0);
    for method in Method::ALL {
        let opts = Options {
            dt: Some(0.01),
            max_steps: 10,
            ..adaptive(1e-8, 1e-10, 100.0)
        };
        match integrate(method, &mut osc, 0.0, y0, &[], &opts) {
            Err(OdeError::StepBudgetExhausted { steps: 10, t }) => {
                assert!(t > 0.0 && t < 100.0, "{method}: t = {t}")
            }
            other => panic!("{method}: {other:?}"),
        }
    }
}

/// ẋ = x² blows up at t = 1 (x = 1/(1 − t)). Explicit Euler with dt = 0.5 overflows to ∞
/// after a few steps: NonFinite. DOPRI5 creeps up to the singularity until its step falls below
/// 16·ε·t: StepSizeUnderflow just before t = 1.
#[test]
fn blow_up_gives_non_finite_or_underflow() {
    struct Blowup;
    impl OdeSystem for Blowup {
        fn rhs(&mut self, _t: f64, y: &State) -> State {
            State::new(y[0] * y[0], 0.0)
        }
    }
    match integrate(
        Method::Euler,
        &mut Blowup,
        0.0,
        State::new(1.0, 0.0),
        &[],
        &fixed(0.5, 100.0),
    ) {
        Err(OdeError::NonFinite { t }) => assert!(t > 1.0 && t < 10.0, "t = {t}"),
        other => panic!("euler: {other:?}"),
    }
    let opts = adaptive(1e-8, 1e-10, 2.0);
    match integrate(
        Method::Dopri5,
        &mut Blowup,
        0.0,
        State::new(1.0, 0.0),
        &[],
        &opts,
    ) {
        Err(OdeError::StepSizeUnderflow { t, h }) => {
            assert!(
                (t - 1.0).abs() < 1e-6 && h < 16.0 * f64::EPSILON * t,
                "t = {t}, h = {h}"
            )
        }
        other => panic!("dopri5: {other:?}"),
    }
}

/// A right-hand side that is NaN past t = 1 (like x^{3/2} past x = 0 without a guard): the
/// explicit methods shrink their steps against the wall and report NonFinite there, Radau5
/// reports its Newton failure, fixed-step methods NonFinite at the first step beyond.
#[test]
fn nan_right_hand_side_is_reported_where_it_starts() {
    struct Wall;
    impl OdeSystem for Wall {
        fn rhs(&mut self, t: f64, _y: &State) -> State {
            State::new((1.0 - t).sqrt(), 0.0)
        }
    }
    let y0 = State::new(0.0, 0.0);
    for method in Method::ALL {
        let opts = Options {
            dt: Some(0.3),
            ..adaptive(1e-8, 1e-10, 2.0)
        };
        let r = integrate(method, &mut Wall, 0.0, y0, &[], &opts);
        eprintln!("{method}: {r:?}");
        match (method, r) {
            (Method::Radau5, Err(OdeError::NewtonFailed { t }))
            | (Method::Dopri5 | Method::Dop853, Err(OdeError::NonFinite { t })) => {
                assert!((t - 1.0).abs() < 1e-3, "{method}: t = {t}")
            }
            (_, Err(OdeError::NonFinite { t })) if !method.is_adaptive() => {
                assert!((t - 1.2).abs() < 1e-12, "{method}: t = {t}")
            }
            (_, other) => panic!("{method}: {other:?}"),
        }
    }
    match integrate(
        Method::Rk4,
        &mut Wall,
        0.0,
        State::new(f64::NAN, 0.0),
        &[],
        &fixed(0.1, 1.0),
    ) {
        Err(OdeError::NonFinite { t }) => assert_eq!(t, 0.0),
        other => panic!("{other:?}"),
    }
}

/// `OdeSystem::check` ends the run with Aborted at the first accepted step it refuses: here an
/// energy guard on explicit Euler, whose energy grows by (1 + h²) per step, so it trips at the
/// first n with (1 + h²)ⁿ > 1.1.
#[test]
fn check_aborts_with_the_reason_and_time() {
    struct Guarded(Harmonic);
    impl OdeSystem for Guarded {
        fn rhs(&mut self, t: f64, y: &State) -> State {
            self.0.rhs(t, y)
        }
        fn check(&mut self, _t: f64, y: &State) -> Result<(), String> {
            let e = self.0.energy(y);
            if e > 1.1 {
                Err(format!("energy grew to {e:.3}"))
            } else {
                Ok(())
            }
        }
    }
    let h: f64 = 0.1;
    let n = (1.1f64.ln() / (1.0 + h * h).ln()).ceil();
    let r = integrate(
        Method::Euler,
        &mut Guarded(Harmonic { omega: 1.0 }),
        0.0,
        State::new(1.0, 0.0),
        &[],
        &fixed(h, 100.0),
    );
    match r {
        Err(OdeError::Aborted { t, reason }) => {
            assert!((t - n * h).abs() < 1e-12, "t = {t}, expected {}", n * h);
            assert!(reason.starts_with("energy grew"));
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn invalid_options_are_rejected() {
    let mut osc = Harmonic { omega: 1.0 };
    let y0 = State::new(1.0, 0.0);
    let base = adaptive(1e-8, 1e-10, 1.0);
    let cases = [
        (Method::Rk4, Options { dt: None, ..base }),
        (
            Method::Euler,
            Options {
                dt: Some(0.0),
                ..base
            },
        ),
        (
            Method::Verlet,
            Options {
                dt: Some(-1e-3),
                ..base
            },
        ),
        (
            Method::SymplecticEuler,
            Options {
                dt: Some(f64::NAN),
                ..base
            },
        ),
        (Method::Dopri5, Options { atol: 0.0, ..base }),
        (
            Method::Dop853,
            Options {
                rtol: -1e-6,
                ..base
            },
        ),
        (
            Method::Radau5,
            Options {
                rtol: 1e-17,
                ..base
            },
        ),
        (
            Method::Dopri5,
            Options {
                h_initial: Some(-1.0),
                ..base
            },
        ),
        (Method::Dopri5, Options { t_max: 0.0, ..base }),
        (
            Method::Rk4,
            Options {
                dt: Some(0.1),
                t_max: -1.0,
                ..base
            },
        ),
    ];
    for (method, opts) in cases {
        match integrate(method, &mut osc, 0.0, y0, &[], &opts) {
            Err(OdeError::InvalidOptions(_)) => {}
            other => panic!("{method} with {opts:?}: {other:?}"),
        }
    }
}
