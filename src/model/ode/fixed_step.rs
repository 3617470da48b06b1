//! Fixed-step methods: explicit Euler, symplectic Euler, velocity Verlet and classic RK4.
//!
//! Steps are t_n = t₀ + n·dt (computed from n, not accumulated, so rounding does not drift the
//! grid). The last step is *not* shortened to land on `t_max`: it is taken whole and the final
//! state is read from its interpolant at `t_max` — the methods are compared at their own step.
//! Dense output is the cubic Hermite interpolant of each step's end states and derivatives.
//!
//! Symplectic Euler and Verlet are splitting methods for ẋ = v, v̇ = a(t, x, v): they update x
//! from v themselves and read only the acceleration component f(t, y)[1] of the system.

use super::dense::monotone_slopes;
use super::driver::{Scheme, Step};
use super::step_control::{is_finite, rhs};
use super::{OdeError, OdeSystem, Options, Segment, State, Stats};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum FixedKind {
    Euler,
    SymplecticEuler,
    Verlet,
    Rk4,
}

pub(super) struct FixedStep {
    kind: FixedKind,
    t0: f64,
    dt: f64,
    /// Index n of the current step start t_n.
    n: u64,
    /// f(t_n, y_n), reused as the next step's first stage and the Hermite start slope.
    f: State,
    max_steps: usize,
}

impl FixedStep {
    pub(super) fn new(
        kind: FixedKind,
        sys: &mut dyn OdeSystem,
        stats: &mut Stats,
        t0: f64,
        y0: &State,
        dt: f64,
        opts: &Options,
    ) -> Result<Self, OdeError> {
        let f = rhs(sys, stats, t0, y0);
        if !is_finite(&f) {
            return Err(OdeError::NonFinite { t: t0 });
        }
        Ok(FixedStep {
            kind,
            t0,
            dt,
            n: 0,
            f,
            max_steps: opts.max_steps,
        })
    }
}

/// Explicit (forward) Euler, order 1 (Hairer–Nørsett–Wanner I, §I.7).
fn euler(y: &State, f: &State, h: f64) -> State {
    y + f * h
}

/// Semi-implicit (symplectic) Euler, order 1 (Hairer–Lubich–Wanner, Geometric Numerical
/// Integration, §I.1.2): v first with the acceleration at the step start, then x with the new v.
fn symplectic_euler(y: &State, f: &State, h: f64) -> State {
    let v1 = y[1] + h * f[1];
    State::new(y[0] + h * v1, v1)
}

/// Velocity Verlet, order 2 (Hairer–Lubich–Wanner, Geometric Numerical Integration, §I.1.4).
/// For an acceleration that depends on v, the end-of-step acceleration is evaluated with the
/// predicted velocity v₀ + h·a₀ (an O(h²) predictor, so the method stays second order); for
/// a = a(t, x) this is exactly the classical scheme. Costs one extra rhs evaluation per step.
fn verlet(
    sys: &mut dyn OdeSystem,
    stats: &mut Stats,
    t: f64,
    y: &State,
    f: &State,
    h: f64,
) -> State {
    let a0 = f[1];
    let x1 = y[0] + h * y[1] + 0.5 * h * h * a0;
    let v_pred = y[1] + h * a0;
    let a1 = rhs(sys, stats, t + h, &State::new(x1, v_pred))[1];
    State::new(x1, y[1] + 0.5 * h * (a0 + a1))
}

/// Classic Runge–Kutta, order 4 (Hairer–Nørsett–Wanner I, §II.1, Table 1.2).
fn rk4(sys: &mut dyn OdeSystem, stats: &mut Stats, t: f64, y: &State, k1: &State, h: f64) -> State {
    let k2 = rhs(sys, stats, t + 0.5 * h, &(y + k1 * (0.5 * h)));
    let k3 = rhs(sys, stats, t + 0.5 * h, &(y + k2 * (0.5 * h)));
    let k4 = rhs(sys, stats, t + h, &(y + k3 * h));
    y + (k1 + (k2 + k3) * 2.0 + k4) * (h / 6.0)
}

impl Scheme for FixedStep {
    fn step(
        &mut self,
        sys: &mut dyn OdeSystem,
        t: f64,
        y: &State,
        stats: &mut Stats,
    ) -> Result<Step, OdeError> {
        // Fixed steps are never rejected, so the budget counts accepted steps only.
        if stats.steps >= self.max_steps {
            return Err(OdeError::StepBudgetExhausted {
                t,
                steps: self.max_steps,
            });
        }
        let t_new = self.t0 + (self.n + 1) as f64 * self.dt;
        let h = t_new - t;
        let f0 = self.f;
        let y_new = match self.kind {
            FixedKind::Euler => euler(y, &f0, h),
            FixedKind::SymplecticEuler => symplectic_euler(y, &f0, h),
            FixedKind::Verlet => verlet(sys, stats, t, y, &f0, h),
            FixedKind::Rk4 => rk4(sys, stats, t, y, &f0, h),
        };
        if !is_finite(&y_new) {
            return Err(OdeError::NonFinite { t: t_new });
        }
        let f_new = rhs(sys, stats, t_new, &y_new);
        if !is_finite(&f_new) {
            return Err(OdeError::NonFinite { t: t_new });
        }
        stats.steps += 1;
        self.n += 1;
        self.f = f_new;
        Ok(Step {
            t: t_new,
            y: y_new,
            segment: {
                let (f0, f1) = monotone_slopes(h, (y, &y_new), (f0, f_new), false);
                Segment::Hermite {
                    t0: t,
                    h,
                    y0: *y,
                    y1: y_new,
                    f0,
                    f1,
                }
            },
        })
    }
}
