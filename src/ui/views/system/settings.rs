//! What the system view runs: the `[system]` table of the scene (its keys edited here), the stops
//! (rigid, and the focused law as the compliant one), and the diagram's key and range.

use crate::chart::system::DiagramAxes;
use crate::format::units::{self, Unit};
use crate::model::presets::Registry;
use crate::model::scene::Scene;
use crate::model::system::{
    CompliantDamping, Contact, DiagramOptions, Param, RunOptions, SystemKey, SystemKind,
    SystemModel, SystemSpec,
};
use crate::model::ForceModel;

/// Transient and recorded impacts of the view's run and of each diagram value: enough to settle
/// on the attractor and show a period up to a few dozen impacts, few enough to answer an edit at
/// once with the rigid stop.
const TRANSIENT: usize = 200;
const RECORDED: usize = 40;
/// Dense samples per forcing period of the drawn run.
const SAMPLES_PER_PERIOD: usize = 100;
/// Values of the diagram unless set.
pub const DEFAULT_VALUES: usize = 120;

/// A row of the form: a `[system]` key, or a setting of the diagram.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Row {
    Key(SystemKey),
    DiagramKey,
    From,
    To,
    Values,
}

impl Row {
    /// Its label in the form.
    pub fn label(self) -> String {
        match self {
            Row::Key(key) => match key {
                SystemKey::Amplitude => "A amplitude",
                SystemKey::Gamma => "Γ = Aω²/g",
                SystemKey::Frequency => "f frequency",
                SystemKey::Gravity => "g gravity",
                SystemKey::Stiffness => "k stiffness",
                SystemKey::DampingRatio => "ζ damping",
                SystemKey::Damping => "c damping",
                SystemKey::ForcingAmplitude => "forcing",
                SystemKey::Gap => "gap",
                SystemKey::SecondGap => "gap₂",
            }
            .into(),
            Row::DiagramKey => "diagram".into(),
            Row::From => "from".into(),
            Row::To => "to".into(),
            Row::Values => "values".into(),
        }
    }
}

/// The view's settings: the diagram's. The `[system]` table it edits is the draft's
/// ([`Draft::system`](crate::ui::field::Draft)), so that `u` undoes its edits and `s` saves them.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Settings {
    /// The diagram's key; `None`: Γ for a ball, the frequency for an oscillator.
    pub diagram_key: Option<Param>,
    /// The diagram's range, SI; `None`: the default of its key.
    pub range: Option<(f64, f64)>,
    pub values: Option<usize>,
    /// Transient and recorded impacts of the run and of each diagram value; `None`: 200 and 40.
    pub budget: Option<(usize, usize)>,
}

/// The presets whose `[system]` table a scene without one can take.
pub const SYSTEM_PRESETS: [&str; 3] = [
    "bouncing-ball",
    "impact-oscillator",
    "impact-oscillator-clearance",
];

/// Why the view has nothing to run on a scene without `[system]`.
pub const NO_SYSTEM: &str = "this scene has no [system] table";

/// A `[system]` table to paste into a scene file: the bouncing-ball preset's (docs/systems.md §1).
pub const TOML_SNIPPET: &str = "[system]
kind = \"bouncing-ball\"
amplitude = 0.001  # m
frequency = 20.0   # Hz";

/// The `[system]` table of preset `name`, or why there is none.
pub fn preset_spec(registry: &Registry, name: &str) -> Result<SystemSpec, String> {
    match registry.scene_system(name, &[]) {
        Ok(Some(spec)) => Ok(spec),
        Ok(None) => Err(format!("{name} has no [system] table")),
        Err(e) => Err(e.to_string()),
    }
}

/// The unit a parameter is typed and shown in.
pub fn unit(param: Param, model: &SystemModel) -> Unit {
    DiagramAxes::impact_speeds(param, model).key_unit
}

impl Settings {
    /// The rows of the form for `model`: its keys, then the diagram's.
    pub fn rows(model: &SystemModel) -> Vec<Row> {
        SystemKey::ALL
            .into_iter()
            .filter(|&k| Param::System(k).get(model).is_ok())
            .map(Row::Key)
            .chain([Row::DiagramKey, Row::From, Row::To, Row::Values])
            .collect()
    }

    /// The diagram's key for `model`.
    pub fn diagram_key(&self, model: &SystemModel) -> Param {
        match self.diagram_key {
            Some(key) if key.get(model).is_ok() => key,
            _ => match model.spec.kind {
                SystemKind::BouncingBall { .. } => Param::System(SystemKey::Gamma),
                SystemKind::ImpactOscillator { .. } => Param::System(SystemKey::Frequency),
            },
        }
    }

    /// The diagram's range: the one set, else Γ from 0.9 to 3.5 (the period-1 orbit's birth, its
    /// doublings and chaos at e = 0.5), else half to one and a half times the current value.
    pub fn range(&self, model: &SystemModel) -> (f64, f64) {
        if let Some(range) = self.range {
            return range;
        }
        let key = self.diagram_key(model);
        if key == Param::System(SystemKey::Gamma) {
            return (0.9, 3.5);
        }
        let v = key.get(model).unwrap_or(1.0);
        (0.5 * v, 1.5 * v)
    }

    /// The value of `row` as the form shows it.
    pub fn show(&self, row: Row, model: &SystemModel) -> String {
        let key = self.diagram_key(model);
        let (from, to) = self.range(model);
        let value = |param: Param, v: f64| units::engineering(v, unit(param, model), 4);
        match row {
            Row::Key(k) => Param::System(k)
                .get(model)
                .map_or_else(|e| e.to_string(), |v| value(Param::System(k), v)),
            Row::DiagramKey => key.path(),
            Row::From => value(key, from),
            Row::To => value(key, to),
            Row::Values => self.values.unwrap_or(DEFAULT_VALUES).to_string(),
        }
    }

    /// The text an editor opens with: the value in its unit, or the key.
    pub fn edit_text(&self, row: Row, model: &SystemModel) -> String {
        self.show(row, model)
    }

    /// Applies typed `text` to `row`: the new `[system]` table if a key of it changed; the reason,
    /// naming the key, if refused.
    pub fn apply(
        &mut self,
        row: Row,
        text: &str,
        model: &SystemModel,
    ) -> Result<Option<SystemSpec>, String> {
        let param = match row {
            Row::Key(k) => Param::System(k),
            Row::From | Row::To => self.diagram_key(model),
            Row::DiagramKey => {
                let param: Param = text
                    .trim()
                    .parse()
                    .map_err(|e: crate::model::system::SystemError| e.to_string())?;
                param.get(model).map_err(|e| e.to_string())?;
                self.diagram_key = Some(param);
                self.range = None;
                return Ok(None);
            }
            Row::Values => {
                let n: f64 = text
                    .trim()
                    .parse()
                    .map_err(|_| format!("\"{}\" is not a whole number", text.trim()))?;
                return self.set(row, n, model);
            }
        };
        let value =
            units::parse(text, unit(param, model)).map_err(|e| format!("{}: {e}", param.path()))?;
        self.set(row, value, model)
    }

    /// Sets a numeric `row` to `value` (SI): the new `[system]` table if a key of it changed; the
    /// reason, naming the key, if refused.
    pub fn set(
        &mut self,
        row: Row,
        value: f64,
        model: &SystemModel,
    ) -> Result<Option<SystemSpec>, String> {
        let key = self.diagram_key(model);
        match row {
            Row::Key(k) => {
                let changed = Param::System(k)
                    .apply(model, value)
                    .map_err(|e| e.to_string())?;
                return Ok(Some(changed.spec));
            }
            Row::From | Row::To => {
                key.apply(model, value).map_err(|e| e.to_string())?;
                let (from, to) = self.range(model);
                self.range = Some(if row == Row::From {
                    (value, to)
                } else {
                    (from, value)
                });
            }
            Row::Values => {
                if !(value.fract() == 0.0 && (2.0..=2000.0).contains(&value)) {
                    return Err(format!("values must be a whole number 2…2000, got {value}"));
                }
                self.values = Some(value as usize);
            }
            Row::DiagramKey => {}
        }
        Ok(None)
    }

    /// ← → on a numeric row: 5 % up or down (values: twice or half as many); the new `[system]`
    /// table if a key of it changed.
    pub fn nudge(
        &mut self,
        row: Row,
        up: bool,
        model: &SystemModel,
    ) -> Result<Option<SystemSpec>, String> {
        let (from, to) = self.range(model);
        let factor = if up { 1.05 } else { 1.0 / 1.05 };
        match row {
            Row::DiagramKey => {
                self.step_key(model, up);
                Ok(None)
            }
            Row::Values => {
                let n = self.values.unwrap_or(DEFAULT_VALUES) as f64;
                let n = if up { n * 2.0 } else { (n / 2.0).floor() };
                self.set(row, n.clamp(2.0, 2000.0), model)
            }
            Row::Key(k) => {
                let v = Param::System(k).get(model).map_err(|e| e.to_string())?;
                self.set(row, v * factor, model)
            }
            Row::From => self.set(row, from * factor, model),
            Row::To => self.set(row, to * factor, model),
        }
    }

    /// ← → on the diagram key: the next or previous key the system has.
    pub fn step_key(&mut self, model: &SystemModel, forward: bool) {
        let keys: Vec<Param> = SystemKey::ALL
            .into_iter()
            .map(Param::System)
            .chain([Param::Scene(crate::model::scene_key::SceneKey::Restitution)])
            .filter(|p| p.get(model).is_ok())
            .collect();
        let here = self.diagram_key(model);
        let i = keys.iter().position(|&k| k == here).unwrap_or(0);
        let n = keys.len().max(1);
        let j = if forward { (i + 1) % n } else { (i + n - 1) % n };
        if let Some(&key) = keys.get(j) {
            self.diagram_key = Some(key);
            self.range = None;
        }
    }
}

/// The stops drawn: rigid with the scene's e, and `law` with its damping from each impact.
pub fn contacts(model: &SystemModel, law: ForceModel) -> Vec<Contact> {
    vec![
        Contact::rigid(model.restitution),
        Contact::Compliant {
            model: law,
            damping: CompliantDamping::PerImpact,
        },
    ]
}

/// The run drawn: a transient, then recorded impacts with dense samples.
pub fn run_options(settings: &Settings) -> RunOptions {
    let (transient, recorded) = settings.budget.unwrap_or((TRANSIENT, RECORDED));
    RunOptions {
        transient_impacts: transient,
        recorded_impacts: recorded,
        max_periods: 2000.0,
        max_impacts: 200_000,
        samples_per_period: SAMPLES_PER_PERIOD,
        initial: None,
    }
}

/// Each value of the diagram: the same budgets without samples.
pub fn diagram_options(settings: &Settings) -> DiagramOptions {
    DiagramOptions {
        run: RunOptions {
            samples_per_period: 0,
            ..run_options(settings)
        },
        ..DiagramOptions::default()
    }
}

/// The model of `scene` in its `[system]` table `system`, or why there is none (naming the key).
pub fn model(system: Option<&SystemSpec>, scene: &Scene) -> Result<SystemModel, String> {
    let spec = system.ok_or(NO_SYSTEM)?;
    SystemModel::from_scene(scene, spec).map_err(|e| e.to_string())
}
