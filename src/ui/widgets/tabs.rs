//! The tab bar: the views with their keys, the shown one highlighted.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::style::Modifier;
use ratatui::text::{Line, Span};

use crate::ui::app::App;
use crate::ui::style::Role;
use crate::ui::tab::Tab;

pub fn render(frame: &mut Frame, area: Rect, app: &App) {
    let theme = app.theme;
    let mut spans = Vec::new();
    for tab in Tab::all() {
        let shown = tab == app.tab;
        let (key_style, title_style) = if shown {
            let style = theme.style(Role::Title).add_modifier(Modifier::REVERSED);
            (style, style)
        } else {
            (theme.style(Role::Key), theme.style(Role::Muted))
        };
        let [key, title, gap] = labels(tab, compact(area.width));
        spans.push(Span::styled(key, key_style));
        spans.push(Span::styled(title, title_style));
        spans.push(Span::raw(gap));
    }
    frame.render_widget(Line::from(spans), area);
}

/// The key, title and gap of a tab's label on the bar; `compact` drops the spaces between labels.
fn labels(tab: Tab, compact: bool) -> [String; 3] {
    let key = tab.key().map(|key| format!(" {key}")).unwrap_or_default();
    if compact {
        return [key, format!(" {}", tab.title()), String::new()];
    }
    [key, format!(" {} ", tab.title()), " ".into()]
}

/// Whether the labels with their spaces are wider than a bar of `width` columns (at 80 columns
/// with seven views): then they go without.
fn compact(width: u16) -> bool {
    // The widths of `labels(tab, false)`, counted rather than written out: the bar is drawn
    // every frame.
    let wide: usize = Tab::all()
        .map(|tab| 2 * usize::from(tab.key().is_some()) + tab.title().chars().count() + 3)
        .sum();
    wide > usize::from(width)
}

/// The tab whose label covers `column` of a bar `width` columns wide (for mouse clicks).
pub fn tab_at(column: u16, width: u16) -> Option<Tab> {
    let mut start = 0;
    let compact = compact(width);
    Tab::all().find(|&tab| {
        let width: usize = labels(tab, compact).iter().map(|l| l.chars().count()).sum();
        let end = start + width as u16;
        let hit = (start..end).contains(&column);
        start = end;
        hit
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The counted widths are those of the labels as written.
    #[test]
    fn the_bar_is_compact_where_the_written_labels_do_not_fit() {
        let wide: usize = Tab::all()
            .flat_map(|tab| labels(tab, false))
            .map(|l| l.chars().count())
            .sum();
        let wide = u16::try_from(wide).unwrap();
        assert!(compact(wide - 1));
        assert!(!compact(wide));
    }
}
