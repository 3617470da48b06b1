//! Test systems shared by the `ode_*` integration tests.

use hertz_tui::model::ode::{Method, OdeSystem, Options, State, integrate};
use nalgebra::Matrix2;

/// ẍ = −ω²x, closed form x = x₀cos ωt + (v₀/ω) sin ωt.
pub struct Harmonic {
    pub omega: f64,
}

impl Harmonic {
    pub fn exact(&self, y0: &State, t: f64) -> State {
        let (s, c) = (self.omega * t).sin_cos();
        State::new(
            y0[0] * c + y0[1] / self.omega * s,
            -y0[0] * self.omega * s + y0[1] * c,
        )
    }

    /// x² + v²/ω², proportional to the energy.
    pub fn energy(&self, y: &State) -> f64 {
        y[0] * y[0] + (y[1] / self.omega).powi(2)
    }
}

impl OdeSystem for Harmonic {
    fn rhs(&mut self, _t: f64, y: &State) -> State {
        State::new(y[1], -self.omega * self.omega * y[0])
    }

    fn jacobian(&mut self, _t: f64, _y: &State) -> Matrix2<f64> {
        Matrix2::new(0.0, 1.0, -self.omega * self.omega, 0.0)
    }
}

/// ẍ = −x·|x|^{1/2}: energy-conserving, and only C^{1,1/2} in x at x = 0 (like Hertz contact).
pub struct Nonlinear;

impl OdeSystem for Nonlinear {
    fn rhs(&mut self, _t: f64, y: &State) -> State {
        State::new(y[1], -y[0] * y[0].abs().sqrt())
    }
}

/// Damped Hertz contact ẍ = −k·x^{3/2} − b·x^{1/2}·ẋ (x ≥ 0; the force is taken as 0 for x < 0).
pub struct DampedHertz {
    pub k: f64,
    pub b: f64,
}

impl OdeSystem for DampedHertz {
    fn rhs(&mut self, _t: f64, y: &State) -> State {
        let x = y[0].max(0.0);
        let r = x.sqrt();
        State::new(y[1], -self.k * x * r - self.b * r * y[1])
    }
}

/// ẍ = −sign(ẋ)·c − x (dry friction on a unit spring). `branch` fixes sign(ẋ) for one phase;
/// `None` evaluates the sign from the state (discontinuous right-hand side).
pub struct Friction {
    pub c: f64,
    pub branch: Option<f64>,
}

impl OdeSystem for Friction {
    fn rhs(&mut self, _t: f64, y: &State) -> State {
        let s = self.branch.unwrap_or(if y[1] > 0.0 {
            1.0
        } else if y[1] < 0.0 {
            -1.0
        } else {
            0.0
        });
        State::new(y[1], -s * self.c - y[0])
    }
}

/// The state at t_max from (0, y0), panicking on error (tests only).
pub fn solve(method: Method, sys: &mut dyn OdeSystem, y0: State, opts: &Options) -> State {
    match integrate(method, sys, 0.0, y0, &[], opts) {
        Ok(r) => r.y,
        Err(e) => panic!("{method}: {e}"),
    }
}

/// Options of a fixed-step run to t_max.
pub fn fixed(dt: f64, t_max: f64) -> Options {
    Options {
        dt: Some(dt),
        t_max,
        max_steps: 10_000_000,
        ..Options::default()
    }
}

/// Options of an adaptive run to t_max.
pub fn adaptive(rtol: f64, atol: f64, t_max: f64) -> Options {
    Options {
        rtol,
        atol,
        t_max,
        max_steps: 1_000_000,
        ..Options::default()
    }
}

/// log₂ of the ratio of consecutive errors: the observed order when the step halves.
pub fn observed_orders(errors: &[f64]) -> Vec<f64> {
    errors.windows(2).map(|w| (w[0] / w[1]).log2()).collect()
}
