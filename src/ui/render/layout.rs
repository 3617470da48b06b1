//! Where each pane goes, from 80×24 up. Below the minimum there is no layout. Every tab has the
//! tab bar on top and the status line at the bottom; the explorer and the sweep view split the
//! rest into a left column (forms, models) and the charts.

use ratatui::layout::{Constraint, Layout, Rect};

use crate::ui::chart_kind::ChartKind;

/// The smallest terminal the explorer draws in.
pub const MIN_WIDTH: u16 = 80;
pub const MIN_HEIGHT: u16 = 24;

/// The frame every tab shares.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Screen {
    pub tabs: Rect,
    /// What the shown tab draws in.
    pub body: Rect,
    pub status: Rect,
    /// Panes get full borders (roomy screens) or a top rule only (compact ones).
    pub roomy: bool,
}

/// The tab bar, body and status line of a screen of `area`; `None` below the minimum size.
pub fn screen(area: Rect) -> Option<Screen> {
    if area.width < MIN_WIDTH || area.height < MIN_HEIGHT {
        return None;
    }
    let [tabs, body, status] = Layout::vertical([
        Constraint::Length(1),
        Constraint::Fill(1),
        Constraint::Length(1),
    ])
    .areas(area);
    Some(Screen {
        tabs,
        body,
        status,
        roomy: is_roomy(area),
    })
}

/// Width of the left column (forms and models) of the explorer and the sweep view.
pub(super) fn left_width(area: Rect) -> u16 {
    if area.width >= 120 { 44 } else { 33 }
}

/// The rectangles of the explorer's panes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Areas {
    pub tabs: Rect,
    /// Regime line(s).
    pub info: Rect,
    pub form: Rect,
    pub models: Rect,
    pub charts: Vec<(ChartKind, Rect)>,
    pub results: Rect,
    pub status: Rect,
    /// Panes get full borders (roomy screens) or a top rule only (compact ones).
    pub roomy: bool,
}

/// Whether the screen has room for bordered panes and the longer labels.
pub fn is_roomy(area: Rect) -> bool {
    area.width >= 120 && area.height >= 40
}

/// The panes of a screen of `area`, with `first` the chart shown where only one fits.
pub fn layout(area: Rect, first: ChartKind) -> Option<Areas> {
    let Screen {
        tabs,
        body,
        status,
        roomy,
    } = screen(area)?;
    let info_height = if roomy { 6 } else { 3 };
    let [info, body] =
        Layout::vertical([Constraint::Length(info_height), Constraint::Fill(1)]).areas(body);
    let [left, right] =
        Layout::horizontal([Constraint::Length(left_width(area)), Constraint::Fill(1)]).areas(body);
    let models_height = if roomy { 7 } else { 8 };
    let [form, models] =
        Layout::vertical([Constraint::Fill(1), Constraint::Length(models_height)]).areas(left);
    let results_height = if roomy { 10 } else { 8 };
    let [charts_area, results] =
        Layout::vertical([Constraint::Fill(1), Constraint::Length(results_height)]).areas(right);
    Some(Areas {
        tabs,
        info,
        form,
        models,
        charts: chart_grid(charts_area, first),
        results,
        status,
        roomy,
    })
}

/// The panes of the sweep view in the body of a screen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SweepAreas {
    pub form: Rect,
    pub models: Rect,
    /// Below the models: what the sweep marks and what failed.
    pub notes: Rect,
    pub chart: Rect,
}

/// Rows of the sweep form.
pub const SWEEP_FORM_ROWS: u16 = 6;

pub fn sweep_areas(screen: &Screen) -> SweepAreas {
    let [left, chart] = Layout::horizontal([
        Constraint::Length(left_width(screen.body)),
        Constraint::Fill(1),
    ])
    .areas(screen.body);
    let frame = if screen.roomy { 2 } else { 1 };
    // The form, a line describing the row under the cursor, then the model checklist.
    let [form, models, notes] = Layout::vertical([
        Constraint::Length(SWEEP_FORM_ROWS + 1 + frame),
        Constraint::Length(5 + frame),
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

/// Columns the y labels and axis line of a chart take, at most: labels of up to six characters.
pub const Y_AXIS_ALLOWANCE: u16 = 7;

/// Plot columns of the sweep chart on a screen of `area` (80×24 while the size is unknown).
pub fn sweep_plot_columns(area: Rect) -> u16 {
    let chart = screen(area)
        .or_else(|| screen(Rect::new(0, 0, MIN_WIDTH, MIN_HEIGHT)))
        .map(|s| sweep_areas(&s).chart)
        .unwrap_or_default();
    // Borders on roomy screens, a top rule on compact ones: the width loses 2 or nothing.
    let borders = if is_roomy(area) { 2 } else { 0 };
    chart
        .width
        .saturating_sub(borders + Y_AXIS_ALLOWANCE)
        .max(1)
}

/// One, two or three charts, as the space allows: F(x) and v(x) side by side like the paper's
/// Fig. 5, with F(t) under them when there is height, or beside them when there is width.
fn chart_grid(area: Rect, first: ChartKind) -> Vec<(ChartKind, Rect)> {
    use ChartKind::*;
    if area.width >= 76 && area.height >= 30 {
        let [top, bottom] =
            Layout::vertical([Constraint::Percentage(60), Constraint::Fill(1)]).areas(area);
        let [a, b] = Layout::horizontal([Constraint::Fill(1); 2]).areas(top);
        return vec![
            (ForceDisplacement, a),
            (VelocityDisplacement, b),
            (ForceTime, bottom),
        ];
    }
    if area.width >= 114 {
        let [a, b, c] = Layout::horizontal([Constraint::Fill(1); 3]).areas(area);
        return vec![
            (ForceDisplacement, a),
            (VelocityDisplacement, b),
            (ForceTime, c),
        ];
    }
    if area.width >= 76 {
        let [a, b] = Layout::horizontal([Constraint::Fill(1); 2]).areas(area);
        let i = ChartKind::ALL.iter().position(|&k| k == first).unwrap_or(0);
        let second = ChartKind::ALL[(i + 1) % ChartKind::ALL.len()];
        return vec![(first, a), (second, b)];
    }
    vec![(first, area)]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn inside(inner: Rect, outer: Rect) -> bool {
        inner.x >= outer.x
            && inner.y >= outer.y
            && inner.right() <= outer.right()
            && inner.bottom() <= outer.bottom()
    }

    #[test]
    fn too_small_has_no_layout() {
        assert!(layout(Rect::new(0, 0, 79, 24), ChartKind::ForceTime).is_none());
        assert!(layout(Rect::new(0, 0, 80, 23), ChartKind::ForceTime).is_none());
        assert!(layout(Rect::new(0, 0, 80, 24), ChartKind::ForceTime).is_some());
    }

    #[test]
    fn panes_fit_and_do_not_overlap() {
        for (w, h) in [(80, 24), (100, 30), (120, 40), (160, 48), (250, 80)] {
            let area = Rect::new(0, 0, w, h);
            let a = layout(area, ChartKind::ForceDisplacement).unwrap();
            let mut rects = vec![a.tabs, a.info, a.form, a.models, a.results, a.status];
            rects.extend(a.charts.iter().map(|(_, r)| *r));
            for (i, r) in rects.iter().enumerate() {
                assert!(inside(*r, area), "{w}×{h}: {r:?}");
                assert!(r.width > 0 && r.height > 0, "{w}×{h}: {r:?}");
                for s in &rects[i + 1..] {
                    assert!(!r.intersects(*s), "{w}×{h}: {r:?} overlaps {s:?}");
                }
            }
        }
    }

    #[test]
    fn sweep_panes_fit_and_its_chart_sets_the_points() {
        for (w, h) in [(80, 24), (120, 40), (160, 48)] {
            let area = Rect::new(0, 0, w, h);
            let s = screen(area).unwrap();
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

    #[test]
    fn one_chart_on_small_screens_all_three_on_big_ones() {
        let small = layout(Rect::new(0, 0, 80, 24), ChartKind::ForceTime).unwrap();
        assert_eq!(small.charts.len(), 1);
        assert_eq!(small.charts[0].0, ChartKind::ForceTime, "the chosen chart");
        assert!(!small.roomy);
        let big = layout(Rect::new(0, 0, 160, 48), ChartKind::ForceTime).unwrap();
        let kinds: Vec<_> = big.charts.iter().map(|(k, _)| *k).collect();
        assert_eq!(
            kinds,
            [
                ChartKind::ForceDisplacement,
                ChartKind::VelocityDisplacement,
                ChartKind::ForceTime
            ]
        );
        assert!(big.roomy);
    }
}
