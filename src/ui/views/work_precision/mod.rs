//! Tab 2: error against cost of every method for the focused model.

mod render;

use ratatui::Frame;

use crate::chart::work_precision as plot;
use crate::chart::Chart;
use crate::ui::action::Action;
use crate::ui::app::{App, Valid};
use crate::ui::layout::ScreenLayout;
use crate::model::study::runner::{StudyKind, StudySpec};
use crate::chart::work_precision::Cost;

use super::{FIGURE_TICKS, Hints, View};

pub struct WorkPrecision;

/// The work-precision view's own state.
#[derive(Debug, Clone)]
pub struct State {
    /// The chart shown where only one fits.
    pub cost: Cost,
}

impl Default for State {
    fn default() -> State {
        State {
            cost: Cost::Seconds,
        }
    }
}

impl View for WorkPrecision {
    fn id(&self) -> &'static str {
        "work-precision"
    }

    fn title(&self) -> &'static str {
        "work–precision"
    }

    fn render(&self, frame: &mut Frame, screen: &ScreenLayout, app: &App) {
        render::render(frame, screen.body, app, screen.roomy);
    }

    fn hints(&self) -> Hints {
        &[("[ ]", "model"), ("c", "chart")]
    }

    fn handle(&self, app: &mut App, action: Action) -> Option<Action> {
        match action {
            // The cost axis shown where only one chart fits.
            Action::CycleChart => {
                app.views.work_precision.cost = app.views.work_precision.cost.other();
                None
            }
            action => Some(action),
        }
    }

    fn studies(&self) -> &'static [StudyKind] {
        &[StudyKind::WorkPrecision, StudyKind::Current]
    }

    fn study_specs(&self, app: &App, valid: &Valid) -> Vec<StudySpec> {
        let (model, params) = (app.focused, valid.params);
        vec![
            StudySpec::WorkPrecision { model, params },
            StudySpec::Current {
                model,
                params,
                options: app.draft.options,
            },
        ]
    }

    fn charts(&self, app: &App) -> Vec<Chart> {
        match app.studies.work_precision() {
            Some(Ok(data)) => {
                let current = app.studies.current().and_then(|c| c.as_ref().ok());
                [Cost::Seconds, Cost::ForceEvals]
                    .into_iter()
                    .map(|cost| plot::chart(data, current, cost, FIGURE_TICKS))
                    .collect()
            }
            _ => Vec::new(),
        }
    }
}
