//! The system form's keys: ↑↓ move between its rows, Enter types the row, ←→ step it, `r` resets
//! it. A key of the `[system]` table is written to the draft, so that `u` undoes it and `s` saves
//! it. On a scene without `[system]`, ↑↓ choose a system preset and Enter adds its table.

use crate::model::system::{Param, SystemSpec};
use crate::ui::action::Action;
use crate::ui::app::{App, EditTarget};
use crate::ui::field::Nudge;

use super::settings::{self, Row, SYSTEM_PRESETS, Settings};

pub fn handle(app: &mut App, action: Action) -> Option<Action> {
    if app.draft.system.is_none() {
        return add_system(app, action);
    }
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
            let up = direction == Nudge::Up;
            let outcome = app.views.system.settings.nudge(rows[i], up, &model);
            edited(app, outcome);
        }
        Action::ResetField => reset(app, rows[i]),
        Action::Branch => super::branch::toggle(app),
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
    let changed = app.views.system.settings.apply(row, text, &model)?;
    if let Some(spec) = changed {
        app.draft.system = Some(spec);
    }
    Ok(())
}

/// A changed `[system]` table goes to the draft; a refusal to the status line.
fn edited(app: &mut App, outcome: Result<Option<SystemSpec>, String>) {
    match outcome {
        Ok(Some(spec)) => app.draft.system = Some(spec),
        Ok(None) => {}
        Err(reason) => app.say(reason, true),
    }
}

/// `r` on a key: back to its value in the table as loaded or saved.
fn reset(app: &mut App, row: Row) {
    let Row::Key(key) = row else {
        app.say("r resets a key of the [system] table", true);
        return;
    };
    let param = Param::System(key);
    let scene = match &app.valid {
        Some(valid) => valid.scene.clone(),
        None => app.draft.scene.clone(),
    };
    let saved = settings::model(app.saved_system(), &scene).and_then(|saved| {
        param
            .get(&saved)
            .map_err(|_| format!("{} is not in the table as loaded", param.path()))
    });
    let outcome = saved.and_then(|value| {
        let model = super::model(app)?;
        app.views.system.settings.set(row, value, &model)
    });
    match outcome {
        Ok(changed) => {
            edited(app, Ok(changed));
            let shown = super::model(app)
                .map(|m| app.views.system.settings.show(row, &m))
                .unwrap_or_default();
            app.say(format!("{} reset to {shown}", param.path()), false);
        }
        Err(reason) => app.say(reason, true),
    }
}

/// ↑↓ choose a system preset, Enter adds its `[system]` table to the scene.
fn add_system(app: &mut App, action: Action) -> Option<Action> {
    let n = SYSTEM_PRESETS.len();
    let i = app.views.system.cursor.min(n - 1);
    match action {
        Action::Up => app.views.system.cursor = (i + n - 1) % n,
        Action::Down => app.views.system.cursor = (i + 1) % n,
        Action::Enter => {
            let name = SYSTEM_PRESETS[i];
            match settings::preset_spec(&app.registry, name) {
                Ok(spec) => {
                    app.draft.system = Some(spec);
                    app.views.system.cursor = 0;
                    app.say(
                        format!(
                            "added the [system] table of {name} to this scene: s saves it, u takes it back"
                        ),
                        false,
                    );
                }
                Err(reason) => app.say(reason, true),
            }
        }
        action => return Some(action),
    }
    None
}
