//! The explorer's state and its state machine: `update(&mut App, Action)`. No terminal here.

use std::path::PathBuf;
use std::time::{Duration, Instant};

use tui_input::Input;

use crate::model::impact::SolveOptions;
use crate::model::presets::{Registry, SaveTarget, is_kebab_case, kebab_case};
use crate::model::scene_key::{BodyIndex, SceneKey};
use crate::model::{ForceModel, ImpactParams, ModelError, Quasistatic, Scene};

use super::action::Action;
use super::export;
use super::field::{self, Draft, Field, Nudge, Section};
use super::marker::MarkerStyle;
use super::picker::{EntryKind, Picker};
use super::solutions::{Job, Solutions};
use super::theme::Theme;

/// Where the cursor is: on a form field or on a model of the checklist.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Cursor {
    Field(Field),
    Model(ForceModel),
}

/// A field being edited.
#[derive(Debug, Clone)]
pub struct Editor {
    pub field: Field,
    pub input: Input,
    /// Why the last commit was refused (the text did not parse).
    pub error: Option<String>,
}

/// What a prompt asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PromptKind {
    Save,
    Export(ForceModel),
}

/// A one-line question at the bottom of the screen (a file name or a path).
#[derive(Debug, Clone)]
pub struct Prompt {
    pub kind: PromptKind,
    pub input: Input,
    pub error: Option<String>,
}

/// What has the keyboard.
#[derive(Debug, Clone)]
pub enum Mode {
    Normal,
    Editing(Editor),
    Help,
    Picker(Picker),
    Prompt(Prompt),
}

/// The charts, in the order `c` cycles them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ChartKind {
    ForceDisplacement,
    ForceTime,
    VelocityDisplacement,
}

impl ChartKind {
    pub const ALL: [ChartKind; 3] = [
        ChartKind::ForceDisplacement,
        ChartKind::VelocityDisplacement,
        ChartKind::ForceTime,
    ];

    fn next(self) -> ChartKind {
        let i = ChartKind::ALL.iter().position(|&c| c == self).unwrap_or(0);
        ChartKind::ALL[(i + 1) % ChartKind::ALL.len()]
    }
}

/// A line for the status bar: news of the last action.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Message {
    pub text: String,
    pub error: bool,
}

/// The quasistatic estimate of the last valid scene and the solver inputs it gives.
#[derive(Debug, Clone)]
pub struct Valid {
    pub scene: Scene,
    pub quasistatic: Quasistatic,
    pub params: ImpactParams,
}

/// Models checked when the explorer opens: the paper's Fig. 5 three plus elastic Hertz.
const DEFAULT_CHECKED: [ForceModel; 4] = [
    ForceModel::Quasistatic,
    ForceModel::Proposed,
    ForceModel::HuntCrossley,
    ForceModel::LankaraniNikravesh,
];

/// The whole state of the explorer.
#[derive(Debug)]
pub struct App {
    pub draft: Draft,
    /// The scene as last loaded or saved, for the unsaved-changes mark.
    saved: Scene,
    /// The preset the scene was loaded from or saved as, if any.
    pub preset: Option<String>,
    pub registry: Registry,
    /// Why the draft scene is invalid, if it is; the results of `valid` stay on screen meanwhile.
    pub scene_error: Option<ModelError>,
    pub valid: Option<Valid>,
    pub solutions: Solutions,
    checked: [bool; 5],
    pub focused: ForceModel,
    pub cursor: Cursor,
    pub mode: Mode,
    /// The chart shown first (alone where only one fits).
    pub chart: ChartKind,
    pub marker: MarkerStyle,
    pub theme: Theme,
    pub message: Option<Message>,
    /// Wall time of the last complete recompute (estimate and solves).
    pub last_recompute: Option<Duration>,
    recompute_started: Option<Instant>,
    outbox: Vec<Job>,
    pub quit: bool,
}

fn model_index(model: ForceModel) -> usize {
    ForceModel::ALL
        .iter()
        .position(|&m| m == model)
        .unwrap_or_default()
}

impl App {
    /// The explorer on `scene`, with the solves of the checked models queued.
    pub fn new(scene: Scene, registry: Registry, marker: MarkerStyle, theme: Theme) -> App {
        let mut checked = [false; 5];
        for model in DEFAULT_CHECKED {
            checked[model_index(model)] = true;
        }
        let preset = registry
            .scenes()
            .iter()
            .find(|info| registry.scene(&info.name).is_ok_and(|s| s == scene))
            .map(|info| info.name.clone());
        let mut app = App {
            draft: Draft::new(scene.clone(), SolveOptions::default()),
            saved: scene,
            preset,
            registry,
            scene_error: None,
            valid: None,
            solutions: Solutions::default(),
            checked,
            focused: ForceModel::Proposed,
            cursor: Cursor::Field(Field::Number(SceneKey::V0)),
            mode: Mode::Normal,
            chart: ChartKind::ForceDisplacement,
            marker,
            theme,
            message: None,
            last_recompute: None,
            recompute_started: None,
            outbox: Vec::new(),
            quit: false,
        };
        for warning in app.registry.warnings() {
            app.message = Some(Message {
                text: warning.to_string(),
                error: true,
            });
        }
        app.recompute();
        app
    }

    /// The solves requested since the last call, for the worker.
    pub fn take_jobs(&mut self) -> Vec<Job> {
        std::mem::take(&mut self.outbox)
    }

    pub fn is_checked(&self, model: ForceModel) -> bool {
        self.checked[model_index(model)]
    }

    /// Checked models in the order of [`ForceModel::ALL`].
    pub fn checked_models(&self) -> Vec<ForceModel> {
        ForceModel::ALL
            .into_iter()
            .filter(|&m| self.is_checked(m))
            .collect()
    }

    /// Whether the scene differs from the one last loaded or saved.
    pub fn is_dirty(&self) -> bool {
        self.draft.scene != self.saved
    }

    /// Whether any solve is running.
    pub fn is_computing(&self) -> bool {
        self.solutions.any_pending()
    }

    /// The cursor stops, in order: the visible fields, then the models.
    pub fn rows(&self) -> Vec<Cursor> {
        field::all_fields(&self.draft.scene)
            .into_iter()
            .map(Cursor::Field)
            .chain(ForceModel::ALL.into_iter().map(Cursor::Model))
            .collect()
    }

    /// The fields the scene error is about (empty when it names none, or there is none).
    pub fn error_fields(&self) -> Vec<Field> {
        match &self.scene_error {
            Some(ModelError::InvalidParameter { field, .. }) => match field.parse::<SceneKey>() {
                Ok(key) => vec![Field::Number(key)],
                Err(_) => Vec::new(),
            },
            Some(ModelError::UnsupportedPair(_)) => {
                vec![Field::Shape(BodyIndex::One), Field::Shape(BodyIndex::Two)]
            }
            _ => Vec::new(),
        }
    }

    /// The body a material from the picker goes to by default: the one under the cursor.
    fn cursor_body(&self) -> BodyIndex {
        match self.cursor {
            Cursor::Field(f) => match f.section() {
                Section::Body(index) => index,
                Section::Impact => BodyIndex::One,
            },
            Cursor::Model(_) => BodyIndex::One,
        }
    }

    fn say(&mut self, text: impl Into<String>, error: bool) {
        self.message = Some(Message {
            text: text.into(),
            error,
        });
    }

    /// Re-evaluates the estimate of the draft and requests the solves whose inputs changed.
    fn recompute(&mut self) {
        let start = Instant::now();
        match self.draft.scene.quasistatic() {
            Ok(quasistatic) => {
                self.scene_error = None;
                let params = self.draft.scene.impact_params(&quasistatic);
                self.valid = Some(Valid {
                    scene: self.draft.scene.clone(),
                    quasistatic,
                    params,
                });
                self.request_solves(start);
            }
            Err(error) => self.scene_error = Some(error),
        }
        self.keep_cursor_on_a_row();
    }

    fn request_solves(&mut self, start: Instant) {
        let Some(valid) = &self.valid else {
            return;
        };
        let params = valid.params;
        let mut queued = false;
        for model in self.checked_models() {
            if let Some(job) = self.solutions.request(model, params, self.draft.options) {
                self.outbox.push(job);
                queued = true;
            }
        }
        if queued {
            self.recompute_started = Some(start);
        } else if !self.solutions.any_pending() {
            self.last_recompute = Some(start.elapsed());
        }
    }

    /// After a shape change hides the field under the cursor, falls back to the body's shape.
    fn keep_cursor_on_a_row(&mut self) {
        if let Cursor::Field(f) = self.cursor
            && !self.rows().contains(&self.cursor)
        {
            self.cursor = Cursor::Field(match f.section() {
                Section::Body(index) => Field::Shape(index),
                Section::Impact => Field::Number(SceneKey::V0),
            });
        }
    }

    fn move_cursor(&mut self, forward: bool) {
        let rows = self.rows();
        let n = rows.len();
        let i = rows.iter().position(|&r| r == self.cursor).unwrap_or(0);
        let j = if forward {
            (i + 1) % n
        } else {
            (i + n - 1) % n
        };
        self.cursor = rows[j];
        if let Cursor::Model(model) = self.cursor {
            self.focused = model;
        }
    }

    fn toggle(&mut self, model: ForceModel) {
        let i = model_index(model);
        self.checked[i] = !self.checked[i];
        self.focused = model;
        if self.checked[i] {
            self.request_solves(Instant::now());
        }
    }

    fn load_scene(&mut self, scene: Scene) {
        self.draft = Draft::new(scene.clone(), self.draft.options);
        self.saved = scene;
        self.recompute();
    }
}

/// Advances the state machine by one action.
pub fn update(app: &mut App, action: Action) {
    match action {
        Action::Quit => app.quit = true,
        Action::Resize => {}
        Action::Solved(report) => solved(app, report),
        action => {
            app.message = None;
            match std::mem::replace(&mut app.mode, Mode::Normal) {
                Mode::Normal => normal(app, action),
                Mode::Editing(editor) => editing(app, editor, action),
                Mode::Help => {
                    if !matches!(action, Action::Cancel | Action::Enter) {
                        app.mode = Mode::Help;
                    }
                }
                Mode::Picker(picker) => picking(app, picker, action),
                Mode::Prompt(prompt) => prompting(app, prompt, action),
            }
        }
    }
}

fn solved(app: &mut App, report: super::worker::Report) {
    match report {
        Ok(outcome) => {
            if app.solutions.accept(outcome) && !app.solutions.any_pending() {
                app.last_recompute = app.recompute_started.take().map(|s| s.elapsed());
            }
        }
        // The worker only reports errors for solver panics; the runtime ends the app on them.
        Err(message) => app.say(message, true),
    }
}

fn normal(app: &mut App, action: Action) {
    match action {
        Action::Up => app.move_cursor(false),
        Action::Down => app.move_cursor(true),
        Action::Nudge(direction) => match app.cursor {
            Cursor::Field(field) => {
                if field.nudge(direction, &mut app.draft) {
                    app.recompute();
                }
            }
            Cursor::Model(_) => app.focused = step_model(app.focused, direction),
        },
        Action::Enter => match app.cursor {
            Cursor::Field(field) => {
                let text = field.edit_text(&app.draft);
                app.mode = Mode::Editing(Editor {
                    field,
                    input: Input::new(text),
                    error: None,
                });
            }
            Cursor::Model(model) => app.toggle(model),
        },
        Action::ToggleModel => match app.cursor {
            Cursor::Model(model) => app.toggle(model),
            Cursor::Field(_) => app.toggle(app.focused),
        },
        Action::FocusModel(direction) => app.focused = step_model(app.focused, direction),
        Action::CycleChart => app.chart = app.chart.next(),
        Action::Help => app.mode = Mode::Help,
        Action::Presets => {
            let mut picker = Picker::new(&app.registry);
            if let Some(preset) = &app.preset {
                picker.select(EntryKind::Scene, preset);
            }
            app.mode = Mode::Picker(picker);
        }
        Action::Save => {
            let name = &app.draft.scene.name;
            let suggestion = match &app.preset {
                Some(preset) => preset.clone(),
                None if is_kebab_case(name) => name.clone(),
                None => kebab_case(name),
            };
            app.mode = Mode::Prompt(Prompt {
                kind: PromptKind::Save,
                input: Input::new(suggestion),
                error: None,
            });
        }
        Action::Export => {
            let model = app.focused;
            if app.solutions.solution(model).is_some() {
                let stem = app.preset.as_deref().unwrap_or(&app.draft.scene.name);
                let path = export::default_path(stem, model);
                app.mode = Mode::Prompt(Prompt {
                    kind: PromptKind::Export(model),
                    input: Input::new(path.display().to_string()),
                    error: None,
                });
            } else {
                app.say(
                    format!(
                        "no solution of {} to export: check it with Space",
                        model.label()
                    ),
                    true,
                );
            }
        }
        Action::Cancel
        | Action::Input(_)
        | Action::ApplyMaterialTo(_)
        | Action::Quit
        | Action::Resize
        | Action::Solved(_) => {}
    }
}

fn step_model(model: ForceModel, direction: Nudge) -> ForceModel {
    let n = ForceModel::ALL.len();
    let i = model_index(model);
    ForceModel::ALL[match direction {
        Nudge::Up => (i + 1) % n,
        Nudge::Down => (i + n - 1) % n,
    }]
}

fn editing(app: &mut App, mut editor: Editor, action: Action) {
    match action {
        Action::Input(request) => {
            editor.input.handle(request);
            app.mode = Mode::Editing(editor);
        }
        Action::Enter => {
            let mut draft = app.draft.clone();
            match editor.field.apply(editor.input.value(), &mut draft) {
                Ok(()) => {
                    app.draft = draft;
                    app.recompute();
                }
                Err(reason) => {
                    editor.error = Some(reason);
                    app.mode = Mode::Editing(editor);
                }
            }
        }
        Action::Cancel => {}
        _ => app.mode = Mode::Editing(editor),
    }
}

fn picking(app: &mut App, mut picker: Picker, action: Action) {
    let target = match action {
        Action::Up | Action::Down => {
            picker.step(matches!(action, Action::Down));
            app.mode = Mode::Picker(picker);
            return;
        }
        Action::Enter => app.cursor_body(),
        Action::ApplyMaterialTo(index) => index,
        Action::Cancel => return,
        _ => {
            app.mode = Mode::Picker(picker);
            return;
        }
    };
    let Some(entry) = picker.selected().cloned() else {
        return;
    };
    match entry.kind {
        EntryKind::Scene => match app.registry.scene(&entry.name) {
            Ok(scene) => {
                app.load_scene(scene);
                app.preset = Some(entry.name.clone());
                app.say(format!("loaded scene {}", entry.name), false);
            }
            Err(e) => app.say(e.to_string(), true),
        },
        EntryKind::Material => match app.registry.material(&entry.name) {
            Ok(material) => {
                let body = match target {
                    BodyIndex::One => &mut app.draft.scene.body1,
                    BodyIndex::Two => &mut app.draft.scene.body2,
                };
                body.material = material;
                app.recompute();
                let n = if target == BodyIndex::One { 1 } else { 2 };
                app.say(format!("{} applied to body {n}", entry.name), false);
            }
            Err(e) => app.say(e.to_string(), true),
        },
    }
}

fn prompting(app: &mut App, mut prompt: Prompt, action: Action) {
    match action {
        Action::Input(request) => {
            prompt.input.handle(request);
            app.mode = Mode::Prompt(prompt);
        }
        Action::Enter => {
            let text = prompt.input.value().trim().to_string();
            let outcome = match prompt.kind {
                PromptKind::Save => save(app, &text),
                PromptKind::Export(model) => export_model(app, model, &text),
            };
            match outcome {
                Ok(news) => app.say(news, false),
                Err(reason) => {
                    prompt.error = Some(reason);
                    app.mode = Mode::Prompt(prompt);
                }
            }
        }
        Action::Cancel => {}
        _ => app.mode = Mode::Prompt(prompt),
    }
}

/// `~/…` with the home folder expanded.
fn expand_home(text: &str) -> PathBuf {
    match (text.strip_prefix("~/"), std::env::var_os("HOME")) {
        (Some(rest), Some(home)) => PathBuf::from(home).join(rest),
        _ => PathBuf::from(text),
    }
}

/// Saves the draft as a user preset (a kebab-case name) or to a path (with `/` or `.toml`).
fn save(app: &mut App, text: &str) -> Result<String, String> {
    if text.is_empty() {
        return Err("type a preset name or a path ending in .toml".into());
    }
    let is_path = text.contains(['/', '\\']) || text.ends_with(".toml");
    let scene = app.draft.scene.clone();
    let written = if is_path {
        let path = expand_home(text);
        app.registry
            .save_scene(&scene, None, SaveTarget::Path(&path))
            .map_err(|e| e.to_string())?
    } else {
        let path = app
            .registry
            .save_scene(&scene, None, SaveTarget::UserPreset { name: text })
            .map_err(|e| e.to_string())?;
        app.preset = Some(text.to_string());
        path
    };
    app.saved = scene;
    if let Ok(registry) = Registry::load_from(app.registry.user_dir()) {
        app.registry = registry;
    }
    Ok(format!("saved {}", written.display()))
}

fn export_model(app: &App, model: ForceModel, text: &str) -> Result<String, String> {
    if text.is_empty() {
        return Err("type a file name".into());
    }
    let solution = app
        .solutions
        .solution(model)
        .ok_or_else(|| format!("no solution of {} to export", model.label()))?;
    let path = expand_home(text);
    let samples = solution.trajectory.samples(export::EXPORT_SAMPLES);
    export::write(&path, &samples)?;
    Ok(format!(
        "exported {} ({} rows) to {}",
        model.name(),
        samples.len(),
        path.display()
    ))
}
