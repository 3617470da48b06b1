//! No traps: quitting never drops edits but by the one key that says so, and `s` there saves and
//! quits; a field opens selected (typing replaces it); the picker's digits and exact names; the
//! cursor moves without taking the focus from the checked models; a click moves nothing it points
//! at; view 4 exports its sweep; the data cursor names its curves and jumps to a peak.

use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{
    Event, KeyCode, KeyModifiers, MouseButton, MouseEvent, MouseEventKind,
};
use ratatui::layout::{Position, Rect};

use crate::model::ForceModel;
use crate::model::presets::DEFAULT_SCENE;
use crate::model::scene_key::{BodyField, BodyIndex, SceneKey};
use crate::model::study::runner;

use super::action::Action;
use super::app::{App, Confirm, Cursor, Export, Mode, PromptKind};
use super::app_daily_tests::{preset_app, screen};
use super::app_tests::{app, enter_text, key, key_with, settle, type_text};
use super::field::Field;
use super::keymap::{INPUT_HINTS, action_for_event, bindings};
use super::render;
use super::tab::Tab;
use super::testing::{TempPath, temp_path};
use super::update::update;

const R1: Field = Field::Number(SceneKey::Body(BodyIndex::One, BodyField::Radius));

/// Solves and studies everything queued, as the workers would.
fn settle_all(app: &mut App) {
    loop {
        settle(app);
        let studies = app.take_studies();
        if studies.is_empty() {
            return;
        }
        for job in studies {
            if let Some(outcome) = runner::run(&job, &|| false) {
                update(app, Action::Studied(Ok(outcome)));
            }
        }
    }
}

/// The explorer on the default preset with a user folder of its own, edited (v₀ nudged).
fn edited_app(label: &str) -> (App, TempPath) {
    let (mut app, dir) = preset_app(label);
    key(&mut app, KeyCode::Right);
    assert!(app.is_dirty());
    (app, dir)
}

/// The quit question, as the bottom row shows it at 80 columns.
fn question(app: &App) -> String {
    screen(app, 80, 24).pop().unwrap()
}

#[test]
fn the_quit_question_says_what_each_key_does_and_each_key_does_it() {
    // The words: y quits without saving, s saves and quits, other keys stay; whole at 80 columns.
    let (mut a, dir) = edited_app("quit-words");
    key(&mut a, KeyCode::Char('q'));
    let asked = question(&a);
    for words in [
        "y quit without saving",
        "s save and quit",
        "other keys stay",
    ] {
        assert!(asked.contains(words), "{asked:?}");
    }
    assert!(
        asked.trim_end().ends_with("other keys stay"),
        "not cut: {asked:?}"
    );

    // q again is another key: it stays, the edit kept.
    key(&mut a, KeyCode::Char('q'));
    assert!(!a.quit, "q q must not quit without saving");
    assert!(matches!(a.mode, Mode::Normal));
    assert!(a.is_dirty(), "the edit is kept");
    for other in [
        KeyCode::Char('n'),
        KeyCode::Esc,
        KeyCode::Enter,
        KeyCode::Char('x'),
    ] {
        key(&mut a, KeyCode::Char('q'));
        key(&mut a, other);
        assert!(!a.quit && matches!(a.mode, Mode::Normal), "{other:?} stays");
    }

    // y: quits without saving, as it says.
    key(&mut a, KeyCode::Char('q'));
    key(&mut a, KeyCode::Char('y'));
    assert!(a.quit);
    assert!(!dir.join("scenes").exists(), "nothing saved");
}

#[test]
fn q_s_enter_saves_and_quits_and_esc_there_stays() {
    let (mut a, dir) = edited_app("quit-save");
    key(&mut a, KeyCode::Char('q'));
    key(&mut a, KeyCode::Char('s'));
    match &a.mode {
        Mode::Prompt(p) => {
            assert_eq!(p.kind, PromptKind::Save);
            assert!(p.then_quit);
            assert_eq!(p.input.value(), format!("{DEFAULT_SCENE}-edited"));
        }
        other => panic!("{other:?}"),
    }
    assert!(question(&a).contains("Save, then quit"), "{}", question(&a));
    // Esc at the name: back to the explorer, nothing lost, nothing quit.
    key(&mut a, KeyCode::Esc);
    assert!(!a.quit && matches!(a.mode, Mode::Normal) && a.is_dirty());

    // A refused name stays in the prompt, unquit.
    key(&mut a, KeyCode::Char('q'));
    key(&mut a, KeyCode::Char('s'));
    enter_text(&mut a, "  ");
    assert!(!a.quit && matches!(a.mode, Mode::Prompt(_)));
    key(&mut a, KeyCode::Esc);

    // q s Enter: saved under the proposed name, and quit.
    key(&mut a, KeyCode::Char('q'));
    key(&mut a, KeyCode::Char('s'));
    key(&mut a, KeyCode::Enter);
    let file = dir.join(format!("scenes/{DEFAULT_SCENE}-edited.toml"));
    let saved = std::fs::read_to_string(&file);
    assert!(a.quit, "q s Enter quits");
    assert!(!a.is_dirty());
    assert!(saved.unwrap().contains("v0 = 0.31"));

    // A built-in's name asks first; y there saves and quits too.
    let (mut b, dir_b) = edited_app("quit-shadow");
    key(&mut b, KeyCode::Char('q'));
    key(&mut b, KeyCode::Char('s'));
    enter_text(&mut b, DEFAULT_SCENE);
    assert!(matches!(
        &b.mode,
        Mode::Confirm(Confirm::ShadowBuiltin {
            then_quit: true,
            ..
        })
    ));
    key(&mut b, KeyCode::Char('y'));
    assert!(b.quit);
    assert!(dir_b.join(format!("scenes/{DEFAULT_SCENE}.toml")).exists());

    // Ctrl-C twice is the documented way out at once.
    let (mut c, _dir_c) = edited_app("quit-interrupt");
    key_with(&mut c, KeyCode::Char('c'), KeyModifiers::CONTROL);
    assert!(!c.quit);
    key_with(&mut c, KeyCode::Char('c'), KeyModifiers::CONTROL);
    assert!(c.quit);
}

/// The value the open editor holds.
fn editor_text(app: &App) -> String {
    match &app.mode {
        Mode::Editing(editor) => editor.input.value().to_string(),
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_field_opens_selected_and_the_first_key_typed_replaces_it() {
    let mut a = app();
    settle(&mut a);
    key(&mut a, KeyCode::Enter);
    assert_eq!(editor_text(&a), "0.3 m/s");
    type_text(&mut a, "1.5");
    assert_eq!(
        editor_text(&a),
        "1.5",
        "typing replaces, never `0.3 m/s1.5`"
    );
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.draft.scene.impact.v0, 1.5);

    // Backspace clears the selection; a cursor key keeps the text to edit it.
    key(&mut a, KeyCode::Enter);
    key(&mut a, KeyCode::Backspace);
    assert_eq!(editor_text(&a), "");
    key(&mut a, KeyCode::Esc);
    key(&mut a, KeyCode::Enter);
    key(&mut a, KeyCode::End);
    type_text(&mut a, "0");
    assert_eq!(editor_text(&a), "1.5 m/s0");
    key(&mut a, KeyCode::Esc);

    // Ctrl-W drops the last word (the unit), Ctrl-U the whole line.
    key(&mut a, KeyCode::Enter);
    type_text(&mut a, "1.5 mm");
    key_with(&mut a, KeyCode::Char('w'), KeyModifiers::CONTROL);
    assert_eq!(editor_text(&a), "1.5 ");
    type_text(&mut a, "km/h");
    key(&mut a, KeyCode::Enter);
    assert!((a.draft.scene.impact.v0 - 1.5 / 3.6).abs() < 1e-15);
    key(&mut a, KeyCode::Enter);
    type_text(&mut a, "9");
    key_with(&mut a, KeyCode::Char('u'), KeyModifiers::CONTROL);
    assert_eq!(editor_text(&a), "");
    key(&mut a, KeyCode::Esc);

    // A length in centimetres.
    a.cursor = Cursor::Field(R1);
    key(&mut a, KeyCode::Enter);
    type_text(&mut a, "1 cm");
    key(&mut a, KeyCode::Enter);
    assert!(matches!(a.mode, Mode::Normal), "{:?}", a.mode);
    assert!((a.draft.scene.body1.shape.radius() - 0.01).abs() < 1e-15);

    // The selection is shown: the value's cells reversed while it is selected.
    key(&mut a, KeyCode::Enter);
    let selected = screen_has_reversed(&a, &editor_text(&a));
    type_text(&mut a, "2");
    assert!(selected && !screen_has_reversed(&a, "2"));
}

/// Whether `text` is drawn reversed somewhere on a 160×48 screen.
fn screen_has_reversed(app: &App, text: &str) -> bool {
    use ratatui::style::Modifier;
    let mut terminal = Terminal::new(TestBackend::new(160, 48)).unwrap();
    terminal.draw(|frame| render::draw(frame, app)).unwrap();
    let buffer = terminal.backend().buffer();
    let n = text.chars().count() as u16;
    (0..48).any(|y| {
        (0..160u16.saturating_sub(n)).any(|x| {
            let cells: Vec<_> = (x..x + n).map(|x| &buffer[(x, y)]).collect();
            let drawn: String = cells.iter().map(|c| c.symbol()).collect();
            drawn == text
                && cells
                    .iter()
                    .all(|c| c.modifier.contains(Modifier::REVERSED))
        })
    })
}

#[test]
fn line_editing_keys_and_units_are_documented_in_the_help() {
    let help: String = bindings()
        .iter()
        .map(|(keys, what)| format!("{keys} {what}\n"))
        .chain(INPUT_HINTS.iter().map(|line| format!("{line}\n")))
        .collect();
    for words in ["Ctrl-U", "Ctrl-W", "replaces", "cm", "km/h"] {
        assert!(help.contains(words), "{words} in\n{help}");
    }
    let docs = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/keys.md"))
        .expect("docs/keys.md");
    for words in [
        "Ctrl-U",
        "Ctrl-W",
        "cm",
        "km/h",
        "save and quit",
        "`<` `>`",
        "`P`",
    ] {
        assert!(docs.contains(words), "{words} in docs/keys.md");
    }
}

/// Opens the picker and types `filter` into it.
fn filter(app: &mut App, text: &str) {
    key(app, KeyCode::Char('p'));
    type_text(app, text);
}

#[test]
fn the_pickers_digits_apply_a_material_after_a_filter_and_an_exact_name_loads() {
    let mut a = app();
    settle(&mut a);
    // "alloy" leaves the aluminium alloy material selected: 2 applies it to body 2.
    filter(&mut a, "alloy");
    key(&mut a, KeyCode::Char('2'));
    assert!(matches!(a.mode, Mode::Normal), "{:?}", a.mode);
    assert_eq!(a.draft.scene.body2.material.name, "aluminium-alloy");
    assert_eq!(a.draft.scene.body1.material.name, "steel");
    // "steel" is a material's exact name: 1 applies it to body 1 (a filter is typed).
    a.draft.scene.body1.material = a.draft.scene.body2.material.clone();
    filter(&mut a, "steel");
    key(&mut a, KeyCode::Char('1'));
    assert_eq!(a.draft.scene.body1.material.name, "steel");
    // On a scene a digit filters: `r10` finds the scenes of R = 10 mm.
    filter(&mut a, "sphere-r1");
    match &a.mode {
        Mode::Picker(picker) => {
            assert_eq!(picker.filter, "sphere-r1");
            assert!(
                picker
                    .visible()
                    .iter()
                    .all(|e| e.name.contains("sphere-r1"))
            );
        }
        other => panic!("{other:?}"),
    }
    key(&mut a, KeyCode::Esc);
    // Enter loads the scene named exactly, not the first whose name contains it.
    filter(&mut a, "steel-sphere-r10-plate");
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.preset.as_deref(), Some("steel-sphere-r10-plate"));
}

#[test]
fn moving_the_cursor_over_the_models_does_not_focus_an_unchecked_one() {
    let mut a = app();
    settle(&mut a);
    let checked = a.checked_models();
    assert_eq!(a.focused, ForceModel::Proposed);
    // Walk the cursor down the whole checklist: the focus is only ever a checked model.
    a.cursor = Cursor::Model(ForceModel::ALL[0]);
    for _ in 0..ForceModel::ALL.len() {
        key(&mut a, KeyCode::Down);
        assert!(
            a.is_checked(a.focused),
            "{:?} focused at {:?}",
            a.focused,
            a.cursor
        );
    }
    key(&mut a, KeyCode::End);
    assert!(a.is_checked(a.focused));
    // Views 2–3 and the export use it.
    let focused = a.focused;
    key(&mut a, KeyCode::Char('e'));
    match &a.mode {
        Mode::Prompt(p) => assert_eq!(p.kind, PromptKind::Export(Export::Trajectory(focused))),
        other => panic!("{other:?}"),
    }
    key(&mut a, KeyCode::Esc);
    // [ and ] walk the checked models only, in the table's order, around.
    let mut seen = Vec::new();
    for _ in 0..checked.len() {
        key(&mut a, KeyCode::Char(']'));
        seen.push(a.focused);
    }
    seen.sort_by_key(|m| m.index());
    assert_eq!(seen, checked, "] visits each checked model once");
    key(&mut a, KeyCode::Char(']'));
    key(&mut a, KeyCode::Char('['));
    assert!(a.is_checked(a.focused));
    // Unchecking the focused model moves the focus to a checked one.
    let before = a.focused;
    a.toggle(before);
    assert_ne!(a.focused, before);
    assert!(a.is_checked(a.focused));
    // The stability view studies the focused model.
    key(&mut a, KeyCode::Char('3'));
    settle_all(&mut a);
    let lines = screen(&a, 160, 48).join("\n");
    assert!(lines.contains(a.focused.label()), "{lines}");
}

fn click(app: &mut App, column: u16, row: u16) {
    let event = Event::Mouse(MouseEvent {
        kind: MouseEventKind::Down(MouseButton::Left),
        column,
        row,
        modifiers: KeyModifiers::NONE,
    });
    if let Some(action) = action_for_event(&app.mode, &event) {
        update(app, action);
    }
}

/// The text of the left column (the form and the model list) row by row, with what a click may
/// change blanked: the marks of the cursor and focus (`▸`), and the rows below the form's panes,
/// where the field under the cursor is described (on roomy screens, where panes have side
/// borders); the rest must stay where it is. (The charts may change: a click on a model's name
/// focuses it.)
fn layout_text(app: &App, width: u16, height: u16) -> Vec<String> {
    let lines = screen(app, width, height);
    let roomy = lines[1].starts_with('┌');
    let left = usize::from(crate::ui::layout::left_width(Rect::new(
        0, 0, width, height,
    )));
    lines
        .into_iter()
        .map(|line| {
            let line: String = line.replace('▸', " ").chars().take(left).collect();
            if roomy && !line.starts_with(['│', '┌', '└']) {
                String::new()
            } else {
                line
            }
        })
        .collect()
}

#[test]
fn a_click_moves_nothing_it_points_at() {
    for (width, height) in [(160, 48), (120, 40), (100, 30), (80, 24)] {
        let mut a = app();
        update(&mut a, Action::Resize(width, height));
        settle(&mut a);
        // Scroll the models list away from its top first, by keys.
        a.cursor = Cursor::Model(ForceModel::ALL[ForceModel::ALL.len() - 1]);
        key(&mut a, KeyCode::Up);
        let left = Rect::new(0, 0, width / 3, height);
        let mut clicked = 0;
        for row in 1..height - 1 {
            for column in [7, 14] {
                if !left.contains(Position::new(column, row)) {
                    continue;
                }
                let before = layout_text(&a, width, height);
                click(&mut a, column, row);
                let after = layout_text(&a, width, height);
                clicked += 1;
                let changed: Vec<usize> = (0..before.len())
                    .filter(|&y| before[y] != after[y])
                    .collect();
                assert!(
                    changed.is_empty(),
                    "{width}×{height}: a click at ({column}, {row}) changed rows {changed:?}:\n{}\n---\n{}",
                    before.join("\n"),
                    after.join("\n")
                );
            }
        }
        assert!(clicked > 20);
    }
}

#[test]
fn view_4_exports_its_sweep_as_the_command_line_writes_it() {
    let mut a = app();
    update(&mut a, Action::Resize(160, 48));
    key(&mut a, KeyCode::Char('4'));
    settle_all(&mut a);
    let Some(Ok(data)) = a.studies.sweep().cloned() else {
        panic!("no sweep");
    };
    key(&mut a, KeyCode::Char('e'));
    match &a.mode {
        Mode::Prompt(p) => {
            assert_eq!(p.kind, PromptKind::Export(Export::Sweep));
            assert!(
                p.input.value().ends_with("-sweep-impact-v0.csv"),
                "{}",
                p.input.value()
            );
        }
        other => panic!("{other:?}"),
    }
    let path = temp_path("sweep.csv");
    enter_text(&mut a, path.to_str().unwrap());
    let text = std::fs::read_to_string(&path).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let models = &data.spec.models;
    assert_eq!(header.len(), 6 + 5 * models.len() + 1);
    assert_eq!(header[0], "impact.v0");
    assert_eq!(header[6], format!("{}.x_max", models[0]));
    let rows: Vec<&str> = lines.collect();
    assert_eq!(rows.len(), data.rows.len());
    // Each row's swept value and the first model's F_max, as the study computed them.
    for (line, row) in rows.iter().zip(&data.rows) {
        let cells: Vec<&str> = line.split(',').collect();
        assert_eq!(cells[0].parse::<f64>().unwrap(), row.value);
        let f_max = row
            .impacts
            .iter()
            .find(|p| p.model == models[0])
            .unwrap()
            .f_max;
        assert_eq!(cells[7].parse::<f64>().ok(), f_max);
    }
    let news = a.message.clone().unwrap();
    assert!(
        !news.error && news.text.contains("exported the sweep"),
        "{news:?}"
    );
    // `f` still writes the figure.
    assert!(!Tab::named("sweep").unwrap().view().charts(&a).is_empty());
}

#[test]
fn the_data_cursor_names_each_curve_with_its_value_at_120_columns_and_jumps_to_the_peak() {
    let mut a = app();
    update(&mut a, Action::Resize(120, 40));
    settle(&mut a);
    key(&mut a, KeyCode::Char('.'));
    let lines = screen(&a, 120, 40).join("\n");
    // Each curve by its name, with its value: `proposed 254.9 / 94.12 N`.
    for model in a.checked_models() {
        let named = [model.label(), model.name(), model.short()]
            .iter()
            .any(|name| {
                lines
                    .match_indices(&format!("{name} "))
                    .any(|(i, n)| lines[i + n.len()..].starts_with(|c: char| c.is_ascii_digit()))
            });
        assert!(named, "{} named with its value:\n{lines}", model.name());
    }
    // P: the cursor on the focused model's F_max; the readout shows it, to 4 digits.
    key(&mut a, KeyCode::Char('P'));
    let f_max = a.solutions.solution(a.focused).unwrap().summary.f_max;
    let lines = screen(&a, 120, 40).join("\n");
    let shown = format!(
        "{} {} ",
        a.focused.name(),
        crate::format::units::sig(f_max, 4)
    );
    assert!(lines.contains(&shown), "{shown} in\n{lines}");
    // At 80×24 the reading is a box on the plot with a blank column after each row: a mark's
    // label never runs on from it (it read `proposed 326 / 248 N326.4 N`).
    update(&mut a, Action::Resize(80, 24));
    let lines = screen(&a, 80, 24);
    let name = format!("{} ", a.focused.name());
    let row = lines
        .iter()
        .find(|l| l.contains(&name) && l.contains(" N"))
        .unwrap_or_else(|| panic!("{name} read at 80×24:\n{}", lines.join("\n")));
    let after = &row[row.find(&name).unwrap()..];
    let end = after.find(" N").unwrap() + 2;
    assert!(after[end..].starts_with(' '), "{row}");
    update(&mut a, Action::Resize(120, 40));
    // < > move ten steps at once.
    let at = a.views.explorer.data_cursor.unwrap();
    key(&mut a, KeyCode::Char('<'));
    assert_eq!(a.views.explorer.data_cursor, Some(at.saturating_sub(100)));
}
