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
//! slower solve is drawn as computing [`SOLVE_WAIT`] after the key and again when it reports.
//! The solvers' reports collect in an inbox, held from the moment their batch is queued, and wake
//! the loop once, when the last of them is in (not once a report). The loop seldom sleeps for
//! them at all: on two cores a solver woken by the queuing takes the loop's core at once, and
//! the loop runs again when the batch is done, its reports all in; so neither polling for the
//! batch nor running its quick solves on this thread made a key sooner (docs/performance.md,
//! "Fewer wake-ups a key"). Each frame is wrapped in synchronized output
//! (terminals that support it show it at once; others ignore the sequence) and reaches the
//! terminal in one write. Bracketed paste is on, so that pasted text arrives as one paste and
//! never as keys; mouse capture follows the app's `m` toggle.

use std::io::Write;
use std::sync::mpsc::{self, Receiver, RecvTimeoutError, Sender};
use std::sync::{Arc, Mutex, PoisonError};
use std::thread;
use std::time::{Duration, Instant};

use color_eyre::eyre::{WrapErr, eyre};
use ratatui::DefaultTerminal;
use ratatui::crossterm::cursor::Show;
use ratatui::crossterm::event::{
    self, DisableBracketedPaste, DisableMouseCapture, EnableBracketedPaste, EnableMouseCapture,
};
use ratatui::crossterm::execute;

use crate::model::study::runner::{StudyJob, StudyOutcome};

use super::action::Action;
use super::app::App;
use super::frames::{Frames, draw_synchronized};
use super::jobs::{Jobs, Report};
use super::keymap::action_for_event;
use super::solutions::{Job, Outcome};
use super::update::update;

/// What wakes the loop.
enum Wake {
    /// Every terminal event that was waiting when the input thread read (never empty).
    Terminal(Vec<event::Event>),
    /// The solvers' inbox has reports.
    Solver,
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

/// Turns mouse capture and bracketed paste off and shows the cursor again (harmless when they
/// are so already). The cursor is hidden by the frames, whose terminal's own restoring of it on
/// drop would only join its held bytes, never sent.
pub fn release_terminal_modes() {
    let _ = execute!(
        std::io::stdout(),
        DisableMouseCapture,
        DisableBracketedPaste,
        Show
    );
}

/// The solvers' reports not yet handled. While the loop waits for the solves of its keys
/// (`holding`), a report only joins the inbox and the queue's falling idle wakes the loop, once
/// for the batch; otherwise (after a frame's deadline, or a solve nobody waits for) each report
/// wakes it, so a slow solve is drawn when it reports.
#[derive(Default)]
struct Inbox {
    reports: Vec<Report<Outcome>>,
    holding: bool,
}

type SharedInbox = Arc<Mutex<Inbox>>;

/// A report held by the inbox is still a whole one after a panic elsewhere.
fn lock_inbox(shared: &SharedInbox) -> std::sync::MutexGuard<'_, Inbox> {
    shared.lock().unwrap_or_else(PoisonError::into_inner)
}

/// Adds `report` to the inbox; whether the loop is to be woken for it now.
fn post(shared: &SharedInbox, report: Report<Outcome>) -> bool {
    let mut inbox = lock_inbox(shared);
    inbox.reports.push(report);
    !inbox.holding
}

/// The reports in the inbox, taken out, and whether the loop holds reports back from now on.
fn collect(shared: &SharedInbox, holding: bool) -> Vec<Report<Outcome>> {
    let mut inbox = lock_inbox(shared);
    inbox.holding = holding;
    std::mem::take(&mut inbox.reports)
}

/// `threads` solver threads whose reports go to `inbox`, each waking the loop through `events`
/// unless the inbox holds them; the queue's falling idle wakes it once for what it held.
fn spawn_solvers(
    events: &Sender<Wake>,
    inbox: &SharedInbox,
    threads: usize,
) -> std::io::Result<Jobs<Job>> {
    let (posted, reports) = (Arc::clone(inbox), events.clone());
    let (idle, waiting_reports) = (Mutex::new(events.clone()), Arc::clone(inbox));
    Jobs::spawn_with_idle(
        "hertz-solver",
        threads,
        move |report| !post(&posted, report) || reports.send(Wake::Solver).is_ok(),
        // The last report of a batch is in: one wake for all of them.
        move || {
            if !lock_inbox(&waiting_reports).reports.is_empty() {
                let _ = idle
                    .lock()
                    .unwrap_or_else(PoisonError::into_inner)
                    .send(Wake::Solver);
            }
        },
    )
}

/// Queues `jobs` on the solvers with the inbox already holding their reports: a batch is often
/// all solved before this thread runs again (a solver woken on its core takes the core at once),
/// so holding only once the loop came to wait would let every report send a wake of its own.
/// Whether the solvers still run.
fn submit_held(solves: &Jobs<Job>, inbox: &SharedInbox, jobs: Vec<Job>) -> bool {
    if !jobs.is_empty() {
        lock_inbox(inbox).holding = true;
    }
    solves.submit_all(jobs)
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
    let inbox = SharedInbox::default();
    let solves = spawn_solvers(&events, &inbox, SOLVER_THREADS)
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
    // ratatui's terminal set the screen up; frames go through one of our own on the same output.
    let mut frames = Frames::new(size.width, size.height).wrap_err("cannot set up the terminal")?;
    let mut due = Instant::now() + SOLVE_WAIT;
    // Whether anything happened since the last frame.
    let mut changed = true;
    loop {
        if !submit_held(&solves, &inbox, app.take_jobs()) {
            return Err(eyre!("the solver thread stopped"));
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
                Some(wait) => {
                    // Reports that came meanwhile are handled first; the rest wake the loop once.
                    let held = collect(&inbox, true);
                    if !held.is_empty() {
                        changed = true;
                        handle_reports(&mut app, held)?;
                        continue;
                    }
                    match wakes.recv_timeout(wait) {
                        Ok(wake) => (wake, false),
                        // The frame is due: drawn, with what is still computing marked so.
                        Err(RecvTimeoutError::Timeout) => {
                            let held = collect(&inbox, false);
                            changed = true;
                            handle_reports(&mut app, held)?;
                            continue;
                        }
                        Err(RecvTimeoutError::Disconnected) => {
                            return Err(eyre!("the input and solver threads stopped"));
                        }
                    }
                }
                None => {
                    // Solves still running after the frame report one by one.
                    let held = collect(&inbox, false);
                    if !held.is_empty() {
                        changed = true;
                        handle_reports(&mut app, held)?;
                        continue;
                    }
                    if changed {
                        draw_synchronized(&mut frames, &mut std::io::stdout(), &app)?;
                        changed = false;
                    }
                    let wake = wakes
                        .recv()
                        .wrap_err("the input and solver threads stopped")?;
                    (wake, true)
                }
            };
        for wake in waiting(first, &wakes) {
            if !matches!(wake, Wake::Solver) {
                changed = true;
            }
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
                Wake::Solver => {
                    let holding = lock_inbox(&inbox).holding;
                    let reports = collect(&inbox, holding);
                    // A wake whose reports an earlier collection took changes nothing.
                    changed |= !reports.is_empty();
                    handle_reports(&mut app, reports)?;
                }
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

/// The solvers' reports, in the order they came; a solver's panic ends the loop.
fn handle_reports(app: &mut App, reports: Vec<Report<Outcome>>) -> color_eyre::Result<()> {
    for report in reports {
        if let Err(message) = report {
            return Err(eyre!(message));
        }
        update(app, Action::Solved(report));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::ForceModel;
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

    /// Reports wake the loop one by one unless it holds them for a batch; a collection takes
    /// every report in and sets whether later ones are held.
    #[test]
    fn the_inbox_holds_reports_while_the_loop_waits_for_a_batch() {
        let shared = SharedInbox::default();
        let report = |g| -> Report<Outcome> { Err(format!("report {g}")) };
        assert!(post(&shared, report(1)), "not holding: wake the loop");
        assert_eq!(collect(&shared, true).len(), 1);
        assert!(!post(&shared, report(2)), "holding: no wake");
        assert!(!post(&shared, report(3)));
        let held: Vec<String> = collect(&shared, false)
            .into_iter()
            .filter_map(Result::err)
            .collect();
        assert_eq!(held, ["report 2", "report 3"], "in order");
        assert!(post(&shared, report(4)), "no longer holding");
    }

    #[test]
    fn a_batch_queued_held_wakes_the_loop_once_with_every_report_in() {
        let (events, wakes) = mpsc::channel();
        let inbox = SharedInbox::default();
        let solves = spawn_solvers(&events, &inbox, SOLVER_THREADS).unwrap();
        drop(events);
        let job = |generation, model| Job {
            generation,
            model,
            params: crate::ui::testing::fig5_params(0.3),
            options: crate::model::impact::SolveOptions::default(),
            calibrate: false,
            fitted: None,
            dots: crate::chart::sample::ChartDots::UNKNOWN_SCREEN,
            previous: None,
        };
        let models = [
            ForceModel::HuntCrossley,
            ForceModel::Proposed,
            ForceModel::with_id("hertz-viscous"),
        ];
        let batch = (1..).zip(models).map(|(g, m)| job(g, m)).collect();
        assert!(submit_held(&solves, &inbox, batch));
        // The one wake comes when the queue falls idle, with the three reports in.
        assert!(matches!(wakes.recv().unwrap(), Wake::Solver));
        assert_eq!(collect(&inbox, false).len(), 3);
        drop(solves);
        assert_eq!(wakes.iter().count(), 0, "no wake a report");
        // Nothing queued: nothing held, a later report wakes the loop itself.
        let solves = {
            let (events, later) = mpsc::channel();
            let solves = spawn_solvers(&events, &inbox, 1).unwrap();
            assert!(submit_held(&solves, &inbox, Vec::new()));
            assert!(!lock_inbox(&inbox).holding);
            assert!(solves.submit(job(4, ForceModel::HuntCrossley)));
            assert!(matches!(later.recv().unwrap(), Wake::Solver));
            solves
        };
        drop(solves);
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
        send.send(Wake::Solver).unwrap();
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
