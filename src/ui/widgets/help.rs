//! The help overlay: every key binding and how numbers are typed.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Clear, Paragraph, Wrap};

use crate::ui::app::App;
use crate::ui::keymap::{INPUT_HINTS, bindings};
use crate::ui::rebind::{self, key_name};
use crate::ui::style::Role;

use super::common::{centered, pane};

pub fn render(frame: &mut Frame, area: Rect, app: &App) {
    let theme = app.theme;
    let bindings = bindings();
    let key_width = bindings
        .iter()
        .map(|(k, _)| k.chars().count())
        .max()
        .unwrap_or(0);
    let mut lines: Vec<Line> = bindings
        .into_iter()
        .map(|(keys, what)| {
            Line::from(vec![
                Span::styled(format!(" {keys:<key_width$}  "), theme.style(Role::Key)),
                Span::styled(what, theme.style(Role::Normal)),
            ])
        })
        .collect();
    let moved: Vec<String> = rebind::moved()
        .into_iter()
        .map(|(key, action)| format!("{} {action}", key_name(key)))
        .collect();
    if !moved.is_empty() {
        lines.push(Line::from(vec![
            Span::styled(
                format!(" {:<key_width$}  ", "config"),
                theme.style(Role::Key),
            ),
            Span::styled(moved.join(" · "), theme.style(Role::Normal)),
        ]));
    }
    // A blank line before the input hints, where the screen has a row for it.
    if lines.len() + 1 + INPUT_HINTS.len() + 2 <= usize::from(area.height) {
        lines.push(Line::default());
    }
    lines.extend(
        INPUT_HINTS
            .iter()
            .map(|h| Line::from(Span::styled(format!(" {h}"), theme.style(Role::Muted)))),
    );
    let popup = centered(area, 96, lines.len() as u16 + 2);
    frame.render_widget(Clear, popup);
    frame.render_widget(
        Paragraph::new(lines).wrap(Wrap { trim: false }).block(pane(
            "Help · keys (Esc closes)",
            theme,
            true,
        )),
        popup,
    );
}
