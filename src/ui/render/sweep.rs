//! Tab 4, a sweep: the chosen output against the chosen scene parameter for the checked models
//! (or the quasistatic estimate), with the yield-onset velocities marked when v₀ is swept.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::Paragraph;

use crate::model::Scene;
use crate::model::scene_key::SceneKey;
use crate::ui::app::{App, EditTarget, Mode};
use crate::ui::studies::{StudyKind, SweepData};
use crate::ui::sweep_plot::{self, LineOf};
use crate::ui::sweep_settings::{SweepField, key_symbol, key_unit};
use crate::ui::theme::{LinePattern, Role, Theme};
use crate::ui::ticks::{NiceAxis, log_axis, nice_axis};
use crate::ui::units::{self, Unit};

use super::common::{flow, model_name, pane, span, wrap};
use super::editable;
use super::graph::{self, Graph, Rule, Trace};
use super::layout::{Screen, sweep_areas};
use super::models;

/// Width of the label column of the sweep form.
const LABEL_WIDTH: usize = 8;

pub fn render(frame: &mut Frame, screen: &Screen, app: &App) {
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
    let max_points = app.sweep_max_points();
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
                value: app.sweep.display(field, scene, max_points),
                editor: editor.filter(|e| e.target == EditTarget::Sweep(field)),
                under_cursor: app.sweep_cursor == field && editor.is_none(),
            },
            theme,
        );
        lines.push(line);
        cursor = cursor.or(position);
    }
    let help = match editor.and_then(|e| e.error.as_ref()) {
        Some(error) => span(format!("  ✗ {error}"), theme.style(Role::Error)),
        None => span(
            match app.sweep_cursor {
                SweepField::Parameter => "  ← → any scene key",
                SweepField::Output => "  ← → p₀, a|b, x_max, F_max, t_c, v_out, e_out",
                SweepField::From | SweepField::To => "  Enter types it (10 mm/s) · ← → steps",
                SweepField::Points => "  Enter: a count or auto · ← → ½× 2×",
                SweepField::Scale => "  Enter or ← → switches log / linear",
            },
            theme.style(Role::Muted),
        ),
    };
    lines.push(Line::from(help));
    frame.render_widget(Paragraph::new(lines), inner);
    if let Some(position) = cursor {
        frame.set_cursor_position(position);
    }
}

/// The onset velocities, what failed, why nothing is drawn.
fn notes(frame: &mut Frame, area: Rect, app: &App, scene: &Scene, data: Option<&SweepData>) {
    let theme = app.theme;
    let width = usize::from(area.width.saturating_sub(1));
    let mut texts: Vec<(String, Role)> = Vec::new();
    if let Err(reason) = app.sweep.spec(
        scene,
        app.checked_models(),
        app.draft.options,
        app.sweep_max_points(),
    ) {
        texts.push((reason, Role::Error));
    }
    if let Some(Err(reason)) = app.studies.sweep() {
        texts.push((format!("✗ {reason}"), Role::Error));
    }
    if let Some(data) = data {
        if let Some((v_yield, v_plastic)) = sweep_plot::onset(data)
            && data.spec.key == SceneKey::V0
        {
            texts.push((
                format!(
                    "v_y = {} yield begins (p₀ = 1.1·σ_y), v_p = {} fully plastic (2.8·σ_y)",
                    units::engineering(v_yield, units::METRE_PER_SECOND, 3),
                    units::engineering(v_plastic, units::METRE_PER_SECOND, 3)
                ),
                Role::Normal,
            ));
        }
        if let Some((count, first)) = sweep_plot::failures(data) {
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

fn line_style(of: LineOf, theme: Theme) -> (ratatui::style::Style, LinePattern) {
    match of {
        LineOf::Estimate => (theme.style(Role::Normal), LinePattern::Solid),
        LineOf::Model(m) => (theme.model_style(m), LinePattern::of(m)),
    }
}

fn axis(lo: f64, hi: f64, unit: Unit, log: bool, max_labels: usize) -> NiceAxis {
    if log {
        log_axis(lo, hi, unit, max_labels)
    } else {
        nice_axis(lo, hi, unit, max_labels)
    }
}

fn chart(frame: &mut Frame, area: Rect, app: &App, data: Option<&SweepData>, roomy: bool) {
    let theme = app.theme;
    let output = app.sweep.output;
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
    let spec = &data.spec;
    let lines = sweep_plot::lines(data, output);
    let x_unit = key_unit(spec.key);
    let y_unit = output.unit();
    let max_x_labels = usize::from(area.width / 9).clamp(2, 11);
    let max_y_labels = usize::from(area.height / 3).clamp(2, 8);
    let (lo, hi) = (spec.from.min(spec.to), spec.from.max(spec.to));
    let x = axis(lo, hi, x_unit, spec.log, max_x_labels);
    // The y axis includes 0, as the explorer's do: outputs are sizes, times, speeds, ratios.
    let (mut y_lo, mut y_hi) = (0.0f64, 0.0f64);
    for (_, v) in lines.iter().flat_map(|l| l.runs.iter().flatten()) {
        y_lo = y_lo.min(*v);
        y_hi = y_hi.max(*v);
    }
    let y = nice_axis(y_lo, y_hi, y_unit, max_y_labels);
    let to_display = |(px, py): &(f64, f64)| (x.to_display(*px), y.to_display(*py));
    let mut traces = Vec::new();
    for line in &lines {
        let (style, pattern) = line_style(line.of, theme);
        for run in &line.runs {
            traces.push(Trace {
                points: run.iter().map(to_display).collect(),
                style,
                pattern,
            });
        }
    }
    let mut rules = Vec::new();
    if spec.key == SceneKey::V0
        && let Some((v_yield, v_plastic)) = sweep_plot::onset(data)
    {
        rules.push(Rule {
            x: x.to_display(v_yield),
            label: "v_y".into(),
            style: theme.style(Role::Warning),
            pattern: LinePattern::Dotted,
        });
        rules.push(Rule {
            x: x.to_display(v_plastic),
            label: "v_p".into(),
            style: theme.style(Role::Error),
            pattern: LinePattern::Dashed,
        });
    }
    let symbol = key_symbol(spec.key);
    let unit_text = |axis: &NiceAxis, unit: Unit| {
        let text = format!("{}{}", axis.prefix.symbol, unit.symbol);
        if text.is_empty() {
            String::new()
        } else {
            format!(" [{text}]")
        }
    };
    let x_title = format!("{symbol}{}", unit_text(&x, x_unit));
    let y_title = format!("{}{}", output.symbol(), unit_text(&y, y_unit));
    let mut title = format!(
        "{} against {} · {} points, {}",
        output.symbol(),
        symbol,
        spec.points,
        if spec.log { "log" } else { "linear" }
    );
    if computing {
        title.push_str(" · computing…");
    }
    let mut block = pane(title, theme, roomy);
    if roomy {
        block = block.title_bottom(legend(
            &lines,
            theme,
            usize::from(area.width.saturating_sub(2)),
        ));
    }
    let g = Graph {
        x,
        y,
        x_title,
        y_title,
        traces,
        marks: Vec::new(),
        rules,
    };
    graph::render(frame, area, block, &g, app.marker, theme);
}

fn legend(lines: &[sweep_plot::SweepLine], theme: Theme, width: usize) -> Line<'static> {
    let items: Vec<Vec<Span>> = lines
        .iter()
        .map(|l| {
            let (style, pattern) = line_style(l.of, theme);
            let name = match l.of {
                LineOf::Estimate => "Hertz estimate",
                LineOf::Model(m) => model_name(m, 9),
            };
            vec![
                span(format!(" {}", pattern.sample()), style),
                span(format!(" {name} "), style),
            ]
        })
        .collect();
    flow(items, width, 1, Span::raw(""))
        .into_iter()
        .next()
        .unwrap_or_default()
}
