//! The sweep form's keys: ↑↓ move between its rows, ←→ change the row, Enter types it (or steps a
//! row that has choices rather than a value).

use crate::ui::action::Action;
use crate::ui::app::App;
use crate::ui::field::Nudge;

use super::settings::SweepField;

pub fn handle(app: &mut App, action: Action) -> Option<Action> {
    match action {
        Action::Up => app.views.sweep.cursor = app.views.sweep.cursor.step(false),
        Action::Down => app.views.sweep.cursor = app.views.sweep.cursor.step(true),
        Action::Nudge(direction) => nudge(app, app.views.sweep.cursor, direction),
        Action::Enter => {
            let field = app.views.sweep.cursor;
            if field.is_typed() {
                let text = app.views.sweep.settings.edit_text(field, &sweep_scene(app));
                app.open_editor(super::editor(field), text);
            } else {
                nudge(app, field, Nudge::Up);
            }
        }
        action => return Some(action),
    }
    None
}

/// The scene the sweep varies: the last valid one (the form may hold an invalid draft).
pub fn sweep_scene(app: &App) -> crate::model::Scene {
    match &app.valid {
        Some(valid) => valid.scene.clone(),
        None => app.draft.scene.clone(),
    }
}

fn nudge(app: &mut App, field: SweepField, direction: Nudge) {
    let scene = sweep_scene(app);
    let max = super::max_points(app);
    app.views.sweep.settings.nudge(field, direction, &scene, max);
}
