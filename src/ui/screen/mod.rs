//! The terminal the explorer draws into: ratatui's `Terminal` for frames, resizing and the cursor,
//! with the buffer diff done by [`diff`], which finds the cells to rewrite in about a fifth of the
//! instructions ratatui's own diff takes on the explorer's frames, and the same cells.
//!
//! ratatui hands a frame's writes to the backend as a lazy diff. The `Terminal` here draws into a
//! [`Deferred`] backend that drops that diff unread and holds the cursor back; [`Screen::draw`]
//! then diffs the finished frame against what the terminal shows, writes the changed cells, and
//! replays the cursor, in ratatui's order.

mod deferred;
mod diff;
#[cfg(test)]
mod tests;

use ratatui::backend::Backend;
use ratatui::{Frame, Terminal};

use deferred::{CursorOp, Deferred};
use diff::Shown;

/// A full-screen terminal over the backend `B` (crossterm for the explorer, a test backend in
/// tests and benches).
#[derive(Debug)]
pub struct Screen<B: Backend> {
    terminal: Terminal<Deferred<B>>,
    /// What the terminal shows now.
    shown: Shown,
    /// The cells of the last frame that differed from what was shown (kept to reuse its memory).
    changed: Vec<usize>,
}

impl<B: Backend> Screen<B> {
    /// A screen over `backend`, taken to show nothing yet (as ratatui takes a new terminal).
    pub fn new(backend: B) -> Result<Self, B::Error> {
        let mut terminal = Terminal::new(Deferred::new(backend))?;
        let shown = Shown::blank(terminal.get_frame().area());
        Ok(Self {
            terminal,
            shown,
            changed: Vec::new(),
        })
    }

    /// Draws one frame: `render` fills it; the cells that changed are written, then the cursor is
    /// placed (or hidden) as `render` asked, and the backend is flushed.
    pub fn draw(&mut self, render: impl FnOnce(&mut Frame)) -> Result<(), B::Error> {
        self.terminal.backend_mut().drawing = true;
        let drawn = self.terminal.draw(render).map(|frame| {
            let next = frame.buffer;
            // ratatui clears a resized terminal (and only then): it shows nothing.
            if self.shown.buffer.area != next.area {
                self.shown = Shown::blank(next.area);
            }
            self.shown.update(next, &mut self.changed);
        });
        let backend = self.terminal.backend_mut();
        backend.drawing = false;
        let written = drawn.and_then(|()| write(backend, &self.shown, &self.changed));
        if written.is_err() {
            // What the terminal shows is unknown: the next frame is written whole.
            backend.cursor_ops.clear();
            self.shown = Shown::unknown(self.shown.buffer.area);
        }
        written
    }

    /// The terminal's size now.
    pub fn size(&self) -> Result<ratatui::layout::Size, B::Error> {
        self.terminal.size()
    }

    /// The backend (for tests: a `TestBackend`'s buffer is what the terminal shows).
    pub fn backend(&self) -> &B {
        &self.terminal.backend().inner
    }

    /// The backend, to change it between frames (a test backend's size, say).
    pub fn backend_mut(&mut self) -> &mut B {
        &mut self.terminal.backend_mut().inner
    }
}

/// A panic inside `render` leaves a frame unfinished: ratatui's `Terminal`, dropped after this,
/// shows the cursor again, which must reach the terminal, not wait for a frame.
impl<B: Backend> Drop for Screen<B> {
    fn drop(&mut self) {
        self.terminal.backend_mut().drawing = false;
    }
}

/// Writes the `changed` cells of `shown`, replays the frame's cursor requests, flushes.
fn write<B: Backend>(
    backend: &mut Deferred<B>,
    shown: &Shown,
    changed: &[usize],
) -> Result<(), B::Error> {
    let area = shown.buffer.area;
    let width = usize::from(area.width.max(1));
    let cells = &shown.buffer.content;
    backend.inner.draw(changed.iter().map(|&i| {
        // The index of a cell of the frame: its position fits in u16 as the area does.
        let x = area.x + (i % width) as u16;
        let y = area.y + (i / width) as u16;
        (x, y, &cells[i])
    }))?;
    for op in backend.cursor_ops.drain(..) {
        match op {
            CursorOp::Hide => backend.inner.hide_cursor()?,
            CursorOp::Show => backend.inner.show_cursor()?,
            CursorOp::MoveTo(position) => backend.inner.set_cursor_position(position)?,
        }
    }
    backend.inner.flush()
}
