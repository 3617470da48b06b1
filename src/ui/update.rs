//! `update(&mut App, Action)`: the transitions of the state machine, one function per mode.

use std::path::PathBuf;

use tui_input::Input;

use crate::model::ForceModel;
use crate::model::presets::{Registry, SaveTarget, is_kebab_case, kebab_case};
use crate::model::scene_key::BodyIndex;

use super::action::Action;
use super::app::{App, Cursor, EditTarget, Editor, Mode, Prompt, PromptKind, model_index};
use super::data_cursor;
use super::export;
use super::field::{Field, Nudge};
use super::figure_export;
use super::picker::{EntryKind, Picker};
use super::study_worker::StudyReport;
use super::tab::Tab;
use super::update_tabs;
use super::worker::Report;

/// Advances the state machine by one action.
pub fn update(app: &mut App, action: Action) {
    transition(app, action);
    // Whatever changed, the shown tab asks for the studies it lacks (same inputs ask nothing).
    app.request_studies();
}

fn transition(app: &mut App, action: Action) {
    match action {
        Action::Quit => app.quit = true,
        Action::Resize(width, height) => app.screen = (width, height),
        Action::Solved(report) => solved(app, report),
        Action::Studied(report) => studied(app, report),
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

fn solved(app: &mut App, report: Report) {
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

fn studied(app: &mut App, report: StudyReport) {
    match report {
        Ok(outcome) => {
            app.studies.accept(outcome);
        }
        // Only a panic of a study reports an error; the runtime ends the app on it.
        Err(message) => app.say(message, true),
    }
}

fn normal(app: &mut App, action: Action) {
    let action = match app.tab {
        Tab::Explorer => action,
        // The study tabs take the keys that act on their own settings; the rest is shared.
        _ => match update_tabs::study_tab(app, action) {
            Some(action) => action,
            None => return,
        },
    };
    match action {
        Action::Tab(tab) => app.tab = tab,
        Action::Up => app.move_cursor(false),
        Action::Down => app.move_cursor(true),
        Action::Nudge(direction) => match app.cursor {
            Cursor::Field(field) => {
                if field == Field::Dt && app.draft.options.dt.is_none() {
                    // ←/→ from `auto` halve/double the solver's own step.
                    app.draft.options.dt = app.auto_dt();
                }
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
                    target: EditTarget::Field(field),
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
        Action::MoveCursor(forward) => {
            app.data_cursor = Some(data_cursor::moved(app.data_cursor, forward));
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
        Action::Cancel => app.data_cursor = None,
        Action::Input(_)
        | Action::ApplyMaterialTo(_)
        | Action::Quit
        | Action::Resize(..)
        | Action::Solved(_)
        | Action::Studied(_) => {}
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
            let committed = match editor.target {
                EditTarget::Field(field) => {
                    let mut draft = app.draft.clone();
                    field.apply(editor.input.value(), &mut draft).map(|()| {
                        app.draft = draft;
                        app.recompute();
                    })
                }
                target => update_tabs::commit(app, target, editor.input.value()),
            };
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
    let rows = export::write(&path, solution)?;
    Ok(format!(
        "exported {} ({rows} rows) to {}",
        model.name(),
        path.display()
    ))
}
