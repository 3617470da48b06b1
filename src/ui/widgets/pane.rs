//! A pane's frame — full borders on roomy screens, a titled top rule on compact ones — drawn
//! straight into the buffer. The cells are those of the equivalent ratatui `Block` (a test
//! compares them), without the `Block`'s restyling of every cell of its area with its default
//! style, a no-op that cost more than the borders themselves (a tenth of the explorer's frame).

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::text::Line;
use ratatui::widgets::{Block, Borders, Widget};

use crate::ui::style::{Role, Theme};

use super::text::{each_cell, line_width, patch_style, render_line};

/// A pane's frame and its titles: one at the top left, and optionally one at the bottom left.
#[derive(Debug, Clone)]
pub struct Pane<'a> {
    title: Line<'a>,
    bottom: Option<Line<'a>>,
    roomy: bool,
    border_style: Style,
    title_style: Style,
}

impl<'a> Pane<'a> {
    /// Full borders on roomy screens, a titled top rule on compact ones.
    pub fn new(title: impl Into<Line<'a>>, theme: Theme, roomy: bool) -> Pane<'a> {
        Pane {
            title: title.into(),
            bottom: None,
            roomy,
            border_style: theme.style(Role::Muted),
            title_style: theme.style(Role::Title),
        }
    }

    /// With `title` on the bottom row as well, at the left.
    pub fn title_bottom(self, title: impl Into<Line<'a>>) -> Pane<'a> {
        Pane {
            bottom: Some(title.into()),
            ..self
        }
    }

    fn borders(&self) -> Borders {
        if self.roomy {
            Borders::ALL
        } else {
            Borders::TOP
        }
    }

    /// The same frame as a ratatui `Block`, for widgets that draw their own (`Paragraph::block`).
    pub fn block(&self) -> Block<'a> {
        let block = Block::default()
            .borders(self.borders())
            .border_style(self.border_style)
            .title(self.title.clone())
            .title_style(self.title_style);
        match &self.bottom {
            Some(bottom) => block.title_bottom(bottom.clone()),
            None => block,
        }
    }

    /// The area inside the frame, as `Block::inner` gives it.
    pub fn inner(&self, area: Rect) -> Rect {
        let mut inner = area;
        if self.roomy {
            inner.x = inner.x.saturating_add(1).min(inner.right());
            inner.width = inner.width.saturating_sub(2);
        }
        inner.y = inner.y.saturating_add(1).min(inner.bottom());
        inner.height = inner.height.saturating_sub(1);
        if self.roomy || self.bottom.is_some() {
            inner.height = inner.height.saturating_sub(1);
        }
        inner
    }

    /// Sets `symbol` in the border cells of `line` (a side, or a corner), patched with the border
    /// style.
    fn border(&self, buf: &mut Buffer, line: Rect, symbol: &str) {
        let patch = self.border_style != Style::default();
        each_cell(buf, line, |cell| {
            cell.set_symbol(symbol);
            if patch {
                cell.set_style(self.border_style);
            }
        });
    }

    /// `title` left on row `y` between the side borders, as `Block` draws a left-aligned title.
    fn title_on(&self, buf: &mut Buffer, area: Rect, y: u16, title: &Line) {
        let side = u16::from(self.roomy);
        let room = area.width.saturating_sub(2 * side);
        if room == 0 {
            return;
        }
        let width = line_width(title).min(usize::from(u16::MAX)) as u16;
        let title_area = Rect::new(area.x.saturating_add(side), y, width.min(room), 1);
        patch_style(buf, title_area, self.title_style);
        render_line(buf, title_area, title);
    }
}

impl Widget for Pane<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        Widget::render(&self, area, buf);
    }
}

impl Widget for &Pane<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let area = area.intersection(buf.area);
        if area.is_empty() {
            return;
        }
        let (left, top) = (area.x, area.y);
        let (right, bottom) = (area.right() - 1, area.bottom() - 1);
        let row = |y| Rect::new(left, y, area.width, 1);
        let column = |x| Rect::new(x, top, 1, area.height);
        let corner = |x, y| Rect::new(x, y, 1, 1);
        // Sides, then the top and bottom rows over them, then the corners, as `Block` draws them.
        if self.roomy {
            self.border(buf, column(left), "│");
        }
        self.border(buf, row(top), "─");
        if self.roomy {
            self.border(buf, column(right), "│");
            self.border(buf, row(bottom), "─");
            self.border(buf, corner(right, bottom), "┘");
            self.border(buf, corner(right, top), "┐");
            self.border(buf, corner(left, bottom), "└");
            self.border(buf, corner(left, top), "┌");
        }
        self.title_on(buf, area, top, &self.title);
        if let Some(title) = &self.bottom {
            self.title_on(buf, area, bottom, title);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ui::testing::busy_buffer;
    use ratatui::style::Color;
    use ratatui::text::Span;

    /// Roomy and compact panes, with and without colour and a bottom title, titles wider than
    /// the pane, areas down to nothing and partly off the buffer: the cells and styles of the
    /// `Block`, and its inner area.
    #[test]
    fn a_pane_draws_what_its_block_draws() {
        let buf_area = Rect::new(2, 1, 40, 12);
        let titles: [Line; 3] = [
            Line::from("Results"),
            Line::from("Body 1 · sphere · steel — a title longer than the pane"),
            Line::from(vec![
                Span::styled(" ─*── proposed ", Style::new().fg(Color::Red)),
                Span::raw(" +2 more "),
            ]),
        ];
        let areas = [
            Rect::new(2, 1, 40, 12),
            Rect::new(5, 3, 20, 6),
            Rect::new(30, 8, 20, 10),
            Rect::new(4, 2, 1, 1),
            Rect::new(4, 2, 2, 2),
            Rect::new(4, 2, 3, 1),
            Rect::new(4, 2, 0, 5),
            Rect::new(0, 0, 8, 4),
        ];
        for color in [true, false] {
            for roomy in [true, false] {
                for title in &titles {
                    for bottom in [None, Some(&titles[2]), Some(&titles[1])] {
                        let mut pane = Pane::new(title.clone(), Theme { color }, roomy);
                        if let Some(bottom) = bottom {
                            pane = pane.title_bottom(bottom.clone());
                        }
                        for area in areas {
                            let mut ours = busy_buffer(buf_area);
                            (&pane).render(area, &mut ours);
                            let mut theirs = busy_buffer(buf_area);
                            pane.block().render(area, &mut theirs);
                            let case = format!("{color} {roomy} {title} {bottom:?} {area:?}");
                            assert_eq!(ours, theirs, "{case}");
                            assert_eq!(pane.inner(area), pane.block().inner(area), "{case}");
                        }
                    }
                }
            }
        }
    }
}
