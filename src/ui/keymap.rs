//! Key → action, per mode. The only place that knows which key does what (the help lists them).

use ratatui::crossterm::event::{Event, KeyCode, KeyEvent, KeyEventKind, KeyModifiers};
use tui_input::backend::crossterm::to_input_request;

use crate::model::scene_key::BodyIndex;

use super::action::Action;
use super::app::Mode;
use super::field::Nudge;
use super::tab::Tab;

/// The key bindings, as the help screen lists them: (keys, what they do).
pub const BINDINGS: &[(&str, &str)] = &[
    (
        "1 2 3 4",
        "views: explorer · work–precision · stability · sweep",
    ),
    ("↑ ↓  Tab  S-Tab", "move between fields and models"),
    (
        "Enter",
        "edit the field (Enter commits, Esc cancels) · toggle a model",
    ),
    (
        "← →  − +",
        "nudge the value by one step of its 2nd digit; cycle choices",
    ),
    ("Space", "check / uncheck the model (drawn and tabulated)"),
    ("[  ]", "focus the previous / next model"),
    ("c", "next chart (when only one fits)"),
    (
        "p",
        "presets: scenes; materials (1 / 2 apply one to body 1 / 2)",
    ),
    (
        "s",
        "save the scene (preset name, or a path ending in .toml)",
    ),
    ("e", "export the focused model's trajectory as CSV"),
    (
        "f",
        "write the charts of this view to an SVG figure (<scene>-<view>.svg)",
    ),
    (
        "<  >",
        "data cursor along the charts' x axis: each curve's value there (Esc hides)",
    ),
    ("in 2", "work–precision of every method, focused model"),
    (
        "in 3",
        "Enter types the step (auto: rk4 critical); ← → ½× 2×",
    ),
    ("in 4", "↑ ↓ rows; ← → change; Enter types or switches"),
    ("?", "this help"),
    ("Esc", "close · cancel · clear the message"),
    ("q  Ctrl-C", "quit (q closes an overlay; q again quits)"),
];

/// How numbers are typed, and the display options, for the help screen.
pub const INPUT_HINTS: &[&str] = &[
    "numbers: 200G, 2e11, 200 GPa, 10 mm, 0.3 m/s, 2.3 µm (or um), 33 g, 60%",
    "a bare number is in SI units (Pa, m, m/s, kg); mass `auto` = ρ × volume",
    "--marker braille|dot|block for fonts without braille; NO_COLOR=1: no colour",
];

/// The action of a terminal event in `mode`, if any.
pub fn action_for_event(mode: &Mode, event: &Event) -> Option<Action> {
    match event {
        Event::Key(key) if matches!(key.kind, KeyEventKind::Press | KeyEventKind::Repeat) => {
            action_for_key(mode, event, *key)
        }
        Event::Resize(width, height) => Some(Action::Resize(*width, *height)),
        _ => None,
    }
}

fn action_for_key(mode: &Mode, event: &Event, key: KeyEvent) -> Option<Action> {
    if key.modifiers.contains(KeyModifiers::CONTROL) && key.code == KeyCode::Char('c') {
        return Some(Action::Quit);
    }
    match mode {
        Mode::Normal => normal(key),
        Mode::Editing(_) | Mode::Prompt(_) => match key.code {
            KeyCode::Enter => Some(Action::Enter),
            KeyCode::Esc => Some(Action::Cancel),
            _ => to_input_request(event).map(Action::Input),
        },
        Mode::Help => Some(match key.code {
            KeyCode::Char('q') | KeyCode::Char('?') | KeyCode::Esc | KeyCode::Enter => {
                Action::Cancel
            }
            _ => return None,
        }),
        Mode::Picker(_) => Some(match key.code {
            KeyCode::Up | KeyCode::Char('k') | KeyCode::BackTab => Action::Up,
            KeyCode::Down | KeyCode::Char('j') | KeyCode::Tab => Action::Down,
            KeyCode::Enter => Action::Enter,
            KeyCode::Char('1') => Action::ApplyMaterialTo(BodyIndex::One),
            KeyCode::Char('2') => Action::ApplyMaterialTo(BodyIndex::Two),
            KeyCode::Esc | KeyCode::Char('q') | KeyCode::Char('p') => Action::Cancel,
            _ => return None,
        }),
    }
}

fn normal(key: KeyEvent) -> Option<Action> {
    Some(match key.code {
        KeyCode::Char('q') => Action::Quit,
        KeyCode::Up | KeyCode::Char('k') | KeyCode::BackTab => Action::Up,
        KeyCode::Down | KeyCode::Char('j') | KeyCode::Tab => Action::Down,
        KeyCode::Left | KeyCode::Char('-') | KeyCode::Char('h') => Action::Nudge(Nudge::Down),
        KeyCode::Right | KeyCode::Char('+') | KeyCode::Char('=') | KeyCode::Char('l') => {
            Action::Nudge(Nudge::Up)
        }
        KeyCode::Enter => Action::Enter,
        KeyCode::Esc => Action::Cancel,
        KeyCode::Char(' ') => Action::ToggleModel,
        KeyCode::Char('[') => Action::FocusModel(Nudge::Down),
        KeyCode::Char(']') => Action::FocusModel(Nudge::Up),
        KeyCode::Char('c') => Action::CycleChart,
        KeyCode::Char('?') => Action::Help,
        KeyCode::Char('p') => Action::Presets,
        KeyCode::Char('s') => Action::Save,
        KeyCode::Char('e') => Action::Export,
        KeyCode::Char('f') => Action::Figure,
        KeyCode::Char('<') | KeyCode::Char(',') => Action::MoveCursor(false),
        KeyCode::Char('>') | KeyCode::Char('.') => Action::MoveCursor(true),
        KeyCode::Char(c) => Action::Tab(Tab::of_key(c)?),
        _ => return None,
    })
}
