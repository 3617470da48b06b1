//! Tab 4, a sweep: the chosen output against the chosen scene parameter for the checked models
//! (or the quasistatic estimate), with the yield-onset velocities marked when v₀ is swept.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::Paragraph;

use crate::model::Scene;
use crate::model::scene_key::SceneKey;
use crate::ui::app::{App, Mode};
use crate::ui::layout::ScreenLayout;
use crate::model::study::runner::{StudyKind, SweepData};
use crate::ui::style::Role;
use crate::ui::widgets::common::{pane, span, titled, wrap};
use crate::ui::widgets::editable::{self, draw_form};
use crate::ui::widgets::graph::{self, budget};
use crate::ui::widgets::models;
use crate::chart::sweep as plot;

use super::layout::sweep_areas;
use super::settings::SweepField;

/// Width of the label column of the sweep form.
const LABEL_WIDTH: usize = 8;

pub fn render(frame: &mut Frame, screen: &ScreenLayout, app: &App) {
    let areas = sweep_areas(screen);
    let scene = match &app.valid {
        Some(valid) => &valid.scene,
        None => &app.draft.scene,
    };
    form(frame, areas.form, app, scene, screen.roomy);
    models::render(frame, areas.models, app, screen.roomy);
    let data = match app.studies.sweep() {
        Some(Ok(data)) => Some(data.clone()),
        _ => None,
    };
    notes(frame, areas.notes, app, scene, data.as_deref());
    chart(frame, areas.chart, app, data.as_deref(), screen.roomy);
}

fn form(frame: &mut Frame, area: Rect, app: &App, scene: &Scene, roomy: bool) {
    let theme = app.theme;
    let block = pane("Sweep", theme, roomy);
    let inner = block.inner(area);
    frame.render_widget(block, area);
    let editor = match &app.mode {
        Mode::Editing(e) => Some(e),
        _ => None,
    };
    let max_points = super::max_points(app);
    let mut lines = Vec::new();
    let mut cursor = None;
    for (i, field) in SweepField::ALL.into_iter().enumerate() {
        let (line, position) = editable::line(
            editable::Row {
                x: inner.x,
                y: inner.y + i as u16,
                width: inner.width,
                label: field.label(),
                label_width: LABEL_WIDTH,
                value: app.views.sweep.settings.display_within(
                    field,
                    scene,
                    max_points,
                    usize::from(inner.width).saturating_sub(LABEL_WIDTH + 1),
                ),
                editor: editor.filter(|e| e.target == super::editor(field)),
                under_cursor: app.views.sweep.cursor == field && editor.is_none(),
            },
            theme,
        );
        lines.push(line);
        cursor = cursor.or(position);
    }
    let hint = match app.views.sweep.cursor {
        SweepField::Parameter => "  ← → any scene key",
        SweepField::Output => "  ← → p₀, a|b, x_max, F_max, t_c, v_out, e_out",
        SweepField::From | SweepField::To => "  Enter types it (10 mm/s) · ← → steps",
        SweepField::Points => "  Enter: a count or auto · ← → ½× 2×",
        SweepField::Scale => "  Enter or ← → switches log / linear",
    };
    draw_form(frame, inner, lines, editor, hint, cursor, theme);
}

/// The onset velocities, what failed, why nothing is drawn.
fn notes(frame: &mut Frame, area: Rect, app: &App, scene: &Scene, data: Option<&SweepData>) {
    let theme = app.theme;
    let width = usize::from(area.width.saturating_sub(1));
    let mut texts: Vec<(String, Role)> = Vec::new();
    if let Err(reason) = app.views.sweep.settings.spec(
        scene,
        app.checked_models(),
        app.draft.options,
        super::max_points(app),
    ) {
        texts.push((reason, Role::Error));
    }
    if let Some(Err(reason)) = app.studies.sweep() {
        texts.push((format!("✗ {reason}"), Role::Error));
    }
    if let Some(data) = data {
        if let Some((v_yield, v_plastic)) = plot::onset(data)
            && data.spec.key == SceneKey::V0
        {
            texts.push((plot::onset_note(v_yield, v_plastic), Role::Normal));
        }
        if let Some((count, first)) = plot::failures(data) {
            texts.push((
                format!("{count} solves failed, not drawn; first: {first}"),
                Role::Warning,
            ));
        }
    }
    let mut lines = Vec::new();
    for (text, role) in texts {
        lines.extend(
            wrap(&text, width)
                .into_iter()
                .map(|l| Line::from(span(format!(" {l}"), theme.style(role)))),
        );
    }
    lines.truncate(usize::from(area.height));
    frame.render_widget(Paragraph::new(lines), area);
}

fn chart(frame: &mut Frame, area: Rect, app: &App, data: Option<&SweepData>, roomy: bool) {
    let theme = app.theme;
    let computing = app.studies.is_pending(StudyKind::Sweep);
    let Some(data) = data else {
        let text = if computing {
            "computing…"
        } else {
            "nothing swept yet"
        };
        let block = pane("Sweep", theme, roomy);
        let inner = block.inner(area);
        frame.render_widget(block, area);
        frame.render_widget(Paragraph::new(span(text, theme.style(Role::Muted))), inner);
        return;
    };
    let budget = budget(area.width.saturating_sub(9), area.height.saturating_sub(6));
    let yield_stress = app
        .valid
        .as_ref()
        .and_then(|v| v.scene.pair().ok())
        .map(|p| p.yield_stress());
    let set = plot::SweepSet {
        name: None,
        data,
        yield_stress,
    };
    let chart = plot::chart(&[set], app.views.sweep.settings.output, Some(app.focused), budget);
    let mut title = chart.title.clone();
    if computing {
        title.push_str(" · computing…");
    }
    let block = titled(&title, area, theme, roomy);
    graph::render_with_legend(frame, area, block, &chart, (app.marker, theme), roomy);
}
