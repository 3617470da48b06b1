//! Vibro-impact systems: the machine a contact sits in (issue 25; docs/systems.md).
//!
//! A scene with a `[system]` table ([`SystemSpec`], decoded by
//! [`scene_file::decode_system`](crate::model::scene_file::decode_system)) puts body 1 in a
//! machine — a bouncing ball on a vibrating table, or a forced oscillator with one stop or two —
//! whose stop is body 2. [`SystemModel::from_scene`] adds the moving mass, the restitution e of
//! `[impact]` and the Hertz estimate of the two bodies.
//!
//! The entry points dispatch on [`Contact`]: `Rigid { restitution }` (instantaneous impacts,
//! the [`rigid`] solver) or `Compliant { model, damping }` (a law of the law table through each
//! contact; the [`compliant`] solver).
//! - [`simulate`]`(&model, &contact, &RunOptions) -> History`: impacts (time, phase, speeds in
//!   and out, peak force or its Hertz estimate, energy lost), sticking phases, dense samples.
//! - [`find_orbit`]`(&model, &contact, &OrbitGuess, &OrbitOptions) -> Orbit`: a periodic orbit
//!   of the impact map by Newton, with its Floquet multipliers and stability.
//! - [`bifurcation`]`(&model, &contact, Param, &values, &DiagramOptions, on_column) -> Diagram`:
//!   brute force, following the attractor from one value to the next within chunks that run in
//!   parallel on rayon's pool; columns reach `on_column` in the order of the values, on the
//!   calling thread; `ControlFlow::Break` from it cancels the rest.
//!
//! Everything is SI; phases are ωt mod 2π in radians. Errors ([`SystemError`]) name the scene
//! key or the budget concerned.

pub mod compliant;
mod contact;
pub mod continuation;
mod diagram;
mod error;
pub mod map;
mod model;
mod orbit;
mod param;
pub mod rigid;
mod run;
pub(crate) mod seed;
mod spec;

use std::ops::ControlFlow;

pub use contact::{CompliantDamping, Contact};
pub use diagram::{Column, Diagram, DiagramOptions};
pub use error::SystemError;
pub use model::SystemModel;
pub use orbit::{GuessStart, ImpactPoint, Orbit, OrbitGuess, OrbitOptions};
pub use param::{Param, SystemKey};
pub use run::{
    Dents, EndReason, History, IMPACTING_AT_END, ImpactKind, ImpactRecord, RunOptions, State,
    Stick, StopIndex, SystemSample,
};
pub use spec::{
    Damping, Forcing, Groups, OscillatorCoefficients, STANDARD_GRAVITY, SystemKind, SystemSpec,
};

/// Simulates `model` with `contact` (see the module docs).
pub fn simulate(
    model: &SystemModel,
    contact: &Contact,
    options: &RunOptions,
) -> Result<History, SystemError> {
    match contact {
        Contact::Rigid { restitution } => rigid::simulate(model, *restitution, options),
        Contact::Compliant {
            model: law,
            damping,
        } => compliant::simulate(model, *law, *damping, options),
    }
}

/// A periodic orbit of the impact map of `model` with `contact`, and its multipliers.
pub fn find_orbit(
    model: &SystemModel,
    contact: &Contact,
    guess: &OrbitGuess,
    options: &OrbitOptions,
) -> Result<Orbit, SystemError> {
    match contact {
        Contact::Rigid { restitution } => rigid::find_orbit(model, *restitution, guess, options),
        Contact::Compliant {
            model: law,
            damping,
        } => compliant::find_orbit(model, *law, *damping, guess, options),
    }
}

/// A brute-force bifurcation diagram of `model` with `contact` over `param` at `values`.
pub fn bifurcation(
    model: &SystemModel,
    contact: &Contact,
    param: Param,
    values: &[f64],
    options: &DiagramOptions,
    on_column: impl FnMut(&Column) -> ControlFlow<()>,
) -> Result<Diagram, SystemError> {
    // A rigid stop's e follows the model when the diagram varies `impact.restitution`.
    let follows_e = param == Param::Scene(crate::model::scene_key::SceneKey::Restitution);
    let run = |model: &SystemModel, run: &RunOptions| match contact {
        Contact::Rigid { .. } if follows_e => {
            simulate(model, &Contact::rigid(model.restitution), run)
        }
        _ => simulate(model, contact, run),
    };
    diagram::run(model, param, values, options, run, on_column)
}
