//! The presets overlay: scenes (load) and materials (apply to body 1 or 2).

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Clear, List, ListItem, ListState};

use crate::ui::app::App;
use crate::ui::picker::{EntryKind, Picker};
use crate::ui::theme::Role;

use super::common::{centered, pane};

pub fn render(frame: &mut Frame, area: Rect, app: &App, picker: &Picker) {
    let theme = app.theme;
    let name_width = picker
        .entries
        .iter()
        .map(|e| e.name.chars().count())
        .max()
        .unwrap_or(0);
    let items: Vec<ListItem> = picker
        .entries
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
                Span::styled(e.description.clone(), theme.style(Role::Muted)),
            ]))
        })
        .collect();
    let height = (items.len() as u16 + 2).min(area.height.saturating_sub(2));
    let popup = centered(area, area.width.saturating_sub(8).min(110), height);
    let list = List::new(items)
        .block(pane(
            "Presets · Enter loads a scene / applies a material to the body under the cursor · 1 2 pick the body",
            theme,
            true,
        ))
        .highlight_style(theme.style(Role::Cursor));
    let mut state = ListState::default().with_selected(Some(picker.selected));
    frame.render_widget(Clear, popup);
    frame.render_stateful_widget(list, popup, &mut state);
}
