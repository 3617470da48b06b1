//! One chart (F(x), F(t) or v(x)) of the checked models: braille curves in each model's colour and
//! line pattern, the exact peak of each as a point, axes in engineering units.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::symbols::Marker;
use ratatui::text::Line;
use ratatui::widgets::{Axis, Chart, Dataset, GraphType, Paragraph, Wrap};

use crate::model::ForceModel;
use crate::ui::app::{App, ChartKind};
use crate::ui::plot::{Pieces, Series, dash, plot};
use crate::ui::theme::{LinePattern, Role};

use super::common::{model_name, pane, span};

/// Columns taken by the y labels and axis line, and rows by the x labels and axis line.
const Y_AXIS_COLUMNS: u16 = 7;
const X_AXIS_ROWS: u16 = 2;

/// Whether x labels spread evenly over `columns` leave a blank between neighbours.
fn labels_fit(labels: &[String], columns: u16) -> bool {
    let longest = labels.iter().map(|l| l.chars().count()).max().unwrap_or(0);
    let slot = usize::from(columns) / labels.len().saturating_sub(1).max(1);
    longest < slot
}

/// The models drawn, the focused one last so it lies on top.
fn drawn_models(app: &App) -> Vec<ForceModel> {
    let mut models: Vec<ForceModel> = app
        .checked_models()
        .into_iter()
        .filter(|&m| app.solutions.solution(m).is_some())
        .collect();
    if let Some(i) = models.iter().position(|&m| m == app.focused) {
        let focused = models.remove(i);
        models.push(focused);
    }
    models
}

/// The legend of the drawn models: line sample and short name in the model's style, as many
/// entries as fit in `width` columns.
fn legend(app: &App, models: &[ForceModel], width: usize) -> Line<'static> {
    let mut spans = Vec::new();
    let mut used = 0;
    for &model in ForceModel::ALL.iter().filter(|m| models.contains(m)) {
        let sample = format!(" {} ", LinePattern::of(model).sample());
        let name = format!("{} ", model_name(model, 9));
        used += sample.chars().count() + name.chars().count();
        if used > width {
            break;
        }
        let style = app.theme.model_style(model);
        spans.push(span(sample, style));
        spans.push(span(name, style));
    }
    Line::from(spans)
}

pub fn render(frame: &mut Frame, area: Rect, app: &App, kind: ChartKind, roomy: bool) {
    let theme = app.theme;
    let mut title = kind.title().to_string();
    if app.scene_error.is_some() {
        title.push_str(" · last valid scene");
    }
    let block = pane(title, theme, roomy);
    let inner = block.inner(area);
    let models = drawn_models(app);
    if models.is_empty() {
        let text = if app.is_computing() {
            "computing…"
        } else if app.checked_models().is_empty() {
            "no model checked: Space on a model draws it"
        } else {
            "no solution to draw (see the results)"
        };
        let note = Paragraph::new(Line::from(span(text, theme.style(Role::Muted))))
            .wrap(Wrap { trim: true })
            .block(block);
        frame.render_widget(note, area);
        return;
    }
    let dots_x = app.marker.dots_per_cell();
    let dots_y: u16 = match app.marker.marker() {
        Marker::Braille => 4,
        _ => 1,
    };
    let plot_columns = inner.width.saturating_sub(Y_AXIS_COLUMNS).max(1);
    let plot_rows = inner.height.saturating_sub(X_AXIS_ROWS).max(1);
    // About two samples per plot column.
    let n = 2 * usize::from(plot_columns * dots_x);
    let series: Vec<Series> = models
        .iter()
        .filter_map(|&m| app.solutions.solution(m).map(|s| Series::sample(m, s, n)))
        .collect();
    let mut max_x_labels = (usize::from(plot_columns) / 7).clamp(2, 11);
    let max_y_labels = (usize::from(plot_rows) / 2).clamp(2, 8);
    let mut p = plot(kind, &series, max_x_labels, max_y_labels);
    // Fewer x labels while the longest (a scientific one, 1.25e100) overruns its slot.
    while max_x_labels > 2 && !labels_fit(&p.x.labels, plot_columns) {
        max_x_labels -= 1;
        p = plot(kind, &series, max_x_labels, max_y_labels);
    }
    let dots_per_x = f64::from(plot_columns * dots_x) / (p.x.bounds[1] - p.x.bounds[0]);
    let dots_per_y = f64::from(plot_rows * dots_y) / (p.y.bounds[1] - p.y.bounds[0]);
    let pieces: Vec<(ForceModel, Pieces, (f64, f64))> = p
        .curves
        .iter()
        .map(|c| {
            let pattern = LinePattern::of(c.model);
            (
                c.model,
                dash(&c.points, pattern, dots_per_x, dots_per_y),
                c.peak,
            )
        })
        .collect();
    let marker = app.marker.marker();
    let mut datasets = Vec::new();
    // One scatter per model: its dashes rastered, its dots and its exact peak.
    let rasters: Vec<(ForceModel, Vec<(f64, f64)>)> = pieces
        .iter()
        .map(|(model, cut, peak)| {
            let mut points = cut.raster(dots_per_x, dots_per_y);
            points.push(*peak);
            (*model, points)
        })
        .collect();
    for (model, points) in &rasters {
        datasets.push(
            Dataset::default()
                .marker(marker)
                .graph_type(GraphType::Scatter)
                .style(theme.model_style(*model))
                .data(points),
        );
    }
    let block = if roomy {
        block.title_bottom(legend(
            app,
            &models,
            usize::from(area.width.saturating_sub(2)),
        ))
    } else {
        block
    };
    let axis_style = theme.style(Role::Muted);
    let chart = Chart::new(datasets)
        .block(block)
        .x_axis(
            Axis::default()
                .title(span(p.x_title.clone(), theme.style(Role::Label)))
                .style(axis_style)
                .bounds(p.x.bounds)
                .labels(p.x.labels.clone()),
        )
        .y_axis(
            Axis::default()
                .title(span(p.y_title.clone(), theme.style(Role::Label)))
                .style(axis_style)
                .bounds(p.y.bounds)
                .labels(p.y.labels.clone()),
        )
        .legend_position(None);
    frame.render_widget(chart, area);
}
