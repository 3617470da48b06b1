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
    // Each line wrapped to the panel (a note cut at the border would lose its end), continued
    // under its own indent and two more. The scroll counts the panel's lines; the rows shown start
    // at the first row of the line scrolled to, but never so late that rows are left empty at the
    // bottom, so that `End` shows the script's last line even where lines above it wrapped.
    let width = usize::from(popup.width.saturating_sub(2));
    let mut first_row_of_line = Vec::with_capacity(panel.lines.len());
    let mut rows: Vec<String> = Vec::new();
    for line in &panel.lines {
        first_row_of_line.push(rows.len());
        // A line that fits keeps its spacing (the aligned columns).
        if line.chars().count() <= width {
            rows.push(line.clone());
            continue;
        }
        let text = line.trim_start();
        let indent = line.chars().count() - text.chars().count();
        for (i, part) in wrap(text, width.saturating_sub(indent + 2).max(8))
            .into_iter()
            .enumerate()
        {
            let lead = if i == 0 { indent } else { indent + 2 };
            rows.push(format!("{}{part}", " ".repeat(lead)));
        }
    }
    let height = usize::from(popup.height.saturating_sub(2));
    let start = first_row_of_line
        .get(usize::from(panel.scroll))
        .copied()
        .unwrap_or(rows.len())
        .min(rows.len().saturating_sub(height));
    let lines: Vec<Line> = rows
        .into_iter()
        .skip(start)
        .map(|l| Line::from(Span::styled(l, theme.style(role))))
        .collect();
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
        Paragraph::new(lines).block(titled(&title, popup, theme, true)),
        popup,
    );
}
