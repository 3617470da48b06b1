//! The cells to rewrite between two frames: ratatui's buffer diff, with a fast path for the frames
//! the explorer draws, where every cell is one column wide.
//!
//! ratatui's `BufferDiff` measures the display width of every cell of both frames (to skip the
//! columns a wide character covers) and compares cells field by field through the symbol's
//! string: about 190 instructions a cell, 1.5 M for a 160×48 frame, more than the recompute of
//! five impacts. When every cell of both frames is a plain single-width cell, the diff is simply
//! "the cells that differ", which this module finds in about a fifth of that; any other frame (a
//! wide character, a skipped cell, a cell with a diff option) goes through ratatui's diff whole, so
//! the result is ratatui's in every case.

use ratatui::buffer::{Buffer, Cell, CellDiffOption, CellWidth};
use ratatui::layout::Rect;

/// What the terminal shows, and whether every cell of it is known to be a plain one-column cell
/// (then the cells a frame leaves as they were need no check of their own).
#[derive(Debug)]
pub(super) struct Shown {
    pub(super) buffer: Buffer,
    plain: bool,
}

impl Shown {
    /// A blank terminal of `area`: blank cells are plain.
    pub(super) fn blank(area: Rect) -> Self {
        Self {
            buffer: Buffer::empty(area),
            plain: true,
        }
    }

    /// A terminal of `area` whose cells are unknown (a write failed midway): every cell of the
    /// next frame differs from them (a control character no frame draws), so all are written.
    pub(super) fn unknown(area: Rect) -> Self {
        let mut buffer = Buffer::empty(area);
        for cell in &mut buffer.content {
            cell.set_symbol("\u{1}");
        }
        Self {
            buffer,
            plain: true,
        }
    }

    /// Writes into `changed` the indices of the cells of `next` to send to the terminal, in
    /// ratatui's order, and takes `next` as what it shows.
    pub(super) fn update(&mut self, next: &Buffer, changed: &mut Vec<usize>) {
        changed.clear();
        let shown = &mut self.buffer;
        if shown.area == next.area && narrow_diff(shown, self.plain, next, changed) {
            for &i in changed.iter() {
                shown.content[i].clone_from(&next.content[i]);
            }
            self.plain = true;
        } else {
            changed.clear();
            changed.extend(
                shown
                    .diff(next)
                    .into_iter()
                    .map(|(x, y, _)| next.index_of(x, y)),
            );
            shown.clone_from(next);
            self.plain = false;
        }
    }
}

/// The fast path: the indices of the cells that differ, or `false` as soon as a cell of either
/// frame is not a plain single-width cell. With `plain`, every cell of `shown` is known plain, and
/// so is a cell of `next` equal to it.
fn narrow_diff(shown: &Buffer, plain: bool, next: &Buffer, changed: &mut Vec<usize>) -> bool {
    for (i, (old, new)) in shown.content.iter().zip(&next.content).enumerate() {
        let (old_symbol, symbol) = (old.symbol(), new.symbol());
        if same_style(old, new) && same_symbol(old_symbol, symbol) {
            if !plain && !plain_narrow(new, symbol) {
                return false;
            }
        } else if plain_narrow(new, symbol) && (plain || plain_narrow(old, old_symbol)) {
            changed.push(i);
        } else {
            return false;
        }
    }
    true
}

/// ratatui's `Cell` `==` without the symbol.
#[allow(deprecated)] // `skip` is deprecated for `diff_option`, but ratatui's `==` still compares it.
fn same_style(a: &Cell, b: &Cell) -> bool {
    a.fg == b.fg
        && a.bg == b.bg
        && a.modifier == b.modifier
        && a.underline_color == b.underline_color
        && a.diff_option == b.diff_option
        && a.skip == b.skip
}

/// String equality, with the one- and three-byte symbols (ASCII, braille, box drawing) compared
/// byte by byte rather than through `memcmp`.
fn same_symbol(a: &str, b: &str) -> bool {
    match (a.as_bytes(), b.as_bytes()) {
        ([a], [b]) => a == b,
        ([a0, a1, a2], [b0, b1, b2]) => a0 == b0 && a1 == b1 && a2 == b2,
        (a, b) => a == b,
    }
}

/// Whether ratatui would diff `cell`, whose symbol is `symbol`, as one plain column: no diff
/// option, not skipped, and a symbol one column wide by ratatui's own measure.
#[allow(deprecated)] // `skip` is deprecated for `diff_option`, but ratatui's diff still honours it.
fn plain_narrow(cell: &Cell, symbol: &str) -> bool {
    cell.diff_option == CellDiffOption::None
        && !cell.skip
        && (symbol.len() == 1 || known_narrow(symbol) || symbol.cell_width() == 1)
}

/// The non-ASCII symbols the explorer draws most, braille dots and box drawing (U+2500–U+259F,
/// U+2800–U+28FF), recognised from their UTF-8 bytes: all one column wide by ratatui's measure
/// (tested against it), so the general measure is skipped for them.
pub(super) fn known_narrow(symbol: &str) -> bool {
    matches!(
        symbol.as_bytes(),
        [0xE2, 0x94 | 0x95 | 0xA0..=0xA3, _] | [0xE2, 0x96, 0x80..=0x9F]
    )
}
