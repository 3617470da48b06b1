//! The fit view's keys: `o` opens a data file (a path prompt), ↑↓ move in the ranking, Enter
//! writes the fit under the cursor into the scene's `[fit]` (an edit of the draft: `u` undoes
//! it, `s` saves it), `c` fits every fittable law or only the checked ones.

use crate::format::{Zeros, significant};
use crate::model::scene_fit::FittedLaw;
use crate::ui::action::Action;
use crate::ui::app::{App, EditTarget};

use super::{Source, finished, open, proposed_path};

pub fn handle(app: &mut App, action: Action) -> Option<Action> {
    match action {
        Action::Open => {
            let path = proposed_path(app).display().to_string();
            app.open_editor(EditTarget::Row(0), path);
        }
        Action::Up => step(app, false),
        Action::Down => step(app, true),
        Action::Enter => use_fit(app),
        Action::CycleChart => {
            let s = &mut app.views.fit;
            s.checked_only = !s.checked_only;
            s.cursor = 0;
            app.say(
                if app.views.fit.checked_only {
                    "fitting constant e and the checked laws (Space checks, c: every law)"
                } else {
                    "fitting every fittable law (c: only the checked ones)"
                },
                false,
            );
        }
        action => return Some(action),
    }
    None
}

/// Opens the file typed into the prompt; a refused file is shown in the view, not here.
pub fn commit_path(app: &mut App, text: &str) -> Result<(), String> {
    let text = text.trim();
    if text.is_empty() {
        return Err(format!(
            "type the path of a CSV file of v and e, e.g. {}",
            super::EXAMPLE
        ));
    }
    open(app, &crate::ui::update::expand_home(text));
    Ok(())
}

fn step(app: &mut App, down: bool) {
    let n = finished(app).map_or(0, |(_, r)| r.fits.len());
    if n == 0 {
        return;
    }
    let i = app.views.fit.cursor.min(n - 1);
    app.views.fit.cursor = if down { (i + 1) % n } else { (i + n - 1) % n };
}

/// Writes the fit under the cursor into the draft's `[fit]`: its law and constant, and the e it
/// realises at the scene's v₀ (docs/fitting.md); the law is checked and focused.
fn use_fit(app: &mut App) {
    let Some((_, report)) = finished(app) else {
        let why = match &app.views.fit.source {
            Source::None => "no data loaded: o opens a data file",
            Source::Failed { .. } => "the data file was refused: o opens another",
            Source::Loaded { .. } => "the fit is still running",
        };
        app.say(why, true);
        return;
    };
    let Some(fit) = report.fits.get(app.views.fit.cursor.min(report.fits.len() - 1)) else {
        return;
    };
    let Some(param) = fit.params.first() else {
        app.say(format!("{} has no parameter to write", fit.candidate), true);
        return;
    };
    let rank = app.views.fit.cursor.min(report.fits.len() - 1) + 1;
    let file = match &app.views.fit.source {
        Source::Loaded { path, .. } => Some(path.clone()),
        _ => None,
    };
    let fitted = FittedLaw {
        kind: fit.candidate,
        value: param.value,
        source: file,
        note: Some(format!(
            "ranked {rank} of {} by {} (weight {}) over {} points, in the explorer",
            report.fits.len(),
            report.criterion.name(),
            significant(fit.weight, 3, Zeros::Keep),
            fit.n_points
        )),
    };
    let (candidate, symbol, value) = (fit.candidate, param.spec.symbol, param.value);
    let unit = param.spec.unit;
    let mut scene = app.draft.scene.clone();
    scene.fit = Some(fitted.clone());
    if let Err(e) = scene.apply_fit() {
        app.say(format!("the fitted {candidate} cannot set e: {e}"), true);
        return;
    }
    // The draft takes the fit alone: `recompute` sets e from it (an e changed beside a fit
    // would read as typed over it, and the fit would give way).
    app.draft.scene.fit = Some(fitted);
    if let Some(model) = candidate.model() {
        if !app.is_checked(model) {
            app.toggle(model);
        }
        app.focused = model;
    }
    app.recompute();
    let unit = if unit == "1" {
        String::new()
    } else {
        format!(" {unit}")
    };
    app.say(
        format!(
            "[fit] {candidate}, {symbol} = {}{unit}: e = {} at v0; every view uses it (u undoes, s saves)",
            significant(value, 4, Zeros::Keep),
            significant(app.draft.scene.impact.restitution, 4, Zeros::Keep)
        ),
        false,
    );
}
