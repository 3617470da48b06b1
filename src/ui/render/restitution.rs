//! Tab 5, restitution (docs/physics.md §6.4): for the checked models, the e each realises against
//! the e it is given, with the identity line, and the e it realises against v₀ over four decades
//! with its damping coefficient held, v_y and v_p marked; `c` shows the table of realised e for
//! requested 0.1…0.9 instead.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::Line;
use ratatui::widgets::Paragraph;

use crate::format::{Zeros, significant};
use crate::model::ForceModel;
use crate::model::restitution::REQUESTED;
use crate::ui::app::App;
use crate::ui::studies::{RestitutionData, StudyKind};
use crate::ui::theme::{LinePattern, Role};
use crate::ui::ticks::{log_axis, nice_axis};
use crate::ui::units::{DIMENSIONLESS, METRE_PER_SECOND};

use super::common::{model_name, pane, span};
use super::graph::{self, Graph, Rule, Trace};
use super::layout::{Screen, left_width};
use super::models;

pub fn render(frame: &mut Frame, screen: &Screen, app: &App) {
    let [left, right] = Layout::horizontal([
        Constraint::Length(left_width(screen.body)),
        Constraint::Fill(1),
    ])
    .areas(screen.body);
    models::render(frame, left, app, screen.roomy);
    let computing = app.studies.is_pending(StudyKind::Restitution);
    let data = match app.studies.restitution() {
        Some(Ok(data)) => data.clone(),
        Some(Err(e)) => return note(frame, right, app, screen.roomy, e),
        None => {
            let text = if computing {
                "computing…"
            } else {
                "nothing computed yet"
            };
            return note(frame, right, app, screen.roomy, text);
        }
    };
    if app.restitution_table {
        table(frame, right, app, &data, screen.roomy);
    } else {
        let [top, bottom] =
            Layout::vertical([Constraint::Fill(1), Constraint::Fill(1)]).areas(right);
        realised_chart(frame, top, app, &data, screen.roomy, computing);
        velocity_chart(frame, bottom, app, &data, screen.roomy);
    }
}

fn note(frame: &mut Frame, area: Rect, app: &App, roomy: bool, text: &str) {
    let block = pane("Restitution", app.theme, roomy);
    let inner = block.inner(area);
    frame.render_widget(block, area);
    frame.render_widget(
        Paragraph::new(span(text.to_string(), app.theme.style(Role::Muted))),
        inner,
    );
}

/// One trace per model, in its colour and pattern.
fn traces(
    app: &App,
    curves: &[(ForceModel, Vec<(f64, f64)>)],
    x: impl Fn(f64) -> f64,
) -> Vec<Trace> {
    curves
        .iter()
        .map(|(model, points)| Trace {
            points: points.iter().map(|&(px, py)| (x(px), py)).collect(),
            style: app.theme.model_style(*model),
            pattern: LinePattern::of(*model),
        })
        .collect()
}

fn realised_chart(
    frame: &mut Frame,
    area: Rect,
    app: &App,
    data: &RestitutionData,
    roomy: bool,
    computing: bool,
) {
    let labels = usize::from(area.width / 9).clamp(2, 11);
    let axis = nice_axis(0.0, 1.0, DIMENSIONLESS, labels.min(6));
    let mut lines = vec![Trace {
        points: vec![(0.0, 0.0), (1.0, 1.0)],
        style: app.theme.style(Role::Muted),
        pattern: LinePattern::Dotted,
    }];
    lines.extend(traces(app, &data.realised, |e| e));
    let mut title = "realised e against requested e · ··· identity (e_out = e)".to_string();
    if computing {
        title.push_str(" · computing…");
    }
    let g = Graph {
        x: axis.clone(),
        y: axis,
        x_title: "e requested".into(),
        y_title: "e_out".into(),
        traces: lines,
        marks: Vec::new(),
        rules: Vec::new(),
    };
    draw(frame, area, app, roomy, &title, &g);
}

fn velocity_chart(frame: &mut Frame, area: Rect, app: &App, data: &RestitutionData, roomy: bool) {
    let labels = usize::from(area.width / 9).clamp(2, 11);
    let x = log_axis(data.v0 / 100.0, data.v0 * 100.0, METRE_PER_SECOND, labels);
    let y = nice_axis(
        0.0,
        1.0,
        DIMENSIONLESS,
        usize::from(area.height / 3).clamp(2, 6),
    );
    let lines = traces(app, &data.velocity, |v| x.to_display(v));
    let mut rules = Vec::new();
    if let Some(valid) = &app.valid {
        let onset = valid.quasistatic.onset;
        for (v, label, role, pattern) in [
            (onset.v_yield, "v_y", Role::Warning, LinePattern::Dotted),
            (onset.v_plastic, "v_p", Role::Error, LinePattern::Dashed),
        ] {
            let at = x.to_display(v);
            if at.is_finite() && at >= x.bounds[0] && at <= x.bounds[1] {
                rules.push(Rule {
                    x: at,
                    label: label.into(),
                    style: app.theme.style(role),
                    pattern,
                });
            }
        }
    }
    let unit = format!("{}{}", x.prefix.symbol, METRE_PER_SECOND.symbol);
    let g = Graph {
        x_title: format!("v₀ [{unit}]"),
        y_title: "e_out".into(),
        x,
        y,
        traces: lines,
        marks: Vec::new(),
        rules,
    };
    let title = "e_out against v₀, damping coefficient held (α for Hunt–Crossley)";
    draw(frame, area, app, roomy, title, &g);
}

fn draw(frame: &mut Frame, area: Rect, app: &App, roomy: bool, title: &str, g: &Graph) {
    let block = pane(title.to_string(), app.theme, roomy);
    graph::render(frame, area, block, g, app.marker, app.theme);
}

fn table(frame: &mut Frame, area: Rect, app: &App, data: &RestitutionData, roomy: bool) {
    let theme = app.theme;
    let block = pane("realised e for the requested e (c: charts)", theme, roomy);
    let inner = block.inner(area);
    frame.render_widget(block, area);
    let name_width = 20;
    let mut header = format!("{:<name_width$}", "model");
    for e in REQUESTED {
        header.push_str(&format!("{:>9}", format!("e = {e}")));
    }
    let mut lines = vec![Line::from(span(header, theme.style(Role::Label)))];
    for row in &data.table {
        let mut text = format!("{:<name_width$}", model_name(row.model, name_width - 1));
        for p in &row.points {
            let cell = p
                .e_out
                .map_or("failed".to_string(), |e| significant(e, 4, Zeros::Keep));
            text.push_str(&format!("{cell:>9}"));
        }
        lines.push(Line::from(span(text, theme.model_style(row.model))));
    }
    frame.render_widget(Paragraph::new(lines), inner);
}
