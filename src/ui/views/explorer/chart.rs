//! One chart (F(x), F(t) or v(x)) of the checked models: solid curves in each model's colour, the
//! focused one last and bold, each model's glyph at its exact peak and its end, and the reason of
//! every model that failed.

use ratatui::Frame;
use ratatui::layout::{Position, Rect};
use ratatui::text::Line;
use ratatui::widgets::{Paragraph, Wrap};

use crate::chart::{Chart, Ink, Mark, Readout, ReadoutCurve, Rule, model_glyph};
use crate::model::ForceModel;
use crate::model::impact::Sample;
use crate::ui::app::{App, ChartKind};
use crate::ui::data_cursor::{self, FULL};
use crate::chart::sample::{Look, Series, plot};
use crate::ui::style::{Role, Theme};
use crate::format::units::{self, METRE, METRE_PER_SECOND, NEWTON, SECOND};
use crate::ui::widgets::common::{model_name, pane, span, titled};
use crate::ui::widgets::graph;

use super::results::reason_first;

/// The models drawn.
fn drawn_models(app: &App) -> Vec<ForceModel> {
    app.checked_models()
        .into_iter()
        .filter(|&m| app.solutions.solution(m).is_some())
        .collect()
}

/// Why each checked model that failed has no curve: `✗ proposed: …`.
fn failures(app: &App) -> Vec<String> {
    app.checked_models()
        .into_iter()
        .filter_map(|m| match app.solutions.result(m) {
            Some(Err(message)) => Some(format!("✗ {}: {}", m.name(), reason_first(message))),
            _ => None,
        })
        .collect()
}

/// The chart of `kind` for the models of `app` drawn in `columns` × `rows` cells: the focused
/// model's peak labelled with its value, and the data cursor where it stands.
pub fn describe(app: &App, kind: ChartKind, columns: u16, rows: u16) -> Chart {
    let models = drawn_models(app);
    let series: Vec<&Series> = models
        .iter()
        .filter_map(|&m| app.solutions.samples(m))
        .collect();
    let (max_x, max_y) = graph::budget(columns, rows);
    let p = plot(kind, &series, max_x, max_y);
    let (x_scale, y_scale) = (p.x.scale, p.y.scale);
    let x_range = p.x.bounds;
    let mut chart = p.into_chart(kind.title().to_string(), |m| Look {
        name: model_name(m, 9).to_string(),
        ink: Ink::Model(m),
        glyph: model_glyph(m),
        focused: m == app.focused,
        steps: false,
    });
    chart.notes = failures(app);
    if let Some(s) = app.solutions.samples(app.focused) {
        let (peak, label) = match kind {
            ChartKind::VelocityDisplacement => (s.deepest, ("x_max", s.deepest.0, METRE)),
            ChartKind::ForceDisplacement => (s.force_peak_x, ("F_max", s.force_peak_x.1, NEWTON)),
            ChartKind::ForceTime => (s.force_peak_t, ("F_max", s.force_peak_t.1, NEWTON)),
        };
        chart.marks.push(Mark {
            at: (peak.0 / x_scale, peak.1 / y_scale),
            ink: Ink::Model(app.focused),
            glyph: model_glyph(app.focused),
            label: Some(format!(
                "{} {}",
                label.0,
                units::engineering(label.1, label.2, 4)
            )),
        });
    }
    if let Some(at) = app.views.explorer.data_cursor {
        let x = x_range[0] + (x_range[1] - x_range[0]) * f64::from(at) / f64::from(FULL);
        cursor(app, kind, &models, &mut chart, x, (x_scale, y_scale));
    }
    chart
}

/// The data cursor at display value `x`: a rule, a dot where each curve passes, and the readout of
/// every curve's value there, in the chart's units.
fn cursor(
    app: &App,
    kind: ChartKind,
    models: &[ForceModel],
    chart: &mut Chart,
    x: f64,
    (x_scale, y_scale): (f64, f64),
) {
    let (x_unit, y_unit) = match kind {
        ChartKind::ForceDisplacement => (METRE, NEWTON),
        ChartKind::ForceTime => (SECOND, NEWTON),
        ChartKind::VelocityDisplacement => (METRE, METRE_PER_SECOND),
    };
    let x_si = x * x_scale;
    let x_name = if kind == ChartKind::ForceTime {
        "t"
    } else {
        "x"
    };
    let at = format!("{x_name} = {}", units::engineering(x_si, x_unit, 4));
    let mut curves = Vec::new();
    for &m in models {
        let (Some(solution), Some(samples)) = (app.solutions.solution(m), app.solutions.samples(m))
        else {
            continue;
        };
        let readings = data_cursor::read(kind, solution, &samples.samples, x_si);
        let value = |r: &Sample| match kind {
            ChartKind::VelocityDisplacement => r.v,
            _ => r.f,
        };
        for r in &readings {
            chart.marks.push(Mark {
                at: (x, value(r) / y_scale),
                ink: Ink::Model(m),
                glyph: '●',
                label: None,
            });
        }
        if !readings.is_empty() {
            curves.push(ReadoutCurve {
                names: [m.label(), m.name(), m.short()]
                    .into_iter()
                    .map(str::to_string)
                    .collect(),
                ink: Ink::Model(m),
                values: [4, 3]
                    .into_iter()
                    .map(|digits| joined(readings.iter().map(value), y_unit, digits))
                    .collect(),
            });
        }
    }
    chart.rules.push(Rule {
        at: x,
        horizontal: false,
        ink: Ink::Foreground,
        label: String::new(),
    });
    chart.readout = Some(Readout { at, curves });
}

/// Values of one unit to `digits` significant digits joined by ` / ` with the unit once, in the
/// prefix of the largest: `254.9 / 94.12 N`, `0.2176 / -0.166 m/s`.
fn joined(values: impl Iterator<Item = f64> + Clone, unit: units::Unit, digits: usize) -> String {
    let largest = values.clone().map(f64::abs).fold(0.0, f64::max);
    let prefix = units::engineering_prefix(largest, unit);
    let numbers: Vec<String> = values
        .map(|v| units::sig(v / (prefix.factor * unit.si_per_unit), digits))
        .collect();
    format!("{} {}{}", numbers.join(" / "), prefix.symbol, unit.symbol)
}

/// Draws the chart of `kind`; `hint` where some charts do not fit, so the title says which key
/// shows them.
pub fn render(
    frame: &mut Frame,
    area: Rect,
    app: &App,
    kind: ChartKind,
    roomy: bool,
    hint: bool,
) {
    let theme = app.theme;
    let mut title = kind.title().to_string();
    if app.scene_error.is_some() {
        title.push_str(" · last valid scene");
    }
    if hint {
        title.push_str(" · c: next chart");
    }
    let block = titled(&title, area, theme, roomy);
    let inner = block.inner(area);
    if drawn_models(app).is_empty() {
        let failed = failures(app);
        let (texts, role) = if app.is_computing() {
            (vec!["computing…".to_string()], Role::Muted)
        } else if app.checked_models().is_empty() {
            (
                vec!["no model checked: Space on a model draws it".to_string()],
                Role::Muted,
            )
        } else if !failed.is_empty() {
            (failed, Role::Error)
        } else {
            (vec!["no solution to draw".to_string()], Role::Muted)
        };
        let lines: Vec<Line> = texts
            .into_iter()
            .map(|t| Line::from(span(t, theme.style(role))))
            .collect();
        let note = Paragraph::new(lines).wrap(Wrap { trim: true }).block(block);
        frame.render_widget(note, area);
        return;
    }
    // The plot is the frame less the labels, axis lines and titles: about 7 columns, 4 rows.
    let chart = describe(
        app,
        kind,
        inner.width.saturating_sub(7),
        inner.height.saturating_sub(4),
    );
    graph::render_with_legend(frame, area, block, &chart, (app.marker, theme), roomy);
}

/// The data cursor's place for a click at `position` on the chart `kind` drawn in `area`: the
/// plot built and framed as the chart pane draws it, the column's share of the x axis.
pub fn cursor_at(
    app: &App,
    kind: ChartKind,
    area: Rect,
    roomy: bool,
    position: Position,
) -> Option<u16> {
    let inner = pane("", Theme::Plain, roomy).inner(area);
    let chart = describe(
        app,
        kind,
        inner.width.saturating_sub(7),
        inner.height.saturating_sub(4),
    );
    let plot = graph::frame_of(inner, &chart).plot;
    if plot.width < 2 || !plot.contains(position) {
        return None;
    }
    let share = f64::from(position.x - plot.x) / f64::from(plot.width - 1);
    Some((share * f64::from(FULL)).round() as u16)
}

/// The data cursor's place (per mille of the x axis) at the focused model's peak on the chart
/// `kind` as drawn on screen: F_max on F(x) and F(t), x_max on v(x), where the chart marks it.
pub fn peak_at(app: &App, kind: ChartKind) -> Option<u16> {
    let (width, height) = app.screen;
    let on_screen = super::layout::layout(Rect::new(0, 0, width, height), kind, |w| {
        super::form::resting_height(app, w)
    })
    .and_then(|areas| {
        let roomy = areas.roomy;
        areas
            .charts
            .into_iter()
            .find(|(k, _)| *k == kind)
            .map(|(_, rect)| pane("", Theme::Plain, roomy).inner(rect))
    });
    // Off screen (no size known yet): the chart at a common size.
    let (columns, rows) = on_screen.map_or((60, 20), |inner| {
        (inner.width.saturating_sub(7), inner.height.saturating_sub(4))
    });
    let chart = describe(app, kind, columns, rows);
    let peak = chart
        .marks
        .iter()
        .find(|m| m.ink == Ink::Model(app.focused) && m.label.is_some())?;
    let share = chart.x.fraction(peak.at.0);
    share
        .is_finite()
        .then(|| (share.clamp(0.0, 1.0) * f64::from(FULL)).round() as u16)
}
