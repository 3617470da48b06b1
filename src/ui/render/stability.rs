//! Tab 3, where fixed-step methods fail: the focused model integrated at the chosen step by every
//! fixed-step method, drawn over the reference F(x) and v(x), with each method's verdict, its
//! theoretical critical step (bound/ω_max) and its measured largest step within 1 % error.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::Modifier;
use ratatui::text::Line;
use ratatui::widgets::{Cell, Paragraph, Row, Table};

use crate::model::impact::MethodUsed;
use crate::model::ode::Method;
use crate::model::study::reference::REFERENCE_RTOL;
use crate::model::study::stability::{Verdict, stability_bound};
use crate::ui::app::{App, ChartKind, EditTarget, Mode};
use crate::ui::plot::{Series, plot};
use crate::ui::studies::{MeasuredBound, StabilityData, StudyKind};
use crate::ui::theme::{LinePattern, Role, Theme};
use crate::ui::units::{self, sig};

use super::common::{pane, span, wrap};
use super::editable;
use super::graph::{self, Graph, Mark, Trace};

/// Whose curve: the reference or a fixed-step method.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Curve {
    Reference,
    Method(Method),
}

fn curve_style(curve: Curve, theme: Theme) -> (ratatui::style::Style, LinePattern) {
    match curve {
        Curve::Reference => (theme.style(Role::Normal), LinePattern::Solid),
        Curve::Method(m) => (theme.method_style(m), LinePattern::of_method(m)),
    }
}

pub fn render(frame: &mut Frame, area: Rect, app: &App, roomy: bool) {
    let theme = app.theme;
    let data = match app.studies.runs() {
        Some(Ok(data)) => Some(data.clone()),
        _ => None,
    };
    let frame_rows = if roomy { 2 } else { 1 };
    let [head, table_area, charts] = Layout::vertical([
        Constraint::Length(2 + frame_rows),
        Constraint::Length(6 + frame_rows),
        Constraint::Fill(1),
    ])
    .areas(area);
    let mut title = format!(
        "Stability · {} · fixed steps over the reference",
        data.as_ref().map_or(app.focused, |d| d.model).label()
    );
    if app.is_studying() {
        title.push_str(" · computing…");
    }
    let block = pane(title, theme, roomy);
    let inner = block.inner(head);
    frame.render_widget(block, head);
    header(frame, inner, app, data.as_deref());
    let block = pane("Methods at this step", theme, roomy);
    let inner = block.inner(table_area);
    frame.render_widget(block, table_area);
    let Some(data) = data else {
        let text = match app.studies.runs() {
            Some(Err(message)) => format!("✗ {message}"),
            _ if app.studies.is_pending(StudyKind::Runs) => "computing…".to_string(),
            _ => "no valid scene to integrate".to_string(),
        };
        frame.render_widget(Paragraph::new(span(text, theme.style(Role::Muted))), inner);
        return;
    };
    table(frame, inner, app, &data);
    let [left, right] = Layout::horizontal([Constraint::Fill(1); 2]).areas(charts);
    for (kind, rect) in [
        (ChartKind::ForceDisplacement, left),
        (ChartKind::VelocityDisplacement, right),
    ] {
        chart(frame, rect, app, &data, kind, roomy);
    }
}

/// The step (editable), how it compares with the stiffest point of the impact, and the keys.
fn header(frame: &mut Frame, area: Rect, app: &App, data: Option<&StabilityData>) {
    let theme = app.theme;
    let editor = match &app.mode {
        Mode::Editing(e) if e.target == EditTarget::Step => Some(e),
        _ => None,
    };
    let step = app.stability_step();
    let value = match (step, app.step) {
        (Some(dt), None) => format!(
            "{} (auto: the rk4 critical step)",
            units::engineering(dt, units::SECOND, 4)
        ),
        (Some(dt), Some(_)) => units::engineering(dt, units::SECOND, 4),
        (None, _) => "— (no valid scene)".to_string(),
    };
    let (mut first, cursor) = editable::line(
        editable::Row {
            x: area.x,
            y: area.y,
            width: area.width,
            label: "step h",
            label_width: 8,
            value,
            editor,
            under_cursor: false,
        },
        theme,
    );
    if let Some(d) = data.filter(|_| editor.is_none()) {
        first.spans.push(span(
            format!(
                "  ·  h·ω_max = {}  with ω_max = {} rad/s at x_max",
                sig(d.step_ratio, 3),
                sig(d.omega_max, 3)
            ),
            theme.style(Role::Normal),
        ));
    }
    let second = match editor.and_then(|e| e.error.as_ref()) {
        Some(error) => Line::from(span(format!("  ✗ {error}"), theme.style(Role::Error))),
        None => Line::from(span(
            "  Enter types a step (2 µs, 5e-7, auto) · ← → halve / double · [ ] model",
            theme.style(Role::Muted),
        )),
    };
    frame.render_widget(Paragraph::new(vec![first, second]), area);
    if let Some(position) = cursor {
        frame.set_cursor_position(position);
    }
}

/// A verdict in words, with its colour, in `width` columns where the details allow.
fn verdict(v: &Verdict, width: usize) -> (String, Role) {
    let percent = |drift: f64| {
        format!(
            "{}{} %",
            if drift >= 0.0 { "+" } else { "" },
            sig(drift * 100.0, 2)
        )
    };
    match v {
        Verdict::Stable { drift } => (format!("stable (energy {})", percent(*drift)), Role::Good),
        Verdict::EnergyDrift { drift } => {
            (format!("energy drift {}", percent(*drift)), Role::Warning)
        }
        Verdict::Diverged { t, reason } => {
            let at = format!(
                "diverged at t = {}",
                units::engineering(*t, units::SECOND, 3)
            );
            let full = format!("{at} ({reason})");
            (
                if full.chars().count() <= width {
                    full
                } else {
                    at
                },
                Role::Error,
            )
        }
        Verdict::Failed { reason } => (format!("failed: {reason}"), Role::Error),
    }
}

/// The measured largest bounded step of `method`, as the table shows it.
fn measured(app: &App, method: Method) -> String {
    match app.studies.bounds() {
        _ if app.studies.is_pending(StudyKind::Bounds) => "measuring…".to_string(),
        Some(Ok(bounds)) => match bounds.iter().find(|b| b.bound.method == method) {
            Some(MeasuredBound {
                bound,
                step_ratio: Some(ratio),
            }) => match bound.measured_dt {
                Some(dt) => format!(
                    "{} (h·ω {})",
                    units::engineering(dt, units::SECOND, 3),
                    sig(*ratio, 3)
                ),
                None => "none found".to_string(),
            },
            _ => "none found".to_string(),
        },
        Some(Err(message)) => format!("✗ {message}"),
        None => "—".to_string(),
    }
}

/// Widths of the method and measured-step columns (the measured step stands next to the
/// theory's); the verdict takes what the others leave.
const METHOD_WIDTH: u16 = 21;
const MEASURED_WIDTH: u16 = 19;

fn table(frame: &mut Frame, area: Rect, app: &App, data: &StabilityData) {
    let theme = app.theme;
    let verdict_width = usize::from(
        area.width
            .saturating_sub(METHOD_WIDTH + 9 + 10 + MEASURED_WIDTH + 4),
    );
    let header = Row::new(
        [
            "method",
            "bound h·ω",
            "critical h",
            "largest h (1 % err)",
            "verdict at this h",
        ]
        .map(Cell::from),
    )
    .style(theme.style(Role::Label).add_modifier(Modifier::BOLD));
    let name = |curve: Curve, text: String| {
        let (style, pattern) = curve_style(curve, theme);
        Cell::from(Line::from(vec![
            span(pattern.sample(), style),
            span(format!(" {text}"), style),
        ]))
    };
    let reference = match data.reference.summary.method {
        MethodUsed::Exact => "the exact solution".to_string(),
        MethodUsed::Integrator(m) => format!("{m} at rtol {}", sig(REFERENCE_RTOL, 2)),
    };
    let mut rows = vec![Row::new(vec![
        name(Curve::Reference, "reference".into()),
        Cell::from(""),
        Cell::from(""),
        Cell::from(""),
        Cell::from(span(reference, theme.style(Role::Muted))),
    ])];
    for run in &data.runs {
        let method = run.run.method;
        let bound = match stability_bound(method) {
            Some(b) => format!("< {}", sig(b, 3)),
            None => "none".to_string(),
        };
        let critical = match run.critical_dt {
            Some(dt) => units::engineering(dt, units::SECOND, 3),
            None => "— (gains)".to_string(),
        };
        let (text, role) = verdict(&run.run.verdict, verdict_width);
        rows.push(Row::new(vec![
            name(Curve::Method(method), method.to_string()),
            Cell::from(bound),
            Cell::from(critical),
            Cell::from(measured(app, method)),
            Cell::from(span(text, theme.style(role))),
        ]));
    }
    let widths = [
        Constraint::Length(METHOD_WIDTH),
        Constraint::Length(9),
        Constraint::Length(10),
        Constraint::Length(MEASURED_WIDTH),
        Constraint::Fill(1),
    ];
    frame.render_widget(
        Table::new(rows, widths).header(header).column_spacing(1),
        area,
    );
}

fn chart(
    frame: &mut Frame,
    area: Rect,
    app: &App,
    data: &StabilityData,
    kind: ChartKind,
    roomy: bool,
) {
    let theme = app.theme;
    let dots = usize::from(app.marker.dots_per_cell());
    // About two samples per plot column.
    let n = 2 * usize::from(area.width) * dots;
    let mut series = vec![Series::sample(Curve::Reference, &data.reference, n)];
    series.extend(data.runs.iter().filter_map(|r| {
        let solution = r.run.solution.as_ref()?;
        Some(Series::sample(Curve::Method(r.run.method), solution, n))
    }));
    let max_x_labels = usize::from(area.width / 8).clamp(2, 10);
    let max_y_labels = usize::from(area.height / 3).clamp(2, 8);
    let p = plot(kind, &series, max_x_labels, max_y_labels);
    let mut traces = Vec::new();
    let mut marks = Vec::new();
    // The reference first, so the methods lie over it.
    for c in p.curves {
        let (style, pattern) = curve_style(c.model, theme);
        marks.push(Mark {
            at: c.peak,
            style,
            marker: None,
        });
        traces.push(Trace {
            points: c.points,
            style,
            pattern,
        });
    }
    let drawn = data
        .runs
        .iter()
        .filter(|r| r.run.solution.is_some())
        .count();
    let mut title = format!(
        "{} · {drawn} of {} methods drawn",
        kind.title(),
        data.runs.len()
    );
    if area.width < 60 {
        title = wrap(&title, usize::from(area.width.saturating_sub(2)))
            .into_iter()
            .next()
            .unwrap_or_default();
    }
    let g = Graph {
        x: p.x,
        y: p.y,
        x_title: p.x_title,
        y_title: p.y_title,
        traces,
        marks,
        rules: Vec::new(),
    };
    graph::render(
        frame,
        area,
        pane(title, theme, roomy),
        &g,
        app.marker,
        theme,
    );
}
