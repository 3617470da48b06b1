//! Tab 2, the work-precision diagram of the focused model: log₁₀ error against log₁₀ seconds per
//! solve and against log₁₀ force evaluations, one line per method, the explorer's own solve marked,
//! failed rungs listed under the charts.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::Modifier;
use ratatui::text::{Line, Span};
use ratatui::widgets::Paragraph;

use crate::chart::{Ink, method_glyph};
use crate::model::impact::{MethodChoice, MethodUsed};
use crate::model::study::reference::REFERENCE_RTOL;
use crate::model::study::stability::FIXED_STEP_METHODS;
use crate::ui::app::App;
use crate::model::study::runner::{CurrentPoint, WorkPrecisionData};
use crate::ui::style::{Role, Theme, sample};
use crate::format::units::{self, sig};
use crate::ui::views;
use crate::ui::widgets::common::{flow, span, titled, wrap};
use crate::ui::widgets::graph::{self, budget};
use crate::chart::work_precision::{self as plot, CURRENT_GLYPH, Cost, ERROR_FLOOR};

pub fn render(frame: &mut Frame, area: Rect, app: &App, roomy: bool) {
    let theme = app.theme;
    let computing = views::is_studying(app);
    let data = match app.studies.work_precision() {
        Some(Ok(data)) => data.clone(),
        other => {
            let text = match other {
                Some(Err(message)) => format!("✗ no reference for this model: {message}"),
                _ if computing => "computing… (every method over its ladder of tolerances \
                                   and steps)"
                    .to_string(),
                _ => "no valid scene to measure".to_string(),
            };
            let block = titled(&title(app, None), area, theme, roomy);
            let inner = block.inner(area);
            frame.render_widget(block, area);
            let lines: Vec<Line> = wrap(&text, usize::from(inner.width))
                .into_iter()
                .map(|l| Line::from(span(l, theme.style(Role::Muted))))
                .collect();
            frame.render_widget(Paragraph::new(lines), inner);
            return;
        }
    };
    let current = match app.studies.current() {
        Some(Ok(point)) => Some(point),
        _ => None,
    };
    let width = usize::from(area.width.saturating_sub(2));
    let header = header_lines(app, &data, current, width);
    let legend = legend(&data, current.is_some(), theme, width);
    let notes = notes(&data, app, width, if roomy { 3 } else { 2 });
    let frame_rows = if roomy { 2 } else { 1 };
    let [head, charts, legend_area, notes_area] = Layout::vertical([
        Constraint::Length(header.len() as u16 + frame_rows),
        Constraint::Fill(1),
        Constraint::Length(legend.len() as u16),
        Constraint::Length(notes.len() as u16),
    ])
    .areas(area);
    let block = titled(&title(app, Some(&data)), head, theme, roomy);
    let inner = block.inner(head);
    frame.render_widget(block, head);
    frame.render_widget(Paragraph::new(header), inner);
    // Both charts side by side or stacked where they fit, else the one `c` picks.
    let shown: Vec<(Cost, Rect)> = if area.width >= 120 {
        let [a, b] = Layout::horizontal([Constraint::Fill(1); 2]).areas(charts);
        vec![(Cost::Seconds, a), (Cost::ForceEvals, b)]
    } else if charts.height >= 30 {
        let [a, b] = Layout::vertical([Constraint::Fill(1); 2]).areas(charts);
        vec![(Cost::Seconds, a), (Cost::ForceEvals, b)]
    } else {
        vec![(app.views.work_precision.cost, charts)]
    };
    let single = shown.len() == 1;
    for (cost, rect) in shown {
        let budget = budget(rect.width.saturating_sub(9), rect.height.saturating_sub(6));
        let chart = plot::chart(&data, current, cost, budget);
        let mut heading = chart.title.clone();
        if single {
            heading.push_str(" · c: the other chart");
        }
        graph::render(
            frame,
            rect,
            titled(&heading, rect, theme, roomy),
            &chart,
            app.marker,
            theme,
        );
    }
    frame.render_widget(Paragraph::new(legend), legend_area);
    frame.render_widget(Paragraph::new(notes), notes_area);
}

fn title(app: &App, data: Option<&WorkPrecisionData>) -> String {
    let model = data.map_or(app.focused, |d| d.model);
    let mut title = format!("Work–precision · {}", model.label());
    if views::is_studying(app) {
        title.push_str(" · computing…");
    }
    title
}

/// The reference and what "error" means; then the explorer's solve.
fn header_lines(
    app: &App,
    data: &WorkPrecisionData,
    current: Option<&CurrentPoint>,
    width: usize,
) -> Vec<Line<'static>> {
    let theme = app.theme;
    let reference = match data.reference.method {
        MethodUsed::Exact => "the exact solution".to_string(),
        MethodUsed::Integrator(m) => format!("{m} at rtol {}", sig(REFERENCE_RTOL, 2)),
    };
    let mut lines: Vec<Line> = wrap(
        &format!(
            "error: the worst relative error of x_max, F_max, t_c and v_out against {reference}; \
             [ ] changes the model"
        ),
        width,
    )
    .into_iter()
    .map(|l| Line::from(span(l, theme.style(Role::Muted))))
    .collect();
    let Some(point) = current else {
        return lines;
    };
    let choice = match (point.options.method, point.method) {
        (MethodChoice::Auto, used) => format!("auto → {used}"),
        (MethodChoice::Integrator(m), _) => m.to_string(),
    };
    let setting = match point.method {
        MethodUsed::Integrator(m) if !m.is_adaptive() => match point.options.dt {
            Some(dt) => format!("h {}", units::engineering(dt, units::SECOND, 3)),
            None => "default step".to_string(),
        },
        MethodUsed::Exact => "closed form".to_string(),
        MethodUsed::Integrator(_) => format!("rtol {}", sig(point.options.rtol, 2)),
    };
    let text = format!(
        "explorer's solve: {choice}, {setting} · error {} · {} force evaluations · {} per solve",
        sig(point.errors.worst(), 2),
        point.force_evals,
        units::engineering(point.seconds_per_solve, units::SECOND, 2),
    );
    let mut first = true;
    for l in wrap(&text, width.saturating_sub(2)) {
        let lead = if first { "█ " } else { "  " };
        first = false;
        lines.push(Line::from(vec![
            span(lead, current_style(theme)),
            span(l, theme.style(Role::Normal)),
        ]));
    }
    lines
}

/// The style of the explorer's solve on the charts and in the legend.
fn current_style(theme: Theme) -> ratatui::style::Style {
    theme.ink(Ink::Foreground).add_modifier(Modifier::BOLD)
}

/// Line sample and name of every drawn method, then the explorer's mark.
fn legend(
    data: &WorkPrecisionData,
    with_current: bool,
    theme: Theme,
    width: usize,
) -> Vec<Line<'static>> {
    let mut items: Vec<Vec<Span>> = plot::lines(data, Cost::ForceEvals)
        .iter()
        .map(|l| {
            let style = theme.method_style(l.method);
            vec![
                span(sample(method_glyph(l.method), Ink::Method(l.method).dash()), style),
                span(format!(" {}", l.method), style),
            ]
        })
        .collect();
    if with_current {
        items.push(vec![
            span(CURRENT_GLYPH.to_string(), current_style(theme)),
            span(" explorer's solve", theme.style(Role::Normal)),
        ]);
    }
    flow(items, width, 2, Span::raw("   "))
}

/// What is not drawn: failed rungs, methods without a bounded step, errors at the floor.
fn notes(
    data: &WorkPrecisionData,
    app: &App,
    width: usize,
    max_lines: usize,
) -> Vec<Line<'static>> {
    let theme = app.theme;
    let mut items: Vec<String> = plot::failures(data);
    items.extend(
        plot::unmeasured(data, &FIXED_STEP_METHODS)
            .into_iter()
            .map(|m| format!("{m}: no bounded step found, no rungs")),
    );
    let mut lines = Vec::new();
    if !items.is_empty() {
        let text = format!("not plotted ({}): {}", items.len(), items.join("; "));
        let mut wrapped = wrap(&text, width);
        if wrapped.len() > max_lines {
            wrapped.truncate(max_lines);
            if let Some(last) = wrapped.last_mut() {
                let keep = width.saturating_sub(1);
                *last = last.chars().take(keep).collect::<String>() + "…";
            }
        }
        lines.extend(
            wrapped
                .into_iter()
                .map(|l| Line::from(span(l, theme.style(Role::Warning)))),
        );
    }
    if lines.len() < max_lines && plot::any_floored(data) {
        lines.push(Line::from(span(
            format!(
                "errors below {} are drawn at log₁₀ = {}",
                sig(ERROR_FLOOR, 1),
                ERROR_FLOOR.log10()
            ),
            theme.style(Role::Muted),
        )));
    }
    lines
}
