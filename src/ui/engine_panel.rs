//! The engine panel (`t` in the explorer): the scene's contact parameters for one simulation
//! engine, as `hertz-tui translate` prints them; ← → picks the engine, ↑ ↓ scroll.

use crate::format::translation::render_run;
use crate::model::Scene;
use crate::model::engine::run::DEFAULT_TOLERANCE;
use crate::model::engine::{self, ENGINES};

use super::action::Action;
use super::field::Nudge;

/// The open panel: which engine, how far scrolled, and its text (or why there is none).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct EnginePanel {
    pub index: usize,
    pub scroll: u16,
    pub lines: Vec<String>,
    pub failed: bool,
}

impl EnginePanel {
    /// The panel for engine `index` on `scene` (the last valid one; `None` while none is).
    pub fn new(index: usize, scene: Option<&Scene>) -> Self {
        let index = index % ENGINES.len();
        let id = ENGINES[index].id;
        let translated = scene.map(|s| (s, engine::translate_run(id, s, DEFAULT_TOLERANCE)));
        let (text, failed) = match translated {
            Some((s, Ok(translated))) => (render_run(&s.name, &translated), false),
            Some((_, Err(e))) => (format!("{}: {e}", ENGINES[index].name), true),
            None => ("no valid scene to translate".to_string(), true),
        };
        EnginePanel {
            index,
            scroll: 0,
            lines: text.lines().map(str::to_string).collect(),
            failed,
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

    /// The panel after `action`: ← → another engine, ↑ ↓ scroll; `None` closes it (Esc, q, t).
    pub fn update(mut self, action: Action, scene: Option<&Scene>) -> Option<Self> {
        match action {
            Action::Cancel => return None,
            Action::Nudge(direction) => self = self.step(direction, scene),
            Action::Up => self.scroll_by(false),
            Action::Down => self.scroll_by(true),
            _ => {}
        }
        Some(self)
    }

    /// Scrolls by one line, within the text.
    pub fn scroll_by(&mut self, down: bool) {
        let last = self.lines.len().saturating_sub(1) as u16;
        self.scroll = if down {
            (self.scroll + 1).min(last)
        } else {
            self.scroll.saturating_sub(1)
        };
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::presets::Registry;

    #[test]
    fn cycles_through_every_engine_and_scrolls_within_the_text() {
        let scene = Registry::builtin()
            .and_then(|r| r.scene("fig5-steel-sphere-r10-plate"))
            .ok();
        let mut panel = EnginePanel::new(0, scene.as_ref());
        assert!(!panel.failed && panel.lines[0].starts_with(ENGINES[0].name));
        panel = panel.step(Nudge::Down, scene.as_ref());
        assert_eq!(panel.index, ENGINES.len() - 1);
        assert!(panel.lines[0].starts_with(ENGINES[ENGINES.len() - 1].name));
        panel = panel.step(Nudge::Up, scene.as_ref());
        assert_eq!(panel.index, 0);
        panel.scroll_by(false);
        assert_eq!(panel.scroll, 0);
        for _ in 0..1000 {
            panel.scroll_by(true);
        }
        assert_eq!(usize::from(panel.scroll), panel.lines.len() - 1);
        let none = EnginePanel::new(0, None);
        assert!(none.failed);
    }
}
