//! `hertz-tui continue`: a branch of periodic orbits of a system in one key by pseudo-arclength
//! continuation, its stability and special points (folds, period doublings, grazing), the doubled
//! branch switched onto at a period doubling, and a special point's curve in a second key; for
//! each stop asked for, as a table, JSON, CSV and a figure (docs/continuation.md).

use std::ops::ControlFlow;
use std::path::PathBuf;

use clap::{Args, ValueEnum};
use serde::Serialize;

use crate::chart::Chart;
use crate::chart::continuation::{self as plot, BranchCurve};
use crate::chart::figure;
use crate::chart::system::{Approach, Branch as DiagramBranch, DiagramAxes};
use crate::format::csv;
use crate::model::presets::Registry;
use crate::model::system::continuation::{
    Branch, BranchPoint, ContinuationError, ContinuationOptions, SpecialKind, SpecialPoint,
    continue_orbit, continue_special, switch_at_period_doubling,
};
use crate::model::system::{self, Contact, DiagramOptions, Param, SystemModel};

use super::args::{ContactArgs, Format, OrbitStartArgs, RunArgs, SceneSelection};
use super::bifurcation::values;
use super::error::CliError;
use super::json;
use super::layout::columns;
use super::orbit;
use super::system::{GroupsRow, contact_label, contacts, failed, load_system, run_options};
use super::units::compact_number;

/// Rows of the branch the table shows (json and csv give every point).
const TABLE_ROWS: usize = 16;

/// Tick labels of a figure.
const BUDGET: (usize, usize) = (9, 8);

/// Which special point a curve in the second key follows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FollowChoice {
    Fold,
    PeriodDoubling,
    /// An impact speed reaching zero.
    GrazingImpact,
    /// A flight's gap minimum reaching the stop.
    GrazingFlight,
}

impl FollowChoice {
    fn kind(self) -> SpecialKind {
        match self {
            FollowChoice::Fold => SpecialKind::Fold,
            FollowChoice::PeriodDoubling => SpecialKind::PeriodDoubling,
            FollowChoice::GrazingImpact => SpecialKind::GrazingImpact,
            FollowChoice::GrazingFlight => SpecialKind::GrazingFlight,
        }
    }
}

/// Options of `hertz-tui continue`.
#[derive(Debug, Args)]
pub struct ContinueArgs {
    #[command(flatten)]
    pub source: SceneSelection,
    #[command(flatten)]
    pub contact: ContactArgs,
    /// The run that finds the starting orbit's attractor (without --phase/--speed), and the
    /// brute-force diagram of --diagram.
    #[command(flatten)]
    pub run: RunArgs,
    /// The key continued: system.gamma, system.amplitude, system.frequency, system.gap, …,
    /// impact.restitution or a body key.
    #[arg(long, value_name = "KEY")]
    pub param: Param,
    /// Where the branch starts (Newton finds the orbit there), SI units (Hz for
    /// system.frequency).
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub from: f64,
    /// Where it heads; it ends when it leaves [A, B] either way.
    #[arg(long, value_name = "B", allow_hyphen_values = true)]
    pub to: f64,
    /// A second key: the special point (--follow) found on the branch at --from2 is followed in
    /// it to --to2 (a two-parameter curve).
    #[arg(long, value_name = "KEY", requires_all = ["from2", "to2"])]
    pub second: Option<Param>,
    /// The second key's value the branch is computed at, SI.
    #[arg(
        long,
        value_name = "C",
        allow_hyphen_values = true,
        requires = "second"
    )]
    pub from2: Option<f64>,
    /// The second key's end, SI.
    #[arg(
        long,
        value_name = "D",
        allow_hyphen_values = true,
        requires = "second"
    )]
    pub to2: Option<f64>,
    /// The special point followed in the second key (default: the first found on the branch).
    #[arg(long, value_enum, requires = "second")]
    pub follow: Option<FollowChoice>,
    /// Also follow the doubled branch born at the first period doubling.
    #[arg(long)]
    pub doubled: bool,
    /// Newton's start of the branch's first orbit.
    #[command(flatten)]
    pub start: OrbitStartArgs,
    /// Points of a branch at most.
    #[arg(long, value_name = "N", default_value_t = 400, value_parser = clap::value_parser!(u32).range(2..=100_000))]
    pub max_points: u32,
    /// Largest arclength step (scaled: phases in rad, speeds and the key over their scales).
    #[arg(long, value_name = "DS", default_value_t = 0.05)]
    pub max_step: f64,
    /// The figure: the brute-force diagram under the branch, at this many values of the key.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(2..=100_000))]
    pub diagram: Option<u32>,
    /// Write a figure (.svg or .png): the branches over the diagram, and the curve.
    #[arg(short = 'o', long = "out", value_name = "FILE")]
    pub out: Option<PathBuf>,
    /// Figure size in pixels, WIDTHxHEIGHT.
    #[arg(long, value_name = "WxH", default_value = "1200x800")]
    pub size: String,
    /// Output format: table, json or csv (one row per impact of every orbit).
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
}

/// One stop's results.
#[derive(Debug, Clone, Serialize)]
pub struct ContactResult {
    pub contact: String,
    pub branch: Branch,
    /// The doubled branch born at the first period doubling (with --doubled).
    pub doubled: Option<Branch>,
    /// The special point's curve in the second key (with --second).
    pub curve: Option<Branch>,
}

/// The JSON document of `continue`.
#[derive(Debug, Clone, Serialize)]
pub struct ContinueReport {
    pub scene: String,
    pub groups: GroupsRow,
    pub key: String,
    pub second: Option<String>,
    pub results: Vec<ContactResult>,
}

/// A continuation error, naming the stop.
fn refused(contact: &Contact, e: ContinuationError) -> CliError {
    match e {
        ContinuationError::System(e) => failed(contact, e),
        e => CliError::Usage(format!("{} stop: {e}", contact_label(contact))),
    }
}

fn check(args: &ContinueArgs) -> Result<(), CliError> {
    let numbers = [
        ("--from", Some(args.from)),
        ("--to", Some(args.to)),
        ("--from2", args.from2),
        ("--to2", args.to2),
        ("--phase", args.start.phase),
    ];
    for (name, v) in numbers {
        if let Some(v) = v
            && !v.is_finite()
        {
            return Err(CliError::Usage(format!(
                "{name} must be a finite number, got {v}"
            )));
        }
    }
    if args.from == args.to {
        return Err(CliError::Usage("--from and --to must differ".into()));
    }
    if !(args.max_step.is_finite() && args.max_step > 0.0) {
        return Err(CliError::Usage(format!(
            "--max-step must be a finite number > 0, got {}",
            args.max_step
        )));
    }
    Ok(())
}

/// The model the branch runs on: the scene, with the second key at --from2.
fn model(args: &ContinueArgs, registry: &Registry) -> Result<SystemModel, CliError> {
    let model = load_system(&args.source, registry)?;
    match (args.second, args.from2) {
        (Some(key), Some(value)) => key
            .apply(&model, value)
            .map_err(|e| failed(&Contact::rigid(model.restitution), e)),
        _ => Ok(model),
    }
}

/// Everything asked for, for every stop.
pub fn report(args: &ContinueArgs, registry: &Registry) -> Result<ContinueReport, CliError> {
    check(args)?;
    let model = model(args, registry)?;
    let options = ContinuationOptions {
        max_points: args.max_points as usize,
        max_step: args.max_step,
        initial_step: args
            .max_step
            .min(ContinuationOptions::default().initial_step),
        ..ContinuationOptions::default()
    };
    let guess = orbit::guess(&args.start, &args.run);
    let range = (args.from, args.to);
    let mut results = Vec::new();
    for contact in contacts(&args.contact, &model)? {
        let branch = continue_orbit(&model, &contact, args.param, range, &guess, &options)
            .map_err(|e| refused(&contact, e))?;
        let doubled = match branch.special(SpecialKind::PeriodDoubling).next() {
            Some(pd) if args.doubled => Some(
                switch_at_period_doubling(
                    &model, &contact, args.param, range, &branch, pd, &options,
                )
                .map_err(|e| refused(&contact, e))?,
            ),
            _ => None,
        };
        let curve = match (args.second, args.from2, args.to2) {
            (Some(second), Some(from2), Some(to2)) => {
                let special = followed(&branch, args.follow).ok_or_else(|| {
                    CliError::Usage(format!(
                        "{} stop: the branch has no {} to follow in {}",
                        contact_label(&contact),
                        args.follow.map_or("special point", |f| f.kind().label()),
                        second.path()
                    ))
                })?;
                Some(
                    continue_special(
                        &model,
                        &contact,
                        args.param,
                        second,
                        (from2, to2),
                        &branch,
                        special,
                        &options,
                    )
                    .map_err(|e| refused(&contact, e))?,
                )
            }
            _ => None,
        };
        results.push(ContactResult {
            contact: contact_label(&contact),
            branch,
            doubled,
            curve,
        });
    }
    Ok(ContinueReport {
        scene: model
            .scene
            .as_ref()
            .map_or_else(String::new, |s| s.name.clone()),
        groups: GroupsRow::of(&model),
        key: args.param.path(),
        second: args.second.map(Param::path),
        results,
    })
}

fn followed(branch: &Branch, follow: Option<FollowChoice>) -> Option<&SpecialPoint> {
    match follow {
        Some(f) => branch.special(f.kind()).next(),
        None => branch.specials.first(),
    }
}

/// Runs `continue`: the output in the format asked for, and the figure when asked.
pub fn run(args: &ContinueArgs, registry: &Registry) -> Result<String, CliError> {
    let report = report(args, registry)?;
    let mut text = match args.format {
        Format::Json => json(&report)?,
        Format::Csv => to_csv(&report),
        Format::Table => table(&report),
    };
    if let Some(out) = &args.out {
        let usage = |e: figure::FigureError| CliError::Usage(e.to_string());
        let size = figure::parse_size(&args.size).map_err(usage)?;
        figure::Format::of(out).map_err(usage)?;
        let charts = charts(args, registry, &report)?;
        figure::write(&charts, out, size).map_err(usage)?;
        if args.format == Format::Table {
            text.push_str(&format!("\nwrote {}\n", out.display()));
        }
    }
    Ok(text)
}

/// `1.2345` to 8 significant digits (the table's values; csv and json give all digits).
fn n(v: f64) -> String {
    compact_number(v, 8)
}

fn multiplier_text(p: &BranchPoint) -> String {
    p.multipliers
        .iter()
        .map(|z| {
            if z.im == 0.0 {
                compact_number(z.re, 5)
            } else {
                format!(
                    "{}±{}i",
                    compact_number(z.re, 4),
                    compact_number(z.im.abs(), 4)
                )
            }
        })
        .collect::<Vec<_>>()
        .join(", ")
}

fn describe(b: &Branch) -> String {
    let n = b.stops.len();
    format!(
        "period-{} orbit ({} impact{} per period), {} points; {}",
        b.cycles,
        n,
        if n == 1 { "" } else { "s" },
        b.points.len(),
        b.end.describe()
    )
}

fn branch_table(out: &mut String, b: &Branch) {
    let keys = &b.keys;
    let mut rows = vec![{
        let mut h = vec!["special".to_string()];
        h.extend(keys.iter().cloned());
        h.extend(["v_in [m/s]", "φ [rad]", "multipliers"].map(String::from));
        h
    }];
    for s in &b.specials {
        let mut row = vec![s.kind.label().to_string()];
        row.extend(s.point.values.iter().map(|v| n(*v)));
        let first = s.point.points.first();
        row.push(first.map_or_else(String::new, |p| compact_number(p.v_in, 6)));
        row.push(first.map_or_else(String::new, |p| compact_number(p.phase, 6)));
        // A compliant grazing's J is the stroboscopic map's, finite there.
        row.push(
            if s.kind == SpecialKind::GrazingImpact && b.contact == "rigid" {
                "— (J singular at zero speed)".into()
            } else {
                multiplier_text(&s.point)
            },
        );
        rows.push(row);
    }
    if rows.len() > 1 {
        out.push_str(&columns(&rows, "  "));
    } else {
        out.push_str("  no special point on it\n");
    }
    let mut rows = vec![{
        let mut h: Vec<String> = keys.clone();
        h.extend(["v_in [m/s]", "φ [rad]", "max |λ|", "stable"].map(String::from));
        h
    }];
    let stride = b.points.len().div_ceil(TABLE_ROWS).max(1);
    for (i, p) in b.points.iter().enumerate() {
        if i % stride != 0 && i + 1 != b.points.len() {
            continue;
        }
        let mut row: Vec<String> = p.values.iter().map(|v| n(*v)).collect();
        let first = p.points.first();
        row.push(first.map_or_else(String::new, |q| compact_number(q.v_in, 6)));
        row.push(first.map_or_else(String::new, |q| compact_number(q.phase, 6)));
        let grazing =
            p.min_speed.abs() < 1e-9 * p.points.iter().map(|q| q.v_in.abs()).fold(1.0, f64::max);
        row.push(if grazing {
            "—".into()
        } else {
            compact_number(
                p.multipliers.iter().map(|z| z.norm()).fold(0.0, f64::max),
                5,
            )
        });
        row.push(if p.stable { "yes" } else { "no" }.into());
        rows.push(row);
    }
    out.push_str(&columns(&rows, "  "));
}

fn table(report: &ContinueReport) -> String {
    let mut out = format!("{}\n  {}\n", report.scene, report.groups.line());
    for r in &report.results {
        out.push_str(&format!(
            "\n{} over {}: {}\n",
            r.contact,
            report.key,
            describe(&r.branch)
        ));
        branch_table(&mut out, &r.branch);
        if let Some(d) = &r.doubled {
            out.push_str(&format!(
                "\n{} doubled branch: {}\n",
                r.contact,
                describe(d)
            ));
            branch_table(&mut out, d);
        }
        if let Some(c) = &r.curve {
            out.push_str(&format!(
                "\n{} {} curve in ({}): {} points; {}\n",
                r.contact,
                c.follows.map_or("special", SpecialKind::label),
                c.keys.join(", "),
                c.points.len(),
                c.end.describe()
            ));
            branch_table(&mut out, c);
        }
    }
    out
}

fn to_csv(report: &ContinueReport) -> String {
    let second = report.second.as_deref().map(csv::field);
    let mut out = format!(
        "contact,branch,{}{},impact,t,phase,stop,v_in,lambda1_re,lambda1_im,lambda2_re,lambda2_im,det_j,stable,min_gap,special\n",
        csv::field(&report.key),
        second.map_or_else(String::new, |s| format!(",{s}"))
    );
    let row = |out: &mut String, contact: &str, name: &str, p: &BranchPoint, special: &str| {
        let values = if report.second.is_some() && p.values.len() == 1 {
            format!("{:e},", p.values[0])
        } else {
            p.values
                .iter()
                .map(|v| format!("{v:e}"))
                .collect::<Vec<_>>()
                .join(",")
        };
        let lambda: Vec<String> = p
            .multipliers
            .iter()
            .flat_map(|z| [format!("{:e}", z.re), format!("{:e}", z.im)])
            .collect();
        for (i, q) in p.points.iter().enumerate() {
            out.push_str(&format!(
                "{},{name},{values},{},{:e},{:e},{},{:e},{},{:e},{},{},{special}\n",
                csv::field(contact),
                i + 1,
                q.t,
                q.phase,
                q.stop,
                q.v_in,
                lambda.join(","),
                p.jacobian_det,
                p.stable,
                p.min_gap.map_or_else(String::new, |g| format!("{g:e}")),
            ));
        }
    };
    for r in &report.results {
        let parts = [
            Some(("branch", &r.branch)),
            r.doubled.as_ref().map(|d| ("doubled", d)),
            r.curve.as_ref().map(|c| ("curve", c)),
        ];
        for (name, b) in parts.into_iter().flatten() {
            for (i, p) in b.points.iter().enumerate() {
                row(&mut out, &r.contact, name, p, "");
                for s in b.specials.iter().filter(|s| s.after == i) {
                    row(&mut out, &r.contact, name, &s.point, s.kind.label());
                }
            }
        }
    }
    out
}

/// A branch as the chart draws it: every impact's v_in against the key, by stability, with its
/// special points.
fn curve_of(b: &Branch) -> BranchCurve {
    let mut c = BranchCurve {
        label: format!("period-{}", b.cycles),
        ..BranchCurve::default()
    };
    let impacts = b.stops.len();
    for k in 0..impacts {
        let points: Vec<(f64, f64, bool)> = b
            .points
            .iter()
            .filter_map(|p| p.points.get(k).map(|q| (p.values[0], q.v_in, p.stable)))
            .collect();
        c.push_impact(&points);
    }
    for s in &b.specials {
        let label = match s.kind {
            SpecialKind::Fold => "fold",
            SpecialKind::PeriodDoubling => "PD",
            SpecialKind::GrazingImpact | SpecialKind::GrazingFlight => "grazing",
        };
        if let Some(q) = s.point.points.first() {
            c.specials.push((
                s.point.values[0],
                q.v_in,
                format!("{label} {}", compact_number(s.point.values[0], 5)),
            ));
        }
    }
    c
}

fn approach(report_contact: &str, contacts: &[Contact]) -> Approach {
    contacts
        .iter()
        .find(|c| contact_label(c) == report_contact)
        .map_or(Approach::Rigid, Approach::of)
}

/// The figure's charts: the branches (and doubled branches) over the diagram; the curves.
fn charts(
    args: &ContinueArgs,
    registry: &Registry,
    report: &ContinueReport,
) -> Result<Vec<Chart>, CliError> {
    let model = model(args, registry)?;
    let contacts = contacts(&args.contact, &model)?;
    let mut diagrams = Vec::new();
    if let Some(points) = args.diagram {
        let options = DiagramOptions {
            run: run_options(&args.run, 0),
            ..DiagramOptions::default()
        };
        let values = values(args.from, args.to, points as usize);
        for contact in &contacts {
            let d = system::bifurcation(&model, contact, args.param, &values, &options, |_| {
                ControlFlow::Continue(())
            })
            .map_err(|e| failed(contact, e))?;
            diagrams.push((Approach::of(contact), DiagramBranch::of(&d.columns)));
        }
    }
    let mut curves = Vec::new();
    for r in &report.results {
        let a = approach(&r.contact, &contacts);
        curves.push((a, curve_of(&r.branch)));
        if let Some(d) = &r.doubled {
            let doubled = BranchCurve {
                doubled: true,
                ..curve_of(d)
            };
            curves.push((a, doubled));
        }
    }
    let drawn: Vec<(Approach, &BranchCurve)> = curves.iter().map(|(a, c)| (*a, c)).collect();
    let diagram: Vec<(Approach, &DiagramBranch)> = diagrams.iter().map(|(a, d)| (*a, d)).collect();
    let mut axes = DiagramAxes::impact_speeds(args.param, &model);
    axes.range = Some((args.from.min(args.to), args.from.max(args.to)));
    let name = report.scene.clone();
    let mut chart = plot::branch(&drawn, &diagram, &axes, BUDGET);
    // Side by side with a curve there is no room for the scene's name.
    if args.second.is_none() {
        chart.title = format!("{} · {name}", chart.title);
    }
    let mut charts = vec![chart];
    if let Some(second) = args.second {
        let lines: Vec<(Approach, Vec<(f64, f64)>)> = report
            .results
            .iter()
            .filter_map(|r| {
                r.curve.as_ref().map(|c| {
                    (
                        approach(&r.contact, &contacts),
                        c.points
                            .iter()
                            .map(|p| (p.values[0], p.values[1]))
                            .collect(),
                    )
                })
            })
            .collect();
        if !lines.is_empty() {
            let kind = report
                .results
                .iter()
                .find_map(|r| r.curve.as_ref().and_then(|c| c.follows))
                .map_or("special", SpecialKind::label);
            let drawn: Vec<(Approach, &[(f64, f64)])> =
                lines.iter().map(|(a, l)| (*a, l.as_slice())).collect();
            let first = DiagramAxes::impact_speeds(args.param, &model);
            let second_axes = DiagramAxes::impact_speeds(second, &model);
            charts.push(plot::curves(&drawn, kind, (&first, &second_axes), BUDGET));
        }
    }
    Ok(charts)
}
