//! Options of `hertz-tui map` and `hertz-tui merge`.

use std::path::PathBuf;

use clap::Args;

use crate::cli::args::{ContactArgs, Format, SceneSelection};
use crate::model::system::Param;
use crate::model::system::map::Shard;

/// Options of `hertz-tui map`.
#[derive(Debug, Args)]
pub struct MapArgs {
    #[command(flatten)]
    pub source: SceneSelection,
    #[command(flatten)]
    pub contact: ContactArgs,
    /// The key along a row (the attractor is followed from cell to cell along it).
    #[arg(long, value_name = "KEY")]
    pub x: Param,
    /// The key across rows (rows run in parallel and are dealt into shards).
    #[arg(long, value_name = "KEY")]
    pub y: Param,
    /// First value of --x, then of --y: give it twice, in that order (SI units).
    #[arg(long, value_name = "A", required = true, allow_hyphen_values = true)]
    pub from: Vec<f64>,
    /// Last value of --x, then of --y.
    #[arg(long, value_name = "B", required = true, allow_hyphen_values = true)]
    pub to: Vec<f64>,
    /// Number of values of --x, then of --y (each ≥ 2).
    #[arg(long, value_name = "N", required = true)]
    pub points: Vec<u32>,
    /// Impacts run and dropped at each cell before recording.
    #[arg(long, value_name = "N", default_value_t = 300)]
    pub transient: usize,
    /// Impacts recorded at each cell (the period is searched among them, up to half of them).
    #[arg(long, value_name = "N", default_value_t = 64, value_parser = clap::value_parser!(u64).range(2..=100_000))]
    pub recorded: u64,
    /// Impact-map steps the largest Lyapunov exponent is averaged over (0: none).
    #[arg(long, value_name = "N", default_value_t = 200)]
    pub lyapunov: usize,
    /// Two impacts are the same map point within this fraction of the largest speed and of 2π.
    #[arg(long, value_name = "TOL", default_value_t = 1e-5)]
    pub period_tolerance: f64,
    /// |λ| per impact at most this reads as zero (quasi-periodic).
    #[arg(long, value_name = "TOL", default_value_t = 0.01)]
    pub lyapunov_tolerance: f64,
    /// Budget of impacts of one cell's run, chatter included.
    #[arg(long, value_name = "N", default_value_t = 100_000)]
    pub max_impacts: usize,
    /// Forcing periods after which a cell's run ends anyway (no impact).
    #[arg(long, value_name = "P", default_value_t = 20_000.0)]
    pub max_periods: f64,
    /// Budget of impacts of the part computed: cells × (transient + recorded + lyapunov).
    #[arg(long, value_name = "N", default_value_t = 10_000_000_000)]
    pub budget: u128,
    /// Compute only shard I of N: the rows iy with iy mod N = I − 1 (`hertz-tui merge` joins them).
    #[arg(long, value_name = "I/N", value_parser = shard)]
    pub shard: Option<Shard>,
    /// csv or json (the map file), or table (the map drawn as text with its legend).
    #[arg(long, value_enum, default_value_t = Format::Csv)]
    pub format: Format,
    /// Write the map file here (stdout then gets the drawing).
    #[arg(long, short = 'o', value_name = "FILE")]
    pub out: Option<PathBuf>,
    /// Also draw the map to this SVG or PNG figure.
    #[arg(long, value_name = "FILE")]
    pub figure: Option<PathBuf>,
}

/// Options of `hertz-tui merge`.
#[derive(Debug, Args)]
pub struct MergeArgs {
    /// The shards' map files (all of one map, every shard once, csv or json).
    #[arg(required = true, value_name = "FILES")]
    pub files: Vec<PathBuf>,
    /// The merged map file.
    #[arg(long, short = 'o', value_name = "FILE", required = true)]
    pub out: PathBuf,
    /// Also draw the merged map to this SVG or PNG figure.
    #[arg(long, value_name = "FILE")]
    pub figure: Option<PathBuf>,
}

/// `--shard I/N`.
fn shard(s: &str) -> Result<Shard, String> {
    let bad = || format!("\"{s}\" is not a shard I/N with 1 ≤ I ≤ N, e.g. 2/8");
    let (i, n) = s.split_once('/').ok_or_else(bad)?;
    let (i, n) = (
        i.trim().parse().map_err(|_| bad())?,
        n.trim().parse().map_err(|_| bad())?,
    );
    Shard::new(i, n).ok_or_else(bad)
}
