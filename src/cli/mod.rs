//! Headless subcommands over the model layer.

pub mod args;
pub mod bench;
pub mod bifurcation;
pub mod continuation;
pub mod error;
pub mod fit;
mod in_order;
mod layout;
mod list;
pub mod map;
pub mod orbit;
pub mod plot;
mod plot_fit;
mod plot_system;
mod report;
pub mod restitution;
pub mod solve;
pub mod sweep;
pub mod system;
pub mod translate;
pub mod units;

use std::io::Write;

pub use args::{
    BenchArgs, Cli, Command, Format, Marker, PlotArgs, RestitutionArgs, SceneSelection, SolveArgs,
    SweepArgs, TranslateArgs, TranslateFormat,
};
pub use error::CliError;

use crate::format::csv::trajectory_csv;
use crate::model::presets::Registry;

/// Loads the presets and reports problems with user presets as warnings on stderr.
pub fn load_registry() -> Result<Registry, CliError> {
    let registry = Registry::load()?;
    for warning in registry.warnings() {
        eprintln!("warning: {warning}");
    }
    Ok(registry)
}

/// Pretty-printed JSON with a final newline: the `--format json` output of every subcommand.
pub(crate) fn json<T: serde::Serialize>(value: &T) -> Result<String, CliError> {
    let mut text = serde_json::to_string_pretty(value).map_err(|e| CliError::Output(e.into()))?;
    text.push('\n');
    Ok(text)
}

/// Runs a headless subcommand, writing its output to `out`.
pub fn run(command: &Command, out: &mut dyn Write) -> Result<(), CliError> {
    let registry = load_registry()?;
    let text = match command {
        Command::List => list::render(&registry),
        Command::Solve(args) => match args.format {
            Format::Table => report::render(&solve::report(args, &registry)?),
            Format::Json => json(&solve::report(args, &registry)?)?,
            Format::Csv => {
                let solution = solve::trajectory(args, &registry)?;
                trajectory_csv(&solution, args.points as usize).map_err(CliError::Usage)?
            }
        },
        Command::Bench(args) => bench::run(args, &registry)?,
        Command::Sweep(args) if args.format == Format::Csv => {
            sweep::stream_csv(args, &registry, out)?;
            return Ok(out.flush()?);
        }
        Command::Sweep(args) => sweep::run(args, &registry)?,
        Command::Restitution(args) => restitution::run(args, &registry)?,
        Command::Translate(args) => translate::run(args, &registry)?,
        Command::Fit(args) => fit::run(args, &registry)?,
        Command::Plot(args) => plot::run(args, &registry)?,
        Command::System(args) => system::run(args, &registry)?,
        Command::Orbit(args) => orbit::run(args, &registry)?,
        Command::Bifurcation(args) if args.format == Format::Csv => {
            bifurcation::stream_csv(args, &registry, out)?;
            return Ok(out.flush()?);
        }
        Command::Bifurcation(args) => bifurcation::run(args, &registry)?,
        Command::Continue(args) => continuation::run(args, &registry)?,
        Command::Map(args) => return map::run(args, &registry, out),
        Command::Merge(args) => return map::run_merge(args, out),
    };
    out.write_all(text.as_bytes())?;
    out.flush()?;
    Ok(())
}
