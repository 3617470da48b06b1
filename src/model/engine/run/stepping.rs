//! hertz-tui's model of an engine's time stepping through one impact (docs/engines.md, "Time
//! steps"): the engine's force law F(x, ẋ) stepped as the engine steps it, measured as the
//! printed script measures it.
//!
//! x is the approach (penetration), ẋ its rate (> 0 closing), F the repulsive normal force on the
//! reduced mass m, as the engine computes it (negative where the engine lets the contact pull).
//! The impact starts half a step before touch, x = −v₀·h/2 ([`start_gap`]), as the scripts
//! place the bodies: then the first step in contact is the same in every engine, whatever each
//! does with two bodies exactly touching. The measured numbers are those of the scripts:
//! e = −ẋ/v₀ once the bodies have parted, F_max the largest force of any step, and the contact
//! time the number of steps that computed a nonzero force times h.

use serde::Serialize;

use crate::model::numeric::roots::brent;

use super::super::error::EngineError;

/// How an engine advances one step of length h.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Scheme {
    /// MuJoCo's `Euler` integrator (semi-implicit Euler): the force from (xₙ, ẋₙ),
    /// ẋₙ₊₁ = ẋₙ − h·F/m, xₙ₊₁ = xₙ + h·ẋₙ₊₁; a contact exists while xₙ > 0 (MuJoCo
    /// doc/computation.rst, "Numerical integration"; checked against MuJoCo 4.0 to 1e-12).
    SemiImplicitEuler,
    /// Velocity Verlet as LAMMPS and LIGGGHTS `fix nve/sphere` and Yade's leapfrog
    /// `NewtonIntegrator` do it: the force from xₙ₊₁ and the half-step velocity ẋₙ₊½ (the velocity
    /// the pair style sees); a contact exists while x > 0.
    VelocityVerlet,
    /// Drake's discrete approximations (TAMSI, Similar, Lagged, SAP) for one frictionless point
    /// contact: implicit Euler, m(ẋₙ₊₁ − ẋₙ) = −h·F(xₙ + h·ẋₙ₊₁, ẋₙ₊₁)₊, xₙ₊₁ = xₙ + h·ẋₙ₊₁;
    /// a contact exists while xₙ ≥ 0 (checked against Drake 1.51 to 1e-11).
    ImplicitEuler,
}

impl Scheme {
    /// The scheme in words, with the engines that use it.
    pub fn describe(self) -> &'static str {
        match self {
            Scheme::SemiImplicitEuler => "semi-implicit Euler (MuJoCo's Euler integrator)",
            Scheme::VelocityVerlet => {
                "velocity Verlet, force from the half-step velocity (LAMMPS, LIGGGHTS, Yade)"
            }
            Scheme::ImplicitEuler => {
                "implicit Euler on the contact force (Drake's discrete TAMSI, Similar, Lagged, SAP)"
            }
        }
    }
}

/// One impact stepped at a fixed h, measured as the printed scripts measure it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SteppedImpact {
    /// The step, s.
    pub step: f64,
    /// Restitution −ẋ/v₀ after the bodies part.
    pub e_out: f64,
    /// The largest force of any step, N.
    pub f_max: f64,
    /// Steps with a nonzero force, times h, s.
    pub t_contact: f64,
}

/// Steps allowed per elastic contact time before the impact counts as never ending.
const MAX_STEPS_PER_CONTACT: f64 = 200.0;

/// The gap the scripts leave between the bodies at the start, m: half a step of travel.
pub fn start_gap(v0: f64, h: f64) -> f64 {
    0.5 * v0 * h
}

/// Steps the impact of `force` on reduced mass `mass` at `v0` with step `h` by `scheme`, from
/// the approach `x0` (−[`start_gap`] as the scripts start, 0 at touch); `t_scale` (the continuous
/// contact time) bounds the run at 200 contact times.
pub fn step_impact(
    scheme: Scheme,
    force: &dyn Fn(f64, f64) -> f64,
    mass: f64,
    v0: f64,
    h: f64,
    x0: f64,
    t_scale: f64,
) -> Result<SteppedImpact, EngineError> {
    if !(h > 0.0 && h.is_finite() && mass > 0.0 && v0 > 0.0 && t_scale > 0.0) {
        return Err(EngineError::SteppingNonFinite);
    }
    let max_steps = (MAX_STEPS_PER_CONTACT * t_scale / h).ceil().min(1e8) as u64;
    let (mut x, mut v) = (x0, v0);
    let (mut f_max, mut steps_in_contact) = (0.0_f64, 0_u64);
    let mut touched = false;
    // A contact force only where the engine has a contact, 0 elsewhere.
    let open = |x: f64, v: f64| if x > 0.0 { force(x, v) } else { 0.0 };
    let mut f_prev = 0.0; // velocity Verlet: the force computed at the end of the last step
    for _ in 0..max_steps {
        let f = match scheme {
            Scheme::SemiImplicitEuler => {
                let f = open(x, v);
                v -= h * f / mass;
                x += h * v;
                f
            }
            Scheme::VelocityVerlet => {
                let half = v - 0.5 * h * f_prev / mass;
                x += h * half;
                let f = open(x, half);
                v = half - 0.5 * h * f / mass;
                f_prev = f;
                f
            }
            Scheme::ImplicitEuler => {
                let f = if x >= 0.0 {
                    implicit_force(force, mass, x, v, h)?
                } else {
                    0.0
                };
                v -= h * f / mass;
                x += h * v;
                f
            }
        };
        if !(x.is_finite() && v.is_finite() && f.is_finite()) {
            return Err(EngineError::SteppingNonFinite);
        }
        if f != 0.0 {
            steps_in_contact += 1;
            touched = true;
        }
        f_max = f_max.max(f);
        // Parted: no contact left and moving apart (no force acts from here on).
        if touched && x <= 0.0 && v < 0.0 {
            return Ok(SteppedImpact {
                step: h,
                e_out: -v / v0,
                f_max,
                t_contact: steps_in_contact as f64 * h,
            });
        }
    }
    Err(EngineError::SteppingNoSeparation {
        t_limit: max_steps as f64 * h,
    })
}

/// The force F(xₙ + h·u, u)₊ at the new velocity u that solves m(u − ẋₙ) + h·F(xₙ + h·u, u)₊ = 0.
/// The residual rises with u (F rises with x and ẋ), is ≥ 0 at u = ẋₙ and ≤ 0 at
/// u = ẋₙ − h·F(xₙ + h·ẋₙ, ẋₙ)₊/m, so Brent's method brackets the root.
fn implicit_force(
    force: &dyn Fn(f64, f64) -> f64,
    mass: f64,
    x: f64,
    v: f64,
    h: f64,
) -> Result<f64, EngineError> {
    let clamped = |u: f64| force(x + h * u, u).max(0.0);
    let at_v = clamped(v);
    if at_v == 0.0 {
        return Ok(0.0);
    }
    let residual = |u: f64| mass * (u - v) + h * clamped(u);
    let lo = v - h * at_v / mass;
    let u = brent(residual, lo, v).ok_or(EngineError::SteppingNonFinite)?;
    Ok(mass * (v - u) / h)
}

/// The printed step and what it realises against the continuous law's numbers.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct StepChoice {
    /// The scheme the engine steps with.
    pub scheme: Scheme,
    /// The relative tolerance asked of e, F_max and the contact time.
    pub tolerance: f64,
    /// The printed step, s: the largest t_c/N on a 1-2-5 ladder of N (rounded down to two
    /// significant digits) at which e, F_max and the contact time stay within the tolerance, and
    /// still do at half that step.
    pub step: f64,
    /// Steps per continuous contact time at the printed step.
    pub steps_per_contact: f64,
    /// What the engine's stepping gives at the printed step.
    pub at_step: SteppedImpact,
}

/// Steps per contact time tried, coarsest first.
pub const LADDER: [f64; 14] = [
    10.0, 20.0, 30.0, 50.0, 100.0, 200.0, 300.0, 500.0, 1e3, 2e3, 5e3, 1e4, 2e4, 5e4,
];

/// The largest step on [`LADDER`] whose stepped impact keeps e, F_max and t_c within
/// `tolerance` of the continuous `e`, `f_max`, `t_contact` (and does so at half the step too),
/// and is no longer than `max_step`.
pub fn choose_step(
    scheme: Scheme,
    tolerance: f64,
    continuous: (f64, f64, f64),
    max_step: f64,
    simulate: impl Fn(f64) -> Result<SteppedImpact, EngineError>,
) -> Result<StepChoice, EngineError> {
    let (e, f_max, t_contact) = continuous;
    let within = |s: &SteppedImpact| {
        (s.e_out - e).abs() <= tolerance * e
            && (s.f_max - f_max).abs() <= tolerance * f_max
            && (s.t_contact - t_contact).abs() <= tolerance * t_contact
    };
    for n in LADDER {
        let step = round_down(t_contact / n);
        if step > max_step {
            continue;
        }
        let at_step = match simulate(step) {
            Ok(s) if within(&s) => s,
            Ok(_)
            | Err(EngineError::SteppingNoSeparation { .. })
            | Err(EngineError::SteppingNonFinite) => {
                continue;
            }
            Err(other) => return Err(other),
        };
        if !matches!(simulate(step / 2.0), Ok(half) if within(&half)) {
            continue;
        }
        return Ok(StepChoice {
            scheme,
            tolerance,
            step,
            steps_per_contact: t_contact / step,
            at_step,
        });
    }
    Err(EngineError::NoStep { tolerance })
}

/// `h` rounded down to two significant digits: a step that reads as typed.
pub fn round_down(h: f64) -> f64 {
    let scale = 10f64.powf(h.log10().floor() - 1.0);
    let rounded = (h / scale).floor() * scale;
    // Through text so that the value is the one the script prints.
    format!("{rounded:.1e}").parse().unwrap_or(rounded)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// The Fig. 5 scene's reduced mass and elastic contact time (steel sphere R = 10 mm on a steel
    /// plate at 0.3 m/s).
    fn fig5() -> (f64, f64, f64) {
        let (r, rho, e, nu, v0) = (0.01_f64, 7800.0, 2e11, 0.3_f64, 0.3);
        let m = 4.0 / 3.0 * PI * r.powi(3) * rho;
        let k = 4.0 / 3.0 * e / (2.0 * (1.0 - nu * nu)) * r.sqrt();
        let x_max = (5.0 * m * v0 * v0 / (4.0 * k)).powf(0.4);
        (m, v0, 3.21470 * x_max / v0)
    }

    /// MuJoCo 4.0, one frictionless sphere on a plane with solref = (timeconst, 0.2) for
    /// ω₀ = π/t_c and a constant impedance, stepped at t_c/30 and t_c/1000, rebounded at
    /// 0.581845976512843 and 0.572010643696431 (measured with the script `translate` prints).
    #[test]
    fn semi_implicit_euler_reproduces_mujoco() {
        let (m, v0, tc) = fig5();
        let omega = PI / tc;
        let timeconst = 1.0 / (omega * 0.2);
        let (k, b) = (1.0 / (timeconst * 0.2).powi(2), 2.0 / timeconst);
        let force = |x: f64, v: f64| m * (k * x + b * v).max(0.0);
        for (n, measured) in [(30.0, 0.581845976512843), (1000.0, 0.572010643696431)] {
            let s = step_impact(Scheme::SemiImplicitEuler, &force, m, v0, tc / n, 0.0, tc).unwrap();
            assert!((s.e_out - measured).abs() < 1e-9, "N = {n}: {}", s.e_out);
        }
    }

    /// Drake 1.51, point contact K = m(π/t_c)², d = 0.97487/v₀ (e = 0.6), discrete TAMSI,
    /// Lagged and Similar alike: 0.5957304601632778 at t_c/500, 0.5584047863769586 at t_c/50; SAP
    /// with relaxation time 1e-5 s in total: 0.626121614950292 at t_c/500.
    #[test]
    fn implicit_euler_reproduces_drake() {
        let (m, v0, tc) = fig5();
        let k = m * (PI / tc).powi(2);
        let d = 0.97487 / v0;
        let hc = |x: f64, v: f64| k * x * (1.0 + d * v).max(0.0);
        for (n, measured) in [(500.0, 0.5957304601632778), (50.0, 0.5584047863769586)] {
            let s = step_impact(Scheme::ImplicitEuler, &hc, m, v0, tc / n, 0.0, tc).unwrap();
            assert!((s.e_out - measured).abs() < 1e-9, "N = {n}: {}", s.e_out);
        }
        let sap = |x: f64, v: f64| k * (x + 1e-5 * v);
        let s = step_impact(Scheme::ImplicitEuler, &sap, m, v0, tc / 500.0, 0.0, tc).unwrap();
        assert!((s.e_out - 0.626121614950292).abs() < 1e-9, "{}", s.e_out);
    }

    /// An undamped linear spring under velocity Verlet loses or gains energy only where the step
    /// straddles touch and separation: e is 1 to O((ωh)²), and the contact spans π/ω to within two
    /// steps.
    #[test]
    fn velocity_verlet_keeps_an_elastic_impact_elastic() {
        let (m, v0, tc) = fig5();
        let k = m * (PI / tc).powi(2);
        let spring = |x: f64, _v: f64| k * x;
        for n in [10.0, 100.0, 1000.0] {
            let s = step_impact(Scheme::VelocityVerlet, &spring, m, v0, tc / n, 0.0, tc).unwrap();
            let omega_h = PI / n;
            assert!(
                (s.e_out - 1.0).abs() < omega_h * omega_h / 4.0,
                "N = {n}: {}",
                s.e_out
            );
            assert!(
                (s.t_contact - tc).abs() <= 2.0 * tc / n,
                "N = {n}: {}",
                s.t_contact
            );
        }
        // Past h·ω = 2 it is unstable; the spring below the plate then never lets go or blows up.
        assert!(
            step_impact(Scheme::SemiImplicitEuler, &spring, m, v0, tc, 0.0, tc)
                .map_or(true, |s| s.e_out > 1.5)
        );
    }

    #[test]
    fn the_chosen_step_meets_the_tolerance_and_a_coarser_one_does_not() {
        let (m, v0, tc) = fig5();
        let omega = PI / tc;
        let (k, b) = (omega * omega, 2.0 * 0.2 * omega);
        let force = |x: f64, v: f64| m * (k * x + b * v).max(0.0);
        let fine =
            step_impact(Scheme::SemiImplicitEuler, &force, m, v0, tc / 1e5, 0.0, tc).unwrap();
        let continuous = (fine.e_out, fine.f_max, fine.t_contact);
        let simulate = |h| {
            step_impact(
                Scheme::SemiImplicitEuler,
                &force,
                m,
                v0,
                h,
                -start_gap(v0, h),
                tc,
            )
        };
        let choice = choose_step(
            Scheme::SemiImplicitEuler,
            0.01,
            continuous,
            f64::INFINITY,
            simulate,
        )
        .unwrap();
        assert!((choice.at_step.e_out / fine.e_out - 1.0).abs() <= 0.01);
        let coarser = simulate(choice.step * 2.5).unwrap();
        let off = |a: f64, b: f64| (a / b - 1.0).abs() > 0.01;
        assert!(
            off(coarser.e_out, fine.e_out)
                || off(coarser.f_max, fine.f_max)
                || off(coarser.t_contact, fine.t_contact)
        );
    }

    #[test]
    fn round_down_keeps_two_digits() {
        assert_eq!(round_down(9.767e-7), 9.7e-7);
        assert_eq!(round_down(1.0e-5), 1.0e-5);
        assert_eq!(round_down(0.0123), 0.012);
    }
}
