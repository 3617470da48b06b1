//! `hertz-tui plot --chart fit | fit-engines --data FILE`: measured restitution with every fitted
//! law's curve and the residuals, or against each engine's realised e(v₀) (docs/fitting.md).

use crate::chart::fit::{
    Curve, Point, RESIDUALS_WITHIN, points, residual_chart, residual_curves, restitution_chart,
    sample_velocities, velocity_axis,
};
use crate::chart::{Chart, Hue, Ink};
use crate::model::Scene;
use crate::model::engine::{self, ENGINES};
use crate::model::fit::{Candidate, FitOptions, FitReport, candidates, fit_restitution};

use super::args::{ChartChoice, PlotArgs};
use super::error::CliError;
use super::fit::{fitted_scene, read_restitution};

/// Points along each curve.
const CURVE_POINTS: usize = 80;

/// Glyphs of the engines' curves: capitals no law uses.
const ENGINE_GLYPHS: [char; 10] = ['B', 'C', 'D', 'F', 'G', 'H', 'J', 'K', 'L', 'M'];
/// Hues of the engines' curves, in turn.
const ENGINE_HUES: [Hue; 6] = [
    Hue::Red,
    Hue::Blue,
    Hue::Green,
    Hue::Magenta,
    Hue::Cyan,
    Hue::Yellow,
];

/// The chart(s) of `--chart fit` or `fit-engines` on `scene`.
pub fn charts(
    args: &PlotArgs,
    scene: &Scene,
    budget: (usize, usize),
) -> Result<Vec<Chart>, CliError> {
    let path = args.data.as_ref().ok_or_else(|| {
        CliError::Usage("--chart fit and fit-engines need --data FILE (e.g. presets/data/steel-hunt-crossley.csv)".into())
    })?;
    let data = read_restitution(path)?;
    let chosen: Vec<Candidate> = if args.models.is_empty() {
        candidates()
    } else {
        std::iter::once(Candidate::ConstantE)
            .chain(args.models.iter().map(|m| Candidate::Law(*m)))
            .collect()
    };
    let file = path.display().to_string();
    let report = fit_restitution(scene, &data, &chosen, &FitOptions::default())
        .map_err(|e| CliError::Usage(format!("{file}: {e}")))?;
    let points = points(&data);
    match args.chart {
        ChartChoice::FitEngines => {
            let fitted = fitted_scene(scene, &report, &file)?;
            Ok(vec![engines_chart(&fitted, &points, &file, budget)])
        }
        _ => fit_charts(scene, &report, &points, &file, budget),
    }
}

/// The data with each fitted law's e(v₀), the best focused; beside it the residuals.
fn fit_charts(
    scene: &Scene,
    report: &FitReport,
    data: &[Point],
    file: &str,
    budget: (usize, usize),
) -> Result<Vec<Chart>, CliError> {
    let params = scene.impact_params(&scene.quasistatic()?);
    let axis = velocity_axis(data, budget.0);
    let vs = sample_velocities(&axis, CURVE_POINTS);
    let mut curves = Vec::new();
    let mut notes = Vec::new();
    for (i, fit) in report.fits.iter().enumerate() {
        let line: Vec<(f64, f64)> = vs
            .iter()
            .filter_map(|&v| fit.predict_params(&params, v).ok().map(|e| (v, e)))
            .collect();
        if line.len() < vs.len() {
            notes.push(format!(
                "{}: {} of {} points failed",
                fit.candidate,
                vs.len() - line.len(),
                vs.len()
            ));
        }
        let mut curve = Curve::of(fit.candidate, line);
        curve.focused = i == 0;
        curves.push(curve);
    }
    let residuals = residual_curves(data, &report.fits);
    let best = &report.fits[0];
    let title = format!(
        "e(v₀) of {file} · {} fits by {}, best {}",
        report.fits.len(),
        report.criterion.name(),
        best.candidate
    );
    let mut chart = restitution_chart(title, data, &curves, budget);
    chart.notes = notes;
    let mut panel = residual_chart(data, &residuals, budget);
    panel.title = format!(
        "residuals e law − e measured · laws within Δ{} ≤ {RESIDUALS_WITHIN}",
        report.criterion.name()
    );
    Ok(vec![chart, panel])
}

/// The data against each engine's e(v₀), its constants calibrated at the scene's v₀.
fn engines_chart(fitted: &Scene, data: &[Point], file: &str, budget: (usize, usize)) -> Chart {
    let axis = velocity_axis(data, budget.0);
    let vs = sample_velocities(&axis, CURVE_POINTS / 2);
    let mut curves: Vec<Curve> = Vec::new();
    // Per curve: its engines and their laws, for its name.
    let mut named: Vec<(Vec<&str>, Vec<String>)> = Vec::new();
    let mut notes = Vec::new();
    for e in ENGINES.iter() {
        match engine::translate_at(e.id, fitted, &vs) {
            Ok(t) => {
                let points: Vec<(f64, f64)> = t.e_of_v.iter().map(|p| (p.v0, p.e_out)).collect();
                // Engines whose e(v₀) is the same curve share one line, named together.
                let same = |c: &Curve| {
                    c.points.len() == points.len()
                        && c.points
                            .iter()
                            .zip(&points)
                            .all(|(a, b)| (a.1 - b.1).abs() < 1e-6)
                };
                let law = t.model.to_string();
                match curves.iter().position(same) {
                    Some(i) => {
                        named[i].0.push(e.id);
                        if !named[i].1.contains(&law) {
                            named[i].1.push(law);
                        }
                    }
                    None => {
                        let i = curves.len();
                        named.push((vec![e.id], vec![law]));
                        curves.push(Curve {
                            name: String::new(),
                            ink: Ink::Plain(ENGINE_HUES[i % ENGINE_HUES.len()]),
                            glyph: ENGINE_GLYPHS[i],
                            points,
                            focused: false,
                        });
                    }
                }
            }
            Err(err) => notes.push(format!("✗ {}: {err}", e.id)),
        }
    }
    for (curve, (ids, laws)) in curves.iter_mut().zip(&named) {
        curve.name = format!("{} ({})", ids.join(", "), laws.join(" / "));
    }
    let title = format!(
        "e(v₀) of {file} against the engines, calibrated at v₀ = {} m/s",
        crate::format::round_trip(fitted.impact.v0)
    );
    let mut chart = restitution_chart(title, data, &curves, budget);
    chart.notes = notes;
    chart
}
