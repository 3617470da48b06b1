//! What the terminal shows: the cells last written to it, and the cells a new frame changes.
//!
//! ratatui's own diff of a frame against the last one (`Buffer::diff_iter`) measures the width of
//! every cell of both frames and walks a state machine for wide characters, which took a fifth
//! of the explorer's frame (docs/performance.md, § Fewer instructions a frame). Most frames have
//! no wide character at all: every cell is one column, drawn only where it differs from the
//! last. For those, [`OnScreen::changes`] compares the cells and nothing else, measuring only
//! the cells that changed; a frame with a cell of another kind, or the frame after it (a wide or
//! a zero-width symbol, a skipped or always-updated cell), is diffed by ratatui itself. Either way
//! the changes are ratatui's, cell for cell and in the same order (tested).

use ratatui::buffer::{Buffer, Cell, CellDiffOption, CellWidth};
use ratatui::layout::Rect;

/// The cells the terminal shows.
#[derive(Debug)]
pub struct OnScreen {
    shown: Buffer,
    /// Every shown cell is one column wide and diffed plainly (see [`single_column`]).
    single_columns: bool,
}

/// A change to draw: the cell's column and row, and the cell.
pub type Change<'a> = (u16, u16, &'a Cell);

impl OnScreen {
    /// A terminal showing blanks over `area`.
    pub fn blank(area: Rect) -> OnScreen {
        OnScreen {
            shown: Buffer::empty(area),
            single_columns: true,
        }
    }

    /// The cells of `next` to write so that the terminal shows it, in ratatui's order; from then
    /// on the terminal is taken to show `next`. A `next` of another area is diffed against
    /// blanks (the terminal was cleared for it).
    pub fn changes<'n>(&mut self, next: &'n Buffer) -> Vec<Change<'n>> {
        if self.shown.area != next.area {
            *self = OnScreen::blank(next.area);
        }
        let changed = if self.single_columns {
            changed_single_columns(&self.shown, next)
        } else {
            None
        };
        match changed {
            Some(indices) => {
                let width = usize::from(next.area.width.max(1));
                let changes = indices
                    .iter()
                    .map(|&i| {
                        let (x, y) = (i % width, i / width);
                        (
                            next.area.x + x as u16,
                            next.area.y + y as u16,
                            &next.content[i],
                        )
                    })
                    .collect();
                for i in indices {
                    self.shown.content[i].clone_from(&next.content[i]);
                }
                changes
            }
            None => {
                let changes = self.shown.diff_iter(next).collect();
                self.shown.clone_from(next);
                self.single_columns = next.content.iter().all(single_column);
                changes
            }
        }
    }
}

/// The indices of the cells of `next` that differ from `shown`, when every one of them is a
/// single column (`shown`'s all are); `None` at the first that is not. Between single-column
/// cells ratatui's diff is exactly this: a cell is written where it differs.
fn changed_single_columns(shown: &Buffer, next: &Buffer) -> Option<Vec<usize>> {
    let mut changed = Vec::new();
    for (i, (old, new)) in shown.content.iter().zip(&next.content).enumerate() {
        if old != new {
            if !single_column(new) {
                return None;
            }
            changed.push(i);
        }
    }
    Some(changed)
}

/// A cell of one column that ratatui's diff writes exactly when it changed: no skip, no forced
/// width, no forced update.
fn single_column(cell: &Cell) -> bool {
    #[allow(deprecated)] // ratatui's diff still honours the old flag.
    let skipped = cell.skip;
    cell.diff_option == CellDiffOption::None && !skipped && cell.symbol().cell_width() == 1
}

#[cfg(test)]
mod tests {
    use super::*;
    use ratatui::style::{Color, Modifier};

    /// The next frame: `buffer` with about two cells in three redrawn from `seed` (ASCII,
    /// braille and box symbols in a few colours, some bold) and, where `odd` says, one cell of
    /// another kind: wide, zero-width, skipped or always updated.
    fn step(buffer: &mut Buffer, seed: u64, odd: bool) {
        let area = buffer.area;
        let mut state = seed.wrapping_mul(6364136223846793005).wrapping_add(1);
        let mut next = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            state >> 33
        };
        let symbols = ["a", "7", " ", "⠁", "⣿", "─", "│", "·", "≤"];
        for y in area.top()..area.bottom() {
            for x in area.left()..area.right() {
                let r = next();
                if r % 3 == 0 {
                    continue;
                }
                let cell = &mut buffer[(x, y)];
                cell.reset();
                cell.set_symbol(symbols[(r / 3) as usize % symbols.len()]);
                cell.set_fg([Color::Reset, Color::Red, Color::Indexed(42)][(r / 29) as usize % 3]);
                if r % 7 == 0 {
                    cell.modifier = Modifier::BOLD;
                }
            }
        }
        if odd {
            let (x, y) = (area.x + (seed % 5) as u16, area.y + (seed % 3) as u16);
            match seed % 4 {
                0 => {
                    buffer[(x, y)].set_symbol("界");
                    buffer[(x + 1, y)].reset();
                }
                1 => {
                    buffer[(x, y)].set_symbol("");
                }
                2 => {
                    buffer[(x, y)].set_diff_option(CellDiffOption::Skip);
                }
                _ => {
                    buffer[(x, y)].set_diff_option(CellDiffOption::AlwaysUpdate);
                }
            }
        }
    }

    fn owned(changes: Vec<Change<'_>>) -> Vec<(u16, u16, Cell)> {
        changes
            .into_iter()
            .map(|(x, y, c)| (x, y, c.clone()))
            .collect()
    }

    /// A run of frames, each diffed by [`OnScreen`] and by ratatui against the frame before it
    /// (ratatui's terminal keeps the last frame as what is shown): the same changes, frame after
    /// frame, whether frames have odd cells, had them, or change their area.
    #[test]
    fn the_changes_are_ratatuis_frame_after_frame() {
        let small = Rect::new(0, 0, 9, 4);
        let moved = Rect::new(2, 1, 12, 5);
        let mut onscreen = OnScreen::blank(small);
        let mut before = Buffer::empty(small);
        let mut plain = 0;
        for seed in 0..400u64 {
            let area = if (seed / 50) % 2 == 0 { small } else { moved };
            let mut next = if before.area == area {
                before.clone()
            } else {
                Buffer::empty(area)
            };
            step(&mut next, seed, seed % 9 == 4 || seed % 11 == 0);
            if before.area != area {
                before = Buffer::empty(area);
            }
            let ratatui: Vec<_> = before
                .diff_iter(&next)
                .map(|(x, y, c)| (x, y, c.clone()))
                .collect();
            plain += usize::from(onscreen.single_columns);
            assert_eq!(owned(onscreen.changes(&next)), ratatui, "frame {seed}");
            assert!(!ratatui.is_empty(), "frame {seed} changes nothing");
            before = next;
        }
        // Both paths ran, each many times.
        assert!((100..390).contains(&plain), "{plain} frames diffed plainly");
    }

    #[test]
    fn an_unchanged_frame_writes_nothing_and_a_blank_terminal_gets_every_written_cell() {
        let area = Rect::new(0, 0, 6, 2);
        let mut onscreen = OnScreen::blank(area);
        let mut next = Buffer::empty(area);
        next[(3, 1)].set_symbol("x");
        let first = owned(onscreen.changes(&next));
        assert_eq!(first.len(), 1);
        assert_eq!((first[0].0, first[0].1, first[0].2.symbol()), (3, 1, "x"));
        assert!(onscreen.changes(&next).is_empty());
    }

    #[test]
    fn only_plain_single_columns_are_single_column() {
        let mut cell = Cell::new("⣿");
        assert!(single_column(&cell));
        cell.set_symbol("界");
        assert!(!single_column(&cell));
        cell.set_symbol("");
        assert!(!single_column(&cell));
        let mut skipped = Cell::new("a");
        skipped.set_diff_option(CellDiffOption::Skip);
        assert!(!single_column(&skipped));
    }
}
