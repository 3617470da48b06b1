//! Charts whose numbers can be read: in every view, at 80×24, 120×40 and 160×48, a known value
//! (a model's x_max and F_max, a yield-onset velocity, the explorer's solve on the work-precision
//! chart) is drawn within one cell of where the chart's own tick labels put it. Everything is read
//! back from the rendered buffer: the axis lines, the labels and the glyph.

use hertz_tui::chart::sweep as sweep_plot;
use hertz_tui::chart::work_precision::{self as wp_plot, Cost};
use hertz_tui::model::ForceModel;
use hertz_tui::ui::action::Action;
use hertz_tui::ui::app::{App, ChartKind};
use hertz_tui::ui::tab::Tab;
use hertz_tui::ui::update::update;
use ratatui::buffer::Buffer;

use super::render::{app, render, settle};

const SIZES: [(u16, u16); 3] = [(80, 24), (120, 40), (160, 48)];

/// One chart found in the buffer: its plot cells and its labels.
#[derive(Debug)]
pub(super) struct Found {
    /// Plot columns x0..x1 and rows y0..y1 (exclusive ends).
    pub(super) x0: u16,
    pub(super) x1: u16,
    pub(super) y0: u16,
    pub(super) y1: u16,
    /// (value, centre column) of each x label, (value, row) of each y label.
    pub(super) xs: Vec<(f64, u16)>,
    pub(super) ys: Vec<(f64, u16)>,
    /// Text around the chart: its axis titles.
    pub(super) titles: String,
}

pub(super) fn sym(buf: &Buffer, x: u16, y: u16) -> &str {
    buf[(x, y)].symbol()
}

fn row_text(buf: &Buffer, y: u16, from: u16, to: u16) -> String {
    (from..to.min(buf.area.width))
        .map(|x| sym(buf, x, y))
        .collect()
}

/// Number tokens in a row between columns: (value, first column, length).
fn numbers(buf: &Buffer, y: u16, from: u16, to: u16) -> Vec<(f64, u16, u16)> {
    let mut out = Vec::new();
    let mut token = String::new();
    let mut start = 0;
    for x in from..=to.min(buf.area.width) {
        let s = if x < buf.area.width {
            sym(buf, x, y)
        } else {
            " "
        };
        let numeric = s.len() == 1 && s.chars().all(|c| c.is_ascii_digit() || ".-e+".contains(c));
        if numeric {
            if token.is_empty() {
                start = x;
            }
            token.push_str(s);
        } else if !token.is_empty() {
            if let Ok(v) = token.parse::<f64>() {
                out.push((v, start, token.len() as u16));
            }
            token.clear();
        }
    }
    out
}

/// Every chart in the buffer: an axis corner `└` with a run of `─`/`┴` to its right holding
/// tick marks, and `│`/`┤` above it.
pub(super) fn charts(buf: &Buffer) -> Vec<Found> {
    let mut found = Vec::new();
    let area = buf.area;
    for cy in 1..area.height.saturating_sub(1) {
        for cx in 0..area.width {
            if sym(buf, cx, cy) != "└" || !matches!(sym(buf, cx, cy - 1), "│" | "┤") {
                continue;
            }
            let mut x1 = cx + 1;
            let mut ticks = 0;
            while x1 < area.width && matches!(sym(buf, x1, cy), "─" | "┴") {
                ticks += usize::from(sym(buf, x1, cy) == "┴");
                x1 += 1;
            }
            if ticks < 2 {
                continue;
            }
            let mut y0 = cy;
            while y0 > 0 && matches!(sym(buf, cx, y0 - 1), "│" | "┤") {
                y0 -= 1;
            }
            let xs = numbers(buf, cy + 1, cx.saturating_sub(6), x1 + 6)
                .into_iter()
                .map(|(v, first, len)| (v, first + (len - 1) / 2))
                // A neighbouring chart's last label is not this chart's.
                .filter(|&(_, centre)| cx < centre && centre < x1 + 1)
                .collect();
            let ys = (y0..cy)
                .filter(|&y| sym(buf, cx, y) == "┤")
                .filter_map(|y| {
                    numbers(buf, y, cx.saturating_sub(8), cx)
                        .last()
                        .map(|&(v, _, _)| (v, y))
                })
                .collect();
            let mut titles = row_text(buf, y0 - 1, cx.saturating_sub(8), x1 + 6);
            if cy + 2 < area.height {
                titles.push_str(&row_text(buf, cy + 2, cx, x1 + 6));
            }
            found.push(Found {
                x0: cx + 1,
                x1,
                y0,
                y1: cy,
                xs,
                ys,
                titles,
            });
        }
    }
    found
}

/// Where the labels put `v` along an axis: interpolated between the labels around it, in
/// log₁₀ of the labels on a log axis.
pub(super) fn by_labels(labels: &[(f64, u16)], v: f64, log: bool) -> f64 {
    let f = |x: f64| if log { x.log10() } else { x };
    let pair = labels
        .windows(2)
        .find(|w| {
            let (a, b) = (f(w[0].0), f(w[1].0));
            a.min(b) <= f(v) && f(v) <= a.max(b)
        })
        .unwrap_or_else(|| panic!("{v} is not between the labels {labels:?}"));
    let (a, b) = (pair[0], pair[1]);
    f64::from(a.1) + (f(v) - f(a.0)) / (f(b.0) - f(a.0)) * (f64::from(b.1) - f64::from(a.1))
}

/// Asserts a cell showing `glyph` within one cell of where the labels put (x, y).
fn assert_drawn_at(buf: &Buffer, chart: &Found, glyph: &str, (x, y): (f64, f64), log_x: bool) {
    assert!(chart.xs.len() >= 2 && chart.ys.len() >= 2, "{chart:?}");
    let col = by_labels(&chart.xs, x, log_x);
    let row = by_labels(&chart.ys, y, false);
    let near = (chart.y0..chart.y1)
        .flat_map(|r| (chart.x0..chart.x1).map(move |c| (c, r)))
        .filter(|&(c, r)| sym(buf, c, r) == glyph)
        .map(|(c, r)| (f64::from(c) - col).abs().max((f64::from(r) - row).abs()))
        .fold(f64::INFINITY, f64::min);
    assert!(
        near <= 1.0 + 1e-9,
        "{glyph} at ({x}, {y}): labels put it at column {col:.1}, row {row:.1}; nearest {glyph} \
         is {near} cells off in {chart:?}"
    );
}

fn sized(mut app: App, tab: Tab, (w, h): (u16, u16)) -> App {
    update(&mut app, Action::Resize(w, h));
    update(&mut app, Action::Tab(tab));
    settle(&mut app);
    app
}

/// The chart whose titles hold every one of `words`.
pub(super) fn chart_titled<'a>(charts: &'a [Found], words: &[&str]) -> Option<&'a Found> {
    charts
        .iter()
        .find(|c| words.iter().all(|w| c.titles.contains(w)))
}

#[test]
fn explorer_peaks_lie_where_the_ticks_say() {
    for size in SIZES {
        let mut app = sized(app(), Tab::HOME, size);
        let solution = app
            .solutions
            .solution(ForceModel::Proposed)
            .unwrap()
            .clone();
        let s = &solution.summary;
        let x_at_peak = solution.trajectory.at(s.t_f_max).x;
        let mut seen = 0;
        for kind in ChartKind::ALL {
            app.views.explorer.chart = kind;
            let terminal = render(&app, size.0, size.1);
            let buf = terminal.backend().buffer();
            let found = charts(buf);
            let (words, point): (&[&str], _) = match kind {
                ChartKind::ForceDisplacement => (&["F [N]", "x [µm]"], (x_at_peak * 1e6, s.f_max)),
                ChartKind::ForceTime => (&["F [N]", "t [µs]"], (s.t_f_max * 1e6, s.f_max)),
                ChartKind::VelocityDisplacement => (&["v [m/s]", "x [µm]"], (s.x_max * 1e6, 0.0)),
            };
            let chart = chart_titled(&found, words)
                .unwrap_or_else(|| panic!("{kind:?} at {size:?}: {found:?}"));
            assert_drawn_at(buf, chart, "*", point, false);
            seen += 1;
        }
        assert_eq!(seen, 3);
    }
}

#[test]
fn sweep_onset_rules_lie_where_the_ticks_say() {
    for size in SIZES {
        let app = sized(app(), Tab::named("sweep").unwrap(), size);
        let data = match app.studies.sweep() {
            Some(Ok(data)) => data.clone(),
            other => panic!("{other:?}"),
        };
        let (v_y, v_p) = sweep_plot::onset(&data).unwrap();
        let terminal = render(&app, size.0, size.1);
        let buf = terminal.backend().buffer();
        let found = charts(buf);
        let chart = chart_titled(&found, &["v₀ [m/s]"]).expect("the sweep chart");
        for (label, v) in [("v_y", v_y), ("v_p", v_p)] {
            let top = row_text(buf, chart.y0, chart.x0, chart.x1);
            let at = top
                .find(label)
                .unwrap_or_else(|| panic!("{label} in {top:?}"));
            let start = chart.x0 + top[..at].chars().count() as u16;
            // The label stands right of its rule, or left of it where there is no room.
            let rule = if start > chart.x0 && sym(buf, start - 1, chart.y0) != " " {
                start - 1
            } else {
                start + 3
            };
            let col = by_labels(&chart.xs, v, true);
            assert!(
                (f64::from(rule) - col).abs() <= 1.0,
                "{label} = {v} at column {rule}, labels say {col:.1}: {chart:?}"
            );
        }
    }
}

#[test]
fn work_precision_marks_the_explorers_solve_where_the_ticks_say() {
    for size in SIZES {
        let mut app = sized(app(), Tab::named("work-precision").unwrap(), size);
        let current = match app.studies.current() {
            Some(Ok(point)) => point.clone(),
            other => panic!("{other:?}"),
        };
        for cost in [Cost::Seconds, Cost::ForceEvals] {
            app.views.work_precision.cost = cost;
            let terminal = render(&app, size.0, size.1);
            let buf = terminal.backend().buffer();
            let found = charts(buf);
            let chart = chart_titled(&found, &[cost.title()])
                .unwrap_or_else(|| panic!("{cost:?} at {size:?}: {found:?}"));
            let at = wp_plot::current(&current, cost).unwrap();
            assert_drawn_at(buf, chart, "█", at, false);
        }
    }
}

#[test]
fn stability_reference_peak_lies_where_the_ticks_say() {
    for size in SIZES {
        let app = sized(app(), Tab::named("stability").unwrap(), size);
        let data = match app.studies.runs() {
            Some(Ok(data)) => data.clone(),
            other => panic!("{other:?}"),
        };
        let s = &data.reference.summary;
        let x_at_peak = data.reference.trajectory.at(s.t_f_max).x;
        let terminal = render(&app, size.0, size.1);
        let buf = terminal.backend().buffer();
        let found = charts(buf);
        let fx = chart_titled(&found, &["F [N]", "x [µm]"]).expect("F(x)");
        assert_drawn_at(buf, fx, "=", (x_at_peak * 1e6, s.f_max), false);
        let vx = chart_titled(&found, &["v [m/s]", "x [µm]"]).expect("v(x)");
        assert_drawn_at(buf, vx, "=", (s.x_max * 1e6, 0.0), false);
    }
}

#[test]
fn fit_data_and_best_curve_lie_where_the_ticks_say() {
    use hertz_tui::chart::model_glyph;
    use hertz_tui::model::fit::Candidate;
    for size in SIZES {
        let mut app = app();
        hertz_tui::ui::views::fit::open(
            &mut app,
            std::path::Path::new("presets/data/steel-hunt-crossley.csv"),
        );
        let app = sized(app, Tab::named("fit").unwrap(), size);
        let (fit, report) = hertz_tui::ui::views::fit::finished(&app).expect("fitted");
        let best = &report.fits[0];
        assert_eq!(best.candidate, Candidate::Law(ForceModel::HuntCrossley));
        let terminal = render(&app, size.0, size.1);
        let buf = terminal.backend().buffer();
        let found = charts(buf);
        let chart = chart_titled(&found, &["v₀ [m/s]"]).expect("the e(v₀) chart");
        // Every measured point: its mark where the ticks put it (v on a log axis).
        for p in &fit.data.points {
            assert_drawn_at(buf, chart, "O", (p.v, p.e), true);
        }
        // The best law's curve ends in its glyph where the ticks put its last point, which is
        // the law's own e there (the table's parameter through the forward model).
        let glyph = model_glyph(ForceModel::HuntCrossley).to_string();
        let curve = &fit.curves[0];
        let &(v, e) = curve.points.last().unwrap();
        let scene = app.valid.as_ref().unwrap().scene.clone();
        let predicted = best.predict(&scene, v).unwrap();
        assert!((predicted - e).abs() < 1e-9, "{predicted} against {e}");
        assert_drawn_at(buf, chart, &glyph, (v, e), true);
        // The residuals: the best law's last residual where the ticks put it.
        let residuals = found
            .iter()
            .find(|c| c.x0 > chart.x1)
            .expect("the residual chart right of the data");
        let last = fit
            .data
            .points
            .iter()
            .zip(&best.residuals)
            .max_by(|a, b| a.0.v.total_cmp(&b.0.v))
            .map(|(p, r)| (p.v, *r))
            .unwrap();
        assert_drawn_at(buf, residuals, &glyph, last, true);
    }
}
