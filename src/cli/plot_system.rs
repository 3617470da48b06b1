//! The system charts of `hertz-tui plot`: time history, phase portrait, impact map and
//! bifurcation diagram of a system scene, each stop asked for (`--contact`) overlaid in its own
//! look ([`crate::chart::system`]).

use std::ops::ControlFlow;

use crate::chart::Chart;
use crate::chart::system::{self as plot, Approach, Branch, DiagramAxes, Motion, Stops};
use crate::model::presets::Registry;
use crate::model::system::{self, DiagramOptions, History};

use super::args::{ChartChoice, PlotArgs, SceneSelection};
use super::bifurcation::values;
use super::error::CliError;
use super::system::{contacts, failed, load_system, run_options, simulate};

/// Dense samples per forcing period of a drawn history: smooth at any figure size.
const SAMPLES_PER_PERIOD: usize = 200;

/// Forcing periods of the time history and phase portrait: twice the detected period (at least
/// 4, at most 32), or 8 when the motion has none.
fn periods_shown(history: &History, period: f64) -> f64 {
    history
        .period(period)
        .map_or(8.0, |(_, m)| f64::from(2 * m).clamp(4.0, 32.0))
}

/// The chart `args.chart` asks for, of the first `--scene`.
pub fn chart(
    args: &PlotArgs,
    registry: &Registry,
    budget: (usize, usize),
) -> Result<Chart, CliError> {
    let source = SceneSelection {
        scene: args.scene[0].clone(),
        overrides: args.overrides.clone(),
    };
    let model = load_system(&source, registry)?;
    let contacts = contacts(&args.contact, &model)?;
    let name = model
        .scene
        .as_ref()
        .map_or_else(String::new, |s| s.name.clone());
    let mut chart = if args.chart == ChartChoice::Bifurcation {
        let (Some(from), Some(to)) = (args.from, args.to) else {
            return Err(CliError::Usage(
                "--chart bifurcation needs --param, --from and --to (and --points)".into(),
            ));
        };
        let options = DiagramOptions {
            run: run_options(&args.run, 0),
            ..DiagramOptions::default()
        };
        let values = values(from, to, args.points as usize);
        let mut branches = Vec::new();
        for contact in &contacts {
            let diagram =
                system::bifurcation(&model, contact, args.param, &values, &options, |_| {
                    ControlFlow::Continue(())
                })
                .map_err(|e| failed(contact, e))?;
            branches.push((Approach::of(contact), Branch::of(&diagram.columns)));
        }
        let drawn: Vec<(Approach, &Branch)> = branches.iter().map(|(a, b)| (*a, b)).collect();
        plot::bifurcation(
            &drawn,
            &DiagramAxes::impact_speeds(args.param, &model),
            budget,
        )
    } else {
        let options = run_options(&args.run, SAMPLES_PER_PERIOD);
        let period = model.spec.period();
        let mut runs = Vec::new();
        for contact in &contacts {
            runs.push((Approach::of(contact), simulate(&model, contact, &options)?));
        }
        // The same window for every stop: the last periods of the longest-periodic motion.
        let end = runs
            .iter()
            .filter_map(|(_, h)| h.samples.last().map(|s| s.t))
            .fold(f64::NEG_INFINITY, f64::max);
        let shown = runs
            .iter()
            .map(|(_, h)| periods_shown(h, period))
            .fold(0.0, f64::max);
        let from = end - shown * period;
        let motions: Vec<(Approach, Motion)> = runs
            .iter()
            .map(|(a, h)| (*a, Motion::of(h, from)))
            .collect();
        let drawn: Vec<(Approach, &Motion)> = motions.iter().map(|(a, m)| (*a, m)).collect();
        let stops = Stops::of(&model, runs.first().map(|(_, h)| h), from);
        match args.chart {
            ChartChoice::Phase => plot::phase_portrait(&drawn, &stops, budget),
            ChartChoice::ImpactMap => plot::impact_map(&drawn, budget),
            _ => plot::time_history(&drawn, &stops, budget),
        }
    };
    chart.title = format!("{} · {name}", chart.title);
    Ok(chart)
}
