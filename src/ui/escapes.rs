//! The bytes that write a frame's changed cells: exactly those of ratatui's crossterm backend
//! (tested), with the cursor moves and the symbols written directly rather than through
//! `core::fmt`, one `Print` a cell and a `MoveTo` a run (the explorer's frame: 0.5M instructions
//! in crossterm's backend, 0.3M here; docs/performance.md). Colours and attributes, which change
//! far less often, still go through crossterm's commands.

use std::io::{self, Write};

use ratatui::crossterm::queue;
use ratatui::crossterm::style::{
    Attribute, Color as CrosstermColor, Colors, SetAttribute, SetBackgroundColor, SetColors,
    SetForegroundColor, SetUnderlineColor,
};
use ratatui::style::{Color, Modifier};

use super::onscreen::Change;

/// crossterm's colour for ratatui's, as ratatui's crossterm backend converts it.
fn crossterm_color(color: Color) -> CrosstermColor {
    use ratatui::backend::IntoCrossterm;
    color.into_crossterm()
}

/// Writes `changes` to `out` as ratatui's crossterm backend draws them: from the default style,
/// a cursor move wherever a cell does not follow the last, the style's changes, the symbol, and
/// every style reset at the end.
pub fn write_changes<'a>(
    out: &mut impl Write,
    changes: impl IntoIterator<Item = Change<'a>>,
) -> io::Result<()> {
    let (mut fg, mut bg, mut underline) = (Color::Reset, Color::Reset, Color::Reset);
    let mut modifier = Modifier::empty();
    let mut last: Option<(u16, u16)> = None;
    for (x, y, cell) in changes {
        if !matches!(last, Some((lx, ly)) if x == lx.wrapping_add(1) && y == ly) {
            move_to(out, x, y)?;
        }
        last = Some((x, y));
        if cell.modifier != modifier {
            change_modifier(out, modifier, cell.modifier)?;
            modifier = cell.modifier;
        }
        if cell.fg != fg || cell.bg != bg {
            let colors = Colors::new(crossterm_color(cell.fg), crossterm_color(cell.bg));
            queue!(out, SetColors(colors))?;
            (fg, bg) = (cell.fg, cell.bg);
        }
        if cell.underline_color != underline {
            queue!(
                out,
                SetUnderlineColor(crossterm_color(cell.underline_color))
            )?;
            underline = cell.underline_color;
        }
        out.write_all(cell.symbol().as_bytes())?;
    }
    queue!(
        out,
        SetForegroundColor(CrosstermColor::Reset),
        SetBackgroundColor(CrosstermColor::Reset),
        SetUnderlineColor(CrosstermColor::Reset),
        SetAttribute(Attribute::Reset),
    )
}

/// `CSI row ; column H`, one-based, as crossterm's `MoveTo` writes it.
fn move_to(out: &mut impl Write, x: u16, y: u16) -> io::Result<()> {
    let mut bytes = [0u8; 16];
    bytes[..2].copy_from_slice(b"\x1b[");
    let at = decimal(&mut bytes, 2, u32::from(y) + 1);
    bytes[at] = b';';
    let at = decimal(&mut bytes, at + 1, u32::from(x) + 1);
    bytes[at] = b'H';
    out.write_all(&bytes[..=at])
}

/// Writes `n` in decimal into `bytes` from `at`; where it ends.
fn decimal(bytes: &mut [u8; 16], at: usize, n: u32) -> usize {
    let digits = n.checked_ilog10().unwrap_or(0) as usize + 1;
    let mut rest = n;
    for i in (at..at + digits).rev() {
        bytes[i] = b'0' + (rest % 10) as u8;
        rest /= 10;
    }
    at + digits
}

/// The attribute changes from `from` to `to`, in the order ratatui's crossterm backend writes
/// them (its `ModifierDiff`): removals first, bold and dim reset together and set again.
fn change_modifier(out: &mut impl Write, from: Modifier, to: Modifier) -> io::Result<()> {
    let removed = from - to;
    if removed.contains(Modifier::REVERSED) {
        queue!(out, SetAttribute(Attribute::NoReverse))?;
    }
    let reset_intensity = removed.intersects(Modifier::BOLD | Modifier::DIM);
    if reset_intensity {
        queue!(out, SetAttribute(Attribute::NormalIntensity))?;
        if to.contains(Modifier::DIM) {
            queue!(out, SetAttribute(Attribute::Dim))?;
        }
        if to.contains(Modifier::BOLD) {
            queue!(out, SetAttribute(Attribute::Bold))?;
        }
    }
    for (modifier, attribute) in [
        (Modifier::ITALIC, Attribute::NoItalic),
        (Modifier::UNDERLINED, Attribute::NoUnderline),
        (Modifier::CROSSED_OUT, Attribute::NotCrossedOut),
        (Modifier::HIDDEN, Attribute::NoHidden),
    ] {
        if removed.contains(modifier) {
            queue!(out, SetAttribute(attribute))?;
        }
    }
    if removed.intersects(Modifier::SLOW_BLINK | Modifier::RAPID_BLINK) {
        queue!(out, SetAttribute(Attribute::NoBlink))?;
    }
    let added = to - from;
    for (modifier, attribute, unless_reset) in [
        (Modifier::REVERSED, Attribute::Reverse, false),
        (Modifier::BOLD, Attribute::Bold, true),
        (Modifier::ITALIC, Attribute::Italic, false),
        (Modifier::UNDERLINED, Attribute::Underlined, false),
        (Modifier::DIM, Attribute::Dim, true),
        (Modifier::CROSSED_OUT, Attribute::CrossedOut, false),
        (Modifier::HIDDEN, Attribute::Hidden, false),
        (Modifier::SLOW_BLINK, Attribute::SlowBlink, false),
        (Modifier::RAPID_BLINK, Attribute::RapidBlink, false),
    ] {
        if added.contains(modifier) && !(unless_reset && reset_intensity) {
            queue!(out, SetAttribute(attribute))?;
        }
    }
    Ok(())
}

#[cfg(test)]
#[path = "escapes_tests.rs"]
mod tests;
