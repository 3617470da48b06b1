//! The form panes: body 1, body 2 (shape, size, mass, material) and the impact with its solver.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Position, Rect};
use ratatui::text::{Line, Span, Text};

use crate::model::scene_key::{BodyIndex, SceneKey};
use crate::ui::app::{App, Cursor, EditTarget, Mode, Scroll};
use crate::ui::field::{self, Field, Section};
use crate::ui::style::Role;
use crate::ui::widgets::common::{pane, span, wrap};
use crate::ui::widgets::status::shortened;

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

/// The rows of a section: fields, each followed by the errors that concern it. (The description
/// of the field under the cursor goes below the panes, where it moves no row: see
/// [`draw_description`].)
fn rows(app: &App, section: Section, width: usize) -> Vec<Row> {
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
    }
    rows
}

/// The height of the form's section panes of `width` columns with no field described: what the
/// layout leaves the form before giving the rest to the models pane.
pub fn resting_height(app: &App, width: u16) -> u16 {
    let inner_width = width.saturating_sub(2) as usize;
    Section::ALL
        .iter()
        .map(|&s| rows(app, s, inner_width).len() as u16 + 2)
        .sum()
}

/// Where the rows go: one bordered pane per section when they fit, else one scrolling list with
/// a header line per section, scrolled to keep the cursor in view.
enum Placement {
    /// The section panes, and the rows left below them (for the description of the field under
    /// the cursor).
    Panes(Vec<(Section, Rect, Vec<Row>)>, Rect),
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
        .map(|&s| (s, rows(app, s, inner_width)))
        .collect();
    let needed: u16 = sections.iter().map(|(_, r)| r.len() as u16 + 2).sum();
    if roomy && needed <= area.height {
        let heights = sections
            .iter()
            .map(|(_, r)| Constraint::Length(r.len() as u16 + 2));
        let areas = Layout::vertical(heights.chain([Constraint::Fill(1)])).split(area);
        let spare = areas.last().copied().unwrap_or_default();
        return Placement::Panes(
            sections
                .into_iter()
                .zip(areas.iter())
                .map(|((section, rows), rect)| (section, *rect, rows))
                .collect(),
            spare,
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
    // The header of the section at the top stays in view: pinned on the first row when the list
    // is scrolled past it, the rows continuing below it.
    let pinned_at = |offset: usize| {
        headers
            .iter()
            .rev()
            .find(|&&h| h <= offset)
            .copied()
            .filter(|&h| h < offset && inner.height > 2)
    };
    let offset = match app.scroll.form.get() {
        // First drawn: the cursor in the middle, below the header pinned above it.
        Scroll::UNSET => {
            let offset = cursor_row
                .saturating_sub(height / 2)
                .min(list.len().saturating_sub(height));
            offset + usize::from(pinned_at(offset).is_some() && cursor_row > offset)
        }
        stored => list_offset(stored, cursor_row, list.len(), height, |o| {
            pinned_at(o).is_some()
        }),
    };
    app.scroll.form.set(offset);
    Placement::List {
        area: inner,
        rows: list,
        offset,
        pinned: pinned_at(offset),
    }
}

/// The first row of `total` below the pinned header (if `pinned(offset)`, which takes a row of
/// the `height`): scrolled from `stored` as little as keeps row `cursor` in view, so that a click on
/// a row in view scrolls nothing, and no further than shows the last row.
fn list_offset(
    stored: usize,
    cursor: usize,
    total: usize,
    height: usize,
    pinned: impl Fn(usize) -> bool,
) -> usize {
    if height == 0 || total <= height {
        return 0;
    }
    let shown = |offset: usize| if pinned(offset) { height - 1 } else { height };
    let last = if pinned(total - height) {
        total - height + 1
    } else {
        total - height
    };
    let mut offset = stored.min(last);
    if cursor < offset {
        offset = cursor;
    } else if cursor >= offset + shown(offset) {
        offset = cursor + 1 - height;
        if pinned(offset) {
            offset += 1;
        }
    }
    offset.min(last)
}

/// Draws the form and places the terminal cursor in the field being edited.
pub fn render(frame: &mut Frame, area: Rect, app: &App, roomy: bool) {
    match place(app, area, roomy) {
        Placement::Panes(panes, spare) => {
            for (section, rect, rows) in panes {
                let block = pane(title(app, section), app.theme, true);
                let inner = block.inner(rect);
                frame.render_widget(block, rect);
                draw_rows(frame, inner, app, &rows, 0);
            }
            draw_description(frame, spare, app);
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
        Placement::Panes(panes, _) => panes.iter().find_map(|(section, rect, rows)| {
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

/// The description of the field under the cursor in the rows below the panes, muted, wrapped,
/// its last line ending in `…` if it is cut: there it moves no row when the cursor moves.
fn draw_description(frame: &mut Frame, area: Rect, app: &App) {
    let Cursor::Field(field) = app.cursor else {
        return;
    };
    let width = usize::from(area.width.saturating_sub(2));
    let height = usize::from(area.height);
    let mut lines = wrap(field.description(), width);
    if lines.len() > height {
        lines.truncate(height);
        if let Some(last) = lines.last_mut() {
            *last = shortened(&format!("{last} …"), width);
            if !last.ends_with('…') {
                last.push('…');
            }
        }
    }
    let lines: Vec<Line> = lines
        .into_iter()
        .map(|line| Line::from(span(format!(" {line}"), app.theme.style(Role::Muted))))
        .collect();
    frame.render_widget(Text::from(lines), area);
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
                        let role = if editor.selected {
                            // Shown selected: the first key typed replaces it.
                            Role::Cursor
                        } else if editor.error.is_some() {
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
    frame.render_widget(Text::from(lines), area);
    if let Some(position) = cursor_position {
        frame.set_cursor_position(position);
    }
}
