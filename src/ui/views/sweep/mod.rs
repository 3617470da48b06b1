//! Tab 4: one output against one scene parameter for the checked models.

mod keys;
pub mod layout;
mod render;
pub mod settings;

use ratatui::Frame;
use ratatui::layout::Rect;

use crate::chart::sweep as plot;
use crate::chart::Chart;
use crate::ui::action::Action;
use crate::ui::app::{App, EditTarget, Valid};
use crate::ui::layout::ScreenLayout;
use crate::model::study::runner::{StudyKind, StudySpec};
use crate::chart::sweep::SweepSet;

use super::{FIGURE_TICKS, Hints, View};

use settings::{SweepField, SweepSettings};

pub struct Sweep;

/// The line editor of a row of the form.
pub fn editor(field: SweepField) -> EditTarget {
    EditTarget::Row(SweepField::ALL.iter().position(|&f| f == field).unwrap_or_default())
}

/// The sweep view's own state.
#[derive(Debug, Clone)]
pub struct State {
    pub settings: SweepSettings,
    /// The row of the form under the cursor.
    pub cursor: SweepField,
}

impl Default for State {
    fn default() -> State {
        State {
            settings: SweepSettings::default(),
            cursor: SweepField::Parameter,
        }
    }
}

impl View for Sweep {
    fn id(&self) -> &'static str {
        "sweep"
    }

    fn title(&self) -> &'static str {
        "sweep"
    }

    fn help(&self) -> Option<&'static str> {
        Some("↑ ↓ rows; ← → change; Enter types or switches; e: CSV")
    }

    fn render(&self, frame: &mut Frame, screen: &ScreenLayout, app: &App) {
        render::render(frame, screen, app);
    }

    fn hints(&self) -> Hints {
        &[
            ("↑↓", "move"),
            ("Enter", "edit"),
            ("←→", "change"),
            ("Space", "model"),
            ("[ ]", "focus"),
            ("e", "CSV"),
        ]
    }

    fn handle(&self, app: &mut App, action: Action) -> Option<Action> {
        keys::handle(app, action)
    }

    fn commit(&self, app: &mut App, target: EditTarget, text: &str) -> Result<(), String> {
        match target {
            EditTarget::Row(row) => {
                let Some(&field) = SweepField::ALL.get(row) else {
                    return Ok(());
                };
                let scene = keys::sweep_scene(app);
                app.views.sweep.settings.apply(field, text, &scene)
            }
            _ => Ok(()),
        }
    }

    fn studies(&self) -> &'static [StudyKind] {
        &[StudyKind::Sweep]
    }

    fn study_specs(&self, app: &App, valid: &Valid) -> Vec<StudySpec> {
        match app.views.sweep.settings.spec(
            &valid.scene,
            app.checked_models(),
            app.draft.options,
            max_points(app),
        ) {
            Ok(spec) => vec![StudySpec::Sweep {
                scene: Box::new(valid.scene.clone()),
                spec: Box::new(spec),
            }],
            // The view says why; there is nothing to compute.
            Err(_) => Vec::new(),
        }
    }

    fn charts(&self, app: &App) -> Vec<Chart> {
        match app.studies.sweep() {
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
                vec![plot::chart(
                    &[set],
                    app.views.sweep.settings.output,
                    Some(app.focused),
                    FIGURE_TICKS,
                )]
            }
            _ => Vec::new(),
        }
    }
}

/// The most points the sweep chart shows distinctly: one per braille dot column (two per
/// terminal column), one per column with the other markers.
pub fn max_points(app: &App) -> usize {
    let (width, height) = app.screen;
    let columns = layout::sweep_plot_columns(Rect::new(0, 0, width, height));
    usize::from(columns) * usize::from(app.marker.dots_per_cell())
}
