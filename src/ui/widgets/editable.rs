//! The study forms (the stability step, the sweep, system and map settings): a labelled value
//! row, drawn as the explorer's form draws its fields (the open editor's text and cursor when it
//! edits the row), and the form with its help line under the rows.

use ratatui::Frame;
use ratatui::layout::{Position, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::Paragraph;

use crate::ui::app::Editor;
use crate::ui::style::{Role, Theme};

/// A row at column `x`, line `y`, `width` columns wide, with a label column of `label_width`.
pub struct Row<'a> {
    pub x: u16,
    pub y: u16,
    pub width: u16,
    pub label: &'a str,
    pub label_width: usize,
    pub value: String,
    /// The open editor, when it edits this row.
    pub editor: Option<&'a Editor>,
    pub under_cursor: bool,
}

/// The line of the row, and where the terminal cursor goes while it is edited.
pub fn line(row: Row, theme: Theme) -> (Line<'static>, Option<Position>) {
    let label = format!(" {:<w$}", row.label, w = row.label_width.saturating_sub(1));
    let value_width = usize::from(row.width).saturating_sub(row.label_width + 1);
    let Some(editor) = row.editor else {
        let mut line = Line::from(vec![
            Span::styled(label, theme.style(Role::Label)),
            Span::styled(row.value, theme.style(Role::Normal)),
        ]);
        if row.under_cursor {
            line = line.patch_style(theme.style(Role::Cursor));
        }
        return (line, None);
    };
    let scroll = editor.input.visual_scroll(value_width.saturating_sub(1));
    let text: String = editor.input.value().chars().skip(scroll).collect();
    let role = if editor.selected {
        // Shown selected: the first key typed replaces it.
        Role::Cursor
    } else if editor.error.is_some() {
        Role::Error
    } else {
        Role::Normal
    };
    let column = row.label_width + editor.input.visual_cursor().saturating_sub(scroll);
    let x = (row.x + column as u16).min((row.x + row.width).saturating_sub(1));
    let line = Line::from(vec![
        Span::styled(label, theme.style(Role::Cursor)),
        Span::styled(text, theme.style(role)),
    ]);
    (line, Some(Position::new(x, row.y)))
}

/// Draws a form's `lines` in `area` with the line under them: the open editor's refusal where it
/// has one, else `hint`; and the terminal cursor where the edited row put it.
pub fn draw_form(
    frame: &mut Frame,
    area: Rect,
    mut lines: Vec<Line<'static>>,
    editor: Option<&Editor>,
    hint: &'static str,
    cursor: Option<Position>,
    theme: Theme,
) {
    let help = match editor.and_then(|e| e.error.as_ref()) {
        Some(error) => Span::styled(format!("  ✗ {error}"), theme.style(Role::Error)),
        None => Span::styled(hint, theme.style(Role::Muted)),
    };
    lines.push(Line::from(help));
    frame.render_widget(Paragraph::new(lines), area);
    if let Some(position) = cursor {
        frame.set_cursor_position(position);
    }
}
