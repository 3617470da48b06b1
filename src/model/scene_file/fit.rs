//! The `[fit]` table: the law fitted to measured restitution and its material constant
//! ([`FittedLaw`], docs/fitting.md), decoded strictly and written back.

use toml::{Table, Value};

use crate::model::scene_fit::{FittedLaw, fitted_kind};

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
        let kind = fitted_kind(id).ok_or_else(|| {
            self.bad_value(
                "fit.law",
                ValueIssue::UnknownFitLaw {
                    name: id.to_string(),
                },
            )
        })?;
        let (key, _, unit) = FittedLaw::new(kind, 0.0).constant();
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
    let (key, symbol, unit) = fit.constant();
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

#[cfg(test)]
mod tests {
    use std::collections::BTreeMap;

    use super::*;
    use crate::model::ForceModel;
    use crate::model::calibrate::hunt_crossley_restitution;
    use crate::model::scene::tests::fig5_scene;
    use crate::model::scene_file::{parse_scene, to_toml};

    /// Fig. 5's scene file with `fit` appended.
    fn with_fit(fit: &str) -> String {
        format!("{}\n{fit}", to_toml(&fig5_scene(), None))
    }

    fn parse(text: &str) -> Result<crate::model::Scene, SceneFileError> {
        parse_scene("s.toml", text, &BTreeMap::new())
    }

    #[test]
    fn a_fitted_scene_round_trips_and_its_e_is_the_laws_at_v0() {
        let text = with_fit("[fit]\nlaw = \"hunt-crossley\"\na = 2.5\nsource = \"d.csv\"\n");
        let scene = parse(&text).unwrap();
        let fit = scene.fit.clone().unwrap();
        assert_eq!(
            fit.kind,
            crate::model::fit::Candidate::Law(ForceModel::HuntCrossley)
        );
        assert_eq!((fit.value, fit.source.as_deref()), (2.5, Some("d.csv")));
        // Fig. 5's file says e = 0.6; the fit says what e is at v0 = 0.3 m/s.
        let e = hunt_crossley_restitution(2.5 * 0.3);
        assert!((scene.impact.restitution - e).abs() < 1e-15);
        assert!((e - 0.6).abs() > 0.05, "the fit moved e: {e}");
        let again = parse(&to_toml(&scene, None)).unwrap();
        assert_eq!(again, scene);
        assert!(to_toml(&scene, None).contains("a = 2.5  # a, s/m\n"));
    }

    #[test]
    fn bad_fit_tables_name_the_key_and_its_line() {
        let err = |fit: &str| parse(&with_fit(fit)).unwrap_err().to_string();
        let line = to_toml(&fig5_scene(), None).lines().count() + 2;
        let e = err("[fit]\nlaw = \"hunt-crossley\"\nc = 1.0\n");
        assert!(
            e.starts_with(&format!("s.toml:{}:1: `fit.c` is not the constant of hunt-crossley (its constant is `fit.a`)", line + 2)),
            "{e}"
        );
        let e = err("[fit]\nlaw = \"quasistatic\"\na = 1.0\n");
        assert!(
            e.contains(&format!(":{}:", line + 1))
                && e.contains("unknown fitted law \"quasistatic\""),
            "{e}"
        );
        let e = err("[fit]\nlaw = \"kelvin-voigt\"\n");
        assert!(e.contains("missing key `fit.c`"), "{e}");
        let e = err("[fit]\nlaw = \"constant-e\"\ne = 1.2\n");
        assert!(
            e.contains(&format!(":{}:", line + 2))
                && e.contains("fit.e must be in (0, 1], got 1.2"),
            "{e}"
        );
        let e = err("[fit]\nlaw = \"hunt-crossley\"\na = \"big\"\n");
        assert!(e.contains("`fit.a` must be a number"), "{e}");
        let e = err("[fit]\na = 1.0\n");
        assert!(e.contains("missing key `fit.law`"), "{e}");
        let e = err("[fit]\nlaw = \"hunt-crossley\"\na = 1.0\nwhen = 3\n");
        assert!(e.contains("unknown key `fit.when`"), "{e}");
    }

    #[test]
    fn constant_e_sets_e_whatever_v0() {
        let text = with_fit("[fit]\nlaw = \"constant-e\"\ne = 0.55\n");
        let scene = parse(&text).unwrap();
        assert_eq!(scene.impact.restitution, 0.55);
        assert!(!scene.assumed.restitution);
    }
}
