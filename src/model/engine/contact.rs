//! The normal contact laws engines integrate, written in one form, and their impact solved with
//! hertz-tui's own integrator (DOP853) or exact solution (docs/physics.md §7).
//!
//! Every engine below integrates F = k·xⁿ + c(x)·ẋ for x > 0 (or k·xⁿ·(1 + α·ẋ), the Hunt–Crossley
//! form), and ends contact either where x returns to 0 (tension allowed) or where F falls to 0
//! (the force clamped at F ≥ 0, which separates the bodies early with x > 0 left).

use serde::Serialize;

use crate::model::exact::hysteresis::hysteresis;
use crate::model::force::ImpactParams;
use crate::model::numeric::roots::brent_max;
use crate::model::ode::{self, Direction, Event, Method, OdeError, OdeSystem, State};
use crate::model::power_law::PowerLaw;

use super::error::EngineError;

/// Where an engine's contact ends.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum EndRule {
    /// The force is clamped at F ≥ 0: contact ends where F falls to 0, with x > 0 left.
    Clamp,
    /// Tension allowed: contact ends where the approach x returns to 0.
    Tension,
}

impl EndRule {
    /// The rule as a translation states it.
    pub fn describe(self) -> &'static str {
        match self {
            EndRule::Clamp => "F ≥ 0 clamp: contact ends where F falls to 0",
            EndRule::Tension => "tension allowed: contact ends where x returns to 0",
        }
    }
}

/// The dissipative part of an engine's normal force: a form with its coefficients, not a table law's
/// damping parameter ([`crate::model::force::Damping`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum EngineDamping {
    /// k·xⁿ·α·ẋ: the Hunt–Crossley family (eq 19), α in s/m.
    HuntCrossley {
        /// α, s/m.
        alpha: f64,
    },
    /// c·x^p·ẋ: linear (p = 0) or Tsuji's Hertzian (p = 1/4) viscous damping, c in N·s/m^{1+p}.
    Viscous {
        /// c, N·s/m^{1+p}.
        c: f64,
        /// The exponent p of x.
        p: f64,
    },
    /// c_max·STEP(x; 0, 0, d, 1)·ẋ: Adams' IMPACT damping, reaching c_max (N·s/m) at penetration d.
    Step {
        /// c_max, N·s/m.
        c_max: f64,
        /// Penetration d at which the damping reaches c_max, m.
        depth: f64,
    },
}

/// One engine's normal contact law: F = k·xⁿ plus `damping`, ending by `end`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactLaw {
    /// Elastic law F = k·xⁿ.
    pub elastic: PowerLaw,
    /// The dissipative part.
    pub damping: EngineDamping,
    /// How contact ends.
    pub end: EndRule,
}

/// Adams' cubic STEP from 0 at u = 0 to 1 at u = 1: u²(3 − 2u), held at 1 beyond.
pub fn cubic_step(u: f64) -> f64 {
    let u = u.clamp(0.0, 1.0);
    u * u * (3.0 - 2.0 * u)
}

impl ContactLaw {
    /// F(x, ẋ) before the end rule, N; powers continued oddly to x < 0 for integrator stages
    /// evaluated just past the end of contact.
    pub fn force(&self, x: f64, v: f64) -> f64 {
        let PowerLaw { k, n } = self.elastic;
        let elastic = k * x.signum() * x.abs().powf(n);
        match self.damping {
            EngineDamping::HuntCrossley { alpha } => elastic * (1.0 + alpha * v),
            EngineDamping::Viscous { c, p } => elastic + c * x.abs().powf(p) * v,
            EngineDamping::Step { c_max, depth } => elastic + c_max * cubic_step(x / depth) * v,
        }
    }

    /// A function with the sign of F that stays regular as x → 0⁺ (F over a power of x): the
    /// clamp ends contact where it falls through 0.
    fn tension(&self, x: f64, v: f64) -> f64 {
        let PowerLaw { k, n } = self.elastic;
        if x <= 0.0 {
            return k;
        }
        match self.damping {
            EngineDamping::HuntCrossley { alpha } => 1.0 + alpha * v,
            EngineDamping::Viscous { c, p } => k * x.powf(n - p) + c * v,
            EngineDamping::Step { c_max, depth } => {
                k + c_max * cubic_step(x / depth) * v / x.powf(n)
            }
        }
    }

    /// ∂F/∂x at (x, 0), N/m: the stiffness an explicit integrator's step must resolve.
    fn tangent_stiffness(&self, x: f64) -> f64 {
        self.elastic.tangent_stiffness(x)
    }
}

/// What an engine's law gives for one impact, SI units.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct EngineImpact {
    /// Realised restitution v_out/v₀.
    pub e_out: f64,
    /// Peak force, N.
    pub f_max: f64,
    /// Duration of contact, s.
    pub t_contact: f64,
    /// Maximum approach, m.
    pub x_max: f64,
    /// Approach left when contact ends (> 0 where the clamp ended it), m.
    pub x_residual: f64,
    /// Largest stable step of an explicit integrator, s: h·ω_max < 2 (symplectic Euler, velocity
    /// Verlet) with ω_max = √(max ∂F/∂x / m) at x_max; damping ignored.
    pub dt_stable: f64,
}

/// Relative tolerance of the engine solves: far below the 1e-8 the calibration promises.
const RTOL: f64 = 1e-12;

/// Solves the impact of `law` on reduced mass `mass` hitting at `v0`: the exact solution for the
/// Hunt–Crossley form (which never turns tensile, so either end rule gives it) where it comes out
/// finite, else DOP853 at rtol 1e-12 in two phases joined at maximum compression.
pub fn solve(law: &ContactLaw, mass: f64, v0: f64) -> Result<EngineImpact, EngineError> {
    match exact(law, mass, v0)? {
        Some(impact) => Ok(impact),
        None => integrate(law, mass, v0),
    }
}

/// The exact impact of the Hunt–Crossley form; `None` for other laws or where the closed form
/// loses finiteness (χ near 1/e for e → 0).
fn exact(law: &ContactLaw, mass: f64, v0: f64) -> Result<Option<EngineImpact>, EngineError> {
    if let EngineDamping::HuntCrossley { alpha } = law.damping {
        let params = ImpactParams {
            mass,
            law: law.elastic,
            v0,
            restitution: 1.0,
            plastic_indentation: 0.0,
            contact: crate::model::force::Contact::Unspecified,
        };
        params.validate()?;
        return Ok(hysteresis(&params, alpha, RTOL)
            .filter(|x| x.is_valid() && x.t_contact > 0.0 && x.v_out > 0.0)
            .map(|exact| EngineImpact {
                e_out: exact.v_out / v0,
                f_max: exact.f_max,
                t_contact: exact.t_contact,
                x_max: exact.x_max,
                x_residual: exact.x_residual,
                dt_stable: stable_step(law, mass, exact.x_max),
            }));
    }
    Ok(None)
}

/// 2/ω_max, ω_max² = ∂F/∂x(x_max)/m.
fn stable_step(law: &ContactLaw, mass: f64, x_max: f64) -> f64 {
    2.0 / (law.tangent_stiffness(x_max) / mass).sqrt()
}

/// m·ẍ = −F(x, ẋ) in X = x/x_e, V = v/v₀, T = t·v₀/x_e (x_e the elastic x_max).
struct Scaled<'a> {
    law: &'a ContactLaw,
    x_ref: f64,
    v_ref: f64,
    /// x_e/(m·v₀²): dV/dT = −accel·F.
    accel: f64,
}

impl OdeSystem for Scaled<'_> {
    fn rhs(&mut self, _t: f64, y: &State) -> State {
        let f = self.law.force(y[0] * self.x_ref, y[1] * self.v_ref);
        State::new(y[1], -self.accel * f)
    }
}

fn integrate(law: &ContactLaw, mass: f64, v0: f64) -> Result<EngineImpact, EngineError> {
    let x_ref = law.elastic.max_approach(mass, v0);
    let t_ref = x_ref / v0;
    if !(x_ref.is_finite() && x_ref > 0.0 && t_ref.is_finite() && t_ref > 0.0) {
        return Err(EngineError::NonFinite);
    }
    let mut sys = Scaled {
        law,
        x_ref,
        v_ref: v0,
        accel: x_ref / (mass * v0 * v0),
    };
    let opts = ode::Options {
        rtol: RTOL,
        atol: 1e-14,
        t_max: 1e3,
        // Well inside the elastic contact (≈ 3 in these units): Hairer's starting-step guess sees
        // F(0, v₀) = 0 and overshoots into stiff damping.
        h_initial: Some(1e-4),
        max_steps: 1_000_000,
        ..ode::Options::default()
    };
    let velocity_zero = |_t: f64, y: &State| y[1];
    let loading = ode::integrate(
        Method::Dop853,
        &mut sys,
        0.0,
        State::new(0.0, 1.0),
        &[Event {
            g: &velocity_zero,
            direction: Direction::Falling,
        }],
        &opts,
    )?;
    require_event(&loading, t_ref)?;
    let approach_zero = |_t: f64, y: &State| y[0];
    let force_zero = |_t: f64, y: &State| law.tension(y[0] * x_ref, y[1] * v0);
    let mut events = vec![Event {
        g: &approach_zero,
        direction: Direction::Falling,
    }];
    if law.end == EndRule::Clamp {
        events.push(Event {
            g: &force_zero,
            direction: Direction::Falling,
        });
    }
    let unloading = ode::integrate(
        Method::Dop853,
        &mut sys,
        loading.t,
        loading.y,
        &events,
        &opts,
    )?;
    require_event(&unloading, t_ref)?;
    let force_at = |t: f64, dense: &ode::DenseOutput| {
        let y = dense.eval(t);
        law.force(y[0] * x_ref, y[1] * v0).max(0.0)
    };
    let f_max = [&loading.dense, &unloading.dense]
        .into_iter()
        .map(|dense| peak(dense, |t| force_at(t, dense)))
        .fold(0.0, f64::max);
    let x_max = loading.y[0] * x_ref;
    let e_out = -unloading.y[1];
    Ok(EngineImpact {
        e_out,
        f_max,
        t_contact: unloading.t * t_ref,
        x_max,
        x_residual: unloading.y[0].max(0.0) * x_ref,
        dt_stable: stable_step(law, mass, x_max),
    })
}

/// An integration that hit its time limit instead of an event: contact never ended.
fn require_event(run: &ode::Integration, t_ref: f64) -> Result<(), EngineError> {
    match run.stop {
        ode::Stop::Event { .. } => Ok(()),
        ode::Stop::TimeLimit => Err(EngineError::NoSeparation {
            t_limit: run.t * t_ref,
        }),
    }
}

/// The largest value of `f` over a dense output: the best of 16 samples per step, refined by
/// Brent's maximisation between its neighbours.
fn peak(dense: &ode::DenseOutput, f: impl Fn(f64) -> f64) -> f64 {
    let mut best = (dense.t_start(), f(dense.t_start()));
    let mut grid = vec![dense.t_start()];
    for segment in dense.segments() {
        let (a, b) = (segment.t_start(), segment.t_end());
        grid.extend((1..=16).map(|i| a + (b - a) * i as f64 / 16.0));
    }
    let mut at = 0;
    for (i, &t) in grid.iter().enumerate() {
        let value = f(t);
        if value > best.1 {
            best = (t, value);
            at = i;
        }
    }
    let lo = grid[at.saturating_sub(1)];
    let hi = grid[(at + 1).min(grid.len() - 1)];
    if hi > lo {
        let (_, refined) = brent_max(&f, lo, hi);
        best.1 = best.1.max(refined);
    }
    best.1
}

impl From<OdeError> for EngineError {
    fn from(source: OdeError) -> Self {
        EngineError::Integration(source)
    }
}
