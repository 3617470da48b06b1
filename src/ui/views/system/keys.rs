//! The system form's keys: ↑↓ move between its rows, Enter types the row, ←→ step it.

use crate::ui::action::Action;
use crate::ui::app::{App, EditTarget};
use crate::ui::field::Nudge;

use super::settings::Settings;

pub fn handle(app: &mut App, action: Action) -> Option<Action> {
    let Ok(model) = super::model(app) else {
        return Some(action);
    };
    let rows = Settings::rows(&model);
    let n = rows.len().max(1);
    let i = app.views.system.cursor.min(n - 1);
    match action {
        Action::Up => app.views.system.cursor = (i + n - 1) % n,
        Action::Down => app.views.system.cursor = (i + 1) % n,
        Action::Enter => {
            let text = app.views.system.settings.edit_text(rows[i], &model);
            app.open_editor(EditTarget::Row(i), text);
        }
        Action::Nudge(direction) => {
            let preset = app.preset.clone();
            let up = direction == Nudge::Up;
            if let Err(reason) =
                app.views
                    .system
                    .settings
                    .nudge(rows[i], up, &model, preset.as_deref())
            {
                app.say(reason, true);
            }
        }
        action => return Some(action),
    }
    None
}

/// Commits the text typed into row `i`; the reason, naming the key, if refused.
pub fn commit(app: &mut App, i: usize, text: &str) -> Result<(), String> {
    let model = super::model(app)?;
    let rows = Settings::rows(&model);
    let Some(&row) = rows.get(i) else {
        return Ok(());
    };
    let preset = app.preset.clone();
    app.views
        .system
        .settings
        .apply(row, text, &model, preset.as_deref())
}
