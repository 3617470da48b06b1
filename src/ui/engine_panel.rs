//! The engine panel (`t` in the explorer): the scene's contact parameters, warnings and runnable
//! script for one simulation engine, as `hertz-tui translate` prints them. ← → pick the engine;
//! ↑ ↓ scroll a line, PgUp PgDn a page, Home End to either end; `w` writes the script (or the
//! fragments) to a new file in the current folder, `y` copies it to the terminal's clipboard over
//! OSC 52 (which reaches the local clipboard through SSH where the terminal allows it).

use std::path::{Path, PathBuf};

use crate::format::translation::render_run;
use crate::model::Scene;
use crate::model::engine::run::DEFAULT_TOLERANCE;
use crate::model::engine::{self, ENGINES, EngineRun};

use super::action::{Action, Jump};
use super::field::Nudge;

/// The open panel: which engine, how far scrolled, its text (or why there is none), what `w` and
/// `y` take, and the last thing they did.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct EnginePanel {
    pub index: usize,
    pub scroll: u16,
    pub lines: Vec<String>,
    pub failed: bool,
    /// What `w` writes and `y` copies: the script, or the fragments where there is none.
    pub payload: Option<Payload>,
    /// What the last `w` or `y` did (shown in the panel's title).
    pub note: Option<String>,
}

/// The text to write or copy, and a file name for it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Payload {
    /// A file name: `<engine>-impact.py`, `<engine>-impact.in`, `<engine>-fragments.txt`.
    pub file: String,
    pub text: String,
}

impl Payload {
    fn of(id: &str, translated: &EngineRun) -> Option<Self> {
        if let Some(script) = &translated.run.script {
            return Some(Payload {
                file: format!("{id}-{}", script.file),
                text: script.text.clone(),
            });
        }
        let fragments = &translated.translation.fragments;
        (!fragments.is_empty()).then(|| Payload {
            file: format!("{id}-fragments.txt"),
            text: fragments
                .iter()
                .map(|f| f.text.as_str())
                .collect::<Vec<_>>()
                .join("\n\n")
                + "\n",
        })
    }
}

impl EnginePanel {
    /// The panel for engine `index` on `scene` (the last valid one; `None` while none is).
    pub fn new(index: usize, scene: Option<&Scene>) -> Self {
        let index = index % ENGINES.len();
        let id = ENGINES[index].id;
        let translated = scene.map(|s| (s, engine::translate_run(id, s, DEFAULT_TOLERANCE)));
        let (text, failed, payload) = match translated {
            Some((s, Ok(translated))) => (
                render_run(&s.name, &translated),
                false,
                Payload::of(id, &translated),
            ),
            Some((_, Err(e))) => (format!("{}: {e}", ENGINES[index].name), true, None),
            None => ("no valid scene to translate".to_string(), true, None),
        };
        EnginePanel {
            index,
            scroll: 0,
            lines: text.lines().map(str::to_string).collect(),
            failed,
            payload,
            note: None,
        }
    }

    /// The previous or next engine, recomputed for `scene`.
    pub fn step(&self, direction: Nudge, scene: Option<&Scene>) -> Self {
        let n = ENGINES.len();
        let index = match direction {
            Nudge::Up => (self.index + 1) % n,
            Nudge::Down => (self.index + n - 1) % n,
        };
        EnginePanel::new(index, scene)
    }

    /// The panel after `action` with `page` text rows on screen: ← → another engine, ↑ ↓ a line,
    /// PgUp PgDn a page, Home End either end; `None` closes it (Esc, q, t). `w` and `y` are the
    /// caller's ([`EnginePanel::write_to`], [`EnginePanel::copied`]): they reach outside.
    pub fn update(mut self, action: Action, scene: Option<&Scene>, page: u16) -> Option<Self> {
        match action {
            Action::Cancel => return None,
            Action::Nudge(direction) => self = self.step(direction, scene),
            Action::Up => self.scroll_to(i32::from(self.scroll) - 1, page),
            Action::Down => self.scroll_to(i32::from(self.scroll) + 1, page),
            Action::Jump(Jump::First) => self.scroll_to(0, page),
            Action::Jump(Jump::Last) => self.scroll_to(i32::MAX, page),
            Action::Jump(Jump::PreviousSection) => {
                self.scroll_to(i32::from(self.scroll) - i32::from(page.max(1)), page)
            }
            Action::Jump(Jump::NextSection) => {
                self.scroll_to(i32::from(self.scroll) + i32::from(page.max(1)), page)
            }
            _ => {}
        }
        Some(self)
    }

    /// The first line shown, within 0 … the scroll that shows the last line at the bottom.
    fn scroll_to(&mut self, line: i32, page: u16) {
        let last = self.lines.len().saturating_sub(usize::from(page.max(1)));
        let last = i32::try_from(last).unwrap_or(i32::MAX);
        self.scroll = u16::try_from(line.clamp(0, last)).unwrap_or(u16::MAX);
    }

    /// Writes the payload to a new file in `folder` (never over an existing one: `-2`, `-3`, …
    /// before the extension) and notes where; the error names the file.
    pub fn write_to(&mut self, folder: &Path) -> Result<PathBuf, String> {
        let Some(payload) = &self.payload else {
            return Err("nothing to write: this engine has no translation for the scene".into());
        };
        let path = fresh_path(folder, &payload.file);
        std::fs::write(&path, &payload.text)
            .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        self.note = Some(format!("wrote {}", path.display()));
        Ok(path)
    }

    /// The payload for the clipboard, noting that it was sent.
    pub fn copied(&mut self) -> Option<String> {
        let text = self.payload.as_ref()?.text.clone();
        self.note = Some(format!(
            "copied {} lines over OSC 52 (if the terminal allows it)",
            text.lines().count()
        ));
        Some(text)
    }
}

/// `name` in `folder`, or the first of `stem-2.ext`, `stem-3.ext`, … that does not exist.
fn fresh_path(folder: &Path, name: &str) -> PathBuf {
    let first = folder.join(name);
    if !first.exists() {
        return first;
    }
    let (stem, ext) = name.rsplit_once('.').unwrap_or((name, ""));
    (2..)
        .map(|i| {
            if ext.is_empty() {
                folder.join(format!("{stem}-{i}"))
            } else {
                folder.join(format!("{stem}-{i}.{ext}"))
            }
        })
        .find(|p| !p.exists())
        .unwrap_or(first)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::presets::Registry;

    fn fig5() -> Option<Scene> {
        Registry::builtin()
            .and_then(|r| r.scene("fig5-steel-sphere-r10-plate"))
            .ok()
    }

    #[test]
    fn cycles_through_every_engine_and_scrolls_within_the_text() {
        let scene = fig5();
        let mut panel = EnginePanel::new(0, scene.as_ref());
        assert!(!panel.failed && panel.lines[0].starts_with(ENGINES[0].name));
        panel = panel.step(Nudge::Down, scene.as_ref());
        assert_eq!(panel.index, ENGINES.len() - 1);
        assert!(panel.lines[0].starts_with(ENGINES[ENGINES.len() - 1].name));
        panel = panel.step(Nudge::Up, scene.as_ref());
        assert_eq!(panel.index, 0);
        let page = 20;
        panel = panel.update(Action::Up, scene.as_ref(), page).unwrap();
        assert_eq!(panel.scroll, 0);
        for _ in 0..1000 {
            panel = panel.update(Action::Down, scene.as_ref(), page).unwrap();
        }
        let end = panel.lines.len() - usize::from(page);
        assert_eq!(
            usize::from(panel.scroll),
            end,
            "the last line at the bottom"
        );
        let none = EnginePanel::new(0, None);
        assert!(none.failed && none.payload.is_none());
    }

    #[test]
    fn end_and_page_down_reach_the_script_s_last_line() {
        let scene = fig5();
        let page = 15;
        let panel = EnginePanel::new(0, scene.as_ref());
        let at_end = panel
            .clone()
            .update(Action::Jump(Jump::Last), scene.as_ref(), page)
            .unwrap();
        let shown = &at_end.lines[usize::from(at_end.scroll)..];
        assert_eq!(shown.len(), usize::from(page));
        assert!(
            shown.last().unwrap().starts_with("print(f\"RESULT"),
            "{shown:?}"
        );
        let mut paged = panel;
        let mut presses = 0;
        while paged.scroll != at_end.scroll {
            paged = paged
                .update(Action::Jump(Jump::NextSection), scene.as_ref(), page)
                .unwrap();
            presses += 1;
            assert!(presses <= paged.lines.len(), "PgDn never reaches the end");
        }
        assert_eq!(presses, paged.lines.len().div_ceil(usize::from(page)) - 1);
        let home = paged
            .update(Action::Jump(Jump::First), scene.as_ref(), page)
            .unwrap();
        assert_eq!(home.scroll, 0);
    }

    #[test]
    fn writes_the_script_to_a_new_file_and_never_over_one() {
        let folder = tempfile::Builder::new()
            .prefix("hertz-tui-engine-panel-")
            .tempdir()
            .unwrap();
        let dir = folder.path();
        let scene = fig5();
        // MuJoCo: a Python script.
        let index = ENGINES.iter().position(|e| e.id == "mujoco").unwrap();
        let mut panel = EnginePanel::new(index, scene.as_ref());
        let first = panel.write_to(dir).unwrap();
        let second = panel.write_to(dir).unwrap();
        assert_eq!(first.file_name().unwrap(), "mujoco-impact.py");
        assert_eq!(second.file_name().unwrap(), "mujoco-impact-2.py");
        let text = std::fs::read_to_string(&first).unwrap();
        assert!(
            text.contains("import mujoco") && panel.lines.join("\n").ends_with(text.trim_end())
        );
        assert!(
            panel
                .note
                .as_deref()
                .unwrap()
                .contains("mujoco-impact-2.py")
        );
        // Chrono: no script, the fragments.
        let index = ENGINES.iter().position(|e| e.id == "chrono").unwrap();
        let mut panel = EnginePanel::new(index, scene.as_ref());
        let path = panel.write_to(dir).unwrap();
        assert!(
            std::fs::read_to_string(path)
                .unwrap()
                .contains("ChSystemSMC")
        );
        let missing = dir.join("no-such-folder");
        let err = panel.write_to(&missing).unwrap_err();
        assert!(err.contains("no-such-folder"), "{err}");
    }
}
