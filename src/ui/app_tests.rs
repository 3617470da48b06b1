//! The state machine driven by keys, without a terminal: key → action → state.

use ratatui::crossterm::event::{Event, KeyCode, KeyEvent, KeyModifiers};

use crate::model::presets::Registry;
use crate::model::scene_key::{BodyField, BodyIndex, SceneKey};
use crate::model::{ForceModel, ModelError};

use super::action::Action;
use super::app::{App, ChartKind, Cursor, Export, Mode, PromptKind};
use super::field::Field;
use super::keymap::action_for_event;
use super::picker::EntryKind;
use super::style::{MarkerStyle, Theme};
use super::testing::{fig5_scene, temp_path};
use super::update::update;
use super::worker;

const V0: Field = Field::Number(SceneKey::V0);

pub(super) fn app() -> App {
    App::new(
        fig5_scene(),
        Registry::builtin().unwrap(),
        MarkerStyle::Braille,
        Theme::Dark,
    )
}

/// Solves every queued job on this thread and feeds the outcomes back, as the worker would.
pub(super) use super::worker::settle;

pub(super) fn key_with(app: &mut App, code: KeyCode, modifiers: KeyModifiers) {
    let event = Event::Key(KeyEvent::new(code, modifiers));
    if let Some(action) = action_for_event(&app.mode, &event) {
        update(app, action);
    }
}

pub(super) fn key(app: &mut App, code: KeyCode) {
    key_with(app, code, KeyModifiers::NONE);
}

pub(super) fn type_text(app: &mut App, text: &str) {
    for c in text.chars() {
        key(app, KeyCode::Char(c));
    }
}

/// Replaces the text of the open editor or prompt by `text` and presses Enter.
pub(super) fn enter_text(app: &mut App, text: &str) {
    key_with(app, KeyCode::Char('u'), KeyModifiers::CONTROL);
    type_text(app, text);
    key(app, KeyCode::Enter);
}

fn queued_models(app: &mut App) -> Vec<ForceModel> {
    app.take_jobs().into_iter().map(|j| j.model).collect()
}

#[test]
fn opening_solves_the_checked_models_once() {
    let mut a = app();
    assert_eq!(
        queued_models(&mut a),
        [
            ForceModel::Quasistatic,
            ForceModel::Proposed,
            ForceModel::HuntCrossley,
            ForceModel::LankaraniNikravesh
        ]
    );
    assert!(a.is_computing());
    let mut b = app();
    settle(&mut b);
    assert!(!b.is_computing());
    for model in b.checked_models() {
        assert!(b.solutions.solution(model).is_some(), "{model}");
    }
    assert!(b.solutions.result(ForceModel::DryFriction).is_none());
    assert!(!b.is_dirty());
}

#[test]
fn arrows_and_tab_move_through_fields_then_models() {
    let mut a = app();
    assert_eq!(a.cursor, Cursor::Field(V0));
    key(&mut a, KeyCode::Down);
    assert_eq!(
        a.cursor,
        Cursor::Field(Field::Number(SceneKey::Restitution))
    );
    key(&mut a, KeyCode::BackTab);
    key(&mut a, KeyCode::Up);
    assert_eq!(
        a.cursor,
        Cursor::Field(Field::Number(SceneKey::Body(
            BodyIndex::Two,
            BodyField::Density
        )))
    );
    // Past the last impact field come the models; landing on one focuses it.
    for _ in 0..6 {
        key(&mut a, KeyCode::Tab);
    }
    assert_eq!(a.cursor, Cursor::Model(ForceModel::Quasistatic));
    assert_eq!(a.focused, ForceModel::Quasistatic);
    // Up from the first row wraps to the last.
    a.cursor = Cursor::Field(Field::Shape(BodyIndex::One));
    key(&mut a, KeyCode::Up);
    let last = ForceModel::ALL[ForceModel::ALL.len() - 1];
    assert_eq!(a.cursor, Cursor::Model(last));
}

#[test]
fn enter_edits_and_commits_with_units() {
    let mut a = app();
    settle(&mut a);
    key(&mut a, KeyCode::Enter);
    match &a.mode {
        Mode::Editing(editor) => assert_eq!(editor.input.value(), "0.3 m/s"),
        other => panic!("{other:?}"),
    }
    enter_text(&mut a, "500 mm/s");
    assert!(matches!(a.mode, Mode::Normal));
    assert_eq!(a.draft.scene.impact.v0, 0.5);
    assert!(a.is_dirty());
    assert_eq!(
        queued_models(&mut a).len(),
        4,
        "every checked model depends on v₀"
    );
    assert_eq!(a.valid.as_ref().map(|v| v.scene.impact.v0), Some(0.5));
}

#[test]
fn esc_cancels_an_edit() {
    let mut a = app();
    settle(&mut a);
    key(&mut a, KeyCode::Enter);
    type_text(&mut a, "9");
    key(&mut a, KeyCode::Esc);
    assert!(matches!(a.mode, Mode::Normal));
    assert_eq!(a.draft.scene.impact.v0, 0.3);
    assert!(a.take_jobs().is_empty());
    assert!(!a.is_dirty());
}

#[test]
fn unparsable_text_stays_in_the_editor_with_the_reason() {
    let mut a = app();
    settle(&mut a);
    key(&mut a, KeyCode::Enter);
    enter_text(&mut a, "fast");
    match &a.mode {
        Mode::Editing(editor) => {
            assert_eq!(editor.error.as_deref(), Some("'fast' is not a number"));
        }
        other => panic!("{other:?}"),
    }
    assert_eq!(a.draft.scene.impact.v0, 0.3);
    assert!(a.take_jobs().is_empty());
    // Fixing the text commits.
    enter_text(&mut a, "0.2");
    assert!(matches!(a.mode, Mode::Normal));
    assert_eq!(a.draft.scene.impact.v0, 0.2);
}

#[test]
fn a_bad_rtol_is_refused_in_the_field_with_the_reason_and_the_results_stay() {
    let mut a = app();
    settle(&mut a);
    a.cursor = Cursor::Field(Field::Rtol);
    for bad in ["0", "-1e-6", "1", "2"] {
        key(&mut a, KeyCode::Enter);
        enter_text(&mut a, bad);
        match &a.mode {
            Mode::Editing(editor) => {
                let error = editor.error.as_deref().unwrap_or_default();
                assert!(
                    error.starts_with("rtol must be > 0 and < 1"),
                    "{bad}: {error}"
                );
            }
            other => panic!("{bad}: {other:?}"),
        }
        assert_eq!(a.draft.options.rtol, 1e-8);
        assert!(a.take_jobs().is_empty());
        assert!(a.solutions.solution(ForceModel::Proposed).is_some());
        key(&mut a, KeyCode::Esc);
        // ← after the refusal steps down from the last valid rtol, never up.
        key(&mut a, KeyCode::Left);
        assert_eq!(a.draft.options.rtol, 1e-9, "{bad}");
        key(&mut a, KeyCode::Right);
        settle(&mut a);
    }
}

#[test]
fn an_invalid_value_turns_its_field_red_and_the_last_results_stay() {
    let mut a = app();
    settle(&mut a);
    let nu = Field::Number(SceneKey::Body(BodyIndex::One, BodyField::PoissonRatio));
    a.cursor = Cursor::Field(nu);
    key(&mut a, KeyCode::Enter);
    enter_text(&mut a, "0.6");
    assert_eq!(a.draft.scene.body1.material.poisson_ratio, 0.6);
    let message = a.scene_error.as_ref().map(ToString::to_string);
    assert_eq!(
        message.as_deref(),
        Some("body1.material.poisson_ratio must be in [0, 0.5), got 0.6")
    );
    assert_eq!(a.error_fields(), [nu]);
    assert!(a.take_jobs().is_empty(), "an invalid scene solves nothing");
    assert_eq!(
        a.valid
            .as_ref()
            .map(|v| v.scene.body1.material.poisson_ratio),
        Some(0.3)
    );
    assert!(a.solutions.solution(ForceModel::Proposed).is_some());
    // Nudging back down makes it valid again; the physics did not change, so nothing is solved.
    for _ in 0..10 {
        key(&mut a, KeyCode::Left);
    }
    assert!((a.draft.scene.body1.material.poisson_ratio - 0.5).abs() < 1e-12);
    assert!(a.scene_error.is_some(), "0.5 is still outside [0, 0.5)");
    key(&mut a, KeyCode::Left);
    assert!(a.scene_error.is_none());
    assert_eq!(queued_models(&mut a).len(), 4, "ν = 0.49 is a new scene");
}

#[test]
fn nudges_step_values_and_cycle_choices() {
    let mut a = app();
    settle(&mut a);
    key(&mut a, KeyCode::Right);
    assert_eq!(a.draft.scene.impact.v0, 0.31);
    key(&mut a, KeyCode::Char('-'));
    key(&mut a, KeyCode::Char('-'));
    assert_eq!(a.draft.scene.impact.v0, 0.29);
    a.take_jobs();
    a.cursor = Cursor::Field(Field::Method);
    key(&mut a, KeyCode::Char('+'));
    assert_eq!(a.draft.options.method.to_string(), "euler");
    assert_eq!(queued_models(&mut a).len(), 4, "a new method re-solves");
}

#[test]
fn view_changes_solve_nothing() {
    let mut a = app();
    settle(&mut a);
    for code in [
        KeyCode::Char(']'),
        KeyCode::Char('['),
        KeyCode::Char('c'),
        KeyCode::Down,
        KeyCode::Up,
        KeyCode::Char('?'),
        KeyCode::Esc,
    ] {
        key(&mut a, code);
    }
    assert_eq!(a.views.explorer.chart, ChartKind::VelocityDisplacement);
    assert!(a.take_jobs().is_empty());
    // Re-entering the same value solves nothing either.
    key(&mut a, KeyCode::Enter);
    key(&mut a, KeyCode::Enter);
    assert!(a.take_jobs().is_empty());
}

#[test]
fn checking_a_model_solves_only_that_model() {
    let mut a = app();
    settle(&mut a);
    a.cursor = Cursor::Model(ForceModel::DryFriction);
    key(&mut a, KeyCode::Char(' '));
    assert!(a.is_checked(ForceModel::DryFriction));
    assert_eq!(queued_models(&mut a), [ForceModel::DryFriction]);
    key(&mut a, KeyCode::Enter);
    assert!(!a.is_checked(ForceModel::DryFriction));
    assert!(a.take_jobs().is_empty());
    // Checking it again asks for nothing new: the same inputs are already being solved.
    key(&mut a, KeyCode::Char(' '));
    assert!(a.is_checked(ForceModel::DryFriction));
    assert!(a.take_jobs().is_empty());
}

#[test]
fn outcomes_of_superseded_requests_are_dropped() {
    let mut a = app();
    settle(&mut a);
    key(&mut a, KeyCode::Right);
    let first = a.take_jobs();
    key(&mut a, KeyCode::Right);
    let second = a.take_jobs();
    for job in &first {
        update(&mut a, Action::Solved(Ok(worker::solve(job))));
    }
    assert!(
        a.is_computing(),
        "stale outcomes do not finish the recompute"
    );
    let old = a
        .solutions
        .solution(ForceModel::Proposed)
        .map(|s| s.summary.x_max);
    for job in &second {
        update(&mut a, Action::Solved(Ok(worker::solve(job))));
    }
    assert!(!a.is_computing());
    let new = a
        .solutions
        .solution(ForceModel::Proposed)
        .map(|s| s.summary.x_max);
    assert!(
        new > old,
        "v₀ 0.32 goes deeper than 0.3: {new:?} vs {old:?}"
    );
}

#[test]
fn presets_load_scenes_and_apply_materials_to_either_body() {
    let mut a = app();
    settle(&mut a);
    key(&mut a, KeyCode::Char('p'));
    let Mode::Picker(picker) = &mut a.mode else {
        panic!("{:?}", a.mode)
    };
    picker.select(EntryKind::Material, "aluminium-alloy");
    key(&mut a, KeyCode::Char('2'));
    assert!(matches!(a.mode, Mode::Normal));
    assert_eq!(a.draft.scene.body2.material.name, "aluminium-alloy");
    assert_eq!(a.draft.scene.body1.material.name, "steel");
    assert_eq!(queued_models(&mut a).len(), 4);
    key(&mut a, KeyCode::Char('p'));
    let Mode::Picker(picker) = &mut a.mode else {
        panic!("{:?}", a.mode)
    };
    picker.select(EntryKind::Scene, "steel-sphere-r5-plate");
    key(&mut a, KeyCode::Enter);
    assert_eq!(
        a.draft.scene,
        Registry::builtin()
            .unwrap()
            .scene("steel-sphere-r5-plate")
            .unwrap()
    );
    assert!(!a.is_dirty());
    assert!(a.message.as_ref().is_some_and(|m| !m.error));
    // Esc closes the picker without loading anything.
    key(&mut a, KeyCode::Char('p'));
    key(&mut a, KeyCode::Esc);
    assert!(matches!(a.mode, Mode::Normal));
}

#[test]
fn save_writes_the_scene_to_a_path_and_clears_the_unsaved_mark() {
    let mut a = app();
    settle(&mut a);
    key(&mut a, KeyCode::Right);
    assert!(a.is_dirty());
    key(&mut a, KeyCode::Char('s'));
    assert!(matches!(&a.mode, Mode::Prompt(p) if p.kind == PromptKind::Save));
    let path = temp_path("saved.toml");
    enter_text(&mut a, &path.display().to_string());
    assert!(matches!(a.mode, Mode::Normal), "{:?}", a.message);
    assert!(!a.is_dirty());
    let reloaded = a.registry.scene(&path.display().to_string()).unwrap();
    assert_eq!(reloaded.impact.v0, 0.31);
    // A bad target keeps the prompt open with the reason.
    key(&mut a, KeyCode::Char('s'));
    enter_text(&mut a, "Not A Name");
    match &a.mode {
        Mode::Prompt(p) => assert!(p.error.as_deref().unwrap().contains("kebab-case")),
        other => panic!("{other:?}"),
    }
}

#[test]
fn export_writes_the_focused_trajectory_as_csv() {
    let mut a = app();
    settle(&mut a);
    key(&mut a, KeyCode::Char('e'));
    match &a.mode {
        Mode::Prompt(p) => {
            assert_eq!(
                p.kind,
                PromptKind::Export(Export::Trajectory(ForceModel::Proposed))
            );
            assert!(p.input.value().ends_with("-proposed.csv"));
        }
        other => panic!("{other:?}"),
    }
    let path = temp_path("proposed.csv");
    enter_text(&mut a, &path.display().to_string());
    let text = std::fs::read_to_string(&path).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("t,x,v,F"),
        "the header `solve --format csv` prints"
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert!(rows.len() >= 1000);
    let f_max = rows.iter().map(|r| r[3]).fold(f64::MIN, f64::max);
    let summary = &a.solutions.solution(ForceModel::Proposed).unwrap().summary;
    assert_eq!(f_max, summary.f_max, "the true peak is among the rows");
    // A model being solved exports nothing until its solve is done.
    key(&mut a, KeyCode::Right);
    key(&mut a, KeyCode::Char('e'));
    assert!(matches!(a.mode, Mode::Normal));
    assert!(
        a.message
            .as_ref()
            .is_some_and(|m| m.text.contains("being solved"))
    );
    settle(&mut a);
    key(&mut a, KeyCode::Char('e'));
    assert!(matches!(a.mode, Mode::Prompt(_)));
    key(&mut a, KeyCode::Esc);
    // An unchecked model has nothing to export.
    a.focused = ForceModel::DryFriction;
    key(&mut a, KeyCode::Char('e'));
    assert!(matches!(a.mode, Mode::Normal));
    assert!(a.message.as_ref().is_some_and(|m| m.error));
}

#[test]
fn q_quits_except_while_typing_and_ctrl_c_always_quits() {
    let mut a = app();
    key(&mut a, KeyCode::Enter);
    key(&mut a, KeyCode::Char('q'));
    assert!(!a.quit);
    match &a.mode {
        Mode::Editing(editor) => assert!(editor.input.value().ends_with('q')),
        other => panic!("{other:?}"),
    }
    key_with(&mut a, KeyCode::Char('c'), KeyModifiers::CONTROL);
    assert!(a.quit);
    let mut b = app();
    key(&mut b, KeyCode::Char('q'));
    assert!(b.quit);
}

#[test]
fn help_opens_and_closes() {
    let mut a = app();
    key(&mut a, KeyCode::Char('?'));
    assert!(matches!(a.mode, Mode::Help));
    key(&mut a, KeyCode::Char('x'));
    assert!(matches!(a.mode, Mode::Help), "other keys keep it open");
    key(&mut a, KeyCode::Char('q'));
    assert!(matches!(a.mode, Mode::Normal));
    assert!(!a.quit, "q closes the help first");
}

#[test]
fn shapes_change_the_rows_and_plane_on_plane_is_refused() {
    let mut a = app();
    settle(&mut a);
    let radius = Field::Number(SceneKey::Body(BodyIndex::One, BodyField::Radius));
    a.cursor = Cursor::Field(Field::Shape(BodyIndex::One));
    key(&mut a, KeyCode::Enter);
    enter_text(&mut a, "plane");
    // plane–plane has no contact law: both shapes are marked and nothing is solved.
    assert_eq!(
        a.error_fields(),
        [Field::Shape(BodyIndex::One), Field::Shape(BodyIndex::Two)]
    );
    assert_eq!(a.error_note_field(), Some(Field::Shape(BodyIndex::One)));
    assert!(!a.rows().contains(&Cursor::Field(radius)));
    assert!(a.take_jobs().is_empty());
    key(&mut a, KeyCode::Left);
    assert_eq!(a.draft.scene.body1.shape.name(), "cylinder");
    assert!(a.rows().contains(&Cursor::Field(radius)));
}

#[test]
fn an_unsupported_pair_is_reported_on_the_body_whose_shape_changed() {
    let mut a = app();
    settle(&mut a);
    a.cursor = Cursor::Field(Field::Shape(BodyIndex::Two));
    key(&mut a, KeyCode::Enter);
    enter_text(&mut a, "cylinder");
    // sphere–cylinder: the message goes under body 2's shape, the one just edited.
    assert!(matches!(
        a.scene_error,
        Some(ModelError::UnsupportedPair(_))
    ));
    assert_eq!(a.error_note_field(), Some(Field::Shape(BodyIndex::Two)));
    let radius2 = Field::Number(SceneKey::Body(BodyIndex::Two, BodyField::Radius));
    if a.rows().contains(&Cursor::Field(radius2)) {
        a.cursor = Cursor::Field(radius2);
        assert_eq!(a.error_note_field(), Some(Field::Shape(BodyIndex::Two)));
    }
}

#[test]
fn saving_as_a_user_preset_lists_it_in_the_picker() {
    let dir = temp_path("presets");
    let registry = Registry::load_from(Some(&dir)).unwrap();
    let scene = registry
        .scene(crate::model::presets::DEFAULT_SCENE)
        .unwrap();
    let mut a = App::new(scene, registry, MarkerStyle::Braille, Theme::Dark);
    assert_eq!(
        a.preset.as_deref(),
        Some(crate::model::presets::DEFAULT_SCENE)
    );
    key(&mut a, KeyCode::Char('s'));
    match &a.mode {
        // A new name by default: saving never hides the built-in without asking.
        Mode::Prompt(p) => assert_eq!(
            p.input.value(),
            format!("{}-edited", crate::model::presets::DEFAULT_SCENE)
        ),
        other => panic!("{other:?}"),
    }
    enter_text(&mut a, "my-fig5");
    assert!(matches!(a.mode, Mode::Normal), "{:?}", a.message);
    assert!(dir.join("scenes/my-fig5.toml").is_file());
    assert_eq!(a.preset.as_deref(), Some("my-fig5"));
    key(&mut a, KeyCode::Char('p'));
    let Mode::Picker(picker) = &a.mode else {
        panic!("{:?}", a.mode)
    };
    let selected = picker.selected().unwrap();
    assert_eq!(
        (selected.name.as_str(), selected.origin.as_str()),
        ("my-fig5", "user")
    );
}

#[test]
fn a_fixed_step_method_shows_a_dt_row_whose_step_reaches_the_solver() {
    let mut a = app();
    settle(&mut a);
    assert!(a.rows().contains(&Cursor::Field(Field::Rtol)));
    assert!(!a.rows().contains(&Cursor::Field(Field::Dt)));
    a.cursor = Cursor::Field(Field::Method);
    key(&mut a, KeyCode::Enter);
    enter_text(&mut a, "euler");
    assert!(a.rows().contains(&Cursor::Field(Field::Dt)));
    assert!(!a.rows().contains(&Cursor::Field(Field::Rtol)));
    // `auto`: the solver's own step.
    let jobs = a.take_jobs();
    assert!(!jobs.is_empty());
    assert!(jobs.iter().all(|j| j.options.dt.is_none()));
    for job in jobs {
        update(&mut a, Action::Solved(Ok(worker::solve(&job))));
    }
    settle(&mut a);
    let fine = a
        .solutions
        .solution(ForceModel::Proposed)
        .unwrap()
        .summary
        .f_max;
    assert_eq!(Field::Dt.display(&a.draft), "auto");
    // A coarse step, typed with its unit.
    a.cursor = Cursor::Field(Field::Dt);
    key(&mut a, KeyCode::Enter);
    enter_text(&mut a, "2 µs");
    assert!(matches!(a.mode, Mode::Normal));
    assert_eq!(Field::Dt.display(&a.draft), "2 µs");
    let jobs = a.take_jobs();
    assert!(!jobs.is_empty());
    assert!(jobs.iter().all(|j| j.options.dt == Some(2e-6)));
    for job in jobs {
        update(&mut a, Action::Solved(Ok(worker::solve(&job))));
    }
    let coarse = a
        .solutions
        .solution(ForceModel::Proposed)
        .unwrap()
        .summary
        .f_max;
    assert!(
        (coarse / fine - 1.0).abs() > 1e-3,
        "a coarse step changes the results: {coarse} vs {fine}"
    );
    // → doubles, ← halves.
    key(&mut a, KeyCode::Right);
    assert_eq!(a.draft.options.dt, Some(4e-6));
    key(&mut a, KeyCode::Left);
    key(&mut a, KeyCode::Left);
    assert_eq!(a.draft.options.dt, Some(1e-6));
    // From `auto`, the nudge starts at the solver's own step.
    key(&mut a, KeyCode::Enter);
    enter_text(&mut a, "auto");
    assert_eq!(a.draft.options.dt, None);
    let auto = a.auto_dt().unwrap();
    key(&mut a, KeyCode::Right);
    assert_eq!(a.draft.options.dt, Some(auto * 2.0));
    // Back to an adaptive method: the rtol row returns in place of the step.
    a.cursor = Cursor::Field(Field::Method);
    key(&mut a, KeyCode::Enter);
    enter_text(&mut a, "dopri5");
    assert!(a.rows().contains(&Cursor::Field(Field::Rtol)));
    assert!(!a.rows().contains(&Cursor::Field(Field::Dt)));
}

#[test]
fn a_bad_dt_is_refused_in_the_field_with_the_reason_and_the_results_stay() {
    let mut a = app();
    a.draft.options.method =
        crate::model::impact::MethodChoice::Integrator(crate::model::ode::Method::Rk4);
    a.recompute();
    settle(&mut a);
    a.cursor = Cursor::Field(Field::Dt);
    for bad in ["0", "-1 µs", "0 s"] {
        key(&mut a, KeyCode::Enter);
        enter_text(&mut a, bad);
        match &a.mode {
            Mode::Editing(editor) => {
                let error = editor.error.as_deref().unwrap_or_default();
                assert!(
                    error.starts_with("dt must be > 0 and finite"),
                    "{bad}: {error}"
                );
            }
            other => panic!("{bad}: {other:?}"),
        }
        assert_eq!(a.draft.options.dt, None);
        assert!(a.take_jobs().is_empty());
        assert!(a.solutions.solution(ForceModel::Proposed).is_some());
        key(&mut a, KeyCode::Esc);
    }
    for bad in ["fast", "inf", "nan"] {
        key(&mut a, KeyCode::Enter);
        enter_text(&mut a, bad);
        assert!(matches!(a.mode, Mode::Editing(_)), "{bad} is refused");
        assert_eq!(a.draft.options.dt, None);
        key(&mut a, KeyCode::Esc);
    }
}

#[test]
fn shift_c_calibrates_every_checked_law_and_says_so() {
    let mut a = app();
    let before = a.take_jobs();
    assert!(before.iter().all(|j| !j.calibrate));
    key(&mut a, KeyCode::Char('C'));
    assert!(a.calibrate);
    let jobs = a.take_jobs();
    assert_eq!(
        jobs.len(),
        a.checked_models().len(),
        "every checked law again"
    );
    assert!(jobs.iter().all(|j| j.calibrate));
    let message = a
        .message
        .as_ref()
        .map(|m| m.text.clone())
        .unwrap_or_default();
    assert!(message.contains("calibrated"), "{message}");
    // The worker hits the scene's e with the calibrated law.
    let proposed = jobs
        .iter()
        .find(|j| j.model == ForceModel::Proposed)
        .unwrap();
    let outcome = crate::ui::worker::solve(proposed);
    let e_out = outcome.result.unwrap().summary.e_out;
    assert!(
        (e_out / proposed.params.restitution - 1.0).abs() < 1e-6,
        "{e_out}"
    );
    key(&mut a, KeyCode::Char('C'));
    assert!(!a.calibrate);
    assert!(a.take_jobs().iter().all(|j| !j.calibrate));
}

/// A scene with a `[fit]`: e follows v₀ by the fitted law (χ = a·v₀), the fitted law is solved
/// with its constant, and an e typed over the fit is the user's (the fit gives way).
#[test]
fn a_fitted_scene_moves_e_with_v0_and_solves_its_law_with_its_constant() {
    use crate::model::calibrate::hunt_crossley_restitution;
    use crate::model::fit::Candidate;
    use crate::model::scene_fit::FittedLaw;

    let a_fit = 2.0;
    let mut scene = fig5_scene();
    scene.fit = Some(FittedLaw::new(
        Candidate::Law(ForceModel::HuntCrossley),
        a_fit,
    ));
    scene.apply_fit().unwrap();
    let mut a = App::new(
        scene,
        Registry::builtin().unwrap(),
        MarkerStyle::Braille,
        Theme::Dark,
    );
    settle(&mut a);
    let e_at = |v0: f64| hunt_crossley_restitution(a_fit * v0);
    assert!((a.draft.scene.impact.restitution - e_at(0.3)).abs() < 1e-12);
    key(&mut a, KeyCode::Right);
    assert_eq!(a.draft.scene.impact.v0, 0.31);
    assert!((a.draft.scene.impact.restitution - e_at(0.31)).abs() < 1e-12);
    settle(&mut a);
    let hc = a.solutions.solution(ForceModel::HuntCrossley).unwrap();
    assert!(
        (hc.summary.e_out - e_at(0.31)).abs() < 1e-6,
        "the fitted law at its constant"
    );
    // Typing e over the fit: the fit gives way and the typed e stays.
    a.draft.scene.impact.restitution = 0.5;
    a.recompute();
    assert!(a.draft.scene.fit.is_none());
    assert_eq!(a.draft.scene.impact.restitution, 0.5);
}
