//! The command line (clap): no subcommand opens the explorer; `list` and `solve` are headless.

use clap::{Args, Parser, Subcommand, ValueEnum};

use crate::model::ForceModel;
use crate::model::impact::MethodChoice;
use crate::model::overrides::Override;
use crate::model::scene_key::SceneKey;

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
    /// Override a key of the explorer's scene by its dotted path, e.g. impact.v0=0.5 (repeatable).
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub overrides: Vec<Override>,
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
    /// Write a chart as the explorer draws it to an SVG or PNG figure.
    Plot(PlotArgs),
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
    /// Override a key of every scene by its dotted path (repeatable).
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
    /// Sweep: the scene key varied.
    #[arg(long, value_name = "KEY", default_value = "impact.v0")]
    pub param: SceneKey,
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
    /// Override a scene key by its dotted path (repeatable): impact.v0=0.5, body1.radius=0.02,
    /// body1.shape=plane, body1.material=aluminium-alloy, body1.material.youngs_modulus=7e10.
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
