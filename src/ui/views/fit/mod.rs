//! The fit view (docs/explorer.md, Fit; docs/fitting.md): measured restitution e(v₀) from a CSV
//! file, every fittable law (or the checked ones) fitted to it on the scene's bodies through the
//! studies' job queue, refitted on every edit of the scene; the data with error bars and each
//! fitted law's curve, the residuals, the ranking with the verdict; Enter writes a fit into the
//! scene's `[fit]`, so that the other views use it.

mod keys;
mod render;

use std::path::{Path, PathBuf};

use ratatui::Frame;

use crate::chart::Chart;
use crate::chart::fit::{
    Curve, RESIDUALS_WITHIN, points, residual_chart, residual_curves, restitution_chart,
    sample_velocities, velocity_axis,
};
use crate::format::fit_csv::parse_restitution_csv;
use crate::model::fit::{Candidate, FitReport, RestitutionData, candidates};
use crate::model::study::fit::{FitData, FitStudy};
use crate::model::study::runner::{StudyKind, StudySpec};
use crate::ui::action::Action;
use crate::ui::app::{App, EditTarget, Valid};
use crate::ui::layout::ScreenLayout;

use super::{FIGURE_TICKS, Hints, View};

pub struct Fit;

/// Where the example data sets are, as the view and the docs name them.
pub const EXAMPLES: &str = "presets/data/";
/// The file the open prompt proposes first.
pub const EXAMPLE: &str = "presets/data/steel-hunt-crossley.csv";

/// The data the view fits.
#[derive(Debug, Clone, Default, PartialEq)]
pub enum Source {
    /// Nothing loaded yet.
    #[default]
    None,
    /// A file read and checked.
    Loaded { path: String, data: RestitutionData },
    /// A file refused: the reader's message, naming the file and line.
    Failed { path: String, error: String },
}

/// The fit view's own state.
#[derive(Debug, Clone, Default)]
pub struct State {
    pub source: Source,
    /// Fit only the checked laws (and constant e) instead of every fittable one.
    pub checked_only: bool,
    /// The row of the ranking under the cursor: the fit Enter writes into the scene.
    pub cursor: usize,
}

/// Points along each fitted law's curve.
const CURVE_POINTS: usize = 80;

/// Reads the data file `path` into the view; a refused file is kept with the reader's message.
pub fn open(app: &mut App, path: &Path) {
    let shown = path.display().to_string();
    let source = match std::fs::read_to_string(path) {
        Err(e) => Source::Failed {
            error: format!("{shown}: cannot read the data: {e}"),
            path: shown,
        },
        Ok(text) => match parse_restitution_csv(&text, &shown) {
            Ok(data) => Source::Loaded { path: shown, data },
            Err(e) => Source::Failed {
                error: e.to_string(),
                path: shown,
            },
        },
    };
    match &source {
        Source::Loaded { path, data } => {
            app.say(format!("read {} points from {path}", data.len()), false)
        }
        Source::Failed { error, .. } => app.say(error.clone(), true),
        Source::None => {}
    }
    app.views.fit.source = source;
    app.views.fit.cursor = 0;
}

/// The loaded data and its file, if any.
pub fn loaded(app: &App) -> Option<(&str, &RestitutionData)> {
    match &app.views.fit.source {
        Source::Loaded { path, data } => Some((path, data)),
        _ => None,
    }
}

/// The candidates fitted: every fittable law, or constant e and the checked laws among them.
pub fn chosen(app: &App) -> Vec<Candidate> {
    let all = candidates();
    if !app.views.fit.checked_only {
        return all;
    }
    all.into_iter()
        .filter(|c| c.model().is_none_or(|m| app.is_checked(m)))
        .collect()
}

/// The velocities the curves are drawn at: over the widest axis the charts give the data.
fn curve_velocities(data: &RestitutionData) -> Vec<f64> {
    let axis = velocity_axis(&points(data), FIGURE_TICKS.0);
    sample_velocities(&axis, CURVE_POINTS)
}

/// The finished fit and its curves, if the latest study ended in one.
pub fn finished(app: &App) -> Option<(&FitData, &FitReport)> {
    let data = app.studies.fit()?;
    match &data.report {
        Some(Ok(report)) => Some((data, report)),
        _ => None,
    }
}

/// The data with every fitted law's curve (the best focused), and the residuals of the laws
/// within Δ ≤ [`RESIDUALS_WITHIN`] of it, each at most `budget` labels.
pub fn fit_charts(
    file: &str,
    fit: &FitData,
    report: &FitReport,
    budget: (usize, usize),
) -> [Chart; 2] {
    let points = points(&fit.data);
    let mut curves = Vec::new();
    for (i, curve) in fit.curves.iter().enumerate() {
        let mut drawn = Curve::of(curve.candidate, curve.points.clone());
        drawn.focused = i == 0;
        curves.push(drawn);
    }
    let residuals = residual_curves(&points, &report.fits);
    let title = format!(
        "e(v₀) of {file} · {} laws by {}, best {}",
        report.fits.len(),
        report.criterion.name(),
        report.fits[0].candidate
    );
    let chart = restitution_chart(title, &points, &curves, budget);
    let mut panel = residual_chart(&points, &residuals, budget);
    panel.title = format!(
        "residuals e law − e measured · Δ{} ≤ {RESIDUALS_WITHIN}",
        report.criterion.name()
    );
    [chart, panel]
}

impl View for Fit {
    fn id(&self) -> &'static str {
        "fit"
    }

    fn title(&self) -> &'static str {
        "fit"
    }

    fn render(&self, frame: &mut Frame, screen: &ScreenLayout, app: &App) {
        render::render(frame, screen, app);
    }

    fn hints(&self) -> Hints {
        &[
            ("o", "open data"),
            ("↑↓", "law"),
            ("Enter", "use fit"),
            ("c", "all/checked"),
            ("u", "undo"),
        ]
    }

    fn handle(&self, app: &mut App, action: Action) -> Option<Action> {
        keys::handle(app, action)
    }

    fn commit(&self, app: &mut App, target: EditTarget, text: &str) -> Result<(), String> {
        match target {
            EditTarget::Row(_) => keys::commit_path(app, text),
            EditTarget::Field(_) => Ok(()),
        }
    }

    fn studies(&self) -> &'static [StudyKind] {
        &[StudyKind::Fit]
    }

    fn study_specs(&self, app: &App, valid: &Valid) -> Vec<StudySpec> {
        let Some((_, data)) = loaded(app) else {
            return Vec::new();
        };
        vec![StudySpec::Fit(Box::new(FitStudy {
            params: valid.params,
            data: data.clone(),
            candidates: chosen(app),
            velocities: curve_velocities(data),
        }))]
    }

    fn charts(&self, app: &App) -> Vec<Chart> {
        match (loaded(app), finished(app)) {
            (Some((file, _)), Some((fit, report))) => {
                fit_charts(file, fit, report, FIGURE_TICKS).into()
            }
            _ => Vec::new(),
        }
    }
}

/// The path the open prompt proposes: the file loaded (or refused), else the example.
pub fn proposed_path(app: &App) -> PathBuf {
    match &app.views.fit.source {
        Source::Loaded { path, .. } | Source::Failed { path, .. } => PathBuf::from(path),
        Source::None => PathBuf::from(EXAMPLE),
    }
}
