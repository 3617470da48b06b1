//! Event detection and location on the dense output.

use std::f64::consts::PI;

use hertz_tui::model::ode::{Direction, Event, Method, Options, State, Stop, integrate};

use crate::ode_common::{Harmonic, adaptive, fixed};

fn x_of(_t: f64, y: &State) -> f64 {
    y[0]
}

/// x = sin t crosses zero downwards at π. The adaptive methods at rtol 10⁻¹² and RK4 at
/// dt = 10⁻³ locate it to 10⁻¹² relative (measured: 6e-15 DOPRI5, 2e-13 DOP853, 4e-13 Radau5,
/// 3e-14 RK4).
#[test]
fn first_zero_of_sine_is_pi() {
    let mut osc = Harmonic { omega: 1.0 };
    let events = [Event {
        g: &x_of,
        direction: Direction::Falling,
    }];
    let runs = [
        (Method::Dopri5, adaptive(1e-12, 1e-14, 10.0)),
        (Method::Dop853, adaptive(1e-12, 1e-14, 10.0)),
        (Method::Radau5, adaptive(1e-12, 1e-14, 10.0)),
        (Method::Rk4, fixed(1e-3, 10.0)),
    ];
    for (method, opts) in runs {
        let r = integrate(method, &mut osc, 0.0, State::new(0.0, 1.0), &events, &opts)
            .expect("integration");
        assert_eq!(r.stop, Stop::Event { index: 0 }, "{method}");
        let rel = (r.t - PI).abs() / PI;
        assert!(rel <= 1e-12, "{method}: t = {} is {rel:.2e} from π", r.t);
        // The dense output ends at the event and reproduces the returned state there.
        assert_eq!(r.dense.t_end(), r.t, "{method}");
        assert_eq!(r.dense.eval(r.t), r.y, "{method}");
    }
}

/// Whatever the method's accuracy, the event is a root of *its own* dense output: fixed-step
/// methods locate it to ≈ 4·ε·t on the far side of the crossing, with the near side within that
/// distance; adaptive methods retake the step onto it, so |g| there is at rounding level.
#[test]
fn events_are_roots_of_the_dense_output_to_machine_precision() {
    let mut osc = Harmonic { omega: 1.0 };
    let events = [Event {
        g: &x_of,
        direction: Direction::Falling,
    }];
    for method in Method::ALL {
        let opts = Options {
            dt: Some(0.05),
            ..adaptive(1e-4, 1e-6, 10.0)
        };
        let r = integrate(method, &mut osc, 0.0, State::new(0.0, 1.0), &events, &opts)
            .expect("integration");
        assert!((r.t - PI).abs() < 0.05, "{method}: t = {}", r.t);
        if method.is_adaptive() {
            // x crosses at speed 1 near t = π: rounding of t alone moves it by ~4e-16.
            assert!(
                r.y[0].abs() < 1e-14,
                "{method}: x = {} at the event",
                r.y[0]
            );
            assert_eq!(r.dense.eval(r.t), r.y, "{method}");
            continue;
        }
        assert!(
            r.y[0] <= 0.0,
            "{method}: far side means x ≤ 0, got {}",
            r.y[0]
        );
        let before = r.t - 4.0 * f64::EPSILON * r.t;
        assert!(
            r.dense.eval(before)[0] > 0.0,
            "{method}: the crossing must lie within 4·ε·t before t = {}",
            r.t
        );
    }
}

/// x = sin t rises above 0.999 only for |t − π/2| < 0.0447. With RK4 at dt = 0.3 both ends of
/// the step [1.5, 1.8] lie below 0.999 — a check of the step ends alone misses the crossing;
/// the interior samples of the interpolant find it.
#[test]
fn a_double_crossing_inside_one_step_is_found() {
    let mut osc = Harmonic { omega: 1.0 };
    let g = |_t: f64, y: &State| y[0] - 0.999;
    let events = [Event {
        g: &g,
        direction: Direction::Rising,
    }];
    let r = integrate(
        Method::Rk4,
        &mut osc,
        0.0,
        State::new(0.0, 1.0),
        &events,
        &fixed(0.3, 10.0),
    )
    .expect("integration");
    assert_eq!(r.stop, Stop::Event { index: 0 });
    // The step [1.5, 1.8] holds the crossing, and both its ends lie below 0.999 (sin 1.8 =
    // 0.974); its cubic is refitted to end at the event.
    let seg = r.dense.segments().last().expect("segments");
    assert!(seg.y_start()[0] < 0.999 && 1.8f64.sin() < 0.999);
    assert_eq!((seg.t_start(), seg.t_end()), (0.3 * 5.0, r.t));
    assert!(r.t < 0.3 * 6.0);
    // The Hermite interpolant over a 0.3 step is accurate to ~2e-5, which moves a root of
    // slope cos(t) ≈ 0.045 by ~5e-4.
    assert!((r.t - 0.999f64.asin()).abs() < 2e-3, "t = {}", r.t);
}

/// g(t₀) = 0 exactly does not fire at t₀; the direction filter skips crossings the other way.
#[test]
fn zero_at_start_and_direction_filter() {
    let mut osc = Harmonic { omega: 1.0 };
    let opts = adaptive(1e-10, 1e-12, 10.0);
    for (direction, expected) in [
        (Direction::Either, PI),
        (Direction::Falling, PI),
        (Direction::Rising, 2.0 * PI),
    ] {
        let events = [Event {
            g: &x_of,
            direction,
        }];
        let r = integrate(
            Method::Dopri5,
            &mut osc,
            0.0,
            State::new(0.0, 1.0),
            &events,
            &opts,
        )
        .expect("integration");
        assert!(
            (r.t - expected).abs() < 1e-8,
            "{direction:?}: t = {} (expected {expected})",
            r.t
        );
    }
}

/// Re-starting from a located event with the same event function goes on to the next crossing
/// (the event time is on the far side, so g there already has the new sign).
#[test]
fn restarting_at_an_event_does_not_fire_it_again() {
    let mut osc = Harmonic { omega: 1.0 };
    let opts = adaptive(1e-10, 1e-12, 20.0);
    let events = [Event {
        g: &x_of,
        direction: Direction::Either,
    }];
    let first = integrate(
        Method::Dopri5,
        &mut osc,
        0.0,
        State::new(0.0, 1.0),
        &events,
        &opts,
    )
    .expect("first");
    let second =
        integrate(Method::Dopri5, &mut osc, first.t, first.y, &events, &opts).expect("second");
    assert!((first.t - PI).abs() < 1e-8);
    assert!(
        (second.t - 2.0 * PI).abs() < 1e-8,
        "second event at {}",
        second.t
    );
}

/// Of several events the earliest stops the integration, whatever its index.
#[test]
fn the_earliest_event_wins() {
    let mut osc = Harmonic { omega: 1.0 };
    let opts = adaptive(1e-10, 1e-12, 10.0);
    let half = |_t: f64, y: &State| y[0] - 0.5;
    let v = |_t: f64, y: &State| y[1];
    let rising_half = Event {
        g: &half,
        direction: Direction::Rising,
    };
    let falling_v = Event {
        g: &v,
        direction: Direction::Falling,
    };
    let r = integrate(
        Method::Dop853,
        &mut osc,
        0.0,
        State::new(0.0, 1.0),
        &[falling_v, rising_half],
        &opts,
    )
    .expect("integration");
    assert_eq!(r.stop, Stop::Event { index: 1 });
    assert!((r.t - PI / 6.0).abs() < 1e-9, "t = {}", r.t);
}

/// Events after t_max do not fire; fixed-step runs that overshoot t_max end exactly there,
/// with the state read from the last step's interpolant.
#[test]
fn time_limit_comes_before_later_events() {
    let mut osc = Harmonic { omega: 1.0 };
    let events = [Event {
        g: &x_of,
        direction: Direction::Falling,
    }];
    let y0 = State::new(0.0, 1.0);
    // Tolerances: Verlet's global error at dt = 0.3 is ~3e-2, RK4's ~2e-4.
    for (method, opts, tol) in [
        (Method::Verlet, fixed(0.3, 3.1), 5e-2),
        (Method::Rk4, fixed(0.3, 3.1), 1e-3),
        (Method::Radau5, adaptive(1e-9, 1e-12, 3.1), 1e-8),
    ] {
        let r = integrate(method, &mut osc, 0.0, y0, &events, &opts).expect("integration");
        assert_eq!(r.stop, Stop::TimeLimit, "{method}");
        assert_eq!(r.t, 3.1, "{method}");
        assert_eq!(r.dense.t_end(), 3.1, "{method}");
        assert!(
            (r.y - osc.exact(&y0, 3.1)).norm() < tol,
            "{method}: {:?}",
            r.y
        );
    }
    // 3.1 is not a multiple of 0.3: the last RK4 step reaches 3.3 > π, past the zero, yet the
    // event at π > 3.1 does not fire.
    let r = integrate(Method::Rk4, &mut osc, 0.0, y0, &events, &fixed(0.3, 3.1)).expect("rk4");
    assert!(r.dense.segments().last().expect("segments").t_end() > PI);
}
