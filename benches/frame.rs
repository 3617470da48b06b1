//! The drawing of one explorer frame, in process: the UI thread's share of a key (docs/performance.md,
//! key to frame), without the terminal, the solver threads or the machine's other load.
//!
//! `cargo bench --bench frame` opens the explorer at 160×48 on the default scene with every law
//! checked, solves both of two states a nudge of v₀ apart, and draws them in turn, as a run of
//! `l` and `h` keys would (each frame differs from the last wherever the numbers and curves do),
//! as the explorer draws its frames (`hertz_tui::ui::frames`) into a byte buffer. It prints the CPU time a frame and the bytes a
//! frame writes. `HERTZ_FRAMES` sets the frames (default 2000); `HERTZ_FRAME_PAUSE_MS` pauses
//! that long before each frame, as between a user's keys, so that the frame finds the caches as a
//! key does (cold: the CPU a frame is then half as much again).
//!
//! Times follow the machine; the instructions a frame do not. `bash benches/frame_instructions.sh`
//! counts them under callgrind: the run with `HERTZ_FRAMES=100` less the run with none, over 100.

use std::time::Instant;

use hertz_tui::model::ForceModel;
use hertz_tui::model::impact::SolveOptions;
use hertz_tui::model::presets::{DEFAULT_SCENE, Registry};
use hertz_tui::model::scene_file::SceneView;
use hertz_tui::ui::MarkerStyle;
use hertz_tui::ui::action::Action;
use hertz_tui::ui::app::App;
use hertz_tui::ui::frames::{Frames, draw_synchronized};
use hertz_tui::ui::keymap::action_for_event;
use hertz_tui::ui::style::Theme;
use hertz_tui::ui::update::update;
use hertz_tui::ui::worker::settle;
use ratatui::crossterm::event::{Event, KeyCode, KeyEvent, KeyModifiers};

const SIZE: (u16, u16) = (160, 48);

fn key(app: &mut App, code: KeyCode) {
    let event = Event::Key(KeyEvent::new(code, KeyModifiers::NONE));
    if let Some(action) = action_for_event(&app.mode, &event) {
        update(app, action);
    }
    settle(app);
}

/// The explorer on the default scene with every law checked, its cursor on v₀, nudged `nudges`
/// times.
fn explorer(nudges: usize) -> Result<App, String> {
    let registry = Registry::builtin().map_err(|e| e.to_string())?;
    let scene = registry.scene(DEFAULT_SCENE).map_err(|e| e.to_string())?;
    let view = SceneView {
        models: ForceModel::ALL.to_vec(),
        options: SolveOptions::default(),
    };
    let mut app = App::open(scene, view, registry, MarkerStyle::Braille, Theme::Dark);
    update(&mut app, Action::Resize(SIZE.0, SIZE.1));
    settle(&mut app);
    for code in [KeyCode::Home, KeyCode::PageDown, KeyCode::PageDown] {
        key(&mut app, code);
    }
    for _ in 0..nudges {
        key(&mut app, KeyCode::Char('l'));
    }
    Ok(app)
}

/// This thread's CPU time, in seconds.
fn cpu() -> f64 {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse::<f64>().ok())
        .map_or(f64::NAN, |ns| ns * 1e-9)
}

fn run(frames: usize) -> Result<(), String> {
    let states = [explorer(0)?, explorer(1)?];
    let mut terminal = Frames::new(SIZE.0, SIZE.1).map_err(|e| e.to_string())?;
    let mut out = Vec::new();
    draw_synchronized(&mut terminal, &mut out, &states[1]).map_err(|e| e.to_string())?;
    let pause = std::env::var("HERTZ_FRAME_PAUSE_MS")
        .ok()
        .and_then(|s| s.parse().ok())
        .map(std::time::Duration::from_millis);
    let (start, wall) = (cpu(), Instant::now());
    let mut bytes = 0;
    for i in 0..frames {
        if let Some(pause) = pause {
            std::thread::sleep(pause);
        }
        out.clear();
        draw_synchronized(&mut terminal, &mut out, &states[i % 2]).map_err(|e| e.to_string())?;
        bytes += out.len();
    }
    // The wall time less the pauses.
    let paused = pause.unwrap_or_default() * u32::try_from(frames).unwrap_or(u32::MAX);
    if frames > 0 {
        let n = frames as f64;
        println!(
            "{frames} frames of {}x{} with every law checked: {:.0} µs of CPU a frame ({:.0} µs wall), {} bytes a frame",
            SIZE.0,
            SIZE.1,
            (cpu() - start) / n * 1e6,
            wall.elapsed().saturating_sub(paused).as_secs_f64() / n * 1e6,
            bytes / frames
        );
    }
    Ok(())
}

fn main() {
    // `cargo bench` passes `--bench`: nothing here to choose.
    let frames = std::env::var("HERTZ_FRAMES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(2000);
    if let Err(e) = run(frames) {
        eprintln!("frame bench failed: {e}");
        std::process::exit(1);
    }
}
