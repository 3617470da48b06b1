//! Mouse clicks and the wheel: on the tab bar a click picks a tab; in the body the shown view
//! hit-tests them against its own layout.

use ratatui::layout::{Position, Rect};

use super::app::App;
use super::field::Nudge;
use super::layout;
use super::widgets::tabs;

/// Where (column, row) falls: on the tab bar (`Err` with the column within it), else in the body.
fn place(app: &App, column: u16, row: u16) -> Option<Result<Position, u16>> {
    let (width, height) = app.screen;
    let screen = layout::screen_layout(Rect::new(0, 0, width, height))?;
    let position = Position::new(column, row);
    Some(if screen.tabs.contains(position) {
        Err(column - screen.tabs.x)
    } else {
        Ok(position)
    })
}

/// A left click at (column, row).
pub fn click(app: &mut App, column: u16, row: u16) {
    match place(app, column, row) {
        Some(Err(bar_column)) => {
            if let Some(tab) = tabs::tab_at(bar_column, app.screen.0) {
                app.tab = tab;
            }
        }
        Some(Ok(position)) => app.tab.view().click(app, position),
        None => {}
    }
}

/// The wheel at (column, row).
pub fn wheel(app: &mut App, column: u16, row: u16, direction: Nudge) {
    if let Some(Ok(position)) = place(app, column, row) {
        app.tab.view().wheel(app, position, direction);
    }
}
