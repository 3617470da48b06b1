//! `hertz-tui list`: every material and scene, one per line, with its origin and description.

use crate::model::presets::{DEFAULT_SCENE, Origin, PresetInfo, Registry};

use super::layout::columns;

/// The listing as text.
pub fn render(registry: &Registry) -> String {
    let mut rows = vec![vec![
        "KIND".to_string(),
        "NAME".to_string(),
        "ORIGIN".to_string(),
        "DESCRIPTION".to_string(),
    ]];
    let row = |kind: &str, info: &PresetInfo| {
        let origin = match (&info.origin, info.overrides_builtin) {
            (Origin::User(_), true) => "user (replaces built-in)".to_string(),
            (origin, _) => origin.to_string(),
        };
        let mut description = info.description.clone();
        if kind == "scene" && info.name == DEFAULT_SCENE {
            description.push_str(" [default]");
        }
        vec![kind.to_string(), info.name.clone(), origin, description]
    };
    rows.extend(registry.materials().into_iter().map(|m| row("material", m)));
    rows.extend(registry.scenes().into_iter().map(|s| row("scene", s)));
    let mut out = columns(&rows, "");
    match registry.user_dir() {
        Some(dir) => out.push_str(&format!(
            "\nUser presets: {}/{{materials,scenes}}/*.toml (a user preset replaces a built-in of the same name)\n",
            dir.display()
        )),
        None => out.push_str("\nUser presets: none (set XDG_CONFIG_HOME or HOME)\n"),
    }
    out
}
