//! The screen writes what ratatui's own `Terminal` writes: the same cells, the same cursor, frame
//! after frame, on random frames (wide characters, emoji, skipped cells, diff options and styles
//! included) and on the explorer's own frames.

use proptest::prelude::*;
use ratatui::Terminal;
use ratatui::backend::{Backend, ClearType, TestBackend, WindowSize};
use ratatui::buffer::{Buffer, Cell, CellDiffOption, CellWidth};
use ratatui::layout::{Position, Rect, Size};
use ratatui::style::{Color, Modifier, Style};
use std::num::NonZeroU16;
use std::sync::{Arc, Mutex};

use super::Screen;
use super::diff::{Shown, known_narrow};
use crate::model::presets::Registry;
use crate::ui::action::Action;
use crate::ui::app::App;
use crate::ui::field::Nudge;
use crate::ui::render;
use crate::ui::style::{MarkerStyle, Theme};
use crate::ui::testing::fig5_scene;
use crate::ui::update::update;

#[test]
fn the_known_narrow_symbols_are_one_column_wide_by_ratatuis_measure() {
    let inside = ('\u{2500}'..='\u{259F}').chain('\u{2800}'..='\u{28FF}');
    for c in inside {
        let s = c.to_string();
        assert!(known_narrow(&s), "{c:?} ({:X}) is recognised", c as u32);
        assert_eq!(s.cell_width(), 1, "{c:?} ({:X}) is one column", c as u32);
    }
    // Just outside: geometric shapes (some of them emoji, two columns), arrows, CJK.
    for c in [
        '\u{24FF}', '\u{25A0}', '\u{25FD}', '\u{27FF}', '\u{2900}', 'µ', '漢',
    ] {
        assert!(
            !known_narrow(&c.to_string()),
            "{c:?} is measured, not assumed"
        );
    }
}

/// A cell's content drawn from symbols of every width ratatui distinguishes.
const SYMBOLS: [&str; 14] = [
    " ",
    "a",
    "Z",
    "⣿",
    "⠁",
    "─",
    "│",
    "µ",
    "·",
    "漢",
    "😀",
    "❤\u{FE0F}",
    "e\u{301}",
    "ﾞ",
];
const NARROW: usize = 9;

#[derive(Debug, Clone)]
struct CellSpec {
    symbol: usize,
    fg: u8,
    bg: u8,
    bold: bool,
    option: u8,
}

fn cell_spec(symbols: usize) -> impl Strategy<Value = CellSpec> {
    (0..symbols, 0u8..4, 0u8..3, any::<bool>(), 0u8..12).prop_map(
        |(symbol, fg, bg, bold, option)| CellSpec {
            symbol,
            fg,
            bg,
            bold,
            option,
        },
    )
}

fn color(i: u8) -> Color {
    [
        Color::Reset,
        Color::Red,
        Color::Rgb(1, 2, 3),
        Color::Indexed(7),
    ][usize::from(i % 4)]
}

/// Draws `specs` into `buf` by ratatui's own `set_string` (which pads wide symbols as ratatui
/// does), then sets the rarer cell options.
fn fill(buf: &mut Buffer, specs: &[CellSpec], options: bool) {
    let area = buf.area;
    for (i, spec) in specs.iter().enumerate().take(area.area() as usize) {
        let x = (i % usize::from(area.width)) as u16;
        let y = (i / usize::from(area.width)) as u16;
        let mut style = ratatui::style::Style::new()
            .fg(color(spec.fg))
            .bg(color(spec.bg));
        if spec.bold {
            style = style.add_modifier(Modifier::BOLD);
        }
        buf.set_string(x, y, SYMBOLS[spec.symbol], style);
    }
    if options {
        for (cell, spec) in buf.content.iter_mut().zip(specs) {
            match spec.option {
                0 => cell.diff_option = CellDiffOption::AlwaysUpdate,
                1 => cell.diff_option = CellDiffOption::Skip,
                2 => cell.diff_option = CellDiffOption::ForcedWidth(NonZeroU16::MIN),
                #[allow(deprecated)]
                3 => cell.skip = true,
                _ => {}
            }
        }
    }
}

/// One frame: its cells, where it puts the cursor (if anywhere), and whether the terminal was
/// resized before it.
type FrameSpec = (Vec<CellSpec>, Option<(u16, u16)>, bool);

/// One to five frames of 7×3 cells: a cursor or none, and a size that sometimes changes.
fn frames(symbols: usize) -> impl Strategy<Value = Vec<FrameSpec>> {
    prop::collection::vec(
        (
            prop::collection::vec(cell_spec(symbols), 21),
            prop::option::of((0u16..7, 0u16..3)),
            prop::bool::weighted(0.15),
        ),
        1..6,
    )
}

/// What a backend was asked, in order.
#[derive(Debug, Clone, PartialEq)]
enum Call {
    Draw(u16, u16, Cell),
    Hide,
    Show,
    MoveTo(Position),
    Clear,
    ClearRegion(ClearType),
    Flush,
}

/// A test backend that logs every call that changes the terminal, and can be made to fail the
/// next frame's cell writes.
#[derive(Debug)]
struct Recorder {
    inner: TestBackend,
    log: Arc<Mutex<Vec<Call>>>,
    fail_next_draw: bool,
}

impl Recorder {
    fn new(width: u16, height: u16) -> Self {
        Self {
            inner: TestBackend::new(width, height),
            log: Arc::default(),
            fail_next_draw: false,
        }
    }

    fn calls(&self) -> Vec<Call> {
        self.log.lock().unwrap().clone()
    }

    fn record(&self, call: Call) {
        self.log.lock().unwrap().push(call);
    }
}

impl Backend for Recorder {
    type Error = std::io::Error;

    fn draw<'a, I>(&mut self, content: I) -> std::io::Result<()>
    where
        I: Iterator<Item = (u16, u16, &'a Cell)>,
    {
        if std::mem::take(&mut self.fail_next_draw) {
            return Err(std::io::Error::other("the terminal went away"));
        }
        let cells: Vec<(u16, u16, Cell)> = content.map(|(x, y, c)| (x, y, c.clone())).collect();
        for (x, y, c) in &cells {
            self.record(Call::Draw(*x, *y, c.clone()));
        }
        self.inner
            .draw(cells.iter().map(|(x, y, c)| (*x, *y, c)))
            .map_err(std::io::Error::other)
    }

    fn hide_cursor(&mut self) -> std::io::Result<()> {
        self.record(Call::Hide);
        self.inner.hide_cursor().map_err(std::io::Error::other)
    }

    fn show_cursor(&mut self) -> std::io::Result<()> {
        self.record(Call::Show);
        self.inner.show_cursor().map_err(std::io::Error::other)
    }

    fn get_cursor_position(&mut self) -> std::io::Result<Position> {
        self.inner
            .get_cursor_position()
            .map_err(std::io::Error::other)
    }

    fn set_cursor_position<P: Into<Position>>(&mut self, position: P) -> std::io::Result<()> {
        let position = position.into();
        self.record(Call::MoveTo(position));
        self.inner
            .set_cursor_position(position)
            .map_err(std::io::Error::other)
    }

    fn clear(&mut self) -> std::io::Result<()> {
        self.record(Call::Clear);
        self.inner.clear().map_err(std::io::Error::other)
    }

    fn clear_region(&mut self, clear_type: ClearType) -> std::io::Result<()> {
        self.record(Call::ClearRegion(clear_type));
        self.inner
            .clear_region(clear_type)
            .map_err(std::io::Error::other)
    }

    fn size(&self) -> std::io::Result<Size> {
        self.inner.size().map_err(std::io::Error::other)
    }

    fn window_size(&mut self) -> std::io::Result<WindowSize> {
        self.inner.window_size().map_err(std::io::Error::other)
    }

    fn flush(&mut self) -> std::io::Result<()> {
        self.record(Call::Flush);
        Ok(())
    }
}

/// The screen's backend was asked what the terminal's was, in the same order, and shows the same.
fn assert_same_writes(screen: &Screen<Recorder>, terminal: &Terminal<Recorder>, what: &str) {
    assert_eq!(
        screen.backend().calls(),
        terminal.backend().calls(),
        "{what}"
    );
    assert_eq!(screen.backend().inner, terminal.backend().inner, "{what}");
}

/// Draws `frames` through ratatui's `Terminal` and through a `Screen`: the two backends are asked
/// the same things in the same order (cells, cursor, clears, flushes) and show the same.
fn compare(frames: Vec<FrameSpec>, options: bool) {
    let mut terminal = Terminal::new(Recorder::new(7, 3)).unwrap();
    let mut screen = Screen::new(Recorder::new(7, 3)).unwrap();
    for (k, (specs, cursor, resize)) in frames.into_iter().enumerate() {
        if resize {
            let (w, h) = if k % 2 == 0 { (6, 3) } else { (7, 2) };
            terminal.backend_mut().inner.resize(w, h);
            screen.backend_mut().inner.resize(w, h);
        }
        let draw = |frame: &mut ratatui::Frame| {
            let area = frame.area();
            fill(frame.buffer_mut(), &specs, options);
            if let Some((x, y)) = cursor {
                frame.set_cursor_position(Position::new(
                    x.min(area.width - 1),
                    y.min(area.height - 1),
                ));
            }
        };
        terminal.draw(draw).unwrap();
        screen.draw(draw).unwrap();
        assert_same_writes(&screen, &terminal, &format!("frame {k}"));
    }
}

/// A frame whose writes fail leaves the terminal unknown: the next frame is written whole, so the
/// terminal shows it exactly, and the failed frame's cursor request is not replayed.
#[test]
fn after_a_failed_write_the_next_frame_is_written_whole() {
    let mut screen = Screen::new(Recorder::new(7, 3)).unwrap();
    let text = |s: &'static str| {
        move |frame: &mut ratatui::Frame| {
            frame.buffer_mut().set_string(0, 0, s, Style::new());
        }
    };
    screen.draw(text("abcdefg")).unwrap();
    screen.backend_mut().fail_next_draw = true;
    let failed = screen.draw(|frame| {
        frame.buffer_mut().set_string(0, 1, "zzz", Style::new());
        frame.set_cursor_position(Position::new(2, 2));
    });
    assert!(failed.is_err());
    screen.backend().log.lock().unwrap().clear();
    screen.draw(text("abcdefg")).unwrap();
    let calls = screen.backend().calls();
    let drawn = calls.iter().filter(|c| matches!(c, Call::Draw(..))).count();
    assert_eq!(drawn, 21, "every cell rewritten");
    assert!(
        !calls.contains(&Call::MoveTo(Position::new(2, 2))),
        "{calls:?}"
    );
    let mut expected = TestBackend::new(7, 3);
    expected
        .draw(
            Buffer::with_lines(["abcdefg", "       ", "       "])
                .content
                .iter()
                .enumerate()
                .map(|(i, c)| ((i % 7) as u16, (i / 7) as u16, c)),
        )
        .unwrap();
    assert_eq!(screen.backend().inner.buffer(), expected.buffer());
}

/// A panic while a frame is rendered: the screen, dropped as the panic unwinds, shows the cursor
/// again (ratatui's `Terminal` does on drop), rather than leaving the shell without one.
#[test]
fn a_panic_in_a_frame_leaves_the_cursor_shown() {
    let recorder = Recorder::new(7, 3);
    let log = Arc::clone(&recorder.log);
    let unwound = std::panic::catch_unwind(std::panic::AssertUnwindSafe(move || {
        let mut screen = Screen::new(recorder).unwrap();
        // No cursor asked for: ratatui hides it.
        screen.draw(|_| {}).unwrap();
        let _ = screen.draw(|_| panic!("a render bug (expected by this test)"));
    }));
    assert!(unwound.is_err());
    let calls = log.lock().unwrap().clone();
    assert!(calls.contains(&Call::Hide), "{calls:?}");
    assert_eq!(calls.last(), Some(&Call::Show), "{calls:?}");
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 1500, ..ProptestConfig::default() })]

    /// Narrow cells only: the fast path.
    #[test]
    fn narrow_frames_are_written_as_ratatui_writes_them(frames in frames(NARROW)) {
        compare(frames, false);
    }

    /// Every kind of cell: wide characters, emoji, combining marks and cell options.
    #[test]
    fn any_frames_are_written_as_ratatui_writes_them(frames in frames(SYMBOLS.len())) {
        compare(frames, true);
    }

    /// The cells written are the ones ratatui's diff writes, in its order, and the shown frame
    /// becomes the next one.
    #[test]
    fn the_diff_is_ratatuis(
        before in prop::collection::vec(cell_spec(SYMBOLS.len()), 21),
        after in prop::collection::vec(cell_spec(SYMBOLS.len()), 21),
        narrow_before in any::<bool>(),
        narrow_after in any::<bool>(),
        options in any::<bool>(),
    ) {
        let area = Rect::new(0, 0, 7, 3);
        // Narrow frames after any, and any after narrow, as well as narrow after narrow.
        let pick = |specs: Vec<CellSpec>, narrow: bool| -> Vec<CellSpec> {
            specs.into_iter().map(|mut s| { if narrow { s.symbol %= NARROW; } s }).collect()
        };
        let (mut shown, mut next) = (Buffer::empty(area), Buffer::empty(area));
        fill(&mut shown, &pick(before, narrow_before), options);
        fill(&mut next, &pick(after, narrow_after), options);
        let expected: Vec<usize> = shown.diff(&next).into_iter().map(|(x, y, _)| next.index_of(x, y)).collect();
        // The terminal shows `before` after a first frame, so that what it knows of its cells
        // (plain or not) is what drawing `before` taught it.
        let mut changed = vec![99];
        let mut screen = Shown::blank(area);
        screen.update(&shown, &mut changed);
        screen.update(&next, &mut changed);
        prop_assert_eq!(changed, expected);
        prop_assert_eq!(&screen.buffer, &next);
    }
}

#[test]
fn the_explorer_is_written_as_ratatui_writes_it() {
    let mut app = App::new(
        fig5_scene(),
        Registry::builtin().unwrap(),
        MarkerStyle::Braille,
        Theme { color: true },
    );
    update(&mut app, Action::Resize(120, 36));
    let mut terminal = Terminal::new(Recorder::new(120, 36)).unwrap();
    let mut screen = Screen::new(Recorder::new(120, 36)).unwrap();
    let steps = [
        None,
        Some(Action::Nudge(Nudge::Up)),
        Some(Action::Nudge(Nudge::Down)),
        Some(Action::Help),
        Some(Action::Cancel),
        Some(Action::Enter),
        Some(Action::MoveCursor(false)),
        Some(Action::Cancel),
    ];
    for (k, step) in steps.into_iter().enumerate() {
        if let Some(action) = step {
            update(&mut app, action);
        }
        for job in app.take_jobs() {
            update(&mut app, Action::Solved(Ok(crate::ui::worker::solve(&job))));
        }
        terminal.draw(|frame| render::draw(frame, &app)).unwrap();
        screen.draw(|frame| render::draw(frame, &app)).unwrap();
        assert_same_writes(&screen, &terminal, &format!("step {k}"));
    }
    // A resize: both clear and redraw everything.
    terminal.backend_mut().inner.resize(100, 30);
    screen.backend_mut().inner.resize(100, 30);
    update(&mut app, Action::Resize(100, 30));
    terminal.draw(|frame| render::draw(frame, &app)).unwrap();
    screen.draw(|frame| render::draw(frame, &app)).unwrap();
    assert_same_writes(&screen, &terminal, "after the resize");
}
