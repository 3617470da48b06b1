//! The state machine of the tabs and the study settings, driven by keys without a terminal: which
//! studies each tab requests, and when it requests them again.

use ratatui::crossterm::event::{Event, KeyCode, KeyEvent, KeyModifiers};

use crate::chart::work_precision::Cost;
use crate::model::ForceModel;
use crate::model::ode::Method;
use crate::model::presets::Registry;
use crate::model::scene_key::SceneKey;
use crate::model::study::runner::{StudyKind, StudySpec};
use crate::model::study::stability::critical_step;

use super::action::Action;
use super::app::{App, Cursor, Mode};
use super::field::Field;
use super::keymap::action_for_event;
use super::style::{MarkerStyle, Theme};
use super::tab::Tab;
use super::testing::fig5_scene;
use super::update::update;
use super::views;
use super::views::sweep::settings::SweepField;

fn app() -> App {
    let mut app = App::new(
        fig5_scene(),
        Registry::builtin().unwrap(),
        MarkerStyle::Braille,
        Theme::Dark,
    );
    app.take_jobs();
    app
}

fn key_with(app: &mut App, code: KeyCode, modifiers: KeyModifiers) {
    let event = Event::Key(KeyEvent::new(code, modifiers));
    if let Some(action) = action_for_event(&app.mode, &event) {
        update(app, action);
    }
}

fn key(app: &mut App, code: KeyCode) {
    key_with(app, code, KeyModifiers::NONE);
}

fn enter_text(app: &mut App, text: &str) {
    key_with(app, KeyCode::Char('u'), KeyModifiers::CONTROL);
    for c in text.chars() {
        key(app, KeyCode::Char(c));
    }
    key(app, KeyCode::Enter);
}

fn kinds(app: &mut App) -> Vec<StudyKind> {
    app.take_studies()
        .into_iter()
        .map(|j| j.spec.kind())
        .collect()
}

fn rk4_critical(app: &App) -> f64 {
    critical_step(Method::Rk4, &app.valid.as_ref().unwrap().params).unwrap()
}

#[test]
fn digits_switch_tabs_and_each_tab_asks_only_for_its_studies() {
    let mut a = app();
    assert_eq!(a.tab, Tab::HOME);
    assert!(kinds(&mut a).is_empty(), "the explorer studies nothing");
    key(&mut a, KeyCode::Char('2'));
    assert_eq!(a.tab, Tab::named("work-precision").unwrap());
    assert_eq!(
        kinds(&mut a),
        [StudyKind::WorkPrecision, StudyKind::Current]
    );
    assert!(views::is_studying(&a));
    key(&mut a, KeyCode::Char('3'));
    assert_eq!(kinds(&mut a), [StudyKind::Runs, StudyKind::Bounds]);
    key(&mut a, KeyCode::Char('4'));
    assert_eq!(kinds(&mut a), [StudyKind::Sweep]);
    // Back to a tab whose inputs did not change: nothing is computed again.
    key(&mut a, KeyCode::Char('2'));
    key(&mut a, KeyCode::Char('1'));
    assert!(kinds(&mut a).is_empty());
    assert_eq!(a.tab, Tab::HOME);
    assert!(!views::is_studying(&a), "the explorer shows no study");
}

#[test]
fn c_switches_the_chart_of_the_shown_tab_only() {
    let mut a = app();
    let chart = a.views.explorer.chart;
    key(&mut a, KeyCode::Char('2'));
    assert_eq!(a.views.work_precision.cost, Cost::Seconds);
    key(&mut a, KeyCode::Char('c'));
    assert_eq!(a.views.work_precision.cost, Cost::ForceEvals);
    assert_eq!(a.views.explorer.chart, chart, "the explorer's chart stays");
    key(&mut a, KeyCode::Char('1'));
    key(&mut a, KeyCode::Char('c'));
    assert_ne!(a.views.explorer.chart, chart);
    assert_eq!(a.views.work_precision.cost, Cost::ForceEvals);
}

#[test]
fn scene_edits_elsewhere_study_nothing_until_the_tab_opens() {
    let mut a = app();
    key(&mut a, KeyCode::Char('2'));
    a.take_studies();
    key(&mut a, KeyCode::Char('1'));
    // v₀ up twice on the explorer: new solves, no study.
    key(&mut a, KeyCode::Right);
    key(&mut a, KeyCode::Right);
    assert!(kinds(&mut a).is_empty());
    assert!(!a.take_jobs().is_empty());
    key(&mut a, KeyCode::Char('2'));
    let jobs = a.take_studies();
    assert_eq!(jobs.len(), 2);
    match &jobs[0].spec {
        StudySpec::WorkPrecision { model, params } => {
            assert_eq!(*model, ForceModel::Proposed);
            assert_eq!(params.v0, 0.32);
        }
        other => panic!("{other:?}"),
    }
    // A new focus is a new model to measure; a rtol change moves only the explorer's point.
    // `]` walks the checked models only: the next one after the proposed model in table order.
    key(&mut a, KeyCode::Char(']'));
    let next_checked = a
        .checked_models()
        .into_iter()
        .find(|m| m.index() > ForceModel::Proposed.index());
    assert_eq!(Some(a.focused), next_checked);
    assert_eq!(
        kinds(&mut a),
        [StudyKind::WorkPrecision, StudyKind::Current]
    );
    key(&mut a, KeyCode::Char('1'));
    a.cursor = Cursor::Field(Field::Rtol);
    key(&mut a, KeyCode::Right);
    assert_eq!(a.draft.options.rtol, 1e-7);
    key(&mut a, KeyCode::Char('2'));
    assert_eq!(kinds(&mut a), [StudyKind::Current]);
}

#[test]
fn the_stability_step_defaults_to_rk4_critical_and_halves_doubles_and_types() {
    let mut a = app();
    key(&mut a, KeyCode::Char('3'));
    a.take_studies();
    let critical = rk4_critical(&a);
    assert_eq!(views::stability::step(&a), Some(critical));
    key(&mut a, KeyCode::Left);
    assert_eq!(views::stability::step(&a), Some(critical / 2.0));
    // A new step runs the methods again; the measured bounds do not depend on it.
    assert_eq!(kinds(&mut a), [StudyKind::Runs]);
    key(&mut a, KeyCode::Right);
    key(&mut a, KeyCode::Right);
    assert_eq!(views::stability::step(&a), Some(critical * 2.0));
    key(&mut a, KeyCode::Enter);
    assert!(matches!(&a.mode, Mode::Editing(e) if e.target == views::stability::STEP_EDITOR));
    enter_text(&mut a, "2 µs");
    assert!(matches!(a.mode, Mode::Normal));
    assert_eq!(a.views.stability.step, Some(2e-6));
    // Three steps were asked for since: ×2, ×2 and 2 µs; the last is the one that counts.
    let jobs = a.take_studies();
    assert_eq!(jobs.len(), 3);
    match &jobs[2].spec {
        StudySpec::Runs { dt, .. } => assert_eq!(*dt, 2e-6),
        other => panic!("{other:?}"),
    }
    // Refused text keeps the editor open with the reason; `auto` returns to the default.
    key(&mut a, KeyCode::Enter);
    enter_text(&mut a, "-1 s");
    match &a.mode {
        Mode::Editing(e) => assert!(e.error.as_deref().unwrap().contains("1 fs … 1 s")),
        other => panic!("{other:?}"),
    }
    enter_text(&mut a, "auto");
    assert_eq!(a.views.stability.step, None);
    assert_eq!(views::stability::step(&a), Some(critical));
    // Digits typed into the editor are text, not tab switches.
    key(&mut a, KeyCode::Enter);
    key(&mut a, KeyCode::Char('4'));
    assert_eq!(a.tab, Tab::named("stability").unwrap());
    key(&mut a, KeyCode::Esc);
    // The explorer's form is out of reach here: Up/Down leave its cursor alone.
    let cursor = a.cursor;
    key(&mut a, KeyCode::Down);
    assert_eq!(a.cursor, cursor);
}

#[test]
fn the_sweep_form_moves_edits_and_follows_the_checked_models() {
    let mut a = app();
    update(&mut a, Action::Resize(160, 48));
    key(&mut a, KeyCode::Char('4'));
    let jobs = a.take_studies();
    let StudySpec::Sweep { spec, .. } = &jobs[0].spec else {
        panic!("{:?}", jobs[0].spec);
    };
    assert_eq!(spec.key, SceneKey::V0);
    assert_eq!(spec.points, views::sweep::max_points(&a));
    assert_eq!(spec.models, a.checked_models());
    // ↓ to the output, → for the next one: a new sweep (the same rows, another output drawn
    // from them would do, but the spec is the sweep's identity).
    key(&mut a, KeyCode::Down);
    assert_eq!(a.views.sweep.cursor, SweepField::Output);
    let before = a.views.sweep.settings.output;
    key(&mut a, KeyCode::Right);
    assert_ne!(a.views.sweep.settings.output, before);
    // The from bound, typed with a unit.
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Enter);
    assert!(
        matches!(&a.mode, Mode::Editing(e) if e.target == views::sweep::editor(SweepField::From))
    );
    enter_text(&mut a, "10 mm/s");
    let jobs = a.take_studies();
    let StudySpec::Sweep { spec, .. } = &jobs[0].spec else {
        panic!("{:?}", jobs[0].spec);
    };
    assert!((spec.from - 0.01).abs() < 1e-15);
    // Checking dry friction sweeps it too.
    a.focused = ForceModel::DryFriction;
    key(&mut a, KeyCode::Char(' '));
    let jobs = a.take_studies();
    let StudySpec::Sweep { spec, .. } = &jobs[0].spec else {
        panic!("{:?}", jobs[0].spec);
    };
    assert!(spec.models.contains(&ForceModel::DryFriction));
    // A narrower terminal shows fewer points: the sweep follows.
    update(&mut a, Action::Resize(100, 30));
    let jobs = a.take_studies();
    let StudySpec::Sweep { spec, .. } = &jobs[0].spec else {
        panic!("{:?}", jobs[0].spec);
    };
    assert_eq!(spec.points, views::sweep::max_points(&a));
    assert!(spec.points < 200);
    // Enter on the scale switches it.
    a.views.sweep.cursor = SweepField::Scale;
    key(&mut a, KeyCode::Enter);
    assert!(!a.views.sweep.settings.range(&a.draft.scene).unwrap().log);
}

#[test]
fn v_and_shift_v_step_through_every_view_and_wrap() {
    let mut a = app();
    let mut seen = vec![a.tab];
    for _ in 1..views::VIEWS.len() {
        key(&mut a, KeyCode::Char('v'));
        seen.push(a.tab);
    }
    assert_eq!(
        seen,
        Tab::all().collect::<Vec<_>>(),
        "v visits each in order"
    );
    key(&mut a, KeyCode::Char('v'));
    assert_eq!(a.tab, Tab::HOME, "and wraps to the first");
    key(&mut a, KeyCode::Char('V'));
    assert_eq!(a.tab, Tab::all().last().unwrap(), "V goes back, wrapping");
}
