//! A pane's frame: ratatui's `Block`, with full borders on roomy screens and a titled top rule on
//! compact ones, in the theme's border and title styles.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::{Block, Borders, Widget};

use crate::ui::style::{Role, Theme};

/// A pane's frame and its titles: one at the top left, and optionally one at the bottom left.
#[derive(Debug, Clone)]
pub struct Pane<'a>(Block<'a>);

impl<'a> Pane<'a> {
    /// Full borders on roomy screens, a titled top rule on compact ones.
    pub fn new(title: impl Into<Line<'a>>, theme: Theme, roomy: bool) -> Pane<'a> {
        let borders = if roomy { Borders::ALL } else { Borders::TOP };
        Pane(
            Block::new()
                .borders(borders)
                .border_style(theme.style(Role::Muted))
                .title(title)
                .title_style(theme.style(Role::Title)),
        )
    }

    /// With `title` on the bottom row as well, at the left.
    pub fn title_bottom(self, title: impl Into<Line<'a>>) -> Pane<'a> {
        Pane(self.0.title_bottom(title))
    }

    /// The frame as a `Block`, for widgets that draw their own (`Paragraph::block`).
    pub fn block(self) -> Block<'a> {
        self.0
    }

    /// The area inside the frame.
    pub fn inner(&self, area: Rect) -> Rect {
        self.0.inner(area)
    }
}

impl Widget for Pane<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        self.0.render(area, buf);
    }
}
