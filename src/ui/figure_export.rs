//! `f` in the explorer: the charts of the view on screen written to an SVG figure, through the
//! same descriptions the terminal draws (the figure back-end of [`crate::chart`]).

use std::path::PathBuf;

use crate::chart::Chart;
use crate::chart::figure;

use super::app::{App, ChartKind};
use super::export::default_path;
use super::render::chart::describe;
use super::restitution_plot;
use super::stability_plot;
use super::studies::StudyKind;
use super::sweep_plot::{self, SweepSet};
use super::tab::Tab;
use super::wp_plot::{self, Cost};

/// Size of the figure, px: the charts side by side or stacked within it.
const SIZE: (u32, u32) = (1600, 1000);
/// Tick labels on a figure, and columns its curves are sampled for.
const BUDGET: (usize, usize) = (9, 8);
const COLUMNS: u16 = 600;

/// The charts of `tab` as the app holds them (none while a study is missing).
pub fn charts(app: &App, tab: Tab) -> Vec<Chart> {
    match tab {
        Tab::Explorer => [
            ChartKind::ForceDisplacement,
            ChartKind::ForceTime,
            ChartKind::VelocityDisplacement,
        ]
        .into_iter()
        .map(|kind| describe(app, kind, COLUMNS, 40))
        .collect(),
        Tab::WorkPrecision => match app.studies.work_precision() {
            Some(Ok(data)) => {
                let current = app.studies.current().and_then(|c| c.as_ref().ok());
                [Cost::Seconds, Cost::ForceEvals]
                    .into_iter()
                    .map(|cost| wp_plot::chart(data, current, cost, BUDGET))
                    .collect()
            }
            _ => Vec::new(),
        },
        Tab::Stability => match app.studies.runs() {
            Some(Ok(data)) => [
                ChartKind::ForceDisplacement,
                ChartKind::VelocityDisplacement,
            ]
            .into_iter()
            .map(|kind| stability_plot::chart(data, kind, COLUMNS, BUDGET))
            .collect(),
            _ => Vec::new(),
        },
        Tab::Sweep => match app.studies.sweep() {
            Some(Ok(data)) => {
                let yield_stress = app
                    .valid
                    .as_ref()
                    .and_then(|v| v.scene.pair().ok())
                    .map(|p| p.yield_stress());
                let set = SweepSet {
                    name: None,
                    data,
                    yield_stress,
                };
                vec![sweep_plot::chart(
                    &[set],
                    app.sweep.output,
                    Some(app.focused),
                    BUDGET,
                )]
            }
            _ => Vec::new(),
        },
        Tab::Restitution => match app.studies.restitution() {
            Some(Ok(data)) => {
                let onset = app.valid.as_ref().map(|v| v.quasistatic.onset);
                vec![
                    restitution_plot::realised_chart(data, app.focused, BUDGET),
                    restitution_plot::velocity_chart(data, app.focused, onset, BUDGET),
                ]
            }
            _ => Vec::new(),
        },
    }
}

/// Writes the charts of the view on screen to `<scene>-<view>.svg` in the working folder; the
/// news for the status line, or why nothing was written.
pub fn write_view(app: &App) -> Result<String, String> {
    let pending = app.is_computing()
        || app
            .tab_studies()
            .iter()
            .any(|&k: &StudyKind| app.studies.is_pending(k));
    let charts = charts(app, app.tab);
    if charts.is_empty() || pending {
        return Err("nothing drawn yet to write: try again when the charts are done".into());
    }
    // The export's file-friendly scene stem, as `e` names its CSV.
    let stem = app.preset.as_deref().unwrap_or(&app.draft.scene.name);
    let csv = default_path(stem, app.focused).display().to_string();
    let scene = csv.trim_end_matches(&format!("-{}.csv", app.focused.name()));
    let view = match app.tab {
        Tab::Explorer => "explorer",
        Tab::WorkPrecision => "work-precision",
        Tab::Stability => "stability",
        Tab::Sweep => "sweep",
        Tab::Restitution => "restitution",
    };
    let path = PathBuf::from(format!("{scene}-{view}.svg"));
    figure::write(&charts, &path, SIZE).map_err(|e| e.to_string())?;
    Ok(format!(
        "wrote {} ({} charts)",
        path.display(),
        charts.len()
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::presets::{DEFAULT_SCENE, Registry};
    use crate::ui::MarkerStyle;
    use crate::ui::action::Action;
    use crate::ui::theme::Theme;
    use crate::ui::update::update;
    use crate::ui::worker;

    /// The explorer's figure holds the three charts of the checked models, each with its axes'
    /// ticks, and renders to an SVG with every chart's title.
    #[test]
    fn the_explorer_figure_has_every_chart_of_the_checked_models() {
        let registry = Registry::builtin().unwrap();
        let scene = registry.scene(DEFAULT_SCENE).unwrap();
        let mut app = App::new(scene, registry, MarkerStyle::Braille, Theme { color: true });
        for job in app.take_jobs() {
            update(&mut app, Action::Solved(Ok(worker::solve(&job))));
        }
        let charts = charts(&app, Tab::Explorer);
        assert_eq!(charts.len(), 3);
        let checked = app.checked_models().len();
        for chart in &charts {
            assert_eq!(chart.series.len(), checked, "{}", chart.title);
            assert!(chart.x.ticks.len() >= 3 && chart.y.ticks.len() >= 3);
        }
        let svg = figure::svg(&charts, SIZE).unwrap();
        for kind in ChartKind::ALL {
            assert!(svg.contains(kind.title()), "{}", kind.title());
        }
        // No study yet: the other views have nothing to write.
        assert!(charts_of_missing_studies_are_empty(&app));
    }

    fn charts_of_missing_studies_are_empty(app: &App) -> bool {
        [Tab::WorkPrecision, Tab::Stability, Tab::Sweep]
            .into_iter()
            .all(|tab| charts(app, tab).is_empty())
    }
}
