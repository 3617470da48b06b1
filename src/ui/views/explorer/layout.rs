//! Where the explorer's panes go: the regime box on top, the form and the models on the left, the
//! charts over the results on the right.

use ratatui::layout::{Constraint, Layout, Rect};

use crate::ui::MarkerStyle;
use crate::chart::kind::ChartKind;
use crate::ui::layout::{ScreenLayout, Y_AXIS_ALLOWANCE, left_width, screen_layout};
use crate::chart::sample::ChartDots;
use crate::ui::widgets::{graph, models};

/// The least height of the models pane on a roomy screen.
pub const MODELS_HEIGHT: u16 = 7;

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

/// The panes of a screen of `area`, with `first` the chart shown where only one fits;
/// `form_height(width)` is the height the form's panes need at rest at that width: on roomy
/// screens the models pane takes what the form leaves (at least [`MODELS_HEIGHT`] rows).
pub fn layout(area: Rect, first: ChartKind, form_height: impl Fn(u16) -> u16) -> Option<Areas> {
    let ScreenLayout {
        tabs,
        body,
        status,
        roomy,
    } = screen_layout(area)?;
    let info_height = if roomy { 6 } else { 3 };
    let [info, body] =
        Layout::vertical([Constraint::Length(info_height), Constraint::Fill(1)]).areas(body);
    let [left, right] =
        Layout::horizontal([Constraint::Length(left_width(area)), Constraint::Fill(1)]).areas(body);
    let models_height = if roomy {
        // Two spare rows for a field's description or error under the cursor.
        let spare = left
            .height
            .saturating_sub(form_height(left.width).saturating_add(2));
        spare.min(models::row_count() + 2).max(MODELS_HEIGHT)
    } else {
        8
    };
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

/// Dots across the widest plot each chart gets on a screen of `area`, and down the tallest (with
/// `marker`'s dots a cell), whichever chart is shown first; `None` where the explorer does not fit.
pub fn chart_dots(area: Rect, marker: MarkerStyle) -> Option<ChartDots> {
    let mut dots = ChartDots {
        time: 0,
        approach: 0,
        high: 0,
    };
    for first in ChartKind::ALL {
        let areas = layout(area, first, |_| 0)?;
        // The pane's side borders (roomy) and the y labels and axis line.
        let frame = if areas.roomy { 2 } else { 0 } + Y_AXIS_ALLOWANCE;
        // The pane's top and bottom borders (roomy), then the title and axis rows.
        let rims = if areas.roomy { 2 } else { 0 };
        for (kind, rect) in areas.charts {
            let rows = graph::plot_rows(rect.height.saturating_sub(rims));
            let high = u32::from(rows) * u32::from(marker.dots_per_row());
            dots.high = dots.high.max(high);
            let across =
                u32::from(rect.width.saturating_sub(frame)) * u32::from(marker.dots_per_cell());
            let widest = match kind {
                ChartKind::ForceTime => &mut dots.time,
                ChartKind::ForceDisplacement | ChartKind::VelocityDisplacement => {
                    &mut dots.approach
                }
            };
            *widest = (*widest).max(across);
        }
    }
    Some(dots)
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
    use crate::ui::layout::tests::inside;

    /// The chart sampling's own tests measure their lines on the plots this layout gives at
    /// 160×48 (`chart::sample`'s fixture): they must be the same.
    #[test]
    fn the_chart_samples_are_measured_on_this_layouts_plots() {
        let dots = chart_dots(Rect::new(0, 0, 160, 48), MarkerStyle::Braille).expect("160×48 fits");
        assert_eq!(dots, crate::chart::sample::tests::EXPLORER_160X48);
        assert_eq!(dots.stride(), crate::chart::sample::STRIDE);
    }

    #[test]
    fn the_models_pane_takes_what_the_form_leaves_up_to_its_list() {
        let area = Rect::new(0, 0, 160, 48);
        let tall_form = layout(area, ChartKind::ForceTime, |_| 40).unwrap();
        assert_eq!(tall_form.models.height, MODELS_HEIGHT);
        let short_form = layout(area, ChartKind::ForceTime, |_| 26).unwrap();
        assert_eq!(short_form.form.height, 26 + 2, "the form's rows and two spare");
        assert_eq!(short_form.models.height, 40 - 28);
        let tiny_form = layout(area, ChartKind::ForceTime, |_| 3).unwrap();
        assert_eq!(tiny_form.models.height, models::row_count() + 2);
    }

    /// The plots' widths less the y labels and axis (7 columns) and, on roomy screens, the
    /// borders: at 160×48 F(t) spans the right-hand column under F(x) and v(x); at 100×30 two
    /// charts share it and either kind may be in the wider one.
    #[test]
    fn charts_are_sampled_for_their_widest_plots() {
        let at = |w, h, per_cell| {
            let marker = if per_cell == 2 {
                MarkerStyle::Braille
            } else {
                MarkerStyle::Dot
            };
            chart_dots(Rect::new(0, 0, w, h), marker)
        };
        let big = layout(Rect::new(0, 0, 160, 48), ChartKind::ForceTime, |_| 30).unwrap();
        let f_t = big.charts.iter().find(|(k, _)| *k == ChartKind::ForceTime).unwrap();
        let f_x = big.charts.iter().find(|(k, _)| *k == ChartKind::ForceDisplacement).unwrap();
        assert_eq!(
            at(160, 48, 2),
            Some(ChartDots {
                time: 2 * u32::from(f_t.1.width - 9),
                approach: 2 * u32::from(f_x.1.width - 9),
                high: 4 * u32::from(graph::plot_rows(f_x.1.height - 2)),
            })
        );
        assert_eq!(at(160, 48, 1).unwrap().time, u32::from(f_t.1.width - 9));
        let two = layout(Rect::new(0, 0, 100, 30), ChartKind::ForceTime, |_| 30).unwrap();
        let widest = two.charts.iter().map(|(_, r)| r.width).max().unwrap();
        let dots = at(100, 30, 2).unwrap();
        assert_eq!(dots.time, dots.approach);
        assert_eq!(dots.time, 2 * u32::from(widest - 7), "compact: no side borders");
        assert_eq!(at(79, 24, 2), None);
    }

    #[test]
    fn too_small_has_no_layout() {
        assert!(layout(Rect::new(0, 0, 79, 24), ChartKind::ForceTime, |_| 30).is_none());
        assert!(layout(Rect::new(0, 0, 80, 23), ChartKind::ForceTime, |_| 30).is_none());
        assert!(layout(Rect::new(0, 0, 80, 24), ChartKind::ForceTime, |_| 30).is_some());
    }

    #[test]
    fn panes_fit_and_do_not_overlap() {
        for (w, h) in [(80, 24), (100, 30), (120, 40), (160, 48), (250, 80)] {
            let area = Rect::new(0, 0, w, h);
            let a = layout(area, ChartKind::ForceDisplacement, |_| 30).unwrap();
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
    fn one_chart_on_small_screens_all_three_on_big_ones() {
        let small = layout(Rect::new(0, 0, 80, 24), ChartKind::ForceTime, |_| 30).unwrap();
        assert_eq!(small.charts.len(), 1);
        assert_eq!(small.charts[0].0, ChartKind::ForceTime, "the chosen chart");
        assert!(!small.roomy);
        let big = layout(Rect::new(0, 0, 160, 48), ChartKind::ForceTime, |_| 30).unwrap();
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
