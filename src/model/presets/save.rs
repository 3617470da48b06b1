//! Saving a scene as TOML: to the user scenes folder (as a preset) or to a path.

use std::fs;
use std::path::{Path, PathBuf};

use crate::model::scene::Scene;
use crate::model::scene_file::{self, SceneView};
use crate::model::system::SystemSpec;

use super::error::PresetError;
use super::user_dir::user_dir;

/// Where to save a scene.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SaveTarget<'a> {
    /// `<user dir>/scenes/<name>.toml`; `name` must be kebab-case. It overrides a built-in of that name.
    UserPreset {
        /// The preset's kebab-case name.
        name: &'a str,
    },
    /// Any file path; its folder must exist.
    Path(&'a Path),
}

/// Whether `name` is kebab-case: lowercase ASCII letters and digits joined by single hyphens.
pub fn is_kebab_case(name: &str) -> bool {
    !name.is_empty()
        && name.split('-').all(|part| {
            !part.is_empty()
                && part
                    .chars()
                    .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit())
        })
}

/// A kebab-case preset name made from a title: "Steel sphere R = 10 mm" → `steel-sphere-r-10-mm`.
pub fn kebab_case(title: &str) -> String {
    let lowered: String = title
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_lowercase()
            } else {
                ' '
            }
        })
        .collect();
    lowered.split_whitespace().collect::<Vec<_>>().join("-")
}

/// Validates `scene` and writes it (materials inline) to `target`; returns the file written.
/// Uses the user preset folder of the environment for [`SaveTarget::UserPreset`].
pub fn save_scene(
    scene: &Scene,
    description: Option<&str>,
    target: SaveTarget<'_>,
) -> Result<PathBuf, PresetError> {
    save_scene_in(
        user_dir().as_deref(),
        scene,
        description,
        None,
        None,
        target,
    )
}

/// [`save_scene`] with an explicit user preset folder, and the view and `[system]` table if given.
pub(super) fn save_scene_in(
    user_dir: Option<&Path>,
    scene: &Scene,
    description: Option<&str>,
    view: Option<&SceneView>,
    system: Option<&SystemSpec>,
    target: SaveTarget<'_>,
) -> Result<PathBuf, PresetError> {
    scene.validate().map_err(PresetError::InvalidScene)?;
    // A table that would not read back is not written: the file must open again.
    if let Some(system) = system {
        system.validate().map_err(PresetError::InvalidSystem)?;
    }
    let path = match target {
        SaveTarget::Path(path) => path.to_path_buf(),
        SaveTarget::UserPreset { name } => {
            if !is_kebab_case(name) {
                return Err(PresetError::InvalidName(name.to_string()));
            }
            let folder = user_dir.ok_or(PresetError::NoUserDir)?.join("scenes");
            fs::create_dir_all(&folder).map_err(|e| PresetError::Write {
                path: folder.clone(),
                message: e.to_string(),
            })?;
            folder.join(format!("{name}.toml"))
        }
    };
    write_atomically(
        &path,
        &scene_file::to_toml_with_system(scene, description, view, system),
    )?;
    Ok(path)
}

/// Writes through a temporary file and a rename, so a failed save never leaves half a scene.
fn write_atomically(path: &Path, text: &str) -> Result<(), PresetError> {
    let write_error = |e: std::io::Error| PresetError::Write {
        path: path.to_path_buf(),
        message: e.to_string(),
    };
    let mut temporary = path.as_os_str().to_owned();
    temporary.push(".part");
    let temporary = PathBuf::from(temporary);
    fs::write(&temporary, text).map_err(write_error)?;
    fs::rename(&temporary, path).map_err(|e| {
        // Best effort: the rename failed, so the temporary file is all that is left to clean up.
        let _ = fs::remove_file(&temporary);
        write_error(e)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kebab_case_names() {
        assert!(is_kebab_case("steel-sphere-r10-plate"));
        assert!(is_kebab_case("fig5"));
        for bad in ["", "Steel", "a--b", "-a", "a-", "a_b", "a b", "ä"] {
            assert!(!is_kebab_case(bad), "{bad}");
        }
        assert_eq!(
            kebab_case("Steel sphere R = 10 mm on steel plate"),
            "steel-sphere-r-10-mm-on-steel-plate"
        );
        assert!(is_kebab_case(&kebab_case("  Fig. 5: x_pl = 2.3 µm ")));
    }
}
