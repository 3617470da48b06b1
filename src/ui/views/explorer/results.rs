//! The results table: one row per checked model, then the quasistatic (Hertz) estimate.

use std::borrow::Cow;

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::Modifier;
use ratatui::text::{Line, Span, Text};
use ratatui::widgets::{Paragraph, Row, Table};

use crate::format::{Zeros, scientific};
use crate::model::ForceModel;
use crate::model::force::Damping;
use crate::model::impact::ImpactSummary;
use crate::model::quasistatic::ContactGeometry;
use crate::ui::app::App;
use crate::ui::style::{Role, Theme};
use crate::format::units::{self, sig};
use crate::ui::widgets::common::{flow, model_name, pane, span};

/// A column: header, unit, width, and the value of a solved row in that unit.
struct Column {
    header: &'static str,
    unit: &'static str,
    /// How the compact title names the unit of this column ("x µm"), empty for none.
    note: &'static str,
    width: u16,
    value: fn(&Solved) -> Value,
}

/// What a model's row shows: its impact's summary and the damping its law used.
struct Solved<'a> {
    summary: &'a ImpactSummary,
    damping: Option<Damping>,
}

/// A cell before it is fitted to its column: a number with its significant digits, a damping
/// parameter, or text.
enum Value {
    Number(f64, usize),
    Damping(Option<Damping>),
    Text(String),
}

impl Column {
    fn is_number(&self) -> bool {
        !matches!(self.header, "method" | "steps" | "damping")
    }
}

impl Value {
    /// The cell in `width` columns: a number never cut ([`units::fit`]).
    fn text(&self, width: usize) -> String {
        match self {
            Value::Number(value, digits) => units::fit(*value, *digits, width),
            Value::Damping(damping) => damping_text(*damping, width),
            Value::Text(text) => text.clone(),
        }
    }
}

/// A damping parameter in `width` columns, its number never cut: `γ 3.2e3 N·s/m^((n+1)/2)` with
/// its unit where its number keeps the digits it has without, else `γ 3.2e3`; `-` for a law
/// without one.
fn damping_text(damping: Option<Damping>, width: usize) -> String {
    let Some(Damping { param, value }) = damping else {
        return "-".into();
    };
    let symbol = param.symbol.chars().count() + 1;
    let full = damping_number(value, width.saturating_sub(symbol));
    if param.unit == "1" || full == "…" {
        return format!("{} {full}", param.symbol);
    }
    let unit_width = 1 + param.unit.chars().count();
    let with_unit = damping_number(value, width.saturating_sub(symbol + unit_width));
    if with_unit == full {
        format!("{} {full} {}", param.symbol, param.unit)
    } else {
        format!("{} {full}", param.symbol)
    }
}

/// A damping value in `width` columns, never cut: four significant digits or fewer, plain within
/// 1e-3 … 1e4 and scientific outside it, as `solve` prints it (`b = 1.872e5`).
fn damping_number(value: f64, width: usize) -> String {
    if value == 0.0 || (1e-3..1e4).contains(&value.abs()) {
        return units::fit(value, 4, width);
    }
    (1..=4)
        .rev()
        .map(|digits| scientific(value, digits, Zeros::Trim))
        .find(|text| text.chars().count() <= width)
        .unwrap_or_else(|| units::fit(value, 4, width))
}

/// The widest a damping cell of `damping` needs: symbol, four digits and unit.
fn damping_width(damping: Option<Damping>) -> u16 {
    damping_text(damping, 64).chars().count() as u16
}

/// The widest a number column grows to with spare room: `-1.234e-15`.
const NUMBER_WIDTH: u16 = 10;

/// The columns in order of importance: as many as fit are shown. The damping used comes before
/// the e_out it gives.
const COLUMNS: [Column; 10] = [
    Column {
        header: "x_max",
        note: "x µm",
        unit: "µm",
        width: 6,
        value: |r| Value::Number(r.summary.x_max * 1e6, 4),
    },
    Column {
        header: "F_max",
        note: "F N",
        unit: "N",
        width: 6,
        value: |r| Value::Number(r.summary.f_max, 4),
    },
    Column {
        header: "t_c",
        note: "t µs",
        unit: "µs",
        width: 6,
        value: |r| Value::Number(r.summary.t_contact * 1e6, 4),
    },
    Column {
        header: "damping",
        note: "",
        unit: "",
        width: 10,
        value: |r| Value::Damping(r.damping),
    },
    Column {
        header: "e_out",
        note: "",
        unit: "",
        width: 5,
        value: |r| Value::Number(r.summary.e_out, 3),
    },
    Column {
        header: "v_out",
        note: "v m/s",
        unit: "m/s",
        width: 6,
        value: |r| Value::Number(r.summary.v_out, 4),
    },
    Column {
        header: "x_res",
        note: "x µm",
        unit: "µm",
        width: 6,
        value: |r| Value::Number(r.summary.x_residual * 1e6, 4),
    },
    Column {
        header: "ΔE",
        note: "ΔE mJ",
        unit: "mJ",
        width: 6,
        value: |r| Value::Number(r.summary.energy_dissipated * 1e3, 4),
    },
    Column {
        header: "method",
        note: "",
        unit: "",
        width: 16,
        value: |r| Value::Text(r.summary.method.to_string()),
    },
    Column {
        header: "steps",
        note: "",
        unit: "",
        width: 6,
        value: |r| Value::Text(r.summary.steps.to_string()),
    },
];

pub fn render(frame: &mut Frame, area: Rect, app: &App, roomy: bool) {
    let theme = app.theme;
    let checked = app.checked_models();
    let block = pane(
        if app.scene_error.is_some() {
            "Results · last valid scene"
        } else {
            "Results"
        },
        theme,
        roomy,
    );
    let inner = block.inner(area);
    frame.render_widget(block, area);
    let model_width: u16 = if roomy { 28 } else { 9 };
    let header_text = |c: &Column| -> Cow<'static, str> {
        if c.header == "damping" && app.calibrate {
            // Every law's damping solved so that it realises the scene's e.
            Cow::Borrowed("calibrated")
        } else if c.unit.is_empty() || !roomy {
            Cow::Borrowed(c.header)
        } else {
            Cow::Owned(format!("{} {}", c.header, c.unit))
        }
    };
    let header_texts: Vec<Cow<str>> = COLUMNS.iter().map(header_text).collect();
    let width_of = |c: &Column, header: &str| c.width.max(header.chars().count() as u16);
    // As many columns as fit, in order of importance.
    let mut used = model_width;
    let shown = COLUMNS
        .iter()
        .zip(&header_texts)
        .take_while(|(c, header)| {
            used += width_of(c, header) + 1;
            used <= inner.width
        })
        .count();
    let columns: Vec<&Column> = COLUMNS[..shown].iter().collect();
    // Spare room widens the number columns, so that they need fewer compact forms.
    let mut widths: Vec<u16> = columns
        .iter()
        .zip(&header_texts)
        .map(|(c, header)| width_of(c, header))
        .collect();
    let mut spare = inner.width.saturating_sub(used.min(inner.width));
    if columns.len() < COLUMNS.len() {
        spare = 0;
    }
    // The damping column grows with spare room until its units show (its cells are formatted
    // for their width only where there is room to grow).
    let damping_needed = match spare {
        0 => 0,
        _ => checked
            .iter()
            .map(|&m| damping_width(app.solutions.damping(m)))
            .max()
            .unwrap_or(0),
    };
    'grow: while spare > 0 {
        let mut grew = false;
        for (c, w) in columns.iter().zip(widths.iter_mut()) {
            let widest = match c.header {
                "damping" => damping_needed,
                _ if c.is_number() => NUMBER_WIDTH,
                _ => 0,
            };
            if *w < widest && spare > 0 {
                *w += 1;
                spare -= 1;
                grew = true;
            }
        }
        if !grew {
            break 'grow;
        }
    }
    let quasistatic_lines = quasistatic_block(app, inner.width as usize, 2);
    let table_height = inner
        .height
        .saturating_sub(quasistatic_lines.len() as u16)
        .max(1);
    let [table_area, q_area] =
        Layout::vertical([Constraint::Length(table_height), Constraint::Fill(1)]).areas(inner);
    let header = std::iter::once("model").chain(header_texts[..shown].iter().map(|h| h.as_ref()));
    let header_style = theme.style(Role::Label).add_modifier(Modifier::BOLD);
    // Only the rows under the header that fit the pane are drawn (the table is not scrolled):
    // with every law checked, the other three quarters of the rows were formatted for nothing.
    let fitting = usize::from(table_area.height.saturating_sub(1));
    let rows = checked
        .iter()
        .take(fitting)
        .map(|&model| Row::new(model_row(app, model, &columns, &widths, model_width, theme)));
    let constraints = std::iter::once(model_width)
        .chain(widths.iter().copied())
        .map(Constraint::Length);
    let table = Table::new(rows, constraints)
        .header(Row::new(header).style(header_style))
        .column_spacing(1);
    frame.render_widget(table, table_area);
    // A failed model's reason over its number columns, whole where the row has room: a table
    // cell would cut it to the width of one number.
    let reason_x = table_area.x + model_width + 1;
    for (i, &model) in checked.iter().enumerate() {
        let (Some(Err(message)), Some(y)) = (
            app.solutions.result(model),
            table_area.y.checked_add(1 + i as u16),
        ) else {
            continue;
        };
        if y >= table_area.bottom() || reason_x >= table_area.right() {
            continue;
        }
        let width = table_area.right() - reason_x;
        let text = fit_reason(&format!("✗ {}", reason_first(message)), usize::from(width));
        frame.render_widget(
            Paragraph::new(span(text, theme.style(Role::Error))),
            Rect::new(reason_x, y, width, 1),
        );
    }
    frame.render_widget(Text::from(quasistatic_lines), q_area);
    if !roomy {
        // The compact header has no room for units: name them once, in the title row.
        let mut notes: Vec<&str> = Vec::new();
        for c in &columns {
            if !c.note.is_empty() && !notes.contains(&c.note) {
                notes.push(c.note);
            }
        }
        let units = notes.join(" · ");
        let width = units.chars().count() as u16;
        if area.width > width + 10 {
            let rect = Rect::new(area.right() - width - 1, area.y, width, 1);
            frame.render_widget(Paragraph::new(span(units, theme.style(Role::Muted))), rect);
        }
    }
}

/// A model's row, a span per column: its name, then its numbers (nothing more for a failed
/// model, whose reason is laid over the row; `computing…` before its first result).
fn model_row(
    app: &App,
    model: ForceModel,
    columns: &[&Column],
    widths: &[u16],
    model_width: u16,
    theme: Theme,
) -> Vec<Span<'static>> {
    let busy = app.solutions.is_pending(model);
    let mut name = model_name(model, usize::from(model_width) - 1).to_string();
    if busy {
        name.push('…');
    }
    let mut name_style = theme.model_style(model);
    if app.focused == model {
        name_style = name_style.add_modifier(Modifier::BOLD);
    }
    let name_cell = span(name, name_style);
    match app.solutions.result(model) {
        Some(Ok(solution)) => {
            let solved = Solved {
                summary: &solution.summary,
                damping: app.solutions.damping(model),
            };
            std::iter::once(name_cell)
                .chain(
                    columns
                        .iter()
                        .zip(widths)
                        .map(|(c, &w)| Span::raw((c.value)(&solved).text(usize::from(w)))),
                )
                .collect()
        }
        // The reason is laid over the row after the table is drawn.
        Some(Err(_)) => vec![name_cell],
        // In the first number's column, with `…` where it is narrower than the word.
        None => {
            let width = widths.first().map_or(usize::MAX, |&w| usize::from(w));
            let text = fit_reason("computing…", width);
            vec![name_cell, span(text, theme.style(Role::Muted))]
        }
    }
}

/// A solver message with its conclusion first: `euler: energy grew by 347 % at t = …: the method
/// is unstable at this step` → `euler: the method is unstable at this step — energy grew by …`,
/// so that a row cut short still says why.
pub fn reason_first(message: &str) -> String {
    let parts: Vec<&str> = message.split(": ").collect();
    match parts.as_slice() {
        [who, detail @ .., conclusion] if !detail.is_empty() => {
            format!("{who}: {conclusion} — {}", detail.join(": "))
        }
        _ => message.to_string(),
    }
}

/// `text` in `width` columns, cut with … where longer.
fn fit_reason(text: &str, width: usize) -> String {
    if text.chars().count() <= width {
        return text.to_string();
    }
    let kept: String = text.chars().take(width.saturating_sub(1)).collect();
    format!("{kept}…")
}

/// The quasistatic block: k, n, contact radius or half-width, p₀, and the elastic estimates.
fn quasistatic_block(app: &App, width: usize, max_lines: usize) -> Vec<Line<'static>> {
    let Some(valid) = &app.valid else {
        return Vec::new();
    };
    let theme = app.theme;
    let q = &valid.quasistatic;
    let item = |label: &str, value: String| {
        vec![
            Span::styled(format!("{label} "), theme.style(Role::Label)),
            Span::styled(value, theme.style(Role::Normal)),
        ]
    };
    let mut items = vec![
        vec![Span::styled("Hertz estimate", theme.style(Role::Title))],
        item("k", format!("{} N/m^{}", sig(q.k, 4), sig(q.n, 3))),
        item("n", sig(q.n, 4)),
    ];
    items.push(match q.geometry {
        ContactGeometry::Point { contact_radius } => {
            item("a", units::engineering(contact_radius, units::METRE, 4))
        }
        ContactGeometry::Line { half_width, .. } => {
            item("b", units::engineering(half_width, units::METRE, 4))
        }
    });
    items.push(item("p₀", units::engineering(q.p_max, units::PASCAL, 4)));
    items.push(item(
        "m",
        units::engineering(q.reduced_mass, units::GRAM, 4),
    ));
    items.push(item("x_max", units::engineering(q.x_max, units::METRE, 4)));
    items.push(item("F_max", units::engineering(q.f_max, units::NEWTON, 4)));
    items.push(item(
        "t_c",
        units::engineering(q.t_contact, units::SECOND, 4),
    ));
    if let ContactGeometry::Line { fit, .. } = q.geometry {
        items.push(item(
            "fit",
            format!(
                "a·xⁿ+c over {}–{}, max error {} %",
                units::engineering(fit.f_min, units::NEWTON, 3),
                units::engineering(fit.f_max, units::NEWTON, 3),
                sig(fit.max_rel_error * 100.0, 2)
            ),
        ));
    }
    flow(items, width, max_lines, Span::raw("  "))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_reason_leads_with_its_conclusion() {
        assert_eq!(
            reason_first(
                "euler: energy grew by 347.4 % at t = 5.000000e-5 s: the method is unstable at \
                 this step"
            ),
            "euler: the method is unstable at this step — energy grew by 347.4 % at t = \
             5.000000e-5 s"
        );
        assert_eq!(reason_first("contact did not end"), "contact did not end");
        assert_eq!(fit_reason("✗ abcdef", 5), "✗ ab…");
        assert_eq!(fit_reason("✗ ab", 5), "✗ ab");
    }

    #[test]
    fn a_damping_cell_narrows_to_its_symbol_and_number_never_cutting_it() {
        let of = |model: ForceModel, value: f64| {
            Some(Damping {
                param: model.spec().damping.unwrap(),
                value,
            })
        };
        let b = of(ForceModel::Proposed, 187_220.4);
        assert_eq!(damping_text(b, 30), "b 1.872e5 N·s/m^n");
        assert_eq!(damping_text(b, 16), "b 1.872e5");
        assert_eq!(damping_text(b, 8), "b 1.87e5");
        assert_eq!(damping_text(b, 4), "b …");
        assert_eq!(damping_width(b), 17);
        // A pure number has no unit.
        let chi = of(ForceModel::HuntCrossley, 0.6);
        assert_eq!(damping_text(chi, 30), "χ 0.6");
        let p = of(ForceModel::DryFriction, 2.5e-4);
        assert_eq!(damping_text(p, 9), "P 2.5e-4");
        assert_eq!(damping_text(None, 10), "-");
    }
}
