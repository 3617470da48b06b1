//! The system view: the scene's bodies in their machine (its `[system]` table; docs/systems.md),
//! the rigid stop and the focused law's compliant stop side by side: time history with the stops,
//! phase portrait, impact map, and a bifurcation diagram that fills in as it computes. Every edit
//! (of the scene in the explorer, of the system's keys here) runs it again.

pub mod branch;
mod keys;
mod render;
pub mod settings;

use ratatui::Frame;

use crate::chart::Chart;
use crate::chart::system::{self as plot, Approach, Branch, DiagramAxes, Motion, Stops};
use crate::model::study::runner::{StudyKind, StudySpec};
use crate::model::study::system::{DiagramData, DiagramStudy, SystemRuns, SystemStudy};
use crate::model::system::{History, SystemModel};
use crate::ui::action::Action;
use crate::ui::app::{App, EditTarget, Valid};
use crate::ui::layout::ScreenLayout;

use super::{FIGURE_TICKS, Hints, View};

use settings::{Row, Settings};

pub struct System;

/// The system view's own state.
#[derive(Debug, Clone, Default)]
pub struct State {
    pub settings: Settings,
    /// The row of the form under the cursor (an index into [`Settings::rows`]; on a scene without
    /// `[system]`, into [`settings::SYSTEM_PRESETS`]).
    pub cursor: usize,
    /// `b`: the continued branch drawn over the diagram (docs/continuation.md §8).
    pub branch: bool,
}

/// The model the view runs: the last valid scene in the draft's `[system]` table, or why there is
/// none.
pub fn model(app: &App) -> Result<SystemModel, String> {
    let scene = match &app.valid {
        Some(valid) => &valid.scene,
        None => &app.draft.scene,
    };
    settings::model(app.draft.system.as_ref(), scene)
}

/// The row under the cursor, for `model`.
pub fn cursor_row(app: &App, model: &SystemModel) -> Option<Row> {
    let rows = Settings::rows(model);
    rows.get(app.views.system.cursor.min(rows.len().saturating_sub(1)))
        .copied()
}

impl View for System {
    fn id(&self) -> &'static str {
        "system"
    }

    /// `sys`: with the five views before it, `system` would not fit the tab bar at 80 columns.
    fn title(&self) -> &'static str {
        "sys"
    }

    fn render(&self, frame: &mut Frame, screen: &ScreenLayout, app: &App) {
        render::render(frame, screen, app);
    }

    fn hints(&self) -> Hints {
        &[
            ("↑↓", "move"),
            ("Enter", "edit"),
            ("←→", "step"),
            ("u", "undo"),
            ("[ ]", "law"),
            ("b", "branch"),
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

    fn studies(&self) -> &'static [StudyKind] {
        &[
            StudyKind::System,
            StudyKind::Diagram,
            StudyKind::Continuation,
        ]
    }

    fn study_specs(&self, app: &App, valid: &Valid) -> Vec<StudySpec> {
        let Ok(model) = settings::model(app.draft.system.as_ref(), &valid.scene) else {
            // The view says why; there is nothing to run.
            return Vec::new();
        };
        let s = &app.views.system.settings;
        let contacts = settings::contacts(&model, app.focused);
        let (from, to) = s.range(&model);
        let values = crate::model::study::system::values(
            from,
            to,
            s.values.unwrap_or(settings::DEFAULT_VALUES),
        );
        let continued = app
            .views
            .system
            .branch
            .then(|| branch::spec(s, &model, &contacts));
        let mut specs = vec![
            StudySpec::System(Box::new(SystemStudy {
                model: model.clone(),
                contacts: contacts.clone(),
                run: settings::run_options(s),
            })),
            StudySpec::Diagram(Box::new(DiagramStudy {
                param: s.diagram_key(&model),
                model,
                contacts,
                values,
                options: settings::diagram_options(s),
            })),
        ];
        specs.extend(continued);
        specs
    }

    fn charts(&self, app: &App) -> Vec<Chart> {
        let Ok(model) = model(app) else {
            return Vec::new();
        };
        let mut charts = motion_charts(app.studies.system().map(|r| &**r), &model, FIGURE_TICKS);
        if let Some(d) = app.studies.diagram() {
            charts.push(match branch::shown(app, d) {
                Some(b) => branch::chart(d, b, &model, FIGURE_TICKS, 1),
                None => diagram_chart(d, &model, FIGURE_TICKS),
            });
        }
        charts
    }
}

/// Forcing periods the time history and the phase portrait show: the last few of the run.
const PERIODS_SHOWN: f64 = 6.0;

/// The runs that succeeded, with their look.
fn drawn_runs(runs: &SystemRuns) -> Vec<(Approach, &History)> {
    runs.runs
        .iter()
        .filter_map(|(c, r)| r.as_ref().ok().map(|h| (Approach::of(c), h)))
        .collect()
}

/// The time history, phase portrait and impact map of `runs`, each at most `budget` labels.
pub fn motion_charts(
    runs: Option<&SystemRuns>,
    model: &SystemModel,
    budget: (usize, usize),
) -> Vec<Chart> {
    let Some(runs) = runs else {
        return Vec::new();
    };
    let drawn = drawn_runs(runs);
    let end = drawn
        .iter()
        .filter_map(|(_, h)| h.samples.last().map(|s| s.t))
        .fold(f64::NEG_INFINITY, f64::max);
    let from = end - PERIODS_SHOWN * model.spec.period();
    let motions: Vec<(Approach, Motion)> =
        drawn.iter().map(|(a, h)| (*a, Motion::of(h, from))).collect();
    let refs: Vec<(Approach, &Motion)> = motions.iter().map(|(a, m)| (*a, m)).collect();
    let stops = Stops::of(model, drawn.first().map(|(_, h)| *h), from);
    vec![
        plot::time_history(&refs, &stops, budget),
        plot::phase_portrait(&refs, &stops, budget),
        plot::impact_map(&refs, budget),
    ]
}

/// The bifurcation diagram so far.
pub fn diagram_chart(data: &DiagramData, model: &SystemModel, budget: (usize, usize)) -> Chart {
    let branches: Vec<(Approach, Branch)> = data
        .branches
        .iter()
        .map(|b| (Approach::of(&b.contact), Branch::of(&b.columns)))
        .collect();
    let refs: Vec<(Approach, &Branch)> = branches.iter().map(|(a, b)| (*a, b)).collect();
    let mut axes = DiagramAxes::impact_speeds(data.param, model);
    axes.range = value_span(&data.values);
    plot::bifurcation(&refs, &axes, budget)
}

/// The span of a diagram's axis: every value asked for, so that the diagram fills in from the
/// left.
pub fn value_span(values: &[f64]) -> Option<(f64, f64)> {
    values.iter().fold(None, |r: Option<(f64, f64)>, &v| {
        Some(r.map_or((v, v), |(lo, hi)| (lo.min(v), hi.max(v))))
    })
}
