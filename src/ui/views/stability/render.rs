//! Tab 3, where fixed-step methods fail: the focused model integrated at the chosen step by every
//! fixed-step method, drawn over the reference F(x) and v(x), with each method's verdict, its
//! theoretical critical step (bound/ω_max) and its measured largest step within 1 % error.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::Modifier;
use ratatui::text::Line;
use ratatui::widgets::{Cell, Paragraph, Row, Table};

use crate::chart::{Ink, REFERENCE_GLYPH, method_glyph};
use crate::model::impact::MethodUsed;
use crate::model::ode::Method;
use crate::model::study::reference::REFERENCE_RTOL;
use crate::model::study::stability::{Verdict, stability_bound};
use crate::ui::app::{App, ChartKind, Mode};
use crate::model::study::runner::{MeasuredBound, MethodRun, StabilityData, StudyKind};
use crate::ui::style::{Role, Theme, sample};
use crate::format::units::{self, sig};
use crate::ui::views;
use crate::ui::widgets::common::{pane, span, titled};
use crate::ui::widgets::editable::{self, draw_form};
use crate::ui::widgets::graph::{self, budget};
use crate::chart::stability::{self as plot, Curve};

/// The name cell of a curve: its glyph sample and name in its ink.
fn name_cell(curve: Curve, text: &str, theme: Theme, narrow: bool) -> Cell<'static> {
    let (ink, glyph) = match curve {
        Curve::Reference => (Ink::Foreground, REFERENCE_GLYPH),
        Curve::Method(m) | Curve::Steps(m) => (Ink::Method(m), method_glyph(m)),
    };
    let style = theme.ink(ink);
    let lead = if narrow {
        glyph.to_string()
    } else {
        sample(glyph, ink.dash())
    };
    Cell::from(Line::from(vec![
        span(lead, style),
        span(format!(" {text}"), style),
    ]))
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
    if views::is_studying(app) {
        title.push_str(" · computing…");
    }
    let block = titled(&title, head, theme, roomy);
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
        Mode::Editing(e) if e.target == super::STEP_EDITOR => Some(e),
        _ => None,
    };
    let step = super::step(app);
    let value = match (step, app.views.stability.step) {
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
        // The longest wording that fits the row: a number is never cut.
        let ratio = sig(d.step_ratio, 3);
        let omega = sig(d.omega_max, 3);
        let room = usize::from(area.width).saturating_sub(first.width());
        let text = [
            format!("  ·  h·ω_max = {ratio}  with ω_max = {omega} rad/s at x_max"),
            format!("  ·  h·ω_max = {ratio}  (ω_max {omega} rad/s)"),
            format!("  ·  h·ω_max = {ratio}"),
        ]
        .into_iter()
        .find(|t| t.chars().count() <= room)
        .unwrap_or_default();
        first.spans.push(span(text, theme.style(Role::Normal)));
    }
    let hint = "  Enter types a step (2 µs, 5e-7, auto) · ← → halve / double · [ ] model";
    draw_form(frame, area, vec![first], editor, hint, cursor, theme);
}

/// A verdict in words with the headline errors against the reference, with its colour: the
/// longest of its wordings that fits `width` columns (the last one is the shortest).
fn verdict(run: &MethodRun, data: &StabilityData, width: usize) -> (String, Role) {
    let percent = |drift: f64| {
        format!(
            "{}{} %",
            if drift >= 0.0 { "+" } else { "" },
            sig(drift * 100.0, 2)
        )
    };
    let errors = plot::errors_text(run, data);
    let (mut candidates, role) = match &run.run.verdict {
        Verdict::Stable { drift } => (
            vec![
                format!("stable (energy {})", percent(*drift)),
                "stable".to_string(),
            ],
            Role::Good,
        ),
        Verdict::EnergyDrift { drift } => (
            vec![
                format!("energy drift {}", percent(*drift)),
                format!("drift {}", percent(*drift)),
            ],
            Role::Warning,
        ),
        Verdict::Diverged { t, reason } => {
            let at = units::engineering(*t, units::SECOND, 3);
            (
                vec![
                    format!("diverged at t = {at} ({reason})"),
                    format!("diverged at t = {at}"),
                    format!("diverged, t = {at}"),
                ],
                Role::Error,
            )
        }
        Verdict::Failed { reason } => (vec![format!("failed: {reason}")], Role::Error),
    };
    if let Some((full, short)) = errors {
        let with_errors: Vec<String> = candidates
            .iter()
            .flat_map(|c| [format!("{c} · {full}"), format!("{c} · {short}")])
            .collect();
        candidates = with_errors.into_iter().chain([short]).collect();
    }
    let pick = candidates
        .iter()
        .find(|c| c.chars().count() <= width)
        .or(candidates.last())
        .cloned()
        .unwrap_or_default();
    (pick, role)
}

/// The measured largest bounded step of `method`, as the table shows it (without h·ω when
/// `narrow`).
fn measured(app: &App, method: Method, narrow: bool) -> String {
    match app.studies.bounds() {
        _ if app.studies.is_pending(StudyKind::Bounds) => "measuring…".to_string(),
        Some(Ok(bounds)) => match bounds.iter().find(|b| b.bound.method == method) {
            Some(MeasuredBound {
                bound,
                step_ratio: Some(ratio),
            }) => match bound.measured_dt {
                Some(dt) if narrow => units::engineering(dt, units::SECOND, 3),
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

/// Column widths: (method, measured step) on a wide table and on a narrow one (below 120
/// columns: the glyph alone before the name, the measured step without its h·ω); the verdict
/// takes what the others leave.
const WIDE: (u16, u16) = (21, 19);
const NARROW: (u16, u16) = (18, 10);

fn table(frame: &mut Frame, area: Rect, app: &App, data: &StabilityData) {
    let theme = app.theme;
    let narrow = area.width < 118;
    let (method_width, measured_width) = if narrow { NARROW } else { WIDE };
    let verdict_width = usize::from(
        area.width
            .saturating_sub(method_width + 9 + 10 + measured_width + 4),
    );
    let header = Row::new(
        [
            "method",
            "bound h·ω",
            "critical h",
            if narrow {
                "largest h"
            } else {
                "largest h (1 % err)"
            },
            "verdict at this h",
        ]
        .map(Cell::from),
    )
    .style(theme.style(Role::Label).add_modifier(Modifier::BOLD));
    let reference = match data.reference.summary.method {
        MethodUsed::Exact => "the exact solution".to_string(),
        MethodUsed::Integrator(m) => format!("{m} at rtol {}", sig(REFERENCE_RTOL, 2)),
    };
    let mut rows = vec![Row::new(vec![
        name_cell(Curve::Reference, "reference", theme, narrow),
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
        let (text, role) = verdict(run, data, verdict_width);
        rows.push(Row::new(vec![
            name_cell(Curve::Method(method), &method.to_string(), theme, narrow),
            Cell::from(bound),
            Cell::from(critical),
            Cell::from(measured(app, method, narrow)),
            Cell::from(span(text, theme.style(role))),
        ]));
    }
    let widths = [
        Constraint::Length(method_width),
        Constraint::Length(9),
        Constraint::Length(10),
        Constraint::Length(measured_width),
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
    let columns = area.width.saturating_sub(9);
    let budget = budget(columns, area.height.saturating_sub(6));
    let chart = plot::chart(data, kind, columns, budget);
    let block = titled(&chart.title, area, theme, roomy);
    graph::render_with_legend(frame, area, block, &chart, (app.marker, theme), roomy);
}
