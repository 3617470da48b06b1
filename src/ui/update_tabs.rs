//! Transitions of the study tabs (2–4) in normal mode: the keys that act on their settings (the
//! stability step, the sweep form), and the commits of their line editors.

use tui_input::Input;

use super::action::Action;
use super::app::{App, EditTarget, Editor, Mode};
use super::field::Nudge;
use super::sweep_settings::SweepField;
use super::tab::Tab;
use super::units;

/// Smallest and largest step the stability view accepts, s: beyond them a fixed-step solve only
/// exhausts its step budget or takes one step for the whole impact.
const STEP_LIMITS: (f64, f64) = (1e-15, 1.0);

/// Handles `action` if it belongs to the shown study tab; returns it otherwise (keys shared by all
/// tabs: quit, help, presets, models…).
pub fn study_tab(app: &mut App, action: Action) -> Option<Action> {
    match (app.tab, action) {
        (Tab::Stability, Action::Nudge(direction)) => {
            if let Some(dt) = app.stability_step() {
                let next = match direction {
                    Nudge::Up => dt * 2.0,
                    Nudge::Down => dt / 2.0,
                };
                if (STEP_LIMITS.0..=STEP_LIMITS.1).contains(&next) {
                    app.step = Some(next);
                } else {
                    app.say("the step stays within 1 fs … 1 s", true);
                }
            }
            None
        }
        (Tab::Stability, Action::Enter) => {
            let text = match app.step {
                Some(dt) => units::engineering(dt, units::SECOND, 4),
                None => "auto".into(),
            };
            open_editor(app, EditTarget::Step, text);
            None
        }
        (Tab::Sweep, Action::Up) => {
            app.sweep_cursor = app.sweep_cursor.step(false);
            None
        }
        (Tab::Sweep, Action::Down) => {
            app.sweep_cursor = app.sweep_cursor.step(true);
            None
        }
        (Tab::Sweep, Action::Nudge(direction)) => {
            nudge_sweep(app, app.sweep_cursor, direction);
            None
        }
        (Tab::Sweep, Action::Enter) => {
            let field = app.sweep_cursor;
            if field.is_typed() {
                let text = app.sweep.edit_text(field, &sweep_scene(app));
                open_editor(app, EditTarget::Sweep(field), text);
            } else {
                nudge_sweep(app, field, Nudge::Up);
            }
            None
        }
        (Tab::WorkPrecision, Action::CycleChart) => {
            app.cost = app.cost.other();
            None
        }
        (Tab::Restitution, Action::CycleChart) => {
            app.restitution_table = !app.restitution_table;
            None
        }
        // Nothing to move, nudge or edit in these tabs: the keys do nothing rather than reach
        // the explorer's hidden form.
        (
            Tab::WorkPrecision | Tab::Stability | Tab::Restitution,
            Action::Up | Action::Down | Action::Nudge(_) | Action::Enter,
        )
        | (_, Action::CycleChart) => None,
        (_, action) => Some(action),
    }
}

/// The scene the sweep varies: the last valid one (the form may hold an invalid draft).
fn sweep_scene(app: &App) -> crate::model::Scene {
    match &app.valid {
        Some(valid) => valid.scene.clone(),
        None => app.draft.scene.clone(),
    }
}

fn nudge_sweep(app: &mut App, field: SweepField, direction: Nudge) {
    let scene = sweep_scene(app);
    let max = app.sweep_max_points();
    app.sweep.nudge(field, direction, &scene, max);
}

fn open_editor(app: &mut App, target: EditTarget, text: String) {
    app.mode = Mode::Editing(Editor {
        target,
        input: Input::new(text),
        error: None,
    });
}

/// Commits the text of a study editor; the reason if it is refused (the editor stays open).
pub fn commit(app: &mut App, target: EditTarget, text: &str) -> Result<(), String> {
    match target {
        EditTarget::Step => {
            if text.trim() == "auto" {
                app.step = None;
                return Ok(());
            }
            let dt = units::parse(text, units::SECOND)?;
            if !(STEP_LIMITS.0..=STEP_LIMITS.1).contains(&dt) {
                return Err("the step must be within 1 fs … 1 s (or auto)".into());
            }
            app.step = Some(dt);
            Ok(())
        }
        EditTarget::Sweep(field) => {
            let scene = sweep_scene(app);
            app.sweep.apply(field, text, &scene)
        }
        // The explorer's fields are committed by the explorer.
        EditTarget::Field(_) => Ok(()),
    }
}
