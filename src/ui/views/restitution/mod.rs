//! Tab 5: realised against requested restitution, and e against v₀, for the checked models.

mod render;

use ratatui::Frame;

use crate::chart::restitution as plot;
use crate::chart::Chart;
use crate::ui::action::Action;
use crate::ui::app::{App, Valid};
use crate::ui::layout::ScreenLayout;
use crate::model::study::runner::{StudyKind, StudySpec};

use super::{FIGURE_TICKS, Hints, View};

pub struct Restitution;

/// The restitution view's own state.
#[derive(Debug, Clone, Default)]
pub struct State {
    /// The table shows instead of the charts.
    pub table: bool,
}

impl View for Restitution {
    fn id(&self) -> &'static str {
        "restitution"
    }

    fn title(&self) -> &'static str {
        "restitution"
    }

    fn render(&self, frame: &mut Frame, screen: &ScreenLayout, app: &App) {
        render::render(frame, screen, app);
    }

    fn hints(&self) -> Hints {
        &[("Space", "model"), ("[ ]", "focus"), ("c", "table")]
    }

    fn handle(&self, app: &mut App, action: Action) -> Option<Action> {
        match action {
            // The table instead of the charts.
            Action::CycleChart => {
                app.views.restitution.table = !app.views.restitution.table;
                None
            }
            action => Some(action),
        }
    }

    fn studies(&self) -> &'static [StudyKind] {
        &[StudyKind::Restitution]
    }

    fn study_specs(&self, app: &App, valid: &Valid) -> Vec<StudySpec> {
        vec![StudySpec::Restitution {
            models: app.checked_models(),
            params: valid.params,
        }]
    }

    fn charts(&self, app: &App) -> Vec<Chart> {
        match app.studies.restitution() {
            Some(Ok(data)) => {
                let onset = app.valid.as_ref().map(|v| v.quasistatic.onset);
                vec![
                    plot::realised_chart(data, app.focused, FIGURE_TICKS),
                    plot::velocity_chart(data, app.focused, onset, FIGURE_TICKS),
                ]
            }
            _ => Vec::new(),
        }
    }
}
