//! The presets picker: built-in and user scenes, then materials; typing filters them.

use tui_input::InputRequest;

use crate::model::presets::{Origin, Registry};

/// What a picker row loads.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EntryKind {
    Scene,
    Material,
}

/// One row of the picker.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Entry {
    pub kind: EntryKind,
    pub name: String,
    pub description: String,
    /// `built-in` or `user`.
    pub origin: String,
}

/// The picker's rows, filter and selection.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Picker {
    pub entries: Vec<Entry>,
    /// Typed text; the rows shown are those whose name or description contain every word of it.
    pub filter: String,
    /// Index into [`Picker::visible`].
    pub selected: usize,
}

impl Entry {
    fn matches(&self, filter: &str) -> bool {
        let haystack = format!("{} {}", self.name, self.description).to_lowercase();
        filter
            .to_lowercase()
            .split_whitespace()
            .all(|word| haystack.contains(word))
    }
}

impl Picker {
    /// Scenes first, then materials, each sorted by name as the registry lists them.
    pub fn new(registry: &Registry) -> Picker {
        let entry = |kind, info: &crate::model::presets::PresetInfo| Entry {
            kind,
            name: info.name.clone(),
            description: info.description.clone(),
            origin: match info.origin {
                Origin::BuiltIn => "built-in".into(),
                Origin::User(_) => "user".into(),
            },
        };
        let entries = registry
            .scenes()
            .into_iter()
            .map(|info| entry(EntryKind::Scene, info))
            .chain(
                registry
                    .materials()
                    .into_iter()
                    .map(|info| entry(EntryKind::Material, info)),
            )
            .collect();
        Picker {
            entries,
            filter: String::new(),
            selected: 0,
        }
    }

    /// The rows the filter lets through, in order.
    pub fn visible(&self) -> Vec<&Entry> {
        self.entries
            .iter()
            .filter(|e| e.matches(&self.filter))
            .collect()
    }

    pub fn selected(&self) -> Option<&Entry> {
        self.visible().get(self.selected).copied()
    }

    /// Types into the filter (characters, backspace, clearing); the selection goes to the entry
    /// named exactly as the filter (any case) if there is one, else to the top, so that Enter
    /// loads the scene whose name was typed rather than the first that contains it.
    pub fn edit_filter(&mut self, request: InputRequest) {
        match request {
            InputRequest::InsertChar(c) => self.filter.push(c),
            InputRequest::DeletePrevChar => {
                self.filter.pop();
            }
            InputRequest::DeletePrevWord => {
                let kept = self.filter.trim_end().rfind(' ').map_or(0, |i| i + 1);
                self.filter.truncate(kept);
            }
            InputRequest::DeleteLine | InputRequest::DeleteTillEnd => self.filter.clear(),
            _ => return,
        }
        let typed = self.filter.trim().to_lowercase();
        self.selected = self
            .visible()
            .iter()
            .position(|e| e.name.to_lowercase() == typed)
            .unwrap_or(0);
    }

    /// The first or the last visible row.
    pub fn jump(&mut self, to_end: bool) {
        self.selected = if to_end {
            self.visible().len().saturating_sub(1)
        } else {
            0
        };
    }

    /// Moves the selection, wrapping around.
    pub fn step(&mut self, forward: bool) {
        let n = self.visible().len();
        if n == 0 {
            return;
        }
        self.selected = if forward {
            (self.selected + 1) % n
        } else {
            (self.selected + n - 1) % n
        };
    }

    /// Selects the entry of `kind` called `name`, if listed.
    pub fn select(&mut self, kind: EntryKind, name: &str) {
        if let Some(i) = self
            .visible()
            .iter()
            .position(|e| e.kind == kind && e.name == name)
        {
            self.selected = i;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lists_scenes_then_materials_and_wraps() {
        let registry = Registry::builtin().unwrap();
        let mut picker = Picker::new(&registry);
        let scenes = picker
            .entries
            .iter()
            .take_while(|e| e.kind == EntryKind::Scene)
            .count();
        assert_eq!(scenes, registry.scenes().len());
        assert_eq!(
            picker.entries.len(),
            scenes + registry.materials().len(),
            "materials follow the scenes"
        );
        assert!(picker.entries.iter().any(|e| e.name == "steel"));
        picker.step(false);
        assert_eq!(picker.selected, picker.entries.len() - 1);
        picker.step(true);
        assert_eq!(picker.selected, 0);
        picker.select(EntryKind::Material, "steel");
        assert_eq!(picker.selected().map(|e| e.name.as_str()), Some("steel"));
    }

    #[test]
    fn typing_filters_by_name_and_description() {
        let registry = Registry::builtin().unwrap();
        let mut picker = Picker::new(&registry);
        picker.step(true);
        for c in "FIG 4".chars() {
            picker.edit_filter(InputRequest::InsertChar(c));
        }
        let names: Vec<&str> = picker.visible().iter().map(|e| e.name.as_str()).collect();
        assert_eq!(
            names,
            ["fig4-steel-sphere-r10-plate"],
            "every word, any case"
        );
        assert_eq!(picker.selected, 0, "the selection goes to the top");
        for c in "zzz".chars() {
            picker.edit_filter(InputRequest::InsertChar(c));
        }
        assert!(picker.selected().is_none(), "nothing matches");
        picker.edit_filter(InputRequest::DeleteLine);
        for c in "alumin".chars() {
            picker.edit_filter(InputRequest::InsertChar(c));
        }
        // The aluminium sphere scene by its name, the material by its name.
        assert_eq!(picker.visible().len(), 2);
        picker.edit_filter(InputRequest::DeletePrevChar);
        assert_eq!(picker.filter, "alumi");
        picker.jump(true);
        assert_eq!(picker.selected().map(|e| e.kind), Some(EntryKind::Material));
    }

    /// A typed name selects its own entry, not the first entry that contains it: three scenes
    /// contain `steel-sphere-r10-plate`, and `fig4-…` comes first.
    #[test]
    fn an_exact_name_is_selected_over_the_first_match() {
        let registry = Registry::builtin().unwrap();
        for name in ["steel-sphere-r10-plate", "STEEL", "Steel-Sphere-R10-Plate"] {
            let mut picker = Picker::new(&registry);
            for c in name.chars() {
                picker.edit_filter(InputRequest::InsertChar(c));
            }
            assert!(picker.visible().len() > 1, "{name}: more than one match");
            assert_eq!(
                picker.selected().map(|e| e.name.to_lowercase()),
                Some(name.to_lowercase()),
            );
        }
        // A partial name selects the first match; Ctrl-W drops the last word.
        let mut picker = Picker::new(&registry);
        for c in "fig plate".chars() {
            picker.edit_filter(InputRequest::InsertChar(c));
        }
        assert_eq!(picker.selected, 0);
        picker.edit_filter(InputRequest::DeletePrevWord);
        assert_eq!(picker.filter, "fig ");
    }
}
