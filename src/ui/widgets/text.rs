//! Text set into the buffer a character a cell where every character is its own one-cell
//! grapheme, which is all the explorer writes but for rare names: the cells ratatui's
//! `Buffer::set_line` and `Line`'s rendering give (tests compare them), without segmenting the
//! text into graphemes and measuring each (a tenth of the explorer's frame). Any other text takes
//! ratatui's own path.

use ratatui::buffer::{Buffer, Cell};
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::text::{Line, Span};
use ratatui::widgets::Widget;

/// Whether `c` is one cell wide and a grapheme of its own beside any other such character: the
/// printable ASCII and Latin-1 characters, Greek, dashes and punctuation, super- and subscripts,
/// arrows, mathematical operators, box drawing, blocks and shapes, braille, ✓ ✗ ⚠. A test checks
/// every one, and every pair, against ratatui's width and grapheme segmentation.
pub fn is_plain(c: char) -> bool {
    matches!(c,
        ' '..='~'
        | '\u{a0}'..='\u{ac}'
        | '\u{ae}'..='\u{ff}'
        | '\u{370}'..='\u{3ff}'
        | '\u{2010}'..='\u{2027}'
        | '\u{2070}'..='\u{209f}'
        | '\u{2190}'..='\u{22ff}'
        | '\u{2500}'..='\u{25fc}'
        | '\u{2800}'..='\u{28ff}'
        | '\u{26a0}'
        | '\u{2713}'
        | '\u{2717}')
}

/// The printable ASCII characters in order, from the space: each one's symbol is a slice of it.
const PRINTABLE: &str = " !\"#$%&'()*+,-./0123456789:;<=>?@ABCDEFGHIJKLMNOPQRSTUVWXYZ[\\]^_`abcdefghijklmnopqrstuvwxyz{|}~";

/// Whether `text` is all printable ASCII (all plain), checked a byte at a time.
fn printable_ascii(text: &str) -> bool {
    text.bytes().all(printable)
}

/// Whether byte `b` is a printable ASCII character.
fn printable(b: u8) -> bool {
    matches!(b, b' '..=b'~')
}

/// How a text can be set a character a cell.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    /// Printable ASCII only: set a byte at a time.
    Ascii,
    /// Plain characters, some beyond ASCII.
    Plain,
    /// Some character is not plain: ratatui's path.
    Other,
}

/// The kind of `text`: its ASCII start checked a byte at a time, the rest (if any) a character
/// at a time.
fn kind(text: &str) -> Kind {
    match text.bytes().position(|b| !printable(b)) {
        None => Kind::Ascii,
        // The bytes before are ASCII, so a character starts here.
        Some(i) if text[i..].chars().all(is_plain) => Kind::Plain,
        Some(_) => Kind::Other,
    }
}

fn all_plain(text: &str) -> bool {
    kind(text) != Kind::Other
}

/// Sets the plain `text` (all printable ASCII if `ascii`) from (x, y) into at most `width` cells
/// (and no further than the buffer's right edge), each patched with `style`; returns the column
/// after the last.
fn put_plain(
    buf: &mut Buffer,
    (x, y): (u16, u16),
    (text, ascii): (&str, bool),
    width: u16,
    style: Style,
) -> u16 {
    let area = buf.area;
    let room = area.right().saturating_sub(x).min(width);
    if room == 0 || !area.contains((x, y).into()) {
        return x;
    }
    let start = usize::from(y - area.y) * usize::from(area.width) + usize::from(x - area.x);
    let cells = buf.content[start..].iter_mut().take(usize::from(room));
    // The default style patches nothing.
    let patch = style != Style::default();
    let mut written = 0;
    if ascii {
        for (cell, b) in cells.zip(text.bytes()) {
            set_ascii(cell, b);
            if patch {
                cell.set_style(style);
            }
            written += 1;
        }
    } else {
        for (cell, c) in cells.zip(text.chars()) {
            match u8::try_from(c) {
                Ok(b @ b' '..=b'~') => set_ascii(cell, b),
                _ => {
                    cell.set_char(c);
                }
            }
            if patch {
                cell.set_style(style);
            }
            written += 1;
        }
    }
    x + written
}

/// Sets the printable ASCII `b` as the cell's symbol, as `Cell::set_char` does, without making a
/// new symbol where the cell shows it already (a space on a cleared cell, mostly).
fn set_ascii(cell: &mut Cell, b: u8) {
    if cell.symbol().as_bytes() != [b] {
        let i = usize::from(b - b' ');
        cell.set_symbol(&PRINTABLE[i..=i]);
    }
}

/// The columns `line` takes, as `Line::width` measures them, counting the characters of a plain
/// span (each takes one) rather than looking up each one's width.
pub fn line_width(line: &Line) -> usize {
    line.spans.iter().map(span_width).sum()
}

/// The columns `span` takes, as `Span::width` measures them (see [`line_width`]).
pub fn span_width(span: &Span) -> usize {
    match kind(&span.content) {
        Kind::Ascii => span.content.len(),
        Kind::Plain => span.content.chars().count(),
        Kind::Other => span.width(),
    }
}

/// What `buf.set_style(area, style)` does (each cell of `area` within the buffer patched with
/// `style`), a row slice at a time rather than a checked index a cell; nothing for the default
/// style, which patches nothing.
pub fn patch_style(buf: &mut Buffer, area: Rect, style: Style) {
    if style != Style::default() {
        each_cell(buf, area, |cell| {
            cell.set_style(style);
        });
    }
}

/// `f` on each cell of `area` within the buffer, row by row from the top left: a slice of the
/// buffer's cells a row rather than a checked index a cell.
pub fn each_cell(buf: &mut Buffer, area: Rect, mut f: impl FnMut(&mut Cell)) {
    let area = area.intersection(buf.area);
    if area.is_empty() {
        return;
    }
    let (width, left) = (
        usize::from(buf.area.width),
        usize::from(area.x - buf.area.x),
    );
    for y in area.top()..area.bottom() {
        let start = usize::from(y - buf.area.y) * width + left;
        for cell in &mut buf.content[start..start + usize::from(area.width)] {
            f(cell);
        }
    }
}

/// `text` from (x, y) in at most `width` cells, patched with `style`, as a `Span` of it renders
/// into a one-row area of that width (cut where the next character would not fit).
pub fn put_text(buf: &mut Buffer, (x, y): (u16, u16), text: &str, width: u16, style: Style) {
    let area = Rect::new(x, y, width, 1).intersection(buf.area);
    if area.is_empty() {
        return;
    }
    let kind = kind(text);
    if kind != Kind::Other {
        put_plain(
            buf,
            (area.x, area.y),
            (text, kind == Kind::Ascii),
            area.width,
            style,
        );
    } else {
        ratatui::text::Span::styled(text, style).render(area, buf);
    }
}

/// What `buf.set_line(x, y, line, max_width)` does: each span in the line's style patched with
/// its own, from x on, within `max_width` cells in all.
pub fn set_line(buf: &mut Buffer, x: u16, y: u16, line: &Line, max_width: u16) -> (u16, u16) {
    let mut remaining = max_width;
    let mut x = x;
    for span in line {
        if remaining == 0 {
            break;
        }
        let style = line.style.patch(span.style);
        let kind = kind(&span.content);
        let end = if kind != Kind::Other {
            put_plain(
                buf,
                (x, y),
                (&span.content, kind == Kind::Ascii),
                remaining,
                style,
            )
        } else {
            buf.set_stringn(x, y, span.content.as_ref(), usize::from(remaining), style)
                .0
        };
        remaining = remaining.saturating_sub(end.saturating_sub(x));
        x = end;
    }
    (x, y)
}

/// What rendering `line` into `area` does for a line without an alignment of its own (drawn
/// from the left, cut at the right): its style over its row, then each span in its own style.
pub fn render_line(buf: &mut Buffer, area: Rect, line: &Line) {
    if line.alignment.is_some() || !line.spans.iter().all(|s| all_plain(&s.content)) {
        line.render(area, buf);
        return;
    }
    let area = area.intersection(buf.area);
    if area.is_empty() || line.spans.iter().all(|s| s.content.is_empty()) {
        return;
    }
    let area = Rect { height: 1, ..area };
    patch_style(buf, area, line.style);
    let mut x = area.x;
    for span in &line.spans {
        if x >= area.right() {
            break;
        }
        put_plain(
            buf,
            (x, area.y),
            (&span.content, printable_ascii(&span.content)),
            area.right() - x,
            span.style,
        );
        let width = span.content.chars().count();
        x = x.saturating_add(u16::try_from(width).unwrap_or(u16::MAX));
    }
}

/// What a `Paragraph` of `line` aligned right draws into `area` (one row of it), without the
/// paragraph's line composer when the line is plain, in no style of its own and fits: then it is
/// the line drawn against the right edge.
pub fn render_right(buf: &mut Buffer, area: Rect, line: Line) {
    let room = area.intersection(buf.area);
    let width = line_width(&line);
    let plain = line.style == Style::default() && line.spans.iter().all(|s| all_plain(&s.content));
    match u16::try_from(width) {
        Ok(width) if plain && width <= room.width && room.height > 0 => {
            let at = Rect {
                x: room.right() - width,
                width,
                height: 1,
                ..room
            };
            render_line(
                buf,
                at,
                &Line {
                    alignment: None,
                    ..line
                },
            );
        }
        _ => ratatui::widgets::Paragraph::new(line.right_aligned()).render(area, buf),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ui::testing::busy_buffer;
    use ratatui::style::{Color, Modifier};
    use ratatui::text::Span;

    fn plain_chars() -> Vec<char> {
        (0..=0x3000u32)
            .filter_map(char::from_u32)
            .filter(|&c| is_plain(c))
            .collect()
    }

    /// Every plain character is one grapheme one cell wide, and every pair of them two graphemes,
    /// by ratatui's own measure and segmentation.
    #[test]
    fn plain_characters_are_graphemes_of_one_cell() {
        let plain = plain_chars();
        assert!(plain.len() > 1000, "{}", plain.len());
        let graphemes = |s: &str| {
            Span::raw(s.to_string())
                .styled_graphemes(Style::default())
                .map(|g| g.symbol.to_string())
                .collect::<Vec<_>>()
        };
        let mut pair = String::new();
        for &a in &plain {
            let one = a.to_string();
            assert_eq!(Span::raw(one.as_str()).width(), 1, "{a:?}");
            assert_eq!(graphemes(&one), std::slice::from_ref(&one), "{a:?}");
            for &b in &plain {
                pair.clear();
                pair.push(a);
                pair.push(b);
                assert_eq!(graphemes(&pair).len(), 2, "{a:?} {b:?}");
            }
        }
        for c in [
            '\u{ad}', '\u{301}', '\u{200b}', '中', '\u{fe0f}', '\u{25fd}', '\n',
        ] {
            assert!(!is_plain(c), "{c:?}");
        }
    }

    /// All the plain characters in one text, and the test lines: as wide as ratatui measures.
    #[test]
    fn line_width_is_what_ratatui_measures() {
        let all: String = plain_chars().into_iter().collect();
        let line = Line::from(all.as_str());
        assert_eq!(line_width(&line), line.width());
        for line in lines() {
            assert_eq!(line_width(&line), line.width(), "{line:?}");
            for span in &line.spans {
                assert_eq!(span_width(span), span.width(), "{span:?}");
            }
        }
    }

    #[test]
    fn a_text_is_ascii_plain_or_other() {
        assert_eq!(kind(""), Kind::Ascii);
        assert_eq!(kind("x_max 9.115 µm"), Kind::Plain);
        assert_eq!(kind("─┐"), Kind::Plain);
        assert_eq!(kind("Body 1 · sphere"), Kind::Plain);
        assert_eq!(kind("steel"), Kind::Ascii);
        assert_eq!(kind("e\u{301}"), Kind::Other);
        assert_eq!(kind("µ 中"), Kind::Other);
        assert_eq!(kind("tab\there"), Kind::Other);
        assert_eq!(kind("del\u{7f}"), Kind::Other);
    }

    /// Each printable ASCII character's symbol is the character.
    #[test]
    fn printable_holds_each_ascii_character_at_its_place() {
        let expected: String = (b' '..=b'~').map(char::from).collect();
        assert_eq!(PRINTABLE, expected);
    }

    /// Areas inside, across and off the buffer, styles that set and clear: the cells
    /// `Buffer::set_style` gives.
    #[test]
    fn patch_style_patches_what_buffer_set_style_patches() {
        let buf_area = Rect::new(1, 1, 30, 4);
        let styles = [
            Style::default(),
            Style::new().fg(Color::Red).add_modifier(Modifier::BOLD),
            Style::new()
                .bg(Color::Blue)
                .remove_modifier(Modifier::REVERSED),
        ];
        for style in styles {
            for area in [
                Rect::new(1, 1, 30, 4),
                Rect::new(4, 2, 12, 2),
                Rect::new(25, 3, 20, 5),
                Rect::new(3, 2, 0, 1),
                Rect::new(40, 2, 5, 1),
            ] {
                let mut ours = busy_buffer(buf_area);
                patch_style(&mut ours, area, style);
                let mut theirs = busy_buffer(buf_area);
                theirs.set_style(area, style);
                assert_eq!(ours, theirs, "{style:?} in {area:?}");
            }
        }
    }

    fn lines() -> Vec<Line<'static>> {
        let red = Style::new().fg(Color::Red).add_modifier(Modifier::BOLD);
        vec![
            Line::from(vec![
                Span::styled("● yield begins: ", red),
                Span::raw("v_y 0.0316 m/s ≤ v₀ 0.3 m/s < v_p"),
                Span::styled(" (p₀ = 1.1 / 2.8 σ_y)", Style::new().fg(Color::DarkGray)),
            ]),
            Line::from("Hunt–Crossley (eq 19) χ 0.6 … ✓ ⣀⡤⠔ ─┴┤")
                .patch_style(Style::new().add_modifier(Modifier::REVERSED)),
            Line::from(vec![
                Span::raw("café "),
                Span::styled("e\u{301} 中文 x", red),
                Span::raw(" ⚠\u{fe0f} after"),
            ]),
            Line::from(vec![Span::raw(""), Span::styled("", red)]),
            Line::from(vec![Span::raw(""), Span::styled(" x ", red)]),
        ]
    }

    /// Plain and other spans, line styles, cut by the width asked and by the buffer's edge:
    /// `set_line` sets what `Buffer::set_line` sets and returns where it stopped.
    #[test]
    fn set_line_sets_what_buffer_set_line_sets() {
        let buf_area = Rect::new(1, 1, 30, 3);
        for line in lines() {
            for (x, width) in [(1, 30), (3, 10), (20, 40), (30, 5), (5, 0), (2, 1)] {
                let mut ours = busy_buffer(buf_area);
                let end = set_line(&mut ours, x, 2, &line, width);
                let mut theirs = busy_buffer(buf_area);
                let their_end = theirs.set_line(x, 2, &line, width);
                assert_eq!(ours, theirs, "{line:?} at {x} in {width}");
                assert_eq!(end, their_end, "{line:?} at {x} in {width}");
            }
        }
    }

    /// The same lines into areas wide, narrow, empty and off the buffer: `render_line` draws
    /// what rendering the `Line` draws.
    #[test]
    fn render_line_draws_what_a_line_draws() {
        let buf_area = Rect::new(1, 1, 30, 3);
        for line in lines() {
            for area in [
                Rect::new(1, 1, 30, 1),
                Rect::new(4, 2, 12, 2),
                Rect::new(25, 3, 20, 1),
                Rect::new(3, 2, 0, 1),
                Rect::new(40, 2, 5, 1),
            ] {
                let mut ours = busy_buffer(buf_area);
                render_line(&mut ours, area, &line);
                let mut theirs = busy_buffer(buf_area);
                (&line).render(area, &mut theirs);
                assert_eq!(ours, theirs, "{line:?} in {area:?}");
            }
        }
    }

    /// The same lines, right-aligned, into areas wide, exact, narrow, empty and off the buffer:
    /// `render_right` draws what a right-aligned `Paragraph` of the line draws.
    #[test]
    fn render_right_draws_what_a_right_aligned_paragraph_draws() {
        let buf_area = Rect::new(1, 1, 30, 3);
        let mut all = lines();
        all.push(Line::from(vec![
            Span::styled("m", Style::new().fg(Color::Cyan)),
            Span::raw(" mouse  "),
            Span::styled("q", Style::new().fg(Color::Cyan)),
            Span::raw(" quit  "),
        ]));
        for line in all {
            let width = line.width() as u16;
            for area in [
                Rect::new(1, 1, 30, 1),
                Rect::new(4, 2, width, 1),
                Rect::new(4, 2, width.saturating_sub(1), 1),
                Rect::new(25, 3, 20, 1),
                Rect::new(3, 2, 0, 1),
                Rect::new(40, 2, 5, 1),
            ] {
                let mut ours = busy_buffer(buf_area);
                render_right(&mut ours, area, line.clone());
                let mut theirs = busy_buffer(buf_area);
                ratatui::widgets::Paragraph::new(line.clone().right_aligned())
                    .render(area, &mut theirs);
                assert_eq!(ours, theirs, "{line:?} in {area:?}");
            }
        }
    }
}
