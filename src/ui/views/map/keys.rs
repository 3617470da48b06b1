//! The map view's keys. On the form: ↑↓ move between its rows, Enter types the row, ←→ step it.
//! PgDn puts the arrow keys on the map's cursor (PgUp, or Esc when nothing runs, back to the
//! form); a click on a cell does too. `c` shows the next map (rigid, compliant, difference); Esc
//! cancels a map being computed, Enter on the map computes it again.

use ratatui::layout::Position;

use crate::model::study::runner::{StudyKind, StudySpec};
use crate::model::system::SystemModel;
use crate::ui::action::{Action, Jump};
use crate::ui::app::{App, EditTarget};
use crate::ui::field::Nudge;

use super::settings::ROWS;
use super::{Focus, data, fitted, screen_areas, study};

pub fn handle(app: &mut App, action: Action) -> Option<Action> {
    let Ok(model) = super::model(app) else {
        return Some(action);
    };
    match action {
        Action::Cancel if app.studies.is_pending(StudyKind::Map) => cancel(app, &model),
        Action::CycleChart => {
            let s = &mut app.views.map.settings;
            s.shown = s.shown.next();
        }
        Action::Jump(Jump::NextSection) => app.views.map.focus = Focus::Map,
        Action::Jump(Jump::PreviousSection) => app.views.map.focus = Focus::Form,
        action => {
            return match app.views.map.focus {
                Focus::Form => form_key(app, action, &model),
                Focus::Map => map_key(app, action),
            };
        }
    }
    None
}

fn form_key(app: &mut App, action: Action, model: &SystemModel) -> Option<Action> {
    let n = ROWS.len();
    let i = app.views.map.cursor.min(n - 1);
    match action {
        Action::Up => app.views.map.cursor = (i + n - 1) % n,
        Action::Down => app.views.map.cursor = (i + 1) % n,
        Action::Jump(Jump::First) => app.views.map.cursor = 0,
        Action::Jump(Jump::Last) => app.views.map.cursor = n - 1,
        Action::Enter => {
            let text = app
                .views
                .map
                .settings
                .edit_text(ROWS[i], model, fitted(app));
            app.open_editor(EditTarget::Row(i), text);
        }
        Action::Nudge(direction) => {
            let fitted = fitted(app);
            let up = direction == Nudge::Up;
            match app.views.map.settings.nudge(ROWS[i], up, model, fitted) {
                Ok(()) => app.views.map.cancelled = None,
                Err(reason) => app.say(reason, true),
            }
        }
        action => return Some(action),
    }
    None
}

/// The grid's points: of the map shown, else of the settings.
fn points(app: &App) -> (usize, usize) {
    match data(app) {
        Some(d) => (d.grid.x.points, d.grid.y.points),
        None => {
            let (x, y) = fitted(app);
            let s = &app.views.map.settings;
            (
                s.points(super::settings::Which::X, (x, y)),
                s.points(super::settings::Which::Y, (x, y)),
            )
        }
    }
}

fn map_key(app: &mut App, action: Action) -> Option<Action> {
    let (nx, ny) = points(app);
    let (ix, iy) = app.views.map.cell;
    let (ix, iy) = (ix.min(nx - 1), iy.min(ny - 1));
    let cell = match action {
        Action::Up => (ix, (iy + 1).min(ny - 1)),
        Action::Down => (ix, iy.saturating_sub(1)),
        Action::Nudge(Nudge::Up) => ((ix + 1).min(nx - 1), iy),
        Action::Nudge(Nudge::Down) => (ix.saturating_sub(1), iy),
        Action::Jump(Jump::First) => (0, iy),
        Action::Jump(Jump::Last) => (nx - 1, iy),
        Action::Enter => {
            if app.views.map.cancelled.take().is_some() {
                app.say("computing the map again", false);
            }
            return None;
        }
        Action::Cancel => {
            app.views.map.focus = Focus::Form;
            return None;
        }
        action => return Some(action),
    };
    app.views.map.cell = cell;
    None
}

/// Esc while the map computes: stops it, keeps the rows done, and asks for it no more.
fn cancel(app: &mut App, model: &SystemModel) {
    let spec = StudySpec::Map(Box::new(study(app, model)));
    if app.cancel_study(StudyKind::Map) {
        app.views.map.cancelled = Some(spec);
        let (done, all) = data(app).map_or((0, 0), |d| d.progress());
        app.say(
            format!("map cancelled ({done}/{all} rows done): Enter on the map (PgDn) computes it again"),
            false,
        );
    }
}

/// Commits the text typed into row `i`; the reason, naming the row, if refused.
pub fn commit(app: &mut App, i: usize, text: &str) -> Result<(), String> {
    let model = super::model(app)?;
    let Some(&row) = ROWS.get(i) else {
        return Ok(());
    };
    match app.views.map.settings.apply(row, text, &model) {
        Ok(()) => {
            app.views.map.cancelled = None;
            Ok(())
        }
        Err(reason) => {
            app.say(reason.clone(), true);
            Err(reason)
        }
    }
}

/// A click on a cell puts the cursor there; on a row of the form, the form's cursor.
pub fn click(app: &mut App, at: Position) {
    let Some(areas) = screen_areas(app) else {
        return;
    };
    if areas.form.contains(at) {
        let first = areas.form_rows.y;
        if let Some(i) = at.y.checked_sub(first).map(usize::from)
            && i < ROWS.len()
        {
            app.views.map.focus = Focus::Form;
            app.views.map.cursor = i;
        }
        return;
    }
    let (nx, ny) = points(app);
    if let Some(cell) = super::cell_at(areas.cells, (nx, ny), at) {
        app.views.map.focus = Focus::Map;
        app.views.map.cell = cell;
    }
}
