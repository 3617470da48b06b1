//! The mouse in the explorer, hit-tested against the layout the screen is drawn with: a click picks
//! a field or a model (on its box: checks it), or places the data cursor on a chart's plot; the
//! wheel nudges the field under the pointer and moves the model focus.

use ratatui::layout::{Position, Rect};

use crate::model::ForceModel;
use crate::ui::app::{App, Cursor};
use crate::ui::edited;
use crate::ui::field::{Field, Nudge};
use crate::ui::widgets::models;

use super::{chart, form, layout};

/// What lies under the pointer in the explorer.
enum Target {
    Field(Field),
    Model {
        model: ForceModel,
        on_box: bool,
    },
    /// A column of a chart's plot: the data cursor's place there, per mille of the axis.
    Chart(u16),
}

fn target(app: &App, position: Position) -> Option<Target> {
    let (width, height) = app.screen;
    let areas = layout::layout(Rect::new(0, 0, width, height), app.views.explorer.chart, |w| form::resting_height(app, w))?;
    if let Some(field) = form::field_at(app, areas.form, areas.roomy, position) {
        return Some(Target::Field(field));
    }
    if let Some(hit) = models::model_at(app, areas.models, areas.roomy, position) {
        return Some(Target::Model {
            model: hit.0,
            on_box: hit.1,
        });
    }
    areas
        .charts
        .iter()
        .find(|(_, rect)| rect.contains(position))
        .and_then(|&(kind, rect)| chart::cursor_at(app, kind, rect, areas.roomy, position))
        .map(Target::Chart)
}

/// A left click at `position`.
pub fn click(app: &mut App, position: Position) {
    match target(app, position) {
        Some(Target::Field(field)) => app.cursor = Cursor::Field(field),
        Some(Target::Model { model, on_box }) => {
            app.cursor = Cursor::Model(model);
            if on_box {
                app.toggle(model);
            } else {
                app.cursor_on(model);
            }
        }
        Some(Target::Chart(at)) => app.views.explorer.data_cursor = Some(at),
        None => {}
    }
}

/// The wheel at `position`: up nudges the field under the pointer up, down nudges it down; over
/// the models it moves the focus.
pub fn wheel(app: &mut App, position: Position, direction: Nudge) {
    match target(app, position) {
        Some(Target::Field(field)) => {
            app.cursor = Cursor::Field(field);
            edited::nudge_within_domain(app, field, direction);
        }
        Some(Target::Model { model, .. }) => {
            app.cursor = Cursor::Model(model);
            app.move_cursor(direction == Nudge::Down);
        }
        Some(Target::Chart(_)) | None => {}
    }
}
