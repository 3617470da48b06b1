//! The event loop: blocks until a key, a resize or a solver or study report arrives, updates,
//! redraws. Input is read on its own thread, solves run on the worker and studies on the study
//! worker, so none blocks another.

use std::sync::mpsc::{self, Sender};
use std::thread;

use color_eyre::eyre::{WrapErr, eyre};
use ratatui::DefaultTerminal;
use ratatui::crossterm::event;

use super::action::Action;
use super::app::App;
use super::keymap::action_for_event;
use super::render;
use super::study_worker::{StudyReport, StudyWorker};
use super::update::update;
use super::worker::{Report, Worker};

/// What wakes the loop.
enum Wake {
    Terminal(event::Event),
    Solver(Report),
    Study(StudyReport),
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

/// Runs `app` in `terminal` until it quits. Sleeps in `recv` between events: no busy loop.
pub fn event_loop(terminal: &mut DefaultTerminal, mut app: App) -> color_eyre::Result<()> {
    let (events, wakes) = mpsc::channel();
    spawn_input(events.clone()).wrap_err("cannot start the input thread")?;
    let reports = events.clone();
    let worker = Worker::spawn(move |report| reports.send(Wake::Solver(report)).is_ok())
        .wrap_err("cannot start the solver thread")?;
    let study_reports = events.clone();
    let studies = StudyWorker::spawn(move |report| study_reports.send(Wake::Study(report)).is_ok())
        .wrap_err("cannot start the study thread")?;
    drop(events);
    // The sweep view sizes its sweeps to the chart: the app needs the size before any resize.
    let size = terminal.size().wrap_err("cannot read the terminal size")?;
    update(&mut app, Action::Resize(size.width, size.height));
    loop {
        for job in app.take_jobs() {
            if !worker.submit(job) {
                return Err(eyre!("the solver thread stopped"));
            }
        }
        for job in app.take_studies() {
            if !studies.submit(job) {
                return Err(eyre!("the study thread stopped"));
            }
        }
        terminal.draw(|frame| render::draw(frame, &app))?;
        let first = wakes
            .recv()
            .wrap_err("the input and solver threads stopped")?;
        // Take everything that is already waiting before drawing again.
        for wake in std::iter::once(first).chain(wakes.try_iter()) {
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
