//! The catalogue of materials and scenes: built-ins, overridden by user presets of the same name.

use std::collections::BTreeMap;
use std::fmt;
use std::fs;
use std::path::{Path, PathBuf};

use crate::model::material::Material;
use crate::model::overrides::{self, Override};
use crate::model::scene::Scene;
use crate::model::scene_file::{self, Document, SceneView};
use crate::model::scene_title::{bodies_name, retitled};
use crate::model::system::SystemSpec;

use super::builtin;
use super::error::PresetError;
use super::save::{SaveTarget, is_kebab_case, kebab_case, save_scene_in};
use super::user_dir::user_dir;

/// Where a preset comes from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Origin {
    /// Shipped with hertz-tui (`presets/`).
    BuiltIn,
    /// A file in the user preset folder.
    User(PathBuf),
}

impl fmt::Display for Origin {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Origin::BuiltIn => f.write_str("built-in"),
            Origin::User(_) => f.write_str("user"),
        }
    }
}

/// What a listing shows about a preset.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PresetInfo {
    /// Kebab-case name: the file stem.
    pub name: String,
    /// The file's `description`, or empty.
    pub description: String,
    /// Built-in or user.
    pub origin: Origin,
    /// A user preset that replaces a built-in of the same name.
    pub overrides_builtin: bool,
}

/// A scene preset: its listing and its TOML source (parsed again on every load, so overrides apply
/// to the text as written).
#[derive(Debug, Clone)]
struct SceneEntry {
    info: PresetInfo,
    /// How messages name the source.
    origin: String,
    text: String,
}

/// All presets known to this run: built-in ones and those of the user preset folder.
#[derive(Debug, Clone)]
pub struct Registry {
    materials: BTreeMap<String, PresetInfo>,
    /// Name → material, what scene files resolve `material = "name"` against.
    catalog: BTreeMap<String, Material>,
    scenes: BTreeMap<String, SceneEntry>,
    warnings: Vec<PresetError>,
    user_dir: Option<PathBuf>,
}

impl Registry {
    /// Built-in presets plus those of [`user_dir`](super::user_dir()). User presets that fail to
    /// parse are skipped and reported by [`Registry::warnings`]; only a broken built-in fails.
    pub fn load() -> Result<Registry, PresetError> {
        Registry::load_from(user_dir().as_deref())
    }

    /// Built-in presets only.
    pub fn builtin() -> Result<Registry, PresetError> {
        Registry::load_from(None)
    }

    /// Built-in presets plus those of `user_dir` (holding `materials/` and `scenes/`), if given.
    pub fn load_from(user_dir: Option<&Path>) -> Result<Registry, PresetError> {
        let mut registry = Registry {
            materials: BTreeMap::new(),
            catalog: BTreeMap::new(),
            scenes: BTreeMap::new(),
            warnings: Vec::new(),
            user_dir: user_dir.map(Path::to_path_buf),
        };
        for (name, text) in builtin::MATERIALS {
            registry.add_material(
                name,
                builtin::origin("materials", name),
                text,
                Origin::BuiltIn,
            )?;
        }
        let user_materials = user_dir.map(|d| registry.user_files(&d.join("materials")));
        for (name, path, text) in user_materials.into_iter().flatten() {
            let origin = path.display().to_string();
            if let Err(e) = registry.add_material(&name, origin, &text, Origin::User(path)) {
                registry.warnings.push(e);
            }
        }
        for (name, text) in builtin::SCENES {
            registry.add_scene(name, builtin::origin("scenes", name), text, Origin::BuiltIn)?;
        }
        let user_scenes = user_dir.map(|d| registry.user_files(&d.join("scenes")));
        for (name, path, text) in user_scenes.into_iter().flatten() {
            let origin = path.display().to_string();
            if let Err(e) = registry.add_scene(&name, origin, &text, Origin::User(path)) {
                registry.warnings.push(e);
            }
        }
        Ok(registry)
    }

    /// Problems with user presets found while loading (the presets concerned were skipped).
    pub fn warnings(&self) -> &[PresetError] {
        &self.warnings
    }

    /// The user preset folder this registry read, if any.
    pub fn user_dir(&self) -> Option<&Path> {
        self.user_dir.as_deref()
    }

    /// Every scene, sorted by name.
    pub fn scenes(&self) -> Vec<&PresetInfo> {
        self.scenes.values().map(|e| &e.info).collect()
    }

    /// Every material, sorted by name.
    pub fn materials(&self) -> Vec<&PresetInfo> {
        self.materials.values().collect()
    }

    /// The material called `name`.
    pub fn material(&self, name: &str) -> Result<Material, PresetError> {
        self.catalog
            .get(name)
            .cloned()
            .ok_or_else(|| PresetError::UnknownMaterial {
                name: name.to_string(),
                known: self.catalog.keys().cloned().collect(),
            })
    }

    /// Name → material: what `material = "name"` in a scene resolves against.
    pub fn material_catalog(&self) -> &BTreeMap<String, Material> {
        &self.catalog
    }

    /// The scene preset called `name_or_path`, or else the scene file at that path.
    pub fn scene(&self, name_or_path: &str) -> Result<Scene, PresetError> {
        self.scene_with(name_or_path, &[])
    }

    /// [`Registry::scene`] with `--set` overrides applied before the scene is typed and validated.
    pub fn scene_with(
        &self,
        name_or_path: &str,
        overrides: &[Override],
    ) -> Result<Scene, PresetError> {
        let (origin, text) = self.source(name_or_path)?;
        self.decode(Document::parse(origin, &text)?, overrides)
    }

    /// The description of a scene preset or scene file, if it has one.
    pub fn scene_description(&self, name_or_path: &str) -> Result<Option<String>, PresetError> {
        let (origin, text) = self.source(name_or_path)?;
        Ok(Document::parse(origin, &text)?
            .description()
            .map(str::to_string))
    }

    /// The view (checked models, solver settings) of a scene preset or scene file.
    pub fn scene_view(&self, name_or_path: &str) -> Result<SceneView, PresetError> {
        let (origin, text) = self.source(name_or_path)?;
        Ok(scene_file::decode_view(&Document::parse(origin, &text)?)?)
    }

    /// The `[system]` table of a scene preset or scene file (after `overrides`), if it has one.
    pub fn scene_system(
        &self,
        name_or_path: &str,
        overrides: &[Override],
    ) -> Result<Option<SystemSpec>, PresetError> {
        let (origin, text) = self.source(name_or_path)?;
        let mut doc = Document::parse(origin, &text)?;
        overrides::apply(&mut doc, overrides, &self.catalog)?;
        Ok(scene_file::decode_system(&doc)?)
    }

    /// `scene` with `overrides` applied, through the same path as a scene file.
    pub fn apply_overrides(
        &self,
        scene: &Scene,
        overrides: &[Override],
    ) -> Result<Scene, PresetError> {
        Ok(self.apply_overrides_with_system(scene, None, overrides)?.0)
    }

    /// [`Registry::apply_overrides`] to a scene and its `[system]` table (`system.*` keys
    /// included): both, after the overrides, as a scene file with that table would give them.
    pub fn apply_overrides_with_system(
        &self,
        scene: &Scene,
        system: Option<&SystemSpec>,
        overrides: &[Override],
    ) -> Result<(Scene, Option<SystemSpec>), PresetError> {
        let text = scene_file::to_toml_with_system(scene, None, None, system);
        let doc = Document::parse(scene.name.clone(), &text)?;
        let mut edited = doc.clone();
        overrides::apply(&mut edited, overrides, &self.catalog)?;
        let system = scene_file::decode_system(&edited)?;
        Ok((self.decode(doc, overrides)?, system))
    }

    /// Saves `scene` to `target`; a user preset goes to this registry's user folder.
    pub fn save_scene(
        &self,
        scene: &Scene,
        description: Option<&str>,
        target: SaveTarget<'_>,
    ) -> Result<PathBuf, PresetError> {
        save_scene_in(
            self.user_dir.as_deref(),
            scene,
            description,
            None,
            None,
            target,
        )
    }

    /// [`Registry::save_scene`] with the view (`models`, `[solver]`) and the `[system]` table, if
    /// any, written too: what the explorer saves, which reads back to the same scene and system.
    pub fn save_scene_with_view(
        &self,
        scene: &Scene,
        description: Option<&str>,
        view: &SceneView,
        system: Option<&SystemSpec>,
        target: SaveTarget<'_>,
    ) -> Result<PathBuf, PresetError> {
        save_scene_in(
            self.user_dir.as_deref(),
            scene,
            description,
            Some(view),
            system,
            target,
        )
    }

    /// Whether `name` is a built-in scene preset (a user preset of that name would shadow it).
    pub fn is_builtin_scene(&self, name: &str) -> bool {
        builtin::SCENES.iter().any(|(n, _)| *n == name)
    }

    /// The scene of `doc` with `overrides` applied. An edited scene is renamed by what its bodies
    /// are (unless `name` itself is set): a preset's "…on steel plate" no longer names it once
    /// `--set body2.material=…` changed the plate.
    fn decode(&self, mut doc: Document, overrides: &[Override]) -> Result<Scene, PresetError> {
        let original = (!overrides.is_empty())
            .then(|| scene_file::decode_scene(&doc, &self.catalog).ok())
            .flatten();
        overrides::apply(&mut doc, overrides, &self.catalog)?;
        let mut scene = scene_file::decode_scene(&doc, &self.catalog)?;
        if !overrides.is_empty() && !overrides.iter().any(|o| o.key == "name") {
            scene.name = match original {
                Some(original) => retitled(&original, None, &scene).0,
                None => bodies_name(&scene),
            };
        }
        Ok(scene)
    }

    /// (origin for messages, TOML text) of a preset name or, failing that, a file path.
    fn source(&self, name_or_path: &str) -> Result<(String, String), PresetError> {
        if let Some(entry) = self.scenes.get(name_or_path) {
            return Ok((entry.origin.clone(), entry.text.clone()));
        }
        let path = Path::new(name_or_path);
        let looks_like_path = name_or_path.contains(['/', '\\']) || name_or_path.ends_with(".toml");
        if looks_like_path || path.is_file() {
            let text = fs::read_to_string(path).map_err(|e| PresetError::Read {
                path: path.to_path_buf(),
                message: e.to_string(),
            })?;
            return Ok((name_or_path.to_string(), text));
        }
        Err(PresetError::UnknownScene {
            name: name_or_path.to_string(),
            known: self.scenes.keys().cloned().collect(),
        })
    }

    fn add_material(
        &mut self,
        name: &str,
        origin: String,
        text: &str,
        from: Origin,
    ) -> Result<(), PresetError> {
        let doc = Document::parse(origin, text)?;
        let material = scene_file::decode_material(&doc, name)?;
        let info = self.info(
            name,
            doc.description(),
            from,
            self.materials.contains_key(name),
        );
        self.catalog.insert(name.to_string(), material);
        self.materials.insert(name.to_string(), info);
        Ok(())
    }

    /// Parses the scene now, so that a broken user scene is reported at load and not listed.
    fn add_scene(
        &mut self,
        name: &str,
        origin: String,
        text: &str,
        from: Origin,
    ) -> Result<(), PresetError> {
        let doc = Document::parse(origin.clone(), text)?;
        scene_file::decode_scene(&doc, &self.catalog)?;
        let info = self.info(
            name,
            doc.description(),
            from,
            self.scenes.contains_key(name),
        );
        self.scenes.insert(
            name.to_string(),
            SceneEntry {
                info,
                origin,
                text: text.to_string(),
            },
        );
        Ok(())
    }

    fn info(
        &self,
        name: &str,
        description: Option<&str>,
        origin: Origin,
        replaces: bool,
    ) -> PresetInfo {
        PresetInfo {
            name: name.to_string(),
            description: description.unwrap_or_default().to_string(),
            overrides_builtin: replaces && matches!(origin, Origin::User(_)),
            origin,
        }
    }

    /// (stem, path, text) of every `*.toml` in `folder`, sorted; unreadable entries become warnings.
    /// A missing folder is normal (no user presets).
    fn user_files(&mut self, folder: &Path) -> Vec<(String, PathBuf, String)> {
        let entries = match fs::read_dir(folder) {
            Ok(entries) => entries,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Vec::new(),
            Err(e) => {
                self.warnings.push(PresetError::Read {
                    path: folder.to_path_buf(),
                    message: e.to_string(),
                });
                return Vec::new();
            }
        };
        let mut paths: Vec<PathBuf> = entries
            .filter_map(|entry| entry.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|ext| ext == "toml") && p.is_file())
            .collect();
        paths.sort();
        let mut files = Vec::new();
        for path in paths {
            let stem = path
                .file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_default();
            if !is_kebab_case(&stem) {
                self.warnings.push(PresetError::NotKebabCase {
                    suggestion: kebab_case(&stem),
                    path,
                    stem,
                });
                continue;
            }
            match fs::read_to_string(&path) {
                Ok(text) => files.push((stem, path, text)),
                Err(e) => self.warnings.push(PresetError::Read {
                    path,
                    message: e.to_string(),
                }),
            }
        }
        files
    }
}
