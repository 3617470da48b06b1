//! What a scene file says about how to look at the scene: the checked models (`models`, the first
//! focused) and the solver settings (`[solver]`), so that a preset opens as the figure it stands for.

use toml::{Table, Value};

use crate::model::ForceModel;
use crate::model::force::UnknownModel;
use crate::model::impact::{MethodChoice, SolveOptions};

use super::decode::Decoder;
use super::document::{Problem, SceneFileError, ValueIssue};
use super::write::toml_float;

/// Keys of `[solver]`, as on the command line (`--method`, `--rtol`, `--atol`, `--dt`).
pub(super) const SOLVER_KEYS: &[&str] = &["method", "rtol", "atol", "dt"];

/// The models checked when a scene names none: the paper's five, in the paper's order.
pub const PAPER_MODELS: [ForceModel; 5] = [
    ForceModel::Quasistatic,
    ForceModel::DryFriction,
    ForceModel::Proposed,
    ForceModel::HuntCrossley,
    ForceModel::LankaraniNikravesh,
];

/// The view a scene file asks for.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneView {
    /// Checked models, the first focused; never empty, no repeats.
    pub models: Vec<ForceModel>,
    /// Method, tolerances and step; the rest as [`SolveOptions::default`].
    pub options: SolveOptions,
}

impl Default for SceneView {
    fn default() -> SceneView {
        SceneView {
            models: PAPER_MODELS.to_vec(),
            options: SolveOptions::default(),
        }
    }
}

impl SceneView {
    /// The focused model: the first checked one.
    pub fn focused(&self) -> ForceModel {
        self.models.first().copied().unwrap_or(ForceModel::Proposed)
    }

    /// The `models = [...]` line (it must precede the first table header).
    pub fn models_line(&self) -> String {
        let names: Vec<String> = self
            .models
            .iter()
            .map(|m| Value::String(m.name().to_string()).to_string())
            .collect();
        format!(
            "models = [{}]  # checked, the first focused\n",
            names.join(", ")
        )
    }

    /// The `[solver]` table.
    pub fn solver_table(&self) -> String {
        let options = &self.options;
        let mut out = format!(
            "[solver]\nmethod = \"{}\"\nrtol = {}\n",
            options.method,
            toml_float(options.rtol),
        );
        if let Some(atol) = options.atol {
            out.push_str(&format!("atol = {}\n", toml_float(atol)));
        }
        if let Some(dt) = options.dt {
            out.push_str(&format!("dt = {}  # s\n", toml_float(dt)));
        }
        out
    }
}

impl Decoder<'_> {
    /// `models` and `[solver]` of the top-level table, defaults where absent.
    pub(super) fn view(&self, root: &Table) -> Result<SceneView, SceneFileError> {
        let defaults = SceneView::default();
        let models = match root.get("models") {
            None => defaults.models,
            Some(value) => self.models(value)?,
        };
        let options = match root.get("solver") {
            None => defaults.options,
            Some(Value::Table(table)) => self.solver(table)?,
            Some(other) => return Err(self.wrong_type("solver", "a table", other)),
        };
        Ok(SceneView { models, options })
    }

    fn models(&self, value: &Value) -> Result<Vec<ForceModel>, SceneFileError> {
        let bad = |issue: ValueIssue| {
            self.doc.error(
                "models",
                Problem::BadValue {
                    key: "models".into(),
                    issue,
                },
            )
        };
        let Value::Array(items) = value else {
            return Err(self.wrong_type("models", "an array of model names", value));
        };
        let mut models = Vec::with_capacity(items.len());
        for item in items {
            let Value::String(name) = item else {
                return Err(self.wrong_type("models", "an array of model names", item));
            };
            let model: ForceModel = name.parse().map_err(|e: UnknownModel| bad(e.into()))?;
            if models.contains(&model) {
                return Err(bad(ValueIssue::ListedTwice(name.clone())));
            }
            models.push(model);
        }
        if models.is_empty() {
            return Err(bad(ValueIssue::NoModels));
        }
        Ok(models)
    }

    fn solver(&self, table: &Table) -> Result<SolveOptions, SceneFileError> {
        self.check_keys("solver", table, SOLVER_KEYS)?;
        let bad = |key: &str, issue: ValueIssue| {
            let key = format!("solver.{key}");
            self.doc.error(
                &key,
                Problem::BadValue {
                    key: key.clone(),
                    issue,
                },
            )
        };
        let out_of_range = |requirement, value| ValueIssue::OutOfRange { requirement, value };
        let mut options = SolveOptions::default();
        if let Some(method) = self.optional_string(table, "solver", "method")? {
            options.method = method
                .parse::<MethodChoice>()
                .map_err(|e| bad("method", e.into()))?;
        }
        if let Some(rtol) = self.optional_number(table, "solver", "rtol")? {
            if !(rtol > 0.0 && rtol < 1.0) {
                return Err(bad("rtol", out_of_range("> 0 and < 1", rtol)));
            }
            options.rtol = rtol;
        }
        if let Some(atol) = self.optional_number(table, "solver", "atol")? {
            if !(atol > 0.0 && atol.is_finite()) {
                return Err(bad("atol", out_of_range("> 0 and finite", atol)));
            }
            options.atol = Some(atol);
        }
        if let Some(dt) = self.optional_number(table, "solver", "dt")? {
            if !(dt > 0.0 && dt.is_finite()) {
                return Err(bad("dt", out_of_range("> 0 and finite (s)", dt)));
            }
            options.dt = Some(dt);
        }
        Ok(options)
    }
}
