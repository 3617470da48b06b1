//! Keys the config file moves (`[keys]`, docs/explorer.md): each names an action of the explorer
//! and the key that does it instead of its built-in one. A moved key is translated to the
//! built-in key before the keymap reads it, so the keymap stays the one place that knows what a
//! key does; the built-in key keeps working unless another action took it.

use std::collections::BTreeMap;
use std::sync::OnceLock;

use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

/// The actions a config file can move, by name, with their built-in keys.
pub const ACTIONS: &[(&str, char)] = &[
    ("quit", 'q'),
    ("help", '?'),
    ("presets", 'p'),
    ("save", 's'),
    ("export", 'e'),
    ("undo", 'u'),
    ("reset", 'r'),
    ("mouse", 'm'),
    ("engines", 't'),
    ("figure", 'f'),
    ("open", 'o'),
    ("next-chart", 'c'),
    ("calibrate", 'C'),
    ("toggle-model", ' '),
    ("focus-previous", '['),
    ("focus-next", ']'),
    ("next-view", 'v'),
    ("previous-view", 'V'),
    ("cursor-left", '<'),
    ("cursor-right", '>'),
    ("branch", 'b'),
];

/// Moved keys: the key pressed → the built-in key of its action.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Rebind {
    moved: BTreeMap<char, char>,
}

/// Why a `[keys]` entry cannot be used.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum RebindError {
    #[error("unknown action `{0}` (expected one of: {names})", names = ACTIONS.iter().map(|a| a.0).collect::<Vec<_>>().join(", "))]
    UnknownAction(String),
    #[error("`{0}` is not a key: give one character, or \"space\"")]
    NotAKey(String),
    #[error("`{0}` is a view's key (the digits open the views)")]
    Digit(char),
    #[error("`{key}` is given to both {first} and {second}")]
    Taken {
        key: String,
        first: String,
        second: String,
    },
}

/// How a key is written in the config file: one character, or `space`.
pub fn key_name(key: char) -> String {
    if key == ' ' {
        "space".to_string()
    } else {
        key.to_string()
    }
}

impl Rebind {
    /// Gives `action` the key `key` (one character or `space`).
    pub fn bind(&mut self, action: &str, key: &str) -> Result<(), RebindError> {
        let builtin = ACTIONS
            .iter()
            .find(|a| a.0 == action)
            .ok_or_else(|| RebindError::UnknownAction(action.to_string()))?
            .1;
        let mut chars = key.chars();
        let pressed = match (chars.next(), chars.next()) {
            _ if key == "space" => ' ',
            (Some(c), None) if !c.is_control() => c,
            _ => return Err(RebindError::NotAKey(key.to_string())),
        };
        if pressed.is_ascii_digit() {
            return Err(RebindError::Digit(pressed));
        }
        if let Some(other) = self.moved.get(&pressed) {
            let first = ACTIONS.iter().find(|a| a.1 == *other).map_or("", |a| a.0);
            return Err(RebindError::Taken {
                key: key_name(pressed),
                first: first.to_string(),
                second: action.to_string(),
            });
        }
        self.moved.insert(pressed, builtin);
        Ok(())
    }

    /// The moved keys as (key, action), for the help.
    pub fn moved(&self) -> Vec<(char, &'static str)> {
        self.moved
            .iter()
            .filter_map(|(&key, builtin)| Some((key, ACTIONS.iter().find(|a| a.1 == *builtin)?.0)))
            .collect()
    }

    /// The key that does the action of built-in key `builtin`: the key moved to it, else the
    /// built-in one.
    pub fn key_for(&self, builtin: char) -> char {
        self.moved
            .iter()
            .find(|(_, b)| **b == builtin)
            .map_or(builtin, |(&key, _)| key)
    }

    /// A hint's keys (`f m t o b`, `[ ]`) as the keys in force read: each word of one character
    /// that is an action's built-in key becomes the key moved to that action.
    pub fn hint(&self, keys: &str) -> String {
        keys.split(' ')
            .map(|word| {
                let mut chars = word.chars();
                match (chars.next(), chars.next()) {
                    (Some(c), None) if ACTIONS.iter().any(|a| a.1 == c) => {
                        key_name(self.key_for(c))
                    }
                    _ => word.to_string(),
                }
            })
            .collect::<Vec<_>>()
            .join(" ")
    }

    /// `key` as the keymap should read it: a moved key becomes its action's built-in key.
    pub fn apply(&self, mut key: KeyEvent) -> KeyEvent {
        let plain = !key
            .modifiers
            .intersects(KeyModifiers::CONTROL | KeyModifiers::ALT);
        if let (KeyCode::Char(c), true) = (key.code, plain)
            && let Some(&builtin) = self.moved.get(&c)
        {
            key.code = KeyCode::Char(builtin);
        }
        key
    }
}

/// The keys of the config file, set once when the explorer starts.
static MOVED: OnceLock<Rebind> = OnceLock::new();

/// Sets the moved keys for the rest of the run; a second call is ignored.
pub fn install(rebind: Rebind) {
    let _ = MOVED.set(rebind);
}

/// `key` as the keymap should read it in normal mode (see [`Rebind::apply`]).
pub fn translate(key: KeyEvent) -> KeyEvent {
    MOVED.get().map_or(key, |r| r.apply(key))
}

/// The moved keys in force, for the help.
pub fn moved() -> Vec<(char, &'static str)> {
    MOVED.get().map(Rebind::moved).unwrap_or_default()
}

/// The key in force for the action of built-in key `builtin`, as the config file writes it (see
/// [`Rebind::key_for`]), for messages that name it.
pub fn key_for(builtin: char) -> String {
    key_name(MOVED.get().map_or(builtin, |r| r.key_for(builtin)))
}

/// A hint's keys as the keys in force read (see [`Rebind::hint`]).
pub fn hint(keys: &str) -> String {
    match MOVED.get() {
        Some(r) => r.hint(keys),
        None => keys.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn press(c: char) -> KeyEvent {
        KeyEvent::new(KeyCode::Char(c), KeyModifiers::NONE)
    }

    #[test]
    fn a_moved_key_does_its_action_and_the_rest_stay() {
        let mut r = Rebind::default();
        r.bind("quit", "x").unwrap();
        r.bind("toggle-model", "T").unwrap();
        r.bind("help", "space").unwrap();
        assert_eq!(r.apply(press('x')).code, KeyCode::Char('q'));
        assert_eq!(r.apply(press('T')).code, KeyCode::Char(' '));
        assert_eq!(r.apply(press(' ')).code, KeyCode::Char('?'));
        assert_eq!(
            r.apply(press('q')).code,
            KeyCode::Char('q'),
            "built-in key kept"
        );
        let ctrl = KeyEvent::new(KeyCode::Char('x'), KeyModifiers::CONTROL);
        assert_eq!(r.apply(ctrl).code, KeyCode::Char('x'));
        assert_eq!(
            r.moved(),
            [(' ', "help"), ('T', "toggle-model"), ('x', "quit")]
        );
    }

    #[test]
    fn bad_entries_say_what_is_wrong() {
        let mut r = Rebind::default();
        assert!(matches!(
            r.bind("leave", "x"),
            Err(RebindError::UnknownAction(_))
        ));
        assert!(matches!(r.bind("quit", "xy"), Err(RebindError::NotAKey(_))));
        assert!(matches!(r.bind("quit", ""), Err(RebindError::NotAKey(_))));
        assert_eq!(r.bind("quit", "3"), Err(RebindError::Digit('3')));
        r.bind("quit", "x").unwrap();
        let taken = r.bind("save", "x").unwrap_err().to_string();
        assert_eq!(taken, "`x` is given to both quit and save");
        let taken = r.bind("branch", "x").unwrap_err().to_string();
        assert_eq!(taken, "`x` is given to both quit and branch");
    }

    #[test]
    fn branch_moves_like_the_others_and_hints_show_the_key_in_force() {
        let mut r = Rebind::default();
        assert_eq!(r.hint("f m t o b"), "f m t o b");
        r.bind("branch", "B").unwrap();
        assert_eq!(r.apply(press('B')).code, KeyCode::Char('b'));
        assert_eq!(
            r.apply(press('b')).code,
            KeyCode::Char('b'),
            "built-in kept"
        );
        assert_eq!(r.key_for('b'), 'B');
        assert_eq!(r.key_for('q'), 'q');
        assert_eq!(r.hint("f m t o b"), "f m t o B");
        // Words of several characters, and keys of no action, stay.
        assert_eq!(r.hint("Home End g G"), "Home End g G");
        assert_eq!(r.hint("↑↓"), "↑↓");
        r.bind("focus-next", "space").unwrap();
        assert_eq!(r.hint("[ ]"), "[ space");
        assert_eq!(r.moved(), [(' ', "focus-next"), ('B', "branch")]);
    }
}
