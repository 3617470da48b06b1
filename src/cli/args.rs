//! The command line (clap): no subcommand opens the explorer; `list` and `solve` are headless.

use clap::{Args, Parser, Subcommand, ValueEnum};

use crate::model::ForceModel;
use crate::model::impact::MethodChoice;
use crate::model::overrides::Override;
use crate::model::scene_key::SceneKey;
use crate::model::system::Param;

/// Explore impact contact forces: Hertz contact, dry friction, Hunt–Crossley, Lankarani–Nikravesh
/// and the proposed viscous model of Polukoshko, Sokolova & Kononova.
#[derive(Debug, Parser)]
#[command(name = "hertz-tui", version)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
    /// Scene to open in the explorer: a preset name (see `hertz-tui list`) or a scene file path
    /// [default: the config file's `scene`, else fig5-steel-sphere-r10-plate].
    #[arg(long, value_name = "NAME|PATH")]
    pub scene: Option<String>,
    /// Override a key of the explorer's scene by its dotted path, e.g. impact.v0=0.5,
    /// system.gap=0.5mm (repeatable; a number in SI or with its unit).
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub overrides: Vec<Override>,
    /// Measured restitution e(v₀), a CSV file, to open in the explorer's fit view (docs/fitting.md).
    #[arg(long, value_name = "FILE")]
    pub data: Option<std::path::PathBuf>,
    /// How the explorer draws chart points; dot or block for fonts without braille.
    #[arg(long, value_enum, default_value_t = Marker::Braille)]
    pub marker: Marker,
}

/// How the explorer draws chart points (`--marker`), for fonts that lack braille.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Marker {
    /// Braille patterns: 2×4 dots per cell, the finest resolution.
    Braille,
    /// One dot per cell.
    Dot,
    /// One full block per cell.
    Block,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// List the built-in and user materials and scenes.
    List,
    /// Evaluate a scene: the quasistatic Hertz estimate and the impact of each force model.
    Solve(SolveArgs),
    /// Speed against accuracy: every method over a ladder of tolerances or step sizes, errors
    /// against the exact (or DOP853 rtol 1e-13) solution; --stability: largest stable steps.
    Bench(BenchArgs),
    /// Vary one scene key over a range and solve every point (in parallel; rows in order).
    Sweep(SweepArgs),
    /// The restitution each law really gives for requested e = 0.1, 0.3, 0.5, 0.7, 0.9.
    Restitution(RestitutionArgs),
    /// Contact parameters for a simulation engine: its input fragment, calibrated so its realised
    /// restitution at v₀ is the scene's, and what the engine will really give.
    Translate(TranslateArgs),
    /// Fit every law (or --law …) to measured restitution e(v₀) of a CSV file, rank the laws by an
    /// information criterion, say whether the data can tell them apart; --write-scene puts the
    /// fitted law in a scene that solve, translate and the explorer use.
    Fit(FitArgs),
    /// Write a chart as the explorer draws it to an SVG or PNG figure.
    Plot(PlotArgs),
    /// Simulate a system scene (its `[system]` table): impacts, detected period, time history.
    System(SystemArgs),
    /// A periodic orbit of a system's impact map by Newton, its Floquet multipliers and stability.
    Orbit(OrbitArgs),
    /// A brute-force bifurcation diagram of a system over a scene or system key (CSV streamed).
    Bifurcation(BifurcationArgs),
    /// Continue a system's periodic orbit in a key: stability, folds, period doublings, grazing.
    Continue(super::continuation::ContinueArgs),
    /// A two-parameter map of a system's motion (periodic n:m, chaotic, chattering …), whole or
    /// one shard (--shard I/N).
    Map(crate::cli::map::MapArgs),
    /// Join the shards of a map into the whole map (the file the unsharded run writes).
    Merge(crate::cli::map::MergeArgs),
}

/// Options of `hertz-tui fit`.
#[derive(Debug, Args)]
pub struct FitArgs {
    #[command(flatten)]
    pub source: SceneSelection,
    /// The data: a CSV of v, e (and optionally sd) with units in the header, e.g. `v (m/s), e, sd`
    /// (docs/fitting.md).
    #[arg(long, value_name = "FILE")]
    pub data: std::path::PathBuf,
    /// A law to fit: constant-e or a law id (repeatable; default every law with a material
    /// constant, one per distinct e(v)).
    #[arg(long = "law", value_name = "LAW")]
    pub laws: Vec<String>,
    /// The information criterion that ranks the laws: aicc or bic.
    #[arg(long, value_name = "C", default_value = "aicc")]
    pub criterion: crate::model::fit::Criterion,
    /// Confidence level of the parameters' intervals.
    #[arg(long, value_name = "P", default_value_t = 0.95, value_parser = level)]
    pub level: f64,
    /// Output format: table (ranking, verdict, residuals), json, or csv (the ranking).
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
    /// Table: the best law's residual at every point (default: their RMS and the largest).
    #[arg(long)]
    pub residuals: bool,
    /// Write the scene with the best fitted law (or the one --law names) as its `[fit]` to OUT.
    #[arg(long, value_name = "OUT")]
    pub write_scene: Option<std::path::PathBuf>,
    /// Also each simulation engine's realised e(v₀), calibrated at the scene's v₀, against the
    /// data: which engine can reproduce these measurements.
    #[arg(long)]
    pub engines: bool,
}

/// A confidence level in (0, 1).
fn level(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(x) if x > 0.0 && x < 1.0 => Ok(x),
        _ => Err(format!(
            "{s} must be a confidence level in (0, 1), e.g. 0.95"
        )),
    }
}

/// Options of `hertz-tui restitution`.
#[derive(Debug, Args)]
pub struct RestitutionArgs {
    #[command(flatten)]
    pub source: SceneSelection,
    /// Force model (repeatable; default every law).
    #[arg(long = "model", value_name = "MODEL")]
    pub models: Vec<ForceModel>,
    /// Output format (table, json or csv).
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
}

/// The charts `plot` draws.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ChartChoice {
    /// Force against approach.
    Fx,
    /// Force against time.
    Ft,
    /// Velocity against approach.
    Vx,
    /// One output against a scene key (--param, --quantity), a line per model or scene.
    Sweep,
    /// log error against cost of every method on the first --model.
    WorkPrecision,
    /// Every fixed-step method at one step (--dt) over the reference, on the first --model.
    Stability,
    /// A system scene's time history x(t) with its stops (--contact: rigid, compliant, both).
    History,
    /// A system scene's phase portrait v(x).
    Phase,
    /// A system scene's impact map: incoming speed against forcing phase at each impact.
    ImpactMap,
    /// A system scene's bifurcation diagram over --param from --from to --to (--points values).
    Bifurcation,
    /// Measured e(v₀) of --data with error bars and every fitted law's curve (the laws --model
    /// names and constant e, default every fittable law), and the residuals.
    Fit,
    /// Measured e(v₀) of --data against each engine's realised e(v₀), the engine's constants
    /// calibrated at v₀ to the best fit's e.
    FitEngines,
}

/// What a sweep chart shows against the swept key.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum QuantityChoice {
    /// Maximum contact pressure of the quasistatic estimate (the paper's Fig. 2).
    P0,
    /// Contact radius or half-width of the estimate.
    ContactSize,
    XMax,
    FMax,
    /// Contact time (`t-c`, also `tc`).
    #[value(name = "t-c", alias = "tc")]
    TC,
    VOut,
    EOut,
}

/// Options of `hertz-tui plot`.
#[derive(Debug, Args)]
pub struct PlotArgs {
    /// A preset name or scene file; repeat it with --chart sweep for one line per scene.
    #[arg(long, value_name = "NAME|PATH", required = true)]
    pub scene: Vec<String>,
    /// Override a key of every scene by its dotted path (repeatable; a number in SI or with its
    /// unit).
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub overrides: Vec<Override>,
    /// The chart.
    #[arg(long, value_enum)]
    pub chart: ChartChoice,
    /// Force model (repeatable; default every law of the table; the first is focused, and the one
    /// studied by work-precision and stability, default proposed).
    #[arg(long = "model", value_name = "MODEL")]
    pub models: Vec<ForceModel>,
    /// Solution method of fx, ft, vx and sweep (default auto).
    #[arg(long, value_name = "METHOD", default_value = "auto")]
    pub method: MethodChoice,
    /// Relative tolerance of the adaptive methods (default 1e-8).
    #[arg(long, value_name = "R", value_parser = positive_number, allow_hyphen_values = true)]
    pub rtol: Option<f64>,
    /// Step, s: of the fixed-step methods (fx, ft, vx, sweep) and of the stability chart
    /// (default there: the rk4 critical step).
    #[arg(long, value_name = "S", value_parser = positive_number, allow_hyphen_values = true)]
    pub dt: Option<f64>,
    /// Sweep and bifurcation: the key varied (a scene key; a bifurcation also takes system.*).
    #[arg(long, value_name = "KEY", default_value = "impact.v0")]
    pub param: Param,
    /// Sweep: what is drawn against the key.
    #[arg(long, value_enum, default_value_t = QuantityChoice::EOut)]
    pub quantity: QuantityChoice,
    /// Sweep: first value, SI (default: the explorer's range around the scene's value).
    #[arg(long, value_name = "A", allow_hyphen_values = true, requires = "to")]
    pub from: Option<f64>,
    /// Sweep: last value, SI.
    #[arg(long, value_name = "B", allow_hyphen_values = true, requires = "from")]
    pub to: Option<f64>,
    /// Sweep: space the points geometrically (with --from/--to; the default range picks its own).
    #[arg(long)]
    pub log: bool,
    /// Sweep: number of points.
    #[arg(long, value_name = "N", default_value_t = 200, value_parser = clap::value_parser!(u32).range(2..=100_000))]
    pub points: u32,
    #[command(flatten)]
    pub contact: ContactArgs,
    #[command(flatten)]
    pub run: RunArgs,
    /// fit and fit-engines: the measured restitution (the CSV of `hertz-tui fit`).
    #[arg(long, value_name = "FILE")]
    pub data: Option<std::path::PathBuf>,
    /// The figure file: .svg (vector) or .png.
    #[arg(short = 'o', long = "out", value_name = "FILE")]
    pub out: std::path::PathBuf,
    /// Figure size in pixels, WIDTHxHEIGHT.
    #[arg(long, value_name = "WxH", default_value = "1200x800")]
    pub size: String,
}

/// The scene a headless command works on.
#[derive(Debug, Args)]
pub struct SceneSelection {
    /// A preset name (see `hertz-tui list`) or the path of a scene file.
    #[arg(long, value_name = "NAME|PATH")]
    pub scene: String,
    /// Override a scene key by its dotted path (repeatable): impact.v0=0.5, body1.radius=12mm,
    /// body1.shape=plane, body1.material=aluminium-alloy, body1.material.youngs_modulus=70GPa,
    /// system.frequency=20Hz (a number in SI or with its unit).
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub overrides: Vec<Override>,
}

/// Options of `hertz-tui solve`.
#[derive(Debug, Args)]
pub struct SolveArgs {
    #[command(flatten)]
    pub source: SceneSelection,
    /// Output format; csv prints the trajectory t,x,v,F of the one --model given.
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
    /// Force model (repeatable; default every law): a law id such as hunt-crossley or kelvin-voigt
    /// (a wrong id lists them all).
    #[arg(long = "model", value_name = "MODEL")]
    pub models: Vec<ForceModel>,
    /// Calibrate each law's damping parameter so that its realised e equals the scene's
    /// restitution (closed form for the Hunt–Crossley family, a bracketed root for the others).
    #[arg(long)]
    pub calibrate: bool,
    /// Solution method: auto, euler, symplectic-euler, verlet, rk4, dopri5, dop853, radau5.
    #[arg(long, value_name = "METHOD", default_value = "auto")]
    pub method: MethodChoice,
    /// Relative tolerance of the adaptive methods (default 1e-8).
    #[arg(long, value_name = "R", value_parser = positive_number, allow_hyphen_values = true)]
    pub rtol: Option<f64>,
    /// Absolute tolerance of the adaptive methods, in scaled variables (default: tied to rtol).
    #[arg(long, value_name = "A", value_parser = positive_number, allow_hyphen_values = true)]
    pub atol: Option<f64>,
    /// Step of the fixed-step methods, s (default: the elastic contact time / 1000).
    #[arg(long, value_name = "S", value_parser = positive_number, allow_hyphen_values = true)]
    pub dt: Option<f64>,
    /// Number of trajectory samples printed by --format csv.
    #[arg(long, value_name = "N", default_value_t = 400, value_parser = clap::value_parser!(u32).range(2..=1_000_000))]
    pub points: u32,
}

/// Options of `hertz-tui bench`.
#[derive(Debug, Args)]
pub struct BenchArgs {
    #[command(flatten)]
    pub source: SceneSelection,
    /// The force model to measure: any law id (`hertz-tui solve` lists them all), e.g.
    /// hunt-crossley, kelvin-voigt, thornton.
    #[arg(long = "model", value_name = "MODEL")]
    pub model: ForceModel,
    /// Instead of the work-precision ladder: per fixed-step method, the measured largest stable
    /// step next to the theoretical bound h·ω.
    #[arg(long)]
    pub stability: bool,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
}

/// Options of `hertz-tui sweep`.
#[derive(Debug, Args)]
pub struct SweepArgs {
    #[command(flatten)]
    pub source: SceneSelection,
    /// The numeric scene key to vary, e.g. impact.v0, impact.restitution, body1.radius,
    /// body2.material.youngs_modulus.
    #[arg(long, value_name = "KEY")]
    pub param: SceneKey,
    /// First value, SI units.
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub from: f64,
    /// Last value, SI units.
    #[arg(long, value_name = "B", allow_hyphen_values = true)]
    pub to: f64,
    /// Number of points, both ends included.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(2..=10_000_000))]
    pub points: u32,
    /// Space the points geometrically (bounds of one sign).
    #[arg(long)]
    pub log: bool,
    /// Force model (repeatable; default every law).
    #[arg(long = "model", value_name = "MODEL")]
    pub models: Vec<ForceModel>,
    /// Solution method of every impact (default auto).
    #[arg(long, value_name = "METHOD", default_value = "auto")]
    pub method: MethodChoice,
    /// Relative tolerance of the adaptive methods (default 1e-8).
    #[arg(long, value_name = "R", value_parser = positive_number, allow_hyphen_values = true)]
    pub rtol: Option<f64>,
    /// Output format (table, json or csv).
    #[arg(long, value_enum, default_value_t = Format::Csv)]
    pub format: Format,
}

/// Options of `hertz-tui translate`.
#[derive(Debug, Args)]
pub struct TranslateArgs {
    #[command(flatten)]
    pub source: SceneSelection,
    /// The engine: drake, drake-sap, simbody, chrono, liggghts, lammps, lammps-tsuji, yade, adams,
    /// mujoco.
    #[arg(long, value_name = "ENGINE")]
    pub engine: String,
    /// Output format.
    #[arg(long, value_enum, default_value_t = TranslateFormat::Text)]
    pub format: TranslateFormat,
    /// Also write the engine's runnable script to FILE (run it as the output says).
    #[arg(long, value_name = "FILE")]
    pub script: Option<std::path::PathBuf>,
    /// Also the engine's realised e(v₀), its constants calibrated at the scene's v₀, against the
    /// measured restitution in FILE (the CSV of `hertz-tui fit`): can it reproduce them?
    #[arg(long, value_name = "FILE")]
    pub data: Option<std::path::PathBuf>,
    /// Relative tolerance the printed time step keeps on e, F_max and the contact time (default
    /// 0.01).
    #[arg(long, value_name = "T", default_value_t = crate::model::engine::run::DEFAULT_TOLERANCE)]
    pub tolerance: f64,
}

/// How `translate` prints its result.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TranslateFormat {
    /// The law, parameters, realised numbers, notes and the fragments to paste.
    Text,
    /// One JSON object, SI units.
    Json,
}

/// How `solve` prints its results.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// Aligned tables with units.
    Table,
    /// JSON, SI units (solve: one object with scene, quasistatic, impacts; bench, sweep: rows).
    Json,
    /// Comma-separated, SI units (solve: the trajectory t,x,v,F of one model; bench, sweep: rows).
    Csv,
}

/// A finite number > 0 (tolerances and step sizes).
fn positive_number(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(x) if x.is_finite() && x > 0.0 => Ok(x),
        Ok(_) => Err(format!("{s} must be a finite number > 0")),
        Err(_) => Err(format!("\"{s}\" is not a number")),
    }
}

/// Which stop a system command runs: rigid, compliant or both side by side.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ContactChoice {
    /// Instantaneous impacts with the scene's restitution e.
    Rigid,
    /// A contact law (--law) through every impact.
    Compliant,
    /// Rigid and compliant, one after the other, on the same scene.
    Both,
}

/// How a system's stop acts (`system`, `orbit`, `bifurcation`, the system charts of `plot`).
#[derive(Debug, Clone, Args)]
pub struct ContactArgs {
    /// The stop: rigid (instantaneous, restitution e), compliant (--law), or both.
    #[arg(long, value_enum, default_value_t = ContactChoice::Rigid)]
    pub contact: ContactChoice,
    /// The compliant stop's law (a law id of `hertz-tui list`).
    #[arg(long, value_name = "MODEL", default_value = "hunt-crossley")]
    pub law: ForceModel,
    /// How the compliant law's damping is set: per-impact (from each impact's incoming speed),
    /// calibrated (to realise the scene's e), fitted (the scene's `[fit]` constant, for the law it
    /// names), or a number (the law's own constant).
    #[arg(long, value_name = "HOW", default_value = "per-impact", value_parser = damping_choice)]
    pub damping: DampingChoice,
}

/// `--damping`: how a compliant law's damping is set at each impact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DampingChoice {
    PerImpact,
    Calibrated,
    /// The material constant of the scene's `[fit]`.
    Fitted,
    Constant(f64),
}

fn damping_choice(s: &str) -> Result<DampingChoice, String> {
    match s {
        "per-impact" => Ok(DampingChoice::PerImpact),
        "calibrated" => Ok(DampingChoice::Calibrated),
        "fitted" => Ok(DampingChoice::Fitted),
        _ => match s.parse::<f64>() {
            Ok(x) if x.is_finite() && x >= 0.0 => Ok(DampingChoice::Constant(x)),
            _ => Err(format!(
                "\"{s}\" is not per-impact, calibrated, fitted or a finite number ≥ 0"
            )),
        },
    }
}

/// The budgets of a system's run.
#[derive(Debug, Clone, Args)]
pub struct RunArgs {
    /// Impacts simulated and dropped before recording (the transient).
    #[arg(long, value_name = "N", default_value_t = 500)]
    pub transient: usize,
    /// Impacts recorded after the transient.
    #[arg(long, value_name = "N", default_value_t = 200, value_parser = clap::value_parser!(u64).range(1..=10_000_000))]
    pub recorded: u64,
    /// Budget of impacts of one run, chatter included: a run that needs more is refused.
    #[arg(long, value_name = "N", default_value_t = 1_000_000)]
    pub max_impacts: usize,
    /// Forcing periods after which a run ends anyway (a body that stops impacting).
    #[arg(long, value_name = "P", default_value_t = 10_000.0, value_parser = positive_number)]
    pub max_periods: f64,
}

/// Options of `hertz-tui system`.
#[derive(Debug, Args)]
pub struct SystemArgs {
    #[command(flatten)]
    pub source: SceneSelection,
    #[command(flatten)]
    pub contact: ContactArgs,
    #[command(flatten)]
    pub run: RunArgs,
    /// Output format; csv prints the recorded impacts, one row each (or with --history the
    /// time history t,x,v,stop).
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
    /// csv and json: the time history over the recorded impacts, this many samples per forcing
    /// period (csv then prints it instead of the impacts).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(2..=100_000))]
    pub history: Option<u32>,
}

/// Where Newton starts a periodic orbit (`orbit`, and the branch's first orbit in `continue`).
#[derive(Debug, Args)]
pub struct OrbitStartArgs {
    /// m: forcing periods per orbit period (in `continue`, of the branch's first orbit; default:
    /// the period the run settles on after the transient, or 1 without one or with --phase and
    /// --speed).
    #[arg(long, value_name = "M", value_parser = clap::value_parser!(u32).range(1..=1000))]
    pub period: Option<u32>,
    /// n: impacts per orbit period (default: as for --period).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=1000))]
    pub impacts: Option<u32>,
    /// Newton's first impact: its forcing phase ωt, rad (with --speed; default: from the
    /// attractor reached after the transient).
    #[arg(
        long,
        value_name = "RAD",
        requires = "speed",
        allow_hyphen_values = true
    )]
    pub phase: Option<f64>,
    /// Newton's first impact: its approach speed, m/s (with --phase).
    #[arg(
        long,
        value_name = "M/S",
        requires = "phase",
        value_parser = positive_number,
        allow_hyphen_values = true
    )]
    pub speed: Option<f64>,
}

/// Options of `hertz-tui orbit`.
#[derive(Debug, Args)]
pub struct OrbitArgs {
    #[command(flatten)]
    pub source: SceneSelection,
    #[command(flatten)]
    pub contact: ContactArgs,
    #[command(flatten)]
    pub run: RunArgs,
    #[command(flatten)]
    pub start: OrbitStartArgs,
    /// Output format (table or json; csv prints the orbit's impacts).
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
}

/// Options of `hertz-tui bifurcation`.
#[derive(Debug, Args)]
pub struct BifurcationArgs {
    #[command(flatten)]
    pub source: SceneSelection,
    #[command(flatten)]
    pub contact: ContactArgs,
    #[command(flatten)]
    pub run: RunArgs,
    /// The key varied: system.gamma, system.amplitude, system.frequency, system.gap, …,
    /// impact.restitution or a body key.
    #[arg(long, value_name = "KEY")]
    pub param: Param,
    /// First value, SI units (Hz for system.frequency).
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub from: f64,
    /// Last value, SI units.
    #[arg(long, value_name = "B", allow_hyphen_values = true)]
    pub to: f64,
    /// Number of values, both ends included.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(2..=1_000_000))]
    pub points: u32,
    /// Budget of impacts of the whole diagram (values × (transient + recorded)).
    #[arg(long, value_name = "N", default_value_t = 50_000_000)]
    pub budget: usize,
    /// Output format: csv (streamed, one row per recorded impact), json or table (one row per
    /// value).
    #[arg(long, value_enum, default_value_t = Format::Csv)]
    pub format: Format,
}
