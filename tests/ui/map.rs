//! The map view (docs/maps.md §6) rendered into ratatui's TestBackend and read as a measurement:
//! a cell read through the axis ticks and the cursor is the cell `hertz-tui map` computes for the
//! same scene and grid, the legend counts are the command's (an unsettled cell's included), the
//! bouncing ball's period-1 region lies between Γ_SN and Γ_PD (docs/physics.md §8.1), Esc cancels
//! a map being computed, and a scene without `[system]` says how to add one.

use std::process::Command;
use std::sync::mpsc;

use hertz_tui::chart::map::look;
use hertz_tui::format::units;
use hertz_tui::model::presets::Registry;
use hertz_tui::model::study::runner::{StudyJob, StudyKind, StudyResult, StudySpec};
use hertz_tui::model::study::system::SystemStudy;
use hertz_tui::model::system::RunOptions;
use hertz_tui::ui::MarkerStyle;
use hertz_tui::ui::action::Action;
use hertz_tui::ui::app::App;
use hertz_tui::ui::jobs::Jobs;
use hertz_tui::ui::style::Theme;
use hertz_tui::ui::tab::Tab;
use hertz_tui::ui::update::update;
use hertz_tui::ui::views::map::settings::{ROWS, Row, Which};
use ratatui::crossterm::event::KeyCode;

use hertz_tui::model::study::runner;

use super::render::settle;
use super::system::{press, screen, type_in};

/// The explorer on preset `name` at `width`×`height`, on the map view, a cell's run cut to
/// 60 transient, 16 recorded and 20 exponent impacts (the tests run unoptimised), its first
/// request dropped unrun.
fn app_on(name: &str, width: u16, height: u16) -> App {
    let registry = Registry::builtin().unwrap();
    let scene = registry.scene(name).unwrap();
    let mut app = App::new(scene, registry, MarkerStyle::Braille, Theme::Dark);
    app.views.map.settings.budget = Some((60, 16, 20));
    update(&mut app, Action::Resize(width, height));
    settle(&mut app);
    update(&mut app, Action::Tab(Tab::named("map").unwrap()));
    app.take_studies();
    app
}

/// Runs the latest request of each kind of study only: the earlier ones, superseded on the
/// app's queue, would only cost the tests time.
fn settle_latest(app: &mut App) {
    loop {
        let jobs = app.take_studies();
        if jobs.is_empty() {
            break;
        }
        let mut latest: Vec<StudyJob> = Vec::new();
        for job in jobs {
            latest.retain(|j| j.spec.kind() != job.spec.kind());
            latest.push(job);
        }
        for job in latest {
            if let Some(outcome) = runner::run(&job, &|| false) {
                update(app, Action::Studied(Ok(outcome)));
            }
        }
    }
}

/// Moves the form's cursor to `row` and types `value` into it.
fn set(app: &mut App, row: Row, value: &str) {
    let i = ROWS.iter().position(|&r| r == row).unwrap();
    while app.views.map.cursor != i {
        press(app, KeyCode::Down);
    }
    type_in(app, value);
    assert!(
        !matches!(app.mode, hertz_tui::ui::app::Mode::Editing(_)),
        "{row:?} refused {value}"
    );
}

/// A cell of `hertz-tui map`'s CSV.
#[derive(Debug)]
struct CliCell {
    contact: String,
    ix: usize,
    iy: usize,
    motion: String,
    impacts: Option<u32>,
    periods: Option<u32>,
    lyapunov: Option<f64>,
}

/// The cells `hertz-tui map` computes for the view's scene and grid, every stop of the view.
fn command_cells(app: &App, contact: &str) -> Vec<CliCell> {
    let model = hertz_tui::ui::views::map::model(app).unwrap();
    let grid = hertz_tui::ui::views::map::study(app, &model).grid;
    let (t, r, l) = app.views.map.settings.budget.unwrap();
    let mut args: Vec<String> = [
        "map",
        "--scene",
        app.preset.as_deref().unwrap(),
        "--contact",
        contact,
        "--law",
        &app.focused.to_string(),
    ]
    .map(String::from)
    .to_vec();
    for a in [&grid.x, &grid.y] {
        args.extend([
            if std::ptr::eq(a, &grid.x) {
                "--x"
            } else {
                "--y"
            }
            .to_string(),
            a.param.path(),
            "--from".into(),
            a.from.to_string(),
            "--to".into(),
            a.to.to_string(),
            "--points".into(),
            a.points.to_string(),
        ]);
    }
    args.extend(["--transient", &t.to_string(), "--recorded", &r.to_string()].map(String::from));
    args.extend(["--lyapunov".to_string(), l.to_string()]);
    let out = Command::new(env!("CARGO_BIN_EXE_hertz-tui"))
        .args(&args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("contact,"))
        .map(|l| {
            let f: Vec<&str> = l.splitn(10, ',').collect();
            CliCell {
                contact: f[0].into(),
                ix: f[1].parse().unwrap(),
                iy: f[2].parse().unwrap(),
                motion: f[5].into(),
                impacts: f[6].parse().ok(),
                periods: f[7].parse().ok(),
                lyapunov: f[8].parse().ok(),
            }
        })
        .collect()
}

fn find<'a>(cells: &'a [CliCell], contact: &str, ix: usize, iy: usize) -> &'a CliCell {
    cells
        .iter()
        .find(|c| c.contact == contact && c.ix == ix && c.iy == iy)
        .unwrap_or_else(|| panic!("no {contact} cell ({ix}, {iy})"))
}

/// The screen as rows of characters.
fn grid_of(s: &str) -> Vec<Vec<char>> {
    s.lines().map(|l| l.chars().collect()).collect()
}

/// The map's plot read off the screen: the axis line's row and column, the x ticks (column,
/// value as labelled) and the y ticks (row, value as labelled), in display units.
struct Plot {
    x_ticks: Vec<(usize, f64)>,
    y_ticks: Vec<(usize, f64)>,
}

fn plot_of(g: &[Vec<char>]) -> Plot {
    let (row, col) = g
        .iter()
        .enumerate()
        .find_map(|(r, l)| {
            // The axis line: its corner after the y labels' blank columns.
            let c =
                (7..l.len()).find(|&c| l[c] == '└' && l[c - 7..c].iter().all(|&ch| ch == ' '))?;
            Some((r, c))
        })
        .expect("an x axis");
    let labels = &g[row + 1];
    let token = |at: usize| -> f64 {
        let (mut a, mut b) = (at, at);
        while a > 0 && labels[a - 1] != ' ' {
            a -= 1;
        }
        while b + 1 < labels.len() && labels[b + 1] != ' ' {
            b += 1;
        }
        labels[a..=b].iter().collect::<String>().parse().unwrap()
    };
    let x_ticks = g[row]
        .iter()
        .enumerate()
        .filter(|(_, ch)| **ch == '┬')
        .map(|(c, _)| (c, token(c)))
        .collect();
    let mut y_ticks = Vec::new();
    let mut r = row;
    while r > 0 && matches!(g[r - 1].get(col), Some('│' | '┤')) {
        r -= 1;
        if g[r][col] == '┤' {
            let label: String = g[r][col - 7..col].iter().collect();
            y_ticks.push((r, label.trim().parse().unwrap()));
        }
    }
    Plot { x_ticks, y_ticks }
}

/// The SI size of a display unit `unit` of base `base` (`mm` of `m`: 1e-3).
fn si(unit: &str, base: &str) -> f64 {
    match unit.strip_suffix(base).unwrap_or(unit) {
        "" => 1.0,
        "m" => 1e-3,
        "µ" => 1e-6,
        "k" => 1e3,
        other => panic!("prefix {other}"),
    }
}

/// The unit in brackets on the legend's line of an axis (`across` or `up`).
fn axis_unit(s: &str, which: &str) -> String {
    let line = s
        .lines()
        .find(|l| l.contains(&format!("{which}: ")))
        .unwrap();
    let open = line.find('[').unwrap();
    let close = line.find(']').unwrap();
    line[open + 1..close].to_string()
}

/// The left column's text, borders dropped and spaces collapsed.
fn left_text(s: &str, width: usize) -> String {
    s.lines()
        .map(|l| l.chars().take(width).collect::<String>())
        .collect::<Vec<_>>()
        .join(" ")
        .replace(['│', '─', '┌', '┐', '└', '┘'], " ")
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

/// The look name and glyph of a command cell.
fn look_of(c: &CliCell) -> (String, char) {
    let l = look(&c.motion, c.impacts);
    (l.name, l.glyph)
}

#[test]
fn a_cell_read_through_the_ticks_and_the_cursor_is_the_commands_cell() {
    let (w, h) = (160, 48);
    let mut app = app_on("bouncing-ball", w, h);
    set(&mut app, Row::Points(Which::X), "12");
    set(&mut app, Row::Points(Which::Y), "5");
    settle_latest(&mut app);
    let cli = command_cells(&app, "both");
    let law = app.focused.to_string();
    let data = hertz_tui::ui::views::map::data(&app).unwrap().clone();
    assert!(data.complete);
    let grid = data.grid;
    let s = screen(&app, w, h);
    let plot = plot_of(&grid_of(&s));
    assert!(plot.x_ticks.len() >= 3 && plot.y_ticks.len() >= 2, "{s}");
    let (xs, ys) = (
        si(&axis_unit(&s, "across"), "Hz"),
        si(&axis_unit(&s, "up"), "m"),
    );
    let nearest = |a: &hertz_tui::model::system::map::Axis, v: f64| {
        let t = (v - a.from) / (a.to - a.from) * (a.points - 1) as f64;
        let i = t.round() as usize;
        // The tick's cell is the one nearest its value: within half a cell.
        assert!(
            (t - i as f64).abs() <= 0.5 + 1e-9,
            "{v} is off the grid {a:?}"
        );
        i
    };
    let g = grid_of(&s);
    let mut read = 0;
    for &(col, vx) in &plot.x_ticks {
        for &(row, vy) in &plot.y_ticks {
            let (ix, iy) = (nearest(&grid.x, vx * xs), nearest(&grid.y, vy * ys));
            let cell = find(&cli, "rigid", ix, iy);
            assert_eq!(
                g[row][col],
                look_of(cell).1,
                "({vx}, {vy}) → ({ix}, {iy}) {cell:?}\n{s}"
            );
            read += 1;
            // The cursor there reads both stops' values, as the command has them.
            update(&mut app, Action::Click(col as u16, row as u16));
            assert_eq!(app.views.map.cell, (ix, iy));
            let s = screen(&app, w, h);
            assert!(s.contains(&format!("({ix}, {iy})")), "{s}");
            let line = |name: &str| s.lines().find(|l| l.contains(name)).unwrap().to_string();
            for stop in ["rigid", law.as_str()] {
                let c = find(&cli, stop, ix, iy);
                assert!(
                    line(" motion ").contains(&format!(" {} ", c.motion)),
                    "{c:?}\n{s}"
                );
                let nm = match (c.impacts, c.periods) {
                    (Some(n), Some(m)) => format!("{n}:{m}"),
                    _ => "—".into(),
                };
                assert!(line(" n:m ").contains(&nm), "{c:?} {nm}\n{s}");
                let l = c.lyapunov.map_or("—".into(), |l| units::sig(l, 3));
                assert!(line(" λ per impact ").contains(&l), "{c:?} {l}\n{s}");
            }
        }
    }
    assert!(read >= 6, "{read} cells read");
}

#[test]
fn the_legend_counts_are_the_commands_for_every_map() {
    let (w, h) = (160, 48);
    let mut app = app_on("impact-oscillator", w, h);
    set(&mut app, Row::Points(Which::X), "10");
    set(&mut app, Row::Points(Which::Y), "4");
    settle_latest(&mut app);
    legends_are_the_commands(&mut app, w, h);
}

/// Each map's legend (rigid, the law's, the difference, in turn with `c`) lists every motion of
/// `hertz-tui map`'s cells with its count, and nothing else; the look name and glyph, with their
/// counts, of each map.
fn legends_are_the_commands(app: &mut App, w: u16, h: u16) -> Vec<Vec<((String, char), usize)>> {
    let cli = command_cells(app, "both");
    let law = app.focused.to_string();
    let mut legends = Vec::new();
    for (contact, title) in [
        ("rigid", "rigid map"),
        (law.as_str(), &format!("{law} map") as &str),
        ("difference", "difference map"),
    ] {
        let s = screen(app, w, h);
        assert!(s.contains(title), "{title}\n{s}");
        let text = left_text(&s, 44);
        let mut counts: Vec<((String, char), usize)> = Vec::new();
        for c in cli.iter().filter(|c| c.contact == contact) {
            let l = look_of(c);
            match counts.iter_mut().find(|(k, _)| *k == l) {
                Some(e) => e.1 += 1,
                None => counts.push((l, 1)),
            }
        }
        assert!(!counts.is_empty());
        for ((name, glyph), n) in &counts {
            let entry = format!("{glyph} {name}: {n} cell");
            assert!(text.contains(&entry), "{entry}\n{text}");
            // Every type the legend claims is drawn.
            assert!(!text.contains("too small to draw"), "{text}");
        }
        assert_eq!(text.matches(" %)").count(), counts.len(), "{text}");
        legends.push(counts);
        press(app, KeyCode::Char('c'));
    }
    legends
}

#[test]
fn the_legend_names_cells_whose_transient_never_ended() {
    // The focused proposed law (x_pl = 0) is elastic: the ball climbs ever higher and a cell's
    // 1000 transient impacts are not done in the 20 000 forcing periods of its run, yet it still
    // impacts at the end: `unsettled`, not `no impact` (docs/maps.md §2).
    let (w, h) = (160, 48);
    let mut app = app_on("bouncing-ball", w, h);
    assert_eq!(app.focused.to_string(), "proposed");
    app.views.map.settings.budget = Some((1000, 16, 20));
    set(&mut app, Row::Points(Which::X), "4");
    set(&mut app, Row::Points(Which::Y), "2");
    settle_latest(&mut app);
    let legends = legends_are_the_commands(&mut app, w, h);
    let unsettled = look("unsettled", None);
    let count = |legend: &[((String, char), usize)]| {
        legend
            .iter()
            .find(|((name, glyph), _)| *name == unsettled.name && *glyph == unsettled.glyph)
            .map_or(0, |(_, n)| *n)
    };
    assert!(count(&legends[1]) >= 1, "{:?}", legends[1]);
    assert_eq!(count(&legends[0]), 0, "{:?}", legends[0]);
    assert!(
        legends
            .iter()
            .flatten()
            .all(|((name, _), _)| *name != look("no-impact", None).name),
        "{legends:?}"
    );
    // On screen, the law's map: its glyph in the cells and its words in the legend.
    let s = screen(&app, w, h);
    assert!(s.contains("rigid map"), "{s}");
    press(&mut app, KeyCode::Char('c'));
    let s = screen(&app, w, h);
    let text = left_text(&s, 44);
    assert!(
        text.contains(&format!(
            "u unsettled (transient never ended): {} cell",
            count(&legends[1])
        )),
        "{text}"
    );
}

/// Γ_SN = π(1−e)/(1+e) and Γ_PD = √(Γ_SN² + (2(1+e²)/(1+e)²)²) (docs/physics.md §8.1).
fn thresholds(e: f64) -> (f64, f64) {
    let sn = std::f64::consts::PI * (1.0 - e) / (1.0 + e);
    let b = 2.0 * (1.0 + e * e) / (1.0 + e).powi(2);
    (sn, (sn * sn + b * b).sqrt())
}

#[test]
fn the_bouncing_balls_period_one_region_lies_between_gamma_sn_and_gamma_pd() {
    let (w, h) = (160, 48);
    let mut app = app_on("bouncing-ball", w, h);
    app.views.map.settings.budget = None;
    set(&mut app, Row::Stops, "rigid");
    set(&mut app, Row::Start, "period-1");
    set(&mut app, Row::Key(Which::X), "system.gamma");
    set(&mut app, Row::From(Which::X), "1.1");
    set(&mut app, Row::To(Which::X), "1.7");
    set(&mut app, Row::Points(Which::X), "25");
    set(&mut app, Row::Key(Which::Y), "impact.restitution");
    set(&mut app, Row::From(Which::Y), "0.5");
    set(&mut app, Row::To(Which::Y), "0.6");
    set(&mut app, Row::Points(Which::Y), "2");
    settle_latest(&mut app);
    let s = screen(&app, w, h);
    let g = grid_of(&s);
    let plot = plot_of(&g);
    // Γ at a column, from the x ticks (a label is its column's cell to half a cell).
    let (&(c0, v0), &(c1, v1)) = (plot.x_ticks.first().unwrap(), plot.x_ticks.last().unwrap());
    let gamma = |col: usize| v0 + (v1 - v0) * (col as f64 - c0 as f64) / (c1 as f64 - c0 as f64);
    let cell = (1.7 - 1.1) / 24.0;
    let (mut inside, mut beyond) = (0, 0);
    assert_eq!(plot.y_ticks.len(), 2, "a tick a row\n{s}");
    for &(row, e) in &plot.y_ticks {
        let (sn, pd) = thresholds(e);
        let first = (0..c0)
            .rev()
            .find(|&c| matches!(g[row][c], '│' | '┤'))
            .unwrap()
            + 1;
        for (col, &glyph) in g[row].iter().enumerate().skip(first) {
            if glyph == ' ' || glyph == '│' {
                break;
            }
            let at = gamma(col);
            // Within 0.03 of a threshold a multiplier is near the unit circle: the transient is
            // slow (tests/model/systems_map.rs); a cell's width more for reading it off the ticks.
            if at > sn + 0.03 + cell && at < pd - 0.03 - cell {
                inside += 1;
                assert_eq!(
                    glyph, '1',
                    "Γ = {at:.3}, e = {e}: inside ({sn:.3}, {pd:.3})\n{s}"
                );
            } else if at > pd + 0.03 + cell {
                beyond += 1;
                assert_ne!(glyph, '1', "Γ = {at:.3}, e = {e}: past Γ_PD = {pd:.3}\n{s}");
            }
        }
    }
    assert!(inside >= 40 && beyond >= 20, "{inside} {beyond}\n{s}");
    assert!(s.contains("periodic, n = 1 impact"), "{s}");
}

#[test]
fn esc_cancels_a_map_being_computed_and_keeps_the_rows_done() {
    let (w, h) = (120, 40);
    let mut app = app_on("bouncing-ball", w, h);
    set(&mut app, Row::Stops, "rigid");
    set(&mut app, Row::Points(Which::X), "400");
    set(&mut app, Row::Points(Which::Y), "200");
    let map_job = app
        .take_studies()
        .into_iter()
        .rev()
        .find(|j| j.spec.kind() == StudyKind::Map)
        .unwrap();
    let (tx, rx) = mpsc::channel();
    let queue = Jobs::spawn("test-map", 1, move |report| tx.send(report).is_ok()).unwrap();
    assert!(queue.submit(map_job));
    // 80 000 cells: rows come in reports long before the end.
    let first = rx.recv().unwrap().unwrap();
    assert!(first.result.is_partial());
    update(&mut app, Action::Studied(Ok(first)));
    let s = screen(&app, w, h);
    assert!(s.contains("computing…") && s.contains("/200 rows"), "{s}");
    press(&mut app, KeyCode::Esc);
    assert!(!app.studies.is_pending(StudyKind::Map));
    let jobs = app.take_studies();
    assert_eq!(jobs.len(), 1, "{jobs:?}");
    assert_eq!(jobs[0].spec, StudySpec::Stop(StudyKind::Map));
    assert!(queue.submit(jobs.into_iter().next().unwrap()));
    // A quick study after it: the queue's one thread reaches it only once the map has stopped,
    // and a map that ran on to its end would report the whole first.
    let model = hertz_tui::ui::views::map::model(&app).unwrap();
    assert!(queue.submit(StudyJob {
        generation: 1,
        spec: StudySpec::System(Box::new(SystemStudy {
            model,
            contacts: Vec::new(),
            run: RunOptions::default(),
        })),
    }));
    loop {
        let outcome = rx.recv().unwrap().unwrap();
        match &outcome.result {
            StudyResult::Map(d) => {
                assert!(!d.complete, "the map ran to its end");
                update(&mut app, Action::Studied(Ok(outcome)));
            }
            StudyResult::System(_) => break,
            other => panic!("{other:?}"),
        }
    }
    let s = screen(&app, w, h);
    assert!(s.contains("cancelled"), "{s}");
    assert!(s.contains("map cancelled"), "the status line says so\n{s}");
    assert!(
        s.contains(" cells ("),
        "the rows done stay, with their legend\n{s}"
    );
    // Not asked for again by the next key, until asked on the map.
    press(&mut app, KeyCode::Char('c'));
    assert!(app.take_studies().is_empty());
    press(&mut app, KeyCode::PageDown);
    press(&mut app, KeyCode::Enter);
    let again = app.take_studies();
    assert!(
        again.iter().any(|j| j.spec.kind() == StudyKind::Map),
        "{again:?}"
    );
}

#[test]
fn a_scene_without_a_system_says_how_to_add_one_and_takes_every_key() {
    let mut app = app_on("fig5-steel-sphere-r10-plate", 120, 40);
    for (w, h) in [(80, 24), (120, 40)] {
        let s = screen(&app, w, h);
        assert!(s.contains("no [system] table"), "{s}");
        assert!(s.contains("system view (6)"), "{s}");
        assert!(s.contains("kind = \"bouncing-ball\""), "{s}");
    }
    for code in [
        KeyCode::Up,
        KeyCode::Down,
        KeyCode::Left,
        KeyCode::Right,
        KeyCode::Enter,
        KeyCode::Esc,
        KeyCode::PageDown,
        KeyCode::Char('c'),
        KeyCode::Char('f'),
        KeyCode::Char('r'),
    ] {
        press(&mut app, code);
        let _ = screen(&app, 80, 24);
    }
    update(&mut app, Action::Click(100, 20));
    assert!(app.take_studies().is_empty(), "nothing to map");
    assert!(hertz_tui::ui::views::VIEWS.iter().any(|v| v.id() == "map"));
}
