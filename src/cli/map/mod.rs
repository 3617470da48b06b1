//! `hertz-tui map` and `hertz-tui merge`: two-parameter maps of a system's motion, computed whole
//! or in shards that merge into the same file byte for byte (docs/maps.md).

pub mod args;
pub mod draw;
pub mod file;
pub mod merge;

use std::io::Write;
use std::path::Path;

use crate::chart::figure;
use crate::chart::map::{MapPoint, look, motion_map};
use crate::model::presets::Registry;
use crate::model::system::map::{
    Axis, Cause, Cell, Grid, MapOptions, Shard, Tolerances, difference, map as compute,
};
use crate::model::system::{Contact, Param, RunOptions, SystemError, SystemModel};

use super::args::Format;
use super::error::CliError;
use super::system::{contact_label, contacts, failed, load_system};
pub use args::{MapArgs, MergeArgs};
use file::{AxisSpec, Header, Kind, Layer, MapFile, Row, fnv1a};

/// Figure size, pixels.
const FIGURE: (u32, u32) = (1000, 800);

fn usage(text: String) -> CliError {
    CliError::Usage(text)
}

/// The grid the arguments ask for: the first --from/--to/--points belong to --x, the second to --y.
fn grid(args: &MapArgs) -> Result<Grid, CliError> {
    let two = |name: &str, n: usize| {
        if n == 2 {
            Ok(())
        } else {
            Err(usage(format!(
                "{name} must be given twice, first for --x then for --y (got it {n} time{})",
                if n == 1 { "" } else { "s" }
            )))
        }
    };
    two("--from", args.from.len())?;
    two("--to", args.to.len())?;
    two("--points", args.points.len())?;
    for v in args.from.iter().chain(&args.to) {
        if !v.is_finite() {
            return Err(usage(format!(
                "--from and --to must be finite numbers, got {v}"
            )));
        }
    }
    for &p in &args.points {
        if p < 2 {
            return Err(usage(format!("--points must be at least 2, got {p}")));
        }
    }
    let axis = |param: Param, i: usize| Axis {
        param,
        from: args.from[i],
        to: args.to[i],
        points: args.points[i] as usize,
    };
    Ok(Grid {
        x: axis(args.x, 0),
        y: axis(args.y, 1),
    })
}

fn options(args: &MapArgs) -> Result<MapOptions, CliError> {
    for (name, v) in [
        ("--period-tolerance", args.period_tolerance),
        ("--lyapunov-tolerance", args.lyapunov_tolerance),
        ("--max-periods", args.max_periods),
    ] {
        if !(v.is_finite() && v > 0.0) {
            return Err(usage(format!(
                "{name} must be a finite number > 0, got {v}"
            )));
        }
    }
    let recorded = args.recorded as usize;
    Ok(MapOptions {
        run: RunOptions {
            transient_impacts: args.transient,
            recorded_impacts: recorded,
            max_periods: args.max_periods,
            max_impacts: args.max_impacts,
            samples_per_period: 0,
            initial: None,
        },
        lyapunov_impacts: args.lyapunov,
        tolerances: Tolerances {
            period: args.period_tolerance,
            lyapunov: args.lyapunov_tolerance,
            max_period_impacts: (recorded / 2).clamp(1, 64),
        },
        max_total_impacts: args.budget,
    })
}

fn axis_spec(a: &Axis) -> AxisSpec {
    AxisSpec {
        key: a.param.path(),
        from: a.from,
        to: a.to,
        points: a.points,
    }
}

fn rows_of(cells: &[Cell]) -> Vec<Row> {
    cells
        .iter()
        .map(|c| {
            let period = c.motion.period();
            Row {
                ix: c.ix,
                iy: c.iy,
                x: c.x,
                y: c.y,
                motion: c.motion.name().to_string(),
                impacts: period.map(|p| p.0),
                periods: period.map(|p| p.1),
                lyapunov: c.lyapunov,
                error: c.error.clone(),
            }
        })
        .collect()
}

/// How a contact is described in the header (its law and damping too).
fn contact_words(contact: &Contact) -> String {
    match contact {
        Contact::Rigid { .. } => "rigid".into(),
        Contact::Compliant { model, damping } => format!("{model} ({damping:?})"),
    }
}

/// Computes the map (or the shard) the arguments ask for.
pub fn compute_file(args: &MapArgs, registry: &Registry) -> Result<MapFile, CliError> {
    let grid = grid(args)?;
    let options = options(args)?;
    let model: SystemModel = load_system(&args.source, registry)?;
    let stops = contacts(&args.contact, &model)?;
    let shard = args.shard.unwrap_or(Shard::WHOLE);
    let run = format!(
        "transient={} recorded={} lyapunov={} period-tolerance={} lyapunov-tolerance={} max-periods={} max-impacts={}",
        args.transient,
        args.recorded,
        args.lyapunov,
        args.period_tolerance,
        args.lyapunov_tolerance,
        args.max_periods,
        args.max_impacts
    );
    let contact = stops
        .iter()
        .map(contact_words)
        .collect::<Vec<_>>()
        .join(" and ");
    // Everything the cells depend on: shards of different systems never merge.
    let identity = format!("{model:?}|{stops:?}|{grid:?}|{options:?}");
    let header = Header {
        scene: args.source.scene.clone(),
        set: args
            .source
            .overrides
            .iter()
            .map(ToString::to_string)
            .collect::<Vec<_>>()
            .join(" "),
        contact,
        x: axis_spec(&grid.x),
        y: axis_spec(&grid.y),
        run,
        model: format!("{:016x}", fnv1a(identity.as_bytes())),
    };
    let mut layers = Vec::new();
    let mut maps = Vec::new();
    for stop in &stops {
        let rows = compute(&model, stop, &grid, shard, &options).map_err(|e| match e {
            SystemError::DiagramBudget {
                needed,
                values,
                per_value,
                ..
            } => usage(format!(
                "the map needs {needed} impacts ({values} cells × {per_value} impacts a cell), more than --budget {}; use fewer points or impacts a cell, or shards (--shard I/N)",
                args.budget
            )),
            e => failed(stop, e),
        })?;
        layers.push(Layer {
            contact: contact_label(stop),
            cells: rows_of(&rows.cells),
        });
        maps.push(rows.cells);
    }
    if let [rigid, compliant] = &maps[..] {
        let cells = difference(rigid, compliant)
            .into_iter()
            .map(|d| Row {
                ix: d.ix,
                iy: d.iy,
                x: d.x,
                y: d.y,
                motion: d.agreement.name().to_string(),
                impacts: None,
                periods: None,
                lyapunov: d.lyapunov_change,
                // The difference layer's `error` column says why the stops differ, where known.
                error: d.cause.map(Cause::words),
            })
            .collect();
        layers.push(Layer {
            contact: "difference".into(),
            cells,
        });
    }
    Ok(MapFile {
        header,
        shard: args.shard,
        layers,
    })
}

fn render(file: &MapFile, kind: Kind) -> Result<String, CliError> {
    match kind {
        Kind::Csv => Ok(file.to_csv()),
        Kind::Json => file.to_json().map_err(|e| CliError::Output(e.into())),
    }
}

fn write_file(path: &Path, text: &str) -> Result<(), CliError> {
    std::fs::write(path, text).map_err(|e| usage(format!("cannot write {}: {e}", path.display())))
}

/// The map drawn as a figure, one chart per layer.
pub fn figure(file: &MapFile, path: &Path) -> Result<(), CliError> {
    let unit = |key: &str| match key.parse::<Param>() {
        Ok(Param::System(k)) if k.unit() != "N or m" => k.unit(),
        Ok(Param::Scene(k)) => k.unit(),
        _ => "",
    };
    let (hx, hy) = (&file.header.x, &file.header.y);
    let charts: Vec<_> = file
        .layers
        .iter()
        .map(|layer| {
            let points: Vec<MapPoint> = layer
                .cells
                .iter()
                .map(|c| MapPoint {
                    x: c.x,
                    y: c.y,
                    look: look(&c.motion, c.impacts),
                })
                .collect();
            motion_map(
                format!("{} map of {}", layer.contact, file.header.scene),
                (&hx.key, unit(&hx.key), (hx.from, hx.to)),
                (&hy.key, unit(&hy.key), (hy.from, hy.to)),
                &points,
                (9, 8),
            )
        })
        .collect();
    figure::write(&charts, path, FIGURE).map_err(|e| usage(e.to_string()))
}

/// `hertz-tui map`.
pub fn run(args: &MapArgs, registry: &Registry, out: &mut dyn Write) -> Result<(), CliError> {
    let file = compute_file(args, registry)?;
    if let Some(path) = &args.figure {
        figure::Format::of(path).map_err(|e| usage(e.to_string()))?;
        figure(&file, path)?;
    }
    let kind = match args.format {
        Format::Json => Some(Kind::Json),
        Format::Csv => Some(Kind::Csv),
        Format::Table => None,
    };
    match (&args.out, kind) {
        (Some(path), kind) => {
            write_file(path, &render(&file, kind.unwrap_or(Kind::Csv))?)?;
            out.write_all(draw::draw(&file).as_bytes())?;
        }
        (None, Some(kind)) => out.write_all(render(&file, kind)?.as_bytes())?,
        (None, None) => out.write_all(draw::draw(&file).as_bytes())?,
    }
    Ok(out.flush()?)
}

/// `hertz-tui merge`.
pub fn run_merge(args: &MergeArgs, out: &mut dyn Write) -> Result<(), CliError> {
    let files = args
        .files
        .iter()
        .map(|p| {
            std::fs::read_to_string(p)
                .map(|text| (p.display().to_string(), text))
                .map_err(|e| usage(format!("cannot read {}: {e}", p.display())))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let (merged, kind) = merge::merge(&files).map_err(usage)?;
    write_file(&args.out, &render(&merged, kind)?)?;
    if let Some(path) = &args.figure {
        figure(&merged, path)?;
    }
    out.write_all(draw::draw(&merged).as_bytes())?;
    Ok(out.flush()?)
}
