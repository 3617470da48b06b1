//! The sweep form's keys: ↑↓ move between its rows, ←→ change the row, Enter types it (or steps a
//! row that has choices rather than a value).

use tui_input::Input;

use crate::ui::action::Action;
use crate::ui::app::{App, Export, Mode, Prompt, PromptKind};
use crate::ui::export;
use crate::ui::field::Nudge;
use crate::ui::views;

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
        Action::Export => export(app),
        action => return Some(action),
    }
    None
}

/// `e`: the sweep on screen to a CSV file, as `sweep --format csv` writes it (the other views
/// export the focused model's trajectory).
fn export(app: &mut App) {
    let key = match app.studies.sweep() {
        Some(Ok(data)) if !views::is_studying(app) => data.spec.key,
        Some(Err(reason)) => return app.say(format!("no sweep to export: {reason}"), true),
        _ => return app.say("the sweep is being computed: export when it is done", true),
    };
    let stem = app.preset.as_deref().unwrap_or(&app.draft.scene.name);
    let path = export::default_sweep_path(stem, key);
    app.mode = Mode::Prompt(Prompt {
        kind: PromptKind::Export(Export::Sweep),
        input: Input::new(path.display().to_string()),
        error: None,
        then_quit: false,
    });
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
