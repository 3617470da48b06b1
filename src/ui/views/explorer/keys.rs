//! The explorer's keys: the form's cursor, nudges, resets and line editors, the model checklist
//! under the same cursor, the chart shown first and the data cursor.

use crate::ui::action::Action;
use crate::ui::app::{App, Cursor, EditTarget};
use crate::ui::data_cursor;
use crate::ui::edited;
use crate::ui::field::Field;

use super::chart;

pub fn handle(app: &mut App, action: Action) -> Option<Action> {
    match action {
        Action::Up => app.move_cursor(false),
        Action::Down => app.move_cursor(true),
        Action::Jump(jump) => app.jump_cursor(jump),
        Action::Nudge(direction) => match app.cursor {
            Cursor::Field(field) => edited::nudge_within_domain(app, field, direction),
            Cursor::Model(_) => app.step_focus(direction),
        },
        Action::ResetField => match app.cursor {
            Cursor::Field(field) => edited::reset_field(app, field),
            Cursor::Model(_) => app.say("r resets the field under the cursor", true),
        },
        Action::Enter => match app.cursor {
            Cursor::Field(field) => {
                let text = field.edit_text(&app.draft);
                app.open_editor(EditTarget::Field(field), text);
            }
            Cursor::Model(model) => app.toggle(model),
        },
        Action::CycleChart => app.views.explorer.chart = app.views.explorer.chart.next(),
        Action::MoveCursor { forward, fast } => {
            let at = &mut app.views.explorer.data_cursor;
            *at = Some(data_cursor::moved(*at, forward, fast));
        }
        Action::CursorToPeak => match chart::peak_at(app, app.views.explorer.chart) {
            Some(at) => app.views.explorer.data_cursor = Some(at),
            None => app.say(
                format!("no curve of {} to find its peak on", app.focused.label()),
                true,
            ),
        },
        // Esc hides the data cursor.
        Action::Cancel => app.views.explorer.data_cursor = None,
        // A paste outside an editor opens the field under the cursor with the pasted text (its
        // first line), so that pasted characters never run commands.
        Action::Paste(text) => {
            let line = text.lines().next().unwrap_or_default().trim().to_string();
            match app.cursor {
                Cursor::Field(field) if !line.is_empty() => {
                    app.open_editor_typed(EditTarget::Field(field), line);
                }
                _ => return Some(Action::Paste(text)),
            }
        }
        action => return Some(action),
    }
    None
}

/// Commits the text typed into a field of the form; the reason if it is refused.
pub fn commit_field(app: &mut App, field: Field, text: &str) -> Result<(), String> {
    let mut draft = app.draft.clone();
    field.apply(text, &mut draft).map(|()| {
        app.draft = draft;
        app.recompute();
    })
}
