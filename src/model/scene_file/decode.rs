//! Strict typed reading of a [`Document`] into a [`Scene`] or a [`Material`].

use std::collections::BTreeMap;

use toml::{Table, Value};

use crate::model::body::{Body, Shape};
use crate::model::material::Material;
use crate::model::scene::{Assumed, ImpactConditions, Scene};

use super::document::{Document, Problem, SceneFileError, ValueIssue, join};
use super::schema::{
    BODY_KEYS, IMPACT_TABLE_KEYS, MATERIAL_FILE_KEYS, MATERIAL_KEYS, SCENE_KEYS, shape_keys,
};
use super::view::SceneView;

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
pub(super) struct Decoder<'a> {
    pub(super) doc: &'a Document,
    pub(super) materials: &'a BTreeMap<String, Material>,
}

impl Decoder<'_> {
    /// Refuses keys of `table` (at `path`) that are not in `allowed`.
    pub(super) fn check_keys(
        &self,
        path: &str,
        table: &Table,
        allowed: &'static [&'static str],
    ) -> Result<(), SceneFileError> {
        match table.keys().find(|k| !allowed.contains(&k.as_str())) {
            Some(key) => {
                let key = join(path, key);
                Err(self.doc.error(
                    &key,
                    Problem::UnknownKey {
                        key: key.clone(),
                        allowed,
                    },
                ))
            }
            None => Ok(()),
        }
    }

    fn missing(&self, path: &str, why: &'static str) -> SceneFileError {
        self.doc.error(
            path,
            Problem::MissingKey {
                key: path.to_string(),
                why,
            },
        )
    }

    pub(super) fn wrong_type(
        &self,
        path: &str,
        expected: &'static str,
        value: &Value,
    ) -> SceneFileError {
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

    pub(super) fn optional_number(
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
        why: &'static str,
    ) -> Result<f64, SceneFileError> {
        self.optional_number(table, prefix, key)?
            .ok_or_else(|| self.missing(&join(prefix, key), why))
    }

    pub(super) fn optional_string<'t>(
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
        let assumed = self.assumed(root)?;
        // Refused here too, so that a bad view or system is located in the file whoever reads the
        // scene.
        self.view(root)?;
        self.system(root)?;
        Ok(Scene {
            name,
            body1,
            body2,
            impact,
            assumed,
            fit: None,
        })
    }

    /// The `assumed` list of `[impact]`: which of e and x_pl the scene's user did not give.
    fn assumed(&self, root: &Table) -> Result<Assumed, SceneFileError> {
        let path = "impact.assumed";
        let mut assumed = Assumed::default();
        let Some(value) = self.table(root, "", "impact")?.get("assumed") else {
            return Ok(assumed);
        };
        let Value::Array(keys) = value else {
            return Err(self.wrong_type(path, "a list of [impact] keys", value));
        };
        for key in keys {
            match key.as_str() {
                Some(key) if Assumed::KEYS.contains(&key) => assumed.set(key, true),
                _ => {
                    return Err(self.wrong_type(
                        path,
                        "a list of \"restitution\" and \"plastic_indentation\"",
                        key,
                    ));
                }
            }
        }
        Ok(assumed)
    }

    fn body(&self, root: &Table, key: &str) -> Result<Body, SceneFileError> {
        let table = self.table(root, "", key)?;
        self.check_keys(key, table, BODY_KEYS)?;
        let shape_path = join(key, "shape");
        let shape_name = self.string(table, key, "shape")?;
        let shape = match shape_name {
            "sphere" => Shape::Sphere {
                radius: self.geometry(table, key, "radius", " (a sphere needs it)")?,
            },
            "cylinder" => Shape::Cylinder {
                radius: self.geometry(table, key, "radius", " (a cylinder needs it)")?,
                length: self.geometry(table, key, "length", " (a cylinder needs it)")?,
            },
            "plane" => Shape::Plane,
            other => {
                return Err(self.doc.error(
                    &shape_path,
                    Problem::BadValue {
                        key: shape_path.clone(),
                        issue: ValueIssue::UnknownShape(other.to_string()),
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
    /// that asks for it (or at the `--set` that changed the shape); `why` names that shape.
    fn geometry(
        &self,
        body: &Table,
        body_key: &str,
        field: &str,
        why: &'static str,
    ) -> Result<f64, SceneFileError> {
        self.optional_number(body, body_key, field)?.ok_or_else(|| {
            self.doc.error(
                &join(body_key, "shape"),
                Problem::MissingKey {
                    key: join(body_key, field),
                    why,
                },
            )
        })
    }

    fn material(&self, body: &Table, body_key: &str) -> Result<Material, SceneFileError> {
        let path = join(body_key, "material");
        match body.get("material") {
            None => Err(self.missing(&path, " (a preset material name or an inline table)")),
            Some(Value::String(name)) => self.materials.get(name).cloned().ok_or_else(|| {
                self.doc.error(
                    &path,
                    Problem::BadValue {
                        key: path.clone(),
                        issue: ValueIssue::UnknownMaterial {
                            name: name.clone(),
                            known: self.materials.keys().cloned().collect(),
                        },
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
        self.check_keys("impact", table, IMPACT_TABLE_KEYS)?;
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
    let decoder = Decoder { doc, materials };
    let mut scene = decoder.scene()?;
    scene.validate().map_err(|e| doc.invalid(e))?;
    scene.fit = decoder.fit(doc.table())?;
    if let Some(fit) = &scene.fit {
        if doc.is_overridden("impact.restitution") {
            return Err(doc.error(
                "impact.restitution",
                Problem::BadValue {
                    key: "impact.restitution".into(),
                    issue: ValueIssue::Conflict(
                        "the scene's [fit] sets e at every v0; set fit.<constant> instead, or remove [fit]",
                    ),
                },
            ));
        }
        let law = fit.kind.id();
        scene.apply_fit().map_err(|e| {
            doc.error(
                "fit.law",
                Problem::FitRestitution {
                    law,
                    v0: scene.impact.v0,
                    message: e.to_string(),
                },
            )
        })?;
    }
    Ok(scene)
}

/// Decodes the view of a scene file: its `models` and `[solver]`, defaults where absent.
pub fn decode_view(doc: &Document) -> Result<SceneView, SceneFileError> {
    let decoder = Decoder {
        doc,
        materials: &BTreeMap::new(),
    };
    decoder.view(doc.table())
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
