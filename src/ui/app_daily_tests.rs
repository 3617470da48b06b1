//! Everyday use, driven by keys, paste and mouse events through the keymap: nothing lost (quit,
//! save, export ask first; undo and reset), nothing surprising (pastes never run commands, nudges
//! stop at the domain's bound, stale numbers say so), and a help that lists every working key.

use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{
    Event, KeyCode, KeyEvent, KeyModifiers, MouseButton, MouseEvent, MouseEventKind,
};

use crate::model::ForceModel;
use crate::model::presets::{DEFAULT_SCENE, Registry};
use crate::model::scene_key::{BodyField, BodyIndex, SceneKey};

use super::action::Action;
use super::app::{App, Confirm, Cursor, Mode};
use super::app_tests::{app, enter_text, key, key_with, settle, type_text};
use super::field::Field;
use super::keymap::{INPUT_HINTS, action_for_event, bindings};
use super::render;
use super::style::{MarkerStyle, Theme};
use super::tab::Tab;
use super::testing::{TempPath, temp_path};
use super::update::update;

const V0: Field = Field::Number(SceneKey::V0);
const E1: Field = Field::Number(SceneKey::Body(BodyIndex::One, BodyField::YoungsModulus));
const NU1: Field = Field::Number(SceneKey::Body(BodyIndex::One, BodyField::PoissonRatio));

fn event(app: &mut App, event: Event) {
    if let Some(action) = action_for_event(&app.mode, &event) {
        update(app, action);
    }
}

fn paste(app: &mut App, text: &str) {
    event(app, Event::Paste(text.to_string()));
}

fn mouse(app: &mut App, kind: MouseEventKind, column: u16, row: u16) {
    event(
        app,
        Event::Mouse(MouseEvent {
            kind,
            column,
            row,
            modifiers: KeyModifiers::NONE,
        }),
    );
}

/// The screen as text, one line per row.
pub(super) fn screen(app: &App, width: u16, height: u16) -> Vec<String> {
    let mut terminal = Terminal::new(TestBackend::new(width, height)).unwrap();
    terminal.draw(|frame| render::draw(frame, app)).unwrap();
    let buffer = terminal.backend().buffer();
    (0..height)
        .map(|y| (0..width).map(|x| buffer[(x, y)].symbol()).collect())
        .collect()
}

/// The explorer on the default preset, with a user folder of its own.
pub(super) fn preset_app(label: &str) -> (App, TempPath) {
    let dir = temp_path(label);
    let registry = Registry::load_from(Some(&dir)).unwrap();
    let scene = registry.scene(DEFAULT_SCENE).unwrap();
    let view = registry.scene_view(DEFAULT_SCENE).unwrap();
    let app = App::open(scene, view, registry, MarkerStyle::Braille, Theme::Plain);
    (app, dir)
}

#[test]
fn quitting_with_unsaved_changes_asks_once() {
    let mut a = app();
    key(&mut a, KeyCode::Right);
    assert!(a.is_dirty());
    key(&mut a, KeyCode::Char('q'));
    assert!(!a.quit);
    assert!(matches!(a.mode, Mode::Confirm(Confirm::Quit)));
    key(&mut a, KeyCode::Char('n'));
    assert!(
        !a.quit && matches!(a.mode, Mode::Normal),
        "any other key stays"
    );
    key(&mut a, KeyCode::Char('q'));
    key(&mut a, KeyCode::Char('y'));
    assert!(a.quit, "y confirms");

    // Ctrl-C asks too, and a second Ctrl-C quits at once (also from an open editor).
    let mut b = app();
    key(&mut b, KeyCode::Right);
    key(&mut b, KeyCode::Enter);
    key_with(&mut b, KeyCode::Char('c'), KeyModifiers::CONTROL);
    assert!(!b.quit);
    key_with(&mut b, KeyCode::Char('c'), KeyModifiers::CONTROL);
    assert!(b.quit);

    // Nothing to lose: q quits without a question.
    let mut c = app();
    key(&mut c, KeyCode::Char('q'));
    assert!(c.quit);
}

#[test]
fn a_paste_opens_the_field_under_the_cursor_and_never_runs_commands() {
    let mut a = app();
    settle(&mut a);
    let checked = a.checked_models();
    // On a model: ignored with a message; "200 GPa" would have switched to tab 2 and toggled.
    a.cursor = Cursor::Model(ForceModel::Proposed);
    paste(&mut a, "200 GPa");
    assert_eq!(a.tab, Tab::HOME);
    assert_eq!(a.checked_models(), checked);
    assert!(matches!(a.mode, Mode::Normal));
    assert!(
        a.message
            .as_ref()
            .is_some_and(|m| m.text.contains("paste ignored"))
    );
    // On a field: its editor opens with the pasted text.
    a.cursor = Cursor::Field(E1);
    paste(&mut a, "150 GPa\n");
    match &a.mode {
        Mode::Editing(editor) => assert_eq!(editor.input.value(), "150 GPa"),
        other => panic!("{other:?}"),
    }
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.draft.scene.body1.material.youngs_modulus, 150e9);
    // In an open editor the paste is typed at the cursor.
    a.cursor = Cursor::Field(V0);
    key(&mut a, KeyCode::Enter);
    key_with(&mut a, KeyCode::Char('u'), KeyModifiers::CONTROL);
    paste(&mut a, "0.5");
    type_text(&mut a, " m/s");
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.draft.scene.impact.v0, 0.5);
}

#[test]
fn undo_walks_back_several_changes_and_reset_restores_one_field() {
    let mut a = app();
    settle(&mut a);
    let original = a.draft.clone();
    key(&mut a, KeyCode::Right); // v₀ 0.3 → 0.31
    key(&mut a, KeyCode::Right); // → 0.32
    a.cursor = Cursor::Field(E1);
    key(&mut a, KeyCode::Enter);
    enter_text(&mut a, "100 GPa");
    assert_eq!(a.draft.scene.impact.v0, 0.32);
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(a.draft.scene.body1.material.youngs_modulus, 200e9);
    assert_eq!(a.draft.scene.impact.v0, 0.32);
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(a.draft.scene.impact.v0, 0.31);
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(a.draft, original);
    assert!(!a.is_dirty());
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(
        a.message.as_ref().map(|m| m.text.as_str()),
        Some("nothing to undo")
    );

    // r: one field back to the scene as loaded, the others stay.
    a.cursor = Cursor::Field(V0);
    key(&mut a, KeyCode::Right);
    a.cursor = Cursor::Field(E1);
    key(&mut a, KeyCode::Left);
    assert_ne!(a.draft.scene.body1.material.youngs_modulus, 200e9);
    key(&mut a, KeyCode::Char('r'));
    assert_eq!(a.draft.scene.body1.material.youngs_modulus, 200e9);
    assert_eq!(a.draft.scene.impact.v0, 0.31);
    // Undo takes the reset back.
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(a.draft.scene.body1.material.youngs_modulus, 190e9);
}

#[test]
fn nudges_stop_at_the_domain_bound() {
    let mut a = app();
    a.cursor = Cursor::Field(NU1);
    key(&mut a, KeyCode::Enter);
    enter_text(&mut a, "0.49");
    key(&mut a, KeyCode::Right);
    assert_eq!(
        a.draft.scene.body1.material.poisson_ratio, 0.49,
        "0.5 is out of [0, 0.5)"
    );
    assert!(a.scene_error.is_none());
    let message = a.message.clone().unwrap();
    assert!(
        message.error && message.text.starts_with("ν stays at 0.49: "),
        "{message:?}"
    );
    key(&mut a, KeyCode::Left);
    assert_eq!(a.draft.scene.body1.material.poisson_ratio, 0.48);
    // e stops at 1.
    a.cursor = Cursor::Field(Field::Number(SceneKey::Restitution));
    key(&mut a, KeyCode::Enter);
    enter_text(&mut a, "1");
    key(&mut a, KeyCode::Right);
    assert_eq!(a.draft.scene.impact.restitution, 1.0);
}

#[test]
fn saving_never_hides_a_built_in_without_asking_and_keeps_the_description() {
    let (mut a, dir) = preset_app("shadow");
    assert_eq!(a.preset.as_deref(), Some(DEFAULT_SCENE));
    key(&mut a, KeyCode::Char('s'));
    enter_text(&mut a, DEFAULT_SCENE);
    assert_eq!(
        a.mode_confirm(),
        Some(Confirm::ShadowBuiltin {
            name: DEFAULT_SCENE.into(),
            then_quit: false
        }),
        "a built-in's name asks first"
    );
    key(&mut a, KeyCode::Char('n'));
    assert!(!dir.join(format!("scenes/{DEFAULT_SCENE}.toml")).exists());
    key(&mut a, KeyCode::Char('s'));
    enter_text(&mut a, DEFAULT_SCENE);
    key(&mut a, KeyCode::Char('y'));
    let file = dir.join(format!("scenes/{DEFAULT_SCENE}.toml"));
    let text = std::fs::read_to_string(&file).unwrap();
    let message = a.message.clone().unwrap().text;
    assert!(
        text.contains("description = \"Fig. 5: viscous models"),
        "{text}"
    );
    assert!(
        text.contains("models = [\"proposed\", \"hunt-crossley\", \"lankarani-nikravesh\"]"),
        "{text}"
    );
    assert!(text.contains("[solver]\nmethod = \"auto\""), "{text}");
    assert_eq!(
        message,
        format!(
            "saved {} (it hides the built-in; delete the file to get it back)",
            file.display()
        ),
        "the absolute path, and how to undo it"
    );
    assert!(file.is_absolute());
}

#[test]
fn an_edited_material_is_named_so_and_saved_under_the_new_name() {
    let (mut a, dir) = preset_app("edited");
    a.cursor = Cursor::Field(E1);
    key(&mut a, KeyCode::Left);
    assert_eq!(a.draft.scene.body1.material.name, "steel (edited)");
    assert_eq!(a.draft.scene.body2.material.name, "steel");
    let lines = screen(&a, 160, 48).join("\n");
    assert!(
        lines.contains("Body 1 · sphere · steel (edited)"),
        "{lines}"
    );
    // The status line no longer names the preset it came from: the scene is named by its bodies.
    assert!(
        lines
            .lines()
            .last()
            .unwrap()
            .contains("Steel (edited) sphere R = 10 mm on steel plate*"),
        "{lines}"
    );
    key(&mut a, KeyCode::Char('s'));
    match &a.mode {
        Mode::Prompt(p) => assert_eq!(p.input.value(), format!("{DEFAULT_SCENE}-edited")),
        other => panic!("{other:?}"),
    }
    enter_text(&mut a, "soft-plate");
    let text = std::fs::read_to_string(dir.join("scenes/soft-plate.toml")).unwrap();
    assert!(text.starts_with("name = \"soft-plate\"\n"), "{text}");
    assert!(
        text.contains("name = \"steel (edited)\"\nyoungs_modulus = 1.9e11"),
        "{text}"
    );
    assert!(!a.is_dirty());
    // Back to the preset's numbers, back to its name.
    key(&mut a, KeyCode::Right);
    assert_eq!(a.draft.scene.body1.material.name, "steel (edited)");
}

/// Fig. 5's name follows an edit of its plate everywhere a name is shown or written: the status
/// line, the engine panel, the export's file name, the figure's, and a saved scene's description.
#[test]
fn an_edited_scene_is_not_named_after_the_preset_anywhere() {
    let (mut a, dir) = preset_app("renamed");
    assert!(a.title().0.starts_with("Fig. 5"));
    a.cursor = Cursor::Field(Field::Number(SceneKey::Body(
        BodyIndex::Two,
        BodyField::YoungsModulus,
    )));
    key(&mut a, KeyCode::Left);
    let name = "Steel sphere R = 10 mm on steel (edited) plate";
    assert_eq!(a.title().0, name);
    let status = screen(&a, 160, 48).last().unwrap().clone();
    assert!(status.contains(&format!("{name}*")), "{status}");
    key(&mut a, KeyCode::Char('t'));
    match &a.mode {
        Mode::Engine(panel) => assert!(panel.lines[0].ends_with(name), "{:?}", panel.lines),
        other => panic!("{other:?}"),
    }
    key(&mut a, KeyCode::Esc);
    let stem = a.file_stem();
    assert!(!stem.contains("fig5"), "{stem}");
    assert!(stem.contains("edited-plate"), "{stem}");
    // Saved, its description says what was edited instead of Fig. 5's "at v0 = 0.3 m/s…".
    key(&mut a, KeyCode::Char('s'));
    enter_text(&mut a, "edited-plate");
    let text = std::fs::read_to_string(dir.join("scenes/edited-plate.toml")).unwrap();
    let description = text.lines().nth(1).unwrap();
    assert!(
        description.starts_with("description = 'edited from \"Fig. 5: steel sphere R = 10 mm")
            && description.ends_with(
                ": body2.material = steel (edited), body2.material.youngs_modulus = 190000000000'"
            ),
        "{text}"
    );
    // An impact edit alone: the bodies' name, no longer "Fig. 5".
    let (mut b, _dir) = preset_app("renamed-v0");
    b.cursor = Cursor::Field(V0);
    key(&mut b, KeyCode::Right);
    assert_eq!(b.title().0, "Steel sphere R = 10 mm on steel plate");
    assert_eq!(b.valid.as_ref().unwrap().scene.name, b.title().0);
}

#[test]
fn export_asks_before_overwriting() {
    let mut a = app();
    settle(&mut a);
    let path = temp_path("overwrite.csv");
    std::fs::write(&path, "keep me").unwrap();
    key(&mut a, KeyCode::Char('e'));
    enter_text(&mut a, path.to_str().unwrap());
    assert!(matches!(a.mode, Mode::Confirm(Confirm::Overwrite { .. })));
    key(&mut a, KeyCode::Esc);
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "keep me");
    key(&mut a, KeyCode::Char('e'));
    enter_text(&mut a, path.to_str().unwrap());
    key(&mut a, KeyCode::Char('y'));
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(text.starts_with("t,x,v,F\n"));
}

#[test]
fn stale_numbers_say_they_are_the_last_valid_ones() {
    let mut a = app();
    settle(&mut a);
    a.cursor = Cursor::Field(NU1);
    key(&mut a, KeyCode::Enter);
    enter_text(&mut a, "0.7");
    assert!(a.scene_error.is_some());
    let lines = screen(&a, 160, 48).join("\n");
    assert!(lines.contains("last valid scene:"), "regime box\n{lines}");
    assert!(
        lines.contains("Results · last valid scene"),
        "results\n{lines}"
    );
    // The explorer's recompute time is not shown on the study tabs.
    let mut b = app();
    settle(&mut b);
    let explorer = screen(&b, 160, 48);
    assert!(explorer.last().unwrap().contains("recomputed in"));
    key(&mut b, KeyCode::Char('4'));
    let sweep = screen(&b, 160, 48);
    assert!(
        !sweep.last().unwrap().contains("recomputed in"),
        "{:?}",
        sweep.last()
    );
}

#[test]
fn mouse_clicks_tabs_fields_and_model_boxes_and_the_wheel_nudges() {
    let mut a = app();
    settle(&mut a);
    update(&mut a, Action::Resize(160, 48));
    // The cursor elsewhere, so that the click has to move it (rows are found where drawn).
    a.cursor = Cursor::Field(Field::Method);
    let lines = screen(&a, 160, 48);
    let find = |needle: &str| {
        lines.iter().enumerate().find_map(|(y, line)| {
            line.find(needle)
                .map(|byte| (line[..byte].chars().count() as u16, y as u16))
        })
    };
    // The field labelled "v₀" and the "[ ]" box of dry friction, where they are drawn.
    let (x, y) = find(" v₀     0.3 m/s").unwrap();
    mouse(&mut a, MouseEventKind::Down(MouseButton::Left), x + 2, y);
    assert_eq!(a.cursor, Cursor::Field(V0));
    mouse(&mut a, MouseEventKind::ScrollUp, x + 2, y);
    assert_eq!(a.draft.scene.impact.v0, 0.31);
    mouse(&mut a, MouseEventKind::ScrollDown, x + 2, y);
    assert_eq!(a.draft.scene.impact.v0, 0.3);
    // The box on dry friction's own row (other unchecked laws may come first).
    let (x, y) = lines
        .iter()
        .enumerate()
        .find_map(|(y, line)| {
            line.find("dry friction")?;
            let byte = line.find("[ ]")?;
            Some((line[..byte].chars().count() as u16, y as u16))
        })
        .unwrap();
    assert!(!a.is_checked(ForceModel::DryFriction));
    mouse(&mut a, MouseEventKind::Down(MouseButton::Left), x + 1, y);
    assert!(
        a.is_checked(ForceModel::DryFriction),
        "a click on the box checks it"
    );
    assert_eq!(a.cursor, Cursor::Model(ForceModel::DryFriction));
    let (x, y) = find("3 stability").unwrap();
    mouse(&mut a, MouseEventKind::Down(MouseButton::Left), x + 3, y);
    assert_eq!(a.tab, Tab::named("stability").unwrap());
    // m turns capture off (the terminal selects text) and on again.
    key(&mut a, KeyCode::Char('m'));
    assert!(!a.mouse);
    key(&mut a, KeyCode::Char('m'));
    assert!(a.mouse);
}

#[test]
fn home_end_and_pages_move_through_the_form() {
    let mut a = app();
    key(&mut a, KeyCode::Home);
    assert_eq!(a.cursor, Cursor::Field(Field::Shape(BodyIndex::One)));
    key(&mut a, KeyCode::PageDown);
    assert_eq!(a.cursor, Cursor::Field(Field::Shape(BodyIndex::Two)));
    key(&mut a, KeyCode::PageDown);
    assert_eq!(a.cursor, Cursor::Field(V0));
    key(&mut a, KeyCode::PageDown);
    assert_eq!(a.cursor, Cursor::Model(ForceModel::Quasistatic));
    key(&mut a, KeyCode::End);
    let last = ForceModel::ALL[ForceModel::ALL.len() - 1];
    assert_eq!(a.cursor, Cursor::Model(last));
    key(&mut a, KeyCode::PageUp);
    assert_eq!(a.cursor, Cursor::Model(ForceModel::Quasistatic));
    key(&mut a, KeyCode::PageUp);
    assert_eq!(a.cursor, Cursor::Field(V0));
    key(&mut a, KeyCode::Char('G'));
    key(&mut a, KeyCode::Char('g'));
    assert_eq!(a.cursor, Cursor::Field(Field::Shape(BodyIndex::One)));
}

#[test]
fn the_picker_filters_as_you_type_and_presets_open_as_their_figure() {
    let mut a = app();
    key(&mut a, KeyCode::Char('p'));
    type_text(&mut a, "fig4");
    let Mode::Picker(picker) = &a.mode else {
        panic!("{:?}", a.mode)
    };
    assert_eq!(
        picker.visible().len(),
        1,
        "q, p, 1, 2 and letters type into the filter"
    );
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.preset.as_deref(), Some("fig4-steel-sphere-r10-plate"));
    assert_eq!(
        a.checked_models(),
        [ForceModel::Quasistatic, ForceModel::DryFriction]
    );
    assert_eq!(a.focused, ForceModel::DryFriction);
    // Descriptions are cut with … to the picker's width.
    key(&mut a, KeyCode::Char('p'));
    let lines = screen(&a, 80, 24);
    let rows: Vec<&String> = lines
        .iter()
        .filter(|l| l.contains("scene    fig5"))
        .collect();
    assert_eq!(rows.len(), 1, "{lines:#?}");
    assert!(
        rows[0].trim_end_matches([' ', '│']).ends_with('…'),
        "{lines:#?}"
    );
    // The wheel moves the selection (it opened on the loaded preset).
    let selected = |a: &App| match &a.mode {
        Mode::Picker(picker) => picker.selected,
        other => panic!("{other:?}"),
    };
    let before = selected(&a);
    mouse(&mut a, MouseEventKind::ScrollDown, 40, 12);
    assert_eq!(selected(&a), before + 1);
    mouse(&mut a, MouseEventKind::ScrollUp, 40, 12);
    assert_eq!(selected(&a), before);
}

/// Every key the explorer's keymap acts on is in the help, under its own name.
#[test]
fn help_lists_every_key_that_works() {
    let bindings = bindings();
    let listed: Vec<&str> = bindings
        .iter()
        .flat_map(|(keys, _)| keys.split_whitespace())
        .collect();
    let mut keys: Vec<(KeyCode, String)> = (' '..='~')
        .map(|c| {
            let name = if c == ' ' {
                "Space".to_string()
            } else {
                c.to_string()
            };
            (KeyCode::Char(c), name)
        })
        .collect();
    for (code, name) in [
        (KeyCode::Up, "↑"),
        (KeyCode::Down, "↓"),
        (KeyCode::Left, "←"),
        (KeyCode::Right, "→"),
        (KeyCode::Tab, "Tab"),
        (KeyCode::BackTab, "S-Tab"),
        (KeyCode::Home, "Home"),
        (KeyCode::End, "End"),
        (KeyCode::PageUp, "PgUp"),
        (KeyCode::PageDown, "PgDn"),
        (KeyCode::Enter, "Enter"),
        (KeyCode::Esc, "Esc"),
    ] {
        keys.push((code, name.to_string()));
    }
    for (code, name) in keys {
        let event = Event::Key(KeyEvent::new(code, KeyModifiers::NONE));
        if action_for_event(&Mode::Normal, &event).is_some() {
            assert!(
                listed.contains(&name.as_str()),
                "{name} works but the help omits it"
            );
        }
    }
    // At the smallest size every line shows, whole.
    let mut a = app();
    key(&mut a, KeyCode::Char('?'));
    let shown = screen(&a, 80, 24).join("\n");
    let last_hint = INPUT_HINTS[INPUT_HINTS.len() - 1];
    for what in bindings
        .iter()
        .map(|(_, what)| what.as_str())
        .chain([last_hint])
    {
        assert!(shown.contains(what), "{what} is cut at 80×24:\n{shown}");
    }
}

impl App {
    fn mode_confirm(&self) -> Option<Confirm> {
        match &self.mode {
            Mode::Confirm(confirm) => Some(confirm.clone()),
            _ => None,
        }
    }
}

/// A table preset's e and x_pl are Fig. 5's stand-ins: the form says "assumed" beside them, an
/// edit makes the value given, a reset makes it assumed again.
#[test]
fn a_preset_s_stand_ins_are_shown_as_assumed_until_edited() {
    let registry = Registry::builtin().unwrap();
    let scene = registry.scene("steel-sphere-r10-plate").unwrap();
    let mut a = App::new(scene, registry, MarkerStyle::Braille, Theme::Plain);
    let assumed_rows = |a: &App| {
        screen(a, 160, 48)
            .iter()
            .filter(|l| l.contains(" assumed"))
            .count()
    };
    assert_eq!(assumed_rows(&a), 2);
    let why = crate::format::recommendation::why(a.advice().unwrap(), &a.draft.scene);
    assert!(why.contains("e = 0.6 was not given"), "{why}");
    a.cursor = Cursor::Field(Field::Number(SceneKey::Restitution));
    key(&mut a, KeyCode::Left);
    assert!(!a.draft.scene.assumed.restitution);
    assert_eq!(assumed_rows(&a), 1);
    let why = crate::format::recommendation::why(a.advice().unwrap(), &a.draft.scene);
    assert!(
        !why.contains("was not given (a stand-in): what rests on e"),
        "{why}"
    );
    update(&mut a, Action::ResetField);
    assert!(a.draft.scene.assumed.restitution);
    assert_eq!(assumed_rows(&a), 2);
}
