//! What the system layer refuses, naming the scene key or the budget concerned.
#![warn(missing_docs)]

use thiserror::Error;

use crate::model::error::ModelError;

/// Everything [`simulate`](super::simulate), [`find_orbit`](super::find_orbit) and
/// [`bifurcation`](super::bifurcation) can refuse.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SystemError {
    /// A parameter out of range; the model error names the key (`system.gap`, `impact.restitution`).
    #[error(transparent)]
    Invalid(#[from] ModelError),
    /// A run needed more impacts than its budget allows.
    #[error(
        "{what} needs more than max_impacts = {budget} impacts (at t = {time:e} s); raise the budget or shorten the run"
    )]
    ImpactBudget {
        /// What ran out: "the simulation", "the diagram at system.amplitude = …".
        what: String,
        /// The budget.
        budget: usize,
        /// The time reached, s.
        time: f64,
    },
    /// A diagram whose values × (transient + recorded) impacts exceed the diagram's budget.
    #[error(
        "the diagram needs {needed} impacts ({values} values × {per_value} impacts), more than the budget of {budget}; use fewer values or impacts per value"
    )]
    DiagramBudget {
        /// values × per_value.
        needed: u128,
        /// Parameter values.
        values: usize,
        /// transient + recorded impacts per value.
        per_value: usize,
        /// The budget.
        budget: usize,
    },
    /// The certified impact search exhausted its step budget within one flight (docs/systems.md §3).
    #[error(
        "impact search: no decision after {steps} steps in the flight from t = {from:e} s (gap {gap:e} m); the motion is too close to grazing for double precision"
    )]
    SearchBudget {
        /// Steps taken.
        steps: usize,
        /// Flight start, s.
        from: f64,
        /// The gap where it stopped, m.
        gap: f64,
    },
    /// A bifurcation key the system has no value for (`system.second_gap` on a one-sided stop …).
    #[error("`{key}` is not a parameter of this system ({why})")]
    KeyNotApplicable {
        /// The key as given.
        key: String,
        /// Why not.
        why: &'static str,
    },
    /// A bifurcation key that names nothing.
    #[error(
        "unknown parameter `{0}` (system.amplitude, system.gamma, system.frequency, system.gravity, system.stiffness, system.damping_ratio, system.damping, system.forcing_amplitude, system.gap, system.second_gap, impact.restitution, or a body key such as body1.mass)"
    )]
    UnknownKey(String),
    /// No parameter values were given.
    #[error("the diagram has no parameter values")]
    NoValues,
    /// A value that is not finite.
    #[error("`{key}` = {value} is not a finite number")]
    NotFinite {
        /// The key.
        key: String,
        /// The value.
        value: f64,
    },
    /// Newton on the impact map did not converge.
    #[error(
        "periodic orbit: Newton did not converge in {iterations} iterations (residual {residual:e}); try another guess or follow the attractor"
    )]
    OrbitNotConverged {
        /// Iterations done.
        iterations: usize,
        /// The last residual (relative).
        residual: f64,
    },
    /// No start for Newton converged to the orbit asked for (no start given): why, in words.
    #[error(
        "periodic orbit: no orbit of {impacts} impact(s) in {cycles} forcing period(s) found: {why}"
    )]
    OrbitNotFound {
        /// Forcing periods asked for.
        cycles: u32,
        /// Impacts asked for.
        impacts: u32,
        /// What the run did and what Newton met.
        why: String,
    },
    /// The orbit guess led to chatter, sticking or no impact: no isolated impact-map orbit there.
    #[error("periodic orbit: {0}")]
    OrbitDegenerate(&'static str),
    /// The compliant stop needs the scene's two bodies (its Hertz stiffness comes from them).
    #[error(
        "a compliant stop needs the scene's two bodies (body1, body2) for its Hertz stiffness; this system was built without them"
    )]
    CompliantNeedsBodies,
    /// The compliant solver is not available in this build.
    #[error("the compliant stop is not available yet; use the rigid stop (contact = rigid)")]
    CompliantUnavailable,
    /// The compliant solver's own error, in words.
    #[error("compliant stop: {0}")]
    Compliant(String),
    /// The caller stopped a diagram (its callback returned `ControlFlow::Break`).
    #[error("the diagram was cancelled")]
    Cancelled,
}
