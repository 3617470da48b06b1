//! Where the sweep view's panes go: its form, the models and the notes on the left, the chart on
//! the right.

use ratatui::layout::{Constraint, Layout, Rect};

use crate::ui::widgets::models;
use crate::ui::layout::{
    MIN_HEIGHT, MIN_WIDTH, ScreenLayout, Y_AXIS_ALLOWANCE, is_roomy, left_width, screen_layout,
};

/// The panes of the sweep view in the body of a screen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SweepAreas {
    pub form: Rect,
    pub models: Rect,
    /// Below the models: what the sweep marks and what failed.
    pub notes: Rect,
    pub chart: Rect,
}

/// Rows under the models for the sweep's notes.
const NOTES_ROWS: u16 = 6;

/// Rows of the sweep form.
pub const SWEEP_FORM_ROWS: u16 = 6;

pub fn sweep_areas(screen: &ScreenLayout) -> SweepAreas {
    let [left, chart] = Layout::horizontal([
        Constraint::Length(left_width(screen.body)),
        Constraint::Fill(1),
    ])
    .areas(screen.body);
    let frame = if screen.roomy { 2 } else { 1 };
    // The form, a line describing the row under the cursor, the model checklist as long as the
    // notes (v_y and v_p, the failures) allow, the notes.
    let form_rows = SWEEP_FORM_ROWS + 1 + frame;
    let models_rows = left
        .height
        .saturating_sub(form_rows + NOTES_ROWS)
        .min(models::row_count() + frame)
        .max(5 + frame);
    let [form, models, notes] = Layout::vertical([
        Constraint::Length(form_rows),
        Constraint::Length(models_rows),
        Constraint::Fill(1),
    ])
    .areas(left);
    SweepAreas {
        form,
        models,
        notes,
        chart,
    }
}

/// Plot columns of the sweep chart on a screen of `area` (80×24 while the size is unknown).
pub fn sweep_plot_columns(area: Rect) -> u16 {
    let chart = screen_layout(area)
        .or_else(|| screen_layout(Rect::new(0, 0, MIN_WIDTH, MIN_HEIGHT)))
        .map(|s| sweep_areas(&s).chart)
        .unwrap_or_default();
    // Borders on roomy screens, a top rule on compact ones: the width loses 2 or nothing.
    let borders = if is_roomy(area) { 2 } else { 0 };
    chart
        .width
        .saturating_sub(borders + Y_AXIS_ALLOWANCE)
        .max(1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ui::layout::tests::inside;

    #[test]
    fn sweep_panes_fit_and_its_chart_sets_the_points() {
        for (w, h) in [(80, 24), (120, 40), (160, 48)] {
            let area = Rect::new(0, 0, w, h);
            let s = screen_layout(area).unwrap();
            let a = sweep_areas(&s);
            let rects = [s.tabs, s.status, a.form, a.models, a.notes, a.chart];
            for (i, r) in rects.iter().enumerate() {
                assert!(inside(*r, area), "{w}×{h}: {r:?}");
                for other in &rects[i + 1..] {
                    assert!(!r.intersects(*other), "{w}×{h}: {r:?} overlaps {other:?}");
                }
            }
            assert!(a.form.height > SWEEP_FORM_ROWS);
        }
        // 160 wide: a 116-column chart less borders and the y axis.
        assert_eq!(sweep_plot_columns(Rect::new(0, 0, 160, 48)), 107);
        // Unknown size: as on the smallest screen.
        assert_eq!(
            sweep_plot_columns(Rect::new(0, 0, 0, 0)),
            sweep_plot_columns(Rect::new(0, 0, 80, 24))
        );
    }
}
