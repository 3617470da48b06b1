//! A walk over the cells of a rectangle of the buffer, for the chart axes' rules.

use ratatui::buffer::{Buffer, Cell};
use ratatui::layout::Rect;

/// `f` on each cell of `area` within the buffer, row by row from the top left.
pub fn each_cell(buf: &mut Buffer, area: Rect, mut f: impl FnMut(&mut Cell)) {
    let area = area.intersection(buf.area);
    for y in area.top()..area.bottom() {
        for x in area.left()..area.right() {
            f(&mut buf[(x, y)]);
        }
    }
}
