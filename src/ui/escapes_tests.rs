use super::*;
use ratatui::backend::{Backend, CrosstermBackend};
use ratatui::buffer::Cell;

/// A stream of numbers from `seed` (a linear congruential generator: reproducible, no crate).
fn numbers(seed: u64) -> impl FnMut() -> u64 {
    let mut state = seed.wrapping_mul(6364136223846793005).wrapping_add(1);
    move || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        state >> 33
    }
}

const COLORS: [Color; 8] = [
    Color::Reset,
    Color::Black,
    Color::LightRed,
    Color::Gray,
    Color::DarkGray,
    Color::Indexed(7),
    Color::Indexed(213),
    Color::Rgb(1, 200, 37),
];

/// Cells of every colour, every modifier (alone and together) and a few symbols.
fn cells(seed: u64, n: usize) -> Vec<Cell> {
    let mut next = numbers(seed);
    let symbols = ["a", " ", "⣿", "─", "µ", "界"];
    (0..n)
        .map(|_| {
            let mut cell = Cell::new(symbols[next() as usize % symbols.len()]);
            // Runs of one style, as frames have, broken now and then.
            cell.fg = COLORS[next() as usize % 2 * (next() as usize % COLORS.len())];
            cell.bg = COLORS[next() as usize % 3 / 2 * (next() as usize % COLORS.len())];
            cell.underline_color = COLORS[next() as usize % 4 / 3 * (next() as usize % 8)];
            cell.modifier = Modifier::from_bits_truncate((next() % 2 * next()) as u16);
            cell
        })
        .collect()
}

/// Every change list, written here and by ratatui's crossterm backend: the same bytes.
#[test]
fn the_bytes_are_ratatuis_crossterm_backends() {
    for seed in 0..200 {
        let cells = cells(seed, 60);
        let mut next = numbers(seed + 1000);
        let (mut x, mut y) = (0u16, 0u16);
        let changes: Vec<Change<'_>> = cells
            .iter()
            .map(|cell| {
                // Mostly the next column; sometimes a jump, to a far column or row.
                match next() % 5 {
                    0 => x += 1 + (next() % 300) as u16,
                    1 => (x, y) = ((next() % 1000) as u16, y + 1 + (next() % 999) as u16),
                    _ => x += 1,
                }
                (x, y, cell)
            })
            .collect();
        let mut ours = Vec::new();
        write_changes(&mut ours, changes.iter().copied()).unwrap();
        let mut theirs = Vec::new();
        CrosstermBackend::new(&mut theirs)
            .draw(changes.iter().copied())
            .unwrap();
        assert_eq!(
            String::from_utf8_lossy(&ours),
            String::from_utf8_lossy(&theirs),
            "seed {seed}"
        );
    }
}

#[test]
fn nothing_changed_writes_only_the_resets() {
    let mut ours = Vec::new();
    write_changes(&mut ours, []).unwrap();
    assert_eq!(ours, b"\x1b[39m\x1b[49m\x1b[59m\x1b[0m");
}

#[test]
fn cursor_moves_count_from_one_in_every_magnitude() {
    for (x, y, text) in [
        (0, 0, "\x1b[1;1H"),
        (9, 99, "\x1b[100;10H"),
        (u16::MAX - 1, 65534, "\x1b[65535;65535H"),
        (u16::MAX, 0, "\x1b[1;65536H"),
    ] {
        let mut out = Vec::new();
        move_to(&mut out, x, y).unwrap();
        assert_eq!(String::from_utf8_lossy(&out), text);
    }
}
