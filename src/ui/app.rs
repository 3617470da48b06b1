//! The explorer's state; its transitions are in [`update`](super::update). No terminal here.

use std::cell::Cell;
use std::path::PathBuf;
use std::sync::OnceLock;
use std::time::{Duration, Instant};

use tui_input::{Input, InputRequest};

use crate::model::force::LAW_COUNT;
use crate::model::impact::SolveOptions;
use crate::model::presets::Registry;
use crate::model::presets::kebab_case;
use crate::model::recommend::{Recommendation, recommend_reusing};
use crate::model::scene_file::{SceneView, system_table};
use crate::model::scene_fit::FittedKind;
use crate::model::scene_key::{BodyIndex, SceneKey};
use crate::model::scene_title::{edits, retitled};
use crate::model::study::runner::{StudyJob, StudyKind, StudySpec};
use crate::model::system::SystemSpec;
use crate::model::warnings::{ModelWarning, scene_warnings};
use crate::model::{ForceModel, ImpactParams, ModelError, Quasistatic, Scene};
use crate::ui::studies::Studies;

use super::action::Jump;
use super::field::{self, Draft, Field, Nudge, Section};
use super::picker::Picker;
use super::solutions::{Job, Solutions};
use super::style::{MarkerStyle, Theme};
use super::tab::Tab;
use super::views::ViewStates;

/// Where the cursor is: on a form field or on a model of the checklist.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Cursor {
    Field(Field),
    Model(ForceModel),
}

/// What a line editor edits.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EditTarget {
    /// A field of the explorer's form.
    Field(Field),
    /// A row of the shown view's own form, numbered by the view.
    Row(usize),
}

/// A field being edited.
#[derive(Debug, Clone)]
pub struct Editor {
    pub target: EditTarget,
    pub input: Input,
    /// Why the last commit was refused (the text did not parse).
    pub error: Option<String>,
    /// The whole text is selected, as when the editor opens on a value: the first typed character
    /// (or a paste) replaces it and Backspace, Delete or `Ctrl-U` clear it; a cursor key or
    /// `Ctrl-W` keeps the text to edit it.
    pub selected: bool,
}

impl Editor {
    /// Applies a line-editing request, replacing the selected text as [`Editor::selected`] says.
    pub fn handle(&mut self, request: InputRequest) {
        if std::mem::take(&mut self.selected) {
            match request {
                InputRequest::InsertChar(_) => self.input = Input::default(),
                InputRequest::DeletePrevChar
                | InputRequest::DeleteNextChar
                | InputRequest::DeleteLine => {
                    self.input = Input::default();
                    return;
                }
                _ => {}
            }
        }
        self.input.handle(request);
    }

    /// Types the first line of `text` at the cursor (over the selected text).
    pub fn paste(&mut self, text: &str) {
        for c in text.lines().next().unwrap_or_default().chars() {
            self.handle(InputRequest::InsertChar(c));
        }
    }
}

/// What a prompt asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PromptKind {
    Save,
    Export(Export),
}

/// What `e` writes to a CSV file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Export {
    /// A model's trajectory (`t,x,v,F`), from the explorer and the other views.
    Trajectory(ForceModel),
    /// The sweep of view 4, as `sweep --format csv` writes it.
    Sweep,
}

/// A one-line question at the bottom of the screen (a file name or a path).
#[derive(Debug, Clone)]
pub struct Prompt {
    pub kind: PromptKind,
    pub input: Input,
    pub error: Option<String>,
    /// The explorer quits once this is done (`q` then `s`: save and quit).
    pub then_quit: bool,
}

/// What a yes/no question at the bottom of the screen would do on `y`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Confirm {
    /// Quit with unsaved changes.
    Quit,
    /// Save a user preset that hides the built-in of this name (then quit, if the save was asked
    /// for by the quit question).
    ShadowBuiltin { name: String, then_quit: bool },
    /// Export over an existing file.
    Overwrite { path: PathBuf, export: Export },
}

/// What has the keyboard.
#[derive(Debug, Clone)]
pub enum Mode {
    Normal,
    Editing(Editor),
    Help,
    /// The engine panel (`t`).
    Engine(super::engine_panel::EnginePanel),
    Picker(Picker),
    Prompt(Prompt),
    Confirm(Confirm),
}

/// The first row each scrolled list shows, kept from one frame to the next: a list scrolls only
/// as far as needed to keep its cursor in view, so that a click (which moves the cursor to a row
/// in view) never scrolls what the pointer is on. Drawing and hit-testing compute the same
/// offset from it ([`Scroll::keep_in_view`]) and store it back.
#[derive(Debug)]
pub struct Scroll {
    /// The model checklist.
    pub models: Cell<usize>,
    /// The focused model when the checklist was last drawn: a new focus (`[` `]`, a check) is
    /// scrolled into view, an old one is not (a click on a field scrolls nothing).
    pub models_focus: Cell<Option<ForceModel>>,
    /// The explorer's form, when it is one scrolled list (compact screens); [`Scroll::UNSET`]
    /// until first drawn, when it centres the cursor.
    pub form: Cell<usize>,
}

impl Default for Scroll {
    fn default() -> Scroll {
        Scroll {
            models: Cell::new(0),
            models_focus: Cell::new(None),
            form: Cell::new(Scroll::UNSET),
        }
    }
}

impl Scroll {
    /// A list not drawn yet.
    pub const UNSET: usize = usize::MAX;

    /// The first row of `total` shown `height` at a time, starting from `first` and moved as
    /// little as keeps row `anchor` in view.
    pub fn keep_in_view(first: usize, anchor: usize, total: usize, height: usize) -> usize {
        if height == 0 {
            return 0;
        }
        let first = if anchor < first {
            anchor
        } else if anchor >= first + height {
            anchor + 1 - height
        } else {
            first
        };
        first.min(total.saturating_sub(height))
    }
}

/// Lives in its own module so that layouts and charts need not import the app state.
pub use crate::chart::kind::ChartKind;

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
    /// Where the scene leaves the theory's range (a contact not small against R, a cylinder fit
    /// that departs from eqs 13–14), computed once per edit.
    pub warnings: Vec<ModelWarning>,
    /// The recommendation (it solves the laws it speaks of): computed when first shown, once per
    /// edit ([`App::advice`]), so that a burst of keys does not solve them for every key.
    advice: OnceLock<Recommendation>,
}

/// Models checked when the explorer opens on a bare scene: the paper's Fig. 5 three plus elastic
/// Hertz, the proposed model focused.
const DEFAULT_CHECKED: [ForceModel; 4] = [
    ForceModel::Proposed,
    ForceModel::Quasistatic,
    ForceModel::HuntCrossley,
    ForceModel::LankaraniNikravesh,
];

/// Levels of `u` (undo).
const UNDO_LEVELS: usize = 100;

/// The whole state of the explorer.
#[derive(Debug)]
pub struct App {
    pub draft: Draft,
    /// The scene as last loaded or saved, for the unsaved-changes mark.
    pub(super) saved: Scene,
    /// The view (models, solver settings) as last loaded or saved, for resetting the solver rows.
    pub(super) saved_view: SceneView,
    /// The `[system]` table as last loaded or saved, for the unsaved-changes mark.
    pub(super) saved_system: Option<SystemSpec>,
    /// The preset the scene was loaded from or saved as, if any.
    pub preset: Option<String>,
    /// The description of that preset, kept when the scene is saved.
    pub description: Option<String>,
    /// Earlier drafts, the latest last, for `u`.
    pub(super) undo: Vec<Draft>,
    /// Whether the app asks the terminal for mouse events (`m` toggles; off lets the terminal
    /// select text).
    pub mouse: bool,
    pub registry: Registry,
    /// Why the draft scene is invalid, if it is; the results of `valid` stay on screen meanwhile.
    pub scene_error: Option<ModelError>,
    pub valid: Option<Valid>,
    pub solutions: Solutions,
    pub(super) checked: [bool; LAW_COUNT],
    /// Each law's damping calibrated so that it realises the scene's e (docs/physics.md §6.4).
    pub calibrate: bool,
    pub focused: ForceModel,
    pub cursor: Cursor,
    pub mode: Mode,
    /// The view shown.
    pub tab: Tab,
    /// Results of the studies of tabs 2–4.
    pub studies: Studies,
    /// Each view's own state (its settings, cursor, chart shown).
    pub views: ViewStates,
    /// Terminal size (columns, rows), for sizing sweeps to their chart; (0, 0) until known.
    pub screen: (u16, u16),
    /// The first rows the scrolled lists show, as last drawn.
    pub scroll: Scroll,
    pub marker: MarkerStyle,
    pub theme: Theme,
    pub message: Option<Message>,
    /// Wall time of the last complete recompute (estimate and solves).
    pub last_recompute: Option<Duration>,
    /// Text for the terminal's clipboard, sent (OSC 52) by the event loop before the next frame.
    pub clipboard: Option<String>,
    pub(super) recompute_started: Option<Instant>,
    outbox: Vec<Job>,
    study_outbox: Vec<StudyJob>,
    pub quit: bool,
}

/// [`retitled`] of a scene with its `[system]` table: the description names the keys of the
/// table that were edited too, so that a preset's "Γ ≈ 1.61" does not describe another Γ.
pub(crate) fn retitled_with_system(
    (original, saved_system): (&Scene, Option<&SystemSpec>),
    description: Option<&str>,
    (edited, system): (&Scene, Option<&SystemSpec>),
) -> (String, Option<String>) {
    let (name, described) = retitled(original, description, edited);
    let system = system_edits(saved_system, system);
    if system.is_empty() {
        return (name, described);
    }
    let changed: Vec<String> = edits(original, edited).into_iter().chain(system).collect();
    let described = format!("edited from \"{}\": {}", original.name, changed.join(", "));
    (name, Some(described))
}

/// What differs in `edited` from the `[system]` table `saved`: `system.gap = 0.0004`, each key
/// with its new value as the scene file writes it.
fn system_edits(saved: Option<&SystemSpec>, edited: Option<&SystemSpec>) -> Vec<String> {
    if saved == edited {
        return Vec::new();
    }
    let lines = |spec: Option<&SystemSpec>| -> Vec<String> {
        spec.map(system_table)
            .unwrap_or_default()
            .lines()
            .skip(1)
            .map(|l| l.split('#').next().unwrap_or_default().trim().to_string())
            .collect()
    };
    let before = lines(saved);
    match edited {
        None => vec!["[system] removed".to_string()],
        Some(_) => lines(edited)
            .into_iter()
            .filter(|line| !before.contains(line))
            .map(|line| format!("system.{line}"))
            .collect(),
    }
}

pub(super) fn model_index(model: ForceModel) -> usize {
    model.index()
}

impl App {
    /// The explorer on `scene`, with the solves of the checked models queued.
    pub fn new(scene: Scene, registry: Registry, marker: MarkerStyle, theme: Theme) -> App {
        let view = SceneView {
            models: DEFAULT_CHECKED.to_vec(),
            options: SolveOptions::default(),
        };
        App::open(scene, view, registry, marker, theme)
    }

    /// The explorer on `scene` as `view` asks (checked models, the first focused; solver settings),
    /// with the `[system]` table of the preset the scene is, if any.
    pub fn open(
        scene: Scene,
        view: SceneView,
        registry: Registry,
        marker: MarkerStyle,
        theme: Theme,
    ) -> App {
        let system = registry
            .scenes()
            .iter()
            .find(|info| registry.scene(&info.name).is_ok_and(|s| s == scene))
            .and_then(|info| registry.scene_system(&info.name, &[]).ok().flatten());
        App::open_system(scene, system, view, registry, marker, theme)
    }

    /// [`App::open`] on a scene read with its `[system]` table (a scene file, `--set system.*`
    /// applied): the system view shows that table, and `s` writes it back.
    pub fn open_system(
        scene: Scene,
        system: Option<SystemSpec>,
        view: SceneView,
        registry: Registry,
        marker: MarkerStyle,
        theme: Theme,
    ) -> App {
        let preset = registry
            .scenes()
            .iter()
            .find(|info| {
                registry.scene(&info.name).is_ok_and(|s| s == scene)
                    && registry
                        .scene_system(&info.name, &[])
                        .is_ok_and(|s| s == system)
            })
            .map(|info| info.name.clone());
        let description = preset
            .as_deref()
            .and_then(|name| registry.scene_description(name).ok().flatten());
        let mut app = App {
            draft: Draft::new(scene.clone(), view.options).with_system(system),
            saved: scene,
            saved_view: view.clone(),
            saved_system: system,
            preset,
            description,
            undo: Vec::new(),
            mouse: true,
            registry,
            scene_error: None,
            valid: None,
            solutions: Solutions::default(),
            checked: [false; LAW_COUNT],
            calibrate: false,
            focused: view.focused(),
            cursor: Cursor::Field(Field::Number(SceneKey::V0)),
            mode: Mode::Normal,
            tab: Tab::HOME,
            studies: Studies::default(),
            views: ViewStates::default(),
            screen: (0, 0),
            scroll: Scroll::default(),
            marker,
            theme,
            message: None,
            last_recompute: None,
            clipboard: None,
            recompute_started: None,
            outbox: Vec::new(),
            study_outbox: Vec::new(),
            quit: false,
        };
        for warning in app.registry.warnings() {
            app.message = Some(Message {
                text: warning.to_string(),
                error: true,
            });
        }
        app.check_only(&view.models);
        app.recompute();
        app
    }

    /// Checks exactly `models` (nothing is solved here).
    fn check_only(&mut self, models: &[ForceModel]) {
        self.checked = [false; LAW_COUNT];
        for &model in models {
            self.checked[model_index(model)] = true;
        }
    }

    /// The scene view to save: the focused model first if checked, then the other checked ones; the
    /// solver settings of the draft.
    pub fn scene_view(&self) -> SceneView {
        let mut models = self.checked_models();
        if let Some(i) = models.iter().position(|&m| m == self.focused) {
            models[..=i].rotate_right(1);
        }
        if models.is_empty() {
            models = self.saved_view.models.clone();
        }
        SceneView {
            models,
            options: self.draft.options,
        }
    }

    /// Loads a preset or scene file with its view; `name` becomes the preset shown.
    pub(super) fn load_preset(&mut self, name: &str) -> Result<(), String> {
        let scene = self.registry.scene(name).map_err(|e| e.to_string())?;
        let view = self.registry.scene_view(name).map_err(|e| e.to_string())?;
        let system = self
            .registry
            .scene_system(name, &[])
            .map_err(|e| e.to_string())?;
        self.description = self.registry.scene_description(name).ok().flatten();
        self.check_only(&view.models);
        self.focused = view.focused();
        self.draft = Draft::new(scene.clone(), view.options).with_system(system);
        self.saved = scene;
        self.saved_view = view;
        self.saved_system = system;
        self.preset = Some(name.to_string());
        self.recompute();
        Ok(())
    }

    /// Records `before` for `u` when the draft has changed since.
    pub(super) fn remember_for_undo(&mut self, before: Draft) {
        if before != self.draft {
            if self.undo.len() == UNDO_LEVELS {
                self.undo.remove(0);
            }
            self.undo.push(before);
        }
    }

    /// The solves requested since the last call, for the worker.
    pub fn take_jobs(&mut self) -> Vec<Job> {
        std::mem::take(&mut self.outbox)
    }

    /// The studies requested since the last call, for the studies' job queue.
    pub fn take_studies(&mut self) -> Vec<StudyJob> {
        std::mem::take(&mut self.study_outbox)
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

    /// The recommendation for the last valid scene, computed the first time it is asked for after
    /// an edit; the laws it speaks of that the table has solved as it would are not solved again.
    pub fn advice(&self) -> Option<&Recommendation> {
        let valid = self.valid.as_ref()?;
        Some(valid.advice.get_or_init(|| {
            recommend_reusing(&valid.scene, &valid.quasistatic, |model| {
                self.solutions.default_outcome(model, &valid.params)
            })
        }))
    }

    /// The scene's name and description as shown, exported and saved: those loaded while the
    /// draft is as loaded, else named by its bodies with what was edited (a preset's "…on steel
    /// plate" is not the name of a scene whose plate became aluminium).
    /// An edited `[system]` table is named in the description too.
    pub fn title(&self) -> (String, Option<String>) {
        retitled_with_system(
            (&self.saved, self.saved_system.as_ref()),
            self.description.as_deref(),
            (&self.draft.scene, self.draft.system.as_ref()),
        )
    }

    /// The file-name stem of exports: the preset's name while unedited, else the shown name in
    /// kebab case.
    pub fn file_stem(&self) -> String {
        let edited = !edits(&self.saved, &self.draft.scene).is_empty();
        match &self.preset {
            _ if edited => kebab_case(&self.title().0),
            Some(preset) => preset.clone(),
            None => self.draft.scene.name.clone(),
        }
    }

    /// Whether the scene or its `[system]` table differs from the one last loaded or saved.
    pub fn is_dirty(&self) -> bool {
        self.draft.scene != self.saved || self.draft.system != self.saved_system
    }

    /// The `[system]` table as last loaded or saved.
    pub fn saved_system(&self) -> Option<&SystemSpec> {
        self.saved_system.as_ref()
    }

    /// Whether any solve is running.
    pub fn is_computing(&self) -> bool {
        self.solutions.any_pending()
    }

    /// The step fixed-step methods take when dt is `auto`: t_c/1000 of the elastic estimate, as
    /// the solver picks it (`None` without a valid scene).
    pub fn auto_dt(&self) -> Option<f64> {
        self.valid
            .as_ref()
            .map(|v| v.quasistatic.t_contact / 1000.0)
            .filter(|dt| *dt > 0.0 && dt.is_finite())
    }

    /// Queues `spec` for the studies' job queue unless the same study is held or running.
    pub(crate) fn queue_study(&mut self, spec: StudySpec) {
        if let Some(job) = self.studies.request(spec) {
            self.study_outbox.push(job);
        }
    }

    /// Cancels the study of `kind` if one is pending (its result so far stays); whether it was.
    pub(crate) fn cancel_study(&mut self, kind: StudyKind) -> bool {
        match self.studies.cancel(kind) {
            Some(job) => {
                self.study_outbox.push(job);
                true
            }
            None => false,
        }
    }

    /// Opens a line editor on `target` holding `text`, selected: typing replaces it.
    pub(crate) fn open_editor(&mut self, target: EditTarget, text: String) {
        self.mode = Mode::Editing(Editor {
            target,
            input: Input::new(text),
            error: None,
            selected: true,
        });
    }

    /// Opens a line editor on `target` holding text the user gave (a paste): typing goes on
    /// after it.
    pub(crate) fn open_editor_typed(&mut self, target: EditTarget, text: String) {
        self.open_editor(target, text);
        if let Mode::Editing(editor) = &mut self.mode {
            editor.selected = false;
        }
    }

    /// Moves the focus to the next (`Up`) or previous (`Down`) checked model, in the order of
    /// [`ForceModel::ALL`], wrapping around; the focus is always a checked model while any is.
    pub(crate) fn step_focus(&mut self, direction: Nudge) {
        let checked = self.checked_models();
        if checked.is_empty() {
            self.say(
                "no model checked: Space checks the model under the cursor",
                true,
            );
            return;
        }
        let i = model_index(self.focused);
        let next = match direction {
            Nudge::Up => checked
                .iter()
                .find(|m| model_index(**m) > i)
                .or(checked.first()),
            Nudge::Down => checked
                .iter()
                .rev()
                .find(|m| model_index(**m) < i)
                .or(checked.last()),
        };
        if let Some(&model) = next {
            self.focused = model;
        }
    }

    /// The cursor has landed on `model`: it takes the focus if checked (views 2–3 and the export
    /// follow the focus, and an unchecked model has nothing to show).
    pub(crate) fn cursor_on(&mut self, model: ForceModel) {
        if self.is_checked(model) {
            self.focused = model;
        }
    }

    /// The cursor stops, in order: the visible fields, then the models.
    pub fn rows(&self) -> Vec<Cursor> {
        field::all_fields(&self.draft)
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

    /// The field that shows the scene error's message: the one under the cursor when the error is
    /// about it (the shape just changed, the field being edited), else the first it names.
    pub fn error_note_field(&self) -> Option<Field> {
        let fields = self.error_fields();
        match self.cursor {
            Cursor::Field(field) if fields.contains(&field) => Some(field),
            Cursor::Field(field)
                if matches!(self.scene_error, Some(ModelError::UnsupportedPair(_))) =>
            {
                match field.section() {
                    Section::Body(index) => Some(Field::Shape(index)),
                    Section::Impact => fields.first().copied(),
                }
            }
            _ => fields.first().copied(),
        }
    }

    /// The body a material from the picker goes to by default: the one under the cursor.
    pub(super) fn cursor_body(&self) -> BodyIndex {
        match self.cursor {
            Cursor::Field(f) => match f.section() {
                Section::Body(index) => index,
                Section::Impact => BodyIndex::One,
            },
            Cursor::Model(_) => BodyIndex::One,
        }
    }

    pub(crate) fn say(&mut self, text: impl Into<String>, error: bool) {
        self.message = Some(Message {
            text: text.into(),
            error,
        });
    }

    /// Re-evaluates the estimate of the draft and requests the solves whose inputs changed.
    pub(crate) fn recompute(&mut self) {
        let start = Instant::now();
        // Named before it is copied: the valid scene's name and materials are those shown.
        super::edited::name_edited_materials(self);
        // A fitted scene's e follows v₀ as the data says (docs/fitting.md); an e typed over it
        // at the same v₀ is the user's, and the fit gives way (never lose an edit).
        if let Some(valid) = &self.valid
            && self.draft.scene.fit.is_some()
            && self.draft.scene.impact.v0 == valid.scene.impact.v0
            && self.draft.scene.impact.restitution != valid.scene.impact.restitution
        {
            self.draft.scene.fit = None;
            self.say("e edited: the scene's [fit] no longer sets e", false);
        }
        if let Err(e) = self.draft.scene.apply_fit() {
            self.say(format!("[fit]: e at this v0 not computed ({e})"), true);
        }
        match self.draft.scene.quasistatic() {
            Ok(quasistatic) => {
                self.scene_error = None;
                let params = self.draft.scene.impact_params(&quasistatic);
                let warnings = self
                    .draft
                    .scene
                    .pair()
                    .map(|pair| scene_warnings(&pair, &quasistatic))
                    .unwrap_or_default();
                // Named as shown: the engine panel and the studies read the valid scene's name.
                let mut scene = self.draft.scene.clone();
                scene.name = self.title().0;
                self.valid = Some(Valid {
                    scene,
                    quasistatic,
                    params,
                    warnings,
                    advice: OnceLock::new(),
                });
                if !self.request_solves(start) && !self.solutions.any_pending() {
                    // Only the estimate was recomputed.
                    self.last_recompute = Some(start.elapsed());
                }
            }
            Err(error) => self.scene_error = Some(error),
        }
        self.keep_cursor_on_a_row();
    }

    /// Queues the solves of checked models whose inputs changed; returns whether any was queued.
    pub(super) fn request_solves(&mut self, start: Instant) -> bool {
        let Some(valid) = &self.valid else {
            return false;
        };
        let params = valid.params;
        let fit = valid.scene.fit.clone();
        let mut queued = false;
        for model in self.checked_models() {
            let fitted = fit
                .as_ref()
                .filter(|f| f.kind == FittedKind::Law(model))
                .and_then(|f| f.damping_at(params.v0));
            let job = self.solutions.request_fitted(
                model,
                params,
                self.draft.options,
                self.calibrate,
                fitted,
            );
            if let Some(job) = job {
                self.outbox.push(job);
                queued = true;
            }
        }
        if queued {
            self.recompute_started = Some(start);
        }
        queued
    }

    /// After a shape change hides the field under the cursor, falls back to the body's shape.
    pub(super) fn keep_cursor_on_a_row(&mut self) {
        if let Cursor::Field(f) = self.cursor
            && !self.rows().contains(&self.cursor)
        {
            self.cursor = Cursor::Field(match (f, f.section()) {
                // The method changed between adaptive and fixed-step: its other setting.
                (Field::Rtol, _) => Field::Dt,
                (Field::Dt, _) => Field::Rtol,
                (_, Section::Body(index)) => Field::Shape(index),
                (_, Section::Impact) => Field::Number(SceneKey::V0),
            });
        }
    }

    pub(crate) fn move_cursor(&mut self, forward: bool) {
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
            self.cursor_on(model);
        }
    }

    /// `Home` `End` `PgUp` `PgDn`: the first or last row, or the first field of the previous or
    /// next section (the models count as the last section).
    pub(crate) fn jump_cursor(&mut self, jump: Jump) {
        let rows = self.rows();
        let section_of = |row: &Cursor| match row {
            Cursor::Field(f) => Some(f.section()),
            Cursor::Model(_) => None,
        };
        let starts: Vec<usize> = (0..rows.len())
            .filter(|&i| i == 0 || section_of(&rows[i]) != section_of(&rows[i - 1]))
            .collect();
        let here = rows.iter().position(|&r| r == self.cursor).unwrap_or(0);
        let current = starts.iter().rposition(|&s| s <= here).unwrap_or(0);
        let target = match jump {
            Jump::First => 0,
            Jump::Last => rows.len().saturating_sub(1),
            // From inside a section, PgUp goes to its own start first.
            Jump::PreviousSection if starts[current] < here => starts[current],
            Jump::PreviousSection => starts[current.saturating_sub(1)],
            Jump::NextSection => starts.get(current + 1).copied().unwrap_or(starts[current]),
        };
        self.cursor = rows[target];
        if let Cursor::Model(model) = self.cursor {
            self.cursor_on(model);
        }
    }

    /// Checks `model` (it takes the focus) or unchecks it (the focus, if it was there, goes to
    /// the next checked model).
    pub(crate) fn toggle(&mut self, model: ForceModel) {
        let i = model_index(model);
        self.checked[i] = !self.checked[i];
        if self.checked[i] {
            self.focused = model;
            // A cached result needs no solve, and then there is no recompute time to report.
            self.request_solves(Instant::now());
        } else if self.focused == model {
            self.step_focus(Nudge::Up);
        }
    }

    /// Calibration on or off: every checked law is solved again, and the status line says what the
    /// switch means.
    pub(super) fn toggle_calibration(&mut self) {
        self.calibrate = !self.calibrate;
        let text = if self.calibrate {
            "calibrated: each law's damping realises the scene's e (C: the laws' own rules)"
        } else {
            "each law's damping from e by its own rule (C: calibrate to realise e)"
        };
        self.say(text, false);
        self.request_solves(Instant::now());
    }
}
