//! The presets overlay: scenes (load) and materials (apply to body 1 or 2), filtered by typing;
//! each row fits its line, a long description cut with "…".

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Clear, List, ListItem, ListState};

use crate::ui::app::App;
use crate::ui::picker::{EntryKind, Picker};
use crate::ui::style::Role;

use super::common::{centered, pane};
use super::status::shortened;

pub fn render(frame: &mut Frame, area: Rect, app: &App, picker: &Picker) {
    let theme = app.theme;
    let visible = picker.visible();
    let name_width = visible
        .iter()
        .map(|e| e.name.chars().count())
        .max()
        .unwrap_or(0);
    let popup_width = area.width.saturating_sub(8).min(110);
    // Borders, the kind column, the name, the origin column and their spaces.
    let description_width =
        usize::from(popup_width.saturating_sub(2)).saturating_sub(10 + name_width + 1 + 9);
    let mut items: Vec<ListItem> = visible
        .iter()
        .map(|e| {
            let kind = match e.kind {
                EntryKind::Scene => "scene   ",
                EntryKind::Material => "material",
            };
            ListItem::new(Line::from(vec![
                Span::styled(format!(" {kind} "), theme.style(Role::Label)),
                Span::styled(
                    format!("{:<name_width$} ", e.name),
                    theme.style(Role::Normal),
                ),
                Span::styled(format!("{:<8} ", e.origin), theme.style(Role::Muted)),
                Span::styled(
                    shortened(&e.description, description_width),
                    theme.style(Role::Muted),
                ),
            ]))
        })
        .collect();
    if items.is_empty() {
        items.push(ListItem::new(Span::styled(
            " nothing matches: Backspace to widen",
            theme.style(Role::Warning),
        )));
    }
    let height = (items.len() as u16 + 2).min(area.height.saturating_sub(2));
    let popup = centered(area, popup_width, height);
    let on_material = picker
        .selected()
        .is_some_and(|e| e.kind == EntryKind::Material);
    let keys = if on_material {
        "Enter: to the body under the cursor · 1 2: to body 1 2"
    } else {
        "Enter loads"
    };
    let title = if picker.filter.is_empty() {
        format!("Presets · type to filter · {keys}")
    } else {
        format!(
            "Presets · filter: {}▏ · {} of {} · {keys}",
            picker.filter,
            visible.len(),
            picker.entries.len()
        )
    };
    // Within the borders, with `…` where it is cut.
    let title = shortened(&title, usize::from(popup_width.saturating_sub(2)));
    let list = List::new(items)
        .block(pane(title, theme, true))
        .highlight_style(theme.style(Role::Cursor));
    let mut state = ListState::default().with_selected(Some(picker.selected));
    frame.render_widget(Clear, popup);
    frame.render_stateful_widget(list, popup, &mut state);
}
