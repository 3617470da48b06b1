//! Curves as patterned strokes of the plot's dots, and which curve a cell shows where several pass
//! through it. A terminal cell has one colour: where two curves lie within a cell of each other
//! (Hunt–Crossley and Lankarani–Nikravesh, elastic Hertz under dry friction in Fig. 4), the one
//! painted last took every shared cell and the other vanished. Here each shared cell goes to one of
//! the curves in it, the same one whatever other curves are drawn, and every curve gets its share
//! of the cells it shares; a cell shows only its owner's dots, so the owner's pattern reads in it.

use crate::chart::{Dash, Ink};

use super::dots::Dots;

/// One curve's dots on the plot's grid (x from the left, y from the top, in dots), in its ink and
/// boldness.
#[derive(Debug, Clone, PartialEq)]
pub struct Stroke {
    pub ink: (Ink, bool),
    /// Decides the cells this stroke shares (see [`paint`]): the same curve keeps the same key
    /// in every frame, so a shared cell keeps its owner as long as the curves in it do.
    pub key: u64,
    pub dots: Vec<(u16, u16)>,
}

/// A key for a curve named `name`: FNV-1a of the name.
pub fn key_of(name: &str) -> u64 {
    name.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

/// The dots of a run of points (fractional grid dots, x from the left, y from the top) joined by
/// straight lines, drawn with `dash`: the dots along the line are counted from the run's start,
/// and the pattern leaves out its `off` dots of each period. Dots off the `size` grid are dropped.
///
/// It runs once per sample of every curve of every chart in every frame (thousands a frame with
/// every law checked), so it does no division and no call into libm per dot.
pub fn trace(
    points: impl IntoIterator<Item = (f64, f64)>,
    dash: Dash,
    size: (u16, u16),
    out: &mut Vec<(u16, u16)>,
) {
    let mut pen = Pen::new(dash, size);
    let finite = |p: &(f64, f64)| p.0.is_finite() && p.1.is_finite();
    let mut points = points
        .into_iter()
        .filter(finite)
        .map(|(x, y)| (nearest(x), nearest(y)));
    let Some(first) = points.next() else {
        return;
    };
    pen.put(first, out);
    let mut from = first;
    for to in points {
        // A line of single steps, as Bresenham's: one dot per step along the longer side, the
        // other side's dot the nearest to the line (a tie away from `from`); the last is `to`.
        let (dx, dy) = (to.0 - from.0, to.1 - from.1);
        let steps = dx.abs().max(dy.abs());
        if steps == 1 {
            // Most samples lie a dot from the last: the step is `to` itself.
            pen.put(to, out);
        } else {
            let (mut across, mut down) = (Along::new(dx, steps), Along::new(dy, steps));
            for _ in 0..steps {
                pen.put((from.0 + across.step(), from.1 + down.step()), out);
            }
        }
        from = to;
    }
}

/// One coordinate along a line of `steps` single steps that moves it by `d` (|d| ≤ `steps`): at
/// step i it is round(d·i/steps), half away from zero, counted without a division: the count
/// 2|d|·i + steps rolls over at every 2·steps.
struct Along {
    sign: i64,
    rise: i64,
    run: i64,
    count: i64,
    at: i64,
}

impl Along {
    fn new(d: i64, steps: i64) -> Along {
        Along {
            sign: d.signum(),
            rise: 2 * d.abs(),
            run: 2 * steps,
            count: steps,
            at: 0,
        }
    }

    /// The coordinate after one more step.
    fn step(&mut self) -> i64 {
        self.count += self.rise;
        if self.count >= self.run {
            self.count -= self.run;
            self.at += self.sign;
        }
        self.at
    }
}

/// Puts the dots of one run in its pattern: counts every dot along it, keeps those the pattern
/// draws that lie on the grid. The lines of [`trace`] never put a dot twice in a row: each step
/// moves along the longer side, and a line starts one step from the last one's end.
struct Pen {
    on: u32,
    period: u32,
    /// Dots counted so far, modulo the period.
    phase: u32,
    size: (u64, u64),
}

impl Pen {
    fn new(dash: Dash, size: (u16, u16)) -> Pen {
        let (on, off) = dash.on_off();
        Pen {
            on: u32::from(on),
            period: u32::from(on) + u32::from(off),
            phase: 0,
            size: (u64::from(size.0), u64::from(size.1)),
        }
    }

    fn put(&mut self, d: (i64, i64), out: &mut Vec<(u16, u16)>) {
        let draw = self.phase < self.on;
        self.phase += 1;
        if self.phase >= self.period {
            self.phase = 0;
        }
        // A negative coordinate wraps to beyond the grid.
        let inside = (d.0 as u64) < self.size.0 && (d.1 as u64) < self.size.1;
        if draw && inside {
            out.push((d.0 as u16, d.1 as u16));
        }
    }
}

/// `v` rounded half away from zero, as `f64::round` (which is a call into libm on baseline
/// x86-64, once per sample here): truncation corrects by the fraction left. Beyond ±2³¹ dots a
/// point is far off any grid and clamped there, so the lines towards it keep their direction.
fn nearest(v: f64) -> i64 {
    const FAR: f64 = 2_147_483_648.0;
    let v = v.clamp(-FAR, FAR);
    let truncated = v as i64;
    let fraction = v - truncated as f64;
    truncated + i64::from(fraction >= 0.5) - i64::from(fraction <= -0.5)
}

/// Cells (columns, rows) drawn by one curve where curves share them: a run of a few cells along a
/// curve reads as a dash of it, where curves taking turns cell by cell read as noise.
const BLOCK: (u16, u16) = (3, 2);

/// Paints `strokes` on `dots`, each cell where several have dots left to one of them: the one
/// whose key scores highest in the cell's [`BLOCK`] (rendezvous hashing: each of k strokes owns
/// about 1/k of the blocks they share, and removing one stroke changes only the cells it owned).
/// A cell shows only its owner's dots, in its ink.
pub fn paint(strokes: &[Stroke], dots: &mut Dots<(Ink, bool)>) {
    for (s, stroke) in strokes.iter().enumerate() {
        // A stroke's consecutive dots mostly lie in one cell, whose score is the same for each:
        // it is scored once for the run of them.
        let mut last = (usize::MAX, 0);
        for &(x, y) in &stroke.dots {
            let Some(at) = dots.at(usize::from(x), usize::from(y)) else {
                continue;
            };
            if at.index != last.0 {
                let (column, row) = at.cell;
                let block = (u64::from(row / BLOCK.1) << 32) | u64::from(column / BLOCK.0);
                last = (at.index, mix(block ^ stroke.key.rotate_left(17)));
            }
            dots.claim(&at, stroke.ink, (last.1, s));
        }
    }
}

/// SplitMix64's finaliser: a cell's score for a key, spread evenly.
fn mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::ForceModel;
    use crate::ui::style::MarkerStyle;

    fn line(dash: Dash) -> Vec<(u16, u16)> {
        let mut out = Vec::new();
        trace([(0.0, 0.0), (11.0, 0.0)], dash, (40, 8), &mut out);
        out
    }

    #[test]
    fn patterns_leave_out_their_dots_along_the_line() {
        let xs = |d: Vec<(u16, u16)>| d.into_iter().map(|p| p.0).collect::<Vec<_>>();
        assert_eq!(xs(line(Dash::Solid)), (0..12).collect::<Vec<_>>());
        assert_eq!(xs(line(Dash::Dotted)), [0, 2, 4, 6, 8, 10]);
        assert_eq!(xs(line(Dash::Dashed)), [0, 1, 2, 3, 6, 7, 8, 9]);
        // Steep lines take a dot per row, and the pattern goes on over a corner.
        let mut out = Vec::new();
        trace(
            [(0.0, 0.0), (1.0, 5.0), (6.0, 5.0)],
            Dash::Dotted,
            (40, 8),
            &mut out,
        );
        assert_eq!(out, [(0, 0), (0, 2), (1, 4), (2, 5), (4, 5), (6, 5)]);
        let mut out = Vec::new();
        trace(
            [(-3.0, 1.0), (2.0, 1.0), (f64::NAN, 0.0)],
            Dash::Solid,
            (40, 8),
            &mut out,
        );
        assert_eq!(
            out,
            [(0, 1), (1, 1), (2, 1)],
            "off the grid and NaN: no dot"
        );
    }

    /// Every dot of a line is the one the rounded division gives.
    #[test]
    fn lines_take_the_nearest_dot_at_every_step() {
        let lines: [(i64, i64); 8] = [
            (7, 3),
            (-7, 3),
            (3, -7),
            (-5, -5),
            (6, 3),
            (-6, 3),
            (4, 0),
            (0, -4),
        ];
        for (dx, dy) in lines {
            let steps = dx.abs().max(dy.abs());
            let (mut across, mut down) = (Along::new(dx, steps), Along::new(dy, steps));
            for i in 1..=steps {
                let divided = |d: i64| (d as f64 * i as f64 / steps as f64).round() as i64;
                assert_eq!((across.step(), down.step()), (divided(dx), divided(dy)));
            }
        }
    }

    #[test]
    fn nearest_rounds_as_f64_round() {
        for v in [
            0.0, 0.49, 0.5, 0.51, 1.5, 2.5, -0.5, -0.49, -1.5, -2.5, 7.999, 1e-300, 123.4999,
        ] {
            assert_eq!(nearest(v), v.round() as i64, "{v}");
        }
        assert_eq!(nearest(1e300), 2_147_483_648);
        assert_eq!(nearest(-1e300), -2_147_483_648);
    }

    /// Three strokes on the same dots: each owns about a third of the 200 cells, and removing
    /// one leaves the others' cells as they were.
    #[test]
    fn shared_cells_are_shared_fairly_and_stay_put() {
        let line: Vec<(u16, u16)> = (0..400).map(|x| (x, 1)).collect();
        let stroke = |name: &str, ink: usize| Stroke {
            ink: (Ink::Model(ForceModel::ALL[ink]), false),
            key: key_of(name),
            dots: line.clone(),
        };
        let owners = |strokes: &[Stroke]| -> Vec<Option<(char, (Ink, bool))>> {
            let mut dots = Dots::new((200, 2), MarkerStyle::Braille);
            paint(strokes, &mut dots);
            (0..400).map(|i| dots.cell(i)).collect()
        };
        let three = owners(&[stroke("a", 1), stroke("b", 2), stroke("c", 3)]);
        for ink in 1..=3 {
            let cells = three
                .iter()
                .filter(|c| c.is_some_and(|(_, look)| look == stroke("", ink).ink))
                .count();
            assert!((45..=90).contains(&cells), "{cells} of 200");
        }
        // Each cell of the line shows both of its dots, its owner's: ⠒ (dots 2 and 5).
        assert!(
            three[..200]
                .iter()
                .all(|c| c.is_some_and(|(symbol, _)| symbol == '⠒'))
        );
        assert!(
            three[200..].iter().all(Option::is_none),
            "the row below is blank"
        );
        let two = owners(&[stroke("a", 1), stroke("b", 2)]);
        for (before, after) in three.iter().zip(&two) {
            if let Some((_, look)) = before
                && *look != stroke("", 3).ink
            {
                assert_eq!(after.map(|(_, l)| l), Some(*look), "a cell kept its owner");
            }
        }
    }
}
