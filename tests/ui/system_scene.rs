//! The system view's `[system]` table as the explorer opens, edits and saves it: read from a scene
//! file with `--set system.*` (units included) applied, written back by `s` so that the file opens
//! again to the same table, undone by `u` like the form's edits, and added to a scene without one.

use hertz_tui::format::units::sig;
use hertz_tui::model::presets::Registry;
use hertz_tui::model::scene_file;
use hertz_tui::model::system::{STANDARD_GRAVITY, SystemKind, SystemSpec};
use hertz_tui::ui::action::Action;
use hertz_tui::ui::app::{App, Confirm, Mode};
use hertz_tui::ui::style::Theme;
use hertz_tui::ui::tab::Tab;
use hertz_tui::ui::update::update;
use hertz_tui::ui::views::system::settings::{TOML_SNIPPET, preset_spec};
use hertz_tui::ui::{MarkerStyle, Opened};
use ratatui::crossterm::event::KeyCode;

use super::render::settle;
use super::scratch::{self, ScratchPath};
use super::system::{DIAGRAM_VALUES, app_on, go_to_row, press, screen, type_in};

/// A bouncing ball as a user writes it (docs/systems.md §1), with A = 0.9 mm: its name is not the
/// preset's, so no preset's table can stand in for the file's.
const BALL_FILE: &str = r#"name = "My ball"

[body1]
shape = "sphere"
radius = 0.01
material = "steel"

[body2]
shape = "plane"
material = "steel"

[impact]
v0 = 0.25
restitution = 0.5
plastic_indentation = 0.0

[system]
kind = "bouncing-ball"
amplitude = 0.0009
frequency = 20.0
"#;

/// A file called `name` holding `text`, in a temporary folder removed when the result is dropped.
fn scene_file(name: &str, text: &str) -> ScratchPath {
    let path = scratch::path("ui-system", name);
    std::fs::write(&path, text).unwrap();
    path
}

/// What `hertz-tui --scene <source> --set <sets>…` opens, or its error.
fn open(source: &str, sets: &[&str]) -> Result<Opened, String> {
    let registry = Registry::builtin().unwrap();
    let overrides: Vec<_> = sets
        .iter()
        .map(|s| s.parse().map_err(|e| format!("{e}")))
        .collect::<Result<_, _>>()?;
    Opened::read(&registry, source, &overrides).map_err(|e| e.to_string())
}

/// The explorer on `opened` as `hertz-tui` starts it, on the system view, its studies done.
fn app_from(opened: Opened) -> App {
    let registry = Registry::builtin().unwrap();
    let Opened {
        scene,
        system,
        view,
    } = opened;
    let mut app = App::open_system(
        scene,
        system,
        view,
        registry,
        MarkerStyle::Braille,
        Theme::Dark,
    );
    app.views.system.settings.values = Some(DIAGRAM_VALUES);
    app.views.system.settings.budget = Some((60, 10));
    update(&mut app, Action::Resize(160, 48));
    update(&mut app, Action::Tab(Tab::named("system").unwrap()));
    settle(&mut app);
    app
}

/// Γ = Aω²/g as the notes show it (docs/physics.md §8).
fn gamma_note(amplitude: f64, frequency: f64) -> String {
    let omega = 2.0 * std::f64::consts::PI * frequency;
    format!(
        "Γ = Aω²/g = {}",
        sig(amplitude * omega * omega / STANDARD_GRAVITY, 4)
    )
}

fn ball(spec: Option<SystemSpec>) -> (f64, f64) {
    match spec.map(|s| s.kind) {
        Some(SystemKind::BouncingBall {
            amplitude,
            frequency,
            ..
        }) => (amplitude, frequency),
        other => panic!("not a ball: {other:?}"),
    }
}

#[test]
fn a_scene_file_and_its_set_overrides_with_units_reach_the_view() {
    let path = scene_file("my-ball.toml", BALL_FILE);
    let path = path.to_str().unwrap();
    let app = app_from(open(path, &[]).unwrap());
    let s = screen(&app, 160, 48);
    assert!(s.contains(&gamma_note(0.0009, 20.0)), "{s}");
    assert!(s.contains("900 µm"), "{s}");
    assert!(!app.is_dirty());

    // `--set` at start, in units, over the file's table: the view runs what was asked for.
    let opened = open(path, &["system.amplitude=0.8 mm", "system.frequency=25Hz"]).unwrap();
    assert_eq!(ball(opened.system), (0.0008, 25.0));
    let app = app_from(opened);
    let s = screen(&app, 160, 48);
    assert!(s.contains(&gamma_note(0.0008, 25.0)), "{s}");
    assert!(s.contains("800 µm") && s.contains("25 Hz"), "{s}");
    // A preset with `--set system.*` too.
    let app = app_from(open("impact-oscillator", &["system.gap=0.4 mm"]).unwrap());
    assert!(screen(&app, 160, 48).contains("400 µm"));
}

#[test]
fn a_bad_table_or_override_is_refused_at_start_naming_its_key() {
    let path = scene_file("bad-gap.toml", &BALL_FILE.replace("0.0009", "-0.0009"));
    let e = open(path.to_str().unwrap(), &[]).unwrap_err();
    assert!(e.contains("system.amplitude"), "{e}");
    let e = open("bouncing-ball", &["system.frequency=20 kg"]).unwrap_err();
    assert!(
        e.starts_with("--set system.frequency:") && e.contains("unknown unit 'kg'"),
        "{e}"
    );
    let e = open("impact-oscillator", &["system.gap=0"]).unwrap_err();
    assert!(e.contains("system.gap must be > 0"), "{e}");
    let e = open("bouncing-ball", &["system.gap=1 mm"]).unwrap_err();
    assert!(e.contains("system.gap"), "{e}");
}

#[test]
fn saving_writes_the_edited_table_and_the_file_opens_to_the_same_scene() {
    for preset in ["bouncing-ball", "impact-oscillator-clearance"] {
        let mut app = app_on(preset, 160, 48);
        let loaded = app.draft.system;
        if preset == "bouncing-ball" {
            go_to_row(&mut app, "A amplitude");
            type_in(&mut app, "0.8 mm");
            go_to_row(&mut app, "f frequency");
        } else {
            go_to_row(&mut app, "gap₂");
            type_in(&mut app, "0.35 mm");
            go_to_row(&mut app, "ζ damping");
        }
        // ← → by 5 %: a value with all its digits, to round-trip.
        press(&mut app, KeyCode::Right);
        settle(&mut app);
        assert_ne!(app.draft.system, loaded);
        assert!(app.is_dirty(), "a system edit is an unsaved change");
        let shown = screen(&app, 160, 48);

        let path = scene_file(&format!("saved-{preset}.toml"), "");
        press(&mut app, KeyCode::Char('s'));
        update(&mut app, Action::Input(tui_input::InputRequest::DeleteLine));
        for c in path.to_str().unwrap().chars() {
            press(&mut app, KeyCode::Char(c));
        }
        press(&mut app, KeyCode::Enter);
        let news = app.message.as_ref().map(|m| m.text.clone());
        assert!(
            news.as_deref().is_some_and(|t| t.starts_with("saved ")),
            "{news:?}"
        );
        assert!(!app.is_dirty());
        let text = std::fs::read_to_string(&path).unwrap();
        assert!(text.contains("[system]"), "{text}");
        // The preset's description (its Γ, its gaps) no longer describes the file: it says what
        // was edited.
        let edited = if preset == "bouncing-ball" {
            "system.amplitude = 0.0008, system.frequency = 21.0"
        } else {
            "system.damping_ratio = 0.021, system.second_gap = 0.00035"
        };
        assert!(text.contains(edited), "{text}");

        // Exactly the same table, scene and view: every f64 reads back to itself.
        let opened = open(path.to_str().unwrap(), &[]).unwrap();
        assert_eq!(opened.system, app.draft.system, "{text}");
        assert_eq!(opened.scene, app.draft.scene, "{text}");
        assert_eq!(opened.view, app.scene_view(), "{text}");
        let again = app_from(opened);
        assert!(!again.is_dirty());
        let notes = |s: &str| {
            s.lines()
                .filter(|l| l.contains("Γ =") || l.contains("ω/ω₀"))
                .map(|l| l.split('│').nth(1).unwrap_or_default().to_string())
                .collect::<Vec<_>>()
        };
        assert_eq!(notes(&screen(&again, 160, 48)), notes(&shown));
    }
}

#[test]
fn undo_takes_system_edits_back_one_by_one_from_any_view() {
    let mut app = app_on("bouncing-ball", 160, 48);
    let loaded = app.draft.system;
    go_to_row(&mut app, "A amplitude");
    type_in(&mut app, "0.8 mm");
    let first = app.draft.system;
    assert_eq!(ball(first), (0.0008, 20.0));
    go_to_row(&mut app, "f frequency");
    press(&mut app, KeyCode::Right);
    assert_eq!(ball(app.draft.system), (0.0008, 21.0));
    settle(&mut app);
    // Quitting asks first: the edits are not lost.
    press(&mut app, KeyCode::Char('q'));
    assert!(matches!(app.mode, Mode::Confirm(Confirm::Quit)));
    press(&mut app, KeyCode::Esc);

    press(&mut app, KeyCode::Char('u'));
    assert_eq!(app.draft.system, first);
    assert!(
        !app.take_studies().is_empty(),
        "the undone table is run again"
    );
    settle(&mut app);
    assert!(screen(&app, 160, 48).contains(&gamma_note(0.0008, 20.0)));

    // From the explorer's tab, the same undo: one history for the form and the system.
    update(&mut app, Action::Tab(Tab::HOME));
    press(&mut app, KeyCode::Char('u'));
    assert_eq!(app.draft.system, loaded);
    assert!(!app.is_dirty());
    update(&mut app, Action::Tab(Tab::named("system").unwrap()));
    settle(&mut app);
    assert!(screen(&app, 160, 48).contains(&gamma_note(0.001, 20.0)));

    // `r` puts a key back to the table as loaded, and is undone the same way.
    go_to_row(&mut app, "A amplitude");
    type_in(&mut app, "2 mm");
    press(&mut app, KeyCode::Char('r'));
    assert_eq!(app.draft.system, loaded);
    press(&mut app, KeyCode::Char('u'));
    assert_eq!(ball(app.draft.system), (0.002, 20.0));
}

#[test]
fn a_scene_without_a_system_offers_one_and_the_snippet_it_shows_reads() {
    let mut app = app_on("fig5-steel-sphere-r10-plate", 120, 40);
    let s = screen(&app, 120, 40);
    for text in [
        "no [system] table",
        "Add a system",
        "impact-oscillator-clearance",
        "kind = \"bouncing-ball\"",
        "--scene FILE",
    ] {
        assert!(s.contains(text), "{text}\n{s}");
    }
    // Enter on the second preset: its table on this scene's bodies, runnable, undoable.
    press(&mut app, KeyCode::Down);
    press(&mut app, KeyCode::Enter);
    let registry = Registry::builtin().unwrap();
    assert_eq!(
        app.draft.system,
        Some(preset_spec(&registry, "impact-oscillator").unwrap())
    );
    assert!(app.is_dirty());
    settle(&mut app);
    let s = screen(&app, 120, 40);
    assert!(
        s.contains("ω/ω₀ = 0.9") && s.contains("rigid (e = 0.6)"),
        "{s}"
    );
    press(&mut app, KeyCode::Char('u'));
    assert_eq!(app.draft.system, None);
    assert!(!app.is_dirty());
    assert!(screen(&app, 120, 40).contains("Add a system"));

    // The snippet shown, pasted into the scene's file, is the preset ball.
    let scene = registry.scene("fig5-steel-sphere-r10-plate").unwrap();
    let text = format!("{}\n{TOML_SNIPPET}\n", scene_file::to_toml(&scene, None));
    let path = scene_file("pasted.toml", &text);
    let opened = open(path.to_str().unwrap(), &[]).unwrap();
    assert_eq!(
        opened.system,
        Some(preset_spec(&registry, "bouncing-ball").unwrap())
    );
}
