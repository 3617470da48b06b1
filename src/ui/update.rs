//! `update(&mut App, Action)`: the transitions of the state machine, one function per mode.

use std::path::{Path, PathBuf};

use tui_input::{Input, InputRequest};

use crate::model::Scene;
use crate::model::presets::{Origin, Registry, SaveTarget, is_kebab_case, kebab_case};
use crate::model::scene_file::SceneView;
use crate::model::scene_key::BodyIndex;
use crate::model::study::runner::StudyOutcome;

use super::action::{Action, Jump};
use super::app::{App, Confirm, Cursor, Editor, Export, Mode, Prompt, PromptKind};
use super::edited;
use super::export;
use super::field::Nudge;
use super::figure_export;
use super::jobs::Report;
use super::mouse;
use super::picker::{EntryKind, Picker};
use super::solutions::Outcome;
use super::views;

/// Advances the state machine by one action.
pub fn update(app: &mut App, action: Action) {
    let before = app.draft.clone();
    let undoing = matches!(action, Action::Undo);
    transition(app, action);
    edited::name_edited_materials(app);
    if !undoing {
        app.remember_for_undo(before);
    }
    // Whatever changed, the shown tab asks for the studies it lacks (same inputs ask nothing).
    views::request_studies(app);
}

/// The terminal's new size: the sweep view sizes its sweeps by it, and the explorer's curves are
/// sampled for the charts it leaves room for.
fn resize(app: &mut App, width: u16, height: u16) {
    app.screen = (width, height);
    let area = ratatui::layout::Rect::new(0, 0, width, height);
    if let Some(dots) = views::explorer::layout::chart_dots(area, app.marker) {
        app.solutions.set_chart_dots(dots);
    }
}

fn transition(app: &mut App, action: Action) {
    match action {
        Action::Quit if matches!(app.mode, Mode::Normal) => quit_or_ask(app, false),
        Action::Interrupt => quit_or_ask(app, matches!(app.mode, Mode::Confirm(Confirm::Quit))),
        Action::Resize(width, height) => resize(app, width, height),
        Action::Solved(report) => solved(app, report),
        Action::Studied(report) => studied(app, report),
        Action::ToggleMouse => {
            app.mouse = !app.mouse;
            app.say(
                if app.mouse {
                    "mouse on: click and scroll (m: off, to select text)"
                } else {
                    "mouse off: the terminal selects text (m: on)"
                },
                false,
            );
        }
        action => {
            app.message = None;
            match std::mem::replace(&mut app.mode, Mode::Normal) {
                Mode::Normal => normal(app, action),
                Mode::Editing(editor) => editing(app, editor, action),
                Mode::Help => {
                    if !matches!(action, Action::Cancel | Action::Enter | Action::Quit) {
                        app.mode = Mode::Help;
                    }
                }
                Mode::Engine(mut panel) => {
                    match action {
                        Action::Export => {
                            if let Err(reason) = panel.write_to(Path::new(".")) {
                                panel.note = Some(reason);
                            }
                            app.mode = Mode::Engine(panel);
                        }
                        Action::Copy => {
                            app.clipboard = panel.copied();
                            app.mode = Mode::Engine(panel);
                        }
                        action => {
                            let scene = app.valid.as_ref().map(|v| &v.scene);
                            // The panel's text rows: the screen less its margins and borders.
                            let page = app.screen.1.saturating_sub(4);
                            if let Some(panel) = panel.update(action, scene, page) {
                                app.mode = Mode::Engine(panel);
                            }
                        }
                    }
                }
                Mode::Picker(picker) => picking(app, picker, action),
                Mode::Prompt(prompt) => prompting(app, prompt, action),
                Mode::Confirm(confirm) => confirming(app, confirm, action),
            }
        }
    }
}

/// Quits at once when nothing would be lost or `again` (the question was already asked); else asks.
fn quit_or_ask(app: &mut App, again: bool) {
    if again || !app.is_dirty() {
        app.quit = true;
    } else {
        app.mode = Mode::Confirm(Confirm::Quit);
    }
}

fn confirming(app: &mut App, confirm: Confirm, action: Action) {
    match (confirm, action) {
        (Confirm::Quit, Action::Yes) => app.quit = true,
        // Save, then quit: the save prompt says so, and Esc there stays.
        (Confirm::Quit, Action::Save) => open_save_prompt(app, true),
        (Confirm::ShadowBuiltin { name, then_quit }, Action::Yes) => {
            match save_preset(app, &name) {
                Ok(news) => {
                    app.say(
                        format!("{news} (it hides the built-in; delete the file to get it back)"),
                        false,
                    );
                    app.quit = then_quit;
                }
                Err(reason) => app.say(reason, true),
            }
        }
        (Confirm::Overwrite { path, export }, Action::Yes) => match export_to(app, export, &path) {
            Ok(news) => app.say(news, false),
            Err(reason) => app.say(reason, true),
        },
        // Anything else is a no: the question closes and nothing happens.
        _ => app.say("not done", false),
    }
}

fn solved(app: &mut App, report: Report<Outcome>) {
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

fn studied(app: &mut App, report: Report<StudyOutcome>) {
    match report {
        Ok(outcome) => {
            app.studies.accept(outcome);
        }
        // Only a panic of a study reports an error; the runtime ends the app on it.
        Err(message) => app.say(message, true),
    }
}

fn normal(app: &mut App, action: Action) {
    // Keys that act the same on every tab, wherever the pointer is.
    let action = match action {
        Action::Undo => return undo(app),
        Action::Click(column, row) => return mouse::click(app, column, row),
        Action::Wheel(column, row, direction) => return mouse::wheel(app, column, row, direction),
        action => action,
    };
    // The shown view takes its own keys; the rest is shared.
    let Some(action) = app.tab.view().handle(app, action) else {
        return;
    };
    match action {
        Action::Tab(tab) => app.tab = tab,
        Action::CycleView(direction) => app.tab = app.tab.cycle(direction),
        Action::ToggleModel => match app.cursor {
            Cursor::Model(model) => app.toggle(model),
            Cursor::Field(_) => app.toggle(app.focused),
        },
        Action::FocusModel(direction) => app.step_focus(direction),
        Action::ToggleCalibration => app.toggle_calibration(),
        Action::Help => app.mode = Mode::Help,
        Action::Engines => {
            let scene = app.valid.as_ref().map(|v| &v.scene);
            app.mode = Mode::Engine(super::engine_panel::EnginePanel::new(0, scene));
        }
        Action::Presets => {
            let mut picker = Picker::new(&app.registry);
            if let Some(preset) = &app.preset {
                picker.select(EntryKind::Scene, preset);
            }
            app.mode = Mode::Picker(picker);
        }
        Action::Save => open_save_prompt(app, false),
        Action::Open => {
            let fit = super::tab::Tab::named("fit").map_or("v".to_string(), |t| t.name());
            app.say(format!("o opens a data file in the fit view ({fit})"), true);
        }
        Action::Figure => match figure_export::write_view(app) {
            Ok(news) => app.say(news, false),
            Err(reason) => app.say(reason, true),
        },
        Action::Export => {
            let model = app.focused;
            if app.solutions.is_pending(model) {
                app.say(
                    format!("{} is being solved: export when it is done", model.label()),
                    true,
                );
            } else if app.solutions.solution(model).is_some() {
                let path = export::default_path(&app.file_stem(), model);
                app.mode = Mode::Prompt(Prompt {
                    kind: PromptKind::Export(Export::Trajectory(model)),
                    input: Input::new(path.display().to_string()),
                    error: None,
                    then_quit: false,
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
        Action::Paste(_) => app.say(
            "paste ignored: move to a field of the explorer (1) and paste there",
            true,
        ),
        // The keys of a view's form: no form here.
        Action::Up
        | Action::Down
        | Action::Jump(_)
        | Action::Nudge(_)
        | Action::ResetField
        | Action::Enter
        | Action::CycleChart
        | Action::MoveCursor { .. }
        | Action::CursorToPeak
        | Action::Branch
        | Action::Cancel
        | Action::Input(_)
        | Action::ApplyMaterialTo(_)
        | Action::Copy
        | Action::Quit
        | Action::Interrupt
        | Action::Yes
        | Action::Undo
        | Action::ToggleMouse
        | Action::Click(..)
        | Action::Wheel(..)
        | Action::Resize(..)
        | Action::Solved(_)
        | Action::Studied(_) => {}
    }
}

/// The save prompt, with the name `s` proposes; `then_quit`: the explorer quits once saved.
fn open_save_prompt(app: &mut App, then_quit: bool) {
    let suggestion = save_suggestion(app);
    app.mode = Mode::Prompt(Prompt {
        kind: PromptKind::Save,
        input: Input::new(suggestion),
        error: None,
        then_quit,
    });
}

fn undo(app: &mut App) {
    match app.undo.pop() {
        Some(draft) => {
            app.draft = draft;
            app.recompute();
            app.say(format!("undone ({} more)", app.undo.len()), false);
        }
        None => app.say("nothing to undo", true),
    }
}

/// The name `s` proposes: the user preset the scene came from, else a new name that hides no
/// built-in (`<preset>-edited`, `-edited-2`, …).
fn save_suggestion(app: &App) -> String {
    let base = match &app.preset {
        Some(preset) if !app.registry.is_builtin_scene(preset) => return preset.clone(),
        Some(preset) => preset.clone(),
        None if is_kebab_case(&app.draft.scene.name) => app.draft.scene.name.clone(),
        None => kebab_case(&app.draft.scene.name),
    };
    let base = if base.is_empty() {
        "scene".to_string()
    } else {
        base
    };
    (1..)
        .map(|n| match n {
            1 => format!("{base}-edited"),
            n => format!("{base}-edited-{n}"),
        })
        .find(|name| !app.registry.scenes().iter().any(|s| &s.name == name))
        .unwrap_or(base)
}

fn editing(app: &mut App, mut editor: Editor, action: Action) {
    match action {
        Action::Input(request) => {
            editor.handle(request);
            app.mode = Mode::Editing(editor);
        }
        Action::Paste(text) => {
            editor.paste(&text);
            app.mode = Mode::Editing(editor);
        }
        Action::Enter => {
            // An editor belongs to the view shown: no key changes the view while it is open.
            let committed = app
                .tab
                .view()
                .commit(app, editor.target, editor.input.value());
            if let Err(reason) = committed {
                editor.error = Some(reason);
                app.mode = Mode::Editing(editor);
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
        Action::Wheel(_, _, direction) => {
            picker.step(direction == Nudge::Down);
            app.mode = Mode::Picker(picker);
            return;
        }
        Action::Jump(jump) => {
            picker.jump(matches!(jump, Jump::Last | Jump::NextSection));
            app.mode = Mode::Picker(picker);
            return;
        }
        Action::Input(request) => {
            picker.edit_filter(request);
            app.mode = Mode::Picker(picker);
            return;
        }
        Action::Paste(text) => {
            for c in text.lines().next().unwrap_or_default().chars() {
                picker.edit_filter(InputRequest::InsertChar(c));
            }
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
        app.mode = Mode::Picker(picker);
        app.say("no preset matches the filter", true);
        return;
    };
    match entry.kind {
        EntryKind::Scene => match app.load_preset(&entry.name) {
            Ok(()) => app.say(format!("loaded scene {}", entry.name), false),
            Err(e) => app.say(e, true),
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

/// Types the first line of `text` into `input` at its cursor.
fn insert(input: &mut Input, text: &str) {
    for c in text.lines().next().unwrap_or_default().chars() {
        input.handle(InputRequest::InsertChar(c));
    }
}

fn prompting(app: &mut App, mut prompt: Prompt, action: Action) {
    match action {
        Action::Input(request) => {
            prompt.input.handle(request);
            app.mode = Mode::Prompt(prompt);
        }
        Action::Paste(text) => {
            insert(&mut prompt.input, &text);
            app.mode = Mode::Prompt(prompt);
        }
        Action::Enter => {
            let text = prompt.input.value().trim().to_string();
            let outcome = match prompt.kind {
                PromptKind::Save => save(app, &text, prompt.then_quit),
                PromptKind::Export(export) => export_asking(app, export, &text),
            };
            match outcome {
                Ok(Some(news)) => {
                    app.say(news, false);
                    app.quit = prompt.then_quit;
                }
                // A question took over the bottom line.
                Ok(None) => {}
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
pub(crate) fn expand_home(text: &str) -> PathBuf {
    match (text.strip_prefix("~/"), std::env::var_os("HOME")) {
        (Some(rest), Some(home)) => PathBuf::from(home).join(rest),
        _ => PathBuf::from(text),
    }
}

/// Saves the draft as a user preset (a kebab-case name) or to a path (with `/` or `.toml`);
/// a built-in's name asks first (`Ok(None)`).
fn save(app: &mut App, text: &str, then_quit: bool) -> Result<Option<String>, String> {
    if text.is_empty() {
        return Err("type a preset name or a path ending in .toml".into());
    }
    let is_path = text.contains(['/', '\\']) || text.ends_with(".toml");
    if is_path {
        let path = expand_home(text);
        let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or("scene");
        let stem = stem.to_string();
        return write_scene(app, &stem, SaveTarget::Path(&path)).map(Some);
    }
    if app.registry.is_builtin_scene(text) && !is_user_preset(app, text) {
        app.mode = Mode::Confirm(Confirm::ShadowBuiltin {
            name: text.to_string(),
            then_quit,
        });
        return Ok(None);
    }
    save_preset(app, text).map(Some)
}

/// Writes the user preset `name` (kebab-case), whatever it hides.
fn save_preset(app: &mut App, name: &str) -> Result<String, String> {
    write_scene(app, name, SaveTarget::UserPreset { name })
}

/// Writes the draft (named `name` if edited), its view, `[system]` table and description to
/// `target`; a user preset becomes the preset shown.
fn write_scene(app: &mut App, name: &str, target: SaveTarget<'_>) -> Result<String, String> {
    let scene = scene_to_save(app, name);
    let view = app.scene_view();
    let preset = matches!(target, SaveTarget::UserPreset { .. }).then_some(name);
    // An edited scene's description says what was edited, not the preset's "…on steel plate".
    let description = app.title().1;
    let system = app.draft.system;
    let written = app
        .registry
        .save_scene_with_view(
            &scene,
            description.as_deref(),
            &view,
            system.as_ref(),
            target,
        )
        .map_err(|e| e.to_string())?;
    app.description = description;
    saved(app, scene, view, preset);
    Ok(format!("saved {}", absolute(&written)))
}

/// Whether a user preset called `name` exists already (it already hides the built-in).
fn is_user_preset(app: &App, name: &str) -> bool {
    app.registry
        .scenes()
        .iter()
        .any(|s| s.name == name && matches!(s.origin, Origin::User(_)))
}

/// The draft, named after the file it goes to when it was edited: an edited Fig. 5 saved as
/// `my-impact` is no longer "Fig. 5: …".
fn scene_to_save(app: &App, name: &str) -> Scene {
    let mut scene = app.draft.scene.clone();
    if app.is_dirty() {
        scene.name = name.to_string();
    }
    scene
}

/// After a save: the saved scene is the reference for `*` and resets, the registry lists it.
fn saved(app: &mut App, scene: Scene, view: SceneView, preset: Option<&str>) {
    app.draft.scene.name = scene.name.clone();
    app.saved = scene;
    app.saved_view = view;
    app.saved_system = app.draft.system;
    if let Some(name) = preset {
        app.preset = Some(name.to_string());
    }
    if let Ok(registry) = Registry::load_from(app.registry.user_dir()) {
        app.registry = registry;
    }
}

/// `path` made absolute for messages (unchanged if the working folder cannot be read).
fn absolute(path: &Path) -> String {
    std::path::absolute(path)
        .unwrap_or_else(|_| path.to_path_buf())
        .display()
        .to_string()
}

/// Exports, asking first when the file exists (`Ok(None)`).
fn export_asking(app: &mut App, export: Export, text: &str) -> Result<Option<String>, String> {
    if text.is_empty() {
        return Err("type a file name".into());
    }
    let path = expand_home(text);
    if path.exists() {
        app.mode = Mode::Confirm(Confirm::Overwrite { path, export });
        return Ok(None);
    }
    export_to(app, export, &path).map(Some)
}

fn export_to(app: &App, export: Export, path: &Path) -> Result<String, String> {
    match export {
        Export::Trajectory(model) => {
            let solution = app
                .solutions
                .solution(model)
                .ok_or_else(|| format!("no solution of {} to export", model.label()))?;
            let rows = export::write(path, solution)?;
            Ok(format!(
                "exported {} ({rows} rows) to {}",
                model.name(),
                absolute(path)
            ))
        }
        Export::Sweep => {
            let Some(Ok(data)) = app.studies.sweep() else {
                return Err("no sweep to export: wait for it to be done".into());
            };
            let rows = export::write_sweep(path, data)?;
            Ok(format!(
                "exported the sweep of {} ({rows} rows) to {}",
                data.spec.key.path(),
                absolute(path)
            ))
        }
    }
}
