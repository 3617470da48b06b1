//! The event loop: blocks until a key, a resize or a solver or study report arrives, updates,
//! redraws. Input is read on its own thread, solves and studies each on a job queue of their own,
//! so none blocks another.
//!
//! Redraws are coalesced: everything already waiting is handled before one draw, and while keys
//! keep arriving (a held key over a slow link) the loop waits a few milliseconds for the next one
//! before drawing. Each frame is wrapped in synchronized output (terminals that support it show it
//! at once; others ignore the sequence). Bracketed paste is on, so that pasted text arrives as one
//! paste and never as keys; mouse capture follows the app's `m` toggle.

use std::io::Write;
use std::sync::mpsc::{self, Receiver, Sender};
use std::thread;
use std::time::Duration;

use color_eyre::eyre::{WrapErr, eyre};
use ratatui::crossterm::event::{
    self, DisableBracketedPaste, DisableMouseCapture, EnableBracketedPaste, EnableMouseCapture,
};
use ratatui::crossterm::execute;
use ratatui::crossterm::terminal::{BeginSynchronizedUpdate, EndSynchronizedUpdate};
use ratatui::{DefaultTerminal, Terminal};

use super::action::Action;
use super::app::App;
use super::jobs::{Jobs, Report};
use super::keymap::action_for_event;
use super::render;
use super::solutions::{Job, Outcome};
use super::update::update;
use crate::model::study::runner::{StudyJob, StudyOutcome};

/// What wakes the loop.
enum Wake {
    Terminal(event::Event),
    Solver(Report<Outcome>),
    Study(Report<StudyOutcome>),
    InputFailed(String),
}

fn spawn_input(events: Sender<Wake>) -> std::io::Result<()> {
    thread::Builder::new()
        .name("hertz-input".into())
        .spawn(move || {
            loop {
                let wake = match event::read() {
                    Ok(e) => Wake::Terminal(e),
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

/// How long the loop waits for the next key of a burst before drawing: below the ~30 ms of a
/// key repeat, so a held key draws about once per repeat burst and a single key at once.
const KEY_BURST_WAIT: Duration = Duration::from_millis(8);

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

/// Whether a wake is a key (the kind that comes in bursts).
fn is_key(wake: &Wake) -> bool {
    matches!(wake, Wake::Terminal(event::Event::Key(_)))
}

/// The wakes waiting now, and while the last is a key, those that follow within a burst.
fn burst(first: Wake, wakes: &Receiver<Wake>) -> Vec<Wake> {
    let mut batch: Vec<Wake> = std::iter::once(first).chain(wakes.try_iter()).collect();
    while batch.last().is_some_and(is_key) {
        match wakes.recv_timeout(KEY_BURST_WAIT) {
            Ok(wake) => {
                batch.push(wake);
                batch.extend(wakes.try_iter());
            }
            Err(_) => break,
        }
    }
    batch
}

/// Sleeps in `recv` between events: no busy loop.
fn run(terminal: &mut DefaultTerminal, mut app: App) -> color_eyre::Result<()> {
    let mut mouse = false;
    let (events, wakes) = mpsc::channel();
    spawn_input(events.clone()).wrap_err("cannot start the input thread")?;
    let reports = events.clone();
    let solves: Jobs<Job> = Jobs::spawn("hertz-solver", move |report| {
        reports.send(Wake::Solver(report)).is_ok()
    })
    .wrap_err("cannot start the solver thread")?;
    let study_reports = events.clone();
    let studies: Jobs<StudyJob> = Jobs::spawn("hertz-studies", move |report| {
        study_reports.send(Wake::Study(report)).is_ok()
    })
    .wrap_err("cannot start the study thread")?;
    drop(events);
    // The sweep view sizes its sweeps to the chart: the app needs the size before any resize.
    let size = terminal.size().wrap_err("cannot read the terminal size")?;
    update(&mut app, Action::Resize(size.width, size.height));
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
        if app.mouse != mouse {
            mouse = app.mouse;
            if mouse {
                execute!(std::io::stdout(), EnableMouseCapture)?;
            } else {
                execute!(std::io::stdout(), DisableMouseCapture)?;
            }
        }
        draw_synchronized(terminal, &mut std::io::stdout(), &app)?;
        let first = wakes
            .recv()
            .wrap_err("the input and solver threads stopped")?;
        for wake in burst(first, &wakes) {
            match wake {
                Wake::Terminal(e) => {
                    if let Some(action) = action_for_event(&app.mode, &e) {
                        update(&mut app, action);
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

    fn key(c: char) -> Wake {
        Wake::Terminal(Event::Key(KeyEvent::new(
            KeyCode::Char(c),
            KeyModifiers::NONE,
        )))
    }

    #[test]
    fn a_frame_is_one_synchronized_update() {
        let app = App::new(
            fig5_scene(),
            Registry::builtin().unwrap(),
            MarkerStyle::Braille,
            Theme { color: false },
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
    fn keys_of_a_burst_share_one_draw() {
        let (send, wakes) = mpsc::channel();
        // Keys waiting when the first is read join it (a held key's repeats). No key is sent from
        // a timed thread: under load a sleep of a few ms can outlast the burst wait, and a test
        // must not depend on the scheduler.
        for c in "llllh".chars() {
            send.send(key(c)).unwrap();
        }
        let first = wakes.recv().unwrap();
        let batch = burst(first, &wakes);
        assert_eq!(batch.len(), 5, "five waiting keys, one draw");
        // A solver report alone is drawn at once: no wait.
        send.send(Wake::InputFailed("test".into())).unwrap();
        let first = wakes.recv().unwrap();
        assert_eq!(burst(first, &wakes).len(), 1);
    }
}
