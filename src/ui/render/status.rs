//! The status line: scene name with the unsaved mark, recompute time or "computing…", and either
//! the news of the last action or the key hints.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::Paragraph;

use crate::ui::app::{App, Mode};
use crate::ui::tab::Tab;
use crate::ui::theme::Role;
use crate::ui::units;

/// Key hints per mode and tab: (key, action).
fn hints(mode: &Mode, tab: Tab) -> &'static [(&'static str, &'static str)] {
    match (mode, tab) {
        (Mode::Normal, Tab::WorkPrecision) => &[
            ("?", "help"),
            ("q", "quit"),
            ("1-4", "views"),
            ("[ ]", "model"),
            ("c", "chart"),
        ],
        (Mode::Normal, Tab::Stability) => &[
            ("?", "help"),
            ("q", "quit"),
            ("1-4", "views"),
            ("Enter", "step"),
            ("←→", "½× 2×"),
            ("[ ]", "model"),
        ],
        (Mode::Normal, Tab::Sweep) => &[
            ("?", "help"),
            ("q", "quit"),
            ("1-4", "views"),
            ("↑↓", "move"),
            ("Enter", "edit"),
            ("←→", "change"),
            ("Space", "model"),
            ("[ ]", "focus"),
        ],
        (Mode::Normal, Tab::Explorer) => &[
            ("?", "help"),
            ("q", "quit"),
            ("1-4", "views"),
            ("↑↓", "move"),
            ("Enter", "edit"),
            ("←→", "nudge"),
            ("Space", "model"),
            ("p", "presets"),
            ("s", "save"),
            ("e", "export"),
        ],
        (Mode::Editing(_), _) => &[("Enter", "commit"), ("Esc", "cancel")],
        (Mode::Help, _) => &[("Esc", "close")],
        (Mode::Picker(_), _) => &[
            ("Enter", "load / apply"),
            ("1 2", "material to body"),
            ("Esc", "close"),
        ],
        (Mode::Prompt(_), _) => &[("Enter", "write"), ("Esc", "cancel")],
    }
}

/// `text` cut to `width` characters, with an ellipsis when cut.
fn shortened(text: &str, width: usize) -> String {
    if text.chars().count() <= width {
        text.to_string()
    } else {
        let mut cut: String = text.chars().take(width.saturating_sub(1)).collect();
        cut.push('…');
        cut
    }
}

pub fn render(frame: &mut Frame, area: Rect, app: &App) {
    let theme = app.theme;
    let mut left = vec![Span::styled(
        format!(
            " {}",
            shortened(&app.draft.scene.name, usize::from(area.width / 3))
        ),
        theme.style(Role::Title),
    )];
    if app.is_dirty() {
        left.push(Span::styled("*", theme.style(Role::Warning)));
    }
    if app.is_computing() || app.is_studying() {
        left.push(Span::styled(" · computing…", theme.style(Role::Warning)));
    } else if let Some(elapsed) = app.last_recompute {
        left.push(Span::styled(
            format!(
                " · recomputed in {}",
                units::engineering(elapsed.as_secs_f64(), units::SECOND, 2)
            ),
            theme.style(Role::Muted),
        ));
    }
    if app.scene_error.is_some() {
        left.push(Span::styled(" · invalid scene", theme.style(Role::Error)));
    }
    let left = Line::from(left);
    let left_width = (left.width() as u16).min(area.width);
    let room = usize::from(area.width.saturating_sub(left_width + 1));
    let right: Vec<Span> = match &app.message {
        Some(message) => vec![Span::styled(
            format!("{} ", message.text),
            theme.style(if message.error {
                Role::Error
            } else {
                Role::Good
            }),
        )],
        None => {
            // As many hints as fit, in order.
            let mut used = 0;
            hints(&app.mode, app.tab)
                .iter()
                .take_while(|(key, what)| {
                    used += key.chars().count() + what.chars().count() + 3;
                    used <= room
                })
                .flat_map(|(key, what)| {
                    [
                        Span::styled(*key, theme.style(Role::Key)),
                        Span::styled(format!(" {what}  "), theme.style(Role::Muted)),
                    ]
                })
                .collect()
        }
    };
    let right = Line::from(right).right_aligned();
    let [l, r] =
        Layout::horizontal([Constraint::Length(left_width + 1), Constraint::Fill(1)]).areas(area);
    frame.render_widget(Paragraph::new(left), l);
    frame.render_widget(Paragraph::new(right), r);
}
