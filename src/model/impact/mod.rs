//! The impact solver: integrates m·ẍ = −F(x, ẋ) from x = 0, ẋ = v₀ until contact ends.
#![warn(missing_docs)]

use std::fmt;
use std::str::FromStr;

use serde::Serialize;
use thiserror::Error;

use super::error::{ModelError, require, require_positive};
use super::force::{AnyLaw, ForceLaw, ForceModel, ImpactParams, LawVisitor};
use super::ode::{Method, OdeError};

/// Which solution path the caller asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MethodChoice {
    /// The cheapest path that meets the tolerance: exact solution, then adaptive explicit, then implicit.
    Auto,
    /// A specific integrator.
    Integrator(Method),
}

impl fmt::Display for MethodChoice {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MethodChoice::Auto => f.write_str("auto"),
            MethodChoice::Integrator(m) => m.fmt(f),
        }
    }
}

/// A method name that is neither `auto` nor an integrator's; the message lists those that are.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[error(
    "unknown method '{0}' (expected one of: auto, {methods})",
    methods = Method::ALL.map(Method::name).join(", ")
)]
pub struct UnknownMethod(pub String);

impl FromStr for MethodChoice {
    type Err = UnknownMethod;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        if s == "auto" {
            Ok(MethodChoice::Auto)
        } else {
            s.parse::<Method>()
                .map(MethodChoice::Integrator)
                .map_err(|_| UnknownMethod(s.to_string()))
        }
    }
}

/// Requested accuracy and limits of one impact solve.
///
/// The solver works in X = x/x_e, V = v/v₀, T = t·v₀/x_e with x_e the elastic x_max (eq 5), so
/// `rtol` and `atol` are dimensionless and mean the same for every scene. `rtol` is a promise: on
/// adaptive methods and `auto`, x_max, F_max, t_c (relative), x_residual (relative to x_max) and
/// v_out (relative to v₀) are within 100·rtol of the truth, for rtol from 1e-3 to 1e-12 (each
/// method is given the tolerance that keeps it, see `impact::tolerance`), except where the
/// summary's warnings flag the scene as ill-conditioned.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolveOptions {
    /// The solution path: `auto` or one integrator.
    pub method: MethodChoice,
    /// The accuracy asked of adaptive methods and `auto` (see above).
    pub rtol: f64,
    /// Absolute tolerance of adaptive methods in the solver's scaled variables (x/x_e, v/v₀);
    /// `None` ties it to rtol.
    pub atol: Option<f64>,
    /// Step size of fixed-step methods, s; `None` picks t_c/1000 of the elastic estimate.
    pub dt: Option<f64>,
    /// Accepted plus rejected steps per solve before it fails.
    pub max_steps: usize,
}

impl Default for SolveOptions {
    fn default() -> Self {
        SolveOptions {
            method: MethodChoice::Auto,
            rtol: 1e-8,
            atol: None,
            dt: None,
            max_steps: 200_000,
        }
    }
}

/// The solution path actually used.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(into = "String")]
pub enum MethodUsed {
    /// A closed form or quadrature (elastic Hertz, energy integrals); the curves come from a tight-tolerance integrator.
    Exact,
    /// This integrator.
    Integrator(Method),
}

impl fmt::Display for MethodUsed {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MethodUsed::Exact => f.write_str("exact"),
            MethodUsed::Integrator(m) => m.fmt(f),
        }
    }
}

impl From<MethodUsed> for String {
    fn from(m: MethodUsed) -> String {
        m.to_string()
    }
}

/// Where the compressive-only rule ended contact early: the law turned tensile (F < 0) at x > 0.
/// Dry friction always does near x = 0 (k·xⁿ − P·x < 0 below (P/k)^{1/(n−1)}); the Hunt–Crossley
/// family only through an integrator's error (see `exact::hysteresis`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TensileCutoff {
    /// When, s.
    pub t: f64,
    /// The approach left, m.
    pub x: f64,
    /// ẋ at separation (≤ 0), m/s.
    pub v: f64,
}

/// The numbers of one impact, SI units.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ImpactSummary {
    /// The force law solved.
    pub model: ForceModel,
    /// The solution path used.
    pub method: MethodUsed,
    /// Maximum approach (at ẋ = 0), m.
    pub x_max: f64,
    /// Time of maximum compression (ẋ = 0), s.
    pub t_x_max: f64,
    /// The true force peak (where dF/dt = 0 on the dense output, or where the force jumps), N.
    pub f_max: f64,
    /// Time of the force peak, s.
    pub t_f_max: f64,
    /// Duration of contact, s.
    pub t_contact: f64,
    /// Exit speed |ẋ| when contact ends, m/s.
    pub v_out: f64,
    /// Realized restitution v_out/v₀.
    pub e_out: f64,
    /// Approach left when contact ends (x_pl of the proposed model), m.
    pub x_residual: f64,
    /// ½m(v₀² − v_out²), J.
    pub energy_dissipated: f64,
    /// |½m(v₀² − v_out²) − ∮F dx| / (½m v₀²), ∮F dx by quadrature on the dense output. Zero for
    /// exact solutions, whose v_out is the energy balance itself.
    pub energy_residual: f64,
    /// Accepted steps (zero for exact solutions). Work counters include an abandoned DOPRI5
    /// attempt when `auto` switched to Radau5.
    pub steps: usize,
    /// Rejected steps.
    pub rejected_steps: usize,
    /// Force evaluations of the integration (right-hand sides, Jacobians' included).
    pub force_evals: usize,
    /// Set when the compressive-only rule fired.
    pub tensile_cutoff: Option<TensileCutoff>,
}

/// One point of a trajectory.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Sample {
    /// Time since first contact, s.
    pub t: f64,
    /// Approach x, m.
    pub x: f64,
    /// Approach velocity ẋ, m/s.
    pub v: f64,
    /// Contact force F, N.
    pub f: f64,
}

/// Ways an impact solve fails. Each says what happened and when.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ImpactError {
    /// The inputs or options are invalid; the error names the field.
    #[error(transparent)]
    InvalidInput(#[from] ModelError),
    /// The integrator failed.
    #[error("{method}: {source}")]
    Integration {
        /// The integrator that failed.
        method: Method,
        /// Its error, in the solver's time in seconds.
        #[source]
        source: OdeError,
    },
    /// The mechanical energy grew past [`ENERGY_LIMIT`]: the method is unstable at its step.
    #[error(
        "{method}: energy grew by {growth:.1} % at t = {t:.6e} s: the method is unstable at this step"
    )]
    EnergyGrowth {
        /// The integrator.
        method: Method,
        /// When, s.
        t: f64,
        /// The growth, % of the initial kinetic energy.
        growth: f64,
    },
    /// Contact lasted past [`TIME_LIMIT_CONTACTS`] elastic contact times.
    #[error("contact did not end within {t_limit:.3e} s")]
    NoSeparation {
        /// The time limit, s.
        t_limit: f64,
    },
}

mod auto;
mod phases;
mod scale;
mod similar;
mod summary;
mod system;
mod tolerance;
mod trajectory;

pub use phases::TIME_LIMIT_CONTACTS;
pub use similar::{Ratios, SimilarImpact};
pub use system::ENERGY_LIMIT;
pub use trajectory::Trajectory;

/// A solved impact: the numbers and the continuous curves.
#[derive(Debug, Clone)]
pub struct ImpactSolution {
    /// The numbers: peaks, contact time, realised restitution, work.
    pub summary: ImpactSummary,
    /// The continuous curves x(t), ẋ(t), F(t).
    pub trajectory: Trajectory,
}

/// Solves one impact of `model` with `params`.
///
/// Integrates m·ẍ = −F(x, ẋ) from x = 0, ẋ = v₀ in two phases joined at maximum compression
/// (ẋ = 0), until x = 0, or F = 0 for the proposed model and wherever a law would turn tensile
/// (the compressive-only rule, see [`crate::model::force::law`]). `MethodChoice::Auto` reports the
/// exact solution where one exists (curves by DOP853 at tight tolerance), else DOPRI5 (DOP853
/// below rtol 1e-7), or Radau5
/// when the scene is stiff. Failures are typed: invalid input, an integrator error (in seconds),
/// energy growth beyond [`ENERGY_LIMIT`], or no separation within [`TIME_LIMIT_CONTACTS`] elastic
/// contact times.
///
/// The paper's Fig. 5 scene, a steel sphere R = 10 mm dropped at v₀ = 0.3 m/s on a steel plate:
///
/// ```
/// use hertz_tui::model::ForceModel;
/// use hertz_tui::model::impact::{MethodUsed, SolveOptions, solve_impact};
/// use hertz_tui::model::presets::{DEFAULT_SCENE, Registry};
///
/// let scene = Registry::builtin()?.scene(DEFAULT_SCENE)?;
/// let params = scene.impact_params(&scene.quasistatic()?);
/// let options = SolveOptions::default();
///
/// // Elastic Hertz (eq 1) is solved exactly: Table 1's x_max = 9.115 µm (eq 5) and
/// // F_max = 403.2 N (eq 6), t_c = 2.9432·x_max/v₀ (eq 7, (4/5)·B(2/5, 1/2)), all energy back.
/// let elastic = solve_impact(ForceModel::Quasistatic, &params, &options)?.summary;
/// assert_eq!(elastic.method, MethodUsed::Exact);
/// assert!((elastic.x_max / 9.115e-6 - 1.0).abs() < 1e-3);
/// assert!((elastic.f_max / 403.2 - 1.0).abs() < 1e-3);
/// assert!((elastic.t_contact / (2.9432 * elastic.x_max / 0.3) - 1.0).abs() < 1e-4);
/// assert!((elastic.e_out - 1.0).abs() < 1e-9);
///
/// // Hunt–Crossley (eq 19) at e = 0.6 leaves at 0.2136 m/s, faster than v₀·e = 0.18 m/s.
/// let hunt_crossley = solve_impact(ForceModel::HuntCrossley, &params, &options)?;
/// assert!((hunt_crossley.summary.v_out - 0.2136).abs() < 1e-4);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn solve_impact(
    model: ForceModel,
    params: &ImpactParams,
    opts: &SolveOptions,
) -> Result<ImpactSolution, ImpactError> {
    // `ForceModel::law` has validated the parameters.
    solve_valid_law(&model.law(params)?, opts)
}

/// Solves one impact of an already built law, e.g. a Hunt–Crossley law calibrated at another
/// velocity ([`crate::model::force::hysteresis::Hysteresis::hunt_crossley_calibrated`]).
pub fn solve_law(law: &AnyLaw, opts: &SolveOptions) -> Result<ImpactSolution, ImpactError> {
    law.params().validate()?;
    solve_valid_law(law, opts)
}

/// [`solve_law`] for a law whose parameters are known valid: validating them costs four powers,
/// a tenth of an exact impact.
fn solve_valid_law(law: &AnyLaw, opts: &SolveOptions) -> Result<ImpactSolution, ImpactError> {
    validate_options(opts)?;
    let scales = scale::Scales::of_law(law);
    // Monomorphise the solver per law: the force is evaluated in the integrators' inner loop.
    law.visit(Solve {
        any: *law,
        scales: &scales,
        opts,
    })
}

struct Solve<'a> {
    any: AnyLaw,
    scales: &'a scale::Scales,
    opts: &'a SolveOptions,
}

impl LawVisitor for Solve<'_> {
    type Output = Result<ImpactSolution, ImpactError>;

    fn visit<L: ForceLaw>(self, law: &L) -> Self::Output {
        solve_with(law, self.any, self.scales, self.opts)
    }
}

fn solve_with<L: ForceLaw>(
    law: &L,
    any: AnyLaw,
    scales: &scale::Scales,
    opts: &SolveOptions,
) -> Result<ImpactSolution, ImpactError> {
    match opts.method {
        MethodChoice::Auto => auto::solve(law, any, scales, opts),
        MethodChoice::Integrator(method) => {
            // Partitioned methods need the velocity itself as the second variable.
            let scales = &if method.is_partitioned() {
                scales.without_shift()
            } else {
                *scales
            };
            let (rtol, atol) = tolerance::integrator_tolerances(method, opts.rtol, opts.atol);
            let ro = phases::RunOptions {
                method,
                rtol,
                atol,
                // Fixed-step methods: the given step, or t_c/1000 of the elastic estimate (eq 7).
                dt: Some(
                    opts.dt
                        .map_or(scales.t_contact / 1000.0, |dt| dt / scales.t),
                ),
                max_steps: opts.max_steps,
                known: None,
            };
            let run = phases::run(law, scales, &ro)?;
            Ok(integrated_solution(law, any, scales, run, method))
        }
    }
}

/// The summary and curves of an integrated `run`, with a hysteresis's unloading anchored where
/// the run turned ([`ForceLaw::unloading_at_turn`]), as the run itself unloaded.
fn integrated_solution<L: ForceLaw>(
    law: &L,
    any: AnyLaw,
    sc: &scale::Scales,
    run: phases::Run,
    method: Method,
) -> ImpactSolution {
    let x_turn = run.x_turn(sc);
    let (law, any) = (
        &law.unloading_at_turn(x_turn),
        any.unloading_at_turn(x_turn),
    );
    let summary = summary::summarize(law, sc, &run, MethodUsed::Integrator(method));
    let trajectory = Trajectory::integrated(any, *sc, run, &summary);
    ImpactSolution {
        summary,
        trajectory,
    }
}

/// Tolerances finite and > 0, a given step finite and > 0, a step budget of at least one.
fn validate_options(opts: &SolveOptions) -> Result<(), ModelError> {
    require_positive("rtol", opts.rtol)?;
    if let Some(atol) = opts.atol {
        require_positive("atol", atol)?;
    }
    if let Some(dt) = opts.dt {
        require_positive("dt", dt)?;
    }
    require("max_steps", opts.max_steps as f64, "at least 1", |n| {
        n >= 1.0
    })?;
    Ok(())
}
