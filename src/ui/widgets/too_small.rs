//! What is drawn when the terminal is below the minimum size.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Wrap};

use crate::ui::app::App;
use crate::ui::layout::{MIN_HEIGHT, MIN_WIDTH};
use crate::ui::style::Role;

pub fn render(frame: &mut Frame, area: Rect, app: &App) {
    let theme = app.theme;
    let lines = vec![
        Line::from(Span::styled("terminal too small", theme.style(Role::Error))),
        Line::from(format!(
            "{}×{}: hertz-tui needs at least {MIN_WIDTH}×{MIN_HEIGHT}",
            area.width, area.height
        )),
        Line::from(Span::styled(
            "enlarge the window, or press q to quit",
            theme.style(Role::Muted),
        )),
    ];
    let top = area.height.saturating_sub(lines.len() as u16) / 2;
    let rect = Rect::new(area.x, area.y + top, area.width, area.height - top);
    frame.render_widget(
        Paragraph::new(lines).centered().wrap(Wrap { trim: true }),
        rect,
    );
}
