//! Where a row of a map may start instead of at rest: on the rigid stop's period-1 orbit of its
//! first cell, so that a map shows that orbit's region where it coexists with chatter (started
//! from rest, the bouncing ball mostly chatters there; docs/maps.md §2).
#![warn(missing_docs)]

use std::f64::consts::PI;

use crate::model::system::rigid::dynamics::Dynamics;
use crate::model::system::{
    Contact, GuessStart, OrbitGuess, OrbitOptions, RunOptions, State, SystemError, SystemKind,
    SystemModel, find_orbit,
};

/// The state just after the first impact of the rigid stop's period-1 orbit (one impact a forcing
/// period) of `model` with restitution `e`. For the bouncing ball Newton starts from the closed
/// form (docs/physics.md §8.1: Γ·cos φ = Γ_SN = π(1 − e)/(1 + e), v_in = (π + Γ_SN)·g/ω, the
/// stable orbit with sin φ > 0); for an oscillator, from the attractor reached by `attractor`.
pub fn period_one(
    model: &SystemModel,
    e: f64,
    attractor: &RunOptions,
) -> Result<State, SystemError> {
    let start = match model.spec.kind {
        SystemKind::BouncingBall {
            amplitude, gravity, ..
        } => {
            let omega = model.spec.omega();
            let gamma = amplitude * omega * omega / gravity;
            // Γ_SN = π(1 − e)/(1 + e) (docs/physics.md §8.1).
            let sn = PI * (1.0 - e) / (1.0 + e);
            if gamma.partial_cmp(&sn) != Some(std::cmp::Ordering::Greater) {
                return Err(SystemError::OrbitDegenerate(
                    "no period-1 orbit below Γ_SN = π(1 − e)/(1 + e)",
                ));
            }
            Some(GuessStart {
                phase: (sn / gamma).acos(),
                v_in: (PI + sn) * gravity / omega,
                stop: 0,
            })
        }
        SystemKind::ImpactOscillator { .. } => None,
    };
    let guess = OrbitGuess {
        forcing_cycles: 1,
        impacts: 1,
        start,
        attractor: RunOptions {
            samples_per_period: 0,
            initial: None,
            ..*attractor
        },
    };
    let orbit = find_orbit(model, &Contact::rigid(e), &guess, &OrbitOptions::default())?;
    let first = orbit
        .points
        .first()
        .ok_or(SystemError::OrbitDegenerate("the orbit has no impact"))?;
    let d = Dynamics::new(model, e);
    let (s, sv, _) = d.stop_motion(first.stop, first.t);
    Ok(State {
        t: first.t,
        x: s,
        v: sv + d.stops[first.stop].sigma * first.v_out,
    })
}
