//! The engine panel overlay: one engine's translation of the scene, scrollable, each line
//! wrapped to the panel.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Clear, Paragraph};

use crate::model::engine::ENGINES;
use crate::ui::app::App;
use crate::ui::engine_panel::EnginePanel;
use crate::ui::style::Role;

use super::common::{centered, titled, wrap};

pub fn render(frame: &mut Frame, area: Rect, app: &App, panel: &EnginePanel) {
    let theme = app.theme;
    let role = if panel.failed {
        Role::Error
    } else {
        Role::Normal
    };
    let popup = centered(
        area,
        area.width.saturating_sub(4),
        area.height.saturating_sub(2),
    );
    // From the first line scrolled to, each wrapped to the panel (a note cut at the border would
    // lose its end), continued under its own indent and two more.
    let width = usize::from(popup.width.saturating_sub(2));
    let lines: Vec<Line> = panel
        .lines
        .iter()
        .skip(usize::from(panel.scroll))
        .flat_map(|line| {
            // A line that fits keeps its spacing (the aligned columns).
            if line.chars().count() <= width {
                return vec![line.clone()];
            }
            let text = line.trim_start();
            let indent = line.chars().count() - text.chars().count();
            let lead = " ".repeat(indent);
            let more = " ".repeat(indent + 2);
            wrap(text, width.saturating_sub(indent + 2).max(8))
                .into_iter()
                .enumerate()
                .map(move |(i, part)| {
                    let lead = if i == 0 { &lead } else { &more };
                    format!("{lead}{part}")
                })
                .collect::<Vec<_>>()
        })
        .map(|l| Line::from(Span::styled(l, theme.style(role))))
        .collect();
    let title = format!(
        "Engine {}/{} · {} (← → engine, ↑ ↓ scroll, Esc closes)",
        panel.index + 1,
        ENGINES.len(),
        ENGINES[panel.index].id
    );
    frame.render_widget(Clear, popup);
    frame.render_widget(
        Paragraph::new(lines).block(titled(&title, popup, theme, true)),
        popup,
    );
}
