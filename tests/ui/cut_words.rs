//! No word is cut without an ellipsis: every view, the help, the presets picker and the engine
//! panel rendered at sizes from 80×24 to 200×50. A word of three letters or more that is not a
//! word of the program's own text (its sources and presets), as `diverg` or `Restitut` are not, was
//! cut; so was a word that runs into a pane's right edge where the program's text goes on with
//! more of it (`permanent def│`). A word followed by `…` was cut on purpose.

use std::collections::HashSet;
use std::path::Path;

use hertz_tui::model::ForceModel;
use hertz_tui::ui::action::Action;
use hertz_tui::ui::app::{App, Cursor};
use hertz_tui::ui::tab::Tab;
use hertz_tui::ui::update::update;
use ratatui::crossterm::event::KeyCode;

use super::render::{app, press, render, settle};

/// Sizes from the least the explorer fits to a large terminal.
const SIZES: [(u16, u16); 6] = [
    (80, 24),
    (100, 30),
    (120, 40),
    (140, 36),
    (160, 48),
    (200, 50),
];

/// The text of every file under `dir`, appended to `text`.
fn read_under(dir: &Path, text: &mut String) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            read_under(&path, text);
        } else if let Ok(file) = std::fs::read_to_string(&path) {
            text.push_str(&file);
            text.push('\n');
        }
    }
}

/// The program's own text (its sources and presets) and its words: runs of letters, digits and
/// `_`, and runs of letters alone, lowercased.
struct Vocabulary {
    text: String,
    words: HashSet<String>,
}

impl Vocabulary {
    fn load() -> Vocabulary {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let mut text = String::new();
        for dir in ["src", "presets"] {
            read_under(&root.join(dir), &mut text);
        }
        let mut words = HashSet::new();
        for split in [is_word_char as fn(char) -> bool, char::is_alphabetic] {
            words.extend(
                text.split(|c: char| !split(c))
                    .filter(|w| !w.is_empty())
                    .map(str::to_lowercase),
            );
        }
        Vocabulary { text, words }
    }

    fn contains(&self, word: &str) -> bool {
        self.words.contains(&word.to_lowercase())
    }

    /// Whether the program's text has `snippet` only where more of a word follows it (`permanent
    /// def` of `permanent deformation`); `None` where it does not have it at all (text made at
    /// run time).
    fn continues(&self, snippet: &str) -> Option<bool> {
        let mut found = false;
        for (i, _) in self.text.match_indices(snippet) {
            found = true;
            let next = self.text[i + snippet.len()..].chars().next();
            if !next.is_some_and(is_word_char) {
                return Some(false);
            }
        }
        found.then_some(true)
    }
}

fn is_word_char(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

/// Characters that end a pane on the right: a word that runs into one may have been cut by it.
const RIGHT_EDGES: [char; 3] = ['│', '┐', '┘'];

/// The words of `line` that were cut without `…`: a word of three letters or more that is not
/// the program's; and a word that runs into a pane's right edge or the end of the line where the
/// program's text goes on with more of it (judged by the words before it), or, for text made at
/// run time, that is not one of the program's words.
fn cut_in(line: &[char], vocabulary: &Vocabulary) -> Vec<String> {
    let mut found = Vec::new();
    let mut i = 0;
    while i < line.len() {
        if !is_word_char(line[i]) {
            i += 1;
            continue;
        }
        let start = i;
        while i < line.len() && is_word_char(line[i]) {
            i += 1;
        }
        let word: String = line[start..i].iter().collect();
        let next = line.get(i).copied();
        if next == Some('…') || !word.chars().any(char::is_alphabetic) {
            continue;
        }
        let letters_only = word.chars().all(char::is_alphabetic);
        if letters_only && word.chars().count() >= 3 && !vocabulary.contains(&word) {
            found.push(word);
            continue;
        }
        if !next.is_none_or(|c| RIGHT_EDGES.contains(&c)) {
            continue;
        }
        // Up to 24 characters of the line ending with the word, from after a pane's edge.
        let lo = i.saturating_sub(24).min(start);
        let from = (lo..start)
            .rev()
            .find(|&k| RIGHT_EDGES.contains(&line[k]))
            .map_or(lo, |k| k + 1);
        let snippet: String = line[from..i].iter().collect();
        let snippet = snippet.trim_start();
        let cut = match vocabulary.continues(snippet) {
            Some(continues) if snippet.chars().count() > word.chars().count() + 2 => continues,
            _ => !vocabulary.contains(&word),
        };
        if cut {
            found.push(word);
        }
    }
    found
}

/// Where the overlay titled `title` is drawn: the columns and rows inside its frame.
fn overlay(lines: &[Vec<char>], title: &str) -> Option<(usize, usize, usize, usize)> {
    let title: Vec<char> = title.chars().collect();
    for (y, line) in lines.iter().enumerate() {
        let Some(x) = (0..line.len()).find(|&x| line[x..].starts_with(&title)) else {
            continue;
        };
        let left = x.checked_sub(1).filter(|&l| line[l] == '┌')?;
        let right = (x..line.len()).find(|&r| line[r] == '┐')?;
        let bottom = (y + 1..lines.len()).find(|&b| lines[b].get(left) == Some(&'└'))?;
        return Some((left, right, y, bottom));
    }
    None
}

/// The words cut without `…` on the screen of `app` at `size`; within the overlay titled
/// `within` only, if any (what lies under an overlay is hidden by it, not cut).
fn cut_words(
    app: &App,
    (width, height): (u16, u16),
    vocabulary: &Vocabulary,
    within: Option<&str>,
) -> Vec<String> {
    let terminal = render(app, width, height);
    let buffer = terminal.backend().buffer();
    let lines: Vec<Vec<char>> = (0..height)
        .map(|y| {
            (0..width)
                .flat_map(|x| buffer[(x, y)].symbol().chars().next())
                .collect()
        })
        .collect();
    let (left, right, top, bottom) = match within {
        Some(title) => match overlay(&lines, title) {
            Some(frame) => frame,
            None => return vec![format!("no overlay titled {title:?}")],
        },
        None => (0, usize::from(width), 0, usize::from(height)),
    };
    let mut found = Vec::new();
    for line in &lines[top..bottom.min(lines.len())] {
        // Inside an overlay, its right border ends every line.
        let part = &line[left..(right + usize::from(within.is_some())).min(line.len())];
        for word in cut_in(part, vocabulary) {
            let text: String = line.iter().collect();
            found.push(format!("{word:?} in {:?}", text.trim_end()));
        }
    }
    found
}

#[test]
fn the_vocabulary_catches_a_cut_word_and_passes_an_ellipsis() {
    let vocabulary = Vocabulary::load();
    for word in [
        "diverged",
        "restitution",
        "Hunt",
        "Crossley",
        "steel",
        "e_out",
    ] {
        assert!(vocabulary.contains(word), "{word}");
    }
    for cut in ["diverg", "restitut", "stabili", "Crossl"] {
        assert!(!vocabulary.contains(cut), "{cut}");
    }
    let line = |text: &str| text.chars().collect::<Vec<char>>();
    assert_eq!(
        cut_in(&line("(h·ω … diverg Restitut… ab stability─"), &vocabulary),
        ["diverg"]
    );
    // A word that runs into a pane's right edge is cut where the program's text goes on.
    assert_eq!(
        cut_in(
            &line("on steel plate, permanent def│ x [µm]│ 10│"),
            &vocabulary
        ),
        ["def"]
    );
    assert_eq!(
        cut_in(&line("Fig. 4: the dry-friction mo"), &vocabulary),
        ["mo"]
    );
    assert!(cut_in(&line("log₁₀ s per solve│"), &vocabulary).is_empty());
    assert!(cut_in(&line("fits the regime───┐ ⠉⠉⠉o│"), &vocabulary).is_empty());
}

#[test]
fn no_view_cuts_a_word_without_an_ellipsis_at_any_size() {
    let vocabulary = Vocabulary::load();
    let mut cut = Vec::new();
    for size in SIZES {
        let mut app = app();
        update(&mut app, Action::Resize(size.0, size.1));
        for tab in Tab::all() {
            update(&mut app, Action::Tab(tab));
            settle(&mut app);
            let view = tab.view().id();
            cut.extend(
                cut_words(&app, size, &vocabulary, None)
                    .into_iter()
                    .map(|c| format!("{}×{} {view}: {c}", size.0, size.1)),
            );
        }
        // A model being solved: its row says so, whole or with `…`.
        let mut busy = super::render::app();
        update(&mut busy, Action::Resize(size.0, size.1));
        busy.cursor = Cursor::Model(ForceModel::DryFriction);
        press(&mut busy, KeyCode::Char(' '));
        assert!(busy.is_computing());
        cut.extend(
            cut_words(&busy, size, &vocabulary, None)
                .into_iter()
                .map(|c| format!("{}×{} computing: {c}", size.0, size.1)),
        );
        // The overlays, over the explorer: help, engine panel, presets.
        update(&mut app, Action::Tab(Tab::HOME));
        for (open, close, title) in [
            (KeyCode::Char('?'), KeyCode::Esc, "Help"),
            (KeyCode::Char('t'), KeyCode::Esc, "Engine"),
            (KeyCode::Char('p'), KeyCode::Esc, "Presets"),
        ] {
            press(&mut app, open);
            let name = title;
            cut.extend(
                cut_words(&app, size, &vocabulary, Some(title))
                    .into_iter()
                    .map(|c| format!("{}×{} {name}: {c}", size.0, size.1)),
            );
            press(&mut app, close);
        }
    }
    assert!(
        cut.is_empty(),
        "{} words cut without …:\n{}",
        cut.len(),
        cut.join("\n")
    );
}
