//! Cross-check of DOPRI5 and DOP853 against an independent implementation, the
//! `differential-equations` crate's DOP853, on a damped Hertz contact without closed form:
//! ẍ = −k·x^{3/2} − b·x^{1/2}·ẋ from x = 0, ẋ = v₀ until contact ends (x returns to 0).

use differential_equations::prelude::{ExplicitRungeKutta, IVP, ODE};
use hertz_tui::model::ode::{Direction, Event, Method, OdeSystem, Options, State, Stop, integrate};

use crate::ode_common::DampedHertz;

const K: f64 = 1.0;
const B: f64 = 0.5;

struct Reference;

impl ODE<f64, [f64; 2]> for Reference {
    fn diff(&self, t: f64, y: &[f64; 2], dydt: &mut [f64; 2]) {
        let f = DampedHertz { k: K, b: B }.rhs(t, &State::new(y[0], y[1]));
        *dydt = [f[0], f[1]];
    }
}

fn x_of(_t: f64, y: &State) -> f64 {
    y[0]
}

#[test]
fn dopri5_and_dop853_agree_with_an_independent_dop853() {
    let y0 = State::new(0.0, 1.0);
    let events = [Event {
        g: &x_of,
        direction: Direction::Falling,
    }];
    // (method, rtol, agreement required; measured 6e-11 and 3e-13)
    let ours: Vec<_> = [
        (Method::Dopri5, 1e-12, 1e-9),
        (Method::Dop853, 1e-13, 1e-11),
    ]
    .into_iter()
    .map(|(method, rtol, tol)| {
        let opts = Options {
            rtol,
            atol: 1e-15,
            t_max: 100.0,
            ..Options::default()
        };
        let r = integrate(
            method,
            &mut DampedHertz { k: K, b: B },
            0.0,
            y0,
            &events,
            &opts,
        )
        .expect("integration");
        assert_eq!(
            r.stop,
            Stop::Event { index: 0 },
            "{method}: contact must end"
        );
        (method, r, tol)
    })
    .collect();
    let t_c = ours[1].1.t;
    // The reference's own step points up to our end of contact. (Its `t_eval` interpolation is
    // less accurate than its steps — ~1e-9 off here — so the comparison uses the steps, and our
    // dense output, which is accurate to the tolerance, at their times.)
    let solution = IVP::ode(&Reference, 0.0, t_c, [0.0, 1.0])
        .method(ExplicitRungeKutta::dop853().rtol(1e-13).atol(1e-15))
        .solve()
        .expect("reference solve");
    assert!(solution.t.len() > 10);
    let x_max = ours[1]
        .1
        .dense
        .segments()
        .iter()
        .map(|s| s.y_end()[0])
        .fold(0.0, f64::max);
    for (method, r, tol) in &ours {
        let mut worst: f64 = 0.0;
        for (t, y) in solution.t.iter().zip(&solution.y) {
            let mine = r.dense.eval(*t);
            worst = worst
                .max((mine[0] - y[0]).abs() / x_max)
                .max((mine[1] - y[1]).abs());
        }
        eprintln!("{method}: worst difference {worst:.2e} (x relative to x_max, v relative to v₀)");
        assert!(worst < *tol, "{method}: differs by {worst:.2e}");
        // Our end of contact is a zero of the reference solution too.
        let (_, y_end) = solution.last().expect("reference end");
        assert!(
            y_end[0].abs() < 1e-9 * x_max,
            "{method}: reference x(t_c) = {}",
            y_end[0]
        );
        assert!(
            (r.t - t_c).abs() < 1e-9 * t_c,
            "{method}: t_c = {} vs {t_c}",
            r.t
        );
    }
    // The impact is dissipative: exit speed below entry speed.
    assert!(ours[1].1.y[1] < 0.0 && ours[1].1.y[1] > -1.0);
}
