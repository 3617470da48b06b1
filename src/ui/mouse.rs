//! Mouse clicks and the wheel, hit-tested against the same layout the screen is drawn with: a
//! click picks a tab, a field or a model (on its box: checks it), or places the data cursor on a
//! chart's plot; the wheel nudges the field under the pointer and moves the model focus.

use ratatui::layout::{Position, Rect};

use super::app::{App, Cursor};
use super::edited;
use super::field::Nudge;
use super::render::{chart, form, layout, models, tabs};
use super::tab::Tab;

/// What lies under the pointer in the explorer.
enum Target {
    Tab(Tab),
    Field(super::field::Field),
    Model {
        model: crate::model::ForceModel,
        on_box: bool,
    },
    /// A column of a chart's plot: the data cursor's place there, per mille of the axis.
    Chart(u16),
}

fn target(app: &App, column: u16, row: u16) -> Option<Target> {
    let (width, height) = app.screen;
    let screen = layout::screen(Rect::new(0, 0, width, height))?;
    let position = Position::new(column, row);
    if screen.tabs.contains(position) {
        return tabs::tab_at(column - screen.tabs.x).map(Target::Tab);
    }
    if app.tab != Tab::Explorer {
        return None;
    }
    let areas = layout::layout(Rect::new(0, 0, width, height), app.chart)?;
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

/// A left click at (column, row).
pub fn click(app: &mut App, column: u16, row: u16) {
    match target(app, column, row) {
        Some(Target::Tab(tab)) => app.tab = tab,
        Some(Target::Field(field)) => app.cursor = Cursor::Field(field),
        Some(Target::Model { model, on_box }) => {
            app.cursor = Cursor::Model(model);
            if on_box {
                app.toggle(model);
            } else {
                app.focused = model;
            }
        }
        Some(Target::Chart(at)) => app.data_cursor = Some(at),
        None => {}
    }
}

/// The wheel at (column, row): up nudges the field under the pointer up, down nudges it down;
/// over the models it moves the focus.
pub fn wheel(app: &mut App, column: u16, row: u16, direction: Nudge) {
    match target(app, column, row) {
        Some(Target::Field(field)) => {
            app.cursor = Cursor::Field(field);
            edited::nudge_within_domain(app, field, direction);
        }
        Some(Target::Model { model, .. }) => {
            app.cursor = Cursor::Model(model);
            app.move_cursor(direction == Nudge::Down);
        }
        Some(Target::Tab(_)) | Some(Target::Chart(_)) | None => {}
    }
}
