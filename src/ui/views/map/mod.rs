//! The map view (docs/maps.md §6): the type of motion of the scene's `[system]` over a grid of two
//! of its keys — n:m periodic, quasi-periodic or chaotic by the largest Lyapunov exponent of the
//! impact map, chattering, sticking — with the rigid stop, the focused law's compliant stop, and
//! their difference as a map of its own. The map fills in row by row as it computes; a cursor on
//! a cell reads both stops' values there.

mod keys;
mod render;
pub mod settings;

use ratatui::Frame;
use ratatui::layout::{Position, Rect};

use crate::chart::Chart;
use crate::chart::map::{Look, MapPoint, look, motion_map};
use crate::model::study::map::{MapData, MapStudy};
use crate::model::study::runner::{StudyKind, StudySpec};
use crate::model::system::map::Motion;
use crate::model::system::{Param, SystemModel};
use crate::ui::action::Action;
use crate::ui::app::{App, EditTarget, Valid};
use crate::ui::layout::{ScreenLayout, screen_layout};
use crate::ui::views::system::settings as system_settings;

use super::{FIGURE_TICKS, Hints, View};

use settings::{Settings, Shown, fitted_points};

pub use render::{Areas, areas, cell_at, column_of, row_of};

pub struct Map;

/// Where the arrow keys go.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Focus {
    /// The form's rows.
    #[default]
    Form,
    /// The cursor on the map's cells.
    Map,
}

/// The map view's own state.
#[derive(Debug, Clone, Default)]
pub struct State {
    pub settings: Settings,
    /// The form row under the cursor (an index into [`settings::ROWS`]; on a scene without
    /// `[system]`, into the system view's presets).
    pub cursor: usize,
    pub focus: Focus,
    /// The cell under the map's cursor: (ix, iy), iy counted up from the bottom row.
    pub cell: (usize, usize),
    /// The map cancelled with Esc: not asked for again until a setting changes or it is asked
    /// for again (Enter on the map).
    pub cancelled: Option<StudySpec>,
}

/// The look of a motion on the map, its legend and the figure: the one place a kind of motion
/// gets its glyph, colour and words (those of `hertz-tui map`), so that a new kind is one line of
/// [`look`].
pub fn look_of(motion: Motion) -> Look {
    look(motion.name(), motion.period().map(|p| p.0))
}

/// The model the view maps: the last valid scene in the draft's `[system]` table, or why there is
/// none.
pub fn model(app: &App) -> Result<SystemModel, String> {
    let scene = match &app.valid {
        Some(valid) => &valid.scene,
        None => &app.draft.scene,
    };
    system_settings::model(app.draft.system.as_ref(), scene)
}

/// The screen areas of the view at the app's terminal size (`None` below the minimum).
pub fn screen_areas(app: &App) -> Option<Areas> {
    let (w, h) = app.screen;
    let screen = screen_layout(Rect::new(0, 0, w, h))?;
    Some(areas(screen.body, screen.roomy))
}

/// The points that fit the map's pane at the app's terminal size.
pub fn fitted(app: &App) -> (usize, usize) {
    let cap = if app.views.map.settings.rigid_only {
        settings::MAX_RIGID_CELLS
    } else {
        settings::MAX_CELLS
    };
    match screen_areas(app) {
        Some(a) => fitted_points(a.cells.width, a.cells.height, cap),
        None => fitted_points(48, 12, cap),
    }
}

/// The study the settings ask for on `model`.
pub fn study(app: &App, model: &SystemModel) -> MapStudy {
    let s = &app.views.map.settings;
    let mut contacts = system_settings::contacts(model, app.focused);
    if s.rigid_only {
        contacts.truncate(1);
    }
    MapStudy {
        model: model.clone(),
        contacts,
        grid: s.grid(model, fitted(app)),
        options: s.options(),
        start: s.start,
    }
}

/// The map data shown, if any.
pub fn data(app: &App) -> Option<&MapData> {
    app.studies.map().map(|d| &**d)
}

impl View for Map {
    fn id(&self) -> &'static str {
        "map"
    }

    fn title(&self) -> &'static str {
        "map"
    }

    fn render(&self, frame: &mut Frame, screen: &ScreenLayout, app: &App) {
        render::render(frame, screen, app);
    }

    fn hints(&self) -> Hints {
        &[
            ("↑↓", "move"),
            ("Enter", "edit"),
            ("←→", "step"),
            ("PgDn", "cursor"),
            ("c", "map"),
            ("Esc", "cancel"),
        ]
    }

    fn handle(&self, app: &mut App, action: Action) -> Option<Action> {
        keys::handle(app, action)
    }

    fn commit(&self, app: &mut App, target: EditTarget, text: &str) -> Result<(), String> {
        match target {
            EditTarget::Row(i) => keys::commit(app, i, text),
            EditTarget::Field(_) => Ok(()),
        }
    }

    fn click(&self, app: &mut App, at: Position) {
        keys::click(app, at);
    }

    fn studies(&self) -> &'static [StudyKind] {
        &[StudyKind::Map]
    }

    fn study_specs(&self, app: &App, valid: &Valid) -> Vec<StudySpec> {
        let Ok(model) = system_settings::model(app.draft.system.as_ref(), &valid.scene) else {
            // The view says why; there is nothing to run.
            return Vec::new();
        };
        let spec = StudySpec::Map(Box::new(study(app, &model)));
        if app.views.map.cancelled.as_ref() == Some(&spec) {
            return Vec::new();
        }
        vec![spec]
    }

    fn charts(&self, app: &App) -> Vec<Chart> {
        let (Ok(model), Some(data)) = (model(app), data(app)) else {
            return Vec::new();
        };
        [Shown::Rigid, Shown::Compliant, Shown::Difference]
            .into_iter()
            .filter_map(|shown| layer_chart(data, shown, &model, FIGURE_TICKS))
            .collect()
    }
}

/// A key's axis on a figure: (key, unit symbol, span).
fn figure_axis(param: Param, model: &SystemModel, span: (f64, f64)) -> (String, &'static str, (f64, f64)) {
    (param.path(), settings::unit(param, model).symbol, span)
}

/// One map as a figure chart through [`motion_map`], as `hertz-tui map --figure` draws it.
fn layer_chart(
    data: &MapData,
    shown: Shown,
    model: &SystemModel,
    ticks: (usize, usize),
) -> Option<Chart> {
    let cells = render::shown_cells(data, shown)?;
    let points: Vec<MapPoint> = cells
        .iter()
        .map(|c| MapPoint {
            x: c.x,
            y: c.y,
            look: c.look.clone(),
        })
        .collect();
    let g = &data.grid;
    let (xk, xu, xs) = figure_axis(g.x.param, model, (g.x.from, g.x.to));
    let (yk, yu, ys) = figure_axis(g.y.param, model, (g.y.from, g.y.to));
    Some(motion_map(
        format!("{} map of {}", render::layer_name(data, shown), model.spec.kind_name()),
        (&xk, xu, xs),
        (&yk, yu, ys),
        &points,
        ticks,
    ))
}
