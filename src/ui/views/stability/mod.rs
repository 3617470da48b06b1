//! Tab 3, where fixed-step methods fail: the focused model at a chosen step by every fixed-step
//! method over the reference.

mod keys;
mod render;

use ratatui::Frame;

use crate::chart::stability as plot;
use crate::chart::Chart;
use crate::model::ode::Method;
use crate::model::study::stability::critical_step;
use crate::ui::action::Action;
use crate::ui::app::{App, EditTarget, Valid};
use crate::chart::kind::ChartKind;
use crate::ui::layout::ScreenLayout;
use crate::model::study::runner::{StudyKind, StudySpec};

use super::{FIGURE_COLUMNS, FIGURE_TICKS, Hints, View};

pub struct Stability;

/// The line editor of the step.
pub const STEP_EDITOR: EditTarget = EditTarget::Row(0);

/// The stability view's own state.
#[derive(Debug, Clone, Default)]
pub struct State {
    /// The step, s; `None` follows the scene (the RK4 critical step).
    pub step: Option<f64>,
}

impl View for Stability {
    fn id(&self) -> &'static str {
        "stability"
    }

    fn title(&self) -> &'static str {
        "stability"
    }

    fn help(&self) -> Option<&'static str> {
        Some("Enter types the step (auto: rk4 critical); ← → ½× 2×")
    }

    fn render(&self, frame: &mut Frame, screen: &ScreenLayout, app: &App) {
        render::render(frame, screen.body, app, screen.roomy);
    }

    fn hints(&self) -> Hints {
        &[("Enter", "step"), ("←→", "½× 2×"), ("[ ]", "model")]
    }

    fn handle(&self, app: &mut App, action: Action) -> Option<Action> {
        keys::handle(app, action)
    }

    fn commit(&self, app: &mut App, target: EditTarget, text: &str) -> Result<(), String> {
        match target {
            STEP_EDITOR => keys::commit_step(app, text),
            _ => Ok(()),
        }
    }

    fn studies(&self) -> &'static [StudyKind] {
        &[StudyKind::Runs, StudyKind::Bounds]
    }

    fn study_specs(&self, app: &App, valid: &Valid) -> Vec<StudySpec> {
        let (model, params) = (app.focused, valid.params);
        let mut specs = vec![StudySpec::Bounds { model, params }];
        if let Some(dt) = step(app) {
            specs.insert(0, StudySpec::Runs { model, params, dt });
        }
        specs
    }

    fn charts(&self, app: &App) -> Vec<Chart> {
        match app.studies.runs() {
            Some(Ok(data)) => [
                ChartKind::ForceDisplacement,
                ChartKind::VelocityDisplacement,
            ]
            .into_iter()
            .map(|kind| plot::chart(data, kind, FIGURE_COLUMNS, FIGURE_TICKS))
            .collect(),
            _ => Vec::new(),
        }
    }
}

/// The step of the view: the user's, else the RK4 critical step of the last valid scene (the
/// largest step at which RK4 is stable in theory).
pub fn step(app: &App) -> Option<f64> {
    app.views.stability.step.or_else(|| {
        app.valid
            .as_ref()
            .and_then(|v| critical_step(Method::Rk4, &v.params))
    })
}
