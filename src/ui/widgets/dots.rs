//! A plot's cells painted dot by dot: each cell shows its dots' braille pattern (or, with one dot
//! a cell, the marker's dot or block) in the ink painted last in it. It is what ratatui's
//! canvas draws for one layer of points, without the canvas's boxed grid, its layer and the
//! buffer it is drawn into, which took a tenth of a chart's drawing with every law checked
//! (docs/performance.md, key to frame).

use ratatui::symbols::braille::BRAILLE;

use crate::ui::style::MarkerStyle;

/// The cells of a plot, each with its dots (one bit a dot) and the ink `P` painted last in it
/// (the chart's ink and boldness; a colour in the tests against ratatui's canvas).
pub struct Dots<P> {
    /// Cells across and down.
    cells: (usize, usize),
    /// Dots a cell across and down, as powers of two: braille's 2 × 4 is (1, 2).
    shift: (u32, u32),
    mark: Option<char>,
    painted: Vec<Painted<P>>,
}

/// One cell: the dots painted on it by anyone, those of the stroke that owns it (see
/// [`Dots::claim`]), and the ink painted last.
#[derive(Clone, Copy)]
struct Painted<P> {
    dots: u8,
    owned: u8,
    ink: Option<P>,
    /// The owner's score and index.
    owner: Option<(u64, usize)>,
}

/// A dot's cell (column, row), its index row by row, and the dot's bit in it.
pub struct At {
    pub cell: (u16, u16),
    pub index: usize,
    bit: u8,
}

impl<P: Copy> Dots<P> {
    /// A blank plot of `cells` (columns, rows) in `marker`'s dots.
    pub fn new(cells: (u16, u16), marker: MarkerStyle) -> Dots<P> {
        let (shift, mark) = match marker {
            MarkerStyle::Braille => ((1, 2), None),
            MarkerStyle::Dot => ((0, 0), Some('•')),
            MarkerStyle::Block => ((0, 0), Some('█')),
        };
        let cells = (usize::from(cells.0), usize::from(cells.1));
        Dots {
            cells,
            shift,
            mark,
            painted: vec![
                Painted {
                    dots: 0,
                    owned: 0,
                    ink: None,
                    owner: None,
                };
                cells.0 * cells.1
            ],
        }
    }

    /// Dots across and down.
    fn resolution(&self) -> (f64, f64) {
        (
            (self.cells.0 << self.shift.0) as f64,
            (self.cells.1 << self.shift.1) as f64,
        )
    }

    /// The dot (from the top left) where value (`x`, `y`) lies on a plot spanning `x_bounds` ×
    /// `y_bounds`, as ratatui's canvas places a point; `None` off the plot.
    pub fn dot_of(
        &self,
        [left, right]: [f64; 2],
        [bottom, top]: [f64; 2],
        (x, y): (f64, f64),
    ) -> Option<(usize, usize)> {
        if x < left || x > right || y < bottom || y > top {
            return None;
        }
        let (width, height) = (right - left, top - bottom);
        if width <= 0.0 || height <= 0.0 {
            return None;
        }
        let resolution = self.resolution();
        let x = ((x - left) * (resolution.0 - 1.0) / width).round() as usize;
        let y = ((top - y) * (resolution.1 - 1.0) / height).round() as usize;
        Some((x, y))
    }

    /// Where dot (`x`, `y`), from the top left, lies; `None` off the plot.
    pub fn at(&self, x: usize, y: usize) -> Option<At> {
        let (column, row) = (x >> self.shift.0, y >> self.shift.1);
        if column >= self.cells.0 || row >= self.cells.1 {
            return None;
        }
        // Braille's bits: the columns' dots of each row in turn, as ratatui's table has them.
        let across = x & ((1 << self.shift.0) - 1);
        let down = y & ((1 << self.shift.1) - 1);
        Some(At {
            cell: (column as u16, row as u16),
            index: row * self.cells.0 + column,
            bit: 1 << (across + (down << self.shift.0)),
        })
    }

    /// Paints dot (`x`, `y`), from the top left, in `ink`; a dot off the plot is left out.
    pub fn paint(&mut self, x: usize, y: usize, ink: P) {
        if let Some(at) = self.at(x, y) {
            let cell = &mut self.painted[at.index];
            cell.dots |= at.bit;
            cell.ink = Some(ink);
        }
    }

    /// Paints the dot `at` for stroke `stroke` in `ink` where the stroke's `score` for its cell
    /// is the highest so far (the first of equal ones): a cell shows only its owner's dots, on
    /// those [`Dots::paint`] put there, in its ink.
    pub fn claim(&mut self, at: &At, ink: P, (score, stroke): (u64, usize)) {
        let cell = &mut self.painted[at.index];
        match cell.owner {
            Some((_, owner)) if owner == stroke => cell.owned |= at.bit,
            Some((best, _)) if score <= best => {}
            _ => {
                cell.owner = Some((score, stroke));
                cell.owned = at.bit;
                cell.ink = Some(ink);
            }
        }
    }

    /// The symbol and ink of cell `i` (row by row), if any dot of it is painted.
    pub fn cell(&self, i: usize) -> Option<(char, P)> {
        let cell = self.painted.get(i)?;
        let pattern = cell.dots | cell.owned;
        let symbol = self.mark.unwrap_or(BRAILLE[usize::from(pattern)]);
        cell.ink.filter(|_| pattern != 0).map(|ink| (symbol, ink))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ratatui::buffer::Buffer;
    use ratatui::layout::Rect;
    use ratatui::style::Color;
    use ratatui::widgets::Widget;
    use ratatui::widgets::canvas::{Canvas, Points};

    /// The cells ratatui's canvas draws for the same points in the same colours, whatever the
    /// marker: the symbol and the colour of every cell.
    #[test]
    fn the_cells_are_the_ones_ratatuis_canvas_draws() {
        let area = Rect::new(0, 0, 13, 5);
        let bounds = ([-1.0, 3.0], [0.0, 2.0]);
        let points: Vec<(f64, f64)> = (0..400)
            .map(|i| {
                let t = f64::from(i) / 100.0;
                (t - 1.2, 1.0 + (3.0 * t).sin() * 1.1)
            })
            .collect();
        let (first, second) = points.split_at(150);
        for marker in [MarkerStyle::Braille, MarkerStyle::Dot, MarkerStyle::Block] {
            let canvas = Canvas::default()
                .marker(marker.marker())
                .x_bounds(bounds.0)
                .y_bounds(bounds.1)
                .paint(|ctx| {
                    ctx.draw(&Points::new(first, Color::Indexed(1)));
                    ctx.draw(&Points::new(second, Color::Indexed(2)));
                });
            let mut drawn = Buffer::empty(area);
            canvas.render(area, &mut drawn);
            let mut dots = Dots::new((area.width, area.height), marker);
            for (points, color) in [(first, Color::Indexed(1)), (second, Color::Indexed(2))] {
                for &p in points {
                    if let Some((x, y)) = dots.dot_of(bounds.0, bounds.1, p) {
                        dots.paint(x, y, color);
                    }
                }
            }
            let mut painted = 0;
            for (i, position) in area.positions().enumerate() {
                let cell = &drawn[position];
                match dots.cell(i) {
                    Some((symbol, color)) => {
                        painted += 1;
                        assert_eq!(cell.symbol(), symbol.to_string(), "{marker:?} {position:?}");
                        assert_eq!(cell.fg, color, "{marker:?} {position:?}");
                    }
                    None => assert_eq!(cell.symbol(), " ", "{marker:?} {position:?}"),
                }
            }
            assert!(painted > 20, "{marker:?}: {painted} cells painted");
        }
    }
}
