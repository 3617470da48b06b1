//! The results table: one row per checked model, then the quasistatic (Hertz) estimate.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::Modifier;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Cell, Paragraph, Row, Table};

use crate::model::ForceModel;
use crate::model::impact::ImpactSummary;
use crate::model::quasistatic::ContactGeometry;
use crate::ui::app::App;
use crate::ui::style::{Role, Theme};
use crate::ui::units::{self, sig};
use crate::ui::widgets::common::{flow, model_name, pane, span};

/// A column: header, unit, width, and the value of a summary in that unit.
struct Column {
    header: &'static str,
    unit: &'static str,
    /// How the compact title names the unit of this column ("x µm"), empty for none.
    note: &'static str,
    width: u16,
    value: fn(&ImpactSummary) -> Value,
}

/// A cell before it is fitted to its column: a number with its significant digits, or text.
enum Value {
    Number(f64, usize),
    Text(String),
}

impl Column {
    fn is_number(&self) -> bool {
        !matches!(self.header, "method" | "steps")
    }
}

impl Value {
    /// The cell in `width` columns: a number never cut ([`units::fit`]).
    fn text(&self, width: usize) -> String {
        match self {
            Value::Number(value, digits) => units::fit(*value, *digits, width),
            Value::Text(text) => text.clone(),
        }
    }
}

/// The widest a number column grows to with spare room: `-1.234e-15`.
const NUMBER_WIDTH: u16 = 10;

const COLUMNS: [Column; 9] = [
    Column {
        header: "x_max",
        note: "x µm",
        unit: "µm",
        width: 6,
        value: |s| Value::Number(s.x_max * 1e6, 4),
    },
    Column {
        header: "F_max",
        note: "F N",
        unit: "N",
        width: 6,
        value: |s| Value::Number(s.f_max, 4),
    },
    Column {
        header: "t_c",
        note: "t µs",
        unit: "µs",
        width: 6,
        value: |s| Value::Number(s.t_contact * 1e6, 4),
    },
    Column {
        header: "v_out",
        note: "v m/s",
        unit: "m/s",
        width: 6,
        value: |s| Value::Number(s.v_out, 4),
    },
    Column {
        header: "e_out",
        note: "",
        unit: "",
        width: 5,
        value: |s| Value::Number(s.e_out, 3),
    },
    Column {
        header: "x_res",
        note: "x µm",
        unit: "µm",
        width: 6,
        value: |s| Value::Number(s.x_residual * 1e6, 4),
    },
    Column {
        header: "ΔE",
        note: "ΔE mJ",
        unit: "mJ",
        width: 6,
        value: |s| Value::Number(s.energy_dissipated * 1e3, 4),
    },
    Column {
        header: "method",
        note: "",
        unit: "",
        width: 16,
        value: |s| Value::Text(s.method.to_string()),
    },
    Column {
        header: "steps",
        note: "",
        unit: "",
        width: 6,
        value: |s| Value::Text(s.steps.to_string()),
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
    let header_text = |c: &Column| {
        if c.unit.is_empty() || !roomy {
            c.header.to_string()
        } else {
            format!("{} {}", c.header, c.unit)
        }
    };
    let width_of = |c: &Column| c.width.max(header_text(c).chars().count() as u16);
    // As many columns as fit, in order of importance.
    let mut used = model_width;
    let columns: Vec<&Column> = COLUMNS
        .iter()
        .take_while(|c| {
            used += width_of(c) + 1;
            used <= inner.width
        })
        .collect();
    // Spare room widens the number columns, so that they need fewer compact forms.
    let mut widths: Vec<u16> = columns.iter().map(|c| width_of(c)).collect();
    let mut spare = inner.width.saturating_sub(used.min(inner.width));
    if columns.len() < COLUMNS.len() {
        spare = 0;
    }
    'grow: while spare > 0 {
        let mut grew = false;
        for (c, w) in columns.iter().zip(widths.iter_mut()) {
            if c.is_number() && *w < NUMBER_WIDTH && spare > 0 {
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
    let header = Row::new(
        std::iter::once(Cell::from("model"))
            .chain(columns.iter().map(|c| Cell::from(header_text(c)))),
    )
    .style(theme.style(Role::Label).add_modifier(Modifier::BOLD));
    let rows: Vec<Row> = checked
        .iter()
        .map(|&model| model_row(app, model, &columns, &widths, model_width, theme))
        .collect();
    let widths = std::iter::once(Constraint::Length(model_width))
        .chain(widths.iter().map(|&w| Constraint::Length(w)));
    let table = Table::new(rows, widths).header(header).column_spacing(1);
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
    frame.render_widget(Paragraph::new(quasistatic_lines), q_area);
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

fn model_row<'a>(
    app: &App,
    model: ForceModel,
    columns: &[&Column],
    widths: &[u16],
    model_width: u16,
    theme: Theme,
) -> Row<'a> {
    let busy = app.solutions.is_pending(model);
    let mut name = model_name(model, usize::from(model_width) - 1).to_string();
    if busy {
        name.push('…');
    }
    let mut name_style = theme.model_style(model);
    if app.focused == model {
        name_style = name_style.add_modifier(Modifier::BOLD);
    }
    let name_cell = Cell::from(span(name, name_style));
    match app.solutions.result(model) {
        Some(Ok(solution)) => Row::new(
            std::iter::once(name_cell).chain(
                columns
                    .iter()
                    .zip(widths)
                    .map(|(c, &w)| Cell::from((c.value)(&solution.summary).text(usize::from(w)))),
            ),
        ),
        // The reason is laid over the row after the table is drawn.
        Some(Err(_)) => Row::new(vec![name_cell]),
        None => Row::new(vec![
            name_cell,
            Cell::from(span("computing…", theme.style(Role::Muted))),
        ]),
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
}
