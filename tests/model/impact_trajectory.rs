//! The curves of a solved impact: `at(t)` against the exact elastic motion, `samples(n)` with the
//! extrema inserted, and the dry-friction jump at maximum compression drawn as two samples.

use hertz_tui::model::PowerLaw;
use hertz_tui::model::force::{ForceModel, ImpactParams};
use hertz_tui::model::impact::{ImpactSolution, MethodChoice, SolveOptions, solve_impact};
use hertz_tui::model::ode::Method;

fn fig5(restitution: f64) -> ImpactParams {
    ImpactParams {
        mass: 0.033,
        law: PowerLaw {
            k: 1.465e10,
            n: 1.5,
        },
        v0: 0.3,
        restitution,
        plastic_indentation: 2.3e-6,
        contact: crate::laws_common::fig5_contact(),
    }
}

fn rel(a: f64, b: f64) -> f64 {
    (a / b - 1.0).abs()
}

/// `check` on the solution of `p` by every law with `auto` and with each of `methods`, named
/// "law method".
fn each_solution(
    p: &ImpactParams,
    methods: [Method; 2],
    mut check: impl FnMut(&str, &ImpactSolution),
) {
    for model in ForceModel::ALL {
        let choices = [
            MethodChoice::Auto,
            MethodChoice::Integrator(methods[0]),
            MethodChoice::Integrator(methods[1]),
        ];
        for method in choices {
            let opts = SolveOptions {
                method,
                ..SolveOptions::default()
            };
            let sol = solve_impact(model, p, &opts).unwrap();
            check(&format!("{model} {method}"), &sol);
        }
    }
}

#[test]
fn elastic_curve_follows_the_incomplete_beta_solution() {
    // t(x) = (x_max/v₀)·B(u; 1/(n+1), ½)/(n+1), u = (x/x_max)^{n+1} (docs/physics.md §3): the
    // trajectory of `auto` (exact numbers, DOP853 curves at rtol 1e-10) passes through
    // (t(x), x, v(x)) to 1e-9 of x_max, v₀ and F_max.
    let p = fig5(1.0);
    let (m, v0, law) = (p.mass, p.v0, p.law);
    let sol = solve_impact(ForceModel::Quasistatic, &p, &SolveOptions::default()).unwrap();
    let x_max = law.max_approach(m, v0);
    for frac in [0.05, 0.3, 0.6, 0.9, 0.999] {
        let x = frac * x_max;
        let t = law.loading_time_at(m, v0, x);
        let s = sol.trajectory.at(t);
        let f_max = law.force(x_max);
        assert!((s.x - x).abs() < 1e-9 * x_max, "x at {frac}: {}", s.x);
        let v = law.loading_velocity_at(m, v0, x);
        assert!((s.v - v).abs() < 1e-9 * v0, "v at {frac}: {} vs {v}", s.v);
        assert!((s.f - law.force(x)).abs() < 1e-9 * f_max, "F at {frac}");
        // Unloading mirrors loading in time.
        let back = sol.trajectory.at(sol.trajectory.t_end() - t);
        assert!((back.x - x).abs() < 1e-9 * x_max, "x mirror at {frac}");
        assert!((back.v + v).abs() < 1e-9 * v0, "v mirror at {frac}");
    }
}

#[test]
fn samples_are_even_in_time_with_the_extrema_inserted() {
    each_solution(&fig5(0.6), [Method::Dopri5, Method::Rk4], |what, sol| {
        let (s, traj) = (&sol.summary, &sol.trajectory);
        let samples = traj.samples(50);
        assert_eq!(samples.len(), 50 + traj.extrema().len() - 1, "{what}");
        assert!(
            samples.windows(2).all(|w| w[0].t <= w[1].t),
            "{what}: time order"
        );
        assert_eq!((samples[0].t, samples[0].x), (0.0, 0.0));
        let last = samples.last().unwrap();
        assert_eq!(last.t, s.t_contact, "{what}");
        assert_eq!(last.x, s.x_residual);
        assert_eq!(-last.v, s.v_out);
        // The chart's peaks are the summary's, exactly.
        let f_peak = samples.iter().map(|q| q.f).fold(f64::MIN, f64::max);
        let x_peak = samples.iter().map(|q| q.x).fold(f64::MIN, f64::max);
        assert_eq!(f_peak, s.f_max, "{what}");
        assert_eq!(x_peak, s.x_max, "{what}");
        assert!(samples.iter().any(|q| q.t == s.t_f_max && q.f == s.f_max));
        assert!(samples.iter().any(|q| q.t == s.t_x_max && q.v == 0.0));
        // Even samples are at t_end·i/49 (the extrema sit between them).
        let even: Vec<f64> = samples
            .iter()
            .map(|q| q.t)
            .filter(|t| ((t / s.t_contact * 49.0).round() / 49.0 * s.t_contact - t).abs() < 1e-18)
            .collect();
        assert!(even.len() >= 48, "{what}: {} even samples", even.len());
    });
}

#[test]
fn dry_friction_force_jump_is_drawn_as_two_samples() {
    // At ẋ = 0 the friction term flips from +P·x to −P·x: the chart gets both ends of the jump at
    // t_x_max, loading first.
    let p = ImpactParams {
        v0: 0.03,
        restitution: 0.9,
        ..fig5(0.9)
    };
    let sol = solve_impact(ForceModel::DryFriction, &p, &SolveOptions::default()).unwrap();
    let s = &sol.summary;
    let at_switch: Vec<_> = sol
        .trajectory
        .samples(20)
        .into_iter()
        .filter(|q| q.t == s.t_x_max)
        .collect();
    assert_eq!(at_switch.len(), 2);
    let p_fric = hertz_tui::model::force::dry_friction::DryFriction::new(&p).p();
    assert_eq!(at_switch[0].f, s.f_max);
    assert!(rel(at_switch[0].f - at_switch[1].f, 2.0 * p_fric * s.x_max) < 1e-12);
    // `at` belongs to loading up to the switch and to unloading after it (the curves' own switch,
    // within 1e-10 of the exact t_x_max).
    let before = sol.trajectory.at(s.t_x_max * (1.0 - 1e-9));
    let after = sol.trajectory.at(s.t_x_max * (1.0 + 1e-9));
    assert!(rel(before.f, s.f_max) < 1e-9);
    assert!(rel(before.f - after.f, 2.0 * p_fric * s.x_max) < 1e-6);
}

#[test]
fn at_clamps_to_the_contact_and_small_requests_are_served() {
    let p = fig5(0.6);
    let sol = solve_impact(ForceModel::HuntCrossley, &p, &SolveOptions::default()).unwrap();
    let traj = &sol.trajectory;
    assert_eq!(traj.at(-1.0).t, 0.0);
    assert_eq!(traj.at(1.0).t, traj.t_end());
    // n = 0 and n = 1 still include the extrema; every sample is finite.
    assert_eq!(traj.samples(0).len(), traj.extrema().len());
    let one = traj.samples(1);
    assert_eq!(one[0].t, 0.0);
    assert!(one.iter().all(|q| q.f.is_finite() && q.x.is_finite()));
}

/// `samples` walks the segments in time order instead of searching them for each sample: every
/// even sample is `at` its time, bit for bit, on every law and method (integrated, exact, and a
/// fixed-step method's Hermite segments).
#[test]
fn samples_are_at_their_times_exactly() {
    each_solution(&fig5(0.6), [Method::Dop853, Method::Rk4], |what, sol| {
        let traj = &sol.trajectory;
        let marks = traj.extrema();
        for q in traj.samples(257) {
            if !marks.contains(&q) {
                assert_eq!(q, traj.at(q.t), "{what} at {}", q.t);
            }
        }
    });
}

/// What a chart draws of an exact solution — its curves integrated at a chart's tolerance (DOPRI5
/// at rtol 1e-6), not the trajectory's — lies within 2e-5 of x_max, v₀ and F_max of the
/// trajectory's own samples (a thirtieth of a dot on a chart 1000 dots wide; measured up to 1.4e-5,
/// Gharib–Hurmuzlu at e = 0.8), on every law, at e = 0.01, 0.2, 0.6, 0.8 and 0.95; an integrated
/// solution draws its own samples exactly.
#[test]
fn drawn_samples_are_the_trajectory_to_far_below_a_dot() {
    use hertz_tui::model::impact::MethodUsed;
    for e in [0.01, 0.2, 0.6, 0.8, 0.95] {
        let p = fig5(e);
        for model in ForceModel::ALL {
            let sol = solve_impact(model, &p, &SolveOptions::default()).unwrap();
            let (s, traj) = (&sol.summary, &sol.trajectory);
            let (drawn, sampled) = (traj.drawn_samples(301), traj.samples(301));
            assert_eq!(drawn.len(), sampled.len(), "{model} e = {e}");
            if s.method != MethodUsed::Exact {
                assert_eq!(drawn, sampled, "{model} e = {e}");
                continue;
            }
            let worst = drawn
                .iter()
                .zip(&sampled)
                .map(|(d, q)| {
                    assert_eq!(d.t, q.t);
                    ((d.x - q.x).abs() / s.x_max)
                        .max((d.v - q.v).abs() / p.v0)
                        .max((d.f - q.f).abs() / s.f_max)
                })
                .fold(0.0, f64::max);
            assert!(worst < 3e-5, "{model} e = {e}: {worst:e}");
        }
    }
}

/// Samples spaced by bounds: consecutive ones at most Δt apart in time and Δx in approach on every
/// law and method, the extrema inserted exactly and the last at the contact's end; the count kept
/// within its bounds when the spacing asks for fewer or more.
#[test]
fn samples_within_bounds_keep_them_and_the_extrema() {
    each_solution(&fig5(0.6), [Method::Dopri5, Method::Rk4], |what, sol| {
        let (s, traj) = (&sol.summary, &sol.trajectory);
        let (dt, dx) = (s.t_contact / 150.0, s.x_max / 70.0);
        let samples = traj.drawn_samples_within(dt, dx, 2..=10_000);
        for w in samples.windows(2) {
            assert!(w[1].t >= w[0].t, "{what}: time order");
            assert!(w[1].t - w[0].t <= dt * (1.0 + 1e-12), "{what}: Δt");
            assert!((w[1].x - w[0].x).abs() <= dx * (1.0 + 1e-9), "{what}: Δx");
        }
        for mark in traj.extrema() {
            assert!(samples.contains(mark), "{what}: {mark:?}");
        }
        let last = samples.last().unwrap();
        assert_eq!((last.t, last.x), (s.t_contact, s.x_residual), "{what}");
        assert!(
            samples.len() < 151 + 70 * 2 * 2,
            "{what}: {}",
            samples.len()
        );
        // Bounds asking for a million samples get the most allowed; asking for none, the
        // fewest (plus the extrema either way, and the steps refined at a steep end: from 1/128
        // of the widest, doubling, 8 a steep end at most).
        let extrema = traj.extrema().len();
        let many = traj.drawn_samples_within(dt * 1e-6, dx, 2..=500).len();
        assert!((500..=501 + extrema).contains(&many), "{what}: {many}");
        let few = traj.drawn_samples_within(1.0, 1.0, 40..=500).len();
        assert!((40..=41 + extrema + 16).contains(&few), "{what}: {few}");
    });
}

/// Where the force rises slower than x from first contact (the proposed model's b·x^½·ẋ, Tsuji's
/// x^¼·ẋ; Kelvin–Voigt's jump c·ẋ) the steps start at 1/128 of the widest and at most double;
/// where it falls so to an end at x = 0 (the laws kept in tension to the last) they halve towards
/// it; Hertz-like laws (F ∝ x^1.5 at both ends) take the widest step from the start.
#[test]
fn steps_are_refined_where_the_force_is_steep_at_an_end() {
    let p = fig5(0.6);
    for (model, start, end) in [
        (ForceModel::Proposed, true, false),
        (ForceModel::with_id("hertz-viscous"), true, false),
        (ForceModel::with_id("hertz-viscous-tension"), true, true),
        (ForceModel::with_id("kelvin-voigt-tension"), true, true),
        (ForceModel::HuntCrossley, false, false),
        (ForceModel::Quasistatic, false, false),
    ] {
        let sol = solve_impact(model, &p, &SolveOptions::default()).unwrap();
        let (s, traj) = (&sol.summary, &sol.trajectory);
        let dt = s.t_contact / 40.0;
        let samples = traj.drawn_samples_within(dt, 1.0, 2..=10_000);
        let steps: Vec<f64> = samples.windows(2).map(|w| w[1].t - w[0].t).collect();
        let (first, widest) = (steps[0], steps.iter().copied().fold(0.0, f64::max));
        assert!(widest <= dt * (1.0 + 1e-12), "{model}");
        if start {
            assert!(first <= widest / 128.0 * (1.0 + 1e-9), "{model}: {first:e}");
            for w in steps.windows(2).take(10) {
                assert!(w[1] <= 2.0 * w[0] * (1.0 + 1e-9), "{model}: {w:?}");
            }
        } else {
            assert!(first > widest / 2.0, "{model}: {first:e}");
        }
        // The step before the last (the last is what is left to the end; the end mark and,
        // after a jump, the curve's own last sample share its time).
        let last = steps
            .iter()
            .rev()
            .filter(|&&h| h > 0.0)
            .nth(1)
            .copied()
            .unwrap();
        if end {
            assert!(last <= widest / 64.0, "{model}: {last:e}");
        } else {
            assert!(last > widest / 64.0, "{model}: {last:e}");
        }
    }
}
