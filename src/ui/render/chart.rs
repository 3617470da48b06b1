//! One chart (F(x), F(t) or v(x)) of the checked models: solid curves in each model's colour, the
//! focused one last and bold, each model's glyph at its exact peak and its end, and the reason of
//! every model that failed.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::{Paragraph, Wrap};

use crate::chart::{Chart, Ink, model_glyph};
use crate::model::ForceModel;
use crate::ui::app::{App, ChartKind};
use crate::ui::plot::{Look, Series, plot};
use crate::ui::theme::Role;

use super::common::{model_name, pane, span};
use super::graph;
use super::results::reason_first;

/// The models drawn.
fn drawn_models(app: &App) -> Vec<ForceModel> {
    app.checked_models()
        .into_iter()
        .filter(|&m| app.solutions.solution(m).is_some())
        .collect()
}

/// Why each checked model that failed has no curve: `✗ proposed: …`.
fn failures(app: &App) -> Vec<String> {
    app.checked_models()
        .into_iter()
        .filter_map(|m| match app.solutions.result(m) {
            Some(Err(message)) => Some(format!("✗ {}: {}", m.name(), reason_first(message))),
            _ => None,
        })
        .collect()
}

/// Tick budgets for a plot of about `columns` × `rows` cells: labels need a few columns each and
/// a blank row between them.
pub fn budget(columns: u16, rows: u16) -> (usize, usize) {
    (
        usize::from(columns / 7).clamp(2, 11),
        (usize::from(rows.saturating_sub(1)) / 2 + 1).clamp(2, 8),
    )
}

/// The chart of `kind` for the models of `app` drawn in `columns` × `rows` cells.
pub fn describe(app: &App, kind: ChartKind, columns: u16, rows: u16) -> Chart {
    let series: Vec<&Series> = drawn_models(app)
        .iter()
        .filter_map(|&m| app.solutions.samples(m))
        .collect();
    let (max_x, max_y) = budget(columns, rows);
    let mut chart =
        plot(kind, &series, max_x, max_y).into_chart(kind.title().to_string(), |m| Look {
            name: model_name(m, 9).to_string(),
            ink: Ink::Model(m),
            glyph: model_glyph(m),
            focused: m == app.focused,
            steps: false,
        });
    chart.notes = failures(app);
    chart
}

/// Draws the chart of `kind`; `single` where it is the only one shown, so the title says which
/// key shows the others.
pub fn render(
    frame: &mut Frame,
    area: Rect,
    app: &App,
    kind: ChartKind,
    roomy: bool,
    single: bool,
) {
    let theme = app.theme;
    let mut title = kind.title().to_string();
    if app.scene_error.is_some() {
        title.push_str(" · last valid scene");
    }
    if single {
        title.push_str(" · c: next chart");
    }
    let block = pane(title, theme, roomy);
    let inner = block.inner(area);
    if drawn_models(app).is_empty() {
        let failed = failures(app);
        let (texts, role) = if app.is_computing() {
            (vec!["computing…".to_string()], Role::Muted)
        } else if app.checked_models().is_empty() {
            (
                vec!["no model checked: Space on a model draws it".to_string()],
                Role::Muted,
            )
        } else if !failed.is_empty() {
            (failed, Role::Error)
        } else {
            (vec!["no solution to draw".to_string()], Role::Muted)
        };
        let lines: Vec<Line> = texts
            .into_iter()
            .map(|t| Line::from(span(t, theme.style(role))))
            .collect();
        let note = Paragraph::new(lines).wrap(Wrap { trim: true }).block(block);
        frame.render_widget(note, area);
        return;
    }
    // The plot is the frame less the labels, axis lines and titles: about 7 columns, 4 rows.
    let chart = describe(
        app,
        kind,
        inner.width.saturating_sub(7),
        inner.height.saturating_sub(4),
    );
    let block = if roomy {
        block.title_bottom(graph::legend(
            &chart,
            theme,
            usize::from(area.width.saturating_sub(2)),
        ))
    } else {
        block
    };
    graph::render(frame, area, block, &chart, app.marker, theme);
}
