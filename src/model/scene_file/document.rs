//! A parsed TOML source with the position of every key, and the located errors about it.

use std::collections::{BTreeSet, HashMap};
use std::fmt;

use thiserror::Error;
use toml::de::{DeTable, DeValue};
use toml::{Table, Value};

use crate::model::error::ModelError;
use crate::model::force::UnknownModel;
use crate::model::impact::UnknownMethod;

use super::schema::{MATERIAL_KEYS, SHAPES};

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

/// What is wrong with a value of the right type ([`Problem::BadValue`]), with what was given.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ValueIssue {
    /// A shape the schema does not have.
    #[error("unknown shape \"{0}\" (expected one of: {shapes})", shapes = SHAPES.join(", "))]
    UnknownShape(String),
    /// A material name that is no preset: the name and the known ones.
    #[error(
        "unknown material \"{name}\" (known: {}; or give an inline table with the keys {})",
        .known.join(", "),
        MATERIAL_KEYS.join(", ")
    )]
    UnknownMaterial { name: String, known: Vec<String> },
    /// A model id that names no law.
    #[error(transparent)]
    UnknownModel(#[from] UnknownModel),
    /// A model listed twice in `models`.
    #[error("\"{0}\" is listed twice")]
    ListedTwice(String),
    /// An empty `models` list.
    #[error("lists no model (leave the key out for the paper's five)")]
    NoModels,
    /// A solver method that is neither `auto` nor an integrator's.
    #[error(transparent)]
    UnknownMethod(#[from] UnknownMethod),
    /// A name that is not one of the known ones (`system.kind`, `system.forcing`).
    #[error("unknown value \"{name}\" (expected one of: {})", .known.join(", "))]
    UnknownName {
        name: String,
        known: &'static [&'static str],
    },
    /// A `[fit] law` that is neither `constant-e` nor a law with a damping parameter.
    #[error("unknown fitted law \"{name}\" (expected one of: {ids})", ids = crate::model::scene_fit::fitted_ids().join(", "))]
    UnknownFitLaw { name: String },
    /// Two keys that exclude each other.
    #[error("{0}")]
    Conflict(&'static str),
    /// A number outside its range.
    #[error("must be {requirement}, got {value}")]
    OutOfRange {
        requirement: &'static str,
        value: f64,
    },
}

/// What is wrong with a scene or material file. Keys are dotted paths (`body1.material.density`).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum Problem {
    #[error("TOML syntax error: {0}")]
    Syntax(String),
    #[error("unknown key `{key}` (allowed here: {})", .allowed.join(", "))]
    UnknownKey {
        key: String,
        allowed: &'static [&'static str],
    },
    #[error("missing key `{key}`{why}")]
    MissingKey { key: String, why: &'static str },
    #[error("`{key}` must be {expected}, found {found}")]
    WrongType {
        key: String,
        expected: &'static str,
        found: String,
    },
    #[error("`{key}` is not used by a {shape}; remove it")]
    UnusedKey { key: String, shape: &'static str },
    #[error("`{key}`: {issue}")]
    BadValue { key: String, issue: ValueIssue },
    /// A constant of `[fit]` that is another law's.
    #[error("`{key}` is not the constant of {law} (its constant is `fit.{constant}`); remove it")]
    NotTheConstant {
        key: String,
        law: &'static str,
        constant: &'static str,
    },
    /// The fitted law's e at v₀ could not be computed (an impact solve that failed).
    #[error("[fit] {law}: its restitution at v0 = {v0} m/s could not be computed: {message}")]
    FitRestitution {
        law: &'static str,
        v0: f64,
        message: String,
    },
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

    /// Whether `--set` wrote the value at `path`.
    pub(crate) fn is_overridden(&self, path: &str) -> bool {
        self.overridden.contains(path)
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

    pub(super) fn error(&self, path: &str, problem: Problem) -> SceneFileError {
        SceneFileError {
            location: self.location(path),
            problem,
        }
    }

    /// A model validation error located at the field it names.
    pub(super) fn invalid(&self, error: ModelError) -> SceneFileError {
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

/// `prefix.key`, or `key` at the top level.
pub(super) fn join(prefix: &str, key: &str) -> String {
    if prefix.is_empty() {
        key.to_string()
    } else {
        format!("{prefix}.{key}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_and_column_count_characters() {
        let text = "a = 1\nµ = \"x\"\n";
        assert_eq!(line_column(text, 0), (1, 1));
        let offset = text.find('=').unwrap();
        assert_eq!(line_column(text, offset), (1, 3));
        let offset = text.rfind('=').unwrap();
        assert_eq!(line_column(text, offset), (2, 3), "µ is one column");
    }

    #[test]
    fn location_falls_back_to_the_enclosing_table_then_the_override() {
        let mut doc = Document::parse("f.toml", "x = 1\n\n[t]\ny = 2\n").unwrap();
        let at = |line, column| Location::File {
            origin: "f.toml".into(),
            line,
            column,
        };
        assert_eq!(doc.location("t.y"), at(4, 1));
        assert_eq!(doc.location("t.missing"), at(3, 2));
        assert_eq!(doc.location("missing"), at(1, 1));
        doc.mark_overridden("t");
        assert_eq!(
            doc.location("t.y").to_string(),
            "f.toml (--set t)",
            "a value under an override points at it"
        );
    }
}
