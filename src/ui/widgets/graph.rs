//! The terminal back-end of [`crate::chart`]: a chart painted cell by cell. The axes, ticks and
//! labels are drawn here rather than by ratatui's `Chart` (which spreads labels evenly whatever
//! their values), so each label is centred on the cell its value falls in, by the same rounding
//! the curves are drawn with. Axis titles go outside the plot: the y title above it, the x title
//! below the tick labels.

use ratatui::Frame;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::Block;

use crate::chart::layout::dot;
use crate::chart::{Chart, Ink, place_ticks};
use crate::ui::style::MarkerStyle;
use crate::ui::style::{Role, Theme, sample};

use super::common::wrap;
use super::dots::Dots;
use super::strokes::{Stroke, key_of, paint, trace};

/// Where the parts of a chart go inside its frame.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ChartFrame {
    /// Where the curves are drawn.
    pub plot: Rect,
    /// Width of the y tick labels, left of the axis line.
    pub y_labels: u16,
    /// Whether the x title has a row of its own under the tick labels (else it shares the y
    /// title's row above the plot, on the right).
    pub x_title_below: bool,
}

fn width(text: &str) -> u16 {
    text.chars().count() as u16
}

/// Tick budgets for a plot of about `columns` × `rows` cells: labels need a few columns each and
/// a blank row between them.
pub fn budget(columns: u16, rows: u16) -> (usize, usize) {
    (
        usize::from(columns / 7).clamp(2, 11),
        (usize::from(rows.saturating_sub(1)) / 2 + 1).clamp(2, 8),
    )
}

/// Rows inside a chart's pane from which the x title gets a row of its own under the tick labels.
const X_TITLE_BELOW: u16 = 12;

/// Rows of the plot in a chart pane `inner_height` rows high: less the y title's row above it and
/// the axis line, tick labels (and x title, where there is height) below it, as [`frame_of`] lays
/// them out.
pub fn plot_rows(inner_height: u16) -> u16 {
    let bottom = if inner_height >= X_TITLE_BELOW { 3 } else { 2 };
    inner_height.saturating_sub(1 + bottom)
}

/// The plot area inside `inner` for `chart`: the y title row on top, the y tick labels and axis
/// line on the left, the axis line, tick labels (and the x title where there is height) below,
/// and half the last x label's width on the right so it is not cut.
pub fn frame_of(inner: Rect, chart: &Chart) -> ChartFrame {
    let y_labels = chart
        .y
        .ticks
        .iter()
        .map(|t| width(&t.label))
        .max()
        .unwrap_or(1)
        .min(inner.width / 3);
    let x_title_below = inner.height >= X_TITLE_BELOW;
    let right = chart.x.ticks.last().map_or(0, |t| width(&t.label) / 2);
    let left = y_labels + 1;
    let plot = Rect::new(
        inner.x + left.min(inner.width),
        inner.y + 1.min(inner.height),
        inner.width.saturating_sub(left + right),
        plot_rows(inner.height),
    );
    ChartFrame {
        plot,
        y_labels,
        x_title_below,
    }
}

/// Dots per cell across and down for `marker`.
fn dots(marker: MarkerStyle) -> (u16, u16) {
    match marker {
        MarkerStyle::Braille => (2, 4),
        MarkerStyle::Dot | MarkerStyle::Block => (1, 1),
    }
}

/// The cell (column, row) of display point `p` in `plot`, if it lies on both axes.
pub fn cell_of(
    chart: &Chart,
    plot: Rect,
    marker: MarkerStyle,
    p: (f64, f64),
) -> Option<(u16, u16)> {
    let (dx, dy) = dots(marker);
    let col = dot(&chart.x, p.0, plot.width, dx)? / u32::from(dx);
    let row = dot(&chart.y, p.1, plot.height, dy)? / u32::from(dy);
    Some((plot.x + col as u16, plot.bottom() - 1 - row as u16))
}

/// How curves are told apart: by colour on braille, by glyphs where there is no colour or no
/// braille (each model's glyph along the whole curve).
fn glyphs_along(theme: Theme, marker: MarkerStyle) -> bool {
    !theme.color() || marker != MarkerStyle::Braille
}

/// Cells between the glyphs set along a curve when colour cannot tell curves apart.
const GLYPH_SPACING: f64 = 6.0;

/// The style of `ink`, bold or dim.
fn styled(theme: Theme, ink: Ink, bold: bool, dim: bool) -> Style {
    let mut style = theme.ink(ink);
    if bold {
        style = style.add_modifier(Modifier::BOLD);
    }
    if dim {
        style = style.add_modifier(Modifier::DIM);
    }
    style
}

/// Where display point `p` falls on a plot of `dots` dots across and down, in fractional dots
/// from the bottom left (NaN for a non-finite point).
fn dot_of(chart: &Chart, dots: (f64, f64), p: (f64, f64)) -> (f64, f64) {
    (
        chart.x.fraction(p.0) * (dots.0 - 1.0),
        chart.y.fraction(p.1) * (dots.1 - 1.0),
    )
}

/// The glyphs drawn over the dots, in drawing order (a later one over an earlier one in its
/// cell): along each curve every [`GLYPH_SPACING`] cells where colour cannot tell curves apart,
/// at every point of a fixed-step series, at peaks and ends (the focused series' last), then the
/// marks.
fn glyphs(chart: &Chart, plot: Rect, theme: Theme, marker: MarkerStyle) -> Vec<GlyphAt> {
    let (dx, dy) = dots(marker);
    let dots = (
        f64::from(plot.width) * f64::from(dx),
        f64::from(plot.height) * f64::from(dy),
    );
    let spacing = glyphs_along(theme, marker).then_some(GLYPH_SPACING * f64::from(dx));
    let cell = |p: (f64, f64)| cell_of(chart, plot, marker, p);
    let mut out = Vec::new();
    for series in &chart.series {
        if spacing.is_none() && !series.steps {
            // No glyph along this curve: its points need not be walked.
            continue;
        }
        let glyph = |at: (u16, u16)| (at, series.glyph, series.ink, series.focused);
        for run in &series.runs {
            let mut last: Option<(f64, f64)> = None;
            let mut travelled = spacing.unwrap_or(0.0) / 2.0;
            for &p in run.iter().filter(|p| p.0.is_finite() && p.1.is_finite()) {
                let at = dot_of(chart, dots, p);
                if let (Some(spacing), Some(from)) = (spacing, last) {
                    // Distance in cells' aspect: a dot down is half a dot across.
                    travelled += (at.0 - from.0).hypot((at.1 - from.1) * 0.5);
                    if travelled >= spacing {
                        travelled = 0.0;
                        out.extend(cell(p).map(glyph));
                    }
                }
                last = Some(at);
                if series.steps {
                    out.extend(cell(p).map(glyph));
                }
            }
        }
    }
    for series in &chart.series {
        for p in series.peak.iter().copied().chain(series.end()) {
            out.extend(cell(p).map(|at| (at, series.glyph, series.ink, series.focused)));
        }
    }
    for mark in &chart.marks {
        out.extend(cell(mark.at).map(|at| (at, mark.glyph, mark.ink, true)));
    }
    out
}

/// A glyph in a cell of the frame, in an ink, bold or not.
type GlyphAt = ((u16, u16), char, Ink, bool);

/// The rules (dotted: every other dot, so curves crossing them stay visible) and the curves, on
/// the plot's dots, each cell in the style of the ink painted last in it, and the glyphs over
/// them.
fn plot(buf: &mut Buffer, chart: &Chart, plot: Rect, theme: Theme, marker: MarkerStyle) {
    let increasing = |[lo, hi]: [f64; 2]| lo.is_finite() && hi.is_finite() && hi > lo;
    if !increasing(chart.x.range) || !increasing(chart.y.range) {
        // No value has a place on the plot.
        return;
    }
    let (dx, dy) = dots(marker);
    let dots = (
        f64::from(plot.width) * f64::from(dx),
        f64::from(plot.height) * f64::from(dy),
    );
    let mut rules = Vec::new();
    for rule in &chart.rules {
        let [a, b] = rule.ends(chart);
        let (da, db) = (dot_of(chart, dots, a), dot_of(chart, dots, b));
        let steps = (db.0 - da.0).max(db.1 - da.1).max(0.0) as u32 / 2;
        let points: Vec<(f64, f64)> = (0..=steps)
            .map(|k| {
                let s = f64::from(k) / f64::from(steps.max(1));
                (a.0 + (b.0 - a.0) * s, a.1 + (b.1 - a.1) * s)
            })
            .collect();
        rules.push((points, (rule.ink, false)));
    }
    // Each curve's dots in its pattern, painted with each cell shared by curves left to one of
    // them.
    let grid = (plot.width * dx, plot.height * dy);
    let to_grid = |p: (f64, f64)| {
        let (x, y) = dot_of(chart, dots, p);
        (x, dots.1 - 1.0 - y)
    };
    let strokes: Vec<Stroke> = chart
        .series
        .iter()
        .map(|series| {
            // About a dot a point or more: room for twice as many grows the list at most once.
            let points: usize = series.runs.iter().map(Vec::len).sum();
            let mut drawn = Vec::with_capacity(2 * points);
            for run in &series.runs {
                trace(
                    run.iter().map(|&p| to_grid(p)),
                    series.ink.dash(),
                    grid,
                    &mut drawn,
                );
            }
            Stroke {
                ink: (series.ink, series.focused),
                key: key_of(&series.name),
                dots: drawn,
            }
        })
        .collect();
    let mut painted = Dots::new((plot.width, plot.height), marker);
    for (points, ink) in &rules {
        for &p in points {
            if let Some((x, y)) = painted.dot_of(chart.x.range, chart.y.range, p) {
                painted.paint(x, y, *ink);
            }
        }
    }
    paint(&strokes, &mut painted);
    let area = Rect::new(0, 0, plot.width, plot.height);
    let mut over = vec![None; usize::from(plot.width) * usize::from(plot.height)];
    for ((x, y), glyph, ink, bold) in glyphs(chart, plot, theme, marker) {
        let i = usize::from(y - plot.y) * usize::from(plot.width) + usize::from(x - plot.x);
        if let Some(slot) = over.get_mut(i) {
            *slot = Some((glyph, ink, bold));
        }
    }
    // Without braille or colour the dots are only the line between glyphs: keep them light so
    // the glyphs read.
    let dim_dots = glyphs_along(theme, marker) && marker != MarkerStyle::Braille;
    for (i, position) in area.positions().enumerate() {
        let at = (plot.x + position.x, plot.y + position.y);
        if let Some(Some((glyph, ink, bold))) = over.get(i) {
            buf[at]
                .set_char(*glyph)
                .set_style(styled(theme, *ink, *bold, false));
        } else if let Some((symbol, (ink, bold))) = painted.cell(i) {
            let style = styled(theme, ink, bold && !dim_dots, dim_dots);
            buf[at].set_char(symbol).set_style(style);
        }
    }
}

fn put(buf: &mut Buffer, x: u16, y: u16, text: &str, style: Style, limit: Rect) {
    for (x, ch) in (x..).zip(text.chars()) {
        if x >= limit.right() || y >= limit.bottom() || x < limit.x || y < limit.y {
            break;
        }
        buf[(x, y)].set_char(ch).set_style(style);
    }
}

/// The axis lines with a tick mark at each label, and the labels centred on their cells.
fn axes(
    buf: &mut Buffer,
    chart: &Chart,
    inner: Rect,
    f: &ChartFrame,
    theme: Theme,
    marker: MarkerStyle,
) {
    let plot = f.plot;
    let (dx, dy) = dots(marker);
    let line = theme.style(Role::Muted);
    let text = theme.style(Role::Normal);
    let axis_x = plot.x - 1;
    let axis_y = plot.bottom();
    for y in plot.y..plot.bottom() {
        put(buf, axis_x, y, "│", line, inner);
    }
    let x_axis = format!("└{}", "─".repeat(usize::from(plot.width)));
    put(buf, axis_x, axis_y, &x_axis, line, inner);
    for t in place_ticks(&chart.y, plot.height, dy, |_| 1) {
        let y = plot.bottom() - 1 - t.cell;
        put(buf, axis_x, y, "┤", line, inner);
        let w = width(&t.label).min(f.y_labels);
        put(buf, inner.x + f.y_labels - w, y, &t.label, text, inner);
    }
    for t in place_ticks(&chart.x, plot.width, dx, width) {
        let x = plot.x + t.cell;
        put(buf, x, axis_y, "┴", line, inner);
        let start = x.saturating_sub((width(&t.label).saturating_sub(1)) / 2);
        put(buf, start.max(inner.x), axis_y + 1, &t.label, text, inner);
    }
    let title = theme.style(Role::Label).add_modifier(Modifier::BOLD);
    put(buf, inner.x, inner.y, &chart.y.title, title, inner);
    let x_title = width(&chart.x.title);
    let room = readout_room(inner, chart);
    if let Some(readout) = &chart.readout
        && let Some((text, form)) = readout.line(usize::from(room))
    {
        let x = inner.x + width(&chart.y.title) + 2;
        // The cursor's reading takes the row above the plot after the y title where it fits on
        // one line (else it is a box on the plot: `readout_box`), each curve's name in its ink.
        put(buf, x, inner.y, &text, theme.style(Role::Normal), inner);
        let mut name_x = x + width(&readout.at) + 3;
        for curve in &readout.curves {
            let name: String = curve
                .text(form)
                .chars()
                .take(curve.name_len(form))
                .collect();
            put(buf, name_x, inner.y, &name, theme.ink(curve.ink), inner);
            name_x += width(&curve.text(form)) + 3;
        }
        if f.x_title_below {
            let x = inner.right().saturating_sub(x_title);
            put(buf, x, axis_y + 2, &chart.x.title, title, inner);
        } else if width(&text) + 2 + x_title < room {
            // The x title keeps its place right of the reading where both fit.
            let x = inner.right().saturating_sub(x_title + 1);
            put(buf, x, inner.y, &chart.x.title, title, inner);
        }
        return;
    }
    if f.x_title_below {
        let x = inner.right().saturating_sub(x_title);
        put(buf, x, axis_y + 2, &chart.x.title, title, inner);
    } else if width(&chart.y.title) + 3 + x_title <= inner.width {
        // A blank column after it, so it never runs into a neighbouring chart's title.
        let x = inner.right().saturating_sub(x_title + 1);
        put(buf, x, inner.y, &chart.x.title, title, inner);
    }
}

/// Labels of the rules beside their line on the plot's top row, marks' labels beside their
/// glyph (none that the data cursor's reading box, `hidden`, would cover in part), notes under it.
fn labels(
    buf: &mut Buffer,
    chart: &Chart,
    f: &ChartFrame,
    (theme, marker): (Theme, MarkerStyle),
    hidden: Option<Rect>,
) {
    let plot = f.plot;
    let covered =
        |x: u16, y: u16, w: u16| hidden.is_some_and(|h| h.intersects(Rect::new(x, y, w.max(1), 1)));
    for rule in &chart.rules {
        let [_, end] = rule.ends(chart);
        let Some((col, row)) = cell_of(chart, plot, marker, end) else {
            continue;
        };
        let w = width(&rule.label);
        if rule.horizontal {
            // At the right end, on the rule's row.
            let x = plot.right().saturating_sub(w).max(plot.x);
            if !covered(x, row, w) {
                put(buf, x, row, &rule.label, theme.ink(rule.ink), plot);
            }
            continue;
        }
        let x = if col + 1 + w <= plot.right() {
            col + 1
        } else if col >= plot.x + w {
            col - w
        } else {
            continue;
        };
        if !covered(x, plot.y, w) {
            put(buf, x, plot.y, &rule.label, theme.ink(rule.ink), plot);
        }
    }
    for mark in &chart.marks {
        let (Some(label), Some((col, row))) = (&mark.label, cell_of(chart, plot, marker, mark.at))
        else {
            continue;
        };
        let w = width(label);
        let x = if col + 2 + w <= plot.right() {
            col + 2
        } else {
            col.saturating_sub(w + 1)
        };
        if !covered(x, row, w) {
            put(buf, x, row, label, theme.ink(mark.ink), plot);
        }
    }
    // Notes wrapped to the plot's width from its second row, where they leave two thirds of the
    // plot to the curves; else one line naming what has no curve.
    let lines: Vec<String> = chart
        .notes
        .iter()
        .flat_map(|note| wrap(note, usize::from(plot.width.saturating_sub(2))))
        .collect();
    let lines = if lines.len() <= usize::from(plot.height / 3) {
        lines
    } else {
        let names: Vec<&str> = chart
            .notes
            .iter()
            .map(|n| n.trim_start_matches("✗ ").split(':').next().unwrap_or(n))
            .collect();
        wrap(
            &format!("✗ no curve: {}", names.join(", ")),
            usize::from(plot.width.saturating_sub(2)),
        )
    };
    for (y, line) in (plot.y + 1..plot.bottom()).zip(lines) {
        put(buf, plot.x + 1, y, &line, theme.style(Role::Error), plot);
    }
}

/// The data cursor's reading as a box on the plot: where, its rows, their name form, and the
/// `+N more` row where the plot has fewer rows than curves.
struct ReadoutBox {
    rect: Rect,
    rows: Vec<String>,
    form: usize,
    more: Option<String>,
}

/// Where the data cursor's reading goes when it does not fit the row above the plot: a box on the
/// plot's top, on the side away from the cursor's rule, with a blank column either side; `None`
/// where it fits that row (or there is no reading).
fn readout_box(
    chart: &Chart,
    inner: Rect,
    f: &ChartFrame,
    marker: MarkerStyle,
) -> Option<ReadoutBox> {
    let readout = chart.readout.as_ref()?;
    let plot = f.plot;
    if readout
        .line(usize::from(readout_room(inner, chart)))
        .is_some()
        || plot.height < 2
    {
        return None;
    }
    // At most half the plot's width, but room for the names' abbreviations and values.
    let widest = |form: usize| {
        (0..readout.curves.len())
            .map(|i| readout.curves[i].text(form).chars().count())
            .chain([readout.at.chars().count()])
            .max()
            .unwrap_or(0)
    };
    let want = (0..readout.forms())
        .map(widest)
        .find(|&w| w <= usize::from(plot.width / 2));
    let text_width = want
        .unwrap_or(usize::MAX)
        .min(usize::from(plot.width.saturating_sub(2)));
    let (mut rows, form) = readout.rows(text_width);
    let height = usize::from(plot.height);
    let mut more = None;
    if rows.len() > height {
        let left = rows.len() - (height - 1);
        rows.truncate(height - 1);
        more = Some(format!("+{left} more"));
    }
    // Away from the cursor's rule: on the right when the rule is in the left half.
    let rule_col = chart
        .rules
        .iter()
        .find(|r| !r.horizontal)
        .and_then(|r| cell_of(chart, plot, marker, (r.at, chart.y.range[0])))
        .map_or(plot.x, |(col, _)| col);
    let w = (text_width as u16 + 2).min(plot.width);
    let x = if rule_col < plot.x + plot.width / 2 {
        plot.right().saturating_sub(w)
    } else {
        plot.x
    };
    let h = (rows.len() + usize::from(more.is_some())) as u16;
    Some(ReadoutBox {
        rect: Rect::new(x, plot.y, w, h).intersection(plot),
        rows,
        form,
        more,
    })
}

/// Draws the reading's box: each row over blanks, curve `i`'s name (row `i + 1`) in its ink.
fn draw_readout_box(buf: &mut Buffer, chart: &Chart, boxed: &ReadoutBox, theme: Theme) {
    let Some(readout) = &chart.readout else {
        return;
    };
    let area = boxed.rect;
    let blank = " ".repeat(usize::from(area.width));
    let normal = theme.style(Role::Normal);
    for (i, row) in boxed.rows.iter().enumerate() {
        let y = area.y + i as u16;
        put(buf, area.x, y, &blank, normal, area);
        put(buf, area.x + 1, y, row, normal, area);
        if let Some(curve) = i.checked_sub(1).and_then(|c| readout.curves.get(c)) {
            let name: String = row.chars().take(curve.name_len(boxed.form)).collect();
            put(buf, area.x + 1, y, &name, theme.ink(curve.ink), area);
        }
    }
    if let Some(more) = &boxed.more {
        let y = area.y + boxed.rows.len() as u16;
        put(buf, area.x, y, &blank, normal, area);
        put(buf, area.x + 1, y, more, theme.style(Role::Muted), area);
    }
}

/// Columns left for the data cursor's reading on the row above the plot, after the y title.
fn readout_room(inner: Rect, chart: &Chart) -> u16 {
    let x = inner.x + width(&chart.y.title) + 2;
    inner.right().saturating_sub(x)
}

/// Draws `chart` in `area` inside `pane`.
pub fn render(
    frame: &mut Frame,
    area: Rect,
    pane: Block,
    chart: &Chart,
    marker: MarkerStyle,
    theme: Theme,
) {
    let inner = pane.inner(area);
    frame.render_widget(pane, area);
    let f = frame_of(inner, chart);
    if f.plot.width < 4 || f.plot.height < 2 {
        return;
    }
    let buf = frame.buffer_mut();
    plot(buf, chart, f.plot, theme, marker);
    axes(buf, chart, inner, &f, theme, marker);
    let boxed = readout_box(chart, inner, &f, marker);
    labels(
        buf,
        chart,
        &f,
        (theme, marker),
        boxed.as_ref().map(|b| b.rect),
    );
    if let Some(boxed) = &boxed {
        draw_readout_box(buf, chart, boxed, theme);
    }
}

/// [`render`] with the legend along the pane's bottom edge on roomy screens (compact panes have
/// no bottom border to carry it).
pub fn render_with_legend(
    frame: &mut Frame,
    area: Rect,
    pane: Block,
    chart: &Chart,
    (marker, theme): (MarkerStyle, Theme),
    roomy: bool,
) {
    let pane = if roomy {
        pane.title_bottom(legend(
            chart,
            theme,
            usize::from(area.width.saturating_sub(2)),
        ))
    } else {
        pane
    };
    render(frame, area, pane, chart, marker, theme);
}

/// The legend of `chart`'s series in their inks (name and line sample with its glyph), as many as
/// fit in `width` columns, then "+N more".
pub fn legend(chart: &Chart, theme: Theme, width: usize) -> Line<'static> {
    let mut spans = Vec::new();
    let mut used = 0;
    for (i, s) in chart.series.iter().enumerate() {
        let text = format!(" {} {} ", sample(s.glyph, s.ink.dash()), s.name);
        let left = chart.series.len() - i - 1;
        let more = if left > 0 {
            format!(" +{left} more ").chars().count()
        } else {
            0
        };
        let w = text.chars().count();
        if used + w + more > width {
            let rest = left + 1;
            spans.push(Span::styled(
                format!(" +{rest} more "),
                theme.style(Role::Normal),
            ));
            break;
        }
        used += w;
        spans.push(Span::styled(text, styled(theme, s.ink, s.focused, false)));
    }
    Line::from(spans)
}

/// The display value of every x tick label's centre as the buffer shows it, read back from the
/// buffer row under the plot: (value, column). For tests that check labels against data.
#[cfg(test)]
pub fn read_x_labels(buf: &Buffer, f: &ChartFrame) -> Vec<(f64, u16)> {
    read_numbers(
        (f.plot.x.saturating_sub(f.y_labels + 1)..f.plot.right() + 6)
            .map(|x| (x, f.plot.bottom() + 1)),
        buf,
    )
    .into_iter()
    .map(|(v, first, last)| (v, (first + last) / 2))
    .collect()
}

/// Numbers in a run of cells: (value, first cell, last cell).
#[cfg(test)]
fn read_numbers(cells: impl Iterator<Item = (u16, u16)>, buf: &Buffer) -> Vec<(f64, u16, u16)> {
    let mut out = Vec::new();
    let mut text = String::new();
    let mut first = 0;
    let mut last = 0;
    let area = buf.area;
    let mut flush = |text: &mut String, first: u16, last: u16| {
        if let Ok(v) = text.parse::<f64>() {
            out.push((v, first, last));
        }
        text.clear();
    };
    for (x, y) in cells {
        if x >= area.right() || y >= area.bottom() {
            break;
        }
        let s = buf[(x, y)].symbol();
        if s.chars()
            .all(|c| c.is_ascii_digit() || c == '.' || c == '-' || c == 'e' || c == '+')
            && s != " "
        {
            if text.is_empty() {
                first = x;
            }
            text.push_str(s);
            last = x;
        } else {
            flush(&mut text, first, last);
        }
    }
    flush(&mut text, first, last);
    out
}

/// The y tick labels as the buffer shows them: (value, row).
#[cfg(test)]
pub fn read_y_labels(buf: &Buffer, f: &ChartFrame) -> Vec<(f64, u16)> {
    (f.plot.y..f.plot.bottom())
        .filter_map(|y| {
            let x0 = f.plot.x - 1 - f.y_labels;
            read_numbers((x0..f.plot.x - 1).map(|x| (x, y)), buf)
                .first()
                .map(|&(v, _, _)| (v, y))
        })
        .collect()
}

/// Where the labels put display value `v` on an axis: linear interpolation between the two
/// labelled cells around it (labels as read from the buffer, value → cell).
#[cfg(test)]
pub fn cell_by_labels(labels: &[(f64, u16)], v: f64) -> f64 {
    let pair = labels
        .windows(2)
        .find(|w| (w[0].0 <= v && v <= w[1].0) || (w[1].0 <= v && v <= w[0].0))
        .unwrap_or_else(|| panic!("{v} is not between the labels {labels:?}"));
    let (a, b) = (pair[0], pair[1]);
    f64::from(a.1) + (v - a.0) / (b.0 - a.0) * (f64::from(b.1) - f64::from(a.1))
}

#[cfg(test)]
mod tests {
    use super::*;
    use ratatui::Terminal;
    use ratatui::backend::TestBackend;

    use crate::chart::{Axis, Mark, Rule, Series, Tick};

    fn axis(title: &str, range: [f64; 2], ticks: &[f64]) -> Axis {
        Axis {
            title: title.into(),
            range,
            log: false,
            ticks: ticks
                .iter()
                .map(|&at| Tick {
                    at,
                    label: format!("{at}"),
                })
                .collect(),
        }
    }

    fn chart() -> Chart {
        Chart {
            title: "test".into(),
            x: axis("x [µm]", [0.0, 10.0], &[0.0, 2.0, 4.0, 6.0, 8.0, 10.0]),
            y: axis("F [N]", [0.0, 400.0], &[0.0, 100.0, 200.0, 300.0, 400.0]),
            series: vec![Series {
                name: "line".into(),
                ink: Ink::Foreground,
                glyph: '*',
                runs: vec![vec![(0.0, 0.0), (7.575, 326.4), (10.0, 0.0)]],
                focused: true,
                peak: Some((7.575, 326.4)),
                steps: false,
            }],
            marks: vec![Mark {
                at: (2.0, 100.0),
                ink: Ink::Warning,
                glyph: '█',
                label: Some("here".into()),
            }],
            rules: vec![Rule {
                at: 5.0,
                horizontal: false,
                ink: Ink::Error,
                label: "v_p".into(),
            }],
            notes: Vec::new(),
            readout: None,
        }
    }

    fn draw(chart: &Chart, w: u16, h: u16, marker: MarkerStyle) -> (Buffer, ChartFrame) {
        let mut terminal = Terminal::new(TestBackend::new(w, h)).unwrap();
        let area = Rect::new(0, 0, w, h);
        terminal
            .draw(|frame| {
                render(
                    frame,
                    area,
                    crate::ui::widgets::common::pane("", Theme::Plain, true),
                    chart,
                    marker,
                    Theme::Plain,
                )
            })
            .unwrap();
        let inner = Rect::new(1, 1, w - 2, h - 2);
        (terminal.backend().buffer().clone(), frame_of(inner, chart))
    }

    /// The peak at (7.575 µm, 326.4 N) lies where the labels around it say, within a cell, and
    /// its glyph is drawn there; titles are outside the plot.
    #[test]
    fn labels_sit_on_their_values() {
        for (w, h) in [(40, 14), (61, 20), (100, 30)] {
            for marker in [MarkerStyle::Braille, MarkerStyle::Dot] {
                let c = chart();
                let (buf, f) = draw(&c, w, h, marker);
                let xs = read_x_labels(&buf, &f);
                let ys = read_y_labels(&buf, &f);
                assert!(xs.len() >= 3 && ys.len() >= 3, "{xs:?} {ys:?}");
                let (col, row) = cell_of(&c, f.plot, marker, (7.575, 326.4)).unwrap();
                assert_eq!(buf[(col, row)].symbol(), "*");
                assert!((cell_by_labels(&xs, 7.575) - f64::from(col)).abs() <= 1.0);
                assert!((cell_by_labels(&ys, 326.4) - f64::from(row)).abs() <= 1.0);
                // Every label on its tick's column: "8" centred on the cell of 8.
                for (v, x) in &xs {
                    let (tick, _) = cell_of(&c, f.plot, marker, (*v, 0.0)).unwrap();
                    assert_eq!(*x, tick, "{v}");
                }
                let title_row: String = (1..w - 1).map(|x| buf[(x, 1)].symbol()).collect();
                assert!(title_row.starts_with("F [N]"), "{title_row}");
                assert!(f.plot.y > 1);
            }
        }
    }

    #[test]
    fn rules_and_marks_are_labelled_and_the_legend_says_what_is_left_out() {
        let c = chart();
        let (buf, f) = draw(&c, 61, 20, MarkerStyle::Braille);
        let top: String = (f.plot.x..f.plot.right())
            .map(|x| buf[(x, f.plot.y)].symbol())
            .collect();
        assert!(top.contains("v_p"), "{top}");
        let (col, row) = cell_of(&c, f.plot, MarkerStyle::Braille, (2.0, 100.0)).unwrap();
        assert_eq!(buf[(col, row)].symbol(), "█");
        let label: String = (col + 2..col + 6).map(|x| buf[(x, row)].symbol()).collect();
        assert_eq!(label, "here");
        let mut many = chart();
        for name in ["b", "c", "d"] {
            let mut s = many.series[0].clone();
            s.name = name.into();
            many.series.push(s);
        }
        let theme = Theme::Plain;
        assert_eq!(
            legend(&many, theme, 80).to_string().matches("──").count(),
            4
        );
        let short = legend(&many, theme, 30).to_string();
        assert!(
            short.contains("+3 more") || short.contains("+2 more"),
            "{short}"
        );
    }

    #[test]
    fn values_off_the_axes_have_no_cell() {
        let c = chart();
        let plot = Rect::new(10, 0, 21, 5);
        assert_eq!(
            cell_of(&c, plot, MarkerStyle::Dot, (0.0, 0.0)),
            Some((10, 4))
        );
        assert_eq!(
            cell_of(&c, plot, MarkerStyle::Dot, (10.0, 400.0)),
            Some((30, 0))
        );
        assert_eq!(cell_of(&c, plot, MarkerStyle::Dot, (10.5, 0.0)), None);
        assert_eq!(cell_of(&c, plot, MarkerStyle::Dot, (f64::NAN, 0.0)), None);
    }
}
