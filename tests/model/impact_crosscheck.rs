//! The proposed model (eq 18), which has no closed form, against an independent implementation:
//! the `differential-equations` crate's DOP853 on the same equations written out in SI units, with
//! its own event location for ẋ = 0 and F = 0.

use differential_equations::prelude::*;
use hertz_tui::model::PowerLaw;
use hertz_tui::model::force::{ForceModel, ImpactParams};
use hertz_tui::model::impact::{ImpactSummary, MethodChoice, SolveOptions, solve_impact};
use hertz_tui::model::ode::Method;

/// m·ẍ = −(k·xⁿ + b·xⁿ⁻¹·ẋ) in SI units, b = k·x_pl/(v₀e) (eq 18), with x clamped at 0 so
/// the external solver never takes a power of a negative number.
struct Proposed {
    m: f64,
    k: f64,
    n: f64,
    b: f64,
}

impl Proposed {
    fn new(p: &ImpactParams) -> Self {
        Proposed {
            m: p.mass,
            k: p.law.k,
            n: p.law.n,
            b: p.law.k * p.plastic_indentation / (p.v0 * p.restitution),
        }
    }

    fn force(&self, x: f64, v: f64) -> f64 {
        let x = x.max(0.0);
        self.k * x.powf(self.n) + self.b * x.powf(self.n - 1.0) * v
    }
}

impl ODE<f64, [f64; 2]> for Proposed {
    fn diff(&self, _t: f64, y: &[f64; 2], dydt: &mut [f64; 2]) {
        dydt[0] = y[1];
        dydt[1] = -self.force(y[0], y[1]) / self.m;
    }
}

/// ẋ falls through 0: maximum compression.
struct AtRest;

impl Event<f64, [f64; 2]> for AtRest {
    fn config(&self) -> EventConfig {
        EventConfig::new(CrossingDirection::Negative, Some(1))
    }

    fn event(&self, _t: f64, y: &[f64; 2]) -> f64 {
        y[1]
    }
}

/// k·x + b·ẋ (F/xⁿ⁻¹) falls through 0: the proposed model's end of contact.
struct ForceZero {
    k: f64,
    b: f64,
}

impl Event<f64, [f64; 2]> for ForceZero {
    fn config(&self) -> EventConfig {
        EventConfig::new(CrossingDirection::Negative, Some(1))
    }

    fn event(&self, _t: f64, y: &[f64; 2]) -> f64 {
        self.k * y[0] + self.b * y[1]
    }
}

/// Our tolerance.
const RTOL: f64 = 1e-12;
/// The external solver's: its global error at equal rtol is a few times ours (1e-8 in v_out at
/// 1e-12 on Fig. 5, 3e-9 at 1e-13), so it gets one more digit.
const EXTERNAL_RTOL: f64 = 1e-13;
/// Absolute tolerance in SI: x ~ 1e-6 m, so 1e-23 keeps rtol in charge.
const ATOL: f64 = 1e-23;

/// (t_x_max, x_max, t_contact, x_end, v_end) from the external DOP853.
fn external(p: &ImpactParams) -> (f64, f64, f64, f64, f64) {
    let ode = Proposed::new(p);
    let t_far = 100.0 * p.law.contact_time(p.mass, p.v0);
    let loading = IVP::ode(&ode, 0.0, t_far, [0.0, p.v0])
        .event(&AtRest)
        .method(ExplicitRungeKutta::dop853().rtol(EXTERNAL_RTOL).atol(ATOL))
        .solve()
        .expect("external loading");
    let (&t1, y1) = loading.last().expect("loading output");
    let stop = ForceZero { k: ode.k, b: ode.b };
    let unloading = IVP::ode(&ode, t1, t_far, [y1[0], 0.0])
        .event(&stop)
        .method(ExplicitRungeKutta::dop853().rtol(EXTERNAL_RTOL).atol(ATOL))
        .solve()
        .expect("external unloading");
    let (&t2, y2) = unloading.last().expect("unloading output");
    (t1, y1[0], t2, y2[0], y2[1])
}

/// External F at three times around `t` on loading (before `t_end`).
fn external_forces_around(p: &ImpactParams, t: f64, dt: f64) -> [f64; 3] {
    let ode = Proposed::new(p);
    let times = [t - dt, t, t + dt];
    let sol = IVP::ode(&ode, 0.0, t + 2.0 * dt, [0.0, p.v0])
        .t_eval(times)
        .method(ExplicitRungeKutta::dop853().rtol(EXTERNAL_RTOL).atol(ATOL))
        .solve()
        .expect("external dense");
    let forces: Vec<f64> = sol.iter().map(|(_, y)| ode.force(y[0], y[1])).collect();
    [forces[0], forces[1], forces[2]]
}

fn ours(p: &ImpactParams, method: MethodChoice) -> ImpactSummary {
    let opts = SolveOptions {
        method,
        rtol: RTOL,
        atol: Some(1e-14),
        ..SolveOptions::default()
    };
    solve_impact(ForceModel::Proposed, p, &opts)
        .unwrap()
        .summary
}

fn rel(a: f64, b: f64) -> f64 {
    (a / b - 1.0).abs()
}

fn scenes() -> Vec<ImpactParams> {
    let fig5 = ImpactParams {
        mass: 0.033,
        law: PowerLaw {
            k: 1.465e10,
            n: 1.5,
        },
        v0: 0.3,
        restitution: 0.6,
        plastic_indentation: 2.3e-6,
        contact: hertz_tui::model::force::Contact::Unspecified,
    };
    vec![
        fig5,
        ImpactParams {
            restitution: 0.2,
            plastic_indentation: 4e-6,
            ..fig5
        },
        // Table 2's cylinder on a plate.
        ImpactParams {
            mass: 1.0,
            law: PowerLaw {
                k: 1.91e9,
                n: 1.081,
            },
            v0: 0.5,
            restitution: 0.7,
            plastic_indentation: 3e-6,
            contact: hertz_tui::model::force::Contact::Unspecified,
        },
    ]
}

#[test]
fn proposed_model_agrees_with_an_independent_dop853() {
    for p in scenes() {
        let (t1, x1, t2, x2, v2) = external(&p);
        for method in [
            MethodChoice::Auto,
            MethodChoice::Integrator(Method::Dopri5),
            MethodChoice::Integrator(Method::Dop853),
        ] {
            let s = ours(&p, method);
            let what = format!("{method} n = {} e = {}", p.law.n, p.restitution);
            assert!(
                rel(s.x_max, x1) < 1e-8,
                "{what}: x_max {:e} vs {x1:e}",
                s.x_max
            );
            assert!(rel(s.t_x_max, t1) < 1e-8, "{what}: t_x_max");
            assert!(
                rel(s.t_contact, t2) < 1e-8,
                "{what}: t_contact {:e} vs {t2:e}",
                s.t_contact
            );
            // x at the end moves at v_out: an event-time difference of 1e-9·t_c shifts it by
            // ~1e-8 of itself, so it is compared on the scale of x_max.
            assert!(
                (s.x_residual - x2).abs() < 1e-8 * x1,
                "{what}: residual {:e} vs {x2:e}",
                s.x_residual
            );
            assert!(
                rel(s.v_out, -v2) < 1e-8,
                "{what}: v_out {} vs {}",
                s.v_out,
                -v2
            );
        }
    }
}

#[test]
fn the_force_peak_is_a_peak_of_the_independent_solution() {
    // Our F_max sits where dF/dt = 0 on our dense output; on the external solution, F there must
    // agree to 1e-8 and exceed F a little before and after.
    for p in scenes() {
        let s = ours(&p, MethodChoice::Integrator(Method::Dop853));
        let dt = 1e-3 * s.t_f_max;
        let [before, at, after] = external_forces_around(&p, s.t_f_max, dt);
        assert!(rel(s.f_max, at) < 1e-8, "{} vs {at}", s.f_max);
        assert!(at > before && at > after, "{before} {at} {after}");
    }
}

#[test]
fn radau5_agrees_with_the_independent_dop853() {
    // Radau5 scales rtol as Hairer's RADAU5 does (rtol' ≈ 0.1·rtol^{2/3}), so it is held to 1e-7.
    let p = &scenes()[0];
    let (_, x1, t2, x2, v2) = external(p);
    let s = ours(p, MethodChoice::Integrator(Method::Radau5));
    for (a, b) in [(s.x_max, x1), (s.t_contact, t2), (s.v_out, -v2)] {
        assert!(rel(a, b) < 1e-7, "{a:e} vs {b:e}");
    }
    assert!((s.x_residual - x2).abs() < 1e-7 * x1);
}
