//! The engine panel overlay: one engine's translation of the scene, scrollable.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Clear, Paragraph};

use crate::model::engine::ENGINES;
use crate::ui::app::App;
use crate::ui::engine_panel::EnginePanel;
use crate::ui::style::Role;

use super::common::{centered, pane};

pub fn render(frame: &mut Frame, area: Rect, app: &App, panel: &EnginePanel) {
    let theme = app.theme;
    let role = if panel.failed {
        Role::Error
    } else {
        Role::Normal
    };
    let lines: Vec<Line> = panel
        .lines
        .iter()
        .map(|l| Line::from(Span::styled(l.as_str(), theme.style(role))))
        .collect();
    let popup = centered(
        area,
        area.width.saturating_sub(4),
        area.height.saturating_sub(2),
    );
    let keys = match &panel.note {
        Some(note) => note.clone(),
        None => "← → engine, ↑ ↓ PgUp PgDn Home End scroll, w write, y copy, Esc".to_string(),
    };
    let title = format!(
        "Engine {}/{} · {} ({keys})",
        panel.index + 1,
        ENGINES.len(),
        ENGINES[panel.index].id
    );
    frame.render_widget(Clear, popup);
    frame.render_widget(
        Paragraph::new(lines)
            .scroll((panel.scroll, 0))
            .block(pane(title, theme, true)),
        popup,
    );
}
