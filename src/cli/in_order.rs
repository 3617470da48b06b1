//! Output made in parallel and written in order: one worker per core takes the next piece as soon
//! as it is free and fills a buffer; the calling thread writes each piece once those before it are
//! written. No barrier between batches, so no core waits for another's last piece (a sweep's CSV
//! kept both cores busy only 87–94 % of the time with one); at most a window of pieces is in
//! flight, so memory does not grow with the output.

use std::collections::VecDeque;
use std::io::{self, Write};
use std::num::NonZero;
use std::sync::{Condvar, Mutex, MutexGuard};
use std::thread;

/// Pieces filled or being filled ahead of the one being written, per worker.
const AHEAD_PER_WORKER: usize = 4;

/// Writes to `out` the bytes `fill(i, buffer)` appends for every piece i in `0..pieces`, in order;
/// `fill` runs on every core, each call into a cleared buffer reused from a written piece. Stops
/// at the first write error and returns it.
pub fn write_in_order<F>(pieces: usize, out: &mut dyn Write, fill: F) -> io::Result<()>
where
    F: Fn(usize, &mut Vec<u8>) + Sync,
{
    let workers = thread::available_parallelism().map_or(1, NonZero::get);
    let queue = Queue {
        state: Mutex::new(State {
            pieces,
            window: AHEAD_PER_WORKER * workers,
            next: 0,
            written: 0,
            filled: VecDeque::new(),
            spare: Vec::new(),
            stopped: false,
        }),
        filled: Condvar::new(),
        written: Condvar::new(),
    };
    thread::scope(|scope| {
        for _ in 0..workers {
            scope.spawn(|| queue.work(&fill));
        }
        let result = queue.write(out);
        queue.stop();
        result
    })
}

/// The pieces between the workers and the writer.
struct Queue {
    state: Mutex<State>,
    /// Signalled when a piece is filled.
    filled: Condvar,
    /// Signalled when a piece is taken to be written (room in the window) or the work stops.
    written: Condvar,
}

struct State {
    pieces: usize,
    window: usize,
    /// The next piece a worker takes.
    next: usize,
    /// Pieces taken by the writer.
    written: usize,
    /// Pieces `written`, `written + 1`, …: filled, or still being filled (`None`).
    filled: VecDeque<Option<Vec<u8>>>,
    /// Buffers of written pieces, for reuse.
    spare: Vec<Vec<u8>>,
    /// Set when writing failed or a worker panicked: nothing more is filled or written.
    stopped: bool,
}

impl Queue {
    fn lock(&self) -> MutexGuard<'_, State> {
        // A worker that panicked stopped the queue first (`Abandon`): the state is consistent.
        self.state
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner())
    }

    /// A worker: fills pieces until none is left or the queue stops.
    fn work(&self, fill: &(impl Fn(usize, &mut Vec<u8>) + Sync)) {
        let _abandon = Abandon(self);
        let mut state = self.lock();
        loop {
            while !state.stopped
                && state.next < state.pieces
                && state.next >= state.written + state.window
            {
                state = self.written.wait(state).unwrap_or_else(|p| p.into_inner());
            }
            if state.stopped || state.next >= state.pieces {
                return;
            }
            let index = state.next;
            state.next += 1;
            let mut buffer = state.spare.pop().unwrap_or_default();
            drop(state);
            buffer.clear();
            fill(index, &mut buffer);
            state = self.lock();
            let slot = index - state.written;
            if state.filled.len() <= slot {
                state.filled.resize(slot + 1, None);
            }
            state.filled[slot] = Some(buffer);
            self.filled.notify_one();
        }
    }

    /// The writer: each piece in order, as soon as it is filled.
    fn write(&self, out: &mut dyn Write) -> io::Result<()> {
        loop {
            let buffer = {
                let mut state = self.lock();
                loop {
                    if state.stopped || state.written >= state.pieces {
                        return Ok(());
                    }
                    if let Some(Some(_)) = state.filled.front() {
                        break;
                    }
                    state = self.filled.wait(state).unwrap_or_else(|p| p.into_inner());
                }
                state.written += 1;
                self.written.notify_all();
                state.filled.pop_front().flatten().unwrap_or_default()
            };
            out.write_all(&buffer)?;
            self.lock().spare.push(buffer);
        }
    }

    /// Stops the workers waiting for room and the writer waiting for a piece.
    fn stop(&self) {
        self.lock().stopped = true;
        self.written.notify_all();
        self.filled.notify_all();
    }
}

/// Stops the queue if its worker unwinds, so the writer does not wait for a piece that will never
/// come; the panic then reaches the caller through the thread scope.
struct Abandon<'a>(&'a Queue);

impl Drop for Abandon<'_> {
    fn drop(&mut self) {
        if thread::panicking() {
            self.0.stop();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Piece i is the line `i`, each filled after a delay that varies so workers finish out of order.
    fn numbered(pieces: usize, out: &mut dyn Write) -> io::Result<()> {
        write_in_order(pieces, out, |i, buffer| {
            thread::sleep(std::time::Duration::from_micros(
                ((i * 7919) % 13) as u64 * 50,
            ));
            buffer.extend_from_slice(format!("{i}\n").as_bytes());
        })
    }

    #[test]
    fn pieces_come_out_once_each_in_order() {
        for pieces in [0, 1, 3, 200] {
            let mut out = Vec::new();
            numbered(pieces, &mut out).unwrap();
            let expected: String = (0..pieces).map(|i| format!("{i}\n")).collect();
            assert_eq!(String::from_utf8(out).unwrap(), expected);
        }
    }

    /// Accepts `room` bytes, then fails.
    struct Full {
        room: usize,
    }

    impl Write for Full {
        fn write(&mut self, bytes: &[u8]) -> io::Result<usize> {
            if self.room == 0 {
                return Err(io::Error::new(io::ErrorKind::StorageFull, "disk full"));
            }
            let n = bytes.len().min(self.room);
            self.room -= n;
            Ok(n)
        }

        fn flush(&mut self) -> io::Result<()> {
            Ok(())
        }
    }

    #[test]
    fn a_write_error_stops_the_work_and_is_returned() {
        let err = numbered(10_000, &mut Full { room: 100 }).unwrap_err();
        assert_eq!(err.kind(), io::ErrorKind::StorageFull);
    }

    #[test]
    fn a_panicking_piece_reaches_the_caller_instead_of_hanging() {
        let outcome = std::panic::catch_unwind(|| {
            write_in_order(100, &mut Vec::new(), |i, buffer| {
                assert_ne!(i, 37, "piece 37 fails");
                buffer.push(b'.');
            })
        });
        assert!(outcome.is_err());
    }
}
