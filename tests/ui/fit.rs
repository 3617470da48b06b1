//! The fit view rendered into ratatui's TestBackend: a data file fitted on the scene's bodies,
//! its ranking and verdict at every size, the open prompt, the fit written into the scene and
//! undone, a refit on an edit of the scene, the checked laws only, and the empty and refused
//! states (the chart read through its ticks is in `axes`).

use std::path::Path;

use hertz_tui::format::fit_verdict::num;
use hertz_tui::model::ForceModel;
use hertz_tui::model::fit::{Candidate, FitReport};
use hertz_tui::model::scene_key::{BodyField, BodyIndex, SceneKey};
use hertz_tui::model::study::runner::StudyKind;
use hertz_tui::ui::action::Action;
use hertz_tui::ui::app::{App, Cursor, Mode};
use hertz_tui::ui::field::Field;
use hertz_tui::ui::tab::Tab;
use hertz_tui::ui::update::update;
use hertz_tui::ui::views::fit::{self, Source};
use ratatui::crossterm::event::KeyCode;

use super::render::{app, press, render, settle, text};
use super::scratch::{self, ScratchPath};

const SIZES: [(u16, u16); 3] = [(80, 24), (120, 40), (160, 48)];
const STEEL: &str = "presets/data/steel-hunt-crossley.csv";
const HC: Candidate = Candidate::Law(ForceModel::HuntCrossley);

fn screen(app: &App, (w, h): (u16, u16)) -> String {
    text(render(app, w, h).backend().buffer())
}

/// The explorer on the fit view at `size`, `path` opened (if any), its fit done.
fn on_fit(path: Option<&str>, (w, h): (u16, u16)) -> App {
    let mut app = app();
    update(&mut app, Action::Resize(w, h));
    if let Some(path) = path {
        fit::open(&mut app, Path::new(path));
    }
    update(&mut app, Action::Tab(Tab::named("fit").unwrap()));
    settle(&mut app);
    app
}

fn report(app: &App) -> FitReport {
    fit::finished(app).expect("a finished fit").1.clone()
}

/// A file `name` holding `text`, in a temporary folder removed when the result is dropped.
fn data_file(name: &str, text: &str) -> ScratchPath {
    let path = scratch::path("fit-ui", name);
    std::fs::write(&path, text).unwrap();
    path
}

/// Types `text` into the open prompt: `o`, clear, the text, Enter.
fn open_by_keys(app: &mut App, text: &str) {
    press(app, KeyCode::Char('o'));
    assert!(matches!(app.mode, Mode::Editing(_)), "o opens the prompt");
    update(app, Action::Input(tui_input::InputRequest::DeleteLine));
    for c in text.chars() {
        press(app, KeyCode::Char(c));
    }
    press(app, KeyCode::Enter);
    settle(app);
}

#[test]
fn the_ranking_and_verdict_show_what_the_fit_says_at_every_size() {
    for size in SIZES {
        let app = on_fit(Some(STEEL), size);
        let report = report(&app);
        assert_eq!(
            report.fits[0].candidate, HC,
            "the data's own law ranks first"
        );
        let s = screen(&app, size);
        let best = &report.fits[0];
        let p = &best.params[0];
        // The best row: rank, law, a with its interval and Δ = 0, as the report has them.
        let row = s
            .lines()
            .find(|l| l.contains("1  hunt-crossley"))
            .unwrap_or_else(|| panic!("{size:?}: no best row\n{s}"));
        for cell in [
            format!("a = {}", num(p.value)),
            format!("[{}, {}]", num(p.ci.0), num(p.ci.1)),
        ] {
            assert!(row.contains(&cell), "{size:?}: {cell} in {row:?}");
        }
        // The runner-up's Δ, and the verdict in words.
        let second = &report.fits[1];
        let row = s
            .lines()
            .find(|l| l.contains(&format!("2  {}", second.candidate.id())))
            .unwrap_or_else(|| panic!("{size:?}: no second row\n{s}"));
        assert!(row.contains(&num(second.delta)), "{row}");
        assert!(s.contains("Best: hunt-crossley by AICc"), "{size:?}\n{s}");
        for title in ["e(v₀) of steel-hunt-crossley.csv", "residuals"] {
            assert!(s.contains(title), "{size:?}: {title}\n{s}");
        }
        assert!(s.contains("16 points"), "{s}");
        // Every fitted law has a curve with points in the chart.
        let (fit, _) = fit::finished(&app).unwrap();
        assert_eq!(fit.curves.len(), report.fits.len());
        for c in &fit.curves {
            assert!(
                c.points.len() > 40,
                "{:?}: {} points",
                c.candidate,
                c.points.len()
            );
        }
    }
}

#[test]
fn without_data_the_view_says_how_to_load_some_and_where_the_examples_are() {
    for size in SIZES {
        let app = on_fit(None, size);
        let s = screen(&app, size);
        for words in [
            "No data loaded",
            "o opens",
            "presets/data/",
            "steel-hunt-crossley.csv",
        ] {
            assert!(s.contains(words), "{size:?}: {words}\n{s}");
        }
        assert!(app.studies.fit().is_none(), "nothing is fitted");
        assert!(!app.studies.is_pending(StudyKind::Fit));
    }
}

#[test]
fn a_refused_file_shows_the_readers_error_with_file_and_line_and_another_opens() {
    let file = data_file("bad.csv", "v (m/s), e\n0.1, 0.9\n0.2, 1.5\n");
    let bad = file.to_str().unwrap();
    let mut app = on_fit(Some(bad), (120, 40));
    assert!(matches!(app.views.fit.source, Source::Failed { .. }));
    let s = screen(&app, (120, 40));
    assert!(s.contains(&format!("{bad}:3: restitution e = 1.5")), "{s}");
    assert!(s.contains("o opens another file"), "{s}");
    // A file that is not there: said, with its name.
    open_by_keys(&mut app, "no/such/file.csv");
    let s = screen(&app, (120, 40));
    assert!(s.contains("no/such/file.csv: cannot read the data"), "{s}");
    // No dead end: the prompt opens a good file and the fit shows.
    open_by_keys(&mut app, STEEL);
    assert_eq!(report(&app).fits[0].candidate, HC);
    assert!(screen(&app, (120, 40)).contains("Best: hunt-crossley"));
    // An empty path is refused in the prompt, which stays open.
    press(&mut app, KeyCode::Char('o'));
    update(&mut app, Action::Input(tui_input::InputRequest::DeleteLine));
    press(&mut app, KeyCode::Enter);
    assert!(matches!(&app.mode, Mode::Editing(e) if e.error.is_some()));
    assert!(screen(&app, (120, 40)).contains("type the path of a CSV file"));
}

#[test]
fn enter_writes_the_best_fit_into_the_scene_and_u_undoes_it() {
    let mut app = on_fit(Some(STEEL), (120, 40));
    let best = report(&app).fits[0].clone();
    let e_before = app.draft.scene.impact.restitution;
    assert!(app.draft.scene.fit.is_none());
    press(&mut app, KeyCode::Enter);
    settle(&mut app);
    let fitted = app
        .draft
        .scene
        .fit
        .clone()
        .unwrap_or_else(|| panic!("{:?}", app.message));
    assert_eq!(fitted.kind, HC);
    assert_eq!(fitted.value, best.params[0].value);
    assert_eq!(fitted.source.as_deref(), Some(STEEL));
    // e at the scene's v₀ is the fitted law's, and the valid scene (what every view reads) has it.
    let v0 = app.draft.scene.impact.v0;
    let e = best.predict(&app.draft.scene, v0).unwrap();
    assert!((app.draft.scene.impact.restitution - e).abs() < 1e-9);
    assert_eq!(app.valid.as_ref().unwrap().scene.fit, Some(fitted));
    assert!(app.is_checked(ForceModel::HuntCrossley));
    assert_eq!(app.focused, ForceModel::HuntCrossley);
    press(&mut app, KeyCode::Char('u'));
    settle(&mut app);
    assert!(app.draft.scene.fit.is_none(), "undone");
    assert_eq!(app.draft.scene.impact.restitution, e_before);
}

#[test]
fn an_edit_of_the_scene_refits_and_c_fits_only_the_checked_laws() {
    let mut app = on_fit(Some(STEEL), (120, 40));
    let before = report(&app);
    let kk = |r: &FitReport| {
        r.fits
            .iter()
            .find(|f| f.candidate.id() == "kuwabara-kono")
            .map(|f| f.params[0].value)
            .unwrap()
    };
    // A softer sphere, typed in the explorer: Kuwabara–Kono's A follows the contact's
    // stiffness.
    update(&mut app, Action::Tab(Tab::HOME));
    app.cursor = Cursor::Field(Field::Number(SceneKey::Body(
        BodyIndex::One,
        BodyField::YoungsModulus,
    )));
    press(&mut app, KeyCode::Enter);
    update(&mut app, Action::Input(tui_input::InputRequest::DeleteLine));
    for c in "100 GPa".chars() {
        press(&mut app, KeyCode::Char(c));
    }
    press(&mut app, KeyCode::Enter);
    assert_eq!(app.draft.scene.body1.material.youngs_modulus, 100e9);
    update(&mut app, Action::Tab(Tab::named("fit").unwrap()));
    assert!(
        app.studies.is_pending(StudyKind::Fit),
        "the edit asked for a refit"
    );
    settle(&mut app);
    let after = report(&app);
    let (a, b) = (kk(&before), kk(&after));
    assert!((a / b - 1.0).abs() > 1e-3, "A {a} against {b}");

    press(&mut app, KeyCode::Char('c'));
    settle(&mut app);
    let checked = report(&app);
    assert!(checked.fits.len() < after.fits.len());
    for f in &checked.fits {
        assert!(
            f.candidate.model().is_none_or(|m| app.is_checked(m)),
            "{} is not checked",
            f.candidate
        );
    }
    press(&mut app, KeyCode::Char('c'));
    settle(&mut app);
    assert_eq!(report(&app).fits.len(), after.fits.len());
}

#[test]
fn the_cursor_chooses_the_fit_enter_writes() {
    let mut app = on_fit(Some(STEEL), (160, 48));
    let second = report(&app).fits[1].clone();
    press(&mut app, KeyCode::Down);
    press(&mut app, KeyCode::Enter);
    settle(&mut app);
    let fitted = app.draft.scene.fit.clone().unwrap();
    assert_eq!(fitted.kind, second.candidate);
    assert_eq!(fitted.value, second.params[0].value);
}
