//! The event loop: blocks until a key, a resize or a solver or study report arrives, updates,
//! redraws. Input is read on its own thread, solves and studies each on a job queue of their own,
//! so none blocks another.
//!
//! Redraws are coalesced: the input thread reads every event the terminal has already sent and
//! passes them on together, and the loop handles everything waiting in its channel before one
//! draw, so a burst (keys typed ahead over a slow link, a held key while a frame is drawn) is
//! drawn once. The loop never waits for keys that may come; it waits only for the solves a key
//! has started, which take well under a millisecond for every law of the table, so that the key
//! and its results are one frame, not a frame of "computing" marks and another soon after; a
//! slower solve is drawn as computing [`SOLVE_WAIT`] after the key and again when it reports. Each frame is wrapped in synchronized
//! output (terminals that support it show it at once; others ignore the sequence). Bracketed
//! paste is on, so that pasted text arrives as one paste and never as keys; mouse capture follows
//! the app's `m` toggle.

use std::io::Write;
use std::sync::mpsc::{self, Receiver, RecvTimeoutError, Sender};
use std::thread;
use std::time::{Duration, Instant};

use color_eyre::eyre::{WrapErr, eyre};
use ratatui::crossterm::event::{
    self, DisableBracketedPaste, DisableMouseCapture, EnableBracketedPaste, EnableMouseCapture,
};
use ratatui::crossterm::execute;
use ratatui::crossterm::terminal::{BeginSynchronizedUpdate, EndSynchronizedUpdate};
use ratatui::{DefaultTerminal, Terminal};

use crate::model::study::runner::{StudyJob, StudyOutcome};

use super::action::Action;
use super::app::App;
use super::jobs::{Jobs, Report};
use super::keymap::action_for_event;
use super::render;
use super::solutions::{Job, Outcome};
use super::update::update;

/// What wakes the loop.
enum Wake {
    /// Every terminal event that was waiting when the input thread read (never empty).
    Terminal(Vec<event::Event>),
    Solver(Report<Outcome>),
    Study(Report<StudyOutcome>),
    InputFailed(String),
}

fn spawn_input(events: Sender<Wake>) -> std::io::Result<()> {
    thread::Builder::new()
        .name("hertz-input".into())
        .spawn(move || {
            loop {
                let wake = match read_waiting(event::read, || event::poll(Duration::ZERO)) {
                    Ok(events) => Wake::Terminal(events),
                    Err(e) => Wake::InputFailed(e.to_string()),
                };
                let failed = matches!(wake, Wake::InputFailed(_));
                if events.send(wake).is_err() || failed {
                    return;
                }
            }
        })?;
    Ok(())
}

/// Blocks in `read` for one event, then reads those `ready` says are already there (crossterm
/// parses a whole read of the terminal at once, so the keys of a burst are all ready together).
fn read_waiting<E>(
    mut read: impl FnMut() -> std::io::Result<E>,
    mut ready: impl FnMut() -> std::io::Result<bool>,
) -> std::io::Result<Vec<E>> {
    let mut events = vec![read()?];
    while ready()? {
        events.push(read()?);
    }
    Ok(events)
}

/// Runs `app` in `terminal` until it quits, with bracketed paste (and mouse capture while the app
/// wants it) on meanwhile; both are turned off again on every exit.
pub fn event_loop(terminal: &mut DefaultTerminal, app: App) -> color_eyre::Result<()> {
    execute!(std::io::stdout(), EnableBracketedPaste).wrap_err("cannot enable bracketed paste")?;
    let result = run(terminal, app);
    release_terminal_modes();
    result
}

/// Turns mouse capture and bracketed paste off (harmless when they are off already).
pub fn release_terminal_modes() {
    let _ = execute!(
        std::io::stdout(),
        DisableMouseCapture,
        DisableBracketedPaste
    );
}

/// Draws one frame inside a synchronized update, so the terminal shows it whole.
pub fn draw_synchronized<B>(
    terminal: &mut Terminal<B>,
    writer: &mut impl Write,
    app: &App,
) -> color_eyre::Result<()>
where
    B: ratatui::backend::Backend,
    B::Error: Send + Sync + 'static,
{
    execute!(writer, BeginSynchronizedUpdate)?;
    let drawn = terminal.draw(|frame| render::draw(frame, app));
    execute!(writer, EndSynchronizedUpdate)?;
    drawn?;
    Ok(())
}

/// Threads solving an edit's laws: an edit with every law checked is solved on two cores
/// (a study's own parallel work has its queue and thread).
const SOLVER_THREADS: usize = 2;

/// The longest a frame waits for the solves the keys before it started (a frame at 120 Hz).
pub const SOLVE_WAIT: Duration = Duration::from_millis(8);

/// How long to wait before drawing, `None` to draw now: while solves are pending, until the
/// frame's deadline.
fn wait_before_drawing(solving: bool, now: Instant, deadline: Instant) -> Option<Duration> {
    (solving && now < deadline).then(|| deadline - now)
}

/// `first` and every wake already waiting behind it: what one draw answers.
fn waiting(first: Wake, wakes: &Receiver<Wake>) -> Vec<Wake> {
    std::iter::once(first).chain(wakes.try_iter()).collect()
}

/// Sleeps in `recv` between events: no busy loop.
fn run(terminal: &mut DefaultTerminal, mut app: App) -> color_eyre::Result<()> {
    let mut mouse = false;
    let (events, wakes) = mpsc::channel();
    spawn_input(events.clone()).wrap_err("cannot start the input thread")?;
    let reports = events.clone();
    let solves: Jobs<Job> = Jobs::spawn("hertz-solver", SOLVER_THREADS, move |report| {
        reports.send(Wake::Solver(report)).is_ok()
    })
    .wrap_err("cannot start the solver thread")?;
    let study_reports = events.clone();
    let studies: Jobs<StudyJob> = Jobs::spawn("hertz-studies", 1, move |report| {
        study_reports.send(Wake::Study(report)).is_ok()
    })
    .wrap_err("cannot start the study thread")?;
    drop(events);
    // The sweep view sizes its sweeps to the chart: the app needs the size before any resize.
    let size = terminal.size().wrap_err("cannot read the terminal size")?;
    update(&mut app, Action::Resize(size.width, size.height));
    let mut due = Instant::now() + SOLVE_WAIT;
    loop {
        for job in app.take_jobs() {
            if !solves.submit(job) {
                return Err(eyre!("the solver thread stopped"));
            }
        }
        for job in app.take_studies() {
            if !studies.submit(job) {
                return Err(eyre!("the study thread stopped"));
            }
        }
        if let Some(text) = app.clipboard.take() {
            let mut out = std::io::stdout();
            out.write_all(super::osc52::sequence(&text).as_bytes())?;
            out.flush()?;
        }
        if app.mouse != mouse {
            mouse = app.mouse;
            if mouse {
                execute!(std::io::stdout(), EnableMouseCapture)?;
            } else {
                execute!(std::io::stdout(), DisableMouseCapture)?;
            }
        }
        let (first, after_a_frame) =
            match wait_before_drawing(app.solutions.any_pending(), Instant::now(), due) {
                Some(wait) => match wakes.recv_timeout(wait) {
                    Ok(wake) => (wake, false),
                    // The frame is due: drawn, with what is still computing marked so.
                    Err(RecvTimeoutError::Timeout) => continue,
                    Err(RecvTimeoutError::Disconnected) => {
                        return Err(eyre!("the input and solver threads stopped"));
                    }
                },
                None => {
                    draw_synchronized(terminal, &mut std::io::stdout(), &app)?;
                    let wake = wakes
                        .recv()
                        .wrap_err("the input and solver threads stopped")?;
                    (wake, true)
                }
            };
        for wake in waiting(first, &wakes) {
            match wake {
                Wake::Terminal(events) => {
                    for e in events {
                        if let Some(action) = action_for_event(&app.mode, &e) {
                            update(&mut app, action);
                        }
                        // Keys typed after a quit are not the app's any more.
                        if app.quit {
                            return Ok(());
                        }
                    }
                }
                Wake::Solver(Err(message)) => return Err(eyre!(message)),
                Wake::Solver(report) => update(&mut app, Action::Solved(report)),
                Wake::Study(Err(message)) => return Err(eyre!(message)),
                Wake::Study(report) => update(&mut app, Action::Studied(report)),
                Wake::InputFailed(message) => {
                    return Err(eyre!("cannot read the terminal: {message}"));
                }
            }
            if app.quit {
                return Ok(());
            }
        }
        if after_a_frame {
            // What these wakes started is drawn by then at the latest. The wait starts once they
            // are handled, when their solves are queued: a burst of keys takes a while to handle.
            due = Instant::now() + SOLVE_WAIT;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::presets::Registry;
    use crate::ui::style::MarkerStyle;
    use crate::ui::style::Theme;
    use crate::ui::testing::fig5_scene;
    use ratatui::backend::TestBackend;
    use ratatui::crossterm::event::{Event, KeyCode, KeyEvent, KeyModifiers};

    fn key(c: char) -> Event {
        Event::Key(KeyEvent::new(KeyCode::Char(c), KeyModifiers::NONE))
    }

    /// The keys of `text`, read together.
    fn key_wake(text: &str) -> Wake {
        Wake::Terminal(text.chars().map(key).collect())
    }

    #[test]
    fn a_frame_waits_only_for_pending_solves_and_only_until_it_is_due() {
        let now = Instant::now();
        let due = now + SOLVE_WAIT;
        assert_eq!(wait_before_drawing(true, now, due), Some(SOLVE_WAIT));
        assert_eq!(
            wait_before_drawing(false, now, due),
            None,
            "nothing to wait for"
        );
        assert_eq!(wait_before_drawing(true, due, due), None, "due");
        assert_eq!(
            wait_before_drawing(true, due + SOLVE_WAIT, due),
            None,
            "overdue"
        );
    }

    #[test]
    fn a_frame_is_one_synchronized_update() {
        let app = App::new(
            fig5_scene(),
            Registry::builtin().unwrap(),
            MarkerStyle::Braille,
            Theme::Plain,
        );
        let mut terminal = Terminal::new(TestBackend::new(100, 30)).unwrap();
        let mut out: Vec<u8> = Vec::new();
        draw_synchronized(&mut terminal, &mut out, &app).unwrap();
        assert_eq!(
            out, b"\x1b[?2026h\x1b[?2026l",
            "begin, then end (mode 2026)"
        );
        let screen = format!("{:?}", terminal.backend().buffer());
        assert!(
            screen.contains("explorer"),
            "the frame was drawn between them"
        );
    }

    #[test]
    fn a_read_takes_every_event_already_there() {
        // Five keys arrived together (one read of the terminal): one wake carries them all.
        let arrived = std::cell::RefCell::new(std::collections::VecDeque::from_iter(
            "llllh".chars().map(key),
        ));
        let read = || {
            Ok(arrived
                .borrow_mut()
                .pop_front()
                .expect("only what is ready"))
        };
        let events = read_waiting(read, || Ok(!arrived.borrow().is_empty())).unwrap();
        assert_eq!(
            events,
            "llllh".chars().map(key).collect::<Vec<_>>(),
            "one wake, in order"
        );
        // A lone key is passed on at once: nothing else is ready, so nothing is waited for.
        let mut lone = Some(key('l'));
        let read = || Ok(lone.take().expect("one key"));
        assert_eq!(read_waiting(read, || Ok(false)).unwrap(), [key('l')]);
    }

    #[test]
    fn every_waiting_wake_shares_one_draw() {
        let (send, wakes) = mpsc::channel();
        send.send(key_wake("llllh")).unwrap();
        send.send(Wake::Solver(Err("a report".into()))).unwrap();
        send.send(key_wake("h")).unwrap();
        let first = wakes.recv().unwrap();
        let batch = waiting(first, &wakes);
        assert_eq!(batch.len(), 3, "all three wakes before one draw");
        let keys: usize = batch
            .iter()
            .map(|w| match w {
                Wake::Terminal(events) => events.len(),
                _ => 0,
            })
            .sum();
        assert_eq!(keys, 6);
        // Nothing waiting: the wake alone, at once.
        send.send(Wake::InputFailed("test".into())).unwrap();
        let first = wakes.recv().unwrap();
        assert_eq!(waiting(first, &wakes).len(), 1);
    }
}
