//! The presets picker: built-in and user scenes, then materials.

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

/// The picker's rows and selection.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Picker {
    pub entries: Vec<Entry>,
    pub selected: usize,
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
            selected: 0,
        }
    }

    pub fn selected(&self) -> Option<&Entry> {
        self.entries.get(self.selected)
    }

    /// Moves the selection, wrapping around.
    pub fn step(&mut self, forward: bool) {
        let n = self.entries.len();
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
            .entries
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
}
