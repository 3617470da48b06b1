//! `f` in the explorer: the charts of the view on screen written to an SVG figure, through the
//! same descriptions the terminal draws (the figure back-end of [`crate::chart`]).

use std::path::PathBuf;

use crate::chart::figure;

use super::app::App;
use super::export::default_path;
use super::views;

/// Size of the figure, px: the charts side by side or stacked within it.
const SIZE: (u32, u32) = (1600, 1000);

/// Writes the charts of the view on screen to `<scene>-<view>.svg` in the working folder; the
/// news for the status line, or why nothing was written.
pub fn write_view(app: &App) -> Result<String, String> {
    let view = app.tab.view();
    let pending = app.is_computing() || views::is_studying(app);
    let charts = view.charts(app);
    if charts.is_empty() || pending {
        return Err("nothing drawn yet to write: try again when the charts are done".into());
    }
    // The export's file-friendly scene stem, as `e` names its CSV.
    let csv = default_path(&app.file_stem(), app.focused)
        .display()
        .to_string();
    let scene = csv.trim_end_matches(&format!("-{}.csv", app.focused.name()));
    let path = PathBuf::from(format!("{scene}-{}.svg", view.id()));
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
    use crate::chart::kind::ChartKind;
    use crate::model::presets::{DEFAULT_SCENE, Registry};
    use crate::ui::MarkerStyle;
    use crate::ui::action::Action;
    use crate::ui::style::Theme;
    use crate::ui::tab::Tab;
    use crate::ui::update::update;
    use crate::ui::worker;

    /// The explorer's figure holds the three charts of the checked models, each with its axes'
    /// ticks, and renders to an SVG with every chart's title.
    #[test]
    fn the_explorer_figure_has_every_chart_of_the_checked_models() {
        let registry = Registry::builtin().unwrap();
        let scene = registry.scene(DEFAULT_SCENE).unwrap();
        let mut app = App::new(scene, registry, MarkerStyle::Braille, Theme::Dark);
        for job in app.take_jobs() {
            update(&mut app, Action::Solved(Ok(worker::solve(&job))));
        }
        let charts = Tab::HOME.view().charts(&app);
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
        ["work-precision", "stability", "sweep"]
            .into_iter()
            .filter_map(Tab::named)
            .all(|tab| tab.view().charts(app).is_empty())
    }
}
