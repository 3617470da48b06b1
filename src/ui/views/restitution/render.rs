//! Tab 5, restitution (docs/physics.md §6.4): for the checked models, the e each realises against
//! the e it is given, with the identity line, and the e it realises against v₀ over four decades
//! with its damping coefficient held, v_y and v_p marked; `c` shows the table of realised e for
//! requested 0.1…0.9 instead.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::Line;
use ratatui::widgets::Paragraph;

use crate::chart::Chart;
use crate::format::{Zeros, significant};
use crate::model::restitution::REQUESTED;
use crate::ui::app::App;
use crate::ui::layout::{ScreenLayout, left_width};
use crate::model::study::runner::{RestitutionData, StudyKind};
use crate::ui::style::Role;
use crate::ui::widgets::common::{model_name, pane, span, titled};
use crate::ui::widgets::graph::{self, budget};
use crate::ui::widgets::models;
use crate::chart::restitution as plot;

/// Said by every chart and table of the view while `C` is on: they show each law's own damping
/// rule, which is what they are about, and not the calibration the Models pane announces.
pub const UNCALIBRATED: &str = " · own rules: C not applied";

pub fn render(frame: &mut Frame, screen: &ScreenLayout, app: &App) {
    let [left, right] = Layout::horizontal([
        Constraint::Length(left_width(screen.body)),
        Constraint::Fill(1),
    ])
    .areas(screen.body);
    models::render(frame, left, app, screen.roomy);
    let computing = app.studies.is_pending(StudyKind::Restitution);
    let data = match app.studies.restitution() {
        Some(Ok(data)) => data.clone(),
        Some(Err(e)) => return note(frame, right, app, screen.roomy, &e.to_string()),
        None => {
            let text = if computing {
                "computing…"
            } else {
                "nothing computed yet"
            };
            return note(frame, right, app, screen.roomy, text);
        }
    };
    if app.views.restitution.table {
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

fn realised_chart(
    frame: &mut Frame,
    area: Rect,
    app: &App,
    data: &RestitutionData,
    roomy: bool,
    computing: bool,
) {
    let budget = budget(area.width.saturating_sub(9), area.height.saturating_sub(6));
    let chart = plot::realised_chart(data, app.focused, budget);
    let mut title = format!("{} · = identity (e_out = e)", chart.title);
    if app.calibrate {
        title.push_str(UNCALIBRATED);
    }
    if computing {
        title.push_str(" · computing…");
    }
    draw(frame, area, app, roomy, title, &chart);
}

fn velocity_chart(frame: &mut Frame, area: Rect, app: &App, data: &RestitutionData, roomy: bool) {
    let budget = budget(area.width.saturating_sub(9), area.height.saturating_sub(6));
    let onset = app.valid.as_ref().map(|v| v.quasistatic.onset);
    let chart = plot::velocity_chart(data, app.focused, onset, budget);
    let mut title = chart.title.clone();
    if app.calibrate {
        title.push_str(UNCALIBRATED);
    }
    draw(frame, area, app, roomy, title, &chart);
}

fn draw(frame: &mut Frame, area: Rect, app: &App, roomy: bool, title: String, chart: &Chart) {
    let block = titled(&title, area, app.theme, roomy);
    graph::render_with_legend(frame, area, block, chart, (app.marker, app.theme), roomy);
}

fn table(frame: &mut Frame, area: Rect, app: &App, data: &RestitutionData, roomy: bool) {
    let theme = app.theme;
    let title = if app.calibrate {
        format!("realised e for the requested e (c: charts){UNCALIBRATED}")
    } else {
        "realised e for the requested e (c: charts)".to_string()
    };
    let block = titled(&title, area, theme, roomy);
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
