//! The system view rendered into ratatui's TestBackend: its charts and notes for the system
//! presets, edits that run it again, bad input named by its key, a scene without a system, and a
//! bifurcation diagram that fills in as its columns come.

use std::sync::Mutex;

use hertz_tui::model::presets::Registry;
use hertz_tui::model::study::runner::{self, StudyResult, StudySpec};
use hertz_tui::ui::MarkerStyle;
use hertz_tui::ui::action::Action;
use hertz_tui::ui::app::App;
use hertz_tui::ui::style::Theme;
use hertz_tui::ui::tab::Tab;
use hertz_tui::ui::update::update;
use ratatui::crossterm::event::{Event, KeyCode, KeyEvent, KeyModifiers};

use super::render::{render, settle, text};

/// Values of the diagrams the tests draw.
pub(super) const DIAGRAM_VALUES: usize = 4;

/// The explorer on preset `name` at `width`×`height`, on the system view, its studies done.
pub(super) fn app_on(name: &str, width: u16, height: u16) -> App {
    let registry = Registry::builtin().unwrap();
    let scene = registry.scene(name).unwrap();
    let mut app = App::new(scene, registry, MarkerStyle::Braille, Theme::Dark);
    assert_eq!(app.preset.as_deref(), Some(name));
    // A small diagram: the tests run unoptimised, and every value is a run of both stops.
    app.views.system.settings.values = Some(DIAGRAM_VALUES);
    app.views.system.settings.budget = Some((60, 10));
    update(&mut app, Action::Resize(width, height));
    update(&mut app, Action::Tab(Tab::named("system").unwrap()));
    settle(&mut app);
    app
}

pub(super) fn screen(app: &App, width: u16, height: u16) -> String {
    text(render(app, width, height).backend().buffer())
}

pub(super) fn press(app: &mut App, code: KeyCode) {
    let event = Event::Key(KeyEvent::new(code, KeyModifiers::NONE));
    if let Some(action) = hertz_tui::ui::keymap::action_for_event(&app.mode, &event) {
        update(app, action);
    }
}

/// Moves the cursor to the form row labelled `label` (Down until its line is under the cursor).
pub(super) fn go_to_row(app: &mut App, label: &str) {
    let rows = {
        let model = hertz_tui::ui::views::system::model(app).unwrap();
        hertz_tui::ui::views::system::settings::Settings::rows(&model)
    };
    let i = rows
        .iter()
        .position(|r| r.label() == label)
        .unwrap_or_else(|| panic!("no row {label} in {rows:?}"));
    while app.views.system.cursor != i {
        press(app, KeyCode::Down);
    }
}

/// Types `value` into the row under the cursor: Enter, clear, the text, Enter.
pub(super) fn type_in(app: &mut App, value: &str) {
    press(app, KeyCode::Enter);
    update(app, Action::Input(tui_input::InputRequest::DeleteLine));
    for c in value.chars() {
        press(app, KeyCode::Char(c));
    }
    press(app, KeyCode::Enter);
}

#[test]
fn the_bouncing_ball_shows_its_four_charts_groups_and_rigid_answer() {
    let app = app_on("bouncing-ball", 160, 48);
    for (w, h) in [(80, 24), (120, 40), (160, 48)] {
        let s = screen(&app, w, h);
        for title in ["x(t) time history", "v(x) phase portrait", "impact map"] {
            assert!(s.contains(title), "{w}×{h}: {title}\n{s}");
        }
        assert!(s.contains("bifurcation"), "{w}×{h}\n{s}");
        assert!(s.contains("Γ = Aω²/g = 1.61"), "{w}×{h}\n{s}");
        assert!(s.contains("rigid (e = 0.5)"), "{w}×{h}\n{s}");
        assert!(!s.contains("NaN"), "{w}×{h}\n{s}");
    }
}

#[test]
fn the_oscillator_shows_its_groups_and_a_period_one_rigid_orbit() {
    let app = app_on("impact-oscillator", 160, 48);
    let s = screen(&app, 160, 48);
    for group in ["ω/ω₀ = 0.9", "ζ = 0.05", "gap = 1.29 δ_st"] {
        assert!(s.contains(group), "{group}\n{s}");
    }
    // The preset's rigid stop settles on one impact a forcing period (`hertz-tui system`, the
    // model's own period detection).
    assert!(s.contains("rigid (e = 0.8): period-1, 1 impact(s)"), "{s}");
    assert!(s.contains("stop"), "the stop is drawn and named\n{s}");
}

#[test]
fn an_edit_of_a_system_key_runs_it_again_and_bad_input_names_the_key() {
    let mut app = app_on("bouncing-ball", 160, 48);
    go_to_row(&mut app, "A amplitude");
    type_in(&mut app, "0.8 mm");
    assert!(
        app.take_studies().len() == 2,
        "a run and a diagram were asked for"
    );
    let s = screen(&app, 160, 48);
    assert!(s.contains("Γ = Aω²/g = 1.288"), "{s}");
    assert!(s.contains("800 µm"), "{s}");

    let mut app = app_on("impact-oscillator", 160, 48);
    go_to_row(&mut app, "gap");
    type_in(&mut app, "-1 mm");
    let s = screen(&app, 160, 48);
    assert!(s.contains("✗ system.gap must be > 0"), "{s}");
    // The rejected text stays in the editor, nothing is run.
    assert!(app.take_studies().is_empty());
    press(&mut app, KeyCode::Esc);
    go_to_row(&mut app, "f frequency");
    type_in(&mut app, "0");
    assert!(screen(&app, 160, 48).contains("system.frequency must be"));
}

#[test]
fn a_scene_without_a_system_says_where_systems_are() {
    let app = app_on("fig5-steel-sphere-r10-plate", 120, 40);
    let s = screen(&app, 120, 40);
    assert!(s.contains("no [system] table"), "{s}");
    assert!(s.contains("bouncing-ball"), "{s}");
}

#[test]
fn the_diagram_fills_in_as_its_columns_come() {
    let mut app = app_on("bouncing-ball", 160, 48);
    // Ask for another diagram, then run it by hand, feeding each partial report to the app.
    go_to_row(&mut app, "values");
    type_in(&mut app, "8");
    let jobs = app.take_studies();
    let job = jobs
        .into_iter()
        .find(|j| matches!(j.spec, StudySpec::Diagram(_)))
        .expect("a diagram is asked for");
    let partials = Mutex::new(Vec::new());
    let last = runner::run_partially(&job, &|| false, &|o| partials.lock().unwrap().push(o))
        .expect("not stopped");
    let partials = partials.into_inner().unwrap();
    assert!(partials.len() >= 2, "{} partial reports", partials.len());
    let mut shown = Vec::new();
    for outcome in partials {
        update(&mut app, Action::Studied(Ok(outcome)));
        let s = screen(&app, 160, 48);
        let line = s
            .lines()
            .find(|l| l.contains("bifurcation diagram"))
            .unwrap_or_else(|| panic!("{s}"))
            .to_string();
        assert!(line.contains("computing…"), "{line}");
        let d = app.studies.diagram().unwrap();
        let count: usize = d.branches.iter().map(|b| b.columns.len()).sum();
        shown.push(count);
    }
    assert!(shown.windows(2).all(|w| w[0] < w[1]), "{shown:?}");
    update(&mut app, Action::Studied(Ok(last)));
    let Some(StudyResult::Diagram(d)) = app
        .studies
        .result(hertz_tui::model::study::runner::StudyKind::Diagram)
    else {
        panic!("a diagram");
    };
    assert!(d.complete);
    let s = screen(&app, 160, 48);
    let line = s
        .lines()
        .find(|l| l.contains("bifurcation diagram"))
        .unwrap();
    assert!(!line.contains("computing…"), "{line}");
}
