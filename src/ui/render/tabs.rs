//! The tab bar: the four views with their keys, the shown one highlighted.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::style::Modifier;
use ratatui::text::{Line, Span};
use ratatui::widgets::Paragraph;

use crate::ui::app::App;
use crate::ui::tab::Tab;
use crate::ui::theme::Role;

pub fn render(frame: &mut Frame, area: Rect, app: &App) {
    let theme = app.theme;
    let mut spans = Vec::new();
    for tab in Tab::ALL {
        let shown = tab == app.tab;
        let (key_style, title_style) = if shown {
            let style = theme.style(Role::Title).add_modifier(Modifier::REVERSED);
            (style, style)
        } else {
            (theme.style(Role::Key), theme.style(Role::Muted))
        };
        spans.push(Span::styled(format!(" {}", tab.key()), key_style));
        spans.push(Span::styled(format!(" {} ", tab.title()), title_style));
        spans.push(Span::raw(" "));
    }
    frame.render_widget(Paragraph::new(Line::from(spans)), area);
}
