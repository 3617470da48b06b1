//! The form panes: body 1, body 2 (shape, size, mass, material) and the impact with its solver.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Position, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::Paragraph;

use crate::model::scene_key::{BodyIndex, SceneKey};
use crate::ui::app::{App, Cursor, EditTarget, Mode};
use crate::ui::field::{self, Field, Section};
use crate::ui::style::Role;
use crate::ui::widgets::common::{pane, span, wrap};

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

/// The height of the form's section panes of `width` columns with no field described: what the
/// layout leaves the form before giving the rest to the models pane.
pub fn resting_height(app: &App, width: u16) -> u16 {
    let inner_width = width.saturating_sub(2) as usize;
    Section::ALL
        .iter()
        .map(|&s| rows(app, s, inner_width, false).len() as u16 + 2)
        .sum()
}

/// Where the rows go: one bordered pane per section when they fit, else one scrolling list with
/// a header line per section, scrolled to keep the cursor in view.
enum Placement {
    Panes(Vec<(Section, Rect, Vec<Row>)>),
    /// One scrolled list; `pinned` is the header of the section at the top when the list is
    /// scrolled past it, drawn on the first row with the rows from `offset` below it.
    List {
        area: Rect,
        rows: Vec<Row>,
        offset: usize,
        pinned: Option<usize>,
    },
}

impl Placement {
    /// Where the scrolled rows of a list go: below its pinned header, if any.
    fn list_rows(area: Rect, pinned: Option<usize>) -> Rect {
        match pinned {
            Some(_) => Rect::new(area.x, area.y + 1, area.width, area.height - 1),
            None => area,
        }
    }
}

fn place(app: &App, area: Rect, roomy: bool) -> Placement {
    let inner_width = area.width.saturating_sub(2) as usize;
    let sections: Vec<(Section, Vec<Row>)> = Section::ALL
        .iter()
        .map(|&s| (s, rows(app, s, inner_width, roomy)))
        .collect();
    let needed: u16 = sections.iter().map(|(_, r)| r.len() as u16 + 2).sum();
    if roomy && needed <= area.height {
        let heights = sections
            .iter()
            .map(|(_, r)| Constraint::Length(r.len() as u16 + 2));
        let areas = Layout::vertical(heights.chain([Constraint::Fill(1)])).split(area);
        return Placement::Panes(
            sections
                .into_iter()
                .zip(areas.iter())
                .map(|((section, rows), rect)| (section, *rect, rows))
                .collect(),
        );
    }
    let inner = pane("Scene", app.theme, roomy).inner(area);
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
        Some(h) if h < offset && inner.height > 2 => Placement::List {
            area: inner,
            rows: list,
            offset: if cursor_row > offset {
                offset + 1
            } else {
                offset
            },
            pinned: Some(h),
        },
        _ => Placement::List {
            area: inner,
            rows: list,
            offset,
            pinned: None,
        },
    }
}

/// Draws the form and places the terminal cursor in the field being edited.
pub fn render(frame: &mut Frame, area: Rect, app: &App, roomy: bool) {
    match place(app, area, roomy) {
        Placement::Panes(panes) => {
            for (section, rect, rows) in panes {
                let block = pane(title(app, section), app.theme, true);
                let inner = block.inner(rect);
                frame.render_widget(block, rect);
                draw_rows(frame, inner, app, &rows, 0);
            }
        }
        Placement::List {
            area: inner,
            rows,
            offset,
            pinned,
        } => {
            frame.render_widget(pane("Scene", app.theme, roomy), area);
            if let Some(h) = pinned {
                draw_rows(frame, inner, app, &rows[h..=h], 0);
            }
            let below = Placement::list_rows(inner, pinned);
            draw_rows(frame, below, app, &rows, offset);
        }
    }
}

/// The field drawn at `position` of a form drawn in `area` (for mouse clicks), if any.
pub fn field_at(app: &App, area: Rect, roomy: bool, position: Position) -> Option<Field> {
    let pick = |inner: Rect, rows: &[Row], offset: usize| {
        if !inner.contains(position) {
            return None;
        }
        match rows.get(offset + usize::from(position.y - inner.y)) {
            Some(Row::Field(field)) => Some(*field),
            _ => None,
        }
    };
    match place(app, area, roomy) {
        Placement::Panes(panes) => panes.iter().find_map(|(section, rect, rows)| {
            pick(
                pane(title(app, *section), app.theme, true).inner(*rect),
                rows,
                0,
            )
        }),
        Placement::List {
            area: inner,
            rows,
            offset,
            pinned,
        } => pick(Placement::list_rows(inner, pinned), &rows, offset),
    }
}

/// Whether `field` holds a value the scene's user did not give (a preset's stand-in).
fn is_assumed(app: &App, field: Field) -> bool {
    let assumed = app.draft.scene.assumed;
    match field {
        Field::Number(SceneKey::Restitution) => assumed.restitution,
        Field::Number(SceneKey::PlasticIndentation) => assumed.plastic_indentation,
        _ => false,
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
                let label = format!(" {:<1$}", field.label(), LABEL_WIDTH - 1);
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
                // A preset's stand-in, not a value the user gave: said beside it until edited.
                if !editing && is_assumed(app, *field) {
                    line.push_span(Span::styled(" assumed", theme.style(Role::Warning)));
                }
                if under_cursor && !matches!(app.mode, Mode::Editing(_)) {
                    line = line.patch_style(theme.style(Role::Cursor));
                }
                line
            }
        };
        lines.push(line);
    }
    frame.render_widget(Paragraph::new(lines), area);
    if let Some(position) = cursor_position {
        frame.set_cursor_position(position);
    }
}
