//! The stability view's keys: ←→ halve and double the step, Enter types it.

use crate::ui::action::Action;
use crate::ui::app::App;
use crate::ui::field::Nudge;
use crate::format::units;

/// Smallest and largest step the stability view accepts, s: beyond them a fixed-step solve only
/// exhausts its step budget or takes one step for the whole impact.
const STEP_LIMITS: (f64, f64) = (1e-15, 1.0);

pub fn handle(app: &mut App, action: Action) -> Option<Action> {
    match action {
        Action::Nudge(direction) => {
            if let Some(dt) = super::step(app) {
                let next = match direction {
                    Nudge::Up => dt * 2.0,
                    Nudge::Down => dt / 2.0,
                };
                if (STEP_LIMITS.0..=STEP_LIMITS.1).contains(&next) {
                    app.views.stability.step = Some(next);
                } else {
                    app.say("the step stays within 1 fs … 1 s", true);
                }
            }
            None
        }
        Action::Enter => {
            let text = match app.views.stability.step {
                Some(dt) => units::engineering(dt, units::SECOND, 4),
                None => "auto".into(),
            };
            app.open_editor(super::STEP_EDITOR, text);
            None
        }
        action => Some(action),
    }
}

/// Commits a typed step (or `auto`); the reason if it is refused.
pub fn commit_step(app: &mut App, text: &str) -> Result<(), String> {
    if text.trim() == "auto" {
        app.views.stability.step = None;
        return Ok(());
    }
    let dt = units::parse(text, units::SECOND)?;
    if !(STEP_LIMITS.0..=STEP_LIMITS.1).contains(&dt) {
        return Err("the step must be within 1 fs … 1 s (or auto)".into());
    }
    app.views.stability.step = Some(dt);
    Ok(())
}
