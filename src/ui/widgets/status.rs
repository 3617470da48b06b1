//! The status line: scene name with the unsaved mark, recompute time or "computing…", and either
//! the news of the last action or the key hints.

use std::borrow::Cow;

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::Paragraph;

use crate::format::units;
use crate::ui::app::{App, Mode};
use crate::ui::rebind;
use crate::ui::style::Role;
use crate::ui::views::{self, Hints};

/// Key hints of the modes other than normal: (key, action).
fn mode_hints(mode: &Mode) -> Hints {
    match mode {
        Mode::Normal => &[],
        Mode::Editing(_) => &[("Enter", "commit"), ("Esc", "cancel")],
        Mode::Help => &[("Esc", "close")],
        Mode::Engine(_) => &[("←→", "engine"), ("↑↓", "scroll"), ("Esc", "close")],
        Mode::Picker(_) => &[
            ("Enter", "load / apply"),
            ("1 2", "material to body"),
            ("Esc", "close"),
        ],
        Mode::Prompt(_) => &[("Enter", "write"), ("Esc", "cancel")],
        Mode::Confirm(_) => &[("y", "yes"), ("any other key", "no")],
    }
}

/// The key hints of the status line: in normal mode the keys every view shares, then the shown
/// view's own, each as the config file's `[keys]` moved it; else the mode's.
fn hints(app: &App) -> Vec<(Cow<'static, str>, &'static str)> {
    match app.mode {
        Mode::Normal => [
            (Cow::Owned(rebind::hint("?")), "help"),
            (Cow::Owned(rebind::hint("q")), "quit"),
            (Cow::Owned(views::keys_hint()), "views"),
        ]
        .into_iter()
        .chain(
            app.tab
                .view()
                .hints()
                .iter()
                .map(|&(key, what)| (Cow::Owned(rebind::hint(key)), what)),
        )
        .collect(),
        ref mode => mode_hints(mode)
            .iter()
            .map(|&(key, what)| (Cow::Borrowed(key), what))
            .collect(),
    }
}

/// `text` cut to `width` characters, with an ellipsis when cut.
pub(crate) fn shortened(text: &str, width: usize) -> String {
    if text.chars().count() <= width {
        text.to_string()
    } else if width == 0 {
        String::new()
    } else {
        let mut cut: String = text.chars().take(width.saturating_sub(1)).collect();
        cut.push('…');
        cut
    }
}

/// A status message cut to `width` characters with `…`. A path in it (the last word with a `/`)
/// loses its leading folders first, so that the file name stays: `saved …/scenes/my-scene.toml`.
pub(crate) fn fit_message(text: &str, width: usize) -> String {
    let length = text.chars().count();
    if length <= width {
        return text.to_string();
    }
    let path_word = text
        .split_whitespace()
        .rev()
        .find(|word| word.contains(['/', '\\']));
    if let Some(word) = path_word {
        let start = text.rfind(word).unwrap_or(0);
        let (head, rest) = text.split_at(start);
        let tail = &rest[word.len()..];
        let others = head.chars().count() + tail.chars().count();
        if let Some(budget) = width.checked_sub(others).filter(|&b| b >= 2) {
            return format!("{head}{}{tail}", path_end(word, budget));
        }
    }
    shortened(text, width)
}

/// `path` cut to `budget` (> 1) characters from its start: whole trailing components behind `…/`
/// while the file name fits, else the file name's last characters behind `…`.
fn path_end(path: &str, budget: usize) -> String {
    let length = path.chars().count();
    if length <= budget {
        return path.to_string();
    }
    // The separators the shortened path may start at, nearest the end last.
    let mut best = None;
    for (i, c) in path.char_indices() {
        if c == '/' || c == '\\' {
            let kept = path[i..].chars().count();
            if kept < budget {
                best = Some(i);
                break;
            }
        }
    }
    match best {
        Some(i) if i + 1 < path.len() => format!("…{}", &path[i..]),
        _ => {
            let skip = length - (budget - 1);
            format!("…{}", path.chars().skip(skip).collect::<String>())
        }
    }
}

pub fn render(frame: &mut Frame, area: Rect, app: &App) {
    let theme = app.theme;
    // After an edit the scene is no longer the preset it came from: named by its bodies.
    let (name, _) = app.title();
    let mut left = vec![Span::styled(
        format!(" {}", shortened(&name, usize::from(area.width / 3))),
        theme.style(Role::Title),
    )];
    if app.is_dirty() {
        left.push(Span::styled("*", theme.style(Role::Warning)));
    }
    if app.is_computing() || views::is_studying(app) {
        left.push(Span::styled(" · computing…", theme.style(Role::Warning)));
    } else if let Some(elapsed) = app.last_recompute
        // The recompute time is the explorer's; the study views time their own work.
        && app.tab.view().studies().is_empty()
    {
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
            format!("{} ", fit_message(&message.text, room.saturating_sub(1))),
            theme.style(if message.error {
                Role::Error
            } else {
                Role::Good
            }),
        )],
        None => {
            // As many hints as fit, in order.
            let mut used = 0;
            hints(app)
                .into_iter()
                .take_while(|(key, what)| {
                    used += key.chars().count() + what.chars().count() + 3;
                    used <= room
                })
                .flat_map(|(key, what)| {
                    [
                        Span::styled(key, theme.style(Role::Key)),
                        Span::styled(format!(" {what}  "), theme.style(Role::Muted)),
                    ]
                })
                .collect()
        }
    };
    let [left_area, right_area] =
        Layout::horizontal([Constraint::Length(left_width + 1), Constraint::Fill(1)]).areas(area);
    frame.render_widget(Paragraph::new(left), left_area);
    frame.render_widget(
        Paragraph::new(Line::from(right).right_aligned()),
        right_area,
    );
}

#[cfg(test)]
mod tests {
    use super::fit_message;

    #[test]
    fn long_messages_are_cut_with_an_ellipsis_keeping_the_file_name() {
        let saved = "saved /home/someone/.config/hertz-tui/presets/scenes/my-scene.toml";
        assert_eq!(fit_message(saved, 80), saved, "what fits is left alone");
        assert_eq!(
            fit_message(saved, 36),
            "saved …/presets/scenes/my-scene.toml"
        );
        assert_eq!(fit_message(saved, 30), "saved …/scenes/my-scene.toml");
        assert_eq!(fit_message(saved, 24), "saved …/my-scene.toml");
        // Not even the file name fits: its end stays.
        assert_eq!(fit_message(saved, 12), "saved ….toml");
        let exported = "exported proposed (401 rows) to /tmp/some/where/fig5-proposed.csv";
        assert_eq!(
            fit_message(exported, 52),
            "exported proposed (401 rows) to …/fig5-proposed.csv"
        );
        for width in 0..saved.len() {
            let fitted = fit_message(saved, width);
            assert!(fitted.chars().count() <= width, "{width}: {fitted}");
            if width > 0 {
                assert!(fitted.contains('…'), "{width}: {fitted}");
            }
        }
        // Without a path the end is cut.
        assert_eq!(
            fit_message("the step stays within 1 fs … 1 s", 12),
            "the step st…"
        );
    }
}
