//! The contrast of text on its background as WCAG 2 defines it, for the test that holds every
//! style of every theme to 4.5:1 (docs/explorer.md, "Themes"). A terminal's colours are its own; the
//! computation takes xterm's defaults: the 16 ANSI colours at xterm's values, the 256-colour cube
//! and grey ramp as xterm builds them, and the default foreground and background of a dark
//! terminal as ANSI white (#e5e5e5) on black, of a light one as black on white.

use ratatui::style::{Color, Modifier};

/// A colour's red, green and blue, 0–255.
pub type Rgb = (u8, u8, u8);

/// xterm's default values of ANSI colours 0–15: black, red, green, yellow, blue, magenta, cyan,
/// white, then their bright variants.
pub const ANSI: [Rgb; 16] = [
    (0x00, 0x00, 0x00),
    (0xcd, 0x00, 0x00),
    (0x00, 0xcd, 0x00),
    (0xcd, 0xcd, 0x00),
    (0x00, 0x00, 0xee),
    (0xcd, 0x00, 0xcd),
    (0x00, 0xcd, 0xcd),
    (0xe5, 0xe5, 0xe5),
    (0x7f, 0x7f, 0x7f),
    (0xff, 0x00, 0x00),
    (0x00, 0xff, 0x00),
    (0xff, 0xff, 0x00),
    (0x5c, 0x5c, 0xff),
    (0xff, 0x00, 0xff),
    (0x00, 0xff, 0xff),
    (0xff, 0xff, 0xff),
];

/// A terminal's default colours, which `Color::Reset` stands for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Surface {
    pub foreground: Rgb,
    pub background: Rgb,
}

impl Surface {
    /// A dark terminal: ANSI white on black.
    pub const DARK: Surface = Surface {
        foreground: ANSI[7],
        background: ANSI[0],
    };
    /// A light terminal: black on white.
    pub const LIGHT: Surface = Surface {
        foreground: ANSI[0],
        background: ANSI[15],
    };
}

/// xterm's value of colour `index` of the 256: the 16 ANSI colours, the 6×6×6 cube (levels 0,
/// 95, 135, 175, 215, 255), then 24 greys from 8 to 238 in steps of 10.
pub fn indexed(index: u8) -> Rgb {
    const LEVELS: [u8; 6] = [0, 95, 135, 175, 215, 255];
    match index {
        0..=15 => ANSI[usize::from(index)],
        16..=231 => {
            let i = usize::from(index - 16);
            (LEVELS[i / 36], LEVELS[i / 6 % 6], LEVELS[i % 6])
        }
        232..=255 => {
            let v = 8 + 10 * (index - 232);
            (v, v, v)
        }
    }
}

/// The RGB a terminal shows `color` in, `default` for `Color::Reset`.
pub fn rgb(color: Color, default: Rgb) -> Rgb {
    match color {
        Color::Reset => default,
        Color::Black => ANSI[0],
        Color::Red => ANSI[1],
        Color::Green => ANSI[2],
        Color::Yellow => ANSI[3],
        Color::Blue => ANSI[4],
        Color::Magenta => ANSI[5],
        Color::Cyan => ANSI[6],
        Color::Gray => ANSI[7],
        Color::DarkGray => ANSI[8],
        Color::LightRed => ANSI[9],
        Color::LightGreen => ANSI[10],
        Color::LightYellow => ANSI[11],
        Color::LightBlue => ANSI[12],
        Color::LightMagenta => ANSI[13],
        Color::LightCyan => ANSI[14],
        Color::White => ANSI[15],
        Color::Indexed(i) => indexed(i),
        Color::Rgb(r, g, b) => (r, g, b),
    }
}

/// WCAG 2 relative luminance: sRGB channels linearised, weighted 0.2126, 0.7152, 0.0722.
pub fn luminance((r, g, b): Rgb) -> f64 {
    let linear = |c: u8| {
        let c = f64::from(c) / 255.0;
        if c <= 0.04045 {
            c / 12.92
        } else {
            ((c + 0.055) / 1.055).powf(2.4)
        }
    };
    0.2126 * linear(r) + 0.7152 * linear(g) + 0.0722 * linear(b)
}

/// WCAG 2 contrast ratio, (L₁ + 0.05) / (L₂ + 0.05) with L₁ the lighter: 1 to 21.
pub fn ratio(a: Rgb, b: Rgb) -> f64 {
    let (la, lb) = (luminance(a), luminance(b));
    (la.max(lb) + 0.05) / (la.min(lb) + 0.05)
}

/// The contrast of text in `fg` on `bg` with `modifier` on `surface`: reverse video swaps the two;
/// DIM (faint) is taken as the foreground half-way to the background, as terminals that render
/// it by blending do.
pub fn of_text(fg: Color, bg: Color, modifier: Modifier, surface: Surface) -> f64 {
    let mut fg = rgb(fg, surface.foreground);
    let mut bg = rgb(bg, surface.background);
    if modifier.contains(Modifier::REVERSED) {
        std::mem::swap(&mut fg, &mut bg);
    }
    if modifier.contains(Modifier::DIM) {
        let half = |f: u8, b: u8| ((u16::from(f) + u16::from(b)) / 2) as u8;
        fg = (half(fg.0, bg.0), half(fg.1, bg.1), half(fg.2, bg.2));
    }
    ratio(fg, bg)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Published values: black on white is 21:1, and the WCAG examples' #777777 on white 4.48:1.
    #[test]
    fn ratios_match_wcag() {
        assert!((ratio((0, 0, 0), (255, 255, 255)) - 21.0).abs() < 1e-9);
        assert!((ratio((0x77, 0x77, 0x77), (255, 255, 255)) - 4.478).abs() < 1e-3);
        assert_eq!(indexed(69), (95, 135, 255));
        assert_eq!(indexed(242), (108, 108, 108));
        assert_eq!(indexed(196), (255, 0, 0));
        // The measurements: ANSI blue on black and yellow and cyan on white.
        let on_black = |c| of_text(c, Color::Reset, Modifier::empty(), Surface::DARK);
        let on_white = |c| of_text(c, Color::Reset, Modifier::empty(), Surface::LIGHT);
        assert!((on_black(Color::Blue) - 2.23).abs() < 0.01);
        assert!((on_white(Color::Yellow) - 1.71).abs() < 0.01);
        assert!((on_white(Color::Cyan) - 1.98).abs() < 0.01);
        let dim = of_text(Color::Reset, Color::Reset, Modifier::DIM, Surface::DARK);
        assert!(dim < 4.5, "faint text on black: {dim}");
    }
}
