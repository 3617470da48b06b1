//! An x–y chart of the study views: traces in their colours and dash patterns, single marks, and
//! labelled vertical rules (the yield-onset velocities of a v₀ sweep), on axes made elsewhere.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::symbols::Marker;
use ratatui::text::Span;
use ratatui::widgets::{Axis, Block, Chart, Dataset, GraphType, Paragraph};

use crate::ui::marker::MarkerStyle;
use crate::ui::plot::dash;
use crate::ui::theme::{LinePattern, Role, Theme};
use crate::ui::ticks::NiceAxis;

/// A polyline in display units.
#[derive(Debug, Clone, PartialEq)]
pub struct Trace {
    pub points: Vec<(f64, f64)>,
    pub style: Style,
    pub pattern: LinePattern,
}

/// A single point drawn with its own marker (a block stands out among braille lines).
#[derive(Debug, Clone, PartialEq)]
pub struct Mark {
    pub at: (f64, f64),
    pub style: Style,
    /// `None`: the chart marker.
    pub marker: Option<Marker>,
}

/// A vertical line across the plot at `x` (display units), labelled at its top.
#[derive(Debug, Clone, PartialEq)]
pub struct Rule {
    pub x: f64,
    pub label: String,
    pub style: Style,
    pub pattern: LinePattern,
}

/// Everything one chart draws.
#[derive(Debug, Clone, PartialEq)]
pub struct Graph {
    pub x: NiceAxis,
    pub y: NiceAxis,
    pub x_title: String,
    pub y_title: String,
    pub traces: Vec<Trace>,
    pub marks: Vec<Mark>,
    pub rules: Vec<Rule>,
}

/// The plot area ratatui's `Chart` leaves inside `inner` for these labels: the widest y label (or
/// the part of the first x label left of the axis, at most a third of the width) and the y axis
/// line on the left, the x labels and axis line at the bottom.
pub fn plot_area(inner: Rect, y_labels: &[String], first_x_label: Option<&str>) -> Rect {
    let y_width = y_labels
        .iter()
        .map(|l| l.chars().count())
        .max()
        .unwrap_or(0);
    let x_left = first_x_label.map_or(0, |l| l.chars().count().saturating_sub(1));
    let left = (y_width.max(x_left) as u16).min(inner.width / 3) + 1;
    let bottom = 2;
    Rect::new(
        inner.x + left.min(inner.width),
        inner.y,
        inner.width.saturating_sub(left),
        inner.height.saturating_sub(bottom),
    )
}

/// The column of display value `x` in `plot`, if it lies on the axis.
fn column(x: f64, axis: &NiceAxis, plot: Rect) -> Option<u16> {
    let [lo, hi] = axis.bounds;
    let s = (x - lo) / (hi - lo);
    if !(0.0..=1.0).contains(&s) || plot.width == 0 {
        return None;
    }
    let offset = (s * f64::from(plot.width - 1)).round() as u16;
    Some(plot.x + offset)
}

/// Draws `graph` in `area` inside `block`.
pub fn render(
    frame: &mut Frame,
    area: Rect,
    block: Block,
    graph: &Graph,
    marker: MarkerStyle,
    theme: Theme,
) {
    let inner = block.inner(area);
    let plot = plot_area(
        inner,
        &graph.y.labels,
        graph.x.labels.first().map(String::as_str),
    );
    let dots_y: u16 = match marker.marker() {
        Marker::Braille => 4,
        _ => 1,
    };
    let span = |axis: &NiceAxis| axis.bounds[1] - axis.bounds[0];
    let dots_per_x = f64::from(plot.width * marker.dots_per_cell()) / span(&graph.x);
    let dots_per_y = f64::from(plot.height * dots_y) / span(&graph.y);
    let rule_lines: Vec<Trace> = graph
        .rules
        .iter()
        .map(|r| Trace {
            points: vec![(r.x, graph.y.bounds[0]), (r.x, graph.y.bounds[1])],
            style: r.style,
            pattern: r.pattern,
        })
        .collect();
    // One scatter per trace, its dashes rastered: a few canvas layers, not one per dash.
    let rasters: Vec<_> = rule_lines
        .iter()
        .chain(&graph.traces)
        .map(|t| {
            let cut = dash(&t.points, t.pattern, dots_per_x, dots_per_y);
            (t.style, cut.raster(dots_per_x, dots_per_y))
        })
        .collect();
    let chart_marker = marker.marker();
    let mut datasets = Vec::new();
    for (style, points) in &rasters {
        datasets.push(
            Dataset::default()
                .marker(chart_marker)
                .graph_type(GraphType::Scatter)
                .style(*style)
                .data(points),
        );
    }
    for mark in &graph.marks {
        datasets.push(
            Dataset::default()
                .marker(mark.marker.unwrap_or(chart_marker))
                .graph_type(GraphType::Scatter)
                .style(mark.style)
                .data(std::slice::from_ref(&mark.at)),
        );
    }
    let axis_style = theme.style(Role::Muted);
    let title_style = theme.style(Role::Label);
    let chart = Chart::new(datasets)
        .block(block)
        .x_axis(
            Axis::default()
                .title(Span::styled(graph.x_title.clone(), title_style))
                .style(axis_style)
                .bounds(graph.x.bounds)
                .labels(graph.x.labels.clone()),
        )
        .y_axis(
            Axis::default()
                .title(Span::styled(graph.y_title.clone(), title_style))
                .style(axis_style)
                .bounds(graph.y.bounds)
                .labels(graph.y.labels.clone()),
        )
        .legend_position(None);
    frame.render_widget(chart, area);
    // Rule labels on the plot's second row (the first holds the y title), right of the line
    // where they fit, else left of it.
    let row = plot.y + 1;
    if plot.height < 3 {
        return;
    }
    for rule in &graph.rules {
        let Some(col) = column(rule.x, &graph.x, plot) else {
            continue;
        };
        let width = rule.label.chars().count() as u16;
        let x = if col + 1 + width <= plot.right() {
            col + 1
        } else if col >= plot.x + width {
            col - width
        } else {
            continue;
        };
        frame.render_widget(
            Paragraph::new(Span::styled(rule.label.clone(), rule.style)),
            Rect::new(x, row, width, 1),
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ratatui::Terminal;
    use ratatui::backend::TestBackend;
    use ratatui::widgets::Borders;

    use crate::ui::ticks::nice_axis;
    use crate::ui::units::{METRE_PER_SECOND, NEWTON};

    fn graph() -> Graph {
        Graph {
            x: nice_axis(0.0, 1.0, METRE_PER_SECOND, 3),
            y: nice_axis(0.0, 400.0, NEWTON, 3),
            x_title: "v".into(),
            y_title: "F".into(),
            traces: vec![Trace {
                points: vec![(0.0, 0.0), (1.0, 400.0)],
                style: Style::default(),
                pattern: LinePattern::Solid,
            }],
            marks: Vec::new(),
            rules: vec![Rule {
                x: 0.5,
                label: "v_y".into(),
                style: Style::default(),
                pattern: LinePattern::Solid,
            }],
        }
    }

    /// The plot area computed here is the one ratatui draws in: the y axis line is in the column
    /// left of it and the x axis line in the row below it, and the rule's label is beside it.
    #[test]
    fn the_plot_area_matches_ratatui_and_rules_are_labelled() {
        let graph = graph();
        let area = Rect::new(0, 0, 40, 12);
        let mut terminal = Terminal::new(TestBackend::new(40, 12)).unwrap();
        terminal
            .draw(|frame| {
                render(
                    frame,
                    area,
                    Block::default().borders(Borders::ALL),
                    &graph,
                    MarkerStyle::Dot,
                    Theme { color: false },
                )
            })
            .unwrap();
        let buffer = terminal.backend().buffer();
        let plot = plot_area(
            Rect::new(1, 1, 38, 10),
            &graph.y.labels,
            graph.x.labels.first().map(String::as_str),
        );
        assert_eq!(buffer[(plot.x - 1, plot.y + 2)].symbol(), "│", "y axis");
        assert_eq!(buffer[(plot.x + 3, plot.bottom())].symbol(), "─", "x axis");
        // The line from (0, 0) to (1, 400) starts at the bottom-left and ends at the top-right.
        assert_eq!(buffer[(plot.x, plot.bottom() - 1)].symbol(), "•");
        assert_eq!(buffer[(plot.right() - 1, plot.y)].symbol(), "•");
        let row: Vec<&str> = (plot.x..plot.right())
            .map(|x| buffer[(x, plot.y + 1)].symbol())
            .collect();
        let col = usize::from(column(0.5, &graph.x, plot).unwrap() - plot.x);
        assert_eq!(row[col + 1..col + 4].concat(), "v_y", "{row:?}");
    }

    #[test]
    fn values_off_the_axis_have_no_column() {
        let axis = nice_axis(0.0, 1.0, METRE_PER_SECOND, 3);
        let plot = Rect::new(10, 0, 21, 5);
        assert_eq!(column(0.0, &axis, plot), Some(10));
        assert_eq!(column(1.0, &axis, plot), Some(30));
        assert_eq!(column(1.5, &axis, plot), None);
        assert_eq!(column(f64::NAN, &axis, plot), None);
    }
}
