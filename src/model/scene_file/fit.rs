//! The `[fit]` table: the law fitted to measured restitution and its material constant
//! ([`FittedLaw`], docs/fitting.md), decoded strictly and written back.

use toml::{Table, Value};

use crate::model::scene_fit::{FittedKind, FittedLaw};

use super::decode::Decoder;
use super::document::{Problem, SceneFileError, ValueIssue};
use super::write::toml_float;

/// Keys `[fit]` may hold besides the constant: the law, the data file and a note.
const WORDS: &[&str] = &["law", "source", "note"];
/// Every key of `[fit]`: the words and the constant of each law (e, a, c, γ, A, v_y, …).
pub(crate) const FIT_KEYS: &[&str] = &[
    "law", "source", "note", "e", "a", "p", "b", "gamma", "c", "c_max", "v_yield",
];

impl Decoder<'_> {
    /// The optional `[fit]` table, its constant checked (errors name `fit.<key>` and its line).
    pub(super) fn fit(&self, root: &Table) -> Result<Option<FittedLaw>, SceneFileError> {
        let table = match root.get("fit") {
            None => return Ok(None),
            Some(Value::Table(t)) => t,
            Some(other) => return Err(self.wrong_type("fit", "a table", other)),
        };
        self.check_keys("fit", table, FIT_KEYS)?;
        let id = self
            .optional_string(table, "fit", "law")?
            .ok_or_else(|| self.missing_key("fit.law", " (the fitted law's id, or constant-e)"))?;
        let kind = FittedKind::from_id(id).ok_or_else(|| {
            self.bad_value(
                "fit.law",
                ValueIssue::UnknownFitLaw {
                    name: id.to_string(),
                    known: FittedKind::ids(),
                },
            )
        })?;
        let (key, _, unit) = kind.constant();
        if let Some(other) = table
            .keys()
            .find(|k| !WORDS.contains(&k.as_str()) && k.as_str() != key)
        {
            let path = format!("fit.{other}");
            return Err(self.doc.error(
                &path,
                Problem::NotTheConstant {
                    key: path.clone(),
                    law: kind.id(),
                    constant: key,
                },
            ));
        }
        let value = self
            .optional_number(table, "fit", key)?
            .ok_or_else(|| self.missing_key(&format!("fit.{key}"), why(unit)))?;
        let fit = FittedLaw {
            kind,
            value,
            source: self
                .optional_string(table, "fit", "source")?
                .map(str::to_string),
            note: self
                .optional_string(table, "fit", "note")?
                .map(str::to_string),
        };
        fit.validate().map_err(|e| self.doc.invalid(e))?;
        Ok(Some(fit))
    }
}

/// The words after a missing constant: its unit.
fn why(unit: &str) -> &'static str {
    match unit {
        "1" => " (the fitted constant, a pure number)",
        "s/m" => " (the fitted constant a = χ/v₀, s/m)",
        _ => " (the fitted constant, in the SI unit of the law's damping parameter)",
    }
}

/// The `[fit]` table of `fit` as TOML, with the unit of its constant.
pub fn fit_table(fit: &FittedLaw) -> String {
    let quote = |s: &str| Value::String(s.to_string()).to_string();
    let (key, symbol, unit) = fit.kind.constant();
    let unit = if unit == "1" {
        String::new()
    } else {
        format!(", {unit}")
    };
    let mut out = String::from(
        "[fit]  # the law fitted to measured e(v0): solves use its constant; [impact] restitution is its e at v0\n",
    );
    out.push_str(&format!("law = {}\n", quote(fit.kind.id())));
    out.push_str(&format!(
        "{key} = {}  # {symbol}{unit}\n",
        toml_float(fit.value)
    ));
    if let Some(source) = &fit.source {
        out.push_str(&format!("source = {}\n", quote(source)));
    }
    if let Some(note) = &fit.note {
        out.push_str(&format!("note = {}\n", quote(note)));
    }
    out
}
