//! The `hertz-tui` binary: the explorer by default, `list` and `solve` headless.

use std::io;
use std::process::ExitCode;

use clap::Parser;
use hertz_tui::cli::{self, Cli, CliError, Marker};
use hertz_tui::model::presets::DEFAULT_SCENE;
use hertz_tui::ui::config::Config;
use hertz_tui::ui::{MarkerStyle, Opened};

/// mimalloc rather than the system allocator: the explorer's frame builds and drops its strings,
/// spans and sample vectors every edit, and glibc's malloc and free took 9 % of an edit cycle's
/// instructions. Set in the binary, not the library, so that a program using `hertz_tui` as a
/// library keeps its own allocator (the tests and benches run on the system one).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() -> color_eyre::Result<ExitCode> {
    color_eyre::install()?;
    let args = Cli::parse();
    let outcome = match &args.command {
        Some(command) => cli::run(command, &mut io::stdout().lock()),
        None => return explore(&args),
    };
    Ok(exit(outcome))
}

/// Opens the explorer on the chosen scene. A bad scene is a user error (exit 2); failures of the
/// terminal itself go through color_eyre.
fn explore(args: &Cli) -> color_eyre::Result<ExitCode> {
    let config = match Config::load() {
        Ok(config) => config,
        Err(e) => {
            eprintln!("error: {e}");
            return Ok(ExitCode::from(2));
        }
    };
    // `--scene`, else the config file's, else the paper's Fig. 5.
    let source = args
        .scene
        .clone()
        .or_else(|| config.scene.clone())
        .unwrap_or_else(|| DEFAULT_SCENE.to_string());
    let opened = cli::load_registry()
        .and_then(|registry| Ok(Opened::read(&registry, &source, &args.overrides)?));
    match opened {
        Ok(opened) => {
            let marker = match args.marker {
                Marker::Braille => MarkerStyle::Braille,
                Marker::Dot => MarkerStyle::Dot,
                Marker::Block => MarkerStyle::Block,
            };
            hertz_tui::ui::run(opened, &source, args.data.as_deref(), marker, config)?;
            Ok(ExitCode::SUCCESS)
        }
        Err(e) => Ok(exit(Err(e))),
    }
}

/// The exit status of a headless outcome; user errors are printed as `error: …`.
fn exit(outcome: Result<(), CliError>) -> ExitCode {
    match outcome {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) if e.is_broken_pipe() => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(e.exit_code())
        }
    }
}
