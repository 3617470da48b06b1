//! Drawing a frame to the terminal: rendered by ratatui's terminal, in one synchronized update
//! and one write, with the bytes stock ratatui and crossterm would write (tested).
//!
//! The changed cells are found by [`OnScreen`] rather than by ratatui's own diff, and written by
//! `escapes` rather than by crossterm's backend (see each for why: together they were a quarter
//! of a frame). The terminal's backend therefore writes everything ratatui asks of it (the
//! cursor, a clear on a resize) except the cells it would diff, which are written from inside the
//! frame, where the rendered buffer is at hand, before the cursor is placed, as ratatui would.

use std::cell::RefCell;
use std::io::Write;
use std::rc::Rc;

use ratatui::backend::{Backend, ClearType, CrosstermBackend, WindowSize};
use ratatui::buffer::Cell;
use ratatui::crossterm::queue;
use ratatui::crossterm::terminal::{BeginSynchronizedUpdate, EndSynchronizedUpdate};
use ratatui::layout::{Position, Rect, Size};
use ratatui::{Terminal, TerminalOptions, Viewport};

use super::app::App;
use super::escapes;
use super::onscreen::OnScreen;
use super::render;

/// A frame's bytes, held until the frame is whole. ratatui writes a frame's cells as many small
/// commands and flushes its backend after them; through the standard output (a line writer of
/// 1 KiB) that was a write a kilobyte, and the synchronized update's begin, the cursor's hiding
/// and the update's end a write each: about ten writes a frame at 160×48. Here flushing keeps
/// the bytes, and [`FrameWriter::send`] writes them at once. Clones share the bytes: the
/// terminal's backend writes through one, the loop sends through another.
#[derive(Debug, Default, Clone)]
pub struct FrameWriter {
    bytes: Rc<RefCell<Vec<u8>>>,
}

impl Write for FrameWriter {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.bytes.borrow_mut().extend_from_slice(buf);
        Ok(buf.len())
    }

    /// Keeps the bytes: the frame is not whole yet.
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

impl FrameWriter {
    /// Writes the held bytes to `out` in one write and flushes it; holds nothing after.
    pub fn send(&self, out: &mut impl Write) -> std::io::Result<()> {
        let mut bytes = self.bytes.borrow_mut();
        out.write_all(&bytes)?;
        bytes.clear();
        out.flush()
    }
}

/// crossterm's backend, except that while a frame is drawn ratatui's diff of it is left out:
/// ratatui hands it to the backend, which never walks it (so it is never computed); the frame's
/// cells are written by [`Frames`] instead. Cells ratatui writes at other times (blanks, to clear
/// the screen on a resize) are written as they come.
struct AllButCells {
    crossterm: CrosstermBackend<FrameWriter>,
    drawing: bool,
}

impl Backend for AllButCells {
    type Error = std::io::Error;

    fn draw<'a, I>(&mut self, content: I) -> std::io::Result<()>
    where
        I: Iterator<Item = (u16, u16, &'a Cell)>,
    {
        if self.drawing {
            return Ok(());
        }
        self.crossterm.draw(content)
    }

    fn hide_cursor(&mut self) -> std::io::Result<()> {
        self.crossterm.hide_cursor()
    }

    fn show_cursor(&mut self) -> std::io::Result<()> {
        self.crossterm.show_cursor()
    }

    fn get_cursor_position(&mut self) -> std::io::Result<Position> {
        self.crossterm.get_cursor_position()
    }

    fn set_cursor_position<P: Into<Position>>(&mut self, position: P) -> std::io::Result<()> {
        self.crossterm.set_cursor_position(position)
    }

    fn clear(&mut self) -> std::io::Result<()> {
        self.crossterm.clear()
    }

    fn clear_region(&mut self, clear_type: ClearType) -> std::io::Result<()> {
        self.crossterm.clear_region(clear_type)
    }

    fn size(&self) -> std::io::Result<Size> {
        self.crossterm.size()
    }

    fn window_size(&mut self) -> std::io::Result<WindowSize> {
        self.crossterm.window_size()
    }

    fn flush(&mut self) -> std::io::Result<()> {
        Backend::flush(&mut self.crossterm)
    }
}

/// The terminal frames are drawn through: its writes held by a [`FrameWriter`], its size the
/// app's screen (set from the terminal's resize events), so a frame neither asks the terminal
/// for its size (crossterm opens `/dev/tty` and closes it again for that) nor writes in pieces.
pub struct Frames {
    terminal: Terminal<AllButCells>,
    onscreen: OnScreen,
    held: FrameWriter,
}

impl Frames {
    /// Frames of `width` × `height` cells until the app's screen says otherwise.
    pub fn new(width: u16, height: u16) -> std::io::Result<Frames> {
        let held = FrameWriter::default();
        let area = Rect::new(0, 0, width, height);
        let terminal = Terminal::with_options(
            AllButCells {
                crossterm: CrosstermBackend::new(held.clone()),
                drawing: false,
            },
            TerminalOptions {
                viewport: Viewport::Fixed(area),
            },
        )?;
        Ok(Frames {
            terminal,
            onscreen: OnScreen::blank(area),
            held,
        })
    }

    /// The area frames are drawn in.
    pub fn area(&mut self) -> Rect {
        self.terminal.get_frame().area()
    }
}

/// Draws one frame inside a synchronized update, so the terminal shows it whole, at the app's
/// screen size (resized first, and so cleared, where that changed), and writes it to `out` at
/// once.
pub fn draw_synchronized(
    frames: &mut Frames,
    out: &mut impl Write,
    app: &App,
) -> color_eyre::Result<()> {
    queue!(frames.held, BeginSynchronizedUpdate)?;
    let screen = Rect::new(0, 0, app.screen.0, app.screen.1);
    if frames.area() != screen {
        frames.terminal.resize(screen)?;
    }
    let (held, onscreen) = (&mut frames.held, &mut frames.onscreen);
    frames.terminal.backend_mut().drawing = true;
    let drawn = frames
        .terminal
        .try_draw(|frame| {
            render::draw(frame, app);
            let changes = onscreen.changes(frame.buffer_mut());
            escapes::write_changes(held, changes)
        })
        .map(|_| ());
    frames.terminal.backend_mut().drawing = false;
    queue!(frames.held, EndSynchronizedUpdate)?;
    frames.held.send(out)?;
    drawn?;
    Ok(())
}

#[cfg(test)]
#[path = "frames_tests.rs"]
mod tests;
