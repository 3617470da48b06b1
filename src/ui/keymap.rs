//! Key → action, per mode. The only place that knows which key does what (the help lists them).

use ratatui::crossterm::event::{
    Event, KeyCode, KeyEvent, KeyEventKind, KeyModifiers, MouseButton, MouseEvent, MouseEventKind,
};
use tui_input::backend::crossterm::to_input_request;

use crate::model::scene_key::BodyIndex;

use super::action::{Action, Jump};
use super::app::{Confirm, Mode};
use super::field::Nudge;
use super::picker::{EntryKind, Picker};
use super::tab::Tab;

/// The key bindings, as the help screen lists them: (keys, what they do), the views and their
/// keys first, the keys of every view, each view's own, then help and quit; each fits one line at
/// 80 columns (the list of views goes on over as many lines as it needs, its keys column empty).
pub fn bindings() -> Vec<(String, String)> {
    let digits: Vec<String> = Tab::all()
        .filter_map(|t| Some(t.key()?.to_string()))
        .collect();
    let views_keys = format!("{} {}", digits.join(" "), super::rebind::hint("v V"));
    let own = Tab::all().filter_map(|t| Some((format!("in {}", t.name()), t.view().help()?)));
    // Each key as the config file's `[keys]` moved it.
    let fixed = |&(keys, what): &(&str, &str)| (super::rebind::hint(keys), what.to_string());
    let rest: Vec<(String, String)> = SHARED
        .iter()
        .map(fixed)
        .chain(own.map(|(keys, what)| (keys, what.to_string())))
        .chain(CLOSING.iter().map(fixed))
        .collect();
    let key_width = rest
        .iter()
        .map(|(keys, _)| keys.chars().count())
        .chain([views_keys.chars().count()])
        .max()
        .unwrap_or(0);
    // The help's text at 80 columns: within its borders, a space, the keys, two spaces.
    let width = usize::from(HELP_COLUMNS - 2) - 3 - key_width;
    let names: Vec<String> = Tab::all()
        .enumerate()
        .map(|(i, t)| match i {
            0 => format!("views: {}", t.view().short_title()),
            _ => t.view().short_title().to_string(),
        })
        .collect();
    let mut views = wrap(&names, width).into_iter();
    let first = (views_keys, views.next().unwrap_or_default());
    std::iter::once(first)
        .chain(views.map(|more| (String::new(), more)))
        .chain(rest)
        .collect()
}

/// The narrowest terminal the help fits whole.
pub const HELP_COLUMNS: u16 = 80;

/// `items` joined by ` · ` in lines of at most `width` characters, a line that goes on ending in
/// `·`; an item longer than `width` has a line of its own.
fn wrap(items: &[String], width: usize) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for (i, item) in items.iter().enumerate() {
        // Room for the ` ·` that ends the line if more items follow.
        let tail = if i + 1 < items.len() { 2 } else { 0 };
        if line.is_empty() {
            line.clone_from(item);
        } else if line.chars().count() + 3 + item.chars().count() + tail <= width {
            line = format!("{line} · {item}");
        } else {
            lines.push(format!("{line} ·"));
            line.clone_from(item);
        }
    }
    lines.push(line);
    lines
}

/// The keys every view shares, in the help.
const SHARED: &[(&str, &str)] = &[
    ("↑ ↓ k j Tab S-Tab", "move between fields and models"),
    ("Home End g G", "first / last row"),
    ("PgUp PgDn", "previous / next section"),
    ("Enter", "edit (typing replaces the value) · check a model"),
    (
        "← → h l - + =",
        "nudge the 2nd digit, up to the bound; cycle choices",
    ),
    (
        "Space [ ]",
        "check / uncheck the model · focus previous / next",
    ),
    (
        "u r c C",
        "undo · reset field · next chart · calibrate to realise e",
    ),
    (
        "p",
        "presets: type to filter; Enter loads; on a material 1 2",
    ),
    ("s e", "save the scene (name or path.toml) · export as CSV"),
    (
        "f m t o b",
        "figure · mouse · engine · open data · sys: branch",
    ),
    ("paste", "opens the field under the cursor with the text"),
    (
        ", . < > P",
        "data cursor: step, 10 steps, to the focused peak",
    ),
];

/// Help and quit, last in the help.
const CLOSING: &[(&str, &str)] = &[
    ("? Esc", "this help · close, cancel, clear the message"),
    (
        "q Ctrl-C",
        "quit (unsaved: asks; s saves and quits); Ctrl-C twice: now",
    ),
];

/// How numbers are typed, and the display options, for the help screen.
pub const INPUT_HINTS: &[&str] = &[
    "editing: Enter commits, Esc cancels, Ctrl-U clears, Ctrl-W deletes a word",
    "numbers: 200G, 200 GPa, 1 cm, 10 mm, 2.3 µm (um), 0.3 m/s, 3.6 km/h, 60%",
    "a bare number is in SI units (Pa, m, m/s, kg); mass `auto` = ρ × volume",
    "--marker dot · NO_COLOR=1 · theme, keys: ~/.config/hertz-tui/config.toml",
];

/// The action of a terminal event in `mode`, if any.
pub fn action_for_event(mode: &Mode, event: &Event) -> Option<Action> {
    match event {
        Event::Key(key) if matches!(key.kind, KeyEventKind::Press | KeyEventKind::Repeat) => {
            action_for_key(mode, event, *key)
        }
        Event::Resize(width, height) => Some(Action::Resize(*width, *height)),
        Event::Paste(text) => Some(Action::Paste(text.clone())),
        Event::Mouse(mouse) => action_for_mouse(*mouse),
        _ => None,
    }
}

fn action_for_mouse(mouse: MouseEvent) -> Option<Action> {
    let (column, row) = (mouse.column, mouse.row);
    Some(match mouse.kind {
        MouseEventKind::Down(MouseButton::Left) => Action::Click(column, row),
        MouseEventKind::ScrollUp => Action::Wheel(column, row, Nudge::Up),
        MouseEventKind::ScrollDown => Action::Wheel(column, row, Nudge::Down),
        _ => return None,
    })
}

fn action_for_key(mode: &Mode, event: &Event, key: KeyEvent) -> Option<Action> {
    if key.modifiers.contains(KeyModifiers::CONTROL) && key.code == KeyCode::Char('c') {
        return Some(Action::Interrupt);
    }
    match mode {
        Mode::Normal => normal(super::rebind::translate(key)),
        Mode::Editing(_) | Mode::Prompt(_) => match key.code {
            KeyCode::Enter => Some(Action::Enter),
            KeyCode::Esc => Some(Action::Cancel),
            _ => to_input_request(event).map(Action::Input),
        },
        Mode::Engine(_) => Some(match key.code {
            KeyCode::Left | KeyCode::Char('h') => Action::Nudge(Nudge::Down),
            KeyCode::Right | KeyCode::Char('l') => Action::Nudge(Nudge::Up),
            KeyCode::Up | KeyCode::Char('k') => Action::Up,
            KeyCode::Down | KeyCode::Char('j') => Action::Down,
            KeyCode::Home | KeyCode::Char('g') => Action::Jump(Jump::First),
            KeyCode::End | KeyCode::Char('G') => Action::Jump(Jump::Last),
            KeyCode::PageUp => Action::Jump(Jump::PreviousSection),
            KeyCode::PageDown | KeyCode::Char(' ') => Action::Jump(Jump::NextSection),
            KeyCode::Char('w') => Action::Export,
            KeyCode::Char('y') => Action::Copy,
            KeyCode::Esc | KeyCode::Char('q') | KeyCode::Char('t') => Action::Cancel,
            _ => return None,
        }),
        Mode::Help => Some(match key.code {
            KeyCode::Char('q') | KeyCode::Char('?') | KeyCode::Esc | KeyCode::Enter => {
                Action::Cancel
            }
            _ => return None,
        }),
        Mode::Picker(picker) => picker_key(picker, event, key),
        Mode::Confirm(confirm) => Some(match (confirm, key.code) {
            (_, KeyCode::Char('y' | 'Y')) => Action::Yes,
            // `q` again is one of the "other keys": it stays, as the question says.
            (Confirm::Quit, KeyCode::Char('s' | 'S')) => Action::Save,
            _ => Action::Cancel,
        }),
    }
}

/// In the picker, letters and digits type into the filter; on a material, filtered or not, `1`
/// `2` apply it to body 1 or 2 (a scene has no body to pick: there they filter, as in `r10`);
/// while the filter is empty `q` and `p` close the picker.
fn picker_key(picker: &Picker, event: &Event, key: KeyEvent) -> Option<Action> {
    let on_material = picker
        .selected()
        .is_some_and(|entry| entry.kind == EntryKind::Material);
    let filter_empty = picker.filter.is_empty();
    Some(match key.code {
        KeyCode::Up | KeyCode::BackTab => Action::Up,
        KeyCode::Down | KeyCode::Tab => Action::Down,
        KeyCode::Home | KeyCode::PageUp => Action::Jump(Jump::First),
        KeyCode::End | KeyCode::PageDown => Action::Jump(Jump::Last),
        KeyCode::Enter => Action::Enter,
        KeyCode::Esc => Action::Cancel,
        KeyCode::Char('1') if on_material => Action::ApplyMaterialTo(BodyIndex::One),
        KeyCode::Char('2') if on_material => Action::ApplyMaterialTo(BodyIndex::Two),
        KeyCode::Char('q' | 'p') if filter_empty => Action::Cancel,
        _ => return to_input_request(event).map(Action::Input),
    })
}

fn normal(key: KeyEvent) -> Option<Action> {
    Some(match key.code {
        KeyCode::Char('q') => Action::Quit,
        KeyCode::Up | KeyCode::Char('k') | KeyCode::BackTab => Action::Up,
        KeyCode::Down | KeyCode::Char('j') | KeyCode::Tab => Action::Down,
        KeyCode::Home | KeyCode::Char('g') => Action::Jump(Jump::First),
        KeyCode::End | KeyCode::Char('G') => Action::Jump(Jump::Last),
        KeyCode::PageUp => Action::Jump(Jump::PreviousSection),
        KeyCode::PageDown => Action::Jump(Jump::NextSection),
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
        KeyCode::Char('C') => Action::ToggleCalibration,
        KeyCode::Char('?') => Action::Help,
        KeyCode::Char('t') => Action::Engines,
        KeyCode::Char('p') => Action::Presets,
        KeyCode::Char('s') => Action::Save,
        KeyCode::Char('e') => Action::Export,
        KeyCode::Char('u') => Action::Undo,
        KeyCode::Char('r') => Action::ResetField,
        KeyCode::Char('m') => Action::ToggleMouse,
        KeyCode::Char('f') => Action::Figure,
        KeyCode::Char('o') => Action::Open,
        KeyCode::Char('v') => Action::CycleView(Nudge::Up),
        KeyCode::Char('V') => Action::CycleView(Nudge::Down),
        KeyCode::Char(',') => Action::MoveCursor {
            forward: false,
            fast: false,
        },
        KeyCode::Char('.') => Action::MoveCursor {
            forward: true,
            fast: false,
        },
        KeyCode::Char('<') => Action::MoveCursor {
            forward: false,
            fast: true,
        },
        KeyCode::Char('>') => Action::MoveCursor {
            forward: true,
            fast: true,
        },
        KeyCode::Char('P') => Action::CursorToPeak,
        KeyCode::Char('b') => Action::Branch,
        KeyCode::Char(c) => Action::Tab(Tab::of_key(c)?),
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::wrap;

    #[test]
    fn a_long_list_goes_on_over_lines_within_the_width_and_keeps_every_item() {
        let items: Vec<String> = (0..12).map(|i| format!("view{i}")).collect();
        for width in [12, 20, 33, 58] {
            let lines = wrap(&items, width);
            assert!(lines.len() > 1, "12 items need more than {width} columns");
            for line in &lines {
                assert!(line.chars().count() <= width, "{line:?} over {width}");
            }
            let (last, going_on) = lines.split_last().unwrap();
            assert!(going_on.iter().all(|l| l.ends_with(" ·")));
            assert!(!last.ends_with('·'));
            let joined = lines.join(" ").replace(" · ", " ").replace(" ·", "");
            let words: Vec<&str> = joined.split(' ').collect();
            assert_eq!(words, items, "every item once, in order");
        }
        assert_eq!(
            wrap(&items[..2], 20),
            ["view0 · view1"],
            "one line when it fits"
        );
    }
}
