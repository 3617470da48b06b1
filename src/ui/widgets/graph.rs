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

use crate::chart::layout::dot;
use crate::chart::{Chart, Ink, place_ticks};
use crate::ui::style::MarkerStyle;
use crate::ui::style::{Role, Theme, sample};

use super::common::wrap;
use super::pane::Pane;
use super::text::each_cell;

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

/// One cell of the canvas: braille dots set, whose ink is on top, and a glyph over the dots.
#[derive(Debug, Clone, Copy, Default)]
struct Cell {
    dots: u8,
    ink: Option<(Ink, bool)>,
    glyph: Option<(char, Ink, bool)>,
}

/// The canvas of a plot area, in dots.
struct Canvas {
    width: u16,
    dx: u16,
    /// Dots across and down, taken once: every dot set is checked against them.
    wide: u32,
    high: u32,
    /// log₂ of the dots per cell across and down (braille 1 and 2, else 0): a dot's cell by shifts.
    col_shift: u32,
    row_shift: u32,
    /// The bit a dot sets in its cell, by (y mod 4, x mod 2): braille's layout, else a single bit.
    bits: [[u8; 2]; 4],
    /// Row by row from the bottom, as the dots count (`blit` turns them over).
    cells: Vec<Cell>,
}

/// Bits of the braille dots of a cell, by (column, row) within it (Unicode's 2×4 layout).
const BRAILLE: [[u8; 2]; 4] = [[0x01, 0x08], [0x02, 0x10], [0x04, 0x20], [0x40, 0x80]];

/// Display values to fractional dots from the bottom-left of one canvas:
/// [`crate::chart::Axis::fraction`] times the dots less one, with the axes' spans and the
/// canvas's size taken once per chart rather than once per point.
#[derive(Debug, Clone, Copy)]
struct DotMap {
    /// Per axis: the range's start, its span, and the dots less one.
    x: (f64, f64, f64),
    y: (f64, f64, f64),
    /// Both ranges are increasing (else no value has a place, as `Axis::fraction` says).
    valid: bool,
}

impl DotMap {
    fn new(canvas: &Canvas, chart: &Chart) -> DotMap {
        let [x_lo, x_hi] = chart.x.range;
        let [y_lo, y_hi] = chart.y.range;
        DotMap {
            x: (x_lo, x_hi - x_lo, f64::from(canvas.wide.max(1) - 1)),
            y: (y_lo, y_hi - y_lo, f64::from(canvas.high.max(1) - 1)),
            valid: x_hi > x_lo && y_hi > y_lo,
        }
    }

    /// The dot of display point `p`, in fractional dots (may lie outside the canvas); `None` for
    /// a non-finite point.
    #[inline]
    fn at(&self, p: (f64, f64)) -> Option<(f64, f64)> {
        (self.valid && p.0.is_finite() && p.1.is_finite()).then(|| self.unchecked(p))
    }

    /// [`DotMap::at`] without its tests: non-finite for a non-finite point, meaningless unless
    /// `valid`.
    #[inline]
    fn unchecked(&self, p: (f64, f64)) -> (f64, f64) {
        (
            (p.0 - self.x.0) / self.x.1 * self.x.2,
            (p.1 - self.y.0) / self.y.1 * self.y.2,
        )
    }
}

impl Canvas {
    fn new(plot: Rect, marker: MarkerStyle) -> Canvas {
        let (dx, dy) = dots(marker);
        Canvas {
            width: plot.width,
            dx,
            wide: u32::from(plot.width) * u32::from(dx),
            high: u32::from(plot.height) * u32::from(dy),
            col_shift: u32::from(dx).trailing_zeros(),
            row_shift: u32::from(dy).trailing_zeros(),
            bits: if marker == MarkerStyle::Braille {
                [BRAILLE[3], BRAILLE[2], BRAILLE[1], BRAILLE[0]]
            } else {
                [[1; 2]; 4]
            },
            cells: vec![Cell::default(); usize::from(plot.width) * usize::from(plot.height)],
        }
    }

    /// The index in `cells` of the cell of dot (x, y) on the canvas.
    #[inline]
    fn index(&self, x: u32, y: u32) -> usize {
        let col = (x >> self.col_shift) as usize;
        let row = (y >> self.row_shift) as usize;
        row * usize::from(self.width) + col
    }

    fn cell_mut(&mut self, x: u32, y: u32) -> Option<&mut Cell> {
        if x >= self.wide || y >= self.high {
            return None;
        }
        let i = self.index(x, y);
        self.cells.get_mut(i)
    }

    /// The dot nearest a fractional dot position (`None` left of or below the canvas).
    fn nearest(x: f64, y: f64) -> Option<(i64, i64)> {
        (x >= -0.5 && y >= -0.5 && x.is_finite() && y.is_finite())
            .then(|| (round_half_away(x), round_half_away(y)))
    }

    fn set_dot(&mut self, (x, y): (i64, i64), ink: Ink, bold: bool) {
        let (Ok(x), Ok(y)) = (u32::try_from(x), u32::try_from(y)) else {
            return;
        };
        if x < self.wide && y < self.high {
            self.set_on_canvas(x, y, ink, bold);
        }
    }

    /// Sets dot (x, y), which the caller knows lies on the canvas.
    #[inline]
    fn set_on_canvas(&mut self, x: u32, y: u32, ink: Ink, bold: bool) {
        let bits = self.bits[(y & 3) as usize][(x & 1) as usize];
        let i = self.index(x, y);
        if let Some(cell) = self.cells.get_mut(i) {
            cell.dots |= bits;
            cell.ink = Some((ink, bold));
        }
    }

    fn set(&mut self, x: f64, y: f64, ink: Ink, bold: bool) {
        if let Some(dot) = Canvas::nearest(x, y) {
            self.set_dot(dot, ink, bold);
        }
    }

    /// A straight line between two fractional dots, clipped to the canvas, for an end off it.
    fn line_clipped(&mut self, a: (f64, f64), b: (f64, f64), ink: Ink, bold: bool) {
        let steps = (b.0 - a.0).abs().max((b.1 - a.1).abs()).ceil();
        if steps.is_finite() && steps <= 1e5 {
            let steps = steps.max(1.0) as u32;
            for k in 0..=steps {
                let s = f64::from(k) / f64::from(steps);
                self.set(a.0 + (b.0 - a.0) * s, a.1 + (b.1 - a.1) * s, ink, bold);
            }
        }
    }

    /// A straight line between two dots, one dot at a time (clipped to the canvas): from the dot
    /// after `a` to `b`, so that a polyline sets each dot once.
    fn line_dots(&mut self, a: (i64, i64), b: (i64, i64), ink: Ink, bold: bool) {
        walk(a, b, |at| self.set_dot(at, ink, bold));
    }

    /// [`Canvas::line_dots`] between two dots the caller knows lie on the canvas, so that every
    /// dot of the walk does too (it stays in their bounding box): no dot is checked.
    fn line_on_canvas(&mut self, a: (u32, u32), b: (u32, u32), ink: Ink, bold: bool) {
        let (a, b) = (
            (i64::from(a.0), i64::from(a.1)),
            (i64::from(b.0), i64::from(b.1)),
        );
        walk(a, b, |at| {
            self.set_on_canvas(at.0 as u32, at.1 as u32, ink, bold)
        });
    }

    fn glyph(&mut self, at: (f64, f64), glyph: char, ink: Ink, bold: bool) {
        if at.0 < -0.5 || at.1 < -0.5 {
            return;
        }
        if let Some(cell) = self.cell_mut(at.0.round() as u32, at.1.round() as u32) {
            cell.glyph = Some((glyph, ink, bold));
        }
    }
}

/// The dots of a straight line from the dot after `a` to `b`, each given to `set`: the integer
/// DDA rounded to the nearest dot, step k at a + ⌊(2·d·k + steps) / (2·steps)⌋ on each axis,
/// walked by its remainder rather than divided (a division a dot was most of a line's cost). A
/// neighbour, and a line over 100 000 dots (off any canvas), is its end alone.
#[inline]
fn walk(a: (i64, i64), b: (i64, i64), mut set: impl FnMut((i64, i64))) {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let steps = dx.abs().max(dy.abs());
    if steps <= 1 || steps > 100_000 {
        set(b);
        return;
    }
    // |2·d| ≤ 2·steps, so each step moves the quotient by one at most.
    let span = 2 * steps;
    let (mut at, mut rest) = (a, (steps, steps));
    for _ in 0..steps {
        (at.0, rest.0) = dda_step(at.0, rest.0, 2 * dx, span);
        (at.1, rest.1) = dda_step(at.1, rest.1, 2 * dy, span);
        set(at);
    }
}

/// One step of a DDA coordinate: `rest` ∈ [0, span) is the remainder of the walk's numerator
/// over `span`; adding `increment` (|increment| ≤ span) carries at most one into the coordinate.
#[inline]
fn dda_step(at: i64, rest: i64, increment: i64, span: i64) -> (i64, i64) {
    let rest = rest + increment;
    if rest >= span {
        (at + 1, rest - span)
    } else if rest < 0 {
        (at - 1, rest + span)
    } else {
        (at, rest)
    }
}

/// `x.round() as i64` for finite `x ≥ −0.5` (half away from zero), without the call to libm's
/// `round` that a point of every curve of every frame paid twice.
fn round_half_away(x: f64) -> i64 {
    // From 2⁵² up every double is an integer; below it the truncation and the fraction are exact.
    if x >= 4_503_599_627_370_496.0 {
        return x as i64;
    }
    let whole = x as i64;
    let fraction = x - whole as f64;
    if fraction >= 0.5 {
        whole + 1
    } else if fraction <= -0.5 {
        whole - 1
    } else {
        whole
    }
}

/// [`round_half_away`] for `−0.5 < x < 2³¹`, where truncation towards zero is the floor or, in
/// (−0.5, 0), the nearest integer itself.
#[inline]
fn round_above_minus_half(x: f64) -> i64 {
    let whole = x as i32;
    i64::from(whole) + i64::from(x - f64::from(whole) >= 0.5)
}

/// How curves are told apart: by colour on braille, by glyphs where there is no colour or no
/// braille (each model's glyph along the whole curve).
fn glyphs_along(theme: Theme, marker: MarkerStyle) -> bool {
    !theme.color || marker != MarkerStyle::Braille
}

/// Cells between the glyphs set along a curve when colour cannot tell curves apart.
const GLYPH_SPACING: f64 = 6.0;

/// The last point of a curve painted: in fractional dots, its dot, and whether that dot is known
/// to be set.
#[derive(Clone, Copy)]
struct Drawn {
    at: (f64, f64),
    dot: Option<(i64, i64)>,
    dot_set: bool,
}

/// One run of a curve: a line through its points, each point's dot found once; a segment within
/// one dot sets nothing new when that dot is known to be set (a clipped segment may end beside
/// it). `spacing`: dots between the glyphs set along it, where colour cannot tell curves apart.
///
/// Most points of a curve lie on the canvas, as did the last: those take a short path (no
/// finiteness tests, which the bounds test implies; a neighbouring dot set directly, a longer line
/// walked without a check a dot) that sets the same dots as the general one below it.
fn paint_run(
    canvas: &mut Canvas,
    map: &DotMap,
    run: &[(f64, f64)],
    series: &crate::chart::Series,
    spacing: Option<f64>,
) {
    if !map.valid {
        return;
    }
    let (ink, bold) = (series.ink, series.focused);
    // A fractional dot strictly inside these bounds rounds to a dot on the canvas.
    let (x_end, y_end) = (f64::from(canvas.wide) - 0.5, f64::from(canvas.high) - 0.5);
    let plain = spacing.is_none() && !series.steps;
    let mut last: Option<Drawn> = None;
    let mut travelled = spacing.unwrap_or(0.0) / 2.0;
    for &raw in run {
        let q = map.unchecked(raw);
        let (p, dot) = if q.0 > -0.5 && q.0 < x_end && q.1 > -0.5 && q.1 < y_end {
            let b = (round_above_minus_half(q.0), round_above_minus_half(q.1));
            if let Some(Drawn {
                dot: Some(a),
                dot_set: true,
                ..
            }) = last
                && plain
            {
                let b_on = (b.0 as u32, b.1 as u32);
                if (b.0 - a.0).abs() <= 1 && (b.1 - a.1).abs() <= 1 {
                    // The same dot, set already, or a neighbour: a line of one step.
                    if a != b {
                        canvas.set_on_canvas(b_on.0, b_on.1, ink, bold);
                    }
                } else if let (Ok(x), Ok(y)) = (u32::try_from(a.0), u32::try_from(a.1))
                    && x < canvas.wide
                    && y < canvas.high
                {
                    // Both ends on the canvas: the line between them is too.
                    canvas.line_on_canvas((x, y), b_on, ink, bold);
                } else {
                    canvas.line_dots(a, b, ink, bold);
                }
                last = Some(Drawn {
                    at: q,
                    dot: Some(b),
                    dot_set: true,
                });
                continue;
            }
            (q, Some(b))
        } else {
            let Some(p) = map.at(raw) else {
                continue;
            };
            (p, Canvas::nearest(p.0, p.1))
        };
        let mut dot_set = true;
        match last {
            None => {
                if let Some(dot) = dot {
                    canvas.set_dot(dot, ink, bold);
                }
            }
            Some(Drawn {
                at: from,
                dot: from_dot,
                dot_set: from_set,
            }) => {
                match (from_dot, dot) {
                    (Some(a), Some(b)) if a == b && from_set => {}
                    (Some(a), Some(b)) => canvas.line_dots(a, b, ink, bold),
                    _ => {
                        canvas.line_clipped(from, p, ink, bold);
                        dot_set = false;
                    }
                }
                if let Some(spacing) = spacing {
                    travelled += (p.0 - from.0).hypot((p.1 - from.1) * 0.5);
                    if travelled >= spacing {
                        travelled = 0.0;
                        canvas.glyph(p, series.glyph, ink, bold);
                    }
                }
            }
        }
        last = Some(Drawn {
            at: p,
            dot,
            dot_set,
        });
        if series.steps {
            canvas.glyph(p, series.glyph, ink, bold);
        }
    }
}

fn paint(canvas: &mut Canvas, chart: &Chart, theme: Theme, marker: MarkerStyle) {
    let along = glyphs_along(theme, marker);
    let map = DotMap::new(canvas, chart);
    for rule in &chart.rules {
        let [a, b] = rule.ends(chart);
        let (Some(a), Some(b)) = (map.at(a), map.at(b)) else {
            continue;
        };
        // Dotted: every other dot, so curves crossing it stay visible.
        let steps = (b.0 - a.0).max(b.1 - a.1).max(0.0) as u32 / 2;
        for k in 0..=steps {
            let s = f64::from(k) / f64::from(steps.max(1));
            canvas.set(
                a.0 + (b.0 - a.0) * s,
                a.1 + (b.1 - a.1) * s,
                rule.ink,
                false,
            );
        }
    }
    let spacing = GLYPH_SPACING * f64::from(canvas.dx);
    for series in &chart.series {
        for run in &series.runs {
            paint_run(canvas, &map, run, series, along.then_some(spacing));
        }
    }
    // Peaks and ends over every line, the focused series' last.
    for series in &chart.series {
        for p in series.peak.iter().copied().chain(series.end()) {
            if let Some(at) = map.at(p) {
                canvas.glyph(at, series.glyph, series.ink, series.focused);
            }
        }
    }
    for mark in &chart.marks {
        if let Some(at) = map.at(mark.at) {
            canvas.glyph(at, mark.glyph, mark.ink, true);
        }
    }
}

fn cell_symbol(cell: &Cell, marker: MarkerStyle) -> Option<char> {
    if cell.dots == 0 {
        return None;
    }
    Some(match marker {
        MarkerStyle::Braille => char::from_u32(0x2800 + u32::from(cell.dots)).unwrap_or('•'),
        MarkerStyle::Dot => '•',
        MarkerStyle::Block => '█',
    })
}

fn put(buf: &mut Buffer, x: u16, y: u16, text: &str, style: Style, limit: Rect) {
    for (x, ch) in (x..).zip(text.chars()) {
        if x >= limit.right() || y >= limit.bottom() || x < limit.x || y < limit.y {
            break;
        }
        buf[(x, y)].set_char(ch).set_style(style);
    }
}

/// `symbol` in `style` in every cell of `line` (a row or a column) within `limit`: what `put` of
/// it cell by cell sets.
fn rule(buf: &mut Buffer, line: Rect, limit: Rect, symbol: &str, style: Style) {
    each_cell(buf, line.intersection(limit), |cell| {
        cell.set_symbol(symbol).set_style(style);
    });
}

fn blit(buf: &mut Buffer, canvas: &Canvas, plot: Rect, theme: Theme, marker: MarkerStyle) {
    // Without braille or colour the dots are only the line between glyphs: keep them light so
    // the glyphs read.
    let dim_dots = glyphs_along(theme, marker) && marker != MarkerStyle::Braille;
    // Neighbouring cells mostly share an ink: its style is kept for the next.
    let mut last: Option<((Ink, bool, bool), Style)> = None;
    let mut styled = |ink: Ink, bold: bool, dim: bool| match last {
        Some((key, style)) if key == (ink, bold, dim) => style,
        _ => {
            let mut style = theme.ink(ink);
            if bold {
                style = style.add_modifier(Modifier::BOLD);
            }
            if dim {
                style = style.add_modifier(Modifier::DIM);
            }
            last = Some(((ink, bold, dim), style));
            style
        }
    };
    let rows = canvas.cells.chunks(usize::from(plot.width).max(1));
    for (y, row) in (plot.y..).zip(rows.rev()) {
        for (x, cell) in (plot.x..).zip(row) {
            if let Some((glyph, ink, bold)) = cell.glyph {
                buf[(x, y)]
                    .set_char(glyph)
                    .set_style(styled(ink, bold, false));
            } else if let (Some(symbol), Some((ink, bold))) = (cell_symbol(cell, marker), cell.ink)
            {
                let style = if dim_dots {
                    styled(ink, false, true)
                } else {
                    styled(ink, bold, false)
                };
                buf[(x, y)].set_char(symbol).set_style(style);
            }
        }
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
    rule(
        buf,
        Rect::new(axis_x, plot.y, 1, plot.height),
        inner,
        "│",
        line,
    );
    put(buf, axis_x, axis_y, "└", line, inner);
    rule(
        buf,
        Rect::new(plot.x, axis_y, plot.width, 1),
        inner,
        "─",
        line,
    );
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
    if let Some(readout) = &chart.readout {
        // The cursor's reading takes the row above the plot after the y title.
        let x = inner.x + width(&chart.y.title) + 2;
        let room = inner.right().saturating_sub(x);
        let text = readout.fit(usize::from(room));
        put(buf, x, inner.y, &text, theme.style(Role::Normal), inner);
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

/// Labels of the rules beside their line on the plot's top row, notes under it.
fn labels(buf: &mut Buffer, chart: &Chart, f: &ChartFrame, theme: Theme, marker: MarkerStyle) {
    let plot = f.plot;
    for rule in &chart.rules {
        let [_, end] = rule.ends(chart);
        let Some((col, row)) = cell_of(chart, plot, marker, end) else {
            continue;
        };
        let w = width(&rule.label);
        if rule.horizontal {
            // At the right end, on the rule's row.
            let x = plot.right().saturating_sub(w).max(plot.x);
            put(buf, x, row, &rule.label, theme.ink(rule.ink), plot);
            continue;
        }
        let x = if col + 1 + w <= plot.right() {
            col + 1
        } else if col >= plot.x + w {
            col - w
        } else {
            continue;
        };
        put(buf, x, plot.y, &rule.label, theme.ink(rule.ink), plot);
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
        put(buf, x, row, label, theme.ink(mark.ink), plot);
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

/// Draws `chart` in `area` inside `pane`.
pub fn render(
    frame: &mut Frame,
    area: Rect,
    pane: Pane,
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
    let mut canvas = Canvas::new(f.plot, marker);
    paint(&mut canvas, chart, theme, marker);
    let buf = frame.buffer_mut();
    blit(buf, &canvas, f.plot, theme, marker);
    axes(buf, chart, inner, &f, theme, marker);
    labels(buf, chart, &f, theme, marker);
}

/// [`render`] with the legend along the pane's bottom edge on roomy screens (compact panes have
/// no bottom border to carry it).
pub fn render_with_legend(
    frame: &mut Frame,
    area: Rect,
    pane: Pane,
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
    let items: Vec<(String, Style)> = chart
        .series
        .iter()
        .map(|s| {
            let mut style = theme.ink(s.ink);
            if s.focused {
                style = style.add_modifier(Modifier::BOLD);
            }
            // " ─x── name ", as `sample` draws the line.
            let mut text = String::with_capacity(s.name.len() + 16);
            text.push(' ');
            text.push_str(&sample(s.glyph));
            text.push(' ');
            text.push_str(&s.name);
            text.push(' ');
            (text, style)
        })
        .collect();
    let mut spans = Vec::new();
    let mut used = 0;
    for (i, (text, style)) in items.iter().enumerate() {
        let left = items.len() - i - 1;
        // " +N more ": 8 columns and N's digits, none when nothing is left.
        let more = if left > 0 {
            8 + left.ilog10() as usize + 1
        } else {
            0
        };
        let w = text.chars().count();
        let fits_with_more = used + w + more <= width;
        if !(fits_with_more || left == 0 && used + w <= width) {
            let rest = items.len() - i;
            spans.push(Span::styled(
                format!(" +{rest} more "),
                theme.style(Role::Normal),
            ));
            break;
        }
        used += w;
        spans.push(Span::styled(text.clone(), *style));
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
                    Pane::new("", Theme { color: false }, true),
                    chart,
                    marker,
                    Theme { color: false },
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
        let theme = Theme { color: false };
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

    /// With 12 series (a two-digit "+N more") at every width up to 200 columns: the legend the
    /// former rule, formatting every text, gives: as many items as fit beside the "+N more" of
    /// the rest (the last one without). Fails if the "+N more" is counted a column short.
    #[test]
    fn legends_show_what_the_formatted_rule_shows() {
        let mut many = chart();
        for k in 0..11 {
            let mut s = many.series[0].clone();
            s.name = format!("model {k}");
            many.series.push(s);
        }
        let theme = Theme { color: false };
        let items: Vec<String> = many
            .series
            .iter()
            .map(|s| format!(" {} {} ", sample(s.glyph), s.name))
            .collect();
        for width in 0..=200 {
            let mut expected = String::new();
            for (i, text) in items.iter().enumerate() {
                let left = items.len() - i - 1;
                let more = if left > 0 {
                    format!(" +{left} more ")
                } else {
                    String::new()
                };
                let used = expected.chars().count();
                let w = text.chars().count();
                if !(used + w + more.chars().count() <= width || left == 0 && used + w <= width) {
                    expected.push_str(&format!(" +{} more ", items.len() - i));
                    break;
                }
                expected.push_str(text);
            }
            assert_eq!(legend(&many, theme, width).to_string(), expected, "{width}");
        }
    }

    /// Every segment painted on its own, as the painter did before it skipped segments within
    /// one dot: the reference whose dots and inks the painter must match cell for cell.
    fn paint_each_segment(canvas: &mut Canvas, chart: &Chart) {
        for series in &chart.series {
            for run in &series.runs {
                let pts: Vec<(f64, f64)> = run
                    .iter()
                    .filter_map(|&p| DotMap::new(canvas, chart).at(p))
                    .collect();
                if let Some(first) = pts.first() {
                    canvas.set(first.0, first.1, series.ink, series.focused);
                }
                for w in pts.windows(2) {
                    match (
                        Canvas::nearest(w[0].0, w[0].1),
                        Canvas::nearest(w[1].0, w[1].1),
                    ) {
                        (Some(a), Some(b)) if a == b => {
                            canvas.set_dot(b, series.ink, series.focused)
                        }
                        (Some(a), Some(b)) => canvas.line_dots(a, b, series.ink, series.focused),
                        _ => canvas.line_clipped(w[0], w[1], series.ink, series.focused),
                    }
                }
            }
        }
    }

    /// Dense wandering curves of two inks, in and out of the plot on every side (some points
    /// NaN), steps of one dot to several: the painter's cells equal the segment-by-segment
    /// painting's.
    #[test]
    fn skipping_segments_within_a_dot_changes_no_cell() {
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for trial in 0..40 {
            let mut c = chart();
            c.marks.clear();
            c.rules.clear();
            let mut other = c.series[0].clone();
            other.ink = Ink::Warning;
            other.focused = false;
            c.series.insert(0, other);
            for series in &mut c.series {
                let (mut x, mut y) = (next() * 10.0, next() * 400.0);
                // Steps of up to 2, 4, 6 or 8 dots, so lines of several dots are walked too.
                let reach = f64::from(1 + trial % 4);
                let run = (0..600)
                    .map(|i| {
                        x += (next() - 0.5) * 0.4 * reach;
                        y += (next() - 0.5) * 30.0 * reach;
                        if i % 97 == 13 { (f64::NAN, y) } else { (x, y) }
                    })
                    .collect();
                series.runs = vec![run];
            }
            for marker in [MarkerStyle::Braille, MarkerStyle::Dot] {
                let plot = Rect::new(0, 0, 37 + trial % 5, 11 + trial % 3);
                let mut fast = Canvas::new(plot, marker);
                paint(&mut fast, &c, Theme { color: true }, marker);
                let mut plain = Canvas::new(plot, marker);
                paint_each_segment(&mut plain, &c);
                let inked = plain.cells.iter().filter(|cell| cell.dots != 0).count();
                assert!(
                    inked > 20,
                    "trial {trial}: the curves cross the plot ({inked} cells)"
                );
                // The painter's glyphs at peaks and ends aside, the dots and their inks.
                let lines = |canvas: &Canvas| -> Vec<_> {
                    canvas
                        .cells
                        .iter()
                        .map(|cell| (cell.dots, cell.ink))
                        .collect()
                };
                assert!(lines(&fast) == lines(&plain), "trial {trial}, {marker:?}");
            }
        }
    }

    /// Lines from a dot to every dot up to 27 away, on and off the canvas: the dots of the
    /// integer DDA, each divided out on its own, a neighbour included.
    #[test]
    fn lines_set_the_dots_of_their_walk() {
        let plot = Rect::new(0, 0, 20, 6);
        let a = (17, 11);
        for dx in -27..=27 {
            for dy in -27..=27 {
                let b = (a.0 + dx, a.1 + dy);
                let mut line = Canvas::new(plot, MarkerStyle::Braille);
                line.line_dots(a, b, Ink::Foreground, false);
                let mut walk = Canvas::new(plot, MarkerStyle::Braille);
                let steps = dx.abs().max(dy.abs());
                for k in 1..=steps {
                    let x = a.0 + (2 * dx * k + steps).div_euclid(2 * steps);
                    let y = a.1 + (2 * dy * k + steps).div_euclid(2 * steps);
                    walk.set_dot((x, y), Ink::Foreground, false);
                }
                if steps == 0 {
                    walk.set_dot(b, Ink::Foreground, false);
                }
                let dots = |c: &Canvas| c.cells.iter().map(|cell| cell.dots).collect::<Vec<_>>();
                assert_eq!(dots(&line), dots(&walk), "{a:?} to {b:?}");
            }
        }
    }

    /// A rule sets what `put` of its symbol sets cell by cell, where it lies inside the limit,
    /// across it and outside it, as a row and as a column.
    #[test]
    fn rules_set_what_put_sets() {
        let area = Rect::new(0, 0, 12, 8);
        let limit = Rect::new(2, 1, 7, 5);
        let style = Style::new().fg(ratatui::style::Color::Red);
        for line in [
            Rect::new(3, 2, 4, 1),
            Rect::new(0, 3, 12, 1),
            Rect::new(4, 0, 1, 8),
            Rect::new(10, 2, 1, 3),
            Rect::new(1, 9, 5, 1),
            Rect::new(12, 2, 1, 3),
            Rect::new(0, 0, 2, 8),
        ] {
            let mut ruled = Buffer::empty(area);
            rule(&mut ruled, line, limit, "─", style);
            let mut put_each = Buffer::empty(area);
            for y in line.top()..line.bottom() {
                for x in line.left()..line.right() {
                    put(&mut put_each, x, y, "─", style, limit);
                }
            }
            assert_eq!(ruled, put_each, "{line:?}");
        }
    }

    #[test]
    fn dots_round_as_f64_round_does() {
        let halves = [
            0.5,
            1.5,
            2.5,
            99.5,
            -0.5,
            0.499_999_999_999_999_94,
            -0.499_999_999_999_999_94,
            131_071.5,
            2f64.powi(31) - 0.5,
            2f64.powi(52) - 0.5,
        ];
        let large = [2f64.powi(52), 2f64.powi(53) + 2.0, 1e300, f64::MAX];
        let spread = (0..10_000).map(|i| f64::from(i) * 0.0137 - 0.5);
        for x in halves.into_iter().chain(large).chain(spread) {
            assert_eq!(round_half_away(x), x.round() as i64, "{x:e}");
            if x > -0.5 && x < 2f64.powi(31) {
                assert_eq!(round_above_minus_half(x), x.round() as i64, "{x:e}");
            }
            let below = x.next_down();
            if below >= -0.5 {
                assert_eq!(round_half_away(below), below.round() as i64, "{below:e}");
            }
            if below > -0.5 && below < 2f64.powi(31) {
                assert_eq!(
                    round_above_minus_half(below),
                    below.round() as i64,
                    "{below:e}"
                );
            }
        }
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
