//! The system view on screen: the form of the system's keys and the diagram's, the notes (the
//! dimensionless groups, each stop's period or why it failed, which approach the system needs),
//! and the four charts.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::Line;
use ratatui::widgets::Paragraph;

use crate::chart::Chart;
use crate::format::verdict as words;
use crate::model::study::runner::StudyKind;
use crate::model::system::compliant::verdict::Validity;
use crate::model::system::{Contact, EndReason, SystemModel};
use crate::ui::app::{App, Mode};
use crate::ui::layout::{ScreenLayout, left_width};
use crate::ui::style::Role;
use crate::ui::widgets::common::{pane, span, wrap};
use crate::ui::widgets::editable::{self, draw_form};
use crate::ui::widgets::graph::{self, budget};

use super::settings::{NO_SYSTEM, Row, SYSTEM_PRESETS, Settings, TOML_SNIPPET};

/// Width of the label column of the form.
const LABEL_WIDTH: usize = 13;

pub fn render(frame: &mut Frame, screen: &ScreenLayout, app: &App) {
    let [left, right] = Layout::horizontal([
        Constraint::Length(left_width(screen.body)),
        Constraint::Fill(1),
    ])
    .areas(screen.body);
    let model = super::model(app);
    let rows = model.as_ref().map(Settings::rows).unwrap_or_default();
    let frame_rows = if screen.roomy { 2 } else { 1 };
    let form_rows = match app.draft.system {
        Some(_) => rows.len(),
        None => SYSTEM_PRESETS.len(),
    };
    let [form_area, notes_area] = Layout::vertical([
        Constraint::Length(form_rows as u16 + 1 + frame_rows),
        Constraint::Fill(1),
    ])
    .areas(left);
    match &model {
        Ok(model) => form(frame, form_area, app, model, &rows, screen.roomy),
        Err(_) if app.draft.system.is_none() => add_form(frame, form_area, app, screen.roomy),
        Err(_) => {}
    }
    notes(frame, notes_area, app, model.as_ref(), screen.roomy);
    charts(frame, right, app, model.as_ref().ok(), screen.roomy);
}

fn form(frame: &mut Frame, area: Rect, app: &App, model: &SystemModel, rows: &[Row], roomy: bool) {
    let theme = app.theme;
    let block = pane(format!("System · {}", model.spec.kind_name()), theme, roomy);
    let inner = block.inner(area);
    frame.render_widget(block, area);
    let editor = match &app.mode {
        Mode::Editing(e) => Some(e),
        _ => None,
    };
    let settings = &app.views.system.settings;
    let cursor_at = app.views.system.cursor.min(rows.len().saturating_sub(1));
    let mut lines = Vec::new();
    let mut cursor = None;
    for (i, &row) in rows.iter().enumerate() {
        let label = row.label();
        let (line, position) = editable::line(
            editable::Row {
                x: inner.x,
                y: inner.y + i as u16,
                width: inner.width,
                label: &label,
                label_width: LABEL_WIDTH,
                value: settings.show(row, model),
                editor: editor.filter(|e| e.target == crate::ui::app::EditTarget::Row(i)),
                under_cursor: cursor_at == i && editor.is_none(),
            },
            theme,
        );
        lines.push(line);
        cursor = cursor.or(position);
    }
    let hint = match rows.get(cursor_at) {
        Some(Row::DiagramKey) => "  ← → any key of the system",
        Some(Row::Values) => "  Enter types · ← → ½× 2×",
        _ => "  Enter types it (0.5 mm) · ← → 5 %",
    };
    draw_form(frame, inner, lines, editor, hint, cursor, theme);
}

/// On a scene without `[system]`: the system presets whose table Enter adds.
fn add_form(frame: &mut Frame, area: Rect, app: &App, roomy: bool) {
    let theme = app.theme;
    let block = pane("Add a system", theme, roomy);
    let inner = block.inner(area);
    frame.render_widget(block, area);
    let cursor_at = app.views.system.cursor.min(SYSTEM_PRESETS.len() - 1);
    let mut lines: Vec<Line> = SYSTEM_PRESETS
        .iter()
        .enumerate()
        .map(|(i, name)| {
            let line = Line::from(span(format!(" {name}"), theme.style(Role::Normal)));
            if i == cursor_at {
                line.patch_style(theme.style(Role::Cursor))
            } else {
                line
            }
        })
        .collect();
    lines.push(Line::from(span(
        "  Enter adds its [system] table",
        theme.style(Role::Muted),
    )));
    frame.render_widget(Paragraph::new(lines), inner);
}

/// `rigid` or the law's name.
fn contact_name(contact: &Contact) -> String {
    match contact {
        Contact::Rigid { restitution } => format!("rigid (e = {restitution})"),
        Contact::Compliant { model, .. } => model.name().to_string(),
    }
}

/// What the notes say, each with its role.
pub fn note_texts(app: &App, model: Result<&SystemModel, &String>) -> Vec<(String, Role)> {
    let mut texts: Vec<(String, Role)> = Vec::new();
    if let Some(error) = &app.scene_error {
        texts.push((format!("✗ {error}"), Role::Error));
    }
    let model = match model {
        Ok(model) => model,
        Err(_) if app.draft.system.is_none() => {
            texts.extend(how_to_add_a_system());
            return texts;
        }
        Err(reason) => {
            texts.push((reason.clone(), Role::Error));
            return texts;
        }
    };
    let g = model.spec.groups(model.mass);
    let n = |v: f64| crate::format::units::sig(v, 4);
    let mut groups = Vec::new();
    if let Some(v) = g.gamma {
        groups.push(format!("Γ = Aω²/g = {}", n(v)));
    }
    if let Some(v) = g.frequency_ratio {
        groups.push(format!("ω/ω₀ = {}", n(v)));
    }
    if let Some(v) = g.damping_ratio {
        groups.push(format!("ζ = {}", n(v)));
    }
    if let Some(v) = g.gap_ratio {
        groups.push(format!("gap = {} δ_st", n(v)));
    }
    if let Some(v) = g.second_gap_ratio {
        groups.push(format!("gap₂ = {} δ_st", n(v)));
    }
    texts.push((groups.join(" · "), Role::Normal));
    let period = model.spec.period();
    if let Some(runs) = app.studies.system() {
        for (contact, result) in &runs.runs {
            let name = contact_name(contact);
            match result {
                Ok(h) => {
                    let words = match (h.period(period), h.end) {
                        (_, EndReason::StuckForever) => "sticks to the stop".to_string(),
                        (Some((i, m)), _) => format!("period-{m}, {i} impact(s) a period"),
                        (None, EndReason::TimeLimit) => "no impact for long".to_string(),
                        (None, _) => "not periodic (chaos?)".to_string(),
                    };
                    let contact_time = h
                        .impacts
                        .iter()
                        .filter_map(|i| i.contact_time)
                        .fold(None, |m: Option<f64>, t| Some(m.map_or(t, |m| m.max(t))));
                    let ratio = contact_time
                        .map(|t| format!(", contact ≤ {} % of a period", n(100.0 * t / period)))
                        .unwrap_or_default();
                    texts.push((format!("{name}: {words}{ratio}"), Role::Normal));
                }
                Err(e) => texts.push((format!("✗ {name}: {e}"), Role::Error)),
            }
        }
        match &runs.verdict {
            Some(Ok(v)) => {
                let role = match v.validity {
                    Validity::Valid => Role::Normal,
                    Validity::Marginal | Validity::NotValid => Role::Warning,
                };
                texts.push((
                    format!("{}: {}", words::gist(v), words::sentence(v)),
                    role,
                ));
            }
            Some(Err(e)) => texts.push((format!("✗ verdict: {e}"), Role::Error)),
            None => {}
        }
    }
    texts.extend(super::branch::notes(app));
    if let Some(d) = app.studies.diagram() {
        for b in &d.branches {
            if let Some(e) = &b.error {
                texts.push((format!("✗ diagram, {}: {e}", contact_name(&b.contact)), Role::Error));
            }
        }
    }
    texts
}

/// What a scene without `[system]` shows instead of a run: how to add one, here or in its file.
fn how_to_add_a_system() -> Vec<(String, Role)> {
    let mut texts = vec![
        (format!("{NO_SYSTEM}: nothing to run."), Role::Warning),
        (
            "Enter adds the chosen preset's table to this scene, its bodies as the body and \
             the stop (u undoes, s saves); p opens a preset."
                .to_string(),
            Role::Normal,
        ),
        (
            "Or add to the scene file, then hertz-tui --scene FILE:".to_string(),
            Role::Normal,
        ),
    ];
    texts.extend(TOML_SNIPPET.lines().map(|line| (line.to_string(), Role::Label)));
    texts.push((
        "Keys of each kind: docs/systems.md".to_string(),
        Role::Muted,
    ));
    texts
}

fn notes(frame: &mut Frame, area: Rect, app: &App, model: Result<&SystemModel, &String>, roomy: bool) {
    let theme = app.theme;
    let block = pane("Which approach", theme, roomy);
    let inner = block.inner(area);
    frame.render_widget(block, area);
    let width = usize::from(inner.width.saturating_sub(1));
    let mut lines = Vec::new();
    for (text, role) in note_texts(app, model) {
        lines.extend(
            wrap(&text, width)
                .into_iter()
                .map(|l| Line::from(span(format!(" {l}"), theme.style(role)))),
        );
    }
    lines.truncate(usize::from(inner.height));
    frame.render_widget(Paragraph::new(lines), inner);
}

/// A pane with a chart, or what it waits for.
fn chart_pane(frame: &mut Frame, area: Rect, app: &App, chart: Option<Chart>, empty: &str, computing: bool, roomy: bool) {
    let theme = app.theme;
    let Some(chart) = chart else {
        let block = pane("", theme, roomy);
        let inner = block.inner(area);
        frame.render_widget(block, area);
        let text = if computing { "computing…" } else { empty };
        frame.render_widget(Paragraph::new(span(text, theme.style(Role::Muted))), inner);
        return;
    };
    let mut title = chart.title.clone();
    if computing {
        title.push_str(" · computing…");
    }
    let block = pane(title, theme, roomy);
    graph::render_with_legend(frame, area, block, &chart, (app.marker, theme), roomy);
}

fn charts(frame: &mut Frame, area: Rect, app: &App, model: Option<&SystemModel>, roomy: bool) {
    let [top, bottom] = Layout::vertical([Constraint::Fill(1), Constraint::Fill(1)]).areas(area);
    let [history, phase] = Layout::horizontal([Constraint::Fill(1), Constraint::Fill(1)]).areas(top);
    let [map, diagram] = Layout::horizontal([Constraint::Fill(1), Constraint::Fill(1)]).areas(bottom);
    let areas = [history, phase, map];
    let running = app.studies.is_pending(StudyKind::System);
    let mut motion = match model {
        Some(model) => {
            let b = budget(history.width.saturating_sub(9), history.height.saturating_sub(6));
            super::motion_charts(app.studies.system().map(|r| &**r), model, b)
        }
        None => Vec::new(),
    }
    .into_iter();
    let empty = match app.draft.system {
        Some(_) => "no run yet",
        None => "no system",
    };
    for area in areas {
        chart_pane(frame, area, app, motion.next(), empty, running, roomy);
    }
    let continuing =
        app.views.system.branch && app.studies.is_pending(StudyKind::Continuation);
    let filling = app.studies.is_pending(StudyKind::Diagram) || continuing;
    let chart = model.and_then(|model| {
        let b = budget(diagram.width.saturating_sub(9), diagram.height.saturating_sub(6));
        app.studies.diagram().map(|d| {
            let mut chart = match super::branch::shown(app, d) {
                Some(branches) => super::branch::chart(
                    d,
                    branches,
                    model,
                    b,
                    super::branch::TERMINAL_THINNING,
                ),
                None => super::diagram_chart(d, model, b),
            };
            let done = d.branches.iter().map(|b| b.columns.len()).sum::<usize>();
            let all = d.values.len() * d.branches.len();
            if done < all {
                chart.title = format!("{} · {done}/{all}", chart.title);
            }
            chart
        })
    });
    chart_pane(frame, diagram, app, chart, "no diagram yet", filling, roomy);
}
