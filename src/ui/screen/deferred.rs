//! The backend ratatui's `Terminal` draws into inside [`super::Screen`]: it hands the cell writes
//! of a frame to the screen's own diff and holds the cursor back until those writes are out.

use ratatui::backend::{Backend, ClearType, WindowSize};
use ratatui::buffer::Cell;
use ratatui::layout::{Position, Size};

/// What ratatui asked of the cursor during a frame, replayed after the frame's cells are written
/// (in ratatui's own order: cells first, then the cursor).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum CursorOp {
    Hide,
    Show,
    MoveTo(Position),
}

/// A backend that forwards everything to `inner`, except while a frame is being drawn: then
/// ratatui's lazy buffer diff is dropped unread (so it costs nothing; the screen diffs instead) and
/// cursor requests wait in `cursor_ops`.
#[derive(Debug)]
pub(super) struct Deferred<B> {
    pub(super) inner: B,
    pub(super) drawing: bool,
    pub(super) cursor_ops: Vec<CursorOp>,
}

impl<B> Deferred<B> {
    pub(super) fn new(inner: B) -> Self {
        Self {
            inner,
            drawing: false,
            cursor_ops: Vec::new(),
        }
    }
}

impl<B: Backend> Backend for Deferred<B> {
    type Error = B::Error;

    fn draw<'a, I>(&mut self, content: I) -> Result<(), Self::Error>
    where
        I: Iterator<Item = (u16, u16, &'a Cell)>,
    {
        if self.drawing {
            Ok(())
        } else {
            self.inner.draw(content)
        }
    }

    fn append_lines(&mut self, n: u16) -> Result<(), Self::Error> {
        self.inner.append_lines(n)
    }

    fn hide_cursor(&mut self) -> Result<(), Self::Error> {
        if self.drawing {
            self.cursor_ops.push(CursorOp::Hide);
            Ok(())
        } else {
            self.inner.hide_cursor()
        }
    }

    fn show_cursor(&mut self) -> Result<(), Self::Error> {
        if self.drawing {
            self.cursor_ops.push(CursorOp::Show);
            Ok(())
        } else {
            self.inner.show_cursor()
        }
    }

    fn get_cursor_position(&mut self) -> Result<Position, Self::Error> {
        self.inner.get_cursor_position()
    }

    fn set_cursor_position<P: Into<Position>>(&mut self, position: P) -> Result<(), Self::Error> {
        let position = position.into();
        if self.drawing {
            self.cursor_ops.push(CursorOp::MoveTo(position));
            Ok(())
        } else {
            self.inner.set_cursor_position(position)
        }
    }

    fn clear(&mut self) -> Result<(), Self::Error> {
        self.inner.clear()
    }

    fn clear_region(&mut self, clear_type: ClearType) -> Result<(), Self::Error> {
        self.inner.clear_region(clear_type)
    }

    fn size(&self) -> Result<Size, Self::Error> {
        self.inner.size()
    }

    fn window_size(&mut self) -> Result<WindowSize, Self::Error> {
        self.inner.window_size()
    }

    /// A frame's flush waits for the screen's writes; outside a frame it goes through.
    fn flush(&mut self) -> Result<(), Self::Error> {
        if self.drawing {
            Ok(())
        } else {
            self.inner.flush()
        }
    }
}
