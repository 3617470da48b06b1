//! The frame every view shares, from 80×24 up: the tab bar on top, the status line at the bottom,
//! the view's body between. Below the minimum there is no layout. Each view places its own panes
//! in the body (`views/<name>/layout.rs`).

use ratatui::layout::{Constraint, Layout, Rect};

/// The smallest terminal the explorer draws in.
pub const MIN_WIDTH: u16 = 80;
pub const MIN_HEIGHT: u16 = 24;

/// The areas every tab shares: its tab bar, body and status line.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ScreenLayout {
    pub tabs: Rect,
    /// What the shown tab draws in.
    pub body: Rect,
    pub status: Rect,
    /// Panes get full borders (roomy screens) or a top rule only (compact ones).
    pub roomy: bool,
}

/// The tab bar, body and status line of a screen of `area`; `None` below the minimum size.
pub fn screen_layout(area: Rect) -> Option<ScreenLayout> {
    if area.width < MIN_WIDTH || area.height < MIN_HEIGHT {
        return None;
    }
    let [tabs, body, status] = Layout::vertical([
        Constraint::Length(1),
        Constraint::Fill(1),
        Constraint::Length(1),
    ])
    .areas(area);
    Some(ScreenLayout {
        tabs,
        body,
        status,
        roomy: is_roomy(area),
    })
}

/// Width of the left column (forms and models) of the views that have one.
pub fn left_width(area: Rect) -> u16 {
    if area.width >= 120 { 44 } else { 33 }
}

/// Whether the screen has room for bordered panes and the longer labels.
pub fn is_roomy(area: Rect) -> bool {
    area.width >= 120 && area.height >= 40
}

/// Columns the y labels and axis line of a chart take, at most: labels of up to six characters.
pub const Y_AXIS_ALLOWANCE: u16 = 7;

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    pub(crate) fn inside(inner: Rect, outer: Rect) -> bool {
        inner.x >= outer.x
            && inner.y >= outer.y
            && inner.right() <= outer.right()
            && inner.bottom() <= outer.bottom()
    }

    #[test]
    fn too_small_has_no_screen_layout() {
        assert!(screen_layout(Rect::new(0, 0, 79, 24)).is_none());
        assert!(screen_layout(Rect::new(0, 0, 80, 23)).is_none());
        assert!(screen_layout(Rect::new(0, 0, 80, 24)).is_some());
    }
}
