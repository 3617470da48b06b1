//! `--set KEY=VALUE` overrides of scene keys by dotted path.
//!
//! Overrides edit the TOML table of a [`Document`] before it is typed, so every check of the scene
//! file (types, shapes, ranges) applies to overridden values too, and messages point at the `--set`.

use std::collections::BTreeMap;
use std::fmt;
use std::str::FromStr;

use thiserror::Error;
use toml::{Table, Value};

use crate::format::units::{self, Unit};

use super::material::Material;
use super::scene_file::{self, Document, KeyKind};
use super::system::Param;

/// One `KEY=VALUE` override; the key is checked against the scene schema when parsed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Override {
    /// Dotted path, e.g. `body1.material.youngs_modulus`.
    pub key: String,
    /// The value as typed; parsed according to the key's kind when applied.
    pub value: String,
}

/// Why an override could not be parsed or applied. Every message names the key.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum OverrideError {
    #[error("--set \"{0}\": expected KEY=VALUE, e.g. impact.v0=0.5")]
    Syntax(String),
    #[error("--set {key}: unknown scene key (known keys: {KNOWN_KEYS})")]
    UnknownKey { key: String },
    #[error("--set {key}: {problem}")]
    BadValue { key: String, problem: ValueProblem },
}

/// What is wrong with an override's value.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ValueProblem {
    /// A numeric key given text that does not parse as a number.
    #[error("\"{0}\" is not a number (e.g. 0.5, 2e11, 2.3e-6, 10 mm)")]
    NotANumber(String),
    /// A number given with a unit that is not the key's (`system.frequency=20 kg`), or that
    /// overflows; the parser's reason, which names the units the key takes.
    #[error("\"{given}\": {reason}")]
    BadQuantity { given: String, reason: String },
    /// A shape that is not one of the scene schema's.
    #[error("unknown shape \"{0}\" (expected one of: sphere, cylinder, plane)")]
    UnknownShape(String),
    /// A material given as an inline table that TOML does not read; TOML's reason when it has one.
    #[error("not a valid inline table{}", .0.as_ref().map(|r| format!(": {r}")).unwrap_or_default())]
    NotAnInlineTable(Option<String>),
    /// A field set inside a material named by a preset that does not exist.
    #[error("the body's material \"{name}\" is not a known material (known: {})", .known.join(", "))]
    UnknownMaterial { name: String, known: Vec<String> },
    /// A field set inside a key that holds a value, not a table.
    #[error("cannot set a field inside `{part}`, which is a {found}")]
    NotATable { part: String, found: &'static str },
}

/// Every key `--set` accepts, for messages.
const KNOWN_KEYS: &str = "name, description, body1.shape, body1.radius, body1.length, body1.mass, \
     body1.material, body1.material.name, body1.material.youngs_modulus, \
     body1.material.poisson_ratio, body1.material.yield_stress, body1.material.density, the same \
     for body2, impact.v0, impact.restitution, impact.plastic_indentation, system.kind, \
     system.amplitude, system.frequency, system.gravity, system.stiffness, system.damping_ratio, \
     system.damping, system.forcing, system.forcing_amplitude, system.gap, system.second_gap";

impl Override {
    /// An override of `key` with `value`; fails if the scene schema has no such key.
    pub fn new(key: &str, value: &str) -> Result<Override, OverrideError> {
        let key = key.trim();
        let path: Vec<&str> = key.split('.').collect();
        if scene_file::key_kind(&path).is_none() {
            return Err(OverrideError::UnknownKey {
                key: key.to_string(),
            });
        }
        Ok(Override {
            key: key.to_string(),
            value: value.trim().to_string(),
        })
    }
}

impl FromStr for Override {
    type Err = OverrideError;

    /// Parses `KEY=VALUE` (the `--set` argument).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let (key, value) = s
            .split_once('=')
            .ok_or_else(|| OverrideError::Syntax(s.to_string()))?;
        if key.trim().is_empty() {
            return Err(OverrideError::Syntax(s.to_string()));
        }
        Override::new(key, value)
    }
}

impl fmt::Display for Override {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}={}", self.key, self.value)
    }
}

/// Applies `overrides` in order to `doc`; `materials` resolves material names. A number may carry
/// its key's unit (`impact.v0=300 mm/s`, `system.frequency=20 Hz`); the table gets its SI value.
pub fn apply(
    doc: &mut Document,
    overrides: &[Override],
    materials: &BTreeMap<String, Material>,
) -> Result<(), OverrideError> {
    // The forcing amplitude is a force or a length by the forcing, which may be set after it.
    let base_motion = overrides
        .iter()
        .rev()
        .find(|o| o.key == "system.forcing")
        .map(|o| o.value.trim_matches('"') == "base")
        .unwrap_or_else(|| {
            let forcing = doc
                .table()
                .get("system")
                .and_then(|s| s.get("forcing"))
                .and_then(Value::as_str);
            forcing == Some("base")
        });
    for o in overrides {
        apply_one(doc, o, materials, base_motion)?;
        doc.mark_overridden(&o.key);
        if let Some(key) = o.key.strip_prefix("impact.") {
            given(doc.table_mut(), key);
        }
    }
    Ok(())
}

/// Drops `key` from `[impact]`'s `assumed` list: a value set by `--set` is given, not assumed.
fn given(root: &mut Table, key: &str) {
    let Some(Value::Table(impact)) = root.get_mut("impact") else {
        return;
    };
    if let Some(Value::Array(assumed)) = impact.get_mut("assumed") {
        assumed.retain(|k| k.as_str() != Some(key));
        if assumed.is_empty() {
            impact.remove("assumed");
        }
    }
}

fn bad_value(key: &str, problem: ValueProblem) -> OverrideError {
    OverrideError::BadValue {
        key: key.to_string(),
        problem,
    }
}

fn apply_one(
    doc: &mut Document,
    o: &Override,
    materials: &BTreeMap<String, Material>,
    base_motion: bool,
) -> Result<(), OverrideError> {
    let path: Vec<&str> = o.key.split('.').collect();
    let kind = scene_file::key_kind(&path)
        .ok_or_else(|| OverrideError::UnknownKey { key: o.key.clone() })?;
    let value = parse_value(&o.key, &o.value, kind, base_motion)?;
    let (parents, leaf) = path.split_at(path.len() - 1);
    let mut table = doc.table_mut();
    for (depth, part) in parents.iter().enumerate() {
        let is_material = depth == 1 && *part == "material";
        table = descend(table, part, is_material, &o.key, materials)?;
    }
    if kind == KeyKind::Shape {
        drop_geometry_unused_by(table, &o.value);
    }
    table.insert(leaf[0].to_string(), value);
    Ok(())
}

/// The unit the value of numeric `key` may be given in (SI when bare).
fn key_unit(key: &str, base_motion: bool) -> Unit {
    match key.parse::<Param>() {
        Ok(Param::System(k)) => units::system_key_unit(k, base_motion),
        Ok(Param::Scene(k)) => units::key_unit(k),
        // Every numeric key of the schema is one of those; a bare number is SI anyway.
        Err(_) => units::DIMENSIONLESS,
    }
}

/// The value of `raw` for a key of `kind`: numbers must parse (with the key's unit, if any),
/// shapes must be known.
fn parse_value(
    key: &str,
    raw: &str,
    kind: KeyKind,
    base_motion: bool,
) -> Result<Value, OverrideError> {
    let unquoted = raw
        .strip_prefix('"')
        .and_then(|r| r.strip_suffix('"'))
        .unwrap_or(raw);
    match kind {
        // A bare number reads as TOML would (inf and nan included, refused by the range checks).
        KeyKind::Number => match unquoted.parse::<f64>() {
            Ok(number) => Ok(Value::Float(number)),
            Err(_)
                if !unquoted
                    .trim_start()
                    .starts_with(|c: char| c.is_ascii_digit() || matches!(c, '+' | '-' | '.')) =>
            {
                Err(bad_value(key, ValueProblem::NotANumber(raw.to_string())))
            }
            Err(_) => units::parse(unquoted, key_unit(key, base_motion))
                .map(Value::Float)
                .map_err(|reason| {
                    let given = raw.to_string();
                    let reason = match key {
                        "system.forcing_amplitude" if base_motion => {
                            format!("{reason}; a force F₀ needs system.forcing = \"force\"")
                        }
                        "system.forcing_amplitude" => format!(
                            "{reason}; a base motion B in m needs system.forcing = \"base\""
                        ),
                        _ => reason,
                    };
                    bad_value(key, ValueProblem::BadQuantity { given, reason })
                }),
        },
        KeyKind::Text => Ok(Value::String(unquoted.to_string())),
        KeyKind::Shape => {
            if !scene_file::SHAPES.contains(&unquoted) {
                Err(bad_value(key, ValueProblem::UnknownShape(raw.to_string())))
            } else {
                Ok(Value::String(unquoted.to_string()))
            }
        }
        // A preset name, or an inline table written as TOML: `{ name = "x", youngs_modulus = … }`.
        KeyKind::Material if unquoted.trim_start().starts_with('{') => {
            let wrapped = format!("material = {unquoted}");
            let mut table: Table = wrapped.parse().map_err(|e: toml::de::Error| {
                let reason = e.message().trim().to_string();
                bad_value(key, ValueProblem::NotAnInlineTable(Some(reason)))
            })?;
            table
                .remove("material")
                .ok_or_else(|| bad_value(key, ValueProblem::NotAnInlineTable(None)))
        }
        KeyKind::Material => Ok(Value::String(unquoted.to_string())),
    }
}

/// The sub-table `part` of `table`, created if missing. A material given by name is first
/// replaced by its inline table, so that setting one field keeps the others of the named material.
fn descend<'t>(
    table: &'t mut Table,
    part: &str,
    is_material: bool,
    key: &str,
    materials: &BTreeMap<String, Material>,
) -> Result<&'t mut Table, OverrideError> {
    let slot = table
        .entry(part.to_string())
        .or_insert_with(|| Value::Table(Table::new()));
    if let (true, Value::String(name)) = (is_material, &*slot) {
        let material = materials.get(name).ok_or_else(|| {
            let problem = ValueProblem::UnknownMaterial {
                name: name.clone(),
                known: materials.keys().cloned().collect(),
            };
            bad_value(key, problem)
        })?;
        *slot = Value::Table(material_table(material));
    }
    match slot {
        Value::Table(t) => Ok(t),
        other => Err(bad_value(
            key,
            ValueProblem::NotATable {
                part: part.to_string(),
                found: other.type_str(),
            },
        )),
    }
}

/// A material as an inline table of the scene schema.
pub(crate) fn material_table(m: &Material) -> Table {
    let mut t = Table::new();
    t.insert("name".into(), Value::String(m.name.clone()));
    t.insert("youngs_modulus".into(), Value::Float(m.youngs_modulus));
    t.insert("poisson_ratio".into(), Value::Float(m.poisson_ratio));
    t.insert("yield_stress".into(), Value::Float(m.yield_stress));
    t.insert("density".into(), Value::Float(m.density));
    t
}

/// After a shape change, removes the radius/length the new shape does not use, so that
/// `body1.shape=plane` works on a sphere; a key the new shape needs is then reported missing.
fn drop_geometry_unused_by(body: &mut Table, shape: &str) {
    let shape = shape.trim_matches('"');
    for geometric in ["radius", "length"] {
        if !scene_file::shape_keys(shape).contains(&geometric) {
            body.remove(geometric);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::material::tests::{aluminium, steel};
    use crate::model::scene_file::decode_scene;

    const SCENE: &str = r#"name = "test"
[body1]
shape = "sphere"
radius = 0.01
material = "steel"
[body2]
shape = "plane"
material = "steel"
[impact]
v0 = 0.3
restitution = 0.6
plastic_indentation = 2.3e-6
"#;

    fn catalog() -> BTreeMap<String, Material> {
        [steel(), aluminium()]
            .into_iter()
            .map(|m| (m.name.clone(), m))
            .collect()
    }

    fn scene_with(sets: &[&str]) -> Result<crate::model::Scene, String> {
        let mut doc = Document::parse("test.toml", SCENE).map_err(|e| e.to_string())?;
        let overrides: Vec<Override> = sets
            .iter()
            .map(|s| s.parse())
            .collect::<Result<_, _>>()
            .map_err(|e: OverrideError| e.to_string())?;
        apply(&mut doc, &overrides, &catalog()).map_err(|e| e.to_string())?;
        decode_scene(&doc, &catalog()).map_err(|e| e.to_string())
    }

    #[test]
    fn numbers_replace_values() {
        let s = scene_with(&["impact.v0=0.5", "body1.radius=0.02"]).unwrap();
        assert_eq!(s.impact.v0, 0.5);
        assert_eq!(s.body1.shape.radius(), 0.02);
    }

    #[test]
    fn one_field_of_a_named_material_inlines_it_first() {
        let s = scene_with(&["body1.material.youngs_modulus=7e10"]).unwrap();
        assert_eq!(s.body1.material.youngs_modulus, 7e10);
        // The other fields are steel's.
        assert_eq!(s.body1.material.poisson_ratio, 0.3);
        assert_eq!(s.body1.material.density, 7800.0);
        assert_eq!(s.body2.material, steel());
    }

    #[test]
    fn a_named_material_replaces_the_whole_material() {
        let s = scene_with(&["body2.material=aluminium-alloy"]).unwrap();
        assert_eq!(s.body2.material, aluminium());
        let s = scene_with(&[
            r#"body2.material={ name = "x", youngs_modulus = 1e9, poisson_ratio = 0.2, yield_stress = 1e6, density = 1000 }"#,
        ])
        .unwrap();
        assert_eq!(s.body2.material.youngs_modulus, 1e9);
    }

    #[test]
    fn shape_change_drops_unused_geometry_and_asks_for_missing() {
        let s = scene_with(&[
            "body1.shape=plane",
            "body2.shape=sphere",
            "body2.radius=0.01",
        ])
        .unwrap();
        assert_eq!(s.body1.shape.name(), "plane");
        let err = scene_with(&["body1.shape=cylinder"]).unwrap_err();
        assert!(
            err.contains("missing key `body1.length` (a cylinder needs it)"),
            "{err}"
        );
    }

    #[test]
    fn numbers_take_their_keys_unit() {
        let s = scene_with(&[
            "impact.v0=300 mm/s",
            "body1.radius=12mm",
            "body1.mass=33 g",
            "body1.material.youngs_modulus=70 GPa",
            "body2.material.density=2.7 g/cm³",
            "impact.restitution=55%",
        ])
        .unwrap();
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-15 * b.abs();
        assert!(close(s.impact.v0, 0.3), "{}", s.impact.v0);
        assert!(close(s.body1.shape.radius(), 0.012));
        assert!(close(s.body1.mass.unwrap(), 0.033));
        assert_eq!(s.body1.material.youngs_modulus, 7e10);
        assert!(close(s.body2.material.density, 2700.0));
        assert!(close(s.impact.restitution, 0.55));
        let err = scene_with(&["body1.radius=1 kg"]).unwrap_err();
        assert!(
            err.starts_with("--set body1.radius: \"1 kg\": unknown unit 'kg' (expected m"),
            "{err}"
        );
    }

    #[test]
    fn errors_name_the_key() {
        let err = scene_with(&["impact.vo=1"]).unwrap_err();
        assert!(
            err.starts_with("--set impact.vo: unknown scene key"),
            "{err}"
        );
        let err = scene_with(&["impact.v0=fast"]).unwrap_err();
        assert!(
            err.starts_with("--set impact.v0: \"fast\" is not a number"),
            "{err}"
        );
        let err = scene_with(&["impact.v0"]).unwrap_err();
        assert!(err.contains("expected KEY=VALUE"), "{err}");
        let err = scene_with(&["body1.shape=cone"]).unwrap_err();
        assert!(err.starts_with("--set body1.shape: unknown shape"), "{err}");
        // Range checks happen when the scene is typed, and point at the override.
        let err = scene_with(&["body1.material.poisson_ratio=0.7"]).unwrap_err();
        assert_eq!(
            err,
            "test.toml (--set body1.material.poisson_ratio): body1.material.poisson_ratio must be in [0, 0.5), got 0.7"
        );
    }

    #[test]
    fn value_problems_carry_the_key_and_what_was_given() {
        let apply_one = |set: &str| {
            let mut doc = Document::parse("test.toml", SCENE).unwrap();
            apply(&mut doc, &[set.parse().unwrap()], &catalog()).unwrap_err()
        };
        assert_eq!(
            apply_one("impact.v0=fast"),
            OverrideError::BadValue {
                key: "impact.v0".into(),
                problem: ValueProblem::NotANumber("fast".into()),
            }
        );
        // A field of a material named by no preset: the name and the known ones, as data.
        let mut doc = Document::parse("test.toml", SCENE).unwrap();
        let sets: Vec<Override> = ["body1.material=nope", "body1.material.density=3"]
            .iter()
            .map(|s| s.parse().unwrap())
            .collect();
        assert_eq!(
            apply(&mut doc, &sets, &catalog()).unwrap_err(),
            OverrideError::BadValue {
                key: "body1.material.density".into(),
                problem: ValueProblem::UnknownMaterial {
                    name: "nope".into(),
                    known: vec!["aluminium-alloy".into(), "steel".into()],
                },
            }
        );
        assert!(matches!(
            apply_one("body1.material={ name = "),
            OverrideError::BadValue {
                problem: ValueProblem::NotAnInlineTable(Some(_)),
                ..
            }
        ));
    }

    #[test]
    fn unknown_material_name_is_refused_by_the_scene() {
        let err = scene_with(&["body1.material=unobtainium"]).unwrap_err();
        assert!(err.starts_with("test.toml (--set body1.material): `body1.material`: unknown material \"unobtainium\""), "{err}");
    }
}
