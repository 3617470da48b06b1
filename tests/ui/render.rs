//! The explorer rendered into ratatui's TestBackend: snapshots of the default (Fig. 5) scene's
//! layout and of the too-small screen, and checks of what the screens say: each view's charts and
//! tables, an invalid field, the help, colour, NO_COLOR and markers. The layout snapshots blank the
//! rows that list the law table or the views (a new law or view rewrites no snapshot); those rows
//! are checked by content, for any number of laws and views.

use std::time::Duration;

use hertz_tui::chart::{Ink, method_glyph, model_glyph};
use hertz_tui::model::ForceModel;
use hertz_tui::model::ode::Method;
use hertz_tui::model::presets::{DEFAULT_SCENE, Registry};
use hertz_tui::model::scene_key::{BodyField, BodyIndex, SceneKey};
use hertz_tui::model::study::runner::{self, StudyOutcome, StudyResult, WorkPrecisionData};
use hertz_tui::ui::MarkerStyle;
use hertz_tui::ui::action::Action;
use hertz_tui::ui::app::{App, Cursor};
use hertz_tui::ui::field::Field;
use hertz_tui::ui::render::draw;
use hertz_tui::ui::style::{Role, Theme, sample};
use hertz_tui::ui::tab::Tab;
use hertz_tui::ui::update::update;
use hertz_tui::ui::worker;
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::{Event, KeyCode, KeyEvent, KeyModifiers};
use ratatui::style::Color;

/// The explorer on the built-in default scene, every solve done, with a fixed recompute time.
pub fn app_with(marker: MarkerStyle, theme: Theme) -> App {
    let registry = Registry::builtin().unwrap();
    let scene = registry.scene(DEFAULT_SCENE).unwrap();
    let mut app = App::new(scene, registry, marker, theme);
    settle(&mut app);
    app
}

pub fn app() -> App {
    app_with(MarkerStyle::Braille, Theme::Dark)
}

/// Solves and studies everything queued on this thread, as the workers would, then puts fixed
/// stand-ins in place of the measured wall times so that snapshots are deterministic.
pub fn settle(app: &mut App) {
    loop {
        let jobs = app.take_jobs();
        let studies = app.take_studies();
        if jobs.is_empty() && studies.is_empty() {
            break;
        }
        for job in jobs {
            update(app, Action::Solved(Ok(worker::solve(&job))));
        }
        for job in studies {
            if let Some(outcome) = runner::run(&job, &|| false) {
                update(app, Action::Studied(Ok(without_wall_times(outcome))));
            }
        }
    }
    app.last_recompute = Some(Duration::from_micros(1500));
}

/// Stand-in for a measured time per solve: 25 ns per force evaluation.
fn stand_in_seconds(force_evals: usize) -> f64 {
    force_evals as f64 * 25e-9
}

/// The outcome with every wall time replaced by [`stand_in_seconds`].
fn without_wall_times(mut outcome: StudyOutcome) -> StudyOutcome {
    match &mut outcome.result {
        StudyResult::WorkPrecision(Ok(data)) => {
            let mut fixed = WorkPrecisionData::clone(data);
            for row in &mut fixed.rows {
                row.seconds_per_solve = row.force_evals.map(stand_in_seconds);
            }
            *data = std::sync::Arc::new(fixed);
        }
        StudyResult::Current(Ok(point)) => {
            point.seconds_per_solve = stand_in_seconds(point.force_evals);
        }
        _ => {}
    }
    outcome
}

/// The app on `tab` at 160×48, its studies done.
fn app_on(tab: Tab) -> App {
    let mut app = app();
    update(&mut app, Action::Resize(160, 48));
    update(&mut app, Action::Tab(tab));
    settle(&mut app);
    app
}

pub fn press(app: &mut App, code: KeyCode) {
    let event = Event::Key(KeyEvent::new(code, KeyModifiers::NONE));
    if let Some(action) = hertz_tui::ui::keymap::action_for_event(&app.mode, &event) {
        update(app, action);
    }
}

pub fn render(app: &App, width: u16, height: u16) -> Terminal<TestBackend> {
    let mut terminal = Terminal::new(TestBackend::new(width, height)).unwrap();
    terminal.draw(|frame| draw(frame, app)).unwrap();
    terminal
}

pub fn text(buffer: &Buffer) -> String {
    let width = buffer.area.width as usize;
    buffer
        .content
        .chunks(width)
        .map(|row| row.iter().map(|c| c.symbol()).collect::<String>())
        .collect::<Vec<_>>()
        .join("\n")
}

/// Types `value` into the field under the cursor by keystrokes: Enter, clear, the text, Enter.
fn type_in(app: &mut App, value: &str) {
    press(app, KeyCode::Enter);
    update(app, Action::Input(tui_input::InputRequest::DeleteLine));
    for c in value.chars() {
        press(app, KeyCode::Char(c));
    }
    press(app, KeyCode::Enter);
}

/// The app with body 1's ν set to 0.6 by keystrokes: invalid, and the last results stay.
pub fn invalid_app() -> App {
    let mut app = app();
    app.cursor = Cursor::Field(Field::Number(SceneKey::Body(
        BodyIndex::One,
        BodyField::PoissonRatio,
    )));
    type_in(&mut app, "0.6");
    app
}

/// Fills the cells of the rows that list the views (the tab bar, the status line's hints) or the
/// law table (the Models pane below its title, in the left column) with `░`: what is left is the
/// layout, which no new law or view changes.
pub fn layout_of(app: &App, width: u16, height: u16) -> String {
    let screen = text(render(app, width, height).backend().buffer());
    let mut rows: Vec<Vec<char>> = screen.lines().map(|l| l.chars().collect()).collect();
    let models = rows
        .iter()
        .position(|r| {
            let r: String = r.iter().collect();
            r.trim_start_matches('┌').starts_with("Models")
        })
        .unwrap_or_else(|| panic!("no Models pane at {width}×{height}:\n{screen}"));
    let left = usize::from(hertz_tui::ui::layout::left_width(
        ratatui::layout::Rect::new(0, 0, width, height),
    ));
    let last = rows.len() - 1;
    for (y, row) in rows.iter_mut().enumerate() {
        let masked = if y == 0 || y == last {
            row.len()
        } else if y > models {
            left
        } else {
            0
        };
        row[..masked].fill('░');
    }
    rows.iter()
        .map(|r| r.iter().collect::<String>())
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn default_scene_layout_80x24() {
    insta::assert_snapshot!(layout_of(&app(), 80, 24));
}

#[test]
fn default_scene_layout_160x48() {
    insta::assert_snapshot!(layout_of(&app(), 160, 48));
}

/// The rows the layout snapshots blank: the tab bar names every view after its digit, in order,
/// the shown one first; the status line names the digits of all of them.
#[test]
fn the_tab_bar_and_the_status_line_name_every_view() {
    let app = app();
    for (width, height) in [(80, 24), (160, 48)] {
        let screen = text(render(&app, width, height).backend().buffer());
        let lines: Vec<&str> = screen.lines().collect();
        let bar = lines[0];
        let status = lines[lines.len() - 1];
        let mut from = 0;
        for tab in Tab::all() {
            // At 80 columns the first views must fit; the wide screen has room for all of them.
            if width == 80 && tab != Tab::HOME {
                continue;
            }
            let entry = match tab.key() {
                Some(key) => format!("{key} {}", tab.title()),
                None => tab.title().to_string(),
            };
            let at = bar[from..]
                .find(&entry)
                .unwrap_or_else(|| panic!("{width}×{height}: {entry} after column {from}: {bar}"));
            from += at + entry.len();
        }
        let views = format!("{} views", hertz_tui::ui::views::keys_hint());
        assert!(status.contains(&views), "{width}×{height}: {status}");
        assert!(status.contains("? help"), "{width}×{height}: {status}");
    }
    assert_eq!(
        hertz_tui::ui::views::keys_hint(),
        format!("1-{}", Tab::all().count())
    );
}

/// An invalid value: its field says ✗ with the model's message under it, the panes and the status
/// line say the results are those of the last valid scene, and they are: every checked model's
/// row still shows the x_max solved before the edit.
#[test]
fn an_invalid_field_says_why_and_keeps_the_last_results() {
    let valid = app();
    let app = invalid_app();
    for (width, height) in [(80, 24), (160, 48)] {
        let screen = text(render(&app, width, height).backend().buffer());
        assert!(screen.contains("0.6 ✗"), "{width}×{height}:\n{screen}");
        assert!(
            screen.contains("body1.material.poisson_ratio"),
            "{width}×{height}:\n{screen}"
        );
        assert!(screen.contains("last valid scene"), "{width}×{height}");
        assert!(screen.contains("invalid scene"), "{width}×{height}");
        let results = &screen[screen.find("x_max").expect("the results header")..];
        for model in app.checked_models() {
            let x_max = valid.solutions.solution(model).unwrap().summary.x_max;
            let shown = hertz_tui::format::units::sig(x_max * 1e6, 4);
            assert!(
                results.contains(&shown),
                "{width}×{height}: {model} x_max {shown} µm:\n{screen}"
            );
        }
    }
    let wide = text(render(&app, 160, 48).backend().buffer());
    for pane in [
        "Body 1 · sphere · steel (edited)",
        "F(x) force–approach · last valid scene",
        "v(x) velocity–approach · last valid scene",
        "F(t) force–time · last valid scene",
        "Results · last valid scene",
    ] {
        assert!(wide.contains(pane), "{pane}:\n{wide}");
    }
}

/// `?` opens the help over any view: every key binding the keymap has, the digit of every view
/// and its name, whole, at the smallest size and at 160×48.
#[test]
fn the_help_lists_every_view_and_key() {
    let bindings = hertz_tui::ui::keymap::bindings();
    for (width, height) in [(80, 24), (160, 48)] {
        for tab in Tab::all() {
            let mut app = app();
            update(&mut app, Action::Tab(tab));
            press(&mut app, KeyCode::Char('?'));
            let screen = text(render(&app, width, height).backend().buffer());
            assert!(
                screen.contains("Help · keys"),
                "{width}×{height}:\n{screen}"
            );
            let views = screen
                .lines()
                .find(|l| l.contains("views: "))
                .unwrap_or_else(|| panic!("{width}×{height}: no views line:\n{screen}"));
            let (keys, names) = views.split_once("views: ").unwrap();
            // The views' names may wrap onto the lines under the first.
            let names = &screen[screen.find(names).expect("the views line")..];
            for other in Tab::all() {
                if let Some(key) = other.key() {
                    assert!(
                        keys.split_whitespace().any(|k| k == key.to_string()),
                        "{width}×{height}: key {key} in {views}"
                    );
                }
                assert!(
                    names.contains(other.view().short_title()),
                    "{width}×{height}: {} in {views}",
                    other.view().short_title()
                );
            }
            for (keys, what) in &bindings {
                let line = screen
                    .lines()
                    .find(|l| l.contains(what.as_str()))
                    .unwrap_or_else(|| panic!("{width}×{height}: {what} cut:\n{screen}"));
                assert!(
                    line.contains(keys.as_str()),
                    "{width}×{height}: {keys} {what}"
                );
            }
        }
    }
}

#[test]
fn too_small_79x24() {
    insta::assert_snapshot!(render(&app(), 79, 24).backend());
}

#[test]
fn too_small_60x10() {
    insta::assert_snapshot!(render(&app(), 60, 10).backend());
}

#[test]
fn every_size_from_the_minimum_up_draws_without_panicking() {
    let app = app();
    for (w, h) in [
        (80, 24),
        (81, 25),
        (99, 31),
        (119, 39),
        (120, 40),
        (200, 60),
        (30, 5),
        (1, 1),
    ] {
        let screen = text(render(&app, w, h).backend().buffer());
        if w >= 80 && h >= 24 {
            assert!(
                screen.contains("F(x)") || screen.contains("F(t)"),
                "{w}×{h}"
            );
            assert!(!screen.contains("NaN"), "{w}×{h}");
        }
    }
}

#[test]
fn results_show_every_checked_model_and_the_hertz_estimate() {
    let app = app();
    let screen = text(render(&app, 160, 48).backend().buffer());
    for model in app.checked_models() {
        assert!(screen.contains(model.label()), "{model}");
        let x_max = app.solutions.solution(model).unwrap().summary.x_max;
        let shown = hertz_tui::format::units::sig(x_max * 1e6, 4);
        assert!(screen.contains(&shown), "{model}: x_max {shown} µm");
    }
    assert!(screen.contains("Hertz estimate"));
    assert!(screen.contains("yield begins"));
    assert!(screen.contains("use: proposed"));
}

#[test]
fn invalid_field_is_red_with_the_model_message() {
    let terminal = render(&invalid_app(), 160, 48);
    let buffer = terminal.backend().buffer();
    let screen = text(buffer);
    let message = "body1.material.poisson_ratio must be in [0, 0.5), got 0.6";
    let first_line = &message[..30];
    assert!(screen.contains(first_line), "{screen}");
    // The cells of the message are the theme's red (bright red on the dark theme: 5.3:1 on black).
    let (row, line) = screen
        .lines()
        .enumerate()
        .find(|(_, l)| l.contains(first_line))
        .unwrap();
    let col = line[..line.find(first_line).unwrap()].chars().count();
    let cell = &buffer[(col as u16, row as u16)];
    assert_eq!(Some(cell.fg), Theme::Dark.style(Role::Error).fg);
}

#[test]
fn no_color_draws_without_colours() {
    let app = app_with(MarkerStyle::Braille, Theme::Plain);
    let terminal = render(&app, 160, 48);
    let buffer = terminal.backend().buffer();
    assert!(
        buffer
            .content
            .iter()
            .all(|c| matches!(c.fg, Color::Reset) && matches!(c.bg, Color::Reset)),
        "NO_COLOR: no cell has a colour"
    );
    let coloured = render(&self::app(), 160, 48);
    assert!(
        coloured
            .backend()
            .buffer()
            .content
            .iter()
            .any(|c| c.fg == Color::Yellow),
        "the proposed model is drawn in yellow with colour on"
    );
}

#[test]
fn markers_follow_the_option() {
    let braille = text(render(&app(), 160, 48).backend().buffer());
    assert!(
        braille
            .chars()
            .any(|c| ('\u{2801}'..='\u{28FF}').contains(&c))
    );
    let dot = text(
        render(&app_with(MarkerStyle::Dot, Theme::Dark), 160, 48)
            .backend()
            .buffer(),
    );
    assert!(!dot.chars().any(|c| ('\u{2801}'..='\u{28FF}').contains(&c)));
    assert!(dot.contains('•'));
    let block = text(
        render(&app_with(MarkerStyle::Block, Theme::Dark), 160, 48)
            .backend()
            .buffer(),
    );
    assert!(block.contains('█'));
}

#[test]
fn an_edit_changes_the_charts_and_the_results() {
    let mut app = app();
    let before = text(render(&app, 160, 48).backend().buffer());
    press(&mut app, KeyCode::Enter);
    update(&mut app, Action::Input(tui_input::InputRequest::DeleteLine));
    for c in "0.05".chars() {
        press(&mut app, KeyCode::Char(c));
    }
    press(&mut app, KeyCode::Enter);
    settle(&mut app);
    let after = text(render(&app, 160, 48).backend().buffer());
    assert_ne!(before, after);
    let x_max = app
        .solutions
        .solution(ForceModel::Proposed)
        .unwrap()
        .summary
        .x_max;
    assert!(after.contains(&hertz_tui::format::units::sig(x_max * 1e6, 4)));
    assert!(after.contains("v₀     0.05 m/s"));
}

#[test]
fn work_precision_160x48() {
    let app = app_on(Tab::named("work-precision").unwrap());
    let screen = text(render(&app, 160, 48).backend().buffer());
    assert!(
        screen.contains("log₁₀ error against log₁₀ s per solve"),
        "{screen}"
    );
    assert!(screen.contains("log₁₀ force evaluations"));
    let title = format!("Work–precision · {}", app.focused.label());
    assert!(screen.contains(&title), "{title}:\n{screen}");
    for method in Method::ALL {
        let entry = format!(
            "{} {method}",
            sample(method_glyph(method), Ink::Method(method).dash())
        );
        assert!(screen.contains(&entry), "{entry} in the legend:\n{screen}");
    }
    let current = app.studies.current().unwrap().as_ref().unwrap();
    let evals = format!("· {} force evaluations ·", current.force_evals);
    assert!(screen.contains(&evals), "{evals}:\n{screen}");
    assert!(screen.contains("explorer's solve"));
    assert!(screen.contains('█'), "the explorer's solve is marked");
    assert!(!screen.contains("NaN") && !screen.contains("computing…"));
}

#[test]
fn stability_160x48() {
    let app = app_on(Tab::named("stability").unwrap());
    let screen = text(render(&app, 160, 48).backend().buffer());
    assert!(screen.contains("auto: the rk4 critical step"), "{screen}");
    assert!(screen.contains("h·ω_max = 2.83"), "{screen}");
    let title = format!("Stability · {}", app.focused.label());
    assert!(screen.contains(&title), "{title}:\n{screen}");
    for method in [
        Method::Euler,
        Method::SymplecticEuler,
        Method::Verlet,
        Method::Rk4,
    ] {
        let row = format!(
            "{} {method}",
            sample(method_glyph(method), Ink::Method(method).dash())
        );
        assert!(screen.contains(&row), "{row}:\n{screen}");
    }
    assert!(screen.contains("diverged at t = ") || screen.contains("energy drift"));
    assert!(!screen.contains("measuring…") && !screen.contains("NaN"));
}

#[test]
fn sweep_160x48() {
    let app = app_on(Tab::named("sweep").unwrap());
    let screen = text(render(&app, 160, 48).backend().buffer());
    assert!(screen.contains("e_out against v₀"), "{screen}");
    assert!(
        screen.contains("v_y") && screen.contains("v_p"),
        "onset rules labelled"
    );
    assert_legend_names_the_checked_models(&app, &screen);
    assert!(!screen.contains("NaN") && !screen.contains("computing…"));
}

/// Each checked model is in the chart's legend by its glyph and id, whatever the number of laws.
fn assert_legend_names_the_checked_models(app: &App, screen: &str) {
    let checked = app.checked_models();
    assert!(checked.len() >= 3, "{checked:?}");
    for model in checked {
        let entry = format!(
            "{} {}",
            sample(model_glyph(model), Ink::Model(model).dash()),
            model.name()
        );
        assert!(screen.contains(&entry), "{entry} in the legend:\n{screen}");
    }
}

#[test]
fn restitution_160x48() {
    let mut app = app_on(Tab::named("restitution").unwrap());
    let screen = text(render(&app, 160, 48).backend().buffer());
    assert!(
        screen.contains("realised e against requested e"),
        "{screen}"
    );
    assert!(screen.contains("e_out against v₀"), "{screen}");
    assert!(
        screen.contains("v_y") && screen.contains("v_p"),
        "onset rules"
    );
    assert_legend_names_the_checked_models(&app, &screen);
    assert!(!screen.contains("NaN") && !screen.contains("computing…"));
    // c: the table of realised e for requested 0.1…0.9, the checked models' rows.
    press(&mut app, KeyCode::Char('c'));
    let table = text(render(&app, 160, 48).backend().buffer());
    assert!(
        table.contains("e = 0.1") && table.contains("e = 0.9"),
        "{table}"
    );
    assert!(table.contains("0.6630"), "Hunt–Crossley at 0.5: {table}");
}

#[test]
fn every_tab_draws_at_every_size_without_nan() {
    for tab in [
        Tab::named("work-precision").unwrap(),
        Tab::named("stability").unwrap(),
        Tab::named("sweep").unwrap(),
        Tab::named("restitution").unwrap(),
    ] {
        let app = app_on(tab);
        for (w, h) in [(80, 24), (100, 30), (120, 40), (200, 60), (30, 5)] {
            let screen = text(render(&app, w, h).backend().buffer());
            if std::env::var_os("SHOW_SCREENS").is_some() {
                println!("{tab:?} {w}×{h}\n{screen}\n");
            }
            assert!(
                !screen.contains("NaN") && !screen.contains("inf"),
                "{tab:?} {w}×{h}"
            );
            if w >= 80 {
                assert!(screen.contains(tab.title()), "{tab:?} {w}×{h}: the tab bar");
            }
        }
    }
}

#[test]
fn no_color_holds_in_every_tab() {
    for tab in [
        Tab::named("work-precision").unwrap(),
        Tab::named("stability").unwrap(),
        Tab::named("sweep").unwrap(),
    ] {
        let mut app = app_with(MarkerStyle::Braille, Theme::Plain);
        update(&mut app, Action::Resize(160, 48));
        update(&mut app, Action::Tab(tab));
        settle(&mut app);
        let terminal = render(&app, 160, 48);
        assert!(
            terminal
                .backend()
                .buffer()
                .content
                .iter()
                .all(|c| c.fg == Color::Reset && c.bg == Color::Reset),
            "{tab:?}: NO_COLOR, no cell has a colour"
        );
    }
}

/// The app with v₀ typed in by keystrokes, every solve done.
fn app_with_speed(v0: &str) -> App {
    let mut app = app();
    type_in(&mut app, v0);
    settle(&mut app);
    app
}

/// Half a unit in the last digit shown of `text` (`2.7e10` → 5e8, `150.7` → 0.05).
pub fn half_last_digit(text: &str) -> f64 {
    let (mantissa, exponent) = text.split_once('e').unwrap_or((text, "0"));
    let decimals = mantissa.split_once('.').map_or(0, |(_, d)| d.len()) as i32;
    0.5 * 10f64.powi(exponent.parse::<i32>().unwrap() - decimals)
}

/// Every number cell of the results table reads back as its value within the precision shown: a
/// number that does not fit its column is shown with fewer digits or in compact scientific form,
/// never cut (v₀ = 1e6 gave x_max `150687` µm for 1.507 m, F_max `2.71e1` for 2.71e10 N).
#[test]
fn results_cells_are_never_cut_numbers() {
    // A cell's value from the summary and the damping value of the row's law.
    type Get = fn(&hertz_tui::model::impact::ImpactSummary, Option<f64>) -> Option<f64>;
    let columns: [(&str, Get); 8] = [
        ("x_max", |s, _| Some(s.x_max * 1e6)),
        ("F_max", |s, _| Some(s.f_max)),
        ("t_c", |s, _| Some(s.t_contact * 1e6)),
        ("damping", |_, d| d),
        ("v_out", |s, _| Some(s.v_out)),
        ("e_out", |s, _| Some(s.e_out)),
        ("x_res", |s, _| Some(s.x_residual * 1e6)),
        ("ΔE", |s, _| Some(s.energy_dissipated * 1e3)),
    ];
    for v0 in ["1e6", "1e-12", "0.3"] {
        let app = app_with_speed(v0);
        for (width, height) in [(100, 30), (80, 24), (120, 40), (160, 48)] {
            let terminal = render(&app, width, height);
            let rows: Vec<Vec<String>> = text(terminal.backend().buffer())
                .lines()
                .map(|l| l.chars().map(String::from).collect())
                .collect();
            let row_text = |row: &[String], from: usize, to: usize| {
                row[from.min(row.len())..to.min(row.len())].concat()
            };
            let header = rows
                .iter()
                .position(|r| {
                    let t = r.concat();
                    t.contains("model") && t.contains("x_max")
                })
                .unwrap_or_else(|| panic!("no results header at {width}×{height}"));
            let line = rows[header].concat();
            // Column starts: each header word, located in cells.
            let mut starts: Vec<(usize, &str, Get)> = Vec::new();
            // Right of the table's "model": the models pane beside it has a "viscous damping"
            // heading.
            let table = rows[header]
                .windows(5)
                .position(|w| w.concat() == "model")
                .unwrap_or(0);
            for (name, get) in columns {
                let n = name.chars().count();
                if let Some(at) = rows[header][table..]
                    .windows(n)
                    .position(|w| w.concat() == name && !line.is_empty())
                {
                    starts.push((at + table, name, get));
                }
            }
            starts.sort_by_key(|(at, ..)| *at);
            assert!(starts.len() >= 3, "{width}×{height}: {line}");
            let mut ends: Vec<usize> = starts.iter().skip(1).map(|(at, ..)| *at).collect();
            // The last number column ends where "method" begins (or at the pane's edge).
            let next = rows[header]
                .windows(6)
                .position(|w| w.concat() == "method")
                .unwrap_or(rows[header].len());
            ends.push(next);
            let mut checked = 0;
            let mut dampings = 0;
            // One row per checked model, in order, under the header.
            for (i, model) in app.checked_models().into_iter().enumerate() {
                let Some(solution) = app.solutions.solution(model) else {
                    continue;
                };
                let row = &rows[header + 1 + i];
                let damping = app.solutions.damping(model).map(|d| d.value);
                for ((from, name, get), to) in starts.iter().zip(&ends) {
                    let cell = row_text(row, *from, *to);
                    let cell = cell.trim().trim_end_matches('│').trim();
                    let Some(value) = get(&solution.summary, damping) else {
                        assert_eq!(cell, "-", "{name} of {model:?}: a law without one");
                        continue;
                    };
                    // `χ 0.6`, `b 1.872e5 N·s/m^n`: the number is the second word.
                    let cell = match *name {
                        "damping" => cell.split_whitespace().nth(1).unwrap_or(cell),
                        _ => cell,
                    };
                    if cell == "…" || cell.starts_with('✗') {
                        continue;
                    }
                    let shown: f64 = cell.parse().unwrap_or_else(|_| {
                        panic!("v₀ {v0} at {width}×{height}: cell '{cell}' is not a number")
                    });
                    let tolerance = half_last_digit(cell) * (1.0 + 1e-9) + 1e-300;
                    assert!(
                        (shown - value).abs() <= tolerance,
                        "v₀ {v0} at {width}×{height}: '{cell}' shown for {value:e}\n{}\n{}",
                        rows[header].concat(),
                        row.concat()
                    );
                    checked += 1;
                    dampings += usize::from(*name == "damping");
                }
            }
            assert!(
                dampings > 0,
                "v₀ {v0} at {width}×{height}: no damping cell read\n{line}"
            );
            assert!(
                checked > 0,
                "v₀ {v0} at {width}×{height}: no cell checked\n{}",
                rows.iter()
                    .map(|r| r.concat())
                    .collect::<Vec<_>>()
                    .join("\n")
            );
        }
    }
}

/// R = 1e100 and v₀ = 1e6: every chart tick label is short (scientific by the shared formatter,
/// never `5000000000000001830474`), no axis runs out of prefixes (`[TN]`), and neighbouring x
/// labels keep a blank between them.
#[test]
fn extreme_values_give_short_tick_labels() {
    for (key, typed) in [
        (SceneKey::Body(BodyIndex::One, BodyField::Radius), "1e100"),
        (SceneKey::V0, "1e6"),
        (SceneKey::V0, "1e-12"),
    ] {
        let mut app = app();
        app.cursor = Cursor::Field(Field::Number(key));
        press(&mut app, KeyCode::Enter);
        update(&mut app, Action::Input(tui_input::InputRequest::DeleteLine));
        for c in typed.chars() {
            press(&mut app, KeyCode::Char(c));
        }
        press(&mut app, KeyCode::Enter);
        settle(&mut app);
        for (width, height) in [(80, 24), (100, 30), (160, 48)] {
            let screen = text(render(&app, width, height).backend().buffer());
            assert!(
                !screen.contains("[TN]") && !screen.contains("[Tm"),
                "{screen}"
            );
            for line in screen.lines() {
                let mut run = 0;
                for c in line.chars() {
                    run = if c.is_ascii_digit() { run + 1 } else { 0 };
                    assert!(run < 9, "{typed} at {width}×{height}: {line}\n{screen}");
                }
            }
        }
    }
}

#[test]
fn engine_panel_shows_the_translation_and_cycles_engines() {
    let mut app = app();
    press(&mut app, KeyCode::Char('t'));
    let screen = text(render(&app, 120, 40).backend().buffer());
    let engines = &hertz_tui::model::engine::ENGINES;
    let first = format!("Engine 1/{} · {}", engines.len(), engines[0].id);
    let second = format!("Engine 2/{} · {}", engines.len(), engines[1].id);
    assert!(screen.contains(&first), "{first}:\n{screen}");
    for expected in [
        "point_contact_stiffness = 8.063860624e7 N/m",
        "e_out                 0.6 (requested 0.6)",
    ] {
        assert!(screen.contains(expected), "{expected}:\n{screen}");
    }
    press(&mut app, KeyCode::Right);
    let screen = text(render(&app, 120, 40).backend().buffer());
    assert!(screen.contains(&second), "{second}:\n{screen}");
    press(&mut app, KeyCode::Down);
    let scrolled = text(render(&app, 120, 40).backend().buffer());
    let heading = format!("{} —", engines[1].name);
    assert!(!scrolled.contains(&heading), "{scrolled}");
    // End shows the script's last line, the RESULT print, at the panel's bottom.
    update(&mut app, hertz_tui::ui::action::Action::Resize(120, 40));
    press(&mut app, KeyCode::End);
    let end = text(render(&app, 120, 40).backend().buffer());
    assert!(end.contains("print(f\"RESULT e_out"), "{end}");
    press(&mut app, KeyCode::Home);
    let home = text(render(&app, 120, 40).backend().buffer());
    assert!(home.contains(&heading), "{home}");
    press(&mut app, KeyCode::Esc);
    let screen = text(render(&app, 120, 40).backend().buffer());
    assert!(!screen.contains(&second), "closed:\n{screen}");
}

/// The app with every model solved by explicit Euler at 50 µs, a step at which it blows up.
fn unstable_app() -> App {
    let mut app = app();
    for (field, value) in [(Field::Method, "euler"), (Field::Dt, "50 µs")] {
        app.cursor = Cursor::Field(field);
        type_in(&mut app, value);
        settle(&mut app);
    }
    app
}

#[test]
fn a_failed_solve_says_why_in_the_results_and_on_the_chart() {
    let app = unstable_app();
    for (w, h) in [(80, 24), (120, 40), (160, 48)] {
        let screen = text(render(&app, w, h).backend().buffer());
        let rows: Vec<&str> = screen
            .lines()
            .filter(|l| l.contains("✗ euler: the method is unstable"))
            .collect();
        // Every checked model's row, and the chart, say it; no row is a bare ✗.
        assert!(rows.len() >= 4, "{w}×{h}:\n{screen}");
        if std::env::var_os("SHOW_SCREENS").is_some() {
            println!("{screen}");
        }
        assert!(!screen.contains("✗ euler:  ") && !screen.contains("✗ euler:\n"));
    }
}

/// The data cursor's readout on F(t) is each model's force at that time on its dense output, in
/// the chart's units; `<` moves it back, Esc hides it.
#[test]
fn the_data_cursor_reads_each_curve_at_its_place() {
    let mut app = app();
    press(&mut app, KeyCode::Char('.'));
    let screen = text(render(&app, 160, 48).backend().buffer());
    let line = screen
        .lines()
        .find(|l| l.contains("t = "))
        .unwrap_or_else(|| panic!("no readout:\n{screen}"));
    let after = &line[line.find("t = ").unwrap() + 4..];
    let (number, rest) = after.split_once(' ').unwrap();
    assert!(rest.starts_with("µs"), "{line}");
    let t = number.parse::<f64>().unwrap() * 1e-6;
    for model in [ForceModel::Proposed, ForceModel::HuntCrossley] {
        let solution = app.solutions.solution(model).unwrap();
        let f = solution.trajectory.at(t).f;
        let expected =
            hertz_tui::format::units::engineering(f, hertz_tui::format::units::NEWTON, 4);
        assert!(
            line.contains(&expected),
            "{model:?} F({t}) = {expected} in {line}"
        );
    }
    press(&mut app, KeyCode::Char(','));
    assert_eq!(app.views.explorer.data_cursor, Some(490));
    press(&mut app, KeyCode::Esc);
    assert_eq!(app.views.explorer.data_cursor, None);
    let screen = text(render(&app, 160, 48).backend().buffer());
    assert!(!screen.contains("t = "));
}

/// At 80×24 the scrolled form keeps the header of its top section in view, wherever the cursor.
#[test]
fn the_compact_form_keeps_its_section_header_in_view() {
    let mut app = app();
    for _ in 0..20 {
        let screen = text(render(&app, 80, 24).backend().buffer());
        let lines: Vec<&str> = screen.lines().collect();
        let pane = lines.iter().position(|l| l.starts_with("Scene")).unwrap();
        let first = lines[pane + 1];
        assert!(
            ["Body 1", "Body 2", "Impact"]
                .iter()
                .any(|h| first.starts_with(h)),
            "{screen}"
        );
        press(&mut app, KeyCode::Down);
    }
}

/// A sphere struck at 50 m/s has a contact radius 0.23 of its radius: outside Hertz's a ≪ R. The
/// explorer says so in the regime box, as `solve` does in its warnings; the Fig. 5 scene as
/// published has nothing to warn about.
#[test]
fn the_regime_box_warns_where_hertz_theory_does_not_hold() {
    let quiet = text(render(&app(), 160, 48).backend().buffer());
    assert!(!quiet.contains('⚠'), "{quiet}");
    let mut app = app();
    app.cursor = Cursor::Field(Field::Number(SceneKey::V0));
    press(&mut app, KeyCode::Enter);
    update(&mut app, Action::Input(tui_input::InputRequest::DeleteLine));
    for c in "50".chars() {
        press(&mut app, KeyCode::Char(c));
    }
    press(&mut app, KeyCode::Enter);
    settle(&mut app);
    let screen = text(render(&app, 160, 48).backend().buffer());
    assert!(
        screen.contains("⚠ contact radius a =") && screen.contains("of the sphere radius"),
        "{screen}"
    );
}

/// A click on a chart's plot places the data cursor at that column: clicking the F(t) axis's
/// tick for 50 µs reads t = 50 µs to within one column of a 100 µs axis.
#[test]
fn a_click_on_a_chart_places_the_data_cursor_there() {
    let mut app = app();
    update(&mut app, Action::Resize(160, 48));
    let screen = text(render(&app, 160, 48).backend().buffer());
    let lines: Vec<&str> = screen.lines().collect();
    let (title_row, title_col) = lines
        .iter()
        .enumerate()
        .find_map(|(y, l)| {
            l.find("F(t) force–time")
                .map(|b| (y, l[..b].chars().count()))
        })
        .expect("the F(t) chart");
    // The axis line under the plot, and its ticks ┴ (0, 10, …, 100 µs) in this chart's columns.
    let (axis_row, ticks) = lines
        .iter()
        .enumerate()
        .skip(title_row)
        .find_map(|(y, l)| {
            let cols: Vec<usize> = l
                .chars()
                .enumerate()
                .skip(title_col)
                .filter(|&(_, c)| c == '┴')
                .map(|(x, _)| x)
                .collect();
            (cols.len() > 5).then_some((y, cols))
        })
        .expect("the F(t) axis");
    let labels = lines[axis_row + 1];
    assert!(labels.contains("50"), "{labels}");
    let fifty = ticks[5];
    update(&mut app, Action::Click(fifty as u16, (axis_row - 2) as u16));
    assert!(
        app.views.explorer.data_cursor.is_some(),
        "the click placed the cursor"
    );
    let screen = text(render(&app, 160, 48).backend().buffer());
    let readout = screen
        .lines()
        .find(|l| l.contains("t = "))
        .unwrap_or_else(|| panic!("no readout:\n{screen}"));
    let after = &readout[readout.find("t = ").unwrap() + 4..];
    let t: f64 = after.split(' ').next().unwrap().parse().unwrap();
    let column = 100.0 / (ticks[10] - ticks[0]) as f64;
    assert!(
        (t - 50.0).abs() <= column,
        "t = {t} µs, a column is {column} µs"
    );
}

/// The data cursor's readout never cuts a number and names every curve: at every size each drawn
/// model's reading on F(t) is on screen as its name (label, id or abbreviation) and its whole
/// value, the model's force at that time (to 4 digits, or 3 where the chart is narrow).
#[test]
fn the_data_cursor_readout_fits_whole_readings_at_every_size() {
    use hertz_tui::format::units::{NEWTON, engineering};
    for (w, h) in [(80, 24), (120, 40), (160, 48), (200, 24)] {
        let mut app = app();
        update(&mut app, Action::Resize(w, h));
        for _ in 0..10 {
            press(&mut app, KeyCode::Char('.'));
        }
        let mut screen = text(render(&app, w, h).backend().buffer());
        for _ in 0..3 {
            if screen.contains("t = ") {
                break;
            }
            press(&mut app, KeyCode::Char('c'));
            screen = text(render(&app, w, h).backend().buffer());
        }
        let line = screen
            .lines()
            .find(|l| l.contains("t = "))
            .unwrap_or_else(|| panic!("{w}×{h}: no F(t) readout:\n{screen}"));
        let after = &line[line.find("t = ").unwrap() + 4..];
        let t: f64 = after.split(' ').next().unwrap().parse().unwrap();
        let t = t * 1e-6;
        let drawn = app.checked_models();
        assert!(drawn.len() >= 3, "{drawn:?}");
        for &model in &drawn {
            let f = app.solutions.solution(model).unwrap().trajectory.at(t).f;
            let read = [4, 3].into_iter().any(|digits| {
                let value = engineering(f, NEWTON, digits);
                [model.label(), model.name(), model.short()]
                    .iter()
                    .any(|name| screen.contains(&format!("{name} {value}")))
            });
            assert!(read, "{w}×{h}: {} F({t}) whole:\n{screen}", model.name());
        }
    }
}

/// Where a chart does not fit (one or two of three shown), the first chart's title names the key
/// that shows it; where all three fit, no title says so.
#[test]
fn hidden_charts_are_announced_with_their_key() {
    for (w, h, hidden) in [
        (80, 24, true),
        (120, 40, true),
        (160, 48, false),
        (200, 24, false),
    ] {
        let mut app = app();
        update(&mut app, Action::Resize(w, h));
        let screen = text(render(&app, w, h).backend().buffer());
        assert_eq!(
            screen.matches("c: next chart").count(),
            usize::from(hidden),
            "{w}×{h}:\n{screen}"
        );
    }
}

/// At 80 columns the stability view's step line and the sweep form shorten their wording rather
/// than cut a number or a word at the pane's edge.
#[test]
fn narrow_study_headers_shorten_instead_of_cutting() {
    let mut app = app_on(Tab::named("stability").unwrap());
    update(&mut app, Action::Resize(80, 24));
    let screen = text(render(&app, 80, 24).backend().buffer());
    let line = screen
        .lines()
        .find(|l| l.contains("h·ω_max ="))
        .unwrap_or_else(|| panic!("no step line:\n{screen}"));
    let after = line.split("h·ω_max = ").nth(1).unwrap().trim_end();
    let ratio = after.split_whitespace().next().unwrap();
    assert!(ratio.parse::<f64>().is_ok(), "{line}");
    if after.contains("ω_max") {
        assert!(
            after.contains("rad/s"),
            "ω_max is whole with its unit: {line}"
        );
    }
    update(&mut app, Action::Tab(Tab::named("sweep").unwrap()));
    app.views.sweep.settings.output = hertz_tui::chart::sweep::SweepOutput::EOut;
    let screen = text(render(&app, 80, 24).backend().buffer());
    let output = screen
        .lines()
        .find(|l| l.contains(" output "))
        .unwrap_or_else(|| panic!("no output row:\n{screen}"));
    let value = output.split(" output ").nth(1).unwrap().trim_start();
    assert!(
        value.starts_with("e_out realized restitution ") || value.starts_with("e_out  "),
        "the output whole or its symbol alone: {output}"
    );
}

/// The y values of `model`'s line in `chart`, in drawing order.
fn model_ys(chart: &hertz_tui::chart::Chart, model: ForceModel) -> Vec<f64> {
    chart
        .series
        .iter()
        .find(|s| s.name == model.name())
        .unwrap_or_else(|| panic!("{model} in {}", chart.title))
        .runs
        .concat()
        .into_iter()
        .map(|p| p.1)
        .collect()
}

/// Views 4 and 5 both chart e_out against v₀, with opposite trends for the same law: the sweep
/// sets each law's damping from e at every v₀ (Hunt–Crossley's χ = 3(1 − e)/2 keeps its e_out
/// flat, docs/physics.md §6.4), view 5 sets it at the scene's v₀ and holds it (e_out falls as v₀
/// grows). Each title says which.
#[test]
fn the_two_e_out_against_v0_charts_say_how_they_set_the_damping() {
    let sweep = app_on(Tab::named("sweep").unwrap());
    let screen = text(render(&sweep, 160, 48).backend().buffer());
    assert!(screen.contains("damping from e at each v₀"), "{screen}");
    let charts = sweep.tab.view().charts(&sweep);
    let flat = model_ys(&charts[0], ForceModel::HuntCrossley);
    let spread = flat.iter().cloned().fold(f64::MIN, f64::max)
        - flat.iter().cloned().fold(f64::MAX, f64::min);
    assert!(spread < 1e-6, "re-derived at each v₀: {flat:?}");

    let held = app_on(Tab::named("restitution").unwrap());
    let screen = text(render(&held, 160, 48).backend().buffer());
    assert!(
        screen.contains("damping set at v₀ = 0.3 m/s and held"),
        "{screen}"
    );
    let charts = held.tab.view().charts(&held);
    let falling = model_ys(&charts[1], ForceModel::HuntCrossley);
    assert!(
        falling.first().unwrap() - falling.last().unwrap() > 0.3,
        "held: {falling:?}"
    );
    // Both meet at the scene's own impact: its e_out at v₀ (0.712 for e = 0.6, eq 19).
    assert!((flat[0] - 0.712).abs() < 5e-4, "{}", flat[0]);
}

/// With `C` the Models pane says "calibrated to e"; view 5 shows each law's own damping rule
/// (its subject), and says so on every chart and on its table rather than implying they follow.
#[test]
fn view_5_says_its_charts_are_the_laws_own_rules_while_calibrated() {
    let mut app = app_on(Tab::named("restitution").unwrap());
    let before = text(render(&app, 160, 48).backend().buffer());
    assert!(!before.contains("own rules: C not applied"), "{before}");
    press(&mut app, KeyCode::Char('C'));
    settle(&mut app);
    let screen = text(render(&app, 160, 48).backend().buffer());
    assert!(screen.contains("calibrated to e"), "{screen}");
    assert_eq!(
        screen.matches("own rules: C not applied").count(),
        2,
        "both charts: {screen}"
    );
    press(&mut app, KeyCode::Char('c'));
    let table = text(render(&app, 160, 48).backend().buffer());
    assert!(table.contains("own rules: C not applied"), "{table}");
}
