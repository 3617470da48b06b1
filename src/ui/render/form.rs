//! The form panes: body 1, body 2 (shape, size, mass, material) and the impact with its solver.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Position, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::Paragraph;

use crate::model::scene_key::BodyIndex;
use crate::ui::app::{App, Cursor, EditTarget, Mode};
use crate::ui::field::{self, Field, Section};
use crate::ui::theme::Role;

use super::common::{pane, span, wrap};

/// Width of the label column.
const LABEL_WIDTH: usize = 8;

/// One visual row of the form.
enum Row {
    Field(Field),
    /// A red (or plain) note under a field: an error, or the field's description.
    Note(String, Role),
}

fn title(app: &App, section: Section) -> String {
    let scene = &app.draft.scene;
    match section {
        Section::Body(index) => {
            let (n, body) = match index {
                BodyIndex::One => (1, &scene.body1),
                BodyIndex::Two => (2, &scene.body2),
            };
            format!("Body {n} · {} · {}", body.shape, body.material.name)
        }
        Section::Impact => "Impact · solver".into(),
    }
}

/// The rows of a section: fields, each followed by the notes that concern it.
fn rows(app: &App, section: Section, width: usize, describe: bool) -> Vec<Row> {
    let error_note = app.error_note_field();
    let note_width = width.saturating_sub(2);
    let mut rows = Vec::new();
    for field in field::fields_of(section, &app.draft) {
        rows.push(Row::Field(field));
        let mut note = |text: &str, role| {
            rows.extend(
                wrap(text, note_width)
                    .into_iter()
                    .map(|line| Row::Note(format!("  {line}"), role)),
            );
        };
        match &app.mode {
            Mode::Editing(editor) if editor.target == EditTarget::Field(field) => {
                if let Some(error) = &editor.error {
                    note(error, Role::Error);
                }
            }
            _ => {}
        }
        if error_note == Some(field)
            && let Some(error) = &app.scene_error
        {
            note(&error.to_string(), Role::Error);
        }
        if describe && app.cursor == Cursor::Field(field) {
            note(field.description(), Role::Muted);
        }
    }
    rows
}

/// Draws the form: one bordered pane per section when they fit, else one scrolling list.
/// Returns nothing; places the terminal cursor in the field being edited.
pub fn render(frame: &mut Frame, area: Rect, app: &App, roomy: bool) {
    let inner_width = area.width.saturating_sub(2) as usize;
    let sections: Vec<(Section, Vec<Row>)> = Section::ALL
        .iter()
        .map(|&s| (s, rows(app, s, inner_width, roomy)))
        .collect();
    let needed: u16 = sections.iter().map(|(_, r)| r.len() as u16 + 2).sum();
    if roomy && needed <= area.height {
        let mut constraints: Vec<Constraint> = sections
            .iter()
            .map(|(_, r)| Constraint::Length(r.len() as u16 + 2))
            .collect();
        constraints.push(Constraint::Fill(1));
        let areas = Layout::vertical(constraints).split(area);
        for ((section, rows), rect) in sections.iter().zip(areas.iter()) {
            let block = pane(title(app, *section), app.theme, true);
            let inner = block.inner(*rect);
            frame.render_widget(block, *rect);
            draw_rows(frame, inner, app, rows, 0);
        }
        return;
    }
    // One list with a header line per section, scrolled to keep the cursor in view.
    let block = pane("Scene", app.theme, roomy);
    let inner = block.inner(area);
    frame.render_widget(block, area);
    let mut list: Vec<Row> = Vec::new();
    let mut headers: Vec<usize> = Vec::new();
    for (section, rows) in sections {
        headers.push(list.len());
        list.push(Row::Note(title(app, section), Role::Title));
        list.extend(rows);
    }
    let cursor_row = list
        .iter()
        .position(|r| matches!(r, Row::Field(f) if app.cursor == Cursor::Field(*f)))
        .unwrap_or(0);
    let height = inner.height as usize;
    let max_offset = list.len().saturating_sub(height);
    let offset = cursor_row.saturating_sub(height / 2).min(max_offset);
    // The header of the section at the top stays in view: pinned on the first row when the list
    // is scrolled past it, the rows continuing below it.
    let header = headers.iter().rev().find(|&&h| h <= offset).copied();
    match header {
        Some(h) if h < offset && inner.height > 2 => {
            draw_rows(frame, inner, app, &list[h..=h], 0);
            let below = Rect::new(inner.x, inner.y + 1, inner.width, inner.height - 1);
            let next = if cursor_row > offset {
                offset + 1
            } else {
                offset
            };
            draw_rows(frame, below, app, &list, next);
        }
        _ => draw_rows(frame, inner, app, &list, offset),
    }
}

fn draw_rows(frame: &mut Frame, area: Rect, app: &App, rows: &[Row], offset: usize) {
    let theme = app.theme;
    let error_fields = app.error_fields();
    let value_width = (area.width as usize).saturating_sub(LABEL_WIDTH + 1);
    let mut lines: Vec<Line> = Vec::new();
    let mut cursor_position = None;
    for (i, row) in rows
        .iter()
        .enumerate()
        .skip(offset)
        .take(area.height as usize)
    {
        let line = match row {
            Row::Note(text, role) => Line::from(span(text.clone(), theme.style(*role))),
            Row::Field(field) => {
                let label = format!(" {:<w$}", field.label(), w = LABEL_WIDTH - 1);
                let under_cursor = app.cursor == Cursor::Field(*field);
                let (value, value_role) = match &app.mode {
                    Mode::Editing(editor) if editor.target == EditTarget::Field(*field) => {
                        let scroll = editor.input.visual_scroll(value_width.saturating_sub(1));
                        let x = area.x
                            + (LABEL_WIDTH + editor.input.visual_cursor().saturating_sub(scroll))
                                as u16;
                        cursor_position = Some(Position::new(
                            x.min(area.right().saturating_sub(1)),
                            area.y + (i - offset) as u16,
                        ));
                        let text: String = editor.input.value().chars().skip(scroll).collect();
                        let role = if editor.error.is_some() {
                            Role::Error
                        } else {
                            Role::Normal
                        };
                        (text, role)
                    }
                    _ if error_fields.contains(field) => {
                        (format!("{} ✗", field.display(&app.draft)), Role::Error)
                    }
                    _ => (field.display(&app.draft), Role::Normal),
                };
                let editing =
                    matches!(&app.mode, Mode::Editing(e) if e.target == EditTarget::Field(*field));
                let label_role = if editing { Role::Cursor } else { Role::Label };
                let mut line = Line::from(vec![
                    Span::styled(label, theme.style(label_role)),
                    Span::styled(value, theme.style(value_role)),
                ]);
                if under_cursor && !matches!(app.mode, Mode::Editing(_)) {
                    line = line.patch_style(theme.style(Role::Cursor));
                }
                line
            }
        };
        lines.push(line);
    }
    let paragraph = Paragraph::new(lines);
    frame.render_widget(paragraph, area);
    if let Some(position) = cursor_position {
        frame.set_cursor_position(position);
    }
}
