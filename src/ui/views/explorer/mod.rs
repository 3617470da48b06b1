//! Tab 1, the explorer: the scene's form and the model checklist, the charts F(x), v(x) and F(t)
//! of the checked models, their results and the regime of the impact.

pub mod chart;
mod form;
mod keys;
pub mod layout;
mod mouse;
mod regime;
mod results;
#[cfg(test)]
mod visibility_tests;

use ratatui::Frame;
use ratatui::layout::Position;

use crate::chart::Chart;
use crate::ui::action::Action;
use crate::ui::app::{App, EditTarget};
use crate::chart::kind::ChartKind;
use crate::ui::field::Nudge;
use crate::ui::layout::ScreenLayout;
use crate::ui::widgets::models;

use super::{FIGURE_COLUMNS, Hints, View};

pub struct Explorer;

/// The explorer's own state.
#[derive(Debug, Clone)]
pub struct State {
    /// The chart shown first (alone where only one fits).
    pub chart: ChartKind,
    /// The data cursor, per mille along the charts' x axes (`None`: hidden).
    pub data_cursor: Option<u16>,
}

impl Default for State {
    fn default() -> State {
        State {
            chart: ChartKind::ForceDisplacement,
            data_cursor: None,
        }
    }
}

impl View for Explorer {
    fn id(&self) -> &'static str {
        "explorer"
    }

    fn title(&self) -> &'static str {
        "explorer"
    }

    fn render(&self, frame: &mut Frame, _screen: &ScreenLayout, app: &App) {
        let Some(areas) = layout::layout(frame.area(), app.views.explorer.chart, |w| form::resting_height(app, w)) else {
            return;
        };
        regime::render(frame, areas.info, app, areas.roomy);
        form::render(frame, areas.form, app, areas.roomy);
        models::render(frame, areas.models, app, areas.roomy);
        // The first chart's title says which key shows the ones that do not fit.
        let hidden = areas.charts.len() < ChartKind::ALL.len();
        for (i, (kind, rect)) in areas.charts.iter().enumerate() {
            chart::render(frame, *rect, app, *kind, areas.roomy, hidden && i == 0);
        }
        results::render(frame, areas.results, app, areas.roomy);
    }

    fn hints(&self) -> Hints {
        &[
            ("↑↓", "move"),
            ("Enter", "edit"),
            ("←→", "nudge"),
            ("Space", "model"),
            ("p", "presets"),
            ("s", "save"),
            ("e", "export"),
        ]
    }

    fn handle(&self, app: &mut App, action: Action) -> Option<Action> {
        keys::handle(app, action)
    }

    fn commit(&self, app: &mut App, target: EditTarget, text: &str) -> Result<(), String> {
        match target {
            EditTarget::Field(field) => keys::commit_field(app, field, text),
            _ => Ok(()),
        }
    }

    fn click(&self, app: &mut App, at: Position) {
        mouse::click(app, at);
    }

    fn wheel(&self, app: &mut App, at: Position, direction: Nudge) {
        mouse::wheel(app, at, direction);
    }

    fn charts(&self, app: &App) -> Vec<Chart> {
        [
            ChartKind::ForceDisplacement,
            ChartKind::ForceTime,
            ChartKind::VelocityDisplacement,
        ]
        .into_iter()
        .map(|kind| chart::describe(app, kind, FIGURE_COLUMNS, 40))
        .collect()
    }
}
