//! Scene files (TOML): parsing with errors that name file, line and key; writing back.
//!
//! A file is parsed into a [`Document`] (the TOML table plus the line of every key), which
//! `--set` overrides may edit before it is decoded into a [`Scene`]. Decoding is strict: unknown
//! keys, missing keys, wrong types and keys the body's shape does not use are all errors.

use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::fmt;

use thiserror::Error;
use toml::de::{DeTable, DeValue};
use toml::{Table, Value};

use super::body::{Body, Shape};
use super::error::ModelError;
use super::material::Material;
use super::scene::{ImpactConditions, Scene};

/// Keys of the top level of a scene file; `description` is optional.
const SCENE_KEYS: &[&str] = &["name", "description", "body1", "body2", "impact"];
/// Keys of `[body1]` and `[body2]`; which of radius/length are required depends on the shape.
const BODY_KEYS: &[&str] = &["shape", "radius", "length", "mass", "material"];
/// Keys of an inline material table (all required).
const MATERIAL_KEYS: &[&str] = &[
    "name",
    "youngs_modulus",
    "poisson_ratio",
    "yield_stress",
    "density",
];
/// Keys of a material preset file: the inline keys plus an optional description (name optional too).
const MATERIAL_FILE_KEYS: &[&str] = &[
    "name",
    "description",
    "youngs_modulus",
    "poisson_ratio",
    "yield_stress",
    "density",
];
/// Keys of `[impact]` (all required).
const IMPACT_KEYS: &[&str] = &["v0", "restitution", "plastic_indentation"];
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

/// Where in its source a problem is.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Location {
    /// A place in a file (or embedded preset); `line`/`column` are 1-based.
    File {
        origin: String,
        line: usize,
        column: usize,
    },
    /// A value that a `--set KEY=VALUE` override put there.
    Override { origin: String, key: String },
    /// The source as a whole (e.g. two bodies that cannot touch).
    Whole { origin: String },
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Location::File {
                origin,
                line,
                column,
            } => write!(f, "{origin}:{line}:{column}"),
            Location::Override { origin, key } => write!(f, "{origin} (--set {key})"),
            Location::Whole { origin } => f.write_str(origin),
        }
    }
}

/// What is wrong with a scene or material file. Keys are dotted paths (`body1.material.density`).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum Problem {
    #[error("TOML syntax error: {0}")]
    Syntax(String),
    #[error("unknown key `{key}` (allowed here: {allowed})")]
    UnknownKey { key: String, allowed: String },
    #[error("missing key `{key}`{why}")]
    MissingKey { key: String, why: String },
    #[error("`{key}` must be {expected}, found {found}")]
    WrongType {
        key: String,
        expected: &'static str,
        found: String,
    },
    #[error("`{key}` is not used by a {shape}; remove it")]
    UnusedKey { key: String, shape: &'static str },
    #[error("`{key}`: {message}")]
    BadValue { key: String, message: String },
    /// A value outside its physical range; the model error names the dotted field.
    #[error(transparent)]
    Invalid(ModelError),
}

/// A problem at a location: `file:line:column: problem`.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("{location}: {problem}")]
pub struct SceneFileError {
    pub location: Location,
    pub problem: Problem,
}

/// A parsed TOML source: the table, the position of every key, and which keys `--set` changed.
#[derive(Debug, Clone, PartialEq)]
pub struct Document {
    origin: String,
    table: Table,
    /// Dotted path → (line, column) of its key (of the header for `[tables]`).
    positions: HashMap<String, (usize, usize)>,
    overridden: BTreeSet<String>,
}

impl Document {
    /// Parses `text`; `origin` names the source in messages (a path, or a built-in preset's file).
    pub fn parse(origin: impl Into<String>, text: &str) -> Result<Document, SceneFileError> {
        let origin = origin.into();
        let syntax_error = |e: toml::de::Error| {
            let (line, column) = e.span().map_or((1, 1), |s| line_column(text, s.start));
            SceneFileError {
                location: Location::File {
                    origin: origin.clone(),
                    line,
                    column,
                },
                problem: Problem::Syntax(e.message().trim().to_string()),
            }
        };
        let table: Table = text.parse().map_err(syntax_error)?;
        let spanned = DeTable::parse(text).map_err(syntax_error)?;
        let mut positions = HashMap::new();
        record_positions(spanned.get_ref(), "", text, &mut positions);
        Ok(Document {
            origin,
            table,
            positions,
            overridden: BTreeSet::new(),
        })
    }

    /// The name of the source used in messages.
    pub fn origin(&self) -> &str {
        &self.origin
    }

    /// The TOML table as parsed (and overridden).
    pub fn table(&self) -> &Table {
        &self.table
    }

    pub(crate) fn table_mut(&mut self) -> &mut Table {
        &mut self.table
    }

    /// Records that `--set` wrote the value at `path`, so messages about it point at the override.
    pub(crate) fn mark_overridden(&mut self, path: &str) {
        self.overridden.insert(path.to_string());
    }

    /// The optional `description` string, if present and a string.
    pub fn description(&self) -> Option<&str> {
        self.table.get("description").and_then(Value::as_str)
    }

    /// Where the key at `path` is: its override, its line, or the nearest enclosing table's line.
    pub fn location(&self, path: &str) -> Location {
        let mut prefix = Some(path);
        while let Some(p) = prefix {
            if self.overridden.contains(p) {
                return Location::Override {
                    origin: self.origin.clone(),
                    key: p.to_string(),
                };
            }
            prefix = p.rsplit_once('.').map(|(parent, _)| parent);
        }
        let mut prefix = Some(path);
        while let Some(p) = prefix {
            if let Some(&(line, column)) = self.positions.get(p) {
                return Location::File {
                    origin: self.origin.clone(),
                    line,
                    column,
                };
            }
            prefix = p.rsplit_once('.').map(|(parent, _)| parent);
        }
        // Top-level keys live at the top of the file.
        Location::File {
            origin: self.origin.clone(),
            line: 1,
            column: 1,
        }
    }

    fn error(&self, path: &str, problem: Problem) -> SceneFileError {
        SceneFileError {
            location: self.location(path),
            problem,
        }
    }

    /// A model validation error located at the field it names.
    fn invalid(&self, error: ModelError) -> SceneFileError {
        let location = match &error {
            ModelError::InvalidParameter { field, .. } => self.location(field),
            _ => Location::Whole {
                origin: self.origin.clone(),
            },
        };
        SceneFileError {
            location,
            problem: Problem::Invalid(error),
        }
    }
}

/// 1-based line and column (in characters) of byte `offset` in `text`.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    (line, before[line_start..].chars().count() + 1)
}

/// Walks the spanned table and records the position of every key by its dotted path.
fn record_positions(
    table: &DeTable<'_>,
    prefix: &str,
    text: &str,
    out: &mut HashMap<String, (usize, usize)>,
) {
    for (key, value) in table.iter() {
        let path = join(prefix, key.get_ref());
        out.insert(path.clone(), line_column(text, key.span().start));
        if let DeValue::Table(inner) = value.get_ref() {
            record_positions(inner, &path, text, out);
        }
    }
}

fn join(prefix: &str, key: &str) -> String {
    if prefix.is_empty() {
        key.to_string()
    } else {
        format!("{prefix}.{key}")
    }
}

/// Describes a TOML value for "found …" messages: its type, and short scalars verbatim.
fn describe(value: &Value) -> String {
    match value {
        Value::String(s) if s.chars().count() <= 40 => format!("string {value}"),
        Value::Integer(_) | Value::Float(_) | Value::Boolean(_) => {
            format!("{} {value}", value.type_str())
        }
        other => other.type_str().to_string(),
    }
}

/// Strict typed reading of a [`Document`].
struct Decoder<'a> {
    doc: &'a Document,
    materials: &'a BTreeMap<String, Material>,
}

impl Decoder<'_> {
    /// Refuses keys of `table` (at `path`) that are not in `allowed`.
    fn check_keys(
        &self,
        path: &str,
        table: &Table,
        allowed: &[&str],
    ) -> Result<(), SceneFileError> {
        match table.keys().find(|k| !allowed.contains(&k.as_str())) {
            Some(key) => {
                let key = join(path, key);
                Err(self.doc.error(
                    &key,
                    Problem::UnknownKey {
                        key: key.clone(),
                        allowed: allowed.join(", "),
                    },
                ))
            }
            None => Ok(()),
        }
    }

    fn missing(&self, path: &str, why: &str) -> SceneFileError {
        self.doc.error(
            path,
            Problem::MissingKey {
                key: path.to_string(),
                why: why.to_string(),
            },
        )
    }

    fn wrong_type(&self, path: &str, expected: &'static str, value: &Value) -> SceneFileError {
        self.doc.error(
            path,
            Problem::WrongType {
                key: path.to_string(),
                expected,
                found: describe(value),
            },
        )
    }

    fn table<'t>(
        &self,
        parent: &'t Table,
        prefix: &str,
        key: &str,
    ) -> Result<&'t Table, SceneFileError> {
        let path = join(prefix, key);
        match parent.get(key) {
            Some(Value::Table(t)) => Ok(t),
            Some(other) => Err(self.wrong_type(&path, "a table", other)),
            None => Err(self.missing(&path, "")),
        }
    }

    fn optional_number(
        &self,
        table: &Table,
        prefix: &str,
        key: &str,
    ) -> Result<Option<f64>, SceneFileError> {
        match table.get(key) {
            None => Ok(None),
            // Integers are accepted where a number is expected: `v0 = 1` means 1.0 m/s.
            Some(Value::Integer(i)) => Ok(Some(*i as f64)),
            Some(Value::Float(x)) => Ok(Some(*x)),
            Some(other) => Err(self.wrong_type(&join(prefix, key), "a number", other)),
        }
    }

    fn number(
        &self,
        table: &Table,
        prefix: &str,
        key: &str,
        why: &str,
    ) -> Result<f64, SceneFileError> {
        self.optional_number(table, prefix, key)?
            .ok_or_else(|| self.missing(&join(prefix, key), why))
    }

    fn optional_string<'t>(
        &self,
        table: &'t Table,
        prefix: &str,
        key: &str,
    ) -> Result<Option<&'t str>, SceneFileError> {
        match table.get(key) {
            None => Ok(None),
            Some(Value::String(s)) => Ok(Some(s)),
            Some(other) => Err(self.wrong_type(&join(prefix, key), "a string", other)),
        }
    }

    fn string<'t>(
        &self,
        table: &'t Table,
        prefix: &str,
        key: &str,
    ) -> Result<&'t str, SceneFileError> {
        self.optional_string(table, prefix, key)?
            .ok_or_else(|| self.missing(&join(prefix, key), ""))
    }

    fn scene(&self) -> Result<Scene, SceneFileError> {
        let root = self.doc.table();
        self.check_keys("", root, SCENE_KEYS)?;
        let name = self.string(root, "", "name")?.to_string();
        self.optional_string(root, "", "description")?;
        let body1 = self.body(root, "body1")?;
        let body2 = self.body(root, "body2")?;
        let impact = self.impact(root)?;
        Ok(Scene {
            name,
            body1,
            body2,
            impact,
        })
    }

    fn body(&self, root: &Table, key: &str) -> Result<Body, SceneFileError> {
        let table = self.table(root, "", key)?;
        self.check_keys(key, table, BODY_KEYS)?;
        let shape_path = join(key, "shape");
        let shape_name = self.string(table, key, "shape")?;
        let shape = match shape_name {
            "sphere" => Shape::Sphere {
                radius: self.geometry(table, key, "radius", shape_name)?,
            },
            "cylinder" => Shape::Cylinder {
                radius: self.geometry(table, key, "radius", shape_name)?,
                length: self.geometry(table, key, "length", shape_name)?,
            },
            "plane" => Shape::Plane,
            other => {
                return Err(self.doc.error(
                    &shape_path,
                    Problem::BadValue {
                        key: shape_path.clone(),
                        message: format!(
                            "unknown shape \"{other}\" (expected one of: {})",
                            SHAPES.join(", ")
                        ),
                    },
                ));
            }
        };
        for geometric in ["radius", "length"] {
            if table.contains_key(geometric) && !shape_keys(shape.name()).contains(&geometric) {
                let path = join(key, geometric);
                return Err(self.doc.error(
                    &path,
                    Problem::UnusedKey {
                        key: path.clone(),
                        shape: shape.name(),
                    },
                ));
            }
        }
        let mass = self.optional_number(table, key, "mass")?;
        let material = self.material(table, key)?;
        Ok(Body {
            shape,
            material,
            mass,
        })
    }

    /// A radius or length the body's shape needs; if missing, the error points at the `shape`
    /// that asks for it (or at the `--set` that changed the shape).
    fn geometry(
        &self,
        body: &Table,
        body_key: &str,
        field: &str,
        shape: &str,
    ) -> Result<f64, SceneFileError> {
        self.optional_number(body, body_key, field)?.ok_or_else(|| {
            self.doc.error(
                &join(body_key, "shape"),
                Problem::MissingKey {
                    key: join(body_key, field),
                    why: format!(" (a {shape} needs it)"),
                },
            )
        })
    }

    fn material(&self, body: &Table, body_key: &str) -> Result<Material, SceneFileError> {
        let path = join(body_key, "material");
        match body.get("material") {
            None => Err(self.missing(&path, " (a preset material name or an inline table)")),
            Some(Value::String(name)) => self.materials.get(name).cloned().ok_or_else(|| {
                let known: Vec<&str> = self.materials.keys().map(String::as_str).collect();
                self.doc.error(
                    &path,
                    Problem::BadValue {
                        key: path.clone(),
                        message: format!(
                            "unknown material \"{name}\" (known: {}; or give an inline table with the keys {})",
                            known.join(", "),
                            MATERIAL_KEYS.join(", ")
                        ),
                    },
                )
            }),
            Some(Value::Table(table)) => {
                self.check_keys(&path, table, MATERIAL_KEYS)?;
                let name = self.string(table, &path, "name")?.to_string();
                self.material_values(table, &path, name)
            }
            Some(other) => Err(self.wrong_type(&path, "a material name or a table", other)),
        }
    }

    /// The four numbers of a material table at `path`.
    fn material_values(
        &self,
        table: &Table,
        path: &str,
        name: String,
    ) -> Result<Material, SceneFileError> {
        Ok(Material {
            name,
            youngs_modulus: self.number(table, path, "youngs_modulus", "")?,
            poisson_ratio: self.number(table, path, "poisson_ratio", "")?,
            yield_stress: self.number(table, path, "yield_stress", "")?,
            density: self.number(table, path, "density", "")?,
        })
    }

    fn impact(&self, root: &Table) -> Result<ImpactConditions, SceneFileError> {
        let table = self.table(root, "", "impact")?;
        self.check_keys("impact", table, IMPACT_KEYS)?;
        Ok(ImpactConditions {
            v0: self.number(table, "impact", "v0", " (pre-impact velocity, m/s)")?,
            restitution: self.number(
                table,
                "impact",
                "restitution",
                " (coefficient of restitution e)",
            )?,
            plastic_indentation: self.number(
                table,
                "impact",
                "plastic_indentation",
                " (x_pl in m; 0 for no permanent deformation)",
            )?,
        })
    }
}

/// Decodes and validates a scene; `materials` resolves `material = "name"` references.
pub fn decode_scene(
    doc: &Document,
    materials: &BTreeMap<String, Material>,
) -> Result<Scene, SceneFileError> {
    let scene = Decoder { doc, materials }.scene()?;
    scene.validate().map_err(|e| doc.invalid(e))?;
    Ok(scene)
}

/// Decodes and validates a material preset file; `name` defaults to `default_name` (the file stem).
pub fn decode_material(doc: &Document, default_name: &str) -> Result<Material, SceneFileError> {
    let decoder = Decoder {
        doc,
        materials: &BTreeMap::new(),
    };
    let table = doc.table();
    decoder.check_keys("", table, MATERIAL_FILE_KEYS)?;
    decoder.optional_string(table, "", "description")?;
    let name = decoder
        .optional_string(table, "", "name")?
        .unwrap_or(default_name)
        .to_string();
    let material = decoder.material_values(table, "", name)?;
    material.validate().map_err(|e| doc.invalid(e))?;
    Ok(material)
}

/// Parses and decodes a scene in one go.
pub fn parse_scene(
    origin: &str,
    text: &str,
    materials: &BTreeMap<String, Material>,
) -> Result<Scene, SceneFileError> {
    decode_scene(&Document::parse(origin, text)?, materials)
}

/// A float as TOML text that reads back to exactly the same f64, in plain or exponent notation
/// (Rust prints the shortest round-tripping digits in both).
pub fn toml_float(x: f64) -> String {
    if x.is_nan() {
        return "nan".into();
    }
    if x.is_infinite() {
        return if x > 0.0 { "inf".into() } else { "-inf".into() };
    }
    let mut plain = format!("{x}");
    if !plain.contains(['.', 'e']) {
        plain.push_str(".0");
    }
    let exponent = format!("{x:e}");
    // Plain notation unless it is clearly longer (7800.0 rather than 7.8e3, 2e11 rather than 200000000000.0).
    if exponent.len() + 2 < plain.len() {
        exponent
    } else {
        plain
    }
}

/// Writes a scene in the scene-file schema with materials inline; [`parse_scene`] reads it back
/// to an equal [`Scene`].
pub fn to_toml(scene: &Scene, description: Option<&str>) -> String {
    let mut out = String::new();
    let quote = |s: &str| Value::String(s.to_string()).to_string();
    out.push_str(&format!("name = {}\n", quote(&scene.name)));
    if let Some(description) = description {
        out.push_str(&format!("description = {}\n", quote(description)));
    }
    for (key, body) in [("body1", &scene.body1), ("body2", &scene.body2)] {
        out.push_str(&format!("\n[{key}]\nshape = \"{}\"\n", body.shape.name()));
        match body.shape {
            Shape::Sphere { radius } => {
                out.push_str(&format!("radius = {}  # m\n", toml_float(radius)))
            }
            Shape::Cylinder { radius, length } => {
                out.push_str(&format!("radius = {}  # m\n", toml_float(radius)));
                out.push_str(&format!("length = {}  # m\n", toml_float(length)));
            }
            Shape::Plane => {}
        }
        if let Some(mass) = body.mass {
            out.push_str(&format!("mass = {}  # kg\n", toml_float(mass)));
        }
        let m = &body.material;
        out.push_str(&format!("\n[{key}.material]\nname = {}\n", quote(&m.name)));
        out.push_str(&format!(
            "youngs_modulus = {}  # Pa\n",
            toml_float(m.youngs_modulus)
        ));
        out.push_str(&format!(
            "poisson_ratio = {}\n",
            toml_float(m.poisson_ratio)
        ));
        out.push_str(&format!(
            "yield_stress = {}  # Pa\n",
            toml_float(m.yield_stress)
        ));
        out.push_str(&format!("density = {}  # kg/m³\n", toml_float(m.density)));
    }
    let i = &scene.impact;
    out.push_str("\n[impact]\n");
    out.push_str(&format!(
        "v0 = {}  # m/s, pre-impact relative velocity\n",
        toml_float(i.v0)
    ));
    out.push_str(&format!(
        "restitution = {}  # e, used by the dissipative models\n",
        toml_float(i.restitution)
    ));
    out.push_str(&format!(
        "plastic_indentation = {}  # x_pl in m, used by the proposed viscous model\n",
        toml_float(i.plastic_indentation)
    ));
    out
}
