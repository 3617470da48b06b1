//! A table of one-line cells in columns of fixed widths, drawn straight into the buffer: the
//! cells a ratatui `Table` with a styled header row, `Constraint::Length` widths and a column
//! spacing of 1 draws (a test compares them), without its layout solver and its three passes over
//! every cell's graphemes (the results table cost a tenth of the explorer's frame that way).

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::text::Span;

use super::text::{patch_style, put_text};

/// Columns between neighbours.
const SPACING: u16 = 1;

/// Draws in `area` the header row (its cells' texts over the whole row in `header_style`) and
/// below it as many `rows` as fit, each a span per column from the left: the columns `widths`
/// wide from the area's left edge, one cell apart; cells past the last width are not drawn.
/// The columns are meant to fit the area's width (a `Table` would shrink them; here the last
/// ones are cut at its right edge).
pub fn draw_table(
    buf: &mut Buffer,
    area: Rect,
    widths: &[u16],
    (header, header_style): (&[&str], Style),
    rows: &[Vec<Span>],
) {
    let area = area.intersection(buf.area);
    if area.is_empty() {
        return;
    }
    let mut columns = Vec::with_capacity(widths.len());
    let mut x = area.x;
    for &w in widths {
        let width = w.min(area.right().saturating_sub(x));
        columns.push((x, width));
        x = x
            .saturating_add(w)
            .saturating_add(SPACING)
            .min(area.right());
    }
    patch_style(buf, Rect { height: 1, ..area }, header_style);
    for (&(x, width), text) in columns.iter().zip(header) {
        put_text(buf, (x, area.y), text, width, Style::default());
    }
    for (y, row) in (area.y + 1..area.bottom()).zip(rows) {
        for (&(x, width), cell) in columns.iter().zip(row) {
            put_text(buf, (x, y), &cell.content, width, cell.style);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ui::testing::busy_buffer;
    use ratatui::layout::Constraint;
    use ratatui::style::{Color, Modifier};
    use ratatui::widgets::{Cell, Row, Table, Widget};

    /// Texts of every kind a results cell holds (numbers, symbols with units, names with dashes,
    /// an ellipsis) and some that are cut, in columns that fit, in tables cut short at the right
    /// and the bottom, into buffers already drawn on: the cells and styles `Table` draws.
    #[test]
    fn a_table_draws_what_ratatuis_table_draws() {
        let texts = [
            "x_max µm",
            "9.115",
            "-1.234e-15",
            "b 1.872e5 N·s/m^n",
            "Hunt–Crossley (eq 19)",
            "χ 0.6",
            "proposed…",
            "",
            "exact",
            "a much longer text than its column",
            "computing…",
        ];
        let styles = [
            Style::default(),
            Style::new().fg(Color::Red).add_modifier(Modifier::BOLD),
            Style::new().fg(Color::DarkGray),
        ];
        let header_style = Style::new().fg(Color::Cyan).add_modifier(Modifier::BOLD);
        let buf_area = Rect::new(1, 2, 70, 8);
        let width_sets: [&[u16]; 3] = [&[28, 8, 7, 6, 10], &[9, 6, 6, 6, 10, 5, 6], &[4, 12]];
        for (k, widths) in width_sets.into_iter().enumerate() {
            let header: Vec<&str> = (0..widths.len())
                .map(|i| texts[(i + k) % texts.len()])
                .collect();
            // Rows of every length up to one cell past the columns.
            let rows: Vec<Vec<Span>> = (0..6)
                .map(|r| {
                    (0..=(r + k) % (widths.len() + 2))
                        .map(|c| {
                            let i = 3 * r + c + k;
                            Span::styled(texts[i % texts.len()], styles[i % styles.len()])
                        })
                        .collect()
                })
                .collect();
            let total = widths.iter().sum::<u16>() + widths.len() as u16 - 1;
            for area in [
                Rect::new(1, 2, 70, 8),
                Rect::new(3, 3, total, 4),
                Rect::new(2, 8, total + 5, 5),
                Rect::new(5, 5, total + 1, 1),
            ] {
                let mut ours = busy_buffer(buf_area);
                draw_table(&mut ours, area, widths, (&header, header_style), &rows);
                let mut theirs = busy_buffer(buf_area);
                let table = Table::new(
                    rows.iter()
                        .map(|r| Row::new(r.iter().cloned().map(Cell::from))),
                    widths.iter().map(|&w| Constraint::Length(w)),
                )
                .header(Row::new(header.iter().map(|&h| Cell::from(h))).style(header_style))
                .column_spacing(1);
                Widget::render(table, area, &mut theirs);
                assert_eq!(ours, theirs, "widths {widths:?}, {area:?}");
            }
        }
    }
}
