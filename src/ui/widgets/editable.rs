//! One labelled value row of the study forms (the stability step, the sweep settings), drawn as
//! the explorer's form draws its fields: the open editor's text and cursor when it edits the row.

use ratatui::layout::Position;
use ratatui::text::{Line, Span};

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
