//! The scene-file schema: which keys exist, what they hold, which a shape needs.

/// Keys of the top level of a scene file; `description`, `models` and `[solver]` are optional.
pub(super) const SCENE_KEYS: &[&str] = &[
    "name",
    "description",
    "models",
    "body1",
    "body2",
    "impact",
    "solver",
    "system",
    "fit",
];
/// Keys of `[body1]` and `[body2]`; which of radius/length are required depends on the shape.
pub(super) const BODY_KEYS: &[&str] = &["shape", "radius", "length", "mass", "material"];
/// Keys of an inline material table (all required).
pub(super) const MATERIAL_KEYS: &[&str] = &[
    "name",
    "youngs_modulus",
    "poisson_ratio",
    "yield_stress",
    "density",
];
/// Keys of a material preset file: the inline keys plus an optional description (name optional too).
pub(super) const MATERIAL_FILE_KEYS: &[&str] = &[
    "name",
    "description",
    "youngs_modulus",
    "poisson_ratio",
    "yield_stress",
    "density",
];
/// The number keys of `[impact]` (all required).
pub(super) const IMPACT_KEYS: &[&str] = &["v0", "restitution", "plastic_indentation"];
/// Every key of `[impact]`: its numbers and the optional `assumed` list, which names the numbers
/// the scene's user did not give ([`Assumed`](crate::model::scene::Assumed)).
pub(super) const IMPACT_TABLE_KEYS: &[&str] =
    &["v0", "restitution", "plastic_indentation", "assumed"];
/// The shapes a body may have.
pub(crate) const SHAPES: &[&str] = &["sphere", "cylinder", "plane"];

/// What kind of value a scene key holds (used by `--set` to parse its value).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum KeyKind {
    Text,
    Number,
    Shape,
    /// A preset material name or an inline table.
    Material,
}

/// The kind of the scene key at `path`, or `None` if the schema has no such key.
pub(crate) fn key_kind(path: &[&str]) -> Option<KeyKind> {
    match path {
        ["name" | "description"] => Some(KeyKind::Text),
        ["body1" | "body2", "shape"] => Some(KeyKind::Shape),
        ["body1" | "body2", "material"] => Some(KeyKind::Material),
        ["body1" | "body2", "material", "name"] => Some(KeyKind::Text),
        ["body1" | "body2", "material", key] if MATERIAL_KEYS.contains(key) => {
            Some(KeyKind::Number)
        }
        ["body1" | "body2", key] if BODY_KEYS.contains(key) => Some(KeyKind::Number),
        ["impact", key] if IMPACT_KEYS.contains(key) => Some(KeyKind::Number),
        ["system", "kind" | "forcing"] => Some(KeyKind::Text),
        ["fit", "law" | "source" | "note"] => Some(KeyKind::Text),
        ["fit", key] if super::fit::FIT_KEYS.contains(key) => Some(KeyKind::Number),
        ["system", key] if super::system::SYSTEM_KEYS.contains(key) => Some(KeyKind::Number),
        _ => None,
    }
}

/// The keys a body of `shape` needs besides `shape` and `material`.
pub(crate) fn shape_keys(shape: &str) -> &'static [&'static str] {
    match shape {
        "sphere" => &["radius"],
        "cylinder" => &["radius", "length"],
        _ => &[],
    }
}
